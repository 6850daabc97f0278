"""The practice suite's cases, as a plain list: `python -m drivetwin.evals.practice_source`.

A second development suite, written from the campus world, the catalog, the Worker tools and
the checks only (not from the planners, their prompts or any other suite), in the voices of
different users. Every case judges the outcome, and its reference calls build one outcome
its checks accept (tests/evals/test_practice_suite.py). The few builders below only spell
JSON; they hold no logic of their own.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

JSONL_PATH = Path(__file__).with_name("suites") / "practice.jsonl"
Json = dict[str, Any]

# Ids of the campus world's assets, as campus.json names them.
LOT_B_VEHICLES = ["passenger_car_1", "suv_1", "passenger_car_2"]
OK: Json = {"kind": "status", "accepted": True}


def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def at(target: str, relation: str = "at", **more: Any) -> Json:
    return {"relation": relation, "target": target, **more}


def xy(x: float, y: float) -> Json:
    return {"relation": "absolute", "x": x, "y": y}


def keep(*categories: str, assets: tuple[str, ...] | list[str] = (), environment: bool = False) -> Json:
    """Nothing else changed: the collateral-edit guard every case carries."""
    return {"kind": "unchanged_except", "categories": list(categories), "assets": list(assets),
            "environment": environment}


def delta(category: str | list[str], lo: int, hi: int | None = None) -> Json:
    return {"kind": "count_delta", "category": category, "min": lo, "max": lo if hi is None else hi}


def count(category: str | list[str], lo: int | None, hi: int | None) -> Json:
    return {"kind": "count", "category": category, "min": lo, "max": hi}


def near(target: str, within: float, **select: Any) -> Json:
    return {"kind": "near", "target": target, "within": within, **select}


def near_point(x: float, y: float, within: float, **select: Any) -> Json:
    return {"kind": "near", "point": [x, y], "within": within, **select}


def says(*any_of: str, all_of: tuple[str, ...] = (), none_of: tuple[str, ...] = ()) -> Json:
    return {"kind": "answer_contains", "any_of": list(any_of), "all_of": list(all_of),
            "none_of": list(none_of)}


def gone(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": False}


def moved(asset: str, lo: float, hi: float | None = None, **more: Any) -> Json:
    return {"kind": "moved", "asset": asset, "min_distance": lo, "max_distance": hi, **more}


def env(**fields: Any) -> Json:
    return {"kind": "environment", **fields}


def look(colour: str | None = None, material: str | None = None, **select: Any) -> Json:
    return {"kind": "appearance", "colour": colour, "material": material, **select}


def step(prompt: str, calls: list[Json], planned: bool = False) -> Json:
    return {"prompt": prompt, "calls": calls, "planned": planned}


def refused() -> list[Json]:
    """The outcome of an impossible request: refused, and nothing changed."""
    return [{"kind": "status", "accepted": False}, keep()]


CASES: list[Json] = []


def case(task: str, grade: str, name: str, prompt: str, reference: list[Json], checks: list[Json], *,
         setup: list[Json] | None = None, alternatives: list[list[Json]] | None = None,
         tags: tuple[str, ...] = (), notes: str = "") -> None:
    labels = ["practice", *tags]
    if setup:
        labels.append("multi_turn")
    CASES.append({
        "id": f"practice.{task}.{grade}.{name}", "world": "campus", "setup": setup or [],
        "prompt": prompt, "task": task, "grade": grade, "tags": labels, "checks": checks,
        "alternatives": alternatives or [], "reference": reference, "notes": notes,
    })


# Scene set-ups replayed before a prompt (planned=False: the same start for every planner).
CONES_AT_LOT_B = step("Add four traffic cones at the lot B entrance.",
                      [call("add_asset", category="traffic_cone", count=4, location=at("parking lot B entrance"))])
BUS_AHEAD = step("Add a bus 15 m in front of the ego.",
                 [call("add_asset", category="bus", location=at("ego", "in_front_of", distance=15))])
TRUCK_IN_LANE = step("Put a truck in the eastbound lane at x=-20.",
                     [call("add_asset", category="truck", location=xy(-20, -1.75), yaw_deg=0)])
RUBBLE_ON_CAMPUS = step("Put some rubble in the northbound lane of Campus Drive.",
                        [call("add_asset", category="cement_rubble", location=xy(1.75, -30))])
CONES_WESTBOUND = step("Put three cones in the westbound lane near x=30.",
                       [call("add_asset", category="traffic_cone", count=3, location=xy(30, 1.75)),
                        ])
CROWD_AT_CROSSWALK = step("Add five pedestrians at the west crosswalk.",
                          [call("add_asset", category="pedestrian", count=5, location=at("west crosswalk"))])
BARRIERS_AT_GATE = step("Add three road barriers at the east gate.",
                        [call("add_asset", category="road_barrier", count=3, location=at("east gate"))])
RAIN = step("Make it rain.", [call("set_weather", kind="rain", intensity=0.6)])

# ---------------------------------------------------------------------------------------- search
S = "search"
ANSWER = [OK, keep()]
case(S, "direct", "nearest_landmark_to_ego", "Which landmark is nearest to the ego vehicle?",
     [call("find_landmarks", nearest_to="ego")], [*ANSWER, says("parking lot A", "lot A")])
case(S, "direct", "count_street_lights", "How many street lights are there on the campus?",
     [call("find_assets", category="street_light")], [*ANSWER, says("12", "twelve")])
case(S, "direct", "lanes_of_main_street", "List the lanes of Main Street.",
     [call("find_lanes", road="Main Street")],
     [*ANSWER, says(all_of=("main_eastbound", "main_westbound"), none_of=("campus_northbound",))])
case(S, "direct", "where_is_hydrant", "Where is the fire hydrant?",
     [call("find_assets", category="fire_hydrant")], [*ANSWER, says("16", "16.0", all_of=("5.5",))])
case(S, "direct", "nearest_car_to_ego", "What is the nearest car to the ego vehicle?",
     [call("find_assets", category="passenger_car", nearest_to="ego")], [*ANSWER, says("passenger_car_1")])
case(S, "direct", "bus_mass", "How heavy is a bus?",
     [call("asset_properties", category="bus")], [*ANSWER, says("12000", "12,000", "12 t", "12 tonnes")])
case(S, "direct", "trees_near_fountain", "Which trees are within 20 m of the fountain?",
     [call("find_assets", category="tree", near="fountain", within=20)],
     [*ANSWER, says(all_of=("tree_2", "tree_3"), none_of=("tree_1", "tree_4"))])
case(S, "direct", "lane_nearest_union", "Which lane is nearest the Student Union entrance?",
     [call("find_lanes", near="Student Union entrance")], [*ANSWER, says("campus_northbound")])
case(S, "direct", "ego_mass_and_landmark", "How heavy is the ego vehicle, and which landmark is closest to it?",
     [call("asset_properties", asset="ego"), call("find_landmarks", nearest_to="ego")],
     [*ANSWER, says("1600", "1,600", all_of=("parking lot A",))], tags=("compound",))
case(S, "direct", "impossible_swimming_pool", "Where is the swimming pool?",
     [call("find_landmarks", query="swimming pool")], refused(), tags=("impossible",))

case(S, "indirect", "bus_stop_distance", "Could you tell me how far the bus stop is from the ego car?",
     [call("find_landmarks", nearest_to="ego")], [*ANSWER, says("30.2", "30")])
case(S, "indirect", "bench_near_bus_stop",
     "I'd like to know whether there's a bench anywhere near the bus stop before I plan the pedestrian test.",
     [call("find_assets", category="bench", near="bus stop", within=10)], [*ANSWER, says("bench_1")])
case(S, "indirect", "cars_parked_in_lot_b", "Before I add traffic, tell me which cars are parked in lot B.",
     [call("find_assets", category="passenger_car", near="parking lot B", within=25)],
     [*ANSWER, says(all_of=("passenger_car_1", "passenger_car_2"))])
case(S, "indirect", "anything_on_campus_drive",
     "The robot will drive up Campus Drive next; is anything in its way there?",
     [call("find_assets", lane="Campus Drive")], [*ANSWER, says("cement_rubble_1", "rubble", "cement_rubble")],
     setup=[RUBBLE_ON_CAMPUS])
case(S, "indirect", "landmark_by_traffic_light_2",
     "I want to put a sign by whatever landmark sits closest to traffic_light_2; which one is that?",
     [call("find_landmarks", nearest_to="traffic_light_2")], [*ANSWER, says("main intersection", "intersection")])
case(S, "indirect", "truck_mass", "It would help my braking calculation to know what a truck weighs.",
     [call("asset_properties", category="truck")], [*ANSWER, says("9000", "9,000", "9 t")])
case(S, "indirect", "tree_count_for_report", "For my report I need the number of trees on campus.",
     [call("find_assets", category="tree")], [*ANSWER, says("4", "four")])
case(S, "indirect", "lamps_near_bus_stop", "Could you check which lamp posts stand within 15 m of the bus stop?",
     [call("find_assets", category="street_light", near="bus stop", within=15)],
     [*ANSWER, says(all_of=("street_light_4", "street_light_5"), none_of=("street_light_6", "street_light_3"))])
case(S, "indirect", "lanes_and_hydrant",
     "We're mapping the crossroads: which lanes does Campus Drive have, and where is the hydrant?",
     [call("find_lanes", road="Campus Drive"), call("find_assets", category="fire_hydrant")],
     [*ANSWER, says(all_of=("campus_northbound", "campus_southbound", "fire_hydrant_1"))], tags=("compound",))

case(S, "vague", "whats_around_ego", "what's around the ego?",
     [call("find_assets", nearest_to="ego")], [*ANSWER, says("street_light_2")])
case(S, "vague", "anything_blocking_road", "anything blocking the road?",
     [call("find_assets", on_lane=True)], [*ANSWER, says("traffic_cone", "cone", "traffic_cone_1")],
     setup=[CONES_WESTBOUND])
case(S, "vague", "where_to_park", "where can I park?",
     [call("find_landmarks", query="parking")], [*ANSWER, says("parking lot A", "parking lot B")])
case(S, "vague", "which_way_ego", "ego - which way and how?",
     [call("asset_properties", asset="ego")], [*ANSWER, says("drive_lane", "yaw 0", "0 deg", "east")])
case(S, "vague", "the_cars", "the cars - where are they?",
     [call("find_assets", category="passenger_car")],
     [*ANSWER, says(all_of=("passenger_car_1", "passenger_car_2"))])
case(S, "vague", "stuff_near_fountain", "stuff near the fountain?",
     [call("find_assets", near="fountain", within=20)], [*ANSWER, says("tree_2")])
case(S, "vague", "near_back_gate", "closest landmark to the back gate?",
     [call("find_landmarks", nearest_to="east gate")], [*ANSWER, says("fountain")])
case(S, "vague", "bins_and_benches", "bins? benches? how many of each",
     [call("find_assets", category="trash_bin"), call("find_assets", category="bench")],
     [*ANSWER, says("trash_bin_1", "1"), says("bench_1", "1")], tags=("compound",))
case(S, "vague", "impossible_lamps_by_gym", "any lamps near the gym?",
     [call("find_assets", category="street_light", near="gym", within=20)], refused(), tags=("impossible",))

case(S, "erroneous", "wich_landmark_nerest", "wich landmark is nerest to ego car",
     [call("find_landmarks", nearest_to="ego")], [*ANSWER, says("parking lot A", "lot A")])
case(S, "erroneous", "how_much_lihgts", "how much street lihgts there is?",
     [call("find_assets", category="street_light")], [*ANSWER, says("12", "twelve")])
case(S, "erroneous", "were_hydrent", "were is the hydrent",
     [call("find_assets", category="fire_hydrant")], [*ANSWER, says("fire_hydrant_1", "16.0", "16")])
case(S, "erroneous", "lanes_campus_driv", "tel me the lanes on campus driv",
     [call("find_lanes", road="Campus Drive")],
     [*ANSWER, says(all_of=("campus_northbound", "campus_southbound"), none_of=("main_eastbound",))])
case(S, "erroneous", "lorry_weigh", "how heavy a lorry is?",
     [call("asset_properties", category="truck")], [*ANSWER, says("9000", "9,000")])
case(S, "erroneous", "car_most_near", "what car is most near to the ego",
     [call("find_assets", category="passenger_car", nearest_to="ego")], [*ANSWER, says("passenger_car_1")])
case(S, "erroneous", "trees_near_fountian", "tree near fountian, which ones?",
     [call("find_assets", category="tree", near="fountain", within=20)],
     [*ANSWER, says(all_of=("tree_2",), none_of=("tree_1", "tree_4"))])
case(S, "erroneous", "somthing_block_street", "is somthing block the street?",
     [call("find_assets", on_lane=True)], [*ANSWER, says("traffic_cone", "cone", "traffic_cone_1")],
     setup=[CONES_WESTBOUND])
case(S, "erroneous", "bench_near_bus_stp", "bench near bus stp??",
     [call("find_assets", category="bench", near="bus stop", within=10)], [*ANSWER, says("bench_1")])
case(S, "erroneous", "impossible_swiming_pool", "wheres the swiming pool",
     [call("find_landmarks", query="swimming pool")], refused(), tags=("impossible",))

# -------------------------------------------------------------------------------------- addition
A = "addition"
case(A, "direct", "bus_ahead_of_ego", "Add a bus 10 m in front of the ego vehicle.",
     [call("add_asset", category="bus", location=at("ego", "in_front_of", distance=10))],
     [delta("bus", 1), {"kind": "relative", "category": "bus", "relation": "in_front_of", "target": "ego",
                        "max_distance": 25}, keep("bus")])
case(A, "direct", "three_cones_lot_b_entrance", "Place three traffic cones at the entrance of parking lot B.",
     [call("add_asset", category="traffic_cone", count=3, location=at("parking lot B entrance"))],
     [delta("traffic_cone", 3), near("parking lot B entrance", 8, category="traffic_cone", require_all=True),
      keep("traffic_cone")])
case(A, "direct", "pedestrian_sidewalk_library", "Add a pedestrian on the sidewalk near the Library entrance.",
     [call("add_asset", category="pedestrian", location=at("Library entrance", "on_sidewalk"))],
     [delta("pedestrian", 1), {"kind": "on_surface", "category": "pedestrian", "surfaces": ["sidewalk"]},
      near("Library entrance", 15, category="pedestrian"), keep("pedestrian")])
case(A, "direct", "car_driving_westbound", "Add a car driving in main_westbound at 6 m/s.",
     [call("add_asset", category="passenger_car", location=at("main_westbound", "in_lane"),
           behaviour={"kind": "drive_lane", "lane": "main_westbound", "speed": 6})],
     [delta("passenger_car", 1), {"kind": "behaviour", "category": "passenger_car", "behaviour": "drive_lane",
                                  "lane": "main_westbound", "speed_min": 5.5, "speed_max": 6.5},
      keep("passenger_car")])
case(A, "direct", "truck_15m_ahead_in_lane", "Put a truck 15 m ahead of the ego in its lane.",
     [call("add_asset", category="truck", location=at("ego", along_m=15))],
     [delta("truck", 1), {"kind": "in_lane", "category": "truck", "lane": "main_eastbound"},
      {"kind": "relative", "category": "truck", "relation": "in_front_of", "target": "ego", "max_distance": 22,
       "tolerance_deg": 30}, keep("truck")])
case(A, "direct", "two_benches_fountain", "Add two benches near the fountain.",
     [call("add_asset", category="bench", count=2, location=at("fountain"))],
     [delta("bench", 2), near("fountain", 10, category="bench", require_all=True), keep("bench")])
case(A, "direct", "stop_sign_north_crosswalk", "Add a stop sign at the north crosswalk.",
     [call("add_asset", category="stop_sign", location=at("north crosswalk"))],
     [delta("stop_sign", 1), near("north crosswalk", 8, category="stop_sign"), keep("stop_sign")])
case(A, "direct", "robot_lot_a", "Add an Ackermann robot in parking lot A.",
     [call("add_asset", category="ackermann_robot", location=at("parking lot A"))],
     [delta("ackermann_robot", 1), near("parking lot A", 1, category="ackermann_robot"), keep("ackermann_robot")])
case(A, "direct", "bus_and_pedestrian", "Add a bus in front of the ego and a pedestrian at the west crosswalk.",
     [call("add_asset", category="bus", location=at("ego", "in_front_of")),
      call("add_asset", category="pedestrian", location=at("west crosswalk"))],
     [delta("bus", 1), delta("pedestrian", 1), near("west crosswalk", 6, category="pedestrian"),
      {"kind": "relative", "category": "bus", "relation": "in_front_of", "target": "ego", "max_distance": 25},
      keep("bus", "pedestrian")], tags=("compound",))
case(A, "direct", "impossible_250_cones", "Add 250 traffic cones in parking lot A.",
     [call("add_asset", category="traffic_cone", count=250, location=at("parking lot A"))], refused(),
     tags=("impossible",), notes="a scene holds at most 200 cones")

case(A, "indirect", "stalled_van_near_library",
     "For the next run I need a stalled van blocking the eastbound lane near the library.",
     [call("add_asset", category="truck", location=xy(-41, -1.75), yaw_deg=0)],
     [delta("truck", 1), {"kind": "in_lane", "category": "truck", "lane": "main_eastbound"},
      near("Library entrance", 25, category="truck"),
      {"kind": "behaviour", "category": "truck", "behaviour": "parked"}, keep("truck")])
case(A, "indirect", "busier_main_street",
     "I'd like the street to feel busier - could you add a couple of cars driving along Main Street?",
     [call("add_asset", category="passenger_car", count=2, location=at("main_westbound", "in_lane"),
           behaviour={"kind": "drive_lane", "lane": "main_westbound"})],
     [delta(["passenger_car", "suv"], 2, 3), {"kind": "behaviour", "category": ["passenger_car", "suv"],
                                             "behaviour": "drive_lane", "min_count": 2},
      {"kind": "in_lane", "category": ["passenger_car", "suv"]}, keep("passenger_car", "suv")])
case(A, "indirect", "someone_waiting_crosswalk",
     "We're testing pedestrian detection, so someone should be waiting at the west crosswalk.",
     [call("add_asset", category="pedestrian", location=at("west crosswalk"))],
     [delta("pedestrian", 1, 3), near("west crosswalk", 6, category="pedestrian"), keep("pedestrian")])
case(A, "indirect", "shade_by_bus_stop", "It would be nice to have some shade near the bus stop.",
     [call("add_asset", category="tree", location=at("bus stop"))],
     [delta("tree", 1, 3), near("bus stop", 12, category="tree"), keep("tree")])
case(A, "indirect", "shuttle_at_stop", "Could you put a shuttle at the bus stop?",
     [call("add_asset", category="bus", location=at("bus stop"))],
     [delta("bus", 1), near("bus stop", 10, category="bus"), keep("bus")])
case(A, "indirect", "rover_westbound",
     "Our perception team wants one of the small research rovers driving toward the ego in the westbound lane.",
     [call("add_asset", category="ackermann_robot", location=xy(-30, 1.75),
           behaviour={"kind": "drive_lane", "lane": "main_westbound", "speed": 3})],
     [delta("ackermann_robot", 1), {"kind": "in_lane", "category": "ackermann_robot", "lane": "main_westbound"},
      {"kind": "behaviour", "category": "ackermann_robot", "behaviour": "drive_lane", "lane": "main_westbound"},
      keep("ackermann_robot")])
case(A, "indirect", "jaywalker_for_braking",
     "I want to test emergency braking: have a jaywalker cross about 25 m ahead of the ego.",
     [call("add_asset", category="pedestrian", location=at("ego", "in_front_of", distance=25),
           behaviour={"kind": "jaywalk", "ahead": 25})],
     [delta("pedestrian", 1), {"kind": "behaviour", "category": "pedestrian", "behaviour": ["jaywalk", "cross_road"]},
      keep("pedestrian")])
case(A, "indirect", "parking_sign_lot_a", "Please add a parking sign by the lot A entrance so drivers know where to go.",
     [call("add_asset", category="parking_sign", location=at("parking lot A entrance"))],
     [delta("parking_sign", 1), near("parking lot A entrance", 8, category="parking_sign"), keep("parking_sign")])
case(A, "indirect", "roadworks_rubble_campus",
     "Since we're simulating roadworks, drop a pile of rubble in the northbound lane of Campus Drive.",
     [call("add_asset", category="cement_rubble", location=at("campus_northbound", "in_lane"))],
     [delta("cement_rubble", 1, 3), {"kind": "in_lane", "category": "cement_rubble", "lane": "campus_northbound"},
      keep("cement_rubble")])
case(A, "indirect", "impossible_helicopter", "For an aerial test I'd need a helicopter landing on the library roof.",
     [call("add_asset", category="helicopter", location=at("Library entrance"))], refused(),
     tags=("impossible",))

case(A, "vague", "more_cones", "more cones",
     [call("add_asset", category="traffic_cone", count=3, location=at("parking lot B entrance"))],
     [delta("traffic_cone", 1, 50), keep("traffic_cone")], setup=[CONES_AT_LOT_B])
case(A, "vague", "street_busier", "make the street busier",
     [call("add_asset", category="passenger_car", count=3, location=at("main_eastbound", "in_lane"),
           behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
     [delta(["passenger_car", "suv", "bus", "truck", "motorcycle", "bicycle"], 1, 50),
      {"kind": "behaviour", "category": ["passenger_car", "suv", "bus", "truck", "motorcycle", "bicycle"],
       "behaviour": "drive_lane"},
      keep("passenger_car", "suv", "bus", "truck", "motorcycle", "bicycle", "pedestrian")])
case(A, "vague", "someone_at_bus_stop", "someone at the bus stop",
     [call("add_asset", category="pedestrian", location=at("bus stop"))],
     [delta("pedestrian", 1, 3), near("bus stop", 8, category="pedestrian"), keep("pedestrian")])
case(A, "vague", "greenery_engineering", "a bit of greenery by the engineering building",
     [call("add_asset", category="tree", location=at("Engineering Hall entrance"))],
     [delta("tree", 1, 5), near("Engineering Hall", 15, category="tree"), keep("tree")])
case(A, "vague", "something_big_lot_b", "something big parked in lot B",
     [call("add_asset", category="truck", location=at("parking lot B"))],
     [delta(["bus", "truck"], 1, 2), near("parking lot B", 1, category=["bus", "truck"]), keep("bus", "truck")])
case(A, "vague", "dozen_cones_near_ego", "a dozen cones near the ego",
     [call("add_asset", category="traffic_cone", count=12, location=at("ego", "in_front_of"))],
     [delta("traffic_cone", 12), near("ego", 25, category="traffic_cone", require_all=True), keep("traffic_cone")])
case(A, "vague", "barrier_east_gate", "need a barrier at the east gate",
     [call("add_asset", category="road_barrier", location=at("east gate"))],
     [delta("road_barrier", 1, 3), near("east gate", 8, category="road_barrier"), keep("road_barrier")])
case(A, "vague", "bikes_at_union", "bikes at the union",
     [call("add_asset", category="bicycle", count=3, location=at("Student Union entrance"))],
     [delta("bicycle", 2, 10), near("Student Union entrance", 12, category="bicycle", require_all=True),
      keep("bicycle")])
case(A, "vague", "impossible_car_in_library", "stick a car inside the library",
     [call("add_asset", category="passenger_car", location=xy(-41, -30))], refused(), tags=("impossible",))

case(A, "erroneous", "ad_cone_lot_b_entrence", "ad 3 traffic cone at lot b entrence",
     [call("add_asset", category="traffic_cone", count=3, location=at("parking lot B entrance"))],
     [delta("traffic_cone", 3), near("parking lot B entrance", 8, category="traffic_cone", require_all=True),
      keep("traffic_cone")])
case(A, "erroneous", "buss_front_ego", "put a buss in front of ego car",
     [call("add_asset", category="bus", location=at("ego", "in_front_of"))],
     [delta("bus", 1), {"kind": "relative", "category": "bus", "relation": "in_front_of", "target": "ego",
                        "max_distance": 25}, keep("bus")])
case(A, "erroneous", "pedestrain_side_walk", "add pedestrain on side walk near libary",
     [call("add_asset", category="pedestrian", location=at("Library entrance", "on_sidewalk"))],
     [delta("pedestrian", 1), {"kind": "on_surface", "category": "pedestrian", "surfaces": ["sidewalk"]},
      near("Library entrance", 15, category="pedestrian"), keep("pedestrian")])
case(A, "erroneous", "car_drive_westbound", "i want car drive on the westbound lane please",
     [call("add_asset", category="passenger_car", location=at("main_westbound", "in_lane"),
           behaviour={"kind": "drive_lane", "lane": "main_westbound"})],
     [delta(["passenger_car", "suv"], 1), {"kind": "behaviour", "category": ["passenger_car", "suv"],
                                          "behaviour": "drive_lane", "lane": "main_westbound"},
      keep("passenger_car", "suv")])
case(A, "erroneous", "bench_near_fontain", "plz add 2 bench near fontain",
     [call("add_asset", category="bench", count=2, location=at("fountain"))],
     [delta("bench", 2), near("fountain", 10, category="bench", require_all=True), keep("bench")])
case(A, "erroneous", "firehydrant_jtekt", "add one firehydrant near the JTEKT entrence",
     [call("add_asset", category="fire_hydrant", location=at("JTEKT building entrance"))],
     [delta("fire_hydrant", 1), near("JTEKT building entrance", 10, category="fire_hydrant"), keep("fire_hydrant")])
case(A, "erroneous", "motorbike_behind_ego", "add motorbike behind of the ego",
     [call("add_asset", category="motorcycle", location=at("ego", "behind"))],
     [delta("motorcycle", 1), {"kind": "relative", "category": "motorcycle", "relation": "behind", "target": "ego",
                               "max_distance": 20}, keep("motorcycle")])
case(A, "erroneous", "tree_parkin_lot_a", "put tree at parkin lot A",
     [call("add_asset", category="tree", location=at("parking lot A"))],
     [delta("tree", 1), near("parking lot A", 1, category="tree"), keep("tree")])
case(A, "erroneous", "impossible_stripy_barriers_gym", "um can u put like 3 of those stripy barriers by the gym",
     [call("add_asset", category="road_barrier", count=3, location=at("gym"))], refused(),
     tags=("impossible",), notes="the campus has no gym")

# --------------------------------------------------------------------------------------- removal
R = "removal"
case(R, "direct", "remove_hydrant", "Remove the fire hydrant.",
     [call("remove_assets", assets=["fire_hydrant_1"])], [gone("fire_hydrant_1"), keep(assets=["fire_hydrant_1"])])
case(R, "direct", "remove_all_trees", "Remove all the trees.",
     [call("remove_assets", category="tree")], [count("tree", 0, 0), keep("tree")])
case(R, "direct", "remove_suv_lot_b", "Delete the SUV in parking lot B.",
     [call("remove_assets", assets=["suv_1"])], [gone("suv_1"), keep(assets=["suv_1"])])
case(R, "direct", "two_lights_near_bus_stop", "Remove the two street lights nearest the bus stop.",
     [call("remove_assets", category="street_light", near="bus stop", count=2)],
     [gone("street_light_4", "street_light_5"), keep(assets=["street_light_4", "street_light_5"])])
case(R, "direct", "remove_all_cones", "Remove all traffic cones.",
     [call("remove_assets", category="traffic_cone")], [count("traffic_cone", 0, 0), keep("traffic_cone")],
     setup=[CONES_AT_LOT_B])
case(R, "direct", "tree_next_to_library", "Remove the tree next to the Library.",
     [call("remove_assets", assets=["tree_1"])], [gone("tree_1"), keep(assets=["tree_1"])])
case(R, "direct", "remove_stop_sign", "Remove the stop sign.",
     [call("remove_assets", category="stop_sign")], [gone("stop_sign_1"), keep(assets=["stop_sign_1"])])
case(R, "direct", "remove_car_2", "Remove passenger_car_2.",
     [call("remove_assets", assets=["passenger_car_2"])], [gone("passenger_car_2"), keep(assets=["passenger_car_2"])])
case(R, "direct", "hydrant_and_bin", "Remove the fire hydrant and the trash bin.",
     [call("remove_assets", assets=["fire_hydrant_1", "trash_bin_1"])],
     [gone("fire_hydrant_1", "trash_bin_1"), keep(assets=["fire_hydrant_1", "trash_bin_1"])], tags=("compound",))
case(R, "direct", "impossible_remove_ego", "Remove the ego vehicle.",
     [call("remove_assets", assets=["ego"])], refused(), tags=("impossible",))

case(R, "indirect", "no_longer_want_cones", "I no longer want the cones.",
     [call("remove_assets", category="traffic_cone")], [count("traffic_cone", 0, 0), keep("traffic_cone")],
     setup=[CONES_AT_LOT_B])
case(R, "indirect", "bench_in_the_way",
     "The bench by the bus stop is in the way of our sensor rig; could you take it out?",
     [call("remove_assets", assets=["bench_1"])], [gone("bench_1"), keep(assets=["bench_1"])])
case(R, "indirect", "empty_lot_b", "We're testing in an empty parking lot, so the vehicles in lot B have to go.",
     [call("remove_assets", assets=LOT_B_VEHICLES)], [gone(*LOT_B_VEHICLES), keep(assets=LOT_B_VEHICLES)])
case(R, "indirect", "quad_without_trees", "I'd like the quad without trees.",
     [call("remove_assets", assets=["tree_2", "tree_3"])], [gone("tree_2"), keep(assets=["tree_2", "tree_3"])])
case(R, "indirect", "cleaner_without_bin", "It would look cleaner without the trash bin on Main Street.",
     [call("remove_assets", assets=["trash_bin_1"])], [gone("trash_bin_1"), keep(assets=["trash_bin_1"])])
case(R, "indirect", "shuttle_blocks_camera", "The shuttle blocks the camera view - get rid of it.",
     [call("remove_assets", category="bus")], [count("bus", 0, 0), keep("bus")], setup=[BUS_AHEAD])
case(R, "indirect", "dark_lamps_near_ego",
     "For a night test without lighting nearby, please remove the lamp posts within 20 m of the ego.",
     [call("remove_assets", assets=["street_light_2", "street_light_3"])],
     [gone("street_light_2", "street_light_3"), keep(assets=["street_light_2", "street_light_3"])])
case(R, "indirect", "keep_just_two_people", "Fewer people at the crosswalk please - keep just two.",
     [call("remove_assets", category="pedestrian", count=3)], [count("pedestrian", 2, 2), keep("pedestrian")],
     setup=[CROWD_AT_CROSSWALK])
case(R, "indirect", "impossible_bus_at_stop", "The bus at the stop is distracting, please delete it.",
     [call("remove_assets", category="bus")], refused(), tags=("impossible",), notes="there is no bus")

case(R, "vague", "no_more_cones", "no more cones",
     [call("remove_assets", category="traffic_cone")], [count("traffic_cone", 0, 0), keep("traffic_cone")],
     setup=[CONES_AT_LOT_B])
case(R, "vague", "fewer_trees", "fewer trees",
     [call("remove_assets", category="tree", count=2)], [delta("tree", -3, -1), keep("tree")])
case(R, "vague", "rid_of_parked_cars", "get rid of the parked cars",
     [call("remove_assets", category="passenger_car")],
     [count("passenger_car", 0, 0), keep("passenger_car", "suv")])
case(R, "vague", "clear_the_road", "clear the road",
     [call("remove_assets", category="traffic_cone"), call("remove_assets", category="cement_rubble")],
     [count("traffic_cone", 0, 0), count("cement_rubble", 0, 0), keep("traffic_cone", "cement_rubble")],
     setup=[CONES_WESTBOUND, RUBBLE_ON_CAMPUS])
case(R, "vague", "lose_hydrant", "lose the hydrant",
     [call("remove_assets", category="fire_hydrant")], [gone("fire_hydrant_1"), keep(assets=["fire_hydrant_1"])])
case(R, "vague", "too_many_people", "too many people",
     [call("remove_assets", category="pedestrian", count=3)], [delta("pedestrian", -5, -1), keep("pedestrian")],
     setup=[CROWD_AT_CROSSWALK])
case(R, "vague", "bin_gone", "the bin. gone.",
     [call("remove_assets", category="trash_bin")], [gone("trash_bin_1"), keep(assets=["trash_bin_1"])])
case(R, "vague", "barriers_and_bench", "barriers out, bench too",
     [call("remove_assets", category="road_barrier"), call("remove_assets", assets=["bench_1"])],
     [count("road_barrier", 0, 0), gone("bench_1"), keep("road_barrier", assets=["bench_1"])],
     setup=[BARRIERS_AT_GATE], tags=("compound",))
case(R, "vague", "impossible_no_more_trucks", "no more trucks",
     [call("remove_assets", category="truck")], refused(), tags=("impossible",), notes="there is no truck")

case(R, "erroneous", "fire_hydrent", "remove the fire hydrent",
     [call("remove_assets", category="fire_hydrant")], [gone("fire_hydrant_1"), keep(assets=["fire_hydrant_1"])])
case(R, "erroneous", "delet_all_tree", "delet all tree",
     [call("remove_assets", category="tree")], [count("tree", 0, 0), keep("tree")])
case(R, "erroneous", "remove_cones_pls", "remove cone's pls",
     [call("remove_assets", category="traffic_cone")], [count("traffic_cone", 0, 0), keep("traffic_cone")],
     setup=[CONES_AT_LOT_B])
case(R, "erroneous", "suv_from_parkinglot", "take away the suv from parkinglot B",
     [call("remove_assets", assets=["suv_1"])], [gone("suv_1"), keep(assets=["suv_1"])])
case(R, "erroneous", "dont_want_bench", "i dont want anymore the bench",
     [call("remove_assets", assets=["bench_1"])], [gone("bench_1"), keep(assets=["bench_1"])])
case(R, "erroneous", "stop_sing", "remove stop sing",
     [call("remove_assets", category="stop_sign")], [gone("stop_sign_1"), keep(assets=["stop_sign_1"])])
case(R, "erroneous", "remov_2_lamp_post", "remov 2 lamp post nearest bus stop",
     [call("remove_assets", category="street_light", near="bus stop", count=2)],
     [gone("street_light_4", "street_light_5"), keep(assets=["street_light_4", "street_light_5"])])
case(R, "erroneous", "rid_of_pedestrain", "get rid of pedestrain",
     [call("remove_assets", category="pedestrian")], [count("pedestrian", 0, 0), keep("pedestrian")],
     setup=[CROWD_AT_CROSSWALK])
case(R, "erroneous", "impossible_helicoptr", "remove the helicoptr",
     [call("remove_assets", category="helicopter")], refused(), tags=("impossible",))

# ------------------------------------------------------------------------------------ positioning
P = "positioning"
case(P, "direct", "bench_front_of_library", "Put the bench in front of the Library entrance.",
     [call("place_asset", asset="bench_1", location=at("Library entrance", "in_front_of"))],
     [near("Library entrance", 6, asset="bench_1"), keep(assets=["bench_1"])])
case(P, "direct", "ego_into_westbound", "Place the ego vehicle in main_westbound.",
     [call("place_asset", asset="ego", location=at("main_westbound", "in_lane"))],
     [{"kind": "in_lane", "asset": "ego", "lane": "main_westbound", "aligned": True}, keep(assets=["ego"])])
case(P, "direct", "car_1_to_lot_a", "Move passenger_car_1 to parking lot A.",
     [call("place_asset", asset="passenger_car_1", location=at("parking lot A"))],
     [near("parking lot A", 1, asset="passenger_car_1"), keep(assets=["passenger_car_1"])])
case(P, "direct", "bin_next_to_fountain", "Put the trash bin next to the fountain.",
     [call("place_asset", asset="trash_bin_1", location=at("fountain", "next_to"))],
     [near("fountain", 5, asset="trash_bin_1"), keep(assets=["trash_bin_1"])])
case(P, "direct", "suv_10m_behind_ego", "Place the SUV 10 m behind the ego along its lane.",
     [call("place_asset", asset="suv_1", location=at("ego", "behind", along_m=-10))],
     [{"kind": "relative", "asset": "suv_1", "relation": "behind", "target": "ego", "max_distance": 14,
       "tolerance_deg": 30}, {"kind": "in_lane", "asset": "suv_1", "lane": "main_eastbound"},
      keep(assets=["suv_1"])])
case(P, "direct", "hydrant_exact_xy", "Put the fire hydrant at x=20, y=-5.5.",
     [call("place_asset", asset="fire_hydrant_1", location=xy(20, -5.5))],
     [near_point(20, -5.5, 0.5, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])])
case(P, "direct", "stop_sign_sidewalk_jtekt", "Put the stop sign on the sidewalk near the JTEKT building entrance.",
     [call("place_asset", asset="stop_sign_1", location=at("JTEKT building entrance", "on_sidewalk"))],
     [{"kind": "on_surface", "asset": "stop_sign_1", "surfaces": ["sidewalk"]},
      near("JTEKT building entrance", 12, asset="stop_sign_1"), keep(assets=["stop_sign_1"])])
case(P, "direct", "tree_left_of_engineering", "Put tree_4 to the left of the Engineering Hall entrance.",
     [call("place_asset", asset="tree_4", location=at("Engineering Hall entrance", "left_of"))],
     [{"kind": "relative", "asset": "tree_4", "relation": "left_of", "target": "Engineering Hall entrance",
       "max_distance": 15}, keep(assets=["tree_4"])])
case(P, "direct", "bench_fountain_bin_bus_stop", "Put the bench at the fountain and the trash bin at the bus stop.",
     [call("place_asset", asset="bench_1", location=at("fountain")),
      call("place_asset", asset="trash_bin_1", location=at("bus stop"))],
     [near("fountain", 6, asset="bench_1"), near("bus stop", 4, asset="trash_bin_1"),
      {"kind": "moved", "asset": "bench_1", "min_distance": 5},
      keep(assets=["bench_1", "trash_bin_1"])], tags=("compound",))
case(P, "direct", "impossible_bench_in_jtekt", "Put the bench inside the JTEKT Building.",
     [call("place_asset", asset="bench_1", location=xy(37, 30))], refused(), tags=("impossible",))

case(P, "indirect", "suv_behind_us_cut_in", "For a cut-in test the SUV should start just behind us in our lane.",
     [call("place_asset", asset="suv_1", location=at("ego", "behind", along_m=-12))],
     [{"kind": "relative", "asset": "suv_1", "relation": "behind", "target": "ego", "max_distance": 30,
       "tolerance_deg": 30}, {"kind": "in_lane", "asset": "suv_1", "lane": "main_eastbound"},
      keep(assets=["suv_1"])])
case(P, "indirect", "bench_by_the_quad", "I'd like people to sit by the water - put the bench right next to the quad fountain.",
     [call("place_asset", asset="bench_1", location=at("fountain", "next_to"))],
     [near("fountain", 6, asset="bench_1"), keep(assets=["bench_1"])])
case(P, "indirect", "hydrant_sidewalk_lot_b",
     "The hydrant would look more realistic on the sidewalk by lot B's entrance.",
     [call("place_asset", asset="fire_hydrant_1", location=at("parking lot B entrance", "on_sidewalk"))],
     [{"kind": "on_surface", "asset": "fire_hydrant_1", "surfaces": ["sidewalk"]},
      near("parking lot B entrance", 10, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])])
case(P, "indirect", "ego_starts_at_gate", "We need the ego to start the run from the main gate.",
     [call("place_asset", asset="ego", location=at("main gate"))],
     [near("main gate", 8, asset="ego"), keep(assets=["ego"])])
case(P, "indirect", "second_car_in_lot_a", "Could the second car go in lot A instead?",
     [call("place_asset", asset="passenger_car_2", location=at("parking lot A"))],
     [near("parking lot A", 1, asset="passenger_car_2"), keep(assets=["passenger_car_2"])])
case(P, "indirect", "stop_sign_visible_north", "It would be easier to see the stop sign if it stood at the north crosswalk.",
     [call("place_asset", asset="stop_sign_1", location=at("north crosswalk"))],
     [near("north crosswalk", 8, asset="stop_sign_1"), keep(assets=["stop_sign_1"])])
case(P, "indirect", "bin_5m_ahead_right_sidewalk",
     "Our lidar test needs the trash bin 5 m ahead of the ego on the right-hand sidewalk.",
     [call("place_asset", asset="trash_bin_1", location=xy(-55, -5.5))],
     [{"kind": "on_surface", "asset": "trash_bin_1", "surfaces": ["sidewalk"]},
      near_point(-55, -5.5, 4, asset="trash_bin_1"), keep(assets=["trash_bin_1"])])
case(P, "indirect", "ego_to_lot_b_entrance", "The run should begin at the lot B entrance, so take the ego there.",
     [call("place_asset", asset="ego", location=at("parking lot B entrance"))],
     [near("parking lot B entrance", 8, asset="ego"), keep(assets=["ego"])])
case(P, "indirect", "impossible_stadium_car_park", "Please put the SUV at the stadium car park.",
     [call("place_asset", asset="suv_1", location=at("stadium car park"))], refused(), tags=("impossible",))

case(P, "vague", "bench_by_library", "bench over by the library",
     [call("place_asset", asset="bench_1", location=at("Library entrance", "in_front_of"))],
     [near("Library entrance", 10, asset="bench_1"), keep(assets=["bench_1"])])
case(P, "vague", "car_2_lot_a", "car 2 -> lot A",
     [call("place_asset", asset="passenger_car_2", location=at("parking lot A"))],
     [near("parking lot A", 1, asset="passenger_car_2"), keep(assets=["passenger_car_2"])])
case(P, "vague", "ego_at_the_gate", "ego at the gate",
     [call("place_asset", asset="ego", location=at("main gate"))],
     [keep(assets=["ego"])], alternatives=[[near("main gate", 8, asset="ego")], [near("east gate", 8, asset="ego")]])
case(P, "vague", "hydrant_sidewalk_somewhere", "hydrant on a sidewalk somewhere near lot B entrance",
     [call("place_asset", asset="fire_hydrant_1", location=at("parking lot B entrance", "on_sidewalk"))],
     [{"kind": "on_surface", "asset": "fire_hydrant_1", "surfaces": ["sidewalk"]},
      near("parking lot B entrance", 15, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])])
case(P, "vague", "suv_behind_us", "the SUV behind us",
     [call("place_asset", asset="suv_1", location=at("ego", "behind"))],
     [{"kind": "relative", "asset": "suv_1", "relation": "behind", "target": "ego", "max_distance": 30},
      keep(assets=["suv_1"])])
case(P, "vague", "tree_1_at_fountain", "tree_1 over at the fountain",
     [call("place_asset", asset="tree_1", location=at("fountain"))],
     [near("fountain", 8, asset="tree_1"), keep(assets=["tree_1"])])
case(P, "vague", "bin_by_stop_sign", "bin by the stop sign",
     [call("place_asset", asset="trash_bin_1", location=at("stop_sign_1", "next_to"))],
     [near("stop_sign_1", 3, asset="trash_bin_1"), keep(assets=["trash_bin_1"])])
case(P, "vague", "bench_gate_bin_union", "bench -> main gate, bin -> union",
     [call("place_asset", asset="bench_1", location=at("main gate")),
      call("place_asset", asset="trash_bin_1", location=at("Student Union entrance"))],
     [near("main gate", 8, asset="bench_1"), near("Student Union entrance", 8, asset="trash_bin_1"),
      keep(assets=["bench_1", "trash_bin_1"])], tags=("compound",))
case(P, "vague", "impossible_bench_moon", "bench on the moon",
     [call("place_asset", asset="bench_1", location=at("moon"))], refused(), tags=("impossible",))

case(P, "erroneous", "bench_infront_libary", "put bench infront the libary entrance",
     [call("place_asset", asset="bench_1", location=at("Library entrance", "in_front_of"))],
     [near("Library entrance", 6, asset="bench_1"), keep(assets=["bench_1"])])
case(P, "erroneous", "ego_westbound_lain", "place ego in westbound lain",
     [call("place_asset", asset="ego", location=at("main_westbound", "in_lane"))],
     [{"kind": "in_lane", "asset": "ego", "lane": "main_westbound"}, keep(assets=["ego"])])
case(P, "erroneous", "car_one_parking_a", "move car one to parking A",
     [call("place_asset", asset="passenger_car_1", location=at("parking lot A"))],
     [near("parking lot A", 1, asset="passenger_car_1"), keep(assets=["passenger_car_1"])])
case(P, "erroneous", "hydrant_x_y", "hydrant put on x 20 y -5.5",
     [call("place_asset", asset="fire_hydrant_1", location=xy(20, -5.5))],
     [near_point(20, -5.5, 0.5, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])])
case(P, "erroneous", "suv_behind_ego_10_meter", "suv go behind ego 10 meter",
     [call("place_asset", asset="suv_1", location=at("ego", "behind", along_m=-10))],
     [{"kind": "relative", "asset": "suv_1", "relation": "behind", "target": "ego", "max_distance": 16,
       "tolerance_deg": 30}, keep(assets=["suv_1"])])
case(P, "erroneous", "bin_next_fontain", "put the bin next fontain",
     [call("place_asset", asset="trash_bin_1", location=at("fountain", "next_to"))],
     [near("fountain", 5, asset="trash_bin_1"), keep(assets=["trash_bin_1"])])
case(P, "erroneous", "stop_sign_jtekt_entrence", "stop sign put on sidewalk near JTEKT entrence",
     [call("place_asset", asset="stop_sign_1", location=at("JTEKT building entrance", "on_sidewalk"))],
     [{"kind": "on_surface", "asset": "stop_sign_1", "surfaces": ["sidewalk"]},
      near("JTEKT building entrance", 12, asset="stop_sign_1"), keep(assets=["stop_sign_1"])])
case(P, "erroneous", "tree_4_lot_b", "tree 4 placing at lot B please",
     [call("place_asset", asset="tree_4", location=at("parking lot B"))],
     [near("parking lot B", 1, asset="tree_4"), keep(assets=["tree_4"])])
case(P, "erroneous", "impossible_bench_x500", "put bench at x=500 y=0",
     [call("place_asset", asset="bench_1", location=xy(500, 0))], refused(), tags=("impossible",))

# ---------------------------------------------------------------------------------------- moving
M = "moving"
case(M, "direct", "ego_forward_10", "Move the ego forward 10 m.",
     [call("move_asset", asset="ego", forward=10)],
     [moved("ego", 9, 11, direction="forward"), keep(assets=["ego"])])
case(M, "direct", "suv_forward_5", "Move the SUV 5 m forward.",
     [call("move_asset", asset="suv_1", forward=5)],
     [moved("suv_1", 4.5, 5.5, direction="forward"), keep(assets=["suv_1"])])
case(M, "direct", "car_2_right_3", "Move passenger_car_2 3 m to the right.",
     [call("move_asset", asset="passenger_car_2", left=-3)],
     [moved("passenger_car_2", 2.5, 3.5, direction="right"), keep(assets=["passenger_car_2"])])
case(M, "direct", "turn_bench_90", "Turn the bench 90 degrees.",
     [call("move_asset", asset="bench_1", turn_deg=90)],
     [moved("bench_1", 0, 0.5, turn_min_deg=80, turn_max_deg=100), keep(assets=["bench_1"])])
case(M, "direct", "lot_b_vehicles_north_4", "Move every vehicle in lot B 4 m north.",
     [call("move_asset", assets=LOT_B_VEHICLES, north=4)],
     [*[moved(a, 3.5, 4.5, direction="forward") for a in LOT_B_VEHICLES], keep(assets=LOT_B_VEHICLES)])
case(M, "direct", "suv_drive_westbound", "Make the SUV drive in main_westbound at 5 m/s.",
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_westbound", "speed": 5})],
     [{"kind": "behaviour", "asset": "suv_1", "behaviour": "drive_lane", "lane": "main_westbound",
       "speed_min": 4.5, "speed_max": 5.5}, keep(assets=["suv_1"])])
case(M, "direct", "truck_8m_ahead", "Put the truck 8 m ahead of the ego along its lane.",
     [call("move_asset", asset="truck_1", relative_to="ego", along_m=8)],
     [{"kind": "relative", "asset": "truck_1", "relation": "in_front_of", "target": "ego", "max_distance": 16,
       "tolerance_deg": 30}, {"kind": "in_lane", "asset": "truck_1", "lane": "main_eastbound"},
      keep(assets=["truck_1"])], setup=[TRUCK_IN_LANE])
case(M, "direct", "hydrant_east_2", "Move the fire hydrant 2 m east.",
     [call("move_asset", asset="fire_hydrant_1", east=2)],
     [moved("fire_hydrant_1", 1.5, 2.5, direction="forward"), keep(assets=["fire_hydrant_1"])])
case(M, "direct", "suv_forward_bench_turn", "Move the SUV 5 m forward and turn the bench around.",
     [call("move_asset", asset="suv_1", forward=5), call("move_asset", asset="bench_1", turn_deg=180)],
     [moved("suv_1", 4.5, 5.5, direction="forward"), moved("bench_1", 0, 0.5, turn_min_deg=160),
      keep(assets=["suv_1", "bench_1"])], tags=("compound",))
case(M, "direct", "impossible_ego_500m", "Move the ego 500 m forward.",
     [call("move_asset", asset="ego", forward=500)], refused(), tags=("impossible",))

case(M, "indirect", "pull_ego_back_5", "Could you pull the ego back about 5 metres so the sensors see the whole crossing?",
     [call("move_asset", asset="ego", forward=-5)],
     [moved("ego", 4, 6, direction="backward"), keep(assets=["ego"])])
case(M, "indirect", "lot_b_toward_main_street", "I'd like the vehicles in lot B to move up 4 m toward Main Street.",
     [call("move_asset", assets=LOT_B_VEHICLES, north=4)],
     [*[moved(a, 3, 5, direction="forward") for a in LOT_B_VEHICLES], keep(assets=LOT_B_VEHICLES)])
case(M, "indirect", "suv_circles_lot_b", "For the turning test, have the SUV drive circles in lot B.",
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "centre": "parking lot B", "radius": 8})],
     [{"kind": "behaviour", "asset": "suv_1", "behaviour": "circle", "centre_near": "parking lot B"},
      keep(assets=["suv_1"])])
case(M, "indirect", "second_car_drives_north",
     "It'd be more realistic if the second car drove off north along Campus Drive.",
     [call("set_behaviour", asset="passenger_car_2",
           behaviour={"kind": "drive_lane", "lane": "campus_northbound"})],
     [{"kind": "behaviour", "asset": "passenger_car_2", "behaviour": "drive_lane", "lane": "campus_northbound"},
      keep(assets=["passenger_car_2"])])
case(M, "indirect", "ego_facing_other_way", "We want the ego facing the other way for the return leg.",
     [call("move_asset", asset="ego", turn_deg=180)],
     [moved("ego", 0, 3, turn_min_deg=160), keep(assets=["ego"])])
case(M, "indirect", "bench_off_sidewalk",
     "Since the bench sticks into the walkway, slide it 1.5 m further south onto the grass.",
     [call("move_asset", asset="bench_1", north=-1.5)],
     [moved("bench_1", 1, 2, direction="left"), keep(assets=["bench_1"])])
case(M, "indirect", "truck_closer_15m", "The truck is too far from us; bring it to 15 m ahead of the ego.",
     [call("move_asset", asset="truck_1", relative_to="ego", along_m=15)],
     [{"kind": "relative", "asset": "truck_1", "relation": "in_front_of", "target": "ego", "max_distance": 22,
       "tolerance_deg": 30}, {"kind": "in_lane", "asset": "truck_1", "lane": "main_eastbound"},
      keep(assets=["truck_1"])], setup=[TRUCK_IN_LANE])
case(M, "indirect", "car_1_follows_eastbound",
     "We're testing following distance, so have passenger_car_1 drive in the eastbound lane at 8 m/s.",
     [call("set_behaviour", asset="passenger_car_1",
           behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 8})],
     [{"kind": "behaviour", "asset": "passenger_car_1", "behaviour": "drive_lane", "lane": "main_eastbound",
       "speed_min": 7.5, "speed_max": 8.5}, keep(assets=["passenger_car_1"])])
case(M, "indirect", "impossible_move_library", "Please move the library 10 m north, it's too close to the road.",
     [call("move_asset", asset="library", north=10)], refused(), tags=("impossible",))

case(M, "vague", "ego_bit_forward", "ego a bit forward",
     [call("move_asset", asset="ego", forward=3)], [moved("ego", 0.5, 10, direction="forward"), keep(assets=["ego"])])
case(M, "vague", "lot_b_4m_north", "lot B vehicles, 4 m north",
     [call("move_asset", assets=LOT_B_VEHICLES, north=4)],
     [*[moved(a, 3.5, 4.5, direction="forward") for a in LOT_B_VEHICLES], keep(assets=LOT_B_VEHICLES)])
case(M, "vague", "suv_round_lot_b", "suv round and round in lot B",
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "centre": "parking lot B", "radius": 8})],
     [{"kind": "behaviour", "asset": "suv_1", "behaviour": "circle", "centre_near": "parking lot B"},
      keep(assets=["suv_1"])])
case(M, "vague", "nudge_hydrant", "nudge the hydrant",
     [call("move_asset", asset="fire_hydrant_1", east=1)], [moved("fire_hydrant_1", 0.2, 5),
                                                            keep(assets=["fire_hydrant_1"])])
case(M, "vague", "bench_around", "turn the bench around",
     [call("move_asset", asset="bench_1", turn_deg=180)],
     [moved("bench_1", 0, 1, turn_min_deg=150), keep(assets=["bench_1"])])
case(M, "vague", "car_2_driving", "car 2 - driving",
     [call("set_behaviour", asset="passenger_car_2", behaviour={"kind": "drive_lane"})],
     [{"kind": "behaviour", "asset": "passenger_car_2", "behaviour": ["drive_lane", "follow_path", "circle"]},
      keep(assets=["passenger_car_2"])])
case(M, "vague", "suv_back_a_bit", "the SUV back a bit",
     [call("move_asset", asset="suv_1", forward=-2)],
     [moved("suv_1", 0.5, 6, direction="backward"), keep(assets=["suv_1"])])
case(M, "vague", "quad_trees_west", "trees at the quad, 5 m west",
     [call("move_asset", assets=["tree_2", "tree_3"], east=-5)],
     [moved("tree_2", 4, 6, direction="backward"), keep(assets=["tree_2", "tree_3"])])
case(M, "vague", "impossible_ego_1e3", "ego 1e3 m forward",
     [call("move_asset", asset="ego", forward=1000)], refused(), tags=("impossible",))

case(M, "erroneous", "ego_foward_10_meter", "move ego foward 10 meter",
     [call("move_asset", asset="ego", forward=10)],
     [moved("ego", 9, 11, direction="forward"), keep(assets=["ego"])])
case(M, "erroneous", "suv_5m_forwad", "suv go 5m forwad",
     [call("move_asset", asset="suv_1", forward=5)],
     [moved("suv_1", 4.5, 5.5, direction="forward"), keep(assets=["suv_1"])])
case(M, "erroneous", "bench_ninety_degree", "turn bench ninety degree",
     [call("move_asset", asset="bench_1", turn_deg=90)],
     [moved("bench_1", 0, 0.5, turn_min_deg=80, turn_max_deg=100), keep(assets=["bench_1"])])
case(M, "erroneous", "all_car_lot_b_north", "move all car in lot B 4m to north",
     [call("move_asset", assets=LOT_B_VEHICLES, north=4)],
     [*[moved(a, 3.5, 4.5, direction="forward") for a in ["passenger_car_1", "passenger_car_2"]],
      keep(assets=LOT_B_VEHICLES)])
case(M, "erroneous", "suv_drive_westbound_lane", "make suv drive westbound lane 5 m/s",
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_westbound", "speed": 5})],
     [{"kind": "behaviour", "asset": "suv_1", "behaviour": "drive_lane", "lane": "main_westbound",
       "speed_min": 4.5, "speed_max": 5.5}, keep(assets=["suv_1"])])
case(M, "erroneous", "hydrant_2m_east_side", "move hydrant 2m east side",
     [call("move_asset", asset="fire_hydrant_1", east=2)],
     [moved("fire_hydrant_1", 1.5, 2.5, direction="forward"), keep(assets=["fire_hydrant_1"])])
case(M, "erroneous", "car_2_to_right", "car 2 move to right 3 meters",
     [call("move_asset", asset="passenger_car_2", left=-3)],
     [moved("passenger_car_2", 2.5, 3.5, direction="right"), keep(assets=["passenger_car_2"])])
case(M, "erroneous", "suv_circling_parkinglot", "let the suv circling in parkinglot b",
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "centre": "parking lot B", "radius": 8})],
     [{"kind": "behaviour", "asset": "suv_1", "behaviour": "circle", "centre_near": "parking lot B"},
      keep(assets=["suv_1"])])
case(M, "erroneous", "impossible_move_libary", "move the libary 10m north",
     [call("move_asset", asset="library", north=10)], refused(), tags=("impossible",))

# ----------------------------------------------------------------------------------- arrangement
G = "arrangement"


def line(category: str | list[str], n: int, **more: Any) -> Json:
    return {"kind": "arrangement", "category": category, "shape": "line", "min_count": n, **more}


def ring(category: str | list[str], n: int, around: str, **more: Any) -> Json:
    return {"kind": "arrangement", "category": category, "shape": "ring", "around": around, "min_count": n, **more}


case(G, "direct", "six_cones_line_ahead", "Arrange 6 traffic cones in a line in front of the ego.",
     [call("arrange_assets", categories=["traffic_cone"], shape="line", count=6,
           location=at("ego", "in_front_of", distance=15), heading_deg=0)],
     [delta("traffic_cone", 6), line("traffic_cone", 6), near("ego", 40, category="traffic_cone", require_all=True),
      keep("traffic_cone")])
case(G, "direct", "cone_ring_crossroads", "Put 8 cones in a ring of radius 5 m around the middle of the crossroads.",
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=8, location=at("main intersection"), radius=5)],
     [delta("traffic_cone", 8), ring("traffic_cone", 8, "main intersection"), near_point(0, 0, 7, category="traffic_cone",
                                                                          require_all=True), keep("traffic_cone")])
case(G, "direct", "barriers_lane_edge", "Line the edge of main_eastbound with 5 road barriers near the Library.",
     [call("arrange_assets", categories=["road_barrier"], shape="lane_edge", count=5,
           location=at("Library entrance", "in_lane"))],
     [delta("road_barrier", 5), line("road_barrier", 5),
      {"kind": "in_lane", "category": "road_barrier", "lane": "main_eastbound"},
      near("Library entrance", 30, category="road_barrier", require_all=True), keep("road_barrier")])
case(G, "direct", "four_cars_row_lot_a", "Park 4 cars in a row in parking lot A.",
     [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4, location=at("parking lot A"))],
     [delta("passenger_car", 4), line("passenger_car", 4), near("parking lot A", 1, category="passenger_car",
                                                                require_all=True), keep("passenger_car")])
case(G, "direct", "close_westbound_cones", "Close main_westbound with cones starting at x=20, y=1.75.",
     [call("close_lane", lane="main_westbound", at_x=20, at_y=1.75)],
     [delta("traffic_cone", 2, 20), near_point(20, 1.75, 20, category="traffic_cone", require_all=True),
      {"kind": "in_lane", "category": "traffic_cone", "lane": "main_westbound", "min_count": 2,
       "require_all": False}, keep("traffic_cone")])
case(G, "direct", "tree_grid_lot_a", "Place 6 trees in a grid with 3 columns in parking lot A.",
     [call("arrange_assets", categories=["tree"], shape="grid", count=6, columns=3, location=at("parking lot A"))],
     [delta("tree", 6), near("parking lot A", 3, category="tree", require_all=True), keep("tree")])
case(G, "direct", "bollards_2m_apart", "Arrange 5 bollards in a line at the JTEKT building entrance, 2 m apart.",
     [call("arrange_assets", categories=["bollard"], shape="line", count=5, spacing=2,
           location=at("JTEKT building entrance"))],
     [delta("bollard", 5), line("bollard", 5, spacing_min=1.7, spacing_max=2.3),
      near("JTEKT building entrance", 12, category="bollard", require_all=True), keep("bollard")])
case(G, "direct", "pedestrian_ring_bus_stop", "Put a ring of 6 pedestrians around the bus stop.",
     [call("arrange_assets", categories=["pedestrian"], shape="ring", count=6, location=at("bus stop"), radius=3)],
     [delta("pedestrian", 6), ring("pedestrian", 6, "bus stop"), keep("pedestrian")])
case(G, "direct", "cone_line_and_dusk", "Set up a line of 5 cones in front of the ego and make it dusk.",
     [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5,
           location=at("ego", "in_front_of", distance=15), heading_deg=0),
      call("set_time_of_day", time="dusk")],
     [delta("traffic_cone", 5), line("traffic_cone", 5), env(time_from="17:30", time_to="20:30"),
      keep("traffic_cone", environment=True)], tags=("compound",))
case(G, "direct", "impossible_150_cone_line", "Arrange 150 cones in a line along Main Street.",
     [call("arrange_assets", categories=["traffic_cone"], shape="line", count=150, location=at("main_eastbound"))],
     refused(), tags=("impossible",))

case(G, "indirect", "close_northbound_from_south_crossing",
     "For the next run I need the northbound lane of Campus Drive closed off with cones, starting at the south crosswalk.",
     [call("close_lane", lane="campus_northbound", at_x=1.75, at_y=-12)],
     [delta("traffic_cone", 2, 20), near_point(1.75, -12, 25, category="traffic_cone", require_all=True),
      {"kind": "in_lane", "category": "traffic_cone", "lane": "campus_northbound", "min_count": 2,
       "require_all": False}, keep("traffic_cone")])
case(G, "indirect", "busy_lot_b_row", "We're simulating a busy car park: could you add a row of 5 parked cars in lot B?",
     [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=5, location=at("parking lot B"))],
     [delta(["passenger_car", "suv"], 5), line(["passenger_car", "suv"], 5, scope="added"),
      near("parking lot B", 1, category=["passenger_car", "suv"], scope="added", require_all=True),
      keep("passenger_car", "suv")])
case(G, "indirect", "barrier_fence_near_gate",
     "I'd like a line of barriers along the eastbound lane edge near the main gate, to stop cars drifting.",
     [call("arrange_assets", categories=["road_barrier"], shape="lane_edge", count=5, location=at("main gate", "in_lane"))],
     [delta("road_barrier", 3, 20), line("road_barrier", 3), near("main gate", 30, category="road_barrier",
                                                                  require_all=True), keep("road_barrier")])
case(G, "indirect", "slalom_cones_4m", "For a slalom test, set up 8 cones in a straight line 4 m apart ahead of the ego.",
     [call("arrange_assets", categories=["traffic_cone"], shape="line", count=8, spacing=4,
           location=at("ego", "in_front_of", distance=25), heading_deg=0)],
     [delta("traffic_cone", 8), line("traffic_cone", 8, spacing_min=3.5, spacing_max=4.5),
      near("ego", 45, category="traffic_cone", require_all=True), keep("traffic_cone")])
case(G, "indirect", "protect_fountain_bollards", "The fountain needs protecting, so surround it with bollards.",
     [call("arrange_assets", categories=["bollard"], shape="ring", count=8, location=at("fountain"), radius=4)],
     [delta("bollard", 4, 40), ring("bollard", 4, "fountain"), keep("bollard")])
case(G, "indirect", "mixed_row_lot_a", "Our camera team wants cars and SUVs parked side by side in lot A, six in all.",
     [call("arrange_assets", categories=["passenger_car", "suv"], shape="parking_row", count=6,
           location=at("parking lot A"))],
     [delta(["passenger_car", "suv"], 6), delta("suv", 1, 5), delta("passenger_car", 1, 5),
      line(["passenger_car", "suv"], 6), near("parking lot A", 1, category=["passenger_car", "suv"], require_all=True),
      keep("passenger_car", "suv")])
case(G, "indirect", "crowd_grid_union", "We're modelling a crowd leaving the Student Union: ten people in a grid outside it.",
     [call("arrange_assets", categories=["pedestrian"], shape="grid", count=10,
           location=at("Student Union entrance", "in_front_of", distance=8))],
     [delta("pedestrian", 10), near("Student Union entrance", 12, category="pedestrian", require_all=True),
      keep("pedestrian")])
case(G, "indirect", "bins_line_and_rain", "Because we're testing in bad weather by the union, line up 4 bins there and make it rain.",
     [call("arrange_assets", categories=["trash_bin"], shape="line", count=4, location=at("Student Union entrance")),
      call("set_weather", kind="rain")],
     [delta("trash_bin", 4), line("trash_bin", 4), near("Student Union entrance", 12, category="trash_bin",
                                                         require_all=True),
      env(weather=["rain"]), keep("trash_bin", environment=True)], tags=("compound",))
case(G, "indirect", "impossible_ring_stadium", "For the parade scene, please put 5 cones in a ring around the stadium.",
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=5, location=at("stadium"))],
     refused(), tags=("impossible",))

case(G, "vague", "cones_x4_lot_b_entr", "cones x4 lot B entr, in a line",
     [call("arrange_assets", categories=["traffic_cone"], shape="line", count=4, location=at("parking lot B entrance"))],
     [delta("traffic_cone", 4), line("traffic_cone", 4), near("parking lot B entrance", 12, category="traffic_cone",
                                                               require_all=True), keep("traffic_cone")])
case(G, "vague", "ring_cones_junction", "ring of cones round the junction",
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=8, location=at("main intersection"), radius=5)],
     [delta("traffic_cone", 4, 40), ring("traffic_cone", 4, "main intersection"), keep("traffic_cone")])
case(G, "vague", "row_parked_lot_a", "row of parked cars in lot A",
     [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4, location=at("parking lot A"))],
     [delta(["passenger_car", "suv"], 2, 30), line(["passenger_car", "suv"], 2),
      near("parking lot A", 1, category=["passenger_car", "suv"], require_all=True), keep("passenger_car", "suv")])
case(G, "vague", "slalom_ahead", "slalom cones ahead of us",
     [call("arrange_assets", categories=["traffic_cone"], shape="line", count=6, spacing=4,
           location=at("ego", "in_front_of", distance=20), heading_deg=0)],
     [delta("traffic_cone", 3, 30), line("traffic_cone", 3, tolerance=2.0),
      {"kind": "relative", "category": "traffic_cone", "relation": "in_front_of", "target": "ego",
       "max_distance": 60, "tolerance_deg": 30, "require_all": True}, keep("traffic_cone")])
case(G, "vague", "barriers_edge_by_gate", "barriers along the road edge by the gate",
     [call("arrange_assets", categories=["road_barrier"], shape="lane_edge", count=5, location=at("main gate", "in_lane"))],
     [delta("road_barrier", 2, 30), line("road_barrier", 2), keep("road_barrier")],
     alternatives=[[near("main gate", 30, category="road_barrier", require_all=True)],
                   [near("east gate", 30, category="road_barrier", require_all=True)]])
case(G, "vague", "bollards_line_jtekt", "some bollards in a line by JTEKT",
     [call("arrange_assets", categories=["bollard"], shape="line", count=5, location=at("JTEKT building entrance"))],
     [delta("bollard", 3, 30), line("bollard", 3), near("JTEKT building entrance", 15, category="bollard",
                                                        require_all=True), keep("bollard")])
case(G, "vague", "circle_people_bus_stop", "circle of people round the bus stop",
     [call("arrange_assets", categories=["pedestrian"], shape="ring", count=6, location=at("bus stop"), radius=3)],
     [delta("pedestrian", 3, 30), ring("pedestrian", 3, "bus stop"), keep("pedestrian")])
case(G, "vague", "close_westbound_east_gate", "close off the westbound lane near the east gate",
     [call("close_lane", lane="main_westbound", at_x=90, at_y=1.75)],
     [delta(["traffic_cone", "road_barrier"], 2, 30),
      near("east gate", 30, category=["traffic_cone", "road_barrier"], require_all=True),
      {"kind": "in_lane", "category": ["traffic_cone", "road_barrier"], "lane": "main_westbound", "min_count": 2,
       "require_all": False}, keep("traffic_cone", "road_barrier")])
case(G, "vague", "impossible_30_buses_grid", "grid of 30 buses in lot A",
     [call("arrange_assets", categories=["bus"], shape="grid", count=30, location=at("parking lot A"))],
     refused(), tags=("impossible",), notes="a scene holds at most 10 buses")

case(G, "erroneous", "arange_cone_line", "arange 6 cone in line front of ego",
     [call("arrange_assets", categories=["traffic_cone"], shape="line", count=6,
           location=at("ego", "in_front_of", distance=15), heading_deg=0)],
     [delta("traffic_cone", 6), line("traffic_cone", 6), near("ego", 40, category="traffic_cone", require_all=True),
      keep("traffic_cone")])
case(G, "erroneous", "cone_circle_intersection", "put 8 cone in circle around the intersection",
     [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=8, location=at("main intersection"), radius=5)],
     [delta("traffic_cone", 8), ring("traffic_cone", 8, "main intersection"), keep("traffic_cone")])
case(G, "erroneous", "park_car_row_lot_a", "park 4 car in row at lot A",
     [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4, location=at("parking lot A"))],
     [delta("passenger_car", 4), line("passenger_car", 4), near("parking lot A", 1, category="passenger_car",
                                                                require_all=True), keep("passenger_car")])
case(G, "erroneous", "close_west_bound", "close west bound lane with cone from x 20",
     [call("close_lane", lane="main_westbound", at_x=20, at_y=1.75)],
     [delta("traffic_cone", 2, 20), near_point(20, 1.75, 20, category="traffic_cone", require_all=True),
      {"kind": "in_lane", "category": "traffic_cone", "lane": "main_westbound", "min_count": 2,
       "require_all": False}, keep("traffic_cone")])
case(G, "erroneous", "barier_lane_edge", "make line of barier along eastbound lane edge near libary",
     [call("arrange_assets", categories=["road_barrier"], shape="lane_edge", count=5, location=at("Library entrance", "in_lane"))],
     [delta("road_barrier", 2, 30), line("road_barrier", 2),
      {"kind": "in_lane", "category": "road_barrier", "lane": "main_eastbound"}, keep("road_barrier")])
case(G, "erroneous", "bolards_2m", "bolards 5 in line at JTEKT entrence 2m apart",
     [call("arrange_assets", categories=["bollard"], shape="line", count=5, spacing=2,
           location=at("JTEKT building entrance"))],
     [delta("bollard", 5), line("bollard", 5, spacing_min=1.7, spacing_max=2.3), keep("bollard")])
case(G, "erroneous", "grid_tree_colum", "grid of tree 6 in parking lot A 3 colum",
     [call("arrange_assets", categories=["tree"], shape="grid", count=6, columns=3, location=at("parking lot A"))],
     [delta("tree", 6), near("parking lot A", 3, category="tree", require_all=True), keep("tree")])
case(G, "erroneous", "ring_people_bus_stop", "ring people around bus stop, 6 of them",
     [call("arrange_assets", categories=["pedestrian"], shape="ring", count=6, location=at("bus stop"), radius=3)],
     [delta("pedestrian", 6), ring("pedestrian", 6, "bus stop"), keep("pedestrian")])
case(G, "erroneous", "impossible_150_cone", "arrange 150 cone in line",
     [call("arrange_assets", categories=["traffic_cone"], shape="line", count=150, location=at("main_eastbound"))],
     refused(), tags=("impossible",))

# ------------------------------------------------------------------------------------ appearance
L = "appearance"
ENV = keep(environment=True)
case(L, "direct", "paint_suv_red", "Paint the SUV red.",
     [call("set_asset_appearance", assets=["suv_1"], colour="red")],
     [look("red", asset="suv_1"), keep(assets=["suv_1"])])
case(L, "direct", "heavy_rain", "Make it rain heavily.",
     [call("set_weather", kind="rain", intensity=0.9)], [env(weather=["rain"], intensity_min=0.75), ENV])
case(L, "direct", "time_1830", "Set the time to 18:30.",
     [call("set_time_of_day", time="18:30")], [env(time_from="18:25", time_to="18:35"), ENV])
case(L, "direct", "street_lights_on", "Turn the street lights on.",
     [call("set_lighting", street_lights="on")], [env(street_lights="on"), ENV])
case(L, "direct", "benches_wooden", "Make all the benches wooden.",
     [call("set_asset_appearance", category="bench", material="wood")],
     [look(material="wood", category="bench", require_all=True), keep("bench")])
case(L, "direct", "add_fog", "Add fog.", [call("set_weather", kind="fog")], [env(weather=["fog"], intensity_min=0.1), ENV])
case(L, "direct", "bus_yellow", "Make the bus yellow.",
     [call("set_asset_appearance", category="bus", colour="yellow")], [look("yellow", category="bus"), keep("bus")],
     setup=[BUS_AHEAD])
case(L, "direct", "midnight", "Set the time to midnight.",
     [call("set_time_of_day", time="midnight")], [env(night=True, time_from="23:30", time_to="00:30"), ENV])
case(L, "direct", "suv_red_and_night", "Paint the SUV red and make it night.",
     [call("set_asset_appearance", assets=["suv_1"], colour="red"), call("set_time_of_day", time="night")],
     [look("red", asset="suv_1"), env(night=True), keep(assets=["suv_1"], environment=True)], tags=("compound",))
case(L, "direct", "impossible_sparkly_unicorn", "Paint the ego sparkly unicorn.",
     [call("set_asset_appearance", assets=["ego"], colour="sparkly unicorn")], refused(), tags=("impossible",))

case(L, "indirect", "test_the_wipers", "I want to test the wipers.",
     [call("set_weather", kind="rain")], [env(weather=["rain"], intensity_min=0.2), ENV])
case(L, "indirect", "half_past_ten_night", "Our night-vision camera needs a dark scene; half past ten at night would do.",
     [call("set_time_of_day", time="22:30")], [env(night=True, time_from="22:25", time_to="22:35"), ENV])
case(L, "indirect", "suv_bright_orange", "The SUV should be easy to spot from the drone, so make it bright orange.",
     [call("set_asset_appearance", assets=["suv_1"], colour="orange")],
     [look("orange", asset="suv_1"), keep(assets=["suv_1"])])
case(L, "indirect", "simulate_winter", "We're simulating winter, so it should be snowing.",
     [call("set_weather", kind="snow")], [env(weather=["snow"], intensity_min=0.1), ENV])
case(L, "indirect", "lot_b_cars_silver", "It would be nice if the cars in lot B were all silver.",
     [call("set_asset_appearance", assets=["passenger_car_1", "passenger_car_2"], colour="silver")],
     [look("silver", category="passenger_car", scope="all", require_all=True), keep("passenger_car", "suv")])
case(L, "indirect", "exposure_down", "Because the sensor saturates, could you bring the exposure down to 0.6?",
     [call("set_lighting", exposure=0.6)], [env(exposure_min=0.55, exposure_max=0.65), ENV])
case(L, "indirect", "half_past_six_evening", "For the dusk run, set the clock to half past six in the evening.",
     [call("set_time_of_day", time="18:30")], [env(time_from="18:25", time_to="18:35"), ENV])
case(L, "indirect", "headlights_whole_test", "The headlights should be on for the whole test.",
     [call("set_lighting", vehicle_lights="on")], [env(vehicle_lights="on"), ENV])
case(L, "indirect", "impossible_tornado", "Could you make the weather a tornado? We're testing extreme wind.",
     [call("set_weather", kind="tornado")], refused(), tags=("impossible",))

case(L, "vague", "rain", "rain", [call("set_weather", kind="rain")], [env(weather=["rain"]), ENV])
case(L, "vague", "dusk", "dusk", [call("set_time_of_day", time="dusk")], [env(time_from="17:30", time_to="20:30"), ENV])
case(L, "vague", "spooky_night", "spooky night vibes", [call("set_time_of_day", time="night")], [env(night=True), ENV])
case(L, "vague", "suv_in_red", "suv in red",
     [call("set_asset_appearance", assets=["suv_1"], colour="red")], [look("red", asset="suv_1"), keep(assets=["suv_1"])])
case(L, "vague", "foggy_morning", "foggy morning",
     [call("set_weather", kind="fog"), call("set_time_of_day", time="08:00")],
     [env(weather=["fog"], time_from="05:00", time_to="11:00"), ENV], tags=("compound",))
case(L, "vague", "cones_blue", "cones blue",
     [call("set_asset_appearance", category="traffic_cone", colour="blue")],
     [look("blue", category="traffic_cone", scope="all", require_all=True), keep("traffic_cone")],
     setup=[CONES_AT_LOT_B])
case(L, "vague", "lights_on", "lights on",
     [call("set_lighting", street_lights="on")], [ENV],
     alternatives=[[env(street_lights="on")], [env(vehicle_lights="on")]])
case(L, "vague", "clear_skies", "clear skies",
     [call("set_weather", kind="clear")], [env(weather=["clear"]), ENV], setup=[RAIN])
case(L, "vague", "impossible_time_2570", "time 25:70",
     [call("set_time_of_day", time="25:70")], refused(), tags=("impossible",))

case(L, "erroneous", "paint_suv_reed", "paint the suv reed",
     [call("set_asset_appearance", assets=["suv_1"], colour="red")], [look("red", asset="suv_1"), keep(assets=["suv_1"])])
case(L, "erroneous", "rainning_hard", "make it rainning hard",
     [call("set_weather", kind="rain", intensity=0.9)], [env(weather=["rain"], intensity_min=0.75), ENV])
case(L, "erroneous", "time_18_30_oclock", "set time to 18.30 o clock",
     [call("set_time_of_day", time="18:30")], [env(time_from="18:25", time_to="18:35"), ENV])
case(L, "erroneous", "turn_on_streetlight", "turn on the streetlight",
     [call("set_lighting", street_lights="on")], [env(street_lights="on"), ENV])
case(L, "erroneous", "bench_wood_made", "make bench wood made",
     [call("set_asset_appearance", category="bench", material="wood")],
     [look(material="wood", category="bench", require_all=True), keep("bench")])
case(L, "erroneous", "put_fogg", "put fogg", [call("set_weather", kind="fog")], [env(weather=["fog"]), ENV])
case(L, "erroneous", "snowing_please_make", "snowing please make", [call("set_weather", kind="snow")],
     [env(weather=["snow"]), ENV])
case(L, "erroneous", "car_1_colour_blu", "the car 1 colour make blu",
     [call("set_asset_appearance", assets=["passenger_car_1"], colour="blue")],
     [look("blue", asset="passenger_car_1"), keep(assets=["passenger_car_1"])])
case(L, "erroneous", "impossible_tornadoe", "make weather tornadoe",
     [call("set_weather", kind="tornado")], refused(), tags=("impossible",))

# ------------------------------------------- multi-turn: the planner under test plans the first turn too
ADD_CONES_PLANNED = step("Add three cones at the lot B entrance.",
                         [call("add_asset", category="traffic_cone", count=3, location=at("parking lot B entrance"))],
                         planned=True)
BUS_PLANNED = step("Put a bus 12 m in front of the ego.",
                   [call("add_asset", category="bus", location=at("ego", "in_front_of", distance=12))], planned=True)
PED_PLANNED = step("Add a pedestrian at the north crosswalk.",
                   [call("add_asset", category="pedestrian", location=at("north crosswalk"))], planned=True)
TRUCK_PLANNED = step("I need a delivery truck parked in the eastbound lane near the library.",
                     [call("add_asset", category="truck", location=xy(-41, -1.75), yaw_deg=0)], planned=True)
CONE_LINE_PLANNED = step("Line up 4 cones in front of the ego.",
                         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=4,
                               location=at("ego", "in_front_of", distance=15), heading_deg=0)], planned=True)
RAIN_PLANNED = step("Make it rain lightly.", [call("set_weather", kind="rain", intensity=0.3)], planned=True)

case(A, "vague", "two_more_there", "put two more there",
     [call("add_asset", category="traffic_cone", count=2, location=at("parking lot B entrance"))],
     [delta("traffic_cone", 2), near("parking lot B entrance", 10, category="traffic_cone", require_all=True),
      keep("traffic_cone")], setup=[ADD_CONES_PLANNED])
case(L, "indirect", "make_it_yellow", "Actually, make it yellow so it looks like a school bus.",
     [call("set_asset_appearance", category="bus", colour="yellow")], [look("yellow", category="bus"), keep("bus")],
     setup=[BUS_PLANNED])
case(M, "vague", "move_them_a_bit_left", "move them a bit left",
     [call("move_asset", assets=["traffic_cone_1", "traffic_cone_2", "traffic_cone_3", "traffic_cone_4"], left=1.0)],
     [*[moved(f"traffic_cone_{k}", 0.3, 3, direction="left") for k in range(1, 5)], keep("traffic_cone")],
     setup=[CONE_LINE_PLANNED])
case(R, "indirect", "not_the_bus_the_truck", "Hmm, not the bus - remove the truck instead.",
     [call("remove_assets", category="truck")], [count("truck", 0, 0), count("bus", 1, 1), keep("truck")],
     setup=[BUS_PLANNED, step("Also add a truck behind the bus.",
                              [call("add_asset", category="truck", location=at("bus_1", "behind"))])])
case(L, "direct", "heavier_rain", "Make the rain heavier.",
     [call("set_weather", kind="rain", intensity=0.8)], [env(weather=["rain"], intensity_min=0.45), ENV],
     setup=[RAIN_PLANNED])
case(M, "erroneous", "him_walk_across", "now make him walking across the road",
     [call("set_behaviour", asset="pedestrian_1", behaviour={"kind": "cross_road"})],
     [{"kind": "behaviour", "category": "pedestrian", "behaviour": ["cross_road", "jaywalk"]}, keep("pedestrian")],
     setup=[PED_PLANNED])
case(P, "indirect", "truck_8m_behind_ego", "Good. Now I'd like that truck 8 m behind the ego instead, same lane.",
     [call("place_asset", asset="truck_1", location=at("ego", "behind", along_m=-8))],
     [{"kind": "relative", "category": "truck", "relation": "behind", "target": "ego", "max_distance": 18,
       "tolerance_deg": 30}, {"kind": "in_lane", "category": "truck", "lane": "main_eastbound"}, keep("truck")],
     setup=[TRUCK_PLANNED])
case(S, "vague", "how_many_now", "how many cones now?",
     [call("find_assets", category="traffic_cone")], [*ANSWER, says("3", "three")], setup=[ADD_CONES_PLANNED])
case(G, "vague", "same_again_bollard_ring", "same again but bollards, as a ring round the fountain",
     [call("arrange_assets", categories=["bollard"], shape="ring", count=4, location=at("fountain"))],
     [delta("bollard", 3, 8), ring("bollard", 3, "fountain"), delta("traffic_cone", 0), keep("bollard")],
     setup=[CONE_LINE_PLANNED])
case(L, "erroneous", "them_colour_white", "them cones, colour to white and also the rain stop",
     [call("set_asset_appearance", category="traffic_cone", colour="white"), call("set_weather", kind="clear")],
     [look("white", category="traffic_cone", scope="all", require_all=True), env(weather=["clear", "cloudy"]),
      keep("traffic_cone", environment=True)], setup=[ADD_CONES_PLANNED, RAIN], tags=("compound",))
case(A, "indirect", "pedestrian_next_to_truck",
     "For the occlusion test, add a pedestrian on the sidewalk right beside that truck.",
     [call("add_asset", category="pedestrian", location=at("truck_1", "on_sidewalk"))],
     [delta("pedestrian", 1), near("truck_1", 8, category="pedestrian"),
      {"kind": "on_surface", "category": "pedestrian", "surfaces": ["sidewalk"]}, keep("pedestrian")],
     setup=[TRUCK_PLANNED])
case(R, "vague", "drop_the_last_two", "actually drop two of those",
     [call("remove_assets", category="traffic_cone", count=2)], [delta("traffic_cone", -2), keep("traffic_cone")],
     setup=[ADD_CONES_PLANNED])

# ------------------------------------------------------------------ more compound requests (two at once)
C2 = ("compound",)
case(A, "indirect", "van_and_cones_behind",
     "For the next run I need a stalled van in the eastbound lane 20 m ahead of the ego, with two cones just behind it.",
     [call("add_asset", category="truck", location=at("ego", along_m=20)),
      call("add_asset", category="traffic_cone", count=2, location=at("truck_1", "behind"))],
     [delta("truck", 1), delta("traffic_cone", 2), {"kind": "in_lane", "category": "truck", "lane": "main_eastbound"},
      {"kind": "relative", "category": "traffic_cone", "relation": "behind", "target": "truck_1", "max_distance": 12,
       "require_all": True}, keep("truck", "traffic_cone")], tags=C2)
case(A, "vague", "cones_lot_a_entr_sign", "cones x3 lot A entr + parking sign there",
     [call("add_asset", category="traffic_cone", count=3, location=at("parking lot A entrance")),
      call("add_asset", category="parking_sign", location=at("parking lot A entrance"))],
     [delta("traffic_cone", 3), delta("parking_sign", 1),
      near("parking lot A entrance", 10, category=["traffic_cone", "parking_sign"], require_all=True),
      keep("traffic_cone", "parking_sign")], tags=C2)
case(R, "indirect", "trees_out_benches_in",
     "I'd like the quad to be a seating area: take the trees there away and put two benches by the fountain.",
     [call("remove_assets", assets=["tree_2", "tree_3"]),
      call("add_asset", category="bench", count=2, location=at("fountain"))],
     [gone("tree_2"), delta("bench", 2), near("fountain", 10, category="bench", require_all=True),
      keep("bench", assets=["tree_2", "tree_3"])], tags=C2)
case(R, "erroneous", "remove_bin_and_bench", "remove bin and also bench both please",
     [call("remove_assets", assets=["trash_bin_1", "bench_1"])],
     [gone("trash_bin_1", "bench_1"), keep(assets=["trash_bin_1", "bench_1"])], tags=C2)
case(M, "indirect", "suv_drives_car_turns",
     "For the intersection test, send the SUV down Campus Drive southbound and turn passenger_car_1 to face west.",
     [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "campus_southbound"}),
      call("move_asset", asset="passenger_car_1", turn_deg=90)],
     [{"kind": "behaviour", "asset": "suv_1", "behaviour": "drive_lane", "lane": "campus_southbound"},
      moved("passenger_car_1", 0, 1, turn_min_deg=80, turn_max_deg=100),
      keep(assets=["suv_1", "passenger_car_1"])], tags=C2)
case(P, "erroneous", "ego_gate_bench_library", "ego put to main gate and bench to libary",
     [call("place_asset", asset="ego", location=at("main gate")),
      call("place_asset", asset="bench_1", location=at("Library entrance", "in_front_of"))],
     [near("main gate", 8, asset="ego"), near("Library entrance", 8, asset="bench_1"),
      keep(assets=["ego", "bench_1"])], tags=C2)
case(G, "vague", "row_lot_b_and_cones_entr", "parked row of 4 in lot B, plus cones in a line at its entrance",
     [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4, location=at("parking lot B")),
      call("arrange_assets", categories=["traffic_cone"], shape="line", count=4, location=at("parking lot B entrance"))],
     [delta(["passenger_car", "suv"], 4), delta("traffic_cone", 3, 10),
      near("parking lot B", 1, category=["passenger_car", "suv"], scope="added", require_all=True),
      line("traffic_cone", 3), keep("passenger_car", "suv", "traffic_cone")], tags=C2)
case(S, "indirect", "blocking_and_nearest_landmark",
     "Before the run: is anything standing on the lanes, and which landmark is closest to it?",
     [call("find_assets", on_lane=True), call("find_landmarks", nearest_to="cement_rubble_1")],
     [*ANSWER, says("cement_rubble_1", "rubble"), says("parking lot B", "lot B")],
     setup=[RUBBLE_ON_CAMPUS], tags=C2)
case(L, "indirect", "dawn_snow_headlights",
     "We're reproducing a winter commute: light snow at 06:15 with the headlights on.",
     [call("set_weather", kind="snow", intensity=0.3), call("set_time_of_day", time="06:15"),
      call("set_lighting", vehicle_lights="on")],
     [env(weather=["snow"], intensity_max=0.5, time_from="06:10", time_to="06:20", vehicle_lights="on"), ENV], tags=C2)
# (end of cases)


def write_suite(path: Path = JSONL_PATH) -> int:
    """Write every case as one JSON line; returns how many."""
    path.write_text("".join(json.dumps(c, separators=(",", ":")) + "\n" for c in CASES), encoding="utf-8")
    return len(CASES)


if __name__ == "__main__":
    print(f"wrote {write_suite()} cases to {JSONL_PATH}")
