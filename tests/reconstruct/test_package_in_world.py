"""A packaged asset is a first-class asset: a Worker places it, MuJoCo collides its convex
parts, and the hybrid renderer draws its own splats."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from drivetwin.orchestrator.planning import Plan
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolRegistry
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.mujoco_adapter import MujocoWorld, consistency_problems
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.hybrid import HybridRenderer, asset_splats
from drivetwin.worlds.scene import AssetInstance, PhysicsProps, Pose
from fusion_capture import PIECES, fused_package

POST_TOP_M = 1.3  # the red post's top, package frame
SETTLE_S = 1.5


class ScriptedPlanner:
    """Plans exactly the calls it was given (the LLM's part is not under test here)."""

    name = "scripted"

    def __init__(self, *calls: ToolCall) -> None:
        self.calls = list(calls)

    def plan(self, prompt, context):
        return Plan(calls=self.calls, planner=self.name)


@pytest.fixture(scope="module")
def placed(tmp_path_factory):
    """The campus after `add_asset(kerb_stone)` through a Session, with the package on the path."""
    folder = fused_package(tmp_path_factory.mktemp("assets") / "kerb_stone", material="stone")
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("DRIVETWIN_ASSETS", str(folder))
        patch.setenv("DRIVETWIN_CACHE", str(tmp_path_factory.mktemp("cache")))
        call = ToolCall(tool="add_asset", args={"category": "kerb stone", "yaw_deg": 0})
        session = Session(build_campus(), ScriptedPlanner(call), ToolRegistry.default(plugins=False))
        report = session.submit("put the scanned kerb stone in the middle")
        assert report.ok, report.error
        yield session.scene


def _step(world: MujocoWorld, seconds: float) -> None:
    for _ in range(int(seconds / world.model.opt.timestep)):
        mujoco.mj_step(world.model, world.data)


def test_the_add_worker_places_a_packaged_asset_and_it_compiles_as_convex_parts(placed):
    stone = placed.asset("kerb_stone_1")
    assert stone is not None and stone.physics.mass > 1000.0  # stone density times volume
    world = MujocoWorld.from_scene(placed)
    body = world.body_id(stone.id)
    geoms = [g for g in range(world.model.ngeom) if world.model.geom_bodyid[g] == body]
    assert len(geoms) == len(PIECES)
    assert all(world.model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH for g in geoms)
    assert float(world.model.body_subtreemass[body]) == pytest.approx(stone.physics.mass)
    assert consistency_problems(placed, world) == []


def test_a_packaged_asset_rests_on_the_ground_and_a_dropped_body_rests_on_it(placed):
    stone = placed.asset("kerb_stone_1")
    # The red post stands at x = +0.6 and y = -0.125 in the package frame (yaw 0 here).
    cone = AssetInstance(id="traffic_cone_90", category="traffic_cone",
                         pose=Pose(x=stone.pose.x + 0.6, y=stone.pose.y - 0.125, z=POST_TOP_M + 0.4),
                         physics=PhysicsProps(mass=3.0))  # fmt: skip
    world = MujocoWorld.from_scene(placed.model_copy(update={"assets": [*placed.assets, cone]}))
    _step(world, SETTLE_S)
    assert world.body_pose(stone.id).z == pytest.approx(0.0, abs=0.01)  # neither sinks nor jumps
    assert world.body_pose(cone.id).z == pytest.approx(POST_TOP_M, abs=0.02)  # caught by the post


def _screen_box(camera: Camera, low: np.ndarray, high: np.ndarray) -> tuple[slice, slice]:
    corners = np.array(
        [[x, y, z, 1.0] for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])]
    )
    in_camera = (np.linalg.inv(camera.camera_to_world) @ corners.T)[:3]
    pixels = (camera.K @ in_camera)[:2] / in_camera[2]
    u0, v0 = np.floor(pixels.min(axis=1)).astype(int)
    u1, v1 = np.ceil(pixels.max(axis=1)).astype(int)
    return slice(max(v0, 0), v1), slice(max(u0, 0), u1)


def test_the_hybrid_renderer_draws_the_packaged_splats(placed):
    stone = placed.asset("kerb_stone_1")
    target = np.array([stone.pose.x, stone.pose.y, 0.6])
    camera = Camera.from_look_at(target + np.array([-3.0, -3.5, 1.8]), target, width=160, height=120, fovy_deg=50.0)
    rows, cols = _screen_box(camera, target - np.array([0.8, 0.4, 0.6]), target + np.array([0.8, 0.4, 0.7]))
    empty = HybridRenderer(MujocoWorld.from_scene(build_campus()))
    drawn = HybridRenderer(MujocoWorld.from_scene(placed), attachments={stone.id: asset_splats(stone.category)})
    try:
        before = empty.render(camera).rgb[rows, cols].astype(int)
        frame = drawn.compose(camera)
    finally:
        empty.close()
        drawn.close()
    after = np.clip(frame.rgb * 255, 0, 255)[rows, cols].astype(int)
    assert frame.raster is not None and (frame.raster.alpha[rows, cols] > 0.5).mean() > 0.2
    assert (np.abs(after - before).sum(axis=-1) > 60).mean() > 0.2
    # The post's red comes from the splats (the hidden collision hulls are one grey-pink).
    red = (after[..., 0] > 120) & (after[..., 0] > 2 * after[..., 1])
    assert red.sum() > 10


def test_a_live_chat_draws_a_placed_package_as_its_own_splats(placed, tmp_path):
    from drivetwin.orchestrator.live import LiveWorld

    session = Session(placed, ScriptedPlanner(), ToolRegistry.default(plugins=False))
    live = LiveWorld(session, simulate=True, background=False)
    try:
        written = live.render(session, tmp_path / "frame.png")
        attached = live._renderer.attachments
    finally:
        live.close()
    assert (tmp_path / "frame.png") in written
    assert set(attached) == {"kerb_stone_1"}
    assert len(attached["kerb_stone_1"]) == len(asset_splats("kerb_stone"))
