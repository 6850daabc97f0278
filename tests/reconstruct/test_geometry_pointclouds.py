"""Point clouds are read from PLY, PCD, LAS/LAZ and NumPy files; bad input is a typed error."""

from __future__ import annotations

from pathlib import Path

import laspy
import numpy as np
import pytest
from drivetwin.worlds.reconstruct.pointclouds import PointCloud, PointCloudError, read_point_cloud, write_ply

POINTS = np.array([[0.0, 0.0, 0.0], [1.0, 2.0, 3.0], [-4.5, 0.25, 1.5], [2.0, -1.0, 0.5]])
COLORS = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.5, 0.5, 0.5]])


def _write_las(path: Path) -> None:
    header = laspy.LasHeader(point_format=3, version="1.2")
    header.scales = np.array([0.001, 0.001, 0.001])
    header.offsets = np.zeros(3)
    las = laspy.LasData(header)
    las.x, las.y, las.z = POINTS[:, 0], POINTS[:, 1], POINTS[:, 2]
    rgb = np.round(COLORS * 65535).astype(np.uint16)
    las.red, las.green, las.blue = rgb[:, 0], rgb[:, 1], rgb[:, 2]
    las.write(path)


def test_ply_round_trip_keeps_points_colours_and_normals(tmp_path: Path) -> None:
    normals = np.tile([0.0, 0.0, 1.0], (4, 1))
    path = write_ply(PointCloud(POINTS, COLORS, normals), tmp_path / "cloud.ply")
    cloud = read_point_cloud(path)
    np.testing.assert_allclose(cloud.points, POINTS, atol=1e-6)
    assert cloud.colors is not None and cloud.normals is not None
    np.testing.assert_allclose(cloud.colors, COLORS, atol=1 / 255)
    np.testing.assert_allclose(cloud.normals, normals, atol=1e-6)


def test_pcd_files_are_read(tmp_path: Path) -> None:
    import open3d as o3d

    path = tmp_path / "cloud.pcd"
    o3d.io.write_point_cloud(str(path), o3d.geometry.PointCloud(o3d.utility.Vector3dVector(POINTS)))
    np.testing.assert_allclose(read_point_cloud(path).points, POINTS, atol=1e-6)


@pytest.mark.parametrize("suffix", [".las", ".laz"])
def test_las_and_laz_files_are_read_with_colours(tmp_path: Path, suffix: str) -> None:
    path = tmp_path / f"cloud{suffix}"
    _write_las(path)
    cloud = read_point_cloud(path)
    np.testing.assert_allclose(cloud.points, POINTS, atol=1e-3)
    assert cloud.colors is not None
    np.testing.assert_allclose(cloud.colors, COLORS, atol=1e-4)


def test_npy_with_xyz_rgb_columns_gives_colours(tmp_path: Path) -> None:
    np.save(tmp_path / "a.npy", np.hstack([POINTS, COLORS * 255]))
    cloud = read_point_cloud(tmp_path / "a.npy")
    np.testing.assert_allclose(cloud.points, POINTS)
    assert cloud.colors is not None
    np.testing.assert_allclose(cloud.colors, COLORS)


def test_npz_with_points_and_colors_is_read(tmp_path: Path) -> None:
    np.savez(tmp_path / "a.npz", points=POINTS, colors=COLORS)
    cloud = read_point_cloud(tmp_path / "a.npz")
    np.testing.assert_allclose(cloud.points, POINTS)
    assert cloud.colors is not None
    np.testing.assert_allclose(cloud.colors, COLORS)


def test_a_missing_file_is_named(tmp_path: Path) -> None:
    with pytest.raises(PointCloudError, match="not found"):
        read_point_cloud(tmp_path / "nothing.ply")


def test_an_unknown_extension_lists_the_allowed_ones(tmp_path: Path) -> None:
    (tmp_path / "cloud.xyzrgb").write_text("0 0 0\n")
    with pytest.raises(PointCloudError, match=r"allowed: \.ply, \.pcd, \.las, \.laz, \.npy, \.npz"):
        read_point_cloud(tmp_path / "cloud.xyzrgb")


def test_a_badly_shaped_array_says_which_shapes_are_allowed(tmp_path: Path) -> None:
    np.save(tmp_path / "bad.npy", np.zeros((5, 4)))
    with pytest.raises(PointCloudError, match=r"\[N, 3\].*\[N, 6\]"):
        read_point_cloud(tmp_path / "bad.npy")


@pytest.mark.parametrize("name", ["empty.npy", "empty.ply"])
def test_an_empty_cloud_is_refused(tmp_path: Path, name: str) -> None:
    if name.endswith(".npy"):
        np.save(tmp_path / name, np.zeros((0, 3)))
    else:
        (tmp_path / name).write_text("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
                                     "property float y\nproperty float z\nend_header\n")  # fmt: skip
    with pytest.raises(PointCloudError, match=r"empty|no points"):
        read_point_cloud(tmp_path / name)


def test_an_npz_without_points_names_its_arrays(tmp_path: Path) -> None:
    np.savez(tmp_path / "a.npz", xyz=POINTS)
    with pytest.raises(PointCloudError, match=r"needs a 'points' array.*xyz"):
        read_point_cloud(tmp_path / "a.npz")


def test_nan_coordinates_are_refused() -> None:
    with pytest.raises(PointCloudError, match="NaN"):
        PointCloud(np.array([[0.0, np.nan, 0.0]]))
