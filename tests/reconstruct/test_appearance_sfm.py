"""Structure from motion on the textured synthetic capture: pycolmap poses the ring from images alone."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.reconstruct.alignment import apply_transform, check_alignment, surface_samples, umeyama
from drivetwin.worlds.reconstruct.capture_views import SyntheticCapture, capture_ring
from drivetwin.worlds.reconstruct.colmap_model import run_sfm
from drivetwin.worlds.reconstruct.views import PosedImages, ViewsError, write_poses_json

# The capture: 16 views (22.5° apart) of 200x150 px from 2 m above a 3 m ring round the scene.
RADIUS_M, HEIGHT_M, VIEWS, WIDTH, HEIGHT = 3.0, 2.0, 16, 200, 150
# "Most" views: SfM may drop a view or two and still be usable; measured: all 16 register
# (seeds 0-7; 12 of 12 on a 12-view ring).
MIN_REGISTERED = 13
# Camera centres after the best similarity, relative to the ring radius: 2 % is 6 cm at 3 m,
# a few pixels' worth of parallax at this resolution (measured: 0.5-0.65 %, mean 0.3 %).
MAX_CENTRE_ERROR = 0.02
# Rotation between any two registered cameras against the truth: a pixel is 0.32° here
# (measured: 0.54-0.62° worst pair with the focal length estimated, 0.27° with it given).
MAX_RELATIVE_ROTATION_DEG = 1.5
# Focal length estimated from the images (no intrinsics given) against the truth (measured: 1.0 % short).
MAX_FOCAL_ERROR = 0.03


@pytest.fixture(scope="module")
def capture() -> SyntheticCapture:
    return capture_ring(radius=RADIUS_M, heights=(HEIGHT_M,), per_ring=VIEWS, width=WIDTH, height=HEIGHT,
                        points_per_view=0, textured=True)  # fmt: skip


@pytest.fixture(scope="module")
def sfm(capture: SyntheticCapture, tmp_path_factory: pytest.TempPathFactory) -> PosedImages:
    root = tmp_path_factory.mktemp("sfm")
    write_poses_json(capture.images, root / "poses.json")  # the PNGs SfM reads, in root/images
    return run_sfm(root / "images", root / "work", num_threads=2)


def _angle_deg(rotation: np.ndarray) -> float:
    return float(np.degrees(np.arccos(np.clip((np.trace(rotation) - 1.0) / 2.0, -1.0, 1.0))))


def _detail(image: np.ndarray) -> float:
    """Mean absolute difference between horizontally neighbouring pixels."""
    return float(np.abs(np.diff(image, axis=1)).mean())


def _pairs(capture: SyntheticCapture, sfm: PosedImages) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """(true, SfM) camera-to-world matrices of the registered views, matched by image name."""
    truth = {Path(v.name).with_suffix(".png").name: v.camera for v in capture.images}
    return [truth[v.name].camera_to_world for v in sfm], [v.camera.camera_to_world for v in sfm]


def test_the_textured_capture_differs_from_the_flat_one_only_in_texture(capture: SyntheticCapture) -> None:
    flat = capture_ring(radius=RADIUS_M, heights=(HEIGHT_M,), per_ring=1, width=WIDTH, height=HEIGHT,
                        points_per_view=0)  # fmt: skip
    textured, plain = capture.images.views[0], flat.images.views[0]
    np.testing.assert_array_equal(capture.depths[0], flat.depths[0])  # same geometry
    # Texture marks make neighbouring pixels differ far more than flat shading does.
    assert _detail(textured.image) > 3 * _detail(plain.image)


def test_sfm_registers_most_views_of_the_textured_ring(sfm: PosedImages) -> None:
    assert len(sfm.views) >= MIN_REGISTERED
    assert sfm.points is not None and len(sfm.points) >= 100


def test_sfm_camera_centres_match_the_truth_after_a_similarity(capture: SyntheticCapture, sfm: PosedImages) -> None:
    true_poses, sfm_poses = _pairs(capture, sfm)
    true_centres = np.stack([m[:3, 3] for m in true_poses])
    sfm_centres = np.stack([m[:3, 3] for m in sfm_poses])
    transform = umeyama(sfm_centres, true_centres)
    error = np.linalg.norm(apply_transform(transform, sfm_centres) - true_centres, axis=1)
    assert error.max() < MAX_CENTRE_ERROR * RADIUS_M, f"worst centre error {error.max():.4f} m"


def test_sfm_relative_rotations_match_the_truth(capture: SyntheticCapture, sfm: PosedImages) -> None:
    true_poses, sfm_poses = _pairs(capture, sfm)
    worst = 0.0
    for i in range(len(true_poses)):
        for j in range(i + 1, len(true_poses)):
            true_relative = true_poses[i][:3, :3].T @ true_poses[j][:3, :3]
            sfm_relative = sfm_poses[i][:3, :3].T @ sfm_poses[j][:3, :3]
            worst = max(worst, _angle_deg(true_relative.T @ sfm_relative))
    assert worst < MAX_RELATIVE_ROTATION_DEG, f"worst relative rotation error {worst:.3f}°"


def test_sfm_estimates_one_pinhole_focal_length_near_the_truth(capture: SyntheticCapture, sfm: PosedImages) -> None:
    truth = capture.images.views[0].camera
    for view in sfm:
        assert view.camera.fx == view.camera.fy  # SIMPLE_PINHOLE: square pixels
        assert (view.camera.cx, view.camera.cy) == (WIDTH / 2, HEIGHT / 2)
        assert abs(view.camera.fx / truth.fx - 1.0) < MAX_FOCAL_ERROR


def test_sfm_keeps_given_intrinsics(capture: SyntheticCapture, tmp_path: Path) -> None:
    truth = capture.images.views[0].camera
    write_poses_json(capture.images, tmp_path / "poses.json")
    posed = run_sfm(tmp_path / "images", tmp_path / "work", num_threads=2,
                    intrinsics=(truth.fx, truth.fy, truth.cx, truth.cy))  # fmt: skip
    assert len(posed.views) >= MIN_REGISTERED
    for view in posed:
        np.testing.assert_allclose(view.camera.K, truth.K, rtol=1e-9)


def test_sfm_refuses_intrinsics_without_a_positive_focal_length(tmp_path: Path) -> None:
    with pytest.raises(ViewsError, match=r"intrinsics must be \(fx, fy, cx, cy\)"):
        run_sfm(tmp_path, tmp_path / "work", intrinsics=(0.0, 100.0, 50.0, 40.0))


# The true surfaces' ground: a square patch round the scene, about what the ring sees.
GROUND_PATCH_M = 12.0
# SfM points (moved by the camera-centre similarity) against the true surfaces: median and
# 90th percentile distance relative to the ring radius (measured: 1.4 % and 2.6 %; the far
# ground points, up to 8 m away, are the least certain).
MAX_POINT_MEDIAN, MAX_POINT_P90 = 0.03, 0.06


def _scene_mesh(capture: SyntheticCapture) -> trimesh.Trimesh:
    """The capture scene's true surfaces: a ground patch and the assets' box and cylinder geoms."""
    world = MujocoWorld.from_scene(capture.scene)
    model, data = world.model, world.data
    parts = [trimesh.creation.box(extents=(GROUND_PATCH_M, GROUND_PATCH_M, 0.1),
                                  transform=trimesh.transformations.translation_matrix((0, 0, -0.05)))]  # fmt: skip
    for g in range(model.ngeom):
        size, kind = model.geom_size[g], model.geom_type[g]
        if np.linalg.norm(data.geom_xpos[g][:2]) > 2.0:
            continue  # the parked ego
        if kind == mujoco.mjtGeom.mjGEOM_BOX:
            part = trimesh.creation.box(extents=2 * size)
        elif kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
            part = trimesh.creation.cylinder(radius=size[0], height=2 * size[1])
        else:
            continue  # the ground plane: the patch above stands for it
        pose = np.eye(4)
        pose[:3, :3] = data.geom_xmat[g].reshape(3, 3)
        pose[:3, 3] = data.geom_xpos[g]
        parts.append(part.apply_transform(pose))
    return trimesh.util.concatenate(parts)


def test_sfm_points_lie_on_the_true_surfaces_after_the_camera_similarity(
    capture: SyntheticCapture, sfm: PosedImages
) -> None:
    true_poses, sfm_poses = _pairs(capture, sfm)
    transform = umeyama(np.stack([m[:3, 3] for m in sfm_poses]), np.stack([m[:3, 3] for m in true_poses]))
    assert sfm.points is not None
    points = apply_transform(transform, sfm.points.astype(np.float64))
    check = check_alignment(points, surface_samples(_scene_mesh(capture)))
    assert check.median_m < MAX_POINT_MEDIAN * RADIUS_M and check.p90_m < MAX_POINT_P90 * RADIUS_M, check
