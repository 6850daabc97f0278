"""The rule planner reads the structure of a request: which verb governs which things, which thing
moves and which is only where it goes, the scope a place gives, a direction, a layout, a count
said after the thing, and what kind of request it is. Worded for this file, unlike any suite."""

from __future__ import annotations

import math

import pytest
from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.intent import asks
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.planning.rules.reading import find_place
from misreading import Fixed, call  # this folder is on sys.path (no __init__.py)


def calls_of(context, prompt: str) -> list[tuple[str, dict[str, object]]]:
    return [(c.tool, c.args) for c in RulePlanner().plan(prompt, context).calls]


def test_one_verb_governs_each_thing_joined_to_it(context):
    calls = calls_of(context, "delete the bench plus the stop sign")
    assert [(tool, args.get("category")) for tool, args in calls] == [
        ("remove_assets", "bench"),
        ("remove_assets", "stop_sign"),
    ]


def test_one_verb_governs_the_ego_joined_to_another_thing(context):
    calls = calls_of(context, "could you park the SUV in lot B and the ego car in lot A")
    assert [(tool, args["asset"], args["location"]["target"]) for tool, args in calls] == [
        ("place_asset", "suv_1", "parking lot B"), ("place_asset", "ego", "parking lot A")]


def test_a_verb_with_its_particle_governs_each_thing_joined_to_it(context):
    calls = calls_of(context, "could you take out the hydrant and the stop sign")
    assert [(tool, args.get("category")) for tool, args in calls] == [
        ("remove_assets", "fire_hydrant"), ("remove_assets", "stop_sign")]


def test_a_colour_said_once_after_things_joined_colours_each_of_them(context):
    calls = calls_of(context, "paint the hydrant and the bin yellow")
    assert [(tool, args["colour"]) for tool, args in calls] == [("set_asset_appearance", "yellow")] * 2
    calls = calls_of(context, "paint the hydrant green and the bin yellow")
    assert [args["colour"] for _, args in calls] == ["green", "yellow"]


def test_things_joined_inside_a_layout_stay_one_clause(context):
    ((tool, args),) = calls_of(context, "a ring of cones and a barrier round the fountain")
    assert tool == "arrange_assets" and set(args["categories"]) == {"traffic_cone", "road_barrier"}


def test_the_thing_named_first_moves_and_the_ego_is_where_it_goes(context):
    ((tool, args),) = calls_of(context, "set the suv 6 m behind the ego")
    assert tool == "place_asset" and args["asset"] == "suv_1"
    assert args["location"] == {"relation": "behind", "target": "ego", "distance": 6.0}


def test_behind_us_names_the_ego(context):
    ((tool, args),) = calls_of(context, "the suv just behind us please")
    assert tool == "place_asset" and args["location"]["target"] == "ego"


def test_a_compass_move_shifts_east_and_north(context):
    assert calls_of(context, "shove the bench 3 m west") == [
        ("move_asset", {"asset": "bench_1", "east": -3.0, "north": 0.0})
    ]


def test_a_bit_is_a_small_step(context):
    ((tool, args),) = calls_of(context, "could the suv roll back a little")
    assert tool == "move_asset" and args["forward"] < 0


def test_every_member_of_a_catalog_group_in_a_place_moves_together(context, campus):
    ((tool, args),) = calls_of(context, "shift every vehicle in parking lot B 2 m south")
    in_lot_b = {a.id for a in campus.assets if a.category in ("passenger_car", "suv")
                and math.dist((a.pose.x, a.pose.y), campus.landmark("parking lot B").position) < 40}
    assert tool == "move_asset" and set(args["assets"]) == in_lot_b and args["north"] == -2.0


def test_a_removal_takes_only_the_things_at_the_place_it_names(context, campus):
    ((tool, args),) = calls_of(context, "I'd like the fountain area without any trees")
    fountain = campus.landmark("fountain").position
    removed = [campus.asset(i) for i in args["assets"]]
    assert tool == "remove_assets" and removed
    assert all(math.dist((a.pose.x, a.pose.y), fountain) <= 20.0 for a in removed)
    assert len(removed) < campus.count("tree")


def test_one_of_the_plural_is_one(context):
    ((_, args),) = calls_of(context, "add one of those little research rovers")
    assert args["count"] == 1


def test_a_count_may_follow_the_thing(context):
    ((_, args),) = calls_of(context, "bollards x5 at the fountain, as a ring")
    assert args["count"] == 5


def test_a_grid_takes_its_columns(context):
    ((tool, args),) = calls_of(context, "8 benches as a grid of 4 columns in lot A")
    assert tool == "arrange_assets" and args["shape"] == "grid" and args["columns"] == 4


def test_lining_things_up_lays_out_a_line(context):
    ((tool, args),) = calls_of(context, "line up five bins at the library")
    assert tool == "arrange_assets" and args["shape"] == "line" and args["count"] == 5


def test_a_material_changes_the_look_of_what_is_there(context):
    assert calls_of(context, "make the bench metallic") == [
        ("set_asset_appearance", {"assets": ["bench_1"], "material": "metal"})
    ]


def test_more_of_a_quality_is_not_more_things(context):
    ((tool, _),) = calls_of(context, "the hydrant looks more natural on the sidewalk by the library")
    assert tool == "place_asset"


def test_a_wish_for_where_a_thing_should_be_places_it(context):
    ((tool, args),) = calls_of(context, "could the first car go in lot B?")
    assert tool == "place_asset" and args["location"]["target"] == "parking lot B"


def test_a_statement_of_how_things_are_is_context_for_the_clause_that_acts(context):
    calls = calls_of(context, "the trash bin next to the stop is a problem; could you take it away?")
    assert calls == [("remove_assets", {"assets": ["trash_bin_1"]})]


