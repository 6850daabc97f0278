"""A driving vehicle that is placed or moved drives the lane it now stands in, or parks off lanes."""

from __future__ import annotations

from collections.abc import Callable

import pytest
from drivetwin.tools import ToolResult
from drivetwin.worlds.scene import AssetInstance, DriveLane, Parked, Scene

Caller = Callable[..., ToolResult]


def _after(call: Caller, scene: Scene, tool: str, asset: str, **args: object) -> AssetInstance:
    moved = call(scene, tool, asset=asset, **args).edit.apply(scene).asset(asset)
    assert moved is not None
    return moved


def _driving_car(call: Caller, scene: Scene, lane: str, speed: float) -> tuple[Scene, str]:
    result = call(scene, "add_asset", category="passenger_car",
                  behaviour={"kind": "drive_lane", "lane": lane, "speed": speed})
    return result.edit.apply(scene), result.data["ids"][0]


def test_the_ego_placed_in_another_lane_drives_that_lane(call: Caller, campus: Scene) -> None:
    ego = _after(call, campus, "place_asset", "ego",
                 location={"relation": "in_lane", "target": "campus_northbound"})
    assert ego.behaviour == DriveLane(lane="campus_northbound", speed=5.0)


def test_the_ego_placed_at_the_east_gate_facing_west_drives_westbound(call: Caller, campus: Scene) -> None:
    ego = _after(call, campus, "place_asset", "ego",
                 location={"relation": "at", "target": "east gate"}, yaw_deg=180.0)
    assert isinstance(ego.behaviour, DriveLane) and ego.behaviour.lane == "main_westbound"


def test_a_driving_car_moved_into_the_other_lane_drives_it_at_its_old_speed(call: Caller, campus: Scene) -> None:
    scene, car = _driving_car(call, campus, "main_eastbound", 7.0)
    moved = _after(call, scene, "move_asset", car, north=3.5, turn_deg=180.0)
    assert moved.behaviour == DriveLane(lane="main_westbound", speed=7.0)


def test_a_driving_car_put_ahead_of_a_landmark_along_another_lane_drives_that_lane(
    call: Caller, campus: Scene
) -> None:
    scene, car = _driving_car(call, campus, "campus_southbound", 6.0)
    moved = _after(call, scene, "move_asset", car, relative_to="east gate", along_m=-20.0)
    assert isinstance(moved.behaviour, DriveLane) and moved.behaviour.lane.startswith("main_")


def test_a_driving_car_placed_in_a_parking_lot_is_parked_there(call: Caller, campus: Scene) -> None:
    scene, car = _driving_car(call, campus, "main_eastbound", 5.0)
    result = call(scene, "place_asset", asset=car, location={"relation": "at", "target": "parking lot B"})
    parked = result.edit.apply(scene).asset(car)
    assert parked is not None and isinstance(parked.behaviour, Parked)
    assert "parked" in result.text


def test_a_driving_car_turned_against_its_lane_is_turned_and_parked(call: Caller, campus: Scene) -> None:
    result = call(campus, "move_asset", asset="ego", turn_deg=180.0)
    ego = result.edit.apply(campus).ego
    assert ego.pose.yaw == pytest.approx(3.14159265, abs=1e-6)
    assert isinstance(ego.behaviour, Parked)
    assert "against the traffic of main_eastbound" in result.text


def test_a_driving_car_turned_across_its_lane_still_drives_it(call: Caller, campus: Scene) -> None:
    ego = _after(call, campus, "move_asset", "ego", turn_deg=90.0)
    assert ego.behaviour == DriveLane(lane="main_eastbound", speed=5.0)


def test_a_driving_car_moved_along_its_lane_keeps_its_lane(call: Caller, campus: Scene) -> None:
    ego = _after(call, campus, "move_asset", "ego", forward=20.0)
    assert ego.behaviour == DriveLane(lane="main_eastbound", speed=5.0)
