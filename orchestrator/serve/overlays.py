"""What the browser can draw over the world on request: LIDAR points, lane ids, landmark
labels, and the storyboard's routes and triggers (and the paths assets' behaviours follow)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import viser
from drivetwin.orchestrator.serve.world_layer import lane_z
from drivetwin.worlds.scene import CrossRoad, FollowPath, Jaywalk, Scene
from drivetwin.worlds.storyboard import (
    CrossRoadManoeuvre,
    DistanceCondition,
    FollowRoute,
    ReachPositionCondition,
    StopMidRoad,
    TimeToCollisionCondition,
)

__all__ = ["OVERLAYS", "Overlays", "Route", "Trigger", "routes_and_triggers"]

F64 = npt.NDArray[np.float64]
OVERLAYS = ("lidar", "lane_ids", "landmarks", "storyboard")
LABEL_HEIGHT_M = 1.0  # lane ids and landmark names float this high, above parked cars' roofs
ROUTE_HEIGHT_M = 0.15  # route lines sit just above the sidewalk kerbs
ROUTE_RGB = (255, 140, 0)
TRIGGER_RGB = (220, 40, 200)
LIDAR_RGB = (30, 220, 90)
LIDAR_POINT_SIZE_M = 0.08


@dataclass(frozen=True)
class Route:
    """A path an actor will take: a storyboard manoeuvre or an asset's behaviour."""

    name: str
    points: list[tuple[float, float]]


@dataclass(frozen=True)
class Trigger:
    """Where or when a storyboard event starts, in words and (when it has one) at a place."""

    event: str
    text: str
    position: tuple[float, float] | None


def _xy(point: Sequence[float]) -> tuple[float, float]:
    return (float(point[0]), float(point[1]))


def routes_and_triggers(scene: Scene) -> tuple[list[Route], list[Trigger]]:
    """The routes of the storyboard's manoeuvres and of assets' behaviours, and the events' triggers."""
    routes: list[Route] = []
    triggers: list[Trigger] = []
    actors = {a.id: a for a in scene.all_assets()}
    for actor, event in scene.storyboard.events():
        action = event.action
        if isinstance(action, FollowRoute):
            routes.append(Route(f"{event.name} ({actor})", [_xy(p) for p in action.waypoints]))
        elif isinstance(action, CrossRoadManoeuvre | StopMidRoad):
            routes.append(Route(f"{event.name} ({actor})", [_xy(action.start), _xy(action.end)]))
        start = event.start
        if isinstance(start, ReachPositionCondition):
            triggers.append(Trigger(event.name, f"{event.name}: {start.actor} reaches here", _xy(start.position)))
        elif isinstance(start, DistanceCondition | TimeToCollisionCondition):
            limit = f"{start.distance} m" if isinstance(start, DistanceCondition) else f"TTC {start.seconds} s"
            target = actors.get(start.target)
            where = (target.pose.x, target.pose.y) if target is not None else None
            triggers.append(Trigger(event.name, f"{event.name}: {start.actor} within {limit} of {start.target}", where))
        else:
            text = f"{event.name}: at t = {start.time} s" if start.kind == "simulation_time" else f"{event.name}: {start.kind}"
            where = (actors[actor].pose.x, actors[actor].pose.y) if actor in actors else None
            triggers.append(Trigger(event.name, text, where))
    for asset in scene.all_assets():
        behaviour = asset.behaviour
        if isinstance(behaviour, FollowPath):
            routes.append(Route(asset.id, [_xy(p) for p in behaviour.waypoints]))
        elif isinstance(behaviour, CrossRoad | Jaywalk):
            routes.append(Route(asset.id, [_xy(behaviour.start), _xy(behaviour.end)]))
    return routes, triggers


