"""Appearance: what the Scene's environment (clock, weather, lighting) does to a frame.

`look_of` turns an `Environment` into a `Look` (sun direction and colour, ambient, sky,
fog, precipitation, which lights are on). The mesh pass gets GL lights from it
(`light_hook`); everything else is post-processing on the composited RGB + metric depth
(`postprocess`, re-exported here), so splats and meshes get the same sky, fog, wet road,
rain or snow and lamp glow.

The world frame is x east, y north, z up; the sun rises in the east at 06:00, is due
south at its highest (60 degrees) at 12:30 and sets in the west at 19:00 (the Scene's
`is_night` is 19:00 to 06:30).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import mujoco
import numpy as np
import numpy.typing as npt
from drivetwin.worlds.scene import Environment

from .mesh_pass import MAX_GL_LIGHTS, SceneHook
from .postprocess import LAMP_REACH_M, finish, lamp_irradiance, sky_image, world_points

__all__ = ["Lamp", "Look", "finish", "lamp_irradiance", "light_hook", "look_of", "sky_image",
           "sun_elevation_azimuth", "world_points"]  # fmt: skip

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
# At night, street lights scatter in fog and rain haze: the haze glows this warm grey
# instead of taking the near-black night sky's colour.
NIGHT_HAZE_GLOW: RGB = (0.15, 0.13, 0.1)
SNOW_COVER = 0.6  # share of snow white on the ground at full intensity
LAMP_RGB: RGB = (1.0, 0.82, 0.55)  # sodium-ish warm white
HEADLAMP_RGB: RGB = (0.95, 0.95, 1.0)


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
    street_lights = lighting.street_lights == "on" or (lighting.street_lights == "auto" and environment.is_night)
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
        fog_rgb=_haze_colour(horizon, daylight, street_lights, kind),
        precipitation="rain" if kind == "rain" else "snow" if kind == "snow" else "none",
        precipitation_intensity=intensity if kind in ("rain", "snow") else 0.0,
        wetness=intensity if kind == "rain" else 0.3 * intensity if kind == "snow" else 0.0,
        snow_cover=SNOW_COVER * intensity if kind == "snow" else 0.0,
        street_lights=street_lights,
        vehicle_lights=lighting.vehicle_lights == "on"
        or (lighting.vehicle_lights == "auto" and (environment.is_night or bad_weather)),
    )


def _haze_colour(horizon: RGB, daylight: float, street_lights: bool, kind: str) -> RGB:
    """Fog colour: the horizon's, lifted towards the lamps' glow at night in fog or rain."""
    if not street_lights or kind not in ("fog", "rain", "snow"):
        return horizon
    glow = _scale(NIGHT_HAZE_GLOW, 1.0 - daylight)
    return (max(horizon[0], glow[0]), max(horizon[1], glow[1]), max(horizon[2], glow[2]))


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
