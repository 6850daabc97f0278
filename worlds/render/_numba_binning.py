"""Numba-compiled ordering stages of the CPU splat rasterizer: depth sort and tile binning.

The compositor wants each tile's splats front to back, with ties broken by splat id (the
reference's (depth, id) order). Splats are first put in depth order by a stable LSD radix
sort of their depth bits, then (tile, splat) pairs are laid out tile by tile with a stable
counting sort, which keeps the depth order inside each tile: together one sort by the key
(tile, depth, id). Binning drops pairs that lie wholly behind a depth limit (a tile's
farthest mesh depth), so hidden splats cost nothing later.

Like `_numba_kernel`, every kernel is serial, releases the GIL and works on a slice, so the
caller can run slices on its own threads.
"""

from __future__ import annotations

import numba
import numpy as np
import numpy.typing as npt

__all__ = [
    "bin_tiles",
    "count_pairs",
    "gather_rows",
    "radix_argsort",
    "scatter_pairs",
    "tile_depth_bounds",
]

# 11-bit digits: 6 passes cover 64 bits and a 2048-bucket histogram fits in L1.
RADIX_BITS = 11
RADIX_PASSES = 6


@numba.njit(cache=True, nogil=True, boundscheck=False)
def radix_argsort(keys: npt.NDArray[np.uint64]) -> npt.NDArray[np.int64]:
    """Stable argsort of unsigned 64-bit keys (LSD radix sort).

    Positive finite float64 values order like their bit patterns, so depths sort exactly
    (no rounding) with ties in input order. Passes whose digit is the same for every key
    are skipped.
    """
    n = keys.shape[0]
    buckets = 1 << RADIX_BITS
    mask = np.uint64(buckets - 1)
    hist = np.zeros((RADIX_PASSES, buckets), dtype=np.int64)
    for i in range(n):
        key = keys[i]
        for p in range(RADIX_PASSES):
            hist[p, (key >> np.uint64(p * RADIX_BITS)) & mask] += 1
    order = np.arange(n)
    order_tmp = np.empty(n, dtype=np.int64)
    sorted_keys = keys.copy()
    keys_tmp = np.empty(n, dtype=np.uint64)
    starts = np.empty(buckets, dtype=np.int64)
    for p in range(RADIX_PASSES):
        if hist[p].max() == n:
            continue  # one digit value for all keys: the pass would not move anything
        total = 0
        for b in range(buckets):
            starts[b] = total
            total += hist[p, b]
        shift = np.uint64(p * RADIX_BITS)
        for i in range(n):
            key = sorted_keys[i]
            d = (key >> shift) & mask
            slot = starts[d]
            starts[d] = slot + 1
            keys_tmp[slot] = key
            order_tmp[slot] = order[i]
        sorted_keys, keys_tmp = keys_tmp, sorted_keys
        order, order_tmp = order_tmp, order
    return order


@numba.njit(cache=True, nogil=True, boundscheck=False)
def gather_rows(
    start: int,
    stop: int,
    ids: npt.NDArray[np.integer],
    feats: npt.NDArray[np.float64],
    boxes: npt.NDArray[np.int32],
    index: npt.NDArray[np.int32],
    out_feats: npt.NDArray[np.float64],
    out_boxes: npt.NDArray[np.int32],
    out_index: npt.NDArray[np.int32],
) -> None:
    """Rows ``ids[start:stop]`` of feats, boxes and index, copied to rows start:stop of the outputs.

    Used twice: to put visible splats in depth order, then to lay out each (tile, splat)
    pair in tile order, so binning and compositing stream through memory instead of
    chasing ids across tables larger than the caches.
    """
    for k in range(start, stop):
        g = ids[k]
        for j in range(feats.shape[1]):
            out_feats[k, j] = feats[g, j]
        for j in range(4):
            out_boxes[k, j] = boxes[g, j]
        out_index[k] = index[g]


