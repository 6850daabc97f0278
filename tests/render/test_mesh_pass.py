"""The mesh pass draws MuJoCo geoms exactly where the shared pinhole Camera projects them."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.mesh_pass import MeshPass, MeshPassError

SPHERE_CENTRE = np.array([1.3, 0.7, 2.2])
SPHERE_RADIUS = 0.15
WALL_X = 19.5  # the wall's front face


def _world() -> tuple[mujoco.MjModel, mujoco.MjData]:
    spec = mujoco.MjSpec()
    spec.visual.global_.offwidth, spec.visual.global_.offheight = 640, 480
    ball = spec.worldbody.add_body(name="ball", pos=SPHERE_CENTRE.tolist())
    ball.add_geom(type=mujoco.mjtGeom.mjGEOM_SPHERE, size=[SPHERE_RADIUS, 0, 0], rgba=[1, 0, 0, 1])
    spec.worldbody.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, pos=[WALL_X + 0.5, 0, 0],
                            size=[0.5, 30, 30], rgba=[0, 1, 0, 1])  # fmt: skip
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model, data


@pytest.fixture(scope="module")
def mesh_pass() -> MeshPass:
    return MeshPass()


def _off_centre_camera() -> Camera:
    base = Camera.from_look_at((-4.0, -1.0, 1.0), (2.0, 0.5, 2.0), width=320, height=200,
                               fovy_deg=50)  # fmt: skip
    # Principal point well off the image centre and fx != fy: both must be honoured.
    k = np.array([[300.0, 0.0, 140.3], [0.0, 280.0, 117.8], [0.0, 0.0, 1.0]])
    return Camera.from_K(k, base.world_to_camera, 320, 200)


def test_a_sphere_is_drawn_where_the_camera_projects_its_centre(mesh_pass: MeshPass) -> None:
    model, data = _world()
    camera = _off_centre_camera()
    image = mesh_pass.render(model, data, camera)
    red = (image.rgb[..., 0] > 2 * image.rgb[..., 1]) & image.hit
    rows, cols = np.nonzero(red)
    centre = camera.world_to_camera @ np.append(SPHERE_CENTRE, 1.0)
    u = camera.fx * centre[0] / centre[2] + camera.cx
    v = camera.fy * centre[1] / centre[2] + camera.cy
    assert red.sum() > 50
    assert abs(cols.mean() + 0.5 - u) < 1.0 and abs(rows.mean() + 0.5 - v) < 1.0
    # The nearest point of the sphere is one radius in front of its centre (to rounding).
    assert image.depth[int(v), int(u)] == pytest.approx(centre[2] - SPHERE_RADIUS, abs=0.03)


def test_depth_is_camera_z_not_distance_along_the_ray(mesh_pass: MeshPass) -> None:
    model, data = _world()
    camera = Camera.from_look_at((0.0, -5.0, 0.0), (1.0, -5.0, 0.0), width=96, height=64,
                                 fovy_deg=70)  # fmt: skip
    depth = mesh_pass.render(model, data, camera).depth
    # A wall square to the view axis has the same camera z at the centre and the corners.
    assert np.allclose(depth, WALL_X, atol=0.01)


def test_pixels_no_geom_covers_have_infinite_depth_and_no_colour(mesh_pass: MeshPass) -> None:
    model, data = _world()
    camera = Camera.from_look_at((0.0, 0.0, 0.0), (-1.0, 0.0, 0.0), width=64, height=48,
                                 fovy_deg=40)  # fmt: skip
    image = mesh_pass.render(model, data, camera)
    assert not image.hit.any()
    assert np.isinf(image.depth).all() and not image.rgb.any()


def test_hidden_bodies_are_not_drawn(mesh_pass: MeshPass) -> None:
    model, data = _world()
    camera = _off_centre_camera()
    ball = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, "ball")
    image = mesh_pass.render(model, data, camera, hidden_bodies=[ball])
    assert not (image.rgb[..., 0] > 2 * image.rgb[..., 1]).any()


def test_an_image_larger_than_the_offscreen_buffer_is_refused(mesh_pass: MeshPass) -> None:
    model, data = _world()
    camera = Camera.from_look_at((0, 0, 0), (1, 0, 0), width=800, height=600, fovy_deg=60)
    with pytest.raises(MeshPassError, match="offscreen buffer 640x480"):
        mesh_pass.render(model, data, camera)


def test_one_mesh_pass_renders_from_another_thread_too(mesh_pass: MeshPass) -> None:
    import threading

    model, data = _world()
    camera = _off_centre_camera()
    here = mesh_pass.render(model, data, camera)
    there: list[np.ndarray] = []
    worker = threading.Thread(target=lambda: there.append(mesh_pass.render(model, data, camera).rgb))
    worker.start()
    worker.join()
    assert len(there) == 1 and np.array_equal(there[0], here.rgb)
