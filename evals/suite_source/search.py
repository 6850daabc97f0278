"""Search cases: questions about the world; the scene must stay as it is."""

from __future__ import annotations

from typing import Any

from dsl import (
    CONES_AT_JTEKT,
    RUBBLE,
    Json,
    accepted,
    call,
    case,
    only,
    says,
)

STILL = [accepted(), only()]


def _q(cid: str, grade: str, prompt: str, answer: Json, ref: Json, **kw: Any) -> Json:
    return case(f"search.{grade}.{cid}", "search", grade, prompt, [*STILL, answer], [ref], **kw)


LOT_B = says(any_of=["38.5"])
LOT_B_REF = call("find_landmarks", query="parking lot B")
LIGHTS = says(any_of=["2", "two"])
LIGHTS_REF = call("find_assets", category="traffic_light")
CARS_B = says(all_of=["passenger_car_1", "passenger_car_2"])
CARS_B_REF = call("find_assets", category="passenger_car", near="parking lot B", within=30)
BUS_LANE = says(all_of=["main_eastbound"], none_of=["campus_northbound"])
BUS_LANE_REF = call("find_lanes", near="bus stop")
STREETLIGHTS = says(any_of=["12", "twelve"])
STREETLIGHTS_REF = call("find_assets", category="street_light")
FOUNTAIN = says(any_of=["75", "75.0"])
FOUNTAIN_REF = call("find_landmarks", query="fountain")
BUS_MASS = says(any_of=["12000", "12,000", "12 000", "12 t", "12 tonnes", "12000.0"])
BUS_MASS_REF = call("asset_properties", category="bus")
TREES = says(any_of=["4", "four"])
TREES_REF = call("find_assets", category="tree")
EGO = says(any_of=["-60", "-60.0"])
EGO_REF = call("asset_properties", asset="ego")
LIBRARY = says(any_of=["-41", "-41.0"])
LIBRARY_REF = call("find_landmarks", query="Library entrance")


