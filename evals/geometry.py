"""The measurements behind the checks: layouts, behaviours, colours and words in answers."""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from itertools import pairwise
from typing import Literal

import numpy as np
from drivetwin.tools.appearance import resolve_colour
from drivetwin.tools.errors import ToolError
from drivetwin.tools.locate import Target
from drivetwin.worlds.scene import AssetInstance, Scene
from drivetwin.worlds.surface import nearest_on_polyline

ArrangementShape = Literal["line", "ring", "cluster"]
# A ring's centre may miss what it goes around by this share of its radius.
RING_CENTRE_SHARE = 0.5
Range = tuple[float | None, float | None]


def _in_range(value: float, bounds: Range) -> bool:
    lo, hi = bounds
    return (lo is None or value >= lo) and (hi is None or value <= hi)


def judge_arrangement(
    points: Sequence[tuple[float, float]],
    shape: ArrangementShape,
    tolerance: float,
    centre: tuple[float, float] | None = None,
    spacing_min: float | None = None,
    spacing_max: float | None = None,
) -> tuple[bool, str]:
    """Whether points form a line, a ring (around `centre`) or a cluster, and why not."""
    pts = np.asarray(points, dtype=float)
    mean = pts.mean(axis=0)
    n = len(pts)
    if shape == "line":
        # The best-fit line through the points is their first principal axis.
        _, _, vt = np.linalg.svd(pts - mean)
        normal = vt[1] if len(vt) > 1 else np.array([0.0, 1.0])
        off = float(np.max(np.abs((pts - mean) @ normal)))
        if off > tolerance:
            return (
                False,
                f"{n} points are {off:.2f} m off a straight line (tolerance {tolerance:g} m)",
            )
        shape_ok = f"{n} points in a line (max {off:.2f} m off)"
    elif shape == "ring":
        radii = np.hypot(*(pts - mean).T)
        r = float(radii.mean())
        spread = float(np.max(np.abs(radii - r)))
        allowed = max(tolerance, 0.2 * r)
        if spread > allowed:
            return False, f"{n} points are {spread:.2f} m off a circle of radius {r:.1f} m"
        if centre is not None:
            miss = math.hypot(mean[0] - centre[0], mean[1] - centre[1])
            if miss > max(tolerance, RING_CENTRE_SHARE * r):
                return False, f"the ring's centre is {miss:.1f} m from what it should surround"
        shape_ok = f"{n} points on a ring of radius {r:.1f} m"
    else:
        far = float(np.max(np.hypot(*(pts - mean).T)))
        if far > tolerance:
            return (
                False,
                f"{n} points spread {far:.1f} m from their centre (tolerance {tolerance:g} m)",
            )
        shape_ok = f"{n} points within {far:.1f} m"
    if spacing_min is not None or spacing_max is not None:
        gaps = _nearest_gaps(pts)
        bad = [g for g in gaps if not _in_range(g, (spacing_min, spacing_max))]
        if bad:
            return False, (
                f"spacing {min(gaps):.2f}..{max(gaps):.2f} m, wanted "
                f"{spacing_min or 0:g}..{spacing_max or math.inf:g} m"
            )
    return True, shape_ok


def _nearest_gaps(pts: np.ndarray) -> list[float]:
    diff = pts[:, None, :] - pts[None, :, :]
    dist = np.hypot(diff[..., 0], diff[..., 1])
    np.fill_diagonal(dist, np.inf)
    return [float(d) for d in dist.min(axis=1)]


def _segment_crosses(a: tuple[float, float], b: tuple[float, float], line: Sequence[tuple[float, float]]) -> bool:
    """Whether segment a-b ends on opposite sides of a polyline (and within its reach)."""
    na = nearest_on_polyline(a[0], a[1], line)
    nb = nearest_on_polyline(b[0], b[1], line)
    return bool(na.side != nb.side)


def behaviour_matches(
    asset: AssetInstance,
    scene: Scene,
    kinds: Sequence[str],
    *,
    speed: Range = (None, None),
    radius: Range = (None, None),
    lane: str | None = None,
    clockwise: bool | None = None,
    crosses_lane: str | None = None,
    centre: Target | None = None,
    centre_within: float = 20.0,
) -> tuple[bool, str]:
    """Whether an asset's behaviour is one of `kinds` with parameters in range, and why not."""
    b = asset.behaviour
    if b.kind not in kinds:
        return False, f"does {b.kind}"
    got_speed = getattr(b, "speed", None)
    if got_speed is not None and not _in_range(got_speed, speed):
        return False, f"goes at {got_speed:g} m/s"
    if b.kind == "circle":
        if not _in_range(b.radius, radius):
            return False, f"circles at radius {b.radius:g} m"
        if clockwise is not None and b.clockwise != clockwise:
            return False, "circles the other way"
        if centre is not None:
            miss = math.hypot(b.centre[0] - centre.x, b.centre[1] - centre.y)
            if centre.polygon is None and miss > centre_within:
                return False, f"circles {miss:.1f} m from {centre.name}"
            if centre.polygon is not None and miss > centre_within:
                from drivetwin.worlds.surface import point_in_polygon

                if not point_in_polygon(b.centre[0], b.centre[1], centre.polygon):
                    return False, f"circles outside {centre.name}"
    if lane is not None and b.kind == "drive_lane" and b.lane != lane:
        return False, f"drives in {b.lane}"
    if crosses_lane is not None:
        target = scene.roads.lane(crosses_lane)
        path = _walk_path(asset)
        if target is None or path is None:
            return False, f"has no path across {crosses_lane}"
        if not any(_segment_crosses(p, q, target.centreline) for p, q in pairwise(path)):
            return False, f"does not cross {crosses_lane}"
    return True, f"does {b.kind}"


def _walk_path(asset: AssetInstance) -> list[tuple[float, float]] | None:
    b = asset.behaviour
    if b.kind in ("jaywalk", "cross_road"):
        return [b.start, b.end]
    if b.kind == "follow_path":
        return list(b.waypoints)
    return None


def matches_colour(rgba: tuple[float, float, float, float] | None, colour: str, tolerance: float) -> bool:
    """Whether an asset's colour override is within `tolerance` per channel of a named colour."""
    if rgba is None:
        return False
    try:
        want = resolve_colour(colour)
    except ToolError:
        return False
    return all(abs(a - b) <= tolerance for a, b in zip(rgba[:3], want[:3], strict=True))


def mentions(text: str, word: str) -> bool:
    """Whether `text` holds `word` (any case), not inside a longer word or number; -85 matches -85.0."""
    pattern = re.escape(word.strip().lower().replace("_", " ")).replace(r"\ ", r"\s+")
    # Word boundaries only where the word itself starts or ends with a letter or digit.
    left = r"(?<![\w.])" if word[:1].isalnum() else ""
    right = r"(?!\w)(?!\.\d*[1-9])" if word[-1:].isalnum() else ""
    return re.search(left + pattern + right, text.lower().replace("_", " ")) is not None
