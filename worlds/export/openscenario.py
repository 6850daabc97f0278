"""Write a Scene as OpenSCENARIO 1.2 (.xosc) with scenariogeneration, the roads as OpenDRIVE beside it.

Every asset becomes an entity (vehicles with a bounding box and axles, pedestrians, props as
misc objects), placed in Init by a teleport to its pose. The storyboard maps one to one
(see drivetwin.worlds.storyboard): stories, acts, maneuver groups, maneuvers and events keep
their names; each action is named after its drivetwin manoeuvre kind, with `@value` where
OpenSCENARIO has no field for a detail (a named lane, a stop fraction, a reverse distance).
The plain behaviours (drive a lane, follow a path, cross, jaywalk, circle) become initial
speeds and trajectory events in a story named `drivetwin_behaviours`. What has no counterpart
is listed in worlds/export/README.md.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from importlib.metadata import files
from pathlib import Path
from typing import Any

from drivetwin.worlds.catalog import category
from drivetwin.worlds.export.opendrive import export_opendrive
from drivetwin.worlds.routes import NoJunctionError, junction_route
from drivetwin.worlds.scene import AssetInstance, Environment, Scene
from drivetwin.worlds.storyboard import (
    ChangeSpeed,
    Condition,
    CrossRoadManoeuvre,
    CutIn,
    DistanceCondition,
    EventEndCondition,
    FollowRoute,
    JunctionTurn,
    KeepLane,
    LaneChange,
    Manoeuvre,
    ReachPositionCondition,
    Reverse,
    SetLight,
    SimulationTimeCondition,
    Stop,
    StopMidRoad,
    TimeToCollisionCondition,
)

__all__ = [
    "BEHAVIOURS_STORY",
    "CATEGORY_PROPERTY",
    "OSC_MINOR_VERSION",
    "STOP_LINE_PROPERTY",
    "OpenScenarioError",
    "export_openscenario",
    "openscenario_xsd",
    "validate_openscenario",
]

OSC_MINOR_VERSION = 2  # OpenSCENARIO 1.2: what most simulators (esmini, CARLA) read today
BEHAVIOURS_STORY = "drivetwin_behaviours"
CATEGORY_PROPERTY = "drivetwin_category"
# File-header property per traffic-light stop line: "<light> <lane> <x> <y>" (OpenSCENARIO
# keeps stop lines in the road network's signals, which the OpenDRIVE export does not write).
STOP_LINE_PROPERTY = "drivetwin_stop_line"
# A drivetwin weather intensity of 1 is this much precipitation (mm/h: a cloudburst).
MAX_PRECIPITATION_MM_H = 50.0
# Fog of intensity 0 leaves this visual range (m), intensity 1 this much.
CLEAR_VISUAL_RANGE_M = 2000.0
DENSE_FOG_RANGE_M = 20.0
# A date for TimeOfDay: OpenSCENARIO needs one; midsummer keeps the clock time's daylight.
SCENARIO_DATE = (2026, 6, 21)

VEHICLE_CATEGORIES = {"bus": "bus", "truck": "truck", "bicycle": "bicycle", "motorcycle": "motorbike"}
MISC_CATEGORIES = {
    "street_light": "streetLamp", "tree": "tree", "road_barrier": "barrier", "bollard": "pole",
    "traffic_light": "pole", "stop_sign": "pole", "pedestrian_sign": "pole", "parking_sign": "pole",
}


class OpenScenarioError(ValueError):
    """A file that does not validate against the OpenSCENARIO schema, or cannot be read."""


def _xosc() -> Any:
    from scenariogeneration import xosc

    return xosc


def _position(x: float, y: float, z: float = 0.0, h: float = 0.0) -> Any:
    return _xosc().WorldPosition(x=x, y=y, z=z, h=h)


def _entity(asset: AssetInstance) -> Any:
    xosc = _xosc()
    spec = category(asset.category)
    s = asset.scale
    box = xosc.BoundingBox(spec.width * s, spec.length * s, spec.height * s, 0.0, 0.0, spec.height * s / 2)
    if spec.motion == "vehicle" or asset.category in VEHICLE_CATEGORIES:
        wheelbase = (spec.wheelbase or spec.length * 0.6) * s
        wheel = 0.6 * s
        front = xosc.Axle(spec.max_steer or 0.6, wheel, spec.width * s * 0.85, wheelbase / 2, wheel / 2)
        rear = xosc.Axle(0.0, wheel, spec.width * s * 0.85, -wheelbase / 2, wheel / 2)
        kind = getattr(xosc.VehicleCategory, VEHICLE_CATEGORIES.get(asset.category, "car"))
        entity = xosc.Vehicle(asset.id, kind, box, front, rear, 40.0, 5.0, 10.0, mass=asset.physics.mass)
    elif spec.motion == "walker":
        entity = xosc.Pedestrian(asset.id, asset.physics.mass, xosc.PedestrianCategory.pedestrian, box, model=asset.category)
    else:
        kind = getattr(xosc.MiscObjectCategory, MISC_CATEGORIES.get(asset.category, "obstacle"))
        entity = xosc.MiscObject(asset.id, asset.physics.mass, kind, box)
    entity.add_property(CATEGORY_PROPERTY, asset.category)
    return entity


def _environment(environment: Environment, friction: float) -> Any:
    xosc = _xosc()
    hh, mm = (int(v) for v in environment.time_of_day.split(":"))
    weather = environment.weather
    precipitation = None
    if weather.kind in ("rain", "snow"):
        kind = getattr(xosc.PrecipitationType, weather.kind)
        precipitation = xosc.Precipitation(kind, weather.intensity * MAX_PRECIPITATION_MM_H)
    fog = None
    if weather.kind == "fog":
        visual = CLEAR_VISUAL_RANGE_M + weather.intensity * (DENSE_FOG_RANGE_M - CLEAR_VISUAL_RANGE_M)
        fog = xosc.Fog(round(visual))
    oktas = round(weather.intensity * 8) if weather.kind == "cloudy" else 0
    cover = getattr(xosc.FractionalCloudCover, ["zeroOktas", "oneOktas", "twoOktas", "threeOktas", "fourOktas",
                                                "fiveOktas", "sixOktas", "sevenOktas", "eightOktas"][oktas])
    return xosc.Environment(
        "environment",
        xosc.TimeOfDay(False, *SCENARIO_DATE, hh, mm, 0),
        xosc.Weather(cloudstate=cover, precipitation=precipitation, fog=fog),
        xosc.RoadCondition(friction),
    )


def _trigger(condition: Condition, name: str, point: str = "start") -> Any:
    xosc = _xosc()
    edge = xosc.ConditionEdge.none if isinstance(condition, SimulationTimeCondition) else xosc.ConditionEdge.rising
    if isinstance(condition, SimulationTimeCondition):
        return xosc.ValueTrigger(name, 0.0, edge, xosc.SimulationTimeCondition(condition.time, xosc.Rule.greaterThan),
                                 triggeringpoint=point)
    if isinstance(condition, EventEndCondition):
        state = xosc.StoryboardElementStateCondition(
            xosc.StoryboardElementType.event, condition.event, xosc.StoryboardElementState.endTransition)
        return xosc.ValueTrigger(name, 0.0, edge, state)
    if isinstance(condition, DistanceCondition):
        rule = xosc.Rule.lessThan if condition.rule == "less" else xosc.Rule.greaterThan
        entity_condition = xosc.RelativeDistanceCondition(
            condition.distance, rule, xosc.RelativeDistanceType.euclidianDistance, condition.target,
            alongroute=False, freespace=condition.freespace)
        return xosc.EntityTrigger(name, 0.0, edge, entity_condition, condition.actor)
    if isinstance(condition, TimeToCollisionCondition):
        entity_condition = xosc.TimeToCollisionCondition(
            condition.seconds, xosc.Rule.lessThan, alongroute=False, freespace=True, entity=condition.target)
        return xosc.EntityTrigger(name, 0.0, edge, entity_condition, condition.actor)
    assert isinstance(condition, ReachPositionCondition)
    # OpenSCENARIO 1.2 deprecates ReachPositionCondition for a DistanceCondition to the position.
    reach = xosc.DistanceCondition(condition.tolerance, xosc.Rule.lessThan, _position(*condition.position),
                                   alongroute=False, freespace=False,
                                   distance_type=xosc.RelativeDistanceType.euclidianDistance)
    return xosc.EntityTrigger(name, 0.0, edge, reach, condition.actor)


def _trajectory(name: str, points: Sequence[tuple[float, float]], speed: float, closed: bool = False) -> Any:
    xosc = _xosc()
    times, elapsed = [0.0], 0.0
    for (ax, ay), (bx, by) in itertools.pairwise(points):
        elapsed += math.hypot(bx - ax, by - ay) / max(speed, 1e-3)
        times.append(elapsed)
    trajectory = xosc.Trajectory(name, closed)
    trajectory.add_shape(xosc.Polyline(times, [_position(x, y) for x, y in points]))
    return xosc.FollowTrajectoryAction(
        trajectory, xosc.FollowingMode.position, xosc.ReferenceContext.relative, 1.0, 0.0)


def _speed(speed: float, rate: float | None) -> Any:
    xosc = _xosc()
    if rate is None:
        dynamics = xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0.0)
    else:
        dynamics = xosc.TransitionDynamics(xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, rate)
    return xosc.AbsoluteSpeedAction(speed, dynamics)


def _actions(action: Manoeuvre, actor: str | None, scene: Scene) -> list[tuple[str, Any]]:
    """(action name, scenariogeneration action) pairs that play `action` in OpenSCENARIO."""
    xosc = _xosc()
    if isinstance(action, KeepLane):
        return [(f"keep_lane@{action.lane}" if action.lane else "keep_lane", _speed(action.speed, None))]
    if isinstance(action, ChangeSpeed):
        return [("change_speed", _speed(action.speed, action.rate))]
    if isinstance(action, Stop):
        return [("stop", _speed(0.0, action.deceleration))]
    if isinstance(action, LaneChange):
        dimension = xosc.DynamicsDimension.time if action.over == "time" else xosc.DynamicsDimension.distance
        dynamics = xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, dimension, action.value)
        lanes = action.lanes if action.side == "left" else -action.lanes
        return [("lane_change", xosc.RelativeLaneChangeAction(lanes, actor, dynamics))]
    if isinstance(action, CutIn):
        dynamics = xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.time, action.duration)
        return [
            ("cut_in", xosc.RelativeLaneChangeAction(0, action.target, dynamics)),
            ("cut_in_gap", xosc.LongitudinalDistanceAction(action.target, freespace=True, continuous=True,
                                                           distance=action.gap)),
        ]
    if isinstance(action, JunctionTurn):
        pairs = [(f"junction_turn@{action.turn}", _speed(action.speed, None))]
        route = _junction_waypoints(scene, actor, action.turn)
        if route is not None:
            osc_route = xosc.Route(f"{actor}_{action.turn}_route")
            for x, y in route:
                osc_route.add_waypoint(_position(x, y), xosc.RouteStrategy.shortest)
            pairs.append(("junction_route", xosc.AssignRouteAction(osc_route)))
        return pairs
    if isinstance(action, FollowRoute):
        return [("follow_route", _trajectory(f"{actor}_route", action.waypoints, action.speed))]
    if isinstance(action, CrossRoadManoeuvre):
        return [("cross_road", _trajectory(f"{actor}_crossing", [action.start, action.end], action.speed))]
    if isinstance(action, StopMidRoad):
        (sx, sy), (ex, ey) = action.start, action.end
        stop = (sx + action.fraction * (ex - sx), sy + action.fraction * (ey - sy))
        return [(f"stop_mid_road@{action.fraction:g}", _trajectory(f"{actor}_crossing", [action.start, stop], action.speed))]
    if isinstance(action, Reverse):
        return [(f"reverse@{action.distance:g}", _speed(-action.speed, None))]
    assert isinstance(action, SetLight)
    return [("set_light", xosc.TrafficSignalStateAction(action.light, action.state))]


def _junction_waypoints(scene: Scene, actor: str | None, turn: str) -> list[tuple[float, float]] | None:
    """Entry and exit of the junction turn from the actor's authored pose (None if none ahead)."""
    asset = None if actor is None else scene.asset(actor)
    if asset is None:
        return None
    lanes = [(lane.id, lane.centreline) for lane in scene.roads.lanes]
    boxes = [area.polygon for area in scene.roads.paved if area.kind == "intersection"]
    try:
        route, s_exit = junction_route(lanes, boxes, asset.pose.x, asset.pose.y, asset.pose.yaw, turn)
    except NoJunctionError:
        return None
    return [route.point(0.0), route.point(s_exit), route.point(route.length)]


