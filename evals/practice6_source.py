"""The sixth practice suite (practice6): its cases as a plain list, and the writer of its JSONL.

A development suite, written from the campus world, the asset catalog, the Worker tools and the
eval checks only, by a helper who had read neither the planners (their lexicons, prompt examples
or example bank) nor any other suite's cases. Its voices are new: a driving-school instructor
planning a lesson drive, a QA tester filing bug-report steps ("Steps: ... Expected: ..."), a
product manager in business speak, a parent describing the scene to a child, someone dictating
by voice (homophones, no punctuation, run-on sentences), someone who writes in the passive with
nominalisations, someone who refers back to earlier turns, and a US and a UK speaker with their
own road words (sidewalk/pavement, trash can/litter bin, parking lot/car park, truck/lorry).
Requests name groups ("each vehicle in ..."), state the wanted scene ("what this scene is missing
..."), make exceptions ("all the trees except ..."), and ask questions of many shapes, which must
change nothing. About 8 % ask for what the world cannot do (a tram, hail, a hospital, a bench
inside a building, a count past the limits); the right outcome there is a refusal that changes
nothing. Checks judge outcomes, as strict as the request and no stricter, and every case guards
against collateral edits with `unchanged_except`.

`python -m drivetwin.evals.practice6_source` rewrites `suites/practice6.jsonl` from `ALL_CASES`.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

SUITE_PATH = Path(__file__).resolve().parent / "suites" / "practice6.jsonl"

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
        "id": f"practice6.{task}.{grade}.{slug}",
        "prompt": prompt,
        "task": task,
        "grade": grade,
        "tags": ["practice6", *tags],
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


SEARCH: list[Json] = [
    question(
        "direct", "count_street_lights", "How many street lights does the scene have?",
        told(any_of=["12", "twelve"]), [call("find_assets", category="street_light")],
    ),
    question(
        "direct", "qa_list_trees", "Steps: list every tree in the scene. Expected: each tree with its id.",
        told(all_of=["tree_1", "tree_2", "tree_3", "tree_4"]), [call("find_assets", category="tree")],
    ),
    question(
        "direct", "lane_closest_to_bus_stop", "Which lane runs closest to the bus stop?",
        told(any_of=["main_eastbound"]), [call("find_lanes", near="bus stop")],
    ),
    question(
        "direct", "ego_to_fountain_metres", "What is the straight-line distance in metres between our car and the fountain?",
        told(any_of=["141", "141.3", "141.31"]), [call("measure_distance", a="fountain", b="ego")],
    ),
    question(
        "direct", "describe_the_suv", "Tell me about suv_1: where is it and what is it doing?",
        told(any_of=["suv_1", "parked"]), [call("asset_properties", asset="suv_1")],
    ),
    question(
        "indirect", "instructor_nearest_named_place",
        "Before my learner pulls away I want to tell her which named place is closest to the car she's sitting in.",
        told(any_of=["parking lot A", "lot A"]), [call("find_landmarks", nearest_to="ego")],
    ),
    question(
        "indirect", "us_trash_can_by_bus_stop",
        "Is there a trash can within about ten meters of the bus stop? I'm planning a sidewalk scene there.",
        told(any_of=["trash_bin_1"]), [call("find_assets", category="trash_bin", near="bus stop", within=10)],
    ),
    question(
        "indirect", "pm_inventory_of_lot_b",
        "For the stakeholder sync I need a quick inventory of what's currently sitting in parking lot B.",
        told(all_of=["passenger_car_1", "passenger_car_2", "suv_1"]),
        [call("find_assets", near="parking lot B", within=25)],
    ),
    question(
        "indirect", "parent_what_grows_by_fountain",
        "Can you tell Mia what's growing right next to the fountain? She wants to know before we go there.",
        told(any_of=["tree_2", "tree"]), [call("find_assets", category="tree", nearest_to="fountain")],
    ),
    question(
        "indirect", "passive_distance_of_hydrant",
        "The distance between the fire hydrant and the ego vehicle is to be reported.",
        told(any_of=["76", "76.3", "76.34"]), [call("measure_distance", a="fire_hydrant_1", b="ego")],
    ),
    question(
        "indirect", "uk_lorries_in_the_car_park",
        "Are there any lorries parked in the car park at the moment? I'd rather know before I add one.",
        told(any_of=["no", "none", "0", "nothing", "No truck", "no trucks"]),
        [call("find_assets", category="truck", near="parking lot B", within=5)],
    ),
    question(
        "vague", "voice_whats_near_the_fountain", "so whats over by the fountain then anything there",
        told(any_of=["tree_2"]), [call("find_assets", near="fountain", within=15)],
    ),
    question(
        "vague", "every_vehicle_in_the_scene", "vehicles?",
        told(all_of=["passenger_car_1", "passenger_car_2", "suv_1"]), [call("find_assets", category="vehicles")],
    ),
    question(
        "vague", "closest_car_to_us", "the nearest car to us, which one would that be",
        told(any_of=["passenger_car_1"]), [call("find_assets", category="passenger_car", nearest_to="ego")],
    ),
    question(
        "vague", "how_many_lanes", "and the lanes, how many of them are there",
        told(any_of=["4", "four"]), [call("find_lanes")],
    ),
    question(
        "vague", "benches_anywhere", "somewhere to sit in this scene?",
        told(any_of=["bench_1"]), [call("find_assets", category="bench")],
    ),
    question(
        "vague", "backref_those_cones_count", "how many of them did that leave us with",
        told(any_of=["3", "three"]), [call("find_assets", category="traffic_cone")],
        setup=[turn("Put three cones by the bus stop.", [call("add_asset", category="traffic_cone", count=3, location=at("bus stop"))])],
    ),
    question(
        "erroneous", "voice_lamp_posts_on_main", "how many lamp post is their on main street",
        told(any_of=["12", "twelve"]), [call("find_assets", category="street_light", lane="Main Street")],
    ),
    question(
        "erroneous", "typo_nearest_vehicle", "wich vehical is closest too the ego",
        told(any_of=["passenger_car_1"]), [call("find_assets", category="vehicles", nearest_to="ego")],
    ),
    question(
        "erroneous", "non_native_where_is_stop", "where is stay the stop sign, near of which crossing?",
        told(any_of=["-13.5", "west crosswalk", "crossing_west"]), [call("asset_properties", asset="stop_sign_1")],
    ),
    question(
        "erroneous", "dropped_words_lot_a_distance", "how far lot A from ego",
        told(any_of=["39.6", "18.7", "40", "19"]), [call("measure_distance", a="parking lot A", b="ego")],
    ),
    question(
        "direct", "compound_benches_and_hydrants",
        "How many benches are there, and how many fire hydrants?",
        told(all_of=["bench_1", "fire_hydrant_1"]),
        [call("find_assets", category="bench"), call("find_assets", category="fire_hydrant")],
        tags=("compound",),
    ),
    impossible(
        "search", "indirect", "distance_to_hospital",
        "I need to know how far the ego is from the campus hospital for the ambulance scenario.",
        [call("measure_distance", a="campus hospital", b="ego")],
    ),
    question(
        "vague", "backref_anything_in_road_ahead", "right, is anything sitting in the road now",
        told(any_of=["cement_rubble_1"]), [call("find_assets", on_lane=True)],
        setup=[turn("Drop some broken concrete in our lane 30 m ahead of us.",
                    [call("add_asset", category="cement_rubble", location=at("ego", along_m=30))])],
    ),
    question(
        "erroneous", "voice_how_many_peple_now", "hw many peple are their now",
        told(any_of=["5", "five"]), [call("find_assets", category="pedestrian")],
        setup=[turn("Add five people at the Student Union.",
                    [call("add_asset", category="pedestrian", count=5, location=at("Student Union entrance"))])],
    ),
    question(
        "indirect", "pm_status_check_suv",
        "Quick status check for the team: which named place is the SUV nearest, and how far is it from our car?",
        told(all_of=["parking lot B"], any_of=["92.2", "92"]),
        [call("find_landmarks", nearest_to="suv_1"), call("measure_distance", a="suv_1", b="ego")],
        tags=("compound",),
    ),
    question(
        "erroneous", "typo_suv_lane_and_colour", "wich lane is the suv closest and whats it colour",
        told(all_of=["campus_northbound"], any_of=["default", "unpainted", "no colour"]),
        [call("find_lanes", near="suv_1"), call("asset_properties", asset="suv_1")],
        tags=("compound",),
    ),
]

ADDITION: list[Json] = [
    case(
        "addition", "direct", "instructor_pedestrian_on_west_crosswalk",
        "Lesson prep: put one pedestrian on the west crosswalk so my student practises giving way.",
        [delta("pedestrian", 1), near("pedestrian", "west crosswalk", 5), guard("pedestrian")],
        [call("add_asset", category="pedestrian", location=at("west crosswalk"))],
    ),
    case(
        "addition", "direct", "qa_three_cones_westbound",
        "Steps: add 3 traffic cones in lane main_westbound. Expected: 3 new cones standing in that lane.",
        [delta("traffic_cone", 3), {"kind": "in_lane", "category": "traffic_cone", "scope": "added", "lane": "main_westbound"},
         guard("traffic_cone")],
        [call("add_asset", category="traffic_cone", count=3, location=at("main_westbound", "in_lane"))],
    ),
    case(
        "addition", "direct", "us_two_suvs_in_lot_b",
        "Add two SUVs to parking lot B.",
        [delta("suv", 2), near("suv", "parking lot B", 2, require_all=True), guard("suv")],
        [call("add_asset", category="suv", count=2, location=at("parking lot B"))],
    ),
    case(
        "addition", "direct", "uk_lorry_in_car_park_a",
        "Put a lorry in car park A, please.",
        [delta("truck", 1), near("truck", "parking lot A", 2), guard("truck")],
        [call("add_asset", category="truck", location=at("parking lot A"))],
    ),
    case(
        "addition", "direct", "hydrant_beside_jtekt_doors",
        "Add a fire hydrant next to the JTEKT entrance.",
        [delta("fire_hydrant", 1), near("fire_hydrant", "JTEKT building entrance", 6), guard("fire_hydrant")],
        [call("add_asset", category="fire_hydrant", location=at("JTEKT building entrance", "next_to"))],
    ),
    case(
        "addition", "indirect", "pm_onboard_foot_traffic_union",
        "From a stakeholder perspective we need more foot traffic outside the Student Union, so let's onboard four pedestrians there.",
        [delta("pedestrian", 4), near("pedestrian", "Student Union entrance", 12, require_all=True), guard("pedestrian")],
        [call("add_asset", category="pedestrian", count=4, location=at("Student Union entrance"))],
    ),
    case(
        "addition", "indirect", "passive_bench_by_fountain",
        "The placement of a bench beside the fountain is required.",
        [delta("bench", 1), near("bench", "fountain", 8), guard("bench")],
        [call("add_asset", category="bench", location=at("fountain", "next_to"))],
    ),
    case(
        "addition", "indirect", "parent_bus_waiting_at_stop",
        "Look, poppet, nobody's bus is at the bus stop yet. Shall we make one come and wait there?",
        [delta("bus", 1), near("bus", "bus stop", 12), guard("bus")],
        [call("add_asset", category="bus", location=at("bus stop"))],
    ),
    case(
        "addition", "indirect", "us_cyclist_riding_east",
        "My test needs somebody on a bike riding east on Main Street, in the eastbound lane.",
        [delta("bicycle", 1), {"kind": "behaviour", "category": "bicycle", "scope": "added", "behaviour": "drive_lane",
                                "lane": "main_eastbound"}, guard("bicycle")],
        [call("add_asset", category="bicycle", location=at("main_eastbound", "in_lane"),
              behaviour={"kind": "drive_lane", "lane": "main_eastbound"})],
    ),
    case(
        "addition", "indirect", "instructor_emergency_stop_person",
        "For the emergency-stop exercise I want someone to step out into the road in front of the car my pupil drives.",
        [delta("pedestrian", 1), {"kind": "behaviour", "category": "pedestrian", "scope": "added",
                                   "behaviour": ["jaywalk", "cross_road"]}, guard("pedestrian")],
        [call("add_asset", category="pedestrian", location=at("ego", "in_front_of", distance=20),
              behaviour={"kind": "jaywalk"})],
    ),
    case(
        "addition", "vague", "voice_trees_by_lot_a",
        "can we get some trees over by lot a the car park there",
        [delta("tree", 1, 10), near("tree", "parking lot A", 12, require_all=True), guard("tree")],
        [call("add_asset", category="tree", count=3, location=at("parking lot A"))],
    ),
    case(
        "addition", "vague", "wanted_state_traffic_on_campus_drive",
        "What this scene is missing is traffic moving along Campus Drive.",
        [delta(VEHICLES, 1, 20), guard(*VEHICLES)],
        [call("add_asset", category="passenger_car", count=2, location=at("campus_northbound", "in_lane"),
              behaviour={"kind": "drive_lane", "lane": "campus_northbound"})],
        alternatives=[
            [{"kind": "behaviour", "category": VEHICLES, "scope": "added", "behaviour": "drive_lane", "lane": "campus_northbound"}],
            [{"kind": "behaviour", "category": VEHICLES, "scope": "added", "behaviour": "drive_lane", "lane": "campus_southbound"}],
        ],
    ),
    case(
        "addition", "vague", "uk_litter_bins_by_library",
        "Bit bare outside the library, isn't it. Couple of litter bins, perhaps.",
        [delta("trash_bin", 1, 4), near("trash_bin", "Library entrance", 12, require_all=True), guard("trash_bin")],
        [call("add_asset", category="trash_bin", count=2, location=at("Library entrance"))],
    ),
    case(
        "addition", "vague", "more_people_generally",
        "it could do with more people about",
        [delta("pedestrian", 1, 30), guard("pedestrian")],
        [call("add_asset", category="pedestrian", count=3)],
    ),
    case(
        "addition", "erroneous", "voice_two_buses_by_union",
        "ad too buses buy the union building",
        [delta("bus", 2), near("bus", "Student Union entrance", 25, require_all=True), guard("bus")],
        [call("add_asset", category="bus", count=2, location=at("Student Union entrance"))],
    ),
    case(
        "addition", "erroneous", "typo_pedestrain_north_crosswlak",
        "pls add a pedestrain at the north crosswlak",
        [delta("pedestrian", 1), near("pedestrian", "north crosswalk", 5), guard("pedestrian")],
        [call("add_asset", category="pedestrian", location=at("north crosswalk"))],
    ),
    case(
        "addition", "erroneous", "non_native_five_cone_before_ego",
        "put 5 cone in front from the ego car",
        [delta("traffic_cone", 5), {"kind": "relative", "category": "traffic_cone", "scope": "added", "relation": "in_front_of",
                                     "target": "ego", "max_distance": 30, "require_all": True}, guard("traffic_cone")],
        [call("add_asset", category="traffic_cone", count=5, location=at("ego", "in_front_of", distance=10))],
    ),
    impossible(
        "addition", "direct", "tram_on_main_street",
        "Add a tram on Main Street.",
        [call("add_asset", category="tram", location=at("main_eastbound", "in_lane"))],
    ),
    impossible(
        "addition", "indirect", "bench_inside_student_union",
        "The students need somewhere to sit indoors, so put a bench inside the Student Union building itself.",
        [call("add_asset", category="bench", location=point(42.0, -63.0))],
    ),
    case(
        "addition", "indirect", "backref_two_more_vans_there",
        "lovely, now two more of those in the same spot",
        [delta("truck", 2), near("truck", "JTEKT building entrance", 15, require_all=True), guard("truck")],
        [call("add_asset", category="truck", count=2, location=at("JTEKT building entrance"))],
        setup=[turn("Park a delivery van at the JTEKT entrance.",
                    [call("add_asset", category="truck", location=at("JTEKT building entrance"))], planned=True)],
    ),
    case(
        "addition", "vague", "uk_bollards_on_jtekt_pavement",
        "The pavement outside the JTEKT Building looks a bit empty; a few bollards wouldn't go amiss.",
        [delta("bollard", 1, 10), near("bollard", "JTEKT building entrance", 12, require_all=True), guard("bollard")],
        [call("add_asset", category="bollard", count=3, location=at("JTEKT building entrance", "on_sidewalk"))],
    ),
    case(
        "addition", "vague", "parent_bus_and_people_waiting",
        "Ooh, let's have a bus at the bus stop, and some people waiting to get on it!",
        [delta("bus", 1), delta("pedestrian", 1, 12), near("bus", "bus stop", 12),
         near("pedestrian", "bus stop", 15, require_all=True), guard("bus", "pedestrian")],
        [call("add_asset", category="bus", location=at("bus stop")),
         call("add_asset", category="pedestrian", count=3, location=at("bus stop", "on_sidewalk"))],
        tags=("compound",),
    ),
    case(
        "addition", "vague", "backref_one_more_like_that_blue", "one more like that, but blue",
        [delta("passenger_car", 1), looks(category="passenger_car", scope="added", colour="blue"),
         near("passenger_car", "parking lot A", 2), guard("passenger_car")],
        [call("add_asset", category="passenger_car", location=at("parking lot A"), colour="blue")],
        setup=[turn("Add a red car in lot A.",
                    [call("add_asset", category="passenger_car", location=at("parking lot A"), colour="red")], planned=True)],
    ),
    impossible(
        "addition", "vague", "few_hundred_people_at_fountain", "put a few hundred people round the fountain",
        [call("add_asset", category="pedestrian", count=300, location=at("fountain"))],
    ),
    case(
        "addition", "erroneous", "voice_stop_sine_north_cross_walk", "at a stop sine buy the north cross walk",
        [delta("stop_sign", 1), near("stop_sign", "north crosswalk", 8), guard("stop_sign")],
        [call("add_asset", category="stop_sign", location=at("north crosswalk", "next_to"))],
    ),
    case(
        "addition", "erroneous", "non_native_truck_and_motorbikes_lot_b",
        "add one truck in lot B and two motorbike also there",
        [delta("truck", 1), delta("motorcycle", 2), near(["truck", "motorcycle"], "parking lot B", 2, require_all=True),
         guard("truck", "motorcycle")],
        [call("add_asset", category="truck", location=at("parking lot B")),
         call("add_asset", category="motorcycle", count=2, location=at("parking lot B"))],
        tags=("compound",),
    ),
    impossible(
        "addition", "erroneous", "ambulence_at_hospitel", "add a ambulence outside the hospitel",
        [call("add_asset", category="ambulance", location=at("hospital"))],
    ),
]

REMOVAL: list[Json] = [
    case(
        "removal", "direct", "stop_sign_out", "Remove the stop sign.",
        [gone("stop_sign_1"), guard(assets=["stop_sign_1"])],
        [call("remove_assets", assets=["stop_sign_1"])],
    ),
    case(
        "removal", "direct", "qa_delete_tree_3",
        "Steps: delete tree_3. Expected: tree_3 gone, the other trees still there.",
        [gone("tree_3"), kept("tree_1", "tree_2", "tree_4"), guard(assets=["tree_3"])],
        [call("remove_assets", assets=["tree_3"])],
    ),
    case(
        "removal", "direct", "us_trash_can_off_sidewalk",
        "Take the trash can off the sidewalk by the bus stop.",
        [gone("trash_bin_1"), guard(assets=["trash_bin_1"])],
        [call("remove_assets", assets=["trash_bin_1"])],
    ),
    case(
        "removal", "direct", "parked_cars_in_lot_b",
        "Delete both sedans standing in parking lot B.",
        [gone("passenger_car_1", "passenger_car_2"), guard("passenger_car")],
        [call("remove_assets", assets=["passenger_car_1", "passenger_car_2"])],
    ),
    case(
        "removal", "direct", "uk_north_pavement_lamps",
        "Clear away each street lamp on the north pavement of Main Street.",
        [gone(*NORTH_STREET_LIGHTS), kept(*SOUTH_STREET_LIGHTS), guard("street_light")],
        [call("remove_assets", assets=NORTH_STREET_LIGHTS)],
    ),
    case(
        "removal", "indirect", "pm_benches_out_of_scope",
        "Going forward, benches are out of scope for this scenario.",
        [count("bench", 0, 0), guard("bench")],
        [call("remove_assets", category="bench")],
    ),
    case(
        "removal", "indirect", "passive_removal_of_bins",
        "Elimination of every litter bin from the scene is requested.",
        [count("trash_bin", 0, 0), guard("trash_bin")],
        [call("remove_assets", category="trash_bin")],
    ),
    case(
        "removal", "indirect", "parent_tree_behind_the_bench",
        "See the tree just behind the bench at the bus stop? It's spoiling the view, so let's take it away, shall we?",
        [gone("tree_1"), guard(assets=["tree_1"])],
        [call("remove_assets", category="tree", near="bench_1", count=1)],
    ),
    case(
        "removal", "indirect", "instructor_hydrant_distracts",
        "My pupil keeps staring at the fire hydrant on the corner; could it disappear for the lesson?",
        [gone("fire_hydrant_1"), guard(assets=["fire_hydrant_1"])],
        [call("remove_assets", assets=["fire_hydrant_1"])],
    ),
    case(
        "removal", "indirect", "all_trees_except_bus_stop_one",
        "All the trees except the one by the bus stop should go.",
        [gone("tree_2", "tree_3", "tree_4"), kept("tree_1"), guard("tree")],
        [call("remove_assets", assets=["tree_2", "tree_3", "tree_4"])],
    ),
    case(
        "removal", "vague", "fewer_lamp_posts", "fewer lamp posts please, it's like a forest of them",
        [delta("street_light", -11, -1), guard("street_light")],
        [call("remove_assets", category="street_light", count=4)],
    ),
    case(
        "removal", "vague", "voice_cars_in_the_car_lot", "lose all them cars in the car lot",
        [gone("passenger_car_1", "passenger_car_2"), guard("passenger_car", "suv")],
        [call("remove_assets", assets=PARKED_IN_LOT_B)],
    ),
    case(
        "removal", "vague", "backref_pointy_things_at_crossing", "the pointy orange things at the crossing, lose them",
        [count("traffic_cone", 0, 0), guard("traffic_cone")],
        [call("remove_assets", category="traffic_cone")],
        setup=[turn("Put four cones on the west crosswalk.",
                    [call("add_asset", category="traffic_cone", count=4, location=at("west crosswalk"))])],
    ),
    case(
        "removal", "vague", "backref_barrier_nearest_us", "actually the one nearest us can go",
        [delta("road_barrier", -1), guard("road_barrier")],
        [call("remove_assets", category="road_barrier", near="ego", count=1)],
        setup=[turn("Put two barriers across the eastbound lane in front of our car.",
                    [call("add_asset", category="road_barrier", count=2, location=at("ego", "in_front_of", distance=15))],
                    planned=True)],
    ),
    case(
        "removal", "erroneous", "typo_stpo_sign", "remvoe the stpo sign",
        [gone("stop_sign_1"), guard(assets=["stop_sign_1"])],
        [call("remove_assets", assets=["stop_sign_1"])],
    ),
    case(
        "removal", "erroneous", "voice_street_lite_by_libary", "remove the street lite nearest too the libary",
        [gone("street_light_4"), guard(assets=["street_light_4"])],
        [call("remove_assets", category="street_light", near="Library entrance", count=1)],
    ),
    case(
        "removal", "erroneous", "non_native_all_benchs", "delete the all benchs",
        [count("bench", 0, 0), guard("bench")],
        [call("remove_assets", category="bench")],
    ),
    impossible(
        "removal", "indirect", "remove_parking_lot_b",
        "We don't need parking lot B in this scenario at all, take the whole lot out.",
        [call("remove_assets", assets=["parking_lot_b"])],
    ),
    case(
        "removal", "vague", "backref_keep_only_library_people", "just keep the ones at the library, the others can go",
        [delta("pedestrian", -3), count("pedestrian", 2, 2),
         {"kind": "near", "category": "pedestrian", "scope": "all", "target": "Library entrance", "within": 12, "require_all": True},
         guard("pedestrian")],
        [call("remove_assets", category="pedestrian", near="bus stop", count=3)],
        setup=[turn("Add three people at the bus stop and two at the Library entrance.",
                    [call("add_asset", category="pedestrian", count=3, location=at("bus stop")),
                     call("add_asset", category="pedestrian", count=2, location=at("Library entrance"))])],
    ),
    case(
        "removal", "vague", "pm_deprioritise_construction_clutter",
        "Let's deprioritise the clutter: the construction stuff can go.",
        [count("construction_sign", 0, 0), count("cement_rubble", 0, 0), guard("construction_sign", "cement_rubble")],
        [call("remove_assets", category="construction_sign"), call("remove_assets", category="cement_rubble")],
        tags=("compound",),
        setup=[turn("Add two construction signs and three lumps of rubble near the north crosswalk.",
                    [call("add_asset", category="construction_sign", count=2, location=at("north crosswalk")),
                     call("add_asset", category="cement_rubble", count=3, location=at("north crosswalk"))])],
    ),
    case(
        "removal", "vague", "wanted_state_no_people", "Ideally the scene ends up empty of people.",
        [count("pedestrian", 0, 0), guard("pedestrian")],
        [call("remove_assets", category="pedestrian")],
        setup=[turn("Add four pedestrians at the west crosswalk.",
                    [call("add_asset", category="pedestrian", count=4, location=at("west crosswalk"))])],
    ),
    case(
        "removal", "erroneous", "typo_suv_and_hidrant", "delte the suv and the hidrant",
        [gone("suv_1", "fire_hydrant_1"), guard(assets=["suv_1", "fire_hydrant_1"])],
        [call("remove_assets", assets=["suv_1"]), call("remove_assets", assets=["fire_hydrant_1"])],
        tags=("compound",),
    ),
    case(
        "removal", "erroneous", "voice_lamps_accept_south", "remove all the lamps accept the ones on the south side",
        [gone(*NORTH_STREET_LIGHTS), kept(*SOUTH_STREET_LIGHTS), guard("street_light")],
        [call("remove_assets", assets=NORTH_STREET_LIGHTS)],
    ),
    impossible(
        "removal", "erroneous", "delete_the_fountian", "delete the fountian",
        [call("remove_assets", assets=["fountain"])],
    ),
]

POSITIONING: list[Json] = [
    case(
        "positioning", "direct", "bench_at_fountain", "Place the bench next to the fountain.",
        [near(None, "fountain", 8, asset="bench_1"), guard(assets=["bench_1"])],
        [call("place_asset", asset="bench_1", location=at("fountain", "next_to"))],
    ),
    case(
        "positioning", "direct", "qa_hydrant_to_library_sidewalk",
        "Steps: place fire_hydrant_1 on the sidewalk nearest the Library entrance. Expected: hydrant stands on that sidewalk.",
        [{"kind": "on_surface", "asset": "fire_hydrant_1", "surfaces": ["sidewalk"]},
         near(None, "Library entrance", 12, asset="fire_hydrant_1"), guard(assets=["fire_hydrant_1"])],
        [call("place_asset", asset="fire_hydrant_1", location=at("Library entrance", "on_sidewalk"))],
    ),
    case(
        "positioning", "direct", "car_one_into_lot_a", "Put passenger_car_1 in parking lot A.",
        [near(None, "parking lot A", 1, asset="passenger_car_1"), guard(assets=["passenger_car_1"])],
        [call("place_asset", asset="passenger_car_1", location=at("parking lot A"))],
    ),
    case(
        "positioning", "direct", "us_suv_25_meters_ahead",
        "Put the SUV 25 meters ahead of the ego in its lane.",
        [{"kind": "in_lane", "asset": "suv_1", "lane": "main_eastbound"},
         near(None, "ego", 30, asset="suv_1"),
         {"kind": "relative", "asset": "suv_1", "relation": "in_front_of", "target": "ego", "max_distance": 30, "tolerance_deg": 20},
         guard(assets=["suv_1"])],
        [call("place_asset", asset="suv_1", location=at("ego", along_m=25))],
    ),
    case(
        "positioning", "direct", "stop_sign_to_north_crosswalk", "Place the stop sign beside the north crosswalk.",
        [near(None, "north crosswalk", 6, asset="stop_sign_1"), guard(assets=["stop_sign_1"])],
        [call("place_asset", asset="stop_sign_1", location=at("north crosswalk", "next_to"))],
    ),
    case(
        "positioning", "indirect", "instructor_car_by_lot_a_entrance",
        "For the manoeuvring lesson, one of the cars from lot B needs to stand by the entrance of lot A, so the learner has to steer round it.",
        [near(["passenger_car", "suv"], "parking lot A entrance", 10, scope="touched"), guard(assets=PARKED_IN_LOT_B)],
        [call("place_asset", asset="passenger_car_1", location=at("parking lot A entrance", "next_to"))],
    ),
    case(
        "positioning", "indirect", "passive_relocation_of_stop_sign",
        "Relocation of the stop sign to the JTEKT entrance is needed.",
        [near(None, "JTEKT building entrance", 6, asset="stop_sign_1"), guard(assets=["stop_sign_1"])],
        [call("place_asset", asset="stop_sign_1", location=at("JTEKT building entrance", "next_to"))],
    ),
    case(
        "positioning", "indirect", "parent_hydrant_by_big_doors",
        "See the little red hydrant? Let's pop it beside the big doors of Engineering Hall.",
        [near(None, "Engineering Hall entrance", 6, asset="fire_hydrant_1"), guard(assets=["fire_hydrant_1"])],
        [call("place_asset", asset="fire_hydrant_1", location=at("Engineering Hall entrance", "next_to"))],
    ),
    case(
        "positioning", "indirect", "pm_suv_blocks_the_crossing",
        "Let's reposition the SUV so it's parked on the west crosswalk; that's the key edge case for this release.",
        [near(None, "west crosswalk", 4, asset="suv_1"), guard(assets=["suv_1"])],
        [call("place_asset", asset="suv_1", location=at("west crosswalk"))],
    ),
    case(
        "positioning", "indirect", "us_bin_to_the_union",
        "I'd rather have the trash can by the Student Union entrance than at the bus stop.",
        [near(None, "Student Union entrance", 6, asset="trash_bin_1"), guard(assets=["trash_bin_1"])],
        [call("place_asset", asset="trash_bin_1", location=at("Student Union entrance", "next_to"))],
    ),
    case(
        "positioning", "vague", "bench_somewhere_shady", "that bench would be nicer somewhere shady",
        [guard(assets=["bench_1"])],
        [call("place_asset", asset="bench_1", location=at("tree_2", "next_to"))],
        alternatives=[[near(None, tree, 5, asset="bench_1")] for tree in ("tree_1", "tree_2", "tree_3", "tree_4")],
    ),
    case(
        "positioning", "vague", "voice_suv_over_by_the_gate", "the suv thing should be over by the gate",
        [guard(assets=["suv_1"])],
        [call("place_asset", asset="suv_1", location=at("main gate", "next_to"))],
        alternatives=[[near(None, "main gate", 10, asset="suv_1")], [near(None, "east gate", 10, asset="suv_1")]],
    ),
    case(
        "positioning", "vague", "uk_bin_on_pavement_by_engineering",
        "Stick the bin on the pavement outside Engineering Hall.",
        [{"kind": "on_surface", "asset": "trash_bin_1", "surfaces": ["sidewalk"]},
         near(None, "Engineering Hall entrance", 12, asset="trash_bin_1"), guard(assets=["trash_bin_1"])],
        [call("place_asset", asset="trash_bin_1", location=at("Engineering Hall entrance", "on_sidewalk"))],
    ),
    case(
        "positioning", "vague", "backref_that_one_other_side",
        "now mirror it across to the far side of the street",
        [near_point(None, -30.0, 3.5, 3, asset="motorcycle_1"), guard(assets=["motorcycle_1"])],
        [call("place_asset", asset="motorcycle_1", location=point(-30.0, 3.48))],
        setup=[turn("Put a motorbike at the bus stop.", [call("add_asset", category="motorcycle", location=at("bus stop"))],
                    planned=True)],
    ),
    case(
        "positioning", "erroneous", "typo_suv_infront_ego", "plase the suv infront of the ego",
        [{"kind": "relative", "asset": "suv_1", "relation": "in_front_of", "target": "ego", "max_distance": 30},
         guard(assets=["suv_1"])],
        [call("place_asset", asset="suv_1", location=at("ego", "in_front_of", distance=10))],
    ),
    case(
        "positioning", "erroneous", "voice_bench_buy_fountain", "put the bench buy the fountain",
        [near(None, "fountain", 8, asset="bench_1"), guard(assets=["bench_1"])],
        [call("place_asset", asset="bench_1", location=at("fountain", "next_to"))],
    ),
    case(
        "positioning", "erroneous", "non_native_car_two_on_lot_a", "positon the car 2 on lot A",
        [near(None, "parking lot A", 1, asset="passenger_car_2"), guard(assets=["passenger_car_2"])],
        [call("place_asset", asset="passenger_car_2", location=at("parking lot A"))],
    ),
    impossible(
        "positioning", "direct", "bench_inside_library", "Place the bench inside the Library.",
        [call("place_asset", asset="bench_1", location=point(-41.0, -30.0))],
    ),
    case(
        "positioning", "indirect", "us_trash_can_and_bench_by_jtekt",
        "Can the trash can go on the sidewalk by the JTEKT Building, with the bench right beside it?",
        [{"kind": "on_surface", "asset": "trash_bin_1", "surfaces": ["sidewalk"]},
         near(None, "JTEKT building entrance", 12, asset="trash_bin_1"), near(None, "trash_bin_1", 4, asset="bench_1"),
         guard(assets=["trash_bin_1", "bench_1"])],
        [call("place_asset", asset="trash_bin_1", location=at("JTEKT building entrance", "on_sidewalk")),
         call("place_asset", asset="bench_1", location=at("trash_bin_1", "next_to"))],
        tags=("compound",),
    ),
    case(
        "positioning", "indirect", "instructor_parallel_parking_drill",
        "For the parallel-parking drill, I want the SUV standing at the kerb of our road about twenty metres ahead of us.",
        [{"kind": "relative", "asset": "suv_1", "relation": "in_front_of", "target": "ego", "max_distance": 30, "tolerance_deg": 30},
         near(None, "ego", 28, asset="suv_1"), guard(assets=["suv_1"])],
        [call("place_asset", asset="suv_1", location=at("ego", along_m=20, side="right"))],
    ),
    case(
        "positioning", "vague", "backref_cyclist_to_lot_b_entrance", "hmm no, the bike goes by lot B's entrance instead",
        [near(None, "parking lot B entrance", 6, asset="bicycle_1"), guard(assets=["bicycle_1"])],
        [call("place_asset", asset="bicycle_1", location=at("parking lot B entrance", "next_to"))],
        setup=[turn("Add a cyclist at the main gate.", [call("add_asset", category="bicycle", location=at("main gate"))])],
    ),
    case(
        "positioning", "vague", "passive_hydrant_nearer_crossroads",
        "Placement of the hydrant closer to the crossroads is preferred.",
        [near_point(None, 0.0, 0.0, 12, asset="fire_hydrant_1"), guard(assets=["fire_hydrant_1"])],
        [call("place_asset", asset="fire_hydrant_1", location=at("main intersection", "next_to"))],
    ),
    impossible(
        "positioning", "vague", "bench_on_jtekt_roof", "the bench should go up on top of the JTEKT building somewhere",
        [call("place_asset", asset="bench_1", location=point(37.0, 30.0))],
    ),
    case(
        "positioning", "erroneous", "typo_bin_nxt_stop_sign", "plaec the bin nxt to the stop sign",
        [near(None, "stop_sign_1", 3, asset="trash_bin_1"), guard(assets=["trash_bin_1"])],
        [call("place_asset", asset="trash_bin_1", location=at("stop_sign_1", "next_to"))],
    ),
    case(
        "positioning", "erroneous", "voice_stop_sine_too_east_gate", "put the stop sine too the east gate",
        [near(None, "east gate", 8, asset="stop_sign_1"), guard(assets=["stop_sign_1"])],
        [call("place_asset", asset="stop_sign_1", location=at("east gate", "next_to"))],
    ),
]

MOVING: list[Json] = [
    case(
        "moving", "direct", "suv_five_forward", "Move the SUV 5 metres forward.",
        [moved("suv_1", min_distance=4.5, max_distance=5.5, direction="forward"), guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", forward=5)],
    ),
    case(
        "moving", "direct", "qa_turn_bench_90",
        "Steps: rotate bench_1 by 90 degrees where it stands. Expected: bench turned 90 deg, same spot.",
        [moved("bench_1", max_distance=0.5, turn_min_deg=80, turn_max_deg=100), guard(assets=["bench_1"])],
        [call("move_asset", asset="bench_1", turn_deg=90)],
    ),
    case(
        "moving", "direct", "car_two_three_right", "Shift passenger_car_2 3 m to its right.",
        [moved("passenger_car_2", min_distance=2.5, max_distance=3.5, direction="right"), guard(assets=["passenger_car_2"])],
        [call("move_asset", asset="passenger_car_2", left=-3)],
    ),
    case(
        "moving", "direct", "ego_ten_forward", "Move the ego 10 m forward.",
        [moved("ego", min_distance=9, max_distance=11, direction="forward"), guard(assets=["ego"])],
        [call("move_asset", asset="ego", forward=10)],
    ),
    case(
        "moving", "direct", "uk_lorry_back_two",
        "Move the lorry back two metres.",
        [moved("truck_1", min_distance=1.5, max_distance=2.5, direction="backward"), guard(assets=["truck_1"])],
        [call("move_asset", asset="truck_1", forward=-2)],
        setup=[turn("Put a lorry in car park A.", [call("add_asset", category="truck", location=at("parking lot A"))])],
    ),
    case(
        "moving", "indirect", "instructor_run_up_fifteen",
        "The car my learner sits in ought to start further back, fifteen metres say, so she gets a run-up.",
        [moved("ego", min_distance=13, max_distance=17, direction="backward"), guard(assets=["ego"])],
        [call("move_asset", asset="ego", forward=-15)],
    ),
    case(
        "moving", "indirect", "pm_nudge_hydrant_north",
        "Can we nudge the hydrant one metre north to de-risk the kerb clipping issue?",
        [moved("fire_hydrant_1", min_distance=0.5, max_distance=1.5, direction="left"), guard(assets=["fire_hydrant_1"])],
        [call("move_asset", asset="fire_hydrant_1", north=1)],
    ),
    case(
        "moving", "indirect", "passive_rotation_of_stop_sign",
        "A rotation of the stop sign so that it faces the other way is wanted.",
        [moved("stop_sign_1", max_distance=1, turn_min_deg=170), guard(assets=["stop_sign_1"])],
        [call("move_asset", asset="stop_sign_1", turn_deg=180)],
    ),
    case(
        "moving", "indirect", "parent_parked_cars_scoot_forward",
        "Shall we scoot the three cars in the car park forward a little, like they're queueing for the ice-cream van?",
        [*(moved(a, min_distance=0.5, max_distance=6, direction="forward") for a in PARKED_IN_LOT_B), guard(assets=PARKED_IN_LOT_B)],
        [call("move_asset", assets=PARKED_IN_LOT_B, forward=2)],
    ),
    case(
        "moving", "indirect", "us_every_vehicle_in_lot_east",
        "Bump each vehicle in the parking lot 4 meters east.",
        [*(moved(a, min_distance=3.5, max_distance=4.5, direction="right") for a in PARKED_IN_LOT_B), guard(assets=PARKED_IN_LOT_B)],
        [call("move_asset", assets=PARKED_IN_LOT_B, east=4)],
    ),
    case(
        "moving", "vague", "bench_too_close_to_kerb", "the bench is a touch too close to the road",
        [moved("bench_1", min_distance=0.3, max_distance=4, direction="left"), guard(assets=["bench_1"])],
        [call("move_asset", asset="bench_1", north=-1)],
    ),
    case(
        "moving", "vague", "ego_a_bit_forward", "ego: a little further up",
        [moved("ego", min_distance=0.5, max_distance=15, direction="forward"), guard(assets=["ego"])],
        [call("move_asset", asset="ego", forward=3)],
    ),
    case(
        "moving", "vague", "backref_that_person_closer_to_road", "that person, a few steps nearer the road",
        [moved("pedestrian_1", min_distance=0.5, max_distance=8), guard(assets=["pedestrian_1"])],
        [call("move_asset", asset="pedestrian_1", north=3)],
        setup=[turn("Add a pedestrian by the Library entrance.",
                    [call("add_asset", category="pedestrian", location=at("Library entrance"))])],
    ),
    case(
        "moving", "vague", "car_one_round_the_other_way", "passenger_car_1 the other way round",
        [moved("passenger_car_1", max_distance=2, turn_min_deg=160), guard(assets=["passenger_car_1"])],
        [call("move_asset", asset="passenger_car_1", turn_deg=180)],
    ),
    case(
        "moving", "erroneous", "typo_suv_foward", "move the suv 5 meter foward",
        [moved("suv_1", min_distance=4.5, max_distance=5.5, direction="forward"), guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", forward=5)],
    ),
    case(
        "moving", "erroneous", "voice_bench_won_eighty", "turn the bench round won eighty degrees",
        [moved("bench_1", max_distance=1, turn_min_deg=170), guard(assets=["bench_1"])],
        [call("move_asset", asset="bench_1", turn_deg=180)],
    ),
    case(
        "moving", "erroneous", "non_native_car_one_go_back", "car 1 go back 3 metre please",
        [moved("passenger_car_1", min_distance=2.5, max_distance=3.5, direction="backward"), guard(assets=["passenger_car_1"])],
        [call("move_asset", asset="passenger_car_1", forward=-3)],
    ),
    impossible(
        "moving", "direct", "ego_half_a_kilometre", "Move the ego 500 m forward.",
        [call("move_asset", asset="ego", forward=500)],
    ),
    case(
        "moving", "vague", "backref_bring_the_bus_forward", "hmm, bring it forward a bit",
        [moved("bus_1", min_distance=0.5, max_distance=10, direction="forward"), guard(assets=["bus_1"])],
        [call("move_asset", asset="bus_1", forward=3)],
        setup=[turn("Put a bus at the bus stop.", [call("add_asset", category="bus", location=at("bus stop"))], planned=True)],
    ),
    case(
        "moving", "vague", "uk_car_park_cars_further_back", "Every car in the car park a touch further back, please.",
        [*(moved(a, min_distance=0.5, max_distance=6, direction="backward") for a in PARKED_IN_LOT_B), guard(assets=PARKED_IN_LOT_B)],
        [call("move_asset", assets=PARKED_IN_LOT_B, forward=-2)],
    ),
    case(
        "moving", "vague", "suv_facing_wrong_way", "the suv's facing the wrong way",
        [moved("suv_1", max_distance=2, turn_min_deg=160), guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", turn_deg=180)],
    ),
    case(
        "moving", "indirect", "instructor_start_back_and_hydrant_off_kerb",
        "I'll have my learner start five metres further back, and the hydrant should sit a metre further from the kerb.",
        [moved("ego", min_distance=4, max_distance=6, direction="backward"),
         moved("fire_hydrant_1", min_distance=0.5, max_distance=1.5, direction="left"), guard(assets=["ego", "fire_hydrant_1"])],
        [call("move_asset", asset="ego", forward=-5), call("move_asset", asset="fire_hydrant_1", north=1)],
        tags=("compound",),
    ),
    impossible(
        "moving", "indirect", "shift_engineering_hall",
        "Could Engineering Hall be moved ten metres north so the road feels wider?",
        [call("move_asset", asset="Engineering Hall", north=10)],
    ),
    case(
        "moving", "erroneous", "typo_mvoe_ego_bakc", "mvoe ego bakc 5m",
        [moved("ego", min_distance=4, max_distance=6, direction="backward"), guard(assets=["ego"])],
        [call("move_asset", asset="ego", forward=-5)],
    ),
    case(
        "moving", "erroneous", "voice_suv_forward_than_turn", "move the suv forward ten meters and than turn it left ninety",
        [moved("suv_1", min_distance=9, max_distance=11, direction="forward", turn_min_deg=80, turn_max_deg=100),
         guard(assets=["suv_1"])],
        [call("move_asset", asset="suv_1", forward=10), call("move_asset", asset="suv_1", turn_deg=90)],
        tags=("compound",),
    ),
]

ARRANGEMENT: list[Json] = [
    case(
        "arrangement", "direct", "five_cones_line_ahead", "Arrange five cones in a line in front of the ego.",
        [delta("traffic_cone", 5), {"kind": "arrangement", "category": "traffic_cone", "shape": "line", "min_count": 5},
         {"kind": "relative", "category": "traffic_cone", "scope": "added", "relation": "in_front_of", "target": "ego",
          "max_distance": 35, "require_all": True}, guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="line", count=5, location=at("ego", "in_front_of", distance=12))],
    ),
    case(
        "arrangement", "direct", "qa_ring_of_bollards_fountain",
        "Steps: ring of 6 bollards around the fountain, radius 4 m. Expected: 6 bollards on a circle round it.",
        [delta("bollard", 6), {"kind": "arrangement", "category": "bollard", "shape": "ring", "around": "fountain", "min_count": 6},
         near("bollard", "fountain", 5, require_all=True), guard("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="ring", count=6, location=at("fountain"), radius=4)],
    ),
    case(
        "arrangement", "direct", "parking_row_four_cars_lot_a", "Make a parking row of 4 cars in lot A.",
        [delta("passenger_car", 4), {"kind": "arrangement", "category": "passenger_car", "shape": "line", "min_count": 4},
         near("passenger_car", "parking lot A", 1, require_all=True), guard("passenger_car")],
        [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4, location=at("parking lot A"))],
    ),
    case(
        "arrangement", "direct", "us_cones_along_northbound_edge",
        "Line the edge of the northbound lane on Campus Drive with 6 traffic cones.",
        [delta("traffic_cone", 6), {"kind": "arrangement", "category": "traffic_cone", "shape": "line", "min_count": 6},
         near("traffic_cone", "campus_northbound", 3, require_all=True), guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=6, location=at("campus_northbound", "in_lane"))],
    ),
    case(
        "arrangement", "direct", "uk_grid_of_bollards_car_park",
        "Set out a grid of six bollards, three to a row, in the car park.",
        [delta("bollard", 6), {"kind": "arrangement", "category": "bollard", "shape": "cluster", "min_count": 6, "tolerance": 8},
         near("bollard", "parking lot B", 1, require_all=True), guard("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="grid", count=6, columns=3, location=at("parking lot B"))],
    ),
    case(
        "arrangement", "indirect", "instructor_slalom_in_our_lane",
        "Lesson plan: slalom. My learner will weave between six cones spaced eight metres apart along our lane, ahead of us.",
        [delta("traffic_cone", 6),
         {"kind": "arrangement", "category": "traffic_cone", "shape": "line", "min_count": 6, "spacing_min": 7, "spacing_max": 9},
         {"kind": "in_lane", "category": "traffic_cone", "scope": "added", "lane": "main_eastbound"},
         {"kind": "relative", "category": "traffic_cone", "scope": "added", "relation": "in_front_of", "target": "ego",
          "max_distance": 70, "tolerance_deg": 30, "require_all": True}, guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="line", count=6, spacing=8, heading_deg=0,
              location=point(-25.0, -1.75))],
    ),
    case(
        "arrangement", "indirect", "pm_row_of_parked_vehicles_lot_b",
        "To validate the parking feature we need a realistic row of five parked vehicles in lot B.",
        [delta(VEHICLES, 5), {"kind": "arrangement", "category": VEHICLES, "shape": "line", "min_count": 5},
         near(VEHICLES, "parking lot B", 1, require_all=True), guard(*VEHICLES)],
        [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=5, location=at("parking lot B"))],
    ),
    case(
        "arrangement", "indirect", "passive_enclosure_of_fountain",
        "Enclosure of the fountain by a ring of eight bollards is to be carried out.",
        [delta("bollard", 8), {"kind": "arrangement", "category": "bollard", "shape": "ring", "around": "fountain", "min_count": 8},
         guard("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="ring", count=8, location=at("fountain"), radius=3)],
    ),
    case(
        "arrangement", "indirect", "parent_circle_of_people_round_tree",
        "Let's make a circle of six people holding hands around the big tree by the fountain, like ring-a-roses!",
        [delta("pedestrian", 6), {"kind": "arrangement", "category": "pedestrian", "shape": "ring", "around": "tree_2", "min_count": 6},
         guard("pedestrian")],
        [call("arrange_assets", categories=["pedestrian"], shape="ring", count=6, location=at("tree_2"), radius=3)],
    ),
    case(
        "arrangement", "vague", "close_westbound_past_crossroads",
        "shut the westbound lane somewhere west of the crossroads",
        [delta("traffic_cone", 2, 20), {"kind": "in_lane", "category": "traffic_cone", "scope": "added", "lane": "main_westbound",
                                        "require_all": False, "min_count": 2},
         {"kind": "near", "category": "traffic_cone", "scope": "added", "target": "main_westbound", "within": 4, "require_all": True},
         guard("traffic_cone", "road_barrier", "construction_sign")],
        [call("close_lane", lane="main_westbound", at_x=-25.0, at_y=1.75)],
    ),
    case(
        "arrangement", "vague", "voice_row_of_bollards_bus_stop",
        "put a bunch of bollards in a row along the pavement by the bus stop",
        [delta("bollard", 3, 15), {"kind": "arrangement", "category": "bollard", "shape": "line", "min_count": 3},
         near("bollard", "bus stop", 15, require_all=True), guard("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="line", count=5, location=at("bus stop", "on_sidewalk"), spacing=2)],
    ),
    case(
        "arrangement", "vague", "wanted_state_ring_of_cones",
        "What I'm after is a ring of cones in the middle of the crossroads.",
        [delta("traffic_cone", 3, 40), {"kind": "arrangement", "category": "traffic_cone", "shape": "ring", "around": "main intersection"},
         near("traffic_cone", "main intersection", 1, require_all=True), guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=8, location=at("main intersection"), radius=5)],
    ),
    case(
        "arrangement", "vague", "backref_same_in_other_lane", "ditto for the westbound one",
        [delta("traffic_cone", 4), {"kind": "arrangement", "category": "traffic_cone", "shape": "line", "min_count": 4},
         near("traffic_cone", "main_westbound", 3, require_all=True), guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=4, location=at("main_westbound", "in_lane"))],
        setup=[turn("Line the edge of the eastbound lane with four cones.",
                    [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=4,
                          location=at("main_eastbound", "in_lane"))], planned=True)],
    ),
    case(
        "arrangement", "erroneous", "typo_four_cone_line_behind", "arange 4 cone in line behind the ego car",
        [delta("traffic_cone", 4), {"kind": "arrangement", "category": "traffic_cone", "shape": "line", "min_count": 4},
         {"kind": "relative", "category": "traffic_cone", "scope": "added", "relation": "behind", "target": "ego",
          "max_distance": 30, "require_all": True}, guard("traffic_cone")],
        [call("arrange_assets", categories=["traffic_cone"], shape="line", count=4, location=at("ego", "behind", distance=10))],
    ),
    case(
        "arrangement", "erroneous", "voice_ring_of_bowlards", "make a hole ring of bowlards round the fountain",
        [delta("bollard", 3, 40), {"kind": "arrangement", "category": "bollard", "shape": "ring", "around": "fountain"},
         guard("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="ring", count=8, location=at("fountain"), radius=5)],
    ),
    case(
        "arrangement", "erroneous", "typo_parkign_row_suvs", "parkign row of 3 suv's in lot B",
        [delta("suv", 3), {"kind": "arrangement", "category": "suv", "shape": "line", "min_count": 3},
         near("suv", "parking lot B", 1, require_all=True), guard("suv")],
        [call("arrange_assets", categories=["suv"], shape="parking_row", count=3, location=at("parking lot B"))],
    ),
    impossible(
        "arrangement", "indirect", "ring_of_150_bollards",
        "I'd want the fountain fenced in properly: a ring of 150 bollards around it.",
        [call("arrange_assets", categories=["bollard"], shape="ring", count=150, location=at("fountain"), radius=10)],
    ),
    case(
        "arrangement", "indirect", "us_work_zone_cones_and_sign",
        "I'm testing a work zone: five cones along the edge of our lane, and a construction sign ten meters ahead of us.",
        [delta("traffic_cone", 5), delta("construction_sign", 1),
         near("traffic_cone", "main_eastbound", 3, require_all=True),
         {"kind": "relative", "category": "construction_sign", "scope": "added", "relation": "in_front_of", "target": "ego",
          "max_distance": 20}, guard("traffic_cone", "construction_sign")],
        [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=5, location=at("main_eastbound", "in_lane")),
         call("add_asset", category="construction_sign", location=at("ego", "in_front_of", distance=10))],
        tags=("compound",),
    ),
    case(
        "arrangement", "vague", "pm_proper_queue_in_lot_a", "Let's have a proper row of parked vehicles in lot A.",
        [delta(VEHICLES, 3, 20), {"kind": "arrangement", "category": VEHICLES, "shape": "line", "min_count": 3},
         near(VEHICLES, "parking lot A", 1, require_all=True), guard(*VEHICLES)],
        [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4, location=at("parking lot A"))],
    ),
    case(
        "arrangement", "vague", "circle_of_trees_round_fountain", "a circle of trees round the fountain would look nice",
        [delta("tree", 3, 20), {"kind": "arrangement", "category": "tree", "shape": "ring", "around": "fountain"},
         guard("tree")],
        [call("arrange_assets", categories=["tree"], shape="ring", count=6, location=at("fountain"), radius=12)],
    ),
    case(
        "arrangement", "vague", "backref_bollard_line_engineering", "repeat that outside Engineering Hall",
        [delta("bollard", 4), {"kind": "arrangement", "category": "bollard", "shape": "line", "min_count": 4},
         near("bollard", "Engineering Hall entrance", 15, require_all=True), guard("bollard")],
        [call("arrange_assets", categories=["bollard"], shape="line", count=4, spacing=2,
              location=at("Engineering Hall entrance", "on_sidewalk"))],
        setup=[turn("Put a line of four bollards on the pavement outside the Library.",
                    [call("arrange_assets", categories=["bollard"], shape="line", count=4, spacing=2,
                          location=at("Library entrance", "on_sidewalk"))], planned=True)],
    ),
    case(
        "arrangement", "erroneous", "typo_berriers_lien_behind", "put 4 berriers in a lien across the road behind us",
        [delta("road_barrier", 4), {"kind": "arrangement", "category": "road_barrier", "shape": "line", "min_count": 4},
         {"kind": "relative", "category": "road_barrier", "scope": "added", "relation": "behind", "target": "ego",
          "max_distance": 30, "tolerance_deg": 75, "require_all": True}, guard("road_barrier")],
        [call("arrange_assets", categories=["road_barrier"], shape="line", count=4, location=at("ego", "behind", distance=15))],
    ),
    case(
        "arrangement", "erroneous", "voice_ring_and_row_buy_bus_stop",
        "ring of cones round the crossroads and a row of bollards buy the bus stop",
        [delta("traffic_cone", 3, 40), delta("bollard", 3, 15),
         {"kind": "arrangement", "category": "traffic_cone", "shape": "ring", "around": "main intersection"},
         {"kind": "arrangement", "category": "bollard", "shape": "line"},
         near("bollard", "bus stop", 15, require_all=True), guard("traffic_cone", "bollard")],
        [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=8, location=at("main intersection"), radius=5),
         call("arrange_assets", categories=["bollard"], shape="line", count=5, spacing=2, location=at("bus stop", "on_sidewalk"))],
        tags=("compound",),
    ),
    impossible(
        "arrangement", "erroneous", "ring_of_trees_radius_200", "make a ring of trees around the libary, radius 200 m",
        [call("arrange_assets", categories=["tree"], shape="ring", count=12, location=at("Library entrance"), radius=200)],
    ),
]

APPEARANCE: list[Json] = [
    case(
        "appearance", "direct", "bench_green", "Paint the bench by the bus stop green.",
        [looks(asset="bench_1", colour="green"), guard(assets=["bench_1"])],
        [call("set_asset_appearance", assets=["bench_1"], colour="green")],
    ),
    case(
        "appearance", "direct", "clock_twenty_one_fifteen", "Set the time to 21:15.",
        [env(time_from="21:10", time_to="21:20"), guard(environment=True)],
        [call("set_time_of_day", time="21:15")],
    ),
    case(
        "appearance", "direct", "qa_heavy_snow", "Steps: set weather to heavy snow. Expected: snow at high intensity.",
        [env(weather=["snow"], intensity_min=0.7), guard(environment=True)],
        [call("set_weather", kind="snow", intensity=0.9)],
    ),
    case(
        "appearance", "direct", "street_lights_black_metal", "Make all the street lights black metal.",
        [looks(category="street_light", colour="black", material="metal", min_count=12, require_all=True), guard("street_light")],
        [call("set_asset_appearance", category="street_light", colour="black", material="metal")],
    ),
    case(
        "appearance", "direct", "uk_street_lamps_on", "Switch the street lamps on.",
        [env(street_lights="on"), guard(environment=True)],
        [call("set_lighting", street_lights="on")],
    ),
    case(
        "appearance", "indirect", "instructor_night_lesson",
        "Tomorrow is the night-driving lesson, so I want the scene in darkness with the street lamps lit.",
        [env(night=True, street_lights="on"), guard(environment=True)],
        [call("set_time_of_day", time="22:00"), call("set_lighting", street_lights="on")],
        tags=("compound",),
    ),
    case(
        "appearance", "indirect", "pm_showcase_wipers_downpour",
        "For the demo we need to showcase the wipers under real downpour conditions.",
        [env(weather=["rain"], intensity_min=0.7), guard(environment=True)],
        [call("set_weather", kind="rain", intensity=0.9)],
    ),
    case(
        "appearance", "indirect", "passive_repaint_suv_red", "A repainting of the SUV in red is requested.",
        [looks(asset="suv_1", colour="red"), guard(assets=["suv_1"])],
        [call("set_asset_appearance", assets=["suv_1"], colour="red")],
    ),
    case(
        "appearance", "indirect", "parent_misty_like_grandmas",
        "Let's make it all misty outside, like the day we drove to Grandma's and couldn't see the hills.",
        [env(weather=["fog"]), guard(environment=True)],
        [call("set_weather", kind="fog", intensity=0.6)],
    ),
    case(
        "appearance", "indirect", "us_camera_at_sunset",
        "I want to see how the camera copes when the sun is going down.",
        [env(time_from="17:00", time_to="20:30"), guard(environment=True)],
        [call("set_time_of_day", time="sunset")],
    ),
    case(
        "appearance", "vague", "gloomier", "gloomier please",
        [guard(environment=True)],
        [call("set_weather", kind="cloudy", intensity=0.7)],
        alternatives=[
            [env(weather=["cloudy", "rain", "fog", "snow"])],
            [env(time_from="17:00", time_to="06:00")],
            [env(exposure_max=0.9)],
        ],
    ),
    case(
        "appearance", "vague", "voice_half_seven_evening", "can it be like half seven in the evening",
        [env(time_from="19:20", time_to="19:40"), guard(environment=True)],
        [call("set_time_of_day", time="19:30")],
    ),
    case(
        "appearance", "vague", "cars_look_samey", "the cars in the lot all look a bit samey",
        [looks(category=["passenger_car", "suv"], min_count=1), guard(assets=PARKED_IN_LOT_B)],
        [call("set_asset_appearance", assets=["passenger_car_1"], colour="blue"),
         call("set_asset_appearance", assets=["suv_1"], colour="white")],
    ),
    case(
        "appearance", "vague", "backref_same_for_trash_can", "now the trash can in that colour too",
        [looks(asset="trash_bin_1", colour="yellow"), guard(assets=["trash_bin_1"])],
        [call("set_asset_appearance", assets=["trash_bin_1"], colour="yellow")],
        setup=[turn("Paint the bus stop bench yellow.", [call("set_asset_appearance", assets=["bench_1"], colour="yellow")])],
    ),
    case(
        "appearance", "erroneous", "typo_raning_lightly", "make it raning lightly",
        [env(weather=["rain"], intensity_max=0.5), guard(environment=True)],
        [call("set_weather", kind="rain", intensity=0.3)],
    ),
    case(
        "appearance", "erroneous", "voice_hydrant_read", "paint the hydrant read",
        [looks(asset="fire_hydrant_1", colour="red"), guard(assets=["fire_hydrant_1"])],
        [call("set_asset_appearance", assets=["fire_hydrant_1"], colour="red")],
    ),
    case(
        "appearance", "erroneous", "non_native_six_oclock_pm", "set time to 6 o clock pm",
        [env(time_from="17:55", time_to="18:05"), guard(environment=True)],
        [call("set_time_of_day", time="18:00")],
    ),
    impossible(
        "appearance", "direct", "make_it_hail", "Make it hail.",
        [call("set_weather", kind="hail")],
    ),
    case(
        "appearance", "indirect", "uk_drizzly_november_evening",
        "It's meant to be a drizzly November evening: light rain, and the clock at about half five.",
        [env(weather=["rain"], intensity_max=0.5, time_from="17:20", time_to="17:40"), guard(environment=True)],
        [call("set_weather", kind="rain", intensity=0.3), call("set_time_of_day", time="17:30")],
        tags=("compound",),
    ),
    case(
        "appearance", "indirect", "passive_activation_of_headlights", "Activation of the vehicle headlights is required.",
        [env(vehicle_lights="on"), guard(environment=True)],
        [call("set_lighting", vehicle_lights="on")],
    ),
    impossible(
        "appearance", "indirect", "proper_thunderstorm",
        "For the sensor stress test we want a proper thunderstorm with lightning.",
        [call("set_weather", kind="thunderstorm", intensity=1.0)],
    ),
    case(
        "appearance", "vague", "everything_in_lot_b_white", "everything in lot B should be white",
        [looks(category=["passenger_car", "suv"], scope="all", colour="white", min_count=3, require_all=True),
         guard(assets=PARKED_IN_LOT_B)],
        [call("set_asset_appearance", assets=PARKED_IN_LOT_B, colour="white")],
    ),
    case(
        "appearance", "vague", "parent_banana_bench_and_bin",
        "let's make the bench as yellow as a banana, and the bin next to it too",
        [looks(asset="bench_1", colour="yellow"), looks(asset="trash_bin_1", colour="yellow"),
         guard(assets=["bench_1", "trash_bin_1"])],
        [call("set_asset_appearance", assets=["bench_1"], colour="yellow"),
         call("set_asset_appearance", assets=["trash_bin_1"], colour="yellow")],
        tags=("compound",),
    ),
    case(
        "appearance", "vague", "brighter", "brighter",
        [env(exposure_min=1.1), guard(environment=True)],
        [call("set_lighting", exposure=1.5)],
    ),
    case(
        "appearance", "erroneous", "typo_fogy_and_dusk", "set the wether to fogy and the time too dusk",
        [env(weather=["fog"], time_from="17:00", time_to="20:30"), guard(environment=True)],
        [call("set_weather", kind="fog", intensity=0.6), call("set_time_of_day", time="dusk")],
        tags=("compound",),
    ),
    case(
        "appearance", "erroneous", "voice_cars_read_accept_suv", "make all the cars read accept the suv",
        [looks(category="passenger_car", scope="all", colour="red", min_count=2, require_all=True),
         guard("passenger_car")],
        [call("set_asset_appearance", category="passenger_car", colour="red")],
    ),
]

ALL_CASES: list[Json] = [*SEARCH, *ADDITION, *REMOVAL, *POSITIONING, *MOVING, *ARRANGEMENT, *APPEARANCE]


def write(path: Path = SUITE_PATH) -> int:
    """Write every case as one JSON line; return how many."""
    path.write_text("".join(json.dumps(c) + "\n" for c in ALL_CASES), encoding="utf-8")
    return len(ALL_CASES)


if __name__ == "__main__":
    print(f"wrote {write()} cases to {SUITE_PATH}")
