"""Move Workers: shift or turn an asset, and give it a behaviour (drive, circle, cross, jaywalk).

`BehaviourSpec` is what a planner says ("circle at radius 5 m", "jaywalk in front of the ego");
`resolve_behaviour` turns it into a Scene behaviour with concrete geometry, and where the
behaviour decides where the asset starts (a jaywalker at the kerb), that start pose.
`follow_placement` keeps a driving vehicle's lane true to where a move or placement puts it.
"""

from __future__ import annotations

import difflib
import math
from typing import Literal

from drivetwin.tools.along import driving_start, track_kind_for, tracks
from drivetwin.tools.base import Tool, ToolArgs, ToolResult
from drivetwin.tools.driving_route import driving_route
from drivetwin.tools.errors import NotFoundError, RuleViolation, ToolArgumentError
from drivetwin.tools.locate import Anchor, Location, find_free_pose, resolve_anchor, resolve_target
from drivetwin.tools.rules import check_placement
from drivetwin.worlds.catalog import category
from drivetwin.worlds.edits import UpdateAsset, WorldEdit
from drivetwin.worlds.scene import (
    BEHAVIOUR_KINDS,
    AssetInstance,
    Behaviour,
    Circle,
    CrossRoad,
    DriveLane,
    FollowPath,
    Jaywalk,
    Lane,
    Parked,
    Pose,
    Scene,
)
from drivetwin.worlds.surface import (
    DRIVABLE,
    nearest_on_polyline,
    point_along,
    point_in_polygon,
    polyline_length,
    surface_at,
)
from pydantic import Field

BehaviourKind = Literal["parked", "drive_lane", "follow_path", "circle", "cross_road", "jaywalk"]
# A jaywalker steps out this far ahead of the ego unless told otherwise.
JAYWALK_AHEAD_M = 30.0
# ...and reaches the ego's lane when the ego is still this far away (a hard but fair test).
JAYWALK_GAP_M = 12.0
# Crossings count as "not jaywalking": keep this far from any marked crossing.
CROSSING_KEEP_OUT_M = 4.0
# Points checked around a skidpad circle for a clear, drivable path.
CIRCLE_SAMPLES = 36
DEFAULT_SKIDPAD_RADIUS_M = 5.0
# Where a circle with no centre named may go (open paving), and the grid its centre is sought on.
CIRCLE_AREA_KINDS = ("parking", "plaza")
CIRCLE_GRID_M = 2.0
# A group move covers at most this many assets (a scene holds at most 500).
MAX_GROUP = 500
# A driving vehicle put down in a lane drives it when it faces within this of the lane's
# direction: across the lane (a car turned 90 deg where it stands) steers back into it, beyond
# a right angle it would be driving against the lane's traffic. The 1e-9 absorbs rounding.
LANE_FACING_TOLERANCE_RAD = math.pi / 2 + 1e-9


class BehaviourSpec(ToolArgs):
    """A behaviour as a planner names it; unset fields take sensible defaults."""

    kind: BehaviourKind
    speed: float | None = Field(None, gt=0.0, le=40.0, description="metres per second")
    lane: str | None = Field(None, description="lane id for drive_lane (default: nearest lane)")
    radius: float | None = Field(None, gt=0.5, le=200.0, description="circle radius, metres")
    clockwise: bool = False
    centre: str | None = Field(None, description="landmark or asset to circle around")
    waypoints: list[tuple[float, float]] | None = Field(None, description="[[x, y], ...] metres")
    to: str | None = Field(
        None, description="follow_path: a landmark, asset or 'x, y' to go to from where it starts, "
        "instead of waypoints (a new walker with no location starts some way off, on a sidewalk)"
    )
    start_time: float | None = Field(None, ge=0.0, le=3600.0, description="seconds from now")
    ahead: float | None = Field(
        None, gt=2.0, le=150.0, description="jaywalk: metres ahead of the ego to cross"
    )


def _lane_of(scene: Scene, x: float, y: float) -> Lane:
    if not scene.roads.lanes:
        raise NotFoundError("this world has no lanes")
    return min(scene.roads.lanes, key=lambda ln: nearest_on_polyline(x, y, ln.centreline).distance)


