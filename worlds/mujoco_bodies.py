"""MjSpec bodies for scene assets: one body named by the asset id, geoms from catalog parts.

How an asset takes part in the physics follows its category's `motion`:
- vehicle: a free chassis with four hinged wheel bodies (front ones also steer), a velocity
  actuator on each rear wheel (drive and brake) and a position actuator on each front steer;
- walker: a kinematic mocap body moved along its path by its behaviour (it still collides);
- prop / static: a free body when `physics.dynamic`, otherwise welded to the world.
A reconstructed (packaged) category collides as its convex parts, one mesh geom each.
Element names derive from the body's name (`NAME/wheel_fl`, `NAME/drive_rl`, ...) so that
state and controls can be found again after every recompile; the MuJoCo adapter names
bodies by pool slot and maps asset ids to them (drivetwin.worlds.mujoco_pool).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import mujoco
from drivetwin.worlds.catalog import Category, Part, category
from drivetwin.worlds.packages import package_hulls
from drivetwin.worlds.rotation import yaw_quat
from drivetwin.worlds.scene import AssetInstance, Pose

__all__ = [
    "WHEEL_CORNERS",
    "BodyKind",
    "add_asset_body",
    "body_kind",
    "geom_size",
    "hull_mesh_name",
    "part_rgba",
    "part_volume",
    "set_body_frame",
    "wheel_corner",
]

BodyKind = Literal["vehicle", "mocap", "free", "welded"]
WHEEL_CORNERS = ("fl", "fr", "rl", "rr")
# Share of a vehicle's mass in each wheel (a car wheel and tyre is 1-3 % of the car).
WHEEL_MASS_FRACTION = 0.025
# Drive servo stiffness as a time constant: a speed error is halved in about this long.
DRIVE_TIME_CONSTANT_S = 0.3
# Rear-axle torque limit as a multiple of the weight the driven wheels carry (μ ≈ 1 tyres).
DRIVE_TORQUE_WEIGHT_FACTOR = 1.2
# Steer servo: stiff enough to turn a loaded tyre against its scrub torque within a
# hundredth of a radian, damped critically.
STEER_KP_PER_KG = 40.0
STEER_DAMPRATIO = 1.0
# Steer rotor inertia sets the servo's bandwidth (rad/s): kp / armature = bandwidth².
# 60 rad/s settles in ~0.05 s yet stays well inside the explicit-step stability limit.
STEER_BANDWIDTH = 60.0
# Rotor inertia added to wheel joints, as a multiple of the wheel's own; keeps the stiff
# drive and steer servos stable at a few-millisecond timestep.
WHEEL_ARMATURE_FACTOR = 2.0
STANDARD_GRAVITY = 9.81
# Spec meshes of packaged assets' convex parts start with this (never a static prefix).
HULL_MESH_PREFIX = "asset/"

_Y_AXIS_QUAT = (math.cos(math.pi / 4), math.sin(math.pi / 4), 0.0, 0.0)
_X_AXIS_QUAT = (math.cos(math.pi / 4), 0.0, math.sin(math.pi / 4), 0.0)


def body_kind(asset: AssetInstance, cat: Category | None = None) -> BodyKind:
    """How `asset` is modelled in MuJoCo (see the module docstring)."""
    cat = cat or category(asset.category)
    if cat.motion == "vehicle":
        return "vehicle"
    if cat.motion == "walker":
        return "mocap"
    if cat.motion == "prop" and asset.physics.dynamic:
        return "free"
    return "welded"


def part_volume(part: Part) -> float:
    """The volume of an unscaled part in cubic metres (used to share mass among parts)."""
    size = [float(s) for s in part.size]
    if part.shape == "box":
        return 8.0 * size[0] * size[1] * size[2]
    if part.shape == "cylinder":
        return math.pi * size[0] ** 2 * 2.0 * size[1]
    return 4.0 / 3.0 * math.pi * size[0] ** 3


def geom_size(part: Part, scale: float) -> list[float]:
    """MuJoCo's size triple for a part scaled by `scale` (same half-size conventions)."""
    sizes = [s * scale for s in part.size]
    return [*sizes, 0.0, 0.0, 0.0][:3]


