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
                     call("add_asset", category="passenger_car", count=2, location=at("at", "parking lot A")),
                     planned=True)
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


# Positioning: an existing asset put somewhere else; only it changes ------------------------------
P = "positioning"
BUS_AT_STOP = turn("Add a bus at the bus stop.", call("add_asset", category="bus", location=at("at", "bus stop")),
                   planned=True)
ROBOT_AT_STOP = turn("Add a small robot rover at the bus stop.",
                     call("add_asset", category="ackermann_robot", location=at("at", "bus stop")), planned=True)


def put(asset: str, *checks: Json, others: tuple[str, ...] = ()) -> list[Json]:
    return [accepted(), *checks, only(assets=(asset, *others))]


def put_one_of(categories: list[str], *checks: Json) -> list[Json]:
    """One asset of these categories repositioned; nothing added or removed."""
    return [accepted(), delta(categories, 0, 0), *checks, only(*categories)]


case(P, "direct", "bench_to_fountain", "Put the bench next to the fountain.",
     put("bench_1", near("bench_1", "fountain", 6.0)), [call("place_asset", asset="bench_1", location=at("at", "fountain"))])
case(P, "direct", "suv_to_lot_a", "Place the SUV in parking lot A.",
     put("suv_1", near("suv_1", "parking lot A", 1.0)), [call("place_asset", asset="suv_1", location=at("at", "parking lot A"))])
case(P, "direct", "ego_westbound", "Put the ego vehicle in the westbound lane.",
     put("ego", in_lane("ego", "main_westbound")), [call("place_asset", asset="ego", location=at("in_lane", "main_westbound"))])
case(P, "direct", "hydrant_sidewalk_library", "Move the fire hydrant to the sidewalk by the library.",
     put("fire_hydrant_1", on("fire_hydrant_1", "sidewalk"), near("fire_hydrant_1", "Library entrance", 12.0)),
     [call("place_asset", asset="fire_hydrant_1", location=at("on_sidewalk", "Library entrance"))])
case(P, "direct", "bin_north_crosswalk", "Put the trash bin at the north crosswalk.",
     put("trash_bin_1", near("trash_bin_1", "north crosswalk", 6.0)),
     [call("place_asset", asset="trash_bin_1", location=at("at", "north crosswalk"))])
case(P, "direct", "ego_main_gate", "Position the ego at the main gate.",
     put("ego", near("ego", "main gate", 10.0)), [call("place_asset", asset="ego", location=at("at", "main gate"))])
case(P, "direct", "parked_car_behind_ego", "Put one of the parked cars right behind the ego.",
     put_one_of(["passenger_car", "suv"], rel(["passenger_car", "suv"], "behind", "ego", 12.0, tolerance_deg=30.0)),
     [call("place_asset", asset="passenger_car_1", location=at("behind", "ego"))])
case(P, "direct", "bench_5m_library", "Place the bench 5 m in front of the library entrance.",
     put("bench_1", near("bench_1", (-41.0, -10.0), 2.5), rel("bench_1", "in_front_of", "Library entrance", 8.0)),
     [call("place_asset", asset="bench_1", location=at("in_front_of", "Library entrance", distance=5.0))])
case(P, "direct", "stop_sign_xy", "Put the stop sign at x=-13.5, y=5.5.",
     put("stop_sign_1", near("stop_sign_1", (-13.5, 5.5), 0.5)), [call("place_asset", asset="stop_sign_1", location=xy(-13.5, 5.5))])
case(P, "direct", "suv_jtekt", "Move the SUV to the JTEKT building entrance.",
     put("suv_1", near("suv_1", "JTEKT building entrance", 8.0)),
     [call("place_asset", asset="suv_1", location=at("at", "JTEKT building entrance"))])
case(P, "direct", "bench_in_jtekt", "Put the bench inside the JTEKT Building, at x=37, y=29.",
     refused(), [call("place_asset", asset="bench_1", location=xy(37.0, 29.0))], tags=IMPOSSIBLE)
case(P, "direct", "suv_x500", "Put the SUV at x=500, y=0.",
     refused(), [call("place_asset", asset="suv_1", location=xy(500.0, 0.0))], tags=IMPOSSIBLE)

case(P, "indirect", "bench_to_quad", "Could you move the bench over to the quad?",
     put("bench_1", near("bench_1", "fountain", 6.0)), [call("place_asset", asset="bench_1", location=at("at", "the quad"))])
case(P, "indirect", "ego_east_gate", "I'd like the ego to start at the east gate.",
     put("ego", near("ego", "east gate", 10.0)), [call("place_asset", asset="ego", location=at("at", "east gate"))])
case(P, "indirect", "car_to_west_lot", "Would you park one of the sedans over in the west parking lot?",
     put_one_of(["passenger_car"], near("passenger_car", "parking lot A", 1.0)),
     [call("place_asset", asset="passenger_car_1", location=at("at", "west parking lot"))])
case(P, "indirect", "bin_engineering", "It'd be better if the trash bin stood next to the Engineering Hall entrance.",
     put("trash_bin_1", near("trash_bin_1", "Engineering Hall entrance", 6.0)),
     [call("place_asset", asset="trash_bin_1", location=at("at", "Engineering Hall entrance"))])
case(P, "indirect", "ego_northbound", "Can you put our car in the northbound lane of Campus Drive?",
     put("ego", in_lane("ego", "campus_northbound")), [call("place_asset", asset="ego", location=at("in_lane", "campus_northbound"))])
case(P, "indirect", "hydrant_bus_stop", "I'd prefer the fire hydrant to be near the bus stop.",
     put("fire_hydrant_1", near("fire_hydrant_1", "bus stop", 6.0)),
     [call("place_asset", asset="fire_hydrant_1", location=at("at", "bus stop"))])
case(P, "indirect", "ego_behind_bus", "Could you put the ego right behind the bus?",
     put("ego", rel("ego", "behind", "bus_1", 20.0, tolerance_deg=30.0)),
     [call("place_asset", asset="ego", location=at("behind", "bus_1"))], setup=[BUS_AT_STOP])
case(P, "indirect", "stop_sign_east_gate", "I'd like the stop sign moved to the sidewalk near the east gate.",
     put("stop_sign_1", on("stop_sign_1", "sidewalk"), near("stop_sign_1", "east gate", 8.0)),
     [call("place_asset", asset="stop_sign_1", location=at("on_sidewalk", "east gate"))])
case(P, "indirect", "robot_to_lot_a", "Would you put the robot I just added in lot A?",
     [accepted(), delta("ackermann_robot", 0, 0), near("ackermann_robot", "parking lot A", 1.0, scope="all"), only("ackermann_robot")],
     [call("place_asset", asset="ackermann_robot_1", location=at("at", "parking lot A"))],
     setup=[turn("Add a little research robot at the bus stop.",
                 call("add_asset", category="ackermann_robot", location=at("at", "bus stop")), planned=True)])
case(P, "indirect", "bin_front_of_union", "Could you put the trash bin right in front of the Student Union entrance?",
     put("trash_bin_1", rel("trash_bin_1", "in_front_of", "Student Union entrance", 8.0)),
     [call("place_asset", asset="trash_bin_1", location=at("in_front_of", "Student Union entrance"))])
case(P, "indirect", "ego_centre", "I'd like the ego placed in the middle of the crossroads.",
     put("ego", near("ego", "main intersection", 1.0)), [call("place_asset", asset="ego", location=at("at", "main intersection"))])
case(P, "indirect", "hydrant_in_library", "Could you put the fire hydrant in the middle of the Library building (x=-41, y=-30)?",
     refused(), [call("place_asset", asset="fire_hydrant_1", location=xy(-41.0, -30.0))], tags=IMPOSSIBLE)

case(P, "vague", "bench_by_water", "the bench would look better by the water",
     put("bench_1", near("bench_1", "fountain", 8.0)), [call("place_asset", asset="bench_1", location=at("at", "fountain"))])
case(P, "vague", "suv_other_lot", "SUV out of lot B, over to the other lot",
     put("suv_1", near("suv_1", "parking lot A", 1.0)), [call("place_asset", asset="suv_1", location=at("at", "lot A"))])
