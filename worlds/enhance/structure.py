"""Structure-preservation scores: did an enhanced frame keep the baseline's geometry?

The scores compare the baseline (rendered) frame with the enhanced one at low resolution,
where texture the diffusion adds is averaged away and object outlines remain:

- edge SSIM: SSIM of colour Sobel edge maps, pooled over the worst of a grid of tiles, so a
  single moved car in one corner cannot hide behind a large unchanged sky;
- luminance SSIM: plain SSIM of the low-resolution luminance (reported; relighting to night
  lowers it on purpose, so by default it does not reject);
- depth disagreement: where a monocular depth model is available, the difference of its
  scale-and-shift-normalised estimates on the two frames.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from drivetwin.worlds.enhance.settings import (
    DEFAULT_MAX_DEPTH_DISAGREEMENT,
    DEFAULT_MAX_STRUCTURE_DISTANCE,
    EnhanceInputError,
    EnhanceSettings,
)
from drivetwin.worlds.image_metrics import ssim, ssim_map
from numpy.typing import NDArray
from PIL import Image
from scipy import ndimage

FloatImage = NDArray[np.float32]
# A depth estimator maps an RGB uint8 frame [H, W, 3] to relative depth [h, w] (any scale).
DepthEstimator = Callable[[NDArray[np.uint8]], NDArray[np.float32]]

# Long side (px) the comparison runs at: a 640-px frame shrinks 10x, which removes texture
# while a car of 30 px still spans 3 px of edges.
STRUCTURE_LONG_SIDE = 64
# Smoothing before Sobel, in low-res pixels: suppresses one-pixel noise edges.
_EDGE_SMOOTH = 1.0
# Edge maps are divided by their 99th percentile (scale-free, so a darker or tinted frame has
# the same edges) and responses below this fraction are dropped as texture.
_EDGE_PERCENTILE = 99.0
_EDGE_FLOOR = 0.2
# 4 x 4 tiles: a tile of a 64-px frame is 16 px, about the size of a near vehicle.
TILE_GRID = 4
_EPS = 1e-6
_LUMA = np.array([0.299, 0.587, 0.114], dtype=np.float32)  # ITU-R BT.601


@dataclass(frozen=True)
class StructureScore:
    """How far an enhanced frame strayed from its baseline, and the verdict."""

    edge_ssim: float
    edge_ssim_worst_tile: float
    luminance_ssim: float
    depth_disagreement: float | None
    structure_distance: float
    accepted: bool
    reason: str
    outlines_lost: float = 0.0  # worst window: fraction of baseline outlines gone
    outlines_added: float = 0.0  # worst window: fraction of strong edges that are new


def check_frame(frame: object, name: str = "frame") -> NDArray[np.uint8]:
    """A frame as an RGB uint8 array [H, W, 3], or EnhanceInputError saying what was wrong."""
    arr = np.asarray(frame)
    if arr.ndim != 3 or arr.shape[2] != 3 or arr.shape[0] < 8 or arr.shape[1] < 8:
        raise EnhanceInputError(f"{name} must be an RGB image of shape [H, W, 3] with H, W >= 8; got {arr.shape}")
    if arr.dtype != np.uint8:
        raise EnhanceInputError(f"{name} must be uint8 (0..255); got dtype {arr.dtype}")
    return arr


def _resize_plane(plane: FloatImage, long_side: int) -> FloatImage:
    h, w = plane.shape
    scale = long_side / max(h, w)
    if scale >= 1.0:
        return plane
    size = (max(1, round(w * scale)), max(1, round(h * scale)))
    # BOX = area averaging, the right filter for shrinking (no aliasing of fine texture).
    small = Image.fromarray(plane, mode="F").resize(size, Image.Resampling.BOX)
    return np.asarray(small, dtype=np.float32)


def low_res_rgb(frame: NDArray[np.uint8], long_side: int = STRUCTURE_LONG_SIDE) -> FloatImage:
    """A frame as float RGB in [0, 1] [h, w, 3], shrunk so its long side is `long_side`."""
    rgb = frame.astype(np.float32) / 255.0
    return np.stack([_resize_plane(rgb[..., c], long_side) for c in range(3)], axis=-1)


def edge_map(rgb: FloatImage) -> FloatImage:
    """Colour edge strength [H, W] in [0, 1] of a float RGB image, texture floor removed."""
    magnitudes: list[NDArray[np.float64]] = []
    for c in range(3):
        smooth = ndimage.gaussian_filter(rgb[..., c].astype(np.float64), _EDGE_SMOOTH)
        magnitudes.append(np.hypot(ndimage.sobel(smooth, 0), ndimage.sobel(smooth, 1)))
    # Max over channels: an edge between two colours of equal brightness still counts.
    magnitude: NDArray[np.float64] = np.max(np.stack(magnitudes), axis=0)
    magnitude /= float(np.percentile(magnitude, _EDGE_PERCENTILE)) + _EPS
    return np.clip((magnitude - _EDGE_FLOOR) / (1.0 - _EDGE_FLOOR), 0.0, 1.0).astype(np.float32)


def tile_means(values: FloatImage, grid: int = TILE_GRID) -> list[float]:
    """Means of a map [H, W] split into grid x grid tiles (empty tiles left out)."""
    h, w = values.shape
    rows = [(i * h // grid, (i + 1) * h // grid) for i in range(grid)]
    cols = [(j * w // grid, (j + 1) * w // grid) for j in range(grid)]
    return [float(values[r0:r1, c0:c1].mean()) for r0, r1 in rows for c0, c1 in cols if r1 > r0 and c1 > c0]


def worst_tile_mean(values: FloatImage, grid: int = TILE_GRID) -> float:
    """The smallest per-tile mean of a map [H, W] split into grid x grid tiles."""
    return min(tile_means(values, grid))


def normalised_depth(depth: NDArray[np.floating]) -> NDArray[np.float64]:
    """Relative depth made scale-and-shift free: (d - median) / mean |d - median|."""
    d = np.asarray(depth, dtype=np.float64)
    centred = d - np.median(d)
    spread = float(np.mean(np.abs(centred)))
    return centred / (spread + _EPS)


def depth_disagreement(a: NDArray[np.floating], b: NDArray[np.floating]) -> float:
    """Largest per-tile mean |difference| of two normalised depth estimates (0 = same layout).

    Tiles, not the global mean, so one moved vehicle is not averaged away by the scene.
    """
    if a.shape != b.shape:
        b_img = Image.fromarray(np.asarray(b, dtype=np.float32), mode="F")
        b = np.asarray(b_img.resize((a.shape[1], a.shape[0]), Image.Resampling.BILINEAR))
    diff = np.abs(normalised_depth(a) - normalised_depth(b)).astype(np.float32)
    return max(tile_means(diff))


# Outline comparison (the verdict). It runs at 192 px on the long side: a 320 x 180 render
# shrinks 1.7x, a 640 x 360 one 3.3x, so a car 15-20 m ahead of the chase camera's ego still
# spans 6-8 px and a 1 m sideways move shifts it by 2-3 px, beyond the 1-px tolerance below.
OUTLINE_LONG_SIDE = 192
# Pre-smoothing before Sobel and the structure-tensor window (px): one-pixel noise averages out.
_GRAD_SMOOTH = 0.7
_TENSOR_SMOOTH = 1.0
# Local contrast normalisation window (px) and its floor as a fraction of the frame's 90th
# percentile edge energy: relighting and tint change contrast per region, not outlines.
_NORM_SIGMA = 4.0
_NORM_FLOOR = 0.35
_NORM_PERCENTILE = 90.0
# A baseline outline counts when its normalised energy is >= 0.5, and is kept when the
# candidate has >= 0.3 within 1 px at an orientation within 45 degrees (cos^2 >= 0.5).
_REF_LEVEL = 0.5
_KEEP_LEVEL = 0.3
_SAME_ORIENTATION_COS2 = 0.5
# A candidate edge is new when its energy is >= 0.5 of the frame's 90th percentile and the
# baseline has < 0.2 within 1 px at the same orientation.
_NEW_LEVEL = 0.5
_EXPLAINED_LEVEL = 0.2
# Gaussian window (px) in which kept and new outlines are counted (about one vehicle at
# 15 m), and the fewest outline pixels a window needs before it can fail.
OUTLINE_WINDOW = 3.0
_MIN_WINDOW_PIXELS = 4.0
# Depth silhouettes: second difference of disparity (1/depth) above 15 % of the local
# disparity. A plane has zero second difference of disparity, so roads and walls seen at
# a slant are not silhouettes; an object in front of a farther one is.
_SILHOUETTE_JUMP = 0.15
_NEIGHBOURS = [(dy, dx) for dy in (-1, 0, 1) for dx in (-1, 0, 1)]


@dataclass(frozen=True)
class _Outlines:
    """Edge energy (normalised) and orientation of one frame at the outline resolution."""

    local: FloatImage  # energy / local contrast
    frame: FloatImage  # energy / the frame's 90th percentile
    angle: FloatImage  # radians, edge-normal orientation (mod pi)


def _outlines(frame: NDArray[np.uint8]) -> _Outlines:
    """Colour structure-tensor edges: coherent energy sqrt(l1 - l2) resists texture noise."""
    rgb = low_res_rgb(frame, OUTLINE_LONG_SIDE).astype(np.float64)
    jxx = np.zeros(rgb.shape[:2])
    jyy = np.zeros(rgb.shape[:2])
    jxy = np.zeros(rgb.shape[:2])
    for c in range(3):
        smooth = ndimage.gaussian_filter(rgb[..., c], _GRAD_SMOOTH)
        gx, gy = ndimage.sobel(smooth, 1), ndimage.sobel(smooth, 0)
        jxx += gx * gx
        jyy += gy * gy
        jxy += gx * gy
    jxx, jyy, jxy = (ndimage.gaussian_filter(j, _TENSOR_SMOOTH) for j in (jxx, jyy, jxy))
    energy = np.sqrt(np.sqrt((jxx - jyy) ** 2 + 4.0 * jxy * jxy))
    scale = float(np.percentile(energy, _NORM_PERCENTILE)) + _EPS
    local = np.maximum(ndimage.gaussian_filter(energy, _NORM_SIGMA), _NORM_FLOOR * scale)
    return _Outlines(
        local=(energy / local).astype(np.float32),
        frame=(energy / scale).astype(np.float32),
        angle=(0.5 * np.arctan2(2.0 * jxy, jxx - jyy)).astype(np.float32),
    )


def _support(energy: FloatImage, angle: FloatImage, at_angle: FloatImage) -> FloatImage:
    """Strongest edge within 1 px whose orientation is within 45 degrees of `at_angle`."""
    best = np.zeros_like(energy)
    for dy, dx in _NEIGHBOURS:
        e = np.roll(energy, (dy, dx), (0, 1))
        same = np.cos(np.roll(angle, (dy, dx), (0, 1)) - at_angle) ** 2 >= _SAME_ORIENTATION_COS2
        best = np.maximum(best, np.where(same, e, 0.0))
    return best


def depth_silhouettes(depth: NDArray[np.floating], shape: tuple[int, int]) -> NDArray[np.bool_]:
    """Where object outlines are, from the renderer's depth [H, W] metres (inf = sky),
    as a mask of `shape` (any silhouette pixel in a cell marks it), dilated by 1 px."""
    d = np.asarray(depth, dtype=np.float64)
    if d.ndim != 2:
        raise EnhanceInputError(f"baseline depth must be [H, W] metres; got shape {d.shape}")
    disparity = np.where(np.isfinite(d) & (d > 0.0), 1.0 / np.maximum(d, 1e-3), 0.0)
    found = np.zeros(d.shape, dtype=bool)
    for t in (disparity, disparity.T):  # rows, then columns (a view: found.T is written)
        before, mid, after = t[:-2], t[1:-1], t[2:]
        jump = np.abs(before - 2.0 * mid + after) > _SILHOUETTE_JUMP * np.maximum(np.maximum(before, after), mid)
        (found if t is disparity else found.T)[1:-1] |= jump
    small = _resize_plane(found.astype(np.float32), max(shape))
    if small.shape != shape:
        small = np.asarray(Image.fromarray(small, mode="F").resize((shape[1], shape[0]), Image.Resampling.BOX))
    return np.asarray(ndimage.binary_dilation(small > 0.0, iterations=1))


@dataclass(frozen=True)
class OutlineChange:
    """The worst window of the outline comparison: lost and new outline fractions there."""

    lost: float  # fraction of the baseline's outlines the candidate no longer has
    added: float  # fraction of the candidate's strong edges the baseline cannot explain
    lost_at: tuple[int, int]  # (x, y) in the input frame's pixels
    added_at: tuple[int, int]


def outline_change(
    baseline: NDArray[np.uint8],
    candidate: NDArray[np.uint8],
    baseline_depth: NDArray[np.floating] | None = None,
) -> OutlineChange:
    """Compare outlines of two frames [H, W, 3]; with the baseline depth, only silhouettes
    (depth discontinuities) the baseline shows must be kept."""
    a, b = _outlines(baseline), _outlines(candidate)
    reference = a.local >= _REF_LEVEL
    if baseline_depth is not None:
        if baseline_depth.shape != baseline.shape[:2]:
            raise EnhanceInputError(
                f"baseline depth {baseline_depth.shape} does not match the frame {baseline.shape[:2]}"
            )
        reference &= depth_silhouettes(baseline_depth, a.local.shape)
    kept = _support(b.local, b.angle, a.angle) >= _KEEP_LEVEL
    strong = b.frame >= _NEW_LEVEL
    new = strong & (_support(a.frame, a.angle, b.angle) < _EXPLAINED_LEVEL)
    min_mass = _MIN_WINDOW_PIXELS / (2.0 * np.pi * OUTLINE_WINDOW**2)

    def window(mask: NDArray[np.bool_]) -> NDArray[np.float64]:
        return np.asarray(ndimage.gaussian_filter(mask.astype(np.float64), OUTLINE_WINDOW))

    ref_mass, all_mass = window(reference), window(strong | reference)
    lost = np.where(ref_mass >= min_mass, window(reference & ~kept) / (ref_mass + _EPS), 0.0)
    added = np.where(all_mass >= min_mass, window(new) / (all_mass + _EPS), 0.0)
    to_frame = baseline.shape[1] / a.local.shape[1]

    def where(values: NDArray[np.float64]) -> tuple[int, int]:
        y, x = np.unravel_index(int(np.argmax(values)), values.shape)
        return round((x + 0.5) * to_frame), round((y + 0.5) * to_frame)

    return OutlineChange(
        lost=float(np.clip(lost.max(), 0.0, 1.0)),
        added=float(np.clip(added.max(), 0.0, 1.0)),
        lost_at=where(lost),
        added_at=where(added),
    )


def structure_score(
    baseline: NDArray[np.uint8],
    enhanced: NDArray[np.uint8],
    settings: EnhanceSettings | None = None,
    depth_estimator: DepthEstimator | None = None,
    *,
    max_structure_distance: float | None = None,
    baseline_depth: NDArray[np.floating] | None = None,
) -> StructureScore:
    """Score an enhanced frame against its baseline and decide whether to keep it.

    baseline, enhanced: RGB uint8 [H, W, 3] of the same size; baseline_depth: the
    renderer's depth [H, W] in metres (inf = sky), which limits the kept-outline test to
    object silhouettes. structure_distance = max(outlines lost, outlines added) in the
    worst window (see `outline_change`); the frame is rejected when it exceeds the limit
    (settings.max_structure_distance unless `max_structure_distance` is given), when the
    optional luminance limit is exceeded, or when the depth estimator's two estimates
    disagree by more than settings.max_depth_disagreement. Edge SSIM is reported only.
    """
    baseline = check_frame(baseline, "baseline")
    enhanced = check_frame(enhanced, "enhanced frame")
    if baseline.shape != enhanced.shape:
        raise EnhanceInputError(f"baseline {baseline.shape} and enhanced frame {enhanced.shape} differ in size")
    limit = max_structure_distance
    if limit is None:
        limit = settings.max_structure_distance if settings is not None else DEFAULT_MAX_STRUCTURE_DISTANCE
    depth = None if baseline_depth is None else np.asarray(baseline_depth)
    change = outline_change(baseline, enhanced, depth)
    rgb_a, rgb_b = low_res_rgb(baseline), low_res_rgb(enhanced)
    edges = ssim_map(edge_map(rgb_a), edge_map(rgb_b))
    luminance = ssim(rgb_a @ _LUMA, rgb_b @ _LUMA)
    disagreement = None
    if depth_estimator is not None:
        disagreement = depth_disagreement(depth_estimator(baseline), depth_estimator(enhanced))
    distance = max(change.lost, change.added)
    reasons = []
    if distance > limit:
        h, w = baseline.shape[:2]
        if change.lost >= change.added:
            x, y = change.lost_at
            what = f"{change.lost:.0%} of the baseline's outlines lost near x={x}, y={y}"
        else:
            x, y = change.added_at
            what = f"{change.added:.0%} of the strong edges are new near x={x}, y={y}"
        reasons.append(f"edge structure distance {distance:.3f} > {limit:.3f} ({what} of {w}x{h})")
    luminance_limit = settings.max_luminance_distance if settings is not None else None
    if luminance_limit is not None and 1.0 - luminance > luminance_limit:
        reasons.append(f"luminance distance {1.0 - luminance:.3f} > {luminance_limit:.3f}")
    if disagreement is not None:
        depth_limit = settings.max_depth_disagreement if settings is not None else DEFAULT_MAX_DEPTH_DISAGREEMENT
        if disagreement > depth_limit:
            reasons.append(f"depth disagreement {disagreement:.3f} > {depth_limit:.3f}")
    return StructureScore(
        edge_ssim=float(edges.mean()),
        edge_ssim_worst_tile=worst_tile_mean(edges),
        luminance_ssim=luminance,
        depth_disagreement=disagreement,
        structure_distance=distance,
        accepted=not reasons,
        reason="; ".join(reasons) if reasons else "structure kept",
        outlines_lost=change.lost,
        outlines_added=change.added,
    )
