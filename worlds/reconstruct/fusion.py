"""Fusion: the geometry half and the appearance half of one capture become one package.

The halves arrive in one folder in the capture frame (see drivetwin.worlds.packages for the layout). Fusion
(1) keeps each half as reconstruction wrote it under `capture/`, (2) checks that the splat
means lie on the mesh and, when they do not (splats in an SfM frame of unknown scale),
estimates the similarity that puts them there and applies it to the splats (means,
quaternions, log scales, SH), (3) for an asset, drops splats far from the mesh (the capture's
background) and moves everything to the asset frame (origin at the bottom centre of the mesh
bounds, z up), (4) fills the catalog fields and writes `asset.json`. Running it again after
either half is rebuilt starts from the kept halves, so it never compounds transforms.
"""

from __future__ import annotations

import json
import re
import shutil
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any, Literal

import numpy as np
import numpy.typing as npt
import trimesh
from drivetwin.worlds.catalog import refresh_catalog
from drivetwin.worlds.heightfield import load_heightfield
from drivetwin.worlds.packages import (
    APPEARANCE_REPORT,
    CAMERAS_FILE,
    CAPTURE_DIR,
    GEOMETRY_REPORT,
    HEIGHTFIELD_FILE,
    HULL_PATTERN,
    MANIFEST,
    MESH_FILE,
    POINTS_FILE,
    SPLATS_FILE,
    WORLD_SCENE,
    AssetManifest,
    AssetPackage,
    Dimensions,
    Placement,
    file_digest,
)
from drivetwin.worlds.render.splats import Splats
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Bounds, PhysicsProps, Pose, Scene

from .alignment import MIN_COVERAGE, apply_transform, check_alignment, estimate_similarity, surface_samples
from .materials import density_for

__all__ = ["FusionError", "fuse", "fuse_if_complete", "halves_present", "package_name"]

F64 = npt.NDArray[np.float64]
# Splats of an asset farther than this many on-surface tolerances from its mesh are the
# capture's background, not the object.
CROP_TOLERANCES = 4.0
MIN_COVERAGE_TEXT = f"{MIN_COVERAGE:.0%}"
# A world's Scene bounds reach this far past its mesh.
WORLD_MARGIN_M = 5.0
_GEOMETRY_FILES = (MESH_FILE, HEIGHTFIELD_FILE, POINTS_FILE, GEOMETRY_REPORT)
_APPEARANCE_FILES = (SPLATS_FILE, CAMERAS_FILE, APPEARANCE_REPORT)
# More than this share of the cameras under the mesh after an estimated alignment: refused.
MAX_CAMERAS_BELOW = 0.5


class FusionError(ValueError):
    """The halves cannot be fused (one is missing or they cannot be brought into one frame)."""


def halves_present(out_dir: str | Path) -> tuple[bool, bool]:
    """(geometry, appearance): whether each half is in the folder (fresh or kept)."""
    root = Path(out_dir)
    have = [any((base / f).is_file() for base in (root, root / CAPTURE_DIR)) for f in (MESH_FILE, SPLATS_FILE)]
    return have[0], have[1]


def fuse_if_complete(out_dir: str | Path, **options: Any) -> AssetPackage | None:
    """Fuse when both halves are in `out_dir`; None (and nothing written) otherwise."""
    geometry, appearance = halves_present(out_dir)
    return fuse(out_dir, **options) if geometry and appearance else None


def package_name(text: str) -> str:
    """A catalog name (snake_case, starts with a letter, at most 40 characters) from text."""
    name = re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_")
    if not name or not name[0].isalpha():
        name = f"asset_{name}".rstrip("_")
    return name[:40].rstrip("_")


def _previous(root: Path) -> AssetManifest | None:
    """The manifest of an earlier fusion in this folder, if any (a damaged one counts as none)."""
    path = root / MANIFEST
    if not path.is_file():
        return None
    try:
        return AssetManifest.model_validate_json(path.read_text(encoding="utf-8"))
    except ValueError:
        return None


def _is_fresh(root: Path, relative: str, previous: AssetManifest | None) -> bool:
    """Whether a top-level file was written by reconstruction (not by an earlier fusion)."""
    path = root / relative
    if not path.is_file():
        return False
    return previous is None or previous.files.get(relative) != file_digest(path)


