"""Things picked out by kind and number, worded here (none from a suite): a kind's name of two words
with its number ("street light 9"), a list of numbers after one name ("the lamps no. 9 and 11", "trees
1, 2 and 4"), a number that names a thing the scene lacks, a thing's number never read as an angle,
one street light switched (the lamps switch all together), a particle said after two things ("take
car 1 and car 2 away") and a thing put back where it started."""

from __future__ import annotations

from drivetwin.orchestrator.session import Session
from misreading import Fixed, call, held, ruled  # this folder is on sys.path (no __init__.py)


def _ids(scene, category: str) -> set[str]:
    return {a.id for a in scene.assets if a.category == category}


def test_a_two_word_name_and_its_number_pick_that_one(campus, registry):
    left = _ids(ruled(campus, registry, "remove street light 9").scene, "street_light")
    assert left == _ids(campus, "street_light") - {"street_light_9"}


def test_a_list_of_numbers_after_a_name_picks_each_of_them(campus, registry):
    lamps = _ids(campus, "street_light")
    for said in ("remove street lights 9 and 11", "remove the lamps number 9 and 11", "remove lamps no. 9 and 11",
                 "remove lamp no. 9 and lamp no. 11", "get rid of street light 9 and street light 11"):
        assert _ids(ruled(campus, registry, said).scene, "street_light") == lamps - {"street_light_9", "street_light_11"}, said
    painted = ruled(campus, registry, "paint trees 1, 2 and 4 red").scene
    assert {a.id for a in painted.assets if a.category == "tree" and a.appearance.rgba is not None} == {"tree_1", "tree_2", "tree_4"}
    # the list is read whole or not at all: a measure after it is no thing's number
    moved = ruled(campus, registry, "move the trees 3 and 4 two metres north").scene
    assert [moved.asset(t).pose.y - campus.asset(t).pose.y for t in ("tree_3", "tree_4")] == [2.0, 2.0]
    assert _ids(ruled(campus, registry, "remove the cars one at a time").scene, "passenger_car") == set()


def test_a_number_the_scene_has_no_such_thing_for_is_never_another_one(campus, registry):
    report = held(campus, registry, Fixed(call("move_asset", asset="bench_1", turn_deg=90.0)), "rotate bench 4 by 90 degrees")
    assert "there is no bench 4 here" in (report.error or "") and "bench_1" in (report.error or "")
    # the one named is there: the plan stands
    session = Session(campus, Fixed(call("move_asset", asset="bench_1", turn_deg=90.0)), registry)
    assert session.submit("rotate bench 1 by 90 degrees").ok


def test_a_things_number_is_no_angle(campus, registry):
    turned = ruled(campus, registry, "turn car 2 around").scene.asset("passenger_car_2")
    assert abs(abs(turned.pose.yaw - campus.asset("passenger_car_2").pose.yaw) - 3.14159) < 0.01  # not 2 degrees
    assert ruled(campus, registry, "turn car 2 by 45").scene.asset("passenger_car_2").pose.yaw != turned.pose.yaw


def test_one_street_light_switched_is_refused_saying_they_switch_together(campus, registry):
    from drivetwin.orchestrator.planning.rules.planner import RulePlanner

    for said in ("turn off street light 1", "switch lamp 3 on", "switch off street_light_5"):
        report = held(campus, registry, RulePlanner(), said)  # street light 1 had been turned by a degree
        assert "switched all together" in (report.error or ""), said
    report = held(campus, registry, Fixed(call("set_lighting", street_lights="off")), "turn off street light 1")
    assert "switched all together" in (report.error or "")  # every lamp off for one named: never unasked
    assert ruled(campus, registry, "turn the street lights off").scene.environment.lighting.street_lights == "off"


def test_a_particle_after_two_things_goes_with_both(campus, registry):
    scene = ruled(campus, registry, "take passenger_car_1 and passenger_car_2 away").scene
    assert _ids(scene, "passenger_car") == set()  # passenger_car_1 had stayed


def test_a_thing_goes_back_where_it_started(campus, registry):
    start = campus.asset("bench_1").pose
    for said in ("put it back where it started", "put the bench back at its starting position"):
        back = ruled(campus, registry, "move the bench to the fountain", said).scene.asset("bench_1").pose
        assert (back.x, back.y) == (start.x, start.y), said
