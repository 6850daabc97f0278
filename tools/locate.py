"""Where things go: naming targets (landmarks, assets, lanes), relations and free-spot search.

A `Location` is what a planner says ("in front of the JTEKT building entrance", "in lane
main_eastbound", "at x=3, y=4"); `resolve_anchor` turns it into a point and a heading, and
`find_free_pose` searches outwards from there for the nearest pose that passes every rule.
"""

from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass, replace
from typing import Literal

from drivetwin.tools.along import Side, TrackPoint, along_point, free_pose_on_track
from drivetwin.tools.errors import NotFoundError, RuleViolation
from drivetwin.tools.rules import assets_near, check_placement, footprints_overlap
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import AssetInstance, Finite, Lane, Pose, Scene
from drivetwin.worlds.surface import (
    lane_at,
    nearest_on_polyline,
    point_along,
    point_in_polygon,
    polyline_length,
    surface_at,
)
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
        description="a landmark name, asset id, lane id, sidewalk id or 'ego'; not needed for "
        "scene_centre or absolute",
    )
    x: Finite | None = Field(None, description="metres east, for relation 'absolute'")
    y: Finite | None = Field(None, description="metres north, for relation 'absolute'")
    distance: float | None = Field(
        None, ge=0.0, le=100.0, description="metres from the target (default: just clear of it)"
    )
    along_m: float | None = Field(
        None, ge=-200.0, le=200.0,
        description="metres along the lane or sidewalk the target stands on: positive ahead (its "
        "direction of travel), negative behind (relation 'behind' also means behind); the "
        "result stays on that lane or sidewalk",
    )
    side: Literal["left", "right"] | None = Field(
        None, description="with along_m: that edge of the lane or sidewalk (facing ahead), or for "
        "a pedestrian or sign ahead of a vehicle, the sidewalk on that side",
    )
    offset_m: float | None = Field(
        None, ge=0.0, le=10.0, description="with side: metres from the centreline (default: at the edge)"
    )
    lane: str | None = Field(
        None, description="with relation 'in_lane' and a landmark or asset target: the lane id to stand "
        "in, at its point nearest the target (default: the lane nearest the target)",
    )


@dataclass(frozen=True)
class Target:
    """A resolved target: where it is, which way it faces, and how big it is."""

    name: str
    kind: Literal["landmark", "area", "asset", "lane", "sidewalk", "centre", "point"]
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
    # The surface is a preference only: with no free spot on it, any spot the rules allow will do.
    surface_preferred: bool = False
    area: list[tuple[float, float]] | None = None
    exact: bool = False
    near: Target | None = None
    # Placement in a named lane searches along that lane only.
    lane_id: str | None = None
    # "N m ahead of X along its lane": placement searches along that track only.
    spot: TrackPoint | None = None


def target_names(scene: Scene) -> list[str]:
    """Every name a target may be given by."""
    names = [n for lm in scene.landmarks for n in lm.names()]
    names += [a.id for a in scene.all_assets()]
    names += [lane.id for lane in scene.roads.lanes]
    names += [walk.id for walk in scene.roads.sidewalks]
    names += [b.name for b in scene.buildings]
    return names


# "12, -3", "x=12 y=-3", "(12.5 -3)": a point given by its coordinates, metres east and north.
_COORDINATES = re.compile(
    r"^\(?\s*(?:x\s*=\s*)?(-?\d+(?:\.\d+)?)\s*[, ]\s*(?:y\s*=\s*)?(-?\d+(?:\.\d+)?)\s*\)?$", re.IGNORECASE
)


def parse_coordinates(text: str) -> tuple[float, float] | None:
    """(x, y) if `text` is a pair of coordinates such as "12, -3" or "x=12 y=-3", else None."""
    match = _COORDINATES.match(text.strip())
    return (float(match.group(1)), float(match.group(2))) if match else None


def resolve_target(scene: Scene, name: str) -> Target:
    """The landmark, asset, lane, building or coordinate pair that `name` refers to."""
    key = name.strip()
    point = parse_coordinates(key)
    if point is not None:
        b = scene.bounds
        if not b.contains(*point):
            raise RuleViolation(
                "bounds", f"({point[0]:g}, {point[1]:g}) is outside the world; allowed: "
                f"x in [{b.xmin:g}, {b.xmax:g}], y in [{b.ymin:g}, {b.ymax:g}] m",
            )
        return Target(f"({point[0]:g}, {point[1]:g})", "point", point[0], point[1], 0.0)
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
    walk = next((w for w in scene.roads.sidewalks if w.id == key), None)
    if walk is not None:  # a sidewalk: its middle, facing along it
        mx, my, heading = point_along(walk.polyline, polyline_length(walk.polyline) / 2)
        return Target(walk.id, "sidewalk", mx, my, heading)
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


