"""The hybrid renderer: MuJoCo meshes and Gaussian splats in one frame, depth-correct.

Per frame: (1) the mesh pass draws the world's geoms (RGB + camera-z depth); (2) splat
assets are posed on their MuJoCo bodies (T_body applied to body-frame splats) and joined
with the splat background; (3) splats are rasterized with the mesh depth as a limit, so a
splat behind the mesh surface at a pixel is dropped there; (4) the mesh colour (or the sky
where no mesh is) is blended under the splats with the transmittance they leave:
rgb = rgb_splat + T * rgb_mesh; (5) the environment's weather and exposure are applied.
A splat asset's own MuJoCo geoms (its collision proxy) are not drawn.

With the CPU rasterizer, (1) runs on a thread of its own while (3) projects and sorts the
splats, and (3) then culls splats behind each tile's mesh before compositing. Bodies that
did not move keep their posed splats from the last frame. A world package draws its own
splats (Scene.package); without a capture, the scene's buildings get procedural facade
splats (`procedural.facade_splats`). Cameras live in `viewpoints`, procedural splats in
`procedural`; both are re-exported here.
"""

from __future__ import annotations

import functools
import math
import threading
import time
from collections.abc import Mapping
from concurrent.futures import ThreadPoolExecutor
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal, cast

import numpy as np
import numpy.typing as npt
from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld, UnknownBodyError
from drivetwin.worlds.packages import SPLATS_FILE, package_splats
from drivetwin.worlds.scene import Environment, Scene

from ._numba_post import blend_layers
from ._numba_raster import composite_splats, project_splats
from .camera import Camera
from .look import (
    HEADLAMP_RGB,
    LAMP_RGB,
    Lamp,
    Look,
    finish,
    lamp_irradiance,
    light_hook,
    look_of,
    sky_image,
)
from .look import world_points as _world_points
from .mesh_pass import MeshImage, MeshPass
from .procedural import asset_splats, facade_splats
from .rasterize import (
    ALPHA_MIN,
    INDEX_MIN_ALPHA,
    BackendName,
    RasterOutput,
    available_backends,
    check_splats,
    rasterize,
)
from .splats import Splats
from .viewpoints import chase_camera, default_camera

__all__ = [
    "Composite",
    "Frame",
    "HybridRenderer",
    "asset_splats",
    "chase_camera",
    "default_camera",
    "facade_splats",
    "lamps_of",
    "save_frame",
]  # fmt: skip

F32 = npt.NDArray[np.float32]
STREET_LIGHT = "street_light"
# A pixel's depth is the splats' when they cover at least this much of it, else the mesh's.
SPLAT_DEPTH_ALPHA = 0.5
# Vehicle lamps sit this far up the body and this far in from its sides (fractions).
HEADLAMP_HEIGHT, HEADLAMP_INSET = 0.4, 0.3
HEADLAMP_PITCH = -0.12  # radians: dipped beams point a little down
DEPTH_PNG_MAX_MM = 65_535  # 16-bit depth PNGs saturate at 65.5 m


@dataclass
class Frame:
    """A rendered frame: rgb uint8 [H,W,3], depth float32 [H,W] camera z in metres
    (inf where only sky), and per-stage timings in milliseconds."""

    rgb: npt.NDArray[np.uint8]
    depth: npt.NDArray[np.float32]
    timings: dict[str, float] = field(default_factory=dict)


@dataclass
class Composite:
    """The layers of a frame before weather: float rgb [H,W,3] (0..1 nominal), depth,
    the mesh image, the splat raster (None without splats), the layer under the splats
    (mesh colour, else sky), and the Look and lamps the environment asked for."""

    rgb: npt.NDArray[np.float32]
    depth: npt.NDArray[np.float32]
    mesh: MeshImage
    raster: RasterOutput | None
    layer: npt.NDArray[np.float32]
    look: Look
    lamps: list[Lamp]
    sim_time: float
    timings: dict[str, float] = field(default_factory=dict)


def _existing_bodies(world: MujocoWorld, asset_ids: Mapping[str, Splats]) -> dict[str, int]:
    """Body ids of the assets still in the world (a removed asset's splats are not drawn)."""
    bodies = {}
    for asset_id in asset_ids:
        try:
            bodies[asset_id] = world.body_id(asset_id)
        except UnknownBodyError:
            continue
    return bodies


