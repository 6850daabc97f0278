"""The sensor rig fires each sensor at its own rate from the simulation loop."""

from __future__ import annotations

import numpy as np
import pytest
from drivetwin.worlds.defaults import load_world
from drivetwin.worlds.render.hybrid import HybridRenderer
from drivetwin.worlds.sensors import CameraSensor, Lidar, Mount, SensorError, SensorRig
from drivetwin.worlds.simulation import Simulation


@pytest.fixture(scope="module")
def sim() -> Simulation:
    return Simulation(load_world("campus"))


def test_each_sensor_fires_at_its_own_rate(sim: Simulation) -> None:
    rig = SensorRig([Lidar(4, horizontal_resolution_deg=5.0, rate_hz=10.0, name="roof"),
                     Lidar(4, horizontal_resolution_deg=5.0, rate_hz=4.0, name="slow")],
                    lock=sim.lock)  # fmt: skip
    fired: dict[str, int] = {"roof": 0, "slow": 0}
    for step in range(101):  # one simulated second at 100 ticks per second
        for name in rig.tick(step * 0.01, sim.world):
            fired[name] += 1
    assert fired == {"roof": 10 + 1, "slow": 4 + 1}  # both also fire on the first tick


def test_a_camera_on_the_ego_moves_with_it_and_returns_depth(sim: Simulation) -> None:
    renderer = HybridRenderer(sim.world, lock=sim.lock)
    front = CameraSensor("front", width=64, height=36, mount=Mount("ego", (2.5, 0.0, 1.4)))
    rig = SensorRig([front], renderer=renderer, lock=sim.lock)
    before = front.camera(sim.world).position
    reading = rig.tick(sim.time, sim.world)["front"]
    assert reading.frame is not None and reading.frame.rgb.shape == (36, 64, 3)
    assert np.isfinite(reading.frame.depth).any()
    ego = sim.world.body_pose("ego")
    assert before[2] == pytest.approx(ego.z + 1.4, abs=0.05)
    sim.run_for(1.0)  # the ego drives its lane
    assert np.linalg.norm(front.camera(sim.world).position - before) > 0.5


def test_a_camera_needs_a_rig_with_a_renderer() -> None:
    with pytest.raises(SensorError, match="needs a rig made with a renderer"):
        SensorRig([CameraSensor("front")])
