"""`drivetwin chat --enhance`: the live world hands its frames to the online enhancer."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
from drivetwin.orchestrator.live import LiveWorld
from drivetwin.orchestrator.planning.registry import make_planner
from drivetwin.orchestrator.session import Session
from drivetwin.worlds.defaults import load_world
from drivetwin.worlds.enhance import EnhanceSettings
from PIL import Image

TINY = {"work_long_side": 64, "steps": 2, "strength": 0.5, "device": "cpu"}


def test_a_live_chat_writes_the_enhanced_frame_beside_the_rendered_one(
    tmp_path: Path, tiny_sdxl: dict[str, Path]
) -> None:
    session = Session(load_world("campus"), make_planner("rules"), journal_path=tmp_path / "j.jsonl")
    live = LiveWorld(session, simulate=True, background=False,
                     enhance=EnhanceSettings(model=str(tiny_sdxl["model"]), **TINY))
    try:
        session.submit("make it rain")
        written = live.render(session, tmp_path / "step_1.png")
    finally:
        written += live.close()
    enhanced = tmp_path / "step_1_enhanced.png"
    assert enhanced in written and enhanced.exists()
    baseline = np.asarray(Image.open(tmp_path / "step_1.png"))
    assert np.asarray(Image.open(enhanced)).shape == baseline.shape
    summary = live.enhancer_summary() or ""
    assert "1 frames submitted, 1 enhanced, 0 dropped" in summary


def test_chat_with_missing_enhancer_weights_stops_with_one_clear_line(tmp_path: Path) -> None:
    script = tmp_path / "s.txt"
    script.write_text("make it rain\n")
    missing = tmp_path / "no-sdxl-here"
    result = CliRunner().invoke(main, ["chat", "--planner", "rules", "--no-sim", "--script", str(script),
                                       "--journal", str(tmp_path / "j.jsonl"), "--enhance", str(missing)])
    assert result.exit_code == 1
    assert "Traceback" not in result.output
    assert str(missing) in result.output
    assert not (tmp_path / "j.jsonl").exists() or "rain" not in (tmp_path / "j.jsonl").read_text()
