"""The default planner: independent planners, combined by agreement rather than a fixed order.

The rule planner and the retrieval planner (nearest bank examples, adapted) each plan the
request in milliseconds. When their plans agree (the same calls once defaults are filled in,
or the same dry-run outcome), that is the plan. When they disagree, a candidate that is
clearly surer wins: a retrieval plan below RETRIEVAL_CONFIDENT overrules nothing (the rules'
path below applies), a sure one beats unsure rules; when both are sure the LLM hierarchy is
asked (it is slow, so only then) and a candidate it agrees with wins, unless the model is small
(its few-shot answer echoes the retrieval planner's own examples, so its agreement is no
evidence); failing that the person is asked one short question with the readings in plain
words (`Plan.question`). The losing candidates go in `Plan.alternatives`.
When only the rules can plan it, the old rule applies: a sure rule plan is used, an unsure one
goes to the LLM unless the model is small (SMALL_MODEL_PARAMETERS), whose edits spoil more
unsure rule plans than they repair. When nothing but a small model can plan an edit, its plan is
offered as a reading to confirm, not applied: on the suites such plans were right about as
often as wrong. Which path was taken, and why, is the first trace line.
Before any of this, words no planner reads are respelt in context by the model's likelihoods
(llm/respell.py: "make it snoe"); the plan then carries the request as read (`Plan.read_as`).
"""

from __future__ import annotations

import time
from typing import Any, NamedTuple

from drivetwin.orchestrator.backends import BackendError
from drivetwin.orchestrator.planning.answers import SEARCH_TOOLS
from drivetwin.orchestrator.planning.base import Plan, PlanContext, Planner, PlanningError, Question, Reading, TraceStep
from drivetwin.orchestrator.planning.llm.planner import LlmPlanner
from drivetwin.orchestrator.planning.llm.respell import respell
from drivetwin.orchestrator.planning.readings import canonical, describe, dry_run, same_outcome
from drivetwin.orchestrator.planning.request import Request, read_request
from drivetwin.orchestrator.planning.rules.planner import FULL_CONFIDENCE, GUESS_PENALTY
from drivetwin.orchestrator.planning.rules.spelling import Repaired
from drivetwin.orchestrator.planning.scenario_reading import describes_behaviour_over_time
from drivetwin.orchestrator.transaction import TransactionResult

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
# Below this (three unknown words, or guesses beside unknown words), a rule plan that edits is
# offered as a reading to confirm, never applied: on the practice suites' final runs (1147638 to
# 7bc113f) none of the 11 such fast-path edits passed and 3 were wrong edits.
RULES_TOO_UNSURE = 0.33
# A retrieval plan this sure (similarity less its slot penalties) stands on its own: the
# nearest example is a close paraphrase and every name in the request found its place.
RETRIEVAL_CONFIDENT = 0.85
# Below this, a retrieval plan is not offered as a reading to choose from.
RETRIEVAL_READING = 0.45
# The rule planner's name, which leads the hybrid's path log (see _candidate).
RULES_PLANNER = "rules"
# Readings offered in a clarifying question (the interface allows 1-3).
MAX_READINGS = 3


class Candidate(NamedTuple):
    """One planner's plan and its dry run, why (for the path log), and a plan the dry run refused."""

    plan: Plan | None
    run: TransactionResult | None
    why: str
    refused: Plan | None = None


