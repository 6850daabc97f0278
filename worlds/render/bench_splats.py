"""Benchmark of the splat rasterizer: FPS and milliseconds per stage, written as JSON.

Example::

    python -m drivetwin.worlds.render.bench_splats --width 640 --height 360 \\
        --counts 10000 100000 1000000 --frames 7 --out bench_splats.json

The scene is a synthetic street canyon (ground, two facades, an end wall) sampled uniformly
in image space and turned into splats the way 3DGS initialises from a point cloud (kNN
isotropic scales capped at 1 m, opacity 0.8), so density and overlap resemble a
reconstructed scene.
Backends: "numba" (CPU), "torch" (CPU, slow; capped by --torch-max-count), "torch-cuda"
and "gsplat" where CUDA (and gsplat) are present. Against gsplat it reports the PSNR
between gsplat's image and the numba image of the same scene.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
from collections.abc import Sequence
from typing import Any

import numpy as np
import numpy.typing as npt
from drivetwin.worlds.image_metrics import psnr

from .camera import Camera
from .rasterize import RasterOutput, available_backends, rasterize
from .splats import Splats

__all__ = ["main", "markdown_table", "street_camera", "street_scene"]

# Opacity the probe in DESIGN.md used for the garden capture: dense but not solid.
SCENE_OPACITY = 0.8
# kNN scales are capped here: the few isolated samples (sky-grazing rays, the far wall at
# 10k points) would otherwise become splats metres wide; denser samples are unaffected.
SCENE_MAX_SCALE_M = 1.0
_STREET_HALF_WIDTH, _WALL_HEIGHT, _END_WALL = 6.0, 12.0, 80.0  # metres
_EYE_HEIGHT = 1.6  # metres, a car-mounted camera


def street_camera(width: int, height: int, fovy_deg: float = 50.0) -> Camera:
    """The benchmark camera: 1.6 m above the road, looking down the street (+x, z up)."""
    eye = (0.0, 0.0, _EYE_HEIGHT)
    return Camera.from_look_at(eye, (10.0, 0.0, _EYE_HEIGHT), width=width, height=height, fovy_deg=fovy_deg)


def street_scene(n: int, camera: Camera, seed: int = 0) -> Splats:
    """About ``n`` splats on a street canyon seen by ``camera`` (sky rays yield no splat)."""
    rng = np.random.default_rng(seed)
    m = int(n * 1.4) + 16  # oversample: rays into the sky are dropped
    pix = rng.uniform([0, 0], [camera.width, camera.height], (m, 2))
    rays_cam = np.stack([(pix[:, 0] - camera.cx) / camera.fx, (pix[:, 1] - camera.cy) / camera.fy, np.ones(m)], 1)
    c2w = camera.camera_to_world
    rays = rays_cam @ c2w[:3, :3].T
    origin = c2w[:3, 3]
    hits = np.full(m, np.inf)
    kind = np.zeros(m, np.int64)
    with np.errstate(divide="ignore", invalid="ignore"):
        for surface, (axis, value) in enumerate(
            [(2, 0.0), (1, _STREET_HALF_WIDTH), (1, -_STREET_HALF_WIDTH), (0, _END_WALL)]
        ):
            t = (value - origin[axis]) / rays[:, axis]
            point = origin + t[:, None] * rays
            inside = (t > 0) & (point[:, 2] <= _WALL_HEIGHT + 1e-9) & (point[:, 2] >= -1e-9)
            inside &= np.abs(point[:, 1]) <= _STREET_HALF_WIDTH + 1e-9
            better = inside & (t < hits)
            hits[better], kind[better] = t[better], surface
    hit = np.flatnonzero(np.isfinite(hits))[:n]
    points = origin + hits[hit, None] * rays[hit]
    checker = (np.floor(points[:, 0]) + np.floor(points[:, 1]) + np.floor(points[:, 2])) % 2
    palette = np.array([[0.35, 0.35, 0.38], [0.75, 0.55, 0.45], [0.55, 0.6, 0.75], [0.8, 0.8, 0.7]])
    colors = np.clip(palette[kind[hit]] * (0.8 + 0.2 * checker[:, None])
                     + rng.normal(0, 0.03, (len(hit), 3)), 0, 1)  # fmt: skip
    return Splats.from_points(points, colors, opacity=SCENE_OPACITY, max_scale=SCENE_MAX_SCALE_M)


def markdown_table(results: list[dict[str, Any]]) -> str:
    """The results as a Markdown table: backend, splats, ms per stage, FPS."""
    stages = ("project", "bin", "composite", "total")
    lines = ["| backend | splats | " + " | ".join(f"{s} ms" for s in stages) + " | FPS |",
             "|" + " --- |" * (len(stages) + 3)]  # fmt: skip
    for r in results:
        cells = [f"{r['ms'][s]:.1f}" if s in r["ms"] else "" for s in stages]
        lines.append(f"| {r['backend']} | {r['splats']:,} | " + " | ".join(cells) + f" | {r['fps']:.2f} |")
    return "\n".join(lines)


def _run(backend: str, splats: Splats, camera: Camera) -> RasterOutput:
    if backend == "torch-cuda":
        import torch

        from ._torch_raster import rasterize_torch

        def cuda(a: npt.NDArray[np.float32]) -> torch.Tensor:
            return torch.as_tensor(a, device="cuda")

        with torch.no_grad():
            out = rasterize_torch(cuda(splats.means), cuda(splats.quats),
                                  cuda(splats.log_scales), cuda(splats.opacity_logits),
                                  cuda(splats.sh), camera)  # fmt: skip
            torch.cuda.synchronize()
        alpha = out.alpha.cpu().numpy()
        return RasterOutput(out.rgb.cpu().numpy(), alpha, 1 - alpha, out.depth.cpu().numpy(),
                            None, {**out.timings, "total": sum(out.timings.values())})  # fmt: skip
    return rasterize(splats, camera, backend=backend)  # type: ignore[arg-type]


def bench_one(backend: str, splats: Splats, camera: Camera, frames: int) -> dict[str, Any]:
    """Median timings over ``frames`` frames after one warm-up frame (compiles, caches)."""
    first = _run(backend, splats, camera)
    runs = [_run(backend, splats, camera).timings for _ in range(frames)]
    stages = {k: statistics.median(run[k] for run in runs) for k in runs[0] if k != "intersections"}
    return {
        "backend": backend,
        "splats": len(splats),
        "frames": frames,
        "fps": 1e3 / stages["total"],
        "ms": {k: round(v, 2) for k, v in stages.items()},
        "ms_total_all_frames": [round(r["total"], 2) for r in runs],
        "intersections": first.timings.get("intersections"),
        "coverage_alpha_gt_0.5": float(np.mean(first.alpha > 0.5)),
        "_rgb": first.rgb,
    }


def main(argv: Sequence[str] | None = None) -> int:
    """Command-line entry: run the benchmark and write JSON (see the module docstring)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=360)
    parser.add_argument("--counts", type=int, nargs="+", default=[10_000, 100_000, 1_000_000])
    parser.add_argument("--frames", type=int, default=5, help="timed frames per case (median)")
    parser.add_argument("--backends", nargs="+", default=None, help="numba torch torch-cuda gsplat (default: all)")
    parser.add_argument("--torch-max-count", type=int, default=10_000, help="skip CPU torch above this many splats")
    parser.add_argument("--out", default="bench_splats.json", help="JSON output path")
    args = parser.parse_args(argv)

    import numba
    import torch

    cuda = bool(torch.cuda.is_available())
    backends = args.backends or [b for b in available_backends() if b != "reference"] + (["torch-cuda"] if cuda else [])
    camera = street_camera(args.width, args.height)
    report: dict[str, Any] = {
        "resolution": [args.width, args.height],
        "machine": {
            "cpus": os.cpu_count(),
            "numba_threads": numba.get_num_threads(),
            "platform": platform.platform(),
            "python": sys.version.split()[0],
            "cuda": cuda,
            "torch": torch.__version__,
        },
        "results": [],
    }
    for count in args.counts:
        splats = street_scene(count, camera)
        images: dict[str, npt.NDArray[np.float32]] = {}
        for backend in backends:
            if backend == "torch" and count > args.torch_max_count:
                continue
            if backend in ("gsplat", "torch-cuda") and not cuda:
                continue
            result = bench_one(backend, splats, camera, args.frames)
            images[backend] = result.pop("_rgb")
            if "numba" in images and backend != "numba":
                result["psnr_vs_numba_db"] = psnr(np.clip(images[backend], 0, 1), np.clip(images["numba"], 0, 1))
            report["results"].append(result)
            ms = result["ms"]
            print(f"{backend:>10} {count:>8} splats: {result['fps']:7.2f} FPS  "
                  + "  ".join(f"{k} {v:.1f} ms" for k, v in ms.items()))  # fmt: skip
    print(markdown_table(report["results"]))
    with open(args.out, "w") as fh:
        json.dump(report, fh, indent=2)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
