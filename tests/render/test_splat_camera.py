"""The pinhole camera shared by the splat and mesh passes (OpenCV axes)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drivetwin.worlds.render.camera import Camera, CameraError


def project(camera: Camera, point) -> np.ndarray:
    x, y, z = camera.world_to_camera[:3, :3] @ np.asarray(point, float) + camera.world_to_camera[:3, 3]
    return np.array([camera.fx * x / z + camera.cx, camera.fy * y / z + camera.cy, z])


def test_look_at_puts_the_target_at_the_principal_point_and_up_at_the_top():
    camera = Camera.from_look_at((1.0, 2.0, 1.5), (11.0, 2.0, 1.5), width=640, height=360,
                                 fovy_deg=60.0)  # fmt: skip
    u, v, z = project(camera, (11.0, 2.0, 1.5))
    assert (u, v, z) == pytest.approx((320.0, 180.0, 10.0))
    assert project(camera, (11.0, 2.0, 3.0))[1] < 180.0  # higher in the world: up in the image
    assert project(camera, (11.0, 0.0, 1.5))[0] > 320.0  # -y is to the right looking along +x
    assert camera.fovy == pytest.approx(math.radians(60.0))
    assert np.allclose(camera.position, [1.0, 2.0, 1.5])
    assert np.allclose(camera.camera_to_world @ camera.world_to_camera, np.eye(4))


def test_from_k_reads_opencv_intrinsics():
    K = np.array([[500.0, 0.0, 320.0], [0.0, 510.0, 200.0], [0.0, 0.0, 1.0]])
    camera = Camera.from_K(K, np.eye(4), 640, 400)
    assert (camera.fx, camera.fy, camera.cx, camera.cy) == (500.0, 510.0, 320.0, 200.0)
    assert np.array_equal(camera.K, K)


def test_camera_refuses_what_is_not_a_pinhole_camera():
    with pytest.raises(CameraError, match="rigid"):
        Camera(10, 10, 10.0, 10.0, 5.0, 5.0, world_to_camera=np.diag([2.0, 2.0, 2.0, 1.0]))
    with pytest.raises(CameraError, match="positive focal"):
        Camera(10, 10, -1.0, 10.0, 5.0, 5.0, world_to_camera=np.eye(4))
    with pytest.raises(CameraError, match="parallel"):
        Camera.from_look_at((0, 0, 0), (0, 0, 5), width=10, height=10, fovy_deg=50)
    with pytest.raises(CameraError, match="near < far"):
        Camera(10, 10, 10.0, 10.0, 5.0, 5.0, world_to_camera=np.eye(4), near=2.0, far=1.0)


def test_camera_matrix_cannot_be_changed_through_the_array():
    camera = Camera(10, 10, 10.0, 10.0, 5.0, 5.0, world_to_camera=np.eye(4))
    with pytest.raises(ValueError, match="read-only"):
        camera.world_to_camera[0, 3] = 1.0
