"""The browser's side of a session: prompts, chosen readings and history commands, one at a time.

Every browser tab talks to the same Session through one Conversation; a lock keeps two tabs
from planning at once. Prompts go to `Session.submit`, readings to `Session.choose`, and
undo/redo/accept/reject/save to the REPL's own `run_command`, so the browser and `chat`
share one session core and one wording.
"""

from __future__ import annotations

import re
import threading
from dataclasses import dataclass, field
from typing import Literal

from drivetwin.orchestrator.planning import Question
from drivetwin.orchestrator.repl import ChatOptions, format_report, neutralised, run_command
from drivetwin.orchestrator.session import Session, SessionError

__all__ = ["HISTORY_COMMANDS", "Conversation", "Message", "resolve_selection"]

HISTORY_COMMANDS = ("undo", "redo", "accept", "reject")
# "this", "that", "this one", "that car", "the selected asset": words that point at the
# asset picked in the 3D view. "it" is left alone: "make it rain" points at nothing.
_POINTING = re.compile(r"\b(?:this|that)(?: one| asset)?\b|\bthe selected (?:one|asset)\b", re.IGNORECASE)
# The conversation panel shows this many messages; older ones stay in the session's journal.
SHOWN_MESSAGES = 40

Role = Literal["you", "drivetwin"]


@dataclass(frozen=True)
class Message:
    """One line of the conversation: who said it and what."""

    role: Role
    text: str


def resolve_selection(prompt: str, selected: str | None) -> str:
    """`prompt` with "this"/"that" replaced by the selected asset's id (unchanged if none is selected)."""
    if selected is None:
        return prompt
    return _POINTING.sub(selected, prompt)


@dataclass
class Conversation:
    """A session's conversation as the browser shows it."""

    session: Session
    messages: list[Message] = field(default_factory=list)
    question: Question | None = None
    selected: str | None = None
    lock: threading.Lock = field(default_factory=threading.Lock)

    def _say(self, role: Role, text: str) -> None:
        self.messages.append(Message(role, neutralised(text)))

    def send(self, prompt: str) -> bool:
        """Plan and apply one typed request (or a history command typed as a word); whether it worked."""
        with self.lock:
            text = prompt.strip()
            word = text.lstrip("/").lower()
            if word in HISTORY_COMMANDS:
                return self._command(word, "")
            if word.startswith("save "):
                return self._command("save", text.lstrip("/")[5:].strip())
            resolved = resolve_selection(text, self.selected)
            self._say("you", text if resolved == text else f"{text}  →  {resolved}")
            report = self.session.submit(resolved)
            self.question = report.question
            if report.question is not None:
                self._say("drivetwin", report.question.text)
            else:
                self._say("drivetwin", format_report(report, explain=False))
            return report.ok

    def choose(self, number: int) -> bool:
        """Apply reading `number` (from 1) of the open question."""
        with self.lock:
            question = self.question
            label = question.readings[number - 1].text if question and 0 < number <= len(question.readings) else "?"
            self._say("you", f"{number}. {label}")
            try:
                report = self.session.choose(number)
            except SessionError as exc:
                self._say("drivetwin", f"  error: {exc}")
                return False
            self.question = None
            self._say("drivetwin", format_report(report, explain=False))
            return report.ok

    def command(self, word: str, argument: str = "") -> bool:
        """Run undo, redo, accept, reject or save (with a path) as `chat` would."""
        with self.lock:
            return self._command(word, argument)

    def _command(self, word: str, argument: str) -> bool:
        if word not in (*HISTORY_COMMANDS, "save"):
            raise ValueError(f"unknown command {word!r}; commands: {', '.join((*HISTORY_COMMANDS, 'save'))}")
        if word == "save" and not argument:
            self._say("drivetwin", "  error: give a file path to save to, such as scene.json")
            return False
        replies: list[str] = []
        line = f"{word} {argument}".strip()
        self._say("you", line)
        done = run_command(self.session, line, ChatOptions(echo=replies.append))
        self._say("drivetwin", "\n".join(replies))
        if word in ("undo", "redo", "reject"):
            self.question = None
        return bool(done)

    def shown(self) -> list[Message]:
        """The newest messages, oldest first."""
        return self.messages[-SHOWN_MESSAGES:]
