"""Any OpenAI-compatible server (llama.cpp's server, vLLM, LM Studio, Ollama's /v1) via httpx."""

from __future__ import annotations

import json
from collections.abc import Mapping
from typing import Any, Literal

import httpx

from .base import DEFAULT_TIMEOUT_S, Backend, BackendInfo, BackendStatus, Completion, CompletionRequest
from .errors import BackendError, BackendTimeout, BackendUnavailable, ConnectionDropped, InvalidOutput

NAME = "openai"
DEFAULT_BASE_URL = "http://127.0.0.1:8080/v1"
SERVE_FIX = "python -m llama_cpp.server --model MODEL.gguf --port 8080"
WHERE_HINT = "start one, or set DRIVETWIN_OPENAI_BASE_URL to your server's /v1 address"
KEY_FIX = "set DRIVETWIN_OPENAI_API_KEY to the server's API key"
STATUS_TIMEOUT_S = 2.0
HTTP_UNAUTHORIZED = 401
HTTP_NOT_FOUND = 404
# Servers that reject `json_schema` answer with one of these and a message naming the field;
# llama-cpp-python's server reports its request-validation errors as 500.
SCHEMA_REFUSAL_CODES = (400, 422, 500)
# How much of an HTTP error body to quote.
BODY_QUOTE_CHARS = 300

SchemaMode = Literal["auto", "json_schema", "json_object"]


