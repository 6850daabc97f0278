"""Behaviour runners: the data-only behaviours of scene assets, run in the simulation loop.

One runner per moving asset. Vehicles are driven through their servos (pure pursuit on a
route, PI on speed); walkers are kinematic mocap bodies placed along their route each
control tick. Props ignore behaviours (they only move when something pushes them).

| behaviour   | route                          | starts                         | at the end      |
| parked      | none                           | -                              | brakes          |
| drive_lane  | the lane centreline            | now                            | back to start   |
| follow_path | the waypoints (closed if loop) | at start_time                  | loops or stops  |
| circle      | the circle                     | now                            | keeps circling  |
| cross_road  | start → end                    | at start_time                  | stops           |
| jaywalk     | start → end                    | ego within trigger_distance of | stops           |
|             |                                | where it crosses the ego lane  |                 |
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Literal

import mujoco
import numpy as np
from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld, collision_groups
from drivetwin.worlds.mujoco_bodies import body_kind
from drivetwin.worlds.routes import (
    CircleRoute,
    PolylineRoute,
    Route,
    segment_polyline_intersection,
)
from drivetwin.worlds.scene import EGO_ID, AssetInstance, DriveLane, Scene
from drivetwin.worlds.vehicles import AckermannGeometry, VehicleController, VehicleState, pure_pursuit_curvature

__all__ = [
    "SENSE_SIDES",
    "STOP_GAP_M",
    "BehaviourRunner",
    "UnknownLaneError",
    "VehicleParkedRunner",
    "VehicleRouteRunner",
    "WalkerRouteRunner",
    "clear_distance",
    "jaywalk_crossing_point",
    "runner_for",
]

# Pure-pursuit lookahead: this many seconds of travel, but at least this many wheelbases
# (short lookaheads oscillate) and at most the circle radius (longer ones cut the circle).
LOOKAHEAD_S = 0.8
LOOKAHEAD_MIN_WHEELBASES = 1.5
# A vehicle within this distance of the end of an open route has arrived.
ARRIVAL_M = 1.0
# Vehicles stop this far short of whatever stands in their path (a cone, a barrier, a
# pedestrian, another car), planning to brake this hard (m/s², below what the tyres give).
STOP_GAP_M = 2.0
BRAKE_DECEL = 2.5
# Obstacle rays run level this high above the road: over kerbs and road paint, under every
# catalog obstacle's top (rubble is 0.6 m, cones 0.7 m); at the centre and near both sides.
SENSE_HEIGHT_M = 0.3
SENSE_SIDES = (-0.8, 0.0, 0.8)
# A vehicle looks at least this far ahead, more when its stopping distance is longer.
MIN_SENSE_M = 8.0
# A ray that hits the vehicle itself restarts this far past the hit, at most this often.
RAY_STEP_M = 0.01
OWN_HITS_SKIPPED = 4
# A red light's stop line counts for a vehicle whose route passes within this distance of it;
# the vehicle plans to stop with its front bumper this far short of the line, braking this
# gently (m/s², below BRAKE_DECEL: the speed loop lags a planned stop by about 1 m/s).
STOP_LINE_ON_ROUTE_M = 1.5
STOP_LINE_MARGIN_M = 1.0
STOP_LINE_DECEL = 1.8
# A front bumper up to this far past a red line still holds (it overshot; the junction is beyond).
LINE_OVERSHOOT_M = 3.0
# Below this asked and measured speed (m/s) a vehicle told to stop holds its wheels.
STANDSTILL_MPS = 0.05
# A vehicle that stops at the end of its route plans to brake this gently (m/s², as for a red
# line) to come to rest there.
ARRIVAL_DECEL = STOP_LINE_DECEL

AtEnd = Literal["loop", "stop"]
StartCondition = Callable[[MujocoWorld, float], bool]


class UnknownLaneError(LookupError):
    """A drive_lane behaviour that names a lane the scene does not have."""

    def __init__(self, asset_id: str, lane: str, known: list[str]) -> None:
        self.asset_id, self.lane, self.known = asset_id, lane, known
        super().__init__(lane)

    def __str__(self) -> str:
        return f"{self.asset_id}: unknown lane {self.lane!r}; lanes: {', '.join(self.known) or 'none'}"


class BehaviourRunner:
    """Runs one asset's behaviour: `bind` after every recompile, `control` every tick."""

    asset_id: str

    def bind(self, world: MujocoWorld) -> None:
        raise NotImplementedError

    def done(self, world: MujocoWorld) -> bool:
        """Whether a manoeuvre this runner plays has ended (a plain behaviour never ends)."""
        return False

    def control(self, world: MujocoWorld, time: float, dt: float) -> None:
        raise NotImplementedError


