"""Planners by name: the built-in ones and those registered under `drivetwin.planners`."""

from __future__ import annotations

from collections.abc import Callable
from importlib.metadata import entry_points
from typing import Any

from drivetwin.orchestrator.planning.base import Planner

ENTRY_POINT_GROUP = "drivetwin.planners"


def _rules(**options: Any) -> Planner:
    from drivetwin.orchestrator.planning.rules.planner import RulePlanner

    return RulePlanner()


def _llm(**options: Any) -> Planner:
    from drivetwin.orchestrator.planning.hybrid import make_llm

    return make_llm(**options)


def _retrieval(**options: Any) -> Planner:
    from drivetwin.orchestrator.planning.retrieval import RetrievalPlanner

    return RetrievalPlanner()


def _hybrid(**options: Any) -> Planner:
    from drivetwin.orchestrator.planning.hybrid import make_hybrid

    return make_hybrid(**options)


BUILTIN: dict[str, Callable[..., Planner]] = {
    "rules": _rules,
    "retrieval": _retrieval,
    "llm": _llm,
    "hybrid": _hybrid,
}


class UnknownPlannerError(LookupError):
    """A planner name that is neither built in nor registered by a plugin."""


def planner_factories() -> dict[str, Callable[..., Planner]]:
    """Every planner factory by name; plugins may add names but not replace built-ins."""
    found = dict(BUILTIN)
    for ep in entry_points(group=ENTRY_POINT_GROUP):
        if ep.name in found:
            continue
        try:
            found[ep.name] = ep.load()
        except Exception:  # a broken plugin must not hide the working planners
            continue
    return found


def make_planner(name: str, **options: Any) -> Planner:
    """The planner called `name`, built with `options` (backend, model...)."""
    factories = planner_factories()
    if name not in factories:
        raise UnknownPlannerError(f"unknown planner {name!r}; available: {', '.join(factories)}")
    return factories[name](**options)
