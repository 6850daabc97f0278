"""Importing map files as worlds that load by name."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
from drivetwin.worlds.defaults import list_worlds, load_world
from drivetwin.worlds.opendrive.package import MapImportError, import_map


def test_worlds_import_builds_a_world_that_loads_by_name(user_data, town_file):
    result = CliRunner().invoke(main, ["worlds", "import", str(town_file), "--name", "town"])
    assert result.exit_code == 0, result.output
    assert (user_data / "worlds" / "town" / "world.json").is_file()
    assert (user_data / "worlds" / "town" / "map.xodr").is_file()
    assert json.loads((user_data / "worlds" / "town" / "import.json").read_text())["kind"] == "osm"
    assert load_world("town").roads.lanes
    listed = CliRunner().invoke(main, ["worlds", "list"])
    assert "town" in listed.output and "Imported from the OpenStreetMap file town.osm" in listed.output


def test_an_opendrive_file_imports_with_its_lanes(user_data, maps):
    report = import_map(maps["crossroads"], "crossroads")
    assert report.lanes == 20 and report.junctions == 1 and report.crossings == 1
    assert {entry.name for entry in list_worlds()} >= {"campus", "crossroads"}


def test_a_world_name_may_be_a_map_file(town_file):
    assert load_world(str(town_file)).landmark("junction of Main Street and Oak Avenue") is not None


def test_osm_streets_become_named_lanes_sidewalks_and_crossings(town):
    roads = {lane.road for lane in town.roads.lanes}
    assert {"Main Street", "Oak Avenue", "Elm Street", "Mill Lane"} <= roads
    main_lanes = [lane for lane in town.roads.lanes if lane.road == "Main Street"]
    assert len(main_lanes) >= 4  # two lanes each way (lanes=2 in OSM)
    assert town.roads.sidewalks and town.roads.crossings


def test_junctions_roads_and_road_ends_are_landmarks(town):
    for name in ("junction of Main Street and Oak Avenue", "corner of Main Street and Oak Avenue",
                 "junction of Mill Lane and Oak Avenue", "Main Street", "north end of Oak Avenue",
                 "the west end of Main Street"):
        assert town.landmark(name) is not None, name
    north, south = town.landmark("north end of Oak Avenue"), town.landmark("south end of Oak Avenue")
    assert north.position[1] > south.position[1] + 250  # Oak Avenue runs 330 m north-south


def test_osm_buildings_and_amenities_are_buildings_and_landmarks(town):
    names = {b.name for b in town.buildings}
    assert {"Town Hall", "St. Mary's Church", "City Library", "Market Hall"} <= names
    assert len(town.buildings) == 6  # and the two unnamed houses
    hall = town.landmark("Town Hall")
    assert hall.kind == "area"
    assert town.landmark("Cafe Central") is not None


def test_traffic_signals_become_traffic_light_props(town):
    lights = [a for a in town.assets if a.category == "traffic_light"]
    assert lights and all(not a.physics.dynamic for a in lights)


def test_the_real_osm_extract_imports(user_data):
    from pathlib import Path

    report = import_map(Path(__file__).parents[1] / "data" / "spreewaldring.osm", "ring")
    assert report.lanes >= 10 and report.buildings == 3


@pytest.mark.parametrize(("name", "message"), [("Town Hall", "lower-case"), ("campus", "shipped world")])
def test_a_bad_world_name_is_refused_and_nothing_is_written(user_data, town_file, name, message):
    with pytest.raises(MapImportError, match=message):
        import_map(town_file, name)
    assert not (user_data / "worlds").exists() or not any((user_data / "worlds").iterdir())


def test_a_file_that_is_not_a_map_is_refused(user_data, tmp_path):
    text = tmp_path / "notes.txt"
    text.write_text("hello", encoding="utf-8")
    result = CliRunner().invoke(main, ["worlds", "import", str(text), "--name", "notes"])
    assert result.exit_code != 0 and "ends in .xodr (OpenDRIVE) or .osm" in result.output


def test_importing_over_an_existing_world_needs_replace(user_data, maps):
    import_map(maps["crossroads"], "x")
    with pytest.raises(MapImportError, match="--replace"):
        import_map(maps["crossroads"], "x")
    assert import_map(maps["crossroads"], "x", replace=True).lanes == 20


def test_a_road_landmark_is_an_area_covering_all_its_blocks(town):
    from drivetwin.worlds.surface import point_in_polygon

    main = town.landmark("Main Street")
    assert main.kind == "area"
    lanes = [lane for lane in town.roads.lanes if lane.road == "Main Street"]
    assert len(lanes) == 6  # three blocks between junctions, both ways
    assert all(point_in_polygon(x, y, main.polygon) for lane in lanes for x, y in lane.centreline[1:-1])
    assert not point_in_polygon(*town.landmark("Town Hall").position, main.polygon)
