"""Scenario descriptions in the manner of public catalogues (NHTSA pre-crash typology, Euro NCAP
AEB/LSS test scenarios, OpenSCENARIO examples), written for this test: each is read, passed by
the plan-versus-request review, applied, and the resulting Scene's storyboard is what the
description says (who acts, which manoeuvre, what starts it)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import pytest
from drivetwin.orchestrator.planning.base import PlanContext
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.scenario_reading import ScenarioReader
from drivetwin.orchestrator.transaction import execute
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.scene import Scene

REGISTRY = ToolRegistry.default(plugins=False)


def _add(category: str, x: float, y: float, yaw_deg: float, behaviour: dict[str, Any] | None = None) -> dict[str, Any]:
    args: dict[str, Any] = {"category": category, "location": {"relation": "absolute", "x": x, "y": y}, "yaw_deg": yaw_deg}
    if behaviour is not None:
        args["behaviour"] = behaviour
    return {"tool": "add_asset", "args": args}


# Setups: the actors each description talks about, where the catalogues put them relative to the ego
# (the ego drives east on Main Street from x = -60).
LEAD = [_add("passenger_car", -35.0, -1.75, 0.0, {"kind": "drive_lane", "lane": "main_eastbound", "speed": 3.0})]
ONCOMING = [_add("passenger_car", 30.0, 1.75, 180.0, {"kind": "drive_lane", "lane": "main_westbound", "speed": 5.0})]
CROSSING = [_add("passenger_car", 1.75, -40.0, 90.0, {"kind": "drive_lane", "lane": "campus_northbound", "speed": 5.0})]
NEAR_KERB = [_add("pedestrian", -20.0, -6.0, 90.0)]
BEHIND_VAN = [_add("truck", -22.0, 2.4, 180.0), _add("pedestrian", -19.0, 6.5, -90.0)]
LEFT_LANE = [_add("passenger_car", -50.0, 1.75, 0.0,
                  {"kind": "follow_path", "waypoints": [[-50.0, 1.75], [90.0, 1.75]], "speed": 8.0})]


@dataclass(frozen=True)
class Expected:
    """One storyboard event the description must leave: its actor, manoeuvre and start."""

    actor: str
    manoeuvre: str
    start: str
    action: dict[str, Any] = field(default_factory=dict)  # fields the manoeuvre must have
    condition: dict[str, Any] = field(default_factory=dict)  # fields the start condition must have


CATALOGUE: list[tuple[str, list[dict[str, Any]], str, list[Expected]]] = [
    ("ncap_ccrb", LEAD, "Car-to-car rear, braking: the leading vehicle decelerates at 4 m/s² once the ego has "
     "closed to 12 m.", [Expected("passenger_car_3", "stop", "distance", {"deceleration": 4.0}, {"distance": 12.0})]),
    ("nhtsa_lead_stopping", LEAD, "3 seconds into the run the vehicle ahead of the ego comes to a standstill.",
     [Expected("passenger_car_3", "stop", "simulation_time", condition={"time": 3.0})]),
    ("ncap_cpna", NEAR_KERB, "A pedestrian on the near-side kerb walks across the road when the ego is 25 metres "
     "from them.", [Expected("pedestrian_1", "cross_road", "distance", condition={"actor": "ego", "distance": 25.0})]),
    ("ncap_cpnc_obstructed", BEHIND_VAN, "A child runs out from behind the parked van in front of the ego.",
     [Expected("pedestrian_1", "cross_road", "distance", condition={"actor": "ego"})]),
    ("nhtsa_ltap_od", ONCOMING, "The oncoming vehicle turns left across the ego's path as the ego reaches the main "
     "intersection.", [Expected("passenger_car_3", "junction_turn", "reach_position", {"turn": "left"}, {"actor": "ego"})]),
    ("nhtsa_straight_crossing_paths", CROSSING, "The car coming up Campus Drive drives straight through the junction.",
     [Expected("passenger_car_3", "junction_turn", "simulation_time", {"turn": "straight"})]),
    ("xosc_cut_in", LEFT_LANE, "After 4 s the car in the left lane merges into the ego's lane 10 m ahead of it.",
     [Expected("passenger_car_3", "cut_in", "simulation_time", {"target": "ego", "gap": 10.0}, {"time": 4.0})]),
    ("ncap_elk_oncoming", ONCOMING, "The oncoming car drifts into the ego's lane when the two are 40 m apart.",
     [Expected("passenger_car_3", "lane_change", "distance", {"side": "left"}, {"distance": 40.0})]),
    ("xosc_slow_preceding", LEAD, "The lead car slows to 10 km/h once the ego is within 30 m.",
     [Expected("passenger_car_3", "change_speed", "distance", condition={"distance": 30.0})]),
    ("ncap_pedestrian_stops_in_lane", NEAR_KERB, "As the ego approaches, the jogger on the kerb steps into the street "
     "and stops in the middle of the lane.", [Expected("pedestrian_1", "stop_mid_road", "distance", condition={"actor": "ego"})]),
    ("ego_lane_change", [], "The ego changes into the left lane 2 s after the start.",
     [Expected("ego", "lane_change", "simulation_time", {"side": "left"}, {"time": 2.0})]),
    ("ncap_ccrb_ttc", LEAD, "When the time to collision between the ego and the lead car falls under 4 s, the lead car "
     "brakes hard.", [Expected("passenger_car_3", "stop", "time_to_collision", {"deceleration": 6.0}, {"seconds": 4.0})]),
    ("xosc_accelerate_then_brake", LEAD, "The lead car accelerates to 12 m/s after 1 s and brakes hard 4 s later.",
     [Expected("passenger_car_3", "change_speed", "simulation_time", {"speed": 12.0}, {"time": 1.0}),
      Expected("passenger_car_3", "stop", "simulation_time", condition={"time": 5.0})]),
    ("lead_brakes_ego_evades", LEAD, "When the ego is 20 m behind it, the car ahead brakes, then the ego moves into the "
     "left lane.", [Expected("passenger_car_3", "stop", "distance", condition={"distance": 20.0}),
                    Expected("ego", "lane_change", "event_end", {"side": "left"})]),
    ("nhtsa_turn_into_path", CROSSING, "Once the ego is 35 metres from it, the crossing car turns right in front of "
     "the ego.", [Expected("passenger_car_3", "junction_turn", "distance", {"turn": "right"}, {"distance": 35.0})]),
]


def _scene(setup: list[dict[str, Any]]) -> Scene:
    return execute(REGISTRY, build_campus(), [ToolCall.model_validate(c) for c in setup]).after


@pytest.mark.parametrize(("setup", "description", "expected"), [c[1:] for c in CATALOGUE], ids=[c[0] for c in CATALOGUE])
def test_a_catalogue_scenario_is_built_as_described(setup: list[dict[str, Any]], description: str,
                                                    expected: list[Expected]) -> None:
    context = PlanContext(scene=_scene(setup), registry=REGISTRY)
    plan = ScenarioReader().plan(description, context)
    assert review(description, plan, context).action == "apply"
    scene = execute(REGISTRY, context.scene, plan.calls).after
    events = list(scene.storyboard.events())
    assert len(events) == len(expected)
    for (actor, event), want in zip(events, expected, strict=True):
        assert actor == want.actor
        assert event.action.kind == want.manoeuvre
        assert event.start.kind == want.start
        assert {name: getattr(event.action, name) for name in want.action} == pytest.approx(want.action)
        assert {name: getattr(event.start, name) for name in want.condition} == pytest.approx(want.condition)


def test_a_catalogue_light_cycle_is_built_in_the_order_given() -> None:
    context = PlanContext(scene=build_campus(), registry=REGISTRY)
    description = "The signal at the crossroads shows red for 30 s, then green for 20 s, then amber for 3 s."
    plan = ScenarioReader().plan(description, context)
    assert review(description, plan, context).action == "apply"
    light = execute(REGISTRY, context.scene, plan.calls).after.storyboard.light("traffic_light_1")
    assert light is not None
    assert [(p.state, p.duration) for p in light.phases] == [("red", 30.0), ("green", 20.0), ("amber", 3.0)]
