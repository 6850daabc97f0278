"""Addition cases: new assets of the right kind, in the right place, doing the right thing."""

from __future__ import annotations

from typing import Any

from dsl import (
    RAIN,
    VEHICLES,
    Json,
    add,
    behaviour,
    call,
    case,
    delta,
    does,
    env,
    exactly,
    in_lane,
    loc,
    looks,
    near,
    only,
    surface,
)

JTEKT = "JTEKT building entrance"
SIGNS = ["construction_sign", "stop_sign", "parking_sign", "pedestrian_sign"]
PARKABLE = [*VEHICLES, "truck", "bus", "motorcycle", "bicycle"]


def _a(cid: str, grade: str, prompt: str, checks: list[Json], ref: list[Json], **kw: Any) -> Json:
    return case(f"addition.{grade}.{cid}", "addition", grade, prompt, checks, ref, **kw)


CAR_JTEKT = [exactly(VEHICLES, 1), near(VEHICLES, JTEKT, 12), does("parked", VEHICLES), only(*VEHICLES)]
CAR_JTEKT_REF = [add("passenger_car", loc("at", JTEKT), behaviour=behaviour("parked"))]
SKIDPAD = [exactly("ackermann_robot", 1), does("circle", "ackermann_robot"), only("ackermann_robot")]
SKIDPAD_REF = [add("ackermann_robot", behaviour=behaviour("circle"))]
RUBBLE = [
    delta("cement_rubble", 1, 3),
    near("cement_rubble", "main intersection", 10, every=True),
    only("cement_rubble"),
]
RUBBLE_REF = [add("cement_rubble", loc("at", "main intersection"))]
BUS = [exactly("bus", 1), near("bus", "bus stop", 15), only("bus")]
BUS_REF = [add("bus", loc("at", "bus stop"))]
PEDS = [
    exactly("pedestrian", 2),
    surface(["sidewalk"], "pedestrian"),
    near("pedestrian", "Library entrance", 15, every=True),
    only("pedestrian"),
]
PEDS_REF = [add("pedestrian", loc("on_sidewalk", "Library entrance"), count=2)]
TRUCK = [exactly("truck", 1), in_lane("main_westbound", "truck", aligned=True), only("truck")]
TRUCK_REF = [add("truck", loc("in_lane", "main_westbound"))]
BIKE = [exactly("bicycle", 1), near("bicycle", "bench_1", 5), only("bicycle")]
BIKE_REF = [add("bicycle", loc("next_to", "bench_1"))]
TREE = [exactly("tree", 1), near("tree", "Engineering Hall entrance", 10), only("tree")]
TREE_REF = [add("tree", loc("in_front_of", "Engineering Hall entrance"))]
SIGN = [exactly("construction_sign", 1), near("construction_sign", "west crosswalk", 10), only("construction_sign")]
SIGN_REF = [add("construction_sign", loc("at", "west crosswalk"))]
RED_SUV = [exactly("suv", 1), near("suv", "parking lot B", 1), looks("red", "suv"), only("suv")]
RED_SUV_REF = [add("suv", loc("at", "parking lot B"), colour="red")]
JAYWALK = [exactly("pedestrian", 1), does("jaywalk", "pedestrian", crosses_lane="main_eastbound"), only("pedestrian")]
JAYWALK_REF = [add("pedestrian", behaviour=behaviour("jaywalk"))]
CROSSER = [
    exactly("pedestrian", 1),
    does("cross_road", "pedestrian"),
    near("pedestrian", "north crosswalk", 10),
    only("pedestrian"),
]
CROSSER_REF = [add("pedestrian", loc("at", "north crosswalk"), behaviour=behaviour("cross_road"))]


