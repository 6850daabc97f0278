"""Readings worded here, none from a suite, of the kinds practice35's wrong edits showed: lamps
said not to work, a small turn, a place cleared a little, a thing asked to fly, a brake misspelt
after a modal, traffic coming the other way, a count typed as "tree", a short word with an ending
that is a slip, visibility down to nothing, a place said of an id, the kind asked after "which",
people who lack a seat, and a thing moved off the road with no place said."""

from __future__ import annotations

import math

from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.worlds.surface import surface_at
from misreading import ruled  # this folder is on sys.path (no __init__.py)


def _of(scene, category: str) -> list:
    return [a for a in scene.assets if a.category == category]


def test_lamps_said_not_to_work_are_off_unless_switched_on(campus, registry):
    assert ruled(campus, registry, "the street lamps won't work tonight").scene.environment.lighting.street_lights == "off"
    said = "the street lights are not on yet, switch them on"
    assert ruled(campus, registry, said).scene.environment.lighting.street_lights == "on"


def test_a_touch_is_a_small_turn_and_a_place_cleared_a_bit_keeps_some(campus, registry):
    suv = ruled(campus, registry, "rotate the suv a touch to the left").scene.asset("suv_1")
    turned = math.degrees((suv.pose.yaw - campus.asset("suv_1").pose.yaw + math.pi) % (2 * math.pi) - math.pi)
    assert 5.0 <= abs(turned) <= 30.0
    left = [a for a in ruled(campus, registry, "clear lot B a bit").scene.assets if a.category in ("passenger_car", "suv")]
    assert len(left) == 2  # one of the three taken; "clear lot B" alone takes all three
    assert not [a for a in ruled(campus, registry, "clear lot B").scene.assets if a.category in ("passenger_car", "suv")]


