"""`--isolate-plugins`: plugin Workers run in a separate process, so even os._exit or a segfault
in a plugin is only a refusal of the call in flight (the process is started again for the next).

The host process (drivetwin.tools.plugin_host) imports the plugins; this side registers a
stand-in Worker for each, whose `propose` sends the call and the scene across and reads the
proposed edit back within a deadline. The registry then applies the world rules to it as it
does for every Worker.
"""

from __future__ import annotations

import json
import select
import subprocess
import sys
import time
from typing import TYPE_CHECKING, Any, ClassVar

from drivetwin.tools.base import Family, Tool, ToolArgs, ToolResult
from drivetwin.tools.errors import PluginError, ToolError
from drivetwin.tools.plugin_box import CALL_DEADLINE_S, IMPORT_DEADLINE_S
from drivetwin.worlds.edits import WorldEdit
from drivetwin.worlds.scene import Scene
from pydantic import ConfigDict

if TYPE_CHECKING:  # the registry imports this module lazily
    from drivetwin.tools.registry import ToolRegistry

HOST_MODULE = "drivetwin.tools.plugin_host"
# Starting the host imports drivetwin and every plugin: allow for the slowest imports.
START_DEADLINE_S = IMPORT_DEADLINE_S + 10.0


class RemoteArgs(ToolArgs):
    """Arguments passed through as given; the host process validates them against the plugin's model."""

    model_config = ConfigDict(extra="allow")


class PluginProcess:
    """The host process, started on demand and again after a plugin killed it."""

    def __init__(self) -> None:
        self._proc: subprocess.Popen[str] | None = None
        self.catalogue: dict[str, Any] = {}

    def start(self) -> dict[str, Any]:
        self._proc = subprocess.Popen(
            [sys.executable, "-m", HOST_MODULE], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL, text=True, bufsize=1,
        )
        self.catalogue = self._read("the plugin process", START_DEADLINE_S)
        return self.catalogue

    def propose(self, tool: str, args: dict[str, Any], scene: Scene, who: str) -> dict[str, Any]:
        if self._proc is None or self._proc.poll() is not None:
            self.start()
        assert self._proc is not None and self._proc.stdin is not None
        request = {"tool": tool, "args": args, "scene": scene.model_dump(mode="json")}
        try:
            self._proc.stdin.write(json.dumps(request) + "\n")
            self._proc.stdin.flush()
        except OSError as exc:
            self._stop()
            raise PluginError(f"{who}: the plugin process is gone ({exc}); it will be started again") from exc
        return self._read(who, CALL_DEADLINE_S)

    def _read(self, who: str, deadline_s: float) -> dict[str, Any]:
        assert self._proc is not None and self._proc.stdout is not None
        ready, _, _ = select.select([self._proc.stdout], [], [], deadline_s)
        line = self._proc.stdout.readline() if ready else None
        if line is None:
            self._stop()
            raise PluginError(f"{who} did not answer within {deadline_s:g} s; its process was stopped")
        if not line:
            code = self._stop()
            how = f"signal {-code}" if code is not None and code < 0 else f"exit code {code}"
            raise PluginError(f"{who} ended its process ({how}); the call was refused and the process "
                              "will be started again")
        answer: dict[str, Any] = json.loads(line)
        return answer

    def _stop(self) -> int | None:
        if self._proc is None:
            return None
        proc, self._proc = self._proc, None
        if proc.poll() is None:
            proc.kill()
        deadline = time.monotonic() + 5.0
        while proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.01)
        return proc.returncode

    def close(self) -> None:
        self._stop()


class IsolatedTool(Tool[RemoteArgs]):
    """A stand-in for a plugin Worker that runs in the plugin process."""

    Args = RemoteArgs
    # The process is the box: its own deadline, and the scene crosses as JSON, so it cannot be mutated.
    out_of_process: ClassVar[bool] = True
    name: ClassVar[str]  # set per instance below; mypy sees the class contract
    description: ClassVar[str]
    family: ClassVar[Family]

    def __init__(self, process: PluginProcess, schema: dict[str, Any]) -> None:
        self._process = process
        self._schema = schema
        self.__dict__.update(name=schema["name"], description=schema["description"], family=schema["family"])
        self._who = f"{schema['source']} ({schema['name']})"

    def json_schema(self, scene: Scene | None = None) -> dict[str, Any]:
        return {k: v for k, v in self._schema.items() if k != "source"}

    def propose(self, args: RemoteArgs, scene: Scene) -> ToolResult:
        answer = self._process.propose(self.name, args.model_dump(), scene, self._who)
        if "error" in answer:
            raise ToolError(answer["error"])
        try:
            edit = WorldEdit.model_validate(answer["edit"])
        except ValueError as exc:
            raise PluginError(f"{self._who} proposed an edit that is not a valid WorldEdit: {exc}") from exc
        focus = tuple(answer["focus"]) if answer.get("focus") else None
        return ToolResult(edit, str(answer.get("text", "")), focus, dict(answer.get("data") or {}))


def load_isolated_plugins(registry: ToolRegistry) -> PluginProcess:
    """Start the plugin process and register a stand-in for each Worker it loaded."""
    from drivetwin.tools.plugins import PluginProblem

    process = PluginProcess()
    try:
        catalogue = process.start()
    except PluginError as exc:
        registry.problems.append(PluginProblem("the plugin process", str(exc)))
        return process
    for entry_point, error in catalogue.get("problems", []):
        registry.problems.append(PluginProblem(entry_point, error))
    for schema in catalogue.get("tools", []):
        try:
            registry.register(IsolatedTool(process, schema), source=f"isolated {schema['source']}")
        except (TypeError, ValueError) as exc:
            registry.problems.append(PluginProblem(schema.get("source", "?"), str(exc)))
    return process
