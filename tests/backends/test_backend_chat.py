"""The one Backend.chat: transport retries for a dropped connection, and a log line for every call."""

from __future__ import annotations

import json
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from backend_servers import WEATHER_PROMPT, WEATHER_SCHEMA, Reply, ScriptedServer, recorded
from drivetwin.orchestrator import logs
from drivetwin.orchestrator.backends import BackendError, BackendTimeout, ConnectionDropped, InvalidOutput
from drivetwin.orchestrator.backends.base import TRANSPORT_RETRIES
from drivetwin.orchestrator.backends.ollama_backend import OllamaBackend
from drivetwin.orchestrator.backends.openai_backend import OpenAIBackend

Start = Callable[[dict[tuple[str, str], Reply]], ScriptedServer]
ROUTE = ("POST", "/v1/chat/completions")
ANSWER = '{"weather": "rain", "intensity": "heavy"}'
COMPLETION = {
    "choices": [{"index": 0, "message": {"role": "assistant", "content": ANSWER}, "finish_reason": "stop"}],
    "usage": {"prompt_tokens": 30, "completion_tokens": 12},
}


@pytest.fixture
def request_log(tmp_path: Path) -> Iterator[logs.RequestLog]:
    log = logs.open_log(tmp_path, command="test", world="campus")
    yield log
    logs.close_log()


def _openai(server: ScriptedServer) -> OpenAIBackend:
    return OpenAIBackend("served-model", base_url=f"{server.url}/v1")


def _exchanges(log: logs.RequestLog) -> list[dict]:
    return [line for line in logs.read_session(log.folder, log.session) if line["kind"] == "exchange"]


def test_a_dropped_connection_is_tried_again_and_the_answer_comes_back(scripted_server: Start) -> None:
    server = scripted_server({ROUTE: Reply(COMPLETION, drop=1)})
    result = _openai(server).chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA)
    assert result.data == {"weather": "rain", "intensity": "heavy"}
    assert [r["path"] for r in server.requests] == ["/v1/chat/completions"] * 2


def test_a_connection_that_keeps_dropping_is_given_up_after_the_retries(scripted_server: Start) -> None:
    server = scripted_server({ROUTE: Reply(COMPLETION, drop=10)})
    with pytest.raises(ConnectionDropped, match=f"after {TRANSPORT_RETRIES + 1} attempt") as caught:
        _openai(server).chat(WEATHER_PROMPT)
    assert isinstance(caught.value, InvalidOutput) and caught.value.reason == "truncated"
    assert len(server.requests) == TRANSPORT_RETRIES + 1


def test_a_timeout_is_not_tried_again(scripted_server: Start) -> None:
    server = scripted_server({ROUTE: Reply(COMPLETION, delay_s=1.0)})
    with pytest.raises(BackendTimeout):
        _openai(server).chat(WEATHER_PROMPT, timeout_s=0.3)
    assert len(server.requests) == 1


def test_a_refused_request_is_not_tried_again(scripted_server: Start) -> None:
    server = scripted_server({ROUTE: Reply({"error": "bad request"}, status=400)})
    with pytest.raises(BackendError, match="HTTP 400"):
        _openai(server).chat(WEATHER_PROMPT)
    assert len(server.requests) == 1


def test_the_ollama_backend_is_tried_again_after_a_dropped_connection(scripted_server: Start) -> None:
    server = scripted_server({("POST", "/api/chat"): Reply(recorded("ollama_chat_plain.json"), drop=1)})
    result = OllamaBackend("gemma2", host=server.url).chat(WEATHER_PROMPT)
    assert result.text and len(server.requests) == 2


def test_every_request_and_answer_is_one_log_line(scripted_server: Start, request_log: logs.RequestLog) -> None:
    server = scripted_server({ROUTE: Reply(COMPLETION, drop=1)})
    result = _openai(server).chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA, max_tokens=64)
    [line] = _exchanges(request_log)
    assert line["backend"] == "openai" and line["model"] == "served-model"
    assert line["request"]["messages"] == WEATHER_PROMPT and line["request"]["schema"] == WEATHER_SCHEMA
    assert line["request"]["max_tokens"] == 64
    assert line["answer"] == {"text": ANSWER, "finish_reason": "stop", "prompt_tokens": 30, "completion_tokens": 12}
    assert line["error"] is None and line["attempts"] == 2
    assert line["latency_s"] == pytest.approx(result.latency_s, abs=1e-3)
    assert line["session"] == request_log.session and line["id"].startswith(request_log.session)


def test_a_failed_request_is_logged_with_its_error(scripted_server: Start, request_log: logs.RequestLog) -> None:
    server = scripted_server({ROUTE: Reply({**COMPLETION, "choices": [
        {"index": 0, "message": {"role": "assistant", "content": "sunny"}, "finish_reason": "stop"}]})})
    with pytest.raises(InvalidOutput):
        _openai(server).chat(WEATHER_PROMPT, schema=WEATHER_SCHEMA)
    [line] = _exchanges(request_log)
    assert line["answer"] is None and line["error"].startswith("InvalidOutput: openai/served-model answer is not JSON")


def test_the_calls_made_while_a_prompt_is_planned_are_gathered_for_its_turn(
    scripted_server: Start, request_log: logs.RequestLog,
) -> None:
    server = scripted_server({ROUTE: Reply(COMPLETION)})
    backend = _openai(server)
    with logs.turn_scope() as facts:
        backend.chat(WEATHER_PROMPT)
        backend.chat(WEATHER_PROMPT)
    backend.chat(WEATHER_PROMPT)  # outside the turn
    assert facts.model == "openai/served-model" and facts.tokens == 2 * 42
    lines = _exchanges(request_log)
    assert facts.exchanges == [line["id"] for line in lines[:2]]
    assert [line["turn"] for line in lines] == [facts.turn, facts.turn, None]


def test_a_log_file_past_its_limit_is_rotated_and_read_back_whole(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(logs, "MAX_FILE_BYTES", 400)
    log = logs.RequestLog(tmp_path)
    for n in range(10):
        log.write("note", n=n, padding="x" * 100)
    assert len(list(tmp_path.glob(f"{log.session}.*.jsonl"))) >= 2
    assert all(path.stat().st_size <= 400 for path in tmp_path.glob("*.jsonl"))
    assert [line["n"] for line in logs.read_session(tmp_path, log.session)] == list(range(10))


def test_only_the_newest_sessions_are_kept(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(logs, "KEEP_SESSIONS", 3)
    folder = logs.log_folder(tmp_path)
    folder.mkdir()
    for n in range(5):
        (folder / f"session-2026010{n}-000000-1.jsonl").write_text(json.dumps({"kind": "session"}) + "\n")
    logs.open_log(tmp_path, command="test")
    logs.close_log()
    names = [p.name for p in logs.session_files(folder)]
    assert len(names) == 3 and names[:2] == ["session-20260103-000000-1.jsonl", "session-20260104-000000-1.jsonl"]
