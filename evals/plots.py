"""PNG plots of one or more runs: per-task bars, grade degradation curves, latency spread.

Needs matplotlib (the `eval` extra); `plots_available()` says whether it is there.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from drivetwin.evals.case import GRADES, TASKS
from drivetwin.evals.metrics import Rate, RunMetrics

DPI = 120  # sharp enough for a README, small enough to commit


def plots_available() -> bool:
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return False
    return True


def _errors(rates: Sequence[Rate]) -> list[list[float]]:
    # Clamped at 0: at 0 % or 100 % rounding can put a bound a hair inside the value.
    return [
        [max(0.0, 100 * (r.value - r.low)) if r.n else 0.0 for r in rates],
        [max(0.0, 100 * (r.high - r.value)) if r.n else 0.0 for r in rates],
    ]


def _values(rates: Sequence[Rate]) -> list[float]:
    """Percentages, NaN (not drawn) where a cell has no trials."""
    return [100 * r.value if r.n else float("nan") for r in rates]


def plot_tasks(runs: Sequence[RunMetrics], target: Path) -> Path:
    """Grouped bars: success rate per task for each run, with Wilson 95 % intervals."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(9, 4))
    width = 0.8 / max(1, len(runs))
    for i, run in enumerate(runs):
        rates = [run.per_task[t] for t in TASKS]
        xs = [k + (i - (len(runs) - 1) / 2) * width for k in range(len(TASKS))]
        ax.bar(xs, _values(rates), width, yerr=_errors(rates), capsize=2, label=run.label)
    ax.set_xticks(range(len(TASKS)), TASKS)
    ax.set_ylabel("success rate (%)")
    ax.set_ylim(0, 105)
    ax.set_title("Success per task (Wilson 95 % intervals)")
    # Below the axes: inside, the legend would hide bars.
    ax.legend(fontsize="small", loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=min(4, max(1, len(runs))))
    fig.tight_layout()
    fig.savefig(target, dpi=DPI)
    plt.close(fig)
    return target


def plot_grades(runs: Sequence[RunMetrics], target: Path) -> Path:
    """Lines: success rate from direct to erroneous prompts, one line per run."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4))
    for run in runs:
        rates = [run.per_grade[g] for g in GRADES]
        ax.errorbar(
            range(len(GRADES)),
            [100 * r.value for r in rates],
            yerr=_errors(rates),
            marker="o",
            capsize=3,
            label=run.label,
        )
    ax.set_xticks(range(len(GRADES)), GRADES)
    ax.set_ylabel("success rate (%)")
    ax.set_ylim(0, 105)
    ax.set_title("Degradation with prompt grade")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(target, dpi=DPI)
    plt.close(fig)
    return target


def plot_latency(labels: Sequence[str], seconds: Sequence[Sequence[float]], target: Path) -> Path:
    """Box plots of seconds per prompt, one box per run (log scale: planners differ 1000-fold)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    data = [list(s) if s else [float("nan")] for s in seconds]
    ax.boxplot(data, whis=(5, 95), showfliers=True)
    ax.set_xticks(range(1, len(labels) + 1), labels, rotation=15)
    ax.set_yscale("log")
    ax.set_ylabel("seconds per prompt")
    ax.set_title("Latency (whiskers: 5th-95th percentile)")
    fig.tight_layout()
    fig.savefig(target, dpi=DPI)
    plt.close(fig)
    return target
