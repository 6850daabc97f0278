"""The scenario reader turns words about behaviour over time into storyboard calls, and a
scenario request is never answered with a static edit (asked or refused instead)."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.base import Plan, PlanContext, PlanningError
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.scenario_reading import ScenarioReader, describes_behaviour_over_time
from drivetwin.orchestrator.transaction import execute
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.scene import Scene

REGISTRY = ToolRegistry.default(plugins=False)


def _with(*calls: dict[str, object]) -> Scene:
    scene = build_campus()
    return execute(REGISTRY, scene, [ToolCall.model_validate(c) for c in calls]).after


def _add(category: str, x: float, y: float, yaw_deg: float = 0.0, behaviour: dict[str, object] | None = None) -> dict[str, object]:
    args: dict[str, object] = {"category": category, "location": {"relation": "absolute", "x": x, "y": y},
                               "yaw_deg": yaw_deg}
    if behaviour is not None:
        args["behaviour"] = behaviour
    return {"tool": "add_asset", "args": args}


def _plan(prompt: str, scene: Scene) -> Plan:
    return ScenarioReader().plan(prompt, PlanContext(scene=scene, registry=REGISTRY))


@pytest.fixture(scope="module")
def van_ahead() -> Scene:
    """A car driving in the ego's lane 25 m ahead of it (the campus has two parked cars)."""
    return _with(_add("passenger_car", -35.0, -1.75, 0.0, {"kind": "drive_lane", "lane": "main_eastbound", "speed": 3.0}))


def test_a_braking_lead_car_with_a_distance_trigger_is_an_event_on_that_car(van_ahead: Scene) -> None:
    plan = _plan("Once our car has closed to twenty metres, the vehicle in front of it jams on the brakes.", van_ahead)
    (call,) = plan.calls
    assert call.tool == "add_event"
    assert call.args["actor"] == "passenger_car_3"
    assert call.args["manoeuvre"]["kind"] == "stop"
    assert call.args["when"] == {"kind": "distance", "actor": "ego", "other": "passenger_car_3", "metres": 20.0,
                                 "rule": "less"}


def test_hard_braking_asks_for_an_emergency_deceleration(van_ahead: Scene) -> None:
    plan = _plan("the car ahead of the ego should brake sharply after 4 s", van_ahead)
    (call,) = plan.calls
    assert call.tool == "add_manoeuvre" and call.args["at_time"] == 4.0
    assert call.args["manoeuvre"]["rate"] >= 6.0


def test_a_cut_in_from_the_next_lane_targets_the_ego_with_the_gap_asked() -> None:
    scene = _with(_add("passenger_car", -50.0, 1.75, 0.0,
                       {"kind": "follow_path", "waypoints": [[-50.0, 1.75], [90.0, 1.75]], "speed": 8.0}))
    plan = _plan("three seconds in, the car in the left lane merges in front of the ego with a 6 m gap", scene)
    (call,) = plan.calls
    assert call.args["manoeuvre"] == {"kind": "cut_in", "gap": 6.0, "target": "ego"}
    assert call.args["at_time"] == 3.0


def test_a_junction_turn_is_read_for_the_car_on_the_named_road() -> None:
    scene = _with(_add("passenger_car", 1.75, -40.0, 90.0, {"kind": "drive_lane", "lane": "campus_northbound", "speed": 5.0}))
    plan = _plan("The vehicle heading up Campus Drive hangs a right at the intersection.", scene)
    (call,) = plan.calls
    assert call.args == {"actor": "passenger_car_3", "manoeuvre": {"kind": "junction_turn", "turn": "right"}}


def test_a_turn_with_no_direction_is_a_question_not_a_guess() -> None:
    scene = _with(_add("passenger_car", 1.75, -40.0, 90.0, {"kind": "drive_lane", "lane": "campus_northbound", "speed": 5.0}))
    plan = _plan("have the car on Campus Drive turn at the intersection", scene)
    assert plan.calls == [] and plan.question is not None
    assert {r.calls[0].args["manoeuvre"]["turn"] for r in plan.question.readings} == {"left", "right", "straight"}