case(P, "vague", "ego_near_entrance_gate", "ego should start near the entrance gate",
     put("ego", near("ego", "main gate", 12.0)), [call("place_asset", asset="ego", location=at("at", "entrance gate"))])
case(P, "vague", "bin_by_cafeteria", "stick the bin by the cafeteria",
     put("trash_bin_1", near("trash_bin_1", "Student Union entrance", 8.0)),
     [call("place_asset", asset="trash_bin_1", location=at("at", "cafeteria"))])
case(P, "vague", "hydrant_library", "hydrant's in a weird spot, put it by the library",
     put("fire_hydrant_1", near("fire_hydrant_1", "Library entrance", 12.0)),
     [call("place_asset", asset="fire_hydrant_1", location=at("at", "Library entrance"))])
case(P, "vague", "ego_other_lane", "ego over in the other lane",
     put("ego", in_lane("ego", "main_westbound")), [call("place_asset", asset="ego", location=at("in_lane", "main_westbound"))])
case(P, "vague", "car_closer_jtekt", "a car closer to the JTEKT building, not in the lot",
     put_one_of(["passenger_car", "suv"], near(["passenger_car", "suv"], "JTEKT building entrance", 10.0)),
     [call("place_asset", asset="passenger_car_2", location=at("at", "JTEKT building entrance"))])
case(P, "vague", "stop_sign_north_crosswalk", "stop sign somewhere by the north crosswalk",
     put("stop_sign_1", near("stop_sign_1", "north crosswalk", 8.0)),
     [call("place_asset", asset="stop_sign_1", location=at("at", "north crosswalk"))])
case(P, "vague", "tree_to_quad", "the tree by the library blocks the view, put it in the quad",
     put("tree_1", near("tree_1", "fountain", 12.0)), [call("place_asset", asset="tree_1", location=at("at", "fountain"))])
case(P, "vague", "ego_centre", "ego in the centre please",
     put("ego", near("ego", "main intersection", 1.0)), [call("place_asset", asset="ego", location=at("at", "scene centre"))])
case(P, "vague", "suv_engineering", "the SUV, over by the engineering building",
     put("suv_1", near("suv_1", "Engineering Hall entrance", 12.0)),
     [call("place_asset", asset="suv_1", location=at("at", "Engineering Hall entrance"))])
case(P, "vague", "bench_to_moon", "bench? send it to the moon",
     refused(), [call("place_asset", asset="bench_1", location=at("at", "moon"))], tags=IMPOSSIBLE)
case(P, "vague", "suv_and_ego_swap", "SUV to lot A, ego to the east gate",
     [accepted(), near("suv_1", "parking lot A", 1.0), near("ego", "east gate", 10.0), only(assets=("suv_1", "ego"))],
     [call("place_asset", asset="suv_1", location=at("at", "parking lot A")),
      call("place_asset", asset="ego", location=at("at", "east gate"))], tags=COMPOUND)

case(P, "erroneous", "nex_to_fontain", "put the bench nex to fontain",
     put("bench_1", near("bench_1", "fountain", 6.0)), [call("place_asset", asset="bench_1", location=at("at", "fountain"))])
case(P, "erroneous", "suv_parking_a", "place suv in the parking lot A pls",
     put("suv_1", near("suv_1", "parking lot A", 1.0)), [call("place_asset", asset="suv_1", location=at("at", "parking lot A"))])
case(P, "erroneous", "ego_westbond", "ego car put at westbond lane",
     put("ego", in_lane("ego", "main_westbound")), [call("place_asset", asset="ego", location=at("in_lane", "main_westbound"))])
case(P, "erroneous", "hydrant_side_walk", "move hydrant to side walk near librar",
     put("fire_hydrant_1", on("fire_hydrant_1", "sidewalk"), near("fire_hydrant_1", "Library entrance", 12.0)),
     [call("place_asset", asset="fire_hydrant_1", location=at("on_sidewalk", "Library entrance"))])
case(P, "erroneous", "trashbin_crosswalk", "put trashbin on north crosswalk",
     put("trash_bin_1", near("trash_bin_1", "north crosswalk", 6.0)),
     [call("place_asset", asset="trash_bin_1", location=at("at", "north crosswalk"))])
case(P, "erroneous", "ego_in_main_gate", "position the ego in main gate",
     put("ego", near("ego", "main gate", 10.0)), [call("place_asset", asset="ego", location=at("at", "main gate"))])
case(P, "erroneous", "car_behind_of_ego", "put a car behind of ego",
     [accepted(), delta(["passenger_car", "suv"], 0, 1), only("passenger_car", "suv"),
      rel(["passenger_car", "suv"], "behind", "ego", 12.0, tolerance_deg=30.0)],
     [call("place_asset", asset="passenger_car_2", location=at("behind", "ego"))])
case(P, "erroneous", "stop_sign_x_y", "place stop sign at x -13.5 y 5.5",
     put("stop_sign_1", near("stop_sign_1", (-13.5, 5.5), 0.5)), [call("place_asset", asset="stop_sign_1", location=xy(-13.5, 5.5))])
case(P, "erroneous", "ego_centre_intersection", "put ego on centre of intersection",
     put("ego", near("ego", "main intersection", 1.0)), [call("place_asset", asset="ego", location=at("at", "main intersection"))])
case(P, "erroneous", "bin_cafeterea", "move the bin to cafeterea",
     put("trash_bin_1", near("trash_bin_1", "Student Union entrance", 8.0)),
     [call("place_asset", asset="trash_bin_1", location=at("at", "cafeteria"))])
case(P, "erroneous", "robot_lot_a", "put robot at lot A",
     put("ackermann_robot_1", near("ackermann_robot_1", "parking lot A", 1.0)),
     [call("place_asset", asset="ackermann_robot_1", location=at("at", "parking lot A"))], setup=[ROBOT_AT_STOP])
case(P, "erroneous", "bench_inside_jtekt", "place bench in inside jtekt building at x=37 y=29",
     refused(), [call("place_asset", asset="bench_1", location=xy(37.0, 29.0))], tags=IMPOSSIBLE)

# Moving: shift, turn or set in motion an existing asset -----------------------------------------
M = "moving"
PERSON_AT_STOP = turn("Add a pedestrian at the bus stop.", call("add_asset", category="pedestrian", location=at("at", "bus stop")),
                      planned=True)


def shifted(asset: str, *checks: Json) -> list[Json]:
    return [accepted(), *checks, only(assets=(asset,))]


def spun(asset: str, lo: float, hi: float) -> list[Json]:
    return shifted(asset, moved(asset, max_distance=0.5, turn_min_deg=lo, turn_max_deg=hi))


def ego_speed(lo: float | None, hi: float | None) -> list[Json]:
    return shifted("ego", does("ego", "drive_lane", speed_min=lo, speed_max=hi))


case(M, "direct", "ego_forward_10", "Move the ego forward 10 m.",
     shifted("ego", moved("ego", min_distance=8.0, max_distance=12.0, direction="forward")),
     [call("move_asset", asset="ego", forward=10.0)])
case(M, "direct", "suv_left_2", "Shift the SUV 2 m to its left.",
     shifted("suv_1", moved("suv_1", min_distance=1.5, max_distance=2.5, direction="left")),
     [call("move_asset", asset="suv_1", left=2.0)])
case(M, "direct", "turn_bench_around", "Turn the bench around.", spun("bench_1", 170.0, 180.0),
     [call("move_asset", asset="bench_1", turn_deg=180.0)])
case(M, "direct", "back_ego_5", "Back the ego up 5 metres.",
     shifted("ego", moved("ego", min_distance=4.0, max_distance=6.0, direction="backward")),
     [call("move_asset", asset="ego", forward=-5.0)])
case(M, "direct", "rotate_ego_90", "Rotate the ego 90 degrees to the left.", spun("ego", 80.0, 100.0),
     [call("move_asset", asset="ego", turn_deg=90.0)])
case(M, "direct", "ego_10_mps", "Make the ego drive at 10 m/s.", ego_speed(9.5, 10.5),
     [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 10.0})])
