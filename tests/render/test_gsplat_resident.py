"""The gsplat path's resident splats and GPU depth-limit cull: same rule as the NumPy reference."""

from __future__ import annotations

import gc
import importlib.util

import numpy as np
import pytest
import torch
from drivetwin.worlds.render._gsplat_resident import (
    ResidentSplatsCache,
    depth_limit_keep_mask,
    depth_limit_keep_mask_numpy,
)
from drivetwin.worlds.render._torch_raster import cull_behind_depth_limit
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.splats import Splats
from hypothesis import given, settings
from hypothesis import strategies as st

CPU = torch.device("cpu")


def scene_splats(count: int, seed: int) -> Splats:
    rng = np.random.default_rng(seed)
    return Splats(
        means=rng.uniform(-6.0, 6.0, (count, 3)),
        quats=rng.normal(size=(count, 4)) + np.array([3.0, 0.0, 0.0, 0.0]),  # near identity, never zero
        log_scales=rng.uniform(-3.0, -1.0, (count, 3)),
        opacity_logits=rng.normal(size=count),
        sh=rng.normal(size=(count, 4, 3)),
    )


def posed_camera(seed: int, width: int = 37, height: int = 23) -> Camera:
    rng = np.random.default_rng(seed)
    eye = rng.uniform(-3.0, 3.0, 3)
    target = eye + rng.normal(size=3)
    return Camera.from_look_at(eye, target, width=width, height=height, fovy_deg=float(rng.uniform(30.0, 100.0)))


def depth_limit_image(camera: Camera, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    limit = rng.uniform(0.0, 9.0, (camera.height, camera.width)).astype(np.float32)
    limit[rng.random(limit.shape) < 0.2] = np.inf  # sky: no limit
    return limit


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), count=st.integers(1, 400))
def test_torch_cull_keeps_exactly_the_splats_the_numpy_reference_keeps(seed: int, count: int) -> None:
    splats, camera = scene_splats(count, seed), posed_camera(seed)
    limit = depth_limit_image(camera, seed)
    expected = depth_limit_keep_mask_numpy(splats.means, camera, limit)
    got = depth_limit_keep_mask(torch.as_tensor(splats.means), camera, torch.as_tensor(limit))
    assert got.dtype == torch.bool
    assert np.array_equal(got.numpy(), expected)


def test_torch_cull_subset_equals_cull_behind_depth_limit() -> None:
    splats, camera = scene_splats(3000, 7), posed_camera(7)
    limit = depth_limit_image(camera, 7)
    reference = cull_behind_depth_limit(splats, camera, limit)
    resident = ResidentSplatsCache().get(splats, CPU)
    kept = resident.subset(depth_limit_keep_mask(resident.means, camera, torch.as_tensor(limit)))
    assert 0 < len(kept) < len(splats)  # the limit drops some and keeps some
    assert np.array_equal(kept.means.numpy(), reference.means)
    assert np.array_equal(kept.sh.numpy(), reference.sh)
    assert np.allclose(kept.scales.numpy(), np.exp(reference.log_scales), rtol=1e-6)


def test_torch_cull_keeps_splats_behind_the_camera_for_gsplat_to_cull() -> None:
    camera = Camera(8, 6, fx=10.0, fy=10.0, cx=4.0, cy=3.0, world_to_camera=np.eye(4), near=0.5)
    means = torch.tensor([[0.0, 0.0, -2.0], [0.0, 0.0, 0.2], [0.0, 0.0, 2.0]])
    wall = torch.full((6, 8), 1.0)  # everything in front of the near plane lies behind it
    assert depth_limit_keep_mask(means, camera, wall).tolist() == [True, True, False]


def test_torch_cull_reads_the_nearest_edge_pixel_for_means_outside_the_image() -> None:
    camera = Camera(8, 6, fx=10.0, fy=10.0, cx=4.0, cy=3.0, world_to_camera=np.eye(4))
    limit = torch.full((6, 8), 10.0)
    limit[:, 0] = 1.0  # a near wall along the left edge only
    limit[5, :] = 1.0  # and along the bottom edge
    means = torch.tensor([[-50.0, 0.0, 3.0], [50.0, 0.0, 3.0], [0.0, 50.0, 3.0], [0.0, -50.0, 3.0]])
    # far left reads column 0 (wall), far right column 7, below reads row 5 (wall), above row 0
    assert depth_limit_keep_mask(means, camera, limit).tolist() == [False, True, False, True]


