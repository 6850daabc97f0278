"""The spatial index answers every surface query exactly as a scan of every part does."""

from __future__ import annotations

import random

import pytest
from drivetwin.worlds import surface
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.opendrive import samples
from drivetwin.worlds.opendrive.package import scene_from_file
from drivetwin.worlds.scene import Scene
from drivetwin.worlds.surface_index import surface_index

POINTS = 400


def scan_lane_at(scene: Scene, x: float, y: float):
    best = None
    for lane in scene.roads.lanes:
        near = surface.nearest_on_polyline(x, y, lane.centreline)
        if near.distance <= lane.width / 2 and (best is None or near.distance < best[0]):
            best = (near.distance, lane)
    return best[1] if best else None


def scan_nearest_lane(scene: Scene, x: float, y: float):
    return min(scene.roads.lanes, key=lambda ln: surface.nearest_on_polyline(x, y, ln.centreline).distance)


def scan_building_at(scene: Scene, x: float, y: float, margin: float):
    for building in scene.buildings:
        if surface.point_in_polygon(x, y, building.footprint):
            return building.name
        ring = [*building.footprint, building.footprint[0]]
        if margin > 0 and surface.nearest_on_polyline(x, y, ring).distance < margin:
            return building.name
    return None


def scan_surface_at(scene: Scene, x: float, y: float) -> str:
    roads = scene.roads
    if scan_building_at(scene, x, y, 0.0):
        return "building"
    if any(surface.nearest_on_polyline(x, y, [c.start, c.end]).distance <= c.width / 2 for c in roads.crossings):
        return "crossing"
    if scan_lane_at(scene, x, y) is not None:
        return "lane"
    if any(surface.point_in_polygon(x, y, a.polygon) for a in roads.paved):
        return "paved"
    if any(surface.nearest_on_polyline(x, y, w.polyline).distance <= w.width / 2 for w in roads.sidewalks):
        return "sidewalk"
    return "ground"


@pytest.fixture(scope="module")
def grid(tmp_path_factory: pytest.TempPathFactory) -> Scene:
    return scene_from_file(samples.grid_town(tmp_path_factory.mktemp("grid") / "grid3.xodr", 3))


def random_points(scene: Scene, seed: int) -> list[tuple[float, float]]:
    rng, b = random.Random(seed), scene.bounds
    # Half anywhere, half right beside lane centrelines, where strips meet and overlap.
    anywhere = [(rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax)) for _ in range(POINTS // 2)]
    beside = []
    for _ in range(POINTS // 2):
        x, y = rng.choice(rng.choice(scene.roads.lanes).centreline)
        beside.append((x + rng.uniform(-3, 3), y + rng.uniform(-3, 3)))
    return anywhere + beside


def test_indexed_lane_at_equals_the_scan_on_a_generated_grid_map(grid):
    for x, y in random_points(grid, 1):
        assert surface.lane_at(grid, x, y) is scan_lane_at(grid, x, y), (x, y)


def test_indexed_nearest_lane_equals_the_scan_on_a_generated_grid_map(grid):
    for x, y in random_points(grid, 2):
        assert surface.nearest_lane(grid, x, y) is scan_nearest_lane(grid, x, y), (x, y)


@pytest.mark.parametrize("world", ["grid", "campus"])
def test_indexed_surface_at_equals_the_scan(grid, world):
    scene = grid if world == "grid" else build_campus()
    for x, y in random_points(scene, 3):
        assert surface.surface_at(scene, x, y) == scan_surface_at(scene, x, y), (x, y)


def test_indexed_building_at_with_a_margin_equals_the_scan():
    campus = build_campus()
    for x, y in random_points(campus, 4):
        assert surface.building_at(campus, x, y, 2.0) == scan_building_at(campus, x, y, 2.0), (x, y)


def test_a_copy_of_a_scene_shares_its_index_and_an_edited_road_gets_a_new_one(grid):
    index = surface_index(grid)
    copy = grid.model_copy(deep=True)
    assert surface_index(copy) is index
    lane = copy.roads.lanes[0]
    lane.centreline = [(x + 50.0, y) for x, y in lane.centreline]
    assert surface_index(copy) is not index
    x, y = lane.centreline[1]
    assert surface.lane_at(copy, x, y) is scan_lane_at(copy, x, y)


def test_a_lane_moved_in_place_is_seen_at_once(grid):
    copy = grid.model_copy(deep=True)
    surface_index(copy)
    lane = copy.roads.lanes[0]
    lane.centreline[:] = [(x, y + 400.0) for x, y in lane.centreline]  # mutated, not reassigned
    x, y = lane.centreline[0]
    assert surface.lane_at(copy, x, y) is lane
