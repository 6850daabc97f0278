"""Realism of a set of frames against real photographs: FID, KID, CMMD, AI-detector score."""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
from drivetwin.worlds.enhance.extractors import (
    Frames,
    load_ai_detector,
    load_clip_image_encoder,
    load_inception,
)
from drivetwin.worlds.enhance.metrics import cmmd, fid, kid
from drivetwin.worlds.enhance.settings import EnhanceInputError
from numpy.typing import NDArray
from PIL import Image
from pydantic import BaseModel, ConfigDict

IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg")


class RealismModels(BaseModel):
    """Local weights of the feature extractors; a metric whose model is None is skipped."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    inception: str | None = None
    clip: str | None = None
    ai_detector: str | None = None
    ai_label: str | None = None
    device: str = "auto"


@dataclass(frozen=True)
class RealismReport:
    """Realism figures of generated frames against real ones (None = model not given)."""

    real_images: int
    generated_images: int
    fid: float | None
    kid_mean: float | None
    kid_std: float | None
    cmmd: float | None
    ai_probability: float | None
    ai_probability_real: float | None

    def to_json(self) -> str:
        """The report as indented JSON."""
        return json.dumps(asdict(self), indent=2)


def load_frames(folder: str | Path) -> list[NDArray[np.uint8]]:
    """Every PNG/JPEG image in a folder (sorted by name) as RGB uint8 [H, W, 3]."""
    path = Path(folder)
    if not path.is_dir():
        raise EnhanceInputError(f"'{path}' is not a folder of images")
    files = sorted(p for p in path.iterdir() if p.suffix.lower() in IMAGE_SUFFIXES)
    if not files:
        raise EnhanceInputError(f"'{path}' holds no {', '.join(IMAGE_SUFFIXES)} images")
    frames = []
    for file in files:
        with Image.open(file) as im:
            frames.append(np.asarray(im.convert("RGB"), dtype=np.uint8))
    return frames


def realism_report(real: Frames, generated: Frames, models: RealismModels) -> RealismReport:
    """Compute the realism metrics of `generated` frames against `real` ones.

    FID and KID use Inception pool features, CMMD unit CLIP embeddings, and the AI-detector
    figure is the mean probability that a frame is AI-generated.
    """
    if len(real) < 2 or len(generated) < 2:
        raise EnhanceInputError(
            f"realism metrics need at least 2 real and 2 generated images; "
            f"got {len(real)} and {len(generated)}"
        )
    fid_value = kid_mean = kid_std = cmmd_value = ai_gen = ai_real = None
    if models.inception is not None:
        inception = load_inception(models.inception, models.device)
        real_f, gen_f = inception(real), inception(generated)
        fid_value = fid(real_f, gen_f)
        kid_mean, kid_std = kid(real_f, gen_f)
    if models.clip is not None:
        clip = load_clip_image_encoder(models.clip, models.device)
        cmmd_value = cmmd(clip(real), clip(generated))
    if models.ai_detector is not None:
        detector = load_ai_detector(models.ai_detector, models.device, models.ai_label)
        ai_gen = float(detector(generated).mean())
        ai_real = float(detector(real).mean())
    return RealismReport(
        real_images=len(real),
        generated_images=len(generated),
        fid=fid_value,
        kid_mean=kid_mean,
        kid_std=kid_std,
        cmmd=cmmd_value,
        ai_probability=ai_gen,
        ai_probability_real=ai_real,
    )


def realism_report_for_folders(
    real_dir: str | Path, generated_dir: str | Path, models: RealismModels
) -> RealismReport:
    """realism_report on two folders of images."""
    return realism_report(load_frames(real_dir), load_frames(generated_dir), models)
