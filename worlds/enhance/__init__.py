"""Optional diffusion enhancer: SDXL img2img frames that keep the renderer's geometry.

Importing this package needs only the base install; torch, diffusers and transformers (the
extra `drivetwin[enhance]`) are imported when a pipeline or feature extractor is loaded.
"""

from drivetwin.worlds.enhance.metrics import cmmd, fid, kid
from drivetwin.worlds.enhance.offline import EnhanceReport, default_output_dir, enhance_folder
from drivetwin.worlds.enhance.online import OnlineEnhancer, OnlineFrame, OnlineStats
from drivetwin.worlds.enhance.pipeline import EnhancedFrame, FrameEnhancer, load_pipeline
from drivetwin.worlds.enhance.prompting import PromptPair, build_prompts
from drivetwin.worlds.enhance.realism import (
    RealismModels,
    RealismReport,
    realism_report,
    realism_report_for_folders,
)
from drivetwin.worlds.enhance.settings import (
    EnhanceExtraMissing,
    EnhanceInputError,
    EnhancerError,
    EnhanceSettings,
    EnhanceWeightsMissing,
)
from drivetwin.worlds.enhance.structure import StructureScore, structure_score

__all__ = [
    "EnhanceExtraMissing",
    "EnhanceInputError",
    "EnhanceReport",
    "EnhanceSettings",
    "EnhanceWeightsMissing",
    "EnhancedFrame",
    "EnhancerError",
    "FrameEnhancer",
    "OnlineEnhancer",
    "OnlineFrame",
    "OnlineStats",
    "PromptPair",
    "RealismModels",
    "RealismReport",
    "StructureScore",
    "build_prompts",
    "cmmd",
    "default_output_dir",
    "enhance_folder",
    "fid",
    "kid",
    "load_pipeline",
    "realism_report",
    "realism_report_for_folders",
    "structure_score",
]
