"""The placement rules' footprint queries: which assets of a list overlap a footprint or
stand near a point, answered from grid indexes (drivetwin.tools.footprint_grid).

Workers pass lists: a scene's assets (ego first), perhaps without the one being moved,
followed by the few a call is placing. `overlapping` and `near` recognise such a list
(identity checks in C) and answer from the scene's index, which follows the scene's edits,
plus a scan of the few extra ones; any other list gets its own `FootprintIndex`.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Iterable, Sequence

from drivetwin.tools.footprint_grid import (
    NON_COLLIDING_MOTION,
    OVERLAP_TOLERANCE_M,
    Footprint,
    FootprintIndex,
    SceneFootprints,
    footprint_of,
    overlap,
)
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import AssetInstance, Scene

__all__ = [
    "NON_COLLIDING_MOTION",
    "OVERLAP_TOLERANCE_M",
    "Footprint",
    "FootprintIndex",
    "SceneFootprints",
    "footprint_of",
    "near",
    "overlap",
    "overlapping",
    "track",
]

# A list with more assets than a scene's beyond this is not "the scene and what one call
# places" (at most 50, plus the walkers it keeps clear of): it gets an index of its own.
MAX_EXTRAS = 128

def _split(roster: list[AssetInstance], given: Sequence[AssetInstance]) -> tuple[AssetInstance | None, Sequence[AssetInstance]] | None:
    """If `given` is `roster` (by identity, in order) with at most one asset left out, followed
    by a few more: (the one left out or None, the ones after). Slices compare in C."""
    n, m = len(roster), len(given)
    if not n or not n - 1 <= m <= n + MAX_EXTRAS:
        return None
    if m >= n and given[:n] == roster:
        return None, given[n:]
    lo, hi = 0, min(n, m)  # the first place where they differ, if one was left out there
    while lo < hi:
        mid = (lo + hi) // 2
        if given[mid] is roster[mid]:
            lo = mid + 1
        else:
            hi = mid
    if lo < n and given[:lo] == roster[:lo] and given[lo:n - 1] == roster[lo + 1:]:
        return roster[lo], given[n - 1:]
    return None


_lock = threading.Lock()
# Scene indexes kept, most recently used first: a session's scenes are related by edits, so
# one index follows them all; a second spares re-reading when work alternates between worlds.
SCENE_INDEXES_KEPT = 2
_scene_indexes: list[SceneFootprints] = []
# Callers check against a few different lists (a search's nearby subset...): one index
# each, so that switching between them patches instead of rebuilding.
INDEXES_KEPT = 4
# (the sequence last synced, held so its id is not reused; its length then; its index)
_kept: list[tuple[Sequence[AssetInstance], int, FootprintIndex]] = []


def track(scene: Scene) -> None:
    """Index `scene` now, so that lists of its assets that Workers pass later are answered
    from its index (cheap for a scene made by an edit from one indexed before)."""
    with _lock:
        _scene_index(scene)


def overlapping(assets: Sequence[AssetInstance], probe: Footprint, scene: Scene | None = None) -> list[Footprint]:
    """The colliding footprints among `assets` that overlap `probe`, in the order given.

    `scene`: the scene whose assets `assets` (mostly) are, if known. The same sequence object
    as an earlier call (a free-spot search tries many spots against one list) reuses its index.
    """
    with _lock:
        view = _view(assets, scene)
        if view is None:
            return _synced(assets).overlapping(probe)
        index, left_out, extras = view
        found = [f for f in index.overlapping(probe) if f.asset is not left_out]
        for other in _extras(index, left_out, extras):
            if other.id != probe.asset.id and _within(other, probe.x, probe.y, probe.radius):
                fp = footprint_of(other)
                if fp.collides and overlap(probe, fp):
                    found.append(fp)
        return found


def near(assets: Sequence[AssetInstance], x: float, y: float, reach: float, scene: Scene | None = None) -> list[AssetInstance]:
    """The assets among `assets` whose footprint circle comes within `reach` metres of (x, y),
    in the order given (what a free-spot search must check around its disc)."""
    with _lock:
        view = _view(assets, scene)
        if view is None:
            return _synced(assets).near(x, y, reach)
        index, left_out, extras = view
        found = [a for a in index.near(x, y, reach) if a is not left_out]
        found.extend(a for a in _extras(index, left_out, extras) if _within(a, x, y, reach))
        return found


def _within(asset: AssetInstance, x: float, y: float, reach: float) -> bool:
    radius = category(asset.category).footprint_radius * asset.scale
    return math.hypot(asset.pose.x - x, asset.pose.y - y) <= reach + radius


def _extras(index: SceneFootprints, left_out: AssetInstance | None, extras: Iterable[AssetInstance]) -> list[AssetInstance]:
    """The extra assets not already answered for: neither the scene's nor listed before."""
    seen: set[int] = set()
    out = []
    for asset in extras:
        if id(asset) in seen or (asset is not left_out and index.indexes(asset)):
            continue
        seen.add(id(asset))
        out.append(asset)
    return out


def _view(assets: Sequence[AssetInstance], scene: Scene | None) -> tuple[SceneFootprints, AssetInstance | None, Sequence[AssetInstance]] | None:
    """(a scene index, the asset left out, the extras) if `assets` is a scene's list (call with the lock held)."""
    candidates = [_scene_index(scene)] if scene is not None else list(_scene_indexes)
    for index in candidates:
        split = _split(index.roster, assets)
        if split is not None:
            return index, *split
    return None


def _scene_index(scene: Scene) -> SceneFootprints:
    """The index of `scene`, moved there from a kept one it is related to by edits, else
    re-read into a new or the least recently used one (call with the lock held)."""
    index = next((ix for ix in _scene_indexes if ix.holds(scene)), None)
    if index is None:
        index = next((ix for ix in _scene_indexes if ix.steps_to(scene) is not None), None)
        if index is None:
            index = SceneFootprints() if len(_scene_indexes) < SCENE_INDEXES_KEPT else _scene_indexes[-1]
        index.follow(scene)
    if index in _scene_indexes:
        _scene_indexes.remove(index)
    _scene_indexes.insert(0, index)
    return index


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
