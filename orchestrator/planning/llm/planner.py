"""The LLM manager hierarchy as a Planner: Sr. manager -> Requirements -> Jr. managers -> calls.

    planner = make_planner("llm", backend="embedded", model="smollm2-135m")
    plan = planner.plan("make it rain", session.context())
    print(format_trace(plan))

Every fault ends in a PlanningError with a plain message (the session then leaves the scene
unchanged): backend down or slow, answers that are cut off, not JSON, name a tool that does
not exist or break a placement rule after the retry budget, and prompts that try to
rewrite the planner's instructions.
"""

from __future__ import annotations

import re
import time
from typing import Any

from drivetwin.orchestrator.backends import Backend, BackendError, load_backend
from drivetwin.orchestrator.planning.base import Plan, PlanContext, PlanningError, Question, Reading, TraceStep
from drivetwin.orchestrator.planning.grounding import Grounder
from drivetwin.orchestrator.planning.llm.jr_manager import JrManager
from drivetwin.orchestrator.planning.llm.managers import CALL_TIMEOUT_S
from drivetwin.orchestrator.planning.llm.request_names import RequestNames, read_names
from drivetwin.orchestrator.planning.llm.sr_manager import SrManager
from drivetwin.orchestrator.planning.readings import describe
from drivetwin.orchestrator.planning.rules.spelling import repair
from drivetwin.prompts.templates import prompt_version
from drivetwin.tools.base import Family, ToolCall

DEFAULT_BACKEND = "embedded"
DEFAULT_MODEL = "smollm2-135m"
# Confidence of an LLM plan that needed no retries; each retry lowers it.
BASE_CONFIDENCE = 0.9
RETRY_PENALTY = 0.15
MIN_CONFIDENCE = 0.3

# Tools that bring new things in; what kinds they bring the request must name, or the person is asked.
_ADDING = ("add_asset", "arrange_assets")
# Kinds nearest the request in meaning looked at, and offered (those a dry run accepts), when it names none.
KINDS_LOOKED_AT = 6
KINDS_OFFERED = 3

# Text that addresses the planner instead of describing a scene change. Matching is on
# purpose broad: a false alarm costs a rephrase, a miss could cost the user's scene.
_INJECTION = re.compile(
    r"(ignore|disregard|forget|override)\b.{0,40}\b(instruction|rule|prompt|guideline|above|previous)"
    r"|system prompt|you are now|new instructions|developer mode|jailbreak"
    r"|<\|im_start\|>|<start_of_turn>|\[/?INST\]"
    r"|\b(import os|subprocess|os\.system|__import__|eval\(|exec\()",
    re.IGNORECASE,
)


def injection_reason(prompt: str) -> str | None:
    """Why `prompt` looks like an attempt to instruct the planner, or None."""
    found = _INJECTION.search(prompt)
    if found is None:
        return None
    return f"it contains {found.group(0)!r}"


