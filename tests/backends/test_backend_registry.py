"""Backend plugins through the `drivetwin.backends` entry-point group, and the status table."""

from __future__ import annotations

import logging
import textwrap
from pathlib import Path

import pytest
from backend_servers import free_port
from drivetwin.orchestrator.backends import (
    BackendUnavailable,
    InvalidRequest,
    UnknownBackend,
    backend_names,
    backends_table,
    list_backends,
    load_backend,
    open_backend,
    plugin_problems,
)
from drivetwin.orchestrator.backends.openai_backend import OpenAIBackend
from drivetwin.orchestrator.config import load_settings

ECHO_PLUGIN = '''
"""A test plugin: answers with the last user message."""
from drivetwin.orchestrator.backends import Backend, BackendInfo, BackendStatus, Completion


class EchoBackend(Backend):
    name = "echo"
    default_model = "parrot"

    def __init__(self, model=None, *, loud=False):
        super().__init__(model)
        self.loud = loud

    def complete(self, request):
        text = request.messages[-1]["content"]
        return Completion(text.upper() if self.loud else text)

    def describe(self):
        return BackendInfo("echo", self.model)

    @classmethod
    def statuses(cls, **options):
        return [BackendStatus("echo", "parrot", True)]
'''


@pytest.fixture
def plugins(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Install, via a real .dist-info on sys.path, one working and one broken backend plugin."""
    (tmp_path / "drivetwin_echo_plugin.py").write_text(ECHO_PLUGIN)
    info = tmp_path / "drivetwin_test_plugins-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: drivetwin-test-plugins\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text(
        textwrap.dedent(
            """\
            [drivetwin.backends]
            echo = drivetwin_echo_plugin:EchoBackend
            broken = drivetwin_no_such_module:Backend
            """
        )
    )
    monkeypatch.syspath_prepend(str(tmp_path))


def test_built_in_backends_load_without_being_installed_as_entry_points() -> None:
    assert {"embedded", "ollama", "openai"} <= set(backend_names())
    assert isinstance(load_backend("openai", "m"), OpenAIBackend)


def test_an_unknown_backend_name_lists_the_available_ones() -> None:
    with pytest.raises(UnknownBackend) as caught:
        load_backend("llamafile")
    assert "embedded" in caught.value.available and "available: embedded" in str(caught.value)


def test_an_unknown_option_is_refused_with_the_allowed_ones() -> None:
    with pytest.raises(InvalidRequest, match="allowed: base_url, api_key, timeout_s"):
        load_backend("openai", "m", host="x")


def test_a_plugin_backend_is_found_through_its_entry_point(plugins: None) -> None:
    backend = load_backend("echo", loud=True)
    assert backend.model == "parrot"
    assert backend.chat([{"role": "user", "content": "rain"}]).text == "RAIN"


def test_a_broken_plugin_is_skipped_and_reported(plugins: None, caplog: pytest.LogCaptureFixture) -> None:
    with caplog.at_level(logging.WARNING):
        names = backend_names()
    assert "broken" not in names and "echo" in names
    assert "skipping backend plugin broken" in caplog.text
    [problem] = plugin_problems()
    assert problem.group == "drivetwin.backends" and problem.name == "broken"
    assert "--force-reinstall drivetwin-test-plugins" in problem.fix
    assert "ModuleNotFoundError" in problem.error
    row = next(r for r in list_backends() if r.backend == "broken")
    assert not row.usable and row.fix is not None and "drivetwin-test-plugins" in row.fix


def test_opening_a_broken_plugin_names_the_fix(plugins: None) -> None:
    with pytest.raises(BackendUnavailable) as caught:
        load_backend("broken")
    assert caught.value.fix is not None and "--force-reinstall drivetwin-test-plugins" in caught.value.fix


def test_the_table_shows_what_is_usable_and_the_command_that_fixes_the_rest(
    tmp_path: Path,
) -> None:
    dead = f"http://127.0.0.1:{free_port()}"
    settings = load_settings(
        backend="ollama",
        model="llama3.1",
        ollama_host=dead,
        openai_base_url=f"{dead}/v1",
        environ={},
        config_file=tmp_path / "absent.toml",
    )
    table = backends_table(settings)
    lines = table.splitlines()
    assert lines[0].split() == ["backend", "model", "usable", "notes", "/", "fix"]
    ollama_row = next(line for line in lines if "llama3.1:8b" in line)
    assert "llama3.1:8b *" in ollama_row  # the configured choice is marked
    assert " no " in ollama_row and "fix: ollama serve" in ollama_row
    openai_row = next(line for line in lines if line.startswith("openai"))
    assert "fix: python -m llama_cpp.server" in openai_row
    embedded_rows = [line for line in lines if line.startswith("embedded")]
    assert len(embedded_rows) == 2


def test_open_backend_uses_the_resolved_settings(tmp_path: Path) -> None:
    settings = load_settings(
        environ={"DRIVETWIN_BACKEND": "openai", "DRIVETWIN_OPENAI_BASE_URL": "http://h:1/v1"},
        config_file=tmp_path / "absent.toml",
    )
    backend = open_backend(settings)
    assert isinstance(backend, OpenAIBackend)
    assert backend._base_url == "http://h:1/v1"
