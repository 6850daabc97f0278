"""Retrieval: nearest bank examples by MiniLM, adapted to the request's own names and numbers."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from drivetwin.orchestrator.planning import PlanContext, PlanningError, make_planner
from drivetwin.orchestrator.planning.grounding import Grounder
from drivetwin.orchestrator.planning.llm.demos import jr_demos
from drivetwin.orchestrator.planning.llm.sr_manager import SR_EXAMPLES, SrManager
from drivetwin.orchestrator.planning.retrieval import BankIndex, RetrievalPlanner, bank_index, learn
from drivetwin.orchestrator.planning.retrieval.slots import adapt, read_slots
from drivetwin.prompts.templates import sr_examples
from drivetwin.tools import ToolRegistry
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.defaults import load_world
from drivetwin.worlds.scene import Scene


@pytest.fixture(scope="module")
def world() -> Scene:
    return load_world("campus")


@pytest.fixture
def context(world: Scene) -> PlanContext:
    return PlanContext(scene=world.model_copy(deep=True), registry=ToolRegistry.default(plugins=False))


def test_slots_are_read_in_order_with_units_typos_and_clock_times(world: Scene) -> None:
    slots = read_slots("put 4 bycicles 12 metres behind the fountain at 18:30, going 36 km/h", world)
    assert slots.found == [
        ("count", 4),
        ("category", "bicycle"),
        ("distance", 12.0),
        ("relation", "behind"),
        ("place", "fountain"),
        ("time", "18:30"),
        ("speed", 10.0),
    ]


def test_adapting_puts_the_requests_names_in_place_of_the_examples(world: Scene) -> None:
    example = [
        ToolCall(
            tool="add_asset",
            args={"category": "bench", "count": 3, "location": {"relation": "next_to", "target": "fountain"}},
        )
    ]
    fitted = adapt(example, read_slots("five traffic cones near the library", world), world)
    assert fitted.calls[0].args == {
        "category": "traffic_cone",
        "count": 5,
        "location": {"relation": "next_to", "target": "Library entrance"},
    }
    assert (fitted.unfilled, fitted.unused) == (0, 0)


def test_an_unsaid_count_is_left_to_the_tools_default(world: Scene) -> None:
    example = [
        ToolCall(
            tool="add_asset",
            args={"category": "bench", "count": 3, "location": {"relation": "at", "target": "fountain"}},
        )
    ]
    fitted = adapt(example, read_slots("a bench at the bus stop", world), world)
    assert "count" not in fitted.calls[0].args and (fitted.dropped, fitted.unfilled) == (1, 0)


def test_the_nearest_examples_are_close_in_meaning(world: Scene) -> None:
    hits = bank_index(world).nearest("could we get some snow falling", 5)
    assert hits[0].similarity > 0.6
    assert any(c.tool == "set_weather" and c.args.get("kind") == "snow" for h in hits[:3] for c in h.example.calls)


def test_a_description_finds_its_category_through_the_bank(context: PlanContext) -> None:
    plan = RetrievalPlanner().plan("add a portable road work ahead sign by the library", context)
    assert plan.calls[0].tool == "add_asset" and plan.calls[0].args["category"] == "construction_sign"


def test_a_negated_want_becomes_a_removal(context: PlanContext) -> None:
    plan = RetrievalPlanner().plan("honestly I do not want any of the trees anymore", context)
    assert [c.tool for c in plan.calls] == ["remove_assets"] and plan.calls[0].args.get("category") == "tree"


def test_a_question_plans_a_search_not_an_edit(context: PlanContext) -> None:
    plan = RetrievalPlanner().plan("how many fire hydrants have we got", context)
    assert plan.calls[0].tool == "find_assets" and plan.calls[0].args["category"] == "fire_hydrant"


def test_confidence_falls_when_slots_are_left_unfilled(context: PlanContext) -> None:
    sure = RetrievalPlanner().plan("put two benches next to the fountain", context)
    vague = RetrievalPlanner().plan("put two of them next to it", context)
    assert sure.confidence > vague.confidence


def test_an_empty_bank_is_a_planning_error(context: PlanContext) -> None:
    planner = RetrievalPlanner(index=BankIndex([], np.zeros((0, 384), dtype=np.float32)))
    with pytest.raises(PlanningError, match="bank of this world is empty"):
        planner.plan("add a bench", context)


def test_a_learned_request_is_retrieved_from_then_on(
    world: Scene, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, context: PlanContext
) -> None:
    monkeypatch.setenv("DRIVETWIN_CACHE", str(tmp_path))
    calls = [ToolCall(tool="set_lighting", args={"street_lights": "on", "vehicle_lights": "on"})]
    learn(world, "lights everywhere for the party", calls)
    plan = RetrievalPlanner().plan("lights everywhere for the party", context)
    assert plan.calls == calls and plan.confidence > 0.9


def test_retrieval_is_a_planner_by_name() -> None:
    assert make_planner("retrieval").name == "retrieval"


def test_the_sr_manager_is_shown_bank_examples_near_the_request(context: PlanContext) -> None:
    messages = SrManager(None, Grounder()).messages("could the weather turn snowy please", context)  # type: ignore[arg-type]
    shown = [m["content"] for m in messages if m["role"] == "user"][:-1]
    assert len(shown) == SR_EXAMPLES and all(text.startswith("Request: ") for text in shown)
    assert any("snow" in m["content"] for m in messages if m["role"] == "assistant")
    assert not set(shown) & {f"Request: {e.request}" for e in sr_examples()}


def test_a_jr_manager_is_shown_one_call_examples_of_its_own_family(context: PlanContext) -> None:
    demos = jr_demos("add", "drop a couple of benches near the fountain", context, 3)
    assert len(demos) == 3 and all(d.call["tool"] == "add_asset" for d in demos)
    assert all(d.requirement.startswith("add | what: ") for d in demos)


def test_warming_the_bank_in_the_background_leaves_it_ready_for_the_first_prompt(world: Scene) -> None:
    from drivetwin.orchestrator.planning.retrieval import index, warm_bank
    from drivetwin.orchestrator.planning.retrieval.bank import world_key

    thread = warm_bank(world)
    assert thread.daemon and thread.name == "drivetwin-bank-warmup"
    thread.join(timeout=900)
    assert not thread.is_alive() and world_key(world) in index._generated_cache
    assert bank_index(world).nearest("put two benches by the library", k=1)
