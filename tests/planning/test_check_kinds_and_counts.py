"""Counting words and kinds, read by planner and check alike: a catalog group said in the singular
after a counting word, counts spelt to ninety-nine, "somewhere to sit" as one new thing; and the
check's view of a plan that adds what the words call existing, moves what they ask for new, sets
no colour for "painted", leaves standing what is "going east", or drives what cannot. The misread
plans are fixed (as the measured planners made them); the wording is this file's own."""

from __future__ import annotations

from drivetwin.orchestrator.planning.request import read_request
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from misreading import Fixed, add, call  # this folder is on sys.path (no __init__.py)


def submit(campus, registry, planner, prompt, *before: str):
    session = Session(campus, planner, registry)
    for earlier in before:
        assert session.submit(earlier).ok
    return session, session.submit(prompt)


def test_a_group_word_in_the_singular_after_a_counting_word_names_the_whole_group():
    vehicles = md.groups_said("get rid of 3 vehicle beside the library")["vehicle"]
    assert {"passenger_car", "suv", "bus"} <= vehicles
    assert "vehicle" in md.groups_said("count any parked vehicle near the gate")
    assert md.groups_said("move the vehicle forward") == {}  # one thing, not a kind
    assert md.groups_said("dim every street light") == {}  # a category's own name


def test_a_removal_of_every_vehicle_of_a_lot_takes_suvs_too(context):
    plan = RulePlanner().plan("clear away each parked vehicle in lot B", context)
    removed = {a for c in plan.calls for a in c.args.get("assets", [])}
    lot_b = {"passenger_car_1", "passenger_car_2", "suv_1"}
    assert removed == lot_b


def test_counts_spelt_past_twenty_are_read_by_planner_and_check(context, campus):
    (arrange,) = RulePlanner().plan("set thirty-four bollards in a line along main street", context).calls
    assert arrange.args["count"] == 34
    assert read_request("forty cones would be plenty", campus).numbers == (40.0,)
    assert read_request("line up twenty-six cones", campus).numbers == (26.0,)  # one number, not 20 and 6


def test_somewhere_to_sit_is_one_new_bench(context, campus):
    (added,) = RulePlanner().plan("we could do with somewhere to sit beside the fountain", context).calls
    assert added.tool == "add_asset" and added.args["category"] == "bench" and added.args["count"] == 1


def test_a_thing_called_existing_is_not_added_anew_beside_a_layout(campus, registry):
    plan = Fixed(add("fire_hydrant"), call("arrange_assets", categories=["bollard"], shape="ring",
                                          location={"relation": "at", "target": "fire_hydrant_1"}))
    session, report = submit(campus, registry, plan, "water is spraying out of the fire hydrant, ring it with bollards")
    assert not report.ok and session.scene.count("fire_hydrant") == campus.count("fire_hydrant")
    assert "already there" in (report.error or "") or report.question is not None


def test_one_thing_asked_for_new_is_not_taken_from_elsewhere_while_another_is_added(campus, registry):
    plan = Fixed(add("tree", location={"relation": "at", "target": "fountain"}),
                 call("place_asset", asset="bench_1", location={"relation": "at", "target": "fountain"}))
    session, report = submit(campus, registry, plan, "plant a tree at the fountain and a bench as well there")
    assert not report.ok and session.scene.asset("bench_1") == campus.asset("bench_1")


def test_painted_asks_for_a_colour_even_when_said_politely(campus, registry):
    session, report = submit(campus, registry, Fixed(call("set_time_of_day", time="daytime")),
                             "would it be possible to have the engineering hall painted green for the open day?")
    assert not report.ok and session.scene.environment == campus.environment


def test_a_thing_going_east_is_not_added_standing_still(campus, registry):
    parked_bus = Fixed(add("bus", location={"relation": "in_lane", "target": "main_eastbound"}))
    session, report = submit(campus, registry, parked_bus, "I need one bus on main street going towards the east")
    assert not report.ok and session.scene.count("bus") == campus.count("bus")
    heading = Fixed(add("truck", location={"relation": "in_lane", "target": "campus_northbound"}))
    assert not submit(campus, registry, heading, "a truck heading north on campus drive")[1].ok
    going = Fixed(add("traffic_cone", location={"relation": "at", "target": "parking lot A"}))
    assert submit(campus, registry, going, "we are going to need a cone at lot A")[1].ok


def test_somewhere_for_someone_to_sit_is_new_too(context):
    (added,) = RulePlanner().plan("somewhere for visitors to sit by the fountain would be lovely", context).calls
    assert added.tool == "add_asset" and added.args["category"] == "bench"


