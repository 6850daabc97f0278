"""Gaussian splats: the 3DGS parameter set, its .ply I/O, point-cloud init and rigid motion.

Parameters are stored exactly as 3D Gaussian Splatting trains them (Kerbl et al. 2023):
means in metres (world frame), rotations as wxyz quaternions (normalised on use), log
scales, opacity logits and real spherical-harmonic colour coefficients whose DC term maps
to colour as ``0.5 + SH_C0 * dc``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
from drivetwin.worlds.rotation import matrix_to_quat, quat_multiply

__all__ = [
    "SH_C0",
    "Splats",
    "SplatsError",
    "eval_sh_colors",
    "ply_property_names",
    "sh_basis",
    "sh_coefficients",
]

F32 = npt.NDArray[np.float32]
F64 = npt.NDArray[np.float64]

# Constants of the real SH basis exactly as the 3DGS reference code writes them.
SH_C0 = 0.28209479177387814
SH_C1 = 0.4886025119029199
SH_C2 = (1.0925484305920792, -1.0925484305920792, 0.31539156525252005, -1.0925484305920792,
         0.5462742152960396)  # fmt: skip
SH_C3 = (-0.5900435899266435, 2.890611442640554, -0.4570457994644658, 0.3731763325901154,
         -0.4570457994644658, 1.445305721320277, -0.5900435899266435)  # fmt: skip
MAX_SH_DEGREE = 3
# 3DGS clamps squared neighbour distances so duplicate points still get a finite log scale.
MIN_NEIGHBOUR_DIST2 = 1e-7
# Enough well-spread directions to fit an SH band rotation (band 3 has 7 unknowns per row).
_ROTATION_FIT_DIRECTIONS = 64
_PLY_TYPES = {"float": "f4", "float32": "f4", "double": "f8", "float64": "f8", "uchar": "u1",
              "uint8": "u1", "char": "i1", "int8": "i1", "ushort": "u2", "uint16": "u2",
              "short": "i2", "int16": "i2", "uint": "u4", "uint32": "u4", "int": "i4",
              "int32": "i4"}  # fmt: skip


class SplatsError(ValueError):
    """Splat parameters or a splat file are malformed."""


def _f32(values: npt.ArrayLike) -> F32:
    return np.ascontiguousarray(values, dtype=np.float32)


def sh_coefficients(degree: int) -> int:
    """Number of SH coefficients per colour channel for ``degree`` (0..3)."""
    if not 0 <= degree <= MAX_SH_DEGREE:
        raise SplatsError(f"SH degree must be 0..{MAX_SH_DEGREE}, got {degree}")
    return (degree + 1) ** 2


def sh_basis(x: Any, y: Any, z: Any, degree: int) -> list[Any]:
    """The 3DGS real SH basis functions at unit directions (x, y, z), in coefficient order.

    Works on anything with arithmetic (NumPy arrays, torch tensors, floats); the torch
    rasterizer uses it too, so all backends share one basis definition.
    """
    basis: list[Any] = [SH_C0 + 0.0 * x]
    if degree >= 1:
        basis += [-SH_C1 * y, SH_C1 * z, -SH_C1 * x]
    if degree >= 2:
        xx, yy, zz, xy, yz, xz = x * x, y * y, z * z, x * y, y * z, x * z
        basis += [SH_C2[0] * xy, SH_C2[1] * yz, SH_C2[2] * (2.0 * zz - xx - yy),
                  SH_C2[3] * xz, SH_C2[4] * (xx - yy)]  # fmt: skip
    if degree >= 3:
        basis += [
            SH_C3[0] * y * (3.0 * xx - yy),
            SH_C3[1] * xy * z,
            SH_C3[2] * y * (4.0 * zz - xx - yy),
            SH_C3[3] * z * (2.0 * zz - 3.0 * xx - 3.0 * yy),
            SH_C3[4] * x * (4.0 * zz - xx - yy),
            SH_C3[5] * z * (xx - yy),
            SH_C3[6] * x * (xx - 3.0 * yy),
        ]
    return basis


def eval_sh_colors(sh: npt.NDArray[Any], directions: npt.NDArray[Any]) -> F64:
    """RGB [N,3] of SH coefficients [N,K,3] seen along unit ``directions`` [N,3] (3DGS rule).

    The colour is ``0.5 + sum_k basis_k(d) * sh_k`` clamped below at 0, as 3DGS does.
    """
    degree = {1: 0, 4: 1, 9: 2, 16: 3}[sh.shape[1]]
    d = np.asarray(directions, dtype=np.float64)
    basis: F64 = np.stack(sh_basis(d[:, 0], d[:, 1], d[:, 2], degree), axis=1)  # [N, K]
    rgb: F64 = np.einsum("nk,nkc->nc", basis, sh.astype(np.float64)) + 0.5
    return np.maximum(rgb, 0.0)


def _sh_band_rotations(rotation: F64, degree: int) -> list[F64]:
    """Per-band matrices M_l with basis_l(R^T d) = basis_l(d) @ M_l, fitted exactly.

    Each SH band is closed under rotation, so a least-squares fit over well-spread
    directions recovers the Wigner-D matrix of the band to rounding error.
    """
    n = _ROTATION_FIT_DIRECTIONS
    i = np.arange(n) + 0.5
    polar, azimuth = np.arccos(1 - 2 * i / n), np.pi * (1 + 5**0.5) * i
    dirs = np.stack([np.sin(polar) * np.cos(azimuth), np.sin(polar) * np.sin(azimuth), np.cos(polar)], 1)
    rotated = dirs @ rotation  # rows are (R^T d)^T
    before = np.stack(sh_basis(dirs[:, 0], dirs[:, 1], dirs[:, 2], degree), 1)
    after = np.stack(sh_basis(rotated[:, 0], rotated[:, 1], rotated[:, 2], degree), 1)
    bands = []
    for band in range(1, degree + 1):
        cols = slice(band * band, (band + 1) ** 2)
        bands.append(np.linalg.lstsq(before[:, cols], after[:, cols], rcond=None)[0])
    return bands


@dataclass
class Splats:
    """A set of N 3D Gaussians with view-dependent colour.

    means [N,3] float32 world metres; quats [N,4] wxyz (any norm, normalised on use);
    log_scales [N,3] natural-log standard deviations in metres; opacity_logits [N]
    (opacity = sigmoid); sh [N,K,3] with K = (degree+1)^2, sh[:,0] the DC term.
    """

    means: F32
    quats: F32
    log_scales: F32
    opacity_logits: F32
    sh: F32

    def __post_init__(self) -> None:
        self.means = np.ascontiguousarray(self.means, dtype=np.float32)
        n = self.means.shape[0] if self.means.ndim == 2 else -1
        expected = {"means": (n, 3), "quats": (n, 4), "log_scales": (n, 3), "opacity_logits": (n,)}
        for name, shape in expected.items():
            value = np.ascontiguousarray(getattr(self, name), dtype=np.float32)
            if value.shape != shape or n < 0:
                raise SplatsError(f"{name} must have shape {shape} (N splats), got {value.shape}")
            setattr(self, name, value)
        self.sh = np.ascontiguousarray(self.sh, dtype=np.float32)
        k = self.sh.shape[1] if self.sh.ndim == 3 else 0
        if self.sh.shape != (n, k, 3) or k not in (1, 4, 9, 16):
            raise SplatsError(f"sh must be [N,K,3] with K in 1,4,9,16, got {self.sh.shape}")
        if n and not np.all(np.linalg.norm(self.quats, axis=1) > 0):
            raise SplatsError("quats contain a zero quaternion; rotations need a non-zero norm")

    def __len__(self) -> int:
        return int(self.means.shape[0])

    @property
    def sh_degree(self) -> int:
        """Degree (0..3) of the spherical harmonics."""
        return {1: 0, 4: 1, 9: 2, 16: 3}[self.sh.shape[1]]

    @property
    def opacities(self) -> F32:
        """Opacities in [0,1] (sigmoid of the logits)."""
        return (1.0 / (1.0 + np.exp(-self.opacity_logits.astype(np.float64)))).astype(np.float32)

    @classmethod
    def empty(cls, sh_degree: int = 0) -> Splats:
        """A set of zero splats."""
        k = sh_coefficients(sh_degree)
        return cls(_f32(np.zeros((0, 3))), _f32(np.zeros((0, 4))), _f32(np.zeros((0, 3))),
                   _f32(np.zeros(0)), _f32(np.zeros((0, k, 3))))  # fmt: skip

    @classmethod
    def from_points(
        cls,
        points: npt.ArrayLike,
        colors: npt.ArrayLike,
        *,
        k: int = 3,
        opacity: float = 0.1,
        sh_degree: int = 0,
        max_scale: float | None = None,
    ) -> Splats:
        """Splats initialised from a coloured point cloud, as 3DGS does from SfM points.

        Each point becomes an isotropic Gaussian whose standard deviation is the root of the
        mean squared distance to its ``k`` nearest neighbours, capped at ``max_scale``
        metres when given (an isolated point would otherwise become a splat metres wide
        that smears over everything near it); ``colors`` [N,3] are uint8 0..255 or floats
        in [0,1]; the SH bands above 0 start at zero.
        """
        from scipy.spatial import cKDTree

        pts = np.asarray(points, dtype=np.float64)
        col = np.asarray(colors)
        if pts.ndim != 2 or pts.shape[1] != 3 or col.shape != pts.shape:
            raise SplatsError(f"need points [N,3] and colors [N,3], got {pts.shape}, {col.shape}")
        if not 0.0 < opacity < 1.0:
            raise SplatsError(f"opacity must be in (0, 1), got {opacity}")
        if max_scale is not None and not (math.isfinite(max_scale) and max_scale > 0):
            raise SplatsError(f"max_scale must be a positive number of metres or None (no cap), got {max_scale}")
        if k < 1 or len(pts) <= k:
            raise SplatsError(f"need k >= 1 and more than k points, got k={k}, N={len(pts)}")
        if col.dtype == np.uint8:
            rgb = col.astype(np.float64) / 255.0
        elif np.issubdtype(col.dtype, np.floating) and col.min() >= 0 and col.max() <= 1:
            rgb = col.astype(np.float64)
        else:
            raise SplatsError("colors must be uint8 0..255 or floats in [0, 1]")
        dist, _ = cKDTree(pts).query(pts, k=k + 1)  # the first neighbour is the point itself
        dist2 = np.maximum(np.mean(dist[:, 1:] ** 2, axis=1), MIN_NEIGHBOUR_DIST2)
        if max_scale is not None:
            dist2 = np.minimum(dist2, max_scale * max_scale)
        n = len(pts)
        sh = np.zeros((n, sh_coefficients(sh_degree), 3))
        sh[:, 0] = (rgb - 0.5) / SH_C0
        return cls(
            means=_f32(pts),
            quats=_f32(np.tile([1.0, 0.0, 0.0, 0.0], (n, 1))),
            log_scales=_f32(np.repeat(0.5 * np.log(dist2)[:, None], 3, axis=1)),
            opacity_logits=_f32(np.full(n, np.log(opacity / (1.0 - opacity)))),
            sh=_f32(sh),
        )

    @classmethod
    def concat(cls, parts: Sequence[Splats]) -> Splats:
        """One set holding all ``parts`` in order; lower SH degrees are zero-padded."""
        if not parts:
            return cls.empty()
        k = max(p.sh.shape[1] for p in parts)
        shs = [np.pad(p.sh, ((0, 0), (0, k - p.sh.shape[1]), (0, 0))) for p in parts]
        return cls(
            means=_f32(np.concatenate([p.means for p in parts])),
            quats=_f32(np.concatenate([p.quats for p in parts])),
            log_scales=_f32(np.concatenate([p.log_scales for p in parts])),
            opacity_logits=_f32(np.concatenate([p.opacity_logits for p in parts])),
            sh=_f32(np.concatenate(shs)),
        )

    def subset(self, index: npt.ArrayLike) -> Splats:
        """The splats selected by an index or boolean mask."""
        idx = np.asarray(index)
        return Splats(self.means[idx], self.quats[idx], self.log_scales[idx],
                      self.opacity_logits[idx], self.sh[idx])  # fmt: skip

    def transformed(self, transform: npt.ArrayLike) -> Splats:
        """The splats moved by a similarity transform [4,4] (rotation, translation, uniform scale).

        Means move, quaternions are pre-multiplied by the rotation, log scales shift by the
        log of the scale, and every SH band is rotated with the splat so view-dependent colour
        turns with it (exact: each band's rotation matrix is fitted to rounding error).
        """
        matrix = np.asarray(transform, dtype=np.float64)
        if matrix.shape != (4, 4) or not np.allclose(matrix[3], [0, 0, 0, 1]):
            raise SplatsError("transform must be a [4,4] affine matrix with last row 0 0 0 1")
        linear = matrix[:3, :3]
        scale = float(np.cbrt(np.linalg.det(linear)))
        rotation = linear / scale if scale > 0 else linear
        if scale <= 0 or not np.allclose(rotation.T @ rotation, np.eye(3), atol=1e-5):
            raise SplatsError("transform must be rotation * uniform positive scale + translation")
        means = self.means.astype(np.float64) @ linear.T + matrix[:3, 3]
        q = quat_multiply(matrix_to_quat(rotation), self.quats)
        sh = self.sh.astype(np.float64)
        for band, m in enumerate(_sh_band_rotations(rotation, self.sh_degree), start=1):
            cols = slice(band * band, (band + 1) ** 2)
            sh[:, cols] = np.einsum("ij,njc->nic", m, sh[:, cols])
        return Splats(_f32(means), _f32(q), _f32(self.log_scales + np.float32(np.log(scale))),
                      self.opacity_logits.copy(), _f32(sh))  # fmt: skip

    def write_ply(self, path: str | Path) -> None:
        """Write the standard 3DGS binary little-endian .ply (f_rest channel-major)."""
        names = ply_property_names(self.sh_degree)
        n, k = len(self), self.sh.shape[1]
        columns = [
            self.means,
            np.zeros((n, 3), np.float32),  # 3DGS writes unused normals
            self.sh[:, 0, :],
            self.sh[:, 1:, :].transpose(0, 2, 1).reshape(n, 3 * (k - 1)),
            self.opacity_logits[:, None],
            self.log_scales,
            self.quats,
        ]
        data = np.concatenate(columns, axis=1).astype("<f4")
        header = ["ply", "format binary_little_endian 1.0", f"element vertex {n}"]
        header += [f"property float {name}" for name in names] + ["end_header"]
        with open(path, "wb") as fh:
            fh.write(("\n".join(header) + "\n").encode("ascii"))
            fh.write(np.ascontiguousarray(data).tobytes())

    @classmethod
    def read_ply(cls, path: str | Path) -> Splats:
        """Read a 3DGS .ply (binary, either endianness; f_rest may be absent or partial)."""
        with open(path, "rb") as fh:
            if fh.readline().strip() != b"ply":
                raise SplatsError(f"{path} is not a PLY file")
            fmt, count, props, element = "", 0, [], ""
            while (line := fh.readline()) and line.strip() != b"end_header":
                words = line.decode("ascii", "replace").split()
                if words[:1] == ["format"]:
                    fmt = words[1]
                elif words[:1] == ["element"]:
                    element = words[1]
                    if element == "vertex":
                        count = int(words[2])
                elif words[:1] == ["property"] and element == "vertex":
                    if words[1] == "list" or words[1] not in _PLY_TYPES:
                        raise SplatsError(f"unsupported vertex property in {path}: {line!r}")
                    props.append((words[2], _PLY_TYPES[words[1]]))
            order = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(fmt)
            if order is None:
                raise SplatsError(f"{path}: only binary PLY is supported, got format {fmt!r}")
            dtype = np.dtype([(name, order + code) for name, code in props])
            vertex = np.frombuffer(fh.read(dtype.itemsize * count), dtype=dtype, count=count)
        names = set(dtype.names or ())
        required = ["x", "y", "z", "f_dc_0", "f_dc_1", "f_dc_2", "opacity"]
        required += [f"scale_{i}" for i in range(3)] + [f"rot_{i}" for i in range(4)]
        missing = [name for name in required if name not in names]
        if missing:
            raise SplatsError(f"{path} lacks 3DGS properties: {', '.join(missing)}")
        n_rest = sum(1 for name in names if name.startswith("f_rest_"))
        if n_rest % 3 or (n_rest // 3 + 1) not in (1, 4, 9, 16):
            raise SplatsError(f"{path}: {n_rest} f_rest properties is not a valid SH degree")

        def cols(keys: list[str]) -> F32:
            return np.stack([vertex[key].astype(np.float32) for key in keys], axis=1)

        k = n_rest // 3 + 1
        sh = np.empty((count, k, 3), np.float32)
        sh[:, 0] = cols(["f_dc_0", "f_dc_1", "f_dc_2"])
        rest = cols([f"f_rest_{i}" for i in range(n_rest)]) if n_rest else None
        if rest is not None:
            sh[:, 1:] = rest.reshape(count, 3, k - 1).transpose(0, 2, 1)
        return cls(
            means=cols(["x", "y", "z"]),
            quats=cols([f"rot_{i}" for i in range(4)]),
            log_scales=cols([f"scale_{i}" for i in range(3)]),
            opacity_logits=vertex["opacity"].astype(np.float32),
            sh=sh,
        )


def ply_property_names(sh_degree: int) -> list[str]:
    """The vertex property names, in order, of a 3DGS .ply with SH of ``sh_degree``."""
    n_rest = 3 * (sh_coefficients(sh_degree) - 1)
    return (
        ["x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"]
        + [f"f_rest_{i}" for i in range(n_rest)]
        + ["opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3"]
    )
