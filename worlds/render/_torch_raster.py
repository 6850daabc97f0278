"""Differentiable splat rasterizer in PyTorch, and the adapter to gsplat's CUDA rasterizer.

``rasterize_torch`` follows exactly the method of ``rasterize`` (see its module docstring)
with vectorised tensor code, so autograd gives gradients to means, quaternions, log
scales, opacity logits and SH coefficients, e.g. to fit splats to photographs. Tiles are
composited in padded batches [B tiles, P pixels, K splats]; the tile lists and the
early-termination cut are decided on detached values, exactly as the forward CUDA/CPU
kernels decide them, so they carry no gradient (as in 3DGS).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt
import torch

from ._gsplat_resident import depth_limit_keep_mask, depth_limit_keep_mask_numpy, resident_splats
from .camera import Camera
from .rasterize import (
    ALPHA_MAX,
    ALPHA_MIN,
    FOV_CLAMP,
    INDEX_MIN_ALPHA,
    LOW_PASS,
    TILE_SIZE,
    TRANSMITTANCE_MIN,
    RasterizeError,
    RasterOutput,
    tile_grid,
)
from .splats import Splats, sh_basis

__all__ = ["TorchRaster", "cull_behind_depth_limit", "rasterize_gsplat", "rasterize_numpy_via_torch", "rasterize_torch"]

# Elements of one padded [B, P, K] batch: bounds peak memory to a few hundred MB in float64.
MAX_BATCH_ELEMENTS = 1 << 22
# Same pixel-box slack as the compiled kernel: boxes only bound work, the alpha test decides.
_BOX_SLACK = 1e-3


@dataclass
class TorchRaster:
    """Images from ``rasterize_torch``: rgb [H,W,3], alpha [H,W], depth [H,W], index [H,W]."""

    rgb: torch.Tensor
    alpha: torch.Tensor
    depth: torch.Tensor
    index: torch.Tensor
    timings: dict[str, float]


def rotation_matrices(quats: torch.Tensor) -> torch.Tensor:
    """Rotation matrices [N,3,3] of wxyz quaternions [N,4] (normalised here), differentiable.

    The tensor twin of drivetwin.worlds.rotation.quat_to_matrix (kept here: autograd needs torch
    operations); tests/worlds/test_rotation.py holds the two to the same answer.
    """
    q = quats / quats.norm(dim=-1, keepdim=True)
    w, x, y, z = q.unbind(-1)
    rows = [
        torch.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        torch.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        torch.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ]
    return torch.stack(rows, -2)


def _pixel_boxes(
    u: npt.NDArray[np.float64],
    v: npt.NDArray[np.float64],
    cov: npt.NDArray[np.float64],
    opacity: npt.NDArray[np.float64],
    camera: Camera,
) -> npt.NDArray[np.int32]:
    """Inclusive pixel boxes [N,4] (x0,x1,y0,y1) of the ellipses where alpha can reach 1/255."""
    q_max = 2.0 * np.log(np.maximum(opacity, ALPHA_MIN) / ALPHA_MIN)
    rx = np.sqrt(q_max * cov[:, 0]) + _BOX_SLACK
    ry = np.sqrt(q_max * cov[:, 2]) + _BOX_SLACK
    x0 = np.maximum(0, np.ceil(u - rx - 0.5))
    x1 = np.minimum(camera.width - 1, np.floor(u + rx - 0.5))
    y0 = np.maximum(0, np.ceil(v - ry - 0.5))
    y1 = np.minimum(camera.height - 1, np.floor(v + ry - 0.5))
    return np.stack([x0, x1, y0, y1], 1).astype(np.int32)


def rasterize_torch(
    means: torch.Tensor,
    quats: torch.Tensor,
    log_scales: torch.Tensor,
    opacity_logits: torch.Tensor,
    sh: torch.Tensor,
    camera: Camera,
    *,
    depth_limit: torch.Tensor | None = None,
    index_min_alpha: float = INDEX_MIN_ALPHA,
) -> TorchRaster:
    """Differentiable rasterization of splat tensors (shapes as in ``Splats``), same rules.

    All inputs share one dtype and device (float64 for gradcheck, float32 for fitting);
    ``depth_limit`` is [H,W] camera z. Returns premultiplied rgb without background.
    """
    from ._numba_binning import bin_tiles

    t0 = time.perf_counter()
    dtype, device = means.dtype, means.device
    h, w = camera.height, camera.width
    view = torch.tensor(np.array(camera.world_to_camera), dtype=dtype, device=device)
    p_cam = means @ view[:3, :3].T + view[:3, 3]
    x, y, z = p_cam.unbind(-1)
    rs = rotation_matrices(quats) * torch.exp(log_scales)[:, None, :]
    cov_cam = view[:3, :3] @ rs @ rs.transpose(1, 2) @ view[:3, :3].T
    fx, fy, cx, cy = camera.fx, camera.fy, camera.cx, camera.cy
    tan_x, tan_y = 0.5 * w / fx, 0.5 * h / fy
    safe_z = torch.where(z > camera.near, z, torch.ones_like(z))  # culled splats stay finite
    xz = torch.clamp(x / safe_z, -cx / fx - FOV_CLAMP * tan_x, (w - cx) / fx + FOV_CLAMP * tan_x)
    yz = torch.clamp(y / safe_z, -cy / fy - FOV_CLAMP * tan_y, (h - cy) / fy + FOV_CLAMP * tan_y)
    zero = torch.zeros_like(z)
    jac = torch.stack(
        [
            torch.stack([fx / safe_z, zero, -fx * xz / safe_z], -1),
            torch.stack([zero, fy / safe_z, -fy * yz / safe_z], -1),
        ],
        -2,
    )
    cov2d = jac @ cov_cam @ jac.transpose(1, 2)
    cov_xx, cov_xy, cov_yy = cov2d[:, 0, 0] + LOW_PASS, cov2d[:, 0, 1], cov2d[:, 1, 1] + LOW_PASS
    det = cov_xx * cov_yy - cov_xy * cov_xy
    safe_det = torch.where(det > 0, det, torch.ones_like(det))
    conic = torch.stack([cov_yy / safe_det, -cov_xy / safe_det, cov_xx / safe_det], -1)
    uv = torch.stack([fx * x / safe_z + cx, fy * y / safe_z + cy], -1)
    opacity = torch.sigmoid(opacity_logits)
    centre = torch.as_tensor(camera.position, dtype=dtype, device=device)
    dirs = means - centre
    dirs = dirs / dirs.norm(dim=-1, keepdim=True)
    degree = {1: 0, 4: 1, 9: 2, 16: 3}[sh.shape[1]]
    basis = torch.stack(sh_basis(dirs[:, 0], dirs[:, 1], dirs[:, 2], degree), -1)
    colors = torch.clamp_min(torch.einsum("nk,nkc->nc", basis, sh) + 0.5, 0.0)

    # Culling and tile lists, decided on detached values as the compiled kernels do.
    z_np, det_np, op_np = (t.detach().cpu().numpy().astype(np.float64) for t in (z, det, opacity))
    uv_np = uv.detach().cpu().numpy().astype(np.float64)
    cov_np = torch.stack([cov_xx, cov_xy, cov_yy], -1).detach().cpu().numpy().astype(np.float64)
    boxes = _pixel_boxes(uv_np[:, 0], uv_np[:, 1], cov_np, op_np, camera)
    keep = (z_np > camera.near) & (z_np < camera.far) & (det_np > 0) & (op_np >= ALPHA_MIN)
    keep &= (boxes[:, 0] <= boxes[:, 1]) & (boxes[:, 2] <= boxes[:, 3])
    visible = np.flatnonzero(keep)
    t1 = time.perf_counter()
    tiles_x, tiles_y = tile_grid(camera)
    order = visible[np.argsort(z_np[visible], kind="stable")]
    offsets, ranks = bin_tiles(boxes[order], TILE_SIZE, TILE_SIZE, tiles_x, tiles_x * tiles_y)
    ids = order[ranks]
    t2 = time.perf_counter()

    limit = torch.full((h * w,), math.inf, dtype=dtype, device=device)
    if depth_limit is not None:
        limit = depth_limit.reshape(-1).to(dtype=dtype, device=device)
    feats = torch.cat([uv, conic, opacity[:, None], z[:, None], colors], -1)  # [N, 10]
    pix_all, rgb_all, alpha_all, depth_all, index_all = [], [], [], [], []
    for tiles in _tile_batches(np.diff(offsets)):
        tile_ids, pixels, valid_pix = _batch_layout(tiles, offsets, ids, camera, device)
        f = feats[tile_ids.clamp_min(0)]  # [B, K, 10]
        px = (pixels % w).to(dtype)[:, :, None] + 0.5
        py = (pixels // w).to(dtype)[:, :, None] + 0.5
        dx, dy = px - f[:, None, :, 0], py - f[:, None, :, 1]
        power = -0.5 * (f[:, None, :, 2] * dx * dx + f[:, None, :, 4] * dy * dy)
        power = power - f[:, None, :, 3] * dx * dy
        alpha = torch.clamp(f[:, None, :, 5] * torch.exp(power), max=ALPHA_MAX)
        pix_limit = limit[pixels.clamp(0, h * w - 1)][:, :, None]
        live = (alpha >= ALPHA_MIN) & (tile_ids >= 0)[:, None, :] & (f[:, None, :, 6] < pix_limit)
        alpha = torch.where(live, alpha, torch.zeros_like(alpha))
        # The first splat that would take transmittance below the minimum, and all later
        # ones, are cut: transmittance only decreases, so an inclusive cumprod finds it.
        survives = torch.cumprod(1.0 - alpha.detach(), -1) >= TRANSMITTANCE_MIN
        alpha = torch.where(survives, alpha, torch.zeros_like(alpha))
        trans = torch.cumprod(1.0 - alpha, -1)
        before = torch.cat([torch.ones_like(trans[..., :1]), trans[..., :-1]], -1)
        weight = alpha * before
        total = weight.sum(-1)
        depth_sum = (weight * f[:, None, :, 6]).sum(-1)
        owner = (alpha >= index_min_alpha) & (alpha > 0)
        first = torch.where(owner.any(-1), owner.to(torch.int8).argmax(-1), -1)
        gathered = tile_ids.gather(1, first.clamp_min(0))
        mask = valid_pix.reshape(-1)
        pix_all.append(pixels.reshape(-1)[mask])
        rgb_all.append(torch.einsum("bpk,bkc->bpc", weight, f[:, :, 7:10]).reshape(-1, 3)[mask])
        alpha_all.append(total.reshape(-1)[mask])
        safe_total = torch.where(total > 0, total, torch.ones_like(total))
        depth_all.append(torch.where(total > 0, depth_sum / safe_total, 0.0).reshape(-1)[mask])
        index_all.append(torch.where(first >= 0, gathered, -1).reshape(-1)[mask])
    rgb = torch.zeros((h * w, 3), dtype=dtype, device=device)
    alpha_img = torch.zeros(h * w, dtype=dtype, device=device)
    depth = torch.zeros(h * w, dtype=dtype, device=device)
    index = torch.full((h * w,), -1, dtype=torch.int64, device=device)
    if pix_all:
        pix = torch.cat(pix_all)
        rgb = rgb.index_put((pix,), torch.cat(rgb_all))
        alpha_img = alpha_img.index_put((pix,), torch.cat(alpha_all))
        depth = depth.index_put((pix,), torch.cat(depth_all))
        index = index.index_put((pix,), torch.cat(index_all))
    t3 = time.perf_counter()
    timings = {"project": 1e3 * (t1 - t0), "bin": 1e3 * (t2 - t1), "composite": 1e3 * (t3 - t2)}
    return TorchRaster(
        rgb.reshape(h, w, 3), alpha_img.reshape(h, w), depth.reshape(h, w), index.reshape(h, w),
        timings,
    )  # fmt: skip


def _tile_batches(counts: npt.NDArray[np.int64]) -> list[npt.NDArray[np.int64]]:
    """Group non-empty tiles (similar splat counts together) into padded batches."""
    tiles = np.flatnonzero(counts)
    tiles = tiles[np.argsort(counts[tiles], kind="stable")]
    batches, start = [], 0
    pixels = TILE_SIZE * TILE_SIZE
    while start < len(tiles):
        end = start + 1
        while end < len(tiles) and (end + 1 - start) * pixels * counts[tiles[end]] <= (MAX_BATCH_ELEMENTS):
            end += 1
        batches.append(tiles[start:end])
        start = end
    return batches


def _batch_layout(
    tiles: npt.NDArray[np.int64],
    offsets: npt.NDArray[np.int64],
    ids: npt.NDArray[np.integer[Any]],
    camera: Camera,
    device: torch.device,
) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
    """Padded splat ids [B,K] (-1 pad), flat pixel ids [B,P] and their in-image mask [B,P]."""
    tiles_x = tile_grid(camera)[0]
    counts = offsets[tiles + 1] - offsets[tiles]
    k = int(counts.max())
    slots = np.arange(k)
    tile_ids = np.where(slots < counts[:, None], ids[np.minimum(offsets[tiles, None] + slots,
                                                                len(ids) - 1)], -1)  # fmt: skip
    local = np.arange(TILE_SIZE * TILE_SIZE)
    col = (tiles % tiles_x)[:, None] * TILE_SIZE + local % TILE_SIZE
    row = (tiles // tiles_x)[:, None] * TILE_SIZE + local // TILE_SIZE
    inside = (col < camera.width) & (row < camera.height)
    pixels = np.where(inside, row * camera.width + col, 0)
    return (
        torch.as_tensor(tile_ids, dtype=torch.int64, device=device),
        torch.as_tensor(pixels, dtype=torch.int64, device=device),
        torch.as_tensor(inside, device=device),
    )


def rasterize_numpy_via_torch(
    splats: Splats,
    camera: Camera,
    depth_limit: npt.NDArray[np.float64],
    index_min_alpha: float,
) -> RasterOutput:
    """``rasterize(backend="torch")``: float64 tensors on the CPU, no gradients."""
    with torch.no_grad():
        means, quats, log_scales, logits, sh = (
            torch.as_tensor(np.asarray(a, dtype=np.float64))
            for a in (splats.means, splats.quats, splats.log_scales, splats.opacity_logits,
                      splats.sh)
        )  # fmt: skip
        out = rasterize_torch(means, quats, log_scales, logits, sh, camera,
                              depth_limit=torch.as_tensor(depth_limit),
                              index_min_alpha=index_min_alpha)  # fmt: skip
    alpha = out.alpha.numpy().astype(np.float32)
    return RasterOutput(
        rgb=out.rgb.numpy().astype(np.float32),
        alpha=alpha,
        transmittance=(1.0 - out.alpha.numpy()).astype(np.float32),
        depth=out.depth.numpy().astype(np.float32),
        index=out.index.numpy().astype(np.int32),
        timings={**out.timings, "total": sum(out.timings.values())},
    )


def cull_behind_depth_limit(splats: Splats, camera: Camera, depth_limit: npt.NDArray[np.floating]) -> Splats:
    """The splats whose mean lies in front of ``depth_limit`` [H,W] at the pixel under the mean.

    This is how the gsplat backend takes a depth limit (its CUDA rasterizer has no
    per-pixel test): a splat is kept or dropped whole by the limit at its centre pixel
    (means projecting outside the image use the nearest edge pixel; means behind the camera
    are kept for gsplat's own near-plane culling). It equals the CPU backends' per-pixel
    rule except across a depth edge inside one splat's footprint: a kept splat then also
    covers mesh pixels nearer than itself, a dropped one leaves a gap over farther mesh
    pixels. Splats are a few pixels wide, so the difference is a fringe of about a splat
    radius along mesh silhouettes.
    """
    return splats.subset(depth_limit_keep_mask_numpy(splats.means, camera, depth_limit))


def rasterize_gsplat(
    splats: Splats, camera: Camera, depth_limit: npt.NDArray[np.floating] | None = None
) -> RasterOutput:
    """``rasterize(backend="gsplat")``: gsplat's CUDA rasterizer with the same conventions.

    gsplat is imported here, so this module imports without it (and without CUDA). The
    splats stay on the GPU between frames (``_gsplat_resident.resident_splats``); a depth
    limit is uploaded and applied per splat on the GPU by ``depth_limit_keep_mask``, the
    rule of `cull_behind_depth_limit` (see there for how that differs from the per-pixel
    rule); there is no per-pixel splat index; depth is gsplat's expected depth ("ED",
    normalised by alpha).
    """
    try:
        from gsplat import rasterization
    except ImportError as exc:
        raise RasterizeError("backend 'gsplat' needs the gsplat package (CUDA)") from exc
    device = torch.device("cuda")
    t0 = time.perf_counter()
    resident = resident_splats.get(splats, device)
    t1 = time.perf_counter()
    if depth_limit is not None:
        limit = torch.as_tensor(np.asarray(depth_limit, dtype=np.float32), device=device)
        resident = resident.subset(depth_limit_keep_mask(resident.means, camera, limit))
    t2 = time.perf_counter()
    timings = {"upload": 1e3 * (t1 - t0), "cull": 1e3 * (t2 - t1)}
    if len(resident) == 0:  # gsplat wants at least one Gaussian
        shape = (camera.height, camera.width)
        return RasterOutput(rgb=np.zeros((*shape, 3), np.float32), alpha=np.zeros(shape, np.float32),
                            transmittance=np.ones(shape, np.float32), depth=np.zeros(shape, np.float32),
                            index=None, timings={**timings, "total": 1e3 * (t2 - t0)})  # fmt: skip

    def cuda(a: npt.NDArray[np.float32]) -> torch.Tensor:
        return torch.as_tensor(a, device=device)

    colors, alphas, _ = rasterization(
        means=resident.means,
        quats=resident.quats,
        scales=resident.scales,
        opacities=resident.opacities,
        colors=resident.sh,
        viewmats=cuda(camera.world_to_camera.astype(np.float32))[None],
        Ks=cuda(camera.K.astype(np.float32))[None],
        width=camera.width,
        height=camera.height,
        near_plane=camera.near,
        far_plane=camera.far,
        eps2d=LOW_PASS,
        sh_degree=resident.sh_degree,
        packed=False,
        render_mode="RGB+ED",
    )
    torch.cuda.synchronize()
    t3 = time.perf_counter()
    rgb, depth, alpha, transmittance = _read_back(colors[0, ..., :3], colors[0, ..., 3], alphas[0, ..., 0])
    t4 = time.perf_counter()
    timings.update(draw=1e3 * (t3 - t2), read_back=1e3 * (t4 - t3), total=1e3 * (t4 - t0))
    return RasterOutput(rgb=rgb, alpha=alpha, transmittance=transmittance, depth=depth, index=None, timings=timings)


def _read_back(
    rgb: torch.Tensor, depth: torch.Tensor, alpha: torch.Tensor
) -> tuple[npt.NDArray[np.float32], npt.NDArray[np.float32], npt.NDArray[np.float32], npt.NDArray[np.float32]]:
    """rgb [H,W,3], depth, alpha and transmittance [H,W] as float32 arrays, in one copy from the GPU.

    The four images go into one page-locked host buffer (torch's caching host allocator: no
    page faults, full-speed DMA, reused once the arrays are dropped) and come back as views
    of it, so nothing is copied again on the host.
    """
    h, w = alpha.shape
    planes = torch.cat([rgb.reshape(-1), depth.reshape(-1), alpha.reshape(-1), (1.0 - alpha).reshape(-1)])
    host = torch.empty(planes.shape, dtype=torch.float32, pin_memory=True)
    host.copy_(planes, non_blocking=True)
    torch.cuda.current_stream().synchronize()
    flat = host.numpy()
    n = h * w
    return (flat[: 3 * n].reshape(h, w, 3), flat[3 * n : 4 * n].reshape(h, w), flat[4 * n : 5 * n].reshape(h, w),
            flat[5 * n :].reshape(h, w))  # fmt: skip
