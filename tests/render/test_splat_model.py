"""The splat model: 3DGS .ply layout, point-cloud initialisation, rigid motion, concat."""

from __future__ import annotations

import numpy as np
import pytest
from drivetwin.worlds.render.camera import Camera
from drivetwin.worlds.render.rasterize import rasterize
from drivetwin.worlds.render.splats import SH_C0, Splats, SplatsError

# The property order 3DGS's `save_ply` writes for SH degree 3, spelled out independently.
THREE_DGS_DEGREE_3 = (
    ["x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"]
    + [f"f_rest_{i}" for i in range(45)]
    + ["opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3"]
)


def random_splats(n: int, sh_degree: int, seed: int = 0) -> Splats:
    rng = np.random.default_rng(seed)
    return Splats(
        means=rng.uniform([-1.0, -1.0, 2.0], [1.0, 1.0, 5.0], (n, 3)),
        quats=rng.normal(size=(n, 4)),
        log_scales=rng.uniform(-3.0, -1.5, (n, 3)),
        opacity_logits=rng.normal(1.0, 1.5, n),
        sh=rng.normal(0.0, 0.5, (n, (sh_degree + 1) ** 2, 3)),
    )


def ply_header(path) -> tuple[list[str], int]:
    with open(path, "rb") as fh:
        lines = []
        while (line := fh.readline().decode("ascii").strip()) != "end_header":
            lines.append(line)
    names = [line.split()[2] for line in lines if line.startswith("property float")]
    return names, sum(1 for line in lines if line.startswith("property"))


@pytest.mark.parametrize("sh_degree", [0, 1, 3])
def test_ply_round_trip_is_bit_identical(tmp_path, sh_degree):
    splats = random_splats(50, sh_degree)
    splats.write_ply(tmp_path / "s.ply")
    back = Splats.read_ply(tmp_path / "s.ply")
    for name in ("means", "quats", "log_scales", "opacity_logits", "sh"):
        assert np.array_equal(getattr(back, name), getattr(splats, name)), name


def test_ply_header_follows_the_3dgs_layout_with_channel_major_f_rest(tmp_path):
    splats = random_splats(4, 3)
    splats.sh[:] = 0.0
    splats.sh[:, 1, 0] = 7.0  # first higher-order coefficient of red
    splats.sh[:, 1, 1] = 9.0  # ... of green: channel-major puts it after all 15 red ones
    splats.write_ply(tmp_path / "s.ply")
    names, n_properties = ply_header(tmp_path / "s.ply")
    assert names == THREE_DGS_DEGREE_3 and n_properties == len(THREE_DGS_DEGREE_3)
    with open(tmp_path / "s.ply", "rb") as fh:
        body = fh.read().split(b"end_header\n", 1)[1]
    raw = np.frombuffer(body, dtype=np.dtype([(n, "<f4") for n in names]))
    assert (raw["f_rest_0"] == 7.0).all() and (raw["f_rest_15"] == 9.0).all()
    assert (raw["opacity"] == splats.opacity_logits).all()
    assert (raw["rot_0"] == splats.quats[:, 0]).all()  # w first


def test_read_ply_names_missing_properties(tmp_path):
    path = tmp_path / "points.ply"
    path.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 0\n"
                     b"property float x\nproperty float y\nproperty float z\nend_header\n")  # fmt: skip
    with pytest.raises(SplatsError, match="lacks 3DGS properties: f_dc_0"):
        Splats.read_ply(path)


def test_from_points_scales_each_point_by_its_nearest_neighbour_distance():
    grid = np.stack(np.meshgrid(*[np.arange(5) * 0.1] * 3, indexing="ij"), -1).reshape(-1, 3)
    colours = np.tile(np.array([[255, 128, 0]], np.uint8), (len(grid), 1))
    splats = Splats.from_points(grid, colours, k=3, opacity=0.2)
    interior = np.all((grid > 0.05) & (grid < 0.35), axis=1)
    assert np.allclose(np.exp(splats.log_scales[interior]), 0.1, rtol=1e-5)
    assert np.allclose(splats.opacities, 0.2, rtol=1e-5)
    assert np.allclose(0.5 + SH_C0 * splats.sh[0, 0], [1.0, 128 / 255, 0.0], atol=1e-6)
    assert np.allclose(splats.quats, [1.0, 0.0, 0.0, 0.0])


