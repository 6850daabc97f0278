"""The rule-based planner: common phrasings to Worker tool calls, with no LLM.

It is the baseline every LLM is measured against, the fast path of the hybrid planner, and
what makes `drivetwin chat` useful on a fresh install. It reads a prompt clause by clause,
recognises the intent of each from keywords, fills the slots (category, count, place,
behaviour) from what the world actually contains, and reports a confidence: how much of the
prompt it understood.
"""

from __future__ import annotations

import math
import re
import time
from typing import Any

from drivetwin.orchestrator import phrases as ph
from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning import Plan, PlanContext, PlanningError, TraceStep
from drivetwin.tools.appearance import COLOURS
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.catalog import catalog, nearest_categories
from drivetwin.worlds.scene import Scene

PROMPT_VERSION = "rules-1"
# Confidence when every content word of a clause was understood; unknown words lower it.
FULL_CONFIDENCE = 0.95
# How much each unknown content word lowers the confidence.
UNKNOWN_WORD_PENALTY = 0.15

_SPLIT = re.compile(r"[.;!?\n]+|,?\s+(?:and then|then|and also|after that)\s+")
_VERBS = ("add", "make", "put", "place", "remove", "delete", "set", "turn", "move", "create",
          "change", "paint", "spawn", "switch", "arrange", "surround", "drive", "park", "have")
SEARCH_WORDS = ("where", "find", "list", "show me", "how many", "which", "what", "is there",
                "are there", "locate", "search", "tell me")
REMOVE_WORDS = ("remove", "delete", "get rid of", "take away", "take out", "clear away", "erase",
                "eliminate", "despawn", "clear out", "destroy")
WEATHER_WORDS: dict[str, tuple[str, ...]] = {
    "rain": ("rain", "raining", "rainy", "drizzle", "drizzling", "downpour", "storm", "stormy", "wet"),
    "fog": ("fog", "foggy", "mist", "misty", "haze", "hazy"),
    "snow": ("snow", "snowy", "snowing", "blizzard", "snowfall"),
    "cloudy": ("cloudy", "overcast", "clouds", "grey sky"),
    "clear": ("clear weather", "clear the weather", "clear sky", "sunny", "make it clear",
              "stop raining", "stop the rain", "no rain", "fine weather", "clear skies",
              "weather clear", "clear up", "clears up", "nice weather"),
}
HEAVY = ("heavy", "heavily", "dense", "thick", "torrential", "strong", "intense", "lot of",
         "blizzard", "downpour", "pouring", "storm", "very")
LIGHT = ("light", "lightly", "slight", "little", "bit of", "drizzle", "thin", "some", "gentle")
TIME_WORDS = ("daytime", "day time", "day", "noon", "midday", "morning", "afternoon", "evening",
              "dusk", "dawn", "sunrise", "sunset", "night", "nighttime", "night time", "midnight",
              "dark", "bright")
ARRANGE_WORDS = ("around", "surround", "ring", "circle of", "encircle", "mark", "cordon", "enclose",
                 "line of", "row of", "in a line", "in a row", "grid", "along the")
BEHAVIOUR_WORDS = {
    "jaywalk": ("jaywalk", "jaywalking", "jaywalker", "cut across", "cuts across", "cutting across",
                "run across", "runs across", "darts across", "ego's path", "ego vehicle's path"),
    "circle": ("skidpad", "skid pad", "circle", "circles", "circling", "donut", "donuts",
               "doughnut", "loop around", "round and round"),
    "cross_road": ("cross the road", "crossing the road", "cross the street", "crossing the street",
                   "crosses the road", "crosses the street", "at the crosswalk", "on the crosswalk"),
    "drive_lane": ("driving", "drive along", "drives along", "moving along", "cruising",
                   "drive down", "drive on", "drives on"),
    "parked": ("parked", "park ", "parking", "stationary", "stopped"),
}


def _clauses(prompt: str) -> list[str]:
    parts = [p.strip() for p in _SPLIT.split(prompt) if p and p.strip()]
    out: list[str] = []
    for part in parts:
        # "make it rain and add a cone": split at "and" only when a new command follows.
        pieces = re.split(rf"\s+and\s+(?=(?:{'|'.join(_VERBS)})\b)", part)
        out.extend(p.strip(" ,") for p in pieces if p.strip(" ,"))
    return out


