"""Storyboard manoeuvres played by MuJoCo vehicles and walkers on the campus (no rendering)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import AssetInstance, FollowPath, PhysicsProps, Pose
from drivetwin.worlds.storyboard import (
    ChangeSpeed,
    CutIn,
    DistanceCondition,
    Event,
    EventEndCondition,
    JunctionTurn,
    LaneChange,
    LightPhase,
    SetLight,
    SimulationTimeCondition,
    StopLine,
    StopMidRoad,
    Storyboard,
    TrafficLight,
)
from drivetwin.worlds.surface import DRIVABLE, surface_at
from scenario_worlds import EAST_Y, EGO_ID, WEST_Y, campus_with, simulate, speeds, vehicle

LEAD = "passenger_car_9"
# The west stop line of Main Street eastbound, before the west crossing (x = -11.5 ± 1.5).
EAST_STOP_LINE = (-14.0, EAST_Y)


def _lead_scene(storyboard: Storyboard, lead_x: float = -40.0, speed: float = 6.0) -> object:
    lead = vehicle(LEAD, lead_x, EAST_Y, FollowPath(waypoints=[(lead_x, EAST_Y), (100.0, EAST_Y)], speed=speed))
    return campus_with(lead, storyboard=storyboard)


def test_braking_lead_car_decelerates_at_the_asked_rate() -> None:
    asked = 3.0
    board = Storyboard().with_event(LEAD, Event(
        name="lead_brakes", action=ChangeSpeed(speed=0.0, rate=asked), start=SimulationTimeCondition(time=3.0)))
    simulation = simulate(_lead_scene(board), 7.0)  # type: ignore[arg-type]
    profile = speeds(simulation.trace(LEAD))
    # The straight part of the ramp: after the start transient, before the final creep.
    braking = [(t, v) for t, v in profile if t > 3.3 and 1.0 < v < 5.0]
    assert len(braking) > 20
    times, values = np.array(braking).T
    slope = np.polyfit(times, values, 1)[0]
    assert -slope == pytest.approx(asked, rel=0.10)
    assert profile[-1][1] < 0.1


def test_braking_starts_when_the_ego_comes_within_the_trigger_distance() -> None:
    board = Storyboard().with_event(LEAD, Event(
        name="lead_brakes", action=ChangeSpeed(speed=0.0, rate=4.0),
        start=DistanceCondition(actor=EGO_ID, target=LEAD, distance=15.0)))
    lead = vehicle(LEAD, -30.0, EAST_Y)  # parked 30 m ahead: the ego closes in on it
    simulation = simulate(campus_with(lead, storyboard=board), 5.0)
    started = simulation.player.records["lead_brakes"].started
    assert started is not None
    ego_at_start = next(x for t, x, _, _ in simulation.trace(EGO_ID) if t >= started)
    assert -30.0 - ego_at_start == pytest.approx(15.0, abs=0.5)


def test_lane_change_ends_centred_in_the_target_lane() -> None:
    board = Storyboard().with_event(LEAD, Event(
        name="overtake", action=LaneChange(side="left", over="time", value=3.0),
        start=SimulationTimeCondition(time=2.0)))
    simulation = simulate(_lead_scene(board), 8.0)  # type: ignore[arg-type]
    record = simulation.player.records["overtake"]
    assert record.ended is not None
    _, _, y, yaw = simulation.trace(LEAD)[-1]
    assert y == pytest.approx(WEST_Y, abs=0.25)
    assert abs(yaw) < 0.05


def test_cut_in_leaves_the_asked_gap_ahead_of_the_ego() -> None:
    gap = 8.0
    cutter = vehicle(LEAD, -45.0, WEST_Y, FollowPath(waypoints=[(-45.0, WEST_Y), (100.0, WEST_Y)], speed=7.0))
    board = Storyboard().with_event(LEAD, Event(
        name="cut_in", action=CutIn(target=EGO_ID, gap=gap, duration=3.0), start=SimulationTimeCondition(time=2.0)))
    simulation = simulate(campus_with(cutter, storyboard=board, ego_x=-60.0), 9.0)
    ended = simulation.player.records["cut_in"].ended
    assert ended is not None
    cut = {round(t, 2): (x, y) for t, x, y, _ in simulation.trace(LEAD)}
    ego = {round(t, 2): x for t, x, _, _ in simulation.trace(EGO_ID)}
    x, y = cut[round(ended, 2)]
    bumpers = (category("passenger_car").length + category("ego_vehicle").length) / 2
    assert x - ego[round(ended, 2)] - bumpers == pytest.approx(gap, abs=1.0)
    assert y == pytest.approx(EAST_Y, abs=0.35)


def _footprint(asset: AssetInstance, x: float, y: float, yaw: float) -> list[tuple[float, float]]:
    shape = category(asset.category)
    half_l, half_w = shape.length / 2, shape.width / 2
    c, s = math.cos(yaw), math.sin(yaw)
    return [(x + dx * c - dy * s, y + dx * s + dy * c) for dx in (-half_l, half_l) for dy in (-half_w, half_w)]


@pytest.mark.parametrize(("turn", "exit_check"), [
    ("right", lambda x, y: y < -12.0 and abs(x + 1.75) < 0.5),
    ("left", lambda x, y: y > 12.0 and abs(x - 1.75) < 0.5),
    ("straight", lambda x, y: x > 12.0 and abs(y - EAST_Y) < 0.5),
])
def test_a_junction_turn_stays_on_the_paved_junction_and_leaves_by_the_asked_lane(turn: str, exit_check: object) -> None:
    car = vehicle(LEAD, -25.0, EAST_Y)
    board = Storyboard().with_event(LEAD, Event(name="turn", action=JunctionTurn(turn=turn, speed=4.0)))  # type: ignore[arg-type]
    scene = campus_with(car, storyboard=board, ego_x=-90.0, ego_speed=1.0)
    simulation = simulate(scene, 11.0)
    trace = simulation.trace(LEAD)
    for _, x, y, yaw in trace:
        for corner in _footprint(car, x, y, yaw):
            assert surface_at(scene, *corner) in DRIVABLE, f"corner {corner} of {LEAD} left the road"
    _, x, y, _ = trace[-1]
    assert exit_check(x, y)  # type: ignore[operator]


def test_the_ego_stops_before_a_red_light() -> None:
    light = TrafficLight(light="traffic_light_1", phases=[LightPhase(state="red", duration=60.0)],
                         stop_lines=[StopLine(lane="main_eastbound", position=EAST_STOP_LINE)])
    simulation = simulate(campus_with(storyboard=Storyboard(lights=[light]), ego_x=-40.0), 9.0)
    front = category("ego_vehicle").length / 2
    assert max(x for _, x, _, _ in simulation.trace(EGO_ID)) + front < EAST_STOP_LINE[0]
    assert speeds(simulation.trace(EGO_ID))[-1][1] < 0.1
    assert simulation.player.light_states["traffic_light_1"] == "red"


def test_a_light_set_green_by_an_event_lets_the_stopped_ego_go() -> None:
    light = TrafficLight(light="traffic_light_1", phases=[LightPhase(state="red", duration=60.0)],
                         stop_lines=[StopLine(lane="main_eastbound", position=EAST_STOP_LINE)])
    board = Storyboard(lights=[light]).with_event(None, Event(
        name="turn_green", action=SetLight(light="traffic_light_1", state="green"),
        start=SimulationTimeCondition(time=7.0)))
    simulation = simulate(campus_with(storyboard=board, ego_x=-40.0), 10.0)
    assert simulation.player.light_states["traffic_light_1"] == "green"
    assert simulation.trace(EGO_ID)[-1][1] > EAST_STOP_LINE[0]


def test_a_pedestrian_stops_mid_road_and_a_chained_event_follows() -> None:
    walker = AssetInstance(id="pedestrian_9", category="pedestrian", pose=Pose(x=-20.0, y=-6.0),
                           physics=PhysicsProps(mass=category("pedestrian").mass))
    board = Storyboard().with_event("pedestrian_9", Event(
        name="step_out", action=StopMidRoad(start=(-20.0, -6.0), end=(-20.0, 6.0), fraction=0.5),
        start=SimulationTimeCondition(time=0.5)))
    board = board.with_event(LEAD, Event(
        name="lead_slows", action=ChangeSpeed(speed=2.0, rate=2.0), start=EventEndCondition(event="step_out")))
    simulation = simulate(campus_with(walker, vehicle(LEAD, 40.0, EAST_Y), storyboard=board, ego_x=-90.0), 7.0)
    _, x, y, _ = simulation.trace("pedestrian_9")[-1]
    assert (x, y) == pytest.approx((-20.0, 0.0), abs=0.05)
    walked, slowed = simulation.player.records["step_out"], simulation.player.records["lead_slows"]
    assert walked.ended is not None and slowed.started == walked.ended


def test_a_manoeuvre_the_actor_cannot_do_is_reported_and_changes_nothing() -> None:
    walker = AssetInstance(id="pedestrian_9", category="pedestrian", pose=Pose(x=-20.0, y=-6.0),
                           physics=PhysicsProps(mass=category("pedestrian").mass))
    board = Storyboard().with_event("pedestrian_9", Event(name="bad", action=LaneChange(side="left")))
    simulation = simulate(campus_with(walker, storyboard=board), 0.5)
    assert "cannot lane_change" in (simulation.player.records["bad"].failed or "")
    assert simulation.trace("pedestrian_9") == []


def test_an_edited_storyboard_starts_its_clock_when_it_reaches_the_live_world() -> None:
    scene = _lead_scene(Storyboard())
    simulation = simulate(scene, 2.0)  # type: ignore[arg-type]
    board = Storyboard().with_event(LEAD, Event(
        name="lead_brakes", action=ChangeSpeed(speed=0.0, rate=3.0), start=SimulationTimeCondition(time=1.0)))
    simulation.apply(scene.model_copy(update={"storyboard": board}))  # type: ignore[attr-defined]
    simulation.run_for(1.5)
    started = simulation.player.records["lead_brakes"].started
    assert started == pytest.approx(1.0, abs=0.05)  # one second after the edit, not at t = 1 s
    assert simulation.player.start_time == pytest.approx(2.0, abs=0.01)
