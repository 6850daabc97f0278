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

from .conftest import ScriptedBackend, call, requirement, scripted_session


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
    said = read_names("shift the tree across to the library", campus)
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


def _args(prompt: str, need: Requirement, campus: Scene, grounder: Grounder, tool: str) -> dict[str, Any]:
    properties: dict[str, Any] = _offered(prompt, need, campus, grounder)[tool]["properties"]
    return properties


def test_a_length_is_never_a_count_and_a_length_field_takes_only_lengths(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    need = Requirement(kind="add", what="crossing sign", where="ego")
    args = _args("a crossing sign on the right-hand footway 25 m ahead of the ego", need, campus, spelling_grounder,
                 "add_asset")
    assert "count" not in args
    need = Requirement(kind="arrange", what="cones", where="eastbound lane", how="line")
    args = _args("set 6 cones out in a line 4 metres apart", need, campus, spelling_grounder, "arrange_assets")
    assert args["count"]["enum"] == [6]
    assert args["spacing"]["enum"] == [4.0]


def test_coordinates_go_only_to_their_own_axis_and_are_no_count(campus: Scene, spelling_grounder: Grounder) -> None:
    need = Requirement(kind="add", what="cone", where="x=40 y=-2")
    args = _args("drop one cone at x=40 y=-2", need, campus, spelling_grounder, "add_asset")
    location = args["location"]["properties"]
    assert location["x"]["enum"] == [40.0] and location["y"]["enum"] == [-2.0]
    assert "count" not in args
    args = _args("drop one cone by the fountain", Requirement(kind="add", what="cone", where="fountain"), campus,
                 spelling_grounder, "add_asset")
    assert not {"x", "y"} & set(args["location"]["properties"])  # no coordinates said, none offered


def test_a_speed_said_must_be_written_and_a_compass_way_picks_the_lanes_going_that_way(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    need = Requirement(kind="add", what="motorbike", how="drive")
    args = _offered("spawn a motorbike heading north at 7 m/s", need, campus, spelling_grounder)["add_asset"]
    assert "behaviour" in args["required"]
    behaviour = args["properties"]["behaviour"]
    assert "speed" in behaviour["required"] and behaviour["properties"]["speed"]["enum"] == [7.0]
    assert behaviour["properties"]["lane"]["enum"] == ["campus_northbound"]


@pytest.mark.parametrize(("prompt", "tools"), [
    ("so how far is it from the fountain to the east gate?", {"measure_distance"}),
    ("is it still foggy out there?", {"describe_environment"}),
    ("which lanes has Campus Drive got?", {"find_lanes"}),
    ("where have the bollards got to?", {"find_assets", "asset_properties"}),
])
def test_a_question_is_offered_the_lookups_that_answer_what_it_asks(
    campus: Scene, spelling_grounder: Grounder, prompt: str, tools: set[str]
) -> None:
    assert set(_offered(prompt, Requirement(kind="search", what=prompt), campus, spelling_grounder)) == tools


def test_a_distance_between_two_things_named_measures_one_to_the_other(campus: Scene, spelling_grounder: Grounder) -> None:
    prompt = "so how far is it from the fountain to the east gate?"
    args = _offered(prompt, Requirement(kind="search", what=prompt), campus, spelling_grounder)["measure_distance"]
    ends = {args["properties"]["a"]["enum"][0], args["properties"]["b"]["enum"][0]}
    assert ends == {"fountain", "east gate"} and len(args["properties"]["a"]["enum"]) == 1
    assert "b" in args["required"]


def test_a_search_for_a_landmark_takes_words_of_a_landmark_name_never_free_words(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    prompt = "which places are there near the junction?"
    args = _offered(prompt, Requirement(kind="search", what=prompt), campus, spelling_grounder)["find_landmarks"]
    query = args["properties"]["query"]["enum"]
    assert "crosswalk" in query and "parking lot A" in query and "maxLength" not in args["properties"]["query"]


@pytest.mark.parametrize("prompt", ["Reverse the player car 8 metres.", "nudge the insured vehicle 2 m forward",
                                    "move the ego car 3 m"])
def test_every_word_for_the_ego_names_the_ego_not_a_new_car(campus: Scene, prompt: str) -> None:
    found = read_slots(prompt, campus).found
    assert ("asset", "ego") in found
    assert ("category", "passenger_car") not in found


def test_a_shape_said_is_an_arrangement_not_things_added_one_by_one(campus: Scene) -> None:
    kinds = read_names("stand six people in a ring around the fountain", campus).kinds()
    assert "arrange" in kinds and "add" not in kinds
    assert "add" in read_names("add a cone by the fountain", campus).kinds()


def test_a_kind_the_words_never_name_is_asked_not_guessed(campus: Scene) -> None:
    # The model picked a truck for "somewhere to sit": nothing is applied; the kinds nearest the
    # words in meaning (MiniLM, for real) are offered instead.
    truck = call("add_asset", category="truck", location={"relation": "at", "target": "Library entrance"})
    session, _ = scripted_session(campus, [requirement("add", "somewhere to sit", "Library entrance"), truck, truck],
                                  Grounder())  # the review sends the first truck back once
    before = session.scene.model_dump_json()
    report = session.submit("we could do with somewhere to sit down outside the library")
    assert report.question is not None and not report.ok
    assert session.scene.model_dump_json() == before
    offered = [c.args["category"] for r in report.question.readings for c in r.calls]
    assert "bench" in offered and "truck" not in offered


def test_a_kind_the_words_name_is_not_asked(campus: Scene, spelling_grounder: Grounder) -> None:
    session, _ = scripted_session(campus, [
        requirement("add", "bench", "Library entrance"),
        call("add_asset", category="bench", location={"relation": "at", "target": "Library entrance"}),
    ], spelling_grounder)
    report = session.submit("add a bench at the library entrance")
    assert report.ok, report.error
    assert report.question is None


@pytest.mark.parametrize(("prompt", "speed"), [("get the ego up to thirty-six kilometres an hour", 10.0),
                                               ("have car 2 go east at 6 ms", 6.0)])
def test_a_speed_however_its_unit_is_written_is_a_speed_and_no_count(campus: Scene, prompt: str, speed: float) -> None:
    said = read_names(prompt, campus)
    assert [round(s, 2) for s in said.speeds] == [speed]
    assert said.numbers == ()  # neither the figure nor the unit's "an hour"


def test_going_somewhere_is_motion_and_moving_a_thing_to_a_place_is_not(campus: Scene) -> None:
    assert "move" in read_names("have the SUV head over to the library", campus).kinds()
    assert "move" not in read_names("move the trash bin to the library", campus).kinds()


def test_the_behaviour_said_is_the_only_behaviour_offered(campus: Scene, spelling_grounder: Grounder) -> None:
    prompt = "let the SUV do laps round and round lot B"
    args = _offered(prompt, Requirement(kind="move", what="SUV"), campus, spelling_grounder)["set_behaviour"]
    assert args["properties"]["behaviour"]["properties"]["kind"]["enum"] == ["circle"]


def test_driving_somewhere_is_a_path_there_never_a_teleport(campus: Scene) -> None:
    kinds = read_names("get the SUV to drive across to the east gate", campus).kinds()
    assert "move" in kinds and "position" not in kinds
    assert "position" in read_names("park the SUV over in lot A", campus).kinds()
    assert "follow_path" in read_names("get the SUV to drive across to the east gate", campus).behaviours


def test_a_place_said_right_after_a_thing_picks_which_one_and_is_no_destination(campus: Scene) -> None:
    said = read_names("shift the tree near the bus stop across to the engineering hall entrance", campus)
    assert said.assets == ("tree_1",)  # the tree nearest the bus stop, not any tree
    assert said.places == ("Engineering Hall entrance",)
    assert read_names("stand a cone beside the tree by lot A", campus).places == ("tree_4",)


def test_a_footway_said_puts_the_thing_on_it_not_merely_near_the_place(campus: Scene) -> None:
    assert read_names("move the stop sign onto the footway by the east gate", campus).relations == ("on_sidewalk",)


def test_a_removal_of_a_kind_the_words_never_name_is_refused_and_changes_nothing(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    bins = call("remove_assets", category="trash_bin")
    session, _ = scripted_session(campus, [requirement("remove", "library"), bins, bins], spelling_grounder)
    before = session.scene.model_dump_json()
    report = session.submit("get rid of the library, it's an eyesore")
    assert not report.ok and report.error is not None and "no kind of thing to remove" in report.error
    assert session.scene.model_dump_json() == before


def test_a_question_about_people_or_traffic_is_answered_by_finding_things(campus: Scene) -> None:
    assert read_names("is anybody walking about?", campus).lookups == ("find_assets", "asset_properties")


def test_the_strength_said_is_the_only_intensity_offered(campus: Scene, spelling_grounder: Grounder) -> None:
    prompt = "the shower has thinned to a light drizzle now, set that"
    args = _offered(prompt, Requirement(kind="appearance", what="drizzle"), campus, spelling_grounder)["set_weather"]
    assert args["properties"]["intensity"]["enum"] == [0.3]


def test_a_setting_alone_is_an_appearance_edit_and_nothing_else(campus: Scene) -> None:
    assert read_names("could we have it snowing", campus).kinds() == ["appearance"]
    assert read_names("set the clock to 07:40", campus).kinds() == ["appearance"]


def test_no_word_for_looks_weather_time_or_light_is_no_appearance_edit(campus: Scene) -> None:
    assert "appearance" not in read_names("give the SUV a spot by the east gate", campus).kinds()
    assert "appearance" in read_names("give the SUV a coat of blue paint", campus).kinds()
    assert "appearance" not in read_names("I am putting the bench by the fountain", campus).kinds()  # "am" is no clock
