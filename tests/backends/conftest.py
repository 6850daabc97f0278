"""Fixtures for the backend tests: scripted HTTP servers and a real llama_cpp.server."""

from __future__ import annotations

import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import httpx
import pytest
from backend_servers import TEST_THREADS, Reply, ScriptedServer, free_port

# llama_cpp.server with the 98 MB SmolLM2 file is ready in about 1 s on 2 cores.
SERVER_START_DEADLINE_S = 60.0


@pytest.fixture
def scripted_server() -> Iterator[Callable[[dict[tuple[str, str], Reply]], ScriptedServer]]:
    """Start scripted servers from route tables; all are stopped after the test."""
    servers: list[ScriptedServer] = []

    def start(routes: dict[tuple[str, str], Reply]) -> ScriptedServer:
        servers.append(ScriptedServer(routes).start())
        return servers[-1]

    yield start
    for server in servers:
        server.stop()


@pytest.fixture(scope="session")
def model_cache(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A drivetwin cache folder for this test session, so tests never touch ~/.cache."""
    return tmp_path_factory.mktemp("drivetwin-cache")


@pytest.fixture(autouse=True)
def _isolated_cache(model_cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("DRIVETWIN_CACHE", str(model_cache))


@pytest.fixture(scope="module")
def llama_server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """`python -m llama_cpp.server` with the shipped SmolLM2 file; yields its /v1 base URL."""
    pytest.importorskip("llama_cpp.server", reason="needs the llm extra (llama-cpp-python[server])")
    from drivetwin.orchestrator.backends.gguf_models import SMOLLM2

    model_path = SMOLLM2.locate()
    port = free_port()
    log_path = tmp_path_factory.mktemp("llama-server") / "server.log"
    with log_path.open("wb") as log:
        process = subprocess.Popen(
            [
                sys.executable, "-m", "llama_cpp.server",
                "--model", str(model_path), "--model_alias", "smollm2-135m",
                "--host", "127.0.0.1", "--port", str(port),
                "--n_ctx", "2048", "--n_threads", str(TEST_THREADS),
            ],
            stdout=log,
            stderr=subprocess.STDOUT,
        )  # fmt: skip
    base_url = f"http://127.0.0.1:{port}/v1"
    try:
        deadline = time.monotonic() + SERVER_START_DEADLINE_S
        while True:
            if process.poll() is not None:
                pytest.fail(f"llama_cpp.server exited early:\n{log_path.read_text()[-2000:]}")
            try:
                if httpx.get(f"{base_url}/models", timeout=1.0).status_code == 200:
                    break
            except httpx.HTTPError:
                pass
            if time.monotonic() > deadline:
                pytest.fail(f"llama_cpp.server not ready in {SERVER_START_DEADLINE_S} s")
            time.sleep(0.1)
        yield base_url
    finally:
        process.terminate()
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
