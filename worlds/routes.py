"""Paths that behaviours follow, parameterised by arc length: polylines and circles.

Vehicles steer towards a point a lookahead distance along the route from their projection
on it (pure pursuit); walkers are placed at the point `speed · elapsed` along it.
"""

from __future__ import annotations

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
    _points: np.ndarray = field(init=False, repr=False)
    _cumulative: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        points = np.asarray(self.waypoints, dtype=float)
        if self.closed and not np.allclose(points[0], points[-1]):
            points = np.vstack([points, points[:1]])
        steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
        keep = np.concatenate([[True], steps > 1e-9])
        self._points = points[keep]
        if len(self._points) < 2:
            raise ValueError("a route needs two distinct waypoints")
        self._cumulative = np.concatenate(
            [[0.0], np.cumsum(np.linalg.norm(np.diff(self._points, axis=0), axis=1))]
        )
        self.length = float(self._cumulative[-1])

    def _segment(self, s: float) -> tuple[int, float]:
        s = self.wrap(s)
        index = int(np.searchsorted(self._cumulative, s, side="right") - 1)
        index = min(max(index, 0), len(self._points) - 2)
        return index, s - float(self._cumulative[index])

    def point(self, s: float) -> tuple[float, float]:
        index, along = self._segment(s)
        a, b = self._points[index], self._points[index + 1]
        t = along / float(np.linalg.norm(b - a))
        p = a + t * (b - a)
        return float(p[0]), float(p[1])

    def heading(self, s: float) -> float:
        index, _ = self._segment(s)
        d = self._points[index + 1] - self._points[index]
        return math.atan2(float(d[1]), float(d[0]))

    def project(self, x: float, y: float) -> float:
        a, b = self._points[:-1], self._points[1:]
        d = b - a
        lengths2 = np.einsum("ij,ij->i", d, d)
        t = np.clip(np.einsum("ij,ij->i", np.array([x, y]) - a, d) / lengths2, 0.0, 1.0)
        nearest = a + t[:, None] * d
        distances = np.linalg.norm(nearest - np.array([x, y]), axis=1)
        best = int(np.argmin(distances))
        return float(self._cumulative[best] + t[best] * math.sqrt(lengths2[best]))

    def distance_to(self, x: float, y: float) -> float:
        """Distance from (x, y) to the nearest point of the route."""
        px, py = self.point(self.project(x, y))
        return math.hypot(x - px, y - py)

    @property
    def start(self) -> tuple[float, float]:
        return float(self._points[0][0]), float(self._points[0][1])


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
