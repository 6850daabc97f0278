"""Closures and rows along lanes, tried in this file's own words on the packaged campus world:
a lane blocked a distance ahead of the ego, a lot entrance or a gate sealed off, a ring round a
thing that keeps its neighbours out, a lane lined on both sides or as a whole, and what the
world says when a fully read request cannot stand where it was asked."""

from __future__ import annotations

import itertools
import math

import pytest
from drivetwin.orchestrator.planning import PlanContext, PlanningError
from drivetwin.orchestrator.planning.hybrid import HybridPlanner
from drivetwin.orchestrator.planning.llm.planner import LlmPlanner
from drivetwin.orchestrator.planning.retrieval import RetrievalPlanner
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.tools import ToolRegistry
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.scene import Scene
from drivetwin.worlds.surface import point_in_polygon
from misreading import Fixed  # this folder is on sys.path (no __init__.py)
from test_check import submit


def added(session, before: Scene, category: str):
    old = {a.id for a in before.assets}
    return [a for a in session.scene.assets if a.category == category and a.id not in old]


def in_junction(scene: Scene, asset) -> bool:
    junction = scene.landmark("main intersection")
    assert junction is not None and junction.polygon is not None
    return point_in_polygon(asset.pose.x, asset.pose.y, junction.polygon)


def lane_of(scene: Scene, x: float, y: float) -> str:
    return min(scene.roads.lanes, key=lambda ln: min(math.dist((x, y), p) for p in ln.centreline)).id


def test_a_lane_blocked_a_distance_ahead_of_the_ego_is_closed_there_and_only_that_lane(session, campus):
    report = session.submit("we need the eastbound lane shut 25 metres in front of our car, use barriers")
    assert report.ok, report.error
    barriers = added(session, campus, "road_barrier")
    assert len(barriers) >= 2
    ego = campus.ego.pose
    assert all(abs(b.pose.x - (ego.x + 25)) < 3 for b in barriers)  # there, not the lane's middle
    assert all(b.pose.y < 0.5 for b in barriers)  # the eastbound half of Main Street only


def test_a_lane_named_alone_is_closed_alone_and_the_road_whole_when_the_road_is_named(session, campus):
    assert session.submit("close off the westbound lane by the east gate").ok
    lane_only = added(session, campus, "road_barrier")
    assert lane_only and all(b.pose.y > 0 for b in lane_only)
    before = session.scene
    assert session.submit("close Main Street just west of the crossroads").ok
    road = added(session, before, "road_barrier")
    assert min(b.pose.y for b in road) < -1 and max(b.pose.y for b in road) > 1


def test_a_row_across_a_path_with_no_count_is_as_many_as_fit(campus, registry):
    tool = registry.get("arrange_assets")
    result = tool.propose(tool.Args(categories=["road_barrier"], shape="line",
                                    location={"relation": "in_front_of", "target": "ego", "distance": 30}), campus)
    ids = result.data["ids"]
    assert 2 <= len(ids) < 5 and "to fit across" in result.text
    with pytest.raises(Exception, match="does not fit"):  # a count asked for is kept, or refused
        tool.propose(tool.Args(categories=["road_barrier"], shape="line", count=6,
                               location={"relation": "in_front_of", "target": "ego", "distance": 30}), campus)


