"""One Settings object per command: flags > environment > config file > defaults.

Every command resolves its Settings once (`load_settings`) and passes them down: which
planner, which LLM backend and model with the backend's options, and the user's folders.
`drivetwin config show` prints each resolved value and where it came from.

A model belongs to its backend: when the backend is chosen at a higher level than the model
(say `--backend ollama` while the config file names `model = "smollm2-135m"`), the lower-level
model is ignored and the backend's default model is used.

Config file (`~/.config/drivetwin/config.toml`, or the path in DRIVETWIN_CONFIG):

    planner = "hybrid"
    backend = "ollama"
    model = "llama3.1"
    timeout_s = 60
    state_dir = "~/drivetwin-state"
    [openai]
    base_url = "http://127.0.0.1:8080/v1"
    [ollama]
    host = "http://127.0.0.1:11434"
    [embedded]
    threads = 1   # llama.cpp threads; default: half the logical CPUs (physical cores)

Environment: DRIVETWIN_PLANNER, DRIVETWIN_BACKEND, DRIVETWIN_MODEL, DRIVETWIN_OPENAI_BASE_URL,
DRIVETWIN_OPENAI_API_KEY (environment only, so keys stay out of files and shell history),
DRIVETWIN_OLLAMA_HOST, DRIVETWIN_TIMEOUT_S, DRIVETWIN_THREADS, DRIVETWIN_STATE, DRIVETWIN_CACHE,
DRIVETWIN_DATA, DRIVETWIN_CONFIG.
"""

from __future__ import annotations

import os
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from drivetwin.worlds import paths
from pydantic import BaseModel, ConfigDict, Field, ValidationError
from pydantic_settings import BaseSettings, SettingsConfigDict

DEFAULT_BACKEND = "embedded"
DEFAULT_PLANNER = "hybrid"
# llama.cpp's own server listens on 8080 by default; `python -m llama_cpp.server` on 8000.
DEFAULT_OPENAI_BASE_URL = "http://127.0.0.1:8080/v1"
ENV_PREFIX = "DRIVETWIN_"
ENV_CONFIG = paths.ENV_CONFIG
ENV_CACHE = paths.ENV_CACHE
ENV_OPENAI_API_KEY = "DRIVETWIN_OPENAI_API_KEY"

# Lower number = higher precedence; used to decide whether a model belongs to the backend.
_LEVELS = ("argument", "environment", "config file", "default")
# Fields whose environment variable is not DRIVETWIN_<FIELD> (kept from earlier releases).
_ENV_NAMES = {"state_dir": paths.ENV_STATE, "cache_dir": paths.ENV_CACHE, "data_dir": paths.ENV_DATA}
# Never read from a file: a key in a config file ends up in backups and screenshots.
_ENV_ONLY = {"openai_api_key"}


class ConfigError(Exception):
    """The config file or an environment variable holds something drivetwin cannot use."""


def cache_dir() -> Path:
    """Where drivetwin keeps files it builds once (assembled models); never inside the repo."""
    return paths.cache_dir()


def config_path() -> Path:
    """The TOML config file drivetwin reads (it need not exist)."""
    return paths.config_file()


class Settings(BaseSettings):
    """The resolved settings of one command; `sources` says where each value came from."""

    model_config = SettingsConfigDict(env_prefix=ENV_PREFIX, frozen=True, extra="forbid")

    planner: str = DEFAULT_PLANNER
    backend: str = DEFAULT_BACKEND
    model: str | None = None
    openai_base_url: str = DEFAULT_OPENAI_BASE_URL
    openai_api_key: str | None = Field(default=None, repr=False)
    # None lets the ollama client apply its own default and OLLAMA_HOST.
    ollama_host: str | None = None
    timeout_s: float | None = Field(default=None, gt=0)
    # None: the embedded backend's default_threads().
    threads: int | None = Field(default=None, ge=1)
    state_dir: Path = Field(default_factory=paths.state_dir)
    cache_dir: Path = Field(default_factory=paths.cache_dir)
    data_dir: Path = Field(default_factory=paths.data_dir)
    config_file: Path = Field(default_factory=paths.config_file)
    sources: dict[str, str] = Field(default_factory=dict, exclude=True)

    def options_for(self, backend: str) -> dict[str, Any]:
        """The constructor options this configuration gives to `backend`."""
        options: dict[str, Any] = {}
        if self.timeout_s is not None:
            options["timeout_s"] = self.timeout_s
        if backend == "openai":
            options["base_url"] = self.openai_base_url
            if self.openai_api_key:
                options["api_key"] = self.openai_api_key
        if backend == "ollama" and self.ollama_host:
            options["host"] = self.ollama_host
        if backend == "embedded" and self.threads is not None:
            options["n_threads"] = self.threads
        return options

    def planner_options(self) -> dict[str, Any]:
        """What `make_planner` needs to build a planner on the chosen backend and model."""
        return {"backend": self.backend, "model": self.model, **self.options_for(self.backend)}

    def rows(self) -> list[tuple[str, str, str]]:
        """(name, value, source) for every setting, secrets masked, for `config show`."""
        out: list[tuple[str, str, str]] = []
        for name in type(self).model_fields:
            if name == "sources":
                continue
            value = getattr(self, name)
            shown = "(set)" if name in _ENV_ONLY and value else ("-" if value is None else str(value))
            out.append((name, shown, self.sources.get(name, "default")))
        return out


# The Settings built from the config file's own layout.
class _OpenAISection(BaseModel):
    model_config = ConfigDict(extra="forbid")
    base_url: str | None = None


