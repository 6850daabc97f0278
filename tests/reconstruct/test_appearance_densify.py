"""Adaptive density control: clone small and split large high-gradient splats, prune, reset opacity."""

from __future__ import annotations

import math

import numpy as np
import pytest
import torch
from drivetwin.worlds.reconstruct.densify import (
    PARAM_NAMES,
    GradientStats,
    densify_and_prune,
    reset_opacity,
    view_space_gradient,
)
from drivetwin.worlds.render.camera import Camera

EXTENT = 10.0  # metres: small splats are <= 0.1 m (1 %), too large > 1 m (10 %)
THRESHOLD = 1e-3


def _logit(p: float) -> float:
    return math.log(p / (1 - p))


def _setup(scales: list[float], opacities: list[float], grads: list[float]) -> tuple[
    dict[str, torch.nn.Parameter], torch.optim.Adam, GradientStats
]:  # fmt: skip
    n = len(scales)
    params = {
        "means": torch.nn.Parameter(torch.arange(3 * n, dtype=torch.float32).reshape(n, 3)),
        "quats": torch.nn.Parameter(torch.tensor([[1.0, 0.0, 0.0, 0.0]] * n)),
        "log_scales": torch.nn.Parameter(torch.log(torch.tensor(scales))[:, None].repeat(1, 3)),
        "opacity_logits": torch.nn.Parameter(torch.tensor([_logit(p) for p in opacities])),
        "sh": torch.nn.Parameter(torch.arange(n, dtype=torch.float32).reshape(n, 1, 1).repeat(1, 1, 3)),
    }
    optimizer = torch.optim.Adam([{"params": [params[k]], "lr": 1e-3, "name": k} for k in PARAM_NAMES])
    sum(p.sum() for p in params.values()).backward()  # type: ignore[union-attr]
    optimizer.step()  # creates Adam moments for every splat
    stats = GradientStats(n, torch.device("cpu"))
    stats.add(torch.tensor(grads))
    return params, optimizer, stats


def _run(params: dict[str, torch.nn.Parameter], optimizer: torch.optim.Adam, stats: GradientStats,
         max_splats: int = 100) -> tuple[dict[str, torch.nn.Parameter], object]:  # fmt: skip
    return densify_and_prune(params, optimizer, stats, iteration=10, grad_threshold=THRESHOLD, percent_dense=0.01,
                             extent=EXTENT, min_opacity=0.005, max_scale_fraction=0.1, max_splats=max_splats,
                             generator=torch.Generator().manual_seed(0))  # fmt: skip


def test_a_small_splat_with_a_high_gradient_is_cloned_in_place() -> None:
    params, optimizer, stats = _setup([0.05, 0.05], [0.5, 0.5], [2e-3, 1e-4])
    new, change = _run(params, optimizer, stats)
    assert (change.cloned, change.split, change.pruned, change.count) == (1, 0, 0, 3)  # type: ignore[attr-defined]
    assert torch.equal(new["means"][2], new["means"][0])  # the clone sits on its source
    assert torch.equal(new["sh"][2], new["sh"][0])


def test_a_large_splat_with_a_high_gradient_is_split_into_two_smaller_ones() -> None:
    params, optimizer, stats = _setup([0.5, 0.05], [0.5, 0.5], [2e-3, 1e-4])
    new, change = _run(params, optimizer, stats)
    assert (change.cloned, change.split, change.pruned, change.count) == (0, 1, 0, 3)  # type: ignore[attr-defined]
    children = new["log_scales"][1:].exp().detach()
    parent = params["log_scales"][0].exp().detach()
    np.testing.assert_allclose(children.numpy(), (parent / 1.6).expand(2, 3).numpy(), rtol=1e-5)
    assert torch.equal(new["means"][0], params["means"][1])  # the untouched splat is kept, first
    # Children are drawn from the parent's Gaussian: near it, not on it.
    offsets = (new["means"][1:] - params["means"][0]).norm(dim=1)
    assert torch.all(offsets > 0) and torch.all(offsets < 5 * 0.5)


def test_transparent_and_oversized_splats_are_pruned() -> None:
    params, optimizer, stats = _setup([0.05, 0.05, 2.0], [0.5, 0.001, 0.5], [0.0, 0.0, 0.0])
    new, change = _run(params, optimizer, stats)
    assert (change.cloned, change.split, change.pruned, change.count) == (0, 0, 2, 1)  # type: ignore[attr-defined]
    assert torch.equal(new["means"][0], params["means"][0])


def test_adam_moments_follow_the_splats() -> None:
    params, optimizer, stats = _setup([0.05, 0.5, 0.05], [0.5, 0.5, 0.001], [2e-3, 2e-3, 0.0])
    old_moment = optimizer.state[params["sh"]]["exp_avg"].clone()
    new, _ = _run(params, optimizer, stats)
    # Kept 0 and 2 -> 2 is pruned; then clone of 0, then two children of 1: [0, clone0, child, child].
    state = optimizer.state[new["sh"]]
    assert state["exp_avg"].shape == new["sh"].shape
    assert torch.equal(state["exp_avg"][1], old_moment[0])  # a clone continues its source's moments
    assert torch.all(state["exp_avg"][2:] == 0)  # split children start fresh
    assert optimizer.param_groups[4]["params"][0] is new["sh"]


def test_growth_stops_at_the_splat_budget_taking_the_largest_gradients_first() -> None:
    params, optimizer, stats = _setup([0.05, 0.05, 0.05], [0.5, 0.5, 0.5], [2e-3, 5e-3, 3e-3])
    new, change = _run(params, optimizer, stats, max_splats=4)
    assert change.cloned == 1 and change.count == 4  # type: ignore[attr-defined]
    assert torch.equal(new["means"][3], params["means"][1])  # the largest gradient's clone


def test_opacity_reset_clamps_opacities_and_clears_their_moments() -> None:
    params, optimizer, _ = _setup([0.05, 0.05], [0.9, 0.001], [0.0, 0.0])
    reset_opacity(params, optimizer, 0.01)
    opacity = torch.sigmoid(params["opacity_logits"]).detach()
    assert opacity[0] == pytest.approx(0.01, rel=1e-5) and opacity[1] == pytest.approx(0.001, rel=1e-2)
    assert torch.all(optimizer.state[params["opacity_logits"]]["exp_avg"] == 0)


def test_view_space_gradient_is_the_pixel_gradient_of_the_projected_centre() -> None:
    camera = Camera.from_look_at((0.0, -5.0, 0.0), (0.0, 0.0, 0.0), width=64, height=48, fovy_deg=50)
    mean = torch.tensor([[0.3, 0.0, -0.2]], dtype=torch.float64, requires_grad=True)
    view = torch.tensor(np.array(camera.world_to_camera))
    p = mean @ view[:3, :3].T + view[:3, 3]
    u = camera.fx * p[:, 0] / p[:, 2] + camera.cx
    (3.0 * u).sum().backward()  # dL/du = 3 per pixel
    assert mean.grad is not None
    got = view_space_gradient(mean.grad, mean, camera)
    # 3 per pixel is 3 * W / 2 per NDC unit; the z-dependence of u adds a small term.
    assert float(got[0]) == pytest.approx(3.0 * 32, rel=0.1)
