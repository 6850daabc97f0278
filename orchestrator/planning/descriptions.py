"""Things and places said by what they are or do instead of by name: "the big vehicle that carries
lots of passengers", "the thing you throw rubbish in", "the building where the books are kept".

The words from a general head noun ("thing", "vehicle", "place", "building") through the clause
that describes it are compared in meaning (MiniLM, `grounding.embed`) with the catalog's category
descriptions, or with the world's places (names, aliases, descriptions). The head says which of
them it can be: a catalog group word ("vehicle", "sign", "car", "marker") one of that group, a
building, place or entrance a landmark (one that way, when a compass word is said). A description
is read as a name only when one candidate stands clearly ahead of the next (`described`, used by
the spelling repair every planner and the check share); one near two is asked about (`unsure`, the
rule planner's question); otherwise the words are left as said.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from typing import Any

from drivetwin.orchestrator.planning.grounding import GroundingUnavailable, embed
from drivetwin.orchestrator.planning.rules.modifiers import SIZE_WORDS
from drivetwin.tools.appearance import COLOURS
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.scene import Scene

# Cosine similarity a description must reach, and its lead over the next candidate (MiniLM: a
# paraphrase of a catalog description scores 0.5-0.65, unrelated short phrases 0.1-0.35).
THING_FLOOR, THING_LEAD = 0.45, 0.10
PLACE_FLOOR, PLACE_LEAD = 0.40, 0.08
# With one candidate left (the one place that way), no lead can be measured: it must be this close on its own.
ALONE_FLOOR = 0.65
# The longest clause read after the head, in words.
MAX_CLAUSE_WORDS = 10

_THING_HEADS = ("thing", "things", "object", "objects", "item", "items", "device", "devices", "contraption", "gadget", "pole", "poles")
_PLACE_HEADS = ("place", "building", "spot", "location", "site", "entrance", "exit", "way in", "way out")
# What opens a describing clause after the head: "that carries ...", "where the books are kept",
# "you throw rubbish in", "firefighters hook their hoses to" (a plural noun doing something).
_CLAUSE_START = r"(?:that|which|who|where|whose|with|for|you|we|people|they|everyone|[a-z]+ers|[a-z]+ists|students|of the campus|of campus)"
# Catalog tags that are not nouns a person calls a thing by.
_NOT_HEADS = frozenset(["ego", "actor", "npc", "permanent", "temporary", "vulnerable", "vru", "maintenance", "street furniture"])
# Modifiers that pick one out rather than say what it is: a colour, what it is doing or its size among
# the others ("the red car", "the parked cars", "the smallest vehicle").
_PICKING = frozenset([*COLOURS, *SIZE_WORDS, "parked", "moving", "driving", "stopped", "stationary", "nearest", "closest", "furthest"])


# A clause that only says where a thing is ("which are standing in lot B", "parked by the gate").
_ONLY_WHERE = re.compile(r"(?:(?:which|that|who)\s+(?:is|are|was|were|'s)\s+|(?:which|that|who)\s+)?"
                         r"(?:(?:standing|sitting|parked|waiting|stopped|left|placed|located|situated|lined up)\s+)?"
                         r"(?:in|at|on|by|near|next to|beside|behind|outside|inside|along|across|around|in front of)\b", re.IGNORECASE)


@cache
def _groups() -> dict[str, frozenset[str]]:
    """Head words for a group of categories, singular and plural: "sign" and "signs" are the signs."""
    out: dict[str, set[str]] = {}
    for c in catalog().values():
        for tag in c.tags:
            if tag not in _NOT_HEADS and " " not in tag and c.name != "ego_vehicle":
                for word in (tag, f"{tag}s"):
                    out.setdefault(word, set()).add(c.name)
    return {w: frozenset(kinds) for w, kinds in out.items()}


@cache
def _span() -> re.Pattern[str]:
    heads = sorted({*_THING_HEADS, *_PLACE_HEADS, *_groups()}, key=len, reverse=True)
    return re.compile(
        r"(?:\b(the|a|an|that|those|these|this|some)\s+|^\s*|(?<=[,.;:!?]\s))((?:[a-z0-9'-]+\s+){0,3}?)(" + "|".join(heads)
        + rf")\b((?:\s+{_CLAUSE_START}\b[^,.;:!?\n]*)?)",
        re.IGNORECASE,
    )


# Where the describing clause ends and the request goes on: a place said after it ("... in by the
# bus stop"), what the thing is to be doing ("... waiting at the stop"), or the request's own verb.
_CLAUSE_END = re.compile(r"\s(?=(?:at|by|near|next to|beside|behind|outside|inside|in front of|on|onto|into|in|over|across|along|from|to"
                         r"|before|after|past|beyond|around|round|opposite|between|under|above)"
                         r"\s+(?:the|a|an|lot|parking|main|campus|our|my|this|that)\b|[a-z]+ing\b|(?:should|must|will|would|can|could|"
                         r"needs?|has|have|had|is|was|gets?|goes|please|and|then|but|so|instead|now|too|again)\b)")
# Words before a head that are no description: an article, a verb, a preposition ("put a construction sign").
_NOT_MODIFIERS = frozenset(["a", "an", "the", "then", "and", "or", "put", "add", "place", "some", "this", "that", "those",
                            "these", "to", "of", "in", "at", "on", "by", "with", "is", "are", "be"])
_COMPASS = re.compile(r"\b(north|south|east|west)", re.IGNORECASE)
# Modifiers that say which one, not what kind: "the same spot", "that other thing", "the first vehicle".
_POINTING = frozenset(["our", "my", "your", "their", "his", "her", "its", "same", "other", "first", "second", "third", "last", "next", "previous", "one", "new", "old", "whole", "only", "each", "every"])


@dataclass(frozen=True)
class Described:
    """A description read as a name: the words, the name, how sure, and the next best name."""

    said: str
    name: str
    score: float
    lead: float
    runner_up: str = ""
    start: int = 0
    end: int = 0
    determiner: str = "the"
    plural: bool = False

    @property
    def sure(self) -> bool:
        floor, needed = (THING_FLOOR, THING_LEAD) if self.name in catalog() else (PLACE_FLOOR, PLACE_LEAD)
        return self.score >= floor and self.lead >= needed

    def said_as(self, name: str) -> str:
        """How the request says `name` in the description's place ("the bus", "those benches")."""
        words = name.replace("_", " ")
        if self.plural and name in catalog():
            words += "es" if words.endswith(("s", "sh", "ch", "x")) else "s"
        return f"{self.determiner} {words}"


