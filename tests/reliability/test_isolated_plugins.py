"""--isolate-plugins: plugin Workers in their own process, so os._exit and segfaults are refusals."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolRegistry

from .plugins import install_plugin
from .scripted import ScriptedPlanner, call


@pytest.fixture
def plugin_dir(tmp_path, monkeypatch):
    folder = tmp_path / "site"
    folder.mkdir()
    monkeypatch.syspath_prepend(str(folder))
    monkeypatch.setenv("PYTHONPATH", str(folder))  # the plugin process finds the plugin too
    return folder


@pytest.mark.parametrize(("body", "says"), [
    ("os._exit(7)", "exit code 7"),
    ("import ctypes; ctypes.string_at(0)", "signal 11"),
])
def test_a_plugin_that_kills_its_process_is_only_a_refusal(plugin_dir, campus, tmp_path, body, says):
    tool = install_plugin(plugin_dir, "deadly_plugin", body)
    registry = ToolRegistry.default(isolate=True)
    assert registry.sources[tool].startswith("isolated plugin")
    session = Session(campus, ScriptedPlanner(call(tool)), registry, journal_path=tmp_path / "j.jsonl")
    report = session.submit("use the deadly plugin")
    assert not report.ok and says in report.error and "deadly_plugin" in report.error
    assert session.scene == campus
    session.planner = ScriptedPlanner(call("set_weather", kind="fog"))
    assert session.submit("make it foggy").ok
    session.close()


def test_an_isolated_plugin_that_works_edits_the_world_through_the_host(plugin_dir, campus, tmp_path):
    tool = install_plugin(plugin_dir, "distant_plugin")
    registry = ToolRegistry.default(isolate=True)
    session = Session(campus, ScriptedPlanner(call(tool)), registry, journal_path=tmp_path / "j.jsonl")
    for _ in range(2):  # the process serves call after call
        assert session.submit("add a cone through the plugin process").ok
    assert session.scene.count("traffic_cone") == campus.count("traffic_cone") + 2
    assert registry.get(tool).json_schema()["name"] == tool
    session.close()
