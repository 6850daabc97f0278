"""The SDXL img2img enhancer, loaded from disk through the same code users run."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import CAR_X, FRAME_H, FRAME_W, draw_depth, draw_street
from drivetwin.worlds.enhance import (
    EnhanceInputError,
    EnhanceSettings,
    EnhanceWeightsMissing,
    FrameEnhancer,
    load_pipeline,
)
from drivetwin.worlds.enhance.pipeline import depth_to_control, work_size
from drivetwin.worlds.scene import Environment, Weather

# Tiny pipeline: 64 x 64 work size, 4 steps at strength 0.5 = 2 denoising steps.
TINY = {"work_long_side": 64, "steps": 4, "strength": 0.5, "device": "cpu"}


@pytest.fixture(scope="module")
def enhancer(tiny_sdxl: dict[str, Path]) -> FrameEnhancer:
    return FrameEnhancer(EnhanceSettings(model=str(tiny_sdxl["model"]), **TINY))


def test_importing_the_package_does_not_import_torch_or_diffusers() -> None:
    code = (
        "import sys, drivetwin.worlds.enhance as e; "
        "print(sorted(m for m in ('torch', 'diffusers', 'transformers') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_the_saved_pipeline_loads_as_sdxl_img2img(tiny_sdxl: dict[str, Path]) -> None:
    pipe = load_pipeline(EnhanceSettings(model=str(tiny_sdxl["model"]), **TINY))
    assert type(pipe).__name__ == "StableDiffusionXLImg2ImgPipeline"
    assert pipe.device.type == "cpu"


def test_an_enhanced_frame_has_the_frame_size_and_is_repeatable(enhancer: FrameEnhancer) -> None:
    frame = draw_street()
    rainy = Environment(time_of_day="21:00", weather=Weather(kind="rain", intensity=0.8))
    first = enhancer.repaint(frame, env=rainy)
    second = enhancer.repaint(frame, env=rainy)
    assert first.shape == (FRAME_H, FRAME_W, 3) and first.dtype == np.uint8
    assert not np.array_equal(first, frame)  # the diffusion did repaint it
    np.testing.assert_array_equal(first, second)  # fixed seed: same frame twice


def test_a_frame_that_fails_the_structure_check_shows_the_baseline(
    tiny_sdxl: dict[str, Path], enhancer: FrameEnhancer
) -> None:
    strict = FrameEnhancer(
        EnhanceSettings(model=str(tiny_sdxl["model"]), max_structure_distance=0.0, **TINY),
        pipeline=enhancer.pipeline,
    )
    result = strict.enhance(draw_street())
    assert not result.accepted
    np.testing.assert_array_equal(result.image, draw_street())
    assert not np.array_equal(result.candidate, draw_street())


def test_a_frame_within_the_limit_shows_the_enhancement(
    tiny_sdxl: dict[str, Path], enhancer: FrameEnhancer
) -> None:
    lenient = FrameEnhancer(
        EnhanceSettings(model=str(tiny_sdxl["model"]), max_structure_distance=2.0, **TINY),
        pipeline=enhancer.pipeline,
    )
    result = lenient.enhance(draw_street())
    assert result.accepted and result.seconds > 0.0
    np.testing.assert_array_equal(result.image, result.candidate)


class CarMovingEnhancer(FrameEnhancer):
    """An enhancer whose 'diffusion' moves the car 12 px and brightens the frame."""

    def repaint(self, frame, depth=None, env=None):  # type: ignore[no-untyped-def]
        return np.clip(draw_street(car_x=CAR_X + 12).astype(int) + 15, 0, 255).astype(np.uint8)


def test_an_enhancement_that_moved_the_geometry_is_rejected_and_the_baseline_kept(
    tiny_sdxl: dict[str, Path], enhancer: FrameEnhancer
) -> None:
    settings = EnhanceSettings(model=str(tiny_sdxl["model"]), **TINY)
    result = CarMovingEnhancer(settings, pipeline=enhancer.pipeline).enhance(draw_street())
    assert not result.accepted
    assert "edge structure distance" in result.score.reason
    np.testing.assert_array_equal(result.image, draw_street())


def test_the_depth_controlnet_pipeline_conditions_on_the_renderer_depth(
    tiny_sdxl: dict[str, Path],
) -> None:
    settings = EnhanceSettings(
        model=str(tiny_sdxl["model"]), controlnet=str(tiny_sdxl["controlnet"]), **TINY
    )
    controlled = FrameEnhancer(settings)
    assert type(controlled.pipeline).__name__ == "StableDiffusionXLControlNetImg2ImgPipeline"
    near = controlled.repaint(draw_street(), depth=draw_depth())
    far = controlled.repaint(draw_street(), depth=draw_depth() * 50.0 + 100.0)
    assert near.shape == (FRAME_H, FRAME_W, 3)
    assert not np.array_equal(near, far)  # the depth reaches the ControlNet
    with pytest.raises(EnhanceInputError, match="needs the renderer's depth"):
        controlled.repaint(draw_street())


def test_without_the_extra_loading_says_which_pip_install_fixes_it() -> None:
    code = (
        "import sys; sys.modules['diffusers'] = None\n"  # makes `import diffusers` fail
        "from drivetwin.worlds.enhance import EnhanceExtraMissing, EnhanceSettings, load_pipeline\n"
        "try:\n"
        "    load_pipeline(EnhanceSettings(model='m', device='cpu'))\n"
        "except EnhanceExtraMissing as exc:\n"
        "    print(exc)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "pip install 'drivetwin[enhance]'" in out.stdout


def test_a_missing_model_folder_is_one_line_naming_how_to_get_the_weights(tmp_path: Path) -> None:
    pytest.importorskip("diffusers", reason="the enhance extra (diffusers) is not installed")
    with pytest.raises(EnhanceWeightsMissing) as err:
        load_pipeline(EnhanceSettings(model=str(tmp_path / "nowhere"), device="cpu"))
    message = str(err.value)
    assert "\n" not in message
    assert "hf download stabilityai/stable-diffusion-xl-base-1.0" in message


def test_a_model_id_missing_from_the_cache_is_not_downloaded(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    pytest.importorskip("diffusers", reason="the enhance extra (diffusers) is not installed")
    monkeypatch.setenv("HF_HOME", str(tmp_path / "empty-cache"))
    monkeypatch.setenv("HF_HUB_CACHE", str(tmp_path / "empty-cache" / "hub"))
    with pytest.raises(EnhanceWeightsMissing, match="nothing is downloaded") as err:
        load_pipeline(EnhanceSettings(model="stabilityai/stable-diffusion-xl-base-1.0"))
    assert "\n" not in str(err.value)


def test_an_empty_folder_is_reported_as_missing_weights(tmp_path: Path) -> None:
    pytest.importorskip("diffusers", reason="the enhance extra (diffusers) is not installed")
    with pytest.raises(EnhanceWeightsMissing, match="hf download"):
        load_pipeline(EnhanceSettings(model=str(tmp_path), device="cpu"))


def test_settings_refuse_a_run_without_any_denoising_step() -> None:
    with pytest.raises(ValueError, match="runs no denoising step"):
        EnhanceSettings(model="m", steps=2, strength=0.3)


def test_default_strength_is_low_without_a_controlnet_and_higher_with_one() -> None:
    plain = EnhanceSettings(model="m").effective_strength()
    controlled = EnhanceSettings(model="m", controlnet="c").effective_strength()
    assert plain <= 0.35 < controlled


def test_work_size_scales_the_long_side_and_keeps_sides_multiples_of_64() -> None:
    assert work_size(360, 640, 1024) == (576, 1024)
    assert work_size(96, 128, None) == (128, 128)
    assert all(side % 64 == 0 for side in work_size(123, 457, 777))


def test_depth_becomes_a_disparity_image_with_near_bright_and_sky_black() -> None:
    control = np.asarray(depth_to_control(draw_depth(), (FRAME_H, FRAME_W)))
    assert control.shape == (FRAME_H, FRAME_W, 3)
    car = control[FRAME_H // 2 + 10, CAR_X + 10, 0]
    building = control[40, 20, 0]
    sky = control[2, 64, 0]
    assert car > building > sky == 0


def test_the_benchmark_times_full_enhancements_at_the_requested_size(
    tiny_sdxl: dict[str, Path], enhancer: FrameEnhancer
) -> None:
    from drivetwin.worlds.enhance.bench import measure_fps

    settings = EnhanceSettings(model=str(tiny_sdxl["model"]), **TINY)
    result = measure_fps(settings, height=96, width=128, frames=1, warmup=0, enhancer=enhancer)
    assert result.frame == (96, 128) and result.work == (64, 64) and result.steps_run == 2
    assert result.frames_per_second > 0.0 and result.device == "cpu"
