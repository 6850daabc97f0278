"""Benchmark: planning latency per prompt for the rule planner, the retrieval planner, each
embedded model through the LLM hierarchy, and the hybrid default, over the paper's prompts; prints median and p95 and
writes JSON.

    python -m drivetwin.orchestrator.bench_planners --repeats 3 --out bench_planners.json

Each repeat replays the whole script in a fresh session on the campus, so that turns which
refer back ("around there") see the same conversation every time. Latency is the Session's
wall time for the prompt (plan + dry runs + apply); models are loaded before timing starts.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import time
from importlib.resources import files
from pathlib import Path
from typing import Any

from drivetwin.orchestrator.planning import Planner
from drivetwin.orchestrator.planning.registry import make_planner
from drivetwin.orchestrator.session import Session
from drivetwin.prompts.templates import prompt_version
from drivetwin.worlds.defaults import load_world
from drivetwin.worlds.progress import progress_bar

# Vague or misspelled requests the rules are unsure of: they exercise the hybrid's LLM path.
VAGUE_PROMPTS = (
    "put some pylons near the big building",
    "add trafic conez near the libary",
)
# name -> (planner name, options)
CONFIGS: dict[str, tuple[str, dict[str, Any]]] = {
    "rules": ("rules", {}),
    "retrieval": ("retrieval", {}),
    "hybrid/smollm2-135m": ("hybrid", {"backend": "embedded", "model": "smollm2-135m"}),
    "llm/smollm2-135m": ("llm", {"backend": "embedded", "model": "smollm2-135m"}),
    "llm/gemma3-270m": ("llm", {"backend": "embedded", "model": "gemma3-270m"}),
}
# The p95 of n samples is taken by the nearest-rank method; with few repeats it is the max.
P95 = 0.95


def paper_prompts() -> list[str]:
    """The paper's edits in order, from the demo script the CLI runs."""
    text = files("drivetwin.orchestrator").joinpath("demo_script.txt").read_text(encoding="utf-8")
    lines = [line.strip() for line in text.splitlines()]
    return [line for line in lines if line and not line.startswith("#")] + list(VAGUE_PROMPTS)


def percentile(values: list[float], q: float) -> float:
    """Nearest-rank percentile of `values` (q in 0..1)."""
    ordered = sorted(values)
    rank = max(1, min(len(ordered), round(q * len(ordered) + 0.5)))
    return ordered[rank - 1]


def run_config(planner: Planner, prompts: list[str], repeats: int) -> dict[str, Any]:
    """Latency and outcome of every prompt, over `repeats` fresh sessions."""
    Session(load_world("campus"), planner).submit(prompts[0])  # load models, caches
    # By position: the script repeats some prompts ("make it daytime") on purpose.
    samples: dict[int, list[float]] = {i: [] for i in range(len(prompts))}
    outcomes: dict[int, list[str]] = {i: [] for i in range(len(prompts))}
    with progress_bar(planner.name, total=repeats * len(prompts), unit="prompts") as bar:
        for _ in range(repeats):
            session = Session(load_world("campus"), planner)
            for p, prompt in enumerate(prompts):
                started = time.perf_counter()
                report = session.submit(prompt)
                samples[p].append(time.perf_counter() - started)
                path = report.plan.trace[0].input if report.plan and report.plan.trace else ""
                outcomes[p].append(("ok" if report.ok else f"failed: {report.error}")[:200] + f" {path}")
                bar.advance()
    rows = [
        {
            "prompt": prompts[p],
            "median_s": statistics.median(samples[p]),
            "p95_s": percentile(samples[p], P95),
            "ok": sum(o.startswith("ok") for o in outcomes[p]),
            "runs": len(samples[p]),
            "outcomes": outcomes[p],
        }
        for p in range(len(prompts))
    ]
    every = [s for p in samples for s in samples[p]]
    return {
        "median_s": statistics.median(every),
        "p95_s": percentile(every, P95),
        "ok": sum(r["ok"] for r in rows),
        "runs": len(every),
        "prompts": rows,
    }


def main(argv: list[str] | None = None) -> dict[str, Any]:
    """Run the benchmark, print a table, write JSON."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--configs", default=",".join(CONFIGS), help="comma-separated; " + ", ".join(CONFIGS))
    parser.add_argument("--out", type=Path, default=Path("bench_planners.json"))
    args = parser.parse_args(argv)
    prompts = paper_prompts()
    results: dict[str, Any] = {}
    for name in args.configs.split(","):
        planner_name, options = CONFIGS[name]
        try:
            planner = make_planner(planner_name, **options)
            results[name] = run_config(planner, prompts, args.repeats)
        except Exception as exc:  # one broken config must not lose the others' figures
            results[name] = {"error": f"{type(exc).__name__}: {exc}"}
        _print(name, results[name])
    report = {
        "machine": {"platform": platform.platform(), "cpus": os.cpu_count(), "load_avg": os.getloadavg()},
        "prompt_version": prompt_version(),
        "repeats": args.repeats,
        "results": results,
    }
    args.out.write_text(json.dumps(report, indent=2), encoding="utf-8")
    print(f"wrote {args.out}")
    return report


def _print(name: str, result: dict[str, Any]) -> None:
    if "error" in result:
        print(f"{name}: {result['error']}")
        return
    print(f"{name}: median {result['median_s']:.3f} s, p95 {result['p95_s']:.3f} s, {result['ok']}/{result['runs']} ok")
    for row in result["prompts"]:
        print(f"  {row['median_s']:8.3f} {row['p95_s']:8.3f}  {row['ok']}/{row['runs']}  {row['prompt']}")


if __name__ == "__main__":
    main()
