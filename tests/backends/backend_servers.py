"""Helpers for the backend tests: recorded responses, free ports, a scripted HTTP server."""

from __future__ import annotations

import json
import socket
import threading
import time
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

RECORDED = Path(__file__).parent / "recorded"
# One llama.cpp thread in tests: its spinning threads crawl when other jobs share the 2 CI
# cores (measured on a busy machine: 0.8 s with 1 thread, 11 s with 2, for the same answer).
TEST_THREADS = 1
# How often a scripted server checks for shutdown; small so that tests end quickly.
POLL_INTERVAL_S = 0.05
WEATHER_SCHEMA: dict[str, Any] = {
    "type": "object",
    "properties": {
        "weather": {"type": "string", "enum": ["clear", "rain", "snow", "fog"]},
        "intensity": {"type": "string", "enum": ["light", "heavy"]},
    },
    "required": ["weather", "intensity"],
    "additionalProperties": False,
}
WEATHER_PROMPT: list[Any] = [
    {"role": "system", "content": "You set the weather of a driving simulator. Answer in JSON."},
    {"role": "user", "content": "Make it rain heavily."},
]


def free_port() -> int:
    """A TCP port on 127.0.0.1 that nothing listens on (at the moment of asking)."""
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def recorded(name: str) -> dict[str, Any]:
    """One recorded response from tests/backends/recorded/."""
    data: dict[str, Any] = json.loads((RECORDED / name).read_text(encoding="utf-8"))
    return data


@dataclass
class Reply:
    """What the scripted server sends for one route."""

    body: Any = None
    status: int = 200
    content_type: str = "application/json"
    delay_s: float = 0.0
    # Announce the full length but send only half, then hang up: a cut-off reply.
    truncate: bool = False
    # Hang up without a word on the first `drop` requests to this route: a dropped connection.
    drop: int = 0

    def payload(self) -> bytes:
        if isinstance(self.body, bytes):
            return self.body
        if isinstance(self.body, str):
            return self.body.encode()
        return json.dumps(self.body).encode()


@dataclass
class ScriptedServer:
    """A tiny http.server on 127.0.0.1 that answers from a route table and records requests."""

    routes: dict[tuple[str, str], Reply]
    requests: list[dict[str, Any]] = field(default_factory=list)
    url: str = ""
    server: ThreadingHTTPServer | None = None

    def start(self) -> ScriptedServer:
        script = self

        class Handler(BaseHTTPRequestHandler):
            def _answer(self) -> None:
                length = int(self.headers.get("content-length") or 0)
                raw = self.rfile.read(length) if length else b""
                body = json.loads(raw) if raw else None
                script.requests.append({"method": self.command, "path": self.path, "json": body})
                reply = script.routes.get((self.command, self.path))
                if reply is None:
                    reply = Reply({"error": f"no route {self.command} {self.path}"}, status=404)
                if reply.drop > 0:
                    reply.drop -= 1
                    self.close_connection = True
                    return
                time.sleep(reply.delay_s)
                data = reply.payload()
                try:
                    self.send_response(reply.status)
                    self.send_header("content-type", reply.content_type)
                    self.send_header("content-length", str(len(data)))
                    self.end_headers()
                    self.wfile.write(data[: len(data) // 2] if reply.truncate else data)
                except (BrokenPipeError, ConnectionResetError):
                    pass  # the client gave up first (the timeout tests)
                if reply.truncate:
                    self.close_connection = True

            do_GET = do_POST = _answer

            def log_message(self, format: str, *args: Any) -> None:
                pass

        server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        server.daemon_threads = True
        server.block_on_close = False  # a sleeping handler must not hold up the test's end
        threading.Thread(target=server.serve_forever, args=(POLL_INTERVAL_S,), daemon=True).start()
        self.server = server
        self.url = f"http://127.0.0.1:{server.server_address[1]}"
        return self

    def stop(self) -> None:
        if self.server is not None:
            self.server.shutdown()
            self.server.server_close()