case(M, "direct", "suv_circles_lot_b", "Make the SUV drive in circles in parking lot B.",
     shifted("suv_1", does("suv_1", "circle", centre_near="parking lot B", centre_within=20.0)),
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "centre": "parking lot B"})])
case(M, "direct", "bin_3m_east", "Move the trash bin 3 m east.",
     shifted("trash_bin_1", moved("trash_bin_1", min_distance=2.5, max_distance=3.5, direction="forward")),
     [call("move_asset", asset="trash_bin_1", forward=3.0)])
case(M, "direct", "ego_drive_westbound", "Make the ego drive in the westbound lane.",
     shifted("ego", does("ego", "drive_lane", lane="main_westbound")),
     [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_westbound"})])
case(M, "direct", "ego_face_north", "Turn the ego to face north.", spun("ego", 80.0, 100.0),
     [call("move_asset", asset="ego", turn_deg=90.0)])
case(M, "direct", "ego_forward_500", "Move the ego forward 500 m.",
     refused(), [call("move_asset", asset="ego", forward=500.0)], tags=IMPOSSIBLE)
case(M, "direct", "bench_drives", "Make the bench drive around the parking lot.",
     refused(), [call("set_behaviour", asset="bench_1", behaviour={"kind": "circle", "centre": "parking lot A"})],
     tags=IMPOSSIBLE)
case(M, "direct", "ego_forward_and_faster", "Move the ego forward 10 m and make it drive at 8 m/s.",
     shifted("ego", moved("ego", min_distance=8.0, max_distance=12.0, direction="forward"),
             does("ego", "drive_lane", speed_min=7.5, speed_max=8.5)),
     [call("move_asset", asset="ego", forward=10.0),
      call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 8.0})],
     tags=COMPOUND)

case(M, "indirect", "nudge_ego_3", "Could you nudge the ego forward by about 3 metres?",
     shifted("ego", moved("ego", min_distance=2.0, max_distance=4.0, direction="forward")),
     [call("move_asset", asset="ego", forward=3.0)])
case(M, "indirect", "suv_north_campus_drive", "I'd like the SUV to drive up Campus Drive heading north.",
     shifted("suv_1", does("suv_1", "drive_lane", lane="campus_northbound")),
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "campus_northbound"})])
case(M, "indirect", "bench_other_way", "Would you turn the bench so it faces the other way?", spun("bench_1", 170.0, 180.0),
     [call("move_asset", asset="bench_1", turn_deg=180.0)])
case(M, "indirect", "slow_ego_3", "Can you slow the ego down to 3 m/s?", ego_speed(2.5, 3.5),
     [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 3.0})])
case(M, "indirect", "ego_20_back", "I'd like the ego to start 20 m further back.",
     shifted("ego", moved("ego", min_distance=18.0, max_distance=22.0, direction="backward")),
     [call("move_asset", asset="ego", forward=-20.0)])
case(M, "indirect", "donuts_lot_a", "I want to see how the ego copes with a car doing doughnuts in lot A.",
     [accepted(), does(["passenger_car", "suv"], "circle", centre_near="parking lot A", centre_within=20.0),
      delta(["passenger_car", "suv"], 0, 1), only("passenger_car", "suv")],
     [call("set_behaviour", asset="passenger_car_1", behaviour={"kind": "circle", "centre": "parking lot A"})])
case(M, "indirect", "ego_point_west", "Could you spin the ego around so it points west?", spun("ego", 170.0, 180.0),
     [call("move_asset", asset="ego", turn_deg=180.0)])
case(M, "indirect", "ego_twice_as_fast", "I'd like the ego going twice as fast as it is now.", ego_speed(9.0, 11.0),
     [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 10.0})])
case(M, "indirect", "ego_half_lane_left", "Would you shift the ego half a lane to the left?",
     shifted("ego", moved("ego", min_distance=1.2, max_distance=2.3, direction="left")),
     [call("move_asset", asset="ego", left=1.75)])
case(M, "indirect", "hydrant_2m_east", "Could the fire hydrant sit 2 m further east?",
     shifted("fire_hydrant_1", moved("fire_hydrant_1", min_distance=1.5, max_distance=2.5, direction="forward")),
     [call("move_asset", asset="fire_hydrant_1", forward=2.0)])
case(M, "indirect", "person_crosses", "I'd like to see that pedestrian cross the road at the west crosswalk.",
     shifted("pedestrian_1", does("pedestrian_1", "cross_road", crosses_lane="main_eastbound")),
     [call("set_behaviour", asset="pedestrian_1", behaviour={"kind": "cross_road"})], setup=[PERSON_AT_STOP])
case(M, "indirect", "tree_walks", "Could you make the tree walk across the road?",
     refused(), [call("set_behaviour", asset="tree_1", behaviour={"kind": "cross_road"})], tags=IMPOSSIBLE)

case(M, "vague", "ego_further_along", "the ego a bit further along",
     shifted("ego", moved("ego", min_distance=1.0, max_distance=30.0, direction="forward")),
     [call("move_asset", asset="ego", forward=5.0)])
case(M, "vague", "ego_faster", "get the ego moving faster", ego_speed(5.5, None),
     [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 8.0})])
case(M, "vague", "car_should_drive", "that sedan should be driving, not parked",
     [accepted(), does("passenger_car", "drive_lane"), delta("passenger_car", 0, 0), only("passenger_car")],
     [call("set_behaviour", asset="passenger_car_1", behaviour={"kind": "drive_lane"})])
case(M, "vague", "bench_wrong_way", "the bench faces the wrong way", spun("bench_1", 90.0, 180.0),
     [call("move_asset", asset="bench_1", turn_deg=180.0)])
case(M, "vague", "ego_other_way", "ego should go the other way",
     [accepted(), only(assets=("ego",))], [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_westbound"})],
     alternatives=[[moved("ego", turn_min_deg=150.0)], [does("ego", "drive_lane", lane="main_westbound")]])
case(M, "vague", "ego_bit_left", "a bit to the left with the ego",
     shifted("ego", moved("ego", min_distance=0.3, max_distance=3.6, direction="left")), [call("move_asset", asset="ego", left=1.0)])
case(M, "vague", "suv_round_and_round", "SUV going round and round", shifted("suv_1", does("suv_1", "circle")),
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "centre": "parking lot B"})])
case(M, "vague", "ego_too_slow", "the ego's too slow", ego_speed(5.5, None),
     [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 8.0})])
case(M, "vague", "bin_little_east", "the trash bin, a little to the east",
     shifted("trash_bin_1", moved("trash_bin_1", min_distance=0.3, max_distance=4.0, direction="forward")),
     [call("move_asset", asset="trash_bin_1", forward=1.5)])
case(M, "vague", "that_person_jaywalks", "now have them jaywalk",
     [accepted(), does("pedestrian", "jaywalk", crosses_lane="main_eastbound"), delta("pedestrian", 0, 0), only("pedestrian")],
     [call("set_behaviour", asset="pedestrian_1", behaviour={"kind": "jaywalk"})],
     setup=[turn("Put a pedestrian on the sidewalk near the bus stop.",
                 call("add_asset", category="pedestrian", location=at("on_sidewalk", "bus stop")), planned=True)])
case(M, "vague", "park_the_ego", "park the ego", shifted("ego", does("ego", "parked")),
     [call("set_behaviour", asset="ego", behaviour={"kind": "parked"})])
case(M, "vague", "stop_sign_chases", "stop sign chasing the ego down the road",
     refused(), [call("set_behaviour", asset="stop_sign_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
     tags=IMPOSSIBLE)

case(M, "erroneous", "forwad_10", "move ego forwad 10 meter",
     shifted("ego", moved("ego", min_distance=8.0, max_distance=12.0, direction="forward")), [call("move_asset", asset="ego", forward=10.0)])
case(M, "erroneous", "turn_around_bench", "turn around the bench", spun("bench_1", 170.0, 180.0),
     [call("move_asset", asset="bench_1", turn_deg=180.0)])
case(M, "erroneous", "ego_go_back", "ego go back 5 metre",
     shifted("ego", moved("ego", min_distance=4.0, max_distance=6.0, direction="backward")), [call("move_asset", asset="ego", forward=-5.0)])
case(M, "erroneous", "ego_10_meter_per_second", "make ego drive 10 meter per second", ego_speed(9.5, 10.5),
     [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 10.0})])