def _geom_type(part: Part) -> mujoco.mjtGeom:
    return {
        "box": mujoco.mjtGeom.mjGEOM_BOX,
        "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER,
        "sphere": mujoco.mjtGeom.mjGEOM_SPHERE,
    }[part.shape]


def _add_part_geom(
    body: mujoco.MjsBody,
    name: str,
    part: Part,
    asset: AssetInstance,
    mass: float,
    pos: tuple[float, float, float],
) -> None:
    rgba = part_rgba(part, asset)
    quat = (1.0, 0.0, 0.0, 0.0)
    if part.shape == "cylinder" and part.axis == "y":
        quat = _Y_AXIS_QUAT
    elif part.shape == "cylinder" and part.axis == "x":
        quat = _X_AXIS_QUAT
    body.add_geom(
        name=name,
        type=_geom_type(part),
        size=geom_size(part, asset.scale),
        pos=list(pos),
        quat=list(quat),
        rgba=list(rgba),
        mass=mass,
        friction=[asset.physics.friction, 0.005, 0.0001],
    )


def part_rgba(part: Part, asset: AssetInstance) -> tuple[float, float, float, float]:
    """The colour a part's geom shows: the asset's colour override on body parts, else the part's."""
    if part.role == "body" and asset.appearance.rgba is not None:
        return asset.appearance.rgba
    return part.rgba


def set_body_frame(body: mujoco.MjsBody, pose: Pose) -> None:
    """Set a spec body's authored position and heading (used when compiling it again)."""
    body.pos = [pose.x, pose.y, pose.z]
    body.quat = yaw_quat(pose.yaw)


def _scaled(pos: tuple[float, float, float], scale: float) -> tuple[float, float, float]:
    return (pos[0] * scale, pos[1] * scale, pos[2] * scale)


def add_asset_body(spec: mujoco.MjSpec, asset: AssetInstance, name: str | None = None) -> mujoco.MjsBody:
    """Add `asset` to `spec` as one top-level body at its authored pose, named `name` (the
    asset id by default); the names of its geoms, joints and actuators start with `name/`."""
    cat = category(asset.category)
    kind = body_kind(asset, cat)
    pose = asset.pose
    name = name or asset.id
    body = spec.worldbody.add_body(
        name=name,
        pos=[pose.x, pose.y, pose.z],
        quat=yaw_quat(pose.yaw),
        mocap=kind == "mocap",
    )
    if cat.package is not None:
        _add_hull_geoms(spec, body, asset, cat.package, name)
        if kind == "free":
            body.add_freejoint(name=f"{name}/free")
        return body
    body_parts = [p for p in cat.parts if not (kind == "vehicle" and p.role == "wheel")]
    wheel_parts = [p for p in cat.parts if kind == "vehicle" and p.role == "wheel"]
    mass = asset.physics.mass
    wheel_mass = mass * WHEEL_MASS_FRACTION
    chassis_mass = mass - wheel_mass * len(wheel_parts)
    volumes = [part_volume(p) for p in body_parts]
    total = sum(volumes)
    for index, (part, volume) in enumerate(zip(body_parts, volumes, strict=True)):
        share = chassis_mass * volume / total
        _add_part_geom(body, f"{name}/part{index}", part, asset, share, _scaled(part.pos, asset.scale))
    if kind in ("vehicle", "free"):
        body.add_freejoint(name=f"{name}/free")
    if kind == "vehicle":
        _add_wheels(spec, body, asset, cat, wheel_parts, wheel_mass, name)
    return body


def hull_mesh_name(body_name: str, index: int) -> str:
    """The spec mesh of a packaged asset's convex part (prefixed so static rebuilds skip it)."""
    return f"{HULL_MESH_PREFIX}{body_name}/hull{index}"