@pytest.mark.parametrize("prompt", ["barricade off the entrance to lot A", "seal the main gate off with cones"])
def test_sealing_off_a_way_in_lays_a_line_across_it(session, campus, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    calls = report.plan.calls
    assert [c.args["shape"] for c in calls] == ["line"]
    where = "parking lot A entrance" if "lot A" in prompt else "main gate"
    mark = campus.landmark(where)
    assert mark is not None
    new = [a for a in session.scene.assets if a.id not in {b.id for b in campus.assets}]
    assert new and all(math.dist((a.pose.x, a.pose.y), mark.position) < 12 for a in new)


def test_fencing_off_a_thing_rings_that_thing_and_leaves_its_neighbours_outside(session, campus):
    report = session.submit("could you fence off the tree by the library with some bollards")
    assert report.ok, report.error
    tree = campus.asset("tree_1")
    bench = campus.asset("bench_1")
    assert tree is not None and bench is not None
    bollards = added(session, campus, "bollard")
    radii = [math.dist((b.pose.x, b.pose.y), (tree.pose.x, tree.pose.y)) for b in bollards]
    assert len(bollards) >= 4 and max(radii) - min(radii) < 0.01
    assert max(radii) < math.dist((bench.pose.x, bench.pose.y), (tree.pose.x, tree.pose.y))


def test_a_road_lined_on_both_sides_gets_a_row_at_each_kerb_inside_the_world(session, campus):
    report = session.submit("near the main gate, cones down both sides of the road please")
    assert report.ok, report.error
    cones = added(session, campus, "traffic_cone")
    lanes = {lane_of(campus, c.pose.x, c.pose.y) for c in cones}
    assert lanes == {"main_eastbound", "main_westbound"}
    assert all(-110 <= c.pose.x <= 110 for c in cones)


def test_one_lane_lined_on_both_edges_keeps_to_that_lane(session, campus):
    report = session.submit("i'd like bollards on each edge of the northbound lane of Campus Drive")
    assert report.ok, report.error
    bollards = added(session, campus, "bollard")
    xs = {round(b.pose.x, 1) for b in bollards}
    assert len(xs) == 2 and all(0 < x < 3.5 for x in xs)  # its left and right edges


def test_a_lane_lined_as_a_whole_is_not_lined_through_the_junction(session, campus):
    report = session.submit("line the eastbound lane with barriers")
    assert report.ok, report.error
    barriers = added(session, campus, "road_barrier")
    assert barriers and not any(in_junction(campus, b) for b in barriers)


def test_a_fully_read_request_the_world_refuses_says_why_and_what_could_stand_there() -> None:
    from drivetwin.worlds.defaults import load_world

    context = PlanContext(scene=load_world("campus"), registry=ToolRegistry.default(plugins=False))
    planner = HybridPlanner(RulePlanner(), LlmPlanner(model="no-such-model"), retrieval=RetrievalPlanner())
    with pytest.raises(PlanningError, match=r"^I could not do it: .*must stand on a road.*bollards can stand on"):
        planner.plan("surround the fountain with barriers", context)


def test_the_check_counts_each_side_and_refuses_walkers_added_standing(campus, registry):
    twelve = [ToolCall(tool="add_asset", args={"category": "bollard", "count": 6, "location": loc})
              for loc in ({"relation": "left_of", "target": "bus stop", "distance": 2.0},
                          {"relation": "right_of", "target": "bus stop", "distance": 2.0})]
    session, report = submit(campus, registry, Fixed(*twelve), "six bollards either side of the bus stop")
    assert report.ok, report.error
    standing = ToolCall(tool="add_asset", args={"category": "pedestrian", "location": {"relation": "at", "target": "fountain"}})
    session, report = submit(campus, registry, Fixed(standing), "someone jogging past the fountain would be nice")
    assert not report.ok and "jogging" in (report.error or "")
    assert session.scene.assets == campus.assets


def test_everything_but_one_thing_keeps_that_thing(session, campus):
    report = session.submit("take everything away from the bus stop but the bench")
    assert report.ok, report.error
    assert session.scene.asset("bench_1") is not None
    assert session.scene.asset("trash_bin_1") is None


def test_one_of_a_group_is_removed_without_the_check_asking_for_all(session, campus):
    report = session.submit("lose one of the cars over in lot B, any will do")
    assert report.ok, report.error
    assert len(session.scene.assets) == len(campus.assets) - 1


def test_a_thing_picked_by_a_superlative_after_it_is_no_unknown_thing(session, campus):
    report = session.submit("we don't need the tree nearest the fountain any more")
    assert report.ok, report.error
    assert session.scene.asset("tree_2") is None and session.scene.asset("tree_3") is not None


def test_a_side_of_a_road_is_its_lane_on_that_side_and_a_side_of_a_lot_is_no_lane(session, campus):
    report = session.submit("add a car on the north side of Main Street")
    assert report.ok, report.error
    assert report.plan.calls[0].args["location"].get("target") == "main_westbound"
    from drivetwin.orchestrator.planning.rules.reading import find_lane

    assert find_lane(campus, "benches along the south side of lot b") is None  # a compass word saying where


def test_a_possessive_before_a_known_place_is_no_unknown_place(campus, registry):
    move = ToolCall(tool="place_asset", args={"asset": "suv_1", "location": {"relation": "at", "target": "JTEKT building entrance"}})
    session, report = submit(campus, registry, Fixed(move), "the visitors are from JTEKT, so the SUV goes at their entrance")
    assert report.ok, report.error
    assert session.scene.asset("suv_1") != campus.asset("suv_1")


def test_a_thing_that_casts_a_shadow_across_the_road_is_no_road_closure(session, campus):
    report = session.submit("that tree by the library throws shade across the road")
    assert session.scene.count("tree") <= campus.count("tree")
    assert not report.ok or all(c.tool != "arrange_assets" for c in report.plan.calls)


@pytest.mark.parametrize(("prompt", "place"), [("could we get some roadworks going by the east gate", "east gate"),
                                               ("make it look like a building site outside the library", "Library entrance")])
def test_roadworks_named_alone_are_cones_and_a_sign_at_the_place(session, campus, prompt, place):
    report = session.submit(prompt)
    assert report.ok, report.error
    mark = campus.landmark(place)
    assert mark is not None
    cones, signs = added(session, campus, "traffic_cone"), added(session, campus, "construction_sign")
    assert len(cones) >= 3 and len(signs) == 1
    assert all(math.dist((a.pose.x, a.pose.y), mark.position) < 15 for a in [*cones, *signs])


def test_roadworks_with_no_place_ask_where(session, campus):
    report = session.submit("the scene needs roadworks")
    assert not report.ok and "where" in (report.error or "")
    assert session.scene.assets == campus.assets


def test_a_place_said_to_feel_empty_is_never_emptied(session, campus):
    report = session.submit("honestly the bus stop looks empty")
    assert all(session.scene.asset(a.id) is not None for a in campus.assets)  # nothing taken away
    assert not report.ok or not any(c.tool == "remove_assets" for c in report.plan.calls)


def test_lamps_that_should_be_working_are_switched_on(session):
    report = session.submit("for tonight's run the street lamps should be working")
    assert report.ok, report.error
    assert session.scene.environment.lighting.street_lights == "on"


@pytest.mark.parametrize("prompt", ["that tree behind the bus stop is rotten and should be felled",
                                    "shift the bench by the bus stop over to the fountain"])
def test_a_thing_picked_out_by_where_it_stands_is_not_moved_there(campus, registry, prompt):
    thing = "tree_1" if "tree" in prompt else "bench_1"
    there = ToolCall(tool="place_asset", args={"asset": thing, "location": {"relation": "behind" if "tree" in prompt else "next_to",
                                                                             "target": "bus stop"}})
    session, report = submit(campus, registry, Fixed(there), prompt)
    said = report.error or (report.question.text if report.question else "")
    assert not report.ok and "not where it should go" in said
    assert session.scene.assets == campus.assets
    # said as where it should go, the same plan is applied
    session, report = submit(campus, registry, Fixed(there), f"put the {'tree' if 'tree' in prompt else 'bench'} by the bus stop")
    assert report.ok, report.error


def test_a_greeting_and_a_sign_off_set_no_time_of_day(session, campus):
    report = session.submit("Good evening! Could we have a bench by the fountain? Many thanks, Ruth.")
    assert report.ok, report.error
    assert [c.tool for c in report.plan.calls] == ["add_asset"]
    assert session.scene.environment == campus.environment


def test_dropping_the_things_there_takes_them_away_and_a_mass_word_points_at_them(session, campus):
    report = session.submit("drop the vegetation")
    assert report.ok, report.error
    assert session.scene.count("tree") == 0
    report = session.submit("drop a bench next to the bus stop")
    assert report.ok, report.error
    assert session.scene.count("bench") == campus.count("bench") + 1


def test_a_spacing_in_feet_is_laid_out_in_metres(session, campus):
    report = session.submit("a line of 4 bollards ten feet apart in lot B")
    assert report.ok, report.error
    xs = sorted((b.pose.x, b.pose.y) for b in added(session, campus, "bollard"))
    gaps = [math.dist(a, b) for a, b in itertools.pairwise(xs)]
    assert len(gaps) == 3 and all(abs(g - 3.05) < 0.1 for g in gaps)


def test_a_side_of_an_area_is_just_inside_that_edge(session, campus):
    report = session.submit("three benches in a line along the western edge of the parking lot B")
    assert report.ok, report.error
    lot = campus.landmark("parking lot B")
    assert lot is not None and lot.polygon is not None
    west = min(x for x, _ in lot.polygon)
    benches = added(session, campus, "bench")
    assert len(benches) == 3 and all(b.pose.x - west < 6 for b in benches)
    assert max(b.pose.y for b in benches) - min(b.pose.y for b in benches) > 1  # running along that edge


def test_a_command_before_a_colon_acts_on_what_follows_it_once(session, campus):
    report = session.submit("Take the parked cars away from lot B: the two sedans and the SUV.")
    assert report.ok, report.error
    assert session.scene.count("passenger_car") == 0 and session.scene.count("suv") == 0
    assert len(session.scene.assets) == len(campus.assets) - 3


def test_a_clause_with_no_verb_ending_in_too_repeats_the_one_before(session, campus):
    report = session.submit("the hydrant must go, and the bench as well")
    assert report.ok, report.error
    assert session.scene.asset("fire_hydrant_1") is None and session.scene.asset("bench_1") is None
    assert session.scene.count("bench") == campus.count("bench") - 1


def test_a_thing_that_should_not_exist_is_removed_and_fewer_of_a_group_is_some_of_it(session, campus):
    report = session.submit("that hydrant should not exist")
    assert report.ok, report.error
    assert session.scene.asset("fire_hydrant_1") is None
    report = session.submit("I'd like fewer vehicles parked in lot B")
    assert report.ok, report.error
    assert 0 < sum(session.scene.count(c) for c in ("passenger_car", "suv")) < 3


def test_moving_a_thing_onto_the_sidewalk_is_a_placement_not_a_manoeuvre(session, campus):
    report = session.submit("please move the hydrant onto the sidewalk by the bus stop")
    assert report.ok, report.error
    hydrant = session.scene.asset("fire_hydrant_1")
    assert hydrant is not None and math.dist((hydrant.pose.x, hydrant.pose.y), (-30.0, -5.5)) < 10


@pytest.mark.parametrize(("prompt", "time"), [("clock to 0545 please", "05:45"), ("run it at 2215 hours", "22:15")])
def test_four_figures_on_the_24_hour_clock_set_the_time(session, prompt, time):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert session.scene.environment.time_of_day == time


def test_an_exposure_value_said_is_set(session):
    report = session.submit("lower the camera exposure to 0.6")
    assert report.ok, report.error
    assert session.scene.environment.lighting.exposure == pytest.approx(0.6)


@pytest.mark.parametrize("said", ["12 m/s", "12 metres per second", "43.2 kilometres an hour"])
def test_a_speed_however_written_is_a_speed_and_never_a_distance(session, campus, said):
    report = session.submit(f"add a car in front of the ego doing {said}")
    assert report.ok, report.error
    car = added(session, campus, "passenger_car")[0]
    assert car.behaviour.kind == "drive_lane" and car.behaviour.speed == pytest.approx(12.0, abs=0.05)
    assert "distance" not in report.plan.calls[0].args["location"]


def test_what_is_left_as_it_is_is_excepted_and_no_moment_in_time(session, campus):
    report = session.submit("paint the bench blue and leave the bin as it is")
    assert report.ok, report.error
    assert session.scene.asset("trash_bin_1") == campus.asset("trash_bin_1")
    bench = session.scene.asset("bench_1")
    assert bench is not None and bench.appearance != campus.asset("bench_1").appearance


def test_a_thing_that_has_to_come_down_is_removed_and_a_spec_placing_it_is_a_move(session, campus):
    report = session.submit("the tree behind the bus stop is dying and needs to come down")
    assert report.ok, report.error
    assert session.scene.asset("tree_1") is None and session.scene.count("tree") == campus.count("tree") - 1
    report = session.submit("the plan puts the hydrant at the west crosswalk, not where it is now")
    assert report.ok, report.error
    hydrant = session.scene.asset("fire_hydrant_1")
    assert hydrant is not None and math.dist((hydrant.pose.x, hydrant.pose.y), (-11.5, 0.0)) < 10


@pytest.mark.parametrize("prompt", ["move fire_hydrant_1 next to stop_sign_1", "put the hydrant beside stop_sign_1"])
def test_an_id_after_a_relation_is_where_the_thing_goes_not_a_second_thing_moved(session, campus, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert session.scene.asset("stop_sign_1") == campus.asset("stop_sign_1")
    hydrant, sign = session.scene.asset("fire_hydrant_1"), campus.asset("stop_sign_1")
    assert hydrant is not None and sign is not None
    assert math.dist((hydrant.pose.x, hydrant.pose.y), (sign.pose.x, sign.pose.y)) < 4
    assert session.scene.count("fire_hydrant") == campus.count("fire_hydrant")


@pytest.mark.parametrize("prompt", ["a bench directly across the road from the bus stop", "put a bench opposite the bus stop"])
def test_across_from_a_place_is_the_far_side_of_the_road(session, campus, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    bench = added(session, campus, "bench")[0]
    assert bench.pose.y > 3.5 and abs(bench.pose.x - (-30.0)) < 3  # the bus stop is south of Main Street


def test_a_things_answers_say_its_lane_speed_and_colour_by_name(session, campus):
    assert session.submit("paint the suv red").ok
    report = session.submit("what lane is the suv in?")
    assert report.ok and report.answer is not None
    assert "suv_1 stands in no lane (parking lot B)" in report.answer
    report = session.submit("tell me about the ego")
    assert report.ok and report.answer is not None
    assert "in lane main_eastbound" in report.answer and "at 5 m/s" in report.answer
    report = session.submit("describe suv_1")
    assert report.ok and report.answer is not None and "colour red" in report.answer


def test_a_vehicle_told_to_follow_a_driving_one_drives_its_lane_behind_it(session, campus):
    report = session.submit("have the SUV tail the ego")
    assert report.ok, report.error
    suv, ego = session.scene.asset("suv_1"), session.scene.asset("ego")
    assert suv is not None and ego is not None and suv.behaviour.kind == "drive_lane"
    assert suv.behaviour.lane == "main_eastbound" and suv.pose.x < ego.pose.x  # behind it, eastbound
    report = session.submit("make the ego follow passenger_car_2")
    assert not report.ok and "parked" in (report.error or "")


def test_stopping_at_a_place_is_a_stop_when_it_gets_there(campus, registry):
    from drivetwin.orchestrator.planning.scenario_reading import ScenarioReader
    from drivetwin.orchestrator.session import Session

    planner = HybridPlanner(RulePlanner(), LlmPlanner(model="no-such-model"), retrieval=RetrievalPlanner(),
                            scenario=ScenarioReader(), respell=False)
    session = Session(campus, planner, registry)
    report = session.submit("the ego should pull up at the north crosswalk")
    assert report.ok, report.error
    assert [c.tool for c in report.plan.calls] == ["add_event"]
    when = report.plan.calls[0].args["when"]
    assert when["kind"] == "reach" and when["place"] == "north crosswalk"
    assert session.scene.asset("ego") == campus.asset("ego")  # nothing moves now


def test_a_line_too_long_to_stand_across_the_road_runs_along_the_path(session, campus):
    report = session.submit("five cones 2 m apart ahead of the ego please")
    assert report.ok, report.error
    cones = added(session, campus, "traffic_cone")
    ys = {round(c.pose.y, 1) for c in cones}
    assert len(cones) == 5 and len(ys) == 1 and all(c.pose.x > campus.ego.pose.x for c in cones)


def test_the_nearest_thing_of_a_kind_is_nearest_the_asker_not_itself(session):
    report = session.submit("where's the closest fire hydrant?")
    assert report.ok, report.error
    assert report.plan.calls[0].args.get("nearest_to") == "ego"
    assert report.answer is not None and "fire_hydrant_1" in report.answer


def test_a_lane_closed_with_no_place_said_is_closed_midway_off_the_junction(session, campus):
    report = session.submit("shut the southbound lane of Campus Drive")
    assert report.ok, report.error
    barriers = added(session, campus, "road_barrier")
    assert barriers and all(-90 < b.pose.y < 90 and not in_junction(campus, b) for b in barriers)


def test_a_walker_who_jaywalks_is_added_jaywalking(session, campus):
    report = session.submit("a kid jaywalks in front of our car")
    assert report.ok, report.error
    walker = added(session, campus, "pedestrian")[0]
    assert walker.behaviour.kind == "jaywalk"


@pytest.mark.parametrize(("said", "turn"), [("30 degrees clockwise", -30.0), ("30 degrees to the right", -30.0),
                                            ("30 degrees anticlockwise", 30.0), ("30 degrees", 30.0)])
def test_a_turn_said_clockwise_or_right_turns_that_way(session, campus, said, turn):
    report = session.submit(f"rotate the hydrant {said}")
    assert report.ok, report.error
    before, after = campus.asset("fire_hydrant_1"), session.scene.asset("fire_hydrant_1")
    assert before is not None and after is not None
    assert math.degrees(math.remainder(after.pose.yaw - before.pose.yaw, math.tau)) == pytest.approx(turn, abs=0.01)


def test_more_of_the_same_at_a_second_place_and_a_comma_list_of_looks(session, campus):
    report = session.submit("put three cones by the main gate and another two by the east gate")
    assert report.ok, report.error
    cones = added(session, campus, "traffic_cone")
    assert sorted(sum(1 for c in cones if (c.pose.x < 0) == west) for west in (True, False)) == [2, 3]
    report = session.submit("colour the bench green, the bin white and the hydrant black")
    assert report.ok, report.error
    looks = {i: session.scene.asset(i).appearance.rgba for i in ("bench_1", "trash_bin_1", "fire_hydrant_1")}
    assert len(set(looks.values())) == 3 and None not in looks.values()


def test_a_new_thing_where_a_removed_one_was_stands_on_its_spot(session, campus):
    report = session.submit("get rid of the bin and put a bench where it used to be")
    assert report.ok, report.error
    bin_ = campus.asset("trash_bin_1")
    bench = next(a for a in added(session, campus, "bench"))
    assert bin_ is not None and math.dist((bench.pose.x, bench.pose.y), (bin_.pose.x, bin_.pose.y)) < 1.5


def test_a_number_is_not_accounted_for_by_a_unit_never_said(campus, registry):
    speed_only = ToolCall(tool="set_behaviour", args={"asset": "ego", "behaviour": {"kind": "drive_lane", "speed": 3.0}})
    session, report = submit(campus, registry, Fixed(speed_only),
                             "the ego should start ten metres further back and roll at three metres a second")
    assert not report.ok and "10" in (report.error or "")  # ten metres is no 3 m read as ten feet
    assert session.scene.asset("ego") == campus.asset("ego")


def test_a_distance_in_centimetres_moves_that_far_and_its_compass_word_is_no_lane(session, campus):
    report = session.submit("shift the hydrant 80 cm south")
    assert report.ok, report.error
    before, after = campus.asset("fire_hydrant_1"), session.scene.asset("fire_hydrant_1")
    assert before is not None and after is not None
    assert after.pose.y == pytest.approx(before.pose.y - 0.8) and after.pose.x == pytest.approx(before.pose.x)


@pytest.mark.parametrize("prompt", ["is anything parked on Campus Drive", "is anybody standing by the fountain"])
def test_a_yes_no_question_about_anything_or_anyone_changes_nothing(session, campus, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert report.plan.calls and all(c.tool == "find_assets" for c in report.plan.calls)
    assert session.scene.assets == campus.assets


def test_everyday_words_for_a_person_add_a_pedestrian_and_a_sidewalks_compass_word_is_no_lane(session, campus):
    report = session.submit("a couple of tourists by the fountain, and a visitor at the bus stop")
    assert report.ok, report.error
    assert session.scene.count("pedestrian") == campus.count("pedestrian") + 3
    report = session.submit("one more commuter on the south sidewalk")
    assert report.ok, report.error
    assert all(c.args.get("location", {}).get("relation") != "in_lane" for c in report.plan.calls)


def test_can_it_disappear_asks_for_it_gone_and_two_things_asked_are_two_calls(session, campus):
    report = session.submit("the bench by the bus stop blocks my shot. could it vanish?")
    assert report.ok, report.error
    assert session.scene.asset("bench_1") is None
    report = session.submit("Two questions: how far is the fountain from the east gate, and is it raining?")
    assert report.ok, report.error
    assert len(report.plan.calls) == 2


def test_too_many_along_a_road_takes_some_never_all(session, campus):
    report = session.submit("there are way too many street lamps along Main Street")
    assert report.ok, report.error
    left = session.scene.count("street_light")
    assert 0 < left < campus.count("street_light")


def test_getting_things_out_of_a_place_takes_them_away_unless_it_says_where_to(session, campus):
    report = session.submit("get the cars out of lot B, but not the SUV")
    assert report.ok, report.error
    assert session.scene.count("passenger_car") == 0 and session.scene.asset("suv_1") == campus.asset("suv_1")


def test_a_crowd_is_several_people_and_a_slalom_is_cones_well_apart_down_a_lane(session, campus):
    report = session.submit("we need a crowd outside the library")
    assert report.ok, report.error
    assert session.scene.count("pedestrian") - campus.count("pedestrian") >= 5
    report = session.submit("lay out a slalom with cones in the westbound lane")
    assert report.ok, report.error
    cones = sorted(c.pose.x for c in added(session, campus, "traffic_cone"))
    assert len(cones) >= 4 and all(b - a >= 4 for a, b in itertools.pairwise(cones))
    assert all(1.0 < c.pose.y < 2.5 for c in added(session, campus, "traffic_cone"))  # down the lane's middle


def test_pointing_a_thing_at_a_place_turns_it_there_and_never_moves_it_there(session, campus):
    report = session.submit("point the bench towards the fountain")
    assert report.ok, report.error
    before, after = campus.asset("bench_1"), session.scene.asset("bench_1")
    assert before is not None and after is not None
    assert (after.pose.x, after.pose.y) == (before.pose.x, before.pose.y) and after.pose.yaw != before.pose.yaw
    fountain = campus.landmark("fountain")
    assert fountain is not None
    towards = math.atan2(fountain.position[1] - after.pose.y, fountain.position[0] - after.pose.x)
    assert abs(math.remainder(after.pose.yaw - towards, math.tau)) < 0.05


def test_a_roads_lanes_say_their_speed_limit(session, campus):
    report = session.submit("what's the speed limit on Campus Drive?")
    assert report.ok and report.answer is not None
    limit = next(ln.speed_limit for ln in campus.roads.lanes if ln.road == "Campus Drive")
    assert f"speed limit {limit:g} m/s" in report.answer


def test_turning_a_thing_into_another_kind_replaces_it_on_its_spot(session, campus):
    report = session.submit("turn the fire hydrant into a bench")
    assert report.ok, report.error
    hydrant = campus.asset("fire_hydrant_1")
    bench = added(session, campus, "bench")
    assert hydrant is not None and session.scene.asset("fire_hydrant_1") is None and len(bench) == 1
    assert math.dist((bench[0].pose.x, bench[0].pose.y), (hydrant.pose.x, hydrant.pose.y)) < 1.5
    report = session.submit("change the time to a foggy morning")
    assert report.ok, report.error
    assert session.scene.environment.weather.kind == "fog"