def cases() -> list[Json]:
    paper = ["paper"]
    return [
        _a(
            "car_jtekt",
            "direct",
            "add a parked car at the JTEKT building entrance",
            CAR_JTEKT,
            CAR_JTEKT_REF,
            tags=paper,
        ),
        _a(
            "skidpad_robot",
            "direct",
            "add a mid-scale Ackermann-steered robot performing a skidpad maneuver",
            SKIDPAD,
            SKIDPAD_REF,
            tags=paper,
        ),
        _a("rubble", "direct", "create cement rubble at the centre of the scene", RUBBLE, RUBBLE_REF, tags=paper),
        _a(
            "jaywalker",
            "direct",
            "make a jaywalking pedestrian cut across the ego vehicle's path",
            JAYWALK,
            JAYWALK_REF,
            tags=paper,
        ),
        _a("bus", "direct", "Add a bus at the bus stop.", BUS, BUS_REF),
        _a("pedestrians", "direct", "Add two pedestrians on the sidewalk near the Library entrance.", PEDS, PEDS_REF),
        _a("truck", "direct", "Add a truck in lane main_westbound.", TRUCK, TRUCK_REF),
        _a("bicycle", "direct", "Add a bicycle next to the bench at the bus stop.", BIKE, BIKE_REF),
        _a("tree", "direct", "Add a tree in front of the Engineering Hall entrance.", TREE, TREE_REF),
        _a("sign", "direct", "Add a construction sign at the west crosswalk.", SIGN, SIGN_REF),
        _a("red_suv", "direct", "Add a red SUV in parking lot B.", RED_SUV, RED_SUV_REF),
        _a("crosser", "direct", "Add a pedestrian crossing the road at the north crosswalk.", CROSSER, CROSSER_REF),
        _a(
            "car_jtekt_in_rain",
            "direct",
            "add a parked car at the JTEKT building entrance",
            [*CAR_JTEKT[:3], env(weather=["rain"])],
            CAR_JTEKT_REF,
            setup=[RAIN],
            tags=["paper", "multi_turn"],
        ),
        # indirect
        _a(
            "left_car",
            "indirect",
            "Someone left their car at the JTEKT entrance.",
            [exactly(PARKABLE, 1), near(PARKABLE, JTEKT, 12), only(*PARKABLE)],
            CAR_JTEKT_REF,
        ),
        _a("shuttle", "indirect", "There should be a shuttle waiting at the bus stop.", BUS, BUS_REF),
        _a(
            "robot_test",
            "indirect",
            "We need a test robot doing circles in parking lot B.",
            [
                exactly("ackermann_robot", 1),
                does("circle", "ackermann_robot", centre_near="parking lot B"),
                only("ackermann_robot"),
            ],
            [add("ackermann_robot", loc("at", "parking lot B"), behaviour=behaviour("circle"))],
        ),
        _a(
            "delivery",
            "indirect",
            "Let's have a delivery truck dropping something off at the Student Union.",
            [exactly("truck", 1), near("truck", "Student Union entrance", 15), only("truck")],
            [add("truck", loc("at", "Student Union entrance"))],
        ),
        _a(
            "greenery",
            "indirect",
            "Put some greenery by the fountain.",
            [delta("tree", 1, 6), near("tree", "fountain", 12, every=True), only("tree")],
            [add("tree", loc("at", "fountain"))],
        ),
        _a(
            "seating",
            "indirect",
            "Somewhere for students to sit near the Library entrance would be nice.",
            [delta("bench", 1, 6), near("bench", "Library entrance", 12), only("bench")],
            [add("bench", loc("at", "Library entrance"))],
        ),
        _a(
            "campus_traffic",
            "indirect",
            "Make the crossroads feel busy: a car should be driving through on Campus Drive.",
            [exactly(VEHICLES, 1), does("drive_lane", VEHICLES), in_lane(None, VEHICLES), only(*VEHICLES)],
            [
                add(
                    "passenger_car",
                    loc("in_lane", "campus_northbound"),
                    behaviour=behaviour("drive_lane", lane="campus_northbound"),
                )
            ],
            alternatives=[
                [does("drive_lane", VEHICLES, lane="campus_northbound")],
                [does("drive_lane", VEHICLES, lane="campus_southbound")],
            ],
        ),
        _a(
            "cyclist",
            "indirect",
            "A cyclist is waiting at the west crosswalk.",
            [exactly("bicycle", 1), near("bicycle", "west crosswalk", 8), only("bicycle")],
            [add("bicycle", loc("at", "west crosswalk"))],
        ),
        _a(
            "roadworks_warning",
            "indirect",
            "Drivers should be warned about roadworks before the main intersection.",
            [
                delta("construction_sign", 1, 4),
                near("construction_sign", "main intersection", 25),
                only("construction_sign", "traffic_cone"),
            ],
            [add("construction_sign", loc("at", "west crosswalk"))],
        ),
        _a(
            "broken_lorry",
            "indirect",
            "There's a broken-down lorry blocking the eastbound lane by the east gate.",
            [exactly("truck", 1), in_lane("main_eastbound", "truck"), near("truck", "east gate", 20), only("truck")],
            [add("truck", loc("in_lane", "east gate"))],
        ),
        _a(
            "dumped_bin",
            "indirect",
            "Someone dumped a trash bin in front of the Engineering Hall.",
            [exactly("trash_bin", 1), near("trash_bin", "Engineering Hall entrance", 10), only("trash_bin")],
            [add("trash_bin", loc("in_front_of", "Engineering Hall entrance"))],
        ),
        # vague
        _a(
            "a_car",
            "vague",
            "add a car somewhere",
            [exactly(VEHICLES, 1), only(*VEHICLES)],
            [add("passenger_car", loc("at", "parking lot A"))],
        ),
        _a(
            "a_robot",
            "vague",
            "put a robot in",
            [exactly("ackermann_robot", 1), only("ackermann_robot")],
            [add("ackermann_robot", loc("at", "parking lot B"))],
        ),
        _a(
            "people_library",
            "vague",
            "more people near the library",
            [delta("pedestrian", 1, 10), near("pedestrian", "Library entrance", 15, every=True), only("pedestrian")],
            [add("pedestrian", loc("at", "Library entrance"), count=3)],
        ),
        _a(
            "debris",
            "vague",
            "some debris in the road maybe",
            [delta("cement_rubble", 1, 5), surface(["drivable"], "cement_rubble"), only("cement_rubble")],
            [add("cement_rubble", loc("in_lane", "main_eastbound"))],
        ),
        _a(
            "trees_fountain",
            "vague",
            "add a tree or two by the fountain",
            [delta("tree", 1, 2), near("tree", "fountain", 12, every=True), only("tree")],
            [add("tree", loc("at", "fountain"), count=2)],
        ),
        _a("a_bus", "vague", "a bus", [exactly("bus", 1), only("bus")], BUS_REF),
        _a(
            "bike_stop",
            "vague",
            "could use a bike around the bus stop",
            [
                exactly(["bicycle", "motorcycle"], 1),
                near(["bicycle", "motorcycle"], "bus stop", 10),
                only("bicycle", "motorcycle"),
            ],
            [add("bicycle", loc("at", "bus stop"))],
        ),
        _a(
            "gate_sign",
            "vague",
            "stick a sign up near the gate",
            [delta(SIGNS, 1, 2), only(*SIGNS)],
            [add("construction_sign", loc("at", "main gate"))],
            alternatives=[[near(SIGNS, "main gate", 15)], [near(SIGNS, "east gate", 15)]],
        ),
        _a(
            "something_jtekt",
            "vague",
            "something parked at JTEKT",
            [exactly(PARKABLE, 1), near(PARKABLE, JTEKT, 12), only(*PARKABLE)],
            CAR_JTEKT_REF,
        ),
        _a(
            "few_people",
            "vague",
            "a few pedestrians",
            [delta("pedestrian", 2, 10), only("pedestrian")],
            [add("pedestrian", loc("at", "bus stop"), count=3)],
        ),
        _a(
            "hydrant",
            "vague",
            "put a hydrant somewhere near the intersection",
            [exactly("fire_hydrant", 1), near("fire_hydrant", "main intersection", 20), only("fire_hydrant")],
            [add("fire_hydrant", loc("on_sidewalk", "north crosswalk"))],
        ),
        # erroneous
        _a("car_jtekt", "erroneous", "add parked car at jtekt bulding entrace", CAR_JTEKT, CAR_JTEKT_REF),
        _a("skidpad_robot", "erroneous", "ad a robot what do skidpad manuver", SKIDPAD, SKIDPAD_REF),
        _a("rubble", "erroneous", "put cement rubbel in center of scene", RUBBLE, RUBBLE_REF),
        _a("bus", "erroneous", "please to add one bus on bus stop", BUS, BUS_REF),
        _a("pedestrians", "erroneous", "add 2 pedestrain on sidewalk near of libary", PEDS, PEDS_REF),
        _a("truck", "erroneous", "add truk in main westbond lane", TRUCK, TRUCK_REF),
        _a("bicycle", "erroneous", "i want a bicylce next to bench on bus stop", BIKE, BIKE_REF),
        _a("tree", "erroneous", "plant one tree infront engineering hall", TREE, TREE_REF),
        _a("red_suv", "erroneous", "add the red suv on parking B", RED_SUV, RED_SUV_REF),
        _a("jaywalker", "erroneous", "make a pedestrain jaywalk infront ego car", JAYWALK, JAYWALK_REF),
        _a("sign", "erroneous", "add a constrution sign at west crosswalk", SIGN, SIGN_REF),
        _a(
            "weather_and_car",
            "direct",
            "Make it rain and add a parked car at the JTEKT building entrance.",
            [*CAR_JTEKT[:3], env(weather=["rain"]), only(*VEHICLES, environment=True)],
            [call("set_weather", kind="rain"), *CAR_JTEKT_REF],
            tags=["compound"],
        ),
    ]
