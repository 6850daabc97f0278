"""The hybrid renderer: MuJoCo meshes and Gaussian splats in one frame, depth-correct.

Per frame: (1) the mesh pass draws the world's geoms (RGB + camera-z depth); (2) splat
assets are posed on their MuJoCo bodies (T_body applied to body-frame splats) and joined
with the splat background; (3) splats are rasterized with the mesh depth as a limit, so a
splat behind the mesh surface at a pixel is dropped there; (4) the mesh colour (or the sky
where no mesh is) is blended under the splats with the transmittance they leave:
rgb = rgb_splat + T * rgb_mesh; (5) the environment's weather and exposure are applied.
A splat asset's own MuJoCo geoms (its collision proxy) are not drawn.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Mapping
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld, UnknownBodyError
from drivetwin.worlds.scene import EGO_ID, Environment, Scene

from .appearance import (
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
from .appearance import world_points as _world_points
from .camera import Camera
from .mesh_pass import MeshImage, MeshPass
from .rasterize import BackendName, RasterOutput, rasterize
from .splats import SH_C0, Splats

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

STREET_LIGHT = "street_light"
# A pixel's depth is the splats' when they cover at least this much of it, else the mesh's.
SPLAT_DEPTH_ALPHA = 0.5
# Vehicle lamps sit this far up the body and this far in from its sides (fractions).
HEADLAMP_HEIGHT, HEADLAMP_INSET = 0.4, 0.3
HEADLAMP_PITCH = -0.12  # radians: dipped beams point a little down
# Default overview: look at the main landmark from this far back and this high up.
OVERVIEW_DISTANCE_M, OVERVIEW_HEIGHT_M, OVERVIEW_FOVY_DEG = 45.0, 22.0, 60.0
OVERVIEW_LANDMARK = "main intersection"
CHASE_BACK_M, CHASE_UP_M, CHASE_AHEAD_M = 8.0, 3.5, 10.0
DEPTH_PNG_MAX_MM = 65_535  # 16-bit depth PNGs saturate at 65.5 m
# Procedural splats: size (x sample spacing) and opacity that close gaps without blur.
SPLAT_SIZE, SPLAT_OPACITY_LOGIT, SPLAT_TEXTURE = 0.6, 2.5, 0.06
FACADE_OFFSET_M = 0.05  # facade splats float this far out, so the wall mesh does not hide them
WINDOW_PITCH_M = (3.0, 3.5)  # window spacing along a wall and between floors
WINDOW_FRACTION = (0.55, 0.45)  # share of each pitch that is glass
WINDOW_RGB = (0.16, 0.2, 0.27)


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
        background: splats in the world frame (a reconstructed scene), or None.
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
        background: Splats | None = None,
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

    def close(self) -> None:
        """Free the GL resources."""
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
        """Steps 1-4 of a frame (meshes, posed splats, depth test, blend), before weather."""
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
        splats = self._posed_splats(poses)
        t1 = time.perf_counter()
        hook = light_hook(look, lamps, _point(camera.position))
        hidden = list(bodies.values())
        mesh = self.mesh_pass.render(model, data, camera, lock=self.lock, hidden_bodies=hidden, scene_hook=hook)
        t2 = time.perf_counter()
        raster = None
        if splats is not None and len(splats):
            raster = rasterize(splats, camera, background=None, depth_limit=mesh.depth,
                               backend=self.backend)  # fmt: skip
        t3 = time.perf_counter()
        layer = np.where(mesh.hit[..., None], mesh.rgb, sky_image(camera, look))
        if raster is not None:
            lit = raster.rgb * np.asarray(look.splat_gain, np.float32)
            covered = raster.alpha > 1.0 / 255.0
            if lamps and covered.any():
                points = _world_points(np.where(covered, raster.depth, 0.0), camera)
                lit += raster.rgb * lamp_irradiance(points, lamps, covered)
            rgb = lit + raster.transmittance[..., None] * layer
            depth = np.where(raster.alpha >= SPLAT_DEPTH_ALPHA, raster.depth, mesh.depth)
        else:
            rgb, depth = layer, mesh.depth
        t4 = time.perf_counter()
        timings = {"pose": 1e3 * (t1 - t0), **mesh.timings}
        if raster is not None:
            timings.update({f"splat_{k}": v for k, v in raster.timings.items()})
        timings.update({"splats": 1e3 * (t3 - t2), "blend": 1e3 * (t4 - t3)})
        return Composite(rgb=rgb.astype(np.float32), depth=depth.astype(np.float32), mesh=mesh,
                         raster=raster, layer=layer.astype(np.float32), look=look, lamps=lamps,
                         sim_time=sim_time, timings=timings)  # fmt: skip

    def _posed_splats(self, poses: Mapping[str, npt.NDArray[np.float64]]) -> Splats | None:
        parts = [self.attachments[a].transformed(pose) for a, pose in poses.items()]
        if self.background is not None:
            parts.insert(0, self.background)
        if not parts:
            return None
        return parts[0] if len(parts) == 1 else Splats.concat(parts)


# Procedural splats -------------------------------------------------------------------------
def _splats(points: npt.NDArray[np.float64], rgb: npt.NDArray[np.float64], spacing: float,
            rng: np.random.Generator) -> Splats:  # fmt: skip
    """Round splats at ``points`` with ``rgb`` (a little per-splat variation, like texture)."""
    n = len(points)
    colour = np.clip(rgb * rng.uniform(1 - SPLAT_TEXTURE, 1 + SPLAT_TEXTURE, (n, 1)), 0.0, 1.0)
    f32 = np.float32
    sh = ((colour - 0.5) / SH_C0)[:, None, :].astype(f32)
    return Splats(means=points.astype(f32), quats=np.tile(np.array([1, 0, 0, 0], f32), (n, 1)),
                  log_scales=np.full((n, 3), math.log(SPLAT_SIZE * spacing), f32),
                  opacity_logits=np.full(n, SPLAT_OPACITY_LOGIT, f32), sh=sh)  # fmt: skip


def facade_splats(scene: Scene, *, spacing_m: float = 0.35, seed: int = 0) -> Splats:
    """A splat background for a Scene without a capture: every building's walls as splats
    with rows of windows, floating just outside the wall mesh (which stays the collider)."""
    rng = np.random.default_rng(seed)
    points, colours = [], []
    for building in scene.buildings:
        ring = np.asarray(building.footprint, dtype=np.float64)
        x, y = ring[:, 0], ring[:, 1]
        ccw = float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)) > 0
        for a, b in zip(ring, np.roll(ring, -1, axis=0), strict=True):
            length = float(np.linalg.norm(b - a))
            columns, rows = int(length / spacing_m), int(building.height / spacing_m)
            if columns == 0 or rows == 0:
                continue
            # A jittered grid: even cover without the holes and clumps of uniform sampling.
            grid = np.stack(np.meshgrid(np.arange(columns), np.arange(rows)), -1).reshape(-1, 2)
            cells = (grid + rng.uniform(0.25, 0.75, grid.shape)) * spacing_m
            along, up = cells[:, 0], cells[:, 1]
            direction = (b - a) / length
            normal = np.array([direction[1], -direction[0]]) * (1.0 if ccw else -1.0)
            xy = a + along[:, None] * direction + FACADE_OFFSET_M * normal
            points.append(np.column_stack([xy, up]))
            window = (
                ((along % WINDOW_PITCH_M[0]) < WINDOW_PITCH_M[0] * WINDOW_FRACTION[0])
                & ((up % WINDOW_PITCH_M[1]) > WINDOW_PITCH_M[1] * (1 - WINDOW_FRACTION[1]))
                & (up > WINDOW_PITCH_M[1])
            )
            wall = np.asarray(building.rgba[:3], np.float64)
            colours.append(np.where(window[:, None], WINDOW_RGB, wall))
    if not points:
        return Splats.empty()
    return _splats(np.concatenate(points), np.concatenate(colours), spacing_m, rng)


def asset_splats(category_name: str, *, scale: float = 1.0, spacing_m: float = 0.08,
                 seed: int = 0) -> Splats:  # fmt: skip
    """Body-frame splats covering a catalog category's parts (for `attachments`), so an
    asset can be drawn as splats while its MuJoCo geoms stay its collision proxy."""
    # Reconstructed asset package: its own fitted splats (drivetwin.worlds.reconstruct.package).
    package = category(category_name).package
    if package is not None:
        from drivetwin.worlds.reconstruct.package import package_splats

        return package_splats(package, scale=scale)
    rng = np.random.default_rng(seed)
    points, colours = [], []
    for part in category(category_name).parts:
        size = np.asarray(part.size, np.float64) * scale
        if part.shape == "box":
            area = 8 * (size[0] * size[1] + size[1] * size[2] + size[0] * size[2])
            count = max(8, int(area / spacing_m**2))
            local = rng.uniform(-1, 1, (count, 3))
            face = rng.choice(3, count, p=_face_weights(size))
            local[np.arange(count), face] = np.sign(local[np.arange(count), face])
            local *= size
        elif part.shape == "cylinder":
            radius, half = size[0], size[1]
            count = max(8, int((4 * math.pi * radius * half + 2 * math.pi * radius**2) / spacing_m**2))
            angle = rng.uniform(0, 2 * math.pi, count)
            on_side = rng.uniform(0, 1, count) < half / (half + radius / 2)
            r = np.where(on_side, radius, radius * np.sqrt(rng.uniform(0, 1, count)))
            z = np.where(on_side, rng.uniform(-half, half, count), half * rng.choice([-1, 1], count))
            local = np.column_stack([r * np.cos(angle), r * np.sin(angle), z])
            local = local[:, list(_CYLINDER_AXES[part.axis])]
        else:
            count = max(8, int(4 * math.pi * size[0] ** 2 / spacing_m**2))
            direction = rng.normal(size=(count, 3))
            local = size[0] * direction / np.linalg.norm(direction, axis=1, keepdims=True)
        points.append(local + np.asarray(part.pos) * scale)
        colours.append(np.tile(np.asarray(part.rgba[:3], np.float64), (count, 1)))
    return _splats(np.concatenate(points), np.concatenate(colours), spacing_m, rng)


def _face_weights(half: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """Chance that a box-surface sample lies on the faces normal to x, y, z (by area)."""
    areas = np.array([half[1] * half[2], half[0] * half[2], half[0] * half[1]])
    return np.asarray(areas / areas.sum(), dtype=np.float64)


# A z-axis cylinder's (x, y, z) columns reordered so its axis lies along x, y or z.
_CYLINDER_AXES = {"z": (0, 1, 2), "x": (2, 0, 1), "y": (0, 2, 1)}


# Cameras ------------------------------------------------------------------------------------
def default_camera(scene: Scene, width: int = 640, height: int = 360) -> Camera:
    """An elevated overview of the campus centre (its main landmark, else the bounds' centre)."""
    landmark = scene.landmark(OVERVIEW_LANDMARK)
    cx, cy = landmark.position if landmark is not None else scene.bounds.centre
    # Look from the south-east so the sun (south by day) lights the faces we see.
    back = OVERVIEW_DISTANCE_M / math.sqrt(2)
    eye = (cx + back, cy - back, OVERVIEW_HEIGHT_M)
    return Camera.from_look_at(eye, (cx, cy, 0.0), width=width, height=height,
                               fovy_deg=OVERVIEW_FOVY_DEG)  # fmt: skip


def chase_camera(world: MujocoWorld, asset_id: str = EGO_ID, *, width: int = 640, height: int = 360) -> Camera:
    """A camera behind and above an asset's live pose, looking past it along its heading."""
    pose = world.body_pose(asset_id)
    heading = (math.cos(pose.yaw), math.sin(pose.yaw))
    eye = (pose.x - CHASE_BACK_M * heading[0], pose.y - CHASE_BACK_M * heading[1],
           pose.z + CHASE_UP_M)  # fmt: skip
    target = (
        pose.x + CHASE_AHEAD_M * heading[0],
        pose.y + CHASE_AHEAD_M * heading[1],
        pose.z + 0.5,
    )
    return Camera.from_look_at(eye, target, width=width, height=height, fovy_deg=OVERVIEW_FOVY_DEG)


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
