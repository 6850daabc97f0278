"""The records file of a run: a header line, then one JSON line per (case, trial) as it finishes.

Lines are appended and flushed one at a time, so an interrupted run loses at most the trial
in flight, and resuming skips every (case, trial) already written. Metrics and reports read
only this file, which makes an interrupted-then-resumed run measure the same as a clean one.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

RECORDS_FORMAT = "drivetwin-eval-records/1"
Outcome = Literal["pass", "fail", "error"]
# What a trial amounted to for the person: done as meant, a clarifying question, a refusal, or
# a change accepted that fails a check (the one to drive to zero); "error": the trial crashed.
Result = Literal["passed", "asked", "refused", "wrong", "error"]
RESULTS: tuple[str, ...] = ("passed", "asked", "refused", "wrong", "error")


class ModelFacts(BaseModel):
    """What a planner says about the model behind it, where known."""

    model_config = ConfigDict(extra="forbid")

    name: str | None = None
    size_bytes: int | None = None
    parameters: int | None = None


class RunHeader(BaseModel):
    """The first line of a records file: what was run, with what, when and from which commit."""

    model_config = ConfigDict(extra="forbid")

    type: Literal["header"] = "header"
    format: str = RECORDS_FORMAT
    suite: str
    suite_path: str
    suite_digest: str
    cases: int
    # Grades and tasks the run was limited to (`--only direct`); empty: every case.
    only: list[str] = Field(default_factory=list)
    planner: str
    planner_options: dict[str, Any] = Field(default_factory=dict)
    label: str = ""
    trials: int
    started: str
    git_commit: str | None = None
    drivetwin_version: str | None = None
    executor: str = "local"
    workers: int = 1
    host: dict[str, Any] = Field(default_factory=dict)


class FailedCheck(BaseModel):
    """A check that did not pass, and why."""

    model_config = ConfigDict(extra="forbid")

    kind: str
    reason: str


# How much of each trace step a trial record keeps (the rule planner's step ends with its reasons).
TRACE_CHARS = 1000


class TrialRecord(BaseModel):
    """One trial of one case: its outcome, why it failed, what the planner did and how fast."""

    model_config = ConfigDict(extra="forbid", validate_assignment=False)

    type: Literal["trial"] = "trial"
    case_id: str
    trial: int = Field(ge=0)
    task: str
    grade: str
    outcome: Outcome
    # Records written before outcome classes existed have none; `result_class` derives it.
    result: Result | None = None
    planner: str = ""
    accepted: bool | None = None
    failed_checks: list[FailedCheck] = Field(default_factory=list)
    error: str | None = None
    answer: str = ""
    calls: list[dict[str, Any]] = Field(default_factory=list)
    retries: int = 0
    tokens: int = 0
    prompt_version: str | None = None
    # How sure the planner was of the plan it answered with (0-1), and the path a combining
    # planner took ("fast", "agree", "retrieval", "llm", ...): what calibration is measured on.
    confidence: float | None = None
    path: str | None = None
    # The plan's trace, a line per step ("level: what it said", its last TRACE_CHARS): why
    # the planner did what it did, for reading a run's failures without re-running them.
    trace: list[str] = Field(default_factory=list)
    latency_s: float | None = None
    latency_levels: dict[str, float] = Field(default_factory=dict)
    wall_s: float = 0.0
    fingerprint: str | None = None
    model: ModelFacts | None = None

    @property
    def key(self) -> tuple[str, int]:
        return (self.case_id, self.trial)

    @property
    def result_class(self) -> Result:
        """passed, asked, refused, wrong or error (derived for records that predate the field)."""
        if self.result is not None:
            return self.result
        if self.outcome == "error":
            return "error"
        if self.outcome == "pass":
            return "passed"
        return "refused" if self.accepted is False else "wrong"


class RecordsError(ValueError):
    """A records file that is not one, or belongs to a different run than the one resumed."""


@dataclass
class Run:
    """A records file read back: its header and its trials (first record of each key wins)."""

    path: Path
    header: RunHeader
    records: list[TrialRecord]

    def done(self) -> set[tuple[str, int]]:
        return {r.key for r in self.records}


def _parse_lines(path: Path) -> tuple[RunHeader | None, list[TrialRecord], int]:
    """Header, trials, and the byte length of the valid prefix (a torn last line is cut)."""
    data = path.read_bytes()
    header: RunHeader | None = None
    records: list[TrialRecord] = []
    seen: set[tuple[str, int]] = set()
    valid = 0
    offset = 0
    for raw in data.splitlines(keepends=True):
        offset += len(raw)
        if not raw.endswith(b"\n"):
            break  # written only in part when the run was stopped
        text = raw.decode("utf-8").strip()
        if text:
            try:
                obj = json.loads(text)
                if obj.get("type") == "header":
                    header = header or RunHeader.model_validate(obj)
                else:
                    record = TrialRecord.model_validate(obj)
                    if record.key not in seen:
                        seen.add(record.key)
                        records.append(record)
            except (json.JSONDecodeError, ValidationError, AttributeError) as exc:
                raise RecordsError(f"{path}: line at byte {offset - len(raw)} is not a record: {exc}") from exc
        valid = offset
    return header, records, valid


def read_run(path: str | Path) -> Run:
    """Read a records file written by `run_suite`."""
    target = Path(path)
    if not target.is_file():
        raise RecordsError(f"no records file at {target}")
    header, records, _ = _parse_lines(target)
    if header is None:
        raise RecordsError(f"{target} has no header line; is it a drivetwin eval records file?")
    return Run(target, header, records)


class RecordWriter:
    """Appends trial records to a run's file, starting it or resuming it."""

    def __init__(self, path: str | Path, header: RunHeader) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self.header = header
        self.done: set[tuple[str, int]] = set()
        if self.path.is_file() and self.path.stat().st_size > 0:
            old, records, valid = _parse_lines(self.path)
            if old is None:
                raise RecordsError(f"{self.path} exists but is not a records file; choose another --out")
            _check_same_run(self.path, old, header)
            self.header = old
            self.done = {r.key for r in records}
            with self.path.open("r+b") as fh:
                fh.truncate(valid)
            self._fh = self.path.open("a", encoding="utf-8")
        else:
            self._fh = self.path.open("w", encoding="utf-8")
            self._write(header.model_dump(mode="json"))

    def append(self, record: TrialRecord) -> None:
        """Write one record now, durably: a Ctrl-C right after it loses nothing."""
        if record.key in self.done:
            return
        self._write(record.model_dump(mode="json", exclude_defaults=False))
        self.done.add(record.key)

    def _write(self, obj: dict[str, Any]) -> None:
        self._fh.write(json.dumps(obj, separators=(",", ":")) + "\n")
        self._fh.flush()
        os.fsync(self._fh.fileno())

    def close(self) -> None:
        self._fh.close()


def _check_same_run(path: Path, old: RunHeader, new: RunHeader) -> None:
    for field in ("suite_digest", "only", "planner", "planner_options"):
        if getattr(old, field) != getattr(new, field):
            raise RecordsError(
                f"{path} holds a run with another {field} ({getattr(old, field)!r}, now "
                f"{getattr(new, field)!r}); resume with the same settings or choose another --out"
            )