def _behaviour_events(scene: Scene, init: Any) -> Any | None:
    """Plain behaviours: initial speeds in Init, trajectories as events of their own story."""
    xosc = _xosc()
    group_count, act = 0, xosc.Act("behaviours", _trigger(SimulationTimeCondition(time=0.0), "behaviours_start"))
    for asset in scene.all_assets():
        b = asset.behaviour
        trigger: Condition = SimulationTimeCondition(time=getattr(b, "start_time", 0.0))
        if b.kind == "parked":
            continue
        if b.kind == "drive_lane":
            init.add_init_action(asset.id, _speed(b.speed, None))
            continue
        if b.kind == "follow_path":
            action = _trajectory(f"{asset.id}_path", b.waypoints, b.speed, b.loop)
        elif b.kind == "circle":
            points = [(b.centre[0] + b.radius * math.cos(a), b.centre[1] + b.radius * math.sin(a))
                      for a in (2 * math.pi * k / 36 * (-1 if b.clockwise else 1) for k in range(37))]
            action = _trajectory(f"{asset.id}_circle", points, b.speed, True)
        else:
            action = _trajectory(f"{asset.id}_walk", [b.start, b.end], b.speed)
            if b.kind == "jaywalk":
                mid = ((b.start[0] + b.end[0]) / 2, (b.start[1] + b.end[1]) / 2)
                trigger = ReachPositionCondition(actor="ego", position=mid, tolerance=b.trigger_distance)
        event = xosc.Event(f"{asset.id}_{b.kind}", xosc.Priority.override)
        event.add_action(b.kind, action)
        event.add_trigger(_trigger(trigger, f"{asset.id}_{b.kind}_start"))
        maneuver = xosc.Maneuver(f"{asset.id}_behaviour")
        maneuver.add_event(event)
        group = xosc.ManeuverGroup(f"{asset.id}_behaviour_group")
        group.add_actor(asset.id)
        group.add_maneuver(maneuver)
        act.add_maneuver_group(group)
        group_count += 1
    if not group_count:
        return None
    story = xosc.Story(BEHAVIOURS_STORY)
    story.add_act(act)
    return story


