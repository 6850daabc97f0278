"""Doing the last edit again: "repeat that outside Engineering Hall", "ditto for the trees", "do it
again". The last edit's calls come back from the session's memory and go to the place or things
this turn names; what they have no slot for is refused with the scene unchanged. The wording is
this file's own, run through a Session with the rule planner on the packaged campus world."""

from __future__ import annotations

import math

from drivetwin.orchestrator.memory import Turn


def _distance(session, asset_id: str, landmark: str) -> float:
    asset, mark = session.scene.asset(asset_id), session.scene.landmark(landmark)
    return math.hypot(asset.pose.x - mark.position[0], asset.pose.y - mark.position[1])


def test_repeat_that_somewhere_else_makes_the_last_edit_there(session, campus):
    assert session.submit("put three cones by the library").ok
    report = session.submit("repeat that outside Engineering Hall")
    assert report.ok, report.error
    assert session.scene.count("traffic_cone") == campus.count("traffic_cone") + 6
    added = session.memory.last_added("traffic_cone")
    assert len(added) == 3
    assert all(_distance(session, i, "Engineering Hall") < _distance(session, i, "Library") for i in added)


def test_do_it_again_repeats_the_last_edit_as_it_was(session, campus):
    assert session.submit("add two benches in lot A").ok
    assert session.submit("do it again please").ok
    assert session.scene.count("bench") == campus.count("bench") + 4


def test_ditto_for_other_things_changes_those_things_the_same_way(session, campus):
    assert session.submit("paint the suv yellow").ok
    yellow = session.scene.asset("suv_1").appearance.rgba
    report = session.submit("ditto for both trees by the fountain")
    assert report.ok, report.error
    changed = {line.split(":")[0].lstrip("~ ") for line in report.diff}
    assert changed == {"tree_2", "tree_3"}
    assert all(session.scene.asset(t).appearance.rgba == yellow for t in changed)


def test_ditto_for_another_lane_drives_there(session):
    assert session.submit("add a car driving in the eastbound lane of main street").ok
    report = session.submit("ditto for the westbound lane")
    assert report.ok, report.error
    car = session.scene.asset(session.memory.last_added()[0])
    assert car.behaviour is not None and car.behaviour.lane == "main_westbound"


def test_what_the_last_edit_has_no_slot_for_is_refused_and_changes_nothing(session):
    assert session.submit("paint the suv yellow").ok
    before = session.scene
    report = session.submit("do the same next to the bench")
    assert not report.ok and "no place to change" in report.error
    assert session.scene is before


def test_with_nothing_done_yet_there_is_nothing_to_repeat(session):
    report = session.submit("ditto")
    assert not report.ok and "no earlier edit to repeat" in report.error


def test_same_again_but_with_something_new_takes_the_last_amount_of_it(session, campus):
    assert session.submit("add 4 cones by the library").ok
    assert session.submit("same again but bollards").ok
    assert session.scene.count("bollard") == campus.count("bollard") + 4


def test_a_turn_s_calls_read_back_as_calls():
    turn = Turn(prompt="p", status="applied",
                calls=["add_asset(category='bench', count=2, location={'relation': 'at', 'target': 'lot A'})"])
    [call] = turn.tool_calls()
    assert call.tool == "add_asset" and call.args["location"] == {"relation": "at", "target": "lot A"}
