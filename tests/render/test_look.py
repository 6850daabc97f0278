"""The environment (clock, weather, lights) changes what the camera sees, repeatably."""

from __future__ import annotations

import numpy as np
import pytest
from drivetwin.worlds.defaults import load_world
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.hybrid import HybridRenderer, chase_camera, default_camera
from drivetwin.worlds.render.look import finish, look_of, sky_image, sun_elevation_azimuth
from drivetwin.worlds.scene import Environment, Lighting, Weather

WIDTH, HEIGHT = 160, 90


def _luminance(rgb: np.ndarray) -> np.ndarray:
    return np.asarray(rgb, np.float64) @ np.array([0.2126, 0.7152, 0.0722])


@pytest.fixture(scope="module")
def campus_view() -> tuple[MujocoWorld, HybridRenderer]:
    world = MujocoWorld.from_scene(load_world("campus"))
    return world, HybridRenderer(world, seed=7)


def test_the_sun_is_high_at_noon_low_at_dusk_and_down_at_midnight() -> None:
    noon, dusk, midnight = (sun_elevation_azimuth(h)[0] for h in (12.5, 18.5, 0.0))
    assert noon > 55 and 0 < dusk < 10 and midnight < 0
    assert look_of(Environment(time_of_day="12:30")).to_sun[1] < 0  # due south at noon


def test_a_night_frame_is_darker_than_a_noon_frame(campus_view) -> None:  # type: ignore[no-untyped-def]
    world, renderer = campus_view
    camera = default_camera(world.scene, WIDTH, HEIGHT)
    noon = renderer.render(camera, Environment(time_of_day="12:00")).rgb
    night = renderer.render(camera, Environment(time_of_day="23:00")).rgb
    assert _luminance(night).mean() < 0.4 * _luminance(noon).mean()


def test_street_lights_glow_at_night_only_when_they_are_on(campus_view) -> None:  # type: ignore[no-untyped-def]
    world, renderer = campus_view
    camera = chase_camera(world, width=WIDTH, height=HEIGHT)
    on = Environment(time_of_day="23:00", lighting=Lighting(street_lights="on"))
    off = Environment(time_of_day="23:00", lighting=Lighting(street_lights="off", vehicle_lights="off"))
    lit, dark = renderer.render(camera, on).rgb, renderer.render(camera, off).rgb
    assert _luminance(lit).max() > 200 and _luminance(dark).max() < 120
    assert _luminance(lit).mean() > _luminance(dark).mean()


def test_rain_changes_the_frame_the_same_way_every_time_for_a_seed(campus_view) -> None:  # type: ignore[no-untyped-def]
    world, renderer = campus_view
    camera = chase_camera(world, width=WIDTH, height=HEIGHT)
    rain = Environment(weather=Weather(kind="rain", intensity=0.8))
    clear = renderer.render(camera, Environment(), time_s=1.0).rgb
    first = renderer.render(camera, rain, time_s=1.0).rgb
    again = renderer.render(camera, rain, time_s=1.0).rgb
    later = renderer.render(camera, rain, time_s=1.2).rgb
    assert np.array_equal(first, again)
    assert not np.array_equal(first, clear) and not np.array_equal(first, later)
    other_seed = HybridRenderer(world, seed=8).render(camera, rain, time_s=1.0).rgb
    assert not np.array_equal(first, other_seed)


def _flat_ground_view() -> tuple[Camera, np.ndarray, np.ndarray]:
    """A camera 2 m above flat ground, with a grey image and the ground's camera-z depth."""
    camera = Camera.from_look_at((0, 0, 2.0), (10, 0, 0.0), width=64, height=48, fovy_deg=60)
    rows = (np.arange(48) + 0.5 - camera.cy) / camera.fy
    cols = (np.arange(64) + 0.5 - camera.cx) / camera.fx
    rays = np.stack(np.broadcast_arrays(cols[None, :], rows[:, None], 1.0), -1)
    world_rays = rays @ camera.world_to_camera[:3, :3]
    with np.errstate(divide="ignore"):
        depth = np.where(world_rays[..., 2] < 0, -2.0 / world_rays[..., 2], np.inf)
    rgb = np.full((48, 64, 3), 0.5, np.float32)
    return camera, rgb, depth.astype(np.float32)


def test_fog_pulls_far_pixels_closer_to_the_fog_colour_than_near_ones() -> None:
    camera, rgb, depth = _flat_ground_view()
    look = look_of(Environment(weather=Weather(kind="fog", intensity=0.7)))
    out = finish(rgb, depth, camera, look).astype(np.float64) / 255
    fog = np.asarray(look.fog_rgb)
    near, far = np.argmin(depth[:, 32]), np.argmax(np.where(np.isfinite(depth[:, 32]), depth[:, 32], 0))
    gap = np.abs(out[:, 32] - fog).sum(axis=-1)
    assert depth[far, 32] > 3 * depth[near, 32]
    assert gap[far] < 0.5 * gap[near]


def test_a_wet_road_is_darker_than_a_dry_one_and_snow_whitens_it() -> None:
    camera, rgb, depth = _flat_ground_view()
    ground = np.isfinite(depth)
    dry = finish(rgb, depth, camera, look_of(Environment()))
    wet = finish(rgb, depth, camera, look_of(Environment(weather=Weather(kind="rain", intensity=1.0))))
    snowy = finish(rgb, depth, camera, look_of(Environment(weather=Weather(kind="snow", intensity=1.0))))
    # Compare away from the particles: the median ground pixel.
    assert np.median(_luminance(wet[ground])) < 0.8 * np.median(_luminance(dry[ground]))
    assert np.median(_luminance(snowy[ground])) > 1.2 * np.median(_luminance(dry[ground]))


def test_exposure_brightens_the_frame() -> None:
    camera, rgb, depth = _flat_ground_view()
    normal = finish(rgb, depth, camera, look_of(Environment()))
    bright = finish(rgb, depth, camera, look_of(Environment(lighting=Lighting(exposure=1.5))))
    assert _luminance(bright).mean() > 1.3 * _luminance(normal).mean()


def test_a_clear_sky_keeps_its_horizon_to_zenith_gradient_through_the_haze() -> None:
    camera = Camera.from_look_at((0, 0, 2.0), (10, 0, 8.0), width=64, height=48, fovy_deg=70)
    look = look_of(Environment(time_of_day="12:00"))
    sky = sky_image(camera, look)
    out = finish(sky, np.full((48, 64), np.inf, np.float32), camera, look).astype(np.float64) / 255
    top, bottom = out[0].mean(axis=0), out[-1].mean(axis=0)
    # The top rows look higher up: bluer and darker than the hazy rows near the horizon.
    assert np.abs(top - bottom).sum() > 0.15
    assert top[2] - top[0] > bottom[2] - bottom[0]


def test_dense_fog_hides_the_sky_too() -> None:
    camera = Camera.from_look_at((0, 0, 2.0), (10, 0, 8.0), width=64, height=48, fovy_deg=70)
    look = look_of(Environment(weather=Weather(kind="fog", intensity=1.0)))
    out = finish(sky_image(camera, look), np.full((48, 64), np.inf, np.float32), camera, look)
    fog = np.round(np.asarray(look.fog_rgb) * look.exposure * 255)
    assert np.abs(out.astype(np.float64) - fog).max() <= 2
