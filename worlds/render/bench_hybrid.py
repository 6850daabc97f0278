"""Benchmark of the hybrid renderer: FPS and milliseconds per stage, written as JSON.

Example::

    python -m drivetwin.worlds.render.bench_hybrid --width 640 --height 360 \\
        --splats 10000 100000 --assets 50 --frames 5 --out bench_hybrid.json

The world is a street canyon: the splat rasterizer benchmark's canyon as the splat
background (``bench_splats.street_scene``) and ``--assets`` mesh assets from the catalog
(cones, barriers, bins, cars) standing along the street in view, on a MuJoCo ground plane.
Each frame runs every stage the REPL's frames run: posing, mesh pass, splat projection,
binning and compositing against the mesh depth, blending, appearance. Stage times are
medians over the timed frames (one warm-up frame first, which also compiles Numba).
CUDA: the splat rasterizer's CUDA backend (gsplat) does not take a depth limit, which the
hybrid composition needs, so CUDA runs are reported as unavailable rather than faked.
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

__all__ = ["bench_world", "main"]

# Assets cycle through these catalog categories (mixed shapes and sizes, as in a scene).
ASSET_CATEGORIES = ("traffic_cone", "road_barrier", "trash_bin", "bollard", "passenger_car")
STREET_START_M, STREET_SPACING_M, STREET_HALF_WIDTH_M = 6.0, 2.5, 4.0
# Stages reported, mapped from the frame's timing keys.
STAGES = {
    "projection": "splat_project",
    "binning": "splat_bin",
    "compositing": "splat_composite",
    "mesh_pass": "mesh",
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


def bench_cpu(width: int, height: int, count: int, assets: int, frames: int,
              environment: Environment) -> dict[str, Any]:  # fmt: skip
    """Median stage times of ``frames`` hybrid frames with ``count`` splats on the CPU."""
    camera = street_camera(width, height)
    world = bench_world(assets)
    renderer = HybridRenderer(world, background=street_scene(count, camera), backend="numba")
    renderer.render(camera, environment)  # warm-up: GL context, Numba compilation
    timings = [renderer.render(camera, environment).timings for _ in range(frames)]
    renderer.close()
    stages = _median_stages(timings)
    return {
        "device": "cpu",
        "splats": count,
        "assets": assets,
        "frames": frames,
        "ms": stages,
        "fps": round(1000.0 / stages["total"], 2),
    }


def main(argv: Sequence[str] | None = None) -> int:
    """Run the benchmark and write its JSON; prints one line per configuration."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=360)
    parser.add_argument("--splats", type=int, nargs="+", default=[10_000, 100_000])
    parser.add_argument("--assets", type=int, default=50)
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--weather", default="clear", help="clear cloudy rain fog snow")
    parser.add_argument("--time-of-day", default="12:00")
    parser.add_argument("--out", default="bench_hybrid.json")
    args = parser.parse_args(argv)
    environment = Environment.model_validate(
        {"time_of_day": args.time_of_day,
         "weather": {"kind": args.weather, "intensity": 0.0 if args.weather == "clear" else 0.7}}
    )  # fmt: skip
    import numba

    results: list[dict[str, Any]] = []
    for count in args.splats:
        result = bench_cpu(args.width, args.height, count, args.assets, args.frames, environment)
        results.append(result)
        stages = " ".join(f"{k}={v:.1f}" for k, v in result["ms"].items())
        print(f"cpu splats={count} assets={args.assets}: {result['fps']:.2f} FPS | ms {stages}")
    try:
        import torch

        cuda = bool(torch.cuda.is_available())
    except ImportError:
        cuda = False
    if cuda:
        results.append({"device": "cuda", "skipped": "gsplat backend takes no depth_limit"})
        print("cuda: skipped (the splat rasterizer's CUDA backend takes no depth_limit)")
    report = {
        "benchmark": "hybrid",
        "width": args.width,
        "height": args.height,
        "environment": environment.model_dump(),
        "machine": {
            "cpu_count": os.cpu_count(),
            "numba_threads": numba.get_num_threads(),
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