def cases() -> list[Json]:
    out = [
        # direct: a person who knows what to ask
        _q("parking_lot_b", "direct", "Where is parking lot B?", LOT_B, LOT_B_REF),
        _q("traffic_lights", "direct", "How many traffic lights are in the scene?", LIGHTS, LIGHTS_REF),
        _q("cars_lot_b", "direct", "List the passenger cars in parking lot B.", CARS_B, CARS_B_REF),
        _q("lane_bus_stop", "direct", "Which lane is nearest to the bus stop?", BUS_LANE, BUS_LANE_REF),
        _q("street_lights", "direct", "How many street lights are there?", STREETLIGHTS, STREETLIGHTS_REF),
        _q("fountain", "direct", "Where is the fountain?", FOUNTAIN, FOUNTAIN_REF),
        _q("bus_mass", "direct", "What is the mass of a bus?", BUS_MASS, BUS_MASS_REF),
        _q("trees", "direct", "How many trees are in the scene?", TREES, TREES_REF),
        _q("ego", "direct", "Where is the ego vehicle?", EGO, EGO_REF),
        _q("library", "direct", "Where is the Library entrance?", LIBRARY, LIBRARY_REF),
        _q(
            "main_street_lanes",
            "direct",
            "Which lanes does Main Street have?",
            says(all_of=["main_eastbound", "main_westbound"]),
            call("find_lanes", road="Main Street"),
        ),
        _q(
            "cones_count",
            "direct",
            "How many traffic cones are there now?",
            says(any_of=["5", "five"]),
            call("find_assets", category="traffic_cone"),
            setup=[CONES_AT_JTEKT],
            tags=["multi_turn"],
        ),
        # indirect: the question behind a task
        _q("student_parking", "indirect", "I need to know where the student parking is.", LOT_B, LOT_B_REF),
        _q(
            "bus_stop_things",
            "indirect",
            "Tell me what is standing at the bus stop.",
            says(any_of=["bench", "trash_bin", "trash bin", "bench_1", "trash_bin_1"]),
            call("find_assets", near="bus stop", within=6),
        ),
        _q(
            "cars_in_b",
            "indirect",
            "Could you check how many cars are parked in lot B?",
            says(any_of=["2", "3", "two", "three"]),
            call("find_assets", category="passenger_car", near="parking lot B", within=20),
        ),
        _q(
            "junction_signals",
            "indirect",
            "Before I add anything: what signals control the crossroads?",
            says(any_of=["traffic_light", "traffic light", "traffic_light_1"]),
            call("find_assets", category="traffic_light", near="main intersection", within=20),
        ),
        _q("our_car", "indirect", "I'd like to know where our car is right now.", EGO, EGO_REF),
        _q(
            "engineering",
            "indirect",
            "Show me where the engineering building is.",
            says(any_of=["-40", "-40.0"]),
            call("find_landmarks", query="Engineering Hall entrance"),
        ),
        _q(
            "gate",
            "indirect",
            "We want to put something at the campus gate; where exactly is it?",
            says(any_of=["-100", "-100.0"]),
            call("find_landmarks", query="main gate"),
        ),
        _q(
            "cone_weight",
            "indirect",
            "How heavy would one of those orange traffic cones be?",
            says(any_of=["3", "3 kg", "3kg", "3.0"]),
            call("asset_properties", category="cone"),
        ),
        _q(
            "bench_count",
            "indirect",
            "Remind me how many benches we have.",
            says(any_of=["1", "one"]),
            call("find_assets", category="bench"),
        ),
        _q(
            "rubble_where",
            "indirect",
            "Where did that rubble end up?",
            says(any_of=["0.0", "0", "intersection", "centre", "center"]),
            call("find_assets", category="cement_rubble"),
            setup=[RUBBLE],
            tags=["multi_turn"],
        ),
        _q(
            "library_lane",
            "indirect",
            "Which lane would a car use to drop someone at the Library entrance?",
            says(any_of=["main_eastbound", "main_westbound"]),
            call("find_lanes", near="Library entrance"),
        ),
        # vague: few words, the intent must be guessed
        _q(
            "parking",
            "vague",
            "where's the parking?",
            says(any_of=["parking lot A", "parking lot B", "-85", "38.5"]),
            call("find_landmarks", query="parking"),
        ),
        _q(
            "fountain_area",
            "vague",
            "what's around the fountain?",
            says(any_of=["tree", "tree_2", "tree_3"]),
            call("find_assets", near="fountain", within=20),
        ),
        _q(
            "cars",
            "vague",
            "any cars around?",
            says(any_of=["passenger_car", "passenger_car_1", "suv", "suv_1", "car"]),
            call("find_assets", category="car"),
        ),
        _q(
            "lights",
            "vague",
            "lights?",
            says(any_of=["street_light", "street_light_1", "traffic_light", "traffic_light_1"]),
            call("find_assets", category="street_light"),
        ),
        _q(
            "library_what",
            "vague",
            "what's at the library",
            says(any_of=["-41", "Library entrance", "trash_bin", "tree", "tree_1", "bench"]),
            call("find_landmarks", query="library"),
        ),
        _q(
            "lanes",
            "vague",
            "lanes?",
            says(any_of=["main_eastbound", "campus_northbound", "main_westbound"]),
            call("find_lanes"),
        ),
        _q(
            "gates",
            "vague",
            "the gates, where are they",
            says(any_of=["-100", "100", "main gate", "east gate"]),
            call("find_landmarks", query="gate"),
        ),
        _q(
            "junction_stuff",
            "vague",
            "stuff near the intersection?",
            says(any_of=["traffic_light", "traffic light", "stop_sign", "fire_hydrant", "traffic_light_1"]),
            call("find_assets", near="main intersection", within=15),
        ),
        _q(
            "bus_size",
            "vague",
            "how big is a bus",
            says(any_of=["12", "12x2.55x3.2", "12000"]),
            call("asset_properties", category="bus"),
        ),
        _q("where_am_i", "vague", "where am i", says(any_of=["-60", "-60.0", "main_eastbound"]), EGO_REF),
        _q("trees_v", "vague", "trees?", says(any_of=["4", "four", "tree_1"]), TREES_REF),
        # erroneous: typos, grammar slips, non-native phrasing
        _q("parking_lot_b", "erroneous", "were is the parkign lot b", LOT_B, LOT_B_REF),
        _q("traffic_lights", "erroneous", "how many trafic lite are in scene", LIGHTS, LIGHTS_REF),
        _q("cars_lot_b", "erroneous", "list me all passenger car what is in lot b", CARS_B, CARS_B_REF),
        _q("lane_bus_stop", "erroneous", "wich lane is near to bus stop?", BUS_LANE, BUS_LANE_REF),
        _q("street_lights", "erroneous", "how much street lamp there is", STREETLIGHTS, STREETLIGHTS_REF),
        _q("fountain", "erroneous", "where fountian is located", FOUNTAIN, FOUNTAIN_REF),
        _q("bus_mass", "erroneous", "how mutch weigh a bus", BUS_MASS, BUS_MASS_REF),
        _q("trees", "erroneous", "how many tree's are on the campus pls", TREES, TREES_REF),
        _q("ego", "erroneous", "where is ego vehical now", EGO, EGO_REF),
        _q("library", "erroneous", "the libary entrence, where it is?", LIBRARY, LIBRARY_REF),
    ]
    return out
