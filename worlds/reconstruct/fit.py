"""Fit Gaussian splats to posed images with the project's differentiable rasterizer (3DGS training).

The method is 3D Gaussian Splatting's (Kerbl et al. 2023): splats start from the sparse
coloured points (``Splats.from_points``), one random training view per iteration is
rendered with ``rasterize_torch``, the loss is (1 - lambda) L1 + lambda (1 - SSIM) with
lambda = 0.2, Adam steps every parameter with its own learning rate (means' decays
exponentially and scales with the scene extent), and adaptive density control (``densify``)
clones, splits and prunes splats, with periodic opacity resets. The defaults are 3DGS's
rates with its schedule compressed for small captures of a few hundred iterations.

Runs on the CPU for small captures and on CUDA when torch sees a GPU (``device="auto"``);
tile binning stays on the CPU either way. Deterministic for a seed on one device.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np
import numpy.typing as npt
import torch
from drivetwin.worlds.render._torch_raster import rasterize_torch
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.splats import Splats, SplatsError

from .densify import PARAM_NAMES, DensityChange, GradientStats, densify_and_prune, reset_opacity, view_space_gradient
from .image_metrics import ssim_torch
from .views import PosedImages

__all__ = [
    "FitConfig",
    "FitError",
    "FitHistory",
    "FitProgress",
    "fit_splats",
    "initial_splats",
    "render_views",
    "torch_device",
]

DeviceName = Literal["auto", "cpu", "cuda"]


class FitError(ValueError):
    """A splat fit was asked for with settings or inputs it cannot use."""


@dataclass(frozen=True)
class FitConfig:
    """Settings of one fit. Learning rates are 3DGS's; the schedule is scaled to short runs."""

    iterations: int = 300
    seed: int = 0
    ssim_weight: float = 0.2  # lambda of the D-SSIM term (3DGS)
    sh_degree: int = 0  # view-dependent colour bands; 0 is enough for diffuse captures
    lr_means: float = 1.6e-4  # times the scene extent, decaying to lr_means_final (3DGS)
    lr_means_final: float = 1.6e-6
    lr_sh_dc: float = 2.5e-3
    lr_sh_rest: float = 2.5e-3 / 20.0  # higher bands learn 20x slower (3DGS)
    lr_opacity: float = 0.05
    lr_scales: float = 5e-3
    lr_quats: float = 1e-3
    init_opacity: float = 0.1  # 3DGS starts every splat at 10 % opacity
    init_neighbours: int = 3  # initial scale: RMS distance to this many nearest points
    densify_from: int = 50  # 3DGS: 500 of 30k iterations
    densify_until: int = 240  # 3DGS: 15k of 30k
    densify_every: int = 50  # 3DGS: 100
    grad_threshold: float = 2e-4  # mean view-space gradient norm (NDC) that marks a splat for densification
    percent_dense: float = 0.01  # splats larger than this fraction of the extent are split, smaller cloned
    min_opacity: float = 0.005  # pruned below this opacity
    max_scale_fraction: float = 0.1  # pruned when larger than this fraction of the extent
    opacity_reset_every: int = 150  # 3DGS: 3000
    opacity_reset_value: float = 0.01
    max_splats: int = 20_000  # growth budget (memory and time of the CPU rasterizer)
    background: tuple[float, float, float] = (0.0, 0.0, 0.0)  # colour behind the splats
    device: DeviceName = "auto"

    def check(self) -> None:
        """Raise ``FitError`` for settings outside their allowed ranges."""
        if self.iterations < 1:
            raise FitError(f"iterations must be >= 1, got {self.iterations}")
        if not 0.0 <= self.ssim_weight <= 1.0:
            raise FitError(f"ssim_weight must be in [0, 1], got {self.ssim_weight}")
        if not 0 <= self.sh_degree <= 3:
            raise FitError(f"sh_degree must be 0..3, got {self.sh_degree}")
        if self.densify_every < 1 or self.opacity_reset_every < 1 or self.max_splats < 1:
            raise FitError("densify_every, opacity_reset_every and max_splats must be >= 1")
        if any(not 0.0 <= c <= 1.0 for c in self.background):
            raise FitError(f"background must be an RGB triple in [0, 1], got {self.background}")