def _add_hull_geoms(
    spec: mujoco.MjSpec, body: mujoco.MjsBody, asset: AssetInstance, package: str, name: str
) -> None:
    """A reconstructed asset collides as its convex parts: one mesh geom per hull, the mass
    shared by hull volume (the splats, not these geoms, are what the renderer draws)."""
    hulls = package_hulls(package, asset.scale)
    volumes = [_hull_volume(vertices) for vertices in hulls]
    total = sum(volumes)
    rgba = list(asset.appearance.rgba or category(asset.category).parts[0].rgba)
    for index, (vertices, volume) in enumerate(zip(hulls, volumes, strict=True)):
        mesh = spec.add_mesh(name=hull_mesh_name(name, index), uservert=vertices.reshape(-1).tolist())
        # The parts are convex already: inertia from the hull, no exact-volume pass needed.
        mesh.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_CONVEX
        body.add_geom(
            name=f"{name}/hull{index}",
            type=mujoco.mjtGeom.mjGEOM_MESH,
            meshname=mesh.name,
            rgba=rgba,
            mass=asset.physics.mass * volume / total,
            friction=[asset.physics.friction, 0.005, 0.0001],
        )


def _hull_volume(vertices: object) -> float:
    from scipy.spatial import ConvexHull

    return float(ConvexHull(vertices).volume)


def wheel_corner(part: Part) -> str:
    """Which corner a wheel part sits at: f/r by the sign of x, l/r by the sign of y."""
    return ("f" if part.pos[0] > 0 else "r") + ("l" if part.pos[1] > 0 else "r")


@dataclass(frozen=True)
class _WheelDims:
    radius: float
    mass: float

    @property
    def spin_inertia(self) -> float:
        return 0.5 * self.mass * self.radius**2


def _add_wheels(
    spec: mujoco.MjSpec,
    chassis: mujoco.MjsBody,
    asset: AssetInstance,
    cat: Category,
    wheel_parts: list[Part],
    wheel_mass: float,
    name: str,
) -> None:
    max_steer = cat.max_steer or 0.6
    drive_weight = asset.physics.mass * STANDARD_GRAVITY / 2.0
    for part in wheel_parts:
        corner = wheel_corner(part)
        dims = _WheelDims(part.size[0] * asset.scale, wheel_mass)
        wheel = chassis.add_body(name=f"{name}/wheel_{corner}", pos=list(_scaled(part.pos, asset.scale)))
        armature = WHEEL_ARMATURE_FACTOR * dims.spin_inertia
        steer_kp = STEER_KP_PER_KG * asset.physics.mass
        if corner.startswith("f"):
            wheel.add_joint(
                name=f"{name}/steer_{corner}",
                type=mujoco.mjtJoint.mjJNT_HINGE,
                axis=[0.0, 0.0, 1.0],
                range=[-max_steer, max_steer],
                limited=mujoco.mjtLimited.mjLIMITED_TRUE,
                armature=steer_kp / STEER_BANDWIDTH**2,
            )
        wheel.add_joint(
            name=f"{name}/spin_{corner}",
            type=mujoco.mjtJoint.mjJNT_HINGE,
            axis=[0.0, 1.0, 0.0],
            armature=armature,
        )
        _add_part_geom(wheel, f"{name}/wheel_{corner}", part, asset, wheel_mass, (0.0, 0.0, 0.0))
        if corner.startswith("f"):
            steer = spec.add_actuator(
                name=f"{name}/steer_{corner}",
                target=f"{name}/steer_{corner}",
                trntype=mujoco.mjtTrn.mjTRN_JOINT,
            )
            steer.set_to_position(kp=steer_kp, dampratio=STEER_DAMPRATIO)
            steer.ctrlrange = [-max_steer, max_steer]
            steer.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
        else:
            drive = spec.add_actuator(
                name=f"{name}/drive_{corner}",
                target=f"{name}/spin_{corner}",
                trntype=mujoco.mjtTrn.mjTRN_JOINT,
            )
            # Force at the contact per unit speed error: m / (2 wheels · τ), as a joint gain.
            kv = asset.physics.mass * dims.radius**2 / (2.0 * DRIVE_TIME_CONSTANT_S)
            drive.set_to_velocity(kv=kv)
            torque = DRIVE_TORQUE_WEIGHT_FACTOR * drive_weight * dims.radius / 2.0
            drive.forcerange = [-torque, torque]
            drive.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
