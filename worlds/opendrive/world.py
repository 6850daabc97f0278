"""A drivetwin Scene from a RoadMap: lanes, sidewalks, crossings, junction paving, props,
buildings and the names people use for places.

Map coordinates are kept when they fit a Scene (within ±10 km); a map further from its own
origin is shifted so its centre is the world origin.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from drivetwin.worlds.catalog import category
from drivetwin.worlds.opendrive.landmarks import MapPlace, place_landmarks
from drivetwin.worlds.opendrive.reader import MapLane, RoadMap
from drivetwin.worlds.scene import (
    EGO_ID,
    MAX_COORDINATE_M,
    AssetInstance,
    Bounds,
    Building,
    Crossing,
    DriveLane,
    Lane,
    PavedArea,
    PhysicsProps,
    Pose,
    RoadNetwork,
    Scene,
    Sidewalk,
)
from shapely import LineString, Polygon

__all__ = ["MapBuilding", "scene_from_map"]

# Centrelines are simplified to within this many metres of the library's evaluation.
SIMPLIFY_TOLERANCE_M = 0.02
# Heights below this everywhere on a lane mean the lane is flat (no elevation kept).
FLAT_M = 0.005
BOUNDS_MARGIN_M = 20.0
DEFAULT_SPEED_M_S = 8.0
# Imported props stop here, leaving room in the Scene's asset limit for the user's own.
MAX_PROPS = 200
EGO_SPEED_M_S = 5.0


@dataclass
class MapBuilding:
    """A building footprint (map coordinates) with its name and height, from OSM."""

    key: str
    name: str
    footprint: list[tuple[float, float]]
    height: float


def slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_")


def lane_id(lane: MapLane, sections: int) -> str:
    """A readable, unique lane id: road name, road id, side and number (and section)."""
    road_id, section, number = lane.key
    base = f"junction_{lane.junction}_{road_id}" if lane.junction else f"{slug(lane.road_name) or 'road'}_{road_id}"
    side = f"{'left' if number > 0 else 'right'}{abs(number)}"
    return f"{base}_{side}" + (f"_s{section}" if sections > 1 else "")


def scene_from_map(road_map: RoadMap, name: str, description: str,
                   buildings: Sequence[MapBuilding] = (), places: Sequence[MapPlace] = ()) -> Scene:
    """The Scene of an imported map (see the module docstring for the origin shift)."""
    drivable = [lane for lane in road_map.lanes if lane.kind != "sidewalk"]
    if not any(lane.kind == "driving" for lane in drivable):
        raise ValueError("the map has no driving lanes")
    everything = np.vstack([lane.points[:, :2] for lane in road_map.lanes]
                           + [np.asarray(b.footprint) for b in buildings])
    lo, hi = everything.min(axis=0), everything.max(axis=0)
    # Coordinates stay as they are when they fit (export then writes the source's frame back).
    fits = max(abs(lo).max(), abs(hi).max()) + BOUNDS_MARGIN_M < MAX_COORDINATE_M
    origin = np.zeros(2) if fits else np.round((lo + hi) / 2)
    sections: dict[str, int] = {}
    for lane in road_map.lanes:
        sections[lane.road_id] = max(sections.get(lane.road_id, 0), lane.key[1] + 1)
    ids = {lane.key: lane_id(lane, sections[lane.road_id]) for lane in road_map.lanes}
    lanes = [_lane(lane, ids, origin) for lane in drivable]
    walks = [Sidewalk(id=ids[lane.key], polyline=_simplified(lane.points - [*origin, 0])[0], width=lane.width)
             for lane in road_map.lanes if lane.kind == "sidewalk"]
    crossings = [Crossing(id=f"crossing_{k + 1}", start=_shift(c.start, origin), end=_shift(c.end, origin),
                          width=c.width) for k, c in enumerate(road_map.crossings)]
    paved = _junction_paving(road_map, origin)
    houses = [Building(id=f"building_{slug(b.key)}", name=b.name or f"building {b.key}",
                      footprint=[_shift(p, origin) for p in b.footprint], height=b.height) for b in buildings]
    roads = RoadNetwork(lanes=lanes, sidewalks=walks, crossings=crossings, paved=paved)
    low, high = lo - origin - BOUNDS_MARGIN_M, hi - origin + BOUNDS_MARGIN_M
    bounds = Bounds(xmin=float(low[0]), xmax=float(high[0]), ymin=float(low[1]), ymax=float(high[1]))
    shifted_places = [MapPlace(p.name, p.kind, *_shift((p.x, p.y), origin), p.polygon and
                               [_shift(q, origin) for q in p.polygon]) for p in places]
    landmarks = place_landmarks(road_map, roads, ids, (float(origin[0]), float(origin[1])), houses, shifted_places)
    return Scene(name=name, description=description, bounds=bounds, roads=roads, buildings=houses,
                 landmarks=landmarks, ego=_ego(lanes), assets=_props(road_map, origin))


def _shift(point: Sequence[float], origin: np.ndarray) -> tuple[float, float]:
    return (round(float(point[0] - origin[0]), 3), round(float(point[1] - origin[1]), 3))


def _simplified(points: np.ndarray) -> tuple[list[tuple[float, float]], list[float]]:
    """The polyline with the points that matter kept: within SIMPLIFY_TOLERANCE_M of the
    original in plan and, where it has heights, in its height profile (a crest on a straight
    road keeps its top)."""
    kept = _kept(points[:, :2])
    if points.shape[1] > 2:
        stations = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(points[:, :2], axis=0), axis=1))])
        kept |= _kept(np.column_stack([stations, points[:, 2]]))
    coords = points[sorted(kept)]
    xy = [(round(float(x), 3), round(float(y), 3)) for x, y in coords[:, :2]]
    z = [round(float(v), 3) for v in coords[:, 2]] if coords.shape[1] > 2 else [0.0] * len(xy)
    return xy, z


def _kept(line: np.ndarray) -> set[int]:
    """Indices of the vertices Douglas-Peucker keeps of the 2-D polyline `line` (ends always)."""
    simple = np.asarray(LineString(line).simplify(SIMPLIFY_TOLERANCE_M, preserve_topology=False).coords)
    first = {vertex: k for k, vertex in reversed(list(enumerate(map(tuple, line.tolist()))))}
    return {0, len(line) - 1} | {first[vertex] for vertex in map(tuple, simple.tolist())}


def _lane(lane: MapLane, ids: dict[tuple[str, int, int], str], origin: np.ndarray) -> Lane:
    xy, z = _simplified(lane.points - [*origin, 0])
    kind = lane.kind if lane.kind in ("driving", "shoulder", "border", "parking") else "driving"
    return Lane(id=ids[lane.key], road=lane.road_name or (f"junction {lane.junction}" if lane.junction else "road"),
                centreline=xy, width=lane.width, speed_limit=lane.speed_limit or DEFAULT_SPEED_M_S,
                kind=kind,
                elevation=z if max(abs(v) for v in z) > FLAT_M else None,
                successors=[ids[s] for s in lane.successors if s in ids])


def _junction_paving(road_map: RoadMap, origin: np.ndarray) -> list[PavedArea]:
    """Each junction's connecting lanes, as the convex hull of their strips."""
    by_junction: dict[str, list[MapLane]] = {}
    for lane in road_map.lanes:
        if lane.junction is not None and lane.kind == "driving":
            by_junction.setdefault(lane.junction, []).append(lane)
    paved = []
    for junction in road_map.junctions:
        lanes = by_junction.get(junction.id, [])
        if not lanes:
            continue
        # One vectorised buffer and hull per junction: building shapely Points one by one
        # took a third of a grid town's import.
        strips = shapely.buffer([LineString(lane.points[:, :2] - origin) for lane in lanes],
                                np.array([lane.width / 2 for lane in lanes]), cap_style="flat")
        hull = shapely.convex_hull(shapely.geometrycollections(strips))
        if not isinstance(hull, Polygon):
            continue
        ring = [(round(float(x), 3), round(float(y), 3)) for x, y in list(hull.exterior.coords)[:-1]]
        if len(ring) >= 3:
            paved.append(PavedArea(id=f"junction_{junction.id}", kind="intersection", polygon=ring))
    return paved


