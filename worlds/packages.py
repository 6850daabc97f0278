"""Asset and world packages: what reconstruction hands to a drivetwin world.

A package is a folder:

    PKG/
      asset.json                 the manifest (AssetManifest): name, kind, catalog fields,
                                 the transform applied at fusion, files with checksums, metrics
      visual/splats.ply          3DGS splats, package frame (metres, z up)
      visual/cameras.json        the capture's cameras (appearance half, optional)
      collision/mesh.obj         the surface mesh, package frame
      collision/hull_000.obj ... convex parts; MuJoCo collides these (asset packages)
      collision/heightfield.npz  terrain: heights [rows, cols] float32 m, origin [x0,y0,z0], cell m
      world.json                 a Scene (world packages only)
      capture/                   the halves as reconstruction wrote them, in the capture frame
      geometry_report.json, appearance_report.json   the halves' own metrics

The package frame of an asset has its origin at the bottom centre of the mesh's bounding box,
x forward, z up: the frame every catalog category uses. A world package keeps its capture
frame, so its Scene, background splats and terrain share coordinates.

Packages are found in the folders on DRIVETWIN_ASSETS (os.pathsep-separated; each entry a
package or a folder of packages) and in the user's asset folder, `<cache>/assets` (cache:
DRIVETWIN_CACHE, default ~/.cache/drivetwin). Each asset package becomes a catalog category
(drivetwin.worlds.catalog); reconstruction (drivetwin.worlds.reconstruct) writes packages.
"""

from __future__ import annotations

import hashlib
import json
import os
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
import numpy.typing as npt
from drivetwin.worlds import paths
from drivetwin.worlds.heightfield import CollisionError, Heightfield, load_heightfield
from drivetwin.worlds.render.splats import Splats, SplatsError
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

if TYPE_CHECKING:
    import trimesh

__all__ = [
    "APPEARANCE_REPORT",
    "ASSETS_ENV",
    "CAMERAS_FILE",
    "GEOMETRY_REPORT",
    "HEIGHTFIELD_FILE",
    "MANIFEST",
    "MESH_FILE",
    "SPLATS_FILE",
    "WORLD_SCENE",
    "AssetManifest",
    "AssetPackage",
    "AssetPackageError",
    "Dimensions",
    "Placement",
    "discover_packages",
    "file_digest",
    "package_folders",
    "package_hulls",
    "package_splats",
    "user_asset_folder",
]

MANIFEST = "asset.json"
WORLD_SCENE = "world.json"
SPLATS_FILE = "visual/splats.ply"
CAMERAS_FILE = "visual/cameras.json"
MESH_FILE = "collision/mesh.obj"
HULL_PATTERN = "collision/hull_*.obj"
HEIGHTFIELD_FILE = "collision/heightfield.npz"
POINTS_FILE = "points.ply"
GEOMETRY_REPORT = "geometry_report.json"
APPEARANCE_REPORT = "appearance_report.json"
CAPTURE_DIR = "capture"
ASSETS_ENV = "DRIVETWIN_ASSETS"
FORMAT_VERSION: Literal[1] = 1
# A hull thinner than this (m³) is a sliver MuJoCo cannot compute inertia for; it is skipped.
MIN_HULL_VOLUME_M3 = 1e-9
# Where an asset may stand; the catalog's categories use the same words.
Placement = Literal["road", "sidewalk", "drivable", "anywhere"]
Matrix4 = list[list[float]]
_IDENTITY: Matrix4 = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]


class AssetPackageError(ValueError):
    """A package folder that is missing files or holds a malformed manifest or file."""

    def __init__(self, root: Path, problems: list[str]) -> None:
        self.root = root
        self.problems = problems
        super().__init__(f"asset package {root} is not usable: " + "; ".join(problems))


