"""Numba-compiled stages of the CPU splat rasterizer: EWA projection and compositing.

All kernels take their thresholds as arguments (not module globals) so the on-disk cache
(``cache=True``: compiled once per machine) can never hold stale constants. Arithmetic is
float64 so the kernel agrees with the float64 reference to rounding error, thresholds
included.

Every kernel is serial, releases the GIL (``nogil=True``) and works on a slice of its
items, so `_numba_raster` runs slices on its own threads. Numba's ``parallel=True`` is not
used: its loop bodies are generated functions whose cached environments belong to the
module "<dynamic>", which numba cannot rebuild from the on-disk cache once the in-memory
copy has been garbage-collected (an intermittent ModuleNotFoundError: No module named
'<dynamic>'); own threads also let the mesh pass run beside the splat stages.
"""

from __future__ import annotations

import math

import numba
import numpy as np
import numpy.typing as npt

__all__ = ["composite", "project"]

# Columns of the packed per-splat feature rows the compositor reads.
U, V, CONIC_A, CONIC_B, CONIC_C, OPACITY, MIN_POWER, DEPTH, RED, GREEN, BLUE = range(11)
N_FEATURES = 11
# Slack (pixels) on each splat's pixel box so rounding never drops a pixel the exact
# alpha test would keep; extra pixels are harmless because that test still runs.
BOX_SLACK = 1e-3
# Slack on the per-splat "power below which alpha < alpha_min" shortcut, for the same reason.
POWER_SLACK = 1e-9
# Fast-math without the no-NaN/no-inf promises: depth limits are legitimately infinite.
_SAFE_FASTMATH = {"nsz", "arcp", "contract", "afn", "reassoc"}


