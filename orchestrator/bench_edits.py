"""Benchmark: edit latency (add, remove, move) through a Session in a world of N assets,
including the MuJoCo update, and physics steps per second; prints figures and writes JSON.

    python -m drivetwin.orchestrator.bench_edits --assets 200 --repeats 15 --out bench_edits.json
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import time
from pathlib import Path
from typing import Any

from drivetwin.orchestrator.planning import Plan, PlanContext
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolCall
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import AssetInstance, PhysicsProps, Pose, Scene
from drivetwin.worlds.simulation import Simulation


class _Replay:
    """Plans exactly the calls it is given: the benchmark times edits, not language."""

    name = "replay"

    def __init__(self) -> None:
        self.calls: list[ToolCall] = []

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        return Plan(calls=self.calls, planner=self.name)


def crowded_campus(n: int) -> Scene:
    """The campus with `n` extra cones and barriers on a grid in parking lot A."""
    scene = build_campus()
    extra = []
    for k in range(n):
        cat = "traffic_cone" if k % 2 else "road_barrier"
        x, y = -98.0 + (k % 12) * 2.4, 15.5 + (k // 12) * 1.4
        extra.append(AssetInstance(id=f"bench_{cat}_{k}", category=cat, pose=Pose(x=x, y=y),
                                   physics=PhysicsProps(mass=category(cat).mass)))
    return scene.model_copy(update={"assets": [*scene.assets, *extra]})


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--assets", type=int, default=200)
    parser.add_argument("--repeats", type=int, default=15)
    parser.add_argument("--out", type=Path, default=None)
    args = parser.parse_args()
    scene = crowded_campus(args.assets)
    sim = Simulation(scene)
    planner = _Replay()

    def apply(changed: Scene) -> None:
        sim.apply(changed)

    session = Session(scene, planner, on_change=apply)
    timings: dict[str, list[float]] = {"add": [], "move": [], "remove": []}
    for _ in range(args.repeats):
        for kind, call in (
            ("add", ToolCall(tool="add_asset", args={"category": "bench", "location": {"relation": "at", "target": "fountain"}})),
            ("move", ToolCall(tool="move_asset", args={"asset": "bench_2", "forward": 1.0})),
            ("remove", ToolCall(tool="remove_assets", args={"assets": ["bench_2"]})),
        ):
            planner.calls = [call]
            started = time.perf_counter()
            report = session.submit(kind)
            timings[kind].append((time.perf_counter() - started) * 1000)
            if not report.ok:
                raise SystemExit(f"{kind} failed: {report.error}")
    steps = 2000
    rates = []
    for _ in range(3):
        started = time.perf_counter()
        sim.step(steps)
        rates.append(steps / (time.perf_counter() - started))
    result: dict[str, Any] = {
        "assets": len(session.scene.assets),
        "edit_ms_median": {k: statistics.median(v) for k, v in timings.items()},
        "edit_ms_p95": {k: sorted(v)[int(0.95 * (len(v) - 1))] for k, v in timings.items()},
        "physics_steps_per_s_median": statistics.median(rates),
        "physics_dt_s": sim.dt,
        "machine": platform.processor() or platform.machine(),
        "date": time.strftime("%Y-%m-%d"),
    }
    print(f"world with {result['assets']} assets")
    for kind in timings:
        print(f"  {kind:6s} median {result['edit_ms_median'][kind]:7.1f} ms   p95 {result['edit_ms_p95'][kind]:7.1f} ms"
              "  (plan + check + transaction + journal-free commit + MuJoCo recompile)")
    print(f"  physics {result['physics_steps_per_s_median']:.0f} steps/s at dt {sim.dt} s")
    if args.out:
        args.out.write_text(json.dumps(result, indent=2), encoding="utf-8")
        print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
