"""The CPU splat rasterizer's host side: runs the Numba kernels in two phases on its own threads.

``project_splats`` (projection, depth sort, colours) needs only the splats and the camera;
``composite_splats`` (tile binning with depth-limit culling, compositing) needs the depth
limit too. The hybrid renderer runs the first while the mesh pass draws the depth limit.
``rasterize(backend="numba")`` is the two in a row.

The kernels are serial and release the GIL; ``KernelThreads`` runs slices of their work on
a small pool of threads (one per core this process may use, or DRIVETWIN_RENDER_THREADS).
Compositing hands out tiles busiest first in shrinking tasks, so threads finish together
even when another process takes one of the cores for a while.
"""

from __future__ import annotations

import itertools
import os
import threading
import time
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _numba_binning as binning
from . import _numba_kernel as kernel
from .camera import Camera
from .rasterize import ALPHA_MAX, ALPHA_MIN, CPU_TILE, FOV_CLAMP, LOW_PASS, TRANSMITTANCE_MIN, RasterOutput
from .splats import SH_C0, Splats, eval_sh_colors

__all__ = ["KernelThreads", "ProjectedSplats", "composite_splats", "kernel_threads", "project_splats",
           "rasterize_numba"]  # fmt: skip

THREADS_ENV = "DRIVETWIN_RENDER_THREADS"
# Compositing tasks per thread: later, smaller tasks even out threads that started unevenly.
COMPOSITE_TASKS_PER_THREAD = 6
# Splat slices per thread: a thread slowed by another process leaves its later slices to
# the others. Below MIN_ITEMS_PER_SLICE splats a slice costs more in hand-over than it saves.
SLICES_PER_THREAD, MIN_ITEMS_PER_SLICE = 4, 10_000


