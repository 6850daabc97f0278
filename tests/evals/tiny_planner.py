"""A tiny test planner that emits fixed tool calls for a few key words (a real Planner, no LLM).

Spawned worker processes and subprocesses import it as `tiny_planner:make` (tests/evals is on
their sys.path), so the runner is tested across processes without any model.
"""

from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Any

from drivetwin.orchestrator.planning import Plan, PlanContext, PlanningError, TraceStep
from drivetwin.tools.base import ToolCall

RULES: list[tuple[str, list[ToolCall]]] = [
    ("rain", [ToolCall(tool="set_weather", args={"kind": "rain"})]),
    ("fog", [ToolCall(tool="set_weather", args={"kind": "fog"})]),
    ("night", [ToolCall(tool="set_time_of_day", args={"time": "night"})]),
    ("cone", [ToolCall(tool="add_asset", args={"category": "traffic_cone", "count": 3})]),
    ("bench", [ToolCall(tool="remove_assets", args={"assets": ["bench_1"]})]),
    ("where", [ToolCall(tool="find_landmarks", args={"query": "parking lot B"})]),
]


class TinyPlanner:
    """Matches the first key word found in the prompt; refuses prompts with none."""

    name = "tiny"

    def __init__(self, delay: float = 0.0, flip_every: int = 0) -> None:
        self.delay = delay
        # With flip_every = n, every n-th plan adds one cone more: an unrepeatable planner.
        self.flip_every = flip_every
        self.plans = 0

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        time.sleep(self.delay)
        self.plans += 1
        for word, calls in RULES:
            if word in prompt.lower():
                chosen = [c.model_copy(deep=True) for c in calls]
                if self.flip_every and word == "cone" and self.plans % self.flip_every == 0:
                    chosen[0].args["count"] = 4
                step = TraceStep(level="tiny", input=prompt, output=f"matched {word!r}", seconds=0.0)
                return Plan(calls=chosen, planner=self.name, prompt_version="tiny-1", tokens=7, trace=[step])
        raise PlanningError(f"the tiny planner knows none of the words in {prompt!r}")

    def model_facts(self) -> dict[str, Any]:
        return {"name": "tiny", "size_bytes": 1234, "parameters": 42}


def make(**options: Any) -> TinyPlanner:
    return TinyPlanner(**options)


def write_suite(path: Path, cases: list[dict[str, Any]]) -> Path:
    path.write_text("".join(json.dumps(c) + "\n" for c in cases), encoding="utf-8")
    return path


TINY_CASES: list[dict[str, Any]] = [
    {
        "id": "rain",
        "prompt": "make it rain",
        "task": "appearance",
        "grade": "direct",
        "checks": [{"kind": "environment", "weather": ["rain"]}],
    },
    {
        "id": "fog",
        "prompt": "make it foggy",
        "task": "appearance",
        "grade": "vague",
        "checks": [{"kind": "environment", "weather": ["fog"]}],
    },
    {
        "id": "snow",
        "prompt": "make it snow",
        "task": "appearance",
        "grade": "direct",
        "checks": [{"kind": "environment", "weather": ["snow"]}],
    },
    {
        "id": "cones",
        "prompt": "add some cones",
        "task": "addition",
        "grade": "direct",
        "checks": [{"kind": "count_delta", "category": "traffic_cone", "min": 3, "max": 3}],
    },
    {
        "id": "bench",
        "prompt": "remove the bench",
        "task": "removal",
        "grade": "direct",
        "checks": [{"kind": "exists", "assets": ["bench_1"], "present": False}],
    },
    {
        "id": "where",
        "prompt": "where is parking lot B?",
        "task": "search",
        "grade": "direct",
        "checks": [{"kind": "answer_contains", "any_of": ["38.5"]}],
    },
    {
        "id": "night_cones",
        "prompt": "cones at night",
        "task": "addition",
        "grade": "indirect",
        "checks": [{"kind": "environment", "night": True}],
    },
    {
        "id": "truck",
        "prompt": "add a truck",
        "task": "addition",
        "grade": "erroneous",
        "checks": [{"kind": "count_delta", "category": "truck", "min": 1}],
    },
]
