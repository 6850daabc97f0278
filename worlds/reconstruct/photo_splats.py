"""Appearance from images: fit splats to a posed capture, score held-out views, write the results.

``reconstruct_splats`` is the library form of ``drivetwin reconstruct splats``. It holds out
every k-th view (3DGS's evaluation protocol), fits splats to the rest, measures PSNR, SSIM
and (with user-supplied weights) LPIPS on the held-out views, and writes into ``out_dir``:

- ``visual/splats.ply``: the splats as a standard 3DGS PLY (``Splats.write_ply``);
- ``visual/cameras.json``: every view's name, split, intrinsics and world_to_camera;
- ``appearance_report.json``: held-out metrics, iterations, time per iteration, splat counts.

Coordinates are metres in the capture's world frame (z up for drivetwin captures).
"""

from __future__ import annotations

import json
import math
import platform
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
from drivetwin.worlds.render.splats import Splats

from .fit import FitConfig, FitHistory, FitProgress, fit_splats, initial_splats, render_views
from .image_metrics import psnr, ssim
from .lpips import load_lpips
from .views import PosedImages, camera_record

__all__ = [
    "CAMERAS_FILE",
    "REPORT_FILE",
    "SPLATS_FILE",
    "AppearanceResult",
    "ViewScore",
    "reconstruct_splats",
]

SPLATS_FILE = "visual/splats.ply"
CAMERAS_FILE = "visual/cameras.json"
REPORT_FILE = "appearance_report.json"
REPORT_FORMAT = "drivetwin-appearance-report-v1"


@dataclass(frozen=True)
class ViewScore:
    """Metrics of one held-out view: PSNR (dB), SSIM, LPIPS (None without weights)."""

    name: str
    psnr: float
    ssim: float
    lpips: float | None = None


@dataclass
class AppearanceResult:
    """What ``reconstruct_splats`` made: the splats, per-view scores, their means, the fit's history, files."""

    splats: Splats = field(repr=False)
    held_out: list[ViewScore]
    psnr: float
    ssim: float
    lpips: float | None
    initial_psnr: float
    history: FitHistory = field(repr=False)
    splats_path: Path
    cameras_path: Path
    report_path: Path


def _mean(values: list[float]) -> float:
    finite = [v for v in values if math.isfinite(v)]
    return float(np.mean(finite)) if finite else math.inf


def _scores(splats: Splats, held: PosedImages, config: FitConfig, lpips_weights: Path | None) -> list[ViewScore]:
    network = load_lpips(lpips_weights) if lpips_weights is not None else None
    rendered = render_views(splats, held.cameras, config.background)
    scores = []
    for view, image in zip(held.views, rendered, strict=True):
        lp = network.distance(image, view.image) if network is not None else None
        scores.append(ViewScore(view.name, psnr(image, view.image), ssim(image, view.image), lp))
    return scores


def reconstruct_splats(
    images: PosedImages,
    out_dir: str | Path,
    *,
    iterations: int,
    held_out_every: int = 8,
    config: FitConfig | None = None,
    lpips_weights: str | Path | None = None,
    progress: Callable[[FitProgress], None] | None = None,
) -> AppearanceResult:
    """Fit splats to ``images`` with every ``held_out_every``-th view held out; score and write them.

    ``config`` sets everything but ``iterations`` (default ``FitConfig()``); ``lpips_weights``
    is a weights file or folder for ``load_lpips`` (checked before the fit, so a bad path
    fails fast). Returns the ``AppearanceResult``; files as in the module docstring.
    """
    fit_config = replace(config or FitConfig(), iterations=iterations)
    fit_config.check()
    weights = Path(lpips_weights) if lpips_weights is not None else None
    if weights is not None:
        load_lpips(weights)  # fail before a long fit, not after it
    train, held = images.split(held_out_every)
    start = initial_splats(train, fit_config)
    initial = _scores(start, held, fit_config, None)
    splats, history = fit_splats(train, fit_config, init=start, progress=progress)
    scores = _scores(splats, held, fit_config, weights)

    out = Path(out_dir)
    splats_path, cameras_path, report_path = out / SPLATS_FILE, out / CAMERAS_FILE, out / REPORT_FILE
    splats_path.parent.mkdir(parents=True, exist_ok=True)
    splats.write_ply(splats_path)
    held_names = {v.name for v in held.views}
    cameras = [
        {"name": v.name, "split": "test" if v.name in held_names else "train", **camera_record(v.camera)}
        for v in images.views
    ]
    cameras_doc = {"frame": "capture world, metres; cameras OpenCV (x right, y down, z forward)", "views": cameras}
    cameras_path.write_text(json.dumps(cameras_doc, indent=1), encoding="utf-8")
    lpips_values = [s.lpips for s in scores if s.lpips is not None]
    result = AppearanceResult(
        splats=splats,
        held_out=scores,
        psnr=_mean([s.psnr for s in scores]),
        ssim=float(np.mean([s.ssim for s in scores])),
        lpips=float(np.mean(lpips_values)) if lpips_values else None,
        initial_psnr=_mean([s.psnr for s in initial]),
        history=history,
        splats_path=splats_path,
        cameras_path=cameras_path,
        report_path=report_path,
    )
    report_path.write_text(json.dumps(_report(result, fit_config, images, held_out_every), indent=1), encoding="utf-8")
    return result


def _report(result: AppearanceResult, config: FitConfig, images: PosedImages, held_out_every: int) -> dict[str, Any]:
    history = result.history
    view = images.views[0].camera
    return {
        "format": REPORT_FORMAT,
        "metrics": {
            "psnr": result.psnr,
            "ssim": result.ssim,
            "lpips": result.lpips,
            "initial_psnr": result.initial_psnr,
            "views": [vars(score) for score in result.held_out],
        },
        "views": {"total": len(images), "held_out": len(result.held_out), "held_out_every": held_out_every},
        "image_size": [view.width, view.height],
        "iterations": len(history.loss),
        "seconds": history.seconds,
        "seconds_per_iteration": history.seconds_per_iteration,
        "device": history.device,
        "machine": platform.machine(),
        "splats": {
            "initial": history.initial_count,
            "final": len(result.splats),
            "max": max(history.splats),
        },
        "loss": {"first": history.loss[0], "last": history.loss[-1]},
        "density_changes": [vars(change) for change in history.changes],
        "opacity_resets": history.opacity_resets,
        "config": vars(config),
        "files": {"splats": SPLATS_FILE, "cameras": CAMERAS_FILE},
    }
