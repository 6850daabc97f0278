"""The MuJoCo view of a Scene: Scene → MjSpec → model (static) and data (state).

`MujocoWorld.from_scene` builds the spec; `update` diffs a new Scene against the one it was
built from by asset id, patches only the bodies that changed and recompiles with the state
kept, so everything else keeps moving. `consistency_problems` says whether a world still
matches a scene (used by property tests of random edit sequences).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import mujoco
import numpy as np
import numpy.typing as npt
from drivetwin.worlds.catalog import UnknownCategoryError, category
from drivetwin.worlds.mujoco_bodies import (
    WHEEL_CORNERS,
    add_asset_body,
    body_kind,
    geom_size,
    remove_asset_body,
    set_body_frame,
    yaw_quat,
)
from drivetwin.worlds.mujoco_static import (
    STATIC_PREFIXES,
    add_static_geoms,
    configure_spec,
    static_signature,
)
from drivetwin.worlds.scene import AssetInstance, Pose, Scene

__all__ = [
    "DEFAULT_TIMESTEP",
    "MujocoWorld",
    "UnknownBodyError",
    "UpdateStats",
    "consistency_problems",
]

# Stable for 60 kg robots to 12 t buses on cylinder wheels with the implicit integrator,
# and 200 steps per simulated second keep 200-asset worlds faster than real time on 2 cores.
DEFAULT_TIMESTEP = 0.005
# Relative tolerance for a body's total mass against the asset's (float32-free, so tight).
MASS_TOLERANCE = 1e-6
# Geom sizes are compared to the scaled parts to this many metres.
SIZE_TOLERANCE_M = 1e-9

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


def yaw_of_quat(quat: np.ndarray) -> float:
    """The heading (rotation about z) of a unit quaternion (w, x, y, z)."""
    w, x, y, z = (float(v) for v in quat)
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


class MujocoWorld:
    """A Scene compiled to MuJoCo; `update` patches it from a newer Scene, keeping state."""

    spec: mujoco.MjSpec
    model: mujoco.MjModel
    data: mujoco.MjData
    scene: Scene

    def __init__(self, spec: mujoco.MjSpec, model: mujoco.MjModel, data: mujoco.MjData, scene: Scene) -> None:
        self.spec = spec
        self.model = model
        self.data = data
        self.scene = scene
        # Bumped on every recompile: element ids change then, so cached ids must be redone.
        self.generation = 0
        self._body_ids: dict[str, int] = {}
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
        for asset in scene.all_assets():
            add_asset_body(spec, asset)
        model = spec.compile()
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
        return cls(spec, model, data, scene)

    # Editing ------------------------------------------------------------------------------
    def update(self, scene: Scene) -> UpdateStats:
        """Patch the world to match `scene`; unchanged assets keep their state (keep moving).

        Added and changed assets start at their authored pose. A change of pose alone moves
        the body in place (no rebuild); welded and mocap bodies then need no recompile.
        Raises UnknownCategoryError, leaving the world untouched, for an unknown category.
        """
        started = time.perf_counter()
        old = {a.id: a for a in self.scene.all_assets()}
        new = {a.id: a for a in scene.all_assets()}
        removed = [i for i in old if i not in new]
        added = [i for i in new if i not in old]
        changed = [i for i in new if i in old and _body_differs(old[i], new[i])]
        moved = [i for i in changed if _only_pose_differs(old[i], new[i])]
        replaced = [i for i in changed if i not in moved]
        static_changed = static_signature(self.scene) != static_signature(scene)
        for asset_id in replaced + added:
            category(new[asset_id].category)  # refuse unknown categories before any change
        for asset_id in removed + replaced:
            remove_asset_body(self.spec, asset_id)
        for asset_id in replaced + added:
            add_asset_body(self.spec, new[asset_id])
        if static_changed:
            self._remove_static()
            add_static_geoms(self.spec, scene)
        for asset_id in moved:
            set_body_frame(self.spec.body(asset_id), new[asset_id].pose)
        # Free bodies may be asleep; only a recompile wakes them reliably.
        moved_free = [i for i in moved if body_kind(new[i]) in ("vehicle", "free")]
        recompile = bool(removed or added or replaced or static_changed or moved_free)
        if recompile:
            self._recompile()
        for asset_id in moved:
            self._place(new[asset_id])
        if moved:
            # Placing writes qpos/mocap/body_pos only: frames (xpos) must follow before anyone
            # renders or ray-casts, with or without a recompile before it.
            self._refresh_kinematics()
        self.scene = scene
        return UpdateStats(
            added=len(added),
            removed=len(removed),
            replaced=len(changed),
            unchanged=len(new) - len(added) - len(changed),
            static_rebuilt=static_changed,
            recompiled=recompile,
            ms=(time.perf_counter() - started) * 1000.0,
        )

    def _refresh_kinematics(self) -> None:
        """Recompute every body's frame, static ones included (sleep caches those)."""
        options = self.model.opt
        flags = int(options.enableflags)
        options.enableflags = flags & ~int(mujoco.mjtEnableBit.mjENBL_SLEEP)
        try:
            mujoco.mj_kinematics(self.model, self.data)
        finally:
            options.enableflags = flags

    def _place(self, asset: AssetInstance) -> None:
        """Put an existing body at the asset's authored pose, at rest."""
        body = self.body_id(asset.id)
        model, data = self.model, self.data
        pose = asset.pose
        position = [pose.x, pose.y, pose.z]
        quat = yaw_quat(pose.yaw)
        joint = int(model.body_jntadr[body])
        mocap = int(model.body_mocapid[body])
        if joint >= 0 and model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE:
            start = int(model.jnt_qposadr[joint])
            data.qpos[start : start + 3] = position
            data.qpos[start + 3 : start + 7] = quat
            dof, count = int(model.body_dofadr[body]), int(model.body_dofnum[body])
            data.qvel[dof : dof + count] = 0.0
        elif mocap >= 0:
            data.mocap_pos[mocap] = position
            data.mocap_quat[mocap] = quat
        else:
            model.body_pos[body] = position
            model.body_quat[body] = quat

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
        model, data = self.spec.recompile(self.model, self.data)
        self.model, self.data = model, data
        # Positions of new bodies are only known after kinematics; renderers read them.
        mujoco.mj_kinematics(self.model, self.data)
        self.generation += 1
        self._body_ids.clear()
        self._pose_sources.clear()

    # Reading ------------------------------------------------------------------------------
    def body_id(self, asset_id: str) -> int:
        """The MuJoCo body id of an asset (valid until the next recompile)."""
        body = self._body_ids.get(asset_id)
        if body is None:
            body = int(mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_BODY, asset_id))
            if body < 0:
                raise UnknownBodyError(asset_id, [a.id for a in self.scene.all_assets()])
            self._body_ids[asset_id] = body
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
        return x, y, z, math.atan2(2.0 * (w * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz))

    def _pose_source(self, body: int) -> tuple[int, int]:
        model = self.model
        joint = int(model.body_jntadr[body])
        if joint >= 0 and model.jnt_type[joint] == mujoco.mjtJoint.mjJNT_FREE:
            return _FREE, int(model.jnt_qposadr[joint])
        if model.body_mocapid[body] >= 0:
            return _MOCAP, int(model.body_mocapid[body])
        return _WELDED, body

    def joint_id(self, name: str) -> int:
        """The id of a joint by its full name, or -1."""
        return int(mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_JOINT, name))

    def actuator_id(self, name: str) -> int:
        """The id of an actuator by its full name, or -1."""
        return int(mujoco.mj_name2id(self.model, mujoco.mjtObj.mjOBJ_ACTUATOR, name))


