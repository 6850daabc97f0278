"""Asset footprints on the ground and a grid index over them, for the placement rules.

A footprint is an asset's rectangle (category length × width, scaled, turned by its yaw);
two footprints overlap by the separating-axis test. `FootprintIndex` answers "which assets
could overlap this one" from a uniform grid instead of a scan over every asset. It is derived
from the assets it is given (never a second truth): `sync` patches it by object identity, so
the next scene of an edit (which shares every unchanged AssetInstance) costs a dict pass and
the few changed assets, not a rebuild. `_reference_overlaps` is the plain scan the index must
agree with (tested on random scenes).
"""

from __future__ import annotations

import math
import threading
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from operator import attrgetter

from drivetwin.worlds.catalog import Category, category
from drivetwin.worlds.scene import AssetInstance, Pose

__all__ = [
    "NON_COLLIDING_MOTION",
    "OVERLAP_TOLERANCE_M",
    "Footprint",
    "FootprintIndex",
    "footprint_of",
    "near",
    "overlap",
    "overlapping",
]

# Footprints may touch: cones in a tight ring or cars in adjacent bays are fine.
OVERLAP_TOLERANCE_M = 0.05
# Grid cell edge: about the footprint of a car, so a query reads a handful of cells and a
# cell holds a handful of props (a bus spans a few cells).
CELL_M = 4.0
# Walkers and riders are kinematic and step around furniture; they never block a placement.
NON_COLLIDING_MOTION = frozenset({"walker"})

Cell = tuple[int, int]
_POSE = attrgetter("pose")
_SCALE = attrgetter("scale")


@dataclass(frozen=True)
class Footprint:
    """An asset's footprint: its four corners (world metres) and a bounding circle."""

    asset: AssetInstance
    corners: tuple[tuple[float, float], ...]
    x: float
    y: float
    radius: float
    collides: bool
    # What the footprint was computed from: an asset changed in place no longer matches.
    pose: Pose
    scale: float


def footprint_of(asset: AssetInstance, cat: Category | None = None) -> Footprint:
    """The footprint of `asset` (its category's rectangle, scaled and turned)."""
    cat = cat or category(asset.category)
    hl, hw = cat.length * asset.scale / 2, cat.width * asset.scale / 2
    c, s = math.cos(asset.pose.yaw), math.sin(asset.pose.yaw)
    x, y = asset.pose.x, asset.pose.y
    corners = tuple(
        (x + c * dx - s * dy, y + s * dx + c * dy) for dx, dy in ((hl, hw), (-hl, hw), (-hl, -hw), (hl, -hw))
    )
    radius = cat.footprint_radius * asset.scale
    return Footprint(asset, corners, x, y, radius, cat.motion not in NON_COLLIDING_MOTION, asset.pose, asset.scale)


def overlap(a: Footprint, b: Footprint, tolerance: float = OVERLAP_TOLERANCE_M) -> bool:
    """Separating-axis test of two footprint rectangles, each shrunk by `tolerance`."""
    if math.hypot(a.x - b.x, a.y - b.y) > a.radius + b.radius:
        return False
    pa, pb = a.corners, b.corners
    for poly in (pa, pb):
        for i in range(2):
            (x1, y1), (x2, y2) = poly[i], poly[i + 1]
            ax, ay = x2 - x1, y2 - y1
            norm = math.hypot(ax, ay)
            ax, ay = ax / norm, ay / norm
            proj_a = [x * ax + y * ay for x, y in pa]
            proj_b = [x * ax + y * ay for x, y in pb]
            if max(proj_a) - tolerance <= min(proj_b) or max(proj_b) - tolerance <= min(proj_a):
                return False
    return True


def _cells(x: float, y: float, radius: float) -> list[Cell]:
    i0, i1 = math.floor((x - radius) / CELL_M), math.floor((x + radius) / CELL_M)
    j0, j1 = math.floor((y - radius) / CELL_M), math.floor((y + radius) / CELL_M)
    return [(i, j) for i in range(i0, i1 + 1) for j in range(j0, j1 + 1)]