def _body_transform(xpos: npt.ArrayLike, xmat: npt.ArrayLike) -> npt.NDArray[np.float64]:
    transform = np.eye(4)
    transform[:3, :3] = np.asarray(xmat, dtype=np.float64).reshape(3, 3)
    transform[:3, 3] = np.asarray(xpos, dtype=np.float64)
    return transform


def lamps_of(world: MujocoWorld, look: Look) -> list[Lamp]:
    """The lamps that are on: street-light heads and vehicle headlamps at their live poses.

    Reads ``world.data``: call it under the simulation's lock when another thread steps it.
    """
    lamps: list[Lamp] = []
    data = world.data
    for asset in world.scene.all_assets():
        cat = category(asset.category)
        street = asset.category == STREET_LIGHT and look.street_lights
        vehicle = cat.motion == "vehicle" and look.vehicle_lights
        if not (street or vehicle):
            continue
        try:
            body = world.body_id(asset.id)
        except UnknownBodyError:
            continue
        transform = _body_transform(data.xpos[body], data.xmat[body])
        if street:
            # The lamp head is the catalog part with the brightest colour.
            head = max(cat.parts, key=lambda part: sum(part.rgba[:3]))
            local = np.array([*head.pos, 1.0])
            local[:3] *= asset.scale
            lamps.append(Lamp(_point(transform @ local), (0.0, 0.0, -1.0), LAMP_RGB, "street"))
            continue
        ahead = np.array([math.cos(HEADLAMP_PITCH), 0.0, math.sin(HEADLAMP_PITCH)])
        direction = transform[:3, :3] @ ahead
        for side in (-1.0, 1.0):
            local = np.array([cat.length / 2, side * cat.width * (0.5 - HEADLAMP_INSET),
                              cat.height * HEADLAMP_HEIGHT]) * asset.scale  # fmt: skip
            position = _point(transform @ np.append(local, 1.0))
            lamps.append(Lamp(position, _point(direction), HEADLAMP_RGB, "vehicle"))
    return lamps


def _point(values: npt.ArrayLike) -> tuple[float, float, float]:
    x, y, z = (float(v) for v in np.asarray(values).reshape(-1)[:3])
    return (x, y, z)


