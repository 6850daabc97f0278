"""`drivetwin journal check|repair`: say whether a journal replays, and salvage what does.

Repair keeps the longest whole, valid prefix (every line up to the first one that is torn,
garbage, of the wrong type or out of step with the transaction ids), keeps the original
beside it as FILE.bak, and says what it dropped. It takes the journal's lock, so it never
rewrites a journal a live session is writing.
"""

from __future__ import annotations

import fcntl
import os
import shutil
from dataclasses import dataclass
from pathlib import Path

from drivetwin.orchestrator.journal import JournalError, JournalLockedError, Salvage, salvage_lines
from drivetwin.worlds.json_input import JsonInputError, decode_utf8


@dataclass(frozen=True)
class JournalReport:
    """What a check or repair found: event lines kept and dropped, and why the first was dropped."""

    path: Path
    lines: int
    kept: int
    changes: int
    torn_tail: bool
    problem: str | None
    backup: Path | None = None

    @property
    def healthy(self) -> bool:
        return self.problem is None and not self.torn_tail

    def describe(self) -> str:
        head = f"{self.path}: {self.kept} of {self.lines} line(s) replay, {self.changes} change(s) applied"
        if self.healthy:
            return f"{head}; the journal is whole"
        parts = [head]
        if self.problem:
            parts.append(f"first bad line: {self.problem}")
        if self.torn_tail:
            parts.append("the last line is torn (no newline)")
        if self.backup is not None:
            parts.append(f"dropped {self.lines - self.kept} line(s){' and the torn tail' if self.torn_tail else ''}; "
                         f"the original is kept as {self.backup}")
        return "; ".join(parts)


def check_journal(path: Path) -> JournalReport:
    """Replay the journal read-only and report how far it gets."""
    salvage, lines, torn, _ = _salvage(path)
    return _report(path, salvage, lines, torn)


def repair_journal(path: Path) -> JournalReport:
    """Rewrite the journal as its longest valid prefix, keeping the original as FILE.bak."""
    fd = os.open(path, os.O_RDONLY)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError as exc:
            raise JournalLockedError(f"journal {path} is in use by a drivetwin session; close it first") from exc
        salvage, lines, torn, raw = _salvage(path)
        report = _report(path, salvage, lines, torn)
        if report.healthy:
            return report
        if salvage.kept == 0:
            raise JournalError(f"{path}: nothing can be salvaged ({report.problem}); the file was left as it was")
        backup = path.with_name(path.name + ".bak")
        shutil.copy2(path, backup)
        tmp = path.with_name(path.name + ".tmp")
        tmp.write_bytes(b"".join(line + b"\n" for line in raw[: _raw_count(raw, salvage.kept)]))
        tmp.replace(path)
        return _report(path, salvage, lines, torn, backup)
    finally:
        os.close(fd)


def _salvage(path: Path) -> tuple[Salvage, int, bool, list[bytes]]:
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise JournalError(f"cannot read journal {path}: {exc.strerror}") from exc
    *raw, tail = data.split(b"\n")
    numbered: list[tuple[int, str]] = []
    problem: JournalError | None = None
    for number, line in enumerate(raw, start=1):
        try:
            text = decode_utf8(line, f"{path} line {number}")
        except JsonInputError as exc:
            problem = JournalError(str(exc))
            break
        numbered.append((number, text))
    usable = [(n, t) for n, t in numbered if t.strip()]
    salvage = salvage_lines(usable, str(path))
    if salvage.error is None and problem is not None:
        salvage = Salvage(salvage.restored, salvage.kept, problem)
    return salvage, sum(1 for line in raw if line.strip()), bool(tail), raw


def _raw_count(raw: list[bytes], kept_events: int) -> int:
    """How many raw lines hold the first `kept_events` non-blank ones."""
    seen = 0
    for index, line in enumerate(raw):
        if line.strip():
            if seen == kept_events:
                return index
            seen += 1
    return len(raw)


def _report(path: Path, salvage: Salvage, lines: int, torn: bool, backup: Path | None = None) -> JournalReport:
    changes = len(salvage.restored.history.done) if salvage.restored else 0
    problem = str(salvage.error) if salvage.error else None
    return JournalReport(path, lines, salvage.kept, changes, torn, problem, backup)
