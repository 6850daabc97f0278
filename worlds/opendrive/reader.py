"""Read an OpenDRIVE file into plain road parts with pyxodr-omega-prime.

Why this reader: the candidates installable here were compared (November 2026):
- `pyxodr-omega-prime` 0.1.5 (May 2025, MIT): evaluates line, arc, spiral, poly3 and
  paramPoly3 reference lines, lane widths and borders, lane offsets and elevation to
  points; links lanes through junctions; the fork of `pyxodr` that the omega-prime project
  (RWTH ika) maintains, with its exception-handling fixes. Pure Python on numpy/shapely.
- `pyxodr` 0.1.3: the original, unchanged since August 2023.
- `pyopendrive` 0.2.0 (2026): needs Python >= 3.12; drivetwin is on 3.11.
- `opendrive2lanelet` 1.2.1 (2021, CommonRoad): converts to lanelets, unmaintained.
- `maliput-malidrive`: a C++ road-runtime backend, far more than reading a map needs.
So pyxodr-omega-prime: maintained, complete on geometry, light to install.

Every driving, shoulder, border and parking lane becomes a MapLane (its centreline in the
direction traffic flows, with heights); sidewalk lanes become sidewalks; crosswalk objects
become crossings; signals and a few object types become catalog assets (MapProp).
"""

from __future__ import annotations

import io
import math
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
from lxml import etree

__all__ = ["MapCrossing", "MapJunction", "MapLane", "MapProp", "RoadMap", "read_opendrive", "reference_pose"]

Array = npt.NDArray[np.float64]
# Sampling step of reference lines (m): an arc of 20 m radius sampled at 0.5 m strays
# 1.6 mm from its chords, far under what drivetwin's lanes need.
SAMPLE_STEP_M = 0.5
LANE_KINDS = {"driving": "driving", "shoulder": "shoulder", "border": "border", "parking": "parking",
              "stop": "shoulder", "entry": "driving", "exit": "driving", "onRamp": "driving",
              "offRamp": "driving", "connectingRamp": "driving", "bidirectional": "driving"}
# Curvatures closer than this (1/m) are equal: a spiral between them is an arc.
CONSTANT_CURVATURE = 1e-12
SIDEWALK_KINDS = {"sidewalk", "walking"}
# Signals further apart than this are separate props (SUMO writes one per signal head).
SAME_PROP_M = 1.5
# OpenDRIVE signal types (German StVO and US MUTCD codes, as maps write them) drivetwin has assets for.
SIGN_CATEGORIES = {"206": "stop_sign", "R1-1": "stop_sign", "350": "pedestrian_sign", "R9-7": "pedestrian_sign",
                   "314": "parking_sign", "R7-8": "parking_sign"}
OBJECT_CATEGORIES = {"tree": "tree", "vegetation": "tree", "streetlamp": "street_light", "pole": "street_light"}


class MapReadError(ValueError):
    """An OpenDRIVE file that cannot be read."""


@dataclass
class MapLane:
    key: tuple[str, int, int]  # (road id, lane section index, OpenDRIVE lane id)
    road_id: str
    road_name: str
    junction: str | None
    kind: str  # driving, shoulder, border, parking or sidewalk
    points: Array  # (N, 3): x, y, z along the direction of travel
    width: float
    speed_limit: float | None
    successors: list[tuple[str, int, int]] = field(default_factory=list)


@dataclass
class MapCrossing:
    key: str
    start: tuple[float, float]
    end: tuple[float, float]
    width: float


@dataclass
class MapProp:
    category: str
    x: float
    y: float
    z: float
    yaw: float


@dataclass
class MapJunction:
    id: str
    name: str
    incoming_roads: list[str]


@dataclass
class RoadMap:
    lanes: list[MapLane]
    crossings: list[MapCrossing]
    props: list[MapProp]
    junctions: list[MapJunction]
    road_names: dict[str, str]  # road id -> name ("" when unnamed)


