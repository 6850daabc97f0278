"""The LIDAR measures the collision geometry by ray casting, within its range only."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.scene import AssetInstance, Bounds, PhysicsProps, Pose, Scene
from drivetwin.worlds.sensors import Lidar, Mount, SensorError, save_pointcloud

BARRIER_X = 10.0
BARRIER_FRONT_X = BARRIER_X - 0.25  # the barrier's lower block is 0.5 m thick


def _asset(asset_id: str, name: str, x: float, y: float, yaw: float = 0.0) -> AssetInstance:
    return AssetInstance(id=asset_id, category=name, pose=Pose(x=x, y=y, yaw=yaw),
                         physics=PhysicsProps(mass=category(name).mass, dynamic=False))  # fmt: skip


@pytest.fixture(scope="module")
def world() -> MujocoWorld:
    # The barrier's long side faces the origin (turned 90 degrees).
    barrier = _asset("road_barrier_1", "road_barrier", BARRIER_X, 0.0, yaw=math.pi / 2)
    scene = Scene(name="lidar", bounds=Bounds(xmin=-50, xmax=50, ymin=-50, ymax=50),
                  ego=_asset("ego", "ego_vehicle", -20.0, 0.0), assets=[barrier])  # fmt: skip
    return MujocoWorld.from_scene(scene)


def test_a_ray_hits_a_barrier_at_its_known_distance(world: MujocoWorld) -> None:
    lidar = Lidar(1, vertical_fov_deg=(0.0, 0.0), horizontal_resolution_deg=0.5, range_m=50.0,
                  mount=Mount(asset_id=None, offset=(0.0, 0.0, 0.25)))  # fmt: skip
    points = lidar.scan(world)
    ahead = points[np.abs(points[:, 1]) < 0.05]
    assert len(ahead) == 1
    assert ahead[0, 0] == pytest.approx(BARRIER_FRONT_X, abs=0.02)
    assert ahead[0, 2] == pytest.approx(0.25, abs=1e-6)


def test_nothing_beyond_the_range_is_reported(world: MujocoWorld) -> None:
    mount = Mount(asset_id=None, offset=(0.0, 0.0, 0.25))
    short = Lidar(1, vertical_fov_deg=(0.0, 0.0), range_m=BARRIER_FRONT_X - 0.5, mount=mount)
    assert len(short.scan(world)) == 0
    ring = Lidar(8, vertical_fov_deg=(-30.0, -2.0), range_m=6.0, mount=Mount(None, (0, 0, 2.0)))
    points = ring.scan(world)
    assert len(points) > 0  # the steep rings reach the ground within 6 m
    assert np.linalg.norm(points - [0.0, 0.0, 2.0], axis=1).max() <= 6.0 + 1e-9


def test_a_lidar_on_the_ego_does_not_see_the_ego(world: MujocoWorld) -> None:
    # Mounted inside the ego's own chassis: without excluding it every ray would stop there.
    lidar = Lidar(16, horizontal_resolution_deg=2.0, range_m=60.0, mount=Mount("ego", (0, 0, 1.0)))
    points = lidar.scan(world)
    ego_xy = world.data.xpos[world.body_id("ego")][:2]
    assert len(points) > 100
    assert np.linalg.norm(points[:, :2] - ego_xy, axis=1).min() > 2.4  # beyond the ego's body


def test_visual_only_road_paint_is_not_a_lidar_target(world: MujocoWorld) -> None:
    lidar = Lidar(4, vertical_fov_deg=(-40.0, -20.0), range_m=30.0, mount=Mount(None, (0, 0, 2.0)))
    ground = lidar.scan(world)
    assert np.abs(ground[:, 2]).max() < 1e-6  # the ground plane, not paint a few mm above it


def test_point_clouds_save_as_ply_and_npy(tmp_path) -> None:  # type: ignore[no-untyped-def]
    points = np.array([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
    np.testing.assert_array_equal(np.load(save_pointcloud(points, tmp_path / "a.npy")), points)
    data = (tmp_path / "a.ply").read_bytes() if save_pointcloud(points, tmp_path / "a.ply") else b""
    header, body = data.split(b"end_header\n")
    assert b"element vertex 2" in header
    np.testing.assert_array_equal(np.frombuffer(body, "<f4").reshape(-1, 3), points)
    with pytest.raises(SensorError, match=r"\.ply or \.npy"):
        save_pointcloud(points, tmp_path / "a.txt")


def test_a_lidar_refuses_settings_it_cannot_scan_with() -> None:
    with pytest.raises(SensorError, match="at least 1 channel"):
        Lidar(0)
    with pytest.raises(SensorError, match="horizontal_resolution_deg"):
        Lidar(16, horizontal_resolution_deg=0.0)
