"""Scenario Workers: events ("when … then …"), timed manoeuvres and traffic-light phases.

They edit the Scene's storyboard (drivetwin.worlds.storyboard) through one SetStoryboard
operation, so undo, redo, the journal and save/load cover them like any edit. A planner
names a manoeuvre and a trigger in words-like fields (`ManoeuvreSpec`, `TriggerSpec`);
these Workers turn them into storyboard actions and conditions with concrete geometry
(where a pedestrian's walk across the road ends, where a light's stop line is), and refuse
what an actor cannot do (a pedestrian changing lanes, a car with no lane beside it).
"""

from __future__ import annotations

import math
from typing import Literal

from drivetwin.tools.base import Tool, ToolArgs, ToolResult
from drivetwin.tools.errors import NotFoundError, RuleViolation
from drivetwin.tools.locate import resolve_target
from drivetwin.tools.move import find_asset
from drivetwin.worlds.catalog import category
from drivetwin.worlds.edits import SetStoryboard, WorldEdit
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Scene
from drivetwin.worlds.storyboard import (
    VEHICLE_MANOEUVRES,
    WALKER_MANOEUVRES,
    ChangeSpeed,
    Condition,
    CrossRoadManoeuvre,
    CutIn,
    DistanceCondition,
    Event,
    EventEndCondition,
    FollowRoute,
    JunctionTurn,
    KeepLane,
    LaneChange,
    LightPhase,
    Manoeuvre,
    ReachPositionCondition,
    Reverse,
    SetLight,
    SimulationTimeCondition,
    Stop,
    StopLine,
    StopMidRoad,
    TimeToCollisionCondition,
    TrafficLight,
)
from drivetwin.worlds.surface import (
    DRIVABLE,
    nearest_lane,
    nearest_on_polyline,
    point_along,
    point_in_polygon,
    surface_at,
)
from pydantic import Field

__all__ = ["AddEvent", "AddManoeuvre", "ManoeuvreSpec", "SetLightPhases", "TriggerSpec"]

ManoeuvreKind = Literal[
    "keep_lane", "change_speed", "stop", "lane_change", "cut_in", "junction_turn", "follow_route",
    "cross_road", "stop_mid_road", "reverse", "set_light",
]
# A traffic light governs the lanes it stands to the right of (within this distance) that
# run into a junction within this distance of it: traffic drives on the right.
LIGHT_REACH_M = 12.0
# Vehicles stop this far before a crossing that lies just before the light.
CROSSING_CLEARANCE_M = 1.0
# The time a vehicle's braking takes to build up in the physics: it covers this many seconds of its speed first.
BRAKE_LAG_S = 0.5
# A walker's walk across the road ends this far past the last drivable point.
KERB_STEP_M = 0.5
MAX_CROSSING_M = 40.0
# "Reach a place" holds within this radius of the place.
REACH_TOLERANCE_M = 3.0
# A place this far from every lane's edge is reached by a vehicle where its lane passes it; further, never.
KERBSIDE_REACH_M = 25.0


class ManoeuvreSpec(ToolArgs):
    """What the actor does; only the fields of the chosen kind are used, the rest default."""

    kind: ManoeuvreKind = Field(description=(
        "keep_lane (drive on at speed), change_speed (speed up/slow down at rate), stop (brake at "
        "rate to a halt), lane_change (side), cut_in (into target's lane ahead of it at gap), "
        "junction_turn (turn at the next junction), follow_route (waypoints), cross_road (a "
        "pedestrian walks across), stop_mid_road (walks out and stops in the road), reverse "
        "(distance), set_light (a traffic light's state)"))
    speed: float | None = Field(None, ge=0.0, le=40.0, description="target speed, m/s")
    rate: float | None = Field(None, gt=0.0, le=12.0, description="acceleration or braking, m/s² (hard braking ≈ 6)")
    side: Literal["left", "right"] | None = Field(None, description="lane_change direction")
    duration: float | None = Field(None, gt=0.5, le=20.0, description="seconds a lane change or cut-in takes")
    target: str | None = Field(None, description="cut_in: the asset to cut in front of (default ego)")
    gap: float | None = Field(None, gt=0.0, le=100.0, description="cut_in: metres left ahead of the target")
    turn: Literal["left", "right", "straight"] | None = Field(None, description="junction_turn direction")
    waypoints: list[tuple[float, float]] | None = Field(None, description="follow_route: [[x, y], ...] metres")
    distance: float | None = Field(None, gt=0.0, le=200.0, description="reverse: metres to back up")
    state: Literal["red", "amber", "green"] | None = Field(None, description="set_light: the light's new state")


