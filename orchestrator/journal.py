"""The append-only journal: every committed transaction, undo, redo, accept and reject.

One JSON object per line, written and fsync-ed before the session reports success, so a
kill -9 loses nothing that was reported done. Replaying the journal from its `start` line
rebuilds the scene, the undo/redo stacks and the memory exactly.

What ordinary events cannot break:
- a torn last line (the process died mid-write, the disk filled) is ignored on replay and
  cut off before the next append, so nothing is ever glued onto a fragment;
- a failed write (ENOSPC) is undone to the last whole line and raised as JournalWriteError,
  so the edit is refused and the scene stays as it was;
- one writer per journal: an OS lock (flock) held while the session lives;
- replay follows transaction ids: an undo, redo, accept or reject names the change it
  concerns, and a line that does not fit (a duplicate, a stale id) is a JournalError naming
  the line, as is every line that is not a well-formed event.
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from drivetwin.orchestrator.journal_events import (
    CommitEvent,
    EndEvent,
    Event,
    JournalError,
    LoadEvent,
    PlanFacts,
    StartEvent,
    TurnEvent,
    TxnEvent,
    parse_event,
)
from drivetwin.orchestrator.memory import Memory
from drivetwin.worlds.edits import EditConflict, WorldEdit
from drivetwin.worlds.json_input import JsonInputError, decode_utf8
from drivetwin.worlds.scene import Scene

__all__ = [
    "Entry", "History", "Journal", "JournalError", "JournalLockedError", "JournalWriteError", "Restored",
    "read_lines", "replay_lines",
]

EventKind = Literal["start", "commit", "undo", "redo", "accept", "reject", "load", "turn", "end"]


class JournalLockedError(JournalError):
    """Another session is writing this journal."""


class JournalWriteError(JournalError):
    """An event could not be written (disk full...); the journal is as it was before it."""


@dataclass
class Entry:
    """A committed transaction: its id, the prompt that made it and its edit."""

    txn: int
    prompt: str
    edit: WorldEdit
    accepted: bool = False
    # Which planner and model made it (None for journals written before they were recorded).
    facts: PlanFacts | None = None


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
    # Whether the last event is `end`: the session that wrote it closed normally.
    ended_cleanly: bool = False


class Journal:
    """Appends events to a JSON Lines file, durably, as the file's only writer."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        self._fd: int | None = None
        # Where an existing journal at `path` was moved by `start` (never truncated).
        self.set_aside: Path | None = None

    # Writing -----------------------------------------------------------------------------
    def open(self) -> None:
        """Take the writer's lock and cut a torn tail off; JournalLockedError if another holds it."""
        if self._fd is not None:
            return
        self.path.parent.mkdir(parents=True, exist_ok=True)
        fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o644)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError as exc:
            os.close(fd)
            raise JournalLockedError(
                f"journal {self.path} is in use by another drivetwin session; close it first, "
                "or start this one with another --journal"
            ) from exc
        self._fd = fd
        _cut_torn_tail(fd)

    def close(self) -> None:
        """Release the lock (events already written stay)."""
        if self._fd is not None:
            os.close(self._fd)  # closing the descriptor releases its flock
            self._fd = None

    @property
    def is_open(self) -> bool:
        return self._fd is not None

    def append(self, kind: EventKind, **payload: Any) -> None:
        """Write one event durably; on failure the file is left at its last whole line."""
        self.open()
        assert self._fd is not None
        data = (json.dumps({"event": kind, **payload}, separators=(",", ":"), allow_nan=False) + "\n").encode()
        size = os.lseek(self._fd, 0, os.SEEK_END)
        try:
            written = 0
            while written < len(data):
                written += os.write(self._fd, data[written:])
            os.fsync(self._fd)
        except OSError as exc:
            _truncate_quietly(self._fd, size)
            reason = "the disk is full" if exc.errno == errno.ENOSPC else (exc.strerror or str(exc))
            raise JournalWriteError(f"cannot write to journal {self.path}: {reason}; nothing was changed") from exc

    def start(self, scene: Scene) -> None:
        """Begin a fresh journal at `scene`; an existing one is moved aside, never truncated."""
        if self.path.exists() and self.path.stat().st_size > 0:
            self.open()  # refuses if another session writes it
            self.set_aside = _free_name(self.path)
            self.path.rename(self.set_aside)
            self.close()
        self.open()
        self.append("start", scene=scene.model_dump(mode="json"))

    def commit(self, entry: Entry) -> None:
        facts = {} if entry.facts is None else {"facts": entry.facts.model_dump(mode="json")}
        self.append("commit", txn=entry.txn, prompt=entry.prompt, edit=entry.edit.model_dump(mode="json"), **facts)

    def end(self) -> None:
        """Mark a clean end of the session and release the lock."""
        if self._fd is not None:
            try:
                self.append("end")
            finally:
                self.close()

    # Reading -----------------------------------------------------------------------------
    def replay(self) -> Restored:
        """Rebuild the scene, history and memory from the journal (reading needs no lock)."""
        if not self.path.exists():
            raise JournalError(f"no journal at {self.path}")
        lines = read_lines(self.path)
        return replay_lines(lines, str(self.path))


def read_lines(path: Path) -> list[tuple[int, str]]:
    """The whole lines of a journal with their numbers; a torn final fragment is left out."""
    data = path.read_bytes()
    lines = []
    for number, raw in enumerate(data.split(b"\n")[:-1], start=1):
        try:
            line = decode_utf8(raw, f"journal {path} line {number}")
        except JsonInputError as exc:
            raise JournalError(str(exc)) from exc
        if line.strip():
            lines.append((number, line))
    return lines