@dataclass
class _Start:
    """Latches a start condition and remembers when it first held."""

    condition: StartCondition
    started_at: float | None = None

    def elapsed(self, world: MujocoWorld, time: float) -> float | None:
        if self.started_at is None and self.condition(world, time):
            self.started_at = time
        return None if self.started_at is None else time - self.started_at


def _at_time(start_time: float) -> StartCondition:
    return lambda _world, time: time >= start_time


def _ego_within(point: tuple[float, float], distance: float) -> StartCondition:
    def near(world: MujocoWorld, _time: float) -> bool:
        x, y, _, _ = world.planar_pose(EGO_ID)
        return math.hypot(x - point[0], y - point[1]) <= distance

    return near


class VehicleParkedRunner(BehaviourRunner):
    """Holds a vehicle's wheels and steering (so a vehicle told to park stops driving)."""

    def __init__(self, asset: AssetInstance) -> None:
        self.asset_id = asset.id
        self.vehicle = VehicleController(asset.id, AckermannGeometry.of(asset))

    def bind(self, world: MujocoWorld) -> None:
        self.vehicle.bind(world)

    def control(self, world: MujocoWorld, time: float, dt: float) -> None:
        self.vehicle.brake(world.data)


class VehicleRouteRunner(BehaviourRunner):
    """Drives a vehicle along a route at a speed with pure pursuit, once started."""

    def __init__(self, asset: AssetInstance, route: Route, speed: float, start: StartCondition, at_end: AtEnd) -> None:
        self.asset_id = asset.id
        self.vehicle = VehicleController(asset.id, AckermannGeometry.of(asset))
        self.route, self.at_end = route, at_end
        # The speed asked for now; with a `rate` (m/s²) it ramps towards `target_speed`.
        self.speed = self.target_speed = speed
        self.rate: float | None = None
        # Stop lines of red lights (set by the storyboard player every tick).
        self.red_stops: Sequence[tuple[float, float]] = ()
        self.start = _Start(start)
        # How far along the route the vehicle was last tick (None: not yet known, or it looped).
        self.progress: float | None = None
        shape = category(asset.category)
        # From the rear axle (where VehicleState is) to the front bumper, and half the width.
        self.front_m = (shape.length / 2 + self.vehicle.geometry.wheelbase / 2) * asset.scale
        self.half_width_m = shape.width / 2 * asset.scale

    def bind(self, world: MujocoWorld) -> None:
        self.vehicle.bind(world)

    def lookahead(self) -> float:
        distance = max(LOOKAHEAD_S * self.speed, LOOKAHEAD_MIN_WHEELBASES * self.vehicle.geometry.wheelbase)
        if isinstance(self.route, CircleRoute):
            distance = min(distance, self.route.radius)
        return float(distance)

    def control(self, world: MujocoWorld, time: float, dt: float) -> None:
        data = world.data
        if self.start.elapsed(world, time) is None:
            self.vehicle.brake(data)
            return
        if self.rate is not None:
            step = self.rate * dt
            self.speed += max(-step, min(step, self.target_speed - self.speed))
        state = self.vehicle.state(data)
        if self.speed <= STANDSTILL_MPS and abs(state.speed) <= STANDSTILL_MPS * 4:
            self.vehicle.brake(data)
            return
        s = self.route.project(state.x, state.y) if self.progress is None else (
            self.route.follow(state.x, state.y, self.progress))
        self.progress = s
        if not self.route.closed and s >= self.route.length - ARRIVAL_M:
            if self.at_end == "stop":
                self.vehicle.brake(data)
                return
            # An open lane loops by putting the vehicle back at its start, speed kept.
            x0, y0 = self.route.point(0.0)
            yaw = self.route.heading(0.0)
            half = self.vehicle.geometry.wheelbase / 2
            self.vehicle.teleport(data, x0 + half * math.cos(yaw), y0 + half * math.sin(yaw), yaw)
            self.progress = None
            return
        tx, ty = self.pursuit_point(s)
        curvature = pure_pursuit_curvature(state.x, state.y, state.yaw, tx, ty)
        speed = self.safe_speed(world, state, tx, ty)
        if not self.route.closed and self.at_end == "stop":
            # Braking to arrive: a vehicle at speed when it reached the end would overshoot it.
            to_end = self.route.length - s - ARRIVAL_M / 2
            speed = min(speed, math.sqrt(2 * ARRIVAL_DECEL * max(0.0, to_end)))
        self.vehicle.drive(data, speed, curvature, dt)

    def pursuit_point(self, s: float) -> tuple[float, float]:
        """The point a lookahead ahead of arc length `s`; past the end of an open route, on the
        line of its last heading: aimed at the end itself, a vehicle that comes to it off line
        circles it, its turn too tight to steer."""
        ahead = s + self.lookahead()
        if self.route.closed or ahead <= self.route.length:
            return self.route.point(ahead)
        (ex, ey), heading = self.route.point(self.route.length), self.route.heading(self.route.length)
        over = ahead - self.route.length
        return ex + over * math.cos(heading), ey + over * math.sin(heading)

    def safe_speed(self, world: MujocoWorld, state: VehicleState, tx: float, ty: float) -> float:
        """The route speed, lowered so the vehicle can stop STOP_GAP_M short of an obstacle.

        Rays go from the front bumper towards the pursuit point, so on a curve they follow
        the path rather than the heading.
        """
        reach = max(MIN_SENSE_M, self.speed**2 / (2 * BRAKE_DECEL) + STOP_GAP_M)
        gap = clear_distance(world, self.asset_id, state, (tx, ty), self.front_m, self.half_width_m, reach)
        free = gap - STOP_GAP_M
        red_speed = math.sqrt(2 * STOP_LINE_DECEL * max(0.0, self.red_light_distance(state) - STOP_LINE_MARGIN_M))
        return min(self.speed, red_speed, math.sqrt(2 * BRAKE_DECEL * max(0.0, free)))

    def red_light_distance(self, state: VehicleState) -> float:
        """Distance along the route from the front bumper to the nearest red stop line ahead."""
        nearest = math.inf
        if not self.red_stops:
            return nearest
        fx = state.x + self.front_m * math.cos(state.yaw)
        fy = state.y + self.front_m * math.sin(state.yaw)
        s_front = self.route.project(fx, fy)
        for sx, sy in self.red_stops:
            s_line = self.route.project(sx, sy)
            px, py = self.route.point(s_line)
            if math.hypot(px - sx, py - sy) > STOP_LINE_ON_ROUTE_M:
                continue
            ahead = s_line - s_front
            if self.route.closed and ahead < 0.0:
                ahead += self.route.length
            if ahead >= -LINE_OVERSHOOT_M:
                nearest = min(nearest, ahead)
        return nearest


