"""The hybrid planner combines independent planners by agreement, and asks when they disagree.

The candidates here are fixed plans (the hybrid's decisions are the subject); the last tests
run the real rule and retrieval planners."""

from __future__ import annotations

from typing import Any

import pytest
from drivetwin.orchestrator.planning import Plan, PlanContext, PlanningError
from drivetwin.orchestrator.planning.hybrid import HybridPlanner
from drivetwin.orchestrator.planning.llm.planner import LlmPlanner
from drivetwin.orchestrator.planning.retrieval import RetrievalPlanner
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.tools import ToolRegistry
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.defaults import load_world

RAIN = [ToolCall(tool="set_weather", args={"kind": "rain", "intensity": 0.6})]
SNOW = [ToolCall(tool="set_weather", args={"kind": "snow"})]
TREES_BY_CATEGORY = [ToolCall(tool="remove_assets", args={"category": "tree"})]
TREES_BY_ID = [ToolCall(tool="remove_assets", args={"assets": ["tree_1", "tree_2", "tree_3", "tree_4"]})]


class Fixed:
    """A planner that always answers the same plan (or fails)."""

    def __init__(self, name: str, calls: list[ToolCall] | None, confidence: float = 0.9) -> None:
        self.name, self.calls, self.confidence = name, calls, confidence
        self.asked = 0

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        self.asked += 1
        if self.calls is None:
            raise PlanningError(f"{self.name} cannot")
        return Plan(calls=self.calls, planner=self.name, confidence=self.confidence)


@pytest.fixture
def context() -> PlanContext:
    return PlanContext(scene=load_world("campus"), registry=ToolRegistry.default(plugins=False))


def hybrid(rules: Fixed, retrieval: Fixed, llm: Any) -> HybridPlanner:
    return HybridPlanner(rules, llm, retrieval=retrieval)


def path(plan: Plan) -> str:
    return plan.trace[0].input


def test_candidates_with_the_same_calls_agree_and_the_llm_is_not_asked(context: PlanContext) -> None:
    llm = Fixed("llm", SNOW)
    plan = hybrid(Fixed("rules", RAIN, 0.6), Fixed("retrieval", RAIN, 0.5), llm).plan("wet please", context)
    assert path(plan) == "path: agree" and plan.calls == RAIN and llm.asked == 0


def test_candidates_with_the_same_dry_run_outcome_agree(context: PlanContext) -> None:
    plan = hybrid(Fixed("rules", TREES_BY_CATEGORY), Fixed("retrieval", TREES_BY_ID), Fixed("llm", None)).plan(
        "no trees", context
    )
    assert path(plan) == "path: agree"


def test_a_clearly_surer_candidate_wins_and_the_other_is_an_alternative(context: PlanContext) -> None:
    plan = hybrid(Fixed("rules", RAIN, 0.95), Fixed("retrieval", SNOW, 0.5), Fixed("llm", None)).plan("x", context)
    assert plan.calls == RAIN and [r.calls for r in plan.alternatives] == [SNOW]
    # the trace says what each planner read, so a run's records show what the loser proposed
    assert "rules read 'weather rain" in plan.trace[0].output and "retrieval 'weather snow" in plan.trace[0].output


def test_the_llm_breaks_a_tie_between_two_sure_candidates(context: PlanContext) -> None:
    llm = Fixed("llm", SNOW)
    plan = hybrid(Fixed("rules", RAIN, 0.9), Fixed("retrieval", SNOW, 0.9), llm).plan("x", context)
    assert path(plan) == "path: tie-break" and plan.calls == SNOW and llm.asked == 1


class SmallModel(Fixed):
    """An LLM that says it has 135M parameters, like the embedded SmolLM2."""

    class backend:  # the attribute the hybrid reads
        @staticmethod
        def describe() -> Any:
            return type("Facts", (), {"parameters": 135_000_000})()


def test_a_small_model_breaks_no_tie_the_person_chooses(context: PlanContext) -> None:
    llm = SmallModel("llm", SNOW)
    plan = hybrid(Fixed("rules", RAIN, 0.9), Fixed("retrieval", SNOW, 0.9), llm).plan("x", context)
    assert plan.calls == [] and plan.question is not None and llm.asked == 0
    assert [r.calls for r in plan.question.readings] == [RAIN, SNOW]


def test_a_small_models_edit_that_nothing_else_could_plan_is_offered_to_confirm(context: PlanContext) -> None:
    llm = SmallModel("llm", SNOW)
    plan = hybrid(Fixed("rules", None), Fixed("retrieval", None), llm).plan("x", context)
    assert path(plan) == "path: ask" and plan.calls == [] and llm.asked == 1
    assert plan.question is not None and [r.calls for r in plan.question.readings] == [SNOW]


def test_a_small_models_search_that_nothing_else_could_plan_is_answered(context: PlanContext) -> None:
    lookup = [ToolCall(tool="find_assets", args={"category": "tree"})]
    plan = hybrid(Fixed("rules", None), Fixed("retrieval", None), SmallModel("llm", lookup)).plan("x", context)
    assert path(plan) == "path: llm" and plan.calls == lookup


def test_a_large_models_plan_of_what_nothing_else_could_plan_is_used(context: PlanContext) -> None:
    plan = hybrid(Fixed("rules", None), Fixed("retrieval", None), Fixed("llm", SNOW)).plan("x", context)
    assert path(plan) == "path: llm" and plan.calls == SNOW