def test_a_letter_that_names_a_lot_is_not_an_article(campus):
    assert find_place(campus, " leave it in lot a for now ")[0] == "parking lot A"
    assert find_place(campus, " by lot b's entrance ")[0] == "parking lot B entrance"


def test_the_middle_of_a_place_is_that_place_and_the_middle_alone_the_scene_s_centre(context):
    ((_, args),) = calls_of(context, "a 2 by 2 grid of bins right in the middle of lot A")
    assert args["location"] == {"relation": "at", "target": "parking lot A"}
    ((_, args),) = calls_of(context, "one bin in the middle, please")
    assert args["location"] == {"relation": "scene_centre"}


def test_past_a_place_in_a_lane_named_is_further_along_that_lane(context):
    ((_, args),) = calls_of(context, "two barriers in the westbound lane a way beyond the crossroads")
    assert args["location"] == {"relation": "in_lane", "target": "main intersection", "lane": "main_westbound", "distance": 25.0}
    ((_, args),) = calls_of(context, "a cone in the eastbound lane 12 m past the main gate")
    assert args["location"]["distance"] == 12.0 and args["location"]["lane"] == "main_eastbound"


def test_the_entrance_to_a_place_is_that_place_s_entrance(campus):
    assert find_place(campus, " cones at the entrance to lot b please ")[:1] == ("parking lot B entrance",)
    assert find_place(campus, " a bin by the driveway into the lot a ")[0] == "parking lot A entrance"
    assert find_place(campus, " two bikes at the entrance of the library ")[0] == "Library entrance"


@pytest.mark.parametrize(
    ("words", "question"),
    [
        ("i need to know how many benches there are", True),
        ("tell me where the hydrant is", True),
        ("could you add two bins by the library?", False),
        ("could the suv park in lot a?", False),
        ("is the bus near the stop?", True),
    ],
)
def test_intent_tells_a_question_from_a_polite_command(words, question):
    assert asks(words) is question


def test_modifiers_read_direction_layout_groups_and_shares():
    assert md.compass_direction("slide it 2 m northwards") == "north"
    assert md.compass_direction("the north gate") is None  # a place's name, not a way to go
    assert md.layout_said("stand them in a row") == "row"
    assert md.layout_said("wait at the stop line") is None
    assert "vehicle" in md.groups_said("all the vehicles")
    assert md.groups_said("the street lights") == {}  # the lights of a category's own name
    assert md.partitive_count("move two of the ") == 2


def test_a_bare_noun_after_put_that_moves_the_one_there_is_asked_about(context):
    plan = Fixed(call("place_asset", asset="bench_1", location={"relation": "at", "target": "fountain"}))
    verdict = review("put bench at the fountain", plan.plan("put bench at the fountain", context), context)
    assert verdict.action in ("ask", "refuse")
    assert "new bench" in verdict.problems[0]


def test_a_contraction_with_its_apostrophe_is_not_repaired_into_a_word(campus):
    from drivetwin.orchestrator.planning.rules.spelling import repair

    assert repair("we don't want it and can't keep it", campus).repairs == []


def test_not_so_many_removes_some_not_all(context, campus):
    ((tool, args),) = calls_of(context, "not quite so many benches, thanks")
    assert tool == "remove_assets" and 0 < args.get("count", 0) < max(2, campus.count("bench") + 1)


def test_a_colour_not_understood_is_asked_about_never_added(context):
    with pytest.raises(PlanningError, match="which colour"):
        RulePlanner().plan("paint the bench mauvish", context)


def test_the_nearest_to_the_ego_are_the_ones_removed(context):
    ((_, args),) = calls_of(context, "take away the 2 lamp posts nearest the ego")
    assert args["count"] == 2 and args["near"] == "ego"


def test_its_entrance_is_the_entrance_of_the_place_just_named(context):
    calls = calls_of(context, "three parked cars in a row in lot B, then a parking sign by its entrance")
    assert calls[-1][1]["location"]["target"] == "parking lot B entrance"


def test_what_a_perception_test_is_about_is_not_added(context):
    assert calls_of(context, "we are running a night test of cyclist detection") == [
        ("set_time_of_day", {"time": "night"})
    ]


def test_the_world_named_by_its_own_name_is_no_place_in_it(campus):
    assert find_place(campus, " two people at union ")[0] == "Student Union entrance"
    named_union = campus.model_copy(update={"name": "union"})  # "in town" in a world called town
    assert find_place(named_union, " how many people are in union ") is None


def test_a_speed_for_one_thing_there_keeps_what_it_does_at_that_speed(context):
    ((tool, args),) = calls_of(context, "please change the ego's speed to 7 m/s")
    assert (tool, args) == ("set_behaviour", {"asset": "ego", "behaviour": {"kind": "drive_lane", "lane": "main_eastbound", "speed": 7.0}})
    ((_, args),) = calls_of(context, "hmm, can the ego be a little slower")
    assert args["behaviour"]["speed"] < 5.0 and args["behaviour"]["lane"] == "main_eastbound"
    ((_, args),) = calls_of(context, "the suv should circle at 4 m/s")
    assert args["behaviour"]["kind"] == "circle"  # another behaviour is planned as one


def test_a_new_thing_said_to_face_a_compass_way_is_turned_that_way(session):
    report = session.submit("could you add a bus at the shuttle stop, pointing west")
    assert report.ok, report.error
    bus = next(a for a in session.scene.assets if a.category == "bus")
    assert abs(math.remainder(bus.pose.yaw - math.pi, math.tau)) < 0.05