class RulePlanner:
    """Keyword-and-slot planner over the Worker tools."""

    name = "rules"

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        started = time.perf_counter()
        calls: list[ToolCall] = []
        confidences: list[float] = []
        scene = context.scene
        clauses = _clauses(prompt)
        if not clauses:
            raise PlanningError("the prompt has no request in it")
        for clause in clauses:
            clause_calls = _plan_clause(clause, scene, context.memory)
            if clause_calls is None:
                raise PlanningError(
                    f"I could not tell what to do with {clause!r}; try e.g. 'add 3 traffic cones "
                    "in front of the JTEKT building entrance', 'make it rain', 'remove the bus'"
                )
            calls.extend(clause_calls)
            confidences.append(_confidence(clause, scene))
        confidence = min(confidences)
        step = TraceStep(level="rules", input=prompt, output="; ".join(str(c) for c in calls),
                         seconds=time.perf_counter() - started)
        return Plan(calls=calls, planner=self.name, confidence=confidence,
                    prompt_version=PROMPT_VERSION, trace=[step])


def _confidence(clause: str, scene: Scene) -> float:
    known = ph.known_words(scene) | _GRAMMAR
    content = [w for w in ph.tokens(clause) if len(w) > 2 and not w.replace(".", "").isdigit()]
    unknown = [w for w in content if w not in known and ph.singular(w) not in known]
    return max(0.05, FULL_CONFIDENCE - UNKNOWN_WORD_PENALTY * len(unknown))


_GRAMMAR = set(
    " ".join(
        [*SEARCH_WORDS, *REMOVE_WORDS, *HEAVY, *LIGHT, *TIME_WORDS, *ARRANGE_WORDS, *_VERBS,
         *(w for ws in WEATHER_WORDS.values() for w in ws),
         *(w for ws in BEHAVIOUR_WORDS.values() for w in ws),
         "the", "and", "that", "this", "those", "these", "there", "here", "also", "with", "into",
         "from", "for", "its", "it's", "all", "any", "every", "please", "can", "you", "could",
         "would", "want", "need", "let's", "front", "behind", "left", "right", "next", "beside",
         "near", "nearby", "centre", "middle", "scene", "map", "world", "campus", "sidewalk",
         "pavement", "lane", "road", "street", "maintenance", "construction", "work", "works",
         "performing", "doing", "manoeuvre", "maneuver", "mid-scale", "ackermann-steered",
         "path", "vehicle's", "across", "new", "another", "more", "them", "they", "their",
         "forward", "backward", "back", "metres", "meters", "turn", "rotate", "degrees",
         "colour", "paint", "red", "blue", "green", "yellow", "white", "black", "orange",
         "silver", "grey", "purple", "pink", "brown", "street lights", "lights", "headlights",
         "on", "off", "weather", "time", "o'clock", "speed", "radius", "clockwise", "entrance",
         "added", "you", "just", "was", "were", "again", "instead", "put", "time", "look", "like",
         "heavier", "lighter", "intensity", "visible", "around", "there"]
    ).split()
)


def _plan_clause(clause: str, scene: Scene, memory: Memory) -> list[ToolCall] | None:
    low = ph.normalise(clause)
    if ph.has_any(clause, ("ignore", "pretend", "disregard", "jailbreak", "system prompt", "bypass")) and not (
        ph.find_categories(clause) or ph.mentions_ego(clause)
    ):
        raise PlanningError(
            f"{clause!r} is not a scene edit; the world's rules always apply and cannot be switched off"
        )
    if ph.has_any(clause, SEARCH_WORDS) and not ph.has_any(clause, ("add", "make", "put", "remove")):
        return _search(clause, scene)
    weather = _weather(clause)
    if weather is not None and not ph.has_any(clause, REMOVE_WORDS):
        return [weather]
    if ph.has_any(clause, REMOVE_WORDS):
        return _remove(clause, scene, memory)
    lights = _lights(clause)
    if lights is not None:
        return [lights]
    when = _time_of_day(clause)
    if when is not None:
        return [when]
    colour = _recolour(clause, scene, memory)
    if colour is not None:
        return [colour]
    existing = _move_existing(clause, scene, memory)
    if existing is not None:
        return existing
    mentions = ph.find_categories(clause)
    if not mentions:
        if ph.has_any(clause, ("add", "create", "spawn", "place", "put", "insert")):
            noun = ph.tokens(clause)[-1]
            nearest = ", ".join(nearest_categories(noun))
            raise PlanningError(f"unknown asset {noun!r}; nearest: {nearest}")
        return None
    if ph.has_any(clause, ARRANGE_WORDS) and not _behaviour_kind(clause):
        return [_arrange(clause, scene, memory, mentions)]
    if " mark " in low or ph.has_any(clause, ("to mark",)):
        return [_arrange(clause, scene, memory, mentions)]
    return _add(clause, scene, memory, mentions)


