"""Several assets of one request spread out, group moves are order-free, parked rows line up."""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Callable

import pytest
from drivetwin.orchestrator.transaction import TransactionError, execute
from drivetwin.tools import RuleViolation, ToolCall, ToolRegistry, ToolResult
from drivetwin.tools.arrange import PARKING_BAY_WIDTH_M
from drivetwin.tools.rules import footprint, footprints_overlap
from drivetwin.worlds.scene import AssetInstance, Scene
from drivetwin.worlds.surface import point_in_polygon

Caller = Callable[..., ToolResult]


def _added(call: Caller, scene: Scene, tool: str = "add_asset", **args: object) -> tuple[Scene, list[AssetInstance]]:
    result = call(scene, tool, **args)
    after = result.edit.apply(scene)
    return after, [a for i in result.data["ids"] if (a := after.asset(i)) is not None]


def test_three_pedestrians_at_the_north_crossing_stand_on_three_distinct_free_spots(
    call: Caller, campus: Scene
) -> None:
    _, walkers = _added(call, campus, category="pedestrian", count=3,
                        location={"relation": "at", "target": "north crossing"})
    assert len(walkers) == 3
    for a, b in itertools.combinations(walkers, 2):
        assert not footprints_overlap(a, b, tolerance=0.0), (a.id, b.id)
    mark = campus.landmark("north crossing")
    assert mark is not None
    assert all(math.hypot(w.pose.x - mark.position[0], w.pose.y - mark.position[1]) < 10.0 for w in walkers)


def test_a_request_for_more_than_fit_says_how_many_do(call: Caller, campus: Scene) -> None:
    entrance = {"relation": "at", "target": "parking lot A entrance"}
    with pytest.raises(RuleViolation, match=r"within 12 m of parking lot A entrance for 7 bus; (\d+) fit") as refused:
        call(campus, "add_asset", category="bus", count=7, location=entrance)
    match = re.search(r"; (\d+) fit", str(refused.value))
    assert match is not None
    fit = int(match.group(1))
    assert 0 < fit < 7
    _, buses = _added(call, campus, category="bus", count=fit, location=entrance)
    assert len(buses) == fit


def _cone_line(call: Caller, campus: Scene) -> tuple[Scene, list[str]]:
    scene, cones = _added(call, campus, "arrange_assets", categories=["traffic_cone"], shape="line", count=4,
                          spacing=1.0, heading_deg=0.0, location={"relation": "absolute", "x": -40.0, "y": -1.75})
    return scene, [c.id for c in cones]


def test_a_group_move_lets_members_take_each_others_old_places(call: Caller, campus: Scene) -> None:
    scene, ids = _cone_line(call, campus)
    result = call(scene, "move_asset", assets=ids, east=1.0)
    after = result.edit.apply(scene)
    for cone_id in ids:
        before, moved = scene.asset(cone_id), after.asset(cone_id)
        assert before is not None and moved is not None
        assert (moved.pose.x, moved.pose.y) == pytest.approx((before.pose.x + 1.0, before.pose.y))


def test_a_group_move_gives_the_same_scene_whatever_the_order_of_its_members(call: Caller, campus: Scene) -> None:
    scene, ids = _cone_line(call, campus)
    forwards = call(scene, "move_asset", assets=ids, north=-0.5, east=1.0).edit.apply(scene)
    backwards = call(scene, "move_asset", assets=list(reversed(ids)), north=-0.5, east=1.0).edit.apply(scene)
    assert forwards.assets == backwards.assets


def test_members_moved_one_call_at_a_time_collide_which_is_why_the_group_move_exists(
    registry: ToolRegistry, call: Caller, campus: Scene
) -> None:
    scene, ids = _cone_line(call, campus)
    one_by_one = [ToolCall(tool="move_asset", args={"asset": i, "east": 1.0}) for i in ids]
    with pytest.raises(TransactionError, match="overlap"):
        execute(registry, scene, one_by_one)
    outcome = execute(registry, scene, [ToolCall(tool="move_asset", args={"assets": ids, "east": 1.0})])
    assert len(outcome.edit.ops) == len(ids)


def test_a_parking_row_stands_side_by_side_in_the_lot_aligned_and_facing_one_way(call: Caller, campus: Scene) -> None:
    _, cars = _added(call, campus, "arrange_assets", categories=["passenger_car"], shape="parking_row", count=5,
                     location={"relation": "at", "target": "parking lot A"})
    lot = campus.landmark("parking lot A")
    assert lot is not None and lot.polygon is not None
    assert len(cars) == 5
    assert all(point_in_polygon(x, y, lot.polygon) for car in cars for x, y in footprint(car))
    assert len({round(car.pose.yaw, 6) for car in cars}) == 1
    heading = cars[0].pose.yaw
    # Aligned: no car stands ahead of or behind another; neighbours one bay apart.
    along = [car.pose.x * math.cos(heading) + car.pose.y * math.sin(heading) for car in cars]
    assert max(along) - min(along) == pytest.approx(0.0, abs=1e-6)
    across = sorted(-car.pose.x * math.sin(heading) + car.pose.y * math.cos(heading) for car in cars)
    assert all(b - a == pytest.approx(PARKING_BAY_WIDTH_M) for a, b in itertools.pairwise(across))


