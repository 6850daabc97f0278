"""Adaptive density control of a splat fit, as 3D Gaussian Splatting does it (Kerbl et al. 2023).

Splats whose view-space positional gradient, averaged over the views that saw them, exceeds
a threshold are under-reconstructed: small ones (largest scale at most ``percent_dense`` of
the scene extent) are cloned, large ones are split into two smaller ones sampled from their
own Gaussian. Nearly transparent splats and splats larger than a fraction of the scene are
pruned. Opacity is periodically reset low so splats that are not needed fade and are pruned.
Adam's moments follow the splats through every change (copied for clones, zero for splits).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import torch
from drivetwin.worlds.render._torch_raster import rotation_matrices
from drivetwin.worlds.render.camera import Camera

__all__ = ["PARAM_NAMES", "DensityChange", "GradientStats", "densify_and_prune", "reset_opacity", "view_space_gradient"]

PARAM_NAMES = ("means", "quats", "log_scales", "opacity_logits", "sh")
# A split splat becomes two whose scales shrink by this factor (3DGS: 0.8 * N with N = 2).
SPLIT_SHRINK = 1.6
SPLIT_COPIES = 2

Params = dict[str, torch.nn.Parameter]


@dataclass(frozen=True)
class DensityChange:
    """What one densification step did: splats cloned, split (originals) and pruned, and the count after."""

    iteration: int
    cloned: int
    split: int
    pruned: int
    count: int


class GradientStats:
    """Running sum of view-space positional gradient norms per splat and how many views saw each."""

    def __init__(self, count: int, device: torch.device) -> None:
        self.sum = torch.zeros(count, device=device)
        self.views = torch.zeros(count, device=device)

    def add(self, grad_norm: torch.Tensor) -> None:
        """Add one view's gradient norms [N]; splats with zero gradient were not seen."""
        seen = grad_norm > 0
        self.sum += torch.where(seen, grad_norm, torch.zeros_like(grad_norm))
        self.views += seen.to(self.views.dtype)

    def mean(self) -> torch.Tensor:
        """Average gradient norm per splat over the views that saw it (0 if none)."""
        return self.sum / self.views.clamp_min(1.0)


def view_space_gradient(means_grad: torch.Tensor, means: torch.Tensor, camera: Camera) -> torch.Tensor:
    """Norm [N] of the loss gradient with respect to each splat's projected centre, in NDC units.

    The rasterizer does not expose its projected centres, so the gradient is recovered from
    the world-space mean gradient: rotated into the camera frame, its x and y components
    times z / f are the gradient per pixel of the centre (exact for the centre's own path,
    ignoring the smaller covariance-Jacobian terms), and times half the image size per NDC
    unit, the units of 3DGS's threshold.
    """
    view = torch.tensor(np.array(camera.world_to_camera), dtype=means.dtype, device=means.device)
    grad_cam = means_grad @ view[:3, :3].T
    z = (means.detach() @ view[:3, :3].T + view[:3, 3])[:, 2].clamp_min(camera.near)
    du = grad_cam[:, 0] * z / camera.fx * (0.5 * camera.width)
    dv = grad_cam[:, 1] * z / camera.fy * (0.5 * camera.height)
    return torch.sqrt(du * du + dv * dv)


def _rebuild(
    params: Params, optimizer: torch.optim.Optimizer, keep: torch.Tensor, extra: dict[str, torch.Tensor]
) -> Params:
    """New parameters = old rows ``keep`` then ``extra`` rows; Adam moments follow (zero for extras).

    Extra rows listed in ``extra['_moment_source']`` (indices into the old rows) copy their
    moments from those rows instead (clones continue their source's optimisation).
    """
    source = extra.get("_moment_source")
    new_params: Params = {}
    for group in optimizer.param_groups:
        name = group["name"]
        old = params[name]
        fresh = torch.nn.Parameter(torch.cat([old.detach()[keep], extra[name]]).contiguous())
        state = optimizer.state.pop(old, None)
        if state is not None:
            for key in ("exp_avg", "exp_avg_sq"):
                moment = state[key]
                tail = moment[source] if source is not None else torch.zeros_like(extra[name])
                state[key] = torch.cat([moment[keep], tail])
            optimizer.state[fresh] = state
        group["params"] = [fresh]
        new_params[name] = fresh
    return new_params


