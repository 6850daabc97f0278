"""Driving vehicles start where they were asked for, spaced along their lane, and drive it."""

from __future__ import annotations

import itertools
from collections.abc import Callable

import pytest
from drivetwin.tools import RuleViolation, ToolResult
from drivetwin.tools.along import DRIVING_GAP_M, LANE_ENTRY_M
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import AssetInstance, DriveLane, Scene
from drivetwin.worlds.simulation import Simulation
from drivetwin.worlds.surface import lane_at, nearest_on_polyline

Caller = Callable[..., ToolResult]
DRIVE = {"kind": "drive_lane"}


def _add(call: Caller, scene: Scene, **args: object) -> tuple[Scene, list[AssetInstance]]:
    result = call(scene, "add_asset", **args)
    after = result.edit.apply(scene)
    added = [after.asset(i) for i in result.data["ids"]]
    assert all(a is not None for a in added)
    return after, [a for a in added if a is not None]


def _lane_id(scene: Scene, asset: AssetInstance) -> str | None:
    lane = lane_at(scene, asset.pose.x, asset.pose.y)
    return lane.id if lane else None


def test_a_car_driving_a_named_lane_starts_in_that_lane_near_its_start(call: Caller, campus: Scene) -> None:
    _, [car] = _add(call, campus, category="passenger_car",
                    behaviour={"kind": "drive_lane", "lane": "campus_northbound"})
    assert _lane_id(campus, car) == "campus_northbound"
    assert car.pose.y == pytest.approx(-90.0 + LANE_ENTRY_M)
    assert isinstance(car.behaviour, DriveLane) and car.behaviour.lane == "campus_northbound"


def test_several_driving_cars_in_one_lane_are_spaced_along_it(call: Caller, campus: Scene) -> None:
    _, cars = _add(call, campus, category="passenger_car", count=3,
                   behaviour={"kind": "drive_lane", "lane": "campus_southbound"})
    lane = campus.roads.lane("campus_southbound")
    assert lane is not None
    arcs = sorted(nearest_on_polyline(c.pose.x, c.pose.y, lane.centreline).arc_length for c in cars)
    needed = category("passenger_car").length + DRIVING_GAP_M
    assert all(b - a >= needed - 1e-6 for a, b in itertools.pairwise(arcs))
    assert all(_lane_id(campus, c) == "campus_southbound" for c in cars)


def test_a_second_driving_car_in_a_later_request_is_not_refused_as_overlapping(call: Caller, campus: Scene) -> None:
    scene, [first] = _add(call, campus, category="passenger_car", behaviour=DRIVE)
    _, [second] = _add(call, scene, category="passenger_car", behaviour=DRIVE)
    assert (first.pose.x, first.pose.y) != (second.pose.x, second.pose.y)


def test_a_driving_car_near_a_place_starts_in_the_lane_nearest_it(call: Caller, campus: Scene) -> None:
    _, [car] = _add(call, campus, category="passenger_car", behaviour=DRIVE,
                    location={"relation": "at", "target": "east gate"})
    assert _lane_id(campus, car) in ("main_eastbound", "main_westbound")
    assert car.pose.x > 85.0


def test_a_driving_car_at_coordinates_in_a_lane_starts_exactly_there(call: Caller, campus: Scene) -> None:
    _, [car] = _add(call, campus, category="passenger_car", behaviour=DRIVE,
                    location={"relation": "absolute", "x": -30.0, "y": 1.5})
    assert (car.pose.x, car.pose.y) == (-30.0, 1.5)
    assert isinstance(car.behaviour, DriveLane) and car.behaviour.lane == "main_westbound"


def test_a_driving_car_at_coordinates_off_every_lane_is_refused(call: Caller, campus: Scene) -> None:
    with pytest.raises(RuleViolation, match=r"\(-30, 8\) is not in lane main_westbound"):
        call(campus, "add_asset", category="passenger_car", behaviour=DRIVE,
             location={"relation": "absolute", "x": -30.0, "y": 8.0})


def test_a_spawned_driving_car_drives_along_its_lane_in_mujoco(call: Caller, campus: Scene) -> None:
    scene, [car] = _add(call, campus, category="passenger_car",
                        behaviour={"kind": "drive_lane", "lane": "campus_northbound", "speed": 5.0})
    sim = Simulation(scene)
    sim.run_for(4.0)
    pose = sim.pose(car.id)
    assert pose.y - car.pose.y > 10.0, "it should have driven north along its lane"
    assert abs(pose.x - car.pose.x) < 0.5, "and stayed on the lane's centreline"


@pytest.mark.parametrize("rider", ["bicycle", "motorcycle"])
def test_a_rider_can_ride_a_lane_and_a_pedestrian_cannot(call: Caller, campus: Scene, rider: str) -> None:
    scene, (added,) = _add(call, campus, category=rider, behaviour={**DRIVE, "lane": "campus_northbound"})
    assert added.behaviour == DriveLane(lane="campus_northbound", speed=added.behaviour.speed)
    assert _lane_id(scene, added) == "campus_northbound"
    with pytest.raises(RuleViolation, match="a pedestrian cannot drive_lane"):
        call(campus, "add_asset", category="pedestrian", behaviour=DRIVE)


def test_only_movers_follow_a_path(call: Caller, campus: Scene) -> None:
    """A tree or a cone given a route to walk is refused; a pedestrian or a car may take one."""
    walk = {"kind": "follow_path", "to": "fountain"}
    for fixed in ("tree_1", "fire_hydrant_1"):
        with pytest.raises(RuleViolation, match="cannot follow a path"):
            call(campus, "set_behaviour", asset=fixed, behaviour=walk)
    scene, (walker,) = _add(call, campus, category="pedestrian", location={"relation": "at", "target": "bus stop"})
    result = call(scene, "set_behaviour", asset=walker.id, behaviour=walk)
    moved = result.edit.apply(scene).asset(walker.id)
    assert moved is not None and moved.behaviour is not None and moved.behaviour.kind == "follow_path"


def test_things_near_an_area_are_measured_to_its_edge(call: Caller, campus: Scene) -> None:
    """Inside a lot is 0 m from it, as measure_distance has it, not the metres to the lot's middle."""
    found = call(campus, "find_assets", category="passenger_car", near="parking lot B", within=1.0)
    assert set(found.data["ids"]) == {"passenger_car_1", "passenger_car_2"}
    assert all(d == 0.0 for d in found.data["distances"].values())
