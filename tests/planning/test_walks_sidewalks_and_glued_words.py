"""Walks to a place, sidewalks named by their side, and words run together, tried in this file's
own words on the packaged campus world: a walker added on his way somewhere starts some way off
and walks there, a vehicle heading for a gate drives the lane that leads there, "the north
sidewalk of Main Street" is that sidewalk (not a lane of the road), "lotA" and "nearlotb" are
places, and "that bench" is the one the last turn added."""

from __future__ import annotations

import itertools
import math

import pytest
from drivetwin.orchestrator.planning.registry import make_planner
from drivetwin.orchestrator.planning.rules.spelling import repair
from drivetwin.orchestrator.session import Session
from drivetwin.orchestrator.transaction import TransactionError, execute
from drivetwin.tools import ToolRegistry
from drivetwin.tools.base import ToolCall
from drivetwin.tools.errors import RuleViolation
from drivetwin.worlds.scene import FollowPath, Scene
from drivetwin.worlds.surface import surface_at


def added(session, before: Scene, category: str):
    old = {a.id for a in before.assets}
    return [a for a in session.scene.assets if a.category == category and a.id not in old]


def place(scene: Scene, name: str) -> tuple[float, float]:
    landmark = scene.landmark(name)
    assert landmark is not None
    return landmark.position


# --- the Worker: a walk to a target, a sidewalk as a target ------------------------------------


def test_a_new_walker_going_somewhere_with_no_start_said_starts_some_way_off(campus, registry: ToolRegistry):
    done = execute(registry, campus, [ToolCall(tool="add_asset", args={
        "category": "pedestrian", "behaviour": {"kind": "follow_path", "to": "bus stop"}}),
        ToolCall(tool="add_asset", args={"category": "pedestrian", "behaviour": {"kind": "follow_path", "to": "fountain"}})])
    to_stop, to_fountain = sorted((a for a in done.after.assets if a.category == "pedestrian"), key=lambda a: a.id)
    for walker, goal in ((to_stop, place(campus, "bus stop")), (to_fountain, place(campus, "fountain"))):
        assert isinstance(walker.behaviour, FollowPath)
        assert walker.behaviour.waypoints[0] == pytest.approx((walker.pose.x, walker.pose.y), abs=0.01)
        assert walker.behaviour.waypoints[-1] == pytest.approx(goal, abs=0.01)
        assert 8.0 <= math.dist((walker.pose.x, walker.pose.y), goal) <= 16.0  # some way off, in sight of it
    assert surface_at(campus, to_stop.pose.x, to_stop.pose.y) == "sidewalk"  # along the sidewalk to the stop
    assert to_fountain.pose.y < 40.0  # on the way from Main Street's sidewalk to the fountain on the grass


def test_a_walk_to_a_thing_ends_beside_it_and_one_already_there_is_refused(campus, registry: ToolRegistry):
    done = execute(registry, campus, [ToolCall(tool="add_asset", args={
        "category": "pedestrian", "location": {"relation": "at", "target": "bus stop"},
        "behaviour": {"kind": "follow_path", "to": "bench_1"}})])
    walker = next(a for a in done.after.assets if a.category == "pedestrian")
    bench = campus.asset("bench_1")
    assert bench is not None and isinstance(walker.behaviour, FollowPath)
    end = walker.behaviour.waypoints[-1]
    assert 0.5 < math.dist(end, (bench.pose.x, bench.pose.y)) < 3.0  # beside the bench, not in it
    with pytest.raises(TransactionError, match="already at") as refused:
        execute(registry, done.after, [ToolCall(tool="set_behaviour", args={
            "asset": walker.id, "behaviour": {"kind": "follow_path", "to": f"{walker.pose.x}, {walker.pose.y}"}})])
    assert isinstance(refused.value.error, RuleViolation)


def test_a_sidewalk_is_a_target_by_its_id(campus, registry: ToolRegistry):
    done = execute(registry, campus, [ToolCall(tool="add_asset", args={
        "category": "bench", "location": {"relation": "at", "target": "main_north_east"}})])
    bench = next(a for a in done.after.assets if a.id not in {b.id for b in campus.assets})
    assert bench.pose.x > 9 and bench.pose.y > 3.5 and surface_at(campus, bench.pose.x, bench.pose.y) == "sidewalk"


