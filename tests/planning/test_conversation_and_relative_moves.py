"""What a new user types in the first minutes of a chat: "undo that" and "redo" in words, a new
amount for the last edit ("actually, make that five"), whatever is nearest something, moves
closer to or further from a place, "ahead of it", a question in two parts that one search
answers, and a scene said to be without something ("make sure there are no cars in lot B").
The wording is this file's own, run through a Session with the rule planner on the campus world;
the check's tests hand the session a plan that misreads the request."""

from __future__ import annotations

import itertools
import math

import pytest
from drivetwin.orchestrator.planning.intent import history_request
from drivetwin.orchestrator.session import Session
from drivetwin.tools.base import ToolCall
from misreading import Fixed, add  # this folder is on sys.path (no __init__.py)


def _added(session, campus, category):
    return [a for a in session.scene.assets if a.category == category and campus.asset(a.id) is None]


def _dist(a, point):
    return math.dist((a.pose.x, a.pose.y), point)


def _xy(a):
    return a.pose.x, a.pose.y


# Undo and redo said in words -----------------------------------------------------------------
def test_undo_said_in_words_takes_the_last_change_back(session, campus):
    assert session.submit("put a bench next to the fountain").ok
    report = session.submit("oops, undo that please")
    assert report.ok, report.error
    assert session.scene.assets == campus.assets
    assert "put a bench next to the fountain" in (report.answer or "")


def test_redo_said_in_words_brings_it_back(session, campus):
    session.submit("put a bench next to the fountain")
    after = session.scene.assets
    session.submit("scratch that")
    report = session.submit("redo it, thanks")
    assert report.ok, report.error
    assert session.scene.assets == after


def test_undo_with_nothing_done_changes_nothing_and_says_so(session, campus):
    report = session.submit("revert the last change")
    assert not report.ok
    assert "nothing to undo" in (report.error or "")
    assert session.scene == campus


@pytest.mark.parametrize("words", ["undo the red paint on the suv", "take back the bench and put a bin there",
                                   "cancel the rain and make it sunny"])
def test_a_request_that_says_what_to_change_back_is_no_bare_undo(words):
    assert history_request(words) is None


# A new amount for the last edit ----------------------------------------------------------------
def test_make_that_five_after_three_leaves_five_at_the_same_place(session, campus):
    session.submit("add three cones near the east gate")
    report = session.submit("actually, make that five")
    assert report.ok, report.error
    cones = _added(session, campus, "traffic_cone")
    assert len(cones) == 5
    gate = campus.landmark("east gate").position
    assert all(_dist(c, gate) < 12.0 for c in cones)


def test_fewer_than_before_takes_the_extra_ones_away(session, campus):
    session.submit("put 4 benches by the library")
    report = session.submit("no, make it two instead")
    assert report.ok, report.error
    assert len(_added(session, campus, "bench")) == 2


def test_half_of_them_takes_away_half_of_what_the_last_turn_added(session, campus):
    assert session.submit("put eight cones near the student union").ok
    report = session.submit("too cluttered, lose roughly half of them")
    assert report.ok, report.error
    assert len(_added(session, campus, "traffic_cone")) == 4


def test_clearing_a_place_but_leaving_one_leaves_one_there(session, campus):
    lot = campus.landmark("parking lot B")
    vehicles = [a.id for a in campus.assets if a.category in ("passenger_car", "suv") and _dist(a, lot.position) < 30]
    assert len(vehicles) == 3
    report = session.submit("clear the vehicles out of lot B but leave one of them")
    assert report.ok, report.error
    assert sum(session.scene.asset(i) is not None for i in vehicles) == 1


def test_a_side_of_a_road_said_with_its_kind_abbreviated_is_that_side(session, campus):
    report = session.submit("take away the lamps along the north side of Main St.")
    assert report.ok, report.error
    gone = {a.id for a in campus.assets if a.category == "street_light"} - {a.id for a in session.scene.assets}
    assert gone and all(campus.asset(i).pose.y > 0 for i in gone)
    assert session.scene.count("street_light") == campus.count("street_light") - len(gone) > 0


