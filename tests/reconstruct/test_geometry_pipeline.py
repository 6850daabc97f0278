"""The synthetic LIDAR capture reconstructs into a mesh, a height field and hulls that MuJoCo collides with."""

from __future__ import annotations

import json
from pathlib import Path

import mujoco
import numpy as np
import pytest
import trimesh
from drivetwin.worlds.heightfield import CollisionError, Heightfield, add_collision_geoms, load_heightfield
from drivetwin.worlds.meshes import category_mesh
from drivetwin.worlds.reconstruct.capture_lidar import LidarCapture, capture_scene
from drivetwin.worlds.reconstruct.lidar_mesh import GeometryResult, reconstruct_mesh
from drivetwin.worlds.reconstruct.pointclouds import PointCloudError
from drivetwin.worlds.reconstruct.poisson import SurfaceError, simplify_mesh
from scipy.spatial import ConvexHull, cKDTree

VOXEL_M = 0.08
BUDGET = 10_000
# Measured on this capture (1 cm range noise): cloud-to-truth mean 4.7 mm, p95 14 mm; mesh
# samples to truth median 4.8 mm, mean 27 mm (Poisson skin over unseen parts). Bounds ~3x that.
CLOUD_MEAN_BOUND_M = 0.015
CLOUD_P95_BOUND_M = 0.04
MESH_MEDIAN_BOUND_M = 0.015
MESH_MEAN_BOUND_M = 0.08
# Ground cells away from objects must match the flat ground within a few centimetres.
GROUND_TOLERANCE_M = 0.03
# Rest heights: a voxel of reconstruction error plus contact margin.
REST_TOLERANCE_M = 0.08
# On the barrier the Poisson skin closing its unseen far side bulges 7-11 cm over the true top
# (hull tops 1.07-1.11 m): measured rest 1.179-1.181 m on five runs, the cloud differing in
# the last bits run to run. A voxel and a half; a missing hull drops the box 1 m to the ground.
BARRIER_REST_TOLERANCE_M = 0.12
BARRIER_XY = (0.5, 2.6)  # where default_capture_scene puts the road barrier
BARRIER_TOP_M = 1.0


@pytest.fixture(scope="module")
def capture() -> LidarCapture:
    return capture_scene(channels=32, horizontal_resolution_deg=0.4, vertical_fov_deg=(-35.0, 15.0))


@pytest.fixture(scope="module")
def result(capture: LidarCapture, tmp_path_factory: pytest.TempPathFactory) -> GeometryResult:
    folder = tmp_path_factory.mktemp("geometry")
    inputs = []
    for number, scan in enumerate(capture.scans):
        inputs.append(folder / f"scan_{number}.npy")
        np.save(inputs[-1], scan)
    return reconstruct_mesh(inputs, folder / "out", kind="scene", triangle_budget=BUDGET, voxel_m=VOXEL_M,
                            origins=capture.origins, reference=capture.truth)  # fmt: skip


def test_the_pipeline_writes_the_agreed_files(result: GeometryResult) -> None:
    out = result.out_dir
    assert (out / "points.ply").is_file() and (out / "collision" / "mesh.obj").is_file()
    assert (out / "collision" / "hull_000.obj").is_file()
    assert len(list((out / "collision").glob("hull_*.obj"))) == len(result.hulls)
    with np.load(out / "collision" / "heightfield.npz") as archive:
        assert archive["heights"].dtype == np.float32 and archive["heights"].ndim == 2
        assert archive["origin"].shape == (3,)
        assert float(archive["cell"]) > 0.0
    report = json.loads((out / "geometry_report.json").read_text())
    assert {"register", "clean", "normals", "surface", "heightfield", "convex_decomposition"} <= set(
        report["timings_s"]
    )
    assert report["triangles"]["final"] <= BUDGET and report["hulls"] == len(result.hulls)


def test_the_reconstruction_lies_on_the_true_surface(result: GeometryResult) -> None:
    metrics = result.report["metrics"]
    assert metrics["cloud_to_mesh"]["mean"] < CLOUD_MEAN_BOUND_M
    assert metrics["cloud_to_mesh"]["p95"] < CLOUD_P95_BOUND_M
    assert metrics["mesh_to_mesh"]["accuracy"]["median"] < MESH_MEDIAN_BOUND_M
    assert metrics["mesh_to_mesh"]["accuracy"]["mean"] < MESH_MEAN_BOUND_M


