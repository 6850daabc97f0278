"""What the LLM managers share: the Requirement type and the ask-validate-retry loop.

Every answer is constrained by a JSON Schema where the backend allows it and is always
re-validated here; a validation error goes back to the model as a message, within a bounded
retry budget. Backend faults (down, timeout) end planning at once with a clear message.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Generic, TypeVar

from drivetwin.orchestrator.backends import (
    Backend,
    BackendError,
    BackendTimeout,
    BackendUnavailable,
    InvalidOutput,
    Message,
)
from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.tools.base import FAMILIES, Family
from pydantic import BaseModel, ConfigDict, Field, ValidationError

# Re-asks per step after a refused answer; tiny models rarely fix an answer after two hints.
RETRY_BUDGET = 2
# Per LLM call; a 135M model answers in about a second, a 9B one in under ten.
CALL_TIMEOUT_S = 30.0
# Longest free text a Requirement field may hold; longer text is a model rambling.
FIELD_CHARS = 60
# Most requirements one prompt may produce ("snow, a truck, and a cone line" is three).
MAX_REQUIREMENTS = 4

T = TypeVar("T")


class Requirement(BaseModel):
    """One thing the user asked for, typed by the tool family that can do it."""

    model_config = ConfigDict(extra="forbid")

    kind: Family
    what: str = Field("", max_length=FIELD_CHARS)
    where: str = Field("", max_length=FIELD_CHARS)
    how: str = Field("", max_length=FIELD_CHARS)

    def __str__(self) -> str:
        return f"{self.kind} | what: {self.what} | where: {self.where} | how: {self.how}"


class Requirements(BaseModel):
    """The Sr. manager's answer."""

    model_config = ConfigDict(extra="forbid")

    requirements: list[Requirement] = Field(min_length=1, max_length=MAX_REQUIREMENTS)


def requirements_schema(kinds: list[Family] | None = None) -> dict[str, Any]:
    """The Sr. manager's answer schema: flat and small, for grammar-constrained decoding;
    `kinds` narrows the requirement kinds (to what the request's mood allows)."""
    text = {"type": "string", "maxLength": FIELD_CHARS}
    item = {
        "type": "object",
        "properties": {"kind": {"enum": list(kinds or FAMILIES)}, "what": text, "where": text, "how": text},
        "required": ["kind", "what", "where", "how"],
        "additionalProperties": False,
    }
    return {
        "type": "object",
        "properties": {
            "requirements": {
                "type": "array",
                "items": item,
                "minItems": 1,
                "maxItems": MAX_REQUIREMENTS,
            }
        },
        "required": ["requirements"],
        "additionalProperties": False,
    }


@dataclass
class Answer(Generic[T]):
    """A validated answer, with what it cost and the refusals on the way."""

    value: T
    raw: str
    retries: int = 0
    tokens: int = 0
    seconds: float = 0.0
    refusals: list[str] = field(default_factory=list)


def ask(
    backend: Backend,
    messages: list[Message],
    schema: dict[str, Any],
    validate: Callable[[Any], T],
    *,
    step: str,
    max_tokens: int,
    budget: int = RETRY_BUDGET,
    timeout_s: float = CALL_TIMEOUT_S,
) -> Answer[T]:
    """Ask until `validate` accepts the parsed JSON answer, re-asking with the error message.

    `validate` raises ValueError (pydantic's ValidationError is one) with a message the model
    can act on. Raises PlanningError when the backend fails or the budget is spent.
    """
    started = time.perf_counter()
    conversation = list(messages)
    refusals: list[str] = []
    tokens = 0
    for attempt in range(budget + 1):
        try:
            result = backend.chat(
                conversation,
                schema=schema,
                temperature=0.0,
                seed=attempt,
                max_tokens=max_tokens,
                timeout_s=timeout_s,
            )
        except BackendUnavailable as exc:
            raise PlanningError(f"{step}: the language model is not available: {exc}") from exc
        except BackendTimeout as exc:
            raise PlanningError(
                f"{step}: the language model did not answer within {exc.timeout_s:g} s; "
                "try again, or use a smaller model or the rule planner"
            ) from exc
        except InvalidOutput as exc:
            refusals.append(_short(f"{exc.reason} answer: {exc.message}"))
            conversation += [_assistant(exc.raw), _fix(refusals[-1])]
            continue
        except BackendError as exc:
            raise PlanningError(f"{step}: the language model failed: {exc}") from exc
        tokens += result.prompt_tokens + result.completion_tokens
        try:
            parsed = result.data if result.data is not None else json.loads(result.text)
            value = validate(parsed)
        except (ValueError, TypeError) as exc:
            message = _validation_message(exc)
            refusals.append(message)
            conversation += [_assistant(result.text), _fix(message)]
            continue
        return Answer(value, result.text, attempt, tokens, time.perf_counter() - started, refusals)
    raise PlanningError(f"{step}: no usable answer after {budget + 1} tries; last problem: {refusals[-1]}")


def _validation_message(exc: Exception) -> str:
    if isinstance(exc, ValidationError):
        details = "; ".join(f"{'.'.join(str(p) for p in e['loc']) or 'answer'}: {e['msg']}" for e in exc.errors()[:3])
        return f"{exc.error_count()} validation error(s): {details}"
    if isinstance(exc, json.JSONDecodeError):
        return f"the answer is not JSON ({exc.msg})"
    return _short(str(exc))


# A refusal told to the model is cut here: long enough for the list of every Worker's name.
REFUSAL_CHARS = 500


def _short(text: str, limit: int = REFUSAL_CHARS) -> str:
    return text if len(text) <= limit else text[:limit] + "…"


def _assistant(text: str) -> Message:
    return Message(role="assistant", content=text[:400] or "(empty)")


def _fix(problem: str) -> Message:
    return Message(
        role="user",
        content=f"That answer was refused: {_short(problem)}. Fix it and answer again with JSON.",
    )


__all__ = [
    "CALL_TIMEOUT_S",
    "FIELD_CHARS",
    "MAX_REQUIREMENTS",
    "RETRY_BUDGET",
    "Answer",
    "Requirement",
    "Requirements",
    "ask",
    "requirements_schema",
]
