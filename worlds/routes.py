"""Paths that behaviours follow, parameterised by arc length: polylines and circles.

Vehicles steer towards a point a lookahead distance along the route from their projection
on it (pure pursuit); walkers are placed at the point `speed · elapsed` along it.
"""

from __future__ import annotations

import bisect
import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

__all__ = [
    "CircleRoute",
    "NoJunctionError",
    "OffsetRoute",
    "PolylineRoute",
    "Route",
    "junction_route",
    "segment_polyline_intersection",
]

# A junction turn's exit lane must leave within this angle of the asked turn (90° left or
# right, 0° straight on); a U-turn is never a junction turn.
TURN_TOLERANCE_RAD = math.pi / 4
# Lanes are sampled this finely (m) to find where they enter and leave a junction box.
JUNCTION_SAMPLE_M = 0.5
# Points on a turn's curve through the junction (a quadratic Bézier).
TURN_CURVE_POINTS = 16
# A vehicle following a route looks for itself at most this far (m) ahead of where it was a
# moment ago, and this far back: a route that passes near itself again (a U-turn, out of a
# car park and back past it) is followed in order, not jumped along to where it passes again.
FOLLOW_AHEAD_M = 8.0
FOLLOW_BACK_M = 2.0


class Route:
    """A path in the plane parameterised by arc length s ∈ [0, length]."""

    length: float
    closed: bool

    def point(self, s: float) -> tuple[float, float]:
        """The point at arc length s (wrapped on a closed route, clamped on an open one)."""
        raise NotImplementedError

    def heading(self, s: float) -> float:
        """The direction of travel (yaw, rad) at arc length s."""
        raise NotImplementedError

    def project(self, x: float, y: float) -> float:
        """The arc length of the route point nearest to (x, y)."""
        raise NotImplementedError

    def follow(self, x: float, y: float, s_last: float) -> float:
        """The arc length of the route point nearest to (x, y) within FOLLOW_BACK_M behind and
        FOLLOW_AHEAD_M ahead of `s_last` (where the vehicle was a moment ago)."""
        return self.project(x, y)

    def wrap(self, s: float) -> float:
        if self.closed:
            return s % self.length
        return min(max(s, 0.0), self.length)


@dataclass
class PolylineRoute(Route):
    """Straight segments through waypoints; `closed` joins the last point to the first."""

    waypoints: Sequence[Sequence[float]]
    closed: bool = False
    # Plain Python floats: a route is queried a few times per tick, where numpy's per-call
    # overhead would dominate.
    _points: list[tuple[float, float]] = field(init=False, repr=False)
    _cumulative: list[float] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        raw = [(float(p[0]), float(p[1])) for p in self.waypoints]
        if self.closed and raw and math.dist(raw[0], raw[-1]) > 1e-9:
            raw.append(raw[0])
        points = raw[:1]
        for point in raw[1:]:
            if math.dist(point, points[-1]) > 1e-9:
                points.append(point)
        if len(points) < 2:
            raise ValueError("a route needs two distinct waypoints")
        self._points = points
        self._cumulative = [0.0]
        for a, b in itertools.pairwise(points):
            self._cumulative.append(self._cumulative[-1] + math.dist(a, b))
        self.length = self._cumulative[-1]

    def _segment(self, s: float) -> tuple[int, float]:
        s = self.wrap(s)
        index = bisect.bisect_right(self._cumulative, s) - 1
        index = min(max(index, 0), len(self._points) - 2)
        return index, s - self._cumulative[index]

    def point(self, s: float) -> tuple[float, float]:
        index, along = self._segment(s)
        (ax, ay), (bx, by) = self._points[index], self._points[index + 1]
        t = along / (self._cumulative[index + 1] - self._cumulative[index])
        return ax + t * (bx - ax), ay + t * (by - ay)

    def heading(self, s: float) -> float:
        index, _ = self._segment(s)
        (ax, ay), (bx, by) = self._points[index], self._points[index + 1]
        return math.atan2(by - ay, bx - ax)

    def project(self, x: float, y: float) -> float:
        return self._nearest(x, y, 0.0, self.length)

    def follow(self, x: float, y: float, s_last: float) -> float:
        if self.closed:
            return self.project(x, y)
        return self._nearest(x, y, s_last - FOLLOW_BACK_M, s_last + FOLLOW_AHEAD_M)

    def _nearest(self, x: float, y: float, s_from: float, s_to: float) -> float:
        """The arc length in [s_from, s_to] of the route point nearest to (x, y)."""
        best, best_s = math.inf, min(max(s_from, 0.0), self.length)
        for index, ((ax, ay), (bx, by)) in enumerate(itertools.pairwise(self._points)):
            s0, s1 = self._cumulative[index], self._cumulative[index + 1]
            if s1 < s_from or s0 > s_to:
                continue
            dx, dy = bx - ax, by - ay
            length = s1 - s0
            t_from, t_to = max(0.0, (s_from - s0) / length), min(1.0, (s_to - s0) / length)
            t = min(t_to, max(t_from, ((x - ax) * dx + (y - ay) * dy) / (length * length)))
            distance2 = (ax + t * dx - x) ** 2 + (ay + t * dy - y) ** 2
            if distance2 < best:
                best, best_s = distance2, s0 + t * length
        return best_s

    def distance_to(self, x: float, y: float) -> float:
        """Distance from (x, y) to the nearest point of the route."""
        px, py = self.point(self.project(x, y))
        return math.hypot(x - px, y - py)

    @property
    def start(self) -> tuple[float, float]:
        return self._points[0]


