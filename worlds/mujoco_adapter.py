"""The MuJoCo view of a Scene: Scene → MjSpec → model (static) and data (state).

`MujocoWorld.from_scene` builds the spec with a pool of body slots per slot shape
(drivetwin.worlds.mujoco_pool); `update` diffs a new Scene against the one it was built
from by asset id and activates, moves, restyles or parks only the slots that changed, in
place. Only a pool's growth and a changed static world recompile (with the state kept), so
everything else keeps moving. `consistency_problems` says whether a world still matches a
scene (used by property tests of random edit sequences).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import mujoco
import numpy as np
import numpy.typing as npt
from drivetwin.worlds.catalog import category
from drivetwin.worlds.edits import lineage
from drivetwin.worlds.mujoco_dormancy import ContactDormancy
from drivetwin.worlds.mujoco_pool import LOAD_HEADROOM_SHARE, BodyPool, slot_key
from drivetwin.worlds.mujoco_static import (
    STATIC_PREFIXES,
    add_static_geoms,
    configure_spec,
    static_signature,
)
from drivetwin.worlds.rotation import yaw_of_quat
from drivetwin.worlds.scene import AssetInstance, Pose, Scene

__all__ = [
    "DEFAULT_TIMESTEP",
    "MujocoWorld",
    "UnknownBodyError",
    "UpdateStats",
    "collision_groups",
    "consistency_problems",
    "scene_diff",
]

# Stable for 60 kg robots to 12 t buses on cylinder wheels with the implicit integrator,
# and 200 steps per simulated second keep 200-asset worlds faster than real time on 2 cores.
DEFAULT_TIMESTEP = 0.005
# MuJoCo's default arena grows with dofs squared (531 MB at 3,000 dofs; no memory at
# 30,000): size it by slot count instead. Measured peak use in drivetwin bench edits:
# under 8 KiB per slot with every prop resting; 64 KiB leaves room for piles of contacts.
ARENA_BYTES_PER_SLOT = 64 * 1024
ARENA_MIN_BYTES = 64 * 1024 * 1024

# Up to this many changed assets, scene_diff finds them by scanning (a whole new scene, as a
# resumed journal gives, would make that quadratic).
_FEW_CHANGES = 64
# Where a body's pose lives: the qpos of its free joint, its mocap slot, or its xpos.
_FREE, _MOCAP, _WELDED = 0, 1, 2

# Asset fields that change the body; behaviour and label changes leave it alone.
_BODY_FIELDS = ("category", "pose", "scale", "physics", "appearance")


class UnknownBodyError(KeyError):
    """An asset id that has no body in the MuJoCo world."""

    def __init__(self, asset_id: str, known: list[str]) -> None:
        self.asset_id = asset_id
        self.known = known
        super().__init__(asset_id)

    def __str__(self) -> str:
        shown = ", ".join(self.known[:8]) + (" ..." if len(self.known) > 8 else "")
        return f"no body for asset {self.asset_id!r}; bodies: {shown}"


@dataclass(frozen=True)
class UpdateStats:
    """What one `MujocoWorld.update` did and how long it took."""

    added: int = 0
    removed: int = 0
    replaced: int = 0
    unchanged: int = 0
    static_rebuilt: bool = False
    recompiled: bool = False
    ms: float = 0.0


def _body_differs(old: AssetInstance, new: AssetInstance) -> bool:
    return any(getattr(old, f) != getattr(new, f) for f in _BODY_FIELDS)


def _only_pose_differs(old: AssetInstance, new: AssetInstance) -> bool:
    return all(getattr(old, f) == getattr(new, f) for f in _BODY_FIELDS if f != "pose")


def _refresh_kinematics(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """Recompute every body's frame, static ones included (sleep caches those)."""
    options = model.opt
    flags = int(options.enableflags)
    options.enableflags = flags & ~int(mujoco.mjtEnableBit.mjENBL_SLEEP)
    try:
        mujoco.mj_kinematics(model, data)
    finally:
        options.enableflags = flags


def scene_diff(old: Scene, new: Scene) -> tuple[dict[str, AssetInstance], dict[str, AssetInstance]]:
    """The assets of `old` that `new` does not hold and those of `new` that `old` does not,
    each by id, matched by identity: edits share every unchanged AssetInstance between
    scenes, so this costs set operations (C), not a comparison per asset. An asset changed
    (or copied) appears in both. When `new` is an edit applied to `old`, the edit's own record
    of what left and came (its lineage) is the answer, without looking at the other assets."""
    step = lineage(new)
    if step.parent is not None and step.parent is lineage(old):
        return {a.id: a for a in step.gone}, {a.id: a for a in step.came}
    before, after = old.all_assets(), new.all_assets()
    ids_before, ids_after = list(map(id, before)), list(map(id, after))
    set_before, set_after = set(ids_before), set(ids_after)
    gone_ids, came_ids = set_before - set_after, set_after - set_before
    if len(gone_ids) + len(came_ids) <= _FEW_CHANGES:
        # Finding each one's place is a scan in C, cheaper than a dict of every asset.
        gone = [before[ids_before.index(k)] for k in gone_ids]
        came = [after[ids_after.index(k)] for k in came_ids]
    else:
        by_id = dict(zip(ids_before, before, strict=True))
        by_id.update(zip(ids_after, after, strict=True))
        gone, came = [by_id[k] for k in gone_ids], [by_id[k] for k in came_ids]
    return {a.id: a for a in gone}, {a.id: a for a in came}


