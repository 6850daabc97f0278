"""`drivetwin chat` on an imported map: cars go into named lanes and near named junctions, and a
frame renders."""

from __future__ import annotations

import math

import numpy as np
import pytest
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
from drivetwin.worlds.scene import Scene
from drivetwin.worlds.surface import lane_at
from PIL import Image

LANE = "main_street_99_right1"
JUNCTION = "junction of Main Street and Oak Avenue"


@pytest.fixture
def state(tmp_path, monkeypatch):
    monkeypatch.setenv("DRIVETWIN_STATE", str(tmp_path / "state"))
    return tmp_path


def chat(town_file, script, *flags: str):
    return CliRunner().invoke(main, ["chat", "--world", str(town_file), "--planner", "rules", "--script", str(script),
                                     "--fail-fast", *flags])


def test_chat_without_physics_places_a_car_in_a_named_lane_and_a_cone_at_a_junction(state, town_file):
    script = state / "script.txt"
    saved = state / "after.json"
    script.write_text(f"add a car in lane {LANE}\nput a traffic cone next to the {JUNCTION}\nsave {saved}\n",
                      encoding="utf-8")
    result = chat(town_file, script, "--no-sim")
    assert result.exit_code == 0, result.output
    scene = Scene.load(saved)
    (car,) = [a for a in scene.assets if a.category == "passenger_car"]
    assert lane_at(scene, car.pose.x, car.pose.y).id == LANE
    (cone,) = [a for a in scene.assets if a.category == "traffic_cone"]
    assert math.dist(cone.pose.xy, scene.landmark(JUNCTION).position) < 15.0


def test_chat_renders_a_frame_of_the_imported_map_after_the_prompt(state, town_file):
    script = state / "script.txt"
    script.write_text(f"add a car in lane {LANE}\n", encoding="utf-8")
    out = state / "out"
    result = chat(town_file, script, "--render-each", "--out", str(out))
    assert result.exit_code == 0, result.output
    frames = sorted(out.glob("*.png"))
    assert frames, result.output
    rgb = np.asarray(Image.open(frames[0]).convert("RGB"), dtype=float)
    assert rgb.shape[0] >= 90 and rgb.std() > 10.0  # a picture of something, not a blank
    r, g, b = rgb[..., 0], rgb[..., 1], rgb[..., 2]
    assert ((r > 150) & (g > 110) & (b < 0.5 * g)).sum() > 50  # the street's yellow centre line
