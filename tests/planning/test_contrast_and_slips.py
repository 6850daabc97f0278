"""What a request says it does not mean ("..., not the ego", "except the one by the fountain",
"rather than in the lot"), and small slips of everyday writing: "is their a", "45ish", "a couple
of metres", "far too bright", "must not show up". Read alike by the rule planner and the plan
check; the wording is this file's own, run on the packaged campus world."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.base import Plan, PlanContext
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.intent import REMOVE_WORDS, excepted, without_reason
from drivetwin.orchestrator.planning.request import read_request
from drivetwin.orchestrator.planning.rules.numbers import numbers_in, spelt_measures
from drivetwin.orchestrator.planning.rules.spelling import repair
from drivetwin.tools.base import ToolCall


@pytest.mark.parametrize(
    ("text", "kept", "said"),
    [
        ("recolour all vehicles green, but not the ego", "recolour all vehicles green", ["the ego"]),
        ("clear the benches except for the one near the library", "clear the benches", ["the one near the library"]),
        ("the robot should wait by the union rather than in the car park", "the robot should wait by the union",
         ["in the car park"]),
        ("park suv_1 in lot b instead of leaving it on the road", "park suv_1 in lot b", ["leaving it on the road"]),
    ],
)
def test_a_clause_naming_what_is_not_meant_is_read_apart(text, kept, said):
    assert without_reason(text) == kept
    assert excepted(text) == said


@pytest.mark.parametrize("text", ["swap in a bench instead of the bin", "Nope, not the bench - the bin",
                                  "make it drizzle but not too heavily"])
def test_a_swap_a_correction_said_first_or_a_denied_strength_is_no_exception(text):
    assert excepted(text) == []


def _context(campus, registry):
    return PlanContext(campus, registry)


def test_a_plan_that_changes_what_the_request_excepts_is_not_applied(campus, registry):
    calls = [ToolCall(tool="set_asset_appearance", args={"assets": ["passenger_car_1", "passenger_car_2", "suv_1"],
                                                         "colour": "green"})]
    verdict = review("give every car a green paint job except passenger_car_1", Plan(calls=calls, planner="t"),
                     _context(campus, registry))
    assert verdict.action == "ask"
    assert "not passenger_car_1" in verdict.problems[0]
    spared = verdict.question.readings[0].calls  # the reading offered first leaves the excepted one alone
    assert spared[0].args["assets"] == ["passenger_car_2", "suv_1"]


def test_a_thing_excepted_by_where_it_stands_is_the_one_of_its_kind_nearest_there(campus, registry):
    trees = sorted(campus.assets, key=lambda a: (a.pose.x - 75.0) ** 2 + (a.pose.y - 40.0) ** 2)
    by_fountain = next(a.id for a in trees if a.category == "tree")
    verdict = review("chop down every tree apart from the one beside the fountain",
                     Plan(calls=[ToolCall(tool="remove_assets", args={"category": "tree"})], planner="t"),
                     _context(campus, registry))
    assert verdict.action == "ask" and by_fountain in verdict.problems[0]
    offered = verdict.question.readings[0].calls[0].args["assets"]
    assert by_fountain not in offered and offered


def test_a_plan_that_leaves_the_excepted_thing_alone_is_applied(campus, registry):
    calls = [ToolCall(tool="set_asset_appearance", args={"assets": ["passenger_car_1", "passenger_car_2"], "colour": "teal"})]
    verdict = review("paint the two sedans teal, not the suv", Plan(calls=calls, planner="t"), _context(campus, registry))
    assert verdict.action == "apply", verdict.problems


def test_the_session_never_touches_the_excepted_ego(session, campus):
    report = session.submit("start the parked ones moving, not the ego")
    ego = session.scene.ego
    assert ego is not None and campus.ego is not None
    assert ego.behaviour == campus.ego.behaviour and ego.pose == campus.ego.pose
    assert report.ok or report.question is not None or report.error


def test_their_for_there_after_is_makes_a_question(session, campus):
    assert repair("is their a hydrant near the bus stop", campus).text.startswith("is there a hydrant")
    assert repair("their are benches by the fountain", campus).text.startswith("there are benches")
    assert repair("park it in their lot", campus).text == "park it in their lot"
    report = session.submit("is their a bench anywhere near the library")
    assert report.ok and session.scene.assets == campus.assets


def test_must_not_show_up_asks_for_the_thing_gone(campus):
    assert REMOVE_WORDS.search("those barrels must not appear in tomorrow's run")
    assert REMOVE_WORDS.search("the bin shouldn't be there at all")
    assert not REMOVE_WORDS.search("the robot must not drive through the fountain")
    assert read_request("that hydrant should not be in the scene", campus).polarity == "remove"


def test_a_figure_said_roughly_is_that_figure(session, campus):
    assert [n.value for n in numbers_in("spin it 30ish")] == [30.0]
    report = session.submit("spin the hydrant 60ish")
    hydrant, before = session.scene.asset("fire_hydrant_1"), campus.asset("fire_hydrant_1")
    assert report.ok and hydrant is not None and before is not None
    assert abs(abs(hydrant.pose.yaw - before.pose.yaw) - 1.0472) < 0.01  # 60 degrees, not a default half turn


def test_a_vague_measure_is_a_small_figure():
    assert spelt_measures("shift it a couple of metres left") == "shift it 2 metres left"
    assert spelt_measures("wait a few seconds") == "wait 3 seconds"
    assert spelt_measures("a couple of cones") == "a couple of cones"  # a count stays vague


def test_too_bright_turns_the_exposure_down_and_keeps_the_time(session, campus):
    report = session.submit("honestly the picture is way too bright")
    assert report.ok
    assert session.scene.environment.lighting.exposure < campus.environment.lighting.exposure
    assert session.scene.environment.time_of_day == campus.environment.time_of_day


def test_where_an_unknown_thing_appears_is_refused_by_its_name(session, campus):
    report = session.submit("where do the hovercraft usually show up?")
    assert not report.ok and "hovercraft" in (report.error or "")
    assert session.scene.assets == campus.assets
