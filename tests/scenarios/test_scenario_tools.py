"""Scenario Workers: events, manoeuvres and light phases edit the storyboard like any edit."""

from __future__ import annotations

from pathlib import Path

import pytest
from drivetwin.evals.trial import ScriptedPlanner
from drivetwin.orchestrator.session import Session
from drivetwin.tools.base import ToolCall
from drivetwin.tools.errors import ToolError
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.scene import Scene, scene_json_schema
from drivetwin.worlds.storyboard import (
    ChangeSpeed,
    CrossRoadManoeuvre,
    DistanceCondition,
    EventEndCondition,
    SetLight,
    SimulationTimeCondition,
)
from drivetwin.worlds.surface import DRIVABLE, surface_at

REGISTRY = ToolRegistry.default(plugins=False)
BRAKE = ToolCall(tool="add_event", args={
    "actor": "ego", "manoeuvre": {"kind": "change_speed", "speed": 0, "rate": 6},
    "when": {"kind": "distance", "actor": "ego", "other": "traffic_light_1", "metres": 20},
})


def _run(call: ToolCall, scene: Scene | None = None) -> Scene:
    start = scene or build_campus()
    return REGISTRY.run(call, start).edit.apply(start)


def test_add_event_puts_a_triggered_manoeuvre_in_the_storyboard() -> None:
    scene = _run(BRAKE)
    [(actor, event)] = list(scene.storyboard.events())
    assert actor == "ego"
    assert event.action == ChangeSpeed(speed=0.0, rate=6.0)
    assert event.start == DistanceCondition(actor="ego", target="traffic_light_1", distance=20.0)


def test_add_manoeuvre_after_previous_chains_on_the_actors_last_event() -> None:
    scene = _run(BRAKE)
    scene = _run(ToolCall(tool="add_manoeuvre", args={
        "actor": "ego", "manoeuvre": {"kind": "keep_lane", "speed": 4}, "after_previous": True}), scene)
    first, second = (e for _, e in scene.storyboard.events())
    assert second.start == EventEndCondition(event=first.name)


def test_a_pedestrian_crossing_walks_from_its_kerb_to_the_far_kerb() -> None:
    scene = _run(ToolCall(tool="add_asset", args={
        "category": "pedestrian", "location": {"relation": "at", "target": "bus stop"}}))
    walker = next(a for a in scene.assets if a.category == "pedestrian")
    scene = _run(ToolCall(tool="add_manoeuvre", args={
        "actor": walker.id, "manoeuvre": {"kind": "cross_road"}, "at_time": 2}), scene)
    [(_, event)] = list(scene.storyboard.events())
    assert isinstance(event.action, CrossRoadManoeuvre)
    assert event.start == SimulationTimeCondition(time=2.0)
    assert surface_at(scene, *event.action.end) not in DRIVABLE
    assert abs(event.action.end[1] - event.action.start[1]) > 7.0  # both lanes of Main Street


def test_light_phases_stop_only_the_lane_the_light_faces() -> None:
    scene = _run(ToolCall(tool="set_light_phases", args={
        "light": "traffic_light_1", "phases": [{"state": "green", "duration": 10}, {"state": "red", "duration": 10}]}))
    [light] = scene.storyboard.lights
    assert [line.lane for line in light.stop_lines] == ["main_eastbound"]
    assert light.state_at(5.0) == "green" and light.state_at(15.0) == "red"


def test_an_event_can_set_a_light_that_has_no_phases_yet() -> None:
    scene = _run(ToolCall(tool="add_event", args={
        "actor": "traffic_light_2", "manoeuvre": {"kind": "set_light", "state": "red"},
        "when": {"kind": "distance", "actor": "ego", "other": "traffic_light_2", "metres": 30}}))
    [(actor, event)] = list(scene.storyboard.events())
    assert actor is None and event.action == SetLight(light="traffic_light_2", state="red")
    assert scene.storyboard.light("traffic_light_2") is not None


@pytest.mark.parametrize(("args", "words"), [
    ({"actor": "bench_1", "manoeuvre": {"kind": "stop"}, "when": {"kind": "time"}}, "cannot stop"),
    ({"actor": "ego", "manoeuvre": {"kind": "lane_change", "side": "right"}, "when": {"kind": "time"}}, "no lane to the right"),
    ({"actor": "ego", "manoeuvre": {"kind": "cross_road"}, "when": {"kind": "time"}}, "cannot cross_road"),
    ({"actor": "ego", "manoeuvre": {"kind": "stop"}, "when": {"kind": "after_event", "event": "nope"}}, "no event 'nope'"),
    ({"actor": "ego", "manoeuvre": {"kind": "stop"}, "when": {"kind": "distance", "metres": 5}}, "two different assets"),
    ({"actor": "car_99", "manoeuvre": {"kind": "stop"}, "when": {"kind": "time"}}, "no asset 'car_99'"),
])
def test_an_impossible_request_is_refused_in_one_line_and_changes_nothing(args: dict[str, object], words: str) -> None:
    scene = build_campus()
    with pytest.raises(ToolError, match=words) as refusal:
        REGISTRY.run(ToolCall(tool="add_event", args=args), scene)
    assert "\n" not in str(refusal.value)
    assert scene == build_campus()


def test_undo_redo_save_load_and_journal_replay_cover_the_storyboard(tmp_path: Path) -> None:
    journal = tmp_path / "journal.jsonl"
    session = Session(build_campus(), ScriptedPlanner([BRAKE]), REGISTRY, journal_path=journal)
    assert session.submit("the ego brakes hard 20 m before the light").ok
    edited = session.scene
    assert not edited.storyboard.empty
    saved = session.save(tmp_path / "scene.json")
    assert Scene.load(saved) == edited
    session.undo()
    assert session.scene.storyboard.empty
    session.redo()
    assert session.scene == edited
    session.close()
    resumed = Session.resume(journal, ScriptedPlanner([]), REGISTRY)
    assert resumed.scene == edited
    resumed.close()


def test_the_published_scene_schema_describes_the_storyboard() -> None:
    schema = scene_json_schema()
    assert "storyboard" in schema["properties"]
    assert {"Storyboard", "Event", "CutIn", "TrafficLight", "TimeToCollisionCondition"} <= set(schema["$defs"])
