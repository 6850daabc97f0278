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

__all__ = ["CircleRoute", "PolylineRoute", "Route", "segment_polyline_intersection"]


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
        best, best_s = math.inf, 0.0
        for index, ((ax, ay), (bx, by)) in enumerate(itertools.pairwise(self._points)):
            dx, dy = bx - ax, by - ay
            length2 = dx * dx + dy * dy
            t = min(1.0, max(0.0, ((x - ax) * dx + (y - ay) * dy) / length2))
            distance2 = (ax + t * dx - x) ** 2 + (ay + t * dy - y) ** 2
            if distance2 < best:
                best, best_s = distance2, self._cumulative[index] + t * math.sqrt(length2)
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