def test_a_thing_made_to_fly_is_refused_and_birds_flying_are_no_request(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("make the bus fly to the library")
    assert not report.ok and session.scene == campus and "'fly'" in (report.error or "")
    assert len(_of(ruled(campus, registry, "the birds fly over the fountain, add a bench there").scene, "bench")) == 2


def test_a_brake_misspelt_after_a_modal_is_a_stop_as_the_ego_closes_in(campus, registry):
    session = ruled(campus, registry, "add a car 30 m ahead of the ego in its lane going 3 m/s")
    report = session.submit("the car ahead should break when the ego is 15 m away")
    # read as a scenario, it is asked about or done, never the car moved
    car = session.scene.asset("passenger_car_3")
    assert car is not None and math.isclose(car.pose.x, ruled(campus, registry, "add a car 30 m ahead of the ego in its lane going 3 m/s").scene.asset("passenger_car_3").pose.x)
    readings = [c for reading in (report.question.readings if report.question else []) for c in reading.calls]
    calls = readings or (report.plan.calls if report.plan else [])
    assert any(c.tool == "add_event" and c.args["manoeuvre"]["kind"] == "stop" for c in calls), calls


def test_traffic_coming_the_other_way_drives_in_the_oncoming_lane(campus, registry):
    (truck,) = _of(ruled(campus, registry, "add a truck coming from the opposite direction").scene, "truck")
    assert truck.behaviour.kind == "drive_lane" and truck.behaviour.lane == "main_westbound"


def test_counts_and_short_words_typed_with_a_slip(campus, registry):
    assert len(_of(ruled(campus, registry, "add two cones by the stop sign", "add tree more cones").scene, "traffic_cone")) == 5
    report = Session(campus, RulePlanner(), registry).submit("tell me if it's raning right now")
    assert report.ok and report.plan is not None and [c.tool for c in report.plan.calls] == ["describe_environment"]
    weather = ruled(campus, registry, "fog so thick you can see next to nothing").scene.environment.weather
    assert weather.kind == "fog" and weather.intensity >= 0.75


def test_a_place_said_after_an_id_describes_that_thing(campus, registry):
    new = [b for b in _of(ruled(campus, registry, "put a bench beside tree_2, just south of the fountain").scene, "bench") if b.id != "bench_1"]
    tree = campus.asset("tree_2")
    assert len(new) == 1 and math.dist((new[0].pose.x, new[0].pose.y), (tree.pose.x, tree.pose.y)) < 4.0


def test_the_kind_asked_after_which_is_looked_up_and_people_who_lack_a_seat_get_one(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("the visitors at the library want to know which tree is nearest them")
    assert report.ok and report.plan is not None and report.plan.calls[0].args.get("category") == "tree"
    for said in ("the kids at the fountain have nowhere to sit", "the parents at the east gate have no place to sit"):
        scene = ruled(campus, registry, said).scene
        assert len(_of(scene, "bench")) == 2 and not _of(scene, "pedestrian"), said
        assert scene.asset("bench_1").pose == campus.asset("bench_1").pose, said  # a new bench, the old one unmoved


def test_a_thing_moved_off_the_road_goes_somewhere_off_it(campus, registry):
    car = ruled(campus, registry, "add a car in the westbound lane", "move the car off the road").scene.asset("passenger_car_3")
    assert surface_at(campus, car.pose.x, car.pose.y) == "paved"  # parked in a lot, not shifted along the lane
    walker = ruled(campus, registry, "add a pedestrian in the eastbound lane", "move the pedestrian out of the road").scene.asset("pedestrian_1")
    assert surface_at(campus, walker.pose.x, walker.pose.y) == "sidewalk"


def test_a_summary_heading_and_a_thing_said_to_stay_in_a_sentence_of_its_own(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("Title: list the lanes on Main Street / Expected: two lanes")
    assert report.ok and report.plan is not None and [c.tool for c in report.plan.calls] == ["find_lanes"]
    scene = ruled(campus, registry, "Delete passenger_car_2 and passenger_car_1. Their SUV stays.").scene
    assert scene.asset("suv_1") is not None and not _of(scene, "passenger_car")


def test_half_of_the_things_on_one_side_is_half_of_those(campus, registry):
    scene = ruled(campus, registry, "take away half of the lamps on the north side").scene
    north = [a for a in _of(campus, "street_light") if a.pose.y > 0]
    left = [a for a in _of(scene, "street_light") if a.pose.y > 0]
    assert len(left) == len(north) - len(north) // 2 and len(_of(scene, "street_light")) == len(_of(campus, "street_light")) - len(north) // 2


def test_a_thing_turned_to_face_away_from_the_road_has_its_back_to_it(campus, registry):
    bench = ruled(campus, registry, "move the bench next to the bus stop", "have the bench face away from the road").scene.asset("bench_1")
    assert math.sin(bench.pose.yaw) < -0.9  # the road runs north of the stop: facing south
    bench = ruled(campus, registry, "have the bench face the road").scene.asset("bench_1")  # it faces west as the campus ships
    assert math.sin(bench.pose.yaw) > 0.9


def test_a_thing_with_no_motor_asked_to_go_by_itself_is_refused(campus, registry):
    for said in ("let the bench roll away by itself", "could the hydrant back up on its own"):
        session = Session(campus, RulePlanner(), registry)
        report = session.submit(said)
        assert not report.ok and session.scene == campus, said
    # "on its own" said of a move the person makes is the thing alone, moved
    moved = ruled(campus, registry, "move the bin 2 m left on its own").scene.asset("trash_bin_1")
    assert moved.pose != campus.asset("trash_bin_1").pose


def test_a_pace_complained_of_never_starts_parked_things(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("the cars are going much too fast")  # those there are parked: none is set going
    assert not report.ok and session.scene == campus


def test_a_scene_made_to_look_like_a_time_of_day_gets_it(campus, registry):
    env = ruled(campus, registry, "make it look like a snowy evening").scene.environment
    assert env.weather.kind == "snow" and env.time_of_day != campus.environment.time_of_day


def test_the_nearest_kind_of_place_asked_with_the_superlative_first(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("what's the closest building to the hydrant")
    assert report.ok and report.plan is not None and report.plan.calls[0].args.get("query") == "building"


def test_a_things_data_needed_is_a_question_never_one_more_of_it(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("the safety officer needs bench data for the audit")
    assert report.ok and session.scene == campus and report.plan is not None
    assert [c.tool for c in report.plan.calls] == ["find_assets"]