case(M, "erroneous", "suv_move_left", "suv move left 2m",
     shifted("suv_1", moved("suv_1", min_distance=1.5, max_distance=2.5, direction="left")), [call("move_asset", asset="suv_1", left=2.0)])
case(M, "erroneous", "rotate_90_degre", "rotate ego 90 degre left", spun("ego", 80.0, 100.0),
     [call("move_asset", asset="ego", turn_deg=90.0)])
case(M, "erroneous", "suv_driving_circle", "make suv driving in circle in parking b",
     shifted("suv_1", does("suv_1", "circle", centre_near="parking lot B", centre_within=20.0)),
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "centre": "parking lot B"})])
case(M, "erroneous", "westbond", "ego car must drive in westbond lane", shifted("ego", does("ego", "drive_lane", lane="main_westbound")),
     [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_westbound"})])
case(M, "erroneous", "pedestrain_jaywalk", "the pedestrain must to jaywalk",
     shifted("pedestrian_1", does("pedestrian_1", "jaywalk", crosses_lane="main_eastbound")),
     [call("set_behaviour", asset="pedestrian_1", behaviour={"kind": "jaywalk"})], setup=[PERSON_AT_STOP])
case(M, "erroneous", "slow_down_ego", "slow down ego to 3 m/s please", ego_speed(2.5, 3.5),
     [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 3.0})])
case(M, "erroneous", "bin_move_3_east", "trash bin move 3 meter to east",
     shifted("trash_bin_1", moved("trash_bin_1", min_distance=2.5, max_distance=3.5, direction="forward")),
     [call("move_asset", asset="trash_bin_1", forward=3.0)])
case(M, "erroneous", "foward_1e4", "move the ego foward 1e4 m", refused(), [call("move_asset", asset="ego", forward=10000.0)],
     tags=IMPOSSIBLE)

# Arrangement: several new assets laid out together ----------------------------------------------
G = "arrangement"
RUBBLE_CROSSROADS = turn("Put a pile of construction debris in the middle of the crossroads.",
                 call("add_asset", category="cement_rubble", location=at("at", "main intersection")))
RUBBLE_PLANNED = turn("There should be some broken concrete lying in the centre of the intersection.",
                      call("add_asset", category="cement_rubble", location=at("at", "main intersection")),
                      planned=True)
BLOCKERS = ["road_barrier", "traffic_cone", "bollard"]


def laid(category: str | list[str], n: int | tuple[int, int], form: str, *checks: Json, **layout: Any) -> list[Json]:
    lo, hi = (n, n) if isinstance(n, int) else n
    cats = [category] if isinstance(category, str) else category
    return [accepted(), delta(category, lo, hi), shape(category, form, lo, **layout), *checks, only(*cats)]


def ring(category: str | list[str], n: int | tuple[int, int], around: str, *checks: Json) -> list[Json]:
    return laid(category, n, "ring", *checks, around=around)


case(G, "direct", "cones_ring_rubble", "Put six cones in a ring around the rubble.",
     ring("traffic_cone", 6, "cement_rubble_1"),
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=6, location=at("at", "cement_rubble_1"))],
     setup=[RUBBLE_CROSSROADS])
case(G, "direct", "cones_lane_edge", "Put a line of 4 cones along the edge of the eastbound lane.",
     laid("traffic_cone", 4, "line", in_lane("traffic_cone", "main_eastbound")),
     [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=4, location=at("in_lane", "main_eastbound"))])
case(G, "direct", "twelve_cones_ring_intersection", "Arrange twelve cones in a circle around the intersection.",
     ring("traffic_cone", 12, "main intersection"),
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=12, location=at("at", "main intersection"))])
case(G, "direct", "trees_row_fountain", "Plant a row of four trees near the fountain.",
     laid("tree", 4, "line", near("tree", "fountain", 10.0)),
     [call("arrange_assets", categories=["tree"], shape="line", count=4, location=at("at", "fountain"))])
case(G, "direct", "cars_grid_lot_a", "Set out a 3 by 3 grid of cars in parking lot A.",
     laid("passenger_car", 9, "cluster", near("passenger_car", "parking lot A", 0.5), tolerance=15.0),
     [call("arrange_assets", categories=["passenger_car"], shape="grid", count=9, columns=3, location=at("at", "parking lot A"))])
case(G, "direct", "bollards_jtekt_sidewalk", "Place eight bollards in a line along the sidewalk near the JTEKT entrance.",
     laid("bollard", 8, "line", on("bollard", "sidewalk"), near("bollard", "JTEKT building entrance", 15.0)),
     [call("arrange_assets", categories=["bollard"], shape="line", count=8,
           location=at("on_sidewalk", "JTEKT building entrance"))])
case(G, "direct", "bollards_around_hydrant", "Surround the fire hydrant with 4 bollards.",
     ring("bollard", 4, "fire_hydrant_1"),
     [call("arrange_assets", categories=["bollard"], shape="ring", count=4, location=at("at", "fire_hydrant_1"))])
case(G, "direct", "barriers_east_gate", "Put three barriers in a line across the road at the east gate.",
     laid("road_barrier", 3, "line", near("road_barrier", "east gate", 6.0), on("road_barrier", "lane")),
     [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, location=at("at", "east gate"))])
case(G, "direct", "ten_cones_westbound_edge", "Arrange 10 traffic cones along the edge of the westbound lane.",
     laid("traffic_cone", 10, "line", in_lane("traffic_cone", "main_westbound")),
     [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=10, location=at("in_lane", "main_westbound"))])
case(G, "direct", "signs_front_library", "Put 5 construction signs in a line in front of the library entrance.",
     laid("construction_sign", 5, "line", near("construction_sign", "Library entrance", 6.0)),
     [call("arrange_assets", categories=["construction_sign"], shape="line", count=5,
           location=at("in_front_of", "Library entrance"))])
case(G, "direct", "five_hundred_cones", "Arrange 500 cones in a circle around the intersection.",
     refused(), [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=500,
                      location=at("at", "main intersection"))], tags=IMPOSSIBLE)
case(G, "direct", "ring_inside_library", "Put a ring of cones around the middle of the Library building, x=-41, y=-30.",
     refused(), [call("arrange_assets", categories=["traffic_cone"], shape="ring", radius=5.0, location=xy(-41.0, -30.0))],
     tags=IMPOSSIBLE)

case(G, "indirect", "ring_round_rubble", "Could you set up a ring of cones around that pile of rubble?",
     ring("traffic_cone", (4, 30), "cement_rubble_1"),
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", location=at("at", "cement_rubble_1"))],
     setup=[RUBBLE_PLANNED])
case(G, "indirect", "close_lane_two_barriers", "I'd like our lane closed with two barriers 20 m ahead of the ego.",
     laid("road_barrier", 2, "line", in_lane("road_barrier", "main_eastbound"),
          rel("road_barrier", "in_front_of", "ego", 30.0, tolerance_deg=20.0)),
     [call("arrange_assets", categories=["road_barrier"], shape="line", count=2,
           location=at("in_front_of", "ego", distance=20.0))])
case(G, "indirect", "protect_hydrant", "Could you put some bollards around the fire hydrant to protect it?",
     ring("bollard", (3, 12), "fire_hydrant_1"),
     [call("arrange_assets", categories=["bollard"], shape="ring", count=4, location=at("at", "fire_hydrant_1"))])
case(G, "indirect", "trees_line_fountain", "It'd be nice to have a line of trees by the fountain.",
     laid("tree", (3, 8), "line", near("tree", "fountain", 12.0)),
     [call("arrange_assets", categories=["tree"], shape="line", count=4, location=at("at", "fountain"))])
case(G, "indirect", "suv_grid_lot_a", "Would you fill lot A with a grid of six parked SUVs?",
     laid("suv", 6, "cluster", near("suv", "parking lot A", 0.5), tolerance=15.0),
     [call("arrange_assets", categories=["suv"], shape="grid", count=6, columns=3, location=at("at", "parking lot A"))])