# --- walks and drives read from the words --------------------------------------------------------


def test_a_walker_added_on_his_way_somewhere_walks_there_from_some_way_off(session, campus):
    assert session.submit("a man walks toward the fountain").ok
    (walker,) = added(session, campus, "pedestrian")
    assert isinstance(walker.behaviour, FollowPath)
    assert walker.behaviour.waypoints[-1] == pytest.approx(place(campus, "fountain"), abs=0.01)
    assert math.dist((walker.pose.x, walker.pose.y), place(campus, "fountain")) > 8  # not standing at it


def test_a_walk_from_one_place_to_another_starts_at_the_first(session, campus):
    assert session.submit("a pedestrian walks from the bus stop to the library entrance").ok
    (walker,) = added(session, campus, "pedestrian")
    assert math.dist((walker.pose.x, walker.pose.y), place(campus, "bus stop")) < 3
    assert isinstance(walker.behaviour, FollowPath)
    assert walker.behaviour.waypoints[-1] == pytest.approx(place(campus, "Library entrance"), abs=0.01)


def test_where_a_walker_goes_is_not_a_thing_to_add_and_then_after_who_is_the_same_walker(session, campus):
    assert session.submit("put a pedestrian at the bus stop who then walks to the bench").ok
    assert not added(session, campus, "bench")
    (walker,) = added(session, campus, "pedestrian")
    assert isinstance(walker.behaviour, FollowPath) and math.dist(walker.behaviour.waypoints[-1], (-26.0, -6.9)) < 3


def test_a_walker_there_told_to_run_somewhere_runs_there_from_where_she_stands(session, campus):
    assert session.submit("add a pedestrian at the fountain").ok
    (walker,) = added(session, campus, "pedestrian")
    report = session.submit("now have her jog over to the hydrant")
    assert report.ok, report.error
    now = session.scene.asset(walker.id)
    assert now is not None and isinstance(now.behaviour, FollowPath)
    assert now.behaviour.speed > 2.0 and math.dist(now.behaviour.waypoints[-1], (16.0, 5.5)) < 3
    assert (now.pose.x, now.pose.y) == (walker.pose.x, walker.pose.y)  # from where she stood, not moved there


def test_a_new_walker_then_told_to_walk_in_the_same_prompt_walks(session, campus):
    assert session.submit("add a pedestrian at the fountain and then make him walk to the east gate").ok
    (walker,) = added(session, campus, "pedestrian")
    assert isinstance(walker.behaviour, FollowPath)
    assert walker.behaviour.waypoints[-1] == pytest.approx(place(campus, "east gate"), abs=0.01)
    assert math.dist((walker.pose.x, walker.pose.y), place(campus, "fountain")) < 3  # still where he was put


def test_a_vehicle_heading_for_a_gate_drives_the_lane_that_leads_there(session, campus):
    assert session.submit("a truck heading for the main gate").ok
    (truck,) = added(session, campus, "truck")
    gate = place(campus, "main gate")
    assert truck.behaviour.kind == "drive_lane" and truck.behaviour.lane == "main_westbound"
    assert 20 < truck.pose.x - gate[0] < 60  # some way east of the gate, driving west towards it
    assert session.submit("the suv drives to the main gate").ok
    suv = session.scene.asset("suv_1")
    assert suv is not None and suv.behaviour.kind == "drive_lane" and suv.behaviour.lane == "main_westbound"


# --- sidewalks named by their side -------------------------------------------------------------


def test_the_north_sidewalk_of_main_street_is_that_sidewalk_not_a_lane(session, campus):
    assert session.submit("put a pedestrian on the north sidewalk of main street").ok
    (walker,) = added(session, campus, "pedestrian")
    assert walker.pose.y > 3.5 and surface_at(campus, walker.pose.x, walker.pose.y) == "sidewalk"


