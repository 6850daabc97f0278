"""The SDXL img2img enhancer of one frame: loading the weights, repainting, checking structure.

torch and diffusers are imported inside functions, so `import drivetwin.worlds.enhance` works
on the base install; only loading a pipeline needs the extra `drivetwin[enhance]`.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from drivetwin.worlds.enhance.prompting import build_prompts
from drivetwin.worlds.enhance.settings import (
    EnhanceExtraMissing,
    EnhanceInputError,
    EnhanceSettings,
    EnhanceWeightsMissing,
)
from drivetwin.worlds.enhance.structure import (
    DepthEstimator,
    StructureScore,
    check_frame,
    structure_score,
)
from drivetwin.worlds.scene import Environment
from numpy.typing import NDArray
from PIL import Image

# SDXL's UNet downsamples latents (already 1/8 of the image) up to 3 times, so image sides
# must be multiples of 64 for every SDXL-family UNet.
SIDE_MULTIPLE = 64
# Disparity is divided by this percentile, not the maximum, so one very near pixel cannot wash
# out the rest of the control image (zero disparity stays zero: infinitely far, like the sky).
_DISPARITY_PERCENTILE = 98.0
EXTRA_HINT = "pip install 'drivetwin[enhance]'  (diffusers, transformers, accelerate, torch)"
SDXL_HINT = (
    "hf download stabilityai/stable-diffusion-xl-base-1.0 --include '*.json' '*.txt' "
    "'*.fp16.safetensors' --local-dir models/sdxl"
)
CONTROLNET_HINT = (
    "hf download diffusers/controlnet-depth-sdxl-1.0-small --local-dir models/depth-cn"
)


def import_extra(*modules: str) -> list[Any]:
    """Import the optional extra's modules, or raise EnhanceExtraMissing naming the fix."""
    import importlib

    loaded = []
    for name in modules:
        try:
            loaded.append(importlib.import_module(name))
        except ImportError as exc:
            raise EnhanceExtraMissing(
                f"the enhancer needs '{name}', which is not installed; install it with: "
                f"{EXTRA_HINT}"
            ) from exc
    return loaded


def resolve_device(name: str) -> str:
    """'auto' becomes 'cuda' when a CUDA GPU is visible, else 'cpu'; others pass through."""
    if name != "auto":
        return name
    (torch,) = import_extra("torch")
    return "cuda" if torch.cuda.is_available() else "cpu"


def _variant(source: str) -> str | None:
    """'fp16' when a local folder holds only the fp16 weight files (the small download)."""
    folder = Path(source)
    if not folder.is_dir():
        return None
    # A pipeline keeps its UNet weights in unet/, a ControlNet at the top of its folder.
    weights = folder / "unet" if (folder / "unet").is_dir() else folder
    has_fp16 = any(weights.glob("*.fp16.safetensors"))
    has_full = any(weights.glob("diffusion_pytorch_model.safetensors"))
    return "fp16" if has_fp16 and not has_full else None


def _missing(what: str, source: str, hint: str, exc: Exception) -> EnhanceWeightsMissing:
    first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
    return EnhanceWeightsMissing(
        f"{what} weights not found at '{source}' (a folder, or a model id already in the "
        f"Hugging Face cache; nothing is downloaded at run time: {first[:120]}); "
        f"get them with: {hint}"
    )


def load_pipeline(settings: EnhanceSettings) -> Any:
    """Load the SDXL img2img pipeline (with the depth ControlNet when one is configured).

    Uses `from_pretrained(..., local_files_only=settings.local_files_only)`, exactly what a
    user's run does; float16 on CUDA, float32 elsewhere.
    """
    torch, diffusers = import_extra("torch", "diffusers")
    device = resolve_device(settings.device)
    dtype = torch.float16 if device.startswith("cuda") else torch.float32
    common: dict[str, Any] = {"local_files_only": settings.local_files_only, "torch_dtype": dtype}
    extra: dict[str, Any] = {}
    if settings.controlnet is not None:
        try:
            with warnings.catch_warnings():
                warnings.filterwarnings("ignore", message=".*torch_dtype.*", category=FutureWarning)
                extra["controlnet"] = diffusers.ControlNetModel.from_pretrained(
                    settings.controlnet, variant=_variant(settings.controlnet), **common
                )
        except (OSError, ValueError) as exc:
            raise _missing("depth ControlNet", settings.controlnet, CONTROLNET_HINT, exc) from exc
        cls = diffusers.StableDiffusionXLControlNetImg2ImgPipeline
    else:
        cls = diffusers.StableDiffusionXLImg2ImgPipeline
    try:
        with warnings.catch_warnings():
            # Newer diffusers rename torch_dtype to dtype; older ones only know torch_dtype.
            warnings.filterwarnings("ignore", message=".*torch_dtype.*", category=FutureWarning)
            pipe = cls.from_pretrained(
                settings.model, variant=_variant(settings.model), **common, **extra
            )
    except (OSError, ValueError) as exc:
        raise _missing("SDXL", settings.model, SDXL_HINT, exc) from exc
    if dtype == torch.float32:
        # Upcasting the VAE is a no-op in float32 and only logs a warning every frame.
        pipe.vae.register_to_config(force_upcast=False)
    pipe.set_progress_bar_config(disable=True)
    return pipe.to(device)


