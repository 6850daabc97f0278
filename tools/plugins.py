"""The one plugin loader: every entry-point group drivetwin reads goes through `load_group`.

A plugin is an entry point in one of the groups below, declared by any installed package:

    [project.entry-points."drivetwin.tools"]
    close_lane = "my_package:CloseLane"

Loading an entry point imports its module and hands the object to the group's `accept`
(which checks it is what the group expects, or builds it), all inside the plugin box
(drivetwin.tools.plugin_box): a deadline, and anything raised (SystemExit included) caught.
A plugin that fails is skipped and reported as one `PluginProblem`, the same for every
group: which group, which entry point, what went wrong and the command that fixes it.

It lives with the tools because the Worker registry is its first user and the box it
needs is here; the backend, planner, world and command registries above call it too.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import partial
from importlib.metadata import EntryPoint, entry_points
from typing import Generic, TypeVar

from drivetwin.tools.errors import PluginError
from drivetwin.tools.plugin_box import IMPORT_DEADLINE_S, run_boxed

T = TypeVar("T")

TOOLS_GROUP = "drivetwin.tools"
BACKENDS_GROUP = "drivetwin.backends"
PLANNERS_GROUP = "drivetwin.planners"
WORLDS_GROUP = "drivetwin.worlds"
COMMANDS_GROUP = "drivetwin.commands"
# Every group drivetwin reads; each is declared (possibly empty) in pyproject.toml.
GROUPS = (TOOLS_GROUP, BACKENDS_GROUP, PLANNERS_GROUP, WORLDS_GROUP, COMMANDS_GROUP)


@dataclass(frozen=True)
class PluginProblem:
    """A plugin that could not be loaded (or is used only in part), why, and what fixes it.

    `entry_point` reads like the line that declares it: `name = module:attribute`.
    """

    entry_point: str
    error: str
    group: str = TOOLS_GROUP
    fix: str = ""

    @property
    def name(self) -> str:
        """The entry point's name (a backend's, a planner's, a command's...)."""
        return self.entry_point.split(" = ", 1)[0]

    def __str__(self) -> str:
        fix = f"; fix: {self.fix}" if self.fix else ""
        return f"{self.group} plugin {self.entry_point}: {self.error}{fix}"


@dataclass(frozen=True)
class LoadedPlugin(Generic[T]):
    """One entry point that loaded: its name, what it provides and where it came from."""

    name: str
    value: T
    target: str
    distribution: str | None = None


@dataclass
class PluginGroup(Generic[T]):
    """What one entry-point group gave: the plugins that loaded, and the problems of the rest."""

    group: str
    loaded: list[LoadedPlugin[T]] = field(default_factory=list)
    problems: list[PluginProblem] = field(default_factory=list)

    def by_name(self) -> dict[str, LoadedPlugin[T]]:
        return {plugin.name: plugin for plugin in self.loaded}


def _identity(loaded: object) -> object:
    return loaded


def load_group(
    group: str,
    accept: Callable[[object], T] = _identity,  # type: ignore[assignment]
    *,
    builtins: Mapping[str, str] | None = None,
    deadline_s: float = IMPORT_DEADLINE_S,
) -> PluginGroup[T]:
    """Load every entry point of `group` (after `builtins`, name -> 'module:attribute').

    `accept` turns the loaded object into what the group holds, raising TypeError (or
    anything) for an object that is not one. An installed entry point of a built-in's name
    replaces nothing: the built-in wins and the plugin is reported.
    """
    if group not in GROUPS:
        raise ValueError(f"unknown plugin group {group!r}; groups: {', '.join(GROUPS)}")
    result: PluginGroup[T] = PluginGroup(group)
    candidates: list[tuple[str, str, str | None, Callable[[], object]]] = [
        (name, target, None, partial(_import_target, target)) for name, target in (builtins or {}).items()
    ]
    for ep in entry_points(group=group):
        if builtins and ep.name in builtins:
            if ep.value != builtins[ep.name]:  # the project's own declaration of a built-in is no clash
                result.problems.append(PluginProblem(
                    f"{ep.name} = {ep.value}", f"a built-in is called {ep.name!r}; the plugin is ignored",
                    group, f"rename the entry point {ep.name!r} in {_distribution(ep) or 'its package'}",
                ))
            continue
        candidates.append((ep.name, ep.value, _distribution(ep), ep.load))
    for name, target, distribution, load in candidates:
        loaded = _load_boxed(group, name, target, distribution, load, accept, deadline_s)
        if isinstance(loaded, PluginProblem):
            result.problems.append(loaded)
        else:
            result.loaded.append(loaded)
    return result


def load_target(
    group: str,
    target: str,
    accept: Callable[[object], T] = _identity,  # type: ignore[assignment]
    *,
    deadline_s: float = IMPORT_DEADLINE_S,
) -> LoadedPlugin[T] | PluginProblem:
    """Load one `module:attribute` target as a plugin of `group` would be (the same box and checks).

    For places that name a plugin directly instead of installing it (`--planner pkg.mod:factory`).
    """
    if ":" not in target:
        return PluginProblem(target, "not a 'module:attribute' target", group, "write it as package.module:name")
    return _load_boxed(group, target, target, None, partial(_import_target, target), accept, deadline_s)


def _load_boxed(
    group: str, name: str, target: str, distribution: str | None,
    load: Callable[[], object], accept: Callable[[object], T], deadline_s: float,
) -> LoadedPlugin[T] | PluginProblem:
    where = f"{name} = {target}"
    who = f"{group} plugin {where}"
    try:
        value = run_boxed(partial(_accepted, accept, load), who, deadline_s)
    except PluginError as exc:  # a broken plugin must never take the command down
        error = str(exc).removeprefix(f"{who} ").removeprefix("failed: ")
        return PluginProblem(where, error, group, fix_for(name, target, distribution))
    except Exception as exc:  # a ToolError raised by a plugin's factory, re-raised by the box
        return PluginProblem(where, f"{type(exc).__name__}: {exc}", group, fix_for(name, target, distribution))
    return LoadedPlugin(name, value, target, distribution)


def fix_for(name: str, target: str, distribution: str | None) -> str:
    """The one command that repairs a broken entry point."""
    if distribution:
        return f"pip install --force-reinstall {distribution}  (or pip uninstall {distribution})"
    return f"fix or remove the entry point {name} = {target}"


def _accepted(accept: Callable[[object], T], load: Callable[[], object]) -> T:
    return accept(load())


def _import_target(target: str) -> object:
    return EntryPoint(name="", value=target, group="").load()


def _distribution(ep: EntryPoint) -> str | None:
    dist = getattr(ep, "dist", None)
    return str(dist.name) if dist is not None else None
