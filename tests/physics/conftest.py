"""Small scenes built straight from the Scene model, for the physics tests."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import (
    AssetInstance,
    Bounds,
    Lane,
    PhysicsProps,
    Pose,
    RoadNetwork,
    Scene,
)

STRAIGHT_LANE = Lane(id="east", road="main", centreline=[(-100.0, -1.75), (100.0, -1.75)])
OPPOSITE_LANE = Lane(id="west", road="main", centreline=[(100.0, 1.75), (-100.0, 1.75)])


def make_asset(
    asset_id: str, category_name: str, x: float, y: float, yaw: float = 0.0, **fields: object
) -> AssetInstance:
    """An asset of a catalog category at (x, y, yaw) with the category's mass."""
    mass = category(category_name).mass
    physics = fields.pop("physics", PhysicsProps(mass=mass))
    return AssetInstance(
        id=asset_id,
        category=category_name,
        pose=Pose(x=x, y=y, yaw=yaw),
        physics=physics,
        **fields,  # type: ignore[arg-type]
    )


def make_scene(*assets: AssetInstance, ego: AssetInstance | None = None) -> Scene:
    """A 200 m × 200 m flat world with one two-lane road along x and the given assets."""
    return Scene(
        name="test",
        bounds=Bounds(xmin=-100, xmax=100, ymin=-100, ymax=100),
        roads=RoadNetwork(lanes=[STRAIGHT_LANE, OPPOSITE_LANE]),
        ego=ego or make_asset("ego", "ego_vehicle", -60.0, -1.75),
        assets=list(assets),
    )


def fit_circle(points: np.ndarray) -> tuple[float, float, float]:
    """Least-squares (Kåsa) circle through 2-D points: centre x, centre y, radius."""
    x, y = points[:, 0], points[:, 1]
    a = np.column_stack([2 * x, 2 * y, np.ones_like(x)])
    b = x**2 + y**2
    (cx, cy, c), *_ = np.linalg.lstsq(a, b, rcond=None)
    return float(cx), float(cy), float(math.sqrt(c + cx**2 + cy**2))


@pytest.fixture
def empty_scene() -> Scene:
    return make_scene()
