"""Checks a model's answer against the JSON Schema the caller asked for."""

from __future__ import annotations

import json
from collections.abc import Mapping
from typing import Any

import jsonschema
import jsonschema.exceptions

from .base import ChatResult
from .errors import InvalidOutput, InvalidRequest

# How much of a bad answer to quote in an error message; the full text is on `.raw`.
QUOTE_CHARS = 200


def check_schema(schema: Mapping[str, Any], *, backend: str) -> None:
    """Refuse a schema that is not valid JSON Schema, before the model runs."""
    try:
        validator = jsonschema.validators.validator_for(schema)
        validator.check_schema(schema)
    except jsonschema.exceptions.SchemaError as error:
        raise InvalidRequest(f"schema is not a valid JSON Schema: {error.message}", backend=backend) from None


def parse_answer(
    text: str,
    schema: Mapping[str, Any],
    *,
    finish_reason: str,
    max_tokens: int,
    backend: str,
    model: str,
) -> Any:
    """Parse `text` as JSON and validate it against `schema`; return the parsed value.

    A grammar on the server side is not trusted: servers silently drop schemas they cannot
    compile, so the answer is always re-validated here.
    """
    quoted = _quote(text)
    if not text.strip():
        raise InvalidOutput(
            f"{backend}/{model} returned an empty answer where JSON was required",
            raw=text,
            reason="empty",
            backend=backend,
            model=model,
        )
    try:
        value = json.loads(text)
    except json.JSONDecodeError as error:
        if finish_reason == "length":
            raise InvalidOutput(
                f"{backend}/{model} answer was cut off at max_tokens={max_tokens} before the "
                f"JSON was complete; raise max_tokens or ask for less. Answer began: {quoted}",
                raw=text,
                reason="truncated",
                backend=backend,
                model=model,
            ) from None
        raise InvalidOutput(
            f"{backend}/{model} answer is not JSON ({error.msg} at char {error.pos}): {quoted}",
            raw=text,
            reason="not_json",
            backend=backend,
            model=model,
        ) from None
    errors = sorted(
        jsonschema.validators.validator_for(schema)(schema).iter_errors(value),
        key=lambda e: list(e.absolute_path),
    )
    if errors:
        details = "; ".join(f"at {_json_path(list(e.absolute_path))}: {e.message}" for e in errors[:3])
        raise InvalidOutput(
            f"{backend}/{model} answer does not match the schema ({len(errors)} error(s): {details}). Answer: {quoted}",
            raw=text,
            reason="schema_mismatch",
            backend=backend,
            model=model,
        )
    return value


def _json_path(parts: list[str | int]) -> str:
    return "$" + "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in parts)


def _quote(text: str) -> str:
    if len(text) <= QUOTE_CHARS:
        return repr(text)
    return repr(text[:QUOTE_CHARS]) + f"… ({len(text)} chars)"


def answer_result(
    text: str,
    schema: Mapping[str, Any] | None,
    *,
    finish_reason: str,
    max_tokens: int,
    prompt_tokens: int,
    completion_tokens: int,
    latency_s: float,
    backend: str,
    model: str,
) -> ChatResult:
    """The ChatResult of one answer; with a schema, its text is parsed and checked first."""
    data = None
    if schema is not None:
        data = parse_answer(
            text, schema, finish_reason=finish_reason, max_tokens=max_tokens, backend=backend, model=model
        )
    return ChatResult(
        text=text,
        prompt_tokens=prompt_tokens,
        completion_tokens=completion_tokens,
        latency_s=latency_s,
        model=model,
        backend=backend,
        finish_reason=finish_reason,
        data=data,
    )