def test_a_light_turning_red_on_approach_is_an_event_on_the_light_the_ego_meets() -> None:
    plan = _plan("as our car nears the intersection, the signal switches to red", build_campus())
    (call,) = plan.calls
    assert call.tool == "add_event"
    assert call.args["actor"] == "traffic_light_1"  # ahead of the ego, on its right
    assert call.args["manoeuvre"] == {"kind": "set_light", "state": "red"}
    assert call.args["when"]["kind"] == "distance" and call.args["when"]["actor"] == "ego"


def test_a_light_cycle_keeps_the_order_and_durations_given() -> None:
    plan = _plan("traffic light: 20 s green then 4 s amber then 25 s red, on repeat as a cycle", build_campus())
    (call,) = plan.calls
    assert call.tool == "set_light_phases"
    assert call.args["phases"] == [{"state": "green", "duration": 20.0}, {"state": "amber", "duration": 4.0},
                                   {"state": "red", "duration": 25.0}]


def test_a_pedestrian_from_behind_a_parked_bus_crosses_when_the_ego_is_near() -> None:
    scene = _with(_add("bus", -20.0, 2.0, 180.0), _add("pedestrian", -14.0, 6.0, -90.0))
    plan = _plan("when the ego is 18 metres from her, the woman hidden behind the parked bus runs across the street", scene)
    (call,) = plan.calls
    assert call.args["actor"] == "pedestrian_1"
    assert call.args["manoeuvre"]["kind"] == "cross_road"
    assert call.args["when"]["metres"] == 18.0


def test_a_manoeuvre_the_actor_cannot_do_is_refused_saying_what_is_possible() -> None:
    with pytest.raises(PlanningError, match=r"a bench cannot stop.*a scenario can make"):
        _plan("the bench slams on its brakes after 2 seconds", build_campus())


def test_a_static_plan_for_a_scenario_request_is_never_applied(van_ahead: Scene) -> None:
    context = PlanContext(scene=van_ahead, registry=REGISTRY)
    prompt = "the car ahead of the ego brakes hard when the ego is 12 m behind it"
    static = Plan(calls=[ToolCall(tool="move_asset", args={"asset": "passenger_car_3", "forward": 3})], planner="t")
    verdict = review(prompt, static, context)
    assert verdict.action == "ask" and verdict.question is not None
    assert verdict.question.readings[0].calls[0].tool == "add_event"


def test_a_static_plan_for_an_impossible_scenario_is_refused() -> None:
    context = PlanContext(scene=build_campus(), registry=REGISTRY)
    static = Plan(calls=[ToolCall(tool="remove_assets", args={"category": "bench"})], planner="t")
    verdict = review("the bench brakes hard when our car comes close", static, context)
    assert verdict.action == "refuse"
    assert verdict.message is not None and "cannot stop" in verdict.message


def test_static_requests_are_not_read_as_behaviour_over_time() -> None:
    scene = build_campus()
    assert not describes_behaviour_over_time("add a car overtaking in the left lane", scene)
    assert not describes_behaviour_over_time("move the bench 2 m to the left", scene)
    assert not describes_behaviour_over_time("the pedestrian should cross the road", scene)
    assert describes_behaviour_over_time("the car changes lanes to the left after 5 seconds", scene)
    # a stop denied, or said before a colon that introduces something else, is no stop in the road
    assert not describes_behaviour_over_time("the walker shouldn't just wait there: make her go over the road", scene)
    assert describes_behaviour_over_time("the walker stops in the middle of the road when the ego is 20 m away", scene)


# Reading by structure: who acts, what it does, when, and against whom.

def _oncoming_truck_and_follower() -> Scene:
    return _with(_add("truck", 45.0, 1.75, 180.0, {"kind": "drive_lane", "lane": "main_westbound", "speed": 2.5}),
                 _add("passenger_car", 62.0, 1.75, 180.0, {"kind": "drive_lane", "lane": "main_westbound", "speed": 6.0}))


def test_a_condition_that_names_nobody_is_measured_from_the_actor_to_what_it_acts_on() -> None:
    plan = _plan("the car behind the truck overtakes it once twelve metres behind", _oncoming_truck_and_follower())
    (call,) = plan.calls
    assert call.args["when"]["actor"] == "passenger_car_3" and call.args["when"]["other"] == "truck_1"
    assert call.args["when"]["metres"] == 12.0


