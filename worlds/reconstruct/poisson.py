"""Surface reconstruction: Open3D's screened Poisson, density trimming, cropping, decimation, cleaning.

The Poisson solver is Kazhdan's, as Open3D ships it; this module chooses its depth from the
cloud's spacing, drops the vertices that few samples support (Poisson closes every surface,
inventing skin over unseen areas), crops to the cloud's bounds, cuts the mesh to a triangle
budget with quadric decimation and removes degenerate, duplicated and non-manifold parts.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt
import open3d as o3d
import trimesh
from drivetwin.worlds.reconstruct.pointclouds import PointCloud, PointCloudError, to_open3d

__all__ = [
    "SurfaceError",
    "SurfaceStats",
    "clean_mesh",
    "crop_to_bounds",
    "poisson_depth",
    "poisson_surface",
    "reconstruct_surface",
    "simplify_mesh",
    "to_open3d_mesh",
    "to_trimesh",
]

# Poisson's scale default: the octree cube is this much larger than the samples' bounding cube.
POISSON_SCALE = 1.1
# Octree depths worth solving: below 6 a car is a blob, above 10 a 2-core machine waits minutes.
MIN_POISSON_DEPTH = 6
MAX_POISSON_DEPTH = 10
# Vertices whose Poisson density is in the lowest 3 % are unsupported skin (tuned on the
# synthetic capture: lower keeps skin over unseen gaps, higher eats into thin parts).
DEFAULT_DENSITY_QUANTILE = 0.03
# The mesh is cropped to the cloud's bounding box grown by this many voxels.
CROP_MARGIN_VOXELS = 1.0


class SurfaceError(ValueError):
    """A surface reconstruction setting or result that cannot be used, and what is allowed."""


@dataclass
class SurfaceStats:
    """What surface reconstruction did: Poisson depth and the triangles after each stage."""

    depth: int
    poisson_triangles: int
    trimmed_triangles: int
    final_triangles: int


def poisson_depth(cloud: PointCloud, voxel_m: float) -> int:
    """The octree depth whose finest cell is about one voxel across the cloud's extent."""
    extent = float(np.ptp(cloud.points, axis=0).max()) * POISSON_SCALE
    depth = math.ceil(math.log2(max(extent / voxel_m, 1.0)))
    return int(min(max(depth, MIN_POISSON_DEPTH), MAX_POISSON_DEPTH))


def poisson_surface(cloud: PointCloud, *, depth: int) -> tuple[Any, npt.NDArray[np.float64]]:
    """Screened Poisson reconstruction: an Open3D mesh and the sample density at each vertex."""
    if cloud.normals is None:
        raise SurfaceError("Poisson reconstruction needs oriented normals; estimate them first")
    if not MIN_POISSON_DEPTH <= depth <= MAX_POISSON_DEPTH:
        raise SurfaceError(f"depth must be in [{MIN_POISSON_DEPTH}, {MAX_POISSON_DEPTH}], got {depth}")
    mesh, densities = o3d.geometry.TriangleMesh.create_from_point_cloud_poisson(
        to_open3d(cloud), depth=depth, scale=POISSON_SCALE, linear_fit=False
    )
    return mesh, np.asarray(densities, dtype=np.float64)


def trim_low_density(mesh: Any, densities: npt.NDArray[np.float64], quantile: float) -> Any:
    """The mesh without the vertices whose density is below the given quantile (0 keeps all)."""
    if not 0.0 <= quantile < 1.0:
        raise SurfaceError(f"density_quantile must be in [0, 1), got {quantile}")
    if quantile > 0.0 and len(densities):
        mesh.remove_vertices_by_mask(densities < np.quantile(densities, quantile))
    return mesh


def crop_to_bounds(mesh: Any, cloud: PointCloud, margin_m: float) -> Any:
    """The mesh cut to the cloud's axis-aligned bounding box grown by `margin_m`."""
    low = cloud.points.min(axis=0) - margin_m
    high = cloud.points.max(axis=0) + margin_m
    return mesh.crop(o3d.geometry.AxisAlignedBoundingBox(low, high))


def clean_mesh(mesh: Any) -> Any:
    """The mesh without degenerate, duplicated or non-manifold triangles and unused vertices."""
    mesh.remove_duplicated_vertices()
    mesh.remove_degenerate_triangles()
    mesh.remove_duplicated_triangles()
    mesh.remove_non_manifold_edges()
    mesh.remove_unreferenced_vertices()
    return mesh


def simplify_mesh(mesh: Any, triangle_budget: int) -> Any:
    """The mesh cut to at most `triangle_budget` triangles by quadric decimation."""
    if triangle_budget < 4:
        raise SurfaceError(f"triangle_budget must be at least 4, got {triangle_budget}")
    if len(mesh.triangles) <= triangle_budget:
        return mesh
    return mesh.simplify_quadric_decimation(target_number_of_triangles=int(triangle_budget))


def to_trimesh(mesh: Any) -> trimesh.Trimesh:
    """An Open3D triangle mesh as a trimesh (vertices and faces only)."""
    vertices = np.asarray(mesh.vertices, dtype=np.float64)
    faces = np.asarray(mesh.triangles, dtype=np.int64)
    if len(faces) == 0:
        raise SurfaceError("the reconstructed mesh has no triangles left (trim less or use a denser cloud)")
    return trimesh.Trimesh(vertices.copy(), faces.copy(), process=False)


def to_open3d_mesh(mesh: trimesh.Trimesh) -> Any:
    """A trimesh as an Open3D triangle mesh."""
    return o3d.geometry.TriangleMesh(
        o3d.utility.Vector3dVector(np.asarray(mesh.vertices, np.float64)),
        o3d.utility.Vector3iVector(np.asarray(mesh.faces, np.int32)),
    )


def reconstruct_surface(
    cloud: PointCloud,
    *,
    voxel_m: float,
    triangle_budget: int,
    depth: int | None = None,
    density_quantile: float = DEFAULT_DENSITY_QUANTILE,
) -> tuple[trimesh.Trimesh, SurfaceStats]:
    """A cleaned mesh of the oriented cloud within `triangle_budget` triangles, and what it took.

    Args:
        voxel_m: the cloud's spacing; sets the Poisson depth (unless `depth` is given) and the crop margin.
        triangle_budget: most triangles in the result.
        density_quantile: share of lowest-density vertices removed after Poisson.
    """
    if len(cloud) < 4:
        raise PointCloudError(f"surface reconstruction needs at least 4 points, got {len(cloud)}")
    chosen = poisson_depth(cloud, voxel_m) if depth is None else depth
    mesh, densities = poisson_surface(cloud, depth=chosen)
    poisson_triangles = len(mesh.triangles)
    mesh = trim_low_density(mesh, densities, density_quantile)
    mesh = crop_to_bounds(mesh, cloud, CROP_MARGIN_VOXELS * voxel_m)
    trimmed = len(mesh.triangles)
    mesh = clean_mesh(simplify_mesh(clean_mesh(mesh), triangle_budget))
    result = to_trimesh(mesh)
    return result, SurfaceStats(chosen, poisson_triangles, trimmed, len(result.faces))
