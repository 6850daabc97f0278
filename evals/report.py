"""Reports of one or more runs: Markdown and JSON in the paper's Table 4 and Table 5 layouts, and PNGs.

`write_report` is what `drivetwin eval report RUN...` calls. Several runs are compared
side by side, with the paper's published figures as a reference row.
"""

from __future__ import annotations

import datetime as dt
import json
from collections.abc import Sequence
from pathlib import Path

from drivetwin.evals.case import GRADES, TASKS
from drivetwin.evals.metrics import Rate, RunMetrics, compute_metrics
from drivetwin.evals.plots import plot_grades, plot_latency, plot_tasks, plots_available
from drivetwin.evals.records import read_run
from pydantic import BaseModel


class PaperRow(BaseModel):
    """A row of the paper's Table 4, as published (percentages and seconds per prompt)."""

    model: str
    parameters: str
    generalizability: float
    repeatability: float
    seconds: float


# Samak et al., "When Digital Twins Meet Large Language Models", Table 4.
PAPER_TABLE4: tuple[PaperRow, ...] = (
    PaperRow(model="Mistral 0.2", parameters="7B", generalizability=46.21, repeatability=92.65, seconds=6.60),
    PaperRow(model="Llama 3.1", parameters="8B", generalizability=82.43, repeatability=89.38, seconds=7.52),
    PaperRow(model="Gemma 2", parameters="9B", generalizability=84.93, repeatability=94.86, seconds=8.45),
)


class ReportError(ValueError):
    """Nothing to report (no runs given)."""


def pct(rate: Rate | None, ci: bool = True) -> str:
    """A rate as '84.9 % [80.1–88.6] (n=280)', or '—' when there is none."""
    if rate is None or rate.n == 0:
        return "—"
    text = f"{100 * rate.value:.1f} %"
    if ci:
        text += f" [{100 * rate.low:.1f}–{100 * rate.high:.1f}]"
    return text


