"""Closing a road or a lot's driveway (a line across every lane there), a request on a condition
about the scene ("if there's a ..., ..."), a topic said first and pointed back at, things on each
side of a place, a ring said in the passive, and smaller readings: a place the world lacks named
after "along", an exception before the colour, a question opened with "wait", the driver's
"which lane am I in", lamps switched by a bare "on" and a bare weather strength ("fog 0.5"), the
light before sunset, someone walking over a crossing, and filling a place with things. The wording
is this file's own, run through a Session with the rule planner on the campus world."""

from __future__ import annotations

import math

import pytest
from drivetwin.worlds.surface import lane_at


def _added(session, campus, category):
    return [a for a in session.scene.assets if a.category == category and campus.asset(a.id) is None]


def _lanes_covered(scene, assets):
    return {lane.id for a in assets if (lane := lane_at(scene, a.pose.x, a.pose.y)) is not None}


def test_closing_the_road_by_a_building_lines_barriers_across_both_lanes(session, campus):
    report = session.submit("shut the road outside the library")
    assert report.ok, report.error
    barriers = _added(session, campus, "road_barrier")
    assert len(barriers) >= 2
    assert _lanes_covered(session.scene, barriers) == {"main_eastbound", "main_westbound"}
    assert max(a.pose.x for a in barriers) - min(a.pose.x for a in barriers) < 1.0  # one line, across the road


def test_a_closure_east_of_the_junction_stands_past_it_in_that_direction(session, campus):
    report = session.submit("block Main Street east of the crossroads using traffic cones")
    assert report.ok, report.error
    cones = _added(session, campus, "traffic_cone")
    assert cones and all(a.pose.x > 7.0 for a in cones)
    assert _lanes_covered(session.scene, cones) == {"main_eastbound", "main_westbound"}


def test_closing_a_lot_closes_its_driveway_not_the_street(session, campus):
    report = session.submit("close off parking lot A")
    assert report.ok, report.error
    barriers = _added(session, campus, "road_barrier")
    assert len(barriers) >= 2
    assert not _lanes_covered(session.scene, barriers)  # Main Street stays open
    assert all(abs(a.pose.x + 85.0) < 4.0 and 3.5 < a.pose.y < 14.0 for a in barriers)  # between street and lot


def test_traffic_kept_out_is_not_what_the_closure_is_made_of(session, campus):
    report = session.submit("close the lot B driveway to traffic")
    assert report.ok, report.error
    assert len(_added(session, campus, "road_barrier")) >= 2
    assert session.scene.count("passenger_car") == campus.count("passenger_car")


def test_a_line_laid_over_the_street_spans_it(session, campus):
    report = session.submit("lay 4 cones over the street near the Engineering Hall entrance")
    assert report.ok, report.error
    cones = _added(session, campus, "traffic_cone")
    assert len(cones) == 4 and _lanes_covered(session.scene, cones) == {"main_eastbound", "main_westbound"}


def test_a_condition_on_a_thing_that_is_not_there_changes_nothing_and_says_so(session, campus):
    report = session.submit("if there is a truck anywhere, make it white")
    assert report.ok, report.error
    assert session.scene.count("truck") == 0 and session.scene.assets == campus.assets
    assert "0 truck" in (report.answer or "")


def test_a_condition_on_a_thing_that_is_there_edits_that_one(session, campus):
    assert session.submit("add a truck in lot A").ok
    report = session.submit("if there's a truck, make it white")
    assert report.ok, report.error
    trucks = [a for a in session.scene.assets if a.category == "truck"]
    assert len(trucks) == 1 and trucks[0].appearance.rgba[:3] == pytest.approx((0.95, 0.95, 0.95), abs=0.06)


def test_a_hedge_about_room_is_no_condition(session, campus):
    report = session.submit("if there's room, put a bench by the fountain")
    assert report.ok, report.error
    assert session.scene.count("bench") == campus.count("bench") + 1


@pytest.mark.parametrize(("prompt", "moved"), [
    ("the tree which stands near the fountain, shift it 2 m west", "tree_2"),
    ("bench at the bus stop - make it 1 m further east", "bench_1"),
])
def test_a_topic_said_first_is_what_it_points_back_at(session, campus, prompt, moved):
    report = session.submit(prompt)
    assert report.ok, report.error
    changed = [a.id for a in session.scene.assets if campus.asset(a.id) is not None and a.pose != campus.asset(a.id).pose]
    assert changed == [moved]


def test_a_request_that_opens_with_a_verb_is_no_topic(session, campus):
    report = session.submit("could we have the bench sitting at the fountain instead, and paint it red")
    assert report.ok, report.error
    bench = session.scene.asset("bench_1")
    assert bench is not None and bench.pose != campus.asset("bench_1").pose
    assert bench.appearance != campus.asset("bench_1").appearance