@dataclass
class CircleRoute(Route):
    """A circle about `centre` of `radius`, driven anticlockwise unless `clockwise`."""

    centre: tuple[float, float]
    radius: float
    clockwise: bool = False
    closed: bool = True

    def __post_init__(self) -> None:
        self.length = 2.0 * math.pi * self.radius

    @property
    def _sense(self) -> float:
        return -1.0 if self.clockwise else 1.0

    def point(self, s: float) -> tuple[float, float]:
        angle = self._sense * s / self.radius
        return (
            self.centre[0] + self.radius * math.cos(angle),
            self.centre[1] + self.radius * math.sin(angle),
        )

    def heading(self, s: float) -> float:
        return self._sense * s / self.radius + self._sense * math.pi / 2

    def project(self, x: float, y: float) -> float:
        angle = math.atan2(y - self.centre[1], x - self.centre[0])
        return (self._sense * angle * self.radius) % self.length


def segment_polyline_intersection(
    a: Sequence[float], b: Sequence[float], polyline: Sequence[Sequence[float]]
) -> tuple[float, float] | None:
    """Where segment a→b first crosses `polyline` (from a), or None if it does not."""
    p = np.asarray(a, dtype=float)
    r = np.asarray(b, dtype=float) - p
    best: tuple[float, tuple[float, float]] | None = None
    for q0, q1 in itertools.pairwise(polyline):
        q = np.asarray(q0, dtype=float)
        s = np.asarray(q1, dtype=float) - q
        denominator = r[0] * s[1] - r[1] * s[0]
        if abs(denominator) < 1e-12:
            continue
        qp = q - p
        t = (qp[0] * s[1] - qp[1] * s[0]) / denominator
        u = (qp[0] * r[1] - qp[1] * r[0]) / denominator
        if 0.0 <= t <= 1.0 and 0.0 <= u <= 1.0 and (best is None or t < best[0]):
            hit = p + t * r
            best = (float(t), (float(hit[0]), float(hit[1])))
    return None if best is None else best[1]


@dataclass
class OffsetRoute(Route):
    """A base route shifted sideways: from `d_from` to `d_to` metres (left positive) between
    arc lengths `s_start` and `s_start + span`, with a smooth (cosine) blend: a lane change."""

    base: Route
    s_start: float
    span: float
    d_from: float
    d_to: float

    def __post_init__(self) -> None:
        self.length = self.base.length
        self.closed = self.base.closed

    def offset(self, s: float) -> float:
        t = min(1.0, max(0.0, (s - self.s_start) / self.span))
        return self.d_from + (self.d_to - self.d_from) * (1.0 - math.cos(math.pi * t)) / 2.0

    def point(self, s: float) -> tuple[float, float]:
        x, y = self.base.point(s)
        yaw, d = self.base.heading(s), self.offset(s)
        return x - d * math.sin(yaw), y + d * math.cos(yaw)

    def heading(self, s: float) -> float:
        return self.base.heading(s)

    def project(self, x: float, y: float) -> float:
        return self.base.project(x, y)

    def follow(self, x: float, y: float, s_last: float) -> float:
        return self.base.follow(x, y, s_last)


class NoJunctionError(LookupError):
    """No junction ahead, or no lane out of it in the asked direction."""


