"""The plan-vs-request review as a hint: why a finished plan would not be applied as it is.

The session reviews every plan before applying it (planning/check.py) and asks or refuses
when the plan misses what the words say. The managers ask the same review first, so that a
plan it would not apply goes back to the model once, inside the ask-validate-retry loop,
with the review's own words as the message ("you said east, but the plan moves it north").
"""

from __future__ import annotations

from drivetwin.orchestrator.planning.base import Plan, PlanContext
from drivetwin.orchestrator.planning.check import review
from drivetwin.tools.base import ToolCall

# Review reasons passed back to the model: a 135M model acts on the first one or two at most.
MAX_HINTS = 2


def review_problems(prompt: str, calls: list[ToolCall], context: PlanContext) -> list[str]:
    """The review's reasons for not applying `calls` for `prompt` as they are; [] when it would."""
    verdict = review(prompt, Plan(calls=calls, planner="llm"), context)
    if verdict.action == "apply":
        return []
    return verdict.problems[:MAX_HINTS] or ["the review would not apply it"]


__all__ = ["MAX_HINTS", "review_problems"]