def resolve_anchor(scene: Scene, location: Location, new_half_length: float,
                   category_name: str | None = None) -> Anchor:
    """The point, heading and surface need that a Location describes.

    `category_name` is what will stand there: it decides whether a spot "along" the target's
    lane goes in a lane or on a sidewalk.
    """
    rel = location.relation
    if location.along_m is not None or location.side is not None:
        return _along_anchor(scene, location, category_name)
    if rel == "absolute":
        if location.x is None or location.y is None:
            raise NotFoundError("relation 'absolute' needs both x and y (metres)")
        return Anchor(location.x, location.y, 0.0, exact=True)
    if rel == "scene_centre":  # no place said: a bench or a person at the nearest verge, not in the junction
        cx, cy = scene.bounds.centre
        kind = category(category_name) if category_name is not None else None
        off_road = kind is not None and kind.placement != "drivable" and (
            kind.motion == "prop" or (kind.motion == "walker" and "vehicle" not in kind.tags))  # a bicycle rides the road
        return Anchor(cx, cy, 0.0, surface="sidewalk" if off_road else "any", surface_preferred=off_road)
    if location.target is None:
        if rel in ("on_sidewalk", "in_lane"):
            target = resolve_target(scene, "ego")
        else:
            raise NotFoundError(f"relation {rel!r} needs a target (a landmark, asset or lane)")
    else:
        target = resolve_target(scene, location.target)
    if rel == "in_lane":
        return _lane_anchor(scene, target, location.distance, location.lane)
    if rel == "on_sidewalk":
        return _sidewalk_anchor(scene, target)
    if rel == "at" and target.kind == "sidewalk":
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
            x, y = target.x + gap * math.cos(target.heading), target.y + gap * math.sin(target.heading)
            lane = _lane_along(scene, x, y, target.heading) if _is_vehicle(category_name) else None
            if lane is not None:
                # A vehicle whose spot is in a lane faces along it (at a gate, along the lane
                # running in through it): parallel to a gate it stood across the road.
                return Anchor(x, y, nearest_on_polyline(x, y, lane.centreline).heading, near=target)
            return Anchor(x, y, target.heading + math.pi / 2, near=target)
    offsets = {"in_front_of": 0.0, "behind": math.pi, "left_of": math.pi / 2,
               "right_of": -math.pi / 2, "next_to": math.pi / 2}
    direction = target.heading + offsets[rel]
    lateral = rel in ("left_of", "right_of", "next_to")
    own = new_half_length * (0.6 if lateral else 1.0)
    gap = location.distance if location.distance is not None else (
        target.half_length * (0.5 if lateral else 1.0) + own + CLEARANCE_M
    )
    # Ahead of or behind something on the road (debris ahead of the ego): in its lane too.
    lane = lane_at(scene, target.x, target.y) if rel in ("in_front_of", "behind") and target.kind == "asset" else None
    if lane is not None and category_name is not None and category(category_name).placement == "drivable":
        return Anchor(target.x + gap * math.cos(direction), target.y + gap * math.sin(direction),
                      target.heading, surface="lane", near=target, lane_id=lane.id)
    return Anchor(target.x + gap * math.cos(direction), target.y + gap * math.sin(direction),
                  target.heading, near=target)


def _is_vehicle(category_name: str | None) -> bool:
    return category_name is not None and category(category_name).motion == "vehicle"


def _lane_along(scene: Scene, x: float, y: float, heading: float) -> Lane | None:
    """The lane whose strip holds (x, y), the nearest centreline winning and, on the line
    between two, the one running nearer `heading`; None where no lane does."""
    under = [(nearest_on_polyline(x, y, lane.centreline), lane) for lane in scene.roads.lanes]
    under = [(near, lane) for near, lane in under if near.distance <= lane.width / 2 + 1e-6]
    best = min(under, key=lambda item: (round(item[0].distance, 6), -math.cos(item[0].heading - heading)), default=None)
    return None if best is None else best[1]


def _along_anchor(scene: Scene, location: Location, category_name: str | None) -> Anchor:
    if location.relation in ("absolute", "scene_centre") or location.target is None:
        raise NotFoundError("along_m and side need a target (an asset, landmark or lane) to go "
                            "ahead of or behind, and a relation other than absolute or scene_centre")
    target = resolve_target(scene, location.target)
    along = location.along_m or 0.0
    if location.relation == "behind":
        along = -abs(along)
    side: Side | None = location.side
    spot = along_point(
        scene, target.name, target.x, target.y, None if target.kind in ("point", "centre") else target.heading,
        category_name, along, side, location.offset_m, lane_id=target.lane_id or location.lane,
        heading_is_facing=target.kind == "asset",
    )
    pose = spot.pose()
    return Anchor(pose.x, pose.y, spot.yaw, near=target, spot=spot)


