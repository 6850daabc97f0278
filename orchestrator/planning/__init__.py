"""Planning: turning a request into Worker tool calls.

The interface (`Planner`, `Plan`, `PlanContext`, `PlanningError`) lives in `base`; the planners
live in their own packages (`rules`, `llm`, `retrieval`) and `hybrid` combines them. Planners are
found by name through `make_planner` (built-ins and the `drivetwin.planners` entry points).
"""

from drivetwin.orchestrator.planning.base import (
    MAX_PROMPT_CHARS,
    Plan,
    PlanContext,
    Planner,
    PlanningError,
    Question,
    Reading,
    TraceStep,
)
from drivetwin.orchestrator.planning.registry import UnknownPlannerError, make_planner, planner_factories

__all__ = [
    "MAX_PROMPT_CHARS",
    "Plan",
    "PlanContext",
    "Planner",
    "PlanningError",
    "Question",
    "Reading",
    "TraceStep",
    "UnknownPlannerError",
    "make_planner",
    "planner_factories",
]
