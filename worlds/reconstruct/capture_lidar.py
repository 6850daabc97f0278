"""A synthetic LIDAR capture the project makes itself: a known scene scanned from several places.

A small drivetwin Scene (flat ground, the ego car and a road barrier by default) is compiled
through the MuJoCo adapter and scanned by the project's `Lidar` (MuJoCo ray casting) from
fixed world mounts, with Gaussian range noise. The ground truth is the triangle mesh of the
very collision geoms the rays hit, so reconstruction can be measured against it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np
import numpy.typing as npt
import trimesh
from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.scene import AssetInstance, Bounds, Building, PhysicsProps, Pose, Scene
from drivetwin.worlds.sensors import Lidar, Mount, SensorError

__all__ = ["LidarCapture", "capture_scene", "default_capture_scene", "scene_truth_mesh"]

F64 = npt.NDArray[np.float64]
# Half-size of the default scene's square of ground: room for a car, a barrier and the sensors.
DEFAULT_HALF_EXTENT_M = 8.0
# A survey tripod LIDAR head sits about this high.
DEFAULT_SENSOR_HEIGHT_M = 1.8
# Sensors stand on a circle this far from the scene centre, looking at the objects from all sides.
DEFAULT_SENSOR_RADIUS_M = 6.0
# 1-sigma range noise of a survey-grade spinning LIDAR (a VLP-16 quotes about 3 cm, 2 sigma).
DEFAULT_RANGE_NOISE_M = 0.01
# Rays beyond this would leave the default scene's ground.
DEFAULT_RANGE_M = 12.0
# Facets of a cylinder in the truth mesh: chord error of a 0.33 m wheel stays under 3 mm.
TRUTH_CYLINDER_SECTIONS = 32


@dataclass
class LidarCapture:
    """Scans [K][N_k,3] (world frame, metres), sensor origins [K,3] and the true scene mesh."""

    scans: list[F64]
    origins: F64
    truth: trimesh.Trimesh
    scene: Scene
    range_noise_m: float


def _asset(asset_id: str, name: str, x: float, y: float, yaw: float) -> AssetInstance:
    mass = category(name).mass
    return AssetInstance(
        id=asset_id, category=name, pose=Pose(x=x, y=y, yaw=yaw), physics=PhysicsProps(mass=mass, dynamic=False)
    )


def default_capture_scene(half_extent_m: float = DEFAULT_HALF_EXTENT_M) -> Scene:
    """A small world on flat ground: the ego car at the origin, a road barrier and two kiosks.

    The kiosks' walls face two directions, so scans from different places overlap on
    vertical planes that pin ICP in x and y (flat ground alone lets scans slide).
    """
    h = half_extent_m
    bounds = Bounds(xmin=-h, xmax=h, ymin=-h, ymax=h)
    ego = _asset("ego", "ego_vehicle", 0.0, 0.0, 0.0)
    barrier = _asset("road_barrier_1", "road_barrier", 0.5, 2.6, 0.0)
    kiosks = [
        Building(id="kiosk_1", name="kiosk", footprint=[(0.4 * h, -0.95 * h), (0.75 * h, -0.95 * h),
                 (0.75 * h, -0.8 * h), (0.4 * h, -0.8 * h)], height=2.5),
        Building(id="kiosk_2", name="kiosk", footprint=[(-0.95 * h, 0.25 * h), (-0.8 * h, 0.25 * h),
                 (-0.8 * h, 0.75 * h), (-0.95 * h, 0.75 * h)], height=2.5),
    ]  # fmt: skip
    return Scene(name="lidar_capture", bounds=bounds, ego=ego, assets=[barrier], buildings=kiosks)


def _geom_mesh(model: mujoco.MjModel, data: mujoco.MjData, geom: int, bounds: Bounds) -> trimesh.Trimesh | None:
    kind = int(model.geom_type[geom])
    size = model.geom_size[geom]
    mesh: trimesh.Trimesh
    if kind == mujoco.mjtGeom.mjGEOM_PLANE:
        # The ground plane is cut to the scene's bounds: that is all the capture is about.
        extents = [bounds.xmax - bounds.xmin, bounds.ymax - bounds.ymin]
        vertices = np.array([[-0.5, -0.5, 0.0], [0.5, -0.5, 0.0], [0.5, 0.5, 0.0], [-0.5, 0.5, 0.0]])
        vertices[:, :2] *= extents
        vertices[:, :2] += bounds.centre
        return trimesh.Trimesh(vertices, [[0, 1, 2], [0, 2, 3]], process=False)
    if kind == mujoco.mjtGeom.mjGEOM_BOX:
        mesh = trimesh.creation.box(extents=2.0 * size)
    elif kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
        mesh = trimesh.creation.cylinder(radius=size[0], height=2.0 * size[1], sections=TRUTH_CYLINDER_SECTIONS)
    elif kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        mesh = trimesh.creation.icosphere(subdivisions=3, radius=size[0])
    elif kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
        mesh = trimesh.creation.capsule(height=2.0 * size[1], radius=size[0])
    else:
        return None
    pose = np.eye(4)
    pose[:3, :3] = np.asarray(data.geom_xmat[geom]).reshape(3, 3)
    pose[:3, 3] = data.geom_xpos[geom]
    mesh.apply_transform(pose)
    return mesh


def scene_truth_mesh(world: MujocoWorld) -> trimesh.Trimesh:
    """The mesh of every collision geom at the world's current state (the ground cut to bounds)."""
    model, data = world.model, world.data
    meshes = []
    for geom in range(model.ngeom):
        if model.geom_contype[geom] == 0 and model.geom_conaffinity[geom] == 0:
            continue  # visual-only: the LIDAR does not see it either
        mesh = _geom_mesh(model, data, geom, world.scene.bounds)
        if mesh is not None:
            meshes.append(mesh)
    merged = trimesh.util.concatenate(meshes)
    if not isinstance(merged, trimesh.Trimesh):
        raise TypeError("the scene's geoms did not merge into one mesh")
    return merged


