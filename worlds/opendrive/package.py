"""Road-map worlds: import an OpenDRIVE or OSM file into a world folder in the user's data
folder, or read one straight into a Scene.

    <data>/worlds/NAME/
      world.json    the Scene (loads by name everywhere a world is named)
      map.xodr      the OpenDRIVE the world was built from (OSM imports: netconvert's output)
      import.json   source file, kind, counts and timings of the import

<data> is $DRIVETWIN_DATA, else $XDG_DATA_HOME/drivetwin, else ~/.local/share/drivetwin.
"""

from __future__ import annotations

import json
import pickle
import re
import shutil
import tempfile
import time
from dataclasses import asdict, dataclass
from functools import lru_cache
from pathlib import Path

from drivetwin.worlds import paths
from drivetwin.worlds.opendrive.osm import osm_to_opendrive, read_osm_places
from drivetwin.worlds.opendrive.reader import MapReadError, read_opendrive
from drivetwin.worlds.opendrive.world import scene_from_map
from drivetwin.worlds.scene import Scene

__all__ = ["DATA_ENV", "MAP_SUFFIXES", "ImportReport", "MapImportError", "import_map", "scene_from_file",
           "user_world_folder"]

DATA_ENV = paths.ENV_DATA
MAP_SUFFIXES = (".xodr", ".osm")
WORLD_FILE = paths.IMPORTED_WORLD_FILE
MAP_FILE = "map.xodr"
REPORT_FILE = "import.json"
_NAME = re.compile(r"^[a-z][a-z0-9_-]{0,39}$")


class MapImportError(ValueError):
    """A map file or world name that cannot be imported; nothing was written."""


@dataclass(frozen=True)
class ImportReport:
    name: str
    folder: str
    source: str
    kind: str
    lanes: int
    sidewalks: int
    crossings: int
    junctions: int
    buildings: int
    landmarks: int
    props: int
    seconds: float


def user_world_folder() -> Path:
    """Where imported worlds live (see the module docstring)."""
    return paths.imported_worlds_dir()


def _kind(source: Path) -> str:
    suffix = source.suffix.lower()
    if suffix not in MAP_SUFFIXES:
        raise MapImportError(f"{source.name}: a map file ends in .xodr (OpenDRIVE) or .osm (OpenStreetMap)")
    if not source.is_file():
        raise MapImportError(f"no map file at {source}")
    return suffix[1:]


def _build(source: Path, name: str, workdir: Path) -> tuple[Scene, Path]:
    kind = _kind(source)
    try:
        if kind == "osm":
            xodr, net = osm_to_opendrive(source, workdir)
            buildings, places = read_osm_places(source, net, workdir)
            description = f"Imported from the OpenStreetMap file {source.name}"
        else:
            xodr, buildings, places = source, [], []
            description = f"Imported from the OpenDRIVE file {source.name}"
        road_map = read_opendrive(xodr)
        scene = scene_from_map(road_map, name, description + f": {len(road_map.lanes)} lanes.", buildings, places)
    except (MapReadError, RuntimeError, ValueError) as exc:
        raise MapImportError(f"cannot import {source.name}: {exc}") from exc
    return scene, xodr


def scene_from_file(path: str | Path) -> Scene:
    """The Scene of a map file, read in place (cached while the file is unchanged)."""
    source = Path(path).resolve()
    _kind(source)
    copy: Scene = pickle.loads(_cached_scene(str(source), source.stat().st_mtime_ns))
    return copy


@lru_cache(maxsize=4)
def _cached_scene(source: str, mtime_ns: int) -> bytes:
    """The Scene pickled: each caller gets its own copy, four times faster than a deep copy
    (the bytes are this process's own, never read from elsewhere)."""
    with tempfile.TemporaryDirectory(prefix="drivetwin-map-") as work:
        scene, _ = _build(Path(source), Path(source).stem.lower(), Path(work))
    return pickle.dumps(scene, protocol=pickle.HIGHEST_PROTOCOL)


def import_map(source: str | Path, name: str, folder: Path | None = None, replace: bool = False) -> ImportReport:
    """Build the world folder NAME from the map file `source`; it then loads by name."""
    if not _NAME.match(name):
        raise MapImportError(f"world name {name!r}: use 1-40 lower-case letters, digits, '_' or '-', "
                             "starting with a letter")
    from drivetwin.worlds.defaults import SHIPPED

    if (SHIPPED / f"{name}.json").exists():
        raise MapImportError(f"world name {name!r} is a shipped world's; choose another")
    root = (folder or user_world_folder()) / name
    if root.exists() and not replace:
        raise MapImportError(f"a world called {name!r} exists at {root}; pass --replace to overwrite it")
    started = time.perf_counter()
    src = Path(source)
    with tempfile.TemporaryDirectory(prefix="drivetwin-map-") as work:
        scene, xodr = _build(src, name, Path(work))
        staging = Path(tempfile.mkdtemp(prefix=f".{name}-", dir=_parent(root)))
        shutil.copyfile(xodr, staging / MAP_FILE)
    scene.save(staging / WORLD_FILE)
    report = ImportReport(
        name=name, folder=str(root), source=str(src.resolve()), kind=_kind(src), lanes=len(scene.roads.lanes),
        sidewalks=len(scene.roads.sidewalks), crossings=len(scene.roads.crossings),
        junctions=sum(1 for p in scene.roads.paved if p.kind == "intersection"), buildings=len(scene.buildings),
        landmarks=len(scene.landmarks), props=len(scene.assets), seconds=round(time.perf_counter() - started, 3))
    (staging / REPORT_FILE).write_text(json.dumps(asdict(report), indent=2), encoding="utf-8")
    if root.exists():
        shutil.rmtree(root)
    staging.replace(root)
    return report


def _parent(root: Path) -> Path:
    root.parent.mkdir(parents=True, exist_ok=True)
    return root.parent