def densify_and_prune(
    params: Params,
    optimizer: torch.optim.Optimizer,
    stats: GradientStats,
    *,
    iteration: int,
    grad_threshold: float,
    percent_dense: float,
    extent: float,
    min_opacity: float,
    max_scale_fraction: float,
    max_splats: int,
    generator: torch.Generator,
) -> tuple[Params, DensityChange]:
    """Clone, split, then prune (3DGS order); returns the new parameters and what changed.

    ``max_splats`` caps growth: when more splats qualify than the budget allows, those with
    the largest gradients are densified first.
    """
    n = params["means"].shape[0]
    device = params["means"].device
    with torch.no_grad():
        grad = stats.mean()
        max_scale = params["log_scales"].exp().max(dim=1).values
        candidates = grad >= grad_threshold
        budget = max(0, max_splats - n)
        if int(candidates.sum()) > budget:
            order = torch.argsort(
                torch.where(candidates, grad, torch.full_like(grad, -1.0)), descending=True, stable=True
            )
            candidates = torch.zeros_like(candidates)
            candidates[order[:budget]] = True
        small = max_scale <= percent_dense * extent
        clone = torch.nonzero(candidates & small).flatten()
        split = torch.nonzero(candidates & ~small).flatten()

        # Split: two samples from each large splat's own Gaussian, scales shrunk.
        rep = split.repeat(SPLIT_COPIES)
        scales = params["log_scales"][rep].exp()
        offsets = torch.randn(scales.shape, generator=generator, device="cpu").to(device) * scales
        rot = rotation_matrices(params["quats"][rep])
        extra = {
            "means": torch.cat([params["means"][clone], params["means"][rep] + (rot @ offsets[:, :, None])[:, :, 0]]),
            "log_scales": torch.cat([params["log_scales"][clone], torch.log(scales / SPLIT_SHRINK)]),
        }
        for name in ("quats", "opacity_logits", "sh"):
            extra[name] = torch.cat([params[name][clone], params[name][rep]])
        keep = torch.ones(n, dtype=torch.bool, device=device)
        keep[split] = False  # split originals are replaced by their two samples
        kept = torch.nonzero(keep).flatten()
        extra_source = torch.cat([clone, rep])
        params = _rebuild(params, optimizer, kept, {**extra, "_moment_source": extra_source})
        # Split children start with zero moments, as 3DGS does; clones keep their source's.
        for group in optimizer.param_groups:
            state = optimizer.state.get(group["params"][0])
            if state is not None and len(split):
                for key in ("exp_avg", "exp_avg_sq"):
                    state[key][len(kept) + len(clone) :] = 0.0

        opacity = torch.sigmoid(params["opacity_logits"])
        too_big = params["log_scales"].exp().max(dim=1).values > max_scale_fraction * extent
        prune = (opacity < min_opacity) | too_big
        if int(prune.sum()) == len(prune):  # never prune every splat: keep the most opaque
            prune[torch.argmax(opacity)] = False
        survivors = torch.nonzero(~prune).flatten()
        empty = {name: params[name][:0] for name in PARAM_NAMES}
        params = _rebuild(params, optimizer, survivors, empty)
    change = DensityChange(iteration=iteration, cloned=len(clone), split=len(split), pruned=int(prune.sum()),
                           count=params["means"].shape[0])  # fmt: skip
    return params, change


def reset_opacity(params: Params, optimizer: torch.optim.Optimizer, ceiling: float) -> None:
    """Clamp every opacity to at most ``ceiling`` and zero the opacity's Adam moments (3DGS reset)."""
    logit = math.log(ceiling / (1.0 - ceiling))
    with torch.no_grad():
        params["opacity_logits"].clamp_(max=logit)
    state = optimizer.state.get(params["opacity_logits"])
    if state is not None:
        state["exp_avg"].zero_()
        state["exp_avg_sq"].zero_()