def _kerb(scene: Scene, x: float, y: float, direction: float) -> tuple[float, float]:
    """The first point off the carriageway walking from (x, y) along `direction`."""
    for i in range(1, 60):
        d = i * 0.5
        px, py = x + d * math.cos(direction), y + d * math.sin(direction)
        if surface_at(scene, px, py) not in DRIVABLE:
            return (px + 0.5 * math.cos(direction), py + 0.5 * math.sin(direction))
    raise RuleViolation("surface", f"no kerb within 30 m of ({x:.1f}, {y:.1f})")


def _jaywalk(scene: Scene, spec: BehaviourSpec) -> tuple[Jaywalk, Pose]:
    ego = scene.ego
    lane = _lane_of(scene, ego.pose.x, ego.pose.y)
    here = nearest_on_polyline(ego.pose.x, ego.pose.y, lane.centreline)
    ahead = spec.ahead or JAYWALK_AHEAD_M
    for _ in range(20):
        cx, cy, heading = point_along(lane.centreline, here.arc_length + ahead)
        near_crossing = any(
            nearest_on_polyline(cx, cy, [c.start, c.end]).distance < c.width / 2 + CROSSING_KEEP_OUT_M
            for c in scene.roads.crossings
        )
        if not near_crossing and surface_at(scene, cx, cy) == "lane":
            break
        ahead += 3.0
    else:
        raise RuleViolation("surface", "no stretch of the ego's lane ahead is clear of crossings")
    right, left = heading - math.pi / 2, heading + math.pi / 2
    start, end = _kerb(scene, cx, cy, right), _kerb(scene, cx, cy, left)
    speed = spec.speed or 1.8
    walk_to_lane = math.hypot(start[0] - cx, start[1] - cy)
    ego_speed = ego.behaviour.speed if isinstance(ego.behaviour, DriveLane) else 5.0
    trigger = ego_speed * walk_to_lane / speed + JAYWALK_GAP_M
    behaviour = Jaywalk(start=start, end=end, speed=speed, trigger_distance=min(trigger, 200.0))
    return behaviour, Pose(x=start[0], y=start[1], yaw=left)


def _cross_road(scene: Scene, spec: BehaviourSpec, near: tuple[float, float]) -> tuple[CrossRoad, Pose]:
    if not scene.roads.crossings:
        raise NotFoundError("this world has no pedestrian crossings")
    crossing = min(
        scene.roads.crossings,
        key=lambda c: math.hypot((c.start[0] + c.end[0]) / 2 - near[0], (c.start[1] + c.end[1]) / 2 - near[1]),
    )
    heading = math.atan2(crossing.end[1] - crossing.start[1], crossing.end[0] - crossing.start[0])
    behaviour = CrossRoad(start=crossing.start, end=crossing.end, speed=spec.speed or 1.4,
                          start_time=spec.start_time or 0.0)
    return behaviour, Pose(x=crossing.start[0], y=crossing.start[1], yaw=heading)


def circle_path_clear(scene: Scene, asset: AssetInstance, centre: tuple[float, float], radius: float) -> bool:
    """Whether an asset can drive the whole circle: every sample drivable and free."""
    others = [a for a in scene.all_assets() if a.id != asset.id]
    for k in range(CIRCLE_SAMPLES):
        angle = 2 * math.pi * k / CIRCLE_SAMPLES
        x, y = centre[0] + radius * math.cos(angle), centre[1] + radius * math.sin(angle)
        if not scene.bounds.contains(x, y) or surface_at(scene, x, y) not in DRIVABLE:
            return False
        probe = asset.model_copy(update={"pose": Pose(x=x, y=y, yaw=angle + math.pi / 2)})
        try:
            check_placement(scene, probe, others)
        except RuleViolation:
            return False
    return True


def _distance_to_area(point: tuple[float, float], polygon: list[tuple[float, float]]) -> float:
    """Metres from `point` to a paved area: 0 inside it, else to its nearest edge."""
    if point_in_polygon(point[0], point[1], polygon):
        return 0.0
    return nearest_on_polyline(point[0], point[1], [*polygon, polygon[0]]).distance