class HybridRenderer:
    """Draws a MujocoWorld's meshes together with splat background and splat assets.

    Args:
        world: the MuJoCo world (its model/data are read each frame, so recompiles are fine).
        background: splats in the world frame (a reconstructed scene); "facades" (default)
            for the splats of the scene's world package when it has one, else procedural
            facade splats on the scene's buildings (`facade_splats`, rebuilt when the
            buildings change), the stand-in for a capture; None for no background.
        attachments: asset id -> splats in that asset's body frame; they follow the body and
            the body's own geoms are not drawn (they remain its collision proxy).
        lock: the simulation's lock when another thread steps the world.
        shadows: draw mesh shadows (about 3x the mesh-pass time in software GL).
        antialias: multisample the mesh pass (about 3x its time in software GL).
        backend: the splat rasterizer backend (see `rasterize`).
        seed: seed of the weather particles (same seed and sim time, same frame).
    """

    def __init__(
        self,
        world: MujocoWorld,
        *,
        background: Splats | Literal["facades"] | None = "facades",
        attachments: Mapping[str, Splats] | None = None,
        lock: threading.Lock | AbstractContextManager[Any] | None = None,
        shadows: bool = False,
        antialias: bool = False,
        backend: BackendName = "auto",
        seed: int = 0,
    ) -> None:
        self.world = world
        self.background = background
        self.attachments: dict[str, Splats] = dict(attachments or {})
        for asset_id in self.attachments:
            world.body_id(asset_id)  # raises UnknownBodyError naming the known assets
        self.lock = lock
        self.backend: BackendName = backend
        self.seed = seed
        self.mesh_pass = MeshPass(shadows=shadows, antialias=antialias)
        self._posing = _PosedSplats()
        self._mesh_thread: ThreadPoolExecutor | None = None
        self._frame_lock = threading.Lock()

    def close(self) -> None:
        """Free the GL resources and the mesh-pass thread."""
        if self._mesh_thread is not None:
            self._mesh_thread.submit(self.mesh_pass.close).result()
            self._mesh_thread.shutdown()
            self._mesh_thread = None
        self.mesh_pass.close()

    def render(self, camera: Camera, environment: Environment | None = None, *, time_s: float | None = None) -> Frame:
        """Draw one frame through ``camera`` under ``environment`` (default: the scene's).

        ``time_s`` animates rain and snow; it defaults to the simulation time.
        """
        t0 = time.perf_counter()
        comp = self.compose(camera, environment)
        t1 = time.perf_counter()
        out = finish(comp.rgb, comp.depth, camera, comp.look, comp.lamps, seed=self.seed,
                     time_s=comp.sim_time if time_s is None else time_s)  # fmt: skip
        t2 = time.perf_counter()
        timings = {**comp.timings, "appearance": 1e3 * (t2 - t1), "total": 1e3 * (t2 - t0)}
        return Frame(rgb=out, depth=comp.depth, timings=timings)

    def compose(self, camera: Camera, environment: Environment | None = None) -> Composite:
        """Steps 1-4 of a frame (meshes, posed splats, depth test, blend), before weather.

        MuJoCo's scene is filled on this thread (under ``lock``); with the numba backend the
        mesh pass then draws on its own thread while the splats are projected and
        depth-sorted (both release the GIL); binning and compositing, which need the mesh
        depth, follow.
        """
        t0 = time.perf_counter()
        world = self.world
        env = environment if environment is not None else world.scene.environment
        look = look_of(env)
        with self.lock if self.lock is not None else nullcontext():
            model, data = world.model, world.data
            sim_time = float(data.time)
            bodies = _existing_bodies(world, self.attachments)
            poses = {a: _body_transform(data.xpos[b], data.xmat[b]) for a, b in bodies.items()}
            lamps = lamps_of(world, look)
        splats = self._posing.update(self._background_splats(), self.attachments, poses)
        t1 = time.perf_counter()
        hook = light_hook(look, lamps, _point(camera.position))
        hidden = list(bodies.values())
        backend = self._resolved_backend()
        timings: dict[str, float] = {"pose": 1e3 * (t1 - t0)}
        raster = None
        with self._frame_lock:  # one frame at a time: fill and draw come in pairs
            self.mesh_pass.fill(model, data, camera, lock=self.lock, hidden_bodies=hidden, scene_hook=hook)
            if splats is not None and backend == "numba":
                if self._mesh_thread is None:
                    self._mesh_thread = ThreadPoolExecutor(1, thread_name_prefix="drivetwin-mesh")
                mesh_job = self._mesh_thread.submit(self.mesh_pass.draw)
                try:
                    projected = project_splats(splats, camera)
                finally:
                    t_wait = time.perf_counter()
                    mesh = mesh_job.result()
                timings["mesh_wait"] = 1e3 * (time.perf_counter() - t_wait)
                raster = composite_splats(projected, camera, mesh.depth, INDEX_MIN_ALPHA, False)
            else:
                mesh = self.mesh_pass.draw()
                if splats is not None:
                    raster = rasterize(splats, camera, background=None, depth_limit=mesh.depth, backend=backend)
        t3 = time.perf_counter()
        rgb, depth, layer = self._blend(camera, look, lamps, mesh, raster)
        t4 = time.perf_counter()
        timings.update(mesh.timings)
        if raster is not None:
            timings.update({f"splat_{k}": v for k, v in raster.timings.items()})
        timings.update({"splats_and_mesh": 1e3 * (t3 - t1), "blend": 1e3 * (t4 - t3)})
        return Composite(rgb=rgb, depth=depth, mesh=mesh, raster=raster, layer=layer, look=look,
                         lamps=lamps, sim_time=sim_time, timings=timings)  # fmt: skip

    def _resolved_backend(self) -> BackendName:
        if self.backend != "auto":
            return self.backend
        return _auto_backend()

    def _background_splats(self) -> Splats | None:
        if self.background == "facades":
            return _facades_of(self.world.scene)
        return self.background

    @staticmethod
    def _blend(camera: Camera, look: Look, lamps: list[Lamp], mesh: MeshImage,
               raster: RasterOutput | None) -> tuple[F32, F32, F32]:  # fmt: skip
        """rgb, depth and the layer under the splats (mesh colour, else sky)."""
        sky = sky_image(camera, look)
        if raster is None:
            layer = np.where(mesh.hit[..., None], mesh.rgb, sky).astype(np.float32)
            return layer.copy(), mesh.depth, layer
        light = np.zeros((1, 1, 3), np.float32)  # not read unless lamps light the splats
        covered = raster.alpha > ALPHA_MIN
        use_light = bool(lamps) and bool(covered.any())
        if use_light:
            points = _world_points(np.where(covered, raster.depth, 0.0), camera)
            light = lamp_irradiance(points, lamps, covered)
        h, w = raster.alpha.shape
        rgb, depth, layer = (
            np.empty((h, w, 3), np.float32),
            np.empty((h, w), np.float32),
            np.empty((h, w, 3), np.float32),
        )
        blend_layers(raster.rgb, raster.alpha, raster.depth, light, use_light, mesh.rgb, mesh.hit, mesh.depth,
                     sky, np.asarray(look.splat_gain, np.float32), SPLAT_DEPTH_ALPHA, rgb, depth, layer)  # fmt: skip
        return rgb, depth, layer


