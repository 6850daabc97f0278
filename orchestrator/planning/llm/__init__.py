"""The LLM manager hierarchy: a Sr. manager writes requirements, Jr. managers write tool calls."""

from drivetwin.orchestrator.planning.llm.planner import LlmPlanner, format_trace

__all__ = ["LlmPlanner", "format_trace"]
