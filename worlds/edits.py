"""WorldEdit: a list of operations on a Scene that can be applied, inverted and journaled.

Each operation carries the full state before and after, so an edit is its own undo record and
replaying a journal of edits rebuilds a Scene exactly.
"""

from __future__ import annotations

import bisect
import weakref
from dataclasses import dataclass
from typing import Annotated, Literal

from drivetwin.worlds.asset_table import asset_table, keep_table
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Environment, Scene, asset_order
from drivetwin.worlds.storyboard import Storyboard
from pydantic import BaseModel, ConfigDict, Field


class _Op(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class AddAsset(_Op):
    """Put a new asset into the scene."""

    op: Literal["add"] = "add"
    asset: AssetInstance


class RemoveAsset(_Op):
    """Take an asset out of the scene (`before` is kept to undo it)."""

    op: Literal["remove"] = "remove"
    before: AssetInstance


class UpdateAsset(_Op):
    """Replace an asset's state (pose, behaviour, appearance...) keeping its id."""

    op: Literal["update"] = "update"
    before: AssetInstance
    after: AssetInstance


class SetEnvironment(_Op):
    """Change time of day, weather or lighting."""

    op: Literal["environment"] = "environment"
    before: Environment
    after: Environment


class SetStoryboard(_Op):
    """Replace the storyboard (events, manoeuvres, traffic-light phases)."""

    op: Literal["storyboard"] = "storyboard"
    before: Storyboard
    after: Storyboard


Operation = Annotated[
    AddAsset | RemoveAsset | UpdateAsset | SetEnvironment | SetStoryboard, Field(discriminator="op")
]


class EditConflict(ValueError):
    """An edit that does not fit the scene it is applied to (stale `before`, duplicate id)."""


class WorldEdit(BaseModel):
    """An ordered list of operations; empty for tools that only look (search)."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    ops: tuple[Operation, ...] = ()

    def __add__(self, other: WorldEdit) -> WorldEdit:
        return WorldEdit(ops=(*self.ops, *other.ops))

    @property
    def empty(self) -> bool:
        return not self.ops

    def inverse(self) -> WorldEdit:
        """The edit that undoes this one."""
        undone: list[AddAsset | RemoveAsset | UpdateAsset | SetEnvironment | SetStoryboard] = []
        for op in reversed(self.ops):
            if isinstance(op, AddAsset):
                undone.append(RemoveAsset(before=op.asset))
            elif isinstance(op, RemoveAsset):
                undone.append(AddAsset(asset=op.before))
            elif isinstance(op, UpdateAsset):
                undone.append(UpdateAsset(before=op.after, after=op.before))
            elif isinstance(op, SetStoryboard):
                undone.append(SetStoryboard(before=op.after, after=op.before))
            else:
                undone.append(SetEnvironment(before=op.after, after=op.before))
        return WorldEdit(ops=tuple(undone))

    def touched_ids(self) -> set[str]:
        """Ids of assets this edit adds, removes or changes."""
        ids: set[str] = set()
        for op in self.ops:
            if isinstance(op, AddAsset):
                ids.add(op.asset.id)
            elif isinstance(op, RemoveAsset | UpdateAsset):
                ids.add(op.before.id)
        return ids

    def apply(self, scene: Scene) -> Scene:
        """A new Scene with the operations applied in order; `scene` is not changed.

        Copy-on-write: the new scene shares every asset the edit leaves alone, its asset list
        is a copy patched in place (the canonical order kept), and its id lookups come from
        `scene`'s patched (drivetwin.worlds.asset_table), so an edit costs what it changes, not
        the size of the world. How the scene was made is kept (`lineage`) for the views
        that follow edits instead of re-reading every asset.
        """
        by_id = asset_table(scene.assets).by_id
        # The assets this edit changes, by id: the asset now, or None once removed.
        changed: dict[str, AssetInstance | None] = {}

        def current(asset_id: str) -> AssetInstance | None:
            return changed[asset_id] if asset_id in changed else by_id.get(asset_id)

        ego = scene.ego
        environment = scene.environment
        storyboard = scene.storyboard
        for op in self.ops:
            if isinstance(op, AddAsset):
                if op.asset.id == EGO_ID or current(op.asset.id) is not None:
                    raise EditConflict(f"an asset with id {op.asset.id!r} already exists")
                changed[op.asset.id] = op.asset
            elif isinstance(op, RemoveAsset):
                if op.before.id == EGO_ID:
                    raise EditConflict("the ego vehicle cannot be removed")
                if current(op.before.id) != op.before:
                    raise EditConflict(f"asset {op.before.id!r} is not as this edit expects")
                changed[op.before.id] = None
            elif isinstance(op, UpdateAsset):
                now = ego if op.before.id == EGO_ID else current(op.before.id)
                if now != op.before or op.after.id != op.before.id:
                    raise EditConflict(f"asset {op.before.id!r} is not as this edit expects")
                if op.before.id == EGO_ID:
                    ego = op.after
                else:
                    changed[op.before.id] = op.after
            elif isinstance(op, SetStoryboard):
                if storyboard != op.before:
                    raise EditConflict("the storyboard is not as this edit expects")
                storyboard = op.after
            else:
                if environment != op.before:
                    raise EditConflict("the environment is not as this edit expects")
                environment = op.after
        gone = [by_id[k] for k, a in changed.items() if k in by_id and by_id[k] is not a]
        came = [a for k, a in changed.items() if a is not None and by_id.get(k) is not a]
        assets = _patched_list(scene.assets, gone, came) if gone or came else scene.assets
        after = scene.model_copy(
            update={"assets": assets, "ego": ego, "environment": environment, "storyboard": storyboard}
        )
        if assets is not scene.assets:
            keep_table(assets, asset_table(scene.assets).patched(gone, came))
        if ego is not scene.ego:
            gone.append(scene.ego)
            came.append(ego)
        _made(scene, after, gone, came)
        return after

    def summary(self) -> list[str]:
        """One line per operation, in words, for the REPL's diff."""
        lines = []
        for op in self.ops:
            if isinstance(op, AddAsset):
                p = op.asset.pose
                lines.append(f"+ {op.asset.id} ({op.asset.category}) at ({p.x:.1f}, {p.y:.1f})")
            elif isinstance(op, RemoveAsset):
                lines.append(f"- {op.before.id} ({op.before.category})")
            elif isinstance(op, UpdateAsset):
                lines.append(f"~ {op.before.id}: {', '.join(_changed(op.before, op.after))}")
            elif isinstance(op, SetStoryboard):
                before = {e.name for _, e in op.before.events()}
                added = [f"{a or 'signals'}: {e.name} ({e.action.kind})" for a, e in op.after.events() if e.name not in before]
                lines.append(f"~ storyboard: {', '.join(added) or 'changed'}")
            else:
                lines.append(f"~ environment: {', '.join(_env_changes(op.before, op.after))}")
        return lines


@dataclass(eq=False)
class Lineage:
    """A scene's place among the scenes that edits made from one another: its parent's place
    and the assets (the ego included) that left and came, matched by identity; every other
    asset object is shared with the parent. Views of a scene (the placement rules' footprint
    index) follow these steps instead of re-reading thousands of assets."""

    parent: Lineage | None
    gone: tuple[AssetInstance, ...] = ()
    came: tuple[AssetInstance, ...] = ()


# Steps of history kept behind each scene: enough to go from a dry run to its sibling commit,
# or back through a few undos; older places are let go (a view then re-reads the scene).
LINEAGE_STEPS = 16
# id(scene) -> (a weak reference whose callback drops the entry, its lineage, and what the
# scene held then: one changed in place since is a new root)
_lineages: dict[int, tuple[weakref.ref[Scene], Lineage, list[AssetInstance], int, AssetInstance]] = {}


def lineage(scene: Scene) -> Lineage:
    """`scene`'s place in the history of edits (a new root for a scene no edit made, or one
    changed in place since)."""
    entry = _lineages.get(id(scene))
    if entry is not None:
        ref, place, assets, length, ego = entry
        if ref() is scene and assets is scene.assets and length == len(scene.assets) and ego is scene.ego:
            return place
    place = Lineage(None)
    _remember(scene, place)
    return place


def _remember(scene: Scene, place: Lineage) -> None:
    key = id(scene)
    ref = weakref.ref(scene, lambda _: _lineages.pop(key, None))
    _lineages[key] = (ref, place, scene.assets, len(scene.assets), scene.ego)


def _made(parent: Scene, made: Scene, gone: list[AssetInstance], came: list[AssetInstance]) -> None:
    place = Lineage(lineage(parent), tuple(gone), tuple(came))
    _remember(made, place)
    older: Lineage | None = place
    for _ in range(LINEAGE_STEPS):
        older = older.parent if older is not None else None
    if older is not None:
        older.parent = None  # history this old is not followed: let its assets go


def _patched_list(assets: list[AssetInstance], gone: list[AssetInstance], came: list[AssetInstance]) -> list[AssetInstance]:
    """A copy of `assets` without `gone` and with `came`: a replaced asset keeps its place and an
    added one is inserted in canonical order (a full sort of thousands of assets per edit was
    most of an edit's time in a 5,000-asset world)."""
    out = list(assets)
    arriving = {a.id: a for a in came}
    leaving = []
    for old in gone:
        at = _position(out, old)
        new = arriving.pop(old.id, None)
        if new is None:
            leaving.append(at)
        else:
            out[at] = new
    for at in sorted(leaving, reverse=True):
        del out[at]
    for asset in arriving.values():
        bisect.insort(out, asset, key=asset_order)
    return out


def _position(assets: list[AssetInstance], asset: AssetInstance) -> int:
    """Where `asset` (this object) stands in `assets`: a binary search in canonical order, or a
    scan by identity for a list made without validation (not in that order)."""
    at = bisect.bisect_left(assets, asset_order(asset), key=asset_order)
    if at < len(assets) and assets[at] is asset:
        return at
    return list(map(id, assets)).index(id(asset))

def _changed(before: AssetInstance, after: AssetInstance) -> list[str]:
    out = []
    if before.pose != after.pose:
        p, q = before.pose, after.pose
        out.append(f"pose ({p.x:.1f}, {p.y:.1f}) -> ({q.x:.1f}, {q.y:.1f}, yaw {q.yaw:.2f})")
    if before.behaviour != after.behaviour:
        out.append(f"behaviour {before.behaviour.kind} -> {after.behaviour.kind}")
    if before.appearance != after.appearance:
        out.append(f"appearance -> {after.appearance.model_dump(exclude_defaults=True)}")
    if before.scale != after.scale:
        out.append(f"scale {before.scale:g} -> {after.scale:g}")
    if before.physics != after.physics:
        out.append("physics")
    if before.label != after.label:
        out.append(f"label {after.label!r}")
    return out or ["unchanged"]


def _env_changes(before: Environment, after: Environment) -> list[str]:
    out = []
    if before.time_of_day != after.time_of_day:
        out.append(f"time {before.time_of_day} -> {after.time_of_day}")
    if before.weather != after.weather:
        w = after.weather
        out.append(f"weather {before.weather.kind} -> {w.kind} ({w.intensity:.1f})")
    if before.lighting != after.lighting:
        out.append(f"lighting -> {after.lighting.model_dump()}")
    return out or ["unchanged"]
