"""The splat benchmark runs end to end and writes its JSON report."""

from __future__ import annotations

import json

import numpy as np
import pytest
from drivetwin.worlds.image_metrics import psnr
from drivetwin.worlds.render.bench_splats import main, street_camera, street_scene


def test_benchmark_writes_fps_and_stage_timings_as_json(tmp_path):
    out = tmp_path / "bench.json"
    args = ["--width", "96", "--height", "64", "--counts", "500", "--frames", "2",
            "--backends", "numba", "torch", "--out", str(out)]  # fmt: skip
    assert main(args) == 0
    report = json.loads(out.read_text())
    assert report["resolution"] == [96, 64]
    numba_run, torch_run = report["results"]
    assert numba_run["backend"] == "numba" and numba_run["splats"] == 500
    assert {"project", "bin", "composite", "total"} <= numba_run["ms"].keys()
    stages = numba_run["ms"]
    # FPS is the inverse of the measured total (the JSON rounds milliseconds to 0.01).
    assert 1000.0 / numba_run["fps"] == pytest.approx(stages["total"], abs=0.0051)
    assert stages["total"] >= 0.9 * (stages["project"] + stages["bin"] + stages["composite"])
    assert numba_run["coverage_alpha_gt_0.5"] > 0.5
    assert torch_run["psnr_vs_numba_db"] > 60  # the same image up to rounding


def test_street_scene_fills_the_view_below_the_skyline():
    camera = street_camera(64, 48)
    splats = street_scene(2000, camera, seed=1)
    assert len(splats) == 2000
    depth = (splats.means @ camera.world_to_camera[:3, :3].T + camera.world_to_camera[:3, 3])[:, 2]
    assert depth.min() > 0


def test_psnr_of_identical_images_is_infinite_and_falls_with_noise():
    image = np.random.default_rng(0).random((8, 8, 3))
    assert psnr(image, image) == float("inf")
    assert psnr(image, image + 0.1) < psnr(image, image + 0.01)


def test_hybrid_benchmark_prints_a_stage_table_and_writes_json(tmp_path, capsys):
    from drivetwin.worlds.render.bench_hybrid import main as hybrid_main

    out = tmp_path / "hybrid.json"
    args = ["--width", "96", "--height", "54", "--splats", "800", "--assets", "3", "--frames", "1",
            "--out", str(out)]  # fmt: skip
    assert hybrid_main(args) == 0
    table = capsys.readouterr().out
    assert "| cpu | 800 |" in table and "compositing ms" in table
    cpu = json.loads(out.read_text())["results"][0]
    assert {"mesh_pass", "projection", "binning", "compositing", "blend", "appearance", "total"} <= cpu["ms"].keys()
    assert cpu["device"] == "cpu" and cpu["fps"] == pytest.approx(1000.0 / cpu["ms"]["total"], abs=0.01)
