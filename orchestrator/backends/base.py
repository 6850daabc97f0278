"""The one interface every LLM backend implements: chat with an optional JSON Schema."""

from __future__ import annotations

import inspect
from abc import ABC, abstractmethod
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, ClassVar, Literal, TypedDict

from .errors import InvalidRequest

Role = Literal["system", "user", "assistant"]
ROLES: tuple[Role, ...] = ("system", "user", "assistant")

# Enough for the managers' JSON answers (a plan of a few tool calls) without letting a
# runaway model spin for minutes.
DEFAULT_MAX_TOKENS = 512
# A generous bound for one answer from a 7–9B model on a laptop CPU; callers pass less.
DEFAULT_TIMEOUT_S = 120.0


class Message(TypedDict):
    """One chat turn as every backend receives it."""

    role: Role
    content: str


@dataclass(frozen=True)
class ChatResult:
    """What one chat call produced, with its cost.

    `data` is the parsed JSON when a schema was given (already checked against it), else None.
    `latency_s` is wall-clock seconds for the whole call, as the user would feel it.
    """

    text: str
    prompt_tokens: int
    completion_tokens: int
    latency_s: float
    model: str
    backend: str
    finish_reason: str = "stop"
    data: Any = None


@dataclass(frozen=True)
class BackendInfo:
    """What a backend runs: for reports and `drivetwin backends list`."""

    backend: str
    model: str
    path: str | None = None
    size_bytes: int | None = None
    parameters: int | None = None
    quantisation: str | None = None
    context_length: int | None = None
    detail: str = ""


@dataclass(frozen=True)
class BackendStatus:
    """Whether one backend/model pair can answer right now, and the one command that fixes it."""

    backend: str
    model: str
    usable: bool
    fix: str | None = None
    detail: str = ""


class Backend(ABC):
    """A chat model behind one interface; subclasses are found through entry points.

    Subclasses take `model` (a preset name or a backend-specific model id) and keyword
    options, and never let a library exception escape: every failure is a BackendError.
    """

    name: ClassVar[str]
    default_model: ClassVar[str | None] = None
    # Preset name -> the backend's own model id (or a description for embedded models).
    presets: ClassVar[Mapping[str, str]] = {}

    model: str

    def __init__(self, model: str | None = None, **options: Any) -> None:
        """Take a preset name or backend-specific model id (None: the default) and options."""
        self.model = model or self.default_model or ""

    @abstractmethod
    def chat(
        self,
        messages: Sequence[Message],
        *,
        schema: Mapping[str, Any] | None = None,
        temperature: float = 0.0,
        seed: int | None = 0,
        max_tokens: int = DEFAULT_MAX_TOKENS,
        timeout_s: float | None = None,
    ) -> ChatResult:
        """Answer the conversation; with `schema`, the text is JSON that matches it."""

    @abstractmethod
    def describe(self) -> BackendInfo:
        """Say what model this backend runs (path, size on disk, parameters, quantisation)."""

    @classmethod
    @abstractmethod
    def statuses(cls, **options: Any) -> list[BackendStatus]:
        """Say, cheaply and without raising, which of this backend's models are usable now."""

    @classmethod
    def option_names(cls) -> list[str]:
        """The keyword options this backend's constructor accepts, besides `model`."""
        params = inspect.signature(cls.__init__).parameters.values()
        return [p.name for p in params if p.kind is inspect.Parameter.KEYWORD_ONLY and p.name not in ("self", "model")]


def check_request(messages: Sequence[Message], *, max_tokens: int, temperature: float, backend: str) -> list[Message]:
    """Validate a chat request before any backend spends time on it."""
    if not messages:
        raise InvalidRequest("messages is empty; give at least one user message", backend=backend)
    checked: list[Message] = []
    for index, message in enumerate(messages):
        role = message.get("role") if isinstance(message, Mapping) else None
        content = message.get("content") if isinstance(message, Mapping) else None
        if role not in ROLES:
            raise InvalidRequest(
                f"messages[{index}].role is {role!r}; allowed: {', '.join(ROLES)}",
                backend=backend,
            )
        if not isinstance(content, str):
            raise InvalidRequest(
                f"messages[{index}].content must be a string, got {type(content).__name__}",
                backend=backend,
            )
        checked.append(Message(role=role, content=content))
    if max_tokens < 1:
        raise InvalidRequest(f"max_tokens is {max_tokens}; it must be at least 1", backend=backend)
    if not 0.0 <= temperature <= 2.0:
        raise InvalidRequest(f"temperature is {temperature}; allowed: 0.0 to 2.0", backend=backend)
    return checked
