"""Reading OpenDRIVE maps: geometry, lanes, junctions, crossings, signals, elevation."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drivetwin.worlds.opendrive.reader import MapReadError, read_opendrive
from lxml import etree


def test_the_tour_map_holds_every_plan_view_geometry(maps):
    kinds = {child.tag for g in etree.parse(str(maps["tour"])).getroot().iter("geometry") for child in g}
    assert kinds == {"line", "spiral", "arc", "paramPoly3", "poly3"}


def test_driving_lanes_follow_traffic_right_lanes_along_the_reference_line(maps):
    lanes = {lane.key: lane for lane in read_opendrive(maps["tour"]).lanes}
    right, left = lanes[("1", 0, -1)], lanes[("1", 0, 1)]
    assert right.points[0, 0] < right.points[-1, 0]  # the road starts at x = 0 heading east
    assert left.points[0, 0] > left.points[-1, 0]
    assert right.kind == left.kind == "driving" and lanes[("1", 0, -2)].kind == "sidewalk"


def test_a_lane_section_of_changing_width_keeps_its_mean_width(maps):
    lanes = {lane.key: lane for lane in read_opendrive(maps["tour"]).lanes}
    assert lanes[("1", 0, -1)].width == pytest.approx(3.5, abs=0.01)
    # 3.0 m widening 1 cm per metre over the second section's ~90 m: mean ~3.45 m.
    assert 3.3 < lanes[("1", 1, -1)].width < 3.6


def test_elevation_is_read_along_the_lane(maps):
    lane = next(lane for lane in read_opendrive(maps["tour"]).lanes if lane.key == ("1", 1, -1))
    assert lane.points[-1, 2] > 2.5  # 2 % over ~150 m
    assert np.all(np.diff(lane.points[:, 2]) >= -1e-9)


def test_junction_lanes_connect_the_arms(maps):
    road_map = read_opendrive(maps["crossroads"])
    junction_lanes = [lane for lane in road_map.lanes if lane.junction == "100"]
    assert len(junction_lanes) == 12  # 6 connecting roads, both ways
    arm = next(lane for lane in road_map.lanes if lane.key == ("1", 0, 1))
    assert len(arm.successors) == 3  # straight on, left and right
    assert {road_map.road_names[r] for r in road_map.junctions[0].incoming_roads} == {"Main Street", "Oak Avenue"}


def test_a_crosswalk_object_becomes_a_crossing_across_the_road(maps):
    (crossing,) = read_opendrive(maps["crossroads"]).crossings
    assert math.dist(crossing.start, crossing.end) == pytest.approx(7.0)
    assert crossing.width == pytest.approx(3.0)


def test_a_dynamic_signal_becomes_a_traffic_light(maps):
    (prop,) = read_opendrive(maps["crossroads"]).props
    assert prop.category == "traffic_light"


def test_a_file_that_is_not_opendrive_is_refused_in_one_line(tmp_path):
    bad = tmp_path / "bad.xodr"
    bad.write_text("<OpenDRIVE><road", encoding="utf-8")
    with pytest.raises(MapReadError, match="not an XML file") as exc:
        read_opendrive(bad)
    assert "\n" not in str(exc.value)