class Dimensions(BaseModel):
    """Size of the package's mesh bounds in its own frame, metres."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    length: float = Field(gt=0.0, description="along x")
    width: float = Field(gt=0.0, description="along y")
    height: float = Field(gt=0.0, description="along z")


class AssetManifest(BaseModel):
    """The `asset.json` of a package: what it is, how big and heavy, and how it was made."""

    model_config = ConfigDict(extra="forbid")

    format_version: Literal[1] = FORMAT_VERSION
    name: str = Field(pattern=r"^[a-z][a-z0-9_]{0,39}$", description="catalog name, snake_case")
    kind: Literal["asset", "world"]
    description: str = ""
    dimensions: Dimensions
    volume_m3: float = Field(ge=0.0)
    material: str = "default"
    density_kg_m3: float = Field(gt=0.0)
    mass: float = Field(gt=0.0, description="kg: volume × density")
    tags: list[str] = Field(default_factory=list)
    synonyms: list[str] = Field(default_factory=list)
    placement: Placement = "anywhere"
    motion: Literal["prop", "static"] = "prop"
    max_count: int = Field(20, ge=1, le=200)
    # Capture frame -> package frame (applied to the mesh half and, after alignment, the splats).
    transform: Matrix4 = Field(default_factory=lambda: [row[:] for row in _IDENTITY])
    # Splat capture frame -> mesh capture frame: the similarity fusion estimated (identity
    # when the halves already agreed).
    splat_alignment: Matrix4 = Field(default_factory=lambda: [row[:] for row in _IDENTITY])
    # Package-relative path -> sha256 of the file as fusion wrote it.
    files: dict[str, str] = Field(default_factory=dict)
    metrics: dict[str, float] = Field(default_factory=dict)
    provenance: dict[str, Any] = Field(default_factory=dict)

    @field_validator("transform", "splat_alignment")
    @classmethod
    def _four_by_four(cls, value: Matrix4) -> Matrix4:
        matrix = np.asarray(value, dtype=np.float64)
        if matrix.shape != (4, 4) or not np.all(np.isfinite(matrix)):
            raise ValueError("must be a 4x4 matrix of finite numbers")
        return value


def file_digest(path: Path) -> str:
    """The sha256 of a file, hex."""
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


@dataclass(frozen=True)
class AssetPackage:
    """A validated package folder and its manifest."""

    root: Path
    manifest: AssetManifest

    @classmethod
    def load(cls, root: str | Path) -> AssetPackage:
        """Read and validate the package at `root`; AssetPackageError names every problem."""
        folder = Path(root)
        manifest_path = folder / MANIFEST
        if not folder.is_dir():
            raise AssetPackageError(folder, ["the folder does not exist"])
        if not manifest_path.is_file():
            raise AssetPackageError(folder, [f"missing {MANIFEST} (run fusion: drivetwin reconstruct mesh/splats)"])
        try:
            manifest = AssetManifest.model_validate_json(manifest_path.read_text(encoding="utf-8"))
        except ValidationError as exc:
            problems = [
                f"{MANIFEST}: {'.'.join(str(p) for p in e['loc']) or '(top)'}: {e['msg']}" for e in exc.errors()
            ]
            raise AssetPackageError(folder, problems) from None
        package = cls(folder, manifest)
        problems = package.problems()
        if problems:
            raise AssetPackageError(folder, problems)
        return package

    def problems(self) -> list[str]:
        """What is missing or inconsistent; [] for a usable package."""
        found: list[str] = []
        required = [SPLATS_FILE, *self.manifest.files]
        if self.manifest.kind == "asset" and not self.hull_paths():
            found.append(f"no convex hulls ({HULL_PATTERN}); an asset needs at least one to collide")
        if self.manifest.kind == "world":
            required += [WORLD_SCENE]
            if not (self.root / HEIGHTFIELD_FILE).is_file() and not (self.root / MESH_FILE).is_file():
                found.append(f"missing {HEIGHTFIELD_FILE} or {MESH_FILE}: a world needs terrain")
        for relative in dict.fromkeys(required):
            if not (self.root / relative).is_file():
                found.append(f"missing {relative}")
        return found

    # Files ------------------------------------------------------------------------------
    @property
    def name(self) -> str:
        return self.manifest.name

    def hull_paths(self) -> list[Path]:
        """The convex parts, in order."""
        return sorted(self.root.glob(HULL_PATTERN))

    def splats(self) -> Splats:
        """The package's splats in its frame."""
        try:
            return Splats.read_ply(self.root / SPLATS_FILE)
        except (OSError, SplatsError) as exc:
            raise AssetPackageError(self.root, [f"{SPLATS_FILE}: {exc}"]) from None

    def hulls(self) -> list[trimesh.Trimesh]:
        """The convex parts as meshes (slivers without volume left out)."""
        return list(_load_hulls(str(self.root), _mtime_key(self.hull_paths())))

    def mesh(self) -> trimesh.Trimesh:
        """The surface mesh."""
        return _load_mesh(self.root / MESH_FILE)

    def heightfield(self) -> Heightfield | None:
        """The terrain of a world package, None when it has none (a mesh-only world)."""
        path = self.root / HEIGHTFIELD_FILE
        if not path.is_file():
            return None
        try:
            return load_heightfield(path)
        except (OSError, ValueError, CollisionError) as exc:
            raise AssetPackageError(self.root, [f"{HEIGHTFIELD_FILE}: {exc}"]) from None

    def report(self, which: str) -> dict[str, Any]:
        """One half's report (GEOMETRY_REPORT or APPEARANCE_REPORT), {} when absent."""
        for path in (self.root / which, self.root / CAPTURE_DIR / which):
            if path.is_file():
                loaded: dict[str, Any] = json.loads(path.read_text(encoding="utf-8"))
                return loaded
        return {}

