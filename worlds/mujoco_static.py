"""The static part of a MuJoCo world: ground, buildings, road paint, lights and the view camera.

Buildings collide; a world package's terrain (Scene.package) collides as a height field; roads, sidewalks, crossings and paved areas are thin visual-only geoms
(contype = conaffinity = 0) so a mesh render shows the road layout while vehicles roll on
the ground plane. A lane with elevation (imported road maps) is a colliding deck instead: a
slab per centreline segment, tilted so its top follows the road's height, that vehicles
drive on. Every static geom's name starts with one of STATIC_PREFIXES so an update
can remove and rebuild them without touching asset bodies.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

import mujoco
import numpy as np
from drivetwin.worlds.heightfield import Heightfield, add_collision_geoms, load_heightfield
from drivetwin.worlds.packages import HEIGHTFIELD_FILE
from drivetwin.worlds.road_marks import road_marks
from drivetwin.worlds.rotation import look_at_quat, yaw_pitch_quat, yaw_quat
from drivetwin.worlds.scene import Building, Scene

__all__ = [
    "OFFSCREEN_HEIGHT",
    "OFFSCREEN_WIDTH",
    "STATIC_PREFIXES",
    "TERRAIN_PREFIX",
    "VIEW_CAMERA",
    "add_static_geoms",
    "configure_spec",
    "static_signature",
]

VIEW_CAMERA = "drivetwin_view"
OFFSCREEN_WIDTH = 1920
OFFSCREEN_HEIGHT = 1080
STATIC_PREFIXES = ("ground", "terrain/", "building/", "lane/", "sidewalk/", "crossing/", "paved/")
# Name prefix of a world package's terrain: its height field geom is "terrain/ground".
TERRAIN_PREFIX = "terrain"
# Ground plane reaches this far past the scene bounds so the horizon is not a cliff edge.
GROUND_MARGIN_M = 50.0
# Visual layers stacked a few millimetres apart so they do not z-fight; tops in metres.
PAVED_TOP_M = 0.003
LANE_TOP_M = 0.004
LINE_TOP_M = 0.005
CROSSING_TOP_M = 0.006
SIDEWALK_TOP_M = 0.008
# Half thickness of an elevated lane's deck slab: thick enough that a wheel never tunnels
# through it at a 2 ms step, thin enough to stay under the road beside a junction.
DECK_HALF_THICKNESS_M = 0.15
ZEBRA_STRIPE_HALF_M = 0.25
ZEBRA_PITCH_M = 1.0
# Near clip 5 cm (close-up views of cones); far clip twice the scene diagonal.
NEAR_CLIP_M = 0.05
FAR_CLIP_DIAGONALS = 2.0
RIGHT_ANGLE_TOLERANCE = 1e-6

ASPHALT = (0.22, 0.22, 0.24, 1.0)
PAVING = (0.3, 0.3, 0.32, 1.0)
PAINT = (0.95, 0.95, 0.95, 1.0)
CONCRETE = (0.68, 0.68, 0.65, 1.0)

_VISUAL_ONLY = {"contype": 0, "conaffinity": 0, "group": 1}


def static_signature(scene: Scene) -> tuple[object, ...]:
    """The scene parts the static geoms are built from; equal signatures need no rebuild."""
    return (scene.bounds, scene.ground, scene.roads, tuple(scene.buildings), scene.package)


def configure_spec(spec: mujoco.MjSpec, scene: Scene) -> None:
    """Options and visuals that do not depend on edits: buffer, clip, lights, view camera."""
    bounds = scene.bounds
    diagonal = math.hypot(bounds.xmax - bounds.xmin, bounds.ymax - bounds.ymin)
    spec.stat.extent = diagonal
    spec.stat.center = [*bounds.centre, 0.0]
    spec.visual.global_.offwidth = OFFSCREEN_WIDTH
    spec.visual.global_.offheight = OFFSCREEN_HEIGHT
    spec.visual.map.znear = NEAR_CLIP_M / diagonal
    spec.visual.map.zfar = FAR_CLIP_DIAGONALS
    spec.visual.headlight.ambient = [0.25, 0.25, 0.25]
    spec.visual.headlight.diffuse = [0.35, 0.35, 0.35]
    spec.worldbody.add_light(
        name="sun",
        type=mujoco.mjtLightType.mjLIGHT_DIRECTIONAL,
        pos=[*bounds.centre, 100.0],
        dir=[0.3, 0.2, -1.0],
        diffuse=[0.7, 0.7, 0.68],
        castshadow=True,
    )
    ego = scene.ego.pose
    heading = (math.cos(ego.yaw), math.sin(ego.yaw))
    eye = (ego.x - 8.0 * heading[0], ego.y - 8.0 * heading[1], 4.0)
    target = (ego.x + 10.0 * heading[0], ego.y + 10.0 * heading[1], 0.5)
    spec.worldbody.add_camera(name=VIEW_CAMERA, pos=list(eye), quat=look_at_quat(eye, target), fovy=60.0)


def add_static_geoms(spec: mujoco.MjSpec, scene: Scene) -> None:
    """Add the ground, buildings and road paint of `scene` to the world body."""
    world = spec.worldbody
    bounds = scene.bounds
    terrain = _terrain_of(scene)
    half = (
        (bounds.xmax - bounds.xmin) / 2 + GROUND_MARGIN_M,
        (bounds.ymax - bounds.ymin) / 2 + GROUND_MARGIN_M,
    )
    world.add_geom(
        name="ground",
        type=mujoco.mjtGeom.mjGEOM_PLANE,
        # The plane continues the terrain past its edges and never covers its low parts.
        pos=[*bounds.centre, 0.0 if terrain is None else min(0.0, float(terrain.origin[2]))],
        size=[half[0], half[1], 1.0],
        rgba=list(scene.ground.rgba),
        friction=[scene.ground.friction, 0.005, 0.0001],
        # The ground's friction governs every contact with it (tyres on ice slip).
        priority=1,
    )
    if terrain is not None:
        _add_terrain(spec, terrain, scene)
    for building in scene.buildings:
        _add_building(spec, building)
    roads = scene.roads
    for paved in roads.paved:
        _add_prism(spec, f"paved/{paved.id}", paved.polygon, 0.0, PAVED_TOP_M, PAVING, _VISUAL_ONLY)
    for lane in roads.lanes:
        if lane.elevation is None:
            line = [(x, y, 0.0) for x, y in lane.centreline]
            _add_ribbon(spec, f"lane/{lane.id}/surface", [line], lane.width / 2, LANE_TOP_M, ASPHALT)
            continue
        for k, (a, b) in enumerate(zip(lane.centreline, lane.centreline[1:], strict=False)):
            _add_deck(world, f"lane/{lane.id}/{k}", a, b, (lane.elevation[k], lane.elevation[k + 1]),
                      lane.width / 2, scene)
    for mark in road_marks(scene):
        _add_ribbon(spec, f"lane/{mark.id}", mark.pieces, mark.half_width, LINE_TOP_M, mark.rgba)
    for walk in roads.sidewalks:
        line = [(x, y, 0.0) for x, y in walk.polyline]
        _add_ribbon(spec, f"sidewalk/{walk.id}", [line], walk.width / 2, SIDEWALK_TOP_M, CONCRETE)
    for crossing in roads.crossings:
        _add_zebra(world, crossing.id, crossing.start, crossing.end, crossing.width)


def _terrain_of(scene: Scene) -> Heightfield | None:
    """The height field of the scene's world package, None without one."""
    if scene.package is None:
        return None
    path = Path(scene.package) / HEIGHTFIELD_FILE
    return load_heightfield(path) if path.is_file() else None