@cache
def _category_vectors() -> tuple[tuple[str, ...], Any]:
    kinds = tuple(c.name for c in catalog().values() if c.name != "ego_vehicle")
    return kinds, embed([catalog()[k].description for k in kinds])


@cache
def _place_vectors(texts: tuple[str, ...]) -> Any:
    return embed(list(texts))


def _place_text(scene: Scene) -> tuple[tuple[str, ...], tuple[str, ...]]:
    names = tuple(lm.name for lm in scene.landmarks)
    texts = tuple(f"{lm.name}: {', '.join(lm.aliases)}" + (f"; {lm.description}" if lm.description else "")
                  for lm in scene.landmarks)
    return names, texts


def _best(phrases: list[str], names: tuple[str, ...], vectors: Any, allowed: list[int]) -> tuple[str, float, float, str]:
    """The name nearest any of `phrases`, its score, its lead over the next, and that next."""
    said = embed(phrases)
    scores = said @ vectors[allowed].T
    best = (names[allowed[0]], -1.0, 0.0, "")
    for line in scores:
        order = sorted(range(len(allowed)), key=lambda j: -float(line[j]))
        top = float(line[order[0]])
        lead = top - float(line[order[1]]) if len(order) > 1 else top
        if top > best[1]:
            best = (names[allowed[order[0]]], top, lead, names[allowed[order[1]]] if len(order) > 1 else "")
    return best


