"""Every splat backend draws what the slow reference draws, and follows 3DGS's rules."""

from __future__ import annotations

import numpy as np
import pytest
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.rasterize import (
    ALPHA_MAX,
    RasterizeError,
    rasterize,
)
from drivetwin.worlds.render.splats import SH_C0, Splats

TOLERANCE = 1e-4  # the bar for backend agreement
FAST_BACKENDS = ["numba", "torch"]


def random_scene(n: int, seed: int, sh_degree: int) -> Splats:
    """Anisotropic, rotated splats with SH, 2-6 m in front of a camera at the origin."""
    rng = np.random.default_rng(seed)
    return Splats(
        means=rng.uniform([-1.5, -1.0, 2.0], [1.5, 1.0, 6.0], (n, 3)),
        quats=rng.normal(size=(n, 4)),
        log_scales=rng.uniform(-3.0, -1.2, (n, 3)),
        opacity_logits=rng.normal(1.0, 2.0, n),
        sh=rng.normal(0.0, 0.5, (n, (sh_degree + 1) ** 2, 3)),
    )


def small_camera(width: int = 45, height: int = 33) -> Camera:
    # Odd sizes exercise partial tiles; an off-centre principal point exercises cx, cy.
    view = np.eye(4)
    return Camera(width, height, fx=40.0, fy=42.0, cx=width / 2 + 1.3, cy=height / 2 - 0.7,
                  world_to_camera=view)  # fmt: skip


def assert_same_image(fast, reference) -> None:
    for name in ("rgb", "alpha", "transmittance", "depth"):
        error = np.abs(getattr(fast, name) - getattr(reference, name)).max()
        assert error < TOLERANCE, f"{name} differs by {error}"
    if reference.index is not None:
        assert np.array_equal(fast.index, reference.index)


@pytest.mark.parametrize("backend", FAST_BACKENDS)
@pytest.mark.parametrize(("seed", "sh_degree"), [(0, 0), (1, 1), (2, 3)])
def test_backend_matches_reference_on_random_scenes(backend, seed, sh_degree):
    splats, camera = random_scene(120, seed, sh_degree), small_camera()
    reference = rasterize(splats, camera, backend="reference", return_index=True)
    assert reference.alpha.mean() > 0.2 and (reference.index >= 0).mean() > 0.1  # not trivial
    assert_same_image(rasterize(splats, camera, backend=backend, return_index=True), reference)


@pytest.mark.parametrize("backend", FAST_BACKENDS)
def test_backend_matches_reference_with_a_depth_limit(backend):
    splats, camera = random_scene(120, 3, 2), small_camera()
    limit = np.random.default_rng(7).uniform(2.0, 6.0, (camera.height, camera.width))
    limit[:5] = np.inf  # rows without a mesh
    reference = rasterize(splats, camera, backend="reference", depth_limit=limit, return_index=True)
    unlimited = rasterize(splats, camera, backend="reference")
    assert np.abs(reference.alpha - unlimited.alpha).max() > 0.1  # the limit matters here
    out = rasterize(splats, camera, backend=backend, depth_limit=limit, return_index=True)
    assert_same_image(out, reference)


def test_background_fills_what_the_splats_leave_through():
    splats, camera = random_scene(60, 4, 0), small_camera()
    plain = rasterize(splats, camera, backend="numba")
    blue = rasterize(splats, camera, backend="numba", background=(0.0, 0.0, 1.0))
    expected = plain.rgb + plain.transmittance[..., None] * np.array([0.0, 0.0, 1.0])
    assert np.allclose(blue.rgb, expected, atol=1e-6)
    assert np.allclose(plain.transmittance, 1.0 - plain.alpha)


def one_splat(z: float, *, x: float = 0.0, opacity: float = 0.5, scale: float = 0.3,
              rgb: tuple[float, float, float] = (1.0, 0.0, 0.0)) -> Splats:  # fmt: skip
    dc = (np.asarray(rgb, dtype=np.float64) - 0.5) / SH_C0
    return Splats(
        means=[[x, 0.0, z]],
        quats=[[1.0, 0.0, 0.0, 0.0]],
        log_scales=np.log([[scale, scale, scale]]),
        opacity_logits=[np.log(opacity / (1.0 - opacity))],
        sh=dc.reshape(1, 1, 3),
    )


def centred_camera() -> Camera:
    # Odd size: the principal point is the centre of pixel (16, 16), where a splat on the
    # optical axis has exactly its opacity as alpha.
    return Camera(33, 33, fx=30.0, fy=30.0, cx=16.5, cy=16.5, world_to_camera=np.eye(4), near=0.5)


@pytest.mark.parametrize("backend", ["reference", *FAST_BACKENDS])
def test_alpha_is_clamped_at_0_99(backend):
    out = rasterize(one_splat(3.0, opacity=0.99999), centred_camera(), backend=backend)
    assert out.alpha[16, 16] == pytest.approx(ALPHA_MAX, abs=1e-6)
    assert out.transmittance[16, 16] == pytest.approx(1.0 - ALPHA_MAX, abs=1e-6)