def test_a_new_amount_of_another_kind_is_not_read_as_the_last_edit(session, campus):
    session.submit("add a bench near the fountain")
    before = session.scene
    report = session.submit("make that two hydrants")
    assert not report.ok
    assert session.scene == before


# Whatever is nearest -----------------------------------------------------------------------------
def test_whatever_is_closest_to_the_ego_is_the_nearest_thing_of_any_kind(session, campus):
    ego = _xy(campus.asset("ego"))
    nearest = min((a for a in campus.assets if a.id != "ego"), key=lambda a: _dist(a, ego))
    report = session.submit("get rid of whatever is closest to the ego")
    assert report.ok, report.error
    assert session.scene.asset(nearest.id) is None
    assert len(session.scene.assets) == len(campus.assets) - 1


def test_the_thing_nearest_a_place_is_moved_by_the_step_said(session, campus):
    stop = campus.landmark("bus stop").position
    nearest = min((a for a in campus.assets if a.id != "ego"), key=lambda a: _dist(a, stop))
    report = session.submit("shift the object nearest the bus stop 3 m north")
    assert report.ok, report.error
    moved = session.scene.asset(nearest.id)
    assert moved.pose.y == pytest.approx(nearest.pose.y + 3.0, abs=0.05)
    assert moved.pose.x == pytest.approx(nearest.pose.x, abs=0.05)


def test_a_destination_that_is_no_place_is_never_a_guessed_move(session, campus):
    report = session.submit("move the bench over to the gym")
    assert not report.ok
    assert session.scene == campus


# Closer to and further from a place ------------------------------------------------------------
def test_further_away_from_a_place_moves_away_from_it(session, campus):
    stop = campus.landmark("bus stop").position
    report = session.submit("shove the trash bin further away from the bus stop")
    assert report.ok, report.error
    assert _dist(session.scene.asset("trash_bin_1"), stop) > _dist(campus.asset("trash_bin_1"), stop) + 1.0


def test_a_bit_closer_is_a_step_people_see_towards_the_place_never_past_halfway(session, campus):
    # Three suites written apart from the planners (full, practice24, practice25) all wanted "a bit closer"
    # to be a move one sees: half the way there, not a metre or two.
    library = campus.landmark("Library entrance").position
    report = session.submit("bring the bench a little closer to the library")
    assert report.ok, report.error
    before, after = campus.asset("bench_1"), session.scene.asset("bench_1")
    gap = _dist(before, library)
    assert 2.0 < gap - _dist(after, library) <= gap / 2 + 0.5


def test_a_plan_that_brings_a_thing_nearer_when_asked_for_further_is_not_applied(campus, registry):
    onto_the_stop = Fixed(ToolCall(tool="place_asset", args={"asset": "trash_bin_1", "location": {
        "relation": "at", "target": "bus stop"}}))
    session = Session(campus, onto_the_stop, registry)
    report = session.submit("the bin needs to be further from the bus stop")
    assert not report.ok
    assert session.scene == campus


# "Ahead of it" ---------------------------------------------------------------------------------
def test_ahead_of_it_is_ahead_of_what_the_last_turn_added(session, campus):
    session.submit("add a truck")
    (truck,) = _added(session, campus, "truck")
    report = session.submit("now a car ahead of it")
    assert report.ok, report.error
    (car,) = _added(session, campus, "passenger_car")
    assert _dist(car, _xy(truck)) < 12.0


def test_ahead_of_it_in_the_same_request_is_ahead_of_the_thing_named_first(session, campus):
    report = session.submit("the ego is lonely: give it a car ahead of it")
    assert report.ok, report.error
    (car,) = _added(session, campus, "passenger_car")
    ego = campus.asset("ego")
    ahead = (car.pose.x - ego.pose.x) * math.cos(ego.pose.yaw) + (car.pose.y - ego.pose.y) * math.sin(ego.pose.yaw)
    assert 0.0 < ahead < 20.0


