"""A reconstructed world package loads by name as a Scene that names its package: MuJoCo
collides its terrain height field and the hybrid renderer draws its splats as background."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh
from drivetwin.worlds.defaults import load_world
from drivetwin.worlds.heightfield import load_heightfield
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.mujoco_static import STATIC_PREFIXES, TERRAIN_PREFIX
from drivetwin.worlds.packages import HEIGHTFIELD_FILE
from drivetwin.worlds.reconstruct.fusion import fuse
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.hybrid import HybridRenderer
from drivetwin.worlds.render.splats import Splats
from drivetwin.worlds.scene import AssetInstance, Building, PhysicsProps, Pose, Scene
from fusion_capture import write_appearance

# A 15 m x 10 m ramp rising 0.1 m per metre from 0.4 m: wholly above the ground plane (z = 0),
# so a body resting on the plane instead of the terrain is 0.4 m or more too low.
ROWS, COLS, CELL_M = 11, 16, 1.0
ORIGIN = (-8.0, -5.0)
BASE_M, SLOPE = 0.4, 0.1
SPLAT_COUNT = 400
DROP_XY = (4.0, 1.0)
SETTLE_S = 1.5


def _ramp_height(x: float) -> float:
    return BASE_M + SLOPE * (x - ORIGIN[0])


def _write_ramp_halves(out_dir: Path) -> None:
    """The geometry half (height field, ground mesh) and the appearance half (splats on it)."""
    xs, ys = np.meshgrid(ORIGIN[0] + np.arange(COLS) * CELL_M, ORIGIN[1] + np.arange(ROWS) * CELL_M)
    heights = (BASE_M + SLOPE * (xs - ORIGIN[0])).astype(np.float32)
    (out_dir / "collision").mkdir(parents=True, exist_ok=True)
    np.savez(out_dir / HEIGHTFIELD_FILE, heights=heights, origin=np.array([*ORIGIN, BASE_M]), cell=np.array(CELL_M))
    faces = [
        face
        for r in range(ROWS - 1)
        for c in range(COLS - 1)
        for face in ((r * COLS + c, r * COLS + c + 1, (r + 1) * COLS + c),
                     (r * COLS + c + 1, (r + 1) * COLS + c + 1, (r + 1) * COLS + c))
    ]  # fmt: skip
    ground = trimesh.Trimesh(np.column_stack([xs.ravel(), ys.ravel(), heights.ravel()]), faces, process=False)
    ground.export(out_dir / "collision" / "mesh.obj")
    (out_dir / "geometry_report.json").write_text(json.dumps({"kind": "ground"}), encoding="utf-8")
    points, _ = trimesh.sample.sample_surface(ground, SPLAT_COUNT, seed=5)
    write_appearance(
        out_dir, Splats.from_points(np.asarray(points), np.tile((0.8, 0.3, 0.2), (SPLAT_COUNT, 1)), opacity=0.9)
    )


@pytest.fixture(scope="module")
def ramp_world(tmp_path_factory):
    """The world package `scanned_ramp` fused from the halves and loaded by name."""
    packages = tmp_path_factory.mktemp("packages")
    _write_ramp_halves(packages / "scanned_ramp")
    fuse(packages / "scanned_ramp", kind="world", description="A scanned ramp.")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("DRIVETWIN_ASSETS", str(packages))
        patch.setenv("DRIVETWIN_CACHE", str(tmp_path_factory.mktemp("cache")))
        yield load_world("scanned_ramp")


def _with_cone(scene: Scene) -> Scene:
    cone = AssetInstance(id="traffic_cone_1", category="traffic_cone", pose=Pose(x=DROP_XY[0], y=DROP_XY[1], z=2.5),
                         physics=PhysicsProps(mass=3.0))  # fmt: skip
    return scene.model_copy(update={"assets": [cone]})


def _settle(world: MujocoWorld) -> None:
    for _ in range(int(SETTLE_S / world.model.opt.timestep)):
        mujoco.mj_step(world.model, world.data)


def test_a_world_package_loads_naming_its_package_and_keeps_it_through_json(ramp_world, tmp_path):
    package = Path(ramp_world.package or "")
    assert package.is_absolute() and (package / HEIGHTFIELD_FILE).is_file()
    assert Scene.from_json(ramp_world.to_json()).package == ramp_world.package
    # Loading the package's world.json by path names the package too; a plain scene file does not.
    assert load_world(str(package / "world.json")).package == ramp_world.package
    plain = tmp_path / "plain.json"
    ramp_world.model_copy(update={"package": None}).save(plain)
    assert load_world(str(plain)).package is None


def test_the_world_packages_ego_starts_on_the_terrain(ramp_world):
    ego = ramp_world.ego
    terrain = load_heightfield(Path(ramp_world.package or "") / HEIGHTFIELD_FILE)
    assert ego.pose.z == pytest.approx(terrain.height_at(ego.pose.x, ego.pose.y), abs=1e-6)
    assert ego.pose.z > 0.3  # the ramp is raised: z = 0 would bury the ego


def test_a_body_dropped_on_a_world_package_rests_on_its_terrain(ramp_world):
    world = MujocoWorld.from_scene(_with_cone(ramp_world))
    terrain = world.model.geom(f"{TERRAIN_PREFIX}/ground")
    assert terrain.name.startswith(STATIC_PREFIXES) and terrain.type == mujoco.mjtGeom.mjGEOM_HFIELD
    _settle(world)
    expected = load_heightfield(Path(ramp_world.package or "") / HEIGHTFIELD_FILE).height_at(*DROP_XY)
    assert expected == pytest.approx(_ramp_height(DROP_XY[0]), abs=1e-4)
    assert world.body_pose("traffic_cone_1").z == pytest.approx(expected, abs=0.03)


def test_a_static_rebuild_keeps_the_terrain_colliding(ramp_world):
    world = MujocoWorld.from_scene(ramp_world)
    shed = Building(id="shed", name="shed", footprint=[(-7.0, 3.0), (-6.0, 3.0), (-6.0, 4.0), (-7.0, 4.0)], height=2.0)
    stats = world.update(_with_cone(ramp_world.model_copy(update={"buildings": [shed]})))
    assert stats.static_rebuilt
    assert [world.model.hfield(i).name for i in range(world.model.nhfield)] == [f"{TERRAIN_PREFIX}/ground"]
    _settle(world)
    assert world.body_pose("traffic_cone_1").z == pytest.approx(_ramp_height(DROP_XY[0]), abs=0.03)


def test_the_hybrid_renderer_draws_a_world_package_splats_as_its_background(ramp_world):
    camera = Camera.from_look_at((-12.0, 0.0, 5.0), (0.0, 0.0, 0.8), width=96, height=72, fovy_deg=60.0)
    drawn = HybridRenderer(MujocoWorld.from_scene(ramp_world))
    bare = HybridRenderer(MujocoWorld.from_scene(ramp_world.model_copy(update={"package": None})))
    try:
        frame = drawn.compose(camera)
        without = bare.compose(camera)
    finally:
        drawn.close()
        bare.close()
    assert without.raster is None  # no buildings, no package: nothing to draw as splats
    assert frame.raster is not None and (frame.raster.alpha > 0.5).mean() > 0.2
    # The splats' brick red, not the grey terrain mesh under them.
    covered = frame.raster.alpha > 0.5
    red, green = frame.rgb[..., 0][covered], frame.rgb[..., 1][covered]
    assert np.median(red - green) > 0.2
