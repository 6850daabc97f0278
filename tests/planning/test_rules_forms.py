"""The rule planner reads the forms a request takes beyond the plain imperative: a gerund used as
the command, a reason added with "so ...", a thing pointed at with "that thing", "out of here",
"nobody should ...", a layout named as the means, a place said by part of its name, a lane where
it passes a place, a catalog word used as a verb, and an "a" that cannot count a plural. Worded
for this file, unlike any suite."""

from __future__ import annotations

import math

import pytest
from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.orchestrator.planning.intent import asks
from drivetwin.orchestrator.planning.request import read_request
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.planning.rules.reading import find_place
from drivetwin.orchestrator.planning.rules.spelling import repair
from drivetwin.orchestrator.session import Session
from drivetwin.tools.errors import NotFoundError
from drivetwin.tools.locate import Location, resolve_anchor
from drivetwin.worlds.surface import point_in_polygon
from misreading import Fixed, call  # this folder is on sys.path (no __init__.py)


def calls_of(context, prompt: str) -> list[tuple[str, dict[str, object]]]:
    return [(c.tool, c.args) for c in RulePlanner().plan(prompt, context).calls]


def test_a_gerund_before_a_thing_is_the_command(context):
    assert calls_of(context, "deleting the hydrant near the library")[0][0] == "remove_assets"
    assert repair("the moving car", context.scene).text == "the moving car"  # an adjective stays


def test_a_reason_after_so_is_not_a_second_request(session):
    assert session.submit("add cement rubble at the junction").ok
    report = session.submit("empty the crossroads so buses can pass again")
    assert report.ok and session.scene.count("cement_rubble") == 0 and session.scene.count("bus") == 0


def test_that_thing_points_at_what_the_last_turn_added(session):
    assert session.submit("drop a cement rubble at lot B").ok
    added = [a.id for a in session.scene.assets if a.category == "cement_rubble"]
    report = session.submit("now delete that thing")
    assert report.ok and all(session.scene.asset(i) is None for i in added[-1:])


def test_out_of_here_takes_a_thing_away(context):
    ((tool, args),) = calls_of(context, "take the bus out of the scene")
    assert tool == "remove_assets" and "bus" in str(args)


def test_coordinates_without_equals_signs_are_read(context):
    ((tool, args),) = calls_of(context, "put the bench to x 12 y -7")
    assert tool == "place_asset" and args["location"] == {"relation": "absolute", "x": 12.0, "y": -7.0}


def test_a_side_move_with_no_amount_takes_a_default_step(context):
    ((tool, args),) = calls_of(context, "the suv should roll back a bit")
    assert tool == "move_asset" and args["forward"] < 0
    ((tool, args),) = calls_of(context, "the suv ought to edge forward")
    assert tool == "move_asset" and args["forward"] > 0


def test_a_lane_said_with_a_place_stands_in_that_lane_by_that_place(context, campus):
    ((tool, args),) = calls_of(context, "a van stalled in the westbound lane by the library")
    assert tool == "add_asset" and args["location"] == {
        "relation": "in_lane", "target": "Library entrance", "lane": "main_westbound"}
    anchor = resolve_anchor(campus, Location(**args["location"]), 3.0)
    assert anchor.lane_id == "main_westbound"


def test_an_a_in_front_of_another_noun_does_not_count_a_plural(context):
    ((tool, args),) = calls_of(context, "give lot A a safe corner with bollards")
    assert tool == "add_asset" and args.get("count") != 1


def test_someone_doing_something_to_a_thing_is_not_a_pedestrian_to_add(context):
    ((tool, args),) = calls_of(context, "somebody abandoned a bicycle at the fountain")
    assert tool == "add_asset" and args["category"] == "bicycle"


def test_a_place_name_read_as_a_verb_phrase_is_not_the_place(context, campus):
    place = find_place(campus, " a pedestrian crossing the road by the north crosswalk ")
    assert place is not None and place[0] == "north crosswalk"


def test_a_place_said_by_the_first_and_last_words_of_its_name(campus):
    place = find_place(campus, " leave it in the west lot ")
    assert place is not None and place[0] == "parking lot A"


def test_where_slips_and_a_question_after_the_thing_are_questions(context):
    assert repair("were is the fountain", context.scene).text.startswith("where is")
    assert asks("the hydrants, where are they")
    assert not asks("remove the bench, which is in the way")