@pytest.mark.parametrize("backend", ["reference", *FAST_BACKENDS])
def test_a_splat_that_would_end_the_pixel_is_excluded_and_ends_it(backend):
    # Four 0.95-opaque splats in a row: after three T = 1.25e-4; the fourth would take it
    # to 6.25e-6 < 1e-4, so 3DGS stops there and never adds the (very bright) fourth.
    colours = [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
    parts = [one_splat(2.0 + i, opacity=0.95, rgb=c) for i, c in enumerate(colours)]
    bright = one_splat(5.0, opacity=0.95)
    bright.sh[:] = 1e4  # colour about 2821: visible if it were composited at all
    out = rasterize(Splats.concat([*parts, bright]), centred_camera(), backend=backend)
    weights = np.array([0.95, 0.05 * 0.95, 0.0025 * 0.95])
    assert np.allclose(out.rgb[16, 16], weights, atol=1e-5)
    assert out.transmittance[16, 16] == pytest.approx(1.25e-4, rel=1e-4)


@pytest.mark.parametrize("backend", ["reference", *FAST_BACKENDS])
def test_fragments_below_one_255th_are_skipped(backend):
    faint = rasterize(one_splat(3.0, opacity=0.0035), centred_camera(), backend=backend)
    assert faint.alpha.max() == 0.0
    visible = rasterize(one_splat(3.0, opacity=0.0045), centred_camera(), backend=backend)
    assert visible.alpha[16, 16] == pytest.approx(0.0045, rel=1e-5)
    # Three pixels out it would still have 0.6 of its peak, but that is below 1/255: skipped.
    assert visible.alpha[16, 19] == 0.0 and visible.alpha[16, 17] > 0.0


@pytest.mark.parametrize("backend", ["reference", *FAST_BACKENDS])
def test_splats_in_front_of_the_near_plane_or_behind_the_camera_are_culled(backend):
    camera = centred_camera()  # near = 0.5 m
    for z in (0.4, -2.0):
        assert rasterize(one_splat(z, scale=0.2), camera, backend=backend).alpha.max() == 0.0
    assert rasterize(one_splat(0.6, scale=0.2), camera, backend=backend).alpha.max() > 0.4


@pytest.mark.parametrize("backend", ["reference", *FAST_BACKENDS])
def test_depth_limit_drops_splats_at_or_behind_it(backend):
    camera, splat = centred_camera(), one_splat(3.0)
    at = rasterize(splat, camera, backend=backend, depth_limit=np.full((33, 33), 3.0))
    before = rasterize(splat, camera, backend=backend, depth_limit=np.full((33, 33), 3.001))
    assert at.alpha.max() == 0.0
    assert before.alpha[16, 16] == pytest.approx(0.5, rel=1e-5)


@pytest.mark.parametrize("backend", ["reference", *FAST_BACKENDS])
def test_depth_is_the_alpha_weighted_camera_z(backend):
    near, far = one_splat(2.0, opacity=0.5), one_splat(4.0, opacity=0.5)
    out = rasterize(Splats.concat([far, near]), centred_camera(), backend=backend)
    # weights 0.5 (z=2) and 0.25 (z=4): expected depth (1 + 1) / 0.75
    assert out.depth[16, 16] == pytest.approx(2.0 / 0.75, rel=1e-5)
    assert out.depth[0, 0] == 0.0 and out.alpha[0, 0] == 0.0


@pytest.mark.parametrize("backend", ["reference", *FAST_BACKENDS])
def test_index_names_the_front_most_opaque_splat(backend):
    faint_front = one_splat(2.0, opacity=0.3)  # below the 0.5 index threshold
    solid_middle = one_splat(3.0, opacity=0.9)
    solid_back = one_splat(4.0, opacity=0.9)
    splats = Splats.concat([solid_back, faint_front, solid_middle])
    out = rasterize(splats, centred_camera(), backend=backend, return_index=True)
    assert out.index[16, 16] == 2
    assert out.index[0, 0] == -1
    assert rasterize(splats, centred_camera(), backend=backend).index is None


def test_an_empty_splat_set_draws_nothing():
    out = rasterize(Splats.empty(), centred_camera(), backend="numba", return_index=True)
    assert out.alpha.max() == 0.0 and out.transmittance.min() == 1.0
    assert (out.index == -1).all()


def test_rasterize_refuses_bad_arguments_with_what_is_allowed():
    splats, camera = one_splat(3.0), centred_camera()
    with pytest.raises(RasterizeError, match="choose one of"):
        rasterize(splats, camera, backend="vulkan")  # type: ignore[arg-type]
    with pytest.raises(RasterizeError, match=r"depth_limit must be \[H, W\]"):
        rasterize(splats, camera, depth_limit=np.ones((4, 4)))
    with pytest.raises(RasterizeError, match="background"):
        rasterize(splats, camera, background=(1.0, 0.0))
    splats.means[0, 0] = np.nan
    with pytest.raises(RasterizeError, match="means contains NaN"):
        rasterize(splats, camera)


def test_gsplat_backend_says_what_it_needs_when_absent():
    pytest.importorskip("torch")
    import importlib.util

    import torch

    if importlib.util.find_spec("gsplat") is not None and torch.cuda.is_available():
        pytest.skip("gsplat and CUDA are present; this checks the message when they are not")
    with pytest.raises(RasterizeError, match="gsplat"):
        rasterize(one_splat(3.0), centred_camera(), backend="gsplat")


def test_timings_report_each_stage():
    out = rasterize(random_scene(50, 5, 0), small_camera(), backend="numba")
    assert {"project", "bin", "composite", "total"} <= out.timings.keys()
    assert out.backend == "numba"


@pytest.mark.parametrize("backend", ["reference", *FAST_BACKENDS])
def test_splats_at_exactly_the_same_depth_draw_in_id_order(backend):
    splats = Splats.concat(
        [one_splat(3.0, rgb=(0.0, 0.0, 1.0))]
        + [one_splat(4.0, rgb=(0.0, 1.0, 0.0))] * 5
        + [one_splat(3.0, rgb=(1.0, 0.0, 0.0))]
    )
    out = rasterize(splats, centred_camera(), backend=backend, return_index=True)
    assert out.index[16, 16] == 0  # blue, the lower id of the two at 3 m, is in front
    assert out.rgb[16, 16, 2] == pytest.approx(0.5, rel=1e-5)
    assert out.rgb[16, 16, 0] == pytest.approx(0.25, rel=1e-5)
