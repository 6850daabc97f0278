"""Procedural splats for scenes without a capture: building facades and catalog assets.

`facade_splats` covers every building's walls with splats (windows in rows) floating just
outside the wall mesh, which stays the collider; `asset_splats` covers a catalog category's
parts (or returns a reconstructed asset package's own splats), in the body frame, for the
hybrid renderer's ``attachments``.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt
from drivetwin.worlds.catalog import category
from drivetwin.worlds.packages import package_splats
from drivetwin.worlds.scene import Scene

from .splats import SH_C0, Splats

__all__ = ["asset_splats", "facade_splats"]

# Procedural splats: size (x sample spacing) and opacity that close gaps without blur.
SPLAT_SIZE, SPLAT_OPACITY_LOGIT, SPLAT_TEXTURE = 0.6, 2.5, 0.06
FACADE_OFFSET_M = 0.05  # facade splats float this far out, so the wall mesh does not hide them
WINDOW_PITCH_M = (3.0, 3.5)  # window spacing along a wall and between floors
WINDOW_FRACTION = (0.55, 0.45)  # share of each pitch that is glass
WINDOW_RGB = (0.16, 0.2, 0.27)
# Facades carry the shading of a capture made with light from the south-east (x east,
# y north): walls facing it are lit fully, walls facing away keep FACADE_AMBIENT of their
# colour, so a building's faces stay distinguishable as a captured one's would.
CAPTURE_LIGHT_XY = (0.6, -0.8)
FACADE_AMBIENT = 0.62


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
            facing = max(0.0, float(normal @ np.asarray(CAPTURE_LIGHT_XY)))
            shade = FACADE_AMBIENT + (1.0 - FACADE_AMBIENT) * facing
            wall = np.asarray(building.rgba[:3], np.float64) * shade
            colours.append(np.where(window[:, None], np.asarray(WINDOW_RGB) * shade, wall))
    if not points:
        return Splats.empty()
    return _splats(np.concatenate(points), np.concatenate(colours), spacing_m, rng)


def asset_splats(category_name: str, *, scale: float = 1.0, spacing_m: float = 0.08,
                 seed: int = 0) -> Splats:  # fmt: skip
    """Body-frame splats covering a catalog category's parts (for `attachments`), so an
    asset can be drawn as splats while its MuJoCo geoms stay its collision proxy."""
    # Reconstructed asset package: its own fitted splats.
    package = category(category_name).package
    if package is not None:
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