def test_a_catalog_word_used_as_the_verb_is_not_the_thing(context):
    ((tool, args),) = calls_of(context, "plant a row of bins along lot B")
    assert tool == "arrange_assets" and args.get("categories", [args.get("category")]) == ["trash_bin"]


def test_a_layout_named_as_the_means_is_what_is_built(context):
    ((tool, args),) = calls_of(context, "keep buses out of lot A using a line of barriers")
    assert tool == "arrange_assets" and args["categories"] == ["road_barrier"] and args["shape"] == "line"


def test_things_laid_out_with_are_the_layout_not_its_centre(session):
    assert session.submit("put some rubble in lot B").ok
    report = session.submit("surround the rubble with cones")
    assert report.ok and [a.category for a in session.scene.assets].count("traffic_cone") >= 3


def test_nobody_should_be_somewhere_removes_who_is_there(session):
    assert session.submit("add a pedestrian at the fountain").ok
    walkers = [a.id for a in session.scene.assets if a.category == "pedestrian"]
    report = session.submit("no one should be standing at the fountain")
    assert report.ok and session.scene.asset(walkers[-1]) is None


def test_closing_a_road_by_its_name_lays_barriers_across_it(context):
    ((tool, args),) = calls_of(context, "shut Main Street near the library")
    assert tool == "arrange_assets" and args["shape"] == "line" and "road_barrier" in args["categories"]


def test_standing_out_asks_for_a_conspicuous_colour(context):
    ((tool, args),) = calls_of(context, "the suv needs to stand out")
    assert tool == "set_asset_appearance" and args["colour"] == "orange"


def test_an_avenue_is_a_line(context):
    ((tool, args),) = calls_of(context, "an avenue of benches along lot B")
    assert tool == "arrange_assets" and args["shape"] == "line"


def test_a_ring_of_some_things_all_the_way_round_takes_as_many_as_it_needs(context):
    ((tool, args),) = calls_of(context, "some bollards all the way around the fountain")
    assert tool == "arrange_assets" and "count" not in args


def test_lane_field_names_a_lane_unknown_to_the_world_in_one_line(campus):
    with pytest.raises(NotFoundError, match="no lane 'main_sideways'"):
        resolve_anchor(campus, Location(relation="in_lane", target="fountain", lane="main_sideways"), 3.0)


def test_a_lane_by_a_place_is_nearer_the_place_than_the_lane_start(campus):
    lib = campus.landmark("Library entrance")
    assert lib is not None
    anchor = resolve_anchor(campus, Location(relation="in_lane", target="Library entrance", lane="main_eastbound"), 3.0)
    start = next(ln for ln in campus.roads.lanes if ln.id == "main_eastbound").centreline[0]
    assert math.dist((anchor.x, anchor.y), lib.position) < math.dist(start, lib.position)


def test_a_question_about_a_thing_this_world_has_no_word_for_is_refused_by_name(context):
    with pytest.raises(PlanningError, match="no 'airships'"):
        RulePlanner().plan("how many airships are hovering over the quad?", context)


def test_turn_of_before_the_lights_is_a_slip_for_off(context):
    assert calls_of(context, "switch of the street lamps") == [("set_lighting", {"street_lights": "off"})]


def test_a_colour_said_after_the_thing_in_another_clause_is_for_that_thing(context):
    calls = calls_of(context, "the suv must be easy to spot; bright green works")
    assert calls[-1] == ("set_asset_appearance", {"assets": ["suv_1"], "colour": "green"})


def test_a_radius_is_read_however_it_is_said_and_is_no_distance(context):
    for said in ("at a 4 m radius", "with a radius of 4 metres", "radius 4"):
        ((tool, args),) = calls_of(context, f"ring the fountain with six cones {said}")
        assert tool == "arrange_assets" and args["radius"] == 4.0 and "distance" not in args["location"]


def test_the_weights_of_two_kinds_are_two_lookups_and_change_nothing(session):
    before = len(session.scene.assets)
    report = session.submit("I'd need the masses of a bus and a motorcycle for my notes")
    assert report.ok and len(session.scene.assets) == before
    assert [c.args.get("category") for c in report.plan.calls] == ["bus", "motorcycle"]


def test_a_question_about_a_road_is_answered_by_a_lookup_of_its_lane(session):
    report = session.submit("could you tell me if something blocks the westbound lane of Main Street?")
    assert report.ok and report.plan.calls[0].args.get("lane") == "main_westbound"


