"""Planning fixtures on top of the root ones (tests/conftest.py: campus, registry)."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning import PlanContext
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolRegistry
from drivetwin.worlds.scene import Scene


@pytest.fixture
def context(campus: Scene, registry: ToolRegistry) -> PlanContext:
    return PlanContext(scene=campus, registry=registry)


@pytest.fixture
def session(campus: Scene, registry: ToolRegistry, tmp_path) -> Session:
    return Session(campus, RulePlanner(), registry, journal_path=tmp_path / "journal.jsonl")
