"""Shared fixtures for the eval harness tests: the campus world and outcomes of real tool calls."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from drivetwin.evals.outcome import CaseOutcome
from drivetwin.evals.trial import fresh_world
from drivetwin.orchestrator.transaction import execute
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import ToolRegistry
from tiny_planner import TINY_CASES, write_suite

HERE = Path(__file__).resolve().parent




OutcomeOf = Callable[..., CaseOutcome]


@pytest.fixture()
def outcome_of(registry: ToolRegistry) -> OutcomeOf:
    """CaseOutcome of running calls (tool, args) on the campus, after optional setup calls."""

    def make(
        *calls: tuple[str, dict[str, Any]],
        setup: tuple[tuple[str, dict[str, Any]], ...] = (),
        answer: str = "",
        accepted: bool = True,
    ) -> CaseOutcome:
        scene = fresh_world("campus")
        if setup:
            scene = execute(registry, scene, [ToolCall(tool=t, args=a) for t, a in setup]).after
        done = execute(registry, scene, [ToolCall(tool=t, args=a) for t, a in calls])
        return CaseOutcome(scene, done.after, accepted, answer, None, tuple(r.text for r in done.results))

    return make


@pytest.fixture()
def tiny_suite(tmp_path: Path) -> Path:
    return write_suite(tmp_path / "tiny.jsonl", TINY_CASES)