def test_all_and_a_number_name_things_already_there(session):
    report = session.submit("move all three vehicles in lot B 4 m north")
    assert report.ok and [c.tool for c in report.plan.calls] == ["move_asset"]
    assert len(report.plan.calls[0].args["assets"]) == 3


def test_a_place_said_before_the_things_says_which_and_a_little_moves_them_all(context):
    ((tool, args),) = calls_of(context, "budge the lot B cars a touch")
    assert tool == "move_asset" and sorted(args["assets"]) == ["passenger_car_1", "passenger_car_2", "suv_1"]  # cars: the SUV too


def test_feet_are_read_as_metres(context):
    ((tool, args),) = calls_of(context, "roll the suv forward 20 feet")
    assert tool == "move_asset" and args["forward"] == pytest.approx(6.1, abs=0.01)


def test_a_thing_joined_without_an_article_is_a_second_thing(context):
    assert [a.get("category") for _, a in calls_of(context, "delete hydrant and bench both")] == ["fire_hydrant", "bench"]


def test_a_doubled_w_is_a_slip_not_an_inflection(context):
    assert calls_of(context, "make it snowwing hard") == [("set_weather", {"kind": "snow", "intensity": 0.9})]


def test_a_distance_said_with_a_side_is_in_front_or_behind(context):
    ((tool, args),) = calls_of(context, "a stalled bus in the ego's lane some 30 m ahead")
    assert tool == "add_asset" and args["location"] == {"relation": "in_front_of", "target": "ego", "distance": 30.0}


def test_a_word_written_apart_is_joined_when_it_is_one_known_word(context):
    assert repair("a cone on the side walk", context.scene).text == "a cone on the sidewalk"
    assert repair("a lamp post", context.scene).text == "a lamp post"  # a catalog phrase stays apart


def test_a_road_named_drive_asks_no_one_to_drive(context):
    ((tool, args),) = calls_of(context, "move the suv into the northbound lane of Campus Drive")
    assert tool == "place_asset" and "behaviour" not in args


def test_the_ego_after_near_or_from_is_a_reference_never_the_thing_removed(context):
    ((tool, args),) = calls_of(context, "take away the two lamps nearest from the ego")
    assert tool == "remove_assets" and args.get("category") == "street_light" and args.get("near") == "ego"


def test_two_verbless_requests_joined_by_comma_and_are_two_edits(context):
    calls = calls_of(context, "the suv a little back, and the bench turned around")
    assert [(t, a.get("asset")) for t, a in calls] == [("move_asset", "suv_1"), ("move_asset", "bench_1")]


def test_a_street_wished_busier_gets_traffic_that_drives(context):
    ((tool, args),) = calls_of(context, "campus drive feels empty, make it livelier")
    assert tool == "add_asset" and args["category"] == "passenger_car" and args["behaviour"]["kind"] == "drive_lane"


def test_a_square_wished_busier_gets_people(context):
    ((tool, args),) = calls_of(context, "the fountain could be busier")
    assert tool == "add_asset" and args["category"] == "pedestrian"


def test_night_said_as_when_lamps_are_needed_is_no_time_change(session):
    report = session.submit("lot A gets pitch black at night, it needs a street light")
    assert report.ok and session.scene.count("street_light") > 0
    assert not any(c.tool == "set_time_of_day" for c in report.plan.calls)


def test_without_doing_something_is_a_manner_not_a_removal(context):
    calls = calls_of(context, "add a kid who steps onto the road without looking")
    assert calls[0][0] == "add_asset" and calls[0][1]["count"] == 1


def test_an_e_kept_before_ing_is_a_slip(context):
    ((tool, args),) = calls_of(context, "a bus moveing along main street")
    assert tool == "add_asset" and args["behaviour"]["kind"] == "drive_lane"


def test_in_front_without_of_is_still_in_front(context):
    ((tool, args),) = calls_of(context, "a bin in front the library")
    assert tool == "add_asset" and args["location"]["relation"] == "in_front_of"


def test_things_along_a_place_are_laid_out_in_a_line(context):
    ((tool, args),) = calls_of(context, "benches along the north side of lot B")
    assert tool == "arrange_assets" and args["shape"] == "line"


def test_whatever_is_parked_somewhere_empty_says_nothing_is_there(context):
    with pytest.raises(PlanningError, match="nothing parked at parking lot A"):
        RulePlanner().plan("clear away whatever is parked in lot A", context)