def _expected_geoms(asset: AssetInstance) -> list[tuple[str, int, list[float] | None]]:
    """(geom name, geom type, size) for every geom the asset's body tree should hold.

    A packaged (reconstructed) asset holds one mesh geom per convex part; MuJoCo sizes
    mesh geoms itself, so their size is not checked (None).
    """
    cat = category(asset.category)
    if cat.package is not None:
        from drivetwin.worlds.reconstruct.package import package_hulls

        hulls = package_hulls(cat.package, asset.scale)
        return [(f"{asset.id}/hull{k}", int(mujoco.mjtGeom.mjGEOM_MESH), None) for k in range(len(hulls))]
    kind = body_kind(asset, cat)
    expected: list[tuple[str, int, list[float] | None]] = []
    index = 0
    for part in cat.parts:
        geom_type = int(
            {
                "box": mujoco.mjtGeom.mjGEOM_BOX,
                "cylinder": mujoco.mjtGeom.mjGEOM_CYLINDER,
                "sphere": mujoco.mjtGeom.mjGEOM_SPHERE,
            }[part.shape]
        )
        if kind == "vehicle" and part.role == "wheel":
            corner = ("f" if part.pos[0] > 0 else "r") + ("l" if part.pos[1] > 0 else "r")
            name = f"{asset.id}/wheel_{corner}"
        else:
            name = f"{asset.id}/part{index}"
            index += 1
        expected.append((name, geom_type, geom_size(part, asset.scale)))
    return expected


