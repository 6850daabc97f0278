from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolRegistry
from drivetwin.worlds.scene import Scene


@pytest.fixture
def session(campus: Scene, registry: ToolRegistry, tmp_path):
    made = Session(campus, RulePlanner(), registry, journal_path=tmp_path / "journal.jsonl")
    yield made
    made.close()
