"""Road marks of any world, derived from its lanes: solid white edge lines where a lane has
no neighbour, dashed white dividers between lanes of one direction, a solid yellow centre
line between opposing lanes. Nothing is painted inside junctions (intersection paving).

The MuJoCo world draws each mark as a thin ribbon mesh (`drivetwin.worlds.mujoco_static`),
so the mesh pass of the hybrid renderer shows them in every frame.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np
import shapely
from drivetwin.worlds.scene import Lane, Scene
from drivetwin.worlds.surface import SceneSurface, nearest_on_polyline, point_along, polyline_length
from shapely import Polygon
from shapely.geometry.base import BaseGeometry

__all__ = ["CENTRE_RGBA", "EDGE_RGBA", "RoadMark", "road_marks"]

MarkKind = Literal["edge", "divider", "centre"]
Point3 = tuple[float, float, float]

EDGE_RGBA = (0.95, 0.95, 0.95, 1.0)
CENTRE_RGBA = (0.95, 0.75, 0.1, 1.0)
LINE_HALF_WIDTH_M = 0.06
# Dividers: 3 m of paint, 6 m of gap (the short urban pattern of most national rules).
DASH_M, GAP_M = 3.0, 6.0
# How far past a lane's edge to look for a neighbouring lane: further than rounding between
# two lanes' shared edge, nearer than the far side of a neighbour 2.5 m wide.
PROBE_M = 0.5
# Fractions of a lane's length where its neighbours are looked for (the first outside a
# junction counts): a lane through a crossroads has its middle inside it.
PROBE_STATIONS = (0.5, 0.25, 0.75, 0.1, 0.9)
# Marks are cut at junction edges to within this, metres.
SAMPLE_M = 0.5
# Headings closer than this (cosine) count as one direction of travel.
SAME_DIRECTION_COS = 0.0


@dataclass(frozen=True)
class RoadMark:
    """One painted line: pieces of polyline (x, y, road height) to paint, each >= 2 points."""

    id: str
    kind: MarkKind
    pieces: list[list[Point3]]
    half_width: float
    rgba: tuple[float, float, float, float]


def road_marks(scene: Scene) -> list[RoadMark]:
    """The marks of every lane, each shared edge painted once, none inside junctions."""
    junctions = shapely.union_all([Polygon(area.polygon) for area in scene.roads.paved
                                   if area.kind == "intersection"])
    shapely.prepare(junctions)
    surface = SceneSurface(scene)
    marks: list[RoadMark] = []
    for lane in scene.roads.lanes:
        length = polyline_length(lane.centreline)
        # Where the lane's neighbours are looked at: the first station outside a junction.
        stations = [point_along(lane.centreline, length * f) for f in PROBE_STATIONS]
        outside = [p for p in stations if not shapely.contains_xy(junctions, p[0], p[1])]
        if not outside:
            continue  # a connecting lane within a junction
        for side in (1, -1):  # left, right
            kind = _edge_kind(surface, lane, side, outside[0])
            if kind is None:
                continue
            edge = _outside(junctions, _densified(_offset(lane, side * lane.width / 2)))
            pieces = [d for piece in edge for d in _dashes(piece)] if kind == "divider" else edge
            if pieces:
                marks.append(RoadMark(f"{lane.id}/{'left' if side > 0 else 'right'}", kind, pieces,
                                      LINE_HALF_WIDTH_M, CENTRE_RGBA if kind == "centre" else EDGE_RGBA))
    return marks


def _densified(line: Sequence[Point3]) -> list[Point3]:
    """`line` with a point at least every SAMPLE_M metres, so junction edges cut it finely."""
    out = [line[0]]
    for a, b in itertools.pairwise(line):
        steps = max(1, math.ceil(math.hypot(b[0] - a[0], b[1] - a[1]) / SAMPLE_M))
        out.extend(_lerp(a, b, k / steps) for k in range(1, steps + 1))
    return out


def _outside(junctions: BaseGeometry, line: Sequence[Point3]) -> list[list[Point3]]:
    """The stretches of `line` outside the junctions (each at least two points)."""
    points = np.asarray(line, dtype=float)
    inside = shapely.contains_xy(junctions, points[:, 0], points[:, 1])
    pieces: list[list[Point3]] = [[]]
    for point, covered in zip(line, inside, strict=True):
        if covered:
            if pieces[-1]:
                pieces.append([])
        else:
            pieces[-1].append(point)
    return [piece for piece in pieces if len(piece) >= 2]


def _edge_kind(surface: SceneSurface, lane: Lane, side: int, station: tuple[float, float, float]) -> MarkKind | None:
    """What this lane paints on its left (+1) or right (-1) edge, judged at `station`; None
    where the neighbouring lane paints the shared line."""
    x, y, heading = station
    reach = lane.width / 2 + PROBE_M
    probe = (x - side * reach * math.sin(heading), y + side * reach * math.cos(heading))
    neighbour = surface.lane_at(*probe)
    if neighbour is None or neighbour.id == lane.id:
        return "edge"
    theirs = nearest_on_polyline(*probe, neighbour.centreline).heading
    if math.cos(theirs - heading) > SAME_DIRECTION_COS:
        return "divider" if side < 0 else None  # the left lane paints it on its right
    return "centre" if lane.id < neighbour.id else None


def _offset(lane: Lane, offset: float) -> list[Point3]:
    """The lane's centreline moved `offset` metres to its left, with the road's heights."""
    points = lane.centreline
    heights = lane.elevation or [0.0] * len(points)
    out: list[Point3] = []
    for k, (x, y) in enumerate(points):
        before, after = points[max(k - 1, 0)], points[min(k + 1, len(points) - 1)]
        dx, dy = after[0] - before[0], after[1] - before[1]
        norm = math.hypot(dx, dy) or 1.0
        out.append((x - offset * dy / norm, y + offset * dx / norm, heights[k]))
    return out


def _dashes(line: Sequence[Point3]) -> list[list[Point3]]:
    """The painted stretches of a dashed line along `line`."""
    pieces: list[list[Point3]] = []
    piece: list[Point3] = []
    travelled = 0.0
    pitch = DASH_M + GAP_M
    for a, b in itertools.pairwise(line):
        seg = math.hypot(b[0] - a[0], b[1] - a[1])
        if seg == 0.0:
            continue
        cuts = [0.0]
        # Dash boundaries within this segment, as distances from its start.
        start = travelled
        boundary = math.floor(start / pitch) * pitch
        while boundary < start + seg:
            for edge in (boundary, boundary + DASH_M):
                if start < edge < start + seg:
                    cuts.append(edge - start)
            boundary += pitch
        cuts.append(seg)
        for t0, t1 in itertools.pairwise(cuts):
            if t1 <= t0:
                continue
            painted = ((start + (t0 + t1) / 2) % pitch) < DASH_M
            p0, p1 = _lerp(a, b, t0 / seg), _lerp(a, b, t1 / seg)
            if painted:
                if not piece:
                    piece = [p0]
                piece.append(p1)
            elif piece:
                pieces.append(piece)
                piece = []
        travelled += seg
    if len(piece) >= 2:
        pieces.append(piece)
    return pieces


def _lerp(a: Point3, b: Point3, t: float) -> Point3:
    return (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]))
