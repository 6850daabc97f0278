"""The differentiable torch rasterizer has correct gradients for every splat parameter."""

from __future__ import annotations

import numpy as np
import pytest

torch = pytest.importorskip("torch")

from drivetwin.worlds.render._torch_raster import rasterize_torch  # noqa: E402
from drivetwin.worlds.render.camera import Camera  # noqa: E402


def tiny_scene() -> tuple[list, Camera]:
    # Three overlapping splats, SH degree 1, opacities well inside (1/255, 0.99) and sizes
    # of a few pixels, so no fragment sits on a threshold a finite difference could cross.
    rng = np.random.default_rng(11)
    means = np.array([[-0.1, 0.05, 2.0], [0.1, -0.05, 2.4], [0.0, 0.1, 2.8]])
    quats = rng.normal(size=(3, 4))
    log_scales = np.log(rng.uniform(0.05, 0.12, (3, 3)))
    logits = np.array([0.2, -0.3, 0.5])
    sh = rng.normal(0.0, 0.4, (3, 4, 3))
    tensors = [torch.tensor(a, dtype=torch.float64, requires_grad=True)
               for a in (means, quats, log_scales, logits, sh)]  # fmt: skip
    camera = Camera(12, 10, fx=20.0, fy=20.0, cx=6.2, cy=4.9, world_to_camera=np.eye(4))
    return tensors, camera


def test_gradients_to_means_scales_rotations_opacities_and_sh_pass_gradcheck():
    params, camera = tiny_scene()
    generator = torch.Generator().manual_seed(0)
    weights = [torch.rand(s, generator=generator, dtype=torch.float64)
               for s in ((10, 12, 3), (10, 12), (10, 12))]  # fmt: skip

    def render(*p):
        out = rasterize_torch(*p, camera)
        return torch.stack([(out.rgb * weights[0]).sum(), (out.alpha * weights[1]).sum(),
                            (out.depth * weights[2]).sum()])  # fmt: skip

    assert torch.autograd.gradcheck(render, params, eps=1e-6, atol=1e-6, rtol=1e-4)
    render(*params).sum().backward()
    for name, p in zip(["means", "quats", "log_scales", "opacity_logits", "sh"], params,
                       strict=True):  # fmt: skip
        assert p.grad is not None and p.grad.abs().sum() > 0, f"no gradient reaches {name}"


def test_fitting_colours_to_a_target_image_reduces_the_error():
    params, camera = tiny_scene()
    target = torch.zeros(10, 12, 3, dtype=torch.float64)
    target[..., 1] = 0.8  # green
    sh = params[4]
    optimiser = torch.optim.Adam([sh], lr=0.1)
    losses = []
    for _ in range(15):
        optimiser.zero_grad()
        out = rasterize_torch(*params, camera)
        loss = ((out.rgb - target * out.alpha[..., None]) ** 2).mean()
        loss.backward()
        optimiser.step()
        losses.append(float(loss.detach()))
    assert losses[-1] < 0.3 * losses[0]