def test_cache_hands_back_the_same_tensors_for_the_same_splats() -> None:
    cache, splats = ResidentSplatsCache(), scene_splats(50, 1)
    first = cache.get(splats, CPU)
    second = cache.get(splats, CPU)
    assert second is first
    assert cache.uploads == 1


def test_cache_uploads_activated_parameters() -> None:
    splats = scene_splats(50, 2)
    resident = ResidentSplatsCache().get(splats, CPU)
    assert np.array_equal(resident.means.numpy(), splats.means)
    assert np.array_equal(resident.quats.numpy(), splats.quats)
    assert np.allclose(resident.scales.numpy(), np.exp(splats.log_scales), rtol=1e-6)
    assert np.allclose(resident.opacities.numpy(), 1.0 / (1.0 + np.exp(-splats.opacity_logits)), rtol=1e-6)
    assert resident.sh_degree == splats.sh_degree == 1


def test_cache_uploads_again_when_an_array_is_replaced() -> None:
    cache, splats = ResidentSplatsCache(), scene_splats(50, 3)
    before = cache.get(splats, CPU)
    splats.means = splats.means + np.float32(1.0)
    after = cache.get(splats, CPU)
    assert after is not before
    assert np.array_equal(after.means.numpy(), splats.means)
    assert cache.uploads == 2 and len(cache) == 1  # the stale copy was replaced, not kept


def test_cache_uploads_again_for_another_set_with_equal_values() -> None:
    cache, splats = ResidentSplatsCache(), scene_splats(50, 4)
    first = cache.get(splats, CPU)
    moved = splats.transformed(np.eye(4))
    assert cache.get(moved, CPU) is not first
    assert cache.uploads == 2


def test_forget_drops_a_set_written_in_place() -> None:
    cache, splats = ResidentSplatsCache(), scene_splats(50, 5)
    cache.get(splats, CPU)
    splats.means[:] = 0.0  # same array: the cache cannot see this write
    cache.forget(splats)
    assert len(cache) == 0
    assert np.array_equal(cache.get(splats, CPU).means.numpy(), np.zeros((50, 3), np.float32))


def test_cache_holds_at_most_its_capacity_dropping_the_least_recently_used() -> None:
    cache = ResidentSplatsCache(capacity=2)
    a, b, c = scene_splats(10, 6), scene_splats(10, 7), scene_splats(10, 8)
    tensors_a = cache.get(a, CPU)
    cache.get(b, CPU)
    cache.get(a, CPU)  # a is now the most recent
    cache.get(c, CPU)
    assert len(cache) == 2
    assert cache.get(a, CPU) is tensors_a  # a stayed
    uploads = cache.uploads
    cache.get(b, CPU)
    assert cache.uploads == uploads + 1  # b was dropped and comes back as a new upload


def test_cache_entry_dies_with_its_splats() -> None:
    cache, splats = ResidentSplatsCache(), scene_splats(10, 9)
    cache.get(splats, CPU)
    assert len(cache) == 1
    del splats
    gc.collect()
    assert len(cache) == 0


def test_cache_refuses_a_capacity_below_one() -> None:
    with pytest.raises(ValueError, match="capacity must be at least 1"):
        ResidentSplatsCache(capacity=0)


GSPLAT_READY = torch.cuda.is_available() and importlib.util.find_spec("gsplat") is not None


@pytest.mark.skipif(not GSPLAT_READY, reason="needs gsplat and a CUDA device; the CPU tests above cover the logic")
def test_gsplat_backend_draws_what_it_draws_for_the_numpy_culled_set_and_uploads_once() -> None:
    from drivetwin.worlds.render._gsplat_resident import resident_splats
    from drivetwin.worlds.render.rasterize import rasterize

    splats, camera = scene_splats(2000, 10), posed_camera(10, 96, 64)
    limit = depth_limit_image(camera, 10)
    expected = rasterize(cull_behind_depth_limit(splats, camera, limit), camera, backend="gsplat")
    uploads = resident_splats.uploads
    first = rasterize(splats, camera, backend="gsplat", depth_limit=limit)
    second = rasterize(splats, camera, backend="gsplat", depth_limit=limit)
    assert resident_splats.uploads == uploads + 1  # the second frame reused the resident set
    for out in (first, second):
        assert np.allclose(out.rgb, expected.rgb, atol=1e-5)
        assert np.allclose(out.alpha, expected.alpha, atol=1e-5)
        assert np.allclose(out.depth, expected.depth, atol=1e-4)
        assert np.array_equal(out.transmittance, 1.0 - out.alpha)
