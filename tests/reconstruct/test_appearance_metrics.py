"""PSNR, SSIM and LPIPS on known cases; LPIPS loads user-supplied weights or says how to get them."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import torch
from drivetwin.worlds.reconstruct.image_metrics import SSIM_SIGMA, SSIM_WINDOW, MetricsError, psnr, ssim
from drivetwin.worlds.reconstruct.lpips import AlexLPIPS, LpipsWeightsError, load_lpips
from scipy.signal import convolve2d


def _image(seed: int = 0, h: int = 48, w: int = 64) -> np.ndarray:
    """A smooth-ish test image in [0.2, 0.8] (room for offsets without clipping)."""
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0:h, 0:w] / 10.0
    base = np.stack([np.sin(x + c) * np.cos(y - c) for c in range(3)], -1)
    return (0.5 + 0.25 * base + 0.05 * rng.uniform(-1, 1, (h, w, 3))).astype(np.float32)


def test_psnr_of_identical_images_is_infinite() -> None:
    img = _image()
    assert psnr(img, img) == math.inf


def test_psnr_of_a_constant_offset_of_a_tenth_is_twenty_db() -> None:
    img = _image()
    assert psnr(img, img + 0.1) == pytest.approx(20.0, abs=1e-4)  # MSE = 0.01


def test_psnr_of_gaussian_noise_matches_its_variance() -> None:
    img = _image()
    sigma = 0.05
    noisy = img + np.random.default_rng(1).normal(0.0, sigma, img.shape)
    assert psnr(img, noisy) == pytest.approx(-10 * math.log10(sigma**2), abs=0.15)  # 26.02 dB


def test_ssim_of_identical_images_is_one() -> None:
    img = _image()
    assert ssim(img, img) == pytest.approx(1.0, abs=1e-9)


def _ssim_reference(a: np.ndarray, b: np.ndarray) -> float:
    """Wang et al.'s SSIM with an 11x11 sigma-1.5 Gaussian, zero padding (3DGS), by 2D convolution."""
    r = np.arange(SSIM_WINDOW) - SSIM_WINDOW // 2
    g = np.exp(-(r**2) / (2 * SSIM_SIGMA**2))
    window = np.outer(g, g) / np.outer(g, g).sum()
    maps = []
    for c in range(3):
        x, y = a[..., c].astype(np.float64), b[..., c].astype(np.float64)

        def blur(m: np.ndarray) -> np.ndarray:
            return convolve2d(m, window, mode="same", boundary="fill")

        mx, my = blur(x), blur(y)
        vx, vy, cxy = blur(x * x) - mx**2, blur(y * y) - my**2, blur(x * y) - mx * my
        c1, c2 = 0.01**2, 0.03**2
        maps.append(((2 * mx * my + c1) * (2 * cxy + c2)) / ((mx**2 + my**2 + c1) * (vx + vy + c2)))
    return float(np.mean(maps))


def test_ssim_matches_a_direct_convolution_reference() -> None:
    a, b = _image(0), _image(0) + np.random.default_rng(2).normal(0, 0.03, (48, 64, 3))
    assert ssim(a, b) == pytest.approx(_ssim_reference(a, b), abs=1e-9)


def test_ssim_falls_as_noise_grows() -> None:
    img = _image()
    rng = np.random.default_rng(3)
    values = [ssim(img, img + rng.normal(0, s, img.shape)) for s in (0.01, 0.05, 0.2)]
    assert 1.0 > values[0] > values[1] > values[2]


def test_metrics_refuse_images_of_different_shapes() -> None:
    with pytest.raises(MetricsError, match="one shape"):
        psnr(_image(), _image(h=40))
    with pytest.raises(MetricsError, match="RGB"):
        ssim(np.zeros((8, 8)), np.zeros((8, 8)))


# LPIPS -------------------------------------------------------------------------------------


def test_lpips_without_weights_says_how_to_get_them(tmp_path: Path) -> None:
    with pytest.raises(LpipsWeightsError, match=r"alex\.pth"):
        load_lpips(None)
    with pytest.raises(LpipsWeightsError, match=r"do not exist.*alexnet-owt"):
        load_lpips(tmp_path / "missing")


