"""Behaviours run in the loop: skidpad circles, lane driving, parking, crossing, jaywalking."""

from __future__ import annotations

import math

import numpy as np
from conftest import fit_circle, make_asset, make_scene
from drivetwin.worlds.routes import PolylineRoute
from drivetwin.worlds.scene import (
    Circle,
    Crossing,
    CrossRoad,
    DriveLane,
    Jaywalk,
    Lane,
    Parked,
    RoadNetwork,
)
from drivetwin.worlds.simulation import Simulation

# An ego out of the way of the lane tests (the default one waits in the eastbound lane).
PARKED_AWAY = make_asset("ego", "ego_vehicle", 80.0, 40.0)
# The skidpad must come within this share of the asked radius (the project's done-when).
RADIUS_TOLERANCE = 0.10


def test_skidpad_robot_drives_a_circle_of_the_asked_radius() -> None:
    radius, speed = 5.0, 2.0
    robot = make_asset(
        "robot",
        "ackermann_robot",
        3.0,
        12.0,
        -math.pi / 2,
        behaviour=Circle(centre=(8.0, 12.0), radius=radius, speed=speed),
    )
    sim = Simulation(make_scene(robot))
    lap = 2 * math.pi * radius / speed
    settle = 3.0
    sim.run_for(settle + 1.25 * lap)
    trace = np.array(sim.trace("robot"))
    lap_points = trace[trace[:, 0] >= settle][:, 1:3]
    turned = np.unwrap(np.arctan2(lap_points[:, 1] - 12.0, lap_points[:, 0] - 8.0))
    assert abs(turned[-1] - turned[0]) >= 2 * math.pi, "recorded less than one lap"
    cx, cy, fitted = fit_circle(lap_points)
    assert abs(fitted - radius) <= RADIUS_TOLERANCE * radius
    assert math.hypot(cx - 8.0, cy - 12.0) <= RADIUS_TOLERANCE * radius
    steps = np.linalg.norm(np.diff(trace[:, 1:3], axis=0), axis=1) / np.diff(trace[:, 0])
    assert abs(np.median(steps[-50:]) - speed) < 0.1 * speed


def test_clockwise_circle_turns_right() -> None:
    robot = make_asset(
        "robot",
        "ackermann_robot",
        5.0,
        0.0,
        -math.pi / 2,
        behaviour=Circle(centre=(0.0, 0.0), radius=5.0, speed=2.0, clockwise=True),
    )
    sim = Simulation(make_scene(robot))
    sim.run_for(4.0)
    trace = np.array(sim.trace("robot"))
    angles = np.unwrap(np.arctan2(trace[:, 2], trace[:, 1]))
    assert angles[-1] < angles[0] - 1.0


def test_jaywalker_crosses_the_ego_lane_ahead_of_the_ego_and_away_from_the_crossing() -> None:
    crossing = Crossing(id="zebra", start=(40.0, -6.0), end=(40.0, 6.0))
    walker = make_asset(
        "jaywalker",
        "pedestrian",
        0.0,
        -6.0,
        math.pi / 2,
        behaviour=Jaywalk(start=(0.0, -6.0), end=(0.0, 6.0), speed=1.8, trigger_distance=20.0),
    )
    ego = make_asset("ego", "ego_vehicle", -30.0, -1.75, behaviour=DriveLane(lane="east", speed=5.0))
    scene = make_scene(walker, ego=ego)
    scene.roads.crossings.append(crossing)
    sim = Simulation(scene)
    sim.run_for(1.0)
    assert sim.pose("jaywalker").y == -6.0, "the jaywalker left the kerb before the ego came near"
    crossed = None
    while sim.time < 12.0:
        sim.run_for(0.02)
        walker_pose, ego_pose = sim.pose("jaywalker"), sim.pose("ego")
        if walker_pose.y >= -1.75:  # the ego lane's centreline is y = -1.75
            crossed = (walker_pose.x, ego_pose.x, ego_pose.y)
            break
    assert crossed is not None, "the jaywalker never crossed the ego lane"
    walker_x, ego_x, ego_y = crossed
    assert ego_x < walker_x, "the jaywalker crossed behind the ego"
    assert walker_x - ego_x < 25.0, "it crossed long before the ego came near"
    assert abs(ego_y + 1.75) < 0.2, "the ego left its lane"
    assert abs(walker_x - crossing.start[0]) > crossing.width / 2, "it walked on the crossing"


def test_cross_road_walker_waits_for_its_start_time_then_walks_at_its_speed() -> None:
    walker = make_asset(
        "walker",
        "pedestrian",
        10.0,
        -6.0,
        behaviour=CrossRoad(start=(10.0, -6.0), end=(10.0, 6.0), speed=1.5, start_time=1.0),
    )
    sim = Simulation(make_scene(walker))
    sim.run_for(0.9)
    assert sim.pose("walker").y == -6.0
    sim.run_for(3.1)
    assert math.isclose(sim.pose("walker").y, -6.0 + 1.5 * 3.0, abs_tol=0.1)
    sim.run_for(10.0)
    assert sim.pose("walker").y == 6.0, "it should stop at the far kerb"


