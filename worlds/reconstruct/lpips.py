"""LPIPS (Zhang et al. 2018, AlexNet variant v0.1) in plain torch, with weights the user supplies.

The network is AlexNet's five conv layers (as torchvision builds them) whose ReLU outputs
are unit-normalised per pixel along channels, differenced, squared, weighted by a learned
1x1 "linear" head per layer, averaged over pixels and summed over layers. Inputs in 0..1
are mapped to -1..1 and then by LPIPS's scaling layer.

No weights ship with drivetwin and none are downloaded. ``load_lpips`` accepts:
- one state-dict file holding both the backbone (torchvision names ``features.N.weight``,
  or the lpips package's ``net.sliceK.N.weight``) and the heads (``linK.model.1.weight``), or
- a folder holding two .pth files: the heads (``alex.pth`` from the lpips package,
  lpips/weights/v0.1/alex.pth) and torchvision's AlexNet weights (``alexnet-owt-7be5be79.pth``).
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import numpy.typing as npt
import torch
from torch import nn

from .image_metrics import MetricsError

__all__ = ["LPIPS_CHANNELS", "AlexLPIPS", "LpipsWeightsError", "load_lpips"]

# Channels of AlexNet's five ReLU taps that LPIPS compares.
LPIPS_CHANNELS = (64, 192, 384, 256, 256)
# torchvision's indices of AlexNet's conv layers inside ``features``.
_CONV_INDICES = (0, 3, 6, 8, 10)
# LPIPS's scaling layer: ImageNet statistics in the -1..1 range.
_SHIFT = (-0.030, -0.088, -0.188)
_SCALE = (0.458, 0.448, 0.450)
_NORM_EPS = 1e-10  # LPIPS's guard against dividing a zero feature vector by its norm
_HOW_TO_GET = (
    "LPIPS needs weights you supply: the AlexNet heads 'alex.pth' (lpips package, "
    "lpips/weights/v0.1/alex.pth) and torchvision's AlexNet 'alexnet-owt-7be5be79.pth', "
    "both in one folder, or one state dict holding both; pass that path as lpips_weights"
)
_SLICE_KEY = re.compile(r"^net\.slice\d\.(\d+)\.(weight|bias)$")


class LpipsWeightsError(MetricsError):
    """LPIPS weights are absent or do not fit the network."""


class AlexLPIPS(nn.Module):
    """The LPIPS-Alex distance network; parameter names match torchvision's and lpips's files."""

    def __init__(self) -> None:
        super().__init__()
        convs: list[nn.Module] = [
            nn.Conv2d(3, 64, kernel_size=11, stride=4, padding=2),
            nn.Conv2d(64, 192, kernel_size=5, padding=2),
            nn.Conv2d(192, 384, kernel_size=3, padding=1),
            nn.Conv2d(384, 256, kernel_size=3, padding=1),
            nn.Conv2d(256, 256, kernel_size=3, padding=1),
        ]
        # Laid out at torchvision's indices so its state dict loads as it is.
        layers: list[nn.Module] = [nn.Identity() for _ in range(_CONV_INDICES[-1] + 2)]
        for index, conv in zip(_CONV_INDICES, convs, strict=True):
            layers[index] = conv
            layers[index + 1] = nn.ReLU(inplace=False)
        layers[2] = layers[5] = nn.MaxPool2d(kernel_size=3, stride=2)
        self.features = nn.Sequential(*layers)
        for k, channels in enumerate(LPIPS_CHANNELS):
            # lpips names the 1x1 conv "model.1" (model.0 is a dropout, inactive at eval).
            head = nn.Sequential(nn.Identity(), nn.Conv2d(channels, 1, kernel_size=1, bias=False))
            self.add_module(f"lin{k}", nn.Module())
            getattr(self, f"lin{k}").model = head
        self.register_buffer("shift", torch.tensor(_SHIFT).view(1, 3, 1, 1))
        self.register_buffer("scale", torch.tensor(_SCALE).view(1, 3, 1, 1))
        self.eval()

    def _taps(self, x: torch.Tensor) -> list[torch.Tensor]:
        taps = []
        for index, layer in enumerate(self.features):
            x = layer(x)
            if index - 1 in _CONV_INDICES:
                taps.append(x)
        return taps

    def forward(self, a: torch.Tensor, b: torch.Tensor) -> torch.Tensor:
        """Distances [B] of image batches [B,3,H,W] in 0..1 (H, W at least 32 pixels)."""
        shift, scale = self.shift, self.scale
        assert isinstance(shift, torch.Tensor) and isinstance(scale, torch.Tensor)
        fa = self._taps(((2 * a - 1) - shift) / scale)
        fb = self._taps(((2 * b - 1) - shift) / scale)
        total = torch.zeros(a.shape[0], dtype=a.dtype, device=a.device)
        for k, (x, y) in enumerate(zip(fa, fb, strict=True)):
            x = x / (x.norm(dim=1, keepdim=True) + _NORM_EPS)
            y = y / (y.norm(dim=1, keepdim=True) + _NORM_EPS)
            total = total + getattr(self, f"lin{k}").model((x - y) ** 2).mean(dim=(1, 2, 3))
        return total

    def distance(self, a: npt.ArrayLike, b: npt.ArrayLike) -> float:
        """LPIPS distance of two RGB images [H,W,3] in 0..1 (0 when equal; larger is less alike)."""
        x, y = np.asarray(a, dtype=np.float32), np.asarray(b, dtype=np.float32)
        if x.shape != y.shape or x.ndim != 3 or x.shape[2] != 3:
            raise MetricsError(f"need two RGB images [H,W,3] of one shape, got {x.shape} and {y.shape}")
        if min(x.shape[:2]) < 32:
            raise MetricsError(f"LPIPS-Alex needs images of at least 32x32 pixels, got {x.shape[1]}x{x.shape[0]}")
        with torch.no_grad():
            ta = torch.from_numpy(x).permute(2, 0, 1)[None]
            tb = torch.from_numpy(y).permute(2, 0, 1)[None]
            return float(self(ta, tb)[0])


def _read_state(path: Path) -> dict[str, torch.Tensor]:
    try:
        state = torch.load(path, map_location="cpu", weights_only=True)
    except (OSError, RuntimeError, ValueError) as exc:
        raise LpipsWeightsError(f"cannot read LPIPS weights {path}: {exc}. {_HOW_TO_GET}") from exc
    if not isinstance(state, dict):
        raise LpipsWeightsError(f"{path} is not a state dict. {_HOW_TO_GET}")
    return {str(k): v for k, v in state.items() if isinstance(v, torch.Tensor)}


def load_lpips(path: str | Path | None) -> AlexLPIPS:
    """The LPIPS-Alex network with user-supplied weights from a file or folder (see module doc).

    Raises ``LpipsWeightsError`` naming how to get the weights when ``path`` is None, missing,
    or its tensors do not fill the network exactly.
    """
    if path is None:
        raise LpipsWeightsError(f"no LPIPS weights given. {_HOW_TO_GET}")
    source = Path(path)
    if not source.exists():
        raise LpipsWeightsError(f"LPIPS weights {source} do not exist. {_HOW_TO_GET}")
    files = sorted(source.glob("*.pth")) + sorted(source.glob("*.pt")) if source.is_dir() else [source]
    merged: dict[str, torch.Tensor] = {}
    for file in files:
        for key, value in _read_state(file).items():
            match = _SLICE_KEY.match(key)
            merged[f"features.{match.group(1)}.{match.group(2)}" if match else key] = value
    network = AlexLPIPS()
    wanted = {k for k in network.state_dict() if k not in ("shift", "scale")}
    missing = sorted(wanted - merged.keys())
    if missing:
        raise LpipsWeightsError(f"LPIPS weights in {source} lack {', '.join(missing[:4])}"
                                f"{' ...' if len(missing) > 4 else ''}. {_HOW_TO_GET}")  # fmt: skip
    try:
        network.load_state_dict({k: merged[k] for k in wanted}, strict=False)
    except RuntimeError as exc:
        raise LpipsWeightsError(f"LPIPS weights in {source} do not fit AlexNet-LPIPS: {exc}") from exc
    return network
