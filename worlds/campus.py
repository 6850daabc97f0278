"""The default world: a university campus with a crossroads, four buildings and two car parks.

The layout is authored here in code, which keeps its numbers readable and reviewable; the
shipped `data/campus.json` is generated from it (`python -m drivetwin.worlds.campus`), and a
test keeps the two identical.
"""

from __future__ import annotations

import math
from pathlib import Path

from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import (
    EGO_ID,
    AssetInstance,
    Bounds,
    Building,
    Crossing,
    DriveLane,
    Environment,
    Landmark,
    Lane,
    PavedArea,
    PhysicsProps,
    Pose,
    RoadNetwork,
    Scene,
    Sidewalk,
)

HALF_X = 110.0  # the campus spans 220 m east-west
HALF_Y = 90.0  # and 180 m north-south
LANE_WIDTH = 3.5  # metres, a standard lane
SIDEWALK_OFFSET = 5.5  # sidewalk centreline from the road centreline: lane + 2 m verge
SIDEWALK_WIDTH = 2.0
JUNCTION = 9.0  # half-size of the paved crossroads box, with generous corner radii
CROSSING_AT = 11.5  # crossings sit just outside the crossroads box
ROAD_EDGE = LANE_WIDTH  # Main Street's kerbs, either side of its centreline
DRIVEWAY_HALF_WIDTH = 3.0  # a two-way car-park driveway, 6 m wide
LOT_A_DRIVEWAY_X = -85.0  # clear of the street lights at x = -80
LOT_B_DRIVEWAY_X = 47.0  # clear of the street lights at x = 37 and 62


def _rect(x0: float, y0: float, x1: float, y1: float) -> list[tuple[float, float]]:
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def _lanes() -> list[Lane]:
    h = LANE_WIDTH / 2
    return [
        Lane(id="main_eastbound", road="Main Street", centreline=[(-HALF_X, -h), (HALF_X, -h)]),
        Lane(id="main_westbound", road="Main Street", centreline=[(HALF_X, h), (-HALF_X, h)]),
        Lane(id="campus_northbound", road="Campus Drive", centreline=[(h, -HALF_Y), (h, HALF_Y)]),
        Lane(id="campus_southbound", road="Campus Drive", centreline=[(-h, HALF_Y), (-h, -HALF_Y)]),
    ]


def _sidewalks() -> list[Sidewalk]:
    walks = []
    o, j = SIDEWALK_OFFSET, JUNCTION
    for side, y in (("south", -o), ("north", o)):
        walks.append(Sidewalk(id=f"main_{side}_west", polyline=[(-HALF_X, y), (-j, y)]))
        walks.append(Sidewalk(id=f"main_{side}_east", polyline=[(j, y), (HALF_X, y)]))
    for side, x in (("west", -o), ("east", o)):
        walks.append(Sidewalk(id=f"campus_{side}_south", polyline=[(x, -HALF_Y), (x, -j)]))
        walks.append(Sidewalk(id=f"campus_{side}_north", polyline=[(x, j), (x, HALF_Y)]))
    return walks


def _crossings() -> list[Crossing]:
    c, o = CROSSING_AT, SIDEWALK_OFFSET
    return [
        Crossing(id="crossing_west", start=(-c, -o), end=(-c, o)),
        Crossing(id="crossing_east", start=(c, -o), end=(c, o)),
        Crossing(id="crossing_south", start=(-o, -c), end=(o, -c)),
        Crossing(id="crossing_north", start=(-o, c), end=(o, c)),
    ]


def _buildings() -> list[Building]:
    return [
        Building(id="jtekt", name="JTEKT Building", footprint=_rect(20, 16, 55, 42), height=14.0),
        Building(
            id="engineering", name="Engineering Hall", footprint=_rect(-60, 16, -20, 40), height=18.0
        ),
        Building(id="library", name="Library", footprint=_rect(-60, -44, -22, -16), height=12.0),
        Building(
            id="student_union", name="Student Union", footprint=_rect(25, -75, 60, -52), height=9.0
        ),
    ]


