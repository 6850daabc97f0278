"""Read back an .xosc that drivetwin wrote: its entities, environment and storyboard.

This is the inverse of worlds/export/openscenario.py, written with ElementTree against the
OpenSCENARIO 1.2 elements that the writer uses (not a general OpenSCENARIO importer). The
`drivetwin_behaviours` story (plain behaviours) is skipped: those come back as the entities'
poses only. Floats come back as written; speeds of trajectories are recomputed from their
vertex times (to rounding error).
"""

from __future__ import annotations

import itertools
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

from drivetwin.worlds.export.openscenario import (
    BEHAVIOURS_STORY,
    CATEGORY_PROPERTY,
    CLEAR_VISUAL_RANGE_M,
    DENSE_FOG_RANGE_M,
    MAX_PRECIPITATION_MM_H,
    STOP_LINE_PROPERTY,
    OpenScenarioError,
)
from drivetwin.worlds.scene import Weather
from drivetwin.worlds.storyboard import (
    Act,
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
    Maneuver,
    ManeuverGroup,
    Manoeuvre,
    ReachPositionCondition,
    Reverse,
    SetLight,
    SimulationTimeCondition,
    Stop,
    StopLine,
    StopMidRoad,
    Story,
    Storyboard,
    TimeToCollisionCondition,
    TrafficLight,
)

__all__ = ["ReadActor", "ReadScenario", "read_openscenario"]


@dataclass(frozen=True)
class ReadActor:
    """An entity as the file has it: drivetwin category, pose and bounding box (metres, rad)."""

    category: str
    x: float
    y: float
    z: float
    yaw: float
    size: tuple[float, float, float]  # length, width, height


@dataclass
class ReadScenario:
    actors: dict[str, ReadActor] = field(default_factory=dict)
    storyboard: Storyboard = field(default_factory=Storyboard)
    time_of_day: str = "12:00"
    weather: Weather = field(default_factory=Weather)


def _f(element: ET.Element | None, key: str) -> float:
    if element is None or key not in element.attrib:
        raise OpenScenarioError(f"expected attribute {key!r} on {element.tag if element is not None else 'nothing'}")
    return float(element.attrib[key])


def _need(parent: ET.Element, path: str) -> ET.Element:
    found = parent.find(path)
    if found is None:
        raise OpenScenarioError(f"{parent.tag} has no {path}")
    return found


def _world(parent: ET.Element) -> tuple[float, float]:
    position = _need(parent, ".//WorldPosition")
    return (_f(position, "x"), _f(position, "y"))


def _condition(element: ET.Element) -> Condition:
    value = element.find("ByValueCondition")
    if value is not None:
        time = value.find("SimulationTimeCondition")
        if time is not None:
            return SimulationTimeCondition(time=_f(time, "value"))
        state = _need(value, "StoryboardElementStateCondition")
        return EventEndCondition(event=state.attrib["storyboardElementRef"])
    entity = _need(element, "ByEntityCondition")
    actor = _need(entity, "TriggeringEntities/EntityRef").attrib["entityRef"]
    inner = _need(entity, "EntityCondition")
    distance = inner.find("RelativeDistanceCondition")
    if distance is not None:
        rule = "less" if distance.attrib["rule"].startswith("less") else "greater"
        return DistanceCondition(actor=actor, target=distance.attrib["entityRef"], distance=_f(distance, "value"),
                                 rule=rule, freespace=distance.attrib.get("freespace") == "true")
    ttc = inner.find("TimeToCollisionCondition")
    if ttc is not None:
        target = _need(ttc, ".//EntityRef").attrib["entityRef"]
        return TimeToCollisionCondition(actor=actor, target=target, seconds=_f(ttc, "value"))
    reach = _need(inner, "DistanceCondition")
    return ReachPositionCondition(actor=actor, position=_world(reach), tolerance=_f(reach, "value"))


def _polyline(action: ET.Element) -> tuple[list[tuple[float, float]], float]:
    """Vertices of a trajectory and the speed its vertex times imply."""
    vertices = action.findall(".//Polyline/Vertex")
    points = [_world(v) for v in vertices]
    times = [_f(v, "time") for v in vertices]
    length = sum(math.dist(a, b) for a, b in itertools.pairwise(points))
    return points, length / max(times[-1] - times[0], 1e-9)


def _speed(action: ET.Element) -> float:
    return _f(_need(action, ".//AbsoluteTargetSpeed"), "value")


def _manoeuvre(actions: dict[str, ET.Element]) -> Manoeuvre:
    name, action = next(iter(actions.items()))
    kind, _, detail = name.partition("@")
    if kind == "keep_lane":
        return KeepLane(speed=_speed(action), lane=detail or None)
    if kind == "change_speed":
        return ChangeSpeed(speed=_speed(action), rate=_f(_need(action, ".//SpeedActionDynamics"), "value"))
    if kind == "stop":
        return Stop(deceleration=_f(_need(action, ".//SpeedActionDynamics"), "value"))
    if kind == "lane_change":
        dynamics = _need(action, ".//LaneChangeActionDynamics")
        lanes = int(_f(_need(action, ".//RelativeTargetLane"), "value"))
        over = "time" if dynamics.attrib["dynamicsDimension"] == "time" else "distance"
        return LaneChange(side="left" if lanes > 0 else "right", lanes=abs(lanes), over=over, value=_f(dynamics, "value"))
    if kind == "cut_in":
        target = _need(action, ".//RelativeTargetLane").attrib["entityRef"]
        gap = _f(_need(actions["cut_in_gap"], ".//LongitudinalDistanceAction"), "distance")
        return CutIn(target=target, gap=gap, duration=_f(_need(action, ".//LaneChangeActionDynamics"), "value"))
    if kind == "junction_turn":
        return JunctionTurn(turn=detail, speed=_speed(action))
    if kind == "follow_route":
        points, speed = _polyline(action)
        return FollowRoute(waypoints=points, speed=speed)
    if kind == "cross_road":
        (start, end), speed = _polyline(action)
        return CrossRoadManoeuvre(start=start, end=end, speed=speed)
    if kind == "stop_mid_road":
        ((sx, sy), (mx, my)), speed = _polyline(action)
        fraction = float(detail)
        end = (sx + (mx - sx) / fraction, sy + (my - sy) / fraction)
        return StopMidRoad(start=(sx, sy), end=end, speed=speed, fraction=fraction)
    if kind == "reverse":
        return Reverse(distance=float(detail), speed=-_speed(action))
    if kind == "set_light":
        state = _need(action, ".//TrafficSignalStateAction")
        return SetLight(light=state.attrib["name"], state=state.attrib["state"])
    raise OpenScenarioError(f"action {name!r} is not one drivetwin writes")


