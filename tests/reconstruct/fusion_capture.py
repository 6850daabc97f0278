"""Synthetic halves of a capture for the package and fusion tests: a known object as the
geometry half writes it (mesh, convex parts) and as the appearance half writes it (splats)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import trimesh
from drivetwin.worlds.render.splats import Splats

# An L-shaped "kerb stone with a post": no symmetry, so its pose is recoverable from shape.
PIECES = (
    # extents (m), centre (m), colour
    ((1.6, 0.5, 0.4), (0.0, 0.0, 0.2), (0.55, 0.55, 0.52)),
    ((0.4, 0.5, 0.9), (0.6, 0.0, 0.85), (0.75, 0.2, 0.15)),
    ((0.3, 0.3, 0.3), (-0.55, 0.35, 0.15), (0.1, 0.3, 0.7)),
)
# Where the object stands in the capture frame (the package frame puts it at the origin).
CAPTURE_OFFSET = np.array([12.0, -4.0, 0.5])


def pieces() -> list[trimesh.Trimesh]:
    meshes = []
    for extents, centre, _ in PIECES:
        box = trimesh.creation.box(extents=extents)
        box.apply_translation(np.asarray(centre) + CAPTURE_OFFSET)
        meshes.append(box)
    return meshes


def write_geometry(out_dir: Path) -> trimesh.Trimesh:
    """The geometry half: collision/mesh.obj, one convex hull per piece, a report."""
    parts = pieces()
    mesh = trimesh.util.concatenate(parts)
    (out_dir / "collision").mkdir(parents=True, exist_ok=True)
    mesh.export(out_dir / "collision" / "mesh.obj")
    for index, part in enumerate(parts):
        part.convex_hull.export(out_dir / "collision" / f"hull_{index:03d}.obj")
    report = {"kind": "object", "cloud_to_mesh": {"mean_m": 0.004, "p95_m": 0.011}, "faces": len(mesh.faces)}
    (out_dir / "geometry_report.json").write_text(json.dumps(report), encoding="utf-8")
    return mesh


def object_splats(count: int = 6000, seed: int = 0, background: int = 0) -> Splats:
    """Splats on the object's surface with each piece's colour (capture frame), plus
    `background` splats scattered around it like a capture's surroundings."""
    rng = np.random.default_rng(seed)
    points, colours = [], []
    for mesh, (_, _, colour) in zip(pieces(), PIECES, strict=True):
        share = int(count * mesh.area / sum(p.area for p in pieces()))
        sampled, _ = trimesh.sample.sample_surface(mesh, share, seed=int(rng.integers(1 << 30)))
        points.append(np.asarray(sampled))
        colours.append(np.tile(colour, (share, 1)))
    if background:
        ring = rng.uniform(-6.0, 6.0, (background, 3)) * [1, 1, 0.3] + CAPTURE_OFFSET
        far = np.linalg.norm(ring[:, :2] - CAPTURE_OFFSET[:2], axis=1) > 2.0
        points.append(ring[far])
        colours.append(np.tile((0.2, 0.6, 0.2), (int(far.sum()), 1)))
    return Splats.from_points(np.concatenate(points), np.concatenate(colours), opacity=0.9)


def write_appearance(out_dir: Path, splats: Splats) -> None:
    """The appearance half: visual/splats.ply and a report."""
    (out_dir / "visual").mkdir(parents=True, exist_ok=True)
    splats.write_ply(out_dir / "visual" / "splats.ply")
    report = {"psnr_db": 27.5, "ssim": 0.86, "lpips": None, "views": {"train": 24, "held_out": 4}}
    (out_dir / "appearance_report.json").write_text(json.dumps(report), encoding="utf-8")


def similarity(
    angle_deg: float, axis: tuple[float, float, float], scale: float, shift: tuple[float, float, float]
) -> np.ndarray:
    """A 4x4 similarity: rotate about `axis`, scale, then shift."""
    rotation = trimesh.transformations.rotation_matrix(np.radians(angle_deg), axis)[:3, :3]
    matrix = np.eye(4)
    matrix[:3, :3] = scale * rotation
    matrix[:3, 3] = shift
    return matrix


def fused_package(
    out_dir: Path, *, background: int = 0, transform: np.ndarray | None = None, **options: object
) -> Path:
    """Both halves written into `out_dir` and fused; the package folder."""
    from drivetwin.worlds.reconstruct.fusion import fuse

    out_dir.mkdir(parents=True, exist_ok=True)
    write_geometry(out_dir)
    splats = object_splats(background=background)
    write_appearance(out_dir, splats if transform is None else splats.transformed(transform))
    fuse(out_dir, **options)  # type: ignore[arg-type]
    return out_dir


def write_world_halves(out_dir: Path) -> None:
    """A 30 m x 20 m patch of gently sloping ground as the geometry and appearance halves."""
    rows, cols, cell = 21, 31, 1.0
    xs, ys = np.meshgrid(np.arange(cols) * cell, np.arange(rows) * cell)
    heights = (0.02 * xs).astype(np.float32)
    (out_dir / "collision").mkdir(parents=True, exist_ok=True)
    np.savez(out_dir / "collision" / "heightfield.npz", heights=heights, origin=np.array([-15.0, -10.0, 0.0]),
             cell=np.array(cell))  # fmt: skip
    vertices = np.column_stack([xs.ravel() - 15.0, ys.ravel() - 10.0, heights.ravel()])
    faces = []
    for r in range(rows - 1):
        for c in range(cols - 1):
            i = r * cols + c
            faces += [(i, i + 1, i + cols), (i + 1, i + cols + 1, i + cols)]
    ground = trimesh.Trimesh(vertices, np.asarray(faces), process=False)
    ground.export(out_dir / "collision" / "mesh.obj")
    (out_dir / "geometry_report.json").write_text(json.dumps({"kind": "ground"}), encoding="utf-8")
    points, _ = trimesh.sample.sample_surface(ground, 4000, seed=3)
    colours = np.tile((0.35, 0.4, 0.3), (len(points), 1))
    write_appearance(out_dir, Splats.from_points(np.asarray(points), colours, opacity=0.9))
