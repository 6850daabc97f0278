"""Rotations, one convention everywhere: quaternions are (w, x, y, z), scalar first, as MuJoCo
stores them (qpos, xquat, body quat) and as splats keep them.

Frames are right-handed with z up. A yaw (heading) is a rotation about +z, counter-clockwise
seen from above, in radians; a pitch is then a rotation about the rotated +y, so a positive
pitch tips +x down. A rotation matrix R maps body coordinates to world coordinates (p_world =
R @ p_body), like MuJoCo's xmat. Quaternions need not be unit length where a function says it
normalises; q and -q are the same rotation.

The compiled kernels keep their own inline copies (`_numba_kernel` per splat in a Numba loop,
`_torch_raster.rotation_matrices` for autograd); the tests hold them to this module.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

__all__ = [
    "look_at_quat",
    "matrix_to_quat",
    "quat_multiply",
    "quat_to_matrix",
    "yaw_of_quat",
    "yaw_pitch_matrix",
    "yaw_pitch_quat",
    "yaw_quat",
    "yaw_quats",
]

F64 = npt.NDArray[np.float64]
Quat = tuple[float, float, float, float]


def yaw_quat(yaw: float) -> Quat:
    """The unit quaternion of a rotation by `yaw` radians about +z."""
    return (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))


def yaw_quats(yaws: npt.ArrayLike) -> F64:
    """Unit quaternions [N,4] of rotations by `yaws` [N] radians about +z."""
    half = np.asarray(yaws, dtype=np.float64) / 2.0
    zeros = np.zeros_like(half)
    return np.stack([np.cos(half), zeros, zeros, np.sin(half)], axis=-1)


def yaw_of_quat(quat: Sequence[float] | F64) -> float:
    """The heading (radians, in (-π, π]) of a quaternion: where it turns +x, projected on the ground."""
    w, x, y, z = (float(v) for v in quat)
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def yaw_pitch_quat(yaw: float, pitch: float) -> Quat:
    """The unit quaternion of `yaw` about z, then `pitch` about the new y (positive tips +x down)."""
    cy, sy, cp, sp = math.cos(yaw / 2), math.sin(yaw / 2), math.cos(pitch / 2), math.sin(pitch / 2)
    return (cy * cp, -sy * sp, cy * sp, sy * cp)


def yaw_pitch_matrix(yaw: float, pitch: float) -> F64:
    """The rotation matrix [3,3] of `yaw` about z, then `pitch` about the new y."""
    cy, sy, cp, sp = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    rz = np.array([[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]])
    ry = np.array([[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]])
    rotation: F64 = rz @ ry
    return rotation


def quat_to_matrix(quats: npt.ArrayLike) -> F64:
    """Rotation matrices [...,3,3] of quaternions [...,4] (normalised here; any non-zero norm)."""
    q = np.asarray(quats, dtype=np.float64)
    if q.shape == (4,):  # one quaternion: plain floats are ~20x faster (in-place moves call this per geom)
        return _one_matrix(*(float(v) for v in q))
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    rows = [
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ]
    return np.stack(rows, axis=-2)


def _one_matrix(w: float, x: float, y: float, z: float) -> F64:
    norm = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / norm, x / norm, y / norm, z / norm
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


def matrix_to_quat(rotation: npt.ArrayLike) -> F64:
    """The unit quaternion [4] of a rotation matrix [3,3], w ≥ 0 (Shepperd's method: the
    largest of w, x, y, z is found first, so no division by a small number)."""
    r = np.asarray(rotation, dtype=np.float64)
    trace = float(np.trace(r))
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = [0.25 * s, (r[2, 1] - r[1, 2]) / s, (r[0, 2] - r[2, 0]) / s, (r[1, 0] - r[0, 1]) / s]
    else:
        i = int(np.argmax(np.diag(r)))
        j, k = (i + 1) % 3, (i + 2) % 3
        s = 2.0 * math.sqrt(1.0 + r[i, i] - r[j, j] - r[k, k])
        q = [0.0, 0.0, 0.0, 0.0]
        q[0] = (r[k, j] - r[j, k]) / s
        q[1 + i] = 0.25 * s
        q[1 + j] = (r[j, i] + r[i, j]) / s
        q[1 + k] = (r[k, i] + r[i, k]) / s
    quat = np.asarray(q, dtype=np.float64)
    quat /= np.linalg.norm(quat)
    return -quat if quat[0] < 0 else quat


def quat_multiply(a: npt.ArrayLike, b: npt.ArrayLike) -> F64:
    """The Hamilton product a ⊗ b of quaternions [...,4] (broadcast): rotate by b, then by a."""
    p, q = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    aw, ax, ay, az = p[..., 0], p[..., 1], p[..., 2], p[..., 3]
    bw, bx, by, bz = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack(
        [
            aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
        ],
        axis=-1,
    )


def look_at_quat(eye: Sequence[float], target: Sequence[float]) -> F64:
    """The quaternion of a MuJoCo camera at `eye` looking at `target` with z up (a MuJoCo
    camera looks along its -z, with +y up in the image)."""
    forward = np.asarray(target, dtype=np.float64) - np.asarray(eye, dtype=np.float64)
    forward /= np.linalg.norm(forward)
    right = np.cross(forward, (0.0, 0.0, 1.0))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    return matrix_to_quat(np.stack([right, up, -forward], axis=1))
