"""What lies under a point of a world: a building, a lane, paving, a sidewalk or plain ground.

Workers use these queries for their placement rules ("a car goes on something drivable",
"nothing inside a building") and for positions relative to lanes and sidewalks. The queries
about a scene look only at the parts its spatial index (`drivetwin.worlds.surface_index`)
finds near the point, and answer exactly as a scan of every part would.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

from drivetwin.worlds.scene import Lane, Scene
from drivetwin.worlds.surface_index import surface_index

Point = tuple[float, float]
SurfaceKind = Literal["building", "lane", "crossing", "paved", "sidewalk", "ground"]


def point_in_polygon(x: float, y: float, polygon: Sequence[Point]) -> bool:
    """Even-odd rule; points on an edge may fall either way."""
    inside = False
    n = len(polygon)
    for i in range(n):
        x1, y1 = polygon[i]
        x2, y2 = polygon[(i + 1) % n]
        if (y1 > y) != (y2 > y):
            x_cross = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
            if x < x_cross:
                inside = not inside
    return inside


@dataclass(frozen=True)
class PolylinePoint:
    """The point of a polyline nearest to a query point."""

    x: float
    y: float
    distance: float  # from the query point, metres
    heading: float  # of the segment there, radians
    arc_length: float  # from the polyline's start, metres
    # Which side of the polyline the query point lies on: +1 left, -1 right (facing along it).
    side: int


def nearest_on_polyline(x: float, y: float, polyline: Sequence[Point]) -> PolylinePoint:
    """The point of `polyline` nearest to (x, y)."""
    best: PolylinePoint | None = None
    travelled = 0.0
    for (x1, y1), (x2, y2) in itertools.pairwise(polyline):
        dx, dy = x2 - x1, y2 - y1
        seg = math.hypot(dx, dy)
        if seg == 0.0:
            continue
        t = max(0.0, min(1.0, ((x - x1) * dx + (y - y1) * dy) / (seg * seg)))
        px, py = x1 + t * dx, y1 + t * dy
        dist = math.hypot(x - px, y - py)
        if best is None or dist < best.distance:
            cross = dx * (y - y1) - dy * (x - x1)
            best = PolylinePoint(
                px, py, dist, math.atan2(dy, dx), travelled + t * seg, 1 if cross >= 0 else -1
            )
        travelled += seg
    if best is None:
        raise ValueError("a polyline needs two distinct points")
    return best


def polyline_length(polyline: Sequence[Point]) -> float:
    return sum(
        math.hypot(x2 - x1, y2 - y1) for (x1, y1), (x2, y2) in itertools.pairwise(polyline)
    )


def point_along(polyline: Sequence[Point], arc_length: float) -> tuple[float, float, float]:
    """(x, y, heading) at `arc_length` metres along the polyline, clamped to its ends."""
    remaining = max(0.0, arc_length)
    last_heading = 0.0
    for (x1, y1), (x2, y2) in itertools.pairwise(polyline):
        seg = math.hypot(x2 - x1, y2 - y1)
        if seg == 0.0:
            continue
        last_heading = math.atan2(y2 - y1, x2 - x1)
        if remaining <= seg:
            t = remaining / seg
            return (x1 + t * (x2 - x1), y1 + t * (y2 - y1), last_heading)
        remaining -= seg
    x_end, y_end = polyline[-1]
    return (x_end, y_end, last_heading)


def _on_strip(x: float, y: float, polyline: Sequence[Point], half_width: float) -> bool:
    return nearest_on_polyline(x, y, polyline).distance <= half_width


class SceneSurface:
    """The surface queries of one scene, its spatial index looked up once: for a batch of
    queries (a search over many candidate points) while the scene's geometry stays as it
    is. The module's functions answer one query each with a fresh one."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self.index = surface_index(scene)

    def lane_at(self, x: float, y: float) -> Lane | None:
        """The lane whose strip contains (x, y), the nearest centreline winning."""
        lanes = self.scene.roads.lanes
        best: tuple[float, Lane] | None = None
        for k in self.index.lanes.near(x, y):
            lane = lanes[k]
            near = nearest_on_polyline(x, y, lane.centreline)
            if near.distance <= lane.width / 2 and (best is None or near.distance < best[0]):
                best = (near.distance, lane)
        return best[1] if best else None

    def nearest_lane(self, x: float, y: float) -> Lane | None:
        """The lane whose centreline passes nearest to (x, y) (the first in scene order on a tie)."""
        lanes = self.scene.roads.lanes
        if not lanes:
            return None
        # Lanes in order of their boxes' distance; a box nearer than the best lane so far may
        # hold a nearer lane, a box further away cannot.
        bounds = self.index.lane_lines.box_distances(x, y)
        best: tuple[float, int] | None = None
        for k in (int(i) for i in bounds.argsort(kind="stable")):
            if best is not None and bounds[k] > best[0]:
                break
            distance = nearest_on_polyline(x, y, lanes[k].centreline).distance
            if best is None or (distance, k) < best:
                best = (distance, k)
        assert best is not None
        return lanes[best[1]]

    def road_height(self, x: float, y: float) -> float:
        """Height (m) of the road surface at (x, y): the elevation of the lane there,
        interpolated along it; 0 off lanes and on flat ones (the ground plane's height)."""
        lane = self.lane_at(x, y)
        if lane is None or lane.elevation is None:
            return 0.0
        along = nearest_on_polyline(x, y, lane.centreline).arc_length
        travelled = 0.0
        for (x1, y1), (x2, y2), z1, z2 in zip(lane.centreline, lane.centreline[1:], lane.elevation,
                                              lane.elevation[1:], strict=False):
            seg = math.hypot(x2 - x1, y2 - y1)
            if along <= travelled + seg and seg > 0.0:
                return z1 + (z2 - z1) * (along - travelled) / seg
            travelled += seg
        return lane.elevation[-1]

    def building_at(self, x: float, y: float, margin: float = 0.0) -> str | None:
        """The name of the building whose footprint (grown by `margin`) contains (x, y)."""
        buildings = self.scene.buildings
        for k in self.index.buildings.near(x, y, max(margin, 0.0)):
            building = buildings[k]
            if point_in_polygon(x, y, building.footprint):
                return building.name
            if margin > 0.0:
                ring = [*building.footprint, building.footprint[0]]
                if nearest_on_polyline(x, y, ring).distance < margin:
                    return building.name
        return None

    def surface_at(self, x: float, y: float) -> SurfaceKind:
        """What the ground at (x, y) is, the most restrictive kind winning."""
        index, roads = self.index, self.scene.roads
        if self.building_at(x, y):
            return "building"
        for k in index.crossings.near(x, y):
            crossing = roads.crossings[k]
            if _on_strip(x, y, [crossing.start, crossing.end], crossing.width / 2):
                return "crossing"
        if self.lane_at(x, y) is not None:
            return "lane"
        if any(point_in_polygon(x, y, roads.paved[k].polygon) for k in index.paved.near(x, y)):
            return "paved"
        if any(_on_strip(x, y, roads.sidewalks[k].polyline, roads.sidewalks[k].width / 2)
               for k in index.sidewalks.near(x, y)):
            return "sidewalk"
        return "ground"


def lane_at(scene: Scene, x: float, y: float) -> Lane | None:
    """The lane whose strip contains (x, y), the nearest centreline winning."""
    return SceneSurface(scene).lane_at(x, y)


def nearest_lane(scene: Scene, x: float, y: float) -> Lane | None:
    """The lane whose centreline passes nearest to (x, y) (the first in scene order on a tie)."""
    return SceneSurface(scene).nearest_lane(x, y)


def road_height(scene: Scene, x: float, y: float) -> float:
    """Height (m) of the road surface at (x, y); 0 off lanes and on flat ones."""
    return SceneSurface(scene).road_height(x, y)


def building_at(scene: Scene, x: float, y: float, margin: float = 0.0) -> str | None:
    """The name of the building whose footprint (grown by `margin`) contains (x, y)."""
    return SceneSurface(scene).building_at(x, y, margin)


def surface_at(scene: Scene, x: float, y: float) -> SurfaceKind:
    """What the ground at (x, y) is, the most restrictive kind winning."""
    return SceneSurface(scene).surface_at(x, y)


DRIVABLE: frozenset[SurfaceKind] = frozenset({"lane", "crossing", "paved"})
