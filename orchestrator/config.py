"""Which LLM backend and model to use, from CLI flags, env vars, a TOML file and defaults.

Precedence, highest first: explicit arguments (`--backend`, `--model`, ...), environment
variables, the config file, built-in defaults. A model belongs to its backend: when the
backend is chosen at a higher level than the model (say `--backend ollama` while the config
file names `model = "smollm2-135m"`), the lower-level model is ignored and the backend's
default model is used.

Config file (`~/.config/drivetwin/config.toml`, or the path in DRIVETWIN_CONFIG):

    backend = "ollama"
    model = "llama3.1"
    timeout_s = 60
    [openai]
    base_url = "http://127.0.0.1:8080/v1"
    [ollama]
    host = "http://127.0.0.1:11434"
    [embedded]
    threads = 1   # llama.cpp threads; default: half the logical CPUs (physical cores)
"""

from __future__ import annotations

import os
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ConfigDict, Field, ValidationError

ENV_BACKEND = "DRIVETWIN_BACKEND"
ENV_MODEL = "DRIVETWIN_MODEL"
ENV_OPENAI_BASE_URL = "DRIVETWIN_OPENAI_BASE_URL"
ENV_OLLAMA_HOST = "DRIVETWIN_OLLAMA_HOST"
# Read from the environment only, so that keys stay out of config files and shell history.
ENV_OPENAI_API_KEY = "DRIVETWIN_OPENAI_API_KEY"
ENV_TIMEOUT = "DRIVETWIN_TIMEOUT_S"
ENV_THREADS = "DRIVETWIN_THREADS"
ENV_CONFIG = "DRIVETWIN_CONFIG"
ENV_CACHE = "DRIVETWIN_CACHE"

DEFAULT_BACKEND = "embedded"
# llama.cpp's own server listens on 8080 by default; `python -m llama_cpp.server` on 8000.
DEFAULT_OPENAI_BASE_URL = "http://127.0.0.1:8080/v1"

# Lower number = higher precedence; used to decide whether a model belongs to the backend.
_LEVELS = ("argument", "environment", "config file", "default")


class ConfigError(Exception):
    """The config file or an environment variable holds something drivetwin cannot use."""


def cache_dir() -> Path:
    """Where drivetwin keeps files it builds once (assembled models); never inside the repo."""
    configured = os.environ.get(ENV_CACHE)
    return Path(configured).expanduser() if configured else Path.home() / ".cache" / "drivetwin"


def config_path() -> Path:
    """The TOML config file drivetwin reads (it need not exist)."""
    configured = os.environ.get(ENV_CONFIG)
    if configured:
        return Path(configured).expanduser()
    return Path.home() / ".config" / "drivetwin" / "config.toml"


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
    backend: str | None = None
    model: str | None = None
    timeout_s: float | None = Field(default=None, gt=0)
    openai: _OpenAISection = _OpenAISection()
    ollama: _OllamaSection = _OllamaSection()
    embedded: _EmbeddedSection = _EmbeddedSection()


class BackendSettings(BaseModel):
    """The resolved backend choice; `sources` says where each value came from."""

    model_config = ConfigDict(frozen=True)

    backend: str = DEFAULT_BACKEND
    model: str | None = None
    openai_base_url: str = DEFAULT_OPENAI_BASE_URL
    openai_api_key: str | None = Field(default=None, repr=False)
    # None lets the ollama client apply its own default and OLLAMA_HOST.
    ollama_host: str | None = None
    timeout_s: float | None = Field(default=None, gt=0)
    # None: the embedded backend's default_threads().
    threads: int | None = Field(default=None, ge=1)
    sources: dict[str, str] = {}

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


def load_settings(
    *,
    backend: str | None = None,
    model: str | None = None,
    openai_base_url: str | None = None,
    ollama_host: str | None = None,
    timeout_s: float | None = None,
    threads: int | None = None,
    environ: Mapping[str, str] | None = None,
    config_file: Path | None = None,
) -> BackendSettings:
    """Resolve the backend choice from arguments, environment, config file and defaults."""
    env = os.environ if environ is None else environ
    path = config_file
    if path is None:
        path = Path(env[ENV_CONFIG]).expanduser() if env.get(ENV_CONFIG) else config_path()
    file = _read_config_file(path)
    layers: dict[str, dict[str, Any]] = {
        "argument": {
            "backend": backend,
            "model": model,
            "openai_base_url": openai_base_url,
            "ollama_host": ollama_host,
            "timeout_s": timeout_s,
            "threads": threads,
        },
        "environment": {
            "backend": env.get(ENV_BACKEND) or None,
            "model": env.get(ENV_MODEL) or None,
            "openai_base_url": env.get(ENV_OPENAI_BASE_URL) or None,
            "ollama_host": env.get(ENV_OLLAMA_HOST) or None,
            "timeout_s": _env_float(env, ENV_TIMEOUT),
            "threads": _env_int(env, ENV_THREADS),
        },
        "config file": {
            "backend": file.backend,
            "model": file.model,
            "openai_base_url": file.openai.base_url,
            "ollama_host": file.ollama.host,
            "timeout_s": file.timeout_s,
            "threads": file.embedded.threads,
        },
    }
    values: dict[str, Any] = {}
    sources: dict[str, str] = {}
    for level in _LEVELS[:-1]:
        for key, value in layers[level].items():
            if value is not None and key not in values:
                values[key] = value
                sources[key] = f"{level} ({path})" if level == "config file" else level
    backend_level = _level_of(sources.get("backend", "default"))
    if "model" in values and _level_of(sources["model"]) > backend_level:
        # The model was chosen for another backend; let the chosen backend pick its default.
        del values["model"]
        del sources["model"]
    for key in ("backend", "openai_base_url", "timeout_s", "model", "ollama_host", "threads"):
        sources.setdefault(key, "default")
    api_key = env.get(ENV_OPENAI_API_KEY) or None
    try:
        return BackendSettings(**values, openai_api_key=api_key, sources=sources)
    except ValidationError as error:
        raise ConfigError(_describe(error, "settings")) from None


def _level_of(source: str) -> int:
    return next(i for i, level in enumerate(_LEVELS) if source.startswith(level))


def _env_float(env: Mapping[str, str], name: str) -> float | None:
    raw = env.get(name)
    if not raw:
        return None
    try:
        return float(raw)
    except ValueError:
        raise ConfigError(f"{name}={raw!r} is not a number of seconds") from None


def _env_int(env: Mapping[str, str], name: str) -> int | None:
    raw = env.get(name)
    if not raw:
        return None
    try:
        return int(raw)
    except ValueError:
        raise ConfigError(f"{name}={raw!r} is not a whole number") from None


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
        raise ConfigError(_describe(error, f"config file {path}")) from None


def _describe(error: ValidationError, where: str) -> str:
    allowed = "backend, model, timeout_s, [openai] base_url, [ollama] host, [embedded] threads"
    problems = "; ".join(f"{'.'.join(str(p) for p in e['loc']) or '(top)'}: {e['msg']}" for e in error.errors())
    return f"{where} is invalid ({problems}); allowed keys: {allowed}"
