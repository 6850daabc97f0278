"""Planners by name: the built-in ones and those registered under `drivetwin.planners`.

A planner plugin is an entry point naming a factory (a callable taking the keyword options
`backend`, `model`... and returning a Planner); it loads through the one plugin loader
(drivetwin.tools.plugins), so a broken one is a PluginProblem, reported like a broken tool.
A name may also be a `package.module:factory` target, loaded the same way without installing it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from drivetwin.orchestrator.planning.base import Planner
from drivetwin.tools.plugins import PLANNERS_GROUP, PluginProblem, load_group, load_target

PlannerFactory = Callable[..., Planner]


def _rules(**options: Any) -> Planner:
    """Rule-based: the grammar of requests the Workers cover; no model."""
    from drivetwin.orchestrator.planning.rules.planner import RulePlanner

    return RulePlanner()


def _llm(**options: Any) -> Planner:
    """The LLM manager hierarchy (Sr. -> Jr. managers) on the chosen backend and model."""
    from drivetwin.orchestrator.planning.hybrid import make_llm

    return make_llm(**options)


def _retrieval(**options: Any) -> Planner:
    """Adapts the nearest examples of the example bank (MiniLM); no model."""
    from drivetwin.orchestrator.planning.retrieval import RetrievalPlanner

    return RetrievalPlanner()


def _hybrid(**options: Any) -> Planner:
    """Rules, retrieval and the LLM managers by agreement, asking when they disagree."""
    from drivetwin.orchestrator.planning.hybrid import make_hybrid

    return make_hybrid(**options)


BUILTIN: dict[str, PlannerFactory] = {
    "rules": _rules,
    "retrieval": _retrieval,
    "llm": _llm,
    "hybrid": _hybrid,
}
_BUILTIN_TARGETS = {name: f"{__name__}:{factory.__name__}" for name, factory in BUILTIN.items()}


class UnknownPlannerError(LookupError):
    """A planner name that is neither built in nor registered by a working plugin."""


@dataclass(frozen=True)
class PlannerEntry:
    """One planner that can be built: its name, where it comes from and what it does."""

    name: str
    source: str
    description: str
    factory: PlannerFactory


def _factory(loaded: object) -> PlannerFactory:
    if not callable(loaded):
        raise TypeError(f"{loaded!r} is not a planner factory (a callable returning a Planner)")
    return loaded


def discover_planners() -> tuple[list[PlannerEntry], list[PluginProblem]]:
    """Every planner that loads, built-ins first, and the planner plugins that do not."""
    found = load_group(PLANNERS_GROUP, _factory, builtins=_BUILTIN_TARGETS)
    entries = [
        PlannerEntry(
            plugin.name,
            "built-in" if plugin.name in BUILTIN else f"plugin {plugin.target}",
            _first_line(plugin.value.__doc__),
            plugin.value,
        )
        for plugin in found.loaded
    ]
    return entries, found.problems


def planner_factories() -> dict[str, PlannerFactory]:
    """Every planner factory by name; plugins may add names but not replace built-ins."""
    return {entry.name: entry.factory for entry in discover_planners()[0]}


def make_planner(name: str, **options: Any) -> Planner:
    """The planner called `name` (or a `package.module:factory`), built with `options`."""
    if ":" in name:
        loaded = load_target(PLANNERS_GROUP, name, _factory)
        if isinstance(loaded, PluginProblem):
            raise UnknownPlannerError(f"planner {name!r} cannot be loaded: {loaded.error}; fix: {loaded.fix}")
        return _built(name, loaded.value, options)
    entries, problems = discover_planners()
    factories = {entry.name: entry.factory for entry in entries}
    if name not in factories:
        broken = next((p for p in problems if p.name == name), None)
        if broken is not None:
            raise UnknownPlannerError(
                f"planner plugin {name!r} is installed but broken ({broken.error}); fix: {broken.fix}")
        raise UnknownPlannerError(f"unknown planner {name!r}; available: {', '.join(factories)}")
    return _built(name, factories[name], options)


def _built(name: str, factory: PlannerFactory, options: dict[str, Any]) -> Planner:
    planner = factory(**options)
    if not isinstance(planner, Planner):
        raise UnknownPlannerError(
            f"planner {name!r} built a {type(planner).__name__}, which has no name and plan(prompt, context)")
    return planner


def _first_line(doc: str | None) -> str:
    return (doc or "").strip().splitlines()[0] if (doc or "").strip() else ""
