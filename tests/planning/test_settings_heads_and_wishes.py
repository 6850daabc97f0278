"""Readings from the thirteenth practice round, worded this file's own way on the packaged campus
world: questions that are only a setting's word, the weather asked for beside the weather
complained of, wishes that things were gone, counts in hundreds, a bare name for the one thing
of its kind, a compound noun's head, and the check's flags for each misreading a planner made."""

from __future__ import annotations

import pytest
from drivetwin.tools.base import ToolCall
from misreading import Fixed, add  # this folder is on sys.path (no __init__.py)
from test_check import submit


def test_a_question_of_bare_setting_words_describes_the_environment(session, campus):
    report = session.submit("weather + lighting?")
    assert report.ok, report.error
    assert [c.tool for c in report.plan.calls] == ["describe_environment"]
    assert session.scene.environment == campus.environment


def test_setting_words_before_a_second_question_are_answered_with_it(session):
    report = session.submit("weather, and is anybody near the fountain?")
    assert report.ok, report.error
    calls = report.plan.calls
    assert [c.tool for c in calls] == ["describe_environment", "find_assets"]
    assert calls[1].args["category"] == "pedestrian"


def test_a_question_opened_without_its_apostrophe_changes_nothing(session, campus):
    report = session.submit("hows the weather out there")
    assert report.ok, report.error
    assert [c.tool for c in report.plan.calls] == ["describe_environment"]
    report = session.submit("wheres the nearest hydrant to the fountain")
    assert report.ok, report.error
    assert session.scene.assets == campus.assets


@pytest.mark.parametrize(("prompt", "kind"), [("way too sunny for this test; could we have it overcast", "cloudy"),
                                              ("it's foggy now, make it snow instead", "snow"),
                                              ("the dataset wants clouds, but no rain", "cloudy")])
def test_with_two_kinds_of_weather_said_the_one_asked_for_is_set(session, prompt, kind):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert session.scene.environment.weather.kind == kind


def test_a_storm_word_is_heavy_and_dark_with_lamps_on_still_sets_the_night(session):
    assert session.submit("we need a snowstorm, please").ok
    assert session.scene.environment.weather.intensity >= 0.8
    report = session.submit("we want it dark with all the street lamps on")
    assert report.ok, report.error
    assert {c.tool for c in report.plan.calls} == {"set_lighting", "set_time_of_day"}


def test_the_check_refuses_a_weather_kind_said_but_not_set(campus, registry):
    session, report = submit(campus, registry, Fixed(ToolCall(tool="set_weather", args={"kind": "clear"})),
                             "switch it to fog for the sensor run")
    assert not report.ok and session.scene.environment == campus.environment


def test_the_check_refuses_a_question_about_the_weather_answered_with_a_search(campus, registry):
    session, report = submit(campus, registry, Fixed(ToolCall(tool="find_assets", args={})), "weather and time?")
    assert not report.ok and "weather" in (report.error or "") and session.scene.assets == campus.assets


@pytest.mark.parametrize(("setup", "prompt", "category"), [
    ("put three people by the fountain", "hmm, no people after all", "pedestrian"),
    ("put two cones at the bus stop", "the cones look silly; I wish they weren't there", "traffic_cone")])
def test_a_wish_that_things_were_gone_takes_them_away(session, campus, setup, prompt, category):
    assert session.submit(setup).ok
    report = session.submit(prompt)
    assert report.ok, report.error
    assert session.scene.count(category) == campus.count(category)


def test_hundreds_and_thousands_are_counts_the_world_refuses_past_its_limit(session, campus):
    report = session.submit("put a thousand cones on Main Street")
    assert not report.ok and session.scene.count("traffic_cone") == campus.count("traffic_cone")
    assert "50" in (report.error or "")


def test_a_bare_name_of_the_one_thing_of_its_kind_is_not_added_anew(campus, registry):
    session, report = submit(campus, registry, Fixed(add("fire_hydrant")), "fire hydrant over by the library")
    assert not report.ok and session.scene.count("fire_hydrant") == campus.count("fire_hydrant")


def test_a_compound_nouns_head_is_the_thing_asked_for(campus, registry):
    session, report = submit(campus, registry, Fixed(add("bus")), "put a bus kiosk near the gate")
    assert not report.ok and "kiosk" in (report.error or "")
    assert session.scene.count("bus") == campus.count("bus")


def test_the_check_refuses_a_distance_measured_from_an_ego_never_named(campus, registry):
    session, report = submit(campus, registry, Fixed(ToolCall(tool="measure_distance", args={"a": "fountain", "b": "ego"})),
                             "how far is the stadium from the fountain")
    assert not report.ok and "ego" in (report.error or "") and session.scene.assets == campus.assets


def test_a_stop_sign_moved_is_no_stop_manoeuvre(session):
    from drivetwin.orchestrator.planning.scenario_reading import describes_behaviour_over_time

    assert not describes_behaviour_over_time("stop sign over to the far side of the street", session.scene)
    assert describes_behaviour_over_time("the car ahead stops hard when the ego is 20 m behind it", session.scene)


