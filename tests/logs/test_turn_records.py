"""Which model made an edit: the journal's facts per turn, the request log, and `drivetwin logs`."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner
from drivetwin.orchestrator import logs
from drivetwin.orchestrator.backends import Backend, BackendInfo, BackendStatus, Completion, CompletionRequest
from drivetwin.orchestrator.cli import main
from drivetwin.orchestrator.journal import Journal
from drivetwin.orchestrator.planning import Plan, PlanContext, TraceStep
from drivetwin.orchestrator.planning.registry import make_planner
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolCall
from drivetwin.worlds.scene import Scene

WEATHER_SCHEMA = {"type": "object", "properties": {"kind": {"enum": ["rain", "fog"]}}, "required": ["kind"]}


class WeatherModel(Backend):
    """A model that reads 'fog' or else 'rain' in the last message (the Backend.chat path is under test)."""

    name = "weather-model"
    default_model = "tiny"

    def complete(self, request: CompletionRequest) -> Completion:
        kind = "fog" if "fog" in request.messages[-1]["content"] else "rain"
        return Completion(json.dumps({"kind": kind}), "stop", 17, 5)

    def describe(self) -> BackendInfo:
        return BackendInfo(self.name, self.model)

    @classmethod
    def statuses(cls, **options: object) -> list[BackendStatus]:
        return [BackendStatus(cls.name, "tiny", True)]


class ModelPlanner:
    """Asks its model for the weather and sets it: one backend call per prompt."""

    name = "model-weather"

    def __init__(self, **options: object) -> None:  # a planner factory is given backend, model...
        self.backend = WeatherModel()

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        answer = self.backend.chat([{"role": "user", "content": prompt}], schema=WEATHER_SCHEMA)
        return Plan(calls=[ToolCall(tool="set_weather", args={"kind": answer.data["kind"]})], planner=self.name,
                    prompt_version="weather-1", tokens=answer.prompt_tokens + answer.completion_tokens,
                    trace=[TraceStep(level="requirements", input=prompt, output=answer.text)])


@pytest.fixture
def state(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A state folder the commands read (DRIVETWIN_STATE), with this process's request log open in it."""
    monkeypatch.setenv("DRIVETWIN_STATE", str(tmp_path))
    logs.open_log(tmp_path, command="chat", world="campus")
    yield tmp_path
    logs.close_log()


def _session(campus: Scene, state: Path, planner: object) -> Session:
    return Session(campus, planner, journal_path=state / "journals" / "session-1.jsonl")  # type: ignore[arg-type]


def test_a_journaled_change_records_the_planner_model_and_prompt_version(campus: Scene, state: Path) -> None:
    session = _session(campus, state, ModelPlanner())
    assert session.submit("make it foggy").ok
    session.close()
    [entry] = Journal(state / "journals" / "session-1.jsonl").replay().history.done
    facts = entry.facts
    assert facts is not None and facts.planner == "model-weather" and facts.model == "weather-model/tiny"
    assert facts.prompt_version == "weather-1" and facts.tokens == 22
    assert facts.trace[0]["output"] == '{"kind": "fog"}'
    assert 0 < facts.plan_s <= facts.turn_s
    assert facts.log is not None and facts.log.startswith(logs.active_log().session)  # type: ignore[union-attr]


def test_a_failed_turn_is_journaled_with_its_planner_too(campus: Scene, state: Path) -> None:
    session = _session(campus, state, make_planner("rules"))
    assert not session.submit("paint the sky with polka dots").ok
    session.close()
    lines = [json.loads(line) for line in (state / "journals" / "session-1.jsonl").read_text().splitlines()]
    turn = next(line for line in lines if line["event"] == "turn")
    assert turn["turn"]["status"] == "failed" and turn["facts"]["planner"] == "rules" and turn["facts"]["model"] is None


def test_a_journal_written_before_the_facts_still_replays(campus: Scene, tmp_path: Path) -> None:
    path = tmp_path / "old.jsonl"
    session = Session(campus, make_planner("rules"), journal_path=path)
    assert session.submit("make it rain").ok
    session.close()
    lines = [json.loads(line) for line in path.read_text().splitlines()]
    old = [{k: v for k, v in line.items() if k != "facts"} for line in lines]
    path.write_text("".join(json.dumps(line) + "\n" for line in old))
    [entry] = Journal(path).replay().history.done
    assert entry.prompt == "make it rain" and entry.facts is None


