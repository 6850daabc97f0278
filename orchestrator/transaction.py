"""Transactions: a prompt's tool calls apply all together or not at all."""

from __future__ import annotations

from dataclasses import dataclass

from drivetwin.tools.base import ToolCall, ToolResult
from drivetwin.tools.errors import ToolError
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.edits import WorldEdit
from drivetwin.worlds.scene import Scene


class TransactionError(Exception):
    """A call of a transaction was refused; nothing of the transaction was applied."""

    def __init__(self, index: int, call: ToolCall, error: ToolError) -> None:
        self.index = index
        self.call = call
        self.error = error
        super().__init__(f"step {index + 1} ({call.tool}) was refused: {error}")


@dataclass(frozen=True)
class TransactionResult:
    """The scene after a transaction, the combined edit and each call's result."""

    before: Scene
    after: Scene
    edit: WorldEdit
    results: list[ToolResult]


def execute(registry: ToolRegistry, scene: Scene, calls: list[ToolCall]) -> TransactionResult:
    """Run `calls` in order, each seeing the edits before it; `scene` itself is never changed."""
    current = scene
    edit = WorldEdit()
    results: list[ToolResult] = []
    for index, call in enumerate(calls):
        try:
            result = registry.run(call, current)
            current = result.edit.apply(current)
        except ToolError as exc:
            raise TransactionError(index, call, exc) from exc
        except ValueError as exc:  # an edit conflicting with the scene: a bug, kept typed
            raise TransactionError(index, call, ToolError(str(exc))) from exc
        edit = edit + result.edit
        results.append(result)
    return TransactionResult(scene, current, edit, results)


def first_refusal(registry: ToolRegistry, scene: Scene, calls: list[ToolCall]) -> str | None:
    """The message of the first refused call, or None if all would apply (a dry run)."""
    try:
        execute(registry, scene, calls)
    except TransactionError as exc:
        return str(exc)
    return None
