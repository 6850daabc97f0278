"""The storyboard: what happens over time, modelled one to one on OpenSCENARIO 1.x.

Storyboard ─ Story ─ Act ─ ManeuverGroup (one actor) ─ Maneuver ─ Event (one action, one
start trigger). Simplifications that keep the mapping one to one: a maneuver group has one
actor (or none, for traffic-light events); an event has one action and one start condition
(OpenSCENARIO's condition groups of one condition); acts start at once. Traffic lights are
OpenSCENARIO's TrafficSignalControllers: timed phase cycles, or a state set by an event.

| drivetwin manoeuvre | OpenSCENARIO action                                     |
| keep_lane           | SpeedAction (step) + keep lane (no lateral action)      |
| change_speed, stop  | SpeedAction, linear dynamics with the rate (m/s²)       |
| lane_change         | LaneChangeAction, relative target lane, time/distance   |
| cut_in              | LaneChangeAction to the target's lane + LongitudinalDistanceAction |
| junction_turn       | RoutingAction / AssignRouteAction through the junction  |
| follow_route        | RoutingAction / FollowTrajectoryAction (polyline)       |
| cross_road, stop_mid_road | FollowTrajectoryAction of a pedestrian            |
| reverse             | SpeedAction with a negative speed                       |
| set_light           | TrafficSignalStateAction                                |
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

__all__ = [
    "VEHICLE_MANOEUVRES",
    "WALKER_MANOEUVRES",
    "Act",
    "ChangeSpeed",
    "Condition",
    "CrossRoadManoeuvre",
    "CutIn",
    "DistanceCondition",
    "Event",
    "EventEndCondition",
    "FollowRoute",
    "JunctionTurn",
    "KeepLane",
    "LaneChange",
    "LightPhase",
    "Maneuver",
    "ManeuverGroup",
    "Manoeuvre",
    "ReachPositionCondition",
    "Reverse",
    "SetLight",
    "SimulationTimeCondition",
    "Stop",
    "StopLine",
    "StopMidRoad",
    "Story",
    "Storyboard",
    "TimeToCollisionCondition",
    "TrafficLight",
]

# The Scene imports this module, so the storyboard has its own base and coordinate types
# (same rules as the Scene's: unknown fields refused, finite coordinates within 10 km).
Coordinate = Annotated[float, Field(ge=-10_000.0, le=10_000.0, allow_inf_nan=False)]
Vec2 = tuple[Coordinate, Coordinate]


class StoryModel(BaseModel):
    model_config = ConfigDict(extra="forbid", validate_assignment=True)


Speed = Annotated[float, Field(ge=0.0, le=40.0, allow_inf_nan=False, description="metres per second")]
Rate = Annotated[float, Field(gt=0.0, le=12.0, allow_inf_nan=False, description="m/s², magnitude")]
Seconds = Annotated[float, Field(ge=0.0, le=3600.0, allow_inf_nan=False)]
Metres = Annotated[float, Field(gt=0.0, le=500.0, allow_inf_nan=False)]
Side = Literal["left", "right"]
Rule = Literal["less", "greater"]
LightState = Literal["red", "amber", "green"]


# Conditions (OpenSCENARIO ByValue / ByEntity conditions) ---------------------------------
class SimulationTimeCondition(StoryModel):
    """True from a simulation time on (SimulationTimeCondition, rule greaterThan)."""

    kind: Literal["simulation_time"] = "simulation_time"
    time: Seconds = 0.0


class DistanceCondition(StoryModel):
    """Distance between two actors' centres (or bumpers, freespace) passes a value."""

    kind: Literal["distance"] = "distance"
    actor: str
    target: str
    distance: Metres
    rule: Rule = "less"
    freespace: bool = False


class TimeToCollisionCondition(StoryModel):
    """The actor would reach the target within `seconds` at the current closing speed."""

    kind: Literal["time_to_collision"] = "time_to_collision"
    actor: str
    target: str
    seconds: Annotated[float, Field(gt=0.0, le=60.0)]


class ReachPositionCondition(StoryModel):
    """The actor comes within `tolerance` metres of a position."""

    kind: Literal["reach_position"] = "reach_position"
    actor: str
    position: Vec2
    tolerance: Metres = 2.0


class EventEndCondition(StoryModel):
    """Another event has ended (StoryboardElementStateCondition, endTransition)."""

    kind: Literal["event_end"] = "event_end"
    event: str