def test_a_walker_stepping_out_in_front_of_the_ego_waits_for_the_ego_to_approach() -> None:
    scene = _with(_add("pedestrian", -20.0, 6.0, -90.0))
    plan = _plan("a man steps out in front of the ego", scene)
    (call,) = plan.calls
    assert call.tool == "add_event" and call.args["manoeuvre"]["kind"] == "cross_road"
    assert call.args["when"]["kind"] == "distance" and call.args["when"]["actor"] == "ego"


def test_standing_still_in_the_road_is_behaviour_over_time() -> None:
    scene = _with(_add("pedestrian", -20.0, -6.0, 90.0))
    assert describes_behaviour_over_time("the ped should drift into the street and stand there", scene)
    (call,) = _plan("the ped should drift into the street and stand there", scene).calls
    assert call.args["manoeuvre"]["kind"] == "stop_mid_road"


def test_a_verb_word_before_the_subjects_noun_describes_it() -> None:
    scene = _with(_add("passenger_car", 1.75, -40.0, 90.0, {"kind": "drive_lane", "lane": "campus_northbound", "speed": 5.0}))
    (call,) = _plan("the crossing car turns right after 2 s", scene).calls
    assert call.args == {"actor": "passenger_car_3", "manoeuvre": {"kind": "junction_turn", "turn": "right"}, "at_time": 2.0}


def test_the_actor_is_the_first_thing_named_not_a_thing_it_acts_on() -> None:
    scene = _with(_add("passenger_car", 1.75, -40.0, 90.0, {"kind": "drive_lane", "lane": "campus_northbound", "speed": 5.0}))
    with pytest.raises(PlanningError, match="red light"):  # the car acts; it is not a request to change the light
        _plan("the car on Campus Drive jumps the red light", scene)


def test_a_lane_named_by_whose_it_is_is_entered_on_the_side_they_are() -> None:
    scene = _with(_add("passenger_car", 30.0, 1.75, 180.0, {"kind": "drive_lane", "lane": "main_westbound", "speed": 5.0}))
    (call,) = _plan("after 1 s the oncoming car veers into the ego's lane", scene).calls
    assert call.args["manoeuvre"] == {"kind": "lane_change", "side": "left"}  # heading west, the ego's lane is south


def test_straight_through_the_junction_is_a_junction_turn_straight() -> None:
    scene = _with(_add("passenger_car", 1.75, -40.0, 90.0, {"kind": "drive_lane", "lane": "campus_northbound", "speed": 5.0}))
    (call,) = _plan("the car on Campus Drive carries straight on over the crossroads", scene).calls
    assert call.args["manoeuvre"]["turn"] == "straight"


def test_turning_off_with_no_side_asks_between_left_and_right_only() -> None:
    scene = _with(_add("passenger_car", 30.0, 1.75, 180.0, {"kind": "drive_lane", "lane": "main_westbound", "speed": 5.0}))
    plan = _plan("the oncoming car turns off at the intersection", scene)
    assert plan.question is not None
    assert {r.calls[0].args["manoeuvre"]["turn"] for r in plan.question.readings} == {"left", "right"}


def test_a_deceleration_with_no_end_speed_brakes_to_a_stop(van_ahead: Scene) -> None:
    (call,) = _plan("the car ahead decelerates at 5 m/s² after 2 s", van_ahead).calls
    assert call.args["manoeuvre"] == {"kind": "stop", "rate": 5.0}


def test_a_delay_counted_from_the_start_of_the_run_is_a_start_time(van_ahead: Scene) -> None:
    (call,) = _plan("6 seconds into the scenario, the car ahead stops", van_ahead).calls
    assert call.tool == "add_manoeuvre" and call.args["at_time"] == 6.0


def test_a_delay_counted_from_a_condition_is_refused_saying_what_can_start_a_manoeuvre(van_ahead: Scene) -> None:
    with pytest.raises(PlanningError, match=r"cannot wait a time after a condition.*seconds after the scenario starts"):
        _plan("the car ahead stops 2 s after the ego gets within 25 m", van_ahead)


