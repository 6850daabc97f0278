"""Offline enhancement of a folder: outputs, the JSON report, rejection rate and resuming."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from conftest import draw_depth, draw_street
from drivetwin.worlds.enhance import (
    EnhancedFrame,
    EnhanceInputError,
    EnhanceSettings,
    FrameEnhancer,
    enhance_folder,
)
from drivetwin.worlds.scene import Environment, Scene, Weather
from PIL import Image

TINY = {"work_long_side": 64, "steps": 4, "strength": 0.5, "device": "cpu"}


@pytest.fixture(scope="module")
def settings(tiny_sdxl: dict[str, Path]) -> EnhanceSettings:
    return EnhanceSettings(model=str(tiny_sdxl["model"]), **TINY)


@pytest.fixture(scope="module")
def enhancer(settings: EnhanceSettings) -> FrameEnhancer:
    return FrameEnhancer(settings)


def write_frames(folder: Path, count: int, depth: bool = False) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for i in range(count):
        path = folder / f"frame_{i:04d}.png"
        Image.fromarray(draw_street(seed=i)).save(path)
        if depth:
            np.save(folder / f"frame_{i:04d}.depth.npy", draw_depth())
        paths.append(path)
    return paths


class InterruptAfter:
    """Wraps the real enhancer and raises KeyboardInterrupt (Ctrl-C) on frame `after` + 1."""

    def __init__(self, inner: FrameEnhancer, after: int) -> None:
        self.inner, self.after, self.calls = inner, after, 0

    def enhance(self, frame, depth=None, env=None) -> EnhancedFrame:  # type: ignore[no-untyped-def]
        self.calls += 1
        if self.calls > self.after:
            raise KeyboardInterrupt
        return self.inner.enhance(frame, depth, env)


class RecordingEnhancer:
    """Wraps the real enhancer and records the environment and depth each frame came with."""

    def __init__(self, inner: FrameEnhancer) -> None:
        self.inner = inner
        self.envs: list[Environment | None] = []
        self.depths: list[bool] = []

    def enhance(self, frame, depth=None, env=None) -> EnhancedFrame:  # type: ignore[no-untyped-def]
        self.envs.append(env)
        self.depths.append(depth is not None)
        return self.inner.enhance(frame, depth, env)


def test_a_folder_is_enhanced_and_reported(
    tmp_path: Path, settings: EnhanceSettings, enhancer: FrameEnhancer
) -> None:
    write_frames(tmp_path / "src", 3)
    report = enhance_folder(
        tmp_path / "src", tmp_path / "out", settings, progress=False, enhancer=enhancer
    )
    outputs = sorted(p.name for p in (tmp_path / "out").glob("*.png"))
    assert outputs == ["frame_0000.png", "frame_0001.png", "frame_0002.png"]
    assert report.frames_total == report.frames_done == report.frames_this_run == 3
    records = [json.loads(line) for line in (tmp_path / "out" / "frames.jsonl").read_text().splitlines()]
    assert len(records) == 3
    rejected = sum(1 for record in records if not record["accepted"])
    assert report.rejected == rejected and report.rejection_rate == rejected / 3
    assert report.seconds_per_frame is not None and report.seconds_per_frame > 0
    saved = json.loads((tmp_path / "out" / "report.json").read_text())
    assert saved["frames_done"] == 3 and saved["rejected"] == report.rejected
    assert not list((tmp_path / "out").glob("*.tmp"))


def test_an_interrupted_run_resumes_without_redoing_finished_frames(
    tmp_path: Path, settings: EnhanceSettings, enhancer: FrameEnhancer
) -> None:
    write_frames(tmp_path / "src", 5)
    out = tmp_path / "out"
    with pytest.raises(KeyboardInterrupt):
        enhance_folder(
            tmp_path / "src", out, settings, progress=False, enhancer=InterruptAfter(enhancer, 2)
        )
    assert sorted(p.name for p in out.glob("*.png")) == ["frame_0000.png", "frame_0001.png"]
    assert not list(out.glob(".*.tmp"))
    first_mtime = (out / "frame_0000.png").stat().st_mtime_ns
    report = enhance_folder(tmp_path / "src", out, settings, progress=False, enhancer=enhancer)
    assert report.frames_skipped == 2 and report.frames_this_run == 3
    assert report.frames_done == 5
    assert (out / "frame_0000.png").stat().st_mtime_ns == first_mtime
    again = enhance_folder(tmp_path / "src", out, settings, progress=False, enhancer=enhancer)
    assert again.frames_this_run == 0 and again.frames_done == 5


def test_a_frame_whose_record_was_cut_short_is_redone(
    tmp_path: Path, settings: EnhanceSettings, enhancer: FrameEnhancer
) -> None:
    write_frames(tmp_path / "src", 2)
    out = tmp_path / "out"
    enhance_folder(tmp_path / "src", out, settings, progress=False, enhancer=enhancer)
    lines = (out / "frames.jsonl").read_text().splitlines()
    (out / "frames.jsonl").write_text(lines[0] + "\n" + lines[1][:10])
    report = enhance_folder(tmp_path / "src", out, settings, progress=False, enhancer=enhancer)
    assert report.frames_this_run == 1 and report.frames_done == 2


def test_rejected_frames_keep_the_baseline_and_count_in_the_rejection_rate(
    tmp_path: Path, tiny_sdxl: dict[str, Path], enhancer: FrameEnhancer
) -> None:
    strict = EnhanceSettings(model=str(tiny_sdxl["model"]), max_structure_distance=0.0, **TINY)
    frames = write_frames(tmp_path / "src", 2)
    report = enhance_folder(
        tmp_path / "src",
        tmp_path / "out",
        strict,
        progress=False,
        enhancer=FrameEnhancer(strict, pipeline=enhancer.pipeline),
    )
    assert report.rejected == 2 and report.rejection_rate == 1.0
    for frame in frames:
        out = np.asarray(Image.open(tmp_path / "out" / frame.name))
        np.testing.assert_array_equal(out, np.asarray(Image.open(frame)))


def test_depth_files_and_the_scene_environment_reach_the_enhancer(
    tmp_path: Path, settings: EnhanceSettings, enhancer: FrameEnhancer
) -> None:
    from drivetwin.worlds.defaults import load_world

    write_frames(tmp_path / "src", 2, depth=True)
    scene: Scene = load_world("campus")
    night_rain = Environment(time_of_day="22:00", weather=Weather(kind="rain", intensity=0.7))
    scene.model_copy(update={"environment": night_rain}).save(tmp_path / "src" / "scene.json")
    recorder = RecordingEnhancer(enhancer)
    enhance_folder(tmp_path / "src", tmp_path / "out", settings, progress=False, enhancer=recorder)
    assert recorder.depths == [True, True]
    assert all(env == night_rain for env in recorder.envs)


def test_a_rendered_session_folder_enhances_each_frame_with_its_own_depth_and_environment(
    tmp_path: Path, settings: EnhanceSettings, enhancer: FrameEnhancer
) -> None:
    """The layout `drivetwin demo` and `chat --render-each` write: step_N.png with
    step_N_depth.npy, a step_N_depth.png preview and step_N_env.json beside it."""
    src = tmp_path / "src"
    src.mkdir()
    envs = [Environment(weather=Weather(kind="rain", intensity=0.6)), Environment(time_of_day="22:00")]
    for i, env in enumerate(envs, 1):
        Image.fromarray(draw_street(seed=i)).save(src / f"step_{i:02d}.png")
        np.save(src / f"step_{i:02d}_depth.npy", draw_depth())
        Image.fromarray(np.zeros((8, 8), np.uint8)).save(src / f"step_{i:02d}_depth.png")
        (src / f"step_{i:02d}_env.json").write_text(env.model_dump_json())
    Image.fromarray(draw_street()).save(src / "step_01_enhanced.png")
    recorder = RecordingEnhancer(enhancer)
    report = enhance_folder(src, tmp_path / "out", settings, progress=False, enhancer=recorder)
    assert report.frames_total == 2
    assert recorder.depths == [True, True]
    assert recorder.envs == envs


def test_the_controlnet_enhancer_reads_depth_from_the_folder(
    tmp_path: Path, tiny_sdxl: dict[str, Path]
) -> None:
    controlled = EnhanceSettings(
        model=str(tiny_sdxl["model"]), controlnet=str(tiny_sdxl["controlnet"]), **TINY
    )
    write_frames(tmp_path / "src", 1, depth=True)
    report = enhance_folder(tmp_path / "src", tmp_path / "out", controlled, progress=False)
    assert report.frames_done == 1


def test_progress_is_shown_on_a_terminal_and_not_in_a_pipe(
    tmp_path: Path,
    settings: EnhanceSettings,
    enhancer: FrameEnhancer,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    import io
    import sys

    class Terminal(io.StringIO):
        def isatty(self) -> bool:
            return True

    monkeypatch.delenv("CI", raising=False)
    write_frames(tmp_path / "src", 2)
    enhance_folder(tmp_path / "src", tmp_path / "piped", settings, progress=True, enhancer=enhancer)
    assert capsys.readouterr().err == ""  # stderr is captured here: a pipe gets no bar
    screen = Terminal()
    monkeypatch.setattr(sys, "stderr", screen)
    enhance_folder(tmp_path / "src", tmp_path / "out", settings, progress=True, enhancer=enhancer)
    assert "enhance" in screen.getvalue() and "2/2" in screen.getvalue()


def test_folder_mistakes_are_refused_with_the_reason(tmp_path: Path) -> None:
    settings = EnhanceSettings(model="unused")
    with pytest.raises(EnhanceInputError, match="not a folder"):
        enhance_folder(tmp_path / "missing", tmp_path / "out", settings)
    (tmp_path / "empty").mkdir()
    with pytest.raises(EnhanceInputError, match="holds no"):
        enhance_folder(tmp_path / "empty", tmp_path / "out", settings)
    write_frames(tmp_path / "src", 1)
    with pytest.raises(EnhanceInputError, match="must differ"):
        enhance_folder(tmp_path / "src", tmp_path / "src", settings)


def test_the_default_output_folder_sits_beside_the_source(tmp_path: Path) -> None:
    from drivetwin.worlds.enhance import default_output_dir

    assert default_output_dir(tmp_path / "run1") == tmp_path / "run1-enhanced"
