"""The real campus world and the built-in Workers, for the tool behaviour tests."""

from __future__ import annotations

from typing import Any, Protocol

import pytest
from drivetwin.tools import ToolCall, ToolRegistry, ToolResult
from drivetwin.worlds.scene import Scene


class Caller(Protocol):
    def __call__(self, scene: Scene, tool: str, **args: Any) -> ToolResult: ...


@pytest.fixture
def call(registry: ToolRegistry) -> Caller:
    """Runs one Worker call against a scene (which is not changed)."""

    def run(scene: Scene, tool: str, **args: Any) -> ToolResult:
        return registry.run(ToolCall(tool=tool, args=args), scene)

    return run
