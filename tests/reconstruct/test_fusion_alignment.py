"""Fusion: splats in another frame are brought onto the mesh; aligned halves stay put."""

from __future__ import annotations

import numpy as np
import pytest
from drivetwin.worlds.packages import AssetPackage, file_digest
from drivetwin.worlds.reconstruct.alignment import apply_transform
from drivetwin.worlds.reconstruct.fusion import FusionError, fuse, fuse_if_complete
from fusion_capture import CAPTURE_OFFSET, fused_package, object_splats, similarity, write_appearance, write_geometry

# Bounds for a 1.6 m object from 6,000 surface splats (measured: 0.13°, 0.2 %, 4.3 mm).
MAX_ROTATION_DEG = 0.5
MAX_SCALE_ERROR = 0.005
MAX_POINT_ERROR_M = 0.01


def _errors(recovered: np.ndarray, applied: np.ndarray) -> tuple[float, float, float]:
    """Rotation (deg), scale and largest point error of recovered @ applied against identity."""
    residual = np.asarray(recovered) @ applied
    scale = float(np.cbrt(np.linalg.det(residual[:3, :3])))
    rotation = residual[:3, :3] / scale
    angle = float(np.degrees(np.arccos(np.clip((np.trace(rotation) - 1) / 2, -1, 1))))
    points = object_splats().means.astype(np.float64)
    moved = float(np.max(np.linalg.norm(apply_transform(residual, points) - points, axis=1)))
    return angle, abs(scale - 1), moved


@pytest.mark.parametrize("background", [0, 800])
def test_fusion_recovers_a_similarity_applied_to_the_splats(tmp_path, background):
    # An SfM-like frame: turned 70° about a tilted axis, 0.4x the size, shifted.
    applied = similarity(70.0, (0.3, 1.0, 0.2), 0.4, (3.0, -1.0, 2.0))
    package = AssetPackage.load(fused_package(tmp_path / "p", background=background, transform=applied))
    angle, scale_error, point_error = _errors(np.asarray(package.manifest.splat_alignment), applied)
    assert angle < MAX_ROTATION_DEG and scale_error < MAX_SCALE_ERROR and point_error < MAX_POINT_ERROR_M
    metrics = package.manifest.metrics
    assert metrics["alignment.median_before_m"] > 1.0 > 0.01 > metrics["alignment.median_after_m"]
    # The background (about 10 % of the splats) is cropped away; the object's splats stay.
    assert metrics["splats.kept"] == pytest.approx(len(object_splats()), rel=0.01)


def _write_cameras(folder, centres, transform):
    """visual/cameras.json with cameras at `centres` (capture frame), moved into the splats' frame."""
    import json

    views = []
    for centre in apply_transform(transform, np.asarray(centres, dtype=np.float64)):
        world_to_camera = np.eye(4)
        world_to_camera[:3, 3] = -centre  # identity rotation: only the centre matters here
        views.append({"name": f"v{len(views)}", "world_to_camera": world_to_camera.tolist()})
    (folder / "visual" / "cameras.json").write_text(json.dumps({"views": views}), encoding="utf-8")


@pytest.mark.parametrize(("height_m", "accepted"), [(2.0, True), (-3.0, False)])
def test_an_alignment_that_puts_the_cameras_under_the_surface_is_refused(tmp_path, height_m, accepted):
    applied = similarity(70.0, (0.3, 1.0, 0.2), 0.4, (3.0, -1.0, 2.0))
    folder = tmp_path / "p"
    folder.mkdir()
    write_geometry(folder)
    write_appearance(folder, object_splats().transformed(applied))
    ring = [(CAPTURE_OFFSET[0] + 3 * np.cos(a), CAPTURE_OFFSET[1] + 3 * np.sin(a), height_m) for a in np.linspace(0, 6, 8)]
    _write_cameras(folder, ring, applied)
    if accepted:
        fuse(folder)
        assert AssetPackage.load(folder).manifest.name
    else:
        with pytest.raises(FusionError, match="under the scanned surface"):
            fuse(folder)


def test_halves_already_in_one_frame_are_not_moved_and_the_background_is_cropped(tmp_path):
    package = AssetPackage.load(fused_package(tmp_path / "p", background=800))
    assert np.allclose(package.manifest.splat_alignment, np.eye(4))
    splats = package.splats()
    low, high = package.mesh().bounds
    assert np.all(splats.means >= low - 0.1) and np.all(splats.means <= high + 0.1)


def test_fusing_again_starts_from_the_kept_halves_and_gives_the_same_package(tmp_path):
    folder = fused_package(tmp_path / "p", transform=similarity(30.0, (0, 0, 1), 2.0, (1.0, 2.0, 0.0)))
    first = AssetPackage.load(folder).manifest
    again = fuse(folder).manifest
    assert again.files == first.files
    assert np.allclose(again.splat_alignment, first.splat_alignment)


def test_a_rebuilt_half_replaces_the_kept_one(tmp_path):
    folder = fused_package(tmp_path / "p")
    kept = file_digest(folder / "capture" / "visual" / "splats.ply")
    write_appearance(folder, object_splats(count=3000, seed=7))
    package = fuse(folder)
    assert file_digest(folder / "capture" / "visual" / "splats.ply") != kept
    assert package.manifest.metrics["splats.total"] == pytest.approx(3000, rel=0.01)


def test_fuse_if_complete_waits_for_both_halves(tmp_path):
    write_geometry(tmp_path)
    assert fuse_if_complete(tmp_path) is None and not (tmp_path / "asset.json").exists()
    with pytest.raises(FusionError, match="needs both halves"):
        fuse(tmp_path)
    write_appearance(tmp_path, object_splats())
    assert fuse_if_complete(tmp_path, name="Kerb Stone #2").name == "kerb_stone_2"
