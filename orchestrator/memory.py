"""Conversation memory: what was asked and done, so later prompts can say "there" or "that car".

Memory is bounded: past `budget_chars` of rendered text, the oldest turns fold into a
one-line-per-turn summary. It is plain data and is saved with the session.
"""

from __future__ import annotations

import ast
from typing import Literal

from drivetwin.tools.base import ToolCall
from pydantic import BaseModel, ConfigDict, Field

TurnStatus = Literal["applied", "failed", "undone", "rejected", "accepted", "answered", "asked"]
DEFAULT_BUDGET_CHARS = 2400


class Turn(BaseModel):
    """One prompt and what came of it."""

    model_config = ConfigDict(extra="forbid")

    prompt: str
    status: TurnStatus
    calls: list[str] = Field(default_factory=list)
    results: list[str] = Field(default_factory=list)
    # Where the edits happened, and what they added (ids), for "around there" / "those cones".
    focus: tuple[float, float] | None = None
    added: list[str] = Field(default_factory=list)
    removed: list[str] = Field(default_factory=list)
    touched: list[str] = Field(default_factory=list)
    # Where the things the turn moved stood before it, for "put the bench back where it was".
    moved_from: dict[str, tuple[float, float]] = Field(default_factory=dict)

    def tool_calls(self) -> list[ToolCall]:
        """The turn's calls read back from their text (`tool(key=value, ...)`, literal parsing
        only); ValueError or SyntaxError for one that does not read back."""
        return [_read_call(text) for text in self.calls]

    def render(self) -> str:
        did = "; ".join(self.results) if self.results else self.status
        return f"user: {self.prompt}\n-> {self.status}: {did}"


def _read_call(text: str) -> ToolCall:
    node = ast.parse(text, mode="eval").body
    if not isinstance(node, ast.Call) or not isinstance(node.func, ast.Name) or node.args:
        raise ValueError(f"not a tool call: {text!r}")
    return ToolCall(tool=node.func.id, args={k.arg: ast.literal_eval(k.value) for k in node.keywords if k.arg})


class Memory(BaseModel):
    """The conversation so far, newest last, with a summary of what was folded away."""

    model_config = ConfigDict(extra="forbid")

    turns: list[Turn] = Field(default_factory=list)
    summary: list[str] = Field(default_factory=list)
    budget_chars: int = DEFAULT_BUDGET_CHARS

    def record(self, turn: Turn) -> None:
        self.turns.append(turn)
        while len(self.turns) > 1 and sum(len(t.render()) for t in self.turns) > self.budget_chars:
            old = self.turns.pop(0)
            self.summary.append(f"{old.prompt[:60]} ({old.status}, added {len(old.added)})")
        self.summary = self.summary[-20:]

    def mark_last(self, status: TurnStatus) -> None:
        """Follow an undo, redo, accept or reject in the turns it concerns."""
        if status == "applied":  # redo: the newest undone turn is back
            wanted: tuple[TurnStatus, ...] = ("undone",)
        else:
            wanted = ("applied", "accepted")
        for turn in reversed(self.turns):
            if turn.status in wanted:
                turn.status = status
                return

    def live_turns(self) -> list[Turn]:
        """Turns whose edits are still in the scene."""
        return [t for t in self.turns if t.status in ("applied", "accepted")]

    def last_focus(self) -> tuple[float, float] | None:
        """Where the most recent edit still in the scene happened."""
        for turn in reversed(self.live_turns()):
            if turn.focus is not None:
                return turn.focus
        return None

    def last_added(self, category: str | None = None) -> list[str]:
        """Ids added by the most recent turn that added something (of `category`, if given)."""
        for turn in reversed(self.live_turns()):
            ids = [i for i in turn.added if category is None or i.rsplit("_", 1)[0] == category]
            if ids:
                return ids
        return []

    def last_asked(self) -> list[ToolCall]:
        """The look-ups of the latest turn when it was a question answered ("which one's the SUV?"),
        for the "it" of the turn after; [] otherwise."""
        last = self.turns[-1] if self.turns else None
        if last is None or last.status != "answered":
            return []
        try:
            return last.tool_calls()
        except (ValueError, SyntaxError):
            return []

    def stood_before(self, asset_id: str) -> tuple[float, float] | None:
        """Where the thing stood before the most recent turn still in the scene that moved it."""
        for turn in reversed(self.live_turns()):
            if asset_id in turn.moved_from:
                return turn.moved_from[asset_id]
        return None

    def last_touched(self) -> list[str]:
        """Ids the most recent turn still in the scene added, moved or changed."""
        for turn in reversed(self.live_turns()):
            if turn.added or turn.touched:
                return list(dict.fromkeys([*turn.added, *turn.touched]))  # a thing added is touched too: once
        return []

    def render(self) -> str:
        """The memory as text for a prompt: summary lines, then the recent turns."""
        parts = []
        if self.summary:
            parts.append("earlier: " + " | ".join(self.summary))
        parts += [t.render() for t in self.turns]
        return "\n".join(parts)
