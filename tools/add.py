"""Add Worker: put new assets of a catalog category into the world."""

from __future__ import annotations

import math
from dataclasses import replace

from drivetwin.tools.along import LANE_ENTRY_M, driving_start
from drivetwin.tools.appearance import resolve_colour
from drivetwin.tools.base import CategoryName, Tool, ToolArgs, ToolResult
from drivetwin.tools.errors import NotFoundError, RuleViolation
from drivetwin.tools.footprints import track
from drivetwin.tools.locate import SEARCH_RADIUS_M, Anchor, Location, find_free_pose, resolve_anchor
from drivetwin.tools.move import BehaviourSpec, resolve_behaviour, start_towards
from drivetwin.tools.rules import NON_COLLIDING_MOTION, check_placement
from drivetwin.worlds import edits
from drivetwin.worlds.asset_table import asset_table
from drivetwin.worlds.catalog import category, placeable_categories
from drivetwin.worlds.edits import WorldEdit
from drivetwin.worlds.scene import Appearance, AssetInstance, Lane, PhysicsProps, Pose, Scene, asset_order
from drivetwin.worlds.surface import lane_at, nearest_on_polyline
from pydantic import Field

# One call adds at most this many; bigger layouts are several calls or an arrangement.
MAX_PER_CALL = 50


def new_asset(scene: Scene, category_name: str, taken: set[str], label: str = "",
              colour: str | None = None, dynamic: bool | None = None) -> AssetInstance:
    """A fresh asset of a category at the origin, with an id not in the scene nor in `taken`."""
    cat = category(category_name)
    n = 1
    while f"{cat.name}_{n}" in taken or scene.asset(f"{cat.name}_{n}") is not None:
        n += 1
    is_dynamic = dynamic if dynamic is not None else cat.motion in ("vehicle", "walker", "prop")
    appearance = Appearance(rgba=resolve_colour(colour)) if colour else Appearance()
    return AssetInstance(
        id=f"{cat.name}_{n}", category=cat.name, pose=Pose(x=0.0, y=0.0),
        physics=PhysicsProps(mass=cat.mass, dynamic=is_dynamic), appearance=appearance, label=label,
    )


class AddArgs(ToolArgs):
    category: CategoryName = Field(description="asset category from the catalog, e.g. traffic_cone")
    count: int = Field(1, ge=1, le=MAX_PER_CALL, description="how many to add; several spread onto distinct free spots")
    location: Location = Field(
        default_factory=lambda: Location(relation="scene_centre"),
        description="where to put it (default: the scene centre); absolute x/y is honoured exactly or "
        "refused with the reason; along_m/side put it N m ahead of or behind a target along its lane",
    )
    behaviour: BehaviourSpec | None = Field(
        None, description="what it does (default: parked); a drive_lane vehicle starts in its lane at the "
        "location, several spaced along the lane",
    )
    yaw_deg: float | None = Field(None, ge=-360.0, le=360.0, description="heading, degrees")
    colour: str | None = Field(None, description="a colour name such as red, or #rrggbb")
    label: str = Field("", max_length=80, description="the user's words for it")