case(G, "indirect", "cones_northbound_edge", "I'd like cones along the edge of the northbound lane of Campus Drive, say eight of them.",
     laid("traffic_cone", 8, "line", in_lane("traffic_cone", "campus_northbound")),
     [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=8,
           location=at("in_lane", "campus_northbound"))])
case(G, "indirect", "benches_circle_fountain", "Could you put a circle of benches around the fountain?",
     ring("bench", (3, 12), "fountain"),
     [call("arrange_assets", categories=["bench"], shape="ring", location=at("at", "fountain"))])
case(G, "indirect", "queue_at_bus_stop", "Can you line up 4 people waiting along the sidewalk at the bus stop?",
     laid("pedestrian", 4, "line", near("pedestrian", "bus stop", 5.0)),
     [call("arrange_assets", categories=["pedestrian"], shape="line", count=4, location=at("on_sidewalk", "bus stop"))])
case(G, "indirect", "cars_block_student_parking", "I'd like a 2 by 3 block of cars in the student parking.",
     laid("passenger_car", 6, "cluster", near("passenger_car", "parking lot B", 0.5), tolerance=15.0),
     [call("arrange_assets", categories=["passenger_car"], shape="grid", count=6, columns=3, location=at("at", "student parking"))])
case(G, "indirect", "signs_jtekt_sidewalk", "Could you line up some road work signs along the sidewalk near the JTEKT entrance?",
     laid("construction_sign", (3, 12), "line", on("construction_sign", "sidewalk"), near("construction_sign", "JTEKT building entrance", 15.0)),
     [call("arrange_assets", categories=["construction_sign"], shape="line", count=5,
           location=at("on_sidewalk", "JTEKT building entrance"))])
case(G, "indirect", "mark_ego_lane", "I want the ego's lane marked off with cones along its edge.",
     laid("traffic_cone", (3, 40), "line", in_lane("traffic_cone", "main_eastbound")),
     [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", location=at("in_lane", "ego"))])
case(G, "indirect", "line_through_jtekt", "Could you run a line of cones straight through the JTEKT Building, at x=37, y=29?",
     refused(), [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5, location=xy(37.0, 29.0))],
     tags=IMPOSSIBLE)
case(G, "indirect", "ring_and_sign", "Could you ring the rubble with cones and put a road work sign in front of the ego?",
     [accepted(), shape("traffic_cone", "ring", 4, around="cement_rubble_1"), delta("construction_sign", 1, 1),
      rel("construction_sign", "in_front_of", "ego", 40.0), only("traffic_cone", "construction_sign")],
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", location=at("at", "cement_rubble_1")),
      call("add_asset", category="construction_sign", location=at("in_front_of", "ego", distance=10.0))],
     setup=[RUBBLE_CROSSROADS], tags=COMPOUND)

case(G, "vague", "fence_off_rubble", "fence off the rubble",
     [accepted(), delta(BLOCKERS, 4, 40), shape(BLOCKERS, "ring", 4, around="cement_rubble_1"), only(*BLOCKERS)],
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", location=at("at", "cement_rubble_1"))],
     setup=[RUBBLE_PLANNED])
case(G, "vague", "close_road_ahead", "close the road ahead of us",
     [accepted(), delta(BLOCKERS, 2, 20), shape(BLOCKERS, "line", 2),
      rel(BLOCKERS, "in_front_of", "ego", 40.0, tolerance_deg=30.0, scope="added"), only(*BLOCKERS)],
     [call("arrange_assets", categories=["road_barrier"], shape="line", count=2, location=at("in_front_of", "ego", distance=15.0))])
case(G, "vague", "trees_row", "a row of trees near the fountain",
     laid("tree", (3, 8), "line", near("tree", "fountain", 12.0)),
     [call("arrange_assets", categories=["tree"], shape="line", count=3, location=at("at", "fountain"))])
case(G, "vague", "fill_empty_lot", "fill the empty parking lot with cars",
     [accepted(), delta(VEHICLES, 4, 60), near(VEHICLES, "parking lot A", 0.5), only(*VEHICLES)],
     [call("arrange_assets", categories=["passenger_car"], shape="grid", count=9, location=at("at", "parking lot A"))])
case(G, "vague", "mark_lane_edge", "mark the lane edge with cones",
     laid("traffic_cone", (3, 40), "line", in_lane("traffic_cone")),
     [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", location=at("in_lane", "ego"))])
case(G, "vague", "protect_hydrant", "protect the hydrant",
     [accepted(), delta(BLOCKERS, 3, 12), shape(BLOCKERS, "ring", 3, around="fire_hydrant_1"), only(*BLOCKERS)],
     [call("arrange_assets", categories=["bollard"], shape="ring", count=4, location=at("at", "fire_hydrant_1"))])
case(G, "vague", "seating_round_fountain", "some seating around the fountain",
     [accepted(), delta("bench", 2, 12), near("bench", "fountain", 8.0), only("bench")],
     [call("arrange_assets", categories=["bench"], shape="ring", location=at("at", "fountain"))])
case(G, "vague", "queue_bus_stop", "a queue of people at the bus stop",
     laid("pedestrian", (3, 20), "line", near("pedestrian", "bus stop", 8.0)),
     [call("arrange_assets", categories=["pedestrian"], shape="line", count=5, location=at("on_sidewalk", "bus stop"))])
case(G, "vague", "work_zone_library", "a work zone in front of the library",
     [accepted(), delta(["construction_sign", *BLOCKERS], 2, 30), shape(["construction_sign", *BLOCKERS], "line", 2),
      near(["construction_sign", *BLOCKERS], "Library entrance", 10.0), only("construction_sign", *BLOCKERS)],
     [call("arrange_assets", categories=["construction_sign", "traffic_cone"], shape="line", count=6,
           location=at("in_front_of", "Library entrance"))])
case(G, "vague", "cone_off_intersection", "cone off the intersection",
     ring("traffic_cone", (4, 60), "main intersection"),
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=12, location=at("at", "main intersection"))])
case(G, "vague", "robot_fleet", "a fleet of robots lined up in lot B",
     laid("ackermann_robot", (3, 20), "line", near("ackermann_robot", "parking lot B", 0.5)),
     [call("arrange_assets", categories=["ackermann_robot"], shape="line", count=5, location=at("at", "parking lot B"))])
case(G, "vague", "ring_round_moon", "a ring of cones around the moon",
     refused(), [call("arrange_assets", categories=["traffic_cone"], shape="ring", location=at("at", "moon"))], tags=IMPOSSIBLE)

case(G, "erroneous", "cone_circle_rubel", "put 6 cone in circle around the rubel",
     ring("traffic_cone", 6, "cement_rubble_1"),
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=6, location=at("at", "cement_rubble_1"))],
     setup=[RUBBLE_PLANNED])
case(G, "erroneous", "barier_infront_ego", "line 2 barier across lane infront ego 15m",
     laid("road_barrier", 2, "line", in_lane("road_barrier", "main_eastbound"),
          rel("road_barrier", "in_front_of", "ego", 25.0, tolerance_deg=20.0)),
     [call("arrange_assets", categories=["road_barrier"], shape="line", count=2, location=at("in_front_of", "ego", distance=15.0))])
case(G, "erroneous", "twelv_cones", "twelv cones circle around intersecion",
     ring("traffic_cone", 12, "main intersection"),
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=12, location=at("at", "main intersection"))])
case(G, "erroneous", "row_tree_fontain", "row of 4 tree near fontain",
     laid("tree", 4, "line", near("tree", "fountain", 10.0)),
     [call("arrange_assets", categories=["tree"], shape="line", count=4, location=at("at", "fountain"))])
case(G, "erroneous", "grid_car_parking_a", "grid 3x3 car in parking A",
     laid("passenger_car", 9, "cluster", near("passenger_car", "parking lot A", 0.5), tolerance=15.0),
     [call("arrange_assets", categories=["passenger_car"], shape="grid", count=9, columns=3, location=at("at", "parking lot A"))])
