"""`drivetwin reconstruct`: LIDAR scans and photographs to an asset or world package.

Two commands make a package, in either order; the second one fuses it:

    drivetwin reconstruct mesh scan_*.ply --out pkg/kerb_stone --kind object
    drivetwin reconstruct splats photos/ --out pkg/kerb_stone --colmap photos/sparse/0
    drivetwin reconstruct report pkg/kerb_stone

Put the package's parent folder on DRIVETWIN_ASSETS (or the package in ~/.cache/drivetwin/assets)
and the Workers can place it: `drivetwin chat` -> "add a kerb stone next to the bus stop".
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, cast

import click
from drivetwin.worlds.progress import progress_bar

# Commands import the reconstruction modules when run, so `drivetwin --help` stays fast.

__all__ = ["add_reconstruct_parser", "reconstruct"]

DEFAULT_BUDGET = 20_000
_OUT = click.option("--out", "out_dir", required=True, type=click.Path(file_okay=False, path_type=Path),
                    help="the package folder (created); both halves go into the same one")  # fmt: skip
_NAME = click.option("--name", default=None, help="catalog name (default: the folder's name)")
_MATERIAL = click.option(
    "--material", default=None, help="what it is made of, for the mass estimate (e.g. concrete, wood)"
)
_TAGS = click.option("--tag", "tags", multiple=True, help="a tag (repeatable); a tag with a density sets the mass too")
_QUIET = click.option("--quiet", "-q", is_flag=True, help="no progress bar (one is drawn only on a terminal anyway)")


@click.group(name="reconstruct")
def reconstruct() -> None:
    """Real to sim: scans and photographs to a package a world can use.

    Example: drivetwin reconstruct mesh scans/*.ply --out pkg/kerb_stone --kind object
    """


def _fuse_options(name: str | None, material: str | None, tags: tuple[str, ...]) -> dict[str, Any]:
    return {"name": name, "material": material, "tags": list(tags)}


def _finish(out_dir: Path, options: dict[str, Any]) -> None:
    """Fuse when the other half is there already; say what is missing otherwise."""
    from drivetwin.worlds.packages import AssetPackageError

    from .fusion import FusionError, fuse_if_complete, halves_present

    try:
        package = fuse_if_complete(out_dir, **options)
    except (FusionError, AssetPackageError) as exc:
        raise click.ClickException(f"fusion failed: {exc}") from exc
    if package is None:
        geometry, _ = halves_present(out_dir)
        other = "reconstruct splats IMAGES_DIR" if geometry else "reconstruct mesh SCANS..."
        click.echo(f"half written to {out_dir}; run `drivetwin {other} --out {out_dir}` to fuse the package")
        return
    _summary(package, out_dir)


def _summary(package: Any, out_dir: Path) -> None:
    """Say what the package is and how to use it."""
    from drivetwin.worlds.packages import user_asset_folder

    m = package.manifest
    size = m.dimensions
    click.echo(f"package {m.name!r} ({m.kind}) in {out_dir}: {size.length:.2f} x {size.width:.2f} x "
               f"{size.height:.2f} m, {m.mass:.1f} kg, {int(m.metrics.get('splats.kept', 0))} splats, "
               f"{len(package.hull_paths())} convex parts")  # fmt: skip
    click.echo(f"use it: export DRIVETWIN_ASSETS={out_dir.resolve().parent} (or copy it into {user_asset_folder()})")


@reconstruct.command("mesh")
@click.argument("scans", nargs=-1, required=True, type=click.Path(exists=True, dir_okay=False, path_type=Path))
@_OUT
@click.option("--kind", type=click.Choice(["object", "ground", "scene"]), default="object", show_default=True,
              help="object: convex parts; ground: height field; scene: both")  # fmt: skip
@click.option("--reference", type=click.Path(exists=True, dir_okay=False, path_type=Path), default=None,
              help="a true mesh to measure cloud-to-mesh and mesh-to-mesh distances against")  # fmt: skip
@click.option("--voxel", default=0.05, show_default=True, type=click.FloatRange(0.001, 10.0),
              help="working resolution in metres (downsampling, normals, Poisson depth)")  # fmt: skip
@click.option("--budget", default=DEFAULT_BUDGET, show_default=True, type=click.IntRange(100, 2_000_000),
              help="most triangles in the mesh")  # fmt: skip
@_NAME
@_MATERIAL
@_TAGS
@_QUIET
def mesh_command(scans: tuple[Path, ...], out_dir: Path, kind: str, reference: Path | None, voxel: float, budget: int,
                 name: str | None,
                 material: str | None, tags: tuple[str, ...], quiet: bool) -> None:  # fmt: skip
    """Point clouds (PLY, PCD, LAS, NumPy) to a collision mesh, convex parts and a height field.

    Example: drivetwin reconstruct mesh scan_0.ply scan_1.ply --out pkg/kerb_stone --kind object
    """
    from .lidar_mesh import GeometryKind, reconstruct_mesh
    from .pointclouds import PointCloudError

    try:
        geometry_kind: GeometryKind = cast("GeometryKind", kind)  # click.Choice checked it
        with progress_bar(f"mesh from {len(scans)} scan(s)", None, enabled=not quiet):  # a spinner and the time it has taken
            result = reconstruct_mesh(
                list(scans), out_dir, kind=geometry_kind, triangle_budget=budget, voxel_m=voxel, reference=reference
            )
    except (PointCloudError, ValueError, OSError) as exc:
        raise click.ClickException(str(exc)) from exc
    click.echo(f"mesh: {len(result.mesh.faces)} triangles, {len(result.hulls)} convex parts")
    _finish(out_dir, _fuse_options(name, material, tags))


@reconstruct.command("splats")
@click.argument("images_dir", type=click.Path(exists=True, file_okay=False, path_type=Path))
@_OUT
@click.option("--colmap", "colmap_dir", type=click.Path(exists=True, file_okay=False, path_type=Path), default=None,
              help="a COLMAP model folder (cameras, images, points3D) posing the images")  # fmt: skip
@click.option("--poses", "poses_json", type=click.Path(exists=True, dir_okay=False, path_type=Path), default=None,
              help="a drivetwin poses JSON file (see views.load_poses_json)")  # fmt: skip
@click.option("--iterations", default=None, type=click.IntRange(1, 1_000_000), help="fit iterations (default 300)")
@click.option("--lpips", "lpips_weights", type=click.Path(exists=True, path_type=Path), default=None,
              help="LPIPS weights (file or folder) for the held-out LPIPS; none are downloaded")  # fmt: skip
@_NAME
@_MATERIAL
@_TAGS
@_QUIET
def splats_command(images_dir: Path, out_dir: Path, colmap_dir: Path | None, poses_json: Path | None,
                   iterations: int | None, lpips_weights: Path | None, name: str | None, material: str | None,
                   tags: tuple[str, ...], quiet: bool) -> None:  # fmt: skip
    """Photographs to fitted Gaussian splats (posed by COLMAP, a poses file, or SfM when neither).

    Example: drivetwin reconstruct splats photos/ --out pkg/kerb_stone --colmap photos/sparse/0
    """
    from .colmap_model import load_colmap, run_sfm
    from .fit import FitConfig
    from .photo_splats import reconstruct_splats
    from .views import load_poses_json

    if colmap_dir is not None and poses_json is not None:
        raise click.UsageError("give --colmap or --poses, not both")
    try:
        if poses_json is not None:
            images = load_poses_json(poses_json, image_root=images_dir)
        elif colmap_dir is not None:
            images = load_colmap(colmap_dir, images_dir)
        else:
            click.echo(f"no poses given: running structure from motion on {images_dir}")
            images = run_sfm(images_dir, out_dir / "sfm")
        total = iterations or FitConfig().iterations
        with progress_bar("fitting splats", total, "iterations", enabled=not quiet) as bar:
            result = reconstruct_splats(images, out_dir, iterations=total, lpips_weights=lpips_weights,
                                        progress=lambda step: bar.advance(note=f"loss {step.loss:.4f}, {step.splats} splats"))  # fmt: skip
    except (ValueError, OSError) as exc:
        raise click.ClickException(str(exc)) from exc
    lpips = f", LPIPS {result.lpips:.3f}" if result.lpips is not None else ""
    click.echo(f"splats: {len(result.splats)}; held-out PSNR {result.psnr:.2f} dB, SSIM {result.ssim:.3f}{lpips}")
    _finish(out_dir, _fuse_options(name, material, tags))


@reconstruct.command("fuse")
@click.argument("package_dir", type=click.Path(exists=True, file_okay=False, path_type=Path))
@click.option(
    "--kind", type=click.Choice(["asset", "world"]), default=None, help="default: asset when convex parts exist"
)
@_NAME
@_MATERIAL
@_TAGS
@click.option("--description", default="", help="one line saying what it is")
def fuse_command(package_dir: Path, kind: str | None, name: str | None, material: str | None,
                 tags: tuple[str, ...], description: str) -> None:  # fmt: skip
    """Fuse (again) the two halves in a folder, e.g. with another name or material.

    Example: drivetwin reconstruct fuse pkg/kerb_stone --material concrete --tag kerb
    """
    from drivetwin.worlds.packages import AssetPackageError

    from .fusion import FusionError, fuse

    try:
        package = fuse(package_dir, kind=kind, description=description, **_fuse_options(name, material, tags))  # type: ignore[arg-type]
    except (FusionError, AssetPackageError) as exc:
        raise click.ClickException(str(exc)) from exc
    _summary(package, package_dir)


@reconstruct.command("report")
@click.argument("package_dir", type=click.Path(exists=True, file_okay=False, path_type=Path))
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              help="folder for the report (default: the package)")  # fmt: skip
@click.option("--frames", default=5, show_default=True, type=click.IntRange(1, 1000), help="frames timed for FPS")
@click.option("--json", "as_json", is_flag=True, help="print the report's figures as JSON instead of Markdown")
def report_command(package_dir: Path, out_dir: Path | None, frames: int, as_json: bool) -> None:
    """Write the metrics report (Markdown and JSON): cloud-to-mesh, PSNR/SSIM/LPIPS, FPS.

    Example: drivetwin reconstruct report pkg/kerb_stone
    """
    from drivetwin.worlds.packages import AssetPackageError

    from .report import write_report

    try:
        report = write_report(package_dir, out_dir, frames)
    except AssetPackageError as exc:
        raise click.ClickException(str(exc)) from exc
    target = out_dir or package_dir
    if as_json:
        click.echo(json.dumps(report, indent=2))
        return
    click.echo((target / "reconstruction_report.md").read_text(encoding="utf-8"))
    click.echo(f"wrote {target / 'reconstruction_report.json'} ({report['render']['fps']:.1f} FPS)")


@reconstruct.command("show")
@click.argument("package_dir", type=click.Path(exists=True, file_okay=False, path_type=Path))
def show_command(package_dir: Path) -> None:
    """Print a package's manifest, or every problem that makes it unusable.

    Example: drivetwin reconstruct show pkg/kerb_stone
    """
    from drivetwin.worlds.packages import AssetPackage, AssetPackageError

    try:
        package = AssetPackage.load(package_dir)
    except AssetPackageError as exc:
        raise click.ClickException(str(exc)) from exc
    click.echo(json.dumps(package.manifest.model_dump(mode="json"), indent=2))


def add_reconstruct_parser(main: click.Group) -> None:
    """Register the `reconstruct` command group on the drivetwin CLI."""
    from .demo import demo_command

    reconstruct.add_command(demo_command)
    main.add_command(reconstruct)
