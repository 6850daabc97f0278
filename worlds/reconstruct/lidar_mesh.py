"""LIDAR to collision geometry in one call: `reconstruct_mesh` runs the whole geometry pipeline.

read scans → register (ICP) → remove outliers → downsample → normals → Poisson surface →
height field (ground) and CoACD hulls (objects) → files in ``out_dir``:

- ``points.ply``: the cleaned, registered cloud with normals;
- ``collision/mesh.obj``: the simplified Poisson mesh;
- ``collision/hull_000.obj`` ...: convex parts (kinds ``object`` and ``scene``);
- ``collision/heightfield.npz``: ``heights`` float32 [rows, cols], ``origin`` [x0, y0, z0],
  ``cell`` (kinds ``ground`` and ``scene``);
- ``geometry_report.json``: timings per stage, counts and, given a reference, metrics.

All coordinates are metres, z up, in the frame of the first scan (the capture's world frame).
"""

from __future__ import annotations

import json
import time
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

import numpy as np
import numpy.typing as npt
import open3d as o3d
import trimesh
from drivetwin.worlds.heightfield import Heightfield
from drivetwin.worlds.reconstruct import collision, geometry_metrics, poisson, registration
from drivetwin.worlds.reconstruct.pointclouds import PointCloud, PointCloudError, read_point_cloud, write_ply

__all__ = ["GeometryKind", "GeometryResult", "reconstruct_clouds", "reconstruct_mesh"]

GeometryKind = Literal["object", "ground", "scene"]
KINDS: tuple[str, ...] = ("object", "ground", "scene")
DEFAULT_VOXEL_M = 0.05
DEFAULT_TRIANGLE_BUDGET = 20_000
# Ground cells a quarter metre across: finer than a kerb's width, coarse enough to fill holes well.
DEFAULT_HEIGHTFIELD_CELL_M = 0.25
# Object points closer together than this many voxels belong to one object.
CLUSTER_DISTANCE_VOXELS = 3.0
# An object needs at least this many points; fewer is noise or a stray leaf.
MIN_OBJECT_POINTS = 30


@dataclass
class GeometryResult:
    """What `reconstruct_mesh` made: the files it wrote and the geometry, with its report."""

    out_dir: Path
    points_path: Path
    mesh_path: Path
    report_path: Path
    mesh: trimesh.Trimesh
    cloud: PointCloud
    hull_paths: list[Path] = field(default_factory=list)
    hulls: list[trimesh.Trimesh] = field(default_factory=list)
    heightfield_path: Path | None = None
    heightfield: Heightfield | None = None
    report: dict[str, Any] = field(default_factory=dict)


class _Timer:
    def __init__(self) -> None:
        self.seconds: dict[str, float] = {}

    @contextmanager
    def stage(self, name: str) -> Iterator[None]:
        start = time.perf_counter()
        yield
        self.seconds[name] = round(time.perf_counter() - start, 4)


