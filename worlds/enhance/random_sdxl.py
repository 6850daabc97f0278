"""An SDXL base 1.0 folder with the published architecture and random weights, for speed benchmarks.

The enhancer's time per frame depends on the architecture, the work size and the steps run,
not on the weight values, and the real weights (~7 GB) cannot be fetched on every machine that
must measure it. `write_random_sdxl` writes a folder that `FrameEnhancer` loads exactly as it
loads stabilityai/stable-diffusion-xl-base-1.0: the same model_index (StableDiffusionXLPipeline),
the same component configs (UNet 2.567 B parameters, VAE, CLIP ViT-L and OpenCLIP bigG text
encoders, Euler scheduler), fp16 variant weight files, and CLIP tokenizers built from CLIP's own
BPE merges. Its weights are random: its images are meaningless and the structure check's
verdicts on them mean nothing; only its timings do. The folder says so in RANDOM_WEIGHTS.txt.

Run (CLIP's merges ship as bpe_simple_vocab_16e6.txt.gz inside the open_clip_torch package)::

    python -m drivetwin.worlds.enhance.random_sdxl models/sdxl-random \\
        --clip-bpe bpe_simple_vocab_16e6.txt.gz --device cuda
    python -m drivetwin.worlds.enhance.bench --model models/sdxl-random
"""

from __future__ import annotations

import argparse
import gzip
import json
import tempfile
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from drivetwin.worlds.enhance.pipeline import import_extra
from drivetwin.worlds.enhance.settings import EnhanceInputError

__all__ = [
    "CLIP_MERGES",
    "SDXL_BASE",
    "SdxlArchitecture",
    "read_clip_merges",
    "write_clip_tokenizer",
    "write_random_sdxl",
]

# CLIP's vocabulary is 49,408 tokens: 256 byte symbols, the same 256 ending a word ("</w>"),
# the first 48,894 merges of its BPE file, and the two special tokens.
CLIP_MERGES = 49_408 - 2 * 256 - 2
CLIP_MAX_LENGTH = 77  # CLIP's context length, which SDXL pads every prompt to
START, END = "<|startoftext|>", "<|endoftext|>"
NOTE_FILE = "RANDOM_WEIGHTS.txt"

# The configs below are those of stabilityai/stable-diffusion-xl-base-1.0 (unet/, vae/,
# text_encoder/, text_encoder_2/, scheduler/ config.json), keys the constructors take.
_SDXL_UNET: dict[str, Any] = {
    "act_fn": "silu",
    "addition_embed_type": "text_time",
    "addition_embed_type_num_heads": 64,
    "addition_time_embed_dim": 256,
    "attention_head_dim": [5, 10, 20],
    "block_out_channels": [320, 640, 1280],
    "center_input_sample": False,
    "cross_attention_dim": 2048,
    "down_block_types": ["DownBlock2D", "CrossAttnDownBlock2D", "CrossAttnDownBlock2D"],
    "downsample_padding": 1,
    "dual_cross_attention": False,
    "flip_sin_to_cos": True,
    "freq_shift": 0,
    "in_channels": 4,
    "layers_per_block": 2,
    "mid_block_scale_factor": 1,
    "mid_block_type": "UNetMidBlock2DCrossAttn",
    "norm_eps": 1e-05,
    "norm_num_groups": 32,
    "only_cross_attention": False,
    "out_channels": 4,
    "projection_class_embeddings_input_dim": 2816,
    "resnet_out_scale_factor": 1.0,
    "resnet_skip_time_act": False,
    "resnet_time_scale_shift": "default",
    "sample_size": 128,
    "time_embedding_type": "positional",
    "transformer_layers_per_block": [1, 2, 10],
    "up_block_types": ["CrossAttnUpBlock2D", "CrossAttnUpBlock2D", "UpBlock2D"],
    "use_linear_projection": True,
}
_SDXL_VAE: dict[str, Any] = {
    "act_fn": "silu",
    "block_out_channels": [128, 256, 512, 512],
    "down_block_types": ["DownEncoderBlock2D"] * 4,
    "force_upcast": True,
    "in_channels": 3,
    "latent_channels": 4,
    "layers_per_block": 2,
    "norm_num_groups": 32,
    "out_channels": 3,
    "sample_size": 1024,
    "scaling_factor": 0.13025,
    "up_block_types": ["UpDecoderBlock2D"] * 4,
}
_SDXL_TEXT_ENCODER: dict[str, Any] = {  # CLIP ViT-L/14's text tower
    "attention_dropout": 0.0,
    "bos_token_id": 0,
    "dropout": 0.0,
    "eos_token_id": 2,
    "hidden_act": "quick_gelu",
    "hidden_size": 768,
    "initializer_factor": 1.0,
    "initializer_range": 0.02,
    "intermediate_size": 3072,
    "layer_norm_eps": 1e-05,
    "max_position_embeddings": CLIP_MAX_LENGTH,
    "num_attention_heads": 12,
    "num_hidden_layers": 12,
    "pad_token_id": 1,
    "projection_dim": 768,
    "vocab_size": 49_408,
}
_SDXL_TEXT_ENCODER_2: dict[str, Any] = {  # OpenCLIP ViT-bigG/14's text tower, with projection
    **_SDXL_TEXT_ENCODER,
    "hidden_act": "gelu",
    "hidden_size": 1280,
    "intermediate_size": 5120,
    "num_attention_heads": 20,
    "num_hidden_layers": 32,
    "projection_dim": 1280,
}
_SDXL_SCHEDULER: dict[str, Any] = {
    "beta_end": 0.012,
    "beta_schedule": "scaled_linear",
    "beta_start": 0.00085,
    "interpolation_type": "linear",
    "num_train_timesteps": 1000,
    "prediction_type": "epsilon",
    "steps_offset": 1,
    "timestep_spacing": "leading",
    "use_karras_sigmas": False,
}


