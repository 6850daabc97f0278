"""One trial of one case: build the starting scene, submit the prompt, judge the outcome.

The prompt goes through a real `Session`, so a trial sees exactly what a user would: the
planner, the all-or-nothing transaction and the conversation memory of the setup turns.
"""

from __future__ import annotations

import hashlib
import json
import time
from functools import cache
from typing import Any

from drivetwin.evals.case import Case
from drivetwin.evals.outcome import CaseOutcome
from drivetwin.evals.records import TRACE_CHARS, FailedCheck, TrialRecord
from drivetwin.orchestrator.planning import Plan, PlanContext, Planner, PlanningError
from drivetwin.orchestrator.session import Session, TurnReport
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.defaults import load_world
from drivetwin.worlds.scene import Scene

REFERENCE_PLANNER = "reference"
# Fingerprints round poses to this many decimals (0.1 m, ~0.06 rad): jitter below that is
# the same scene to a person looking at it.
FINGERPRINT_DECIMALS = 1


class ScriptedPlanner:
    """Plans by replaying fixed calls: the setup turns of a case."""

    name = "script"

    def __init__(self, calls: list[ToolCall]) -> None:
        self.calls = calls

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        return Plan(calls=list(self.calls), planner=self.name, verbatim=True)


class ReferencePlanner:
    """Plans each prompt of a case with the case's own reference calls; proves a case passable."""

    name = REFERENCE_PLANNER

    def __init__(self, case: Case) -> None:
        self._calls = {step.prompt: step.calls for step in case.setup}
        self._calls[case.prompt] = case.reference

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        if prompt not in self._calls:
            raise PlanningError(f"the reference planner has no plan for {prompt!r}")
        return Plan(calls=list(self._calls[prompt]), planner=self.name, prompt_version="reference", verbatim=True)


@cache
def _world_json(name: str) -> str:
    text: str = load_world(name).model_dump_json()
    return text


def fresh_world(name: str) -> Scene:
    """A fresh copy of a world; the file is read once per process."""
    return Scene.model_validate_json(_world_json(name))


def _rounded(value: Any) -> Any:
    if isinstance(value, float):
        rounded = round(value, FINGERPRINT_DECIMALS)
        return 0.0 if rounded == 0 else rounded  # -0.0 and 0.0 are the same place
    if isinstance(value, dict):
        return {k: _rounded(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [_rounded(v) for v in value]
    return value


def scene_fingerprint(scene: Scene) -> str:
    """A digest of what a person would see: categories, rounded poses, behaviours, looks, weather.

    Asset ids are left out, so two plans that add the same things in another order agree.
    """
    assets = sorted(
        json.dumps(
            _rounded(a.model_dump(include={"category", "pose", "scale", "behaviour", "appearance"})),
            sort_keys=True,
        )
        for a in scene.all_assets()
    )
    env = json.dumps(_rounded(scene.environment.model_dump()), sort_keys=True)
    return hashlib.sha256("\n".join([*assets, env]).encode()).hexdigest()[:16]


def _levels(plan: Plan | None) -> dict[str, float]:
    levels: dict[str, float] = {}
    for step in plan.trace if plan else []:
        levels[step.level] = levels.get(step.level, 0.0) + step.seconds
    return levels


def run_trial(case: Case, planner: Planner, trial: int, registry: ToolRegistry | None = None) -> TrialRecord:
    """Run one trial of `case` with `planner` from a fresh copy of its world."""
    started = time.perf_counter()
    under_test: Planner = ReferencePlanner(case) if planner.name == REFERENCE_PLANNER else planner
    session = Session(fresh_world(case.world), under_test, registry)
    record = TrialRecord(
        case_id=case.id,
        trial=trial,
        task=case.task,
        grade=case.grade,
        outcome="error",
        planner=planner.name,
    )
    try:
        for number, step in enumerate(case.setup, start=1):
            session.planner = under_test if step.planned else ScriptedPlanner(step.calls)
            turn = session.submit(step.prompt)
            if not turn.ok:
                # A replayed step that fails is a broken case; a planned one is the planner's.
                record.outcome = "fail" if step.planned else "error"
                record.result = ("asked" if turn.question is not None else "refused") if step.planned else "error"
                record.error = f"setup turn {number} ({step.prompt!r}) failed: {turn.error}"
                return _finish(record, started)
        before = session.scene
        session.planner = under_test
        report = session.submit(case.prompt)
    except Exception as exc:  # a crashing planner is recorded, not fatal to the run
        record.error = f"{type(exc).__name__}: {exc}"
        return _finish(record, started)
    outcome = CaseOutcome(before, session.scene, report.ok, report.answer or "", report.error, tuple(report.results))
    passed, results = case.judge(outcome)
    _fill(record, report, passed)
    record.failed_checks = [FailedCheck(kind=r.kind, reason=r.reason) for r in results if not r.passed]
    record.fingerprint = scene_fingerprint(session.scene)
    return _finish(record, started)


def _fill(record: TrialRecord, report: TurnReport, passed: bool) -> None:
    plan = report.plan
    asked = report.question is not None
    record.outcome = "pass" if passed and not asked else "fail"
    record.result = "asked" if asked else "passed" if passed else "refused" if not report.ok else "wrong"
    record.accepted = report.ok
    if asked and report.question is not None:
        record.answer = report.question.text[:500]
    record.error = report.error
    record.answer = record.answer or (report.answer or "")[:500]
    record.latency_s = report.seconds
    record.latency_levels = _levels(plan)
    if plan is not None:
        record.calls = [c.model_dump() for c in plan.calls]
        record.retries = plan.retries
        record.tokens = plan.tokens
        record.prompt_version = plan.prompt_version
        record.confidence = plan.confidence
        record.path = _path(plan)
        record.trace = [f"{t.level}: {t.output}"[-TRACE_CHARS:] for t in plan.trace]


def _path(plan: Plan) -> str | None:
    # A combining planner names the path it took in its first trace step ("path: agree").
    first = plan.trace[0].input if plan.trace else ""
    return first.removeprefix("path: ") if first.startswith("path: ") else None


def _finish(record: TrialRecord, started: float) -> TrialRecord:
    record.wall_s = time.perf_counter() - started
    return record
