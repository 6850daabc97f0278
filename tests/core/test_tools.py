import math

import pytest
from drivetwin.tools import RuleViolation, ToolArgumentError, ToolCall, ToolError, UnknownToolError
from drivetwin.tools.rules import footprints_overlap


def run(registry, scene, tool, **args):
    result = registry.run(ToolCall(tool=tool, args=args), scene)
    return result, result.edit.apply(scene)


def test_every_tool_exports_a_json_schema_with_its_family(registry):
    families = {registry.get(n).family for n in registry.names()}
    assert families == {"search", "add", "remove", "position", "move", "arrange", "appearance"}
    add = registry.get("add_asset").json_schema()
    assert "traffic_cone" in add["parameters"]["properties"]["category"]["enum"]


def test_add_puts_the_asset_at_the_scene_centre(registry, campus):
    _, after = run(registry, campus, "add_asset", category="cement rubble", location={"relation": "scene_centre"})
    rubble = [a for a in after.assets if a.category == "cement_rubble"]
    assert len(rubble) == 1 and math.hypot(rubble[0].pose.x, rubble[0].pose.y) < 1.0


@pytest.mark.parametrize("category", ["tree", "bench", "pedestrian", "trash_bin"])
def test_a_thing_added_with_no_place_stands_at_the_verge_nearest_the_centre_not_in_the_junction(registry, campus, category):
    from drivetwin.worlds.surface import surface_at

    _, after = run(registry, campus, "add_asset", category=category, location={"relation": "scene_centre"})
    (added,) = [a for a in after.assets if campus.asset(a.id) is None]
    assert surface_at(after, added.pose.x, added.pose.y) == "sidewalk"
    assert math.hypot(added.pose.x, added.pose.y) < 15.0


def test_a_thing_added_with_no_place_where_no_verge_is_near_goes_where_the_rules_allow(registry, campus):
    from drivetwin.worlds.scene import Bounds

    far_from_roads = campus.model_copy(update={"bounds": Bounds(xmin=60.0, xmax=100.0, ymin=60.0, ymax=100.0)})
    _, after = run(registry, far_from_roads, "add_asset", category="bench", location={"relation": "scene_centre"})
    (added,) = [a for a in after.assets if campus.asset(a.id) is None]
    assert math.hypot(added.pose.x - 80.0, added.pose.y - 80.0) < 13.0


def test_add_refuses_a_position_inside_a_building(registry, campus):
    with pytest.raises(RuleViolation, match="inside JTEKT Building") as exc:
        run(registry, campus, "add_asset", category="bus", location={"relation": "absolute", "x": 40, "y": 30})
    assert exc.value.rule == "building"


def test_add_refuses_a_position_outside_the_world(registry, campus):
    with pytest.raises(RuleViolation, match="outside the world"):
        run(registry, campus, "add_asset", category="bench", location={"relation": "absolute", "x": 500, "y": 0})


def test_add_refuses_a_car_off_the_road(registry, campus):
    with pytest.raises(RuleViolation, match="road, crossing or paved") as exc:
        run(registry, campus, "add_asset", category="car", location={"relation": "absolute", "x": 80, "y": 30})
    assert exc.value.rule == "surface"


def test_add_refuses_an_overlap_at_exact_coordinates(registry, campus):
    ego = campus.ego.pose
    with pytest.raises(RuleViolation, match="overlap ego"):
        run(registry, campus, "add_asset", category="car", location={"relation": "absolute", "x": ego.x, "y": ego.y})


def test_relative_placement_finds_the_nearest_free_spot(registry, campus):
    result, after = run(registry, campus, "add_asset", category="car",
                        location={"relation": "at", "target": "JTEKT building entrance"})
    car = after.asset(result.data["ids"][0])
    entrance = campus.landmark("JTEKT building entrance")
    assert math.dist(car.pose.xy, entrance.position) < 6.0
    assert not any(footprints_overlap(car, other) for other in after.all_assets() if other.id != car.id)


def test_in_front_of_places_along_the_targets_heading(registry, campus):
    result, after = run(registry, campus, "add_asset", category="traffic_cone",
                        location={"relation": "in_front_of", "target": "ego", "distance": 8})
    cone = after.asset(result.data["ids"][0])
    assert cone.pose.x > campus.ego.pose.x + 5 and abs(cone.pose.y - campus.ego.pose.y) < 1.5


def test_counts_beyond_the_limit_are_refused_in_words(registry, campus):
    with pytest.raises(ToolArgumentError, match="less than or equal to 50"):
        run(registry, campus, "add_asset", category="traffic_cone", count=10_000)


