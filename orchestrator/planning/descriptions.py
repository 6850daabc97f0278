"""Things and places said by what they are or do instead of by name: "the big vehicle that carries
lots of passengers", "the thing you throw rubbish in", "the building where the books are kept".

The words from a general head noun ("thing", "vehicle", "place", "building") through the clause
that describes it are compared in meaning (MiniLM, `grounding.embed`) with the catalog's category
descriptions, or with the world's places (names, aliases, descriptions). The head says which of
them it can be: a vehicle is one of the categories that drive, a building or place is a landmark.
A description is read as a name only when one candidate stands clearly ahead of the next;
otherwise the words are left as said, for the planners and the check to ask about.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache
from typing import Any

from drivetwin.orchestrator.planning.grounding import GroundingUnavailable, embed
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.scene import Scene

# Cosine similarity a description must reach, and its lead over the next candidate (MiniLM: a
# paraphrase of a catalog description scores 0.5-0.65, unrelated short phrases 0.1-0.35).
THING_FLOOR, THING_LEAD = 0.45, 0.10
PLACE_FLOOR, PLACE_LEAD = 0.40, 0.08
# The longest clause read after the head, in words.
MAX_CLAUSE_WORDS = 10

_THING_HEADS = ("thing", "things", "object", "objects", "item", "items", "device", "devices", "contraption", "gadget")
_VEHICLE_HEADS = ("vehicle", "vehicles")
_PLACE_HEADS = ("place", "building", "spot", "location", "site")
# What opens a describing clause after the head: "that carries ...", "where the books are kept",
# "you throw rubbish in", "firefighters hook their hoses to" (a plural noun doing something).
_CLAUSE_START = r"(?:that|which|who|where|whose|with|for|you|we|people|they|everyone|[a-z]+ers|[a-z]+ists|students)"
_SPAN = re.compile(
    r"\b(the|a|an|that|those|these|this|some)\s+((?:[a-z0-9'-]+\s+){0,3}?)("
    + "|".join((*_THING_HEADS, *_VEHICLE_HEADS, *_PLACE_HEADS))
    + rf")\b((?:\s+{_CLAUSE_START}\b[^,.;:!?\n]*)?)",
    re.IGNORECASE,
)
# Where the describing clause ends and the request goes on: a place said after it ("... in by the
# bus stop"), what the thing is to be doing ("... waiting at the stop"), or the request's own verb.
_CLAUSE_END = re.compile(r"\s(?=(?:at|by|near|next to|beside|behind|outside|inside|in front of|on|onto|into|in|over|across|along|from|to)"
                         r"\s+(?:the|a|an|lot|parking|main|campus|our|my|this|that)\b|[a-z]+ing\b|(?:should|must|will|would|can|could|"
                         r"needs?|has|have|had|is|was|gets?|goes|please|and|then|but|so)\b)")
# Modifiers that say which one, not what kind: "the same spot", "that other thing", "the first vehicle".
_POINTING = frozenset(["same", "other", "first", "second", "third", "last", "next", "previous", "one", "new", "old", "whole", "only", "each", "every"])


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
    place = head in _PLACE_HEADS
    if place and not clause:
        return None  # "that nice spot": a place pointed at, not described
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
        name, score, lead, runner_up = _best(phrases, names, _place_vectors(texts), list(range(len(names))))
    else:
        kinds, vectors = _category_vectors()
        allowed = [i for i, k in enumerate(kinds) if head not in _VEHICLE_HEADS or catalog()[k].motion == "vehicle"]
        name, score, lead, runner_up = _best(phrases, kinds, vectors, allowed)
        if head in _VEHICLE_HEADS and name == "passenger_car" and lead >= THING_LEAD:
            return None  # a vehicle that is a car: the words already say so
    end = m.start(4) + (len(m.group(4)) - len(m.group(4).lstrip())) + len(" ".join(words))
    plural = head.endswith("s") and not head.endswith("ss")
    return Described(m.group(0)[: end - m.start()].strip(), name, score, lead, runner_up, m.start(), end, m.group(1), plural)


def _all_read(text: str, scene: Scene) -> list[Described]:
    """Every description in `text` with its best and next best names, in order."""
    found: list[Described] = []
    for m in _SPAN.finditer(text):
        if found and m.start() < found[-1].end:
            continue
        try:
            read = _read(m, scene)
        except GroundingUnavailable:
            return []
        if read is not None:
            found.append(read)
    return found


def unsure(text: str, scene: Scene) -> list[Described]:
    """The descriptions in `text` that come near a name but not clearly nearer one than the next
    ("the big vehicle that carries lots of passengers": a bus or a truck), for a question."""
    return [d for d in _all_read(text, scene) if not d.sure and d.score >= (THING_FLOOR if d.name in catalog() else PLACE_FLOOR)
            and d.runner_up and _CLAUSE_OPENS.match(text, d.start + len(d.determiner))]


# A description with a clause of its own ("... vehicle that carries lots of passengers"), not only adjectives.
_CLAUSE_OPENS = re.compile(rf"\s+(?:[a-z0-9'-]+\s+){{0,3}}?(?:{'|'.join((*_THING_HEADS, *_VEHICLE_HEADS, *_PLACE_HEADS))})\s+{_CLAUSE_START}\b",
                           re.IGNORECASE)


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
