"""`drivetwin reconstruct demo`: the project's own synthetic capture, reconstructed end to end.

A small known scene (a cone, a bin and a bench on flat ground) is scanned by the LIDAR
sensor (noisy, several positions) and photographed by the mesh renderer from two rings of
cameras; the demo writes the scans and the posed photographs as a user would have them, then
runs the two commands a user runs (`reconstruct mesh`, `reconstruct splats`), which fuse the
package, and `reconstruct report`, whose figures the README quotes.
"""

from __future__ import annotations

from pathlib import Path

import click
import numpy as np

__all__ = ["demo_command", "write_capture"]

# LIDAR points below this height are the ground; the asset is what stands on it.
GROUND_CUT_M = 0.03
# Only points within this radius of the group's centre belong to the asset.
GROUP_RADIUS_M = 2.0
DEMO_NAME = "street_furniture_group"
# A tripod LIDAR walked round the group: six stations 3 m out, 1.5 m up, 64 channels at 0.3°
# (dense enough for a 2 cm voxel mesh of half-metre objects).
LIDAR_POSITIONS, LIDAR_RING_M, LIDAR_HEIGHT_M = 6, 3.0, 1.5
LIDAR_CHANNELS, LIDAR_RESOLUTION_DEG = 64, 0.3
DEMO_VOXEL_M = 0.02


def write_capture(folder: Path, *, views: int = 12, seed: int = 0) -> tuple[list[Path], Path, Path]:
    """Write LIDAR scans (scan_K.npy, [N,3] metres), posed photographs (poses.json and
    images/) and the true mesh of the group (truth.obj) into `folder`; their paths."""
    from .capture_lidar import capture_scene as lidar_capture
    from .capture_views import capture_ring
    from .capture_views import capture_scene as demo_scene
    from .views import write_poses_json

    folder.mkdir(parents=True, exist_ok=True)
    scene = demo_scene()
    angles = np.linspace(0.0, 2.0 * np.pi, LIDAR_POSITIONS, endpoint=False)
    origins = np.column_stack([LIDAR_RING_M * np.cos(angles), LIDAR_RING_M * np.sin(angles),
                               np.full(LIDAR_POSITIONS, LIDAR_HEIGHT_M)])  # fmt: skip
    lidar = lidar_capture(scene, origins=origins.tolist(), channels=LIDAR_CHANNELS,
                          horizontal_resolution_deg=LIDAR_RESOLUTION_DEG, seed=seed)  # fmt: skip
    scans = []
    for index, points in enumerate(lidar.scans):
        near = np.linalg.norm(points[:, :2], axis=1) <= GROUP_RADIUS_M
        path = folder / f"scan_{index}.npy"
        np.save(path, points[near & (points[:, 2] > GROUND_CUT_M)])
        scans.append(path)
    # The truth the scans are measured against: the group's surfaces above the ground.
    normals = [(0, 0, 1), (1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0)]
    cuts = [(0, 0, GROUND_CUT_M), *[tuple(-GROUP_RADIUS_M * np.asarray(n)) for n in normals[1:]]]
    truth = lidar.truth.slice_plane(cuts, normals)
    truth_path = folder / "truth.obj"
    truth.export(truth_path)
    photos = capture_ring(scene=scene, per_ring=max(views // 2, 2), seed=seed)
    poses = folder / "poses.json"
    write_poses_json(photos.images, poses)
    return scans, poses, truth_path


@click.command("demo")
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=Path("reconstruct_demo"),
              show_default=True, help="folder for the capture and the package")  # fmt: skip
@click.option("--iterations", default=300, show_default=True, type=click.IntRange(1, 100_000))
@click.option("--views", default=12, show_default=True, type=click.IntRange(4, 200), help="photographs taken")
@click.pass_context
def demo_command(ctx: click.Context, out_dir: Path, iterations: int, views: int) -> None:
    """Make the synthetic capture, reconstruct it with the two commands and write the report.

    Example: drivetwin reconstruct demo --out reconstruct_demo
    """
    from .cli import mesh_command, report_command, splats_command

    capture = out_dir / "capture"
    package = out_dir / DEMO_NAME
    scans, poses, truth = write_capture(capture, views=views)
    click.echo(f"capture: {len(scans)} LIDAR scans and {poses} in {capture}")
    ctx.invoke(mesh_command, scans=tuple(scans), out_dir=package, kind="object", budget=20_000, voxel=DEMO_VOXEL_M, reference=truth, name=DEMO_NAME,
               material="furniture", tags=("street furniture",))  # fmt: skip
    ctx.invoke(splats_command, images_dir=poses.parent, out_dir=package, colmap_dir=None, poses_json=poses,
               iterations=iterations, lpips_weights=None, name=DEMO_NAME, material="furniture", tags=("street furniture",))  # fmt: skip
    ctx.invoke(report_command, package_dir=package, out_dir=None, frames=5)
