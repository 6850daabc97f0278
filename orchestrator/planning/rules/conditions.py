"""A request on a condition about the scene: "if there's a bus, paint it yellow".

Read the same way by the rule planner (which plans the request when the condition holds, and
otherwise looks the thing up, changing nothing) and by the plan-versus-request check (which
holds a plan to the request when it holds, and otherwise to a question).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from drivetwin.orchestrator.planning.rules import phrases as ph
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


__all__ = ["Condition", "condition"]
