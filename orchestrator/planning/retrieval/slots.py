"""Slots: the world's names and the numbers a request states, and putting them into an
example's calls in place of the example's own.

`read_slots` finds, in text order, categories, landmarks, lanes, asset ids, colours, weather
and time words (exact, plural or a close spelling) and numbers by their units (metres,
speeds, degrees, clock times, coordinates; a bare number is a count). `adapt` walks an
example's calls, replaces each named value by the request's value of the same kind (the
first by the first, ...) and counts what it had to keep (unfilled) and what the request said
that the example has no place for (unused).
"""

from __future__ import annotations

import copy
import difflib
import re
from dataclasses import dataclass, field
from functools import cache
from typing import Any

from drivetwin.orchestrator.planning.retrieval._frames import RELATION_WORDS, STRENGTHS, TIME_WORDS, WEATHER
from drivetwin.orchestrator.planning.retrieval._words import NUMBER_WORDS, plural
from drivetwin.orchestrator.planning.rules.phrases import EGO_WORDS
from drivetwin.orchestrator.planning.rules.spelling import english_words
from drivetwin.tools.appearance import COLOURS
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.catalog import catalog, placeable_categories
from drivetwin.worlds.scene import Scene

# A single word this close in spelling to a known one is read as it ("benchs"); a long word
# may be further off ("bycicles": a swapped letter costs a long word less of its meaning).
SPELLING_CUTOFF = 0.84
LONG_WORD_LETTERS = 7
LONG_WORD_CUTOFF = 0.74
# Words shorter than this are never repaired ("bus"/"bush", "car"/"cat").
SPELLING_MIN_LETTERS = 4
LONGEST_PHRASE_WORDS = 5
_SPEED = re.compile(r"(\d+(?:\.\d+)?)\s*(m/s|km/h|kmh|kph|mph)")
_ANGLE = re.compile(r"(\d+(?:\.\d+)?)\s*(degrees|degree|deg|°)")
_METRES = re.compile(r"(\d+(?:\.\d+)?|" + "|".join(NUMBER_WORDS) + r")\s*(m|metres|meters|metre|meter)\b")
_CLOCK = re.compile(r"\b([01]?\d|2[0-3]):([0-5]\d)\s*(am|pm)?\b|\b(1[0-2]|[1-9])\s*(am|pm)\b")
_XY = re.compile(
    r"x\s*=?\s*(-?\d+(?:\.\d+)?)[^\d-]{1,8}y\s*=?\s*(-?\d+(?:\.\d+)?)|\((-?\d+(?:\.\d+)?),\s*(-?\d+(?:\.\d+)?)\)"
    r"|coordinates\s*(-?\d+(?:\.\d+)?),?\s*(-?\d+(?:\.\d+)?)"
)
_AMOUNTS = {"a couple of": 2, "a pair of": 2, "half a dozen": 6, "a dozen": 12}
_SPEED_FACTOR = {"m/s": 1.0, "km/h": 3.6, "kmh": 3.6, "kph": 3.6, "mph": 2.237}
_RADIUS = re.compile(r"radius|wide circle|across")
# Relation words, longest first ("to the left of" before "left of"); "at", "by" and "around"
# say too little to overrule an example's relation ("at 18:30").
_RELATIONS = sorted(
    [
        (w, rel)
        for rel, words in RELATION_WORDS.items()
        if rel != "on_sidewalk"
        for w in words
        if w not in ("at", "by", "around")
    ]
    + [("on the sidewalk", "on_sidewalk"), ("on the pavement", "on_sidewalk"), ("on the footpath", "on_sidewalk")],
    key=lambda wr: -len(wr[0]),
)
# Words that point back at the conversation: retrieval cannot resolve them, the rules can.
REFERENCES = re.compile(r"\b(there|them|those|it|that one|same place|again)\b")


# What a request asks for, told by its words: a removal, or a question (which changes nothing).
_REMOVAL = re.compile(
    r"\b(remove|delete|get rid|take away|take out|clear|erase|no longer|don'?t (want|need)|do not (want|need)"
    r"|no more|shouldn'?t be|must go|lose|pull out)\b"
)
_QUESTION = re.compile(r"\?|^\s*(where|which|what|how|is there|are there|list|find|show|count|tell me|locate)\b")