@dataclass(frozen=True)
class FitProgress:
    """One iteration's report to a progress callback."""

    iteration: int
    iterations: int
    loss: float
    splats: int
    seconds: float


@dataclass
class FitHistory:
    """Loss and splat count per iteration, density changes, and time."""

    loss: list[float] = field(default_factory=list)
    splats: list[int] = field(default_factory=list)
    changes: list[DensityChange] = field(default_factory=list)
    opacity_resets: list[int] = field(default_factory=list)
    seconds: float = 0.0
    device: str = "cpu"
    initial_count: int = 0

    @property
    def seconds_per_iteration(self) -> float:
        return self.seconds / max(1, len(self.loss))


def torch_device(name: DeviceName) -> torch.device:
    """The torch device for ``name``: "auto" is CUDA when torch sees a GPU, else the CPU."""
    if name == "auto":
        return torch.device("cuda" if torch.cuda.is_available() else "cpu")
    if name == "cuda" and not torch.cuda.is_available():
        raise FitError("device 'cuda' asked for but torch sees no CUDA GPU; use 'auto' or 'cpu'")
    return torch.device(name)


def initial_splats(images: PosedImages, config: FitConfig) -> Splats:
    """Splats seeded from the set's sparse coloured points, as 3DGS seeds from SfM points."""
    if images.points is None or images.colors is None or len(images.points) <= config.init_neighbours:
        raise FitError("fitting needs sparse coloured points to start from (a COLMAP model's points3D, "
                       "run_sfm, or \"points\" in the poses JSON); this set has too few")  # fmt: skip
    try:
        return Splats.from_points(images.points, np.clip(images.colors, 0.0, 1.0), k=config.init_neighbours,
                                  opacity=config.init_opacity, sh_degree=config.sh_degree)  # fmt: skip
    except SplatsError as exc:
        raise FitError(f"cannot seed splats from the sparse points: {exc}") from exc


def _means_lr(config: FitConfig, extent: float, iteration: int) -> float:
    """3DGS's log-linear decay of the means' learning rate from lr_means to lr_means_final."""
    t = min(1.0, iteration / max(1, config.iterations))
    return extent * math.exp((1 - t) * math.log(config.lr_means) + t * math.log(config.lr_means_final))


def _optimizer(params: dict[str, torch.nn.Parameter], config: FitConfig, extent: float) -> torch.optim.Adam:
    rates = {"means": config.lr_means * extent, "quats": config.lr_quats, "log_scales": config.lr_scales,
             "opacity_logits": config.lr_opacity, "sh": config.lr_sh_dc}  # fmt: skip
    groups = [{"params": [params[name]], "lr": rates[name], "name": name} for name in PARAM_NAMES]
    # 3DGS's Adam epsilon: small enough not to damp the tiny gradients of small splats.
    return torch.optim.Adam(groups, lr=0.0, eps=1e-15)


