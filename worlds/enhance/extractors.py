"""Feature extractors for the realism metrics and the depth check, from local weights only.

Each loader takes a path the user supplies and returns a plain function from RGB uint8
frames [N][H, W, 3] to a numpy array. A missing path is one EnhanceWeightsMissing line that
names how to get the weights; nothing is downloaded.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numpy as np
from drivetwin.worlds.enhance.pipeline import import_extra, resolve_device
from drivetwin.worlds.enhance.settings import EnhanceInputError, EnhanceWeightsMissing
from numpy.typing import NDArray
from PIL import Image

Frames = Sequence[NDArray[np.uint8]]
FeatureExtractor = Callable[[Frames], NDArray[np.float64]]

# The FID Inception network (TensorFlow's 2015-12-05 graph, as TorchScript) takes 299 x 299.
INCEPTION_SIZE = 299
# Images go through the feature extractors this many at a time (bounded memory).
BATCH = 16
INCEPTION_HINT = (
    "curl -L -o models/inception-2015-12-05.pt https://nvlabs-fi-cdn.nvidia.com/"
    "stylegan2-ada-pytorch/pretrained/metrics/inception-2015-12-05.pt"
)
CLIP_HINT = "hf download openai/clip-vit-large-patch14-336 --local-dir models/clip-l14-336"
DETECTOR_HINT = "hf download umm-maybe/AI-image-detector --local-dir models/ai-detector"
DEPTH_HINT = (
    "hf download depth-anything/Depth-Anything-V2-Small-hf --local-dir models/depth-anything"
)
# Label names a binary real-vs-generated classifier uses for its "generated" class.
AI_LABEL_WORDS = ("artificial", "fake", "generated", "synthetic", "ai")


def _require(path: str | Path, what: str, hint: str) -> Path:
    p = Path(path).expanduser()
    if not p.exists():
        raise EnhanceWeightsMissing(
            f"{what} weights not found at '{p}' (supply a local path; nothing is downloaded); "
            f"get them with: {hint}"
        )
    return p


def _batches(frames: Frames) -> list[list[Image.Image]]:
    images = []
    for i, frame in enumerate(frames):
        arr = np.asarray(frame)
        if arr.ndim != 3 or arr.shape[2] != 3 or arr.dtype != np.uint8:
            raise EnhanceInputError(
                f"image {i} must be RGB uint8 [H, W, 3]; got {arr.shape} {arr.dtype}"
            )
        images.append(Image.fromarray(arr))
    return [images[i : i + BATCH] for i in range(0, len(images), BATCH)]


def load_inception(path: str | Path, device: str = "auto") -> FeatureExtractor:
    """FID/KID features [N, 2048] from the TorchScript Inception file at `path`.

    The file is the one StyleGAN and clean-fid use: forward(images, return_features=True),
    images float [N, 3, 299, 299] in 0..255. Images are resized with bicubic filtering
    first (clean-fid's "clean" resize).
    """
    file = _require(path, "FID Inception", INCEPTION_HINT)
    (torch,) = import_extra("torch")
    dev = resolve_device(device)
    try:
        with warnings.catch_warnings():
            # torch deprecates TorchScript, but the FID reference network ships only as one.
            warnings.filterwarnings("ignore", category=DeprecationWarning, message=".*jit.*")
            net = torch.jit.load(str(file), map_location=dev).eval()
    except (RuntimeError, ValueError) as exc:
        raise EnhanceWeightsMissing(
            f"'{file}' is not a TorchScript Inception file ({str(exc).splitlines()[0][:100]}); "
            f"get the right one with: {INCEPTION_HINT}"
        ) from exc

    def extract(frames: Frames) -> NDArray[np.float64]:
        out = []
        for batch in _batches(frames):
            arrs = [
                np.asarray(im.resize((INCEPTION_SIZE, INCEPTION_SIZE), Image.Resampling.BICUBIC))
                for im in batch
            ]
            x = torch.from_numpy(np.stack(arrs)).permute(0, 3, 1, 2).float().to(dev)
            with torch.inference_mode():
                feats = net(x, return_features=True)
            out.append(feats.reshape(len(batch), -1).double().cpu().numpy())
        return np.concatenate(out) if out else np.zeros((0, 0))

    return extract


def _hf_model(path: str | Path, what: str, hint: str, auto_class: str, device: str) -> Any:
    folder = _require(path, what, hint)
    transformers, torch = import_extra("transformers", "torch")
    dev = resolve_device(device)
    try:
        model = getattr(transformers, auto_class).from_pretrained(folder, local_files_only=True)
        processor = transformers.AutoImageProcessor.from_pretrained(folder, local_files_only=True)
    except (OSError, ValueError) as exc:
        first = str(exc).strip().splitlines()[0][:120] if str(exc).strip() else ""
        raise EnhanceWeightsMissing(
            f"{what} weights at '{folder}' could not be loaded ({first}); get them with: {hint}"
        ) from exc
    return model.eval().to(dev), processor, torch, dev


def load_clip_image_encoder(path: str | Path, device: str = "auto") -> FeatureExtractor:
    """CMMD embeddings [N, D]: a CLIP vision model with projection, L2-normalised."""
    model, processor, torch, dev = _hf_model(
        path, "CLIP image encoder", CLIP_HINT, "CLIPVisionModelWithProjection", device
    )

    def extract(frames: Frames) -> NDArray[np.float64]:
        out = []
        for batch in _batches(frames):
            inputs = processor(images=batch, return_tensors="pt").to(dev)
            with torch.inference_mode():
                emb = model(**inputs).image_embeds
            emb = emb / emb.norm(dim=-1, keepdim=True)
            out.append(emb.double().cpu().numpy())
        return np.concatenate(out) if out else np.zeros((0, 0))

    return extract


def ai_label_index(id2label: dict[int, str], label: str | None = None) -> int:
    """The class index of "AI-generated" in a classifier's labels (explicit or by name)."""
    names = {int(k): str(v) for k, v in id2label.items()}
    if label is not None:
        for idx, name in names.items():
            if name.lower() == label.lower():
                return idx
        raise EnhanceInputError(f"the detector has no label '{label}'; its labels: {names}")
    for idx, name in names.items():
        if any(word == name.lower() or word in name.lower().split() for word in AI_LABEL_WORDS):
            return idx
    raise EnhanceInputError(
        f"cannot tell which of the detector's labels {sorted(names.values())} means "
        f"AI-generated; name it with the label argument"
    )


def load_ai_detector(
    path: str | Path, device: str = "auto", label: str | None = None
) -> FeatureExtractor:
    """Per-image probability [N] that an image is AI-generated, from an image classifier."""
    model, processor, torch, dev = _hf_model(
        path, "AI-image detector", DETECTOR_HINT, "AutoModelForImageClassification", device
    )
    index = ai_label_index(model.config.id2label, label)

    def extract(frames: Frames) -> NDArray[np.float64]:
        out = []
        for batch in _batches(frames):
            inputs = processor(images=batch, return_tensors="pt").to(dev)
            with torch.inference_mode():
                probs = model(**inputs).logits.softmax(dim=-1)[:, index]
            out.append(probs.double().cpu().numpy())
        return np.concatenate(out) if out else np.zeros(0)

    return extract


def load_depth_estimator(
    path: str | Path, device: str = "auto"
) -> Callable[[NDArray[np.uint8]], NDArray[np.float32]]:
    """A monocular depth estimator: RGB uint8 [H, W, 3] -> relative depth [h, w]."""
    model, processor, torch, dev = _hf_model(
        path, "depth estimator", DEPTH_HINT, "AutoModelForDepthEstimation", device
    )

    def estimate(frame: NDArray[np.uint8]) -> NDArray[np.float32]:
        (batch,) = _batches([frame])
        inputs = processor(images=batch, return_tensors="pt").to(dev)
        with torch.inference_mode():
            depth = model(**inputs).predicted_depth[0]
        return np.asarray(depth.float().cpu().numpy(), dtype=np.float32)

    return estimate
