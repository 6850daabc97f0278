"""Settings and errors of the diffusion enhancer (plain data; importing this needs no torch)."""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, ConfigDict, Field, model_validator

# Without a ControlNet nothing pins the layout, so img2img may only repaint lightly:
# at 0.3 SDXL keeps object outlines and mostly changes texture, light and colour.
LOW_STRENGTH = 0.3
# With a depth ControlNet the renderer's depth holds poses and scales in place, so the
# diffusion may repaint more of the frame.
CONTROLLED_STRENGTH = 0.5
# Fewer than ~20 scheduler steps leaves img2img noisy; strength x steps are actually run.
DEFAULT_STEPS = 20
# Moderate classifier-free guidance; high values push SDXL towards its own composition.
DEFAULT_GUIDANCE = 5.0
# SDXL is trained at about 1024 px on the long side; renderer frames are scaled up to this.
DEFAULT_WORK_LONG_SIDE = 1024
# Worst-window fraction of outlines lost or new (structure.outline_change). On rendered campus
# frames (worlds/enhance/README.md) tint, brightness, contrast, relighting, noise sigma 8, blur
# sigma 1 and JPEG q30 stay <= 0.20 and cars moved sideways by 1-2 m mostly score > 0.3.
DEFAULT_MAX_STRUCTURE_DISTANCE = 0.25
# Worst-tile difference of scale-and-shift-normalised depth estimates (units: the baseline's
# mean absolute deviation). 0.3 separates a vehicle moved by a quarter of the frame (0.46)
# from 5 % per-pixel estimator noise (0.13) on the test scenes; not yet tuned on a real model.
DEFAULT_MAX_DEPTH_DISAGREEMENT = 0.3

Fraction = Annotated[float, Field(gt=0.0, le=1.0, allow_inf_nan=False)]


class EnhancerError(RuntimeError):
    """Base of every error the enhancer raises on purpose."""


class EnhanceExtraMissing(EnhancerError):
    """The optional extra (diffusers, transformers, torch) is not installed."""


class EnhanceWeightsMissing(EnhancerError):
    """Weights the user named are not on disk (nothing is ever downloaded at run time)."""


class EnhanceInputError(EnhancerError, ValueError):
    """A frame, depth map or folder given to the enhancer has the wrong shape or content."""


class EnhanceSettings(BaseModel):
    """What the enhancer loads and how hard it repaints; defaults keep the geometry."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    model: str = Field(description="SDXL folder, or a model id already in the Hugging Face cache")
    controlnet: str | None = Field(
        default=None, description="SDXL depth ControlNet folder or cached id; None = plain img2img"
    )
    depth_model: str | None = Field(
        default=None,
        description="monocular depth estimator (transformers) for the depth-disagreement check",
    )
    local_files_only: bool = Field(
        default=True, description="never reach the network; False lets from_pretrained download"
    )
    strength: Fraction | None = Field(
        default=None,
        description=f"img2img strength; None = {LOW_STRENGTH} without a ControlNet, {CONTROLLED_STRENGTH} with one",
    )
    steps: Annotated[int, Field(ge=1, le=200)] = DEFAULT_STEPS
    guidance: Annotated[float, Field(ge=0.0, le=30.0)] = DEFAULT_GUIDANCE
    controlnet_scale: Annotated[float, Field(ge=0.0, le=2.0)] = 0.8
    seed: int | None = Field(default=0, description="fixed seed for repeatable frames; None = random")
    work_long_side: Annotated[int, Field(ge=64, le=4096)] | None = Field(
        default=DEFAULT_WORK_LONG_SIDE,
        description="long side (px) the diffusion runs at; None = the frame's own size",
    )
    device: str = Field(default="auto", description="'auto', 'cpu', 'cuda', 'cuda:1', 'mps'")
    max_structure_distance: Annotated[float, Field(ge=0.0, le=2.0)] = DEFAULT_MAX_STRUCTURE_DISTANCE
    max_luminance_distance: Annotated[float, Field(ge=0.0, le=2.0)] | None = Field(
        default=None,
        description="optional limit on 1 - low-res luminance SSIM (off: relighting is intended)",
    )
    max_depth_disagreement: Annotated[float, Field(ge=0.0)] = DEFAULT_MAX_DEPTH_DISAGREEMENT

    @model_validator(mode="after")
    def _runs_at_least_one_step(self) -> EnhanceSettings:
        # img2img runs int(steps x strength) denoising steps; zero would be a silent no-op.
        if int(self.steps * self.effective_strength()) < 1:
            raise ValueError(
                f"steps x strength = {self.steps} x {self.effective_strength()} runs no "
                f"denoising step; raise steps to at least {int(1 / self.effective_strength()) + 1}"
            )
        return self

    def effective_strength(self) -> float:
        """The img2img strength actually used."""
        if self.strength is not None:
            return self.strength
        return CONTROLLED_STRENGTH if self.controlnet else LOW_STRENGTH