def _circle_centres_near(scene: Scene, here: tuple[float, float]) -> list[tuple[float, float]]:
    """Centres to try for a circle with none named: the open paving (parking lots, plazas)
    nearest `here` first, and in each area its points on a CIRCLE_GRID_M grid nearest `here`
    first, so an asset circles where it stands instead of in the first lot of the world."""
    areas = sorted((a for a in scene.roads.paved if a.kind in CIRCLE_AREA_KINDS),
                   key=lambda a: _distance_to_area(here, a.polygon))
    candidates: list[tuple[float, float]] = []
    for area in areas:
        xs = [p[0] for p in area.polygon]
        ys = [p[1] for p in area.polygon]
        nx = int((max(xs) - min(xs)) / CIRCLE_GRID_M)
        ny = int((max(ys) - min(ys)) / CIRCLE_GRID_M)
        grid = [(min(xs) + i * CIRCLE_GRID_M, min(ys) + j * CIRCLE_GRID_M)
                for i in range(nx + 1) for j in range(ny + 1)]
        candidates += sorted(grid, key=lambda p: (math.hypot(p[0] - here[0], p[1] - here[1]), p))
    return candidates


def _circle(scene: Scene, asset: AssetInstance, spec: BehaviourSpec,
            anchor: tuple[float, float] | None) -> tuple[Circle, Pose]:
    radius = spec.radius or DEFAULT_SKIDPAD_RADIUS_M
    candidates: list[tuple[float, float]] = []
    if spec.centre is not None:
        target = resolve_target(scene, spec.centre)
        candidates.append((target.x, target.y))
    elif anchor is not None:
        candidates.append(anchor)
    else:
        candidates = _circle_centres_near(scene, (asset.pose.x, asset.pose.y))
    for cx, cy in candidates:
        if circle_path_clear(scene, asset, (cx, cy), radius):
            behaviour = Circle(centre=(cx, cy), radius=radius, speed=spec.speed or 2.0,
                               clockwise=spec.clockwise)
            yaw = -math.pi / 2 if spec.clockwise else math.pi / 2
            return behaviour, Pose(x=cx + radius, y=cy, yaw=yaw)
    raise RuleViolation(
        "no_space", f"no clear, drivable circle of radius {radius:g} m for {asset.id}; "
        "try a smaller radius or another centre",
    )


def resolve_behaviour(
    scene: Scene, asset: AssetInstance, spec: BehaviourSpec, anchor: tuple[float, float] | None = None
) -> tuple[Behaviour, Pose | None]:
    """The Scene behaviour for `spec` and, where the behaviour fixes it, the asset's start pose."""
    cat = category(asset.category)
    if spec.kind in ("drive_lane", "circle") and not cat.drives:
        raise RuleViolation("behaviour", f"a {cat.name} cannot {spec.kind}; only vehicles, robots and riders drive")
    if spec.kind in ("cross_road", "jaywalk") and cat.motion != "walker":
        raise RuleViolation("behaviour", f"a {cat.name} cannot {spec.kind}; only pedestrians and riders walk")
    if spec.kind == "follow_path" and cat.motion not in ("vehicle", "walker"):
        raise RuleViolation("behaviour", f"a {cat.name} cannot follow a path; only vehicles, robots, riders and pedestrians move")
    if spec.kind == "parked":
        return Parked(), None
    if spec.kind == "drive_lane":
        lane = scene.roads.lane(spec.lane) if spec.lane else _lane_of(scene, asset.pose.x, asset.pose.y)
        if lane is None:
            names = ", ".join(ln.id for ln in scene.roads.lanes)
            raise NotFoundError(f"no lane {spec.lane!r}; lanes: {names}")
        near = nearest_on_polyline(asset.pose.x, asset.pose.y, lane.centreline)
        # off the lane: into it beside where it stands, spaced from what drives it ("make the cars in lot B drive")
        pose = None if near.distance < lane.width / 2 else driving_start(
            scene, asset, lane, near.arc_length, [a for a in scene.all_assets() if a.id != asset.id])
        if pose is None and abs(math.remainder(asset.pose.yaw - near.heading, 2 * math.pi)) > 0.3:
            pose = Pose(x=asset.pose.x, y=asset.pose.y, yaw=near.heading)
        return DriveLane(lane=lane.id, speed=spec.speed or min(5.0, lane.speed_limit)), pose
    if spec.kind == "follow_path":
        waypoints: list[tuple[float, float]] | None = spec.waypoints
        if spec.to and cat.motion == "vehicle":  # it drives the roads there, not across the grass
            waypoints = driving_route(scene, asset, goal_of(scene, asset, spec.to), spec.to)
        elif spec.to:  # a walker or a rider goes straight there: kinematic, nothing stops it
            waypoints = [(asset.pose.x, asset.pose.y), goal_of(scene, asset, spec.to)]
        if not waypoints or len(waypoints) < 2:
            raise RuleViolation("behaviour", "follow_path needs a place to go to or at least two waypoints [[x, y], ...]")
        default = 1.4 if cat.motion == "walker" else 4.0
        return FollowPath(waypoints=waypoints, speed=spec.speed or default,
                          start_time=spec.start_time or 0.0), None
    if spec.kind == "circle":
        return _circle(scene, asset, spec, anchor)
    if spec.kind == "cross_road":
        return _cross_road(scene, spec, anchor or (asset.pose.x, asset.pose.y))
    return _jaywalk(scene, spec)


