"""Benchmark of the physics: steps per second of a many-asset world and the cost of edits.

    python -m drivetwin.worlds.bench_physics --assets 200 --out bench_physics.json

Prints physics steps per second (median of several runs, behaviours included, and raw
mj_step) for a flat world with the given number of assets (mostly props, a few driving
and parked vehicles, some walking pedestrians), and the milliseconds MujocoWorld.update
takes to add, remove and move one asset in it (moving a welded or walking asset needs no
recompile, moving a free one does); writes the same figures as JSON.
"""

from __future__ import annotations

import argparse
import json
import math
import platform
import statistics
import time
from pathlib import Path
from typing import Any

import mujoco
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import (
    MAX_ASSETS,
    AssetInstance,
    Behaviour,
    Bounds,
    CrossRoad,
    DriveLane,
    FollowPath,
    Lane,
    Parked,
    PhysicsProps,
    Pose,
    RoadNetwork,
    Scene,
)
from drivetwin.worlds.simulation import Simulation

__all__ = ["PROP_MIX", "benchmark", "benchmark_scene", "main"]

# Share of the assets that are vehicles and walkers; the rest are props.
DRIVING_VEHICLES = 6
PARKED_VEHICLES = 4
WALKERS = 10
# Props: (category, dynamic) in rotation; dynamic ones are free bodies resting on the ground.
PROP_MIX = (
    ("traffic_cone", True),
    ("road_barrier", True),
    ("trash_bin", True),
    ("bollard", False),
    ("bench", False),
    ("construction_sign", True),
    ("street_light", False),
    ("cement_rubble", True),
    ("tree", False),
    ("fire_hydrant", False),
)
# Props stand on a grid this far apart, off the roads (|y| > ROAD_HALF_WIDTH_M).
PROP_PITCH_M = 4.0
ROAD_HALF_WIDTH_M = 12.0
HALF_SIZE_M = 150.0
# Three simulated seconds: props settle (and fall asleep) and vehicles reach their speed.
WARMUP_STEPS = 600


def _asset(
    asset_id: str,
    name: str,
    x: float,
    y: float,
    yaw: float = 0.0,
    dynamic: bool = True,
    behaviour: Behaviour | None = None,
) -> AssetInstance:
    return AssetInstance(
        id=asset_id,
        category=name,
        pose=Pose(x=x, y=y, yaw=yaw),
        physics=PhysicsProps(mass=category(name).mass, dynamic=dynamic),
        behaviour=behaviour or Parked(),
    )


