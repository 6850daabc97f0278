"""The mesh pass: RGB and metric depth of a MuJoCo world, drawn offscreen from a `Camera`.

MuJoCo's OpenGL renderer draws the world's geoms (ground, buildings, road paint, asset
bodies). The projection is not MuJoCo's fovy camera: after `mjv_updateScene` the scene's
GL camera is overwritten with the `Camera`'s pose and an off-centre frustum built from its
fx, fy, cx, cy, near and far, so mesh pixels line up with splat pixels exactly (OpenCV
intrinsics, principal point anywhere, fx != fy allowed). Depth comes from the reversed-Z
float depth buffer and is converted to camera z (OpenCV z, metres); pixels that nothing
covers have depth ``inf``.

On a machine without a GPU the GL is Mesa's software EGL; `MUJOCO_GL` defaults to "egl"
here, before MuJoCo is imported, and "osmesa" works too where it is installed.
"""

from __future__ import annotations

import os

os.environ.setdefault("MUJOCO_GL", "egl")

import threading
import time
from collections.abc import Callable, Collection
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass, field
from typing import Any, Protocol

import mujoco
import numpy as np
import numpy.typing as npt

from .camera import Camera

__all__ = ["MeshImage", "MeshPass", "MeshPassError", "SceneHook", "gl_camera_frustum"]

# Room for every geom of a 500-asset world (about 10 geoms each) plus decorations.
MAX_SCENE_GEOMS = 10_000
# GL lights beyond this many are ignored by MuJoCo's fixed-function pipeline (OpenGL 1.x
# guarantees 8 lights); the appearance code keeps its lights within it.
MAX_GL_LIGHTS = 8
ANTIALIAS_SAMPLES = 4  # MuJoCo's default offscreen multisampling

SceneHook = Callable[[mujoco.MjvScene], None]


class MeshPassError(RuntimeError):
    """The mesh pass cannot render: no GL backend, or an image larger than its buffer."""


class _Locker(Protocol):
    def __enter__(self) -> object: ...
    def __exit__(self, *args: object) -> object: ...


@dataclass
class MeshImage:
    """One mesh-pass image: rgb [H,W,3] float32 in 0..1, depth [H,W] float32 camera z (m).

    ``hit`` [H,W] bool marks pixels some geom covers (elsewhere rgb is 0, depth inf).
    """

    rgb: npt.NDArray[np.float32]
    depth: npt.NDArray[np.float32]
    hit: npt.NDArray[np.bool_]
    timings: dict[str, float] = field(default_factory=dict)


def gl_camera_frustum(camera: Camera) -> dict[str, Any]:
    """The MuJoCo GL camera (pose and frustum) that projects exactly like ``camera``.

    MuJoCo's GL camera looks along ``forward`` with ``up`` as image up; its near-plane
    window is [center - width, center + width] x [bottom, top] at distance ``near``.
    OpenCV's camera looks along +z with +y down, so forward = z axis, up = -y axis.
    """
    rotation = camera.world_to_camera[:3, :3]
    near = camera.near
    return {
        "pos": camera.position,
        "forward": rotation[2].copy(),
        "up": -rotation[1],
        "frustum_near": near,
        "frustum_far": camera.far,
        "frustum_center": near * (camera.width / 2 - camera.cx) / camera.fx,
        "frustum_width": near * camera.width / (2 * camera.fx),
        "frustum_top": near * camera.cy / camera.fy,
        "frustum_bottom": -near * (camera.height - camera.cy) / camera.fy,
    }


def _context_class() -> type[Any]:
    """The GLContext class for MUJOCO_GL, imported directly (mujoco may predate the env)."""
    backend = os.environ.get("MUJOCO_GL", "egl").lower()
    try:
        if backend == "egl":
            from mujoco.egl import GLContext as EglContext

            return EglContext  # type: ignore[no-any-return]
        if backend == "osmesa":
            from mujoco.osmesa import GLContext as OsmesaContext

            return OsmesaContext  # type: ignore[no-any-return]
        from mujoco.gl_context import GLContext

        return GLContext  # type: ignore[no-any-return]
    except (ImportError, RuntimeError, AttributeError) as exc:
        raise MeshPassError(
            f"MuJoCo cannot open an OpenGL context with MUJOCO_GL={backend!r} ({exc}); "
            "install Mesa EGL (libegl1, libgl1-mesa-dri) or set MUJOCO_GL=osmesa with libosmesa6"
        ) from exc


