"""measure_distance: how far apart two things or places are, and which way; find_lanes' lengths."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from drivetwin.tools import NotFoundError, ToolResult
from drivetwin.tools.errors import ToolArgumentError
from drivetwin.worlds.scene import Scene

Caller = Callable[..., ToolResult]


def test_two_landmarks_are_measured_in_a_straight_line_with_the_way_between(call: Caller, campus: Scene) -> None:
    result = call(campus, "measure_distance", a="Library entrance", b="fountain")
    # The Library entrance is at (-41, -15), the fountain at (75, 40).
    assert result.data["metres"] == pytest.approx(math.hypot(116.0, 55.0), abs=0.01)
    assert result.text.startswith("from Library entrance to fountain: 128.4 m in a straight line, to the north-east")


def test_the_other_end_defaults_to_the_ego(call: Caller, campus: Scene) -> None:
    result = call(campus, "measure_distance", a="bench_1")
    ego, bench = campus.asset("ego"), campus.asset("bench_1")
    assert ego is not None and bench is not None
    assert result.data["to"] == "ego"
    assert result.data["metres"] == pytest.approx(math.dist((ego.pose.x, ego.pose.y), (bench.pose.x, bench.pose.y)), abs=0.01)


def test_an_area_also_gives_the_distance_to_its_edge(call: Caller, campus: Scene) -> None:
    result = call(campus, "measure_distance", a="parking lot A", b="main gate")
    assert "m from the edge of the area" in result.text
    centre = result.data["metres"]
    edge = float(result.text.rsplit("; ", 1)[1].split(" m ")[0])
    assert edge < centre


def test_an_unknown_end_or_the_same_end_twice_is_refused(call: Caller, campus: Scene) -> None:
    with pytest.raises(NotFoundError):
        call(campus, "measure_distance", a="the gym", b="fountain")
    with pytest.raises(ToolArgumentError):
        call(campus, "measure_distance", a="fountain", b="fountain")


def test_lanes_are_listed_with_width_and_length(call: Caller, campus: Scene) -> None:
    result = call(campus, "find_lanes", road="Main Street")
    lane = campus.roads.lane("main_eastbound")
    assert lane is not None
    length = sum(math.dist(p, q) for p, q in zip(lane.centreline, lane.centreline[1:], strict=False))
    assert f"main_eastbound on Main Street, heading 0 deg, {lane.width:g} m wide, {length:.0f} m long" in result.text
