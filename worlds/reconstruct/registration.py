"""Scan registration and cleaning: ICP into one frame, outlier removal, downsampling, normals.

Every step is Open3D's: point-to-plane ICP (with an optional FPFH + RANSAC coarse
alignment for scans that start far apart), statistical and radius outlier removal, voxel
downsampling and normal estimation. Normals are turned towards the sensor that saw each
point when the sensor origins are known, else made consistent over the tangent-plane graph.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt
import open3d as o3d
from drivetwin.worlds.reconstruct.pointclouds import (
    PointCloud,
    PointCloudError,
    from_open3d,
    merge_clouds,
    to_open3d,
)
from scipy.spatial import cKDTree

__all__ = [
    "Registration",
    "estimate_normals",
    "merge_registered",
    "nearest_viewpoints",
    "register_scans",
    "remove_outliers",
    "transform_cloud",
    "voxel_downsample",
]

F64 = npt.NDArray[np.float64]
# ICP runs coarse to fine at these multiples of the voxel: the coarse levels pull scans in
# from afar, the fine one settles them (Open3D's multi-scale ICP recipe).
ICP_LEVELS = (4.0, 2.0, 1.0)
# ICP pairs points up to this many (level) voxels apart: wider than the noise, narrower than a wall.
ICP_DISTANCE_VOXELS = 2.0
ICP_MAX_ITERATIONS = 60
# Target normals for point-to-plane ICP are fitted over this many (level) voxels: LIDAR rings
# on the ground lie farther apart than a few voxels, and a plane fitted to one ring tilts,
# which lets the scans slide (measured: 3 voxels drift 17 cm on the synthetic capture, 6 about 1 cm).
ICP_NORMAL_RADIUS_VOXELS = 6.0
ICP_NORMAL_MAX_NEIGHBOURS = 60
# Normals fitted over this many voxels: enough neighbours for a stable plane, small enough for edges.
NORMAL_RADIUS_VOXELS = 3.0
NORMAL_MAX_NEIGHBOURS = 30
# FPFH describes a point's neighbourhood over about five voxels (Open3D's global registration guide).
FPFH_RADIUS_VOXELS = 5.0
FPFH_MAX_NEIGHBOURS = 100
RANSAC_DISTANCE_VOXELS = 1.5
RANSAC_ITERATIONS = 100_000
RANSAC_CONFIDENCE = 0.999
# A coarse match is accepted only when its edge lengths agree this well (rigid motions keep them).
RANSAC_EDGE_SIMILARITY = 0.9
# Neighbours graph for tangent-plane orientation when no sensor origin is known.
TANGENT_PLANE_NEIGHBOURS = 15
# Statistical outlier removal: a point whose mean neighbour distance exceeds the average by
# this many standard deviations is noise (2.0 keeps thin structures such as poles).
STATISTICAL_NEIGHBOURS = 20
STATISTICAL_STD_RATIO = 2.0
# Radius outlier removal: a point needs this many others within a few voxels to be kept.
RADIUS_MIN_POINTS = 4
RADIUS_VOXELS = 2.5


@dataclass
class Registration:
    """Scan-to-frame transforms [K,4,4] (scan 0 is the frame) with ICP fitness and inlier RMSE."""

    transforms: list[F64]
    fitness: list[float] = field(default_factory=list)
    inlier_rmse: list[float] = field(default_factory=list)


def _positive(value: float, name: str) -> float:
    if not (value > 0.0 and math.isfinite(value)):
        raise PointCloudError(f"{name} must be a positive number of metres, got {value}")
    return float(value)


def transform_cloud(cloud: PointCloud, transform: npt.ArrayLike) -> PointCloud:
    """The cloud moved by a [4,4] rigid transform (normals rotated with it)."""
    matrix = np.asarray(transform, dtype=np.float64)
    if matrix.shape != (4, 4):
        raise PointCloudError(f"a transform is a [4, 4] matrix, got shape {matrix.shape}")
    rotation, shift = matrix[:3, :3], matrix[:3, 3]
    normals = None if cloud.normals is None else cloud.normals @ rotation.T
    return PointCloud(cloud.points @ rotation.T + shift, cloud.colors, normals)


def voxel_downsample(cloud: PointCloud, voxel_m: float) -> PointCloud:
    """One point per occupied voxel (the mean of its points, colours and normals)."""
    return from_open3d(to_open3d(cloud).voxel_down_sample(_positive(voxel_m, "voxel_m")))


def remove_outliers(
    cloud: PointCloud,
    *,
    voxel_m: float,
    neighbours: int = STATISTICAL_NEIGHBOURS,
    std_ratio: float = STATISTICAL_STD_RATIO,
    min_points: int = RADIUS_MIN_POINTS,
) -> tuple[PointCloud, npt.NDArray[np.intp]]:
    """Drop statistical outliers, then points with fewer than `min_points` within 2.5 voxels.

    Returns the kept cloud and the indices of the kept points in the input.
    """
    radius = RADIUS_VOXELS * _positive(voxel_m, "voxel_m")
    o3d_cloud = to_open3d(cloud)
    _, kept = o3d_cloud.remove_statistical_outlier(nb_neighbors=neighbours, std_ratio=std_ratio)
    first = np.asarray(kept, dtype=np.intp)
    _, kept_again = o3d_cloud.select_by_index(first.tolist()).remove_radius_outlier(nb_points=min_points, radius=radius)
    index = first[np.asarray(kept_again, dtype=np.intp)]
    if len(index) == 0:
        raise PointCloudError("outlier removal left no points; the cloud is too sparse for this voxel size")
    return cloud.subset(index), index


def _with_normals(cloud: o3d.geometry.PointCloud, voxel_m: float) -> o3d.geometry.PointCloud:
    cloud.estimate_normals(
        o3d.geometry.KDTreeSearchParamHybrid(radius=NORMAL_RADIUS_VOXELS * voxel_m, max_nn=NORMAL_MAX_NEIGHBOURS)
    )
    return cloud


def estimate_normals(cloud: PointCloud, *, voxel_m: float, viewpoints: npt.ArrayLike | None = None) -> PointCloud:
    """The cloud with unit normals, oriented towards `viewpoints` when given.

    Args:
        voxel_m: the cloud's spacing; normals are fitted over a 3-voxel radius.
        viewpoints: the sensor position [3] or [N,3] (one per point) that saw each point;
            without it, orientation is made consistent over a tangent-plane graph (slower,
            and the global sign is then arbitrary).
    """
    o3d_cloud = _with_normals(to_open3d(PointCloud(cloud.points, cloud.colors)), _positive(voxel_m, "voxel_m"))
    normals = np.asarray(o3d_cloud.normals, dtype=np.float64).copy()
    if viewpoints is None:
        o3d_cloud.orient_normals_consistent_tangent_plane(TANGENT_PLANE_NEIGHBOURS)
        normals = np.asarray(o3d_cloud.normals, dtype=np.float64).copy()
    else:
        views = np.broadcast_to(np.asarray(viewpoints, dtype=np.float64), cloud.points.shape)
        flip = np.einsum("ij,ij->i", normals, views - cloud.points) < 0.0
        normals[flip] *= -1.0
    return PointCloud(cloud.points, cloud.colors, normals)


def _fpfh(cloud: o3d.geometry.PointCloud, voxel_m: float) -> o3d.pipelines.registration.Feature:
    search = o3d.geometry.KDTreeSearchParamHybrid(radius=FPFH_RADIUS_VOXELS * voxel_m, max_nn=FPFH_MAX_NEIGHBOURS)
    return o3d.pipelines.registration.compute_fpfh_feature(cloud, search)  # type: ignore[call-arg]


def _coarse_alignment(source: o3d.geometry.PointCloud, target: o3d.geometry.PointCloud, voxel_m: float) -> F64:
    """A rough source-to-target transform from FPFH feature matches and RANSAC (seeded)."""
    registration = o3d.pipelines.registration
    distance = RANSAC_DISTANCE_VOXELS * voxel_m
    o3d.utility.random.seed(0)
    result = registration.registration_ransac_based_on_feature_matching(
        source,
        target,
        _fpfh(source, voxel_m),
        _fpfh(target, voxel_m),
        True,
        distance,
        registration.TransformationEstimationPointToPoint(False),
        3,
        [
            registration.CorrespondenceCheckerBasedOnEdgeLength(RANSAC_EDGE_SIMILARITY),
            registration.CorrespondenceCheckerBasedOnDistance(distance),
        ],
        registration.RANSACConvergenceCriteria(RANSAC_ITERATIONS, RANSAC_CONFIDENCE),
    )
    transform: F64 = np.asarray(result.transformation, dtype=np.float64).copy()
    return transform


def register_scans(
    scans: Sequence[PointCloud],
    *,
    voxel_m: float,
    coarse: bool = False,
    initial: Sequence[npt.ArrayLike] | None = None,
    max_distance_m: float | None = None,
) -> Registration:
    """Transforms that bring every scan into the frame of scan 0, by point-to-plane ICP.

    Each scan is aligned to the union of those already aligned, so overlaps chain.

    Args:
        voxel_m: working resolution; scans are downsampled to it before matching.
        coarse: first align each scan roughly with FPFH features and RANSAC (for scans that
            start more than a few voxels apart); otherwise ICP starts from `initial`.
        initial: optional starting [4,4] transform per scan (identity by default).
        max_distance_m: farthest point pairs matched at the coarsest level, about how far
            apart the scans may start (default 8 voxels); finer levels match within 2 of theirs.
    """
    if not scans:
        raise PointCloudError("no scans to register; give at least one")
    if initial is not None and len(initial) != len(scans):
        raise PointCloudError(f"initial has {len(initial)} transforms for {len(scans)} scans; give one per scan")
    voxel = _positive(voxel_m, "voxel_m")
    if max_distance_m is not None:
        _positive(max_distance_m, "max_distance_m")
    starts = [np.eye(4) if initial is None else np.asarray(t, dtype=np.float64).reshape(4, 4) for t in initial or scans]
    result = Registration([starts[0]], [1.0], [0.0])
    aligned = [transform_cloud(scans[0], starts[0]).points]
    for scan, start in zip(scans[1:], starts[1:], strict=True):
        target = np.concatenate(aligned)
        guess = start
        if coarse:
            source_down = _with_normals(_o3d_points(scan.points).voxel_down_sample(voxel), voxel)
            target_down = _with_normals(_o3d_points(target).voxel_down_sample(voxel), voxel)
            guess = _coarse_alignment(source_down, target_down, voxel)
        transform, fitness, rmse = _multiscale_icp(scan.points, target, voxel, guess, max_distance_m)
        result.transforms.append(transform)
        result.fitness.append(fitness)
        result.inlier_rmse.append(rmse)
        aligned.append(scan.points @ transform[:3, :3].T + transform[:3, 3])
    return result


def _o3d_points(points: F64) -> o3d.geometry.PointCloud:
    return o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))


def _multiscale_icp(
    source: F64, target: F64, voxel: float, guess: F64, max_distance_m: float | None
) -> tuple[F64, float, float]:
    """Point-to-plane ICP of source onto target, coarse to fine; (transform, fitness, inlier RMSE)."""
    registration = o3d.pipelines.registration
    criteria = registration.ICPConvergenceCriteria(max_iteration=ICP_MAX_ITERATIONS)
    transform, fitness, rmse = guess, 0.0, 0.0
    for step, level in enumerate(ICP_LEVELS):
        size = level * voxel
        source_down = _o3d_points(source).voxel_down_sample(size)
        target_down = _o3d_points(target).voxel_down_sample(size)
        target_down.estimate_normals(o3d.geometry.KDTreeSearchParamHybrid(
            radius=ICP_NORMAL_RADIUS_VOXELS * size, max_nn=ICP_NORMAL_MAX_NEIGHBOURS))  # fmt: skip
        distance = ICP_DISTANCE_VOXELS * size
        if step == 0 and max_distance_m is not None:
            distance = max_distance_m
        icp = registration.registration_icp(
            source_down, target_down, distance, transform, registration.TransformationEstimationPointToPlane(), criteria
        )
        transform = np.asarray(icp.transformation, dtype=np.float64).copy()
        fitness, rmse = float(icp.fitness), float(icp.inlier_rmse)
    return transform, fitness, rmse


def merge_registered(
    scans: Sequence[PointCloud], registration: Registration, origins: npt.ArrayLike | None = None
) -> tuple[PointCloud, F64 | None]:
    """All scans in the common frame, and the sensor origin that saw each point ([N,3]) when known."""
    moved = [transform_cloud(s, t) for s, t in zip(scans, registration.transforms, strict=True)]
    merged = merge_clouds(moved)
    if origins is None:
        return merged, None
    places = np.asarray(origins, dtype=np.float64).reshape(-1, 3)
    if len(places) != len(scans):
        raise PointCloudError(f"{len(places)} sensor origins for {len(scans)} scans; give one per scan")
    seen_from = [t[:3, :3] @ p + t[:3, 3] for p, t in zip(places, registration.transforms, strict=True)]
    per_point = np.concatenate([np.tile(o, (len(s), 1)) for o, s in zip(seen_from, scans, strict=True)])
    return merged, per_point


def nearest_viewpoints(cloud: PointCloud, source: PointCloud, viewpoints: F64) -> F64:
    """The viewpoint of each point of `cloud` taken from its nearest point in `source` (after downsampling)."""
    _, index = cKDTree(source.points).query(cloud.points)
    picked: F64 = viewpoints[index]
    return picked
