"""The fourth practice suite (practice4): its cases as a plain list, and the writer of its JSONL.

A development suite, written from the campus world, the asset catalog, the Worker tools and the
eval checks only, by someone who had read neither the planners (their lexicons, prompt examples
or example bank) nor any other suite. Its prompts come in voices invented for it: a QA tester
filing a scenario, a teacher preparing a lesson, someone typing fast on a phone, a non-native
speaker, someone describing things instead of naming them, someone stating a goal rather than
an edit, someone asking about the scene. It uses numbers in words and digits, metres and feet,
clock times, weather, negation, questions that must change nothing, compound requests, earlier
turns (some planned by the planner under test) and places and scopes (lanes, lots, sidewalks,
crossings, named landmarks, "the parked ones"). About 8 % of the cases ask for what the world
cannot do; the right outcome there is a refusal that changes nothing.

`python -m drivetwin.evals.practice4_source` rewrites `suites/practice4.jsonl` from `ALL_CASES`.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from drivetwin.evals.suite_source import dsl
from drivetwin.evals.suite_source.dsl import (
    add,
    arrange,
    behaviour,
    call,
    delta,
    does,
    env,
    exactly,
    gone,
    in_lane,
    loc,
    looks,
    moved,
    near,
    only,
    present,
    relative,
    says,
    shape,
    step,
    surface,
)

Json = dict[str, Any]
SUITE_PATH = Path(__file__).resolve().parent / "suites" / "practice4.jsonl"
TAG = "practice4"
VEHICLES = ["passenger_car", "suv"]
ROAD_VEHICLES = [*VEHICLES, "bus", "truck", "motorcycle"]
LOT_B_CARS = ("passenger_car_1", "suv_1", "passenger_car_2")
NORTH_LIGHTS = tuple(f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11))
SOUTH_LIGHTS = tuple(f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12))
TREES = ("tree_1", "tree_2", "tree_3", "tree_4")


# Small builders of our own ----------------------------------------------------------------
def refused() -> Json:
    return {"kind": "status", "accepted": False}


def nothing_changed() -> Json:
    return only()


def every(check: Json, n: int | None = None) -> Json:
    """The same selecting check, passed by every selected asset (and at least n of them)."""
    out = {**check, "require_all": True}
    if n is not None:
        out["min_count"] = n
    return out


def added(check: Json) -> Json:
    return {**check, "scope": "added"}


def ring(category: Any, around: str | None = None, n: int = 3) -> Json:
    return shape("ring", category, around=around, n=n, tolerance=1.5)


def line(category: Any, n: int = 3, spacing: tuple[float, float] | None = None) -> Json:
    return shape("line", category, n=n, tolerance=1.0, spacing=spacing)


def drives(category: Any = None, *, asset: str | None = None, lane: str | None = None,
           speed: tuple[float | None, float | None] = (None, None), every_one: bool = False) -> Json:
    out = does("drive_lane", category, asset=asset, lane=lane, speed_min=speed[0], speed_max=speed[1])
    return {**out, "require_all": True} if every_one else out


def place(asset: str, where: Json, yaw: float | None = None) -> Json:
    return call("place_asset", asset=asset, location=where, yaw_deg=yaw)


def shift(asset: str, **kw: Any) -> Json:
    return call("move_asset", asset=asset, **kw)


def act(asset: str, kind: str, **kw: Any) -> Json:
    return call("set_behaviour", asset=asset, behaviour=behaviour(kind, **kw))


def remove(*ids: str, **kw: Any) -> Json:
    return call("remove_assets", assets=list(ids) if ids else None, **kw)


def find(**kw: Any) -> Json:
    return call("find_assets", **kw)


def marks(**kw: Any) -> Json:
    return call("find_landmarks", **kw)


def weather(kind: str, intensity: float | None = None) -> Json:
    return call("set_weather", kind=kind, intensity=intensity)


def clock(time: str) -> Json:
    return call("set_time_of_day", time=time)


def lights(**kw: Any) -> Json:
    return call("set_lighting", **kw)


def paint(*ids: str, category: str | None = None, colour: str | None = None, material: str | None = None) -> Json:
    return call("set_asset_appearance", assets=list(ids) if ids else None, category=category,
                colour=colour, material=material)


def case(
    task: str,
    grade: str,
    slug: str,
    prompt: str,
    checks: list[Json],
    reference: list[Json],
    *,
    setup: list[Json] | None = None,
    tags: tuple[str, ...] = (),
    alternatives: list[list[Json]] | None = None,
    notes: str = "",
) -> Json:
    all_tags = [TAG, *tags]
    if setup and "multi_turn" not in all_tags:
        all_tags.append("multi_turn")
    return dsl.case(f"{TAG}.{task}.{grade}.{slug}", task, grade, prompt, checks, reference, setup=setup,
                    tags=all_tags, alternatives=alternatives, notes=notes)


def impossible(task: str, grade: str, slug: str, prompt: str, reference: list[Json], *,
               setup: list[Json] | None = None, notes: str = "") -> Json:
    """A request the world cannot do: the right outcome is a refusal that changes nothing."""
    return case(task, grade, slug, prompt, [refused(), nothing_changed()], reference, setup=setup,
                tags=("impossible",), notes=notes)


def planned(earlier: Json) -> Json:
    """The same earlier turn, planned by the planner under test (its calls only a reference)."""
    return {**earlier, "planned": True}


# Earlier turns, replayed as given ------------------------------------------------------------
TWO_PEDS_LIBRARY = step("put two pedestrians by the Library entrance",
                        add("pedestrian", loc("at", "Library entrance"), count=2))
PED_AT_BUS_STOP = step("someone waiting at the bus stop", add("pedestrian", loc("at", "bus stop")))
RUBBLE_CENTRE = step("drop a pile of rubble in the middle of the crossroads",
                     add("cement_rubble", loc("at", "main intersection")))
RUBBLE_WEST = step("rubble on the west crosswalk", add("cement_rubble", loc("at", "west crosswalk")))
CONES_JTEKT = step("five cones in front of the JTEKT entrance",
                   arrange(["traffic_cone"], "line", loc("in_front_of", "JTEKT building entrance"), count=5))
CAR_JTEKT = step("a parked car at the JTEKT entrance",
                 add("passenger_car", loc("at", "JTEKT building entrance"), behaviour=behaviour("parked")))
TRUCK_UNION = step("a delivery truck at the Student Union", add("truck", loc("at", "Student Union entrance")))
ROBOT_LOT_B = step("add a robot in parking lot B", add("ackermann_robot", loc("at", "parking lot B")))
BIKE_LIBRARY = step("a bike by the library", add("bicycle", loc("at", "Library entrance")))
RAIN = step("make it rain", weather("rain"))
NIGHT = step("make it night", clock("night"))
CONES_EASTBOUND = step("cones along the eastbound lane ahead of the ego",
                       arrange(["traffic_cone"], "lane_edge", loc("at", "ego", along_m=25), count=6))


# Search: questions; nothing may change ------------------------------------------------------
SEARCH = [
    # direct
    case("search", "direct", "count-street-lights", "How many street lights are there in the scene?",
         [says(all_of=["12"]), nothing_changed()], [find(category="street_light")]),
    case("search", "direct", "list-trees", "List every tree on the campus.",
         [says(all_of=list(TREES)), nothing_changed()], [find(category="tree")]),
    case("search", "direct", "car-nearest-union", "Which car is nearest to the Student Union entrance?",
         [says(all_of=["passenger_car_2"]), nothing_changed()],
         [find(category="car", nearest_to="Student Union entrance")]),
    case("search", "direct", "main-street-lanes", "Which lanes does Main Street have?",
         [says(all_of=["main_eastbound", "main_westbound"]), nothing_changed()], [call("find_lanes", road="Main Street")]),
    case("search", "direct", "assets-in-lanes", "Is anything standing in a lane right now?",
         [says(all_of=["ego"]), nothing_changed()], [find(on_lane=True)]),
    case("search", "direct", "nearest-light-distance",
         "How far is the nearest street light from the ego vehicle, in metres?",
         [says(all_of=["street_light_2"], any_of=["9", "9.0"]), nothing_changed()],
         [find(category="street_light", nearest_to="ego")]),
    case("search", "direct", "landmark-nearest-fountain", "Which named place is closest to the fountain?",
         [says(all_of=["JTEKT"]), nothing_changed()], [marks(nearest_to="fountain")]),
    case("search", "direct", "bus-mass", "How heavy is a bus in the catalog?",
         [says(any_of=["12000", "12,000", "12 000", "12 t", "12 tonnes"]), nothing_changed()],
         [call("asset_properties", category="bus")]),
    case("search", "direct", "count-peds-after-setup", "How many pedestrians are in the scene now?",
         [says(all_of=["2"]), nothing_changed()], [find(category="pedestrian")], setup=[planned(TWO_PEDS_LIBRARY)]),
    case("search", "direct", "trees-and-ego-lane",
         "How many trees are there, and which lane is the ego driving in?",
         [says(all_of=["4", "main_eastbound"]), nothing_changed()],
         [find(category="tree"), find(lane="main_eastbound", category="ego")], tags=("compound",)),
    # indirect
    case("search", "indirect", "somewhere-to-sit",
         "I'm wondering whether there's somewhere to sit near the bus stop, could you check?",
         [says(all_of=["bench"]), nothing_changed()], [find(category="bench", nearest_to="bus stop")]),
    case("search", "indirect", "north-south-lanes",
         "Could you tell me which lanes run north and south, so I can plan the test route?",
         [says(all_of=["campus_northbound", "campus_southbound"]), nothing_changed()],
         [call("find_lanes", road="Campus Drive")]),
    case("search", "indirect", "vehicles-in-lot-b",
         "Before I add anything, I'd like to know how many vehicles are already parked in lot B.",
         [says(all_of=["3"]), nothing_changed()], [find(category="vehicles", near="parking lot B", within=25)]),
    case("search", "indirect", "light-nearer-library",
         "My student asked which of the two traffic lights is closer to the Library entrance. Do you know?",
         [says(all_of=["traffic_light_1"]), nothing_changed()],
         [find(category="traffic_light", nearest_to="Library entrance")]),
    case("search", "indirect", "lane-width", "For the lesson plan I need to know how wide one lane is.",
         [says(all_of=["3.5"]), nothing_changed()], [call("find_lanes")]),
    case("search", "indirect", "where-is-ego",
         "It would help me to know where our test car is at the moment, and on which lane.",
         [says(all_of=["main_eastbound"]), nothing_changed()], [find(category="ego", lane="main_eastbound")]),
    case("search", "indirect", "leftover-cones",
         "I'd like to find out whether any traffic cones were left over from the last setup.",
         [says(any_of=["0", "no", "none", "zero"]), says(none_of=["traffic_cone_1"]), nothing_changed()],
         [find(category="traffic_cone")]),
    case("search", "indirect", "place-nearest-hydrant",
         "Please let me know which named place is nearest to the fire hydrant.",
         [says(all_of=["intersection"]), nothing_changed()], [marks(nearest_to="fire_hydrant_1")]),
    case("search", "indirect", "bin-nearest-library",
         "Would you mind telling me which bin is nearest to the Library entrance, and how far away it is?",
         [says(all_of=["trash_bin_1"], any_of=["12.1", "12"]), nothing_changed()],
         [find(category="trash_bin", nearest_to="Library entrance")]),
    case("search", "indirect", "cones-after-planned-turn",
         "Now could you check how many cones ended up in front of the Library?",
         [says(all_of=["3"]), nothing_changed()], [find(category="traffic_cone", near="Library entrance", within=15)],
         setup=[step("put three traffic cones in front of the Library entrance",
                     add("traffic_cone", loc("in_front_of", "Library entrance"), count=3), planned=True)]),
    # vague
    case("search", "vague", "around-bus-stop", "what's around the bus stop",
         [says(all_of=["bench", "trash bin"]), nothing_changed()], [find(nearest_to="bus stop", within=6)]),
    case("search", "vague", "anything-on-road", "anything on the road?",
         [says(all_of=["ego"]), nothing_changed()], [find(on_lane=True)]),
    case("search", "vague", "where-to-park", "where could a car park around here",
         [says(any_of=["parking lot A", "parking lot B", "lot A", "lot B"]), nothing_changed()],
         [marks(query="parking lot")]),
    case("search", "vague", "lamps-count", "how many lamps we got",
         [says(all_of=["12"]), nothing_changed()], [find(category="lamp post")]),
    case("search", "vague", "whats-in-south-east-lot", "what's parked over in the south-east lot?",
         [says(all_of=list(LOT_B_CARS)), nothing_changed()], [find(category="vehicles", near="parking lot B", within=25)]),
    case("search", "vague", "road-names", "the roads here, what are they called",
         [says(all_of=["Main Street", "Campus Drive"]), nothing_changed()], [call("find_lanes")]),
    case("search", "vague", "any-people", "any people around?",
         [says(any_of=["0", "no", "none", "nobody", "zero"]), says(none_of=["pedestrian_1"]), nothing_changed()],
         [find(category="pedestrian")]),
    case("search", "vague", "tree-by-library", "closest tree to the library?",
         [says(all_of=["tree_1"]), nothing_changed()], [find(category="tree", nearest_to="Library entrance")]),
    case("search", "vague", "fountain-to-east-gate", "fountain to east gate, how far",
         [says(any_of=["47.2", "47"]), nothing_changed()], [marks(query="fountain", nearest_to="east gate")]),
    case("search", "vague", "robot-still-there", "that robot, still in the lot?",
         [says(any_of=["ackermann_robot_1", "yes"]), nothing_changed()],
         [find(category="robot", near="parking lot B", within=30)], setup=[ROBOT_LOT_B]),
    # erroneous
    case("search", "erroneous", "streetlihgts", "how many streetlihgts r there",
         [says(all_of=["12"]), nothing_changed()], [find(category="street_light")]),
    case("search", "erroneous", "wich-car-union", "wich car is closest too the student union",
         [says(all_of=["passenger_car_2"]), nothing_changed()],
         [find(category="car", nearest_to="Student Union entrance")]),
    case("search", "erroneous", "how-much-tree", "how much tree are there in the campus?",
         [says(all_of=["4"]), nothing_changed()], [find(category="tree")]),
    case("search", "erroneous", "pls-list-lanes", "pls list teh lanes",
         [says(all_of=["main_eastbound", "main_westbound", "campus_northbound", "campus_southbound"]),
          nothing_changed()], [call("find_lanes")]),
    case("search", "erroneous", "nearst-landmark-ego", "what is nearst landmark of the ego?",
         [says(all_of=["parking lot A"]), nothing_changed()], [marks(nearest_to="ego")]),
    case("search", "erroneous", "cone-on-road", "there is some cone on road or not?",
         [says(any_of=["0", "no", "none", "zero"]), says(none_of=["traffic_cone_1"]), nothing_changed()],
         [find(category="traffic_cone", on_lane=True)]),
    case("search", "erroneous", "light-near-jtekt", "which trafic light is more near to the JTEKT buliding?",
         [says(all_of=["traffic_light_2"]), nothing_changed()],
         [find(category="traffic_light", nearest_to="JTEKT building entrance")]),
    case("search", "erroneous", "vehicle-parking-lot-b", "how many vehicle are parking in the lot B now",
         [says(all_of=["3"]), nothing_changed()], [find(category="vehicles", near="parking lot B", within=25)]),
    case("search", "erroneous", "ego-wich-lane", "ego is in wich lane??",
         [says(all_of=["main_eastbound"]), nothing_changed()], [find(category="ego", on_lane=True)]),
    case("search", "erroneous", "cones-count-after-setup", "how many cone is infront JTEKT now",
         [says(all_of=["5"]), nothing_changed()],
         [find(category="traffic_cone", near="JTEKT building entrance", within=15)], setup=[CONES_JTEKT]),
]


# Addition -----------------------------------------------------------------------------------
ADDITION = [
    # direct
    case("addition", "direct", "bus-and-rider-at-stop", "Add a bus at the bus stop and a pedestrian waiting next to it.",
         [exactly("bus", 1), near("bus", "bus stop", 8), exactly("pedestrian", 1), near("pedestrian", "bus stop", 8),
          only("bus", "pedestrian")],
         [add("bus", loc("at", "bus stop")), add("pedestrian", loc("at", "bus stop"))], tags=("compound",)),
    case("addition", "direct", "two-peds-library", "Add two pedestrians near the Library entrance.",
         [exactly("pedestrian", 2), every(near("pedestrian", "Library entrance", 10)), only("pedestrian")],
         [add("pedestrian", loc("at", "Library entrance"), count=2)]),
    case("addition", "direct", "truck-lot-a", "Add a truck in parking lot A.",
         [exactly("truck", 1), near("truck", "parking lot A", 1), only("truck")], [add("truck", loc("at", "parking lot A"))]),
    case("addition", "direct", "car-westbound", "Add a car driving in the westbound lane of Main Street.",
         [exactly(VEHICLES, 1), drives(VEHICLES, lane="main_westbound"), in_lane("main_westbound", VEHICLES),
          only(*VEHICLES)],
         [add("passenger_car", loc("in_lane", "main_westbound"), behaviour=behaviour("drive_lane", lane="main_westbound"))]),
    case("addition", "direct", "bike-next-to-bench", "Put a bicycle next to the bench.",
         [exactly("bicycle", 1), near("bicycle", "bench_1", 4), only("bicycle")], [add("bicycle", loc("next_to", "bench_1"))]),
    case("addition", "direct", "ped-20m-ahead", "Add a pedestrian on the sidewalk 20 metres ahead of the ego vehicle, on its right.",
         [exactly("pedestrian", 1), relative("in_front_of", "ego", "pedestrian", max_distance=28, tolerance_deg=30),
          near("pedestrian", point=[-40.0, -5.5], within=3), surface(["sidewalk"], "pedestrian"), only("pedestrian")],
         [add("pedestrian", loc("at", "ego", along_m=20, side="right"))]),
    case("addition", "direct", "motorcycle-lot-b", "Add a motorcycle in parking lot B.",
         [exactly("motorcycle", 1), near("motorcycle", "parking lot B", 1), only("motorcycle")],
         [add("motorcycle", loc("at", "parking lot B"))]),
    case("addition", "direct", "sign-behind-rubble", "Add a construction sign next to the rubble.",
         [exactly("construction_sign", 1), near("construction_sign", "cement_rubble_1", 6), only("construction_sign")],
         [add("construction_sign", loc("next_to", "cement_rubble_1"))], setup=[RUBBLE_CENTRE]),
    case("addition", "direct", "four-bollards-gate", "Add four bollards at the main gate.",
         [exactly("bollard", 4), every(near("bollard", "main gate", 12)), only("bollard")],
         [add("bollard", loc("at", "main gate"), count=4)]),
    impossible("addition", "direct", "car-inside-library", "Add a parked car inside the Library building.",
               [add("passenger_car", loc("absolute", x=-40, y=-30))]),
    # indirect
    case("addition", "indirect", "truck-waiting-jtekt", "We need a delivery truck waiting at the JTEKT building entrance.",
         [exactly("truck", 1), near("truck", "JTEKT building entrance", 10), only("truck")],
         [add("truck", loc("at", "JTEKT building entrance"))]),
    case("addition", "indirect", "someone-waiting-shuttle", "I'd like someone standing at the bus stop, waiting for the shuttle.",
         [exactly("pedestrian", 1), near("pedestrian", "bus stop", 6), only("pedestrian")],
         [add("pedestrian", loc("at", "bus stop"))]),
    case("addition", "indirect", "traffic-north-campus",
         "The crossroads feels empty. Could we get two cars driving north on Campus Drive?",
         [exactly(VEHICLES, 2), every(drives(VEHICLES, lane="campus_northbound"), 2), only(*VEHICLES)],
         [add("passenger_car", loc("in_lane", "campus_northbound"), count=2,
              behaviour=behaviour("drive_lane", lane="campus_northbound"))]),
    case("addition", "indirect", "hydrant-union", "The safety officer wants a fire hydrant near the Student Union entrance.",
         [exactly("fire_hydrant", 1), added(near("fire_hydrant", "Student Union entrance", 8)), only("fire_hydrant")],
         [add("fire_hydrant", loc("at", "Student Union entrance"))]),
    case("addition", "indirect", "suv-library-dropoff",
         "For the pick-up scenario there should be an SUV parked in front of the Library entrance.",
         [exactly("suv", 1), added(relative("in_front_of", "Library entrance", "suv", max_distance=10)),
          added(does("parked", "suv")), only("suv")],
         [add("suv", loc("in_front_of", "Library entrance"), behaviour=behaviour("parked"))]),
    case("addition", "indirect", "bike-circling-lot-b", "Somebody should be riding a bike round and round in lot B.",
         [exactly("bicycle", 1), does("circle", "bicycle", centre_near="parking lot B", centre_within=25),
          only("bicycle")], [add("bicycle", loc("at", "parking lot B"), behaviour=behaviour("circle"))]),
    case("addition", "indirect", "crossing-ped-west", "Let's have a pedestrian walk across at the west crosswalk.",
         [exactly("pedestrian", 1), does("cross_road", "pedestrian", crosses_lane="main_eastbound"), only("pedestrian")],
         [add("pedestrian", loc("at", "west crosswalk"), behaviour=behaviour("cross_road"))]),
    case("addition", "indirect", "jaywalker-braking",
         "I want to test emergency braking, so I need a person who jaywalks in front of our car.",
         [exactly("pedestrian", 1), does("jaywalk", "pedestrian", crosses_lane="main_eastbound"), only("pedestrian")],
         [add("pedestrian", behaviour=behaviour("jaywalk"))]),
    case("addition", "indirect", "rover-jtekt-rain",
         "Our robotics lab would like its rover parked by the JTEKT entrance, and the test should run in the rain.",
         [exactly("ackermann_robot", 1), near("ackermann_robot", "JTEKT building entrance", 10),
          env(weather=["rain"]), only("ackermann_robot", environment=True)],
         [add("ackermann_robot", loc("at", "JTEKT building entrance")), weather("rain")], tags=("compound",)),
    impossible("addition", "indirect", "seventy-cars",
               "The open day needs a packed campus: please add seventy cars in one go.",
               [add("passenger_car", loc("at", "parking lot A"), count=70)],
               notes="one call adds at most 50, and a scene holds at most 60 passenger cars"),
    # vague
    case("addition", "vague", "some-cones-library", "some cones by the library",
         [delta("traffic_cone", 2, 10), every(near("traffic_cone", "Library entrance", 12)), only("traffic_cone")],
         [add("traffic_cone", loc("in_front_of", "Library entrance"), count=3)]),
    case("addition", "vague", "few-people-fountain", "a few people at the fountain",
         [delta("pedestrian", 2, 6), every(near("pedestrian", "fountain", 10)), only("pedestrian")],
         [add("pedestrian", loc("at", "fountain"), count=3)]),
    case("addition", "vague", "more-traffic-main", "more traffic on main street",
         [delta(ROAD_VEHICLES, 1, 10), only(*VEHICLES, "bus", "truck", "motorcycle")],
         [add("passenger_car", loc("in_lane", "main_westbound"), behaviour=behaviour("drive_lane", lane="main_westbound"))],
         alternatives=[[drives(ROAD_VEHICLES, lane="main_westbound")],
                       [drives(ROAD_VEHICLES, lane="main_eastbound")]]),
    case("addition", "vague", "bin-by-bench", "stick a bin near the bench",
         [exactly("trash_bin", 1), added(near("trash_bin", "bench_1", 5)), only("trash_bin")],
         [add("trash_bin", loc("next_to", "bench_1"))]),
    case("addition", "vague", "seat-east-gate", "somewhere to sit by the east gate",
         [exactly("bench", 1), added(near("bench", "east gate", 12)), only("bench")], [add("bench", loc("at", "east gate"))]),
    case("addition", "vague", "lorry-union", "need a lorry over at the student union",
         [exactly("truck", 1), near("truck", "Student Union entrance", 12), only("truck")],
         [add("truck", loc("at", "Student Union entrance"))]),
    case("addition", "vague", "tree-or-two-library", "a tree or two by the library",
         [delta("tree", 1, 2), every(added(near("tree", "Library entrance", 15))), only("tree")],
         [add("tree", loc("at", "Library entrance"))]),
    case("addition", "vague", "cyclist-lot-a", "a cyclist in lot A",
         [exactly("bicycle", 1), near("bicycle", "parking lot A", 1), only("bicycle")], [add("bicycle", loc("at", "parking lot A"))]),
    case("addition", "vague", "barrier-cone-back-gate", "barrier at the back gate, plus a cone next to it",
         [exactly("road_barrier", 1), near("road_barrier", "east gate", 10), exactly("traffic_cone", 1),
          near("traffic_cone", "road_barrier_1", 5), only("road_barrier", "traffic_cone")],
         [add("road_barrier", loc("at", "east gate")), add("traffic_cone", loc("next_to", "road_barrier_1"))],
         tags=("compound",)),
    impossible("addition", "vague", "car-train-station", "a car at the train station",
               [add("passenger_car", loc("at", "train station"))], notes="the campus has no train station"),
    # erroneous
    case("addition", "erroneous", "pedestrain-bus-stopp", "ad a pedestrain at the bus stopp",
         [exactly("pedestrian", 1), near("pedestrian", "bus stop", 6), only("pedestrian")], [add("pedestrian", loc("at", "bus stop"))]),
    case("addition", "erroneous", "two-car-lot-b", "pls add 2 car in the parking lot B",
         [exactly(VEHICLES, 2), every(added(near(VEHICLES, "parking lot B", 1)), 2), only(*VEHICLES)],
         [add("passenger_car", loc("at", "parking lot B"), count=2)]),
    case("addition", "erroneous", "cone-infront-egoo", "add one trafic cone infront of the egoo",
         [exactly("traffic_cone", 1), relative("in_front_of", "ego", "traffic_cone", max_distance=15, tolerance_deg=30),
          only("traffic_cone")], [add("traffic_cone", loc("in_front_of", "ego"))]),
    case("addition", "erroneous", "bus-going-east", "I want add a bus in the Main street going to east",
         [exactly("bus", 1), drives("bus", lane="main_eastbound"), only("bus")],
         [add("bus", loc("in_lane", "main_eastbound"), behaviour=behaviour("drive_lane", lane="main_eastbound"))]),
    case("addition", "erroneous", "tree-bench-near-of-fountain", "put a tree near of fountain please and also one bench there",
         [exactly("tree", 1), added(near("tree", "fountain", 8)), exactly("bench", 1), added(near("bench", "fountain", 8)),
          only("tree", "bench")], [add("tree", loc("at", "fountain")), add("bench", loc("at", "fountain"))],
         tags=("compound",)),
    case("addition", "erroneous", "moter-bike-lot-a", "add the moter bike at lot A",
         [exactly("motorcycle", 1), near("motorcycle", "parking lot A", 1), only("motorcycle")],
         [add("motorcycle", loc("at", "parking lot A"))]),
    case("addition", "erroneous", "hydrant-next-jtekt", "add a hidrant next the JTEKT entrence",
         [exactly("fire_hydrant", 1), added(near("fire_hydrant", "JTEKT building entrance", 10)), only("fire_hydrant")],
         [add("fire_hydrant", loc("at", "JTEKT building entrance"))]),
    case("addition", "erroneous", "three-bollard-lot-b", "adding three bollard at entrance of lot B",
         [exactly("bollard", 3), every(near("bollard", "parking lot B entrance", 12)), only("bollard")],
         [add("bollard", loc("at", "parking lot B entrance"), count=3)]),
    case("addition", "erroneous", "ped-50-feet", "add one person walking 50 feet ahead the ego on sidewalk right side",
         [exactly("pedestrian", 1), relative("in_front_of", "ego", "pedestrian", max_distance=22, tolerance_deg=35),
          near("pedestrian", point=[-44.8, -5.5], within=3), surface(["sidewalk"], "pedestrian"), only("pedestrian")],
         [add("pedestrian", loc("at", "ego", along_m=15.24, side="right"))]),
    impossible("addition", "erroneous", "sheep-quad", "add a sheep in the quad", [add("sheep", loc("at", "fountain"))],
               notes="the catalog has no animals"),
]


# Removal ------------------------------------------------------------------------------------
REMOVAL = [
    # direct
    case("removal", "direct", "bench", "Remove the bench.",
         [gone("bench_1"), only(assets=("bench_1",))], [remove("bench_1")]),
    case("removal", "direct", "north-street-lights", "Remove all the street lights on the north side of Main Street.",
         [gone(*NORTH_LIGHTS), present(*SOUTH_LIGHTS), only(assets=NORTH_LIGHTS)], [remove(*NORTH_LIGHTS)]),
    case("removal", "direct", "bin-at-bus-stop", "Delete the trash bin at the bus stop.",
         [gone("trash_bin_1"), only(assets=("trash_bin_1",))], [remove(category="trash_bin", near="bus stop", count=1)]),
    case("removal", "direct", "suv-lot-b", "Remove the SUV from parking lot B.",
         [gone("suv_1"), present("passenger_car_1", "passenger_car_2"), only(assets=("suv_1",))], [remove("suv_1")]),
    case("removal", "direct", "two-trees-fountain", "Remove the two trees nearest the fountain.",
         [gone("tree_2", "tree_3"), present("tree_1", "tree_4"), only(assets=("tree_2", "tree_3"))],
         [remove(category="tree", near="fountain", count=2)]),
    case("removal", "direct", "stop-sign-and-hydrant", "Remove the stop sign and the fire hydrant.",
         [gone("stop_sign_1", "fire_hydrant_1"), only(assets=("stop_sign_1", "fire_hydrant_1"))],
         [remove("stop_sign_1"), remove("fire_hydrant_1")], tags=("compound",)),
    case("removal", "direct", "parked-vehicles-lot-b", "Take away every parked vehicle in lot B.",
         [gone(*LOT_B_CARS), present("ego"), only(assets=LOT_B_CARS)], [remove(*LOT_B_CARS)]),
    case("removal", "direct", "the-cones", "Remove the cones.",
         [{"kind": "count", "category": "traffic_cone", "max": 0}, only("traffic_cone")],
         [remove(category="traffic_cone")], setup=[CONES_JTEKT]),
    case("removal", "direct", "sw-traffic-light", "Remove the traffic light on the south-west corner of the intersection.",
         [gone("traffic_light_1"), present("traffic_light_2"), only(assets=("traffic_light_1",))], [remove("traffic_light_1")]),
    impossible("removal", "direct", "ego", "Remove the ego vehicle from the scene.", [remove("ego")]),
    # indirect
    case("removal", "indirect", "bin-cluttered", "The bus stop looks cluttered; could you get rid of the bin there?",
         [gone("trash_bin_1"), only(assets=("trash_bin_1",))], [remove("trash_bin_1")]),
    case("removal", "indirect", "hydrant-and-bench-not-needed", "We don't need the fire hydrant any more, and the bench can go too.",
         [gone("fire_hydrant_1", "bench_1"), only(assets=("fire_hydrant_1", "bench_1"))],
         [remove("fire_hydrant_1"), remove("bench_1")], tags=("compound",)),
    case("removal", "indirect", "lot-b-empty", "I'd rather the cars in lot B weren't there for this test.",
         [gone(*LOT_B_CARS), only(assets=LOT_B_CARS)], [remove(*LOT_B_CARS)]),
    case("removal", "indirect", "keep-one-ped", "Actually, I only want one of them to stay.",
         [{"kind": "count", "category": "pedestrian", "min": 1, "max": 1}, delta("pedestrian", -2, -2), only("pedestrian")],
         [remove(category="pedestrian", count=2)],
         setup=[step("add three pedestrians at the fountain", add("pedestrian", loc("at", "fountain"), count=3),
                     planned=True)]),
    case("removal", "indirect", "light-by-bus-stop",
         "Passengers can't see the timetable; please take away the street light right next to the bus stop.",
         [gone("street_light_4"), only(assets=("street_light_4",))], [remove(category="street_light", near="bus stop", count=1)]),
    case("removal", "indirect", "uncontrolled-junction",
         "No more traffic lights please, the junction should be uncontrolled for this run.",
         [gone("traffic_light_1", "traffic_light_2"), only(assets=("traffic_light_1", "traffic_light_2"))],
         [remove(category="traffic_light")]),
    case("removal", "indirect", "changed-mind-car", "I changed my mind about that car, it can go.",
         [{"kind": "count", "category": "passenger_car", "max": 2}, present("passenger_car_1", "passenger_car_2"),
          only("passenger_car")], [remove("passenger_car_3")], setup=[CAR_JTEKT]),
    case("removal", "indirect", "open-sightlines", "The sensor team wants open sightlines, so every tree has to go.",
         [gone(*TREES), only(assets=TREES)], [remove(category="tree")]),
    case("removal", "indirect", "crosswalk-rubble", "The pedestrian crossing is blocked by rubble; please clear it away.",
         [{"kind": "count", "category": "cement_rubble", "max": 0}, only("cement_rubble")],
         [remove(category="cement_rubble")], setup=[RUBBLE_WEST]),
    impossible("removal", "indirect", "library-building",
               "Could you take the Library building away? It blocks the view of the south side.",
               [remove("library")], notes="buildings are part of the world, not assets"),
    # vague
    case("removal", "vague", "lose-bench", "lose the bench",
         [gone("bench_1"), only(assets=("bench_1",))], [remove("bench_1")]),
    case("removal", "vague", "no-more-lamps", "no more lamp posts",
         [{"kind": "count", "category": "street_light", "max": 0}, only("street_light")], [remove(category="street_light")]),
    case("removal", "vague", "fewer-cars-lot-b", "fewer cars in lot B",
         [delta(VEHICLES, -3, -1), only(assets=LOT_B_CARS)], [remove("suv_1")]),
    case("removal", "vague", "clear-the-road", "clear the road",
         [{"kind": "count", "category": "traffic_cone", "max": 0}, only("traffic_cone")],
         [remove(category="traffic_cone")], setup=[planned(CONES_EASTBOUND)]),
    case("removal", "vague", "hydrant-gotta-go", "the hydrant's gotta go",
         [gone("fire_hydrant_1"), only(assets=("fire_hydrant_1",))], [remove("fire_hydrant_1")]),
    case("removal", "vague", "tree-by-library", "too many trees. drop the one by the library",
         [gone("tree_1"), present("tree_2", "tree_3", "tree_4"), only(assets=("tree_1",))],
         [remove(category="tree", near="Library entrance", count=1)]),
    case("removal", "vague", "that-truck", "nah, take that truck back out",
         [{"kind": "count", "category": "truck", "max": 0}, only("truck")], [remove(category="truck")],
         setup=[planned(TRUCK_UNION)]),
    case("removal", "vague", "ditch-rubble-cones", "ditch the rubble and the cones round it",
         [{"kind": "count", "category": ["cement_rubble", "traffic_cone"], "max": 0}, only("cement_rubble", "traffic_cone")],
         [remove(category="cement_rubble"), remove(category="traffic_cone")], tags=("compound",),
         setup=[RUBBLE_CENTRE, step("cones around it", arrange(["traffic_cone"], "ring", loc("at", "cement_rubble_1")))]),
    case("removal", "vague", "parked-ones", "the parked cars can go, all of them",
         [gone(*LOT_B_CARS), present("ego"), only(assets=LOT_B_CARS)], [remove(*LOT_B_CARS)]),
    impossible("removal", "vague", "helipad", "remove the helipad", [remove("helipad")],
               notes="there is no helipad"),
    # erroneous
    case("removal", "erroneous", "remvoe-bench", "remvoe the bench pls",
         [gone("bench_1"), only(assets=("bench_1",))], [remove("bench_1")]),
    case("removal", "erroneous", "delet-all-tree", "delet all tree",
         [gone(*TREES), only(assets=TREES)], [remove(category="tree")]),
    case("removal", "erroneous", "suv-parkin-lot", "remove the suv in parkin lot b",
         [gone("suv_1"), only(assets=("suv_1",))], [remove("suv_1")]),
    case("removal", "erroneous", "fire-hidrant", "take out fire hidrant",
         [gone("fire_hydrant_1"), only(assets=("fire_hydrant_1",))], [remove("fire_hydrant_1")]),
    case("removal", "erroneous", "traffic-light-near-of-library", "I want remove the traffic light near of library",
         [gone("traffic_light_1"), present("traffic_light_2"), only(assets=("traffic_light_1",))],
         [remove(category="traffic_light", near="Library entrance", count=1)]),
    case("removal", "erroneous", "teh-cones", "remove teh cones from infront JTEKT",
         [{"kind": "count", "category": "traffic_cone", "max": 0}, only("traffic_cone")],
         [remove(category="traffic_cone")], setup=[CONES_JTEKT]),
    case("removal", "erroneous", "trash-can-and-bench-bustop", "remove trash can and the bench at bustop",
         [gone("trash_bin_1", "bench_1"), only(assets=("trash_bin_1", "bench_1"))],
         [remove("trash_bin_1"), remove("bench_1")], tags=("compound",)),
    case("removal", "erroneous", "two-vehicle-near-union", "remove 2 vehicle from lot B, the ones more near to Student Union",
         [gone("passenger_car_2", "suv_1"), present("passenger_car_1"), only(assets=("passenger_car_2", "suv_1"))],
         [remove("passenger_car_2", "suv_1")]),
    case("removal", "erroneous", "street-lite-ego", "remoev the street lite closest of ego",
         [gone("street_light_2"), only(assets=("street_light_2",))], [remove(category="street_light", near="ego", count=1)]),
    impossible("removal", "erroneous", "fountain", "pls delet the fountain, its ugly", [remove("fountain")],
               notes="the fountain is a landmark of the world, not an asset"),
]


# Positioning: an existing asset put at a new place --------------------------------------------
POSITIONING = [
    # direct
    case("positioning", "direct", "bench-and-bin-fountain", "Put the bench next to the fountain and the trash bin beside the bench.",
         [near(asset="bench_1", target="fountain", within=6), near(asset="trash_bin_1", target="bench_1", within=3),
          only(assets=("bench_1", "trash_bin_1"))],
         [place("bench_1", loc("at", "fountain")), place("trash_bin_1", loc("next_to", "bench_1"))], tags=("compound",)),
    case("positioning", "direct", "bin-library", "Place the trash bin at the Library entrance.",
         [near(asset="trash_bin_1", target="Library entrance", within=6), only(assets=("trash_bin_1",))],
         [place("trash_bin_1", loc("at", "Library entrance"))]),
    case("positioning", "direct", "suv-lot-a", "Move the SUV to parking lot A.",
         [near(asset="suv_1", target="parking lot A", within=1), only(assets=("suv_1",))], [place("suv_1", loc("at", "parking lot A"))]),
    case("positioning", "direct", "ego-northbound", "Put the ego vehicle in the northbound lane of Campus Drive.",
         [in_lane("campus_northbound", asset="ego", aligned=True), drives(asset="ego", lane="campus_northbound"),
          only(assets=("ego",))], [place("ego", loc("in_lane", "campus_northbound"))]),
    case("positioning", "direct", "car1-coordinates", "Put passenger_car_1 at x = -85, y = 30.",
         [near(asset="passenger_car_1", point=[-85.0, 30.0], within=0.5), only(assets=("passenger_car_1",))],
         [place("passenger_car_1", loc("absolute", x=-85, y=30))]),
    case("positioning", "direct", "stop-sign-sidewalk-jtekt", "Put the stop sign on the sidewalk in front of the JTEKT building entrance.",
         [surface(["sidewalk"], asset="stop_sign_1"), near(asset="stop_sign_1", target="JTEKT building entrance", within=12),
          only(assets=("stop_sign_1",))], [place("stop_sign_1", loc("on_sidewalk", "JTEKT building entrance"))]),
    case("positioning", "direct", "bench-behind-bus-stop", "Place the bench behind the bus stop.",
         [relative("behind", "bus stop", asset="bench_1", max_distance=6), only(assets=("bench_1",))],
         [place("bench_1", loc("behind", "bus stop"))]),
    case("positioning", "direct", "hydrant-left-union", "Put the fire hydrant to the left of the Student Union entrance.",
         [relative("left_of", "Student Union entrance", asset="fire_hydrant_1", max_distance=6), only(assets=("fire_hydrant_1",))],
         [place("fire_hydrant_1", loc("left_of", "Student Union entrance"))]),
    case("positioning", "direct", "ped-front-engineering", "Put the pedestrian in front of the Engineering Hall entrance.",
         [relative("in_front_of", "Engineering Hall entrance", asset="pedestrian_1", max_distance=8),
          only(assets=("pedestrian_1",))], [place("pedestrian_1", loc("in_front_of", "Engineering Hall entrance"))],
         setup=[PED_AT_BUS_STOP]),
    impossible("positioning", "direct", "bench-off-map", "Put the bench at x = 500, y = 0.",
               [place("bench_1", loc("absolute", x=500, y=0))], notes="the campus spans x -110..110"),
    # indirect
    case("positioning", "indirect", "bench-east-gate", "The bench would be far more useful at the east gate.",
         [near(asset="bench_1", target="east gate", within=12), only(assets=("bench_1",))], [place("bench_1", loc("at", "east gate"))]),
    case("positioning", "indirect", "suv-waiting-union-white",
         "Could we have the SUV waiting at the Student Union entrance instead of in the lot, and make it white so it stands out?",
         [near(asset="suv_1", target="Student Union entrance", within=12), looks("white", asset="suv_1"),
          only(assets=("suv_1",))],
         [place("suv_1", loc("at", "Student Union entrance")), paint("suv_1", colour="white")], tags=("compound",)),
    case("positioning", "indirect", "bin-beside-bench", "I'd prefer the trash bin to stand right beside the bench.",
         [near(asset="trash_bin_1", target="bench_1", within=3), only(assets=("trash_bin_1",))],
         [place("trash_bin_1", loc("next_to", "bench_1"))]),
    case("positioning", "indirect", "car1-pickup-jtekt",
         "For the pick-up test, passenger_car_1 should be waiting at the JTEKT entrance rather than in the lot.",
         [near(asset="passenger_car_1", target="JTEKT building entrance", within=10), only(assets=("passenger_car_1",))],
         [place("passenger_car_1", loc("at", "JTEKT building entrance"))]),
    case("positioning", "indirect", "stop-sign-north-crosswalk",
         "It would make more sense if the stop sign stood at the north crosswalk.",
         [near(asset="stop_sign_1", target="north crosswalk", within=8), only(assets=("stop_sign_1",))],
         [place("stop_sign_1", loc("at", "north crosswalk"))]),
    case("positioning", "indirect", "rover-starts-main-gate", "The rover should start its run from the main gate.",
         [near(category="ackermann_robot", target="main gate", within=10), only("ackermann_robot")],
         [place("ackermann_robot_1", loc("at", "main gate"))], setup=[ROBOT_LOT_B]),
    case("positioning", "indirect", "ego-begins-lot-a", "Our ego should begin this test parked in parking lot A.",
         [near(asset="ego", target="parking lot A", within=1), only(assets=("ego",))],
         [place("ego", loc("at", "parking lot A"))]),
    case("positioning", "indirect", "hydrant-right-library", "Can the fire hydrant go to the right of the Library entrance?",
         [relative("right_of", "Library entrance", asset="fire_hydrant_1", max_distance=6), only(assets=("fire_hydrant_1",))],
         [place("fire_hydrant_1", loc("right_of", "Library entrance"))]),
    case("positioning", "indirect", "ped-now-bus-stop", "Now have them wait at the bus stop instead.",
         [{"kind": "count", "category": "pedestrian", "min": 1, "max": 1}, near("pedestrian", "bus stop", 6, scope="all"),
          only("pedestrian")], [place("pedestrian_1", loc("at", "bus stop"))],
         setup=[step("add a pedestrian at the fountain", add("pedestrian", loc("at", "fountain")), planned=True)]),
    impossible("positioning", "indirect", "bench-stadium", "The bench would look better at the football stadium.",
               [place("bench_1", loc("at", "football stadium"))], notes="the campus has no stadium"),
    # vague
    case("positioning", "vague", "bench-arrow-fountain", "bench -> fountain",
         [near(asset="bench_1", target="fountain", within=6), only(assets=("bench_1",))], [place("bench_1", loc("at", "fountain"))]),
    case("positioning", "vague", "bin-near-library", "the bin should be somewhere near the library",
         [near(asset="trash_bin_1", target="Library entrance", within=10), only(assets=("trash_bin_1",))],
         [place("trash_bin_1", loc("at", "Library entrance"))]),
    case("positioning", "vague", "suv-by-union", "park the SUV over by the union",
         [near(asset="suv_1", target="Student Union entrance", within=12), only(assets=("suv_1",))],
         [place("suv_1", loc("at", "Student Union entrance"))]),
    case("positioning", "vague", "hydrant-east-gate", "stick the hydrant by the east gate",
         [near(asset="fire_hydrant_1", target="east gate", within=12), only(assets=("fire_hydrant_1",))],
         [place("fire_hydrant_1", loc("at", "east gate"))]),
    case("positioning", "vague", "ego-back-gate", "ego: start at the back gate",
         [near(asset="ego", target="east gate", within=12), only(assets=("ego",))], [place("ego", loc("at", "east gate"))]),
    case("positioning", "vague", "car1-other-lot", "passenger car 1 over to the other lot",
         [near(asset="passenger_car_1", target="parking lot A", within=1), only(assets=("passenger_car_1",))],
         [place("passenger_car_1", loc("at", "parking lot A"))]),
    case("positioning", "vague", "stop-sign-by-bus-stop", "stop sign somewhere by the bus stop",
         [near(asset="stop_sign_1", target="bus stop", within=8), only(assets=("stop_sign_1",))],
         [place("stop_sign_1", loc("at", "bus stop"))]),
    case("positioning", "vague", "bike-fountain", "the bike, over by the fountain",
         [near(category="bicycle", target="fountain", within=8), only("bicycle")],
         [place("bicycle_1", loc("at", "fountain"))], setup=[BIKE_LIBRARY]),
    case("positioning", "vague", "ego-somewhere-lot-b", "put the ego somewhere in lot B",
         [near(asset="ego", target="parking lot B", within=1), only(assets=("ego",))], [place("ego", loc("at", "parking lot B"))]),
    impossible("positioning", "vague", "ego-bike-lane", "ego into the bike lane",
               [place("ego", loc("in_lane", "bike_lane", lane="bike_lane"))], notes="the campus has no bike lane"),
    # erroneous
    case("positioning", "erroneous", "bench-infront-library", "put the bench infront the library enterance",
         [relative("in_front_of", "Library entrance", asset="bench_1", max_distance=8), only(assets=("bench_1",))],
         [place("bench_1", loc("in_front_of", "Library entrance"))]),
    case("positioning", "erroneous", "suv-parking-lot-a", "place suv at the parking lot A pls",
         [near(asset="suv_1", target="parking lot A", within=1), only(assets=("suv_1",))], [place("suv_1", loc("at", "parking lot A"))]),
    case("positioning", "erroneous", "bin-near-of-fountain", "put the bin to near of fountain",
         [near(asset="trash_bin_1", target="fountain", within=6), only(assets=("trash_bin_1",))],
         [place("trash_bin_1", loc("at", "fountain"))]),
    case("positioning", "erroneous", "ego-lane-nortbound", "put ego car in lane campus nortbound",
         [in_lane("campus_northbound", asset="ego", aligned=True), only(assets=("ego",))],
         [place("ego", loc("in_lane", "campus_northbound"))]),
    case("positioning", "erroneous", "hidrant-coordinates", "place hidrant at x 20, y -8",
         [near(asset="fire_hydrant_1", point=[20.0, -8.0], within=0.5), only(assets=("fire_hydrant_1",))],
         [place("fire_hydrant_1", loc("absolute", x=20, y=-8))]),
    case("positioning", "erroneous", "stop-sign-next-bus-stop", "stop sign put next to the bus stop plz",
         [near(asset="stop_sign_1", target="bus stop", within=8), only(assets=("stop_sign_1",))],
         [place("stop_sign_1", loc("at", "bus stop"))]),
    case("positioning", "erroneous", "car-number-2-union", "i want the car number 2 stay at student union entrance",
         [near(asset="passenger_car_2", target="Student Union entrance", within=12), only(assets=("passenger_car_2",))],
         [place("passenger_car_2", loc("at", "Student Union entrance"))]),
    case("positioning", "erroneous", "suv-lot-a-entrance", "plase the SUV to lot A entrence",
         [near(asset="suv_1", target="parking lot A entrance", within=8), only(assets=("suv_1",))],
         [place("suv_1", loc("at", "parking lot A entrance"))]),
    case("positioning", "erroneous", "ego-main-gate-east", "put ego to the main gate, it must look to east",
         [near(asset="ego", target="main gate", within=8), moved("ego", 30.0, None, None, (None, 20.0)),
          only(assets=("ego",))], [place("ego", loc("at", "main gate"), yaw=0)]),
    impossible("positioning", "erroneous", "bench-inside-jtekt", "put the bench inside of JTEKT building, in the middle",
               [place("bench_1", loc("absolute", x=37.5, y=29))], notes="nothing may stand inside a building"),
]


# Moving: shift, turn, or change what an asset does ---------------------------------------------
MOVING = [
    # direct
    case("moving", "direct", "ego-10m-forward", "Move the ego vehicle 10 metres forward.",
         [moved("ego", 9.5, 10.5, "forward"), only(assets=("ego",))], [shift("ego", forward=10)]),
    case("moving", "direct", "suv-5m-north", "Move the SUV 5 m north.",
         [moved("suv_1", 4.5, 5.5, "forward"), only(assets=("suv_1",))], [shift("suv_1", north=5)]),
    case("moving", "direct", "turn-bench-90", "Turn the bench 90 degrees.",
         [moved("bench_1", 0.0, 0.5, None, (80.0, 100.0)), only(assets=("bench_1",))], [shift("bench_1", turn_deg=90)]),
    case("moving", "direct", "bin-2m-east", "Shift the trash bin 2 metres east.",
         [near(asset="trash_bin_1", point=[-31.5, -5.5], within=0.5), only(assets=("trash_bin_1",))], [shift("trash_bin_1", east=2)]),
    case("moving", "direct", "ego-10-mps", "Make the ego drive at 10 m/s.",
         [drives(asset="ego", lane="main_eastbound", speed=(9.5, 10.5)), only(assets=("ego",))],
         [act("ego", "drive_lane", lane="main_eastbound", speed=10)]),
    case("moving", "direct", "car1-eastbound", "Make passenger_car_1 drive in the eastbound lane of Main Street.",
         [drives(asset="passenger_car_1", lane="main_eastbound"), in_lane("main_eastbound", asset="passenger_car_1"),
          only(assets=("passenger_car_1",))], [act("passenger_car_1", "drive_lane", lane="main_eastbound")]),
    case("moving", "direct", "ego-20m-back-4mps", "Move the ego 20 metres backward and then set its speed to 4 m/s.",
         [moved("ego", 19.5, 20.5, "backward"), drives(asset="ego", speed=(3.5, 4.5)), only(assets=("ego",))],
         [shift("ego", forward=-20), act("ego", "drive_lane", lane="main_eastbound", speed=4)], tags=("compound",)),
    case("moving", "direct", "suv-circle-6", "Have the SUV drive in a circle of radius 6 m in parking lot B.",
         [does("circle", asset="suv_1", radius_min=5.5, radius_max=6.5), only(assets=("suv_1",))],
         [act("suv_1", "circle", radius=6, centre="parking lot B")]),
    case("moving", "direct", "ped-cross-west", "Make the pedestrian cross the road at the west crosswalk.",
         [does("cross_road", asset="pedestrian_1", crosses_lane="main_eastbound"), only(assets=("pedestrian_1",))],
         [act("pedestrian_1", "cross_road")], setup=[PED_AT_BUS_STOP]),
    impossible("moving", "direct", "ego-300m", "Move the ego 300 metres forward.", [shift("ego", forward=300)],
               notes="the campus is 220 m wide; a shift is at most 100 m"),
    # indirect
    case("moving", "indirect", "ego-15m-further-back", "I'd like the ego to start 15 metres further back than it does now.",
         [moved("ego", 14.5, 15.5, "backward"), only(assets=("ego",))], [shift("ego", forward=-15)]),
    case("moving", "indirect", "bench-turned-around", "The bench faces the road; it would look nicer turned around the other way.",
         [moved("bench_1", 0.0, 0.5, None, (160.0, 180.0)), only(assets=("bench_1",))], [shift("bench_1", turn_deg=180)]),
    case("moving", "indirect", "suv-pull-forward", "Can the SUV pull forward about 3 m so it isn't level with the other two?",
         [moved("suv_1", 2.5, 3.5, "forward"), only(assets=("suv_1",))], [shift("suv_1", forward=3)]),
    case("moving", "indirect", "ego-slower-3", "We want the ego to go slower, something like 3 m/s.",
         [drives(asset="ego", speed=(2.5, 3.5)), only(assets=("ego",))], [act("ego", "drive_lane", lane="main_eastbound", speed=3)]),
    case("moving", "indirect", "suv-up-campus-drive", "The SUV should be driving up Campus Drive, heading north.",
         [drives(asset="suv_1", lane="campus_northbound"), only(assets=("suv_1",))],
         [act("suv_1", "drive_lane", lane="campus_northbound")]),
    case("moving", "indirect", "car2-laps", "Could passenger_car_2 do some laps in lot B, radius 8 metres?",
         [does("circle", asset="passenger_car_2", radius_min=7.5, radius_max=8.5, centre_near="parking lot B", centre_within=25),
          only(assets=("passenger_car_2",))], [act("passenger_car_2", "circle", radius=8, centre="parking lot B")]),
    case("moving", "indirect", "jaywalker-from-ped", "Let's have a jaywalker: that pedestrian should cut across in front of the ego.",
         [does("jaywalk", asset="pedestrian_1", crosses_lane="main_eastbound"), only(assets=("pedestrian_1",))],
         [act("pedestrian_1", "jaywalk")], setup=[PED_AT_BUS_STOP]),
    case("moving", "indirect", "bin-nudge-west", "The trash bin crowds the bus stop a bit; nudge it a metre to the west.",
         [near(asset="trash_bin_1", point=[-34.5, -5.5], within=0.4), only(assets=("trash_bin_1",))], [shift("trash_bin_1", east=-1)]),
    case("moving", "indirect", "speed-it-up", "Speed it up to 12 m/s.",
         [drives(VEHICLES, lane="main_westbound", speed=(11.5, 12.5)), only(*VEHICLES)],
         [act("passenger_car_3", "drive_lane", lane="main_westbound", speed=12)],
         setup=[step("add a car driving in the westbound lane of Main Street",
                     add("passenger_car", loc("in_lane", "main_westbound"),
                         behaviour=behaviour("drive_lane", lane="main_westbound")), planned=True)]),
    case("moving", "indirect", "ego-stay-put-headlights",
         "Our ego should stay put for this test, no driving, but with its headlights switched on.",
         [does("parked", asset="ego"), env(vehicle_lights="on"), only(assets=("ego",), environment=True)],
         [act("ego", "parked"), lights(vehicle_lights="on")], tags=("compound",)),
    # vague
    case("moving", "vague", "ego-forward-bit", "ego forward a bit",
         [moved("ego", 0.5, 15.0, "forward"), only(assets=("ego",))], [shift("ego", forward=5)]),
    case("moving", "vague", "spin-bench", "spin the bench round",
         [moved("bench_1", 0.0, 0.5, None, (150.0, 180.0)), only(assets=("bench_1",))], [shift("bench_1", turn_deg=180)]),
    case("moving", "vague", "suv-donuts", "SUV doing donuts in lot B",
         [does("circle", asset="suv_1", centre_near="parking lot B", centre_within=25), only(assets=("suv_1",))],
         [act("suv_1", "circle", centre="parking lot B")]),
    case("moving", "vague", "ego-slower", "ego slower",
         [drives(asset="ego", speed=(0.1, 4.9)), only(assets=("ego",))], [act("ego", "drive_lane", lane="main_eastbound", speed=3)]),
    case("moving", "vague", "car2-back-few", "passenger car 2, back up a few metres",
         [moved("passenger_car_2", 1.0, 8.0, "backward"), only(assets=("passenger_car_2",))],
         [shift("passenger_car_2", forward=-3)]),
    case("moving", "vague", "bin-2m-east", "bin, 2 m east",
         [near(asset="trash_bin_1", point=[-31.5, -5.5], within=0.5), only(assets=("trash_bin_1",))], [shift("trash_bin_1", east=2)]),
    case("moving", "vague", "stop-the-ego", "stop the ego",
         [does("parked", asset="ego"), only(assets=("ego",))], [act("ego", "parked")]),
    case("moving", "vague", "hydrant-bit-north", "hydrant a little north",
         [moved("fire_hydrant_1", 0.3, 5.0, "left"), only(assets=("fire_hydrant_1",))], [shift("fire_hydrant_1", north=1)]),
    case("moving", "vague", "ego-faster", "the ego, faster",
         [drives(asset="ego", speed=(5.5, None)), only(assets=("ego",))], [act("ego", "drive_lane", lane="main_eastbound", speed=8)]),
    case("moving", "vague", "ped-crossing", "get them crossing at the crosswalk",
         [does("cross_road", category="pedestrian", scope="all"), only("pedestrian")],
         [act("pedestrian_1", "cross_road")], setup=[step("a pedestrian at the bus stop",
                                                          add("pedestrian", loc("at", "bus stop")), planned=True)]),
    # erroneous
    case("moving", "erroneous", "ego-10-meter-foward", "move ego 10 meter foward",
         [moved("ego", 9.5, 10.5, "forward"), only(assets=("ego",))], [shift("ego", forward=10)]),
    case("moving", "erroneous", "turn-teh-bench-east", "turn teh bench 90 degre and move it 1 meter to east",
         [moved("bench_1", 0.5, 1.5, None, (80.0, 100.0)), near(asset="bench_1", point=[-25.0, -6.9], within=0.4),
          only(assets=("bench_1",))], [shift("bench_1", turn_deg=90), shift("bench_1", east=1)], tags=("compound",)),
    case("moving", "erroneous", "ego-8-mps", "make the ego go with 8 m/s speed",
         [drives(asset="ego", speed=(7.5, 8.5)), only(assets=("ego",))], [act("ego", "drive_lane", lane="main_eastbound", speed=8)]),
    case("moving", "erroneous", "suv-5-metre-north", "suv go 5 metre to north plese",
         [moved("suv_1", 4.5, 5.5, "forward"), only(assets=("suv_1",))], [shift("suv_1", north=5)]),
    case("moving", "erroneous", "pedestrain-zebra", "the pedestrain must walk across the road on zebra crossing",
         [does("cross_road", asset="pedestrian_1"), only(assets=("pedestrian_1",))],
         [act("pedestrian_1", "cross_road")], setup=[PED_AT_BUS_STOP]),
    case("moving", "erroneous", "car1-circle-lot-b", "car_1 make circle in lot B radius 5m",
         [does("circle", asset="passenger_car_1", radius_min=4.5, radius_max=5.5), only(assets=("passenger_car_1",))],
         [act("passenger_car_1", "circle", radius=5, centre="parking lot B")]),
    case("moving", "erroneous", "hydrant-2m-back", "move hydrant 2m in back",
         [moved("fire_hydrant_1", 1.5, 2.5, "backward"), only(assets=("fire_hydrant_1",))], [shift("fire_hydrant_1", forward=-2)]),
    case("moving", "erroneous", "ego-have-to-stop", "ego car have to stop and stay",
         [does("parked", asset="ego"), only(assets=("ego",))], [act("ego", "parked")]),
    case("moving", "erroneous", "ego-30-feet", "move ego 30 feet foward",
         [moved("ego", 8.6, 9.7, "forward"), only(assets=("ego",))], [shift("ego", forward=9.14)]),
    impossible("moving", "erroneous", "bench-drive", "make the bench drive in main street",
               [act("bench_1", "drive_lane", lane="main_eastbound")], notes="only vehicles, robots and riders drive"),
]


# Arrangement: several new assets laid out together ---------------------------------------------
ARRANGEMENT = [
    # direct
    case("arrangement", "direct", "five-cones-jtekt", "Place five traffic cones in a line in front of the JTEKT building entrance.",
         [exactly("traffic_cone", 5), line("traffic_cone", 5), every(near("traffic_cone", "JTEKT building entrance", 12)),
          only("traffic_cone")],
         [arrange(["traffic_cone"], "line", loc("in_front_of", "JTEKT building entrance"), count=5)]),
    case("arrangement", "direct", "ring-cones-intersection", "Put a ring of traffic cones around the centre of the intersection.",
         [delta("traffic_cone", 4, None), ring("traffic_cone", "main intersection", 4), only("traffic_cone")],
         [arrange(["traffic_cone"], "ring", loc("at", "main intersection"))]),
    case("arrangement", "direct", "lane-edge-ahead-ego",
         "Line the right edge of the eastbound lane with 6 cones, starting 20 m ahead of the ego.",
         [exactly("traffic_cone", 6), in_lane("main_eastbound", "traffic_cone", every=True), line("traffic_cone", 6),
          every(relative("in_front_of", "ego", "traffic_cone", max_distance=45, tolerance_deg=20)), only("traffic_cone")],
         [arrange(["traffic_cone"], "lane_edge", loc("at", "ego", along_m=20), count=6)]),
    case("arrangement", "direct", "four-cars-lot-a", "Park four cars side by side in parking lot A.",
         [exactly(VEHICLES, 4), line(VEHICLES, 4), every(near(VEHICLES, "parking lot A", 1), 4), only(*VEHICLES)],
         [arrange(["passenger_car"], "parking_row", loc("at", "parking lot A"), count=4)]),
    case("arrangement", "direct", "grid-bollards-gate", "Arrange nine bollards in a grid at the main gate.",
         [exactly("bollard", 9), every(near("bollard", "main gate", 12)), shape("cluster", "bollard", n=9, tolerance=6.0),
          only("bollard")], [arrange(["bollard"], "grid", loc("at", "main gate"), count=9)]),
    case("arrangement", "direct", "barriers-behind-ego", "Put a line of 3 road barriers across Main Street behind the ego.",
         [exactly("road_barrier", 3), line("road_barrier", 3),
          every(relative("behind", "ego", "road_barrier", max_distance=15, tolerance_deg=70)), only("road_barrier")],
         [arrange(["road_barrier"], "line", loc("behind", "ego"), count=3)]),
    case("arrangement", "direct", "ring-peds-fountain", "Make a ring of 8 pedestrians around the fountain.",
         [exactly("pedestrian", 8), ring("pedestrian", "fountain", 8), only("pedestrian")],
         [arrange(["pedestrian"], "ring", loc("at", "fountain"), count=8)]),
    case("arrangement", "direct", "surround-rubble-and-sign",
         "Surround the rubble with traffic cones and put a construction sign next to it.",
         [delta("traffic_cone", 4, None), ring("traffic_cone", "cement_rubble_1", 4), exactly("construction_sign", 1),
          near("construction_sign", "cement_rubble_1", 8), only("traffic_cone", "construction_sign")],
         [arrange(["traffic_cone"], "ring", loc("at", "cement_rubble_1")),
          add("construction_sign", loc("next_to", "cement_rubble_1"))], setup=[RUBBLE_CENTRE], tags=("compound",)),
    case("arrangement", "direct", "three-suvs-lot-b", "Put a row of three SUVs side by side in parking lot B.",
         [exactly("suv", 3), line("suv", 3), every(added(near("suv", "parking lot B", 1)), 3), only("suv")],
         [arrange(["suv"], "parking_row", loc("at", "parking lot B"), count=3)]),
    impossible("arrangement", "direct", "thirty-trucks", "Park thirty trucks side by side in parking lot A.",
               [arrange(["truck"], "parking_row", loc("at", "parking lot A"), count=30)],
               notes="a scene holds at most 10 trucks"),
    # indirect
    case("arrangement", "indirect", "close-westbound-east-gate",
         "We're closing the westbound lane near the east gate, so please line its edge with six cones there.",
         [exactly("traffic_cone", 6), in_lane("main_westbound", "traffic_cone", every=True),
          every(near("traffic_cone", "east gate", 30)), only("traffic_cone")],
         [arrange(["traffic_cone"], "lane_edge", loc("at", "east gate", lane="main_westbound"), count=6)]),
    case("arrangement", "indirect", "fence-hydrant-bollards",
         "Something's leaking at the fire hydrant; I'd like it fenced off with bollards all around.",
         [delta("bollard", 4, None), ring("bollard", "fire_hydrant_1", 4), only("bollard")],
         [arrange(["bollard"], "ring", loc("at", "fire_hydrant_1"))]),
    case("arrangement", "indirect", "crowd-fountain-evening",
         "We're filming a crowd scene in the evening: ten people should stand in a circle around the fountain.",
         [exactly("pedestrian", 10), ring("pedestrian", "fountain", 10), env(time_from="19:00", time_to="22:30"),
          only("pedestrian", environment=True)],
         [arrange(["pedestrian"], "ring", loc("at", "fountain"), count=10), clock("evening")], tags=("compound",)),
    case("arrangement", "indirect", "parking-test-lot-b",
         "For the parking test, fill a row in lot B with three cars side by side.",
         [exactly(VEHICLES, 3), line(VEHICLES, 3), every(added(near(VEHICLES, "parking lot B", 1)), 3), only(*VEHICLES)],
         [arrange(["passenger_car"], "parking_row", loc("at", "parking lot B"), count=3)]),
    case("arrangement", "indirect", "cordon-union-bollards",
         "Cordon off the Student Union entrance with a line of five bollards in front of it.",
         [exactly("bollard", 5), line("bollard", 5),
          every(relative("in_front_of", "Student Union entrance", "bollard", max_distance=8, tolerance_deg=75)), only("bollard")],
         [arrange(["bollard"], "line", loc("in_front_of", "Student Union entrance"), count=5)]),
    case("arrangement", "indirect", "work-zone-rubble", "We want the work zone marked out properly: cones all the way round it.",
         [delta("traffic_cone", 4, None), ring("traffic_cone", "cement_rubble_1", 4), only("traffic_cone")],
         [arrange(["traffic_cone"], "ring", loc("at", "cement_rubble_1"))],
         setup=[step("put some rubble on the road at the crossroads", add("cement_rubble", loc("at", "main intersection")),
                     planned=True)]),
    case("arrangement", "indirect", "trucks-photo-lot-a",
         "I need the delivery trucks lined up in lot A for a photo: three of them, side by side.",
         [exactly("truck", 3), line("truck", 3), every(near("truck", "parking lot A", 1), 3), only("truck")],
         [arrange(["truck"], "parking_row", loc("at", "parking lot A"), count=3)]),
    case("arrangement", "indirect", "block-library-dropoff",
         "The Library drop-off has to be closed, so put a line of five cones across it in front of the entrance.",
         [exactly("traffic_cone", 5), line("traffic_cone", 5),
          every(relative("in_front_of", "Library entrance", "traffic_cone", max_distance=8, tolerance_deg=75)),
          only("traffic_cone")], [arrange(["traffic_cone"], "line", loc("in_front_of", "Library entrance"), count=5)]),
    case("arrangement", "indirect", "slalom-ahead-ego",
         "Could you set up a slalom for the ego: five cones in a line along its lane, about 30 metres ahead of it?",
         [exactly("traffic_cone", 5), line("traffic_cone", 5), in_lane("main_eastbound", "traffic_cone", every=True),
          every(relative("in_front_of", "ego", "traffic_cone", max_distance=45, tolerance_deg=20)), only("traffic_cone")],
         [arrange(["traffic_cone"], "line", loc("at", "ego", along_m=30), count=5)]),
    impossible("arrangement", "indirect", "row-lot-c", "For the parking test, set up a row of four cars in parking lot C.",
               [arrange(["passenger_car"], "parking_row", loc("at", "parking lot C"), count=4)],
               notes="the campus has lots A and B only"),
    # vague
    case("arrangement", "vague", "cones-round-rubble", "cones around the rubble",
         [delta("traffic_cone", 3, None), ring("traffic_cone", "cement_rubble_1", 3), only("traffic_cone")],
         [arrange(["traffic_cone"], "ring", loc("at", "cement_rubble_1"))], setup=[RUBBLE_CENTRE]),
    case("arrangement", "vague", "row-of-cars-lot-a", "a row of cars in lot A",
         [delta(VEHICLES, 2, None), line(VEHICLES, 2), every(added(near(VEHICLES, "parking lot A", 1))), only(*VEHICLES)],
         [arrange(["passenger_car"], "parking_row", loc("at", "parking lot A"), count=4)]),
    case("arrangement", "vague", "circle-people-fountain", "circle of people round the fountain",
         [delta("pedestrian", 3, None), ring("pedestrian", "fountain", 3), only("pedestrian")],
         [arrange(["pedestrian"], "ring", loc("at", "fountain"), count=8)]),
    case("arrangement", "vague", "line-bins-bus-stop", "line of bins by the bus stop",
         [delta("trash_bin", 2, None), line("trash_bin", 2), every(added(near("trash_bin", "bus stop", 12))),
          only("trash_bin")], [arrange(["trash_bin"], "line", loc("at", "bus stop"), count=4)]),
    case("arrangement", "vague", "block-main-street", "block main street with a line of barriers, just west of the crossroads",
         [delta("road_barrier", 2, None), line("road_barrier", 2), every(added(in_lane(None, "road_barrier"))),
          every(added(near("road_barrier", "main intersection", 45))), only("road_barrier")],
         [arrange(["road_barrier"], "line", loc("absolute", x=-20, y=0), count=3, heading_deg=90, spacing=2.2)]),
    case("arrangement", "vague", "bollard-grid-east-gate", "some bollards in a grid near the east gate",
         [delta("bollard", 4, None), every(added(near("bollard", "east gate", 15))), only("bollard")],
         [arrange(["bollard"], "grid", loc("at", "east gate"), count=4)]),
    case("arrangement", "vague", "ring-cones-middle", "ring of cones in the middle of the junction",
         [delta("traffic_cone", 4, None), ring("traffic_cone", "main intersection", 4), only("traffic_cone")],
         [arrange(["traffic_cone"], "ring", loc("at", "main intersection"))]),
    case("arrangement", "vague", "cones-along-westbound", "cones all along the edge of the westbound lane",
         [delta("traffic_cone", 4, None), in_lane("main_westbound", "traffic_cone", every=True), line("traffic_cone", 4),
          only("traffic_cone")], [arrange(["traffic_cone"], "lane_edge", loc("at", "main_westbound"), count=8)]),
    case("arrangement", "vague", "few-suvs-lot-b", "line up a few SUVs in lot B",
         [delta("suv", 2, 6), line("suv", 2), every(added(near("suv", "parking lot B", 1))), only("suv")],
         [arrange(["suv"], "parking_row", loc("at", "parking lot B"), count=3)]),
    case("arrangement", "vague", "benches-round-fountain-tree", "benches in a circle round the tree by the fountain",
         [delta("bench", 3, None), ring("bench", "tree_2", 3), only("bench")],
         [arrange(["bench"], "ring", loc("at", "tree_2"), count=4)]),
    # erroneous
    case("arrangement", "erroneous", "5-cone-jtekt", "put 5 cone in line infront of JTEKT enterance",
         [exactly("traffic_cone", 5), line("traffic_cone", 5), every(near("traffic_cone", "JTEKT building entrance", 12)),
          only("traffic_cone")], [arrange(["traffic_cone"], "line", loc("in_front_of", "JTEKT building entrance"), count=5)]),
    case("arrangement", "erroneous", "circel-rubble", "make circel of cones arround the rubble",
         [delta("traffic_cone", 3, None), ring("traffic_cone", "cement_rubble_1", 3), only("traffic_cone")],
         [arrange(["traffic_cone"], "ring", loc("at", "cement_rubble_1"))], setup=[RUBBLE_CENTRE]),
    case("arrangement", "erroneous", "3-car-side-by-side", "park 3 car side by side in lot b",
         [exactly(VEHICLES, 3), line(VEHICLES, 3), every(added(near(VEHICLES, "parking lot B", 1)), 3), only(*VEHICLES)],
         [arrange(["passenger_car"], "parking_row", loc("at", "parking lot B"), count=3)]),
    case("arrangement", "erroneous", "east-bound-8-peace", "I want the cones along the east bound lane edge, 8 peace",
         [exactly("traffic_cone", 8), in_lane("main_eastbound", "traffic_cone", every=True), line("traffic_cone", 8),
          only("traffic_cone")], [arrange(["traffic_cone"], "lane_edge", loc("at", "main_eastbound"), count=8)]),
    case("arrangement", "erroneous", "4-bollard-grid", "arange 4 bollard in grid at lot B entrence",
         [exactly("bollard", 4), every(near("bollard", "parking lot B entrance", 10)), only("bollard")],
         [arrange(["bollard"], "grid", loc("at", "parking lot B entrance"), count=4)]),
    case("arrangement", "erroneous", "10-pedestrian-circle", "10 pedestrian around fountain like circle",
         [exactly("pedestrian", 10), ring("pedestrian", "fountain", 10), only("pedestrian")],
         [arrange(["pedestrian"], "ring", loc("at", "fountain"), count=10)]),
    case("arrangement", "erroneous", "cones-2-meter", "put line of 3 cones 2 meter apart in front the main gate",
         [exactly("traffic_cone", 3), line("traffic_cone", 3, spacing=(1.8, 2.2)), every(near("traffic_cone", "main gate", 12)),
          only("traffic_cone")],
         [arrange(["traffic_cone"], "line", loc("in_front_of", "main gate"), count=3, spacing=2)]),
    case("arrangement", "erroneous", "row-truk-lot-a", "row of truk in lot A, three",
         [exactly("truck", 3), line("truck", 3), every(near("truck", "parking lot A", 1), 3), only("truck")],
         [arrange(["truck"], "parking_row", loc("at", "parking lot A"), count=3)]),
    case("arrangement", "erroneous", "bollards-hidrant", "bollards in ring round the fire hidrant, 6 of them",
         [exactly("bollard", 6), ring("bollard", "fire_hydrant_1", 6), only("bollard")],
         [arrange(["bollard"], "ring", loc("at", "fire_hydrant_1"), count=6)]),
    impossible("arrangement", "erroneous", "150-cone-ring", "put 150 cone in ring arround the intersection",
               [arrange(["traffic_cone"], "ring", loc("at", "main intersection"), count=150)],
               notes="one arrangement holds at most 100"),
]


# Appearance: weather, time, lighting, colours and materials -------------------------------------
APPEARANCE = [
    # direct
    case("appearance", "direct", "rain", "Make it rain.", [env(weather=["rain"]), only(environment=True)], [weather("rain")]),
    case("appearance", "direct", "time-1845", "Set the time to 18:45.",
         [env(time_from="18:45", time_to="18:45"), only(environment=True)], [clock("18:45")]),
    case("appearance", "direct", "suv-red", "Paint the SUV red.",
         [looks("red", asset="suv_1"), only(assets=("suv_1",))], [paint("suv_1", colour="red")]),
    case("appearance", "direct", "street-lights-on", "Turn the street lights on.",
         [env(street_lights="on"), only(environment=True)], [lights(street_lights="on")]),
    case("appearance", "direct", "heavy-fog", "Add heavy fog.",
         [env(weather=["fog"], intensity_min=0.75), only(environment=True)], [weather("fog", 0.9)]),
    case("appearance", "direct", "benches-blue", "Make all the benches blue.",
         [looks("blue", "bench", scope="all", every=True), only("bench")], [paint(category="bench", colour="blue")]),
    case("appearance", "direct", "night", "Make it night.", [env(night=True), only(environment=True)], [clock("night")]),
    case("appearance", "direct", "ego-metal-silver", "Give the ego vehicle a silver metallic finish.",
         [looks("silver", asset="ego", material="metal"), only(assets=("ego",))], [paint("ego", colour="silver", material="metal")]),
    case("appearance", "direct", "light-snow-dawn", "Set light snow and move the clock to 06:15.",
         [env(weather=["snow"], intensity_min=0.1, intensity_max=0.45, time_from="06:15", time_to="06:15"),
          only(environment=True)], [weather("snow", 0.3), clock("06:15")], tags=("compound",)),
    impossible("appearance", "direct", "sandstorm", "Make it a sandstorm.", [weather("sandstorm")],
               notes="weather is clear, cloudy, rain, fog or snow"),
    # indirect
    case("appearance", "indirect", "overcast-afternoon", "I'd like the scene to feel like a grey, overcast afternoon.",
         [env(weather=["cloudy"], time_from="12:30", time_to="17:59", night=False), only(environment=True)],
         [weather("cloudy"), clock("15:00")], tags=("compound",)),
    case("appearance", "indirect", "cameras-at-dawn", "We need to test the cameras at dawn.",
         [env(time_from="05:00", time_to="07:00"), only(environment=True)], [clock("dawn")]),
    case("appearance", "indirect", "hydrant-yellow", "Can the fire hydrant be yellow, like the ones in my home town?",
         [looks("yellow", asset="fire_hydrant_1"), only(assets=("fire_hydrant_1",))], [paint("fire_hydrant_1", colour="yellow")]),
    case("appearance", "indirect", "headlights-on", "The drivers should have their headlights switched on.",
         [env(vehicle_lights="on"), only(environment=True)], [lights(vehicle_lights="on")]),
    case("appearance", "indirect", "downpour", "It would be good to test how the ego copes in a real downpour.",
         [env(weather=["rain"], intensity_min=0.75), only(environment=True)], [weather("rain", 0.9)]),
    case("appearance", "indirect", "bench-wood", "The bench should look like it's made of wood.",
         [looks(asset="bench_1", material="wood"), only(assets=("bench_1",))], [paint("bench_1", material="wood")]),
    case("appearance", "indirect", "after-sundown", "Let's see how the sensors cope once the sun has gone down.",
         [env(night=True), only(environment=True)], [clock("night")]),
    case("appearance", "indirect", "sponsor-colour", "Our sponsor wants the ego in their colour, #1e90ff.",
         [looks("#1e90ff", asset="ego"), only(assets=("ego",))], [paint("ego", colour="#1e90ff")]),
    case("appearance", "indirect", "no-rain", "I don't want any rain in this scene any more.",
         [env(weather=["clear", "cloudy"]), only(environment=True)], [weather("clear")], setup=[planned(RAIN)]),
    impossible("appearance", "indirect", "library-red", "Could the Library building be painted red for the open day?",
               [paint("library", colour="red")], notes="buildings are not assets and cannot be recoloured"),
    # vague
    case("appearance", "vague", "spooky-night-fog", "spooky foggy night",
         [env(weather=["fog"], night=True), only(environment=True)], [weather("fog"), clock("night")], tags=("compound",)),
    case("appearance", "vague", "winter", "make it snow, proper winter",
         [env(weather=["snow"]), only(environment=True)], [weather("snow")]),
    case("appearance", "vague", "bench-green", "bench -> green",
         [looks("green", asset="bench_1"), only(assets=("bench_1",))], [paint("bench_1", colour="green")]),
    case("appearance", "vague", "sunset", "sunset",
         [env(time_from="18:30", time_to="20:30"), only(environment=True)], [clock("sunset")]),
    case("appearance", "vague", "lights-on-night", "it's dark, lights on",
         [only(environment=True)], [lights(street_lights="on")], setup=[NIGHT],
         alternatives=[[env(street_lights="on")], [env(vehicle_lights="on")]]),
    case("appearance", "vague", "lot-cars-orange", "make the two sedans in lot B pop, bright orange",
         [looks("orange", asset="passenger_car_1"), looks("orange", asset="passenger_car_2"), only("passenger_car")],
         [paint("passenger_car_1", "passenger_car_2", colour="orange")]),
    case("appearance", "vague", "clear-skies", "clear skies please",
         [env(weather=["clear"]), only(environment=True)], [weather("clear")], setup=[RAIN]),
    case("appearance", "vague", "midnight", "midnight",
         [env(time_from="23:30", time_to="00:30"), only(environment=True)], [clock("midnight")]),
    case("appearance", "vague", "drizzle", "just a drizzle",
         [env(weather=["rain"], intensity_max=0.45), only(environment=True)], [weather("rain", 0.2)]),
    case("appearance", "vague", "ego-black", "ego in black",
         [looks("black", asset="ego"), only(assets=("ego",))], [paint("ego", colour="black")]),
    # erroneous
    case("appearance", "erroneous", "rainning-nigth", "make it rainning and nigth",
         [env(weather=["rain"], night=True), only(environment=True)], [weather("rain"), clock("night")], tags=("compound",)),
    case("appearance", "erroneous", "7-evning", "set time to 7 in the evning",
         [env(time_from="19:00", time_to="19:00"), only(environment=True)], [clock("19:00")]),
    case("appearance", "erroneous", "suv-redd", "paint the suv in redd colour",
         [looks("red", asset="suv_1"), only(assets=("suv_1",))], [paint("suv_1", colour="red")]),
    case("appearance", "erroneous", "turn-of-street-lights", "turn of the street lights, we dont need them",
         [env(street_lights="off"), only(environment=True)], [lights(street_lights="off")]),
    case("appearance", "erroneous", "snowing-more-heavy", "I want snowing weather, more heavy",
         [env(weather=["snow"], intensity_min=0.75), only(environment=True)], [weather("snow", 0.9)]),
    case("appearance", "erroneous", "fog-lite", "make fog lite",
         [env(weather=["fog"], intensity_max=0.45), only(environment=True)], [weather("fog", 0.3)]),
    case("appearance", "erroneous", "hydrnat-blue", "colour the fire hydrnat to blue",
         [looks("blue", asset="fire_hydrant_1"), only(assets=("fire_hydrant_1",))], [paint("fire_hydrant_1", colour="blue")]),
    case("appearance", "erroneous", "hole-scene-night", "make the hole scene at night time",
         [env(night=True), only(environment=True)], [clock("night")]),
    impossible("appearance", "erroneous", "25-oclock", "make it 25 o'clock", [clock("25:00")],
               notes="a clock time runs 00:00..23:59"),
    impossible("appearance", "erroneous", "sparkly-rainbow", "change the bench color to sparkly rainbow",
               [paint("bench_1", colour="sparkly rainbow")], notes="a colour is a name or #rrggbb"),
]

ALL_CASES: list[Json] = [*SEARCH, *ADDITION, *REMOVAL, *POSITIONING, *MOVING, *ARRANGEMENT, *APPEARANCE]


def write(path: Path = SUITE_PATH) -> int:
    """Write every case as one JSON line; returns how many were written."""
    ids = [c["id"] for c in ALL_CASES]
    repeated = sorted({i for i in ids if ids.count(i) > 1})
    if repeated:
        raise ValueError(f"repeated case ids: {', '.join(repeated)}")
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", encoding="utf-8") as out:
        for c in ALL_CASES:
            out.write(json.dumps(c, ensure_ascii=False) + "\n")
    return len(ALL_CASES)


if __name__ == "__main__":
    print(f"wrote {write()} cases to {SUITE_PATH}")
