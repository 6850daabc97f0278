"""The shipped suites: valid against the published schema, complete, and passable."""

from __future__ import annotations

import json
import subprocess
import sys
from collections import Counter
from pathlib import Path

import jsonschema
import pytest
from drivetwin.evals.case import GRADES, SCHEMA_PATH, SUITES_DIR, TASKS, SuiteError, load_suite
from drivetwin.evals.records import read_run
from drivetwin.evals.runner import run_suite
from drivetwin.evals.schema import render_schema
from drivetwin.evals.trial import fresh_world
from drivetwin.tools.locate import resolve_target

REPO = Path(__file__).resolve().parents[2]
# Issue: at least 10 cases in every task x grade cell.
MIN_PER_CELL = 10


def test_the_shipped_schema_file_is_the_one_the_case_model_generates() -> None:
    assert SCHEMA_PATH.read_text(encoding="utf-8") == render_schema()


@pytest.mark.parametrize("name", ["full", "smoke"])
def test_every_shipped_case_line_validates_against_the_published_schema(name: str) -> None:
    schema = json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))
    validator = jsonschema.Draft202012Validator(schema)
    lines = (SUITES_DIR / f"{name}.jsonl").read_text(encoding="utf-8").splitlines()
    for number, line in enumerate(lines, start=1):
        errors = list(validator.iter_errors(json.loads(line)))
        assert not errors, f"{name}.jsonl:{number}: {errors[0].message}"


def test_the_full_suite_has_ten_cases_in_every_task_and_grade_cell() -> None:
    suite = load_suite("full")
    cells = Counter((c.task, c.grade) for c in suite.cases)
    thin = {cell: n for cell in ((t, g) for t in TASKS for g in GRADES) if (n := cells[cell]) < MIN_PER_CELL}
    assert not thin
    assert len(suite.cases) >= len(TASKS) * len(GRADES) * MIN_PER_CELL


def test_the_full_suite_holds_the_papers_prompts_and_multi_turn_and_compound_cases() -> None:
    suite = load_suite("full")
    prompts = {c.prompt for c in suite.cases}
    for paper_prompt in (
        "make it rain",
        "make it foggy",
        "make it snow",
        "make it daytime",
        "make it night",
        "clear the weather",
        "create cement rubble at the centre of the scene",
        "add traffic cones to mark the maintenance",
        "also add road barriers around there",
        "add a parked car at the JTEKT building entrance",
        "add a mid-scale Ackermann-steered robot performing a skidpad maneuver",
        "make a jaywalking pedestrian cut across the ego vehicle's path",
    ):
        assert paper_prompt in prompts
    tags = Counter(t for c in suite.cases for t in c.tags)
    assert tags["multi_turn"] >= 20 and tags["compound"] >= 5
    assert any(step.planned for c in suite.cases for step in c.setup)


def test_every_target_a_check_names_is_a_place_in_the_campus_or_an_asset_a_case_makes() -> None:
    campus = fresh_world("campus")
    for case in load_suite("full").cases:
        for check in [*case.checks, *(c for alt in case.alternatives for c in alt)]:
            for name in (getattr(check, "target", None), getattr(check, "around", None)):
                if name is None or "_" in name:  # asset ids are made by the case's own setup
                    continue
                resolve_target(campus, name)  # raises NotFoundError on a typo


def test_the_reference_plans_pass_every_case_of_the_full_suite(tmp_path: Path) -> None:
    """Proves every case passable: its checks accept at least one real plan."""
    out = tmp_path / "reference.jsonl"
    summary = run_suite("full", "reference", trials=1, out_path=out, progress=False)
    failures = [f"{r.case_id}: {r.error or r.failed_checks}" for r in read_run(out).records if r.outcome != "pass"]
    assert not failures
    assert summary.passed == summary.total == len(load_suite("full").cases)


def test_the_committed_suites_are_what_the_generator_writes(tmp_path: Path) -> None:
    # The generator writes the development suites (full, smoke); the others (held-out, scenarios,
    # roads) have sources of their own, tested beside them.
    subprocess.run(
        [sys.executable, str(REPO / "evals" / "suite_source" / "build.py"), str(tmp_path)],
        check=True,
        capture_output=True,
    )
    written = {p.name: p.read_bytes() for p in tmp_path.glob("*.jsonl")}
    assert {"full.jsonl", "smoke.jsonl"} <= set(written)
    assert written == {name: (SUITES_DIR / name).read_bytes() for name in written}


def test_a_bad_case_line_is_reported_with_its_line_number(tmp_path: Path) -> None:
    path = tmp_path / "bad.jsonl"
    good = {
        "id": "a",
        "prompt": "make it rain",
        "task": "appearance",
        "grade": "direct",
        "checks": [{"kind": "environment", "weather": ["rain"]}],
    }
    bad = {**good, "id": "b", "grade": "polite"}
    path.write_text(json.dumps(good) + "\n" + json.dumps(bad) + "\n", encoding="utf-8")
    with pytest.raises(SuiteError, match=r"bad.jsonl:2: .*grade"):
        load_suite(path)


def test_a_case_without_checks_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "empty.jsonl"
    path.write_text(json.dumps({"id": "a", "prompt": "p", "task": "search", "grade": "vague"}) + "\n")
    with pytest.raises(SuiteError, match="no checks"):
        load_suite(path)