def test_a_layout_verb_lays_out_what_comes_after_with(context):
    ((tool, args),) = calls_of(context, "edge the quad with benches")
    assert tool == "arrange_assets" and args["categories"] == ["bench"]


def test_a_superlative_is_no_unknown_place(session):
    report = session.submit("where's the closest bench to the library?")
    assert report.ok and report.plan.calls[0].args.get("nearest_to") == "Library entrance"


def test_facing_a_compass_point_turns_by_the_difference(context, campus):
    suv = campus.asset("suv_1")
    assert suv is not None and abs(suv.pose.yaw - math.pi / 2) < 1e-6  # it faces north
    assert calls_of(context, "have the suv pointing south") == [("move_asset", {"asset": "suv_1", "turn_deg": 180.0})]
    with pytest.raises(PlanningError, match="already faces north"):
        RulePlanner().plan("turn the suv to face north", context)


def test_a_reason_said_first_then_so_and_a_command_is_the_command(context):
    calls = calls_of(context, "we are checking how the planner copes with mist, so give us some fog")
    assert [c[0] for c in calls] == ["set_weather"] and calls[0][1]["kind"] == "fog"


def test_give_me_asks_for_a_thing_unless_it_asks_for_a_list_or_a_number(context):
    assert calls_of(context, "give me a bit of snow")[0][0] == "set_weather"
    assert asks("give us a rundown of the benches") and not asks("give us a bit of snow")
    assert calls_of(context, "I'd like the number of street lamps") == calls_of(context, "how many street lamps are there")
    assert calls_of(context, "what's the number of lamps")[0][1] == {"category": "street_light"}


def test_later_earlier_and_brighter_are_said_from_where_the_scene_is(context, session):
    assert context.scene.environment.time_of_day == "12:00"
    assert calls_of(context, "push the clock on a bit, later in the afternoon")[0][1] == {"time": "15:00"}
    assert calls_of(context, "three hours earlier")[0][1] == {"time": "09:00"}
    assert calls_of(context, "the picture is too dark, brighter") == [("set_lighting", {"exposure": 1.5})]
    assert calls_of(context, "switch the street lamps on, it is too dark") == [("set_lighting", {"street_lights": "on"})]
    assert session.submit("set the time to 22:30").ok
    assert session.submit("an hour later").ok and session.scene.environment.time_of_day == "23:30"


def test_measures_spelt_in_words_are_read_as_figures(context):
    assert calls_of(context, "nudge the fire hydrant forty-five degrees round") == calls_of(
        context, "nudge the fire hydrant 45 degrees round")
    assert calls_of(context, "roll the ego back by seven metres") == [("move_asset", {"asset": "ego", "forward": -7.0})]
    assert calls_of(context, "shove the bench half a metre to its left")[0][1]["left"] == 0.5
    assert repair("meet at 7 a m", context.scene).text == "meet at 7 a m"


def test_a_weather_strength_said_in_figures_is_that_strength(context):
    assert calls_of(context, "snow, with an intensity of 0.45") == [("set_weather", {"kind": "snow", "intensity": 0.45})]
    assert calls_of(context, "drizzle at 20 percent")[0][1]["intensity"] == 0.2


def test_a_lane_and_a_distance_ahead_of_a_thing_count_along_that_lane(context):
    loc = calls_of(context, "drop some rubble in the eastbound lane twenty metres ahead of the ego")[0][1]["location"]
    assert loc == {"relation": "in_lane", "target": "ego", "along_m": 20.0, "lane": "main_eastbound"}
    loc = calls_of(context, "a cone in the westbound lane 8 m behind the bus stop")[0][1]["location"]
    assert loc["along_m"] == -8.0 and loc["lane"] == "main_westbound"


def test_a_grid_said_as_rows_by_columns_holds_their_product(context):
    args = calls_of(context, "set out a five by two grid of bollards at the fountain")[0][1]
    assert (args["count"], args["columns"], args["shape"]) == (10, 2, "grid")
    args = calls_of(context, "bollards in a 4x4 grid in lot A")[0][1]
    assert (args["count"], args["columns"], args["categories"]) == (16, 4, ["bollard"])
    assert calls_of(context, "a four-by-four grid of cones in lot A")[0][1]["categories"] == ["traffic_cone"]


