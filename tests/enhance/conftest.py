"""Fixtures for the enhancer tests: synthetic street frames and a tiny SDXL saved to disk."""

from __future__ import annotations

import contextlib
import json
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np
import pytest

# Frames are 96 x 128: big enough for 4 x 4 structure tiles, small enough to stay fast.
FRAME_H, FRAME_W = 96, 128
CAR_X = 60
CAR_W = 26


def draw_street(car_x: int = CAR_X, seed: int = 0) -> np.ndarray:
    """A synthetic rendered frame: sky, two buildings, road with lane marks, a red car."""
    rng = np.random.default_rng(seed)
    h, w = FRAME_H, FRAME_W
    img = np.zeros((h, w, 3), np.float32)
    img[: h // 2] = np.linspace([120, 160, 220], [180, 200, 230], h // 2)[:, None, :]
    img[h // 2 :] = [90, 90, 95]
    img[h // 2 + 20 : h // 2 + 22, ::8] = 240
    img[20 : h // 2, 5:35] = [150, 120, 100]
    img[30 : h // 2, 90:120] = [120, 130, 140]
    img[h // 2 + 5 : h // 2 + 25, car_x : car_x + CAR_W] = [200, 30, 30]
    img += rng.normal(0.0, 3.0, img.shape)
    return np.clip(img, 0, 255).astype(np.uint8)


def draw_depth(car_x: int = CAR_X) -> np.ndarray:
    """Renderer-style depth in metres for draw_street: ground plane, a near car, sky = inf."""
    h, w = FRAME_H, FRAME_W
    depth = np.full((h, w), np.inf, dtype=np.float32)
    rows = np.arange(h // 2, h, dtype=np.float32)[:, None]
    depth[h // 2 :] = 60.0 / (rows - h // 2 + 1)
    depth[20 : h // 2, 5:35] = 30.0
    depth[30 : h // 2, 90:120] = 25.0
    depth[h // 2 + 5 : h // 2 + 25, car_x : car_x + CAR_W] = 8.0
    return depth


@contextlib.contextmanager
def one_torch_thread() -> Iterator[None]:
    """Run torch on one thread: tiny models gain nothing from more, and on a shared 2-core
    machine spinning OpenMP workers make them 20x slower."""
    try:
        import torch
    except ImportError:
        yield
        return
    before = torch.get_num_threads()
    torch.set_num_threads(1)
    try:
        yield
    finally:
        torch.set_num_threads(before)


@pytest.fixture(autouse=True)
def _single_torch_thread() -> Iterator[None]:
    with one_torch_thread():
        yield


@pytest.fixture
def street() -> Callable[..., np.ndarray]:
    return draw_street


@pytest.fixture
def street_depth() -> Callable[..., np.ndarray]:
    return draw_depth


def _bytes_to_unicode() -> list[str]:
    """GPT-2/CLIP byte-level alphabet: every byte has a printable stand-in character."""
    printable = (
        list(range(ord("!"), ord("~") + 1))
        + list(range(ord("¡"), ord("¬") + 1))
        + list(range(ord("®"), ord("ÿ") + 1))
    )
    chars = printable[:]
    extra = 0
    for b in range(256):
        if b not in printable:
            chars.append(256 + extra)
            extra += 1
    return [chr(c) for c in chars]


def write_tiny_clip_tokenizer(folder: Path) -> Path:
    """A CLIP BPE tokenizer with the byte alphabet and no merges (514 tokens)."""
    folder.mkdir(parents=True, exist_ok=True)
    alphabet = _bytes_to_unicode()
    vocab: dict[str, int] = {}
    for ch in alphabet:
        vocab[ch] = len(vocab)
    for ch in alphabet:
        vocab[ch + "</w>"] = len(vocab)
    vocab["<|startoftext|>"] = len(vocab)
    vocab["<|endoftext|>"] = len(vocab)
    (folder / "vocab.json").write_text(json.dumps(vocab))
    (folder / "merges.txt").write_text("#version: 0.2\n")
    return folder


@pytest.fixture(scope="session")
def tiny_sdxl(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """A randomly initialised tiny SDXL img2img pipeline and depth ControlNet, saved locally.

    Sizes follow diffusers' own SDXL img2img fast tests; the tokenizers are built from a
    vocabulary written here (no download).
    """
    pytest.importorskip("diffusers", reason="the enhance extra (diffusers) is not installed")
    with one_torch_thread():
        return _build_tiny_sdxl(tmp_path_factory.mktemp("tiny-sdxl"))


def _build_tiny_sdxl(root: Path) -> dict[str, Path]:
    import torch
    from diffusers import (
        AutoencoderKL,
        ControlNetModel,
        EulerDiscreteScheduler,
        StableDiffusionXLImg2ImgPipeline,
        UNet2DConditionModel,
    )
    from transformers import (
        CLIPTextConfig,
        CLIPTextModel,
        CLIPTextModelWithProjection,
        CLIPTokenizer,
    )

    tok_dir = write_tiny_clip_tokenizer(root / "tokenizer-src")
    tokenizer = CLIPTokenizer(
        str(tok_dir / "vocab.json"), str(tok_dir / "merges.txt"), model_max_length=77
    )
    torch.manual_seed(0)
    unet = UNet2DConditionModel(
        block_out_channels=(32, 64),
        layers_per_block=2,
        sample_size=32,
        in_channels=4,
        out_channels=4,
        down_block_types=("DownBlock2D", "CrossAttnDownBlock2D"),
        up_block_types=("CrossAttnUpBlock2D", "UpBlock2D"),
        attention_head_dim=(2, 4),
        use_linear_projection=True,
        addition_embed_type="text_time",
        addition_time_embed_dim=8,
        transformer_layers_per_block=(1, 2),
        projection_class_embeddings_input_dim=72,  # 5 time ids x 8 + 32 pooled text
        cross_attention_dim=64,  # the two 32-wide text encoders, concatenated
    )
    scheduler = EulerDiscreteScheduler(
        beta_start=0.00085,
        beta_end=0.012,
        steps_offset=1,
        beta_schedule="scaled_linear",
        timestep_spacing="leading",
    )
    torch.manual_seed(0)
    vae = AutoencoderKL(
        block_out_channels=[32, 64],
        in_channels=3,
        out_channels=3,
        down_block_types=["DownEncoderBlock2D", "DownEncoderBlock2D"],
        up_block_types=["UpDecoderBlock2D", "UpDecoderBlock2D"],
        latent_channels=4,
        sample_size=128,
    )
    text_config = CLIPTextConfig(
        bos_token_id=tokenizer.bos_token_id,
        eos_token_id=tokenizer.eos_token_id,
        hidden_size=32,
        intermediate_size=37,
        layer_norm_eps=1e-05,
        num_attention_heads=4,
        num_hidden_layers=5,
        pad_token_id=1,
        vocab_size=1000,
        hidden_act="gelu",
        projection_dim=32,
    )
    torch.manual_seed(0)
    pipe = StableDiffusionXLImg2ImgPipeline(
        vae=vae,
        text_encoder=CLIPTextModel(text_config),
        text_encoder_2=CLIPTextModelWithProjection(text_config),
        tokenizer=tokenizer,
        tokenizer_2=tokenizer,
        unet=unet,
        scheduler=scheduler,
        requires_aesthetics_score=True,
    )
    pipe.save_pretrained(root / "sdxl")
    # One 2x downsample in the conditioning embedding, matching the tiny VAE's 2x latents.
    controlnet = ControlNetModel.from_unet(unet, conditioning_embedding_out_channels=(16, 32))
    # from_unet zero-initialises the "zero convolutions" (training starts from a no-op); a
    # trained ControlNet's are not zero, so give them random weights to make the depth count.
    zero_convs = [
        controlnet.controlnet_cond_embedding.conv_out,
        controlnet.controlnet_mid_block,
        *controlnet.controlnet_down_blocks,
    ]
    torch.manual_seed(1)
    for conv in zero_convs:
        torch.nn.init.normal_(conv.weight, std=0.1)
    controlnet.save_pretrained(root / "controlnet")
    return {"model": root / "sdxl", "controlnet": root / "controlnet"}
