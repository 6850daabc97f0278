"""Requests as engineers and testers paste them: a ticket label in front, a spec's count and
radius notation ("5x", "r=4 m"), a British clock ("half eight"), and a remark that the scene must
stay as it is. Read alike by the rule planner and the plan check; the wording is this file's own."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.intent import asks, without_reason
from drivetwin.orchestrator.planning.request import read_request
from drivetwin.orchestrator.planning.rules.clock import clock_time
from drivetwin.orchestrator.planning.rules.numbers import radius_said
from drivetwin.orchestrator.planning.rules.phrases import normalise
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session


@pytest.mark.parametrize("label", ["SIM-2291:", "[QA-18]", "ticket #7:", "perf-30"])
def test_a_pasted_label_is_neither_a_number_nor_a_word_to_understand(label, campus):
    text = f"{label} put two bollards at the east gate"
    assert without_reason(text).startswith("put two bollards")
    assert read_request(text, campus).numbers == (2.0,)


def test_a_labelled_request_is_planned_and_checked_as_if_unlabelled(session):
    report = session.submit("OPS-58: fog, heavy, for the sensor-degradation run")
    assert report.ok and session.scene.environment.weather.kind == "fog"


def test_a_remark_that_nothing_may_change_makes_the_request_a_question(session, campus):
    assert asks("which lanes does main street have? read-only please")
    assert asks("list every bin near the library, do not change anything")
    assert not asks("move the bus to the gate but don't touch anything else")
    report = session.submit("what stands closest to the fountain, don't edit anything")
    assert report.ok and report.answer and session.scene.assets == campus.assets


def test_a_count_and_a_radius_in_spec_notation(campus):
    assert normalise("5x bollard at gate").split()[:2] == ["5", "bollard"]
    assert "3x4" in normalise("grid 3x4 cones")  # a grid's size stays whole
    assert radius_said("ring of cones, r = 4 m") == 4.0
    assert read_request("7x barrier across main street", campus).numbers == (7.0,)


def test_a_british_half_hour_is_half_past(session):
    assert str(clock_time("wake the scene at half eight in the morning")) == "08:30"
    assert str(clock_time("half nine at night")) == "21:30"
    assert clock_time("shift it half a metre") is None
    report = session.submit("make it half four in the afternoon")
    assert report.ok and session.scene.environment.time_of_day == "16:30"


def test_a_ring_said_as_a_spec_has_its_count_and_radius(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("Circle: 5x bollard round the fountain, r=6 m")
    assert report.ok
    added = [a for a in session.scene.assets if a.category == "bollard" and campus.asset(a.id) is None]
    assert len(added) == 5
