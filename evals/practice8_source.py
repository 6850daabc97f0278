"""practice8: the ninth practice suite for drivetwin (a development suite, tag `practice8`).

Natural-language requests a person might type at the live campus twin, each with checks that
judge the outcome (never the calls) and a known-good reference plan. It was written by a helper
who had read neither the planners (their lexicons, prompts or example banks) nor any other
suite's cases: only the campus world (worlds/campus.py, worlds/data/campus.json), the catalog,
the Worker tools (tools/*.py) and the checks (evals/checks.py and friends).

Voices, spread over every task x grade cell: an insurance adjuster reconstructing an incident
("vehicle 1", "the claimant's car", "at the time of the incident"); a logistics dispatcher
("dispatch", "stage two units", "pull the unit", "ETA"); someone frustrated or sarcastic; someone
explaining to a child as they go; a sports commentator or storyteller ("and here comes a
cyclist ..."); someone who names things by look, size, colour or material, or by chains of
relations ("the bench next to the tree by the library"); imperial and odd units and rough amounts
(yards, feet, "a stone's throw", "a handful", "a dozen", "half a block"); one-word and fragment
requests; commands asked as questions ("could we get ...?") and real questions that must change
nothing; formal or legal wording ("it is requested that", "pursuant to"); and speakers who mix in
Spanish, French, German or Hindi words, or emoji. About 8 % ask for what the world cannot do and
expect a refusal that changes nothing (tag `impossible`).

Regenerate the JSONL with `python -m drivetwin.evals.practice8_source`; every reference passes
(`tests/evals/test_later_practice_suites.py`).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

SUITE_PATH = Path(__file__).resolve().parent / "suites" / "practice8.jsonl"

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
        "id": f"practice8.{task}.{grade}.{slug}",
        "prompt": prompt,
        "task": task,
        "grade": grade,
        "tags": ["practice8", *tags],
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




# A few more check builders (the same check kinds, named for this file).
def in_lane(lane: str | None = None, *, aligned: bool = False, **more: Any) -> Json:
    return {"kind": "in_lane", "lane": lane, "aligned": aligned, **more}


def does(behaviour: str | list[str], **more: Any) -> Json:
    return {"kind": "behaviour", "behaviour": behaviour, **more}


def shaped(shape: str, category: str | list[str] | None, **more: Any) -> Json:
    return {"kind": "arrangement", "shape": shape, "category": category, **more}


def on(surfaces: list[str], **more: Any) -> Json:
    return {"kind": "on_surface", "surfaces": surfaces, **more}


def rel(relation: str, target: str, **more: Any) -> Json:
    return {"kind": "relative", "relation": relation, "target": target, **more}


def sim(seconds: float, *expect: Json) -> Json:
    return {"kind": "scenario", "seconds": seconds, "expect": list(expect)}


def event(manoeuvre: str, actor: str | None = None, **more: Any) -> Json:
    return {"kind": "event", "manoeuvre": manoeuvre, "actor": actor, **more}


COMPOUND = ("compound",)


# --- search: questions, answered with nothing changed -------------------------------------------
SEARCH: list[Json] = [
    # direct
    question("direct", "bus-stop-to-library", "How far is the bus stop from the Library entrance?",
             told(any_of=["14.5", "14.53", "15"]), [call("measure_distance", a="bus stop", b="Library entrance")]),
    question("direct", "weather-now", "What's the weather doing right now?",
             told(any_of=["clear", "sunny", "fine"]), [call("describe_environment")]),
    question("direct", "count-street-lights", "How many street lights are there in the scene?",
             told(any_of=["12", "twelve"]), [call("find_assets", category="street_light")]),
    question("direct", "ego-lane", "Which lane is the ego vehicle driving in?",
             told(any_of=["main_eastbound", "eastbound"]), [call("find_lanes", near="ego")]),
    question("direct", "adjuster-distance", "At the time of the incident, how far was the claimant's car (the ego) "
             "from the west crosswalk?", told(any_of=["48.5", "48.53", "49"]),
             [call("measure_distance", a="ego", b="west crosswalk")]),
    question("direct", "dispatch-eta", "ETA check: straight-line distance from the ego to the east gate?",
             told(any_of=["160", "160.0"]), [call("measure_distance", a="ego", b="east gate")]),
    question("direct", "count-traffic-lights", "🚦 how many of these are in the scene?",
             told(any_of=["2", "two"]), [call("find_assets", category="traffic_light")]),
    question("direct", "hydrant-where", "What are the coordinates of the fire hydrant?",
             told(all_of=["16"]), [call("asset_properties", asset="fire_hydrant_1")]),
    # indirect
    question("indirect", "daytime-sarcastic", "oh great, is it even daytime in this thing or what?",
             told(any_of=["day", "daytime", "12:00", "noon", "midday"]), [call("describe_environment")]),
    question("indirect", "building-by-hydrant", "see the red hydrant, sweetie? which big building's front door "
             "is closest to it, can you tell me?", told(any_of=["JTEKT"]),
             [call("find_landmarks", query="entrance", nearest_to="fire_hydrant_1")]),
    question("indirect", "formal-union-lotb", "It is requested that the distance between the Student Union "
             "entrance and the parking lot B entrance be reported.", told(any_of=["47.7", "47.71", "48"]),
             [call("measure_distance", a="Student Union entrance", b="parking lot B entrance")]),
    question("indirect", "raining-question", "Is it raining on campus at the moment?",
             told(any_of=["clear", "no", "not"]), [call("describe_environment")]),
    question("indirect", "vehicles-in-lot-b", "I'd like to know how many vehicles are sitting in lot B.",
             told(any_of=["3", "three"]), [call("find_assets", category="vehicles", near="parking lot B", within=25)]),
    question("indirect", "metal-pole-bus-stop", "the tall metal thing with the lamp on top that's closest to the "
             "bus stop - how far from the stop is it?", told(any_of=["8.0", "8", "8.01"]),
             [call("find_assets", category="street_light", nearest_to="bus stop")]),
    question("indirect", "bench-to-bin-chain", "the bench next to the tree by the library - how far is it from "
             "the litter bin?", told(any_of=["7.6", "7.63", "8"]),
             [call("measure_distance", a="bench_1", b="trash_bin_1")]),
    question("indirect", "cones-after-setup", "right, so how many cones did that give us?",
             told(any_of=["3", "three"]), [call("find_assets", category="traffic_cone")],
             setup=[turn("put three cones in lot A", [call("add_asset", category="traffic_cone", count=3,
                                                            location=at("parking lot A"))])]),
    # vague
    question("vague", "sit-near-bus-stop", "anywhere to sit near the bus stop?",
             told(any_of=["bench_1", "bench"]), [call("find_assets", category="bench", nearest_to="bus stop")]),
    question("vague", "around-fountain", "what's around the fountain?",
             told(any_of=["tree_2", "tree"]), [call("find_assets", near="fountain", within=15)]),
    question("vague", "closest-to-ego", "what's the closest thing to our car?",
             told(any_of=["street_light_2", "street light"]), [call("find_assets", nearest_to="ego")]),
    question("vague", "bins-fragment", "bins?",
             told(any_of=["trash_bin_1", "one", "1"]), [call("find_assets", category="trash_bin")]),
    question("vague", "lights-state", "street lamps - on or off right now?",
             told(any_of=["off", "auto"]), [call("describe_environment")]),
    question("vague", "stone-throw-gate", "is the fountain a stone's throw from the east gate or a proper walk? "
             "give me the metres", told(any_of=["47.2", "47.17", "47"]),
             [call("measure_distance", a="fountain", b="east gate")]),
    question("vague", "donde-bus-stop", "¿Dónde está the bus stop? coordinates please",
             told(all_of=["-30"]), [call("find_landmarks", query="bus stop")]),
    question("vague", "trees-count-story", "so tell me, how many trees has this campus got, all told?",
             told(any_of=["4", "four"]), [call("find_assets", category="tree")]),
    # erroneous
    question("erroneous", "fountain-gate-typos", "how far si the fountian from teh east gate?",
             told(any_of=["47.2", "47.17", "47"]), [call("measure_distance", a="fountain", b="east gate")]),
    question("erroneous", "lane-typos", "wich lane is teh ego car drivng in",
             told(any_of=["main_eastbound", "eastbound"]), [call("find_lanes", near="ego")]),
    question("erroneous", "trees-texty", "hw many trees r there",
             told(any_of=["4", "four"]), [call("find_assets", category="tree")]),
    question("erroneous", "nearest-tree-library", "whats the neerest tree to the libary entrence",
             told(any_of=["tree_1"]), [call("find_assets", category="tree", nearest_to="Library entrance")]),
    question("erroneous", "feet-stop-signal", "how many feet betwen the stop sign and the trafic signal on that "
             "corner?", told(any_of=["4.1", "4.06", "13", "13.3"]),
             [call("measure_distance", a="stop_sign_1", b="traffic_light_1")]),
    question("erroneous", "time-nonnative", "Which hour is it now in the scene, please to tell me?",
             told(any_of=["12:00", "noon", "midday", "12"]), [call("describe_environment")]),
    question("erroneous", "hindi-benches", "kitne benches hai campus mein? how many benchs",
             told(any_of=["1", "one", "bench_1"]), [call("find_assets", category="bench")]),
]


# --- addition ----------------------------------------------------------------------------------
ADDITION: list[Json] = [
    # direct
    case("addition", "direct", "pedestrian-bus-stop", "Add a pedestrian at the bus stop.",
         [status(), delta("pedestrian", 1), near("pedestrian", "bus stop", 6), guard("pedestrian")],
         [call("add_asset", category="pedestrian", location=at("bus stop"))]),
    case("addition", "direct", "two-cones-lot-b-entrance", "Add two traffic cones at the lot B entrance.",
         [status(), delta("traffic_cone", 2), near("traffic_cone", "parking lot B entrance", 8, require_all=True),
          guard("traffic_cone")],
         [call("add_asset", category="traffic_cone", count=2, location=at("parking lot B entrance"))]),
    case("addition", "direct", "red-suv-lot-a", "Add a red SUV in parking lot A.",
         [status(), delta("suv", 1), near("suv", "parking lot A", 1), looks(category="suv", colour="red", scope="added"),
          guard("suv")],
         [call("add_asset", category="suv", colour="red", location=at("parking lot A"))]),
    case("addition", "direct", "adjuster-motorcycle-ahead", "Reconstruct the scene with a motorcycle driving "
         "eastbound on Main Street about 20 m ahead of the claimant's car.",
         [status(), delta("motorcycle", 1), does("drive_lane", category="motorcycle", scope="added", lane="main_eastbound"),
          rel("in_front_of", "ego", category="motorcycle", scope="added", max_distance=35, tolerance_deg=20),
          guard("motorcycle")],
         [call("add_asset", category="motorcycle", location=at("ego", along_m=20),
               behaviour={"kind": "drive_lane", "lane": "main_eastbound"})]),
    case("addition", "direct", "dispatch-truck-jtekt", "Dispatch one box truck to the JTEKT building entrance.",
         [status(), delta("truck", 1), near("truck", "JTEKT building entrance", 10), guard("truck")],
         [call("add_asset", category="truck", location=at("JTEKT building entrance"))]),
    case("addition", "direct", "bus-and-waiting-people", "Add a bus at the bus stop and two pedestrians waiting "
         "next to it.",
         [status(), delta("bus", 1), delta("pedestrian", 2), near("bus", "bus stop", 10),
          near("pedestrian", "bus stop", 12, require_all=True), guard("bus", "pedestrian")],
         [call("add_asset", category="bus", location=at("bus stop")),
          call("add_asset", category="pedestrian", count=2, location=at("bus stop"))], tags=COMPOUND),
    impossible("addition", "direct", "ambulance", "Add an ambulance at the Student Union entrance.",
               [call("add_asset", category="ambulance", location=at("Student Union entrance"))]),
    # indirect
    case("addition", "indirect", "could-we-get-a-bus", "could we get a bus waiting at the bus stop?",
         [status(), delta("bus", 1), near("bus", "bus stop", 10), guard("bus")],
         [call("add_asset", category="bus", location=at("bus stop"))]),
    case("addition", "indirect", "child-little-tree", "let's put a little tree by the big library building, ok? "
         "right by its front door, so people get some shade.",
         [status(), delta("tree", 1), near("tree", "Library entrance", 10), guard("tree")],
         [call("add_asset", category="tree", location=at("Library entrance"))]),
    case("addition", "indirect", "adjuster-grey-sedan", "For the reconstruction we need vehicle 2, a grey sedan, "
         "parked at the lot A entrance at the time of the incident.",
         [status(), delta("passenger_car", 1), near("passenger_car", "parking lot A entrance", 10),
          looks(category="passenger_car", colour="grey", scope="added"),
          does("parked", category="passenger_car", scope="added"), guard("passenger_car")],
         [call("add_asset", category="passenger_car", colour="grey", location=at("parking lot A entrance"))]),
    case("addition", "indirect", "commentary-cyclist-north", "And here comes a cyclist, pedalling hard up Campus "
         "Drive, heading north!",
         [status(), delta("bicycle", 1), does("drive_lane", category="bicycle", scope="added", lane="campus_northbound"),
          guard("bicycle")],
         [call("add_asset", category="bicycle", behaviour={"kind": "drive_lane", "lane": "campus_northbound"})]),
    case("addition", "indirect", "any-chance-people-engineering", "any chance we could have a couple of people "
         "standing outside Engineering Hall?",
         [status(), delta("pedestrian", 2), near("pedestrian", "Engineering Hall entrance", 12, require_all=True),
          guard("pedestrian")],
         [call("add_asset", category="pedestrian", count=2, location=at("Engineering Hall entrance"))]),
    case("addition", "indirect", "formal-hydrant-union", "It is requested that one fire hydrant be installed in "
         "the vicinity of the Student Union entrance.",
         [status(), delta("fire_hydrant", 1), near("fire_hydrant", "Student Union entrance", 12), guard("fire_hydrant")],
         [call("add_asset", category="fire_hydrant", location=at("Student Union entrance"))]),
    case("addition", "indirect", "spanish-blue-car", "Necesito un coche azul - a blue car, parked in lot B, "
         "por favor.",
         [status(), delta(["passenger_car", "suv"], 1), near(["passenger_car", "suv"], "parking lot B", 1),
          looks(category=["passenger_car", "suv"], colour="blue", scope="added"), guard("passenger_car", "suv")],
         [call("add_asset", category="passenger_car", colour="blue", location=at("parking lot B"))]),
    case("addition", "indirect", "adjuster-cyclist-and-rain", "At the time of the incident it was raining and "
         "a cyclist was waiting at the west crosswalk. Reconstruct the scene with both.",
         [status(), delta("bicycle", 1), near("bicycle", "west crosswalk", 8), env(weather=["rain"]),
          guard("bicycle", environment=True)],
         [call("add_asset", category="bicycle", location=at("west crosswalk")), call("set_weather", kind="rain")],
         tags=COMPOUND),
    # vague
    case("addition", "vague", "folks-at-bus-stop", "the bus stop looks deserted. put some folks there",
         [status(), delta("pedestrian", 2, 8), near("pedestrian", "bus stop", 12, require_all=True), guard("pedestrian")],
         [call("add_asset", category="pedestrian", count=3, location=at("bus stop"))]),
    case("addition", "vague", "fragment-cones-lot-b", "cones -> lot B entrance, 4",
         [status(), delta("traffic_cone", 4), near("traffic_cone", "parking lot B entrance", 10, require_all=True),
          guard("traffic_cone")],
         [call("add_asset", category="traffic_cone", count=4, location=at("parking lot B entrance"))]),
    case("addition", "vague", "handful-bins-sidewalk", "a handful of bins along the sidewalk by the library",
         [status(), delta("trash_bin", 3, 7), near("trash_bin", "Library entrance", 22, require_all=True),
          on(["sidewalk"], category="trash_bin", scope="added"), guard("trash_bin")],
         [call("add_asset", category="trash_bin", count=5, location=at("Library entrance", "on_sidewalk"))]),
    case("addition", "vague", "stage-two-units-lot-a", "stage two units at lot A, ETA asap",
         [status(), delta(VEHICLES, 2), near(VEHICLES, "parking lot A", 1, require_all=True), guard(*VEHICLES)],
         [call("add_asset", category="truck", count=2, location=at("parking lot A"))]),
    case("addition", "vague", "sarcastic-no-soul", "wow, what a lively campus, not a single soul walking about. "
         "fix it",
         [status(), delta("pedestrian", 1, 30), guard("pedestrian")],
         [call("add_asset", category="pedestrian", count=4, location=at("main intersection"))]),
    case("addition", "vague", "stones-throw-bench", "a bench, a stone's throw from the fountain",
         [status(), delta("bench", 1), near("bench", "fountain", 15), guard("bench")],
         [call("add_asset", category="bench", location=at("fountain"))]),
    case("addition", "vague", "cone-by-bin-chain", "stick a cone beside the bin that's next to the bench by the "
         "bus stop",
         [status(), delta("traffic_cone", 1), near("traffic_cone", "trash_bin_1", 5), guard("traffic_cone")],
         [call("add_asset", category="traffic_cone", location=at("trash_bin_1", "next_to"))]),
    impossible("addition", "vague", "ferris-wheel", "put something fun over by the quad, like a ferris wheel",
               [call("add_asset", category="ferris_wheel", location=at("fountain"))]),
    # erroneous
    case("addition", "erroneous", "pedestrain-north", "ad a pedestrain at the norht crosswalk",
         [status(), delta("pedestrian", 1), near("pedestrian", "north crosswalk", 8), guard("pedestrian")],
         [call("add_asset", category="pedestrian", location=at("north crosswalk"))]),
    case("addition", "erroneous", "tree-trees-fountain", "put tree trees near teh fountian",
         [status(), delta("tree", 3), near("tree", "fountain", 15, require_all=True), guard("tree")],
         [call("add_asset", category="tree", count=3, location=at("fountain"))]),
    case("addition", "erroneous", "motorbikes-lot-b", "plz add 2 motorbikes in parkign lot B",
         [status(), delta("motorcycle", 2), near("motorcycle", "parking lot B", 1, require_all=True), guard("motorcycle")],
         [call("add_asset", category="motorcycle", count=2, location=at("parking lot B"))]),
    case("addition", "erroneous", "bollard-infront-librery", "Add one bollard infront of the librery entrance",
         [status(), delta("bollard", 1), near("bollard", "Library entrance", 6),
          rel("in_front_of", "Library entrance", category="bollard", scope="added", max_distance=8), guard("bollard")],
         [call("add_asset", category="bollard", location=at("Library entrance", "in_front_of"))]),
    case("addition", "erroneous", "cars-westbund-driving", "stage 2 cars on teh westbund lane, drivng",
         [status(), delta("passenger_car", 2),
          does("drive_lane", category="passenger_car", scope="added", lane="main_westbound", require_all=True),
          guard("passenger_car")],
         [call("add_asset", category="passenger_car", count=2, behaviour={"kind": "drive_lane", "lane": "main_westbound"})]),
    case("addition", "erroneous", "nonnative-ped-sign", "Add for me one pedestrian sign close the west crosswalk",
         [status(), delta("pedestrian_sign", 1), near("pedestrian_sign", "west crosswalk", 10), guard("pedestrian_sign")],
         [call("add_asset", category="pedestrian_sign", location=at("west crosswalk", "on_sidewalk"))]),
    case("addition", "erroneous", "dispatch-truck-and-pull-suv", "dispach a truck to the JTEKT drop-off and pul "
         "the suv from lot b",
         [status(), delta("truck", 1), near("truck", "JTEKT building entrance", 12), gone("suv_1"),
          kept("passenger_car_1", "passenger_car_2"), guard("truck", assets=["suv_1"])],
         [call("add_asset", category="truck", location=at("JTEKT building entrance")),
          call("remove_assets", assets=["suv_1"])], tags=COMPOUND),
    impossible("addition", "erroneous", "three-dozen-scooters", "dispach three dozen scooters too lot A",
               [call("add_asset", category="motorcycle", count=36, location=at("parking lot A"))]),
    impossible("addition", "erroneous", "dog-crossing", "recontruct w/ a dog crosing at the west crosswalk, as "
               "per the claimant's statment",
               [call("add_asset", category="dog", location=at("west crosswalk"))]),
]


# --- removal -----------------------------------------------------------------------------------
ALL_STREET_LIGHTS = [f"street_light_{n}" for n in range(1, 13)]
CARS_IN_LOT_B = ["passenger_car", "suv"]

REMOVAL: list[Json] = [
    # direct
    case("removal", "direct", "trash-bin", "Remove the trash bin.",
         [status(), gone("trash_bin_1"), guard("trash_bin")],
         [call("remove_assets", assets=["trash_bin_1"])]),
    case("removal", "direct", "suv-lot-b", "Remove the SUV from lot B.",
         [status(), gone("suv_1"), kept("passenger_car_1", "passenger_car_2"), guard(assets=["suv_1"])],
         [call("remove_assets", assets=["suv_1"])]),
    case("removal", "direct", "south-street-lights", "Delete all the street lights on the south side of Main Street.",
         [status(), gone(*SOUTH_STREET_LIGHTS), kept(*NORTH_STREET_LIGHTS), guard(assets=SOUTH_STREET_LIGHTS)],
         [call("remove_assets", assets=SOUTH_STREET_LIGHTS)]),
    case("removal", "direct", "adjuster-vehicle-3", "Remove vehicle 3 - the car parked furthest east in lot B - "
         "from the reconstruction.",
         [status(), gone("passenger_car_2"), kept("passenger_car_1", "suv_1"), guard(assets=["passenger_car_2"])],
         [call("remove_assets", assets=["passenger_car_2"])]),
    case("removal", "direct", "dispatch-pull-sedans", "Pull both sedans from lot B; the SUV stays.",
         [status(), gone("passenger_car_1", "passenger_car_2"), kept("suv_1"),
          guard(assets=["passenger_car_1", "passenger_car_2"])],
         [call("remove_assets", category="passenger_car")]),
    case("removal", "direct", "bench-and-bin", "Remove the bench and the bin by the bus stop.",
         [status(), gone("bench_1", "trash_bin_1"), guard(assets=["bench_1", "trash_bin_1"])],
         [call("remove_assets", assets=["bench_1"]), call("remove_assets", assets=["trash_bin_1"])], tags=COMPOUND),
    impossible("removal", "direct", "fountain", "Remove the fountain from the quad.",
               [call("remove_assets", assets=["fountain"])]),
    # indirect
    case("removal", "indirect", "sarcastic-hydrant", "ugh, who put a fire hydrant on the pavement right by the "
         "crossroads. get rid of it",
         [status(), gone("fire_hydrant_1"), guard("fire_hydrant")],
         [call("remove_assets", assets=["fire_hydrant_1"])]),
    case("removal", "indirect", "could-we-lose-stop-sign", "could we lose the stop sign by the west crosswalk?",
         [status(), gone("stop_sign_1"), guard("stop_sign")],
         [call("remove_assets", assets=["stop_sign_1"])]),
    case("removal", "indirect", "pursuant-lamp-bus-stop", "Pursuant to the lighting review, the street lamp "
         "closest to the bus stop shall be removed.",
         [status(), gone("street_light_4"), kept(*[s for s in ALL_STREET_LIGHTS if s != "street_light_4"]),
          guard(assets=["street_light_4"])],
         [call("remove_assets", category="street_light", near="bus stop", count=1)]),
    case("removal", "indirect", "child-bye-tree", "see that tree way up past parking lot A, at the top? let's say "
         "bye-bye to it, ok?",
         [status(), gone("tree_4"), kept("tree_1", "tree_2", "tree_3"), guard(assets=["tree_4"])],
         [call("remove_assets", assets=["tree_4"])]),
    case("removal", "indirect", "take-those-cones-away", "actually, take those cones away again",
         [status(), count("traffic_cone", 0, 0), guard("traffic_cone")],
         [call("remove_assets", category="traffic_cone")],
         setup=[turn("put four cones at the lot A entrance", [call("add_asset", category="traffic_cone", count=4,
                location=at("parking lot A entrance"))], planned=True)]),
    case("removal", "indirect", "story-bench-vanishes", "And the bench by the bus stop... vanishes into thin air! "
         "Poof!",
         [status(), gone("bench_1"), guard("bench")],
         [call("remove_assets", assets=["bench_1"])]),
    case("removal", "indirect", "pole-red-green-lights", "the tall pole with the red, amber and green lamps on the "
         "corner by the stop sign - take that one out",
         [status(), gone("traffic_light_1"), kept("traffic_light_2"), guard(assets=["traffic_light_1"])],
         [call("remove_assets", assets=["traffic_light_1"])]),
    case("removal", "indirect", "french-trees-fountain", "Enlevez the trees près de la fountain, s'il vous plaît "
         "- both of them",
         [status(), gone("tree_2", "tree_3"), kept("tree_1", "tree_4"), guard(assets=["tree_2", "tree_3"])],
         [call("remove_assets", assets=["tree_2", "tree_3"])]),
    # vague
    case("removal", "vague", "hydrant-bye", "hydrant. bye.",
         [status(), gone("fire_hydrant_1"), guard("fire_hydrant")],
         [call("remove_assets", category="fire_hydrant")]),
    case("removal", "vague", "clear-parked-cars", "clear out the parked cars",
         [status(), gone(*PARKED_IN_LOT_B), guard(*CARS_IN_LOT_B)],
         [call("remove_assets", assets=PARKED_IN_LOT_B)]),
    case("removal", "vague", "couple-north-lamps", "get rid of a couple of the street lamps on the north side",
         [status(), delta("street_light", -2), kept(*SOUTH_STREET_LIGHTS), guard("street_light")],
         [call("remove_assets", assets=["street_light_1", "street_light_3"])]),
    case("removal", "vague", "half-the-trees", "half the trees have to go",
         [status(), delta("tree", -2), guard("tree")],
         [call("remove_assets", category="tree", count=2)]),
    case("removal", "vague", "all-but-one-lot-b", "all but one of the cars in lot B can go",
         [status(), delta(CARS_IN_LOT_B, -2), guard(*CARS_IN_LOT_B)],
         [call("remove_assets", assets=["passenger_car_1", "suv_1"])]),
    case("removal", "vague", "too-many-cones-keep-one", "that's way too many cones. keep just the one",
         [status(), count("traffic_cone", 1, 1), guard("traffic_cone")],
         [call("remove_assets", category="traffic_cone", count=4)],
         setup=[turn("five cones at the lot B entrance", [call("add_asset", category="traffic_cone", count=5,
                location=at("parking lot B entrance"))])]),
    case("removal", "vague", "dispatch-clear-road", "clear the road of anything that shouldn't be on it - not "
         "the ego, obviously",
         [status(), count("cement_rubble", 0, 0), count("traffic_cone", 0, 0), guard("cement_rubble", "traffic_cone")],
         [call("remove_assets", category="cement_rubble"), call("remove_assets", category="traffic_cone")],
         setup=[turn("some rubble and two cones in the eastbound lane near the library",
                     [call("add_asset", category="cement_rubble", location=at("Library entrance", "in_lane")),
                      call("add_asset", category="traffic_cone", count=2, location=at("Library entrance", "in_lane"))])]),
    case("removal", "vague", "lose-both-sarcastic", "ugh, a bin AND a hydrant cluttering the pavements. lose "
         "both",
         [status(), gone("trash_bin_1", "fire_hydrant_1"), guard(assets=["trash_bin_1", "fire_hydrant_1"])],
         [call("remove_assets", assets=["trash_bin_1"]), call("remove_assets", assets=["fire_hydrant_1"])],
         tags=COMPOUND),
    impossible("removal", "vague", "roundabout", "the roundabout's ugly, lose it",
               [call("remove_assets", assets=["roundabout"])]),
    # erroneous
    case("removal", "erroneous", "remvoe-benhc", "remvoe the benhc",
         [status(), gone("bench_1"), guard("bench")],
         [call("remove_assets", assets=["bench_1"])]),
    case("removal", "erroneous", "both-trafic-lights", "delet the trafic lights pls, both",
         [status(), gone("traffic_light_1", "traffic_light_2"), guard("traffic_light")],
         [call("remove_assets", category="traffic_light")]),
    case("removal", "erroneous", "bin-next-bus-stop", "take away teh bin next the bus stop",
         [status(), gone("trash_bin_1"), guard("trash_bin")],
         [call("remove_assets", assets=["trash_bin_1"])]),
    case("removal", "erroneous", "all-lights-except-two", "remove al the strret lights exept the two nearest "
         "the ego",
         [status(), gone(*[s for s in ALL_STREET_LIGHTS if s not in ("street_light_2", "street_light_3")]),
          kept("street_light_2", "street_light_3"), guard("street_light")],
         [call("remove_assets", assets=[s for s in ALL_STREET_LIGHTS if s not in ("street_light_2", "street_light_3")])]),
    case("removal", "erroneous", "get-ride-suv", "get ride of the suv in parking lot b",
         [status(), gone("suv_1"), kept("passenger_car_1", "passenger_car_2"), guard("suv")],
         [call("remove_assets", assets=["suv_1"])]),
    case("removal", "erroneous", "nonnative-tree-east-gate", "Remove please the tree which stands most near to "
         "the east gate.",
         [status(), gone("tree_3"), kept("tree_1", "tree_2", "tree_4"), guard(assets=["tree_3"])],
         [call("remove_assets", category="tree", near="east gate", count=1)]),
    impossible("removal", "erroneous", "lane-markings", "remvoe the lane markings on main stret, they're "
               "destracting",
               [call("remove_assets", assets=["lane_markings"])]),
]


# --- positioning: put an existing asset somewhere -----------------------------------------------
POSITIONING: list[Json] = [
    # direct
    case("positioning", "direct", "bench-fountain", "Put the bench next to the fountain.",
         [status(), near(None, "fountain", 6, asset="bench_1"), guard(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=at("fountain"))]),
    case("positioning", "direct", "suv-jtekt", "Place the SUV at the JTEKT building entrance.",
         [status(), near(None, "JTEKT building entrance", 8, asset="suv_1"), guard(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=at("JTEKT building entrance"))]),
    case("positioning", "direct", "bin-union", "Put the trash bin at the Student Union entrance.",
         [status(), near(None, "Student Union entrance", 6, asset="trash_bin_1"), guard(assets=["trash_bin_1"])],
         [call("place_asset", asset="trash_bin_1", location=at("Student Union entrance"))]),
    case("positioning", "direct", "ego-westbound-east-gate", "Put the ego in the westbound lane near the east gate.",
         [status(), near(None, "east gate", 15, asset="ego"), in_lane("main_westbound", aligned=True, asset="ego"),
          guard(assets=["ego"])],
         [call("place_asset", asset="ego", location=at("east gate", "in_lane", lane="main_westbound"))]),
    case("positioning", "direct", "adjuster-before-crosswalk", "Position the claimant's car in the eastbound lane, "
         "just short of the west crosswalk.",
         [status(), near_point(None, -19.0, -1.75, 6, asset="ego"), in_lane("main_eastbound", aligned=True, asset="ego"),
          guard(assets=["ego"])],
         [call("place_asset", asset="ego", location=point(-19.0, -1.75))]),
    case("positioning", "direct", "dispatch-bus-to-stop", "Reposition the bus to the bus stop.",
         [status(), near(None, "bus stop", 10, asset="bus_1"), guard(assets=["bus_1"])],
         [call("place_asset", asset="bus_1", location=at("bus stop"))],
         setup=[turn("park a bus in lot B", [call("add_asset", category="bus", location=at("parking lot B"))])]),
    impossible("positioning", "direct", "suv-off-map", "Put the SUV at x = 150, y = 20.",
               [call("place_asset", asset="suv_1", location=point(150.0, 20.0))]),
    # indirect
    case("positioning", "indirect", "could-bench-library", "could the bench go over by the Library entrance "
         "instead?",
         [status(), near(None, "Library entrance", 6, asset="bench_1"), guard(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=at("Library entrance"))]),
    case("positioning", "indirect", "adjuster-stopped-lot-b", "At the time of the incident the claimant's car was "
         "stopped at the lot B entrance. Reconstruct that.",
         [status(), near(None, "parking lot B entrance", 8, asset="ego"), does("parked", asset="ego"),
          guard(assets=["ego"])],
         [call("place_asset", asset="ego", location=at("parking lot B entrance")),
          call("set_behaviour", asset="ego", behaviour={"kind": "parked"})], tags=COMPOUND),
    case("positioning", "indirect", "dispatch-truck-jtekt", "Unit 1 (the truck) - send it over to the JTEKT "
         "drop-off, please.",
         [status(), near(None, "JTEKT building entrance", 12, asset="truck_1"), guard(assets=["truck_1"])],
         [call("place_asset", asset="truck_1", location=at("JTEKT building entrance"))],
         setup=[turn("a truck in lot A", [call("add_asset", category="truck", location=at("parking lot A"))])]),
    case("positioning", "indirect", "child-lonely-bin", "now, the bin looks lonely, so let's take it over to sit "
         "right next to the bench, ok?",
         [status(), near(None, "bench_1", 3.5, asset="trash_bin_1"), guard(assets=["trash_bin_1"])],
         [call("place_asset", asset="trash_bin_1", location=at("bench_1", "next_to"))]),
    case("positioning", "indirect", "story-hero-main-gate", "Our hero, the ego car, takes up its position right "
         "at the main gate, ready to roll east.",
         [status(), near(None, "main gate", 12, asset="ego"), does("drive_lane", asset="ego", lane="main_eastbound"),
          guard(assets=["ego"])],
         [call("place_asset", asset="ego", location=at("main gate"))]),
    case("positioning", "indirect", "formal-hydrant-engineering", "The party shall ensure that the fire hydrant is "
         "relocated to the sidewalk in front of Engineering Hall.",
         [status(), near(None, "Engineering Hall entrance", 11, asset="fire_hydrant_1"),
          on(["sidewalk"], asset="fire_hydrant_1"), guard(assets=["fire_hydrant_1"])],
         [call("place_asset", asset="fire_hydrant_1", location=at("Engineering Hall entrance", "on_sidewalk"))]),
    case("positioning", "indirect", "boxy-car-union", "Take the tall boxy car out of the car park and leave it "
         "at the Student Union doors.",
         [status(), near(None, "Student Union entrance", 8, asset="suv_1"), guard(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=at("Student Union entrance"))]),
    case("positioning", "indirect", "story-gate-and-rain", "The ego rolls up to the east gate... and just then it "
         "starts to pour.",
         [status(), near(None, "east gate", 15, asset="ego"), env(weather=["rain"], intensity_min=0.6),
          guard(assets=["ego"], environment=True)],
         [call("place_asset", asset="ego", location=at("east gate", "in_lane", lane="main_eastbound")),
          call("set_weather", kind="rain", intensity=0.8)], tags=COMPOUND),
    impossible("positioning", "indirect", "ego-inside-union", "Is it possible to park the claimant's car inside "
               "the Student Union, for the photo?",
               [call("place_asset", asset="ego", location=point(42.0, -63.0))]),
    # vague
    case("positioning", "vague", "bench-somewhere-shady", "the bench should be somewhere shady",
         [status(), moved("bench_1", min_distance=1.0), guard(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=at("tree_2", "next_to"))],
         alternatives=[[near(None, t, 5, asset="bench_1")] for t in ("tree_1", "tree_2", "tree_3", "tree_4")]),
    case("positioning", "vague", "bin-off-sidewalk", "the bin's in everyone's way, shove it somewhere off the "
         "sidewalk",
         [status(), on(["ground", "paved"], asset="trash_bin_1"), near(None, "bus stop", 20, asset="trash_bin_1"),
          guard(assets=["trash_bin_1"])],
         [call("place_asset", asset="trash_bin_1", location=point(-33.5, -9.0))]),
    case("positioning", "vague", "half-block-east-gate", "scoot the SUV to about half a block from the east gate",
         [status(), near(None, "east gate", 60, asset="suv_1"), guard(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=at("east gate"))]),
    case("positioning", "vague", "pedestrian-there-instead", "hmm, actually put them at the north crosswalk "
         "instead",
         [status(), count("pedestrian", 1, 1), near("pedestrian", "north crosswalk", 8, scope="all", require_all=True),
          guard("pedestrian")],
         [call("place_asset", asset="pedestrian_1", location=at("north crosswalk"))],
         setup=[turn("add a pedestrian at the bus stop", [call("add_asset", category="pedestrian",
                location=at("bus stop"))], planned=True)]),
    case("positioning", "vague", "van-thing-lot-a", "that van thing from before - stick it by lot A",
         [status(), near(None, "parking lot A", 6, asset="truck_1"), guard(assets=["truck_1"])],
         [call("place_asset", asset="truck_1", location=at("parking lot A"))],
         setup=[turn("put a delivery van at the Student Union", [call("add_asset", category="truck",
                location=at("Student Union entrance"))])]),
    case("positioning", "vague", "sarcastic-ego-back-on-road", "brilliant, the ego's parked in a car park. put "
         "it back on the road where it belongs",
         [status(), in_lane(asset="ego", aligned=True), guard(assets=["ego"])],
         [call("place_asset", asset="ego", location=at("parking lot B entrance", "in_lane", lane="main_eastbound"))],
         setup=[turn("park the ego in lot B", [call("place_asset", asset="ego", location=at("parking lot B"))])]),
    case("positioning", "vague", "emoji-bench-fountain", "🪑 -> ⛲",
         [status(), near(None, "fountain", 6, asset="bench_1"), guard(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=at("fountain"))]),
    case("positioning", "vague", "bench-and-bin-fountain", "move the bench over to the fountain and the bin "
         "somewhere next to it",
         [status(), near(None, "fountain", 6, asset="bench_1"), near(None, "bench_1", 4, asset="trash_bin_1"),
          guard(assets=["bench_1", "trash_bin_1"])],
         [call("place_asset", asset="bench_1", location=at("fountain")),
          call("place_asset", asset="trash_bin_1", location=at("bench_1", "next_to"))], tags=COMPOUND),
    # erroneous
    case("positioning", "erroneous", "bench-infront-jtekt", "put teh bench infront of the JTEKT entrence",
         [status(), near(None, "JTEKT building entrance", 6, asset="bench_1"),
          rel("in_front_of", "JTEKT building entrance", asset="bench_1", max_distance=8), guard(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=at("JTEKT building entrance", "in_front_of"))]),
    case("positioning", "erroneous", "hydrant-stop-sing", "place hydrant next too the stop sing",
         [status(), near(None, "stop_sign_1", 4, asset="fire_hydrant_1"), guard(assets=["fire_hydrant_1"])],
         [call("place_asset", asset="fire_hydrant_1", location=at("stop_sign_1", "next_to"))]),
    case("positioning", "erroneous", "positon-suv-lot-a", "Positon the SUV at parking lot A plz",
         [status(), near(None, "parking lot A", 1, asset="suv_1"), guard(assets=["suv_1"])],
         [call("place_asset", asset="suv_1", location=at("parking lot A"))]),
    case("positioning", "erroneous", "ego-campus-north", "put the ego car on campus drive goign north near the "
         "intersecton",
         [status(), in_lane("campus_northbound", aligned=True, asset="ego"), near(None, "main intersection", 25, asset="ego"),
          guard(assets=["ego"])],
         [call("place_asset", asset="ego", location=at("main intersection", "in_lane", lane="campus_northbound"))]),
    case("positioning", "erroneous", "nonnative-bin-library", "The bin, put it to the front of library please.",
         [status(), near(None, "Library entrance", 6, asset="trash_bin_1"), guard(assets=["trash_bin_1"])],
         [call("place_asset", asset="trash_bin_1", location=at("Library entrance"))]),
    case("positioning", "erroneous", "hindi-bench-fountain", "bench ko fountain ke paas rakh do, jaldi please",
         [status(), near(None, "fountain", 6, asset="bench_1"), guard(assets=["bench_1"])],
         [call("place_asset", asset="bench_1", location=at("fountain"))]),
    impossible("positioning", "erroneous", "suv-300-yards", "put the suv 300 yards north of the fountian",
               [call("place_asset", asset="suv_1", location=point(75.0, 314.0))]),
]


# --- moving: shift, turn, behaviours and timed manoeuvres ---------------------------------------
TRUCK_IN_LOT_A = turn("a box truck in lot A, facing east",
                      [call("add_asset", category="truck", location=point(-95.0, 25.0), yaw_deg=0)])
PEDESTRIAN_AT_BUS_STOP = turn("someone standing at the bus stop",
                              [call("add_asset", category="pedestrian", location=at("bus stop"))])

MOVING: list[Json] = [
    # direct
    case("moving", "direct", "suv-forward-5", "Move the SUV 5 metres forward.",
         [status(), moved("suv_1", min_distance=4.0, max_distance=6.0, direction="forward"), guard(assets=["suv_1"])],
         [call("move_asset", asset="suv_1", forward=5)]),
    case("moving", "direct", "turn-bench-around", "Turn the bench around.",
         [status(), moved("bench_1", max_distance=1.0, turn_min_deg=150), guard(assets=["bench_1"])],
         [call("move_asset", asset="bench_1", turn_deg=180)]),
    case("moving", "direct", "ego-westbound", "Make the ego drive in the westbound lane.",
         [status(), does("drive_lane", asset="ego", lane="main_westbound"), guard(assets=["ego"])],
         [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_westbound"})]),
    case("moving", "direct", "suv-circles-lot-b", "Make the SUV drive in circles in lot B, radius 5 m.",
         [status(), does("circle", asset="suv_1", radius_min=4.5, radius_max=5.5, centre_near="parking lot B",
                         centre_within=25), guard(assets=["suv_1"])],
         [call("set_behaviour", asset="suv_1", behaviour={"kind": "circle", "radius": 5})]),
    case("moving", "direct", "adjuster-brakes-at-4s", "Vehicle 1 (the ego) brakes to a stop 4 seconds into the "
         "reconstruction.",
         [status(), sim(8, event("stop", "ego")), guard()],
         [call("add_manoeuvre", actor="ego", manoeuvre={"kind": "stop"}, at_time=4)]),
    case("moving", "direct", "truck-10m-east", "Move the truck 10 m east.",
         [status(), moved("truck_1", min_distance=9.0, max_distance=11.0, direction="forward"), guard(assets=["truck_1"])],
         [call("move_asset", asset="truck_1", east=10)], setup=[TRUCK_IN_LOT_A]),
    case("moving", "direct", "turn-and-forward", "Turn the bench around, then push it 2 m forward.",
         [status(), moved("bench_1", min_distance=1.5, max_distance=2.5, turn_min_deg=150),
          near_point(None, -24.0, -6.9, 0.8, asset="bench_1"), guard(assets=["bench_1"])],
         [call("move_asset", asset="bench_1", turn_deg=180), call("move_asset", asset="bench_1", forward=2)],
         tags=COMPOUND),
    impossible("moving", "direct", "reverse-250", "Reverse the ego 250 metres.",
               [call("add_manoeuvre", actor="ego", manoeuvre={"kind": "reverse", "distance": 250})]),
    # indirect
    case("moving", "indirect", "story-pedestrian-strides", "and now our pedestrian strides out across the west "
         "crosswalk!",
         [status(), does("cross_road", asset="pedestrian_1", crosses_lane="main_eastbound"),
          near(None, "west crosswalk", 8, asset="pedestrian_1"), guard(assets=["pedestrian_1"])],
         [call("set_behaviour", asset="pedestrian_1", behaviour={"kind": "cross_road"})],
         setup=[PEDESTRIAN_AT_BUS_STOP]),
    case("moving", "indirect", "is-it-possible-suv-eastbound", "is it possible to make the SUV drive along the "
         "eastbound lane?",
         [status(), does("drive_lane", asset="suv_1", lane="main_eastbound"), guard(assets=["suv_1"])],
         [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})]),
    case("moving", "indirect", "sarcastic-speed-up", "great, the ego's just crawling along. speed it up to like "
         "10 m/s, honestly",
         [status(), guard(assets=["ego"])],
         [call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 10})],
         alternatives=[[does("drive_lane", asset="ego", lane="main_eastbound", speed_min=9.5, speed_max=10.5)],
                       [sim(6, event("change_speed", "ego"))]]),
    case("moving", "indirect", "adjuster-backing-out", "At the time of the incident vehicle 2 (the SUV) was "
         "backing out of its bay. Reconstruct that: reverse it about 3 metres.",
         [status(), guard(assets=["suv_1"])],
         [call("add_manoeuvre", actor="suv_1", manoeuvre={"kind": "reverse", "distance": 3})],
         alternatives=[[moved("suv_1", min_distance=2.0, max_distance=4.0, direction="backward")],
                       [sim(6, event("reverse", "suv_1"))]]),
    case("moving", "indirect", "formal-hold-red", "It is requested that the traffic signal on the south-west "
         "corner of the crossroads be held at red for the entire run.",
         [status(), sim(20, {"kind": "stopped_before", "actor": "ego", "line": [-11.5, -1.75]}), guard()],
         [call("set_light_phases", light="traffic_light_1", phases=[{"state": "red", "duration": 600}])]),
    case("moving", "indirect", "child-robot-round", "see the little robot? let's make it go round and round in "
         "lot A, wheee!",
         [status(), does("circle", asset="ackermann_robot_1", centre_near="parking lot A", centre_within=20),
          guard(assets=["ackermann_robot_1"])],
         [call("set_behaviour", asset="ackermann_robot_1", behaviour={"kind": "circle"})],
         setup=[turn("put a little robot in lot A", [call("add_asset", category="ackermann_robot",
                location=at("parking lot A"))])]),
    case("moving", "indirect", "dispatch-reroute-north", "Unit 1 (the truck) is rerouting: have it take the "
         "northbound lane on Campus Drive.",
         [status(), does("drive_lane", asset="truck_1", lane="campus_northbound"), guard(assets=["truck_1"])],
         [call("set_behaviour", asset="truck_1", behaviour={"kind": "drive_lane", "lane": "campus_northbound"})],
         setup=[TRUCK_IN_LOT_A]),
    impossible("moving", "indirect", "suv-120-mph", "can the SUV drive down Main Street at 120 mph?",
               [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound",
                                                                "speed": 53.6})]),
    # vague
    case("moving", "vague", "bench-few-feet-east", "shuffle the bench a few feet east",
         [status(), near_point(None, -24.5, -6.9, 1.4, asset="bench_1"), moved("bench_1", min_distance=0.6),
          guard(assets=["bench_1"])],
         [call("move_asset", asset="bench_1", east=1.5)]),
    case("moving", "vague", "lot-b-cars-moving", "get the lot B cars moving",
         [status(), does("drive_lane", category=CARS_IN_LOT_B, scope="all", min_count=3), guard(*CARS_IN_LOT_B)],
         [call("set_behaviour", asset=a, behaviour={"kind": "drive_lane", "lane": lane})
          for a, lane in zip(PARKED_IN_LOT_B, ("main_eastbound", "main_westbound", "campus_southbound"), strict=True)]),
    case("moving", "vague", "nudge-ego-car-length", "nudge the ego up a car length",
         [status(), moved("ego", min_distance=3.5, max_distance=6.5, direction="forward"), guard(assets=["ego"])],
         [call("move_asset", asset="ego", forward=4.6)]),
    case("moving", "vague", "flip-wrong-way", "ugh, it's going the wrong way. flip it",
         [status(), does("drive_lane", asset="passenger_car_3", lane="main_eastbound"), guard(assets=["passenger_car_3"])],
         [call("set_behaviour", asset="passenger_car_3", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
         setup=[turn("add a car driving westbound", [call("add_asset", category="passenger_car",
                behaviour={"kind": "drive_lane", "lane": "main_westbound"})])]),
    case("moving", "vague", "dozen-yards-forward", "push the truck forward a dozen yards",
         [status(), moved("truck_1", min_distance=9.5, max_distance=12.5, direction="forward"), guard(assets=["truck_1"])],
         [call("move_asset", asset="truck_1", forward=11)], setup=[TRUCK_IN_LOT_A]),
    case("moving", "vague", "story-cyclist-sets-off", "and the cyclist sets off, pedalling east down Main Street!",
         [status(), does("drive_lane", category="bicycle", scope="all", lane="main_eastbound"), guard("bicycle")],
         [call("set_behaviour", asset="bicycle_1", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
         setup=[turn("put a bike at the main gate", [call("add_asset", category="bicycle", location=at("main gate"))],
                     planned=True)]),
    case("moving", "vague", "suv-west-ego-faster", "SUV out onto Main Street westbound, and the ego a bit quicker, "
         "8 m/s say",
         [status(), does("drive_lane", asset="suv_1", lane="main_westbound"),
          does("drive_lane", asset="ego", speed_min=7.5, speed_max=8.5), guard(assets=["suv_1", "ego"])],
         [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_westbound"}),
          call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "lane": "main_eastbound", "speed": 8})],
         tags=COMPOUND),
    impossible("moving", "vague", "bend-main-street", "make Main Street curve up a bit north around the library",
               [call("move_asset", asset="main_eastbound", north=5)]),
    # erroneous
    case("moving", "erroneous", "suv-bakwards", "mvoe the suv 3 meter bakwards",
         [status(), moved("suv_1", min_distance=2.0, max_distance=4.0, direction="backward"), guard(assets=["suv_1"])],
         [call("move_asset", asset="suv_1", forward=-3)]),
    case("moving", "erroneous", "bench-90-degres", "turn teh bench 90 degres",
         [status(), moved("bench_1", max_distance=1.0, turn_min_deg=80, turn_max_deg=100), guard(assets=["bench_1"])],
         [call("move_asset", asset="bench_1", turn_deg=90)]),
    case("moving", "erroneous", "ego-stopp-5s", "make the ego stopp 5 secnds in",
         [status(), sim(9, event("stop", "ego")), guard()],
         [call("add_manoeuvre", actor="ego", manoeuvre={"kind": "stop"}, at_time=5)]),
    case("moving", "erroneous", "pedestrain-jaywalk", "pedestrain at bus stop shud jaywalk infront of ego",
         [status(), does("jaywalk", asset="pedestrian_1", crosses_lane="main_eastbound"), guard(assets=["pedestrian_1"])],
         [call("set_behaviour", asset="pedestrian_1", behaviour={"kind": "jaywalk"})],
         setup=[PEDESTRIAN_AT_BUS_STOP]),
    case("moving", "erroneous", "nonnative-suv-westbound", "The SUV, make it go to drive on westbound lane.",
         [status(), does("drive_lane", asset="suv_1", lane="main_westbound"), guard(assets=["suv_1"])],
         [call("set_behaviour", asset="suv_1", behaviour={"kind": "drive_lane", "lane": "main_westbound"})]),
    case("moving", "erroneous", "hydrent-2m-nort", "shift the hydrent 2 m nort",
         [status(), moved("fire_hydrant_1", min_distance=1.5, max_distance=2.5, direction="left"),
          guard(assets=["fire_hydrant_1"])],
         [call("move_asset", asset="fire_hydrant_1", north=2)]),
    case("moving", "erroneous", "spanish-red-car", "el coche rojo - muévelo 4 metros adelante porfa",
         [status(), moved("passenger_car_1", min_distance=3.0, max_distance=5.0, direction="forward"),
          guard(assets=["passenger_car_1"])],
         [call("move_asset", asset="passenger_car_1", forward=4)],
         setup=[turn("paint the first car in lot B red", [call("set_asset_appearance", assets=["passenger_car_1"],
                                                               colour="red")])]),
    impossible("moving", "erroneous", "bench-drve-cirlce", "make the bench drve in a cirlce",
               [call("set_behaviour", asset="bench_1", behaviour={"kind": "circle"})]),
]


# --- arrangement: several new assets laid out together -------------------------------------------
ARRANGEMENT: list[Json] = [
    # direct
    case("arrangement", "direct", "five-cones-lot-b-entrance", "Put five cones in a line at the lot B entrance.",
         [status(), delta("traffic_cone", 5), shaped("line", "traffic_cone", min_count=5),
          near("traffic_cone", "parking lot B entrance", 10, require_all=True), guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5,
               location=at("parking lot B entrance"))]),
    case("arrangement", "direct", "benches-ring-fountain", "Arrange six benches in a ring around the fountain, "
         "about 5 metres out.",
         [status(), delta("bench", 6), shaped("ring", "bench", around="fountain", min_count=6, tolerance=1.5),
          near("bench", "fountain", 7, require_all=True), guard("bench")],
         [call("arrange_assets", categories=["bench"], shape="ring", count=6, radius=5, location=at("fountain"))]),
    case("arrangement", "direct", "four-cars-row-lot-a", "Line up four cars side by side in parking lot A.",
         [status(), delta("passenger_car", 4), shaped("line", "passenger_car", min_count=4),
          near("passenger_car", "parking lot A", 1, require_all=True), guard("passenger_car")],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4,
               location=at("parking lot A"))]),
    case("arrangement", "direct", "cones-lane-edge-library", "Put a row of 6 cones along the edge of the eastbound "
         "lane by the Library.",
         [status(), delta("traffic_cone", 6), in_lane("main_eastbound", category="traffic_cone", scope="added"),
          shaped("line", "traffic_cone", min_count=6), near("traffic_cone", "Library", 20, require_all=True),
          guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=6,
               location=at("Library entrance", lane="main_eastbound"))]),
    case("arrangement", "direct", "adjuster-debris-line", "Reconstruct the debris field: three piles of rubble in "
         "a line across the eastbound lane, 20 m ahead of the claimant's car.",
         [status(), delta("cement_rubble", 3), shaped("line", "cement_rubble", min_count=3),
          rel("in_front_of", "ego", category="cement_rubble", scope="added", max_distance=30, tolerance_deg=20,
              require_all=True),
          in_lane("main_eastbound", category="cement_rubble", scope="added", require_all=False), guard("cement_rubble")],
         [call("arrange_assets", categories=["cement_rubble"], shape="line", count=3,
               location=at("ego", "in_front_of", distance=20))]),
    case("arrangement", "direct", "dispatch-truck-row-lot-b", "Stage a row of three trucks side by side in lot B.",
         [status(), delta("truck", 3), shaped("line", "truck", min_count=3), near("truck", "parking lot B", 1, require_all=True),
          guard("truck")],
         [call("arrange_assets", categories=["truck"], shape="parking_row", count=3, location=at("parking lot B"))]),
    case("arrangement", "direct", "cones-across-lot-a-and-night", "Line five cones across the lot A entrance and "
         "make it night.",
         [status(), delta("traffic_cone", 5), shaped("line", "traffic_cone", min_count=5),
          near("traffic_cone", "parking lot A entrance", 10, require_all=True), env(night=True),
          guard("traffic_cone", environment=True)],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5,
               location=at("parking lot A entrance")), call("set_time_of_day", time="night")], tags=COMPOUND),
    impossible("arrangement", "direct", "two-fifty-cones", "Arrange two hundred and fifty cones in a ring around the "
               "crossroads.",
               [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=250,
                     location=at("main intersection"))]),
    # indirect
    case("arrangement", "indirect", "could-we-ring-rubble", "could we get a ring of cones around that rubble?",
         [status(), delta("traffic_cone", 4, 20), shaped("ring", "traffic_cone", around="cement_rubble_1", min_count=4),
          guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=6, location=at("cement_rubble_1"))],
         setup=[turn("drop some rubble in the middle of the crossroads",
                     [call("add_asset", category="cement_rubble", location=point(0.0, 0.0))])]),
    case("arrangement", "indirect", "child-bench-line-park", "let's make a little line of benches by the fountain, "
         "like a real park! maybe four?",
         [status(), delta("bench", 4), shaped("line", "bench", min_count=4), near("bench", "fountain", 15, require_all=True),
          guard("bench")],
         [call("arrange_assets", categories=["bench"], shape="line", count=4, location=at("fountain"))]),
    case("arrangement", "indirect", "formal-line-northbound", "It is requested that the northbound lane of Campus "
         "Drive be lined with eight traffic cones, north of the crossroads.",
         [status(), delta("traffic_cone", 8), in_lane("campus_northbound", category="traffic_cone", scope="added"),
          near_point("traffic_cone", 1.75, 30.0, 22, require_all=True), guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=8,
               location=at("north crosswalk", lane="campus_northbound"))]),
    case("arrangement", "indirect", "commentary-cones-block", "And the cones go up - a whole line of them right "
         "across Campus Drive, south of the junction, five of them!",
         [status(), delta("traffic_cone", 5), shaped("line", "traffic_cone", min_count=5),
          near_point("traffic_cone", 0.0, -18.0, 10, require_all=True),
          in_lane("campus_southbound", category="traffic_cone", scope="added", require_all=False),
          in_lane("campus_northbound", category="traffic_cone", scope="added", require_all=False), guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5, heading_deg=0, spacing=1.2,
               location=point(0.0, -16.0))]),
    case("arrangement", "indirect", "adjuster-witness-line", "Now reconstruct the witnesses: three more people "
         "standing in a line next to that pedestrian.",
         [status(), delta("pedestrian", 3), shaped("line", "pedestrian", min_count=3),
          near("pedestrian", "Library entrance", 14, require_all=True), guard("pedestrian")],
         [call("arrange_assets", categories=["pedestrian"], shape="line", count=3, location=at("pedestrian_1", "next_to"))],
         setup=[turn("Add a pedestrian standing at the Library entrance", [call("add_asset", category="pedestrian",
                location=at("Library entrance"))], planned=True)]),
    case("arrangement", "indirect", "dispatch-buses-westbound", "Dispatch four buses to queue along the westbound "
         "lane's kerb, starting at the east gate.",
         [status(), delta("bus", 4), in_lane("main_westbound", category="bus", scope="added"),
          near("bus", "east gate", 70, require_all=True), guard("bus")],
         [call("arrange_assets", categories=["bus"], shape="lane_edge", count=4, spacing=14,
               location=at("east gate", lane="main_westbound", offset_m=0.2))]),
    case("arrangement", "indirect", "emoji-barriers-lot-a", "🚧🚧🚧 barriers across the lot A driveway pls, 3 of them",
         [status(), delta("road_barrier", 3), shaped("line", "road_barrier", min_count=3),
          near("road_barrier", "parking lot A entrance", 9, require_all=True), guard("road_barrier")],
         [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, heading_deg=0, spacing=2.2,
               location=point(-85.0, 8.0))]),
    impossible("arrangement", "indirect", "parade-150", "could you line Main Street with 150 pedestrians, for the "
               "parade?",
               [call("arrange_assets", categories=["pedestrian"], shape="line", count=150,
                     location=at("main intersection"))]),
    # vague
    case("arrangement", "vague", "few-bollards-hydrant", "a few bollards round the hydrant",
         [status(), delta("bollard", 3, 8), shaped("ring", "bollard", around="fire_hydrant_1", min_count=3),
          guard("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="ring", count=4, location=at("fire_hydrant_1"))]),
    case("arrangement", "vague", "bunch-cones-lot-b", "a bunch of cones blocking off lot B's driveway",
         [status(), delta("traffic_cone", 3, 15), near("traffic_cone", "parking lot B entrance", 10, require_all=True),
          guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5,
               location=at("parking lot B entrance"))]),
    case("arrangement", "vague", "fill-lot-a-row", "fill lot A with a row of cars",
         [status(), delta(["passenger_car", "suv"], 3, 20), shaped("line", ["passenger_car", "suv"], min_count=3),
          near(["passenger_car", "suv"], "parking lot A", 1, require_all=True), guard("passenger_car", "suv")],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=6,
               location=at("parking lot A"))]),
    case("arrangement", "vague", "sarcastic-barriers-crossroads", "oh look, the crossroads is totally "
         "unprotected. a line of barriers somewhere by it, I don't care where",
         [status(), delta("road_barrier", 2, 20), shaped("line", "road_barrier", min_count=2, tolerance=1.5),
          near("road_barrier", "main intersection", 15, require_all=True), guard("road_barrier")],
         [call("arrange_assets", categories=["road_barrier"], shape="line", count=4, location=at("main intersection"))]),
    case("arrangement", "vague", "bikes-row-lot-b", "bikes. row. lot B.",
         [status(), delta("bicycle", 3, 20), shaped("line", "bicycle", min_count=3),
          near("bicycle", "parking lot B", 1, require_all=True), guard("bicycle")],
         [call("arrange_assets", categories=["bicycle"], shape="parking_row", count=5, location=at("parking lot B"))]),
    case("arrangement", "vague", "dozen-cones-yards-apart", "a dozen cones along the westbound lane from the east "
         "gate, a couple of yards apart",
         [status(), delta("traffic_cone", 12), in_lane("main_westbound", category="traffic_cone", scope="added"),
          shaped("line", "traffic_cone", min_count=12, spacing_min=1.2, spacing_max=2.8),
          near("traffic_cone", "east gate", 35, require_all=True), guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=12, spacing=1.8,
               location=at("east gate", lane="main_westbound"))]),
    case("arrangement", "vague", "same-again-lot-b", "same again, but at lot B",
         [status(), delta("traffic_cone", 4), shaped("line", "traffic_cone", min_count=4),
          near("traffic_cone", "parking lot B entrance", 12, require_all=True), guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=4,
               location=at("parking lot B entrance"))],
         setup=[turn("line four cones across the lot A entrance", [call("arrange_assets", categories=["traffic_cone"],
                shape="line", count=4, location=at("parking lot A entrance"))], planned=True)]),
    case("arrangement", "vague", "bollard-ring-red", "some bollards in a ring round the hydrant, and make them red",
         [status(), delta("bollard", 3, 8), shaped("ring", "bollard", around="fire_hydrant_1", min_count=3),
          looks(category="bollard", colour="red", scope="added", require_all=True), guard("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="ring", count=4, location=at("fire_hydrant_1")),
          call("set_asset_appearance", category="bollard", colour="red")], tags=COMPOUND),
    # erroneous
    case("arrangement", "erroneous", "cones-infront-ego", "make a line of 4 cones infront the ego",
         [status(), delta("traffic_cone", 4), shaped("line", "traffic_cone", min_count=4),
          rel("in_front_of", "ego", category="traffic_cone", scope="added", max_distance=30, tolerance_deg=30,
              require_all=True), guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=4, location=at("ego", "in_front_of",
                                                                                             distance=10))]),
    case("arrangement", "erroneous", "pedestrains-circel", "put 6 pedestrains in a circel around the bus stop",
         [status(), delta("pedestrian", 6), shaped("ring", "pedestrian", around="bus stop", min_count=6, tolerance=1.5),
          guard("pedestrian")],
         [call("arrange_assets", categories=["pedestrian"], shape="ring", count=6, location=at("bus stop"))]),
    case("arrangement", "erroneous", "suvs-sid-by-side", "line up 3 SUVs sid by side in lot b",
         [status(), delta("suv", 3), shaped("line", "suv", min_count=3), near("suv", "parking lot B", 1, require_all=True),
          guard("suv")],
         [call("arrange_assets", categories=["suv"], shape="parking_row", count=3, location=at("parking lot B"))]),
    case("arrangement", "erroneous", "linning-eastbund-jtekt", "linning the eastbund lane with cones by teh JTEKT "
         "bulding, like 10",
         [status(), delta("traffic_cone", 10), in_lane("main_eastbound", category="traffic_cone", scope="added"),
          near("traffic_cone", "JTEKT building entrance", 35, require_all=True), guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=10,
               location=at("JTEKT building entrance", lane="main_eastbound"))]),
    case("arrangement", "erroneous", "nonnative-grid-lot-a", "Make for me a grid from nine cones in the parking A.",
         [status(), delta("traffic_cone", 9), near("traffic_cone", "parking lot A", 1, require_all=True),
          guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="grid", count=9, location=at("parking lot A"))]),
    case("arrangement", "erroneous", "benchs-round-tree", "ring of benchs round the tree by the fountian, 5 of them",
         [status(), delta("bench", 5), shaped("ring", "bench", around="tree_2", min_count=5, tolerance=1.5),
          guard("bench")],
         [call("arrange_assets", categories=["bench"], shape="ring", count=5, location=at("tree_2"))]),
    case("arrangement", "erroneous", "cone-row-acros-lot-b", "put 5 cone in row acros the lot B entrence",
         [status(), delta("traffic_cone", 5), shaped("line", "traffic_cone", min_count=5),
          near("traffic_cone", "parking lot B entrance", 10, require_all=True), guard("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5, heading_deg=0,
               location=point(47.0, -8.0))]),
]


# --- appearance: weather, time, lights, colours and materials ------------------------------------
NAMED_COLOURS = ["red", "green", "blue", "yellow", "orange", "white", "black", "grey", "silver", "purple", "pink",
                 "brown", "cyan", "teal", "beige", "gold", "navy", "maroon"]
LIVELY_MATERIALS = ("glossy", "metal", "plastic", "matte", "wood")

APPEARANCE: list[Json] = [
    # direct
    case("appearance", "direct", "make-it-rain", "Make it rain.",
         [status(), env(weather=["rain"], time_from="11:59", time_to="12:01"), guard(environment=True)],
         [call("set_weather", kind="rain")]),
    case("appearance", "direct", "time-2130", "Set the time to 21:30.",
         [status(), env(time_from="21:25", time_to="21:35", weather=["clear"]), guard(environment=True)],
         [call("set_time_of_day", time="21:30")]),
    case("appearance", "direct", "suv-red", "Paint the SUV red.",
         [status(), looks(asset="suv_1", colour="red"), guard(assets=["suv_1"])],
         [call("set_asset_appearance", assets=["suv_1"], colour="red")]),
    case("appearance", "direct", "street-lights-on", "Turn the street lights on.",
         [status(), env(street_lights="on", time_from="11:59", time_to="12:01"), guard(environment=True)],
         [call("set_lighting", street_lights="on")]),
    case("appearance", "direct", "adjuster-fog-7am", "At the time of the incident it was foggy, around 7 in the "
         "morning. Set the scene accordingly.",
         [status(), env(weather=["fog"], time_from="06:30", time_to="07:30"), guard(environment=True)],
         [call("set_weather", kind="fog"), call("set_time_of_day", time="07:00")], tags=COMPOUND),
    case("appearance", "direct", "dispatch-trucks-orange", "Paint both units, the two trucks, orange.",
         [status(), looks(category="truck", colour="orange", scope="all", require_all=True, min_count=2),
          guard("truck")],
         [call("set_asset_appearance", category="truck", colour="orange")],
         setup=[turn("two trucks in lot A", [call("add_asset", category="truck", count=2, location=at("parking lot A"))])]),
    case("appearance", "direct", "dusk-and-lights", "Make it dusk and switch the street lights on.",
         [status(), env(time_from="18:30", time_to="20:30", street_lights="on"), guard(environment=True)],
         [call("set_time_of_day", time="dusk"), call("set_lighting", street_lights="on")], tags=COMPOUND),
    impossible("appearance", "direct", "exposure-ten", "Set the exposure to 10.",
               [call("set_lighting", exposure=10)]),
    # indirect
    case("appearance", "indirect", "sarcastic-pitch-dark", "great, now it's pitch dark and I can't see a thing. "
         "fix that",
         [status(), env(night=False), guard(environment=True)],
         [call("set_time_of_day", time="12:00")],
         setup=[turn("set the time to 23:00", [call("set_time_of_day", time="23:00")], planned=True)]),
    case("appearance", "indirect", "any-chance-snow", "any chance of some snow?",
         [status(), env(weather=["snow"]), guard(environment=True)],
         [call("set_weather", kind="snow")]),
    case("appearance", "indirect", "formal-vehicle-lights", "It is requested that all vehicle lights be switched "
         "on for the duration of the test.",
         [status(), env(vehicle_lights="on"), guard(environment=True)],
         [call("set_lighting", vehicle_lights="on")]),
    case("appearance", "indirect", "child-happy-yellow", "ooh, let's make the bench a happy yellow colour, shall "
         "we?",
         [status(), looks(asset="bench_1", colour="yellow"), guard(assets=["bench_1"])],
         [call("set_asset_appearance", assets=["bench_1"], colour="yellow")]),
    case("appearance", "indirect", "adjuster-silver-claimant", "The claimant's car was silver. Please update "
         "vehicle 1 accordingly.",
         [status(), looks(asset="ego", colour="silver"), guard(assets=["ego"])],
         [call("set_asset_appearance", assets=["ego"], colour="silver")]),
    case("appearance", "indirect", "story-sun-sinks", "The sun sinks low over the campus, the shadows stretch "
         "long...",
         [status(), env(time_from="17:30", time_to="20:30"), guard(environment=True)],
         [call("set_time_of_day", time="sunset")]),
    case("appearance", "indirect", "emoji-heavy-rain", "🌧️🌧️ heavy pls",
         [status(), env(weather=["rain"], intensity_min=0.7), guard(environment=True)],
         [call("set_weather", kind="rain", intensity=0.9)]),
    case("appearance", "indirect", "german-night", "Mach es Nacht, bitte - I want it night",
         [status(), env(night=True), guard(environment=True)],
         [call("set_time_of_day", time="night")]),
    impossible("appearance", "indirect", "ego-to-motorbike", "swap the ego for a motorbike, would you?",
               [call("set_asset_appearance", assets=["ego"], category="motorcycle")]),
    # vague
    case("appearance", "vague", "feel-gloomy", "make it feel gloomy",
         [status(), guard(environment=True)],
         [call("set_weather", kind="cloudy")],
         alternatives=[[env(weather=["cloudy", "fog", "rain"])], [env(night=True)], [env(time_from="18:00", time_to="21:00")]]),
    case("appearance", "vague", "drizzle", "drizzle.",
         [status(), env(weather=["rain"], intensity_max=0.45), guard(environment=True)],
         [call("set_weather", kind="rain", intensity=0.2)]),
    case("appearance", "vague", "jazz-up-lot-b", "the cars in lot B look so boring. jazz them up",
         [status(), *[moved(a, max_distance=0.1) for a in PARKED_IN_LOT_B], guard(*CARS_IN_LOT_B)],
         [call("set_asset_appearance", assets=PARKED_IN_LOT_B, colour="pink", material="glossy")],
         alternatives=[[looks(category=CARS_IN_LOT_B, colour=NAMED_COLOURS, min_count=3)],
                       *[[looks(category=CARS_IN_LOT_B, material=m, min_count=3)] for m in LIVELY_MATERIALS]]),
    case("appearance", "vague", "brightness-notches", "dial the brightness up a couple of notches",
         [status(), env(exposure_min=1.15, exposure_max=3.0, time_from="11:59", time_to="12:01"), guard(environment=True)],
         [call("set_lighting", exposure=1.5)]),
    case("appearance", "vague", "a-bit-less-rain", "ok, a bit less than that",
         [status(), env(weather=["rain"], intensity_min=0.1, intensity_max=0.75), guard(environment=True)],
         [call("set_weather", kind="rain", intensity=0.5)],
         setup=[turn("make it rain heavily", [call("set_weather", kind="rain", intensity=0.9)], planned=True)]),
    case("appearance", "vague", "seat-wood", "that seat by the tree near the library - something more natural "
         "looking, like wood",
         [status(), looks(asset="bench_1", material="wood"), guard(assets=["bench_1"])],
         [call("set_asset_appearance", assets=["bench_1"], material="wood")]),
    case("appearance", "vague", "snow-plus-night", "snow + night",
         [status(), env(weather=["snow"], night=True), guard(environment=True)],
         [call("set_weather", kind="snow"), call("set_time_of_day", time="night")], tags=COMPOUND),
    case("appearance", "vague", "red-instead", "hmm, not blue. make that red instead",
         [status(), looks(asset="bench_1", colour="red"), guard(assets=["bench_1"])],
         [call("set_asset_appearance", assets=["bench_1"], colour="red")],
         setup=[turn("paint the bench blue", [call("set_asset_appearance", assets=["bench_1"], colour="blue")])]),
    impossible("appearance", "vague", "suv-see-through", "make the SUV see-through",
               [call("set_asset_appearance", assets=["suv_1"], material="glass")]),
    # erroneous
    case("appearance", "erroneous", "mak-it-snwo", "mak it snwo",
         [status(), env(weather=["snow"]), guard(environment=True)],
         [call("set_weather", kind="snow")]),
    case("appearance", "erroneous", "tiem-6-morning", "set tiem to 6 in teh morning",
         [status(), env(time_from="05:45", time_to="06:15"), guard(environment=True)],
         [call("set_time_of_day", time="06:00")]),
    case("appearance", "erroneous", "bench-bleu", "paint the bus stop bench bleu",
         [status(), looks(asset="bench_1", colour="blue"), guard(assets=["bench_1"])],
         [call("set_asset_appearance", assets=["bench_1"], colour="blue")]),
    case("appearance", "erroneous", "turn-of-streetlights", "turn of the streetlights",
         [status(), env(street_lights="off"), guard(environment=True)],
         [call("set_lighting", street_lights="off")]),
    case("appearance", "erroneous", "nonnative-clear-again", "The weather, make it to be clear again please.",
         [status(), env(weather=["clear"]), guard(environment=True)],
         [call("set_weather", kind="clear")],
         setup=[turn("make it rain", [call("set_weather", kind="rain")])]),
    case("appearance", "erroneous", "black-exept-suv", "colour al the cars in lot b black exept the suv",
         [status(), looks(asset="passenger_car_1", colour="black"), looks(asset="passenger_car_2", colour="black"),
          guard(assets=["passenger_car_1", "passenger_car_2"])],
         [call("set_asset_appearance", assets=["passenger_car_1", "passenger_car_2"], colour="black")]),
    case("appearance", "erroneous", "formal-clear-ten", "It is requsted that the weather be set to clear and the "
         "time to 10:00 hrs.",
         [status(), env(weather=["clear"], time_from="09:55", time_to="10:05"), guard(environment=True)],
         [call("set_weather", kind="clear"), call("set_time_of_day", time="10:00")],
         setup=[turn("fog please", [call("set_weather", kind="fog")])], tags=COMPOUND),
    impossible("appearance", "erroneous", "clok-19-75", "set the clok to 19:75",
               [call("set_time_of_day", time="19:75")]),
    impossible("appearance", "erroneous", "tree-twice-big", "make the tree by the libary twice as big",
               [call("set_asset_appearance", assets=["tree_1"], scale=2.0)]),
]


ALL_CASES: list[Json] = [*SEARCH, *ADDITION, *REMOVAL, *POSITIONING, *MOVING, *ARRANGEMENT, *APPEARANCE]


def write(path: Path = SUITE_PATH) -> Path:
    """Write the suite: one JSON object per line."""
    path.write_text("".join(json.dumps(c, ensure_ascii=False) + "\n" for c in ALL_CASES), encoding="utf-8")
    return path


if __name__ == "__main__":
    print(f"wrote {len(ALL_CASES)} cases to {write()}")
