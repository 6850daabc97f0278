"""Planners that misread on purpose, for the plan-check tests: each answers every prompt with
the same fixed calls, as the measured planners did when they misread a request; and the two
outcomes those tests assert, a request held (the scene unchanged) or applied; and the rule planner's
session those tests read requests with (`ruled`)."""

from __future__ import annotations

from drivetwin.orchestrator.planning import Plan, PlanContext
from drivetwin.orchestrator.session import Session, TurnReport
from drivetwin.tools.base import ToolCall


class Fixed:
    """A planner that always answers with the same (misread) calls."""

    name = "fixed"

    def __init__(self, *calls: ToolCall) -> None:
        self.calls = list(calls)

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        return Plan(calls=list(self.calls), planner=self.name)


def call(tool: str, **args: object) -> ToolCall:
    return ToolCall(tool=tool, args=dict(args))


def add(category: str, **extra: object) -> ToolCall:
    return ToolCall(tool="add_asset", args={"category": category, "count": 1, **extra})


def held(campus: object, registry: object, planner: object, prompt: str) -> TurnReport:
    """The report of `prompt` planned by `planner`, which must leave the scene as it was."""
    session = Session(campus, planner, registry)  # type: ignore[arg-type]
    before = session.scene
    report = session.submit(prompt)
    assert not report.ok, f"{prompt!r} was applied: {report.plan.calls if report.plan else None}"
    assert session.scene == before
    return report


def applied(campus: object, registry: object, planner: object, prompt: str) -> Session:
    """The session after `prompt` planned by `planner`, which must have applied it."""
    session = Session(campus, planner, registry)  # type: ignore[arg-type]
    report = session.submit(prompt)
    assert report.ok, report.error or report.question
    return session


def ruled(campus: object, registry: object, *prompts: str) -> Session:
    """A rule-planner session that has applied every one of `prompts`."""
    from drivetwin.orchestrator.planning.rules.planner import RulePlanner

    session = Session(campus, RulePlanner(), registry)  # type: ignore[arg-type]
    for prompt in prompts:
        report = session.submit(prompt)
        assert report.ok, report.error or report.question
    return session
