"""The held-out suite: complete, valid, reproducible from its source, and passable."""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path

import jsonschema
from drivetwin.evals import heldout_source
from drivetwin.evals.case import GRADES, SCHEMA_PATH, SUITES_DIR, TASKS, load_suite
from drivetwin.evals.outcome import CaseOutcome
from drivetwin.evals.trial import fresh_world
from drivetwin.tools.base import ToolCall
from drivetwin.tools.errors import ToolError
from drivetwin.tools.locate import resolve_target
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.scene import Scene

HELDOUT = SUITES_DIR / "heldout.jsonl"
# Issue 11: at least 300 prompts; the brief asks 320 with 11 in every task x grade cell.
MIN_CASES = 320
MIN_PER_CELL = 11
# ...with multi-turn (15 planned by the planner under test) and compound cases.
MIN_MULTI_TURN, MIN_PLANNED, MIN_COMPOUND = 30, 15, 25
# About 8 % are impossible as stated; the right outcome is a refusal.
IMPOSSIBLE_SHARE = (0.05, 0.12)


def test_the_committed_heldout_suite_is_what_its_source_writes(tmp_path: Path) -> None:
    out = tmp_path / "heldout.jsonl"
    heldout_source.write(out)
    assert out.read_bytes() == HELDOUT.read_bytes()


def test_every_heldout_line_validates_against_the_published_schema() -> None:
    validator = jsonschema.Draft202012Validator(json.loads(SCHEMA_PATH.read_text(encoding="utf-8")))
    for number, line in enumerate(HELDOUT.read_text(encoding="utf-8").splitlines(), start=1):
        errors = list(validator.iter_errors(json.loads(line)))
        assert not errors, f"heldout.jsonl:{number}: {errors[0].message}"


def test_every_task_and_grade_cell_holds_at_least_eleven_heldout_cases() -> None:
    suite = load_suite("heldout")
    cells = Counter((c.task, c.grade) for c in suite.cases)
    thin = {cell: n for cell in ((t, g) for t in TASKS for g in GRADES) if (n := cells[cell]) < MIN_PER_CELL}
    assert not thin
    assert len(suite.cases) >= MIN_CASES


def test_heldout_cases_are_tagged_and_hold_multi_turn_compound_and_impossible_ones() -> None:
    cases = load_suite("heldout").cases
    assert all(c.id.startswith("heldout.") and "heldout" in c.tags for c in cases)
    tags = Counter(t for c in cases for t in c.tags)
    planned = sum(1 for c in cases if any(step.planned for step in c.setup))
    assert tags["multi_turn"] >= MIN_MULTI_TURN and planned >= MIN_PLANNED
    assert tags["compound"] >= MIN_COMPOUND
    assert IMPOSSIBLE_SHARE[0] <= tags["impossible"] / len(cases) <= IMPOSSIBLE_SHARE[1]


def test_every_impossible_heldout_case_expects_a_refusal_that_changes_nothing() -> None:
    for case in load_suite("heldout").cases:
        if "impossible" not in case.tags:
            continue
        kinds = {check.kind for check in case.checks}
        refusal = any(getattr(c, "kind", "") == "status" and not getattr(c, "accepted", True)
                      for c in [*case.checks, *(c for alt in case.alternatives for c in alt)])
        assert "unchanged_except" in kinds and refusal, case.id


def test_every_place_a_heldout_check_names_is_in_the_campus_or_made_by_the_case() -> None:
    campus = fresh_world("campus")
    for case in load_suite("heldout").cases:
        for check in [*case.checks, *(c for alt in case.alternatives for c in alt)]:
            for name in (getattr(check, "target", None), getattr(check, "around", None)):
                if name is None or "_" in name:  # asset ids are made by the case's own setup
                    continue
                resolve_target(campus, name)  # raises NotFoundError on a typo


def _replay(calls: list[ToolCall], scene: Scene, registry: ToolRegistry) -> CaseOutcome:
    """The outcome of running calls as one all-or-nothing prompt, straight through the Workers."""
    after, texts = scene, []
    try:
        for call in calls:
            result = registry.run(call, after)
            after = result.edit.apply(after)
            texts.append(result.text)
    except ToolError as exc:
        return CaseOutcome(scene, scene, accepted=False, error=str(exc))
    return CaseOutcome(scene, after, results=tuple(texts))


def test_the_reference_calls_build_an_outcome_every_heldout_case_accepts() -> None:
    """Proves every case passable: its checks accept what its reference calls really do."""
    registry = ToolRegistry.default(plugins=False)
    failures = []
    for case in load_suite("heldout").cases:
        scene = fresh_world(case.world)
        for step in case.setup:
            start = _replay(step.calls, scene, registry)
            assert start.accepted, f"{case.id}: setup {step.prompt!r} refused: {start.error}"
            scene = start.after
        passed, results = case.judge(_replay(case.reference, scene, registry))
        if not passed:
            failures.append(f"{case.id}: {[r.reason for r in results if not r.passed]}")
    assert not failures


def test_the_reference_planner_passes_every_heldout_case_through_the_harness(tmp_path) -> None:  # type: ignore[no-untyped-def]
    from drivetwin.evals import run_suite

    summary = run_suite("heldout", "reference", out_path=tmp_path / "ref.jsonl", progress=False)
    assert summary.failed == 0 and summary.errors == 0 and summary.passed >= 370