def _paved() -> list[PavedArea]:
    j = JUNCTION
    return [
        PavedArea(id="crossroads", kind="intersection", polygon=_rect(-j, -j, j, j)),
        PavedArea(id="parking_lot_a", kind="parking", polygon=_rect(-100, 14, -70, 44)),
        PavedArea(id="parking_lot_b", kind="parking", polygon=_rect(15, -46, 62, -12)),
        PavedArea(id="jtekt_dropoff", kind="driveway", polygon=_rect(28, 7.5, 46, 15)),
        PavedArea(id="library_dropoff", kind="driveway", polygon=_rect(-50, -15, -32, -7.5)),
        # The car parks' driveways join them to Main Street across the verge and sidewalk.
        PavedArea(id="parking_lot_a_driveway", kind="driveway", polygon=_rect(
            LOT_A_DRIVEWAY_X - DRIVEWAY_HALF_WIDTH, ROAD_EDGE, LOT_A_DRIVEWAY_X + DRIVEWAY_HALF_WIDTH, 14)),
        PavedArea(id="parking_lot_b_driveway", kind="driveway", polygon=_rect(
            LOT_B_DRIVEWAY_X - DRIVEWAY_HALF_WIDTH, -12, LOT_B_DRIVEWAY_X + DRIVEWAY_HALF_WIDTH, -ROAD_EDGE)),
    ]


def _landmarks() -> list[Landmark]:
    north, south, east, west = math.pi / 2, -math.pi / 2, 0.0, math.pi
    return [
        Landmark(
            name="JTEKT building entrance",
            aliases=["JTEKT entrance", "JTEKT building", "JTEKT", "JTEKT center entrance"],
            position=(37.5, 15.0), heading=south,
            description="main doors of the JTEKT Building, facing Main Street",
        ),
        Landmark(
            name="Engineering Hall entrance",
            aliases=["engineering entrance", "Engineering Hall", "engineering building"],
            position=(-40.0, 15.0), heading=south,
        ),
        Landmark(
            name="Library entrance", aliases=["library", "the library"],
            position=(-41.0, -15.0), heading=north,
        ),
        Landmark(
            name="Student Union entrance", aliases=["student union", "union building", "cafeteria"],
            position=(42.5, -51.0), heading=north,
        ),
        Landmark(
            name="main gate", aliases=["campus gate", "front gate", "entrance gate", "west gate"],
            position=(-100.0, 0.0), heading=east,
            description="where Main Street enters the campus from the west",
        ),
        Landmark(
            name="east gate", aliases=["back gate"], position=(100.0, 0.0), heading=west,
        ),
        Landmark(
            name="main intersection",
            aliases=["intersection", "crossroads", "junction", "centre of the scene",
                     "center of the scene", "scene centre", "scene center"],
            kind="area", position=(0.0, 0.0), polygon=_rect(-JUNCTION, -JUNCTION, JUNCTION, JUNCTION),
        ),
        Landmark(
            name="parking lot A", aliases=["lot A", "west parking lot", "parking A"],
            kind="area", position=(-85.0, 29.0), polygon=_rect(-100, 14, -70, 44), heading=south,
        ),
        Landmark(
            name="parking lot B", aliases=["lot B", "student parking", "parking B", "car park"],
            kind="area", position=(38.5, -29.0), polygon=_rect(15, -46, 62, -12), heading=north,
        ),
        Landmark(
            name="parking lot A entrance",
            aliases=["lot A entrance", "entrance of lot A", "entrance of parking lot A",
                     "parking lot A driveway", "lot A driveway"],
            position=(LOT_A_DRIVEWAY_X, ROAD_EDGE), heading=south,
            description="where parking lot A's driveway meets Main Street",
        ),
        Landmark(
            name="parking lot B entrance",
            aliases=["lot B entrance", "entrance of lot B", "entrance of parking lot B",
                     "parking lot B driveway", "lot B driveway"],
            position=(LOT_B_DRIVEWAY_X, -ROAD_EDGE), heading=north,
            description="where parking lot B's driveway meets Main Street",
        ),
        Landmark(
            name="bus stop", aliases=["shuttle stop", "bus station"],
            position=(-30.0, -SIDEWALK_OFFSET), heading=north,
        ),
        Landmark(
            name="fountain", aliases=["quad fountain", "the quad", "campus quad"],
            position=(75.0, 40.0), heading=south,
        ),
        Landmark(
            name="west crosswalk", aliases=["crosswalk", "zebra crossing", "pedestrian crossing"],
            position=(-CROSSING_AT, 0.0), heading=north,
        ),
        Landmark(
            name="north crosswalk", aliases=["north crossing"],
            position=(0.0, CROSSING_AT), heading=east,
        ),
    ]