def test_a_plan_that_drops_a_place_said_as_it_is_not_applied(campus, registry):
    session = Session(campus, Fixed(add("passenger_car")), registry)
    report = session.submit("put one car behind it, the ego I mean")
    assert not report.ok
    assert session.scene == campus


# A question in two parts, one search ---------------------------------------------------------------
def test_how_many_and_where_is_answered_by_one_list(session, campus):
    report = session.submit("how many trees have we got and where")
    assert report.ok, report.error
    assert session.scene == campus
    answer = report.answer or ""
    assert "4" in answer and all(a.id in answer for a in campus.assets if a.category == "tree")


# A scene said to be without something -------------------------------------------------------------
def test_make_sure_there_are_no_cars_in_a_lot_removes_them_and_adds_none(session, campus):
    lot_b = [a.id for a in campus.assets if a.id in ("passenger_car_1", "passenger_car_2", "suv_1")]
    report = session.submit("make sure there are no cars left in lot B")
    assert report.ok, report.error
    assert all(session.scene.asset(i) is None for i in lot_b)
    assert not [a for a in session.scene.assets if campus.asset(a.id) is None]


def test_nothing_parked_at_a_place_takes_the_vehicles_there(session, campus):
    report = session.submit("please ensure nothing is parked in parking lot B")
    assert report.ok, report.error
    assert session.scene.count("passenger_car") == campus.count("passenger_car") - 2
    assert session.scene.count("suv") == campus.count("suv") - 1


# How many in all, every place of a kind, and all but one ------------------------------------------
def test_a_count_in_total_is_what_the_scene_ends_up_with(session, campus):
    report = session.submit("we'd like 6 trees in total")
    assert report.ok, report.error
    assert session.scene.count("tree") == 6


def test_at_every_place_of_a_kind_is_one_at_each_of_them(session, campus):
    report = session.submit("a stop sign at every crosswalk please")
    assert report.ok, report.error
    signs = _added(session, campus, "stop_sign")
    assert len(signs) == 2
    for name in ("west crosswalk", "north crosswalk"):
        assert any(_dist(s, campus.landmark(name).position) < 15.0 for s in signs)


def test_two_at_each_of_two_places_is_four(session, campus):
    report = session.submit("two cones by each of the gates")
    assert report.ok, report.error
    cones = _added(session, campus, "traffic_cone")
    assert len(cones) == 4
    for gate in ("main gate", "east gate"):
        assert sum(_dist(c, campus.landmark(gate).position) < 15.0 for c in cones) == 2


def test_both_of_a_kind_there_are_more_of_is_not_every_one(session, campus):
    session.submit("a bench outside both entrances")
    assert len(_added(session, campus, "bench")) < 3  # never one at each of the six entrances


def test_a_plan_that_puts_things_at_one_of_every_place_is_not_applied(campus, registry):
    one = Fixed(add("stop_sign", location={"relation": "at", "target": "west crosswalk"}))
    session = Session(campus, one, registry)
    report = session.submit("stop signs at each crosswalk")
    assert not report.ok
    assert session.scene == campus


def test_all_but_one_on_a_side_keeps_the_one_of_that_side(session, campus):
    library = campus.landmark("Library entrance").position
    north = [a for a in campus.assets if a.category == "street_light" and a.pose.y > 0]
    kept = min(north, key=lambda a: _dist(a, library))
    report = session.submit("take out the street lights on the north side except the one nearest the library")
    assert report.ok, report.error
    assert session.scene.asset(kept.id) is not None
    assert all(session.scene.asset(a.id) is None for a in north if a.id != kept.id)
    assert session.scene.count("street_light") == campus.count("street_light") - len(north) + 1