# A walk to a thing ends this far short of its edge, beside it rather than inside it.
GOAL_SHORT_M = 1.0
# A new walker going somewhere, with no start said, starts this far from where it goes.
WALK_LEAD_M = 12.0


def goal_of(scene: Scene, asset: AssetInstance, name: str) -> tuple[float, float]:
    """Where `asset` going to the target called `name` ends: the place itself, or beside a thing."""
    target = resolve_target(scene, name)
    here = (asset.pose.x, asset.pose.y)
    gap = math.dist(here, (target.x, target.y))
    short = target.half_length + GOAL_SHORT_M if target.kind == "asset" else 0.0
    if gap <= short + 0.5:
        raise RuleViolation("behaviour", f"{asset.id} is already at {target.name}; say where else it should go")
    f = (gap - short) / gap
    return (round(here[0] + f * (target.x - here[0]), 2), round(here[1] + f * (target.y - here[1]), 2))


def start_towards(scene: Scene, category_name: str, name: str) -> Anchor:
    """Where a new walker (or vehicle) going to the target called `name` starts when no place is
    said: the spot of its track kind (a sidewalk, a lane) nearest WALK_LEAD_M from the target, or
    for a walker going to a place further than that from any sidewalk, WALK_LEAD_M from it on the
    way from the nearest sidewalk; facing it."""
    target = resolve_target(scene, name)
    kind = track_kind_for(category(category_name)) or "sidewalk"
    options = tracks(scene, kind)
    nearest = min((nearest_on_polyline(target.x, target.y, t.polyline) for t in options), key=lambda p: p.distance, default=None)
    if nearest is not None and nearest.distance > WALK_LEAD_M and kind == "sidewalk":
        # a place off the sidewalks (a fountain on the grass): WALK_LEAD_M from it, on the way from the nearest sidewalk
        f = WALK_LEAD_M / nearest.distance
        x, y = target.x + f * (nearest.x - target.x), target.y + f * (nearest.y - target.y)
        return Anchor(x, y, math.atan2(target.y - y, target.x - x), surface="any", surface_preferred=False)
    best: tuple[float, float, float] | None = None
    for track in options:
        for step in range(int(polyline_length(track.polyline)) + 1):
            x, y, _ = point_along(track.polyline, float(step))
            miss = abs(math.dist((x, y), (target.x, target.y)) - WALK_LEAD_M)
            if best is None or miss < best[0]:
                best = (miss, x, y)
    if best is None:  # a world without that kind of track: on the ground, towards the world's middle
        cx, cy = scene.bounds.centre
        away = math.atan2(cy - target.y, cx - target.x)
        best = (0.0, target.x + WALK_LEAD_M * math.cos(away), target.y + WALK_LEAD_M * math.sin(away))
    _, x, y = best
    facing = math.atan2(target.y - y, target.x - x)
    return Anchor(x, y, facing, surface=kind, surface_preferred=True)


