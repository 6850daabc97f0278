"""The managers' grammars offer only what the request names, and a plan the review would not
apply goes back to the model once with the review's reasons."""

from __future__ import annotations

from typing import Any

import pytest
from drivetwin.orchestrator.planning.base import PlanContext
from drivetwin.orchestrator.planning.grounding import Grounder
from drivetwin.orchestrator.planning.llm.demos import fits
from drivetwin.orchestrator.planning.llm.jr_manager import ground_requirement
from drivetwin.orchestrator.planning.llm.jr_schema import call_schema
from drivetwin.orchestrator.planning.llm.managers import Requirement
from drivetwin.orchestrator.planning.llm.request_names import read_names
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.scene import Scene

from .conftest import call, requirement, scripted_session


def _args(prompt: str, need: Requirement, campus: Scene, tool: str, grounder: Grounder) -> dict[str, Any]:
    """The argument schema of `tool` that the Jr. manager for `need` would decode with."""
    registry = ToolRegistry.default(plugins=False)
    context = PlanContext(campus, registry)
    names = ground_requirement(need, prompt, context, grounder).names
    schema = call_schema(registry.family(need.kind), names)
    options = schema.get("anyOf", [schema])
    found: dict[str, Any] = next(o["properties"]["args"] for o in options if o["properties"]["tool"]["const"] == tool)
    return found


def _props(args: dict[str, Any]) -> dict[str, Any]:
    properties: dict[str, Any] = args["properties"]
    return properties