# Facing something ---------------------------------------------------------------------------------
def test_so_it_faces_the_road_turns_it_towards_the_road(session, campus):
    report = session.submit("rotate the bench so it faces the road")
    assert report.ok, report.error
    bench = session.scene.asset("bench_1")
    assert math.sin(bench.pose.yaw) == pytest.approx(1.0, abs=0.05)  # Main Street is north of it
    assert _xy(bench) == _xy(campus.asset("bench_1"))


def test_to_face_a_place_turns_it_towards_the_place(session, campus):
    fountain = campus.landmark("fountain").position
    report = session.submit("turn the bench round to face the fountain")
    assert report.ok, report.error
    bench = session.scene.asset("bench_1")
    heading = math.atan2(fountain[1] - bench.pose.y, fountain[0] - bench.pose.x)
    assert abs(math.remainder(heading - bench.pose.yaw, 2 * math.pi)) < 0.1


def test_a_turn_of_a_thing_that_is_not_at_the_place_named_is_not_applied(session, campus):
    report = session.submit("turn the car in lot A to face the library")
    assert not report.ok
    assert session.scene == campus


# Things said to be there that are not -----------------------------------------------------------------
@pytest.mark.parametrize("words", ["put the cones back where they were", "space the cones out more"])
def test_things_said_as_there_that_are_not_are_asked_about_not_added(session, campus, words):
    report = session.submit(words)
    assert not report.ok and report.question is not None
    assert session.scene == campus


# Furthest, and what a new thing does as it goes -----------------------------------------------------
def test_the_one_furthest_from_a_place_is_the_one_taken(session, campus):
    library = campus.landmark("Library entrance").position
    trees = [a for a in campus.assets if a.category == "tree"]
    far = max(trees, key=lambda a: _dist(a, library))
    report = session.submit("remove the tree that's furthest from the library")
    assert report.ok, report.error
    assert session.scene.asset(far.id) is None
    assert session.scene.count("tree") == len(trees) - 1


def test_a_plan_that_takes_the_nearest_when_the_furthest_was_said_is_not_applied(campus, registry):
    library = campus.landmark("Library entrance").position
    near = min((a for a in campus.assets if a.category == "tree"), key=lambda a: _dist(a, library))
    session = Session(campus, Fixed(ToolCall(tool="remove_assets", args={"assets": [near.id]})), registry)
    report = session.submit("get rid of the tree farthest from the library")
    assert not report.ok
    assert session.scene == campus


def test_a_new_car_said_to_brake_is_not_added_standing_still(campus, registry):
    session = Session(campus, Fixed(add("passenger_car", location={"relation": "in_front_of", "target": "ego"})), registry)
    report = session.submit("add a car in front of the ego that brakes suddenly")
    assert not report.ok
    assert session.scene == campus


# Between two things, half of them, both and each side, the start of a lane ---------------------------
def test_between_two_places_is_halfway_between_them(session, campus):
    library, stop = campus.landmark("Library entrance").position, campus.landmark("bus stop").position
    report = session.submit("plant a tree between the library and the bus stop")
    assert report.ok, report.error
    (tree,) = _added(session, campus, "tree")
    middle = ((library[0] + stop[0]) / 2, (library[1] + stop[1]) / 2)
    assert _dist(tree, middle) < min(_dist(tree, library), _dist(tree, stop))


def test_between_two_things_names_no_thing_to_change(session, campus):
    report = session.submit("a bin halfway between the bench and the stop sign please")
    assert report.ok, report.error
    assert session.scene.asset("bench_1") == campus.asset("bench_1")
    assert len(_added(session, campus, "trash_bin")) == 1


def test_a_plan_that_puts_a_thing_at_one_end_of_a_between_is_not_applied(campus, registry):
    at_the_stop = Fixed(add("tree", location={"relation": "at", "target": "bus stop"}))
    session = Session(campus, at_the_stop, registry)
    report = session.submit("a tree in between the library and the bus stop")
    assert not report.ok
    assert session.scene == campus


