"""The eighth practice suite, `practice7`: requests in new voices, judged by their outcome.

What it is: 242 natural-language requests for the campus world, each with checks that judge
the scene after the request and the answer (never the calls), an `unchanged_except` guard and a
known-good reference plan that the `reference` planner replays to prove the case passable. Every
task x grade cell holds 7 to 10 cases; the indirect (65), erroneous (60) and vague (59) grades each
outnumber the direct one (58). 19 cases are multi-turn (9 with the earlier turn planned by the
planner under test), 19 are compound (two or more edits in one request), and 20 (8 %) ask for what
the world cannot do and expect a refusal that changes nothing: the distance to a stadium or a
swimming pool, a horse-drawn carriage, twelve shuttle buses, a second ego vehicle, removing our own
car, Campus Drive or the zebra crossings, a traffic light in the middle of the junction, the SUV
40 m outside the world, a car on the library footpath, a hydrant doing circles, a bin that walks
across the road, a 150 m shift, a line of twelve buses, a lakeside promenade, fifteen trucks in
lot A, a tornado, a repainted library facade and the time 25:30.

Who wrote it and from what: a helper who read only the campus world (`worlds/campus.py`,
`worlds/data/campus.json`), the asset catalog, the Worker tools and the eval check machinery
(`evals/README.md` "Suites", the case schema and the checks), and ran the tools to learn where
things land. It did not read the planners, their lexicons or prompt examples, nor any other
suite or suite source: the wording is its own.

Its voices: a film director blocking a shot ("for this take", "hero car", "out of frame"); a
traffic researcher writing test-matrix rows ("Condition 9: ...; IV: ..."); a teenager texting
("ngl", "pls", "u", "rn", "lowkey"); someone who corrects themself mid-request ("three, no wait,
two"; "the bench - sorry, the bin"); a driver speaking from the driver's seat ("up ahead", "on my
right", "behind me"); a city official ("install", "decommission", "relocate", "deploy"); someone
who states the scene they want instead of the edit ("there should be exactly four cones in lot
A", "I want no bins on campus"); markdown lists and numbered steps; non-native speakers carrying
German, Spanish, Hindi and Mandarin word order into English; and someone hedging or asking
conditionally ("if there's a bus, paint it yellow", "maybe a couple of trees?").

Regenerate the JSONL after editing the lists below (from any directory):

    python -m drivetwin.evals.practice7_source

Every reference must pass: `drivetwin eval run --suite practice7 --planner reference`, also run
by `tests/evals/test_later_practice_suites.py`.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

SUITE_PATH = Path(__file__).resolve().parent / "suites" / "practice7.jsonl"

Json = dict[str, Any]

# The campus world's fixed assets that the cases name.
PARKED_IN_LOT_B = ["passenger_car_1", "suv_1", "passenger_car_2"]
NORTH_STREET_LIGHTS = [f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11)]
SOUTH_STREET_LIGHTS = [f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12)]
VEHICLES = ["passenger_car", "suv", "bus", "truck", "motorcycle"]


def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def at(target: str, relation: str = "at", **more: Any) -> Json:
    return {"relation": relation, "target": target, **more}


def point(x: float, y: float) -> Json:
    return {"relation": "absolute", "x": x, "y": y}


def guard(*categories: str, assets: list[str] | None = None, environment: bool = False) -> Json:
    check: Json = {"kind": "unchanged_except", "categories": list(categories)}
    if assets:
        check["assets"] = assets
    if environment:
        check["environment"] = True
    return check


def delta(category: str | list[str], lo: int | None, hi: int | None = None) -> Json:
    check: Json = {"kind": "count_delta", "category": category, "min": lo}
    check["max"] = lo if hi is None else hi
    return check


def count(category: str | list[str], lo: int | None = None, hi: int | None = None) -> Json:
    return {"kind": "count", "category": category, "min": lo, "max": hi}


def near(category: str | list[str] | None, target: str, within: float, **more: Any) -> Json:
    return {"kind": "near", "category": category, "target": target, "within": within, "scope": "added", **more}


def near_point(category: str | list[str] | None, x: float, y: float, within: float, **more: Any) -> Json:
    return {"kind": "near", "category": category, "point": [x, y], "within": within, "scope": "added", **more}


def gone(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": False}


def kept(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": True}


def moved(asset: str, **more: Any) -> Json:
    return {"kind": "moved", "asset": asset, **more}


def told(*, any_of: list[str] | None = None, all_of: list[str] | None = None) -> Json:
    return {"kind": "answer_contains", "any_of": any_of or [], "all_of": all_of or []}


def told_but_not(none_of: list[str], **words: list[str]) -> Json:
    """An answer check that also names words a right answer does not contain."""
    return {**told(**words), "none_of": none_of}


def status(ok: bool = True) -> Json:
    return {"kind": "status", "accepted": ok}


def env(**more: Any) -> Json:
    return {"kind": "environment", **more}


def looks(**more: Any) -> Json:
    return {"kind": "appearance", **more}


def turn(prompt: str, calls: list[Json], *, planned: bool = False) -> Json:
    return {"prompt": prompt, "calls": calls, "planned": planned}


def case(
    task: str,
    grade: str,
    slug: str,
    prompt: str,
    checks: list[Json],
    reference: list[Json],
    *,
    tags: tuple[str, ...] = (),
    setup: list[Json] | None = None,
    alternatives: list[list[Json]] | None = None,
) -> Json:
    line: Json = {
        "id": f"practice7.{task}.{grade}.{slug}",
        "prompt": prompt,
        "task": task,
        "grade": grade,
        "tags": ["practice7", *tags],
        "checks": checks,
        "reference": reference,
    }
    if setup:
        line["setup"] = setup
        if "multi_turn" not in line["tags"]:
            line["tags"].append("multi_turn")
    if alternatives:
        line["alternatives"] = alternatives
    return line


def question(grade: str, slug: str, prompt: str, answer: Json, reference: list[Json], **more: Any) -> Json:
    """A question: answered, with nothing in the scene changed."""
    return case("search", grade, slug, prompt, [status(), answer, guard()], reference, **more)


def impossible(task: str, grade: str, slug: str, prompt: str, reference: list[Json], **more: Any) -> Json:
    """A request the world cannot do: refused, with nothing changed."""
    return case(task, grade, slug, prompt, [status(False), guard()], reference, tags=("impossible",), **more)




# The campus before any edit: 6 street lights either side of Main Street, 2 traffic lights,
# 4 trees, a bench, a bin, a hydrant and a stop sign; three cars parked in lot B; the ego
# driving east in main_eastbound from (-60, -1.75).
ALL_LIGHTS = NORTH_STREET_LIGHTS + SOUTH_STREET_LIGHTS
OBSTACLES = ["cement_rubble", "traffic_cone", "road_barrier", "bollard"]
CARS = ["passenger_car", "suv"]

BRIGHT = ["red", "green", "blue", "yellow", "orange", "purple", "pink", "cyan", "teal", "gold", "navy", "maroon"]
# What each part of the environment is at the start, and the env() fields that name it.
BASELINE: dict[str, Json] = {
    "weather": {"weather": ["clear"]},
    "time": {"time_from": "12:00", "time_to": "12:00"},
    "street_lights": {"street_lights": "auto"},
    "vehicle_lights": {"vehicle_lights": "auto"},
    "exposure": {"exposure_min": 1.0, "exposure_max": 1.0},
}
_ASPECT = {"weather": "weather", "intensity_min": "weather", "intensity_max": "weather", "night": "time",
           "time_from": "time", "time_to": "time", "street_lights": "street_lights",
           "vehicle_lights": "vehicle_lights", "exposure_min": "exposure", "exposure_max": "exposure"}


def env_only(*free: str, **wanted: Any) -> Json:
    """An environment check: what was asked for, and every other part (except those `free`
    to change along with it, such as lights at night) left as it was."""
    asked = {_ASPECT[k] for k in wanted}
    pins: Json = {}
    for aspect, fields in BASELINE.items():
        if aspect not in asked and aspect not in free:
            pins.update(fields)
    return env(**pins, **wanted)

SEARCH: list[Json] = [
    # --- direct ---
    question(
        "direct", "light_count",
        "Condition 0 (baseline); IV: number of street lights in the scene; report the count.",
        told(any_of=["12 street", "twelve street", "12 lights", "12 lamp", "12 in total"]),
        [call("find_assets", category="street_light")],
    ),
    question(
        "direct", "nearest_light_to_bus_stop",
        "Which street light stands closest to the bus stop, and how far from it?",
        told(all_of=["street_light_4"], any_of=["8.0", "8 m", "8 metres", "eight"]),
        [call("find_assets", category="street_light", nearest_to="bus stop")],
    ),
    question(
        "direct", "fountain_to_east_gate",
        "What is the straight-line distance between the fountain and the east gate?",
        told(any_of=["47.2", "47"]),
        [call("measure_distance", a="fountain", b="east gate")],
    ),
    question(
        "direct", "lot_b_for_the_take",
        "For this take I need to know exactly what's parked in lot B right now. List the vehicles.",
        told_but_not(["ego"], all_of=["passenger_car_1", "suv_1", "passenger_car_2"]),
        [call("find_assets", category="vehicles", near="parking lot B", within=25)],
    ),
    question(
        "direct", "campus_drive_lanes",
        "List the lanes of Campus Drive.",
        told(all_of=["campus_northbound", "campus_southbound"]),
        [call("find_lanes", road="Campus Drive")],
    ),
    question(
        "direct", "bus_mass",
        "How heavy is a bus from the catalog, in kilograms?",
        told(any_of=["12000", "12,000", "12 000", "12 t", "12 tonnes"]),
        [call("asset_properties", category="bus")],
    ),
    question(
        "direct", "union_to_nearest_car",
        "Measure the distance from the Student Union entrance to passenger_car_2.",
        told(any_of=["17.9", "18 m", "18 metres", "about 18"]),
        [call("measure_distance", a="Student Union entrance", b="passenger_car_2")],
    ),
    impossible(
        "search", "direct", "distance_to_stadium",
        "How far is the ego vehicle from the campus stadium?",
        [call("measure_distance", a="ego", b="stadium")],
    ),
    # --- indirect ---
    question(
        "indirect", "north_east_building",
        "What's the big building on the north-east corner of the crossroads called?",
        told(any_of=["JTEKT"]),
        [call("find_landmarks", nearest_to="40,30")],
    ),
    question(
        "indirect", "shortest_walk_to_a_car",
        "Which parked car is the shortest walk from the Student Union doors?",
        told(all_of=["passenger_car_2"], any_of=["17.9", "18 m", "18 metres", "about 18"]),
        [call("find_assets", category="vehicles", nearest_to="Student Union entrance")],
    ),
    question(
        "indirect", "lamp_beside_stop_sign",
        "Which lamp post stands right beside the stop sign?",
        told(all_of=["street_light_6"], any_of=["0.6", "0.5", "1 m", "less than a metre", "under a metre"]),
        [call("find_assets", category="street_light", nearest_to="stop_sign_1")],
    ),
    question(
        "indirect", "which_lane_am_i_in",
        "Which lane am I driving in right now?",
        told_but_not(["westbound"], all_of=["eastbound"]),
        [call("find_assets", category="ego", on_lane=True)],
    ),
    question(
        "indirect", "hydrant_to_jtekt_doors",
        "For the fire-code review: how far is the hydrant from the main doors of the JTEKT Building?",
        told(any_of=["23.5"]),
        [call("measure_distance", a="fire_hydrant_1", b="JTEKT building entrance")],
    ),
    question(
        "indirect", "around_the_library_doors",
        "What stands within 20 m of the library doors?",
        told(all_of=["street_light_4", "trash_bin_1", "tree_1", "bench_1"]),
        [call("find_assets", near="Library entrance", within=20)],
    ),
    question(
        "indirect", "driveway_to_gate",
        "From where lot A's driveway meets Main Street to where Main Street enters campus from the west: how many metres is that?",
        told(any_of=["15.4"]),
        [call("measure_distance", a="parking lot A entrance", b="main gate")],
    ),
    question(
        "indirect", "east_west_road_length",
        "How long is the road that runs east-west through campus?",
        told(any_of=["220"]),
        [call("find_lanes", road="Main Street")],
    ),
    impossible(
        "search", "indirect", "library_to_pool",
        "How many metres is it from the library to the campus swimming pool?",
        [call("measure_distance", a="Library entrance", b="swimming pool")],
    ),
    # --- vague ---
    question(
        "vague", "anything_in_student_lot",
        "anything parked in the student lot?",
        told_but_not(["ego"], all_of=["passenger_car_1", "suv_1", "passenger_car_2"]),
        [call("find_assets", category="vehicles", near="student parking", within=25)],
    ),
    question(
        "vague", "shade_by_fountain",
        "is there any shade near the fountain?",
        told(all_of=["tree_2"], any_of=["7.1", "7 m", "7 metres"]),
        [call("find_assets", category="tree", nearest_to="fountain")],
    ),
    question(
        "vague", "lamps_on_my_side",
        "how many lamps are on my side of the street?",
        told_but_not(NORTH_STREET_LIGHTS, all_of=SOUTH_STREET_LIGHTS),
        [call("find_assets", category="street_light", lane="main_eastbound")],
    ),
    question(
        "vague", "where_to_sit",
        "where can people sit around here?",
        told(all_of=["bench_1"]),
        [call("find_assets", category="bench")],
    ),
    question(
        "vague", "truck_size",
        "roughly how big is one of those delivery trucks?",
        told(any_of=["8x2.5x3.4", "8 m", "8 metres"]),
        [call("asset_properties", category="truck")],
    ),
    question(
        "vague", "by_the_back_gate",
        "what's over by the back gate?",
        told(all_of=["street_light_12"], any_of=["9.9", "10 m", "10 metres"]),
        [call("find_assets", nearest_to="east gate", within=25)],
    ),
    question(
        "vague", "where_am_i",
        "where am I at the moment?",
        told(all_of=["-60"]),
        [call("asset_properties", asset="ego")],
    ),
    question(
        "vague", "how_many_cones_i_put",
        "how many cones did I put down?",
        told(any_of=["6 traffic", "6 cones", "six"]),
        [call("find_assets", category="traffic_cone")],
        setup=[turn("Put six cones in a row in the middle of lot A.",
                    [call("arrange_assets", categories=["traffic_cone"], shape="line", count=6,
                          location=at("parking lot A"))])],
    ),
    question(
        "vague", "benches_now",
        "so how many benches are there now?",
        told(any_of=["3 bench", "3 benches", "three"]),
        [call("find_assets", category="bench")],
        setup=[turn("Add two benches by the fountain.",
                    [call("add_asset", category="bench", count=2, location=at("fountain"))], planned=True)],
    ),
    # --- erroneous ---
    question(
        "erroneous", "how_many_signals",
        "wait how many trafic lights r there even",
        told(all_of=["traffic_light_1", "traffic_light_2"]),
        [call("find_assets", category="traffic_light")],
    ),
    question(
        "erroneous", "german_distance",
        "How many meters are it from the ego car until the crossroads?",
        told(any_of=["60.0 m", "60 m", "60 metres", "51.0 m", "51 m", "51 metres"]),
        [call("measure_distance", a="ego", b="main intersection")],
    ),
    question(
        "erroneous", "spanish_bench",
        "Where is the bench more near of the library?",
        told(all_of=["bench_1"]),
        [call("find_assets", category="bench", nearest_to="Library entrance")],
    ),
    question(
        "erroneous", "hindi_dustbin",
        "Bus stop to nearest dustbin, which one it is, please tell.",
        told(all_of=["trash_bin_1"]),
        [call("find_assets", category="trash_bin", nearest_to="bus stop")],
    ),
    question(
        "erroneous", "mandarin_lot_b",
        "Lot B inside have how many car?",
        told_but_not(["ego"], all_of=["passenger_car_1", "suv_1", "passenger_car_2"]),
        [call("find_assets", category="vehicles", near="parking lot B", within=25)],
    ),
    question(
        "erroneous", "hydrant_typo",
        "wher is the fire hydrnat",
        told(all_of=["16", "5.5"]),
        [call("find_assets", category="fire_hydrant")],
    ),
    question(
        "erroneous", "bench_sorry_bin",
        "how far is the bench from the bus stop - sorry, the bin from the bus stop?",
        told(all_of=["3.5"], any_of=["trash_bin_1", "bin"]),
        [call("measure_distance", a="trash_bin_1", b="bus stop")],
    ),
    question(
        "erroneous", "teen_trees",
        "lowkey how many trees r on campus rn",
        told(all_of=["tree_1", "tree_2", "tree_3", "tree_4"]),
        [call("find_assets", category="tree")],
    ),
]

ADDITION: list[Json] = [
    # --- direct ---
    case(
        "addition", "direct", "benches_at_fountain",
        "Install two benches at the fountain.",
        [delta("bench", 2), near("bench", "fountain", 8, require_all=True), guard("bench")],
        [call("add_asset", category="bench", count=2, location=at("fountain"))],
    ),
    case(
        "addition", "direct", "truck_condition_1",
        "Condition 1: one truck driving main_westbound at 6 m/s; everything else baseline.",
        [delta("truck", 1),
         {"kind": "behaviour", "category": "truck", "behaviour": "drive_lane", "lane": "main_westbound",
          "speed_min": 5.5, "speed_max": 6.5, "scope": "added"},
         guard("truck")],
        [call("add_asset", category="truck",
              behaviour={"kind": "drive_lane", "lane": "main_westbound", "speed": 6})],
    ),
    case(
        "addition", "direct", "pedestrian_on_north_crosswalk",
        "Add a pedestrian walking across the north crosswalk.",
        [delta("pedestrian", 1),
         {"kind": "behaviour", "category": "pedestrian", "behaviour": "cross_road",
          "crosses_lane": "campus_northbound", "scope": "added"},
         near("pedestrian", "north crosswalk", 8),
         guard("pedestrian")],
        [call("add_asset", category="pedestrian", location=at("north crosswalk"),
              behaviour={"kind": "cross_road"})],
    ),
    case(
        "addition", "direct", "motorbike_ahead_of_me",
        "Put a motorbike 20 m up ahead of me, in my lane.",
        [delta("motorcycle", 1), {"kind": "in_lane", "category": "motorcycle", "lane": "main_eastbound", "scope": "added"},
         near_point("motorcycle", -40, -1.75, 5),
         guard("motorcycle")],
        [call("add_asset", category="motorcycle", location=at("ego", along_m=20))],
    ),
    case(
        "addition", "direct", "robot_circles_lot_b",
        "Spawn an Ackermann robot in lot B doing circles with a 4 m radius.",
        [delta("ackermann_robot", 1),
         {"kind": "behaviour", "category": "ackermann_robot", "behaviour": "circle", "radius_min": 3.5,
          "radius_max": 4.5, "centre_near": "parking lot B", "centre_within": 1, "scope": "added"},
         guard("ackermann_robot")],
        [call("add_asset", category="ackermann_robot", location=at("parking lot B"),
              behaviour={"kind": "circle", "radius": 4})],
    ),
    case(
        "addition", "direct", "markdown_list",
        "Please add:\n- 2 cones at the lot A entrance\n- 1 bench by the fountain\n- 1 bin next to that bench",
        [delta("traffic_cone", 2), delta("bench", 1), delta("trash_bin", 1),
         near("traffic_cone", "parking lot A entrance", 8, require_all=True),
         near("bench", "fountain", 8), near("trash_bin", "fountain", 10),
         guard("traffic_cone", "bench", "trash_bin")],
        [call("add_asset", category="traffic_cone", count=2, location=at("parking lot A entrance")),
         call("add_asset", category="bench", location=at("fountain")),
         call("add_asset", category="trash_bin", location=at("bench_2", "next_to"))],
        tags=("compound",),
    ),
    case(
        "addition", "direct", "red_sedan_and_cyclist",
        "For this take: the hero car, a red sedan, parked at the JTEKT drop-off, and a cyclist riding west on Main Street.",
        [delta("passenger_car", 1), delta("bicycle", 1),
         near("passenger_car", "JTEKT building entrance", 8),
         looks(category="passenger_car", colour="red", scope="added"),
         {"kind": "behaviour", "category": "bicycle", "behaviour": ["drive_lane", "follow_path"], "scope": "added"},
         {"kind": "in_lane", "category": "bicycle", "lane": "main_westbound", "scope": "added"},
         guard("passenger_car", "bicycle")],
        [call("add_asset", category="passenger_car", colour="red", location=at("JTEKT building entrance")),
         call("add_asset", category="bicycle", behaviour={"kind": "drive_lane", "lane": "main_westbound"})],
        tags=("compound",),
    ),
    impossible(
        "addition", "direct", "horse_drawn_carriage",
        "For the period scene, add a horse-drawn carriage at the main gate.",
        [call("add_asset", category="horse-drawn carriage", location=at("main gate"))],
    ),
    # --- indirect ---
    case(
        "addition", "indirect", "exactly_four_cones_lot_a",
        "There should be exactly four cones in lot A.",
        [count("traffic_cone", 4, 4), near("traffic_cone", "parking lot A", 0.5, require_all=True), guard("traffic_cone")],
        [call("add_asset", category="traffic_cone", count=4, location=at("parking lot A"))],
    ),
    case(
        "addition", "indirect", "shade_for_the_bench",
        "The bench by the bus stop bakes in the sun all afternoon. Give it some shade.",
        [delta("tree", 1, 2), near("tree", "bench_1", 5), guard("tree")],
        [call("add_asset", category="tree", location=at("bench_1", "next_to"))],
    ),
    case(
        "addition", "indirect", "hero_car_at_dropoff",
        "The hero car pulls up at the JTEKT drop-off in this shot. Park a sedan there.",
        [delta("passenger_car", 1), near("passenger_car", "JTEKT building entrance", 8),
         {"kind": "on_surface", "category": "passenger_car", "surfaces": ["drivable"], "scope": "added"},
         {"kind": "behaviour", "category": "passenger_car", "behaviour": "parked", "scope": "added"},
         guard("passenger_car")],
        [call("add_asset", category="passenger_car", location=at("JTEKT building entrance"))],
    ),
    case(
        "addition", "indirect", "warn_drivers_west_crosswalk",
        "Pedestrians keep getting surprised at the west crosswalk. Deploy a warning sign for drivers there.",
        [delta("pedestrian_sign", 1), near("pedestrian_sign", "west crosswalk", 10),
         {"kind": "on_surface", "category": "pedestrian_sign", "surfaces": ["sidewalk", "ground"], "scope": "added"},
         guard("pedestrian_sign")],
        [call("add_asset", category="pedestrian_sign", location=at("west crosswalk"))],
    ),
    case(
        "addition", "indirect", "bus_waiting_at_stop",
        "The students at the shuttle stop have nothing to get on. Have a bus pulled up at the stop.",
        [delta("bus", 1), near("bus", "bus stop", 10),
         {"kind": "on_surface", "category": "bus", "surfaces": ["drivable"], "scope": "added"},
         guard("bus")],
        [call("add_asset", category="bus", location=at("bus stop"))],
    ),
    case(
        "addition", "indirect", "passer_by_library",
        "I need a passer-by in frame by the library doors, just standing there.",
        [delta("pedestrian", 1), near("pedestrian", "Library entrance", 6),
         {"kind": "behaviour", "category": "pedestrian", "behaviour": "parked", "scope": "added"},
         guard("pedestrian")],
        [call("add_asset", category="pedestrian", location=at("Library entrance"))],
    ),
    case(
        "addition", "indirect", "bins_flank_union_doors",
        "The Student Union doors should have a bin on each side.",
        [delta("trash_bin", 2), near("trash_bin", "Student Union entrance", 6, require_all=True),
         *[{"kind": "relative", "category": "trash_bin", "relation": side, "target": "Student Union entrance",
            "max_distance": 6, "tolerance_deg": 45, "scope": "added"} for side in ("left_of", "right_of")],
         guard("trash_bin")],
        [call("add_asset", category="trash_bin", location=at("Student Union entrance", "left_of", distance=2)),
         call("add_asset", category="trash_bin", location=at("Student Union entrance", "right_of", distance=2))],
    ),
    case(
        "addition", "indirect", "more_of_the_same",
        "Add a few more of them.",
        [delta("pedestrian", 2, 5), near("pedestrian", "fountain", 12, require_all=True), guard("pedestrian")],
        [call("add_asset", category="pedestrian", count=3, location=at("fountain"))],
        setup=[turn("Put two people chatting by the fountain.",
                    [call("add_asset", category="pedestrian", count=2, location=at("fountain"))])],
    ),
    impossible(
        "addition", "indirect", "open_day_buses",
        "Deploy twelve shuttle buses on Main Street for the open day.",
        [call("add_asset", category="bus", count=12, location=at("main_westbound", "in_lane"))],
    ),
    # --- vague ---
    case(
        "addition", "vague", "couple_of_trees_engineering",
        "maybe a couple of trees near the engineering building?",
        [delta("tree", 2, 3), near("tree", "Engineering Hall entrance", 15, require_all=True), guard("tree")],
        [call("add_asset", category="tree", count=2, location=at("Engineering Hall entrance"))],
    ),
    case(
        "addition", "vague", "some_traffic",
        "could use some traffic on the roads",
        [delta(["passenger_car", "suv", "bus", "truck", "motorcycle"], 2, 12),
         {"kind": "behaviour", "category": ["passenger_car", "suv", "bus", "truck", "motorcycle"],
          "behaviour": ["drive_lane", "follow_path"], "require_all": True, "scope": "added"},
         guard("passenger_car", "suv", "bus", "truck", "motorcycle")],
        [call("add_asset", category="passenger_car", count=3,
              behaviour={"kind": "drive_lane", "lane": "main_westbound"})],
    ),
    case(
        "addition", "vague", "few_people_fountain",
        "can u put like a few ppl by the fountain",
        [delta("pedestrian", 2, 6), near("pedestrian", "fountain", 12, require_all=True), guard("pedestrian")],
        [call("add_asset", category="pedestrian", count=3, location=at("fountain"))],
    ),
    case(
        "addition", "vague", "something_to_swerve_around",
        "put something in the road up ahead that I have to swerve around",
        [delta(OBSTACLES, 1, 6),
         {"kind": "in_lane", "category": OBSTACLES, "lane": "main_eastbound", "scope": "added", "require_all": False},
         {"kind": "relative", "category": OBSTACLES, "relation": "in_front_of", "target": "ego",
          "max_distance": 80, "tolerance_deg": 15, "scope": "added"},
         guard(*OBSTACLES)],
        [call("add_asset", category="cement_rubble", location=at("ego", along_m=30))],
    ),
    case(
        "addition", "vague", "dark_corner_lot_a",
        "the corner where lot A meets the street is kind of dark, fix that?",
        [delta("street_light", 1, 2), near("street_light", "parking lot A entrance", 12, require_all=True),
         guard("street_light")],
        [call("add_asset", category="street_light", location=at("parking lot A entrance", "on_sidewalk"))],
    ),
    case(
        "addition", "vague", "bike_or_two_library",
        "if there's room, a bike or two outside the library?",
        [delta("bicycle", 1, 2), near("bicycle", "Library entrance", 10, require_all=True), guard("bicycle")],
        [call("add_asset", category="bicycle", count=2, location=at("Library entrance"))],
    ),
    case(
        "addition", "vague", "busier_crossing",
        "make the zebra crossing busier",
        [delta("pedestrian", 2, 8),
         {"kind": "behaviour", "category": "pedestrian", "behaviour": ["cross_road", "follow_path"],
          "min_count": 2, "scope": "added"},
         near("pedestrian", "west crosswalk", 10, min_count=2),
         guard("pedestrian")],
        [call("add_asset", category="pedestrian", count=3, location=at("west crosswalk"),
              behaviour={"kind": "cross_road"})],
    ),
    case(
        "addition", "vague", "bus_stop_looks_sad",
        "the bus stop looks a bit sad. maybe another bench and a tree behind it?",
        [delta("bench", 1), delta("tree", 1), near("bench", "bus stop", 6), near("tree", "bus stop", 8),
         {"kind": "on_surface", "category": ["bench", "tree"], "surfaces": ["sidewalk", "ground"], "scope": "added"},
         guard("bench", "tree")],
        [call("add_asset", category="bench", location=at("bus stop")),
         call("add_asset", category="tree", location=at("bus stop", "behind"))],
        tags=("compound",),
    ),
    # --- erroneous ---
    case(
        "addition", "erroneous", "three_no_two_cones",
        "add three, no wait, two cones at the lot B entrance",
        [delta("traffic_cone", 2), near("traffic_cone", "parking lot B entrance", 8, require_all=True),
         guard("traffic_cone")],
        [call("add_asset", category="traffic_cone", count=2, location=at("parking lot B entrance"))],
    ),
    case(
        "addition", "erroneous", "german_bench_beside_tree",
        "Put please one bench beside of the tree at the fountain.",
        [delta("bench", 1), near("bench", "tree_2", 4), guard("bench")],
        [call("add_asset", category="bench", location=at("tree_2", "next_to"))],
    ),
    case(
        "addition", "erroneous", "spanish_red_car_lot_a",
        "Put a car of color red in the parking A.",
        [delta("passenger_car", 1), near("passenger_car", "parking lot A", 0.5),
         looks(category="passenger_car", colour="red", scope="added"), guard("passenger_car")],
        [call("add_asset", category="passenger_car", colour="red", location=at("parking lot A"))],
    ),
    case(
        "addition", "erroneous", "scooter_next_2_bench",
        "pls add a scooter next 2 the bench lol",
        [delta("motorcycle", 1), near("motorcycle", "bench_1", 7), guard("motorcycle")],
        [call("add_asset", category="motorcycle", location=at("bench_1", "next_to"))],
    ),
    case(
        "addition", "erroneous", "mandarin_two_tree",
        "Engineering Hall front put two tree.",
        [delta("tree", 2), near("tree", "Engineering Hall entrance", 15, require_all=True), guard("tree")],
        [call("add_asset", category="tree", count=2, location=at("Engineering Hall entrance", "in_front_of"))],
    ),
    case(
        "addition", "erroneous", "delivry_truck_dropof",
        "ad a delivry truck parkd at the jtekt dropof",
        [delta("truck", 1), near("truck", "JTEKT building entrance", 10),
         {"kind": "on_surface", "category": "truck", "surfaces": ["drivable"], "scope": "added"},
         {"kind": "behaviour", "category": "truck", "behaviour": "parked", "scope": "added"},
         guard("truck")],
        [call("add_asset", category="truck", location=at("JTEKT building entrance"))],
    ),
    case(
        "addition", "erroneous", "hindi_cyclist_northbound",
        "One cyclist please put, on Campus Drive going north side.",
        [delta("bicycle", 1),
         {"kind": "behaviour", "category": "bicycle", "behaviour": ["drive_lane", "follow_path"], "scope": "added"},
         {"kind": "in_lane", "category": "bicycle", "lane": "campus_northbound", "scope": "added"},
         guard("bicycle")],
        [call("add_asset", category="bicycle", behaviour={"kind": "drive_lane", "lane": "campus_northbound"})],
    ),
    case(
        "addition", "erroneous", "numbered_ped_and_bike",
        "1) add a pedestrain at the north crosswalk 2) add a bycicle next to him",
        [delta("pedestrian", 1), delta("bicycle", 1),
         near("pedestrian", "north crosswalk", 8), near("bicycle", "north crosswalk", 10),
         guard("pedestrian", "bicycle")],
        [call("add_asset", category="pedestrian", location=at("north crosswalk")),
         call("add_asset", category="bicycle", location=at("pedestrian_1", "next_to"))],
        tags=("compound",),
    ),
    impossible(
        "addition", "erroneous", "second_ego",
        "add a 2nd ego vehical so we can test 2 at once",
        [call("add_asset", category="ego_vehicle", location=at("ego", "behind"))],
    ),
]

REMOVAL: list[Json] = [
    # --- direct ---
    case(
        "removal", "direct", "decommission_bus_stop_bench",
        "Decommission the bench at the bus stop.",
        [gone("bench_1"), delta("bench", -1), guard("bench")],
        [call("remove_assets", assets=["bench_1"])],
    ),
    case(
        "removal", "direct", "clear_lot_b",
        "Clear all the parked cars out of lot B.",
        [gone("passenger_car_1", "suv_1", "passenger_car_2"), guard(*CARS)],
        [call("remove_assets", assets=PARKED_IN_LOT_B)],
    ),
    case(
        "removal", "direct", "no_bins_on_campus",
        "I want no bins on campus.",
        [count("trash_bin", 0, 0), guard("trash_bin")],
        [call("remove_assets", category="trash_bin")],
    ),
    case(
        "removal", "direct", "south_side_lights",
        "Remove the six street lights on the south side of Main Street.",
        [gone(*SOUTH_STREET_LIGHTS), kept(*NORTH_STREET_LIGHTS), guard("street_light")],
        [call("remove_assets", assets=SOUTH_STREET_LIGHTS)],
    ),
    case(
        "removal", "direct", "condition_5_no_stop_sign",
        "Condition 5: stop sign removed; all other assets as baseline.",
        [gone("stop_sign_1"), guard("stop_sign")],
        [call("remove_assets", assets=["stop_sign_1"])],
    ),
    case(
        "removal", "direct", "stop_sign_and_hydrant",
        "Remove the stop sign and the fire hydrant.",
        [gone("stop_sign_1", "fire_hydrant_1"), guard("stop_sign", "fire_hydrant")],
        [call("remove_assets", assets=["stop_sign_1"]), call("remove_assets", assets=["fire_hydrant_1"])],
        tags=("compound",),
    ),
    case(
        "removal", "direct", "remove_two_of_those",
        "Remove two of those cones.",
        [delta("traffic_cone", -2), count("traffic_cone", 2, 2), guard("traffic_cone")],
        [call("remove_assets", assets=["traffic_cone_3", "traffic_cone_4"])],
        setup=[turn("Put four cones at the lot A entrance.",
                    [call("add_asset", category="traffic_cone", count=4, location=at("parking lot A entrance"))])],
    ),
    impossible(
        "removal", "direct", "remove_our_own_car",
        "Remove our own car from the scene; I want an empty road for this shot.",
        [call("remove_assets", assets=["ego"])],
    ),
    # --- indirect ---
    case(
        "removal", "indirect", "red_thing_near_jtekt",
        "Get rid of the little red thing on the pavement near the JTEKT corner.",
        [gone("fire_hydrant_1"), guard("fire_hydrant")],
        [call("remove_assets", assets=["fire_hydrant_1"])],
    ),
    case(
        "removal", "indirect", "lamp_by_the_bin",
        "Remove the lamp post that stands beside the bin at the bus stop.",
        [gone("street_light_4"), kept(*[i for i in ALL_LIGHTS if i != "street_light_4"]), guard("street_light")],
        [call("remove_assets", category="street_light", near="trash_bin_1", count=1)],
    ),
    case(
        "removal", "indirect", "car_between_the_sedans",
        "In lot B, take away the car parked between the two sedans.",
        [gone("suv_1"), kept("passenger_car_1", "passenger_car_2"), guard("suv")],
        [call("remove_assets", assets=["suv_1"])],
    ),
    case(
        "removal", "indirect", "lights_in_front_of_engineering",
        "Remove the street lights in front of Engineering Hall.",
        [gone("street_light_3", "street_light_5"),
         kept(*[i for i in ALL_LIGHTS if i not in ("street_light_3", "street_light_5")]), guard("street_light")],
        [call("remove_assets", assets=["street_light_3", "street_light_5"])],
    ),
    case(
        "removal", "indirect", "tree_north_of_lot_a",
        "Take out the tree just north of lot A.",
        [gone("tree_4"), kept("tree_1", "tree_2", "tree_3"), guard("tree")],
        [call("remove_assets", category="tree", near="parking lot A", count=1)],
    ),
    case(
        "removal", "indirect", "light_on_my_right_before_junction",
        "Take out the street light on my right just before the junction.",
        [gone("street_light_6"), kept(*[i for i in ALL_LIGHTS if i != "street_light_6"]), guard("street_light")],
        [call("remove_assets", assets=["street_light_6"])],
    ),
    case(
        "removal", "indirect", "no_signals_at_crossroads",
        "There should be no traffic signals at the crossroads.",
        [count("traffic_light", 0, 0), guard("traffic_light")],
        [call("remove_assets", category="traffic_light")],
    ),
    case(
        "removal", "indirect", "numbered_bench_then_bin",
        "1. Remove the bench at the bus stop.\n2. Remove the bin next to it as well.",
        [gone("bench_1", "trash_bin_1"), guard("bench", "trash_bin")],
        [call("remove_assets", assets=["bench_1"]), call("remove_assets", assets=["trash_bin_1"])],
        tags=("compound",),
    ),
    impossible(
        "removal", "indirect", "decommission_campus_drive",
        "Decommission Campus Drive: remove the north-south road entirely.",
        [call("remove_assets", assets=["campus_northbound", "campus_southbound"])],
    ),
    # --- vague ---
    case(
        "removal", "vague", "declutter_bus_stop",
        "declutter the sidewalk at the bus stop",
        [delta(["bench", "trash_bin"], -2, -1), kept("street_light_4"), guard("bench", "trash_bin")],
        [call("remove_assets", assets=["trash_bin_1"])],
    ),
    case(
        "removal", "vague", "couple_of_north_lamps",
        "maybe there are too many lamps on the north side? drop a couple",
        [delta("street_light", -3, -2), kept(*SOUTH_STREET_LIGHTS), guard("street_light")],
        [call("remove_assets", assets=["street_light_1", "street_light_11"])],
    ),
    case(
        "removal", "vague", "thin_out_student_lot",
        "the student lot's too full, thin it out a bit",
        [delta(CARS, -2, -1), guard(*CARS)],
        [call("remove_assets", assets=["suv_1"])],
    ),
    case(
        "removal", "vague", "trees_by_the_quad",
        "lose the tree by the quad",
        [gone("tree_2"), kept("tree_1", "tree_3", "tree_4"), guard("tree")],
        [call("remove_assets", category="tree", near="fountain", count=1)],
    ),
    case(
        "removal", "vague", "empty_lot_b_shot",
        "Lose whatever's standing in the lot B shot. I want the lot empty for this take.",
        [gone(*PARKED_IN_LOT_B), guard(*CARS)],
        [call("remove_assets", assets=PARKED_IN_LOT_B)],
    ),
    case(
        "removal", "vague", "bins_and_dusk",
        "lose the bins and make it dusk",
        [count("trash_bin", 0, 0), env_only("street_lights", "vehicle_lights", time_from="18:30", time_to="21:00"), guard("trash_bin", environment=True)],
        [call("remove_assets", category="trash_bin"), call("set_time_of_day", time="dusk")],
        tags=("compound",),
    ),
    case(
        "removal", "vague", "get_rid_of_new_benches",
        "nah get rid of those new benches, keep the old one",
        [count("bench", 1, 1), kept("bench_1"), guard("bench")],
        [call("remove_assets", assets=["bench_2", "bench_3", "bench_4"])],
        setup=[turn("Add three benches around the fountain.",
                    [call("add_asset", category="bench", count=3, location=at("fountain"))], planned=True)],
    ),
    case(
        "removal", "vague", "too_many_leave_one",
        "ok that's too many, just leave one of them",
        [count("traffic_cone", 1, 1), near("traffic_cone", "parking lot A entrance", 8, scope="all"),
         guard("traffic_cone")],
        [call("remove_assets", assets=["traffic_cone_1", "traffic_cone_2", "traffic_cone_4", "traffic_cone_5"])],
        setup=[turn("Put five cones across the lot A driveway.",
                    [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5, location=point(-85, 8),
                          heading_deg=0)], planned=True)],
    ),
    # --- erroneous ---
    case(
        "removal", "erroneous", "german_lamps_except_stop_sign",
        "Remove all the street lamps, except the one which at the stop sign stands.",
        [gone(*[i for i in ALL_LIGHTS if i != "street_light_6"]), kept("street_light_6"), guard("street_light")],
        [call("remove_assets", assets=[i for i in ALL_LIGHTS if i != "street_light_6"])],
    ),
    case(
        "removal", "erroneous", "spanish_trees_of_fountain",
        "Quit the trees of the fountain, the two.",
        [gone("tree_2", "tree_3"), kept("tree_1", "tree_4"), guard("tree")],
        [call("remove_assets", assets=["tree_2", "tree_3"])],
    ),
    case(
        "removal", "erroneous", "teen_hydrant",
        "ngl that hydrant is ugly af, yeet it",
        [gone("fire_hydrant_1"), guard("fire_hydrant")],
        [call("remove_assets", assets=["fire_hydrant_1"])],
    ),
    case(
        "removal", "erroneous", "bench_sorry_bin",
        "remove the bench - sorry, the bin - at the bus stop",
        [gone("trash_bin_1"), kept("bench_1"), guard("trash_bin")],
        [call("remove_assets", assets=["trash_bin_1"])],
    ),
    case(
        "removal", "erroneous", "hindi_middle_car",
        "Lot B in the middle car, that one remove karo.",
        [gone("suv_1"), kept("passenger_car_1", "passenger_car_2"), guard("suv")],
        [call("remove_assets", assets=["suv_1"])],
    ),
    case(
        "removal", "erroneous", "mandarin_cones_all",
        "Cone all take away.",
        [count("traffic_cone", 0, 0), guard("traffic_cone")],
        [call("remove_assets", category="traffic_cone")],
        setup=[turn("Put five cones across the lot B driveway.",
                    [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5,
                          location=point(47, -7), heading_deg=0)])],
    ),
    case(
        "removal", "erroneous", "typo_tree_by_libary",
        "remvoe the tree closest to the libary",
        [gone("tree_1"), kept("tree_2", "tree_3", "tree_4"), guard("tree")],
        [call("remove_assets", category="tree", near="Library entrance", count=1)],
    ),
    impossible(
        "removal", "erroneous", "zebra_crossings_away",
        "take away the zebra crosings, all four of them pls",
        [call("remove_assets", assets=["crossing_west", "crossing_east", "crossing_south", "crossing_north"])],
    ),
]


def near_asset(asset: str, target: str, within: float) -> Json:
    """A moved asset (by id) lies within `within` m of a target."""
    return {"kind": "near", "asset": asset, "target": target, "within": within}


def at_point(asset: str, x: float, y: float, within: float) -> Json:
    """A moved asset (by id) lies within `within` m of the point (x, y)."""
    return {"kind": "near", "asset": asset, "point": [x, y], "within": within}


def surface(asset: str, *surfaces: str) -> Json:
    return {"kind": "on_surface", "asset": asset, "surfaces": list(surfaces)}


POSITIONING: list[Json] = [
    # --- direct ---
    case(
        "positioning", "direct", "bench_to_fountain",
        "Place the bench next to the fountain.",
        [near_asset("bench_1", "fountain", 6), guard(assets=["bench_1"])],
        [call("place_asset", asset="bench_1", location=at("fountain"))],
    ),
    case(
        "positioning", "direct", "car_2_into_lot_a",
        "Put passenger_car_2 in parking lot A.",
        [near_asset("passenger_car_2", "parking lot A", 0.5),
         {"kind": "behaviour", "asset": "passenger_car_2", "behaviour": "parked"}, guard(assets=["passenger_car_2"])],
        [call("place_asset", asset="passenger_car_2", location=at("parking lot A"))],
    ),
    case(
        "positioning", "direct", "hydrant_exact_coordinates",
        "Condition 4: fire hydrant at (20, -5.5); IV: pedestrian sight lines at the east crosswalk.",
        [at_point("fire_hydrant_1", 20, -5.5, 0.5), guard(assets=["fire_hydrant_1"])],
        [call("place_asset", asset="fire_hydrant_1", location=point(20, -5.5))],
    ),
    case(
        "positioning", "direct", "bin_to_union",
        "Relocate the trash bin to the Student Union entrance.",
        [near_asset("trash_bin_1", "Student Union entrance", 5), guard(assets=["trash_bin_1"])],
        [call("place_asset", asset="trash_bin_1", location=at("Student Union entrance"))],
    ),
    case(
        "positioning", "direct", "car_right_behind_me",
        "Put passenger_car_1 right behind me in my lane.",
        [{"kind": "relative", "asset": "passenger_car_1", "relation": "behind", "target": "ego",
          "max_distance": 20, "tolerance_deg": 20},
         {"kind": "in_lane", "asset": "passenger_car_1", "lane": "main_eastbound"},
         guard(assets=["passenger_car_1"])],
        [call("place_asset", asset="passenger_car_1", location=at("ego", "behind"))],
    ),
    case(
        "positioning", "direct", "stop_sign_coordinates",
        "Put the stop sign on the sidewalk at x=-5.5, y=20.",
        [at_point("stop_sign_1", -5.5, 20, 0.5), surface("stop_sign_1", "sidewalk"), guard(assets=["stop_sign_1"])],
        [call("place_asset", asset="stop_sign_1", location=point(-5.5, 20))],
    ),
    case(
        "positioning", "direct", "bench_and_bin_to_fountain",
        "1. Put the bench at the fountain.\n2. Put the bin right beside it.",
        [near_asset("bench_1", "fountain", 6), near_asset("trash_bin_1", "bench_1", 3),
         guard(assets=["bench_1", "trash_bin_1"])],
        [call("place_asset", asset="bench_1", location=at("fountain")),
         call("place_asset", asset="trash_bin_1", location=at("bench_1", "next_to"))],
        tags=("compound",),
    ),
    impossible(
        "positioning", "direct", "signal_in_junction_centre",
        "Place traffic_light_1 at x = 0, y = 0, in the middle of the crossroads.",
        [call("place_asset", asset="traffic_light_1", location=point(0, 0))],
    ),
    # --- indirect ---
    case(
        "positioning", "indirect", "hydrant_to_library_sidewalk",
        "Relocate the hydrant to the sidewalk in front of the Library.",
        [near_asset("fire_hydrant_1", "Library entrance", 12), surface("fire_hydrant_1", "sidewalk"),
         guard(assets=["fire_hydrant_1"])],
        [call("place_asset", asset="fire_hydrant_1", location=at("Library entrance", "on_sidewalk"))],
    ),
    case(
        "positioning", "indirect", "suv_to_jtekt_dropoff",
        "The SUV is in my shot. Move it out of frame: park it at the JTEKT drop-off.",
        [near_asset("suv_1", "JTEKT building entrance", 8), surface("suv_1", "drivable"), guard(assets=["suv_1"])],
        [call("place_asset", asset="suv_1", location=at("JTEKT building entrance"))],
    ),
    case(
        "positioning", "indirect", "bin_beside_bench",
        "The bin should stand right beside the bench, not 7 m away from it.",
        [near_asset("trash_bin_1", "bench_1", 2.5), moved("trash_bin_1", min_distance=3), guard(assets=["trash_bin_1"])],
        [call("place_asset", asset="trash_bin_1", location=at("bench_1", "next_to"))],
    ),
    case(
        "positioning", "indirect", "car_before_back_gate",
        "Park passenger_car_2 up ahead of me, just before the back gate.",
        [near_asset("passenger_car_2", "east gate", 12), surface("passenger_car_2", "drivable"),
         guard(assets=["passenger_car_2"])],
        [call("place_asset", asset="passenger_car_2",
              location=at("east gate", "in_lane", lane="main_eastbound"))],
    ),
    case(
        "positioning", "indirect", "replant_tree_for_shade",
        "Replant the tree that stands by the fountain so that it shades the bench at the bus stop.",
        [near_asset("tree_2", "bench_1", 5), guard(assets=["tree_2"])],
        [call("place_asset", asset="tree_2", location=at("bench_1", "next_to"))],
    ),
    case(
        "positioning", "indirect", "bench_should_be_at_lot_a",
        "The bench should be at the lot A entrance.",
        [near_asset("bench_1", "parking lot A entrance", 6), guard(assets=["bench_1"])],
        [call("place_asset", asset="bench_1", location=at("parking lot A entrance"))],
    ),
    case(
        "positioning", "indirect", "car_in_library_dropoff",
        "Put passenger_car_1 in the drop-off bay in front of the Library.",
        [near_asset("passenger_car_1", "Library entrance", 8), surface("passenger_car_1", "drivable"),
         guard(assets=["passenger_car_1"])],
        [call("place_asset", asset="passenger_car_1", location=at("Library entrance"))],
    ),
    case(
        "positioning", "indirect", "swap_bench_and_bin",
        "Swap the bench and the bin at the bus stop.",
        [at_point("bench_1", -33.5, -5.5, 1.5), at_point("trash_bin_1", -26, -6.9, 1.5),
         guard(assets=["bench_1", "trash_bin_1"])],
        [call("place_asset", asset="trash_bin_1", location=point(-30, -8)),
         call("place_asset", asset="bench_1", location=point(-33.5, -5.5)),
         call("place_asset", asset="trash_bin_1", location=point(-26, -6.9))],
        tags=("compound",),
    ),
    case(
        "positioning", "indirect", "cones_to_lot_a_instead",
        "Actually, move them to the lot A entrance instead.",
        [count("traffic_cone", 3, 3),
         near("traffic_cone", "parking lot A entrance", 8, scope="all", require_all=True),
         guard("traffic_cone")],
        [call("place_asset", asset=f"traffic_cone_{n}", location=at("parking lot A entrance")) for n in (1, 2, 3)],
        setup=[turn("Put three cones at the lot B entrance.",
                    [call("add_asset", category="traffic_cone", count=3, location=at("parking lot B entrance"))],
                    planned=True)],
    ),
    impossible(
        "positioning", "indirect", "suv_past_the_east_gate",
        "Put the SUV 40 m past the east gate, out where Main Street leaves campus.",
        [call("place_asset", asset="suv_1", location=point(140, -1.75))],
    ),
    # --- vague ---
    case(
        "positioning", "vague", "bench_somewhere_shady",
        "put the bench somewhere shady",
        [moved("bench_1", min_distance=1), guard(assets=["bench_1"])],
        [call("place_asset", asset="bench_1", location=at("tree_2", "next_to"))],
        alternatives=[[near_asset("bench_1", f"tree_{n}", 4)] for n in (1, 2, 3, 4)],
    ),
    case(
        "positioning", "vague", "bin_near_library",
        "stick the bin somewhere near the library",
        [near_asset("trash_bin_1", "Library entrance", 10), moved("trash_bin_1", min_distance=1),
         guard(assets=["trash_bin_1"])],
        [call("place_asset", asset="trash_bin_1", location=at("Library entrance"))],
    ),
    case(
        "positioning", "vague", "hydrant_closer_to_jtekt",
        "the hydrant is kind of far from the JTEKT building, bring it closer",
        [near_asset("fire_hydrant_1", "JTEKT building entrance", 15), guard(assets=["fire_hydrant_1"])],
        [call("place_asset", asset="fire_hydrant_1", location=at("JTEKT building entrance", "on_sidewalk"))],
    ),
    case(
        "positioning", "vague", "lot_b_car_next_to_me",
        "put one of the lot b cars next to me",
        [near(CARS, "ego", 6, scope="touched"), delta(CARS, 0), guard(*CARS)],
        [call("place_asset", asset="passenger_car_1", location=at("ego", "next_to"))],
        alternatives=[[{"kind": "relative", "category": CARS, "relation": side, "target": "ego",
                        "max_distance": 8, "tolerance_deg": 45}] for side in ("left_of", "right_of")],
    ),
    case(
        "positioning", "vague", "bench_with_fountain_view",
        "move the bench somewhere with a nice view of the fountain",
        [near_asset("bench_1", "fountain", 12), guard(assets=["bench_1"])],
        [call("place_asset", asset="bench_1", location=at("fountain"))],
    ),
    case(
        "positioning", "vague", "hydrant_if_not_on_sidewalk",
        "if the hydrant isn't on a sidewalk, put it on one",
        [kept("fire_hydrant_1"), guard()],
        [call("find_assets", category="fire_hydrant")],
    ),
    case(
        "positioning", "vague", "cone_a_bit_further",
        "hmm, move it a bit further up, like 10 more metres",
        [moved("traffic_cone_1", min_distance=7, max_distance=13),
         at_point("traffic_cone_1", -35, -1.75, 4),
         guard("traffic_cone")],
        [call("place_asset", asset="traffic_cone_1", location=at("ego", along_m=25))],
        setup=[turn("Drop a cone 15 m ahead of me in my lane.",
                    [call("add_asset", category="traffic_cone", location=at("ego", along_m=15))], planned=True)],
    ),
    case(
        "positioning", "vague", "truck_out_of_the_way",
        "eh, that's blocking everything. stick it somewhere it's not in the way",
        [moved("truck_1", min_distance=12), {"kind": "on_surface", "asset": "truck_1", "surfaces": ["paved"]},
         guard(assets=["truck_1"])],
        [call("place_asset", asset="truck_1", location=at("parking lot A"))],
        setup=[turn("Park a delivery truck in the middle of the crossroads.",
                    [call("add_asset", category="truck", location=at("main intersection"))])],
    ),
    # --- erroneous ---
    case(
        "positioning", "erroneous", "german_bench_before_library",
        "The bench put you please at the library before the entrance.",
        [near_asset("bench_1", "Library entrance", 6), guard(assets=["bench_1"])],
        [call("place_asset", asset="bench_1", location=at("Library entrance", "in_front_of"))],
    ),
    case(
        "positioning", "erroneous", "spanish_suv_west_parking",
        "Put the SUV in the parking of the west.",
        [near_asset("suv_1", "parking lot A", 0.5), guard(assets=["suv_1"])],
        [call("place_asset", asset="suv_1", location=at("parking lot A"))],
    ),
    case(
        "positioning", "erroneous", "teen_hydrant_fountain",
        "can u put the hydrant by the fountain pls",
        [near_asset("fire_hydrant_1", "fountain", 6), guard(assets=["fire_hydrant_1"])],
        [call("place_asset", asset="fire_hydrant_1", location=at("fountain"))],
    ),
    case(
        "positioning", "erroneous", "plase_bin_nxt_stopp",
        "plase the bin nxt to the stopp sign",
        [near_asset("trash_bin_1", "stop_sign_1", 3), guard(assets=["trash_bin_1"])],
        [call("place_asset", asset="trash_bin_1", location=at("stop_sign_1", "next_to"))],
    ),
    case(
        "positioning", "erroneous", "lot_a_no_lot_b_entrance",
        "put the bench at lot A - no, sorry, at the lot B entrance",
        [near_asset("bench_1", "parking lot B entrance", 6), guard(assets=["bench_1"])],
        [call("place_asset", asset="bench_1", location=at("parking lot B entrance"))],
    ),
    case(
        "positioning", "erroneous", "hindi_tree_to_union",
        "Tree which is near fountain, that one keep near the Student Union door.",
        [near_asset("tree_2", "Student Union entrance", 8), guard(assets=["tree_2"])],
        [call("place_asset", asset="tree_2", location=at("Student Union entrance"))],
    ),
    case(
        "positioning", "erroneous", "mandarin_hydrant_bus_stop",
        "Hydrant put to bus stop side.",
        [near_asset("fire_hydrant_1", "bus stop", 5), guard(assets=["fire_hydrant_1"])],
        [call("place_asset", asset="fire_hydrant_1", location=at("bus stop"))],
    ),
    impossible(
        "positioning", "erroneous", "car_on_library_footpath",
        "park the car 1 on the footpath of library please, on the footpath itself",
        [call("place_asset", asset="passenger_car_1", location=at("Library entrance", "on_sidewalk"))],
    ),
]


def does(behaviour: str | list[str], **more: Any) -> Json:
    """A behaviour check (category or asset given in `more`)."""
    return {"kind": "behaviour", "behaviour": behaviour, **more}


def scenario(seconds: float, *expect: Json) -> Json:
    return {"kind": "scenario", "seconds": seconds, "expect": list(expect)}


MOVING: list[Json] = [
    # --- direct ---
    case(
        "moving", "direct", "suv_five_forward",
        "Move the SUV 5 m forward.",
        [moved("suv_1", min_distance=4.5, max_distance=5.5, direction="forward", turn_max_deg=10), guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", forward=5)],
    ),
    case(
        "moving", "direct", "condition_8_ego_speed",
        "Condition 8: ego at 8 m/s in main_eastbound; IV: braking distance.",
        [does("drive_lane", asset="ego", lane="main_eastbound", speed_min=7.9, speed_max=8.1), guard(assets=["ego"])],
        [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 8})],
    ),
    case(
        "moving", "direct", "car_1_drives_westbound",
        "passenger_car_1 should be driving along main_westbound at 5 m/s.",
        [does("drive_lane", asset="passenger_car_1", lane="main_westbound", speed_min=4.9, speed_max=5.1),
         guard(assets=["passenger_car_1"])],
        [call("set_behaviour", asset="passenger_car_1",
              behaviour={"kind": "drive_lane", "lane": "main_westbound", "speed": 5})],
    ),
    case(
        "moving", "direct", "turn_bench_90",
        "Turn the bench 90 degrees where it stands.",
        [moved("bench_1", max_distance=0.5, turn_min_deg=85, turn_max_deg=95), guard(assets=["bench_1"])],
        [call("move_asset", asset="bench_1", turn_deg=90)],
    ),
    case(
        "moving", "direct", "hydrant_three_east",
        "Move the fire hydrant 3 m east.",
        [moved("fire_hydrant_1", min_distance=2.5, max_distance=3.5, direction="forward", turn_max_deg=10),
         at_point("fire_hydrant_1", 19, 5.5, 0.6), guard(assets=["fire_hydrant_1"])],
        [call("move_asset", asset="fire_hydrant_1", east=3)],
    ),
    case(
        "moving", "direct", "condition_9_brake_at_4s",
        "Condition 9: at t = 4 s the ego brakes hard (6 m/s^2) to a stop.",
        [scenario(8, {"kind": "event", "actor": "ego", "manoeuvre": "stop", "trigger": "simulation_time"},
                  {"kind": "stopped_before", "actor": "ego", "line": [-33.2, -1.75]}),
         guard()],
        [call("add_event", actor="ego", manoeuvre={"kind": "stop", "rate": 6}, when={"kind": "time", "seconds": 4})],
    ),
    case(
        "moving", "direct", "numbered_suv_forward_then_turn",
        "1. Move the SUV 3 m forward.\n2. Then turn it 90 degrees to the left.",
        [moved("suv_1", min_distance=2.5, max_distance=3.5, turn_min_deg=85, turn_max_deg=95),
         at_point("suv_1", 23, -39, 0.6), guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", forward=3), call("move_asset", asset="suv_1", turn_deg=90)],
        tags=("compound",),
    ),
    case(
        "moving", "direct", "truck_to_3_mps",
        "Make the truck go 3 m/s.",
        [does("drive_lane", category="truck", speed_min=2.9, speed_max=3.1, lane="main_westbound"), delta("truck", 0),
         guard("truck")],
        [call("set_behaviour", asset="truck_1", behaviour={"kind": "drive_lane", "lane": "main_westbound", "speed": 3})],
        setup=[turn("Add a truck driving west on Main Street.",
                    [call("add_asset", category="truck", behaviour={"kind": "drive_lane", "lane": "main_westbound"})])],
    ),
    impossible(
        "moving", "direct", "hydrant_circles",
        "Make the fire hydrant drive in circles in lot B.",
        [call("set_behaviour", asset="fire_hydrant_1", behaviour={"kind": "circle", "centre": "parking lot B"})],
    ),
    # --- indirect ---
    case(
        "moving", "indirect", "back_car_2_out_of_bay",
        "Back passenger_car_2 out of its bay by 3 metres.",
        [moved("passenger_car_2", min_distance=2.5, max_distance=3.5, direction="backward", turn_max_deg=10),
         guard(assets=["passenger_car_2"])],
        [call("move_asset", asset="passenger_car_2", forward=-3)],
    ),
    case(
        "moving", "indirect", "someone_darts_out",
        "Have someone dart out in front of me up ahead, not at a crosswalk.",
        [delta("pedestrian", 1), does("jaywalk", category="pedestrian", crosses_lane="main_eastbound", scope="added"),
         guard("pedestrian")],
        [call("add_asset", category="pedestrian", behaviour={"kind": "jaywalk"})],
    ),
    case(
        "moving", "indirect", "now_have_them_cross",
        "Now have them walk across.",
        [does("cross_road", category="pedestrian", crosses_lane="campus_northbound"), delta("pedestrian", 0),
         guard("pedestrian")],
        [call("set_behaviour", asset="pedestrian_1", behaviour={"kind": "cross_road"})],
        setup=[turn("Add a pedestrian waiting at the north crosswalk.",
                    [call("add_asset", category="pedestrian", location=at("north crosswalk"))])],
    ),
    case(
        "moving", "indirect", "ego_walking_pace",
        "Slow me down to walking pace.",
        [does("drive_lane", asset="ego", lane="main_eastbound", speed_min=0.8, speed_max=2.2), guard(assets=["ego"])],
        [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 1.4})],
    ),
    case(
        "moving", "indirect", "suv_pulls_out_east",
        "Action on the SUV: it pulls out of lot B and heads east along Main Street, out of frame.",
        [does("drive_lane", asset="suv_1", lane="main_eastbound"), guard(assets=["suv_1"])],
        [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
    ),
    case(
        "moving", "indirect", "hydrant_other_side",
        "Relocate the hydrant across Main Street: shift it due south to the far sidewalk.",
        [moved("fire_hydrant_1", min_distance=9, max_distance=13, direction="right", turn_max_deg=10),
         surface("fire_hydrant_1", "sidewalk", "ground"), guard(assets=["fire_hydrant_1"])],
        [call("move_asset", asset="fire_hydrant_1", north=-11)],
    ),
    case(
        "moving", "indirect", "robot_laps",
        "Make it do laps, 6 m radius.",
        [does("circle", category="ackermann_robot", radius_min=5.5, radius_max=6.5), delta("ackermann_robot", 0),
         guard("ackermann_robot")],
        [call("set_behaviour", asset="ackermann_robot_1", behaviour={"kind": "circle", "radius": 6})],
        setup=[turn("Put a small robot in lot A.",
                    [call("add_asset", category="ackermann_robot", location=at("parking lot A"))], planned=True)],
    ),
    case(
        "moving", "indirect", "suv_east_and_ego_slow",
        "Have the SUV drive east on Main Street, and slow the ego down to 3 m/s.",
        [does("drive_lane", asset="suv_1", lane="main_eastbound"),
         does("drive_lane", asset="ego", speed_min=2.9, speed_max=3.1),
         guard(assets=["suv_1", "ego"])],
        [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"}),
         call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 3})],
        tags=("compound",),
    ),
    case(
        "moving", "indirect", "hold_my_light_red",
        "Keep the signal I'm driving towards on red so I have to wait at it.",
        [scenario(15, {"kind": "stopped_before", "actor": "ego", "line": [-11.5, -1.75]},
                  {"kind": "reached", "actor": "ego", "place": "-17, -1.75", "within": 3}),
         guard()],
        [call("set_light_phases", light="traffic_light_1", phases=[{"state": "red", "duration": 600}])],
    ),
    impossible(
        "moving", "indirect", "bin_rolls_across",
        "For the gag shot, make the bin roll across the zebra crossing all by itself.",
        [call("set_behaviour", asset="trash_bin_1", behaviour={"kind": "cross_road"})],
    ),
    # --- vague ---
    case(
        "moving", "vague", "nudge_bench",
        "nudge the bench a little",
        [moved("bench_1", min_distance=0.2, max_distance=3), guard(assets=["bench_1"])],
        [call("move_asset", asset="bench_1", forward=1)],
    ),
    case(
        "moving", "vague", "get_parked_cars_moving",
        "get the parked cars moving",
        [does(["drive_lane", "follow_path", "circle"], category=CARS, scope="all", min_count=3, require_all=True),
         guard(*CARS)],
        [call("set_behaviour", asset="passenger_car_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"}),
         call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_westbound"}),
         call("set_behaviour", asset="passenger_car_2", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
    ),
    case(
        "moving", "vague", "bit_quicker",
        "can we go a bit quicker?",
        [does("drive_lane", asset="ego", lane="main_eastbound", speed_min=5.5, speed_max=12), guard(assets=["ego"])],
        [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 7})],
    ),
    case(
        "moving", "vague", "suv_bit_left",
        "shift the SUV a bit to its left",
        [moved("suv_1", min_distance=0.3, max_distance=1.8, direction="left", turn_max_deg=10), guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", left=1)],
    ),
    case(
        "moving", "vague", "someone_crossing",
        "have somebody crossing the road somewhere",
        [delta("pedestrian", 1, 3),
         does(["cross_road", "jaywalk", "follow_path"], category="pedestrian", scope="added"),
         guard("pedestrian")],
        [call("add_asset", category="pedestrian", location=at("west crosswalk"), behaviour={"kind": "cross_road"})],
    ),
    case(
        "moving", "vague", "ego_should_stop_sometime",
        "the ego should stop at some point, maybe after a few seconds?",
        [scenario(10, {"kind": "event", "actor": "ego", "manoeuvre": "stop"}), guard()],
        [call("add_event", actor="ego", manoeuvre={"kind": "stop"}, when={"kind": "time", "seconds": 4})],
    ),
    case(
        "moving", "vague", "if_suv_still_in_lot",
        "if the SUV's still in lot B, nudge it forward a couple of metres",
        [moved("suv_1", min_distance=1.5, max_distance=3.5, direction="forward", turn_max_deg=10), guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", forward=2)],
    ),
    case(
        "moving", "vague", "spin_me_around",
        "spin me around, I want to head back west",
        [does("drive_lane", asset="ego", lane="main_westbound"), guard(assets=["ego"])],
        [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_westbound"})],
    ),
    case(
        "moving", "vague", "get_things_moving",
        "let's get things moving: maybe the SUV drives off, and someone crosses at the zebra crossing?",
        [does("drive_lane", asset="suv_1"), delta("pedestrian", 1),
         does("cross_road", category="pedestrian", scope="added"), near("pedestrian", "west crosswalk", 8),
         guard("pedestrian", assets=["suv_1"])],
        [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"}),
         call("add_asset", category="pedestrian", location=at("west crosswalk"), behaviour={"kind": "cross_road"})],
        tags=("compound",),
    ),
    # --- erroneous ---
    case(
        "moving", "erroneous", "german_suv_forward",
        "The SUV shall 4 meters to the front drive.",
        [moved("suv_1", min_distance=3.5, max_distance=4.5, direction="forward", turn_max_deg=10), guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", forward=4)],
    ),
    case(
        "moving", "erroneous", "spanish_car_east_lane",
        "Make that the car one goes for the lane of the east direction.",
        [does("drive_lane", asset="passenger_car_1", lane="main_eastbound"), guard(assets=["passenger_car_1"])],
        [call("set_behaviour", asset="passenger_car_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
    ),
    case(
        "moving", "erroneous", "teen_too_fast",
        "make the ego go slower its 2 fast rn",
        [does("drive_lane", asset="ego", lane="main_eastbound", speed_max=4.5), guard(assets=["ego"])],
        [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 3})],
    ),
    case(
        "moving", "erroneous", "benhc_arround",
        "turn the benhc arround 180 degres",
        [moved("bench_1", max_distance=0.5, turn_min_deg=175), guard(assets=["bench_1"])],
        [call("move_asset", asset="bench_1", turn_deg=180)],
    ),
    case(
        "moving", "erroneous", "bench_east_sorry_west",
        "move the bench 2 m east - sorry, west",
        [moved("bench_1", min_distance=1.5, max_distance=2.5, turn_max_deg=10), at_point("bench_1", -28, -6.9, 0.6),
         guard(assets=["bench_1"])],
        [call("move_asset", asset="bench_1", east=-2)],
    ),
    case(
        "moving", "erroneous", "hindi_ego_three",
        "Ego car speed make 3 meter per second only.",
        [does("drive_lane", asset="ego", speed_min=2.9, speed_max=3.1), guard(assets=["ego"])],
        [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 3})],
    ),
    case(
        "moving", "erroneous", "mandarin_walk_north_crossing",
        "Let one pedestrian walk across at north crossing.",
        [delta("pedestrian", 1),
         does("cross_road", category="pedestrian", crosses_lane="campus_northbound", scope="added"),
         guard("pedestrian")],
        [call("add_asset", category="pedestrian", location=at("north crosswalk"), behaviour={"kind": "cross_road"})],
    ),
    case(
        "moving", "erroneous", "suv_ten_feet",
        "move the suv forwrd 10 feet",
        [moved("suv_1", min_distance=2.6, max_distance=3.6, direction="forward", turn_max_deg=10), guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", forward=3.05)],
    ),
    impossible(
        "moving", "erroneous", "suv_150_est",
        "move the suv 150m est",
        [call("move_asset", asset="suv_1", east=150)],
    ),
]


def layout(category: str | list[str], shape: str, **more: Any) -> Json:
    """The added assets of a category, together, form a line or a ring."""
    return {"kind": "arrangement", "category": category, "shape": shape, **more}


ARRANGEMENT: list[Json] = [
    # --- direct ---
    case(
        "arrangement", "direct", "bench_ring_fountain",
        "The fountain should be ringed by six benches.",
        [delta("bench", 6), layout("bench", "ring", around="fountain", min_count=6), guard("bench")],
        [call("arrange_assets", categories=["bench"], shape="ring", count=6, location=at("fountain"))],
    ),
    case(
        "arrangement", "direct", "barrier_line_lot_b_entrance",
        "Put a line of 5 road barriers at the lot B entrance.",
        [delta("road_barrier", 5), layout("road_barrier", "line", min_count=5),
         near("road_barrier", "parking lot B entrance", 8, require_all=True), guard("road_barrier")],
        [call("arrange_assets", categories=["road_barrier"], shape="line", count=5,
              location=at("parking lot B entrance", "in_front_of"))],
    ),
    case(
        "arrangement", "direct", "cone_ring_crossroads",
        "Put a ring of 8 cones in the middle of the crossroads, 4 m radius.",
        [delta("traffic_cone", 8), layout("traffic_cone", "ring", around="main intersection", min_count=8),
         near("traffic_cone", "main intersection", 0.5, require_all=True),
         near_point("traffic_cone", 0, 0, 5, require_all=True), guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=8, radius=4,
              location=at("main intersection"))],
    ),
    case(
        "arrangement", "direct", "suv_parking_row_lot_a",
        "Deploy a parking row of 4 SUVs in lot A.",
        [delta("suv", 4), near("suv", "parking lot A", 0.5, require_all=True),
         layout("suv", "line", min_count=4, spacing_min=2.3, spacing_max=4), guard("suv")],
        [call("arrange_assets", categories=["suv"], shape="parking_row", count=4, location=at("parking lot A"))],
    ),
    case(
        "arrangement", "direct", "condition_10_lane_edge_cones",
        "Condition 10: 10 cones along the right edge of main_eastbound, starting at the lot B entrance, 3 m apart.",
        [delta("traffic_cone", 10),
         {"kind": "in_lane", "category": "traffic_cone", "lane": "main_eastbound", "scope": "added"},
         layout("traffic_cone", "line", min_count=10, spacing_min=2.5, spacing_max=3.5),
         near("traffic_cone", "parking lot B entrance", 35, require_all=True),
         guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=10, spacing=3,
              location=at("parking lot B entrance", lane="main_eastbound"))],
    ),
    case(
        "arrangement", "direct", "bollards_jtekt_entrance",
        "Put a line of 6 bollards in front of the JTEKT entrance.",
        [delta("bollard", 6), layout("bollard", "line", min_count=6),
         near("bollard", "JTEKT building entrance", 8, require_all=True), guard("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="line", count=6,
              location=at("JTEKT building entrance", "in_front_of"))],
    ),
    case(
        "arrangement", "direct", "cones_and_sign_lot_a_driveway",
        "Line 5 cones across the lot A driveway and put a construction sign next to them.",
        [delta("traffic_cone", 5), delta("construction_sign", 1), layout("traffic_cone", "line", min_count=5),
         near("traffic_cone", "parking lot A entrance", 8, require_all=True),
         near("construction_sign", "parking lot A entrance", 10),
         guard("traffic_cone", "construction_sign")],
        [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5, location=point(-85, 8),
              heading_deg=0),
         call("add_asset", category="construction_sign", location=at("traffic_cone_5", "next_to"))],
        tags=("compound",),
    ),
    impossible(
        "arrangement", "direct", "twelve_buses_main_street",
        "Arrange a line of 12 buses along Main Street.",
        [call("arrange_assets", categories=["bus"], shape="line", count=12, location=at("main_westbound", "in_lane"))],
    ),
    # --- indirect ---
    case(
        "arrangement", "indirect", "close_lot_b_driveway",
        "Close off the lot B driveway to traffic.",
        [near(["road_barrier", "traffic_cone"], "parking lot B entrance", 8, min_count=2),
         near_point(["road_barrier", "traffic_cone"], 47, -7.75, 4.3, require_all=True),
         guard("road_barrier", "traffic_cone")],
        [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, location=point(47, -7),
              heading_deg=0)],
        alternatives=[[delta("road_barrier", 2, 8), layout("road_barrier", "line", min_count=2)],
                      [delta("traffic_cone", 3, 15), layout("traffic_cone", "line", min_count=3)]],
    ),
    case(
        "arrangement", "indirect", "visitors_row_lot_a",
        "We're expecting visitors for the open day. Lay out a row of parked cars in lot A.",
        [delta(CARS, 3, 12), near(CARS, "parking lot A", 0.5, require_all=True),
         layout(CARS, "line", min_count=3), guard(*CARS)],
        [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=5, location=at("parking lot A"))],
    ),
    case(
        "arrangement", "indirect", "cordon_the_debris",
        "Cordon that debris off with cones.",
        [delta("traffic_cone", 4, 16), layout("traffic_cone", "ring", around="cement_rubble_1", min_count=4),
         guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=8, location=at("cement_rubble_1"))],
        setup=[turn("Drop a pile of debris in the middle of the crossroads.",
                    [call("add_asset", category="cement_rubble", location=at("main intersection"))])],
    ),
    case(
        "arrangement", "indirect", "stunt_marks_lot_a",
        "Lay out marks for the stunt: a straight row of 6 cones down the middle of lot A, 4 m apart.",
        [delta("traffic_cone", 6), layout("traffic_cone", "line", min_count=6, spacing_min=3.5, spacing_max=4.5),
         near("traffic_cone", "parking lot A", 0.5, require_all=True), guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="line", count=6, spacing=4,
              location=at("parking lot A"))],
    ),
    case(
        "arrangement", "indirect", "queue_ahead_of_me",
        "Build me a queue of traffic ahead: three cars lined up in my lane.",
        [delta(["passenger_car", "suv", "truck"], 3),
         {"kind": "in_lane", "category": ["passenger_car", "suv", "truck"], "lane": "main_eastbound", "scope": "added"},
         {"kind": "relative", "category": ["passenger_car", "suv", "truck"], "relation": "in_front_of", "target": "ego",
          "max_distance": 80, "tolerance_deg": 10, "scope": "added", "require_all": True},
         layout(["passenger_car", "suv", "truck"], "line", min_count=3),
         guard("passenger_car", "suv", "truck")],
        [call("arrange_assets", categories=["passenger_car"], shape="line", count=3, location=at("ego", along_m=20))],
    ),
    case(
        "arrangement", "indirect", "benches_along_library_front",
        "Give students somewhere to sit along the front of the library: a row of four benches.",
        [delta("bench", 4), layout("bench", "line", min_count=4),
         near("bench", "Library entrance", 8, require_all=True), guard("bench")],
        [call("arrange_assets", categories=["bench"], shape="line", count=4,
              location=at("Library entrance", "in_front_of"))],
    ),
    case(
        "arrangement", "indirect", "markdown_work_zone",
        "Work zone on Campus Drive, north of the junction:\n- a row of 6 cones along the northbound lane edge\n- one roadworks sign where it starts",
        [delta("traffic_cone", 6), delta("construction_sign", 1),
         {"kind": "in_lane", "category": "traffic_cone", "lane": "campus_northbound", "scope": "added"},
         layout("traffic_cone", "line", min_count=6),
         near("construction_sign", "north crosswalk", 12),
         guard("traffic_cone", "construction_sign")],
        [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=6,
              location=at("north crosswalk", lane="campus_northbound")),
         call("add_asset", category="construction_sign", location=at("north crosswalk", "on_sidewalk"))],
        tags=("compound",),
    ),
    impossible(
        "arrangement", "indirect", "lakeside_promenade",
        "Set up a row of benches along the lakeside promenade for the picnic scene.",
        [call("arrange_assets", categories=["bench"], shape="line", count=4, location=at("lakeside promenade"))],
    ),
    # --- vague ---
    case(
        "arrangement", "vague", "some_cones_lot_b",
        "throw some cones around lot B",
        [delta("traffic_cone", 2, 30), near("traffic_cone", "parking lot B", 0.5, require_all=True), guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="grid", count=6, location=at("parking lot B"))],
    ),
    case(
        "arrangement", "vague", "little_work_zone",
        "set up a little work zone on Campus Drive north of the junction",
        [delta("traffic_cone", 2, 30), near_point("traffic_cone", 0, 30, 21, require_all=True),
         {"kind": "on_surface", "category": "traffic_cone", "surfaces": ["drivable"], "scope": "added"},
         guard("traffic_cone", "construction_sign", "road_barrier")],
        [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=6,
              location=at("north crosswalk", lane="campus_northbound"))],
    ),
    case(
        "arrangement", "vague", "circle_of_people",
        "can u make like a circle of ppl around the fountain",
        [delta("pedestrian", 4, 30), layout("pedestrian", "ring", around="fountain", min_count=4), guard("pedestrian")],
        [call("arrange_assets", categories=["pedestrian"], shape="ring", count=8, location=at("fountain"))],
    ),
    case(
        "arrangement", "vague", "block_off_lot_a",
        "block off lot A somehow",
        [near(["road_barrier", "traffic_cone", "bollard"], "parking lot A entrance", 8, min_count=2),
         guard("road_barrier", "traffic_cone", "bollard")],
        [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, location=point(-85, 8),
              heading_deg=0)],
        alternatives=[[layout(cat, "line", min_count=2)] for cat in ("road_barrier", "traffic_cone", "bollard")],
    ),
    case(
        "arrangement", "vague", "bins_and_benches_bus_stop",
        "maybe a row of bins and benches along the sidewalk by the bus stop?",
        [delta("bench", 1, 6), delta("trash_bin", 1, 6), layout(["bench", "trash_bin"], "line", min_count=3),
         near(["bench", "trash_bin"], "bus stop", 12, require_all=True), guard("bench", "trash_bin")],
        [call("arrange_assets", categories=["trash_bin", "bench"], shape="line", count=4, location=point(-22, -5.5),
              heading_deg=0)],
    ),
    case(
        "arrangement", "vague", "fill_empty_half_lot_b",
        "fill the empty half of lot B with parked cars",
        [delta(CARS, 3, 30), near(CARS, "parking lot B", 0.5, require_all=True),
         near_point(CARS, 50, -29, 14, require_all=True), guard(*CARS)],
        [call("arrange_assets", categories=["passenger_car"], shape="grid", count=6, columns=3,
              location=point(50, -29))],
    ),
    case(
        "arrangement", "vague", "make_that_line_longer",
        "hmm make the line longer, like two more",
        [delta("traffic_cone", 2), count("traffic_cone", 6, 6),
         layout("traffic_cone", "line", scope="all", min_count=6, tolerance=1.5), guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="line", count=2, location=point(-96, 30),
              heading_deg=90, spacing=2)],
        setup=[turn("Put a line of 4 cones down lot A's west side, 2 m apart.",
                    [call("arrange_assets", categories=["traffic_cone"], shape="line", count=4,
                          location=point(-96, 24), heading_deg=90, spacing=2)], planned=True)],
    ),
    case(
        "arrangement", "vague", "order_in_lot_a",
        "lot A needs some order. maybe a row of parked cars, and a line of cones beside the row?",
        [delta(CARS, 2, 12), near(CARS, "parking lot A", 0.5, require_all=True), layout(CARS, "line", min_count=2),
         delta("traffic_cone", 2, 20), near("traffic_cone", "parking lot A", 0.5, require_all=True),
         layout("traffic_cone", "line", min_count=2), guard("traffic_cone", *CARS)],
        [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4, location=at("parking lot A")),
         call("arrange_assets", categories=["traffic_cone"], shape="line", count=5, location=point(-92, 29),
              heading_deg=90)],
        tags=("compound",),
    ),
    # --- erroneous ---
    case(
        "arrangement", "erroneous", "german_cones_over_street",
        "Make please a line from 5 cones over the street at the library, so that nobody can drive through.",
        [delta("traffic_cone", 5), layout("traffic_cone", "line", min_count=5),
         {"kind": "in_lane", "category": "traffic_cone", "lane": "main_eastbound", "scope": "added",
          "require_all": False, "min_count": 2},
         {"kind": "in_lane", "category": "traffic_cone", "lane": "main_westbound", "scope": "added",
          "require_all": False, "min_count": 2},
         near("traffic_cone", "Library entrance", 20, require_all=True),
         guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5, spacing=1.5,
              location=point(-41, 0), heading_deg=90)],
    ),
    case(
        "arrangement", "erroneous", "spanish_trees_in_line",
        "Put four trees in line in the side of the parking A.",
        [delta("tree", 4), layout("tree", "line", min_count=4),
         near("tree", "parking lot A", 8, require_all=True), guard("tree")],
        [call("arrange_assets", categories=["tree"], shape="line", count=4, location=at("parking lot A"))],
    ),
    case(
        "arrangement", "erroneous", "teen_scooter_row",
        "pls make a row of 5 scooters outside the union",
        [delta("motorcycle", 5), layout("motorcycle", "line", min_count=5),
         near("motorcycle", "Student Union entrance", 16, require_all=True), guard("motorcycle")],
        [call("arrange_assets", categories=["motorcycle"], shape="parking_row", count=5,
              location=at("Student Union entrance"))],
    ),
    case(
        "arrangement", "erroneous", "rign_of_cones_crossroads",
        "put a rign of 6 cones in teh middle of the crossraods",
        [delta("traffic_cone", 6), layout("traffic_cone", "ring", around="main intersection", min_count=6),
         near("traffic_cone", "main intersection", 0.5, require_all=True), guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=6, location=at("main intersection"))],
    ),
    case(
        "arrangement", "erroneous", "barriers_no_cones_lot_a_driveway",
        "line of four barriers - no, make it cones, six of them - across the lot A driveway",
        [delta("traffic_cone", 6), layout("traffic_cone", "line", min_count=6),
         near("traffic_cone", "parking lot A entrance", 8, require_all=True), guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="line", count=6, location=point(-85, 8),
              heading_deg=0)],
    ),
    case(
        "arrangement", "erroneous", "hindi_ten_car_row",
        "Lot B in, ten cars parking row make please.",
        [delta("passenger_car", 10), near("passenger_car", "parking lot B", 0.5, require_all=True),
         layout("passenger_car", "line", min_count=10), guard("passenger_car")],
        [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=10, heading_deg=90,
              location=at("parking lot B"))],
    ),
    case(
        "arrangement", "erroneous", "mandarin_bollard_line",
        "Library front, bollard make one line, four piece.",
        [delta("bollard", 4), layout("bollard", "line", min_count=4),
         near("bollard", "Library entrance", 8, require_all=True), guard("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="line", count=4,
              location=at("Library entrance", "in_front_of"))],
    ),
    impossible(
        "arrangement", "erroneous", "fifteen_truks_lot_a",
        "make a parking row of 15 truks in lot A",
        [call("arrange_assets", categories=["truck"], shape="parking_row", count=15, location=at("parking lot A"))],
    ),
]


APPEARANCE: list[Json] = [
    # --- direct ---
    case(
        "appearance", "direct", "night_for_this_take",
        "For this take it's night: set the clock to 23:00.",
        [env_only("street_lights", "vehicle_lights", night=True, time_from="22:45", time_to="23:15"), guard(environment=True)],
        [call("set_time_of_day", time="23:00")],
    ),
    case(
        "appearance", "direct", "condition_2_fog",
        "Condition 2: fog, intensity 0.8; everything else as baseline.",
        [env_only(weather=["fog"], intensity_min=0.75, intensity_max=0.85), guard(environment=True)],
        [call("set_weather", kind="fog", intensity=0.8)],
    ),
    case(
        "appearance", "direct", "suv_black",
        "Paint the SUV in lot B black.",
        [looks(asset="suv_1", colour="black"), guard(assets=["suv_1"])],
        [call("set_asset_appearance", assets=["suv_1"], colour="black")],
    ),
    case(
        "appearance", "direct", "street_lights_on",
        "Activate the street lighting along all campus roads.",
        [env_only(street_lights="on"), guard(environment=True)],
        [call("set_lighting", street_lights="on")],
    ),
    case(
        "appearance", "direct", "bench_wooden",
        "Give the bench a wood finish.",
        [looks(asset="bench_1", material="wood"), guard(assets=["bench_1"])],
        [call("set_asset_appearance", assets=["bench_1"], material="wood")],
    ),
    case(
        "appearance", "direct", "condition_11_rain_night_lights",
        "Condition 11: rain 0.6; time 21:00; street lights on.",
        [env_only(weather=["rain"], intensity_min=0.55, intensity_max=0.65, time_from="20:45", time_to="21:15",
                  street_lights="on"),
         guard(environment=True)],
        [call("set_weather", kind="rain", intensity=0.6), call("set_time_of_day", time="21:00"),
         call("set_lighting", street_lights="on")],
        tags=("compound",),
    ),
    case(
        "appearance", "direct", "street_lights_on_after_night",
        "Now turn the street lights on.",
        [env_only("vehicle_lights", street_lights="on", night=True), guard(environment=True)],
        [call("set_lighting", street_lights="on")],
        setup=[turn("Make it night.", [call("set_time_of_day", time="night")])],
    ),
    case(
        "appearance", "direct", "night_shoot_list",
        "Look for the night shoot:\n- time 22:30\n- light fog\n- vehicle headlights on",
        [env_only("street_lights", time_from="22:15", time_to="22:45", weather=["fog"], intensity_max=0.45,
                  vehicle_lights="on"),
         guard(environment=True)],
        [call("set_time_of_day", time="22:30"), call("set_weather", kind="fog", intensity=0.3),
         call("set_lighting", vehicle_lights="on")],
        tags=("compound",),
    ),
    impossible(
        "appearance", "direct", "condition_6_tornado",
        "Condition 6: weather = tornado, intensity 0.9.",
        [call("set_weather", kind="tornado", intensity=0.9)],
    ),
    # --- indirect ---
    case(
        "appearance", "indirect", "golden_hour",
        "We're shooting golden hour: give me the last light before the sun goes down.",
        [env_only("street_lights", "vehicle_lights", "exposure", time_from="17:00", time_to="20:00"),
         guard(environment=True)],
        [call("set_time_of_day", time="sunset")],
    ),
    case(
        "appearance", "indirect", "wet_roads",
        "I want the roads wet for the braking test.",
        [env_only("street_lights", "vehicle_lights", weather=["rain"]), guard(environment=True)],
        [call("set_weather", kind="rain", intensity=0.6)],
    ),
    case(
        "appearance", "indirect", "hero_car_red",
        "Make the hero car stand out: the car in the middle of lot B should be red.",
        [looks(asset="suv_1", colour="red"), guard(assets=["suv_1"])],
        [call("set_asset_appearance", assets=["suv_1"], colour="red")],
    ),
    case(
        "appearance", "indirect", "whiteout",
        "Drivers should barely see a thing: whiteout conditions.",
        [env(weather=["snow", "fog"], intensity_min=0.7), guard(environment=True)],
        [call("set_weather", kind="snow", intensity=0.9)],
    ),
    case(
        "appearance", "indirect", "bin_like_hydrant",
        "Paint the bin the same colour as the fire hydrant.",
        [looks(asset="trash_bin_1", colour="red"), guard(assets=["trash_bin_1"])],
        [call("set_asset_appearance", assets=["trash_bin_1"], colour="red")],
    ),
    case(
        "appearance", "indirect", "my_headlights",
        "Turn my headlights on.",
        [env_only(vehicle_lights="on"), guard(environment=True)],
        [call("set_lighting", vehicle_lights="on")],
    ),
    case(
        "appearance", "indirect", "morning_commute",
        "Set the scene for the morning commute.",
        [env_only("street_lights", "vehicle_lights", time_from="06:30", time_to="09:30"), guard(environment=True)],
        [call("set_time_of_day", time="08:00")],
    ),
    case(
        "appearance", "indirect", "actually_make_it_blue",
        "Actually, make it blue.",
        [looks(category="passenger_car", colour="blue", scope="touched"), delta("passenger_car", 0),
         guard("passenger_car")],
        [call("set_asset_appearance", assets=["passenger_car_3"], colour="blue")],
        setup=[turn("Add a red sedan in lot A.",
                    [call("add_asset", category="passenger_car", colour="red", location=at("parking lot A"))],
                    planned=True)],
    ),
    case(
        "appearance", "indirect", "if_bus_paint_yellow",
        "If there's a bus, paint it yellow.",
        [looks(category="bus", colour="yellow", scope="all", require_all=True), guard("bus")],
        [call("set_asset_appearance", category="bus", colour="yellow")],
        setup=[turn("Add a bus driving west on Main Street.",
                    [call("add_asset", category="bus", behaviour={"kind": "drive_lane", "lane": "main_westbound"})])],
    ),
    impossible(
        "appearance", "indirect", "library_facade",
        "Repaint the Library building's facade brick red for the heritage review.",
        [call("set_asset_appearance", assets=["library"], colour="#8b3a2b")],
    ),
    # --- vague ---
    case(
        "appearance", "vague", "spookier",
        "make it spookier",
        [guard(environment=True)],
        [call("set_time_of_day", time="night"), call("set_weather", kind="fog", intensity=0.6)],
        alternatives=[[env(night=True)], [env(weather=["fog"])]],
    ),
    case(
        "appearance", "vague", "bit_overcast",
        "maybe a bit overcast?",
        [env_only("street_lights", "vehicle_lights", "exposure", weather=["cloudy"]), guard(environment=True)],
        [call("set_weather", kind="cloudy", intensity=0.4)],
    ),
    case(
        "appearance", "vague", "brighten_render",
        "the render's too dark, brighten it up",
        [env_only("street_lights", "vehicle_lights", exposure_min=1.1), guard(environment=True)],
        [call("set_lighting", exposure=1.5)],
    ),
    case(
        "appearance", "vague", "feel_like_winter",
        "make it feel like winter",
        [env(weather=["snow"]), guard(environment=True)],
        [call("set_weather", kind="snow", intensity=0.6)],
    ),
    case(
        "appearance", "vague", "parked_cars_colour",
        "give the parked cars some colour",
        [looks(category=CARS, colour=BRIGHT, scope="all", min_count=3, require_all=True), guard(*CARS)],
        [call("set_asset_appearance", assets=["passenger_car_1"], colour="red"),
         call("set_asset_appearance", assets=["suv_1"], colour="yellow"),
         call("set_asset_appearance", assets=["passenger_car_2"], colour="blue")],
    ),
    case(
        "appearance", "vague", "rainy_night_vibes",
        "rainy night vibes pls",
        [env(weather=["rain"], night=True), guard(environment=True)],
        [call("set_weather", kind="rain", intensity=0.6), call("set_time_of_day", time="night")],
        tags=("compound",),
    ),
    case(
        "appearance", "vague", "if_bus_no_bus",
        "if there's a bus anywhere, paint it yellow",
        [guard()],
        [call("find_assets", category="bus")],
    ),
    case(
        "appearance", "vague", "tone_down_exposure",
        "tone the exposure down a touch",
        [env_only(exposure_min=0.5, exposure_max=0.95), guard(environment=True)],
        [call("set_lighting", exposure=0.8)],
    ),
    case(
        "appearance", "vague", "bit_earlier_dusk",
        "hmm, a bit too dark. can we make it a little earlier, like dusk?",
        [env_only("street_lights", "vehicle_lights", "exposure", time_from="18:30", time_to="21:00"),
         guard(environment=True)],
        [call("set_time_of_day", time="dusk")],
        setup=[turn("Make it night.", [call("set_time_of_day", time="night")], planned=True)],
    ),
    # --- erroneous ---
    case(
        "appearance", "erroneous", "german_little_snow",
        "Make please the weather with snow, but only a little bit.",
        [env_only("street_lights", "vehicle_lights", weather=["snow"], intensity_max=0.45), guard(environment=True)],
        [call("set_weather", kind="snow", intensity=0.3)],
    ),
    case(
        "appearance", "erroneous", "spanish_bench_blue",
        "Put the color blue to the bench.",
        [looks(asset="bench_1", colour="blue"), guard(assets=["bench_1"])],
        [call("set_asset_appearance", assets=["bench_1"], colour="blue")],
    ),
    case(
        "appearance", "erroneous", "hindi_nine_night",
        "Evening time make it, 9 o'clock of night.",
        [env_only("street_lights", "vehicle_lights", time_from="20:45", time_to="21:15"), guard(environment=True)],
        [call("set_time_of_day", time="21:00")],
    ),
    case(
        "appearance", "erroneous", "teen_barbie_bench",
        "make the bus stop bench pink pls its giving barbie",
        [looks(asset="bench_1", colour="pink"), guard(assets=["bench_1"])],
        [call("set_asset_appearance", assets=["bench_1"], colour="pink")],
    ),
    case(
        "appearance", "erroneous", "whether_heavey",
        "set the whether to rainy, heavey",
        [env_only("street_lights", "vehicle_lights", weather=["rain"], intensity_min=0.75), guard(environment=True)],
        [call("set_weather", kind="rain", intensity=0.9)],
    ),
    case(
        "appearance", "erroneous", "bench_sorry_bin_green",
        "paint the bench - sorry, the bin - green",
        [looks(asset="trash_bin_1", colour="green"), guard(assets=["trash_bin_1"])],
        [call("set_asset_appearance", assets=["trash_bin_1"], colour="green")],
    ),
    case(
        "appearance", "erroneous", "mandarin_lamps_off",
        "Street lamp all make off.",
        [env_only(street_lights="off"), guard(environment=True)],
        [call("set_lighting", street_lights="off")],
    ),
    case(
        "appearance", "erroneous", "mandarin_snow_night",
        "Weather make snow, time make night.",
        [env_only("street_lights", "vehicle_lights", weather=["snow"], night=True), guard(environment=True)],
        [call("set_weather", kind="snow", intensity=0.6), call("set_time_of_day", time="night")],
        tags=("compound",),
    ),
    case(
        "appearance", "erroneous", "every_vehicle_but_ego_blue",
        "paint evry vehicle exept the ego blue",
        [looks(category=CARS, colour="blue", scope="all", min_count=3, require_all=True),
         guard(*CARS)],
        [call("set_asset_appearance", category="passenger_car", colour="blue"),
         call("set_asset_appearance", category="suv", colour="blue")],
    ),
    impossible(
        "appearance", "erroneous", "time_25_30",
        "set the time to 25:30 lol",
        [call("set_time_of_day", time="25:30")],
    ),
]

ALL_CASES: list[Json] = [*SEARCH, *ADDITION, *REMOVAL, *POSITIONING, *MOVING, *ARRANGEMENT, *APPEARANCE]


def write() -> None:
    """Write the suite: one JSON object per line, in the order of ALL_CASES."""
    SUITE_PATH.write_text("".join(json.dumps(line) + "\n" for line in ALL_CASES), encoding="utf-8")


if __name__ == "__main__":
    write()
    print(f"wrote {len(ALL_CASES)} cases to {SUITE_PATH}")