def test_a_walker_said_to_be_crossing_crosses(session):
    report = session.submit("a kid crossing at the north crosswalk")
    assert report.ok, report.error
    added = session.scene.asset(session.memory.last_added()[0])
    assert added is not None and added.behaviour.kind == "cross_road"


def test_each_thing_may_face_one_of_the_ways_said(session):
    report = session.submit("add a truck heading west on Main Street and a car heading east")
    assert report.ok, report.error


def test_a_polite_wish_for_a_brighter_picture_is_a_request(session, campus):
    report = session.submit("The screen looks murky to me. Could the picture be a little brighter?")
    assert report.ok, report.error
    assert session.scene.environment.lighting.exposure > campus.environment.lighting.exposure


def test_writing_down_which_lane_is_a_question(session, campus):
    report = session.submit("for my notes I have to write down which lane the ego is in")
    assert report.ok, report.error
    assert [c.tool for c in report.plan.calls] == ["find_lanes"]
    assert session.scene.assets == campus.assets


def test_the_check_refuses_moving_a_place_by_moving_a_thing_at_it(campus, registry):
    sign = ToolCall(tool="place_asset", args={"asset": "stop_sign_1", "location": {"relation": "at", "target": "main gate"}})
    session, report = submit(campus, registry, Fixed(sign), "shift the bus stop over towards the main gate")
    assert not report.ok and "bus stop" in (report.error or "")
    assert session.scene.asset("stop_sign_1") == campus.asset("stop_sign_1")


def test_an_arranged_kind_the_request_never_names_is_no_companion(campus, registry):
    line = ToolCall(tool="arrange_assets", args={"categories": ["traffic_cone", "bench"], "shape": "line",
                                                 "location": {"relation": "at", "target": "parking lot B"}})
    session, report = submit(campus, registry, Fixed(line), "a row of cones across lot B")
    assert not report.ok and session.scene.count("bench") == campus.count("bench")


def test_a_story_before_a_verifying_question_is_what_it_looks_up(session, campus):
    report = session.submit("Our tester said there's a hydrant by the crossroads. I'd like to confirm it's there.")
    assert report.ok, report.error
    assert [(c.tool, c.args.get("category")) for c in report.plan.calls] == [("find_assets", "fire_hydrant")]
    assert session.scene.assets == campus.assets


def test_a_thing_left_somewhere_stays_there(session):
    report = session.submit("please leave a van over in lot B")
    assert report.ok, report.error
    added = session.scene.asset(session.memory.last_added()[0])
    assert added is not None and added.behaviour.kind == "parked"


def test_another_just_like_it_has_its_colour(session):
    assert session.submit("add a green bus at the east gate").ok
    report = session.submit("now put another bus just like that one behind it")
    assert report.ok, report.error
    first, second = (session.scene.asset(i) for i in ("bus_1", "bus_2"))
    assert second is not None and first is not None and first.appearance.rgba is not None
    assert second.appearance.rgba is not None  # the same colour, to the 8 bits a colour is written in
    assert all(abs(a - b) <= 1 / 255 for a, b in zip(second.appearance.rgba, first.appearance.rgba, strict=True))


def test_the_check_refuses_a_copy_answered_with_a_move(campus, registry):
    move = ToolCall(tool="place_asset", args={"asset": "bench_1", "location": {"relation": "at", "target": "fountain"}})
    session, report = submit(campus, registry, Fixed(move), "make a duplicate of the bench over by the fountain")
    assert not report.ok and session.scene.asset("bench_1") == campus.asset("bench_1")


@pytest.mark.parametrize(("prompt", "a", "b"), [("what way is the main gate from the fountain", "fountain", "main gate"),
                                                ("in which direction should I go for the east gate", "ego", "east gate")])
def test_which_way_measures_from_the_start_towards_the_end(session, prompt, a, b):
    report = session.submit(prompt)
    assert report.ok, report.error
    call = report.plan.calls[0]
    assert call.tool == "measure_distance" and (call.args["a"], call.args["b"]) == (a, b)
    assert " to the " in (report.answer or "")  # the answer says the way


def test_a_distance_from_the_asker_to_one_place_is_still_measured(session):
    report = session.submit("how far off is the fountain?")
    assert report.ok, report.error
    assert report.plan.calls[0].tool == "measure_distance"


def test_a_place_word_offered_as_readings_is_not_asked_about_again_without_end(session, campus):
    # it asked "which gate?" of each reading it tried, each of which asked again: a RecursionError
    report = session.submit("Line five cones across the westbound lane near the east gate, then a roadworks sign by them.")
    if not report.ok:
        assert session.scene.assets == campus.assets