def test_half_of_a_kind_is_painted_not_all_of_it(session, campus):
    lamps = [a for a in campus.assets if a.category == "street_light"]
    report = session.submit("paint half the street lights red")
    assert report.ok, report.error
    changed = [a for a in session.scene.assets if a.category == "street_light" and a != campus.asset(a.id)]
    assert len(changed) == len(lamps) // 2


def test_a_plan_that_paints_all_when_half_was_said_is_not_applied(campus, registry):
    session = Session(campus, Fixed(ToolCall(tool="set_asset_appearance", args={"category": "street_light", "colour": "red"})),
                      registry)
    report = session.submit("half of the street lights should be red")
    assert not report.ok
    assert session.scene == campus


@pytest.mark.parametrize("words", ["benches at both ends of the bus stop", "a cone on each side of the hydrant",
                                   "a bollard at every corner of the intersection"])
def test_both_or_each_side_is_never_one_thing_added(campus, registry, words):
    session = Session(campus, Fixed(add("bench" if "bench" in words else "traffic_cone")), registry)
    report = session.submit(words)
    assert not report.ok
    assert session.scene == campus


def test_a_thing_put_back_where_there_is_none_is_asked_about(session, campus):
    report = session.submit("put the truck back in lot A")
    assert not report.ok and report.question is not None
    assert session.scene == campus


def test_the_start_of_a_lane_is_near_where_it_begins(session, campus):
    lane = campus.roads.lane("main_westbound")
    report = session.submit("move the ego to the start of main street westbound")
    assert report.ok, report.error
    ego = session.scene.asset("ego")
    assert _dist(ego, lane.centreline[0]) < 15.0


# Referring back over turns ------------------------------------------------------------------------------
def test_them_moved_to_a_place_moves_every_one_of_them(session, campus):
    session.submit("three cones near the library please")
    cones = _added(session, campus, "traffic_cone")
    report = session.submit("now move them to the east gate")
    assert report.ok, report.error
    gate = campus.landmark("east gate").position
    assert all(_dist(session.scene.asset(c.id), gate) < 15.0 for c in cones)


def test_same_again_but_at_another_place(session, campus):
    session.submit("put a bin by the union")
    report = session.submit("same again but by the library")
    assert report.ok, report.error
    bins = _added(session, campus, "trash_bin")
    assert len(bins) == 2
    assert any(_dist(b, campus.landmark("Library entrance").position) < 15.0 for b in bins)


def test_same_again_but_another_kind_goes_where_the_last_ones_went(session, campus):
    session.submit("2 cones at the east gate")
    report = session.submit("same again but bollards")
    assert report.ok, report.error
    bollards = _added(session, campus, "bollard")
    assert len(bollards) == 2
    assert all(_dist(b, campus.landmark("east gate").position) < 15.0 for b in bollards)


@pytest.mark.parametrize(("first", "then", "done"), [
    ("paint the suv yellow", "and the cars too", lambda s, c: all(
        s.asset(i).appearance != c.asset(i).appearance for i in ("passenger_car_1", "passenger_car_2"))),
    ("remove the bench", "oh, and the bin", lambda s, c: s.asset("trash_bin_1") is None),
    ("move the bench 2 m east", "and the bin as well", lambda s, c: s.asset("trash_bin_1").pose.x == pytest.approx(
        c.asset("trash_bin_1").pose.x + 2.0, abs=0.05)),
])
def test_and_the_other_things_too_does_the_last_edit_to_them(session, campus, first, then, done):
    session.submit(first)
    report = session.submit(then)
    assert report.ok, report.error
    assert done(session.scene, campus)


def test_and_a_thing_too_after_an_addition_is_not_read_as_a_repeat_on_existing_ones(session, campus):
    session.submit("add a bench")
    session.submit("and the bin too")
    assert session.scene.asset("trash_bin_1") == campus.asset("trash_bin_1")