def read_opendrive(path: str | Path, step: float = SAMPLE_STEP_M) -> RoadMap:
    """Everything drivetwin uses from the OpenDRIVE file at `path`."""
    from pyxodr_omega_prime.road_objects.network import RoadNetwork

    source = Path(path)
    if not source.is_file():
        raise MapReadError(f"no OpenDRIVE file at {source}")
    try:
        network = RoadNetwork(_normalised(source), resolution=step)
        roads = network.get_roads()
        junctions = network.get_junctions()
    except (OSError, etree.XMLSyntaxError) as exc:
        raise MapReadError(f"{source} is not an XML file: {exc}") from exc
    except Exception as exc:  # lxml and pyxodr raise many kinds; all mean "not a usable map"
        raise MapReadError(f"{source} is not a readable OpenDRIVE file: {type(exc).__name__}: {exc}") from exc
    if not roads:
        raise MapReadError(f"{source} has no roads")
    names = {str(road.id): _road_name(road.road_xml) for road in roads}
    lanes: list[MapLane] = []
    crossings: list[MapCrossing] = []
    props: list[MapProp] = []
    for road in roads:
        lanes.extend(_lanes_of(road, names))
        crossings.extend(_crossings_of(road))
        props.extend(_props_of(road))
    touching = _roads_at_junctions(roads)
    return RoadMap(lanes, crossings, _merge_props(props), [_junction(j, touching) for j in junctions], names)


def _normalised(source: Path) -> io.BytesIO:
    """The file with what pyxodr cannot evaluate rewritten to equal geometry.

    A spiral whose curvature does not change is an arc (or a line); pyxodr divides by the
    curvature's rate of change, and junction generators write such spirals.
    """
    tree = etree.parse(str(source))
    for spiral in tree.getroot().iter("spiral"):
        start, end = float(spiral.get("curvStart", 0)), float(spiral.get("curvEnd", 0))
        if abs(end - start) < CONSTANT_CURVATURE:
            geometry = spiral.getparent()
            geometry.remove(spiral)
            if abs(start) < CONSTANT_CURVATURE:
                etree.SubElement(geometry, "line")
            else:
                etree.SubElement(geometry, "arc", curvature=repr(start))
    return io.BytesIO(etree.tostring(tree))


def _road_name(road_xml: Any) -> str:
    name = str(road_xml.attrib.get("name", "")).strip()
    # netconvert names junction-internal roads after SUMO's internal edges (":1001_0").
    return "" if name.startswith(":") or re.fullmatch(r"(road\s*)?\d+", name, re.I) else name


def _speed_of(road_xml: Any) -> float | None:
    speed = road_xml.find("type/speed")
    if speed is None or "max" not in speed.attrib:
        return None
    try:
        value = float(speed.attrib["max"])
    except ValueError:
        return None  # "no limit" and "undefined" are allowed values
    factor = {"km/h": 1 / 3.6, "mph": 0.44704}.get(speed.attrib.get("unit", "m/s"), 1.0)
    return value * factor if value > 0 else None


def _lanes_of(road: Any, names: dict[str, str]) -> Iterable[MapLane]:
    road_id = str(road.id)
    junction = str(road.road_xml.attrib.get("junction", "-1"))
    speed = _speed_of(road.road_xml)
    for section_index, section in enumerate(road.lane_sections):
        for lane in section.lanes:
            lane_type = lane.type
            kind = "sidewalk" if lane_type in SIDEWALK_KINDS else LANE_KINDS.get(lane_type or "")
            if kind is None:
                continue
            points = np.asarray(lane.traffic_flow_line, dtype=float)
            reference = np.asarray(lane.lane_reference_line, dtype=float)[:, :2]
            boundary = np.asarray(lane.boundary_line, dtype=float)[:, :2]
            if len(points) < 2 or reference.shape != boundary.shape or not np.isfinite(points).all():
                continue
            widths = np.linalg.norm(boundary - reference, axis=1)
            width = float(np.mean(widths))
            if width < 0.3 or _length(points) < 0.5:
                continue  # a lane that only opens or closes within this section
            successors = [(str(s.road_id), int(s.lane_section_id), int(s.id)) for s in lane.traffic_flow_successors]
            yield MapLane((road_id, section_index, int(lane.id)), road_id, names[road_id],
                          None if junction == "-1" else junction, kind, points, width, speed, successors)


def _length(points: Array) -> float:
    return float(np.linalg.norm(np.diff(points[:, :2], axis=0), axis=1).sum())