def test_from_points_gives_duplicate_points_a_finite_scale():
    points = np.array([[0.0, 0.0, 0.0]] * 3 + [[1.0, 0.0, 0.0]] * 2)
    splats = Splats.from_points(points, np.full((5, 3), 0.5), k=2)
    assert np.all(np.isfinite(splats.log_scales))


def test_from_points_refuses_colours_out_of_range():
    with pytest.raises(SplatsError, match=r"uint8 0\.\.255 or floats in"):
        Splats.from_points(np.random.rand(10, 3), np.full((10, 3), 2.0))


def test_splats_refuse_mismatched_shapes():
    with pytest.raises(SplatsError, match="quats must have shape"):
        Splats(np.zeros((3, 3)), np.zeros((2, 4)), np.zeros((3, 3)), np.zeros(3),
               np.zeros((3, 1, 3)))  # fmt: skip


def rigid_transform(seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    q *= np.sign(np.linalg.det(q))
    transform = np.eye(4)
    transform[:3, :3], transform[:3, 3] = q, rng.normal(0.0, 3.0, 3)
    return transform


def test_moving_splats_and_camera_together_leaves_the_image_unchanged():
    splats = random_splats(150, 3, seed=4)
    camera = Camera(48, 36, fx=40.0, fy=40.0, cx=24.0, cy=18.0, world_to_camera=np.eye(4))
    transform = rigid_transform(5)
    before = rasterize(splats, camera, backend="numba")
    after = rasterize(splats.transformed(transform), camera.transformed(transform), backend="numba")
    assert before.alpha.mean() > 0.3
    # float32 storage of the moved parameters is the only difference
    assert np.abs(after.rgb - before.rgb).mean() < 1e-5
    assert np.abs(after.rgb - before.rgb).max() < 5e-3
    assert np.abs(after.depth - before.depth).max() < 1e-3
    # Without rotating the SH bands the view-dependent colour would not follow the splats.
    moved = splats.transformed(transform)
    moved.sh[:, 1:] = splats.sh[:, 1:]
    stale = rasterize(moved, camera.transformed(transform), backend="numba")
    assert np.abs(stale.rgb - before.rgb).max() > 0.05


def test_uniform_scale_scales_the_splats():
    splats = random_splats(5, 0)
    transform = np.diag([2.0, 2.0, 2.0, 1.0])
    scaled = splats.transformed(transform)
    assert np.allclose(scaled.means, 2 * splats.means)
    assert np.allclose(scaled.log_scales, splats.log_scales + np.log(2.0), atol=1e-6)


def test_transformed_refuses_shear():
    shear = np.eye(4)
    shear[0, 1] = 0.5
    with pytest.raises(SplatsError, match="rotation"):
        random_splats(3, 0).transformed(shear)


def test_concat_keeps_order_and_pads_lower_sh_degrees():
    a, b = random_splats(3, 0, seed=1), random_splats(2, 2, seed=2)
    both = Splats.concat([a, b])
    assert len(both) == 5 and both.sh_degree == 2
    assert np.array_equal(both.means[3:], b.means)
    assert np.array_equal(both.sh[:3, 0], a.sh[:, 0]) and not both.sh[:3, 1:].any()


def test_from_points_caps_the_scale_of_an_isolated_point_at_max_scale():
    grid = np.stack(np.meshgrid(*[np.arange(5) * 0.1] * 3, indexing="ij"), -1).reshape(-1, 3)
    points = np.vstack([grid, [[40.0, 0.0, 0.0]]])  # one stray point 40 m away
    colours = np.full((len(points), 3), 0.5)
    free = Splats.from_points(points, colours, k=3)
    capped = Splats.from_points(points, colours, k=3, max_scale=0.25)
    assert np.exp(free.log_scales[-1, 0]) > 30.0
    assert np.exp(capped.log_scales[-1]) == pytest.approx([0.25] * 3, rel=1e-6)
    assert np.array_equal(capped.log_scales[:-1], free.log_scales[:-1])  # dense points untouched


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan"), float("inf")])
def test_from_points_refuses_a_max_scale_that_is_not_a_positive_length(bad):
    with pytest.raises(SplatsError, match="max_scale must be a positive number of metres"):
        Splats.from_points(np.random.rand(10, 3), np.full((10, 3), 0.5), max_scale=bad)