class TriggerSpec(ToolArgs):
    """When the manoeuvre starts."""

    kind: Literal["time", "distance", "time_to_collision", "reach", "after_event"] = Field(description=(
        "time (seconds after the scenario starts), distance (between `actor` and `other` drops "
        "below metres), time_to_collision (of `actor` and `other`, seconds), reach (`actor` "
        "reaches `place`), after_event (another event ended)"))
    seconds: float | None = Field(None, ge=0.0, le=3600.0, description="time or time_to_collision seconds")
    actor: str = Field(EGO_ID, description="whose distance or position is watched (default ego)")
    other: str | None = Field(None, description="distance/time_to_collision: the other asset (default: the event's actor)")
    metres: float | None = Field(None, gt=0.0, le=500.0, description="distance threshold, metres")
    rule: Literal["less", "greater"] = Field("less", description="distance: fires when less (closer) or greater")
    place: str | None = Field(None, description="reach: landmark, asset id or 'x, y'")
    event: str | None = Field(None, description="after_event: the name of the event that must end")


class EventArgs(ToolArgs):
    actor: str = Field(description="id of the asset that acts (e.g. passenger_car_2, pedestrian_1, ego), "
                                   "or a traffic_light id for set_light")
    manoeuvre: ManoeuvreSpec
    when: TriggerSpec
    name: str | None = Field(None, pattern=r"^[A-Za-z][A-Za-z0-9_]{0,63}$", description="event name (default: made up)")


class ManoeuvreArgs(ToolArgs):
    actor: str = Field(description="id of the asset that acts (e.g. passenger_car_2, pedestrian_1, ego)")
    manoeuvre: ManoeuvreSpec
    at_time: float = Field(0.0, ge=0.0, le=3600.0, description="seconds after the scenario starts")
    after_previous: bool = Field(False, description="start when this actor's previous manoeuvre ends instead")


class PhaseSpec(ToolArgs):
    state: Literal["red", "amber", "green"]
    duration: float = Field(gt=0.0, le=600.0, description="seconds")


class LightArgs(ToolArgs):
    light: str = Field(description="id of a traffic_light asset, e.g. traffic_light_1")
    phases: list[PhaseSpec] = Field(min_length=1, max_length=8, description=(
        "the cycle in order, e.g. green 20 s, amber 3 s, red 20 s; one phase holds that state"))
    offset: float = Field(0.0, ge=0.0, le=600.0, description="seconds into the cycle at the start")


def _kind_of(asset: AssetInstance) -> str:
    return category(asset.category).motion


def _walk_across(scene: Scene, walker: AssetInstance) -> tuple[tuple[float, float], tuple[float, float]]:
    """From the walker's spot, straight across the nearest lane's road to the far kerb."""
    if not scene.roads.lanes:
        raise NotFoundError("this world has no lanes to cross")
    x, y = walker.pose.x, walker.pose.y
    near = min((nearest_on_polyline(x, y, ln.centreline) for ln in scene.roads.lanes), key=lambda p: p.distance)
    heading = math.atan2(near.y - y, near.x - x) if near.distance > 0.1 else near.heading + math.pi / 2
    seen_road, d = False, 0.0
    while d < MAX_CROSSING_M:
        d += KERB_STEP_M
        px, py = x + d * math.cos(heading), y + d * math.sin(heading)
        on_road = surface_at(scene, px, py) in DRIVABLE
        if on_road:
            seen_road = True
        elif seen_road:
            return (x, y), (px, py)
    raise RuleViolation("surface", f"{walker.id} has no road to cross within {MAX_CROSSING_M:g} m")


