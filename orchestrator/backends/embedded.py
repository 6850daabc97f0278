"""The default backend: llama.cpp in-process, with decoding constrained by the JSON Schema."""

from __future__ import annotations

import atexit
import functools
import json
import os
import threading
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from .base import DEFAULT_TIMEOUT_S, Backend, BackendInfo, BackendStatus, Completion, CompletionRequest, Message
from .errors import BackendError, BackendTimeout, BackendUnavailable, InvalidRequest
from .gguf_models import SHIPPED_MODELS, is_installed, resolve_gguf

if TYPE_CHECKING:
    from llama_cpp import Llama

NAME = "embedded"
# Room for the managers' ~3k-token prompts (scene summary, catalog, memory) plus the answer.
DEFAULT_N_CTX = 4096
LLAMA_INSTALL = "pip install 'llama-cpp-python==0.3.36'"
# One per tool schema plus the Sr. manager's; more than the project has.
GRAMMAR_CACHE_SIZE = 64

# Used only when a GGUF carries no chat template (the shipped Gemma 3 270M base has none).
# Gemma has no system role: its own template folds the system text into the first user turn.
GEMMA_TEMPLATE = (
    "{{ bos_token }}{% for m in messages %}<start_of_turn>"
    "{{ 'model' if m['role'] == 'assistant' else 'user' }}\n{{ m['content'] }}<end_of_turn>\n"
    "{% endfor %}<start_of_turn>model\n"
)
GEMMA_STOP = "<end_of_turn>"
CHATML_TEMPLATE = (
    "{% for m in messages %}<|im_start|>{{ m['role'] }}\n{{ m['content'] }}<|im_end|>\n"
    "{% endfor %}<|im_start|>assistant\n"
)
CHATML_STOP = "<|im_end|>"


@dataclass
class _LoadedModel:
    """One GGUF loaded once per process; the lock serialises use of its single context."""

    llama: Llama
    path: Path
    load_s: float
    lock: threading.Lock = field(default_factory=threading.Lock)


# Model states kept for prompt-prefix reuse, per loaded model (least recently used go first).
PROMPT_CACHE_BYTES = 1 << 30
_LOADED: dict[tuple[Path, int, bool], _LoadedModel] = {}
# Scoring reads short requests; it keeps every position's logits (logits_all), so a second
# llama.cpp context of the same GGUF (its weights are memory-mapped once) does it.
SCORING_N_CTX = 256
_LOADED_LOCK = threading.Lock()


def _load(path: Path, n_ctx: int, n_threads: int, model: str, scoring: bool = False) -> _LoadedModel:
    key = (path, n_ctx, scoring)
    with _LOADED_LOCK:
        if key in _LOADED:
            return _LOADED[key]
        try:
            from llama_cpp import Llama
        except ImportError:
            raise BackendUnavailable(
                "llama-cpp-python is not installed", fix=LLAMA_INSTALL, backend=NAME, model=model
            ) from None
        start = time.perf_counter()
        try:
            llama = Llama(
                model_path=str(path),
                n_ctx=n_ctx,
                n_threads=n_threads,
                n_threads_batch=n_threads,  # else prompt reading takes every CPU regardless
                logits_all=scoring,
                verbose=False,
            )
        except (ValueError, RuntimeError, OSError) as error:
            raise BackendUnavailable(
                f"llama.cpp could not load {path}: {error}",
                fix="give a valid GGUF file, or a preset: " + ", ".join(SHIPPED_MODELS),
                backend=NAME,
                model=model,
            ) from None
        # The managers' prompts share long prefixes (instructions, catalog, examples): keeping
        # the model state after each prompt and restarting from the longest matching one cut
        # SmolLM2's median time per planned prompt from 6.8 s to 1.6 s on 2 cores
        # (bench_planners). Sliding-window models (Gemma 3) save their whole window with each
        # state and cannot restart mid-window: there the cache made Gemma slower (5.7 -> 8.8 s).
        if not scoring and not any(key.endswith(".attention.sliding_window") for key in llama.metadata):
            from llama_cpp.llama_cache import LlamaRAMCache

            llama.set_cache(LlamaRAMCache(capacity_bytes=PROMPT_CACHE_BYTES))
        # Free the model while the interpreter is whole: left to garbage collection at exit,
        # llama-cpp-python's finaliser runs after its C bindings are gone and prints a TypeError.
        atexit.register(llama.close)
        loaded = _LoadedModel(llama=llama, path=path, load_s=time.perf_counter() - start)
        _LOADED[key] = loaded
        return loaded


