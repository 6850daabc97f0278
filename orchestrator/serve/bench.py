"""Benchmark: how many pose updates per second `drivetwin serve` can send with N assets.

    drivetwin bench serve --assets 200 --seconds 5 --out bench_serve.json

A world of N assets (bench_physics's: driving vehicles, walkers, props) runs in the live
simulation in the background, as under `serve`; a viser server gets the world through
SceneSync, and a websocket client connected to it receives every message, so serialising
and sending are measured too. Two runs, each as fast as it goes for the given seconds:
`live` reads the simulated poses (only what moved is sent) and `all_moving` moves every
asset every tick (the worst case). Prints the figures and writes them as JSON.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import viser
from drivetwin.orchestrator.serve.scene_sync import PlanarPose, SceneSync
from drivetwin.worlds.bench_physics import benchmark_scene
from drivetwin.worlds.simulation import Simulation

__all__ = ["main", "measure"]

P95 = 0.95
# The floor: the browser view must keep up at this many updates a second.
REQUIRED_UPDATES_PER_S = 20.0
SETTLE_S = 1.0  # let the client receive the initial scene before timing


class _Receiver:
    """A websocket client of the viser server that counts what it receives."""

    def __init__(self, port: int) -> None:
        from websockets.sync.client import connect

        self.connection = connect(f"ws://127.0.0.1:{port}", subprotocols=[f"viser-v{viser.__version__}"],  # type: ignore[list-item]
                                  max_size=None)  # fmt: skip
        self.messages = 0
        self.bytes = 0
        self._thread = threading.Thread(target=self._drain, daemon=True)
        self._thread.start()

    def _drain(self) -> None:
        try:
            for message in self.connection:
                self.messages += 1
                self.bytes += len(message)
        except Exception:  # closed at the end of the benchmark
            return

    def close(self) -> None:
        self.connection.close()
        self._thread.join(timeout=5)


def _timed(tick: Callable[[int], int], seconds: float, receiver: _Receiver) -> dict[str, Any]:
    times: list[float] = []
    batches = 0
    bytes_before = receiver.bytes
    start = time.perf_counter()
    while time.perf_counter() - start < seconds:
        t0 = time.perf_counter()
        batches += tick(len(times))
        times.append(time.perf_counter() - t0)
    elapsed = time.perf_counter() - start
    time.sleep(0.2)  # the last messages in flight
    times.sort()
    return {
        "updates_per_s": len(times) / elapsed,
        "tick_ms_median": 1e3 * statistics.median(times),
        "tick_ms_p95": 1e3 * times[min(len(times) - 1, int(P95 * len(times)))],
        "batches_per_tick": batches / len(times),
        "received_mb_per_s": (receiver.bytes - bytes_before) / elapsed / 1e6,
        "ticks": len(times),
    }


def measure(n_assets: int, seconds: float) -> dict[str, Any]:
    """Both runs for a world of `n_assets` assets; the figures as a dict."""
    scene = benchmark_scene(n_assets)
    sim = Simulation(scene)
    sim.start(realtime=True)
    server = viser.ViserServer(host="127.0.0.1", port=0, verbose=False)
    try:
        sync = SceneSync(server.scene, server.atomic)
        t0 = time.perf_counter()
        sync.show(scene)
        show_ms = 1e3 * (time.perf_counter() - t0)
        receiver = _Receiver(server.get_port())
        time.sleep(SETTLE_S)

        def live(_: int) -> int:
            with sim.lock:
                world = sim.world
                poses = {a.id: world.planar_pose(a.id) for a in world.scene.all_assets()}
            return sync.move(poses)

        base = {a.id: (a.pose.x, a.pose.y, a.pose.z, a.pose.yaw) for a in scene.all_assets()}

        def all_moving(i: int) -> int:
            step = 0.01 * (i + 1)
            poses: dict[str, PlanarPose] = {k: (x + step, y, z, yaw + step) for k, (x, y, z, yaw) in base.items()}
            return sync.move(poses)

        results = {"live": _timed(live, seconds, receiver), "all_moving": _timed(all_moving, seconds, receiver)}
        receiver.close()
    finally:
        server.stop()
        sim.stop()
    return {"assets": n_assets, "batches": len(sync._batches), "show_ms": show_ms, **results}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="drivetwin bench serve", description=__doc__.split("\n\n")[0])
    parser.add_argument("--assets", type=int, nargs="+", default=[200], help="world sizes to measure")
    parser.add_argument("--seconds", type=float, default=5.0, help="seconds per run")
    parser.add_argument("--out", type=Path, default=None, help="JSON file for the figures")
    args = parser.parse_args(argv)
    if any(n < 1 for n in args.assets) or args.seconds <= 0:
        parser.error("--assets must be at least 1 and --seconds positive")
    rows = []
    print(f"{'assets':>6} {'run':>10} {'updates/s':>10} {'tick ms':>8} {'p95 ms':>7} {'batches':>8} {'MB/s':>6}")
    for n in args.assets:
        row = measure(n, args.seconds)
        rows.append(row)
        for run in ("live", "all_moving"):
            r = row[run]
            print(f"{n:>6} {run:>10} {r['updates_per_s']:>10.0f} {r['tick_ms_median']:>8.2f} {r['tick_ms_p95']:>7.2f} "
                  f"{r['batches_per_tick']:>8.1f} {r['received_mb_per_s']:>6.2f}")
    worst = min(r[run]["updates_per_s"] for r in rows for run in ("live", "all_moving"))
    verdict = "meets" if worst >= REQUIRED_UPDATES_PER_S else "misses"
    print(f"slowest: {worst:.0f} updates/s; {verdict} the {REQUIRED_UPDATES_PER_S:.0f}/s floor")
    report = {"benchmark": "serve", "machine": platform.machine(), "cpus": os.cpu_count(),
              "python": platform.python_version(), "viser": viser.__version__,
              "required_updates_per_s": REQUIRED_UPDATES_PER_S, "results": rows}  # fmt: skip
    if args.out:
        args.out.write_text(json.dumps(report, indent=2), encoding="utf-8")
        print(f"wrote {args.out}")
    return 0