@dataclass(frozen=True)
class SdxlArchitecture:
    """Constructor configs of the SDXL pipeline's components (diffusers / transformers keys)."""

    unet: Mapping[str, Any] = field(default_factory=lambda: dict(_SDXL_UNET))
    vae: Mapping[str, Any] = field(default_factory=lambda: dict(_SDXL_VAE))
    text_encoder: Mapping[str, Any] = field(default_factory=lambda: dict(_SDXL_TEXT_ENCODER))
    text_encoder_2: Mapping[str, Any] = field(default_factory=lambda: dict(_SDXL_TEXT_ENCODER_2))
    scheduler: Mapping[str, Any] = field(default_factory=lambda: dict(_SDXL_SCHEDULER))


SDXL_BASE = SdxlArchitecture()


def _bytes_to_unicode() -> list[str]:
    """CLIP's byte alphabet, in CLIP's order: printable bytes stand for themselves."""
    printable = [*range(ord("!"), ord("~") + 1), *range(ord("¡"), ord("¬") + 1), *range(ord("®"), ord("ÿ") + 1)]
    others = [b for b in range(256) if b not in printable]
    return [chr(c) for c in printable] + [chr(256 + i) for i in range(len(others))]


def read_clip_merges(path: Path, count: int = CLIP_MERGES) -> list[tuple[str, str]]:
    """The first ``count`` merges of a CLIP BPE file (gzipped or plain; first line a header)."""
    raw = path.read_bytes()
    text = gzip.decompress(raw).decode("utf-8") if raw[:2] == b"\x1f\x8b" else raw.decode("utf-8")
    lines = text.split("\n")[1 : count + 1]
    merges = [tuple(line.split()) for line in lines]
    if len(merges) < count or any(len(m) != 2 for m in merges):
        raise EnhanceInputError(
            f"{path} is not a CLIP BPE merges file: need a header line then {count} lines "
            f"'a b'; found {len(merges)} lines"
        )
    return [(a, b) for a, b in merges]