def test_a_sidewalk_on_a_side_of_campus_drive_and_a_bench_on_a_side_of_main_street(session, campus):
    assert session.submit("put a hydrant on the sidewalk on the west side of campus drive").ok
    (hydrant,) = [a for a in added(session, campus, "fire_hydrant")]
    assert hydrant.pose.x < -3.5 and abs(hydrant.pose.x + 5.5) < 1.5  # Campus Drive's west sidewalk
    before = session.scene
    assert session.submit("add a bench on the south side of main street").ok
    (bench,) = added(session, before, "bench")
    assert bench.pose.y < -3.5 and surface_at(campus, bench.pose.x, bench.pose.y) == "sidewalk"


def test_a_cone_on_a_side_of_the_road_still_goes_in_that_sides_lane(session, campus):
    assert session.submit("put a cone on the north side of main street").ok
    (cone,) = added(session, campus, "traffic_cone")
    assert 0 < cone.pose.y < 3.5  # the westbound lane, the north half of the road


def test_a_thing_moved_to_the_north_sidewalk_goes_across_from_where_it_stood(session, campus):
    assert session.submit("move the bench to the north sidewalk").ok
    bench = session.scene.asset("bench_1")
    assert bench is not None and bench.pose.y > 3.5 and abs(bench.pose.x - (-26.0)) < 3


# --- words run together, console commands, and "that" one ---------------------------------------


@pytest.mark.parametrize(("said", "read"), [
    ("add 2 benchs lotA", "add 2 benchs lot a"),
    ("/find suv nearlotb", "find suv near lot b"),
    ("put a cone atthe busstop", "put a cone at the bus stop"),
    ("conesnear the eastgate", "cones near the east gate"),
    ("car2 drive westbond main st", "car 2 drive westbound Main Street"),  # a slip, not "west bond"
])
def test_words_run_together_are_read_apart(campus, said: str, read: str):
    assert repair(said, campus).text == read


def test_glued_places_and_a_console_command_are_done_as_meant(session, campus):
    assert session.submit("add 2 benchs lotA").ok
    benches = added(session, campus, "bench")
    lot = campus.landmark("parking lot A")
    assert len(benches) == 2 and lot is not None and all(math.dist((b.pose.x, b.pose.y), lot.position) < 6 for b in benches)
    before = session.scene
    report = session.submit("/find suv nearlotb")
    assert report.ok and report.answer is not None and "suv_1" in report.answer
    assert session.scene == before


def test_that_bench_is_the_one_the_last_turn_added(session, campus):
    assert session.submit("Add a bench by the fountain.").ok
    (bench,) = added(session, campus, "bench")
    before = session.scene
    assert session.submit("now add a rubbish bin next to that bench").ok
    (bin_,) = added(session, before, "trash_bin")
    assert math.dist((bin_.pose.x, bin_.pose.y), (bench.pose.x, bench.pose.y)) < 4


def test_children_and_kids_are_people(session, campus):
    assert session.submit("add three kids at the bus stop").ok
    assert len(added(session, campus, "pedestrian")) == 3
    assert session.submit("remove the children").ok
    assert session.scene.count("pedestrian") == 0


def test_a_warning_that_children_cross_is_a_pedestrian_sign(session, campus):
    assert session.submit("drivers coming up to the west crosswalk need some warning that children cross there").ok
    assert added(session, campus, "pedestrian_sign") and not added(session, campus, "construction_sign")
    assert not added(session, campus, "pedestrian")


def test_a_row_of_several_and_one_thing_beside_it_is_the_row_and_the_one(session, campus):
    report = session.submit("put a construction sign and six cones along the westbound lane by the JTEKT drop-off")
    assert report.ok, report.error
    assert len(added(session, campus, "traffic_cone")) == 6 and len(added(session, campus, "construction_sign")) == 1
    before = session.scene
    report = session.submit("put three cones in a row at the lot a entrance and a road work sign next to them")
    assert report.ok, report.error  # the sign beside the row is not "scattering" it
    assert len(added(session, before, "traffic_cone")) == 3 and len(added(session, before, "construction_sign")) == 1


