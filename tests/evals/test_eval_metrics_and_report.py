"""Metrics computed from records (Wilson, pass^k, repeatability) and the reports made of them."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner
from drivetwin.evals.metrics import compute_metrics, pass_hat_k, wilson
from drivetwin.evals.records import TrialRecord, read_run
from drivetwin.evals.report import ReportError, write_report
from drivetwin.evals.runner import run_suite
from drivetwin.orchestrator.cli import main
from tiny_planner import TINY_CASES, write_suite

TINY = "tiny_planner:make"
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def test_wilson_interval_matches_the_textbook_values() -> None:
    low, high = wilson(8, 10)
    assert low == pytest.approx(0.4902, abs=1e-4) and high == pytest.approx(0.9433, abs=1e-4)
    assert wilson(0, 0) == (0.0, 1.0)
    assert wilson(5, 5)[1] == 1.0 and wilson(0, 5)[0] == 0.0


def _record(case: str, trial: int, passed: bool) -> TrialRecord:
    return TrialRecord(case_id=case, trial=trial, task="search", grade="direct", outcome="pass" if passed else "fail")


def test_pass_hat_k_is_the_chance_that_k_trials_of_a_case_all_pass() -> None:
    records = [_record("a", t, True) for t in range(3)]
    records += [_record("b", 0, True), _record("b", 1, False), _record("b", 2, False)]
    got = pass_hat_k(records)
    assert got[1] == pytest.approx((1 + 1 / 3) / 2)
    assert got[2] == pytest.approx(0.5) and got[3] == pytest.approx(0.5)


def test_repeatability_is_the_share_of_direct_trials_that_build_the_modal_scene(tmp_path: Path) -> None:
    suite = write_suite(tmp_path / "cones.jsonl", [c for c in TINY_CASES if c["id"] == "cones"])
    out = tmp_path / "flaky.jsonl"
    # Every second plan adds four cones instead of three: two different scenes in four trials.
    run_suite(suite, TINY, planner_options={"flip_every": 2}, trials=4, out_path=out, progress=False)
    metrics = compute_metrics(read_run(out))
    assert metrics.repeatability is not None
    assert (metrics.repeatability.successes, metrics.repeatability.n) == (2, 4)
    assert metrics.generalizability.value == pytest.approx(0.5)
    steady = tmp_path / "steady.jsonl"
    run_suite(suite, TINY, trials=4, out_path=steady, progress=False)
    assert compute_metrics(read_run(steady)).repeatability.value == 1.0  # type: ignore[union-attr]


def test_metrics_split_success_by_task_and_grade(tiny_suite: Path, tmp_path: Path) -> None:
    out = tmp_path / "run.jsonl"
    run_suite(tiny_suite, TINY, trials=2, out_path=out, progress=False)
    m = compute_metrics(read_run(out))
    assert (m.per_cell["appearance"]["direct"].successes, m.per_cell["appearance"]["direct"].n) == (2, 4)
    assert m.per_cell["appearance"]["vague"].value == 1.0  # "make it foggy"
    assert m.per_cell["addition"]["erroneous"].value == 0.0
    assert m.generalizability.n == 16 and m.cases == 8 and m.trials_per_case == 2
    assert m.latency.median is not None and m.latency.p95 >= m.latency.median  # type: ignore[operator]
    assert m.model is not None and m.model.size_bytes == 1234
    assert m.failed_check_kinds["environment"] >= 2


def test_report_writes_table_4_table_5_json_and_plots_for_runs_side_by_side(tiny_suite: Path, tmp_path: Path) -> None:
    first, second = tmp_path / "a.jsonl", tmp_path / "b.jsonl"
    run_suite(tiny_suite, TINY, trials=2, out_path=first, progress=False, label="tiny A")
    run_suite(tiny_suite, "reference", trials=1, out_path=second, progress=False)
    written = write_report([first, second], tmp_path / "report")
    names = {p.name for p in written}
    assert {"report.md", "report.json", "per_task.png", "grades.png", "latency.png"} <= names
    md = (tmp_path / "report" / "report.md").read_text(encoding="utf-8")
    assert "| Planner / model | Size | Parameters | Generalizability | Repeatability" in md
    assert "| tiny A | 1.2 kB | 42 |" in md and "*paper: Gemma 2* | — | 9B | 84.93 %" in md
    assert "## Table 5: tiny A" in md and "| appearance | 50.0 % | — | 100.0 % | — |" in md
    data = json.loads((tmp_path / "report" / "report.json").read_text(encoding="utf-8"))
    assert [r["label"] for r in data["runs"]] == ["tiny A", "reference"]
    assert data["paper_table4"][0]["generalizability"] == 46.21
    for png in ("per_task.png", "grades.png", "latency.png"):
        assert (tmp_path / "report" / png).read_bytes()[:8] == PNG_MAGIC


def test_a_report_needs_at_least_one_run(tmp_path: Path) -> None:
    with pytest.raises(ReportError, match="at least one"):
        write_report([], tmp_path)


def test_eval_report_as_json_prints_the_figures_it_wrote(tiny_suite: Path, tmp_path: Path) -> None:
    run = tmp_path / "run.jsonl"
    run_suite(tiny_suite, TINY, trials=1, out_path=run, progress=False, label="tiny")
    result = CliRunner().invoke(main, ["eval", "report", str(run), "--out", str(tmp_path / "report"), "--json"])
    assert result.exit_code == 0, result.output
    printed = json.loads(result.output)
    written = json.loads((tmp_path / "report" / "report.json").read_text(encoding="utf-8"))
    assert printed["runs"] == written["runs"] and printed["runs"][0]["label"] == "tiny"
    assert str(tmp_path / "report" / "report.md") in printed["written"]
