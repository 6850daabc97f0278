"""Campus scenes with a storyboard, simulated without rendering, for the scenario tests (helpers)."""

from __future__ import annotations

import itertools
import math

from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import (
    EGO_ID,
    AssetInstance,
    Behaviour,
    DriveLane,
    Parked,
    PhysicsProps,
    Pose,
    Scene,
)
from drivetwin.worlds.simulation import Simulation, TracePoint
from drivetwin.worlds.storyboard import Storyboard

EAST_Y = -1.75  # main_eastbound's centreline
WEST_Y = 1.75  # main_westbound's centreline


def vehicle(asset_id: str, x: float, y: float, behaviour: Behaviour | None = None, yaw: float = 0.0,
            category_name: str = "passenger_car") -> AssetInstance:
    """A vehicle of the catalog at (x, y, yaw) with a behaviour (parked by default)."""
    return AssetInstance(
        id=asset_id,
        category=category_name,
        pose=Pose(x=x, y=y, yaw=yaw),
        physics=PhysicsProps(mass=category(category_name).mass),
        behaviour=behaviour or Parked(),
    )


def campus_with(*assets: AssetInstance, storyboard: Storyboard | None = None, ego_x: float = -60.0,
                ego_speed: float = 6.0) -> Scene:
    """The campus with extra assets, the ego driving east on Main Street from `ego_x`."""
    campus = build_campus()
    ego = campus.ego.model_copy(update={
        "pose": Pose(x=ego_x, y=EAST_Y), "behaviour": DriveLane(lane="main_eastbound", speed=ego_speed),
    })
    return Scene.model_validate(campus.model_copy(update={
        "ego": ego, "assets": [*campus.assets, *assets], "storyboard": storyboard or Storyboard(),
    }).model_dump())


def simulate(scene: Scene, seconds: float) -> Simulation:
    simulation = Simulation(scene)
    simulation.run_for(seconds)
    return simulation


def speeds(trace: list[TracePoint]) -> list[tuple[float, float]]:
    """(time, speed) between successive trace points."""
    return [
        (t1, math.hypot(x1 - x0, y1 - y0) / (t1 - t0))
        for (t0, x0, y0, _), (t1, x1, y1, _) in itertools.pairwise(trace)
        if t1 > t0
    ]


__all__ = ["EAST_Y", "EGO_ID", "WEST_Y", "campus_with", "simulate", "speeds", "vehicle"]