def test_a_thing_named_with_its_number_run_on_is_that_thing_and_only_if_it_is_there(session, campus):
    assert repair("car2 drive westbound", campus).text == "car 2 drive westbound"
    assert repair("paint bench2 red", campus).text == "paint bench2 red"  # there is no bench 2: not bench_1
    assert session.submit("car2 drive westbond main st").ok
    car = session.scene.asset("passenger_car_2")
    assert car is not None and car.behaviour.kind == "drive_lane" and car.behaviour.lane == "main_westbound"


def test_driving_the_other_way_is_the_roads_other_lane_not_a_parked_u_turn(session, campus):
    assert session.submit("the ego should be going the other way down main street").ok
    ego = session.scene.ego
    assert ego.behaviour.kind == "drive_lane" and ego.behaviour.lane == "main_westbound"
    assert session.submit("turn the bench the other way").ok  # a thing that does not drive is turned
    bench = session.scene.asset("bench_1")
    assert bench is not None and abs(math.remainder(bench.pose.yaw - (campus.asset("bench_1").pose.yaw + math.pi), 2 * math.pi)) < 0.01


def test_the_temporary_traffic_control_is_the_work_zone_not_the_traffic(session, campus):
    assert session.submit("put a construction sign and six cones along the westbound lane by the JTEKT drop-off").ok
    report = session.submit("remove the temporary traffic control")
    assert report.ok, report.error
    assert session.scene.count("traffic_cone") == 0 and session.scene.count("construction_sign") == 0
    assert session.scene.count("passenger_car") == campus.count("passenger_car")


def test_slowing_a_car_down_for_where_children_walk_adds_no_children(session, campus):
    report = session.submit("slow our car down, it's going far too fast for somewhere children walk")
    assert report.ok, report.error
    assert session.scene.count("pedestrian") == campus.count("pedestrian")
    assert session.scene.ego.behaviour.kind == "drive_lane" and session.scene.ego.behaviour.speed < campus.ego.behaviour.speed


def test_setting_a_parked_car_going_drives_it_and_that_said_last_is_the_last_thing_added(session, campus):
    assert session.submit("get the suv moving").ok
    suv = session.scene.asset("suv_1")
    assert suv is not None and suv.behaviour.kind == "drive_lane"
    assert session.submit("add a delivery truck at the JTEKT entrance").ok
    assert session.submit("actually get rid of that").ok
    assert session.scene.count("truck") == 0 and session.scene.asset("suv_1") is not None


def test_a_place_said_to_look_empty_is_not_emptied_and_the_next_clause_fills_it(session, campus):
    report = session.submit("lot A looks empty in the renders. fix with 3 parked cars")
    assert report.ok, report.error
    lot = campus.landmark("parking lot A")
    assert lot is not None and lot.polygon is not None
    cars = added(session, campus, "passenger_car")
    assert len(cars) == 3 and all(c.pose.x < -60 and c.pose.y > 10 for c in cars)
    assert all(session.scene.asset(a.id) is not None for a in campus.assets)  # nothing taken away


def test_both_of_a_kind_written_in_the_plural_are_both(session, campus):
    assert session.submit("delte both trafic lights").ok
    assert session.scene.count("traffic_light") == 0


@pytest.mark.parametrize(("said", "read"), [
    ("witch lane is the suv in", "which lane is the suv in"),
    ("make the ego break at ten seconds", "make the ego brake at 10 seconds"),
    ("the car breaks hard", "the car brakes hard"),
    ("the car should break down", "the car should break down"),  # a breakdown is not a brake
])
def test_words_that_sound_alike_are_the_ones_meant(campus, said: str, read: str):
    assert repair(said, campus).text == read


def test_a_kid_running_out_into_the_road_jaywalks(session, campus):
    assert session.submit("a kid runs out into the road").ok
    (kid,) = added(session, campus, "pedestrian")
    assert kid.behaviour.kind == "jaywalk"


