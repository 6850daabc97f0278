"""The architecture-only SDXL folder the enhancer's GPU benchmark runs on (random weights)."""

from __future__ import annotations

import gzip
import json
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from drivetwin.worlds.enhance.random_sdxl import (
    CLIP_MERGES,
    END,
    NOTE_FILE,
    SDXL_BASE,
    START,
    SdxlArchitecture,
    read_clip_merges,
    write_clip_tokenizer,
    write_random_sdxl,
)
from drivetwin.worlds.enhance.settings import EnhanceInputError, EnhanceSettings

# Merges that build "rain</w>" from its bytes: r+a, i+n</w>, ra+in</w>.
RAIN_MERGES = [("r", "a"), ("i", "n</w>"), ("ra", "in</w>")]
BYTE_SYMBOLS = 2 * 256  # each byte's symbol, alone and ending a word

# Published parameter counts of SDXL base 1.0's components.
SDXL_PARAMETERS = {
    "unet": 2_567_463_684,
    "vae": 83_653_863,
    "text_encoder": 123_060_480,
    "text_encoder_2": 694_659_840,
}

# The tiny SDXL of conftest.py's sizes (diffusers' own fast tests), same component types.
TINY = SdxlArchitecture(
    unet={
        "block_out_channels": (32, 64), "layers_per_block": 2, "sample_size": 32,
        "in_channels": 4, "out_channels": 4,
        "down_block_types": ("DownBlock2D", "CrossAttnDownBlock2D"),
        "up_block_types": ("CrossAttnUpBlock2D", "UpBlock2D"),
        "attention_head_dim": (2, 4), "use_linear_projection": True,
        "addition_embed_type": "text_time", "addition_time_embed_dim": 8,
        "transformer_layers_per_block": (1, 2),
        "projection_class_embeddings_input_dim": 80,  # 6 time ids x 8 + 32 pooled text
        "cross_attention_dim": 64,
    },
    vae={
        "block_out_channels": [32, 64], "in_channels": 3, "out_channels": 3, "latent_channels": 4,
        "down_block_types": ["DownEncoderBlock2D"] * 2, "up_block_types": ["UpDecoderBlock2D"] * 2,
    },
    text_encoder={"hidden_size": 32, "intermediate_size": 37, "num_attention_heads": 4,
                  "num_hidden_layers": 2, "vocab_size": 1000, "projection_dim": 32},
    text_encoder_2={"hidden_size": 32, "intermediate_size": 37, "num_attention_heads": 4,
                    "num_hidden_layers": 2, "vocab_size": 1000, "projection_dim": 32},
)  # fmt: skip


def test_sdxl_base_architecture_has_the_published_parameter_counts() -> None:
    torch = pytest.importorskip("torch")
    diffusers = pytest.importorskip("diffusers")
    transformers = pytest.importorskip("transformers")
    with torch.device("meta"):  # shapes only: no memory, no initialisation
        parts = {
            "unet": diffusers.UNet2DConditionModel(**SDXL_BASE.unet),
            "vae": diffusers.AutoencoderKL(**SDXL_BASE.vae),
            "text_encoder": transformers.CLIPTextModel(transformers.CLIPTextConfig(**SDXL_BASE.text_encoder)),
            "text_encoder_2": transformers.CLIPTextModelWithProjection(
                transformers.CLIPTextConfig(**SDXL_BASE.text_encoder_2)
            ),
        }
    assert {name: sum(p.numel() for p in part.parameters()) for name, part in parts.items()} == SDXL_PARAMETERS


def test_clip_tokenizer_built_from_merges_tokenizes_as_clip(tmp_path: Path) -> None:
    transformers = pytest.importorskip("transformers")
    folder = write_clip_tokenizer(tmp_path / "tok", RAIN_MERGES, pad_token="!")
    tokenizer = transformers.CLIPTokenizer.from_pretrained(folder)
    rain = BYTE_SYMBOLS + RAIN_MERGES.index(("ra", "in</w>"))
    start, end = BYTE_SYMBOLS + len(RAIN_MERGES), BYTE_SYMBOLS + len(RAIN_MERGES) + 1
    assert tokenizer("Rain").input_ids == [start, rain, end]
    assert tokenizer.convert_ids_to_tokens([start, end]) == [START, END]
    assert tokenizer.pad_token == "!" and tokenizer.model_max_length == 77


def test_read_clip_merges_takes_the_first_merges_after_the_header(tmp_path: Path) -> None:
    lines = ["bpe_simple_vocab_16e6.txt#version: 0.2", *(f"{a} {b}" for a, b in RAIN_MERGES), "x y"]
    path = tmp_path / "bpe.txt.gz"
    path.write_bytes(gzip.compress("\n".join(lines).encode()))
    assert read_clip_merges(path, count=3) == RAIN_MERGES
    assert CLIP_MERGES + BYTE_SYMBOLS + 2 == 49_408  # CLIP's vocabulary size


def test_read_clip_merges_rejects_a_file_that_is_not_a_merges_file(tmp_path: Path) -> None:
    path = tmp_path / "notes.txt"
    path.write_text("header\nthree words here\n")
    with pytest.raises(EnhanceInputError, match="not a CLIP BPE merges file"):
        read_clip_merges(path, count=1)


def test_random_sdxl_folder_loads_and_enhances_as_a_download_does(
    tmp_path: Path, street: Callable[..., np.ndarray], street_depth: Callable[..., np.ndarray]
) -> None:
    pytest.importorskip("diffusers")
    from drivetwin.worlds.enhance.pipeline import FrameEnhancer, _variant

    folder = tmp_path / "sdxl"
    counts = write_random_sdxl(folder, RAIN_MERGES, architecture=TINY)
    index = json.loads((folder / "model_index.json").read_text())
    assert index["_class_name"] == "StableDiffusionXLPipeline"
    assert _variant(str(folder)) == "fp16"  # only fp16 files, as the published download
    assert (folder / NOTE_FILE).read_text().startswith("Random weights")
    enhancer = FrameEnhancer(EnhanceSettings(model=str(folder), device="cpu", work_long_side=64, steps=4, strength=0.5))
    assert sum(p.numel() for p in enhancer.pipeline.unet.parameters()) == counts["unet"]
    frame = street()
    result = enhancer.enhance(frame, street_depth())
    assert result.candidate.shape == frame.shape and result.candidate.dtype == np.uint8


def test_write_random_sdxl_refuses_a_folder_that_is_not_empty(tmp_path: Path) -> None:
    (tmp_path / "keep.txt").write_text("user data")
    with pytest.raises(EnhanceInputError, match="not empty"):
        write_random_sdxl(tmp_path, RAIN_MERGES, architecture=TINY)
    assert [p.name for p in tmp_path.iterdir()] == ["keep.txt"]