def reconstruct_mesh(
    inputs: Sequence[Path],
    out_dir: Path,
    *,
    kind: GeometryKind,
    triangle_budget: int = DEFAULT_TRIANGLE_BUDGET,
    voxel_m: float = DEFAULT_VOXEL_M,
    origins: npt.ArrayLike | None = None,
    register: bool = True,
    coarse: bool = False,
    heightfield_cell_m: float = DEFAULT_HEIGHTFIELD_CELL_M,
    max_hulls: int = collision.DEFAULT_MAX_HULLS,
    reference: trimesh.Trimesh | Path | None = None,
) -> GeometryResult:
    """Reconstruct collision geometry from point cloud files (see the module docstring for outputs).

    Args:
        inputs: one file per scan (.ply, .pcd, .las, .laz, .npy, .npz); scan 0 sets the frame.
        out_dir: folder for the outputs (created).
        kind: ``object`` (mesh + convex hulls), ``ground`` (mesh + height field) or
            ``scene`` (ground as a height field, the objects on it as convex hulls).
        triangle_budget: most triangles in ``collision/mesh.obj``.
        voxel_m: working resolution in metres (downsampling, normals, Poisson depth).
        origins: sensor position [K,3] per scan, in its own file's frame; orients normals.
        register: refine the scans' alignment with ICP (off when they are already registered).
        coarse: align scans globally (FPFH + RANSAC) before ICP, for scans far apart.
        heightfield_cell_m: grid spacing of the height field.
        max_hulls: most convex parts per object.
        reference: a true mesh (or mesh file) to measure the result against, for the report.
    """
    if not inputs:
        raise PointCloudError("no input point clouds; give at least one file")
    timer = _Timer()
    with timer.stage("read"):
        scans = [read_point_cloud(path) for path in inputs]
    return reconstruct_clouds(
        scans, out_dir, kind=kind, triangle_budget=triangle_budget, voxel_m=voxel_m, origins=origins,
        register=register, coarse=coarse, heightfield_cell_m=heightfield_cell_m, max_hulls=max_hulls,
        reference=reference, timer=timer, sources=[str(p) for p in inputs],
    )  # fmt: skip


def reconstruct_clouds(
    scans: Sequence[PointCloud],
    out_dir: Path,
    *,
    kind: GeometryKind,
    triangle_budget: int = DEFAULT_TRIANGLE_BUDGET,
    voxel_m: float = DEFAULT_VOXEL_M,
    origins: npt.ArrayLike | None = None,
    register: bool = True,
    coarse: bool = False,
    heightfield_cell_m: float = DEFAULT_HEIGHTFIELD_CELL_M,
    max_hulls: int = collision.DEFAULT_MAX_HULLS,
    reference: trimesh.Trimesh | Path | None = None,
    timer: _Timer | None = None,
    sources: Sequence[str] = (),
) -> GeometryResult:
    """`reconstruct_mesh` for scans already in memory."""
    if kind not in KINDS:
        raise PointCloudError(f"unknown kind {kind!r}; allowed: {', '.join(KINDS)}")
    if not scans:
        raise PointCloudError("no scans to reconstruct; give at least one")
    timer = timer or _Timer()
    out = Path(out_dir)
    folder = out / "collision"
    folder.mkdir(parents=True, exist_ok=True)
    with timer.stage("register"):
        aligned = (
            registration.register_scans(scans, voxel_m=voxel_m, coarse=coarse) if register and len(scans) > 1 else None
        )
        transforms = registration.Registration([np.eye(4) for _ in scans]) if aligned is None else aligned
        merged, views = registration.merge_registered(scans, transforms, origins)
    with timer.stage("clean"):
        cleaned, kept = registration.remove_outliers(merged, voxel_m=voxel_m)
        cloud = registration.voxel_downsample(cleaned, voxel_m)
    with timer.stage("normals"):
        viewpoints = None if views is None else registration.nearest_viewpoints(cloud, cleaned, views[kept])
        cloud = registration.estimate_normals(cloud, voxel_m=voxel_m, viewpoints=viewpoints)
    points_path = write_ply(cloud, out / "points.ply")
    with timer.stage("surface"):
        mesh, stats = poisson.reconstruct_surface(cloud, voxel_m=voxel_m, triangle_budget=triangle_budget)
    mesh_path = folder / "mesh.obj"
    mesh.export(mesh_path, file_type="obj")
    result = GeometryResult(out, points_path, mesh_path, out / "geometry_report.json", mesh, cloud)
    ground = np.ones(len(cloud), dtype=bool)
    if kind == "scene":
        with timer.stage("ground"):
            ground = collision.ground_mask(cloud, cell_m=heightfield_cell_m)
    if kind in ("ground", "scene"):
        with timer.stage("heightfield"):
            low, high = cloud.points[:, :2].min(axis=0), cloud.points[:, :2].max(axis=0)
            bounds = (float(low[0]), float(low[1]), float(high[0]), float(high[1]))
            result.heightfield = collision.heightfield_from_points(
                cloud.points[ground], cell_m=heightfield_cell_m, bounds=bounds
            )
            result.heightfield_path = result.heightfield.save(folder / "heightfield.npz")
    if kind in ("object", "scene"):
        with timer.stage("convex_decomposition"):
            parts = [mesh] if kind == "object" else _object_meshes(cloud, ~ground, result.heightfield, voxel_m)
            result.hulls = [hull for part in parts for hull in collision.convex_parts(part, max_hulls=max_hulls)]
            result.hull_paths = collision.write_hulls(result.hulls, folder)
    result.report = _report(result, kind, timer, stats, scans, merged, transforms, sources)
    if reference is not None:
        with timer.stage("metrics"):
            truth = reference if isinstance(reference, trimesh.Trimesh) else _load_mesh(Path(reference))
            result.report["metrics"] = {
                "cloud_to_mesh": geometry_metrics.cloud_to_mesh(cloud.points, truth),
                "mesh_to_mesh": geometry_metrics.mesh_to_mesh(mesh, truth),
            }
        result.report["timings_s"] = dict(timer.seconds)
    result.report_path.write_text(json.dumps(result.report, indent=2))
    return result