Condition = Annotated[
    SimulationTimeCondition | DistanceCondition | TimeToCollisionCondition | ReachPositionCondition
    | EventEndCondition,
    Field(discriminator="kind"),
]


# Manoeuvres (OpenSCENARIO actions) --------------------------------------------------------
class KeepLane(StoryModel):
    """Drive along the nearest lane (or the named one) at a speed, reached at once."""

    kind: Literal["keep_lane"] = "keep_lane"
    speed: Speed = 5.0
    lane: str | None = None


class ChangeSpeed(StoryModel):
    """Go to a new speed at a constant acceleration or deceleration, keeping the path."""

    kind: Literal["change_speed"] = "change_speed"
    speed: Speed
    rate: Rate = 2.0


class Stop(StoryModel):
    """Brake to a standstill at a constant deceleration and stay stopped."""

    kind: Literal["stop"] = "stop"
    deceleration: Rate = 3.0


class LaneChange(StoryModel):
    """Move into the next lane on one side over a time (seconds) or a distance (metres)."""

    kind: Literal["lane_change"] = "lane_change"
    side: Side
    over: Literal["time", "distance"] = "time"
    value: Annotated[float, Field(gt=0.0, le=200.0)] = 3.0
    lanes: Annotated[int, Field(ge=1, le=3)] = 1


class CutIn(StoryModel):
    """Change into the target's lane ahead of it, leaving `gap` metres bumper to bumper."""

    kind: Literal["cut_in"] = "cut_in"
    target: str
    gap: Annotated[float, Field(gt=0.0, le=100.0)] = 8.0
    duration: Annotated[float, Field(gt=0.5, le=20.0)] = 3.0


class JunctionTurn(StoryModel):
    """At the next junction ahead, turn left, right or go straight on, then keep that lane."""

    kind: Literal["junction_turn"] = "junction_turn"
    turn: Literal["left", "right", "straight"]
    speed: Speed = 5.0


class FollowRoute(StoryModel):
    """Drive or walk through waypoints at a speed, stopping at the last one."""

    kind: Literal["follow_route"] = "follow_route"
    waypoints: list[Vec2] = Field(min_length=2)
    speed: Speed = 5.0


class CrossRoadManoeuvre(StoryModel):
    """Walk from one side of the road to the other."""

    kind: Literal["cross_road"] = "cross_road"
    start: Vec2
    end: Vec2
    speed: Annotated[float, Field(gt=0.0, le=10.0)] = 1.4


class StopMidRoad(StoryModel):
    """Walk out into the road and stop part of the way across (a fraction of the way)."""

    kind: Literal["stop_mid_road"] = "stop_mid_road"
    start: Vec2
    end: Vec2
    speed: Annotated[float, Field(gt=0.0, le=10.0)] = 1.4
    fraction: Annotated[float, Field(gt=0.0, lt=1.0)] = 0.5


class Reverse(StoryModel):
    """Back up straight for a distance at a speed."""

    kind: Literal["reverse"] = "reverse"
    distance: Metres = 5.0
    speed: Annotated[float, Field(gt=0.0, le=5.0)] = 1.5


class SetLight(StoryModel):
    """Put a traffic light into a state and hold it there (ends its timed cycle)."""

    kind: Literal["set_light"] = "set_light"
    light: str
    state: LightState


Manoeuvre = Annotated[
    KeepLane | ChangeSpeed | Stop | LaneChange | CutIn | JunctionTurn | FollowRoute
    | CrossRoadManoeuvre | StopMidRoad | Reverse | SetLight,
    Field(discriminator="kind"),
]
VEHICLE_MANOEUVRES = frozenset(
    {"keep_lane", "change_speed", "stop", "lane_change", "cut_in", "junction_turn", "follow_route", "reverse"}
)
WALKER_MANOEUVRES = frozenset({"follow_route", "cross_road", "stop_mid_road", "stop"})


# The hierarchy ----------------------------------------------------------------------------
class Event(StoryModel):
    """One manoeuvre started by a condition; a later event of the same actor overrides it."""

    name: Annotated[str, Field(pattern=r"^[A-Za-z][A-Za-z0-9_]{0,63}$")]
    action: Manoeuvre
    start: Condition = Field(default_factory=SimulationTimeCondition)


class Maneuver(StoryModel):
    name: str
    events: list[Event] = Field(default_factory=list)