def replay_lines(lines: list[tuple[int, str]], source: str) -> Restored:
    """Replay numbered event lines; the first line that does not fit is a JournalError naming it."""
    salvage = salvage_lines(lines, source)
    if salvage.error is not None:
        raise salvage.error
    assert salvage.restored is not None
    return salvage.restored


@dataclass
class Salvage:
    """How far a journal replays: the state after its longest valid prefix, and what stopped it."""

    restored: Restored | None
    kept: int  # how many of the lines replayed
    error: JournalError | None


def salvage_lines(lines: list[tuple[int, str]], source: str) -> Salvage:
    """Replay lines until the first that does not fit; never raises for a bad line."""
    if not lines:
        return Salvage(None, 0, JournalError(f"{source} is empty: it does not begin with a start event"))
    state: ReplayState | None = None
    last: Event | None = None
    kept = 0
    for number, line in lines:
        where = f"{source} line {number}"
        try:
            event = parse_event(line, where, first=state is None)
            if state is None:
                assert isinstance(event, StartEvent)
                state = ReplayState(_scene_of(event.scene, where))
            else:
                state.apply(event)
        except JournalError as exc:
            error = exc if str(exc).startswith(where) else JournalError(f"{where}: {exc}")
            return Salvage(state.restored(last) if state else None, kept, error)
        except (EditConflict, ValueError) as exc:
            return Salvage(state.restored(last) if state else None, kept, JournalError(f"{where}: {exc}"))
        last = event
        kept += 1
    assert state is not None
    return Salvage(state.restored(last), kept, None)


def _scene_of(data: dict[str, Any], where: str) -> Scene:
    try:
        return Scene.model_validate(data)
    except ValueError as exc:
        raise JournalError(f"{where}: the scene is not valid: {str(exc).splitlines()[0]}") from exc


class ReplayState:
    """The state a replay builds, one event at a time, checking each against transaction ids."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self.history = History()
        self.memory = Memory()

    def restored(self, last: Event | None) -> Restored:
        # Each event checks before it changes anything, so a refused one left no trace.
        return Restored(self.scene, self.history, self.memory, isinstance(last, EndEvent))

    def apply(self, event: Event) -> None:
        if isinstance(event, StartEvent):
            raise JournalError("a second start event")
        if isinstance(event, CommitEvent):
            self._commit(event)
        elif isinstance(event, TxnEvent) and event.event == "redo":
            self._redo(event.txn)
        elif isinstance(event, TxnEvent):
            self._step_back(event.event, event.txn)
        elif isinstance(event, LoadEvent):
            self.scene = _scene_of(event.scene, "load")
            self.history.done.clear()
            self.history.undone.clear()
        elif isinstance(event, TurnEvent):
            self.memory.record(event.turn)
        # An EndEvent changes nothing: a resumed session may write more after it.

    def _commit(self, event: CommitEvent) -> None:
        history = self.history
        if event.txn < history.next_txn:
            raise JournalError(f"change {event.txn} reuses an id (the next is {history.next_txn})")
        self.scene = event.edit.apply(self.scene)
        history.done.append(Entry(event.txn, event.prompt, event.edit, facts=event.facts))
        history.undone.clear()
        history.next_txn = event.txn + 1

    def _step_back(self, kind: str, txn: int) -> None:
        """undo, accept or reject of the newest applied change, which must be `txn`."""
        history = self.history
        top = history.done[-1] if history.done else None
        if top is None or top.txn != txn:
            newest = f"the newest applied change is {top.txn}" if top else "no change is applied"
            raise JournalError(f"{kind} of change {txn}, but {newest}")
        if kind != "undo" and top.accepted:
            raise JournalError(f"{kind} of change {txn}, which was already accepted")
        if kind == "accept":
            top.accepted = True
            self.memory.mark_last("accepted")
            return
        self.scene = top.edit.inverse().apply(self.scene)
        history.done.pop()
        if kind == "undo":
            history.undone.append(top)
            self.memory.mark_last("undone")
        else:
            history.undone.clear()  # redo entries were built on the rejected change
            self.memory.mark_last("rejected")

    def _redo(self, txn: int) -> None:
        history = self.history
        top = history.undone[-1] if history.undone else None
        if top is None or top.txn != txn:
            newest = f"the newest undone change is {top.txn}" if top else "no change is undone"
            raise JournalError(f"redo of change {txn}, but {newest}")
        self.scene = top.edit.apply(self.scene)
        history.undone.pop()
        history.done.append(top)
        self.memory.mark_last("applied")


def _cut_torn_tail(fd: int) -> None:
    """Truncate a final line that has no newline (a torn write), so appends start clean."""
    size = os.lseek(fd, 0, os.SEEK_END)
    if size == 0:
        return
    chunk = min(size, 1 << 16)
    position = size
    while position > 0:
        start = max(0, position - chunk)
        data = os.pread(fd, position - start, start)
        if position == size and data.endswith(b"\n"):
            return
        cut = data.rfind(b"\n")
        if cut >= 0:
            os.ftruncate(fd, start + cut + 1)
            return
        position = start
    os.ftruncate(fd, 0)


def _truncate_quietly(fd: int, size: int) -> None:
    with contextlib.suppress(OSError):
        os.ftruncate(fd, size)  # shrinking needs no free space


def _free_name(path: Path) -> Path:
    """`path` with a number added that no file has yet: session.jsonl -> session.1.jsonl."""
    number = 1
    while True:
        candidate = path.with_name(f"{path.stem}.{number}{path.suffix}")
        if not candidate.exists():
            return candidate
        number += 1
