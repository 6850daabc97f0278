"""Manoeuvre runners: a storyboard action becomes a controller for one actor, from where it is.

Vehicles are driven through their servos (VehicleRouteRunner's pure pursuit and PI speed
loop) on a route built for the manoeuvre: the lane, the lane shifted sideways (lane change,
cut-in), the lane connection through a junction. Walkers move along their route as mocap
bodies, as plain behaviours do. Nothing is teleported.
"""

from __future__ import annotations

import math

from drivetwin.worlds.behaviours import (
    ARRIVAL_M,
    BehaviourRunner,
    VehicleRouteRunner,
    WalkerRouteRunner,
)
from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.mujoco_bodies import body_kind
from drivetwin.worlds.routes import OffsetRoute, PolylineRoute, Route, junction_route
from drivetwin.worlds.scene import AssetInstance, Scene
from drivetwin.worlds.storyboard import (
    VEHICLE_MANOEUVRES,
    WALKER_MANOEUVRES,
    ChangeSpeed,
    CutIn,
    JunctionTurn,
    KeepLane,
    LaneChange,
    Manoeuvre,
    Reverse,
    Stop,
)
from drivetwin.worlds.vehicles import AckermannGeometry, VehicleController, VehicleState

__all__ = ["ManoeuvreError", "lateral_offset", "manoeuvre_runner"]

# A lane is "along" a vehicle when its direction is within this angle of the heading.
ALONG_RAD = math.pi / 3
# Cut-in: metres per second of extra speed per metre of gap error, and the speed limits
# around the target's speed that the gap controller may ask for (m/s).
GAP_GAIN = 0.5
GAP_SPEED_BELOW_MPS = 3.0
GAP_SPEED_ABOVE_MPS = 6.0
# A lane change over a time covers at least this distance (slow vehicles still blend).
MIN_LANE_CHANGE_M = 8.0
# Speed (m/s) at which a change of speed counts as done.
SPEED_REACHED_MPS = 0.15


class ManoeuvreError(ValueError):
    """A manoeuvre the actor cannot do here (no lane beside it, no junction ahead...)."""


def _always(_world: MujocoWorld, _time: float) -> bool:
    return True


def _now_state(world: MujocoWorld, asset: AssetInstance) -> tuple[VehicleController, VehicleState]:
    vehicle = VehicleController(asset.id, AckermannGeometry.of(asset))
    vehicle.bind(world)
    return vehicle, vehicle.state(world.data)


def _along_lanes(scene: Scene, x: float, y: float, yaw: float) -> list[tuple[float, str, PolylineRoute]]:
    """(distance, id, route) of lanes running along heading `yaw`, nearest first."""
    found = []
    for lane in scene.roads.lanes:
        route = PolylineRoute(lane.centreline)
        s = route.project(x, y)
        if math.cos(route.heading(s) - yaw) > math.cos(ALONG_RAD):
            found.append((route.distance_to(x, y), lane.id, route))
    return sorted(found, key=lambda item: item[0])


def lateral_offset(route: Route, x: float, y: float) -> float:
    """Signed distance of (x, y) from `route` (positive to the left of its direction)."""
    s = route.project(x, y)
    px, py = route.point(s)
    yaw = route.heading(s)
    return -(x - px) * math.sin(yaw) + (y - py) * math.cos(yaw)


def _lane_route(scene: Scene, asset: AssetInstance, state: VehicleState, lane_id: str | None) -> PolylineRoute:
    if lane_id is not None:
        lane = scene.roads.lane(lane_id)
        if lane is None:
            raise ManoeuvreError(f"{asset.id}: no lane {lane_id!r}; lanes: {', '.join(ln.id for ln in scene.roads.lanes)}")
        return PolylineRoute(lane.centreline)
    along = _along_lanes(scene, state.x, state.y, state.yaw)
    if not along:
        raise ManoeuvreError(f"{asset.id}: no lane runs along its heading here")
    return along[0][2]


def _current_route(scene: Scene, asset: AssetInstance, state: VehicleState, current: BehaviourRunner | None) -> Route:
    if isinstance(current, VehicleRouteRunner):
        return current.route
    return _lane_route(scene, asset, state, None)


class ProgressDone(VehicleRouteRunner):
    """A route runner whose manoeuvre ends once the vehicle passes an arc length on its route."""

    end_s: float = math.inf

    def done(self, world: MujocoWorld) -> bool:
        state = self.vehicle.state(world.data)
        return self.route.project(state.x, state.y) >= self.end_s or (
            not self.route.closed and self.route.project(state.x, state.y) >= self.route.length - ARRIVAL_M
        )