def follow_placement(scene: Scene, moved: AssetInstance) -> tuple[AssetInstance, str]:
    """`moved` (an asset at its new pose) with a drive_lane behaviour that follows where it now
    stands, and a note saying what changed ("" when nothing did).

    A vehicle that drove a lane and now stands in a lane running the way it faces drives that
    lane, at its old speed (where several are under it, as in a junction, the one it faces
    along best; a vehicle turned across its lane still drives it). Put down off every lane (a parking lot, a
    driveway) it is parked there, which is what a user who moves a car into a lot expects.
    Turned to face against the traffic of every lane it stands in ("spin the ego around") it
    is turned as asked and parked, since it can drive none of them that way; it never keeps a
    lane it no longer stands in or drives one backwards. The note says which happened. Other
    behaviours are left as they are.
    """
    behaviour = moved.behaviour
    if not isinstance(behaviour, DriveLane):
        return moved, ""
    x, y, yaw = moved.pose.x, moved.pose.y, moved.pose.yaw
    under = []
    for lane in scene.roads.lanes:
        near = nearest_on_polyline(x, y, lane.centreline)
        if near.distance <= lane.width / 2:
            under.append((near.distance, lane, near.heading))
    if not under:
        return moved.model_copy(update={"behaviour": Parked()}), (
            f"; {moved.id} stands on no lane there, so it is parked now (it drove {behaviour.lane})"
        )
    facing = [(math.cos(yaw - heading), -d, lane) for d, lane, heading in under
              if abs(math.remainder(yaw - heading, 2 * math.pi)) <= LANE_FACING_TOLERANCE_RAD]
    if not facing:
        names = " and ".join(lane.id for _, lane, _ in under)
        return moved.model_copy(update={"behaviour": Parked()}), (
            f"; facing {math.degrees(yaw) % 360:.0f} deg {moved.id} stands against the traffic of "
            f"{names}, so it is parked now (it drove {behaviour.lane}); to drive that way, put it in "
            "a lane running the way it faces"
        )
    # The lane it faces along best (in a junction the crossing lanes are under it too); on a
    # tie its own lane, then the nearest.
    _, _, lane = max(facing, key=lambda f: (round(f[0], 6), f[2].id == behaviour.lane, f[1]))
    if lane.id == behaviour.lane:
        return moved, ""
    after = moved.model_copy(update={"behaviour": behaviour.model_copy(update={"lane": lane.id})})
    return after, f"; it now drives {lane.id} (was {behaviour.lane})"


def find_asset(scene: Scene, asset_id: str) -> AssetInstance:
    """The asset with this id, or NotFoundError naming the nearest ids."""
    found = scene.asset(asset_id.strip())
    if found is None:
        ids = [a.id for a in scene.all_assets()]
        near = difflib.get_close_matches(asset_id, ids, n=3, cutoff=0.3)
        hint = f"; nearest: {', '.join(near)}" if near else f"; assets: {', '.join(ids[:8])}"
        raise NotFoundError(f"no asset {asset_id!r}{hint}")
    return found


class MoveArgs(ToolArgs):
    asset: str | None = Field(None, description="id of the asset to move, e.g. passenger_car_2 or ego")
    assets: list[str] = Field(
        default_factory=list, max_length=MAX_GROUP,
        description="ids moved together as one group (e.g. all the cones); members may take each "
        "other's old places",
    )
    forward: float = Field(0.0, ge=-100.0, le=100.0, description="metres along its heading")
    left: float = Field(0.0, ge=-100.0, le=100.0, description="metres to its left")
    east: float = Field(0.0, ge=-100.0, le=100.0, description="metres east (+x), whatever its heading")
    north: float = Field(0.0, ge=-100.0, le=100.0, description="metres north (+y), whatever its heading")
    turn_deg: float = Field(0.0, ge=-360.0, le=360.0, description="degrees anticlockwise")
    relative_to: str | None = Field(
        None, description="instead of shifting: put the asset along_m metres ahead of (negative: "
        "behind) this asset or landmark, along the lane or sidewalk it stands on",
    )
    along_m: float = Field(0.0, ge=-200.0, le=200.0, description="with relative_to: metres ahead (+) or behind (-)")
    side: Literal["left", "right"] | None = Field(
        None, description="with relative_to: that edge of the lane or sidewalk, facing ahead"
    )
    offset_m: float | None = Field(
        None, ge=0.0, le=10.0, description="with side: metres from the centreline (default: at the edge)"
    )


def _shifted(asset: AssetInstance, args: MoveArgs) -> AssetInstance:
    p = asset.pose
    c, s = math.cos(p.yaw), math.sin(p.yaw)
    pose = Pose(x=p.x + c * args.forward - s * args.left + args.east,
                y=p.y + s * args.forward + c * args.left + args.north,
                yaw=p.yaw + math.radians(args.turn_deg))
    return asset.model_copy(update={"pose": pose})


