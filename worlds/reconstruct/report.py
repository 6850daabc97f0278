"""The metrics report of a package, as in the paper's Tables 2 and 3: geometry (cloud-to-mesh),
appearance (PSNR, SSIM, LPIPS on held-out views), alignment, and the frames per second of
the result drawn by the hybrid renderer (measured here by rendering a few frames)."""

from __future__ import annotations

import json
import math
import os
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from drivetwin.worlds.catalog import category, refresh_catalog
from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.packages import ASSETS_ENV, POINTS_FILE, WORLD_SCENE, AssetPackage
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.hybrid import HybridRenderer
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Bounds, PhysicsProps, Pose, Scene

__all__ = ["measure_fps", "preview_scene", "write_report"]

# The renderer's default frame size (the paper reports FPS at a similar resolution).
FPS_WIDTH, FPS_HEIGHT = 640, 360
DEFAULT_FRAMES = 5
# An asset preview looks from this many bounding diagonals away, from above and aside.
PREVIEW_DISTANCE_DIAGONALS = 1.6
PREVIEW_FOVY_DEG = 50.0
# The ego is required in a Scene; in an asset preview it is parked out of view.
PREVIEW_EGO_OFFSET_M = 30.0
PREVIEW_ASSET_ID = "preview_asset"


def preview_scene(package: AssetPackage) -> tuple[Scene, Camera]:
    """A small scene holding only the packaged asset (at the origin) and a camera on it."""
    size = package.manifest.dimensions
    diagonal = math.sqrt(size.length**2 + size.width**2 + size.height**2)
    half = max(PREVIEW_EGO_OFFSET_M + 10.0, 3.0 * diagonal)
    ego = AssetInstance(id=EGO_ID, category="ego_vehicle", pose=Pose(x=-PREVIEW_EGO_OFFSET_M, y=-PREVIEW_EGO_OFFSET_M),
                        physics=PhysicsProps(mass=category("ego_vehicle").mass))  # fmt: skip
    asset = AssetInstance(id=PREVIEW_ASSET_ID, category=package.name, pose=Pose(x=0.0, y=0.0),
                          physics=PhysicsProps(mass=package.manifest.mass, dynamic=False))  # fmt: skip
    scene = Scene(name=f"{package.name}_preview", bounds=Bounds(xmin=-half, xmax=half, ymin=-half, ymax=half),
                  ego=ego, assets=[asset])  # fmt: skip
    away = PREVIEW_DISTANCE_DIAGONALS * diagonal
    target = (0.0, 0.0, size.height / 2)
    eye = (away * 0.8, -away * 0.6, size.height / 2 + away * 0.45)
    camera = Camera.from_look_at(eye, target, width=FPS_WIDTH, height=FPS_HEIGHT, fovy_deg=PREVIEW_FOVY_DEG)
    return scene, camera


@contextmanager
def _on_search_path(root: Path) -> Iterator[None]:
    """The package's category in the catalog for a while, whether or not it is installed."""
    before = os.environ.get(ASSETS_ENV)
    os.environ[ASSETS_ENV] = os.pathsep.join([str(root), *([before] if before else [])])
    refresh_catalog()
    try:
        yield
    finally:
        if before is None:
            os.environ.pop(ASSETS_ENV, None)
        else:
            os.environ[ASSETS_ENV] = before
        refresh_catalog()


def _world_camera(package: AssetPackage) -> Camera:
    """An elevated view over a world's mesh, from its south-east corner towards its centre."""
    low, high = package.mesh().bounds
    centre = (low + high) / 2
    reach = float(max(high[0] - low[0], high[1] - low[1])) / 2
    eye = (centre[0] + reach, centre[1] - reach, high[2] + reach * 0.6)
    target = (centre[0], centre[1], low[2])
    return Camera.from_look_at(eye, target, width=FPS_WIDTH, height=FPS_HEIGHT, fovy_deg=PREVIEW_FOVY_DEG)


