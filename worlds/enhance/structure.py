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
from numpy.typing import NDArray
from PIL import Image
from scipy import ndimage

FloatImage = NDArray[np.float32]
# A depth estimator maps an RGB uint8 frame [H, W, 3] to relative depth [h, w] (any scale).
DepthEstimator = Callable[[NDArray[np.uint8]], NDArray[np.float32]]

# Long side (px) the comparison runs at: a 640-px frame shrinks 10x, which removes texture
# while a car of 30 px still spans 3 px of edges.
STRUCTURE_LONG_SIDE = 64
# The Gaussian window of Wang et al. (2004): sigma 1.5, 11 taps (radius 5 = 3.5 sigma).
SSIM_SIGMA = 1.5
_SSIM_TRUNCATE = 3.5
# SSIM's stabilising constants, as fractions of the data range (Wang et al. 2004).
_K1 = 0.01
_K2 = 0.03
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


def check_frame(frame: object, name: str = "frame") -> NDArray[np.uint8]:
    """A frame as an RGB uint8 array [H, W, 3], or EnhanceInputError saying what was wrong."""
    arr = np.asarray(frame)
    if arr.ndim != 3 or arr.shape[2] != 3 or arr.shape[0] < 8 or arr.shape[1] < 8:
        raise EnhanceInputError(
            f"{name} must be an RGB image of shape [H, W, 3] with H, W >= 8; got {arr.shape}"
        )
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


def ssim_map(a: FloatImage, b: FloatImage, data_range: float = 1.0) -> FloatImage:
    """Per-pixel SSIM of two single-channel images [H, W] with an 11-tap Gaussian window."""
    if a.shape != b.shape or a.ndim != 2:
        raise EnhanceInputError(f"ssim needs two equal 2-D images; got {a.shape} and {b.shape}")
    a64 = a.astype(np.float64)
    b64 = b.astype(np.float64)

    def window(x: NDArray[np.float64]) -> NDArray[np.float64]:
        return np.asarray(ndimage.gaussian_filter(x, SSIM_SIGMA, truncate=_SSIM_TRUNCATE))

    mu_a, mu_b = window(a64), window(b64)
    var_a = window(a64 * a64) - mu_a * mu_a
    var_b = window(b64 * b64) - mu_b * mu_b
    cov = window(a64 * b64) - mu_a * mu_b
    c1 = (_K1 * data_range) ** 2
    c2 = (_K2 * data_range) ** 2
    num = (2 * mu_a * mu_b + c1) * (2 * cov + c2)
    den = (mu_a * mu_a + mu_b * mu_b + c1) * (var_a + var_b + c2)
    return (num / den).astype(np.float32)


def ssim(a: FloatImage, b: FloatImage, data_range: float = 1.0) -> float:
    """Mean SSIM of two single-channel images [H, W]."""
    return float(ssim_map(a, b, data_range).mean())


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
    return [
        float(values[r0:r1, c0:c1].mean())
        for r0, r1 in rows
        for c0, c1 in cols
        if r1 > r0 and c1 > c0
    ]


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


def structure_score(
    baseline: NDArray[np.uint8],
    enhanced: NDArray[np.uint8],
    settings: EnhanceSettings | None = None,
    depth_estimator: DepthEstimator | None = None,
    *,
    max_structure_distance: float | None = None,
) -> StructureScore:
    """Score an enhanced frame against its baseline and decide whether to keep it.

    baseline, enhanced: RGB uint8 [H, W, 3] of the same size. The frame is rejected when
    1 - (worst-tile edge SSIM) exceeds the limit (settings.max_structure_distance unless
    `max_structure_distance` is given), when the optional luminance limit is exceeded, or
    when the depth estimator's two estimates disagree by more than
    settings.max_depth_disagreement.
    """
    baseline = check_frame(baseline, "baseline")
    enhanced = check_frame(enhanced, "enhanced frame")
    if baseline.shape != enhanced.shape:
        raise EnhanceInputError(
            f"baseline {baseline.shape} and enhanced frame {enhanced.shape} differ in size"
        )
    limit = max_structure_distance
    if limit is None:
        limit = (
            settings.max_structure_distance
            if settings is not None
            else DEFAULT_MAX_STRUCTURE_DISTANCE
        )
    rgb_a, rgb_b = low_res_rgb(baseline), low_res_rgb(enhanced)
    edges = ssim_map(edge_map(rgb_a), edge_map(rgb_b))
    worst = worst_tile_mean(edges)
    luminance = ssim(rgb_a @ _LUMA, rgb_b @ _LUMA)
    disagreement = None
    if depth_estimator is not None:
        disagreement = depth_disagreement(depth_estimator(baseline), depth_estimator(enhanced))
    distance = 1.0 - worst
    reasons = []
    if distance > limit:
        reasons.append(f"edge structure distance {distance:.3f} > {limit:.3f}")
    luminance_limit = settings.max_luminance_distance if settings is not None else None
    if luminance_limit is not None and 1.0 - luminance > luminance_limit:
        reasons.append(f"luminance distance {1.0 - luminance:.3f} > {luminance_limit:.3f}")
    if disagreement is not None:
        depth_limit = (
            settings.max_depth_disagreement
            if settings is not None
            else DEFAULT_MAX_DEPTH_DISAGREEMENT
        )
        if disagreement > depth_limit:
            reasons.append(f"depth disagreement {disagreement:.3f} > {depth_limit:.3f}")
    return StructureScore(
        edge_ssim=float(edges.mean()),
        edge_ssim_worst_tile=worst,
        luminance_ssim=luminance,
        depth_disagreement=disagreement,
        structure_distance=distance,
        accepted=not reasons,
        reason="; ".join(reasons) if reasons else "structure kept",
    )
