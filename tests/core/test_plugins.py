import sys
import textwrap

from drivetwin.tools import ToolRegistry


def _install_fake_dist(tmp_path, name, module_source, entry):
    (tmp_path / f"{name}.py").write_text(textwrap.dedent(module_source), encoding="utf-8")
    dist = tmp_path / f"{name}-0.1.dist-info"
    dist.mkdir()
    (dist / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {name}\nVersion: 0.1\n", encoding="utf-8")
    (dist / "entry_points.txt").write_text(f"[drivetwin.tools]\n{entry}\n", encoding="utf-8")


def test_a_plugin_that_raises_on_import_is_reported_and_skipped(tmp_path, monkeypatch):
    _install_fake_dist(tmp_path, "broken_plugin", "raise RuntimeError('boom at import')\n",
                       "broken = broken_plugin:Tool")
    monkeypatch.syspath_prepend(str(tmp_path))
    registry = ToolRegistry.default()
    assert "add_asset" in registry  # the built-ins are all still there
    problem = next(p for p in registry.problems if "broken_plugin" in p.entry_point)
    assert "boom at import" in problem.error
    sys.modules.pop("broken_plugin", None)


def test_a_plugin_object_that_is_not_a_tool_is_reported(tmp_path, monkeypatch):
    _install_fake_dist(tmp_path, "odd_plugin", "THING = 42\n", "odd = odd_plugin:THING")
    monkeypatch.syspath_prepend(str(tmp_path))
    registry = ToolRegistry.default()
    assert any("odd_plugin" in p.entry_point and "not a Worker tool" in p.error for p in registry.problems)
    sys.modules.pop("odd_plugin", None)
