"""Requests that state the scene wanted rather than the edit ("there must be exactly three cones
here", "we'd like no trees by the fountain"), that count some of what was just made ("drop three of
those", "keep just two of them"), that take a word back as it is said ("3 m north, no wait,
south"), that hedge a wish as a question ("perhaps a few bikes ...?"), or that are typed as texts.
The wording is this file's own, run through a Session with the rule planner on the campus world."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.intent import without_slip


def test_an_exact_count_wished_for_removes_the_surplus(session, campus):
    assert session.submit("put seven cones in lot A").ok
    report = session.submit("there must be exactly three cones in lot A")
    assert report.ok, report.error
    assert session.scene.count("traffic_cone") == campus.count("traffic_cone") + 3


def test_an_exact_count_wished_for_adds_what_is_missing(session, campus):
    assert session.submit("put two cones in lot A").ok
    report = session.submit("we want only five cones in lot A")
    assert report.ok, report.error
    assert session.scene.count("traffic_cone") == campus.count("traffic_cone") + 5


def test_a_count_already_met_changes_nothing_and_says_so(session):
    assert session.submit("put two cones in lot A").ok
    before = session.scene
    report = session.submit("there should be exactly two cones in lot A")
    assert not report.ok and "already 2" in report.error
    assert session.scene is before


@pytest.mark.parametrize("prompt", ["we'd like no trees by the fountain", "there must be no trees by the fountain"])
def test_none_wished_for_at_a_place_removes_those_there(session, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert session.scene.asset("tree_2") is None and session.scene.asset("tree_3") is None
    assert session.scene.asset("tree_1") is not None


def test_some_of_what_was_just_made_are_counted(session, campus):
    assert session.submit("put five cones by the library").ok
    assert session.submit("take three of those away").ok
    assert session.scene.count("traffic_cone") == campus.count("traffic_cone") + 2
    report = session.submit("hmm, keep just one of them")
    assert report.ok, report.error
    assert session.scene.count("traffic_cone") == campus.count("traffic_cone") + 1


@pytest.mark.parametrize(("said", "meant"), [
    ("shift the bin 3 m north, no wait, south", "shift the bin 3 m south"),
    ("add four, sorry, six bollards by the library", "add six bollards by the library"),
    ("paint the hydrant - oops, the bench - blue", "paint the bench blue"),
    ("I'm sorry to ask again, add a cone", "I'm sorry to ask again, add a cone"),  # nothing taken back
    ("set the street lights on - no, off. Off!", "set the street lights off"),
    ("how far is the bus from, no sory, the truck from the gate", "how far is the truck from the gate"),
    ("how far is bench 1 from, no, bench 2 from the gate", "how far is bench 2 from the gate"),
    ("find the tree nearest the gate, or actually the one nearest the quad", "find the tree nearest the quad"),
    ("add another one - no, three more", "add three more"),
    ("fewer bins. a third - no, keep only one", "fewer bins. keep only one"),
    ("put bins, no, bollards by the gate", "put bollards by the gate"),
    ("rings, no, a line - no, rings", "rings"),
    ("put two bins by the bench - sorry, three. Three bins.", "put three bins by the bench"),
    ("paint the blue car red, no, green", "paint the blue car green"),
    ("any parked suv by the quad? sorry, parked bus, typo", "any parked bus by the quad? typo"),
    ("park it by the fountain. By the bench I mean, sorry.", "park it by the fountain. By the bench I mean, sorry."),
    ("There are no cars. Add one.", "There are no cars. Add one."),  # "no" is not broken off
    ("Is there a bench? No? Then add one.", "Is there a bench? No? Then add one."),
])
def test_a_word_taken_back_is_replaced_by_its_correction(said, meant):
    assert without_slip(said) == meant


def test_a_corrected_direction_is_the_one_applied(session, campus):
    report = session.submit("shift the bin 3 m north, no wait, south")
    assert report.ok, report.error
    before, after = campus.asset("trash_bin_1"), session.scene.asset("trash_bin_1")
    assert after.pose.y == pytest.approx(before.pose.y - 3.0, abs=0.3)


def test_a_switch_corrected_mid_request_is_set_the_way_said_last(session):
    report = session.submit("switch the street lamps on - no, off. Off!")
    assert report.ok, report.error
    assert session.scene.environment.lighting.street_lights == "off"


def test_a_thing_corrected_mid_question_is_the_one_measured(session):
    report = session.submit("how far is bench 1 from, no sorry, the hydrant from the fountain")
    assert report.ok, report.error
    assert "fire_hydrant_1" in report.answer and "bench_1" not in report.answer


def test_a_distance_said_not_to_be_meant_is_not_a_move(session, campus):
    report = session.submit("the hydrant belongs right by the bench, not 40 m away from it")
    assert report.ok, report.error
    hydrant, bench = session.scene.asset("fire_hydrant_1"), campus.asset("bench_1")
    assert abs(hydrant.pose.x - bench.pose.x) + abs(hydrant.pose.y - bench.pose.y) < 6.0


def test_a_hedged_wish_asked_as_a_question_is_added(session, campus):
    report = session.submit("perhaps a few bikes outside Engineering Hall?")
    assert report.ok, report.error
    assert session.scene.count("bicycle") > campus.count("bicycle")


def test_text_speak_and_an_imperative_measure_are_questions(session, campus):
    report = session.submit("how many benches r there")
    assert report.ok and [c.tool for c in report.plan.calls] == ["find_assets"]
    report = session.submit("Measure from the fountain to the ego, please")
    assert report.ok and [c.tool for c in report.plan.calls] == ["measure_distance"]
    assert session.scene.assets == campus.assets


def test_lamps_made_off_and_a_clock_hour_of_the_night_in_learner_word_order(session):
    assert session.submit("All street lamp make off please.").ok
    assert session.scene.environment.lighting.street_lights == "off"
    assert session.submit("Make it the 10 o'clock of night.").ok
    assert session.scene.environment.time_of_day == "22:00"