def _load_mesh(path: Path) -> trimesh.Trimesh:
    if not path.is_file():
        raise PointCloudError(f"reference mesh not found: {path}")
    loaded = trimesh.load(path, force="mesh")
    if not isinstance(loaded, trimesh.Trimesh):
        raise PointCloudError(f"{path.name} does not hold one triangle mesh")
    return loaded


def _object_meshes(
    cloud: PointCloud, objects: npt.NDArray[np.bool_], ground: Heightfield | None, voxel_m: float
) -> list[trimesh.Trimesh]:
    """A closed mesh per cluster of object points, standing on the ground beneath it."""
    if not objects.any():
        return []
    members = cloud.subset(objects)
    labels = np.asarray(
        o3d.geometry.PointCloud(o3d.utility.Vector3dVector(members.points)).cluster_dbscan(
            eps=CLUSTER_DISTANCE_VOXELS * voxel_m, min_points=4
        )
    )
    meshes = []
    for label in range(int(labels.max()) + 1 if len(labels) else 0):
        if (labels == label).sum() < MIN_OBJECT_POINTS:
            continue
        part = members.subset(labels == label)
        centre = part.points.mean(axis=0)
        floor = ground.height_at(centre[0], centre[1]) if ground is not None else float(part.points[:, 2].min())
        meshes.append(collision.closed_object_mesh(part, floor_m=floor, voxel_m=voxel_m))
    return meshes


def _report(
    result: GeometryResult,
    kind: str,
    timer: _Timer,
    stats: poisson.SurfaceStats,
    scans: Sequence[PointCloud],
    merged: PointCloud,
    transforms: registration.Registration,
    sources: Sequence[str],
) -> dict[str, Any]:
    field_info = None
    if result.heightfield is not None:
        rows, cols = result.heightfield.heights.shape
        field_info = {"rows": rows, "cols": cols, "cell_m": result.heightfield.cell}
    return {
        "kind": kind,
        "inputs": list(sources),
        "points": {"scans": [len(s) for s in scans], "merged": len(merged), "final": len(result.cloud)},
        "registration": {
            "fitness": transforms.fitness,
            "inlier_rmse_m": transforms.inlier_rmse,
            "transforms": [np.round(t, 6).tolist() for t in transforms.transforms],
        },
        "poisson_depth": stats.depth,
        "triangles": {
            "poisson": stats.poisson_triangles,
            "trimmed": stats.trimmed_triangles,
            "final": stats.final_triangles,
        },
        "hulls": len(result.hulls),
        "heightfield": field_info,
        "timings_s": dict(timer.seconds),
    }
