"""find_landmarks / find_assets: nearest-to an asset, place or x,y, and assets standing on lanes."""

from __future__ import annotations

import math
from collections.abc import Callable

import pytest
from drivetwin.tools import NotFoundError, ToolResult
from drivetwin.worlds.scene import Scene

Caller = Callable[..., ToolResult]



def test_nearest_landmark_to_the_ego_is_named_with_its_distance(call: Caller, campus: Scene) -> None:
    result = call(campus, "find_landmarks", nearest_to="ego")
    # The ego starts at (-60, -1.75); parking lot A's nearest corner is (-70, 14).
    assert result.data["names"][0] == "parking lot A"
    assert result.data["distances"]["parking lot A"] == pytest.approx(math.hypot(10.0, 15.75), abs=0.01)
    assert result.text.startswith("nearest landmark to ego: parking lot A, 18.7 m away")


def test_nearest_landmark_to_a_landmark_leaves_the_landmark_itself_out(call: Caller, campus: Scene) -> None:
    result = call(campus, "find_landmarks", nearest_to="west crosswalk")
    assert "west crosswalk" not in result.data["names"]
    assert result.data["names"][0] == "main intersection"


def test_nearest_landmark_to_coordinates(call: Caller, campus: Scene) -> None:
    result = call(campus, "find_landmarks", nearest_to="x=74 y=38")
    assert result.data["names"][0] == "fountain"


def test_closest_car_to_the_fountain_is_named_with_its_distance(call: Caller, campus: Scene) -> None:
    result = call(campus, "find_assets", category="car", nearest_to="fountain")
    # Cars stand at (19, -42) and (27, -42); the fountain is at (75, 40).
    assert result.data["ids"][0] == "passenger_car_2"
    assert result.data["distances"]["passenger_car_2"] == pytest.approx(math.hypot(48.0, 82.0), abs=0.01)
    assert "nearest car to fountain: passenger_car_2, 95.0 m away" in result.text


def test_nearest_asset_to_an_asset_leaves_that_asset_out(call: Caller, campus: Scene) -> None:
    result = call(campus, "find_assets", category="passenger_car", nearest_to="passenger_car_1")
    assert result.data["ids"] == ["passenger_car_2"]


def test_nearest_to_coordinates_outside_the_world_is_refused(call: Caller, campus: Scene) -> None:
    with pytest.raises(Exception, match="outside the world"):
        call(campus, "find_assets", nearest_to="500, 0")


def _with_cones(call: Caller, campus: Scene) -> Scene:
    in_lane = call(campus, "add_asset", category="traffic_cone",
                   location={"relation": "absolute", "x": 1.75, "y": -40.0})
    scene = in_lane.edit.apply(campus)
    on_walk = call(scene, "add_asset", category="trash_bin",
                   location={"relation": "absolute", "x": 5.5, "y": -40.0})
    return on_walk.edit.apply(scene)


def test_on_lane_lists_only_assets_standing_on_a_lane(call: Caller, campus: Scene) -> None:
    scene = _with_cones(call, campus)
    result = call(scene, "find_assets", on_lane=True)
    assert "traffic_cone_1" in result.data["ids"]  # in campus_northbound
    assert "trash_bin_2" not in result.data["ids"]  # on the sidewalk
    assert result.data["lanes"]["traffic_cone_1"] == "campus_northbound"
    assert "street_light_1" not in result.data["ids"]


def test_a_lane_named_by_a_word_lists_what_is_in_it(call: Caller, campus: Scene) -> None:
    scene = _with_cones(call, campus)
    result = call(scene, "find_assets", lane="northbound")
    assert result.data["ids"] == ["traffic_cone_1"]
    assert call(scene, "find_assets", lane="main_eastbound").data["ids"] == ["ego"]


def test_a_road_name_covers_both_of_its_lanes(call: Caller, campus: Scene) -> None:
    scene = _with_cones(call, campus)
    assert call(scene, "find_assets", lane="Campus Drive").data["ids"] == ["traffic_cone_1"]


def test_an_unknown_lane_is_refused_naming_the_lanes(call: Caller, campus: Scene) -> None:
    with pytest.raises(NotFoundError, match="campus_northbound"):
        call(campus, "find_assets", lane="skyway")


def test_a_kind_said_in_the_plural_finds_every_category_of_it(call: Caller, campus: Scene) -> None:
    found = call(campus, "find_assets", category="vehicles", near="parking lot B", within=30.0).data
    assert {"passenger_car_1", "passenger_car_2", "suv_1"} <= set(found["ids"])
    signs = call(campus, "find_assets", category="signs").data
    assert "stop_sign_1" in signs["ids"] and "tree_1" not in signs["ids"]
    # a single word is read as the catalog reads it: "vehicle" is a passenger car
    assert set(call(campus, "find_assets", category="vehicle").data["ids"]) == {"passenger_car_1", "passenger_car_2"}


def test_furthest_from_lists_the_furthest_first_and_leaves_the_reference_out(campus):
    from drivetwin.tools.search import FindAssets, FindAssetsArgs

    result = FindAssets().propose(FindAssetsArgs(category="tree", furthest_from="tree_2"), campus)
    ids = result.data["ids"]
    assert "tree_2" not in ids and len(ids) == campus.count("tree") - 1
    gaps = [result.data["distances"][i] for i in ids]
    assert gaps == sorted(gaps, reverse=True)
    assert result.text.startswith(f"furthest tree from tree_2: {ids[0]}")


def test_most_orders_by_the_figure_and_names_the_first_with_it(campus):
    from drivetwin.tools.search import FindAssets, FindAssetsArgs

    result = FindAssets().propose(FindAssetsArgs(category="vehicles", most="heaviest"), campus)
    masses = [a.physics.mass for i in result.data["ids"] if (a := campus.asset(i)) is not None]
    assert masses == sorted(masses, reverse=True)
    assert result.text.startswith(f"heaviest vehicles: {result.data['ids'][0]}") and f"{masses[0]:g} kg" in result.text


def test_assets_on_one_side_of_the_road_nearest_each(call: Caller, campus: Scene) -> None:
    # north of Main Street (it runs east-west), and east of Campus Drive (it runs north-south)
    north = call(campus, "find_assets", category="street_light", side="north").data["ids"]
    assert sorted(north) == sorted(a.id for a in campus.assets if a.category == "street_light" and a.pose.y > 0)
    east = call(campus, "find_assets", category="tree", side="east").data["ids"]
    assert sorted(east) == sorted(a.id for a in campus.assets if a.category == "tree" and a.pose.x > 0)
    assert call(campus, "find_assets", category="stop_sign", side="west").data["ids"] == ["stop_sign_1"]
