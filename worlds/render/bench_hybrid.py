"""Benchmark of the hybrid renderer: FPS and milliseconds per stage, written as JSON.

Example::

    python -m drivetwin.worlds.render.bench_hybrid --width 640 --height 360 \\
        --splats 10000 100000 1000000 --assets 50 --frames 5 --out bench_hybrid.json

It prints a Markdown table (milliseconds per stage and FPS, one row per splat count) and
writes the same figures, with the machine's description, as JSON.

The world is a street canyon: the splat rasterizer benchmark's canyon as the splat
background (``bench_splats.street_scene``) and ``--assets`` mesh assets from the catalog
(cones, barriers, bins, cars) standing along the street in view, on a MuJoCo ground plane.
Each frame runs every stage the REPL's frames run: posing, mesh pass, splat projection,
binning and compositing against the mesh depth, blending, appearance. The mesh pass runs
on its own thread while the splats are projected, so "mesh" overlaps "projection" and the
stages add up to more than "total" (the frame's wall time); "mesh wait" is the part of the
mesh pass that projection did not hide. Stage times are medians over the timed frames (one
warm-up frame first, which also compiles Numba); FPS is 1000 / median total.
CUDA: where torch sees a CUDA device and gsplat is installed, the same frames are drawn with
``--cuda-backend gsplat`` (a per-splat depth limit, see ``cull_behind_depth_limit``) and
reported beside the CPU rows; elsewhere CUDA rows say "not measured".
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

from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.scene import AssetInstance, Bounds, Environment, PhysicsProps, Pose, Scene

from .bench_splats import street_camera, street_scene
from .hybrid import HybridRenderer
from .rasterize import BackendName, available_backends

__all__ = ["bench_frames", "bench_world", "main", "markdown_table"]

# Assets cycle through these catalog categories (mixed shapes and sizes, as in a scene).
ASSET_CATEGORIES = ("traffic_cone", "road_barrier", "trash_bin", "bollard", "passenger_car")
STREET_START_M, STREET_SPACING_M, STREET_HALF_WIDTH_M = 6.0, 2.5, 4.0
# Stages reported, mapped from the frame's timing keys.
STAGES = {
    "pose": "pose",
    "mesh_pass": "mesh",
    "projection": "splat_project",
    "mesh_wait": "mesh_wait",
    "binning": "splat_bin",
    "compositing": "splat_composite",
    "blend": "blend",
    "appearance": "appearance",
    "total": "total",
}


def bench_world(assets: int) -> MujocoWorld:
    """A flat world with ``assets`` static catalog assets along the benchmark street."""
    placed = []
    for i in range(assets):
        name = ASSET_CATEGORIES[i % len(ASSET_CATEGORIES)]
        x = STREET_START_M + STREET_SPACING_M * (i // 3)
        y = (i % 3 - 1) * STREET_HALF_WIDTH_M
        placed.append(AssetInstance(id=f"{name}_{i}", category=name, pose=Pose(x=x, y=y),
                                    physics=PhysicsProps(mass=category(name).mass,
                                                         dynamic=False)))  # fmt: skip
    ego = AssetInstance(id="ego", category="ego_vehicle", pose=Pose(x=-10.0, y=0.0),
                        physics=PhysicsProps(mass=category("ego_vehicle").mass))  # fmt: skip
    scene = Scene(name="bench", bounds=Bounds(xmin=-20, xmax=200, ymin=-40, ymax=40), ego=ego,
                  assets=placed)  # fmt: skip
    return MujocoWorld.from_scene(scene)


def _median_stages(timings: list[dict[str, float]]) -> dict[str, float]:
    stages = {}
    for stage, key in STAGES.items():
        values = [t[key] for t in timings if key in t]
        if values:
            stages[stage] = round(statistics.median(values), 2)
    return stages


def bench_frames(width: int, height: int, count: int, assets: int, frames: int, environment: Environment,
                 backend: BackendName = "numba") -> dict[str, Any]:  # fmt: skip
    """Median stage times of ``frames`` hybrid frames with ``count`` splats."""
    camera = street_camera(width, height)
    world = bench_world(assets)
    renderer = HybridRenderer(world, background=street_scene(count, camera), backend=backend)
    try:
        first = renderer.render(camera, environment)  # warm-up: GL context, Numba compilation
        timings = [renderer.render(camera, environment).timings for _ in range(frames)]
    finally:
        renderer.close()
    stages = _median_stages(timings)
    return {
        "device": "cpu" if backend == "numba" else "cuda",
        "backend": backend,
        "splats": count,
        "assets": assets,
        "frames": frames,
        "ms": stages,
        "ms_total_all_frames": [round(t["total"], 2) for t in timings],
        "intersections": first.timings.get("splat_intersections"),
        "fps": round(1000.0 / stages["total"], 2),
    }


def markdown_table(results: list[dict[str, Any]]) -> str:
    """The results as a Markdown table: one row per run, ms per stage, then FPS."""
    columns = list(STAGES)
    lines = ["| device | splats | " + " | ".join(c.replace("_", " ") + " ms" for c in columns) + " | FPS |",
             "|" + " --- |" * (len(columns) + 3)]  # fmt: skip
    for r in results:
        if "ms" not in r:
            lines.append(f"| {r['device']} | {r.get('splats', 0):,} | " + " | ".join("" for _ in columns)
                         + f" | {r.get('skipped', 'not measured')} |")  # fmt: skip
            continue
        cells = [f"{r['ms'][c]:.1f}" if c in r["ms"] else "" for c in columns]
        lines.append(f"| {r['device']} | {r['splats']:,} | " + " | ".join(cells) + f" | {r['fps']:.2f} |")
    return "\n".join(lines)


def _cuda_ready() -> bool:
    try:
        import torch
    except ImportError:
        return False
    return bool(torch.cuda.is_available()) and "gsplat" in available_backends()


def main(argv: Sequence[str] | None = None) -> int:
    """Run the benchmark, print its table and write its JSON."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=360)
    parser.add_argument("--splats", type=int, nargs="+", default=[10_000, 100_000, 1_000_000])
    parser.add_argument("--assets", type=int, default=50)
    parser.add_argument("--frames", type=int, default=5, help="timed frames per row (median)")
    parser.add_argument("--weather", default="clear", help="clear cloudy rain fog snow")
    parser.add_argument("--time-of-day", default="12:00")
    parser.add_argument("--out", default="bench_hybrid.json")
    args = parser.parse_args(argv)
    environment = Environment.model_validate(
        {"time_of_day": args.time_of_day,
         "weather": {"kind": args.weather, "intensity": 0.0 if args.weather == "clear" else 0.7}}
    )  # fmt: skip
    from ._numba_raster import kernel_threads

    results: list[dict[str, Any]] = []
    cuda = _cuda_ready()
    for count in args.splats:
        results.append(bench_frames(args.width, args.height, count, args.assets, args.frames, environment))
        if cuda:
            results.append(bench_frames(args.width, args.height, count, args.assets, args.frames, environment,
                                        backend="gsplat"))  # fmt: skip
        else:
            results.append({"device": "cuda", "splats": count, "skipped": "not measured (no CUDA device or gsplat)"})
    print(f"hybrid frames {args.width}x{args.height}, {args.assets} mesh assets, {args.frames} frames per row "
          f"(medians), {kernel_threads().threads} kernel threads")  # fmt: skip
    print(markdown_table(results))
    report = {
        "benchmark": "hybrid",
        "width": args.width,
        "height": args.height,
        "environment": environment.model_dump(),
        "machine": {
            "cpu_count": os.cpu_count(),
            "kernel_threads": kernel_threads().threads,
            "load_average": list(os.getloadavg()),
            "platform": platform.platform(),
            "python": sys.version.split()[0],
            "mujoco_gl": os.environ.get("MUJOCO_GL", ""),
        },
        "results": results,
    }
    with open(args.out, "w", encoding="utf-8") as fh:
        json.dump(report, fh, indent=2)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
