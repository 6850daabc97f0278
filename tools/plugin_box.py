"""Plugins in a box: every call into plugin code has a deadline, and whatever it raises is a refusal.

A plugin runs in a worker thread: an exception (SystemExit and KeyboardInterrupt included)
becomes a PluginError naming the plugin, and a call that does not return within the
deadline is abandoned as a refusal (Python cannot stop a thread; the daemon thread is left
to finish or hang on its own while the session goes on). A Worker is handed a copy of the
scene, and a proposal made by mutating that copy is refused: the only way to change the
world is the WorldEdit it returns, which the host checks against the world rules itself.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

from drivetwin.tools.base import Tool, ToolResult
from drivetwin.tools.deadline import DeadlineExceeded, call_within
from drivetwin.tools.errors import PluginError, ToolError
from drivetwin.worlds.edits import WorldEdit
from drivetwin.worlds.scene import Scene

T = TypeVar("T")

# A Worker plans one edit of an in-memory scene: far below a second when it works at all.
CALL_DEADLINE_S = 5.0
# Importing a plugin may import heavy libraries (torch, shapely...): more room than a call.
IMPORT_DEADLINE_S = 20.0


class _PluginRaised(Exception):
    """What the plugin raised, kept apart from a Ctrl-C the user presses while it runs."""

    def __init__(self, error: BaseException) -> None:
        super().__init__(error)
        self.error = error


def run_boxed(function: Callable[[], T], who: str, deadline_s: float) -> T:
    """`function()` in a worker thread; its failure or hang becomes a PluginError naming `who`."""

    def guarded() -> T:
        try:
            return function()
        except BaseException as exc:  # SystemExit, KeyboardInterrupt: the plugin's, not ours
            raise _PluginRaised(exc) from exc

    try:
        return call_within(guarded, deadline_s, who)
    except DeadlineExceeded as exc:
        raise PluginError(f"{who} did not answer within {deadline_s:g} s and was abandoned") from exc
    except _PluginRaised as raised:
        if isinstance(raised.error, ToolError):
            raise raised.error from None  # a refusal in the contract's own words
        error = raised.error
        raise PluginError(f"{who} failed: {type(error).__name__}: {error}") from error


def propose_boxed(tool: Tool[Any], args: Any, scene: Scene, who: str, deadline_s: float = CALL_DEADLINE_S) -> ToolResult:
    """A plugin Worker's proposal for `scene`, made on a copy and checked for tampering and shape."""
    handed = scene.model_copy(deep=True)
    result = run_boxed(lambda: tool.propose(args, handed), who, deadline_s)
    if not isinstance(result, ToolResult) or not isinstance(result.edit, WorldEdit):
        raise PluginError(f"{who} returned {type(result).__name__}, not a ToolResult with a WorldEdit")
    if handed != scene:
        raise PluginError(f"{who} changed the scene it was handed; a Worker may only return a WorldEdit")
    return result
