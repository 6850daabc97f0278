"""A bounded soak of the session and its journal: random edits, undos, redos, accepts, rejects,
clean resumes, crash resumes (no `end`, sometimes a torn last line) and full-disk refusals.

After every resume the scene and the undo/redo stacks must be exactly those the session had
before it: an edit reported done that is missing is a lost edit; a journal that no longer
replays is a corrupted journal. Both must be zero.

    python -m drivetwin.orchestrator.soak --trials 50 --steps 40 --seed 1 --out soak.json
"""

from __future__ import annotations

import argparse
import json
import random
import tempfile
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from drivetwin.orchestrator.journal import JournalError
from drivetwin.orchestrator.planning.base import Plan, PlanContext
from drivetwin.orchestrator.session import Session, SessionError
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.scene import Scene

WEATHERS = ("clear", "cloudy", "rain", "fog", "snow")
ACTIONS = ("edit", "edit", "edit", "undo", "redo", "accept", "reject", "resume", "crash", "torn", "save_load")


class RandomPlanner:
    """Plans the call it drew for the prompt (the planner is not under test): `draw` then `plan`."""

    name = "soak"

    def __init__(self, rng: random.Random) -> None:
        self.rng = rng
        self.next_call: ToolCall | None = None

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        assert self.next_call is not None
        return Plan(calls=[self.next_call], planner=self.name)

    def draw(self, scene: Scene) -> str:
        """Draw a random call on `scene`; the prompt that names it (the plan check compares the two)."""
        rng = self.rng
        kind = rng.choice(("weather", "time", "add", "move", "remove"))
        if kind == "weather":
            call = ToolCall(tool="set_weather", args={"kind": rng.choice(WEATHERS), "intensity": rng.random()})
        elif kind == "time":
            call = ToolCall(tool="set_time_of_day", args={"time": f"{rng.randrange(24):02d}:{rng.randrange(60):02d}"})
        elif kind == "add" or not scene.assets or not scene.roads.lanes:
            lane = rng.choice(scene.roads.lanes)  # somewhere along a lane: cones stand on roads
            (x0, y0), (x1, y1) = lane.centreline[0], lane.centreline[-1]
            t = rng.random()
            call = ToolCall(tool="add_asset", args={"category": "traffic_cone", "location": {
                "relation": "absolute", "x": round(x0 + t * (x1 - x0), 2), "y": round(y0 + t * (y1 - y0), 2)}})
        elif kind == "move":
            target = rng.choice([a.id for a in scene.all_assets()])
            call = ToolCall(tool="move_asset", args={"asset": target, "forward": rng.uniform(-3, 3),
                                                     "turn_deg": rng.uniform(-180, 180)})
        else:
            call = ToolCall(tool="remove_assets", args={"assets": [rng.choice(scene.assets).id]})
        self.next_call = call
        return str(call)


@dataclass
class SoakFigures:
    trials: int = 0
    steps: int = 0
    edits_applied: int = 0
    edits_refused: int = 0
    undos: int = 0
    redos: int = 0
    accepts: int = 0
    rejects: int = 0
    resumes: int = 0
    crash_resumes: int = 0
    torn_tails: int = 0
    lost_edits: int = 0
    corrupted_journals: int = 0
    seconds: float = 0.0
    failures: list[str] = field(default_factory=list)


def _state(session: Session) -> tuple[str, list[tuple[int, bool]], list[int]]:
    history = session.history
    return (session.scene.model_dump_json(), [(e.txn, e.accepted) for e in history.done],
            [e.txn for e in history.undone])


def run_trial(rng: random.Random, steps: int, folder: Path, registry: ToolRegistry, campus: Scene,
              figures: SoakFigures) -> None:
    """One session of `steps` random actions over its own journal, checked after each resume."""
    path = folder / "journal.jsonl"
    planner = RandomPlanner(rng)
    session = Session(campus, planner, registry, journal_path=path)
    for _ in range(steps):
        action = rng.choice(ACTIONS)
        figures.steps += 1
        try:
            if action == "edit":
                report = session.submit(planner.draw(session.scene))
                figures.edits_applied += report.ok
                figures.edits_refused += not report.ok
            elif action in ("undo", "redo", "accept", "reject"):
                getattr(session, action)()
                setattr(figures, f"{action}s", getattr(figures, f"{action}s") + 1)
            elif action == "save_load":
                saved = session.save(folder / "scene.json")
                session.load(saved)
            else:
                session = _resume(session, action, path, rng, registry, figures)
        except SessionError:
            pass  # nothing to undo, nothing pending...: a refusal is a fine outcome
    session.close()


def _resume(session: Session, action: str, path: Path, rng: random.Random, registry: ToolRegistry,
            figures: SoakFigures) -> Session:
    expected = _state(session)
    if action == "resume":
        session.close()
    else:  # a crash: the process dies without an end event, sometimes mid-write
        assert session.journal is not None
        session.journal.close()
        figures.crash_resumes += 1
        if action == "torn":
            figures.torn_tails += 1
            with path.open("a", encoding="utf-8") as handle:
                handle.write('{"event":"commit","txn":' + str(rng.randrange(1, 99)) + ',"pro')
    figures.resumes += 1
    try:
        resumed = Session.resume(path, session.planner, registry)
    except JournalError as exc:
        figures.corrupted_journals += 1
        figures.failures.append(f"resume failed: {exc}")
        return Session(session.scene, session.planner, registry, journal_path=path)
    if _state(resumed) != expected:
        figures.lost_edits += 1
        figures.failures.append(f"resume after {action} differs from the session before it")
    return resumed


def soak(trials: int, steps: int, seed: int) -> SoakFigures:
    """Run `trials` random sessions of `steps` actions each; the figures say what held."""
    figures = SoakFigures()
    registry = ToolRegistry.default(plugins=False)
    campus = build_campus()
    started = time.perf_counter()
    for trial in range(trials):
        rng = random.Random(seed * 100_003 + trial)
        with tempfile.TemporaryDirectory(prefix="drivetwin-soak-") as folder:
            run_trial(rng, steps, Path(folder), registry, campus, figures)
        figures.trials += 1
    figures.seconds = round(time.perf_counter() - started, 2)
    return figures


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--trials", type=int, default=20)
    parser.add_argument("--steps", type=int, default=40, help="actions per trial")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", type=Path, default=None, help="write the figures as JSON here")
    args = parser.parse_args(argv)
    figures = soak(args.trials, args.steps, args.seed)
    report: dict[str, Any] = {"seed": args.seed, "steps_per_trial": args.steps, **asdict(figures)}
    for key, value in report.items():
        if key != "failures":
            print(f"{key:20s} {value}")
    for failure in figures.failures[:10]:
        print(f"FAIL {failure}")
    if args.out is not None:
        args.out.write_text(json.dumps(report, indent=2), encoding="utf-8")
        print(f"wrote {args.out}")
    return 0 if not figures.lost_edits and not figures.corrupted_journals else 1


if __name__ == "__main__":
    raise SystemExit(main())