def build_manoeuvre(scene: Scene, asset: AssetInstance, spec: ManoeuvreSpec) -> Manoeuvre:
    """The storyboard action for `spec` done by `asset`; RuleViolation if it cannot do it."""
    kind = spec.kind
    if kind == "set_light":
        if asset.category != "traffic_light" or spec.state is None:
            raise RuleViolation("behaviour", "set_light needs a traffic_light actor and a state (red, amber, green)")
        return SetLight(light=asset.id, state=spec.state)
    motion = _kind_of(asset)
    allowed = VEHICLE_MANOEUVRES if motion == "vehicle" else WALKER_MANOEUVRES if motion == "walker" else frozenset()
    if kind not in allowed:
        what = ", ".join(sorted(allowed)) or "nothing (it is a prop)"
        raise RuleViolation("behaviour", f"a {asset.category} cannot {kind}; it can: {what}")
    if kind == "keep_lane":
        return KeepLane(speed=spec.speed if spec.speed is not None else 5.0)
    if kind == "change_speed":
        if spec.speed is None:
            raise RuleViolation("behaviour", "change_speed needs a target speed in m/s")
        return ChangeSpeed(speed=spec.speed, rate=spec.rate or 2.0)
    if kind == "stop":
        return Stop(deceleration=spec.rate or 3.0)
    if kind == "lane_change":
        if spec.side is None:
            raise RuleViolation("behaviour", "lane_change needs a side: left or right")
        _lane_beside(scene, asset, spec.side)
        return LaneChange(side=spec.side, over="time", value=spec.duration or 3.0)
    if kind == "cut_in":
        target = find_asset(scene, spec.target or EGO_ID)
        if target.id == asset.id:
            raise RuleViolation("behaviour", f"{asset.id} cannot cut in front of itself")
        return CutIn(target=target.id, gap=spec.gap or 8.0, duration=spec.duration or 3.0)
    if kind == "junction_turn":
        if spec.turn is None:
            raise RuleViolation("behaviour", "junction_turn needs a turn: left, right or straight")
        if not any(area.kind == "intersection" for area in scene.roads.paved):
            raise NotFoundError("this world has no junction to turn at")
        return JunctionTurn(turn=spec.turn, speed=spec.speed or 5.0)
    if kind == "follow_route":
        if not spec.waypoints or len(spec.waypoints) < 2:
            raise RuleViolation("behaviour", "follow_route needs at least two waypoints [[x, y], ...]")
        return FollowRoute(waypoints=spec.waypoints, speed=spec.speed or (5.0 if motion == "vehicle" else 1.4))
    if kind == "reverse":
        return Reverse(distance=spec.distance or 5.0, speed=min(spec.speed or 1.5, 5.0))
    start, end = _walk_across(scene, asset)
    walk = min(spec.speed or 1.4, 10.0)
    if kind == "cross_road":
        return CrossRoadManoeuvre(start=start, end=end, speed=walk)
    return StopMidRoad(start=start, end=end, speed=walk)


def _lane_beside(scene: Scene, asset: AssetInstance, side: str) -> None:
    """Refuse a lane change with no lane on that side of the vehicle (a static check)."""
    x, y, yaw = asset.pose.x, asset.pose.y, asset.pose.yaw
    for lane in scene.roads.lanes:
        near = nearest_on_polyline(x, y, lane.centreline)
        left = -(near.x - x) * math.sin(yaw) + (near.y - y) * math.cos(yaw)
        if abs(math.cos(near.heading - yaw)) > 0.5 and (left > lane.width / 2 if side == "left" else left < -lane.width / 2):
            return
    raise RuleViolation("behaviour", f"there is no lane to the {side} of {asset.id} where it is")


def build_condition(scene: Scene, actor: str, spec: TriggerSpec) -> Condition:
    """The storyboard start condition for `spec`; NotFoundError for unknown assets or places."""
    if spec.kind == "time":
        return SimulationTimeCondition(time=spec.seconds or 0.0)
    if spec.kind == "after_event":
        if not spec.event or scene.storyboard.event(spec.event) is None:
            names = ", ".join(e.name for _, e in scene.storyboard.events()) or "none yet"
            raise NotFoundError(f"no event {spec.event!r} to wait for; events: {names}")
        return EventEndCondition(event=spec.event)
    watched = find_asset(scene, spec.actor).id
    if spec.kind == "reach":
        if not spec.place:
            raise RuleViolation("trigger", "a reach trigger needs a place")
        target = resolve_target(scene, spec.place)
        position = (target.x, target.y)
        lanes = scene.roads.lanes
        if category(find_asset(scene, watched).category).drives and lanes:
            # A vehicle keeps to the lanes: "stop at the library" is where its lane passes the library (the
            # lane's point nearest it), and a place no lane passes near ("near the fountain") is never reached.
            actor_at = find_asset(scene, watched).pose
            own = nearest_lane(scene, actor_at.x, actor_at.y)  # its own lane first: the point it will drive through
            lane = own if own is not None and nearest_on_polyline(target.x, target.y, own.centreline).distance - own.width / 2 \
                <= KERBSIDE_REACH_M else min(lanes, key=lambda ln: nearest_on_polyline(target.x, target.y, ln.centreline).distance)
            nearest = nearest_on_polyline(target.x, target.y, lane.centreline)
            if nearest.distance - lane.width / 2 > KERBSIDE_REACH_M:
                raise RuleViolation("trigger", f"{watched} drives on the roads and never comes near {target.name} "
                                    f"({nearest.distance - lane.width / 2:.0f} m from the nearest lane); name a place on "
                                    "its way, or a distance from another actor")
            if nearest.distance > lane.width / 2 + REACH_TOLERANCE_M:
                position = (nearest.x, nearest.y)
        return ReachPositionCondition(actor=watched, position=position, tolerance=REACH_TOLERANCE_M)
    other = find_asset(scene, spec.other or actor).id
    if other == watched:
        raise RuleViolation("trigger", f"a {spec.kind} trigger needs two different assets, got {watched} twice")
    if spec.kind == "distance":
        if spec.metres is None:
            raise RuleViolation("trigger", "a distance trigger needs metres")
        return DistanceCondition(actor=watched, target=other, distance=spec.metres, rule=spec.rule)
    if spec.seconds is None or spec.seconds <= 0.0:
        raise RuleViolation("trigger", "a time_to_collision trigger needs seconds > 0")
    return TimeToCollisionCondition(actor=watched, target=other, seconds=spec.seconds)


