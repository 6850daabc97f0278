"""Amounts and times in the forms people write them outside the English-speaking default: a
decimal comma ("2,5 m"), a clock time read aloud ("seven fifteen in the morning"), a time whose
half of the day is said with no word about setting it ("we start around 9 pm"), and "then" said
formally ("and subsequently"). Each runs through the rule planner and the session's check."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.rules.clock import clock_time
from drivetwin.orchestrator.planning.rules.numbers import decimal_points
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from misreading import applied  # this folder is on sys.path (no __init__.py)


def test_a_decimal_comma_with_a_unit_is_a_decimal(campus, registry):
    scene = applied(campus, registry, RulePlanner(), "shift the bench 2,5 m to the west").scene
    before = campus.asset("bench_1")
    assert scene.asset("bench_1").pose.x == pytest.approx(before.pose.x - 2.5)


def test_a_setting_given_with_a_decimal_comma_is_that_value(campus, registry):
    scene = applied(campus, registry, RulePlanner(), "exposure 0,8 please").scene
    assert scene.environment.lighting.exposure == pytest.approx(0.8)


@pytest.mark.parametrize(("said", "read"), [
    ("cones at 10,5", "cones at 10,5"),  # a pair of figures may be coordinates
    ("add 10,000 cones", "add 10,000 cones"),  # thousands
    ("a barrier 3,75 metres ahead of the ego", "a barrier 3.75 metres ahead of the ego"),
    ("the lead car slows to 4,5 m/s", "the lead car slows to 4.5 m/s"),
])
def test_only_a_comma_before_a_unit_or_in_a_setting_is_a_decimal_point(said, read):
    assert decimal_points(said) == read


@pytest.mark.parametrize(("said", "time"), [
    ("the shoot is at seven fifteen in the morning", "07:15"),
    ("set the clock to ten oh five pm", "22:05"),
    ("what the campus looks like at nine forty-five in the evening", "21:45"),
])
def test_a_time_read_aloud_is_that_time(said, time):
    assert str(clock_time(said)) == time


def test_hours_and_minutes_words_that_count_things_are_no_time():
    assert clock_time("add six twenty-metre poles") is None
    assert clock_time("put eight fifteen cones by the fountain") is None


def test_a_time_is_set_when_its_half_of_the_day_is_said(campus, registry):
    scene = applied(campus, registry, RulePlanner(), "we start the night runs around 9 pm").scene
    assert scene.environment.time_of_day == "21:00"
    scene = applied(campus, registry, RulePlanner(), "the drive happens about seven fifteen in the morning").scene
    assert scene.environment.time_of_day == "07:15"


def test_then_said_formally_splits_the_request(campus, registry):
    scene = applied(campus, registry, RulePlanner(), "Paint the SUV green and subsequently move it 3 m north.").scene
    before, after = campus.asset("suv_1"), scene.asset("suv_1")
    assert after.appearance is not None and after.appearance != before.appearance
    assert after.pose.y == pytest.approx(before.pose.y + 3.0)
