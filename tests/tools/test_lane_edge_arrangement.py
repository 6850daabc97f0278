"""A lane-edge arrangement lines the lane asked for, from where it was asked to start."""

from __future__ import annotations

from collections.abc import Callable

import pytest
from drivetwin.tools import RuleViolation, ToolResult
from drivetwin.worlds.scene import AssetInstance, Scene
from drivetwin.worlds.surface import lane_at

Caller = Callable[..., ToolResult]


def _cones(call: Caller, scene: Scene, count: int, **location: object) -> list[AssetInstance]:
    result = call(scene, "arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=count,
                  location=location)
    after = result.edit.apply(scene)
    cones = [after.asset(i) for i in result.data["ids"]]
    return [c for c in cones if c is not None]


def _lanes(scene: Scene, cones: list[AssetInstance]) -> set[str | None]:
    return {getattr(lane_at(scene, c.pose.x, c.pose.y), "id", None) for c in cones}


def test_a_lane_edge_by_a_landmark_lines_the_lane_named_not_the_nearest(call: Caller, campus: Scene) -> None:
    cones = _cones(call, campus, 4, relation="in_lane", target="east gate", lane="main_westbound")
    assert _lanes(campus, cones) == {"main_westbound"}
    assert all(c.pose.x > 85.0 for c in cones)


def test_a_lane_edge_with_at_and_a_lane_lines_that_lane(call: Caller, campus: Scene) -> None:
    cones = _cones(call, campus, 4, relation="at", target="east gate", lane="main_westbound")
    assert _lanes(campus, cones) == {"main_westbound"}


def test_a_long_row_said_to_start_ahead_of_the_ego_is_never_moved_back_behind_it(call: Caller, campus: Scene) -> None:
    # 6 cones 10 m apart from 15 m ahead run into the crossroads; the row may move on, never back past the ego
    cones = _cones(call, campus, 6, relation="in_lane", target="ego", along_m=15.0, lane="main_eastbound")
    assert min(c.pose.x for c in cones) >= campus.ego.pose.x + 15.0 - 1e-6


def test_a_lane_edge_along_m_ahead_of_the_ego_starts_that_far_ahead(call: Caller, campus: Scene) -> None:
    cones = _cones(call, campus, 3, relation="at", target="ego", along_m=30.0)
    assert min(c.pose.x for c in cones) == pytest.approx(campus.ego.pose.x + 30.0)
    assert _lanes(campus, cones) == {"main_eastbound"}


def test_a_lane_edge_on_the_left_side_keeps_to_the_lanes_left_edge(call: Caller, campus: Scene) -> None:
    cones = _cones(call, campus, 3, relation="in_lane", target="main_eastbound", side="left")
    assert all(-1.75 < c.pose.y < 0.0 for c in cones)


def test_a_lane_edge_at_coordinates_starts_there_not_at_the_ego(call: Caller, campus: Scene) -> None:
    cones = _cones(call, campus, 3, relation="absolute", x=50.0, y=-2.0)
    assert min(c.pose.x for c in cones) == pytest.approx(50.0)


def test_a_lane_edge_of_a_lane_far_from_its_target_is_refused(call: Caller, campus: Scene) -> None:
    with pytest.raises(RuleViolation, match="campus_northbound passes 98 m from east gate"):
        _cones(call, campus, 4, relation="in_lane", target="east gate", lane="campus_northbound")