def test_unknown_asset_names_the_nearest_categories(registry, campus):
    with pytest.raises(ToolArgumentError, match="unknown asset 'tank'; nearest: truck"):
        run(registry, campus, "add_asset", category="tank")


def test_unknown_tool_lists_what_exists(registry, campus):
    with pytest.raises(UnknownToolError, match="nearest: add_asset"):
        run(registry, campus, "add_assets")


def test_removing_what_does_not_exist_is_refused(registry, campus):
    with pytest.raises(ToolError, match="no asset 'bus_9'"):
        run(registry, campus, "remove_assets", assets=["bus_9"])
    with pytest.raises(ToolError, match="no bus in the scene"):
        run(registry, campus, "remove_assets", category="bus")


def test_the_ego_vehicle_cannot_be_removed(registry, campus):
    with pytest.raises(RuleViolation, match="ego vehicle cannot be removed"):
        run(registry, campus, "remove_assets", assets=["ego"])


def test_ring_of_cones_surrounds_its_target_without_overlap(registry, campus):
    _, scene = run(registry, campus, "add_asset", category="cement_rubble", location={"relation": "scene_centre"})
    result, scene = run(registry, scene, "arrange_assets", categories=["traffic_cone"], shape="ring",
                        location={"relation": "at", "target": "cement_rubble_1"})
    cones = [scene.asset(i) for i in result.data["ids"]]
    radii = [math.hypot(c.pose.x, c.pose.y) for c in cones]
    assert len(cones) >= 6 and max(radii) - min(radii) < 1e-6
    assert all(not footprints_overlap(c, scene.asset("cement_rubble_1")) for c in cones)


def test_a_second_ring_encloses_the_first(registry, campus):
    _, scene = run(registry, campus, "add_asset", category="cement_rubble", location={"relation": "scene_centre"})
    _, scene = run(registry, scene, "arrange_assets", categories=["traffic_cone"], shape="ring",
                   location={"relation": "at", "target": "cement_rubble_1"})
    result, scene = run(registry, scene, "arrange_assets", categories=["road_barrier"], shape="ring",
                        location={"relation": "absolute", "x": 0, "y": 0})
    cone_r = max(math.hypot(a.pose.x, a.pose.y) for a in scene.assets if a.category == "traffic_cone")
    barrier_r = min(math.hypot(scene.asset(i).pose.x, scene.asset(i).pose.y) for i in result.data["ids"])
    assert barrier_r > cone_r + 0.4


def test_mixed_line_alternates_categories(registry, campus):
    result, scene = run(registry, campus, "arrange_assets", categories=["traffic_cone", "bollard"], shape="line",
                        count=4, location={"relation": "at", "target": "parking lot B"})
    assert [scene.asset(i).category for i in result.data["ids"]] == ["traffic_cone", "bollard"] * 2


def test_weather_and_time_change_the_environment(registry, campus):
    _, scene = run(registry, campus, "set_weather", kind="fog", intensity=0.8)
    _, scene = run(registry, scene, "set_time_of_day", time="night")
    assert scene.environment.weather.kind == "fog" and scene.environment.is_night


def test_recolouring_changes_only_the_appearance(registry, campus):
    _, scene = run(registry, campus, "set_asset_appearance", assets=["suv_1"], colour="red")
    before, after = campus.asset("suv_1"), scene.asset("suv_1")
    assert after.appearance.rgba == (0.8, 0.1, 0.1, 1.0) and after.pose == before.pose


def test_skidpad_robot_gets_a_clear_drivable_circle(registry, campus):
    result, scene = run(registry, campus, "add_asset", category="ackermann_robot",
                        behaviour={"kind": "circle", "radius": 5})
    robot = scene.asset(result.data["ids"][0])
    assert robot.behaviour.kind == "circle" and robot.behaviour.radius == 5
    cx, cy = robot.behaviour.centre
    assert math.isclose(math.hypot(robot.pose.x - cx, robot.pose.y - cy), 5.0, abs_tol=1e-6)


def test_jaywalker_starts_at_the_kerb_ahead_of_the_ego(registry, campus):
    result, scene = run(registry, campus, "add_asset", category="pedestrian", behaviour={"kind": "jaywalk"})
    walker = scene.asset(result.data["ids"][0])
    (sx, sy), (_ex, ey) = walker.behaviour.start, walker.behaviour.end
    assert sx > campus.ego.pose.x + 10
    assert sy < campus.ego.pose.y < ey  # the walk crosses the ego's lane


def test_search_answers_without_editing(registry, campus):
    result, scene = run(registry, campus, "find_assets", category="street lights")
    assert result.edit.empty and scene == campus
    assert result.text.startswith("12 street lights(s) found")
