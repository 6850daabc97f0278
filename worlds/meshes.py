"""Triangle meshes of catalog categories, built from the same primitive parts MuJoCo collides.

The mesh is in the asset frame (x forward, z up, origin on the ground), unscaled; callers
scale and place it. Used for rendering and for export to OBJ.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path

import numpy as np
import trimesh
from drivetwin.worlds.catalog import Part, catalog, category
from drivetwin.worlds.packages import AssetPackage

__all__ = ["category_mesh", "export_catalog_meshes", "part_mesh"]

# Facets around a cylinder or sphere: enough to look round at street distances, few enough
# that 200 assets stay cheap to draw.
CYLINDER_SECTIONS = 24
SPHERE_SUBDIVISIONS = 2


def _axis_rotation(axis: str) -> np.ndarray:
    """The 4x4 transform that turns a z-aligned primitive to lie along `axis`.

    A quarter turn about x takes +z to -y (axis "y"); about y it takes +z to +x (axis "x").
    """
    rotation = np.eye(4)
    if axis in ("x", "y"):
        i, j = (1, 2) if axis == "y" else (2, 0)
        rotation[i, i], rotation[i, j], rotation[j, i], rotation[j, j] = 0.0, -1.0, 1.0, 0.0
    return rotation


def part_mesh(part: Part) -> trimesh.Trimesh:
    """One primitive part as a mesh in the asset frame, coloured with the part's rgba."""
    mesh: trimesh.Trimesh
    if part.shape == "box":
        mesh = trimesh.creation.box(extents=[2.0 * s for s in part.size[:3]])
    elif part.shape == "cylinder":
        radius, half_height = part.size[0], part.size[1]
        mesh = trimesh.creation.cylinder(radius=radius, height=2.0 * half_height, sections=CYLINDER_SECTIONS)
        mesh.apply_transform(_axis_rotation(part.axis))
    else:
        mesh = trimesh.creation.icosphere(subdivisions=SPHERE_SUBDIVISIONS, radius=part.size[0])
    mesh.apply_translation(part.pos)
    colour = np.clip(np.round(np.asarray(part.rgba) * 255.0), 0, 255).astype(np.uint8)
    mesh.visual = trimesh.visual.ColorVisuals(mesh, face_colors=np.tile(colour, (len(mesh.faces), 1)))
    return mesh


@cache
def _category_mesh(category_name: str) -> trimesh.Trimesh:
    cat = category(category_name)
    if cat.package is not None:  # a reconstructed asset: its surface mesh, package frame
        surface: trimesh.Trimesh = AssetPackage.load(cat.package).mesh()
        return surface
    parts = cat.parts
    merged = trimesh.util.concatenate([part_mesh(p) for p in parts])
    if not isinstance(merged, trimesh.Trimesh):
        raise TypeError(f"parts of {category_name!r} did not merge into one mesh")
    return merged


def category_mesh(category_name: str) -> trimesh.Trimesh:
    """The mesh of a category's parts (unscaled, asset frame); a fresh copy of a cached one.

    Raises UnknownCategoryError for a name the catalog does not have.
    """
    mesh: trimesh.Trimesh = _category_mesh(category_name).copy()
    return mesh


def export_catalog_meshes(folder: str | Path) -> list[Path]:
    """Write one OBJ per catalog category into `folder` (created if missing); their paths."""
    target = Path(folder)
    target.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    for name in catalog():
        path = target / f"{name}.obj"
        category_mesh(name).export(path, file_type="obj", include_color=True)
        written.append(path)
    return written
