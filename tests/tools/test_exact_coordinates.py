"""Explicit coordinates are honoured exactly or refused with the reason, never silently moved."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from drivetwin.tools import RuleViolation, ToolArgumentError, ToolResult
from drivetwin.worlds.scene import Scene

Caller = Callable[..., ToolResult]


def _at(x: float, y: float) -> dict[str, object]:
    return {"relation": "absolute", "x": x, "y": y}


def test_a_cone_at_coordinates_stands_exactly_there(call: Caller, campus: Scene) -> None:
    result = call(campus, "add_asset", category="traffic_cone", location=_at(12.0, -3.0))
    cone = result.edit.apply(campus).asset(result.data["ids"][0])
    assert cone is not None and (cone.pose.x, cone.pose.y) == (12.0, -3.0)


def test_coordinates_inside_a_building_are_refused_naming_it(call: Caller, campus: Scene) -> None:
    with pytest.raises(RuleViolation, match="inside JTEKT Building"):
        call(campus, "add_asset", category="traffic_cone", location=_at(40.0, 30.0))


def test_coordinates_outside_the_world_are_refused_with_its_bounds(call: Caller, campus: Scene) -> None:
    with pytest.raises(RuleViolation, match=r"outside the world; allowed: x in \[-110, 110\]"):
        call(campus, "add_asset", category="traffic_cone", location=_at(500.0, 0.0))


def test_a_car_on_grass_is_refused_not_moved_to_a_road(call: Caller, campus: Scene) -> None:
    with pytest.raises(RuleViolation, match=r"must stand on a road.*\(60.0, 60.0\) is ground"):
        call(campus, "add_asset", category="passenger_car", location=_at(60.0, 60.0))


@pytest.mark.parametrize(("value", "message"), [
    (math.nan, "must be a finite number"),
    (math.inf, "must be a finite number"),
    (1e9, "must be within ±10000 m"),
])
def test_non_finite_or_huge_numbers_are_refused_with_a_clear_message(
    call: Caller, campus: Scene, value: float, message: str
) -> None:
    with pytest.raises(ToolArgumentError, match=message):
        call(campus, "add_asset", category="traffic_cone", location=_at(value, 0.0))


def test_place_asset_at_coordinates_moves_it_exactly_there(call: Caller, campus: Scene) -> None:
    result = call(campus, "place_asset", asset="bench_1", location=_at(-20.0, -7.0))
    bench = result.edit.apply(campus).asset("bench_1")
    assert bench is not None and (bench.pose.x, bench.pose.y) == (-20.0, -7.0)


def test_a_move_by_a_non_finite_distance_is_refused(call: Caller, campus: Scene) -> None:
    with pytest.raises(ToolArgumentError, match="forward"):
        call(campus, "move_asset", asset="bench_1", forward=math.nan)
