"""A line in front of or behind something runs across its path as asked: closed up or refused, never turned."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from drivetwin.tools import RuleViolation, ToolResult
from drivetwin.worlds.scene import Scene

Caller = Callable[..., ToolResult]
ACROSS = math.pi / 2  # the ego faces east (yaw 0): across its path is north-south


def _line(call: Caller, scene: Scene, category: str, count: int, **more: object) -> ToolResult:
    return call(scene, "arrange_assets", categories=[category], shape="line", count=count,
                location={"relation": "in_front_of", "target": "ego"}, **more)


def test_a_long_line_across_the_road_closes_up_to_fit_and_says_so(call: Caller, campus: Scene) -> None:
    result = _line(call, campus, "traffic_cone", 15)
    after = result.edit.apply(campus)
    cones = [a for i in result.data["ids"] if (a := after.asset(i)) is not None]
    assert len(cones) == 15 and all(abs(c.pose.yaw - ACROSS) < 1e-6 for c in cones)
    assert "closed up to" in result.text


def test_a_line_across_the_road_that_cannot_fit_is_refused_not_turned(call: Caller, campus: Scene) -> None:
    with pytest.raises(RuleViolation, match="line of 5 road_barrier across the path in front of ego does not fit"):
        _line(call, campus, "road_barrier", 5)


def test_a_line_across_with_its_spacing_said_keeps_that_spacing_or_is_refused(call: Caller, campus: Scene) -> None:
    with pytest.raises(RuleViolation, match=r"does not fit, even 0\.86 m apart"):
        _line(call, campus, "traffic_cone", 15, spacing=0.86)


def test_a_line_with_no_direction_that_is_turned_to_fit_says_so(call: Caller, campus: Scene) -> None:
    result = call(campus, "arrange_assets", categories=["road_barrier"], shape="line", count=5,
                  location={"relation": "at", "target": "east gate"})
    assert "turned a quarter" in result.text
