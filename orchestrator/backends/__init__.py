"""LLM backends: one chat interface over llama.cpp in-process, Ollama and OpenAI-style servers.

from drivetwin.orchestrator.backends import load_backend
backend = load_backend("embedded", "smollm2-135m")
result = backend.chat([{"role": "user", "content": "Make it rain."}], schema=WEATHER_SCHEMA)
result.data  # parsed JSON, already checked against WEATHER_SCHEMA
"""

from .base import (
    DEFAULT_MAX_TOKENS,
    DEFAULT_TIMEOUT_S,
    Backend,
    BackendInfo,
    BackendStatus,
    ChatResult,
    Message,
)
from .errors import (
    BackendError,
    BackendTimeout,
    BackendUnavailable,
    InvalidOutput,
    InvalidRequest,
    UnknownBackend,
    UnknownModel,
)
from .registry import (
    PluginProblem,
    backend_names,
    backends_table,
    list_backends,
    load_backend,
    open_backend,
    plugin_problems,
)

__all__ = [
    "DEFAULT_MAX_TOKENS",
    "DEFAULT_TIMEOUT_S",
    "Backend",
    "BackendError",
    "BackendInfo",
    "BackendStatus",
    "BackendTimeout",
    "BackendUnavailable",
    "ChatResult",
    "InvalidOutput",
    "InvalidRequest",
    "Message",
    "PluginProblem",
    "UnknownBackend",
    "UnknownModel",
    "backend_names",
    "backends_table",
    "list_backends",
    "load_backend",
    "open_backend",
    "plugin_problems",
]