@numba.njit(cache=True, nogil=True, boundscheck=False)
def project(
    start: int,
    stop: int,
    means: npt.NDArray[np.float32],
    quats: npt.NDArray[np.float32],
    log_scales: npt.NDArray[np.float32],
    opacity_logits: npt.NDArray[np.float32],
    viewmat: npt.NDArray[np.float64],
    intrinsics: npt.NDArray[np.float64],
    image_size: npt.NDArray[np.int64],
    near: float,
    far: float,
    low_pass: float,
    alpha_min: float,
    fov_clamp: float,
    sh_dc: npt.NDArray[np.float32],
    sh_c0: float,
    colour_from_dc: bool,
    feats: npt.NDArray[np.float64],
    boxes: npt.NDArray[np.int32],
    visible: npt.NDArray[np.bool_],
) -> None:
    """EWA-project splats ``start:stop``: fill their feats rows, pixel boxes and visibility.

    A splat is visible when its mean lies strictly between the near and far planes, its 2D
    covariance is positive definite, its opacity can reach ``alpha_min`` and the box of the
    ellipse where it can reach ``alpha_min`` overlaps the image. Boxes are inclusive pixel
    ranges x0, x1, y0, y1. With ``colour_from_dc`` (SH degree 0: view-independent) the
    colour columns get 0.5 + sh_c0 * dc clamped below at 0; otherwise the caller fills them.
    """
    fx, fy, cx, cy = intrinsics[0], intrinsics[1], intrinsics[2], intrinsics[3]
    width, height = image_size[0], image_size[1]
    tan_x, tan_y = 0.5 * width / fx, 0.5 * height / fy
    lim_x_pos = (width - cx) / fx + fov_clamp * tan_x
    lim_x_neg = cx / fx + fov_clamp * tan_x
    lim_y_pos = (height - cy) / fy + fov_clamp * tan_y
    lim_y_neg = cy / fy + fov_clamp * tan_y
    w = viewmat
    for i in range(start, stop):
        visible[i] = False
        mx, my, mz = float(means[i, 0]), float(means[i, 1]), float(means[i, 2])
        x = w[0, 0] * mx + w[0, 1] * my + w[0, 2] * mz + w[0, 3]
        y = w[1, 0] * mx + w[1, 1] * my + w[1, 2] * mz + w[1, 3]
        z = w[2, 0] * mx + w[2, 1] * my + w[2, 2] * mz + w[2, 3]
        if z <= near or z >= far:
            continue
        opacity = 1.0 / (1.0 + math.exp(-float(opacity_logits[i])))
        if opacity < alpha_min:
            continue
        qw, qx, qy, qz = (
            float(quats[i, 0]),
            float(quats[i, 1]),
            float(quats[i, 2]),
            float(quats[i, 3]),
        )
        qn = math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz)
        qw, qx, qy, qz = qw / qn, qx / qn, qy / qn, qz / qn
        # Rows of R (quaternion rotation, inline for Numba: drivetwin.worlds.rotation.quat_to_matrix
        # is the one definition); R S columns are R[:, c] * scale_c.
        r00, r01, r02 = (
            1 - 2 * (qy * qy + qz * qz),
            2 * (qx * qy - qw * qz),
            2 * (qx * qz + qw * qy),
        )
        r10, r11, r12 = (
            2 * (qx * qy + qw * qz),
            1 - 2 * (qx * qx + qz * qz),
            2 * (qy * qz - qw * qx),
        )
        r20, r21, r22 = (
            2 * (qx * qz - qw * qy),
            2 * (qy * qz + qw * qx),
            1 - 2 * (qx * qx + qy * qy),
        )
        # T = J W R S, so the 2D covariance is T T^T; J is the pinhole Jacobian at the mean
        # with x/z, y/z clamped to just outside the view as 3DGS/gsplat do.
        tx = min(lim_x_pos, max(-lim_x_neg, x / z)) * z
        ty = min(lim_y_pos, max(-lim_y_neg, y / z)) * z
        j00, j02 = fx / z, -fx * tx / (z * z)
        j11, j12 = fy / z, -fy * ty / (z * z)
        cov_xx, cov_xy, cov_yy = low_pass, 0.0, low_pass
        for c in range(3):
            s = math.exp(float(log_scales[i, c]))
            rc0 = r00 if c == 0 else (r01 if c == 1 else r02)
            rc1 = r10 if c == 0 else (r11 if c == 1 else r12)
            rc2 = r20 if c == 0 else (r21 if c == 1 else r22)
            wr0 = w[0, 0] * rc0 + w[0, 1] * rc1 + w[0, 2] * rc2
            wr1 = w[1, 0] * rc0 + w[1, 1] * rc1 + w[1, 2] * rc2
            wr2 = w[2, 0] * rc0 + w[2, 1] * rc1 + w[2, 2] * rc2
            t0 = (j00 * wr0 + j02 * wr2) * s
            t1 = (j11 * wr1 + j12 * wr2) * s
            cov_xx += t0 * t0
            cov_xy += t0 * t1
            cov_yy += t1 * t1
        det = cov_xx * cov_yy - cov_xy * cov_xy
        if det <= 0.0:
            continue
        u = fx * x / z + cx
        v = fy * y / z + cy
        # opacity * exp(-q/2) >= alpha_min  <=>  q <= 2 ln(opacity / alpha_min): the support.
        q_max = 2.0 * math.log(opacity / alpha_min)
        rx = math.sqrt(q_max * cov_xx) + BOX_SLACK
        ry = math.sqrt(q_max * cov_yy) + BOX_SLACK
        x0 = max(0.0, math.ceil(u - rx - 0.5))
        x1 = min(width - 1.0, math.floor(u + rx - 0.5))
        y0 = max(0.0, math.ceil(v - ry - 0.5))
        y1 = min(height - 1.0, math.floor(v + ry - 0.5))
        if x0 > x1 or y0 > y1:
            continue
        visible[i] = True
        feats[i, U] = u
        feats[i, V] = v
        feats[i, CONIC_A] = cov_yy / det
        feats[i, CONIC_B] = -cov_xy / det
        feats[i, CONIC_C] = cov_xx / det
        feats[i, OPACITY] = opacity
        feats[i, MIN_POWER] = math.log(alpha_min / opacity) - POWER_SLACK
        feats[i, DEPTH] = z
        boxes[i, 0], boxes[i, 1], boxes[i, 2], boxes[i, 3] = x0, x1, y0, y1
        if colour_from_dc:
            for c in range(3):
                feats[i, RED + c] = max(0.0, 0.5 + sh_c0 * float(sh_dc[i, c]))


