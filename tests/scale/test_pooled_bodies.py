"""Large worlds: pooled MuJoCo bodies (edits patch slots in place, only growth recompiles),
parked slots that neither collide nor show, and dormant contacts of far resting props."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from drivetwin.worlds.bench_physics import benchmark_scene
from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld, collision_groups, consistency_problems
from drivetwin.worlds.mujoco_dormancy import REFRESH_EVERY_TICKS
from drivetwin.worlds.mujoco_pool import PARKED_GROUP, slot_key
from drivetwin.worlds.scene import AssetInstance, Bounds, PhysicsProps, Pose, Scene
from drivetwin.worlds.simulation import Simulation


def _asset(asset_id: str, name: str, x: float, y: float, z: float = 0.0, dynamic: bool = True) -> AssetInstance:
    return AssetInstance(id=asset_id, category=name, pose=Pose(x=x, y=y, z=z),
                         physics=PhysicsProps(mass=category(name).mass, dynamic=dynamic))  # fmt: skip


def _scene(*assets: AssetInstance) -> Scene:
    return Scene(name="pool", bounds=Bounds(xmin=-100, xmax=100, ymin=-100, ymax=100),
                 ego=_asset("ego", "ego_vehicle", -60.0, -1.75), assets=list(assets))  # fmt: skip


def _with(scene: Scene, *assets: AssetInstance) -> Scene:
    return scene.model_copy(update={"assets": [*scene.assets, *assets]})


def _moved(scene: Scene, asset_id: str, x: float, y: float) -> Scene:
    target = scene.asset(asset_id)
    assert target is not None
    moved = target.model_copy(update={"pose": Pose(x=x, y=y)})
    return scene.model_copy(update={"assets": [moved if a.id == asset_id else a for a in scene.assets]})


@pytest.mark.slow
def test_a_5000_asset_world_loads_takes_an_add_a_move_and_a_remove_and_stays_consistent() -> None:
    # Street furniture welded (compiling 30,000 free-body dofs would take the test's time),
    # vehicles driving and pedestrians walking, as in the physics benchmark.
    crowd = benchmark_scene(5000)
    welded = [a.model_copy(update={"physics": PhysicsProps(mass=a.physics.mass, dynamic=False)})
              if a.id.startswith("prop_") else a for a in crowd.assets]  # fmt: skip
    scene = crowd.model_copy(update={"assets": welded})
    world = MujocoWorld.from_scene(scene)
    assert consistency_problems(scene, world) == []
    added = _with(scene, _asset("extra_cone", "traffic_cone", 0.0, 30.0))
    moved = _moved(added, "extra_cone", 3.0, 31.0)
    removed = moved.model_copy(update={"assets": [a for a in moved.assets if a.id != "prop_3"]})
    for edited in (added, moved, removed):
        stats = world.update(edited)
        assert not stats.recompiled, "a pooled slot takes every edit"
        assert consistency_problems(edited, world) == []
    assert world.body_pose("extra_cone").x == pytest.approx(3.0)


def test_a_pool_that_runs_out_doubles_and_only_that_growth_recompiles() -> None:
    buses = [_asset(f"bus_{k}", "bus", -80.0 + 20.0 * k, 40.0) for k in range(3)]
    scene = _scene(*buses)
    world = MujocoWorld.from_scene(scene)
    key = slot_key(buses[0])
    start = world.pool.capacity(key)
    while world.pool.free_count(key):  # use up the spare slots: no recompile
        n = len(scene.assets)
        scene = _with(scene, _asset(f"bus_{n}", "bus", -80.0 + 20.0 * (n % 8), 60.0 - 15.0 * (n // 8)))
        assert not world.update(scene).recompiled
    grown = _with(scene, _asset("bus_last", "bus", 80.0, -60.0))
    stats = world.update(grown)
    assert stats.recompiled and world.pool.capacity(key) == 2 * start
    assert consistency_problems(grown, world) == []


def test_the_growth_recompile_keeps_a_sliding_body_sliding() -> None:
    scene = _scene(_asset("bin_1", "trash_bin", 0.0, 20.0))
    world = MujocoWorld.from_scene(scene)
    dof = world.model.jnt_dofadr[world.joint_id("bin_1/free")]
    world.data.qvel[dof] = 3.0
    mujoco.mj_step(world.model, world.data)
    before = float(world.data.qvel[dof])
    # A packaged-free category shape no pool holds yet (a scaled cone): a new pool, compiled.
    scaled = _asset("big_cone", "traffic_cone", 30.0, 30.0).model_copy(update={"scale": 2.0})
    stats = world.update(_with(scene, scaled))
    assert stats.recompiled
    assert world.data.qvel[world.model.jnt_dofadr[world.joint_id("bin_1/free")]] == before


def test_a_parked_slot_neither_collides_nor_shows_nor_stops_a_ray() -> None:
    scene = _scene(_asset("barrier_1", "road_barrier", 10.0, 10.0))
    world = MujocoWorld.from_scene(scene)
    slot = world.pool.slot_of("barrier_1")
    assert slot is not None
    world.update(_scene())  # removed: its slot is parked
    model, data = world.model, world.data
    parked = [g.id for g in slot.geoms]
    assert all(model.geom_group[g] == PARKED_GROUP for g in parked)
    assert not mujoco.MjvOption().geomgroup[PARKED_GROUP], "the renderer's default view hides it"
    # Held where it stood, the parked barrier lets a bin dropped onto it fall to the ground.
    world.pool.place(slot, Pose(x=10.0, y=10.0), model, data)
    world.update(_scene(_asset("bin_1", "trash_bin", 10.0, 10.0, 1.5)))
    for _ in range(400):
        mujoco.mj_step(world.model, world.data)
        assert not any(c.geom1 in parked or c.geom2 in parked for c in world.data.contact[: world.data.ncon])
    assert world.body_pose("bin_1").z < 0.05, "it rests on the ground, not on the barrier"
    # A ray cast the way the LIDAR does passes the parked geoms (and stops at the ground).
    mujoco.mj_kinematics(world.model, world.data)
    geom = np.array([-1], np.int32)
    hit = mujoco.mj_ray(world.model, world.data, np.array([10.6, 10.0, 5.0]), np.array([0.0, 0.0, -1.0]),
                        collision_groups(world.model), 1, -1, geom)  # fmt: skip
    assert hit == pytest.approx(5.0, abs=0.01) and geom[0] not in parked


def test_a_resting_prop_far_from_movers_goes_dormant_and_collides_again_when_one_comes_near() -> None:
    scene = _scene(_asset("bollard_1", "bollard", 60.0, 60.0, dynamic=False))
    sim = Simulation(scene)
    sim.step(4 * REFRESH_EVERY_TICKS + 4)
    body = sim.world.body_id("bollard_1")
    assert sim.world.dormancy.is_dormant(body) and sim.world.model.body_contype[body] == 0
    assert consistency_problems(sim.scene, sim.world) == []
    near = scene.model_copy(update={"ego": scene.ego.model_copy(update={"pose": Pose(x=55.0, y=60.0)})})
    sim.apply(near)
    sim.step(4 * REFRESH_EVERY_TICKS + 4)
    assert not sim.world.dormancy.is_dormant(body) and sim.world.model.body_contype[body] != 0
    assert consistency_problems(near, sim.world) == []


def test_frames_set_in_place_for_a_moved_asset_are_those_mj_kinematics_computes() -> None:
    scene = _scene(_asset("bench_1", "bench", 5.0, 5.0, dynamic=False), _asset("cone_1", "traffic_cone", 8.0, 5.0),
                   _asset("ped_1", "pedestrian", 11.0, 5.0))  # fmt: skip
    world = MujocoWorld.from_scene(scene)
    moved = scene
    for asset_id, x in (("bench_1", -7.0), ("cone_1", -4.0), ("ped_1", -1.0)):
        target = moved.asset(asset_id)
        assert target is not None
        turned = target.model_copy(update={"pose": Pose(x=x, y=12.0, yaw=0.7)})
        moved = moved.model_copy(update={"assets": [turned if a.id == asset_id else a for a in moved.assets]})
    stats = world.update(moved)
    assert not stats.recompiled
    model, data = world.model, world.data
    geoms = [g.id for i in ("bench_1", "cone_1", "ped_1") for g in world.pool.slot_of(i).geoms]  # type: ignore[union-attr]
    fast = np.array(data.geom_xpos[geoms]), np.array(data.geom_xmat[geoms])
    flags = int(model.opt.enableflags)
    model.opt.enableflags = flags & ~int(mujoco.mjtEnableBit.mjENBL_SLEEP)
    mujoco.mj_kinematics(model, data)
    model.opt.enableflags = flags
    np.testing.assert_allclose(fast[0], data.geom_xpos[geoms], atol=1e-12)
    np.testing.assert_allclose(fast[1], data.geom_xmat[geoms], atol=1e-12)