def _weather(clause: str) -> ToolCall | None:
    for kind in ("clear", "snow", "fog", "rain", "cloudy"):
        if ph.has_any(clause, WEATHER_WORDS[kind]):
            args: dict[str, Any] = {"kind": kind}
            if kind != "clear":
                args["intensity"] = 0.9 if ph.has_any(clause, HEAVY) else 0.3 if ph.has_any(clause, LIGHT) else 0.6
            return ToolCall(tool="set_weather", args=args)
    return None


def _time_of_day(clause: str) -> ToolCall | None:
    low = ph.normalise(clause)
    m = re.search(r"(\d{1,2})(?::(\d\d))?\s*(am|pm|o'clock)?", low)
    if m and (m.group(2) or m.group(3)) and ph.has_any(clause, ("time", "make it", "set", "at", "clock", "change")):
        hour = int(m.group(1)) % 24
        if m.group(3) == "pm" and hour < 12:
            hour += 12
        if m.group(3) == "am" and hour == 12:
            hour = 0
        return ToolCall(tool="set_time_of_day", args={"time": f"{hour:02d}:{m.group(2) or '00'}"})
    for word, preset in (("midnight", "midnight"), ("night", "night"), ("dark", "night"),
                         ("evening", "evening"), ("dusk", "dusk"), ("sunset", "sunset"),
                         ("dawn", "dawn"), ("sunrise", "sunrise"), ("morning", "morning"),
                         ("afternoon", "afternoon"), ("noon", "noon"), ("midday", "noon"),
                         ("daytime", "daytime"), ("day time", "daytime"), ("day", "daytime"),
                         ("bright", "daytime")):
        if ph.has_any(clause, (word,)):
            return ToolCall(tool="set_time_of_day", args={"time": preset})
    return None


def _lights(clause: str) -> ToolCall | None:
    if not ph.has_any(clause, ("street lights", "streetlights", "street lamps", "headlights", "vehicle lights")):
        return None
    state = "off" if ph.has_any(clause, ("off", "switch off", "turn off")) else "on"
    key = "vehicle_lights" if ph.has_any(clause, ("headlights", "vehicle lights")) else "street_lights"
    return ToolCall(tool="set_lighting", args={key: state})


def _referenced(clause: str, scene: Scene, memory: Memory) -> list[str]:
    """Existing assets a clause refers to: ids, 'the ego', 'that car', 'the cones you added', 'it'."""
    ids = ph.find_asset_ids(scene, clause)
    if ids:
        return ids
    if ph.mentions_ego(clause) and not ph.has_any(clause, BEHAVIOUR_WORDS["jaywalk"]):
        return ["ego"]
    mentions = ph.find_categories(clause)
    recent_words = ("you added", "you just added", "that", "those", "these", "the new", "last")
    if mentions:
        name = mentions[0].category
        recent = memory.last_added(name)
        if recent and ph.has_any(clause, recent_words):
            return recent if mentions[0].plural else recent[-1:]
        present = [a.id for a in scene.assets if a.category == name]
        if not present:
            return []
        if mentions[0].plural or ph.has_any(clause, ("all",)):
            return present
        return recent[-1:] if recent else present[-1:]
    if ph.has_any(clause, ("it", "them", "that one")):
        return memory.last_added()
    return []