class _OllamaSection(BaseModel):
    model_config = ConfigDict(extra="forbid")
    host: str | None = None


class _EmbeddedSection(BaseModel):
    model_config = ConfigDict(extra="forbid")
    threads: int | None = Field(default=None, ge=1)


class _ConfigFile(BaseModel):
    model_config = ConfigDict(extra="forbid")
    planner: str | None = None
    backend: str | None = None
    model: str | None = None
    timeout_s: float | None = Field(default=None, gt=0)
    state_dir: Path | None = None
    cache_dir: Path | None = None
    data_dir: Path | None = None
    openai: _OpenAISection = _OpenAISection()
    ollama: _OllamaSection = _OllamaSection()
    embedded: _EmbeddedSection = _EmbeddedSection()

    def flat(self) -> dict[str, Any]:
        return {
            "planner": self.planner,
            "backend": self.backend,
            "model": self.model,
            "timeout_s": self.timeout_s,
            "state_dir": self.state_dir.expanduser() if self.state_dir else None,
            "cache_dir": self.cache_dir.expanduser() if self.cache_dir else None,
            "data_dir": self.data_dir.expanduser() if self.data_dir else None,
            "openai_base_url": self.openai.base_url,
            "ollama_host": self.ollama.host,
            "threads": self.embedded.threads,
        }


def env_name(field: str) -> str:
    """The environment variable that sets `field`."""
    return _ENV_NAMES.get(field, f"{ENV_PREFIX}{field.upper()}")


def _from_environment(env: Mapping[str, str]) -> dict[str, Any]:
    values: dict[str, Any] = {}
    for field in Settings.model_fields:
        if field in ("sources", "config_file"):
            continue
        raw = env.get(env_name(field))
        if raw:
            values[field] = Path(raw).expanduser() if field.endswith("_dir") else raw
    return values


def load_settings(
    *,
    planner: str | None = None,
    backend: str | None = None,
    model: str | None = None,
    openai_base_url: str | None = None,
    ollama_host: str | None = None,
    timeout_s: float | None = None,
    threads: int | None = None,
    environ: Mapping[str, str] | None = None,
    config_file: Path | None = None,
) -> Settings:
    """Resolve the settings from flags, environment, config file and defaults, remembering
    where each value came from; a bad value raises ConfigError naming its source."""
    env = os.environ if environ is None else environ
    path = config_file
    if path is None:
        path = Path(env[ENV_CONFIG]).expanduser() if env.get(ENV_CONFIG) else paths.config_file()
    flags = {
        "planner": planner, "backend": backend, "model": model, "openai_base_url": openai_base_url,
        "ollama_host": ollama_host, "timeout_s": timeout_s, "threads": threads,
    }
    layers: dict[str, dict[str, Any]] = {
        "argument": flags,
        "environment": _from_environment(env),
        "config file": _read_config_file(path).flat(),
    }
    values: dict[str, Any] = {"config_file": path}
    sources: dict[str, str] = {"config_file": "environment" if config_file is None and env.get(ENV_CONFIG) else "default"}
    for level in _LEVELS[:-1]:
        for key, value in layers[level].items():
            if value is None or key in values or (key in _ENV_ONLY and level != "environment"):
                continue
            values[key] = value
            sources[key] = f"{level} ({path})" if level == "config file" else level
    backend_level = _level_of(sources.get("backend", "default"))
    if "model" in values and _level_of(sources["model"]) > backend_level:
        # The model was chosen for another backend; let the chosen backend pick its default.
        del values["model"]
        del sources["model"]
    if environ is not None:
        # Folders not set by any layer follow the given environment, not the process's.
        for field in ("state_dir", "cache_dir", "data_dir"):
            values.setdefault(field, _default_folder(field, env))
    for key in Settings.model_fields:
        if key != "sources":
            sources.setdefault(key, "default")
    try:
        return Settings.model_validate({**values, "sources": sources})
    except ValidationError as error:
        raise ConfigError(_describe(error, sources)) from None


def _default_folder(field: str, env: Mapping[str, str]) -> Path:
    fallback = {"state_dir": paths.state_dir, "cache_dir": paths.cache_dir, "data_dir": paths.data_dir}[field]
    return fallback() if env is os.environ else Path(env.get(env_name(field)) or fallback())


def _level_of(source: str) -> int:
    return next(i for i, level in enumerate(_LEVELS) if source.startswith(level))


def _read_config_file(path: Path) -> _ConfigFile:
    if not path.is_file():
        return _ConfigFile()
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise ConfigError(f"config file {path} is not valid TOML: {error}") from None
    try:
        return _ConfigFile.model_validate(raw)
    except ValidationError as error:
        allowed = ("planner, backend, model, timeout_s, state_dir, cache_dir, data_dir, "
                   "[openai] base_url, [ollama] host, [embedded] threads")
        problems = "; ".join(f"{'.'.join(str(p) for p in e['loc']) or '(top)'}: {e['msg']}" for e in error.errors())
        raise ConfigError(f"config file {path} is invalid ({problems}); allowed keys: {allowed}") from None


def _describe(error: ValidationError, sources: Mapping[str, str]) -> str:
    problems = []
    for e in error.errors():
        field = str(e["loc"][0]) if e["loc"] else "(top)"
        where = sources.get(field, "default")
        raw = e.get("input")
        named = f"{env_name(field)}={raw!r}" if where == "environment" else f"{field}={raw!r} ({where})"
        problems.append(f"{named}: {e['msg']}")
    return "invalid settings: " + "; ".join(problems)