def test_a_distance_from_a_place_is_refused_not_read_as_a_distance_between_actors() -> None:
    scene = _with(_add("passenger_car", 1.75, -40.0, 90.0, {"kind": "drive_lane", "lane": "campus_northbound", "speed": 5.0}))
    with pytest.raises(PlanningError, match="distance from a place"):
        _plan("once the ego is 25 m from the main intersection, the car on Campus Drive turns left", scene)


def test_a_step_some_seconds_later_starts_that_long_after_the_timed_step_before(van_ahead: Scene) -> None:
    first, second = _plan("after 2 s the car ahead speeds up to 9 m/s and slows to a stop 3 s later", van_ahead).calls
    assert first.args["at_time"] == 2.0 and first.args["manoeuvre"]["kind"] == "change_speed"
    assert second.args["at_time"] == 5.0 and second.args["manoeuvre"]["kind"] == "stop"


def test_a_next_step_by_another_actor_waits_for_the_first_event_to_end(van_ahead: Scene) -> None:
    first, second = _plan("when the ego is 20 m behind it, the car ahead brakes, then the ego moves into the left lane",
                          van_ahead).calls
    assert first.tool == "add_event" and first.args["name"]
    assert second.args["actor"] == "ego" and second.args["when"] == {"kind": "after_event", "event": first.args["name"]}


@pytest.mark.parametrize("prompt", [
    "the oncoming car makes a U-turn after 3 s",
    "after 2 s the car ahead mounts the pavement",
    "the car ahead honks when the ego is 10 m behind",
    "the car ahead rams into the bench after 4 s",
])
def test_what_no_worker_can_play_is_refused_naming_what_is_possible(prompt: str) -> None:
    scene = _with(_add("passenger_car", -35.0, -1.75, 0.0, {"kind": "drive_lane", "lane": "main_eastbound", "speed": 3.0}),
                  _add("passenger_car", 30.0, 1.75, 180.0, {"kind": "drive_lane", "lane": "main_westbound", "speed": 5.0}))
    assert describes_behaviour_over_time(prompt, scene)
    with pytest.raises(PlanningError, match=r"I cannot make anything .*: .*(can|only|outcome)"):
        _plan(prompt, scene)


def test_a_storyboard_plan_the_reader_agrees_with_is_applied_despite_colour_words() -> None:
    context = PlanContext(scene=build_campus(), registry=REGISTRY)
    prompt = "the traffic light goes red as the ego approaches it"
    plan = _plan(prompt, context.scene)
    assert review(prompt, plan, context).action == "apply"


def test_a_storyboard_plan_other_than_the_story_described_is_asked_about_offering_the_reading(van_ahead: Scene) -> None:
    context = PlanContext(scene=van_ahead, registry=REGISTRY)
    other = Plan(calls=[ToolCall(tool="set_light_phases", args={
        "light": "traffic_light_1", "phases": [{"state": "green", "duration": 60.0}]})], planner="t")
    verdict = review("the traffic light goes red as the ego approaches it", other, context)
    assert verdict.action == "ask" and verdict.question is not None
    assert verdict.question.readings[0].calls[0].args["manoeuvre"] == {"kind": "set_light", "state": "red"}


def test_a_request_opening_with_a_verb_keeps_that_verb_as_the_action() -> None:
    (call,) = _plan("halt our car at the traffic signal", build_campus()).calls
    assert call.tool == "set_light_phases" and call.args["phases"][0]["state"] == "red"


def test_a_place_name_with_a_verb_in_it_is_not_a_manoeuvre() -> None:
    assert not describes_behaviour_over_time("take the bench away from the bus stop and put a bin there", build_campus())


def test_naming_the_jaywalk_behaviour_is_a_static_behaviour_request() -> None:
    scene = _with(_add("pedestrian", -20.0, -6.0, 90.0))
    assert not describes_behaviour_over_time("have pedestrian_1 jaywalk ahead of the ego", scene)
    assert describes_behaviour_over_time("have pedestrian_1 dart out ahead of the ego", scene)