def test_the_log_holds_each_turn_with_its_backend_requests_and_answers(campus: Scene, state: Path) -> None:
    session = _session(campus, state, ModelPlanner())
    session.submit("make it foggy")
    session.close()
    log = logs.active_log()
    assert log is not None
    lines = logs.read_session(log.folder, log.session)
    [exchange] = [line for line in lines if line["kind"] == "exchange"]
    [turn] = [line for line in lines if line["kind"] == "turn"]
    assert exchange["request"]["messages"] == [{"role": "user", "content": "make it foggy"}]
    assert exchange["answer"]["text"] == '{"kind": "fog"}' and exchange["turn"] == turn["turn"]
    assert turn["exchanges"] == [exchange["id"]] and turn["calls"] == [{"tool": "set_weather", "args": {"kind": "fog"}}]
    assert turn["model"] == "weather-model/tiny" and turn["txn"] == 1 and turn["ok"]


def test_logs_edits_shows_the_model_and_prompt_behind_every_accepted_edit(campus: Scene, state: Path) -> None:
    session = _session(campus, state, ModelPlanner())
    session.submit("make it foggy")
    session.accept()
    session.close()
    result = CliRunner().invoke(main, ["logs", "edits", "--json"])
    assert result.exit_code == 0, result.output
    [row] = json.loads(result.stdout)
    assert row["accepted"] and row["prompt"] == "make it foggy"
    assert row["planner"] == "model-weather" and row["model"] == "weather-model/tiny"
    assert row["prompt_version"] == "weather-1" and row["log"].endswith(":" + row["log"].rsplit(":", 1)[1])


def test_logs_list_and_show_give_the_turn_its_request_and_answer(campus: Scene, state: Path) -> None:
    session = _session(campus, state, ModelPlanner())
    session.submit("make it foggy")
    session.close()
    runner = CliRunner()
    listing = runner.invoke(main, ["logs", "list"])
    assert listing.exit_code == 0
    assert "model-weather  weather-model/tiny  ok  'make it foggy'" in listing.stdout
    turn_id = listing.stdout.split()[listing.stdout.split().index("model-weather") - 1]
    shown = runner.invoke(main, ["logs", "show", turn_id])
    assert shown.exit_code == 0
    assert "prompt version: weather-1" in shown.stdout and "[requirements] make it foggy" in shown.stdout
    assert "user: make it foggy" in shown.stdout and 'answer (17+5 tokens): {"kind": "fog"}' in shown.stdout
    assert 'set_weather({"kind": "fog"})' in shown.stdout


def test_logs_list_as_json_gives_each_session_its_turns(campus: Scene, state: Path) -> None:
    session = _session(campus, state, ModelPlanner())
    session.submit("make it foggy")
    session.close()
    result = CliRunner().invoke(main, ["logs", "list", "--json"])
    assert result.exit_code == 0, result.output
    [listed] = json.loads(result.stdout)
    [turn] = listed["turns"]
    assert listed["exchanges"] >= 1 and turn["prompt"] == "make it foggy" and turn["ok"]
    assert (turn["planner"], turn["model"], turn["prompt_version"]) == ("model-weather", "weather-model/tiny", "weather-1")


def test_logs_replay_says_whether_another_planner_makes_the_same_calls(campus: Scene, state: Path) -> None:
    session = _session(campus, state, ModelPlanner())
    session.submit("make it rain")
    session.submit("make it foggy")
    session.close()
    runner = CliRunner()
    same = runner.invoke(main, ["logs", "replay", "last:" + _turn_of(state, "make it foggy"),
                                "--planner", "tests.logs.test_turn_records:ModelPlanner"])
    assert same.exit_code == 0 and same.stdout.strip().endswith("same calls"), same.output
    rules = runner.invoke(main, ["logs", "replay", "last:" + _turn_of(state, "make it rain"), "--planner", "rules"])
    assert rules.exit_code == 1 and "replayed (rules): set_weather(kind='rain', intensity=0.6)" in rules.stdout
    different = runner.invoke(main, ["logs", "replay", "last:" + _turn_of(state, "make it foggy"),
                                     "--planner", "tests.logs.test_turn_records:always_rain"])
    assert different.exit_code == 1 and different.stdout.strip().endswith("different calls")


def always_rain(**options: object) -> ModelPlanner:
    planner = ModelPlanner()
    planner.plan = lambda prompt, context: Plan(  # type: ignore[method-assign]
        calls=[ToolCall(tool="set_weather", args={"kind": "rain"})], planner="always-rain")
    return planner


def test_a_turn_that_is_not_logged_is_a_one_line_error(state: Path) -> None:
    result = CliRunner().invoke(main, ["logs", "show", "last:99"])
    assert result.exit_code == 1 and "has no turn 99" in result.output


def _turn_of(state: Path, prompt: str) -> str:
    log = logs.active_log()
    assert log is not None
    return str(next(line["turn"] for line in logs.read_session(log.folder, log.session)
                    if line["kind"] == "turn" and line["prompt"] == prompt))
