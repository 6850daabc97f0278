"""Numba kernels of the per-pixel passes after compositing: blend, fog and exposure.

Each is one pass over the frame in place of several NumPy passes (each of which reads and
writes whole float images): at 640x360 they take about a millisecond together. Like the
rasterizer's kernels they are cached on disk, serial and release the GIL.
"""

from __future__ import annotations

import math

import numba
import numpy as np
import numpy.typing as npt

__all__ = ["apply_fog", "blend_layers", "expose"]


@numba.njit(cache=True, nogil=True, boundscheck=False)
def blend_layers(
    splat_rgb: npt.NDArray[np.float32],
    splat_alpha: npt.NDArray[np.float32],
    splat_depth: npt.NDArray[np.float32],
    splat_light: npt.NDArray[np.float32],
    use_light: bool,
    mesh_rgb: npt.NDArray[np.float32],
    mesh_hit: npt.NDArray[np.bool_],
    mesh_depth: npt.NDArray[np.float32],
    sky: npt.NDArray[np.float32],
    gain: npt.NDArray[np.float32],
    splat_depth_alpha: float,
    out_rgb: npt.NDArray[np.float32],
    out_depth: npt.NDArray[np.float32],
    out_layer: npt.NDArray[np.float32],
) -> None:
    """rgb = splat_rgb * (gain + light) + (1 - alpha) * layer, layer = mesh colour else sky.

    Depth is the splats' where their alpha reaches ``splat_depth_alpha``, else the mesh's.
    ``splat_light`` [H,W,3] (lamp light on the splats) is read only when ``use_light``.
    """
    height, width = splat_alpha.shape
    for y in range(height):
        for x in range(width):
            alpha = splat_alpha[y, x]
            through = np.float32(1.0) - alpha
            hit = mesh_hit[y, x]
            for c in range(3):
                under = mesh_rgb[y, x, c] if hit else sky[y, x, c]
                out_layer[y, x, c] = under
                lit = splat_rgb[y, x, c] * gain[c]
                if use_light:
                    lit += splat_rgb[y, x, c] * splat_light[y, x, c]
                out_rgb[y, x, c] = lit + through * under
            out_depth[y, x] = splat_depth[y, x] if alpha >= splat_depth_alpha else mesh_depth[y, x]


@numba.njit(cache=True, nogil=True, boundscheck=False)
def apply_fog(
    rgb: npt.NDArray[np.float32],
    depth: npt.NDArray[np.float32],
    ray_lengths: npt.NDArray[np.float32],
    sky_distance: npt.NDArray[np.float32],
    density: float,
    fog_rgb: npt.NDArray[np.float32],
) -> None:
    """Exponential fog in place: rgb <- rgb (1 - f) + fog_rgb f, f = 1 - exp(-density * distance).

    Distance along the ray is camera z times the ray's length per unit z; where nothing was
    hit (infinite depth) it is ``sky_distance``, the path through the hazy air layer.
    """
    height, width = depth.shape
    for y in range(height):
        for x in range(width):
            d = depth[y, x]
            distance = d * ray_lengths[y, x] if math.isfinite(d) else sky_distance[y, x]
            fog = 1.0 - math.exp(-density * distance)
            for c in range(3):
                rgb[y, x, c] = rgb[y, x, c] * (1.0 - fog) + fog_rgb[c] * fog


@numba.njit(cache=True, nogil=True, boundscheck=False)
def expose(rgb: npt.NDArray[np.float32], exposure: float, out: npt.NDArray[np.uint8]) -> None:
    """out = round(rgb * exposure * 255), clamped to 0..255 (8-bit display values)."""
    height, width, channels = rgb.shape
    scale = np.float32(exposure) * np.float32(255.0)
    for y in range(height):
        for x in range(width):
            for c in range(channels):
                v = rgb[y, x, c] * scale + np.float32(0.5)
                out[y, x, c] = 255 if v >= 255.0 else (np.uint8(v) if v > 0.0 else 0)  # NaN -> 0