def test_what_cannot_drive_is_not_put_in_a_lane_instead(campus, registry):
    into_lane = Fixed(call("place_asset", asset="trash_bin_1", location={"relation": "in_lane", "target": "main_eastbound"}))
    session, report = submit(campus, registry, into_lane, "let the rubbish bin drive down main street")
    assert not report.ok and session.scene.asset("trash_bin_1") == campus.asset("trash_bin_1")
    assert "cannot drive" in (report.error or "")
    cone = Fixed(add("traffic_cone", location={"relation": "in_lane", "target": "campus_northbound"}))
    assert submit(campus, registry, cone, "pop a cone onto campus drive")[1].ok  # a road's name asks no one to drive
    gate = Fixed(call("arrange_assets", categories=["bollard"], shape="line", location={"relation": "at", "target": "main gate"}))
    blocked = submit(campus, registry, gate, "keep trucks from driving through the main gate: bollards in a line")[1]
    assert "cannot drive" not in (blocked.error or "")  # the trucks drive; the bollards stop them


def test_weather_denied_clears_it_and_is_never_set(campus, registry, context):
    (cleared,) = RulePlanner().plan("we really don't want any snow any more", context).calls
    assert cleared.args == {"kind": "clear"}
    rain = Fixed(call("set_weather", kind="rain", intensity=0.6))
    session, report = submit(campus, registry, rain, "no more of that rain, thanks")
    assert not report.ok and session.scene.environment == campus.environment


def test_a_lettered_place_the_world_lacks_is_named_with_those_it_has(campus, registry):
    row = Fixed(call("arrange_assets", categories=["suv"], count=3, shape="parking_row", location={"relation": "scene_centre"}))
    session, report = submit(campus, registry, row, "three SUVs side by side in lot D for the parking test")
    assert not report.ok and session.scene.count("suv") == campus.count("suv")
    assert "there is no 'lot d'" in (report.error or "") and "lot a, lot b" in (report.error or "")


def test_a_vaguely_counted_grid_is_two_by_two_at_least(context):
    (grid,) = RulePlanner().plan("a few cones in a grid at lot A", context).calls
    assert grid.args["shape"] == "grid" and grid.args["count"] == 4


def test_a_new_thing_said_to_go_near_a_thing_there_is_not_put_far_away(campus, registry):
    session, report = submit(campus, registry, Fixed(add("traffic_cone")), "pop a cone right beside the fire hydrant")
    assert not report.ok and session.scene.count("traffic_cone") == campus.count("traffic_cone")
    beside = Fixed(add("traffic_cone", location={"relation": "next_to", "target": "fire_hydrant_1"}))
    assert submit(campus, registry, beside, "pop a cone right beside the fire hydrant")[1].ok


def test_the_side_of_a_road_limits_a_removal_to_that_side(context, campus, registry):
    (removal,) = RulePlanner().plan("clear the lamp posts from the south side of main street", context).calls
    south = {a.id for a in campus.assets if a.category == "street_light" and a.pose.y < 0}
    assert set(removal.args["assets"]) == south and south
    every = Fixed(call("remove_assets", category="street_light"))
    session, report = submit(campus, registry, every, "lose the street lights along the east side of campus drive")
    assert not report.ok and session.scene.count("street_light") == campus.count("street_light")


def test_more_near_and_most_close_are_nearer_and_nearest(context):
    (search,) = RulePlanner().plan("what bench is the most close to the fountain?", context).calls
    assert search.args.get("nearest_to") == "fountain"


def test_the_sun_gone_down_is_night_and_spinning_round_is_a_half_turn(context):
    calls = RulePlanner().plan("we test once the sun goes down", context).calls
    assert any(c.tool == "set_time_of_day" and c.args["time"] == "night" for c in calls)
    (turn,) = RulePlanner().plan("spin the suv round", context).calls
    assert turn.args["turn_deg"] == 180.0


def test_a_lane_kind_the_world_lacks_is_said_with_the_kinds_it_has(campus, registry):
    bike = Fixed(add("bicycle", location={"relation": "at", "target": "ego"}))
    session, report = submit(campus, registry, bike, "send our car over into the cycle lane")
    assert not report.ok and session.scene.count("bicycle") == campus.count("bicycle")
    assert "there is no 'cycle lane'" in (report.error or "") and "driving" in (report.error or "")


def test_a_place_of_a_kind_is_told_from_the_others_by_the_compass(context):
    (added,) = RulePlanner().plan("drop a bench off at the eastern car park", context).calls
    assert added.args["location"]["target"] == "parking lot B"
    (search,) = RulePlanner().plan("anything standing in the north-west lot?", context).calls
    assert search.args.get("near") == "parking lot A"
    (cone,) = RulePlanner().plan("a cone at the east gate", context).calls
    assert cone.args["location"]["target"] == "east gate"  # a place's own name wins


def test_a_sidewalk_thing_at_a_place_far_from_any_sidewalk_stands_by_the_place(context, campus):
    session = Session(campus, RulePlanner(), context.registry)
    report = session.submit("we need a fire hydrant by the Student Union entrance")
    (hydrant,) = [a for a in session.scene.assets if a.category == "fire_hydrant" and campus.asset(a.id) is None]
    door = campus.landmark("Student Union entrance")
    assert report.ok and door is not None
    assert ((hydrant.pose.x - door.position[0]) ** 2 + (hydrant.pose.y - door.position[1]) ** 2) ** 0.5 < 8.0
