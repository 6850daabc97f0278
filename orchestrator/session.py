"""The Session: one person editing one live world, prompt by prompt.

A prompt goes to the planner; its calls run as one transaction; a refusal leaves the scene
exactly as it was. Every change is journaled before it is reported, and every change is
handed to the views (the MuJoCo simulation, the renderer) through `on_change`.
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from drivetwin.orchestrator import logs
from drivetwin.orchestrator.journal import Entry, EventKind, History, Journal, JournalError, JournalWriteError
from drivetwin.orchestrator.journal_events import PlanFacts
from drivetwin.orchestrator.memory import Memory, Turn
from drivetwin.orchestrator.planning import (
    MAX_PROMPT_CHARS,
    Plan,
    PlanContext,
    Planner,
    PlanningError,
    Question,
    TraceStep,
)
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.intent import history_request
from drivetwin.orchestrator.transaction import TransactionError, TransactionResult, execute
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.edits import EditConflict, WorldEdit
from drivetwin.worlds.scene import Scene


class SessionError(Exception):
    """A session command that cannot be done now (nothing to undo, bad file...)."""


@dataclass
class TurnReport:
    """What one prompt did: the plan, each call's result, the scene diff or the error."""

    prompt: str
    ok: bool
    plan: Plan | None = None
    results: list[str] = field(default_factory=list)
    diff: list[str] = field(default_factory=list)
    error: str | None = None
    seconds: float = 0.0
    answer: str | None = None
    # Set when the plan did not account for the request: nothing was applied; the person
    # picks a numbered reading (`Session.choose`) or rephrases.
    question: Question | None = None


