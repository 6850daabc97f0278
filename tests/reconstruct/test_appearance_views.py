"""Posed image sets: COLMAP and poses-JSON round trips, the synthetic capture, typed errors."""

from __future__ import annotations

import json
import os
from pathlib import Path

import numpy as np
import pytest
from drivetwin.worlds.reconstruct.capture_views import capture_ring
from drivetwin.worlds.reconstruct.colmap_model import load_colmap, run_sfm, write_colmap
from drivetwin.worlds.reconstruct.views import (
    PosedImages,
    PosedView,
    ViewsError,
    load_poses_json,
    write_poses_json,
)
from drivetwin.worlds.render.camera import Camera

W, H = 40, 30


def _posed(seed: int = 0) -> PosedImages:
    rng = np.random.default_rng(seed)
    base = Camera.from_look_at((3.0, 0.0, 1.5), (0.0, 0.0, 0.0), width=W, height=H, fovy_deg=50)
    cameras = [Camera.from_look_at((3 * np.cos(a), 3 * np.sin(a), 1.5), (0, 0, 0), width=W, height=H, fovy_deg=50)
               for a in np.linspace(0, 3, 4)]  # fmt: skip
    # One camera with fx != fy and an off-centre principal point: both must survive.
    k = np.array([[41.0, 0.0, 19.3], [0.0, 37.5, 16.1], [0.0, 0.0, 1.0]])
    cameras.append(Camera.from_K(k, base.world_to_camera, W, H))
    # Images on the 8-bit grid, so PNG storage is lossless.
    views = [PosedView(f"v{i}.png", (rng.integers(0, 256, (H, W, 3)) / 255).astype(np.float32), c)
             for i, c in enumerate(cameras)]  # fmt: skip
    colors = (rng.integers(0, 256, (25, 3)) / 255).astype(np.float32)
    return PosedImages(views, rng.normal(size=(25, 3)).astype(np.float32), colors)


def _same(a: PosedImages, b: PosedImages) -> None:
    assert [v.name for v in a] == [v.name for v in b]
    for va, vb in zip(a, b, strict=True):
        np.testing.assert_allclose(va.camera.world_to_camera, vb.camera.world_to_camera, atol=1e-9)
        np.testing.assert_allclose(va.camera.K, vb.camera.K, atol=1e-9)
        np.testing.assert_allclose(va.image, vb.image, atol=1e-6)
    assert a.points is not None and b.points is not None and a.colors is not None and b.colors is not None
    np.testing.assert_allclose(a.points, b.points, atol=1e-6)
    np.testing.assert_allclose(a.colors, b.colors, atol=1e-6)


@pytest.mark.parametrize("binary", [False, True])
def test_a_colmap_model_written_with_pycolmap_reads_back_identically(tmp_path: Path, binary: bool) -> None:
    posed = _posed()
    write_poses_json(posed, tmp_path / "poses.json")  # writes the PNGs into tmp_path/images
    write_colmap(posed, tmp_path / "sparse", binary=binary)
    _same(posed, load_colmap(tmp_path / "sparse", tmp_path / "images"))


def test_a_colmap_model_without_rigs_and_frames_still_reads(tmp_path: Path) -> None:
    posed = _posed()
    write_poses_json(posed, tmp_path / "poses.json")
    write_colmap(posed, tmp_path / "sparse")
    for legacy_absent in ("rigs.txt", "frames.txt"):  # COLMAP 3.x models have neither
        os.remove(tmp_path / "sparse" / legacy_absent)
    _same(posed, load_colmap(tmp_path / "sparse", tmp_path / "images"))


def test_a_distorted_colmap_camera_is_refused_with_a_way_out(tmp_path: Path) -> None:
    posed = _posed()
    write_poses_json(posed, tmp_path / "poses.json")
    write_colmap(posed, tmp_path / "sparse")
    cameras = tmp_path / "sparse" / "cameras.txt"
    lines = [
        f"{p[0]} OPENCV {p[2]} {p[3]} {' '.join(p[4:])} 0.1 0 0 0" if p and not p[0].startswith("#") else " ".join(p)
        for p in (line.split() for line in cameras.read_text().splitlines())
    ]
    cameras.write_text("\n".join(lines) + "\n")
    with pytest.raises(ViewsError, match=r"OPENCV with distortion.*undistort"):
        load_colmap(tmp_path / "sparse", tmp_path / "images")


