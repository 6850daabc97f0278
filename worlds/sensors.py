"""Sensors on the simulated world: a ray-cast LIDAR, RGB / depth cameras, and a rig that
fires each at its own rate from the simulation loop.

Sensor frames follow vehicle convention (x forward, y left, z up) and are mounted on an
asset's MuJoCo body (moving with it) or fixed in the world. The LIDAR casts rays with
MuJoCo against the collision geometry (visual-only road paint is skipped); cameras render
through the hybrid renderer, so they see splats as well as meshes.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import mujoco
import numpy as np
import numpy.typing as npt
from drivetwin.worlds.mujoco_adapter import MujocoWorld, collision_groups
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.hybrid import Frame, HybridRenderer
from drivetwin.worlds.rotation import yaw_pitch_matrix

__all__ = ["CameraSensor", "Lidar", "Mount", "Reading", "SensorError", "SensorRig",
           "save_pointcloud"]  # fmt: skip

F64 = npt.NDArray[np.float64]
Lock = AbstractContextManager[Any]
# Sensor frame (x forward, y left, z up) to OpenCV camera axes (x right, y down, z forward):
# the columns are the camera axes written in the sensor frame.
SENSOR_TO_OPENCV = np.array([[0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]])
# A roof-top LIDAR on a car sits about this high above the body origin (on the ground).
DEFAULT_MOUNT_HEIGHT_M = 2.0
# Readings due within this much of a tick fire on it (float rounding of sim time).
DUE_SLACK_S = 1e-9
MAX_RAYS = 2_000_000  # a guard against a typo such as 0.0001 degrees per step


class SensorError(ValueError):
    """A sensor was configured with values it cannot work with."""


@dataclass(frozen=True)
class Mount:
    """Where a sensor sits: on an asset's body (``asset_id``) or fixed in the world (None).

    ``offset`` (metres), ``yaw`` and ``pitch`` (radians, positive pitch looks down) are in
    the body's frame, or in the world frame for a fixed mount.
    """

    asset_id: str | None = "ego"
    offset: tuple[float, float, float] = (0.0, 0.0, DEFAULT_MOUNT_HEIGHT_M)
    yaw: float = 0.0
    pitch: float = 0.0

    def sensor_to_world(self, world: MujocoWorld) -> F64:
        """The [4,4] sensor-to-world transform at the world's current state."""
        local = np.eye(4)
        local[:3, :3] = yaw_pitch_matrix(self.yaw, self.pitch)
        local[:3, 3] = self.offset
        if self.asset_id is None:
            return local
        body = world.body_id(self.asset_id)
        parent = np.eye(4)
        parent[:3, :3] = np.asarray(world.data.xmat[body]).reshape(3, 3)
        parent[:3, 3] = world.data.xpos[body]
        return parent @ local


def _as_mount(mount: Mount | str | None) -> Mount:
    if isinstance(mount, Mount):
        return mount
    return Mount(asset_id=mount)


class Lidar:
    """A spinning multi-channel LIDAR simulated by MuJoCo ray casting.

    Args:
        channels: number of laser rings, spread evenly over ``vertical_fov_deg``.
        horizontal_resolution_deg: azimuth step of one revolution (360 / step rays a ring).
        range_m: farthest return; nothing beyond it is reported.
        rate_hz: revolutions (scans) per second, used by `SensorRig`.
        mount: a Mount, or an asset id (mounted on its roof), or None (world origin).
    """

    def __init__(
        self,
        channels: int = 16,
        *,
        vertical_fov_deg: tuple[float, float] = (-15.0, 15.0),
        horizontal_resolution_deg: float = 1.0,
        range_m: float = 100.0,
        rate_hz: float = 10.0,
        mount: Mount | str | None = "ego",
        name: str = "lidar",
    ) -> None:
        low, high = vertical_fov_deg
        if channels < 1:
            raise SensorError(f"a LIDAR needs at least 1 channel, got {channels}")
        if not -90.0 <= low <= high <= 90.0:
            raise SensorError(f"vertical_fov_deg must be (low, high) within ±90, got {vertical_fov_deg}")
        if not 0.0 < horizontal_resolution_deg <= 360.0:
            raise SensorError(f"horizontal_resolution_deg must be in (0, 360], got {horizontal_resolution_deg}")
        if not (range_m > 0.0 and math.isfinite(range_m)) or not rate_hz > 0.0:
            raise SensorError(f"range_m and rate_hz must be positive, got {range_m}, {rate_hz}")
        azimuths = round(360.0 / horizontal_resolution_deg)
        if channels * azimuths > MAX_RAYS:
            raise SensorError(f"{channels * azimuths} rays per scan exceeds the limit {MAX_RAYS}")
        self.name = name
        self.channels = channels
        self.range_m = float(range_m)
        self.rate_hz = float(rate_hz)
        self.mount = _as_mount(mount)
        elevation = np.radians(np.linspace(low, high, channels) if channels > 1 else [low])
        azimuth = np.radians(np.arange(azimuths) * (360.0 / azimuths))
        el, az = np.meshgrid(elevation, azimuth, indexing="ij")
        self.directions: F64 = np.stack(
            [np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)], axis=-1
        ).reshape(-1, 3)

    def scan(self, world: MujocoWorld, lock: Lock | None = None) -> F64:
        """One revolution: world-frame points [N,3] of every return within range."""
        with lock if lock is not None else nullcontext():
            model, data = world.model, world.data
            pose = self.mount.sensor_to_world(world)
            own = world.body_id(self.mount.asset_id) if self.mount.asset_id is not None else -1
            origin = pose[:3, 3].copy()
            rays = self.directions @ pose[:3, :3].T
            count = len(rays)
            geom = np.full(count, -1, np.int32)
            dist = np.full(count, -1.0)
            mujoco.mj_multiRay(model, data, origin, np.ascontiguousarray(rays).reshape(-1),
                               collision_groups(model), 1, own, geom, dist, None, count,
                               self.range_m)  # fmt: skip
            hit = (geom >= 0) & (dist >= 0.0) & (dist <= self.range_m)
            if own >= 0:
                # The mount body is excluded by MuJoCo; its wheels (child bodies) too, here.
                root = model.body_rootid[own]
                hit &= model.body_rootid[model.geom_bodyid[np.maximum(geom, 0)]] != root
        points: F64 = origin + rays[hit] * dist[hit, None]
        return points


