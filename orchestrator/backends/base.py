"""The one interface every LLM backend implements: chat with an optional JSON Schema.

`Backend.chat` is written once, here: it checks the request, holds the whole-call deadline,
retries a dropped connection, times the call, checks the answer against the schema, and
logs the request and answer (drivetwin.orchestrator.logs). A backend implements only
`complete`: one request to its model, one raw answer back.
"""

from __future__ import annotations

import inspect
import time
from abc import ABC, abstractmethod
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, ClassVar, Literal, TypedDict

from drivetwin.orchestrator import logs
from drivetwin.tools.deadline import DeadlineExceeded, call_within

from .errors import BackendError, BackendTimeout, BackendUnavailable, ConnectionDropped, InvalidRequest

Role = Literal["system", "user", "assistant"]
ROLES: tuple[Role, ...] = ("system", "user", "assistant")

# Enough for the managers' JSON answers (a plan of a few tool calls) without letting a
# runaway model spin for minutes.
DEFAULT_MAX_TOKENS = 512
# A generous bound for one answer from a 7–9B model on a laptop CPU; callers pass less.
DEFAULT_TIMEOUT_S = 120.0
# A dropped connection (a server restarting, a proxy closing idle sockets) is tried again this
# many times, waiting RETRY_BACKOFF_S, then twice that...; timeouts and refusals never are.
TRANSPORT_RETRIES = 2
RETRY_BACKOFF_S = 0.25


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
class CompletionRequest:
    """One checked request, as `Backend.complete` receives it."""

    messages: list[Message]
    schema: Mapping[str, Any] | None
    temperature: float
    seed: int | None
    max_tokens: int
    # The whole call's limit; a backend passes it on as its client's own (per-read) timeout.
    timeout_s: float | None


@dataclass(frozen=True)
class Completion:
    """A model's raw answer to one request, before the schema check."""

    text: str
    finish_reason: str = "stop"
    prompt_tokens: int = 0
    completion_tokens: int = 0


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

    # True for a backend that stops its own generation at the deadline (in-process llama.cpp:
    # an abandoned thread would keep the model's lock and the CPU), so chat() does not abandon it.
    stops_at_deadline: ClassVar[bool] = False

    model: str
    # The limit of a call that gives none; subclasses set it from their `timeout_s` option.
    timeout_s: float | None = DEFAULT_TIMEOUT_S

    def __init__(self, model: str | None = None, **options: Any) -> None:
        """Take a preset name or backend-specific model id (None: the default) and options."""
        self.model = model or self.default_model or ""

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
        """Answer the conversation; with `schema`, the text is JSON that matches it.

        Every failure is a BackendError; the request and its answer (or error) are logged.
        """
        # structured.py builds ChatResults (defined here): imported at call time.
        from drivetwin.orchestrator.backends.structured import answer_result, check_schema

        checked = check_request(messages, max_tokens=max_tokens, temperature=temperature, backend=self.name)
        if schema is not None:
            check_schema(schema, backend=self.name)
        limit = timeout_s if timeout_s is not None else self.timeout_s
        request = CompletionRequest(checked, schema, temperature, seed, max_tokens, limit)
        self.prepare()
        start = time.perf_counter()
        attempts = 0
        try:
            completion, attempts = self._complete_within(request, start)
            result = answer_result(
                completion.text, schema, finish_reason=completion.finish_reason, max_tokens=max_tokens,
                prompt_tokens=completion.prompt_tokens, completion_tokens=completion.completion_tokens,
                latency_s=time.perf_counter() - start, backend=self.name, model=self.model,
            )
        except BackendError as error:
            logs.record_exchange(self.name, self.model, request, None, error, attempts, time.perf_counter() - start)
            raise
        logs.record_exchange(self.name, self.model, request, result, None, attempts, result.latency_s)
        return result

    def _complete_within(self, request: CompletionRequest, start: float) -> tuple[Completion, int]:
        """`complete`, under the whole-call deadline, tried again after a dropped connection."""
        limit = request.timeout_s
        attempt = 1
        while True:
            left = None if limit is None else max(0.0, limit - (time.perf_counter() - start))
            try:
                if self.stops_at_deadline or left is None:
                    return self.complete(request), attempt
                # A client's own timeout counts per read (a server dripping a byte every few
                # seconds never trips it); this deadline counts for the whole call.
                return call_within(lambda: self.complete(request), left, f"{self.name} request"), attempt
            except DeadlineExceeded:
                raise BackendTimeout(
                    f"{self.name}/{self.model or '?'} did not answer within {limit:g} s",
                    timeout_s=limit or 0.0, backend=self.name, model=self.model,
                ) from None
            except ConnectionDropped as dropped:
                wait = RETRY_BACKOFF_S * 2 ** (attempt - 1)
                out_of_time = limit is not None and time.perf_counter() - start + wait >= limit
                if attempt > TRANSPORT_RETRIES or out_of_time:
                    dropped.args = (f"{dropped.message} (after {attempt} attempt(s))",)
                    raise
                time.sleep(wait)
                attempt += 1

    def prepare(self) -> None:  # noqa: B027 - an optional hook, not an abstract method
        """Get ready for a first answer (load a model file) before the call is timed; by default nothing."""

    def log_likelihoods(self, texts: Sequence[str]) -> list[float]:
        """The natural-log probability the model gives each text, read from its start to an end
        of text: how likely a sentence is, to choose between spellings of one request
        (planning/llm/respell.py). Only an in-process model can answer cheaply; the others raise
        BackendUnavailable, and callers plan without it."""
        raise BackendUnavailable(f"the {self.name} backend cannot score text", backend=self.name)

    @abstractmethod
    def complete(self, request: CompletionRequest) -> Completion:
        """Send one checked request to the model and return its raw answer.

        Raise a BackendError for every failure, ConnectionDropped when the connection broke
        before a whole answer came back (chat() tries again).
        """

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
