"""Write any world's road network as OpenDRIVE with scenariogeneration.

Each lane becomes one road with one right-hand lane whose centre is the road's reference line
(a lane offset of half its width): the plan view is the lane's centreline as line segments,
the elevation profile its heights as linear pieces, so reading the file back gives the same
lanes. Sidewalks are roads with one sidewalk lane. The road's name is the lane's road name.

`validate_opendrive` checks a file against the ASAM OpenDRIVE 1.7 schema that the
scenariogeneration package ships (opendrive_17_core.xsd and the parts it includes); the
files written here declare 1.5, whose elements they use are unchanged in 1.7.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from importlib.metadata import files
from pathlib import Path

from drivetwin.worlds.scene import Scene

__all__ = ["OpenDriveError", "export_opendrive", "opendrive_xsd", "validate_opendrive"]

OPENDRIVE_XSD = "opendrive_17_core.xsd"


class OpenDriveError(ValueError):
    """An OpenDRIVE file that does not validate against the schema, or no schema to check it with."""


def _road(road_id: int, name: str, polyline: Sequence[tuple[float, float]], width: float, lane_type: str,
          elevation: Sequence[float] | None) -> object:
    from scenariogeneration import xodr

    planview = xodr.PlanView()
    travelled, stations = 0.0, [0.0]
    for (x1, y1), (x2, y2) in itertools.pairwise(polyline):
        length = math.hypot(x2 - x1, y2 - y1)
        if length <= 0.0:
            continue
        planview.add_fixed_geometry(xodr.Line(length), x1, y1, math.atan2(y2 - y1, x2 - x1), s=travelled)
        travelled += length
        stations.append(travelled)
    centre = xodr.Lane()
    section = xodr.LaneSection(0.0, centre)
    section.add_right_lane(xodr.Lane(lane_type=getattr(xodr.LaneType, lane_type), a=width))
    lanes = xodr.Lanes()
    lanes.add_lanesection(section)
    # The centre lane sits half a lane to the left, so lane -1's centre is the reference line.
    lanes.add_laneoffset(xodr.LaneOffset(0.0, width / 2, 0.0, 0.0, 0.0))
    road = xodr.Road(road_id, planview, lanes, name=name)
    if elevation is not None:
        kept = [z for (a, b), z in zip(itertools.pairwise(polyline), elevation, strict=False)
                if math.hypot(b[0] - a[0], b[1] - a[1]) > 0.0]
        heights = [*kept, elevation[-1]]
        for k in range(len(stations) - 1):
            slope = (heights[k + 1] - heights[k]) / max(stations[k + 1] - stations[k], 1e-9)
            road.add_elevation(stations[k], heights[k], slope, 0.0, 0.0)
    return road


def export_opendrive(scene: Scene, path: str | Path) -> Path:
    """Write `scene`'s lanes and sidewalks to the OpenDRIVE file `path` and return it."""
    from scenariogeneration import xodr

    odr = xodr.OpenDrive(scene.name)
    road_id = 1
    for lane in scene.roads.lanes:
        lane_type = "driving" if lane.kind == "driving" else lane.kind
        odr.add_road(_road(road_id, lane.road, lane.centreline, lane.width, lane_type, lane.elevation))
        road_id += 1
    for walk in scene.roads.sidewalks:
        odr.add_road(_road(road_id, walk.id, walk.polyline, walk.width, "sidewalk", None))
        road_id += 1
    target = Path(path)
    odr.write_xml(str(target))
    return target


def opendrive_xsd() -> Path:
    """The ASAM OpenDRIVE 1.7 schema (its core file) that the scenariogeneration package ships."""
    for file in files("scenariogeneration") or []:
        if file.name == OPENDRIVE_XSD:
            return Path(str(file.locate()))
    raise OpenDriveError(f"scenariogeneration ships no {OPENDRIVE_XSD}; reinstall it (pip install scenariogeneration)")


def validate_opendrive(path: str | Path) -> None:
    """Raise OpenDriveError with the first problem if `path` does not validate against the XSD."""
    import xmlschema

    schema = xmlschema.XMLSchema(str(opendrive_xsd()))
    try:
        errors = list(schema.iter_errors(str(path)))
    except (OSError, SyntaxError) as exc:  # ElementTree's ParseError is a SyntaxError
        raise OpenDriveError(f"{path} cannot be read as XML: {exc}") from exc
    if errors:
        first = errors[0]
        reason = " ".join(str(first.reason).split())
        raise OpenDriveError(f"{path} is not valid OpenDRIVE 1.7: {len(errors)} error(s), first at {first.path}: {reason}")