class FootprintIndex:
    """A uniform grid of the footprints of some assets, kept in their order."""

    def __init__(self) -> None:
        self._grid: dict[Cell, dict[int, Footprint]] = {}
        self._members: dict[int, tuple[Footprint, list[Cell]]] = {}
        self._order: dict[int, int] = {}
        self._shapes: dict[int, tuple[int, float]] = {}  # id(asset) -> (id(pose), scale)
        self._categories: dict[str, Category] = {}

    def __len__(self) -> int:
        return len(self._members)

    def sync(self, assets: Sequence[AssetInstance]) -> None:
        """Index exactly `assets`: drop those no longer given (or changed in place), add the
        new ones. Assets are matched by identity, in set operations over C-built maps (a
        world of 5,000 assets costs about a millisecond, not a loop of Python per asset)."""
        keys = list(map(id, assets))
        # What each footprint was computed from: the pose object and the scale.
        shapes = dict(zip(keys, zip(map(id, map(_POSE, assets)), map(_SCALE, assets), strict=True), strict=True))
        self._order = dict(zip(reversed(keys), range(len(keys) - 1, -1, -1), strict=True))  # first place of each
        members = self._members
        for key, _ in self._shapes.items() - shapes.items():
            _, cells = members.pop(key)
            for cell in cells:
                del self._grid[cell][key]
        fresh = shapes.keys() - members.keys()
        self._shapes = shapes
        if fresh:
            by_key = dict(zip(keys, assets, strict=True))
            for key in fresh:
                self._insert(key, by_key[key])

    def _insert(self, key: int, asset: AssetInstance) -> None:
        cat = self._categories.get(asset.category)
        if cat is None:
            cat = self._categories[asset.category] = category(asset.category)
        footprint = footprint_of(asset, cat)
        cells = _cells(footprint.x, footprint.y, footprint.radius)
        for cell in cells:
            self._grid.setdefault(cell, {})[key] = footprint
        self._members[key] = (footprint, cells)

    def overlapping(self, probe: Footprint, tolerance: float = OVERLAP_TOLERANCE_M) -> list[Footprint]:
        """Indexed colliding footprints that overlap `probe` (other than its own asset id), in
        the order the assets were given."""
        found: dict[int, Footprint] = {}
        for cell in _cells(probe.x, probe.y, probe.radius):
            for key, other in self._grid.get(cell, {}).items():
                if (key not in found and other.collides and other.asset.id != probe.asset.id
                        and overlap(probe, other, tolerance)):  # fmt: skip
                    found[key] = other
        return [found[k] for k in self._in_order(found)]

    def near(self, x: float, y: float, reach: float) -> list[AssetInstance]:
        """Indexed assets whose footprint circle comes within `reach` metres of (x, y), in
        the order the assets were given."""
        found: dict[int, Footprint] = {}
        for cell in _cells(x, y, reach):
            for key, other in self._grid.get(cell, {}).items():
                if key not in found and math.hypot(other.x - x, other.y - y) <= reach + other.radius:
                    found[key] = other
        return [found[k].asset for k in self._in_order(found)]

    def _in_order(self, found: dict[int, Footprint]) -> list[int]:
        # Only assets of the last sync answer: an entry the grid still holds for an asset no
        # longer given (a dry run seen from another list) must neither answer nor raise.
        order = self._order
        return sorted((k for k in found if k in order), key=order.__getitem__)


_lock = threading.Lock()
# Callers check against a few different lists (a whole scene, a search's nearby subset):
# one index each, so that switching between them patches instead of rebuilding.
INDEXES_KEPT = 4
# (the sequence last synced, held so its id is not reused; its length then; its index)
_kept: list[tuple[Sequence[AssetInstance], int, FootprintIndex]] = []


def overlapping(assets: Sequence[AssetInstance], probe: Footprint) -> list[Footprint]:
    """The colliding footprints among `assets` that overlap `probe`, in the order given.

    The same sequence object as an earlier call (a free-spot search tries many spots against
    one list) reuses its index as it is; another one patches the index closest in size.
    """
    with _lock:
        return _synced(assets).overlapping(probe)


def near(assets: Sequence[AssetInstance], x: float, y: float, reach: float) -> list[AssetInstance]:
    """The assets among `assets` whose footprint circle comes within `reach` metres of (x, y),
    in the order given (what a free-spot search must check around its disc)."""
    with _lock:
        return _synced(assets).near(x, y, reach)


def _synced(assets: Sequence[AssetInstance]) -> FootprintIndex:
    """The index of `assets` (call with the lock held)."""
    for k, (source, length, index) in enumerate(_kept):
        if source is assets and length == len(assets):
            _kept.insert(0, _kept.pop(k))
            return index
    closest = min(range(len(_kept)), key=lambda k: abs(len(_kept[k][2]) - len(assets)), default=None)
    similar = closest is not None and abs(len(_kept[closest][2]) - len(assets)) <= len(assets) // 2
    if closest is not None and (similar or len(_kept) >= INDEXES_KEPT):
        index = _kept.pop(closest)[2]
    else:
        index = FootprintIndex()
    index.sync(assets)
    _kept.insert(0, (assets, len(assets), index))
    return index


def _reference_overlaps(probe: Footprint, assets: Iterable[AssetInstance]) -> list[AssetInstance]:
    """The plain scan: every colliding asset (other than the probe's id) that overlaps it."""
    out = []
    for other in assets:
        fp = footprint_of(other)
        if fp.collides and other.id != probe.asset.id and overlap(probe, fp):
            out.append(other)
    return out
