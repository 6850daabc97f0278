"""The held-out suite: prompts the planners are measured on and never developed against.

Written by a helper who had not read the planners, their lexicons, their prompt examples or
the development suite; only the campus world, the catalog, the Worker tools and the eval
checks. A plain list of cases; run `python -m drivetwin.evals.heldout_source` to write
`suites/heldout.jsonl`. Frozen: do not edit a case to suit a planner.

World facts the cases rely on (campus): the ego at (-60, -1.75) drives east in
main_eastbound at 5 m/s; Main Street lanes at y = -1.75 (east) and 1.75 (west), Campus Drive
at x = 1.75 (north) and -1.75 (south); sidewalks at |y| = 5.5 and |x| = 5.5; lot A spans
x -100..-70, y 14..44 (empty), lot B x 15..62, y -46..-12 with passenger_car_1 (19, -42),
suv_1 (23, -42), passenger_car_2 (27, -42); bench_1 (-26, -6.9), trash_bin_1 (-33.5, -5.5),
fire_hydrant_1 (16, 5.5), stop_sign_1 (-13.5, -5.5), street lights 1-12 (odd ones north
of Main Street), traffic lights 1-2, trees 1-4; the time is 12:00 and the sky clear.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

Json = dict[str, Any]
OUT = Path(__file__).with_name("suites") / "heldout.jsonl"
CASES: list[Json] = []

VEHICLES = ["passenger_car", "suv", "bus", "truck", "ackermann_robot"]
TRAFFIC = [*VEHICLES, "bicycle", "motorcycle", "pedestrian"]
OBSTACLES = ["traffic_cone", "road_barrier", "cement_rubble", "construction_sign", "bollard"]
LOTB_CARS = ["passenger_car_1", "passenger_car_2", "suv_1"]
NORTH_LIGHTS = [f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11)]


# Building blocks ---------------------------------------------------------------------------
def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def at(relation: str, target: str | None = None, **more: Any) -> Json:
    place: Json = {"relation": relation}
    if target is not None:
        place["target"] = target
    return {**place, **more}


def xy(x: float, y: float) -> Json:
    return {"relation": "absolute", "x": x, "y": y}


def turn(prompt: str, *calls: Json, planned: bool = False) -> Json:
    return {"prompt": prompt, "calls": list(calls), "planned": planned}


def case(task: str, grade: str, name: str, prompt: str, checks: list[Json], reference: list[Json],
         *, alternatives: list[list[Json]] | None = None, setup: list[Json] | None = None,
         tags: tuple[str, ...] = ()) -> None:
    labels = ["heldout", *tags]
    if setup:
        labels.append("multi_turn")
    line: Json = {
        "id": f"heldout.{task}.{grade}.{name}", "world": "campus", "setup": setup or [],
        "prompt": prompt, "task": task, "grade": grade, "tags": labels, "checks": checks,
        "alternatives": alternatives or [], "reference": reference,
    }
    CASES.append(line)


# Checks --------------------------------------------------------------------------------------
def only(*categories: str, assets: tuple[str, ...] = (), environment: bool = False) -> Json:
    return {"kind": "unchanged_except", "categories": list(categories), "assets": list(assets),
            "environment": environment}


def delta(category: str | list[str], lo: int | None, hi: int | None = None) -> Json:
    return {"kind": "count_delta", "category": category, "min": lo, "max": lo if hi is None else hi}


def count(category: str | list[str], lo: int | None = None, hi: int | None = None) -> Json:
    return {"kind": "count", "category": category, "min": lo, "max": hi}


def pick(what: str | list[str]) -> Json:
    """A selection: an asset id (contains a digit or is 'ego'), else categories (scope touched)."""
    if isinstance(what, str) and (what == "ego" or what[-1].isdigit()):
        return {"asset": what}
    return {"category": what}


def near(what: str | list[str], target: str | tuple[float, float], within: float, **more: Any) -> Json:
    place: Json = {"point": list(target)} if isinstance(target, tuple) else {"target": target}
    return {"kind": "near", **pick(what), **place, "within": within, "require_all": True, **more}


def rel(what: str | list[str], relation: str, target: str, max_distance: float = 15.0, **more: Any) -> Json:
    return {"kind": "relative", **pick(what), "relation": relation, "target": target,
            "max_distance": max_distance, "require_all": True, **more}


def in_lane(what: str | list[str], lane: str | None = None, **more: Any) -> Json:
    return {"kind": "in_lane", **pick(what), "lane": lane, **more}


def on(what: str | list[str], *surfaces: str, **more: Any) -> Json:
    return {"kind": "on_surface", **pick(what), "surfaces": list(surfaces), **more}


def shape(what: str | list[str], form: str, least: int, **more: Any) -> Json:
    return {"kind": "arrangement", **pick(what), "shape": form, "min_count": least, **more}


def does(what: str | list[str], behaviour: str | list[str], **more: Any) -> Json:
    return {"kind": "behaviour", **pick(what), "behaviour": behaviour, "require_all": True, **more}


def env(**settings: Any) -> Json:
    return {"kind": "environment", **settings}


def looks(what: str | list[str], **settings: Any) -> Json:
    return {"kind": "appearance", **pick(what), "require_all": True, **settings}


def moved(asset: str, **settings: Any) -> Json:
    return {"kind": "moved", "asset": asset, **settings}


def gone(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": False}


def kept(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": True}


def says(*any_of: str, all_of: tuple[str, ...] = (), none_of: tuple[str, ...] = ()) -> Json:
    return {"kind": "answer_contains", "any_of": list(any_of), "all_of": list(all_of),
            "none_of": list(none_of)}


def accepted(yes: bool = True) -> Json:
    return {"kind": "status", "accepted": yes}


def question(*checks: Json) -> list[Json]:
    """A question: answered, nothing in the scene changed."""
    return [accepted(), only(), *checks]


def refused() -> list[Json]:
    """The world cannot do it: refused, nothing changed."""
    return [accepted(False), only()]


IMPOSSIBLE = ("impossible",)
COMPOUND = ("compound",)


# Search: questions change nothing; the answer must carry the fact -----------------------------
S = "search"
TWELVE = ("12", "twelve")
FOUR = ("4", "four")
ZERO = ("0", "no", "none", "zero", "not")
RUBBLE_AHEAD = turn("Drop a heap of broken concrete in our lane 30 m ahead of the ego.",
                    call("add_asset", category="cement_rubble", location=at("in_front_of", "ego", distance=30.0)))
NO_HELICOPTER = [[accepted(False)], [accepted(), says(*ZERO)]]

case(S, "direct", "how_many_street_lights", "How many street lights are there on campus?",
     question(says(*TWELVE)), [call("find_assets", category="street_light")])
case(S, "direct", "where_is_hydrant", "Where is the fire hydrant?",
     question(says(all_of=("16", "5.5"))), [call("find_assets", category="fire_hydrant")])
case(S, "direct", "main_street_lanes", "List the lanes of Main Street.",
     question(says(all_of=("main_eastbound", "main_westbound"))), [call("find_lanes", road="Main Street")])
case(S, "direct", "bus_weight", "What does a bus weigh?",
     question(says("12000", "12,000", "12 000", "12 t", "12 tonnes")), [call("asset_properties", category="bus")])
case(S, "direct", "how_many_trees", "How many trees are in the scene?",
     question(says(*FOUR)), [call("find_assets", category="tree")])
case(S, "direct", "ego_lane", "Which lane is the ego vehicle in?",
     question(says("main_eastbound", "eastbound"), ), [call("find_lanes", near="ego")])
case(S, "direct", "where_is_bus_stop", "Where is the bus stop?",
     question(says(all_of=("-30", "-5.5"))), [call("find_landmarks", query="bus stop")])
case(S, "direct", "any_pedestrians", "Are there any pedestrians in the scene?",
     question(says(*ZERO)), [call("find_assets", category="pedestrian")])
case(S, "direct", "traffic_light_count", "How many traffic lights are there?",
     question(says("2", "two")), [call("find_assets", category="traffic_light")])
case(S, "direct", "trees_near_fountain", "Which trees are within 20 m of the fountain?",
     question(says(all_of=("tree_2", "tree_3"), none_of=("tree_1", "tree_4"))),
     [call("find_assets", category="tree", near="fountain", within=20.0)])
case(S, "direct", "robot_weight", "How heavy is the Ackermann robot?",
     question(says("60")), [call("asset_properties", category="ackermann_robot")])
case(S, "direct", "count_after_adding", "How many traffic cones are there now?",
     question(says("6", "six")), [call("find_assets", category="traffic_cone")],
     setup=[turn("Put six cones at the crossroads.",
                 call("add_asset", category="traffic_cone", count=6, location=at("at", "main intersection")),
                 planned=True)])
case(S, "direct", "where_is_swimming_pool", "Where is the swimming pool?",
     refused(), [call("find_landmarks", query="swimming pool")], tags=IMPOSSIBLE)

case(S, "indirect", "lamp_posts", "I'm wondering how many lamp posts line the streets here.",
     question(says(*TWELVE)), [call("find_assets", category="lamp post")])
case(S, "indirect", "where_bench", "Could you tell me where the bench is?",
     question(says(all_of=("-26", "-6.9"))), [call("find_assets", category="bench")])
case(S, "indirect", "our_lane", "I'd like to know what lane our car is driving in.",
     question(says("main_eastbound", "eastbound")), [call("find_lanes", near="ego")])
case(S, "indirect", "suv_weight", "Would you mind telling me how much an SUV weighs?",
     question(says("2100", "2,100", "2 100", "2.1 t")), [call("asset_properties", category="suv")])
case(S, "indirect", "stop_sign_by_crosswalk", "I need to know whether there's a stop sign near the west crosswalk.",
     question(says("stop_sign_1", "1", "yes", "one")),
     [call("find_assets", category="stop_sign", near="west crosswalk", within=10.0)])
case(S, "indirect", "landmark_nearest_ego", "Can you find out which landmark is closest to the test vehicle?",
     question(says(all_of=("library",), none_of=("fountain", "east gate", "Student Union"))),
     [call("find_landmarks", query="Library entrance")])
case(S, "indirect", "where_fountain", "It'd help to know where the fountain is.",
     question(says(all_of=("75", "40"))), [call("find_landmarks", query="fountain")])
case(S, "indirect", "vehicles_in_lot_b", "I'm curious how many vehicles are parked in lot B.",
     question(), [call("find_assets", category="passenger_car", near="parking lot B", within=30.0),
                  call("find_assets", category="suv", near="parking lot B", within=30.0)],
     alternatives=[[says("3", "three")], [says(all_of=tuple(LOTB_CARS))]])
case(S, "indirect", "where_main_gate", "Do you know where the main gate is?",
     question(says(all_of=("-100",))), [call("find_landmarks", query="main gate")])
case(S, "indirect", "campus_drive_lanes", "I wonder which lanes Campus Drive has.",
     question(says(all_of=("campus_northbound", "campus_southbound"))), [call("find_lanes", road="Campus Drive")])
case(S, "indirect", "orange_marker_weight", "I'd love to know how heavy one of those orange road markers is.",
     question(says("3")), [call("asset_properties", category="traffic_cone")])
case(S, "indirect", "helicopters", "Could you tell me how many helicopters are parked on campus?",
     [only()], [call("find_assets", category="helicopter")], alternatives=NO_HELICOPTER, tags=IMPOSSIBLE)

case(S, "vague", "lights", "how many lights are out there",
     question(says("12", "14", "twelve", "fourteen")), [call("find_assets", category="street_light")])
case(S, "vague", "anything_blocking", "anything blocking the road?",
     question(says("rubble", "cement_rubble_1", "debris", "concrete")),
     [call("find_assets", category="cement_rubble")], setup=[RUBBLE_AHEAD])
case(S, "vague", "nearest_parking", "where's the nearest place to park?",
     question(says("lot A", "parking lot A", "west parking lot", none_of=("lot B",))),
     [call("find_landmarks", query="parking lot A")])
case(S, "vague", "around_bus_stop", "what's around the bus stop?",
     question(says("bench", "trash", "bin", "bench_1", "trash_bin_1")),
     [call("find_assets", near="bus stop", within=10.0)])
case(S, "vague", "ego_doing", "the ego, what's it up to?",
     question(says("drive_lane", "driving", "drives", "eastbound")), [call("asset_properties", asset="ego")])
case(S, "vague", "cars_around", "cars around?",
     question(says("2", "3", "two", "three")), [call("find_assets", category="car")])
case(S, "vague", "trees_by_quad", "trees by the quad?",
     question(says("tree_2", "tree_3", "2", "two")), [call("find_assets", category="tree", near="the quad", within=20.0)])
case(S, "vague", "where_buses_stop", "where do the buses stop",
     question(says(all_of=("-30",))), [call("find_landmarks", query="bus stop")])
case(S, "vague", "heaviest", "heaviest thing I could add?",
     question(says("bus")), [call("asset_properties", category="bus")])
case(S, "vague", "ego_facing", "which way is the ego pointing",
     question(says("east", "0 deg", "0")), [call("asset_properties", asset="ego")])
case(S, "vague", "cones_left", "cones still out there?",
     question(says("2", "two")), [call("find_assets", category="traffic_cone")],
     setup=[turn("Put three cones in front of the library entrance.",
                 call("add_asset", category="traffic_cone", count=3, location=at("in_front_of", "Library entrance"))),
            turn("Take away one of those cones.", call("remove_assets", category="traffic_cone", count=1),
                 planned=True)])
case(S, "vague", "stadium", "is the stadium far?",
     refused(), [call("find_landmarks", query="stadium")], tags=IMPOSSIBLE)

case(S, "erroneous", "treees", "how many treees is there",
     question(says(*FOUR)), [call("find_assets", category="tree")])
case(S, "erroneous", "hidrant", "were is the fire hidrant",
     question(says(all_of=("16", "5.5"))), [call("find_assets", category="fire_hydrant")])
case(S, "erroneous", "wich_lane", "wich lane ego car driving",
     question(says("main_eastbound", "eastbound")), [call("find_lanes", near="ego")])
case(S, "erroneous", "buss_weight", "how much weight the buss have",
     question(says("12000", "12,000", "12 000", "12 t", "12 tonnes")), [call("asset_properties", category="bus")])
case(S, "erroneous", "pedestrans", "is there pedestrans on road?",
     question(says(*ZERO)), [call("find_assets", category="pedestrian")])
case(S, "erroneous", "stret_lights", "show me stret lights near of bus stop",
     question(says(all_of=("street_light_4",))),
     [call("find_assets", category="street_light", near="bus stop", within=15.0)])
case(S, "erroneous", "parkng_lot", "where the parkng lot A is",
     question(says(all_of=("-85", "29"))), [call("find_landmarks", query="parking lot A")])
case(S, "erroneous", "crosroad_lights", "how many traffic light at crosroad",
     question(says("2", "two")), [call("find_assets", category="traffic_light")])
case(S, "erroneous", "campus_drive", "lanes of campus drive, list them pls",
     question(says(all_of=("campus_northbound", "campus_southbound"))), [call("find_lanes", road="Campus Drive")])
case(S, "erroneous", "wat_weight_suv", "wat is weight of suv",
     question(says("2100", "2,100", "2 100", "2.1 t")), [call("asset_properties", category="suv")])
case(S, "erroneous", "fountan", "where is fountan",
     question(says(all_of=("75", "40"))), [call("find_landmarks", query="fountain")])
case(S, "erroneous", "helicoptr", "how many helicoptr in scene",
     [only()], [call("find_assets", category="helicopter")], alternatives=NO_HELICOPTER, tags=IMPOSSIBLE)
case(S, "erroneous", "lights_and_trees", "how many street light and how many tree there is",
     question(says(all_of=("12",)), says(*FOUR)),
     [call("find_assets", category="street_light"), call("find_assets", category="tree")], tags=COMPOUND)
case(S, "indirect", "lights_and_benches", "Could you count the street lights and the benches for me?",
     question(says(all_of=("12",)), says("1", "one")),
     [call("find_assets", category="street_light"), call("find_assets", category="bench")], tags=COMPOUND)


# Addition: new assets, counted, placed where asked, nothing else touched ------------------------
A = "addition"


def added(category: str | list[str], n: int | tuple[int, int], *checks: Json, others: tuple[str, ...] = ()) -> list[Json]:
    lo, hi = (n, n) if isinstance(n, int) else n
    cats = [category] if isinstance(category, str) else category
    return [accepted(), delta(category, lo, hi), *checks, only(*cats, *others)]


case(A, "direct", "bus_at_bus_stop", "Add a bus at the bus stop.",
     added("bus", 1, near("bus", "bus stop", 10.0)), [call("add_asset", category="bus", location=at("at", "bus stop"))])
case(A, "direct", "two_people_north_crosswalk", "Add two pedestrians at the north crosswalk.",
     added("pedestrian", 2, near("pedestrian", "north crosswalk", 8.0)),
     [call("add_asset", category="pedestrian", count=2, location=at("at", "north crosswalk"))])
case(A, "direct", "twelve_cones_intersection", "Add twelve traffic cones in the intersection.",
     added("traffic_cone", 12, near("traffic_cone", "main intersection", 1.0)),
     [call("add_asset", category="traffic_cone", count=12, location=at("at", "main intersection"))])
case(A, "direct", "truck_8m_ahead", "Add a truck 8 m in front of the ego vehicle.",
     added("truck", 1, rel("truck", "in_front_of", "ego", 16.0, tolerance_deg=30.0)),
     [call("add_asset", category="truck", location=at("in_front_of", "ego", distance=8.0))])
case(A, "direct", "car_driving_westbound", "Add a car driving in the westbound lane of Main Street.",
     added("passenger_car", 1, does("passenger_car", "drive_lane", lane="main_westbound"),
           in_lane("passenger_car", "main_westbound")),
     [call("add_asset", category="passenger_car", location=at("in_lane", "main_westbound"),
           behaviour={"kind": "drive_lane", "lane": "main_westbound"})])
case(A, "direct", "tree_at_library", "Plant a tree near the library entrance.",
     added("tree", 1, near("tree", "Library entrance", 10.0)),
     [call("add_asset", category="tree", location=at("at", "Library entrance"))])
case(A, "direct", "bicycle_next_to_bench", "Add a bicycle next to the bench.",
     added("bicycle", 1, near("bicycle", "bench_1", 3.0)),
     [call("add_asset", category="bicycle", location=at("next_to", "bench_1"))])
case(A, "direct", "cone_10ft_behind_ego", "Put a traffic cone 10 ft behind the ego.",
     added("traffic_cone", 1, rel("traffic_cone", "behind", "ego", 8.0, tolerance_deg=30.0)),
     [call("add_asset", category="traffic_cone", location=at("behind", "ego", distance=3.05))])
case(A, "direct", "robot_in_lot_b", "Add an Ackermann robot in parking lot B.",
     added("ackermann_robot", 1, near("ackermann_robot", "parking lot B", 1.0)),
     [call("add_asset", category="ackermann_robot", location=at("at", "parking lot B"))])
case(A, "direct", "hydrant_at_xy", "Add a fire hydrant at x=30, y=-5.5.",
     added("fire_hydrant", 1, near("fire_hydrant", (30.0, -5.5), 1.0)),
     [call("add_asset", category="fire_hydrant", location=xy(30.0, -5.5))])
case(A, "direct", "car_1e2_m_ahead", "Add a parked car 1e2 m in front of the ego.",
     added("passenger_car", 1, near("passenger_car", (40.0, -1.75), 6.0)),
     [call("add_asset", category="passenger_car", location=at("in_front_of", "ego", distance=100.0))])
case(A, "direct", "ten_thousand_cones", "Add 10,000 traffic cones.",
     refused(), [call("add_asset", category="traffic_cone", count=10000)], tags=IMPOSSIBLE)
case(A, "direct", "bus_painted_yellow", "Add a bus at the bus stop and paint it yellow.",
     added("bus", 1, near("bus", "bus stop", 10.0), looks("bus", colour="yellow")),
     [call("add_asset", category="bus", location=at("at", "bus stop"), colour="yellow")], tags=COMPOUND)

case(A, "indirect", "motorbike_by_union", "I'd like a motorbike parked near the Student Union.",
     added("motorcycle", 1, near("motorcycle", "Student Union entrance", 12.0)),
     [call("add_asset", category="motorcycle", location=at("at", "Student Union entrance"))])
case(A, "indirect", "benches_by_fountain", "It would be nice to have a couple of benches by the fountain.",
     added("bench", 2, near("bench", "fountain", 8.0)),
     [call("add_asset", category="bench", count=2, location=at("at", "fountain"))])
case(A, "indirect", "person_by_hydrant", "Could you add a person standing next to the fire hydrant?",
     added("pedestrian", 1, near("pedestrian", "fire_hydrant_1", 3.0)),
     [call("add_asset", category="pedestrian", location=at("next_to", "fire_hydrant_1"))])
case(A, "indirect", "delivery_truck_lot_a", "I want a delivery truck parked in lot A.",
     added("truck", 1, near("truck", "parking lot A", 1.0)),
     [call("add_asset", category="truck", location=at("at", "parking lot A"))])
case(A, "indirect", "rubble_30m_ahead", "Would you drop a pile of rubble in our lane about 30 m ahead of the ego?",
     added("cement_rubble", 1, near("cement_rubble", (-30.0, -1.75), 6.0), in_lane("cement_rubble", "main_eastbound")),
     [call("add_asset", category="cement_rubble", location=at("in_front_of", "ego", distance=30.0))])
case(A, "indirect", "lamps_by_jtekt", "Can you put 3 street lamps along the sidewalk near the JTEKT entrance?",
     added("street_light", 3, on("street_light", "sidewalk"), near("street_light", "JTEKT building entrance", 15.0)),
     [call("add_asset", category="street_light", count=3, location=at("on_sidewalk", "JTEKT building entrance"))])
case(A, "indirect", "stop_sign_east_corner", "I'd appreciate a stop sign on the south-east corner, at x=13.5, y=-5.5.",
     added("stop_sign", 1, near("stop_sign", (13.5, -5.5), 1.0), on("stop_sign", "sidewalk")),
     [call("add_asset", category="stop_sign", location=xy(13.5, -5.5))])
case(A, "indirect", "bus_northbound", "Would it be possible to add a big vehicle that carries lots of passengers, driving north on Campus Drive?",
     added("bus", 1, does("bus", "drive_lane", lane="campus_northbound")),
     [call("add_asset", category="bus", location=at("in_lane", "campus_northbound"),
           behaviour={"kind": "drive_lane", "lane": "campus_northbound"})])
case(A, "indirect", "cyclist_west_crosswalk", "I need someone on a bike waiting at the west crosswalk.",
     added("bicycle", 1, near("bicycle", "west crosswalk", 6.0)),
     [call("add_asset", category="bicycle", location=at("at", "west crosswalk"))])
case(A, "indirect", "bin_beside_bench", "Could you put a garbage can beside the bench at the bus stop?",
     added("trash_bin", 1, near("trash_bin", "bench_1", 3.0)),
     [call("add_asset", category="trash_bin", location=at("next_to", "bench_1"))])
case(A, "indirect", "jaywalker_test", "I'd like to test how the ego reacts to someone jaywalking in front of it.",
     added("pedestrian", 1, does("pedestrian", "jaywalk", crosses_lane="main_eastbound")),
     [call("add_asset", category="pedestrian", behaviour={"kind": "jaywalk"})])
case(A, "indirect", "car_inside_library", "Could you park a car inside the Library, at x=-41, y=-30?",
     refused(), [call("add_asset", category="passenger_car", location=xy(-41.0, -30.0))], tags=IMPOSSIBLE)

case(A, "vague", "busier_street", "make the street busier",
     [accepted(), delta(TRAFFIC, 1, 20), only(*TRAFFIC)],
     [call("add_asset", category="passenger_car", location=at("in_lane", "main_westbound"),
           behaviour={"kind": "drive_lane", "lane": "main_westbound"}),
      call("add_asset", category="pedestrian", count=3, location=at("on_sidewalk", "bus stop"))])
case(A, "vague", "empty_lot_cars", "the empty parking lot could use some cars",
     [accepted(), delta(VEHICLES, 1, 30), near(VEHICLES, "parking lot A", 1.0), only(*VEHICLES)],
     [call("add_asset", category="passenger_car", count=3, location=at("at", "parking lot A"))])
case(A, "vague", "more_trees", "more trees please",
     [accepted(), delta("tree", 1, 10), only("tree")], [call("add_asset", category="tree", count=3, location=at("at", "fountain"))])
case(A, "vague", "few_cones_bus_stop", "a few cones by the bus stop",
     added("traffic_cone", (2, 6), near("traffic_cone", "bus stop", 8.0)),
     [call("add_asset", category="traffic_cone", count=3, location=at("at", "bus stop"))])
case(A, "vague", "foot_traffic_library", "some foot traffic near the library",
     added("pedestrian", (2, 10), near("pedestrian", "Library entrance", 12.0)),
     [call("add_asset", category="pedestrian", count=3, location=at("at", "Library entrance"))])
case(A, "vague", "something_to_brake_for", "I want something in our lane that the ego has to brake for",
     [accepted(), delta([*OBSTACLES, *TRAFFIC], 1, 10), in_lane([*OBSTACLES, *TRAFFIC], "main_eastbound", scope="added"),
      rel([*OBSTACLES, *TRAFFIC], "in_front_of", "ego", 60.0, tolerance_deg=20.0, scope="added"), only(*OBSTACLES, *TRAFFIC)],
     [call("add_asset", category="cement_rubble", location=at("in_front_of", "ego", distance=20.0))])
case(A, "vague", "greenery_fountain", "a bit more greenery around the fountain",
     added("tree", (1, 10), near("tree", "fountain", 15.0)), [call("add_asset", category="tree", count=2, location=at("at", "fountain"))])
case(A, "vague", "bikes_at_union", "some bikes at the union",
     added("bicycle", (2, 10), near("bicycle", "Student Union entrance", 12.0)),
     [call("add_asset", category="bicycle", count=3, location=at("at", "student union"))])
case(A, "vague", "oncoming_car", "a car coming the other way",
     added("passenger_car", 1, does("passenger_car", "drive_lane", lane="main_westbound")),
     [call("add_asset", category="passenger_car", location=at("in_lane", "main_westbound"),
           behaviour={"kind": "drive_lane", "lane": "main_westbound"})])
case(A, "vague", "seat_by_fountain", "somewhere to sit near the fountain",
     added("bench", (1, 3), near("bench", "fountain", 10.0)), [call("add_asset", category="bench", location=at("at", "fountain"))])
case(A, "vague", "bus_on_road", "a bus on the road",
     added("bus", 1, in_lane("bus")), [call("add_asset", category="bus", location=at("in_lane", "main_westbound"))])
case(A, "vague", "dinosaurs", "a couple of dinosaurs would be fun",
     refused(), [call("add_asset", category="dinosaur", count=2)], tags=IMPOSSIBLE)
case(A, "vague", "people_and_bikes", "people and a few bikes outside the library",
     [accepted(), delta("pedestrian", 1, 10), delta("bicycle", 2, 6), near(["pedestrian", "bicycle"], "Library entrance", 12.0),
      only("pedestrian", "bicycle")],
     [call("add_asset", category="pedestrian", count=2, location=at("at", "Library entrance")),
      call("add_asset", category="bicycle", count=3, location=at("at", "Library entrance"))], tags=COMPOUND)

case(A, "erroneous", "bycicles_bench", "ad 3 bycicles next to the bench",
     added("bicycle", 3, near("bicycle", "bench_1", 6.0)), [call("add_asset", category="bicycle", count=3, location=at("next_to", "bench_1"))])
case(A, "erroneous", "firehydrant_bustop", "put one firehydrant near bustop",
     added("fire_hydrant", 1, near("fire_hydrant", "bus stop", 6.0)),
     [call("add_asset", category="fire_hydrant", location=at("at", "bus stop"))])
case(A, "erroneous", "tree_librery", "add tree at librery",
     added("tree", 1, near("tree", "Library entrance", 10.0)), [call("add_asset", category="tree", location=at("at", "Library entrance"))])
case(A, "erroneous", "buss_in_bus_stop", "pls add a buss in bus stop",
     added("bus", 1, near("bus", "bus stop", 10.0)), [call("add_asset", category="bus", location=at("at", "bus stop"))])
case(A, "erroneous", "pedestrain_crossing", "add a pedestrain who cross the road at the zebra crosing",
     added("pedestrian", 1, does("pedestrian", "cross_road")),
     [call("add_asset", category="pedestrian", location=at("at", "west crosswalk"), behaviour={"kind": "cross_road"})])
case(A, "erroneous", "two_car_lot_a", "i want two car parked at lot A",
     added("passenger_car", 2, near("passenger_car", "parking lot A", 1.0)),
     [call("add_asset", category="passenger_car", count=2, location=at("at", "parking lot A"))])
case(A, "erroneous", "cone_infront_ego", "add cone 5 meter infront of ego",
     added("traffic_cone", 1, rel("traffic_cone", "in_front_of", "ego", 10.0, tolerance_deg=30.0)),
     [call("add_asset", category="traffic_cone", location=at("in_front_of", "ego", distance=5.0))])
case(A, "erroneous", "barier_westbond", "putting a barier on the westbond lane",
     added("road_barrier", 1, in_lane("road_barrier", "main_westbound")),
     [call("add_asset", category="road_barrier", location=at("in_lane", "main_westbound"))])
case(A, "erroneous", "truk_jtekt", "add a truk near JTEKT entrence",
     added("truck", 1, near("truck", "JTEKT building entrance", 12.0)),
     [call("add_asset", category="truck", location=at("at", "JTEKT building entrance"))])
case(A, "erroneous", "robots_two_parking_b", "add robots two in parking B",
     added("ackermann_robot", 2, near("ackermann_robot", "parking lot B", 1.0)),
     [call("add_asset", category="ackermann_robot", count=2, location=at("at", "parking lot B"))])
case(A, "erroneous", "stop_sing", "plese add a stop sing near crosswalk west",
     added("stop_sign", 1, near("stop_sign", "west crosswalk", 8.0)),
     [call("add_asset", category="stop_sign", location=at("at", "west crosswalk"))])
case(A, "erroneous", "cone_x_1e9", "add cone at x=1e9 y=0",
     refused(), [call("add_asset", category="traffic_cone", location=xy(1e9, 0.0))], tags=IMPOSSIBLE)


# Removal: the named assets go, the rest stay ---------------------------------------------------
R = "removal"
CONES_AT_CROSSROADS = turn("Scatter six cones over the crossroads.",
                           call("add_asset", category="traffic_cone", count=6, location=at("at", "main intersection")))
CARS_IN_LOT_A = turn("Park two cars in lot A.",
                     call("add_asset", category="passenger_car", count=2, location=at("at", "parking lot A")))
DRIVER_WESTBOUND = turn("Add a car driving in the westbound lane.",
                        call("add_asset", category="passenger_car", location=at("in_lane", "main_westbound"),
                             behaviour={"kind": "drive_lane", "lane": "main_westbound"}), planned=True)


def removed(category: str | list[str], n: int | tuple[int, int], *checks: Json) -> list[Json]:
    lo, hi = (n, n) if isinstance(n, int) else n
    cats = [category] if isinstance(category, str) else category
    return [accepted(), delta(category, -hi, -lo), *checks, only(*cats)]


case(R, "direct", "all_trees", "Remove all the trees.",
     removed("tree", 4, count("tree", 0, 0)), [call("remove_assets", category="tree")])
case(R, "direct", "the_bench", "Remove the bench.", removed("bench", 1, gone("bench_1")),
     [call("remove_assets", assets=["bench_1"])])
case(R, "direct", "stop_sign", "Delete the stop sign.", removed("stop_sign", 1, gone("stop_sign_1")),
     [call("remove_assets", category="stop_sign")])
case(R, "direct", "light_nearest_bus_stop", "Remove the street light closest to the bus stop.",
     removed("street_light", 1, gone("street_light_4")),
     [call("remove_assets", category="street_light", near="bus stop", count=1)])
case(R, "direct", "tree_nearest_fountain", "Remove the tree nearest the fountain.",
     removed("tree", 1, gone("tree_2")), [call("remove_assets", category="tree", near="fountain", count=1)])
case(R, "direct", "vehicles_lot_b", "Remove every vehicle in parking lot B.",
     removed(["passenger_car", "suv"], 3, gone(*LOTB_CARS)), [call("remove_assets", assets=LOTB_CARS)])
case(R, "direct", "bin_at_bus_stop", "Remove the trash bin at the bus stop.",
     removed("trash_bin", 1, gone("trash_bin_1")), [call("remove_assets", category="trash_bin", near="bus stop", count=1)])
case(R, "direct", "two_trees", "Remove two trees.", removed("tree", 2), [call("remove_assets", category="tree", count=2)])
case(R, "direct", "all_cones", "Remove all the traffic cones.",
     removed("traffic_cone", 6, count("traffic_cone", 0, 0)), [call("remove_assets", category="traffic_cone")],
     setup=[CONES_AT_CROSSROADS])
case(R, "direct", "parked_cars", "Remove the parked cars.",
     [accepted(), gone("passenger_car_1", "passenger_car_2"),
      does("passenger_car", "drive_lane", scope="all", require_all=True, min_count=1), only("passenger_car", "suv")],
     [call("remove_assets", assets=["passenger_car_1", "passenger_car_2"])], setup=[DRIVER_WESTBOUND])
case(R, "direct", "the_ego", "Remove the ego vehicle.", refused(), [call("remove_assets", assets=["ego"])], tags=IMPOSSIBLE)
case(R, "direct", "bench_and_bin", "Remove the bench and the trash bin.",
     [accepted(), gone("bench_1", "trash_bin_1"), only("bench", "trash_bin")],
     [call("remove_assets", assets=["bench_1", "trash_bin_1"])], tags=COMPOUND)

case(R, "indirect", "no_trees_by_fountain", "I no longer want the trees near the fountain.",
     removed("tree", 2, gone("tree_2", "tree_3"), kept("tree_1", "tree_4")),
     [call("remove_assets", assets=["tree_2", "tree_3"])])
case(R, "indirect", "get_rid_of_bench", "Could you get rid of the bench?", removed("bench", 1, gone("bench_1")),
     [call("remove_assets", assets=["bench_1"])])
case(R, "indirect", "hydrant_not_wanted", "I'd prefer not to have the fire hydrant there anymore.",
     removed("fire_hydrant", 1, gone("fire_hydrant_1")), [call("remove_assets", category="fire_hydrant")])
case(R, "indirect", "stop_sign_gone", "It would be nice if the stop sign were gone.",
     removed("stop_sign", 1, gone("stop_sign_1")), [call("remove_assets", category="stop_sign")])
case(R, "indirect", "suv_out", "Can you take the SUV out of the scene?", removed("suv", 1, gone("suv_1")),
     [call("remove_assets", assets=["suv_1"])])
case(R, "indirect", "cones_not_needed", "I don't need the orange road markers any more.",
     removed("traffic_cone", 6, count("traffic_cone", 0, 0)), [call("remove_assets", category="traffic_cone")],
     setup=[CONES_AT_CROSSROADS])
case(R, "indirect", "clear_rubble", "Could you clear the rubble off the road?",
     removed("cement_rubble", 1, count("cement_rubble", 0, 0)), [call("remove_assets", category="cement_rubble")],
     setup=[RUBBLE_AHEAD])
case(R, "indirect", "north_side_lights", "I'd rather the street lights on the north side of Main Street weren't there.",
     removed("street_light", 6, gone(*NORTH_LIGHTS), kept("street_light_2", "street_light_4", "street_light_12")),
     [call("remove_assets", assets=NORTH_LIGHTS)])
case(R, "indirect", "cars_in_lot_a", "Would you mind removing the cars in lot A?",
     removed("passenger_car", 2, gone("passenger_car_3", "passenger_car_4"), kept("passenger_car_1", "passenger_car_2")),
     [call("remove_assets", assets=["passenger_car_3", "passenger_car_4"])], setup=[CARS_IN_LOT_A])
case(R, "indirect", "bin_not_needed", "We don't need the rubbish bin anymore, do we? Take it away.",
     removed("trash_bin", 1, gone("trash_bin_1")), [call("remove_assets", category="trash_bin")])
case(R, "indirect", "fewer_lights", "I'd like fewer street lights; maybe drop a couple.",
     removed("street_light", (1, 4)), [call("remove_assets", category="street_light", count=2)])
case(R, "indirect", "remove_fountain", "Could you remove the fountain?",
     refused(), [call("remove_assets", assets=["fountain"])], tags=IMPOSSIBLE)

case(R, "vague", "too_many_trees", "too many trees", removed("tree", (1, 3)), [call("remove_assets", category="tree", count=2)])
case(R, "vague", "fewer_lights", "fewer lights",
     [accepted(), delta(["street_light", "traffic_light"], -11, -1), only("street_light", "traffic_light")],
     [call("remove_assets", category="street_light", count=3)])
case(R, "vague", "clear_the_road", "clear the road",
     [accepted(), count("traffic_cone", 0, 0), count("cement_rubble", 0, 0), only("traffic_cone", "cement_rubble")],
     [call("remove_assets", category="traffic_cone"), call("remove_assets", category="cement_rubble")],
     setup=[RUBBLE_AHEAD, CONES_AT_CROSSROADS])
case(R, "vague", "lot_b_too_full", "lot B is too full",
     [accepted(), delta(["passenger_car", "suv"], -3, -1), kept("ego"), only("passenger_car", "suv")],
     [call("remove_assets", assets=["passenger_car_2"])])
case(R, "vague", "no_more_cones", "no more cones",
     removed("traffic_cone", 6, count("traffic_cone", 0, 0)), [call("remove_assets", category="traffic_cone")],
     setup=[CONES_AT_CROSSROADS])
case(R, "vague", "declutter_bus_stop", "declutter the bus stop",
     [accepted(), delta(["bench", "trash_bin", "street_light"], -3, -1), only("bench", "trash_bin", "street_light")],
     [call("remove_assets", assets=["trash_bin_1"])])
case(R, "vague", "lose_hydrant", "lose the hydrant", removed("fire_hydrant", 1, gone("fire_hydrant_1")),
     [call("remove_assets", assets=["fire_hydrant_1"])])
case(R, "vague", "empty_lot_b", "empty out lot B", removed(["passenger_car", "suv"], 3, gone(*LOTB_CARS)),
     [call("remove_assets", assets=LOTB_CARS)])
case(R, "vague", "rubble_must_go", "that rubble has to go",
     removed("cement_rubble", 1, count("cement_rubble", 0, 0)), [call("remove_assets", category="cement_rubble")],
     setup=[RUBBLE_AHEAD])
case(R, "vague", "car_i_just_added", "never mind that car I just added",
     [accepted(), delta("passenger_car", -1, -1), kept("passenger_car_1", "passenger_car_2"), only("passenger_car")],
     [call("remove_assets", category="passenger_car", near="bus stop", count=1)],
     setup=[turn("Park a car at the bus stop.", call("add_asset", category="passenger_car", location=at("at", "bus stop")),
                 planned=True)])
case(R, "vague", "suv_can_go", "the SUV can go", removed("suv", 1, gone("suv_1")), [call("remove_assets", category="suv")])
case(R, "vague", "get_rid_of_library", "get rid of the library",
     refused(), [call("remove_assets", assets=["library"])], tags=IMPOSSIBLE)

case(R, "erroneous", "tress", "remove tress", removed("tree", 4, count("tree", 0, 0)), [call("remove_assets", category="tree")])
case(R, "erroneous", "delet_bench", "delet the bench pls", removed("bench", 1, gone("bench_1")),
     [call("remove_assets", assets=["bench_1"])])
case(R, "erroneous", "stopsign", "remove the stopsign", removed("stop_sign", 1, gone("stop_sign_1")),
     [call("remove_assets", category="stop_sign")])
case(R, "erroneous", "hydrent", "take away hydrent", removed("fire_hydrant", 1, gone("fire_hydrant_1")),
     [call("remove_assets", category="fire_hydrant")])
case(R, "erroneous", "all_car_parking_b", "remove all car from parking B",
     [accepted(), gone("passenger_car_1", "passenger_car_2"), only("passenger_car", "suv")],
     [call("remove_assets", category="passenger_car")])
case(R, "erroneous", "cone_what_i_add", "remove the cone what I add",
     removed("traffic_cone", 1, count("traffic_cone", 0, 0)), [call("remove_assets", category="traffic_cone")],
     setup=[turn("add one cone on the north crosswalk",
                 call("add_asset", category="traffic_cone", location=at("at", "north crosswalk")), planned=True)])
case(R, "erroneous", "two_tree", "remove two tree please", removed("tree", 2), [call("remove_assets", category="tree", count=2)])
case(R, "erroneous", "light_near_of_bus_stop", "remove street light near of bus stop",
     removed("street_light", 1, gone("street_light_4")),
     [call("remove_assets", category="street_light", near="bus stop", count=1)])
case(R, "erroneous", "remov_bin", "remov trash bin", removed("trash_bin", 1, gone("trash_bin_1")),
     [call("remove_assets", category="trash_bin")])
case(R, "erroneous", "suv_who_parked", "delete the suv who is parked", removed("suv", 1, gone("suv_1")),
     [call("remove_assets", assets=["suv_1"])])
case(R, "erroneous", "rubbles", "no want the rubbles anymore",
     removed("cement_rubble", 1, count("cement_rubble", 0, 0)), [call("remove_assets", category="cement_rubble")],
     setup=[RUBBLE_AHEAD])
case(R, "erroneous", "egoo", "remove the egoo car", refused(), [call("remove_assets", assets=["ego"])], tags=IMPOSSIBLE)
case(R, "erroneous", "trees_and_cones", "remove the tree near fountain and also all cone",
     [accepted(), gone("tree_2"), count("traffic_cone", 0, 0), delta("tree", -1, -1), only("tree", "traffic_cone")],
     [call("remove_assets", category="tree", near="fountain", count=1), call("remove_assets", category="traffic_cone")],
     setup=[CONES_AT_CROSSROADS], tags=COMPOUND)


def write(path: Path = OUT) -> int:
    """Write the cases as JSON Lines; returns how many."""
    lines = [json.dumps(c, separators=(",", ":")) for c in CASES]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return len(lines)


if __name__ == "__main__":
    print(f"wrote {write()} cases to {OUT}")