class AddAsset(Tool[AddArgs]):
    name = "add_asset"
    description = (
        "Add new assets of one category at a location (relative to a landmark, asset, lane, "
        "sidewalk, the scene centre, N m ahead of/behind a target along its lane, or exact x/y), "
        "optionally with a behaviour; several spread without overlap."
    )
    family = "add"
    Args = AddArgs

    def propose(self, args: AddArgs, scene: Scene) -> ToolResult:
        cat = category(args.category)
        if cat.name not in placeable_categories():
            raise RuleViolation("protected", f"{cat.name} cannot be added; the world has exactly one")
        placed: list[AssetInstance] = []
        others = scene.all_assets()
        track(scene)  # the free-spot searches below pass lists of its assets: its index answers them
        anchor = resolve_anchor(scene, args.location, cat.length / 2, cat.name)
        located = "location" in args.model_fields_set
        # A behaviour that decides where the asset starts (a skidpad circle, a crossing) uses
        # the location only when the caller gave one.
        hint = (anchor.x, anchor.y) if located else None
        yaw = math.radians(args.yaw_deg) if args.yaw_deg is not None else None
        # Walkers may stand among furniture, but not on each other.
        walkers = _walkers(scene)
        for _ in range(args.count):
            template = new_asset(scene, cat.name, {a.id for a in placed}, args.label, args.colour)
            start: Pose | None = None
            spec = args.behaviour
            if spec is not None and spec.kind == "follow_path" and spec.to is not None:
                # Going somewhere: placed first (where said, else some way off), then on its way from there.
                start_at = anchor if located else start_towards(scene, cat.name, spec.to)
                here = start_at if not placed else replace(start_at, exact=False)
                # A walker faces where it goes; a vehicle put in a lane faces along it (default_yaw).
                facing = yaw if yaw is not None or cat.motion == "vehicle" else start_at.heading
                pose = find_free_pose(scene, template, here, [*others, *placed], facing,
                                      keep_clear=[*walkers, *placed], slots=args.count)
                moved = template.model_copy(update={"pose": pose})
                behaviour, _ = resolve_behaviour(scene, moved, spec)
                placed.append(moved.model_copy(update={"behaviour": behaviour}))
                continue
            if spec is not None and spec.kind == "drive_lane":
                pose = _driving_pose(scene, template, spec, anchor, located, [*others, *placed], not placed)
                moved = template.model_copy(update={"pose": pose})
                lane_spec = spec.model_copy(update={"lane": spec.lane or _lane_at_pose(scene, pose).id})
                behaviour, _ = resolve_behaviour(scene, moved, lane_spec)
                placed.append(moved.model_copy(update={"behaviour": behaviour}))
                continue
            if spec is not None:
                behaviour, start = resolve_behaviour(scene, template, spec, hint)
                template = template.model_copy(update={"behaviour": behaviour})
            if start is not None:
                pose = start
                check_placement(scene, template.model_copy(update={"pose": pose}), [*others, *placed])
            else:
                # Coordinates are honoured exactly for the first; the rest stand nearest them.
                here = anchor if not placed else replace(anchor, exact=False)
                try:
                    pose = find_free_pose(scene, template, here, [*others, *placed], yaw,
                                          keep_clear=[*walkers, *placed], slots=args.count)
                except RuleViolation as exc:
                    raise _fewer_fit(exc, args.count, len(placed), cat.name, anchor) from exc
            placed.append(template.model_copy(update={"pose": pose}))
        edit = WorldEdit(ops=tuple(edits.AddAsset(asset=a) for a in placed))
        cx = sum(a.pose.x for a in placed) / len(placed)
        cy = sum(a.pose.y for a in placed) / len(placed)
        where = f" {anchor.spot.label}" if anchor.spot else f" near {anchor.near.name}" if anchor.near else ""
        ids = ", ".join(a.id for a in placed)
        return ToolResult(edit, f"added {ids}{where} around ({cx:.1f}, {cy:.1f})", (cx, cy),
                          {"ids": [a.id for a in placed]})


def _walkers(scene: Scene) -> list[AssetInstance]:
    """The scene's walkers (by category, not a scan of every asset), in canonical order."""
    groups = asset_table(scene.assets).by_category()
    walking = [a for name, group in groups.items() if category(name).motion in NON_COLLIDING_MOTION for a in group]
    if category(scene.ego.category).motion in NON_COLLIDING_MOTION:
        walking.append(scene.ego)
    return sorted(walking, key=asset_order)


def _fewer_fit(exc: RuleViolation, wanted: int, fitted: int, name: str, anchor: Anchor) -> RuleViolation:
    """The refusal of a request for more assets than fit, saying how many do."""
    if wanted == 1 or (fitted == 0 and anchor.exact):
        return exc
    where = anchor.spot.label if anchor.spot else anchor.near.name if anchor.near else f"({anchor.x:.1f}, {anchor.y:.1f})"
    return RuleViolation(
        "no_space", f"no free spot within {SEARCH_RADIUS_M:g} m of {where} for {wanted} {name}; "
        f"{fitted} fit ({exc})",
    )


def _lane_at_pose(scene: Scene, pose: Pose) -> Lane:
    lane = lane_at(scene, pose.x, pose.y)
    if lane is None:
        raise RuleViolation("surface", f"({pose.x:.1f}, {pose.y:.1f}) is not in a lane")
    return lane


def _driving_pose(scene: Scene, template: AssetInstance, spec: BehaviourSpec, anchor: Anchor,
                  located: bool, others: list[AssetInstance], first: bool) -> Pose:
    """Where a vehicle that will drive a lane starts: at the location asked for, in its lane."""
    if category(template.category).motion != "vehicle":
        resolve_behaviour(scene, template, spec)  # raises the typed "cannot drive" refusal
    lanes = scene.roads.lanes
    if not lanes:
        raise NotFoundError("this world has no lanes to drive")
    lane_id = spec.lane or anchor.lane_id or (anchor.spot.track.id if anchor.spot and anchor.spot.track.kind == "lane" else None)
    if lane_id is not None:
        found = scene.roads.lane(lane_id)
        if found is None:
            raise NotFoundError(f"no lane {lane_id!r}; lanes: {', '.join(ln.id for ln in lanes)}")
        lane = found
    elif anchor.exact:
        lane = lane_at(scene, anchor.x, anchor.y) or min(
            lanes, key=lambda ln: nearest_on_polyline(anchor.x, anchor.y, ln.centreline).distance)
    else:
        lane = min(lanes, key=lambda ln: nearest_on_polyline(anchor.x, anchor.y, ln.centreline).distance)
    if anchor.exact and first:
        return driving_start(scene, template, lane, 0.0, others, exact=(anchor.x, anchor.y))
    if located or spec.lane is None:
        start_arc = nearest_on_polyline(anchor.x, anchor.y, lane.centreline).arc_length
    else:
        start_arc = LANE_ENTRY_M
    return driving_start(scene, template, lane, start_arc, others)
