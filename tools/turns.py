"""The turns a vehicle drives off the lanes: pulling out of where it stands, and turning back in a junction box.

A vehicle drives forwards only, turning no tighter than its steering allows, so where it
faces and how much room it has decide where it can go: a car parked in a row between two
others first pulls out ahead, a car facing away from its way turns round in a circle that
must be clear. `driving_route` strings these onto the lanes.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from drivetwin.worlds.routes import PolylineRoute
from drivetwin.worlds.surface import nearest_on_polyline, point_in_polygon

__all__ = ["Departure", "UTurn", "departures", "fillet", "u_turn"]

Point = tuple[float, float]
Sweep = Callable[[Sequence[Point]], bool]

# Turns off the lanes are drawn this much wider than the vehicle's tightest turn (about
# 5 m for a car): pure pursuit cuts a drawn curve, and a curve at full lock leaves it no slack.
TURN_RADIUS_FACTOR = 1.3
# A way out of where the vehicle stands: straight ahead this far (m), then a turn through
# this angle (rad, left positive), then on in a straight line.
PULL_OUT_M = (0.0, 4.0, 8.0)
TURN_ANGLES = (0.0, math.pi / 2, -math.pi / 2, math.pi, -math.pi)
# Curves are drawn as points this many radians apart.
ARC_STEP_RAD = math.pi / 12
# A turn back in a junction box keeps the vehicle's centre this far (m) beyond its half width
# inside the box's edge, and goes into a lane at most this far to its left (the next lane
# but one at most: further ones are another road).
BOX_MARGIN_M = 0.5
MAX_TURN_BACK_SPAN_M = 8.0


@dataclass(frozen=True)
class Departure:
    """A way out of where the vehicle stands: its points from the start to `point`, where it
    then faces `heading`; `length` metres driven, `turned` radians turned on the way."""

    points: list[Point]
    point: Point
    heading: float
    length: float
    turned: float


@dataclass(frozen=True)
class UTurn:
    """A turn back in a junction box: from lane A at arc length `s_in` to lane B at `s_out`."""

    s_in: float
    s_out: float
    points: list[Point]
    length: float


def departures(sweep: Sweep, start: Point, yaw: float, turn_radius: float) -> list[Departure]:
    """The clear ways out of `start` for a vehicle facing `yaw` whose tightest turn has radius
    `turn_radius` (m): every PULL_OUT_M ahead, then every TURN_ANGLES turn, each one that
    `sweep` (whether the vehicle driven along these points hits nothing) passes. Staying put
    comes first."""
    found = []
    for ahead in PULL_OUT_M:
        out = (start[0] + ahead * math.cos(yaw), start[1] + ahead * math.sin(yaw))
        if ahead > 0.0 and not sweep([start, out]):
            break  # further out along a blocked line is blocked too
        for angle in TURN_ANGLES:
            arc = _arc(out, yaw, angle, turn_radius * TURN_RADIUS_FACTOR)
            if arc and not sweep([out, *arc]):
                continue
            points = [start, out, *arc] if ahead > 0.0 else [start, *arc]
            length = ahead + abs(angle) * turn_radius * TURN_RADIUS_FACTOR
            found.append(Departure(points, points[-1], yaw + angle, length, abs(angle)))
    return found


def _arc(start: Point, heading: float, angle: float, radius: float) -> list[Point]:
    """Points along a circle of `radius` from `start` (facing `heading`) turning through
    `angle` (left positive), every ARC_STEP_RAD after the start; [] for no turn."""
    if angle == 0.0:
        return []
    side = math.copysign(1.0, angle)
    cx, cy = start[0] - side * radius * math.sin(heading), start[1] + side * radius * math.cos(heading)
    steps = max(1, math.ceil(abs(angle) / ARC_STEP_RAD))
    return [(cx + side * radius * math.sin(heading + angle * k / steps),
             cy - side * radius * math.cos(heading + angle * k / steps)) for k in range(1, steps + 1)]


def fillet(corner: Point, heading_in: float, heading_out: float, radius: float) -> list[Point]:
    """The arc of `radius` a vehicle drives round a corner of a path, from where it leaves the
    line in (heading `heading_in` to `corner`) to where it meets the line out (`heading_out`),
    R·tan(θ/2) either side of the corner; [corner] where the path does not bend."""
    turn = math.remainder(heading_out - heading_in, math.tau)
    if abs(turn) < 1e-3:
        return [corner]
    back = radius * math.tan(abs(turn) / 2)
    start = (corner[0] - back * math.cos(heading_in), corner[1] - back * math.sin(heading_in))
    return [start, *_arc(start, heading_in, turn, radius)]


def u_turn(lane: PolylineRoute, back: PolylineRoute, box: Sequence[Point], turn_radius: float,
           half_width: float) -> UTurn | None:
    """The turn from `lane` back into `back` inside junction box `box`, or None where `back`
    does not run the other way beside `lane` to its left there, or the turn does not fit.

    The vehicle enters the box along `lane`, swings out to the right and round a circle
    TURN_RADIUS_FACTOR wider than its tightest turn, centred between the two lanes, and
    leaves the box along `back` abeam where it came in.
    """
    entry = _entry(lane, box)
    if entry is None:
        return None
    s_in, (ex, ey) = entry
    heading = lane.heading(s_in)
    fx, fy, lx, ly = math.cos(heading), math.sin(heading), -math.sin(heading), math.cos(heading)
    s_out = back.project(ex, ey)
    bx, by = back.point(s_out)
    span = (bx - ex) * lx + (by - ey) * ly
    if not 0.0 < span <= MAX_TURN_BACK_SPAN_M or math.cos(back.heading(s_out) - heading) > -0.95:
        return None
    radius = turn_radius * TURN_RADIUS_FACTOR
    cx, cy = ex + radius * fx + span / 2 * lx, ey + radius * fy + span / 2 * ly
    steps = math.ceil(math.pi / ARC_STEP_RAD)
    circle = [(cx + radius * (math.cos(t) * fx + math.sin(t) * lx), cy + radius * (math.cos(t) * fy + math.sin(t) * ly))
              for t in (-math.pi / 2 + math.pi * k / steps for k in range(steps + 1))]
    ring = [*box, box[0]]
    if not all(point_in_polygon(x, y, box) and nearest_on_polyline(x, y, ring).distance >= half_width + BOX_MARGIN_M
               for x, y in circle):
        return None
    points = [(ex, ey), *circle, (bx, by)]
    length = sum(math.dist(a, b) for a, b in itertools.pairwise(points))
    return UTurn(s_in, s_out, points, length)


def _entry(lane: PolylineRoute, box: Sequence[Point]) -> tuple[float, Point] | None:
    """Where `lane` first enters `box`: its arc length and point (metre steps, then halved)."""
    s = 0.0
    while s <= lane.length:
        if point_in_polygon(*lane.point(s), box):
            low, high = max(0.0, s - 1.0), s
            for _ in range(6):
                middle = (low + high) / 2
                low, high = (low, middle) if point_in_polygon(*lane.point(middle), box) else (middle, high)
            return high, lane.point(high)
        s += 1.0
    return None