@numba.njit(cache=True, nogil=True, boundscheck=False, fastmath=_SAFE_FASTMATH)
def composite(
    tiles: npt.NDArray[np.int64],
    offsets: npt.NDArray[np.int64],
    feats: npt.NDArray[np.float64],
    boxes: npt.NDArray[np.int32],
    splat_index: npt.NDArray[np.int32],
    depth_limit: npt.NDArray[np.float64],
    tile_min_depth: npt.NDArray[np.float64],
    tile_w: int,
    tile_h: int,
    tiles_x: int,
    thresholds: npt.NDArray[np.float64],
    use_limit: bool,
    want_index: bool,
    out_rgb: npt.NDArray[np.float32],
    out_alpha: npt.NDArray[np.float32],
    out_depth: npt.NDArray[np.float32],
    out_index: npt.NDArray[np.int32],
) -> None:
    """Front-to-back alpha compositing of the image tiles ``tiles``, splat-major in a tile.

    Rows ``offsets[t]:offsets[t+1]`` of feats/boxes/splat_index (from binning) are tile
    t's splats, front to back; every pixel of the listed tiles is written.

    Per pixel the splats arrive in depth order, so this equals the per-pixel loop of 3DGS:
    alpha = min(alpha_max, o * exp(power)); skip alpha < alpha_min; stop (excluding the
    splat) once transmittance would fall below t_min. Visiting only each splat's pixel box
    inside the tile is what makes the CPU fast: most splats cover a few pixels.
    ``thresholds`` = (alpha_min, alpha_max, t_min, index_min_alpha); ``use_limit`` and
    ``want_index`` switch off the depth-limit test and index tracking when unused.

    Depth limit: splats arrive in depth order, so once one is at or behind a pixel's limit
    every later one is too and the pixel is finished (exactly as if each were dropped).
    A splat in front of the tile's nearest limit (``tile_min_depth``) skips the test.
    """
    alpha_min, alpha_max, t_min, index_min_alpha = (
        thresholds[0],
        thresholds[1],
        thresholds[2],
        thresholds[3],
    )
    height, width = depth_limit.shape
    for k in range(tiles.shape[0]):
        t = tiles[k]
        px0, py0 = (t % tiles_x) * tile_w, (t // tiles_x) * tile_h
        px1, py1 = min(px0 + tile_w, width), min(py0 + tile_h, height)
        tw = px1 - px0
        n_pix = tw * (py1 - py0)
        trans = np.ones(n_pix)
        acc_r, acc_g = np.zeros(n_pix), np.zeros(n_pix)
        acc_b, acc_z = np.zeros(n_pix), np.zeros(n_pix)
        first = np.full(n_pix, -1, dtype=np.int64)
        done = np.zeros(n_pix, dtype=np.bool_)
        # Pixels per tile row still open: whole finished rows are skipped before any maths.
        row_open = np.full(py1 - py0, tw, dtype=np.int64)
        n_done = 0
        for g in range(offsets[t], offsets[t + 1]):
            u, v = feats[g, U], feats[g, V]
            ca, cb, cc = feats[g, CONIC_A], feats[g, CONIC_B], feats[g, CONIC_C]
            opacity, z = feats[g, OPACITY], feats[g, DEPTH]
            limited = use_limit and z >= tile_min_depth[t]
            red, green, blue = feats[g, RED], feats[g, GREEN], feats[g, BLUE]
            x_lo, x_hi = max(boxes[g, 0], px0), min(boxes[g, 1], px1 - 1)
            # Row span of the ellipse power >= min_power: ca dx^2 + 2 cb dy dx + cc dy^2 <= q_max
            # gives dx = -slope dy +- sqrt(k1 dy^2 + k2); constants hoisted out of the rows.
            inv_ca = 1.0 / ca
            slope = cb * inv_ca
            k1 = (cb * cb - ca * cc) * inv_ca * inv_ca
            k2 = -2.0 * feats[g, MIN_POWER] * inv_ca
            # Along a row the Gaussian is exp of a quadratic, so successive values follow
            # e[k+1] = e[k] * r[k], r[k+1] = r[k] * exp(-ca): two exps per row, not per pixel.
            # The conic's entries are at most 1/LOW_PASS, so none of these can overflow.
            step_decay = math.exp(-ca)
            for py in range(max(boxes[g, 2], py0), min(boxes[g, 3], py1 - 1) + 1):
                if row_open[py - py0] == 0:
                    continue
                dy = py + 0.5 - v
                disc = k1 * dy * dy + k2
                if disc < 0.0:
                    continue
                root = math.sqrt(disc)
                centre = u - 0.5 - slope * dy
                span_lo = max(x_lo, math.ceil(centre - root - BOX_SLACK))
                span_hi = min(x_hi, math.floor(centre + root + BOX_SLACK))
                if span_lo > span_hi:
                    continue
                dx = span_lo + 0.5 - u
                value = opacity * math.exp(-0.5 * (ca * dx * dx + cc * dy * dy) - cb * dx * dy)
                ratio = math.exp(-ca * (dx + 0.5) - cb * dy)
                row = (py - py0) * tw - px0
                for px in range(span_lo, span_hi + 1):
                    p = row + px
                    alpha = min(alpha_max, value)
                    value *= ratio
                    ratio *= step_decay
                    if done[p]:
                        continue
                    if limited and z >= depth_limit[py, px]:
                        done[p] = True
                        n_done += 1
                        row_open[py - py0] -= 1
                        continue
                    if alpha < alpha_min:
                        continue
                    next_t = trans[p] * (1.0 - alpha)
                    if next_t < t_min:
                        done[p] = True
                        n_done += 1
                        row_open[py - py0] -= 1
                        continue
                    weight = alpha * trans[p]
                    acc_r[p] += weight * red
                    acc_g[p] += weight * green
                    acc_b[p] += weight * blue
                    acc_z[p] += weight * z
                    if want_index and first[p] < 0 and alpha >= index_min_alpha:
                        first[p] = splat_index[g]
                    trans[p] = next_t
            if n_done == n_pix:
                break
        for p in range(n_pix):
            py, px = py0 + p // tw, px0 + p % tw
            alpha_sum = 1.0 - trans[p]
            out_rgb[py, px, 0] = acc_r[p]
            out_rgb[py, px, 1] = acc_g[p]
            out_rgb[py, px, 2] = acc_b[p]
            out_alpha[py, px] = alpha_sum
            out_depth[py, px] = acc_z[p] / alpha_sum if alpha_sum > 0.0 else 0.0
            out_index[py, px] = first[p]
