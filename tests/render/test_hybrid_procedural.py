"""Procedural splats let a Scene without a capture render as a hybrid (splats + meshes) frame."""

from __future__ import annotations

import numpy as np
from drivetwin.worlds.catalog import category
from drivetwin.worlds.defaults import load_world
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.render.hybrid import (
    HybridRenderer,
    asset_splats,
    default_camera,
    facade_splats,
)
from drivetwin.worlds.render.look import world_points
from drivetwin.worlds.scene import Environment


def test_asset_splats_cover_the_category_and_no_more() -> None:
    car = category("passenger_car")
    splats = asset_splats("passenger_car", scale=1.5)
    low, high = splats.means.min(axis=0), splats.means.max(axis=0)
    assert len(splats) > 1000
    np.testing.assert_allclose(high[0] - low[0], 1.5 * car.length, rtol=0.05)
    np.testing.assert_allclose(high[2], 1.5 * car.height, rtol=0.05)
    assert low[2] >= -1e-6  # nothing below the ground the car stands on


def test_a_campus_frame_shows_facade_splats_in_front_of_the_building_meshes() -> None:
    scene = load_world("campus")
    world = MujocoWorld.from_scene(scene)
    cars = {a.id: asset_splats(a.category) for a in scene.assets if a.category == "suv"}
    renderer = HybridRenderer(world, background=facade_splats(scene), attachments=cars)
    camera = default_camera(scene, 160, 90)
    comp = renderer.compose(camera, Environment(time_of_day="15:00"))
    assert comp.raster is not None
    heights = world_points(np.where(comp.mesh.hit, comp.mesh.depth, 0.0), camera)[..., 2]
    walls = comp.mesh.hit & (heights > 1.0)  # mostly building walls; posts and trees are thin
    assert walls.sum() > 300
    # Buildings are covered by their facade splats (the wall mesh does not hide them).
    assert (comp.raster.alpha[walls] > 0.5).mean() > 0.7


def test_a_removed_splat_asset_is_no_longer_drawn() -> None:
    scene = load_world("campus")
    world = MujocoWorld.from_scene(scene)
    suv = next(a for a in scene.assets if a.category == "suv")
    renderer = HybridRenderer(world, background=None, attachments={suv.id: asset_splats("suv")})
    camera = default_camera(scene, 96, 54)
    assert renderer.compose(camera).raster is not None
    world.update(scene.model_copy(update={"assets": [a for a in scene.assets if a.id != suv.id]}))
    assert renderer.compose(camera).raster is None  # nothing left to rasterize, no error


def test_a_renderer_given_no_background_draws_the_scenes_facades_as_splats() -> None:
    scene = load_world("campus")
    world = MujocoWorld.from_scene(scene)
    camera = default_camera(scene, 96, 54)
    default = HybridRenderer(world).compose(camera)
    explicit = HybridRenderer(world, background=facade_splats(scene)).compose(camera)
    assert default.raster is not None and explicit.raster is not None
    assert np.array_equal(default.rgb, explicit.rgb)
    assert HybridRenderer(world, background=None).compose(camera).raster is None