def _props(road_map: RoadMap, origin: np.ndarray) -> list[AssetInstance]:
    assets: list[AssetInstance] = []
    counts: dict[str, int] = {}
    for prop in road_map.props[:MAX_PROPS]:
        counts[prop.category] = counts.get(prop.category, 0) + 1
        spec = category(prop.category)
        x, y = _shift((prop.x, prop.y), origin)
        assets.append(AssetInstance(id=f"{prop.category}_{counts[prop.category]}", category=prop.category,
                                    pose=Pose(x=x, y=y, z=round(prop.z, 3), yaw=prop.yaw),
                                    physics=PhysicsProps(mass=spec.mass, dynamic=False)))
    return assets


def _ego(lanes: list[Lane]) -> AssetInstance:
    """The ego vehicle a quarter of the way along the longest driving lane, driving it."""
    from drivetwin.worlds.surface import point_along, polyline_length

    driving = [lane for lane in lanes if lane.kind == "driving"]
    lane = max(driving, key=lambda ln: polyline_length(ln.centreline))
    x, y, heading = point_along(lane.centreline, polyline_length(lane.centreline) / 4)
    ego = category("ego_vehicle")
    z = 0.0
    if lane.elevation is not None:
        z = float(np.interp(polyline_length(lane.centreline) / 4, _stations(lane.centreline), lane.elevation))
    return AssetInstance(id=EGO_ID, category=ego.name, pose=Pose(x=x, y=y, z=z, yaw=heading),
                         physics=PhysicsProps(mass=ego.mass),
                         behaviour=DriveLane(lane=lane.id, speed=min(EGO_SPEED_M_S, lane.speed_limit)),
                         label="ego vehicle")


def _stations(polyline: Sequence[tuple[float, float]]) -> list[float]:
    out = [0.0]
    for (x1, y1), (x2, y2) in itertools.pairwise(polyline):
        out.append(out[-1] + math.hypot(x2 - x1, y2 - y1))
    return out