def _mtime_key(paths: list[Path]) -> tuple[tuple[str, int], ...]:
    return tuple((p.name, p.stat().st_mtime_ns) for p in paths)


def _load_mesh(path: Path) -> trimesh.Trimesh:
    import trimesh  # only when a package is opened: the catalog looks for packages at start-up

    try:
        loaded = trimesh.load(path, force="mesh", process=False)
    except (OSError, ValueError) as exc:
        raise AssetPackageError(path.parent.parent, [f"{path.name}: {exc}"]) from None
    if not isinstance(loaded, trimesh.Trimesh) or not len(loaded.faces):
        raise AssetPackageError(path.parent.parent, [f"{path.name} holds no triangles"])
    return loaded


@lru_cache(maxsize=64)
def _load_hulls(root: str, key: tuple[tuple[str, int], ...]) -> tuple[trimesh.Trimesh, ...]:
    hulls = []
    for name, _ in key:
        mesh = _load_mesh(Path(root) / "collision" / name)
        hull = mesh.convex_hull
        if hull.volume > MIN_HULL_VOLUME_M3:
            hulls.append(hull)
    if not hulls:
        raise AssetPackageError(Path(root), ["every convex hull is flat (no volume); MuJoCo cannot collide them"])
    return tuple(hulls)


def package_hulls(root: str | Path, scale: float = 1.0) -> list[npt.NDArray[np.float64]]:
    """Vertices [V,3] of each convex part of the package at `root`, times `scale` (for MuJoCo)."""
    package = AssetPackage(Path(root), _manifest(Path(root)))
    return [np.asarray(h.vertices, dtype=np.float64) * scale for h in package.hulls()]


@lru_cache(maxsize=32)
def _cached_splats(path: str, mtime_ns: int) -> Splats:
    try:
        return Splats.read_ply(path)
    except (OSError, SplatsError) as exc:
        raise AssetPackageError(Path(path).parent.parent, [f"{SPLATS_FILE}: {exc}"]) from None


def package_splats(root: str | Path, scale: float = 1.0) -> Splats:
    """The splats of the package at `root` in its frame, uniformly scaled by `scale`."""
    path = Path(root) / SPLATS_FILE
    if not path.is_file():
        raise AssetPackageError(Path(root), [f"missing {SPLATS_FILE}"])
    splats = _cached_splats(str(path), path.stat().st_mtime_ns)
    if scale == 1.0:
        return splats
    return splats.transformed(np.diag([scale, scale, scale, 1.0]))


def _manifest(root: Path) -> AssetManifest:
    try:
        return AssetManifest.model_validate_json((root / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValidationError) as exc:
        raise AssetPackageError(root, [f"{MANIFEST}: {exc}"]) from None


# Discovery ------------------------------------------------------------------------------
def user_asset_folder() -> Path:
    """The user's own asset folder, beside drivetwin's other cached files."""
    return paths.cache_dir() / "assets"


def package_folders() -> list[Path]:
    """Where packages are looked for: DRIVETWIN_ASSETS entries first, then the user folder."""
    extra = [Path(p).expanduser() for p in os.environ.get(ASSETS_ENV, "").split(os.pathsep) if p]
    return [*extra, user_asset_folder()]


def _candidates(folder: Path) -> list[Path]:
    if (folder / MANIFEST).is_file():
        return [folder]
    if not folder.is_dir():
        return []
    return sorted(p for p in folder.iterdir() if (p / MANIFEST).is_file())


def discover_packages(
    kind: Literal["asset", "world"] | None = None,
    problems: list[str] | None = None,
) -> list[AssetPackage]:
    """Every valid package on the search folders (first one of a name wins). A broken package
    is skipped and described in `problems` when a list is given, never fatal."""
    found: dict[str, AssetPackage] = {}
    for folder in package_folders():
        for candidate in _candidates(folder):
            try:
                package = AssetPackage.load(candidate)
            except AssetPackageError as exc:
                if problems is not None:
                    problems.append(str(exc))
                continue
            if kind is None or package.manifest.kind == kind:
                found.setdefault(package.name, package)
    return list(found.values())
