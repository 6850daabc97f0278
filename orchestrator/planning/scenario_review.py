"""How the plan-versus-request review treats a request that describes behaviour over time.

Two rules, both the scenario reader's to apply because it is the one that reads such words:
a static edit never stands for a scenario (the review asks with the scenario reading, or
refuses saying what is possible), and a storyboard plan that is exactly what the scenario
reader reads from the request stands as it is. The static checks (a colour named, a
category named) misread scenario words ("turns red", "cycles", "stops"), so they are not
the judge of a storyboard plan the reader agrees with; a storyboard plan it does not agree
with is left to them.
"""

from __future__ import annotations

from dataclasses import dataclass

from drivetwin.orchestrator.planning.base import Plan, PlanContext, PlanningError, Question, Reading
from drivetwin.orchestrator.planning.readings import canonical, describe, dry_run, same_outcome
from drivetwin.orchestrator.planning.scenario_reading import (
    SCENARIO_TOOLS,
    ScenarioReader,
    describes_behaviour_over_time,
)


@dataclass(frozen=True)
class MissedScenario:
    """A plan that answers a scenario request with a static edit: the problem, and either a
    question offering the scenario reading or a refusal saying what is possible."""

    problem: str
    question: Question | None
    message: str | None


def missed_scenario(prompt: str, plan: Plan, context: PlanContext) -> MissedScenario | None:
    """None when the plan may stand; else what to ask or say instead of a static edit, or
    instead of a storyboard edit other than the one the request describes."""
    if plan.calls and all(c.tool in SCENARIO_TOOLS for c in plan.calls):
        return _other_story(prompt, plan, context)
    if not plan.calls or any(c.tool in SCENARIO_TOOLS for c in plan.calls) or not describes_behaviour_over_time(
        prompt, context.scene
    ):
        return None
    problem = "you described something that happens over time, but the plan is a static edit"
    try:
        reading = ScenarioReader().plan(prompt, context)
    except PlanningError as exc:
        return MissedScenario(problem, None, f"I did not do it: {problem}, and {exc}")
    if reading.question is not None:
        return MissedScenario(problem, reading.question, None)
    text = f"I am not sure what you meant: {problem}. Did you mean this?"
    return MissedScenario(problem, Question(text=text, readings=[Reading(text=describe(reading.calls),
                                                                         calls=reading.calls)]), None)


def _other_story(prompt: str, plan: Plan, context: PlanContext) -> MissedScenario | None:
    """A question offering the scenario reader's reading beside the plan's own, when the reader
    reads the request as a different story ("goes red" planned as a green light); None when it
    reads the same story, or none."""
    try:
        reading = ScenarioReader().plan(prompt, context)
    except PlanningError:
        return None
    if not reading.calls or canonical(reading.calls, context.registry) == canonical(plan.calls, context.registry):
        return None
    ours, theirs = dry_run(reading.calls, context.registry, context.scene), dry_run(plan.calls, context.registry, context.scene)
    if not isinstance(ours, str) and not isinstance(theirs, str) and same_outcome(ours, theirs):
        return None
    problem = "the plan's storyboard is not the one the request describes"
    return MissedScenario(problem, Question(text=f"I am not sure what you meant: {problem}. Which did you mean?", readings=[
        Reading(text=describe(reading.calls), calls=reading.calls),
        Reading(text="as planned: " + describe(plan.calls), calls=list(plan.calls))]), None)


def read_as_scenario(prompt: str, plan: Plan, context: PlanContext) -> bool:
    """Whether `plan` writes the storyboard (bringing in its newcomer, if any) and is what the
    scenario reader reads from `prompt` (the same calls up to defaults): such a plan needs no
    static check."""
    if not any(c.tool in SCENARIO_TOOLS for c in plan.calls) or any(
            c.tool not in (*SCENARIO_TOOLS, "add_asset") for c in plan.calls):
        return False
    try:
        reading = ScenarioReader().plan(prompt, context)
    except PlanningError:
        return False
    return bool(reading.calls) and canonical(reading.calls, context.registry) == canonical(plan.calls, context.registry)


__all__ = ["MissedScenario", "missed_scenario", "read_as_scenario"]