def _keep_halves(root: Path, previous: AssetManifest | None) -> None:
    """Copy freshly reconstructed halves to capture/ (replacing the kept copy of that half)."""
    capture = root / CAPTURE_DIR
    halves = ((MESH_FILE, (*_GEOMETRY_FILES, HULL_PATTERN)), (SPLATS_FILE, _APPEARANCE_FILES))
    for marker, members in halves:
        if not _is_fresh(root, marker, previous):
            continue
        for member in members:
            for old in capture.glob(member):
                old.unlink()
            for path in sorted(root.glob(member)):
                relative = path.relative_to(root).as_posix()
                if previous is not None and previous.files.get(relative) == file_digest(path):
                    path.unlink()  # an earlier fusion's output the new half no longer has
                    continue
                target = capture / relative
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(path, target)


def _load_mesh(path: Path) -> trimesh.Trimesh:
    mesh = trimesh.load(path, force="mesh", process=False)
    if not isinstance(mesh, trimesh.Trimesh) or not len(mesh.faces):
        raise FusionError(f"{path} holds no triangles")
    return mesh


def _read_json(path: Path) -> dict[str, Any]:
    if not path.is_file():
        return {}
    loaded = json.loads(path.read_text(encoding="utf-8"))
    return loaded if isinstance(loaded, dict) else {}


def _numeric(report: dict[str, Any], prefix: str) -> dict[str, float]:
    """Numbers of a half's report, one level of nesting flattened with dots."""
    found: dict[str, float] = {}
    for key, value in report.items():
        if isinstance(value, bool):
            continue
        if isinstance(value, int | float):
            found[f"{prefix}.{key}"] = float(value)
        elif isinstance(value, dict):
            for inner, number in value.items():
                if isinstance(number, int | float) and not isinstance(number, bool):
                    found[f"{prefix}.{key}.{inner}"] = float(number)
    return found


def _matrix(values: F64) -> list[list[float]]:
    return [[float(v) for v in row] for row in values]