case(G, "erroneous", "ring_bollard_hydrant", "ring of bollard around hydrant",
     ring("bollard", (3, 12), "fire_hydrant_1"),
     [call("arrange_assets", categories=["bollard"], shape="ring", count=4, location=at("at", "fire_hydrant_1"))])
case(G, "erroneous", "cones_edge_westbond", "cones 10 along edge westbond lane",
     laid("traffic_cone", 10, "line", in_lane("traffic_cone", "main_westbound")),
     [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=10, location=at("in_lane", "main_westbound"))])
case(G, "erroneous", "construction_sign_line", "5 construction sign in line front of library",
     laid("construction_sign", 5, "line", near("construction_sign", "Library entrance", 6.0)),
     [call("arrange_assets", categories=["construction_sign"], shape="line", count=5,
           location=at("in_front_of", "Library entrance"))])
case(G, "erroneous", "bench_circle", "bench circle around fountain pls",
     ring("bench", (3, 12), "fountain"), [call("arrange_assets", categories=["bench"], shape="ring", location=at("at", "fountain"))])
case(G, "erroneous", "people_line_4", "line of people at bus stop, 4 of them",
     laid("pedestrian", 4, "line", near("pedestrian", "bus stop", 5.0)),
     [call("arrange_assets", categories=["pedestrian"], shape="line", count=4, location=at("on_sidewalk", "bus stop"))])
case(G, "erroneous", "robots_5_line", "robots 5 line in parking B",
     laid("ackermann_robot", 5, "line", near("ackermann_robot", "parking lot B", 0.5)),
     [call("arrange_assets", categories=["ackermann_robot"], shape="line", count=5, location=at("at", "parking lot B"))])
case(G, "erroneous", "arange_500", "arange 500 cone in circle at crossroad",
     refused(), [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=500,
                      location=at("at", "main intersection"))], tags=IMPOSSIBLE)

# Appearance: weather, time, lighting and the looks of assets ------------------------------------
L = "appearance"
RAINING = turn("Make it rain.", call("set_weather", kind="rain", intensity=0.6))


def sky(*checks: Json) -> list[Json]:
    """An environment change only."""
    return [accepted(), *checks, only(environment=True)]


def painted(asset: str, **look: Any) -> list[Json]:
    return [accepted(), looks(asset, **look), only(assets=(asset,))]


DARKER = [[env(exposure_max=0.95)], [env(time_from="18:00", time_to="06:00")]]
WET = ["rain", "snow"]

case(L, "direct", "make_it_rain", "Make it rain.", sky(env(weather=["rain"])), [call("set_weather", kind="rain")])
case(L, "direct", "time_1830", "Set the time to 18:30.", sky(env(time_from="18:25", time_to="18:35")),
     [call("set_time_of_day", time="18:30")])
case(L, "direct", "bench_green", "Paint the bench green.", painted("bench_1", colour="green"),
     [call("set_asset_appearance", assets=["bench_1"], colour="green")])
case(L, "direct", "street_lights_on", "Turn on the street lights.", sky(env(street_lights="on")),
     [call("set_lighting", street_lights="on")])
case(L, "direct", "heavy_fog", "Add heavy fog.", sky(env(weather=["fog"], intensity_min=0.7)),
     [call("set_weather", kind="fog", intensity=0.9)])
case(L, "direct", "parked_cars_blue", "Make all the parked cars blue.",
     [accepted(), looks("passenger_car", colour="blue", scope="all"), only("passenger_car", "suv")],
     [call("set_asset_appearance", category="passenger_car", colour="blue")])
case(L, "direct", "headlights_on", "Switch the vehicle headlights on.", sky(env(vehicle_lights="on")),
     [call("set_lighting", vehicle_lights="on")])
case(L, "direct", "midnight", "Set the time to midnight.", sky(env(time_from="23:45", time_to="00:15")),
     [call("set_time_of_day", time="00:00")])
case(L, "direct", "light_snow", "Make it snow lightly.", sky(env(weather=["snow"], intensity_min=0.05, intensity_max=0.45)),
     [call("set_weather", kind="snow", intensity=0.3)])
case(L, "direct", "ego_hex", "Paint the ego #ff8800.", painted("ego", colour="#ff8800", colour_tolerance=0.05),
     [call("set_asset_appearance", assets=["ego"], colour="#ff8800")])
case(L, "direct", "time_2500", "Set the time to 25:00.", refused(), [call("set_time_of_day", time="25:00")], tags=IMPOSSIBLE)
case(L, "direct", "hail", "Make it hail.", refused(), [call("set_weather", kind="hail")], tags=IMPOSSIBLE)
case(L, "direct", "rain_and_headlights", "Make it rain and turn on the headlights.",
     sky(env(weather=["rain"], vehicle_lights="on")),
     [call("set_weather", kind="rain"), call("set_lighting", vehicle_lights="on")], tags=COMPOUND)

case(L, "indirect", "test_wipers", "I want to test the wipers.", sky(env(weather=WET, intensity_min=0.2)),
     [call("set_weather", kind="rain", intensity=0.6)])
case(L, "indirect", "half_six_evening", "Could you make it half past six in the evening?",
     sky(env(time_from="18:25", time_to="18:35")), [call("set_time_of_day", time="18:30")])
case(L, "indirect", "suv_red", "I'd like the SUV to be red.", painted("suv_1", colour="red"),
     [call("set_asset_appearance", assets=["suv_1"], colour="red")])
case(L, "indirect", "bit_darker", "Would you make the scene a bit darker?", [accepted(), only(environment=True)],
     [call("set_lighting", exposure=0.7)], alternatives=DARKER)
case(L, "indirect", "sky_clears", "It would be nice if the sky cleared up.", sky(env(weather=["clear"])),
     [call("set_weather", kind="clear")], setup=[RAINING])
case(L, "indirect", "night_vision", "I need to test how the ego's cameras do at night.", sky(env(night=True)),
     [call("set_time_of_day", time="22:00")])
case(L, "indirect", "wooden_bench", "Could you give the bench a wooden look?", painted("bench_1", material="wood"),
     [call("set_asset_appearance", assets=["bench_1"], material="wood")])
case(L, "indirect", "thick_fog_cameras", "I'd like to see how the cameras cope with thick fog.",
     sky(env(weather=["fog"], intensity_min=0.7)), [call("set_weather", kind="fog", intensity=0.9)])
case(L, "indirect", "street_lights_off", "Could the street lights be switched off?", sky(env(street_lights="off")),
     [call("set_lighting", street_lights="off")])
case(L, "indirect", "hydrant_yellow", "Can you paint the fire hydrant yellow instead of red?", painted("fire_hydrant_1", colour="yellow"),
     [call("set_asset_appearance", assets=["fire_hydrant_1"], colour="yellow")])
case(L, "indirect", "early_morning_7", "I'd like it to be early morning, around 7.", sky(env(time_from="06:30", time_to="08:00")),
     [call("set_time_of_day", time="07:00")])
case(L, "indirect", "unicorn_bench", "Could you paint the bench a sparkly unicorn colour?",
     refused(), [call("set_asset_appearance", assets=["bench_1"], colour="sparkly unicorn")], tags=IMPOSSIBLE)
case(L, "indirect", "dusk_and_lights", "Could you make it dusk and switch the street lights on?",
     sky(env(time_from="18:00", time_to="21:00", street_lights="on")),
     [call("set_time_of_day", time="dusk"), call("set_lighting", street_lights="on")], tags=COMPOUND)

case(L, "vague", "dusk", "dusk", sky(env(time_from="18:00", time_to="21:00")), [call("set_time_of_day", time="dusk")])
case(L, "vague", "gloomy", "gloomy weather", sky(env(weather=["cloudy", "rain", "fog"])), [call("set_weather", kind="cloudy", intensity=0.8)])
case(L, "vague", "winter_vibes", "winter vibes", sky(env(weather=["snow"])), [call("set_weather", kind="snow")])
case(L, "vague", "storm", "make it look like a storm", sky(env(weather=["rain"], intensity_min=0.7)),
     [call("set_weather", kind="rain", intensity=0.9)])
