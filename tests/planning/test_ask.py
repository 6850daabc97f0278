"""The session asks instead of guessing: nothing applied, one numbered question, a number
chooses a reading (journaled like any change), a new prompt drops the question; the REPL
shows it and `--script` counts it as a failed line."""

from __future__ import annotations

import subprocess
import sys

import pytest
from drivetwin.orchestrator.planning import Plan, PlanContext
from drivetwin.orchestrator.session import Session, SessionError
from drivetwin.tools.base import ToolCall

NEGATED = "honestly I'd rather not have the bus around any more"


class AddsABus:
    name = "adds-a-bus"

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        return Plan(calls=[ToolCall(tool="add_asset", args={"category": "bus", "count": 1})], planner=self.name)


@pytest.fixture
def asking(campus, registry, tmp_path):
    session = Session(campus, AddsABus(), registry, journal_path=tmp_path / "j.jsonl")
    assert session.submit("add a bus").ok  # the words ask for a bus: applied
    return session


def test_a_misread_plan_is_asked_about_and_nothing_is_applied(asking):
    buses = asking.scene.count("bus")
    report = asking.submit(NEGATED)
    assert report.question is not None and not report.ok
    assert asking.scene.count("bus") == buses and asking.memory.turns[-1].status == "asked"


def test_choosing_a_number_applies_that_reading_as_the_turns_transaction(asking):
    report = asking.submit(NEGATED)
    assert report.question is not None
    removal = next(n for n, r in enumerate(report.question.readings, 1) if r.calls[0].tool == "remove_assets")
    chosen = asking.choose(removal)
    assert chosen.ok and asking.scene.count("bus") == 0
    assert asking.history.done[-1].prompt == NEGATED


def test_a_new_prompt_drops_the_open_question(asking):
    asking.submit(NEGATED)
    asking.submit("make it rain")
    with pytest.raises(SessionError, match="no open question"):
        asking.choose(1)


def test_the_script_shows_numbered_readings_and_fails_on_an_asked_line(tmp_path):
    script = tmp_path / "asks.txt"
    script.write_text("are there benches by the library? add one bench there please\n", encoding="utf-8")
    code = (
        "import sys\n"
        "from drivetwin.orchestrator.planning import Plan\n"
        "from drivetwin.orchestrator.repl import ChatOptions, run_lines\n"
        "from drivetwin.orchestrator.session import Session\n"
        "from drivetwin.tools.base import ToolCall\n"
        "from drivetwin.worlds.campus import build_campus\n"
        "class P:\n"
        "    name = 'p'\n"
        "    def plan(self, prompt, context):\n"
        "        return Plan(calls=[ToolCall(tool='add_asset', args={'category': 'bus', 'count': 1})], planner='p')\n"
        "s = Session(build_campus(), P())\n"
        f"lines = open({str(script)!r}).read().splitlines() + ['1']\n"
        "sys.exit(run_lines(s, lines, ChatOptions(fail_fast=True)))\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "asked:" in done.stdout and "    1. " in done.stdout
