"""Benchmark: edit latency (add, move, remove) through a Session in worlds of N assets,
including the rules and the MuJoCo update, and physics steps per second; prints a growth
table and writes JSON.

    drivetwin bench edits --assets 200 1000 5000 --repeats 15 --out bench_edits.json
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import statistics
import time
from pathlib import Path
from typing import Any

import mujoco
from drivetwin.orchestrator.planning import Plan, PlanContext
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolCall
from drivetwin.tools.footprints import track
from drivetwin.worlds.bench_physics import PROP_MIX
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.catalog import category
from drivetwin.worlds.progress import progress_bar
from drivetwin.worlds.scene import MAX_ASSETS, AssetInstance, PhysicsProps, Pose, Scene, asset_order
from drivetwin.worlds.simulation import Simulation
from drivetwin.worlds.surface import building_at

__all__ = ["crowded_campus", "main", "measure"]

# The edits land near the fountain: the crowd keeps this far from it.
CLEAR_RADIUS_M = 12.0
# Crowd assets keep this far from the campus's own assets and the bounds.
CLEARANCE_M = 2.5
# The physics benchmark's prop mix without benches: the edits add benches, and a category
# holds at most its catalog limit (60 benches).
CROWD_MIX = tuple(mix for mix in PROP_MIX if mix[0] != "bench")
# Simulated seconds before physics is timed: props settle and fall asleep.
WARMUP_STEPS = 600
PHYSICS_STEPS = 1000
PHYSICS_RUNS = 3
# p95 of this many samples: the sample at this rank.
P95 = 0.95


class _Replay:
    """Plans exactly the calls it is given: the benchmark times edits, not language."""

    name = "replay"

    def __init__(self) -> None:
        self.calls: list[ToolCall] = []

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        return Plan(calls=self.calls, planner=self.name, verbatim=True)


def crowded_campus(n: int) -> Scene:
    """The campus with `n` extra props on a grid over its open ground (not in buildings, clear
    of its own assets, the bounds and the fountain, where the edits land): the physics
    benchmark's mix of resting free props (cones, barriers, bins...) and welded street
    furniture (bollards, benches, lights...)."""
    scene = build_campus()
    fountain = scene.landmark("fountain")
    assert fountain is not None
    fx, fy = fountain.position
    taken = [(a.pose.x, a.pose.y) for a in scene.all_assets()]
    b = scene.bounds
    pitch = math.sqrt((b.xmax - b.xmin) * (b.ymax - b.ymin) / max(n, 1))
    while True:
        spots: list[tuple[float, float]] = []
        y = b.ymin + CLEARANCE_M
        while y <= b.ymax - CLEARANCE_M and len(spots) < n:
            x = b.xmin + CLEARANCE_M
            while x <= b.xmax - CLEARANCE_M and len(spots) < n:
                near = math.hypot(x - fx, y - fy) < CLEAR_RADIUS_M or any(
                    math.hypot(x - ax, y - ay) < CLEARANCE_M for ax, ay in taken
                )
                if not near and not building_at(scene, x, y):
                    spots.append((x, y))
                x += pitch
            y += pitch
        if len(spots) >= n:
            break
        pitch *= 0.95  # buildings and clear zones took room: a finer grid
    extra = []
    for k, (x, y) in enumerate(spots):
        cat, dynamic = CROWD_MIX[k % len(CROWD_MIX)]
        extra.append(AssetInstance(id=f"crowd_{cat}_{k}", category=cat, pose=Pose(x=x, y=y),
                                   physics=PhysicsProps(mass=category(cat).mass, dynamic=dynamic)))  # fmt: skip
    # In canonical order, as every scene that was validated (loaded, built) holds its assets.
    return scene.model_copy(update={"assets": sorted([*scene.assets, *extra], key=asset_order)})


def _edits() -> list[tuple[str, str, ToolCall]]:
    """(kind, the prompt a user would type, the call it plans to) for one round of edits."""
    return [
        ("add", "add a bench at the fountain",
         ToolCall(tool="add_asset", args={"category": "bench", "location": {"relation": "at", "target": "fountain"}})),
        ("move", "move the bench forward 1 m", ToolCall(tool="move_asset", args={"asset": "bench_2", "forward": 1.0})),
        ("remove", "remove the bench", ToolCall(tool="remove_assets", args={"assets": ["bench_2"]})),
    ]  # fmt: skip


def _p95(values: list[float]) -> float:
    """The nearest-rank 95th percentile (the largest of up to 20 samples)."""
    return sorted(values)[math.ceil(P95 * len(values)) - 1]


class _Clocks:
    """Wall time and this process's CPU time since it was made: on a machine shared with
    other work, CPU time is what an idle machine's wall clock would show."""

    def __init__(self) -> None:
        self.wall, self.cpu = time.perf_counter(), time.process_time()

    def ms(self) -> tuple[float, float]:
        return (time.perf_counter() - self.wall) * 1000, (time.process_time() - self.cpu) * 1000


def _summary(samples: dict[str, list[float]]) -> dict[str, dict[str, float]]:
    return {"median": {k: statistics.median(v) for k, v in samples.items()},
            "p95": {k: _p95(v) for k, v in samples.items()}}  # fmt: skip