def _search(clause: str, scene: Scene) -> list[ToolCall]:
    mentions = ph.find_categories(clause)
    landmark = ph.find_landmark(scene, clause)
    if mentions:
        args: dict[str, Any] = {"category": mentions[0].category}
        if landmark:
            args["near"] = landmark[0]
        return [ToolCall(tool="find_assets", args=args)]
    if ph.has_any(clause, ("lane", "lanes", "road", "roads")):
        return [ToolCall(tool="find_lanes", args={})]
    if landmark:
        return [ToolCall(tool="find_landmarks", args={"query": landmark[0]})]
    if ph.has_any(clause, ("landmark", "landmarks", "places", "buildings", "entrances")):
        return [ToolCall(tool="find_landmarks", args={})]
    return [ToolCall(tool="find_assets", args={})]


def _remove(clause: str, scene: Scene, memory: Memory) -> list[ToolCall] | None:
    ids = ph.find_asset_ids(scene, clause)
    if ph.mentions_ego(clause):
        ids = ["ego", *ids]
    if ids:
        return [ToolCall(tool="remove_assets", args={"assets": ids})]
    mentions = ph.find_categories(clause)
    if not mentions:
        recent = memory.last_added()
        return [ToolCall(tool="remove_assets", args={"assets": recent})] if recent and ph.has_any(
            clause, ("it", "them", "that", "those", "everything you added")) else None
    name = mentions[0].category
    recent = memory.last_added(name)
    if recent and ph.has_any(clause, ("you added", "you just added", "the new", "that", "those")):
        return [ToolCall(tool="remove_assets", args={"assets": recent})]
    args: dict[str, Any] = {"category": name}
    count = ph.find_count(clause, mentions[0].start)
    if not mentions[0].plural and not ph.has_any(clause, ("all", "every")):
        count = count or 1
    elif ph.has_any(clause, ("all", "every")):
        count = None
    if count:
        args["count"] = count
    landmark = ph.find_landmark(scene, clause)
    if landmark:
        args["near"] = landmark[0]
    elif count and memory.last_focus() is not None and recent:
        args["near"] = recent[0]
    return [ToolCall(tool="remove_assets", args=args)]


def _recolour(clause: str, scene: Scene, memory: Memory) -> ToolCall | None:
    if not ph.has_any(clause, ("paint", "colour", "make", "turn", "change", "recolour")):
        return None
    colour = next((c for c in COLOURS if ph.has_any(clause, (c,))), None)
    if colour is None or ph.has_any(clause, ("add", "create", "place", "spawn")):
        return None
    ids = _referenced(clause, scene, memory)
    if not ids:
        what = ph.find_categories(clause)
        if what and ph.has_any(clause, ("paint", "recolour", "colour")):
            raise PlanningError(f"there is no {what[0].category} in the scene to recolour")
        return None
    return ToolCall(tool="set_asset_appearance", args={"assets": ids, "colour": colour})


def _move_existing(clause: str, scene: Scene, memory: Memory) -> list[ToolCall] | None:
    if not ph.has_any(clause, ("move", "shift", "relocate", "put", "place", "turn", "rotate", "drive",
                               "make the", "make that", "have the", "let the", "send")):
        return None
    if ph.has_any(clause, ("add", "create", "spawn", "new", "another")):
        return None
    mentions = ph.find_categories(clause)
    if mentions and ph.find_count(clause, mentions[0].start) is not None:
        return None  # "put 3 benches ...", "put a cone ...": new assets, not existing ones
    ids = _referenced(clause, scene, memory)
    if not ids:
        return None
    asset = ids[0]
    kind = _behaviour_kind(clause)
    if kind is not None:
        return [ToolCall(tool="set_behaviour", args={"asset": asset, "behaviour": _behaviour_spec(kind, clause, scene)})]
    metres = ph.find_distance(clause)
    for word, key, sign in (("forward", "forward", 1), ("ahead", "forward", 1), ("back", "forward", -1),
                            ("left", "left", 1), ("right", "left", -1)):
        if metres is not None and ph.has_any(clause, (word,)) and not ph.find_landmark(scene, clause):
            return [ToolCall(tool="move_asset", args={"asset": asset, key: sign * metres})]
    if ph.has_any(clause, ("turn around", "rotate", "turn it", "face the other way")):
        deg = re.search(r"(-?\d+)\s*deg", clause.lower())
        return [ToolCall(tool="move_asset", args={"asset": asset, "turn_deg": float(deg.group(1)) if deg else 180.0})]
    location = _location(clause, scene, memory, exclude=ids)
    if location is None:
        return None
    return [ToolCall(tool="place_asset", args={"asset": a, "location": location}) for a in ids[:1]]


