"""The rule planner: clause reading, slots and typo repair over the world's vocabulary."""

from drivetwin.orchestrator.planning.rules.planner import RulePlanner

__all__ = ["RulePlanner"]
