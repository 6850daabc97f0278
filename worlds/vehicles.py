"""Ackermann vehicle control: steer geometry, a PI speed loop and pure-pursuit steering.

A vehicle body (see mujoco_bodies) has a free chassis, velocity servos on the rear wheels
and position servos on the front steer hinges. `VehicleController` turns a wanted speed and
path curvature into those servo commands; `pure_pursuit_curvature` turns a target point
ahead on a path into a curvature. Frames: the bicycle model's reference point is the centre
of the rear axle; curvature is positive for a left turn.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import mujoco
from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.rotation import yaw_of_quat, yaw_quat
from drivetwin.worlds.scene import AssetInstance

__all__ = [
    "AckermannGeometry",
    "SpeedController",
    "VehicleController",
    "VehicleState",
    "ackermann_angles",
    "pure_pursuit_curvature",
]

# PI gains on the speed error (m/s → m/s of extra wheel-speed command); the drive servo
# itself is a stiff proportional loop, so these only remove its steady-state lag.
SPEED_KP = 0.6
SPEED_KI = 0.8
# Anti-windup: the integral may add at most this much wheel speed (m/s).
SPEED_INTEGRAL_LIMIT_MPS = 3.0


def ackermann_angles(curvature: float, wheelbase: float, track: float) -> tuple[float, float]:
    """Left and right front-wheel steer angles (rad) that turn about one centre.

    `curvature` is 1/R of the rear-axle centre's path (positive left). Each wheel at lateral
    offset y points at the turn centre: δ = atan2(L·κ, 1 − κ·y), so the inner wheel turns more.
    """
    left = math.atan2(wheelbase * curvature, 1.0 - curvature * track / 2.0)
    right = math.atan2(wheelbase * curvature, 1.0 + curvature * track / 2.0)
    if abs(curvature) > 1e-12 and (1.0 - abs(curvature) * track / 2.0) <= 0.0:
        # A turn centre inside the track is not drivable; fall back to the bicycle angle.
        left = right = math.atan(wheelbase * curvature)
    return left, right


def pure_pursuit_curvature(x: float, y: float, yaw: float, target_x: float, target_y: float) -> float:
    """The curvature of the arc from the rear axle (x, y, heading yaw) through the target.

    κ = 2·sin(α) / ℓ, with α the target's bearing from the heading and ℓ its distance. A
    target behind (|α| > 90°) is steered for as one abeam on its side: sin(α) shrinks past 90°,
    so a vehicle facing away from its route would turn ever more gently, and not at all with
    the route straight behind it.
    """
    dx, dy = target_x - x, target_y - y
    distance = math.hypot(dx, dy)
    if distance < 1e-9:
        return 0.0
    alpha = math.remainder(math.atan2(dy, dx) - yaw, math.tau)
    alpha = max(-math.pi / 2, min(math.pi / 2, alpha))
    return 2.0 * math.sin(alpha) / distance


@dataclass
class SpeedController:
    """A PI loop on forward speed with a clamped integral (anti-windup)."""

    kp: float = SPEED_KP
    ki: float = SPEED_KI
    limit: float = SPEED_INTEGRAL_LIMIT_MPS
    integral: float = 0.0

    def command(self, wanted: float, measured: float, dt: float) -> float:
        """The wheel-rim speed (m/s) to ask the drive servos for."""
        error = wanted - measured
        self.integral = max(-self.limit, min(self.limit, self.integral + self.ki * error * dt))
        return wanted + self.kp * error + self.integral

    def reset(self) -> None:
        self.integral = 0.0


@dataclass(frozen=True)
class AckermannGeometry:
    """The dimensions steering needs: wheelbase, track, wheel radius, steer limit (m, rad)."""

    wheelbase: float
    track: float
    wheel_radius: float
    max_steer: float

    @classmethod
    def of(cls, asset: AssetInstance) -> AckermannGeometry:
        cat = category(asset.category)
        wheels = [p for p in cat.parts if p.role == "wheel"]
        if cat.wheelbase is None or not wheels:
            raise ValueError(f"{asset.category!r} is not a wheeled vehicle")
        ys = [p.pos[1] for p in wheels]
        return cls(
            wheelbase=cat.wheelbase * asset.scale,
            track=(max(ys) - min(ys)) * asset.scale,
            wheel_radius=wheels[0].size[0] * asset.scale,
            max_steer=cat.max_steer or 0.6,
        )

    @property
    def min_turn_radius(self) -> float:
        return self.wheelbase / math.tan(self.max_steer)


@dataclass(frozen=True)
class VehicleState:
    """The rear-axle centre, heading and forward speed of a vehicle right now."""

    x: float
    y: float
    yaw: float
    speed: float


@dataclass
class VehicleController:
    """Drives one vehicle body: speed and curvature in, servo commands out."""

    asset_id: str
    geometry: AckermannGeometry
    speed_loop: SpeedController = field(default_factory=SpeedController)
    _generation: int = -1
    _qpos: int = 0
    _qvel: int = 0
    _drive: tuple[int, int] = (0, 0)
    _steer: tuple[int, int] = (0, 0)

    def bind(self, world: MujocoWorld) -> None:
        """Look up joint and actuator ids again (they change on every recompile)."""
        if self._generation == world.generation:
            return
        model = world.model
        joint = world.joint_id(f"{self.asset_id}/free")
        self._qpos = int(model.jnt_qposadr[joint])
        self._qvel = int(model.jnt_dofadr[joint])
        self._drive = (
            world.actuator_id(f"{self.asset_id}/drive_rl"),
            world.actuator_id(f"{self.asset_id}/drive_rr"),
        )
        self._steer = (
            world.actuator_id(f"{self.asset_id}/steer_fl"),
            world.actuator_id(f"{self.asset_id}/steer_fr"),
        )
        self._generation = world.generation

    def state(self, data: mujoco.MjData) -> VehicleState:
        """Rear-axle position, heading and forward speed from the chassis free joint."""
        q = data.qpos[self._qpos : self._qpos + 7]
        yaw = yaw_of_quat(q[3:7])
        half = self.geometry.wheelbase / 2.0
        x = float(q[0]) - half * math.cos(yaw)
        y = float(q[1]) - half * math.sin(yaw)
        vx, vy = float(data.qvel[self._qvel]), float(data.qvel[self._qvel + 1])
        return VehicleState(x, y, yaw, vx * math.cos(yaw) + vy * math.sin(yaw))

    def drive(self, data: mujoco.MjData, speed: float, curvature: float, dt: float) -> None:
        """Ask for a forward speed (m/s) along an arc of `curvature` (1/m, positive left)."""
        state = self.state(data)
        rim_speed = self.speed_loop.command(speed, state.speed, dt)
        omega = rim_speed / self.geometry.wheel_radius
        for actuator in self._drive:
            data.ctrl[actuator] = omega
        limit = self.geometry.max_steer
        left, right = ackermann_angles(curvature, self.geometry.wheelbase, self.geometry.track)
        data.ctrl[self._steer[0]] = max(-limit, min(limit, left))
        data.ctrl[self._steer[1]] = max(-limit, min(limit, right))

    def brake(self, data: mujoco.MjData) -> None:
        """Hold the rear wheels still and the steering straight (a parked vehicle)."""
        for actuator in (*self._drive, *self._steer):
            data.ctrl[actuator] = 0.0
        self.speed_loop.reset()

    def teleport(self, data: mujoco.MjData, x: float, y: float, yaw: float) -> None:
        """Put the chassis at (x, y) heading `yaw`, keeping its forward speed (for looping)."""
        speed = self.state(data).speed
        q = data.qpos
        q[self._qpos] = x
        q[self._qpos + 1] = y
        q[self._qpos + 3 : self._qpos + 7] = yaw_quat(yaw)
        v = data.qvel
        v[self._qvel : self._qvel + 6] = 0.0
        v[self._qvel] = speed * math.cos(yaw)
        v[self._qvel + 1] = speed * math.sin(yaw)