def benchmark_scene(n_assets: int) -> Scene:
    """A flat 300 m square world with two roads and `n_assets` assets (ego not counted)."""
    lanes = [
        Lane(id="east", road="main", centreline=[(-140.0, -1.75), (140.0, -1.75)]),
        Lane(id="west", road="main", centreline=[(140.0, 1.75), (-140.0, 1.75)]),
    ]
    assets: list[AssetInstance] = []
    vehicles = min(n_assets, DRIVING_VEHICLES + PARKED_VEHICLES)
    for k in range(vehicles):
        driving = k < DRIVING_VEHICLES
        lane = lanes[k % 2]
        direction = 1.0 if lane.id == "east" else -1.0
        x = direction * (-120.0 + 40.0 * (k // 2))
        y = lane.centreline[0][1] if driving else 8.0 + 3.0 * (k % 2)
        behaviour = DriveLane(lane=lane.id, speed=6.0) if driving else Parked()
        yaw = 0.0 if direction > 0 else math.pi
        assets.append(_asset(f"car_{k}", "passenger_car", x, y, yaw, behaviour=behaviour))
    walkers = min(n_assets - len(assets), WALKERS)
    for k in range(walkers):
        x = -90.0 + 20.0 * k
        walk: Behaviour = (
            CrossRoad(start=(x, -10.0), end=(x, 10.0), start_time=0.5 * k)
            if k % 2 == 0
            else FollowPath(waypoints=[(x, 14.0), (x + 6.0, 14.0), (x + 6.0, 20.0)], loop=True)
        )
        assets.append(_asset(f"walker_{k}", "pedestrian", x, -10.0, behaviour=walk))
    columns = int(2 * (HALF_SIZE_M - 10.0) / PROP_PITCH_M)
    for k in range(n_assets - len(assets)):
        name, dynamic = PROP_MIX[k % len(PROP_MIX)]
        row, column = divmod(k, columns)
        x = -HALF_SIZE_M + 10.0 + column * PROP_PITCH_M
        side = 1.0 if row % 2 == 0 else -1.0
        y = side * (ROAD_HALF_WIDTH_M + 10.0 + PROP_PITCH_M * (row // 2) * 2)
        assets.append(_asset(f"prop_{k}", name, x, y, dynamic=dynamic))
    ego = _asset("ego", "ego_vehicle", -60.0, -1.75, behaviour=DriveLane(lane="east", speed=5.0))
    return Scene(
        name="bench",
        bounds=Bounds(xmin=-HALF_SIZE_M, xmax=HALF_SIZE_M, ymin=-HALF_SIZE_M, ymax=HALF_SIZE_M),
        roads=RoadNetwork(lanes=lanes),
        ego=ego,
        assets=assets,
    )


def _timed(action: Any) -> float:
    started = time.perf_counter()
    action()
    return time.perf_counter() - started


def benchmark(n_assets: int, steps: int = 1000, runs: int = 5, edits: int = 10) -> dict[str, Any]:
    """Measure steps per second and update milliseconds; returns the figures as a dict."""
    scene = benchmark_scene(n_assets)
    build_s = _timed(lambda: Simulation(scene))
    sim = Simulation(scene)
    sim.step(WARMUP_STEPS)
    loop_rates = [steps / _timed(lambda: sim.step(steps)) for _ in range(runs)]
    model, data = sim.world.model, sim.world.data
    raw_rates = []
    for _ in range(runs):
        started = time.perf_counter()
        for _ in range(steps):
            mujoco.mj_step(model, data)
        raw_rates.append(steps / (time.perf_counter() - started))
    world = sim.world
    extra = _asset("bench_extra_cone", "traffic_cone", 0.0, 30.0)
    add_ms: list[float] = []
    remove_ms: list[float] = []
    move_ms: list[float] = []
    move_free_ms: list[float] = []
    # prop_0 is a (dynamic) cone, prop_3 a (welded) bollard: see PROP_MIX.
    for k in range(edits):
        grown = scene.model_copy(update={"assets": [*scene.assets, extra]})
        add_ms.append(world.update(grown).ms)
        remove_ms.append(world.update(scene).ms)
        for asset_id, timings in (("prop_3", move_ms), ("prop_0", move_free_ms)):
            moved = scene.model_copy(deep=True)
            target = moved.asset(asset_id)
            assert target is not None
            target.pose = Pose(x=target.pose.x, y=target.pose.y + 0.5 * (1 + k % 2), yaw=0.1 * k)
            timings.append(world.update(moved).ms)
            scene = moved
    return {
        "assets": n_assets,
        "bodies": int(model.nbody),
        "geoms": int(model.ngeom),
        "dofs": int(model.nv),
        "timestep_s": float(model.opt.timestep),
        "build_ms": build_s * 1000.0,
        "steps_per_second": statistics.median(loop_rates),
        "steps_per_second_runs": loop_rates,
        "raw_mj_step_per_second": statistics.median(raw_rates),
        "realtime_factor": statistics.median(loop_rates) * float(model.opt.timestep),
        "update_add_ms": statistics.median(add_ms),
        "update_remove_ms": statistics.median(remove_ms),
        "update_move_ms": statistics.median(move_ms),
        "update_move_dynamic_ms": statistics.median(move_free_ms),
        "mujoco": mujoco.__version__,
        "python": platform.python_version(),
        "machine": platform.machine(),
    }


def main(argv: list[str] | None = None) -> int:
    """Command-line entry: run the benchmark, print a summary, write JSON."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--assets", type=int, default=200, help="assets besides the ego")
    parser.add_argument("--steps", type=int, default=1000, help="steps per timed run")
    parser.add_argument("--runs", type=int, default=5, help="timed runs (median reported)")
    parser.add_argument("--out", type=Path, default=None, help="write the figures as JSON here")
    args = parser.parse_args(argv)
    if not 0 <= args.assets <= MAX_ASSETS:
        parser.error(f"--assets must be between 0 and {MAX_ASSETS} (a scene's limit)")
    result = benchmark(args.assets, steps=args.steps, runs=args.runs)
    print(
        f"{result['assets']} assets ({result['bodies']} bodies, {result['dofs']} dofs): "
        f"{result['steps_per_second']:.0f} physics steps/s with behaviours "
        f"({result['realtime_factor']:.1f}x real time at dt={result['timestep_s']} s), "
        f"raw mj_step {result['raw_mj_step_per_second']:.0f}/s"
    )
    print(
        f"MujocoWorld.update: add {result['update_add_ms']:.2f} ms, "
        f"remove {result['update_remove_ms']:.2f} ms, move {result['update_move_ms']:.2f} ms "
        f"(a welded prop; a free one {result['update_move_dynamic_ms']:.2f} ms)"
    )
    if args.out is not None:
        args.out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
        print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
