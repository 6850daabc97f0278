"""Pooled MuJoCo bodies: an edit activates, moves or parks a pre-built body in place.

Compiling a model costs time that grows with bodies × degrees of freedom (about 1 s for
4,000 bodies on 2 cores, measured with MuJoCo 4.0), so an edit must not recompile. Each
slot is a body built for one *slot shape*: the asset fields its compiled geometry depends
on (category, body kind, scale, mass). Pose, colour and friction are patched in place.

A parked slot is out of the world: its geoms neither collide nor show (a geom group that
the renderer and the ray casts leave out), and its free bodies float weightless (gravity
compensation) far below the ground, where they fall asleep and cost no physics time.
When a shape runs out of free slots its pool doubles: only that growth recompiles.

Every patch is written to the spec too, so a recompile (growth, a static rebuild) keeps it.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import mujoco
import numpy as np
import numpy.typing as npt
from drivetwin.worlds.catalog import Category, catalog, category
from drivetwin.worlds.mujoco_bodies import BodyKind, add_asset_body, body_kind
from drivetwin.worlds.rotation import quat_to_matrix, yaw_quat
from drivetwin.worlds.scene import Appearance, AssetInstance, PhysicsProps, Pose

__all__ = [
    "LOAD_HEADROOM_SHARE",
    "PARKED_GROUP",
    "POOL_ANCHOR",
    "BodyPool",
    "Slot",
    "SlotKey",
    "slot_key",
]

# What a slot's compiled body depends on: category, body kind, scale, mass.
SlotKey = tuple[str, BodyKind, float, float]

# Geom group of parked slots: MjvOption draws groups 0-2 by default, and the LIDAR and the
# behaviours' ray casts only look at groups that hold colliding geoms (parked ones do not).
PARKED_GROUP = 5
ACTIVE_GROUP = 0
# Parked slots wait this far below the world's centre: out of every camera's view.
PARK_DEPTH_M = 100.0
# Spare slots each catalog category gets at load, so a first add needs no recompile.
# Vehicles never sleep (they are actuated), so they get one: each costs physics time.
PRESPAWN_SLOTS = 2
PRESPAWN_VEHICLE_SLOTS = 1
# Headroom a world's own slot shapes get at load, as a share of their asset count.
LOAD_HEADROOM_SHARE = 0.125
# MuJoCo applies gravity compensation only if some body was compiled with it; this empty
# welded body makes sure, whatever the slots' states at the last compile.
POOL_ANCHOR = "pool#anchor"


def slot_key(asset: AssetInstance, cat: Category | None = None) -> SlotKey:
    """The slot shape an asset needs."""
    return (asset.category, body_kind(asset, cat), asset.scale, asset.physics.mass)


@dataclass
class _SlotGeom:
    spec: mujoco.MjsGeom
    name: str
    # The catalog colour, and whether the asset's colour override replaces it.
    rgba: tuple[float, float, float, float]
    takes_colour: bool
    contype: int
    conaffinity: int
    id: int = -1


@dataclass
class Slot:
    """One pooled body tree: its spec elements, model ids and the asset it shows (or None)."""

    name: str
    key: SlotKey
    body: mujoco.MjsBody
    bodies: list[mujoco.MjsBody]
    geoms: list[_SlotGeom]
    asset_id: str | None = None
    body_id: int = -1
    body_ids: list[int] = field(default_factory=list)

    @property
    def kind(self) -> BodyKind:
        return self.key[1]


def _tree(body: mujoco.MjsBody) -> list[mujoco.MjsBody]:
    out = [body]
    for child in body.bodies:
        out.extend(_tree(child))
    return out


def _colour_takers(cat: Category, kind: BodyKind, name: str) -> dict[str, tuple[tuple[float, float, float, float], bool]]:
    """Geom name -> (catalog colour, takes the asset's colour) for a slot named `name`."""
    if cat.package is not None:
        return {}
    body_parts = [p for p in cat.parts if not (kind == "vehicle" and p.role == "wheel")]
    return {f"{name}/part{k}": (p.rgba, p.role == "body") for k, p in enumerate(body_parts)}


class BodyPool:
    """The slots of a spec, by shape, and which asset each one shows."""

    def __init__(self, spec: mujoco.MjSpec, park_xy: tuple[float, float]) -> None:
        self.spec = spec
        self.park = [park_xy[0], park_xy[1], -PARK_DEPTH_M]
        self.slots: dict[str, Slot] = {}
        self._by_asset: dict[str, Slot] = {}
        self._free: dict[SlotKey, list[Slot]] = {}
        self._capacity: dict[SlotKey, int] = {}
        self._serial = 0
        # Bumped whenever slots are assigned, parked, spawned or rebound (views cache by it).
        self.version = 0
        if spec.body(POOL_ANCHOR) is None:
            spec.worldbody.add_body(name=POOL_ANCHOR, gravcomp=1.0)

    # Bookkeeping ---------------------------------------------------------------------------
    def slot_of(self, asset_id: str) -> Slot | None:
        return self._by_asset.get(asset_id)

    def asset_ids(self) -> list[str]:
        return list(self._by_asset)

    def capacity(self, key: SlotKey) -> int:
        return self._capacity.get(key, 0)

    def free_count(self, key: SlotKey) -> int:
        return len(self._free.get(key, ()))

    # Growing (spec only; the caller recompiles) --------------------------------------------
    def reserve(self, assets: list[AssetInstance], headroom: float = 0.0) -> bool:
        """Make sure every asset in `assets` will find a free slot of its shape; a pool that
        runs short doubles (at least). Returns whether the spec grew (a recompile is due)."""
        wanted: dict[SlotKey, list[AssetInstance]] = {}
        for asset in assets:
            wanted.setdefault(slot_key(asset), []).append(asset)
        grew = False
        for key, group in wanted.items():
            short = len(group) - self.free_count(key)
            if short <= 0:
                continue
            have = self.capacity(key)
            target = max(2 * have, have + short + int(headroom * len(group)))
            self._spawn(group[0], key, target - have)
            grew = True
        return grew

    def prespawn_catalog(self) -> None:
        """Spare slots for every catalog category at its default shape (no recompile on a
        first add); packaged categories are spawned on demand (their hulls are files)."""
        for cat in catalog().values():
            if cat.package is not None or "ego" in cat.tags:
                continue
            dynamic = cat.motion in ("vehicle", "walker", "prop")
            template = AssetInstance(
                id="pool_template", category=cat.name, pose=Pose(x=0.0, y=0.0),
                physics=PhysicsProps(mass=cat.mass, dynamic=dynamic),
            )
            key = slot_key(template, cat)
            spare = PRESPAWN_VEHICLE_SLOTS if cat.motion == "vehicle" else PRESPAWN_SLOTS
            if self.free_count(key) < spare:
                self._spawn(template, key, spare - self.free_count(key))

    def _spawn(self, template: AssetInstance, key: SlotKey, count: int) -> None:
        cat = category(template.category)
        kind = key[1]
        # Built with the catalog colours: the slot's geoms remember them for restyling.
        plain = template.model_copy(update={"appearance": Appearance(), "pose": Pose(x=0.0, y=0.0)})
        for _ in range(count):
            self._serial += 1
            name = f"{template.category}#{self._serial}"
            body = add_asset_body(self.spec, plain, name=name)
            colours = _colour_takers(cat, kind, name)
            fallback = cat.parts[0].rgba
            geoms = []
            for tree_body in _tree(body):
                for geom in tree_body.geoms:
                    rgba, takes = colours.get(geom.name, (tuple(geom.rgba), cat.package is not None))
                    if cat.package is not None:
                        rgba = fallback
                    geoms.append(_SlotGeom(geom, geom.name, rgba, takes, int(geom.contype), int(geom.conaffinity)))
            slot = Slot(name=name, key=key, body=body, bodies=_tree(body), geoms=geoms)
            self.slots[name] = slot
            self._free.setdefault(key, []).append(slot)
            self._park_spec(slot)
        self._capacity[key] = self.capacity(key) + count

    def bind(self, model: mujoco.MjModel) -> None:
        """Look up every slot's model ids (after each compile: ids change then)."""
        body_type, geom_type = mujoco.mjtObj.mjOBJ_BODY, mujoco.mjtObj.mjOBJ_GEOM
        self.version += 1
        for slot in self.slots.values():
            slot.body_id = int(mujoco.mj_name2id(model, body_type, slot.name))
            slot.body_ids = [int(mujoco.mj_name2id(model, body_type, b.name)) for b in slot.bodies]
            for geom in slot.geoms:
                geom.id = int(mujoco.mj_name2id(model, geom_type, geom.name))

    # Assigning (spec and model) ------------------------------------------------------------
    def activate(self, asset: AssetInstance, model: mujoco.MjModel, data: mujoco.MjData) -> bool:
        """Show `asset` in a free slot of its shape (reserve first), at its authored pose;
        False when its frames still need mj_kinematics (see `place`)."""
        slot = self._free[slot_key(asset)].pop()
        self.version += 1
        slot.asset_id = asset.id
        self._by_asset[asset.id] = slot
        self._set_contacts(slot, model, active=True)
        self._set_weightless(slot, model, False)
        self.restyle(asset, model)
        return self.place(slot, asset.pose, model, data)

    def release(self, asset_id: str, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """Park the slot that shows `asset_id` and give it back to its pool."""
        slot = self._by_asset.pop(asset_id)
        self.version += 1
        slot.asset_id = None
        self._set_contacts(slot, model, active=False)
        self._set_weightless(slot, model, True)
        x, y, z = self.park
        self.place(slot, Pose(x=x, y=y, z=z), model, data)
        self._free[slot.key].append(slot)

    def restyle(self, asset: AssetInstance, model: mujoco.MjModel) -> None:
        """Colour and friction of the asset's slot, in place."""
        slot = self._by_asset[asset.id]
        override = asset.appearance.rgba
        friction = asset.physics.friction
        for geom in slot.geoms:
            rgba = override if geom.takes_colour and override is not None else geom.rgba
            geom.spec.rgba = list(rgba)
            geom.spec.friction = [friction, *list(geom.spec.friction)[1:]]
            model.geom_rgba[geom.id] = rgba
            model.geom_friction[geom.id, 0] = friction

    def place(self, slot: Slot, pose: Pose, model: mujoco.MjModel, data: mujoco.MjData) -> bool:
        """Put a slot's body at `pose`, at rest (free joint, mocap or welded body frame).

        The frames renderers and ray casts read follow at once for a one-body slot; returns
        False for a tree (a vehicle), whose frames need mj_kinematics.
        """
        body = slot.body_id
        position = [pose.x, pose.y, pose.z]
        quat = yaw_quat(pose.yaw)
        slot.body.pos = position
        slot.body.quat = quat
        joint = int(model.body_jntadr[body])
        mocap = int(model.body_mocapid[body])
        if joint >= 0 and model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE:
            start = int(model.jnt_qposadr[joint])
            data.qpos[start : start + 3] = position
            data.qpos[start + 3 : start + 7] = quat
            # The whole tree comes to rest; -0.0 wakes a sleeping tree without moving it.
            for tree_body in slot.body_ids:
                dof, count = int(model.body_dofadr[tree_body]), int(model.body_dofnum[tree_body])
                data.qvel[dof : dof + count] = -0.0
        elif mocap >= 0:
            data.mocap_pos[mocap] = position
            data.mocap_quat[mocap] = quat
        else:
            model.body_pos[body] = position
            model.body_quat[body] = quat
        if len(slot.body_ids) != 1:
            return False
        _set_frames(slot, np.array(position), np.array(quat), model, data)
        return True

    def restore_contacts(self, asset_id: str, model: mujoco.MjModel) -> None:
        """The asset's slot collides as built (a moved prop whose contacts were dormant)."""
        self._set_contacts(self._by_asset[asset_id], model, active=True)

    def _set_contacts(self, slot: Slot, model: mujoco.MjModel, active: bool) -> None:
        group = ACTIVE_GROUP if active else PARKED_GROUP
        for geom in slot.geoms:
            contype, conaffinity = (geom.contype, geom.conaffinity) if active else (0, 0)
            geom.spec.contype, geom.spec.conaffinity, geom.spec.group = contype, conaffinity, group
            model.geom_contype[geom.id] = contype
            model.geom_conaffinity[geom.id] = conaffinity
            model.geom_group[geom.id] = group
        # The broad phase filters bodies by the union of their geoms' flags.
        ids = np.array([g.id for g in slot.geoms], dtype=np.int64)
        for body in slot.body_ids:
            own = ids[model.geom_bodyid[ids] == body]
            model.body_contype[body] = int(np.bitwise_or.reduce(model.geom_contype[own], initial=0))
            model.body_conaffinity[body] = int(np.bitwise_or.reduce(model.geom_conaffinity[own], initial=0))

    def _set_weightless(self, slot: Slot, model: mujoco.MjModel, weightless: bool) -> None:
        value = 1.0 if weightless else 0.0
        for spec_body, body in zip(slot.bodies, slot.body_ids, strict=True):
            spec_body.gravcomp = value
            model.body_gravcomp[body] = value

    def _park_spec(self, slot: Slot) -> None:
        """A new slot starts parked (spec only: it has no model ids before the recompile)."""
        for geom in slot.geoms:
            geom.spec.contype, geom.spec.conaffinity, geom.spec.group = 0, 0, PARKED_GROUP
        for body in slot.bodies:
            body.gravcomp = 1.0
        slot.body.pos = list(self.park)
        slot.body.quat = [1.0, 0.0, 0.0, 0.0]


def _set_frames(
    slot: Slot, position: npt.NDArray[np.float64], quat: npt.NDArray[np.float64], model: mujoco.MjModel, data: mujoco.MjData
) -> None:
    """A one-body slot's world frames (body, inertia, geoms) at `position`, `quat`: what
    mj_kinematics would compute for it, without a pass over every body of a large world."""
    body = slot.body_id
    rotation = quat_to_matrix(quat)
    data.xpos[body] = position
    data.xquat[body] = quat
    data.xmat[body] = rotation.ravel()
    data.xipos[body] = position + rotation @ model.body_ipos[body]
    data.ximat[body] = (rotation @ quat_to_matrix(model.body_iquat[body])).ravel()
    for geom in slot.geoms:
        data.geom_xpos[geom.id] = position + rotation @ model.geom_pos[geom.id]
        data.geom_xmat[geom.id] = (rotation @ quat_to_matrix(model.geom_quat[geom.id])).ravel()