def fuse(
    out_dir: str | Path,
    *,
    name: str | None = None,
    kind: Literal["asset", "world"] | None = None,
    material: str | None = None,
    tags: Sequence[str] = (),
    synonyms: Sequence[str] = (),
    description: str = "",
    placement: Placement = "anywhere",
    motion: Literal["prop", "static"] = "prop",
    seed: int = 0,
) -> AssetPackage:
    """Fuse the halves in `out_dir` into a package there and return it (loaded, validated).

    kind: "asset" (default when convex hulls exist) or "world"; material or a tag picks the
    density of the mass estimate (materials.DENSITY_KG_M3).
    """
    started = time.perf_counter()
    root = Path(out_dir)
    previous = _previous(root)
    _keep_halves(root, previous)
    capture = root / CAPTURE_DIR
    if not (capture / MESH_FILE).is_file() or not (capture / SPLATS_FILE).is_file():
        raise FusionError(
            f"{root} needs both halves: {MESH_FILE} (reconstruct mesh) and {SPLATS_FILE} (reconstruct splats)"
        )
    geometry_report = _read_json(capture / GEOMETRY_REPORT)
    hull_sources = sorted(capture.glob(HULL_PATTERN))
    if kind is None:
        kind = "world" if geometry_report.get("kind") in ("ground", "scene") or not hull_sources else "asset"
    if kind == "asset" and not hull_sources:
        raise FusionError(f"an asset needs convex parts ({HULL_PATTERN}); reconstruct the mesh with --kind object")
    mesh = _load_mesh(capture / MESH_FILE)
    splats = Splats.read_ply(capture / SPLATS_FILE)
    if not len(splats):
        raise FusionError(f"{SPLATS_FILE} holds no splats")

    surface = surface_samples(mesh, seed=seed)
    means = splats.means.astype(np.float64)
    before = check_alignment(means, surface)
    alignment, after = np.eye(4), before
    if not before.aligned:
        estimated, check = estimate_similarity(means, surface, seed=seed)
        if not check.aligned:
            raise FusionError(
                f"the splats do not match the mesh in any frame (they cover {before.coverage:.0%} of it as given, "
                f"{check.coverage:.0%} after the best similarity; {MIN_COVERAGE_TEXT} needed): are both halves of "
                "one capture? Crop the splats to the object or pose the images in the LIDAR frame (--poses)"
            )
        _check_cameras_above(capture / CAMERAS_FILE, estimated, float(mesh.bounds[0][2]))
        alignment, after = estimated, check
        splats = splats.transformed(alignment)
    kept = len(splats)
    kept_median = after.median_m
    if kind == "asset":
        distances = np.asarray(_distances(splats.means.astype(np.float64), surface))
        on_object = distances <= CROP_TOLERANCES * after.tolerance_m
        splats = splats.subset(on_object)
        kept_median = float(np.median(distances[on_object])) if on_object.any() else float("nan")
        if not len(splats):
            raise FusionError("no splat lies on the mesh, even after alignment: are the halves of one object?")

    low, high = mesh.bounds
    to_package = np.eye(4)
    if kind == "asset":
        to_package[:3, 3] = [-(low[0] + high[0]) / 2, -(low[1] + high[1]) / 2, -low[2]]
    files = _write_outputs(root, to_package, mesh, hull_sources, splats)

    extents = np.maximum(high - low, 1e-3)
    hulls = [_load_mesh(root / f) for f in files if f.startswith("collision/hull_")]
    volume = float(mesh.volume) if mesh.is_watertight else float(sum(h.convex_hull.volume for h in hulls))
    if volume <= 0:
        volume = float(np.prod(extents))  # a world's open terrain: the box it spans
    chosen, density = density_for(material, tags)
    metrics = {
        "alignment.median_before_m": before.median_m,
        "alignment.median_after_m": after.median_m,
        "alignment.p90_after_m": after.p90_m,
        "alignment.median_kept_m": kept_median,
        "alignment.inliers_before": before.inlier_fraction,
        "alignment.inliers_after": after.inlier_fraction,
        "alignment.coverage_before": before.coverage,
        "alignment.coverage_after": after.coverage,
        "alignment.scale": float(np.cbrt(np.linalg.det(alignment[:3, :3]))),
        "splats.total": float(kept),
        "splats.kept": float(len(splats)),
        "hulls": float(len(hulls)),
        "fusion_s": time.perf_counter() - started,
        **_numeric(geometry_report, "geometry"),
        **_numeric(_read_json(capture / APPEARANCE_REPORT), "appearance"),
    }
    manifest = AssetManifest(
        name=package_name(name or root.resolve().name),
        kind=kind,
        description=description,
        dimensions=Dimensions(length=float(extents[0]), width=float(extents[1]), height=float(extents[2])),
        volume_m3=volume,
        material=chosen,
        density_kg_m3=density,
        mass=max(volume * density, 1e-3),
        tags=list(dict.fromkeys(tags)),
        synonyms=list(dict.fromkeys(synonyms)),
        placement=placement,
        motion=motion,
        transform=_matrix(to_package),
        splat_alignment=_matrix(alignment),
        metrics=metrics,
        provenance={
            "fused_at": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
            "geometry_kind": geometry_report.get("kind"),
            "capture": CAPTURE_DIR,
            "cameras_frame": "capture splat frame: apply transform @ splat_alignment",
        },
    )
    if kind == "world":
        _write_world(root, manifest, mesh)
        files.append(WORLD_SCENE)
    manifest.files = {f: file_digest(root / f) for f in files}
    tmp = root / (MANIFEST + ".tmp")
    tmp.write_text(manifest.model_dump_json(indent=2), encoding="utf-8")
    tmp.replace(root / MANIFEST)
    refresh_catalog()
    return AssetPackage.load(root)


def _distances(points: F64, surface: F64) -> F64:
    from scipy.spatial import cKDTree

    distances, _ = cKDTree(surface).query(points)
    return np.asarray(distances, dtype=np.float64)