def test_walking_to_a_place_is_a_walk_from_where_they_stand(session, campus):
    session.submit("add a pedestrian at the bus stop")
    (walker,) = _added(session, campus, "pedestrian")
    report = session.submit("make him walk to the library")
    assert report.ok, report.error
    now = session.scene.asset(walker.id)
    assert now.behaviour.kind == "follow_path"
    assert now.behaviour.waypoints[0] == pytest.approx([walker.pose.x, walker.pose.y], abs=0.05)
    assert math.dist(now.behaviour.waypoints[-1], campus.landmark("Library entrance").position) < 2.0


def test_the_second_one_is_the_second_thing_the_last_turn_added(session, campus):
    session.submit("add two benches by the fountain")
    benches = _added(session, campus, "bench")
    report = session.submit("paint the second one blue")
    assert report.ok, report.error
    assert session.scene.asset(benches[1].id).appearance != benches[1].appearance
    assert session.scene.asset(benches[0].id) == benches[0]


# Not needed any more, and a little turn --------------------------------------------------------------------
@pytest.mark.parametrize(("words", "gone"), [("there's no need for the bus stop bench", "bench_1"),
                                             ("i dont think we need the stop sign anymore", "stop_sign_1"),
                                             ("the hydrant isn't needed any longer", "fire_hydrant_1")])
def test_a_thing_no_longer_needed_is_taken_away(session, campus, words, gone):
    report = session.submit(words)
    assert report.ok, report.error
    assert session.scene.asset(gone) is None
    assert len(session.scene.assets) == len(campus.assets) - 1


def test_a_little_turn_is_a_small_one_the_way_said(session, campus):
    report = session.submit("could you turn the suv a little to the right")
    assert report.ok, report.error
    turned = math.degrees(math.remainder(session.scene.asset("suv_1").pose.yaw - campus.asset("suv_1").pose.yaw, 2 * math.pi))
    assert -30.0 <= turned < 0.0


def test_more_visible_is_a_colour_that_stands_out(session, campus):
    report = session.submit("the hydrant should be more visible")
    assert report.ok, report.error
    assert session.scene.asset("fire_hydrant_1").appearance != campus.asset("fire_hydrant_1").appearance
    assert session.scene.count("fire_hydrant") == campus.count("fire_hydrant")


# Things that happen later, and things said to move -----------------------------------------------------
def test_setting_off_when_the_ego_approaches_is_never_done_from_the_start(session, campus):
    report = session.submit("the suv pulls out of lot B as the ego approaches")
    assert not report.ok
    assert session.scene.asset("suv_1") == campus.asset("suv_1")


def test_setting_off_with_no_time_said_is_done_now(session, campus):
    report = session.submit("the suv should pull out of its spot")
    assert report.ok, report.error
    assert session.scene.asset("suv_1").behaviour.kind == "drive_lane"


def test_a_slow_truck_is_not_added_parked(campus, registry):
    session = Session(campus, Fixed(add("truck", location={"relation": "in_front_of", "target": "ego"})), registry)
    report = session.submit("a slow truck ahead of the ego please")
    assert not report.ok
    assert session.scene == campus


def test_furthest_a_compass_way_is_the_outermost_that_way_not_the_furthest_from_the_place(session, campus):
    lot_b = [a for a in campus.assets if a.id in ("passenger_car_1", "passenger_car_2", "suv_1")]
    east = max(lot_b, key=lambda a: a.pose.x)
    report = session.submit("paint the car furthest east in lot B red")
    assert report.ok, report.error
    assert [a.id for a in session.scene.assets if a != campus.asset(a.id)] == [east.id]


def test_a_distance_asked_between_two_things_must_name_both(campus, registry):
    wrong_pair = Fixed(ToolCall(tool="measure_distance", args={"a": "stop_sign_1", "b": "ego"}))
    report = Session(campus, wrong_pair, registry).submit("how many metres between the stop sign and the traffic light?")
    assert not report.ok


