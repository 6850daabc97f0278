"""The structure check: SSIM, edge maps, depth disagreement and the rejection rule."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import draw_depth, draw_street
from drivetwin.worlds.enhance import EnhanceInputError, EnhanceSettings, structure_score
from drivetwin.worlds.enhance.structure import (
    depth_disagreement,
    ssim,
    ssim_map,
    worst_tile_mean,
)

SETTINGS = EnhanceSettings(model="unused")


def reference_ssim_map(a: np.ndarray, b: np.ndarray, data_range: float = 1.0) -> np.ndarray:
    """Obviously-correct SSIM: explicit 11 x 11 Gaussian weights at every pixel."""
    sigma, radius = 1.5, 5
    taps = np.exp(-0.5 * (np.arange(-radius, radius + 1) / sigma) ** 2)
    weights = np.outer(taps, taps) / np.outer(taps, taps).sum()
    pa = np.pad(a.astype(np.float64), radius, mode="symmetric")
    pb = np.pad(b.astype(np.float64), radius, mode="symmetric")
    c1, c2 = (0.01 * data_range) ** 2, (0.03 * data_range) ** 2
    out = np.zeros(a.shape)
    for i in range(a.shape[0]):
        for j in range(a.shape[1]):
            wa = pa[i : i + 2 * radius + 1, j : j + 2 * radius + 1]
            wb = pb[i : i + 2 * radius + 1, j : j + 2 * radius + 1]
            ma, mb = (weights * wa).sum(), (weights * wb).sum()
            va = (weights * (wa - ma) ** 2).sum()
            vb = (weights * (wb - mb) ** 2).sum()
            cov = (weights * (wa - ma) * (wb - mb)).sum()
            out[i, j] = ((2 * ma * mb + c1) * (2 * cov + c2)) / (
                (ma**2 + mb**2 + c1) * (va + vb + c2)
            )
    return out


def test_ssim_matches_the_per_pixel_reference() -> None:
    rng = np.random.default_rng(1)
    a = rng.random((20, 24)).astype(np.float32)
    b = np.clip(a + rng.normal(0, 0.2, a.shape), 0, 1).astype(np.float32)
    np.testing.assert_allclose(ssim_map(a, b), reference_ssim_map(a, b), atol=1e-5)


def test_ssim_of_an_image_with_itself_is_one_and_of_noise_is_low() -> None:
    rng = np.random.default_rng(2)
    a = rng.random((32, 32)).astype(np.float32)
    assert ssim(a, a) == pytest.approx(1.0, abs=1e-6)
    assert ssim(a, rng.random((32, 32)).astype(np.float32)) < 0.2


def test_an_unchanged_frame_scores_one_and_is_accepted() -> None:
    frame = draw_street()
    score = structure_score(frame, frame.copy(), SETTINGS)
    assert score.edge_ssim_worst_tile == pytest.approx(1.0, abs=1e-6)
    assert score.luminance_ssim == pytest.approx(1.0, abs=1e-6)
    assert score.structure_distance == pytest.approx(0.0, abs=1e-6)
    assert score.accepted


@pytest.mark.parametrize(
    "change",
    ["brighter", "darker", "warm tint", "texture noise", "night grading"],
)
def test_appearance_changes_keep_the_frame(change: str) -> None:
    base = draw_street().astype(np.float32)
    rng = np.random.default_rng(3)
    changed = {
        "brighter": base + 25,
        "darker": base * 0.6,
        "warm tint": base * np.array([1.1, 0.95, 0.8]),
        "texture noise": base + rng.normal(0, 12, base.shape),
        "night grading": base * np.array([0.35, 0.4, 0.55]) + 5,
    }[change]
    enhanced = np.clip(changed, 0, 255).astype(np.uint8)
    score = structure_score(draw_street(), enhanced, SETTINGS)
    assert score.accepted, score.reason


@pytest.mark.parametrize("shift_px", [6, 12, 30])
def test_a_frame_whose_car_was_moved_is_rejected(shift_px: int) -> None:
    baseline = draw_street()
    moved = draw_street(car_x=60 + shift_px)
    score = structure_score(baseline, moved, SETTINGS)
    assert not score.accepted
    assert "edge structure distance" in score.reason
    assert score.structure_distance > SETTINGS.max_structure_distance


def test_a_moved_car_is_rejected_even_under_new_lighting() -> None:
    moved_and_brighter = np.clip(draw_street(car_x=75).astype(int) + 20, 0, 255)
    score = structure_score(draw_street(), moved_and_brighter.astype(np.uint8), SETTINGS)
    assert not score.accepted


def test_the_worst_tile_catches_a_change_that_the_global_mean_hides() -> None:
    score = structure_score(draw_street(), draw_street(car_x=66), SETTINGS)
    # 1 - global mean is well inside the limit: the mean alone would have let it through.
    assert 1.0 - score.edge_ssim < SETTINGS.max_structure_distance
    assert not score.accepted


def test_luminance_limit_rejects_relighting_only_when_asked() -> None:
    dark = (draw_street() * 0.3).astype(np.uint8)
    strict = EnhanceSettings(model="unused", max_luminance_distance=0.05)
    assert structure_score(draw_street(), dark, SETTINGS).accepted
    verdict = structure_score(draw_street(), dark, strict)
    assert not verdict.accepted and "luminance" in verdict.reason


def test_worst_tile_mean_picks_the_lowest_tile() -> None:
    values = np.ones((8, 8), np.float32)
    values[6:, 6:] = 0.0
    assert worst_tile_mean(values, grid=4) == 0.0
    assert worst_tile_mean(values, grid=2) == pytest.approx(0.75)


def disparity(car_x: int = 60) -> np.ndarray:
    """Relative inverse depth, as monocular estimators return it (sky = 0)."""
    depth = draw_depth(car_x=car_x)
    return np.where(np.isfinite(depth), 1.0 / depth, 0.0)


def test_depth_disagreement_ignores_scale_and_shift() -> None:
    base = disparity()
    assert depth_disagreement(base, base * 3.0 + 7.0) == pytest.approx(0.0, abs=1e-4)


def test_depth_disagreement_sees_a_moved_vehicle_but_tolerates_estimator_noise() -> None:
    base = disparity()
    noisy = base * (1.0 + np.random.default_rng(4).normal(0.0, 0.05, base.shape))
    assert depth_disagreement(base, noisy) < SETTINGS.max_depth_disagreement
    assert depth_disagreement(base, disparity(car_x=90)) > SETTINGS.max_depth_disagreement


def test_a_depth_estimator_that_sees_a_different_layout_rejects_the_frame() -> None:
    # A "depth estimator" reading the red car's position from the image itself.
    def estimator(frame: np.ndarray) -> np.ndarray:
        red = (frame[..., 0] > 150) & (frame[..., 1] < 80)
        return np.where(red, 1.0, 10.0).astype(np.float32)

    strict = EnhanceSettings(model="unused", max_structure_distance=2.0)
    same = structure_score(draw_street(), draw_street(seed=1), strict, estimator)
    assert same.accepted and same.depth_disagreement == pytest.approx(0.0, abs=1e-6)
    moved = structure_score(draw_street(), draw_street(car_x=90), strict, estimator)
    assert not moved.accepted and "depth disagreement" in moved.reason


@pytest.mark.parametrize(
    ("frame", "message"),
    [
        (np.zeros((96, 128), np.uint8), "shape"),
        (np.zeros((96, 128, 4), np.uint8), "shape"),
        (np.zeros((96, 128, 3), np.float32), "uint8"),
    ],
)
def test_a_frame_of_the_wrong_kind_is_refused_with_the_reason(
    frame: np.ndarray, message: str
) -> None:
    with pytest.raises(EnhanceInputError, match=message):
        structure_score(draw_street(), frame, SETTINGS)


def test_frames_of_different_sizes_are_refused() -> None:
    with pytest.raises(EnhanceInputError, match="differ in size"):
        structure_score(draw_street(), draw_street()[:64], SETTINGS)
