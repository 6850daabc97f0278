"""The physics benchmark runs end to end and writes its figures as JSON."""

from __future__ import annotations

import json
import statistics
from pathlib import Path

import pytest
from drivetwin.worlds.bench_physics import benchmark_scene, main


def test_benchmark_scene_has_the_asked_number_of_assets_with_vehicles_and_walkers() -> None:
    scene = benchmark_scene(200)
    assert len(scene.assets) == 200
    kinds = {a.behaviour.kind for a in scene.assets}
    assert {"drive_lane", "parked", "cross_road", "follow_path"} <= kinds


def test_benchmark_prints_steps_per_second_and_writes_json(tmp_path: Path, capsys) -> None:  # type: ignore[no-untyped-def]
    out = tmp_path / "bench.json"
    assert main(["--assets", "30", "--steps", "50", "--runs", "2", "--out", str(out)]) == 0
    figures = json.loads(out.read_text())
    assert figures["assets"] == 30 and len(figures["steps_per_second_runs"]) == 2
    # The figure is the median of the timed runs, and real time follows from the step.
    assert figures["steps_per_second"] == pytest.approx(statistics.median(figures["steps_per_second_runs"]))
    assert figures["realtime_factor"] == pytest.approx(figures["steps_per_second"] * figures["timestep_s"])
    assert figures["update_add_ms"] > 0 and figures["update_remove_ms"] > 0
    assert "physics steps/s" in capsys.readouterr().out