class KernelThreads:
    """A fixed pool of threads that runs GIL-free kernel calls side by side."""

    def __init__(self, threads: int) -> None:
        self.threads = max(1, threads)
        self._pool = (
            ThreadPoolExecutor(self.threads, thread_name_prefix="drivetwin-splats") if self.threads > 1 else None
        )

    def run(self, tasks: Sequence[Callable[[], None]]) -> None:
        """Run every task; the calling thread and up to ``threads - 1`` helpers take them in
        order, so a helper that the OS wakes late just takes fewer (or none)."""
        if self._pool is None or len(tasks) == 1:
            for task in tasks:
                task()
            return
        lock = threading.Lock()
        queue = iter(tasks)

        def work() -> None:
            while True:
                with lock:
                    task = next(queue, None)
                if task is None:
                    return
                task()

        helpers = [self._pool.submit(work) for _ in range(min(self.threads, len(tasks)) - 1)]
        try:
            work()
        finally:
            for helper in helpers:
                helper.result()

    def slices(self, n: int) -> list[tuple[int, int]]:
        """``n`` items cut into contiguous (start, stop) slices, a few per thread."""
        parts = max(1, min(self.threads * SLICES_PER_THREAD, n // MIN_ITEMS_PER_SLICE))
        bounds = np.linspace(0, n, parts + 1).astype(np.int64)
        return [(int(a), int(b)) for a, b in itertools.pairwise(bounds)]


class _Scratch(threading.local):
    """Per-thread scratch arrays reused from frame to frame (intermediates only, never outputs).

    At 1M splats the intermediates are a few hundred MB; allocating them afresh costs a page
    fault per 4 kB on first touch every frame.
    """

    def __init__(self) -> None:
        self.buffers: dict[str, npt.NDArray[Any]] = {}

    def take(self, name: str, shape: tuple[int, ...], dtype: type[Any]) -> npt.NDArray[Any]:
        """An uninitialised array of ``shape`` backed by the named buffer (grown as needed)."""
        size = int(np.prod(shape))
        buffer = self.buffers.get(name)
        if buffer is None or buffer.dtype != dtype or buffer.size < size:
            buffer = np.empty(max(size, 1), dtype)
            self.buffers[name] = buffer
        return buffer[:size].reshape(shape)


_scratch = _Scratch()
_threads: KernelThreads | None = None
_threads_lock = threading.Lock()


def kernel_threads() -> KernelThreads:
    """The process's kernel threads (made on first use)."""
    global _threads
    with _threads_lock:
        if _threads is None:
            wanted = os.environ.get(THREADS_ENV, "")
            count = int(wanted) if wanted.isdigit() and int(wanted) > 0 else len(os.sched_getaffinity(0))
            _threads = KernelThreads(count)
        return _threads


@dataclass
class ProjectedSplats:
    """Visible splats after projection, in (depth, id) order.

    feats [M, 11] float64 (columns named in `_numba_kernel`), boxes [M, 4] inclusive pixel
    boxes x0, x1, y0, y1, index [M] the splats' ids in the input set.
    """

    feats: npt.NDArray[np.float64]
    boxes: npt.NDArray[np.int32]
    index: npt.NDArray[np.int32]
    width: int
    height: int
    timings: dict[str, float] = field(default_factory=dict)


def project_splats(splats: Splats, camera: Camera) -> ProjectedSplats:
    """Phase one: EWA projection, culling, depth sort and colours of ``splats``."""
    t0 = time.perf_counter()
    pool = kernel_threads()
    n = len(splats)
    feats = _scratch.take("project_feats", (n, kernel.N_FEATURES), np.float64)
    boxes = _scratch.take("project_boxes", (n, 4), np.int32)
    visible = _scratch.take("project_visible", (n,), np.bool_)
    view = np.ascontiguousarray(camera.world_to_camera, dtype=np.float64)
    intrinsics = np.array([camera.fx, camera.fy, camera.cx, camera.cy], np.float64)
    size = np.array([camera.width, camera.height], np.int64)
    dc = np.ascontiguousarray(splats.sh[:, 0, :])
    from_dc = splats.sh_degree == 0

    def project(start: int, stop: int) -> Callable[[], None]:
        return lambda: kernel.project(start, stop, splats.means, splats.quats, splats.log_scales,
                                      splats.opacity_logits, view, intrinsics, size, camera.near,
                                      camera.far, LOW_PASS, ALPHA_MIN, FOV_CLAMP, dc, SH_C0, from_dc,
                                      feats, boxes, visible)  # fmt: skip

    pool.run([project(a, b) for a, b in pool.slices(n)])
    ids = np.flatnonzero(visible)
    depth_bits = np.ascontiguousarray(feats[ids, kernel.DEPTH]).view(np.uint64)
    order = ids[binning.radix_argsort(depth_bits)]
    m = len(order)
    ids_as_index = np.arange(n, dtype=np.int32)
    out_feats = np.empty((m, kernel.N_FEATURES), np.float64)
    out_boxes = np.empty((m, 4), np.int32)
    out_index = np.empty(m, np.int32)

    def gather(start: int, stop: int) -> Callable[[], None]:
        return lambda: binning.gather_rows(start, stop, order, feats, boxes, ids_as_index, out_feats, out_boxes,
                                           out_index)  # fmt: skip

    pool.run([gather(a, b) for a, b in pool.slices(m)])
    if not from_dc:
        directions = splats.means[out_index].astype(np.float64) - camera.position
        directions /= np.linalg.norm(directions, axis=1, keepdims=True)
        out_feats[:, kernel.RED : kernel.BLUE + 1] = eval_sh_colors(splats.sh[out_index], directions)
    ms = 1e3 * (time.perf_counter() - t0)
    return ProjectedSplats(out_feats, out_boxes, out_index, camera.width, camera.height, {"project": ms})


def composite_splats(
    projected: ProjectedSplats,
    camera: Camera,
    depth_limit: npt.NDArray[np.floating] | None,
    index_min_alpha: float,
    return_index: bool,
) -> RasterOutput:
    """Phase two: tile binning (pairs behind a tile's farthest limit culled) and compositing."""
    if (projected.width, projected.height) != (camera.width, camera.height):
        raise ValueError("projected splats were made for another image size")
    t0 = time.perf_counter()
    pool = kernel_threads()
    tile_w, tile_h = CPU_TILE
    tiles_x, tiles_y = -(-camera.width // tile_w), -(-camera.height // tile_h)
    n_tiles = tiles_x * tiles_y
    use_limit = depth_limit is not None
    limit: npt.NDArray[np.float64]
    if depth_limit is None:
        limit = np.empty((camera.height, camera.width))  # never read
        tile_near, tile_far = np.zeros(n_tiles), np.full(n_tiles, np.inf)
    else:
        limit = np.ascontiguousarray(depth_limit, dtype=np.float64)
        tile_near, tile_far = binning.tile_depth_bounds(limit, tile_w, tile_h, tiles_x, n_tiles)
    feats, boxes, index = projected.feats, projected.boxes, projected.index
    slices = pool.slices(len(feats))
    counts = np.zeros((len(slices), n_tiles), np.int64)

    def count(k: int) -> Callable[[], None]:
        a, b = slices[k]
        return lambda: binning.count_pairs(a, b, boxes, feats, kernel.DEPTH, tile_far, tile_w, tile_h,
                                           tiles_x, counts[k])  # fmt: skip

    pool.run([count(k) for k in range(len(slices))])
    per_tile = counts.sum(axis=0)
    offsets = np.zeros(n_tiles + 1, np.int64)
    np.cumsum(per_tile, out=offsets[1:])
    # Each slice writes after the earlier (nearer) slices' pairs of the same tile.
    cursors = offsets[:-1] + np.cumsum(counts, axis=0) - counts
    pairs = int(offsets[-1])
    ids = _scratch.take("pair_ids", (pairs,), np.int32)

    def scatter(k: int) -> Callable[[], None]:
        a, b = slices[k]
        return lambda: binning.scatter_pairs(a, b, boxes, feats, kernel.DEPTH, tile_far, tile_w, tile_h, tiles_x,
                                             cursors[k], ids)  # fmt: skip

    pool.run([scatter(k) for k in range(len(slices))])
    tile_feats = _scratch.take("tile_feats", (pairs, kernel.N_FEATURES), np.float64)
    tile_boxes = _scratch.take("tile_boxes", (pairs, 4), np.int32)
    tile_index = _scratch.take("tile_index", (pairs,), np.int32)

    def gather(start: int, stop: int) -> Callable[[], None]:
        return lambda: binning.gather_rows(start, stop, ids, feats, boxes, index, tile_feats, tile_boxes,
                                           tile_index)  # fmt: skip

    pool.run([gather(a, b) for a, b in pool.slices(pairs)])
    t1 = time.perf_counter()
    h, w = camera.height, camera.width
    index_image = np.empty((h, w), np.int32)
    out = RasterOutput(rgb=np.empty((h, w, 3), np.float32), alpha=np.empty((h, w), np.float32),
                       transmittance=np.empty((h, w), np.float32), depth=np.empty((h, w), np.float32),
                       index=index_image)  # fmt: skip
    thresholds = np.array([ALPHA_MIN, ALPHA_MAX, TRANSMITTANCE_MIN, index_min_alpha])

    def composite(tiles: npt.NDArray[np.int64]) -> Callable[[], None]:
        return lambda: kernel.composite(tiles, offsets, tile_feats, tile_boxes, tile_index, limit,
                                        tile_near, tile_w, tile_h, tiles_x, thresholds, use_limit,
                                        return_index, out.rgb, out.alpha, out.depth, index_image)  # fmt: skip

    pool.run([composite(tiles) for tiles in _composite_tasks(per_tile, pool.threads)])
    np.subtract(1.0, out.alpha, out=out.transmittance)
    t2 = time.perf_counter()
    out.timings = {**projected.timings, "bin": 1e3 * (t1 - t0), "composite": 1e3 * (t2 - t1),
                   "intersections": float(pairs)}  # fmt: skip
    out.timings["total"] = out.timings["project"] + out.timings["bin"] + out.timings["composite"]
    return out


def _composite_tasks(per_tile: npt.NDArray[np.int64], threads: int) -> list[npt.NDArray[np.int64]]:
    """Tiles, busiest first, grouped into tasks of about equal work (+1 per tile for its pixels)."""
    order = np.argsort(-per_tile, kind="stable")
    if threads == 1:
        return [order]
    work = per_tile[order] + 1
    target = max(1.0, float(work.sum()) / (threads * COMPOSITE_TASKS_PER_THREAD))
    cuts = np.searchsorted(np.cumsum(work), np.arange(target, float(work.sum()), target), side="left") + 1
    return [tiles for tiles in np.split(order, np.unique(cuts[cuts < len(order)])) if len(tiles)]


def rasterize_numba(
    splats: Splats,
    camera: Camera,
    depth_limit: npt.NDArray[np.float64] | None,
    index_min_alpha: float,
    return_index: bool,
) -> RasterOutput:
    """``rasterize(backend="numba")``: both phases in a row."""
    return composite_splats(project_splats(splats, camera), camera, depth_limit, index_min_alpha, return_index)