case(L, "vague", "lights_on", "lights on", [accepted(), only(environment=True)], [call("set_lighting", street_lights="on")],
     alternatives=[[env(street_lights="on")], [env(vehicle_lights="on")]])
case(L, "vague", "less_bright", "something less bright", [accepted(), only(environment=True)],
     [call("set_lighting", exposure=0.6)], alternatives=DARKER)
case(L, "vague", "bench_dull", "the bench looks dull",
     [accepted(), looks("bench"), only("bench")], [call("set_asset_appearance", assets=["bench_1"], colour="red")])
case(L, "vague", "late_night", "late at night", sky(env(night=True, time_from="22:00", time_to="04:00")),
     [call("set_time_of_day", time="23:30")])
case(L, "vague", "visibility_trouble", "more visibility trouble for the ego",
     sky(env(weather=["fog", "rain", "snow"], intensity_min=0.3)), [call("set_weather", kind="fog", intensity=0.7)])
case(L, "vague", "sunny_please", "sunny please", sky(env(weather=["clear"])), [call("set_weather", kind="clear")],
     setup=[turn("Let it rain hard.", call("set_weather", kind="rain", intensity=0.9), planned=True)])
case(L, "vague", "ego_stand_out", "make the ego stand out", [accepted(), looks("ego_vehicle"), only("ego_vehicle")],
     [call("set_asset_appearance", assets=["ego"], colour="orange")])
case(L, "vague", "thirty_oclock", "make it 30 o'clock", refused(), [call("set_time_of_day", time="30:00")], tags=IMPOSSIBLE)

case(L, "erroneous", "rainning", "make it rainning", sky(env(weather=["rain"])), [call("set_weather", kind="rain")])
case(L, "erroneous", "time_18h30", "set time to 18h30", sky(env(time_from="18:25", time_to="18:35")),
     [call("set_time_of_day", time="18:30")])
case(L, "erroneous", "bench_green_colour", "paint bench in green colour", painted("bench_1", colour="green"),
     [call("set_asset_appearance", assets=["bench_1"], colour="green")])
case(L, "erroneous", "turn_on_street_light", "turn on street light", sky(env(street_lights="on")),
     [call("set_lighting", street_lights="on")])
case(L, "erroneous", "fogg", "put heavy fogg", sky(env(weather=["fog"], intensity_min=0.7)),
     [call("set_weather", kind="fog", intensity=0.9)])
case(L, "erroneous", "car_all_blue", "make car all blue",
     [accepted(), looks("passenger_car", colour="blue", scope="all"), only("passenger_car", "suv")],
     [call("set_asset_appearance", category="passenger_car", colour="blue")])
case(L, "erroneous", "headlight_on", "switch on headlight of car", sky(env(vehicle_lights="on")),
     [call("set_lighting", vehicle_lights="on")])
case(L, "erroneous", "mid_night", "set time to mid night", sky(env(time_from="23:45", time_to="00:15")),
     [call("set_time_of_day", time="00:00")])
case(L, "erroneous", "snowing_little", "make snowing a little", sky(env(weather=["snow"], intensity_min=0.05, intensity_max=0.45)),
     [call("set_weather", kind="snow", intensity=0.3)])
case(L, "erroneous", "ego_paint_orange", "ego paint orange", painted("ego", colour="orange"),
     [call("set_asset_appearance", assets=["ego"], colour="orange")])
case(L, "erroneous", "nigth", "make nigth time", sky(env(night=True)), [call("set_time_of_day", time="night")])
case(L, "erroneous", "tornado", "set the wether to tornado", refused(), [call("set_weather", kind="tornado")], tags=IMPOSSIBLE)

# More compound and multi-turn cases (two requests at once; references to earlier turns) --------
case(A, "indirect", "bus_and_bench", "Could you add a bus at the bus stop, and a bench next to it?",
     [accepted(), delta("bus", 1, 1), delta("bench", 1, 1), near("bus", "bus stop", 10.0), near("bench", "bus_1", 4.0),
      only("bus", "bench")],
     [call("add_asset", category="bus", location=at("at", "bus stop")),
      call("add_asset", category="bench", location=at("next_to", "bus_1"))], tags=COMPOUND)
case(A, "direct", "people_and_cyclist", "Add two pedestrians at the north crosswalk and a cyclist at the west crosswalk.",
     [accepted(), delta("pedestrian", 2, 2), delta("bicycle", 1, 1), near("pedestrian", "north crosswalk", 8.0),
      near("bicycle", "west crosswalk", 6.0), only("pedestrian", "bicycle")],
     [call("add_asset", category="pedestrian", count=2, location=at("at", "north crosswalk")),
      call("add_asset", category="bicycle", location=at("at", "west crosswalk"))], tags=COMPOUND)
case(A, "erroneous", "tree_and_bench_fountain", "add tree at fountain and bench also there",
     [accepted(), delta("tree", 1, 1), delta("bench", 1, 1), near(["tree", "bench"], "fountain", 10.0), only("tree", "bench")],
     [call("add_asset", category="tree", location=at("at", "fountain")),
      call("add_asset", category="bench", location=at("at", "fountain"))], tags=COMPOUND)
case(A, "vague", "two_more_there", "put two more there",
     [accepted(), delta("traffic_cone", 2, 2), count("traffic_cone", 3, 3), near("traffic_cone", (-50.0, -1.75), 6.0),
      only("traffic_cone")],
     [call("add_asset", category="traffic_cone", count=2, location=at("in_front_of", "ego", distance=10.0))],
     setup=[turn("Put a cone 10 m in front of the ego.",
                 call("add_asset", category="traffic_cone", location=at("in_front_of", "ego", distance=10.0)), planned=True)])
case(R, "indirect", "trees_and_stop_sign", "Could you get rid of the trees and the stop sign?",
     [accepted(), count("tree", 0, 0), gone("stop_sign_1"), only("tree", "stop_sign")],
     [call("remove_assets", category="tree"), call("remove_assets", category="stop_sign")], tags=COMPOUND)
case(R, "vague", "suv_becomes_bus", "swap the SUV for a bus, same spot",
     [accepted(), gone("suv_1"), delta("bus", 1, 1), near("bus", (23.0, -42.0), 3.0), only("suv", "bus")],
     [call("remove_assets", assets=["suv_1"]),
      call("add_asset", category="bus", location=xy(23.0, -42.0), yaw_deg=90.0)], tags=COMPOUND)
case(R, "indirect", "two_fewer_cones", "Actually, I'd like two fewer of those cones.",
     [accepted(), delta("traffic_cone", -2, -2), only("traffic_cone")],
     [call("remove_assets", category="traffic_cone", count=2)],
     setup=[turn("Put five cones in a line in front of the library entrance.",
                 call("arrange_assets", categories=["traffic_cone"], shape="line", count=5,
                      location=at("in_front_of", "Library entrance")), planned=True)])
case(P, "direct", "suv_lot_a_black", "Put the SUV in lot A and paint it black.",
     [accepted(), near("suv_1", "parking lot A", 1.0), looks("suv_1", colour="black"), only(assets=("suv_1",))],
     [call("place_asset", asset="suv_1", location=at("at", "parking lot A")),
      call("set_asset_appearance", assets=["suv_1"], colour="black")], tags=COMPOUND)
case(P, "indirect", "bench_and_bin_fountain", "Could you move the bench to the fountain and the trash bin next to it?",
     [accepted(), near("bench_1", "fountain", 6.0), near("trash_bin_1", "fountain", 8.0),
      only(assets=("bench_1", "trash_bin_1"))],
     [call("place_asset", asset="bench_1", location=at("at", "fountain")),
      call("place_asset", asset="trash_bin_1", location=at("next_to", "bench_1"))], tags=COMPOUND)
case(P, "erroneous", "ego_east_gate_face_west", "put ego to east gate and make it face to west",
     [accepted(), near("ego", "east gate", 10.0), moved("ego", turn_min_deg=150.0), only(assets=("ego",))],
     [call("place_asset", asset="ego", location=at("at", "east gate"), yaw_deg=180.0)], tags=COMPOUND)
