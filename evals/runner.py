"""Run a suite against a planner: every case × trial, in parallel, resumable, with progress.

`run_suite` is what `drivetwin eval run` calls. Records are appended to `out_path` as
trials finish; run the same command again after an interruption and it does only what is
missing.
"""

from __future__ import annotations

import datetime as dt
import platform
import subprocess
import time
from collections.abc import Sequence
from dataclasses import dataclass
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path
from typing import Any, TextIO

from drivetwin.evals.case import GRADES, TASKS, Case, load_suite
from drivetwin.evals.executors import EXECUTORS, Job, PlannerLoadError, preflight, run_local
from drivetwin.evals.records import RecordWriter, RunHeader, TrialRecord
from drivetwin.worlds.progress import progress_bar


@dataclass(frozen=True)
class RunSummary:
    """What a call of `run_suite` did: where the records are, how many ran, and how they went."""

    out_path: Path
    total: int  # case × trial pairs the run asks for
    already_done: int  # found in the records file when the call started
    ran: int  # finished by this call
    passed: int  # over every record in the file
    failed: int
    errors: int
    interrupted: bool
    seconds: float

    @property
    def complete(self) -> bool:
        return not self.interrupted and self.already_done + self.ran >= self.total

    @property
    def success_rate(self) -> float:
        judged = self.passed + self.failed + self.errors
        return self.passed / judged if judged else 0.0


class RunError(ValueError):
    """Run settings that cannot work (no trials, unknown executor...)."""


def git_commit(start: Path | None = None) -> str | None:
    """The commit of the checkout that holds this code, with '-dirty' if it has edits; or None."""
    where = start or Path(__file__).resolve().parent

    def git(*args: str) -> str:
        done = subprocess.run(["git", *args], cwd=where, capture_output=True, text=True, timeout=10, check=True)
        return done.stdout.strip()

    try:
        sha = git("rev-parse", "--short=12", "HEAD")
        dirty = git("status", "--porcelain", "--untracked-files=no")
    except (OSError, subprocess.SubprocessError):
        return None
    return sha + ("-dirty" if dirty else "")


def _version() -> str | None:
    try:
        return version("drivetwin")
    except PackageNotFoundError:
        return None


def select_cases(cases: Sequence[Case], only: Sequence[str]) -> list[Case]:
    """The cases whose grade and task pass the `only` filter (grade and task names)."""
    unknown = sorted(set(only) - set(GRADES) - set(TASKS))
    if unknown:
        raise RunError(f"unknown grade or task {', '.join(unknown)}; grades: {', '.join(GRADES)}; "
                       f"tasks: {', '.join(TASKS)}")
    grades = set(only) & set(GRADES) or set(GRADES)
    tasks = set(only) & set(TASKS) or set(TASKS)
    return [case for case in cases if case.grade in grades and case.task in tasks]


def run_suite(
    suite_path: str | Path,
    planner_name: str,
    *,
    planner_options: dict[str, Any] | None = None,
    trials: int = 1,
    out_path: str | Path,
    executor: str = "local",
    workers: int = 1,
    progress: bool = True,
    label: str = "",
    stream: TextIO | None = None,
    only: Sequence[str] = (),
) -> RunSummary:
    """Run every case of a suite `trials` times with a planner, appending records to `out_path`.

    `planner_name` is a registered planner ('rules', 'llm', 'hybrid'), 'reference' (each
    case's own reference calls: checks the suite itself), or 'package.module:factory'.
    `only` limits the run to cases of those grades and tasks (a grade and a task both given:
    cases that match one of the grades and one of the tasks).
    A Ctrl-C stops the run cleanly: the summary says `interrupted` and the records written
    so far stay; calling again with the same arguments resumes.
    """
    if trials < 1:
        raise RunError(f"trials must be at least 1, got {trials}")
    if executor not in EXECUTORS:
        raise RunError(f"unknown executor {executor!r}; choose one of: {', '.join(EXECUTORS)}")
    options = dict(planner_options or {})
    suite = load_suite(suite_path)
    cases = select_cases(suite.cases, only)
    try:
        preflight(planner_name, options)
    except PlannerLoadError as exc:
        raise RunError(str(exc)) from exc
    header = RunHeader(
        suite=suite.name,
        suite_path=suite.path,
        suite_digest=suite.digest,
        cases=len(cases),
        only=sorted(set(only)),
        planner=planner_name,
        planner_options=options,
        label=label,
        trials=trials,
        started=dt.datetime.now(dt.UTC).isoformat(timespec="seconds"),
        git_commit=git_commit(),
        drivetwin_version=_version(),
        executor=executor,
        workers=workers,
        host={
            "python": platform.python_version(),
            "machine": platform.machine(),
            "system": platform.system(),
        },
    )
    writer = RecordWriter(out_path, header)
    already = len(writer.done)
    # Trial-major order: an interrupted run has covered many cases once, not few cases often.
    jobs: list[Job] = [
        (case.model_dump_json(), trial)
        for trial in range(trials)
        for case in cases
        if (case.id, trial) not in writer.done
    ]
    total = len(cases) * trials
    counts = {"pass": 0, "fail": 0, "error": 0}
    ran = passed = 0
    started = time.perf_counter()
    interrupted = False
    with progress_bar("eval", total, "trials", initial=total - len(jobs), enabled=progress, stream=stream) as bar:

        def keep(record: TrialRecord) -> None:
            nonlocal ran, passed
            writer.append(record)
            ran += 1
            passed += record.outcome == "pass"
            bar.advance(note=f"pass {passed}")

        try:
            if executor == "ray":
                from drivetwin.evals.ray_executor import run_ray

                run_ray(jobs, planner_name, options, workers, keep)
            else:
                run_local(jobs, planner_name, options, workers, keep)
        except KeyboardInterrupt:
            interrupted = True
        finally:
            writer.close()
    from drivetwin.evals.records import read_run

    for record in read_run(out_path).records:
        counts[record.outcome] += 1
    return RunSummary(
        Path(out_path),
        total,
        already,
        ran,
        counts["pass"],
        counts["fail"],
        counts["error"],
        interrupted,
        time.perf_counter() - started,
    )
