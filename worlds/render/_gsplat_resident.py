"""Splats kept on the GPU between frames for the gsplat backend, and its depth-limit cull in torch.

A renderer draws the same ``Splats`` object frame after frame (``hybrid._PosedSplats`` hands
back one joined set while nothing moves), so ``ResidentSplatsCache`` uploads each set once,
already activated the way gsplat takes it (scales = exp, opacities = sigmoid), and hands the
same tensors back until the set changes. A set counts as changed when it is another object
or one of its five arrays was replaced or reshaped; ``Splats`` produce new arrays when they
change (``transformed``, ``subset``, ``concat``), so writing into a cached set's arrays in
place is not seen: ``forget`` it first. Entries die with their ``Splats`` (a weak reference)
and at most ``capacity`` are held, so neither a stream of new sets nor a long session grows
GPU memory.

``depth_limit_keep_mask`` is ``_torch_raster.cull_behind_depth_limit``'s rule on tensors,
so the depth limit is the only thing a frame uploads: same float64 arithmetic in the same
order, elementwise (no matrix product, whose summation order is the BLAS library's), so on
any device it agrees bit for bit with the NumPy reference (``depth_limit_keep_mask_numpy``).
"""

from __future__ import annotations

import threading
import weakref
from collections import OrderedDict
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt
import torch

from .camera import Camera
from .splats import Splats

__all__ = [
    "RESIDENT_CAPACITY",
    "ResidentSplats",
    "ResidentSplatsCache",
    "depth_limit_keep_mask",
    "depth_limit_keep_mask_numpy",
    "resident_splats",
]

# Sets held at once: a renderer draws one (background plus attachments, joined), a second
# renderer or a set being swapped in is the next; more would only pin stale GPU memory.
RESIDENT_CAPACITY = 4
_FIELDS = ("means", "quats", "log_scales", "opacity_logits", "sh")


@dataclass(frozen=True)
class ResidentSplats:
    """One ``Splats`` on a device as gsplat takes it: [N,3] means, [N,4] quats, [N,3] scales
    (metres, not logs), [N] opacities (0..1, not logits), [N,K,3] SH coefficients."""

    means: torch.Tensor
    quats: torch.Tensor
    scales: torch.Tensor
    opacities: torch.Tensor
    sh: torch.Tensor
    sh_degree: int

    def __len__(self) -> int:
        return int(self.means.shape[0])

    def subset(self, keep: torch.Tensor) -> ResidentSplats:
        """The splats where the boolean mask ``keep`` [N] is true, on the same device."""
        index = keep.nonzero().squeeze(1)
        means, quats, scales, opacities, sh = (
            t.index_select(0, index) for t in (self.means, self.quats, self.scales, self.opacities, self.sh)
        )
        return ResidentSplats(means, quats, scales, opacities, sh, self.sh_degree)


def _upload(splats: Splats, device: torch.device) -> ResidentSplats:
    def put(a: npt.NDArray[np.float32]) -> torch.Tensor:
        return torch.as_tensor(a, device=device)

    return ResidentSplats(
        means=put(splats.means),
        quats=put(splats.quats),
        scales=torch.exp(put(splats.log_scales)),
        opacities=torch.sigmoid(put(splats.opacity_logits)),
        sh=put(splats.sh),
        sh_degree=splats.sh_degree,
    )


def _version(splats: Splats) -> tuple[Any, ...]:
    """What changes when a set's arrays are replaced: each array's identity, address and shape."""
    return tuple((id(a), a.ctypes.data, a.shape) for a in (getattr(splats, f) for f in _FIELDS))


@dataclass
class _Entry:
    owner: weakref.ref[Splats]
    version: tuple[Any, ...]
    tensors: ResidentSplats


