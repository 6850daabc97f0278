"""The Worker registry: built-in tools plus plugins found through the `drivetwin.tools` entry points.

A plugin's entry point names a Tool subclass (or an instance, or a function returning a list
of them). A plugin that fails to import or to build (it raises, calls sys.exit or hangs) is
reported and skipped, never fatal (the one plugin loader, drivetwin.tools.plugins, for every
entry-point group). Plugin Workers run boxed (drivetwin.tools.plugin_box): a
deadline on every call, a copy of the scene, and the world rules applied by the registry to
whatever they propose; with `isolate` they run in a separate process
(drivetwin.tools.plugin_process), so even os._exit or a segfault is only a refusal.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from dataclasses import replace
from typing import Any, cast

from drivetwin.tools.add import AddAsset
from drivetwin.tools.appearance import SetAssetAppearance, SetLighting, SetTimeOfDay, SetWeather
from drivetwin.tools.arrange import ArrangeAssets
from drivetwin.tools.base import FAMILIES, Family, Tool, ToolCall, ToolResult, overridden_host_methods
from drivetwin.tools.errors import ToolError, UnknownToolError
from drivetwin.tools.move import MoveAsset, SetBehaviour
from drivetwin.tools.plugin_box import CALL_DEADLINE_S, IMPORT_DEADLINE_S, propose_boxed, run_boxed
from drivetwin.tools.plugins import TOOLS_GROUP, PluginProblem, fix_for, load_group
from drivetwin.tools.position import PlaceAsset
from drivetwin.tools.remove import RemoveAssets
from drivetwin.tools.rules import check_edit, settle_on_roads
from drivetwin.tools.scenario import AddEvent, AddManoeuvre, SetLightPhases
from drivetwin.tools.search import (
    AssetProperties,
    DescribeEnvironment,
    FindAssets,
    FindLandmarks,
    FindLanes,
    MeasureDistance,
)
from drivetwin.worlds.catalog import UnknownCategoryError
from drivetwin.worlds.scene import Scene


def builtin_tools() -> list[Tool[Any]]:
    """One instance of every built-in Worker, in family order."""
    return [
        FindAssets(), FindLandmarks(), FindLanes(), AssetProperties(), MeasureDistance(), DescribeEnvironment(),
        AddAsset(),
        RemoveAssets(),
        PlaceAsset(),
        MoveAsset(), SetBehaviour(),
        AddEvent(), AddManoeuvre(), SetLightPhases(),
        ArrangeAssets(),
        SetTimeOfDay(), SetWeather(), SetLighting(), SetAssetAppearance(),
    ]


class ToolRegistry:
    """Tools by name; validates and runs calls, turning every refusal into a ToolError."""

    def __init__(self, tools: Iterable[Tool[Any]] = ()) -> None:
        self._tools: dict[str, Tool[Any]] = {}
        self.problems: list[PluginProblem] = []
        self.sources: dict[str, str] = {}
        for tool in tools:
            self.register(tool)

    @classmethod
    def default(cls, plugins: bool = True, isolate: bool = False) -> ToolRegistry:
        """The built-in tools, plus installed plugins unless `plugins` is False.

        With `isolate`, plugins are imported and run in a separate process.
        """
        registry = cls(builtin_tools())
        for name in registry._tools:
            registry.sources[name] = "built-in"
        if plugins and isolate:
            from drivetwin.tools.plugin_process import load_isolated_plugins

            load_isolated_plugins(registry)
        elif plugins:
            registry.load_plugins()
        return registry

    def register(self, tool: Tool[Any], source: str = "built-in") -> None:
        _validate_tool(tool)
        if tool.name in self._tools:
            raise ValueError(f"a tool named {tool.name!r} is already registered")
        self._tools[tool.name] = tool
        self.sources[tool.name] = source
        overrides = overridden_host_methods(tool)
        if overrides:
            self.problems.append(PluginProblem(
                f"{tool.name} ({source})",
                f"overrides {', '.join(overrides)}, which only the host runs; the override is ignored",
                TOOLS_GROUP, f"remove the {', '.join(overrides)} override from {tool.name}",
            ))

    def load_plugins(self) -> None:
        """Register every tool the `drivetwin.tools` entry points provide; report failures."""
        found = load_group(TOOLS_GROUP, plugin_tools, deadline_s=IMPORT_DEADLINE_S)
        self.problems += found.problems
        for plugin in found.loaded:
            for tool in plugin.value:
                try:
                    self.register(tool, source=f"plugin {plugin.target}")
                except (TypeError, ValueError) as exc:  # not a Worker, or a name already taken
                    self.problems.append(PluginProblem(
                        f"{plugin.name} = {plugin.target}", str(exc), TOOLS_GROUP,
                        fix_for(plugin.name, plugin.target, plugin.distribution),
                    ))

    # Queries ---------------------------------------------------------------------------
    def names(self) -> list[str]:
        return list(self._tools)

    def __contains__(self, name: object) -> bool:
        return name in self._tools

    def get(self, name: str) -> Tool[Any]:
        tool = self._tools.get(name)
        if tool is None:
            near = difflib.get_close_matches(name, self._tools, n=3, cutoff=0.3)
            raise UnknownToolError(
                f"unknown tool {name!r}; nearest: {', '.join(near) or 'none'}. "
                f"Available: {', '.join(self._tools)}"
            )
        return tool

    def family(self, family: Family) -> list[Tool[Any]]:
        return [t for t in self._tools.values() if t.family == family]

    def schemas(self, families: Iterable[Family] = FAMILIES) -> list[dict[str, Any]]:
        """JSON Schemas of the tools of the given families, as an LLM sees them."""
        wanted = set(families)
        return [t.json_schema() for t in self._tools.values() if t.family in wanted]

    # Running ---------------------------------------------------------------------------
    def check(self, call: ToolCall, scene: Scene) -> None:
        """Raise a ToolError if `call` cannot be applied to `scene`."""
        self.run(call, scene)

    def run(self, call: ToolCall, scene: Scene) -> ToolResult:
        """Validate one call, let its Worker propose an edit, and check that against the world rules.

        `scene` is not changed. Plugin Workers are boxed: a copy of the scene, a deadline,
        and every failure a PluginError naming the plugin.
        """
        tool = self.get(call.tool)
        source = self.sources.get(call.tool, "built-in")
        try:
            if source == "built-in" or getattr(tool, "out_of_process", False):
                result = tool.propose(Tool.parse(tool, call.args), scene)
            else:
                who = f"{source} ({call.tool})"
                args = run_boxed(lambda: Tool.parse(tool, call.args), who, CALL_DEADLINE_S)
                result = propose_boxed(tool, args, scene, who, CALL_DEADLINE_S)
            result = replace(result, edit=settle_on_roads(scene, result.edit))
            check_edit(scene, result.edit)  # the world rules, applied by the host to every proposal
            return result
        except ToolError:
            raise
        except UnknownCategoryError as exc:
            raise ToolError(str(exc)) from exc
        except ValueError as exc:
            # A pydantic model built inside a tool refused a value (an out-of-range pose...).
            raise ToolError(f"{call.tool}: {exc}") from exc


def _validate_tool(tool: object) -> None:
    for attr in ("name", "description", "family", "Args"):
        if not hasattr(tool, attr):
            raise TypeError(f"{type(tool).__name__} is not a Worker tool: it has no {attr!r}")
    family = getattr(tool, "family", None)
    if family not in FAMILIES:
        raise TypeError(f"tool {getattr(tool, 'name', '?')!r} has unknown family {family!r}; allowed: {FAMILIES}")


def plugin_tools(loaded: object) -> list[Tool[Any]]:
    """The Workers an entry point's object provides: a Tool class or instance, or a factory of them."""
    made = loaded() if callable(loaded) else loaded
    tools: list[object] = list(made) if isinstance(made, list | tuple) else [made]
    for tool in tools:
        _validate_tool(tool)
    return cast(list[Tool[Any]], tools)
