"""Does a plan cover every content phrase of a request? The signals check.py adds to polarity.

The plan-versus-request check (check.py) weighs what a plan does against what the words ask.
This module reads the structural signals that need more than a word: which named things the
plan leaves out altogether ("the hydrant and the bin" done as the hydrant only), a definite
reference to something that exists answered by adding another ("the SUV behind us" adds an
SUV), weather and clock times named but not set, a plural or bare removal done on only one
of many, and a place whose name the world does not know ("near the gym"). Each finding is a
sentence in plain words; check.py turns findings into a question or a refusal.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.spelling import edits, english_words, is_known, vocabulary
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.scene import AssetInstance, Scene

# Words before a category that point at one already in the scene ("the SUV", "those cones").
_DEFINITE = ("the", "that", "this", "those", "these", "our", "my", "all", "every", "each", "both")
# Words that ask for a new one even after a definite article ("the new bench", "another").
_NEW = re.compile(
    r"\b(add|adds|added|adding|new|another|more|extra|create|spawn|insert|second|additional|"
    r"copy|duplicate|row of|line of|ring of|grid of)\b"
)
# Prepositions after which a request names a place ("near the gym", "on the moon").
_PLACE_PREPOSITION = re.compile(
    r"\b(?:near|at|by|around|round|beside|next to|behind|in front of|inside|outside|into|onto|on|to|towards|"
    r"close to|opposite|where is|where's|where are)\s+the\s+([a-z][a-z' -]*)"
)
# Words after "the" that are part of a relation, not a place ("on the right", "to the north").
_RELATION_WORDS = frozenset(
    [
        "right",
        "left",
        "north",
        "south",
        "east",
        "west",
        "side",
        "middle",
        "centre",
        "center",
        "edge",
        "end",
        "corner",
        "way",
        "moment",
        "front",
        "back",
        "rear",
        "top",
        "bottom",
        "same",
        "other",
        "first",
        "last",
        "next",
        "road",
        "street",
        "lane",
        "sidewalk",
        "pavement",
        "kerb",
        "curb",
        "ground",
        "scene",
        "world",
        "campus",
        "area",
        "spot",
        "place",
        "crossing",
        "intersection",
        "junction",
        "road's",
    ]
)
# Weather kinds a request names directly (a goal such as "test the wipers" is read by the planner).
_WEATHER_NAMES = ("rain", "snow", "fog", "cloud", "clear sky", "clear skies", "sunny", "sunshine")
# A clock time: "18:30", "7 pm", "7 o'clock", "half past six", "quarter to nine".
_CLOCK = re.compile(r"\b(\d{1,2}:\d\d|\d{1,2}\s*(?:am|pm|o'clock)|(?:half|quarter) (?:past|to) \w+)\b")
# Parts of the day a request names as a time to set; "this morning" is when, not what.
_DAY_PART = re.compile(r"(?<!this )\b(morning|afternoon|evening|night|midnight|noon|midday|dusk|dawn|sunset|sunrise)\b")
# Words that open background ("where people relax", "before I plan the pedestrian test"):
# a category named after them is circumstance, not something the plan must act on.
_BACKGROUND = re.compile(r"\b(where|when|while|before|after|because|so that|so|since|until|unless)\b")
# A thing named after a preposition of place ("from behind the parked bus", "next to a bench")
# is where something is, not something the plan must act on.
_LOCATIVE = re.compile(
    r"\b(behind|beside|next to|in front of|near|around|by|past|alongside|opposite|across from|beyond)\s+"
    r"(?:(?:the|a|an|that|this|those|these|its|their|our)\s+)?(?:[a-z]+\s+)?$"
)
# Category names that are also the planner's verbs ("stop the ego"): not a thing named.
_VERB_NAMES = frozenset(
    w for table in (lx.STOP_WORDS, lx.MOVE_WORDS, lx.TURN_WORDS, lx.REMOVE_WORDS) for w in table if " " not in w
)


@dataclass(frozen=True)
class Scope:
    """What a plan touches, as the coverage checks need it."""

    calls: tuple[ToolCall, ...]
    touched: tuple[AssetInstance, ...]
    removed: tuple[AssetInstance, ...]
    added: tuple[AssetInstance, ...]


def _ids_of(scene: Scene, category: str) -> set[str]:
    return {a.id for a in scene.all_assets() if a.category == category}


def named_things(masked: str, categories: Iterable[str], scene: Scene) -> set[str]:
    """The categories a plan must act on: not ones named as background, as a verb, as the
    head of a compound ("suv car"), or as the start of a misspelt place ("bus stpo")."""
    wanted = set(categories)
    mentions = ph.find_categories(masked)
    masked = ph.normalise(masked)  # the text find_categories indexes
    places = [ph.normalise(n).strip() for lm in scene.landmarks for n in lm.names()]
    out = set()
    for i, m in enumerate(mentions):
        said = masked[m.start : m.end].strip()
        rest = re.findall(r"[a-z0-9']+", masked[m.start :])
        near_place = any(
            len(p.split()) > len(said.split()) and edits(" ".join(rest[: len(p.split())]), p) <= 2 for p in places
        )
        compound = i > 0 and not masked[mentions[i - 1].end : m.start].strip()
        if m.category not in wanted or _BACKGROUND.search(masked[: m.start]) or said in _VERB_NAMES:
            continue
        if _LOCATIVE.search(masked[max(0, m.start - 40) : m.start]):
            continue
        if not (near_place or compound):
            out.add(m.category)
    return out


def missing_categories(categories: Iterable[str], scope: Scope, scene: Scene) -> list[str]:
    """Categories the request names that the plan neither touches nor names in any call."""
    said = " ".join(str(c.args) for c in scope.calls).lower()
    out = []
    for category in sorted(categories):
        if any(a.category == category for a in scope.touched):
            continue
        if category in said or any(re.search(rf"\b{re.escape(i)}\b", said) for i in _ids_of(scene, category)):
            continue
        out.append(category)
    return out


def definite_but_added(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """Categories referred to as existing ("the SUV", "those benches") that the plan adds anew
    while the scene has them and no word asks for a new one."""
    if _NEW.search(masked) or any(c.tool == "arrange_assets" for c in scope.calls):
        return []
    out = []
    mentions = ph.find_categories(masked)
    masked = ph.normalise(masked)  # the text find_categories indexes
    for m in mentions:
        before = masked[: m.start].split()[-2:]
        if not any(w in _DEFINITE for w in before) or not scene.count(m.category):
            continue
        if any(a.category == m.category for a in scope.added) and m.category not in out:
            out.append(m.category)
    return out


def environment_left_out(low: str, calls: tuple[ToolCall, ...]) -> list[str]:
    """Weather or time of day the request names that no call sets (or sets to another time)."""
    tools = {c.tool for c in calls}
    out = []
    weather = [w for w in _WEATHER_NAMES if re.search(rf"\b{w}", low)]
    if weather and "set_weather" not in tools:
        out.append(f"you mentioned {weather[0]}, but the plan does not set the weather")
    clock = _CLOCK.search(low)
    day = _DAY_PART.search(low)
    day_part = day.group(1) if day else None
    if (clock or day_part) and "set_time_of_day" not in tools and "set_lighting" not in tools:
        out.append(f"you mentioned {clock.group(1) if clock else day_part}, but the plan does not set the time")
    exact = re.search(r"\b(\d{1,2}):(\d\d)\b", low)
    times = [str(c.args.get("time")) for c in calls if c.tool == "set_time_of_day"]
    if exact and times and f"{int(exact.group(1)):02d}:{exact.group(2)}" not in times:
        out.append(f"you said {exact.group(0)}, but the plan sets the time to {times[0]}")
    return out


def partial_removal(masked: str, scope: Scope, scene: Scene, limited: bool) -> list[str]:
    """A plural or bare category ("remove cones", "get rid of pedestrian") of which the plan
    removes only some, with no number, place or state in the request to say which."""
    if limited or not scope.removed or re.search(r"\b(fewer|less|too many|thin|some of|one of|a few)\b", masked):
        return []
    out = []
    mentions = ph.find_categories(masked)
    masked = ph.normalise(masked)  # the text find_categories indexes
    for m in mentions:
        before = masked[: m.start].split()[-1:]
        single = bool(before) and before[0] in ("a", "an", "one", "the", "that", "this")
        if single and not m.plural:
            continue
        gone = sum(1 for a in scope.removed if a.category == m.category)
        there = scene.count(m.category)
        if 0 < gone < there:
            out.append(f"you named {m.category.replace('_', ' ')}s, but the plan removes {gone} of the {there}")
    return out


def unknown_places(masked: str, calls: tuple[ToolCall, ...], scene: Scene) -> list[str]:
    """Place names the world does not know ("near the gym") that no call mentions."""
    vocab = vocabulary(scene)
    said = " ".join(str(c.args) for c in calls).lower()
    ids = {a.id for a in scene.all_assets()}
    out = []
    for m in _PLACE_PREPOSITION.finditer(masked):
        words = [w for w in re.split(r"[\s-]+", m.group(1)) if w][:3]
        for word in words:
            if word in lx.GRAMMAR or word in _RELATION_WORDS or word in ids or word == "ego":
                break
            if ph.find_categories(word) or is_known(word, vocab):
                break
            if word in said or word not in english_words():
                break  # a misspelling is the planner's to repair; a word the plan uses is accounted for
            out.append(word)
            break
    return list(dict.fromkeys(out))


__all__ = [
    "Scope",
    "definite_but_added",
    "environment_left_out",
    "missing_categories",
    "named_things",
    "partial_removal",
    "unknown_places",
]
