"""OpenDRIVE maps generated with scenariogeneration: test and benchmark maps, never downloaded.

- `geometry_tour`: one road through every plan-view geometry OpenDRIVE has (line, spiral,
  arc, poly3, paramPoly3), two lane sections whose right lane widens, a sidewalk, a slope.
- `crossroads`: Main Street and Oak Avenue meeting in a four-way junction with connecting
  lanes, a traffic light and a zebra crossing.
- `grid_town`: an n x n grid of crossroads, for import-time measurements of larger maps.
"""

from __future__ import annotations

import math
from pathlib import Path

from lxml import etree

__all__ = ["crossroads", "geometry_tour", "grid_town"]

ARM_LENGTH_M = 80.0
LANE_WIDTH_M = 3.5
# Gradient of the tour road: 2 % climbs 3 m over its 150 m.
TOUR_GRADIENT = 0.02


def geometry_tour(path: str | Path) -> Path:
    """Write the geometry tour map to `path` and return it."""
    from scenariogeneration import xodr

    planview = xodr.PlanView(0.0, 0.0, 0.0)
    planview.add_geometry(xodr.Line(40.0))
    planview.add_geometry(xodr.Spiral(0.0001, 0.02, 30.0))
    planview.add_geometry(xodr.Arc(0.02, angle=0.5))
    planview.add_geometry(xodr.ParamPoly3(0, 1, 0, 0, 0, 0, 0.004, -0.0001, "arcLength", 30.0))
    planview.add_geometry(xodr.Line(25.0))  # becomes a poly3 below (scenariogeneration writes none)
    lanes = xodr.Lanes()
    for s, widen in ((0.0, 0.0), (60.0, 0.01)):
        section = xodr.LaneSection(s, xodr.standard_lane())
        section.add_left_lane(xodr.standard_lane(LANE_WIDTH_M))
        section.add_right_lane(xodr.Lane(a=LANE_WIDTH_M - 0.5 if widen else LANE_WIDTH_M, b=widen))
        section.add_right_lane(xodr.Lane(lane_type=xodr.LaneType.sidewalk, a=2.0))
        lanes.add_lanesection(section)
    road = xodr.Road(1, planview, lanes, name="Tour Road")
    road.add_elevation(0.0, 0.0, TOUR_GRADIENT, 0.0, 0.0)
    odr = xodr.OpenDrive("geometry_tour")
    odr.add_road(road)
    odr.adjust_roads_and_lanes()
    target = Path(path)
    odr.write_xml(str(target))
    _last_line_to_poly3(target)
    return target


def _last_line_to_poly3(path: Path) -> None:
    """Turn the road's last <line/> into the equivalent cubic <poly3> with a gentle bend."""
    tree = etree.parse(str(path))
    geometry = tree.getroot().findall("road/planView/geometry")[-1]
    line = geometry.find("line")
    assert line is not None
    geometry.remove(line)
    # v(u) = 0.002 u^2: a 25 m long gentle left bend (arc length ~ u for such a small slope).
    etree.SubElement(geometry, "poly3", a="0", b="0", c="0.002", d="0")
    tree.write(str(path), xml_declaration=True, encoding="UTF-8")


def crossroads(path: str | Path, first_id: int = 1, junction_id: int = 100) -> Path:
    """Write a four-way junction of Main Street (east-west) and Oak Avenue (north-south)."""
    from scenariogeneration import xodr

    drive = xodr.OpenDrive("crossroads")
    creator = xodr.CommonJunctionCreator(junction_id, "", startnum=first_id + 100)
    arms = [("Main Street", 0.0), ("Oak Avenue", math.pi / 2), ("Main Street", math.pi), ("Oak Avenue", -math.pi / 2)]
    radius = 12.0
    for k, (name, angle) in enumerate(arms):
        road = xodr.create_road(xodr.Line(ARM_LENGTH_M), first_id + k, left_lanes=1, right_lanes=1,
                                lane_width=LANE_WIDTH_M)
        road.name = name
        creator.add_incoming_road_cartesian_geometry(
            road, radius * math.cos(angle), radius * math.sin(angle),
            angle + math.pi, "predecessor")
        drive.add_road(road)
    for a in range(4):
        for b in range(a + 1, 4):
            creator.add_connection(first_id + a, first_id + b)
    drive.add_junction_creator(creator)
    target = Path(path)
    drive.adjust_roads_and_lanes()
    drive.write_xml(str(target))
    _add_furniture(target, str(first_id))
    return target


def _add_furniture(path: Path, road_id: str) -> None:
    """A traffic light and a zebra crossing on the east arm of Main Street, near the junction."""
    tree = etree.parse(str(path))
    road = next(r for r in tree.getroot().findall("road") if r.get("id") == road_id)
    signals = road.find("signals")
    if signals is None:
        signals = etree.SubElement(road, "signals")
    etree.SubElement(signals, "signal", id="1", s="2.0", t="-5.0", zOffset="0", orientation="+", dynamic="yes",
                     country="OpenDRIVE", type="1000001", subtype="-1", value="-1", height="0.8", width="0.3")
    objects = road.find("objects")
    if objects is None:
        objects = etree.SubElement(road, "objects")
    crosswalk = etree.SubElement(objects, "object", id="2", type="crosswalk", s="5.0", t="0.0", zOffset="0",
                                 hdg="0", orientation="none", length="3.0", width="7.0")
    outline = etree.SubElement(crosswalk, "outline", id="0", closed="true")
    for k, (u, v) in enumerate(((-1.5, -3.5), (1.5, -3.5), (1.5, 3.5), (-1.5, 3.5))):
        etree.SubElement(outline, "cornerLocal", id=str(k), u=str(u), v=str(v), z="0", height="0")
    tree.write(str(path), xml_declaration=True, encoding="UTF-8")


def grid_town(path: str | Path, size: int) -> Path:
    """`size` x `size` separate crossroads 200 m apart (a few km² at size 10), in one file."""
    target = Path(path)
    pitch = 2 * (ARM_LENGTH_M + 20.0)
    merged: etree._ElementTree | None = None
    for i in range(size):
        for j in range(size):
            k = i * size + j
            part = target.with_name(f".{target.stem}_{k}.xodr")
            crossroads(part, first_id=1 + 1000 * k, junction_id=100000 + k)
            tree = etree.parse(str(part))
            part.unlink()
            for geometry in tree.getroot().iter("geometry"):  # the junction creator ignores the origin
                geometry.set("x", repr(float(geometry.get("x", 0)) + i * pitch))
                geometry.set("y", repr(float(geometry.get("y", 0)) + j * pitch))
            if merged is None:
                merged = tree
            else:
                root = merged.getroot()
                for element in tree.getroot().findall("road") + tree.getroot().findall("junction"):
                    root.append(element)
    assert merged is not None
    merged.write(str(target), xml_declaration=True, encoding="UTF-8")
    return target