@dataclass
class CameraSensor:
    """An RGB, depth or RGB-D camera on a mount, drawn by the hybrid renderer."""

    name: str
    width: int = 640
    height: int = 360
    fovy_deg: float = 60.0
    mount: Mount = field(default_factory=lambda: Mount(offset=(0.5, 0.0, 1.5)))
    rate_hz: float = 10.0
    kind: Literal["rgb", "depth", "rgbd"] = "rgbd"

    def __post_init__(self) -> None:
        if not 0.0 < self.fovy_deg < 180.0 or not self.rate_hz > 0.0:
            raise SensorError(f"{self.name}: need 0 < fovy_deg < 180 and rate_hz > 0")

    def camera(self, world: MujocoWorld) -> Camera:
        """The pinhole camera at the mount's current pose (OpenCV axes)."""
        sensor_to_world = self.mount.sensor_to_world(world)
        camera_to_world = np.eye(4)
        camera_to_world[:3, :3] = sensor_to_world[:3, :3] @ SENSOR_TO_OPENCV
        camera_to_world[:3, 3] = sensor_to_world[:3, 3]
        focal = 0.5 * self.height / math.tan(math.radians(self.fovy_deg) / 2)
        return Camera(width=self.width, height=self.height, fx=focal, fy=focal,
                      cx=self.width / 2, cy=self.height / 2,
                      world_to_camera=np.linalg.inv(camera_to_world).astype(np.float64))  # fmt: skip


@dataclass
class Reading:
    """One sensor output: a point cloud (LIDAR) or a rendered frame (camera), with its time."""

    sensor: str
    time: float
    points: F64 | None = None
    frame: Frame | None = None


Sensor = Lidar | CameraSensor


class SensorRig:
    """Sensors fired by rate from the simulation loop: call `tick` every step or frame."""

    def __init__(
        self,
        sensors: Sequence[Sensor] = (),
        *,
        renderer: HybridRenderer | None = None,
        lock: Lock | None = None,
    ) -> None:
        self.renderer = renderer
        self.lock = lock
        self.sensors: dict[str, Sensor] = {}
        self._schedule: dict[str, tuple[float, int]] = {}  # (first tick time, next index)
        for sensor in sensors:
            self.add(sensor)

    def add(self, sensor: Sensor) -> None:
        """Add a sensor; it fires on the next tick, then every 1 / rate_hz seconds."""
        if sensor.name in self.sensors:
            raise SensorError(f"a sensor named {sensor.name!r} is already on the rig")
        if isinstance(sensor, CameraSensor) and self.renderer is None:
            raise SensorError(f"camera {sensor.name!r} needs a rig made with a renderer")
        self.sensors[sensor.name] = sensor

    def tick(self, sim_time: float, world: MujocoWorld) -> dict[str, Reading]:
        """Readings of every sensor due at ``sim_time`` (missed periods are skipped)."""
        readings: dict[str, Reading] = {}
        for name, sensor in self.sensors.items():
            start, due_index = self._schedule.setdefault(name, (sim_time, 0))
            period = 1.0 / sensor.rate_hz
            # Times are start + k * period (no summed periods, so no drift or double fires).
            if sim_time + DUE_SLACK_S < start + due_index * period:
                continue
            elapsed = math.floor((sim_time - start) / period + DUE_SLACK_S)
            self._schedule[name] = (start, elapsed + 1)
            if isinstance(sensor, Lidar):
                readings[name] = Reading(name, sim_time, points=sensor.scan(world, self.lock))
            else:
                assert self.renderer is not None
                with self.lock if self.lock is not None else nullcontext():
                    camera = sensor.camera(world)
                frame = self.renderer.render(camera)
                readings[name] = Reading(name, sim_time, frame=frame)
        return readings


def save_pointcloud(points: npt.ArrayLike, path: str | Path) -> Path:
    """Write points [N,3] (metres) as .npy (float32) or a binary little-endian .ply."""
    target = Path(path)
    cloud = np.asarray(points, dtype=np.float32).reshape(-1, 3)
    target.parent.mkdir(parents=True, exist_ok=True)
    if target.suffix == ".npy":
        np.save(target, cloud)
    elif target.suffix == ".ply":
        header = ("ply\nformat binary_little_endian 1.0\n"
                  f"element vertex {len(cloud)}\nproperty float x\nproperty float y\n"
                  "property float z\nend_header\n")  # fmt: skip
        with open(target, "wb") as fh:
            fh.write(header.encode("ascii"))
            fh.write(cloud.astype("<f4").tobytes())
    else:
        raise SensorError(f"point clouds are saved as .ply or .npy, got {target.name!r}")
    return target
