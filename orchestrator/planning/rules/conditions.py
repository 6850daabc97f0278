"""Requests that say first what they are about, restated before they are read.

A condition on the scene ("if there's a bus, paint it yellow") is read the same way by the rule
planner (which plans the request when the condition holds, and otherwise looks the thing up,
changing nothing) and by the plan-versus-request check (which holds a plan to the request when
it holds, and otherwise to a question). A topic said first and pointed back at ("the tree
which is near the fountain, move it 3 m north") names the one thing the rest is about.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from drivetwin.orchestrator.planning.intent import commands
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.reading import find_place
from drivetwin.worlds.scene import Scene

# A condition on what is there: "if there's a bus (anywhere), paint it yellow".
_IF_THERE = re.compile(r"^\s*(?:(?:and|so|ok|oh|also)\s+)?if there(?:'s| is| are|s| be)\s+(?:a |an |any |some )?(?P<thing>[^,;:]+?)"
                       r"(?:\s+(?:anywhere|around|about|nearby|here|in the scene|on campus))?\s*(?:,|;|:|\bthen\b)\s*(?:then\s+)?(?P<rest>\S.*)$",
                       re.IGNORECASE)
# What the request after the condition calls the thing ("paint it yellow").
_CONDITION_PRONOUN = re.compile(r"\b(?:it|them|they|those|these|that one)\b")


@dataclass(frozen=True)
class Condition:
    """A request on condition that a kind of thing is there: whether it is, the request with the
    pronoun standing for the ones there ("paint the bus yellow"), and the question it becomes
    when there are none (the search's answer says so, and nothing changes)."""

    category: str
    met: bool
    request: str
    question: str  # what is asked instead when it is not met: "are there any bus?"


def condition(text: str, scene: Scene) -> Condition | None:
    """The condition "if there's a <thing>, ..." puts on a request, when it names a kind of thing
    ("if there's room, ..." names none and is a hedge, not a condition)."""
    said = _IF_THERE.match(text)
    named = ph.find_categories(f" {ph.normalise(said.group('thing'))} ") if said is not None else []
    if said is None or not named:
        return None
    there = scene.count(named[0].category)
    thing = said.group("thing").strip()
    request = _CONDITION_PRONOUN.sub(f"every {thing}" if there > 1 else f"the {thing}", said.group("rest"), count=1)
    return Condition(named[0].category, there > 0, request, f"are there any {thing}?")



# A thing said first with where it is, then pointed back at: "Tree which is near fountain, that
# one keep near the door", "the tree that's by the fountain, move it 3 m north".
_TOPIC_FIRST = re.compile(r"^\s*(?:the\s+|that\s+|this\s+)?(?P<thing>[a-z][a-z-]*(?:\s+[a-z][a-z-]*){0,2}?)\s+(?:(?:which|that|who)(?:'s|\s+is|\s+stands?|\s+sits?)\s+)?"
                          r"(?:near|by|next to|beside|close to|at|in)\s+(?P<place>[^,;]+?)\s*[,;:-]+\s*(?P<rest>.*\b(?:it|that one|this one)\b.*)$",
                          re.IGNORECASE)
_POINTING = re.compile(r"\b(?:that one|this one|it)\b")


def topic_first(text: str, scene: Scene) -> str | None:
    """The request with the thing it said first, where it said it is, put for the word pointing
    back at it ("move tree_2 3 m north"); None when it does not open so."""
    said = _TOPIC_FIRST.match(text)
    if said is None or commands(said.group("thing").lower()):
        return None  # "put the bench at the union, and the bin beside it": a command, no topic
    named = ph.find_categories(f" {ph.normalise(said.group('thing'))} ")
    place = find_place(scene, f" {ph.normalise(said.group('place'))} ")
    landmark = scene.landmark(place[0]) if place is not None else None
    if len(named) != 1 or landmark is None:
        return None
    there = [a for a in scene.assets if a.category == named[0].category]
    if not there:
        return None
    nearest = min(there, key=lambda a: math.dist((a.pose.x, a.pose.y), landmark.position))
    return _POINTING.sub(nearest.id, said.group("rest"), count=1)


__all__ = ["Condition", "condition", "topic_first"]
