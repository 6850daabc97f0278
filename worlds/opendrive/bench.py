"""Benchmark road-map import: time per map and lane accuracy (the Scene's simplified lane
centrelines against pyxodr-omega-prime's own evaluation at 5 cm steps: max deviation, cm).

    python -m drivetwin.worlds.opendrive.bench --grid 10 --out bench_roads.json
    drivetwin bench roads --out bench_roads.json
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

import numpy as np
from drivetwin.worlds.opendrive import samples
from drivetwin.worlds.opendrive.package import scene_from_file
from drivetwin.worlds.opendrive.reader import read_opendrive
from drivetwin.worlds.opendrive.world import lane_id
from drivetwin.worlds.progress import progress_bar
from shapely import LineString, Point

# The library's evaluation step the Scene's lanes are measured against, metres.
REFERENCE_STEP_M = 0.05
# Reference points projecting within this distance of a lane's ends are not compared.
END_M = 1e-6
DATA = Path(__file__).parents[2] / "tests" / "data"


def _accuracy_cm(path: Path) -> float:
    """Max distance (cm) from the library's fine lane centre points to the Scene's lanes."""
    if path.suffix == ".osm":  # measured on netconvert's OpenDRIVE, as the import reads it
        from drivetwin.worlds.opendrive.osm import osm_to_opendrive

        with tempfile.TemporaryDirectory() as work:
            xodr, _ = osm_to_opendrive(path, Path(work))
            kept = path.with_name(f".{path.stem}.bench.xodr")
            kept.write_bytes(xodr.read_bytes())
        try:
            return _accuracy_cm(kept)
        finally:
            kept.unlink()
    scene = scene_from_file(path)
    reference = read_opendrive(path, step=REFERENCE_STEP_M)
    sections: dict[str, int] = {}
    for lane in reference.lanes:
        sections[lane.road_id] = max(sections.get(lane.road_id, 0), lane.key[1] + 1)
    mine = {lane.id: LineString(lane.centreline) for lane in scene.roads.lanes}
    worst = 0.0
    for lane in reference.lanes:
        line = mine.get(lane_id(lane, sections[lane.road_id]))
        if line is None:
            continue
        # Lateral error only: sampling moves a lane's ends by up to a step along the road.
        inside = [Point(p) for p in lane.points[:, :2] if END_M < line.project(Point(p)) < line.length - END_M]
        worst = max([worst, *(line.distance(p) for p in inside)])
    return 100.0 * worst


def measure(path: Path) -> dict[str, float | int | str]:
    started = time.perf_counter()
    scene = scene_from_file(path)  # first read: conversion and evaluation, nothing cached
    seconds = time.perf_counter() - started
    xs = [p[0] for lane in scene.roads.lanes for p in lane.centreline]
    ys = [p[1] for lane in scene.roads.lanes for p in lane.centreline]
    area = (max(xs) - min(xs)) * (max(ys) - min(ys)) / 1e6
    return {"map": path.name, "area_km2": round(area, 3), "lanes": len(scene.roads.lanes),
            "import_s": round(seconds, 3), "max_deviation_cm": round(_accuracy_cm(path), 2)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--grid", type=int, default=10, help="grid town size (n x n crossroads, 200 m apart)")
    parser.add_argument("--out", type=Path, default=None, help="write the figures as JSON here")
    args = parser.parse_args()
    import drivetwin.worlds.opendrive.reader as _warm  # noqa: F401  (library import not timed)
    import pyxodr_omega_prime.road_objects.network  # noqa: F401

    with tempfile.TemporaryDirectory() as work:
        folder = Path(work)
        paths = [samples.geometry_tour(folder / "tour.xodr"), samples.crossroads(folder / "crossroads.xodr"),
                 samples.grid_town(folder / f"grid{args.grid}.xodr", args.grid),
                 DATA / "town.osm", DATA / "spreewaldring.osm"]
        present = [path for path in paths if path.is_file()]
        rows = []
        with progress_bar("road maps", total=len(present), unit="maps") as bar:
            for path in present:
                rows.append(measure(path))
                bar.advance(note=path.name)
    print(f"{'map':22s} {'km²':>7s} {'lanes':>6s} {'import s':>9s} {'max dev cm':>11s}")
    for row in rows:
        print(f"{row['map']!s:22s} {row['area_km2']:>7} {row['lanes']:>6} {row['import_s']:>9} {row['max_deviation_cm']:>11}")
    if args.out is not None:
        args.out.write_text(json.dumps({"rows": rows, "reference_step_m": REFERENCE_STEP_M,
                                        "numpy": np.__version__}, indent=2), encoding="utf-8")


if __name__ == "__main__":
    main()