class HybridPlanner:
    """Rules, retrieval and (when needed) the LLM hierarchy, combined by agreement."""

    name = "hybrid"

    def __init__(
        self,
        rules: Planner,
        llm: LlmPlanner,
        confident: float | None = None,
        fallback: float = RULES_FALLBACK,
        retrieval: Planner | None = None,
        scenario: Planner | None = None,
        respell: bool = True,
    ) -> None:
        """`confident`: how sure a rule plan must be to skip the LLM; None: by the model's size.
        `retrieval`: the second independent planner; None plans with rules and LLM only."""
        self.rules = rules
        self.llm = llm
        self.retrieval = retrieval
        # Tried first on words that describe behaviour over time (scenario_reading's predicate).
        self.scenario = scenario
        self.confident = confident
        # Words no planner reads are respelt in context by the LLM's likelihoods first.
        self.respell = respell
        self.fallback = fallback
        self._small: bool | None = None

    def confidence_needed(self) -> float:
        """The rule confidence that skips the LLM: as given, else by the model's size (a small
        or unknown-size model is asked about its size once, which opens it)."""
        if self.confident is not None:
            return self.confident
        return RULES_CONFIDENT_SMALL_MODEL if self.small_model() else RULES_CONFIDENT

    def small_model(self) -> bool:
        """Whether the LLM is below SMALL_MODEL_PARAMETERS (asked once, which opens it)."""
        if self._small is None:
            try:
                parameters = self.llm.backend.describe().parameters
            except Exception:  # a model that cannot say its size is not assumed small
                parameters = None
            self._small = parameters is not None and parameters < SMALL_MODEL_PARAMETERS
        return self._small

    def _needed(self, confidence: float) -> float:
        if self.confident is None and confidence >= RULES_CONFIDENT:
            return RULES_CONFIDENT  # sure enough whatever the model: no need to open it
        return self.confidence_needed()

    def _candidate(self, planner: Planner, prompt: str, context: PlanContext) -> Candidate:
        try:
            plan = planner.plan(prompt, context)
        except PlanningError as exc:
            return Candidate(None, None, f"{planner.name} could not plan it ({exc})")
        if not plan.calls:
            return Candidate(plan, None, f"{planner.name}: no calls")
        outcome = dry_run(plan.calls, context.registry, context.scene)
        if isinstance(outcome, str):
            return Candidate(None, None, f"a dry run refused the {planner.name} plan: {outcome}", plan)
        return Candidate(plan, outcome, f"{planner.name} confidence {plan.confidence:.2f}")

    def agree(self, a: Plan, a_run: TransactionResult | None, b: Plan, b_run: TransactionResult | None, context: PlanContext) -> bool:
        """Whether two candidates mean the same: equal calls up to defaults, or equal outcomes."""
        if canonical(a.calls, context.registry) == canonical(b.calls, context.registry):
            return True
        return a_run is not None and b_run is not None and same_outcome(a_run, b_run)

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        """The agreed plan, a clearly surer one, the LLM's tie-break, or a clarifying question,
        for the request with the words no planner reads respelt in context (when the model can
        score text)."""
        started = time.perf_counter()
        respelt = self._respelt(prompt, context)
        if respelt is None:
            return self._plan(prompt, context)
        step = TraceStep(level="respell", input=prompt, output="; ".join(respelt.repairs),
                         seconds=time.perf_counter() - started)
        plan = self._plan(respelt.text, context)
        # Each word respelt is a guess, as each the rule planner repairs is (rules/planner.py).
        sure = max(0.0, plan.confidence - GUESS_PENALTY * len(respelt.repairs)) if plan.calls else plan.confidence
        return plan.model_copy(update={"read_as": respelt.text, "confidence": sure,
                                       "trace": [*plan.trace[:1], step, *plan.trace[1:]]})

    def _respelt(self, prompt: str, context: PlanContext) -> Repaired | None:
        """The request respelt by the model's likelihoods, or None when nothing was respelt or
        the backend cannot score text (a server: the planners read the words as typed)."""
        if not self.respell or not isinstance(self.llm, LlmPlanner):
            return None  # a stand-in for the LLM (a test's) has no model to ask

        def score(texts: list[str]) -> list[float]:  # opens the model only for a word to judge
            return self.llm.backend.log_likelihoods(texts)

        try:
            respelt = respell(prompt, context.scene, score)
        except (BackendError, PlanningError):  # no scoring backend, or no model to open
            return None
        return respelt if respelt.repairs else None

    def _plan(self, prompt: str, context: PlanContext) -> Plan:
        started = time.perf_counter()
        if self.scenario is not None and describes_behaviour_over_time(prompt, context.scene):
            read, _, read_why, _ = self._candidate(self.scenario, prompt, context)
            if read is not None and (read.calls or read.question is not None):
                return self._mark(read, "scenario", started, read_why)
        rule_plan, rule_run, rule_why, rules_refused = self._candidate(self.rules, prompt, context)
        if self.retrieval is None:
            return self._rules_then_llm(prompt, context, rule_plan, rule_why, started)
        found, found_run, found_why, _ = self._candidate(self.retrieval, prompt, context)
        why = f"{rule_why}; {found_why}"
        if rules_refused is not None and rules_refused.confidence >= RULES_CONFIDENT and (
                found is None or found.confidence < RETRIEVAL_CONFIDENT):
            # Every word read and the world says no ("a ring of cones round the tree": cones stand
            # on paving): its reason is the answer, not another planner's guess at something else.
            raise PlanningError(_not_understood(rule_why))
        if rule_plan is None or found is None or not rule_plan.calls or not found.calls:
            if rule_plan is not None:
                return self._rules_then_llm(prompt, context, rule_plan, why, started, [found] if found else [])
            if found is not None and found.confidence >= RETRIEVAL_CONFIDENT:
                return self._mark(found, "retrieval", started, f"{why}; retrieval alone is sure")
            return self._llm_or_ask(prompt, context, [found] if found else [], why, started, rule_why)
        if self.agree(rule_plan, rule_run, found, found_run, context):
            best = rule_plan.model_copy(update={"confidence": max(rule_plan.confidence, found.confidence)})
            return self._mark(best, "agree", started, f"{why}; rules and retrieval agree")
        rules_sure = rule_plan.confidence >= RULES_CONFIDENT
        why = f"{why}; rules read {describe(rule_plan.calls)!r}, retrieval {describe(found.calls)!r}"
        if rule_plan.confidence < FULL_CONFIDENCE and found.confidence >= RETRIEVAL_READING and _opposed(rule_plan, found) \
                and _fits_the_mood(found, read_request(prompt, context.scene)):
            # a word the rules could not read, and the two do opposite things, retrieval's as the words ask ("could you
            # add an SUV ...?" read as a look-up, "tek out di stop sign" as an addition): which is the person's to say
            return self._ask([rule_plan, found], f"{why}; they do opposite things and the rules missed a word", started)
        if found.confidence < RETRIEVAL_CONFIDENT:  # an unsure retrieval plan overrules nothing
            return self._rules_then_llm(prompt, context, rule_plan, f"{why}; they disagree", started, [found])
        if not rules_sure:
            return self._mark(
                found, "retrieval", started, f"{why}; they disagree, retrieval clearly surer", [rule_plan]
            )
        return self._llm_or_ask(prompt, context, [rule_plan, found], f"{why}; they disagree, both sure", started)

    def _rules_then_llm(
        self,
        prompt: str,
        context: PlanContext,
        rule_plan: Plan | None,
        why: str,
        started: float,
        others: list[Plan] | None = None,
    ) -> Plan:
        """Only the rules could plan it: the sure rule plan, else the LLM, else a fallback."""
        if rule_plan is not None and _edits(rule_plan) and rule_plan.confidence < RULES_TOO_UNSURE and self.confident is None:
            # three or more words it could not read: a reading to confirm, whatever the model's size
            return self._ask([rule_plan, *(o for o in others or [] if o.calls)], f"{why}; rules too unsure to edit", started)
        if rule_plan is not None and (
            not rule_plan.calls or rule_plan.confidence >= (needed := self._needed(rule_plan.confidence))
        ):
            return self._mark(rule_plan, "fast", started, f"{why}; rules plan used", others)
        if rule_plan is not None:
            why = f"{why}; rules confidence {rule_plan.confidence:.2f} < {needed}"
        try:
            llm_plan = self.llm.plan(prompt, context)
        except PlanningError as exc:
            if rule_plan is not None and rule_plan.confidence >= self.fallback:
                return self._mark(rule_plan, "fallback", started, f"{why}; the LLM failed ({exc}); using the rule plan")
            raise PlanningError(f"{exc} (rule planner: {why})") from exc
        rule_steps = rule_plan.trace if rule_plan is not None else []
        if rule_plan is None and self.small_model() and _edits(llm_plan):
            return self._ask([llm_plan], f"{why}; only the small LLM could plan it", started)
        return self._mark(llm_plan, "llm", started, why, [p for p in [rule_plan] if p is not None], rule_steps)

    def _llm_or_ask(
        self, prompt: str, context: PlanContext, candidates: list[Plan], why: str, started: float, rules_said: str = ""
    ) -> Plan:
        """Candidates that disagree (or none sure): the LLM's plan breaks the tie, else ask;
        `rules_said`: why the rule planner had no plan, for the refusal when nothing fits."""
        llm_plan: Plan | None = None
        if candidates and self.small_model():
            # A small model's answer copies its few-shot demonstrations, which are the retrieval
            # planner's own nearest examples: no independent vote, for seconds of CPU. The
            # person chooses between the candidates instead.
            why = f"{why}; the LLM is too small to break the tie"
        else:
            try:
                llm_plan = self.llm.plan(prompt, context)
            except PlanningError as exc:
                why = f"{why}; the LLM failed ({exc})"
        if llm_plan is not None:
            llm_run = dry_run(llm_plan.calls, context.registry, context.scene)
            for candidate in candidates:
                run = dry_run(candidate.calls, context.registry, context.scene)
                if self.agree(
                    candidate,
                    None if isinstance(run, str) else run,
                    llm_plan,
                    None if isinstance(llm_run, str) else llm_run,
                    context,
                ):
                    others = [c for c in candidates if c is not candidate]
                    return self._mark(
                        candidate, "tie-break", started, f"{why}; the LLM agrees with {candidate.planner}", others
                    )
            if not candidates and not (self.small_model() and _edits(llm_plan)):
                return self._mark(llm_plan, "llm", started, why)
            if not candidates:  # a small model's guess at what nothing else could read: it is asked
                why = f"{why}; only the small LLM could plan it"
            candidates = [*candidates, llm_plan]
        request = read_request(prompt, context.scene)
        # a retrieval reading that does what the words do not ask ("move the bench ..." read as a removal) is no offer
        readings = [
            c for c in candidates
            if c.calls and (c.planner != "retrieval" or (c.confidence >= RETRIEVAL_READING and _may_be_offered(c, request)))
        ]
        if not readings:
            raise PlanningError(_not_understood(rules_said))
        return self._ask(readings, why, started)

    def _ask(self, readings: list[Plan], why: str, started: float) -> Plan:
        """One short question offering `readings` (the first MAX_READINGS) in plain words."""
        question = Question(
            text="I am not sure what you mean. Did you mean:",
            readings=[Reading(text=describe(c.calls), calls=c.calls, confidence=c.confidence) for c in readings[:MAX_READINGS]],
        )
        step = TraceStep(
            level="hybrid", input="path: ask", output=f"{why}; asking", seconds=time.perf_counter() - started
        )
        return Plan(
            calls=[], planner=self.name, confidence=0.0, question=question, trace=[step], alternatives=question.readings
        )

    def _mark(
        self,
        plan: Plan,
        path: str,
        started: float,
        why: str,
        others: list[Plan] | None = None,
        before: list[TraceStep] | None = None,
    ) -> Plan:
        step = TraceStep(level="hybrid", input=f"path: {path}", output=why, seconds=time.perf_counter() - started)
        alternatives = [Reading(text=describe(o.calls), calls=o.calls) for o in others or [] if o.calls]
        return plan.model_copy(
            update={
                "planner": self.name,
                "trace": [step, *(before or []), *plan.trace],
                "prompt_version": _version(plan, path),
                "alternatives": [*plan.alternatives, *alternatives],
            }
        )


