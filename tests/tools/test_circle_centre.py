"""A circle with no centre named is driven where the asset is, not in the world's first lot."""

from __future__ import annotations

import math
from collections.abc import Callable

from drivetwin.tools import ToolResult
from drivetwin.worlds.scene import Circle, Scene
from drivetwin.worlds.surface import point_in_polygon

Caller = Callable[..., ToolResult]


def _circling(call: Caller, scene: Scene, asset: str, **spec: object) -> Circle:
    after = call(scene, "set_behaviour", asset=asset, behaviour={"kind": "circle", **spec}).edit.apply(scene)
    moved = after.asset(asset)
    assert moved is not None and isinstance(moved.behaviour, Circle)
    return moved.behaviour


def _lot(scene: Scene, name: str) -> list[tuple[float, float]]:
    landmark = scene.landmark(name)
    assert landmark is not None and landmark.polygon is not None
    return landmark.polygon


def test_a_car_in_lot_b_told_to_circle_circles_in_lot_b(call: Caller, campus: Scene) -> None:
    added = call(campus, "add_asset", category="passenger_car", location={"relation": "at", "target": "parking lot B"})
    scene, car = added.edit.apply(campus), added.data["ids"][0]
    circle = _circling(call, scene, car)
    assert point_in_polygon(*circle.centre, _lot(scene, "parking lot B"))


def test_a_circle_with_no_centre_starts_from_the_spot_nearest_the_asset(call: Caller, campus: Scene) -> None:
    added = call(campus, "add_asset", category="passenger_car",
                 location={"relation": "absolute", "x": 55.0, "y": -40.0})
    scene, car = added.edit.apply(campus), added.data["ids"][0]
    circle = _circling(call, scene, car)
    # Lot B's centre is about 20 m away; the circle is drawn round the car's own corner of it.
    assert math.hypot(circle.centre[0] - 55.0, circle.centre[1] + 40.0) < 8.0


def test_a_named_centre_still_wins_over_where_the_asset_is(call: Caller, campus: Scene) -> None:
    circle = _circling(call, campus, "ego", centre="parking lot B")
    assert circle.centre == (38.5, -29.0)
