"""The answer schema of a Jr. manager: its family's tools, with the world's names as enums.

Built per scene from each tool's own pydantic argument model: references are inlined,
nullable fields become plain optional ones, rarely needed fields are left out so that a tiny
model is not tempted to fill them, and every field that names something in the world
(a category, a landmark, a lane, an asset) becomes an enum of the names that exist. A
constrained decoder then cannot name what does not exist.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from drivetwin.tools.appearance import COLOURS, TIME_PRESETS
from drivetwin.tools.base import Tool
from drivetwin.worlds.catalog import category, placeable_categories
from drivetwin.worlds.scene import Scene

# Fields a Jr. manager is not offered (the tool still accepts them from other planners):
# free geometry and fine timing that a short prompt never states and a small model invents.
OMITTED_FIELDS = frozenset({"waypoints", "start_time", "label", "exposure", "ahead", "clockwise", "name"})
# Longest free string the model may write where no enum applies.
FREE_TEXT_CHARS = 40
CLOCK_PATTERN = "^([01][0-9]|2[0-3]):[0-5][0-9]$"
# Fields that hold an amount the request states (metres, a count, degrees, coordinates): where
# the request states numbers, these may hold only those (see WorldNames.numbers).
NUMBER_FIELDS = frozenset({
    "count", "columns", "cones", "distance", "along_m", "radius", "spacing", "within", "speed",
    "forward", "left", "east", "north", "turn_deg", "yaw_deg", "heading_deg", "x", "y", "at_x", "at_y",
    "offset_m", "gap", "metres", "rate", "seconds", "at_time", "start_time",
})
# Of those, the ones that count things: a length said ("25 m ahead") is never one of them.
COUNT_FIELDS = frozenset({"count", "columns", "cones"})
# Of those, the ones that hold metres: where the request says lengths ("every 5 m"), only those.
LENGTH_FIELDS = frozenset({"distance", "along_m", "radius", "spacing", "within", "offset_m", "gap", "metres",
                           "forward", "left", "east", "north"})
# Of those, the ones that hold coordinates: offered only where the request gives some ("x=40 y=5").
COORDINATE_FIELDS = frozenset({"x", "y", "at_x", "at_y"})
# Of those, the ones that turn a thing: offered only when the request speaks of turning.
TURN_FIELDS = frozenset({"yaw_deg", "turn_deg", "heading_deg"})
# Of those, the ones a direction word can turn negative ("1.5 m south" is north -1.5).
SIGNED_FIELDS = frozenset({"forward", "left", "east", "north", "turn_deg", "along_m", "x", "y", "at_x", "at_y"})


@dataclass
class WorldNames:
    """The names a Jr. manager may use, each list possibly narrowed by grounding."""

    categories: list[str]
    places: list[str]
    assets: list[str]
    lanes: list[str]
    notes: list[str] = field(default_factory=list)
    # Set from what the request itself says (llm/request_names.py); empty means not narrowed.
    relations: list[str] = field(default_factory=list)
    numbers: list[float] = field(default_factory=list)
    # Of the numbers, those said as lengths ("25 m") and as coordinates ("x=40"): no count takes them.
    lengths: list[float] = field(default_factory=list)
    coordinates: list[tuple[str, float]] = field(default_factory=list)
    angles: list[float] = field(default_factory=list)
    speeds: list[float] = field(default_factory=list)
    weathers: list[str] = field(default_factory=list)
    intensities: list[float] = field(default_factory=list)
    colours: list[str] = field(default_factory=list)
    times: list[str] = field(default_factory=list)
    shapes: list[str] = field(default_factory=list)
    # The sign a direction word gives a move field ("south" makes north negative).
    signs: dict[str, int] = field(default_factory=dict)
    # Things that can act in a storyboard (vehicles, riders, walkers) and the traffic lights.
    movers: list[str] = field(default_factory=list)
    lights: list[str] = field(default_factory=list)
    # The manoeuvres and behaviours the request's words name: the only kinds a storyboard step
    # or a behaviour may take where it names some.
    manoeuvres: list[str] = field(default_factory=list)
    behaviours: list[str] = field(default_factory=list)
    # The places and things the request names (the ego too, when said): a distance's two ends.
    ends: list[str] = field(default_factory=list)
    # Every landmark's names and the roads' names: what a search's words may be.
    landmark_words: list[str] = field(default_factory=list)
    roads: list[str] = field(default_factory=list)
    # Fields left out of this request's schema on top of OMITTED_FIELDS, and fields it must fill.
    omitted: frozenset[str] = frozenset()
    required: frozenset[str] = frozenset()

    @classmethod
    def of(cls, scene: Scene) -> WorldNames:
        """Every name in the scene: placeable categories, landmarks, lanes, asset ids."""
        lanes = [lane.id for lane in scene.roads.lanes]
        assets = [a.id for a in scene.all_assets()]
        places = [lm.name for lm in scene.landmarks] + lanes + assets
        movers = [a.id for a in scene.all_assets() if category(a.category).motion != "prop"]
        lights = [a.id for a in scene.all_assets() if a.category == "traffic_light"]
        words = [name for lm in scene.landmarks for name in lm.names()]
        roads = sorted({lane.road for lane in scene.roads.lanes if lane.road})
        return cls(placeable_categories(), places, assets, lanes, movers=movers, lights=lights, landmark_words=words,
                   roads=roads)


def _enum(values: list[str]) -> dict[str, Any]:
    return {"type": "string", "enum": list(dict.fromkeys(values))}


def _named(prop: str, names: WorldNames) -> dict[str, Any] | None:
    """The enum for a property whose name says it names something in the world."""
    if prop in ("category",):
        return _enum(names.categories)
    if prop in ("categories",):
        return {"type": "array", "items": _enum(names.categories), "minItems": 1, "maxItems": 4}
    if prop in ("a", "b") and len(names.ends) == 2:  # a distance's two ends named: one each, never one twice
        return _enum(names.ends[:1] if prop == "a" else names.ends[1:])
    if prop in ("a", "b"):  # or one and the ego ("how far is the library?")
        return _enum(names.ends if len(names.ends) > 2 else [*names.places, "ego"])
    if prop in ("target", "near", "centre", "to", "nearest_to"):  # a place, thing or lane named, never a free phrase ("250km/h")
        return _enum(names.places)
    if prop == "asset":
        return _enum(names.assets)
    if prop == "actor":  # a storyboard actor moves, or is a light; never a free name ("lead_car_1")
        return _enum([a for a in names.assets if a in names.movers or a in names.lights] or names.movers)
    if prop == "query" and names.landmark_words:  # words of a landmark's name, never free words
        return _enum(names.landmark_words)
    if prop == "road" and names.roads:
        return _enum(names.roads)
    if prop == "light":
        return _enum([a for a in names.assets if a in names.lights] or names.lights)
    if prop == "assets":
        return {"type": "array", "items": _enum(names.assets), "maxItems": 20}
    if prop == "lane":
        return _enum(names.lanes)
    if prop == "colour":
        return _enum(names.colours or list(COLOURS))
    if prop == "shape" and names.shapes:
        return _enum(names.shapes)
    if prop == "relation" and names.relations:
        return _enum(names.relations)
    if prop == "time" and names.times:
        return _enum(names.times)  # the clock time the request says, never a neighbouring one
    if prop == "time":
        return {"anyOf": [_enum(list(TIME_PRESETS)), {"type": "string", "pattern": CLOCK_PATTERN}]}
    return None


def _slim(node: Any, defs: dict[str, Any], names: WorldNames, prop: str | None = None) -> Any:
    """`node` with refs inlined, nulls dropped, enums injected and noise removed."""
    if not isinstance(node, dict):
        return node
    if "$ref" in node:
        return _slim(defs[node["$ref"].split("/")[-1]], defs, names, prop)
    if prop is not None:
        named = _named(prop, names)
        if named is not None:
            return named
    if "anyOf" in node:
        branches = [b for b in node["anyOf"] if b.get("type") != "null"]
        if len(branches) == 1:
            return _slim(branches[0], defs, names, prop)
        return {"anyOf": [_slim(b, defs, names) for b in branches]}
    out: dict[str, Any] = {}
    for key, value in node.items():
        if key in ("title", "description", "default", "$defs", "examples"):
            continue
        if key == "properties":
            left_out = OMITTED_FIELDS | names.omitted
            out[key] = {name: _slim(sub, defs, names, name) for name, sub in value.items() if name not in left_out}
        elif key == "items":
            out[key] = _slim(value, defs, names)
        elif key == "required":
            out[key] = [r for r in value if r not in OMITTED_FIELDS | names.omitted]
        else:
            out[key] = value
    amounts = names.angles if prop in TURN_FIELDS else names.speeds if prop == "speed" else names.numbers
    if prop in COUNT_FIELDS:
        amounts = [n for n in amounts if n not in names.lengths and all(n != v for _, v in names.coordinates)]
    amounts = names.lengths if prop in LENGTH_FIELDS and names.lengths else amounts
    axis = [v for a, v in names.coordinates if prop in COORDINATE_FIELDS and prop.endswith(a)]
    if axis and out.get("type") == "number":
        return {"type": "number", "enum": axis}  # x as said, sign and all; never the y
    if prop in NUMBER_FIELDS and amounts and out.get("type") in ("number", "integer"):
        said = _said_numbers(out, amounts, prop in SIGNED_FIELDS | TURN_FIELDS, names.signs.get(prop))
        if said:
            return {"type": out["type"], "enum": said}
    if prop == "intensity" and names.intensities and out.get("type") == "number":
        return {"type": "number", "enum": list(names.intensities)}  # "a light drizzle" is light, never 0.9
    if prop == "kind" and names.weathers and set(names.weathers) <= set(out.get("enum", ())):
        return {**out, "enum": list(names.weathers)}  # the weather's kind, not a behaviour's
    said_manoeuvres = [m for m in names.manoeuvres if m in out.get("enum", ())]
    if prop == "kind" and said_manoeuvres:
        return {**out, "enum": said_manoeuvres}  # "brakes" is a stop, never a lane change
    said_behaviours = [b for b in names.behaviours if b in out.get("enum", ())]
    if prop == "kind" and said_behaviours and "parked" in out.get("enum", ()):
        return {**out, "enum": said_behaviours}  # "round and round the car park" is a circle, never parked
    if out.get("type") == "string" and "enum" not in out and "pattern" not in out:
        out.setdefault("maxLength", FREE_TEXT_CHARS)
    if out.get("type") == "object":
        out["additionalProperties"] = False
        must = [r for r in names.required if r in out.get("properties", {}) and r not in out.get("required", [])]
        if must:
            out["required"] = [*out.get("required", []), *sorted(must)]
    return out


def _said_numbers(node: dict[str, Any], numbers: list[float], signed: bool, sign: int | None) -> list[float | int]:
    """The request's numbers (and their negatives where a direction can flip them; only the
    direction's sign where one was said) that fit the field's type and bounds, so the model
    copies an amount instead of making one up."""
    values = [sign * abs(n) for n in numbers] if sign else [*numbers, *(-n for n in numbers if signed and n)]
    if node["type"] == "integer":
        values = [v for v in values if float(v).is_integer()]
    low = max(node.get("minimum", -math.inf), node.get("exclusiveMinimum", -math.inf))
    high = min(node.get("maximum", math.inf), node.get("exclusiveMaximum", math.inf))
    fitting = [v for v in values if low <= v <= high and v != node.get("exclusiveMinimum")]
    as_type: list[float | int] = [int(v) if node["type"] == "integer" else v for v in fitting]
    return list(dict.fromkeys(as_type))


def args_schema(tool: Tool[Any], names: WorldNames) -> dict[str, Any]:
    """The JSON Schema of `tool`'s arguments as a Jr. manager may fill them."""
    raw = tool.Args.model_json_schema()
    slimmed: dict[str, Any] = _slim(raw, raw.get("$defs", {}), names)
    return slimmed