def _edits(plan: Plan) -> bool:
    """Whether the plan would change the scene (a search changes nothing, so needs no confirming)."""
    return any(c.tool not in SEARCH_TOOLS for c in plan.calls)


def _opposed(one: Plan, other: Plan) -> bool:
    """Whether two plans do opposite things: one only looks up what the other changes, or one only
    adds where the other only removes."""
    kinds = {_kind_of(one), _kind_of(other)}
    return kinds in ({"look", "add"}, {"look", "remove"}, {"look", "change"}, {"add", "remove"})


def _fits_the_mood(plan: Plan, request: Request) -> bool:
    """Whether the plan does what the words' mood and polarity ask: a look-up for a question, a change
    for a command, and an addition or a removal only where the words say which ("that truck has left"
    says neither: its removal read by the rules stands against an addition)."""
    kind = _kind_of(plan)
    return _may_be_offered(plan, request) and (kind not in ("add", "remove") or kind == request.polarity)


def _may_be_offered(plan: Plan, request: Request) -> bool:
    """Whether a reading may be offered for the person to choose: a look-up only for a question, a change only
    for a command, a removal only where the words say one ("move the bench ..." read as a removal is none), an
    addition unless they say a removal ("stick a sign up near the gate" says neither: an addition may be offered)."""
    kind = _kind_of(plan)
    if (kind == "look") != request.question:
        return False
    return not ((kind == "remove" and request.polarity != "remove") or (kind == "add" and request.polarity == "remove"))