def intents(text: str) -> frozenset[str]:
    """The request's intent markers: "removal" and/or "question"."""
    low = text.lower()
    found = {"removal"} if _REMOVAL.search(low) else set()
    return frozenset(found | ({"question"} if _QUESTION.search(low) else set()))


@dataclass
class Slots:
    """What a request named, in order: (kind, value) pairs."""

    found: list[tuple[str, Any]] = field(default_factory=list)

    def of(self, kind: str) -> list[Any]:
        return [v for k, v in self.found if k == kind]


def _norm(text: str) -> str:
    return " ".join(re.sub(r"[^a-z0-9 ]+", " ", text.lower().replace("_", " ")).split())


@cache
def _static_phrases() -> dict[str, tuple[str, Any]]:
    phrases: dict[str, tuple[str, Any]] = {}
    allowed = set(placeable_categories())
    for cat in catalog().values():
        if cat.name not in allowed:
            continue
        for word in cat.words:
            key = _norm(word)
            phrases.setdefault(key, ("category", cat.name))
            phrases.setdefault(_norm(plural(word)), ("category", cat.name))
    for name in COLOURS:
        phrases[name] = ("colour", name)
    for kind, words in WEATHER.items():
        for word in words:
            phrases.setdefault(_norm(word), ("weather", kind))
    for word, value in STRENGTHS:
        phrases[word] = ("intensity", value)
    for word, preset in TIME_WORDS:
        phrases[_norm(word)] = ("time", preset)
    return phrases


def _scene_phrases(scene: Scene) -> dict[str, tuple[str, Any]]:
    phrases = dict(_static_phrases())
    for lm in scene.landmarks:
        for word in lm.names():
            phrases[_norm(word)] = ("place", lm.name)
    for lane in scene.roads.lanes:
        words = _norm(lane.id)
        phrases[words] = phrases[f"{words} lane"] = ("lane", lane.id)
    words_of = {c.name: c.words for c in catalog().values()}
    for asset in scene.all_assets():
        phrases[_norm(asset.id)] = ("asset", asset.id)
        number = asset.id.rsplit("_", 1)[-1]
        if number.isdigit():
            for word in words_of.get(asset.category, ()):
                phrases[f"{_norm(word)} {number}"] = ("asset", asset.id)
                phrases[f"{_norm(word)} number {number}"] = ("asset", asset.id)
        if asset.label:
            phrases[_norm(asset.label)] = ("asset", asset.id)
    for word in EGO_WORDS:  # "the player car", "the insured vehicle": the ego, not a car
        phrases[_norm(word)] = phrases[_norm(f"the {word.removeprefix('the ')}")] = ("asset", "ego")
    return phrases


def read_slots(text: str, scene: Scene) -> Slots:
    """The world's names and the numbers in `text`, in the order they appear."""
    low = text.lower()
    found: list[tuple[int, str, Any]] = []

    def take(match: re.Match[str], kind: str, value: Any) -> None:
        nonlocal low
        found.append((match.start(), kind, value))
        low = low[: match.start()] + " " * (match.end() - match.start()) + low[match.end() :]

    for m in list(_XY.finditer(low)):
        x, y = (
            next(g for g in (m.group(1), m.group(3), m.group(5)) if g),
            next(g for g in (m.group(2), m.group(4), m.group(6)) if g),
        )
        take(m, "x", float(x))
        found.append((m.start() + 1, "y", float(y)))
    for m in list(_CLOCK.finditer(low)):
        if m.group(1) is not None:
            hour = int(m.group(1)) % 12 + (12 if m.group(3) == "pm" else 0) if m.group(3) else int(m.group(1))
            take(m, "time", f"{hour:02d}:{m.group(2)}")
        else:
            hour = int(m.group(4)) % 12 + (12 if m.group(5) == "pm" else 0)
            take(m, "time", f"{hour:02d}:00")
    for m in list(_SPEED.finditer(low)):
        take(m, "speed", round(float(m.group(1)) / _SPEED_FACTOR[m.group(2)], 2))
    for m in list(_ANGLE.finditer(low)):
        take(m, "angle", float(m.group(1)))
    for m in list(_METRES.finditer(low)):
        said = m.group(1)
        value = float(NUMBER_WORDS.index(said)) if said in NUMBER_WORDS else float(said)
        take(m, "radius" if _RADIUS.search(low[max(0, m.start() - 16) : m.start()]) else "distance", value)
    for phrase, amount in _AMOUNTS.items():
        for m in list(re.finditer(rf"\b{phrase}\b", low)):
            take(m, "count", amount)
    for words, relation in _RELATIONS:
        for m in list(re.finditer(rf"\b{re.escape(words)}\b", low)):
            take(m, "relation", relation)
    # weather said gone ("no more snow", "kill the rain", "turn off the fog") is clear weather
    found += [(at, kind, "clear" if kind == "weather" and _WEATHER_GONE.search(low[max(0, at - 24) : at]) else value)
              for at, kind, value in _words(low, scene)]
    if "light" in low or "lamp" in low:
        state = re.search(r"\b(on|off)\b", low)
        if state:
            found.append((state.start(), "lights", state.group(1)))
    return Slots([(kind, value) for _, kind, value in sorted(found, key=lambda f: f[0])])


