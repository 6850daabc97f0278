"""The process that runs plugin Workers for `--isolate-plugins` (python -m drivetwin.tools.plugin_host).

It speaks JSON Lines on its stdin and stdout: first it reports the Workers it loaded (and
the plugins it skipped), then it answers each request {"tool", "args", "scene"} with the
proposed edit or a refusal. Plugins' own printing goes to stderr, so it cannot corrupt the
protocol. If a plugin kills this process (os._exit, a segfault), the session only loses
the call in flight: drivetwin.tools.plugin_process turns that into a refusal.
"""

from __future__ import annotations

import json
import os
import sys
from typing import Any

from drivetwin.tools.base import Tool
from drivetwin.tools.errors import ToolError
from drivetwin.tools.plugin_box import CALL_DEADLINE_S, propose_boxed, run_boxed
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.scene import Scene


def main() -> None:
    channel = os.fdopen(os.dup(sys.stdout.fileno()), "w", encoding="utf-8")
    os.dup2(sys.stderr.fileno(), sys.stdout.fileno())  # whatever plugins print goes to stderr
    registry = ToolRegistry()
    registry.load_plugins()
    tools = {name: registry.get(name) for name in registry.names()}
    _send(channel, {
        "tools": [{**tool.json_schema(), "source": registry.sources[name]} for name, tool in tools.items()],
        "problems": [[p.entry_point, p.error] for p in registry.problems],
    })
    for line in sys.stdin:
        request = json.loads(line)
        _send(channel, _answer(tools, registry.sources, request))


def _answer(tools: dict[str, Tool[Any]], sources: dict[str, str], request: dict[str, Any]) -> dict[str, Any]:
    tool = tools[request["tool"]]
    who = f"{sources[tool.name]} ({tool.name})"
    try:
        scene = Scene.model_validate(request["scene"])
        args = run_boxed(lambda: Tool.parse(tool, request["args"]), who, CALL_DEADLINE_S)
        result = propose_boxed(tool, args, scene, who, CALL_DEADLINE_S)
    except ToolError as exc:
        return {"error": str(exc), "kind": exc.kind}
    except ValueError as exc:
        return {"error": f"{who}: {exc}", "kind": "error"}
    return {
        "edit": result.edit.model_dump(mode="json"),
        "text": result.text,
        "focus": list(result.focus) if result.focus else None,
        "data": result.data,
    }


def _send(channel: Any, message: dict[str, Any]) -> None:
    channel.write(json.dumps(message, default=str) + "\n")
    channel.flush()


if __name__ == "__main__":
    main()
