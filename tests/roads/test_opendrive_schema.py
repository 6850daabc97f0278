"""Exported OpenDRIVE files validate against the ASAM OpenDRIVE 1.7 schema scenariogeneration ships."""

from __future__ import annotations

import pytest
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.export.opendrive import OpenDriveError, export_opendrive, validate_opendrive
from drivetwin.worlds.opendrive.package import scene_from_file
from lxml import etree


def test_the_exported_campus_validates(tmp_path):
    validate_opendrive(export_opendrive(build_campus(), tmp_path / "campus.xodr"))


@pytest.mark.parametrize("which", ["tour", "crossroads"])
def test_an_exported_imported_map_validates(tmp_path, maps, which):
    validate_opendrive(export_opendrive(scene_from_file(maps[which]), tmp_path / f"{which}.xodr"))


def test_an_exported_osm_town_validates(tmp_path, town):
    validate_opendrive(export_opendrive(town, tmp_path / "town.xodr"))


def test_a_road_without_its_plan_view_is_refused_in_one_line(tmp_path):
    path = export_opendrive(build_campus(), tmp_path / "campus.xodr")
    tree = etree.parse(str(path))
    road = tree.getroot().find("road")
    road.remove(road.find("planView"))
    tree.write(str(path))
    with pytest.raises(OpenDriveError, match=r"not valid OpenDRIVE 1\.7") as exc:
        validate_opendrive(path)
    assert "\n" not in str(exc.value)