def _ego() -> AssetInstance:
    ego = category("ego_vehicle")
    return AssetInstance(
        id=EGO_ID,
        category=ego.name,
        pose=Pose(x=-60.0, y=-LANE_WIDTH / 2, yaw=0.0),
        physics=PhysicsProps(mass=ego.mass),
        behaviour=DriveLane(lane="main_eastbound", speed=5.0),
        label="ego vehicle",
    )


def _furniture() -> list[AssetInstance]:
    placed: list[AssetInstance] = []

    def put(cat: str, x: float, y: float, yaw: float = 0.0, dynamic: bool = False) -> None:
        spec = category(cat)
        n = sum(1 for a in placed if a.category == cat) + 1
        placed.append(
            AssetInstance(
                id=f"{cat}_{n}",
                category=cat,
                pose=Pose(x=x, y=y, yaw=yaw),
                physics=PhysicsProps(mass=spec.mass, dynamic=dynamic),
            )
        )

    o = SIDEWALK_OFFSET
    for x in (-80.0, -50.0, -25.0, 25.0, 50.0, 80.0):
        put("street_light", x, o + 0.3, yaw=-math.pi / 2)
        put("street_light", x + 12.0, -o - 0.3, yaw=math.pi / 2)
    put("traffic_light", -JUNCTION - 0.5, -o - 0.7)
    put("traffic_light", JUNCTION + 0.5, o + 0.7)
    for x, y in ((-26.0, -12.0), (70.0, 45.0), (85.0, 25.0), (-85.0, 50.0)):
        put("tree", x, y)
    put("bench", -26.0, -o - 1.4, yaw=math.pi)
    put("trash_bin", -33.5, -o)
    put("fire_hydrant", 16.0, o)
    put("stop_sign", -CROSSING_AT - 2.0, -o, yaw=0.0)
    for i, x in enumerate((19.0, 23.0, 27.0)):
        put("passenger_car" if i != 1 else "suv", x, -42.0, yaw=math.pi / 2, dynamic=True)
    return placed


def build_campus() -> Scene:
    """The default campus world, built from its authored layout."""
    return Scene(
        name="campus",
        description=(
            "A university campus with a crossroads, four buildings and two parking lots. "
            "Main Street (east-west) crosses Campus Drive at a signalled crossroads in the "
            "centre; JTEKT Building and Engineering Hall to the north, the "
            "Library and Student Union to the south, parking lots A (west) and B (south-east)."
        ),
        bounds=Bounds(xmin=-HALF_X, xmax=HALF_X, ymin=-HALF_Y, ymax=HALF_Y),
        roads=RoadNetwork(
            lanes=_lanes(), sidewalks=_sidewalks(), crossings=_crossings(), paved=_paved()
        ),
        buildings=_buildings(),
        landmarks=_landmarks(),
        ego=_ego(),
        assets=_furniture(),
        environment=Environment(time_of_day="12:00"),
    )


if __name__ == "__main__":
    target = Path(__file__).with_name("data") / "campus.json"
    build_campus().save(target)
    print(f"wrote {target}")
