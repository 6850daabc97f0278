"""The Sr. manager: from a prompt in context to a list of typed Requirements.

Its prompt holds the rules (prompts/sr_manager.txt), the world's places, a bounded view of
the conversation, and the few-shot examples closest in meaning to the request, retrieved from
the world's example bank (llm/demos.py; the static prompts/sr_examples.json without one).
"""

from __future__ import annotations

from drivetwin.orchestrator.backends import Backend, Message
from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning.base import PlanContext, TraceStep
from drivetwin.orchestrator.planning.grounding import Grounder
from drivetwin.orchestrator.planning.llm.demos import sr_demos
from drivetwin.orchestrator.planning.llm.managers import (
    CALL_TIMEOUT_S,
    FIELD_CHARS,
    Answer,
    Requirement,
    Requirements,
    ask,
    requirements_schema,
)
from drivetwin.orchestrator.planning.llm.request_names import CLAUSE_JOINS
from drivetwin.prompts.templates import as_json, render, sr_examples
from drivetwin.tools.base import Family

# Few-shot examples per prompt: enough to show the pattern, few enough for a 4k context.
SR_EXAMPLES = 4
SR_MAX_TOKENS = 160
# Characters of conversation memory shown to the Sr. manager (the rest is summarised).
MEMORY_CHARS = 600


def memory_view(memory: Memory, limit: int = MEMORY_CHARS) -> str:
    """The newest part of the conversation, within `limit` characters, plus the last edit."""
    text = memory.render()
    if len(text) > limit:
        text = "…" + text[-limit:]
    lines = [text or "(nothing yet)"]
    added = memory.last_added()
    if added:
        lines.append(f"last added: {', '.join(added[:6])}")
    return "\n".join(lines)


class SrManager:
    """Turns a prompt into Requirements with one (constrained, validated) LLM answer."""

    def __init__(self, backend: Backend, grounder: Grounder, timeout_s: float = CALL_TIMEOUT_S) -> None:
        self.backend = backend
        self.grounder = grounder
        self.timeout_s = timeout_s

    def messages(self, prompt: str, context: PlanContext) -> list[Message]:
        """The chat the model sees: rules and context, then retrieved examples, then the request."""
        places = ", ".join(lm.name for lm in context.scene.landmarks)
        system = render("sr_manager.txt", places=places, memory=memory_view(context.memory))
        demos = [(d.request, d.requirements) for d in sr_demos(prompt, context, SR_EXAMPLES)]
        if not demos:  # no bank (no embedding model): the static examples, nearest by spelling
            bank = sr_examples()
            chosen = self.grounder.nearest(prompt, [e.request for e in bank], SR_EXAMPLES)
            demos = [(bank[i].request, bank[i].requirements) for i in chosen]
        messages: list[Message] = [Message(role="system", content=system)]
        # Most similar last, nearest the real request, where small models copy from.
        for request, requirements in reversed(demos):
            messages.append(Message(role="user", content=f"Request: {request}"))
            messages.append(Message(role="assistant", content=as_json({"requirements": requirements})))
        messages.append(Message(role="user", content=f"Request: {prompt}"))
        return messages

    def requirements(
        self, prompt: str, context: PlanContext, kinds: list[Family] | None = None
    ) -> tuple[list[Requirement], TraceStep]:
        """The prompt's requirements (of `kinds` only, when given) and the trace step that explains them.

        A one-clause request whose mood allows one kind only ("where is the hydrant?") is one
        requirement of that kind: the model is not asked (it could only copy the words).
        """
        if kinds is not None and len(kinds) == 1 and CLAUSE_JOINS.search(prompt.lower()) is None:
            only = Requirement(kind=kinds[0], what=prompt.strip()[:FIELD_CHARS])
            return [only], TraceStep(level="sr_manager", input=prompt, output=f"{only}\n(one clause, one kind: not asked)")
        answer: Answer[Requirements] = ask(
            self.backend,
            self.messages(prompt, context),
            requirements_schema(kinds),
            Requirements.model_validate,
            step="Sr. manager",
            max_tokens=SR_MAX_TOKENS,
            timeout_s=self.timeout_s,
        )
        found = answer.value.requirements
        output = "\n".join(str(r) for r in found)
        if answer.refusals:
            output += "\nrefused on the way: " + " | ".join(answer.refusals)
        step = TraceStep(
            level="sr_manager",
            input=prompt,
            output=output,
            seconds=answer.seconds,
            retries=answer.retries,
            tokens=answer.tokens,
        )
        return found, step


__all__ = ["SrManager", "memory_view"]