# Words just before a weather that deny it ("no more snow", "turn off the fog"): what is asked for is the
# weather without it. (Narrower than the rule planner's: "not too heavy rain" is still rain.)
_WEATHER_GONE = re.compile(r"\b(?:no|stop|end|without|rid of|kill|cancel|remove|lift|clear|off|don'?t want|do not want)\s+"
                           r"(?:(?:the|any|all|that|this|more|of)\s+)*$")


def _words(low: str, scene: Scene) -> list[tuple[int, str, Any]]:
    """Longest known phrases first, then single words by spelling, then bare numbers."""
    phrases = _scene_phrases(scene)
    spans = [(m.start(), m.group(0)) for m in re.finditer(r"[a-z0-9]+", low.replace("_", " "))]
    words = [w for _, w in spans]
    found: list[tuple[int, str, Any]] = []
    i = 0
    singles = [p for p in phrases if " " not in p and len(p) >= SPELLING_MIN_LETTERS]
    while i < len(words):
        for size in range(min(LONGEST_PHRASE_WORDS, len(words) - i), 0, -1):
            key = " ".join(words[i : i + size])
            if key in phrases:
                found.append((spans[i][0], *phrases[key]))
                i += size
                break
        else:
            word = words[i]
            if word.isdigit():
                found.append((spans[i][0], "count", int(word)))
            elif word in NUMBER_WORDS[2:] and not low[: spans[i][0]].endswith("-"):  # not the "six" of "thirty-six"
                found.append((spans[i][0], "count", NUMBER_WORDS.index(word)))
            elif len(word) >= SPELLING_MIN_LETTERS and word not in english_words():
                # a real word is no slip for a near name ("there" is no "three", "over" no "rover")
                cutoff = LONG_WORD_CUTOFF if len(word) >= LONG_WORD_LETTERS else SPELLING_CUTOFF
                close = difflib.get_close_matches(word, singles, n=1, cutoff=cutoff)
                if close:
                    found.append((spans[i][0], *phrases[close[0]]))
            i += 1
    return found


# Argument names that hold a slot, and the slot's kind.
_KEY_KIND = {
    "category": "category",
    "categories": "category",
    "asset": "asset",
    "assets": "asset",
    "lane": "lane",
    "count": "count",
    "distance": "distance",
    "forward": "distance",
    "left": "distance",
    "turn_deg": "angle",
    "yaw_deg": "angle",
    "speed": "speed",
    "radius": "radius",
    "colour": "colour",
    "time": "time",
    "intensity": "intensity",
    "street_lights": "lights",
    "vehicle_lights": "lights",
    "x": "x",
    "y": "y",
    "relation": "relation",
}
_PLACE_KEYS = ("target", "near", "centre", "query", "a", "b")  # a, b: the ends measure_distance measures between
# When the request has none of a kind, these stand in for it (a lane is a place, an asset's
# category names it...); how they convert is in `_stand_in`.
_STAND_INS = {"place": ("lane", "asset"), "lane": ("place",), "asset": ("category",), "category": ("asset",)}