def test_loading_a_folder_that_is_not_a_colmap_model_says_so(tmp_path: Path) -> None:
    with pytest.raises(ViewsError, match="not a COLMAP model folder"):
        load_colmap(tmp_path, tmp_path)


def test_the_poses_json_round_trips(tmp_path: Path) -> None:
    posed = _posed()
    write_poses_json(posed, tmp_path / "capture" / "poses.json")
    _same(posed, load_poses_json(tmp_path / "capture" / "poses.json"))


def test_a_poses_json_view_without_intrinsics_names_the_missing_key(tmp_path: Path) -> None:
    posed = _posed()
    write_poses_json(posed, tmp_path / "poses.json")
    data = json.loads((tmp_path / "poses.json").read_text())
    del data["views"][2]["fx"]
    (tmp_path / "poses.json").write_text(json.dumps(data))
    with pytest.raises(ViewsError, match="view 2: missing key 'fx'"):
        load_poses_json(tmp_path / "poses.json")


def test_a_poses_json_of_another_format_is_refused(tmp_path: Path) -> None:
    (tmp_path / "poses.json").write_text(json.dumps({"frames": []}))
    with pytest.raises(ViewsError, match="drivetwin-poses-v1"):
        load_poses_json(tmp_path / "poses.json")


def test_a_view_whose_image_does_not_match_its_camera_is_refused() -> None:
    camera = Camera.from_look_at((3, 0, 1), (0, 0, 0), width=W, height=H, fovy_deg=50)
    with pytest.raises(ViewsError, match="image shape"):
        PosedView("bad", np.zeros((H + 1, W, 3), np.float32), camera)
    with pytest.raises(ViewsError, match=r"in \[0, 1\]"):
        PosedView("bright", np.full((H, W, 3), 255.0, np.float32), camera)


def test_split_holds_out_every_kth_view_and_refuses_an_empty_side() -> None:
    posed = _posed()
    train, held = posed.split(2)
    assert [v.name for v in held] == ["v0.png", "v2.png", "v4.png"]
    assert [v.name for v in train] == ["v1.png", "v3.png"]
    with pytest.raises(ViewsError, match=">= 2"):
        posed.split(1)


def test_sfm_on_a_folder_that_is_not_there_is_a_typed_error(tmp_path: Path) -> None:
    with pytest.raises(ViewsError, match="not a folder of images"):
        run_sfm(tmp_path / "nothing", tmp_path / "work")


def test_the_synthetic_capture_gives_posed_views_depths_and_points_on_the_surfaces() -> None:
    capture = capture_ring(per_ring=4, heights=(1.6,), points_per_view=40, seed=1)
    views = capture.images.views
    assert len(views) == 4 and all(v.image.shape == (48, 64, 3) for v in views)
    assert capture.images.points is not None and capture.images.colors is not None
    points = capture.images.points
    assert len(points) == 4 * 40
    # Every sample lies on the ground (z = 0) or on an asset within a metre and a half of the origin.
    on_ground = np.abs(points[:, 2]) < 0.01
    on_assets = (np.linalg.norm(points[:, :2], axis=1) < 1.5) & (points[:, 2] < 1.5)
    assert np.all(on_ground | on_assets) and on_ground.sum() > 0 and (~on_ground).sum() > 0
    # A sample re-projects into the view it came from at a pixel whose depth it matches.
    cam, depth = views[0].camera, capture.depths[0]
    p = cam.world_to_camera @ np.append(points[0], 1.0)
    u, v = cam.fx * p[0] / p[2] + cam.cx, cam.fy * p[1] / p[2] + cam.cy
    assert depth[int(v), int(u)] == pytest.approx(p[2], abs=1e-3)


def test_sfm_on_textureless_photographs_says_it_posed_nothing(tmp_path: Path) -> None:
    # The synthetic scene's flat-coloured geoms give SIFT too few features to register views:
    # pycolmap runs extraction, matching and mapping, and the failure is a typed error.
    capture = capture_ring(width=128, height=96, per_ring=6, heights=(1.6,), points_per_view=5)
    write_poses_json(capture.images, tmp_path / "poses.json")
    with pytest.raises(ViewsError, match="posed no images"):
        run_sfm(tmp_path / "images", tmp_path / "work", num_threads=2)
