"""The one rotation module: MuJoCo's (w, x, y, z) quaternions, matrices and headings agree with
MuJoCo's own functions, round-trip, and give the known values."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest
from drivetwin.worlds.rotation import (
    look_at_quat,
    matrix_to_quat,
    quat_multiply,
    quat_to_matrix,
    yaw_of_quat,
    yaw_pitch_matrix,
    yaw_pitch_quat,
    yaw_quat,
    yaw_quats,
)
from hypothesis import given
from hypothesis import strategies as st

angles = st.floats(-math.pi + 1e-6, math.pi, allow_nan=False)
pitches = st.floats(-1.5, 1.5, allow_nan=False)
components = st.floats(-1.0, 1.0, allow_nan=False)
quats = st.tuples(components, components, components, components).filter(lambda q: np.linalg.norm(q) > 0.1)


def _mju_matrix(quat: np.ndarray) -> np.ndarray:
    unit = np.asarray(quat, np.float64) / np.linalg.norm(quat)
    out = np.empty(9)
    mujoco.mju_quat2Mat(out, unit)
    return out.reshape(3, 3)


def _same_rotation(a: np.ndarray, b: np.ndarray) -> bool:
    return bool(np.allclose(a, b, atol=1e-9) or np.allclose(a, -b, atol=1e-9))


def test_a_quarter_turn_about_z_takes_x_to_y():
    assert quat_to_matrix(yaw_quat(math.pi / 2)) @ np.array([1.0, 0.0, 0.0]) == pytest.approx([0.0, 1.0, 0.0])


def test_a_positive_pitch_tips_x_down():
    assert (yaw_pitch_matrix(0.0, 0.3) @ np.array([1.0, 0.0, 0.0]))[2] == pytest.approx(-math.sin(0.3))


@given(quats)
def test_quat_to_matrix_matches_mujoco(quat):
    assert np.allclose(quat_to_matrix(np.array(quat)), _mju_matrix(np.array(quat)), atol=1e-12)


@given(st.lists(quats, min_size=1, max_size=5))
def test_batched_quat_to_matrix_matches_one_at_a_time(batch):
    stacked = quat_to_matrix(np.array(batch))
    assert stacked.shape == (len(batch), 3, 3)
    for quat, matrix in zip(batch, stacked, strict=True):
        assert np.allclose(matrix, quat_to_matrix(np.array(quat)), atol=1e-12)


@given(quats)
def test_matrix_to_quat_matches_mujoco_and_round_trips(quat):
    unit = np.array(quat) / np.linalg.norm(quat)
    matrix = quat_to_matrix(unit)
    expected = np.empty(4)
    mujoco.mju_mat2Quat(expected, matrix.ravel())
    recovered = matrix_to_quat(matrix)
    assert recovered[0] >= 0.0
    assert _same_rotation(recovered, expected) and _same_rotation(recovered, unit)


@given(quats, quats)
def test_quat_multiply_matches_mujoco_and_composes_matrices(a, b):
    ua, ub = np.array(a) / np.linalg.norm(a), np.array(b) / np.linalg.norm(b)
    expected = np.empty(4)
    mujoco.mju_mulQuat(expected, ua, ub)
    product = quat_multiply(ua, ub)
    assert np.allclose(product, expected, atol=1e-12)
    assert np.allclose(quat_to_matrix(product), quat_to_matrix(ua) @ quat_to_matrix(ub), atol=1e-9)


@given(angles)
def test_yaw_round_trips_through_its_quaternion(yaw):
    assert yaw_of_quat(yaw_quat(yaw)) == pytest.approx(yaw, abs=1e-9)


@given(angles, pitches)
def test_heading_ignores_pitch(yaw, pitch):
    assert yaw_of_quat(yaw_pitch_quat(yaw, pitch)) == pytest.approx(yaw, abs=1e-9)


@given(angles, pitches)
def test_yaw_pitch_quaternion_and_matrix_are_one_rotation(yaw, pitch):
    assert np.allclose(quat_to_matrix(yaw_pitch_quat(yaw, pitch)), yaw_pitch_matrix(yaw, pitch), atol=1e-12)


def test_yaw_quats_stack_yaw_quat():
    yaws = np.array([-2.0, 0.0, 0.5, 3.0])
    assert np.allclose(yaw_quats(yaws), [yaw_quat(float(y)) for y in yaws])


def test_a_look_at_camera_looks_along_its_minus_z_at_the_target():
    eye, target = np.array([3.0, -4.0, 5.0]), np.array([1.0, 2.0, 0.5])
    rotation = quat_to_matrix(look_at_quat(eye, target))
    direction = (target - eye) / np.linalg.norm(target - eye)
    assert rotation @ np.array([0.0, 0.0, -1.0]) == pytest.approx(direction)
    assert (rotation @ np.array([1.0, 0.0, 0.0]))[2] == pytest.approx(0.0, abs=1e-12)  # image stays level


def test_the_torch_rasterizers_rotations_agree_with_this_module():
    torch = pytest.importorskip("torch")
    from drivetwin.worlds.render._torch_raster import rotation_matrices

    batch = np.random.default_rng(3).normal(size=(16, 4))
    assert np.allclose(rotation_matrices(torch.as_tensor(batch)).numpy(), quat_to_matrix(batch), atol=1e-12)
