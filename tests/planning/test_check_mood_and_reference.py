"""The plan check, continued: the mood of a request, where it points and which way it goes.

Like test_check.py, each test hands the session a planner whose plan misreads the request and
asserts it becomes a question or a refusal with the scene unchanged (worded unlike any suite
prompt), plus the readings a person is offered where one can be built.
"""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.request import read_request
from drivetwin.orchestrator.planning.rules.clock import clock_time
from drivetwin.orchestrator.planning.rules.numbers import numbers_in
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.tools.base import ToolCall
from misreading import Fixed, add, call  # this folder is on sys.path (no __init__.py)


def refused_unchanged(campus, registry, planner, prompt, setup=None):
    session = Session(campus, setup or planner, registry)
    if setup is not None:
        assert session.submit("set the stage with a few things").ok  # "things": points at what is added without naming it
        session.planner = planner
    before = session.scene
    report = session.submit(prompt)
    assert not report.ok, f"{prompt!r} was applied: {report.plan.calls if report.plan else None}"
    assert session.scene == before
    return report


def test_a_command_answered_by_a_lookup_is_not_reported_done(campus, registry):
    refused_unchanged(campus, registry, Fixed(call("find_assets", category="bench")),
                      "two more benches by the fountain, could you?")


def test_a_move_that_moves_nothing_is_not_reported_done(campus, registry):
    refused_unchanged(campus, registry, Fixed(call("move_asset", asset="ego")), "nudge the ego a little")


def test_a_question_is_answered_about_the_place_it_names(campus, registry):
    report = refused_unchanged(campus, registry, Fixed(call("asset_properties", asset="ego")),
                               "roughly what distance separates the fountain and our car?")
    assert "fountain" in (report.error or report.question.text if report.question else report.error or "")


def test_a_question_about_a_road_looks_up_that_road(campus, registry):
    refused_unchanged(campus, registry, Fixed(call("find_lanes")), "name every lane on Campus Drive")


def test_a_lookup_said_as_a_command_is_a_question():
    assert read_request("list the trees", _campus()).question
    assert read_request("could you locate the hydrant", _campus()).question
    assert not read_request("the street is quiet, can you add two cars?", _campus()).question


def test_a_move_the_wrong_way_is_not_applied(campus, registry):
    refused_unchanged(campus, registry, Fixed(call("move_asset", asset="ego", east=-3.0)), "roll the ego 3 m eastwards")


def test_a_move_the_named_way_is_applied(campus, registry):
    session = Session(campus, Fixed(call("move_asset", asset="ego", east=3.0)), registry)
    assert session.submit("roll the ego 3 m eastwards").ok


def test_a_removal_only_request_never_adds(campus, registry):
    plan = Fixed(call("remove_assets", category="trash_bin", count=1), add("bench"))
    report = refused_unchanged(campus, registry, plan, "clear out the trash bin as well as the bench")
    assert report.question is not None
    offered = [c.tool for r in report.question.readings[:-1] for c in r.calls]
    assert offered and set(offered) == {"remove_assets"}


def test_a_removal_done_as_a_move_is_not_applied(campus, registry):
    plan = Fixed(call("place_asset", asset="tree_1", location={"relation": "at", "target": "fountain"}))
    refused_unchanged(campus, registry, plan, "I'd prefer the lawn without that tree")


def test_pointing_back_at_cones_does_not_add_bollards(campus, registry):
    cones = Fixed(add("traffic_cone", count=3, location={"relation": "in_front_of", "target": "ego", "distance": 12}))
    plan = Fixed(add("bollard", count=2, location={"relation": "in_front_of", "target": "ego", "distance": 20}))
    refused_unchanged(campus, registry, plan, "pop another two in", setup=cones)


def test_them_means_all_of_what_the_last_turn_made(campus, registry):
    cones = Fixed(add("traffic_cone", count=3, location={"relation": "in_front_of", "target": "ego", "distance": 12}))
    one = Fixed(call("move_asset", asset="traffic_cone_1", left=1.0))
    refused_unchanged(campus, registry, one, "shove them over a touch", setup=cones)


def test_a_spoken_time_is_set_as_said(campus, registry):
    refused_unchanged(campus, registry, Fixed(call("set_time_of_day", time="evening")),
                      "wind the clock to a quarter past seven in the evening")
    session = Session(campus, Fixed(call("set_time_of_day", time="19:15")), registry)
    assert session.submit("wind the clock to a quarter past seven in the evening").ok


