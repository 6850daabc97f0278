"""FID, KID and CMMD estimators, checked on feature sets drawn from known distributions."""

from __future__ import annotations

import numpy as np
import pytest
from drivetwin.worlds.enhance import EnhanceInputError, cmmd, fid, kid
from drivetwin.worlds.enhance.metrics import mmd2_unbiased

DIM = 8


def gaussian(n: int, mean: float = 0.0, std: float = 1.0, seed: int = 0) -> np.ndarray:
    return np.random.default_rng(seed).normal(mean, std, (n, DIM))


def test_fid_of_identical_sets_is_zero() -> None:
    x = gaussian(500)
    assert fid(x, x.copy()) == pytest.approx(0.0, abs=1e-6)


def test_fid_between_unit_gaussians_is_the_squared_mean_shift() -> None:
    mu = np.full(DIM, 0.5)  # |mu|² = 2
    x = gaussian(20_000, seed=1)
    y = gaussian(20_000, seed=2) + mu
    assert fid(x, y) == pytest.approx(float(mu @ mu), rel=0.05)


def test_fid_sees_a_change_of_spread() -> None:
    # N(0, I) vs N(0, 4 I): tr(I + 4I - 2 * 2I) = DIM.
    assert fid(gaussian(20_000, seed=3), gaussian(20_000, std=2.0, seed=4)) == pytest.approx(
        DIM, rel=0.05
    )


def test_kid_is_unbiased_for_sets_from_one_distribution() -> None:
    rng = np.random.default_rng(5)
    pairs = [(rng.normal(size=(40, DIM)), rng.normal(size=(40, DIM))) for _ in range(300)]
    draws = [mmd2_unbiased(x, y) for x, y in pairs]
    mean, spread = float(np.mean(draws)), float(np.std(draws)) / np.sqrt(len(draws))
    assert abs(mean) < 3 * spread  # zero within three standard errors
    assert min(draws) < 0.0  # an unbiased estimate of a zero distance must go negative


def test_the_biased_estimator_would_fail_the_unbiasedness_check() -> None:
    # Guard that the check above can fail: keeping the diagonal makes the mean clearly > 0.
    rng = np.random.default_rng(6)

    def biased(x: np.ndarray, y: np.ndarray) -> float:
        k = lambda p, q: (p @ q.T / DIM + 1.0) ** 3  # noqa: E731
        return float(k(x, x).mean() + k(y, y).mean() - 2 * k(x, y).mean())

    draws = [biased(rng.normal(size=(40, DIM)), rng.normal(size=(40, DIM))) for _ in range(300)]
    assert np.mean(draws) > 3 * np.std(draws) / np.sqrt(len(draws))


def test_kid_grows_with_the_distance_between_distributions() -> None:
    x = gaussian(400, seed=7)
    near, _ = kid(x, gaussian(400, mean=0.2, seed=8), subsets=20, subset_size=200)
    far, _ = kid(x, gaussian(400, mean=1.0, seed=9), subsets=20, subset_size=200)
    same, _ = kid(x, gaussian(400, seed=10), subsets=20, subset_size=200)
    assert abs(same) < near < far


def test_kid_uses_subsets_no_larger_than_the_sets() -> None:
    mean, std = kid(gaussian(30, seed=11), gaussian(50, seed=12), subsets=5)
    assert np.isfinite(mean) and std >= 0.0


def reference_cmmd(x: np.ndarray, y: np.ndarray, sigma: float = 10.0) -> float:
    """CMMD by double loops over all pairs (diagonals included), times 1000."""

    def mean_k(p: np.ndarray, q: np.ndarray) -> float:
        return float(
            np.mean([[np.exp(-np.sum((a - b) ** 2) / (2 * sigma**2)) for b in q] for a in p])
        )

    return 1000.0 * (mean_k(x, x) + mean_k(y, y) - 2 * mean_k(x, y))


def unit(rows: np.ndarray) -> np.ndarray:
    return rows / np.linalg.norm(rows, axis=1, keepdims=True)


def test_cmmd_matches_the_pairwise_reference() -> None:
    x, y = unit(gaussian(30, seed=13)), unit(gaussian(25, mean=0.3, seed=14))
    assert cmmd(x, y) == pytest.approx(reference_cmmd(x, y), rel=1e-9)


def test_cmmd_is_zero_for_identical_sets_and_grows_with_a_shift() -> None:
    x = unit(gaussian(200, seed=15))
    assert cmmd(x, x) == pytest.approx(0.0, abs=1e-9)
    near = cmmd(x, unit(gaussian(200, mean=0.2, seed=16)))
    far = cmmd(x, unit(gaussian(200, mean=1.0, seed=17)))
    assert 0.0 < near < far


@pytest.mark.parametrize(
    ("a", "b", "message"),
    [
        (np.zeros((5, 3)), np.zeros((5, 4)), "feature sizes differ"),
        (np.zeros(5), np.zeros((5, 4)), r"2-D array \[N, D\]"),
        (np.full((5, 3), np.nan), np.zeros((5, 3)), "finite"),
    ],
)
def test_malformed_feature_sets_are_refused(a: np.ndarray, b: np.ndarray, message: str) -> None:
    with pytest.raises(EnhanceInputError, match=message):
        fid(a, b)
