"""A vehicle follows its route in order, steers hard for a point behind it, and stops at its end."""

from __future__ import annotations

import math

import pytest
from drivetwin.evals.trial import fresh_world
from drivetwin.tools.add import new_asset
from drivetwin.worlds.routes import FOLLOW_AHEAD_M, PolylineRoute
from drivetwin.worlds.scene import FollowPath, Pose
from drivetwin.worlds.simulation import Simulation
from drivetwin.worlds.vehicles import pure_pursuit_curvature


def test_a_target_behind_is_steered_for_as_hard_as_one_abeam() -> None:
    """Facing east, a point 4 m away to the south-west turns the vehicle right at full 2/ℓ;
    one dead behind turns it too (sin α would give nothing)."""
    abeam = pure_pursuit_curvature(0.0, 0.0, 0.0, 0.0, -4.0)
    assert pure_pursuit_curvature(0.0, 0.0, 0.0, -4.0 * math.cos(math.pi / 4), -4.0 * math.sin(math.pi / 4)) == (
        pytest.approx(abeam))
    assert abs(pure_pursuit_curvature(0.0, 0.0, 0.0, -4.0, 0.0)) == pytest.approx(0.5)


def test_a_route_that_comes_back_past_itself_is_followed_in_order() -> None:
    """Out along y = 0 and back along y = 3 (a turn back): a vehicle just started on the way out,
    nearer the way back, is still on the way out."""
    route = PolylineRoute([(0.0, 0.0), (30.0, 0.0), (30.0, 3.0), (0.0, 3.0)])
    assert route.project(2.0, 2.0) > 30.0
    s = route.follow(2.0, 2.0, 1.0)
    assert s == pytest.approx(2.0)
    assert route.follow(20.0, 0.0, 1.0) == pytest.approx(1.0 + FOLLOW_AHEAD_M), "no further than it can have gone"


def test_a_car_at_speed_stops_at_the_end_of_its_route() -> None:
    """At 8 m/s it braked only on reaching the end and rolled on some 10 m past it."""
    campus = fresh_world("campus")
    car = new_asset(campus, "passenger_car", set()).model_copy(update={
        "pose": Pose(x=60.0, y=1.75, yaw=math.pi),
        "behaviour": FollowPath(waypoints=[(60.0, 1.75), (20.0, 1.75)], speed=8.0),
    })
    simulation = Simulation(campus.model_copy(update={"assets": [*campus.assets, car]}))
    simulation.run_for(12.0)
    pose = simulation.pose(car.id)
    assert abs(pose.x - 20.0) < 2.0, f"it stopped at x = {pose.x:.1f}, the route ends at 20"