class ResidentSplatsCache:
    """At most ``capacity`` splat sets resident on their devices, least recently used dropped first."""

    def __init__(self, capacity: int = RESIDENT_CAPACITY) -> None:
        if capacity < 1:
            raise ValueError(f"capacity must be at least 1 splat set, got {capacity}")
        self.capacity = capacity
        self._entries: OrderedDict[tuple[int, str], _Entry] = OrderedDict()
        self._lock = threading.Lock()  # renderers may draw from several threads
        self.uploads = 0  # sets uploaded so far: a hit leaves it unchanged

    def __len__(self) -> int:
        return len(self._entries)

    def get(self, splats: Splats, device: torch.device | str) -> ResidentSplats:
        """``splats`` on ``device``: the tensors uploaded before if the set is unchanged, else new ones."""
        device = torch.device(device)
        key = (id(splats), str(device))
        version = _version(splats)
        with self._lock:
            entry = self._entries.get(key)
            if entry is not None and entry.owner() is splats and entry.version == version:
                self._entries.move_to_end(key)
                return entry.tensors
        tensors = _upload(splats, device)  # outside the lock: other sets need not wait on a copy
        with self._lock:
            self._entries[key] = _Entry(weakref.ref(splats, self._dropper(key)), version, tensors)
            self._entries.move_to_end(key)
            self.uploads += 1
            while len(self._entries) > self.capacity:
                self._entries.popitem(last=False)
        return tensors

    def forget(self, splats: Splats) -> None:
        """Drop ``splats`` on every device (call it after writing into its arrays in place)."""
        with self._lock:
            for key in [k for k, e in self._entries.items() if e.owner() is splats]:
                del self._entries[key]

    def clear(self) -> None:
        """Drop every resident set."""
        with self._lock:
            self._entries.clear()

    def _dropper(self, key: tuple[int, str]) -> Any:
        def drop(ref: weakref.ref[Splats]) -> None:
            with self._lock:
                entry = self._entries.get(key)
                if entry is not None and entry.owner is ref:  # not a newer set at a reused id
                    del self._entries[key]

        return drop


resident_splats = ResidentSplatsCache()
"""The process's cache, used by ``rasterize(backend="gsplat")``."""


def _view_rows(camera: Camera) -> list[list[float]]:
    """The first three rows of world-to-camera as Python floats: the same scalars for NumPy and torch."""
    return np.asarray(camera.world_to_camera, dtype=np.float64)[:3].tolist()  # type: ignore[no-any-return]


def depth_limit_keep_mask(means: torch.Tensor, camera: Camera, depth_limit: torch.Tensor) -> torch.Tensor:
    """Boolean [N]: the splats whose mean lies in front of ``depth_limit`` [H,W] at its centre pixel.

    Means projecting outside the image read the nearest edge pixel; means behind the near
    plane are kept (gsplat culls them itself). Runs on ``means``' device.
    """
    device = means.device
    m = means.to(torch.float64)
    x, y, z = (m[:, 0] * r[0] + m[:, 1] * r[1] + m[:, 2] * r[2] + r[3] for r in _view_rows(camera))
    in_front = z > camera.near
    safe_z = torch.where(in_front, z, torch.ones_like(z))
    col = torch.clamp(torch.floor(camera.fx * x / safe_z + camera.cx), 0, camera.width - 1).to(torch.int64)
    row = torch.clamp(torch.floor(camera.fy * y / safe_z + camera.cy), 0, camera.height - 1).to(torch.int64)
    limit = depth_limit.to(device=device, dtype=torch.float64).reshape(-1)[row * camera.width + col]
    return ~in_front | (z < limit)


def depth_limit_keep_mask_numpy(
    means: npt.NDArray[np.floating], camera: Camera, depth_limit: npt.NDArray[np.floating]
) -> npt.NDArray[np.bool_]:
    """The same mask in NumPy: the reference ``depth_limit_keep_mask`` is held to."""
    m = np.asarray(means, dtype=np.float64)
    x, y, z = (m[:, 0] * r[0] + m[:, 1] * r[1] + m[:, 2] * r[2] + r[3] for r in _view_rows(camera))
    in_front = z > camera.near
    safe_z = np.where(in_front, z, 1.0)
    col = np.clip(np.floor(camera.fx * x / safe_z + camera.cx), 0, camera.width - 1).astype(np.int64)
    row = np.clip(np.floor(camera.fy * y / safe_z + camera.cy), 0, camera.height - 1).astype(np.int64)
    limit = np.asarray(depth_limit, dtype=np.float64)[row, col]
    keep: npt.NDArray[np.bool_] = ~in_front | (z < limit)
    return keep
