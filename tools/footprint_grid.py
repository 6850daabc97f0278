"""Asset footprints on the ground and the grid indexes over them (drivetwin.tools.footprints
answers the placement rules' queries through these).

A footprint is an asset's rectangle (category length × width, scaled, turned by its yaw);
two footprints overlap by the separating-axis test. A grid index answers "which assets could
overlap this one" from a few cells instead of a scan over every asset. Both indexes are
derived from what they index (never a second truth):

- `SceneFootprints` indexes one Scene's assets (the ego included) and follows its edits:
  moved to a scene that `WorldEdit.apply` made from the one it indexes (or back to the parent,
  or across to a sibling: a dry run and its commit), it patches the few assets the edits
  changed (`drivetwin.worlds.edits.lineage`), so an edit costs what it changes, not the size
  of the world. Only a scene of unknown making is re-read (by identity, in C).
- `FootprintIndex` indexes a plain list of assets, patched by identity from the last list.

`_reference_overlaps` is the plain scan both must agree with (tested on random scenes and
random edit sequences). Scenes are values: an asset or asset list changed in place under a
scene that edits were made from is not followed.
"""

from __future__ import annotations

import math
import weakref
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from operator import attrgetter

from drivetwin.worlds.catalog import Category, category
from drivetwin.worlds.edits import Lineage, lineage
from drivetwin.worlds.scene import AssetInstance, Pose, Scene, asset_order

__all__ = [
    "NON_COLLIDING_MOTION",
    "OVERLAP_TOLERANCE_M",
    "Footprint",
    "FootprintIndex",
    "SceneFootprints",
    "footprint_of",
    "overlap",
]

# Footprints may touch: cones in a tight ring or cars in adjacent bays are fine.
OVERLAP_TOLERANCE_M = 0.05
# Grid cell edge: about the footprint of a car, so a query reads a handful of cells and a
# cell holds a handful of props (a bus spans a few cells).
CELL_M = 4.0
# Walkers and riders are kinematic and step around furniture; they never block a placement.
NON_COLLIDING_MOTION = frozenset({"walker"})
# Edits followed back and forth between two scenes before re-reading one is cheaper.
MAX_STEPS = 16

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


class _Grid:
    """Footprints in a uniform grid, keyed by the identity of their asset."""

    def __init__(self) -> None:
        self._grid: dict[Cell, dict[int, Footprint]] = {}
        self._members: dict[int, tuple[Footprint, list[Cell]]] = {}
        self._shapes: dict[int, tuple[int, float]] = {}  # id(asset) -> (id(pose), scale)
        self._categories: dict[str, Category] = {}

    def __len__(self) -> int:
        return len(self._members)

    def _sync(self, assets: Sequence[AssetInstance]) -> None:
        """Index exactly `assets`: drop those no longer given (or changed in place), add the
        new ones. Assets are matched by identity, in set operations over C-built maps (a
        world of 5,000 assets costs a few milliseconds, not a loop of Python per asset)."""
        keys = list(map(id, assets))
        # What each footprint was computed from: the pose object and the scale.
        shapes = dict(zip(keys, zip(map(id, map(_POSE, assets)), map(_SCALE, assets), strict=True), strict=True))
        for key, _ in self._shapes.items() - shapes.items():
            self._remove(key)
        fresh = shapes.keys() - self._members.keys()
        if fresh:
            by_key = dict(zip(keys, assets, strict=True))
            for key in fresh:
                self._insert(by_key[key])
        self._shapes = shapes

    def _insert(self, asset: AssetInstance) -> None:
        cat = self._categories.get(asset.category)
        if cat is None:
            cat = self._categories[asset.category] = category(asset.category)
        footprint = footprint_of(asset, cat)
        cells = _cells(footprint.x, footprint.y, footprint.radius)
        key = id(asset)
        for cell in cells:
            self._grid.setdefault(cell, {})[key] = footprint
        self._members[key] = (footprint, cells)
        self._shapes[key] = (id(asset.pose), asset.scale)

    def _remove(self, key: int) -> None:
        _, cells = self._members.pop(key)
        for cell in cells:
            del self._grid[cell][key]
        self._shapes.pop(key, None)

    def _overlapping(self, probe: Footprint, tolerance: float) -> dict[int, Footprint]:
        found: dict[int, Footprint] = {}
        for cell in _cells(probe.x, probe.y, probe.radius):
            for key, other in self._grid.get(cell, {}).items():
                if (key not in found and other.collides and other.asset.id != probe.asset.id
                        and overlap(probe, other, tolerance)):  # fmt: skip
                    found[key] = other
        return found

    def _near(self, x: float, y: float, reach: float) -> dict[int, Footprint]:
        found: dict[int, Footprint] = {}
        for cell in _cells(x, y, reach):
            for key, other in self._grid.get(cell, {}).items():
                if key not in found and math.hypot(other.x - x, other.y - y) <= reach + other.radius:
                    found[key] = other
        return found