def test_a_clause_saying_what_a_thing_does_is_context_for_the_command(context):
    calls = calls_of(context, "The SUV blocks my camera; shift it three metres forward")
    assert calls == [("move_asset", {"asset": "suv_1", "forward": 3.0})]
    assert calls_of(context, "the street lights look dull; make it foggy")[0][0] == "set_weather"
    # what should be, said of a thing, is itself the request
    assert calls_of(context, "The SUV should be at lot A; add a bench by the library")[0][0] == "place_asset"


def test_hedged_suggestions_denied_strengths_and_place_words(context):
    assert not asks("perhaps put a bench by the fountain?")
    assert calls_of(context, "perhaps put a bench by the fountain?")[0][0] == "add_asset"
    assert calls_of(context, "snow please, but not too heavy")[0][1]["intensity"] < 0.5
    # "student" names the car park here, not a person in it; "rows" lays cars out
    args = calls_of(context, "three hatchbacks in rows in the student car park")[0][1]
    assert args["categories"] == ["passenger_car"] and args["shape"] == "parking_row"


def test_more_and_another_after_a_turn_count_what_is_said(session):
    assert session.submit("four cones in our lane 25 m ahead of the ego").ok
    assert session.submit("those cone, make them all white").ok
    assert all(a.appearance.rgba is not None for a in session.scene.assets if a.category == "traffic_cone")
    assert session.submit("and 2 more next to them").ok and session.scene.count("traffic_cone") == 6
    assert session.submit("another there").ok and session.scene.count("traffic_cone") == 7


def test_keep_just_n_takes_away_the_rest_and_a_long_line_ahead_runs_along(context, session):
    assert session.submit("put four benches by the fountain").ok
    assert session.submit("too many benches by the fountain, leave only one").ok
    assert sum(1 for a in session.scene.assets if a.category == "bench" and math.dist((a.pose.x, a.pose.y), (75, 40)) < 30) == 1
    args = calls_of(context, "six cones in a line 5 m apart ahead of the ego")[0][1]
    assert args["heading_deg"] == 0.0 and args["location"]["distance"] > 12.5  # the ego faces east; all of it ahead
    assert "heading_deg" not in calls_of(context, "a line of four cones across the road in front of the ego")[0][1]


def test_a_question_about_a_whole_kind_searches_the_kind(context):
    assert calls_of(context, "which vehicles stand in lot B?")[0][1]["category"] == "vehicles"
    assert calls_of(context, "how many signs do we have")[0][1] == {"category": "signs"}
    assert calls_of(context, "where are the hatchbacks")[0][1] == {"category": "passenger_car"}


def test_riders_ride_lanes_and_a_place_word_is_the_head_of_its_name(context):
    args = calls_of(context, "a scooter riding up the northbound lane")[0][1]
    assert args["category"] == "motorcycle" and args["behaviour"]["kind"] == "drive_lane"
    # "scene" ends "centre of the scene" but names no place; "stop" is the stop sign's word here
    assert calls_of(context, "what have we got in this scene")[0] == ("find_assets", {})
    assert calls_of(context, "whats the closest thing too the stop sing")[0] == ("find_assets", {"nearest_to": "stop_sign_1"})


def test_next_to_it_is_beside_what_an_earlier_clause_adds_and_a_colon_introduces(session):
    report = session.submit("the robot needs a warning for drivers: add a rover at the JTEKT entrance and a road-work sign beside it")
    assert report.ok, report.error
    rover, sign = (next(a for a in session.scene.assets if a.category == c) for c in ("ackermann_robot", "construction_sign"))
    assert session.scene.count("ackermann_robot") == 1, "the introduction before the colon adds nothing of its own"
    assert math.dist((rover.pose.x, rover.pose.y), (sign.pose.x, sign.pose.y)) < 5.0


def test_nobody_using_a_thing_any_more_takes_it_away(session, campus):
    report = session.submit("no one uses the bench at the bus stop any more, it only clutters the picture")
    assert report.ok, report.error
    assert session.scene.count("bench") == campus.count("bench") - 1
    assert read_request("nobody uses the bench any more", campus).polarity == "remove"


def test_a_parked_car_asked_to_pull_out_drives_off_and_is_not_removed(session):
    # ("... on main street": the plan drives it in the lane nearest lot B, off Main Street, which the
    # check's road scope refuses; the SUV is never removed either way)
    assert session.submit("time for the parked 4x4 to pull out, then it should follow the eastbound traffic on main street").error \
        and session.scene.asset("suv_1") is not None
    report = session.submit("time for the parked 4x4 to pull out, then it should follow the eastbound traffic")
    assert report.ok, report.error
    suv = session.scene.asset("suv_1")
    assert suv is not None and suv.behaviour.kind == "drive_lane"


