"""The tenth practice suite: campus requests in voices the planners were not written for.

`suites/practice10.jsonl` (tag `practice10`, ids `practice10.*`) was written from the campus
world (worlds/campus.py), the asset catalog, the Worker tools and the eval checks only, by a
helper who had not read the planners, their lexicons or prompt examples, nor any other suite's
cases. It is a development suite: it measures how well a planner understands requests worded
in ways its developers never saw.

Voices (new to the practice suites): a traffic engineer citing sign codes and work-zone jargon
("R1-1", "channelizing devices", "taper", "signal heads", "luminaire"); a teenager texting with
slang, abbreviations and emoji; someone writing markdown bullets or numbered steps; someone
pasting a CSV or YAML fragment; someone hedging and unsure ("I think there's a bench somewhere
near... could you maybe"); a journalist describing the scene for a story or a photo; a
robotics student speaking in map frames, poses, yaw and base_link; someone with dyslexic or
phonetic spellings ("libary", "sooveee", "trafic coan"); someone who refers to earlier edits
("the ones I just added", "same again but by the library", "take those away again");
conditional and quantified requests ("if there's more than one bin...", "every other one");
an accessibility auditor (footways, clear width, contrast, resting points); a delivery driver
(my van, the drop, unloading, boxed in); a landscape gardener (specimens, planting, an avenue,
a grove, autumn colour); and a novelist writing the scene as it happens in the story. Prompts
mix lengths and punctuation, metres, feet and rough amounts ("a couple", "a few", "six-ish"),
clock times ("quarter to seven in the evening"), weather words, negation ("except the ones
west of the junction") and scopes (lanes, lots, sidewalks, crossings, landmarks, compass
sides, "the lot B cars").

Every case judges the outcome, never the calls: a main check (counts with exact bounds, places
with near / relative / on_surface / in_lane, layouts, behaviours, looks, the environment, or the
answer to a question) and an `unchanged_except` guard, so collateral edits fail; questions must
change nothing and their answers must name the right facts. Requests the world cannot do (a
kangaroo, a hospital, parking lot C, fifteen buses, a bench inside a building, a car 500 feet
past the east gate, a hydrant that walks or a stop sign that drives, 500 m forward, 150 cones, a
100 m ring, removing the ego, the fountain or the Library, painting Main Street, a monsoon,
26:15) are tagged `impossible` and expect a refusal that changes nothing. Each case carries a
`reference` plan (Worker calls) whose outcome its checks accept.

Counts: 240 cases; every task x grade cell holds 7 to 12 (direct 50, indirect 72, vague 59,
erroneous 59); 22 `multi_turn` (8 with an earlier turn planned by the planner under test, some
taking back or repeating that turn's edit), 17 `compound` (two or more edits or questions in one
request), 18 `impossible` (7.5 %).

`python -m drivetwin.evals.practice10_source` rewrites the JSONL from the list below.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

SUITE = "practice10"
SUITE_PATH = Path(__file__).resolve().with_name("suites") / f"{SUITE}.jsonl"

Json = dict[str, Any]

# ---------------------------------------------------------------------------------------------
# Spelling helpers: each returns the JSON of one call, location, check or case, nothing more.
# ---------------------------------------------------------------------------------------------


def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def loc(relation: str, target: str | None = None, **more: Any) -> Json:
    return {"relation": relation, "target": target, **more}


def xy(x: float, y: float) -> Json:
    return {"relation": "absolute", "x": x, "y": y}


def beh(kind: str, **more: Any) -> Json:
    return {"kind": kind, **more}


def exactly(category: str | list[str], n: int) -> Json:
    return {"kind": "count_delta", "category": category, "min": n, "max": n}


def between(category: str | list[str], lo: int, hi: int) -> Json:
    return {"kind": "count_delta", "category": category, "min": lo, "max": hi}


def total(category: str | list[str], lo: int, hi: int) -> Json:
    return {"kind": "count", "category": category, "min": lo, "max": hi}


def near(target: str, within: float, **select: Any) -> Json:
    return {"kind": "near", "target": target, "within": within, **select}


def near_point(x: float, y: float, within: float, **select: Any) -> Json:
    return {"kind": "near", "point": [x, y], "within": within, **select}


def rel(relation: str, target: str, **more: Any) -> Json:
    return {"kind": "relative", "relation": relation, "target": target, **more}


def on(surfaces: list[str], **select: Any) -> Json:
    return {"kind": "on_surface", "surfaces": surfaces, **select}


def in_lane(lane: str, **more: Any) -> Json:
    return {"kind": "in_lane", "lane": lane, **more}


def layout(shape: str, **more: Any) -> Json:
    return {"kind": "arrangement", "shape": shape, **more}


def does(behaviour: str | list[str], **more: Any) -> Json:
    return {"kind": "behaviour", "behaviour": behaviour, **more}


def env(**more: Any) -> Json:
    return {"kind": "environment", **more}


def looks(**more: Any) -> Json:
    return {"kind": "appearance", **more}


def moved(asset: str, **more: Any) -> Json:
    return {"kind": "moved", "asset": asset, **more}


def gone(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": False}


def present(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": True}


def only(*categories: str, assets: list[str] | None = None, environment: bool = False) -> Json:
    return {"kind": "unchanged_except", "categories": list(categories), "assets": assets or [],
            "environment": environment}


def says(all_of: list[str] | None = None, any_of: list[str] | None = None) -> Json:
    return {"kind": "answer_contains", "all_of": all_of or [], "any_of": any_of or []}


def refused() -> Json:
    return {"kind": "status", "accepted": False}


def turn(prompt: str, *calls: Json, planned: bool = False) -> Json:
    return {"prompt": prompt, "calls": list(calls), "planned": planned}


def case(name: str, task: str, grade: str, prompt: str, checks: list[Json], reference: list[Json], *,
         tags: list[str] | None = None, setup: list[Json] | None = None,
         alternatives: list[list[Json]] | None = None) -> Json:
    return {
        "id": f"{SUITE}.{task}.{grade}.{name}",
        "world": "campus",
        "setup": setup or [],
        "prompt": prompt,
        "task": task,
        "grade": grade,
        "tags": [SUITE, *(tags or [])],
        "checks": checks,
        "alternatives": alternatives or [],
        "reference": reference,
    }


# Names that recur: the campus as built (worlds/campus.py).
NORTH_LIGHTS = ["street_light_1", "street_light_3", "street_light_5", "street_light_7", "street_light_9",
                "street_light_11"]
SOUTH_LIGHTS = ["street_light_2", "street_light_4", "street_light_6", "street_light_8", "street_light_10",
                "street_light_12"]
LOT_B_CARS = ["passenger_car", "suv"]
TRAFFIC = ["passenger_car", "suv", "bus", "truck", "motorcycle", "bicycle"]
NOON = {"time_from": "12:00", "time_to": "12:00"}
IMPOSSIBLE = ["impossible"]
MULTI = ["multi_turn"]
COMPOUND = ["compound"]

TRUCK_IN_LOT_B = turn("Add a delivery truck parked in lot B.",
                      call("add_asset", category="truck", location=loc("at", "parking lot B")))

# ---------------------------------------------------------------------------------------------
# Search: questions that must change nothing and whose answers name the right facts.
# ---------------------------------------------------------------------------------------------

SEARCH: list[Json] = [
    # direct
    case("lamp_total", "search", "direct", "How many street lights does the campus have?",
         [says(all_of=["street light"], any_of=["12", "twelve"]), only()],
         [call("find_assets", category="street_light")]),
    case("light_nearest_bus_stop", "search", "direct", "Which street light is closest to the bus stop?",
         [says(all_of=["street_light_4"], any_of=["8.0", "8 m", "8 metres", "8 meters"]), only()],
         [call("find_assets", category="street_light", nearest_to="bus stop")]),
    case("weather_and_clock", "search", "direct", "What are the weather and the time of day right now?",
         [says(all_of=["clear", "12:00"]), only()],
         [call("describe_environment")]),
    case("library_to_union", "search", "direct",
         "How far is the Library entrance from the Student Union entrance?",
         [says(any_of=["90.9", "91"]), only()],
         [call("measure_distance", a="Library entrance", b="Student Union entrance")]),
    case("campus_drive_lanes", "search", "direct", "List the lanes on Campus Drive.",
         [says(all_of=["campus_northbound", "campus_southbound"]), only()],
         [call("find_lanes", road="Campus Drive")]),
    case("parked_in_lot_b", "search", "direct", "What vehicles are parked in parking lot B?",
         [says(all_of=["suv"], any_of=["passenger_car_1", "passenger car", "sedan"]), only()],
         [call("find_assets", category="vehicles", near="parking lot B", within=25)]),
    case("hydrant_xy", "search", "direct", "Give me the x, y position of the fire hydrant.",
         [says(all_of=["16", "5.5"]), only()],
         [call("find_assets", category="fire_hydrant")]),
    # indirect
    case("closest_to_hydrant", "search", "indirect",
         "I think there's a fire hydrant somewhere near the middle of campus... could you maybe tell me what "
         "stands closest to it?",
         [says(all_of=["traffic light"]), only()],
         [call("find_assets", nearest_to="fire_hydrant_1")]),
    case("drop_distance", "search", "indirect",
         "Got a drop at the Student Union. Roughly how far's that from the east gate, in metres?",
         [says(any_of=["76.9", "77"]), only()],
         [call("measure_distance", a="east gate", b="Student Union entrance")]),
    case("seating_for_audit", "search", "indirect",
         "Audit question: is there seating within reach of the bus stop for people who can't stand for long, "
         "and how far from the stop is it?",
         [says(all_of=["bench"], any_of=["4.2", "bench_1"]), only()],
         [call("find_assets", category="bench", nearest_to="bus stop")]),
    case("conditions_for_piece", "search", "indirect",
         "For my piece I need the conditions on the ground: is it day or night out there, and what's the sky "
         "doing?",
         [says(all_of=["clear"], any_of=["12:00", "noon", "midday", "daytime"]), only()],
         [call("describe_environment")]),
    case("trees_before_planting", "search", "indirect",
         "Before I plant anything: how many trees are in already, and which one stands nearest the fountain?",
         [says(all_of=["4", "tree_2"]), only()],
         [call("find_assets", category="tree", nearest_to="fountain")]),
    case("ego_pose_map_frame", "search", "indirect", "What's the ego's pose in the map frame? x, y, yaw.",
         [says(all_of=["-60"], any_of=["-1.8", "-1.75"]), only()],
         [call("asset_properties", asset="ego")]),
    case("signal_inventory", "search", "indirect",
         "Signal inventory, please: how many signal heads are installed on campus?",
         [says(all_of=["traffic light"], any_of=["2", "two"]), only()],
         [call("find_assets", category="traffic_light")]),
    case("csv_counts", "search", "indirect",
         "category,count\nstreet_light,?\ntree,?\n(fill in the counts please)",
         [says(all_of=["street light", "12", "tree", "4"]), only()],
         [call("find_assets", category="street_light"), call("find_assets", category="tree")],
         tags=COMPOUND),
    case("hospital_distance", "search", "indirect",
         "For the story I need one number: how far is the campus hospital from the Library?",
         [refused(), only()],
         [call("measure_distance", a="campus hospital", b="Library entrance")],
         tags=IMPOSSIBLE),
    # vague
    case("dark_yet", "search", "vague", "um is it getting dark yet? or is it still daytime, I'm not sure",
         [says(any_of=["12:00", "noon", "midday"]), only()],
         [call("describe_environment")]),
    case("parked_by_union", "search", "vague", "Paint me a picture of what's parked down by the Student Union.",
         [says(all_of=["suv"]), only()],
         [call("find_assets", category="vehicles", near="Student Union entrance", within=30)]),
    case("greenery", "search", "vague", "Much greenery about?",
         [says(all_of=["tree"], any_of=["4", "four"]), only()],
         [call("find_assets", category="tree")]),
    case("junk_in_road", "search", "vague", "road clear up ahead or is there junk in it?",
         [says(all_of=["rubble"]), only()],
         [call("find_assets", on_lane=True)],
         tags=MULTI,
         setup=[turn("Drop a pile of rubble in our lane about 25 m ahead of the ego.",
                     call("add_asset", category="cement_rubble", location=loc("at", "ego", along_m=25)))]),
    case("stop_sign_somewhere", "search", "vague",
         "Could you maybe check... I'm fairly sure there's a stop sign around somewhere, but where exactly?",
         [says(any_of=["-13.5", "crosswalk", "crossing"]), only()],
         [call("find_assets", category="stop_sign", nearest_to="west crosswalk")]),
    case("somewhere_to_sit", "search", "vague", "Where would a tired character sit down around here?",
         [says(all_of=["bench"], any_of=["-26", "bus stop", "bench_1"]), only()],
         [call("find_assets", category="bench", nearest_to="bus stop")]),
    case("around_ego", "search", "vague", "what's hanging around near the ego, roughly?",
         [says(all_of=["street light"]), only()],
         [call("find_assets", near="ego", within=20)]),
    case("litter_near_stop", "search", "vague", "Somewhere to drop litter near the bus stop?",
         [says(all_of=["bin"], any_of=["3.5", "-33.5", "trash_bin_1"]), only()],
         [call("find_assets", category="trash_bin", nearest_to="bus stop")]),
    case("caption_facts", "search", "vague",
         "Two facts for the caption: the number of trees, and what the weather's doing.",
         [says(all_of=["tree", "4", "clear"]), only()],
         [call("find_assets", category="tree"), call("describe_environment")],
         tags=COMPOUND),
    # erroneous
    case("meny_treez", "search", "erroneous", "how meny treez are their on the campis",
         [says(all_of=["tree"], any_of=["4", "four"]), only()],
         [call("find_assets", category="tree")]),
    case("lamps_lol", "search", "erroneous", "how many lamps we got lol \U0001f4a1",
         [says(all_of=["street light"], any_of=["12", "twelve"]), only()],
         [call("find_assets", category="street_light")]),
    case("wich_lite", "search", "erroneous", "wich strete lite is closist to the bus stopp",
         [says(all_of=["street_light_4"], any_of=["8.0", "8 m", "8 metres", "8 meters"]), only()],
         [call("find_assets", category="street_light", nearest_to="bus stop")]),
    case("whether_rainning", "search", "erroneous", "whats the whether like, is it rainning?",
         [says(all_of=["clear"]), only()],
         [call("describe_environment")]),
    case("distanse_fountan", "search", "erroneous", "distanse from ego to the fountan pls, in meters",
         [says(any_of=["141.3", "141"]), only()],
         [call("measure_distance", a="ego", b="fountain")]),
    case("which_lane_rn", "search", "erroneous", "yo which lane is the ego even in rn \U0001f914",
         [says(any_of=["main_eastbound", "eastbound"]), only()],
         [call("find_lanes", near="ego")]),
    case("conez_jsut_put", "search", "erroneous", "how many conez did i jsut put down?",
         [says(all_of=["cone"], any_of=["4", "four"]), only()],
         [call("find_assets", category="traffic_cone")],
         tags=MULTI,
         setup=[turn("Put four traffic cones in parking lot A.",
                     call("add_asset", category="traffic_cone", count=4, location=loc("at", "parking lot A")),
                     planned=True)]),
    case("wut_tyme", "search", "erroneous", "wut tyme is it in the sim",
         [says(any_of=["12:00", "noon", "midday"]), only()],
         [call("describe_environment")]),
]

# ---------------------------------------------------------------------------------------------
# Addition
# ---------------------------------------------------------------------------------------------

ADDITION: list[Json] = [
    # direct
    case("bench_fountain", "addition", "direct", "Add a bench next to the fountain.",
         [exactly("bench", 1), near("fountain", 8, category="bench"), only("bench")],
         [call("add_asset", category="bench", location=loc("at", "fountain"))]),
    case("three_cones_lot_a", "addition", "direct", "Put three traffic cones in parking lot A.",
         [exactly("traffic_cone", 3), near("parking lot A", 0.5, category="traffic_cone", require_all=True),
          only("traffic_cone")],
         [call("add_asset", category="traffic_cone", count=3, location=loc("at", "parking lot A"))]),
    case("pedestrian_bus_stop", "addition", "direct", "Add a pedestrian standing on the sidewalk by the bus stop.",
         [exactly("pedestrian", 1), on(["sidewalk"], category="pedestrian"),
          near("bus stop", 8, category="pedestrian"), only("pedestrian")],
         [call("add_asset", category="pedestrian", location=loc("on_sidewalk", "bus stop"))]),
    case("robot_at_xy", "addition", "direct", "Add an Ackermann robot at x = 30, y = -30.",
         [exactly("ackermann_robot", 1), near_point(30, -30, 1.0, category="ackermann_robot"),
          only("ackermann_robot")],
         [call("add_asset", category="ackermann_robot", location=xy(30, -30))]),
    case("bus_east_main", "addition", "direct", "Add a bus driving east on Main Street.",
         [exactly("bus", 1), does("drive_lane", lane="main_eastbound", category="bus"), only("bus")],
         [call("add_asset", category="bus", behaviour=beh("drive_lane", lane="main_eastbound"))]),
    case("tree_behind_bench", "addition", "direct", "Add a tree behind the bench at the bus stop.",
         [exactly("tree", 1), rel("behind", "bench_1", category="tree", max_distance=8), only("tree")],
         [call("add_asset", category="tree", location=loc("behind", "bench_1"))]),
    case("lot_c_bench", "addition", "direct", "Put a bench in parking lot C.",
         [refused(), only()],
         [call("add_asset", category="bench", location=loc("at", "parking lot C"))],
         tags=IMPOSSIBLE),
    # indirect
    case("r1_1_north", "addition", "indirect", "Install an R1-1 at the north crosswalk approach.",
         [exactly("stop_sign", 1), near("north crosswalk", 8, category="stop_sign"),
          on(["sidewalk", "ground"], category="stop_sign"), only("stop_sign")],
         [call("add_asset", category="stop_sign", location=loc("at", "north crosswalk"))]),
    case("van_at_jtekt", "addition", "indirect",
         "I'll be unloading at JTEKT, so stick my van in front of the entrance, on the drop-off.",
         [exactly("truck", 1), near("JTEKT building entrance", 10, category="truck"),
          on(["drivable"], category="truck"), only("truck")],
         [call("add_asset", category="truck", location=loc("at", "JTEKT building entrance"))]),
    case("shade_at_stop", "addition", "indirect",
         "Whoever waits at the bus stop could do with some shade; one good specimen behind the stop should do it.",
         [exactly("tree", 1), near("bus stop", 10, category="tree"), on(["ground", "sidewalk"], category="tree"),
          only("tree")],
         [call("add_asset", category="tree", location=loc("behind", "bus stop"))]),
    case("resting_point_library", "addition", "indirect",
         "Wheelchair users need a resting point outside the Library. Provide seating there.",
         [exactly("bench", 1), near("Library entrance", 10, category="bench"),
          on(["ground", "sidewalk", "paved"], category="bench"), only("bench")],
         [call("add_asset", category="bench", location=loc("at", "Library entrance"))]),
    case("lone_cyclist", "addition", "indirect",
         "As the chapter opens, a lone cyclist is pedalling west along Main Street.",
         [exactly("bicycle", 1), does("drive_lane", lane="main_westbound", category="bicycle"), only("bicycle")],
         [call("add_asset", category="bicycle", behaviour=beh("drive_lane", lane="main_westbound"))]),
    case("students_at_crossing", "addition", "indirect",
         "For the photo: two students waiting at the north crosswalk, out of the traffic.",
         [exactly("pedestrian", 2), near("north crosswalk", 10, category="pedestrian", require_all=True),
          on(["sidewalk", "ground"], category="pedestrian"), only("pedestrian")],
         [call("add_asset", category="pedestrian", count=2, location=loc("on_sidewalk", "north crosswalk"))]),
    case("channelizing_lot_b", "addition", "indirect",
         "Deploy four channelizing devices in the eastbound lane at the lot B driveway.",
         [exactly(["traffic_cone", "road_barrier"], 4),
          in_lane("main_eastbound", category=["traffic_cone", "road_barrier"]),
          near("parking lot B entrance", 15, category=["traffic_cone", "road_barrier"], require_all=True),
          only("traffic_cone", "road_barrier")],
         [call("add_asset", category="traffic_cone", count=4,
               location=loc("in_lane", "parking lot B entrance", lane="main_eastbound"))]),
    case("boxed_in", "addition", "indirect", "Now box my truck in: park a car right behind it.",
         [exactly(LOT_B_CARS, 1), rel("behind", "truck_1", category=LOT_B_CARS, max_distance=12),
          only(*LOT_B_CARS)],
         [call("add_asset", category="passenger_car", location=loc("behind", "truck_1"))],
         tags=MULTI, setup=[TRUCK_IN_LOT_B]),
    case("bench_in_union_lobby", "addition", "indirect",
         "Put a bench inside the Student Union's lobby for visitors.",
         [refused(), only()],
         [call("add_asset", category="bench", location=xy(42, -63))],
         tags=IMPOSSIBLE),
    case("markdown_bench_and_bin", "addition", "indirect",
         "Two things:\n- a bench at the fountain\n- a bin right beside that bench",
         [exactly("bench", 1), exactly("trash_bin", 1), near("fountain", 8, category="bench"),
          near("fountain", 10, category="trash_bin"), only("bench", "trash_bin")],
         [call("add_asset", category="bench", location=loc("at", "fountain")),
          call("add_asset", category="trash_bin", location=loc("next_to", "bench_2"))],
         tags=COMPOUND),
    case("yaml_bus_and_walker", "addition", "indirect",
         "add:\n  - kind: bus\n    lane: main_westbound\n    doing: driving\n  - kind: pedestrian\n"
         "    where: bus stop",
         [exactly("bus", 1), exactly("pedestrian", 1), does("drive_lane", lane="main_westbound", category="bus"),
          near("bus stop", 8, category="pedestrian"), only("bus", "pedestrian")],
         [call("add_asset", category="bus", behaviour=beh("drive_lane", lane="main_westbound")),
          call("add_asset", category="pedestrian", location=loc("at", "bus stop"))],
         tags=COMPOUND),
    # vague
    case("few_cones_junction", "addition", "vague",
         "Could you maybe add a few cones somewhere around the main intersection? Not too many, I think.",
         [between("traffic_cone", 2, 5), near("main intersection", 12, category="traffic_cone", require_all=True),
          only("traffic_cone")],
         [call("add_asset", category="traffic_cone", count=3, location=loc("at", "main intersection"))]),
    case("liven_quad", "addition", "vague", "Liven up the quad with some people.",
         [between("pedestrian", 2, 10), near("fountain", 15, category="pedestrian", require_all=True),
          only("pedestrian")],
         [call("add_asset", category="pedestrian", count=4, location=loc("at", "fountain"))]),
    case("planting_lot_b", "addition", "vague",
         "The car park by the Student Union looks bare. Soften it with a bit of planting.",
         [between("tree", 1, 6), near("parking lot B", 8, category="tree", require_all=True), only("tree")],
         [call("add_asset", category="tree", count=2, location=loc("at", "parking lot B"))]),
    case("debris_ahead", "addition", "vague",
         "Something should be in the ego's way: some debris on the road ahead of it.",
         [between("cement_rubble", 1, 3), in_lane("main_eastbound", category="cement_rubble"),
          rel("in_front_of", "ego", category="cement_rubble", max_distance=80, tolerance_deg=20),
          only("cement_rubble")],
         [call("add_asset", category="cement_rubble", location=loc("at", "ego", along_m=30))]),
    case("needs_traffic", "addition", "vague", "The scene needs traffic.",
         [between(TRAFFIC, 1, 12), does("drive_lane", category=TRAFFIC), only(*TRAFFIC)],
         [call("add_asset", category="passenger_car", count=2, behaviour=beh("drive_lane", lane="main_westbound"))]),
    case("couple_of_bins", "addition", "vague", "drop a couple of bins by the JTEKT entrance",
         [between("trash_bin", 2, 3), near("JTEKT building entrance", 10, category="trash_bin", require_all=True),
          only("trash_bin")],
         [call("add_asset", category="trash_bin", count=2, location=loc("at", "JTEKT building entrance"))]),
    case("something_to_react_to", "addition", "vague",
         "Hmm, I guess the ego needs something to react to? Maybe someone stepping out in front of it?",
         [exactly("pedestrian", 1), only("pedestrian")],
         [call("add_asset", category="pedestrian", behaviour=beh("jaywalk"))],
         alternatives=[[does("jaywalk", category="pedestrian")],
                       [does("cross_road", category="pedestrian", crosses_lane="main_eastbound")]]),
    case("undo_no_put_it_back", "addition", "vague", "wait, undo that... no, actually, put it back where it was",
         [total("bench", 1, 1), near_point(-26, -6.9, 1.5, category="bench", scope="all"), only("bench")],
         [call("add_asset", category="bench", location=xy(-26, -6.9), yaw_deg=180)],
         tags=MULTI, setup=[turn("Remove the bench.", call("remove_assets", assets=["bench_1"]), planned=True)]),
    case("top_up_to_three", "addition", "indirect",
         "If there are fewer than three cones at the lot B entrance, top them up to three.",
         [total("traffic_cone", 3, 3), near("parking lot B entrance", 8, category="traffic_cone", scope="all",
                                           require_all=True), only("traffic_cone")],
         [call("add_asset", category="traffic_cone", count=2, location=loc("at", "parking lot B entrance"))],
         tags=MULTI,
         setup=[turn("Put a cone at the lot B entrance.",
                     call("add_asset", category="traffic_cone", location=loc("at", "parking lot B entrance")))]),
    case("fleet_of_fifteen", "addition", "vague",
         "A fleet of fifteen shuttle buses should be parked around campus.",
         [refused(), only()],
         [call("add_asset", category="bus", count=15)],
         tags=IMPOSSIBLE),
    # erroneous
    case("bench_neer_libary", "addition", "erroneous", "ad a bench neer the libary enterance",
         [exactly("bench", 1), near("Library entrance", 10, category="bench"), only("bench")],
         [call("add_asset", category="bench", location=loc("at", "Library entrance"))]),
    case("two_scooters", "addition", "erroneous", "yo put like 2 scooters by lot b \U0001f6f5\U0001f6f5",
         [exactly("motorcycle", 2), near("parking lot B", 5, category="motorcycle", require_all=True),
          only("motorcycle")],
         [call("add_asset", category="motorcycle", count=2, location=loc("at", "parking lot B"))]),
    case("coan_frunt_stop", "addition", "erroneous", "pleez put a trafic coan in frunt of the stop sine",
         [exactly("traffic_cone", 1), near("stop_sign_1", 4, category="traffic_cone"), only("traffic_cone")],
         [call("add_asset", category="traffic_cone", location=loc("in_front_of", "stop_sign_1"))]),
    case("three_pedestrains", "addition", "erroneous", "put 3 pedestrains on the sidwalk next to the bus stopp",
         [exactly("pedestrian", 3), on(["sidewalk"], category="pedestrian"),
          near("bus stop", 10, category="pedestrian", require_all=True), only("pedestrian")],
         [call("add_asset", category="pedestrian", count=3, location=loc("on_sidewalk", "bus stop"))]),
    case("bus_north_ngl", "addition", "erroneous", "add a bus on campus drive going north ngl",
         [exactly("bus", 1), does("drive_lane", lane="campus_northbound", category="bus"), only("bus")],
         [call("add_asset", category="bus", behaviour=beh("drive_lane", lane="campus_northbound"))]),
    case("hidrent_jtekt", "addition", "erroneous", "I wud like a fire hidrent next to the JTEKT bilding",
         [exactly("fire_hydrant", 1), near("JTEKT building entrance", 12, category="fire_hydrant"),
          on(["sidewalk", "ground"], category="fire_hydrant"), only("fire_hydrant")],
         [call("add_asset", category="fire_hydrant", location=loc("on_sidewalk", "JTEKT building entrance"))]),
    case("same_agian_libary", "addition", "erroneous", "now add the same agian but by the libary",
         [exactly("bench", 2), near("Library entrance", 12, category="bench", scope="added", require_all=True),
          only("bench")],
         [call("add_asset", category="bench", count=2, location=loc("at", "Library entrance"))],
         tags=MULTI,
         setup=[turn("Add two benches by the fountain.",
                     call("add_asset", category="bench", count=2, location=loc("at", "fountain")),
                     planned=True)]),
    case("kangaroo", "addition", "erroneous", "ad a kangaroo by the fountin",
         [refused(), only()],
         [call("add_asset", category="kangaroo", location=loc("at", "fountain"))],
         tags=IMPOSSIBLE),
    case("steps_cones_sign", "addition", "erroneous",
         "1) ad 2 cones at the lot b entrence\n2) and a constuction sine next to them",
         [exactly("traffic_cone", 2), exactly("construction_sign", 1),
          near("parking lot B entrance", 8, category="traffic_cone", require_all=True),
          near("parking lot B entrance", 8, category="construction_sign"),
          only("traffic_cone", "construction_sign")],
         [call("add_asset", category="traffic_cone", count=2, location=loc("at", "parking lot B entrance")),
          call("add_asset", category="construction_sign", location=loc("next_to", "traffic_cone_1"))],
         tags=COMPOUND),
]

# ---------------------------------------------------------------------------------------------
# Removal
# ---------------------------------------------------------------------------------------------

ADDED_TWO_BINS = turn("Add two more trash bins at the JTEKT entrance.",
                      call("add_asset", category="trash_bin", count=2, location=loc("at", "JTEKT building entrance")))

REMOVAL: list[Json] = [
    # direct
    case("the_bench", "removal", "direct", "Remove the bench.",
         [exactly("bench", -1), gone("bench_1"), only("bench")],
         [call("remove_assets", assets=["bench_1"])]),
    case("suv_lot_b", "removal", "direct", "Delete the SUV in parking lot B.",
         [exactly("suv", -1), gone("suv_1"), only("suv")],
         [call("remove_assets", assets=["suv_1"])]),
    case("south_side_lights", "removal", "direct", "Remove all the street lights on the south side of Main Street.",
         [gone(*SOUTH_LIGHTS), present(*NORTH_LIGHTS), only("street_light")],
         [call("remove_assets", assets=SOUTH_LIGHTS)]),
    case("tree_nearest_library", "removal", "direct", "Remove the tree nearest the Library.",
         [exactly("tree", -1), gone("tree_1"), only("tree")],
         [call("remove_assets", category="tree", near="Library entrance", count=1)]),
    case("two_of_five_cones", "removal", "direct", "Remove two of the cones.",
         [exactly("traffic_cone", -2), only("traffic_cone")],
         [call("remove_assets", category="traffic_cone", count=2)],
         tags=MULTI,
         setup=[turn("Put five cones in parking lot A.",
                     call("add_asset", category="traffic_cone", count=5, location=loc("at", "parking lot A")))]),
    case("bin_and_hydrant", "removal", "direct", "Remove the trash bin and the fire hydrant.",
         [gone("trash_bin_1", "fire_hydrant_1"), only("trash_bin", "fire_hydrant")],
         [call("remove_assets", assets=["trash_bin_1"]), call("remove_assets", assets=["fire_hydrant_1"])],
         tags=COMPOUND),
    case("remove_ego", "removal", "direct", "Remove the ego vehicle.",
         [refused(), only()],
         [call("remove_assets", assets=["ego"])],
         tags=IMPOSSIBLE),
    # indirect
    case("pull_r1_1", "removal", "indirect", "Pull the R1-1 sign from the west approach to the junction.",
         [gone("stop_sign_1"), only("stop_sign")],
         [call("remove_assets", assets=["stop_sign_1"])]),
    case("bin_narrows_footway", "removal", "indirect",
         "The bin at the bus stop narrows the footway below 1.5 m of clear width. It has to go.",
         [gone("trash_bin_1"), only("trash_bin")],
         [call("remove_assets", assets=["trash_bin_1"])]),
    case("fell_diseased", "removal", "indirect",
         "That specimen by the Library is diseased; fell it and leave the others standing.",
         [gone("tree_1"), present("tree_2", "tree_3", "tree_4"), only("tree")],
         [call("remove_assets", assets=["tree_1"])]),
    case("clear_lot_b", "removal", "indirect", "Clear every car out of lot B, I need the bays to unload.",
         [total(LOT_B_CARS, 0, 0), only(*LOT_B_CARS)],
         [call("remove_assets", assets=["passenger_car_1", "suv_1", "passenger_car_2"])]),
    case("after_photo_hydrant", "removal", "indirect",
         "In the 'after' photo, the hydrant by the junction is gone.",
         [gone("fire_hydrant_1"), only("fire_hydrant")],
         [call("remove_assets", assets=["fire_hydrant_1"])]),
    case("purge_near_base_link", "removal", "indirect",
         "Purge every static prop within 10 m of base_link (the ego) from the map. Keep the ego itself.",
         [gone("street_light_2"), only(assets=["street_light_2"])],
         [call("remove_assets", assets=["street_light_2"])]),
    case("stolen_lamps", "removal", "indirect",
         "In this chapter the lamps along the north side of Main Street have all been stolen, except the ones "
         "west of the junction, which the thieves missed.",
         [gone("street_light_7", "street_light_9", "street_light_11"),
          present("street_light_1", "street_light_3", "street_light_5", *SOUTH_LIGHTS), only("street_light")],
         [call("remove_assets", assets=["street_light_7", "street_light_9", "street_light_11"])]),
    case("keep_one_bin", "removal", "indirect",
         "If there's more than one bin on campus now, keep only the one nearest the bus stop.",
         [present("trash_bin_1"), total("trash_bin", 1, 1), only("trash_bin")],
         [call("remove_assets", assets=["trash_bin_2", "trash_bin_3"])],
         tags=MULTI, setup=[ADDED_TWO_BINS]),
    case("demolish_library", "removal", "indirect", "Demolish the Library to make room for parking.",
         [refused(), only()],
         [call("remove_assets", assets=["Library"])],
         tags=IMPOSSIBLE),
    case("swap_bench_for_bin", "removal", "indirect", "Swap the bench at the bus stop for a bin.",
         [gone("bench_1"), exactly("trash_bin", 1), near("bus stop", 8, category="trash_bin", scope="added"),
          only("bench", "trash_bin")],
         [call("remove_assets", assets=["bench_1"]),
          call("add_asset", category="trash_bin", location=loc("at", "bus stop"))],
         tags=COMPOUND),
    # vague
    case("bench_somewhere", "removal", "vague",
         "I think there's a bench somewhere near the bus stop... could you maybe get rid of it? If it's no trouble.",
         [gone("bench_1"), only("bench")],
         [call("remove_assets", assets=["bench_1"])]),
    case("thin_trees", "removal", "vague", "Thin out the trees a bit.",
         [between("tree", -2, -1), only("tree")],
         [call("remove_assets", assets=["tree_4"])]),
    case("take_those_away", "removal", "vague", "Actually, take those away again.",
         [total("traffic_cone", 0, 0), only("traffic_cone")],
         [call("remove_assets", category="traffic_cone")],
         tags=MULTI,
         setup=[turn("Add four cones in a line in front of the JTEKT entrance.",
                     call("arrange_assets", categories=["traffic_cone"], shape="line", count=4,
                          location=loc("in_front_of", "JTEKT building entrance")),
                     planned=True)]),
    case("junk_in_junction", "removal", "vague", "ok that's way too much junk in the junction, clear it out",
         [total(["traffic_cone", "cement_rubble"], 0, 0), present("traffic_light_1", "traffic_light_2", "stop_sign_1"),
          only("traffic_cone", "cement_rubble")],
         [call("remove_assets", category="traffic_cone"), call("remove_assets", category="cement_rubble")],
         tags=MULTI,
         setup=[turn("Scatter four cones and two piles of rubble across the main intersection.",
                     call("add_asset", category="traffic_cone", count=4, location=loc("at", "main intersection")),
                     call("add_asset", category="cement_rubble", count=2, location=loc("at", "main intersection")))]),
    case("some_parked_cars", "removal", "vague", "get rid of some of those parked cars in lot B, it's a squeeze",
         [between(LOT_B_CARS, -2, -1), only(*LOT_B_CARS)],
         [call("remove_assets", assets=["passenger_car_1"])]),
    case("lose_a_few_lamps", "removal", "vague", "The lamp-lined boulevard looks cluttered. Lose a few of the lamps.",
         [between("street_light", -4, -2), only("street_light")],
         [call("remove_assets", assets=["street_light_1", "street_light_6", "street_light_11"])]),
    case("obstructing_footway", "removal", "vague",
         "Something's obstructing the footway right at the bus stop. Please clear it.",
         [between(["bench", "trash_bin"], -2, -1), only("bench", "trash_bin")],
         [call("remove_assets", assets=["trash_bin_1"])]),
    case("every_other_light", "removal", "vague",
         "Maybe we don't need quite so many street lights? Like... every other one could go?",
         [exactly("street_light", -6), only("street_light")],
         [call("remove_assets", assets=["street_light_1", "street_light_5", "street_light_9", "street_light_4",
                                        "street_light_8", "street_light_12"])]),
    # erroneous
    case("remvoe_hydrent", "removal", "erroneous", "remvoe the fire hydrent",
         [gone("fire_hydrant_1"), only("fire_hydrant")],
         [call("remove_assets", assets=["fire_hydrant_1"])]),
    case("trash_can_ugly", "removal", "erroneous", "ngl the trash can is ugly af, delete it",
         [gone("trash_bin_1"), only("trash_bin")],
         [call("remove_assets", assets=["trash_bin_1"])]),
    case("sue_vee", "removal", "erroneous", "take away the sue-vee in the car park",
         [gone("suv_1"), only("suv")],
         [call("remove_assets", assets=["suv_1"])]),
    case("all_the_tress", "removal", "erroneous", "remove all the tress",
         [total("tree", 0, 0), only("tree")],
         [call("remove_assets", category="tree")]),
    case("stop_sighn", "removal", "erroneous", "git rid of the stop sighn",
         [gone("stop_sign_1"), only("stop_sign")],
         [call("remove_assets", assets=["stop_sign_1"])]),
    case("furthest_car", "removal", "erroneous", "delet the car in lot B thats furthest from the entrence",
         [gone("passenger_car_1"), exactly(LOT_B_CARS, -1), only(*LOT_B_CARS)],
         [call("remove_assets", assets=["passenger_car_1"])]),
    case("kick_out_ppl", "removal", "erroneous", "kick out the ppl by the fountain thx",
         [total("pedestrian", 0, 0), only("pedestrian")],
         [call("remove_assets", category="pedestrian")],
         tags=MULTI,
         setup=[turn("Add three pedestrians by the fountain.",
                     call("add_asset", category="pedestrian", count=3, location=loc("at", "fountain")))]),
    case("fountian", "removal", "erroneous", "remove the fountian pls",
         [refused(), only()],
         [call("remove_assets", assets=["fountain"])],
         tags=IMPOSSIBLE),
    case("bench_and_bin_lol", "removal", "erroneous", "delete the bench AND the bin lol",
         [gone("bench_1", "trash_bin_1"), only("bench", "trash_bin")],
         [call("remove_assets", assets=["bench_1"]), call("remove_assets", assets=["trash_bin_1"])],
         tags=COMPOUND),
]

# ---------------------------------------------------------------------------------------------
# Positioning: an existing asset put somewhere else.
# ---------------------------------------------------------------------------------------------

POSITIONING: list[Json] = [
    # direct
    case("bench_to_fountain", "positioning", "direct", "Move the bench to the fountain.",
         [near("fountain", 8, asset="bench_1"), only(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=loc("at", "fountain"))]),
    case("suv_to_lot_a", "positioning", "direct", "Put the SUV in parking lot A.",
         [near("parking lot A", 0.5, asset="suv_1"), only(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=loc("at", "parking lot A"))]),
    case("bin_next_to_jtekt", "positioning", "direct", "Place the trash bin next to the JTEKT building entrance.",
         [near("JTEKT building entrance", 8, asset="trash_bin_1"), only(assets=["trash_bin_1"])],
         [call("place_asset", asset="trash_bin_1", location=loc("next_to", "JTEKT building entrance"))]),
    case("ego_into_northbound", "positioning", "direct", "Put the ego in lane campus_northbound.",
         [in_lane("campus_northbound", asset="ego", aligned=True), only(assets=["ego"])],
         [call("place_asset", asset="ego", location=loc("in_lane", "campus_northbound"))]),
    case("hydrant_at_xy", "positioning", "direct", "Place the fire hydrant at x = -20, y = 5.5.",
         [near_point(-20, 5.5, 0.5, asset="fire_hydrant_1"), only(assets=["fire_hydrant_1"])],
         [call("place_asset", asset="fire_hydrant_1", location=xy(-20, 5.5))]),
    case("car2_front_of_union", "positioning", "direct", "Put passenger_car_2 in front of the Student Union entrance.",
         [rel("in_front_of", "Student Union entrance", asset="passenger_car_2", max_distance=12),
          only(assets=["passenger_car_2"])],
         [call("place_asset", asset="passenger_car_2", location=loc("in_front_of", "Student Union entrance"))]),
    case("stop_sign_north_walk", "positioning", "direct",
         "Put the stop sign on the sidewalk next to the north crosswalk.",
         [on(["sidewalk"], asset="stop_sign_1"), near("north crosswalk", 8, asset="stop_sign_1"),
          only(assets=["stop_sign_1"])],
         [call("place_asset", asset="stop_sign_1", location=loc("on_sidewalk", "north crosswalk"))]),
    case("two_poses", "positioning", "direct",
         "Set poses: hydrant to (-5.5, 30), trash bin to (5.5, 30).",
         [near_point(-5.5, 30, 0.5, asset="fire_hydrant_1"), near_point(5.5, 30, 0.5, asset="trash_bin_1"),
          only(assets=["fire_hydrant_1", "trash_bin_1"])],
         [call("place_asset", asset="fire_hydrant_1", location=xy(-5.5, 30)),
          call("place_asset", asset="trash_bin_1", location=xy(5.5, 30))],
         tags=COMPOUND),
    # indirect
    case("r1_1_to_driveway", "positioning", "indirect", "Relocate the R1-1 to the lot B driveway exit.",
         [near("parking lot B entrance", 8, asset="stop_sign_1"), on(["sidewalk", "ground"], asset="stop_sign_1"),
          only(assets=["stop_sign_1"])],
         [call("place_asset", asset="stop_sign_1", location=loc("at", "parking lot B entrance"))]),
    case("suv_round_to_jtekt", "positioning", "indirect",
         "Bring the SUV round to the JTEKT drop-off so I can load it.",
         [near("JTEKT building entrance", 12, asset="suv_1"), on(["drivable"], asset="suv_1"),
          only(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=loc("at", "JTEKT building entrance"))]),
    case("bench_off_tactile", "positioning", "indirect",
         "The bench blocks the tactile route at the bus stop; relocate it beside the Library entrance instead.",
         [near("Library entrance", 8, asset="bench_1"), only(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=loc("at", "Library entrance"))]),
    case("transplant_tree", "positioning", "indirect", "Transplant the tree by the Library over beside the fountain.",
         [near("fountain", 10, asset="tree_1"), only(assets=["tree_1"])],
         [call("place_asset", asset="tree_1", location=loc("at", "fountain"))]),
    case("hydrant_world_frame", "positioning", "indirect",
         "Set the hydrant's pose to (-5.5, -30) in the world frame; yaw doesn't matter.",
         [near_point(-5.5, -30, 0.5, asset="fire_hydrant_1"), only(assets=["fire_hydrant_1"])],
         [call("place_asset", asset="fire_hydrant_1", location=xy(-5.5, -30))]),
    case("suv_at_main_gate", "positioning", "indirect", "In the shot, the SUV is waiting right at the main gate.",
         [near("main gate", 10, asset="suv_1"), only(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=loc("at", "main gate"))]),
    case("her_car_engineering", "positioning", "indirect",
         "She'd left her car, the one parked in the middle of the row in lot B, outside the Engineering Hall.",
         [near("Engineering Hall entrance", 14, asset="suv_1"), only(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=loc("at", "Engineering Hall entrance"))]),
    case("bike_i_added", "positioning", "indirect", "Now put the bike I just added over by the east gate.",
         [near("east gate", 12, category="motorcycle"), only("motorcycle")],
         [call("place_asset", asset="motorcycle_1", location=loc("at", "east gate"))],
         tags=MULTI,
         setup=[turn("Add a motorcycle in lot A.",
                     call("add_asset", category="motorcycle", location=loc("at", "parking lot A")))]),
    case("suv_500_feet_out", "positioning", "indirect", "Park the SUV out past the east gate, about 500 feet beyond it.",
         [refused(), only()],
         [call("place_asset", asset="suv_1", location=xy(252, 0))],
         tags=IMPOSSIBLE),
    case("numbered_suv_bench", "positioning", "indirect",
         "1. Put the SUV in lot A.\n2. Put the bench next to the fountain.",
         [near("parking lot A", 0.5, asset="suv_1"), near("fountain", 8, asset="bench_1"),
          only(assets=["suv_1", "bench_1"])],
         [call("place_asset", asset="suv_1", location=loc("at", "parking lot A")),
          call("place_asset", asset="bench_1", location=loc("at", "fountain"))],
         tags=COMPOUND),
    # vague
    case("bench_nicer_fountain", "positioning", "vague",
         "The bench... I think it'd be nicer somewhere near the fountain? If that's ok.",
         [near("fountain", 12, asset="bench_1"), only(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=loc("at", "fountain"))]),
    case("suv_nearer_exit", "positioning", "vague", "Park the SUV nearer its lot's way out.",
         [near("parking lot B entrance", 12, asset="suv_1"), on(["drivable"], asset="suv_1"),
          only(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=xy(47, -9))]),
    case("bin_off_walkway", "positioning", "vague", "Move the trash bin off the walkway.",
         [on(["ground", "paved"], asset="trash_bin_1"), near_point(-33.5, -5.5, 12, asset="trash_bin_1"),
          only(assets=["trash_bin_1"])],
         [call("place_asset", asset="trash_bin_1", location=xy(-30, -8))]),
    case("ego_east_side", "positioning", "vague",
         "Could the ego maybe start somewhere else, like... over on the east side of the map?",
         [near("east gate", 40, asset="ego"), on(["drivable"], asset="ego"), only(assets=["ego"])],
         [call("place_asset", asset="ego", location=loc("in_lane", "east gate", lane="main_westbound"))]),
    case("robot_near_origin", "positioning", "vague", "re-init the robot somewhere around the origin",
         [near_point(0, 0, 10, category="ackermann_robot"), only("ackermann_robot")],
         [call("place_asset", asset="ackermann_robot_1", location=xy(0, -1.75))],
         tags=MULTI,
         setup=[turn("Add a robot in lot A.",
                     call("add_asset", category="ackermann_robot", location=loc("at", "parking lot A")))]),
    case("lot_b_car_on_main", "positioning", "vague",
         "For the picture, one of the lot B cars should be out on Main Street.",
         [only(*LOT_B_CARS)],
         [call("place_asset", asset="passenger_car_2",
               location=loc("in_lane", "parking lot B entrance", lane="main_eastbound"))],
         alternatives=[[in_lane("main_eastbound", category=LOT_B_CARS)],
                       [in_lane("main_westbound", category=LOT_B_CARS)]]),
    case("tree_closer_to_lot", "positioning", "vague",
         "That tree just north of lot A: bring it in closer to the lot.",
         [near("parking lot A", 3, asset="tree_4"), only(assets=["tree_4"])],
         [call("place_asset", asset="tree_4", location=xy(-85, 42))]),
    case("hydrant_nearer_union", "positioning", "vague",
         "Hmm, maybe put the hydrant somewhere nearer the Student Union? I'm not sure where exactly.",
         [near("Student Union entrance", 15, asset="fire_hydrant_1"), only(assets=["fire_hydrant_1"])],
         [call("place_asset", asset="fire_hydrant_1", location=loc("at", "Student Union entrance"))]),
    # erroneous
    case("bensh_fountian", "positioning", "erroneous", "put the bensh by the fountian",
         [near("fountain", 10, asset="bench_1"), only(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=loc("at", "fountain"))]),
    case("s_u_v_parkin", "positioning", "erroneous", "plaice the S U V in parkin lot A",
         [near("parking lot A", 0.5, asset="suv_1"), only(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=loc("at", "parking lot A"))]),
    case("ego_southbound_thx", "positioning", "erroneous",
         "can u put the ego in the southbound lane on campus drive thx",
         [in_lane("campus_southbound", asset="ego", aligned=True), only(assets=["ego"])],
         [call("place_asset", asset="ego", location=loc("in_lane", "campus_southbound"))]),
    case("bin_stundet_union", "positioning", "erroneous", "move the trash bin to the stundet union entrence",
         [near("Student Union entrance", 10, asset="trash_bin_1"), only(assets=["trash_bin_1"])],
         [call("place_asset", asset="trash_bin_1", location=loc("at", "Student Union entrance"))]),
    case("hydrent_libary_dropof", "positioning", "erroneous", "the fire hydrent shud go by the libary drop off",
         [near("Library entrance", 12, asset="fire_hydrant_1"), only(assets=["fire_hydrant_1"])],
         [call("place_asset", asset="fire_hydrant_1", location=loc("at", "Library entrance"))]),
    case("bench_insdie_hall", "positioning", "erroneous", "put the bench insdie the engeneering hall",
         [refused(), only()],
         [call("place_asset", asset="bench_1", location=xy(-40, 28))],
         tags=IMPOSSIBLE),
    case("pedestrain_other_side", "positioning", "erroneous",
         "now put the pedestrain on the other side of the rode, by the Engeneering hall",
         [near("Engineering Hall entrance", 12, category="pedestrian"), only("pedestrian")],
         [call("place_asset", asset="pedestrian_1", location=loc("at", "Engineering Hall entrance"))],
         tags=MULTI,
         setup=[turn("Add a pedestrian at the bus stop.",
                     call("add_asset", category="pedestrian", location=loc("at", "bus stop")),
                     planned=True)]),
    case("hydrant_next_2_stop", "positioning", "erroneous", "yo move the hydrant next 2 the bus stop lol",
         [near("bus stop", 6, asset="fire_hydrant_1"), only(assets=["fire_hydrant_1"])],
         [call("place_asset", asset="fire_hydrant_1", location=loc("at", "bus stop"))]),
]

# ---------------------------------------------------------------------------------------------
# Moving: shifts, turns and behaviours of existing assets.
# ---------------------------------------------------------------------------------------------

PEDESTRIAN_AT_STOP = turn("Add a pedestrian at the bus stop.",
                          call("add_asset", category="pedestrian", location=loc("at", "bus stop")))

MOVING: list[Json] = [
    # direct
    case("ego_ten_forward", "moving", "direct", "Move the ego 10 metres forward.",
         [moved("ego", min_distance=9, max_distance=11, direction="forward"), only(assets=["ego"])],
         [call("move_asset", asset="ego", forward=10)]),
    case("suv_half_turn", "moving", "direct", "Turn the SUV around 180 degrees.",
         [moved("suv_1", max_distance=0.5, turn_min_deg=170), only(assets=["suv_1"])],
         [call("move_asset", asset="suv_1", turn_deg=180)]),
    case("car2_westbound", "moving", "direct", "Make passenger_car_2 drive in lane main_westbound.",
         [does("drive_lane", lane="main_westbound", asset="passenger_car_2"), only(assets=["passenger_car_2"])],
         [call("set_behaviour", asset="passenger_car_2", behaviour=beh("drive_lane", lane="main_westbound"))]),
    case("bin_two_east", "moving", "direct", "Shift the trash bin 2 metres east.",
         [near_point(-31.5, -5.5, 0.5, asset="trash_bin_1"), moved("trash_bin_1", min_distance=1.5, max_distance=2.5),
          only(assets=["trash_bin_1"])],
         [call("move_asset", asset="trash_bin_1", east=2)]),
    case("ego_eight_mps", "moving", "direct", "Make the ego drive at 8 m/s.",
         [does("drive_lane", asset="ego", speed_min=7.9, speed_max=8.1, lane="main_eastbound"),
          only(assets=["ego"])],
         [call("set_behaviour", asset="ego", behaviour=beh("drive_lane", lane="main_eastbound", speed=8))]),
    case("bench_three_south", "moving", "direct", "Move the bench 3 metres south.",
         [near_point(-26, -9.9, 0.5, asset="bench_1"), only(assets=["bench_1"])],
         [call("move_asset", asset="bench_1", north=-3)]),
    case("suv_circles_lot_b", "moving", "direct", "Make the SUV drive in circles in parking lot B.",
         [does("circle", asset="suv_1", centre_near="parking lot B"), only(assets=["suv_1"])],
         [call("set_behaviour", asset="suv_1", behaviour=beh("circle"))]),
    # indirect
    case("advance_thirty_feet", "moving", "indirect", "Advance the ego 30 feet along its lane.",
         [moved("ego", min_distance=8, max_distance=10.5, direction="forward"), only(assets=["ego"])],
         [call("move_asset", asset="ego", forward=9.14)]),
    case("back_truck_up", "moving", "indirect", "Back my truck up a couple of metres.",
         [moved("truck_1", min_distance=1.5, max_distance=3.5, direction="backward"), only("truck")],
         [call("move_asset", asset="truck_1", forward=-2)],
         tags=MULTI, setup=[TRUCK_IN_LOT_B]),
    case("yaw_plus_ninety", "moving", "indirect", "Apply a +90° yaw to the SUV, in place (CCW positive).",
         [moved("suv_1", max_distance=0.5, turn_min_deg=80, turn_max_deg=100), only(assets=["suv_1"])],
         [call("move_asset", asset="suv_1", turn_deg=90)]),
    case("walking_pace", "moving", "indirect", "In the footage, the ego is seen creeping along at walking pace.",
         [does("drive_lane", asset="ego", speed_min=0.5, speed_max=2.0), only(assets=["ego"])],
         [call("set_behaviour", asset="ego", behaviour=beh("drive_lane", lane="main_eastbound", speed=1.4))]),
    case("suv_joins_traffic", "moving", "indirect",
         "The SUV pulls out of its bay and joins the eastbound traffic on Main Street.",
         [does("drive_lane", lane="main_eastbound", asset="suv_1"), only(assets=["suv_1"])],
         [call("set_behaviour", asset="suv_1", behaviour=beh("drive_lane", lane="main_eastbound"))]),
    case("marked_crossing", "moving", "indirect",
         "That pedestrian has to get across Main Street, at a marked crossing, not mid-block.",
         [does("cross_road", category="pedestrian", crosses_lane="main_eastbound"), only("pedestrian")],
         [call("set_behaviour", asset="pedestrian_1", behaviour=beh("cross_road"))],
         tags=MULTI, setup=[PEDESTRIAN_AT_STOP]),
    case("ease_tree", "moving", "indirect", "Ease the tree by the Library a metre or two further from the bench.",
         [moved("tree_1", min_distance=0.8, max_distance=2.5, direction="right"), only(assets=["tree_1"])],
         [call("move_asset", asset="tree_1", north=-1.5)]),
    case("ten_mps_maybe", "moving", "indirect",
         "I'm not totally sure, but I think the ego could go faster? Maybe 10 m/s?",
         [does("drive_lane", asset="ego", speed_min=9.9, speed_max=10.1), only(assets=["ego"])],
         [call("set_behaviour", asset="ego", behaviour=beh("drive_lane", lane="main_eastbound", speed=10))]),
    case("hydrant_strolls", "moving", "indirect", "Have the fire hydrant stroll across the road.",
         [refused(), only()],
         [call("set_behaviour", asset="fire_hydrant_1", behaviour=beh("cross_road"))],
         tags=IMPOSSIBLE),
    case("bullets_speed_and_turn", "moving", "indirect",
         "- ego: drive at 6 m/s\n- SUV: turn it round to face the other way",
         [does("drive_lane", asset="ego", speed_min=5.9, speed_max=6.1), moved("suv_1", turn_min_deg=170),
          only(assets=["ego", "suv_1"])],
         [call("set_behaviour", asset="ego", behaviour=beh("drive_lane", lane="main_eastbound", speed=6)),
          call("move_asset", asset="suv_1", turn_deg=180)],
         tags=COMPOUND),
    case("csv_two_drivers", "moving", "indirect",
         "asset,action\npassenger_car_1,drive main_westbound\npassenger_car_2,drive main_eastbound",
         [does("drive_lane", lane="main_westbound", asset="passenger_car_1"),
          does("drive_lane", lane="main_eastbound", asset="passenger_car_2"),
          only(assets=["passenger_car_1", "passenger_car_2"])],
         [call("set_behaviour", asset="passenger_car_1", behaviour=beh("drive_lane", lane="main_westbound")),
          call("set_behaviour", asset="passenger_car_2", behaviour=beh("drive_lane", lane="main_eastbound"))],
         tags=COMPOUND),
    # vague
    case("nudge_suv", "moving", "vague", "Could you nudge the SUV forward a tiny bit? Just a touch.",
         [moved("suv_1", min_distance=0.2, max_distance=3, direction="forward"), only(assets=["suv_1"])],
         [call("move_asset", asset="suv_1", forward=1)]),
    case("ego_brrr", "moving", "vague", "make the ego go brrr, way faster",
         [does("drive_lane", asset="ego", speed_min=5.5), only(assets=["ego"])],
         [call("set_behaviour", asset="ego", behaviour=beh("drive_lane", lane="main_eastbound", speed=8))]),
    case("lot_b_cars_moving", "moving", "vague", "Get the lot B cars moving.",
         [does(["drive_lane", "circle", "follow_path"], category=LOT_B_CARS, min_count=3), only(*LOT_B_CARS)],
         [call("set_behaviour", asset="passenger_car_1", behaviour=beh("drive_lane", lane="main_westbound")),
          call("set_behaviour", asset="suv_1", behaviour=beh("drive_lane", lane="main_eastbound")),
          call("set_behaviour", asset="passenger_car_2", behaviour=beh("drive_lane", lane="campus_northbound"))]),
    case("shuffle_bin", "moving", "vague", "shuffle the bin over a bit so I can get the van past",
         [moved("trash_bin_1", min_distance=0.5, max_distance=5), only(assets=["trash_bin_1"])],
         [call("move_asset", asset="trash_bin_1", north=-1.5)]),
    case("ego_rolls_back", "moving", "vague", "The ego hesitates, then rolls back a few metres.",
         [moved("ego", min_distance=1.5, max_distance=8, direction="backward"), only(assets=["ego"])],
         [call("move_asset", asset="ego", forward=-3)]),
    case("perturb_lateral", "moving", "vague", "perturb the ego's start pose laterally, about a metre to its left",
         [moved("ego", min_distance=0.5, max_distance=1.5, direction="left"), only(assets=["ego"])],
         [call("move_asset", asset="ego", left=1)]),
    case("hydrant_back_from_kerb", "moving", "vague", "Could the hydrant sit a little further back from the kerb?",
         [moved("fire_hydrant_1", min_distance=0.3, max_distance=3, direction="left"),
          only(assets=["fire_hydrant_1"])],
         [call("move_asset", asset="fire_hydrant_1", north=1)]),
    case("slow_it_down", "moving", "vague", "hmm, maybe slow it down a bit? it seems kinda fast",
         [does("drive_lane", category=LOT_B_CARS, speed_max=4.5, lane="campus_northbound"), only(*LOT_B_CARS)],
         [call("set_behaviour", asset="passenger_car_3",
               behaviour=beh("drive_lane", lane="campus_northbound", speed=3))],
         tags=MULTI,
         setup=[turn("Add a car driving north on Campus Drive.",
                     call("add_asset", category="passenger_car",
                          behaviour=beh("drive_lane", lane="campus_northbound")),
                     planned=True)]),
    # erroneous
    case("mvoe_ego_foward", "moving", "erroneous", "mvoe the ego 20 meters foward",
         [moved("ego", min_distance=18, max_distance=22, direction="forward"), only(assets=["ego"])],
         [call("move_asset", asset="ego", forward=20)]),
    case("tern_sooveee", "moving", "erroneous", "tern the sooveee around",
         [moved("suv_1", max_distance=0.5, turn_min_deg=170), only(assets=["suv_1"])],
         [call("move_asset", asset="suv_1", turn_deg=180)]),
    case("donuts_lot_b", "moving", "erroneous", "make the suv do donuts in lot b lmao",
         [does("circle", asset="suv_1", centre_near="parking lot B"), only(assets=["suv_1"])],
         [call("set_behaviour", asset="suv_1", behaviour=beh("circle"))]),
    case("drvie_westboud", "moving", "erroneous", "make the ego drvie in the westboud lane",
         [does("drive_lane", lane="main_westbound", asset="ego"), only(assets=["ego"])],
         [call("set_behaviour", asset="ego", behaviour=beh("drive_lane", lane="main_westbound"))]),
    case("bentch_eest", "moving", "erroneous", "push the bentch 2 meeters eest",
         [near_point(-24, -6.9, 0.6, asset="bench_1"), only(assets=["bench_1"])],
         [call("move_asset", asset="bench_1", east=2)]),
    case("speed_too_three", "moving", "erroneous", "set the egos speed too 3 m/s",
         [does("drive_lane", asset="ego", speed_min=2.9, speed_max=3.1), only(assets=["ego"])],
         [call("set_behaviour", asset="ego", behaviour=beh("drive_lane", lane="main_eastbound", speed=3))]),
    case("stop_sine_circels", "moving", "erroneous", "make the stop sine drive around in circels",
         [refused(), only()],
         [call("set_behaviour", asset="stop_sign_1", behaviour=beh("circle"))],
         tags=IMPOSSIBLE),
    case("five_hundred_forwerd", "moving", "erroneous", "mvoe the ego 500 meters forwerd",
         [refused(), only()],
         [call("move_asset", asset="ego", forward=500)],
         tags=IMPOSSIBLE),
]

# ---------------------------------------------------------------------------------------------
# Arrangement: several new assets in a layout.
# ---------------------------------------------------------------------------------------------

RUBBLE_IN_LOT_B = turn("Drop some rubble in the middle of lot B.",
                       call("add_asset", category="cement_rubble", location=loc("at", "parking lot B")))
DEVICES = ["traffic_cone", "road_barrier"]

ARRANGEMENT: list[Json] = [
    # direct
    case("cone_line_ahead_of_ego", "arrangement", "direct",
         "Put a line of five cones across the eastbound lane in front of the ego.",
         [exactly("traffic_cone", 5), layout("line", category="traffic_cone", min_count=5),
          rel("in_front_of", "ego", category="traffic_cone", max_distance=15, require_all=True),
          only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5,
               location=loc("in_front_of", "ego"))]),
    case("bollard_ring_hydrant", "arrangement", "direct", "Arrange six bollards in a ring around the fire hydrant.",
         [exactly("bollard", 6), layout("ring", around="fire_hydrant_1", category="bollard", min_count=6),
          only("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="ring", count=6, location=loc("at", "fire_hydrant_1"))]),
    case("westbound_edge_cones", "arrangement", "direct",
         "Line the right edge of lane main_westbound with eight cones, starting at the east gate.",
         [exactly("traffic_cone", 8), layout("line", category="traffic_cone", min_count=8),
          in_lane("main_westbound", category="traffic_cone"),
          near("east gate", 40, category="traffic_cone", require_all=True), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=8,
               location=loc("at", "east gate", lane="main_westbound"))]),
    case("four_cars_lot_a", "arrangement", "direct", "Park four cars side by side in parking lot A.",
         [exactly(LOT_B_CARS, 4),
          layout("line", category=LOT_B_CARS, min_count=4, spacing_min=2.2, spacing_max=3.6),
          near("parking lot A", 0.5, category=LOT_B_CARS, require_all=True), only(*LOT_B_CARS)],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4,
               location=loc("at", "parking lot A"))]),
    case("bollard_grid_fountain", "arrangement", "direct", "Place a 3 by 3 grid of bollards at the fountain.",
         [exactly("bollard", 9), layout("cluster", category="bollard", min_count=9, tolerance=4),
          near("fountain", 8, category="bollard", require_all=True), only("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="grid", count=9, columns=3,
               location=loc("at", "fountain"))]),
    case("bench_line_library", "arrangement", "direct",
         "Arrange four benches in a line in front of the Library entrance.",
         [exactly("bench", 4), layout("line", category="bench", min_count=4),
          near("Library entrance", 10, category="bench", require_all=True), only("bench")],
         [call("arrange_assets", categories=["bench"], shape="line", count=4,
               location=loc("in_front_of", "Library entrance"))]),
    case("bin_line_jtekt", "arrangement", "direct",
         "Put a line of four trash bins along the north sidewalk by the JTEKT building.",
         [exactly("trash_bin", 4), layout("line", category="trash_bin", min_count=4),
          on(["sidewalk"], category="trash_bin"),
          near("JTEKT building entrance", 15, category="trash_bin", require_all=True), only("trash_bin")],
         [call("arrange_assets", categories=["trash_bin"], shape="line", count=4,
               location=loc("on_sidewalk", "JTEKT building entrance"))]),
    # indirect
    case("taper_eastbound", "arrangement", "indirect",
         "Set up a taper closing the eastbound lane ahead of the ego: six channelizing devices along the lane edge.",
         [exactly(DEVICES, 6), layout("line", category=DEVICES, min_count=6),
          in_lane("main_eastbound", category=DEVICES),
          rel("in_front_of", "ego", category=DEVICES, max_distance=60, tolerance_deg=30, require_all=True),
          only(*DEVICES)],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=6,
               location=loc("at", "ego", along_m=20))]),
    case("stage_four_vans", "arrangement", "indirect", "I've got four vans to stage in lot B, side by side.",
         [exactly("truck", 4), layout("line", category="truck", min_count=4, spacing_min=2.5, spacing_max=4.5),
          near("parking lot B", 0.5, category="truck", require_all=True), only("truck")],
         [call("arrange_assets", categories=["truck"], shape="parking_row", count=4,
               location=loc("at", "parking lot B"))]),
    case("bollards_two_m", "arrangement", "indirect",
         "Bollards spaced two metres apart across the front of the Library entrance would stop cars mounting the "
         "footway. Five of them.",
         [exactly("bollard", 5), layout("line", category="bollard", min_count=5, spacing_min=1.8, spacing_max=2.2),
          near("Library entrance", 10, category="bollard", require_all=True), only("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="line", count=5, spacing=2,
               location=loc("in_front_of", "Library entrance"))]),
    case("avenue_of_trees", "arrangement", "indirect",
         "Plant an avenue: six trees in a straight row between Main Street and the Engineering Hall.",
         [exactly("tree", 6), layout("line", category="tree", min_count=6),
          near("Engineering Hall entrance", 20, category="tree", require_all=True),
          on(["ground", "sidewalk"], category="tree"), only("tree")],
         [call("arrange_assets", categories=["tree"], shape="line", count=6, heading_deg=0,
               location=xy(-40, 10.5))]),
    case("protest_ring", "arrangement", "indirect",
         "The protest image: eight people standing in a ring around the fountain.",
         [exactly("pedestrian", 8), layout("ring", around="fountain", category="pedestrian", min_count=8),
          only("pedestrian")],
         [call("arrange_assets", categories=["pedestrian"], shape="ring", count=8, location=loc("at", "fountain"))]),
    case("motorbikes_row", "arrangement", "indirect",
         "Along the JTEKT drop-off, five motorbikes stood in a tidy row.",
         [exactly("motorcycle", 5), layout("line", category="motorcycle", min_count=5),
          near("JTEKT building entrance", 12, category="motorcycle", require_all=True), only("motorcycle")],
         [call("arrange_assets", categories=["motorcycle"], shape="line", count=5,
               location=loc("at", "JTEKT building entrance"))]),
    case("calibration_grid", "arrangement", "indirect",
         "Spawn a calibration grid: 2 x 3 cones, 2 m pitch, centred at (40, -30).",
         [exactly("traffic_cone", 6),
          layout("cluster", category="traffic_cone", min_count=6, tolerance=2.6, spacing_min=1.8, spacing_max=2.2),
          near_point(40, -30, 3, category="traffic_cone", require_all=True), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="grid", count=6, columns=3, spacing=2,
               location=xy(40, -30))]),
    case("fill_a_row_if_empty", "arrangement", "indirect",
         "If lot A has no cars in it yet, fill one row of it with three.",
         [exactly(LOT_B_CARS, 3), layout("line", category=LOT_B_CARS, min_count=3),
          near("parking lot A", 0.5, category=LOT_B_CARS, require_all=True), only(*LOT_B_CARS)],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=3,
               location=loc("at", "parking lot A"))]),
    case("ring_100_m", "arrangement", "indirect", "Encircle the whole Library with cones at a 100-metre radius.",
         [refused(), only()],
         [call("arrange_assets", categories=["traffic_cone"], shape="ring", radius=100,
               location=loc("at", "Library entrance"))],
         tags=IMPOSSIBLE),
    case("steps_row_and_line", "arrangement", "indirect",
         "1. Park three cars side by side in lot A.\n2. Put a line of four cones in front of the JTEKT entrance.",
         [exactly(LOT_B_CARS, 3), exactly("traffic_cone", 4),
          layout("line", category=LOT_B_CARS, min_count=3),
          near("parking lot A", 0.5, category=LOT_B_CARS, require_all=True),
          layout("line", category="traffic_cone", min_count=4),
          near("JTEKT building entrance", 10, category="traffic_cone", require_all=True),
          only("traffic_cone", *LOT_B_CARS)],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=3,
               location=loc("at", "parking lot A")),
          call("arrange_assets", categories=["traffic_cone"], shape="line", count=4,
               location=loc("in_front_of", "JTEKT building entrance"))],
         tags=COMPOUND),
    # vague
    case("six_ish_round_rubble", "arrangement", "vague",
         "Maybe some cones in a circle around... I dunno, that rubble? Like six-ish?",
         [between("traffic_cone", 5, 8), layout("ring", around="cement_rubble_1", category="traffic_cone", min_count=5),
          only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=6,
               location=loc("at", "cement_rubble_1"))],
         tags=MULTI, setup=[RUBBLE_IN_LOT_B]),
    case("lil_wall", "arrangement", "vague", "make a lil wall of barriers across campus drive north of the junction",
         [between("road_barrier", 2, 8), layout("line", category="road_barrier", min_count=2, tolerance=1.5),
          near("north crosswalk", 25, category="road_barrier", require_all=True),
          near("campus_southbound", 1.5, category="road_barrier"), near("campus_northbound", 1.5, category="road_barrier"),
          on(["drivable"], category="road_barrier"), only("road_barrier")],
         [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, spacing=2.3, heading_deg=0,
               location=xy(0, 20))]),
    case("little_grove", "arrangement", "vague", "A little grove near the east gate would be lovely.",
         [between("tree", 3, 9), layout("cluster", category="tree", min_count=3, tolerance=12),
          near("east gate", 25, category="tree", require_all=True),
          on(["ground", "sidewalk", "paved"], category="tree"), only("tree")],
         [call("arrange_assets", categories=["tree"], shape="grid", count=4, spacing=4, location=xy(95, 20))]),
    case("queue_at_driveway", "arrangement", "vague", "Show a queue of cars backed up at the lot B driveway.",
         [between(LOT_B_CARS, 2, 8), layout("line", category=LOT_B_CARS, min_count=2, tolerance=1.5),
          near("parking lot B entrance", 25, category=LOT_B_CARS, require_all=True),
          on(["drivable"], category=LOT_B_CARS), only(*LOT_B_CARS)],
         [call("arrange_assets", categories=["passenger_car"], shape="line", count=3, spacing=6,
               location=loc("in_lane", "parking lot B entrance", lane="main_eastbound"))]),
    case("loose_huddle", "arrangement", "vague", "The students gathered in a loose huddle outside the Library.",
         [between("pedestrian", 3, 15), layout("cluster", category="pedestrian", min_count=3, tolerance=6),
          near("Library entrance", 12, category="pedestrian", require_all=True), only("pedestrian")],
         [call("arrange_assets", categories=["pedestrian"], shape="grid", count=6, location=loc("at", "Library entrance"))]),
    case("row_whatever_fits", "arrangement", "vague",
         "I guess a row of parked cars in lot A? Three, or maybe four, whatever fits.",
         [between(LOT_B_CARS, 3, 4), layout("line", category=LOT_B_CARS, min_count=3),
          near("parking lot A", 0.5, category=LOT_B_CARS, require_all=True), only(*LOT_B_CARS)],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=3,
               location=loc("at", "parking lot A"))]),
    case("slalom_bunch", "arrangement", "vague", "drop a bunch of cones in a line somewhere in lot A for a slalom",
         [between("traffic_cone", 4, 15), layout("line", category="traffic_cone", min_count=4),
          near("parking lot A", 0.5, category="traffic_cone", require_all=True), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=6, spacing=3,
               location=loc("at", "parking lot A"))]),
    case("barriers_across_driveway", "arrangement", "vague",
         "stack a few barriers in a row across the lot B driveway so nobody drives in while I unload",
         [between("road_barrier", 2, 5), layout("line", category="road_barrier", min_count=2),
          near("parking lot B entrance", 10, category="road_barrier", require_all=True), only("road_barrier")],
         [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, spacing=2, heading_deg=0,
               location=xy(47, -8))]),
    # erroneous
    case("lign_of_conez", "arrangement", "erroneous", "put a lign of 5 conez infront of the ego",
         [exactly("traffic_cone", 5), layout("line", category="traffic_cone", min_count=5),
          rel("in_front_of", "ego", category="traffic_cone", max_distance=15, require_all=True),
          only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5,
               location=loc("in_front_of", "ego"))]),
    case("parkt_in_a_roe", "arrangement", "erroneous", "arange for cars parkt in a roe in lot bee, four of them",
         [exactly(LOT_B_CARS, 4), layout("line", category=LOT_B_CARS, min_count=4),
          near("parking lot B", 0.5, category=LOT_B_CARS, require_all=True), only(*LOT_B_CARS)],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4,
               location=loc("at", "parking lot B"))]),
    case("ring_of_ppl", "arrangement", "erroneous", "ring of ppl around the fountain pls, 8 of em \U0001f64f",
         [exactly("pedestrian", 8), layout("ring", around="fountain", category="pedestrian", min_count=8),
          only("pedestrian")],
         [call("arrange_assets", categories=["pedestrian"], shape="ring", count=8, location=loc("at", "fountain"))]),
    case("tres_strait_line", "arrangement", "erroneous", "plant 4 tres in a strait line by the libary",
         [exactly("tree", 4), layout("line", category="tree", min_count=4),
          near("Library entrance", 15, category="tree", require_all=True), only("tree")],
         [call("arrange_assets", categories=["tree"], shape="line", count=4, location=loc("at", "Library entrance"))]),
    case("bollerds_grid", "arrangement", "erroneous", "sett up bollerds in a grid, 2 by 2, at the fountin",
         [exactly("bollard", 4), layout("cluster", category="bollard", min_count=4, tolerance=3),
          near("fountain", 8, category="bollard", require_all=True), only("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="grid", count=4, columns=2,
               location=loc("at", "fountain"))]),
    case("eestbound_edje", "arrangement", "erroneous", "line the eestbound lane edje with 6 coans from the ego onwards",
         [exactly("traffic_cone", 6), layout("line", category="traffic_cone", min_count=6),
          in_lane("main_eastbound", category="traffic_cone"),
          near("ego", 25, category="traffic_cone", require_all=True), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=6,
               location=loc("at", "ego", lane="main_eastbound"))]),
    case("hundred_fifty_cones", "arrangement", "erroneous", "make a ring of 150 cones around the fountian",
         [refused(), only()],
         [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=150, location=loc("at", "fountain"))],
         tags=IMPOSSIBLE),
    case("robots_row_ngl", "arrangement", "erroneous", "3 robots in a row in lot a ngl",
         [exactly("ackermann_robot", 3), layout("line", category="ackermann_robot", min_count=3),
          near("parking lot A", 0.5, category="ackermann_robot", require_all=True), only("ackermann_robot")],
         [call("arrange_assets", categories=["ackermann_robot"], shape="line", count=3,
               location=loc("at", "parking lot A"))]),
    case("anuther_row", "arrangement", "erroneous", "ad anuther row like that in lot B",
         [exactly(LOT_B_CARS, 3), layout("line", category=LOT_B_CARS, min_count=3),
          near("parking lot B", 0.5, category=LOT_B_CARS, require_all=True), only(*LOT_B_CARS)],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=3,
               location=loc("at", "parking lot B"))],
         tags=MULTI,
         setup=[turn("Park three cars side by side in lot A.",
                     call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=3,
                          location=loc("at", "parking lot A")),
                     planned=True)]),
]

# ---------------------------------------------------------------------------------------------
# Appearance: colours, materials, time, weather and lights.
# ---------------------------------------------------------------------------------------------

AUTUMN = ["orange", "brown", "red", "gold", "maroon", "yellow"]
ENV = only(environment=True)

APPEARANCE: list[Json] = [
    # direct
    case("suv_red", "appearance", "direct", "Paint the SUV red.",
         [looks(colour="red", asset="suv_1"), only(assets=["suv_1"])],
         [call("set_asset_appearance", assets=["suv_1"], colour="red")]),
    case("make_night", "appearance", "direct", "Make it night.",
         [env(night=True, weather=["clear"]), ENV],
         [call("set_time_of_day", time="night")]),
    case("heavy_rain", "appearance", "direct", "Set the weather to heavy rain.",
         [env(weather=["rain"], intensity_min=0.75, **NOON), ENV],
         [call("set_weather", kind="rain", intensity=0.9)]),
    case("bench_wooden", "appearance", "direct", "Make the bench wooden.",
         [looks(material="wood", asset="bench_1"), only(assets=["bench_1"])],
         [call("set_asset_appearance", assets=["bench_1"], material="wood")]),
    case("street_lights_on", "appearance", "direct", "Turn the street lights on.",
         [env(street_lights="on", weather=["clear"], **NOON), ENV],
         [call("set_lighting", street_lights="on")]),
    case("cars_yellow", "appearance", "direct", "Paint both passenger cars yellow.",
         [looks(colour="yellow", category="passenger_car", min_count=2, require_all=True),
          only(assets=["passenger_car_1", "passenger_car_2"])],
         [call("set_asset_appearance", category="passenger_car", colour="yellow")]),
    case("clock_26_15", "appearance", "direct", "Set the clock to 26:15.",
         [refused(), only()],
         [call("set_time_of_day", time="26:15")],
         tags=IMPOSSIBLE),
    # indirect
    case("low_visibility", "appearance", "indirect",
         "Simulate a low-visibility condition: dense fog, per the test plan.",
         [env(weather=["fog"], intensity_min=0.7, **NOON), ENV],
         [call("set_weather", kind="fog", intensity=0.9)]),
    case("snowy_evening", "appearance", "indirect", "It was a snowy evening when the story began.",
         [env(weather=["snow"], time_from="17:00", time_to="23:30"), ENV],
         [call("set_weather", kind="snow"), call("set_time_of_day", time="evening")],
         tags=COMPOUND),
    case("after_sunrise", "appearance", "indirect", "The photo was taken just after sunrise.",
         [env(time_from="06:15", time_to="08:00", weather=["clear"]), ENV],
         [call("set_time_of_day", time="sunrise")]),
    case("timber_finish", "appearance", "indirect", "Give the bench a natural timber finish.",
         [looks(material="wood", asset="bench_1"), only(assets=["bench_1"])],
         [call("set_asset_appearance", assets=["bench_1"], material="wood")]),
    case("white_van", "appearance", "indirect", "My van's meant to be the white one. Can you sort that out so I can spot it in the lot?",
         [looks(colour="white", category="truck", require_all=True), only("truck")],
         [call("set_asset_appearance", category="truck", colour="white")],
         tags=MULTI, setup=[TRUCK_IN_LOT_B]),
    case("contrast_bollards", "appearance", "indirect",
         "Bollards must contrast with the paving: colour the ones I just added yellow.",
         [looks(colour="yellow", category="bollard", min_count=3, require_all=True), only("bollard")],
         [call("set_asset_appearance", category="bollard", colour="yellow")],
         tags=MULTI,
         setup=[turn("Put three bollards in front of the Library entrance.",
                     call("add_asset", category="bollard", count=3, location=loc("in_front_of", "Library entrance")))]),
    case("perception_run", "appearance", "indirect",
         "For the perception run: exposure 0.5, and vehicle headlights forced on.",
         [env(exposure_min=0.45, exposure_max=0.55, vehicle_lights="on", weather=["clear"], **NOON), ENV],
         [call("set_lighting", exposure=0.5), call("set_lighting", vehicle_lights="on")],
         tags=COMPOUND),
    case("just_overcast", "appearance", "indirect",
         "Um, could it be a bit cloudy? Not raining or anything, just overcast, I think.",
         [env(weather=["cloudy"], **NOON), ENV],
         [call("set_weather", kind="cloudy")]),
    case("nine_pm_drizzle", "appearance", "indirect",
         "The accident happened at nine in the evening, in a light drizzle.",
         [env(weather=["rain"], intensity_max=0.45, time_from="20:45", time_to="21:15"), ENV],
         [call("set_time_of_day", time="21:00"), call("set_weather", kind="rain", intensity=0.3)],
         tags=COMPOUND),
    case("paint_main_street", "appearance", "indirect", "Paint Main Street's tarmac red for the new bus lane.",
         [refused(), only()],
         [call("set_asset_appearance", assets=["Main Street"], colour="red")],
         tags=IMPOSSIBLE),
    # vague
    case("darker_evening_ish", "appearance", "vague",
         "I think it's too bright? Could you make it a bit darker, maybe like evening-ish?",
         [ENV],
         [call("set_time_of_day", time="evening")],
         alternatives=[[env(time_from="17:00", time_to="23:59")], [env(exposure_max=0.9)]]),
    case("gloomy_and_wet", "appearance", "vague", "Make it feel gloomy and wet.",
         [env(weather=["rain"]), ENV],
         [call("set_weather", kind="rain")]),
    case("suv_look_sick", "appearance", "vague", "make the suv look sick, like matte black or smth",
         [looks(colour="black", material="matte", asset="suv_1"), only(assets=["suv_1"])],
         [call("set_asset_appearance", assets=["suv_1"], colour="black", material="matte")]),
    case("winter_scene", "appearance", "vague", "Winter scene, please.",
         [env(weather=["snow"]), ENV],
         [call("set_weather", kind="snow")]),
    case("autumnal_trees", "appearance", "vague", "Make the trees look more autumnal.",
         [looks(colour=AUTUMN, category="tree", min_count=4, require_all=True), only("tree")],
         [call("set_asset_appearance", category="tree", colour="orange")]),
    case("night_run", "appearance", "vague", "it's late, I'm on the night run",
         [env(night=True), ENV],
         [call("set_time_of_day", time="night")]),
    case("lamps_always_lit", "appearance", "vague", "Lamps should stay lit whatever the hour.",
         [env(street_lights="on", **NOON), ENV],
         [call("set_lighting", street_lights="on")]),
    case("something_warmer", "appearance", "vague",
         "hmm... actually maybe not blue. Something warmer? Orange, I guess?",
         [looks(colour="orange", asset="bench_1"), only(assets=["bench_1"])],
         [call("set_asset_appearance", assets=["bench_1"], colour="orange")],
         tags=MULTI,
         setup=[turn("Paint the bench blue.", call("set_asset_appearance", assets=["bench_1"], colour="blue"),
                     planned=True)]),
    case("night_fog_lamps", "appearance", "vague", "Night, fog, street lamps blazing.",
         [env(night=True, weather=["fog"], street_lights="on"), ENV],
         [call("set_time_of_day", time="night"), call("set_weather", kind="fog"),
          call("set_lighting", street_lights="on")],
         tags=COMPOUND),
    # erroneous
    case("pain_suv_yelow", "appearance", "erroneous", "pain the suv yelow",
         [looks(colour="yellow", asset="suv_1"), only(assets=["suv_1"])],
         [call("set_asset_appearance", assets=["suv_1"], colour="yellow")]),
    case("make_it_snoe", "appearance", "erroneous", "make it snoe",
         [env(weather=["snow"], **NOON), ENV],
         [call("set_weather", kind="snow")]),
    case("nighttime_rn", "appearance", "erroneous", "make it nighttime rn \U0001f319",
         [env(night=True, weather=["clear"]), ENV],
         [call("set_time_of_day", time="night")]),
    case("whether_fogy", "appearance", "erroneous", "chnage the whether to fogy",
         [env(weather=["fog"], **NOON), ENV],
         [call("set_weather", kind="fog")]),
    case("streat_lites_of", "appearance", "erroneous", "turn the streat lites of",
         [env(street_lights="off", **NOON), ENV],
         [call("set_lighting", street_lights="off")]),
    case("hidrant_gren", "appearance", "erroneous", "colur the fire hidrant gren",
         [looks(colour="green", asset="fire_hydrant_1"), only(assets=["fire_hydrant_1"])],
         [call("set_asset_appearance", assets=["fire_hydrant_1"], colour="green")]),
    case("monsoon_plz", "appearance", "erroneous", "can u make a monsoon happen plz",
         [refused(), only()],
         [call("set_weather", kind="monsoon")],
         tags=IMPOSSIBLE),
    case("quater_to_seven", "appearance", "erroneous", "set the tyme to quater to seven in the evening",
         [env(time_from="18:45", time_to="18:45", weather=["clear"]), ENV],
         [call("set_time_of_day", time="18:45")]),
]

ALL_CASES: list[Json] = [*SEARCH, *ADDITION, *REMOVAL, *POSITIONING, *MOVING, *ARRANGEMENT, *APPEARANCE]


def main() -> None:
    """Write the suite's JSONL: one case per line, in list order."""
    lines = [json.dumps(c, ensure_ascii=False) for c in ALL_CASES]
    SUITE_PATH.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(ALL_CASES)} cases to {SUITE_PATH}")


if __name__ == "__main__":
    main()