def _behaviour_kind(clause: str) -> str | None:
    for kind in ("jaywalk", "circle", "cross_road", "drive_lane", "parked"):
        if ph.has_any(clause, BEHAVIOUR_WORDS[kind]):
            return kind
    return None


def _behaviour_spec(kind: str, clause: str, scene: Scene) -> dict[str, Any]:
    spec: dict[str, Any] = {"kind": kind}
    speed = ph.find_speed(clause)
    if speed:
        spec["speed"] = speed
    if kind == "circle":
        m = re.search(r"radius (?:of )?(\d+(?:\.\d+)?)", clause.lower()) or re.search(
            r"(\d+(?:\.\d+)?)\s*(?:m|metre|meter)s?\s*radius", clause.lower())
        if m:
            spec["radius"] = float(m.group(1))
        if ph.has_any(clause, ("clockwise",)) and not ph.has_any(clause, ("anticlockwise", "counterclockwise", "counter-clockwise")):
            spec["clockwise"] = True
    if kind == "drive_lane":
        lane = ph.find_lane(scene, clause)
        if lane:
            spec["lane"] = lane
    return spec


def _location(clause: str, scene: Scene, memory: Memory, exclude: list[str] | None = None) -> dict[str, Any] | None:
    low = ph.normalise(clause)
    coords = ph.find_coordinates(clause)
    if coords is not None:
        return {"relation": "absolute", "x": coords[0], "y": coords[1]}
    if ph.has_any(clause, ("centre of the scene", "centre of the map", "scene centre", "middle of the scene",
                           "centre of the world", "middle of the map", "centre of campus", "in the centre",
                           "in the middle", "centre of the campus")):
        return {"relation": "scene_centre"}
    lane = ph.find_lane(scene, clause)
    if lane and ph.has_any(clause, ("lane", "in lane", "on main street", "on campus drive")):
        return {"relation": "in_lane", "target": lane}
    target: str | None = None
    landmark = ph.find_landmark(scene, clause)
    ids = [i for i in ph.find_asset_ids(scene, clause) if i not in (exclude or [])]
    if landmark:
        target = landmark[0]
    elif ids:
        target = ids[0]
    elif ph.mentions_ego(clause) and "ego" not in (exclude or []):
        target = "ego"
    elif ph.has_any(clause, ("there", "same place", "same spot", "nearby", "around it", "near it")):
        focus = memory.last_focus()
        if focus is not None:
            return {"relation": "absolute", "x": round(focus[0], 2), "y": round(focus[1], 2)}
    if ph.has_any(clause, ("sidewalk", "pavement", "footpath", "kerb", "curb")):
        return {"relation": "on_sidewalk", **({"target": target} if target else {})}
    if ph.has_any(clause, ("in the lane", "on the road", "in lane", "on the street")):
        return {"relation": "in_lane", **({"target": target} if target else {})}
    if target is None:
        return None
    relation = "at"
    for words, rel in ((("in front of", "ahead of"), "in_front_of"), (("behind",), "behind"),
                       (("left of", "to the left"), "left_of"), (("right of", "to the right"), "right_of"),
                       (("next to", "beside", "alongside"), "next_to")):
        if any(f" {w} " in low for w in words):
            relation = rel
            break
    location: dict[str, Any] = {"relation": relation, "target": target}
    metres = ph.find_distance(clause)
    if metres is not None and relation != "at":
        location["distance"] = metres
    return location