def _lane_anchor(scene: Scene, target: Target, distance: float | None, lane_id: str | None = None) -> Anchor:
    lanes = scene.roads.lanes
    if not lanes:
        raise NotFoundError("this world has no lanes")
    lane_id = target.lane_id or lane_id
    if lane_id is not None:
        lane = next((lane for lane in lanes if lane.id == lane_id), None)
        if lane is None:
            raise NotFoundError(f"no lane {lane_id!r}; lanes: {', '.join(ln.id for ln in lanes)}")
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
    """Vehicles face along the lane they stand in (on the line between two, the one running
    nearer the anchor's heading); everything else takes the anchor's heading."""
    cat = category(category_name)
    lane = _lane_along(scene, x, y, anchor.heading) if cat.motion == "vehicle" else None
    return nearest_on_polyline(x, y, lane.centreline).heading if lane is not None else anchor.heading


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
    keep_clear: list[AssetInstance] | None = None,
    slots: int = 1,
) -> Pose:
    """The pose nearest the anchor where `template` passes every placement rule.

    Exact anchors (absolute coordinates) are not moved: they pass or raise. `keep_clear` are
    assets the pose must not overlap even where the rules let it (walkers of one request
    spread out instead of standing on one point); `slots` is how many assets the caller will
    fit around the anchor, widening a search along a track.
    """
    if anchor.spot is not None:
        return free_pose_on_track(scene, template, anchor.spot, [*others, *(keep_clear or [])], yaw, slots)
    if anchor.lane_id is not None:
        return _free_pose_in_lane(scene, template, anchor, anchor.lane_id, others, yaw, keep_clear or [])
    last: RuleViolation | None = None
    steps = 1 if anchor.exact else int(SEARCH_RADIUS_M / SEARCH_STEP_M) + 1
    if anchor.area is not None:
        xs = [p[0] for p in anchor.area]
        ys = [p[1] for p in anchor.area]
        span = max(max(xs) - min(xs), max(ys) - min(ys))
        steps = max(steps, int(span / SEARCH_STEP_M) + 1)
    # Only what stands within reach of the searched disc can overlap a candidate.
    reach = steps * SEARCH_STEP_M + category(template.category).footprint_radius * template.scale
    others = assets_near(others, anchor.x, anchor.y, reach)  # through the grid index
    keep_clear = _within(keep_clear or [], anchor.x, anchor.y, reach)
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
                _check_clear(candidate, keep_clear or [])
            except RuleViolation as exc:
                last = exc
                continue
            return candidate.pose
    if last is not None and anchor.exact:
        raise last
    if anchor.surface_preferred:  # no verge within reach (an imported map): wherever the rules allow
        return find_free_pose(scene, template, replace(anchor, surface="any", surface_preferred=False), others, yaw,
                              keep_clear, slots)
    where = f"({anchor.x:.1f}, {anchor.y:.1f})"
    reason = f" (last refusal: {last})" if last else ""
    raise RuleViolation(
        "no_space",
        f"no free spot for a {template.category} within {SEARCH_RADIUS_M:g} m of {where}{reason}",
    )


def _within(assets: list[AssetInstance], x: float, y: float, reach: float) -> list[AssetInstance]:
    """The assets whose footprints come within `reach` metres of (x, y)."""
    return [a for a in assets if math.hypot(a.pose.x - x, a.pose.y - y)
            <= reach + category(a.category).footprint_radius * a.scale]


# Walkers of one request keep this much apart, so they read as separate people.
SPREAD_GAP_M = 0.3


def _check_clear(candidate: AssetInstance, keep_clear: list[AssetInstance]) -> None:
    for other in keep_clear:
        if other.id != candidate.id and footprints_overlap(candidate, other, tolerance=-SPREAD_GAP_M):
            raise RuleViolation("overlap", f"{candidate.id} would stand on {other.id}")


def _free_pose_in_lane(
    scene: Scene, template: AssetInstance, anchor: Anchor, lane_id: str,
    others: list[AssetInstance], yaw: float | None, keep_clear: list[AssetInstance],
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
                _check_clear(candidate, keep_clear)
            except RuleViolation as exc:
                last = exc
                continue
            return candidate.pose
    raise RuleViolation(
        "no_space", f"no free stretch of lane {lane_id} for a {template.category} ({last})"
    )