def test_a_category_the_request_names_wins_over_the_managers_paraphrase(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    # The Sr. manager wrote "pedestrian sign"; the request said "stop sign".
    need = Requirement(kind="add", what="pedestrian sign", where="north crosswalk")
    args = _args("Add a stop sign at the north crosswalk.", need, campus, "add_asset", spelling_grounder)
    location = _props(_props(args)["location"])
    assert _props(args)["category"]["enum"] == ["stop_sign"]
    assert location["target"]["enum"] == ["north crosswalk"]
    assert location["relation"]["enum"] == ["at"]


def test_a_place_after_a_relation_word_is_the_target_even_when_it_is_an_asset(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    need = Requirement(kind="add", what="buses", where="ahead of parking lot B entrance")
    args = _args("put a buss in front of ego car", need, campus, "add_asset", spelling_grounder)
    location = _props(_props(args)["location"])
    assert location["target"]["enum"] == ["ego"]
    assert location["relation"]["enum"] == ["in_front_of"]


def test_numbers_are_copied_from_the_request_with_the_sign_its_direction_gives(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    need = Requirement(kind="move", what="bench")
    args = _args("slide the bench 1.5 m further south", need, campus, "move_asset", spelling_grounder)
    assert args["properties"]["north"]["enum"] == [-1.5]
    assert not {"east", "forward", "left"} & set(args["properties"])
    assert {"asset", "north"} <= set(args["required"])


def test_fields_the_request_gives_no_words_for_are_not_offered(campus: Scene, spelling_grounder: Grounder) -> None:
    need = Requirement(kind="add", what="stop sign", where="north crosswalk")
    args = _args("Add a stop sign at the north crosswalk.", need, campus, "add_asset", spelling_grounder)
    assert not {"colour", "behaviour", "yaw_deg", "count"} & set(args["properties"])


def test_a_stated_count_must_be_written_and_is_the_only_count_allowed(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    need = Requirement(kind="arrange", what="cones", where="ego", how="line")
    args = _args("Arrange 6 traffic cones in a line in front of the ego.", need, campus, "arrange_assets",
                 spelling_grounder)
    assert args["properties"]["count"] == {"type": "integer", "enum": [6]}
    assert "count" in args["required"]
    assert args["properties"]["shape"]["enum"] == ["line", "parking_row"]


def test_the_request_mood_limits_the_requirement_kinds(campus: Scene) -> None:
    assert read_names("where is the nearest fire hydrant?", campus).kinds() == ["search"]
    assert "search" not in read_names("add a bench by the fountain", campus).kinds()
    assert read_names("wheres the swiming pool", campus).kinds() == ["search"]  # a misspelt question
    assert "add" not in read_names("Place the ego vehicle in main_westbound.", campus).kinds()
    assert "add" not in read_names("I no longer want the trees", campus).kinds()
    assert "remove" not in read_names("put the bench in front of the library", campus).kinds()


def test_the_sr_schema_offers_only_the_kinds_the_mood_allows(campus: Scene, spelling_grounder: Grounder) -> None:
    session, backend = scripted_session(
        campus,
        [requirement("search", "hydrant"), call("find_assets", category="fire_hydrant")],
        spelling_grounder,
    )
    session.submit("where are the fire hydrant and the bus?")  # two clauses: the Sr. manager splits them
    sr_schema = backend.schemas[0]
    assert sr_schema is not None
    assert sr_schema["properties"]["requirements"]["items"]["properties"]["kind"]["enum"] == ["search"]


def test_a_one_clause_question_goes_straight_to_the_search_manager(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    session, backend = scripted_session(campus, [call("find_assets", category="fire_hydrant")], spelling_grounder)
    report = session.submit("where is the fire hydrant?")
    assert report.ok, report.error
    assert backend.calls == 1
    schema = backend.schemas[0]
    assert schema is not None
    assert {o["properties"]["tool"]["const"] for o in schema["anyOf"]} == {"find_assets", "asset_properties"}
    assert report.answer and "fire_hydrant_1" in report.answer


def test_a_plan_the_review_would_not_apply_goes_back_once_with_its_reasons(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    session, backend = scripted_session(
        campus,
        [
            requirement("move", "hydrant"),
            call("move_asset", asset="fire_hydrant_1", north=2.0),  # the request said east
            call("move_asset", asset="fire_hydrant_1", east=2.0),
        ],
        spelling_grounder,
    )
    before = campus.asset("fire_hydrant_1")
    report = session.submit("move the fire hydrant 2 m east")
    assert report.ok, report.error
    hint = backend.seen[2][-1]["content"]
    assert "does not do what the request says" in hint and "east" in hint
    after = session.scene.asset("fire_hydrant_1")
    assert before is not None and after is not None
    assert after.pose.x - before.pose.x == 2.0


def test_the_review_sends_a_plan_back_only_once(campus: Scene, spelling_grounder: Grounder) -> None:
    wrong = call("move_asset", asset="fire_hydrant_1", north=2.0)
    session, backend = scripted_session(campus, [requirement("move", "hydrant"), wrong, wrong], spelling_grounder)
    report = session.submit("move the fire hydrant 2 m east")
    assert backend.calls == 3  # Sr., the first answer, one retry: the second wrong answer is kept
    assert not report.ok  # and the session's own review does not apply it
    assert session.scene.asset("fire_hydrant_1") == campus.asset("fire_hydrant_1")


def test_a_demonstration_is_shown_only_if_this_requests_grammar_allows_its_fields(campus: Scene) -> None:
    registry = ToolRegistry.default(plugins=False)
    names = ground_requirement(
        Requirement(kind="add", what="stop sign", where="north crosswalk"),
        "Add a stop sign at the north crosswalk.",
        PlanContext(campus, registry),
        Grounder(use_embeddings=False),
    ).names
    schema = call_schema(registry.family("add"), names)
    plain = {"tool": "add_asset", "args": {"category": "bench", "location": {"relation": "next_to", "target": "fountain"}}}
    counted = {"tool": "add_asset", "args": {**plain["args"], "count": 2}}  # type: ignore[dict-item]
    coloured = {"tool": "add_asset", "args": {**plain["args"], "colour": "beige"}}  # type: ignore[dict-item]
    assert fits(plain, schema)
    assert not fits(counted, schema) and not fits(coloured, schema)
    assert not fits({"tool": "remove_assets", "args": {"category": "bench"}}, schema)


def test_an_angle_said_is_offered_only_to_a_turn_never_as_metres(campus: Scene, spelling_grounder: Grounder) -> None:
    need = Requirement(kind="move", what="bench")
    props = _props(_args("Turn the bench 90 degrees.", need, campus, "move_asset", spelling_grounder))
    assert props["turn_deg"]["enum"] == [90.0, -90.0]
    assert not {"forward", "left", "east", "north"} & set(props)


def test_a_speed_said_is_offered_only_as_a_speed_never_as_a_count(campus: Scene, spelling_grounder: Grounder) -> None:
    need = Requirement(kind="add", what="car", where="main_westbound", how="driving")
    props = _props(_args("Add a car driving in main_westbound at 6 m/s.", need, campus, "add_asset", spelling_grounder))
    assert "count" not in props
    assert _props(props["behaviour"])["speed"]["enum"] == [6.0]


def test_a_weather_word_is_the_only_weather_offered(campus: Scene, spelling_grounder: Grounder) -> None:
    need = Requirement(kind="appearance", what="skies")
    props = _props(_args("clear skies", need, campus, "set_weather", spelling_grounder))
    assert props["kind"]["enum"] == ["clear"]


@pytest.mark.parametrize(("prompt", "clock"), [("could we have it at 7am please", "07:00"), ("the clock should read 18:30", "18:30")])
def test_a_clock_time_said_is_the_only_time_offered(campus: Scene, spelling_grounder: Grounder, prompt: str, clock: str) -> None:
    need = Requirement(kind="appearance", what="time", how=prompt)
    props = _props(_args(prompt, need, campus, "set_time_of_day", spelling_grounder))
    assert props["time"]["enum"] == [clock]


def test_no_clock_time_said_leaves_every_time_offered(campus: Scene, spelling_grounder: Grounder) -> None:
    need = Requirement(kind="appearance", what="night")
    props = _props(_args("make it night", need, campus, "set_time_of_day", spelling_grounder))
    assert "anyOf" in props["time"]


def test_where_a_path_leads_is_a_name_of_the_world_never_free_words(campus: Scene, spelling_grounder: Grounder) -> None:
    need = Requirement(kind="move", what="suv", where="library", how="drive at 250 km/h")
    props = _props(_args("Make the SUV drive to the library at 250 km/h.", need, campus, "set_behaviour", spelling_grounder))
    to = _props(props["behaviour"])["to"]
    assert "enum" in to and "Library entrance" in to["enum"]
    assert "maxLength" not in to


@pytest.mark.parametrize(("prompt", "moves"), [("Spawn a parked truck in lot A.", False), ("create one more bench by the fountain", False),
                                               ("add a bench, then shift the bin to the library", True)])
def test_a_request_only_for_new_things_offers_no_move(campus: Scene, prompt: str, moves: bool) -> None:
    kinds = read_names(prompt, campus).kinds()
    assert "add" in kinds
    assert ("position" in kinds) is moves


def test_the_managers_read_the_request_with_its_slips_repaired(campus: Scene, spelling_grounder: Grounder) -> None:
    session, backend = scripted_session(campus, [requirement("remove", "bench", "bus stop"), call("remove_assets", assets=["bench_1"])],
                                        spelling_grounder)
    report = session.submit("remvoe the bech by the bus stpo")
    assert report.ok, report.error
    assert session.scene.asset("bench_1") is None
    asked = backend.seen[0][-1]["content"]
    assert "remove the bench" in asked and "bech" not in asked
    assert report.plan is not None and report.plan.read_as == "remove the bench by the bus stop"


@pytest.mark.parametrize(("prompt", "search", "arrange"), [
    ("make it a lot darker outside", False, False),
    ("move the bus to the bus stop", False, False),
    ("put barriers all around the rubble", False, True),
    ("bus go forward little bit", False, False),
])
def test_only_a_question_is_a_search_and_only_a_layout_said_is_an_arrangement(campus: Scene, prompt: str, search: bool,
                                                                                arrange: bool) -> None:
    kinds = read_names(prompt, campus).kinds()
    assert ("search" in kinds) is search
    assert ("arrange" in kinds) is arrange


def test_the_two_ends_of_a_distance_are_the_places_the_request_names(campus: Scene, spelling_grounder: Grounder) -> None:
    prompt = "How far is the fountain from the east gate?"
    need = Requirement(kind="search", what="distance", where="fountain, east gate")
    props = _props(_args(prompt, need, campus, "measure_distance", spelling_grounder))
    assert {*props["a"]["enum"], *props["b"]["enum"]} == {"fountain", "east gate"}  # one end each, no ego


@pytest.mark.parametrize(("prompt", "count"), [("put a few cones by the east gate", 3), ("a handful of bins near the library", 4),
                                               ("a couple more benches by the fountain", 2)])
def test_an_amount_said_in_words_is_a_count_to_copy(campus: Scene, prompt: str, count: int) -> None:
    assert float(count) in read_names(prompt, campus).numbers
