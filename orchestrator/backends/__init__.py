"""LLM backends: one chat interface over llama.cpp in-process, Ollama and OpenAI-style servers.

from drivetwin.orchestrator.backends import load_backend
backend = load_backend("embedded", "smollm2-135m")
result = backend.chat([{"role": "user", "content": "Make it rain."}], schema=WEATHER_SCHEMA)
result.data  # parsed JSON, already checked against WEATHER_SCHEMA

A backend (built in or a plugin) subclasses Backend and implements `complete` (one request,
one raw answer), `describe` and `statuses`; Backend.chat does the rest.
"""

from drivetwin.tools.plugins import PluginProblem

from .base import (
    DEFAULT_MAX_TOKENS,
    DEFAULT_TIMEOUT_S,
    Backend,
    BackendInfo,
    BackendStatus,
    ChatResult,
    Completion,
    CompletionRequest,
    Message,
)
from .errors import (
    BackendError,
    BackendTimeout,
    BackendUnavailable,
    ConnectionDropped,
    InvalidOutput,
    InvalidRequest,
    UnknownBackend,
    UnknownModel,
)
from .registry import (
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
    "Completion",
    "CompletionRequest",
    "ConnectionDropped",
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