def _add(scene: Scene, asset: AssetInstance, action: Manoeuvre, start: Condition, name: str | None) -> ToolResult:
    board = scene.storyboard
    if name is not None and board.event(name) is not None:
        raise RuleViolation("name", f"an event called {name!r} already exists")
    event = Event(name=name or board.next_event_name(f"{asset.id}_{action.kind}"), action=action, start=start)
    actor = None if isinstance(action, SetLight) else asset.id
    after = board.with_event(actor, event)
    if isinstance(action, SetLight) and after.light(asset.id) is None:
        # A light set by an event needs its stop lines; until the event it stays green.
        after = after.with_light(_light_plan(scene, asset, [LightPhase(state="green", duration=600.0)], 0.0))
    edit = WorldEdit(ops=(SetStoryboard(before=board, after=after),))
    text = f"event {event.name}: {asset.id} will {action.kind} when {_describe(start)}"
    return ToolResult(edit, text, (asset.pose.x, asset.pose.y), {"event": event.name})


def _describe(condition: Condition) -> str:
    if isinstance(condition, SimulationTimeCondition):
        return f"t = {condition.time:g} s"
    if isinstance(condition, DistanceCondition):
        return f"{condition.actor} is {condition.rule} than {condition.distance:g} m from {condition.target}"
    if isinstance(condition, TimeToCollisionCondition):
        return f"{condition.actor} is {condition.seconds:g} s from reaching {condition.target}"
    if isinstance(condition, ReachPositionCondition):
        return f"{condition.actor} reaches ({condition.position[0]:.1f}, {condition.position[1]:.1f})"
    return f"event {condition.event} ends"


def _crossing_edge(scene: Scene, place: tuple[float, float], start: tuple[float, float]) -> float:
    """How far the painted crossing at `place` reaches towards `start` (0 where no crossing is there)."""
    gap = math.dist(place, start)
    if gap == 0.0:
        return 0.0
    ux, uy = (start[0] - place[0]) / gap, (start[1] - place[1]) / gap
    edge = 0.0
    while edge < min(gap, MAX_CROSSING_M) and surface_at(scene, place[0] + ux * edge, place[1] + uy * edge) == "crossing":
        edge += 0.25
    return edge


class AddEvent(Tool[EventArgs]):
    name = "add_event"
    description = (
        "Add a triggered event: WHEN a condition holds (time, distance or time-to-collision "
        "between two assets, an asset reaching a place, another event ending) THEN an actor "
        "does a manoeuvre (brake, change speed, lane change, cut in, turn at the junction, "
        "cross the road, stop mid-road, reverse, set a traffic light)."
    )
    family = "move"
    Args = EventArgs

    def propose(self, args: EventArgs, scene: Scene) -> ToolResult:
        asset = find_asset(scene, args.actor)
        action = build_manoeuvre(scene, asset, args.manoeuvre)
        condition = build_condition(scene, asset.id, args.when)
        if isinstance(action, Stop) and isinstance(condition, ReachPositionCondition) and condition.actor == asset.id:
            # "stop at the crosswalk": braking starts early enough to come to rest with the front short of it
            speed = float(getattr(asset.behaviour, "speed", 0.0) or 0.0)
            early = speed**2 / (2 * action.deceleration) + speed * BRAKE_LAG_S + category(asset.category).length / 2
            early += _crossing_edge(scene, condition.position, (asset.pose.x, asset.pose.y)) + CROSSING_CLEARANCE_M
            condition = condition.model_copy(update={"tolerance": max(condition.tolerance, early)})
        return _add(scene, asset, action, condition, args.name)


