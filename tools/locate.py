"""Where things go: naming targets (landmarks, assets, lanes), relations and free-spot search.

A `Location` is what a planner says ("in front of the JTEKT building entrance", "in lane
main_eastbound", "at x=3, y=4"); `resolve_anchor` turns it into a point and a heading, and
`find_free_pose` searches outwards from there for the nearest pose that passes every rule.
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass
from typing import Literal

from drivetwin.tools.errors import NotFoundError, RuleViolation
from drivetwin.tools.rules import check_placement
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import AssetInstance, Finite, Pose, Scene
from drivetwin.worlds.surface import nearest_on_polyline, point_along, point_in_polygon, surface_at
from pydantic import BaseModel, ConfigDict, Field

Relation = Literal[
    "at", "in_front_of", "behind", "left_of", "right_of", "next_to",
    "scene_centre", "on_sidewalk", "in_lane", "absolute",
]
RELATIONS: tuple[str, ...] = (
    "at", "in_front_of", "behind", "left_of", "right_of", "next_to",
    "scene_centre", "on_sidewalk", "in_lane", "absolute",
)
# Gap left between a placed asset and what it is placed relative to.
CLEARANCE_M = 1.0
# Free-spot search: rings every SEARCH_STEP_M out to SEARCH_RADIUS_M around the anchor.
SEARCH_STEP_M = 0.5
SEARCH_RADIUS_M = 12.0
# Along a named lane the search may go further: lanes are long and narrow.
LANE_SEARCH_M = 80.0


class Location(BaseModel):
    """Where to put something: a relation to a target, or absolute coordinates."""

    model_config = ConfigDict(extra="forbid")

    relation: Relation = Field(
        "at",
        description="how the position relates to the target; 'absolute' uses x and y",
    )
    target: str | None = Field(
        None,
        description="a landmark name, asset id, lane id or 'ego'; not needed for "
        "scene_centre or absolute",
    )
    x: Finite | None = Field(None, description="metres east, for relation 'absolute'")
    y: Finite | None = Field(None, description="metres north, for relation 'absolute'")
    distance: float | None = Field(
        None, ge=0.0, le=100.0, description="metres from the target (default: just clear of it)"
    )


@dataclass(frozen=True)
class Target:
    """A resolved target: where it is, which way it faces, and how big it is."""

    name: str
    kind: Literal["landmark", "area", "asset", "lane", "centre"]
    x: float
    y: float
    heading: float
    half_length: float = 0.0
    polygon: list[tuple[float, float]] | None = None
    lane_id: str | None = None


@dataclass(frozen=True)
class Anchor:
    """A point to search from, the heading a placed asset should take, and a surface need."""

    x: float
    y: float
    heading: float
    surface: Literal["any", "lane", "sidewalk"] = "any"
    area: list[tuple[float, float]] | None = None
    exact: bool = False
    near: Target | None = None
    # Placement in a named lane searches along that lane only.
    lane_id: str | None = None


def target_names(scene: Scene) -> list[str]:
    """Every name a target may be given by."""
    names = [n for lm in scene.landmarks for n in lm.names()]
    names += [a.id for a in scene.all_assets()]
    names += [lane.id for lane in scene.roads.lanes]
    names += [b.name for b in scene.buildings]
    return names


def resolve_target(scene: Scene, name: str) -> Target:
    """The landmark, asset, lane or building that `name` refers to."""
    key = name.strip()
    asset = scene.asset(key) or scene.asset(key.lower().replace(" ", "_"))
    if asset is not None:
        cat = category(asset.category)
        return Target(asset.id, "asset", asset.pose.x, asset.pose.y, asset.pose.yaw,
                      cat.length * asset.scale / 2)
    if key.lower() in ("ego", "ego vehicle", "the ego vehicle", "ego car"):
        return resolve_target(scene, "ego")
    landmark = scene.landmark(key)
    if landmark is not None:
        kind: Literal["landmark", "area"] = "area" if landmark.kind == "area" else "landmark"
        x, y = landmark.position
        return Target(landmark.name, kind, x, y, landmark.heading, polygon=landmark.polygon)
    lane = scene.roads.lane(key)
    if lane is not None:
        (x1, y1), (x2, y2) = lane.centreline[0], lane.centreline[1]
        mid = len(lane.centreline) // 2
        mx, my = lane.centreline[mid] if len(lane.centreline) > 2 else ((x1 + x2) / 2, (y1 + y2) / 2)
        return Target(lane.id, "lane", mx, my, math.atan2(y2 - y1, x2 - x1), lane_id=lane.id)
    for building in scene.buildings:
        if key.lower() in (building.name.lower(), building.id):
            xs = [p[0] for p in building.footprint]
            ys = [p[1] for p in building.footprint]
            return Target(building.name, "area", sum(xs) / len(xs), sum(ys) / len(ys), 0.0,
                          polygon=building.footprint)
    if key.lower().replace("center", "centre") in ("scene centre", "centre", "the centre"):
        cx, cy = scene.bounds.centre
        return Target("scene centre", "centre", cx, cy, 0.0)
    nearest = difflib.get_close_matches(key, target_names(scene), n=3, cutoff=0.4)
    hint = f"; nearest: {', '.join(nearest)}" if nearest else ""
    raise NotFoundError(f"no landmark, asset or lane called {name!r}{hint}")


def resolve_anchor(scene: Scene, location: Location, new_half_length: float) -> Anchor:
    """The point, heading and surface need that a Location describes."""
    rel = location.relation
    if rel == "absolute":
        if location.x is None or location.y is None:
            raise NotFoundError("relation 'absolute' needs both x and y (metres)")
        return Anchor(location.x, location.y, 0.0, exact=True)
    if rel == "scene_centre":
        cx, cy = scene.bounds.centre
        return Anchor(cx, cy, 0.0)
    if location.target is None:
        if rel in ("on_sidewalk", "in_lane"):
            target = resolve_target(scene, "ego")
        else:
            raise NotFoundError(f"relation {rel!r} needs a target (a landmark, asset or lane)")
    else:
        target = resolve_target(scene, location.target)
    if rel == "in_lane":
        return _lane_anchor(scene, target, location.distance)
    if rel == "on_sidewalk":
        return _sidewalk_anchor(scene, target)
    if rel == "at":
        if target.kind in ("area", "centre"):
            return Anchor(target.x, target.y, target.heading, area=target.polygon, near=target)
        if target.kind == "lane":
            return _lane_anchor(scene, target, location.distance)
        if target.kind == "asset":
            rel = "next_to"
        else:
            # At a point landmark: just out from it along its facing, parallel to its front.
            gap = (location.distance or 0.0) + CLEARANCE_M + new_half_length * 0.5
            return Anchor(target.x + gap * math.cos(target.heading),
                          target.y + gap * math.sin(target.heading),
                          target.heading + math.pi / 2, near=target)
    offsets = {"in_front_of": 0.0, "behind": math.pi, "left_of": math.pi / 2,
               "right_of": -math.pi / 2, "next_to": math.pi / 2}
    direction = target.heading + offsets[rel]
    lateral = rel in ("left_of", "right_of", "next_to")
    own = new_half_length * (0.6 if lateral else 1.0)
    gap = location.distance if location.distance is not None else (
        target.half_length * (0.5 if lateral else 1.0) + own + CLEARANCE_M
    )
    return Anchor(target.x + gap * math.cos(direction), target.y + gap * math.sin(direction),
                  target.heading, near=target)


def _lane_anchor(scene: Scene, target: Target, distance: float | None) -> Anchor:
    lanes = scene.roads.lanes
    if not lanes:
        raise NotFoundError("this world has no lanes")
    if target.lane_id is not None:
        lane = next(lane for lane in lanes if lane.id == target.lane_id)
    else:
        lane = min(lanes, key=lambda ln: nearest_on_polyline(target.x, target.y, ln.centreline).distance)
    near = nearest_on_polyline(target.x, target.y, lane.centreline)
    ahead = distance if distance is not None else 0.0
    x = near.x + ahead * math.cos(near.heading)
    y = near.y + ahead * math.sin(near.heading)
    return Anchor(x, y, near.heading, surface="lane", near=target, lane_id=lane.id)


def _sidewalk_anchor(scene: Scene, target: Target) -> Anchor:
    walks = scene.roads.sidewalks
    if not walks:
        raise NotFoundError("this world has no sidewalks")
    best = min(
        (nearest_on_polyline(target.x, target.y, w.polyline) for w in walks),
        key=lambda p: p.distance,
    )
    return Anchor(best.x, best.y, best.heading, surface="sidewalk", near=target)


def default_yaw(scene: Scene, category_name: str, anchor: Anchor, x: float, y: float) -> float:
    """Vehicles face along the lane they stand in; everything else takes the anchor's heading."""
    cat = category(category_name)
    if cat.motion == "vehicle" and scene.roads.lanes:
        lane = min(scene.roads.lanes, key=lambda ln: nearest_on_polyline(x, y, ln.centreline).distance)
        near = nearest_on_polyline(x, y, lane.centreline)
        if near.distance <= lane.width / 2:
            return near.heading
    return anchor.heading


