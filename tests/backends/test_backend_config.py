"""Choosing the backend: arguments over environment over config file over defaults."""

from __future__ import annotations

from pathlib import Path

import pytest
from drivetwin.orchestrator.config import (
    ConfigError,
    cache_dir,
    load_settings,
)

REPO = Path(__file__).resolve().parents[2]


def write_config(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "config.toml"
    path.write_text(text)
    return path


def test_without_any_setting_the_embedded_smollm2_is_chosen(tmp_path: Path) -> None:
    settings = load_settings(environ={}, config_file=tmp_path / "absent.toml")
    assert (settings.backend, settings.model) == ("embedded", None)
    assert settings.sources["backend"] == "default"


def test_the_config_file_is_read(tmp_path: Path) -> None:
    path = write_config(
        tmp_path,
        'backend = "ollama"\nmodel = "mistral"\ntimeout_s = 30\n[ollama]\nhost = "http://gpu:11434"\n',
    )
    settings = load_settings(environ={}, config_file=path)
    assert (settings.backend, settings.model, settings.timeout_s) == ("ollama", "mistral", 30)
    assert settings.options_for("ollama") == {"host": "http://gpu:11434", "timeout_s": 30}
    assert settings.sources["model"].startswith("config file")


def test_the_config_file_path_comes_from_drivetwin_config(tmp_path: Path) -> None:
    path = write_config(tmp_path, 'backend = "openai"\n')
    assert load_settings(environ={"DRIVETWIN_CONFIG": str(path)}).backend == "openai"


def test_environment_overrides_the_file_and_arguments_override_both(tmp_path: Path) -> None:
    path = write_config(tmp_path, 'backend = "ollama"\n[openai]\nbase_url = "http://file/v1"\n')
    env = {"DRIVETWIN_BACKEND": "openai", "DRIVETWIN_OPENAI_BASE_URL": "http://env/v1"}
    from_env = load_settings(environ=env, config_file=path)
    assert (from_env.backend, from_env.openai_base_url) == ("openai", "http://env/v1")
    from_args = load_settings(backend="embedded", environ=env, config_file=path)
    assert from_args.backend == "embedded" and from_args.sources["backend"] == "argument"


def test_a_model_chosen_for_another_backend_is_dropped(tmp_path: Path) -> None:
    path = write_config(tmp_path, 'backend = "embedded"\nmodel = "gemma3-270m"\n')
    settings = load_settings(backend="ollama", environ={}, config_file=path)
    assert (settings.backend, settings.model) == ("ollama", None)


def test_a_model_from_the_same_level_as_the_backend_is_kept(tmp_path: Path) -> None:
    env = {"DRIVETWIN_BACKEND": "ollama", "DRIVETWIN_MODEL": "llama3.1"}
    settings = load_settings(environ=env, config_file=tmp_path / "absent.toml")
    assert settings.model == "llama3.1"


def test_the_api_key_comes_only_from_the_environment_and_is_not_printed(tmp_path: Path) -> None:
    settings = load_settings(environ={"DRIVETWIN_OPENAI_API_KEY": "sk-secret"}, config_file=tmp_path / "absent.toml")
    assert settings.options_for("openai")["api_key"] == "sk-secret"
    assert "sk-secret" not in repr(settings)


def test_invalid_toml_is_a_config_error_naming_the_file(tmp_path: Path) -> None:
    path = write_config(tmp_path, "backend = \n")
    with pytest.raises(ConfigError, match=r"config\.toml is not valid TOML"):
        load_settings(environ={}, config_file=path)


def test_an_unknown_key_is_a_config_error_listing_the_allowed_keys(tmp_path: Path) -> None:
    path = write_config(tmp_path, 'backnd = "ollama"\n')
    with pytest.raises(ConfigError, match=r"backnd.*allowed keys: planner, backend, model"):
        load_settings(environ={}, config_file=path)


def test_a_timeout_that_is_not_a_number_is_a_config_error(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match="DRIVETWIN_TIMEOUT_S='soon'"):
        load_settings(environ={"DRIVETWIN_TIMEOUT_S": "soon"}, config_file=tmp_path / "x.toml")


def test_the_cache_folder_follows_drivetwin_cache_and_defaults_outside_the_repo(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setenv("DRIVETWIN_CACHE", str(tmp_path / "c"))
    assert cache_dir() == tmp_path / "c"
    monkeypatch.delenv("DRIVETWIN_CACHE")
    assert cache_dir() == Path.home() / ".cache" / "drivetwin"
    assert REPO not in cache_dir().parents


def test_embedded_threads_come_from_the_file_or_drivetwin_threads(tmp_path: Path) -> None:
    path = write_config(tmp_path, "[embedded]\nthreads = 1\n")
    assert load_settings(environ={}, config_file=path).options_for("embedded") == {"n_threads": 1}
    from_env = load_settings(environ={"DRIVETWIN_THREADS": "3"}, config_file=path)
    assert from_env.options_for("embedded") == {"n_threads": 3}
