"""What the request's words allow the managers to do: a thing said with "the" is the one
already there, a thing said with "a" or an amount is new, a request with no distance, way,
speed or behaviour is no move, only a question is a search, and a request about something
happening over time is planned with the storyboard's tools and the manoeuvres it names."""

from __future__ import annotations

from typing import Any

import pytest
from drivetwin.orchestrator.planning.base import PlanContext
from drivetwin.orchestrator.planning.grounding import Grounder
from drivetwin.orchestrator.planning.llm.jr_manager import JrManager, ground_requirement
from drivetwin.orchestrator.planning.llm.jr_schema import call_schema
from drivetwin.orchestrator.planning.llm.managers import Requirement
from drivetwin.orchestrator.planning.llm.request_names import read_names
from drivetwin.orchestrator.planning.retrieval.slots import read_slots
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.scene import Scene

from .conftest import ScriptedBackend


def _offered(prompt: str, need: Requirement, campus: Scene, grounder: Grounder) -> dict[str, dict[str, Any]]:
    """Each tool the Jr. manager for `need` may call, with the argument schema it decodes with."""
    context = PlanContext(campus, ToolRegistry.default(plugins=False))
    grounding = ground_requirement(need, prompt, context, grounder)
    junior = JrManager(need.kind, ScriptedBackend([]), grounder)
    schema = call_schema(junior.offered(grounding, context), grounding.names)
    return {o["properties"]["tool"]["const"]: o["properties"]["args"] for o in schema.get("anyOf", [schema])}


def test_a_thing_said_with_the_is_the_one_there_as_the_thing_acted_on_or_as_the_place(campus: Scene) -> None:
    said = read_names("could you stand the trash bin right beside the bench", campus)
    assert said.assets == ("trash_bin_1",)
    assert said.places == ("bench_1",)
    assert "add" not in said.kinds()


def test_one_of_several_things_said_with_the_is_one_already_there_never_a_new_one(campus: Scene) -> None:
    said = read_names("shift the tree by the bus stop across to the library", campus)
    assert said.existing == ("tree",)
    assert "add" not in said.kinds()


@pytest.mark.parametrize("prompt", ["a pair of motorbikes waiting in lot B", "two buses by the main gate please"])
def test_things_said_with_a_or_an_amount_are_new(campus: Scene, prompt: str) -> None:
    kinds = read_names(prompt, campus).kinds()
    assert "add" in kinds
    assert not {"position", "move", "search"} & set(kinds)


def test_a_verb_that_acts_on_things_there_keeps_one_of_them_possible(campus: Scene) -> None:
    assert "position" in read_names("move a car over to lot A", campus).kinds()


@pytest.mark.parametrize("prompt", ["relocate the stop sign to the east gate", "the SUV belongs over at the main gate"])
def test_no_distance_way_speed_or_behaviour_said_is_no_move(campus: Scene, prompt: str) -> None:
    said = read_names(prompt, campus)
    assert said.directions == ()  # "east gate" names a place, it says no way to go
    assert "move" not in said.kinds()
    assert "position" in said.kinds()


def test_a_statement_that_asks_nothing_is_never_only_looked_up(campus: Scene) -> None:
    assert "search" not in read_names("I'd like somewhere to rest outside the Library doors", campus).kinds()
    assert read_names("anyone walking about near the fountain?", campus).kinds() == ["search"]


def test_a_real_word_is_not_read_as_a_slip_for_a_near_name(campus: Scene) -> None:
    assert ("category", "ackermann_robot") not in read_slots("shift the SUV over to the main gate", campus).found
    assert ("category", "bench") in read_slots("add a benchh by the fountain", campus).found


def test_something_over_time_is_planned_with_the_storyboard_and_the_manoeuvre_named(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    prompt = "have the ego brake 4 seconds in"
    said = read_names(prompt, campus)
    assert said.over_time and said.kinds() == ["move"]
    offered = _offered(prompt, Requirement(kind="move", what="ego"), campus, spelling_grounder)
    assert set(offered) == {"add_event", "add_manoeuvre"}  # no light is named: no light's phases
    manoeuvre = offered["add_manoeuvre"]["properties"]["manoeuvre"]["properties"]
    assert manoeuvre["kind"]["enum"] == ["stop"]
    assert "side" not in manoeuvre and "name" not in offered["add_event"]["properties"]
    # the actor is a thing that moves, never a free name ("lead_car_1") nor a sign
    actor = offered["add_manoeuvre"]["properties"]["actor"]["enum"]
    assert "ego" in actor and "stop_sign_1" not in actor and "bench_1" not in actor


def test_a_light_named_is_offered_its_phases(campus: Scene, spelling_grounder: Grounder) -> None:
    prompt = "make traffic light 1 stay red for 30 s"
    offered = _offered(prompt, Requirement(kind="move", what="traffic light 1"), campus, spelling_grounder)
    assert offered["set_light_phases"]["properties"]["light"]["enum"] == ["traffic_light_1"]
