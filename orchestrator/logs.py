"""The log of what the models did: every backend request and answer, and each turn they served.

One JSON Lines file per session in the state folder (Settings.state_dir / "logs"), written by
the one `Backend.chat` (`record_exchange`) and by the session at the end of each planned
prompt (`record_turn`). Lines are of three kinds, each with the session id:

- `session`: the header (when, which command and world);
- `exchange`: one backend call: the messages, schema and parameters sent, the answer text,
  tokens, latency and attempts, or the error; with the turn it served;
- `turn`: one prompt: the planner, model(s), prompt version, the trace (requirements...),
  the calls, what came of it and the ids of its exchanges.

A file past MAX_FILE_BYTES is rotated (`NAME.1.jsonl`...), and only the newest KEEP_SESSIONS
sessions are kept. Turn facts (models, tokens, exchanges) are gathered even with no log
open, so the journal records them either way. `drivetwin logs` reads the files
(drivetwin.orchestrator.cli_logs).
"""

from __future__ import annotations

import contextlib
import itertools
import json
import os
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from drivetwin.orchestrator.journal_events import PlanFacts

if TYPE_CHECKING:
    from drivetwin.orchestrator.backends.base import ChatResult, CompletionRequest
    from drivetwin.orchestrator.backends.errors import BackendError
    from drivetwin.orchestrator.planning.base import Plan

LOG_FOLDER = "logs"
# A turn of the managers' prompts is some 10-40 kB of lines; a long session stays far below.
MAX_FILE_BYTES = 20 * 1024 * 1024
# Enough to look back over several days of sessions; older session files are deleted.
KEEP_SESSIONS = 50
_PATTERN = "session-*.jsonl"


def log_folder(state_dir: Path) -> Path:
    return state_dir / LOG_FOLDER


@dataclass
class TurnFacts:
    """What the backends did for one prompt: gathered while it is planned."""

    session: str | None
    turn: int
    models: list[str] = field(default_factory=list)
    exchanges: list[str] = field(default_factory=list)
    tokens: int = 0
    started: float = field(default_factory=time.perf_counter)

    @property
    def log_id(self) -> str | None:
        """The turn's id in `drivetwin logs` (SESSION:TURN), or None when nothing is logged."""
        return f"{self.session}:{self.turn}" if self.session else None

    @property
    def model(self) -> str | None:
        return ", ".join(self.models) or None


class RequestLog:
    """One session's log file, appended to by any thread; rotated past MAX_FILE_BYTES."""

    def __init__(self, folder: Path, session: str | None = None) -> None:
        self.folder = folder
        self.session = session or time.strftime("session-%Y%m%d-%H%M%S-") + str(os.getpid())
        self.path = folder / f"{self.session}.jsonl"
        self._lock = threading.Lock()
        self._exchange_ids = itertools.count(1)

    def next_exchange_id(self) -> str:
        return f"{self.session}:x{next(self._exchange_ids)}"

    def write(self, kind: str, **fields: Any) -> None:
        line = json.dumps({"kind": kind, "session": self.session, "time": time.time(), **fields},
                          ensure_ascii=False, default=str)
        with self._lock:
            self.folder.mkdir(parents=True, exist_ok=True)
            if self.path.exists() and self.path.stat().st_size + len(line) > MAX_FILE_BYTES:
                self._rotate()
            with self.path.open("a", encoding="utf-8") as out:
                out.write(line + "\n")

    def _rotate(self) -> None:
        parts = [p for p in self.folder.glob(f"{self.session}.*.jsonl")]
        self.path.rename(self.folder / f"{self.session}.{len(parts) + 1}.jsonl")


class _State:
    """The process's open log and the turn being planned (one session per process)."""

    def __init__(self) -> None:
        self.log: RequestLog | None = None
        self.turn: TurnFacts | None = None
        self.turns = itertools.count(1)
        self.lock = threading.Lock()


_STATE = _State()