def clear_distance(
    world: MujocoWorld,
    asset_id: str,
    state: VehicleState,
    towards: tuple[float, float],
    front_m: float,
    half_width_m: float,
    reach: float,
) -> float:
    """Free distance from a vehicle's front bumper towards `towards`, up to `reach` (metres).

    Level rays from the bumper's centre and near its corners hit collision geometry only
    (not road paint or visual-only parts); the vehicle's own bodies are never hit.
    """
    heading = math.atan2(towards[1] - state.y, towards[0] - state.x)
    model, data = world.model, world.data
    own_root = model.body_rootid[world.body_id(asset_id)]
    cos_h, sin_h = math.cos(state.yaw), math.sin(state.yaw)
    direction = np.array([math.cos(heading), math.sin(heading), 0.0])
    groups = collision_groups(model)
    geom = np.zeros(1, np.int32)
    nearest = reach
    for side in SENSE_SIDES:
        offset = side * half_width_m
        origin = np.array([
            state.x + front_m * cos_h - offset * sin_h,
            state.y + front_m * sin_h + offset * cos_h,
            SENSE_HEIGHT_M,
        ])
        travelled = 0.0
        # A ray may first graze the vehicle's own bumper or wheel: step past it and cast again.
        for _ in range(OWN_HITS_SKIPPED):
            distance = mujoco.mj_ray(model, data, origin, direction, groups, 1, -1, geom)
            if distance < 0.0 or travelled + distance >= nearest:
                break
            if model.body_rootid[model.geom_bodyid[geom[0]]] != own_root:
                nearest = travelled + distance
                break
            step = distance + RAY_STEP_M
            origin = origin + step * direction
            travelled += step
    return float(nearest)


