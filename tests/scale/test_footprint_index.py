"""The placement rules' grid indexes answer exactly as the plain scan over every asset, for a
plain list and for a scene index that follows edits (dry runs, commits, undo)."""

from __future__ import annotations

import math

import pytest
from drivetwin.tools.errors import RuleViolation
from drivetwin.tools.footprint_grid import _reference_overlaps
from drivetwin.tools.footprints import FootprintIndex, SceneFootprints, footprint_of, near, overlapping, track
from drivetwin.tools.rules import assets_near, check_placement
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.catalog import category
from drivetwin.worlds.edits import AddAsset, RemoveAsset, UpdateAsset, WorldEdit
from drivetwin.worlds.scene import AssetInstance, Bounds, PhysicsProps, Pose, Scene
from hypothesis import given, settings
from hypothesis import strategies as st

CATEGORIES = ["traffic_cone", "road_barrier", "bench", "bus", "pedestrian", "passenger_car", "tree"]


def _asset(k: int, name: str, x: float, y: float, yaw: float, scale: float) -> AssetInstance:
    return AssetInstance(id=f"a{k}", category=name, pose=Pose(x=x, y=y, yaw=yaw), scale=scale,
                         physics=PhysicsProps(mass=category(name).mass))  # fmt: skip


# Crowded on purpose: 60 m square, up to 120 assets, so that most probes touch something.
assets_st = st.lists(
    st.tuples(st.sampled_from(CATEGORIES), st.floats(-30, 30), st.floats(-30, 30),
              st.floats(-math.pi, math.pi), st.sampled_from([0.5, 1.0, 2.0])),
    min_size=0, max_size=120,
)


@settings(max_examples=60, deadline=None)
@given(assets_st, assets_st, st.lists(st.integers(0, 119), max_size=20))
def test_the_index_finds_exactly_the_overlaps_the_scan_finds(placed, probes, dropped) -> None:
    assets = [_asset(k, *spec) for k, spec in enumerate(placed)]
    index = FootprintIndex()
    index.sync(assets)
    # Patched by identity (an edit's next scene): some removed, probes' twins added.
    kept = [a for k, a in enumerate(assets) if k not in set(dropped)]
    extra = [_asset(1000 + k, *spec) for k, spec in enumerate(probes[:10])]
    index.sync([*kept, *extra])
    for k, spec in enumerate(probes):
        probe = footprint_of(_asset(2000 + k, *spec))
        expected = [a.id for a in _reference_overlaps(probe, [*kept, *extra])]
        assert [f.asset.id for f in index.overlapping(probe)] == expected
        reach = 5.0
        within = [a.id for a in [*kept, *extra]
                  if math.hypot(a.pose.x - probe.x, a.pose.y - probe.y) <= reach + footprint_of(a).radius]  # fmt: skip
        assert [a.id for a in index.near(probe.x, probe.y, reach)] == within


def test_an_asset_changed_in_place_is_indexed_where_it_stands_now() -> None:
    cone = _asset(1, "traffic_cone", 0.0, 0.0, 0.0, 1.0)
    others = [cone]
    index = FootprintIndex()
    index.sync(others)
    cone.pose = Pose(x=20.0, y=0.0)  # mutable pydantic model: the footprint must follow
    index.sync(list(others))
    probe = footprint_of(_asset(2, "traffic_cone", 20.0, 0.0, 0.0, 1.0))
    assert [f.asset.id for f in index.overlapping(probe)] == ["a1"]


def test_check_placement_names_the_first_overlapping_asset_in_the_given_order() -> None:
    scene = build_campus()
    a = _asset(1, "road_barrier", -98.0, 16.0, 0.0, 1.0)
    b = _asset(2, "road_barrier", -97.0, 16.0, 0.0, 1.0)
    probe = _asset(3, "road_barrier", -97.5, 16.0, 0.0, 1.0)
    for order in ([a, b], [b, a]):
        with pytest.raises(RuleViolation, match=f"would overlap {order[0].id}"):
            check_placement(scene, probe, [*scene.all_assets(), *order])
    assert overlapping([a], footprint_of(_asset(4, "traffic_cone", 50.0, 50.0, 0.0, 1.0))) == []
    assert [x.id for x in assets_near([a, b], -99.5, 16.0, 0.6)] == ["a1"]


# Random edit sequences: what each step does to the scene it starts from.
steps_st = st.lists(
    st.tuples(st.sampled_from(["add", "move", "remove", "add_and_move", "undo", "dry_run"]),
              st.sampled_from(CATEGORIES), st.floats(-28, 28), st.floats(-28, 28),
              st.floats(-math.pi, math.pi), st.integers(0, 10_000)),
    min_size=1, max_size=25,
)


