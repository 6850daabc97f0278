"""Outcome classes of eval records (passed, asked, refused, wrong) with Wilson rates, and the
early stop of a run whose planner or model cannot start."""

from __future__ import annotations

import pytest
from drivetwin.evals.metrics import outcome_rates, wilson
from drivetwin.evals.records import TrialRecord
from drivetwin.evals.runner import RunError, run_suite


def record(outcome: str, accepted: bool | None, result: str | None = None) -> TrialRecord:
    return TrialRecord(case_id=f"c{id(object())}", trial=0, task="addition", grade="direct",
                       outcome=outcome, accepted=accepted, result=result)


def test_a_failed_but_accepted_record_is_wrong_and_a_refused_one_is_refused():
    assert record("fail", True).result_class == "wrong"
    assert record("fail", False).result_class == "refused"
    assert record("fail", False, "asked").result_class == "asked"
    assert record("pass", True).result_class == "passed"


def test_outcome_rates_share_every_trial_with_a_wilson_interval():
    records = [record("pass", True)] * 6 + [record("fail", True)] * 2 + [record("fail", False, "asked")] * 2
    rates = outcome_rates(records)
    assert rates["passed"].value == pytest.approx(0.6) and rates["wrong"].successes == 2
    assert (rates["asked"].low, rates["asked"].high) == pytest.approx(wilson(2, 10))


def test_an_unknown_model_stops_the_run_before_the_first_case(tmp_path):
    out = tmp_path / "run.jsonl"
    with pytest.raises(RunError, match="nosuchmodel"):
        run_suite("smoke", "llm", planner_options={"model": "nosuchmodel"}, out_path=out, progress=False)
    assert not out.exists()


def test_an_option_the_rules_planner_does_not_take_stops_the_run(tmp_path):
    with pytest.raises(RunError, match="takes no options"):
        run_suite("smoke", "rules", planner_options={"temperature": 0.2}, out_path=tmp_path / "r.jsonl",
                  progress=False)