def test_lining_up_all_the_cars_there_never_adds_new_ones(campus, registry):
    row = Fixed(ToolCall(tool="arrange_assets", args={"categories": ["passenger_car"], "shape": "parking_row",
                                                       "location": {"relation": "at", "target": "parking lot B"}}))
    report = Session(campus, row, registry).submit("line up all the cars in lot B next to each other")
    assert not report.ok


# "And so does the bin", "oops, I meant bins" ---------------------------------------------------------------
@pytest.mark.parametrize(("words", "check"), [
    ("the bench has to go, and so does the bin", lambda s: s.asset("bench_1") is None and s.asset("trash_bin_1") is None),
    ("move the bench 2 m north and so should the bin", lambda s: s.asset("trash_bin_1").pose.y == pytest.approx(-3.5, abs=0.05)),
])
def test_so_does_the_other_thing_does_the_clause_before_to_it(session, campus, words, check):
    report = session.submit(words)
    assert report.ok, report.error
    assert check(session.scene)


def test_i_meant_another_thing_is_never_read_as_adding_it(session, campus):
    session.submit("remove the bench")
    before = session.scene
    report = session.submit("oops, I meant bins")
    assert not report.ok
    assert "undo" in (report.error or "")
    assert session.scene == before


def test_a_compass_way_said_with_away_from_the_road_is_the_way_moved(session, campus):
    report = session.submit("the bin sits on the kerb; nudge it one metre north, away from the road")
    assert report.ok, report.error
    moved, was = session.scene.asset("trash_bin_1"), campus.asset("trash_bin_1")
    assert (moved.pose.x, moved.pose.y) == pytest.approx((was.pose.x, was.pose.y + 1.0), abs=0.05)


def test_things_asked_into_a_layout_are_laid_out_not_piled_on_its_place(session, campus):
    session.submit("arrange the trees in one line along the library front")
    trees = [a for a in session.scene.assets if a.category == "tree"]
    library = campus.landmark("Library entrance").position
    assert len(trees) == campus.count("tree") and all(_dist(t, library) < 15.0 for t in trees)
    assert len({round(t.pose.y, 1) for t in trees}) == 1  # one line, along the library front
    xs = sorted(t.pose.x for t in trees)
    assert min(b - a for a, b in itertools.pairwise(xs)) > 1.0  # each its own spot


# Dozens, and weather that stops ---------------------------------------------------------------------------
@pytest.mark.parametrize(("words", "count"), [("put half a dozen pedestrians at the north crosswalk", 6),
                                              ("two dozen cones by the east gate", 24)])
def test_dozens_said_in_words_are_counted(session, campus, words, count):
    report = session.submit(words)
    assert report.ok, report.error
    kind = "pedestrian" if "pedestrian" in words else "traffic_cone"
    assert len(_added(session, campus, kind)) == count


def test_make_the_rain_stop_clears_it_and_adds_no_stop_sign(session, campus):
    session.submit("make it rain")
    report = session.submit("make the rain stop")
    assert report.ok, report.error
    assert session.scene.environment.weather.kind == "clear"
    assert session.scene.count("stop_sign") == campus.count("stop_sign")


def test_between_a_road_and_a_place_is_between_the_place_and_the_road_nearest_it(session, campus):
    hall = campus.landmark("Engineering Hall entrance").position
    report = session.submit("a tree between Main Street and the Engineering Hall")
    assert report.ok, report.error
    (tree,) = _added(session, campus, "tree")
    assert 0.0 < tree.pose.y < hall[1] and abs(tree.pose.x - hall[0]) < 3.0  # Main Street runs along y = 0


def test_things_on_the_road_ahead_of_the_ego_stay_in_its_lane(session, campus):
    report = session.submit("some debris on the road ahead of the ego")
    assert report.ok, report.error
    rubble = _added(session, campus, "cement_rubble")
    ego = campus.asset("ego")
    assert rubble and all(abs(r.pose.y - ego.pose.y) < 1.0 and r.pose.x > ego.pose.x for r in rubble)