def test_disagreement_nobody_settles_becomes_a_question_with_plain_readings(context: PlanContext) -> None:
    plan = hybrid(Fixed("rules", RAIN, 0.9), Fixed("retrieval", SNOW, 0.9), Fixed("llm", None)).plan("x", context)
    assert plan.calls == [] and plan.question is not None
    assert [r.text for r in plan.question.readings] == ["weather rain (intensity 0.6)", "weather snow"]
    assert [r.calls for r in plan.question.readings] == [RAIN, SNOW]


def test_a_sure_retrieval_plan_stands_when_the_rules_cannot_plan(context: PlanContext) -> None:
    plan = hybrid(Fixed("rules", None), Fixed("retrieval", SNOW, 0.9), Fixed("llm", None)).plan("x", context)
    assert path(plan) == "path: retrieval" and plan.calls == SNOW


def test_a_refused_candidate_does_not_count(context: PlanContext) -> None:
    refused = [ToolCall(tool="remove_assets", args={"assets": ["no_such_thing"]})]
    plan = hybrid(Fixed("rules", RAIN, 0.9), Fixed("retrieval", refused, 0.99), Fixed("llm", None)).plan("x", context)
    assert plan.calls == RAIN


def test_real_rules_and_retrieval_agree_on_a_plain_request(context: PlanContext) -> None:
    planner = HybridPlanner(RulePlanner(), LlmPlanner(model="no-such-model"), retrieval=RetrievalPlanner())
    plan = planner.plan("make it snow", context)
    assert path(plan) == "path: agree" and plan.calls[0].tool == "set_weather"
    assert plan.calls[0].args["kind"] == "snow"


def test_a_rule_edit_read_past_three_unknown_words_is_offered_to_confirm(context: PlanContext) -> None:
    llm = SmallModel("llm", SNOW)
    plan = hybrid(Fixed("rules", RAIN, 0.2), Fixed("retrieval", None), llm).plan("x", context)
    assert path(plan) == "path: ask" and plan.calls == [] and llm.asked == 0
    assert plan.question is not None and [r.calls for r in plan.question.readings] == [RAIN]
    # a little surer, it is used as before
    plan = hybrid(Fixed("rules", RAIN, 0.35), Fixed("retrieval", None), llm).plan("x", context)
    assert path(plan) == "path: fast" and plan.calls == RAIN


def test_plans_that_do_opposite_things_are_asked_when_the_rules_missed_a_word(context: PlanContext) -> None:
    look = [ToolCall(tool="find_assets", args={"category": "suv"})]
    add = [ToolCall(tool="add_asset", args={"category": "suv", "location": {"relation": "at", "target": "parking lot A"}})]
    # a word unread (0.80) and a look-up against an addition: which is the person's to say, however unsure retrieval is
    plan = hybrid(Fixed("rules", look, 0.8), Fixed("retrieval", add, 0.6), Fixed("llm", None)).plan("add an SUV in lot A, real quick", context)
    assert path(plan) == "path: ask" and plan.question is not None and len(plan.question.readings) == 2
    # every word read: the rules' plan stands
    plan = hybrid(Fixed("rules", look, 0.95), Fixed("retrieval", add, 0.6), Fixed("llm", None)).plan("where is the SUV", context)
    assert path(plan) == "path: fast" and plan.calls == look
    # an addition against a removal is as opposite; two edits of one kind are not
    stop = [ToolCall(tool="add_asset", args={"category": "stop_sign"})]
    gone = [ToolCall(tool="remove_assets", args={"category": "stop_sign"})]
    assert path(hybrid(Fixed("rules", stop, 0.6), Fixed("retrieval", gone, 0.5), Fixed("llm", None)).plan("get rid of stop sign pls", context)) == "path: ask"
    # words that say neither: the rules' reading stands
    plan = hybrid(Fixed("rules", gone, 0.75), Fixed("retrieval", stop, 0.6), Fixed("llm", None)).plan("that stop sign has left", context)
    assert path(plan) != "path: ask" and plan.calls == gone
    assert path(hybrid(Fixed("rules", RAIN, 0.8), Fixed("retrieval", SNOW, 0.6), Fixed("llm", None)).plan("wet please", context)) == "path: fast"
    # retrieval's reading against the words' mood (a look-up for a command) is no reading to offer
    plan = hybrid(Fixed("rules", add, 0.8), Fixed("retrieval", look, 0.6), Fixed("llm", None)).plan("add an SUV in lot A, real quick", context)
    assert path(plan) == "path: fast" and plan.calls == add


def test_a_retrieval_reading_that_does_what_the_words_do_not_ask_is_no_offer(context: PlanContext) -> None:
    removal = [ToolCall(tool="remove_assets", args={"category": "bench"})]
    moved = [ToolCall(tool="move_asset", args={"asset": "bench_1", "forward": 2.0})]
    with pytest.raises(PlanningError, match="rules cannot"):  # "move" read as a removal: the rules' reason is the answer
        hybrid(Fixed("rules", None), Fixed("retrieval", removal, 0.5), SmallModel("llm", None)).plan("move the bench a bit", context)
    plan = hybrid(Fixed("rules", None), Fixed("retrieval", moved, 0.5), SmallModel("llm", None)).plan("move the bench a bit", context)
    assert path(plan) == "path: ask" and plan.question is not None and [r.calls for r in plan.question.readings] == [moved]
    # words that say neither an addition nor a removal ("stick a sign up"): an addition may still be offered
    sign = [ToolCall(tool="add_asset", args={"category": "stop_sign", "location": {"relation": "at", "target": "main gate"}})]
    plan = hybrid(Fixed("rules", None), Fixed("retrieval", sign, 0.5), SmallModel("llm", None)).plan("stick a sign up near the gate", context)
    assert plan.question is not None and [r.calls for r in plan.question.readings] == [sign]
