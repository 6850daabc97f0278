"""The planner interface: anything that maps (prompt, context) to Worker tool calls.

The rule-based planner, the LLM manager hierarchy and their hybrid all implement `Planner`;
the session and the eval harness only ever see this interface.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.transaction import first_refusal
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.scene import Scene
from pydantic import BaseModel, ConfigDict, Field

# Prompts longer than this are refused before any planner sees them.
MAX_PROMPT_CHARS = 4000


class TraceStep(BaseModel):
    """One level of planning, for `--explain`: what went in, what came out, how long it took."""

    model_config = ConfigDict(extra="forbid")

    level: str
    input: str = ""
    output: str = ""
    seconds: float = 0.0
    retries: int = 0
    tokens: int = 0


class Reading(BaseModel):
    """One way to understand a request: a few words for the person and the calls that do it."""

    model_config = ConfigDict(extra="forbid")

    text: str = Field(min_length=1)
    calls: list[ToolCall] = Field(default_factory=list)
    # How sure the planner that offered it was (0 when it did not say).
    confidence: float = Field(0.0, ge=0.0, le=1.0)


class Question(BaseModel):
    """A short clarifying question with numbered readings to choose from (nothing applied yet)."""

    model_config = ConfigDict(extra="forbid")

    text: str = Field(min_length=1)
    readings: list[Reading] = Field(min_length=1, max_length=3)


class Plan(BaseModel):
    """A planner's answer: tool calls to run as one transaction, and how it got there."""

    model_config = ConfigDict(extra="forbid")

    calls: list[ToolCall] = Field(default_factory=list)
    planner: str
    # How sure the planner is that the calls do what was asked (1 = certain).
    confidence: float = Field(1.0, ge=0.0, le=1.0)
    prompt_version: str | None = None
    # A direct answer for questions that need no edit ("where is parking lot B?").
    answer: str | None = None
    trace: list[TraceStep] = Field(default_factory=list)
    retries: int = 0
    tokens: int = 0
    # Set when the planner cannot tell which of a few readings was meant: the session asks
    # instead of applying anything (the calls are then empty).
    question: Question | None = None
    # Other candidate readings, best first (other planners' plans), for the plan-vs-request check.
    alternatives: list[Reading] = Field(default_factory=list)
    # The calls were given as they are (a case's reference plan, a recorded replay), not read
    # from the words, so the plan-vs-request check has nothing to compare them with.
    verbatim: bool = False
    # The request as the planner read it, when it respelt words of it (planning/llm/respell.py):
    # the plan-versus-request check reads the same words.
    read_as: str | None = None


class PlanningError(Exception):
    """The planner could not turn the prompt into calls; the message says why, in plain words."""


@dataclass
class PlanContext:
    """What a planner may look at: the scene, the tools, memory, and a dry run of calls."""

    scene: Scene
    registry: ToolRegistry
    memory: Memory = field(default_factory=Memory)

    def check(self, calls: list[ToolCall]) -> str | None:
        """The first refusal these calls would meet, or None when they would all apply."""
        return first_refusal(self.registry, self.scene, calls)


@runtime_checkable
class Planner(Protocol):
    """Maps a prompt in context to a Plan; raises PlanningError when it cannot."""

    name: str

    def plan(self, prompt: str, context: PlanContext) -> Plan: ...
