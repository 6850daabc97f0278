"""Post-processing of a composited frame: sky, fog, wet or snowy ground, rain, snow, lamp glow.

Everything here works on the composited RGB + metric depth, so splats and meshes get the
same atmosphere. The per-pixel passes that run on every frame (fog, exposure) are single
Numba passes (`_numba_post`); the rest run only in the weather or lights that need them.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from . import _numba_post
from .camera import Camera

if TYPE_CHECKING:
    from .look import Lamp, Look

__all__ = ["finish", "lamp_irradiance", "sky_image", "world_points"]

F32 = npt.NDArray[np.float32]
F64 = npt.NDArray[np.float64]

# Road wetness: darken by this much at full rain, mirror a little sky.
WET_DARKENING, WET_SKY_SHEEN = 0.45, 0.08
GROUND_Z_M = 0.05  # pixels whose world z is below this are ground (road paint is 8 mm)
# Particles live in a world-fixed box around the camera, this large (metres).
PARTICLE_BOX_M = (30.0, 30.0, 14.0)
MAX_RAIN_DROPS, MAX_SNOW_FLAKES = 6000, 4000
RAIN_SPEED, SNOW_SPEED = 9.0, 1.2  # terminal fall speeds, m/s
SHUTTER_S = 1.0 / 30.0  # streak length is what falls during one video frame's exposure
MAX_STREAK_PX = 48
RAIN_RGBA = (0.78, 0.82, 0.88, 0.35)
SNOW_RGBA = (0.97, 0.97, 1.0, 0.85)
GLOW_RADIUS_M = 0.25  # apparent size of a lamp's halo
LAMP_REACH_M = 18.0  # irradiance of a lamp falls off over this distance
LAMP_STRENGTH = 0.8
SUN_GLARE_POWER = 400  # cos^400 halves about 3 degrees from the sun's centre
SUN_GLARE_COS = 0.97  # beyond ~14 degrees the glare is below 1e-5: skip those pixels
# Sky pixels see haze over the air layer this thick (not an infinite path, which would
# paint the whole sky the fog colour in any haze): thin overhead, thick at the horizon.
HAZE_LAYER_M = 300.0
MIN_SKY_ELEVATION_SIN = 0.01  # rays at or below the horizon cross 100 layer thicknesses


# Geometry helpers ---------------------------------------------------------------------------
def _camera_key(camera: Camera) -> tuple[int, int, float, float, float, float, bytes]:
    """What the per-pixel ray tables depend on: intrinsics and orientation (not position)."""
    rotation = camera.world_to_camera[:3, :3]
    return (camera.width, camera.height, camera.fx, camera.fy, camera.cx, camera.cy,
            rotation.tobytes())  # fmt: skip


def _rays(camera: Camera) -> F32:
    """World-frame ray directions [H,W,3] with camera-z component 1 (scale by depth)."""
    return _cached_rays(_camera_key(camera))


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


@functools.lru_cache(maxsize=8)
def _cached_sky_distance(key: tuple[int, int, float, float, float, float, bytes]) -> F32:
    rays, lengths = _cached_rays(key), _cached_ray_lengths(key)
    up = np.maximum(rays[..., 2] / lengths, MIN_SKY_ELEVATION_SIN)
    distance: F32 = (HAZE_LAYER_M / up).astype(np.float32)
    distance.setflags(write=False)
    return distance


def world_points(depth: npt.NDArray[np.floating], camera: Camera) -> F64:
    """World points [H,W,3] of a camera-z depth map (inf depth gives inf/nan points)."""
    with np.errstate(invalid="ignore"):
        return camera.position + _rays(camera) * np.asarray(depth, np.float64)[..., None]


def sky_image(camera: Camera, look: Look) -> F32:
    """The sky [H,W,3] behind everything: horizon colour blending to zenith with elevation.

    Cached per camera orientation and look (read-only result): a still camera pays once.
    """
    return _cached_sky(_camera_key(camera), look)


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
    """Weather and exposure on a composited frame: wet or snowy ground, fog by depth (the
    sky by its path through the haze layer), lamp glow, precipitation streaks; returns
    uint8 [H,W,3]. Same seed and time, same image."""
    out = rgb.astype(np.float32, copy=True)
    depth = np.ascontiguousarray(depth, dtype=np.float32)
    if look.wetness > 0 or look.snow_cover > 0:
        finite = np.isfinite(depth)
        ground = finite & (world_points(np.where(finite, depth, 0.0), camera)[..., 2] < GROUND_Z_M)
        g = out[ground]
        g *= 1.0 - WET_DARKENING * look.wetness
        g += WET_SKY_SHEEN * look.wetness * np.asarray(look.sky_horizon, np.float32)
        snow = np.float32(look.snow_cover)
        g = g * (1 - snow) + snow * (0.25 + 0.75 * look.daylight)
        out[ground] = g
    if look.fog_density > 0:
        key = _camera_key(camera)
        _numba_post.apply_fog(out, depth, _cached_ray_lengths(key), _cached_sky_distance(key),
                              look.fog_density, np.asarray(look.fog_rgb, np.float32))  # fmt: skip
    _glow(out, depth, camera, look, lamps)
    if look.precipitation != "none" and look.precipitation_intensity > 0:
        _precipitation(out, depth, camera, look, seed, time_s)
    image = np.empty(out.shape, np.uint8)
    _numba_post.expose(out, look.exposure, image)
    return image


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
