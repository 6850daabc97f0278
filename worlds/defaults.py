"""Worlds that can be loaded by name: the shipped ones, any in the user's world folders,
road maps imported with `drivetwin worlds import` (drivetwin.worlds.opendrive.package), and
reconstructed world packages (drivetwin.worlds.packages) on the asset search path.
A world name may also be the path of a map file (.xodr or .osm), read in place."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from drivetwin.worlds import paths
from drivetwin.worlds.packages import WORLD_SCENE, AssetPackage, AssetPackageError, discover_packages
from drivetwin.worlds.scene import Scene

if TYPE_CHECKING:
    from drivetwin.tools.plugins import PluginProblem

SHIPPED = Path(__file__).with_name("data")
# Extra folders of `NAME.json` worlds, separated like PATH (os.pathsep).
WORLD_PATH_ENV = "DRIVETWIN_WORLDS"


@dataclass(frozen=True)
class WorldEntry:
    """A loadable world: its name, where it lives and its one-line description."""

    name: str
    path: Path
    description: str
    # The world package folder (background splats, terrain) when the world was reconstructed.
    package: Path | None = None


def _folders() -> list[Path]:
    extra = [Path(p) for p in os.environ.get(WORLD_PATH_ENV, "").split(os.pathsep) if p]
    return [SHIPPED, *extra]


def list_worlds() -> list[WorldEntry]:
    """Every world found, shipped first; a later folder's world of the same name wins."""
    found: dict[str, WorldEntry] = {}
    for folder in _folders():
        for path in sorted(folder.glob("*.json")):
            try:
                scene = Scene.load(path)
            except ValueError:
                continue  # a damaged user file must not hide the other worlds
            first_line = scene.description.split(". ")[0]
            found[path.stem] = WorldEntry(path.stem, path, first_line)
    for entry in _imported_worlds():
        found[entry.name] = entry
    for entry in _packaged_worlds():
        found.setdefault(entry.name, entry)
    for entry in plugin_worlds()[0]:
        found.setdefault(entry.name, entry)
    return list(found.values())


def _imported_worlds() -> list[WorldEntry]:
    """Road-map worlds in the user's data folder (each a folder holding world.json)."""
    # Only the folder: listing worlds must not import the map reader (the roads extra).
    entries = []
    for path in sorted(paths.imported_worlds_dir().glob(f"*/{paths.IMPORTED_WORLD_FILE}")):
        try:
            scene = Scene.load(path)
        except ValueError:
            continue  # a damaged import must not hide the other worlds
        entries.append(WorldEntry(path.parent.name, path, scene.description.split(". ")[0]))
    return entries


def plugin_worlds() -> tuple[list[WorldEntry], list[PluginProblem]]:
    """Worlds that `drivetwin.worlds` plugins provide, and the plugins that failed.

    The entry point's name is the world's; its object is the path of a world JSON file the
    plugin ships (or a function returning it). A file that is not a Scene is a problem too.
    """
    # The one plugin loader lives with the tools (its box and deadline are there).
    from drivetwin.tools.plugins import WORLDS_GROUP, load_group

    def world_file(loaded: object) -> tuple[Path, str]:
        path = Path(loaded() if callable(loaded) else loaded)  # type: ignore[arg-type]
        return path, Scene.load(path).description.split(". ")[0]

    found = load_group(WORLDS_GROUP, world_file)
    entries = [WorldEntry(p.name, p.value[0], p.value[1]) for p in found.loaded]
    return entries, found.problems


def _packaged_worlds() -> list[WorldEntry]:
    entries = []
    for package in discover_packages("world"):
        path = package.root / WORLD_SCENE
        try:
            scene = Scene.load(path)
        except ValueError:
            continue
        entries.append(WorldEntry(package.name, path, scene.description.split(". ")[0], package.root))
    return entries


def load_world(name: str) -> Scene:
    """The world called `name` (a shipped name, a user world, or a path to a JSON file)."""
    as_path = Path(name)
    if as_path.suffix.lower() in (".xodr", ".osm") and as_path.is_file():
        from drivetwin.worlds.opendrive.package import scene_from_file

        return scene_from_file(as_path)
    if as_path.suffix == ".json" and as_path.exists():
        return _with_package(Scene.load(as_path), _package_of(as_path))
    for entry in reversed(list_worlds()):
        if entry.name == name:
            return _with_package(Scene.load(entry.path), entry.package)
    known = ", ".join(e.name for e in list_worlds()) or "none"
    raise UnknownWorldError(f"unknown world {name!r}; known worlds: {known}")


def _package_of(scene_file: Path) -> Path | None:
    """The world package holding `scene_file` (its world.json), or None for a plain world file."""
    if scene_file.name != WORLD_SCENE:
        return None
    try:
        package = AssetPackage.load(scene_file.parent)
    except AssetPackageError:
        return None  # a world.json outside a usable package is just a scene file
    return package.root if package.manifest.kind == "world" else None


def _with_package(scene: Scene, package: Path | None) -> Scene:
    """`scene` naming its world package (absolute), so physics and rendering find its files."""
    if package is not None:
        scene.package = str(package.resolve())
    return scene


class UnknownWorldError(LookupError):
    """A world name that no world folder has."""