class SpeedDone(VehicleRouteRunner):
    """A route runner whose manoeuvre ends once the measured speed reaches the target."""

    def done(self, world: MujocoWorld) -> bool:
        speed = self.vehicle.state(world.data).speed
        return self.speed == self.target_speed and abs(speed - self.target_speed) <= SPEED_REACHED_MPS


class CutInRunner(ProgressDone):
    """Blends into the target's lane while a gap controller holds `gap` metres ahead of it."""

    def __init__(self, asset: AssetInstance, target: AssetInstance, route: Route, gap: float, speed: float) -> None:
        super().__init__(asset, route, speed, _always, "stop")
        self.target_id, self.gap = target.id, gap
        # Bumper to bumper: half of each body's length between the two centres.
        self.half_lengths = (category(asset.category).length * asset.scale + category(target.category).length * target.scale) / 2
        self._last: tuple[float, float] | None = None

    def control(self, world: MujocoWorld, time: float, dt: float) -> None:
        ax, ay, _, _ = world.planar_pose(self.asset_id)
        tx, ty, _, _ = world.planar_pose(self.target_id)
        s_target = self.route.project(tx, ty)
        gap = self.route.project(ax, ay) - s_target - self.half_lengths
        target_speed = 0.0
        if self._last is not None and time > self._last[0]:
            target_speed = max(0.0, (s_target - self._last[1]) / (time - self._last[0]))
        self._last = (time, s_target)
        # The cutter is ahead: too big a gap means slow down, too small speed up.
        wanted = target_speed - GAP_GAIN * (gap - self.gap)
        low = max(0.0, target_speed - GAP_SPEED_BELOW_MPS)
        self.speed = self.target_speed = max(low, min(target_speed + GAP_SPEED_ABOVE_MPS, wanted))
        super().control(world, time, dt)


class ReverseRunner(BehaviourRunner):
    """Backs a vehicle up straight for a distance, then holds it."""

    def __init__(self, asset: AssetInstance, world: MujocoWorld, action: Reverse) -> None:
        self.asset_id = asset.id
        self.vehicle, state = _now_state(world, asset)
        self.origin, self.action = (state.x, state.y), action

    def bind(self, world: MujocoWorld) -> None:
        self.vehicle.bind(world)

    def done(self, world: MujocoWorld) -> bool:
        state = self.vehicle.state(world.data)
        return math.hypot(state.x - self.origin[0], state.y - self.origin[1]) >= self.action.distance

    def control(self, world: MujocoWorld, time: float, dt: float) -> None:
        if self.done(world):
            self.vehicle.brake(world.data)
        else:
            self.vehicle.drive(world.data, -self.action.speed, 0.0, dt)


class WalkerHold(BehaviourRunner):
    """A walker that stands still where it is (a mocap body stays where it was put)."""

    def __init__(self, asset: AssetInstance) -> None:
        self.asset_id = asset.id

    def bind(self, world: MujocoWorld) -> None:
        return None

    def control(self, world: MujocoWorld, time: float, dt: float) -> None:
        return None

    def done(self, world: MujocoWorld) -> bool:
        return True


class WalkerDone(WalkerRouteRunner):
    def done(self, world: MujocoWorld) -> bool:
        x, y, _, _ = world.planar_pose(self.asset_id)
        return self.route.project(x, y) >= self.route.length - 0.05


def manoeuvre_runner(
    action: Manoeuvre, asset: AssetInstance, scene: Scene, world: MujocoWorld, current: BehaviourRunner | None
) -> BehaviourRunner:
    """The runner that plays `action` for `asset` from its state in `world` now.

    Raises ManoeuvreError when the actor cannot do it (a walker told to change lanes, no
    lane beside a vehicle, no junction ahead).
    """
    kind = body_kind(asset)
    if kind == "mocap":
        return _walker_runner(action, asset, world)
    if kind != "vehicle" or action.kind not in VEHICLE_MANOEUVRES:
        raise ManoeuvreError(f"{asset.id} ({asset.category}) cannot {action.kind}")
    _, state = _now_state(world, asset)
    if isinstance(action, KeepLane):
        route = _lane_route(scene, asset, state, action.lane)
        lane_runner = VehicleRouteRunner(asset, route, action.speed, _always, "loop")
        return lane_runner
    if isinstance(action, ChangeSpeed | Stop):
        target = action.speed if isinstance(action, ChangeSpeed) else 0.0
        rate = action.rate if isinstance(action, ChangeSpeed) else action.deceleration
        at_end = current.at_end if isinstance(current, VehicleRouteRunner) else "stop"
        ramp = SpeedDone(asset, _current_route(scene, asset, state, current), max(0.0, state.speed), _always, at_end)
        ramp.target_speed, ramp.rate = target, rate
        return ramp
    if isinstance(action, LaneChange):
        base = _current_route(scene, asset, state, current)
        offset = _side_lane_offset(scene, state, base, action.side, action.lanes, asset.id)
        speed = max(state.speed, 1.0)
        span = action.value if action.over == "distance" else max(MIN_LANE_CHANGE_M, speed * action.value)
        s0 = base.project(state.x, state.y)
        shifted = OffsetRoute(base, s0, span, lateral_offset(base, state.x, state.y), offset)
        runner = ProgressDone(asset, shifted, _asked_speed(current, state), _always, "stop")
        runner.end_s = s0 + span
        return runner
    if isinstance(action, CutIn):
        return _cut_in(action, asset, scene, world, state)
    if isinstance(action, JunctionTurn):
        lanes = [(lane.id, lane.centreline) for lane in scene.roads.lanes]
        boxes = [area.polygon for area in scene.roads.paved if area.kind == "intersection"]
        try:
            route, s_exit = junction_route(lanes, boxes, state.x, state.y, state.yaw, action.turn)
        except LookupError as exc:
            raise ManoeuvreError(f"{asset.id}: {exc}") from exc
        runner = ProgressDone(asset, route, action.speed, _always, "stop")
        runner.end_s = s_exit
        return runner
    if action.kind == "follow_route":
        route = PolylineRoute(action.waypoints)
        return ProgressDone(asset, route, action.speed, _always, "stop")
    assert isinstance(action, Reverse)
    return ReverseRunner(asset, world, action)


