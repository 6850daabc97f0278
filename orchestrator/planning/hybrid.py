"""The default planner: rules first, the LLM hierarchy when the rules are unsure.

A plain request ("make it rain") is planned by the rule planner in milliseconds; when its
confidence is at least RULES_CONFIDENT and a dry run accepts its calls, that is the plan
(the fast path, no LLM). A vague or misspelled request ("put some pylons by the big
building") goes to the LLM hierarchy, whose calls are dry-run and retried with the
refusal like any other. Which path was taken, and why, is the first line of the trace.

How unsure the rules may be before the LLM takes over depends on the model: a small model
(under SMALL_MODEL_PARAMETERS) spoils more unsure rule plans than it repairs, so with one the
LLM only gets what the rules cannot plan at all (or what a dry run refuses).
"""

from __future__ import annotations

import time
from typing import Any

from drivetwin.orchestrator.planning.base import Plan, PlanContext, Planner, PlanningError, TraceStep
from drivetwin.orchestrator.planning.llm.planner import LlmPlanner

# Rule plans at least this sure skip the LLM. The rule planner scores 0.95 for a prompt whose
# every content word it knows, 0.15 less per unknown word and 0.2 less per guess (a repaired
# typo, a defaulted amount, an ignored clause): one unknown word is allowed, no guess is.
RULES_CONFIDENT = 0.8
# When the LLM cannot answer, a rule plan at least this sure (and accepted by a dry run)
# is used rather than failing: half-understood beats a dead backend.
RULES_FALLBACK = 0.5
# Measured on the full eval suite (evals/results): with SmolLM2-135M behind the unsure rule
# plans, the LLM repaired 3 of the 30 that failed and spoiled 55 of the 72 that passed.
# Below this many parameters, an accepted rule plan is kept however unsure it is.
SMALL_MODEL_PARAMETERS = 1_000_000_000
RULES_CONFIDENT_SMALL_MODEL = 0.0


class HybridPlanner:
    """Rule planner fast path, LLM hierarchy slow path; a Planner the eval harness can name."""

    name = "hybrid"

    def __init__(
        self,
        rules: Planner,
        llm: LlmPlanner,
        confident: float | None = None,
        fallback: float = RULES_FALLBACK,
    ) -> None:
        """`confident`: how sure a rule plan must be to skip the LLM; None: by the model's size."""
        self.rules = rules
        self.llm = llm
        self.confident = confident
        self.fallback = fallback
        self._by_model_size: float | None = None

    def confidence_needed(self) -> float:
        """The rule confidence that skips the LLM: as given, else by the model's size (a small
        or unknown-size model is asked about its size once, which opens it)."""
        if self.confident is not None:
            return self.confident
        if self._by_model_size is None:
            try:
                parameters = self.llm.backend.describe().parameters
            except Exception:  # a model that cannot say its size is not assumed small
                parameters = None
            small = parameters is not None and parameters < SMALL_MODEL_PARAMETERS
            self._by_model_size = RULES_CONFIDENT_SMALL_MODEL if small else RULES_CONFIDENT
        return self._by_model_size

    def _needed(self, confidence: float) -> float:
        if self.confident is None and confidence >= RULES_CONFIDENT:
            return RULES_CONFIDENT  # sure enough whatever the model: no need to open it
        return self.confidence_needed()

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        """The rule plan when it is sure and accepted, else the LLM plan (or a rule fallback)."""
        started = time.perf_counter()
        rule_plan: Plan | None = None
        why: str
        try:
            rule_plan = self.rules.plan(prompt, context)
        except PlanningError as exc:
            why = f"rules could not plan it ({exc})"
        else:
            refusal = context.check(rule_plan.calls) if rule_plan.calls else None
            if refusal is not None:
                why = f"a dry run refused the rule plan: {refusal}"
                rule_plan = None
            elif rule_plan.confidence >= (needed := self._needed(rule_plan.confidence)):
                return self._mark(rule_plan, "fast", started, f"rules confidence {rule_plan.confidence:.2f} >= {needed}")
            else:
                why = f"rules confidence {rule_plan.confidence:.2f} < {needed}"
        try:
            llm_plan = self.llm.plan(prompt, context)
        except PlanningError as exc:
            if rule_plan is not None and rule_plan.confidence >= self.fallback:
                return self._mark(rule_plan, "fallback", started, f"{why}; the LLM failed ({exc}); using the rule plan")
            raise PlanningError(f"{exc} (rule planner: {why})") from exc
        rule_steps = rule_plan.trace if rule_plan is not None else []
        return self._mark(llm_plan, "llm", started, why, rule_steps)

    def _mark(self, plan: Plan, path: str, started: float, why: str, before: list[TraceStep] | None = None) -> Plan:
        step = TraceStep(level="hybrid", input=f"path: {path}", output=why, seconds=time.perf_counter() - started)
        return plan.model_copy(
            update={
                "planner": self.name,
                "trace": [step, *(before or []), *plan.trace],
                "prompt_version": _version(plan, path),
            }
        )


def _version(plan: Plan, path: str) -> str | None:
    # The LLM path's prompts are the versioned files; the rule path names the rule set.
    return plan.prompt_version if path == "llm" else f"{plan.prompt_version or 'rules'}"


def make_hybrid(**options: Any) -> HybridPlanner:
    """The hybrid planner with the rule planner and an LLM hierarchy on `options`' backend;
    option `rules_confident` fixes the hand-off threshold (default: by the model's size)."""
    from drivetwin.orchestrator.planning.rules.planner import RulePlanner

    confident = options.pop("rules_confident", None)
    return HybridPlanner(RulePlanner(), make_llm(**options), confident=confident)


def make_llm(**options: Any) -> LlmPlanner:
    """The LLM hierarchy: options backend (name or Backend), model, and backend options."""
    return LlmPlanner(**options)


__all__ = ["RULES_CONFIDENT", "SMALL_MODEL_PARAMETERS", "HybridPlanner", "make_hybrid", "make_llm"]
