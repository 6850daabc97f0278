"""Where sessions keep their journals: one file per session in the state folder, rotated.

A session never truncates another's journal: each gets its own file named by its start time
(and process id), the oldest beyond `KEEP_JOURNALS` are deleted, and `chat` can find the
newest one that did not end cleanly to offer resuming it.
"""

from __future__ import annotations

import fcntl
import os
import time
from dataclasses import dataclass
from pathlib import Path

from drivetwin.orchestrator.journal import Journal, JournalError

# Enough to resume any session of the last few days; each file is a few hundred kB at most.
KEEP_JOURNALS = 20
JOURNAL_FOLDER = "journals"
_PATTERN = "session-*.jsonl"


@dataclass(frozen=True)
class UncleanJournal:
    """A journal whose session did not write an `end` event (a crash, a kill, a closed terminal)."""

    path: Path
    changes: int

    def describe(self) -> str:
        when = time.strftime("%Y-%m-%d %H:%M", time.localtime(self.path.stat().st_mtime))
        return f"the session of {when} ({self.changes} change(s)) did not end cleanly: {self.path}"


def journal_folder(state_dir: Path) -> Path:
    return state_dir / JOURNAL_FOLDER


def new_journal_path(state_dir: Path) -> Path:
    """A fresh journal file for a new session, after rotating out the oldest ones."""
    folder = journal_folder(state_dir)
    folder.mkdir(parents=True, exist_ok=True)
    rotate(folder, KEEP_JOURNALS - 1)
    stamp = time.strftime("%Y%m%d-%H%M%S")
    return folder / f"session-{stamp}-{os.getpid()}.jsonl"


def session_journals(folder: Path) -> list[Path]:
    """The session journals in `folder`, oldest first."""
    return sorted(folder.glob(_PATTERN), key=lambda p: (p.stat().st_mtime, p.name))


def rotate(folder: Path, keep: int) -> list[Path]:
    """Delete the oldest journals beyond `keep`, never one a live session holds; the deleted paths."""
    journals = session_journals(folder)
    deleted = []
    for path in journals[: max(0, len(journals) - keep)]:
        if _in_use(path):
            continue
        path.unlink(missing_ok=True)
        deleted.append(path)
    return deleted


def latest_journal(state_dir: Path) -> Path | None:
    """The newest session journal, for `chat --resume` without --journal."""
    journals = session_journals(journal_folder(state_dir))
    return journals[-1] if journals else None


def latest_unclean(state_dir: Path) -> UncleanJournal | None:
    """The newest journal that replays, did not end cleanly and is not in use; None if all did."""
    for path in reversed(session_journals(journal_folder(state_dir))):
        if _in_use(path):
            continue
        try:
            restored = Journal(path).replay()
        except JournalError:
            continue
        if restored.ended_cleanly:
            return None  # the newest session that can be resumed ended well: nothing to offer
        if not restored.history.done:
            continue  # nothing would be lost by starting afresh
        return UncleanJournal(path, len(restored.history.done))
    return None


def _in_use(path: Path) -> bool:
    try:
        fd = os.open(path, os.O_RDONLY)
    except OSError:
        return False
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        return True
    finally:
        os.close(fd)
    return False
