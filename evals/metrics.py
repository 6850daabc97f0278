"""Metrics of a run, computed only from its records file.

- generalizability: the share of trials that pass, over all grades, and per task × grade
  (the paper's Table 5);
- repeatability (the paper's): for each direct-grade case, the share of its trials whose
  resulting scene equals the case's most common one, pooled over direct cases;
- pass^k (tau-bench): the chance that k independent trials of a case all pass, averaged
  over cases, estimated without bias as C(c, k) / C(n, k) for c passes in n trials;
- latency median and p95 per prompt and per planning level; tokens and retries;
- outcomes: the share of trials passed, asked (a clarifying question), refused, wrong
  (accepted but failing a check: the worst) and crashed.

Rates carry Wilson 95 % intervals so that a small suite is not over-read.
"""

from __future__ import annotations

import math
from collections import Counter, defaultdict
from collections.abc import Iterable, Sequence

import numpy as np
from drivetwin.evals.case import GRADES, TASKS
from drivetwin.evals.records import RESULTS, ModelFacts, Run, TrialRecord
from pydantic import BaseModel, Field

# z for a two-sided 95 % interval.
Z_95 = 1.959963984540054


def wilson(successes: int, n: int, z: float = Z_95) -> tuple[float, float]:
    """The Wilson score interval of a proportion (0, 1 when there are no trials)."""
    if n == 0:
        return (0.0, 1.0)
    p = successes / n
    denom = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denom
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom
    return (max(0.0, centre - half), min(1.0, centre + half))


class Rate(BaseModel):
    """A proportion with its count and Wilson 95 % interval."""

    successes: int
    n: int
    value: float
    low: float
    high: float

    @classmethod
    def of(cls, successes: int, n: int) -> Rate:
        lo, hi = wilson(successes, n)
        return cls(successes=successes, n=n, value=successes / n if n else 0.0, low=lo, high=hi)


class Latency(BaseModel):
    """Seconds per prompt: how many were timed, median, 95th percentile and mean."""

    n: int
    median: float | None
    p95: float | None
    mean: float | None

    @classmethod
    def of(cls, seconds: Sequence[float]) -> Latency:
        if not seconds:
            return cls(n=0, median=None, p95=None, mean=None)
        arr = np.asarray(seconds, dtype=float)
        return cls(
            n=len(arr),
            median=float(np.median(arr)),
            p95=float(np.percentile(arr, 95)),
            mean=float(arr.mean()),
        )


class RunMetrics(BaseModel):
    """Everything a report shows about one run."""

    label: str
    planner: str
    planner_options: dict[str, object] = Field(default_factory=dict)
    suite: str
    suite_digest: str
    # The grades/tasks the run was limited to; empty: the whole suite.
    only: list[str] = Field(default_factory=list)
    started: str
    git_commit: str | None
    model: ModelFacts | None
    trials_per_case: int
    records: int
    cases: int
    errors: int
    generalizability: Rate
    per_task: dict[str, Rate]
    per_grade: dict[str, Rate]
    per_cell: dict[str, dict[str, Rate]]
    repeatability: Rate | None
    pass_hat_k: dict[int, float]
    latency: Latency
    latency_levels: dict[str, Latency]
    mean_tokens: float
    mean_retries: float
    failed_check_kinds: dict[str, int]
    # Share of trials per outcome class (passed, asked, refused, wrong, error), with intervals.
    outcomes: dict[str, Rate] = Field(default_factory=dict)


def _rate(records: Iterable[TrialRecord]) -> Rate:
    rows = list(records)
    return Rate.of(sum(r.outcome == "pass" for r in rows), len(rows))


def repeatability(records: Sequence[TrialRecord]) -> Rate | None:
    """Share of direct-grade trials that built their case's modal scene; None below 2 trials."""
    by_case: dict[str, list[str]] = defaultdict(list)
    for r in records:
        if r.grade == "direct":
            # A crashed trial built no scene: it counts as a scene of its own.
            by_case[r.case_id].append(r.fingerprint or f"error-{r.trial}")
    same = total = 0
    for prints in by_case.values():
        if len(prints) < 2:
            continue
        same += Counter(prints).most_common(1)[0][1]
        total += len(prints)
    return Rate.of(same, total) if total else None


def pass_hat_k(records: Sequence[TrialRecord]) -> dict[int, float]:
    """tau-bench's pass^k for k = 1 .. the fewest trials any case has."""
    by_case: dict[str, list[bool]] = defaultdict(list)
    for r in records:
        by_case[r.case_id].append(r.outcome == "pass")
    if not by_case:
        return {}
    fewest = min(len(v) for v in by_case.values())
    out: dict[int, float] = {}
    for k in range(1, fewest + 1):
        vals = [math.comb(sum(v), k) / math.comb(len(v), k) for v in by_case.values()]
        out[k] = float(sum(vals) / len(vals))
    return out


def compute_metrics(run: Run) -> RunMetrics:
    """All metrics of a run, from its header and records only."""
    recs = run.records
    h = run.header
    cell: dict[str, dict[str, Rate]] = {}
    for task in TASKS:
        row: dict[str, Rate] = {g: _rate(r for r in recs if r.task == task and r.grade == g) for g in GRADES}
        cell[task] = row
    levels: dict[str, list[float]] = defaultdict(list)
    for r in recs:
        for level, secs in r.latency_levels.items():
            levels[level].append(secs)
    failed = Counter(fc.kind for r in recs for fc in r.failed_checks)
    failed.update("error" for r in recs if r.outcome == "error")
    model = next((r.model for r in recs if r.model is not None), None)
    trials = Counter(r.case_id for r in recs)
    return RunMetrics(
        label=h.label or _default_label(h.planner, h.planner_options, model) + (f" [{'/'.join(h.only)} only]" if h.only else ""),
        planner=h.planner,
        planner_options=dict(h.planner_options),
        suite=h.suite,
        suite_digest=h.suite_digest,
        only=list(h.only),
        started=h.started,
        git_commit=h.git_commit,
        model=model,
        trials_per_case=max(trials.values(), default=0),
        records=len(recs),
        cases=len(trials),
        errors=sum(r.outcome == "error" for r in recs),
        generalizability=_rate(recs),
        per_task={t: _rate(r for r in recs if r.task == t) for t in TASKS},
        per_grade={g: _rate(r for r in recs if r.grade == g) for g in GRADES},
        per_cell=cell,
        repeatability=repeatability(recs),
        pass_hat_k=pass_hat_k(recs),
        latency=Latency.of([r.latency_s for r in recs if r.latency_s is not None]),
        latency_levels={k: Latency.of(v) for k, v in sorted(levels.items())},
        mean_tokens=float(np.mean([r.tokens for r in recs])) if recs else 0.0,
        mean_retries=float(np.mean([r.retries for r in recs])) if recs else 0.0,
        failed_check_kinds=dict(failed.most_common()),
        outcomes=outcome_rates(recs),
    )


def outcome_rates(records: Sequence[TrialRecord]) -> dict[str, Rate]:
    """passed / asked / refused / wrong / error, each as a share of all trials with its interval."""
    counts: Counter[str] = Counter(r.result_class for r in records)
    return {name: Rate.of(counts.get(name, 0), len(records)) for name in RESULTS}


def _default_label(planner: str, options: dict[str, object], model: ModelFacts | None) -> str:
    if model is not None and model.name:
        return f"{planner} ({model.name})"
    extra = options.get("model") or options.get("backend")
    return f"{planner} ({extra})" if extra else planner