def test_things_listed_that_should_go_all_go_and_can_go_is_removal(session, campus):
    report = session.submit("it looks untidy, so the bench plus the bin at the bus stop must go")
    assert report.ok, report.error
    assert (session.scene.count("bench"), session.scene.count("trash_bin")) == (campus.count("bench") - 1, campus.count("trash_bin") - 1)
    assert session.submit("the hatchbacks can go, i think").ok and session.scene.count("passenger_car") == 0
    assert read_request("the car should go to lot A", campus).polarity != "remove"


def test_moving_a_thing_that_drives_up_moves_it_forward(context):
    assert calls_of(context, "could you move the test car up a little")[0] == ("move_asset", {"asset": "ego", "forward": 1.5})
    assert "forward" not in calls_of(context, "move the bench 3 m north")[0][1]


def test_the_sun_coming_up_is_sunrise_and_a_hyphenated_phrase_reads_as_its_words(context):
    assert ("set_time_of_day", {"time": "sunrise"}) in calls_of(context, "make it the early-morning rush, sun coming up")


def test_a_move_toward_a_place_heads_straight_for_it_and_a_car_moved_vaguely_moves_on(session, context):
    bin_before = session.scene.asset("trash_bin_1")
    assert bin_before is not None and session.submit("shift the trash bin 3 m towards the fountain").ok
    bin_after, fountain = session.scene.asset("trash_bin_1"), session.scene.landmark("fountain")
    assert bin_after is not None and fountain is not None
    before, after = (math.dist((b.pose.x, b.pose.y), fountain.position) for b in (bin_before, bin_after))
    assert before - after == pytest.approx(3.0, abs=0.1)
    assert "forward" in calls_of(context, "shift the suv a little")[0][1]
    assert calls_of(context, "push trash bin 2 meter to east side")[0][1]["east"] == 2.0


def test_the_one_on_a_corner_or_furthest_one_way_is_the_one_meant(session, campus):
    lights = [a for a in campus.assets if a.category == "street_light"]
    westernmost = min(lights, key=lambda a: a.pose.x)
    assert session.submit("take away the westernmost street lamp").ok
    assert session.scene.asset(westernmost.id) is None and session.scene.count("street_light") == len(lights) - 1
    signals = [a for a in campus.assets if a.category == "traffic_light"]
    north_east = max(signals, key=lambda a: a.pose.x + a.pose.y)
    assert session.submit("i'd rather not have the signal on the north-east corner of the crossroads").ok
    assert session.scene.asset(north_east.id) is None and session.scene.count("traffic_light") == len(signals) - 1


def test_what_follows_so_is_the_request_when_nothing_else_is_and_lamps_wished_lit_are_switched_on(context):
    calls = calls_of(context, "we're filming the graveyard shift, so it has to be night and the street lamps have to be lit")
    assert ("set_time_of_day", {"time": "night"}) in calls and ("set_lighting", {"street_lights": "on"}) in calls
    assert calls_of(context, "street lamps should stay off tonight") == [("set_lighting", {"street_lights": "off"})]
    assert calls_of(context, "could you make the weather nice again") == [("set_weather", {"kind": "clear"})]


def test_junk_off_the_road_is_what_stands_on_it_and_a_mistake_goes(session, campus):
    assert session.submit("drop two cones and a barrier in our lane 30 m ahead of the ego").ok
    assert session.submit("remove the clutter from our lane").ok
    assert session.scene.count("traffic_cone") == campus.count("traffic_cone") and session.scene.count("road_barrier") == 0
    assert session.scene.count("bench") == campus.count("bench"), "what stands off the road stays"
    assert session.submit("put a bench next to the fountain").ok
    assert session.submit("hmm, that bench was a mistake").ok and session.scene.count("bench") == campus.count("bench")


def test_a_question_after_please_is_a_question_and_whoever_opens_a_statement(context):
    assert asks(" please , where is the bus stop ? ") and not asks(" please add a cone ? ")
    assert calls_of(context, "whoever uses the bench looks straight at the cars; turn the bench round")[0][0] == "move_asset"


