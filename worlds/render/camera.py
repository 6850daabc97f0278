"""Pinhole camera shared by the splat rasterizer and the mesh pass.

Frames follow OpenCV: camera x points right, y down, z forward; image coordinates are
continuous pixels with the centre of pixel (row i, column j) at (j + 0.5, i + 0.5), so the
principal point (cx, cy) is in the same units as an OpenCV intrinsic matrix K.
Units are metres for positions and radians for the ``fovy`` property.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

__all__ = ["Camera", "CameraError"]

FloatArray = npt.NDArray[np.float64]

# A world-to-camera rotation whose R^T R differs from identity by more than this is not rigid.
_RIGID_TOLERANCE = 1e-4


class CameraError(ValueError):
    """A camera was described with values that cannot form a pinhole camera."""


def _as_vec3(value: Sequence[float] | npt.ArrayLike, name: str) -> FloatArray:
    vec = np.asarray(value, dtype=np.float64).reshape(-1)
    if vec.shape != (3,) or not np.all(np.isfinite(vec)):
        raise CameraError(f"{name} must be 3 finite numbers, got {value!r}")
    return vec


@dataclass(frozen=True, eq=False)
class Camera:
    """A pinhole camera: image size, intrinsics and a rigid world-to-camera transform.

    ``world_to_camera`` is a [4, 4] float64 matrix mapping world points (metres) to the
    camera frame (OpenCV axes). ``near`` and ``far`` bound the camera-z range that renderers
    draw, in metres.
    """

    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    world_to_camera: FloatArray = field(repr=False)
    near: float = 0.05
    far: float = 1000.0

    def __post_init__(self) -> None:
        if int(self.width) != self.width or int(self.height) != self.height:
            raise CameraError(f"image size must be integers, got {self.width}x{self.height}")
        if self.width <= 0 or self.height <= 0:
            raise CameraError(f"image size must be positive, got {self.width}x{self.height}")
        for name in ("fx", "fy"):
            value = float(getattr(self, name))
            if not math.isfinite(value) or value <= 0:
                raise CameraError(f"{name} must be a positive focal length in pixels, got {value}")
        for name in ("cx", "cy"):
            if not math.isfinite(float(getattr(self, name))):
                raise CameraError(f"{name} must be finite, got {getattr(self, name)}")
        if not (0 < self.near < self.far) or not math.isfinite(self.far):
            raise CameraError(f"need 0 < near < far < inf, got near={self.near}, far={self.far}")
        matrix = np.array(self.world_to_camera, dtype=np.float64, copy=True)
        if matrix.shape != (4, 4) or not np.all(np.isfinite(matrix)):
            raise CameraError(f"world_to_camera must be a finite [4,4] matrix, got {matrix.shape}")
        rotation = matrix[:3, :3]
        rigid = np.allclose(rotation.T @ rotation, np.eye(3), atol=_RIGID_TOLERANCE)
        if not rigid or np.linalg.det(rotation) <= 0 or not np.allclose(matrix[3], [0, 0, 0, 1]):
            raise CameraError("world_to_camera must be a rigid transform (rotation + translation)")
        matrix.setflags(write=False)
        object.__setattr__(self, "world_to_camera", matrix)
        object.__setattr__(self, "width", int(self.width))
        object.__setattr__(self, "height", int(self.height))
        for name in ("fx", "fy", "cx", "cy", "near", "far"):
            object.__setattr__(self, name, float(getattr(self, name)))

    @classmethod
    def from_look_at(
        cls,
        eye: Sequence[float] | npt.ArrayLike,
        target: Sequence[float] | npt.ArrayLike,
        up: Sequence[float] | npt.ArrayLike = (0.0, 0.0, 1.0),
        *,
        width: int,
        height: int,
        fovy_deg: float,
        near: float = 0.05,
        far: float = 1000.0,
    ) -> Camera:
        """Build a camera at ``eye`` looking at ``target`` with square pixels, centred axis."""
        eye_v, target_v, up_v = (
            _as_vec3(eye, "eye"),
            _as_vec3(target, "target"),
            _as_vec3(up, "up"),
        )
        if not 0 < fovy_deg < 180:
            raise CameraError(f"fovy_deg must be in (0, 180), got {fovy_deg}")
        forward = target_v - eye_v
        if np.linalg.norm(forward) < 1e-9:
            raise CameraError("eye and target coincide; a camera needs a viewing direction")
        forward /= np.linalg.norm(forward)
        right = np.cross(forward, up_v)
        if np.linalg.norm(right) < 1e-9:
            raise CameraError("up is parallel to the viewing direction; pass another up vector")
        right /= np.linalg.norm(right)
        down = np.cross(forward, right)
        camera_to_world = np.eye(4)
        camera_to_world[:3, :3] = np.stack([right, down, forward], axis=1)
        camera_to_world[:3, 3] = eye_v
        focal = 0.5 * height / math.tan(math.radians(fovy_deg) / 2)
        return cls(
            width=width,
            height=height,
            fx=focal,
            fy=focal,
            cx=width / 2,
            cy=height / 2,
            world_to_camera=np.asarray(np.linalg.inv(camera_to_world), dtype=np.float64),
            near=near,
            far=far,
        )

    @classmethod
    def from_K(
        cls,
        K: npt.ArrayLike,
        viewmat: npt.ArrayLike,
        width: int,
        height: int,
        *,
        near: float = 0.05,
        far: float = 1000.0,
    ) -> Camera:
        """Build a camera from an OpenCV intrinsic matrix K [3,3] and a world-to-camera [4,4]."""
        k = np.asarray(K, dtype=np.float64)
        if k.shape != (3, 3) or abs(k[0, 1]) > 1e-9:
            raise CameraError(f"K must be a [3,3] pinhole matrix without skew, got {k.shape}")
        return cls(
            width=width,
            height=height,
            fx=float(k[0, 0]),
            fy=float(k[1, 1]),
            cx=float(k[0, 2]),
            cy=float(k[1, 2]),
            world_to_camera=np.asarray(viewmat, dtype=np.float64),
            near=near,
            far=far,
        )

    @property
    def K(self) -> FloatArray:
        """The [3,3] OpenCV intrinsic matrix."""
        return np.array([[self.fx, 0.0, self.cx], [0.0, self.fy, self.cy], [0.0, 0.0, 1.0]])

    @property
    def camera_to_world(self) -> FloatArray:
        """The [4,4] camera-to-world transform (inverse of ``world_to_camera``)."""
        rotation = self.world_to_camera[:3, :3]
        inverse = np.eye(4)
        inverse[:3, :3] = rotation.T
        inverse[:3, 3] = -rotation.T @ self.world_to_camera[:3, 3]
        return inverse

    @property
    def position(self) -> FloatArray:
        """The camera centre in world coordinates, metres."""
        return self.camera_to_world[:3, 3].copy()

    @property
    def fovy(self) -> float:
        """The vertical field of view in radians."""
        return 2.0 * math.atan(0.5 * self.height / self.fy)

    @property
    def fovx(self) -> float:
        """The horizontal field of view in radians."""
        return 2.0 * math.atan(0.5 * self.width / self.fx)

    def transformed(self, transform: npt.ArrayLike) -> Camera:
        """The same camera after moving the world by the rigid ``transform`` [4,4].

        A point p seen by this camera is seen at the same pixel by the returned camera
        as ``transform @ p``.
        """
        matrix = np.asarray(transform, dtype=np.float64)
        if matrix.shape != (4, 4):
            raise CameraError(f"transform must be [4,4], got {matrix.shape}")
        return Camera(
            width=self.width,
            height=self.height,
            fx=self.fx,
            fy=self.fy,
            cx=self.cx,
            cy=self.cy,
            world_to_camera=self.world_to_camera @ np.linalg.inv(matrix),
            near=self.near,
            far=self.far,
        )
