"""Lane connections through a junction box, and sideways-shifted routes (pure geometry)."""

from __future__ import annotations

import math

import pytest
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.routes import NoJunctionError, OffsetRoute, PolylineRoute, junction_route

CAMPUS = build_campus()
LANES = [(lane.id, lane.centreline) for lane in CAMPUS.roads.lanes]
BOXES = [area.polygon for area in CAMPUS.roads.paved if area.kind == "intersection"]


@pytest.mark.parametrize(("turn", "exit_heading"), [("left", math.pi / 2), ("right", -math.pi / 2), ("straight", 0.0)])
def test_a_junction_route_leaves_the_box_on_the_lane_in_the_turned_direction(turn: str, exit_heading: float) -> None:
    route, s_exit = junction_route(LANES, BOXES, -40.0, -1.75, 0.0, turn)
    assert abs(math.remainder(route.heading(s_exit + 1.0) - exit_heading, math.tau)) < 1e-6
    x, y = route.point(s_exit)
    assert max(abs(x), abs(y)) == pytest.approx(9.0, abs=0.01)  # on the box's edge


def test_a_junction_route_is_tangent_to_the_lanes_it_joins() -> None:
    route, s_exit = junction_route(LANES, BOXES, -40.0, -1.75, 0.0, "right")
    s_entry = route.project(-9.0, -1.75)
    assert abs(route.heading(s_entry + 0.1)) < 0.15
    assert abs(math.remainder(route.heading(s_exit - 0.1) + math.pi / 2, math.tau)) < 0.15


def test_no_junction_ahead_is_a_clear_error() -> None:
    with pytest.raises(NoJunctionError, match="no junction ahead on lane main_eastbound"):
        junction_route(LANES, BOXES, 40.0, -1.75, 0.0, "left")


def test_an_offset_route_blends_from_one_offset_to_the_other() -> None:
    base = PolylineRoute([(0.0, 0.0), (100.0, 0.0)])
    shifted = OffsetRoute(base, s_start=10.0, span=20.0, d_from=0.0, d_to=3.5)
    assert shifted.point(5.0) == pytest.approx((5.0, 0.0))
    assert shifted.point(20.0) == pytest.approx((20.0, 1.75))
    assert shifted.point(40.0) == pytest.approx((40.0, 3.5))
