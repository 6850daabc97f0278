"""Typed errors every LLM backend raises, so callers never see a library traceback."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Literal

InvalidOutputReason = Literal["truncated", "not_json", "schema_mismatch", "empty"]


class BackendError(Exception):
    """Base of every error a backend raises; the message says what went wrong and what to do."""

    def __init__(self, message: str, *, backend: str = "", model: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.backend = backend
        self.model = model


class BackendUnavailable(BackendError):
    """The backend cannot answer now: server down, model or package missing.

    `fix` is the one command (or setting) that makes it usable.
    """

    def __init__(self, message: str, *, fix: str | None = None, backend: str = "", model: str = "") -> None:
        super().__init__(message, backend=backend, model=model)
        # `message` stays the bare problem (for tables); str(error) adds the fix.
        self.args = (f"{message}; fix: {fix}" if fix else message,)
        self.fix = fix


class BackendTimeout(BackendError):
    """The backend did not finish within the time allowed; `partial_text` is what arrived."""

    def __init__(
        self,
        message: str,
        *,
        timeout_s: float,
        partial_text: str = "",
        backend: str = "",
        model: str = "",
    ) -> None:
        super().__init__(message, backend=backend, model=model)
        self.timeout_s = timeout_s
        self.partial_text = partial_text


class InvalidOutput(BackendError):
    """The model's answer is unusable: cut off, not JSON, or not matching the schema.

    `raw` is the model's text exactly as it came back, for logs and retry prompts.
    """

    def __init__(
        self,
        message: str,
        *,
        raw: str,
        reason: InvalidOutputReason,
        backend: str = "",
        model: str = "",
    ) -> None:
        super().__init__(message, backend=backend, model=model)
        self.raw = raw
        self.reason: InvalidOutputReason = reason


class ConnectionDropped(InvalidOutput):
    """The connection broke before a whole answer arrived (reset, closed, cut off mid-reply).

    The one failure `Backend.chat` retries: the request may well succeed on a new connection.
    """

    def __init__(self, message: str, *, backend: str = "", model: str = "") -> None:
        super().__init__(message, raw="", reason="truncated", backend=backend, model=model)


class InvalidRequest(BackendError):
    """The caller asked for something no backend can do (bad role, bad schema, bad option)."""


class UnknownModel(BackendError):
    """The model name is neither a preset nor something the backend can resolve."""

    def __init__(self, message: str, *, presets: Sequence[str], backend: str = "", model: str = "") -> None:
        super().__init__(message, backend=backend, model=model)
        self.presets = tuple(presets)


class UnknownBackend(BackendError):
    """No backend plugin of that name is installed."""

    def __init__(self, name: str, available: Sequence[str]) -> None:
        names = ", ".join(sorted(available)) or "none"
        super().__init__(f"unknown backend {name!r}; available: {names}", backend=name)
        self.available = tuple(sorted(available))