class AddManoeuvre(Tool[ManoeuvreArgs]):
    name = "add_manoeuvre"
    description = (
        "Give an actor a manoeuvre at a time in the scenario (default at the start), or right "
        "after its previous manoeuvre: keep lane, change speed, stop, lane change, cut in, "
        "junction turn, follow a route, cross the road, stop mid-road, reverse."
    )
    family = "move"
    Args = ManoeuvreArgs

    def propose(self, args: ManoeuvreArgs, scene: Scene) -> ToolResult:
        asset = find_asset(scene, args.actor)
        action = build_manoeuvre(scene, asset, args.manoeuvre)
        start: Condition = SimulationTimeCondition(time=args.at_time)
        if args.after_previous:
            previous = [e.name for actor, e in scene.storyboard.events() if actor == asset.id]
            if not previous:
                raise RuleViolation("trigger", f"{asset.id} has no earlier manoeuvre to follow")
            start = EventEndCondition(event=previous[-1])
        return _add(scene, asset, action, start, None)


def _light_plan(scene: Scene, light: AssetInstance, phases: list[LightPhase], offset: float) -> TrafficLight:
    """Phases for `light` with stop lines on the lanes it faces, before any crossing."""
    lines = []
    boxes = [area.polygon for area in scene.roads.paved if area.kind == "intersection"]
    for lane in scene.roads.lanes:
        near = nearest_on_polyline(light.pose.x, light.pose.y, lane.centreline)
        left = -(light.pose.x - near.x) * math.sin(near.heading) + (light.pose.y - near.y) * math.cos(near.heading)
        if near.distance > LIGHT_REACH_M or left > -lane.width / 2 or not _enters_junction(lane.centreline, near.arc_length, boxes):
            continue
        back = 0.0
        for crossing in scene.roads.crossings:
            # A crossing just before the light: stop short of it, not on it.
            mid = ((crossing.start[0] + crossing.end[0]) / 2, (crossing.start[1] + crossing.end[1]) / 2)
            behind = (near.x - mid[0]) * math.cos(near.heading) + (near.y - mid[1]) * math.sin(near.heading)
            side = abs(-(mid[0] - near.x) * math.sin(near.heading) + (mid[1] - near.y) * math.cos(near.heading))
            if 0.0 <= behind <= LIGHT_REACH_M and side < lane.width * 2:
                back = max(back, behind + crossing.width / 2 + CROSSING_CLEARANCE_M)
        x, y = near.x - back * math.cos(near.heading), near.y - back * math.sin(near.heading)
        lines.append(StopLine(lane=lane.id, position=(x, y)))
    if not lines:
        raise RuleViolation("surface", f"{light.id} stands more than {LIGHT_REACH_M:g} m from every lane")
    return TrafficLight(light=light.id, phases=phases, offset=offset, stop_lines=lines)


def _enters_junction(centreline: list[tuple[float, float]], s: float, boxes: list[list[tuple[float, float]]]) -> bool:
    """Whether a lane, from outside every junction box at arc length s, enters one just ahead."""
    def inside(d: float) -> bool:
        x, y, _ = point_along(centreline, s + d)
        return any(point_in_polygon(x, y, box) for box in boxes)

    if not boxes:
        return True
    return not inside(0.0) and any(inside(float(d)) for d in range(1, int(LIGHT_REACH_M) + 1))


class SetLightPhases(Tool[LightArgs]):
    name = "set_light_phases"
    description = (
        "Give a traffic light a timed cycle of phases (e.g. green 20 s, amber 3 s, red 20 s) or "
        "hold it in one state (one phase); vehicles on routes, the ego included, stop at red."
    )
    family = "move"
    Args = LightArgs

    def propose(self, args: LightArgs, scene: Scene) -> ToolResult:
        light = find_asset(scene, args.light)
        if light.category != "traffic_light":
            lights = ", ".join(a.id for a in scene.assets if a.category == "traffic_light") or "none"
            raise RuleViolation("behaviour", f"{light.id} is a {light.category}, not a traffic light; lights: {lights}")
        phases = [LightPhase(state=p.state, duration=p.duration) for p in args.phases]
        plan = _light_plan(scene, light, phases, args.offset)
        board = scene.storyboard
        after = board.with_light(plan)
        edit = WorldEdit(ops=(SetStoryboard(before=board, after=after),))
        cycle = ", ".join(f"{p.state} {p.duration:g} s" for p in phases)
        lanes = ", ".join(line.lane for line in plan.stop_lines)
        return ToolResult(edit, f"{light.id}: {cycle} (stops {lanes})", (light.pose.x, light.pose.y))