def _ring(radius: float) -> list[tuple[float, float]]:
    if radius == 0.0:
        return [(0.0, 0.0)]
    n = max(8, int(2 * math.pi * radius / SEARCH_STEP_M))
    return [(radius * math.cos(2 * math.pi * k / n), radius * math.sin(2 * math.pi * k / n))
            for k in range(n)]


def find_free_pose(
    scene: Scene,
    template: AssetInstance,
    anchor: Anchor,
    others: list[AssetInstance],
    yaw: float | None = None,
) -> Pose:
    """The pose nearest the anchor where `template` passes every placement rule.

    Exact anchors (absolute coordinates) are not moved: they pass or raise.
    """
    if anchor.lane_id is not None:
        return _free_pose_in_lane(scene, template, anchor, anchor.lane_id, others, yaw)
    last: RuleViolation | None = None
    steps = 1 if anchor.exact else int(SEARCH_RADIUS_M / SEARCH_STEP_M) + 1
    if anchor.area is not None:
        xs = [p[0] for p in anchor.area]
        ys = [p[1] for p in anchor.area]
        span = max(max(xs) - min(xs), max(ys) - min(ys))
        steps = max(steps, int(span / SEARCH_STEP_M) + 1)
    for i in range(steps):
        for dx, dy in _ring(i * SEARCH_STEP_M):
            x, y = anchor.x + dx, anchor.y + dy
            if anchor.area is not None and not point_in_polygon(x, y, anchor.area):
                continue
            if anchor.surface == "lane" and surface_at(scene, x, y) not in ("lane", "crossing"):
                continue
            if anchor.surface == "sidewalk" and surface_at(scene, x, y) != "sidewalk":
                continue
            heading = yaw if yaw is not None else default_yaw(scene, template.category, anchor, x, y)
            candidate = template.model_copy(update={"pose": Pose(x=x, y=y, yaw=heading)})
            try:
                check_placement(scene, candidate, others)
            except RuleViolation as exc:
                last = exc
                continue
            return candidate.pose
    if last is not None and anchor.exact:
        raise last
    where = f"({anchor.x:.1f}, {anchor.y:.1f})"
    reason = f" (last refusal: {last})" if last else ""
    raise RuleViolation(
        "no_space",
        f"no free spot for a {template.category} within {SEARCH_RADIUS_M:g} m of {where}{reason}",
    )


def _free_pose_in_lane(
    scene: Scene, template: AssetInstance, anchor: Anchor, lane_id: str,
    others: list[AssetInstance], yaw: float | None,
) -> Pose:
    """The free pose on the lane's centreline nearest the anchor, searching both ways along it."""
    lane = scene.roads.lane(lane_id)
    if lane is None:
        raise NotFoundError(f"no lane {lane_id!r}")
    start = nearest_on_polyline(anchor.x, anchor.y, lane.centreline).arc_length
    last: RuleViolation | None = None
    for k in range(int(LANE_SEARCH_M / SEARCH_STEP_M) + 1):
        for sign in (1, -1):
            x, y, heading = point_along(lane.centreline, start + sign * k * SEARCH_STEP_M)
            candidate = template.model_copy(
                update={"pose": Pose(x=x, y=y, yaw=heading if yaw is None else yaw)}
            )
            try:
                check_placement(scene, candidate, others)
            except RuleViolation as exc:
                last = exc
                continue
            return candidate.pose
    raise RuleViolation(
        "no_space", f"no free stretch of lane {lane_id} for a {template.category} ({last})"
    )