def measure(n: int, repeats: int) -> dict[str, Any]:
    """Edit milliseconds and physics rate in a campus crowded with `n` extra assets."""
    scene = crowded_campus(n)
    clocks = _Clocks()
    sim = Simulation(scene)
    load_wall, load_cpu = clocks.ms()
    # The placement rules index a world's footprints once (later edits patch the index):
    # timed here, like loading, so that the edit samples are what every later edit costs.
    clocks = _Clocks()
    track(scene)
    index_wall, index_cpu = clocks.ms()
    planner = _Replay()

    def apply(changed: Scene) -> None:
        sim.apply(changed)

    session = Session(scene, planner, on_change=apply)
    wall: dict[str, list[float]] = {"add": [], "move": [], "remove": []}
    cpu: dict[str, list[float]] = {"add": [], "move": [], "remove": []}
    mujoco_ms: list[float] = []
    recompiles = 0
    with progress_bar(f"edits, {n} assets", total=repeats * len(_edits()), unit="edits") as bar:
        for _ in range(repeats):
            for kind, prompt, call in _edits():
                planner.calls = [call]
                clocks = _Clocks()
                report = session.submit(prompt)
                wall_ms, cpu_ms = clocks.ms()
                wall[kind].append(wall_ms)
                cpu[kind].append(cpu_ms)
                if not report.ok:
                    raise SystemExit(f"{kind} failed at {n} assets: {report.error}")
                if sim.last_update is not None:
                    recompiles += sim.last_update.recompiled
                    mujoco_ms.append(sim.last_update.ms)
                bar.advance(note=kind)
    sim.step(WARMUP_STEPS)
    wall_rates, cpu_rates = [], []
    for _ in range(PHYSICS_RUNS):
        clocks = _Clocks()
        sim.step(PHYSICS_STEPS)
        wall_ms, cpu_ms = clocks.ms()
        wall_rates.append(PHYSICS_STEPS / wall_ms * 1000)
        cpu_rates.append(PHYSICS_STEPS / cpu_ms * 1000)
    model = sim.world.model
    return {
        "assets": len(session.scene.assets),
        "bodies": int(model.nbody),
        "dofs": int(model.nv),
        "load_s": {"wall": load_wall / 1000, "cpu": load_cpu / 1000},
        "footprint_index_ms": {"wall": index_wall, "cpu": index_cpu},
        "edit_ms": {"wall": _summary(wall), "cpu": _summary(cpu)},
        "recompiles": recompiles,
        "mujoco_update_ms_median": statistics.median(mujoco_ms),
        "edits": repeats * len(wall),
        "physics_steps_per_s": {"wall": statistics.median(wall_rates), "cpu": statistics.median(cpu_rates)},
        "realtime_factor": {"wall": statistics.median(wall_rates) * sim.dt, "cpu": statistics.median(cpu_rates) * sim.dt},
        "physics_dt_s": sim.dt,
        "awake_trees": int(sim.world.data.ntree_awake),
    }


def _table(rows: list[dict[str, Any]], clock: str) -> str:
    head = (f"{'assets':>7} {'bodies':>7} {'load s':>7} {'index ms':>8} | {'add ms':>13} {'move ms':>13}"
            f" {'remove ms':>13} | {'steps/s':>8} {'x real':>6} | {'MuJoCo ms':>9}")
    lines = [head, " " * 33 + "|   median  p95" * 3 + " |" + " " * 17 + "| (wall)", "-" * len(head)]
    for r in rows:
        med, p95 = r["edit_ms"][clock]["median"], r["edit_ms"][clock]["p95"]
        edits = " ".join(f"{med[k]:6.1f} {p95[k]:6.1f}" for k in ("add", "move", "remove"))
        lines.append(f"{r['assets']:7d} {r['bodies']:7d} {r['load_s'][clock]:7.1f}"
                     f" {r['footprint_index_ms'][clock]:8.0f} | {edits} |"
                     f" {r['physics_steps_per_s'][clock]:8.0f} {r['realtime_factor'][clock]:6.1f} |"
                     f" {r['mujoco_update_ms_median']:9.2f}")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """Command-line entry: measure each world size, print the growth table, write JSON."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--assets", type=int, nargs="+", default=[200], help="extra assets per world")
    parser.add_argument("--repeats", type=int, default=15, help="add/move/remove rounds per world")
    parser.add_argument("--out", type=Path, default=None, help="write the figures as JSON here")
    args = parser.parse_args(argv)
    if any(not 0 <= n <= MAX_ASSETS - 100 for n in args.assets) or args.repeats < 1:
        parser.error(f"--assets must be between 0 and {MAX_ASSETS - 100} and --repeats at least 1")
    rows = []
    for n in args.assets:
        rows.append(measure(n, args.repeats))
        print(f"measured {rows[-1]['assets']} assets", flush=True)
    load = os.getloadavg()
    print("edit = replayed plan (verbatim: no plan-vs-request review, a planning cost) + Worker + rules")
    print("       + transaction + commit (no journal) + MuJoCo update; index = the footprint index's first build;")
    print("MuJoCo ms = the MujocoWorld.update part of an edit (median over all edits);")
    print("physics = steps with behaviours and contact dormancy")
    print("CPU time of this process (what an idle machine's wall clock would show):")
    print(_table(rows, "cpu"))
    print(f"wall time (load average at the end {load[0]:.2f} on {os.cpu_count()} cores):")
    print(_table(rows, "wall"))
    result = {
        "rows": rows,
        "load_average": list(load),
        "cpus": os.cpu_count(),
        "mujoco": mujoco.__version__,
        "machine": platform.processor() or platform.machine(),
        "date": time.strftime("%Y-%m-%d"),
    }
    if args.out:
        args.out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
        print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