def _write_outputs(root: Path, to_package: F64, mesh: trimesh.Trimesh, hulls: list[Path], splats: Splats) -> list[str]:
    """Write the halves in the package frame at their top-level paths; their relative paths."""
    capture = root / CAPTURE_DIR
    written: list[str] = []
    for old in root.glob(HULL_PATTERN):
        old.unlink()
    moved = mesh.copy()
    moved.apply_transform(to_package)
    (root / "collision").mkdir(parents=True, exist_ok=True)
    moved.export(root / MESH_FILE, file_type="obj")
    written.append(MESH_FILE)
    for source in hulls:
        hull = _load_mesh(source)
        hull.apply_transform(to_package)
        relative = source.relative_to(capture).as_posix()
        hull.export(root / relative, file_type="obj")
        written.append(relative)
    if (capture / HEIGHTFIELD_FILE).is_file():
        with np.load(capture / HEIGHTFIELD_FILE) as data:
            fields = {k: np.asarray(data[k]) for k in data.files}
        fields["origin"] = np.asarray(fields["origin"], np.float64) + to_package[:3, 3]
        np.savez(root / HEIGHTFIELD_FILE, **fields)  # type: ignore[arg-type]
        written.append(HEIGHTFIELD_FILE)
    (root / SPLATS_FILE).parent.mkdir(parents=True, exist_ok=True)
    splats.transformed(to_package).write_ply(root / SPLATS_FILE)
    written.append(SPLATS_FILE)
    if (capture / POINTS_FILE).is_file():
        _write_points(capture / POINTS_FILE, root / POINTS_FILE, to_package)
        written.append(POINTS_FILE)
    return written


def _write_points(source: Path, target: Path, to_package: F64) -> None:
    """The geometry half's point cloud in the package frame (xyz and colours kept)."""
    cloud: Any = trimesh.load(source, process=False)
    vertices = apply_transform(to_package, np.asarray(cloud.vertices, np.float64))
    colours = getattr(cloud, "colors", None)
    point_cloud: Any = trimesh.PointCloud  # untyped in trimesh
    moved: Any = point_cloud(vertices, colors=colours if colours is not None and len(colours) else None)
    moved.export(target)


def _check_cameras_above(cameras_path: Path, alignment: F64, ground_z: float) -> None:
    """Refuse a similarity that puts the photographs' cameras under the scanned surface.

    Over a mostly flat mesh, a mirror-image fit (turned over, rescaled) can cover the surface
    as well as the right one; cameras stand above what they photograph, so a fit that moves
    most of them below the mesh's lowest point is the wrong one.
    """
    if not cameras_path.is_file():
        return
    views = json.loads(cameras_path.read_text(encoding="utf-8")).get("views", [])
    centres = []
    for view in views:
        world_to_camera = np.asarray(view["world_to_camera"], dtype=np.float64)
        rotation, translation = world_to_camera[:3, :3], world_to_camera[:3, 3]
        centres.append(-rotation.T @ translation)
    if not centres:
        return
    below = float(np.mean(apply_transform(alignment, np.asarray(centres))[:, 2] < ground_z))
    if below > MAX_CAMERAS_BELOW:
        raise FusionError(
            f"the best fit of the splats to the mesh puts {below:.0%} of the cameras under the scanned "
            "surface, so it is a mirror image, not the capture: crop the splats to the object or pose "
            "the images in the LIDAR frame (--poses)"
        )


def _write_world(root: Path, manifest: AssetManifest, mesh: trimesh.Trimesh) -> None:
    """A Scene for a world package: bounds around the mesh, the ego at its centre."""
    low, high = mesh.bounds
    cx, cy = float((low[0] + high[0]) / 2), float((low[1] + high[1]) / 2)
    cz = 0.0
    if (root / HEIGHTFIELD_FILE).is_file():  # the ego stands on the terrain, not buried in it
        cz = float(load_heightfield(root / HEIGHTFIELD_FILE).height_at(cx, cy))
    scene = Scene(
        name=manifest.name,
        description=manifest.description or f"a reconstructed world ({manifest.name.replace('_', ' ')})",
        bounds=Bounds(
            xmin=float(low[0]) - WORLD_MARGIN_M,
            xmax=float(high[0]) + WORLD_MARGIN_M,
            ymin=float(low[1]) - WORLD_MARGIN_M,
            ymax=float(high[1]) + WORLD_MARGIN_M,
        ),
        ego=AssetInstance(
            id=EGO_ID, category="ego_vehicle", pose=Pose(x=cx, y=cy, z=cz), physics=PhysicsProps(mass=1600.0)
        ),
    )
    scene.save(root / WORLD_SCENE)