def test_a_parking_row_longer_than_the_lot_is_refused_saying_how_many_fit(call: Caller, campus: Scene) -> None:
    # Lot A is 30 m across: eleven 2.7 m bays.
    with pytest.raises(RuleViolation, match=r"no free row for 14 parked passenger_car .* 11 fit side by side"):
        call(campus, "arrange_assets", categories=["passenger_car"], shape="parking_row", count=14,
             location={"relation": "at", "target": "parking lot A"})


def test_a_line_in_front_of_a_vehicle_runs_across_its_path_shifted_onto_the_road(
    call: Caller, campus: Scene
) -> None:
    """Six cones across the ego's 3.5 m lane would stand on the verge; the cordon still runs
    across the ego's path, moved across the road until every cone stands on it, never turned."""
    _, cones = _added(call, campus, "arrange_assets", categories=["traffic_cone"], count=6, shape="line",
                      location={"relation": "in_front_of", "target": "ego"})
    ego = campus.asset("ego")
    assert ego is not None and len(cones) == 6
    assert all(abs(c.pose.yaw - math.pi / 2) < 1e-6 for c in cones)  # across the eastbound lane
    assert len({round(c.pose.x, 6) for c in cones}) == 1
    assert all(c.pose.x > ego.pose.x + 2.0 for c in cones)  # ahead of the ego, not through it
    assert all(-3.5 <= c.pose.y <= 3.5 for c in cones)  # on Main Street's carriageway


def test_a_line_with_a_direction_said_is_not_turned(call: Caller, campus: Scene) -> None:
    _, cones = _added(call, campus, "arrange_assets", categories=["traffic_cone"], count=6, shape="line",
                      heading_deg=90.0, location={"relation": "in_front_of", "target": "ego"})
    assert len(cones) == 6 and all(abs(c.pose.yaw - math.pi / 2) < 1e-6 for c in cones)


def test_a_line_that_runs_into_a_building_moves_out_whole_and_keeps_its_spacing(call: Caller, campus: Scene) -> None:
    _, barriers = _added(call, campus, "arrange_assets", categories=["road_barrier"], count=4, shape="line",
                         spacing=3.0, location={"relation": "next_to", "target": "JTEKT building entrance"})
    gaps = [math.dist((a.pose.x, a.pose.y), (b.pose.x, b.pose.y)) for a, b in itertools.pairwise(barriers)]
    entrance = campus.landmark("JTEKT building entrance")
    assert entrance is not None and all(abs(g - 3.0) < 1e-6 for g in gaps)
    assert all(math.dist((b.pose.x, b.pose.y), entrance.position) < 15.0 for b in barriers)



def test_things_already_there_are_moved_into_a_layout_not_added(call: Caller, campus: Scene) -> None:
    cars = ["passenger_car_1", "passenger_car_2", "suv_1"]
    result = call(campus, "arrange_assets", categories=["passenger_car"], shape="parking_row", assets=cars,
                  location={"relation": "at", "target": "parking lot A"})
    after = result.edit.apply(campus)
    assert len(after.assets) == len(campus.assets) and result.data["ids"] == cars
    lot = campus.landmark("parking lot A")
    assert lot is not None and lot.polygon is not None
    moved = [after.asset(i) for i in cars]
    assert all(a is not None and point_in_polygon(a.pose.x, a.pose.y, lot.polygon) for a in moved)
    assert len({round(a.pose.yaw, 3) for a in moved if a is not None}) == 1  # side by side, one way
    # a ring round the fountain made of the trees there, however far each stood
    trees = [a.id for a in campus.assets if a.category == "tree"]
    ringed = call(campus, "arrange_assets", categories=["tree"], shape="ring", assets=trees,
                  location={"relation": "at", "target": "fountain"}).edit.apply(campus)
    fountain = campus.landmark("fountain")
    assert fountain is not None
    points = [(a.pose.x, a.pose.y) for i in trees if (a := ringed.asset(i)) is not None]
    centre = (sum(x for x, _ in points) / len(points), sum(y for _, y in points) / len(points))
    distances = [math.dist(p, centre) for p in points]
    assert len(points) == len(trees) and max(distances) - min(distances) < 0.5 and math.dist(centre, fountain.position) < 2
    with pytest.raises(RuleViolation, match="ego"):
        call(campus, "arrange_assets", categories=["passenger_car"], shape="line", assets=["ego", "suv_1"],
             location={"relation": "at", "target": "parking lot B"})