class LlmPlanner:
    """The Sr./Jr. manager hierarchy over one LLM backend."""

    name = "llm"

    def __init__(
        self,
        backend: Backend | str = DEFAULT_BACKEND,
        model: str | None = DEFAULT_MODEL,
        grounder: Grounder | None = None,
        call_timeout_s: float = CALL_TIMEOUT_S,
        **backend_options: Any,
    ) -> None:
        self.call_timeout_s = call_timeout_s
        self._backend = backend if isinstance(backend, Backend) else None
        self._backend_name = backend if isinstance(backend, str) else backend.name
        self._model = model
        self._options = backend_options
        self.grounder = grounder or Grounder()

    @property
    def backend(self) -> Backend:
        """The backend, opened on first use so that a missing model is a planning error."""
        if self._backend is None:
            try:
                self._backend = load_backend(self._backend_name, self._model, **self._options)
            except BackendError as exc:
                raise PlanningError(f"cannot open the language model: {exc}") from exc
        return self._backend

    @property
    def label(self) -> str:
        """backend/model, for reports."""
        model = self._backend.model if self._backend is not None else self._model
        return f"{self._backend_name}/{model}"

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        """Requirements from the Sr. manager, one checked call per requirement from Jr. managers."""
        reason = injection_reason(prompt)
        if reason is not None:
            raise PlanningError(
                f"the prompt was not run because it tries to give the planner instructions "
                f"({reason}); describe the change you want in the scene instead"
            )
        backend = self.backend
        trace: list[TraceStep] = []
        started = time.perf_counter()
        # The repair every reader of requests shares: slips and run-together words, and things
        # described instead of named ("the red thing firefighters use"), read as the names they mean.
        repaired = repair(prompt, context.scene)
        read_as = repaired.text if repaired.text != prompt else None
        if read_as is not None:
            trace.append(TraceStep(level="repair", input=prompt, output="; ".join(repaired.repairs) or read_as,
                                   seconds=time.perf_counter() - started))
            prompt = read_as
        said = read_names(prompt, context.scene)
        senior = SrManager(backend, self.grounder, self.call_timeout_s)
        requirements, sr_step = senior.requirements(prompt, context, said.kinds())
        trace.append(sr_step)
        calls: list[ToolCall] = []
        juniors: dict[Family, JrManager] = {}
        for number, requirement in enumerate(requirements, start=1):
            junior = juniors.setdefault(
                requirement.kind, JrManager(requirement.kind, backend, self.grounder, self.call_timeout_s)
            )
            call, steps = junior.call(requirement, prompt, context, calls, said, last=number == len(requirements))
            calls.append(call)
            trace += steps
        retries = sum(step.retries for step in trace)
        tokens = sum(step.tokens for step in trace)
        guessed = next((c.args["category"] for c in calls if c.tool == "remove_assets" and "category" in c.args
                        and not said.categories and not said.existing), None)
        if guessed is not None:  # "delete the library": no thing named, the model picked one to take away
            raise PlanningError(f"your words name no kind of thing to remove (the plan guessed "
                                f"{str(guessed).replace('_', ' ')}s); name what should go, e.g. 'remove the bench by the bus stop'")
        question = kind_to_ask(prompt, calls, said, context, self.grounder)
        if question is not None:  # the model picked a kind the words never name: ask, apply nothing
            trace.append(TraceStep(level="llm_planner", input="; ".join(str(c) for c in calls),
                                   output="the request names no kind of thing to add: asking which"))
            return Plan(calls=[], planner=self.name, confidence=MIN_CONFIDENCE, prompt_version=prompt_version(),
                        trace=trace, retries=retries, tokens=tokens, read_as=read_as, question=question)
        trace.append(
            TraceStep(
                level="llm_planner",
                input=f"{self.label}, prompts {prompt_version()}",
                output=f"{len(calls)} call(s), all accepted by a dry run",
                seconds=time.perf_counter() - started,
                retries=retries,
                tokens=tokens,
            )
        )
        confidence = max(MIN_CONFIDENCE, BASE_CONFIDENCE - RETRY_PENALTY * retries)
        return Plan(
            calls=calls,
            planner=self.name,
            confidence=confidence,
            prompt_version=prompt_version(),
            trace=trace,
            retries=retries,
            tokens=tokens,
            read_as=read_as,
        )


def kind_to_ask(
    prompt: str, calls: list[ToolCall], said: RequestNames, context: PlanContext, grounder: Grounder
) -> Question | None:
    """A question when the plan adds a kind of thing the request never names ("somewhere to rest",
    "set-dress the entrance"): the model's pick is a guess, so the kinds nearest the words in meaning
    are offered instead, each as the same plan with that kind, as far as a dry run accepts it. None
    when the request names a kind, or the thing was added the turn before ("two more of them")."""
    at = next((i for i, c in enumerate(calls) if c.tool in _ADDING), None)
    if at is None or said.categories or said.existing:
        return None
    call = calls[at]
    picked = call.args.get("category") or next(iter(call.args.get("categories") or []), None)
    if picked is not None and context.memory.last_added(str(picked)):
        return None
    readings: list[Reading] = []
    for match in grounder.rank(prompt, "category", context.scene, KINDS_LOOKED_AT):
        swapped = [*calls[:at], _of_kind(call, match.name), *calls[at + 1 :]]
        if context.check(swapped) is None:
            readings.append(Reading(text=describe(swapped), calls=swapped, confidence=max(0.0, min(1.0, match.score))))
        if len(readings) == KINDS_OFFERED:
            break
    if not readings:
        return None
    return Question(text="I am not sure what you meant: your words name no kind of thing to add. Which did you mean?",
                    readings=readings)


def _of_kind(call: ToolCall, kind: str) -> ToolCall:
    key, value = ("category", kind) if call.tool == "add_asset" else ("categories", [kind])
    return ToolCall(tool=call.tool, args={**call.args, key: value})


def format_trace(plan: Plan) -> str:
    """Each planning level's input and output, time, retries and tokens, for `--explain`."""
    lines = [
        f"planner {plan.planner}, confidence {plan.confidence:.2f}, "
        f"prompts {plan.prompt_version or '-'}, {plan.retries} retries, {plan.tokens} tokens"
    ]
    for step in plan.trace:
        cost = f"{step.seconds * 1000:.0f} ms"
        if step.retries:
            cost += f", {step.retries} retries"
        if step.tokens:
            cost += f", {step.tokens} tokens"
        lines.append(f"[{step.level}] {cost}")
        for label, text in (("in ", step.input), ("out", step.output)):
            for index, line in enumerate(text.splitlines() or [""]):
                lines.append(f"  {label if index == 0 else '   '}: {line}")
    if plan.calls:
        lines.append("calls:")
        lines += [f"  {call}" for call in plan.calls]
    return "\n".join(lines)


__all__ = ["LlmPlanner", "format_trace", "injection_reason", "kind_to_ask"]
