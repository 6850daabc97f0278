"""Appearance: what the Scene's environment (clock, weather, lighting) does to a frame.

`look_of` turns an `Environment` into a `Look` (sun direction and colour, ambient, sky,
fog, precipitation, which lights are on). The mesh pass gets GL lights from it
(`light_hook`); everything else is post-processing on the composited RGB + metric depth,
so splats and meshes get the same sky, fog, wet road, rain or snow and lamp glow.

The world frame is x east, y north, z up; the sun rises in the east at 06:00, is due
south at its highest (60 degrees) at 12:30 and sets in the west at 19:00 (the Scene's
`is_night` is 19:00 to 06:30).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import mujoco
import numpy as np
import numpy.typing as npt
from drivetwin.worlds.scene import Environment

from .camera import Camera
from .mesh_pass import MAX_GL_LIGHTS, SceneHook

__all__ = ["Lamp", "Look", "finish", "lamp_irradiance", "light_hook", "look_of", "sky_image",
           "world_points"]  # fmt: skip

F32 = npt.NDArray[np.float32]
F64 = npt.NDArray[np.float64]
RGB = tuple[float, float, float]

SUNRISE_H, SUNSET_H = 6.0, 19.0
MAX_SUN_ELEVATION_DEG = 60.0  # a mid-latitude summer noon
# Twilight: the sky darkens from 10 degrees above the horizon to 6 below (civil twilight).
TWILIGHT_DEG = (-6.0, 10.0)
NIGHT_AMBIENT: RGB = (0.035, 0.04, 0.07)  # moonlit, bluish
DAY_AMBIENT: RGB = (0.32, 0.33, 0.35)
NOON_SUN: RGB = (0.72, 0.7, 0.66)
LOW_SUN: RGB = (0.75, 0.42, 0.22)  # red-orange light through a long air path
SKY_ZENITH_DAY: RGB = (0.32, 0.52, 0.86)
SKY_HORIZON_DAY: RGB = (0.74, 0.82, 0.92)
SKY_HORIZON_DUSK: RGB = (0.95, 0.58, 0.38)
SKY_ZENITH_NIGHT: RGB = (0.01, 0.014, 0.035)
SKY_HORIZON_NIGHT: RGB = (0.04, 0.05, 0.08)
OVERCAST: RGB = (0.62, 0.64, 0.67)
# Fog density (1/m) by weather; visibility is about 3.9 / density (Koschmieder).
CLEAR_HAZE = 0.0004  # ~10 km visibility
FOG_DENSITY = (0.004, 0.06)  # light fog ~1 km visibility, dense fog ~65 m
RAIN_HAZE, SNOW_HAZE = 0.004, 0.008  # per unit intensity
# Vehicle lights come on by day too when the weather is at least this bad.
LIGHTS_WEATHER_INTENSITY = 0.5
# Road wetness: darken by this much at full rain, mirror a little sky.
WET_DARKENING, WET_SKY_SHEEN = 0.45, 0.08
SNOW_COVER = 0.6  # share of snow white on the ground at full intensity
GROUND_Z_M = 0.05  # pixels whose world z is below this are ground (road paint is 8 mm)
# Particles live in a world-fixed box around the camera, this large (metres).
PARTICLE_BOX_M = (30.0, 30.0, 14.0)
MAX_RAIN_DROPS, MAX_SNOW_FLAKES = 6000, 4000
RAIN_SPEED, SNOW_SPEED = 9.0, 1.2  # terminal fall speeds, m/s
SHUTTER_S = 1.0 / 30.0  # streak length is what falls during one video frame's exposure
MAX_STREAK_PX = 48
RAIN_RGBA = (0.78, 0.82, 0.88, 0.35)
SNOW_RGBA = (0.97, 0.97, 1.0, 0.85)
LAMP_RGB: RGB = (1.0, 0.82, 0.55)  # sodium-ish warm white
HEADLAMP_RGB: RGB = (0.95, 0.95, 1.0)
GLOW_RADIUS_M = 0.25  # apparent size of a lamp's halo
LAMP_REACH_M = 18.0  # irradiance of a lamp falls off over this distance
LAMP_STRENGTH = 0.8
SUN_GLARE_POWER = 400  # cos^400 halves about 3 degrees from the sun's centre
SUN_GLARE_COS = 0.97  # beyond ~14 degrees the glare is below 1e-5: skip those pixels


@dataclass(frozen=True)
class Look:
    """Lighting and atmosphere for one frame, derived from an Environment."""

    to_sun: tuple[float, float, float]  # unit vector from the scene towards the sun
    sun_rgb: RGB  # directional light colour (0 at night)
    ambient_rgb: RGB
    sky_zenith: RGB
    sky_horizon: RGB
    splat_gain: RGB  # multiplier on daylight-captured splat colours
    daylight: float  # 0 night .. 1 full day
    exposure: float
    fog_density: float
    fog_rgb: RGB
    precipitation: Literal["none", "rain", "snow"]
    precipitation_intensity: float
    wetness: float
    snow_cover: float
    street_lights: bool
    vehicle_lights: bool


@dataclass(frozen=True)
class Lamp:
    """A light source in the world: position, direction it shines (unit), colour, kind."""

    position: tuple[float, float, float]
    direction: tuple[float, float, float]
    rgb: RGB
    kind: Literal["street", "vehicle"]


def _mix(a: Sequence[float], b: Sequence[float], t: float) -> RGB:
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t)


def _scale(a: Sequence[float], s: float) -> RGB:
    return (a[0] * s, a[1] * s, a[2] * s)


def _smoothstep(lo: float, hi: float, x: float) -> float:
    t = min(1.0, max(0.0, (x - lo) / (hi - lo)))
    return t * t * (3 - 2 * t)


def sun_elevation_azimuth(hours: float) -> tuple[float, float]:
    """Sun elevation (deg; negative at night) and azimuth (rad from east, towards south)."""
    day_length = SUNSET_H - SUNRISE_H
    if SUNRISE_H <= hours <= SUNSET_H:
        phase = (hours - SUNRISE_H) / day_length
        return MAX_SUN_ELEVATION_DEG * math.sin(math.pi * phase), math.pi * phase
    since_sunset = (hours - SUNSET_H) % 24.0
    night_phase = since_sunset / (24.0 - day_length)
    return -30.0 * math.sin(math.pi * night_phase), math.pi * (1.0 + night_phase)


def look_of(environment: Environment) -> Look:
    """The Look an Environment asks for (deterministic, no randomness)."""
    elevation, azimuth = sun_elevation_azimuth(environment.hours)
    e = math.radians(elevation)
    to_sun = (math.cos(azimuth) * math.cos(e), -math.sin(azimuth) * math.cos(e), math.sin(e))
    daylight = _smoothstep(*TWILIGHT_DEG, elevation)
    warmth = _smoothstep(0.0, 30.0, elevation)
    sun = _scale(_mix(LOW_SUN, NOON_SUN, warmth), _smoothstep(-2.0, 8.0, elevation))
    ambient = _mix(NIGHT_AMBIENT, DAY_AMBIENT, daylight)
    zenith = _mix(SKY_ZENITH_NIGHT, SKY_ZENITH_DAY, daylight)
    horizon = _mix(SKY_HORIZON_NIGHT, _mix(SKY_HORIZON_DUSK, SKY_HORIZON_DAY, warmth), daylight)
    weather = environment.weather
    kind, intensity = weather.kind, weather.intensity
    overcast = {"clear": 0.0, "cloudy": 0.4 + 0.5 * intensity, "fog": 0.8,
                "rain": 0.6 + 0.35 * intensity, "snow": 0.6 + 0.3 * intensity}[kind]  # fmt: skip
    sun = _scale(sun, 1.0 - 0.85 * overcast)
    grey = _scale(OVERCAST, 0.15 + 0.85 * daylight)
    zenith, horizon = _mix(zenith, grey, overcast), _mix(horizon, grey, overcast)
    ambient = _scale(ambient, 1.0 - 0.25 * overcast)
    fog = {"clear": CLEAR_HAZE, "cloudy": CLEAR_HAZE * 2,
           "fog": FOG_DENSITY[0] + (FOG_DENSITY[1] - FOG_DENSITY[0]) * intensity,
           "rain": RAIN_HAZE * intensity, "snow": SNOW_HAZE * intensity}[kind]  # fmt: skip
    noon = np.add(DAY_AMBIENT, NOON_SUN)
    lit = np.add(ambient, np.multiply(sun, max(0.0, math.sin(e))))
    gain = tuple(float(v) for v in np.clip(lit / noon, 0.0, 1.5))
    bad_weather = kind in ("rain", "fog", "snow") and intensity >= LIGHTS_WEATHER_INTENSITY
    lighting = environment.lighting
    return Look(
        to_sun=to_sun,
        sun_rgb=sun,
        ambient_rgb=ambient,
        sky_zenith=zenith,
        sky_horizon=horizon,
        splat_gain=(gain[0], gain[1], gain[2]),
        daylight=daylight,
        exposure=lighting.exposure,
        fog_density=fog,
        fog_rgb=horizon,
        precipitation="rain" if kind == "rain" else "snow" if kind == "snow" else "none",
        precipitation_intensity=intensity if kind in ("rain", "snow") else 0.0,
        wetness=intensity if kind == "rain" else 0.3 * intensity if kind == "snow" else 0.0,
        snow_cover=SNOW_COVER * intensity if kind == "snow" else 0.0,
        street_lights=lighting.street_lights == "on" or (lighting.street_lights == "auto" and environment.is_night),
        vehicle_lights=lighting.vehicle_lights == "on"
        or (lighting.vehicle_lights == "auto" and (environment.is_night or bad_weather)),
    )


# GL lights --------------------------------------------------------------------------------
def light_hook(look: Look, lamps: Sequence[Lamp], camera_position: Sequence[float]) -> SceneHook:
    """A mesh-pass scene hook: sun and ambient from ``look``, nearest lamps as spot lights."""
    eye = np.asarray(camera_position, dtype=np.float64)

    def hook(scene: mujoco.MjvScene) -> None:
        sun_done = False
        for light in scene.lights[: scene.nlight]:
            if light.headlight:
                light.ambient = look.ambient_rgb
                light.diffuse = _scale(look.ambient_rgb, 0.6)  # a soft fill from the camera
                light.specular = (0.0, 0.0, 0.0)
            elif light.type == mujoco.mjtLightType.mjLIGHT_DIRECTIONAL:
                light.dir = [-v for v in look.to_sun]
                light.diffuse = look.sun_rgb if not sun_done else (0.0, 0.0, 0.0)
                light.ambient = (0.0, 0.0, 0.0)
                light.specular = _scale(look.sun_rgb, 0.2)
                sun_done = True
        near = sorted(lamps, key=lambda lamp: float(np.linalg.norm(np.subtract(lamp.position, eye))))
        for lamp in near[: max(0, MAX_GL_LIGHTS - scene.nlight)]:
            light = scene.lights[scene.nlight]
            scene.nlight += 1
            light.type = mujoco.mjtLightType.mjLIGHT_SPOT
            light.headlight = 0
            light.castshadow = 0
            light.pos, light.dir = lamp.position, lamp.direction
            light.diffuse = _scale(lamp.rgb, 1.2)
            light.ambient = (0.0, 0.0, 0.0)
            light.specular = (0.1, 0.1, 0.1)
            light.cutoff = 70.0 if lamp.kind == "street" else 35.0
            light.exponent = 2.0
            light.attenuation = (1.0, 0.0, 1.0 / LAMP_REACH_M**2 * 4.0)

    return hook


# Geometry helpers ---------------------------------------------------------------------------
def _rays(camera: Camera) -> F32:
    """World-frame ray directions [H,W,3] with camera-z component 1 (scale by depth)."""
    rotation = camera.world_to_camera[:3, :3]
    key = (camera.width, camera.height, camera.fx, camera.fy, camera.cx, camera.cy,
           rotation.tobytes())  # fmt: skip
    return _cached_rays(key)


@functools.lru_cache(maxsize=8)
def _cached_rays(key: tuple[int, int, float, float, float, float, bytes]) -> F32:
    width, height, fx, fy, cx, cy, rotation_bytes = key
    rotation = np.frombuffer(rotation_bytes, dtype=np.float64).reshape(3, 3).astype(np.float32)
    u = ((np.arange(width) + 0.5 - cx) / fx).astype(np.float32)
    v = ((np.arange(height) + 0.5 - cy) / fy).astype(np.float32)
    # R^T [u, v, 1]: the camera axes (rows of R) weighted by the pixel's normalised coords.
    rays: F32 = u[None, :, None] * rotation[0] + v[:, None, None] * rotation[1] + rotation[2]
    rays.setflags(write=False)
    return rays


@functools.lru_cache(maxsize=8)
def _cached_ray_lengths(key: tuple[int, int, float, float, float, float, bytes]) -> F32:
    rays = _cached_rays(key)
    lengths: F32 = np.sqrt(rays[..., 0] ** 2 + rays[..., 1] ** 2 + rays[..., 2] ** 2)
    lengths.setflags(write=False)
    return lengths


def _ray_lengths(camera: Camera) -> F32:
    rotation = camera.world_to_camera[:3, :3]
    key = (camera.width, camera.height, camera.fx, camera.fy, camera.cx, camera.cy,
           rotation.tobytes())  # fmt: skip
    return _cached_ray_lengths(key)


def world_points(depth: npt.NDArray[np.floating], camera: Camera) -> F64:
    """World points [H,W,3] of a camera-z depth map (inf depth gives inf/nan points)."""
    with np.errstate(invalid="ignore"):
        return camera.position + _rays(camera) * np.asarray(depth, np.float64)[..., None]


def sky_image(camera: Camera, look: Look) -> F32:
    """The sky [H,W,3] behind everything: horizon colour blending to zenith with elevation.

    Cached per camera orientation and look (read-only result): a still camera pays once.
    """
    rotation = camera.world_to_camera[:3, :3]
    key = (camera.width, camera.height, camera.fx, camera.fy, camera.cx, camera.cy,
           rotation.tobytes())  # fmt: skip
    return _cached_sky(key, look)


@functools.lru_cache(maxsize=4)
def _cached_sky(key: tuple[int, int, float, float, float, float, bytes], look: Look) -> F32:
    rays, lengths = _cached_rays(key), _cached_ray_lengths(key)
    up = rays[..., 2] / lengths
    t = np.sqrt(np.clip(up, 0.0, 1.0))[..., None]
    horizon = np.asarray(look.sky_horizon, np.float32)
    zenith = np.asarray(look.sky_zenith, np.float32)
    sky: F32 = horizon + (zenith - horizon) * t
    sx, sy, sz = (np.float32(v) for v in look.to_sun)
    sun_dot = (rays[..., 0] * sx + rays[..., 1] * sy + rays[..., 2] * sz) / lengths
    near_sun = sun_dot > SUN_GLARE_COS
    if near_sun.any():  # the sun's disc and glare
        glare = sun_dot[near_sun] ** SUN_GLARE_POWER
        sky[near_sun] += np.asarray(look.sun_rgb, np.float32) * glare[:, None] * 2.0
    sky.setflags(write=False)
    return sky


def lamp_irradiance(points: F64, lamps: Sequence[Lamp], mask: npt.NDArray[np.bool_]) -> F32:
    """Light [H,W,3] lamps throw on world ``points`` where ``mask`` (smooth distance falloff)."""
    out = np.zeros((*points.shape[:2], 3), np.float32)
    if not lamps or not mask.any():
        return out
    p = points[mask]
    total = np.zeros((p.shape[0], 3))
    for lamp in lamps:
        offset = p - np.asarray(lamp.position)
        dist2 = np.einsum("ij,ij->i", offset, offset)
        facing = np.clip((offset @ np.asarray(lamp.direction)) / np.sqrt(dist2 + 1e-9), 0, 1)
        total += np.outer(facing * LAMP_STRENGTH / (1.0 + dist2 / (LAMP_REACH_M / 3) ** 2), lamp.rgb)
    out[mask] = total
    return out


# Post-processing -----------------------------------------------------------------------------
def finish(
    rgb: F32,
    depth: F32,
    camera: Camera,
    look: Look,
    lamps: Sequence[Lamp] = (),
    *,
    seed: int = 0,
    time_s: float = 0.0,
) -> npt.NDArray[np.uint8]:
    """Weather and exposure on a composited frame: wet or snowy ground, fog by depth,
    precipitation streaks, lamp glow; returns uint8 [H,W,3]. Same seed and time, same image."""
    out = rgb.astype(np.float32, copy=True)
    finite = np.isfinite(depth)
    if look.wetness > 0 or look.snow_cover > 0:
        ground = finite & (world_points(np.where(finite, depth, 0.0), camera)[..., 2] < GROUND_Z_M)
        g = out[ground]
        g *= 1.0 - WET_DARKENING * look.wetness
        g += WET_SKY_SHEEN * look.wetness * np.asarray(look.sky_horizon, np.float32)
        snow = np.float32(look.snow_cover)
        g = g * (1 - snow) + snow * (0.25 + 0.75 * look.daylight)
        out[ground] = g
    if look.fog_density > 0:
        distance = np.where(finite, depth, np.inf) * _ray_lengths(camera)
        fog = (1.0 - np.exp(-look.fog_density * distance)).astype(np.float32)[..., None]
        out = out * (1 - fog) + np.asarray(look.fog_rgb, np.float32) * fog
    _glow(out, depth, camera, look, lamps)
    if look.precipitation != "none" and look.precipitation_intensity > 0:
        _precipitation(out, depth, camera, look, seed, time_s)
    out *= np.float32(look.exposure)
    return np.asarray(np.clip(out * 255.0 + 0.5, 0, 255), dtype=np.uint8)


def _project(points: F64, camera: Camera) -> tuple[F64, F64, F64]:
    cam = points @ camera.world_to_camera[:3, :3].T + camera.world_to_camera[:3, 3]
    z = cam[:, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        u = camera.fx * cam[:, 0] / z + camera.cx
        v = camera.fy * cam[:, 1] / z + camera.cy
    return u, v, z


def _glow(out: F32, depth: F32, camera: Camera, look: Look, lamps: Sequence[Lamp]) -> None:
    """Additive halos at lamp bulbs the camera can see (bigger and softer in fog)."""
    if not lamps:
        return
    u, v, z = _project(np.array([lamp.position for lamp in lamps]), camera)
    spread = 1.0 + 20.0 * look.fog_density
    for lamp, uu, vv, zz in zip(lamps, u, v, z, strict=True):
        if not zz > camera.near or not (0 <= uu < camera.width and 0 <= vv < camera.height):
            continue
        if depth[int(vv), int(uu)] < zz - 0.3:  # something stands in front of the bulb
            continue
        sigma = max(1.5, GLOW_RADIUS_M * camera.fx / zz) * spread
        r = int(4 * sigma) + 1
        x0, x1 = max(0, int(uu) - r), min(camera.width, int(uu) + r + 1)
        y0, y1 = max(0, int(vv) - r), min(camera.height, int(vv) + r + 1)
        xs, ys = np.arange(x0, x1) + 0.5 - uu, np.arange(y0, y1) + 0.5 - vv
        weight = np.exp(-(xs[None, :] ** 2 + ys[:, None] ** 2) / (2 * sigma**2)).astype(np.float32)
        out[y0:y1, x0:x1] += weight[..., None] * np.asarray(lamp.rgb, np.float32) * 1.5


def _precipitation(out: F32, depth: F32, camera: Camera, look: Look, seed: int, time_s: float) -> None:
    """Seeded rain streaks or snow flakes in a world-fixed box around the camera."""
    rain = look.precipitation == "rain"
    count = int((MAX_RAIN_DROPS if rain else MAX_SNOW_FLAKES) * look.precipitation_intensity)
    if count == 0:
        return
    rng = np.random.default_rng(seed)
    box = np.asarray(PARTICLE_BOX_M)
    start = rng.uniform(0.0, 1.0, (count, 3)) * box
    speed = RAIN_SPEED if rain else SNOW_SPEED
    phase = rng.uniform(0, 2 * np.pi, count)
    sway = np.zeros((count, 3))
    if not rain:  # flakes drift sideways as they fall
        sway[:, 0] = 0.4 * np.sin(1.3 * time_s + phase)
        sway[:, 1] = 0.4 * np.cos(0.9 * time_s + phase)
    velocity = np.array([0.8 if rain else 0.3, 0.3, -speed])
    corner = camera.position - box / 2
    moved = start + velocity * time_s + sway
    heads = corner + np.mod(moved - corner, box)  # particles stay put in the world
    tails = heads - velocity * SHUTTER_S * (1.0 if rain else 0.5)
    u0, v0, z0 = _project(heads, camera)
    u1, v1, z1 = _project(tails, camera)
    ok = (z0 > camera.near) & (z1 > camera.near)
    ok &= (u0 > -MAX_STREAK_PX) & (u0 < camera.width + MAX_STREAK_PX)
    ok &= (v0 > -MAX_STREAK_PX) & (v0 < camera.height + MAX_STREAK_PX)
    u0, v0, u1, v1, z0 = u0[ok], v0[ok], u1[ok], v1[ok], z0[ok]
    length = np.clip(np.hypot(u1 - u0, v1 - v0), 1.0, MAX_STREAK_PX)
    steps = int(MAX_STREAK_PX) if rain else 3
    t = np.linspace(0.0, 1.0, steps)[None, :]
    limit = length[:, None] / MAX_STREAK_PX if rain else np.ones((len(length), 1))
    used = t <= limit
    us = (u0[:, None] + (u1 - u0)[:, None] * t)[used]
    vs = (v0[:, None] + (v1 - v0)[:, None] * t)[used]
    zs = np.broadcast_to(z0[:, None], used.shape)[used]
    # Near drops are bigger and more transparent per pixel; far ones fade into the haze.
    size = np.broadcast_to((1.0 / np.maximum(z0, 1.0))[:, None], used.shape)[used]
    cols, rows = np.floor(us).astype(np.int64), np.floor(vs).astype(np.int64)
    inside = (cols >= 0) & (cols < camera.width) & (rows >= 0) & (rows < camera.height)
    cols, rows, zs, size = cols[inside], rows[inside], zs[inside], size[inside]
    visible = zs < depth[rows, cols]
    rgba = RAIN_RGBA if rain else SNOW_RGBA
    weight = rgba[3] * np.clip(size * 4.0, 0.15, 1.0)[visible]
    flat = rows[visible] * camera.width + cols[visible]
    cover = np.bincount(flat, weights=weight, minlength=camera.width * camera.height)
    if not rain:  # flakes are a couple of pixels wide
        grid = cover.reshape(camera.height, camera.width)
        grid[:, 1:] = grid[:, 1:] + 0.5 * grid[:, :-1]
        grid[1:, :] = grid[1:, :] + 0.5 * grid[:-1, :]
    alpha = np.clip(cover, 0.0, 1.0).reshape(camera.height, camera.width, 1).astype(np.float32)
    brightness = 0.35 + 0.65 * look.daylight  # drops catch what light there is
    colour = np.asarray(rgba[:3], np.float32) * np.float32(brightness)
    out *= 1 - alpha
    out += alpha * colour