def _read(m: re.Match[str], scene: Scene) -> Described | None:
    modifiers, head, clause = m.group(2).strip(), m.group(3).lower(), m.group(4).strip()
    if set(modifiers.lower().split()) & _POINTING or (not clause and not modifiers):
        return None  # "the same spot", "the vehicle": which one, said before
    single = len(_groups().get(head, ())) == 1  # "orange markers": the one kind of marker there is
    if not clause and set(modifiers.lower().split()) <= _PICKING and not single:
        return None  # "the red car", "the parked vehicles": which ones, not what kind
    if set(modifiers.lower().split()) & _NOT_MODIFIERS:
        return None  # "put a construction sign", "then a parking sign": a verb or an article, no description
    place = head in _PLACE_HEADS
    if place and not clause:
        return None  # "that nice spot": a place pointed at, not described
    if not place and _ONLY_WHERE.match(clause):
        return None  # "the vehicles which are standing in lot B": where they are, which says no kind
    cut = _CLAUSE_END.search(clause, 1 + (clause.find(" ") if " " in clause else len(clause)))  # never before its first word
    clause = clause[: cut.start()] if cut is not None else clause
    words = clause.split()[:MAX_CLAUSE_WORDS]
    stem = f"{modifiers} {head}".strip()
    # The clause ends where the request goes on ("... passengers waiting at the stop"): every length is tried.
    phrases = [stem] if not words else [f"{stem} {' '.join(words[:n])}" for n in range(1, len(words) + 1)]
    if place:
        names, texts = _place_text(scene)
        if not names:
            return None
        allowed = list(range(len(names)))
        text_said = phrases[-1].lower()
        inside = [lm.name for lm in scene.landmarks if any(re.search(rf"\b{re.escape(n.lower())}\b", text_said) for n in lm.names())]
        if inside:  # "the lot B exit where it meets Main Street": of the places named there
            allowed = [i for i in allowed if any(n.lower() in names[i].lower() for n in inside)]
        way = _COMPASS.search(" ".join(phrases[-1:]))
        if way is not None:  # "the east entrance of the campus": a place that way, never the west one
            allowed = [i for i in allowed if re.search(rf"\b{way.group(1)}", texts[i], re.IGNORECASE)]
            if not allowed:
                return None
        name, score, lead, runner_up = _best(phrases, names, _place_vectors(texts), allowed)
        if len(allowed) == 1 and score < ALONE_FLOOR:
            return None  # "the north entrance of the campus": the north crosswalk is the only place that way, and no entrance
    else:
        kinds, vectors = _category_vectors()
        group = _groups().get(head) if head not in _THING_HEADS else None
        allowed = [i for i, k in enumerate(kinds) if group is None or k in group]
        if not allowed:
            return None
        name, score, lead, runner_up = _best(phrases, kinds, vectors, allowed)
        # imported here: rules/__init__ imports the planner, which imports this module
        from drivetwin.orchestrator.planning.rules.lexicon import CONCEPTS
        from drivetwin.orchestrator.planning.rules.phrases import find_categories, has_any, normalise

        said = f"{modifiers} {head}"
        plain, indexed = find_categories(said), normalise(said)
        concept = has_any(said, tuple(w for words in CONCEPTS.values() for w in words if " " in w))
        if concept or any(indexed[p.start : p.end].strip() != head for p in plain):
            return None  # "a parking sign", "a warning sign": words that name a thing already
        if any(p.category == name for p in plain) and lead >= THING_LEAD:
            return None  # "the red-roofed car" that is a car: the words already say so
    end = m.start(4) + (len(m.group(4)) - len(m.group(4).lstrip())) + len(" ".join(words))
    plural = head.endswith("s") and not head.endswith("ss")
    start = m.start(1) if m.group(1) else m.start(2)
    return Described(m.string[start:end].strip(), name, score, lead, runner_up, start, end, m.group(1) or "the", plural)


def _all_read(text: str, scene: Scene) -> list[Described]:
    """Every description in `text` with its best and next best names, in order."""
    found: list[Described] = []
    at = 0
    while (m := _span().search(text, at)) is not None:
        try:
            read = _read(m, scene)
        except GroundingUnavailable:
            return []
        if read is not None:
            found.append(read)
        at = read.end if read is not None else m.start() + 1  # "remove the thing you ...": tried again from "the"
    return found


def unsure(text: str, scene: Scene) -> list[Described]:
    """The descriptions in `text` that come near a name but not clearly nearer one than the next
    ("the big vehicle that carries lots of passengers": a bus or a truck), for a question."""
    return [d for d in _all_read(text, scene) if not d.sure and d.score >= (THING_FLOOR if d.name in catalog() else PLACE_FLOOR)
            and d.runner_up and _CLAUSE_OPENS.match(text, d.start + len(d.determiner))]


# A description with a clause of its own ("... vehicle that carries lots of passengers"), not only adjectives.
_CLAUSE_OPENS = re.compile(rf"\s+(?:[a-z0-9'-]+\s+){{0,3}}?[a-z]+\s+{_CLAUSE_START}\b", re.IGNORECASE)


def described(text: str, scene: Scene) -> tuple[str, list[Described]]:
    """`text` with each confidently read description replaced by the name it describes (the
    determiner kept: "the bus", "the Library entrance"), and what was read."""
    sure = [d for d in _all_read(text, scene) if d.sure]
    out, at = [], 0
    for d in sure:
        out += [text[at : d.start], d.said_as(d.name)]
        at = d.end
    return "".join([*out, text[at:]]), sure


__all__ = ["Described", "described", "unsure"]