def test_two_things_trade_places_each_keeping_its_heading(session, campus):
    bench, bin_ = campus.asset("bench_1"), campus.asset("trash_bin_1")
    assert bench is not None and bin_ is not None
    report = session.submit("swap the bench and the bin around")
    assert report.ok, report.error
    assert session.scene.count("bench") == 1 and session.scene.count("trash_bin") == 1  # no ring of new ones
    now_bench, now_bin = session.scene.asset("bench_1"), session.scene.asset("trash_bin_1")
    assert now_bench is not None and now_bin is not None
    assert math.dist((now_bench.pose.x, now_bench.pose.y), (bin_.pose.x, bin_.pose.y)) < 0.1
    assert math.dist((now_bin.pose.x, now_bin.pose.y), (bench.pose.x, bench.pose.y)) < 0.1
    assert now_bench.pose.yaw == pytest.approx(bench.pose.yaw, abs=0.01)
    assert session.submit("switch the street lights on").ok  # a switch of a setting is no trade
    assert session.scene.environment.lighting.street_lights == "on"


def test_closer_to_the_road_stops_at_the_kerb(session, campus):
    assert session.submit("push the bin closer to the road").ok
    moved = session.scene.asset("trash_bin_1")
    assert moved is not None and -5.0 < moved.pose.y < -3.5  # nearer the road, still off it
    assert surface_at(campus, moved.pose.x, moved.pose.y) != "lane"


def test_every_thing_a_turn_names_is_turned_each_its_own_way_round(session, campus):
    report = session.submit("turn the cars in lot B to face south")
    assert report.ok, report.error
    for car in ("passenger_car_1", "passenger_car_2", "suv_1"):
        asset = session.scene.asset(car)
        assert asset is not None and math.sin(asset.pose.yaw) == pytest.approx(-1.0, abs=0.01)


# --- questions about kinds of place and lanes --------------------------------------------------


def test_a_kind_of_place_near_another_is_looked_up_among_that_kind(session, campus):
    for asked in ("is there a crossing near the library?", "which crosswalk is closest to the library?",
                  "where should pedestrians cross near the library?"):
        report = session.submit(asked)
        assert report.ok and report.answer is not None, (asked, report.error)
        assert report.answer.startswith("nearest landmark to Library entrance: west crosswalk"), (asked, report.answer)
    report = session.submit("where are the crosswalks?")
    assert report.answer is not None and "west crosswalk" in report.answer and "north crosswalk" in report.answer
    assert session.scene == campus


def test_anything_occupying_a_lane_is_a_search_of_what_stands_on_lanes(session, campus):
    report = session.submit("is anything occupying a travel lane at the moment?")
    assert report.ok and report.plan is not None
    assert [(c.tool, c.args.get("on_lane")) for c in report.plan.calls] == [("find_assets", True)]


def test_the_sun_coming_up_or_going_down_is_sunrise_or_sunset(session, campus):
    assert session.submit("i want to test the camera when the sun is just coming up").ok
    assert session.scene.environment.time_of_day == "sunrise" or session.scene.environment.time_of_day < "08:00"
    assert session.submit("now the sun is just going down").ok
    assert session.scene.environment.time_of_day > "17:00"


def test_where_another_thing_is_or_was(session, campus):
    assert session.submit("put the bus where the suv is now").ok
    (bus,) = added(session, campus, "bus")
    suv = campus.asset("suv_1")
    assert suv is not None and math.dist((bus.pose.x, bus.pose.y), (suv.pose.x, suv.pose.y)) < 8
    before = session.scene
    assert session.submit("remove the bench and put a tree where the bench was").ok
    (tree,) = added(session, before, "tree")
    assert math.dist((tree.pose.x, tree.pose.y), (-26.0, -6.9)) < 0.5


def test_a_vehicle_across_the_road_parks_in_the_far_lane_and_a_bench_on_the_far_sidewalk(session, campus):
    assert session.submit("there should be a truck parked on the far side of the road from the bus stop").ok
    (truck,) = added(session, campus, "truck")
    assert 0 < truck.pose.y < 3.5  # the far (westbound) lane, not the far sidewalk
    before = session.scene
    assert session.submit("put a bench across the road from the bus stop").ok
    (bench,) = added(session, before, "bench")
    assert bench.pose.y > 3.5


def test_who_asks_about_people(session, campus):
    assert session.submit("add two pedestrians by the fountain").ok
    report = session.submit("who is standing near the fountain?")
    assert report.answer is not None and "pedestrian" in report.answer and "tree" not in report.answer


