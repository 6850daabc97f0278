"""No plugin can break a session: each failure class becomes a refusal naming the plugin."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.journal import Journal
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolRegistry
from drivetwin.tools import registry as registry_module

from .plugins import install_plugin
from .scripted import ScriptedPlanner, call


@pytest.fixture
def plugin_dir(tmp_path, monkeypatch):
    folder = tmp_path / "site"
    folder.mkdir()
    monkeypatch.syspath_prepend(str(folder))
    return folder


def _session_with(tool: str, campus, tmp_path, registry: ToolRegistry | None = None) -> Session:
    registry = registry or ToolRegistry.default()
    return Session(campus, ScriptedPlanner(call(tool)), registry, journal_path=tmp_path / "j.jsonl")


def _refused_and_unchanged(session: Session, says: str) -> None:
    before = session.scene
    journal_before = Journal(session.journal.path).replay().scene
    report = session.submit("use the plugin")
    assert not report.ok and says in report.error and "_plugin" in report.error  # names the plugin
    assert session.scene == before and Journal(session.journal.path).replay().scene == journal_before
    session.planner = ScriptedPlanner(call("set_weather", kind="rain"))
    assert session.submit("make it rain").ok  # the session goes on


@pytest.mark.parametrize(("body", "says"), [
    ("raise RuntimeError('plugin bug')", "RuntimeError: plugin bug"),
    ("sys.exit(3)", "SystemExit: 3"),
    ("raise KeyboardInterrupt()", "KeyboardInterrupt"),
    ("return 'not a result'", "returned str, not a ToolResult"),
])
def test_a_plugin_that_fails_in_propose_is_a_refusal_naming_it(plugin_dir, campus, tmp_path, body, says):
    tool = install_plugin(plugin_dir, "failing_plugin", body)
    session = _session_with(tool, campus, tmp_path)
    _refused_and_unchanged(session, says)
    session.close()


def test_a_plugin_exception_during_a_dry_run_is_a_refusal(plugin_dir, campus):
    from drivetwin.orchestrator.transaction import first_refusal

    tool = install_plugin(plugin_dir, "dry_plugin", "raise ValueError('in a dry run')")
    refusal = first_refusal(ToolRegistry.default(), campus, [call(tool)])
    assert refusal is not None and "dry_plugin" in refusal and "in a dry run" in refusal


def test_a_plugin_that_hangs_is_refused_at_its_deadline(plugin_dir, campus, tmp_path, monkeypatch):
    monkeypatch.setattr(registry_module, "CALL_DEADLINE_S", 0.5)
    tool = install_plugin(plugin_dir, "hanging_plugin", "time.sleep(30)")
    session = _session_with(tool, campus, tmp_path)
    _refused_and_unchanged(session, "did not answer within 0.5 s")
    session.close()


def test_a_plugin_that_mutates_the_scene_it_is_handed_is_refused(plugin_dir, campus, tmp_path):
    tool = install_plugin(plugin_dir, "sneaky_plugin", "scene.assets.clear()\nscene.name = 'mine'")
    session = _session_with(tool, campus, tmp_path)
    _refused_and_unchanged(session, "changed the scene it was handed")
    assert session.scene.assets and session.scene.name == campus.name
    session.close()


def test_a_plugin_overriding_apply_cannot_bypass_the_world_rules(plugin_dir, campus, tmp_path):
    inside_building = """
    from drivetwin.worlds.edits import AddAsset, WorldEdit
    cone = result.edit.ops[0].asset
    moved = cone.model_copy(update={"pose": Pose(x=40.0, y=30.0)})  # inside the JTEKT building
    result = ToolResult(WorldEdit(ops=(AddAsset(asset=moved),)), "a cone in a building")
    """
    override = """
    def _apply(self, args, scene):
        return self.propose(args, scene)  # no check_edit: tries to skip the world rules

    Plug.apply = _apply
    """
    tool = install_plugin(plugin_dir, "bypass_plugin", inside_building, extra=override)
    registry = ToolRegistry.default()
    assert any("overrides apply" in p.error for p in registry.problems)
    session = _session_with(tool, campus, tmp_path, registry)
    before = session.scene
    report = session.submit("put a cone in the building")
    assert not report.ok and "inside JTEKT Building" in report.error and session.scene == before
    session.close()


@pytest.mark.parametrize(("module_level", "says"), [
    ("raise RuntimeError('boom at import')", "boom at import"),
    ("sys.exit(2)", "SystemExit"),
    ("time.sleep(30)", "did not answer within 1 s"),
])
def test_a_plugin_whose_import_fails_is_reported_and_skipped(plugin_dir, monkeypatch, module_level, says):
    monkeypatch.setattr(registry_module, "IMPORT_DEADLINE_S", 1.0)
    install_plugin(plugin_dir, "import_plugin", module_level=module_level)
    registry = ToolRegistry.default()
    assert "add_asset" in registry and "import_plugin_tool" not in registry
    problem = next(p for p in registry.problems if "import_plugin" in p.entry_point)
    assert says in problem.error


def test_a_good_plugin_still_works_in_its_box(plugin_dir, campus, tmp_path):
    tool = install_plugin(plugin_dir, "good_plugin")
    session = _session_with(tool, campus, tmp_path)
    report = session.submit("add a cone through the plugin")
    assert report.ok and session.scene.count("traffic_cone") == campus.count("traffic_cone") + 1
    session.close()


def test_a_plugin_that_exits_at_import_does_not_stop_a_drivetwin_command(plugin_dir):
    from click.testing import CliRunner
    from drivetwin.orchestrator.cli import main

    install_plugin(plugin_dir, "exiting_plugin", module_level="sys.exit(1)")
    result = CliRunner().invoke(main, ["tools", "list"])
    assert result.exit_code == 0 and "add_asset" in result.output
    assert "exiting_plugin" in result.output and "SystemExit" in result.output
