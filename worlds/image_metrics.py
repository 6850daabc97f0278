"""Image similarity: PSNR and SSIM, one implementation for the whole project.

The renderer's benchmarks, the enhancer's structure check and the reconstruction reports all
measure images with these. SSIM uses a Gaussian window of sigma 1.5 pixels cut at 11 taps and
the constants of Wang et al. 2004 (K1 = 0.01, K2 = 0.03 of the data range). Borders are
padded by reflection by default; `padding="zeros"` gives the 3DGS papers' convention (zero
padding of half a window), which reconstruction reports use so their figures compare with
published ones. The differentiable SSIM loss the splat fit needs lives beside its optimiser
(`drivetwin.worlds.reconstruct.image_metrics.ssim_torch`) and is tested against this one.
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
import numpy.typing as npt
from scipy import ndimage

__all__ = ["SSIM_SIGMA", "SSIM_WINDOW", "MetricsError", "psnr", "ssim", "ssim_map"]

SSIM_WINDOW = 11  # pixels per side of the Gaussian window (Wang et al. 2004, 3DGS)
SSIM_SIGMA = 1.5  # its standard deviation in pixels
# scipy's Gaussian reaches int(truncate * sigma + 0.5) = 5 pixels each side: an 11-tap window.
_TRUNCATE = (SSIM_WINDOW // 2) / SSIM_SIGMA
_K1 = 0.01
_K2 = 0.03
Padding = Literal["reflect", "zeros"]


class MetricsError(ValueError):
    """Images given to a metric do not match in shape or hold non-finite values."""


def _checked_pair(a: npt.ArrayLike, b: npt.ArrayLike) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    x, y = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    if x.shape != y.shape or x.ndim not in (2, 3):
        raise MetricsError(f"need two images [H,W] or [H,W,C] of one shape, got {x.shape} and {y.shape}")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y))):
        raise MetricsError("images must be finite")
    return x, y


def psnr(a: npt.ArrayLike, b: npt.ArrayLike, data_range: float = 1.0) -> float:
    """Peak signal-to-noise ratio in dB of two images of one shape; ``inf`` when they are equal."""
    x, y = _checked_pair(a, b)
    mse = float(np.mean((x - y) ** 2))
    return math.inf if mse == 0.0 else 10.0 * math.log10(data_range**2 / mse)


def ssim_map(a: npt.ArrayLike, b: npt.ArrayLike, data_range: float = 1.0,
             padding: Padding = "reflect") -> npt.NDArray[np.float32]:
    """Per-pixel SSIM [H, W] of two images [H, W] or [H, W, C] (a colour image: mean over channels)."""
    x, y = _checked_pair(a, b)
    planes = [(x, y)] if x.ndim == 2 else [(x[..., c], y[..., c]) for c in range(x.shape[2])]
    mean: npt.NDArray[np.float64] = np.mean([_plane_map(p, q, data_range, padding) for p, q in planes], axis=0)
    return mean.astype(np.float32)


def ssim(a: npt.ArrayLike, b: npt.ArrayLike, data_range: float = 1.0, padding: Padding = "reflect") -> float:
    """Mean SSIM of two images [H, W] or [H, W, C] over pixels (and channels); 1 when they are equal."""
    x, y = _checked_pair(a, b)
    planes = [(x, y)] if x.ndim == 2 else [(x[..., c], y[..., c]) for c in range(x.shape[2])]
    return float(np.mean([_plane_map(p, q, data_range, padding) for p, q in planes]))


def _plane_map(x: npt.NDArray[np.float64], y: npt.NDArray[np.float64], data_range: float,
               padding: Padding) -> npt.NDArray[np.float64]:
    mode = "constant" if padding == "zeros" else "reflect"

    def window(v: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
        return np.asarray(ndimage.gaussian_filter(v, SSIM_SIGMA, truncate=_TRUNCATE, mode=mode, cval=0.0))

    mu_x, mu_y = window(x), window(y)
    var_x = window(x * x) - mu_x * mu_x
    var_y = window(y * y) - mu_y * mu_y
    cov = window(x * y) - mu_x * mu_y
    c1 = (_K1 * data_range) ** 2
    c2 = (_K2 * data_range) ** 2
    num = (2 * mu_x * mu_y + c1) * (2 * cov + c2)
    den = (mu_x * mu_x + mu_y * mu_y + c1) * (var_x + var_y + c2)
    return np.asarray(num / den)
