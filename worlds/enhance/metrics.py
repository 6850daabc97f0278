"""Distribution distances between feature sets: FID, KID and CMMD (numpy and scipy only).

Every function takes two feature arrays [N, D] and [M, D] (rows are images). They are the
estimators themselves; the feature extractors live in `extractors`.
"""

from __future__ import annotations

import numpy as np
from drivetwin.worlds.enhance.settings import EnhanceInputError
from numpy.typing import ArrayLike, NDArray
from scipy import linalg

# KID as in Bińkowski et al. (2018) and clean-fid: 100 subsets of up to 1000 images.
KID_SUBSETS = 100
KID_SUBSET_SIZE = 1000
# CMMD (Jayasumana et al. 2024): Gaussian RBF bandwidth on unit CLIP embeddings, and a
# x1000 scale so typical values read as small numbers rather than 1e-3.
CMMD_SIGMA = 10.0
CMMD_SCALE = 1000.0
# Added to the covariance diagonals when their product's square root is singular
# (as pytorch-fid does).
_FID_EPS = 1e-6
# Imaginary parts of sqrtm larger than this mean the covariances are not PSD-like.
_IMAG_TOLERANCE = 1e-3


def _features(x: ArrayLike, name: str, min_rows: int = 2) -> NDArray[np.float64]:
    arr = np.asarray(x, dtype=np.float64)
    if arr.ndim != 2 or arr.shape[0] < min_rows or not np.isfinite(arr).all():
        raise EnhanceInputError(
            f"{name} must be a finite 2-D array [N, D] with N >= {min_rows}; got {arr.shape}"
        )
    return arr


def _pair(
    a: ArrayLike, b: ArrayLike, min_rows: int = 2
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    x, y = _features(a, "first features", min_rows), _features(b, "second features", min_rows)
    if x.shape[1] != y.shape[1]:
        raise EnhanceInputError(f"feature sizes differ: {x.shape[1]} and {y.shape[1]}")
    return x, y


def frechet_distance(
    mu1: NDArray[np.float64],
    sigma1: NDArray[np.float64],
    mu2: NDArray[np.float64],
    sigma2: NDArray[np.float64],
) -> float:
    """Fréchet distance of two Gaussians: |mu1 - mu2|² + tr(S1 + S2 - 2 (S1 S2)^½)."""
    covmean = linalg.sqrtm(sigma1 @ sigma2)
    if not np.isfinite(covmean).all():
        offset = np.eye(sigma1.shape[0]) * _FID_EPS
        covmean = linalg.sqrtm((sigma1 + offset) @ (sigma2 + offset))
    if np.iscomplexobj(covmean):
        if np.abs(covmean.imag).max() > _IMAG_TOLERANCE * max(1.0, np.abs(covmean.real).max()):
            raise EnhanceInputError("covariances are not positive semi-definite; use more images")
        covmean = covmean.real
    diff = mu1 - mu2
    return float(diff @ diff + np.trace(sigma1) + np.trace(sigma2) - 2.0 * np.trace(covmean))


def fid(a: ArrayLike, b: ArrayLike) -> float:
    """FID: Fréchet distance of Gaussians fitted to two feature sets [N, D], [M, D]."""
    x, y = _pair(a, b)
    return frechet_distance(
        x.mean(axis=0), np.cov(x, rowvar=False), y.mean(axis=0), np.cov(y, rowvar=False)
    )


def _poly_kernel(x: NDArray[np.float64], y: NDArray[np.float64]) -> NDArray[np.float64]:
    # The cubic polynomial kernel of KID: (x·y / d + 1)^3.
    return np.asarray((x @ y.T / x.shape[1] + 1.0) ** 3)


def mmd2_unbiased(x: NDArray[np.float64], y: NDArray[np.float64]) -> float:
    """Unbiased MMD² with the cubic polynomial kernel (the diagonal terms left out)."""
    m, n = x.shape[0], y.shape[0]
    kxx, kyy, kxy = _poly_kernel(x, x), _poly_kernel(y, y), _poly_kernel(x, y)
    within_x = (kxx.sum() - np.trace(kxx)) / (m * (m - 1))
    within_y = (kyy.sum() - np.trace(kyy)) / (n * (n - 1))
    return float(within_x + within_y - 2.0 * kxy.mean())


def kid(
    a: ArrayLike,
    b: ArrayLike,
    subsets: int = KID_SUBSETS,
    subset_size: int = KID_SUBSET_SIZE,
    seed: int = 0,
) -> tuple[float, float]:
    """KID: mean and standard deviation of unbiased MMD² over random subsets.

    Subsets of min(subset_size, N, M) rows are drawn without replacement. The estimate is
    unbiased, so for two sets from one distribution it scatters around 0 and can be < 0.
    """
    x, y = _pair(a, b)
    if subsets < 1:
        raise EnhanceInputError(f"subsets must be >= 1; got {subsets}")
    size = min(subset_size, x.shape[0], y.shape[0])
    rng = np.random.default_rng(seed)
    values = [
        mmd2_unbiased(
            x[rng.choice(x.shape[0], size, replace=False)],
            y[rng.choice(y.shape[0], size, replace=False)],
        )
        for _ in range(subsets)
    ]
    return float(np.mean(values)), float(np.std(values))


def cmmd(a: ArrayLike, b: ArrayLike, sigma: float = CMMD_SIGMA, scale: float = CMMD_SCALE) -> float:
    """CMMD: MMD² with a Gaussian RBF kernel on (unit) CLIP embeddings, times `scale`.

    Follows the reference implementation: means over all pairs, diagonals included.
    """
    x, y = _pair(a, b, min_rows=1)
    gamma = 1.0 / (2.0 * sigma**2)

    def mean_kernel(p: NDArray[np.float64], q: NDArray[np.float64]) -> float:
        sq = (p * p).sum(1)[:, None] + (q * q).sum(1)[None, :] - 2.0 * p @ q.T
        return float(np.exp(-gamma * np.maximum(sq, 0.0)).mean())

    return scale * (mean_kernel(x, x) + mean_kernel(y, y) - 2.0 * mean_kernel(x, y))