def _inside(point: tuple[float, float], polygon: Sequence[Sequence[float]]) -> bool:
    x, y = point
    inside = False
    for (ax, ay), (bx, by) in itertools.pairwise([*polygon, polygon[0]]):
        if (ay > y) != (by > y) and x < ax + (y - ay) * (bx - ax) / (by - ay):
            inside = not inside
    return inside


def _span_inside(route: PolylineRoute, polygon: Sequence[Sequence[float]], s_from: float) -> tuple[float, float] | None:
    """Arc lengths where `route` first enters and then leaves `polygon`, from `s_from` on."""
    s, entered = s_from, None
    while s <= route.length:
        inside = _inside(route.point(s), polygon)
        if entered is None and inside:
            entered = s
        elif entered is not None and not inside:
            return entered, s
        s += JUNCTION_SAMPLE_M
    return None if entered is None else (entered, route.length)


def junction_route(
    lanes: Sequence[tuple[str, Sequence[Sequence[float]]]],
    junctions: Sequence[Sequence[Sequence[float]]],
    x: float,
    y: float,
    yaw: float,
    turn: str,
) -> tuple[PolylineRoute, float]:
    """A route from (x, y, heading yaw) through the next junction ahead, turning as asked.

    `lanes` are (id, centreline) pairs and `junctions` the junction boxes' polygons. The
    route follows the current lane to the box, a curve tangent to both lanes across it (the
    lane connection), then the exit lane to its end. Returns the route and the arc length
    where it leaves the junction. Raises NoJunctionError when no junction or exit lane fits.
    """
    routes = {lane_id: PolylineRoute(points) for lane_id, points in lanes}
    aligned = [
        (r.distance_to(x, y), lane_id) for lane_id, r in routes.items()
        if math.cos(r.heading(r.project(x, y)) - yaw) > math.cos(TURN_TOLERANCE_RAD)
    ]
    if not aligned:
        raise NoJunctionError(f"no lane runs along heading {math.degrees(yaw):.0f}° at ({x:.1f}, {y:.1f})")
    current_id = min(aligned)[1]
    current = routes[current_id]
    s_here = current.project(x, y)
    ahead = [(span, box) for box in junctions if (span := _span_inside(current, box, s_here)) is not None]
    if not ahead:
        raise NoJunctionError(f"no junction ahead on lane {current_id}")
    (s_in, _), box = min(ahead, key=lambda item: item[0][0])
    entry, in_yaw = current.point(s_in), current.heading(s_in)
    want = {"left": math.pi / 2, "right": -math.pi / 2, "straight": 0.0}[turn]
    best: tuple[float, PolylineRoute, float] | None = None
    for lane_id, r in routes.items():
        span = _span_inside(r, box, 0.0)
        if (lane_id == current_id and turn != "straight") or span is None:
            continue
        s_out = span[1]
        error = abs(math.remainder(r.heading(s_out) - in_yaw - want, math.tau))
        if error < TURN_TOLERANCE_RAD and (best is None or error < best[0]):
            best = (error, r, s_out)
    if best is None:
        raise NoJunctionError(f"no lane leaves the junction to the {turn} of lane {current_id}")
    _, exit_route, s_out = best
    exit_point, out_yaw = exit_route.point(s_out), exit_route.heading(s_out)
    control = _corner(entry, in_yaw, exit_point, out_yaw)
    curve = [
        (
            (1 - t) ** 2 * entry[0] + 2 * (1 - t) * t * control[0] + t**2 * exit_point[0],
            (1 - t) ** 2 * entry[1] + 2 * (1 - t) * t * control[1] + t**2 * exit_point[1],
        )
        for t in (k / TURN_CURVE_POINTS for k in range(TURN_CURVE_POINTS + 1))
    ]
    back = current.point(max(0.0, s_here - 1.0))
    tail = [exit_route.point(s) for s in (s_out + 1.0, exit_route.length) if s <= exit_route.length]
    route = PolylineRoute([back, *curve, *tail])
    return route, route.project(*exit_point)


def _corner(a: tuple[float, float], a_yaw: float, b: tuple[float, float], b_yaw: float) -> tuple[float, float]:
    """Where the entry line (a, a_yaw) meets the exit line (b, b_yaw); the midpoint if parallel."""
    ca, sa, cb, sb = math.cos(a_yaw), math.sin(a_yaw), math.cos(b_yaw), math.sin(b_yaw)
    denominator = ca * sb - sa * cb
    if abs(denominator) < 1e-6:
        return ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    t = ((b[0] - a[0]) * sb - (b[1] - a[1]) * cb) / denominator
    return (a[0] + t * ca, a[1] + t * sa)
