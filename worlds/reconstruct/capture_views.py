"""A synthetic camera capture the project makes itself: a known mesh scene seen from a ring.

A small drivetwin ``Scene`` (ground plus a few catalog assets) is compiled with the MuJoCo
adapter and drawn by the mesh pass from cameras on rings around a target, giving posed
images, metric depths and a sparse coloured point cloud (depth samples back-projected to
the world, as an SfM cloud would be: points on visible surfaces with their pixel colours).
The lighting is made view-independent (no headlight diffuse, no specular), so a splat fit
with view-independent colour can match the images and a held-out-view PSNR measures the
fit, not the shading model.

Flat-coloured geoms give SIFT almost nothing to match, so ``textured=True`` puts MuJoCo's
own builtin textures on them (a checker strewn with random dark marks, tinted by each
geom's colour): structure from motion can then pose the views from the images alone.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np
import numpy.typing as npt
from drivetwin.worlds.catalog import category
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.mesh_pass import MeshPass
from drivetwin.worlds.scene import AssetInstance, Bounds, PhysicsProps, Pose, Scene

from .views import PosedImages, PosedView, ViewsError

__all__ = ["SyntheticCapture", "capture_ring", "capture_scene", "ring_cameras"]

F32 = npt.NDArray[np.float32]

# The ego is required by a Scene; it is parked far outside every view of the capture.
_EGO_PARKING = (-40.0, -40.0)
_CAPTURE_BOUNDS = Bounds(xmin=-50.0, xmax=50.0, ymin=-50.0, ymax=50.0)
# (id, category, x, y, yaw): a cone, a bin and a bench within a metre of the origin.
_DEFAULT_ASSETS = (
    ("traffic_cone_1", "traffic_cone", 0.55, 0.35, 0.0),
    ("trash_bin_1", "trash_bin", -0.5, -0.45, 0.0),
    ("bench_1", "bench", -0.1, 0.85, 0.3),
)


@dataclass(eq=False)
class SyntheticCapture:
    """Posed images of a known scene with their true depths [V][H,W] (camera z, m; inf = sky)."""

    images: PosedImages
    depths: list[F32] = field(repr=False)
    scene: Scene = field(repr=False)


def capture_scene(assets: Sequence[tuple[str, str, float, float, float]] = _DEFAULT_ASSETS) -> Scene:
    """A small scene: default ground and static catalog assets given as (id, category, x, y, yaw)."""
    ego = AssetInstance(id="ego", category="ego_vehicle", pose=Pose(x=_EGO_PARKING[0], y=_EGO_PARKING[1]),
                        physics=PhysicsProps(mass=category("ego_vehicle").mass))  # fmt: skip
    placed = [
        AssetInstance(
            id=asset_id,
            category=name,
            pose=Pose(x=x, y=y, yaw=yaw),
            physics=PhysicsProps(mass=category(name).mass, dynamic=False),
        )
        for asset_id, name, x, y, yaw in assets
    ]
    return Scene(name="synthetic_capture", bounds=_CAPTURE_BOUNDS, ego=ego, assets=placed)


def ring_cameras(
    target: Sequence[float],
    *,
    radius: float,
    heights: Sequence[float],
    per_ring: int,
    width: int,
    height: int,
    fovy_deg: float,
) -> list[Camera]:
    """Cameras on horizontal rings (one per height, metres above the target) looking at ``target``.

    Rings are staggered by half a step so no two cameras share an azimuth.
    """
    if radius <= 0 or per_ring < 1 or not heights:
        raise ViewsError("rings need radius > 0, per_ring >= 1 and at least one height")
    centre = np.asarray(target, dtype=np.float64)
    cameras = []
    for ring, dz in enumerate(heights):
        for k in range(per_ring):
            angle = 2.0 * math.pi * (k + 0.5 * (ring % 2)) / per_ring
            eye = centre + np.array([radius * math.cos(angle), radius * math.sin(angle), dz])
            cameras.append(Camera.from_look_at(eye, centre, width=width, height=height, fovy_deg=fovy_deg))
    return cameras


# Textured mode. The ground's texture repeats every 4 m, the assets' every 2 m: more than a
# view or an asset spans, so no repeat makes two places look alike to the matcher.
_GROUND_TILE_M, _ASSET_TILE_M = 4.0, 2.0
# Texels per tile: 6 cm on the ground, 3 cm on assets, 2-3 px at 3 m in a 200x150 view,
# the scale at which SIFT finds blobs without the texture blurring to grey.
_TEXELS = 64
# Share of texels marked dark: 0.5 gives the most contrast between neighbouring patches
# (on a 16-view ring at 200x150, 0.3 left 5 of 16 views unregistered).
_MARK_PROBABILITY = 0.5
_LIGHT, _SHADE, _MARK = (0.95, 0.95, 0.95), (0.55, 0.55, 0.55), (0.08, 0.08, 0.08)


def _add_textures(spec: mujoco.MjSpec) -> None:
    """Give every geom of ``spec`` a builtin random-marked checker material (tinted by its rgba)."""
    for name, tile in (("capture_ground", _GROUND_TILE_M), ("capture_asset", _ASSET_TILE_M)):
        spec.add_texture(name=name, type=mujoco.mjtTexture.mjTEXTURE_2D, builtin=mujoco.mjtBuiltin.mjBUILTIN_CHECKER,
                         width=_TEXELS, height=_TEXELS, rgb1=list(_LIGHT), rgb2=list(_SHADE),
                         mark=mujoco.mjtMark.mjMARK_RANDOM, random=_MARK_PROBABILITY, markrgb=list(_MARK))  # fmt: skip
        # texuniform: repeats per metre, so the texel size is the same on every geom.
        material = spec.add_material(name=name, texuniform=True, texrepeat=[1.0 / tile, 1.0 / tile])
        material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = name
    for geom in spec.geoms:
        geom.material = "capture_ground" if geom.name == "ground" else "capture_asset"


def _lambertian(scene: mujoco.MjvScene) -> None:
    """Scene hook: lights without specular highlights and a headlight that only adds ambient."""
    for light in scene.lights[: scene.nlight]:
        light.specular[:] = 0.0
        if light.headlight:
            light.diffuse[:] = 0.0


def _back_project(camera: Camera, depth: F32, rgb: F32, count: int, rng: np.random.Generator) -> tuple[F32, F32]:
    """``count`` random covered pixels of one view as world points [n,3] and their colours [n,3]."""
    rows, cols = np.nonzero(np.isfinite(depth))
    if len(rows) == 0:
        return np.zeros((0, 3), np.float32), np.zeros((0, 3), np.float32)
    pick = rng.choice(len(rows), size=min(count, len(rows)), replace=False)
    r, c = rows[pick], cols[pick]
    z = depth[r, c].astype(np.float64)
    x = (c + 0.5 - camera.cx) / camera.fx * z
    y = (r + 0.5 - camera.cy) / camera.fy * z
    cam_points = np.stack([x, y, z, np.ones_like(z)], 1)
    world = (cam_points @ camera.camera_to_world.T)[:, :3]
    return world.astype(np.float32), rgb[r, c].astype(np.float32)


def capture_ring(
    *,
    scene: Scene | None = None,
    target: Sequence[float] = (0.0, 0.0, 0.35),
    radius: float = 3.0,
    heights: Sequence[float] = (1.6, 2.6),
    per_ring: int = 12,
    width: int = 64,
    height: int = 48,
    fovy_deg: float = 45.0,
    points_per_view: int = 60,
    seed: int = 0,
    textured: bool = False,
) -> SyntheticCapture:
    """Render ``scene`` (default ``capture_scene()``) from ring cameras around ``target``.

    Returns the posed views (named ``view_000`` ...), each view's metric depth, and a sparse
    cloud of ``points_per_view`` back-projected depth samples per view with pixel colours.
    ``textured`` draws the ground and assets with builtin textures instead of flat colours
    (for structure from motion; e.g. 16 views of 200x150 from 2 m above a 3 m ring).
    Deterministic for a seed; needs the mesh pass's OpenGL (Mesa EGL on a CPU machine).
    """
    world_scene = scene if scene is not None else capture_scene()
    world = MujocoWorld.from_scene(world_scene)
    model, data = world.model, world.data
    if textured:
        _add_textures(world.spec)
        model = world.spec.compile()
        data = mujoco.MjData(model)
        mujoco.mj_forward(model, data)
    cameras = ring_cameras(target, radius=radius, heights=heights, per_ring=per_ring, width=width,
                           height=height, fovy_deg=fovy_deg)  # fmt: skip
    rng = np.random.default_rng(seed)
    mesh_pass = MeshPass()
    views, depths, points, colors = [], [], [], []
    try:
        for index, camera in enumerate(cameras):
            image = mesh_pass.render(model, data, camera, scene_hook=_lambertian)
            views.append(PosedView(f"view_{index:03d}", image.rgb, camera))
            depths.append(image.depth)
            pts, cols = _back_project(camera, image.depth, image.rgb, points_per_view, rng)
            points.append(pts)
            colors.append(cols)
    finally:
        mesh_pass.close()
    posed = PosedImages(views, np.concatenate(points), np.concatenate(colors))
    return SyntheticCapture(images=posed, depths=depths, scene=world_scene)
