"""The journal's event lines as typed models: a line is one of these, or a JournalError naming it."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from drivetwin.orchestrator.memory import Turn
from drivetwin.worlds.edits import WorldEdit
from drivetwin.worlds.json_input import JsonInputError, parse_json
from pydantic import BaseModel, ConfigDict, Field, TypeAdapter, ValidationError

# A transaction id: a positive whole number (JSON true, "3" or 2.5 are refused).
TxnId = Annotated[int, Field(ge=1, strict=True)]


class JournalError(ValueError):
    """A journal that cannot be replayed (missing start, damaged line, stale edit)."""


class _Event(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class StartEvent(_Event):
    event: Literal["start"]
    scene: dict[str, Any]


class PlanFacts(BaseModel):
    """Which planner and model made a turn's plan, and what it cost: for `drivetwin logs edits`.

    Journals written before these facts were recorded replay without them (None).
    """

    model_config = ConfigDict(extra="forbid", frozen=True)

    planner: str
    # "backend/model" of every model the planner asked, in order; None for a planner with no model.
    model: str | None = None
    prompt_version: str | None = None
    # The planning levels (requirements, calls...), as `--explain` shows them.
    trace: list[dict[str, Any]] = Field(default_factory=list)
    tokens: int = 0
    plan_s: float = 0.0
    turn_s: float = 0.0
    # The turn's id in `drivetwin logs` (SESSION:TURN), when the backend calls were logged.
    log: str | None = None


class CommitEvent(_Event):
    event: Literal["commit"]
    txn: TxnId
    prompt: Annotated[str, Field(strict=True)]
    edit: WorldEdit
    facts: PlanFacts | None = None


class TxnEvent(_Event):
    """undo, redo, accept or reject of the change `txn`."""

    event: Literal["undo", "redo", "accept", "reject"]
    txn: TxnId


class LoadEvent(_Event):
    event: Literal["load"]
    scene: dict[str, Any]


class TurnEvent(_Event):
    event: Literal["turn"]
    turn: Turn
    facts: PlanFacts | None = None


class EndEvent(_Event):
    """The session closed normally."""

    event: Literal["end"]


Event = Annotated[
    StartEvent | CommitEvent | TxnEvent | LoadEvent | TurnEvent | EndEvent,
    Field(discriminator="event"),
]
_EVENT: TypeAdapter[Event] = TypeAdapter(Event)
EVENT_KINDS = ("start", "commit", "undo", "redo", "accept", "reject", "load", "turn", "end")


def parse_event(line: str, where: str, first: bool = False) -> Event:
    """The event on one journal line; JournalError (naming `where`) for anything else.

    The `first` line of a journal must be its start event.
    """
    try:
        data = parse_json(line, where)
    except JsonInputError as exc:
        raise JournalError(str(exc)) from exc
    if not isinstance(data, dict):
        raise JournalError(f"{where} is a JSON {type(data).__name__}, not an event object")
    kind = data.get("event")
    if kind not in EVENT_KINDS:
        raise JournalError(f"{where}: unknown event {kind!r}; events are {', '.join(EVENT_KINDS)}")
    if first and kind != "start":
        raise JournalError(f"{where} is a {kind} event: a journal begins with a start event")
    try:
        return _EVENT.validate_python(data)
    except ValidationError as exc:
        error = exc.errors()[0]
        at = ".".join(str(p) for p in error["loc"][1:]) or "event"
        raise JournalError(f"{where}: a {kind} event with a bad {at}: {error['msg']}") from exc
