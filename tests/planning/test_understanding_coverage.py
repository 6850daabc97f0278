"""A plan must cover every content phrase of the request, or the session asks or refuses.

One test per general failure class (named things left out, an existing thing added anew,
weather and clock times dropped, all of a plural done as one, a place the world lacks, an
amount ignored by a lookup, a request for information read as an edit). Each hands the
session a planner whose plan misreads the request, worded in this file's own voice.
"""

from __future__ import annotations

from drivetwin.orchestrator.planning import Plan
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.request import read_request
from drivetwin.orchestrator.session import Session
from misreading import Fixed, call  # this folder is on sys.path (no __init__.py)


def test_a_second_thing_named_in_a_compound_request_is_not_dropped(campus, registry):
    half = Fixed(call("add_asset", category="bench", count=1))
    session = Session(campus, half, registry)
    report = session.submit("set down a bench beside the fountain plus a bicycle next to it")
    assert not report.ok and session.scene.count("bench") == campus.count("bench")


def test_moving_the_reference_instead_of_the_thing_named_is_not_applied(campus, registry):
    moves_ego = Fixed(call("move_asset", asset="ego", forward=6.0))
    session = Session(campus, moves_ego, registry)
    report = session.submit("shift the bus 6 m up the road from our car")
    assert not report.ok and session.scene.asset("ego") == campus.asset("ego")


def test_the_one_already_there_is_not_answered_by_adding_another(campus, registry):
    assert campus.count("suv") >= 1
    session = Session(campus, Fixed(call("add_asset", category="suv", count=1)), registry)
    report = session.submit("that suv should sit right behind our vehicle")
    assert not report.ok and session.scene.count("suv") == campus.count("suv")


def test_a_clock_time_named_with_the_weather_is_not_dropped(context):
    plan = Plan(calls=[call("set_weather", kind="snow")], planner="x")
    verdict = review("snowfall please, and make it 07:45", plan, context)
    assert verdict.action != "apply" and any("07:45" in p for p in verdict.problems)


def test_a_clock_time_set_to_another_hour_is_not_applied(context):
    plan = Plan(calls=[call("set_time_of_day", time="evening")], planner="x")
    assert review("switch the clock over to 19:10", plan, context).action != "apply"


def test_weather_named_but_not_set_is_not_applied(context):
    plan = Plan(calls=[call("add_asset", category="stop_sign", count=1)], planner="x")
    assert review("the snowfall can stop now", plan, context).action != "apply"


def test_a_plural_removal_done_on_one_of_many_asks_or_refuses(campus, registry):
    session = Session(campus, Fixed(call("remove_assets", category="tree", count=1)), registry)
    report = session.submit("clear away trees")
    assert not report.ok and session.scene.count("tree") == campus.count("tree")


def test_a_place_the_world_does_not_have_is_named_in_the_refusal(context):
    plan = Plan(calls=[call("add_asset", category="bench", count=1)], planner="x")
    verdict = review("set a bench down near the observatory", plan, context)
    assert verdict.action == "refuse" and "observatory" in (verdict.message or "")


def test_a_lookup_that_ignores_the_distance_asked_for_is_not_answered(context):
    plan = Plan(calls=[call("find_assets", category="bench", near="fountain")], planner="x")
    assert review("list benches no more than 35 metres from the fountain", plan, context).action != "apply"


def test_a_request_for_information_worded_as_a_need_is_a_question(campus):
    assert read_request("I'd love to find out how heavy the bus is", campus).question
    assert read_request("for the log, let me know what the hydrant is next to", campus).question


def test_an_amount_written_as_a_word_is_checked(context):
    plan = Plan(calls=[call("add_asset", category="bollard", count=1)], planner="x")
    assert review("we need nine bollards", plan, context).action != "apply"


def test_a_plan_covering_every_phrase_is_still_applied(campus, registry):
    both = Fixed(
        call("add_asset", category="bench", count=2, location={"relation": "at", "target": "fountain"}),
        call("set_weather", kind="fog"),
    )
    session = Session(campus, both, registry)
    report = session.submit("put 2 benches at the fountain and make it foggy")
    assert report.ok and session.scene.count("bench") == campus.count("bench") + 2


def test_a_thing_named_after_a_preposition_of_place_is_where_not_what() -> None:
    from drivetwin.evals.trial import fresh_world
    from drivetwin.orchestrator.planning.coverage import named_things

    scene = fresh_world("campus")
    named = named_things("put a cone next to the parked bus", ["traffic_cone", "bus"], scene)
    assert named == {"traffic_cone"}
    assert named_things("remove the bus and the cone", ["traffic_cone", "bus"], scene) == {"traffic_cone", "bus"}
