"""ICP brings two LIDAR scans of the synthetic capture back together after a known offset."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drivetwin.worlds.reconstruct.capture_lidar import capture_scene
from drivetwin.worlds.reconstruct.pointclouds import PointCloud, PointCloudError
from drivetwin.worlds.reconstruct.registration import register_scans, remove_outliers, transform_cloud

VOXEL_M = 0.08
# Measured residuals on these scans: under 1 cm and 0.1 degree; bounds leave room for platforms.
TRANSLATION_TOLERANCE_M = 0.03
ROTATION_TOLERANCE_DEG = 0.3


def _offset(yaw_deg: float, shift: tuple[float, float, float]) -> np.ndarray:
    yaw = math.radians(yaw_deg)
    transform = np.eye(4)
    transform[:3, :3] = [[math.cos(yaw), -math.sin(yaw), 0.0], [math.sin(yaw), math.cos(yaw), 0.0], [0.0, 0.0, 1.0]]
    transform[:3, 3] = shift
    return transform


@pytest.fixture(scope="module")
def scans() -> tuple[PointCloud, PointCloud]:
    # Two nearby stations see mostly the same car, barrier and kiosk walls.
    capture = capture_scene(origins=[(4.2, 4.2, 1.8), (3.0, 5.0, 1.8)], channels=32, horizontal_resolution_deg=0.4,
                            vertical_fov_deg=(-35.0, 15.0))  # fmt: skip
    return PointCloud(capture.scans[0]), PointCloud(capture.scans[1])


def _errors(recovered: np.ndarray, applied: np.ndarray) -> tuple[float, float]:
    residual = recovered @ applied  # identity when ICP undid the offset
    angle = math.degrees(math.acos(np.clip((np.trace(residual[:3, :3]) - 1.0) / 2.0, -1.0, 1.0)))
    return float(np.linalg.norm(residual[:3, 3])), angle


def test_icp_recovers_a_known_offset_between_two_scans(scans: tuple[PointCloud, PointCloud]) -> None:
    applied = _offset(3.0, (0.2, -0.15, 0.05))
    moved = transform_cloud(scans[1], applied)
    result = register_scans([scans[0], moved], voxel_m=VOXEL_M)
    shift, angle = _errors(result.transforms[1], applied)
    assert shift < TRANSLATION_TOLERANCE_M
    assert angle < ROTATION_TOLERANCE_DEG
    assert result.fitness[1] > 0.5


def test_coarse_alignment_recovers_an_offset_too_large_for_icp_alone(scans: tuple[PointCloud, PointCloud]) -> None:
    applied = _offset(90.0, (3.0, -2.0, 0.0))
    moved = transform_cloud(scans[1], applied)
    plain = register_scans([scans[0], moved], voxel_m=VOXEL_M)
    coarse = register_scans([scans[0], moved], voxel_m=VOXEL_M, coarse=True)
    assert _errors(plain.transforms[1], applied)[0] > 0.1  # ICP alone is stuck in a local minimum
    shift, angle = _errors(coarse.transforms[1], applied)
    assert shift < TRANSLATION_TOLERANCE_M
    assert angle < ROTATION_TOLERANCE_DEG


def test_outlier_removal_drops_isolated_points(scans: tuple[PointCloud, PointCloud]) -> None:
    strays = np.array([[0.0, 0.0, 6.0], [3.0, -3.0, 5.0], [-4.0, 1.0, 7.5]])
    noisy = PointCloud(np.vstack([scans[0].points, strays]))
    kept, index = remove_outliers(noisy, voxel_m=VOXEL_M)
    assert not np.isin(np.arange(len(scans[0].points), len(noisy)), index).any()
    assert len(kept) > 0.9 * len(scans[0])


def test_registration_refuses_bad_settings(scans: tuple[PointCloud, PointCloud]) -> None:
    with pytest.raises(PointCloudError, match="voxel_m must be a positive"):
        register_scans(list(scans), voxel_m=0.0)
    with pytest.raises(PointCloudError, match="give at least one"):
        register_scans([], voxel_m=VOXEL_M)
    with pytest.raises(PointCloudError, match="one per scan"):
        register_scans(list(scans), voxel_m=VOXEL_M, initial=[np.eye(4)])