@dataclass
class Adapted:
    """An example's calls with this request's slots put in, and how well they fitted."""

    calls: list[ToolCall]
    unfilled: int
    unused: int
    filled: int
    # Slots filled from another kind (an asset from a category said, a lane for a place...).
    stood_in: int = 0
    # Amounts the request did not state, left to the tool's default.
    dropped: int = 0


def adapt(calls: list[ToolCall], slots: Slots, scene: Scene, tool_defaults: frozenset[str] = frozenset()) -> Adapted:
    """`calls` with each slot value replaced by the request's value of the same kind."""
    lanes = {lane.id for lane in scene.roads.lanes}
    assets = {a.id for a in scene.all_assets()}
    wanted: dict[str, list[Any]] = {}
    for kind, value in slots.found:
        wanted.setdefault(kind, []).append(value)
    used: dict[str, set[int]] = {}
    seen: dict[str, list[Any]] = {}
    counts = {"unfilled": 0, "filled": 0, "stood_in": 0, "dropped": 0}

    def kind_of(key: str, value: Any, tool: str) -> str | None:
        if key in _PLACE_KEYS and isinstance(value, str):
            return "lane" if value in lanes else "asset" if value in assets and key != "query" else "place"
        if key == "kind" and tool == "set_weather":
            return "weather"
        return _KEY_KIND.get(key)

    def replace(kind: str, value: Any) -> Any:
        order = seen.setdefault(kind, [])
        if value not in order:
            order.append(value)
        index = order.index(value)
        pool = wanted.get(kind, [])
        if index < len(pool):
            used.setdefault(kind, set()).add(index)
            counts["filled"] += 1
            new = pool[index]
            if kind == "distance" and isinstance(value, (int, float)) and value < 0:
                return -abs(new)
            return new
        for other in _STAND_INS.get(kind, ()):
            stood = _stand_in(kind, other, wanted.get(other, []), scene)
            if stood is not None:
                used.setdefault(other, set()).add(0)
                counts["stood_in"] += 1
                return stood
        if kind == "relation":
            return value  # an unsaid relation keeps the example's: "at" and "near" differ little
        if kind in _DROPPABLE:
            counts["dropped"] += 1
            return _DROP  # unsaid: the tool's default ("a sign" is one, "by X" is just clear of it)
        counts["unfilled"] += 1
        return value

    def walk(node: Any, tool: str) -> Any:
        if isinstance(node, dict):
            out: dict[str, Any] = {}
            for key, value in node.items():
                kind = (
                    kind_of(key, value, tool)
                    if not isinstance(value, (dict, list)) or key in ("categories", "assets")
                    else None
                )
                if kind is not None and isinstance(value, list):
                    out[key] = [replace(kind, v) for v in value]
                elif kind is not None:
                    new = replace(kind, value)
                    if new is not _DROP:
                        out[key] = new
                else:
                    out[key] = walk(value, tool)
            return out
        if isinstance(node, list):
            return [walk(v, tool) for v in node]
        return node

    adapted = [ToolCall(tool=c.tool, args=walk(copy.deepcopy(c.args), c.tool)) for c in calls]
    unused = sum(len(values) - len(used.get(kind, set())) for kind, values in wanted.items())
    return Adapted(adapted, counts["unfilled"], max(0, unused), counts["filled"], counts["stood_in"], counts["dropped"])


_DROP = object()
# Slot kinds whose value an example may lose when the request does not say one.
_DROPPABLE = frozenset({"count", "distance"})


def _stand_in(kind: str, other: str, values: list[Any], scene: Scene) -> Any:
    if not values:
        return None
    value = values[0]
    if kind == "asset" and other == "category":
        same = [a.id for a in scene.all_assets() if a.category == value]
        return same[0] if same else None
    if kind == "category" and other == "asset":
        asset = scene.asset(value)
        return asset.category if asset is not None and asset.id != "ego" else None
    return value


__all__ = ["REFERENCES", "Adapted", "Slots", "adapt", "intents", "read_slots"]
