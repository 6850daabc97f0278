import json
import math
from pathlib import Path

import jsonschema
import pytest
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.catalog import catalog, nearest_categories, resolve_category
from drivetwin.worlds.defaults import UnknownWorldError, list_worlds, load_world
from drivetwin.worlds.scene import Pose, Scene, SceneFileError, scene_json_schema
from drivetwin.worlds.surface import surface_at
from pydantic import ValidationError


def test_saved_scene_loads_back_identical(campus, tmp_path):
    path = tmp_path / "s.json"
    campus.save(path)
    assert Scene.load(path) == campus


def test_saved_scene_validates_against_the_published_schema(campus):
    jsonschema.validate(json.loads(campus.to_json()), scene_json_schema())


def test_shipped_campus_json_matches_its_builder():
    shipped = Path(__file__).parents[2] / "worlds" / "data" / "campus.json"
    assert Scene.load(shipped) == build_campus()


def test_campus_has_the_landmarks_the_paper_uses(campus):
    for name in ("JTEKT building entrance", "main gate", "parking lot B"):
        assert campus.landmark(name) is not None
    assert len(campus.landmarks) >= 10
    assert len(campus.buildings) >= 3 and campus.roads.crossings and campus.roads.sidewalks


def test_campus_assets_stand_on_surfaces_their_category_allows(campus):
    for asset in campus.all_assets():
        ground = surface_at(campus, asset.pose.x, asset.pose.y)
        assert ground != "building", asset.id
        if catalog()[asset.category].placement == "drivable":
            assert ground in ("lane", "paved", "crossing"), asset.id


def test_a_corrupted_save_file_is_a_clear_error(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"name": "x", "bounds": ', encoding="utf-8")
    with pytest.raises(SceneFileError, match="not valid JSON"):
        Scene.load(bad)
    bad.write_text('{"name": "x"}', encoding="utf-8")
    with pytest.raises(SceneFileError, match="not a valid scene"):
        Scene.load(bad)


def test_nan_and_far_coordinates_are_refused():
    with pytest.raises(ValidationError):
        Pose(x=math.nan, y=0.0)
    with pytest.raises(ValidationError):
        Pose(x=1e9, y=0.0)


def test_time_of_day_must_be_a_clock_time(campus):
    with pytest.raises(ValidationError):
        campus.environment.model_validate({"time_of_day": "25:00"})


def test_catalog_has_twenty_categories_with_real_sizes():
    cats = catalog()
    required = {"passenger_car", "suv", "bus", "truck", "traffic_cone", "road_barrier", "cement_rubble",
                "pedestrian", "pedestrian_sign", "stop_sign", "street_light", "traffic_light", "bicycle",
                "trash_bin", "tree", "bench", "fire_hydrant", "construction_sign", "ackermann_robot",
                "ego_vehicle"}
    assert required <= set(cats) and len(cats) >= 20
    assert 4.0 < cats["passenger_car"].length < 5.0 and cats["bus"].mass > 5000


def test_synonyms_and_plurals_resolve_to_categories():
    assert resolve_category("pylons") == "traffic_cone"
    assert resolve_category("Lorry") == "truck"
    assert resolve_category("tank") is None
    assert nearest_categories("trafic con")[0] == "traffic_cone"


def test_worlds_are_listed_and_loaded_by_name(tmp_path, monkeypatch):
    assert "campus" in [w.name for w in list_worlds()]
    mine = build_campus().model_copy(update={"name": "mine"})
    mine.save(tmp_path / "mine.json")
    monkeypatch.setenv("DRIVETWIN_WORLDS", str(tmp_path))
    assert load_world("mine").name == "mine"
    with pytest.raises(UnknownWorldError, match="known worlds: campus"):
        load_world("atlantis")