def _add_terrain(spec: mujoco.MjSpec, terrain: Heightfield, scene: Scene) -> None:
    """The terrain height field, colliding like the ground plane (same colour and friction)."""
    (geom,) = add_collision_geoms(spec, heightfield=terrain, prefix=TERRAIN_PREFIX)
    geom.rgba = list(scene.ground.rgba)
    geom.friction = [scene.ground.friction, 0.005, 0.0001]
    geom.priority = 1


def _segment_frame(
    a: Sequence[float], b: Sequence[float], rise: tuple[float, float]
) -> tuple[float, float, float, float, list[float]] | None:
    """(half length along the slope, left normal x, y, mid height, quaternion) of a→b, or None."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    flat = math.hypot(dx, dy)
    if flat <= 0.0:
        return None
    dz = rise[1] - rise[0]
    yaw, pitch = math.atan2(dy, dx), -math.atan2(dz, flat)  # MuJoCo's +y rotation tips +x down
    quat = list(yaw_pitch_quat(yaw, pitch))
    return math.hypot(flat, dz) / 2, -dy / flat, dx / flat, (rise[0] + rise[1]) / 2, quat


def _strip(
    world: mujoco.MjsBody,
    name: str,
    a: Sequence[float],
    b: Sequence[float],
    half_width: float,
    top: float,
    rgba: Sequence[float],
    offset: float = 0.0,
    rise: tuple[float, float] = (0.0, 0.0),
) -> None:
    """A thin visual box from a to b, `offset` metres to the left of the a→b line, its top
    `top` metres over a surface rising from rise[0] at a to rise[1] at b."""
    frame = _segment_frame(a, b, rise)
    if frame is None:
        return
    half_length, nx, ny, mid, quat = frame
    world.add_geom(
        name=name,
        type=mujoco.mjtGeom.mjGEOM_BOX,
        pos=[(a[0] + b[0]) / 2 + nx * offset, (a[1] + b[1]) / 2 + ny * offset, mid + top / 2],
        quat=quat,
        size=[half_length, half_width, top / 2],
        rgba=list(rgba),
        **_VISUAL_ONLY,
    )


def _add_deck(
    world: mujoco.MjsBody,
    name: str,
    a: Sequence[float],
    b: Sequence[float],
    rise: tuple[float, float],
    half_width: float,
    scene: Scene,
) -> None:
    """A colliding asphalt slab under one segment of an elevated lane, its top on the road."""
    frame = _segment_frame(a, b, rise)
    if frame is None:
        return
    half_length, _, _, mid, quat = frame
    world.add_geom(
        name=name,
        type=mujoco.mjtGeom.mjGEOM_BOX,
        pos=[(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, mid + LANE_TOP_M - DECK_HALF_THICKNESS_M],
        quat=quat,
        size=[half_length, half_width, DECK_HALF_THICKNESS_M],
        rgba=list(ASPHALT),
        # Like the ground: its friction governs every contact (tyres on ice slip on decks too).
        friction=[scene.ground.friction, 0.005, 0.0001],
        priority=1,
    )


def _add_ribbon(
    spec: mujoco.MjSpec,
    name: str,
    pieces: Sequence[Sequence[tuple[float, float, float]]],
    half_width: float,
    top: float,
    rgba: Sequence[float],
) -> None:
    """A visual-only ribbon mesh `2 * half_width` wide along each piece, `top` metres over its
    heights: one geom per lane or mark (per-segment boxes made a 2000-lane town 50,000 geoms)."""
    vertices: list[float] = []
    faces: list[int] = []
    for piece in pieces:
        base = len(vertices) // 3
        count = 0
        for k, (x, y, z) in enumerate(piece):
            before, after = piece[max(k - 1, 0)], piece[min(k + 1, len(piece) - 1)]
            dx, dy = after[0] - before[0], after[1] - before[1]
            norm = math.hypot(dx, dy)
            if norm == 0.0:
                continue
            nx, ny = -dy / norm * half_width, dx / norm * half_width
            vertices.extend((x - nx, y - ny, z + top, x + nx, y + ny, z + top))  # right, left
            count += 1
        for k in range(count - 1):
            r0, l0, r1, l1 = base + 2 * k, base + 2 * k + 1, base + 2 * k + 2, base + 2 * k + 3
            faces.extend((r0, r1, l1, r0, l1, l0))  # counter-clockwise from above: faces up
    if not faces:
        return
    mesh = spec.add_mesh(name=name, uservert=vertices, userface=faces)
    # A ribbon has no volume; its (unused: static, visual-only) inertia is a shell's.
    mesh.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL
    spec.worldbody.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_MESH, meshname=name, rgba=list(rgba),
                            **_VISUAL_ONLY)


def _add_zebra(
    world: mujoco.MjsBody,
    crossing_id: str,
    start: Sequence[float],
    end: Sequence[float],
    width: float,
) -> None:
    dx, dy = end[0] - start[0], end[1] - start[1]
    length = math.hypot(dx, dy)
    if length <= 0.0:
        return
    ux, uy = dx / length, dy / length
    count = max(1, int(length / ZEBRA_PITCH_M))
    for k in range(count):
        along = (k + 0.5) * length / count
        centre = (start[0] + ux * along, start[1] + uy * along)
        a = (centre[0] - ux * ZEBRA_STRIPE_HALF_M, centre[1] - uy * ZEBRA_STRIPE_HALF_M)
        b = (centre[0] + ux * ZEBRA_STRIPE_HALF_M, centre[1] + uy * ZEBRA_STRIPE_HALF_M)
        _strip(world, f"crossing/{crossing_id}/{k}", a, b, width / 2, CROSSING_TOP_M, PAINT)


def _rectangle(
    footprint: Sequence[Sequence[float]],
) -> tuple[float, float, float, float, float] | None:
    """(cx, cy, yaw, half_length, half_width) when the footprint is a rectangle, else None."""
    points = [tuple(p) for p in footprint]
    if len(points) == 5 and points[0] == points[-1]:
        points = points[:-1]
    if len(points) != 4:
        return None
    edges = [np.subtract(points[(i + 1) % 4], points[i]) for i in range(4)]
    lengths = [float(np.linalg.norm(e)) for e in edges]
    if min(lengths) <= 0.0:
        return None
    for i in range(4):
        cosine = float(np.dot(edges[i], edges[(i + 1) % 4])) / (lengths[i] * lengths[(i + 1) % 4])
        if abs(cosine) > RIGHT_ANGLE_TOLERANCE:
            return None
    cx, cy = np.mean(points, axis=0)
    yaw = math.atan2(edges[0][1], edges[0][0])
    return float(cx), float(cy), yaw, lengths[0] / 2, lengths[1] / 2


def _add_building(spec: mujoco.MjSpec, building: Building) -> None:
    rgba = list(building.rgba)
    box = _rectangle(building.footprint)
    if box is None:
        # Collision meshes are convex hulls: a concave footprint collides as its hull.
        _add_prism(spec, f"building/{building.id}", building.footprint, 0.0, building.height, rgba, {})
        return
    cx, cy, yaw, half_length, half_width = box
    spec.worldbody.add_geom(
        name=f"building/{building.id}",
        type=mujoco.mjtGeom.mjGEOM_BOX,
        pos=[cx, cy, building.height / 2],
        quat=list(yaw_quat(yaw)),
        size=[half_length, half_width, building.height / 2],
        rgba=rgba,
    )


def _add_prism(
    spec: mujoco.MjSpec,
    name: str,
    polygon: Sequence[Sequence[float]],
    bottom: float,
    top: float,
    rgba: Sequence[float],
    flags: dict[str, int],
) -> None:
    """A vertical prism over `polygon` as a mesh geom (MuJoCo uses its convex hull)."""
    vertices: list[float] = []
    for z in (bottom, top):
        for x, y in polygon:
            vertices.extend((x, y, z))
    spec.add_mesh(name=name, uservert=vertices)
    spec.worldbody.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_MESH, meshname=name, rgba=list(rgba), **flags)