def fit_splats(
    images: PosedImages,
    config: FitConfig = FitConfig(),
    *,
    init: Splats | None = None,
    progress: Callable[[FitProgress], None] | None = None,
) -> tuple[Splats, FitHistory]:
    """Fit splats to ``images`` (all views train); returns the splats and the fit's history.

    ``init`` replaces the seeding from sparse points. ``progress`` is called after every
    iteration with a ``FitProgress``.
    """
    config.check()
    device = torch_device(config.device)
    start = init if init is not None else initial_splats(images, config)
    if start.sh_degree != config.sh_degree:
        raise FitError(f"init splats have SH degree {start.sh_degree}, the config asks for {config.sh_degree}")
    torch.manual_seed(config.seed)
    rng = np.random.default_rng(config.seed)
    generator = torch.Generator().manual_seed(config.seed)
    extent = images.scene_extent()
    params = {name: torch.nn.Parameter(torch.as_tensor(getattr(start, name), device=device)) for name in PARAM_NAMES}
    optimizer = _optimizer(params, config, extent)
    sh_rest_ratio = config.lr_sh_rest / config.lr_sh_dc
    targets = [torch.as_tensor(v.image, device=device) for v in images.views]
    background = torch.tensor(config.background, dtype=torch.float32, device=device)
    stats = GradientStats(len(start), device)
    history = FitHistory(device=str(device), initial_count=len(start))
    order: list[int] = []
    t0 = time.perf_counter()
    for iteration in range(1, config.iterations + 1):
        for group in optimizer.param_groups:
            if group["name"] == "means":
                group["lr"] = _means_lr(config, extent, iteration)
        if not order:  # every view once per epoch, in a seeded random order (3DGS)
            order = rng.permutation(len(images)).tolist()
        index = order.pop()
        camera = images.views[index].camera
        out = rasterize_torch(
            params["means"], params["quats"], params["log_scales"], params["opacity_logits"], params["sh"], camera
        )
        rendered = out.rgb + (1.0 - out.alpha)[..., None] * background
        target = targets[index]
        l1 = (rendered - target).abs().mean()
        loss = (1.0 - config.ssim_weight) * l1 + config.ssim_weight * (1.0 - ssim_torch(rendered, target))
        optimizer.zero_grad(set_to_none=True)
        loss.backward()  # type: ignore[no-untyped-call]
        sh = params["sh"]
        if sh.shape[1] > 1:
            snapshot = sh.detach()[:, 1:].clone()
        means_grad = params["means"].grad
        if iteration <= config.densify_until and means_grad is not None:
            stats.add(view_space_gradient(means_grad, params["means"], camera))
        optimizer.step()
        if sh.shape[1] > 1:
            with torch.no_grad():  # higher SH bands take lr_sh_rest-sized steps
                sh[:, 1:] = snapshot + sh_rest_ratio * (sh[:, 1:] - snapshot)
        if config.densify_from <= iteration <= config.densify_until and iteration % config.densify_every == 0:
            params, change = densify_and_prune(
                params, optimizer, stats, iteration=iteration, grad_threshold=config.grad_threshold,
                percent_dense=config.percent_dense, extent=extent, min_opacity=config.min_opacity,
                max_scale_fraction=config.max_scale_fraction, max_splats=config.max_splats, generator=generator,
            )  # fmt: skip
            history.changes.append(change)
            stats = GradientStats(change.count, device)
        if iteration % config.opacity_reset_every == 0 and iteration < config.iterations:
            reset_opacity(params, optimizer, config.opacity_reset_value)
            history.opacity_resets.append(iteration)
        history.loss.append(float(loss.detach()))
        history.splats.append(int(params["means"].shape[0]))
        if progress is not None:
            progress(FitProgress(iteration, config.iterations, history.loss[-1], history.splats[-1],
                                 time.perf_counter() - t0))  # fmt: skip
    history.seconds = time.perf_counter() - t0
    arrays = {name: params[name].detach().cpu().numpy() for name in PARAM_NAMES}
    return Splats(**arrays), history


def render_views(
    splats: Splats, cameras: Sequence[Camera], background: tuple[float, float, float] = (0.0, 0.0, 0.0)
) -> list[npt.NDArray[np.float32]]:
    """Images [H,W,3] float32 in 0..1 of ``splats`` through ``cameras`` (the fit's renderer and background)."""
    images = []
    means, quats, log_scales, opacity_logits, sh = (torch.as_tensor(getattr(splats, name)) for name in PARAM_NAMES)
    bg = torch.tensor(background, dtype=torch.float32)
    with torch.no_grad():
        for camera in cameras:
            out = rasterize_torch(means, quats, log_scales, opacity_logits, sh, camera)
            images.append((out.rgb + (1.0 - out.alpha)[..., None] * bg).clamp(0.0, 1.0).numpy())
    return images
