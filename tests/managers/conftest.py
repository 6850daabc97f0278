"""Fixtures for the manager tests: the campus world and a scripted Backend.

`ScriptedBackend` is a real subclass of the Backend interface whose answers are a script:
it stands in for a model's answers (the real backends are tested in tests/backends and by
the few real-model tests here). Like a backend without grammar support, it returns text
unvalidated, so every check the managers make on an answer is exercised.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any, ClassVar

import pytest
from drivetwin.orchestrator.backends import Backend, BackendError, BackendInfo, BackendStatus, ChatResult, Message
from drivetwin.orchestrator.backends.base import Completion, CompletionRequest
from drivetwin.orchestrator.planning.grounding import Grounder
from drivetwin.orchestrator.planning.llm.planner import LlmPlanner
from drivetwin.orchestrator.session import Session
from drivetwin.worlds.scene import Scene


class ScriptedBackend(Backend):
    """Answers from a script: dicts become JSON text, strings are sent as they are,
    BackendErrors are raised. Records every conversation and schema it was given."""

    name: ClassVar[str] = "scripted"

    def __init__(self, answers: Sequence[Any]) -> None:
        super().__init__("script")
        self.answers = list(answers)
        self.seen: list[list[Message]] = []
        self.schemas: list[Mapping[str, Any] | None] = []

    @property
    def calls(self) -> int:
        return len(self.seen)

    def chat(  # type: ignore[override]
        self,
        messages: Sequence[Message],
        *,
        schema: Mapping[str, Any] | None = None,
        temperature: float = 0.0,
        seed: int | None = 0,
        max_tokens: int = 512,
        timeout_s: float | None = None,
    ) -> ChatResult:
        # Like a backend without grammar support, the text comes back unvalidated (Backend.chat
        # would check it against the schema first), so the managers' own checks are exercised.
        completion = self.complete(CompletionRequest(list(messages), schema, temperature, seed, max_tokens, timeout_s))
        return ChatResult(completion.text, completion.prompt_tokens, completion.completion_tokens, 0.01, "script",
                          self.name)

    def complete(self, request: CompletionRequest) -> Completion:
        self.seen.append(list(request.messages))
        self.schemas.append(request.schema)
        if not self.answers:
            raise AssertionError("the script has no more answers")
        answer = self.answers.pop(0)
        if isinstance(answer, BackendError):
            raise answer
        text = answer if isinstance(answer, str) else json.dumps(answer)
        return Completion(text, "stop", 100, 20)

    def describe(self) -> BackendInfo:
        return BackendInfo(self.name, self.model)

    @classmethod
    def statuses(cls, **options: Any) -> list[BackendStatus]:
        return [BackendStatus(cls.name, "script", True)]


def requirement(kind: str, what: str = "", where: str = "", how: str = "") -> dict[str, Any]:
    """A Sr. manager answer with one requirement."""
    return {"requirements": [{"kind": kind, "what": what, "where": where, "how": how}]}


def call(tool: str, **args: Any) -> dict[str, Any]:
    """A Jr. manager answer."""
    return {"tool": tool, "args": args}


@pytest.fixture
def spelling_grounder() -> Grounder:
    """Grounding by spelling only: fast, for tests about the managers, not about meaning."""
    return Grounder(use_embeddings=False)


def scripted_session(campus: Scene, answers: Sequence[Any], grounder: Grounder) -> tuple[Session, ScriptedBackend]:
    """A session on the campus whose planner is the LLM hierarchy over a scripted backend."""
    backend = ScriptedBackend(answers)
    return Session(campus, LlmPlanner(backend, grounder=grounder)), backend
