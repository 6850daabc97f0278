"""The still parts of a world as coloured triangle meshes, and its environment as sky, light and fog.

Roads, sidewalks, crossings, paved areas and buildings come from the Scene (the single
source of truth); the sky, sun, ambient light and fog come from the same `look_of` the
hybrid renderer uses, so the browser and the rendered frames agree on the weather and clock.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import shapely
import trimesh
from drivetwin.worlds.render.look import look_of
from drivetwin.worlds.scene import Environment, Lane, Scene

__all__ = ["EnvironmentView", "Surface", "environment_view", "lane_z", "sun_position", "world_surfaces"]

F64 = npt.NDArray[np.float64]
RGB = tuple[int, int, int]

# Each layer sits a little above the one below, so the browser's depth test never flickers
# between coplanar triangles (z-fighting) when seen from street level.
GROUND_Z, PAVED_Z, LANE_Z, SIDEWALK_Z, CROSSING_Z = 0.0, 0.01, 0.02, 0.06, 0.03
ASPHALT: RGB = (70, 72, 76)
SIDEWALK: RGB = (170, 168, 160)
CROSSING: RGB = (235, 235, 230)
PAVED: RGB = (95, 96, 98)
# Fog in the browser is linear (near, far); the renderer's is exponential with a density.
# Koschmieder: visibility ~ 3.9 / density; fog starts at a tenth of it and is opaque at it.
KOSCHMIEDER = 3.9
FOG_START_SHARE = 0.1
# Beyond this a clear day's haze is not worth drawing: the campus is a few hundred metres.
MAX_FOG_FAR_M = 3000.0
SKY_ROWS = 32  # rows of the sky gradient image; the browser stretches it to the window


@dataclass(frozen=True)
class Surface:
    """One coloured mesh of the still world (a layer: lanes, sidewalks, a building...)."""

    name: str
    mesh: trimesh.Trimesh
    rgb: RGB


@dataclass(frozen=True)
class EnvironmentView:
    """How the environment shows in the browser: sky image, sun, ambient light and fog."""

    sky: npt.NDArray[np.uint8]  # [SKY_ROWS, 1, 3], zenith at the top
    to_sun: tuple[float, float, float]
    sun_rgb: RGB
    sun_intensity: float
    ambient_rgb: RGB
    ambient_intensity: float
    fog_near: float
    fog_far: float
    fog_rgb: RGB
    caption: str  # "12:00, rain 0.6" for the status line


def _rgb(values: npt.ArrayLike) -> RGB:
    r, g, b = (round(255 * min(1.0, max(0.0, float(v)))) for v in np.asarray(values, dtype=np.float64)[:3])
    return (r, g, b)


def _strip(points: Sequence[Sequence[float]], width: float, z: npt.ArrayLike) -> trimesh.Trimesh | None:
    """A flat ribbon `width` wide along a polyline, at height z (one per point, or one for all)."""
    line = np.asarray(points, dtype=np.float64)
    if len(line) < 2:
        return None
    tangents = np.gradient(line, axis=0)
    norms = np.linalg.norm(tangents, axis=1, keepdims=True)
    if not np.all(norms > 0):
        return None
    normals = np.stack([-tangents[:, 1], tangents[:, 0]], axis=1) / norms
    heights = np.broadcast_to(np.asarray(z, dtype=np.float64), (len(line),))
    left = np.column_stack([line + normals * width / 2, heights])
    right = np.column_stack([line - normals * width / 2, heights])
    vertices = np.vstack([left, right])
    n = len(line)
    faces = [f for i in range(n - 1) for f in ((i, n + i, i + 1), (i + 1, n + i, n + i + 1))]
    return trimesh.Trimesh(vertices, np.asarray(faces), process=False)


def _triangles(shape: shapely.Polygon) -> tuple[F64, npt.NDArray[np.int64]]:
    """Vertices [V,2] and faces [F,3] (counter-clockwise) of a polygon, holes respected."""
    triangles = shapely.get_parts(shapely.constrained_delaunay_triangles(shape))
    corners = np.asarray([np.asarray(t.exterior.coords)[:3] for t in triangles], dtype=np.float64)
    if not len(corners):
        return np.zeros((0, 2)), np.zeros((0, 3), dtype=np.int64)
    edge1, edge2 = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]
    clockwise = edge1[:, 0] * edge2[:, 1] - edge1[:, 1] * edge2[:, 0] < 0
    corners[clockwise] = corners[clockwise][:, ::-1]
    return corners.reshape(-1, 2), np.arange(3 * len(corners)).reshape(-1, 3)


def _polygon(points: Sequence[Sequence[float]], z: float, height: float | None = None) -> trimesh.Trimesh | None:
    """A polygon as a flat face at z, or extruded `height` up from z (a building)."""
    shape = shapely.Polygon(points)
    if not shape.is_valid:
        shape = shape.buffer(0)
    if shape.is_empty or shape.area <= 0 or not isinstance(shape, shapely.Polygon):
        return None
    vertices, faces = _triangles(shape)
    top = height if height is not None else 0.0
    roof = trimesh.Trimesh(np.column_stack([vertices, np.full(len(vertices), z + top)]), faces, process=False)
    if height is None:
        return roof
    ring = np.asarray(shapely.geometry.polygon.orient(shape).exterior.coords)[:-1]
    n = len(ring)
    walls_vertices = np.vstack([np.column_stack([ring, np.full(n, z)]), np.column_stack([ring, np.full(n, z + top)])])
    walls_faces = [f for i in range(n) for f in ((i, (i + 1) % n, n + i), ((i + 1) % n, n + (i + 1) % n, n + i))]
    walls = trimesh.Trimesh(walls_vertices, np.asarray(walls_faces), process=False)
    merged = trimesh.util.concatenate([roof, walls])
    return merged if isinstance(merged, trimesh.Trimesh) else None


def _merged(name: str, meshes: Sequence[trimesh.Trimesh | None], rgb: RGB) -> list[Surface]:
    parts = [m for m in meshes if m is not None and len(m.faces)]
    if not parts:
        return []
    merged = trimesh.util.concatenate(parts)
    return [Surface(name, merged, rgb)] if isinstance(merged, trimesh.Trimesh) else []


def lane_z(lane: Lane) -> F64:
    """Height of a lane's surface at each centreline point (imported maps have elevation)."""
    return np.asarray(lane.elevation if lane.elevation is not None else [0.0] * len(lane.centreline))