class OpenAIBackend(Backend):
    """Chat completions over HTTP; the schema goes in `response_format`.

    `schema_mode="auto"` sends OpenAI's `{"type": "json_schema", ...}` first and, if the
    server refuses it (llama-cpp-python's server only knows `json_object` with a `schema`),
    falls back to `{"type": "json_object", "schema": ...}` for the rest of this backend's life.
    """

    name = NAME
    default_model = None  # whatever the server serves first

    def __init__(
        self,
        model: str | None = None,
        *,
        base_url: str = DEFAULT_BASE_URL,
        api_key: str | None = None,
        timeout_s: float | None = DEFAULT_TIMEOUT_S,
        schema_mode: SchemaMode = "auto",
    ) -> None:
        self._base_url = base_url.rstrip("/")
        self._headers = {"Authorization": f"Bearer {api_key}"} if api_key else {}
        self.timeout_s = timeout_s
        self._schema_mode: SchemaMode = schema_mode
        self._requested_model = model
        self.model = model or ""

    def _served_models(self, timeout_s: float | None) -> list[str]:
        body = self._request("GET", "/models", None, timeout_s)
        try:
            return [str(entry["id"]) for entry in body["data"]]
        except (KeyError, TypeError):
            raise InvalidOutput(
                f"{self._base_url}/models did not list models the OpenAI way",
                raw=json.dumps(body)[:BODY_QUOTE_CHARS],
                reason="not_json",
                backend=NAME,
                model=self.model,
            ) from None

    def _resolve_model(self, timeout_s: float | None) -> str:
        if not self.model:
            served = self._served_models(timeout_s)
            if not served:
                raise BackendUnavailable(f"the server at {self._base_url} serves no model", fix=SERVE_FIX, backend=NAME)
            self.model = served[0]
        return self.model

    def complete(self, request: CompletionRequest) -> Completion:
        """POST one non-streamed `/chat/completions` request."""
        payload: dict[str, Any] = {
            "model": self._resolve_model(request.timeout_s),
            "messages": [dict(m) for m in request.messages],
            "temperature": request.temperature,
            "max_tokens": request.max_tokens,
            "stream": False,
        }
        if request.seed is not None:
            payload["seed"] = request.seed
        body = self._complete(payload, request.schema, request.timeout_s)
        try:
            choice = body["choices"][0]
            text = choice["message"]["content"] or ""
            finish_reason = str(choice.get("finish_reason") or "stop")
            usage = body.get("usage") or {}
        except (KeyError, IndexError, TypeError):
            raise InvalidOutput(
                f"the server at {self._base_url} answered without choices[0].message.content",
                raw=json.dumps(body)[:BODY_QUOTE_CHARS],
                reason="not_json",
                backend=NAME,
                model=self.model,
            ) from None
        return Completion(
            str(text),
            finish_reason,
            _token_count(usage, "prompt_tokens"),
            _token_count(usage, "completion_tokens"),
        )

    def _complete(self, payload: dict[str, Any], schema: Mapping[str, Any] | None, timeout_s: float | None) -> Any:
        if schema is None:
            return self._request("POST", "/chat/completions", payload, timeout_s)
        mode = "json_schema" if self._schema_mode == "auto" else self._schema_mode
        payload["response_format"] = _response_format(mode, schema)
        try:
            return self._request("POST", "/chat/completions", payload, timeout_s)
        except _Refused as refusal:
            if self._schema_mode != "auto":
                raise refusal.error from None
        # Only once: the fallback is remembered, and a refused fallback is reported as is.
        self._schema_mode = "json_object"
        payload["response_format"] = _response_format("json_object", schema)
        try:
            return self._request("POST", "/chat/completions", payload, timeout_s)
        except _Refused as refusal:
            raise refusal.error from None

    def _request(self, method: str, path: str, payload: Mapping[str, Any] | None, timeout_s: float | None) -> Any:
        """One HTTP exchange; every transport or protocol failure becomes a BackendError."""
        url = f"{self._base_url}{path}"
        try:
            response = httpx.request(method, url, json=payload, headers=self._headers, timeout=timeout_s)
        except httpx.ConnectError:
            raise BackendUnavailable(
                f"no OpenAI-compatible server answers at {self._base_url} ({WHERE_HINT})",
                fix=SERVE_FIX,
                backend=NAME,
                model=self.model,
            ) from None
        except httpx.TimeoutException:
            raise BackendTimeout(
                f"{NAME}/{self.model or '?'} at {self._base_url} did not answer within {timeout_s:g} s",
                timeout_s=timeout_s or 0.0,
                backend=NAME,
                model=self.model,
            ) from None
        except (httpx.RemoteProtocolError, httpx.ReadError, httpx.WriteError) as error:
            raise ConnectionDropped(
                f"the connection to {url} broke before a whole reply came back: {error}",
                backend=NAME,
                model=self.model,
            ) from None
        except httpx.HTTPError as error:
            raise BackendUnavailable(
                f"could not talk to {url}: {error}", fix=SERVE_FIX, backend=NAME, model=self.model
            ) from None
        if response.status_code >= 400:
            self._raise_for_status(response, payload)
        try:
            return response.json()
        except (json.JSONDecodeError, UnicodeDecodeError):
            raise InvalidOutput(
                f"{url} did not answer with JSON (HTTP {response.status_code}, "
                f"{response.headers.get('content-type', 'no content type')}); is "
                "DRIVETWIN_OPENAI_BASE_URL an OpenAI-compatible /v1 address?",
                raw=response.text,
                reason="not_json",
                backend=NAME,
                model=self.model,
            ) from None

    def _raise_for_status(self, response: httpx.Response, payload: Mapping[str, Any] | None) -> None:
        status, text = response.status_code, response.text[:BODY_QUOTE_CHARS]
        error: BackendError
        if status == HTTP_UNAUTHORIZED:
            error = BackendUnavailable(
                f"{self._base_url} refused the API key (HTTP 401)",
                fix=KEY_FIX,
                backend=NAME,
                model=self.model,
            )
        elif status == HTTP_NOT_FOUND and "model" in text.lower():
            error = BackendUnavailable(
                f"{self._base_url} does not serve model {self.model!r}: {text}",
                fix="pass --model with one of the ids that GET /v1/models lists",
                backend=NAME,
                model=self.model,
            )
        else:
            error = BackendError(
                f"{response.request.url} answered HTTP {status}: {text}",
                backend=NAME,
                model=self.model,
            )
        refused_schema = (
            payload is not None
            and "response_format" in payload
            and status in SCHEMA_REFUSAL_CODES
            and ("response_format" in response.text or "json_schema" in response.text)
        )
        if refused_schema:
            raise _Refused(error)
        raise error

    def describe(self) -> BackendInfo:
        """The served model id; sizes are not part of the OpenAI API."""
        model = self._resolve_model(self.timeout_s)
        return BackendInfo(backend=NAME, model=model, detail=f"served by {self._base_url}")

    @classmethod
    def statuses(cls, **options: Any) -> list[BackendStatus]:
        """One row per model the configured server lists, or one unusable row if it is down."""
        base_url = str(options.get("base_url") or DEFAULT_BASE_URL)
        backend = cls(base_url=base_url, api_key=options.get("api_key"))
        try:
            served = backend._served_models(STATUS_TIMEOUT_S)
        except BackendError as error:
            fix = error.fix if isinstance(error, BackendUnavailable) else SERVE_FIX
            return [BackendStatus(NAME, "(any served model)", False, fix, error.message)]
        return [BackendStatus(NAME, m, True, None, f"served by {base_url}") for m in served]


class _Refused(Exception):
    """The server rejected the `response_format` shape; carries the error to raise otherwise."""

    def __init__(self, error: BackendError) -> None:
        super().__init__(error.message)
        self.error = error


def _response_format(mode: str, schema: Mapping[str, Any]) -> dict[str, Any]:
    if mode == "json_object":
        return {"type": "json_object", "schema": dict(schema)}
    return {
        "type": "json_schema",
        "json_schema": {"name": "answer", "schema": dict(schema), "strict": True},
    }


def _token_count(usage: object, key: str) -> int:
    """A token count from the answer's `usage`; 0 when the server sent none or nonsense."""
    value = usage.get(key) if isinstance(usage, dict) else None
    return value if isinstance(value, int) and not isinstance(value, bool) and value >= 0 else 0
