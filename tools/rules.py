"""Pre-execution rules every edit must pass: bounds, buildings, overlap, surface and limits.

Rules look only at what an edit adds or moves, so an edit is never refused for a conflict
that was already in the scene (a recolour of an asset that touches another is fine).
Overlap checks read a grid index of the footprints (drivetwin.tools.footprints), not every
asset, so they stay fast in worlds of thousands of assets.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from functools import cache

from drivetwin.tools.errors import RuleViolation
from drivetwin.tools.footprints import (
    NON_COLLIDING_MOTION,
    OVERLAP_TOLERANCE_M,
    footprint_of,
    near,
    overlap,
    overlapping,
)
from drivetwin.worlds.catalog import Category, catalog, category
from drivetwin.worlds.edits import AddAsset, EditConflict, RemoveAsset, UpdateAsset, WorldEdit
from drivetwin.worlds.scene import EGO_ID, MAX_ASSETS, AssetInstance, Scene
from drivetwin.worlds.surface import DRIVABLE, building_at, road_height, surface_at

__all__ = [
    "NON_COLLIDING_MOTION",
    "OVERLAP_TOLERANCE_M",
    "assets_near",
    "check_edit",
    "check_placement",
    "footprint",
    "footprints_overlap",
]


def footprint(asset: AssetInstance) -> list[tuple[float, float]]:
    """The four corners of an asset's footprint rectangle, in world metres."""
    return list(footprint_of(asset).corners)


def footprints_overlap(a: AssetInstance, b: AssetInstance, tolerance: float = OVERLAP_TOLERANCE_M) -> bool:
    """Separating-axis test of two footprint rectangles, each shrunk by `tolerance`."""
    return overlap(footprint_of(a), footprint_of(b), tolerance)


def assets_near(assets: Sequence[AssetInstance], x: float, y: float, reach: float,
                scene: Scene | None = None) -> list[AssetInstance]:
    """The assets whose footprints come within `reach` metres of (x, y), in the order given,
    found through the grid index (what a free-spot search must check around its disc).
    `scene`: the scene whose assets `assets` mostly are, if known (its index answers)."""
    return near(assets, x, y, reach, scene)


def settle_on_roads(scene: Scene, edit: WorldEdit) -> WorldEdit:
    """The edit with every asset it adds or moves onto a raised road standing on that road's
    surface (z from the lane's elevation). Workers place in the plane; an imported map's lanes
    may climb, and a car at z = 0 there would sit inside the road. Flat worlds are unchanged."""
    if not any(lane.elevation for lane in scene.roads.lanes):
        return edit
    ops = []
    for op in edit.ops:
        asset = op.asset if isinstance(op, AddAsset) else op.after if isinstance(op, UpdateAsset) else None
        height = road_height(scene, asset.pose.x, asset.pose.y) if asset is not None else 0.0
        if asset is None or height == 0.0 or asset.pose.z == height:
            ops.append(op)
            continue
        settled = asset.model_copy(update={"pose": asset.pose.model_copy(update={"z": height})})
        ops.append(op.model_copy(update={"asset": settled} if isinstance(op, AddAsset) else {"after": settled}))
    return edit.model_copy(update={"ops": ops})


def _placed(edit: WorldEdit) -> list[AssetInstance]:
    """Assets the edit adds or moves (a pose, scale or category change)."""
    out = []
    for op in edit.ops:
        if isinstance(op, AddAsset):
            out.append(op.asset)
        elif isinstance(op, UpdateAsset) and (
            op.before.pose != op.after.pose or op.before.scale != op.after.scale
        ):
            out.append(op.after)
    return out


