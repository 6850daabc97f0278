"""Feature extractors loaded from local weights, and the realism report built on them."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import draw_street, one_torch_thread
from drivetwin.worlds.enhance import (
    EnhanceInputError,
    EnhanceSettings,
    EnhanceWeightsMissing,
    FrameEnhancer,
    RealismModels,
    fid,
    realism_report,
    realism_report_for_folders,
)
from drivetwin.worlds.enhance.extractors import (
    ai_label_index,
    load_ai_detector,
    load_clip_image_encoder,
    load_depth_estimator,
    load_inception,
)
from PIL import Image

pytest.importorskip("transformers", reason="the enhance extra (transformers) is not installed")


@pytest.fixture(scope="module")
def tiny_models(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """Randomly initialised stand-ins saved in the formats users supply."""
    import torch
    from transformers import (
        CLIPImageProcessor,
        CLIPVisionConfig,
        CLIPVisionModelWithProjection,
        DepthAnythingConfig,
        DepthAnythingForDepthEstimation,
        Dinov2Config,
        DPTImageProcessor,
        ViTConfig,
        ViTForImageClassification,
        ViTImageProcessor,
    )

    root = tmp_path_factory.mktemp("extractors")

    class TinyInception(torch.nn.Module):
        """Same TorchScript interface as the FID Inception file, 16 features."""

        def __init__(self) -> None:
            super().__init__()
            self.conv = torch.nn.Conv2d(3, 16, 5, stride=4)

        def forward(self, x: torch.Tensor, return_features: bool = False) -> torch.Tensor:
            features = torch.relu(self.conv(x / 255.0)).mean(dim=(2, 3))
            return features if return_features else features.softmax(-1)

    with one_torch_thread():
        torch.manual_seed(0)
        torch.jit.script(TinyInception()).save(str(root / "inception.pt"))
        clip = CLIPVisionModelWithProjection(
            CLIPVisionConfig(
                hidden_size=32,
                image_size=32,
                patch_size=8,
                projection_dim=16,
                intermediate_size=37,
                num_attention_heads=4,
                num_hidden_layers=2,
            )
        )
        clip.save_pretrained(root / "clip")
        CLIPImageProcessor(
            size={"shortest_edge": 32}, crop_size={"height": 32, "width": 32}
        ).save_pretrained(root / "clip")
        labels = {0: "human", 1: "artificial"}
        detector = ViTForImageClassification(
            ViTConfig(
                image_size=32,
                patch_size=8,
                hidden_size=32,
                num_hidden_layers=2,
                num_attention_heads=4,
                intermediate_size=37,
                id2label=labels,
                label2id={v: k for k, v in labels.items()},
            )
        )
        detector.save_pretrained(root / "detector")
        ViTImageProcessor(size={"height": 32, "width": 32}).save_pretrained(root / "detector")
        backbone = Dinov2Config(
            image_size=32,
            patch_size=8,
            hidden_size=16,
            num_hidden_layers=4,
            num_attention_heads=2,
            intermediate_size=32,
            out_features=["stage1", "stage2", "stage3", "stage4"],
            reshape_hidden_states=False,
        )
        depth = DepthAnythingForDepthEstimation(
            DepthAnythingConfig(
                backbone_config=backbone,
                reassemble_hidden_size=16,
                patch_size=8,
                neck_hidden_sizes=[8, 16, 16, 16],
                fusion_hidden_size=16,
                head_hidden_size=8,
            )
        )
        depth.save_pretrained(root / "depth")
        DPTImageProcessor(
            size={"height": 32, "width": 32}, keep_aspect_ratio=False, ensure_multiple_of=8
        ).save_pretrained(root / "depth")
    return {
        "inception": root / "inception.pt",
        "clip": root / "clip",
        "detector": root / "detector",
        "depth": root / "depth",
    }


def frames(count: int, offset: int = 0) -> list[np.ndarray]:
    return [draw_street(car_x=20 + 5 * i, seed=i + offset) for i in range(count)]


def test_inception_features_come_from_the_torchscript_file(tiny_models: dict[str, Path]) -> None:
    extract = load_inception(tiny_models["inception"], device="cpu")
    feats = extract(frames(3))
    assert feats.shape == (3, 16)
    np.testing.assert_allclose(extract(frames(3)), feats)
    assert fid(np.concatenate([feats] * 4), np.concatenate([feats] * 4)) == pytest.approx(
        0.0, abs=1e-6
    )


def test_clip_embeddings_are_unit_vectors(tiny_models: dict[str, Path]) -> None:
    emb = load_clip_image_encoder(tiny_models["clip"], device="cpu")(frames(3))
    assert emb.shape == (3, 16)
    np.testing.assert_allclose(np.linalg.norm(emb, axis=1), 1.0, rtol=1e-6)


def test_the_ai_detector_gives_the_probability_of_its_artificial_label(
    tiny_models: dict[str, Path],
) -> None:
    ai = load_ai_detector(tiny_models["detector"], device="cpu")(frames(3))
    human = load_ai_detector(tiny_models["detector"], device="cpu", label="human")(frames(3))
    assert ai.shape == (3,) and np.all((ai >= 0) & (ai <= 1))
    np.testing.assert_allclose(ai + human, 1.0, rtol=1e-6)


@pytest.mark.parametrize(
    ("labels", "label", "index"),
    [
        ({0: "real", 1: "fake"}, None, 1),
        ({0: "artificial", 1: "human"}, None, 0),
        ({0: "REAL", 1: "AI"}, None, 1),
        ({0: "cat", 1: "dog"}, "dog", 1),
    ],
)
def test_the_ai_label_is_found_by_name(
    labels: dict[int, str], label: str | None, index: int
) -> None:
    assert ai_label_index(labels, label) == index


def test_a_detector_without_a_recognisable_ai_label_asks_for_one() -> None:
    with pytest.raises(EnhanceInputError, match="name it with the label argument"):
        ai_label_index({0: "cat", 1: "dog"})


def test_the_realism_report_computes_every_metric(tiny_models: dict[str, Path]) -> None:
    models = RealismModels(
        inception=str(tiny_models["inception"]),
        clip=str(tiny_models["clip"]),
        ai_detector=str(tiny_models["detector"]),
        device="cpu",
    )
    report = realism_report(frames(6), frames(6, offset=50), models)
    values = [report.fid, report.kid_mean, report.kid_std, report.cmmd, report.ai_probability]
    assert all(v is not None and np.isfinite(v) for v in values)
    assert report.real_images == report.generated_images == 6


def test_a_metric_without_a_model_is_skipped(tmp_path: Path, tiny_models: dict[str, Path]) -> None:
    for name, group in (("real", 0), ("generated", 50)):
        (tmp_path / name).mkdir()
        for i, frame in enumerate(frames(3, offset=group)):
            Image.fromarray(frame).save(tmp_path / name / f"{i}.png")
    models = RealismModels(clip=str(tiny_models["clip"]), device="cpu")
    report = realism_report_for_folders(tmp_path / "real", tmp_path / "generated", models)
    assert report.cmmd is not None and report.fid is None and report.ai_probability is None


@pytest.mark.parametrize(
    ("loader", "hint"),
    [
        (load_inception, "inception-2015-12-05.pt"),
        (load_clip_image_encoder, "hf download openai/clip-vit-large-patch14-336"),
        (load_ai_detector, "hf download"),
        (load_depth_estimator, "hf download depth-anything"),
    ],
)
def test_missing_weights_are_one_line_naming_how_to_get_them(
    tmp_path: Path, loader: object, hint: str
) -> None:
    with pytest.raises(EnhanceWeightsMissing) as err:
        loader(tmp_path / "absent", "cpu")  # type: ignore[operator]
    assert hint in str(err.value) and "\n" not in str(err.value)


def test_a_file_that_is_not_torchscript_is_refused(tmp_path: Path) -> None:
    (tmp_path / "inception.pt").write_bytes(b"not a model")
    with pytest.raises(EnhanceWeightsMissing, match="not a TorchScript"):
        load_inception(tmp_path / "inception.pt", "cpu")


def test_a_depth_model_adds_depth_disagreement_to_every_score(
    tiny_models: dict[str, Path], tiny_sdxl: dict[str, Path]
) -> None:
    estimate = load_depth_estimator(tiny_models["depth"], "cpu")
    assert estimate(draw_street()).ndim == 2
    settings = EnhanceSettings(
        model=str(tiny_sdxl["model"]),
        depth_model=str(tiny_models["depth"]),
        work_long_side=64,
        steps=4,
        strength=0.5,
        device="cpu",
    )
    result = FrameEnhancer(settings).enhance(draw_street())
    assert result.score.depth_disagreement is not None
