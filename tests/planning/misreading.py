"""Planners that misread on purpose, for the plan-check tests: each answers every prompt with
the same fixed calls, as the measured planners did when they misread a request."""

from __future__ import annotations

from drivetwin.orchestrator.planning import Plan, PlanContext
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
