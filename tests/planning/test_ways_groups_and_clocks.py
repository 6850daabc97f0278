"""Vehicles that make their way somewhere, behaviours for every one referred to, a lot's entrance,
"later" said of other things than the clock, lights asked after by a place, and a second thing
asked for in the same breath, tried in this file's own words on the packaged campus world: "the
truck should make its way over to the library" drives there, never jumps; "both of them jaywalk"
is both; "we'll sort the weather out later" sets no time; "and a scarecrow next to it" is refused."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.base import Plan, PlanningError
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.tools.base import ToolCall


def _behaviour(session, asset_id):
    asset = session.scene.asset(asset_id)
    assert asset is not None
    return asset.behaviour


@pytest.mark.parametrize("prompt", ["the SUV should make its way over to the library entrance",
                                    "have the suv make its own way to the Student Union",
                                    "the SUV drives to the library"])
def test_a_vehicle_sent_where_no_lane_leads_goes_there_by_path_and_is_not_moved_there(session, campus, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    after, before = session.scene.asset("suv_1"), campus.asset("suv_1")
    assert after is not None and before is not None
    assert (after.pose.x, after.pose.y) == (before.pose.x, before.pose.y)  # it sets off from where it stood
    assert after.behaviour.kind == "follow_path"
    gx, gy = after.behaviour.waypoints[-1]
    goal = session.scene.landmark("Library entrance" if "librar" in prompt else "Student Union entrance")
    assert goal is not None and abs(gx - goal.position[0]) < 3 and abs(gy - goal.position[1]) < 3


def test_a_vehicle_moved_to_a_place_is_still_put_there(session):
    report = session.submit("move the suv to the library")
    assert report.ok, report.error
    assert report.plan is not None and report.plan.calls[0].tool == "place_asset"


@pytest.mark.parametrize("turn", ["both of them should jaywalk now", "the two kids, over the road now, both of them",
                                  "them all to walk to the fountain"])
def test_a_behaviour_for_every_one_referred_to_is_given_to_each(session, turn):
    assert session.submit("add two pedestrians on the south pavement by the west crossing").ok
    report = session.submit(turn)
    assert report.ok, report.error
    kinds = {_behaviour(session, i).kind for i in ("pedestrian_1", "pedestrian_2")}
    assert kinds == {"jaywalk"} if "jaywalk" in turn else kinds == ({"follow_path"} if "walk to" in turn else {"cross_road"})


def test_one_picked_out_of_several_is_the_only_one_given_the_behaviour(session):
    assert session.submit("add two pedestrians at the bus stop").ok
    report = session.submit("now the second one should cross the road")
    assert report.ok, report.error
    assert _behaviour(session, "pedestrian_2").kind == "cross_road"
    assert _behaviour(session, "pedestrian_1").kind != "cross_road"


@pytest.mark.parametrize("prompt", ["put a bench in lot B, by the entrance", "park the suv in parking lot B near the entrance"])
def test_the_entrance_said_after_a_lot_is_that_lots_entrance(session, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert report.plan is not None
    assert report.plan.calls[0].args["location"]["target"] == "parking lot B entrance"


def test_a_crossing_named_by_its_side_is_that_crosswalk_and_one_the_world_lacks_is_refused(session):
    report = session.submit("put a cone on the western crossing")
    assert report.ok, report.error
    assert report.plan is not None and report.plan.calls[0].args["location"]["target"] == "west crosswalk"
    refused = session.submit("put a cone on the east crossing")
    assert not refused.ok and "no 'east crosswalk'" in (refused.error or "")


@pytest.mark.parametrize("prompt", ["we'll sort the weather out later", "cones by the gate, I'll check them later"])
def test_later_said_of_something_else_sets_no_time(context, prompt):
    try:
        plan = RulePlanner().plan(prompt, context)
    except PlanningError:
        return  # not understood is fine; a time set is not
    assert not any(c.tool == "set_time_of_day" for c in plan.calls), plan.calls


@pytest.mark.parametrize(("prompt", "hours"), [("make it a bit later", 3), ("could it be later in the day?", 3),
                                               ("two hours earlier please", -2)])
def test_later_said_of_the_clock_moves_it(context, prompt, hours):
    plan = RulePlanner().plan(prompt, context)
    noon = int(context.scene.environment.time_of_day.split(":")[0])
    assert [(c.tool, c.args) for c in plan.calls] == [("set_time_of_day", {"time": f"{noon + hours:02d}:00"})]


@pytest.mark.parametrize("prompt", ["lights by the library?", "any lamps near the bus stop??"])
def test_lights_asked_after_by_a_place_are_the_lamps_there(context, prompt):
    plan = RulePlanner().plan(prompt, context)
    assert plan.calls[0].tool == "find_assets"
    assert plan.calls[0].args["category"] in ("lights", "street_light")


def test_anything_that_would_block_a_cyclist_is_anything_on_the_road_not_bicycles(session):
    assert session.submit("put some rubble in the eastbound lane 30 m ahead of the ego").ok
    report = session.submit("is there anything sitting in the road that would force a cyclist out into traffic?")
    assert report.ok, report.error
    assert report.plan is not None and "category" not in report.plan.calls[0].args
    assert "cement_rubble_1" in (report.answer or "")


@pytest.mark.parametrize("prompt", ["add a bus at the bus stop and a scarecrow standing next to it",
                                    "put a car by the fountain and two unicorns beside it"])
def test_a_second_thing_this_world_lacks_asked_for_in_the_same_breath_is_not_left_out_silently(context, prompt):
    plan = Plan(calls=[ToolCall(tool="add_asset", args={"category": "bus" if "bus" in prompt else "passenger_car", "count": 1})],
                planner="rules")
    verdict = review(prompt, plan, context)
    assert verdict.action != "apply"
    assert any("there is no" in p for p in verdict.problems), verdict.problems


def test_a_second_thing_the_world_has_is_not_flagged(context):
    at_stop = {"relation": "at", "target": "bus stop"}
    plan = Plan(calls=[ToolCall(tool="add_asset", args={"category": "bus", "count": 1, "location": at_stop}),
                       ToolCall(tool="add_asset", args={"category": "bench", "count": 1,
                                                        "location": {"relation": "next_to", "target": "bus_1"}})], planner="rules")
    assert not any("there is no" in p for p in review("add a bus at the bus stop and a bench next to it", plan, context).problems)