class _PosedSplats:
    """The splats of one frame: background plus attachments at their bodies' poses.

    An attachment is transformed again only when its body moved, and the joined set is
    reused while nothing changed (most bodies stand still in most frames).
    """

    def __init__(self) -> None:
        self._posed: dict[str, tuple[bytes, Splats]] = {}
        self._key: tuple[object, ...] | None = None
        self._joined: Splats | None = None

    def update(self, background: Splats | None, attachments: Mapping[str, Splats],
               poses: Mapping[str, npt.NDArray[np.float64]]) -> Splats | None:  # fmt: skip
        """The joined splats (None when there are none); each part checked finite once."""
        parts = []
        for asset_id, pose in poses.items():
            pose_key = pose.tobytes()
            cached = self._posed.get(asset_id)
            if cached is None or cached[0] != pose_key or cached[1] is not attachments[asset_id]:
                local = attachments[asset_id]
                check_splats(local)
                cached = (pose_key, local.transformed(pose))
                self._posed[asset_id] = cached
            parts.append((asset_id, cached))
        for gone in set(self._posed) - set(poses):
            del self._posed[gone]
        key = (id(background), *((a, c[0], id(c[1])) for a, c in parts))
        if key != self._key:
            joined = [c[1] for _, c in parts if len(c[1])]
            if background is not None and len(background):
                check_splats(background)
                joined.insert(0, background)
            self._joined = None if not joined else joined[0] if len(joined) == 1 else Splats.concat(joined)
            self._key = key
        return self._joined


@functools.cache
def _auto_backend() -> BackendName:
    """The fastest backend here, probed once (a failed `import gsplat` is not cached by Python)."""
    return cast(BackendName, available_backends()[0])


_facade_cache: dict[int, tuple[object, Splats]] = {}


def _facades_of(scene: Scene) -> Splats | None:
    """The splats of ``scene``'s world package, else facade splats of its buildings (made once per set)."""
    if scene.package is not None and (Path(scene.package) / SPLATS_FILE).is_file():
        background = package_splats(scene.package)  # cached per file and modification time
        return background if len(background) else None
    buildings = tuple(scene.buildings)
    cached = _facade_cache.get(id(scene))
    if cached is None or cached[0] != buildings:
        cached = (buildings, facade_splats(scene))
        _facade_cache.clear()  # one live scene at a time; do not keep old ones alive
        _facade_cache[id(scene)] = cached
    splats = cached[1]
    return splats if len(splats) else None


# Saving -------------------------------------------------------------------------------------
def save_frame(frame: Frame, path_png: str | Path) -> dict[str, Path]:
    """Write ``frame`` as PATH.png, its depth as PATH_depth.npy (float32 metres, inf = sky)
    and PATH_depth.png (16-bit millimetres, 0 = no return, saturating at 65.535 m)."""
    from PIL import Image

    path = Path(path_png)
    if path.suffix.lower() != ".png":
        raise ValueError(f"save_frame writes PNG; give a path ending in .png, got {path.name!r}")
    path.parent.mkdir(parents=True, exist_ok=True)
    Image.fromarray(frame.rgb).save(path)
    npy = path.with_name(path.stem + "_depth.npy")
    np.save(npy, frame.depth)
    millimetres = np.where(np.isfinite(frame.depth), frame.depth * 1000.0, 0.0)
    depth16 = np.clip(np.round(millimetres), 0, DEPTH_PNG_MAX_MM).astype(np.uint16)
    depth_png = path.with_name(path.stem + "_depth.png")
    Image.fromarray(depth16).save(depth_png)
    return {"rgb": path, "depth_npy": npy, "depth_png": depth_png}
