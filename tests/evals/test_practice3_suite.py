"""The third practice suite (practice3): valid, big enough in every cell, written from its source, and passable."""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest
from drivetwin.evals import run_suite
from drivetwin.evals.case import Suite, load_suite
from drivetwin.evals.practice3_source import ALL_CASES, SUITE_PATH

TASKS = ("search", "addition", "removal", "positioning", "moving", "arrangement", "appearance")
GRADES = ("direct", "indirect", "vague", "erroneous")
# The brief's minimums: every cell >= 6, the four weighted tasks >= 9 in every grade.
WEIGHTED_TASKS = ("search", "addition", "positioning", "arrangement")
MIN_PER_CELL, MIN_PER_WEIGHTED_CELL = 6, 9
MIN_CASES, MIN_MULTI_TURN, MIN_PLANNED, MIN_COMPOUND = 200, 15, 8, 15
# About 8 % of the cases ask for what the world cannot do; the right outcome is a refusal.
IMPOSSIBLE_SHARE = (0.06, 0.11)


@pytest.fixture(scope="module")
def suite() -> Suite:
    return load_suite("practice3")


def test_every_line_validates_and_ids_and_tags_name_the_suite(suite: Suite) -> None:
    assert len(suite.cases) >= MIN_CASES
    assert all(c.id.startswith("practice3.") and "practice3" in c.tags for c in suite.cases)


def test_the_jsonl_is_what_the_source_writes() -> None:
    lines = [json.loads(line) for line in Path(SUITE_PATH).read_text(encoding="utf-8").splitlines() if line.strip()]
    assert lines == ALL_CASES


def test_every_task_and_grade_cell_holds_its_minimum(suite: Suite) -> None:
    cells = Counter((c.task, c.grade) for c in suite.cases)
    for task in TASKS:
        least = MIN_PER_WEIGHTED_CELL if task in WEIGHTED_TASKS else MIN_PER_CELL
        for grade in GRADES:
            assert cells[(task, grade)] >= least, (task, grade, cells[(task, grade)])


def test_multi_turn_cases_have_earlier_turns_and_enough_are_planned(suite: Suite) -> None:
    multi = [c for c in suite.cases if "multi_turn" in c.tags]
    assert len(multi) >= MIN_MULTI_TURN and all(c.setup for c in multi)
    planned = [c for c in multi if any(step.planned and step.calls for step in c.setup)]
    assert len(planned) >= MIN_PLANNED


def test_compound_cases_ask_two_things(suite: Suite) -> None:
    compound = [c for c in suite.cases if "compound" in c.tags]
    assert len(compound) >= MIN_COMPOUND
    assert all(len(c.reference) >= 2 for c in compound)


def test_impossible_cases_expect_a_refusal_that_changes_nothing(suite: Suite) -> None:
    impossible = [c for c in suite.cases if "impossible" in c.tags]
    low, high = IMPOSSIBLE_SHARE
    assert low <= len(impossible) / len(suite.cases) <= high
    for c in impossible:
        kinds = {(check.kind, getattr(check, "accepted", None)) for check in c.checks}
        assert ("status", False) in kinds and ("unchanged_except", None) in kinds, c.id


def test_every_edit_case_guards_against_collateral_edits(suite: Suite) -> None:
    assert all(any(check.kind == "unchanged_except" for check in c.checks) for c in suite.cases)


def test_every_reference_plan_passes(tmp_path: Path) -> None:
    summary = run_suite(SUITE_PATH, "reference", out_path=tmp_path / "ref.jsonl", progress=False)
    failed = [json.loads(line) for line in (tmp_path / "ref.jsonl").read_text().splitlines()[1:]]
    not_passed = [(r["case_id"], r.get("failed_checks"), r.get("error")) for r in failed if r.get("outcome") != "pass"]
    assert summary.complete and summary.failed == 0 and summary.errors == 0, not_passed[:5]
    assert summary.passed == len(ALL_CASES)
