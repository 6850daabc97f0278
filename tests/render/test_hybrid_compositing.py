"""Hybrid frames: splats and meshes occlude each other by depth; splat assets ride on bodies."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.hybrid import HybridRenderer, save_frame
from drivetwin.worlds.render.rasterize import rasterize
from drivetwin.worlds.render.splats import SH_C0, Splats
from drivetwin.worlds.scene import AssetInstance, Bounds, Environment, PhysicsProps, Pose, Scene

WALL_FRONT_X = 9.8
WALL_RGBA = [0.1, 0.2, 0.9, 1.0]
PROXY_RGBA = [0.0, 1.0, 0.0, 1.0]
NOON = Environment(time_of_day="12:30")


def tiny_world() -> MujocoWorld:
    """A wall 0.4 m thick in front of the origin and a free body with a green proxy sphere."""
    spec = mujoco.MjSpec()
    spec.visual.global_.offwidth, spec.visual.global_.offheight = 320, 240
    wall = spec.worldbody.add_body(name="wall", pos=[WALL_FRONT_X + 0.2, 0.0, 0.0])
    wall.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=[0.2, 1.0, 1.0], rgba=WALL_RGBA)
    mover = spec.worldbody.add_body(name="mover", pos=[5.0, 1.0, 0.0])
    mover.add_freejoint()
    mover.add_geom(type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[0.3, 0, 0], rgba=PROXY_RGBA)
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    ego = AssetInstance(id="ego", category="ego_vehicle", pose=Pose(x=-40.0, y=0.0),
                        physics=PhysicsProps(mass=1500.0))  # fmt: skip
    scene = Scene(name="tiny", bounds=Bounds(xmin=-50, xmax=50, ymin=-50, ymax=50), ego=ego)
    return MujocoWorld(spec, model, data, scene)


def blob(centres: list[tuple[float, float, float]], scale: float = 0.25,
         rgb: tuple[float, float, float] = (1.0, 0.0, 0.0)) -> Splats:  # fmt: skip
    """Nearly opaque round red splats at ``centres``."""
    n = len(centres)
    sh = np.zeros((n, 1, 3))
    sh[:, 0] = (np.asarray(rgb) - 0.5) / SH_C0
    return Splats(means=np.asarray(centres), quats=np.tile([1.0, 0, 0, 0], (n, 1)),
                  log_scales=np.full((n, 3), math.log(scale)), opacity_logits=np.full(n, 6.0),
                  sh=sh)  # fmt: skip


CAMERA = Camera.from_look_at((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), width=96, height=64, fovy_deg=40)
CENTRE = (32, 48)  # row, column of the pixel on the view axis


def _pixel(point: np.ndarray, camera: Camera = CAMERA) -> tuple[float, float]:
    p = camera.world_to_camera @ np.append(point, 1.0)
    return camera.fx * p[0] / p[2] + camera.cx, camera.fy * p[1] / p[2] + camera.cy


def _red(rgb: np.ndarray) -> np.ndarray:
    return (rgb[..., 0] > 0.5) & (rgb[..., 0] > 2 * rgb[..., 2]) & (rgb[..., 0] > 2 * rgb[..., 1])


@pytest.fixture(scope="module")
def world() -> MujocoWorld:
    return tiny_world()


def test_a_splat_between_the_camera_and_a_mesh_wall_is_drawn_in_front(world: MujocoWorld) -> None:
    renderer = HybridRenderer(world, background=blob([(5.0, 0.0, 0.0)]))
    comp = renderer.compose(CAMERA, NOON)
    assert comp.mesh.hit[CENTRE]  # the wall is behind the splat there
    assert _red(comp.rgb)[CENTRE]
    assert comp.depth[CENTRE] == pytest.approx(5.0, abs=0.1)


def test_a_splat_behind_a_mesh_wall_is_hidden_by_it(world: MujocoWorld) -> None:
    renderer = HybridRenderer(world, background=blob([(15.0, 0.0, 0.0)], scale=0.5))
    comp = renderer.compose(CAMERA, NOON)
    assert comp.raster is not None
    inside = comp.mesh.hit
    assert inside[CENTRE] and inside.sum() > 100
    # Inside the wall's silhouette every pixel is the wall's own colour: no splat leaks.
    assert np.array_equal(comp.rgb[inside], comp.mesh.rgb[inside])
    assert not comp.raster.alpha[inside].any()
    # The splat is really there: beside the wall, without the wall in front, it shows.
    beside = HybridRenderer(world, background=blob([(15.0, 4.0, 0.0)], scale=0.5))
    u, v = _pixel(np.array([15.0, 4.0, 0.0]))
    assert _red(beside.compose(CAMERA, NOON).rgb)[int(v), int(u)]


def test_the_mesh_shows_through_with_the_transmittance_splats_leave(world: MujocoWorld) -> None:
    splats = blob([(5.0, 0.0, 0.0), (5.0, 0.5, 0.3)], scale=0.35)
    splats.opacity_logits[:] = 0.0  # half-transparent, so the wall must show through
    renderer = HybridRenderer(world, background=splats)
    comp = renderer.compose(CAMERA, NOON)
    raster = rasterize(splats, CAMERA, background=None, depth_limit=comp.mesh.depth)
    under = np.where(comp.mesh.hit[..., None], comp.mesh.rgb, comp.layer)
    expected = raster.rgb * np.asarray(comp.look.splat_gain, np.float32)
    expected = expected + raster.transmittance[..., None] * under
    partial = (raster.transmittance > 0.05) & (raster.transmittance < 0.95) & comp.mesh.hit
    assert partial.sum() > 20
    assert np.abs(comp.rgb - expected).max() < 1e-4


def test_a_splat_asset_follows_its_body_and_hides_its_mesh_proxy(world: MujocoWorld) -> None:
    offset = np.array([0.0, 0.5, 0.0])  # in the body frame: turning the body moves it
    renderer = HybridRenderer(world, attachments={"mover": blob([tuple(offset)], scale=0.15)})
    body = world.body_id("mover")
    joint_qpos = world.model.jnt_qposadr[world.model.body_jntadr[body]]
    positions = []
    for position, yaw in (((5.0, 1.0, 0.0), 0.0), ((5.0, -1.0, 0.0), math.pi / 2)):
        world.data.qpos[joint_qpos : joint_qpos + 3] = position
        world.data.qpos[joint_qpos + 3 : joint_qpos + 7] = [math.cos(yaw / 2), 0, 0, math.sin(yaw / 2)]
        mujoco.mj_forward(world.model, world.data)
        comp = renderer.compose(CAMERA, NOON)
        rows, cols = np.nonzero(_red(comp.rgb))
        assert len(rows) > 4
        rotation = np.array([[math.cos(yaw), -math.sin(yaw), 0], [math.sin(yaw), math.cos(yaw), 0],
                             [0, 0, 1]])  # fmt: skip
        u, v = _pixel(np.asarray(position) + rotation @ offset)
        assert abs(cols.mean() + 0.5 - u) < 1.0 and abs(rows.mean() + 0.5 - v) < 1.0
        green = (comp.rgb[..., 1] > 0.5) & (comp.rgb[..., 1] > 2 * comp.rgb[..., 0])
        assert not green.any()  # the collision proxy is not drawn
        positions.append((u, v))
    assert abs(positions[0][0] - positions[1][0]) > 10  # it really moved across the image


def test_a_frame_is_saved_with_its_depth_beside_it(world: MujocoWorld, tmp_path) -> None:  # type: ignore[no-untyped-def]
    renderer = HybridRenderer(world, background=blob([(5.0, 0.0, 0.0)]))
    frame = renderer.render(CAMERA, NOON)
    assert frame.rgb.dtype == np.uint8 and frame.rgb.shape == (64, 96, 3)
    paths = save_frame(frame, tmp_path / "frame.png")
    from PIL import Image

    depth_mm = np.asarray(Image.open(paths["depth_png"]))
    assert depth_mm[CENTRE] == pytest.approx(frame.depth[CENTRE] * 1000, abs=1)
    assert np.array_equal(np.load(paths["depth_npy"]), frame.depth)
    assert np.array_equal(np.asarray(Image.open(paths["rgb"])), frame.rgb)


def test_a_caller_holding_the_simulation_lock_can_render(world: MujocoWorld) -> None:
    # The scene is filled on the caller's thread, so a re-entrant simulation lock the
    # caller already holds does not block the mesh pass (which draws on its own thread).
    import threading

    lock = threading.RLock()
    renderer = HybridRenderer(world, background=blob([(5.0, 0.0, 0.0)]), lock=lock)
    frames = []

    def render_holding_the_lock() -> None:
        with lock:
            frames.append(renderer.render(CAMERA, NOON))

    worker = threading.Thread(target=render_holding_the_lock, daemon=True)
    worker.start()
    worker.join(timeout=60)
    assert not worker.is_alive(), "render deadlocked on the caller's own lock"
    assert _red(frames[0].rgb.astype(np.float32) / 255)[CENTRE]
    renderer.close()
