"""Placement N m ahead of / behind a target along its lane or sidewalk, on the left or right."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from drivetwin.tools import RuleViolation, ToolResult
from drivetwin.worlds.scene import AssetInstance, Scene
from drivetwin.worlds.surface import lane_at, surface_at

Caller = Callable[..., ToolResult]
EGO_X, EGO_Y = -60.0, -1.75  # the campus ego, in main_eastbound, facing east


def _added(call: Caller, scene: Scene, **args: object) -> AssetInstance:
    result = call(scene, "add_asset", **args)
    asset = result.edit.apply(scene).asset(result.data["ids"][0])
    assert asset is not None
    return asset


def test_a_cone_ten_metres_ahead_of_the_ego_on_the_right_stands_at_the_right_edge_of_its_lane(
    call: Caller, campus: Scene
) -> None:
    cone = _added(call, campus, category="traffic_cone",
                  location={"relation": "in_front_of", "target": "ego", "along_m": 10, "side": "right"})
    assert cone.pose.x == pytest.approx(EGO_X + 10.0)
    assert cone.pose.y < EGO_Y - 1.0  # right of an eastbound lane is south
    lane = lane_at(campus, cone.pose.x, cone.pose.y)
    assert lane is not None and lane.id == "main_eastbound"


def test_a_car_behind_the_ego_stands_on_its_lane_centreline_facing_the_same_way(call: Caller, campus: Scene) -> None:
    car = _added(call, campus, category="passenger_car",
                 location={"relation": "behind", "target": "ego", "along_m": 15})
    assert (car.pose.x, car.pose.y) == pytest.approx((EGO_X - 15.0, EGO_Y))
    assert car.pose.yaw == pytest.approx(0.0)


def test_ahead_of_a_landmark_follows_the_lane_that_runs_its_way(call: Caller, campus: Scene) -> None:
    # The main gate faces east; both Main Street lanes pass it equally near.
    car = _added(call, campus, category="passenger_car",
                 location={"relation": "at", "target": "main gate", "along_m": 10})
    lane = lane_at(campus, car.pose.x, car.pose.y)
    assert lane is not None and lane.id == "main_eastbound"
    assert car.pose.x == pytest.approx(-90.0)


def test_a_pedestrian_ahead_of_the_ego_on_the_left_goes_onto_the_left_sidewalk(call: Caller, campus: Scene) -> None:
    walker = _added(call, campus, category="pedestrian",
                    location={"relation": "at", "target": "ego", "along_m": 10, "side": "left"})
    assert surface_at(campus, walker.pose.x, walker.pose.y) == "sidewalk"
    assert walker.pose.y > 3.5 and walker.pose.x == pytest.approx(EGO_X + 10.0)


def test_ahead_follows_a_vehicle_facing_against_its_polyline(call: Caller, campus: Scene) -> None:
    # A car in main_westbound drives west: ahead of it is further west.
    car = _added(call, campus, category="passenger_car", location={"relation": "absolute", "x": 30.0, "y": 1.75})
    scene = campus.model_copy(update={"assets": [*campus.assets, car]})
    cone = _added(call, scene, category="traffic_cone",
                  location={"relation": "at", "target": car.id, "along_m": 8})
    assert cone.pose.x == pytest.approx(22.0) and cone.pose.y == pytest.approx(1.75)


def test_further_ahead_than_the_lane_runs_is_refused_saying_how_far_it_goes(call: Caller, campus: Scene) -> None:
    with pytest.raises(RuleViolation, match="runs on only 170 m ahead of ego; ask for at most 170 m"):
        call(campus, "add_asset", category="passenger_car", location={"target": "ego", "along_m": 190})


def test_place_asset_puts_an_existing_car_behind_the_ego_along_its_lane(call: Caller, campus: Scene) -> None:
    result = call(campus, "place_asset", asset="passenger_car_1",
                  location={"relation": "behind", "target": "ego", "along_m": 12})
    car = result.edit.apply(campus).asset("passenger_car_1")
    assert car is not None and (car.pose.x, car.pose.y) == pytest.approx((EGO_X - 12.0, EGO_Y))


def test_move_asset_relative_to_puts_a_car_ahead_of_the_ego_on_its_left_lane_edge(call: Caller, campus: Scene) -> None:
    result = call(campus, "move_asset", asset="passenger_car_1", relative_to="ego", along_m=20,
                  side="left", offset_m=0.5)
    car = result.edit.apply(campus).asset("passenger_car_1")
    assert car is not None
    assert (car.pose.x, car.pose.y) == pytest.approx((EGO_X + 20.0, EGO_Y + 0.5))
    assert math.cos(car.pose.yaw) == pytest.approx(1.0)


def test_a_blocked_spot_shifts_along_the_lane_not_across_it(call: Caller, campus: Scene) -> None:
    first = _added(call, campus, category="road_barrier",
                   location={"relation": "at", "target": "ego", "along_m": 10})
    scene = campus.model_copy(update={"assets": [*campus.assets, first]})
    second = _added(call, scene, category="road_barrier",
                    location={"relation": "at", "target": "ego", "along_m": 10})
    assert second.pose.y == pytest.approx(EGO_Y)
    assert abs(second.pose.x - (EGO_X + 10.0)) <= 4.0


def test_ahead_of_the_ego_in_a_lane_named_goes_in_that_lane(call: Caller, campus: Scene) -> None:
    cone = _added(call, campus, category="traffic_cone",
                  location={"relation": "in_lane", "target": "ego", "lane": "main_westbound", "along_m": 10})
    assert cone.pose.x == pytest.approx(EGO_X + 10.0)  # ahead is the way the ego faces
    lane = lane_at(campus, cone.pose.x, cone.pose.y)
    assert lane is not None and lane.id == "main_westbound"
