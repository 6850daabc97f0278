"""Building collision geometry MuJoCo can use: a height field for the ground, convex hulls for objects.

MuJoCo collides a mesh geom by its convex hull, so a reconstructed scene mesh would collide
as one big blob. The ground becomes a height field (a regular grid of heights, holes under
objects filled from their surroundings) and each object is split into convex parts by
CoACD. The height field itself, and `add_collision_geoms` that puts both into an MjSpec,
are core: drivetwin.worlds.heightfield.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import numpy.typing as npt
import trimesh
from drivetwin.worlds.heightfield import CollisionError, Heightfield
from drivetwin.worlds.reconstruct import poisson
from drivetwin.worlds.reconstruct.pointclouds import PointCloud
from scipy import ndimage
from scipy.interpolate import griddata
from scipy.spatial import cKDTree

__all__ = [
    "closed_object_mesh",
    "convex_parts",
    "ground_mask",
    "heightfield_from_mesh",
    "heightfield_from_points",
    "write_hulls",
]

F64 = npt.NDArray[np.float64]
# A point is ground when it lies within this much of the lowest ground nearby (LIDAR noise
# plus kerb-free paving) and its surface faces up within about 37 degrees.
GROUND_BAND_M = 0.15
GROUND_MIN_NORMAL_Z = 0.8
# The "nearby" window is wider than half the largest object, so a car roof is never the lowest.
GROUND_WINDOW_M = 3.0
# Terrain may rise this much per metre across the window and still count as ground.
GROUND_MAX_SLOPE = 0.1
# CoACD's concavity threshold: 0.05 is its default, fine enough for cars at a few hulls each.
COACD_THRESHOLD = 0.05
DEFAULT_MAX_HULLS = 8
# CoACD's search is cut well below its defaults (150 iterations, 20 nodes, depth 3, 2000
# samples, manifold remesh at 50) and its input to 1,000 faces: on a loaded 2-core machine a
# reconstructed barrier then splits in about 12 s instead of 4 minutes.
COACD_MCTS_ITERATIONS = 20
COACD_MCTS_NODES = 10
COACD_MCTS_DEPTH = 2
COACD_RESOLUTION = 500
COACD_PREPROCESS_RESOLUTION = 20
COACD_INPUT_FACES = 1000
# Floor samples under an object lie within this many voxels of one of its points.
FLOOR_REACH_VOXELS = 2.0


def _grid_index(xy: F64, origin: F64, cell: float) -> npt.NDArray[np.intp]:
    return np.rint((xy - origin[:2]) / cell).astype(np.intp)


def ground_mask(cloud: PointCloud, *, cell_m: float) -> npt.NDArray[np.bool_]:
    """Which points are ground: near the lowest points around them and facing up.

    A one-window morphological filter: the lowest point per cell, eroded over
    `GROUND_WINDOW_M`, is the local ground; points within a band of it (widened by the
    allowed slope) whose normals point up are ground. Needs normals.
    """
    if cloud.normals is None:
        raise CollisionError("ground classification needs normals; estimate them first")
    points = cloud.points
    origin = points.min(axis=0)
    index = _grid_index(points[:, :2], origin, cell_m)
    shape = tuple(index.max(axis=0) + 1)
    lowest = np.full(shape, np.inf)
    np.minimum.at(lowest, (index[:, 0], index[:, 1]), points[:, 2])
    window = 2 * math.ceil(GROUND_WINDOW_M / cell_m) + 1
    local = ndimage.minimum_filter(lowest, size=window, mode="nearest")
    band = GROUND_BAND_M + GROUND_MAX_SLOPE * GROUND_WINDOW_M
    near = points[:, 2] - local[index[:, 0], index[:, 1]] <= band
    mask: npt.NDArray[np.bool_] = near & (np.abs(cloud.normals[:, 2]) >= GROUND_MIN_NORMAL_Z)
    return mask


def _fill_holes(heights: F64) -> F64:
    """NaN cells filled by linear interpolation of the known ones, then nearest outside their hull."""
    known = np.isfinite(heights)
    if known.all():
        return heights
    if known.sum() < 3:
        raise CollisionError("too few ground cells to build a height field; use a larger cell or more points")
    grid = np.indices(heights.shape)
    row, col = grid[0], grid[1]
    at = np.stack([row[known], col[known]], axis=1)
    holes = ~known
    filled = heights.copy()
    filled[holes] = griddata(at, heights[known], (row[holes], col[holes]), method="linear")
    still = ~np.isfinite(filled)
    if still.any():
        filled[still] = griddata(at, heights[known], (row[still], col[still]), method="nearest")
    return filled


def heightfield_from_points(
    points: npt.ArrayLike, *, cell_m: float, bounds: tuple[float, float, float, float] | None = None
) -> Heightfield:
    """Rasterise ground points [N,3] to a grid of mean heights, holes filled.

    Args:
        cell_m: grid spacing in metres.
        bounds: (xmin, ymin, xmax, ymax) of the grid; default the points' extent.
    """
    ground = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    if not (cell_m > 0.0 and math.isfinite(cell_m)):
        raise CollisionError(f"cell_m must be a positive number of metres, got {cell_m}")
    if len(ground) < 3:
        raise CollisionError(f"a height field needs at least 3 ground points, got {len(ground)}")
    low = ground[:, :2].min(axis=0) if bounds is None else np.array(bounds[:2], dtype=np.float64)
    high = ground[:, :2].max(axis=0) if bounds is None else np.array(bounds[2:], dtype=np.float64)
    cols, rows = (int(v) + 1 for v in np.floor((high - low) / cell_m))
    index = _grid_index(ground[:, :2], np.array([*low, 0.0]), cell_m)
    inside = (index[:, 0] >= 0) & (index[:, 0] < cols) & (index[:, 1] >= 0) & (index[:, 1] < rows)
    flat = index[inside, 1] * cols + index[inside, 0]
    total = np.bincount(flat, weights=ground[inside, 2], minlength=rows * cols)
    count = np.bincount(flat, minlength=rows * cols)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = np.where(count > 0, total / np.maximum(count, 1), np.nan).reshape(rows, cols)
    heights = _fill_holes(mean)
    origin = np.array([low[0], low[1], float(heights.min())])
    return Heightfield(heights.astype(np.float32), origin, float(cell_m))


def heightfield_from_mesh(mesh: trimesh.Trimesh, *, cell_m: float) -> Heightfield:
    """Rasterise a (ground) mesh by casting rays straight down at every grid node; misses filled."""
    import open3d as o3d

    low, high = mesh.bounds[0], mesh.bounds[1]
    cols, rows = (int(v) + 1 for v in np.floor((high[:2] - low[:2]) / cell_m))
    ys, xs = np.mgrid[0:rows, 0:cols].astype(np.float64) * cell_m
    top = high[2] + 1.0
    rays = np.zeros((rows * cols, 6), np.float32)
    rays[:, 0], rays[:, 1], rays[:, 2], rays[:, 5] = (xs + low[0]).ravel(), (ys + low[1]).ravel(), top, -1.0
    scene = o3d.t.geometry.RaycastingScene()
    tensor = o3d.core.Tensor.from_numpy
    scene.add_triangles(tensor(mesh.vertices.astype(np.float32)), tensor(mesh.faces.astype(np.uint32)))
    hit = scene.cast_rays(tensor(rays))["t_hit"].numpy().astype(np.float64)
    heights = np.where(np.isfinite(hit), top - hit, np.nan).reshape(rows, cols)
    heights = _fill_holes(heights)
    return Heightfield(heights.astype(np.float32), np.array([low[0], low[1], float(heights.min())]), float(cell_m))


def closed_object_mesh(cloud: PointCloud, *, floor_m: float, voxel_m: float) -> trimesh.Trimesh:
    """A closed mesh of one object's oriented points standing on the floor at height `floor_m`.

    LIDAR never sees an object's underside, so floor samples (normals down) are added under
    its footprint; Poisson then closes the solid, which is cut to the points' bounds.
    """
    if cloud.normals is None:
        raise CollisionError("an object mesh needs oriented normals; estimate them first")
    low = cloud.points.min(axis=0) - voxel_m
    high = cloud.points.max(axis=0) + voxel_m
    xs, ys = np.meshgrid(np.arange(low[0], high[0], voxel_m), np.arange(low[1], high[1], voxel_m))
    floor = np.stack([xs.ravel(), ys.ravel(), np.full(xs.size, floor_m)], axis=1)
    reach = cKDTree(cloud.points[:, :2]).query(floor[:, :2])[0]
    floor = floor[reach <= FLOOR_REACH_VOXELS * voxel_m]
    solid = PointCloud(
        np.concatenate([cloud.points, floor]),
        None,
        np.concatenate([cloud.normals, np.tile([0.0, 0.0, -1.0], (len(floor), 1))]),
    )
    mesh, _ = poisson.poisson_surface(solid, depth=poisson.poisson_depth(solid, voxel_m))
    low[2] = floor_m - voxel_m
    import open3d as o3d

    mesh = mesh.crop(o3d.geometry.AxisAlignedBoundingBox(low, high))
    closed: trimesh.Trimesh = poisson.to_trimesh(poisson.clean_mesh(mesh))
    return closed


def convex_parts(
    mesh: trimesh.Trimesh, *, max_hulls: int = DEFAULT_MAX_HULLS, threshold: float = COACD_THRESHOLD, seed: int = 0
) -> list[trimesh.Trimesh]:
    """Split a mesh into convex hulls with CoACD (approximate convex decomposition)."""
    import coacd

    if len(mesh.faces) == 0:
        raise CollisionError("convex decomposition needs a mesh with triangles")
    if max_hulls < 1:
        raise CollisionError(f"max_hulls must be at least 1, got {max_hulls}")
    if len(mesh.faces) > COACD_INPUT_FACES:
        mesh = poisson.to_trimesh(poisson.simplify_mesh(poisson.to_open3d_mesh(mesh), COACD_INPUT_FACES))
    coacd.set_log_level("error")
    parts = coacd.run_coacd(
        coacd.Mesh(np.asarray(mesh.vertices, np.float64), np.asarray(mesh.faces, np.int32)),
        threshold=threshold, max_convex_hull=max_hulls, seed=seed, mcts_iterations=COACD_MCTS_ITERATIONS,
        mcts_nodes=COACD_MCTS_NODES, mcts_max_depth=COACD_MCTS_DEPTH, resolution=COACD_RESOLUTION,
        preprocess_resolution=COACD_PREPROCESS_RESOLUTION,
    )  # fmt: skip
    hulls: list[trimesh.Trimesh] = [trimesh.Trimesh(v, f, process=True).convex_hull for v, f in parts]
    return [hull for hull in hulls if hull.volume > 0.0]


def write_hulls(hulls: Sequence[trimesh.Trimesh], folder: str | Path) -> list[Path]:
    """Write hulls as ``hull_000.obj``, ``hull_001.obj``, ... into `folder`; their paths."""
    target = Path(folder)
    target.mkdir(parents=True, exist_ok=True)
    paths = []
    for number, hull in enumerate(hulls):
        path = target / f"hull_{number:03d}.obj"
        hull.export(path, file_type="obj")
        paths.append(path)
    return paths