def measure_fps(package: AssetPackage, frames: int = DEFAULT_FRAMES, out_png: Path | None = None) -> dict[str, float]:
    """Frames per second of the package drawn by the hybrid renderer at 640x360 (after one
    warm-up frame), with the renderer's per-stage figures (median). An asset is drawn on its own; a
    world with its background splats from its default camera."""
    with _on_search_path(package.root):
        if package.manifest.kind == "asset":
            if category(package.name).package is None:
                raise ValueError(f"{package.name!r} is a built-in category name; rename the package")
            scene, camera = preview_scene(package)
            world = MujocoWorld.from_scene(scene)
            renderer = HybridRenderer(world, attachments={PREVIEW_ASSET_ID: package.splats()})
        else:
            scene = Scene.load(package.root / WORLD_SCENE)
            world = MujocoWorld.from_scene(scene)
            renderer = HybridRenderer(world, background=package.splats())
            camera = _world_camera(package)
        try:
            first = renderer.render(camera)
            started = time.perf_counter()
            timings: list[dict[str, float]] = []
            for _ in range(frames):
                timings.append(renderer.render(camera).timings)
            elapsed = time.perf_counter() - started
        finally:
            renderer.close()
    if out_png is not None:
        from drivetwin.worlds.render.hybrid import save_frame

        save_frame(first, out_png)
    result = {"fps": frames / elapsed, "frames": float(frames), "width": float(FPS_WIDTH), "height": float(FPS_HEIGHT),
              "splats": float(len(package.splats()))}  # fmt: skip
    for stage in timings[0]:
        values = sorted(t.get(stage, 0.0) for t in timings)
        # The renderer's per-stage figures (milliseconds, and a few counts), median over frames.
        result[f"median.{stage}"] = values[len(values) // 2]
    return result


def _own_cloud_to_mesh(package: AssetPackage) -> dict[str, float] | None:
    """Distances from the package's LIDAR points to its mesh (how well the surface fits the
    scan when no true mesh was given), or None without points."""
    import trimesh

    from .geometry_metrics import cloud_to_mesh

    path = package.root / POINTS_FILE
    if not path.is_file():
        return None
    cloud: Any = trimesh.load(path, process=False)
    return cloud_to_mesh(cloud.vertices, package.mesh())


def _pick(report: dict[str, Any], *paths: str) -> Any:
    """The first value found at one of the dotted `paths` in a nested report, else None."""
    for path in paths:
        value: Any = report
        for key in path.split("."):
            value = value.get(key) if isinstance(value, dict) else None
        if value is not None:
            return value
    return None


def write_report(root: str | Path, out_dir: str | Path | None = None, frames: int = DEFAULT_FRAMES) -> dict[str, Any]:
    """Write `reconstruction_report.json` and `.md` for the package at `root` (into `out_dir`,
    default the package folder); returns the report."""
    package = AssetPackage.load(root)
    target = Path(out_dir) if out_dir is not None else package.root
    target.mkdir(parents=True, exist_ok=True)
    geometry = package.report("geometry_report.json")
    appearance = package.report("appearance_report.json")
    metrics = package.manifest.metrics
    report: dict[str, Any] = {
        "package": package.name,
        "kind": package.manifest.kind,
        "dimensions_m": package.manifest.dimensions.model_dump(),
        "mass_kg": package.manifest.mass,
        "geometry": {
            "cloud_to_mesh_mean_m": _pick(geometry, "metrics.cloud_to_mesh.mean"),
            "cloud_to_mesh_p95_m": _pick(geometry, "metrics.cloud_to_mesh.p95"),
            "own_cloud_to_mesh": _own_cloud_to_mesh(package),
            "mesh_accuracy_mean_m": _pick(geometry, "metrics.mesh_to_mesh.accuracy.mean"),
            "mesh_completeness_mean_m": _pick(geometry, "metrics.mesh_to_mesh.completeness.mean"),
            "triangles": _pick(geometry, "triangles.final", "triangles"),
            "hulls": len(package.hull_paths()),
        },
        "appearance": {
            "psnr_db": _pick(appearance, "metrics.psnr", "psnr_db"),
            "ssim": _pick(appearance, "metrics.ssim", "ssim"),
            "lpips": _pick(appearance, "metrics.lpips", "lpips"),
            "held_out_views": _pick(appearance, "views.held_out"),
            "fit_seconds": _pick(appearance, "seconds"),
            "splats": len(package.splats()),
        },
        "alignment": {k.split(".", 1)[1]: v for k, v in metrics.items() if k.startswith("alignment.")},
        "render": measure_fps(package, frames, target / "preview.png"),
        "sources": {"geometry": geometry, "appearance": appearance},
    }
    (target / "reconstruction_report.json").write_text(json.dumps(report, indent=2, default=str), encoding="utf-8")
    (target / "reconstruction_report.md").write_text(_markdown(report), encoding="utf-8")
    return report


def _fmt(value: Any, unit: str = "", digits: int = 3) -> str:
    if value is None:
        return "—"
    if isinstance(value, float):
        return f"{value:.{digits}f}{unit}"
    return f"{value}{unit}"


def _markdown(report: dict[str, Any]) -> str:
    g, a, r, al = report["geometry"], report["appearance"], report["render"], report["alignment"]
    own = g["own_cloud_to_mesh"] or {}
    size = report["dimensions_m"]
    rows = [
        (
            "cloud-to-mesh mean / p95",
            f"{_fmt(g['cloud_to_mesh_mean_m'], ' m', 4)} / {_fmt(g['cloud_to_mesh_p95_m'], ' m', 4)}",
        ),
        (
            "mesh to truth: accuracy / completeness (mean)",
            f"{_fmt(g['mesh_accuracy_mean_m'], ' m', 4)} / {_fmt(g['mesh_completeness_mean_m'], ' m', 4)}",
        ),
        ("triangles / convex parts", f"{_fmt(g['triangles'])} / {g['hulls']}"),
        (f"held-out PSNR ({_fmt(a['held_out_views'])} views)", _fmt(a["psnr_db"], " dB", 2)),
        ("held-out SSIM", _fmt(a["ssim"])),
        ("held-out LPIPS", _fmt(a["lpips"])),
        ("splats", str(a["splats"])),
        (
            "LIDAR cloud to its own mesh: mean / p95",
            f"{_fmt(own.get('mean'), ' m', 4)} / {_fmt(own.get('p95'), ' m', 4)}",
        ),
        ("kept splats to mesh, median", _fmt(al.get("median_kept_m"), " m", 4)),
        ("mesh covered by splats", _fmt(al.get("coverage_after"), "", 3)),
        ("alignment scale applied to splats", _fmt(al.get("scale"), "", 4)),
        (f"hybrid renderer FPS ({int(r['width'])}x{int(r['height'])})", _fmt(r["fps"], "", 1)),
    ]
    lines = [
        f"# Reconstruction report: {report['package']} ({report['kind']})",
        "",
        f"Size {size['length']:.2f} x {size['width']:.2f} x {size['height']:.2f} m, mass estimate {report['mass_kg']:.1f} kg.",
        "",
        "| metric | value |",
        "| --- | --- |",
        *[f"| {name} | {value} |" for name, value in rows],
        "",
        "Made by `drivetwin reconstruct report`; the JSON beside this file holds every figure.",
        "",
    ]
    return "\n".join(lines)
