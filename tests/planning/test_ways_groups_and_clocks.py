"""Vehicles that make their way somewhere, behaviours for every one referred to, a lot's entrance,
"later" said of other things than the clock, lights asked after by a place, and a second thing
asked for in the same breath, tried in this file's own words on the packaged campus world: "the
truck should make its way over to the library" drives there, never jumps; "both of them jaywalk"
is both; "we'll sort the weather out later" sets no time; "and a scarecrow next to it" is refused."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.base import Plan, PlanningError
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.tools.base import ToolCall


def _behaviour(session, asset_id):
    asset = session.scene.asset(asset_id)
    assert asset is not None
    return asset.behaviour


@pytest.mark.parametrize("prompt", ["the SUV should make its way over to the library entrance",
                                    "have the suv make its own way to the Student Union",
                                    "the SUV drives to the library"])
def test_a_vehicle_sent_where_no_lane_leads_goes_there_by_path_and_is_not_moved_there(session, campus, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    after, before = session.scene.asset("suv_1"), campus.asset("suv_1")
    assert after is not None and before is not None
    assert (after.pose.x, after.pose.y) == (before.pose.x, before.pose.y)  # it sets off from where it stood
    assert after.behaviour.kind == "follow_path"
    gx, gy = after.behaviour.waypoints[-1]
    goal = session.scene.landmark("Library entrance" if "librar" in prompt else "Student Union entrance")
    assert goal is not None and abs(gx - goal.position[0]) < 3 and abs(gy - goal.position[1]) < 3


def test_a_vehicle_moved_to_a_place_is_still_put_there(session):
    report = session.submit("move the suv to the library")
    assert report.ok, report.error
    assert report.plan is not None and report.plan.calls[0].tool == "place_asset"


@pytest.mark.parametrize("turn", ["both of them should jaywalk now", "the two kids, over the road now, both of them",
                                  "them all to walk to the fountain"])
def test_a_behaviour_for_every_one_referred_to_is_given_to_each(session, turn):
    assert session.submit("add two pedestrians on the south pavement by the west crossing").ok
    report = session.submit(turn)
    assert report.ok, report.error
    kinds = {_behaviour(session, i).kind for i in ("pedestrian_1", "pedestrian_2")}
    assert kinds == {"jaywalk"} if "jaywalk" in turn else kinds == ({"follow_path"} if "walk to" in turn else {"cross_road"})


def test_one_picked_out_of_several_is_the_only_one_given_the_behaviour(session):
    assert session.submit("add two pedestrians at the bus stop").ok
    report = session.submit("now the second one should cross the road")
    assert report.ok, report.error
    assert _behaviour(session, "pedestrian_2").kind == "cross_road"
    assert _behaviour(session, "pedestrian_1").kind != "cross_road"


@pytest.mark.parametrize("prompt", ["put a bench in lot B, by the entrance", "park the suv in parking lot B near the entrance"])
def test_the_entrance_said_after_a_lot_is_that_lots_entrance(session, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert report.plan is not None
    assert report.plan.calls[0].args["location"]["target"] == "parking lot B entrance"


def test_a_crossing_named_by_its_side_is_that_crosswalk_and_one_the_world_lacks_is_refused(session):
    report = session.submit("put a cone on the western crossing")
    assert report.ok, report.error
    assert report.plan is not None and report.plan.calls[0].args["location"]["target"] == "west crosswalk"
    refused = session.submit("put a cone on the east crossing")
    assert not refused.ok and "no 'east crosswalk'" in (refused.error or "")


@pytest.mark.parametrize("prompt", ["we'll sort the weather out later", "cones by the gate, I'll check them later"])
def test_later_said_of_something_else_sets_no_time(context, prompt):
    try:
        plan = RulePlanner().plan(prompt, context)
    except PlanningError:
        return  # not understood is fine; a time set is not
    assert not any(c.tool == "set_time_of_day" for c in plan.calls), plan.calls


@pytest.mark.parametrize(("prompt", "hours"), [("make it a bit later", 3), ("could it be later in the day?", 3),
                                               ("two hours earlier please", -2)])
def test_later_said_of_the_clock_moves_it(context, prompt, hours):
    plan = RulePlanner().plan(prompt, context)
    noon = int(context.scene.environment.time_of_day.split(":")[0])
    assert [(c.tool, c.args) for c in plan.calls] == [("set_time_of_day", {"time": f"{noon + hours:02d}:00"})]


@pytest.mark.parametrize("prompt", ["lights by the library?", "any lamps near the bus stop??"])
def test_lights_asked_after_by_a_place_are_the_lamps_there(context, prompt):
    plan = RulePlanner().plan(prompt, context)
    assert plan.calls[0].tool == "find_assets"
    assert plan.calls[0].args["category"] in ("lights", "street_light")


def test_anything_that_would_block_a_cyclist_is_anything_on_the_road_not_bicycles(session):
    assert session.submit("put some rubble in the eastbound lane 30 m ahead of the ego").ok
    report = session.submit("is there anything sitting in the road that would force a cyclist out into traffic?")
    assert report.ok, report.error
    assert report.plan is not None and "category" not in report.plan.calls[0].args
    assert "cement_rubble_1" in (report.answer or "")


@pytest.mark.parametrize("prompt", ["add a bus at the bus stop and a scarecrow standing next to it",
                                    "put a car by the fountain and two unicorns beside it"])
def test_a_second_thing_this_world_lacks_asked_for_in_the_same_breath_is_not_left_out_silently(context, prompt):
    plan = Plan(calls=[ToolCall(tool="add_asset", args={"category": "bus" if "bus" in prompt else "passenger_car", "count": 1})],
                planner="rules")
    verdict = review(prompt, plan, context)
    assert verdict.action != "apply"
    assert any("there is no" in p for p in verdict.problems), verdict.problems


def test_a_second_thing_the_world_has_is_not_flagged(context):
    at_stop = {"relation": "at", "target": "bus stop"}
    plan = Plan(calls=[ToolCall(tool="add_asset", args={"category": "bus", "count": 1, "location": at_stop}),
                       ToolCall(tool="add_asset", args={"category": "bench", "count": 1,
                                                        "location": {"relation": "next_to", "target": "bus_1"}})], planner="rules")
    assert not any("there is no" in p for p in review("add a bus at the bus stop and a bench next to it", plan, context).problems)


@pytest.mark.parametrize(("setup", "turn", "asset", "check"), [
    ("Move the bench next to the fountain.", "actually, put it back by the bus stop", "bench_1", "bus stop"),
    ("Make the SUV drive east on Main Street.", "actually, just park it again", "suv_1", "parked"),
])
def test_it_after_a_move_or_a_behaviour_is_the_thing_that_turn_changed(session, setup, turn, asset, check):
    assert session.submit(setup).ok
    report = session.submit(turn)
    assert report.ok, report.error
    thing = session.scene.asset(asset)
    assert thing is not None
    if check == "parked":
        assert thing.behaviour.kind == "parked"
    else:
        stop = session.scene.landmark(check)
        assert stop is not None and abs(thing.pose.x - stop.position[0]) < 8 and abs(thing.pose.y - stop.position[1]) < 8


def test_on_the_sidewalk_next_to_it_is_the_sidewalk_by_the_thing_just_added(session):
    report = session.submit("Add a bus at the bus stop and a pedestrian waiting on the sidewalk next to it.")
    assert report.ok, report.error
    assert report.plan is not None and report.plan.calls[1].args["location"] == {"relation": "on_sidewalk", "target": "bus_1"}


def test_a_thing_put_by_another_moved_in_the_same_request_is_judged_by_where_that_one_goes(session):
    report = session.submit("Put the bench next to the fountain and the trash bin next to the bench.")
    assert report.ok, report.error
    bench, bin_ = session.scene.asset("bench_1"), session.scene.asset("trash_bin_1")
    assert bench is not None and bin_ is not None and abs(bench.pose.x - bin_.pose.x) + abs(bench.pose.y - bin_.pose.y) < 6


def test_less_of_a_weather_already_there_is_lighter_and_not_refused_as_unwanted(session):
    assert session.submit("Thick fog, please.").ok
    report = session.submit("less foggy, please")
    assert report.ok, report.error
    assert session.scene.environment.weather.kind == "fog" and session.scene.environment.weather.intensity < 0.9


@pytest.mark.parametrize("prompt", ["Fence off the cones with barriers in a circle so nobody drives into them.",
                                    "put a row of five short steel posts in front of the JTEKT doors, to keep cars off the forecourt"])
def test_why_a_thing_is_put_somewhere_asks_for_nothing_more(session, prompt):
    if "cones" in prompt:
        assert session.submit("add a traffic cone at the crossroads").ok
    report = session.submit(prompt)
    assert report.ok, report.error
    assert not any(a.category in ("passenger_car",) and a.id not in ("passenger_car_1", "passenger_car_2")
                   for a in session.scene.assets)


@pytest.mark.parametrize(("prompt", "tool"), [("sunset vibes?", "set_time_of_day"), ("heavy rain?", "set_weather")])
def test_a_setting_offered_with_a_question_mark_is_set(session, prompt, tool):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert report.plan is not None and report.plan.calls[0].tool == tool


@pytest.mark.parametrize("prompt", ["rain or not?", "is it foggy out?", "weather?"])
def test_a_setting_asked_about_is_not_set(session, prompt):
    report = session.submit(prompt)
    assert session.scene.environment.weather.kind == "clear", report


def test_the_nearest_landmark_to_a_thing_is_answered_not_refused(session):
    report = session.submit("What is the nearest landmark to suv_1?")
    assert report.ok, report.error
    assert "parking lot B" in (report.answer or "")


def test_clearing_a_lot_removes_what_stands_in_it(session):
    assert session.submit("clear lot B").ok
    assert not any(a.id in ("passenger_car_1", "passenger_car_2", "suv_1") for a in session.scene.assets)


def test_the_parked_ones_are_those_standing_not_the_one_driving(session):
    assert session.submit("Add a car driving east on Main Street.").ok
    report = session.submit("the parked cars should all be grey, not the moving one")
    assert report.ok, report.error
    assert session.scene.asset("passenger_car_3").appearance.rgba is None
    assert session.scene.asset("passenger_car_1").appearance.rgba is not None


def test_one_of_several_moves_one(session, campus):
    report = session.submit("move one of the cars to the west car park instead of lot B")
    assert report.ok, report.error
    moved = [i for i in ("passenger_car_1", "passenger_car_2", "suv_1")
             if session.scene.asset(i).pose.x != campus.asset(i).pose.x]
    assert len(moved) == 1
    lot_a = session.scene.landmark("parking lot A")
    assert lot_a is not None and abs(session.scene.asset(moved[0]).pose.x - lot_a.position[0]) < 20


def test_walking_pace_is_a_speed(context):
    plan = RulePlanner().plan("Our car should crawl along at walking pace.", context)
    assert plan.calls[0].args["behaviour"]["speed"] == pytest.approx(1.4)


@pytest.mark.parametrize(("said", "meant"), [("delte all the tress", "trees"), ("line up 3 bueses in lot b", "buses")])
def test_a_slip_in_a_things_place_is_that_thing_even_when_the_slip_is_a_word(said, meant, campus):
    from drivetwin.orchestrator.planning.rules.spelling import repair

    assert meant in repair(said, campus).text.split()
    assert "three" in repair("the three cars", campus).text.split()  # a number is never a thing


def test_a_description_near_two_kinds_is_asked_about_with_both_readings(session):
    report = session.submit("We need the big vehicle that carries lots of passengers waiting at the shuttle stop.")
    assert not report.ok and report.question is not None
    kinds = {c.args.get("category") for reading in report.question.readings for c in reading.calls}
    assert {"bus", "truck"} <= kinds and "passenger_car" not in kinds
    assert session.scene.count("bus") == 0  # nothing applied while asking


def test_a_clear_description_is_read_as_its_thing(session):
    report = session.submit("I no longer want the red thing firefighters use on the pavement")
    assert report.ok, report.error
    assert session.scene.count("fire_hydrant") == 0


def test_it_after_an_addition_is_that_one_thing_once(session):
    assert session.submit("Add a bus at the bus stop.").ok
    report = session.submit("now paint it yellow")
    assert report.ok, report.error
    assert report.plan is not None and report.plan.calls[0].args["assets"] == ["bus_1"]


def test_a_thing_named_by_its_id_needs_no_which_one(session):
    report = session.submit("put teh sedan passenger_car_1 at the jtekt entrnce")
    assert report.ok, report.error


@pytest.mark.parametrize(("prompt", "gone"), [("could you lose a couple of the lamps?", 2)])
def test_a_couple_of_the_things_is_two(session, campus, prompt, gone):
    report = session.submit(prompt)
    assert report.ok, report.error
    kind = "street_light" if "lamps" in prompt else "traffic_light"
    assert campus.count(kind) - session.scene.count(kind) == gone


def test_a_material_typed_with_a_slip_is_that_material(session):
    report = session.submit("make the bech wodden pls")
    assert report.ok, report.error
    assert session.scene.asset("bench_1").appearance.material == "wood"


def test_can_have_one_without_a_subject_asks_for_one(session):
    report = session.submit("can have one bus somewhere?")
    assert report.ok, report.error
    assert session.scene.count("bus") == 1


def test_quieter_takes_away_some_of_what_moves_never_moves_it(session):
    assert session.submit("Add three cars driving west on Main Street.").ok
    report = session.submit("make it a bit quieter out there")
    assert report.ok, report.error
    assert 1 <= 3 - sum(1 for a in session.scene.assets if a.id in ("passenger_car_3", "passenger_car_4", "passenger_car_5")) < 3
    assert all(c.tool == "remove_assets" for c in report.plan.calls)


@pytest.mark.parametrize(("prompt", "meant"), [
    ("Park the tall boxy car in front of our test vehicle, about 15 m ahead", "suv_1"),
    ("Our car should start from the west entrance of the campus instead.", "main gate"),
    ("put a cone at the east entrance of the campus", "east gate"),
])
def test_a_description_with_a_group_or_place_head_is_read_as_that_one(context, prompt, meant):
    plan = RulePlanner().plan(prompt, context)
    said = str([c.args for c in plan.calls])
    assert meant in said, said


def test_a_place_that_way_is_never_another_kind_of_place(campus):
    from drivetwin.orchestrator.planning.descriptions import described

    assert described("the north entrance of the campus", campus)[1] == []  # only the north crosswalk lies that way


def test_orange_markers_closing_a_lane_are_cones(context):
    plan = RulePlanner().plan("Close off the westbound lane near the east gate with a row of those orange markers across it.", context)
    assert plan.calls[0].args["categories"] == ["traffic_cone"]


def test_up_ahead_is_ahead_of_the_ego(context):
    plan = RulePlanner().plan("few barriers across the road up ahead", context)
    assert plan.calls[0].args["location"] == {"relation": "in_front_of", "target": "ego"}


def test_a_different_colour_asks_which(context):
    with pytest.raises(PlanningError, match="which colour"):
        RulePlanner().plan("give the SUV a different colour?", context)


def test_walking_over_a_crossing_crosses_it_and_walking_over_to_a_place_walks_there(context):
    crossing = RulePlanner().plan("Someone should be walking over the west zebra crossing when the run starts.", context)
    assert crossing.calls[0].args["behaviour"]["kind"] == "cross_road"
    walk = RulePlanner().plan("have a man walk over to the fountain", context)
    assert walk.calls[0].args["behaviour"]["kind"] == "follow_path"


def test_a_distance_ahead_of_it_is_kept(context):
    plan = RulePlanner().plan("Our car needs something to follow: a car 25 m ahead of it, same lane, same speed.", context)
    assert plan.calls[0].args["location"].get("distance") == 25.0


def test_what_a_warning_is_made_with_is_asked_for(session):
    report = session.submit("Put some broken concrete in the westbound lane near the east gate, "
                            "and warn drivers with a road-works sign next to it.")
    assert report.ok, report.error
    assert session.scene.count("construction_sign") == 1


def test_what_not_to_do_then_what_to_do_does_the_second_with_it_meaning_the_first(context):
    plan = RulePlanner().plan("Don't move the SUV, move the sedan east of it two metres forward.", context)
    assert [c.tool for c in plan.calls] == ["move_asset"] and plan.calls[0].args["asset"] == "passenger_car_2"
    # a sedan stands each side of the SUV: "beside it" is either, which is asked, never the SUV moved
    with pytest.raises(PlanningError, match="which passenger car"):
        RulePlanner().plan("Don't move the SUV, move the sedan beside it two metres forward.", context)


def test_only_what_not_to_do_changes_nothing(context):
    with pytest.raises(PlanningError, match="what not to do"):
        RulePlanner().plan("don't move the SUV", context)


@pytest.mark.parametrize("prompt", ["block off lot B's entrance", "The stop sign should guard the lot B exit where it meets Main Street."])
def test_a_lots_exit_or_its_entrance_is_the_lot_entrance(context, prompt):
    plan = RulePlanner().plan(prompt, context)
    said = str([c.args for c in plan.calls])
    assert "parking lot B entrance" in said or "'x': 47.0" in said, said


def test_a_soaked_road_is_heavy_rain(session):
    report = session.submit("I want the road soaked, like it's been pouring all day.")
    assert report.ok, report.error
    assert session.scene.environment.weather.kind == "rain" and session.scene.environment.time_of_day == "12:00"


def test_a_ring_goes_round_the_place_said_after_around_not_a_thing_said_later(context):
    plan = RulePlanner().plan("a circle of 6 benches around the fountain, and a bin next to the fountain too", context)
    assert plan.calls[0].args["location"]["target"] == "fountain"


def test_some_of_a_thing_not_counted_is_one_heap(context):
    plan = RulePlanner().plan("add some broken concrete in the westbound lane", context)
    assert plan.calls[0].args["count"] == 1
    assert RulePlanner().plan("add some cones in the westbound lane", context).calls[0].args["count"] > 1


def test_a_car_to_follow_at_the_same_speed_drives_at_the_egos_speed(context):
    plan = RulePlanner().plan("Our car needs something to follow: a car 25 m ahead of it, same lane, same speed.", context)
    behaviour = plan.calls[0].args["behaviour"]
    assert behaviour["kind"] == "drive_lane" and behaviour["speed"] == context.scene.ego.behaviour.speed


def test_a_layout_offered_with_a_question_mark_is_laid_out(session):
    report = session.submit("people in a circle round the fountain?")
    assert report.ok, report.error
    assert session.scene.count("pedestrian") >= 4
    assert session.submit("are the cones in a row?").plan.calls[0].tool == "find_assets"


def test_the_other_side_of_the_road_mirrors_a_thing_over_it(session, campus):
    report = session.submit("stick the hydrant on the other side of the road")
    assert report.ok, report.error
    before, after = campus.asset("fire_hydrant_1"), session.scene.asset("fire_hydrant_1")
    assert after.pose.x == pytest.approx(before.pose.x) and after.pose.y == pytest.approx(-before.pose.y)


def test_the_start_of_the_road_is_the_start_of_the_lane_it_is_on(context):
    plan = RulePlanner().plan("put our car back at the start of the road", context)
    where = plan.calls[0].args["location"]
    assert where["lane"] == "main_eastbound" and where["target"].startswith("-100")


def test_us_after_have_or_get_is_the_ego_and_get_rid_at_the_end_removes(context):
    plan = RulePlanner().plan("clutter by the bus stop, get rid", context)
    assert plan.calls[0].tool == "remove_assets"
    from drivetwin.orchestrator.planning.rules.spelling import repair

    assert "have the ego turn" in repair("have us turn at the crossroads", context.scene).text
    assert "let us know" in repair("let us know how far it is", context.scene).text


def test_a_reason_ends_where_a_second_thing_is_asked_for(context):
    plan = RulePlanner().plan("could you add a bench near the fountain so people can rest, and a litter bin beside it as well", context)
    assert [c.args["category"] for c in plan.calls] == ["bench", "trash_bin"]


@pytest.mark.parametrize("prompt", ["I don't think we need quite so much greenery, if it's no bother.", "Quit the bech of the bus stp, pleace"])
def test_less_of_a_thing_or_quitting_it_takes_away_never_adds(context, prompt):
    plan = RulePlanner().plan(prompt, context)
    assert [c.tool for c in plan.calls] == ["remove_assets"] and plan.calls[0].args.get("count") == 1


def test_no_wait_then_a_request_takes_nothing_away(session):
    assert session.submit("Add a trash bin by the fountain.").ok
    report = session.submit("no wait, put the bin I just added by the library entrance instead")
    assert report.ok, report.error
    assert session.scene.count("trash_bin") == 2  # moved, never removed


def test_without_a_crossing_is_how_not_what_goes(session):
    assert session.submit("Add a pedestrian waiting at the bus stop.").ok
    report = session.submit("The pedestrian should go over the street without a zebra, right in front of the ego.")
    assert session.scene.count("pedestrian") == 1, report


@pytest.mark.parametrize(("prompt", "meant"), [("Put 6 barriers in line in the entrance of the parking A.", "parking lot A entrance"),
                                               ("Which of the pedestrian crossings is closest to our test car?", "crosswalk")])
def test_a_lots_entrance_said_the_other_way_round_and_crossings_in_the_plural(context, prompt, meant):
    plan = RulePlanner().plan(prompt, context)
    assert meant in str(plan.calls[0].args)


def test_the_roof_from_a_building_is_its_roof(session):
    report = session.submit("Add a car on the roof from the Libary, for the foto")
    assert not report.ok and "on top of the Library" in (report.error or "")


@pytest.mark.parametrize(("said", "kept"), [("Take away the lone tree behind the bus stop.", "lone"),
                                            ("let midnite fall over evrything, a deep blu dark", "deep")])
def test_a_word_said_of_what_follows_is_no_slip_for_a_thing(campus, said, kept):
    from drivetwin.orchestrator.planning.rules.spelling import repair

    assert kept in repair(said, campus).text.split()


def test_a_figure_said_beside_a_walking_pace_is_the_speed(context):
    plan = RulePlanner().plan("Let the ego drift slowly, a walking pace, no more than two metres a second.", context)
    assert plan.calls[0].args["behaviour"]["speed"] == 2.0