def test_each_side_of_a_door_gets_one(session, campus):
    report = session.submit("put a potted tree on either side of the Engineering Hall entrance")
    assert report.ok, report.error
    trees = _added(session, campus, "tree")
    assert len(trees) == 2
    door = session.scene.landmark("Engineering Hall entrance")
    assert door is not None
    left, right = (((a.pose.x - door.position[0]) * -math.sin(door.heading)
                    + (a.pose.y - door.position[1]) * math.cos(door.heading)) for a in trees)
    assert left * right < 0  # one each side


def test_a_ring_said_in_the_passive_surrounds_the_place(session, campus):
    report = session.submit("I'd like the fountain encircled by eight bollards")
    assert report.ok, report.error
    bollards = _added(session, campus, "bollard")
    assert len(bollards) == 8
    cx = sum(a.pose.x for a in bollards) / 8
    cy = sum(a.pose.y for a in bollards) / 8
    assert math.dist((cx, cy), session.scene.landmark("fountain").position) < 1.5


def test_what_a_ring_surrounds_is_its_centre_not_part_of_it(session, campus):
    report = session.submit("encircle the hydrant with five bollards")
    assert report.ok, report.error
    posts = _added(session, campus, "bollard")
    hydrant = session.scene.asset("fire_hydrant_1")
    assert len(posts) == 5 and hydrant is not None and session.scene.count("fire_hydrant") == campus.count("fire_hydrant")
    centre = (sum(a.pose.x for a in posts) / 5, sum(a.pose.y for a in posts) / 5)
    assert math.dist(centre, (hydrant.pose.x, hydrant.pose.y)) < 1.5


def test_what_is_cordoned_off_is_not_laid_in_the_ring(session, campus):
    assert session.submit("dump some rubble at the junction").ok
    rubble = session.scene.count("cement_rubble")
    report = session.submit("rope that rubble off with barriers")
    assert report.ok, report.error
    assert session.scene.count("cement_rubble") == rubble
    assert len(_added(session, campus, "road_barrier")) >= 3


@pytest.mark.parametrize("prompt", [
    "put some benches along the riverside boardwalk",
    "how far is the library from the campus ice rink?",
])
def test_a_place_the_world_lacks_is_refused_by_its_name(session, campus, prompt):
    report = session.submit(prompt)
    assert not report.ok
    assert ("riverside boardwalk" in (report.error or "")) or ("ice rink" in (report.error or ""))
    assert session.scene == campus


def test_an_exception_before_the_colour_keeps_the_colour(session, campus):
    report = session.submit("colour evry car exept the ego green")
    assert report.ok, report.error
    cars = [a for a in session.scene.assets if a.category == "passenger_car"]
    assert cars and all(a.appearance.rgba != campus.asset(a.id).appearance.rgba for a in cars)
    assert session.scene.ego.appearance == campus.ego.appearance


def test_a_question_opened_with_wait_changes_nothing(session, campus):
    report = session.submit("wait how many benchs r there")
    assert report.ok, report.error
    assert session.scene == campus and "bench_1" in (report.answer or "")


def test_the_drivers_lane_is_the_egos(session, campus):
    report = session.submit("what lane are we driving in?")
    assert report.ok, report.error
    assert "main_eastbound" in (report.answer or "") and "campus_northbound" not in (report.answer or "")


def test_lamps_switched_by_a_bare_on_are_not_new_lamps_and_a_bare_strength_counts(session, campus):
    report = session.submit("Run 4: fog 0.5; time 22:00; street lamps on")
    assert report.ok, report.error
    assert session.scene.count("street_light") == campus.count("street_light")
    assert session.scene.environment.lighting.street_lights == "on"
    assert (session.scene.environment.weather.kind, session.scene.environment.weather.intensity) == ("fog", 0.5)


def test_the_light_before_the_sun_sets_is_sunset_not_night(session, campus):
    report = session.submit("we need the last light just before the sun sets")
    assert report.ok, report.error
    hour = int(session.scene.environment.time_of_day.split(":")[0])
    assert 17 <= hour <= 20 and session.scene.environment.weather == campus.environment.weather


def test_someone_walking_over_a_crossing_crosses(session, campus):
    report = session.submit("add a pedestrian running across the west crosswalk")
    assert report.ok, report.error
    walkers = _added(session, campus, "pedestrian")
    assert len(walkers) == 1 and walkers[0].behaviour.kind == "cross_road"


def test_filling_a_place_adds_whatever_the_place_is_called(session, campus):
    report = session.submit("fill the empty corner of lot A with parked cars")
    assert report.ok, report.error
    assert session.scene.count("passenger_car") > campus.count("passenger_car")