def check_placement(scene: Scene, asset: AssetInstance, others: Iterable[AssetInstance]) -> None:
    """Raise RuleViolation if `asset` may not stand where it is, among `others`."""
    cat = category(asset.category)
    probe = footprint_of(asset, cat)
    corners = probe.corners
    x, y = asset.pose.x, asset.pose.y
    b = scene.bounds
    if not all(b.contains(cx, cy) for cx, cy in corners):
        raise RuleViolation(
            "bounds",
            f"{asset.id} at ({x:.1f}, {y:.1f}) is outside the world; allowed: "
            f"x in [{b.xmin:g}, {b.xmax:g}], y in [{b.ymin:g}, {b.ymax:g}] m",
        )
    for cx, cy in [*corners, (x, y)]:
        inside = building_at(scene, cx, cy)
        if inside:
            raise RuleViolation(
                "building",
                f"{asset.id} at ({x:.1f}, {y:.1f}) would be inside {inside}; "
                "place it outside the building's footprint",
            )
    _check_surface(scene, asset, cat)
    if cat.motion in NON_COLLIDING_MOTION:
        return
    hits = overlapping(others if isinstance(others, Sequence) else list(others), probe, scene)
    if hits:
        raise RuleViolation(
            "overlap",
            f"{asset.id} at ({x:.1f}, {y:.1f}) would overlap {hits[0].asset.id}; "
            "choose a free spot or a larger spacing",
        )


@cache
def _instead(name: str, ground: str) -> str:
    """What could stand on `ground` in a drivable-only thing's place: kinds that share its purpose
    (a tag such as "block" or "maintenance") and may stand anywhere, as a hint to end a refusal.
    Cached: a refused free-spot search raises this refusal thousands of times."""
    tags = set(category(name).tags) - {"temporary", "permanent"}
    kin = [c.name for c in catalog().values() if c.placement == "anywhere" and c.motion == "prop" and set(c.tags) & tags]
    return f"; {' or '.join(k.replace('_', ' ') + 's' for k in kin)} can stand on {ground}" if kin else ""


def _check_surface(scene: Scene, asset: AssetInstance, cat: Category) -> None:
    x, y = asset.pose.x, asset.pose.y
    ground = surface_at(scene, x, y)
    if cat.placement == "drivable" and ground not in DRIVABLE:
        raise RuleViolation(
            "surface",
            f"a {cat.name} must stand on a road, crossing or paved area; ({x:.1f}, {y:.1f}) "
            f"is {ground}{_instead(cat.name, ground)}",
        )
    if cat.placement == "sidewalk" and ground not in ("sidewalk", "ground"):
        raise RuleViolation(
            "surface",
            f"a {cat.name} belongs on a sidewalk or verge, not on the {ground} at "
            f"({x:.1f}, {y:.1f})",
        )


def check_edit(scene: Scene, edit: WorldEdit) -> None:
    """Raise a RuleViolation if `edit` may not be applied to `scene`; change nothing."""
    for op in edit.ops:
        if isinstance(op, RemoveAsset) and op.before.id == EGO_ID:
            raise RuleViolation("protected", "the ego vehicle cannot be removed; move it instead")
        if isinstance(op, UpdateAsset) and op.before.category != op.after.category:
            raise RuleViolation(
                "protected", f"{op.before.id} cannot change category; remove it and add another"
            )
    try:
        after = edit.apply(scene)
    except EditConflict as exc:
        raise RuleViolation("conflict", str(exc)) from exc
    except ValueError as exc:  # pydantic: e.g. more than MAX_ASSETS
        raise RuleViolation("limits", f"the scene would be invalid: {exc}") from exc
    if len(after.assets) > MAX_ASSETS:
        raise RuleViolation("limits", f"a scene holds at most {MAX_ASSETS} assets")
    for name in {op.asset.category for op in edit.ops if isinstance(op, AddAsset)}:
        limit = category(name).max_count
        if after.count(name) > limit:
            raise RuleViolation(
                "limits", f"at most {limit} {name} assets fit a scene; it would have {after.count(name)}"
            )
    everyone = after.all_assets()
    for asset in _placed(edit):
        check_placement(after, asset, everyone)

