"""OpenSCENARIO export: the files validate against the ASAM XSD and read back to the same scene."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.export.opendrive import validate_opendrive
from drivetwin.worlds.export.openscenario import (
    OpenScenarioError,
    export_openscenario,
    openscenario_xsd,
    validate_openscenario,
)
from drivetwin.worlds.export.openscenario_read import read_openscenario
from drivetwin.worlds.scene import AssetInstance, Environment, PhysicsProps, Pose, Scene, Weather
from drivetwin.worlds.storyboard import (
    ChangeSpeed,
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
    ReachPositionCondition,
    Reverse,
    SetLight,
    SimulationTimeCondition,
    Stop,
    StopLine,
    StopMidRoad,
    Storyboard,
    TimeToCollisionCondition,
    TrafficLight,
)

# Positions and speeds come back within this (float text and trajectory times round-trip).
TOLERANCE = 1e-6


def _every_kind_scene() -> Scene:
    """The campus with one event of every manoeuvre and condition kind, and two lights."""
    car, walker = "passenger_car_1", "pedestrian_1"
    campus = build_campus()
    person = AssetInstance(id=walker, category="pedestrian", pose=Pose(x=-20.0, y=-6.0),
                           physics=PhysicsProps(mass=75.0))
    board = Storyboard(stop_time=60.0, lights=[
        TrafficLight(light="traffic_light_1", offset=2.0,
                     phases=[LightPhase(state="green", duration=10.0), LightPhase(state="amber", duration=3.0),
                             LightPhase(state="red", duration=12.0)],
                     stop_lines=[StopLine(lane="main_eastbound", position=(-14.0, -1.75))]),
    ])
    events = [
        ("ego", Event(name="ego_keeps", action=KeepLane(speed=6.0, lane="main_eastbound"))),
        (car, Event(name="car_brakes", action=Stop(deceleration=6.0),
                    start=DistanceCondition(actor="ego", target=car, distance=15.0))),
        (car, Event(name="car_slows", action=ChangeSpeed(speed=2.0, rate=1.5),
                    start=TimeToCollisionCondition(actor="ego", target=car, seconds=2.5))),
        (car, Event(name="car_overtakes", action=LaneChange(side="left", over="distance", value=20.0),
                    start=EventEndCondition(event="car_brakes"))),
        (car, Event(name="car_cuts_in", action=CutIn(target="ego", gap=9.0, duration=2.5),
                    start=SimulationTimeCondition(time=12.0))),
        ("ego", Event(name="ego_turns", action=JunctionTurn(turn="right", speed=4.0),
                      start=ReachPositionCondition(actor="ego", position=(-20.0, -1.75), tolerance=2.0))),
        (car, Event(name="car_route", action=FollowRoute(waypoints=[(0.0, -30.0), (20.0, -30.0), (20.0, -40.0)], speed=3.0),
                    start=SimulationTimeCondition(time=30.0))),
        (car, Event(name="car_backs", action=Reverse(distance=4.0, speed=1.0), start=SimulationTimeCondition(time=40.0))),
        (walker, Event(name="walker_crosses", action=CrossRoadManoeuvre(start=(-20.0, -6.0), end=(-20.0, 6.0), speed=1.6),
                       start=DistanceCondition(actor="ego", target=walker, distance=25.0, freespace=True))),
        (walker, Event(name="walker_stops", action=StopMidRoad(start=(-20.0, 6.0), end=(-20.0, -6.0), fraction=0.4),
                       start=SimulationTimeCondition(time=20.0))),
        (None, Event(name="light_red", action=SetLight(light="traffic_light_1", state="red"),
                     start=SimulationTimeCondition(time=5.0))),
    ]
    for actor, event in events:
        board = board.with_event(actor, event)
    environment = Environment(time_of_day="18:45", weather=Weather(kind="rain", intensity=0.6))
    return Scene.model_validate(campus.model_copy(update={
        "assets": [*campus.assets, person], "storyboard": board, "environment": environment}).model_dump())


def _close(a: object, b: object) -> bool:
    if isinstance(a, float) and isinstance(b, float | int):
        return math.isclose(a, b, rel_tol=TOLERANCE, abs_tol=TOLERANCE)
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_close(a[k], b[k]) for k in a)
    if isinstance(a, list | tuple) and isinstance(b, list | tuple):
        return len(a) == len(b) and all(_close(x, y) for x, y in zip(a, b, strict=True))
    return a == b


@pytest.fixture(scope="module")
def exported(tmp_path_factory: pytest.TempPathFactory) -> tuple[Scene, Path, Path]:
    scene = _every_kind_scene()
    scenario, roads = export_openscenario(scene, tmp_path_factory.mktemp("xosc") / "every_kind.xosc")
    return scene, scenario, roads


def test_the_xsd_is_the_one_scenariogeneration_ships() -> None:
    xsd = openscenario_xsd()
    assert xsd.name == "OpenSCENARIO_1_2.xsd" and xsd.is_file()


def test_every_manoeuvre_and_condition_exports_to_files_that_validate(exported: tuple[Scene, Path, Path]) -> None:
    _, scenario, roads = exported
    validate_openscenario(scenario)
    validate_opendrive(roads)
    assert roads.suffix == ".xodr"
    assert f'filepath="{roads.name}"' in scenario.read_text()


def test_a_file_that_breaks_the_schema_is_refused(exported: tuple[Scene, Path, Path], tmp_path: Path) -> None:
    broken = tmp_path / "broken.xosc"
    broken.write_text(exported[1].read_text().replace("TeleportAction", "TeleportTo"))
    with pytest.raises(OpenScenarioError, match=r"not valid OpenSCENARIO 1\.2"):
        validate_openscenario(broken)


def test_reading_the_export_back_gives_the_same_storyboard(exported: tuple[Scene, Path, Path]) -> None:
    scene, scenario, _ = exported
    read = read_openscenario(scenario)
    assert _close(read.storyboard.model_dump(), scene.storyboard.model_dump())


def test_reading_the_export_back_gives_the_same_actors_and_environment(exported: tuple[Scene, Path, Path]) -> None:
    scene, scenario, _ = exported
    read = read_openscenario(scenario)
    assert set(read.actors) == {a.id for a in scene.all_assets()}
    for asset in scene.all_assets():
        actor = read.actors[asset.id]
        assert actor.category == asset.category
        assert _close([actor.x, actor.y, actor.yaw], [asset.pose.x, asset.pose.y, asset.pose.yaw])
    assert read.time_of_day == "18:45"
    assert read.weather.kind == "rain" and read.weather.intensity == pytest.approx(0.6)


@pytest.mark.parametrize(("weather", "tolerance"), [
    (Weather(kind="fog", intensity=0.7), 0.001), (Weather(kind="snow", intensity=0.3), 1e-9),
    (Weather(kind="cloudy", intensity=0.5), 1 / 16), (Weather(), 0.0),
])
def test_weather_kinds_survive_the_round_trip(weather: Weather, tolerance: float, tmp_path: Path) -> None:
    scene = build_campus().model_copy(update={"environment": Environment(weather=weather)})
    scenario, _ = export_openscenario(scene, tmp_path / "weather.xosc")
    validate_openscenario(scenario)
    read = read_openscenario(scenario)
    assert read.weather.kind == weather.kind
    assert read.weather.intensity == pytest.approx(weather.intensity, abs=tolerance)


def test_the_export_command_writes_and_validates_both_files(tmp_path: Path) -> None:
    source = tmp_path / "scene.json"
    _every_kind_scene().save(source)
    result = CliRunner().invoke(main, ["export", str(source), "--to", str(tmp_path / "out.xosc")])
    assert result.exit_code == 0, result.output
    assert "11 events, valid against the OpenSCENARIO 1.2 XSD; roads valid OpenDRIVE 1.7" in result.output
    assert (tmp_path / "out.xosc").is_file() and (tmp_path / "out.xodr").is_file()


def test_the_export_command_refuses_an_unknown_format_in_one_line(tmp_path: Path) -> None:
    source = tmp_path / "scene.json"
    build_campus().save(source)
    result = CliRunner().invoke(main, ["export", str(source), "--to", str(tmp_path / "out.json")])
    assert result.exit_code != 0
    assert result.output.strip() == "Error: cannot export to 'out.json': the target must end in .xosc (OpenSCENARIO)"
    assert not (tmp_path / "out.json").exists()
