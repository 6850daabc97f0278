"""A vehicle sent to a place (follow_path `to`) drives there by the lanes, clear of what stands still."""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable

import pytest
from drivetwin.tools import ToolResult
from drivetwin.tools.locate import resolve_target
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import AssetInstance, FollowPath, Scene
from drivetwin.worlds.simulation import Simulation
from drivetwin.worlds.surface import nearest_on_polyline

Caller = Callable[..., ToolResult]
# "Got there": within a few metres (a car going to a door stops short of the wall behind it).
REACHED_M = 4.0
# Simulated seconds a car at the default 4 m/s gets for a trip of up to about 200 m.
TRIP_S = 70.0


def _send(call: Caller, scene: Scene, start: str, goal: str) -> tuple[Scene, AssetInstance]:
    result = call(scene, "add_asset", category="passenger_car", location={"relation": "at", "target": start},
                  behaviour={"kind": "follow_path", "to": goal})
    after = result.edit.apply(scene)
    car = after.asset(result.data["ids"][0])
    assert car is not None and isinstance(car.behaviour, FollowPath)
    return after, car


def _closest_approach(scene: Scene, car: AssetInstance, place: str) -> float:
    """How near (m) the car came to `place` in at most TRIP_S simulated seconds."""
    target = resolve_target(scene, place)
    simulation = Simulation(scene)
    nearest = math.inf
    for _ in range(int(TRIP_S / 5.0)):
        simulation.run_for(5.0)
        nearest = min([nearest, *(math.dist((x, y), (target.x, target.y)) for _, x, y, _ in simulation.trace(car.id))])
        if nearest <= REACHED_M:
            break
    return nearest


@pytest.mark.parametrize(("start", "goal"), [
    ("Library entrance", "east gate"),  # the straight line ran into street_light_8 and stalled there
    ("main gate", "Student Union entrance"),  # a right turn at the crossroads; straight on is the Library
])
def test_a_car_sent_to_a_place_gets_there_in_mujoco(call: Caller, campus: Scene, start: str, goal: str) -> None:
    scene, car = _send(call, campus, start, goal)
    nearest = _closest_approach(scene, car, goal)
    assert nearest <= REACHED_M, f"{car.id} came no nearer than {nearest:.1f} m to the {goal}"


def test_a_car_leaving_the_library_drop_off_keeps_clear_of_the_street_lights(call: Caller, campus: Scene) -> None:
    _, car = _send(call, campus, "Library entrance", "east gate")
    assert isinstance(car.behaviour, FollowPath)
    half_width = category(car.category).width / 2
    for light in (a for a in campus.assets if a.category == "street_light"):
        for a, b in itertools.pairwise(car.behaviour.waypoints):
            assert nearest_on_polyline(light.pose.x, light.pose.y, [a, b]).distance > half_width + 1.0, light.id


def test_a_car_sent_to_a_place_drives_along_the_lane_that_leads_there(call: Caller, campus: Scene) -> None:
    _, car = _send(call, campus, "Library entrance", "east gate")
    assert isinstance(car.behaviour, FollowPath)
    on_eastbound = [p for p in car.behaviour.waypoints if p[1] == pytest.approx(-1.75)]
    assert on_eastbound and max(x for x, _ in on_eastbound) - min(x for x, _ in on_eastbound) > 100.0
    assert car.behaviour.waypoints[-1] == pytest.approx((100.0, 0.0))
