"""The user's own Ollama server, through the official `ollama` client (`/api/chat`)."""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Mapping
from typing import Any, ClassVar

import httpx
import pydantic

from .base import DEFAULT_TIMEOUT_S, Backend, BackendInfo, BackendStatus, Completion, CompletionRequest
from .errors import BackendError, BackendTimeout, BackendUnavailable, ConnectionDropped, InvalidOutput

NAME = "ollama"
OLLAMA_INSTALL = "pip install 'ollama>=0.4'"
DEFAULT_HOST = "http://127.0.0.1:11434"
SERVE_FIX = "ollama serve"
WHERE_HINT = "start one, or set DRIVETWIN_OLLAMA_HOST to where it runs"
# `backends list` must stay snappy even when the host is a dead address.
STATUS_TIMEOUT_S = 2.0
HTTP_NOT_FOUND = 404

# The models the paper compares (Samak et al.), by the tags Ollama publishes them under.
PRESETS: dict[str, str] = {
    "mistral": "mistral:7b-instruct-v0.2",
    "llama3.1": "llama3.1:8b",
    "gemma2": "gemma2:9b",
}


def _tag(model: str) -> str:
    """Ollama treats a name without a tag as `name:latest`."""
    return model if ":" in model else f"{model}:latest"


class OllamaBackend(Backend):
    """Chat through an Ollama server; the schema goes in `format`, so the server constrains it."""

    name = NAME
    # The paper's best model: 84.93 % generalizability.
    default_model = "gemma2"
    presets: ClassVar[Mapping[str, str]] = PRESETS

    def __init__(
        self,
        model: str | None = None,
        *,
        host: str | None = None,
        timeout_s: float | None = DEFAULT_TIMEOUT_S,
        keep_alive: str | None = None,
    ) -> None:
        requested = model or self.default_model or ""
        # A preset name maps to the paper's tag; anything else is an Ollama model name as is.
        self.model = PRESETS.get(requested, requested)
        self._host = host
        self.timeout_s = timeout_s
        self._keep_alive = keep_alive

    def _client(self, timeout_s: float | None) -> Any:
        try:
            import ollama
        except ImportError:
            raise BackendUnavailable("the ollama client is not installed", fix=OLLAMA_INSTALL, backend=NAME) from None
        return ollama.Client(host=self._host, timeout=timeout_s)

    @property
    def host(self) -> str:
        """The server address in use: configured, else OLLAMA_HOST, else the client default."""
        return self._host or os.environ.get("OLLAMA_HOST") or DEFAULT_HOST

    def complete(self, request: CompletionRequest) -> Completion:
        """Ask the server's `/api/chat` for one non-streamed answer; the schema goes in `format`."""
        options: dict[str, Any] = {"temperature": request.temperature, "num_predict": request.max_tokens}
        if request.seed is not None:
            options["seed"] = request.seed
        schema = request.schema
        with self._client(request.timeout_s) as client:
            response = self._call(
                lambda: client.chat(
                    model=self.model,
                    messages=[dict(m) for m in request.messages],
                    format=dict(schema) if schema is not None else None,
                    options=options,
                    stream=False,
                    keep_alive=self._keep_alive,
                ),
                request.timeout_s,
            )
        return Completion(
            response.message.content or "",
            response.done_reason or "stop",
            response.prompt_eval_count or 0,
            response.eval_count or 0,
        )

    def _call(self, request: Callable[[], Any], timeout_s: float | None) -> Any:
        """Run one client call, turning every client/transport failure into a BackendError."""
        import ollama

        try:
            return request()
        except ConnectionError:
            # The client turns httpx.ConnectError into a bare ConnectionError.
            raise BackendUnavailable(
                f"no Ollama server answers at {self.host} ({WHERE_HINT})",
                fix=SERVE_FIX,
                backend=NAME,
                model=self.model,
            ) from None
        except httpx.TimeoutException:
            raise BackendTimeout(
                f"{NAME}/{self.model} did not answer within {timeout_s:g} s",
                timeout_s=timeout_s or 0.0,
                backend=NAME,
                model=self.model,
            ) from None
        except ollama.ResponseError as error:
            if error.status_code == HTTP_NOT_FOUND:
                raise BackendUnavailable(
                    f"the Ollama server at {self.host} has no model {self.model!r} "
                    f"({error.error}); presets: " + ", ".join(f"{k} = {v}" for k, v in PRESETS.items()),
                    fix=f"ollama pull {self.model}",
                    backend=NAME,
                    model=self.model,
                ) from None
            raise BackendError(
                f"the Ollama server refused the request (HTTP {error.status_code}): {error.error}",
                backend=NAME,
                model=self.model,
            ) from None
        except (httpx.RemoteProtocolError, httpx.ReadError, httpx.WriteError) as error:
            raise ConnectionDropped(
                f"the connection to the Ollama server at {self.host} broke before a whole reply came back: {error}",
                backend=NAME,
                model=self.model,
            ) from None
        except (json.JSONDecodeError, pydantic.ValidationError) as error:
            raise InvalidOutput(
                f"the server at {self.host} did not answer with Ollama's JSON ({error}); "
                "is DRIVETWIN_OLLAMA_HOST pointing at an Ollama server?",
                raw=getattr(error, "doc", ""),
                reason="not_json",
                backend=NAME,
                model=self.model,
            ) from None
        except httpx.HTTPError as error:
            raise BackendUnavailable(
                f"could not talk to the Ollama server at {self.host}: {error}",
                fix=SERVE_FIX,
                backend=NAME,
                model=self.model,
            ) from None

    def describe(self) -> BackendInfo:
        """The model's size, parameter count and quantisation as the server reports them."""
        with self._client(self.timeout_s) as client:
            shown = self._call(lambda: client.show(self.model), self.timeout_s)
            listed = self._call(client.list, self.timeout_s)
        size = next((int(m.size) for m in listed.models if m.model == _tag(self.model) and m.size), None)
        details = shown.details
        info: Mapping[str, Any] = shown.modelinfo or {}
        architecture = info.get("general.architecture", "")
        parameters = info.get("general.parameter_count")
        context = info.get(f"{architecture}.context_length")
        return BackendInfo(
            backend=NAME,
            model=self.model,
            path=None,
            size_bytes=size,
            parameters=int(parameters) if parameters else None,
            quantisation=details.quantization_level if details else None,
            context_length=int(context) if context else None,
            detail=(f"{details.family} {details.parameter_size} on {self.host}" if details else self.host),
        )

    @classmethod
    def statuses(cls, **options: Any) -> list[BackendStatus]:
        """A row per preset (and per other pulled model), from the server's model list."""
        backend = cls(host=options.get("host"), timeout_s=STATUS_TIMEOUT_S)
        try:
            with backend._client(STATUS_TIMEOUT_S) as client:
                listed = backend._call(client.list, STATUS_TIMEOUT_S)
        except BackendError as error:
            fix = error.fix if isinstance(error, BackendUnavailable) else SERVE_FIX
            return [BackendStatus(NAME, tag, False, fix, error.message) for tag in PRESETS.values()]
        pulled = [str(m.model) for m in listed.models if m.model]
        rows = [
            BackendStatus(NAME, tag, True, None, f"preset {name}")
            if _tag(tag) in pulled
            else BackendStatus(NAME, tag, False, f"ollama pull {tag}", f"preset {name}")
            for name, tag in PRESETS.items()
        ]
        presets = {_tag(tag) for tag in PRESETS.values()}
        rows += [BackendStatus(NAME, m, True, None, "pulled") for m in pulled if m not in presets]
        return rows