def reference_pose(road: Any, s: float, t: float) -> tuple[float, float, float]:
    """(x, y, heading) of the point at road coordinates (s, t) on `road`'s reference line."""
    line = np.asarray(road.reference_line, dtype=float)[:, :2]
    steps = np.linalg.norm(np.diff(line, axis=0), axis=1)
    travelled = np.concatenate([[0.0], np.cumsum(steps)])
    index = int(np.clip(np.searchsorted(travelled, s) - 1, 0, len(line) - 2))
    seg = max(float(steps[index]), 1e-12)
    frac = float(np.clip((s - travelled[index]) / seg, 0.0, 1.0))
    a, b = line[index], line[index + 1]
    heading = math.atan2(b[1] - a[1], b[0] - a[0])
    x, y = a + frac * (b - a)
    return (float(x - t * math.sin(heading)), float(y + t * math.cos(heading)), heading)


def _crossings_of(road: Any) -> Iterable[MapCrossing]:
    for obj in road.road_xml.findall("objects/object"):
        if str(obj.attrib.get("type", "")).lower() != "crosswalk":
            continue
        x, y, heading = reference_pose(road, float(obj.attrib.get("s", 0)), float(obj.attrib.get("t", 0)))
        yaw = heading + float(obj.attrib.get("hdg", 0))
        corners = [(float(c.attrib["u"]), float(c.attrib["v"])) for c in obj.findall("outline/cornerLocal")]
        if corners:
            us, vs = [u for u, _ in corners], [v for _, v in corners]
            u_mid, v_lo, v_hi, along = (max(us) + min(us)) / 2, min(vs), max(vs), max(us) - min(us)
        else:
            half = float(obj.attrib.get("width", 0)) / 2
            u_mid, v_lo, v_hi, along = 0.0, -half, half, float(obj.attrib.get("length", 0))
        if v_hi - v_lo < 0.5 or along < 0.3:
            continue

        def world(u: float, v: float, x: float = x, y: float = y, yaw: float = yaw) -> tuple[float, float]:
            return (x + u * math.cos(yaw) - v * math.sin(yaw), y + u * math.sin(yaw) + v * math.cos(yaw))

        # Pedestrians cross along the object's v axis (across the road); u is the stripe width.
        yield MapCrossing(str(obj.attrib.get("id", "")), world(u_mid, v_lo), world(u_mid, v_hi), along)


def _props_of(road: Any) -> Iterable[MapProp]:
    for signal in road.road_xml.findall("signals/signal"):
        kind = str(signal.attrib.get("type", ""))
        if signal.attrib.get("dynamic") == "yes" or kind.startswith("1000001") or kind.startswith("1000011"):
            category = "traffic_light"
        elif kind in SIGN_CATEGORIES:
            category = SIGN_CATEGORIES[kind]
        else:
            continue
        yield _prop(road, signal, category, facing_back=signal.attrib.get("orientation") != "-")
    for obj in road.road_xml.findall("objects/object"):
        object_category = OBJECT_CATEGORIES.get(str(obj.attrib.get("type", "")).lower())
        if object_category is not None:
            yield _prop(road, obj, object_category, facing_back=False)


def _prop(road: Any, element: Any, category: str, facing_back: bool) -> MapProp:
    s, t = float(element.attrib.get("s", 0)), float(element.attrib.get("t", 0))
    x, y, heading = reference_pose(road, s, t)
    z = float(np.interp(s, np.linspace(0.0, float(road.road_xml.attrib.get("length", s) or s), len(road.z_coordinates)),
                        road.z_coordinates)) if len(road.z_coordinates) else 0.0
    # A signal faces the traffic it controls: traffic along +s sees it facing -s.
    return MapProp(category, x, y, z, heading + (math.pi if facing_back else 0.0))


def _merge_props(props: list[MapProp]) -> list[MapProp]:
    kept: list[MapProp] = []
    for prop in props:
        if not any(k.category == prop.category and math.hypot(k.x - prop.x, k.y - prop.y) < SAME_PROP_M for k in kept):
            kept.append(prop)
    return kept


def _roads_at_junctions(roads: list[Any]) -> dict[str, set[str]]:
    """Junction id -> ids of the roads whose ends link to it."""
    touching: dict[str, set[str]] = {}
    for road in roads:
        for end in road.road_xml.findall("link/*"):
            if end.get("elementType") == "junction":
                touching.setdefault(str(end.get("elementId")), set()).add(str(road.id))
    return touching


def _junction(junction: Any, touching: dict[str, set[str]]) -> MapJunction:
    # Every road the junction joins: a one-way street leaving it is not "incoming" but names it too.
    incoming = sorted({str(r) for r in junction.get_incoming_road_ids()} | touching.get(str(junction.id), set()))
    return MapJunction(str(junction.id), str(junction.junction_xml.attrib.get("name", "")).strip(), incoming)