def _arena_bytes(pool: BodyPool) -> int:
    return max(ARENA_MIN_BYTES, ARENA_BYTES_PER_SLOT * len(pool.slots))


class MujocoWorld:
    """A Scene compiled to MuJoCo; `update` patches it from a newer Scene, keeping state."""

    spec: mujoco.MjSpec
    model: mujoco.MjModel
    data: mujoco.MjData
    scene: Scene

    def __init__(
        self,
        spec: mujoco.MjSpec,
        model: mujoco.MjModel,
        data: mujoco.MjData,
        scene: Scene,
        pool: BodyPool | None = None,
    ) -> None:
        self.spec = spec
        self.model = model
        self.data = data
        self.scene = scene
        # A world built by hand (tests, tools) has no pool: its bodies are found by name.
        self.pool = pool if pool is not None else BodyPool(spec, scene.bounds.centre)
        self.dormancy = ContactDormancy()
        # Bumped on every recompile: element ids change then, so cached ids must be redone.
        self.generation = 0
        self._pose_sources: dict[str, tuple[int, int]] = {}

    @classmethod
    def from_scene(cls, scene: Scene, timestep: float = DEFAULT_TIMESTEP) -> MujocoWorld:
        """Build the spec, model and data of `scene`; every asset starts at its authored pose."""
        spec = mujoco.MjSpec()
        spec.modelname = "drivetwin"
        # SI throughout: joint ranges are in radians (MJCF's default unit is degrees).
        spec.compiler.degree = False
        spec.option.timestep = timestep
        # Implicit in velocity: the stiff wheel drive servos stay stable at a few ms.
        spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
        # Props at rest sleep (MuJoCo skips them) and wake when touched: a world of 200
        # mostly resting assets steps several times faster. Actuated trees (vehicles) and
        # mocap walkers never sleep; a recompile wakes everything.
        spec.option.enableflags |= int(mujoco.mjtEnableBit.mjENBL_SLEEP)
        configure_spec(spec, scene)
        add_static_geoms(spec, scene)
        assets = scene.all_assets()
        for asset in assets:
            category(asset.category)  # an unknown category is refused before any work
        pool = BodyPool(spec, scene.bounds.centre)
        pool.reserve(assets, headroom=LOAD_HEADROOM_SHARE)
        pool.prespawn_catalog()
        spec.memory = _arena_bytes(pool)
        model = spec.compile()
        data = mujoco.MjData(model)
        pool.bind(model)
        for asset in assets:
            pool.activate(asset, model, data)
        # Welded slots were compiled parked: their cached frames must follow the activation.
        _refresh_kinematics(model, data)
        mujoco.mj_forward(model, data)
        return cls(spec, model, data, scene, pool)

    # Editing ------------------------------------------------------------------------------
    def update(self, scene: Scene) -> UpdateStats:
        """Patch the world to match `scene`; unchanged assets keep their state (keep moving).

        Added and changed assets start at their authored pose, in a pooled slot: no
        recompile unless a pool must grow or the static world changed. Raises
        UnknownCategoryError, leaving the world untouched, for an unknown category.
        """
        started = time.perf_counter()
        old, new = scene_diff(self.scene, scene)
        removed = [i for i in old if i not in new]
        added = [i for i in new if i not in old]
        changed = [i for i in new if i in old and _body_differs(old[i], new[i])]
        moved = [i for i in changed if _only_pose_differs(old[i], new[i])]
        reshaped = [i for i in changed if i not in moved and slot_key(old[i]) != slot_key(new[i])]
        restyled = [i for i in changed if i not in moved and i not in reshaped]
        for asset_id in reshaped + added:
            category(new[asset_id].category)  # refuse unknown categories before any change
        static_changed = static_signature(self.scene) != static_signature(scene)
        for asset_id in removed + reshaped:
            self.pool.release(asset_id, self.model, self.data)
            self._pose_sources.pop(asset_id, None)
        grew = self.pool.reserve([new[i] for i in reshaped + added])
        if static_changed:
            self._remove_static()
            add_static_geoms(self.spec, scene)
        recompile = grew or static_changed
        if recompile:
            self._recompile()
        model, data = self.model, self.data
        # Placing writes qpos/mocap/body_pos and the frames of one-body slots; a vehicle's
        # wheels need mj_kinematics before anyone renders or ray-casts.
        kinematics = recompile
        for asset_id in reshaped + added:
            kinematics |= not self.pool.activate(new[asset_id], model, data)
        for asset_id in restyled:
            self.pool.restyle(new[asset_id], model)
        for asset_id in moved + restyled:
            slot = self.pool.slot_of(asset_id)
            assert slot is not None
            self.pool.restore_contacts(asset_id, model)  # it may have been dormant
            self.dormancy.wake(slot.body_id)
            kinematics |= not self.pool.place(slot, new[asset_id].pose, model, data)
        if kinematics:
            _refresh_kinematics(model, data)
        self.scene = scene
        return UpdateStats(
            added=len(added),
            removed=len(removed),
            replaced=len(changed),
            unchanged=len(scene.assets) + 1 - len(added) - len(changed),
            static_rebuilt=static_changed,
            recompiled=recompile,
            ms=(time.perf_counter() - started) * 1000.0,
        )

    def refresh_contacts(self) -> None:
        """Switch off the contacts of props resting far from anything that moves, back on
        near it (drivetwin.worlds.mujoco_dormancy); the simulation calls it every control tick."""
        self.dormancy.refresh(self.pool, self.model, self.data)

    def _remove_static(self) -> None:
        for geom in list(self.spec.worldbody.geoms):
            if geom.name.startswith(STATIC_PREFIXES):
                self.spec.delete(geom)
        for mesh in list(self.spec.meshes):
            if mesh.name.startswith(STATIC_PREFIXES):
                self.spec.delete(mesh)
        for field in list(self.spec.hfields):
            if field.name.startswith(STATIC_PREFIXES):
                self.spec.delete(field)

    def _recompile(self) -> None:
        self.spec.memory = _arena_bytes(self.pool)
        model, data = self.spec.recompile(self.model, self.data)
        self.model, self.data = model, data
        self.pool.bind(model)
        # Positions of new bodies are only known after kinematics; renderers read them.
        mujoco.mj_kinematics(self.model, self.data)
        self.generation += 1
        self._pose_sources.clear()

    # Reading ------------------------------------------------------------------------------
    def body_id(self, asset_id: str) -> int:
        """The MuJoCo body id of an asset (valid until the next recompile or edit of it)."""
        slot = self.pool.slot_of(asset_id)
        if slot is not None:
            return slot.body_id
        # Slot names hold a '#', which asset ids never do: this finds only hand-built bodies.
        body = int(mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, asset_id))
        if body < 0:
            raise UnknownBodyError(asset_id, [a.id for a in self.scene.all_assets()])
        return body

    def body_pose(self, asset_id: str) -> Pose:
        """The current simulated planar pose of an asset's body."""
        x, y, z, yaw = self.planar_pose(asset_id)
        return Pose(x=x, y=y, z=z, yaw=yaw)

    def planar_pose(self, asset_id: str) -> tuple[float, float, float, float]:
        """(x, y, z, yaw) of an asset's body now; the fast path for control loops."""
        source = self._pose_sources.get(asset_id)
        if source is None:
            source = self._pose_source(self.body_id(asset_id))
            self._pose_sources[asset_id] = source
        kind, index = source
        data = self.data
        # Read the state itself, not xpos: xpos lags one step behind after mj_step.
        if kind == _FREE:
            x, y, z, w, qx, qy, qz = data.qpos[index : index + 7].tolist()
        elif kind == _MOCAP:
            x, y, z = data.mocap_pos[index].tolist()
            w, qx, qy, qz = data.mocap_quat[index].tolist()
        else:
            x, y, z = data.xpos[index].tolist()
            w, qx, qy, qz = data.xquat[index].tolist()
        return x, y, z, yaw_of_quat((w, qx, qy, qz))

    def _pose_source(self, body: int) -> tuple[int, int]:
        model = self.model
        joint = int(model.body_jntadr[body])
        if joint >= 0 and model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE:
            return _FREE, int(model.jnt_qposadr[joint])
        if model.body_mocapid[body] >= 0:
            return _MOCAP, int(model.body_mocapid[body])
        return _WELDED, body

    def element_name(self, name: str) -> str:
        """The model's name of an asset's element named `ASSET_ID/part` (its slot's)."""
        asset_id, sep, rest = name.partition("/")
        slot = self.pool.slot_of(asset_id) if sep else None
        return f"{slot.name}/{rest}" if slot is not None else name

    def joint_id(self, name: str) -> int:
        """The id of a joint by its full name (`car_1/spin_fl`), or -1."""
        return int(mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, self.element_name(name)))

    def actuator_id(self, name: str) -> int:
        """The id of an actuator by its full name (`car_1/drive_rl`), or -1."""
        return int(mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_ACTUATOR, self.element_name(name)))

    def geom_id(self, name: str) -> int:
        """The id of a geom by its full name (`cone_1/part0`, `building/hall`), or -1."""
        return int(mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_GEOM, self.element_name(name)))


def collision_groups(model: mujoco.MjModel) -> npt.NDArray[np.uint8]:
    """Geom groups that hold collision geometry (visual-only geoms have contype=conaffinity=0)."""
    groups = np.zeros(6, np.uint8)
    collides = (model.geom_contype != 0) | (model.geom_conaffinity != 0)
    for group in np.unique(model.geom_group[collides]):
        if 0 <= group < 6:
            groups[group] = 1
    return groups


# Re-exported: the consistency check is part of the adapter's contract.
from drivetwin.worlds.mujoco_consistency import consistency_problems  # noqa: E402
