"""The scene -> viser sync, the world layer and the browser's conversation, without a browser.

A real viser server (on a free port of 127.0.0.1) receives every node; nothing is mocked.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest
import viser
from drivetwin.orchestrator.planning.registry import make_planner
from drivetwin.orchestrator.serve.conversation import Conversation, resolve_selection
from drivetwin.orchestrator.serve.overlays import Overlays, routes_and_triggers
from drivetwin.orchestrator.serve.scene_sync import SceneSync, splat_arrays
from drivetwin.orchestrator.serve.world_layer import environment_view, world_surfaces
from drivetwin.orchestrator.session import Session
from drivetwin.worlds.catalog import category
from drivetwin.worlds.render.splats import SH_C0, Splats
from drivetwin.worlds.scene import Environment, FollowPath, Scene, Weather


@pytest.fixture(scope="module")
def server() -> Iterator[viser.ViserServer]:
    server = viser.ViserServer(host="127.0.0.1", port=0, verbose=False)
    yield server
    server.stop()


@pytest.fixture
def sync(server: viser.ViserServer, campus: Scene) -> SceneSync:
    server.scene.reset()
    sync = SceneSync(server.scene, server.atomic)
    sync.show(campus)
    return sync


def _poses(scene: Scene) -> dict[str, tuple[float, float, float, float]]:
    return {a.id: (a.pose.x, a.pose.y, a.pose.z, a.pose.yaw) for a in scene.all_assets()}


def test_every_asset_and_the_ego_is_drawn_once(sync: SceneSync, campus: Scene) -> None:
    assert sync.instance_count() == len(campus.assets) + 1
    for asset in campus.all_assets():
        nodes = [node for node, batch in sync._batches.items() if asset.id in batch.asset_ids]
        assert len(nodes) == len(category(asset.category).parts), asset.id


def test_unchanged_poses_send_nothing(sync: SceneSync, campus: Scene) -> None:
    assert sync.move(_poses(campus)) == 0


def test_one_moved_asset_sends_only_the_batches_of_its_category(sync: SceneSync, campus: Scene) -> None:
    poses = _poses(campus)
    x, y, z, yaw = poses["passenger_car_1"]
    poses["passenger_car_1"] = (x + 2.0, y, z, yaw + 0.5)
    sent = sync.move(poses)
    assert sent == len(category("passenger_car").parts)
    assert sync.pose_of("passenger_car_1") == pytest.approx((x + 2.0, y, z, yaw + 0.5))
    node = next(n for n, b in sync._batches.items() if "passenger_car_1" in b.asset_ids)
    batch = sync._batches[node]
    row = batch.asset_ids.index("passenger_car_1")
    assert isinstance(batch.handle, viser.BatchedMeshHandle)
    assert batch.handle.batched_positions[row] == pytest.approx((x + 2.0, y, z))
    assert batch.handle.batched_wxyzs[row] == pytest.approx((math.cos((yaw + 0.5) / 2), 0, 0, math.sin((yaw + 0.5) / 2)),
                                                            abs=1e-6)


def test_a_sub_millimetre_jitter_is_not_sent(sync: SceneSync, campus: Scene) -> None:
    poses = _poses(campus)
    x, y, z, yaw = poses["bench_1"]
    poses["bench_1"] = (x + 1e-4, y, z, yaw)
    assert sync.move(poses) == 0


def test_a_clicked_instance_names_its_asset(sync: SceneSync, campus: Scene) -> None:
    for node, batch in sync._batches.items():
        for index, asset_id in enumerate(batch.asset_ids):
            assert sync.asset_at(node, index) == asset_id
    assert sync.asset_at("/world/lanes", 0) is None
    assert sync.asset_at(next(iter(sync._batches)), 10_000) is None


def test_an_added_asset_rebuilds_the_layout_and_is_drawn(sync: SceneSync, campus: Scene) -> None:
    session = Session(campus, make_planner("rules"))
    assert session.submit("add a traffic cone in front of the library").ok
    rebuilds = sync.stats.rebuilds
    sync.show(session.scene)
    assert sync.stats.rebuilds == rebuilds + 1
    assert sync.instance_count() == len(session.scene.assets) + 1
    assert any("traffic_cone_1" in batch.asset_ids for batch in sync._batches.values())


def test_a_weather_change_keeps_the_asset_batches(sync: SceneSync, campus: Scene) -> None:
    rebuilds = sync.stats.rebuilds
    rainy = campus.model_copy(update={"environment": Environment(weather=Weather(kind="rain", intensity=0.8))})
    sync.show(rainy)
    assert sync.stats.rebuilds == rebuilds


def test_a_selected_asset_is_cleared_when_it_is_removed(sync: SceneSync, campus: Scene) -> None:
    sync.select("bench_1")
    assert sync.selected == "bench_1"
    sync.show(campus.model_copy(update={"assets": [a for a in campus.assets if a.id != "bench_1"]}))
    assert sync.selected is None


def test_world_surfaces_raise_each_building_to_its_height(campus: Scene) -> None:
    surfaces = {s.name: s for s in world_surfaces(campus)}
    assert {"ground", "lanes", "sidewalks", "crossings", "paved"} <= set(surfaces)
    for building in campus.buildings:
        mesh = surfaces[f"buildings/{building.id}"].mesh
        assert mesh.bounds[1][2] == pytest.approx(building.height)
        xs = [p[0] for p in building.footprint]
        assert mesh.bounds[0][0] == pytest.approx(min(xs))


def test_lanes_cover_their_width_on_both_sides_of_the_centreline(campus: Scene) -> None:
    lanes = next(s for s in world_surfaces(campus) if s.name == "lanes").mesh
    lane = campus.roads.lanes[0]
    (x0, y0), (x1, y1) = lane.centreline[0], lane.centreline[1]
    normal = np.array([-(y1 - y0), x1 - x0]) / math.hypot(x1 - x0, y1 - y0)
    edge = np.array([x0, y0]) + normal * lane.width / 2
    assert np.min(np.linalg.norm(lanes.vertices[:, :2] - edge, axis=1)) < 1e-6


def test_night_sky_is_darker_and_fog_is_nearer_than_a_clear_noon() -> None:
    noon = environment_view(Environment(time_of_day="12:00"))
    night = environment_view(Environment(time_of_day="23:00"))
    fog = environment_view(Environment(weather=Weather(kind="fog", intensity=0.9)))
    assert night.sky.mean() < noon.sky.mean() / 3
    assert night.sun_intensity < noon.sun_intensity / 10
    assert fog.fog_far < noon.fog_far / 10
    assert fog.caption == "12:00, fog 0.9"


def test_splat_covariance_is_rotation_times_squared_scales() -> None:
    angle = 0.7
    splats = Splats(means=np.array([[1.0, 2.0, 3.0]]), quats=np.array([[math.cos(angle / 2), 0, 0, math.sin(angle / 2)]]),
                    log_scales=np.log(np.array([[2.0, 0.5, 1.0]])), opacity_logits=np.array([0.0]),
                    sh=np.array([[[0.5 / SH_C0, 0.0, -0.5 / SH_C0]]]))
    centres, covariances, colours, opacities = splat_arrays(splats)
    rotation = np.array([[math.cos(angle), -math.sin(angle), 0], [math.sin(angle), math.cos(angle), 0], [0, 0, 1]])
    assert covariances[0] == pytest.approx(rotation @ np.diag([4.0, 0.25, 1.0]) @ rotation.T, abs=1e-5)
    assert centres[0] == pytest.approx((1.0, 2.0, 3.0))
    assert colours[0] == pytest.approx((1.0, 0.5, 0.0))
    assert opacities[0, 0] == pytest.approx(0.5)


def test_storyboard_overlay_draws_each_walkers_path(server: viser.ViserServer, campus: Scene) -> None:
    walker = campus.assets[0].model_copy(update={"id": "walker_1", "behaviour": FollowPath(waypoints=[(0, 0), (5, 5)])})
    scene = campus.model_copy(update={"assets": [*campus.assets, walker]})
    routes, _ = routes_and_triggers(scene)
    assert [r.points for r in routes if r.name == "walker_1"] == [[(0.0, 0.0), (5.0, 5.0)]]
    overlays = Overlays(server.scene)
    overlays.set_enabled("storyboard", True, scene)
    assert overlays.counts["storyboard"] == 2 * len(routes)
    overlays.set_enabled("lane_ids", True, scene)
    assert overlays.counts["lane_ids"] == len(scene.roads.lanes)
    overlays.set_enabled("lane_ids", False, scene)
    assert overlays.counts["lane_ids"] == 0


def test_an_unknown_overlay_is_refused_with_the_known_ones(server: viser.ViserServer, campus: Scene) -> None:
    with pytest.raises(ValueError, match="unknown overlay 'roads'; overlays: lidar, lane_ids, landmarks, storyboard"):
        Overlays(server.scene).set_enabled("roads", True, campus)


def test_this_means_the_selected_asset_and_it_means_nothing() -> None:
    assert resolve_selection("move this 3 m left", "tree_4") == "move tree_4 3 m left"
    assert resolve_selection("paint that one red", "bench_1") == "paint bench_1 red"
    assert resolve_selection("make it rain", "tree_4") == "make it rain"
    assert resolve_selection("move this 3 m left", None) == "move this 3 m left"


def test_a_request_about_this_moves_the_selected_asset(campus: Scene) -> None:
    conversation = Conversation(Session(campus, make_planner("rules")))
    before = campus.asset("tree_4")
    assert before is not None
    conversation.selected = "tree_4"
    assert conversation.send("move this 3 m left")
    after = conversation.session.scene.asset("tree_4")
    assert after is not None and math.hypot(after.pose.x - before.pose.x, after.pose.y - before.pose.y) == pytest.approx(3.0)
    assert "move this 3 m left  →  move tree_4 3 m left" in conversation.messages[0].text


def test_undo_from_the_panel_runs_the_sessions_undo(campus: Scene) -> None:
    conversation = Conversation(Session(campus, make_planner("rules")))
    assert conversation.send("make it rain")
    assert conversation.session.scene.environment.weather.kind == "rain"
    assert conversation.command("undo")
    assert conversation.session.scene.environment.weather.kind == "clear"
    assert not conversation.command("undo")  # nothing left: the REPL's own error, shown as text
    assert conversation.messages[-1].text.strip() == "error: nothing to undo"


def test_save_without_a_path_says_what_to_give(campus: Scene) -> None:
    conversation = Conversation(Session(campus, make_planner("rules")))
    assert not conversation.command("save", "")
    assert "give a file path" in conversation.messages[-1].text
