"""The asset package format: round trip, catalog fields, typed errors, discovery."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest
from click.testing import CliRunner
from drivetwin.worlds.catalog import catalog, package_category, placeable_categories, resolve_category
from drivetwin.worlds.packages import AssetPackage, AssetPackageError, discover_packages
from drivetwin.worlds.reconstruct.fusion import fuse
from drivetwin.worlds.reconstruct.materials import DENSITY_KG_M3
from fusion_capture import PIECES, fused_package, write_world_halves


@pytest.fixture(scope="module")
def package_dir(tmp_path_factory):
    return fused_package(
        tmp_path_factory.mktemp("assets") / "kerb_stone",
        material="stone",
        tags=["street furniture"],
        synonyms=["kerb stone", "curb post"],
    )


@pytest.fixture
def assets_env(monkeypatch, tmp_path):
    """Search only the given folders (never the user's own asset folder)."""
    monkeypatch.setenv("DRIVETWIN_CACHE", str(tmp_path / "cache"))

    def use(*folders):
        monkeypatch.setenv("DRIVETWIN_ASSETS", ":".join(str(f) for f in folders))

    return use


def test_a_fused_package_loads_back_with_its_catalog_fields(package_dir):
    package = AssetPackage.load(package_dir)
    m = package.manifest
    assert (m.name, m.kind, m.material) == ("kerb_stone", "asset", "stone")
    # The pieces span x -0.8..0.8, y -0.25..0.5, z 0..1.3 around the capture offset.
    assert (m.dimensions.length, m.dimensions.width, m.dimensions.height) == pytest.approx((1.6, 0.75, 1.3))
    volume = sum(float(np.prod(extents)) for extents, _, _ in PIECES)
    assert m.volume_m3 == pytest.approx(volume, rel=1e-6)
    assert m.mass == pytest.approx(volume * DENSITY_KG_M3["stone"], rel=1e-6)
    low, high = package.mesh().bounds
    assert low[2] == pytest.approx(0.0, abs=1e-9)  # asset frame: origin at the bottom centre
    assert (low[:2] + high[:2]) / 2 == pytest.approx([0.0, 0.0], abs=1e-9)
    assert len(package.hulls()) == len(PIECES)
    assert set(m.files) >= {"collision/mesh.obj", "visual/splats.ply", "collision/hull_000.obj"}
    cat = package_category(package)
    assert cat.package == str(package_dir.resolve()) and "reconstructed" in cat.tags
    assert cat.parts[0].size == pytest.approx((0.8, 0.375, 0.65))


def test_missing_hulls_are_a_typed_error_that_names_them(package_dir, tmp_path):
    broken = shutil.copytree(package_dir, tmp_path / "broken")
    for hull in broken.glob("collision/hull_*.obj"):
        hull.unlink()
    with pytest.raises(AssetPackageError) as caught:
        AssetPackage.load(broken)
    assert "collision/hull_" in str(caught.value) and "missing collision/hull_000.obj" in caught.value.problems


def test_a_missing_manifest_or_a_bad_field_is_a_typed_error(package_dir, tmp_path):
    no_manifest = shutil.copytree(package_dir, tmp_path / "a")
    (no_manifest / "asset.json").unlink()
    with pytest.raises(AssetPackageError, match=r"missing asset\.json"):
        AssetPackage.load(no_manifest)
    bad = shutil.copytree(package_dir, tmp_path / "b")
    manifest = json.loads((bad / "asset.json").read_text())
    manifest["mass"] = -3
    manifest["kind"] = "vehicle"
    (bad / "asset.json").write_text(json.dumps(manifest))
    with pytest.raises(AssetPackageError) as caught:
        AssetPackage.load(bad)
    assert any(p.startswith("asset.json: mass") for p in caught.value.problems)
    assert any(p.startswith("asset.json: kind") for p in caught.value.problems)


def test_an_unknown_material_is_refused_naming_the_known_ones(tmp_path):
    with pytest.raises(AssetPackageError, match="unknown material 'unobtainium'; known: asphalt"):
        fused_package(tmp_path / "x", material="unobtainium")


def test_packages_on_the_search_path_join_the_catalog_and_broken_ones_are_skipped(package_dir, tmp_path, assets_env):
    broken = shutil.copytree(package_dir, tmp_path / "shelf" / "broken_copy")
    (broken / "visual" / "splats.ply").unlink()
    assets_env(package_dir, tmp_path / "shelf")
    problems: list[str] = []
    assert [p.name for p in discover_packages(problems=problems)] == ["kerb_stone"]
    assert len(problems) == 1 and "missing visual/splats.ply" in problems[0]
    assert catalog()["kerb_stone"].package is not None
    assert "kerb_stone" in placeable_categories()
    assert resolve_category("curb posts") == "kerb_stone"
    assets_env()
    assert "kerb_stone" not in catalog()


def test_worlds_list_shows_a_world_package(tmp_path, assets_env):
    from drivetwin.orchestrator.cli import main
    from drivetwin.worlds.defaults import load_world

    world = tmp_path / "packages" / "scanned_lot"
    world.mkdir(parents=True)
    write_world_halves(world)
    package = fuse(world, description="A scanned parking lot. Gentle slope.")
    assert package.manifest.kind == "world"
    assets_env(tmp_path / "packages")
    result = CliRunner().invoke(main, ["worlds", "list"])
    assert result.exit_code == 0, result.output
    line = next(line for line in result.output.splitlines() if line.startswith("scanned_lot"))
    assert "A scanned parking lot" in line
    scene = load_world("scanned_lot")
    assert scene.bounds.xmin < -15.0 and scene.bounds.xmax > 15.0