def test_leaving_bikes_somewhere_is_parking_them_not_riding_off(session, campus):
    report = session.submit("I need a place for cyclists to leave their bikes near the union")
    assert report.ok, report.error
    bikes = added(session, campus, "bicycle")
    assert bikes and all(b.behaviour.kind == "parked" for b in bikes)


# --- statements, polite requests and places not meant --------------------------------------------


def test_a_polite_request_asked_as_a_question_is_done_whole(session, campus):
    report = session.submit("Could you put the fire hydrant beside the stop sign, please, and the rubbish bin beside the bench? Thank you.")
    assert report.ok, report.error
    hydrant, bin_ = session.scene.asset("fire_hydrant_1"), session.scene.asset("trash_bin_1")
    assert hydrant is not None and math.dist((hydrant.pose.x, hydrant.pose.y), (-13.5, -5.5)) < 4
    assert bin_ is not None and math.dist((bin_.pose.x, bin_.pose.y), (-26.0, -6.9)) < 4


def test_how_things_go_for_people_adds_no_people_and_it_is_the_one_thing_named(session, campus):
    report = session.submit("Would you be so kind as to put the rubbish bin somewhere near the Student Union? "
                            "People there must have nowhere to throw their wrappers.")
    assert report.ok, report.error
    assert session.scene.count("pedestrian") == 0
    report = session.submit("Cars keep getting hidden behind that wheelie bin so the kids can't see them coming. Can you get rid of it?")
    assert report.ok, report.error
    assert session.scene.count("trash_bin") == 0 and session.scene.count("passenger_car") == campus.count("passenger_car")
    assert not session.submit("kids can't see the cars").ok  # how it is for them: never more of them
    assert session.scene.count("pedestrian") == 0


def test_a_place_said_not_to_be_meant_is_not_where_it_goes(session, campus):
    report = session.submit("People coming out of Engineering Hall need a bench right outside the door, not way over by the bus stop.")
    assert report.ok, report.error
    (bench,) = added(session, campus, "bench")
    assert math.dist((bench.pose.x, bench.pose.y), place(campus, "Engineering Hall entrance")) < 5


def test_asking_to_be_told_a_distance_or_the_conditions_changes_nothing(session, campus):
    report = session.submit("Please inform me at what distance the suv is standing from the ego.")
    assert report.ok and report.answer is not None and "m" in report.answer
    report = session.submit("sanity check. environment?")
    assert report.answer is not None and "weather" in report.answer
    assert session.scene == campus


# --- sides of roads and places as a scope, times into the drive, reasons first -------------------


def test_things_west_of_a_road_are_those_only(session, campus):
    assert session.submit("remove the lamps west of campus drive").ok
    gone = {a.id for a in campus.assets} - {a.id for a in session.scene.assets}
    assert gone == {f"street_light_{n}" for n in range(1, 7)}  # x < 0 only
    assert all(a.pose.x > 0 for a in session.scene.assets if a.category == "street_light")


def test_the_north_side_east_of_the_crossroads_is_both_at_once(session, campus):
    report = session.submit("decommission the luminaires on the north side of Main Street east of the crossroads")
    assert report.ok, report.error
    gone = {a.id for a in campus.assets} - {a.id for a in session.scene.assets}
    assert gone == {"street_light_7", "street_light_9", "street_light_11"}


def test_a_time_into_the_drive_and_a_reason_said_first_make_a_timed_stop(campus, registry, tmp_path):
    session = Session(campus, make_planner("hybrid"), registry, journal_path=tmp_path / "journal.jsonl")  # the embedded model, for real
    report = session.submit("My learner needs to practise an emergency stop, so have the ego brake hard about ten seconds into the drive.")
    assert report.ok and report.plan is not None, report.error
    (call,) = report.plan.calls  # the ego's stop at 10 s, and no stop sign
    assert call.tool == "add_manoeuvre" and call.args.get("actor") == "ego" and call.args.get("at_time") == 10.0


