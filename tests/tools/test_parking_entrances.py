"""The campus parking lots' entrance landmarks, where their driveways meet Main Street."""

from __future__ import annotations

from collections.abc import Callable

import pytest
from drivetwin.tools import ToolResult
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.scene import Scene
from drivetwin.worlds.surface import DRIVABLE, lane_at, surface_at

Caller = Callable[..., ToolResult]


@pytest.mark.parametrize("name", ["parking lot A entrance", "entrance of lot A", "lot A entrance"])
def test_lot_a_entrance_is_found_by_its_name_and_aliases(campus: Scene, name: str) -> None:
    landmark = campus.landmark(name)
    assert landmark is not None and landmark.name == "parking lot A entrance"


@pytest.mark.parametrize(("entrance", "lot"), [("parking lot A entrance", "parking lot A"),
                                               ("parking lot B entrance", "parking lot B")])
def test_an_entrance_joins_its_lot_to_the_road_over_drivable_paving(campus: Scene, entrance: str, lot: str) -> None:
    mark, area = campus.landmark(entrance), campus.landmark(lot)
    assert mark is not None and area is not None and area.polygon is not None
    x, y = mark.position
    edge_y = min(p[1] for p in area.polygon) if y < area.position[1] else max(p[1] for p in area.polygon)
    # Walk from the road edge to the lot: every step is drivable, and the start touches a lane.
    steps = 20
    for k in range(steps + 1):
        py = y + (edge_y - y) * k / steps
        assert surface_at(campus, x, py) in DRIVABLE, (x, py)
    assert lane_at(campus, x, y - 0.5 if y > 0 else y + 0.5) is not None


def test_the_shipped_campus_file_matches_its_generator(campus: Scene) -> None:
    assert campus == build_campus()


def test_a_car_added_at_lot_b_entrance_stands_on_drivable_ground(call: Caller, campus: Scene) -> None:
    result = call(campus, "add_asset", category="passenger_car",
                  location={"relation": "at", "target": "entrance of lot B"})
    car = result.edit.apply(campus).asset(result.data["ids"][0])
    assert car is not None
    assert surface_at(campus, car.pose.x, car.pose.y) in DRIVABLE
    assert abs(car.pose.x - 47.0) < 6.0
