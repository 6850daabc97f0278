"""The eval harness's `scenario` check simulates the outcome and judges what happened over time."""

from __future__ import annotations

import pytest
from drivetwin.evals.case import load_suite
from drivetwin.evals.checks import CHECK_KINDS
from drivetwin.evals.outcome import CaseOutcome
from drivetwin.evals.scenario_checks import ScenarioCheck
from drivetwin.evals.trial import REFERENCE_PLANNER, ReferencePlanner, run_trial
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.scene import DriveLane, FollowPath, Pose
from drivetwin.worlds.storyboard import LightPhase, StopLine, Storyboard, TrafficLight
from scenario_worlds import EAST_Y, campus_with, vehicle

RED = TrafficLight(light="traffic_light_1", phases=[LightPhase(state="red", duration=60.0)],
                   stop_lines=[StopLine(lane="main_eastbound", position=(-14.0, EAST_Y))])
STOPS_AT_RED = ScenarioCheck.model_validate(
    {"kind": "scenario", "seconds": 14.0, "expect": [{"kind": "stopped_before", "line": [-14.0, EAST_Y]}]})


def test_scenario_is_a_check_kind_a_suite_line_can_use() -> None:
    assert "scenario" in CHECK_KINDS
    suite = load_suite("scenarios")
    assert len(suite.cases) >= 40
    assert {c.grade for c in suite.cases} == {"direct", "indirect", "vague", "erroneous"}


def test_stopped_before_passes_at_a_red_light_and_fails_without_one() -> None:
    still = campus_with(ego_x=-40.0)
    red = still.model_copy(update={"storyboard": Storyboard(lights=[RED])})
    assert STOPS_AT_RED.evaluate(CaseOutcome(still, red)).passed
    failed = STOPS_AT_RED.evaluate(CaseOutcome(still, still))
    assert not failed.passed and "short of the line" in failed.reason


def test_a_collision_is_seen_and_a_min_gap_measured() -> None:
    # A car driving straight at the ego in its lane: they meet head on.
    rammer = vehicle("passenger_car_9", -30.0, EAST_Y, FollowPath(waypoints=[(-30.0, EAST_Y), (-80.0, EAST_Y)], speed=8.0),
                     yaw=3.14159)
    scene = campus_with(rammer, ego_x=-50.0)
    check = ScenarioCheck.model_validate({"kind": "scenario", "seconds": 4.0, "expect": [
        {"kind": "collision", "happens": True},
        {"kind": "min_gap", "other": "passenger_car_9", "metres": 0.0},
    ]})
    result = check.evaluate(CaseOutcome(scene, scene))
    assert result.passed, result.reason
    assert "ego touched passenger_car_9" in result.reason


def test_an_event_assertion_fails_when_the_storyboard_lacks_it() -> None:
    campus = build_campus()
    check = ScenarioCheck.model_validate({"kind": "scenario", "seconds": 0.5, "expect": [
        {"kind": "event", "actor": "ego", "manoeuvre": "stop"}]})
    result = check.evaluate(CaseOutcome(campus, campus))
    assert not result.passed and result.reason == "no stop event for ego"


def test_reached_is_judged_on_the_simulated_path_not_the_authored_pose() -> None:
    ego = build_campus().ego.model_copy(update={"pose": Pose(x=-60.0, y=EAST_Y),
                                                "behaviour": DriveLane(lane="main_eastbound", speed=6.0)})
    scene = build_campus().model_copy(update={"ego": ego})
    check = ScenarioCheck.model_validate({"kind": "scenario", "seconds": 6.0, "expect": [
        {"kind": "reached", "actor": "ego", "place": "-30, -1.75", "within": 2.0}]})
    assert check.evaluate(CaseOutcome(scene, scene)).passed


@pytest.mark.parametrize("case_id", [
    "scenario.direct.lead_brakes", "scenario.direct.cut_in", "scenario.direct.light_turns_red",
    "scenario.direct.refuse_cyclist_turns",
])
def test_reference_plans_of_the_scenario_suite_pass(case_id: str) -> None:
    case = load_suite("scenarios").case(case_id)
    record = run_trial(case, ReferencePlanner(case), trial=1)
    assert record.planner == REFERENCE_PLANNER
    assert record.outcome == "pass", (record.error, record.failed_checks)