class ManeuverGroup(StoryModel):
    """The manoeuvres of one actor (an asset id, or none for traffic-light events)."""

    name: str
    actor: str | None = None
    maneuvers: list[Maneuver] = Field(default_factory=list)


class Act(StoryModel):
    name: str
    groups: list[ManeuverGroup] = Field(default_factory=list)


class Story(StoryModel):
    name: str
    acts: list[Act] = Field(default_factory=list)


class LightPhase(StoryModel):
    """One phase of a traffic light's cycle (OpenSCENARIO Phase)."""

    state: LightState
    duration: Annotated[float, Field(gt=0.0, le=600.0)]


class StopLine(StoryModel):
    """Where vehicles in one lane stop for this light: a point on the lane's centreline."""

    lane: str
    position: Vec2


class TrafficLight(StoryModel):
    """Phases of one traffic_light asset (a TrafficSignalController) and the lanes it stops."""

    light: str
    phases: list[LightPhase] = Field(min_length=1)
    offset: Seconds = 0.0
    stop_lines: list[StopLine] = Field(min_length=1)

    def state_at(self, time: float) -> LightState:
        """The timed cycle's state at a simulation time."""
        cycle = sum(p.duration for p in self.phases)
        t = (time + self.offset) % cycle
        for phase in self.phases:
            if t < phase.duration:
                return phase.state
            t -= phase.duration
        return self.phases[-1].state


DEFAULT_STORY = "drivetwin"
DEFAULT_ACT = "act"


class Storyboard(StoryModel):
    """Stories of events, traffic lights, and when the whole scenario stops (None: never)."""

    stories: list[Story] = Field(default_factory=list)
    lights: list[TrafficLight] = Field(default_factory=list)
    stop_time: Annotated[float, Field(gt=0.0, le=3600.0, allow_inf_nan=False)] | None = None

    @model_validator(mode="after")
    def _unique_names(self) -> Storyboard:
        names = [e.name for _, e in self.events()]
        if len(set(names)) != len(names):
            raise ValueError("event names must be unique in a storyboard")
        lights = [light.light for light in self.lights]
        if len(set(lights)) != len(lights):
            raise ValueError("a traffic light has at most one phase plan")
        return self

    @property
    def empty(self) -> bool:
        return not self.stories and not self.lights and self.stop_time is None

    def events(self) -> Iterator[tuple[str | None, Event]]:
        """Every (actor, event), in story order."""
        for story in self.stories:
            for act in story.acts:
                for group in act.groups:
                    for maneuver in group.maneuvers:
                        for event in maneuver.events:
                            yield group.actor, event

    def event(self, name: str) -> Event | None:
        return next((e for _, e in self.events() if e.name == name), None)

    def actors(self) -> set[str]:
        return {actor for actor, _ in self.events() if actor is not None}

    def light(self, light_id: str) -> TrafficLight | None:
        return next((light for light in self.lights if light.light == light_id), None)

    def next_event_name(self, stem: str) -> str:
        taken = {e.name for _, e in self.events()}
        n = 1
        while f"{stem}_{n}" in taken:
            n += 1
        return f"{stem}_{n}"

    def with_event(self, actor: str | None, event: Event) -> Storyboard:
        """A copy with `event` appended to the actor's maneuver in the default story and act."""
        group_name = f"{actor or 'signals'}_group"
        stories = [s.model_copy(deep=True) for s in self.stories]
        story = next((s for s in stories if s.name == DEFAULT_STORY), None)
        if story is None:
            story = Story(name=DEFAULT_STORY, acts=[Act(name=DEFAULT_ACT)])
            stories.append(story)
        act = story.acts[0]
        group = next((g for g in act.groups if g.name == group_name), None)
        if group is None:
            group = ManeuverGroup(name=group_name, actor=actor,
                                  maneuvers=[Maneuver(name=f"{actor or 'signals'}_maneuver")])
            act.groups = [*act.groups, group]
        group.maneuvers[0].events = [*group.maneuvers[0].events, event]
        return self.model_copy(update={"stories": stories}).validated()

    def with_light(self, light: TrafficLight) -> Storyboard:
        """A copy with `light`'s phase plan set (replacing an earlier plan of the same light)."""
        lights = [x for x in self.lights if x.light != light.light] + [light]
        return self.model_copy(update={"lights": lights}).validated()

    def validated(self) -> Storyboard:
        return Storyboard.model_validate(self.model_dump())