class MoveAsset(Tool[MoveArgs]):
    name = "move_asset"
    description = (
        "Shift existing assets (one, or a group moved together) forward/back/left/right or "
        "east/north by metres and/or turn them; or put one N m ahead of/behind another asset or "
        "landmark along its lane (relative_to, along_m, side). A driving vehicle then drives the "
        "lane it stands in, or is parked off every lane."
    )
    family = "move"
    Args = MoveArgs

    def propose(self, args: MoveArgs, scene: Scene) -> ToolResult:
        ids = ([args.asset] if args.asset else []) + [a for a in args.assets if a != args.asset]
        if not ids:
            raise NotFoundError("name the asset to move (asset) or the group (assets)")
        members = [find_asset(scene, a) for a in ids]
        if args.relative_to is not None:
            if len(members) > 1:
                raise ToolArgumentError("relative_to moves one asset; name it in asset and move "
                                        "the others with separate calls")
            return _place_along(scene, members[0], args)
        # One edit for the whole group: the rules see every member at its new place at once,
        # so the result does not depend on the order of the members.
        followed = [follow_placement(scene, _shifted(m, args)) for m in members]
        ops = tuple(UpdateAsset(before=m, after=after) for m, (after, _) in zip(members, followed, strict=True))
        notes = "".join(note for _, note in followed)
        edit = WorldEdit(ops=ops)
        cx = sum(op.after.pose.x for op in ops) / len(ops)
        cy = sum(op.after.pose.y for op in ops) / len(ops)
        if len(ops) == 1:
            text = f"moved {ops[0].after.id} to ({cx:.1f}, {cy:.1f}){notes}"
        else:
            text = f"moved {', '.join(ids)} together; they now centre on ({cx:.1f}, {cy:.1f}){notes}"
        return ToolResult(edit, text, (cx, cy), {"ids": ids})


def _place_along(scene: Scene, asset: AssetInstance, args: MoveArgs) -> ToolResult:
    """Put `asset` along_m metres ahead of (or behind) `relative_to` along its lane or sidewalk."""
    reference = args.relative_to or ""
    if resolve_target(scene, reference).name == asset.id:
        raise ToolArgumentError(f"{asset.id} cannot be placed relative to itself; name another asset or landmark")
    location = Location(relation="at", target=reference, along_m=args.along_m,
                        side=args.side, offset_m=args.offset_m)
    cat = category(asset.category)
    anchor = resolve_anchor(scene, location, cat.length * asset.scale / 2, asset.category)
    others = [a for a in scene.all_assets() if a.id != asset.id]
    yaw = asset.pose.yaw + math.radians(args.turn_deg) if args.turn_deg else None
    pose = find_free_pose(scene, asset, anchor, others, yaw)
    after, note = follow_placement(scene, asset.model_copy(update={"pose": pose}))
    label = anchor.spot.label if anchor.spot else args.relative_to
    return ToolResult(WorldEdit(ops=(UpdateAsset(before=asset, after=after),)),
                      f"moved {asset.id} {label}, to ({pose.x:.1f}, {pose.y:.1f}){note}", (pose.x, pose.y))


class BehaviourArgs(ToolArgs):
    asset: str = Field(description="id of the asset, e.g. pedestrian_1 or ego")
    behaviour: BehaviourSpec


class SetBehaviour(Tool[BehaviourArgs]):
    name = "set_behaviour"
    description = (
        "Give an asset a behaviour: parked, drive_lane, follow_path, circle (skidpad), "
        "cross_road (at a crossing) or jaywalk (cross in front of the ego vehicle)."
    )
    family = "move"
    Args = BehaviourArgs

    def propose(self, args: BehaviourArgs, scene: Scene) -> ToolResult:
        asset = find_asset(scene, args.asset)
        behaviour, pose = resolve_behaviour(scene, asset, args.behaviour)
        after = asset.model_copy(update={"behaviour": behaviour, "pose": pose or asset.pose})
        edit = WorldEdit(ops=(UpdateAsset(before=asset, after=after),))
        focus = (after.pose.x, after.pose.y)
        return ToolResult(edit, f"{asset.id} now does {behaviour.kind}", focus)


__all__ = ["BEHAVIOUR_KINDS", "BehaviourSpec", "MoveAsset", "SetBehaviour",
           "find_asset", "follow_placement", "resolve_behaviour"]