def test_the_heightfield_matches_the_ground(result: GeometryResult, capture: LidarCapture) -> None:
    field = load_heightfield(result.out_dir / "collision" / "heightfield.npz")
    rows, cols = field.heights.shape
    xs = field.origin[0] + np.arange(cols) * field.cell
    ys = field.origin[1] + np.arange(rows) * field.cell
    gx, gy = np.meshgrid(xs, ys)
    nodes = np.stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)], axis=1)
    # Cells at least 1 m from any object: the truth there is the ground plane z = 0.
    objects = capture.truth.vertices[capture.truth.vertices[:, 2] > 0.05]
    open_ground = cKDTree(objects[:, :2]).query(nodes[:, :2])[0] > 1.0
    error = np.abs(field.heights.ravel()[open_ground])
    assert np.percentile(error, 95) < GROUND_TOLERANCE_M
    assert abs(field.height_at(0.0, 0.0)) < GROUND_TOLERANCE_M  # the hole under the car is filled


def _inside_any(points: np.ndarray, hulls: list[trimesh.Trimesh], tolerance: float) -> np.ndarray:
    inside = np.zeros(len(points), dtype=bool)
    for hull in hulls:
        equations = ConvexHull(hull.vertices).equations
        inside |= (points @ equations[:, :3].T + equations[:, 3]).max(axis=1) <= tolerance
    return inside


def test_hulls_are_convex_and_cover_the_barrier(result: GeometryResult) -> None:
    assert all(hull.is_convex and hull.volume > 0.0 for hull in result.hulls)
    barrier = category_mesh("road_barrier")
    barrier.apply_translation([*BARRIER_XY, 0.0])
    samples = trimesh.sample.sample_surface(barrier, 4000, seed=0)[0]
    samples = samples[samples[:, 2] > 0.05]  # the underside stands on the ground, unseen
    # Only the surface the LIDAR saw can be covered (the car hides the barrier's far side).
    seen = cKDTree(result.cloud.points).query(samples)[0] < 2 * VOXEL_M
    samples = samples[seen]
    assert len(samples) > 1000
    covered = _inside_any(samples, result.hulls, tolerance=VOXEL_M)
    # Measured: 93 % of the seen surface lies within a voxel of a hull (CoACD trims thin lips).
    assert covered.mean() > 0.9, f"{covered.mean():.3f} of the barrier's surface is covered"


def _rest_height(result: GeometryResult, drop_xy: tuple[float, float], shape: str, half: float) -> float:
    spec = mujoco.MjSpec()
    add_collision_geoms(spec, heightfield=result.heightfield, hulls=result.hulls)
    body = spec.worldbody.add_body(name="dropped", pos=[*drop_xy, 2.5])
    body.add_freejoint()
    kind = mujoco.mjtGeom.mjGEOM_SPHERE if shape == "sphere" else mujoco.mjtGeom.mjGEOM_BOX
    body.add_geom(type=kind, size=[half, half, half], mass=1.0)
    model = spec.compile()
    data = mujoco.MjData(model)
    for _ in range(1500):  # 3 s at the default 2 ms step: fallen and settled
        mujoco.mj_step(model, data)
    assert np.linalg.norm(data.qvel[:3]) < 0.05  # at rest, not still falling
    return float(data.xpos[model.body("dropped").id][2])


def test_a_box_dropped_on_open_ground_rests_on_the_heightfield(result: GeometryResult) -> None:
    # A box, not a ball: a ball rolls away on the few-millimetre bumps of a reconstructed ground.
    assert _rest_height(result, (-3.0, -2.0), "box", 0.2) == pytest.approx(0.2, abs=REST_TOLERANCE_M)


def test_a_box_dropped_on_the_barrier_rests_on_its_top(result: GeometryResult) -> None:
    rest = _rest_height(result, BARRIER_XY, "box", 0.1)
    assert rest == pytest.approx(BARRIER_TOP_M + 0.1, abs=BARRIER_REST_TOLERANCE_M)


def test_unknown_kind_lists_the_allowed_ones(tmp_path: Path) -> None:
    np.save(tmp_path / "a.npy", np.random.default_rng(0).normal(size=(50, 3)))
    with pytest.raises(PointCloudError, match="allowed: object, ground, scene"):
        reconstruct_mesh([tmp_path / "a.npy"], tmp_path / "out", kind="building")  # type: ignore[arg-type]


def test_collision_and_surface_errors_are_typed(tmp_path: Path) -> None:
    with pytest.raises(CollisionError, match="give a height field, hulls or both"):
        add_collision_geoms(mujoco.MjSpec())
    flat = Heightfield(np.zeros((1, 5), np.float32), np.zeros(3), 0.1)
    with pytest.raises(CollisionError, match="at least 2 x 2"):
        add_collision_geoms(mujoco.MjSpec(), heightfield=flat)
    with pytest.raises(CollisionError, match="not found"):
        load_heightfield(tmp_path / "missing.npz")
    np.savez(tmp_path / "bad.npz", heights=np.zeros((2, 2)))
    with pytest.raises(CollisionError, match="lacks"):
        load_heightfield(tmp_path / "bad.npz")
    with pytest.raises(SurfaceError, match="at least 4"):
        simplify_mesh(None, 2)