def _world(specs: list[tuple[str, float, float, float, float]]) -> Scene:
    assets = [_asset(k, *spec).model_copy(update={"id": f"{spec[0]}_{k}"}) for k, spec in enumerate(specs)]
    ego = AssetInstance(id="ego", category="ego_vehicle", pose=Pose(x=-25.0, y=-25.0),
                        physics=PhysicsProps(mass=category("ego_vehicle").mass))  # fmt: skip
    return Scene(name="crowd", bounds=Bounds(xmin=-40, xmax=40, ymin=-40, ymax=40), ego=ego, assets=assets)


def _step(scene: Scene, step: tuple[str, str, float, float, float, int], fresh: int) -> WorldEdit:
    kind, name, x, y, yaw, k = step
    everyone = scene.all_assets()
    target = everyone[k % len(everyone)]
    added = AddAsset(asset=_asset(0, name, x, y, yaw, 1.0).model_copy(update={"id": f"{name}_{1000 + fresh}"}))
    moved = UpdateAsset(before=target, after=target.model_copy(update={"pose": Pose(x=x, y=y, yaw=yaw)}))
    if kind == "remove" and scene.assets:
        return WorldEdit(ops=(RemoveAsset(before=scene.assets[k % len(scene.assets)]),))
    if kind == "move":
        return WorldEdit(ops=(moved,))
    if kind == "add_and_move":
        return WorldEdit(ops=(added, moved))
    return WorldEdit(ops=(added,))


def _answers_as_the_scan(scene: Scene, probe_spec: tuple[str, float, float, float, int]) -> None:
    name, x, y, yaw, k = probe_spec
    probe = footprint_of(_asset(99_999, name, x, y, yaw, 1.0))
    everyone = scene.all_assets()
    expected = [a.id for a in _reference_overlaps(probe, everyone)]
    assert [f.asset.id for f in overlapping(everyone, probe, scene)] == expected
    reach = 6.0
    within = [a.id for a in everyone if math.hypot(a.pose.x - x, a.pose.y - y) <= reach + footprint_of(a).radius]
    assert [a.id for a in near(everyone, x, y, reach)] == within
    # A Worker's list: the scene without the asset it moves, then the ones it is placing.
    left_out = everyone[k % len(everyone)]
    extras = [_asset(50_000 + j, "road_barrier", x + j, y, 0.0, 1.0) for j in range(k % 3)]
    given = [a for a in everyone if a is not left_out] + extras
    expected = [a.id for a in _reference_overlaps(probe, given)]
    assert [f.asset.id for f in overlapping(given, probe, scene)] == expected


@settings(max_examples=40, deadline=None)
@given(assets_st, steps_st)
def test_the_scene_index_answers_as_the_scan_after_random_edit_sequences(placed, steps) -> None:
    scene = _world([spec for spec in placed if spec[0] != "pedestrian"][:60])
    history: list[tuple[Scene, WorldEdit]] = []
    for fresh, step in enumerate(steps):
        if step[0] == "undo" and history:  # the session's undo: the inverse edit, applied
            before, edit = history.pop()
            scene = edit.inverse().apply(scene)
            assert scene == before
        else:
            if step[0] == "dry_run" and history:  # back to the parent: a sibling of the last scene
                scene, _ = history.pop()
            edit = _step(scene, step, fresh)
            history.append((scene, edit))
            scene = edit.apply(scene)
        _answers_as_the_scan(scene, (step[1], step[2], step[3], step[4], step[5]))
        for asset in scene.assets[:: max(1, len(scene.assets) // 5)]:
            assert scene.asset(asset.id) is asset
        assert scene.count(step[1]) == sum(1 for a in scene.assets if a.category == step[1])


def test_a_dry_run_and_its_commit_patch_the_scene_index_instead_of_re_reading_it(monkeypatch) -> None:
    scene = _world([("traffic_cone", 2.0 * k - 20.0, 0.0, 0.0, 1.0) for k in range(20)])
    probe = footprint_of(_asset(999, "traffic_cone", 0.0, 0.0, 0.0, 1.0))
    track(scene)
    rereads: list[int] = []
    monkeypatch.setattr(SceneFootprints, "_sync", lambda self, assets: rereads.append(len(assets)))
    cone = scene.assets[10]
    edit = WorldEdit(ops=(UpdateAsset(before=cone, after=cone.model_copy(update={"pose": Pose(x=5.0, y=5.0)})),))
    dry_run, commit = edit.apply(scene), edit.apply(scene)
    for seen in (dry_run, commit, edit.inverse().apply(commit), scene):
        hits = overlapping(seen.all_assets(), probe, seen)
        assert [f.asset.id for f in hits] == [a.id for a in _reference_overlaps(probe, seen.all_assets())]
    assert rereads == []


def test_an_asset_list_grown_in_place_is_looked_up_anew() -> None:
    scene = _world([("bench", 0.0, 0.0, 0.0, 1.0)])
    assert scene.asset("bench_1") is None
    bench = _asset(1, "bench", 10.0, 10.0, 0.0, 1.0).model_copy(update={"id": "bench_1"})
    scene.assets.append(bench)  # bypasses validation, as some tests and tools do
    assert scene.asset("bench_1") is bench
    assert scene.count("bench") == 2