def write_clip_tokenizer(folder: Path, merges: Sequence[tuple[str, str]], pad_token: str) -> Path:
    """Write CLIPTokenizer files (vocab.json, merges.txt, configs) built from BPE ``merges``.

    The vocabulary is built as CLIP builds it: byte symbols, byte symbols ending a word, one
    token per merge, then the start and end tokens. SDXL's first tokenizer pads with the end
    token, its second with "!".
    """
    folder.mkdir(parents=True, exist_ok=True)
    alphabet = _bytes_to_unicode()
    tokens = [*alphabet, *(c + "</w>" for c in alphabet), *("".join(m) for m in merges), START, END]
    (folder / "vocab.json").write_text(json.dumps({t: i for i, t in enumerate(tokens)}, ensure_ascii=False))
    (folder / "merges.txt").write_text("#version: 0.2\n" + "".join(f"{a} {b}\n" for a, b in merges))
    specials = {"bos_token": START, "eos_token": END, "unk_token": END, "pad_token": pad_token}
    (folder / "special_tokens_map.json").write_text(json.dumps(specials))
    config = {**specials, "tokenizer_class": "CLIPTokenizer", "model_max_length": CLIP_MAX_LENGTH,
              "do_lower_case": True, "add_prefix_space": False, "errors": "replace"}  # fmt: skip
    (folder / "tokenizer_config.json").write_text(json.dumps(config))
    return folder


def write_random_sdxl(
    folder: Path,
    merges: Sequence[tuple[str, str]],
    *,
    architecture: SdxlArchitecture = SDXL_BASE,
    device: str = "cpu",
    seed: int = 0,
) -> dict[str, int]:
    """Write an SDXL folder of ``architecture`` with random fp16 weights; parameter counts back.

    The components are made on ``device`` (a GPU makes the 3.5 B random parameters in seconds)
    and saved as the fp16 variant, as the published download is.
    """
    torch, diffusers, transformers = import_extra("torch", "diffusers", "transformers")
    if folder.exists() and any(folder.iterdir()):
        raise EnhanceInputError(f"{folder} is not empty; give a new folder for the random SDXL")
    with tempfile.TemporaryDirectory() as tmp:
        tokenizer = transformers.CLIPTokenizer.from_pretrained(write_clip_tokenizer(Path(tmp) / "1", merges, END))
        tokenizer_2 = transformers.CLIPTokenizer.from_pretrained(write_clip_tokenizer(Path(tmp) / "2", merges, "!"))
    torch.manual_seed(seed)
    with torch.device(device):
        unet = diffusers.UNet2DConditionModel(**architecture.unet)
        vae = diffusers.AutoencoderKL(**architecture.vae)
        text_encoder = transformers.CLIPTextModel(transformers.CLIPTextConfig(**architecture.text_encoder))
        text_encoder_2 = transformers.CLIPTextModelWithProjection(
            transformers.CLIPTextConfig(**architecture.text_encoder_2)
        )
    parts = {"unet": unet, "vae": vae, "text_encoder": text_encoder, "text_encoder_2": text_encoder_2}
    counts = {name: sum(p.numel() for p in part.parameters()) for name, part in parts.items()}
    for part in parts.values():
        part.to(torch.float16)
    pipe = diffusers.StableDiffusionXLPipeline(
        **parts,
        tokenizer=tokenizer,
        tokenizer_2=tokenizer_2,
        scheduler=diffusers.EulerDiscreteScheduler(**architecture.scheduler),
        force_zeros_for_empty_prompt=True,
        add_watermarker=False,
    )
    pipe.save_pretrained(folder, variant="fp16")
    (folder / NOTE_FILE).write_text(
        "Random weights in SDXL base 1.0's architecture, written by drivetwin.worlds.enhance.random_sdxl "
        "for speed benchmarks. Images made with it are meaningless.\n"
    )
    return counts


def main(argv: Sequence[str] | None = None) -> int:
    """Command line: write the folder and print the parameter counts and time taken as JSON."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    parser.add_argument("out", type=Path, help="new folder to write")
    parser.add_argument("--clip-bpe", type=Path, required=True, help="CLIP's bpe_simple_vocab_16e6.txt.gz")
    parser.add_argument("--device", default="cpu", help="where the random weights are made: cpu, cuda")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args(argv)
    start = time.perf_counter()
    counts = write_random_sdxl(args.out, read_clip_merges(args.clip_bpe), device=args.device, seed=args.seed)
    print(json.dumps({"folder": str(args.out), "parameters": counts,
                      "seconds": round(time.perf_counter() - start, 1)}, indent=2))  # fmt: skip
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
