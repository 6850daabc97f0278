"""OpenStreetMap files to OpenDRIVE with SUMO's netconvert, and their buildings and named
places with SUMO's polyconvert (both from the `eclipse-sumo` wheel, run as subprocesses).

polyconvert projects the OSM polygons with the network netconvert wrote, so buildings and
roads share coordinates.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

from drivetwin.worlds.opendrive.landmarks import MapPlace
from drivetwin.worlds.opendrive.world import MapBuilding
from lxml import etree

__all__ = ["OsmConversionError", "osm_to_opendrive", "read_osm_places"]

# netconvert on a city district takes seconds; far longer means something is wrong.
TOOL_TIMEOUT_S = 300.0
NETCONVERT_OPTIONS = (
    "--output.street-names",  # road names for landmarks
    "--osm.sidewalks",  # sidewalks where the OSM ways say so
    "--crossings.guess",  # zebra crossings at junctions with sidewalks
    "--junctions.join",  # one junction where OSM has several nodes close together
    "--no-turnarounds",
    "--no-warnings",
)
# Height of a building whose OSM way gives neither height nor levels; metres per level.
DEFAULT_BUILDING_HEIGHT_M = 9.0
LEVEL_HEIGHT_M = 3.0


class OsmConversionError(RuntimeError):
    """netconvert or polyconvert could not convert an OSM file."""


def _sumo() -> tuple[Path, dict[str, str]]:
    try:
        import sumo
    except ImportError as exc:
        raise OsmConversionError("OSM import needs SUMO: pip install 'drivetwin[roads]'") from exc
    home = Path(sumo.SUMO_HOME)
    env = {**os.environ, "SUMO_HOME": str(home), "PROJ_DATA": str(home / "data" / "proj")}
    return home, env


def _run(tool: str, args: list[str]) -> None:
    home, env = _sumo()
    try:
        done = subprocess.run([str(home / "bin" / tool), *args], env=env, capture_output=True, text=True,
                              timeout=TOOL_TIMEOUT_S, check=False)
    except subprocess.TimeoutExpired as exc:
        raise OsmConversionError(f"{tool} took longer than {TOOL_TIMEOUT_S:g} s") from exc
    if done.returncode != 0:
        lines = [line for line in (done.stderr or done.stdout).splitlines() if line.strip()]
        raise OsmConversionError(f"{tool} failed: {lines[-1] if lines else f'exit {done.returncode}'}")


def osm_to_opendrive(osm: Path, workdir: Path) -> tuple[Path, Path]:
    """Convert `osm` to `workdir`/map.xodr; return it and SUMO's network (for polyconvert)."""
    if not osm.is_file():
        raise OsmConversionError(f"no OSM file at {osm}")
    xodr, net = workdir / "map.xodr", workdir / "map.net.xml"
    _run("netconvert", ["--osm-files", str(osm), "--opendrive-output", str(xodr), "-o", str(net),
                        *NETCONVERT_OPTIONS])
    return xodr, net


def read_osm_places(osm: Path, net: Path, workdir: Path) -> tuple[list[MapBuilding], list[MapPlace]]:
    """Building footprints and named amenities of `osm`, in the network's coordinates."""
    home, _ = _sumo()
    polys = workdir / "polygons.xml"
    _run("polyconvert", ["--net-file", str(net), "--osm-files", str(osm), "--type-file",
                         str(home / "data" / "typemap" / "osmPolyconvert.typ.xml"), "--osm.keep-full-type",
                         "--all-attributes", "-o", str(polys)])
    buildings: dict[str, MapBuilding] = {}
    places: list[MapPlace] = []
    for element in etree.parse(str(polys)).getroot():
        params = {p.get("key"): p.get("value") for p in element.findall("param")}
        name = (params.get("name") or "").strip()
        kind = str(element.get("type", ""))
        base = str(element.get("id", "")).split("#")[0]
        if element.tag == "poly" and params.get("building"):
            shape = [tuple(float(v) for v in pair.split(",")[:2]) for pair in str(element.get("shape")).split()]
            ring = [(x, y) for x, y in shape]
            if len(ring) > 3 and ring[0] == ring[-1]:
                ring = ring[:-1]
            if len(ring) >= 3 and base not in buildings:
                buildings[base] = MapBuilding(base, name, ring, _height(params))
        elif element.tag == "poi" and name:
            x, y = float(element.get("x", 0)), float(element.get("y", 0))
            places.append(MapPlace(name, kind.split(".")[-1], x, y))
    return list(buildings.values()), places


def _height(params: dict[str | None, str | None]) -> float:
    for key, scale in (("height", 1.0), ("building:levels", LEVEL_HEIGHT_M)):
        try:
            value = float(str(params.get(key, "")).split()[0]) * scale
        except (ValueError, IndexError):
            continue
        if value > 0:
            return value
    return DEFAULT_BUILDING_HEIGHT_M