def open_log(state_dir: Path, *, command: str, world: str = "") -> RequestLog:
    """Start logging this process's backend calls to a new session file; old sessions rotate out."""
    folder = log_folder(state_dir)
    folder.mkdir(parents=True, exist_ok=True)
    for old in session_files(folder)[: -(KEEP_SESSIONS - 1) or None]:
        for part in [old, *folder.glob(f"{old.stem}.*.jsonl")]:
            with contextlib.suppress(OSError):
                part.unlink()
    log = RequestLog(folder)
    log.write("session", command=command, world=world, pid=os.getpid())
    _STATE.log = log
    return log


def close_log() -> None:
    _STATE.log = None


def active_log() -> RequestLog | None:
    return _STATE.log


@contextlib.contextmanager
def turn_scope() -> Iterator[TurnFacts]:
    """Gather the backend calls made while one prompt is planned (numbered within the session)."""
    log = _STATE.log
    facts = TurnFacts(log.session if log else None, next(_STATE.turns))
    _STATE.turn = facts
    try:
        yield facts
    finally:
        _STATE.turn = None


def record_exchange(backend: str, model: str, request: CompletionRequest, result: ChatResult | None,
                    error: BackendError | None, attempts: int, latency_s: float) -> None:
    """Log one backend call and note it in the turn being planned (called by Backend.chat)."""
    facts, log = _STATE.turn, _STATE.log
    exchange_id = log.next_exchange_id() if log else None
    if facts is not None:
        with _STATE.lock:
            name = f"{backend}/{model}"
            if name not in facts.models:
                facts.models.append(name)
            if result is not None:
                facts.tokens += result.prompt_tokens + result.completion_tokens
            if exchange_id:
                facts.exchanges.append(exchange_id)
    if log is None:
        return
    log.write(
        "exchange", id=exchange_id, turn=facts.turn if facts else None, backend=backend, model=model,
        request={"messages": request.messages, "schema": request.schema, "temperature": request.temperature,
                 "seed": request.seed, "max_tokens": request.max_tokens, "timeout_s": request.timeout_s},
        answer=None if result is None else {
            "text": result.text, "finish_reason": result.finish_reason,
            "prompt_tokens": result.prompt_tokens, "completion_tokens": result.completion_tokens},
        error=None if error is None else f"{type(error).__name__}: {error}",
        attempts=attempts, latency_s=round(latency_s, 4),
    )


def record_turn(facts: TurnFacts, **fields: Any) -> None:
    """Log one planned prompt (planner, prompt version, trace, calls, outcome) with its exchanges."""
    log = _STATE.log
    if log is not None and facts.session == log.session:
        log.write("turn", turn=facts.turn, model=facts.model, exchanges=facts.exchanges, tokens=facts.tokens,
                  **fields)


def plan_facts(plan: Plan | None, gathered: TurnFacts, planner: str, plan_s: float) -> PlanFacts:
    """The journal's record of who planned a turn: the plan's own account and what the backends saw."""
    return PlanFacts(
        planner=plan.planner if plan else planner,
        model=gathered.model,
        prompt_version=plan.prompt_version if plan else None,
        trace=[step.model_dump(mode="json") for step in plan.trace] if plan else [],
        tokens=(plan.tokens if plan else 0) or gathered.tokens,
        plan_s=round(plan_s, 4),
        log=gathered.log_id,
    )


# Reading ---------------------------------------------------------------------------------
def session_files(folder: Path) -> list[Path]:
    """The sessions' first files, oldest first (rotated parts are named NAME.N.jsonl)."""
    files = [p for p in folder.glob(_PATTERN) if p.stem.count(".") == 0]
    return sorted(files, key=lambda p: p.name)


def read_session(folder: Path, session: str) -> list[dict[str, Any]]:
    """Every line of a session, its rotated parts first; a torn or foreign line is skipped."""
    parts = sorted(folder.glob(f"{session}.*.jsonl"), key=lambda p: int(p.stem.rsplit(".", 1)[1]))
    lines: list[dict[str, Any]] = []
    for path in [*parts, folder / f"{session}.jsonl"]:
        if not path.exists():
            continue
        for raw in path.read_text(encoding="utf-8", errors="replace").splitlines():
            with contextlib.suppress(json.JSONDecodeError):
                value = json.loads(raw)
                if isinstance(value, dict) and "kind" in value:
                    lines.append(value)
    return lines