@numba.njit(cache=True, nogil=True, boundscheck=False)
def tile_depth_bounds(
    depth_limit: npt.NDArray[np.float64],
    tile_w: int,
    tile_h: int,
    tiles_x: int,
    n_tiles: int,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Nearest and farthest depth limit [T] of each tile (row-major tiles of tile_w x tile_h)."""
    near = np.full(n_tiles, np.inf)
    far = np.full(n_tiles, -np.inf)
    height, width = depth_limit.shape
    for py in range(height):
        row = (py // tile_h) * tiles_x
        for px in range(width):
            t = row + px // tile_w
            d = depth_limit[py, px]
            if d < near[t]:
                near[t] = d
            if d > far[t]:
                far[t] = d
    return near, far


@numba.njit(cache=True, nogil=True, boundscheck=False)
def count_pairs(
    start: int,
    stop: int,
    boxes: npt.NDArray[np.int32],
    feats: npt.NDArray[np.float64],
    depth_column: int,
    tile_far: npt.NDArray[np.float64],
    tile_w: int,
    tile_h: int,
    tiles_x: int,
    counts: npt.NDArray[np.int64],
) -> None:
    """Add to ``counts`` [T] the (tile, splat) pairs of rows start:stop that are not culled.

    A pair is culled when the splat's depth is at or behind the farthest depth limit in the
    tile: it would be dropped at every pixel there.
    """
    for g in range(start, stop):
        z = feats[g, depth_column]
        for ty in range(boxes[g, 2] // tile_h, boxes[g, 3] // tile_h + 1):
            for tx in range(boxes[g, 0] // tile_w, boxes[g, 1] // tile_w + 1):
                t = ty * tiles_x + tx
                if z < tile_far[t]:
                    counts[t] += 1


@numba.njit(cache=True, nogil=True, boundscheck=False)
def scatter_pairs(
    start: int,
    stop: int,
    boxes: npt.NDArray[np.int32],
    feats: npt.NDArray[np.float64],
    depth_column: int,
    tile_far: npt.NDArray[np.float64],
    tile_w: int,
    tile_h: int,
    tiles_x: int,
    cursor: npt.NDArray[np.int64],
    ids: npt.NDArray[np.int32],
) -> None:
    """Write the row numbers of the pairs ``count_pairs`` counted for rows start:stop into
    ``ids`` at ``cursor`` [T] (advanced).

    Rows are read in depth order and each tile's slots are filled in that order, so ``ids``
    is sorted by (tile, depth); `gather_rows` then lays the rows out in that order (small
    scattered writes here, long sequential ones there: faster than scattering whole rows).
    """
    for g in range(start, stop):
        z = feats[g, depth_column]
        for ty in range(boxes[g, 2] // tile_h, boxes[g, 3] // tile_h + 1):
            for tx in range(boxes[g, 0] // tile_w, boxes[g, 1] // tile_w + 1):
                t = ty * tiles_x + tx
                if z >= tile_far[t]:
                    continue
                slot = cursor[t]
                cursor[t] = slot + 1
                ids[slot] = g


@numba.njit(cache=True, nogil=True)
def bin_tiles(
    boxes: npt.NDArray[np.int32],
    tile_w: int,
    tile_h: int,
    tiles_x: int,
    n_tiles: int,
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int32]]:
    """Tile offsets [T+1] and, per tile, the row numbers of ``boxes`` that touch it, in order.

    For callers that keep their own splat tables (the torch path): rows given in depth
    order come out sorted by (tile, depth).
    """
    counts = np.zeros(n_tiles + 1, dtype=np.int64)
    for g in range(boxes.shape[0]):
        for ty in range(boxes[g, 2] // tile_h, boxes[g, 3] // tile_h + 1):
            for tx in range(boxes[g, 0] // tile_w, boxes[g, 1] // tile_w + 1):
                counts[ty * tiles_x + tx + 1] += 1
    offsets = np.cumsum(counts)
    cursor = offsets[:-1].copy()
    ids = np.empty(offsets[-1], dtype=np.int32)
    for g in range(boxes.shape[0]):
        for ty in range(boxes[g, 2] // tile_h, boxes[g, 3] // tile_h + 1):
            for tx in range(boxes[g, 0] // tile_w, boxes[g, 1] // tile_w + 1):
                t = ty * tiles_x + tx
                ids[cursor[t]] = g
                cursor[t] += 1
    return offsets, ids