def _maintenance_target(scene: Scene, memory: Memory) -> str | None:
    """The obstacle a "mark the maintenance" request most likely means: the newest one."""
    tagged = [a for a in scene.assets if "maintenance" in catalog()[a.category].tags
              and "obstacle" in catalog()[a.category].tags]
    if not tagged:
        return None
    focus = memory.last_focus()
    if focus is not None:
        tagged.sort(key=lambda a: math.hypot(a.pose.x - focus[0], a.pose.y - focus[1]))
        return tagged[0].id
    return tagged[-1].id


def _arrange(clause: str, scene: Scene, memory: Memory, mentions: list[ph.Mention]) -> ToolCall:
    items = [m for m in mentions if scene.count(m.category) == 0 or m.plural or m is mentions[0]]
    # The categories to lay out are those named before the target ("cones around the bus").
    around_pos = ph.normalise(clause).find(" around ")
    layout = [m.category for m in items if around_pos < 0 or m.start < around_pos] or [items[0].category]
    layout = list(dict.fromkeys(layout))
    args: dict[str, Any] = {"categories": layout[:4]}
    count = ph.find_count(clause, mentions[0].start)
    if count:
        args["count"] = count
    if ph.has_any(clause, ("line", "row", "in a line", "in a row")):
        args["shape"] = "line"
    elif ph.has_any(clause, ("grid",)):
        args["shape"] = "grid"
    elif ph.has_any(clause, ("along the lane", "along the road", "lane edge", "along the edge", "along the kerb")):
        args["shape"] = "lane_edge"
    else:
        args["shape"] = "ring"
    location = _location(clause, scene, memory)
    if args["shape"] == "ring":
        targets = [m for m in mentions if m.category not in layout]
        named = [a for a in scene.assets if targets and a.category == targets[0].category]
        if named:
            location = {"relation": "at", "target": named[-1].id}
        elif location is None or ph.has_any(clause, ("maintenance", "construction", "work zone", "roadwork")):
            focus_target = _maintenance_target(scene, memory)
            if focus_target is not None and location is None:
                location = {"relation": "at", "target": focus_target}
    if location is None:
        focus = memory.last_focus()
        location = ({"relation": "absolute", "x": round(focus[0], 2), "y": round(focus[1], 2)}
                    if focus else {"relation": "scene_centre"})
    args["location"] = location
    spacing = re.search(r"(\d+(?:\.\d+)?)\s*(?:m|metres?|meters?)\s*apart", clause.lower())
    if spacing:
        args["spacing"] = float(spacing.group(1))
    radius = re.search(r"radius (?:of )?(\d+(?:\.\d+)?)", clause.lower())
    if radius:
        args["radius"] = float(radius.group(1))
    label = "maintenance" if ph.has_any(clause, ("maintenance", "construction")) else ""
    if label:
        args["label"] = label
    return ToolCall(tool="arrange_assets", args=args)


def _add(clause: str, scene: Scene, memory: Memory, mentions: list[ph.Mention]) -> list[ToolCall]:
    mention = mentions[0]
    count = ph.find_count(clause, mention.start) or (3 if mention.plural else 1)
    # The count is passed as said: the Worker refuses what is too many, in words.
    args: dict[str, Any] = {"category": mention.category, "count": count}
    kind = _behaviour_kind(clause)
    motion = catalog()[mention.category].motion
    if (kind in ("jaywalk", "cross_road") and motion != "walker") or (
        kind in ("circle", "drive_lane") and motion != "vehicle"
    ):
        kind = None  # "cones in front of the ego's path" describe a place, not a behaviour
    if kind is not None:
        args["behaviour"] = _behaviour_spec(kind, clause, scene)
    location = _location(clause, scene, memory)
    if location is not None and not (kind == "jaywalk" and location.get("target") == "ego"):
        args["location"] = location
    elif kind is None and memory.last_focus() is not None and ph.has_any(clause, ("also", "more", "another")):
        focus = memory.last_focus()
        assert focus is not None
        args["location"] = {"relation": "absolute", "x": round(focus[0], 2), "y": round(focus[1], 2)}
    colour = next((c for c in COLOURS if ph.has_any(clause, (c,))), None)
    if colour is not None:
        args["colour"] = colour
    return [ToolCall(tool="add_asset", args=args)]
