"""The append-only journal: every committed transaction, undo, redo, accept and reject.

One JSON object per line, flushed and fsync-ed before the session reports success, so a
kill -9 loses nothing that was reported done. Replaying the journal from its `start` line
rebuilds the scene, the undo/redo stacks and the memory exactly. A torn last line (the
process died mid-write) is ignored.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from drivetwin.orchestrator.memory import Memory, Turn
from drivetwin.worlds.edits import WorldEdit
from drivetwin.worlds.scene import Scene
from pydantic import ValidationError

EventKind = Literal["start", "commit", "undo", "redo", "accept", "reject", "load", "turn"]


class JournalError(ValueError):
    """A journal that cannot be replayed (missing start, damaged line, stale edit)."""


@dataclass
class Entry:
    """A committed transaction: its id, the prompt that made it and its edit."""

    txn: int
    prompt: str
    edit: WorldEdit
    accepted: bool = False


@dataclass
class History:
    """Undo and redo stacks over committed transactions."""

    done: list[Entry] = field(default_factory=list)
    undone: list[Entry] = field(default_factory=list)
    next_txn: int = 1


@dataclass
class Restored:
    """What a journal replay gives back."""

    scene: Scene
    history: History
    memory: Memory


class Journal:
    """Appends events to a JSON Lines file, durably."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)

    def append(self, kind: EventKind, **payload: Any) -> None:
        line = json.dumps({"event": kind, **payload}, separators=(",", ":"))
        with self.path.open("a", encoding="utf-8") as handle:
            handle.write(line + "\n")
            handle.flush()
            os.fsync(handle.fileno())

    def start(self, scene: Scene) -> None:
        """Begin a fresh journal at `scene` (an existing file is replaced)."""
        self.path.write_text("", encoding="utf-8")
        self.append("start", scene=scene.model_dump(mode="json"))

    def commit(self, entry: Entry) -> None:
        self.append("commit", txn=entry.txn, prompt=entry.prompt, edit=entry.edit.model_dump(mode="json"))

    def replay(self) -> Restored:
        """Rebuild the scene, history and memory from the journal."""
        if not self.path.exists():
            raise JournalError(f"no journal at {self.path}")
        events = _read_events(self.path)
        if not events or events[0].get("event") != "start":
            raise JournalError(f"{self.path} does not begin with a start event")
        try:
            scene = Scene.model_validate(events[0]["scene"])
            history = History()
            memory = Memory()
            for number, event in enumerate(events[1:], start=2):
                scene = _apply_event(event, scene, history, memory, number)
        except (ValidationError, KeyError, ValueError) as exc:
            raise JournalError(f"{self.path} cannot be replayed: {exc}") from exc
        return Restored(scene, history, memory)


def _read_events(path: Path) -> list[dict[str, Any]]:
    lines = path.read_text(encoding="utf-8").split("\n")
    events = []
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            events.append(json.loads(line))
        except json.JSONDecodeError as exc:
            if number >= len(lines) - 1:  # a torn final write: the process died mid-line
                break
            raise JournalError(f"{path} line {number} is damaged: {exc.msg}") from exc
    return events


def _apply_event(event: dict[str, Any], scene: Scene, history: History, memory: Memory, number: int) -> Scene:
    kind = event.get("event")
    if kind == "commit":
        edit = WorldEdit.model_validate(event["edit"])
        entry = Entry(int(event["txn"]), str(event["prompt"]), edit)
        history.done.append(entry)
        history.undone.clear()
        history.next_txn = entry.txn + 1
        return edit.apply(scene)
    if kind in ("undo", "reject"):
        entry = history.done.pop()
        if kind == "undo":
            history.undone.append(entry)
        memory.mark_last("undone" if kind == "undo" else "rejected")
        return entry.edit.inverse().apply(scene)
    if kind == "redo":
        entry = history.undone.pop()
        history.done.append(entry)
        memory.mark_last("applied")
        return entry.edit.apply(scene)
    if kind == "accept":
        history.done[-1].accepted = True
        memory.mark_last("accepted")
        return scene
    if kind == "load":
        history.done.clear()
        history.undone.clear()
        return Scene.model_validate(event["scene"])
    if kind == "turn":
        memory.record(Turn.model_validate(event["turn"]))
        return scene
    raise JournalError(f"line {number}: unknown event {kind!r}")
