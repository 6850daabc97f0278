"""Terrain as a height field: a regular grid of ground heights, read from a world package and
collided by MuJoCo.

Reconstruction writes one (drivetwin.worlds.reconstruct.collision builds it from ground points
or a mesh); a world package keeps it as ``collision/heightfield.npz``; `add_collision_geoms`
puts it, and an asset's convex hulls, into an MjSpec.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

if TYPE_CHECKING:
    import mujoco
    import trimesh

__all__ = [
    "HEIGHTFIELD_BASE_M",
    "CollisionError",
    "Heightfield",
    "add_collision_geoms",
    "load_heightfield",
]

F64 = npt.NDArray[np.float64]
# MuJoCo needs a positive elevation range even for flat ground, and a solid base under it.
MIN_ELEVATION_RANGE_M = 1e-3
HEIGHTFIELD_BASE_M = 0.5


class CollisionError(ValueError):
    """Collision geometry that cannot be built from what was given, and what is allowed."""


@dataclass
class Heightfield:
    """Ground heights on a regular grid: ``heights[r, c]`` is at (x0 + c·cell, y0 + r·cell).

    ``heights`` is float32 [rows, cols] in metres (absolute, z up); ``origin`` is
    (x0, y0, z0) with z0 the lowest height; ``cell`` the grid spacing in metres.
    """

    heights: npt.NDArray[np.float32]
    origin: F64
    cell: float

    def height_at(self, x: float, y: float) -> float:
        """The bilinearly interpolated height at (x, y), clamped to the grid."""
        rows, cols = self.heights.shape
        u = float(np.clip((x - self.origin[0]) / self.cell, 0, cols - 1))
        v = float(np.clip((y - self.origin[1]) / self.cell, 0, rows - 1))
        c0, r0 = min(int(u), max(cols - 2, 0)), min(int(v), max(rows - 2, 0))
        c1, r1 = min(c0 + 1, cols - 1), min(r0 + 1, rows - 1)
        fu, fv = u - c0, v - r0
        h = self.heights.astype(np.float64)
        bottom = h[r0, c0] * (1 - fu) + h[r0, c1] * fu
        top = h[r1, c0] * (1 - fu) + h[r1, c1] * fu
        return float(bottom * (1 - fv) + top * fv)

    def save(self, path: str | Path) -> Path:
        """Write ``heights``, ``origin`` and ``cell`` to an .npz file; the path."""
        target = Path(path)
        target.parent.mkdir(parents=True, exist_ok=True)
        np.savez(target, heights=self.heights.astype(np.float32), origin=self.origin.astype(np.float64),
                 cell=np.float64(self.cell))  # fmt: skip
        return target


def load_heightfield(path: str | Path) -> Heightfield:
    """Read a height field written by `Heightfield.save`."""
    source = Path(path)
    if not source.is_file():
        raise CollisionError(f"height field file not found: {source}")
    with np.load(source) as archive:
        missing = {"heights", "origin", "cell"} - set(archive.files)
        if missing:
            raise CollisionError(f"{source.name} lacks {sorted(missing)}; a height field has heights, origin, cell")
        return Heightfield(archive["heights"].astype(np.float32), archive["origin"].astype(np.float64),
                           float(archive["cell"]))  # fmt: skip


def add_collision_geoms(
    spec: mujoco.MjSpec,
    *,
    heightfield: Heightfield | None = None,
    hulls: Sequence[trimesh.Trimesh] = (),
    prefix: str = "reconstructed",
    body: mujoco.MjsBody | None = None,
) -> list[mujoco.MjsGeom]:
    """Add a height field geom and one mesh geom per convex hull to `spec` (world body by default).

    Hull vertices are in the body's frame (the world frame for the world body). The height
    field keeps its absolute heights: its geom sits at z0 with a `HEIGHTFIELD_BASE_M` base.
    """
    import mujoco  # here, not at the top: the catalog reads packages at start-up, MuJoCo is not needed yet

    parent = spec.worldbody if body is None else body
    geoms: list[mujoco.MjsGeom] = []
    if heightfield is not None:
        geoms.append(_add_heightfield(spec, parent, heightfield, f"{prefix}/ground"))
    for number, hull in enumerate(hulls):
        name = f"{prefix}/hull_{number:03d}"
        vertices = np.asarray(hull.vertices, dtype=np.float64)
        if len(vertices) < 4:
            raise CollisionError(f"hull {number} has {len(vertices)} vertices; a convex hull needs at least 4")
        spec.add_mesh(name=name, uservert=vertices.ravel().tolist(), userface=np.asarray(hull.faces).ravel().tolist())
        geoms.append(parent.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_MESH, meshname=name))
    if not geoms:
        raise CollisionError("nothing to add: give a height field, hulls or both")
    return geoms


def _add_heightfield(spec: mujoco.MjSpec, parent: mujoco.MjsBody, field: Heightfield, name: str) -> mujoco.MjsGeom:
    import mujoco

    rows, cols = field.heights.shape
    if rows < 2 or cols < 2:
        raise CollisionError(f"a height field needs at least 2 x 2 cells, got {rows} x {cols}")
    heights = field.heights.astype(np.float64)
    low = float(heights.min())
    span = max(float(heights.max()) - low, MIN_ELEVATION_RANGE_M)
    # MuJoCo's hfield spans [-rx, rx] x [-ry, ry] around its geom, nodes on the corners, row 0 at -y.
    half_x, half_y = (cols - 1) * field.cell / 2, (rows - 1) * field.cell / 2
    spec.add_hfield(name=name, size=[half_x, half_y, span, HEIGHTFIELD_BASE_M], nrow=rows, ncol=cols,
                    userdata=((heights - low) / span).ravel().tolist())  # fmt: skip
    centre = [field.origin[0] + half_x, field.origin[1] + half_y, low]
    return parent.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_HFIELD, hfieldname=name, pos=centre)
