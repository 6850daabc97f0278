"""The terrain height field: bilinear heights between nodes, clamped at the edges, a file round trip."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest
from drivetwin.worlds.heightfield import CollisionError, Heightfield, add_collision_geoms, load_heightfield

# A 3 x 4 grid (rows along y, columns along x), 2 m cells, starting at (10, 20).
HEIGHTS = np.array([[0.0, 1.0, 2.0, 3.0], [1.0, 2.0, 3.0, 4.0], [4.0, 4.0, 4.0, 4.0]], np.float32)
FIELD = Heightfield(HEIGHTS, np.array([10.0, 20.0, 0.0]), 2.0)


def test_height_at_a_node_is_the_stored_height():
    assert FIELD.height_at(10.0 + 2 * 2.0, 20.0 + 1 * 2.0) == pytest.approx(3.0)


def test_height_between_nodes_is_bilinear():
    # Half way along x and y in the first cell: mean of 0, 1, 1, 2.
    assert FIELD.height_at(11.0, 21.0) == pytest.approx(1.0)
    # A quarter along x and three quarters along y in the cell between rows 1 and 2.
    row_1, row_2 = 0.75 * 1.0 + 0.25 * 2.0, 4.0
    assert FIELD.height_at(10.5, 23.5) == pytest.approx(0.25 * row_1 + 0.75 * row_2)


def test_height_outside_the_grid_is_clamped_to_its_edge():
    assert FIELD.height_at(-100.0, -100.0) == pytest.approx(0.0)
    assert FIELD.height_at(100.0, 21.0) == pytest.approx(3.5)


def test_a_saved_height_field_loads_unchanged(tmp_path):
    loaded = load_heightfield(FIELD.save(tmp_path / "terrain.npz"))
    assert np.array_equal(loaded.heights, HEIGHTS)
    assert loaded.origin.tolist() == [10.0, 20.0, 0.0] and loaded.cell == 2.0


def test_mujoco_collides_the_height_field_at_its_heights():
    spec = mujoco.MjSpec()
    add_collision_geoms(spec, heightfield=FIELD, prefix="terrain")
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    # A ray straight down onto a node between cells lands on that node's height.
    geomid = np.zeros(1, np.int32)
    distance = mujoco.mj_ray(model, data, np.array([14.0, 22.0, 50.0]), np.array([0.0, 0.0, -1.0]), None, 1, -1, geomid)
    assert 50.0 - distance == pytest.approx(FIELD.height_at(14.0, 22.0), abs=1e-3)


def test_adding_nothing_is_a_typed_error():
    with pytest.raises(CollisionError, match="give a height field, hulls or both"):
        add_collision_geoms(mujoco.MjSpec())
