"""A planner that plans exactly the calls it is given (the planner is not under test here)."""

from __future__ import annotations

from drivetwin.orchestrator.planning.base import Plan
from drivetwin.tools.base import ToolCall


class ScriptedPlanner:
    name = "scripted"

    def __init__(self, *calls: ToolCall) -> None:
        self.calls = list(calls)

    def plan(self, prompt, context):
        return Plan(calls=self.calls, planner=self.name)


def call(tool: str, **args) -> ToolCall:
    return ToolCall(tool=tool, args=args)