def _kind_of(plan: Plan) -> str:
    edits = [c.tool for c in plan.calls if c.tool not in SEARCH_TOOLS]
    if not edits:
        return "look"
    if all(t in ("add_asset", "arrange_assets") for t in edits):
        return "add"
    return "remove" if all(t == "remove_assets" for t in edits) else "change"


def _not_understood(rules_said: str) -> str:
    """The refusal a person reads: what the rule planner could not read (or why the world
    refused its plan), which says what is possible, rather than the log of every planner tried."""
    cannot = f"{RULES_PLANNER} could not plan it ("
    if rules_said.startswith(cannot) and rules_said.endswith(")"):
        return rules_said[len(cannot) : -1]
    refused = f"a dry run refused the {RULES_PLANNER} plan: "
    if rules_said.startswith(refused):
        return "I could not do it: " + rules_said[len(refused) :]
    return "I did not understand the request; say what to add, move, remove or change, and where"


def _version(plan: Plan, path: str) -> str | None:
    # The LLM path's prompts are the versioned files; the rule path names the rule set.
    return plan.prompt_version if path == "llm" else f"{plan.prompt_version or 'rules'}"


def make_hybrid(**options: Any) -> HybridPlanner:
    """The hybrid planner: rules, retrieval and an LLM hierarchy on `options`' backend;
    option `rules_confident` fixes the hand-off threshold (default: by the model's size)."""
    from drivetwin.orchestrator.planning.retrieval import RetrievalPlanner
    from drivetwin.orchestrator.planning.rules.planner import RulePlanner
    from drivetwin.orchestrator.planning.scenario_reading import ScenarioReader

    confident = options.pop("rules_confident", None)
    return HybridPlanner(RulePlanner(), make_llm(**options), confident=confident, retrieval=RetrievalPlanner(),
                         scenario=ScenarioReader())


def make_llm(**options: Any) -> LlmPlanner:
    """The LLM hierarchy: options backend (name or Backend), model, and backend options."""
    return LlmPlanner(**options)


__all__ = [
    "RETRIEVAL_CONFIDENT",
    "RULES_CONFIDENT",
    "SMALL_MODEL_PARAMETERS",
    "HybridPlanner",
    "make_hybrid",
    "make_llm",
]