def test_things_lining_one_side_of_a_road_are_those_beside_its_lane_on_that_side(session, campus):
    report = session.submit("count the street lamps along the southern side of Main Street")
    assert report.ok, report.error
    assert report.plan.calls[0].args.get("lane") == "main_eastbound"
    south = [a for a in campus.assets if a.category == "street_light" and -10 < a.pose.y < 0 and abs(a.pose.x) <= 110]
    assert report.answer is not None and report.answer.startswith(f"{len(south)} street_light")


def test_a_count_asked_with_a_describing_word_and_the_weather_beside_it_answers_both(session, campus):
    report = session.submit("Give me a quick tally of the benches, and the weather as well.")
    assert report.ok, report.error
    assert [c.tool for c in report.plan.calls] == ["find_assets", "describe_environment"]
    assert session.scene.assets == campus.assets


def test_taking_away_things_a_place_has_none_of_is_refused_not_read_as_adding(campus, registry):
    from drivetwin.orchestrator.planning.rules.planner import RulePlanner
    from drivetwin.orchestrator.session import Session

    session = Session(campus, RulePlanner(), registry)
    report = session.submit("could we lose any benches out by lot B")
    assert not report.ok and session.scene.count("bench") == campus.count("bench")
    assert report.plan is None or not any(c.tool == "add_asset" for c in report.plan.calls)


def test_what_the_speaker_takes_back_in_the_same_breath_is_not_done(session, campus):
    report = session.submit("move the bin to the fountain... no, hang on, forget that, just spin it round where it is")
    assert report.ok, report.error
    assert [c.tool for c in report.plan.calls] == ["move_asset"]
    bin_now, bin_before = session.scene.asset("trash_bin_1"), campus.asset("trash_bin_1")
    assert (bin_now.pose.x, bin_now.pose.y) == (bin_before.pose.x, bin_before.pose.y)
    report = session.submit("put four, no, two bollards at the main gate")
    assert report.ok, report.error
    assert session.scene.count("bollard") == campus.count("bollard") + 2


def test_the_check_refuses_a_layout_dropped_at_the_centre_when_a_place_was_said(campus, registry):
    line = ToolCall(tool="arrange_assets", args={"categories": ["road_barrier"], "shape": "line",
                                                 "location": {"relation": "scene_centre"}})
    session, report = submit(campus, registry, Fixed(line), "a line of barriers across the lot bee driveway")
    assert not report.ok and session.scene.count("road_barrier") == campus.count("road_barrier")


def test_what_others_tell_me_is_a_story_not_a_question(session):
    assert session.submit("put three cones by the library entrance").ok
    report = session.submit("the gardeners tell me they finished, so those cones shouldn't be there any more")
    assert report.ok, report.error
    assert session.scene.count("traffic_cone") == 0


def test_the_exposure_asked_to_come_down_goes_down(session, campus):
    report = session.submit("the frames look washed out; could the exposure come down a little?")
    assert report.ok, report.error
    assert session.scene.environment.lighting.exposure < campus.environment.lighting.exposure


def test_could_there_be_asks_for_things_and_the_stop_is_the_one_place_called_that(session, campus):
    report = session.submit("could there be two people waiting at the stop?")
    assert report.ok, report.error
    assert session.scene.count("pedestrian") == campus.count("pedestrian") + 2
    assert report.plan.calls[0].args["location"]["target"] == "bus stop"


def test_a_thing_going_round_in_circles_asked_to_go_faster_keeps_circling(session):
    assert session.submit("have a robot drive in a loop around lot B").ok
    report = session.submit("could it go a little quicker?")
    assert report.ok, report.error
    robot = session.scene.asset("ackermann_robot_1")
    assert robot is not None and robot.behaviour.kind == "circle"


def test_standing_out_more_is_a_look_not_more_things(session, campus):
    assert session.submit("add an SUV by the library entrance").ok
    report = session.submit("it should stand out more")
    assert report.ok, report.error
    assert session.scene.count("suv") == campus.count("suv") + 1
    assert [c.tool for c in report.plan.calls] == ["set_asset_appearance"]


def test_one_being_plenty_of_what_the_speaker_ended_up_with_keeps_one(session, campus):
    assert session.submit("put two benches at the east gate").ok
    report = session.submit("seems I ended up with two benches at the east gate, one is plenty")
    assert report.ok, report.error
    assert session.scene.count("bench") == campus.count("bench") + 1


def test_a_slip_opening_a_command_before_a_thing_is_the_command_verb(session):
    report = session.submit("plase the bench at the east gate and the bin at the main gate")
    assert report.ok, report.error
    assert [(c.tool, c.args.get("asset")) for c in report.plan.calls] == [("place_asset", "bench_1"),
                                                                          ("place_asset", "trash_bin_1")]


def test_a_story_question_about_a_kind_said_as_a_group_counts_the_whole_group(session, campus):
    report = session.submit("A colleague said the lot is full. Could you give me a rough idea how many cars are parked there?")
    assert report.ok, report.error
    cars = [a for a in campus.assets if a.category in ("passenger_car", "suv")]
    assert report.answer is not None and report.answer.startswith(f"{len(cars)} ")
    assert session.scene.assets == campus.assets
