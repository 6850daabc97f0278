"""Where trials run: in this process, in local worker processes, or on a Ray cluster.

Every executor takes the same jobs (a case as JSON and a trial number) and hands each
finished record to a callback as soon as it exists, in whatever order trials finish. A
worker builds its planner once and reuses it for all its trials (a model loads once).
"""

from __future__ import annotations

import multiprocessing
import re
import signal
from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from typing import Any, Literal

from drivetwin.evals.case import Case
from drivetwin.evals.records import ModelFacts, TrialRecord
from drivetwin.evals.trial import REFERENCE_PLANNER, run_trial
from drivetwin.orchestrator.planning import Plan, PlanContext, Planner, PlanningError
from drivetwin.orchestrator.planning.registry import UnknownPlannerError, make_planner
from drivetwin.tools.registry import ToolRegistry

ExecutorName = Literal["local", "ray"]
EXECUTORS: tuple[str, ...] = ("local", "ray")
# Planners whose facts can come from an embedded model's file when they give none themselves.
LLM_PLANNERS = ("llm", "hybrid")
Job = tuple[str, int]  # (case as JSON, trial number)
OnRecord = Callable[[TrialRecord], None]


class _ReferenceStub:
    """Stands for the reference planner until a trial swaps in the case's own one."""

    name = REFERENCE_PLANNER

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        raise PlanningError("the reference planner plans from a case; run it through run_trial")


class PlannerLoadError(RuntimeError):
    """A planner that cannot be built from its name and options."""


def build_planner(name: str, options: dict[str, Any]) -> Planner:
    """A planner by registered name, 'reference', or 'package.module:factory' (the planner registry's)."""
    if name == REFERENCE_PLANNER:
        return _ReferenceStub()
    try:
        return make_planner(name, **options)
    except UnknownPlannerError as exc:
        raise PlannerLoadError(str(exc)) from exc


def preflight(name: str, options: dict[str, Any]) -> None:
    """Build the planner once and open its model, so a wrong name, option or model stops a run
    before its first case (in one line) instead of failing every case."""
    if name == "rules" and options:
        raise PlannerLoadError(f"the rules planner takes no options; got {', '.join(sorted(options))}")
    try:
        planner = build_planner(name, options)
        for part in (planner, getattr(planner, "llm", None)):
            if part is not None and hasattr(part, "backend"):
                part.backend  # noqa: B018 - opening the backend is the check
    except PlannerLoadError:
        raise
    except (LookupError, TypeError, ValueError, PlanningError) as exc:
        raise PlannerLoadError(f"planner {name!r} cannot start: {exc}") from exc


def planner_facts(planner: Planner, name: str = "", options: dict[str, Any] | None = None) -> ModelFacts | None:
    """Model name, size on disk and parameter count: from the planner's `model_facts()` if it
    has one, else for an embedded GGUF model from its file and its name ("...-135m")."""
    facts = getattr(planner, "model_facts", None)
    try:
        if callable(facts):
            return ModelFacts.model_validate(facts())
        if name in LLM_PLANNERS:
            return _embedded_facts(dict(options or {}))
    except Exception:  # facts are a nicety; a planner that cannot give them still runs
        return None
    return None


def _embedded_facts(options: dict[str, Any]) -> ModelFacts | None:
    from drivetwin.orchestrator.backends.gguf_models import resolve_gguf
    from drivetwin.orchestrator.planning.llm.planner import DEFAULT_BACKEND, DEFAULT_MODEL

    if options.get("backend", DEFAULT_BACKEND) != "embedded":
        return None
    shown, path = resolve_gguf(str(options.get("model") or DEFAULT_MODEL))
    size = re.search(r"(\d+(?:\.\d+)?)([mb])\b", shown.lower())
    params = int(float(size.group(1)) * (1e6 if size.group(2) == "m" else 1e9)) if size else None
    return ModelFacts(name=shown, size_bytes=path.stat().st_size, parameters=params)


class TrialWorker:
    """Builds a planner once and runs trials with it."""

    def __init__(self, planner_name: str, options: dict[str, Any]) -> None:
        self.planner = build_planner(planner_name, options)
        self.registry = ToolRegistry.default()
        self.facts = planner_facts(self.planner, planner_name, options)

    def run(self, case_json: str, trial: int) -> str:
        case = Case.model_validate_json(case_json)
        record = run_trial(case, self.planner, trial, self.registry)
        record.model = self.facts
        text: str = record.model_dump_json()
        return text


_WORKER: TrialWorker | None = None


def _init_process(planner_name: str, options: dict[str, Any]) -> None:
    global _WORKER
    # Ctrl-C is the parent's to handle: it stops handing out jobs and keeps what finished.
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _WORKER = TrialWorker(planner_name, options)


def _run_in_process(case_json: str, trial: int) -> str:
    if _WORKER is None:  # pragma: no cover - the initializer always ran
        raise RuntimeError("worker used before it was initialised")
    return _WORKER.run(case_json, trial)


def run_inline(jobs: Iterable[Job], planner_name: str, options: dict[str, Any], on_record: OnRecord) -> None:
    """Run every job here, one after another (one worker: no process start-up cost)."""
    worker = TrialWorker(planner_name, options)
    for case_json, trial in jobs:
        on_record(TrialRecord.model_validate_json(worker.run(case_json, trial)))


def run_local(jobs: list[Job], planner_name: str, options: dict[str, Any], workers: int, on_record: OnRecord) -> None:
    """Run jobs in `workers` spawned processes; a Ctrl-C stops them and keeps what finished."""
    if workers <= 1:
        run_inline(jobs, planner_name, options, on_record)
        return
    # Spawn, not fork: a planner may hold threads (llama.cpp, torch) that fork would break.
    context = multiprocessing.get_context("spawn")
    pool = ProcessPoolExecutor(
        max_workers=workers,
        mp_context=context,
        initializer=_init_process,
        initargs=(planner_name, options),
    )
    pending: set[Future[str]] = set()
    queue = iter(jobs)
    try:
        # Keep a few jobs per worker in flight, so an interrupt leaves little half done.
        for case_json, trial in queue:
            pending.add(pool.submit(_run_in_process, case_json, trial))
            if len(pending) >= 2 * workers:
                break
        while pending:
            finished, pending = wait(pending, return_when=FIRST_COMPLETED)
            for future in finished:
                on_record(TrialRecord.model_validate_json(future.result()))
                nxt = next(queue, None)
                if nxt is not None:
                    pending.add(pool.submit(_run_in_process, *nxt))
    except BaseException:
        pool.shutdown(wait=False, cancel_futures=True)
        for child in multiprocessing.active_children():
            child.terminate()
        raise
    pool.shutdown(wait=True)