class Overlays:
    """The overlay nodes under /overlays, each shown or hidden by a toggle."""

    def __init__(self, scene_api: viser.SceneApi) -> None:
        self.api = scene_api
        self.enabled: dict[str, bool] = dict.fromkeys(OVERLAYS, False)
        self._nodes: dict[str, list[viser.SceneNodeHandle]] = {name: [] for name in OVERLAYS}
        self.counts: dict[str, int] = dict.fromkeys(OVERLAYS, 0)

    def _clear(self, name: str) -> None:
        for node in self._nodes[name]:
            node.remove()
        self._nodes[name] = []
        self.counts[name] = 0

    def set_enabled(self, name: str, on: bool, scene: Scene) -> None:
        """Show or hide one overlay (one of OVERLAYS); LIDAR points arrive through `show_lidar`."""
        if name not in OVERLAYS:
            raise ValueError(f"unknown overlay {name!r}; overlays: {', '.join(OVERLAYS)}")
        self.enabled[name] = on
        self._clear(name)
        if on and name != "lidar":
            self.refresh(scene, only=name)

    def refresh(self, scene: Scene, only: str | None = None) -> None:
        """Redraw the enabled scene overlays for `scene` (after it changed)."""
        for name in (only,) if only else ("lane_ids", "landmarks", "storyboard"):
            if not self.enabled[name]:
                continue
            self._clear(name)
            nodes = {"lane_ids": self._lane_ids, "landmarks": self._landmarks, "storyboard": self._storyboard}[name]
            self._nodes[name] = nodes(scene)
            self.counts[name] = len(self._nodes[name])

    def _lane_ids(self, scene: Scene) -> list[viser.SceneNodeHandle]:
        nodes: list[viser.SceneNodeHandle] = []
        for lane in scene.roads.lanes:
            middle = len(lane.centreline) // 2
            x, y = lane.centreline[middle]
            z = float(lane_z(lane)[middle]) + LABEL_HEIGHT_M
            nodes.append(self.api.add_label(f"/overlays/lane_ids/{lane.id}", lane.id, position=(x, y, z)))
        return nodes

    def _landmarks(self, scene: Scene) -> list[viser.SceneNodeHandle]:
        return [self.api.add_label(f"/overlays/landmarks/{i}", landmark.name,
                                   position=(*landmark.position, LABEL_HEIGHT_M))
                for i, landmark in enumerate(scene.landmarks)]

    def _storyboard(self, scene: Scene) -> list[viser.SceneNodeHandle]:
        routes, triggers = routes_and_triggers(scene)
        nodes: list[viser.SceneNodeHandle] = []
        for i, route in enumerate(routes):
            points = np.column_stack([np.asarray(route.points, dtype=np.float64), np.full(len(route.points), ROUTE_HEIGHT_M)])
            segments = np.stack([points[:-1], points[1:]], axis=1)
            nodes.append(self.api.add_line_segments(f"/overlays/storyboard/route_{i}", segments, colors=ROUTE_RGB,
                                                    thickness=3.0))
            nodes.append(self.api.add_label(f"/overlays/storyboard/route_{i}/name", route.name,
                                            position=tuple(points[0] + (0.0, 0.0, LABEL_HEIGHT_M))))
        for i, trigger in enumerate(triggers):
            if trigger.position is None:
                continue
            where = (*trigger.position, ROUTE_HEIGHT_M)
            nodes.append(self.api.add_icosphere(f"/overlays/storyboard/trigger_{i}", radius=0.6, color=TRIGGER_RGB,
                                                position=where))
            nodes.append(self.api.add_label(f"/overlays/storyboard/trigger_{i}/text", trigger.text,
                                            position=(0.0, 0.0, LABEL_HEIGHT_M)))
        return nodes

    def show_lidar(self, points: F64 | None) -> None:
        """Draw one LIDAR scan (world-frame points [N,3]); None hides it."""
        self._clear("lidar")
        if points is None or not self.enabled["lidar"]:
            return
        cloud = np.asarray(points, dtype=np.float32).reshape(-1, 3)
        self._nodes["lidar"] = [self.api.add_point_cloud("/overlays/lidar", cloud, colors=LIDAR_RGB,
                                                         point_size=LIDAR_POINT_SIZE_M)]  # fmt: skip
        self.counts["lidar"] = len(cloud)