def test_a_distance_typed_against_its_unit_is_accounted_for(campus, registry):
    plan = Fixed(call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane"}))
    refused_unchanged(campus, registry, plan, "back the suv up 7m")


@pytest.mark.parametrize(
    ("words", "time"),
    [
        ("switch to 21:05", "21:05"),
        ("a quarter to eight in the evening please", "19:45"),
        ("ten past nine at night", "21:10"),
        ("set time 7.45 o clock", "07:45"),
        ("make it 4 pm", "16:00"),
        ("12 am", "00:00"),
        ("around midnight", "00:00"),
        ("1:30 at night", "01:30"),
    ],
)
def test_clock_times_read_as_said(words, time):
    said = clock_time(words)
    assert said is not None and str(said) == time


@pytest.mark.parametrize("words", ["move it 2.5 m", "add 7 cones", "the 3 benches at 12 m", "car_12"])
def test_amounts_are_not_clock_times(words):
    assert clock_time(words) is None


def test_an_impossible_clock_time_is_read_as_impossible():
    said = clock_time("time 26:61")
    assert said is not None and not said.valid


def test_numbers_glued_to_units_are_read():
    assert [n.value for n in numbers_in("go 12m then 30kmh for 4s")] == [12.0, 30.0, 4.0]
    assert numbers_in("the 2nd car_3") == []


def test_the_rule_planner_sets_a_spoken_time(campus, registry):
    from drivetwin.orchestrator.planning import PlanContext

    plan = RulePlanner().plan("set the clock to twenty past six in the evening", PlanContext(campus, registry))
    assert [(c.tool, c.args) for c in plan.calls] == [("set_time_of_day", {"time": "18:20"})]


def _campus():
    from drivetwin.worlds.campus import build_campus

    return build_campus()


def test_a_new_thing_asked_for_is_not_taken_from_elsewhere(campus, registry):
    moved = Fixed(call("place_asset", asset="tree_1", location={"relation": "at", "target": "parking lot A"}))
    report = refused_unchanged(campus, registry, moved, "stick a tree over at parking lot A")
    assert report.question is not None
    assert report.question.readings[0].calls[0].tool == "add_asset"


def cones_at(*points: tuple[float, float]) -> Fixed:
    return Fixed(*(add("traffic_cone", location={"relation": "absolute", "x": x, "y": y}) for x, y in points))


def test_a_layout_named_is_judged_by_where_things_end_up(campus, registry):
    triangle = cones_at((-40.0, -1.8), (-35.0, -1.8), (-37.5, 1.8))
    refused_unchanged(campus, registry, triangle, "three cones down the road, set out in a row")
    in_a_row = cones_at((-40.0, -1.8), (-35.0, -1.8), (-30.0, -1.8))
    assert Session(campus, in_a_row, registry).submit("three cones down the road, set out in a row").ok


def test_a_spacing_named_is_kept(campus, registry):
    five_apart = cones_at((-40.0, -1.8), (-35.0, -1.8), (-30.0, -1.8))
    refused_unchanged(campus, registry, five_apart, "three cones down the road, 2 m apart")
    assert Session(campus, five_apart, registry).submit("three cones down the road, 5 m apart").ok


def test_nothing_is_put_inside_a_building(campus, registry):
    at_door = Fixed(add("bench", location={"relation": "at", "target": "Library entrance"}))
    report = refused_unchanged(campus, registry, at_door, "could you fit a bench into the library")
    said = report.error or (report.question.text if report.question else "")
    assert "inside or on top of the Library" in said


def test_the_number_said_before_a_thing_is_how_many_are_added(campus, registry):
    three = Fixed(add("traffic_cone", count=3, location={"relation": "in_front_of", "target": "ego", "distance": 2}))
    refused_unchanged(campus, registry, three, "two cones 2 m in front of our car")


def test_a_lane_named_holds_what_is_placed(campus, registry):
    eastbound = Fixed(add("traffic_cone", count=2, location={"relation": "in_front_of", "target": "ego", "distance": 12}))
    refused_unchanged(campus, registry, eastbound, "two cones in the westbound lane of Main Street")


def test_on_the_sidewalk_means_on_the_sidewalk(campus, registry):
    at_door = Fixed(add("pedestrian", location={"relation": "at", "target": "Library entrance"}))
    refused_unchanged(campus, registry, at_door, "a walker on the pavement outside the library")


def test_a_material_asked_for_is_set(campus, registry):
    refused_unchanged(campus, registry, Fixed(add("bench")), "add a wooden bench")


def test_light_weather_is_not_set_heavy(campus, registry):
    refused_unchanged(campus, registry, Fixed(call("set_weather", kind="snow", intensity=0.9)), "light snow for the next run")
    session = Session(campus, Fixed(call("set_weather", kind="snow", intensity=0.3)), registry)
    assert session.submit("light snow for the next run").ok


def test_an_exact_time_is_set_even_beside_the_lights(campus, registry):
    plan = Fixed(call("set_lighting", vehicle_lights="on"), call("set_weather", kind="snow", intensity=0.3))
    refused_unchanged(campus, registry, plan, "flurries at 05:40 with the headlights on")


def test_a_group_named_by_its_kind_is_removed_whole(campus, registry):
    cars_only = Fixed(call("remove_assets", category="passenger_car", near="parking lot B"))
    report = refused_unchanged(campus, registry, cars_only, "all the vehicles parked over in parking lot B can go")
    said = report.error or (report.question.text if report.question else "")
    assert "suv_1" in said


class Asking:
    """A planner that asks which of fixed readings was meant."""

    name = "asking"

    def __init__(self, *readings: list[ToolCall]) -> None:
        self.readings = readings

    def plan(self, prompt, context):
        from drivetwin.orchestrator.planning import Plan, Question, Reading

        question = Question(text="which?", readings=[Reading(text=str(r), calls=r) for r in self.readings])
        return Plan(calls=[], planner=self.name, question=question)


def test_a_planners_question_never_offers_a_reading_the_check_knows_is_wrong(campus, registry):
    west, east = [call("move_asset", asset="ego", east=-3.0)], [call("move_asset", asset="ego", east=3.0)]
    report = Session(campus, Asking(west, east), registry).submit("roll the ego 3 m eastwards")
    assert report.question is not None and [r.calls for r in report.question.readings] == [east]


def test_a_question_whose_every_reading_is_wrong_becomes_a_refusal_saying_why(campus, registry):
    west = [call("move_asset", asset="ego", east=-3.0)]
    report = refused_unchanged(campus, registry, Asking(west), "roll the ego 3 m eastwards")
    assert report.question is None and "east" in (report.error or "")


def test_a_heading_said_as_a_compass_direction_is_kept(campus, registry):
    refused_unchanged(campus, registry, Fixed(add("bench", yaw_deg=90.0)), "add a bench facing east")
    assert Session(campus, Fixed(add("bench", yaw_deg=0.0)), registry).submit("add a bench facing east").ok


def test_in_front_of_an_asset_is_on_the_side_it_faces(campus, registry):
    behind = Fixed(add("traffic_cone", location={"relation": "absolute", "x": -70.0, "y": -1.8}))
    refused_unchanged(campus, registry, behind, "a cone in front of the ego")
    ahead = Fixed(add("traffic_cone", location={"relation": "absolute", "x": -50.0, "y": -1.8}))
    assert Session(campus, ahead, registry).submit("a cone in front of the ego").ok


def test_a_change_to_all_of_a_kind_is_made_to_all_of_them(campus, registry):
    one = Fixed(call("set_asset_appearance", assets=["tree_1"], colour="red"))
    refused_unchanged(campus, registry, one, "every one of the trees should turn red")
    every = Fixed(call("set_asset_appearance", category="tree", colour="red"))
    assert Session(campus, every, registry).submit("make all the trees red").ok


def test_a_refusal_says_first_what_was_not_understood_and_what_is_possible(campus, registry):
    from drivetwin.orchestrator.planning.hybrid import HybridPlanner
    from drivetwin.orchestrator.planning.retrieval import RetrievalPlanner

    class NoModel:
        name = "llm"

        def plan(self, prompt, context):
            from drivetwin.orchestrator.planning import PlanningError

            raise PlanningError("no model here")

    planner = HybridPlanner(RulePlanner(), NoModel(), retrieval=RetrievalPlanner())  # type: ignore[arg-type]
    report = Session(campus, planner, registry).submit("get rid of the zeppelin")
    assert not report.ok and report.error is not None
    assert report.error.startswith("there is no 'zeppelin' in this world")
    assert "I can add, move, remove" in report.error and "confidence" not in report.error


def test_things_put_around_a_place_surround_it(campus, registry):
    north_side = Fixed(*(add("tree", location={"relation": "absolute", "x": x, "y": 48.0}) for x in (70.0, 75.0, 80.0)))
    refused_unchanged(campus, registry, north_side, "plant trees all around the fountain")
    ring = Fixed(call("arrange_assets", categories=["tree"], count=4, shape="ring",
                      location={"relation": "at", "target": "fountain"}))
    assert Session(campus, ring, registry).submit("plant trees all around the fountain").ok


def test_a_compass_word_alone_names_no_lane(campus, registry):
    north = Fixed(call("move_asset", asset="bench_1", north=2.0))
    assert Session(campus, north, registry).submit("shift the bench 2 m north").ok
    assert read_request("park it facing east", campus).lane is None
    assert read_request("cones in the eastbound lane", campus).lane == "main_eastbound"


def test_the_one_of_several_asks_which_and_the_choice_acts_on_that_one(campus, registry):
    # "the hatchback" is one of two passenger cars here; the planner picked one at random.
    first = Fixed(call("set_asset_appearance", assets=["passenger_car_1"], colour="green"))
    report = refused_unchanged(campus, registry, first, "could the hatchback go green")
    assert report.question is not None and "passenger_car_2" in report.question.text
    picks = [r.calls[0].args.get("assets") for r in report.question.readings]
    assert ["passenger_car_1"] in picks and ["passenger_car_2"] in picks
    session = Session(campus, first, registry)
    session.submit("could the hatchback go green")
    chosen = next(i for i, r in enumerate(report.question.readings, 1) if r.calls[0].args.get("assets") == ["passenger_car_2"])
    assert session.choose(chosen).ok
    assert session.scene.asset("passenger_car_2").appearance != campus.asset("passenger_car_2").appearance
    assert session.scene.asset("passenger_car_1").appearance == campus.asset("passenger_car_1").appearance


def test_the_one_singled_out_by_words_or_an_earlier_turn_is_not_asked_about(campus, registry):
    pick = Fixed(call("move_asset", asset="passenger_car_2", left=1.0))
    assert Session(campus, pick, registry).submit("shift the passenger car 2 a metre left").ok
    assert Session(campus, pick, registry).submit("shift the easternmost passenger car a metre left").ok
    session = Session(campus, Fixed(call("move_asset", asset="passenger_car_2", forward=2.0)), registry)
    assert session.submit("roll passenger_car_2 forward a bit").ok
    session.planner = pick
    assert session.submit("now shift the passenger car a metre left").ok


def test_changing_a_thing_that_is_not_there_asks_before_adding_one(campus, registry):
    assert campus.count("truck") == 0
    report = refused_unchanged(campus, registry, Fixed(add("truck", colour="blue")), "recolour the truck blue")
    assert report.question is not None and "no truck" in report.question.text
    assert report.question.readings[0].calls[0].tool == "add_asset"
    by_fountain = add("truck", location={"relation": "at", "target": "parking lot A"})
    assert Session(campus, Fixed(by_fountain), registry).submit("park the truck in lot A").ok


def test_a_change_to_a_thing_the_words_never_point_at_is_not_applied(campus, registry):
    painted = Fixed(call("set_asset_appearance", assets=["suv_1"], material="concrete"))
    report = refused_unchanged(campus, registry, painted, "I would like a rough, concrete feel to the picture")
    assert "which your words do not point at" in (report.error or "")
    assert Session(campus, painted, registry).submit("give the SUV a concrete finish").ok


def test_a_thing_said_to_be_moving_is_not_added_standing_still(campus, registry):
    refused_unchanged(campus, registry, Fixed(add("bicycle", location={"relation": "in_lane", "target": "main_eastbound"})),
                      "i'd like a bike riding along main street eastwards")
    assert read_request("a car that is not moving by the gate", campus).state is None


def test_fewer_lights_does_not_switch_the_street_lights_on(campus, registry):
    refused_unchanged(campus, registry, Fixed(call("set_lighting", street_lights="on")),
                      "fewer lights along the north side, please")


def test_a_thing_the_world_has_no_word_for_is_not_replaced_by_the_one_it_stands_by(campus, registry):
    next_to = {"relation": "next_to", "target": "bench_1"}
    report = refused_unchanged(campus, registry, Fixed(add("bench", location=next_to)), "could you add a letterbox next to the bench")
    assert "'letterbox'" in (report.error or "")
    rain = Fixed(call("set_weather", kind="rain", intensity=0.6))
    report = refused_unchanged(campus, registry, rain, "for the trailer we need a triple rainbow above the fountain")
    assert "'rainbow'" in (report.error or "")
    assert Session(campus, Fixed(add("bench", location=next_to)), registry).submit("add one more bench next to the bench").ok


def test_wanting_to_be_sure_of_something_asks_and_changes_nothing(campus, registry):
    assert read_request("before my run I'd like to verify there are no trucks near the gate", campus).question
    assert read_request("just want to be certain the fountain is still there", campus).question
    refused_unchanged(campus, registry, Fixed(add("truck")), "someone left a truck around last week; I want to be sure there isn't one now")


def test_a_thing_picked_out_by_the_thing_it_stands_by_is_the_one_acted_on(campus, registry):
    report = refused_unchanged(campus, registry, Fixed(call("remove_assets", category="street_light", count=1)),
                               "that lamp post by the stop sign has to go")
    assert report.question is not None
    offered = [r.calls for r in report.question.readings]
    assert [ToolCall(tool="remove_assets", args={"assets": ["street_light_6"]})] in offered
    session = Session(campus, Fixed(call("remove_assets", assets=["street_light_6"])), registry)
    assert session.submit("that lamp post by the stop sign has to go").ok
    assert session.scene.asset("street_light_6") is None


def test_a_time_in_the_other_half_of_the_day_from_the_one_said_is_not_applied(campus, registry):
    refused_unchanged(campus, registry, Fixed(call("set_time_of_day", time="sunset")),
                      "for the glare run I need a low sun shortly after dawn")
    refused_unchanged(campus, registry, Fixed(call("set_time_of_day", time="09:00")), "a night drive in the fog, no moon")
    assert Session(campus, Fixed(call("set_time_of_day", time="sunrise")), registry).submit(
        "for the glare run I need a low sun shortly after dawn").ok


def test_an_unknown_thing_doing_something_is_still_the_thing_asked_for(campus, registry):
    report = refused_unchanged(campus, registry, Fixed(add("pedestrian")), "add a moose wandering across the road by the gate")
    assert "'moose'" in (report.error or "")


def test_a_command_that_ends_with_a_question_mark_is_a_command(campus, registry):
    assert not read_request("umm take away the truck, there's one somewhere I think?", campus).question
    assert not read_request("ok so paint the bench red?", campus).question
    refused_unchanged(campus, registry, Fixed(call("find_assets", category="bus")), "remove the bus, I believe there's one?")


def test_switching_every_vehicle_s_lights_on_does_something_with_the_cars_named(campus, registry):
    lights = Fixed(call("set_lighting", vehicle_lights="on"))
    assert Session(campus, lights, registry).submit("switch the headlights of every car on").ok
    assert not read_request("do the same in lot A", campus).question


def test_a_layout_of_the_things_a_request_wants_gone_is_not_applied(campus, registry):
    ring = Fixed(call("arrange_assets", categories=["pedestrian"], shape="ring", location={"relation": "at", "target": "fountain"}))
    refused_unchanged(campus, registry, ring, "honestly I'd rather not have people standing around the fountain")


def test_things_said_to_be_on_a_road_are_the_ones_by_that_road(campus, registry):
    every_lamp = Fixed(call("remove_assets", category="street_light"))
    refused_unchanged(campus, registry, every_lamp, "take away the street lamps on Campus Drive")
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("remove the street lights along Campus Dr.")
    assert not report.ok and "no street light on Campus Drive" in (report.error or "")
    assert session.submit("remove the street lights along Main Street").ok
    assert session.scene.count("street_light") == 0


def test_a_thing_wanted_that_a_lookup_tells_is_no_unknown_thing(campus, registry):
    measure = Fixed(call("measure_distance", a="Library entrance", b="fountain"))
    report = Session(campus, measure, registry).submit("I want the straight-line distance between the library and the fountain")
    assert report.ok, report.error
