"""The CPU rasterizer's speed-ups change nothing: culling, threads and the radix sort are exact."""

from __future__ import annotations

import numpy as np
import pytest
from drivetwin.worlds.render import _numba_binning, _numba_kernel, _numba_post, _numba_raster
from drivetwin.worlds.render._numba_binning import radix_argsort
from drivetwin.worlds.render._torch_raster import cull_behind_depth_limit
from drivetwin.worlds.render.bench_splats import street_camera, street_scene
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.rasterize import CPU_TILE, rasterize
from numba.core.caching import FunctionCache
from numba.core.registry import CPUDispatcher as Dispatcher
from test_splat_backends import assert_same_image, random_scene


def wide_camera() -> Camera:
    # Three CPU tiles across and three down (the last ones partial), so whole tiles can lie
    # behind the wall below while others do not.
    width, height = 2 * CPU_TILE[0] + 9, 2 * CPU_TILE[1] + 5
    return Camera(width, height, fx=60.0, fy=60.0, cx=width / 2, cy=height / 2, world_to_camera=np.eye(4))


def test_numba_matches_reference_where_whole_tiles_lie_behind_a_wall() -> None:
    camera = wide_camera()
    splats = random_scene(150, 11, 1)
    splats.means[:, 0] *= 2.5  # spread across the wide image
    limit = np.full((camera.height, camera.width), np.inf)
    limit[:, : CPU_TILE[0] + 20] = 3.0  # a wall 3 m away over the left tile and a bit more
    limit[CPU_TILE[1] :, -30:] = np.linspace(2.0, 6.0, 30)  # a slanted surface, per pixel
    reference = rasterize(splats, camera, backend="reference", depth_limit=limit, return_index=True)
    fast = rasterize(splats, camera, backend="numba", depth_limit=limit, return_index=True)
    assert_same_image(fast, reference)
    unlimited = rasterize(splats, camera, backend="numba")
    # Binning culled the pairs behind the wall (fewer than without the limit).
    assert fast.timings["intersections"] < unlimited.timings["intersections"]
    assert reference.alpha[:, :40].max() < unlimited.alpha[:, :40].max()


def test_two_threads_draw_exactly_what_one_thread_draws(monkeypatch: pytest.MonkeyPatch) -> None:
    camera = street_camera(160, 90)
    splats = street_scene(40_000, camera)  # enough for several projection slices
    limit = np.full((camera.height, camera.width), 12.0)
    images = []
    for threads in (1, 2):
        monkeypatch.setattr(_numba_raster, "_threads", _numba_raster.KernelThreads(threads))
        assert len(_numba_raster.kernel_threads().slices(len(splats))) > 1  # several slices
        images.append(rasterize(splats, camera, backend="numba", depth_limit=limit, return_index=True))
    for name in ("rgb", "alpha", "depth", "index"):
        assert np.array_equal(getattr(images[0], name), getattr(images[1], name)), name


def test_radix_argsort_sorts_depths_exactly_with_ties_in_input_order() -> None:
    rng = np.random.default_rng(3)
    depth = rng.uniform(0.05, 900.0, 5000)
    depth[::7] = depth[3]  # many exact ties
    depth[10] = np.nextafter(depth[3], np.inf)  # one ulp apart still orders correctly
    order = radix_argsort(depth.view(np.uint64))
    assert np.array_equal(order, np.argsort(depth, kind="stable"))


def test_gsplat_depth_limit_keeps_a_splat_by_the_limit_at_its_centre_pixel() -> None:
    camera = Camera(40, 20, fx=30.0, fy=30.0, cx=20.0, cy=10.0, world_to_camera=np.eye(4))
    splats = random_scene(200, 5, 0)
    limit = np.full((20, 40), np.inf)
    limit[:, :20] = 3.5  # left half: a wall 3.5 m away
    kept = cull_behind_depth_limit(splats, camera, limit)
    x, z = kept.means[:, 0].astype(np.float64), kept.means[:, 2].astype(np.float64)
    left = np.floor(30.0 * x / z + 20.0) < 20
    assert np.all(z[left] < 3.5)  # nothing kept behind the wall
    assert 0 < len(kept) < len(splats)
    u = np.floor(30.0 * splats.means[:, 0] / splats.means[:, 2] + 20.0)
    assert len(kept) == int(np.sum((u >= 20) | (splats.means[:, 2] < 3.5)))  # the rest all kept


@pytest.mark.parametrize("module", [_numba_kernel, _numba_binning, _numba_post])
def test_cached_kernels_are_never_numba_parallel(module) -> None:  # type: ignore[no-untyped-def]
    # parallel=True compiles loop bodies into generated functions of the module "<dynamic>";
    # numba pickles their environments into the disk cache when they are still alive at save
    # time, and a later process then fails to load the entry (No module named '<dynamic>').
    # The kernels are serial and nogil instead; _numba_raster runs them on its own threads.
    kernels = [v for v in vars(module).values() if isinstance(v, Dispatcher)]
    assert kernels
    for kernel in kernels:
        assert not kernel.targetoptions.get("parallel"), kernel.py_func.__name__
        assert kernel.targetoptions.get("nogil"), kernel.py_func.__name__
        assert isinstance(kernel._cache, FunctionCache), kernel.py_func.__name__  # cache=True