case(P, "vague", "them_by_fountain", "now put them by the fountain",
     [accepted(), delta("pedestrian", 0, 0), near("pedestrian", "fountain", 8.0), only("pedestrian")],
     [call("place_asset", asset="pedestrian_1", location=at("at", "fountain"))],
     setup=[turn("Add a pedestrian next to the bench.",
                 call("add_asset", category="pedestrian", location=at("next_to", "bench_1")), planned=True)])
case(M, "indirect", "back_and_slow", "Could you move the ego back 10 m and slow it down to 3 m/s?",
     shifted("ego", moved("ego", min_distance=8.0, max_distance=12.0, direction="backward"),
             does("ego", "drive_lane", speed_min=2.5, speed_max=3.5)),
     [call("move_asset", asset="ego", forward=-10.0),
      call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 3.0})],
     tags=COMPOUND)
case(M, "vague", "suv_circles_ego_faster", "SUV circling in lot B, and the ego a bit quicker",
     [accepted(), does("suv_1", "circle"), does("ego", "drive_lane", speed_min=5.5), only(assets=("suv_1", "ego"))],
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "centre": "parking lot B"}),
      call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 7.0})],
     tags=COMPOUND)
case(M, "erroneous", "bench_turn_and_move", "turn bench around and move it 2 meter",
     shifted("bench_1", moved("bench_1", min_distance=1.5, max_distance=2.5, turn_min_deg=170.0)),
     [call("move_asset", asset="bench_1", forward=2.0, turn_deg=180.0)], tags=COMPOUND)
case(M, "vague", "move_it_left", "move it a bit left",
     [accepted(), moved("passenger_car_3", min_distance=0.3, max_distance=3.6, direction="left"), only("passenger_car")],
     [call("move_asset", asset="passenger_car_3", left=1.0)],
     setup=[turn("Add a car in lot A.", call("add_asset", category="passenger_car", location=at("at", "parking lot A")),
                 planned=True)])
case(G, "direct", "ring_and_barrier_line", "Put a ring of 8 cones around the intersection and a line of 3 barriers at the east gate.",
     [accepted(), delta("traffic_cone", 8, 8), shape("traffic_cone", "ring", 8, around="main intersection"),
      delta("road_barrier", 3, 3), shape("road_barrier", "line", 3), near("road_barrier", "east gate", 6.0),
      only("traffic_cone", "road_barrier")],
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=8, location=at("at", "main intersection")),
      call("arrange_assets", categories=["road_barrier"], shape="line", count=3, location=at("at", "east gate"))],
     tags=COMPOUND)
case(G, "erroneous", "trees_line_bollards_ring", "line of 4 tree at fountain and 4 bollard around hydrant",
     [accepted(), shape("tree", "line", 4), near("tree", "fountain", 10.0), shape("bollard", "ring", 4, around="fire_hydrant_1"),
      delta("tree", 4, 4), delta("bollard", 4, 4), only("tree", "bollard")],
     [call("arrange_assets", categories=["tree"], shape="line", count=4, location=at("at", "fountain")),
      call("arrange_assets", categories=["bollard"], shape="ring", count=4, location=at("at", "fire_hydrant_1"))],
     tags=COMPOUND)
case(L, "vague", "rainy_night", "rainy night", sky(env(weather=["rain"], night=True)),
     [call("set_weather", kind="rain"), call("set_time_of_day", time="night")], tags=COMPOUND)
case(L, "erroneous", "snow_and_blue_bench", "make it snow and paint the bench blue",
     [accepted(), env(weather=["snow"]), looks("bench_1", colour="blue"), only(assets=("bench_1",), environment=True)],
     [call("set_weather", kind="snow"), call("set_asset_appearance", assets=["bench_1"], colour="blue")], tags=COMPOUND)
case(L, "indirect", "foggy_six_am", "I'd like foggy weather at 6 in the morning.",
     sky(env(weather=["fog"], time_from="05:45", time_to="06:15")),
     [call("set_weather", kind="fog"), call("set_time_of_day", time="06:00")], tags=COMPOUND)
case(L, "indirect", "paint_it_yellow", "Could you paint it yellow?",
     [accepted(), looks("bus", colour="yellow"), only("bus")],
     [call("set_asset_appearance", assets=["bus_1"], colour="yellow")],
     setup=[turn("Add a bus at the bus stop.", call("add_asset", category="bus", location=at("at", "bus stop")), planned=True)])
case(S, "vague", "trees_and_benches", "trees and benches, how many of each?",
     question(says(*FOUR), says("1", "one")),
     [call("find_assets", category="tree"), call("find_assets", category="bench")], tags=COMPOUND)
case(S, "direct", "bus_stop_and_fountain", "Where are the bus stop and the fountain?",
     question(says(all_of=("-30", "75"))),
     [call("find_landmarks", query="bus stop"), call("find_landmarks", query="fountain")], tags=COMPOUND)
case(S, "indirect", "bikes_now", "How many bikes are there now, could you check?",
     question(says("3", "three")), [call("find_assets", category="bicycle")],
     setup=[turn("Add three bicycles at the bus stop.",
                 call("add_asset", category="bicycle", count=3, location=at("at", "bus stop")), planned=True)])

# A few more wordings: a dozen, a clock time in words, a building by what it holds, scopes -------
case(A, "direct", "dozen_cones_crossroads", "Add a dozen cones at the crossroads.",
     added("traffic_cone", 12, near("traffic_cone", "main intersection", 1.0)),
     [call("add_asset", category="traffic_cone", count=12, location=at("at", "main intersection"))])
case(A, "indirect", "bench_cafeteria_building", "I'd like a bench near the building with the cafeteria.",
     added("bench", 1, near("bench", "Student Union entrance", 10.0)),
     [call("add_asset", category="bench", location=at("at", "Student Union entrance"))])
case(A, "direct", "car_8m_ahead_of_bus", "Add a car 8 m in front of the bus.",
     added("passenger_car", 1, rel("passenger_car", "in_front_of", "bus_1", 16.0, tolerance_deg=30.0)),
     [call("add_asset", category="passenger_car", location=at("in_front_of", "bus_1", distance=8.0))],
     setup=[turn("Put a shuttle bus at the bus stop.", call("add_asset", category="bus", location=at("at", "bus stop")),
                 planned=True)])
case(A, "vague", "more_cones", "more cones",
     [accepted(), delta("traffic_cone", 1, 20), only("traffic_cone")],
     [call("add_asset", category="traffic_cone", count=2, location=at("in_front_of", "Library entrance"))],
     setup=[turn("Put two cones in front of the library entrance.",
                 call("add_asset", category="traffic_cone", count=2, location=at("in_front_of", "Library entrance")),
                 planned=True)])
case(R, "vague", "quieter_bus_stop", "make it quieter around the bus stop",
     removed("pedestrian", (1, 4)), [call("remove_assets", category="pedestrian", count=2)],
     setup=[turn("Four people waiting at the bus stop, please.",
                 call("add_asset", category="pedestrian", count=4, location=at("at", "bus stop")))])
case(L, "indirect", "quarter_to_eight", "Could you set the clock to a quarter to eight in the morning?",
     sky(env(time_from="07:40", time_to="07:50")), [call("set_time_of_day", time="07:45")])
case(L, "direct", "lot_b_cars_silver_not_suv", "Paint the cars in lot B silver, but not the SUV.",
     [accepted(), looks("passenger_car", colour="silver", scope="all"), kept("suv_1"), only("passenger_car")],
     [call("set_asset_appearance", assets=["passenger_car_1", "passenger_car_2"], colour="silver")])
case(S, "indirect", "in_the_egos_way", "Is anything in the ego's way within the next 40 metres?",
     question(says("rubble", "cement_rubble_1", "debris", "concrete")),
     [call("find_assets", near="ego", within=40.0)], setup=[RUBBLE_AHEAD])

def write(path: Path = OUT) -> int:
    """Write the cases as JSON Lines; returns how many."""
    lines = [json.dumps(c, separators=(",", ":")) for c in CASES]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return len(lines)


if __name__ == "__main__":
    print(f"wrote {write()} cases to {OUT}")
