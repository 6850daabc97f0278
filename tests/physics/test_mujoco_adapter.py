"""Scene → MuJoCo: bodies named by asset id, edits patch the world and keep its state."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest
from conftest import make_asset, make_scene
from drivetwin.worlds.mujoco_adapter import MujocoWorld, UnknownBodyError, consistency_problems
from drivetwin.worlds.mujoco_static import OFFSCREEN_HEIGHT, OFFSCREEN_WIDTH, VIEW_CAMERA
from drivetwin.worlds.scene import (
    Appearance,
    AssetInstance,
    Building,
    Environment,
    Ground,
    PhysicsProps,
    Pose,
    Scene,
    Weather,
)


def _free_qvel(world: MujocoWorld, asset_id: str) -> np.ndarray:
    joint = world.joint_id(f"{asset_id}/free")
    start = world.model.jnt_dofadr[joint]
    return np.array(world.data.qvel[start : start + 6])


def _asset(scene: Scene, asset_id: str) -> AssetInstance:
    found = scene.asset(asset_id)
    assert found is not None
    return found


def _with(scene: Scene, **changes: object) -> Scene:
    return scene.model_copy(update=changes, deep=True)


def test_every_asset_is_one_top_level_body_found_by_its_id_and_the_ego_is_there() -> None:
    scene = make_scene(
        make_asset("cone_1", "traffic_cone", 5.0, 5.0),
        make_asset("walker_1", "pedestrian", 8.0, 5.0),
        make_asset("bench_1", "bench", 12.0, 5.0, physics=PhysicsProps(mass=45.0, dynamic=False)),
    )
    world = MujocoWorld.from_scene(scene)
    bodies = {world.body_id(i) for i in ("ego", "cone_1", "walker_1", "bench_1")}
    assert len(bodies) == 4 and all(world.model.body_parentid[b] == 0 for b in bodies)
    assert consistency_problems(scene, world) == []
    assert world.model.body_mocapid[world.body_id("walker_1")] >= 0
    assert world.model.body_weldid[world.body_id("bench_1")] == 0, "a static prop is welded"


def test_world_has_the_view_camera_a_full_hd_buffer_and_a_sun() -> None:
    world = MujocoWorld.from_scene(make_scene())
    model = world.model
    assert mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_CAMERA, VIEW_CAMERA) >= 0
    assert model.vis.global_.offwidth >= OFFSCREEN_WIDTH >= 1920
    assert model.vis.global_.offheight >= OFFSCREEN_HEIGHT >= 1080
    assert model.nlight >= 1


def test_buildings_collide_and_road_paint_does_not() -> None:
    scene = make_scene()
    scene.buildings.append(
        Building(id="hall", name="Hall", footprint=[(20, 20), (40, 20), (40, 30), (20, 30)], height=12.0)
    )
    scene.buildings.append(Building(id="tower", name="Tower", footprint=[(-40, 20), (-30, 20), (-35, 30)], height=30.0))
    model = MujocoWorld.from_scene(scene).model
    hall = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "building/hall")
    tower = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "building/tower")
    lane = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "lane/east/surface")
    assert model.geom_type[hall] == mujoco.mjtGeom.mjGEOM_BOX
    np.testing.assert_allclose(model.geom_size[hall], [10.0, 5.0, 6.0])
    assert model.geom_type[tower] == mujoco.mjtGeom.mjGEOM_MESH
    assert model.geom_contype[hall] and model.geom_contype[tower]
    assert model.geom_contype[lane] == 0 and model.geom_conaffinity[lane] == 0


def test_body_mass_is_the_asset_mass_and_colour_overrides_body_parts() -> None:
    car = make_asset(
        "car",
        "passenger_car",
        0.0,
        10.0,
        physics=PhysicsProps(mass=1234.0),
        appearance=Appearance(rgba=(1.0, 0.0, 0.0, 1.0)),
    )
    world = MujocoWorld.from_scene(make_scene(car))
    model = world.model
    assert math.isclose(model.body_subtreemass[world.body_id("car")], 1234.0)
    chassis = world.geom_id("car/part0")
    wheel = world.geom_id("car/wheel_fl")
    np.testing.assert_allclose(model.geom_rgba[chassis], [1.0, 0.0, 0.0, 1.0])
    assert not np.allclose(model.geom_rgba[wheel], [1.0, 0.0, 0.0, 1.0])


def test_update_keeps_a_rolling_body_rolling_and_places_the_new_asset_at_its_pose() -> None:
    scene = make_scene(make_asset("bin_1", "trash_bin", 0.0, 20.0))
    world = MujocoWorld.from_scene(scene)
    joint = world.joint_id("bin_1/free")
    world.data.qvel[world.model.jnt_dofadr[joint]] = 3.0
    for _ in range(5):
        mujoco.mj_step(world.model, world.data)
    before = _free_qvel(world, "bin_1")
    qpos_start = world.model.jnt_qposadr[joint]
    position = np.array(world.data.qpos[qpos_start : qpos_start + 7])
    assert before[0] > 1.0, "the bin should be sliding"
    added = _with(scene, assets=[*scene.assets, make_asset("cone_9", "traffic_cone", -30.0, 40.0, 1.0)])
    stats = world.update(added)
    assert stats.added == 1 and stats.unchanged == 2 and not stats.recompiled, "a pooled slot takes it"
    np.testing.assert_array_equal(_free_qvel(world, "bin_1"), before)
    moved_joint = world.model.jnt_qposadr[world.joint_id("bin_1/free")]
    np.testing.assert_array_equal(world.data.qpos[moved_joint : moved_joint + 7], position)
    cone = world.body_pose("cone_9")
    assert (cone.x, cone.y) == pytest.approx((-30.0, 40.0)) and cone.yaw == pytest.approx(1.0)
    assert consistency_problems(added, world) == []


def test_update_removes_the_body_of_a_removed_asset() -> None:
    scene = make_scene(make_asset("cone_1", "traffic_cone", 5.0, 5.0), make_asset("car", "suv", 0.0, 10.0))
    world = MujocoWorld.from_scene(scene)
    stats = world.update(_with(scene, assets=[]))
    assert stats.removed == 2
    with pytest.raises(UnknownBodyError, match="no body for asset 'car'"):
        world.body_id("car")
    assert world.actuator_id("car/drive_rl") == -1
    assert consistency_problems(_with(scene, assets=[]), world) == []


def test_a_moved_asset_restarts_at_its_new_pose_and_others_keep_state() -> None:
    scene = make_scene(make_asset("cone_1", "traffic_cone", 5.0, 5.0), make_asset("bin_1", "trash_bin", 0.0, 20.0))
    world = MujocoWorld.from_scene(scene)
    world.data.qvel[world.model.jnt_dofadr[world.joint_id("bin_1/free")]] = 2.0
    mujoco.mj_step(world.model, world.data)
    before = _free_qvel(world, "bin_1")
    moved = scene.model_copy(deep=True)
    _asset(moved, "cone_1").pose = Pose(x=7.0, y=-3.0, yaw=0.5)
    stats = world.update(moved)
    assert stats.replaced == 1
    assert world.body_pose("cone_1").x == pytest.approx(7.0)
    # The body's frame (what renderers and ray casts read) follows at once, before any step.
    np.testing.assert_allclose(world.data.xpos[world.body_id("cone_1")][:2], [7.0, -3.0], atol=1e-9)
    np.testing.assert_array_equal(_free_qvel(world, "bin_1"), before)


def test_environment_only_changes_touch_no_bodies() -> None:
    scene = make_scene(make_asset("cone_1", "traffic_cone", 5.0, 5.0))
    world = MujocoWorld.from_scene(scene)
    model = world.model
    rainy = _with(
        scene,
        environment=Environment(time_of_day="21:30", weather=Weather(kind="rain", intensity=0.8)),
    )
    stats = world.update(rainy)
    assert not stats.recompiled and stats.added == stats.removed == stats.replaced == 0
    assert world.model is model


def test_ground_friction_change_rebuilds_only_static_geoms() -> None:
    scene = make_scene(make_asset("cone_1", "traffic_cone", 5.0, 5.0))
    world = MujocoWorld.from_scene(scene)
    icy = _with(scene, ground=Ground(friction=0.2))
    stats = world.update(icy)
    assert stats.static_rebuilt and stats.replaced == 0
    ground = mujoco.mj_name2id(world.model, mujoco.mjtObj.mjOBJ_GEOM, "ground")
    assert world.model.geom_friction[ground][0] == pytest.approx(0.2)


def test_consistency_holds_after_a_series_of_edits() -> None:
    scene = make_scene()
    world = MujocoWorld.from_scene(scene)
    edits: list[Scene] = []
    s1 = _with(
        scene,
        assets=[make_asset("cone_1", "traffic_cone", 5, 5), make_asset("car_1", "bus", 0, 20)],
    )
    s2 = s1.model_copy(deep=True)
    _asset(s2, "cone_1").physics = PhysicsProps(mass=9.0, dynamic=False)
    _asset(s2, "car_1").scale = 0.5
    s3 = _with(s2, assets=[_asset(s2, "car_1"), make_asset("ped_1", "pedestrian", 3, 3)])
    s4 = s3.model_copy(deep=True)
    s4.ego.appearance = Appearance(rgba=(0.0, 0.0, 1.0, 1.0))
    _asset(s4, "ped_1").category = "bicycle"
    edits += [s1, s2, s3, s4, scene]
    for edited in edits:
        world.update(edited)
        assert consistency_problems(edited, world) == []


def test_consistency_reports_a_stale_world() -> None:
    scene = make_scene(make_asset("cone_1", "traffic_cone", 5.0, 5.0))
    world = MujocoWorld.from_scene(scene)
    grown = _with(scene, assets=[*scene.assets, make_asset("cone_2", "traffic_cone", 6.0, 5.0)])
    assert any("cone_2" in p for p in consistency_problems(grown, world))
    heavier = scene.model_copy(deep=True)
    _asset(heavier, "cone_1").physics = PhysicsProps(mass=30.0)
    assert any("mass" in p for p in consistency_problems(heavier, world))
    welded = scene.model_copy(deep=True)
    _asset(welded, "cone_1").physics = PhysicsProps(mass=3.0, dynamic=False)
    assert any("joint" in p for p in consistency_problems(welded, world))
    assert any("not an asset" in p for p in consistency_problems(_with(scene, assets=[]), world))


def test_moving_a_welded_or_walking_asset_needs_no_recompile_and_its_geoms_follow() -> None:
    scene = make_scene(
        make_asset("post", "bollard", 5.0, 5.0, physics=PhysicsProps(mass=40.0, dynamic=False)),
        make_asset("ped", "pedestrian", 8.0, 5.0),
    )
    world = MujocoWorld.from_scene(scene)
    model = world.model
    moved = scene.model_copy(deep=True)
    _asset(moved, "post").pose = Pose(x=-4.0, y=2.0)
    _asset(moved, "ped").pose = Pose(x=1.0, y=1.0, yaw=1.0)
    stats = world.update(moved)
    assert not stats.recompiled and world.model is model and stats.replaced == 2
    geom = world.geom_id("post/part0")
    np.testing.assert_allclose(world.data.geom_xpos[geom][:2], [-4.0, 2.0])
    assert world.body_pose("ped").yaw == pytest.approx(1.0)
    assert consistency_problems(moved, world) == []
    world.update(_with(moved, assets=[*moved.assets, make_asset("cone", "traffic_cone", 0.0, 9.0)]))
    assert world.body_pose("post").x == pytest.approx(-4.0), "a later recompile keeps the move"


def test_an_unknown_category_is_refused_and_leaves_the_world_as_it_was() -> None:
    from drivetwin.worlds.catalog import UnknownCategoryError

    scene = make_scene(make_asset("cone_1", "traffic_cone", 5.0, 5.0))
    world = MujocoWorld.from_scene(scene)
    bad = make_asset("cone_2", "traffic_cone", 6.0, 5.0).model_copy(update={"category": "pylonn"})
    with pytest.raises(UnknownCategoryError, match="nearest"):
        world.update(_with(scene, assets=[bad]))
    assert consistency_problems(scene, world) == []
