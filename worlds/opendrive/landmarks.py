"""Names for the places of an imported map: junctions ("the junction of Main Street and Oak
Avenue"), roads, road ends ("the north end of Oak Avenue"), named buildings and amenities."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from drivetwin.worlds.opendrive.reader import RoadMap
from drivetwin.worlds.scene import Building, Landmark, RoadNetwork
from shapely import LineString, Polygon

# Gaps between a road's blocks (junctions) up to this wide are closed in its area, metres.
JUNCTION_GAP_M = 30.0
# A road area's outline is simplified to within this, metres.
AREA_TOLERANCE_M = 0.2

__all__ = ["MapPlace", "place_landmarks"]


@dataclass
class MapPlace:
    """A named place from the source map (an OSM amenity or shop), world coordinates."""

    name: str
    kind: str
    x: float
    y: float
    polygon: list[tuple[float, float]] | None = None


def _and(names: Sequence[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def _junction_names(streets: list[str]) -> tuple[str, list[str]]:
    name = f"junction of {_and(streets)}"
    if len(streets) < 2:
        return name, [f"{streets[0]} junction"]
    a, b = streets[0], streets[1]
    aliases = [f"{_and(streets)} junction", f"intersection of {_and(streets)}", f"corner of {a} and {b}",
               f"junction of {b} and {a}", f"{a} and {b}", f"{b} and {a}", f"{a} / {b}"]
    return name, aliases


def _unique(name: str, taken: set[str]) -> str:
    candidate, n = name, 2
    while candidate.lower() in taken:
        candidate, n = f"{name} ({n})", n + 1
    taken.add(candidate.lower())
    return candidate


def place_landmarks(road_map: RoadMap, roads: RoadNetwork, ids: dict[tuple[str, int, int], str],
                    origin: tuple[float, float], buildings: Sequence[Building],
                    places: Sequence[MapPlace]) -> list[Landmark]:
    """Landmarks for junctions, roads and their ends, named buildings and places."""
    taken: set[str] = set()
    marks = _junctions(road_map, roads, taken) + _roads(roads, taken)
    for building in buildings:
        if building.name.startswith("building "):
            continue  # unnamed in the source
        xs, ys = zip(*building.footprint, strict=True)
        marks.append(Landmark(name=_unique(building.name, taken), kind="area", polygon=list(building.footprint),
                              position=(round(sum(xs) / len(xs), 3), round(sum(ys) / len(ys), 3)),
                              description=f"building from the source map ({building.height:g} m high)"))
    for place in places:
        if place.name.lower() in taken:
            continue
        marks.append(Landmark(name=_unique(place.name, taken), position=(place.x, place.y),
                              description=f"{place.kind.replace('_', ' ')} from the source map"))
    return marks


def _junctions(road_map: RoadMap, roads: RoadNetwork, taken: set[str]) -> list[Landmark]:
    marks = []
    paved = {area.id: area for area in roads.paved}
    for junction in road_map.junctions:
        area = paved.get(f"junction_{junction.id}")
        if area is None:
            continue
        streets = list(dict.fromkeys(road_map.road_names.get(r, "") for r in junction.incoming_roads))
        streets = sorted(s for s in streets if s)
        if junction.name and not junction.name.isdigit():
            name, aliases = junction.name, ([_junction_names(streets)[0]] if streets else [])
        elif streets:
            name, aliases = _junction_names(streets)
        else:
            name, aliases = f"junction {junction.id}", []
        xs, ys = zip(*area.polygon, strict=True)
        marks.append(Landmark(name=_unique(name, taken), aliases=[a for a in aliases if a.lower() not in taken],
                              position=(round(sum(xs) / len(xs), 3), round(sum(ys) / len(ys), 3)),
                              description=f"junction {junction.id} of the source map"))
        taken.update(a.lower() for a in marks[-1].aliases)
    return marks


def _road_area(lines: Sequence[np.ndarray], width: float) -> list[tuple[float, float]]:
    """The ground a road's lanes cover, its blocks joined across the junctions between them
    (so "the car on Main Street" is on it anywhere along it)."""
    strips = shapely.union_all([LineString(line).buffer(width / 2 + JUNCTION_GAP_M / 2) for line in lines])
    area = strips.buffer(-JUNCTION_GAP_M / 2).simplify(AREA_TOLERANCE_M)
    if not isinstance(area, Polygon):  # blocks too far apart to join: the longest names the road
        area = max(getattr(area, "geoms", [area]), key=lambda part: part.area)
    return [(round(float(x), 3), round(float(y), 3)) for x, y in list(area.exterior.coords)[:-1]]


def _roads(roads: RoadNetwork, taken: set[str]) -> list[Landmark]:
    """The road itself (at its middle) and its two ends, named by compass direction."""
    by_name: dict[str, list[np.ndarray]] = {}
    widths: dict[str, float] = {}
    for lane in roads.lanes:
        if lane.kind == "driving" and not lane.road.startswith("junction ") and lane.road != "road":
            by_name.setdefault(lane.road, []).append(np.asarray(lane.centreline))
            widths[lane.road] = max(widths.get(lane.road, 0.0), lane.width)
    marks = []
    for name, lines in sorted(by_name.items()):
        points = np.vstack(lines)
        centre = points.mean(axis=0)
        middle = points[int(np.argmin(np.linalg.norm(points - centre, axis=1)))]
        span = points.max(axis=0) - points.min(axis=0)
        axis = 0 if span[0] >= span[1] else 1
        low, high = points[int(np.argmin(points[:, axis]))], points[int(np.argmax(points[:, axis]))]
        heading = math.atan2(*(high - low)[::-1])
        marks.append(Landmark(name=_unique(name, taken), kind="area", polygon=_road_area(lines, widths[name]),
                              position=(float(middle[0]), float(middle[1])), heading=heading,
                              description="a road of the source map"))
        for end, point in zip(("west", "east") if axis == 0 else ("south", "north"), (low, high), strict=True):
            end_name = _unique(f"{end} end of {name}", taken)
            marks.append(Landmark(name=end_name, aliases=[f"the {end_name}", f"{name} {end} end"],
                                  position=(float(point[0]), float(point[1])), heading=heading,
                                  description=f"the {end} end of {name}"))
    return marks
