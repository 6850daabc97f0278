"""Imported roads with elevation are surfaces that MuJoCo vehicles stand and drive on."""

from __future__ import annotations

import pytest
from drivetwin.worlds.catalog import category
from drivetwin.worlds.opendrive.package import scene_from_file
from drivetwin.worlds.scene import AssetInstance, Parked, PhysicsProps, Pose, Scene
from drivetwin.worlds.simulation import Simulation
from drivetwin.worlds.surface import point_along, road_height

# A vehicle's body frame sits on the road; suspension and contact softness move it this much.
ON_ROAD_M = 0.05


@pytest.fixture
def slope(maps) -> Scene:
    """The geometry tour: a road climbing 2 % from z = 0 to about 3 m."""
    return scene_from_file(maps["tour"])


def test_road_height_follows_the_lane_elevation(slope):
    lane = next(ln for ln in slope.roads.lanes if ln.elevation and ln.id.endswith("right1_s1"))
    x, y, _ = point_along(lane.centreline, 0.0)
    assert road_height(slope, x, y) == pytest.approx(lane.elevation[0], abs=0.01)
    assert road_height(slope, slope.bounds.xmin + 1, slope.bounds.ymin + 1) == 0.0  # off the road


def test_a_car_placed_on_the_slope_rests_at_the_roads_height(slope):
    lane = next(ln for ln in slope.roads.lanes if ln.elevation and ln.id.endswith("right1_s1"))
    x, y, yaw = point_along(lane.centreline, 30.0)
    z = road_height(slope, x, y)
    assert z > 1.0  # well above the ground plane: a fall would show
    car = AssetInstance(id="passenger_car_1", category="passenger_car", pose=Pose(x=x, y=y, z=z, yaw=yaw),
                        physics=PhysicsProps(mass=category("passenger_car").mass), behaviour=Parked())
    slope.assets.append(car)
    slope.ego.behaviour = Parked()  # the ego drives this lane: it would push the car
    simulation = Simulation(slope)
    simulation.run_for(2.0)
    pose = simulation.pose(car.id)
    assert pose.z == pytest.approx(road_height(slope, pose.x, pose.y), abs=ON_ROAD_M)
    assert abs(pose.x - x) + abs(pose.y - y) < 0.5  # parked: it does not roll down


def test_a_driving_car_follows_the_slope(slope):
    start = slope.ego.pose
    assert start.z == pytest.approx(road_height(slope, start.x, start.y), abs=0.01)
    simulation = Simulation(slope)
    heights = []
    for _ in range(6):
        simulation.run_for(1.0)
        pose = simulation.pose()
        heights.append((pose.z, road_height(slope, pose.x, pose.y)))
    end = simulation.pose()
    assert abs(end.x - start.x) + abs(end.y - start.y) > 15.0
    assert abs(heights[-1][1] - start.z) > 0.3  # it climbed or descended along the road
    for body, road in heights:
        assert body == pytest.approx(road, abs=ON_ROAD_M)


def test_a_crest_on_a_straight_road_keeps_its_height(tmp_path):
    from scenariogeneration import xodr

    road = xodr.create_road(xodr.Line(100.0), 1, left_lanes=1, right_lanes=1)
    road.add_elevation(0.0, 0.0, 0.1, -0.001, 0.0)  # z = 0.1 s - 0.001 s^2: 2.5 m up at s = 50
    drive = xodr.OpenDrive("crest")
    drive.add_road(road)
    drive.adjust_roads_and_lanes()
    drive.write_xml(str(tmp_path / "crest.xodr"))
    lane = scene_from_file(tmp_path / "crest.xodr").roads.lanes[0]
    assert lane.elevation is not None
    assert max(lane.elevation) == pytest.approx(2.5, abs=0.02)  # a straight line in plan, not in height


def test_a_worker_adds_a_car_onto_the_raised_road_at_its_height(slope, registry):
    from drivetwin.tools.base import ToolCall

    lane = next(ln for ln in slope.roads.lanes if ln.elevation and ln.id.endswith("right1_s1"))
    x, y, _ = point_along(lane.centreline, 30.0)
    where = {"relation": "absolute", "x": x, "y": y}
    result = registry.run(ToolCall(tool="add_asset", args={"category": "passenger_car", "location": where}), slope)
    added = result.edit.ops[0].asset
    assert added.pose.z == pytest.approx(road_height(slope, added.pose.x, added.pose.y), abs=1e-9)
    assert added.pose.z > 1.0