class Session:
    """A live editing session over a Scene, with a planner, history and a journal."""

    def __init__(
        self,
        scene: Scene,
        planner: Planner,
        registry: ToolRegistry | None = None,
        journal_path: str | Path | None = None,
        on_change: Callable[[Scene], None] | None = None,
    ) -> None:
        self._scene = scene
        self.planner = planner
        self.registry = registry or ToolRegistry.default()
        self.history = History()
        self.memory = Memory()
        # The prompt and question of a turn that asked, until a reading is chosen or a new prompt comes.
        self.pending: tuple[str, Question] | None = None
        self.on_change = on_change
        # Who planned the prompt being handled (journaled with its commit and turn), and since when.
        self._facts: PlanFacts | None = None
        self._turn_started = 0.0
        self.journal = Journal(journal_path) if journal_path else None
        if self.journal is not None:
            self.journal.start(scene)

    @classmethod
    def resume(
        cls,
        journal_path: str | Path,
        planner: Planner,
        registry: ToolRegistry | None = None,
        on_change: Callable[[Scene], None] | None = None,
    ) -> Session:
        """The session a journal describes, as it was when the journal was last written.

        The session becomes the journal's only writer (JournalLockedError if another has it)
        and appends to it; a journal that does not replay is left untouched.
        """
        journal = Journal(journal_path)
        journal.open()
        try:
            restored = journal.replay()
        except JournalError:
            journal.close()
            raise
        session = cls(restored.scene, planner, registry, None, on_change)
        session.history = restored.history
        session.memory = restored.memory
        session.journal = journal
        return session

    def close(self) -> None:
        """End the session cleanly: an `end` event, and the journal's lock released."""
        if self.journal is not None:
            try:
                self.journal.end()
            except JournalWriteError:
                self.journal.close()  # a full disk: the journal stays resumable without `end`

    def _record(self, kind: EventKind, **payload: object) -> None:
        """Journal an undo/redo/accept/reject/load before it happens; a failed write refuses it."""
        if self.journal is not None:
            try:
                self.journal.append(kind, **payload)
            except JournalWriteError as exc:
                raise SessionError(str(exc)) from exc

    def _note(self, turn: Turn) -> None:
        """Journal a conversation turn; on a full disk the turn lives on in memory only."""
        if self.journal is not None:
            facts = {} if self._facts is None else {"facts": self._finished(self._facts).model_dump(mode="json")}
            with contextlib.suppress(JournalWriteError):
                self.journal.append("turn", turn=turn.model_dump(mode="json"), **facts)

    def _finished(self, facts: PlanFacts) -> PlanFacts:
        return facts.model_copy(update={"turn_s": round(time.perf_counter() - self._turn_started, 4)})

    @property
    def scene(self) -> Scene:
        return self._scene

    def context(self) -> PlanContext:
        return PlanContext(scene=self._scene, registry=self.registry, memory=self.memory)

    # Prompts -----------------------------------------------------------------------------
    def submit(self, prompt: str) -> TurnReport:
        """Plan and apply one prompt; on any refusal the scene stays exactly as it was."""
        started = self._turn_started = time.perf_counter()
        text = prompt.strip()
        if not text:
            return self._failed(prompt, "the prompt is empty; say what to change", started)
        if len(text) > MAX_PROMPT_CHARS:
            return self._failed(
                prompt[:80] + "…",
                f"the prompt is {len(text)} characters; at most {MAX_PROMPT_CHARS} are accepted",
                started,
            )
        self.pending = None  # a new prompt instead of a number drops an open question
        history = history_request(text.lower())
        if history is not None:  # "oops, undo that": the session's undo, not an edit read from the words
            return self._history(text, history, started)
        planner = getattr(self.planner, "name", type(self.planner).__name__)
        with logs.turn_scope() as gathered:  # which models the planner asked, for the journal and the log
            try:
                plan: Plan | None = self.planner.plan(text, self.context())
                error = None
            except PlanningError as exc:
                plan, error = None, str(exc)
        self._facts = logs.plan_facts(plan, gathered, planner, time.perf_counter() - started)
        try:
            report = self._decide(text, plan, started) if plan is not None else self._failed(text, error or "", started)
        finally:
            self._facts = None
        logs.record_turn(gathered, prompt=text, planner=planner if plan is None else plan.planner,
                         prompt_version=plan.prompt_version if plan else None,
                         trace=[step.model_dump(mode="json") for step in plan.trace] if plan else [],
                         calls=[c.model_dump(mode="json") for c in plan.calls] if plan else [],
                         ok=report.ok, error=report.error, txn=self.history.next_txn - 1 if report.diff else None)
        return report

    def _decide(self, text: str, plan: Plan, started: float) -> TurnReport:
        """Check a plan against the request, then apply it, ask, or refuse."""
        if plan.verbatim:
            return self._run(text, plan, started)
        verdict = review(plan.read_as or text, plan, self.context())
        if verdict.action == "refuse":
            return self._failed(text, verdict.message or "; ".join(verdict.problems), started, plan)
        if verdict.question is not None:
            return self._ask(text, plan, verdict.question, started)
        if verdict.calls is not None:  # the plan without what the request excepted
            step = TraceStep(level="check", input="; ".join(verdict.problems), output="applied without them")
            plan = plan.model_copy(update={"calls": verdict.calls, "trace": [*plan.trace, step]})
        return self._run(text, plan, started, verdict.outcome)

    def _run(self, text: str, plan: Plan, started: float, outcome: TransactionResult | None = None) -> TurnReport:
        """Apply a plan's calls as one transaction (or answer, when they change nothing).
        `outcome`: the review's dry run of these calls on the current scene, committed as it is."""
        if outcome is None or outcome.before is not self._scene:  # reviewed on a scene since changed
            try:
                outcome = execute(self.registry, self._scene, plan.calls)
            except TransactionError as exc:
                return self._failed(text, str(exc), started, plan)
        results = [r.text for r in outcome.results]
        if outcome.edit.empty:
            self._remember(text, plan, outcome, "answered")
            answer = plan.answer or ("; ".join(results) if results else None)
            return TurnReport(text, True, plan, results, [], None, time.perf_counter() - started, answer)
        try:
            self._commit(text, outcome.edit, outcome.after)
        except JournalWriteError as exc:  # not durable, so not done: the scene stays as it was
            return self._failed(text, str(exc), started, plan)
        self._remember(text, plan, outcome, "applied")
        return TurnReport(
            text, True, plan, results, outcome.edit.summary(), None,
            time.perf_counter() - started, plan.answer,
        )

    def _ask(self, prompt: str, plan: Plan, question: Question, started: float) -> TurnReport:
        self.pending = (prompt, question)
        turn = Turn(prompt=prompt[:500], status="asked", results=[question.text[:300]])
        self.memory.record(turn)
        self._note(turn)
        return TurnReport(prompt, False, plan, [], [], None, time.perf_counter() - started, None, question)

    def choose(self, number: int) -> TurnReport:
        """Apply reading `number` (from 1) of the open question as the asked prompt's transaction."""
        if self.pending is None:
            raise SessionError("there is no open question to answer; type a request")
        prompt, question = self.pending
        if not 1 <= number <= len(question.readings):
            raise SessionError(f"choose a reading from 1 to {len(question.readings)}, or rephrase")
        self.pending = None
        reading = question.readings[number - 1]
        return self._run(prompt, Plan(calls=list(reading.calls), planner="chosen", answer=None), time.perf_counter())

    def _history(self, prompt: str, word: str, started: float) -> TurnReport:
        """Undo or redo asked for in words: the newest change, as the `undo` and `redo` commands do."""
        stack = self.history.done if word == "undo" else self.history.undone
        change = f"change {stack[-1].txn} ({stack[-1].prompt!r})" if stack else ""
        try:
            diff = self.undo() if word == "undo" else self.redo()
        except SessionError as exc:
            return self._failed(prompt, f"{exc}; the scene is as it was", started)
        done = f"undid {change}" if word == "undo" else f"redid {change}"
        return TurnReport(prompt, True, None, [done], diff, None, time.perf_counter() - started, done)

    def _failed(self, prompt: str, error: str, started: float, plan: Plan | None = None) -> TurnReport:
        turn = Turn(prompt=prompt[:500], status="failed", results=[error[:300]])
        self.memory.record(turn)
        self._note(turn)
        return TurnReport(prompt, False, plan, [], [], error, time.perf_counter() - started)

    def _remember(self, prompt: str, plan: Plan, outcome: TransactionResult, status: str) -> None:
        edit = outcome.edit
        added = [op.asset.id for op in edit.ops if op.op == "add"]
        removed = [op.before.id for op in edit.ops if op.op == "remove"]
        focus = next((r.focus for r in reversed(outcome.results) if r.focus is not None), None)
        turn = Turn(
            prompt=prompt[:500],
            status="applied" if status == "applied" else "answered",
            calls=[str(c) for c in plan.calls],
            results=[r.text for r in outcome.results],
            focus=focus,
            added=added,
            removed=removed,
            touched=sorted(edit.touched_ids()),
            moved_from={op.before.id: (op.before.pose.x, op.before.pose.y) for op in edit.ops if op.op == "update"
                        and (op.before.pose.x, op.before.pose.y) != (op.after.pose.x, op.after.pose.y)},
        )
        self.memory.record(turn)
        self._note(turn)

    def _commit(self, prompt: str, edit: WorldEdit, after: Scene) -> None:
        entry = Entry(self.history.next_txn, prompt, edit,
                      facts=None if self._facts is None else self._finished(self._facts))
        if self.journal is not None:
            self.journal.commit(entry)  # durable before anything reports success
        self.history.next_txn += 1
        self.history.done.append(entry)
        self.history.undone.clear()
        self._set_scene(after)

    def _set_scene(self, scene: Scene) -> None:
        self._scene = scene
        if self.on_change is not None:
            self.on_change(scene)

    # History -----------------------------------------------------------------------------
    def undo(self) -> list[str]:
        """Undo the newest change still applied; returns the diff."""
        if not self.history.done:
            raise SessionError("nothing to undo")
        entry = self.history.done[-1]
        inverse = entry.edit.inverse()
        after = _applied(inverse, self._scene, f"change {entry.txn} cannot be undone")
        self._record("undo", txn=entry.txn)
        self.history.done.pop()
        self.history.undone.append(entry)
        self.memory.mark_last("undone")
        self._set_scene(after)
        return inverse.summary()

    def redo(self) -> list[str]:
        """Re-apply the newest undone change; returns the diff."""
        if not self.history.undone:
            raise SessionError("nothing to redo")
        entry = self.history.undone[-1]
        after = _applied(entry.edit, self._scene, f"change {entry.txn} cannot be redone")
        self._record("redo", txn=entry.txn)
        self.history.undone.pop()
        self.history.done.append(entry)
        self.memory.mark_last("applied")
        self._set_scene(after)
        return entry.edit.summary()

    def accept(self) -> str:
        """Confirm the newest change: it can still be undone, but no longer rejected."""
        if not self.history.done or self.history.done[-1].accepted:
            raise SessionError("no pending change to accept")
        entry = self.history.done[-1]
        self._record("accept", txn=entry.txn)
        entry.accepted = True
        self.memory.mark_last("accepted")
        from drivetwin.orchestrator.planning.retrieval import learn_accepted  # bank code loads only when used

        learn_accepted(self.planner, self._scene, entry.prompt, self.memory)  # learns how this person speaks
        return f"accepted change {entry.txn}: {entry.prompt}"

    def reject(self) -> list[str]:
        """Throw the newest pending change away for good (it cannot be redone)."""
        if not self.history.done or self.history.done[-1].accepted:
            raise SessionError("no pending change to reject")
        entry = self.history.done[-1]
        inverse = entry.edit.inverse()
        after = _applied(inverse, self._scene, f"change {entry.txn} cannot be rejected")
        self._record("reject", txn=entry.txn)
        self.history.done.pop()
        self.history.undone.clear()  # undone changes were made on top of the rejected one
        self.memory.mark_last("rejected")
        self._set_scene(after)
        return inverse.summary()

    # Files -------------------------------------------------------------------------------
    def save(self, path: str | Path) -> Path:
        """Write the scene as JSON (atomically)."""
        target = Path(path)
        if not target.name or target.name in (".", "..") or target.is_dir():
            raise SessionError(f"cannot save to {path!s}: it is a folder; give a file path such as scene.json")
        if not target.parent.is_dir():
            raise SessionError(f"cannot save to {path!s}: the folder {target.parent} does not exist")
        self._scene.save(target)
        return target

    def load(self, path: str | Path) -> None:
        """Replace the scene by a saved one; a bad file changes nothing."""
        scene = Scene.load(path)  # raises SceneFileError before anything changes
        self._record("load", scene=scene.model_dump(mode="json"))
        self.history = History(next_txn=self.history.next_txn)
        self._set_scene(scene)


def _applied(edit: WorldEdit, scene: Scene, refusal: str) -> Scene:
    """`edit` applied to `scene`, or a SessionError saying why it no longer fits."""
    try:
        return edit.apply(scene)
    except EditConflict as exc:
        raise SessionError(f"{refusal}: {exc}") from exc
