"""The simulation loop: steps in the background while edits arrive, keeps movers moving."""

from __future__ import annotations

import threading
import time

from conftest import make_asset, make_scene
from drivetwin.worlds.defaults import load_world
from drivetwin.worlds.mujoco_adapter import consistency_problems
from drivetwin.worlds.scene import DriveLane, Scene
from drivetwin.worlds.simulation import Simulation


def test_background_loop_advances_time_while_another_thread_applies_edits() -> None:
    scene = make_scene(make_asset("car", "passenger_car", -50.0, -1.75, behaviour=DriveLane(lane="east", speed=6.0)))
    sim = Simulation(scene)
    times: list[float] = []
    errors: list[BaseException] = []

    def edit() -> None:
        try:
            current: Scene = scene
            for k in range(12):
                cones = [make_asset(f"cone_{i}", "traffic_cone", 10.0 + i, 10.0) for i in range(k % 4)]
                current = current.model_copy(update={"assets": [scene.assets[0], *cones]})
                sim.apply(current)
                times.append(sim.time)
                time.sleep(0.01)
        except BaseException as exc:
            errors.append(exc)

    sim.start(realtime=False)
    editor = threading.Thread(target=edit)
    editor.start()
    editor.join(timeout=20)
    sim.stop()
    assert not errors, errors
    assert len(times) == 12
    assert times == sorted(times) and times[-1] > times[0], "time must advance monotonically"
    assert not sim.running
    assert consistency_problems(sim.scene, sim.world) == []


def test_realtime_loop_keeps_pace_with_the_wall_clock() -> None:
    sim = Simulation(make_scene())
    sim.start(realtime=True)
    time.sleep(0.5)
    sim.stop()
    assert 0.3 < sim.time < 0.7


def test_a_driving_car_keeps_moving_through_an_unrelated_edit() -> None:
    scene = make_scene(make_asset("car", "passenger_car", -50.0, -1.75, behaviour=DriveLane(lane="east", speed=6.0)))
    sim = Simulation(scene)
    sim.run_for(3.0)
    before = sim.pose("car").x
    sim.apply(scene.model_copy(update={"assets": [*scene.assets, make_asset("cone_1", "traffic_cone", 0.0, 30.0)]}))
    assert abs(sim.pose("car").x - before) < 1e-9, "an unrelated edit must not move the car"
    sim.run_for(1.0)
    assert sim.pose("car").x - before > 4.0, "it keeps driving at about 6 m/s"


def test_campus_world_compiles_consistently_and_its_ego_drives_its_lane() -> None:
    scene = load_world("campus")
    sim = Simulation(scene)
    assert consistency_problems(scene, sim.world) == []
    start = sim.pose("ego")
    sim.run_for(2.0)
    moved = sim.pose("ego")
    assert moved.x - start.x > 3.0 and abs(moved.y - start.y) < 0.3
