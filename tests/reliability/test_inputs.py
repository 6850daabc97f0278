"""Every bad input is a clear, typed one-line error that leaves the scene and journal as they were."""

from __future__ import annotations

import json
import os
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import pytest
from click.testing import CliRunner
from drivetwin.orchestrator.backends.errors import BackendTimeout
from drivetwin.orchestrator.backends.openai_backend import OpenAIBackend
from drivetwin.orchestrator.cli import main
from drivetwin.orchestrator.journal import Journal
from drivetwin.orchestrator.repl import ChatOptions, run_lines
from drivetwin.orchestrator.session import SessionError
from drivetwin.worlds.scene import Scene, SceneFileError

PROMPT = [{"role": "user", "content": "say hi"}]


def _unchanged(session, before, journal_before):
    assert session.scene == before
    assert Journal(session.journal.path).replay().scene == journal_before


@pytest.mark.parametrize(("content", "says"), [
    (b'{"name": "x\xff"}', "not UTF-8 text: byte 0xff"),
    (b"[" * 100_000 + b"]" * 100_000, "nests deeper than 64 levels"),
    (b'{"a": Infinity}', "Infinity is not a number JSON allows"),
])
def test_a_bad_scene_file_is_a_one_line_error_and_changes_nothing(session, tmp_path, content, says):
    bad = tmp_path / "bad.json"
    bad.write_bytes(content)
    before, journal_before = session.scene, Journal(session.journal.path).replay().scene
    with pytest.raises(SceneFileError, match=says) as caught:
        session.load(bad)
    assert "\n" not in str(caught.value)
    _unchanged(session, before, journal_before)


def test_a_scene_holding_infinity_is_refused_on_load_and_never_saved_as_null(campus, tmp_path):
    data = json.loads(campus.model_dump_json())
    data["assets"][0]["behaviour"] = {"kind": "follow_path", "waypoints": [[0, 0], [5, 0]], "start_time": "inf"}
    with pytest.raises(ValueError, match="finite number"):
        Scene.model_validate(data)  # a float field without its own bound still refuses infinity
    text = json.dumps(data).replace('"inf"', "Infinity")
    (tmp_path / "inf.json").write_text(text)
    with pytest.raises(SceneFileError, match="Infinity is not a number JSON allows"):
        Scene.load(tmp_path / "inf.json")


def test_loading_a_fifo_is_refused_without_hanging(session, tmp_path):
    fifo = tmp_path / "scene.fifo"
    os.mkfifo(fifo)
    started = time.perf_counter()
    with pytest.raises(SceneFileError, match="not a regular file"):
        session.load(fifo)
    assert time.perf_counter() - started < 2.0


@pytest.mark.parametrize("target", [".", "..", "/"])
def test_saving_to_a_folder_is_a_session_error(session, target):
    with pytest.raises(SessionError, match="is a folder"):
        session.save(target)


def test_a_non_utf8_script_is_a_one_line_error(tmp_path, monkeypatch):
    monkeypatch.setenv("DRIVETWIN_STATE", str(tmp_path / "state"))
    script = tmp_path / "script.txt"
    script.write_bytes(b"make it rain\n\xff\xfe add a cone\n")
    result = CliRunner().invoke(main, ["chat", "--planner", "rules", "--no-sim", "--script", str(script)])
    assert result.exit_code == 1 and "not UTF-8 text: byte 0xff" in result.output
    assert "Traceback" not in result.output


def test_ansi_escapes_in_a_prompt_are_not_echoed_raw(session):
    shown: list[str] = []
    options = ChatOptions(echo=shown.append)
    run_lines(session, ["make it rain \x1b[2J\x1b]0;pwned\x07 now"], options)
    assert shown and not any("\x1b" in line or "\x07" in line for line in shown)
    assert "\\x1b[2J" in shown[0]


class _Drip(BaseHTTPRequestHandler):
    def do_POST(self) -> None:
        self.rfile.read(int(self.headers.get("Content-Length", 0)))
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", "1000")
        self.end_headers()
        try:
            for _ in range(1000):  # one byte at a time: no read ever waits long
                self.wfile.write(b" ")
                self.wfile.flush()
                time.sleep(0.3)
        except OSError:
            pass

    def log_message(self, format, *args):
        pass


class _Answer(BaseHTTPRequestHandler):
    usage: object = None

    def do_POST(self) -> None:
        self.rfile.read(int(self.headers.get("Content-Length", 0)))
        body = json.dumps({"choices": [{"message": {"content": "hi"}, "finish_reason": "stop"}],
                           "usage": type(self).usage}).encode()
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, format, *args):
        pass


@pytest.fixture
def serve():
    servers = []

    def start(handler) -> str:
        server = ThreadingHTTPServer(("127.0.0.1", 0), handler)
        server.daemon_threads = True
        threading.Thread(target=server.serve_forever, kwargs={"poll_interval": 0.05}, daemon=True).start()
        servers.append(server)
        return f"http://127.0.0.1:{server.server_address[1]}/v1"

    yield start
    for server in servers:
        server.shutdown()
        server.server_close()


def test_a_server_that_drips_bytes_is_timed_out_for_the_whole_call(serve):
    backend = OpenAIBackend("m", base_url=serve(_Drip), timeout_s=1.0)
    started = time.perf_counter()
    with pytest.raises(BackendTimeout, match="did not answer within 1 s"):
        backend.chat(PROMPT)
    assert time.perf_counter() - started < 3.0


@pytest.mark.parametrize("usage", ["lots", [1, 2], {"prompt_tokens": "x", "completion_tokens": -3}, 7])
def test_a_malformed_usage_gives_zero_token_counts_not_a_traceback(serve, usage):
    handler = type("Answer", (_Answer,), {"usage": usage})
    result = OpenAIBackend("m", base_url=serve(handler), timeout_s=10.0).chat(PROMPT)
    assert result.text == "hi" and result.prompt_tokens == 0 and result.completion_tokens == 0


def test_render_without_the_simulation_is_a_one_line_error(tmp_path, monkeypatch):
    monkeypatch.setenv("DRIVETWIN_STATE", str(tmp_path / "state"))
    script = tmp_path / "script.txt"
    script.write_text("render frame.png\n")
    result = CliRunner().invoke(main, ["chat", "--planner", "rules", "--no-sim", "--script", str(script)])
    assert "error: rendering needs the simulation" in result.output and "Traceback" not in result.output
