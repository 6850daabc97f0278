"""`drivetwin reconstruct`: the commands write their half, the second one fuses a package that
joins the catalog, and `report` measures it. (CoACD takes minutes on 2 cores, so the object's
geometry half here is written directly; `reconstruct demo` runs the full two-command path.)"""

from __future__ import annotations

import json

import numpy as np
import pytest
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.reconstruct.capture_views import ring_cameras
from drivetwin.worlds.reconstruct.views import PosedImages, PosedView, write_poses_json
from drivetwin.worlds.render.rasterize import rasterize
from drivetwin.worlds.render.splats import SH_C0
from fusion_capture import CAPTURE_OFFSET, object_splats, write_geometry

# Small enough for CI on 2 cores: 6 photographs of 48x36 and a 10-iteration fit.
VIEWS, WIDTH, HEIGHT, ITERATIONS = 6, 48, 36, 10
# A fit this short only has to beat a blank guess (the black background alone scores ~5 dB).
MIN_PSNR_DB = 10.0


def _photographs(folder):
    """Posed photographs of the object drawn from its true splats, with a sparse cloud."""
    truth = object_splats()
    cameras = ring_cameras(CAPTURE_OFFSET + np.array([0.0, 0.0, 0.6]), radius=3.5, heights=(1.2, 2.4),
                           per_ring=VIEWS // 2, width=WIDTH, height=HEIGHT, fovy_deg=45.0)  # fmt: skip
    views = [PosedView(f"view_{k:03d}", rasterize(truth, cam).rgb, cam) for k, cam in enumerate(cameras)]
    sparse = truth.subset(np.arange(0, len(truth), 10))
    colours = np.clip(0.5 + SH_C0 * sparse.sh[:, 0], 0.0, 1.0).astype(np.float32)
    write_poses_json(PosedImages(views, sparse.means, colours), folder / "poses.json")
    return folder / "poses.json"


def test_the_splats_command_fuses_with_the_geometry_half_and_report_measures_it(tmp_path, monkeypatch):
    monkeypatch.setenv("DRIVETWIN_CACHE", str(tmp_path / "cache"))
    package = tmp_path / "assets" / "kerb_stone"
    write_geometry(package)
    poses = _photographs(tmp_path / "photos")
    runner = CliRunner()
    result = runner.invoke(main, ["reconstruct", "splats", str(poses.parent), "--out", str(package), "--poses",
                                  str(poses), "--iterations", str(ITERATIONS), "--material", "concrete"])  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "package 'kerb_stone' (asset)" in result.output
    manifest = json.loads((package / "asset.json").read_text())
    assert manifest["dimensions"]["height"] == pytest.approx(1.3)
    assert manifest["metrics"]["alignment.coverage_after"] > 0.6
    monkeypatch.setenv("DRIVETWIN_ASSETS", str(package.parent))
    assert catalog()["kerb_stone"].mass == pytest.approx(manifest["mass"])
    report = runner.invoke(main, ["reconstruct", "report", str(package), "--frames", "2"])
    assert report.exit_code == 0, report.output
    figures = json.loads((package / "reconstruction_report.json").read_text())
    assert figures["render"]["fps"] > 0 and figures["appearance"]["psnr_db"] > MIN_PSNR_DB
    assert "hybrid renderer FPS" in (package / "reconstruction_report.md").read_text()
    as_json = runner.invoke(main, ["reconstruct", "report", str(package), "--frames", "1", "--json"])
    assert as_json.exit_code == 0, as_json.output
    assert json.loads(as_json.output)["appearance"] == figures["appearance"]  # the same held-out views


def test_the_mesh_command_writes_its_half_and_names_the_other_command(tmp_path):
    rng = np.random.default_rng(0)
    ground = np.column_stack([rng.uniform(-4, 4, (3000, 2)), rng.normal(0.0, 0.005, 3000)])
    np.save(tmp_path / "scan.npy", ground)
    out = tmp_path / "lot"
    result = CliRunner().invoke(main, ["reconstruct", "mesh", str(tmp_path / "scan.npy"), "--out", str(out),
                                       "--kind", "ground", "--voxel", "0.2", "--budget", "500"])  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "reconstruct splats IMAGES_DIR" in result.output
    assert (out / "collision" / "heightfield.npz").is_file() and not (out / "asset.json").exists()


def test_splats_refuses_both_pose_sources(tmp_path):
    (tmp_path / "photos").mkdir()
    result = CliRunner().invoke(main, ["reconstruct", "splats", str(tmp_path / "photos"), "--out", str(tmp_path / "p"),
                                       "--poses", __file__, "--colmap", str(tmp_path)])  # fmt: skip
    assert result.exit_code != 0 and "not both" in result.output
