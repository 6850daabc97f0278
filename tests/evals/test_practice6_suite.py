"""The sixth practice suite (practice6): valid, big enough in every cell, written from its source, and
passable. Written to its own brief's minimums: new voices, weighted toward the vague and indirect grades."""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest
from drivetwin.evals import practice6_source, run_suite
from drivetwin.evals.case import GRADES, TASKS, Suite, load_suite

MIN_CASES, MIN_PER_CELL = 140, 5
MIN_MULTI_TURN, MIN_PLANNED, MIN_COMPOUND = 12, 6, 12
# About 8 % of the cases ask for what the world cannot do; the right outcome is a refusal.
IMPOSSIBLE_SHARE = (0.06, 0.11)
# The brief weights the suite toward the grades where wording differs most from a catalog name.
WEIGHTED_GRADES = ("vague", "indirect")


@pytest.fixture(scope="module")
def suite() -> Suite:
    return load_suite("practice6")


def test_every_line_validates_and_ids_and_tags_name_the_suite(suite: Suite) -> None:
    assert len(suite.cases) >= MIN_CASES
    assert all(c.id.startswith("practice6.") and "practice6" in c.tags for c in suite.cases)


def test_the_jsonl_is_what_the_source_writes() -> None:
    text = Path(practice6_source.SUITE_PATH).read_text(encoding="utf-8")
    assert [json.loads(line) for line in text.splitlines() if line.strip()] == practice6_source.ALL_CASES


def test_every_task_and_grade_cell_holds_its_minimum(suite: Suite) -> None:
    cells = Counter((c.task, c.grade) for c in suite.cases)
    for task in TASKS:
        for grade in GRADES:
            assert cells[(task, grade)] >= MIN_PER_CELL, (task, grade, cells[(task, grade)])


def test_the_vague_and_indirect_grades_outnumber_the_direct_one(suite: Suite) -> None:
    grades = Counter(c.grade for c in suite.cases)
    assert all(grades[g] > grades["direct"] for g in WEIGHTED_GRADES), grades


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


def test_every_case_guards_against_collateral_edits(suite: Suite) -> None:
    assert all(any(check.kind == "unchanged_except" for check in c.checks) for c in suite.cases)


def test_every_reference_plan_passes(tmp_path: Path) -> None:
    summary = run_suite(practice6_source.SUITE_PATH, "reference", out_path=tmp_path / "ref.jsonl", progress=False)
    records = [json.loads(line) for line in (tmp_path / "ref.jsonl").read_text().splitlines()[1:]]
    not_passed = [(r["case_id"], r.get("failed_checks"), r.get("error")) for r in records if r.get("outcome") != "pass"]
    assert summary.complete and summary.failed == 0 and summary.errors == 0, not_passed[:5]
    assert summary.passed == len(practice6_source.ALL_CASES)