def test_the_case_a_test_is_for_is_not_a_request(session, campus):
    assert session.submit("add a child standing at the bus stop").ok
    report = session.submit("I want to see what happens if a child runs out in front of our car. Make that child dart across the road.")
    assert report.ok, report.error
    assert session.scene.count("pedestrian") == 1 and session.scene.asset("pedestrian_1").behaviour.kind == "jaywalk"


def test_a_thing_that_should_be_driving_is_set_driving_and_a_count_in_pieces_is_a_count(session, campus):
    report = session.submit("For the tracking shot the SUV needs to be driving down Main Street, heading west.")
    assert report.ok, report.error
    suv = session.scene.asset("suv_1")
    assert suv is not None and suv.behaviour.kind == "drive_lane" and suv.behaviour.lane == "main_westbound"
    before = session.scene
    report = session.submit("We wish the cones standing in one row along the side of the westbound lane, beginning from the east gate, ten pieces.")
    assert report.ok, report.error
    assert len(added(session, before, "traffic_cone")) == 10


def test_a_bare_thing_and_how_it_is_then_what_it_needs(session, campus):
    report = session.submit("bin's in a dumb spot. needs to be by the library door")
    assert report.ok, report.error
    bin_ = session.scene.asset("trash_bin_1")
    assert bin_ is not None and math.dist((bin_.pose.x, bin_.pose.y), place(campus, "Library entrance")) < 5
    assert session.scene.count("trash_bin") == 1


def test_the_new_one_is_the_one_just_added_and_the_old_one_is_left(session, campus):
    assert session.submit("add a fire hydrant by the bench").ok
    (new,) = added(session, campus, "fire_hydrant")
    report = session.submit("Please colour the new fire hydrant yellow, and leave the old one as it is.")
    assert report.ok, report.error
    assert session.scene.count("fire_hydrant") == 2
    assert session.scene.asset(new.id).appearance.rgba is not None
    assert session.scene.asset("fire_hydrant_1").appearance.rgba is None


def test_a_building_keeps_its_look_and_a_reason_after_so_adds_no_one(session, campus):
    report = session.submit("paint the library walls something brighter so partially sighted visitors can find it")
    assert not report.ok and "buildings" in (report.error or "")
    assert session.scene == campus


def test_a_straight_line_along_a_side_past_a_place_runs_along_that_sidewalk(session, campus):
    report = session.submit("plant 4 trees in a straight line along the north side of main st, east of the JTEKT building")
    assert report.ok, report.error
    trees = added(session, campus, "tree")
    assert len(trees) == 4 and all(surface_at(campus, t.pose.x, t.pose.y) == "sidewalk" for t in trees)
    assert all(t.pose.x > 37.5 for t in trees)  # east of the JTEKT entrance


def test_nowhere_to_sit_that_people_keep_mentioning_is_a_bench(session, campus):
    report = session.submit("people keep saying there's nowhere to sit outside the student union")
    assert report.ok, report.error
    assert len(added(session, campus, "bench")) == 1 and not added(session, campus, "pedestrian")


def test_how_traffic_is_then_what_the_ego_should_do_is_only_the_ego(session, campus):
    report = session.submit("Traffic on Main Street is crawling this morning; the ego should be down to about two metres a second.")
    assert report.ok, report.error
    assert all(session.scene.asset(a.id) == a for a in campus.assets)  # the parked cars stay where they are
    assert session.scene.ego.behaviour.speed == pytest.approx(2.0)


def test_back_from_the_kerb_is_away_from_the_road_and_a_roof_is_no_place(session, campus):
    assert session.submit("push the bin back from the kerb a little").ok
    moved = session.scene.asset("trash_bin_1")
    assert moved is not None and moved.pose.y < -5.5 - 0.5  # south, away from Main Street
    assert not session.submit("stick the bench up on the library roof").ok


def test_how_many_with_nothing_named_counts_what_the_last_turn_made(session, campus):
    assert session.submit("add three benches along the north side of lot A").ok
    report = session.submit("how many are there now?")
    assert report.answer is not None and report.answer.startswith("4 bench")