def _size(n_bytes: int | None) -> str:
    if n_bytes is None:
        return "—"
    for unit, scale in (("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if n_bytes >= scale:
            return f"{n_bytes / scale:.1f} {unit}"
    return f"{n_bytes} B"


def _params(count: int | None) -> str:
    if count is None:
        return "—"
    for unit, scale in (("B", 1e9), ("M", 1e6), ("k", 1e3)):
        if count >= scale:
            return f"{count / scale:.3g}{unit}"
    return str(count)


def _secs(value: float | None) -> str:
    if value is None:
        return "—"
    return f"{value:.2f} s" if value >= 0.1 else f"{1000 * value:.1f} ms"


def _only(m: RunMetrics) -> str:
    return f", only {'/'.join(m.only)}" if m.only else ""


def table4(runs: Sequence[RunMetrics], paper: bool = True) -> list[str]:
    """Markdown lines of Table 4: one row per planner/model."""
    lines = [
        "| Planner / model | Size | Parameters | Generalizability | Repeatability | Time (median) | Time (p95) |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    for m in runs:
        size = _size(m.model.size_bytes if m.model else None)
        params = _params(m.model.parameters if m.model else None)
        lines.append(
            f"| {m.label} | {size} | {params} | {pct(m.generalizability)} "
            f"| {pct(m.repeatability)} | {_secs(m.latency.median)} | {_secs(m.latency.p95)} |"
        )
    if paper:
        for row in PAPER_TABLE4:
            lines.append(
                f"| *paper: {row.model}* | — | {row.parameters} | {row.generalizability:.2f} % "
                f"| {row.repeatability:.2f} % | {row.seconds:.2f} s (mean) | — |"
            )
    return lines


def table5(run: RunMetrics) -> list[str]:
    """Markdown lines of Table 5 for one run: success per task × grade, with overall margins."""
    lines = [
        "| Task | " + " | ".join(GRADES) + " | all grades |",
        "| --- | " + " | ".join("---" for _ in GRADES) + " | --- |",
    ]
    for task in TASKS:
        cells = [pct(run.per_cell[task][g], ci=False) for g in GRADES]
        lines.append(f"| {task} | " + " | ".join(cells) + f" | {pct(run.per_task[task])} |")
    margins = [pct(run.per_grade[g], ci=False) for g in GRADES]
    lines.append("| **all tasks** | " + " | ".join(margins) + f" | {pct(run.generalizability)} |")
    return lines


def _pass_k(runs: Sequence[RunMetrics]) -> list[str]:
    ks = sorted({k for m in runs for k in m.pass_hat_k})
    if not ks or ks == [1]:
        return []
    lines = [
        "| Planner / model | " + " | ".join(f"pass^{k}" for k in ks) + " |",
        "| --- | " + " | ".join("---" for _ in ks) + " |",
    ]
    for m in runs:
        cells = [f"{100 * m.pass_hat_k[k]:.1f} %" if k in m.pass_hat_k else "—" for k in ks]
        lines.append(f"| {m.label} | " + " | ".join(cells) + " |")
    return lines


def outcomes_table(runs: Sequence[RunMetrics]) -> list[str]:
    """Passed / asked / refused / wrong per run with Wilson intervals (README-ready Markdown)."""
    lines = [
        "| Planner / model | Suite | Passed | Asked | Refused | Wrong |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for m in runs:
        cells = [pct(m.outcomes.get(k)) for k in ("passed", "asked", "refused", "wrong")]
        lines.append(f"| {m.label} | {m.suite}{_only(m)} | " + " | ".join(cells) + " |")
    return lines


def render_markdown(runs: Sequence[RunMetrics], plots: Sequence[Path] = ()) -> str:
    """The whole report as Markdown."""
    out = [
        "# drivetwin eval report",
        "",
        f"Written {dt.datetime.now(dt.UTC).isoformat(timespec='seconds')}. Rates are shares of "
        "trials that passed every check, with Wilson 95 % intervals in brackets. Repeatability "
        "is the paper's: the share of a direct prompt's trials that build the same scene.",
        "",
        "## Runs",
        "",
        "| Label | Planner | Suite | Cases × trials | Errors | Started | Commit |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    for m in runs:
        options = f" `{json.dumps(m.planner_options)}`" if m.planner_options else ""
        out.append(
            f"| {m.label} | {m.planner}{options} | {m.suite} ({m.suite_digest}){_only(m)} "
            f"| {m.cases} × {m.trials_per_case} | {m.errors} | {m.started} | {m.git_commit or '—'} |"
        )
    out += ["", "## Outcomes: passed, asked, refused, wrong (accepted but failing a check)", "",
            *outcomes_table(runs), ""]
    out += ["## Table 4: planners and models", "", *table4(runs), ""]
    for m in runs:
        out += [f"## Table 5: {m.label}, success per task and grade", "", *table5(m), ""]
    pk = _pass_k(runs)
    if pk:
        out += ["## pass^k (tau-bench): chance that k trials of a case all pass", "", *pk, ""]
    out += ["## Where trials failed (failed checks by kind)", ""]
    for m in runs:
        kinds = ", ".join(f"{k} {v}" for k, v in m.failed_check_kinds.items()) or "none"
        out.append(f"- {m.label}: {kinds}")
    if plots:
        out += ["", "## Plots", ""] + [f"![{p.stem}]({p.name})" for p in plots]
    return "\n".join(out) + "\n"


def write_report(run_paths: Sequence[str | Path], out_dir: str | Path) -> list[Path]:
    """Write report.md, report.json and PNG plots for the runs into `out_dir`; return the paths."""
    if not run_paths:
        raise ReportError("give at least one records file to report on")
    runs = [read_run(p) for p in run_paths]
    metrics = [compute_metrics(r) for r in runs]
    target = Path(out_dir)
    target.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    plots: list[Path] = []
    if plots_available():
        plots.append(plot_tasks(metrics, target / "per_task.png"))
        plots.append(plot_grades(metrics, target / "grades.png"))
        seconds = [[r.latency_s for r in run.records if r.latency_s is not None] for run in runs]
        plots.append(plot_latency([m.label for m in metrics], seconds, target / "latency.png"))
    md = target / "report.md"
    md.write_text(render_markdown(metrics, plots), encoding="utf-8")
    data = {
        "runs": [m.model_dump(mode="json") for m in metrics],
        "paper_table4": [row.model_dump() for row in PAPER_TABLE4],
        "sources": [str(Path(p)) for p in run_paths],
    }
    js = target / "report.json"
    js.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    written += [md, js, *plots]
    return written
