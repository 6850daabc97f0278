"""Point clouds for reconstruction: read PLY, PCD, LAS/LAZ and NumPy files, write PLY.

A `PointCloud` holds world-frame points [N,3] in metres (z up) with optional colours [N,3]
in 0..1 and normals [N,3]. Every problem a user can cause with a file (missing, empty, an
unknown extension, a badly shaped array) is a `PointCloudError` that says what is allowed.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

try:
    import open3d as o3d
except ImportError as error:  # pragma: no cover - depends on the installed extras
    raise ImportError("reconstruction needs Open3D: pip install 'drivetwin[reconstruct]'") from error

__all__ = [
    "READABLE_SUFFIXES",
    "PointCloud",
    "PointCloudError",
    "from_open3d",
    "merge_clouds",
    "read_point_cloud",
    "to_open3d",
    "write_ply",
]

F64 = npt.NDArray[np.float64]
READABLE_SUFFIXES = (".ply", ".pcd", ".las", ".laz", ".npy", ".npz")
# LAS colours are 16-bit by the standard, but many writers store 8-bit values in them.
LAS_16BIT_MAX = 65535.0
EIGHT_BIT_MAX = 255.0


class PointCloudError(ValueError):
    """A point cloud file or array that cannot be used, and what would be accepted."""


@dataclass
class PointCloud:
    """Points [N,3] (metres, world frame), optional colours [N,3] in 0..1 and normals [N,3]."""

    points: F64
    colors: F64 | None = None
    normals: F64 | None = None

    def __post_init__(self) -> None:
        self.points = _checked_xyz(self.points, "points")
        if len(self.points) == 0:
            raise PointCloudError("a point cloud needs at least one point, got an empty one")
        for name in ("colors", "normals"):
            values = getattr(self, name)
            if values is not None:
                checked = _checked_xyz(values, name)
                if len(checked) != len(self.points):
                    raise PointCloudError(f"{name} has {len(checked)} rows but there are {len(self.points)} points")
                setattr(self, name, checked)

    def __len__(self) -> int:
        return len(self.points)

    def subset(self, keep: npt.NDArray[np.bool_] | npt.NDArray[np.intp]) -> PointCloud:
        """The points selected by a mask or index array, with their colours and normals."""
        return PointCloud(
            self.points[keep],
            None if self.colors is None else self.colors[keep],
            None if self.normals is None else self.normals[keep],
        )


def _checked_xyz(values: npt.ArrayLike, name: str) -> F64:
    array = np.asarray(values, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != 3:
        raise PointCloudError(f"{name} must be an array of shape [N, 3], got shape {array.shape}")
    if not np.isfinite(array).all():
        raise PointCloudError(f"{name} holds NaN or infinite values; remove them first")
    return array


def _from_array(array: npt.NDArray[Any], source: str) -> PointCloud:
    if array.ndim != 2 or array.shape[1] not in (3, 6):
        raise PointCloudError(
            f"{source}: a NumPy cloud must have shape [N, 3] (xyz) or [N, 6] (xyz + rgb), got {array.shape}"
        )
    if len(array) == 0:
        raise PointCloudError(f"{source}: the point cloud is empty")
    colors = None if array.shape[1] == 3 else _unit_colors(array[:, 3:6])
    return PointCloud(array[:, :3], colors)


def _unit_colors(values: npt.ArrayLike) -> F64:
    """Colours scaled to 0..1 from 0..1, 8-bit or 16-bit values."""
    colors = np.asarray(values, dtype=np.float64)
    peak = float(colors.max()) if colors.size else 0.0
    if peak > EIGHT_BIT_MAX:
        return colors / LAS_16BIT_MAX
    if peak > 1.0:
        return colors / EIGHT_BIT_MAX
    return colors


def _read_npz(path: Path) -> PointCloud:
    with np.load(path) as archive:
        if "points" not in archive:
            raise PointCloudError(f"{path.name}: an .npz cloud needs a 'points' array; it has {sorted(archive.files)}")
        points = np.asarray(archive["points"])
        colors = np.asarray(archive["colors"]) if "colors" in archive else None
    if points.ndim != 2 or points.shape[1] != 3:
        raise PointCloudError(f"{path.name}: 'points' must have shape [N, 3], got {points.shape}")
    if len(points) == 0:
        raise PointCloudError(f"{path.name}: the point cloud is empty")
    if colors is not None and colors.shape != points.shape:
        raise PointCloudError(f"{path.name}: 'colors' must have shape {points.shape}, got {colors.shape}")
    return PointCloud(points, None if colors is None else _unit_colors(colors))


def _read_las(path: Path) -> PointCloud:
    import laspy

    try:
        las = laspy.read(path)
    except (laspy.errors.LaspyException, ValueError, OSError) as error:
        raise PointCloudError(f"{path.name}: not a readable LAS/LAZ file ({error})") from error
    points = np.stack([np.asarray(las.x), np.asarray(las.y), np.asarray(las.z)], axis=1)
    if len(points) == 0:
        raise PointCloudError(f"{path.name}: the point cloud is empty")
    names = set(las.point_format.dimension_names)
    colors = None
    if {"red", "green", "blue"} <= names:
        rgb = np.stack([np.asarray(las.red), np.asarray(las.green), np.asarray(las.blue)], axis=1)
        colors = _unit_colors(rgb) if rgb.any() else None
    return PointCloud(points, colors)


def _read_open3d(path: Path) -> PointCloud:
    cloud = o3d.io.read_point_cloud(path)
    if not cloud.has_points():
        raise PointCloudError(f"{path.name}: no points could be read (empty or not a valid {path.suffix} file)")
    return from_open3d(cloud)


def read_point_cloud(path: str | Path) -> PointCloud:
    """Read a point cloud from .ply, .pcd, .las, .laz, .npy ([N,3] or [N,6]) or .npz (points, colors)."""
    source = Path(path)
    suffix = source.suffix.lower()
    if suffix not in READABLE_SUFFIXES:
        raise PointCloudError(
            f"{source.name}: unknown point cloud extension {suffix or '(none)'!r}; allowed: {', '.join(READABLE_SUFFIXES)}"
        )
    if not source.is_file():
        raise PointCloudError(f"point cloud file not found: {source}")
    if suffix == ".npy":
        return _from_array(np.load(source), source.name)
    if suffix == ".npz":
        return _read_npz(source)
    if suffix in (".las", ".laz"):
        return _read_las(source)
    return _read_open3d(source)


def merge_clouds(clouds: Sequence[PointCloud]) -> PointCloud:
    """One cloud of all points; colours and normals are kept only when every cloud has them."""
    if not clouds:
        raise PointCloudError("no point clouds to merge; give at least one")
    colors = None
    if all(c.colors is not None for c in clouds):
        colors = np.concatenate([c.colors for c in clouds if c.colors is not None])
    normals = None
    if all(c.normals is not None for c in clouds):
        normals = np.concatenate([c.normals for c in clouds if c.normals is not None])
    return PointCloud(np.concatenate([c.points for c in clouds]), colors, normals)


def to_open3d(cloud: PointCloud) -> Any:
    """The cloud as an ``open3d.geometry.PointCloud``."""
    result = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(cloud.points))
    if cloud.colors is not None:
        result.colors = o3d.utility.Vector3dVector(cloud.colors)
    if cloud.normals is not None:
        result.normals = o3d.utility.Vector3dVector(cloud.normals)
    return result


def from_open3d(cloud: Any) -> PointCloud:
    """A `PointCloud` from an ``open3d.geometry.PointCloud``."""
    points = np.asarray(cloud.points, dtype=np.float64)
    if len(points) == 0:
        raise PointCloudError("the point cloud is empty (every point was removed or none was read)")
    colors = np.asarray(cloud.colors, dtype=np.float64) if cloud.has_colors() else None
    normals = np.asarray(cloud.normals, dtype=np.float64) if cloud.has_normals() else None
    return PointCloud(
        points.copy(), None if colors is None else colors.copy(), None if normals is None else normals.copy()
    )


def write_ply(cloud: PointCloud, path: str | Path) -> Path:
    """Write the cloud (with colours and normals when present) as a binary PLY; the path."""
    target = Path(path)
    if target.suffix.lower() != ".ply":
        raise PointCloudError(f"write_ply writes .ply files, got {target.name!r}")
    target.parent.mkdir(parents=True, exist_ok=True)
    if not o3d.io.write_point_cloud(target, to_open3d(cloud), write_ascii=False):
        raise PointCloudError(f"could not write {target}")
    return target
