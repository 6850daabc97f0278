"""Road marks of imported maps: derived from the lanes, drawn in the hybrid renderer's frames."""

from __future__ import annotations

import numpy as np
import pytest
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.hybrid import HybridRenderer
from drivetwin.worlds.render.look import world_points
from drivetwin.worlds.road_marks import road_marks
from drivetwin.worlds.scene import Environment, Lane, RoadNetwork, Scene
from drivetwin.worlds.surface import point_along, point_in_polygon, polyline_length
from shapely import LineString, MultiLineString, Point

# A mark pixel's ground point lies within this of its mark: half the line plus a pixel or two.
ON_MARK_M = 0.25


def test_a_two_way_street_gets_a_yellow_centre_line_and_white_edges(town):
    marks = road_marks(town)
    main_street = {lane.id for lane in town.roads.lanes if lane.road == "Main Street"}
    kinds = [m.kind for m in marks if m.id.rsplit("/", 1)[0] in main_street]
    # One lane each way on three blocks: each block has one shared centre line, two edges.
    assert sorted(kinds) == ["centre"] * 3 + ["edge"] * 6
    assert all(m.rgba[2] < 0.5 * m.rgba[1] for m in marks if m.kind == "centre")  # yellow
    assert all(min(m.rgba[:3]) > 0.9 for m in marks if m.kind == "edge")  # white


def _two_lanes_each_way() -> Scene:
    """Four straight lanes along x: two eastbound (y = -1.75, -5.25), two westbound."""
    campus = build_campus()
    lanes = [Lane(id=f"east{k}", road="Broad Street", centreline=[(-80.0, -1.75 - 3.5 * k), (80.0, -1.75 - 3.5 * k)])
             for k in range(2)]
    lanes += [Lane(id=f"west{k}", road="Broad Street", centreline=[(80.0, 1.75 + 3.5 * k), (-80.0, 1.75 + 3.5 * k)])
              for k in range(2)]
    return campus.model_copy(update={"roads": RoadNetwork(lanes=lanes)})


def test_lanes_of_one_direction_are_parted_by_a_dashed_white_divider():
    marks = {m.id: m for m in road_marks(_two_lanes_each_way())}
    assert {m.kind for m in marks.values()} == {"edge", "divider", "centre"}
    assert marks["east0/right"].kind == "divider" and marks["west0/right"].kind == "divider"
    assert marks["east1/right"].kind == "edge" and marks["west1/right"].kind == "edge"
    assert [m.kind for m in marks.values()].count("centre") == 1  # painted once, by one of the pair
    dashes = marks["east0/right"].pieces
    assert len(dashes) == pytest.approx(160 / 9, abs=1)  # 3 m of paint every 9 m
    assert all(LineString([p[:2] for p in piece]).length == pytest.approx(3.0, abs=0.01) for piece in dashes[1:-1])


def test_no_mark_is_painted_inside_a_junction(town):
    junctions = [area.polygon for area in town.roads.paved if area.kind == "intersection"]
    for mark in road_marks(town):
        for piece in mark.pieces:
            inside = [p for p in piece if any(point_in_polygon(p[0], p[1], j) for j in junctions)]
            assert not inside, mark.id


def _top_down_camera(town) -> Camera:
    lane = next(ln for ln in town.roads.lanes if ln.road == "Main Street" and ln.kind == "driving")
    x, y, _ = point_along(lane.centreline, polyline_length(lane.centreline) * 0.3)
    return Camera.from_look_at((x, y - 0.01, 22.0), (x, y, 0.0), width=320, height=240, fovy_deg=30.0)


@pytest.fixture
def frame_and_ground(town):
    renderer = HybridRenderer(MujocoWorld.from_scene(town))
    camera = _top_down_camera(town)
    frame = renderer.render(camera, Environment(time_of_day="12:00"))
    hit = np.isfinite(frame.depth)
    ground = world_points(np.where(hit, frame.depth, 0.0), camera)
    return frame.rgb.astype(float) / 255.0, hit, ground


def _lines(town, kind):
    return MultiLineString([[p[:2] for p in piece] for m in road_marks(town) if m.kind == kind for piece in m.pieces])


def test_the_rendered_frame_shows_the_yellow_centre_line_where_it_projects(town, frame_and_ground):
    rgb, hit, ground = frame_and_ground
    yellow = (rgb[..., 0] > 0.45) & (rgb[..., 1] > 0.35) & (rgb[..., 2] < 0.5 * rgb[..., 1]) & hit
    assert yellow.sum() > 50
    centre = _lines(town, "centre")
    ys, xs = np.nonzero(yellow)
    far = [centre.distance(Point(ground[y, x, :2])) for y, x in zip(ys, xs, strict=True)]
    assert np.median(far) < ON_MARK_M and np.mean(np.array(far) < ON_MARK_M) > 0.9


def test_the_rendered_frame_shows_white_lines_on_the_lane_edges(town, frame_and_ground):
    rgb, hit, ground = frame_and_ground
    white = (rgb.min(axis=-1) > 0.88) & hit  # brighter than the concrete of the sidewalks
    assert white.sum() > 50
    painted = _lines(town, "edge").union(_lines(town, "divider"))
    ys, xs = np.nonzero(white)
    near = np.array([painted.distance(Point(ground[y, x, :2])) < ON_MARK_M for y, x in zip(ys, xs, strict=True)])
    assert near.mean() > 0.9
