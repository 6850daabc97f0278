"""The practice suite (a second development suite): valid, big enough in every cell, and passable.

Passable means each case's own reference calls, replayed through a real Session by the
`reference` planner, build an outcome that all its checks accept.
"""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import pytest
from drivetwin.evals import run_suite
from drivetwin.evals.case import GRADES, TASKS, Suite, load_suite
from drivetwin.evals.practice_source import CASES, JSONL_PATH

# The brief's minimums for this suite.
MIN_CASES = 240
MIN_PER_CELL = 8
MIN_MULTI_TURN = 20
MIN_PLANNED = 10
MIN_COMPOUND = 20
# Impossible requests should be about 8 % of the suite: refusals are a real outcome, not the norm.
IMPOSSIBLE_SHARE = (0.06, 0.11)


@pytest.fixture(scope="module")
def suite() -> Suite:
    return load_suite(JSONL_PATH)


def test_the_jsonl_is_what_the_source_writes() -> None:
    written = [json.loads(line) for line in JSONL_PATH.read_text(encoding="utf-8").splitlines() if line.strip()]
    assert written == CASES


def test_the_suite_holds_enough_cases_in_every_task_and_grade(suite: Suite) -> None:
    assert len(suite.cases) >= MIN_CASES
    cells = Counter((c.task, c.grade) for c in suite.cases)
    thin = {cell: cells[cell] for cell in ((t, g) for t in TASKS for g in GRADES) if cells[cell] < MIN_PER_CELL}
    assert not thin


def test_every_case_is_named_and_tagged_practice(suite: Suite) -> None:
    assert all(c.id.startswith(f"practice.{c.task}.{c.grade}.") and "practice" in c.tags for c in suite.cases)


def test_multi_turn_cases_have_earlier_turns_and_some_are_planned(suite: Suite) -> None:
    multi = [c for c in suite.cases if "multi_turn" in c.tags]
    assert len(multi) >= MIN_MULTI_TURN
    assert all(c.setup for c in multi)
    assert sum(any(s.planned and s.calls for s in c.setup) for c in multi) >= MIN_PLANNED


def test_enough_cases_ask_two_things_at_once(suite: Suite) -> None:
    assert sum("compound" in c.tags for c in suite.cases) >= MIN_COMPOUND


def test_impossible_requests_expect_a_refusal_that_changes_nothing(suite: Suite) -> None:
    impossible = [c for c in suite.cases if "impossible" in c.tags]
    low, high = IMPOSSIBLE_SHARE
    assert low <= len(impossible) / len(suite.cases) <= high
    for c in impossible:
        kinds = {(chk.kind, getattr(chk, "accepted", None)) for chk in c.checks}
        assert ("status", False) in kinds and ("unchanged_except", None) in kinds, c.id


def test_every_case_guards_against_collateral_edits(suite: Suite) -> None:
    assert all(any(chk.kind == "unchanged_except" for chk in c.checks) for c in suite.cases)


def test_every_reference_plan_passes(tmp_path: Path) -> None:
    out = tmp_path / "practice_reference.jsonl"
    summary = run_suite(JSONL_PATH, "reference", out_path=out, workers=1, progress=False)
    failed = []
    for line in out.read_text(encoding="utf-8").splitlines()[1:]:
        record = json.loads(line)
        if record["outcome"] != "pass":
            failed.append((record["case_id"], record.get("error"), record.get("failed_checks")))
    assert not failed
    assert summary.complete and summary.passed == len(CASES)