def test_a_line_every_few_metres_from_one_thing_to_another(session, campus):
    report = session.submit("cones every 3 m from the ego to the crossroads")
    assert report.ok, report.error
    cones = sorted(added(session, campus, "traffic_cone"), key=lambda c: c.pose.x)
    assert len(cones) >= 15 and cones[0].pose.x > -60 and cones[-1].pose.x < 0  # between the two, not at either
    assert all(abs(b.pose.x - a.pose.x - 3.0) < 0.5 for a, b in itertools.pairwise(cones))


def test_a_cone_every_few_metres_six_of_them_is_a_spaced_line(session, campus):
    report = session.submit("put a cone every 5 m ahead of the ego, six of them")
    assert report.ok, report.error
    cones = sorted(added(session, campus, "traffic_cone"), key=lambda c: c.pose.x)
    assert len(cones) == 6 and all(abs(b.pose.x - a.pose.x - 5.0) < 0.5 for a, b in itertools.pairwise(cones))


def test_a_grid_said_in_rows_of_so_many(session, campus):
    report = session.submit("a grid of cones, 3 rows of 4, in lot B")
    assert report.ok, report.error
    cones = added(session, campus, "traffic_cone")
    assert len(cones) == 12  # three rows of four, whichever way the lot runs
    assert sorted([len({round(c.pose.x, 1) for c in cones}), len({round(c.pose.y, 1) for c in cones})]) == [3, 4]


def test_a_word_found_only_inflected_is_no_slip(campus):
    assert repair("scatter some rubble on the westbound lane", campus).text == "scatter some rubble on the westbound lane"


# --- wishes, reasons and polite forms -------------------------------------------------------------


def test_a_wish_for_a_thing_there_changes_it_and_a_reason_after_so_that_adds_nothing(session, campus):
    report = session.submit("As a test designer I want passenger_car_1 put in the westbound lane of Main Street so that it blocks oncoming traffic.")
    assert report.ok, report.error
    car = session.scene.asset("passenger_car_1")
    assert car is not None and 0 < car.pose.y < 3.5 and session.scene.count("passenger_car") == campus.count("passenger_car")
    assert session.submit("I want the bench painted wooden").ok
    assert session.scene.count("bench") == 1 and session.scene.asset("bench_1").appearance.material == "wood"
    assert session.submit("I want the bench gone").ok and session.scene.count("bench") == 0


def test_what_should_stay_is_spared(session, campus):
    report = session.submit("Please remove both the cars from parking lot B only, the SUV should stay itself.")
    assert report.ok, report.error
    assert session.scene.asset("suv_1") is not None and session.scene.count("passenger_car") == 0


def test_a_lot_wanted_emptied_is_emptied(session, campus):
    report = session.submit("As a QA lead I want lot B emptied of vehicles so that the parking test starts from a blank lot.")
    assert report.ok, report.error
    assert session.scene.asset("suv_1") is None and session.scene.count("passenger_car") == 0


def test_a_polite_wrapped_request_and_the_thing_as_well_are_both_done(session, campus):
    report = session.submit("Would it be possible to take out the fire hydrant, and the stop sign as well?")
    assert report.ok, report.error
    assert session.scene.count("fire_hydrant") == 0 and session.scene.count("stop_sign") == 0


def test_a_time_said_rather_than_another_is_that_time(session, campus):
    assert session.submit("make it night").ok
    report = session.submit("Actually, would you mind making it a bit earlier? Dusk rather than pitch dark.")
    assert report.ok, report.error
    assert session.scene.environment.time_of_day not in ("night", "22:00")


def test_a_stop_the_ego_has_to_make_is_no_stop_sign(session, campus):
    session.submit("I need the ego to have to stop for someone walking out in front of it.")
    assert session.scene.count("stop_sign") == campus.count("stop_sign")


def test_a_slip_that_drops_a_letter_is_still_repaired_and_one_every_step_is_no_count(session, campus):
    assert repair("remov the bench", campus).text == "remove the bench"  # "removed" is a word; "remov" is a slip
    report = session.submit("put a barrier every 10 m along main street")
    assert report.ok, report.error
    assert len(added(session, campus, "road_barrier")) > 1