def _ring_origins(count: int, radius: float, height: float, centre: tuple[float, float]) -> F64:
    angles = np.arange(count) * (2.0 * math.pi / count) + math.pi / count
    return np.stack(
        [centre[0] + radius * np.cos(angles), centre[1] + radius * np.sin(angles), np.full(count, height)], axis=1
    )


def capture_scene(
    scene: Scene | None = None,
    *,
    origins: Sequence[Sequence[float]] | None = None,
    sensor_count: int = 4,
    channels: int = 32,
    vertical_fov_deg: tuple[float, float] = (-40.0, 10.0),
    horizontal_resolution_deg: float = 0.8,
    range_m: float = DEFAULT_RANGE_M,
    range_noise_m: float = DEFAULT_RANGE_NOISE_M,
    seed: int = 0,
) -> LidarCapture:
    """Scan `scene` (default: `default_capture_scene`) with a LIDAR from several world positions.

    Args:
        origins: sensor positions [K,3] in metres; default ``sensor_count`` on a circle of
            6 m radius at 1.8 m height around the scene centre.
        channels, vertical_fov_deg, horizontal_resolution_deg, range_m: the `Lidar`'s settings.
        range_noise_m: standard deviation of the Gaussian noise added along each ray.
        seed: seed of the noise, so a capture is reproducible.
    """
    if range_noise_m < 0.0 or not math.isfinite(range_noise_m):
        raise SensorError(f"range_noise_m must be a finite value >= 0, got {range_noise_m}")
    scene = scene if scene is not None else default_capture_scene()
    world = MujocoWorld.from_scene(scene)
    mujoco.mj_forward(world.model, world.data)
    if origins is None:
        if sensor_count < 1:
            raise SensorError(f"sensor_count must be at least 1, got {sensor_count}")
        places = _ring_origins(sensor_count, DEFAULT_SENSOR_RADIUS_M, DEFAULT_SENSOR_HEIGHT_M, scene.bounds.centre)
    else:
        places = np.asarray(origins, dtype=np.float64).reshape(-1, 3)
    rng = np.random.default_rng(seed)
    scans: list[F64] = []
    for place in places:
        mount = Mount(asset_id=None, offset=(float(place[0]), float(place[1]), float(place[2])))
        lidar = Lidar(channels, vertical_fov_deg=vertical_fov_deg, horizontal_resolution_deg=horizontal_resolution_deg,
                      range_m=range_m, mount=mount)  # fmt: skip
        points = lidar.scan(world)
        rays = points - place
        lengths = np.linalg.norm(rays, axis=1, keepdims=True)
        noisy: F64 = points + rays / np.maximum(lengths, 1e-9) * rng.normal(0.0, range_noise_m, (len(points), 1))
        # Only the scene's area is captured: MuJoCo's ground plane reaches past its bounds.
        box = scene.bounds
        x, y = noisy[:, 0], noisy[:, 1]
        scans.append(noisy[(x >= box.xmin) & (x <= box.xmax) & (y >= box.ymin) & (y <= box.ymax)])
    return LidarCapture(scans, places, scene_truth_mesh(world), scene, range_noise_m)
