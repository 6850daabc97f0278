"""Workers place on imported roads; any world exports to OpenDRIVE and reads back the same."""

from __future__ import annotations

import math

import pytest
from drivetwin.tools import ToolCall
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.export.opendrive import export_opendrive
from drivetwin.worlds.opendrive.package import scene_from_file
from drivetwin.worlds.surface import lane_at, nearest_on_polyline

# import(export(world)) must give the same lanes within this many metres.
ROUND_TRIP_M = 0.05


def run(registry, scene, tool, **args):
    result = registry.run(ToolCall(tool=tool, args=args), scene)
    return result, result.edit.apply(scene)


def test_a_car_added_in_a_named_lane_stands_in_that_lane(registry, town):
    lane = next(ln for ln in town.roads.lanes if ln.road == "Oak Avenue" and ln.kind == "driving")
    result, after = run(registry, town, "add_asset", category="car", location={"relation": "in_lane", "target": lane.id})
    car = after.asset(result.data["ids"][0])
    assert lane_at(after, car.pose.x, car.pose.y).id == lane.id


def test_a_cone_added_near_a_named_junction_is_near_it(registry, town):
    result, after = run(registry, town, "add_asset", category="traffic_cone",
                        location={"relation": "next_to", "target": "junction of Main Street and Oak Avenue"})
    cone = after.asset(result.data["ids"][0])
    junction = town.landmark("junction of Main Street and Oak Avenue")
    assert math.dist(cone.pose.xy, junction.position) < 15.0


def test_a_car_added_at_a_road_end_lands_on_that_road(registry, town):
    result, after = run(registry, town, "add_asset", category="car",
                        location={"relation": "at", "target": "north end of Oak Avenue"})
    car = after.asset(result.data["ids"][0])
    assert lane_at(after, car.pose.x, car.pose.y) is not None


def _max_deviation(before, after) -> float:
    worst = 0.0
    assert len(before.roads.lanes) == len(after.roads.lanes)
    for a, b in zip(before.roads.lanes, after.roads.lanes, strict=True):
        assert a.road == b.road and a.width == pytest.approx(b.width, abs=ROUND_TRIP_M)
        worst = max(worst, *(nearest_on_polyline(x, y, b.centreline).distance for x, y in a.centreline))
        assert math.dist(a.centreline[0], b.centreline[0]) < ROUND_TRIP_M  # same direction of travel
    return worst


def test_the_campus_exports_to_opendrive_and_reads_back_the_same_lanes(tmp_path):
    campus = build_campus()
    back = scene_from_file(export_opendrive(campus, tmp_path / "campus.xodr"))
    assert _max_deviation(campus, back) < ROUND_TRIP_M
    assert len(back.roads.sidewalks) == len(campus.roads.sidewalks)


@pytest.mark.parametrize("which", ["tour", "crossroads"])
def test_a_generated_map_round_trips_through_export_within_5_cm(tmp_path, maps, which):
    world = scene_from_file(maps[which])
    back = scene_from_file(export_opendrive(world, tmp_path / f"{which}.xodr"))
    assert _max_deviation(world, back) < ROUND_TRIP_M


def test_elevation_survives_the_round_trip(tmp_path, maps):
    world = scene_from_file(maps["tour"])
    back = scene_from_file(export_opendrive(world, tmp_path / "tour.xodr"))
    for a, b in zip(world.roads.lanes, back.roads.lanes, strict=True):
        assert a.elevation is not None and b.elevation is not None
        assert max(a.elevation) == pytest.approx(max(b.elevation), abs=ROUND_TRIP_M)