class FootprintIndex(_Grid):
    """A grid of the footprints of a list of assets, answering in the list's order."""

    def __init__(self) -> None:
        super().__init__()
        self._order: dict[int, int] = {}

    def sync(self, assets: Sequence[AssetInstance]) -> None:
        """Index exactly `assets` (patched by identity from the last list synced)."""
        keys = list(map(id, assets))
        self._order = dict(zip(reversed(keys), range(len(keys) - 1, -1, -1), strict=True))  # first place of each
        self._sync(assets)

    def overlapping(self, probe: Footprint, tolerance: float = OVERLAP_TOLERANCE_M) -> list[Footprint]:
        """Indexed colliding footprints that overlap `probe` (other than its own asset id), in
        the order the assets were given."""
        found = self._overlapping(probe, tolerance)
        return [found[k] for k in self._in_order(found)]

    def near(self, x: float, y: float, reach: float) -> list[AssetInstance]:
        """Indexed assets whose footprint circle comes within `reach` metres of (x, y), in
        the order the assets were given."""
        found = self._near(x, y, reach)
        return [found[k].asset for k in self._in_order(found)]

    def _in_order(self, found: dict[int, Footprint]) -> list[int]:
        # Only assets of the last sync answer: an entry the grid still holds for an asset no
        # longer given (a dry run seen from another list) must neither answer nor raise.
        order = self._order
        return sorted((k for k in found if k in order), key=order.__getitem__)


class SceneFootprints(_Grid):
    """A grid of the footprints of one Scene's assets that follows the scene's edits; it
    answers in the scene's canonical order (the ego first)."""

    def __init__(self) -> None:
        super().__init__()
        self._scene: weakref.ref[Scene] | None = None
        # What the scene held when indexed: a scene changed in place since is not this one.
        self._held: tuple[list[AssetInstance], int, AssetInstance] | None = None
        self.roster: list[AssetInstance] = []  # the scene's assets, ego first
        self._place: Lineage | None = None  # its place in the history of edits

    def holds(self, scene: Scene) -> bool:
        """Whether this index is of `scene` as it is now."""
        return (self._scene is not None and self._scene() is scene and self._held is not None
                and self._held[0] is scene.assets and self._held[1] == len(scene.assets)
                and self._held[2] is scene.ego)  # fmt: skip

    def steps_to(self, scene: Scene) -> list[tuple[Lineage, bool]] | None:
        """The edits between the scene indexed now and `scene`, or None if not related. The
        indexed scene may be gone (a dry run's): its place in the history still leads on."""
        now = self._scene() if self._scene is not None else None
        if self._place is None or (now is not None and not self.holds(now)):
            return None  # nothing indexed yet, or changed in place since
        return _steps_between(self._place, lineage(scene))

    def follow(self, scene: Scene) -> None:
        """Index `scene`: patched along the edits between it and the scene indexed now, or re-read."""
        if self.holds(scene):
            return
        steps = self.steps_to(scene)
        if steps is None or not self._patch(steps):
            self._sync(scene.all_assets())
        self._scene = weakref.ref(scene)
        self._held = (scene.assets, len(scene.assets), scene.ego)
        self._place = lineage(scene)
        self.roster = scene.all_assets()

    def _patch(self, steps: list[tuple[Lineage, bool]]) -> bool:
        """Take each step forwards (or backwards); False if one does not fit the index."""
        for step, forwards in steps:
            gone, came = (step.gone, step.came) if forwards else (step.came, step.gone)
            if any(id(a) not in self._members for a in gone):
                return False
            for asset in gone:
                self._remove(id(asset))
            for asset in came:
                self._insert(asset)
        return True

    def overlapping(self, probe: Footprint, tolerance: float = OVERLAP_TOLERANCE_M) -> list[Footprint]:
        """Colliding footprints of the scene that overlap `probe` (other than its own asset id)."""
        found = self._overlapping(probe, tolerance)
        return sorted(found.values(), key=lambda f: self._rank(f.asset))

    def near(self, x: float, y: float, reach: float) -> list[AssetInstance]:
        """Assets of the scene whose footprint circle comes within `reach` metres of (x, y)."""
        found = self._near(x, y, reach)
        return sorted((f.asset for f in found.values()), key=self._rank)

    def indexes(self, asset: AssetInstance) -> bool:
        """Whether this very asset object is one of the scene's."""
        member = self._members.get(id(asset))
        return member is not None and member[0].asset is asset

    def _rank(self, asset: AssetInstance) -> tuple[bool, tuple[str, int, str]]:
        return (asset is not self.roster[0], asset_order(asset))


def _steps_between(start: Lineage, goal: Lineage) -> list[tuple[Lineage, bool]] | None:
    """The steps from history place `start` to `goal`: backwards to their nearest common
    ancestor, then forwards; None if they are not related within MAX_STEPS."""
    ups, downs = _ancestors(start), _ancestors(goal)
    where = {id(place): j for j, place in enumerate(downs)}
    for i, place in enumerate(ups):
        j = where.get(id(place))
        if j is not None and i + j <= MAX_STEPS:
            return [*((p, False) for p in ups[:i]), *((p, True) for p in reversed(downs[:j]))]
    return None


def _ancestors(place: Lineage) -> list[Lineage]:
    chain = [place]
    while len(chain) <= MAX_STEPS and (parent := chain[-1].parent) is not None:
        chain.append(parent)
    return chain


def _reference_overlaps(probe: Footprint, assets: Iterable[AssetInstance]) -> list[AssetInstance]:
    """The plain scan: every colliding asset (other than the probe's id) that overlaps it."""
    out = []
    for other in assets:
        fp = footprint_of(other)
        if fp.collides and other.id != probe.asset.id and overlap(probe, fp):
            out.append(other)
    return out
