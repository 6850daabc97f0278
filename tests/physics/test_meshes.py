"""Category meshes: built from the catalog parts, sized like the category, exportable."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.meshes import category_mesh, export_catalog_meshes

# The mesh must match the category's length/width/height within this share (done-when).
SIZE_TOLERANCE = 0.15
# Categories whose catalog footprint is a clearance envelope wider than their parts
# (a pole's sign, a person's arm swing): their meshes must fit inside it, height matching.
ENVELOPE_CATEGORIES = {"pedestrian", "street_light", "fire_hydrant", "parking_sign"}


@pytest.mark.parametrize("name", sorted(catalog()))
def test_category_mesh_matches_the_category_size(name: str) -> None:
    cat = catalog()[name]
    mesh = category_mesh(name)
    assert len(mesh.faces) > 0 and mesh.bounds is not None
    extents = mesh.bounds[1] - mesh.bounds[0]
    wanted = np.array([cat.length, cat.width, cat.height])
    assert abs(mesh.bounds[0][2]) < 1e-9, "the asset origin is on the ground"
    assert extents[2] == pytest.approx(cat.height, rel=SIZE_TOLERANCE)
    if name in ENVELOPE_CATEGORIES:
        assert np.all(extents <= wanted * (1 + SIZE_TOLERANCE))
    else:
        np.testing.assert_allclose(extents, wanted, rtol=SIZE_TOLERANCE)


def test_category_mesh_is_a_copy_callers_may_transform() -> None:
    first = category_mesh("traffic_cone")
    first.apply_scale(10.0)
    assert category_mesh("traffic_cone").extents[2] == pytest.approx(0.7)


def test_export_writes_a_loadable_obj_per_category(tmp_path) -> None:  # type: ignore[no-untyped-def]
    paths = export_catalog_meshes(tmp_path / "meshes")
    assert {p.stem for p in paths} == set(catalog())
    loaded = trimesh.load(paths[0], force="mesh")
    assert len(loaded.faces) == len(category_mesh(paths[0].stem).faces)
