"""Plays a Scene's storyboard in the live simulation: triggers, manoeuvres and traffic lights.

Every control tick the player (1) sets each traffic light's state (its timed cycle, or the
state an event set), (2) starts the events whose start condition holds, putting the
manoeuvre's controller in place of the actor's current one, (3) ends the events whose
manoeuvre is done, and (4) hands the red lights' stop lines to every vehicle on a route
(ego included), which stops for them. The storyboard's clock starts when the player is
built: when the world is loaded or the storyboard is edited.

Event life cycle (OpenSCENARIO's standby → running → complete): an event starts once;
a later event of the same actor overrides a running one (which then counts as ended); at
the storyboard's stop time running events end and no new one starts, and every actor
keeps its last controller.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field

from drivetwin.worlds.behaviours import BehaviourRunner, VehicleRouteRunner
from drivetwin.worlds.catalog import category
from drivetwin.worlds.manoeuvres import ManoeuvreError, manoeuvre_runner
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.scene import Scene
from drivetwin.worlds.storyboard import (
    Condition,
    DistanceCondition,
    Event,
    EventEndCondition,
    LightState,
    ReachPositionCondition,
    SetLight,
    SimulationTimeCondition,
    TimeToCollisionCondition,
)

__all__ = ["EventRecord", "StoryboardPlayer"]

log = logging.getLogger(__name__)


@dataclass
class EventRecord:
    """When an event started and ended (storyboard clock, seconds), and why it failed."""

    actor: str | None
    event: Event
    started: float | None = None
    ended: float | None = None
    failed: str | None = None


@dataclass
class StoryboardPlayer:
    """The storyboard of one scene, played from `start_time` (simulation seconds) on."""

    scene: Scene
    start_time: float = 0.0
    records: dict[str, EventRecord] = field(default_factory=dict)
    light_states: dict[str, LightState] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    _forced: dict[str, LightState] = field(default_factory=dict)
    _running: dict[str, str] = field(default_factory=dict)  # actor -> event name
    _last_distance: dict[tuple[str, str], tuple[float, float]] = field(default_factory=dict)
    _stopped: bool = False

    def __post_init__(self) -> None:
        for actor, event in self.scene.storyboard.events():
            self.records[event.name] = EventRecord(actor, event)

    @property
    def active(self) -> bool:
        return not self.scene.storyboard.empty

    def clock(self, time: float) -> float:
        return time - self.start_time

    # One control tick ------------------------------------------------------------------------
    def control(self, world: MujocoWorld, time: float, runners: dict[str, BehaviourRunner]) -> None:
        """Advance the storyboard to simulation time `time`, editing `runners` in place."""
        if not self.active:
            return
        now = self.clock(time)
        storyboard = self.scene.storyboard
        if storyboard.stop_time is not None and now >= storyboard.stop_time and not self._stopped:
            self._stopped = True
            for record in self.records.values():
                if record.started is not None and record.ended is None:
                    record.ended = now
        if not self._stopped:
            self._end_done_events(world, now, runners)
            for record in self.records.values():
                if record.started is None and record.failed is None and self._holds(record.event.start, world, now):
                    self._start(record, world, now, runners)
        red = self._update_lights(now)
        for runner in runners.values():
            if isinstance(runner, VehicleRouteRunner):
                runner.red_stops = red

    def _end_done_events(self, world: MujocoWorld, now: float, runners: dict[str, BehaviourRunner]) -> None:
        for actor, name in list(self._running.items()):
            runner = runners.get(actor)
            if runner is None or runner.done(world):
                self.records[name].ended = now
                del self._running[actor]

    def _start(self, record: EventRecord, world: MujocoWorld, now: float, runners: dict[str, BehaviourRunner]) -> None:
        action, actor = record.event.action, record.actor
        if isinstance(action, SetLight):
            self._forced[action.light] = action.state
            record.started = record.ended = now
            return
        asset = None if actor is None else self.scene.asset(actor)
        if asset is None:
            self._fail(record, f"event {record.event.name}: actor {actor!r} is not in the scene")
            return
        try:
            runner = manoeuvre_runner(action, asset, self.scene, world, runners.get(asset.id))
        except (ManoeuvreError, ValueError) as exc:
            self._fail(record, f"event {record.event.name}: {exc}")
            return
        runner.bind(world)
        overridden = self._running.pop(asset.id, None)
        if overridden is not None:
            self.records[overridden].ended = now
        runners[asset.id] = runner
        record.started = now
        self._running[asset.id] = record.event.name

    def _fail(self, record: EventRecord, why: str) -> None:
        record.failed = why
        self.warnings.append(why)
        log.warning("%s", why)

    # Conditions -------------------------------------------------------------------------------
    def _holds(self, condition: Condition, world: MujocoWorld, now: float) -> bool:
        if isinstance(condition, SimulationTimeCondition):
            return now >= condition.time
        if isinstance(condition, EventEndCondition):
            record = self.records.get(condition.event)
            return record is not None and record.ended is not None
        if isinstance(condition, ReachPositionCondition):
            pose = self._pose(world, condition.actor)
            return pose is not None and math.hypot(pose[0] - condition.position[0], pose[1] - condition.position[1]) <= condition.tolerance
        if isinstance(condition, DistanceCondition):
            distance = self._distance(world, condition.actor, condition.target, condition.freespace)
            if distance is None:
                return False
            return distance < condition.distance if condition.rule == "less" else distance > condition.distance
        assert isinstance(condition, TimeToCollisionCondition)
        return self._time_to_collision(world, condition, now)

    def _pose(self, world: MujocoWorld, asset_id: str) -> tuple[float, float] | None:
        if self.scene.asset(asset_id) is None:
            return None
        x, y, _, _ = world.planar_pose(asset_id)
        return (x, y)

    def _distance(self, world: MujocoWorld, a: str, b: str, freespace: bool) -> float | None:
        pa, pb = self._pose(world, a), self._pose(world, b)
        if pa is None or pb is None:
            return None
        distance = math.dist(pa, pb)
        if freespace:
            distance -= (_half_length(self.scene, a) + _half_length(self.scene, b))
        return max(0.0, distance)

    def _time_to_collision(self, world: MujocoWorld, condition: TimeToCollisionCondition, now: float) -> bool:
        distance = self._distance(world, condition.actor, condition.target, freespace=True)
        if distance is None:
            return False
        key = (condition.actor, condition.target)
        last = self._last_distance.get(key)
        self._last_distance[key] = (now, distance)
        if last is None or now <= last[0]:
            return False
        closing = (last[1] - distance) / (now - last[0])
        return closing > 0.0 and distance / closing < condition.seconds

    # Traffic lights ---------------------------------------------------------------------------
    def _update_lights(self, now: float) -> list[tuple[float, float]]:
        red: list[tuple[float, float]] = []
        for light in self.scene.storyboard.lights:
            state = self._forced.get(light.light) or light.state_at(now)
            self.light_states[light.light] = state
            if state == "red":
                red.extend(line.position for line in light.stop_lines)
        return red


def _half_length(scene: Scene, asset_id: str) -> float:
    asset = scene.asset(asset_id)
    if asset is None:
        return 0.0
    return category(asset.category).length * asset.scale / 2
