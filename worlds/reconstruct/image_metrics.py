"""Image quality metrics of novel-view synthesis: PSNR and SSIM as the 3DGS papers compute them.

Images are RGB [H,W,3] in 0..1. PSNR and SSIM are the project's own (drivetwin.worlds.image_metrics);
SSIM with zero padding of half a window, as the 3DGS reference code (``ssim`` in loss_utils) does.
``ssim_torch`` is the differentiable form the fit's D-SSIM loss uses, tested against it. LPIPS is
in ``lpips``.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
import torch
import torch.nn.functional as F
from drivetwin.worlds import image_metrics
from drivetwin.worlds.image_metrics import SSIM_SIGMA, SSIM_WINDOW, MetricsError

__all__ = ["SSIM_SIGMA", "SSIM_WINDOW", "MetricsError", "psnr", "ssim", "ssim_torch"]

# Stabilising constants for a dynamic range of 1: (K * L)^2 with K1 = 0.01, K2 = 0.03.
_C1 = 0.01**2
_C2 = 0.03**2


def _checked_pair(a: npt.ArrayLike, b: npt.ArrayLike) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    x, y = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    if x.shape != y.shape or x.ndim != 3 or x.shape[2] != 3:
        raise MetricsError(f"need two RGB images [H,W,3] of one shape, got {x.shape} and {y.shape}")
    return x, y


def psnr(a: npt.ArrayLike, b: npt.ArrayLike) -> float:
    """Peak signal-to-noise ratio (dB) of two RGB images in 0..1; ``inf`` when they are equal."""
    return image_metrics.psnr(*_checked_pair(a, b))


def _gaussian_window(channels: int, dtype: torch.dtype, device: torch.device) -> torch.Tensor:
    coords = torch.arange(SSIM_WINDOW, dtype=torch.float64) - SSIM_WINDOW // 2
    g = torch.exp(-(coords**2) / (2 * SSIM_SIGMA**2))
    g = g / g.sum()
    window = torch.outer(g, g).to(dtype=dtype, device=device)
    return window.expand(channels, 1, SSIM_WINDOW, SSIM_WINDOW).contiguous()


def ssim_torch(x: torch.Tensor, y: torch.Tensor) -> torch.Tensor:
    """Differentiable mean SSIM of images [H,W,3] or batches [B,H,W,3] (one dtype and device)."""
    if x.shape != y.shape or x.shape[-1] != 3 or x.dim() not in (3, 4):
        raise MetricsError(f"need RGB images [H,W,3] or [B,H,W,3] of one shape, got {tuple(x.shape)}, {tuple(y.shape)}")
    a = (x if x.dim() == 4 else x[None]).permute(0, 3, 1, 2)
    b = (y if y.dim() == 4 else y[None]).permute(0, 3, 1, 2)
    window = _gaussian_window(3, a.dtype, a.device)
    pad = SSIM_WINDOW // 2
    mu_a = F.conv2d(a, window, padding=pad, groups=3)
    mu_b = F.conv2d(b, window, padding=pad, groups=3)
    var_a = F.conv2d(a * a, window, padding=pad, groups=3) - mu_a * mu_a
    var_b = F.conv2d(b * b, window, padding=pad, groups=3) - mu_b * mu_b
    cov = F.conv2d(a * b, window, padding=pad, groups=3) - mu_a * mu_b
    numerator = (2 * mu_a * mu_b + _C1) * (2 * cov + _C2)
    denominator = (mu_a * mu_a + mu_b * mu_b + _C1) * (var_a + var_b + _C2)
    return (numerator / denominator).mean()


def ssim(a: npt.ArrayLike, b: npt.ArrayLike) -> float:
    """Structural similarity (3DGS's Gaussian-window SSIM) of two RGB images in 0..1; 1 when equal."""
    return image_metrics.ssim(*_checked_pair(a, b), padding="zeros")