class MeshPass:
    """Offscreen MuJoCo renderer for RGB + metric depth; one GL context, reused for every size.

    The GL context and MuJoCo's render context are made once (creating them is slow) and
    the render context is rebuilt only when the model object changes (a recompile).
    """

    def __init__(self, *, shadows: bool = False, antialias: bool = False, max_geom: int = MAX_SCENE_GEOMS) -> None:
        # Shadows cost a second full pass (3-4x the frame time in software GL), so off by
        # default; the sun still shades faces by their normals.
        self.shadows = shadows
        # 4x multisampling makes software GL about 3.4x slower (140 vs 42 ms at 640x360), and
        # splats blended over mesh edges soften them anyway.
        self.samples = ANTIALIAS_SAMPLES if antialias else 0
        self.max_geom = max_geom
        self._gl: Any = None
        self._model: mujoco.MjModel | None = None  # the model the GL context was made for
        self._context: mujoco.MjrContext | None = None
        self._scene: mujoco.MjvScene | None = None
        self._scene_model: mujoco.MjModel | None = None
        self._filled: tuple[mujoco.MjModel, Camera, float] | None = None
        self._option = mujoco.MjvOption()
        self._thread_lock = threading.RLock()

    # Set-up ---------------------------------------------------------------------------------
    def _check_size(self, model: mujoco.MjModel, width: int, height: int) -> None:
        buffer = (int(model.vis.global_.offwidth), int(model.vis.global_.offheight))
        if width > buffer[0] or height > buffer[1]:
            raise MeshPassError(
                f"image {width}x{height} exceeds the model's offscreen buffer "
                f"{buffer[0]}x{buffer[1]}; render smaller or raise visual.global offwidth/offheight"
            )

    def _prepare_context(self, model: mujoco.MjModel) -> mujoco.MjrContext:
        """The render context for ``model`` (GL current), rebuilt only when the model changes."""
        if self._model is not model or self._context is None:
            if self._context is not None:
                self._context.free()
            # The render context reads its multisampling from the model; set it just for this.
            samples = int(model.vis.quality.offsamples)
            model.vis.quality.offsamples = self.samples
            try:
                font = mujoco.mjtFontScale.mjFONTSCALE_100.value
                self._context = mujoco.MjrContext(model, font)
            finally:
                model.vis.quality.offsamples = samples
            mujoco.mjr_setBuffer(mujoco.mjtFramebuffer.mjFB_OFFSCREEN.value, self._context)
            # Reversed Z (1 at near, 0 at far) keeps float depth precise far from the camera.
            self._context.readDepthMap = mujoco.mjtDepthMap.mjDEPTH_ZEROFAR
            self._model = model
        return self._context

    def close(self) -> None:
        """Free the GL resources (the pass can be used again afterwards)."""
        with self._thread_lock:
            if self._gl is not None:
                with self._gl.as_current():
                    if self._context is not None:
                        self._context.free()
                self._gl.free()
            self._gl, self._context, self._model = None, None, None
            self._scene, self._scene_model, self._filled = None, None, None

    # Rendering ------------------------------------------------------------------------------
    def render(
        self,
        model: mujoco.MjModel,
        data: mujoco.MjData,
        camera: Camera,
        *,
        lock: _Locker | AbstractContextManager[Any] | None = None,
        hidden_bodies: Collection[int] = (),
        scene_hook: SceneHook | None = None,
    ) -> MeshImage:
        """Draw ``model``/``data`` through ``camera``: `fill`, then `draw`.

        Args:
            model, data: the MuJoCo world; only read (never stepped or edited).
            camera: the pinhole camera; its near/far are the GL clip planes.
            lock: held while MuJoCo's scene is filled from ``data`` (the simulation's lock
                when another thread steps it); the GL drawing runs outside it.
            hidden_bodies: body ids whose geoms (and their subtrees') are not drawn, e.g.
                the mesh proxies of assets drawn as splats.
            scene_hook: called with the filled MjvScene before drawing (lights, extra geoms).
        """
        with self._thread_lock:
            self.fill(model, data, camera, lock=lock, hidden_bodies=hidden_bodies, scene_hook=scene_hook)
            return self.draw()

    def fill(
        self,
        model: mujoco.MjModel,
        data: mujoco.MjData,
        camera: Camera,
        *,
        lock: _Locker | AbstractContextManager[Any] | None = None,
        hidden_bodies: Collection[int] = (),
        scene_hook: SceneHook | None = None,
    ) -> None:
        """First half of `render` (same arguments): copy what to draw out of ``data`` into
        MuJoCo's scene. No GL is needed, so it runs on the caller's thread (under ``lock``)
        while `draw` may run on another; the next `fill` waits for nothing, so call them in
        pairs from one frame loop."""
        with self._thread_lock:
            t0 = time.perf_counter()
            self._check_size(model, camera.width, camera.height)
            if self._scene is None or self._scene_model is not model:
                self._scene = mujoco.MjvScene(model, maxgeom=self.max_geom)
                self._scene_model = model
            scene = self._scene
            free_camera = mujoco.MjvCamera()
            mujoco.mjv_defaultFreeCamera(model, free_camera)
            with lock if lock is not None else nullcontext():
                mujoco.mjv_updateScene(model, data, self._option, None, free_camera,
                                       mujoco.mjtCatBit.mjCAT_ALL.value, scene)  # fmt: skip
            if hidden_bodies:
                _hide_bodies(model, scene, hidden_bodies)
            frustum = gl_camera_frustum(camera)
            for gl_camera in scene.camera:
                for name, value in frustum.items():
                    setattr(gl_camera, name, value)
            for light in scene.lights[: scene.nlight]:
                if light.headlight:  # MuJoCo placed it at the free camera; follow ours instead
                    light.pos, light.dir = frustum["pos"], frustum["forward"]
            scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = self.shadows
            # The sky, haze and fog are the appearance code's job (they must cover splats too).
            scene.flags[mujoco.mjtRndFlag.mjRND_SKYBOX] = False
            scene.flags[mujoco.mjtRndFlag.mjRND_FOG] = False
            scene.flags[mujoco.mjtRndFlag.mjRND_HAZE] = False
            if scene_hook is not None:
                scene_hook(scene)
            self._filled = (model, camera, 1e3 * (time.perf_counter() - t0))

    def draw(self) -> MeshImage:
        """Second half of `render`: draw the scene the last `fill` made and read back RGB and
        depth. The GL context is current only while drawing, so any thread may call it."""
        with self._thread_lock:
            if self._filled is None or self._scene is None:
                raise MeshPassError("draw() needs a fill() first: it draws the scene fill() made")
            model, camera, scene_ms = self._filled
            self._filled = None
            if self._gl is None:
                buffer = (int(model.vis.global_.offwidth), int(model.vis.global_.offheight))
                self._gl = _context_class()(*buffer)
            with self._gl.as_current():
                image = self._draw(model, camera, self._scene)
            image.timings = {"mesh_scene": scene_ms, **image.timings}
            image.timings["mesh"] += scene_ms
            return image

    def _draw(self, model: mujoco.MjModel, camera: Camera, scene: mujoco.MjvScene) -> MeshImage:
        width, height = camera.width, camera.height
        t1 = time.perf_counter()
        context = self._prepare_context(model)
        rect = mujoco.MjrRect(0, 0, width, height)
        mujoco.mjr_render(rect, scene, context)
        rgb8 = np.empty((height, width, 3), np.uint8)
        buffer = np.empty((height, width), np.float32)
        mujoco.mjr_readPixels(rgb8, buffer, rect, context)
        t2 = time.perf_counter()
        # GL rows start at the bottom of the image.
        rgb = np.flipud(rgb8).astype(np.float32) * np.float32(1.0 / 255.0)
        reversed_z = np.flipud(buffer).astype(np.float64)
        hit = reversed_z > 0.0
        near, far = camera.near, camera.far
        with np.errstate(divide="ignore"):
            # Reversed Z stores (n/z - n/f) / (1 - n/f): 1 at the near plane, 0 at the far one.
            depth = near * far / (reversed_z * (far - near) + near)
        depth32 = np.where(hit, depth, np.inf).astype(np.float32)
        rgb[~hit] = 0.0
        t3 = time.perf_counter()
        timings = {"mesh_draw": 1e3 * (t2 - t1), "mesh_convert": 1e3 * (t3 - t2), "mesh": 1e3 * (t3 - t1)}
        return MeshImage(rgb=np.ascontiguousarray(rgb), depth=depth32, hit=hit, timings=timings)


def _hide_bodies(model: mujoco.MjModel, scene: mujoco.MjvScene, bodies: Collection[int]) -> None:
    """Stop geoms of ``bodies`` and their subtrees from drawing (type NONE is skipped)."""
    wanted = np.zeros(model.nbody, dtype=bool)
    wanted[list(bodies)] = True
    # A body is hidden when it or any ancestor is; walk up by parent id (parents come first).
    hidden = wanted.copy()
    for body in range(1, model.nbody):
        hidden[body] |= hidden[model.body_parentid[body]]
    geom_type = int(mujoco.mjtObj.mjOBJ_GEOM)
    for geom in scene.geoms[: scene.ngeom]:
        if geom.objtype == geom_type and hidden[model.geom_bodyid[geom.objid]]:
            geom.type = int(mujoco.mjtGeom.mjGEOM_NONE)
