"""Whether a MuJoCo world still shows a Scene: one active pooled body per asset, every other
slot parked. Read from the compiled model itself (not the pool's bookkeeping alone), so a
stale or half-patched world is caught; used by property tests of random edit sequences.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import mujoco
import numpy as np
from drivetwin.worlds.catalog import UnknownCategoryError, category
from drivetwin.worlds.mujoco_bodies import WHEEL_CORNERS, body_kind, geom_size, part_rgba
from drivetwin.worlds.mujoco_pool import PARKED_GROUP, POOL_ANCHOR, Slot
from drivetwin.worlds.packages import package_hulls
from drivetwin.worlds.scene import AssetInstance, Scene

if TYPE_CHECKING:
    from drivetwin.worlds.mujoco_adapter import MujocoWorld

__all__ = ["consistency_problems"]

# Relative tolerance for a body's total mass against the asset's (float32-free, so tight).
MASS_TOLERANCE = 1e-6
# Geom sizes are compared to the scaled parts to this many metres.
SIZE_TOLERANCE_M = 1e-9
# Colours are stored as float32 in the model.
RGBA_TOLERANCE = 1e-6

_SHAPES = {
    "box": mujoco.mjtGeom.mjGEOM_BOX,
    "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER,
    "sphere": mujoco.mjtGeom.mjGEOM_SPHERE,
}

_Expected = tuple[str, int, "list[float] | None", "tuple[float, float, float, float] | None"]


def _expected_geoms(asset: AssetInstance, name: str) -> list[_Expected]:
    """(geom name, geom type, size, colour) for every geom of the asset's body tree, the
    body being named `name`. A packaged (reconstructed) asset holds one mesh geom per convex
    part; MuJoCo sizes mesh geoms itself, so their size (and colour) is not checked (None).
    """
    cat = category(asset.category)
    if cat.package is not None:
        hulls = package_hulls(cat.package, asset.scale)
        mesh = int(mujoco.mjtGeom.mjGEOM_MESH)
        return [(f"{name}/hull{k}", mesh, None, None) for k in range(len(hulls))]
    kind = body_kind(asset, cat)
    expected: list[_Expected] = []
    index = 0
    for part in cat.parts:
        if kind == "vehicle" and part.role == "wheel":
            corner = ("f" if part.pos[0] > 0 else "r") + ("l" if part.pos[1] > 0 else "r")
            geom = f"{name}/wheel_{corner}"
        else:
            geom = f"{name}/part{index}"
            index += 1
        expected.append((geom, int(_SHAPES[part.shape]), geom_size(part, asset.scale), part_rgba(part, asset)))
    return expected


class _Index:
    """Geoms per tree root and joints per body, grouped once per check (not per asset)."""

    def __init__(self, model: mujoco.MjModel) -> None:
        self.tree_geoms: dict[int, set[int]] = {}
        for geom, root in enumerate(model.body_rootid[model.geom_bodyid].tolist()):
            self.tree_geoms.setdefault(root, set()).add(geom)
        self.joints: dict[int, list[int]] = {}
        for joint, body in enumerate(model.jnt_bodyid.tolist()):
            self.joints.setdefault(body, []).append(joint)


def _joint_problems(world: MujocoWorld, asset: AssetInstance, body: int, index: _Index) -> list[str]:
    model = world.model
    kind = body_kind(asset)
    own = index.joints.get(body, [])
    free = [j for j in own if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    is_mocap = model.body_mocapid[body] >= 0
    problems: list[str] = []
    if kind in ("vehicle", "free") and (len(free) != 1 or len(own) != 1):
        problems.append(f"{asset.id}: expected one free joint, found {len(own)} joint(s)")
    if kind in ("mocap", "welded") and own:
        problems.append(f"{asset.id}: expected no joint ({kind}), found {len(own)}")
    if is_mocap != (kind == "mocap"):
        problems.append(f"{asset.id}: mocap is {is_mocap}, expected {kind == 'mocap'}")
    if kind == "vehicle":
        for corner in WHEEL_CORNERS:
            if world.joint_id(f"{asset.id}/spin_{corner}") < 0:
                problems.append(f"{asset.id}: missing wheel joint spin_{corner}")
            actuator = f"{asset.id}/{'steer' if corner[0] == 'f' else 'drive'}_{corner}"
            if world.actuator_id(actuator) < 0:
                problems.append(f"{asset.id}: missing actuator {actuator}")
    return problems


def _geom_problems(model: mujoco.MjModel, asset: AssetInstance, expected: list[_Expected], in_tree: set[int]) -> list[str]:
    problems: list[str] = []
    for name, geom_type, size, rgba in expected:
        geom = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, name)
        if geom < 0 or geom not in in_tree:
            problems.append(f"{asset.id}: missing geom {name}")
            continue
        if model.geom_type[geom] != geom_type:
            problems.append(f"{asset.id}: geom {name} has the wrong shape")
        elif size is not None and not np.allclose(model.geom_size[geom], size, atol=SIZE_TOLERANCE_M):
            problems.append(f"{asset.id}: geom {name} size {model.geom_size[geom]} != {size}")
        if rgba is not None and not np.allclose(model.geom_rgba[geom], rgba, atol=RGBA_TOLERANCE):
            problems.append(f"{asset.id}: geom {name} colour {model.geom_rgba[geom]} != {rgba}")
        if model.geom_group[geom] == PARKED_GROUP:
            problems.append(f"{asset.id}: geom {name} is parked (hidden)")
    return problems


def _asset_problems(world: MujocoWorld, asset: AssetInstance, slot: Slot, index: _Index) -> list[str]:
    model = world.model
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, slot.name)
    if body < 0 or body != world.body_id(asset.id):
        return [f"{asset.id}: no body in the MuJoCo world"]
    if model.body_parentid[body] != 0:
        return [f"{asset.id}: body is not a child of the world"]
    try:
        expected = _expected_geoms(asset, slot.name)
    except UnknownCategoryError as exc:
        return [f"{asset.id}: {exc}"]
    in_tree = index.tree_geoms.get(body, set())
    problems: list[str] = []
    if len(in_tree) != len(expected):
        problems.append(f"{asset.id}: {len(in_tree)} geoms, expected {len(expected)}")
    problems += _geom_problems(model, asset, expected, in_tree)
    mass = float(model.body_subtreemass[body])
    if not math.isclose(mass, asset.physics.mass, rel_tol=MASS_TOLERANCE):
        problems.append(f"{asset.id}: mass {mass:.6g} kg, expected {asset.physics.mass:g} kg")
    if model.body_gravcomp[body] != 0.0:
        problems.append(f"{asset.id}: body is weightless (parked)")
    dormant = world.dormancy.is_dormant(body)
    for geom in slot.geoms:
        flags = (int(model.geom_contype[geom.id]), int(model.geom_conaffinity[geom.id]))
        if flags != ((0, 0) if dormant else (geom.contype, geom.conaffinity)):
            problems.append(f"{asset.id}: geom {geom.name} contacts {flags}, expected as built")
    return problems + _joint_problems(world, asset, body, index)


def _parked_problems(model: mujoco.MjModel, name: str, body: int, index: _Index) -> list[str]:
    geoms = sorted(index.tree_geoms.get(body, set()))
    if any(model.geom_contype[g] or model.geom_conaffinity[g] for g in geoms):
        return [f"body {name!r} is not an asset of the scene, yet it collides"]
    if any(model.geom_group[g] != PARKED_GROUP for g in geoms):
        return [f"body {name!r} is not an asset of the scene, yet it is visible"]
    return []


def consistency_problems(scene: Scene, world: MujocoWorld) -> list[str]:
    """Every way `world` fails to match `scene`; [] when each scene asset (ego included) has
    exactly one active body (its pool slot) with the right geoms, colours, joint kind and
    mass, and every body that shows no scene asset is parked (no contacts, hidden)."""
    problems: list[str] = []
    model = world.model
    wanted = {a.id for a in scene.all_assets()}
    shown = set(world.pool.asset_ids())
    for asset_id in sorted(shown - wanted):
        problems.append(f"body {asset_id!r} is not an asset of the scene")
    names = [model.body(b).name for b in range(1, model.nbody) if model.body_parentid[b] == 0]
    if len(set(names)) != len(names):
        problems.append("more than one body has the same name")
    active: dict[int, str] = {}
    index = _Index(model)
    for asset in scene.all_assets():
        slot = world.pool.slot_of(asset.id)
        if slot is None:
            problems.append(f"{asset.id}: no body in the MuJoCo world")
            continue
        if slot.body_id in active:
            problems.append(f"{asset.id} and {active[slot.body_id]} share one body")
        active[slot.body_id] = asset.id
        problems.extend(_asset_problems(world, asset, slot, index))
    for body, name in enumerate(model.body(b).name for b in range(model.nbody)):
        if body == 0 or model.body_parentid[body] != 0 or body in active or name == POOL_ANCHOR:
            continue
        slot = world.pool.slots.get(name)
        if slot is None:
            problems.append(f"body {name!r} is not a pool slot")
        elif slot.asset_id is not None and slot.asset_id not in wanted:
            continue  # reported above as "not an asset of the scene"
        else:
            problems.extend(_parked_problems(model, name, body, index))
    return problems