def world_surfaces(scene: Scene) -> list[Surface]:
    """The ground, roads, sidewalks, crossings, paved areas and buildings of a scene."""
    b = scene.bounds
    ground = _polygon([(b.xmin, b.ymin), (b.xmax, b.ymin), (b.xmax, b.ymax), (b.xmin, b.ymax)], GROUND_Z)
    roads = scene.roads
    surfaces = _merged("ground", [ground], _rgb(scene.ground.rgba))
    surfaces += _merged("paved", [_polygon(p.polygon, PAVED_Z) for p in roads.paved], PAVED)
    surfaces += _merged("lanes", [_strip(lane.centreline, lane.width, lane_z(lane) + LANE_Z) for lane in roads.lanes],
                        ASPHALT)
    surfaces += _merged("sidewalks", [_strip(s.polyline, s.width, SIDEWALK_Z) for s in roads.sidewalks], SIDEWALK)
    surfaces += _merged("crossings", [_strip([c.start, c.end], c.width, CROSSING_Z) for c in roads.crossings],
                        CROSSING)
    for building in scene.buildings:
        surfaces += _merged(f"buildings/{building.id}", [_polygon(building.footprint, GROUND_Z, building.height)],
                            _rgb(building.rgba))
    return surfaces


def environment_view(environment: Environment) -> EnvironmentView:
    """Sky gradient, sun, ambient light and fog of an environment, as the renderer sees it."""
    look = look_of(environment)
    rows = np.linspace(0.0, 1.0, SKY_ROWS)[:, None]
    sky = (np.asarray(look.sky_zenith) * (1 - rows) + np.asarray(look.sky_horizon) * rows) * look.exposure
    sky_image = np.clip(np.round(sky * 255), 0, 255).astype(np.uint8)[:, None, :]
    visibility = KOSCHMIEDER / max(look.fog_density, 1e-9)
    far = min(MAX_FOG_FAR_M, visibility)
    sun_peak = max(look.sun_rgb)
    ambient_peak = max(look.ambient_rgb)
    weather = environment.weather
    caption = environment.time_of_day + (
        f", {weather.kind}" if weather.kind == "clear" else f", {weather.kind} {weather.intensity:.1f}")
    return EnvironmentView(
        sky=sky_image,
        to_sun=look.to_sun,
        sun_rgb=_rgb(np.asarray(look.sun_rgb) / sun_peak if sun_peak > 0 else (0.0, 0.0, 0.0)),
        # Three.js light intensities: the renderer's colours peak near 0.7 (sun) and 0.35
        # (ambient) at noon; these gains give a browser noon of similar brightness.
        sun_intensity=3.0 * sun_peak * look.exposure,
        ambient_rgb=_rgb(np.asarray(look.ambient_rgb) / ambient_peak if ambient_peak > 0 else (1.0, 1.0, 1.0)),
        ambient_intensity=3.0 * ambient_peak * look.exposure,
        fog_near=far * FOG_START_SHARE,
        fog_far=far,
        fog_rgb=_rgb(look.fog_rgb),
        caption=caption,
    )


def sun_position(to_sun: tuple[float, float, float], distance: float) -> tuple[float, float, float]:
    """Where to put a directional light `distance` metres towards the sun (it shines at the origin)."""
    norm = math.sqrt(sum(c * c for c in to_sun)) or 1.0
    x, y, z = (c / norm * distance for c in to_sun)
    return (x, y, z)