def test_lpips_refuses_weights_that_lack_the_heads(tmp_path: Path) -> None:
    torch.manual_seed(0)
    backbone = {k: v for k, v in AlexLPIPS().state_dict().items() if k.startswith("features.")}
    torch.save(backbone, tmp_path / "alexnet.pth")
    with pytest.raises(LpipsWeightsError, match=r"lack lin0\.model\.1\.weight"):
        load_lpips(tmp_path / "alexnet.pth")


@pytest.fixture(scope="module")
def random_lpips(tmp_path_factory: pytest.TempPathFactory) -> tuple[AlexLPIPS, Path]:
    """LPIPS with random weights saved as the two files users supply, loaded by the real loader."""
    torch.manual_seed(0)
    net = AlexLPIPS()
    with torch.no_grad():  # heads are non-negative in trained LPIPS; keep that property
        for k in range(5):
            getattr(net, f"lin{k}").model[1].weight.abs_()
    folder = tmp_path_factory.mktemp("lpips")
    state = net.state_dict()
    torch.save({k: v for k, v in state.items() if k.startswith("features.")}, folder / "alexnet-owt-7be5be79.pth")
    torch.save({k: v for k, v in state.items() if k.startswith("lin")}, folder / "alex.pth")
    return load_lpips(folder), folder


def test_lpips_loaded_from_a_folder_equals_the_saved_network(random_lpips: tuple[AlexLPIPS, Path]) -> None:
    loaded, folder = random_lpips
    torch.manual_seed(0)
    original = AlexLPIPS()  # same seed: same initial weights as the fixture's before abs_
    saved = torch.load(folder / "alex.pth", weights_only=True)
    assert torch.equal(loaded.state_dict()["lin2.model.1.weight"], saved["lin2.model.1.weight"])
    assert torch.equal(loaded.state_dict()["features.6.weight"], original.state_dict()["features.6.weight"])


def test_lpips_reads_the_lpips_package_slice_names(tmp_path: Path, random_lpips: tuple[AlexLPIPS, Path]) -> None:
    net, _ = random_lpips
    slices = {0: 1, 3: 2, 6: 3, 8: 4, 10: 5}
    state = {}
    for key, value in net.state_dict().items():
        if key.startswith("features."):
            index = int(key.split(".")[1])
            state[f"net.slice{slices[index]}.{index}.{key.split('.')[2]}"] = value
        elif key.startswith("lin"):
            state[key] = value
    torch.save(state, tmp_path / "lpips_full.pth")
    again = load_lpips(tmp_path / "lpips_full.pth")
    a, b = _image(0), _image(1)
    assert again.distance(a, b) == pytest.approx(net.distance(a, b), rel=1e-6)


def test_lpips_of_identical_images_is_zero(random_lpips: tuple[AlexLPIPS, Path]) -> None:
    net, _ = random_lpips
    img = _image()
    assert net.distance(img, img) == pytest.approx(0.0, abs=1e-9)


def test_lpips_is_symmetric(random_lpips: tuple[AlexLPIPS, Path]) -> None:
    net, _ = random_lpips
    a, b = _image(0), _image(5)
    assert net.distance(a, b) == pytest.approx(net.distance(b, a), rel=1e-5)


def test_lpips_grows_with_distortion(random_lpips: tuple[AlexLPIPS, Path]) -> None:
    net, _ = random_lpips
    img = _image()
    rng = np.random.default_rng(4)
    values = [net.distance(img, np.clip(img + rng.normal(0, s, img.shape), 0, 1)) for s in (0.02, 0.1, 0.3)]
    assert 0.0 < values[0] < values[1] < values[2]


def test_lpips_refuses_images_too_small_for_alexnet(random_lpips: tuple[AlexLPIPS, Path]) -> None:
    net, _ = random_lpips
    with pytest.raises(MetricsError, match="32x32"):
        net.distance(np.zeros((16, 16, 3)), np.zeros((16, 16, 3)))


def test_the_differentiable_ssim_loss_agrees_with_the_shared_metric() -> None:
    import torch
    from drivetwin.worlds.reconstruct.image_metrics import ssim_torch

    rng = np.random.default_rng(3)
    a = rng.random((24, 20, 3))
    b = np.clip(a + rng.normal(0, 0.1, a.shape), 0, 1)
    with torch.no_grad():
        differentiable = float(ssim_torch(torch.from_numpy(a), torch.from_numpy(b)))
    assert differentiable == pytest.approx(ssim(a, b), abs=1e-9)
