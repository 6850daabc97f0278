"""Planner plugins (`drivetwin.planners`) load, fail and are reported exactly as tool plugins are."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner
from drivetwin.evals.executors import PlannerLoadError, build_planner
from drivetwin.orchestrator.cli import main
from drivetwin.orchestrator.planning import UnknownPlannerError, make_planner
from drivetwin.orchestrator.planning.registry import discover_planners

from .throwaway import install

ECHO_PLANNER = '''
from drivetwin.orchestrator.planning import Plan
from drivetwin.tools import ToolCall


class WeatherPlanner:
    """Always makes it rain: a test plugin."""

    name = "weather"

    def __init__(self, kind="rain"):
        self.kind = kind

    def plan(self, prompt, context):
        return Plan(calls=[ToolCall(tool="set_weather", args={"kind": self.kind})], planner=self.name)


def make(**options):
    """Always makes it rain: a test plugin."""
    return WeatherPlanner(**options)
'''


@pytest.fixture
def planners(site: Path) -> Path:
    install(site, "drivetwin-test-planners", {"weather_planner": ECHO_PLANNER, "broken_planner": "raise RuntimeError('boom at import')\n"},
            {"drivetwin.planners": {"weather": "weather_planner:make", "broken": "broken_planner:make",
                                    "rules": "weather_planner:make"}})
    return site


def _broken_line(output: str, plugin: str) -> str:
    return next(line for line in output.splitlines() if line.startswith("broken plugin skipped:") and plugin in line)


def test_a_planner_plugin_is_built_by_name(planners: Path) -> None:
    planner = make_planner("weather", kind="snow")
    assert planner.name == "weather" and planner.kind == "snow"  # type: ignore[attr-defined]


def test_planners_list_shows_built_in_and_plugin_planners(planners: Path) -> None:
    result = CliRunner().invoke(main, ["planners", "list"])
    assert result.exit_code == 0
    rows = {line.split()[0]: line for line in result.stdout.splitlines()}
    assert {"rules", "retrieval", "llm", "hybrid", "weather"} <= set(rows)
    assert "built-in" in rows["rules"] and "plugin weather_planner:make" in rows["weather"]
    assert "Always makes it rain" in rows["weather"]


def test_a_broken_planner_plugin_is_reported_like_a_broken_tool(planners: Path, site: Path) -> None:
    install(site, "drivetwin-test-tools", {"broken_tool": "raise RuntimeError('boom at import')\n"},
            {"drivetwin.tools": {"broken": "broken_tool:Tool"}})
    runner = CliRunner()
    planners_out = runner.invoke(main, ["planners", "list"])
    tools_out = runner.invoke(main, ["tools", "list"])
    assert planners_out.exit_code == 0 and tools_out.exit_code == 0
    planner_line, tool_line = _broken_line(planners_out.stderr, "broken_planner"), _broken_line(tools_out.stderr, "broken_tool")
    # The same line, but for the names: entry point, error, and the command that fixes it.
    assert planner_line.replace("planner", "X") == tool_line.replace("tool", "X").replace("Tool", "make")
    assert "RuntimeError: boom at import" in planner_line
    assert "pip install --force-reinstall drivetwin-test-planners" in planner_line
    assert "broken" not in planners_out.stdout.split()


def test_planners_list_json_carries_the_problems_with_group_and_fix(planners: Path) -> None:
    result = CliRunner().invoke(main, ["planners", "list", "--json"])
    listing = json.loads(result.stdout)
    assert "weather" in [p["name"] for p in listing["planners"]]
    broken = next(p for p in listing["problems"] if p["entry_point"].startswith("broken ="))
    assert broken["group"] == "drivetwin.planners" and "boom at import" in broken["error"]
    assert "drivetwin-test-planners" in broken["fix"]


def test_a_plugin_cannot_replace_a_built_in_planner(planners: Path) -> None:
    entries, problems = discover_planners()
    assert next(e for e in entries if e.name == "rules").source == "built-in"
    assert make_planner("rules").name == "rules"
    assert any(p.name == "rules" and "a built-in is called 'rules'" in p.error for p in problems)


def test_asking_for_a_broken_planner_says_why_and_what_fixes_it(planners: Path) -> None:
    with pytest.raises(UnknownPlannerError, match=r"installed but broken .*boom at import.*force-reinstall"):
        make_planner("broken")


def test_an_unknown_planner_lists_the_available_ones(planners: Path) -> None:
    with pytest.raises(UnknownPlannerError, match="unknown planner 'weathr'; available: rules, retrieval, llm, hybrid, weather"):
        make_planner("weathr")


def test_the_eval_runner_takes_a_module_factory_planner_through_the_registry(site: Path) -> None:
    install(site, "drivetwin-test-loose", {"loose_planner": ECHO_PLANNER}, {})
    planner = build_planner("loose_planner:make", {"kind": "fog"})
    assert planner.name == "weather" and planner.kind == "fog"  # type: ignore[attr-defined]


def test_a_module_factory_planner_that_fails_to_import_is_one_planner_load_error(site: Path) -> None:
    install(site, "drivetwin-test-loose", {"loose_broken": "import sys\nsys.exit(4)\n"}, {})
    with pytest.raises(PlannerLoadError, match="cannot be loaded: SystemExit: 4"):
        build_planner("loose_broken:make", {})


def test_a_factory_that_builds_something_else_than_a_planner_is_refused(site: Path) -> None:
    install(site, "drivetwin-test-loose", {"not_planner": "def make(**options):\n    return 42\n"}, {})
    with pytest.raises(UnknownPlannerError, match="built a int"):
        make_planner("not_planner:make")