def test_the_other_place_is_the_one_like_where_the_thing_stands(session):
    lot_a = session.scene.landmark("parking lot A")
    assert lot_a is not None and lot_a.polygon is not None
    assert session.submit("could the suv go to the other car park").ok
    suv = session.scene.asset("suv_1")
    assert suv is not None and point_in_polygon(suv.pose.x, suv.pose.y, lot_a.polygon)


def test_a_clause_that_only_names_things_is_the_topic_of_the_question_after_it(session):
    report = session.submit("those street lamps... where are they?")
    assert report.ok and report.plan is not None and report.plan.calls[0].tool == "find_assets"
    assert all(f"street_light_{n}" in (report.answer or "") for n in range(1, 13))
    assert calls_of_session(session, "Place the car number 2 in front of the library")[0].args["asset"] == "passenger_car_2"
    assert [c.tool for c in calls_of_session(session, "turn of the street lamps")] == ["set_lighting"]


def calls_of_session(session, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error or (report.question.text if report.question else "")
    return report.plan.calls


def test_a_line_down_a_lane_starts_where_said_and_a_short_line_across_stands_clear_ahead(session):
    assert session.submit("four cones down the middle of the eastbound lane, 8 m apart, starting 15 m ahead of the ego").ok
    ego = session.scene.ego
    cones = sorted((a for a in session.scene.assets if a.category == "traffic_cone"), key=lambda a: a.pose.x)
    assert [round(a.pose.x - ego.pose.x) for a in cones] == [15, 23, 31, 39]
    assert all(abs(a.pose.y - ego.pose.y) < 0.5 for a in cones)
    assert session.submit("now a row of 4 bollards in front of the ego").ok
    barriers = [a for a in session.scene.assets if a.category == "bollard"]
    assert len(barriers) == 4 and all(abs(math.degrees(math.atan2(a.pose.y - ego.pose.y, a.pose.x - ego.pose.x))) < 20 for a in barriers)


def test_beside_it_is_beside_what_the_last_turn_moved_and_what_people_do_is_context(session):
    assert session.submit("take the hydrant over to the fountain").ok
    hydrant = session.scene.asset("fire_hydrant_1")
    report = session.submit("students often sit there at lunch; the trash bin belongs beside it")
    assert report.ok, report.error or (report.question.text if report.question else "")
    bin_ = session.scene.asset("trash_bin_1")
    assert hydrant is not None and bin_ is not None and session.scene.count("pedestrian") == 0
    assert math.dist((bin_.pose.x, bin_.pose.y), (hydrant.pose.x, hydrant.pose.y)) < 4.0


def test_a_forbidden_thing_is_no_request_and_what_follows_so_rings_the_place_it_names(session, campus):
    report = session.submit("cyclists mustn't ride into the bus stop, so fence it off with posts all the way round")
    assert report.ok, report.error or (report.question.text if report.question else "")
    assert session.scene.count("bicycle") == 0 and session.scene.count("road_barrier") == 0
    assert session.scene.count("bollard") >= 4
    report = session.submit("the fire hydrant is leaking: surround it with bollards and put a warning sign beside it")
    assert report.ok, report.error or (report.question.text if report.question else "")
    hydrant = session.scene.asset("fire_hydrant_1")
    sign = next(a for a in session.scene.assets if a.category == "construction_sign")
    assert hydrant is not None and math.dist((hydrant.pose.x, hydrant.pose.y), (sign.pose.x, sign.pose.y)) < 4.0


def test_the_western_one_of_a_kind_and_nothing_put_where_it_already_stands(session, campus, registry):
    lot_a = session.scene.landmark("parking lot A")
    assert lot_a is not None and lot_a.polygon is not None
    report = session.submit("our 4x4 is parked in the wrong parking area; it should be in the western one")
    assert report.ok, report.error or (report.question.text if report.question else "")
    suv = session.scene.asset("suv_1")
    assert suv is not None and point_in_polygon(suv.pose.x, suv.pose.y, lot_a.polygon)
    # a plan that puts the SUV in the lot it already stands in is not applied
    fixed = Session(campus, Fixed(call("place_asset", asset="suv_1", location={"relation": "at", "target": "parking lot B"})), registry)
    report = fixed.submit("the suv should not stay where it is")
    assert not report.ok and fixed.scene == campus


def test_another_pair_of_those_adds_two(session, campus):
    assert session.submit("three bollards by the library entrance").ok
    assert session.submit("and another couple of those beside them").ok
    assert session.scene.count("bollard") == campus.count("bollard") + 5
