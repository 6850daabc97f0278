"""A real captured point cloud (Mip-NeRF 360 garden) as splats, with a mesh box composited in."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.hybrid import HybridRenderer
from drivetwin.worlds.render.splats import Splats
from drivetwin.worlds.scene import AssetInstance, Bounds, Environment, PhysicsProps, Pose, Scene

GARDEN = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "test_garden.npz"
SCALE = 0.25  # render at a quarter of the capture's 648x420
BOX_AHEAD_M = 0.2  # most of the capture is 0.3-2 m from its cameras
BOX_HALF_M = 0.02
BOX_RGBA = [0.9, 0.1, 0.8, 1.0]

pytestmark = pytest.mark.skipif(
    not GARDEN.exists(), reason=f"real capture {GARDEN} is absent (it lives outside the repo)"
)


def _box_world() -> MujocoWorld:
    spec = mujoco.MjSpec()
    spec.visual.global_.offwidth, spec.visual.global_.offheight = 320, 240
    box = spec.worldbody.add_body(name="box", mocap=True)
    box.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=[BOX_HALF_M] * 3, rgba=BOX_RGBA)
    model = spec.compile()
    data = mujoco.MjData(model)
    ego = AssetInstance(id="ego", category="ego_vehicle", pose=Pose(x=0.0, y=0.0),
                        physics=PhysicsProps(mass=1500.0))  # fmt: skip
    scene = Scene(name="garden", bounds=Bounds(xmin=-10, xmax=10, ymin=-10, ymax=10), ego=ego)
    return MujocoWorld(spec, model, data, scene)


def test_a_mesh_box_occludes_the_real_garden_splats_in_all_three_views() -> None:
    capture = np.load(GARDEN)
    splats = Splats.from_points(capture["means3d"], capture["colors"], opacity=0.8)
    world = _box_world()
    renderer = HybridRenderer(world, background=splats)
    splats_only = HybridRenderer(_box_world(), background=splats)
    width, height = int(capture["width"] * SCALE), int(capture["height"] * SCALE)
    environment = Environment(time_of_day="12:30")
    for view in range(3):
        k = capture["Ks"][view].astype(np.float64) * [[SCALE], [SCALE], [1.0]]
        camera = Camera.from_K(k, capture["viewmats"][view], width, height)
        # The box floats on the view axis a little ahead of the camera.
        ahead = camera.position + BOX_AHEAD_M * camera.camera_to_world[:3, 2]
        world.data.mocap_pos[0] = ahead
        mujoco.mj_forward(world.model, world.data)
        comp = renderer.compose(camera, environment)
        without = splats_only.compose(camera, environment)
        assert comp.raster is not None and without.raster is not None
        box = comp.mesh.hit
        assert 30 < box.sum() < 0.5 * width * height
        # Without the box the garden fills those pixels; with it, the box hides nearly all of
        # it: only splats whose depth is in front of the box's surface may still draw there.
        assert (without.raster.alpha[box] > 0.5).mean() > 0.9
        assert comp.raster.alpha[box].mean() < 0.25
        drawn = box & (comp.raster.alpha > 0)
        assert (comp.raster.depth[drawn] < comp.mesh.depth[drawn]).all()
        clean = box & (comp.raster.alpha == 0)
        assert clean.sum() > 0.5 * box.sum()
        assert np.array_equal(comp.rgb[clean], comp.mesh.rgb[clean])
        assert np.array_equal(comp.depth[clean], comp.mesh.depth[clean])
        assert (comp.depth[clean] < BOX_AHEAD_M + 2 * BOX_HALF_M).all()
        # Elsewhere the real garden is drawn, and it is not a flat colour.
        elsewhere = ~box & (comp.raster.alpha > 0.5)
        assert elsewhere.mean() > 0.5 and comp.rgb[elsewhere].std() > 0.05
