"""The placement rules' grid index answers exactly as the plain scan over every asset."""

from __future__ import annotations

import math

import pytest
from drivetwin.tools.errors import RuleViolation
from drivetwin.tools.footprints import FootprintIndex, _reference_overlaps, footprint_of, overlapping
from drivetwin.tools.rules import assets_near, check_placement
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import AssetInstance, PhysicsProps, Pose
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