def work_size(height: int, width: int, long_side: int | None) -> tuple[int, int]:
    """(height, width) the diffusion runs at: long side scaled to `long_side`, sides /64."""
    scale = 1.0 if long_side is None else long_side / max(height, width)

    def snap(side: float) -> int:
        return max(SIDE_MULTIPLE, round(side / SIDE_MULTIPLE) * SIDE_MULTIPLE)

    return snap(height * scale), snap(width * scale)


def depth_to_control(depth: NDArray[np.floating], size: tuple[int, int]) -> Image.Image:
    """A depth map in metres [H, W] as the RGB disparity image depth ControlNets expect.

    Near is bright, far and invalid (non-finite or <= 0, e.g. sky) are black; `size` is
    (height, width) of the result.
    """
    d = np.asarray(depth, dtype=np.float64)
    if d.ndim != 2:
        raise EnhanceInputError(f"depth must be a 2-D array [H, W] in metres; got {d.shape}")
    valid = np.isfinite(d) & (d > 0.0)
    disparity = np.zeros_like(d)
    disparity[valid] = 1.0 / d[valid]
    if valid.any():
        top = float(np.percentile(disparity[valid], _DISPARITY_PERCENTILE))
        disparity = np.clip(disparity / max(top, 1e-9), 0.0, 1.0)
    grey = Image.fromarray((disparity * 255.0).astype(np.uint8), mode="L")
    return grey.resize((size[1], size[0]), Image.Resampling.BILINEAR).convert("RGB")


@dataclass(frozen=True)
class EnhancedFrame:
    """One frame's outcome: the image to show (enhanced, or the baseline if rejected)."""

    image: NDArray[np.uint8]
    candidate: NDArray[np.uint8]
    score: StructureScore
    seconds: float

    @property
    def accepted(self) -> bool:
        """Whether the enhanced frame kept the structure and is the one shown."""
        return bool(self.score.accepted)


class FrameEnhancer:
    """Repaints rendered frames with SDXL img2img and keeps only those that kept structure."""

    def __init__(
        self,
        settings: EnhanceSettings,
        pipeline: Any = None,
        depth_estimator: DepthEstimator | None = None,
    ) -> None:
        """Use `pipeline` if given (already loaded), else load it from `settings`."""
        self.settings = settings
        self.pipeline = pipeline if pipeline is not None else load_pipeline(settings)
        if depth_estimator is None and settings.depth_model is not None:
            from drivetwin.worlds.enhance.extractors import load_depth_estimator

            depth_estimator = load_depth_estimator(settings.depth_model, settings.device)
        self.depth_estimator = depth_estimator

    def repaint(
        self,
        frame: NDArray[np.uint8],
        depth: NDArray[np.floating] | None = None,
        env: Environment | None = None,
    ) -> NDArray[np.uint8]:
        """Run the diffusion on one RGB uint8 frame [H, W, 3]; same size out, no checks."""
        (torch,) = import_extra("torch")
        frame = check_frame(frame)
        height, width = frame.shape[:2]
        size = work_size(height, width, self.settings.work_long_side)
        init = Image.fromarray(frame).resize((size[1], size[0]), Image.Resampling.LANCZOS)
        prompts = build_prompts(env)
        kwargs: dict[str, Any] = {
            "prompt": prompts.prompt,
            "negative_prompt": prompts.negative,
            "image": init,
            "strength": self.settings.effective_strength(),
            "num_inference_steps": self.settings.steps,
            "guidance_scale": self.settings.guidance,
            "output_type": "np",
            # Explicit micro-conditioning sizes (SDXL's "original" and "target" size); also
            # avoids a diffusers ControlNet-img2img bug when they default to a torch.Size.
            "original_size": size,
            "target_size": size,
        }
        if self.settings.seed is not None:
            kwargs["generator"] = torch.Generator(device="cpu").manual_seed(self.settings.seed)
        if self.settings.controlnet is not None:
            if depth is None:
                raise EnhanceInputError(
                    "the depth ControlNet needs the renderer's depth map with every frame; "
                    "pass depth=[H, W] metres or drop --controlnet"
                )
            kwargs["control_image"] = depth_to_control(depth, size)
            kwargs["controlnet_conditioning_scale"] = self.settings.controlnet_scale
        with torch.inference_mode():
            result = self.pipeline(**kwargs).images[0]
        out = (np.clip(np.asarray(result, dtype=np.float32), 0.0, 1.0) * 255.0).round()
        image = Image.fromarray(out.astype(np.uint8))
        return np.asarray(image.resize((width, height), Image.Resampling.LANCZOS), dtype=np.uint8)

    def enhance(
        self,
        frame: NDArray[np.uint8],
        depth: NDArray[np.floating] | None = None,
        env: Environment | None = None,
    ) -> EnhancedFrame:
        """Repaint a frame and keep it only if its structure score passes.

        frame: RGB uint8 [H, W, 3]; depth: the renderer's depth [H, W] in metres (needed
        with a ControlNet); env: the Scene's environment the prompt is built from.
        """
        start = time.perf_counter()
        frame = check_frame(frame)
        candidate = self.repaint(frame, depth, env)
        score = structure_score(frame, candidate, self.settings, self.depth_estimator, baseline_depth=depth)
        shown = candidate if score.accepted else frame
        return EnhancedFrame(shown, candidate, score, time.perf_counter() - start)