def call_schema(tools: list[Tool[Any]], names: WorldNames) -> dict[str, Any]:
    """One call of any of `tools`: {"tool": name, "args": {...}}, as an anyOf by tool."""
    options = [
        {
            "type": "object",
            "properties": {"tool": {"const": tool.name}, "args": args_schema(tool, names)},
            "required": ["tool", "args"],
            "additionalProperties": False,
        }
        for tool in tools
    ]
    return options[0] if len(options) == 1 else {"anyOf": options}


def signature(tool: Tool[Any], names: WorldNames) -> str:
    """A one-line description of a tool and its arguments for the Jr. manager's prompt."""
    props = args_schema(tool, names).get("properties", {})
    parts = []
    for name, sub in props.items():
        inner = sub.get("properties")
        if inner:
            parts.append(f"{name}{{{', '.join(_arg(k, v) for k, v in inner.items())}}}")
        else:
            parts.append(_arg(name, sub))
    return f"{tool.name}({', '.join(parts)}): {tool.description}"


def _arg(name: str, sub: dict[str, Any]) -> str:
    values = sub.get("enum")
    # Short enums are worth showing (relations, shapes); long ones live in the grammar.
    if values is not None and len(values) <= 10:
        return f"{name}: {'|'.join(str(v) for v in values)}"
    return name


__all__ = ["COORDINATE_FIELDS", "COUNT_FIELDS", "LENGTH_FIELDS", "NUMBER_FIELDS", "OMITTED_FIELDS", "TURN_FIELDS", "WorldNames", "args_schema", "call_schema", "signature"]
