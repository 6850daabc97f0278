"""Positions along a lane or sidewalk: "10 m ahead of the ego on the right", "a car driving in lane X".

A position "N m ahead of X" follows the lane or sidewalk X stands on (its direction of travel is
"ahead"), so the result lands on that lane or sidewalk instead of cutting across a bend or a
verge. Driving vehicles start on their lane's centreline, spaced along it by a headway.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Literal

from drivetwin.tools.errors import NotFoundError, RuleViolation
from drivetwin.tools.rules import check_placement
from drivetwin.worlds.catalog import Category, category
from drivetwin.worlds.scene import AssetInstance, DriveLane, Lane, Pose, Scene
from drivetwin.worlds.surface import lane_at, nearest_on_polyline, point_along, polyline_length

Point = tuple[float, float]
TrackKind = Literal["lane", "sidewalk"]
Side = Literal["left", "right"]
# Two lanes this close to a landmark count as equally near; its heading picks between them.
TIE_M = 0.5
# A blocked spot "N m ahead" may shift this far along the track (per asset of the call).
ALONG_TOLERANCE_M = 4.0
ALONG_STEP_M = 0.5
# Room kept inside a lane or sidewalk edge for an asset put "on the right/left side".
EDGE_MARGIN_M = 0.2
# Gap between driving vehicles queued in one lane: about 1 s at the 5 m/s default speed.
DRIVING_GAP_M = 6.0
# A vehicle told only "drive in lane X" starts this far after the lane's start, where traffic
# enters the world, so it drives the lane's whole length in view.
LANE_ENTRY_M = 20.0
# How far along a lane a driving vehicle's start may be searched for.
LANE_SEARCH_M = 80.0


@dataclass(frozen=True)
class Track:
    """A lane or sidewalk as a polyline with a width."""

    id: str
    kind: TrackKind
    polyline: list[Point]
    width: float


@dataclass(frozen=True)
class TrackPoint:
    """A spot on a track: arc length along it, metres left of its centreline, and a heading."""

    track: Track
    arc: float
    lateral: float
    yaw: float
    label: str

    def pose(self, shift: float = 0.0) -> Pose:
        """The pose `shift` metres further along the track, at the same lateral offset."""
        x, y, heading = point_along(self.track.polyline, self.arc + shift)
        return Pose(x=x - self.lateral * math.sin(heading), y=y + self.lateral * math.cos(heading),
                    yaw=self.yaw)


def tracks(scene: Scene, kind: TrackKind) -> list[Track]:
    if kind == "lane":
        return [Track(ln.id, "lane", list(ln.centreline), ln.width) for ln in scene.roads.lanes]
    return [Track(w.id, "sidewalk", list(w.polyline), w.width) for w in scene.roads.sidewalks]


def track_kind_for(cat: Category) -> TrackKind | None:
    """Where a category goes along a road: drivable things in lanes, walkers and signs on
    sidewalks; None for things that may stand on either (benches, bins)."""
    if cat.placement == "drivable":
        return "lane"
    if cat.placement == "sidewalk" or cat.motion == "walker":
        return "sidewalk"
    return None


def _track_under(scene: Scene, x: float, y: float) -> Track | None:
    lane = lane_at(scene, x, y)
    if lane is not None:
        return Track(lane.id, "lane", list(lane.centreline), lane.width)
    for walk in tracks(scene, "sidewalk"):
        if nearest_on_polyline(x, y, walk.polyline).distance <= walk.width / 2:
            return walk
    return None


def _nearest_track(options: Sequence[Track], x: float, y: float, heading: float | None) -> Track:
    """The nearest track; among near-equal ones the one best aligned with `heading`."""
    dist = {t.id: nearest_on_polyline(x, y, t.polyline).distance for t in options}
    best = min(dist.values())
    close = [t for t in options if dist[t.id] <= best + TIE_M]
    if heading is None or len(close) == 1:
        return min(close, key=lambda t: dist[t.id])
    return max(close, key=lambda t: math.cos(nearest_on_polyline(x, y, t.polyline).heading - heading))


def along_point(
    scene: Scene, name: str, x: float, y: float, heading: float | None, category_name: str | None,
    along_m: float, side: Side | None = None, offset_m: float | None = None,
    lane_id: str | None = None, heading_is_facing: bool = False,
) -> TrackPoint:
    """The spot `along_m` metres ahead (negative: behind) of a target along its lane or sidewalk.

    `heading` is the target's facing (an asset's yaw) when `heading_is_facing`, else a hint that
    picks between equally near lanes (a landmark's heading). `side` puts the spot at that edge
    of the track (facing ahead) or, when the category belongs on another kind of track (a
    pedestrian ahead of a car), picks the track on that side.
    """
    cat = category(category_name) if category_name else None
    wanted = track_kind_for(cat) if cat else None
    if lane_id is not None:
        lane = scene.roads.lane(lane_id)
        if lane is None:
            raise NotFoundError(f"no lane {lane_id!r}")
        guide: Track | None = Track(lane.id, "lane", list(lane.centreline), lane.width)
    else:
        guide = _track_under(scene, x, y)
    if guide is None:
        options = tracks(scene, wanted or "lane") or tracks(scene, "sidewalk")
        if not options:
            raise NotFoundError("this world has no lanes or sidewalks to place along")
        guide = _nearest_track(options, x, y, heading)
    here = nearest_on_polyline(x, y, guide.polyline)
    sign = 1 if heading is None or not heading_is_facing or math.cos(heading - here.heading) >= 0 else -1
    arc = here.arc_length + sign * along_m
    length = polyline_length(guide.polyline)
    word = "ahead of" if along_m >= 0 else "behind"
    if not 0.0 <= arc <= length:
        room = length - here.arc_length if sign * along_m > 0 else here.arc_length
        raise RuleViolation(
            "bounds", f"{guide.id} runs on only {room:.0f} m {word} {name}; "
            f"ask for at most {math.floor(room)} m",
        )
    gx, gy, track_heading = point_along(guide.polyline, arc)
    facing = track_heading if sign > 0 else track_heading + math.pi
    label = f"{abs(along_m):g} m {word} {name}"
    if wanted is not None and wanted != guide.kind:
        options = tracks(scene, wanted)
        if side is not None:
            normal = facing + (math.pi / 2 if side == "left" else -math.pi / 2)
            on_side = [t for t in options if _on_side(t, gx, gy, normal)]
            options = on_side or options
        if not options:
            raise NotFoundError(f"this world has no {wanted}s to put it on")
        dest = _nearest_track(options, gx, gy, facing)
        near = nearest_on_polyline(gx, gy, dest.polyline)
        dest_sign = 1 if math.cos(facing - near.heading) >= 0 else -1
        yaw = near.heading if dest_sign > 0 else near.heading + math.pi
        return TrackPoint(dest, near.arc_length, 0.0, yaw, f"{label} on {dest.id}")
    lateral = 0.0
    if side is not None:
        own_half_width = cat.width / 2 if cat else 0.0
        edge = max(0.0, guide.width / 2 - own_half_width - EDGE_MARGIN_M)
        # Left of the facing direction; the track's own left flips when facing against it.
        lateral = (offset_m if offset_m is not None else edge) * (1 if side == "left" else -1) * sign
    yaw = track_heading if cat is not None and cat.motion == "vehicle" and guide.kind == "lane" else facing
    where = f", {side} side" if side else ""
    return TrackPoint(guide, arc, lateral, yaw, f"{label} along {guide.id}{where}")


def _on_side(track: Track, x: float, y: float, normal: float) -> bool:
    near = nearest_on_polyline(x, y, track.polyline)
    return (near.x - x) * math.cos(normal) + (near.y - y) * math.sin(normal) > 0.0


def free_pose_on_track(
    scene: Scene, template: AssetInstance, spot: TrackPoint, others: list[AssetInstance],
    yaw: float | None = None, slots: int = 1,
) -> Pose:
    """The free pose nearest `spot` along its track; raises a RuleViolation naming why none is."""
    tolerance = ALONG_TOLERANCE_M + (slots - 1) * (category(template.category).length + 1.0)
    last: RuleViolation | None = None
    for k in range(int(tolerance / ALONG_STEP_M) + 1):
        for shift in ((0.0,) if k == 0 else (k * ALONG_STEP_M, -k * ALONG_STEP_M)):
            pose = spot.pose(shift)
            if yaw is not None:
                pose = pose.model_copy(update={"yaw": yaw})
            candidate = template.model_copy(update={"pose": pose})
            try:
                check_placement(scene, candidate, others)
            except RuleViolation as exc:
                last = exc
                continue
            return pose
    raise RuleViolation(
        "no_space", f"no free spot for a {template.category} {spot.label} "
        f"(searched ±{tolerance:g} m along it): {last}",
    )


def _driving_arcs(scene: Scene, lane: Lane, others: list[AssetInstance]) -> list[tuple[float, float]]:
    """(arc length, half length) of every vehicle driving `lane` or standing in it."""
    out = []
    for other in others:
        drives_here = isinstance(other.behaviour, DriveLane) and other.behaviour.lane == lane.id
        # The lane lookup (a spatial query) only for vehicles: a world's thousands of props skip it.
        stands_here = not drives_here and category(other.category).motion == "vehicle" and (
            (under := lane_at(scene, other.pose.x, other.pose.y)) is not None and under.id == lane.id)
        if drives_here or stands_here:
            near = nearest_on_polyline(other.pose.x, other.pose.y, lane.centreline)
            out.append((near.arc_length, category(other.category).length * other.scale / 2))
    return out


def driving_start(
    scene: Scene, template: AssetInstance, lane: Lane, start_arc: float,
    others: list[AssetInstance], exact: Point | None = None,
) -> Pose:
    """Where a vehicle that will drive `lane` starts: on its centreline at `start_arc`, or the
    nearest spot behind or ahead of it that keeps DRIVING_GAP_M from the vehicles in the lane.

    With `exact` (coordinates the caller gave) the vehicle starts exactly there or is refused.
    """
    half = category(template.category).length * template.scale / 2
    queue = _driving_arcs(scene, lane, others)

    def refusal(arc: float) -> str | None:
        for other_arc, other_half in queue:
            if abs(arc - other_arc) < half + other_half + DRIVING_GAP_M:
                return f"it would be within {DRIVING_GAP_M:g} m of a vehicle in {lane.id}"
        return None

    if exact is not None:
        near = nearest_on_polyline(exact[0], exact[1], lane.centreline)
        if near.distance > lane.width / 2:
            raise RuleViolation(
                "surface", f"({exact[0]:g}, {exact[1]:g}) is not in lane {lane.id}; a driving vehicle "
                f"starts in its lane (nearest point of it: ({near.x:.1f}, {near.y:.1f}))",
            )
        candidate = template.model_copy(update={"pose": Pose(x=exact[0], y=exact[1], yaw=near.heading)})
        check_placement(scene, candidate, others)
        reason = refusal(near.arc_length)
        if reason:
            raise RuleViolation("overlap", f"a {template.category} cannot start at "
                                f"({exact[0]:g}, {exact[1]:g}): {reason}; choose a free spot")
        return candidate.pose
    length = polyline_length(lane.centreline)
    last = "the lane is full"
    for k in range(int(LANE_SEARCH_M / ALONG_STEP_M) + 1):
        # Behind first: vehicles asked for at one spot queue up behind the first.
        for arc in ((start_arc,) if k == 0 else (start_arc - k * ALONG_STEP_M, start_arc + k * ALONG_STEP_M)):
            if not half <= arc <= length - half:
                continue
            reason = refusal(arc)
            if reason:
                last = reason
                continue
            x, y, heading = point_along(lane.centreline, arc)
            candidate = template.model_copy(update={"pose": Pose(x=x, y=y, yaw=heading)})
            try:
                check_placement(scene, candidate, others)
            except RuleViolation as exc:
                last = str(exc)
                continue
            return candidate.pose
    raise RuleViolation(
        "no_space", f"no free start for a driving {template.category} in {lane.id} within "
        f"{LANE_SEARCH_M:g} m ({last}); remove a vehicle or choose another lane",
    )
