"""Throwaway plugins for the tests: a module and a dist-info with entry_points.txt on sys.path."""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

PLUGIN_TEMPLATE = '''
import os, sys, time
from drivetwin.tools import add  # its Worker AddAsset shares a name with the WorldEdit op a body may import
from drivetwin.tools.base import Tool, ToolArgs, ToolResult
from drivetwin.worlds.scene import Pose
{module_level}

class Args(ToolArgs):
    pass


class Plug(Tool[Args]):
    name = "{tool}"
    description = "a throwaway test plugin"
    family = "add"
    Args = Args

    def propose(self, args, scene):
        result = add.AddAsset().propose(add.AddArgs(category="traffic_cone"), scene)
{body}
        return result
{extra}
'''


def install_plugin(folder: Path, module: str, body: str = "", module_level: str = "", extra: str = "",
                   tool: str | None = None) -> str:
    """Write plugin `module` (its Worker named `tool`) under `folder`; the caller puts `folder` on sys.path."""
    name = tool or f"{module}_tool"
    source = PLUGIN_TEMPLATE.format(
        tool=name, module_level=textwrap.dedent(module_level),
        body=textwrap.indent(textwrap.dedent(body), " " * 8), extra=textwrap.dedent(extra),
    )
    (folder / f"{module}.py").write_text(source, encoding="utf-8")
    dist = folder / f"{module}-0.1.dist-info"
    dist.mkdir()
    (dist / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {module}\nVersion: 0.1\n", encoding="utf-8")
    (dist / "entry_points.txt").write_text(f"[drivetwin.tools]\n{module} = {module}:Plug\n", encoding="utf-8")
    sys.modules.pop(module, None)
    return name
