"""Every command honours one Settings: flags > environment > config file > defaults."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import platformdirs
import pytest
from backend_servers import Reply, ScriptedServer
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
from drivetwin.orchestrator.config import load_settings
from drivetwin.worlds import paths

Start = Callable[[dict[tuple[str, str], Reply]], ScriptedServer]


def test_the_planner_comes_from_the_environment_when_the_command_runs(tmp_path: Path) -> None:
    settings = load_settings(environ={"DRIVETWIN_PLANNER": "rules"}, config_file=tmp_path / "absent.toml")
    assert settings.planner == "rules" and settings.sources["planner"] == "environment"
    assert load_settings(environ={}, config_file=tmp_path / "absent.toml").planner == "hybrid"


def test_folders_follow_their_variables_and_the_config_file(tmp_path: Path) -> None:
    config = tmp_path / "config.toml"
    config.write_text(f'state_dir = "{tmp_path / "from-file"}"\n')
    from_file = load_settings(environ={}, config_file=config)
    assert from_file.state_dir == tmp_path / "from-file"
    assert from_file.sources["state_dir"].startswith("config file")
    from_env = load_settings(environ={"DRIVETWIN_STATE": str(tmp_path / "env")}, config_file=config)
    assert from_env.state_dir == tmp_path / "env" and from_env.sources["state_dir"] == "environment"


def test_platform_folders_follow_xdg_variables(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    for name in ("DRIVETWIN_STATE", "DRIVETWIN_DATA", "DRIVETWIN_CACHE"):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))
    assert paths.state_dir() == tmp_path / "state" / "drivetwin"
    assert paths.data_dir() == tmp_path / "data" / "drivetwin"


def test_config_show_prints_each_value_with_its_source(tmp_path: Path) -> None:
    env = {"DRIVETWIN_BACKEND": "openai", "DRIVETWIN_CONFIG": str(tmp_path / "absent.toml"),
           "DRIVETWIN_OPENAI_API_KEY": "sk-secret"}
    result = CliRunner().invoke(main, ["config", "show", "--json"], env=env)
    assert result.exit_code == 0, result.output
    shown = json.loads(result.output)
    assert shown["backend"] == {"value": "openai", "source": "environment"}
    assert shown["planner"] == {"value": "hybrid", "source": "default"}
    assert shown["openai_api_key"]["value"] == "(set)" and "sk-secret" not in result.output


def test_a_bad_environment_value_is_one_line_naming_the_variable(tmp_path: Path) -> None:
    env = {"DRIVETWIN_TIMEOUT_S": "-3", "DRIVETWIN_CONFIG": str(tmp_path / "absent.toml")}
    result = CliRunner().invoke(main, ["config", "show"], env=env)
    assert result.exit_code == 1
    assert "DRIVETWIN_TIMEOUT_S='-3'" in result.output and "Traceback" not in result.output


def test_chat_uses_the_openai_server_named_in_the_environment(scripted_server: Start, tmp_path: Path) -> None:
    # A real HTTP server on 127.0.0.1 that records what reaches it; its answer need not plan well.
    answer = {"choices": [{"message": {"content": '{"requirements": []}'}}],
              "usage": {"prompt_tokens": 5, "completion_tokens": 3}, "model": "served-model"}
    server = scripted_server({("POST", "/v1/chat/completions"): Reply(answer),
                              ("GET", "/v1/models"): Reply({"data": [{"id": "served-model"}]})})
    script = tmp_path / "lines.txt"
    script.write_text("make it rain\n")
    env = {"DRIVETWIN_BACKEND": "openai", "DRIVETWIN_OPENAI_BASE_URL": f"{server.url}/v1",
           "DRIVETWIN_PLANNER": "llm", "DRIVETWIN_CONFIG": str(tmp_path / "absent.toml"),
           "DRIVETWIN_STATE": str(tmp_path / "state"),
           # The managers' few-shot examples come from the world's example bank: share the one
           # the other tests build in the user cache instead of generating it again here.
           "DRIVETWIN_CACHE": str(platformdirs.user_cache_path("drivetwin"))}
    CliRunner().invoke(main, ["chat", "--no-sim", "--script", str(script)], env=env)
    posted = [r for r in server.requests if r["method"] == "POST"]
    assert posted and posted[0]["path"] == "/v1/chat/completions"
    assert any("make it rain" in json.dumps(r["json"]) for r in posted)