class WalkerRouteRunner(BehaviourRunner):
    """Moves a kinematic (mocap) walker along a route at a speed, once started."""

    def __init__(
        self,
        asset: AssetInstance,
        route: Route,
        speed: float,
        start: StartCondition,
        at_end: AtEnd,
        s0: float = 0.0,
    ) -> None:
        self.asset_id = asset.id
        self.route, self.speed, self.at_end, self.s0 = route, speed, at_end, s0
        self.z = asset.pose.z
        self.start = _Start(start)
        self._mocap = -1
        self._generation = -1

    def bind(self, world: MujocoWorld) -> None:
        if self._generation != world.generation:
            self._mocap = int(world.model.body_mocapid[world.body_id(self.asset_id)])
            self._generation = world.generation

    def arc_length(self, world: MujocoWorld, time: float) -> float:
        """How far along the route the walker is at `time`."""
        elapsed = self.start.elapsed(world, time)
        s = self.s0 + self.speed * (elapsed or 0.0)
        if self.at_end == "loop":
            return float(s % self.route.length)
        return float(min(s, self.route.length))

    def control(self, world: MujocoWorld, time: float, dt: float) -> None:
        s = self.arc_length(world, time)
        x, y = self.route.point(s)
        yaw = self.route.heading(s)
        world.data.mocap_pos[self._mocap] = (x, y, self.z)
        world.data.mocap_quat[self._mocap] = (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))


def jaywalk_crossing_point(scene: Scene, start: tuple[float, float], end: tuple[float, float]) -> tuple[float, float]:
    """Where a start→end walk crosses the ego's lane centreline; its midpoint if it does not."""
    behaviour = scene.ego.behaviour
    if isinstance(behaviour, DriveLane):
        lane = scene.roads.lane(behaviour.lane)
        if lane is not None:
            hit = segment_polyline_intersection(start, end, lane.centreline)
            if hit is not None:
                return (float(hit[0]), float(hit[1]))
    return ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2)


def _lane_route(scene: Scene, asset: AssetInstance, lane_id: str) -> PolylineRoute:
    lane = scene.roads.lane(lane_id)
    if lane is None:
        raise UnknownLaneError(asset.id, lane_id, [lane.id for lane in scene.roads.lanes])
    points = lane.centreline
    closed = len(points) > 2 and math.dist(points[0], points[-1]) < 1e-6
    return PolylineRoute(points, closed=closed)


def runner_for(asset: AssetInstance, scene: Scene) -> BehaviourRunner | None:
    """The runner for `asset`'s behaviour, or None when nothing needs running.

    Raises UnknownLaneError for a drive_lane behaviour on a lane the scene does not have.
    """
    kind = body_kind(asset)
    if kind not in ("vehicle", "mocap"):
        return None
    b = asset.behaviour
    now: StartCondition = _at_time(0.0)
    route: Route
    at_end: AtEnd = "stop"
    start = now
    if b.kind == "parked":
        return VehicleParkedRunner(asset) if kind == "vehicle" else None
    if b.kind == "drive_lane":
        route, at_end = _lane_route(scene, asset, b.lane), "loop"
    elif b.kind == "follow_path":
        route = PolylineRoute(b.waypoints, closed=b.loop)
        at_end, start = ("loop" if b.loop else "stop"), _at_time(b.start_time)
    elif b.kind == "circle":
        route, at_end = CircleRoute(b.centre, b.radius, b.clockwise), "loop"
    elif b.kind == "cross_road":
        route, start = PolylineRoute([b.start, b.end]), _at_time(b.start_time)
    else:
        point = jaywalk_crossing_point(scene, b.start, b.end)
        route, start = PolylineRoute([b.start, b.end]), _ego_within(point, b.trigger_distance)
    if kind == "vehicle":
        return VehicleRouteRunner(asset, route, b.speed, start, at_end)
    # Walkers on lanes and circles join their route where they were put; others at its start.
    s0 = route.project(asset.pose.x, asset.pose.y) if b.kind in ("drive_lane", "circle") else 0.0
    return WalkerRouteRunner(asset, route, b.speed, start, at_end, s0)
