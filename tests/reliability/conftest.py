from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolRegistry
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.scene import Scene


@pytest.fixture(scope="session")
def registry() -> ToolRegistry:
    return ToolRegistry.default(plugins=False)


@pytest.fixture(scope="session")
def campus_json() -> str:
    return build_campus().model_dump_json()


@pytest.fixture
def campus(campus_json: str) -> Scene:
    return Scene.model_validate_json(campus_json)


@pytest.fixture
def session(campus: Scene, registry: ToolRegistry, tmp_path):
    made = Session(campus, RulePlanner(), registry, journal_path=tmp_path / "journal.jsonl")
    yield made
    made.close()