def default_threads() -> int:
    """llama.cpp threads: one per physical core, taken as half the logical CPUs.

    Hyper-threads do not speed llama.cpp up, and its threads spin while they wait, so using
    every logical CPU on a shared machine is ruinous: on 2 busy cores SmolLM2 took a median
    9.3 s per answer with 2 threads and 0.95 s with 1 (llama-cpp-python's own default rule).
    """
    return max(1, (os.cpu_count() or 2) // 2)


class _Deadline:
    """A llama.cpp stopping criterion that ends generation when time is up."""

    def __init__(self, timeout_s: float) -> None:
        self.timeout_s = timeout_s
        self.end = time.perf_counter() + timeout_s
        self.expired = False

    def __call__(self, tokens: Any, logits: Any) -> bool:
        if time.perf_counter() >= self.end:
            self.expired = True
        return self.expired


class EmbeddedBackend(Backend):
    """llama-cpp-python in-process, running a shipped GGUF preset or any local GGUF file.

    Options: `n_ctx` (context tokens), `n_threads` (default: `default_threads()`),
    `timeout_s` (default per call). A GGUF is loaded once per process and context size; the
    first load's thread count is the one that stays.
    """

    name = NAME
    default_model = "smollm2-135m"
    stops_at_deadline = True
    presets: ClassVar[Mapping[str, str]] = {m.name: m.description for m in SHIPPED_MODELS.values()}

    def __init__(
        self,
        model: str | None = None,
        *,
        n_ctx: int = DEFAULT_N_CTX,
        n_threads: int | None = None,
        timeout_s: float | None = DEFAULT_TIMEOUT_S,
    ) -> None:
        requested = model or self.default_model or ""
        self.model, self._path = resolve_gguf(requested)
        self._n_ctx = n_ctx
        self._n_threads = n_threads or default_threads()
        self.timeout_s = timeout_s

    def _loaded(self) -> _LoadedModel:
        return _load(self._path, self._n_ctx, self._n_threads, self.model)

    @property
    def load_s(self) -> float:
        """Seconds it took to load this model's GGUF (once per process)."""
        return self._loaded().load_s

    def prepare(self) -> None:
        """Load the GGUF (once per process) before the first call is timed, like a warm server."""
        self._loaded()

    def complete(self, request: CompletionRequest) -> Completion:
        """Answer in-process; with a schema, sampling follows a grammar built from it."""
        loaded = self._loaded()
        grammar = self._grammar(request.schema) if request.schema is not None else None
        deadline = _Deadline(request.timeout_s) if request.timeout_s is not None else None
        with loaded.lock:
            prompt, stop, stopping = self._format(loaded.llama, request.messages)
            if len(prompt) + request.max_tokens > self._n_ctx:
                raise InvalidRequest(
                    f"prompt ({len(prompt)} tokens) plus max_tokens ({request.max_tokens}) exceeds the "
                    f"context of {self._n_ctx} tokens; shorten the prompt or pass a larger n_ctx",
                    backend=NAME,
                    model=self.model,
                )
            if deadline is not None:
                stopping.append(deadline)
            try:
                completion: Any = loaded.llama.create_completion(
                    prompt=prompt,
                    temperature=request.temperature,
                    seed=request.seed,
                    max_tokens=request.max_tokens,
                    stop=stop,
                    stopping_criteria=stopping,
                    grammar=grammar,
                    # Penalising repeats would fight JSON's repeated quotes and braces.
                    repeat_penalty=1.0,
                )
            except (ValueError, RuntimeError) as error:
                raise BackendError(
                    f"llama.cpp failed while answering: {error}", backend=NAME, model=self.model
                ) from None
        choice = completion["choices"][0]
        text = str(choice["text"])
        if deadline is not None and deadline.expired:
            raise BackendTimeout(
                f"{NAME}/{self.model} did not finish within {deadline.timeout_s:g} s",
                timeout_s=deadline.timeout_s,
                partial_text=text,
                backend=NAME,
                model=self.model,
            )
        usage = completion["usage"]
        return Completion(
            text,
            str(choice.get("finish_reason") or "stop"),
            int(usage["prompt_tokens"]),
            int(usage["completion_tokens"]),
        )

    def log_likelihoods(self, texts: Sequence[str]) -> list[float]:
        """Each text's log-probability, from a beginning of text to an end of text. Texts that
        share a beginning (one request spelt several ways) reuse its evaluation."""
        loaded = _load(self._path, SCORING_N_CTX, self._n_threads, self.model, scoring=True)
        llama = loaded.llama
        out = []
        with loaded.lock:
            for text in texts:
                tokens = [*llama.tokenize(text.encode("utf-8"), add_bos=True), llama.token_eos()]
                if len(tokens) > SCORING_N_CTX:
                    raise InvalidRequest(f"a text to score is {len(tokens)} tokens; at most {SCORING_N_CTX}",
                                         backend=NAME, model=self.model)
                kept = 0  # positions already evaluated for an earlier text with the same beginning
                while kept < min(llama.n_tokens, len(tokens) - 1) and llama.input_ids[kept] == tokens[kept]:
                    kept += 1
                llama.n_tokens = kept
                try:
                    llama.eval(tokens[kept:])
                except (ValueError, RuntimeError) as error:
                    raise BackendError(f"llama.cpp failed while scoring: {error}", backend=NAME, model=self.model) from None
                logits = np.asarray(llama.scores[: len(tokens) - 1], dtype=np.float64)
                top = logits.max(axis=1, keepdims=True)
                log_z = top[:, 0] + np.log(np.exp(logits - top).sum(axis=1))
                chosen = logits[np.arange(len(tokens) - 1), tokens[1:]]
                out.append(float((chosen - log_z).sum()))
        return out

    def _grammar(self, schema: Mapping[str, Any]) -> Any:
        try:
            # Key order is kept: the grammar makes the model write properties in schema order.
            return _grammar_for(json.dumps(schema))
        except (ValueError, RuntimeError, KeyError, TypeError) as error:
            raise InvalidRequest(
                f"llama.cpp cannot turn this JSON Schema into a grammar: {error!r}",
                backend=NAME,
                model=self.model,
            ) from None

    def _format(self, llama: Llama, messages: list[Message]) -> tuple[list[int], list[str], Any]:
        """Render the chat with the GGUF's own template (or a family default) and tokenize."""
        from llama_cpp import StoppingCriteriaList
        from llama_cpp.llama_chat_format import Jinja2ChatFormatter

        metadata = llama.metadata
        template = metadata.get("tokenizer.chat_template")
        stop: list[str] = []
        turns = [{"role": m["role"], "content": m["content"]} for m in messages]
        if template is None:
            if metadata.get("general.architecture", "").startswith("gemma"):
                template, stop = GEMMA_TEMPLATE, [GEMMA_STOP]
                turns = _fold_system_into_first_user(turns)
            else:
                template, stop = CHATML_TEMPLATE, [CHATML_STOP]
        eos_id, bos_id = llama.token_eos(), llama.token_bos()
        formatter = Jinja2ChatFormatter(
            template=template,
            eos_token=_token_text(llama, eos_id),
            bos_token=_token_text(llama, bos_id),
            stop_token_ids=[eos_id],
        )
        try:
            rendered = formatter(messages=turns)  # type: ignore[arg-type]
        except ValueError as error:  # templates reject e.g. two user turns in a row
            raise InvalidRequest(
                f"the model's chat template refused these messages: {error}",
                backend=NAME,
                model=self.model,
            ) from None
        tokens = llama.tokenize(rendered.prompt.encode("utf-8"), add_bos=not rendered.added_special, special=True)
        stop += [s for s in _as_list(rendered.stop) if s]
        return tokens, stop, StoppingCriteriaList(list(rendered.stopping_criteria or []))

    def describe(self) -> BackendInfo:
        """Size, parameters and quantisation of the loaded GGUF."""
        import llama_cpp

        loaded = self._loaded()
        metadata = loaded.llama.metadata
        return BackendInfo(
            backend=NAME,
            model=self.model,
            path=str(loaded.path),
            size_bytes=loaded.path.stat().st_size,
            parameters=int(llama_cpp.llama_model_n_params(loaded.llama.model)),
            quantisation=_quantisation(metadata.get("general.file_type")),
            context_length=self._n_ctx,
            detail=metadata.get("general.name", ""),
        )

    @classmethod
    def statuses(cls, **options: Any) -> list[BackendStatus]:
        """A row per shipped preset: usable when llama-cpp-python and its package are here."""
        from importlib.util import find_spec

        has_llama = find_spec("llama_cpp") is not None
        rows = []
        for model in SHIPPED_MODELS.values():
            if not has_llama:
                rows.append(BackendStatus(NAME, model.name, False, LLAMA_INSTALL, "no llama.cpp"))
            elif not is_installed(model):
                rows.append(BackendStatus(NAME, model.name, False, model.install_command, "not installed"))
            else:
                rows.append(BackendStatus(NAME, model.name, True, None, model.description))
        return rows


@functools.lru_cache(maxsize=GRAMMAR_CACHE_SIZE)
def _grammar_for(schema_json: str) -> Any:
    """The llama.cpp grammar for a JSON Schema; managers reuse a few schemas many times."""
    from llama_cpp.llama_grammar import LlamaGrammar

    # Built here rather than via response_format, which silently falls back to "any JSON"
    # when the schema uses something the converter cannot express.
    return LlamaGrammar.from_json_schema(schema_json, verbose=False)


def _fold_system_into_first_user(turns: list[dict[str, str]]) -> list[dict[str, str]]:
    system = "\n\n".join(t["content"] for t in turns if t["role"] == "system")
    rest = [t for t in turns if t["role"] != "system"]
    if system and rest and rest[0]["role"] == "user":
        rest[0] = {"role": "user", "content": f"{system}\n\n{rest[0]['content']}"}
    elif system:
        rest.insert(0, {"role": "user", "content": system})
    return rest


def _token_text(llama: Llama, token: int) -> str:
    """A special token's text (e.g. `<|im_end|>`), or "" when the model has none (-1)."""
    if token < 0:
        return ""
    return llama.detokenize([token], special=True).decode("utf-8", errors="replace")


def _as_list(stop: str | list[str] | None) -> list[str]:
    if stop is None:
        return []
    return [stop] if isinstance(stop, str) else list(stop)


def _quantisation(file_type: str | None) -> str | None:
    """Name a GGUF `general.file_type` number by llama.cpp's own LLAMA_FTYPE_MOSTLY_* table."""
    if file_type is None:
        return None
    import llama_cpp

    for attribute in dir(llama_cpp):
        if attribute.startswith("LLAMA_FTYPE_MOSTLY_") and str(getattr(llama_cpp, attribute)) == (file_type):
            return attribute.removeprefix("LLAMA_FTYPE_MOSTLY_")
    return f"file_type {file_type}"
