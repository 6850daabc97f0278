"""A spatial index of a Scene's static ground: which lanes, sidewalks, crossings, paved areas
and buildings could be at or near a point, without scanning all of them.

The index is derived from the Scene and never edited: `surface_index(scene)` builds it from
the scene's geometry and keeps it while that geometry is unchanged (compared by value, so a
copy of a scene finds the index of the original and an edited road gets a fresh one). It only
narrows the candidates (bounding boxes in an STRtree); `drivetwin.worlds.surface` decides
each query with the same exact test as a scan of every part would, in the Scene's order.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from operator import attrgetter

import numpy as np
from drivetwin.worlds.scene import Scene
from shapely import STRtree, box

__all__ = ["BoxIndex", "SurfaceIndex", "surface_index"]

Point = tuple[float, float]
# Boxes grow by this much more than the parts' half widths, metres: the exact tests compute
# distances with their own rounding, and a candidate too many costs nothing.
SLACK_M = 1e-6
# Scenes whose indexes are kept at once: a session's live scene and the copies Workers get
# share one entry, so a handful covers undo, redo and an eval run's worlds.
CACHED_SCENES = 8


class BoxIndex:
    """Bounding boxes of a list of parts, queried by point or by disc; answers are indices
    into that list in ascending order (the Scene's order)."""

    def __init__(self, boxes: Sequence[tuple[float, float, float, float]]) -> None:
        self._bounds = np.asarray(boxes, dtype=float).reshape(-1, 4)
        self._tree = STRtree([box(*b) for b in boxes]) if boxes else None

    def __len__(self) -> int:
        return len(self._bounds)

    def near(self, x: float, y: float, radius: float = 0.0) -> list[int]:
        """Parts whose box comes within `radius` metres (per axis) of (x, y)."""
        if self._tree is None:
            return []
        r = radius + SLACK_M
        hits = self._tree.query(box(x - r, y - r, x + r, y + r))
        return sorted(int(i) for i in hits)

    def box_distances(self, x: float, y: float) -> np.ndarray:
        """Distance from (x, y) to every part's box (0 inside): a lower bound of the distance
        to the part itself, for nearest-part searches."""
        lo, hi = self._bounds[:, :2], self._bounds[:, 2:]
        gap = np.maximum(np.maximum(lo - (x, y), (x, y) - hi), 0.0)
        result: np.ndarray = np.hypot(gap[:, 0], gap[:, 1])
        return result


def _bbox(points: Sequence[Point], grow: float) -> tuple[float, float, float, float]:
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return (min(xs) - grow, min(ys) - grow, max(xs) + grow, max(ys) + grow)


@dataclass(frozen=True)
class SurfaceIndex:
    """Boxes of a Scene's parts, each list in the Scene's order; strips grown by half their width."""

    lanes: BoxIndex
    lane_lines: BoxIndex  # centrelines alone, for nearest-lane searches
    sidewalks: BoxIndex
    crossings: BoxIndex
    paved: BoxIndex
    buildings: BoxIndex


def _build(scene: Scene) -> SurfaceIndex:
    roads = scene.roads
    return SurfaceIndex(
        lanes=BoxIndex([_bbox(lane.centreline, lane.width / 2) for lane in roads.lanes]),
        lane_lines=BoxIndex([_bbox(lane.centreline, 0.0) for lane in roads.lanes]),
        sidewalks=BoxIndex([_bbox(walk.polyline, walk.width / 2) for walk in roads.sidewalks]),
        crossings=BoxIndex([_bbox([c.start, c.end], c.width / 2) for c in roads.crossings]),
        paved=BoxIndex([_bbox(area.polygon, 0.0) for area in roads.paved]),
        buildings=BoxIndex([_bbox(b.footprint, 0.0) for b in scene.buildings]),
    )


# What each part's index entry is built from; attrgetter keeps the per-query check in C.
_LANE = attrgetter("centreline", "width")
_WALK = attrgetter("polyline", "width")
_CROSSING = attrgetter("start", "end", "width")
_PAVED = attrgetter("polygon")
_BUILDING = attrgetter("footprint")


def _geometry(scene: Scene) -> tuple[object, ...]:
    """What the index is built from, by reference: equal to a snapshot while nothing changed."""
    roads = scene.roads
    return (list(map(_LANE, roads.lanes)), list(map(_WALK, roads.sidewalks)),
            list(map(_CROSSING, roads.crossings)), list(map(_PAVED, roads.paved)),
            list(map(_BUILDING, scene.buildings)))


def _snapshot(scene: Scene) -> tuple[object, ...]:
    """The same as `_geometry` with every list copied, so later edits cannot reach it."""
    roads = scene.roads
    return ([(list(line), width) for line, width in map(_LANE, roads.lanes)],
            [(list(line), width) for line, width in map(_WALK, roads.sidewalks)],
            list(map(_CROSSING, roads.crossings)),
            [list(polygon) for polygon in map(_PAVED, roads.paved)],
            [list(footprint) for footprint in map(_BUILDING, scene.buildings)])


_cache: list[tuple[tuple[object, ...], SurfaceIndex]] = []


def surface_index(scene: Scene) -> SurfaceIndex:
    """The index of `scene`'s current geometry (built once per distinct geometry)."""
    live = _geometry(scene)
    for k, (snapshot, index) in enumerate(_cache):
        # Tuple and list equality compare element identity first: a few ms on 2000 lanes.
        if snapshot == live:
            _cache.insert(0, _cache.pop(k))
            return index
    index = _build(scene)
    _cache.insert(0, (_snapshot(scene), index))
    del _cache[CACHED_SCENES:]
    return index