def export_openscenario(scene: Scene, path: str | Path) -> tuple[Path, Path]:
    """Write `scene` to the .xosc file `path` and its roads to a .xodr beside it; both paths."""
    xosc = _xosc()
    target = Path(path)
    road_file = target.with_suffix(".xodr")
    export_opendrive(scene, road_file)
    entities, init = xosc.Entities(), xosc.Init()
    for asset in scene.all_assets():
        entities.add_scenario_object(asset.id, _entity(asset))
        p = asset.pose
        init.add_init_action(asset.id, xosc.TeleportAction(_position(p.x, p.y, p.z, p.yaw)))
    init.add_global_action(xosc.EnvironmentAction(_environment(scene.environment, scene.ground.friction)))
    board = scene.storyboard
    stop = None if board.stop_time is None else _trigger(SimulationTimeCondition(time=board.stop_time), "stop", "stop")
    storyboard = xosc.StoryBoard(init, stop)
    behaviours = _behaviour_events(scene, init)
    if behaviours is not None:
        storyboard.add_story(behaviours)
    for story in board.stories:
        osc_story = xosc.Story(story.name)
        for act in story.acts:
            osc_act = xosc.Act(act.name, _trigger(SimulationTimeCondition(time=0.0), f"{act.name}_start"))
            for group in act.groups:
                osc_group = xosc.ManeuverGroup(group.name)
                if group.actor is not None:
                    osc_group.add_actor(group.actor)
                for maneuver in group.maneuvers:
                    osc_maneuver = xosc.Maneuver(maneuver.name)
                    for event in maneuver.events:
                        osc_event = xosc.Event(event.name, xosc.Priority.override)
                        for name, action in _actions(event.action, group.actor, scene):
                            osc_event.add_action(name, action)
                        osc_event.add_trigger(_trigger(event.start, f"{event.name}_start"))
                        osc_maneuver.add_event(osc_event)
                    osc_group.add_maneuver(osc_maneuver)
                osc_act.add_maneuver_group(osc_group)
            osc_story.add_act(osc_act)
        storyboard.add_story(osc_story)
    road_network = xosc.RoadNetwork(roadfile=road_file.name)
    header = xosc.Properties()
    for light in board.lights:
        for line in light.stop_lines:
            header.add_property(STOP_LINE_PROPERTY, f"{light.light} {line.lane} {line.position[0]!r} {line.position[1]!r}")
        controller = xosc.TrafficSignalController(light.light, delay=light.offset)
        for phase in light.phases:
            controller.add_phase(xosc.Phase(phase.state, phase.duration).add_signal_state(light.light, phase.state))
        road_network.add_traffic_signal_controller(controller)
    scenario = xosc.Scenario(
        scene.name, "drivetwin", xosc.ParameterDeclarations(), entities, storyboard, road_network,
        xosc.Catalog(), osc_minor_version=OSC_MINOR_VERSION,
        header_properties=header if board.lights else None)
    scenario.write_xml(str(target))
    return target, road_file


def openscenario_xsd(minor_version: int = OSC_MINOR_VERSION) -> Path:
    """The ASAM OpenSCENARIO 1.x schema that the scenariogeneration package ships."""
    wanted = f"OpenSCENARIO_1_{minor_version}.xsd"
    for file in files("scenariogeneration") or []:
        if file.name == wanted:
            return Path(str(file.locate()))
    raise OpenScenarioError(f"scenariogeneration ships no {wanted}; reinstall it (pip install scenariogeneration)")


def validate_openscenario(path: str | Path) -> None:
    """Raise OpenScenarioError with the first problem if `path` does not validate against the XSD."""
    import xmlschema

    schema = xmlschema.XMLSchema(str(openscenario_xsd()))
    errors = list(schema.iter_errors(str(path)))
    if errors:
        first = errors[0]
        raise OpenScenarioError(f"{path} is not valid OpenSCENARIO 1.{OSC_MINOR_VERSION}: {len(errors)} error(s), "
                                f"first at {first.path}: {first.reason}")