def _joint_problems(world: MujocoWorld, asset: AssetInstance, body: int) -> list[str]:
    model = world.model
    kind = body_kind(asset)
    own = [j for j in range(model.njnt) if model.jnt_bodyid[j] == body]
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


def _asset_problems(world: MujocoWorld, asset: AssetInstance) -> list[str]:
    model = world.model
    body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, asset.id)
    if body < 0:
        return [f"{asset.id}: no body in the MuJoCo world"]
    if model.body_parentid[body] != 0:
        return [f"{asset.id}: body is not a child of the world"]
    try:
        expected = _expected_geoms(asset)
    except UnknownCategoryError as exc:
        return [f"{asset.id}: {exc}"]
    problems: list[str] = []
    in_tree = {g for g in range(model.ngeom) if model.body_rootid[model.geom_bodyid[g]] == body}
    if len(in_tree) != len(expected):
        problems.append(f"{asset.id}: {len(in_tree)} geoms, expected {len(expected)}")
    for name, geom_type, size in expected:
        geom = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, name)
        if geom < 0 or geom not in in_tree:
            problems.append(f"{asset.id}: missing geom {name}")
            continue
        if model.geom_type[geom] != geom_type:
            problems.append(f"{asset.id}: geom {name} has the wrong shape")
        elif size is not None and not np.allclose(model.geom_size[geom], size, atol=SIZE_TOLERANCE_M):
            problems.append(f"{asset.id}: geom {name} size {model.geom_size[geom]} != {size}")
    mass = float(model.body_subtreemass[body])
    if not math.isclose(mass, asset.physics.mass, rel_tol=MASS_TOLERANCE):
        problems.append(f"{asset.id}: mass {mass:.6g} kg, expected {asset.physics.mass:g} kg")
    return problems + _joint_problems(world, asset, body)


def consistency_problems(scene: Scene, world: MujocoWorld) -> list[str]:
    """Every way `world` fails to match `scene`; [] when each scene asset (ego included) has
    exactly one body named by its id with the right geoms, joint kind and mass, and no body
    exists for anything that is not in the scene."""
    problems: list[str] = []
    wanted = {a.id for a in scene.all_assets()}
    model = world.model
    top_level = [model.body(b).name for b in range(1, model.nbody) if model.body_parentid[b] == 0]
    for name in top_level:
        if name not in wanted:
            problems.append(f"body {name!r} is not an asset of the scene")
    seen: set[str] = set()
    for name in top_level:
        if name in seen:
            problems.append(f"more than one body is named {name!r}")
        seen.add(name)
    for asset in scene.all_assets():
        problems.extend(_asset_problems(world, asset))
    return problems


def collision_groups(model: mujoco.MjModel) -> npt.NDArray[np.uint8]:
    """Geom groups that hold collision geometry (visual-only geoms have contype=conaffinity=0)."""
    groups = np.zeros(6, np.uint8)
    collides = (model.geom_contype != 0) | (model.geom_conaffinity != 0)
    for group in np.unique(model.geom_group[collides]):
        if 0 <= group < 6:
            groups[group] = 1
    return groups