def _storyboard(root: ET.Element) -> Storyboard:
    stories = []
    for story in root.iterfind("Storyboard/Story"):
        if story.attrib["name"] == BEHAVIOURS_STORY:
            continue
        acts = []
        for act in story.iterfind("Act"):
            groups = []
            for group in act.iterfind("ManeuverGroup"):
                ref = group.find("Actors/EntityRef")
                maneuvers = []
                for maneuver in group.iterfind("Maneuver"):
                    events = []
                    for event in maneuver.iterfind("Event"):
                        actions = {a.attrib["name"]: a for a in event.iterfind("Action")}
                        condition = _need(event, "StartTrigger/ConditionGroup/Condition")
                        events.append(Event(name=event.attrib["name"], action=_manoeuvre(actions), start=_condition(condition)))
                    maneuvers.append(Maneuver(name=maneuver.attrib["name"], events=events))
                actor = None if ref is None else ref.attrib["entityRef"]
                groups.append(ManeuverGroup(name=group.attrib["name"], actor=actor, maneuvers=maneuvers))
            acts.append(Act(name=act.attrib["name"], groups=groups))
        stories.append(Story(name=story.attrib["name"], acts=acts))
    stop = root.find("Storyboard/StopTrigger//SimulationTimeCondition")
    return Storyboard(stories=stories, lights=_lights(root), stop_time=None if stop is None else _f(stop, "value"))


def _lights(root: ET.Element) -> list[TrafficLight]:
    lines: dict[str, list[StopLine]] = {}
    for prop in root.iterfind("FileHeader/Properties/Property"):
        if prop.attrib["name"] == STOP_LINE_PROPERTY:
            light, lane, x, y = prop.attrib["value"].split()
            lines.setdefault(light, []).append(StopLine(lane=lane, position=(float(x), float(y))))
    lights = []
    for controller in root.iterfind("RoadNetwork/TrafficSignals/TrafficSignalController"):
        name = controller.attrib["name"]
        phases = [LightPhase(state=p.attrib["name"], duration=_f(p, "duration"))
                  for p in controller.iterfind("Phase")]
        lights.append(TrafficLight(light=name, phases=phases, offset=float(controller.attrib.get("delay", 0.0)),
                                   stop_lines=lines.get(name, [])))
    return lights


def _weather(root: ET.Element) -> tuple[str, Weather]:
    environment = _need(root, "Storyboard/Init/Actions/GlobalAction/EnvironmentAction/Environment")
    clock = _need(environment, "TimeOfDay").attrib["dateTime"]
    time_of_day = clock[11:16]
    weather = _need(environment, "Weather")
    rain = weather.find("Precipitation")
    if rain is not None and rain.attrib.get("precipitationType") in ("rain", "snow"):
        intensity = _f(rain, "precipitationIntensity") / MAX_PRECIPITATION_MM_H
        return time_of_day, Weather(kind=rain.attrib["precipitationType"], intensity=intensity)
    fog = weather.find("Fog")
    if fog is not None:
        intensity = (CLEAR_VISUAL_RANGE_M - _f(fog, "visualRange")) / (CLEAR_VISUAL_RANGE_M - DENSE_FOG_RANGE_M)
        return time_of_day, Weather(kind="fog", intensity=min(1.0, max(0.0, intensity)))
    oktas = weather.attrib.get("fractionalCloudCover", "zeroOktas")
    number = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight"].index(oktas.removesuffix("Oktas"))
    if number:
        return time_of_day, Weather(kind="cloudy", intensity=number / 8)
    return time_of_day, Weather()


def read_openscenario(path: str | Path) -> ReadScenario:
    """The entities, environment and storyboard of an .xosc written by export_openscenario."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as exc:
        raise OpenScenarioError(f"cannot read {path}: {exc}") from exc
    result = ReadScenario()
    poses = {}
    for private in root.iterfind("Storyboard/Init/Actions/Private"):
        position = private.find(".//TeleportAction/Position/WorldPosition")
        if position is not None:
            poses[private.attrib["entityRef"]] = position
    for entity in root.iterfind("Entities/ScenarioObject"):
        name = entity.attrib["name"]
        body = entity[0]
        props = {p.attrib["name"]: p.attrib["value"] for p in body.iterfind("Properties/Property")}
        box = _need(body, "BoundingBox/Dimensions")
        position = poses[name]
        result.actors[name] = ReadActor(
            category=props.get(CATEGORY_PROPERTY, body.tag.lower()),
            x=_f(position, "x"), y=_f(position, "y"), z=float(position.attrib.get("z", 0.0)),
            yaw=float(position.attrib.get("h", 0.0)),
            size=(_f(box, "length"), _f(box, "width"), _f(box, "height")),
        )
    result.storyboard = _storyboard(root)
    result.time_of_day, result.weather = _weather(root)
    return result