def _asked_speed(current: BehaviourRunner | None, state: VehicleState) -> float:
    if isinstance(current, VehicleRouteRunner) and current.speed > 0.0:
        return current.speed
    return max(state.speed, 1.0)


def _side_lane_offset(scene: Scene, state: VehicleState, base: Route, side: str, count: int, actor: str) -> float:
    """Lateral offset (from `base`) of the `count`-th lane on `side` of the vehicle."""
    here = lateral_offset(base, state.x, state.y)
    offsets = []
    for lane in scene.roads.lanes:
        route = PolylineRoute(lane.centreline)
        s = route.project(state.x, state.y)
        parallel = abs(math.cos(route.heading(s) - base.heading(base.project(state.x, state.y))))
        if parallel < math.cos(ALONG_RAD):
            continue
        px, py = route.point(s)
        d = lateral_offset(base, px, py)
        if (d - here > lane.width / 2) if side == "left" else (here - d > lane.width / 2):
            offsets.append(d)
    offsets.sort(key=lambda d: abs(d - here))
    if len(offsets) < count:
        raise ManoeuvreError(f"{actor}: no lane {count} to the {side} of it here")
    return offsets[count - 1]


def _cut_in(action: CutIn, asset: AssetInstance, scene: Scene, world: MujocoWorld, state: VehicleState) -> BehaviourRunner:
    target = scene.asset(action.target)
    if target is None:
        raise ManoeuvreError(f"{asset.id}: cut-in target {action.target!r} is not in the scene")
    tx, ty, _, tyaw = world.planar_pose(target.id)
    along = _along_lanes(scene, tx, ty, tyaw)
    if not along:
        raise ManoeuvreError(f"{asset.id}: the target {target.id} is not on a lane")
    base = along[0][2]
    s0 = base.project(state.x, state.y)
    span = max(MIN_LANE_CHANGE_M, max(state.speed, 1.0) * action.duration)
    shifted = OffsetRoute(base, s0, span, lateral_offset(base, state.x, state.y), 0.0)
    runner = CutInRunner(asset, target, shifted, action.gap, max(state.speed, 1.0))
    runner.end_s = s0 + span
    return runner


def _walker_runner(action: Manoeuvre, asset: AssetInstance, world: MujocoWorld) -> BehaviourRunner:
    if action.kind not in WALKER_MANOEUVRES:
        raise ManoeuvreError(f"{asset.id} ({asset.category}) cannot {action.kind}; walkers can "
                             f"{', '.join(sorted(WALKER_MANOEUVRES))}")
    x, y, _, _ = world.planar_pose(asset.id)
    if action.kind == "stop":
        return WalkerHold(asset)
    if action.kind == "follow_route":
        route, speed = PolylineRoute([(x, y), *action.waypoints]), action.speed
    elif action.kind == "cross_road":
        route, speed = PolylineRoute([(x, y), action.end]), action.speed
    else:
        assert action.kind == "stop_mid_road"
        sx, sy = action.start
        ex, ey = action.end
        stop = (sx + action.fraction * (ex - sx), sy + action.fraction * (ey - sy))
        route, speed = PolylineRoute([(x, y), stop]), action.speed
    runner = WalkerDone(asset, route, speed, _always, "stop")
    runner.z = asset.pose.z
    return runner
