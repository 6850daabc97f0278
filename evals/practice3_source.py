"""The third practice suite (`suites/practice3.jsonl`), a fourth development suite, as a plain case list.

Written from the campus world, the catalog, the Worker tools and the checks only, by a helper
who had not read the planners nor any other suite's prompts. `python -m drivetwin.evals.practice3_source`
rewrites the JSONL. Each case's `reference` is a plan the Workers carry out (or, for the
impossible requests, really refuse), so that the reference planner passes every case.

The prompts are written in the voices of people who have never seen the tool: a driving-test
engineer writing a scenario, a city planner, a game designer, someone typing fast on a phone,
a non-native speaker, someone who describes things instead of naming them, someone stating a
goal instead of an edit, and someone asking about the scene.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from drivetwin.evals.practice2_source import (  # the same case-writing helpers
    at,
    behaviour,
    call,
    count,
    delta,
    env,
    gone,
    lane,
    layout,
    looks,
    moved,
    near,
    near_point,
    relative,
    says,
    step,
    surface,
    xy,
)

Json = dict[str, Any]

# resolve(): under a strict editable install this module is a link into the build tree.
SUITE_PATH = Path(__file__).resolve().parent / "suites" / "practice3.jsonl"
SUITE_TAG = "practice3"

VEHICLES = ["passenger_car", "suv", "truck", "bus", "motorcycle", "ackermann_robot"]
CARS = ["passenger_car", "suv"]
OBSTACLES = ["traffic_cone", "road_barrier", "bollard", "construction_sign", "cement_rubble"]
LOT_B = ["passenger_car_1", "passenger_car_2", "suv_1"]
WEST_LIGHTS = [f"street_light_{n}" for n in range(1, 7)]


def only(*categories: str, assets: tuple[str, ...] = (), environment: bool = False) -> Json:
    """Guard against collateral edits: nothing but these may change."""
    return {
        "kind": "unchanged_except",
        "categories": list(categories),
        "assets": list(assets),
        "environment": environment,
    }


def kept(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": True}


ACCEPTED: Json = {"kind": "status", "accepted": True}
REFUSED: list[Json] = [{"kind": "status", "accepted": False}, only()]
QUESTION: list[Json] = [ACCEPTED, only()]


def case(
    name: str,
    prompt: str,
    checks: list[Json],
    reference: list[Json],
    *,
    tags: tuple[str, ...] = (),
    setup: tuple[Json, ...] = (),
    alternatives: tuple[list[Json], ...] = (),
    notes: str = "",
) -> Json:
    task, grade, _ = name.split(".", 2)
    out: Json = {"id": f"{SUITE_TAG}.{name}", "world": "campus", "prompt": prompt, "task": task, "grade": grade}
    out["tags"] = [SUITE_TAG, *tags]
    if setup:
        out["setup"] = list(setup)
        if "multi_turn" not in out["tags"]:
            out["tags"].append("multi_turn")
    out["checks"] = checks
    if alternatives:
        out["alternatives"] = list(alternatives)
    out["reference"] = reference
    if notes:
        out["notes"] = notes
    return out


IMPOSSIBLE = ("impossible",)
COMPOUND = ("compound",)


# Earlier turns several cases start from (replayed as given unless a case says `planned`).
CONES_AHEAD = step(
    "Drop four traffic cones in our lane roughly 25 m in front of the test car.",
    call("add_asset", category="traffic_cone", count=4, location=at("ego", "in_front_of", distance=25)),
)
BUS_AT_GATE = step(
    "Put a shuttle bus in the westbound lane by the east gate, just parked for now.",
    call("add_asset", category="bus", location=at("east gate", "in_lane", lane="main_westbound")),
)
WALKER_AT_STOP = step(
    "Add a pedestrian waiting at the bus stop.",
    call("add_asset", category="pedestrian", location=at("bus stop")),
)
JUNK_ON_ROAD = step(
    "Scatter a pile of rubble and a cone in the eastbound lane about 30 m ahead of our car.",
    call("add_asset", category="cement_rubble", location=at("ego", "in_front_of", distance=30)),
    call("add_asset", category="traffic_cone", location=at("ego", "in_front_of", distance=36)),
)
RAINY = step("Set heavy rain.", call("set_weather", kind="rain", intensity=0.9))


SEARCH = [
    # direct
    case(
        "search.direct.street_light_total",
        "How many street lights are there in the whole scene?",
        [*QUESTION, says("12", "twelve")],
        [call("find_assets", category="street_light")],
    ),
    case(
        "search.direct.trees_with_positions",
        "List every tree on the map together with its x and y coordinates.",
        [*QUESTION, says(all_of=("-26", "70", "85", "-85"))],
        [call("find_assets", category="tree")],
    ),
    case(
        "search.direct.lamp_nearest_ego",
        "Which street light stands closest to the ego vehicle?",
        [*QUESTION, says("street_light_2")],
        [call("find_assets", category="street_light", nearest_to="ego")],
    ),
    case(
        "search.direct.hydrant_position",
        "Find the fire hydrant and give me its position.",
        [*QUESTION, says(all_of=("16", "5.5"))],
        [call("find_assets", category="fire_hydrant")],
    ),
    case(
        "search.direct.campus_drive_lanes",
        "What lanes does Campus Drive have?",
        [*QUESTION, says(all_of=("campus_northbound", "campus_southbound"))],
        [call("find_lanes", road="Campus Drive")],
    ),
    case(
        "search.direct.landmark_nearest_fountain",
        "Which named place is nearest to the fountain?",
        [*QUESTION, says("JTEKT", "JTEKT building entrance")],
        [call("find_landmarks", nearest_to="fountain")],
    ),
    case(
        "search.direct.bus_size",
        "Tell me the length, width and height of a bus from the catalog.",
        QUESTION,
        [call("asset_properties", category="bus")],
        alternatives=([says(all_of=("12", "2.55", "3.2"))], [says("12x2.55x3.2")]),
    ),
    case(
        "search.direct.lot_b_vehicles",
        "Which vehicles are parked in parking lot B? Give me their ids.",
        [*QUESTION, says(all_of=("passenger_car_1", "passenger_car_2", "suv_1"))],
        [call("find_assets", near="parking lot B", within=26)],
    ),
    case(
        "search.direct.nearest_to_stop_sign",
        "What is the nearest object to the stop sign, and how far away is it?",
        [*QUESTION, says("street_light_6", all_of=("0.6",))],
        [call("find_assets", nearest_to="stop_sign_1")],
    ),
    case(
        "search.direct.cones_after_drop",
        "How many traffic cones are in the scene now?",
        [*QUESTION, says("4", "four")],
        [call("find_assets", category="traffic_cone")],
        setup=(step(CONES_AHEAD["prompt"], *CONES_AHEAD["calls"], planned=True),),
    ),
    # indirect
    case(
        "search.indirect.night_drive_lamps",
        "I'm planning a night drive and want to know how well lit the campus is: how many lamp posts are there already?",
        [*QUESTION, says("12", "twelve")],
        [call("find_assets", category="street_light")],
    ),
    case(
        "search.indirect.before_filling_lot",
        "Before I start filling the student parking with cars, could you check what is already standing in it?",
        [*QUESTION, says(all_of=("passenger_car_1", "passenger_car_2", "suv_1"))],
        [call("find_assets", near="parking lot B", within=26)],
    ),
    case(
        "search.indirect.first_signal_eastbound",
        "When our test car sets off east it will meet a traffic signal; I need to know which one it reaches first.",
        [*QUESTION, says("traffic_light_1")],
        [call("find_assets", category="traffic_light", nearest_to="ego")],
    ),
    case(
        "search.indirect.campus_drive_clear",
        "Could you tell me whether anything is standing in the lanes of Campus Drive right now? I don't want surprises in the northbound run.",
        [*QUESTION, says("0", "no", "none", "nothing", "empty", "clear")],
        [call("find_assets", lane="Campus Drive")],
    ),
    case(
        "search.indirect.closer_lot_for_ego",
        "My car needs to pull over somewhere out of traffic; which of the two car parks is closer to where it sits now?",
        [*QUESTION, says("parking lot A", "lot A")],
        [call("find_landmarks", query="parking lot", nearest_to="ego")],
    ),
    case(
        "search.indirect.shuttle_stop_seating",
        "For the shuttle route I need the location of the bus stop, and whether there is somewhere to sit near it.",
        [*QUESTION, says(all_of=("bench_1", "-30"))],
        [call("find_landmarks", query="bus stop"), call("find_assets", near="bus stop", within=8)],
        tags=COMPOUND,
    ),
    case(
        "search.indirect.where_ego_starts",
        "We always start runs from wherever the ego is parked; which named spot of the campus is it closest to?",
        [*QUESTION, says("parking lot A", "lot A")],
        [call("find_landmarks", nearest_to="ego")],
    ),
    case(
        "search.indirect.west_end_of_row",
        "In the student car park there is a short row of vehicles; which one is at the west end of it?",
        [*QUESTION, says("passenger_car_1")],
        [call("find_assets", nearest_to="15, -42", within=8)],
    ),
    case(
        "search.indirect.where_bus_went",
        "Where exactly did that bus end up? I need its coordinates for the scenario file.",
        [*QUESTION, says("bus_1", "bus"), says("1.8", "1.75")],
        [call("find_assets", category="bus")],
        setup=(BUS_AT_GATE,),
    ),
    # vague
    case(
        "search.vague.around_library",
        "what's around the library",
        [*QUESTION, says("street_light_4", "trash_bin_1", "tree_1", "bench_1")],
        [call("find_assets", near="Library entrance", within=20)],
    ),
    case(
        "search.vague.anything_on_road",
        "anything on the road at the moment?",
        [*QUESTION, says("ego", "test vehicle", "ego vehicle")],
        [call("find_assets", on_lane=True)],
    ),
    case(
        "search.vague.over_by_fountain",
        "what's over by the fountain",
        [*QUESTION, says("tree_2", "tree")],
        [call("find_assets", near="fountain", within=12)],
    ),
    case(
        "search.vague.whole_inventory",
        "so what have we got in this scene, roughly?",
        [*QUESTION, says("street_light", "street light", "street lights", "lamp")],
        [call("find_assets")],
    ),
    case(
        "search.vague.shuttle_pickup",
        "where do people catch the shuttle around here",
        [*QUESTION, says("-30", "bus stop")],
        [call("find_landmarks", query="bus stop")],
    ),
    case(
        "search.vague.the_cars",
        "the cars... where are they?",
        [*QUESTION, says(all_of=("passenger_car_1", "passenger_car_2"))],
        [call("find_assets", category="passenger_car")],
    ),
    case(
        "search.vague.red_things_junction",
        "is there something red near the crossroads?",
        [*QUESTION, says("fire_hydrant_1", "stop_sign_1", "hydrant", "stop sign")],
        [call("find_assets", near="main intersection", within=20)],
    ),
    case(
        "search.vague.distance_to_junction",
        "roughly how far is our car from the junction?",
        [*QUESTION, says("51", "60", "50")],
        [call("find_landmarks", nearest_to="ego")],
    ),
    case(
        "search.vague.lanes_overview",
        "tell me about the lanes",
        [*QUESTION, says(all_of=("main_eastbound", "campus_southbound"))],
        [call("find_lanes")],
    ),
    # erroneous
    case(
        "search.erroneous.how_many_tress",
        "how many tress r there",
        [*QUESTION, says("4", "four")],
        [call("find_assets", category="tree")],
    ),
    case(
        "search.erroneous.wich_streetlamp",
        "wich streetlamp is closest to teh ego car",
        [*QUESTION, says("street_light_2")],
        [call("find_assets", category="street_light", nearest_to="ego")],
    ),
    case(
        "search.erroneous.where_stay_hydrant",
        "Please, where stay the fire hidrant in this map?",
        [*QUESTION, says(all_of=("16", "5.5"))],
        [call("find_assets", category="fire_hydrant")],
    ),
    case(
        "search.erroneous.bus_weight",
        "How much is weight of one bus, please tell",
        [*QUESTION, says("12000", "12,000", "12 000", "12 tonnes", "12 t")],
        [call("asset_properties", category="bus")],
    ),
    case(
        "search.erroneous.cars_in_lot_b",
        "is ther any cars in lot b",
        [*QUESTION, says("passenger_car_1", "passenger_car_2", "yes")],
        [call("find_assets", category="passenger_car", near="parking lot B", within=26)],
    ),
    case(
        "search.erroneous.nerest_to_fountian",
        "what landmark nerest to fountian",
        [*QUESTION, says("JTEKT", "JTEKT building entrance")],
        [call("find_landmarks", nearest_to="fountain")],
    ),
    case(
        "search.erroneous.main_stret_lanes",
        "list me the lanes on main stret",
        [*QUESTION, says(all_of=("main_eastbound", "main_westbound"))],
        [call("find_lanes", road="Main Street")],
    ),
    case(
        "search.erroneous.trafic_lights_crosroad",
        "how many trafic lights at the crosroad",
        [*QUESTION, says(all_of=("traffic_light_1", "traffic_light_2"))],
        [call("find_assets", category="traffic_light", near="main intersection", within=20)],
    ),
    case(
        "search.erroneous.closest_to_stop_sing",
        "whats the closest thing too the stop sing",
        [*QUESTION, says("street_light_6")],
        [call("find_assets", nearest_to="stop_sign_1")],
    ),
    case(
        "search.erroneous.cones_i_put",
        "how many cone did i put just now, and where is they",
        [*QUESTION, says("4", "four"), says("-35", "-36", "-37", "-34", "-33")],
        [call("find_assets", category="traffic_cone")],
        setup=(step(CONES_AHEAD["prompt"], *CONES_AHEAD["calls"], planned=True),),
    ),
    case(
        "search.direct.benches_and_main_lanes",
        "How many benches are there, and which lanes does Main Street have?",
        [*QUESTION, says(all_of=("main_eastbound", "main_westbound")), says("bench_1", "1", "one")],
        [call("find_assets", category="bench"), call("find_lanes", road="Main Street")],
        tags=COMPOUND,
    ),
]


ADDITION = [
    # direct
    case(
        "addition.direct.walker_library_entrance",
        "Add one pedestrian standing at the Library entrance.",
        [delta("pedestrian", 1, 1), near("Library entrance", 5, category="pedestrian"), only("pedestrian")],
        [call("add_asset", category="pedestrian", location=at("Library entrance"))],
    ),
    case(
        "addition.direct.cones_ahead_15m",
        "Put 3 traffic cones in lane main_eastbound about 15 m ahead of the ego vehicle.",
        [
            delta("traffic_cone", 3, 3),
            lane("main_eastbound", category="traffic_cone"),
            near_point(-45, -1.75, 6, category="traffic_cone", require_all=True),
            only("traffic_cone"),
        ],
        [call("add_asset", category="traffic_cone", count=3, location=at("ego", "in_front_of", distance=15))],
    ),
    case(
        "addition.direct.bus_westbound_6",
        "Add a bus driving in the westbound lane of Main Street at 6 m/s.",
        [
            delta("bus", 1, 1),
            behaviour("drive_lane", category="bus", lane="main_westbound", speed_min=5.5, speed_max=6.5),
            only("bus"),
        ],
        [
            call(
                "add_asset",
                category="bus",
                location=at("main_westbound"),
                behaviour={"kind": "drive_lane", "lane": "main_westbound", "speed": 6},
            )
        ],
    ),
    case(
        "addition.direct.hydrant_by_bus_stop",
        "Add a fire hydrant on the sidewalk next to the bus stop.",
        [
            delta("fire_hydrant", 1, 1),
            near("bus stop", 6, category="fire_hydrant"),
            surface("sidewalk", "ground", category="fire_hydrant"),
            only("fire_hydrant"),
        ],
        [call("add_asset", category="fire_hydrant", location=at("bus stop", "on_sidewalk"))],
    ),
    case(
        "addition.direct.two_benches_fountain",
        "Add two benches near the fountain.",
        [delta("bench", 2, 2), near("fountain", 10, category="bench", require_all=True), only("bench")],
        [call("add_asset", category="bench", count=2, location=at("fountain"))],
    ),
    case(
        "addition.direct.red_car_lot_a",
        "Add a red passenger car in parking lot A.",
        [
            delta("passenger_car", 1, 1),
            near("parking lot A", 1, category="passenger_car"),
            looks(category="passenger_car", colour="red"),
            only("passenger_car"),
        ],
        [call("add_asset", category="passenger_car", location=at("parking lot A"), colour="red")],
    ),
    case(
        "addition.direct.crosser_north",
        "Add a pedestrian who crosses the road at the north crosswalk.",
        [
            delta("pedestrian", 1, 1),
            behaviour("cross_road", category="pedestrian"),
            near("north crosswalk", 8, category="pedestrian"),
            only("pedestrian"),
        ],
        [call("add_asset", category="pedestrian", location=at("north crosswalk"), behaviour={"kind": "cross_road"})],
    ),
    case(
        "addition.direct.motorbike_northbound",
        "Add a motorcycle driving north on Campus Drive.",
        [delta("motorcycle", 1, 1), only("motorcycle")],
        [
            call(
                "add_asset",
                category="motorcycle",
                location=at("campus_northbound"),
                behaviour={"kind": "follow_path", "waypoints": [[1.75, -60.0], [1.75, 80.0]], "speed": 6},
            )
        ],
        alternatives=(
            [behaviour("drive_lane", category="motorcycle", lane="campus_northbound")],
            [behaviour("follow_path", category="motorcycle"), lane("campus_northbound", category="motorcycle")],
        ),
        notes="A motorcycle moves as a walker, so the Workers refuse drive_lane for it; a path up the lane is accepted too.",
    ),
    case(
        "addition.direct.sign_lot_b_entrance",
        "Add a construction sign at the parking lot B entrance.",
        [
            delta("construction_sign", 1, 1),
            near("parking lot B entrance", 6, category="construction_sign"),
            only("construction_sign"),
        ],
        [call("add_asset", category="construction_sign", location=at("parking lot B entrance"))],
    ),
    case(
        "addition.direct.helicopter_roof",
        "Add a helicopter on the roof of the JTEKT Building.",
        REFUSED,
        [call("add_asset", category="helicopter", location=at("JTEKT Building"))],
        tags=IMPOSSIBLE,
        notes="There is no helicopter in the catalog, and nothing stands on a roof.",
    ),
    case(
        "addition.direct.car_inside_engineering",
        "Add a passenger car at x = -40, y = 28.",
        REFUSED,
        [call("add_asset", category="passenger_car", location=xy(-40, 28))],
        tags=IMPOSSIBLE,
        notes="(-40, 28) is inside Engineering Hall.",
    ),
    # indirect
    case(
        "addition.indirect.jaywalker_test",
        "I want to see whether our car brakes for someone who steps out into the road without using a crossing. Set that up in front of it.",
        [
            delta("pedestrian", 1, 1),
            behaviour("jaywalk", category="pedestrian", crosses_lane="main_eastbound"),
            only("pedestrian"),
        ],
        [call("add_asset", category="pedestrian", behaviour={"kind": "jaywalk"})],
    ),
    case(
        "addition.indirect.two_waiting_students",
        "It would make the shuttle stop look realistic if two students were waiting there.",
        [delta("pedestrian", 2, 2), near("bus stop", 8, category="pedestrian", require_all=True), only("pedestrian")],
        [call("add_asset", category="pedestrian", count=2, location=at("bus stop"))],
    ),
    case(
        "addition.indirect.debris_30m",
        "Our perception team wants something lying on the road: broken concrete in the eastbound lane about thirty metres ahead of the test car.",
        [
            delta("cement_rubble", 1, 1),
            lane("main_eastbound", category="cement_rubble"),
            near_point(-30, -1.75, 8, category="cement_rubble"),
            only("cement_rubble"),
        ],
        [call("add_asset", category="cement_rubble", location=at("ego", "in_front_of", distance=30))],
    ),
    case(
        "addition.indirect.busier_student_lot",
        "The student parking looks too empty; one more four-by-four parked there would help.",
        [delta("suv", 1, 1), near("parking lot B", 1, category="suv", scope="added"), only("suv")],
        [call("add_asset", category="suv", location=at("parking lot B"))],
    ),
    case(
        "addition.indirect.lorry_at_jtekt",
        "For the delivery scenario there should be a lorry waiting at the JTEKT drop-off.",
        [
            delta("truck", 1, 1),
            near("JTEKT building entrance", 10, category="truck"),
            surface("drivable", category="truck"),
            only("truck"),
        ],
        [call("add_asset", category="truck", location=at("JTEKT building entrance"))],
    ),
    case(
        "addition.indirect.cyclist_east",
        "Could we have a cyclist riding east along Main Street, ahead of our car?",
        [delta("bicycle", 1, 1), behaviour(["follow_path", "drive_lane"], category="bicycle"), only("bicycle")],
        [
            call(
                "add_asset",
                category="bicycle",
                location=at("ego", "in_front_of", distance=15),
                behaviour={"kind": "follow_path", "waypoints": [[-45.0, -2.5], [100.0, -2.5]], "speed": 4},
            )
        ],
        notes="Bicycles move as walkers: the Workers refuse drive_lane for them, so the path is explicit.",
    ),
    case(
        "addition.indirect.dark_corner_fountain",
        "At night the corner around the fountain is pitch black; whatever the campus normally uses to light paths should go there.",
        [delta("street_light", 1, 3), near("fountain", 8, category="street_light"), only("street_light")],
        [call("add_asset", category="street_light", location=at("fountain"))],
    ),
    case(
        "addition.indirect.rover_for_demo",
        "The robotics group is giving a demo tomorrow; their little four-wheeled research rover should be parked in the west car park.",
        [delta("ackermann_robot", 1, 1), near("parking lot A", 1, category="ackermann_robot"), only("ackermann_robot")],
        [call("add_asset", category="ackermann_robot", location=at("parking lot A"))],
    ),
    case(
        "addition.indirect.water_for_firefighters",
        "Fire safety review: the fire brigade has nowhere to connect a hose near the Student Union.",
        [delta("fire_hydrant", 1, 2), near("Student Union entrance", 8, category="fire_hydrant"), only("fire_hydrant")],
        [call("add_asset", category="fire_hydrant", location=at("Student Union entrance"))],
    ),
    case(
        "addition.indirect.twelve_buses",
        "For a stress test of the planner I need twelve buses lined up on Main Street.",
        REFUSED,
        [call("add_asset", category="bus", count=12, location=at("main_westbound"))],
        tags=IMPOSSIBLE,
        notes="A scene holds at most 10 buses.",
    ),
    case(
        "addition.indirect.robot_then_sign",
        "Our robot will need a warning for drivers: put the rover at the JTEKT entrance and a road-work sign next to it.",
        [
            delta("ackermann_robot", 1, 1),
            delta("construction_sign", 1, 1),
            near("JTEKT building entrance", 8, category="ackermann_robot"),
            near("ackermann_robot_1", 5, category="construction_sign"),
            only("ackermann_robot", "construction_sign"),
        ],
        [
            call("add_asset", category="ackermann_robot", location=at("JTEKT building entrance")),
            call("add_asset", category="construction_sign", location=at("ackermann_robot_1", "next_to")),
        ],
        tags=COMPOUND,
    ),
    # vague
    case(
        "addition.vague.people_at_quad",
        "add some people around the quad",
        [delta("pedestrian", 2, 10), near("fountain", 12, category="pedestrian", require_all=True), only("pedestrian")],
        [call("add_asset", category="pedestrian", count=4, location=at("fountain"))],
    ),
    case(
        "addition.vague.few_cones_road",
        "put a few cones on the road somewhere",
        [delta("traffic_cone", 2, 6), surface("drivable", category="traffic_cone"), only("traffic_cone")],
        [call("add_asset", category="traffic_cone", count=3, location=at("main_eastbound"))],
    ),
    case(
        "addition.vague.more_traffic",
        "a bit more traffic would be good",
        [delta(VEHICLES, 1, 8), behaviour("drive_lane", category=VEHICLES, scope="added"), only(*VEHICLES)],
        [
            call(
                "add_asset",
                category="passenger_car",
                count=2,
                location=at("main_westbound"),
                behaviour={"kind": "drive_lane", "lane": "main_westbound"},
            )
        ],
    ),
    case(
        "addition.vague.trees_engineering",
        "could use some trees by the engineering building",
        [delta("tree", 1, 8), near("Engineering Hall entrance", 15, category="tree", require_all=True), only("tree")],
        [call("add_asset", category="tree", count=3, location=at("Engineering Hall entrance"))],
    ),
    case(
        "addition.vague.car_at_library_maybe",
        "maybe drop a car in front of the library?",
        [delta(CARS, 1, 1), near("Library entrance", 12, category=CARS), only(*CARS)],
        [call("add_asset", category="passenger_car", location=at("Library entrance"))],
    ),
    case(
        "addition.vague.obstacle_our_lane",
        "some kind of obstacle in our lane, whatever you think",
        [
            delta(OBSTACLES, 1, 6),
            lane("main_eastbound", category=OBSTACLES),
            relative("in_front_of", "ego", 80, category=OBSTACLES, tolerance_deg=20),
            only(*OBSTACLES),
        ],
        [call("add_asset", category="road_barrier", location=at("ego", "in_front_of", distance=25))],
    ),
    case(
        "addition.vague.bench_or_two",
        "a bench or two by the bus stop",
        [delta("bench", 1, 2), near("bus stop", 10, category="bench", scope="added", require_all=True), only("bench")],
        [call("add_asset", category="bench", location=at("bus stop"))],
    ),
    case(
        "addition.vague.bike_near_union",
        "stick a bike somewhere near the student union",
        [delta("bicycle", 1, 1), near("Student Union entrance", 12, category="bicycle"), only("bicycle")],
        [call("add_asset", category="bicycle", location=at("Student Union entrance"))],
    ),
    case(
        "addition.vague.lot_a_kinda_full",
        "lot A is empty, make it kinda full with parked cars",
        [delta(CARS, 3, 40), near("parking lot A", 1, category=CARS, scope="added", require_all=True), only(*CARS)],
        [
            call(
                "arrange_assets",
                categories=["passenger_car"],
                shape="parking_row",
                count=8,
                location=at("parking lot A"),
            )
        ],
    ),
    case(
        "addition.vague.something_at_hospital",
        "put a couple of people outside the hospital or so",
        REFUSED,
        [call("add_asset", category="pedestrian", count=2, location=at("hospital"))],
        tags=IMPOSSIBLE,
        notes="The campus has no hospital.",
    ),
    # erroneous
    case(
        "addition.erroneous.ad_pedestrains",
        "ad 2 pedestrains at the bus stpo",
        [delta("pedestrian", 2, 2), near("bus stop", 8, category="pedestrian", require_all=True), only("pedestrian")],
        [call("add_asset", category="pedestrian", count=2, location=at("bus stop"))],
    ),
    case(
        "addition.erroneous.cone_infront_ego",
        "plz put trafic cone infront of ego car",
        [
            delta("traffic_cone", 1, 1),
            relative("in_front_of", "ego", 40, category="traffic_cone", tolerance_deg=20),
            only("traffic_cone"),
        ],
        [call("add_asset", category="traffic_cone", location=at("ego", "in_front_of", distance=10))],
    ),
    case(
        "addition.erroneous.suv_parking_a",
        "Put one SUV on the parking A, is possible?",
        [delta("suv", 1, 1), near("parking lot A", 1, category="suv"), only("suv")],
        [call("add_asset", category="suv", location=at("parking lot A"))],
    ),
    case(
        "addition.erroneous.bin_nexto_bench",
        "add a trash bin nexto the bench at bus stop",
        [delta("trash_bin", 1, 1), near("bench_1", 4, category="trash_bin"), only("trash_bin")],
        [call("add_asset", category="trash_bin", location=at("bench_1", "next_to"))],
    ),
    case(
        "addition.erroneous.bus_driveing_south",
        "i want a bus driveing on the campus drive going south",
        [delta("bus", 1, 1), behaviour("drive_lane", category="bus", lane="campus_southbound"), only("bus")],
        [
            call(
                "add_asset",
                category="bus",
                location=at("campus_southbound"),
                behaviour={"kind": "drive_lane", "lane": "campus_southbound"},
            )
        ],
    ),
    case(
        "addition.erroneous.tree_beside_of_union",
        "Add please one tree beside of the Student Union entrance",
        [delta("tree", 1, 1), near("Student Union entrance", 8, category="tree"), only("tree")],
        [call("add_asset", category="tree", location=at("Student Union entrance"))],
    ),
    case(
        "addition.erroneous.spwan_motorbike",
        "spwan a motorbike at lot B entrence",
        [delta("motorcycle", 1, 1), near("parking lot B entrance", 8, category="motorcycle"), only("motorcycle")],
        [call("add_asset", category="motorcycle", location=at("parking lot B entrance"))],
    ),
    case(
        "addition.erroneous.bolards_crosswalk",
        "add 3 bolards at the crosswalk west side",
        [delta("bollard", 3, 3), near("west crosswalk", 8, category="bollard", require_all=True), only("bollard")],
        [call("add_asset", category="bollard", count=3, location=at("west crosswalk"))],
    ),
    case(
        "addition.erroneous.walker_cross_west",
        "Add a pedestrain who walk across the street on the west crosswalk",
        [
            delta("pedestrian", 1, 1),
            behaviour("cross_road", category="pedestrian", crosses_lane="main_eastbound"),
            near("west crosswalk", 8, category="pedestrian"),
            only("pedestrian"),
        ],
        [call("add_asset", category="pedestrian", location=at("west crosswalk"), behaviour={"kind": "cross_road"})],
    ),
    case(
        "addition.erroneous.cone_off_map",
        "put a cone at x 150 y 0 pls",
        REFUSED,
        [call("add_asset", category="traffic_cone", location=xy(150, 0))],
        tags=IMPOSSIBLE,
        notes="x = 150 is outside the world (x runs from -110 to 110).",
    ),
    case(
        "addition.erroneous.cones_then_more",
        "and 2 more of same next to them pls",
        [
            delta("traffic_cone", 2, 2),
            near_point(-35, -1.75, 8, category="traffic_cone", scope="added", require_all=True),
            only("traffic_cone"),
        ],
        [call("add_asset", category="traffic_cone", count=2, location=at("traffic_cone_1", "next_to"))],
        setup=(step(CONES_AHEAD["prompt"], *CONES_AHEAD["calls"], planned=True),),
    ),
    case(
        "addition.direct.bus_west_truck_jtekt",
        "Add a bus driving west on Main Street, and a truck parked at the JTEKT drop-off.",
        [
            delta("bus", 1, 1),
            delta("truck", 1, 1),
            behaviour("drive_lane", category="bus", lane="main_westbound"),
            near("JTEKT building entrance", 10, category="truck"),
            behaviour("parked", category="truck"),
            only("bus", "truck"),
        ],
        [
            call(
                "add_asset",
                category="bus",
                location=at("main_westbound"),
                behaviour={"kind": "drive_lane", "lane": "main_westbound"},
            ),
            call("add_asset", category="truck", location=at("JTEKT building entrance")),
        ],
        tags=COMPOUND,
    ),
    case(
        "addition.vague.lifeless_quad",
        "game designer here - the quad by the fountain feels lifeless, throw in a couple of places to sit and a few people hanging out",
        [
            delta("bench", 1, 4),
            delta("pedestrian", 2, 8),
            near("fountain", 12, category="bench", require_all=True),
            near("fountain", 12, category="pedestrian", require_all=True),
            only("bench", "pedestrian"),
        ],
        [
            call("add_asset", category="bench", count=2, location=at("fountain")),
            call("add_asset", category="pedestrian", count=3, location=at("fountain", "next_to", distance=3)),
        ],
        tags=COMPOUND,
    ),
]


BARRIER_AHEAD = step(
    "Put a road barrier in the eastbound lane 20 m ahead of the ego.",
    call("add_asset", category="road_barrier", location=at("ego", "in_front_of", distance=20)),
)
TRUCK_AT_UNION = step(
    "Park a delivery truck by the Student Union entrance.",
    call("add_asset", category="truck", location=at("Student Union entrance")),
)
FIVE_CONES = step(
    "Put five cones at the east gate.",
    call("add_asset", category="traffic_cone", count=5, location=at("east gate")),
)

REMOVAL = [
    # direct
    case(
        "removal.direct.tree_by_library",
        "Remove the tree next to the Library.",
        [gone("tree_1"), delta("tree", -1, -1), only("tree")],
        [call("remove_assets", assets=["tree_1"])],
    ),
    case(
        "removal.direct.all_street_lights",
        "Delete all the street lights.",
        [count("street_light", 0, 0), only("street_light")],
        [call("remove_assets", category="street_light")],
    ),
    case(
        "removal.direct.suv_lot_b",
        "Remove the SUV from parking lot B.",
        [gone("suv_1"), delta(CARS, -1, -1), only("suv")],
        [call("remove_assets", assets=["suv_1"])],
    ),
    case(
        "removal.direct.bench_bus_stop",
        "Remove the bench at the bus stop.",
        [gone("bench_1"), only("bench")],
        [call("remove_assets", assets=["bench_1"])],
    ),
    case(
        "removal.direct.street_light_12",
        "Remove street_light_12.",
        [gone("street_light_12"), delta("street_light", -1, -1), only("street_light")],
        [call("remove_assets", assets=["street_light_12"])],
    ),
    case(
        "removal.direct.two_of_my_cones",
        "Remove two of the cones I just placed.",
        [delta("traffic_cone", -2, -2), only("traffic_cone")],
        [call("remove_assets", category="traffic_cone", count=2)],
        setup=(step(FIVE_CONES["prompt"], *FIVE_CONES["calls"], planned=True),),
    ),
    case(
        "removal.direct.hydrant_and_stop_sign",
        "Remove the fire hydrant, and then remove the stop sign as well.",
        [gone("fire_hydrant_1", "stop_sign_1"), only("fire_hydrant", "stop_sign")],
        [call("remove_assets", assets=["fire_hydrant_1"]), call("remove_assets", assets=["stop_sign_1"])],
        tags=COMPOUND,
    ),
    case(
        "removal.direct.bus_in_lot_a",
        "Remove the parked bus from parking lot A.",
        REFUSED,
        [call("remove_assets", category="bus", near="parking lot A", count=1)],
        tags=IMPOSSIBLE,
        notes="There is no bus anywhere in the scene.",
    ),
    # indirect
    case(
        "removal.indirect.confusing_stop_sign",
        "The stop sign on the west side of the crossroads keeps confusing our planner, so I'd rather not have it at all.",
        [gone("stop_sign_1"), only("stop_sign")],
        [call("remove_assets", assets=["stop_sign_1"])],
    ),
    case(
        "removal.indirect.empty_student_lot",
        "For the parking test we need the student car park completely empty of vehicles.",
        [gone(*LOT_B), only(*CARS)],
        [call("remove_assets", assets=LOT_B)],
    ),
    case(
        "removal.indirect.trees_block_drone",
        "The two trees closest to the fountain block the drone's view of the quad; take them away.",
        [gone("tree_2", "tree_3"), kept("tree_1", "tree_4"), only("tree")],
        [call("remove_assets", category="tree", near="fountain", count=2)],
    ),
    case(
        "removal.indirect.lamps_near_main_gate",
        "The lamp posts at the western end of Main Street are being replaced: clear the three nearest the main gate.",
        [
            gone("street_light_1", "street_light_2", "street_light_3"),
            delta("street_light", -3, -3),
            only("street_light"),
        ],
        [call("remove_assets", category="street_light", near="main gate", count=3)],
    ),
    case(
        "removal.indirect.unused_bin",
        "Nobody uses the rubbish bin by the bus stop any more, it's just clutter in the camera image.",
        [gone("trash_bin_1"), only("trash_bin")],
        [call("remove_assets", assets=["trash_bin_1"])],
    ),
    case(
        "removal.indirect.barrier_mistake",
        "Actually that barrier was a mistake; the lane should be open again.",
        [count("road_barrier", 0, 0), only("road_barrier")],
        [call("remove_assets", assets=["road_barrier_1"])],
        setup=(step(BARRIER_AHEAD["prompt"], *BARRIER_AHEAD["calls"], planned=True),),
    ),
    case(
        "removal.indirect.signal_south_west",
        "Our car keeps stopping at the signal on the south-west corner of the junction; for this run I want that signal gone.",
        [gone("traffic_light_1"), kept("traffic_light_2"), only("traffic_light")],
        [call("remove_assets", assets=["traffic_light_1"])],
    ),
    # vague
    case(
        "removal.vague.some_lamps",
        "get rid of some of the lamps",
        [delta("street_light", -11, -1), only("street_light")],
        [call("remove_assets", category="street_light", count=3)],
    ),
    case(
        "removal.vague.clean_up_cones",
        "ok clean up the cones",
        [count("traffic_cone", 0, 0), only("traffic_cone")],
        [call("remove_assets", category="traffic_cone")],
        setup=(FIVE_CONES,),
    ),
    case(
        "removal.vague.thin_trees",
        "too many trees, thin them out a bit",
        [delta("tree", -3, -1), only("tree")],
        [call("remove_assets", category="tree", count=2)],
    ),
    case(
        "removal.vague.junk_off_road",
        "clear the junk off the road",
        [count(["cement_rubble", "traffic_cone"], 0, 0), only("cement_rubble", "traffic_cone")],
        [call("remove_assets", category="cement_rubble"), call("remove_assets", category="traffic_cone")],
        setup=(JUNK_ON_ROAD,),
        tags=COMPOUND,
    ),
    case(
        "removal.vague.cars_can_go",
        "the cars in the lot can go i guess",
        [gone("passenger_car_1", "passenger_car_2"), only(*CARS)],
        [call("remove_assets", assets=LOT_B)],
    ),
    case(
        "removal.vague.thing_by_union",
        "that thing I parked by the union, lose it",
        [count("truck", 0, 0), only("truck")],
        [call("remove_assets", category="truck")],
        setup=(TRUCK_AT_UNION,),
    ),
    case(
        "removal.vague.fewer_lights_east",
        "fewer lights on the east side of campus",
        [delta("street_light", -6, -1), kept(*WEST_LIGHTS), only("street_light")],
        [call("remove_assets", assets=["street_light_9", "street_light_11"])],
    ),
    # erroneous
    case(
        "removal.erroneous.remvoe_hydrant",
        "remvoe the firehydrant pls",
        [gone("fire_hydrant_1"), only("fire_hydrant")],
        [call("remove_assets", assets=["fire_hydrant_1"])],
    ),
    case(
        "removal.erroneous.delet_all_tree",
        "delet all tree",
        [count("tree", 0, 0), only("tree")],
        [call("remove_assets", category="tree")],
    ),
    case(
        "removal.erroneous.bench_what_is_near",
        "Please to remove the bench what is near bus stop",
        [gone("bench_1"), only("bench")],
        [call("remove_assets", assets=["bench_1"])],
    ),
    case(
        "removal.erroneous.stop_sing",
        "take away teh stop sing",
        [gone("stop_sign_1"), only("stop_sign")],
        [call("remove_assets", assets=["stop_sign_1"])],
    ),
    case(
        "removal.erroneous.lightpole_east_gate",
        "remove 2 lightpole closest to the east gate",
        [gone("street_light_11", "street_light_12"), delta("street_light", -2, -2), only("street_light")],
        [call("remove_assets", category="street_light", near="east gate", count=2)],
    ),
    case(
        "removal.erroneous.suv_thx",
        "remove the suv in lot b thx",
        [gone("suv_1"), kept("passenger_car_1", "passenger_car_2"), only("suv")],
        [call("remove_assets", assets=["suv_1"])],
    ),
    case(
        "removal.erroneous.ego_not_needed",
        "remove the ego car please, we dont need it for this one",
        REFUSED,
        [call("remove_assets", assets=["ego"])],
        tags=IMPOSSIBLE,
        notes="The ego vehicle cannot be removed.",
    ),
    case(
        "removal.indirect.declutter_bus_stop",
        "Speaking as the city planner: the pavement at the bus stop is cluttered, so the seat and the rubbish bin there should both go.",
        [gone("bench_1", "trash_bin_1"), only("bench", "trash_bin")],
        [call("remove_assets", assets=["bench_1"]), call("remove_assets", assets=["trash_bin_1"])],
        tags=COMPOUND,
    ),
]


BENCH_TO_FOUNTAIN = step(
    "Move the bus-stop bench over to the fountain.",
    call("place_asset", asset="bench_1", location=at("fountain")),
)
ROVER_IN_LOT_A = step(
    "Add an ackermann robot in parking lot A.",
    call("add_asset", category="ackermann_robot", location=at("parking lot A")),
)

POSITIONING = [
    # direct
    case(
        "positioning.direct.bench_at_fountain",
        "Place the bench at the fountain.",
        [near("fountain", 6, asset="bench_1"), delta("bench", 0, 0), only("bench")],
        [call("place_asset", asset="bench_1", location=at("fountain"))],
    ),
    case(
        "positioning.direct.hydrant_bus_stop",
        "Put fire_hydrant_1 next to the bus stop.",
        [near("bus stop", 5, asset="fire_hydrant_1"), moved("fire_hydrant_1", 10), only("fire_hydrant")],
        [call("place_asset", asset="fire_hydrant_1", location=at("bus stop"))],
    ),
    case(
        "positioning.direct.suv_lot_a",
        "Put the SUV in parking lot A.",
        [near("parking lot A", 1, asset="suv_1"), only("suv")],
        [call("place_asset", asset="suv_1", location=at("parking lot A"))],
    ),
    case(
        "positioning.direct.car2_westbound_east_gate",
        "Put passenger_car_2 in the westbound lane of Main Street near the east gate.",
        [
            lane("main_westbound", asset="passenger_car_2"),
            near("east gate", 15, asset="passenger_car_2"),
            only("passenger_car"),
        ],
        [call("place_asset", asset="passenger_car_2", location=at("east gate", "in_lane", lane="main_westbound"))],
    ),
    case(
        "positioning.direct.bin_exact_xy",
        "Position the trash bin at x=-20, y=-8.",
        [near_point(-20, -8, 0.5, asset="trash_bin_1"), only("trash_bin")],
        [call("place_asset", asset="trash_bin_1", location=xy(-20, -8))],
    ),
    case(
        "positioning.direct.stop_sign_north_crosswalk",
        "Put the stop sign at the north crosswalk.",
        [
            near("north crosswalk", 6, asset="stop_sign_1"),
            surface("sidewalk", "ground", asset="stop_sign_1"),
            only("stop_sign"),
        ],
        [call("place_asset", asset="stop_sign_1", location=at("north crosswalk"))],
    ),
    case(
        "positioning.direct.ego_northbound",
        "Put the ego vehicle in lane campus_northbound, a little north of the north crosswalk.",
        [lane("campus_northbound", asset="ego"), near("north crosswalk", 12, asset="ego"), only("ego_vehicle")],
        [
            call(
                "place_asset",
                asset="ego",
                location=at("north crosswalk", "in_lane", lane="campus_northbound", distance=8),
            )
        ],
    ),
    case(
        "positioning.direct.tree_inside_engineering",
        "Place tree_4 at x=-40, y=28.",
        REFUSED,
        [call("place_asset", asset="tree_4", location=xy(-40, 28))],
        tags=IMPOSSIBLE,
        notes="(-40, 28) is inside Engineering Hall.",
    ),
    case(
        "positioning.direct.suv_off_map",
        "Move the SUV to x = 300, y = 0.",
        REFUSED,
        [call("place_asset", asset="suv_1", location=xy(300, 0))],
        tags=IMPOSSIBLE,
        notes="The world ends at x = 110.",
    ),
    case(
        "positioning.direct.car1_behind_ego",
        "Place passenger_car_1 in the eastbound lane 15 m behind the ego vehicle.",
        [
            lane("main_eastbound", asset="passenger_car_1"),
            near_point(-75, -1.75, 5, asset="passenger_car_1"),
            only("passenger_car"),
        ],
        [call("place_asset", asset="passenger_car_1", location=at("ego", "behind", along_m=-15))],
    ),
    # indirect
    case(
        "positioning.indirect.seat_at_quad",
        "The fountain area needs somewhere to sit, and the one seat we have is wasted at the bus stop.",
        [near("fountain", 8, asset="bench_1"), delta("bench", 0, 0), only("bench")],
        [call("place_asset", asset="bench_1", location=at("fountain"))],
    ),
    case(
        "positioning.indirect.ego_from_east_gate",
        "From now on our test runs should begin at the east gate, heading into campus.",
        [near("east gate", 15, asset="ego"), lane("main_westbound", asset="ego", aligned=True), only("ego_vehicle")],
        [call("place_asset", asset="ego", location=at("east gate", "in_lane", lane="main_westbound"))],
    ),
    case(
        "positioning.indirect.hydrant_for_library",
        "If the library caught fire the brigade would have to run a hose a long way; the hydrant should be right by its doors.",
        [near("Library entrance", 8, asset="fire_hydrant_1"), delta("fire_hydrant", 0, 0), only("fire_hydrant")],
        [call("place_asset", asset="fire_hydrant_1", location=at("Library entrance"))],
    ),
    case(
        "positioning.indirect.suv_wrong_car_park",
        "The SUV is sitting in the wrong car park; it belongs in the western one.",
        [near("parking lot A", 1, asset="suv_1"), only("suv")],
        [call("place_asset", asset="suv_1", location=at("parking lot A"))],
    ),
    case(
        "positioning.indirect.block_jtekt_dropoff",
        "The scenario needs one of the parked sedans blocking the JTEKT drop-off.",
        [
            near("JTEKT building entrance", 10, category="passenger_car"),
            count("passenger_car", 2, 2),
            only("passenger_car"),
        ],
        [call("place_asset", asset="passenger_car_1", location=at("JTEKT building entrance"))],
    ),
    case(
        "positioning.indirect.stop_sign_east_side",
        "A stop sign only on the west approach is odd; the one we have should guard the east approach of the junction instead.",
        [
            near_point(12, 0, 9, asset="stop_sign_1"),
            surface("sidewalk", "ground", asset="stop_sign_1"),
            only("stop_sign"),
        ],
        [call("place_asset", asset="stop_sign_1", location=xy(13.5, 5.5))],
    ),
    case(
        "positioning.indirect.car_to_meet_ego",
        "I want the ego to come up behind a stopped car: take one of the lot B sedans and leave it in our lane forty metres ahead.",
        [
            lane("main_eastbound", category="passenger_car"),
            near_point(-20, -1.75, 6, category="passenger_car"),
            relative("in_front_of", "ego", 50, category="passenger_car", tolerance_deg=15),
            only("passenger_car"),
        ],
        [call("place_asset", asset="passenger_car_2", location=at("ego", along_m=40))],
    ),
    case(
        "positioning.indirect.bin_beside_moved_bench",
        "People will eat lunch on that bench now; the rubbish bin should stand beside it.",
        [near("bench_1", 3, asset="trash_bin_1"), only("trash_bin")],
        [call("place_asset", asset="trash_bin_1", location=at("bench_1", "next_to"))],
        setup=(BENCH_TO_FOUNTAIN,),
    ),
    case(
        "positioning.indirect.rover_to_jtekt",
        "On second thought the demo happens at the JTEKT Building, so the robot should wait at its entrance rather than in the car park.",
        [
            near("JTEKT building entrance", 8, category="ackermann_robot"),
            delta("ackermann_robot", 0, 0),
            only("ackermann_robot"),
        ],
        [call("place_asset", asset="ackermann_robot_1", location=at("JTEKT building entrance"))],
        setup=(step(ROVER_IN_LOT_A["prompt"], *ROVER_IN_LOT_A["calls"], planned=True),),
    ),
    # vague
    case(
        "positioning.vague.bench_somewhere_nicer",
        "put the bench somewhere nicer, like by the fountain",
        [near("fountain", 10, asset="bench_1"), only("bench")],
        [call("place_asset", asset="bench_1", location=at("fountain"))],
    ),
    case(
        "positioning.vague.suv_near_front_gate",
        "can the suv go somewhere near the front gate",
        [near("main gate", 20, asset="suv_1"), only("suv")],
        [call("place_asset", asset="suv_1", location=at("main gate", "in_lane", lane="main_eastbound", distance=10))],
    ),
    case(
        "positioning.vague.bin_closer_library",
        "stick the bin closer to the library",
        [near("Library entrance", 8, asset="trash_bin_1"), only("trash_bin")],
        [call("place_asset", asset="trash_bin_1", location=at("Library entrance"))],
    ),
    case(
        "positioning.vague.car_other_lot",
        "park one of those cars in the other lot",
        [near("parking lot A", 1, category=CARS), delta(CARS, 0, 0), only(*CARS)],
        [call("place_asset", asset="passenger_car_2", location=at("parking lot A"))],
    ),
    case(
        "positioning.vague.ego_campus_drive",
        "get our car over onto campus drive somewhere",
        [only("ego_vehicle")],
        [call("place_asset", asset="ego", location=at("campus_northbound", "in_lane", distance=30))],
        alternatives=([lane("campus_northbound", asset="ego")], [lane("campus_southbound", asset="ego")]),
    ),
    case(
        "positioning.vague.hydrant_by_crosswalk",
        "the hydrant is kind of in a weird spot, put it near the crosswalk",
        [only("fire_hydrant")],
        [call("place_asset", asset="fire_hydrant_1", location=at("west crosswalk", "on_sidewalk"))],
        alternatives=(
            [near("west crosswalk", 8, asset="fire_hydrant_1")],
            [near("north crosswalk", 8, asset="fire_hydrant_1")],
        ),
    ),
    case(
        "positioning.vague.gate_lamp_central",
        "the lamp by the main gate, could it be more central",
        [near_point(0, 0, 40, asset="street_light_1"), only("street_light")],
        [call("place_asset", asset="street_light_1", location=at("main intersection", "on_sidewalk"))],
    ),
    case(
        "positioning.vague.stop_sign_union",
        "that stop sign would be better somewhere by the union",
        [near("Student Union entrance", 12, asset="stop_sign_1"), only("stop_sign")],
        [call("place_asset", asset="stop_sign_1", location=at("Student Union entrance"))],
    ),
    case(
        "positioning.vague.tree_out_of_view",
        "the tree in front of the library spoils the view, put it somewhere else",
        [moved("tree_1", 3), delta("tree", 0, 0), only("tree")],
        [call("place_asset", asset="tree_1", location=xy(-15, -20))],
    ),
    # erroneous
    case(
        "positioning.erroneous.benhc_fountian",
        "pls put the benhc at teh fountian",
        [near("fountain", 8, asset="bench_1"), only("bench")],
        [call("place_asset", asset="bench_1", location=at("fountain"))],
    ),
    case(
        "positioning.erroneous.suv_more_better",
        "Place the SUV into the parking A, it is more better there",
        [near("parking lot A", 1, asset="suv_1"), only("suv")],
        [call("place_asset", asset="suv_1", location=at("parking lot A"))],
    ),
    case(
        "positioning.erroneous.hydrant_near_of",
        "put hydrant near of bus stop",
        [near("bus stop", 6, asset="fire_hydrant_1"), only("fire_hydrant")],
        [call("place_asset", asset="fire_hydrant_1", location=at("bus stop"))],
    ),
    case(
        "positioning.erroneous.positon_trash_can",
        "positon the trash can at x -20 y -8",
        [near_point(-20, -8, 0.5, asset="trash_bin_1"), only("trash_bin")],
        [call("place_asset", asset="trash_bin_1", location=xy(-20, -8))],
    ),
    case(
        "positioning.erroneous.ego_northbond",
        "put ego car on the campus drive northbond lane",
        [lane("campus_northbound", asset="ego"), only("ego_vehicle")],
        [call("place_asset", asset="ego", location=at("campus_northbound", "in_lane", distance=30))],
    ),
    case(
        "positioning.erroneous.stop_sigh_north",
        "stop sigh move to the north crossing plz",
        [near("north crosswalk", 6, asset="stop_sign_1"), only("stop_sign")],
        [call("place_asset", asset="stop_sign_1", location=at("north crosswalk"))],
    ),
    case(
        "positioning.erroneous.car_number_2_library",
        "Place the car number 2 in front the Library",
        [near("Library entrance", 10, asset="passenger_car_2"), only("passenger_car")],
        [call("place_asset", asset="passenger_car_2", location=at("Library entrance", "in_front_of"))],
    ),
    case(
        "positioning.erroneous.bench_inside_library",
        "put the bench inside the library building pls, at x -41 y -30",
        REFUSED,
        [call("place_asset", asset="bench_1", location=xy(-41, -30))],
        tags=IMPOSSIBLE,
        notes="Nothing may stand inside a building's footprint.",
    ),
    case(
        "positioning.erroneous.tree4_next_fountain",
        "tree 4 go next the fountain",
        [near("fountain", 8, asset="tree_4"), only("tree")],
        [call("place_asset", asset="tree_4", location=at("fountain", "next_to"))],
    ),
    case(
        "positioning.erroneous.bench_then_paint",
        "bring the bench to fountain and make it green colour, thank",
        [near("fountain", 8, asset="bench_1"), looks(asset="bench_1", colour="green"), only("bench")],
        [
            call("place_asset", asset="bench_1", location=at("fountain")),
            call("set_asset_appearance", assets=["bench_1"], colour="green"),
        ],
        tags=COMPOUND,
    ),
    case(
        "positioning.indirect.pole_and_red_outlet",
        "The tall metal pole with a lamp on top that stands nearest the east gate should be moved to the fountain, and the short red water outlet by the crossroads belongs next to the bus stop.",
        [
            near("fountain", 8, asset="street_light_12"),
            near("bus stop", 6, asset="fire_hydrant_1"),
            only(assets=("street_light_12", "fire_hydrant_1")),
        ],
        [
            call("place_asset", asset="street_light_12", location=at("fountain")),
            call("place_asset", asset="fire_hydrant_1", location=at("bus stop")),
        ],
        tags=COMPOUND,
    ),
]


PARKED_BUS = step(
    "Park a bus in the eastbound lane about 40 m ahead of our car.",
    call("add_asset", category="bus", location=at("ego", "in_front_of", distance=40)),
)

MOVING = [
    # direct
    case(
        "moving.direct.ego_forward_10",
        "Move the ego vehicle 10 metres forward.",
        [moved("ego", 9, 11, direction="forward"), only("ego_vehicle")],
        [call("move_asset", asset="ego", forward=10)],
    ),
    case(
        "moving.direct.bench_turn_90",
        "Turn the bench 90 degrees.",
        [moved("bench_1", 0, 0.5, turn_min_deg=80, turn_max_deg=100), only("bench")],
        [call("move_asset", asset="bench_1", turn_deg=90)],
    ),
    case(
        "moving.direct.car1_left_2m",
        "Shift passenger_car_1 two metres to its left.",
        [moved("passenger_car_1", 1.5, 2.5, direction="left"), only("passenger_car")],
        [call("move_asset", asset="passenger_car_1", left=2)],
    ),
    case(
        "moving.direct.car2_drive_east_7",
        "Make passenger_car_2 drive in lane main_eastbound at 7 m/s.",
        [
            behaviour("drive_lane", asset="passenger_car_2", lane="main_eastbound", speed_min=6.5, speed_max=7.5),
            only("passenger_car"),
        ],
        [
            call(
                "set_behaviour",
                asset="passenger_car_2",
                behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 7},
            )
        ],
    ),
    case(
        "moving.direct.hydrant_3m_east",
        "Move the fire hydrant 3 metres east.",
        [moved("fire_hydrant_1", 2.5, 3.5), near_point(19, 5.5, 0.6, asset="fire_hydrant_1"), only("fire_hydrant")],
        [call("move_asset", asset="fire_hydrant_1", east=3)],
    ),
    case(
        "moving.direct.suv_circles_6m",
        "Make the SUV drive in circles in parking lot B with a 6 m radius.",
        [behaviour("circle", asset="suv_1", radius_min=5.5, radius_max=6.5, centre_near="parking lot B"), only("suv")],
        [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "radius": 6, "centre": "parking lot B"})],
    ),
    case(
        "moving.direct.ego_speed_8",
        "Set the ego vehicle to drive its lane at 8 m/s.",
        [
            behaviour("drive_lane", asset="ego", lane="main_eastbound", speed_min=7.5, speed_max=8.5),
            only("ego_vehicle"),
        ],
        [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 8})],
    ),
    case(
        "moving.direct.ego_500m",
        "Move the ego vehicle 500 metres forward.",
        REFUSED,
        [call("move_asset", asset="ego", forward=500)],
        tags=IMPOSSIBLE,
        notes="500 m east of the ego is far outside the world (x ends at 110).",
    ),
    # indirect
    case(
        "moving.indirect.ego_back_up_five",
        "The test car starts a bit too close to the junction for my liking; back it up by five metres.",
        [moved("ego", 4, 6, direction="backward"), only("ego_vehicle")],
        [call("move_asset", asset="ego", forward=-5)],
    ),
    case(
        "moving.indirect.suv_joins_traffic",
        "We'd like the parked SUV to pull out and join the traffic heading west on Main Street.",
        [behaviour("drive_lane", asset="suv_1", lane="main_westbound"), only("suv")],
        [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_westbound"})],
    ),
    case(
        "moving.indirect.bench_face_other_way",
        "Whoever sits on the bench stares at the traffic; swing it round so it faces the other way.",
        [moved("bench_1", 0, 1, turn_min_deg=150), only("bench")],
        [call("move_asset", asset="bench_1", turn_deg=180)],
    ),
    case(
        "moving.indirect.west_car_skidpad",
        "The car at the west end of the lot B row should be doing skidpad laps right there in the lot.",
        [behaviour("circle", asset="passenger_car_1", centre_near="parking lot B"), only("passenger_car")],
        [call("set_behaviour", asset="passenger_car_1", behaviour={"kind": "circle", "centre": "parking lot B"})],
        notes="Without a centre the circle Worker picks the first free lot, lot A, and moves the car there.",
    ),
    case(
        "moving.indirect.walker_crosses_west",
        "That person shouldn't just stand there: have them walk over the road at the west crosswalk.",
        [
            behaviour("cross_road", category="pedestrian", crosses_lane="main_eastbound"),
            near("west crosswalk", 8, category="pedestrian"),
            delta("pedestrian", 0, 0),
            only("pedestrian"),
        ],
        [call("set_behaviour", asset="pedestrian_1", behaviour={"kind": "cross_road"})],
        setup=(step(WALKER_AT_STOP["prompt"], *WALKER_AT_STOP["calls"], planned=True),),
    ),
    case(
        "moving.indirect.bin_off_kerb",
        "The bin at the bus stop sits on the kerb line; nudge it one metre north, away from the road.",
        [moved("trash_bin_1", 0.5, 1.5), near_point(-33.5, -4.5, 0.6, asset="trash_bin_1"), only("trash_bin")],
        [call("move_asset", asset="trash_bin_1", north=1)],
    ),
    case(
        "moving.indirect.ego_hold_still",
        "For the first take the test car should just sit where it is, engine off.",
        [behaviour("parked", asset="ego"), moved("ego", 0, 0.5), only("ego_vehicle")],
        [call("set_behaviour", asset="ego", behaviour={"kind": "parked"})],
    ),
    # vague
    case(
        "moving.vague.ego_up_a_bit",
        "move our car up a bit",
        [moved("ego", 1, 20, direction="forward"), only("ego_vehicle")],
        [call("move_asset", asset="ego", forward=5)],
    ),
    case(
        "moving.vague.turn_suv_around",
        "turn the suv around",
        [moved("suv_1", 0, 3, turn_min_deg=150), only("suv")],
        [call("move_asset", asset="suv_1", turn_deg=180)],
    ),
    case(
        "moving.vague.get_bus_moving",
        "ok now get the bus moving",
        [behaviour("drive_lane", category="bus", lane="main_eastbound"), only("bus")],
        [call("set_behaviour", asset="bus_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
        setup=(PARKED_BUS,),
    ),
    case(
        "moving.vague.shuffle_hydrant",
        "shuffle the hydrant over a few metres",
        [moved("fire_hydrant_1", 1, 10), only("fire_hydrant")],
        [call("move_asset", asset="fire_hydrant_1", east=3)],
    ),
    case(
        "moving.vague.lot_b_cars_do_something",
        "can the cars in lot B do something, like drive around",
        [behaviour(["drive_lane", "circle", "follow_path"], category=CARS), only(*CARS)],
        [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "centre": "parking lot B"})],
    ),
    case(
        "moving.vague.slow_ego_little",
        "slow our car down a little",
        [behaviour("drive_lane", asset="ego", speed_min=1.5, speed_max=4.9), only("ego_vehicle")],
        [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 3.5})],
    ),
    case(
        "moving.vague.bench_back_touch",
        "push the bench back a touch",
        [moved("bench_1", 0.2, 2.5), only("bench")],
        [call("move_asset", asset="bench_1", forward=-1)],
    ),
    case(
        "moving.vague.ego_forward_then_slower",
        "roll our car forward a bit and then have it take it easy, maybe 3 m/s",
        [
            moved("ego", 1, 20, direction="forward"),
            behaviour("drive_lane", asset="ego", speed_min=2.5, speed_max=3.5),
            only("ego_vehicle"),
        ],
        [
            call("move_asset", asset="ego", forward=5),
            call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 3}),
        ],
        tags=COMPOUND,
    ),
    # erroneous
    case(
        "moving.erroneous.mvoe_ego_15",
        "mvoe ego forwrd 15m",
        [moved("ego", 14, 16, direction="forward"), only("ego_vehicle")],
        [call("move_asset", asset="ego", forward=15)],
    ),
    case(
        "moving.erroneous.turn_bench_45",
        "turn teh bench 45 degre",
        [moved("bench_1", 0, 0.5, turn_min_deg=40, turn_max_deg=50), only("bench")],
        [call("move_asset", asset="bench_1", turn_deg=45)],
    ),
    case(
        "moving.erroneous.suv_west_bound",
        "make suv drive on main street west bound",
        [behaviour("drive_lane", asset="suv_1", lane="main_westbound"), only("suv")],
        [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_westbound"})],
    ),
    case(
        "moving.erroneous.hydrant_2_meter_north",
        "Please moving the hydrant 2 meter to north",
        [moved("fire_hydrant_1", 1.5, 2.5), near_point(16, 7.5, 0.6, asset="fire_hydrant_1"), only("fire_hydrant")],
        [call("move_asset", asset="fire_hydrant_1", north=2)],
    ),
    case(
        "moving.erroneous.car1_circle",
        "the car 1 in lot b, make it go in circle",
        [behaviour("circle", asset="passenger_car_1"), only("passenger_car")],
        [call("set_behaviour", asset="passenger_car_1", behaviour={"kind": "circle", "centre": "parking lot B"})],
    ),
    case(
        "moving.erroneous.ego_more_fast",
        "ego go more fast, 10 m/s",
        [behaviour("drive_lane", asset="ego", speed_min=9.5, speed_max=10.5), only("ego_vehicle")],
        [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 10})],
    ),
    case(
        "moving.erroneous.hydrant_drive",
        "make the fire hydrant drive down main street lol",
        REFUSED,
        [call("set_behaviour", asset="fire_hydrant_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
        tags=IMPOSSIBLE,
        notes="A hydrant cannot drive.",
    ),
    case(
        "moving.direct.car2_forward_then_turn",
        "Move passenger_car_2 five metres forward, then turn it 90 degrees to the left.",
        [
            moved("passenger_car_2", 4, 6, turn_min_deg=80, turn_max_deg=100),
            near_point(27, -37, 1, asset="passenger_car_2"),
            only("passenger_car"),
        ],
        [
            call("move_asset", asset="passenger_car_2", forward=5),
            call("move_asset", asset="passenger_car_2", turn_deg=90),
        ],
        tags=COMPOUND,
    ),
    case(
        "moving.direct.ego_30_feet",
        "Move the ego vehicle 30 feet forward.",
        [moved("ego", 8, 10.5, direction="forward"), only("ego_vehicle")],
        [call("move_asset", asset="ego", forward=9.1)],
    ),
]


ARRANGEMENT = [
    # direct
    case(
        "arrangement.direct.cones_across_road",
        "Arrange 6 traffic cones in a line across Main Street, 20 m ahead of the ego.",
        [
            delta("traffic_cone", 6, 6),
            layout("line", category="traffic_cone", tolerance=1.0),
            near_point(-40, 0, 6, category="traffic_cone", require_all=True),
            only("traffic_cone"),
        ],
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="line",
                count=6,
                spacing=1.2,
                heading_deg=90,
                location=xy(-40, 0),
            )
        ],
    ),
    case(
        "arrangement.direct.bollard_ring_fountain",
        "Put a ring of 8 bollards around the fountain.",
        [delta("bollard", 8, 8), layout("ring", category="bollard", around="fountain"), only("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="ring", count=8, location=at("fountain"))],
    ),
    case(
        "arrangement.direct.lane_edge_bus_stop",
        "Line the edge of the eastbound lane with 10 cones, starting at the bus stop.",
        [
            delta("traffic_cone", 10, 10),
            layout("line", category="traffic_cone"),
            lane("main_eastbound", category="traffic_cone", scope="added"),
            near("bus stop", 35, category="traffic_cone", require_all=True),
            only("traffic_cone"),
        ],
        [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=10, location=at("bus stop"))],
    ),
    case(
        "arrangement.direct.row_cars_lot_a",
        "Park a row of 4 passenger cars in parking lot A.",
        [
            delta("passenger_car", 4, 4),
            layout("line", category="passenger_car", min_count=4),
            near("parking lot A", 1, category="passenger_car", scope="added", require_all=True),
            only("passenger_car"),
        ],
        [
            call(
                "arrange_assets",
                categories=["passenger_car"],
                shape="parking_row",
                count=4,
                location=at("parking lot A"),
            )
        ],
    ),
    case(
        "arrangement.direct.bollard_grid_centre",
        "Make a 3 by 3 grid of bollards in the middle of the crossroads.",
        [
            delta("bollard", 9, 9),
            layout("cluster", category="bollard", tolerance=4.5, min_count=9),
            near("main intersection", 1, category="bollard", scope="added", require_all=True),
            only("bollard"),
        ],
        [
            call(
                "arrange_assets",
                categories=["bollard"],
                shape="grid",
                count=9,
                columns=3,
                location=at("main intersection"),
            )
        ],
    ),
    case(
        "arrangement.direct.barriers_jtekt",
        "Place five road barriers in a line in front of the JTEKT building entrance.",
        [
            delta("road_barrier", 5, 5),
            layout("line", category="road_barrier"),
            near("JTEKT building entrance", 10, category="road_barrier", require_all=True),
            only("road_barrier"),
        ],
        [
            call(
                "arrange_assets",
                categories=["road_barrier"],
                shape="line",
                count=5,
                location=at("JTEKT building entrance", "in_front_of"),
            )
        ],
    ),
    case(
        "arrangement.direct.bollards_round_hydrant",
        "Put 6 bollards in a ring around the fire hydrant.",
        [delta("bollard", 6, 6), layout("ring", category="bollard", around="fire_hydrant_1"), only("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="ring", count=6, location=at("fire_hydrant_1"))],
    ),
    case(
        "arrangement.direct.trees_y9",
        "Plant a line of 5 trees, 8 m apart, along y = 9, centred on x = 40.",
        [
            delta("tree", 5, 5),
            layout("line", category="tree", spacing_min=7.5, spacing_max=8.5),
            near_point(40, 9, 17, category="tree", scope="added", require_all=True),
            only("tree"),
        ],
        [
            call(
                "arrange_assets",
                categories=["tree"],
                shape="line",
                count=5,
                spacing=8,
                heading_deg=0,
                location=xy(40, 9),
            )
        ],
    ),
    case(
        "arrangement.direct.suv_row_lot_b",
        "Make a row of three SUVs parked side by side in the student car park.",
        [
            delta("suv", 3, 3),
            layout("line", category="suv", scope="added"),
            near("parking lot B", 1, category="suv", scope="added", require_all=True),
            only("suv"),
        ],
        [call("arrange_assets", categories=["suv"], shape="parking_row", count=3, location=at("parking lot B"))],
    ),
    case(
        "arrangement.direct.ring_100m",
        "Put a ring of traffic cones with a 100 m radius around the crossroads.",
        REFUSED,
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="ring",
                radius=100,
                location=at("main intersection"),
            )
        ],
        tags=IMPOSSIBLE,
        notes="A 100 m ring around the crossroads leaves the world (y ends at 90) and runs through buildings.",
    ),
    # indirect
    case(
        "arrangement.indirect.westbound_closure",
        "We're simulating a lane closure on westbound Main Street by the JTEKT drop-off: eight cones along the lane edge.",
        [
            delta("traffic_cone", 8, 8),
            layout("line", category="traffic_cone"),
            lane("main_westbound", category="traffic_cone"),
            near("JTEKT building entrance", 30, category="traffic_cone", require_all=True),
            only("traffic_cone"),
        ],
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="lane_edge",
                count=8,
                location=at("JTEKT building entrance"),
            )
        ],
    ),
    case(
        "arrangement.indirect.slalom",
        "For a slalom test, put five cones in a straight line down the middle of the eastbound lane, 10 m apart, starting 20 m ahead of our car.",
        [
            delta("traffic_cone", 5, 5),
            layout("line", category="traffic_cone", spacing_min=9, spacing_max=11),
            lane("main_eastbound", category="traffic_cone"),
            relative("in_front_of", "ego", 70, category="traffic_cone", tolerance_deg=10, require_all=True),
            only("traffic_cone"),
        ],
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="line",
                count=5,
                spacing=10,
                heading_deg=0,
                location=xy(-20, -1.75),
            )
        ],
    ),
    case(
        "arrangement.indirect.crowd_round_stop",
        "Crowd-control test: surround the bus stop with people, a circle of eight of them.",
        [
            delta("pedestrian", 8, 8),
            layout("ring", category="pedestrian", around="bus stop", tolerance=1.5),
            only("pedestrian"),
        ],
        [call("arrange_assets", categories=["pedestrian"], shape="ring", count=8, location=at("bus stop"))],
    ),
    case(
        "arrangement.indirect.full_student_lot",
        "The student car park should look busy for the parking-search test: a row of six cars next to each other.",
        [
            delta(CARS, 6, 6),
            layout("line", category=CARS, scope="added"),
            near("parking lot B", 1, category=CARS, scope="added", require_all=True),
            only(*CARS),
        ],
        [
            call(
                "arrange_assets",
                categories=["passenger_car"],
                shape="parking_row",
                count=6,
                location=at("parking lot B"),
            )
        ],
    ),
    case(
        "arrangement.indirect.lidar_grid",
        "To calibrate the lidar we need a four-by-four grid of cones on the open paving of the west car park.",
        [
            delta("traffic_cone", 16, 16),
            layout("cluster", category="traffic_cone", tolerance=6),
            near("parking lot A", 1, category="traffic_cone", require_all=True),
            only("traffic_cone"),
        ],
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="grid",
                count=16,
                columns=4,
                location=at("parking lot A"),
            )
        ],
    ),
    case(
        "arrangement.indirect.block_campus_north",
        "Close Campus Drive just north of the junction: a line of road barriers straight across both lanes.",
        [
            delta("road_barrier", 2, 6),
            layout("line", category="road_barrier", tolerance=1.0),
            near_point(0, 16, 8, category="road_barrier", require_all=True),
            surface("drivable", category="road_barrier"),
            only("road_barrier"),
        ],
        [
            call(
                "arrange_assets",
                categories=["road_barrier"],
                shape="line",
                count=3,
                spacing=2.2,
                heading_deg=0,
                location=xy(0, 15),
            )
        ],
    ),
    case(
        "arrangement.indirect.fence_fountain",
        "The robot mustn't drive through the fountain, so fence it off with posts all the way round.",
        [delta("bollard", 4, 30), layout("ring", category="bollard", around="fountain"), only("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="ring", location=at("fountain"))],
    ),
    case(
        "arrangement.indirect.taxi_rank_library",
        "The library drop-off needs a taxi rank: three cars parked side by side there.",
        [
            delta(CARS, 3, 3),
            layout("line", category=CARS),
            near("Library entrance", 12, category=CARS, require_all=True),
            only(*CARS),
        ],
        [
            call(
                "arrange_assets",
                categories=["passenger_car"],
                shape="parking_row",
                count=3,
                location=at("Library entrance"),
            )
        ],
    ),
    case(
        "arrangement.indirect.queue_jtekt",
        "Our pedestrian-detection run needs a queue of five people lined up outside the JTEKT entrance.",
        [
            delta("pedestrian", 5, 5),
            layout("line", category="pedestrian"),
            near("JTEKT building entrance", 10, category="pedestrian", require_all=True),
            only("pedestrian"),
        ],
        [
            call(
                "arrange_assets",
                categories=["pedestrian"],
                shape="line",
                count=5,
                location=at("JTEKT building entrance"),
            )
        ],
    ),
    case(
        "arrangement.indirect.cones_in_union",
        "To mark the fire exits, put a row of five cones inside the Student Union at x 42, y -63.",
        REFUSED,
        [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5, location=xy(42, -63))],
        tags=IMPOSSIBLE,
        notes="(42, -63) is inside the Student Union.",
    ),
    case(
        "arrangement.indirect.ring_then_sign",
        "The hydrant is being serviced: ring it with bollards and stand a road-work sign beside it.",
        [
            layout("ring", category="bollard", around="fire_hydrant_1"),
            delta("bollard", 4, 16),
            delta("construction_sign", 1, 1),
            near("fire_hydrant_1", 6, category="construction_sign"),
            only("bollard", "construction_sign"),
        ],
        [
            call("arrange_assets", categories=["bollard"], shape="ring", count=6, location=at("fire_hydrant_1")),
            call("add_asset", category="construction_sign", location=at("fire_hydrant_1", "next_to", distance=4)),
        ],
        tags=COMPOUND,
    ),
    # vague
    case(
        "arrangement.vague.circle_round_hydrant",
        "some posts in a circle around the hydrant",
        [delta("bollard", 3, 16), layout("ring", category="bollard", around="fire_hydrant_1"), only("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="ring", location=at("fire_hydrant_1"))],
    ),
    case(
        "arrangement.vague.barriers_east_gate",
        "line a few barriers up near the east gate",
        [
            delta("road_barrier", 2, 8),
            layout("line", category="road_barrier"),
            near("east gate", 15, category="road_barrier", require_all=True),
            only("road_barrier"),
        ],
        [
            call(
                "arrange_assets",
                categories=["road_barrier"],
                shape="line",
                count=3,
                location=at("east gate", "in_lane", lane="main_westbound"),
            )
        ],
    ),
    case(
        "arrangement.vague.rows_lot_a",
        "put a bunch of cars in rows in lot A",
        [
            delta(CARS, 2, 40),
            layout("line", category=CARS, scope="added"),
            near("parking lot A", 1, category=CARS, scope="added", require_all=True),
            only(*CARS),
        ],
        [
            call(
                "arrange_assets",
                categories=["passenger_car"],
                shape="parking_row",
                count=5,
                location=at("parking lot A"),
            )
        ],
    ),
    case(
        "arrangement.vague.cones_down_our_lane",
        "cones in a row down our lane maybe",
        [
            delta("traffic_cone", 2, 12),
            layout("line", category="traffic_cone"),
            lane("main_eastbound", category="traffic_cone"),
            only("traffic_cone"),
        ],
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="line",
                count=5,
                heading_deg=0,
                spacing=4,
                location=at("ego", "in_front_of", distance=25),
            )
        ],
    ),
    case(
        "arrangement.vague.people_round_fountain",
        "people gathered round the fountain, kind of in a circle",
        [delta("pedestrian", 3, 16), layout("ring", category="pedestrian", around="fountain"), only("pedestrian")],
        [call("arrange_assets", categories=["pedestrian"], shape="ring", count=8, location=at("fountain"))],
    ),
    case(
        "arrangement.vague.trees_engineering_drive",
        "trees lining the way up to engineering",
        [
            delta("tree", 2, 10),
            layout("line", category="tree", tolerance=1.5),
            near("Engineering Hall entrance", 20, category="tree", require_all=True),
            only("tree"),
        ],
        [call("arrange_assets", categories=["tree"], shape="line", count=4, location=at("Engineering Hall entrance"))],
    ),
    case(
        "arrangement.vague.bin_grid_lot_b",
        "a little grid of bins somewhere in lot B",
        [
            delta("trash_bin", 4, 16),
            layout("cluster", category="trash_bin", tolerance=6),
            near("parking lot B", 1, category="trash_bin", require_all=True),
            only("trash_bin"),
        ],
        [call("arrange_assets", categories=["trash_bin"], shape="grid", count=6, location=at("parking lot B"))],
    ),
    case(
        "arrangement.vague.posts_round_ego",
        "surround our car with posts or something",
        [delta("bollard", 4, 30), layout("ring", category="bollard", around="ego"), only("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="ring", location=at("ego"))],
    ),
    case(
        "arrangement.vague.motorbikes_by_union",
        "a row of motorbikes parked up near the student union",
        [
            delta("motorcycle", 2, 10),
            layout("line", category="motorcycle"),
            near("Student Union entrance", 16, category="motorcycle", require_all=True),
            only("motorcycle"),
        ],
        [call("arrange_assets", categories=["motorcycle"], shape="parking_row", count=4, location=xy(42, -44))],
    ),
    # erroneous
    case(
        "arrangement.erroneous.line_cone_infront",
        "make line of 5 cone infront ego car",
        [
            delta("traffic_cone", 5, 5),
            layout("line", category="traffic_cone"),
            relative("in_front_of", "ego", 40, category="traffic_cone", tolerance_deg=20, require_all=True),
            only("traffic_cone"),
        ],
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="line",
                count=5,
                location=at("ego", "in_front_of", distance=15),
            )
        ],
    ),
    case(
        "arrangement.erroneous.ring_bollard_fountan",
        "ring of 8 bollard aroud the fountan",
        [delta("bollard", 8, 8), layout("ring", category="bollard", around="fountain"), only("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="ring", count=8, location=at("fountain"))],
    ),
    case(
        "arrangement.erroneous.park_4_car_row",
        "park 4 car in a row on parkin lot A pls",
        [
            delta("passenger_car", 4, 4),
            layout("line", category="passenger_car"),
            near("parking lot A", 1, category="passenger_car", require_all=True),
            only("passenger_car"),
        ],
        [
            call(
                "arrange_assets",
                categories=["passenger_car"],
                shape="parking_row",
                count=4,
                location=at("parking lot A"),
            )
        ],
    ),
    case(
        "arrangement.erroneous.pedestrain_circle",
        "put 6 pedestrain in circle round bus stop",
        [
            delta("pedestrian", 6, 6),
            layout("ring", category="pedestrian", around="bus stop", tolerance=1.5),
            only("pedestrian"),
        ],
        [call("arrange_assets", categories=["pedestrian"], shape="ring", count=6, location=at("bus stop"))],
    ),
    case(
        "arrangement.erroneous.trees_library_front",
        "Please arrange the trees in one line along the Library front, four pieces",
        [
            delta("tree", 4, 4),
            layout("line", category="tree", scope="added"),
            near("Library entrance", 12, category="tree", scope="added", require_all=True),
            only("tree"),
        ],
        [call("arrange_assets", categories=["tree"], shape="line", count=4, location=at("Library entrance"))],
    ),
    case(
        "arrangement.erroneous.grid_2x3_lot_b",
        "grid 2x3 of cones at lot b",
        [
            delta("traffic_cone", 6, 6),
            layout("cluster", category="traffic_cone", tolerance=5),
            near("parking lot B", 1, category="traffic_cone", require_all=True),
            only("traffic_cone"),
        ],
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="grid",
                count=6,
                columns=3,
                location=at("parking lot B"),
            )
        ],
    ),
    case(
        "arrangement.erroneous.cones_allong_westbond",
        "cones allong the edge of the westbond lane near jtekt",
        [
            delta("traffic_cone", 3, 20),
            layout("line", category="traffic_cone"),
            lane("main_westbound", category="traffic_cone"),
            near("JTEKT building entrance", 30, category="traffic_cone", require_all=True),
            only("traffic_cone"),
        ],
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="lane_edge",
                count=8,
                location=at("JTEKT building entrance"),
            )
        ],
    ),
    case(
        "arrangement.erroneous.barriers_accross_campus",
        "line barriers accross campus drive north of crossroad",
        [
            delta("road_barrier", 2, 6),
            layout("line", category="road_barrier", tolerance=1.0),
            near_point(0, 16, 8, category="road_barrier", require_all=True),
            only("road_barrier"),
        ],
        [
            call(
                "arrange_assets",
                categories=["road_barrier"],
                shape="line",
                count=3,
                spacing=2.2,
                heading_deg=0,
                location=xy(0, 15),
            )
        ],
    ),
    case(
        "arrangement.erroneous.ring_300_cones",
        "make a ring of 300 cones around the fountian",
        REFUSED,
        [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=300, location=at("fountain"))],
        tags=IMPOSSIBLE,
        notes="A scene holds at most 200 traffic cones.",
    ),
    case(
        "arrangement.erroneous.more_cones_line",
        "now 4 more cone in same line, continue it further up the road",
        [
            delta("traffic_cone", 4, 4),
            layout("line", category="traffic_cone", scope="all", min_count=8),
            lane("main_eastbound", category="traffic_cone", scope="added"),
            relative("in_front_of", "ego", 80, category="traffic_cone", tolerance_deg=10, require_all=True),
            only("traffic_cone"),
        ],
        [
            call(
                "arrange_assets",
                categories=["traffic_cone"],
                shape="line",
                count=4,
                heading_deg=0,
                spacing=2,
                location=xy(-12, -1.75),
            )
        ],
        setup=(
            step(
                "make a line of 4 cones 30 m in front of the ego",
                call(
                    "arrange_assets",
                    categories=["traffic_cone"],
                    shape="line",
                    count=4,
                    heading_deg=0,
                    spacing=2,
                    location=xy(-30, -1.75),
                ),
                planned=True,
            ),
        ),
    ),
    case(
        "arrangement.direct.edge_cones_and_sign",
        "Line the eastbound lane edge with 6 cones starting at the bus stop, and put a construction sign on the sidewalk where the line starts.",
        [
            delta("traffic_cone", 6, 6),
            layout("line", category="traffic_cone"),
            delta("construction_sign", 1, 1),
            near("bus stop", 8, category="construction_sign"),
            only("traffic_cone", "construction_sign"),
        ],
        [
            call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=6, location=at("bus stop")),
            call("add_asset", category="construction_sign", location=at("bus stop", "on_sidewalk")),
        ],
        tags=COMPOUND,
    ),
]


APPEARANCE = [
    # direct
    case(
        "appearance.direct.suv_red",
        "Paint the SUV red.",
        [looks(asset="suv_1", colour="red"), only(assets=("suv_1",))],
        [call("set_asset_appearance", assets=["suv_1"], colour="red")],
    ),
    case(
        "appearance.direct.time_1830",
        "Set the time of day to 18:30.",
        [env(time_from="18:25", time_to="18:35"), only(environment=True)],
        [call("set_time_of_day", time="18:30")],
    ),
    case(
        "appearance.direct.heavy_rain",
        "Make it rain heavily.",
        [env(weather=["rain"], intensity_min=0.75), only(environment=True)],
        [call("set_weather", kind="rain", intensity=0.9)],
    ),
    case(
        "appearance.direct.street_lights_on",
        "Turn the street lights on.",
        [env(street_lights="on"), only(environment=True)],
        [call("set_lighting", street_lights="on")],
    ),
    case(
        "appearance.direct.lamps_black",
        "Make every street light black.",
        [looks(category="street_light", colour="black", min_count=12, require_all=True), only("street_light")],
        [call("set_asset_appearance", category="street_light", colour="black")],
    ),
    case(
        "appearance.direct.fog_03",
        "Set the weather to fog with intensity 0.3.",
        [env(weather=["fog"], intensity_min=0.25, intensity_max=0.35), only(environment=True)],
        [call("set_weather", kind="fog", intensity=0.3)],
    ),
    case(
        "appearance.direct.car1_glossy_blue",
        "Make passenger_car_1 glossy blue.",
        [looks(asset="passenger_car_1", colour="blue", material="glossy"), only(assets=("passenger_car_1",))],
        [call("set_asset_appearance", assets=["passenger_car_1"], colour="blue", material="glossy")],
    ),
    case(
        "appearance.direct.clock_2530",
        "Set the clock to 25:30.",
        REFUSED,
        [call("set_time_of_day", time="25:30")],
        tags=IMPOSSIBLE,
        notes="There is no 25:30 on a 24-hour clock.",
    ),
    # indirect
    case(
        "appearance.indirect.dusk_wet_roads",
        "We're testing the camera at dusk, with the roads wet from rain that is still falling.",
        [env(time_from="18:30", time_to="21:30", weather=["rain"]), only(environment=True)],
        [call("set_time_of_day", time="dusk"), call("set_weather", kind="rain", intensity=0.5)],
        tags=COMPOUND,
    ),
    case(
        "appearance.indirect.hydrant_easy_to_spot",
        "The fire hydrant should be easy to spot from far away; give it a bright yellow coat.",
        [looks(asset="fire_hydrant_1", colour="yellow"), only(assets=("fire_hydrant_1",))],
        [call("set_asset_appearance", assets=["fire_hydrant_1"], colour="yellow")],
    ),
    case(
        "appearance.indirect.half_past_ten",
        "Our night-vision test starts at half past ten in the evening.",
        [env(time_from="22:25", time_to="22:35"), only(environment=True)],
        [call("set_time_of_day", time="22:30")],
    ),
    case(
        "appearance.indirect.winter",
        "This is meant to be a winter scenario, with snow coming down.",
        [env(weather=["snow"]), only(environment=True)],
        [call("set_weather", kind="snow")],
    ),
    case(
        "appearance.indirect.sunrise_commute",
        "It should look like the early-morning commute, with the sun just coming up.",
        [env(time_from="05:30", time_to="07:30"), only(environment=True)],
        [call("set_time_of_day", time="sunrise")],
    ),
    case(
        "appearance.indirect.suv_stand_out",
        "The SUV in the student car park should be easy to tell apart from the grey sedans, so make it white.",
        [looks(asset="suv_1", colour="white"), only(assets=("suv_1",))],
        [call("set_asset_appearance", assets=["suv_1"], colour="white")],
    ),
    case(
        "appearance.indirect.headlights_whole_run",
        "Every vehicle should have its headlights on for this whole run.",
        [env(vehicle_lights="on"), only(environment=True)],
        [call("set_lighting", vehicle_lights="on")],
    ),
    case(
        "appearance.indirect.tornado",
        "For the extreme-weather test we need a tornado passing over campus.",
        REFUSED,
        [call("set_weather", kind="tornado")],
        tags=IMPOSSIBLE,
        notes="The weather may be clear, cloudy, rain, fog or snow.",
    ),
    case(
        "appearance.indirect.night_lights_on",
        "We're recording the late shift, so it has to be night, and the lamps along the streets must be lit.",
        [env(night=True, street_lights="on"), only(environment=True)],
        [call("set_time_of_day", time="22:00"), call("set_lighting", street_lights="on")],
        tags=COMPOUND,
    ),
    # vague
    case(
        "appearance.vague.bit_gloomy",
        "make it a bit gloomy",
        [env(weather=["cloudy", "fog", "rain"]), only(environment=True)],
        [call("set_weather", kind="cloudy", intensity=0.6)],
    ),
    case(
        "appearance.vague.night_pls",
        "night time pls",
        [env(night=True), only(environment=True)],
        [call("set_time_of_day", time="night")],
    ),
    case(
        "appearance.vague.cars_look_different",
        "make the cars look different",
        [looks(category=CARS), only(*CARS)],
        [call("set_asset_appearance", category="passenger_car", colour="red")],
    ),
    case(
        "appearance.vague.little_foggy",
        "a little foggy",
        [env(weather=["fog"], intensity_max=0.5), only(environment=True)],
        [call("set_weather", kind="fog", intensity=0.3)],
    ),
    case(
        "appearance.vague.too_dark",
        "it's too dark, make it brighter",
        [only(environment=True)],
        [call("set_lighting", exposure=1.5)],
        setup=(step("Set the time to 21:00.", call("set_time_of_day", time="21:00")),),
        alternatives=([env(exposure_min=1.05)], [env(street_lights="on")], [env(night=False)]),
    ),
    case(
        "appearance.vague.bench_natural",
        "the bench should look more natural",
        [only(assets=("bench_1",))],
        [call("set_asset_appearance", assets=["bench_1"], material="wood")],
        alternatives=(
            [looks(asset="bench_1", material="wood")],
            [looks(asset="bench_1", colour=["brown", "green", "beige"])],
        ),
    ),
    case(
        "appearance.vague.weather_nice_again",
        "make the weather nice again",
        [env(weather=["clear"]), only(environment=True)],
        [call("set_weather", kind="clear")],
        setup=(RAINY,),
    ),
    # erroneous
    case(
        "appearance.erroneous.suv_bleu",
        "paint teh suv bleu",
        [looks(asset="suv_1", colour="blue"), only(assets=("suv_1",))],
        [call("set_asset_appearance", assets=["suv_1"], colour="blue")],
    ),
    case(
        "appearance.erroneous.six_thirty_pm",
        "set time to 6.30 pm",
        [env(time_from="18:25", time_to="18:35"), only(environment=True)],
        [call("set_time_of_day", time="18:30")],
    ),
    case(
        "appearance.erroneous.snowing_hard",
        "make it snowing hard",
        [env(weather=["snow"], intensity_min=0.75), only(environment=True)],
        [call("set_weather", kind="snow", intensity=0.9)],
    ),
    case(
        "appearance.erroneous.turn_of_lights",
        "turn of the street lights",
        [env(street_lights="off"), only(environment=True)],
        [call("set_lighting", street_lights="off")],
    ),
    case(
        "appearance.erroneous.rainy_not_strong",
        "Please do the weather rainy but not too much strong",
        [env(weather=["rain"], intensity_min=0.1, intensity_max=0.5), only(environment=True)],
        [call("set_weather", kind="rain", intensity=0.3)],
    ),
    case(
        "appearance.erroneous.bench_in_green",
        "change the bench colour in green plz",
        [looks(asset="bench_1", colour="green"), only(assets=("bench_1",))],
        [call("set_asset_appearance", assets=["bench_1"], colour="green")],
    ),
    case(
        "appearance.erroneous.suv_invisible",
        "make the suv invisable so the camera cant see it",
        REFUSED,
        [call("set_asset_appearance", assets=["suv_1"], colour="invisible")],
        tags=IMPOSSIBLE,
        notes="Assets have a colour and a material; nothing is see-through.",
    ),
    case(
        "appearance.erroneous.cones_i_added_white",
        "those cone i added, make them all white colour",
        [looks(category="traffic_cone", colour="white", min_count=4, require_all=True), only("traffic_cone")],
        [call("set_asset_appearance", category="traffic_cone", colour="white")],
        setup=(step(CONES_AHEAD["prompt"], *CONES_AHEAD["calls"], planned=True),),
    ),
    case(
        "appearance.direct.fog_and_seven_pm",
        "Set fog at intensity 0.7 and the time to 19:00.",
        [
            env(weather=["fog"], intensity_min=0.65, intensity_max=0.75, time_from="18:55", time_to="19:05"),
            only(environment=True),
        ],
        [call("set_weather", kind="fog", intensity=0.7), call("set_time_of_day", time="19:00")],
        tags=COMPOUND,
    ),
]


ALL_CASES: list[Json] = [*SEARCH, *ADDITION, *REMOVAL, *POSITIONING, *MOVING, *ARRANGEMENT, *APPEARANCE]


def main() -> None:
    lines = [json.dumps(c, ensure_ascii=False) for c in ALL_CASES]
    SUITE_PATH.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} cases to {SUITE_PATH}")


if __name__ == "__main__":
    main()
