"""`drivetwin bench edits` measures what it says: every edit kind through a Session, none of
them recompiling MuJoCo, with the footprint index's one-time build reported apart."""

from __future__ import annotations

import json

from drivetwin.orchestrator.bench_edits import crowded_campus, main, measure
from drivetwin.worlds.scene import asset_order


def test_the_crowded_campus_holds_its_extra_assets_in_canonical_order() -> None:
    scene = crowded_campus(300)
    ids = [a.id for a in scene.assets]
    assert len(set(ids)) == len(ids) >= 300
    assert scene.assets == sorted(scene.assets, key=asset_order)  # as every validated scene


def test_a_measured_world_reports_each_edit_kind_and_no_recompile() -> None:
    row = measure(100, 2)
    assert row["edits"] == 6 and row["recompiles"] == 0
    for clock in ("wall", "cpu"):
        assert set(row["edit_ms"][clock]["median"]) == {"add", "move", "remove"}
        assert row["footprint_index_ms"][clock] >= 0.0
    assert row["assets"] == len(crowded_campus(100).assets)  # each round adds then removes its bench


def test_the_command_writes_its_figures_as_json(tmp_path, capsys) -> None:
    out = tmp_path / "edits.json"
    assert main(["--assets", "0", "--repeats", "1", "--out", str(out)]) == 0
    rows = json.loads(out.read_text(encoding="utf-8"))["rows"]
    assert [r["assets"] for r in rows] == [len(crowded_campus(0).assets)]
    assert "index ms" in capsys.readouterr().out
