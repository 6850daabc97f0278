"""Putting the splats of a capture into the frame of its mesh: check, then similarity ICP.

Splats fitted from images posed by structure from motion live in the SfM frame: right
shape, unknown scale, rotation and offset. LIDAR meshes are metric. `check_alignment`
measures how far splat means lie from the mesh surface; `estimate_similarity` finds the
similarity (rotation, uniform scale, translation) that puts the means on it: starts from
centroid, RMS radius and principal axes (and the 24 axis-aligned turns, for shapes whose
axes are ambiguous), refines each by trimmed ICP whose steps are Umeyama fits, and keeps the
start that ends with the most points on the surface.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import trimesh
from scipy.spatial import cKDTree

__all__ = [
    "AlignmentCheck",
    "apply_transform",
    "check_alignment",
    "estimate_similarity",
    "surface_samples",
    "umeyama",
]

F64 = npt.NDArray[np.float64]

# Points sampled on the mesh surface to measure distances to it: about 1 cm spacing on a
# 2 m object, so a sampled distance is within half a centimetre of the true one.
SURFACE_SAMPLES = 40_000
# A splat is "on" the mesh when nearer than this share of the mesh's bounding diagonal...
TOLERANCE_FRACTION = 0.01
# ...but never nearer than this (sampling spacing and LIDAR noise are centimetres).
MIN_TOLERANCE_M = 0.01
# The frames agree when points lie near this share of the surface (the cameras may not
# have seen all of it: the underside, a side against a wall)...
MIN_COVERAGE = 0.6
# ...counting a surface sample as covered within this many of the points' own spacings.
COVERAGE_SPACINGS = 2.0
# Correspondences farther than this quantile are dropped at each ICP step (floaters, the
# part of the mesh the cameras never saw).
TRIM_QUANTILE = 0.8
COARSE_POINTS, COARSE_ITERATIONS = 500, 15
FINE_POINTS, FINE_ITERATIONS = 2500, 40
# The coarse stage's scale is only the start's guess: judge its fit with a looser tolerance.
COARSE_TOLERANCES = 4.0
# Share of points, nearest the median centre, that set the start's centre, axes and radius.
INNER_QUANTILE = 0.8
# ICP stops when a step moves points by less than this share of the diagonal.
CONVERGED_FRACTION = 1e-6


@dataclass(frozen=True)
class AlignmentCheck:
    """How well points sit on a surface: median and 90th-percentile distance (m), the share
    within `tolerance_m`, that tolerance, and `coverage`: the share of the surface that has
    a point within `coverage_tolerance_m` (tolerance or the points' own spacing)."""

    median_m: float
    p90_m: float
    inlier_fraction: float
    tolerance_m: float
    coverage: float = 0.0
    coverage_tolerance_m: float = 0.0

    @property
    def aligned(self) -> bool:
        """Whether the points cover most of the surface (background points do not count
        against it: a capture's splats hold more than the scanned object)."""
        return self.coverage >= MIN_COVERAGE


def surface_samples(mesh: trimesh.Trimesh, count: int = SURFACE_SAMPLES, seed: int = 0) -> F64:
    """`count` points spread evenly (by area) over the mesh surface, [count, 3]."""
    points, _ = trimesh.sample.sample_surface_even(mesh, count, seed=seed)
    if len(points) < count // 2:  # even sampling rejects too many on thin meshes
        points, _ = trimesh.sample.sample_surface(mesh, count, seed=seed)
    return np.asarray(points, dtype=np.float64)


def tolerance_for(surface: F64) -> float:
    """The on-surface tolerance for a surface's sample points (m)."""
    diagonal = float(np.linalg.norm(surface.max(axis=0) - surface.min(axis=0)))
    return max(MIN_TOLERANCE_M, TOLERANCE_FRACTION * diagonal)


def check_alignment(points: F64, surface: F64, tolerance_m: float | None = None) -> AlignmentCheck:
    """Distances of `points` [N,3] to the surface given by its samples `surface` [M,3], and
    how much of the surface the points cover."""
    tolerance = tolerance_for(surface) if tolerance_m is None else tolerance_m
    tree = cKDTree(points)
    distances, _ = cKDTree(surface).query(points)
    spacing, _ = tree.query(points, k=2)
    cover_tolerance = max(tolerance, COVERAGE_SPACINGS * float(np.median(spacing[:, 1])))
    backward, _ = tree.query(surface)
    return AlignmentCheck(
        median_m=float(np.median(distances)),
        p90_m=float(np.quantile(distances, 0.9)),
        inlier_fraction=float(np.mean(distances <= tolerance)),
        tolerance_m=tolerance,
        coverage=float(np.mean(backward <= cover_tolerance)),
        coverage_tolerance_m=cover_tolerance,
    )


def apply_transform(transform: F64, points: F64) -> F64:
    """Points [N,3] moved by a 4x4 transform."""
    return np.asarray(points @ transform[:3, :3].T + transform[:3, 3], dtype=np.float64)


def umeyama(source: F64, target: F64, *, with_scale: bool = True) -> F64:
    """The 4x4 similarity minimising ||s R source + t - target||² over paired points (Umeyama
    1991): source, target [N,3], N >= 3 not collinear."""
    mu_s, mu_t = source.mean(axis=0), target.mean(axis=0)
    xs, xt = source - mu_s, target - mu_t
    covariance = xt.T @ xs / len(source)
    u, singular, vt = np.linalg.svd(covariance)
    sign = np.eye(3)
    if np.linalg.det(u) * np.linalg.det(vt) < 0:
        sign[2, 2] = -1.0
    rotation = u @ sign @ vt
    variance = float(np.mean(np.sum(xs**2, axis=1)))
    scale = float(np.trace(np.diag(singular) @ sign) / variance) if with_scale and variance > 0 else 1.0
    transform = np.eye(4)
    transform[:3, :3] = scale * rotation
    transform[:3, 3] = mu_t - scale * rotation @ mu_s
    return transform


def _axis_turns() -> list[F64]:
    """The 24 rotations that map the coordinate axes onto themselves."""
    turns = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product((1.0, -1.0), repeat=3):
            matrix = np.zeros((3, 3))
            for row, (col, sign) in enumerate(zip(perm, signs, strict=True)):
                matrix[row, col] = sign
            if np.linalg.det(matrix) > 0:
                turns.append(matrix)
    return turns


def _principal_axes(points: F64) -> tuple[F64, F64, float]:
    """Robust centre (median), principal axes and RMS radius of the inner points (the
    INNER_QUANTILE nearest the centre), so background splats barely move the start."""
    centre = np.median(points, axis=0)
    distance = np.linalg.norm(points - centre, axis=1)
    inner = points[distance <= np.quantile(distance, INNER_QUANTILE)]
    centre = inner.mean(axis=0)
    centred = inner - centre
    values, vectors = np.linalg.eigh(centred.T @ centred / len(inner))
    return centre, vectors[:, ::-1], float(np.sqrt(max(values.sum(), 1e-18)))


def _starts(source: F64, target: F64) -> list[F64]:
    c_s, axes_s, radius_s = _principal_axes(source)
    c_t, axes_t, radius_t = _principal_axes(target)
    scale = radius_t / radius_s
    rotations = [axes_t @ np.diag(s) @ axes_s.T for s in itertools.product((1.0, -1.0), repeat=3)]
    rotations = [r for r in rotations if np.linalg.det(r) > 0] + _axis_turns()
    starts = []
    for rotation in rotations:
        start = np.eye(4)
        start[:3, :3] = scale * rotation
        start[:3, 3] = c_t - scale * rotation @ c_s
        starts.append(start)
    return starts


def _icp(
    source: F64, target: F64, tree: cKDTree, start: F64, iterations: int, tolerance: float, *, with_scale: bool
) -> F64:
    """Trimmed ICP. With scale, correspondences go both ways (which stops the scale from
    shrinking the source onto one patch of the target); without, forward only (fast)."""
    transform = start.copy()
    step_limit = CONVERGED_FRACTION * tolerance / TOLERANCE_FRACTION
    for _ in range(iterations):
        moved = apply_transform(transform, source)
        forward, to_target = tree.query(moved)
        keep_f = forward <= np.quantile(forward, TRIM_QUANTILE)
        paired_source, paired_target = moved[keep_f], target[to_target[keep_f]]
        if with_scale:
            backward, to_source = cKDTree(moved).query(target)
            keep_b = backward <= np.quantile(backward, TRIM_QUANTILE)
            paired_source = np.concatenate([paired_source, moved[to_source[keep_b]]])
            paired_target = np.concatenate([paired_target, target[keep_b]])
        step = umeyama(paired_source, paired_target, with_scale=with_scale)
        transform = step @ transform
        if np.max(np.abs(apply_transform(step, moved) - moved)) < step_limit:
            break
    return transform


def _score(transform: F64, source: F64, tree: cKDTree, target: F64, tolerance: float) -> float:
    moved = apply_transform(transform, source)
    forward, _ = tree.query(moved)
    backward, _ = cKDTree(moved).query(target)
    return float(np.mean(forward <= tolerance) + np.mean(backward <= tolerance))


def estimate_similarity(source: F64, surface: F64, *, seed: int = 0) -> tuple[F64, AlignmentCheck]:
    """The 4x4 similarity that puts `source` points [N,3] onto the surface sampled by
    `surface` [M,3], and the alignment check after it."""
    rng = np.random.default_rng(seed)
    tolerance = tolerance_for(surface)

    def pick(points: F64, count: int) -> F64:
        return points[rng.choice(len(points), min(count, len(points)), replace=False)]

    coarse_s, coarse_t = pick(source, COARSE_POINTS), pick(surface, COARSE_POINTS * 4)
    coarse_tree = cKDTree(coarse_t)
    best, best_score = np.eye(4), -1.0
    for start in _starts(source, surface):
        # Rigid at the start's scale: fast, and enough to find the right basin.
        candidate = _icp(coarse_s, coarse_t, coarse_tree, start, COARSE_ITERATIONS, tolerance, with_scale=False)
        score = _score(candidate, coarse_s, coarse_tree, coarse_t, tolerance * COARSE_TOLERANCES)
        if score > best_score:
            best, best_score = candidate, score
    fine_s, fine_t = pick(source, FINE_POINTS), pick(surface, FINE_POINTS * 3)
    refined = _icp(fine_s, fine_t, cKDTree(fine_t), best, FINE_ITERATIONS, tolerance, with_scale=True)
    return refined, check_alignment(apply_transform(refined, source), surface, tolerance)