def _curved_lane() -> Lane:
    """A straight, a 90° left bend of 30 m radius sampled every 3°, and another straight."""
    points = [(-60.0, -30.0)]
    for k in range(31):
        angle = -math.pi / 2 + math.radians(3 * k)
        points.append((30.0 * math.cos(angle), 30.0 * math.sin(angle)))
    points.append((30.0, 60.0))
    return Lane(id="bend", road="ring", centreline=points)


def test_drive_lane_car_stays_within_half_a_metre_of_the_centreline() -> None:
    lane = _curved_lane()
    car = make_asset("car", "passenger_car", -40.0, -30.0, behaviour=DriveLane(lane="bend", speed=8.0))
    scene = make_scene(car)
    scene.roads = RoadNetwork(lanes=[lane])
    sim = Simulation(scene)
    sim.run_for(13.0)
    trace = np.array(sim.trace("car"))
    route = PolylineRoute(lane.centreline)
    errors = [route.distance_to(x, y) for _, x, y, _ in trace]
    assert max(errors) < 0.5
    assert trace[-1, 2] > 10.0, "the car should be past the bend"


def test_a_cyclist_riding_a_lane_keeps_to_its_centreline_at_its_speed() -> None:
    lane = _curved_lane()
    bike = make_asset("bike", "bicycle", -40.0, -30.0, behaviour=DriveLane(lane="bend", speed=4.0))
    scene = make_scene(bike, ego=PARKED_AWAY)
    scene.roads = RoadNetwork(lanes=[lane])
    sim = Simulation(scene)
    sim.run_for(10.0)
    trace = np.array(sim.trace("bike"))
    route = PolylineRoute(lane.centreline)
    assert max(route.distance_to(x, y) for _, x, y, _ in trace) < 0.1, "a rider is placed on its route"
    travelled = route.project(trace[-1, 1], trace[-1, 2]) - route.project(-40.0, -30.0)
    assert math.isclose(travelled, 40.0, rel_tol=0.1), f"rode {travelled:.1f} m in 10 s at 4 m/s"


def test_drive_lane_loops_back_to_the_start_of_an_open_lane() -> None:
    car = make_asset("car", "passenger_car", 90.0, -1.75, behaviour=DriveLane(lane="east", speed=6.0))
    sim = Simulation(make_scene(car))
    sim.run_for(3.0)
    pose = sim.pose("car")
    assert pose.x < -80.0 and abs(pose.y + 1.75) < 0.3


def test_parked_car_drifts_less_than_five_centimetres_in_five_seconds() -> None:
    car = make_asset("car", "passenger_car", 10.0, 8.0, 0.7)
    sim = Simulation(make_scene(car))
    sim.run_for(5.0)
    pose = sim.pose("car")
    assert math.hypot(pose.x - 10.0, pose.y - 8.0) < 0.05
    assert abs(pose.yaw - 0.7) < 0.01


def test_a_parked_vehicle_stops_when_its_behaviour_becomes_parked() -> None:
    car = make_asset("car", "passenger_car", -50.0, -1.75, behaviour=DriveLane(lane="east", speed=6.0))
    scene = make_scene(car)
    sim = Simulation(scene)
    sim.run_for(3.0)
    parked = scene.model_copy(deep=True)
    car_asset = parked.asset("car")
    assert car_asset is not None
    car_asset.behaviour = Parked()
    sim.apply(parked)
    sim.run_for(4.0)
    before = sim.pose("car").x
    sim.run_for(1.0)
    assert abs(sim.pose("car").x - before) < 0.05


def test_a_lane_car_stops_short_of_a_barrier_in_its_lane_and_leaves_it_where_it_was() -> None:
    car = make_asset("car", "passenger_car", -60.0, -1.75, behaviour=DriveLane(lane="east", speed=8.0))
    barrier = make_asset("barrier", "road_barrier", -30.0, -1.75, math.pi / 2)
    sim = Simulation(make_scene(car, barrier, ego=PARKED_AWAY))
    sim.run_for(10.0)
    front = sim.pose("car").x + 4.5 / 2
    barrier_face = -30.0 - 0.5 / 2
    assert 0.5 < barrier_face - front < 4.0, "the car should wait a couple of metres short of the barrier"
    moved = sim.pose("barrier")
    assert math.hypot(moved.x + 30.0, moved.y + 1.75) < 0.01, "nothing should have hit the barrier"


def test_a_lane_car_passes_a_barrier_on_the_sidewalk_at_full_speed() -> None:
    car = make_asset("car", "passenger_car", -60.0, -1.75, behaviour=DriveLane(lane="east", speed=8.0))
    barrier = make_asset("barrier", "road_barrier", -30.0, -6.5)
    sim = Simulation(make_scene(car, barrier, ego=PARKED_AWAY))
    sim.run_for(8.0)
    assert sim.pose("car").x > -30.0 + 10.0
