"""The second practice suite (`suites/practice2.jsonl`), a third development suite, as a plain case list.

Written from the campus world, the catalog, the Worker tools and the checks only, by a helper
who had not read the planners or any other suite. `python -m drivetwin.evals.practice2_source`
rewrites the JSONL. Each case's `reference` is a plan the Workers carry out (or, for the
impossible requests, really refuse) so that the reference planner passes every case.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

Json = dict[str, Any]

# resolve(): under a strict editable install this module is a link into the build tree.
SUITE_PATH = Path(__file__).resolve().parent / "suites" / "practice2.jsonl"
SUITE_TAG = "practice2"

VEHICLES = ["passenger_car", "suv", "truck", "bus", "motorcycle", "ackermann_robot"]
CARS = ["passenger_car", "suv"]
BARRIERS = ["traffic_cone", "road_barrier", "bollard", "construction_sign"]
LOT_B_CARS = ["passenger_car_1", "passenger_car_2", "suv_1"]


def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def at(target: str, relation: str = "at", **more: Any) -> Json:
    return {"relation": relation, "target": target, **more}


def xy(x: float, y: float) -> Json:
    return {"relation": "absolute", "x": x, "y": y}


def step(prompt: str, *calls: Json, planned: bool = False) -> Json:
    return {"prompt": prompt, "calls": list(calls), "planned": planned}


def only(*categories: str, assets: tuple[str, ...] = (), environment: bool = False) -> Json:
    """Guard against collateral edits: nothing but these may change."""
    return {"kind": "unchanged_except", "categories": list(categories), "assets": list(assets), "environment": environment}


def delta(category: str | list[str], lo: int | None, hi: int | None) -> Json:
    return {"kind": "count_delta", "category": category, "min": lo, "max": hi}


def count(category: str | list[str], lo: int | None, hi: int | None) -> Json:
    return {"kind": "count", "category": category, "min": lo, "max": hi}


def near(target: str, within: float, **sel: Any) -> Json:
    return {"kind": "near", "target": target, "within": within, **sel}


def near_point(x: float, y: float, within: float, **sel: Any) -> Json:
    return {"kind": "near", "point": [x, y], "within": within, **sel}


def relative(relation: str, target: str, max_distance: float = 15.0, **sel: Any) -> Json:
    return {"kind": "relative", "relation": relation, "target": target, "max_distance": max_distance, **sel}


def surface(*surfaces: str, **sel: Any) -> Json:
    return {"kind": "on_surface", "surfaces": list(surfaces), **sel}


def lane(lane_id: str | None = None, **sel: Any) -> Json:
    return {"kind": "in_lane", "lane": lane_id, **sel}


def layout(shape: str, **more: Any) -> Json:
    return {"kind": "arrangement", "shape": shape, **more}


def behaviour(kind: str | list[str], **more: Any) -> Json:
    return {"kind": "behaviour", "behaviour": kind, **more}


def env(**more: Any) -> Json:
    return {"kind": "environment", **more}


def looks(**more: Any) -> Json:
    return {"kind": "appearance", **more}


def moved(asset: str, lo: float = 0.0, hi: float | None = None, **more: Any) -> Json:
    return {"kind": "moved", "asset": asset, "min_distance": lo, "max_distance": hi, **more}


def gone(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": False}


def says(*any_of: str, all_of: tuple[str, ...] = (), none_of: tuple[str, ...] = ()) -> Json:
    return {"kind": "answer_contains", "any_of": list(any_of), "all_of": list(all_of), "none_of": list(none_of)}


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
        if "multi_turn" not in tags:
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
BARRIER_AHEAD = step(
    "Put a road barrier 25 m ahead of the ego in its lane.",
    call("add_asset", category="road_barrier", location=at("ego", along_m=25.0)),
)
CONES_AHEAD = step(
    "Add three traffic cones 20 m in front of the ego, in its lane.",
    call("add_asset", category="traffic_cone", count=3, location=at("ego", along_m=20.0)),
)

SEARCH: list[Json] = [
    # direct
    case("search.direct.tree_count", "How many trees are there in the scene?", [*QUESTION, says("4", "four")],
         [call("find_assets", category="tree")]),
    case("search.direct.nearest_landmark_to_ego", "Which named place is closest to the ego vehicle right now?",
         [*QUESTION, says("parking lot A", "lot A")], [call("find_landmarks", nearest_to="ego")]),
    case("search.direct.campus_drive_lanes", "List the lanes that make up Campus Drive.",
         [*QUESTION, says(all_of=("campus_northbound", "campus_southbound"))], [call("find_lanes", road="Campus Drive")]),
    case("search.direct.bus_mass", "What is the mass of a bus?",
         [*QUESTION, says("12000", "12,000", "12 000", "12 t", "12 tonnes")], [call("asset_properties", category="bus")]),
    case("search.direct.lamps_within_20m_of_ego", "Which street lights stand within 20 m of the ego?",
         [*QUESTION, says(all_of=("street_light_2", "street_light_3"), none_of=("street_light_1", "street_light_4"))],
         [call("find_assets", category="street_light", near="ego", within=20.0)]),
    case("search.direct.nearest_car_to_ego", "Which passenger car is nearest to the ego?",
         [*QUESTION, says("passenger_car_1")], [call("find_assets", category="passenger_car", nearest_to="ego")]),
    case("search.direct.things_at_bus_stop", "What is within 5 m of the bus stop?",
         [*QUESTION, says(all_of=("bench", "trash bin"), none_of=("street_light_4",))],
         [call("find_assets", near="bus stop", within=5.0)]),
    case("search.direct.lane_nearest_library", "Which lane is nearest the Library entrance?",
         [*QUESTION, says("main_eastbound", "eastbound")], [call("find_lanes", near="Library entrance")]),
    case("search.direct.assets_on_lanes", "Which assets are standing on a lane?",
         [*QUESTION, says("traffic_cone", "traffic cones", "cones")], [call("find_assets", on_lane=True)],
         setup=(CONES_AHEAD,)),
    # indirect
    case("search.indirect.lamp_count_for_report", "For my report I need the number of street lamps in the scene.",
         [*QUESTION, says("12", "twelve")], [call("find_assets", category="street_light")]),
    case("search.indirect.landmark_by_fountain", "I'm curious which landmark sits closest to the fountain.",
         [*QUESTION, says("JTEKT building entrance", "JTEKT")], [call("find_landmarks", nearest_to="fountain")]),
    case("search.indirect.eastbound_blocked", "Can you tell me whether anything is blocking the eastbound lane of Main Street?",
         [*QUESTION, says("road_barrier", "barrier")], [call("find_assets", lane="main_eastbound")],
         setup=(BARRIER_AHEAD,)),
    case("search.indirect.truck_size", "Before I drop a truck in, how big is one?",
         [*QUESTION, says("8x2.5x3.4", "8 m", "8", "3.4")], [call("asset_properties", category="truck")]),
    case("search.indirect.main_street_lanes", "It would help me to know which lanes Main Street has.",
         [*QUESTION, says(all_of=("main_eastbound", "main_westbound"))], [call("find_lanes", road="Main Street")]),
    case("search.indirect.tree_closest_to_ego", "Tell me, please, which tree grows closest to the ego car.",
         [*QUESTION, says("tree_1")], [call("find_assets", category="tree", nearest_to="ego")]),
    case("search.indirect.suv_weight", "Out of interest, how heavy is the SUV parked in lot B?",
         [*QUESTION, says("2100", "2,100", "2 100", "2.1 t")], [call("asset_properties", asset="suv_1")]),
    case("search.indirect.ego_lane", "I need to know which lane the ego is driving in before I add traffic.",
         [*QUESTION, says("main_eastbound", "eastbound")], [call("find_assets", on_lane=True)]),
    case("search.indirect.bus_stop_distance", "Would you check how far the bus stop is from the ego?",
         [*QUESTION, says("30.2", "30", "30.23")], [call("find_landmarks", nearest_to="ego")]),
    case("search.indirect.entrance_of_lot_b_light", "Before I put a sign there I'd want to know what already stands within 12 m of the lot B driveway.",
         [*QUESTION, says("street_light_8", "street light")], [call("find_assets", near="parking lot B entrance", within=12.0)]),
    # vague
    case("search.vague.around_the_ego", "what's around the ego?",
         [*QUESTION, says("street_light_2", "street light", "parking lot A", "lot A", "street_light_3")],
         [call("find_assets", nearest_to="ego")]),
    case("search.vague.anything_in_the_way", "anything in the way?", [*QUESTION, says("road_barrier", "barrier")],
         [call("find_assets", on_lane=True)], setup=(BARRIER_AHEAD,)),
    case("search.vague.trees", "trees?", [*QUESTION, says("4", "four", "tree_1")], [call("find_assets", category="tree")]),
    case("search.vague.where_to_park", "where could one park around here?",
         [*QUESTION, says("parking lot A", "parking lot B", "lot A", "lot B")], [call("find_landmarks", query="parking")]),
    case("search.vague.closest_to_fountain", "what's closest to the fountain", [*QUESTION, says("tree_2", "tree")],
         [call("find_assets", nearest_to="fountain")]),
    case("search.vague.roads", "which roads are there", [*QUESTION, says(all_of=("Main Street", "Campus Drive"))],
         [call("find_lanes")]),
    case("search.vague.near_library", "what's the nearest spot to the library?", [*QUESTION, says("bus stop")],
         [call("find_landmarks", nearest_to="Library entrance")]),
    case("search.vague.cars_by_union", "any vehicles near the union?",
         [*QUESTION, says("passenger_car_2", "suv_1", "passenger_car_1", "car", "suv")],
         [call("find_assets", near="Student Union entrance", within=30.0)]),
    case("search.vague.how_many_things", "how much stuff is in this scene anyway?", [*QUESTION, says("25", "26")],
         [call("find_assets")]),
    case("search.vague.stadium", "what's going on over by the stadium?", REFUSED,
         [call("find_assets", near="stadium", within=20.0)], tags=IMPOSSIBLE, notes="the campus has no stadium"),
    # erroneous
    case("search.erroneous.tree_count", "how meny tress are in the sceen", [*QUESTION, says("4", "four")],
         [call("find_assets", category="tree")]),
    case("search.erroneous.nearest_landmark", "wich named place is most close to ego car?",
         [*QUESTION, says("parking lot A", "lot A")], [call("find_landmarks", nearest_to="ego")]),
    case("search.erroneous.main_street_lanes", "what lanes has Main streat", [*QUESTION, says(all_of=("main_eastbound", "main_westbound"))],
         [call("find_lanes", road="Main Street")]),
    case("search.erroneous.truck_weight", "how much weigh a truk?", [*QUESTION, says("9000", "9,000", "9 000", "9 t")],
         [call("asset_properties", category="truck")]),
    case("search.erroneous.nearest_car", "where is the nerest car from the ego", [*QUESTION, says("passenger_car_1")],
         [call("find_assets", category="passenger_car", nearest_to="ego")]),
    case("search.erroneous.bus_stop_things", "waht is standing at bus stopp, in 5 meter?", [*QUESTION, says(all_of=("bench", "trash bin"))],
         [call("find_assets", near="bus stop", within=5.0)]),
    case("search.erroneous.road_blocked", "is there some thing block the road?", [*QUESTION, says("road_barrier", "barrier")],
         [call("find_assets", on_lane=True)], setup=(BARRIER_AHEAD,)),
    case("search.erroneous.lamps_near_ego", "tell me the light pole near of ego in 20 meter",
         [*QUESTION, says(all_of=("street_light_2", "street_light_3"), none_of=("street_light_1",))],
         [call("find_assets", category="street_light", near="ego", within=20.0)]),
    case("search.erroneous.helicopters", "how many helicopter are parkd on campus?", REFUSED,
         [call("find_assets", category="helicopter")], tags=IMPOSSIBLE, notes="no such category"),
]


ADDITION: list[Json] = [
    # direct
    case("addition.direct.cones_ahead_of_ego", "Add three traffic cones 15 m in front of the ego vehicle.",
         [delta("traffic_cone", 3, 3), relative("in_front_of", "ego", 25.0, category="traffic_cone", require_all=True),
          only("traffic_cone")],
         [call("add_asset", category="traffic_cone", count=3, location=at("ego", along_m=15.0))]),
    case("addition.direct.bus_at_stop", "Put a bus at the bus stop.",
         [delta("bus", 1, 1), near("bus stop", 12.0, category="bus"), only("bus")],
         [call("add_asset", category="bus", location=at("bus stop"))]),
    case("addition.direct.truck_westbound_10", "Add a truck driving in the westbound lane of Main Street at 10 m/s.",
         [delta("truck", 1, 1), behaviour("drive_lane", category="truck", lane="main_westbound", speed_min=9.0, speed_max=11.0),
          only("truck")],
         [call("add_asset", category="truck", location=at("main_westbound", "in_lane"),
               behaviour={"kind": "drive_lane", "lane": "main_westbound", "speed": 10.0})]),
    case("addition.direct.parking_sign_lot_a_entrance", "Place a parking sign at the entrance of parking lot A.",
         [delta("parking_sign", 1, 1), near("parking lot A entrance", 6.0, category="parking_sign"), only("parking_sign")],
         [call("add_asset", category="parking_sign", location=at("parking lot A entrance"))]),
    case("addition.direct.two_pedestrians_library_sidewalk", "Add two pedestrians on the sidewalk near the Library entrance.",
         [delta("pedestrian", 2, 2), surface("sidewalk", category="pedestrian", scope="added"),
          near("Library entrance", 15.0, category="pedestrian", require_all=True), only("pedestrian")],
         [call("add_asset", category="pedestrian", count=2, location=at("Library entrance", "on_sidewalk"))]),
    case("addition.direct.hydrant_at_coordinates", "Add a fire hydrant at x = 30, y = 5.5.",
         [delta("fire_hydrant", 1, 1), near_point(30.0, 5.5, 1.0, category="fire_hydrant"), only("fire_hydrant")],
         [call("add_asset", category="fire_hydrant", location=xy(30.0, 5.5))]),
    case("addition.direct.car_behind_ego", "Put a passenger car 12 m behind the ego in the same lane.",
         [delta("passenger_car", 1, 1), relative("behind", "ego", 20.0, category="passenger_car", scope="added"),
          lane("main_eastbound", category="passenger_car", scope="added"), only("passenger_car")],
         [call("add_asset", category="passenger_car", location=at("ego", along_m=-12.0))]),
    case("addition.direct.rover_circling_fountain", "Add a small research rover that drives a 6 m radius circle around the middle of the crossroads.",
         [delta("ackermann_robot", 1, 1), behaviour("circle", category="ackermann_robot", radius_min=5.0, radius_max=7.0, centre_near="main intersection",
                                            centre_within=5.0), only("ackermann_robot")],
         [call("add_asset", category="ackermann_robot", location=at("main intersection", distance=6.0),
               behaviour={"kind": "circle", "radius": 6.0, "centre": "main intersection"})]),
    case("addition.direct.fifty_five_cones", "Add 55 traffic cones at the main intersection.", REFUSED,
         [call("add_asset", category="traffic_cone", count=55, location=at("main intersection"))], tags=IMPOSSIBLE,
         notes="one add places at most 50"),
    # indirect
    case("addition.indirect.broken_down_van", "I want to see how the ego copes with a broken-down van sitting in its lane about 40 m ahead.",
         [delta(VEHICLES, 1, 1), lane("main_eastbound", category=VEHICLES, scope="added"),
          relative("in_front_of", "ego", 55.0, category=VEHICLES, scope="added"), only(*VEHICLES)],
         [call("add_asset", category="truck", location=at("ego", along_m=40.0))]),
    case("addition.indirect.people_waiting_for_bus", "The bus stop looks deserted; there should be a few people waiting there.",
         [delta("pedestrian", 2, 6), near("bus stop", 10.0, category="pedestrian", require_all=True), only("pedestrian")],
         [call("add_asset", category="pedestrian", count=3, location=at("bus stop"))]),
    case("addition.indirect.someone_steps_out", "We need to check the ego's reaction when somebody steps onto the road in front of it without using a crossing.",
         [delta("pedestrian", 1, 2), behaviour(["jaywalk", "cross_road"], category="pedestrian"), only("pedestrian")],
         [call("add_asset", category="pedestrian", behaviour={"kind": "jaywalk", "ahead": 25.0})]),
    case("addition.indirect.seat_outside_library", "Students at the library could use somewhere to sit outside.",
         [delta("bench", 1, 3), near("Library entrance", 15.0, category="bench", require_all=True), only("bench")],
         [call("add_asset", category="bench", location=at("Library entrance"))]),
    case("addition.indirect.lot_b_fuller", "Lot B should look a bit fuller, say a couple of extra SUVs parked there.",
         [delta("suv", 2, 2), near("parking lot B", 3.0, category="suv", require_all=True), only("suv")],
         [call("add_asset", category="suv", count=2, location=at("parking lot B"))]),
    case("addition.indirect.northbound_traffic", "Campus Drive feels dead; a car heading north on it would help.",
         [delta(VEHICLES, 1, 3), behaviour("drive_lane", category=VEHICLES, lane="campus_northbound"), only(*VEHICLES)],
         [call("add_asset", category="passenger_car", location=at("campus_northbound", "in_lane"),
               behaviour={"kind": "drive_lane", "lane": "campus_northbound"})]),
    case("addition.indirect.dark_fountain", "The fountain area is too dark at night, it needs a lamp post.",
         [delta("street_light", 1, 2), near("fountain", 12.0, category="street_light", require_all=True), only("street_light")],
         [call("add_asset", category="street_light", location=at("fountain", "next_to"))]),
    case("addition.indirect.hydrant_for_jtekt", "Fire safety says the JTEKT entrance needs a hydrant close by.",
         [delta("fire_hydrant", 1, 1), near("JTEKT building entrance", 10.0, category="fire_hydrant"), only("fire_hydrant")],
         [call("add_asset", category="fire_hydrant", location=at("JTEKT building entrance", "next_to"))]),
    case("addition.indirect.stop_leaving_lot_b", "Cars leaving lot B should have to stop before they pull out onto Main Street.",
         [delta("stop_sign", 1, 1), near("parking lot B entrance", 8.0, category="stop_sign"), only("stop_sign")],
         [call("add_asset", category="stop_sign", location=at("parking lot B entrance", "next_to"))]),
    case("addition.indirect.bench_inside_library", "I want a bench inside the Library, by the reading tables at x -40, y -30.", REFUSED,
         [call("add_asset", category="bench", location=xy(-40.0, -30.0))], tags=IMPOSSIBLE, notes="inside a building"),
    # vague
    case("addition.vague.some_cones", "add some cones", [delta("traffic_cone", 1, 20), only("traffic_cone")],
         [call("add_asset", category="traffic_cone", count=4)]),
    case("addition.vague.more_greenery", "more greenery please", [delta("tree", 1, 20), only("tree")],
         [call("add_asset", category="tree", count=3, location=at("fountain"))]),
    case("addition.vague.people_at_quad", "a few people near the fountain",
         [delta("pedestrian", 2, 6), near("fountain", 15.0, category="pedestrian", require_all=True), only("pedestrian")],
         [call("add_asset", category="pedestrian", count=3, location=at("fountain"))]),
    case("addition.vague.keep_cars_out_of_lot_b", "something at the lot B driveway to keep cars out",
         [delta(BARRIERS, 1, 10), near("parking lot B entrance", 10.0, category=BARRIERS, scope="added", require_all=True),
          only(*BARRIERS)],
         [call("add_asset", category="road_barrier", location=at("parking lot B entrance"))]),
    case("addition.vague.another_vehicle_on_road", "throw another vehicle onto the road somewhere",
         [delta(VEHICLES, 1, 1), surface("lane", "drivable", category=VEHICLES, scope="added"), only(*VEHICLES)],
         [call("add_asset", category="passenger_car", location=at("main_westbound", "in_lane"))]),
    case("addition.vague.scooter_by_ego", "a scooter by the ego",
         [delta("motorcycle", 1, 1), near("ego", 15.0, category="motorcycle"), only("motorcycle")],
         [call("add_asset", category="motorcycle", location=at("ego", "next_to"))]),
    case("addition.vague.rover_by_union", "one of those small research rovers by the union, maybe",
         [delta("ackermann_robot", 1, 1), near("Student Union entrance", 15.0, category="ackermann_robot"), only("ackermann_robot")],
         [call("add_asset", category="ackermann_robot", location=at("Student Union entrance", "next_to"))]),
    case("addition.vague.busier_main_street", "main street needs more going on, traffic wise",
         [delta(VEHICLES, 2, 10), behaviour("drive_lane", category=VEHICLES, scope="added", min_count=2), only(*VEHICLES)],
         [call("add_asset", category="passenger_car", count=3, location=at("main_westbound", "in_lane"),
               behaviour={"kind": "drive_lane", "lane": "main_westbound"})]),
    case("addition.vague.rubbish_by_bench", "somewhere to throw rubbish near the bench would be good",
         [delta("trash_bin", 1, 1), near("bench_1", 8.0, category="trash_bin"), only("trash_bin")],
         [call("add_asset", category="trash_bin", location=at("bench_1", "next_to"))]),
    case("addition.vague.on_the_roof", "something on top of the JTEKT roof, a tree maybe, at 40, 30", REFUSED,
         [call("add_asset", category="tree", location=xy(40.0, 30.0))], tags=IMPOSSIBLE, notes="inside the building's footprint"),
    # erroneous
    case("addition.erroneous.two_cones_ahead", "ad 2 trafic cone infront the ego",
         [delta("traffic_cone", 2, 2), relative("in_front_of", "ego", 30.0, category="traffic_cone", require_all=True),
          only("traffic_cone")],
         [call("add_asset", category="traffic_cone", count=2, location=at("ego", along_m=15.0))]),
    case("addition.erroneous.bus_at_stop", "plase add a buss at the bus stopp",
         [delta("bus", 1, 1), near("bus stop", 12.0, category="bus"), only("bus")],
         [call("add_asset", category="bus", location=at("bus stop"))]),
    case("addition.erroneous.bike_by_fountain", "put one bycicle near of fountain",
         [delta("bicycle", 1, 1), near("fountain", 12.0, category="bicycle"), only("bicycle")],
         [call("add_asset", category="bicycle", location=at("fountain", "next_to"))]),
    case("addition.erroneous.pedestrian_jtekt_sidewalk", "add pedestrain on side walk next JTEKT entrence",
         [delta("pedestrian", 1, 1), surface("sidewalk", category="pedestrian", scope="added"),
          near("JTEKT building entrance", 15.0, category="pedestrian"), only("pedestrian")],
         [call("add_asset", category="pedestrian", location=at("JTEKT building entrance", "on_sidewalk"))]),
    case("addition.erroneous.tree_in_lot_a", "i want more one tree in lot A",
         [delta("tree", 1, 1), near("parking lot A", 5.0, category="tree"), only("tree")],
         [call("add_asset", category="tree", location=at("parking lot A"))]),
    case("addition.erroneous.suv_southbound", "addd a suv driveing on campus drive to south",
         [delta("suv", 1, 1), behaviour("drive_lane", category="suv", lane="campus_southbound"), only("suv")],
         [call("add_asset", category="suv", location=at("campus_southbound", "in_lane"),
               behaviour={"kind": "drive_lane", "lane": "campus_southbound"})]),
    case("addition.erroneous.stop_sign_west_crosswalk", "put a stop sing at the crosswalk of west",
         [delta("stop_sign", 1, 1), near("west crosswalk", 8.0, category="stop_sign"), only("stop_sign")],
         [call("add_asset", category="stop_sign", location=at("west crosswalk", "next_to"))]),
    case("addition.erroneous.bollards_library", "add 3 bolard in front of library entrence",
         [delta("bollard", 3, 3), near("Library entrance", 10.0, category="bollard", require_all=True), only("bollard")],
         [call("add_asset", category="bollard", count=3, location=at("Library entrance", "in_front_of"))]),
    case("addition.erroneous.unicorn", "add a unicorn next the ego pls", REFUSED,
         [call("add_asset", category="unicorn", location=at("ego", "next_to"))], tags=IMPOSSIBLE, notes="no such category"),
]

ARRANGEMENT: list[Json] = [
    # direct
    case("arrangement.direct.cones_lane_edge", "Line five traffic cones along the edge of the ego's lane, starting 30 m ahead of it.",
         [delta("traffic_cone", 5, 5), layout("line", category="traffic_cone", min_count=5, tolerance=1.5),
          near("main_eastbound", 3.0, category="traffic_cone", scope="added", require_all=True), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=5, location=at("ego", along_m=30.0))]),
    case("arrangement.direct.bollard_ring_fountain", "Place six bollards in a ring of radius 5 m around the fountain.",
         [delta("bollard", 6, 6), layout("ring", category="bollard", around="fountain", min_count=6), only("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="ring", count=6, radius=5.0, location=at("fountain"))]),
    case("arrangement.direct.parking_row_lot_a", "Park four passenger cars side by side in parking lot A.",
         [delta("passenger_car", 4, 4), layout("line", category="passenger_car", min_count=4, tolerance=1.5),
          near("parking lot A", 1.0, category="passenger_car", scope="added", require_all=True), only("passenger_car")],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4, location=at("parking lot A"))]),
    case("arrangement.direct.barriers_jtekt", "Put a line of four road barriers by the JTEKT entrance, 3 m apart.",
         [delta("road_barrier", 4, 4), layout("line", category="road_barrier", min_count=4, spacing_min=2.5, spacing_max=3.5),
          near("JTEKT building entrance", 15.0, category="road_barrier", require_all=True), only("road_barrier")],
         [call("arrange_assets", categories=["road_barrier"], shape="line", count=4, spacing=3.0, heading_deg=0.0,
               location=at("JTEKT building entrance"))]),
    case("arrangement.direct.bench_grid_fountain", "Make a grid of six benches in three columns at the fountain.",
         [delta("bench", 6, 6), layout("cluster", category="bench", min_count=6, tolerance=10.0),
          near("fountain", 15.0, category="bench", require_all=True), only("bench")],
         [call("arrange_assets", categories=["bench"], shape="grid", count=6, columns=3, location=at("fountain"))]),
    case("arrangement.direct.trees_north_of_fountain", "Plant five trees in a line running north from the fountain, 6 m apart.",
         [delta("tree", 5, 5), layout("line", category="tree", min_count=5, spacing_min=5.0, spacing_max=7.0),
          near("fountain", 35.0, category="tree", scope="added", require_all=True), only("tree")],
         [call("arrange_assets", categories=["tree"], shape="line", count=5, spacing=6.0, heading_deg=90.0,
               location=at("fountain"))]),
    case("arrangement.direct.cones_ring_stop_sign", "Ring the middle of the crossroads with four cones at a 3 m radius.",
         [delta("traffic_cone", 4, 4), layout("ring", category="traffic_cone", around="main intersection", min_count=4), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=4, radius=3.0, location=at("main intersection"))]),
    case("arrangement.direct.mixed_lane_edge_westbound", "Along the westbound lane's edge by the east gate, lay out eight cones and barriers, alternating.",
         [delta(["traffic_cone", "road_barrier"], 8, 8), count("traffic_cone", 1, None), count("road_barrier", 1, None),
          layout("line", category=["traffic_cone", "road_barrier"], min_count=8, tolerance=1.5),
          near("main_westbound", 3.0, category=["traffic_cone", "road_barrier"], scope="added", require_all=True),
          only("traffic_cone", "road_barrier")],
         [call("arrange_assets", categories=["traffic_cone", "road_barrier"], shape="lane_edge", count=8,
               location=at("main_westbound", "in_lane", distance=0.0))]),
    case("arrangement.direct.hundred_fifty_cones", "Arrange 150 traffic cones in a ring around the main intersection.", REFUSED,
         [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=150, location=at("main intersection"))],
         tags=IMPOSSIBLE, notes="a layout holds at most 100"),
    # indirect
    case("arrangement.indirect.work_zone", "We're simulating a work zone: the eastbound lane needs a run of cones along its edge about 40 m ahead of the ego.",
         [delta("traffic_cone", 4, 20), layout("line", category="traffic_cone", min_count=4, tolerance=1.5),
          near("main_eastbound", 3.0, category="traffic_cone", scope="added", require_all=True), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=6, location=at("ego", along_m=40.0))]),
    case("arrangement.indirect.protect_fountain", "Drivers keep clipping the fountain; protect it with a circle of bollards, please.",
         [delta("bollard", 4, 30), layout("ring", category="bollard", around="fountain", min_count=4, tolerance=1.5), only("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="ring", count=8, radius=4.0, location=at("fountain"))]),
    case("arrangement.indirect.suv_fleet_lot_b", "For the parking test I need three SUVs parked next to each other in lot B.",
         [delta("suv", 3, 3), layout("line", category="suv", min_count=3, tolerance=1.5),
          near("parking lot B", 1.0, category="suv", scope="added", require_all=True), only("suv")],
         [call("arrange_assets", categories=["suv"], shape="parking_row", count=3, location=at("parking lot B"))]),
    case("arrangement.indirect.crowd_at_union", "The union should look busy at lunch time: a group of students standing together out front.",
         [delta("pedestrian", 3, 20), layout("cluster", category="pedestrian", min_count=3, tolerance=8.0),
          near("Student Union entrance", 15.0, category="pedestrian", require_all=True), only("pedestrian")],
         [call("arrange_assets", categories=["pedestrian"], shape="grid", count=6, columns=3, spacing=1.5,
               location=at("Student Union entrance"))]),
    case("arrangement.indirect.close_campus_drive_north", "Campus Drive north of the crossroads is shut for a parade, so block it off with barriers side by side at y = 25.",
         [delta("road_barrier", 2, 6), layout("line", category="road_barrier", min_count=2, tolerance=1.5),
          near_point(0.0, 25.0, 5.0, category="road_barrier", require_all=True),
          surface("lane", "drivable", category="road_barrier", scope="added"), only("road_barrier")],
         [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, spacing=2.5, heading_deg=0.0,
               location=xy(0.0, 25.0))]),
    case("arrangement.indirect.lamps_lot_a", "Lot A is pitch black after sunset; lamp posts in a row along it would fix that.",
         [delta("street_light", 3, 10), layout("line", category="street_light", min_count=3, tolerance=1.5),
          near("parking lot A", 3.0, category="street_light", scope="added", require_all=True), only("street_light")],
         [call("arrange_assets", categories=["street_light"], shape="line", count=4, spacing=7.0, heading_deg=90.0,
               location=xy(-102.0, 29.0))]),
    case("arrangement.indirect.bike_rack_engineering", "Cyclists need somewhere by Engineering Hall, so set up a row of parked bikes at its entrance.",
         [delta("bicycle", 3, 20), layout("line", category="bicycle", min_count=3, tolerance=1.5),
          near("Engineering Hall entrance", 12.0, category="bicycle", require_all=True), only("bicycle")],
         [call("arrange_assets", categories=["bicycle"], shape="line", count=5, spacing=1.0, heading_deg=0.0,
               location=at("Engineering Hall entrance"))]),
    case("arrangement.indirect.queue_at_stop", "It would look realistic if the people at the bus stop stood in a queue, one behind the other.",
         [delta("pedestrian", 3, 10), layout("line", category="pedestrian", min_count=3, tolerance=1.0),
          near("bus stop", 12.0, category="pedestrian", require_all=True), only("pedestrian")],
         [call("arrange_assets", categories=["pedestrian"], shape="line", count=4, spacing=1.0, heading_deg=180.0,
               location=at("bus stop"))]),
    case("arrangement.indirect.huge_tree_ring", "I'd love the Student Union framed by a ring of trees, 100 m in radius.", REFUSED,
         [call("arrange_assets", categories=["tree"], shape="ring", count=12, radius=100.0, location=at("Student Union entrance"))],
         tags=IMPOSSIBLE, notes="a ring's radius is at most 60 m; it would also leave the map"),
    # vague
    case("arrangement.vague.cone_row_main_street", "cones in a row somewhere on main street",
         [delta("traffic_cone", 3, 20), layout("line", category="traffic_cone", min_count=3, tolerance=1.5),
          surface("lane", "drivable", "crossing", category="traffic_cone", scope="added"), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=5, location=at("ego", along_m=50.0))]),
    case("arrangement.vague.circle_stop_sign", "circle of cones in the middle of the junction",
         [delta("traffic_cone", 3, 20), layout("ring", category="traffic_cone", around="main intersection", min_count=3, tolerance=1.5),
          only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=6, radius=4.0, location=at("main intersection"))]),
    case("arrangement.vague.cars_lined_lot_a", "line up a few sedans over at lot A",
         [delta(CARS, 2, 10), layout("line", category=CARS, min_count=2, tolerance=1.5),
          near("parking lot A", 2.0, category=CARS, scope="added", require_all=True), only(*CARS)],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=3, location=at("parking lot A"))]),
    case("arrangement.vague.bollards_round_hydrant", "some bollards around the hydrant",
         [delta("bollard", 3, 20), near("fire_hydrant_1", 6.0, category="bollard", scope="added", require_all=True), only("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="ring", count=4, radius=1.5, location=at("fire_hydrant_1"))]),
    case("arrangement.vague.hanging_out_quad", "a bunch of people hanging out together at the quad",
         [delta("pedestrian", 3, 20), layout("cluster", category="pedestrian", min_count=3, tolerance=8.0),
          near("fountain", 15.0, category="pedestrian", require_all=True), only("pedestrian")],
         [call("arrange_assets", categories=["pedestrian"], shape="grid", count=5, columns=3, spacing=1.5, location=at("fountain"))]),
    case("arrangement.vague.barriers_east_gate", "barriers in a line by the east gate",
         [delta("road_barrier", 2, 20), layout("line", category="road_barrier", min_count=2, tolerance=1.5),
          near("east gate", 20.0, category="road_barrier", require_all=True), only("road_barrier")],
         [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, spacing=2.5, heading_deg=90.0,
               location=xy(96.0, 0.0))]),
    case("arrangement.vague.bikes_near_bus_stop", "a row of parked bikes near the bus stop",
         [delta("bicycle", 2, 20), layout("line", category="bicycle", min_count=2, tolerance=1.5),
          near("bus stop", 15.0, category="bicycle", require_all=True), only("bicycle")],
         [call("arrange_assets", categories=["bicycle"], shape="line", count=4, spacing=1.0, heading_deg=0.0,
               location=xy(-22.0, -7.5))]),
    case("arrangement.vague.benches_quad", "a little grid of benches at the quad",
         [delta("bench", 3, 20), layout("cluster", category="bench", min_count=3, tolerance=10.0),
          near("fountain", 15.0, category="bench", require_all=True), only("bench")],
         [call("arrange_assets", categories=["bench"], shape="grid", count=4, columns=2, location=at("fountain"))]),
    case("arrangement.vague.trees_lot_a_edge", "trees along one side of lot A",
         [delta("tree", 2, 20), layout("line", category="tree", min_count=2, tolerance=1.5),
          near("parking lot A", 4.0, category="tree", scope="added", require_all=True), only("tree")],
         [call("arrange_assets", categories=["tree"], shape="line", count=4, spacing=7.0, heading_deg=0.0, location=xy(-85.0, 42.0))]),
    # erroneous
    case("arrangement.erroneous.cones_lane_edge", "put 5 cone in line infront of ego on lane edge",
         [delta("traffic_cone", 5, 5), layout("line", category="traffic_cone", min_count=5, tolerance=1.5),
          near("main_eastbound", 3.0, category="traffic_cone", scope="added", require_all=True), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=5, location=at("ego", along_m=35.0))]),
    case("arrangement.erroneous.bollard_ring", "make ring of bolards arround the fontain",
         [delta("bollard", 3, 30), layout("ring", category="bollard", around="fountain", min_count=3, tolerance=1.5), only("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="ring", count=6, radius=4.0, location=at("fountain"))]),
    case("arrangement.erroneous.parking_row_lot_a", "park 4 car side by side in lot A pleas",
         [delta("passenger_car", 4, 4), layout("line", category="passenger_car", min_count=4, tolerance=1.5),
          near("parking lot A", 1.0, category="passenger_car", scope="added", require_all=True), only("passenger_car")],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=4, location=at("parking lot A"))]),
    case("arrangement.erroneous.tree_row_north", "six tree in a row from the fountain going to north",
         [delta("tree", 6, 6), layout("line", category="tree", min_count=6, tolerance=1.5),
          near("fountain", 45.0, category="tree", scope="added", require_all=True), only("tree")],
         [call("arrange_assets", categories=["tree"], shape="line", count=6, spacing=6.0, heading_deg=90.0, location=at("fountain"))]),
    case("arrangement.erroneous.barrier_line_campus", "plase put barier line on campus drive in north of crossroad, y 25",
         [delta("road_barrier", 2, 6), layout("line", category="road_barrier", min_count=2, tolerance=1.5),
          near_point(0.0, 25.0, 5.0, category="road_barrier", require_all=True), only("road_barrier")],
         [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, spacing=2.5, heading_deg=0.0,
               location=xy(0.0, 25.0))]),
    case("arrangement.erroneous.cone_circle_stop_sign", "circel of cones around center of intersection, radius 3",
         [delta("traffic_cone", 3, 20), layout("ring", category="traffic_cone", around="main intersection", min_count=3), only("traffic_cone")],
         [call("arrange_assets", categories=["traffic_cone"], shape="ring", count=5, radius=3.0, location=at("main intersection"))]),
    case("arrangement.erroneous.suvs_lot_b", "put three suv parked next each other in lot b",
         [delta("suv", 3, 3), layout("line", category="suv", min_count=3, tolerance=1.5),
          near("parking lot B", 1.0, category="suv", scope="added", require_all=True), only("suv")],
         [call("arrange_assets", categories=["suv"], shape="parking_row", count=3, location=at("parking lot B"))]),
    case("arrangement.erroneous.group_at_union", "grup of pedestrians standing by union enterance",
         [delta("pedestrian", 3, 20), layout("cluster", category="pedestrian", min_count=3, tolerance=8.0),
          near("Student Union entrance", 15.0, category="pedestrian", require_all=True), only("pedestrian")],
         [call("arrange_assets", categories=["pedestrian"], shape="grid", count=6, columns=3, spacing=1.5,
               location=at("Student Union entrance"))]),
    case("arrangement.erroneous.two_hundred_cones", "put 200 cone in line on main street", REFUSED,
         [call("arrange_assets", categories=["traffic_cone"], shape="lane_edge", count=200, location=at("ego", along_m=20.0))],
         tags=IMPOSSIBLE, notes="a layout holds at most 100"),
]


EGO = ("ego",)
CONES_3 = ("traffic_cone_1", "traffic_cone_2", "traffic_cone_3")

POSITIONING: list[Json] = [
    # direct
    case("positioning.direct.bench_by_library", "Put the bench next to the Library entrance.",
         [near("Library entrance", 8.0, asset="bench_1"), only(assets=("bench_1",))],
         [call("place_asset", asset="bench_1", location=at("Library entrance", "next_to"))]),
    case("positioning.direct.suv_northbound", "Place the SUV in the northbound lane of Campus Drive.",
         [lane("campus_northbound", asset="suv_1"), only(assets=("suv_1",))],
         [call("place_asset", asset="suv_1", location=at("campus_northbound", "in_lane"))]),
    case("positioning.direct.hydrant_coordinates", "Put the fire hydrant at x 20, y -5.5.",
         [near_point(20.0, -5.5, 1.0, asset="fire_hydrant_1"), only(assets=("fire_hydrant_1",))],
         [call("place_asset", asset="fire_hydrant_1", location=xy(20.0, -5.5))]),
    case("positioning.direct.car2_ahead_of_ego", "Position passenger_car_2 20 m ahead of the ego, in the ego's lane.",
         [lane("main_eastbound", asset="passenger_car_2"), relative("in_front_of", "ego", 30.0, asset="passenger_car_2"),
          only(assets=("passenger_car_2",))],
         [call("place_asset", asset="passenger_car_2", location=at("ego", along_m=20.0))]),
    case("positioning.direct.bin_lot_b_entrance", "Move the trash bin to the entrance of parking lot B.",
         [near("parking lot B entrance", 6.0, asset="trash_bin_1"), only(assets=("trash_bin_1",))],
         [call("place_asset", asset="trash_bin_1", location=at("parking lot B entrance", "next_to"))]),
    case("positioning.direct.ego_main_gate", "Place the ego at the main gate.",
         [near("main gate", 10.0, asset="ego"), only(assets=EGO)],
         [call("place_asset", asset="ego", location=at("main gate"))]),
    case("positioning.direct.suv_behind_ego", "Put the SUV fifteen metres behind the ego along its lane.",
         [relative("behind", "ego", 25.0, asset="suv_1"), lane("main_eastbound", asset="suv_1"), only(assets=("suv_1",))],
         [call("move_asset", asset="suv_1", relative_to="ego", along_m=-15.0)]),
    case("positioning.direct.bench_off_map", "Put the bench at x 200, y 0.", REFUSED,
         [call("place_asset", asset="bench_1", location=xy(200.0, 0.0))], tags=IMPOSSIBLE, notes="off the map"),
    case("positioning.direct.ego_gate_and_evening", "Put the ego at the main gate and set the clock to 21:00.",
         [near("main gate", 10.0, asset="ego"), env(time_from="20:55", time_to="21:05"), only(assets=EGO, environment=True)],
         [call("place_asset", asset="ego", location=at("main gate")), call("set_time_of_day", time="21:00")], tags=COMPOUND),
    # indirect
    case("positioning.indirect.ego_waits_east_gate", "The test should begin with the ego waiting at the east gate.",
         [near("east gate", 10.0, asset="ego"), only(assets=EGO)],
         [call("place_asset", asset="ego", location=at("east gate"))]),
    case("positioning.indirect.bench_by_fountain", "The bench would be far more pleasant right beside the fountain.",
         [near("fountain", 8.0, asset="bench_1"), only(assets=("bench_1",))],
         [call("place_asset", asset="bench_1", location=at("fountain", "next_to"))]),
    case("positioning.indirect.car1_westbound", "For the oncoming-traffic test, passenger_car_1 needs to be in the westbound lane of Main Street.",
         [lane("main_westbound", asset="passenger_car_1"), only(assets=("passenger_car_1",))],
         [call("place_asset", asset="passenger_car_1", location=at("main_westbound", "in_lane"))]),
    case("positioning.indirect.stop_sign_lot_a_exit", "The stop sign belongs at the way out of lot A, not at the crossroads.",
         [near("parking lot A entrance", 8.0, asset="stop_sign_1"), only(assets=("stop_sign_1",))],
         [call("place_asset", asset="stop_sign_1", location=at("parking lot A entrance", "next_to"))]),
    case("positioning.indirect.suv_ready_to_pull_out", "I want the SUV waiting at the lot B driveway, ready to pull out.",
         [near("parking lot B entrance", 8.0, asset="suv_1"), only(assets=("suv_1",))],
         [call("place_asset", asset="suv_1", location=at("parking lot B entrance"))]),
    case("positioning.indirect.following_distance", "It's a following-distance test, so the SUV should sit in the ego's lane 30 m behind it.",
         [relative("behind", "ego", 40.0, asset="suv_1"), lane("main_eastbound", asset="suv_1"), only(assets=("suv_1",))],
         [call("move_asset", asset="suv_1", relative_to="ego", along_m=-30.0)]),
    case("positioning.indirect.hydrant_where_crews_expect", "Fire crews expect the hydrant on the pavement by the JTEKT entrance, so that's where it should be.",
         [surface("sidewalk", asset="fire_hydrant_1"), near("JTEKT building entrance", 15.0, asset="fire_hydrant_1"),
          only(assets=("fire_hydrant_1",))],
         [call("place_asset", asset="fire_hydrant_1", location=at("JTEKT building entrance", "on_sidewalk"))]),
    case("positioning.indirect.suv_inside_engineering", "It would be great to have the SUV parked indoors in Engineering Hall, at -40, 28.", REFUSED,
         [call("place_asset", asset="suv_1", location=xy(-40.0, 28.0))], tags=IMPOSSIBLE, notes="inside a building"),
    case("positioning.indirect.suv_driveway_bench_fountain", "The SUV should wait at the lot B driveway, and the bench would be nicer by the fountain.",
         [near("parking lot B entrance", 8.0, asset="suv_1"), near("fountain", 8.0, asset="bench_1"),
          only(assets=("suv_1", "bench_1"))],
         [call("place_asset", asset="suv_1", location=at("parking lot B entrance")),
          call("place_asset", asset="bench_1", location=at("fountain", "next_to"))], tags=COMPOUND),
    # vague
    case("positioning.vague.bench_on_pavement", "put the bench somewhere on the sidewalk",
         [surface("sidewalk", asset="bench_1"), moved("bench_1", 0.5), only(assets=("bench_1",))],
         [call("place_asset", asset="bench_1", location=at("bus stop", "on_sidewalk"))]),
    case("positioning.vague.suv_in_lot_a", "park the SUV somewhere over in lot A",
         [near("parking lot A", 2.0, asset="suv_1"), only(assets=("suv_1",))],
         [call("place_asset", asset="suv_1", location=at("parking lot A"))]),
    case("positioning.vague.bin_by_union", "the trash bin over by the union",
         [near("Student Union entrance", 12.0, asset="trash_bin_1"), only(assets=("trash_bin_1",))],
         [call("place_asset", asset="trash_bin_1", location=at("Student Union entrance", "next_to"))]),
    case("positioning.vague.ego_on_campus_drive", "ego somewhere on campus drive",
         [only(assets=EGO)], [call("place_asset", asset="ego", location=at("campus_northbound", "in_lane"))],
         alternatives=([lane("campus_northbound", asset="ego")], [lane("campus_southbound", asset="ego")])),
    case("positioning.vague.hydrant_by_library", "hydrant by the library, I think",
         [near("Library entrance", 12.0, asset="fire_hydrant_1"), only(assets=("fire_hydrant_1",))],
         [call("place_asset", asset="fire_hydrant_1", location=at("Library entrance", "next_to"))]),
    case("positioning.vague.car2_ahead_somewhere", "stick car 2 somewhere in front of the ego",
         [relative("in_front_of", "ego", 60.0, asset="passenger_car_2"), only(assets=("passenger_car_2",))],
         [call("place_asset", asset="passenger_car_2", location=at("ego", along_m=25.0))]),
    case("positioning.vague.bin_at_quad", "the bin would look better at the quad",
         [near("fountain", 10.0, asset="trash_bin_1"), only(assets=("trash_bin_1",))],
         [call("place_asset", asset="trash_bin_1", location=at("fountain", "next_to"))]),
    case("positioning.vague.bus_at_stop_after_all", "hmm, actually it should be at the bus stop",
         [count("bus", 1, 1), near("bus stop", 12.0, category="bus", scope="all"), only("bus")],
         [call("place_asset", asset="bus_1", location=at("bus stop"))],
         setup=(step("Add a bus somewhere in lot B.", call("add_asset", category="bus", location=at("parking lot B")), planned=True),)),
    case("positioning.vague.ego_into_the_lake", "drop the ego in the lake", REFUSED,
         [call("place_asset", asset="ego", location=at("lake"))], tags=IMPOSSIBLE, notes="the campus has no lake"),
    # erroneous
    case("positioning.erroneous.bench_library", "put teh bench infront of libary entrence",
         [near("Library entrance", 10.0, asset="bench_1"), only(assets=("bench_1",))],
         [call("place_asset", asset="bench_1", location=at("Library entrance", "in_front_of"))]),
    case("positioning.erroneous.suv_northbound", "plase place suv in lane northbound of campus drive",
         [lane("campus_northbound", asset="suv_1"), only(assets=("suv_1",))],
         [call("place_asset", asset="suv_1", location=at("campus_northbound", "in_lane"))]),
    case("positioning.erroneous.hydrant_coordinates", "the hydrant put on x 20 y -5.5",
         [near_point(20.0, -5.5, 1.0, asset="fire_hydrant_1"), only(assets=("fire_hydrant_1",))],
         [call("place_asset", asset="fire_hydrant_1", location=xy(20.0, -5.5))]),
    case("positioning.erroneous.car2_ahead", "car 2 must be 20 meter ahead ego same lane",
         [lane("main_eastbound", asset="passenger_car_2"), relative("in_front_of", "ego", 30.0, asset="passenger_car_2"),
          only(assets=("passenger_car_2",))],
         [call("place_asset", asset="passenger_car_2", location=at("ego", along_m=20.0))]),
    case("positioning.erroneous.ego_main_gate", "ego put at main gate please, is start point",
         [near("main gate", 10.0, asset="ego"), only(assets=EGO)], [call("place_asset", asset="ego", location=at("main gate"))]),
    case("positioning.erroneous.bin_lot_b", "move trashbin to entrence of lot B",
         [near("parking lot B entrance", 6.0, asset="trash_bin_1"), only(assets=("trash_bin_1",))],
         [call("place_asset", asset="trash_bin_1", location=at("parking lot B entrance", "next_to"))]),
    case("positioning.erroneous.suv_behind_ego", "suv 15 m behind of ego in his lane",
         [relative("behind", "ego", 25.0, asset="suv_1"), lane("main_eastbound", asset="suv_1"), only(assets=("suv_1",))],
         [call("move_asset", asset="suv_1", relative_to="ego", along_m=-15.0)]),
    case("positioning.erroneous.new_suv_to_lane", "now put it in lane northbound of campus drive",
         [count("suv", 2, 2), lane("campus_northbound", asset="suv_2"), only("suv")],
         [call("place_asset", asset="suv_2", location=at("campus_northbound", "in_lane"))],
         setup=(step("add a suv in lot B", call("add_asset", category="suv", location=at("parking lot B")), planned=True),)),
    case("positioning.erroneous.bench_in_library", "put bench in middel of library bilding, x -41 y -30", REFUSED,
         [call("place_asset", asset="bench_1", location=xy(-41.0, -30.0))], tags=IMPOSSIBLE, notes="inside a building"),
]

MOVING: list[Json] = [
    # direct
    case("moving.direct.ego_forward_10", "Move the ego forward by 33 ft.",
         [moved("ego", 9.0, 11.0, direction="forward"), only(assets=EGO)], [call("move_asset", asset="ego", forward=10.0)]),
    case("moving.direct.car1_left_3", "Shift passenger_car_1 3 m to its left.",
         [moved("passenger_car_1", 2.5, 3.5, direction="left"), only(assets=("passenger_car_1",))],
         [call("move_asset", asset="passenger_car_1", left=3.0)]),
    case("moving.direct.bench_quarter_turn", "Turn the bench by 90 degrees.",
         [moved("bench_1", 0.0, 0.5, turn_min_deg=80.0, turn_max_deg=100.0), only(assets=("bench_1",))],
         [call("move_asset", asset="bench_1", turn_deg=90.0)]),
    case("moving.direct.lot_b_cars_north", "Move all three vehicles in lot B 5 m north.",
         [*[moved(a, 4.5, 5.5, direction="forward") for a in LOT_B_CARS], only(assets=tuple(LOT_B_CARS))],
         [call("move_asset", assets=LOT_B_CARS, north=5.0)]),
    case("moving.direct.bin_east_2", "Push the trash bin 2 m east.",
         [moved("trash_bin_1", 1.5, 2.5, direction="forward"), only(assets=("trash_bin_1",))],
         [call("move_asset", asset="trash_bin_1", east=2.0)]),
    case("moving.direct.ego_forward_suv_turn", "Move the ego 5 m forward and turn the SUV 90 degrees.",
         [moved("ego", 4.0, 6.0, direction="forward"), moved("suv_1", 0.0, 1.0, turn_min_deg=80.0, turn_max_deg=100.0),
          only(assets=("ego", "suv_1"))],
         [call("move_asset", asset="ego", forward=5.0), call("move_asset", asset="suv_1", turn_deg=90.0)], tags=COMPOUND),
    case("moving.direct.ego_off_map", "Move the ego 200 m east.", REFUSED,
         [call("move_asset", asset="ego", east=200.0)], tags=IMPOSSIBLE, notes="x would be 140, past the map's edge at 110"),
    # indirect
    case("moving.indirect.ego_back_from_stop", "The ego starts too close to the bus stop; fifteen metres further back would be right.",
         [moved("ego", 13.0, 17.0, direction="backward"), only(assets=EGO)], [call("move_asset", asset="ego", forward=-15.0)]),
    case("moving.indirect.suv_boxed_in", "The SUV is boxed in; nudge it 2 m to its right so it can get out.",
         [moved("suv_1", 1.5, 2.5, direction="right"), only(assets=("suv_1",))], [call("move_asset", asset="suv_1", left=-2.0)]),
    case("moving.indirect.bench_other_way", "The bench ought to face the other way.",
         [moved("bench_1", 0.0, 1.0, turn_min_deg=170.0, turn_max_deg=180.0), only(assets=("bench_1",))],
         [call("move_asset", asset="bench_1", turn_deg=180.0)]),
    case("moving.indirect.hydrant_clearance", "Give the hydrant a metre more clearance from Main Street by pulling it 1 m north.",
         [moved("fire_hydrant_1", 0.7, 1.3, direction="left"), only(assets=("fire_hydrant_1",))],
         [call("move_asset", asset="fire_hydrant_1", north=1.0)]),
    case("moving.indirect.lot_b_shuffle_back", "The vehicles in lot B need to shuffle 3 m back so there's room in front of them.",
         [*[moved(a, 2.5, 3.5, direction="backward") for a in LOT_B_CARS], only(assets=tuple(LOT_B_CARS))],
         [call("move_asset", assets=LOT_B_CARS, forward=-3.0)]),
    case("moving.indirect.slide_new_cones", "Those are a bit too central; shift all of them 1.5 m further left.",
         [*[moved(a, 1.0, 2.0) for a in (*CONES_3, "traffic_cone_4")], only("traffic_cone")],
         [call("move_asset", assets=[*CONES_3, "traffic_cone_4"], north=1.5)],
         setup=(step("Add four cones 25 m ahead of the ego.",
                     call("add_asset", category="traffic_cone", count=4, location=at("ego", along_m=25.0)), planned=True),),
         notes="left of the eastbound ego is north"),
    # vague
    case("moving.vague.bench_bit_left", "slide the bench leftwards a little",
         [moved("bench_1", 0.2, 5.0, direction="left"), only(assets=("bench_1",))], [call("move_asset", asset="bench_1", left=1.0)]),
    case("moving.vague.ego_bit_ahead", "ego a little further ahead",
         [moved("ego", 0.5, 30.0, direction="forward"), only(assets=EGO)], [call("move_asset", asset="ego", forward=5.0)]),
    case("moving.vague.suv_around", "turn the suv around",
         [moved("suv_1", 0.0, 3.0, turn_min_deg=150.0, turn_max_deg=180.0), only(assets=("suv_1",))],
         [call("move_asset", asset="suv_1", turn_deg=180.0)]),
    case("moving.vague.bin_touch_over", "scoot the trash bin over a touch",
         [moved("trash_bin_1", 0.1, 3.0), only(assets=("trash_bin_1",))], [call("move_asset", asset="trash_bin_1", east=1.0)]),
    case("moving.vague.lot_b_cars_little", "shift the lot B cars a little",
         [*[moved(a, 0.2, 5.0) for a in LOT_B_CARS], only(assets=tuple(LOT_B_CARS))],
         [call("move_asset", assets=LOT_B_CARS, forward=1.0)]),
    case("moving.vague.push_cones_further", "push those further off",
         [*[moved(a, 0.5, 40.0) for a in CONES_3], only("traffic_cone")],
         [call("move_asset", assets=list(CONES_3), east=10.0)], setup=(CONES_AHEAD,)),
    case("moving.vague.ego_bit_ahead_bench_around", "ego a bit forward, and the bench the other way round",
         [moved("ego", 0.5, 30.0, direction="forward"), moved("bench_1", 0.0, 1.0, turn_min_deg=150.0, turn_max_deg=180.0),
          only(assets=("ego", "bench_1"))],
         [call("move_asset", asset="ego", forward=5.0), call("move_asset", asset="bench_1", turn_deg=180.0)], tags=COMPOUND),
    # erroneous
    case("moving.erroneous.ego_forward_5", "mov the ego 5 meter forwrd",
         [moved("ego", 4.0, 6.0, direction="forward"), only(assets=EGO)], [call("move_asset", asset="ego", forward=5.0)]),
    case("moving.erroneous.bench_turn_90", "turn bench 90 degre",
         [moved("bench_1", 0.0, 0.5, turn_min_deg=80.0, turn_max_deg=100.0), only(assets=("bench_1",))],
         [call("move_asset", asset="bench_1", turn_deg=90.0)]),
    case("moving.erroneous.car1_left_3", "shift the car 1 3 metre at left",
         [moved("passenger_car_1", 2.5, 3.5, direction="left"), only(assets=("passenger_car_1",))],
         [call("move_asset", asset="passenger_car_1", left=3.0)]),
    case("moving.erroneous.lot_b_cars_north", "move all car in lot B 5m to nord",
         [*[moved(a, 4.5, 5.5, direction="forward") for a in LOT_B_CARS], only(assets=tuple(LOT_B_CARS))],
         [call("move_asset", assets=LOT_B_CARS, north=5.0)]),
    case("moving.erroneous.bin_east", "push trash bin 2 meter to east side",
         [moved("trash_bin_1", 1.5, 2.5, direction="forward"), only(assets=("trash_bin_1",))],
         [call("move_asset", asset="trash_bin_1", east=2.0)]),
    case("moving.erroneous.ego_off_map", "move the ego 200m to east", REFUSED,
         [call("move_asset", asset="ego", east=200.0)], tags=IMPOSSIBLE, notes="past the map's edge"),
]


ADD_THREE_CONES_PLANNED = step(
    "Put three cones 20 m ahead of the ego in its lane.",
    call("add_asset", category="traffic_cone", count=3, location=at("ego", along_m=20.0)),
    planned=True,
)

REMOVAL: list[Json] = [
    # direct
    case("removal.direct.all_trees", "Remove all the trees.", [count("tree", 0, 0), only("tree")],
         [call("remove_assets", category="tree")]),
    case("removal.direct.suv", "Delete the SUV.", [gone("suv_1"), only(assets=("suv_1",))],
         [call("remove_assets", assets=["suv_1"])]),
    case("removal.direct.two_lamps_nearest_ego", "Remove the two street lights closest to the ego.",
         [gone("street_light_2", "street_light_3"), delta("street_light", -2, -2), only("street_light")],
         [call("remove_assets", category="street_light", near="ego", count=2)]),
    case("removal.direct.cones", "Remove the traffic cones.", [count("traffic_cone", 0, 0), only("traffic_cone")],
         [call("remove_assets", category="traffic_cone")], setup=(CONES_AHEAD,)),
    case("removal.direct.hydrant", "Take out the fire hydrant.", [gone("fire_hydrant_1"), only(assets=("fire_hydrant_1",))],
         [call("remove_assets", assets=["fire_hydrant_1"])]),
    case("removal.direct.trees_and_bench", "Remove the trees and the bench.",
         [count("tree", 0, 0), gone("bench_1"), only("tree", "bench")],
         [call("remove_assets", category="tree"), call("remove_assets", category="bench")], tags=COMPOUND),
    case("removal.direct.bus", "Remove the bus.", REFUSED, [call("remove_assets", category="bus")], tags=IMPOSSIBLE,
         notes="there is no bus in the scene"),
    # indirect
    case("removal.indirect.smelly_bin", "The trash can at the bus stop smells; I don't want it there any more.",
         [gone("trash_bin_1"), only(assets=("trash_bin_1",))], [call("remove_assets", assets=["trash_bin_1"])]),
    case("removal.indirect.empty_lot_b", "Lot B has to be empty for the parking test.",
         [gone(*LOT_B_CARS), only(assets=tuple(LOT_B_CARS))], [call("remove_assets", assets=LOT_B_CARS)]),
    case("removal.indirect.stop_sign_hides_crossing", "The stop sign hides the crossing from the camera, so it has to go.",
         [gone("stop_sign_1"), only(assets=("stop_sign_1",))], [call("remove_assets", assets=["stop_sign_1"])]),
    case("removal.indirect.tree_by_bus_stop", "We don't need the tree beside the bus stop any longer.",
         [gone("tree_1"), only(assets=("tree_1",))], [call("remove_assets", category="tree", near="bus stop", count=1)]),
    case("removal.indirect.barrier_test_done", "The barrier test is finished, so the road should be clear again.",
         [count("road_barrier", 0, 0), only("road_barrier")], [call("remove_assets", category="road_barrier")],
         setup=(BARRIER_AHEAD,)),
    case("removal.indirect.ne_signal", "I'd rather not have the traffic signal on the north-east corner of the crossroads.",
         [gone("traffic_light_2"), only(assets=("traffic_light_2",))], [call("remove_assets", assets=["traffic_light_2"])]),
    case("removal.indirect.cones_gone_lights_on", "Once the cones are cleared away, the street lights should come on too.",
         [count("traffic_cone", 0, 0), env(street_lights="on"), only("traffic_cone", environment=True)],
         [call("remove_assets", category="traffic_cone"), call("set_lighting", street_lights="on")],
         setup=(CONES_AHEAD,), tags=COMPOUND),
    case("removal.indirect.keep_ego_out", "The test doesn't need our own car, please take the ego out of the scene.", REFUSED,
         [call("remove_assets", assets=["ego"])], tags=IMPOSSIBLE, notes="the ego cannot be removed"),
    # vague
    case("removal.vague.not_so_many_trees", "not so many trees", [delta("tree", -4, -1), only("tree")],
         [call("remove_assets", category="tree", count=2)]),
    case("removal.vague.thin_lamps", "thin out the street lamps a bit", [delta("street_light", -11, -1), only("street_light")],
         [call("remove_assets", category="street_light", count=4)]),
    case("removal.vague.bus_stop_clutter", "clear away the clutter at the bus stop",
         [delta(["bench", "trash_bin"], None, -1), only("bench", "trash_bin", "street_light", "tree")],
         [call("remove_assets", assets=["bench_1", "trash_bin_1"])]),
    case("removal.vague.too_many_cones", "that's too many cones", [delta("traffic_cone", -3, -1), only("traffic_cone")],
         [call("remove_assets", category="traffic_cone", count=1)], setup=(ADD_THREE_CONES_PLANNED,)),
    case("removal.vague.clear_lot_b", "clear out lot B", [delta(CARS, -3, -1), only(*CARS)],
         [call("remove_assets", assets=LOT_B_CARS)]),
    case("removal.vague.no_signals", "no traffic signals anymore", [count("traffic_light", 0, 0), only("traffic_light")],
         [call("remove_assets", category="traffic_light")]),
    # erroneous
    case("removal.erroneous.all_trees", "remvoe all the tres", [count("tree", 0, 0), only("tree")],
         [call("remove_assets", category="tree")]),
    case("removal.erroneous.suv", "delet the suv pls", [gone("suv_1"), only(assets=("suv_1",))],
         [call("remove_assets", assets=["suv_1"])]),
    case("removal.erroneous.two_lamps", "take away two lamp more near from ego",
         [gone("street_light_2", "street_light_3"), delta("street_light", -2, -2), only("street_light")],
         [call("remove_assets", category="street_light", near="ego", count=2)]),
    case("removal.erroneous.cones_all", "now remove cone all of them", [count("traffic_cone", 0, 0), only("traffic_cone")],
         [call("remove_assets", category="traffic_cone")], setup=(ADD_THREE_CONES_PLANNED,)),
    case("removal.erroneous.hydrant_and_bin", "remove hydrant and trash bin both",
         [gone("fire_hydrant_1"), gone("trash_bin_1"), only(assets=("fire_hydrant_1", "trash_bin_1"))],
         [call("remove_assets", assets=["fire_hydrant_1"]), call("remove_assets", assets=["trash_bin_1"])], tags=COMPOUND),
    case("removal.erroneous.helicopter", "remove the helicoptr from roof", REFUSED,
         [call("remove_assets", category="helicopter")], tags=IMPOSSIBLE, notes="no such category"),
]

APPEARANCE: list[Json] = [
    # direct
    case("appearance.direct.suv_red", "Paint the SUV red.", [looks(asset="suv_1", colour="red"), only(assets=("suv_1",))],
         [call("set_asset_appearance", assets=["suv_1"], colour="red")]),
    case("appearance.direct.heavy_rain", "Make it rain heavily.",
         [env(weather=["rain"], intensity_min=0.7), only(environment=True)], [call("set_weather", kind="rain", intensity=0.9)]),
    case("appearance.direct.time_1745", "Set the clock to 17:45.", [env(time_from="17:40", time_to="17:50"), only(environment=True)],
         [call("set_time_of_day", time="17:45")]),
    case("appearance.direct.street_lights_on", "Switch the street lights on.", [env(street_lights="on"), only(environment=True)],
         [call("set_lighting", street_lights="on")]),
    case("appearance.direct.matte_trees", "Give all the trees a matte finish.",
         [looks(category="tree", material="matte", min_count=4, require_all=True), only("tree")],
         [call("set_asset_appearance", category="tree", material="matte")]),
    case("appearance.direct.suv_red_cars_blue", "Paint the SUV red and both passenger cars blue.",
         [looks(asset="suv_1", colour="red"), looks(category="passenger_car", colour="blue", min_count=2, require_all=True),
          only(assets=("suv_1", "passenger_car_1", "passenger_car_2"))],
         [call("set_asset_appearance", assets=["suv_1"], colour="red"),
          call("set_asset_appearance", category="passenger_car", colour="blue")], tags=COMPOUND),
    case("appearance.direct.hail", "Make it hail.", REFUSED, [call("set_weather", kind="hail")], tags=IMPOSSIBLE,
         notes="hail is not a weather the world has"),
    # indirect
    case("appearance.indirect.wipers", "I want to find out whether the wipers keep up, so give me some proper precipitation.",
         [env(weather=["rain", "snow"], intensity_min=0.3), only(environment=True)], [call("set_weather", kind="rain", intensity=0.7)]),
    case("appearance.indirect.low_sun", "We're checking how the cameras handle a low sun, so set it to around sunset.",
         [env(time_from="17:30", time_to="20:30"), only(environment=True)], [call("set_time_of_day", time="sunset")]),
    case("appearance.indirect.night_detection", "Next up is a night-time test of pedestrian detection.",
         [env(night=True), only(environment=True)], [call("set_time_of_day", time="night")]),
    case("appearance.indirect.ego_hard_to_miss", "The ego should be hard to miss on camera; bright yellow would do.",
         [looks(asset="ego", colour="yellow"), only(assets=EGO)], [call("set_asset_appearance", assets=["ego"], colour="yellow")]),
    case("appearance.indirect.foggy_morning", "It's meant to be a foggy morning with poor visibility.",
         [env(weather=["fog"], intensity_min=0.5, time_from="05:00", time_to="11:00"), only(environment=True)],
         [call("set_weather", kind="fog", intensity=0.8), call("set_time_of_day", time="morning")], tags=COMPOUND),
    case("appearance.indirect.lot_b_metallic", "The vehicles in lot B look too plain; metallic silver would suit them.",
         [looks(category=CARS, colour=["silver", "grey", "gray"], material="metal", min_count=3, require_all=True),
          only(assets=tuple(LOT_B_CARS))],
         [call("set_asset_appearance", assets=LOT_B_CARS, colour="silver", material="metal")]),
    case("appearance.indirect.school_bus_colour", "It should look like a proper school bus, so yellow, please.",
         [looks(category="bus", colour="yellow"), only("bus")],
         [call("set_asset_appearance", category="bus", colour="yellow")],
         setup=(step("Add a bus at the bus stop.", call("add_asset", category="bus", location=at("bus stop")), planned=True),)),
    # vague
    case("appearance.vague.gloomy", "make it gloomy", [only(environment=True)], [call("set_weather", kind="cloudy", intensity=0.8)],
         alternatives=([env(weather=["cloudy", "rain", "fog"])], [env(night=True)], [env(exposure_max=0.9)])),
    case("appearance.vague.brighter", "brighter please", [env(exposure_min=1.1), only(environment=True)],
         [call("set_lighting", exposure=1.5)]),
    case("appearance.vague.later_in_day", "later in the day", [env(time_from="13:00", time_to="23:59"), only(environment=True)],
         [call("set_time_of_day", time="afternoon")]),
    case("appearance.vague.suv_stand_out", "make the SUV stand out",
         [looks(category="suv", scope="touched"), only(assets=("suv_1",))], [call("set_asset_appearance", assets=["suv_1"], colour="orange")]),
    case("appearance.vague.winter", "winter vibes", [env(weather=["snow"]), only(environment=True)],
         [call("set_weather", kind="snow", intensity=0.6)]),
    case("appearance.vague.drizzle", "a bit of drizzle", [env(weather=["rain"], intensity_min=0.05, intensity_max=0.5), only(environment=True)],
         [call("set_weather", kind="rain", intensity=0.3)]),
    case("appearance.vague.twilight_and_mist", "twilight, and a little mist",
         [env(weather=["fog"], intensity_max=0.6, time_from="17:30", time_to="21:30"), only(environment=True)],
         [call("set_weather", kind="fog", intensity=0.3), call("set_time_of_day", time="dusk")], tags=COMPOUND),
    # erroneous
    case("appearance.erroneous.suv_blue", "paint suv bleu", [looks(asset="suv_1", colour="blue"), only(assets=("suv_1",))],
         [call("set_asset_appearance", assets=["suv_1"], colour="blue")]),
    case("appearance.erroneous.heavy_snow", "make it snowwing hard", [env(weather=["snow"], intensity_min=0.7), only(environment=True)],
         [call("set_weather", kind="snow", intensity=0.9)]),
    case("appearance.erroneous.quarter_to_seven", "put time on quarter to seven of evening", [env(time_from="18:40", time_to="18:50"), only(environment=True)],
         [call("set_time_of_day", time="18:45")]),
    case("appearance.erroneous.lights_off", "turn of the street light", [env(street_lights="off"), only(environment=True)],
         [call("set_lighting", street_lights="off")]),
    case("appearance.erroneous.light_rain", "make rain littel bit", [env(weather=["rain"], intensity_min=0.05, intensity_max=0.5), only(environment=True)],
         [call("set_weather", kind="rain", intensity=0.3)]),
    case("appearance.erroneous.blurple_trees", "paint the tree in colour blurple", REFUSED,
         [call("set_asset_appearance", category="tree", colour="blurple")], tags=IMPOSSIBLE, notes="not a colour the world knows"),
]


# Compound and multi-turn cases of the first three tasks (kept apart so the lists above stay per task).
EXTRA: list[Json] = [
    case("search.indirect.truck_and_bus_mass", "I need the weights of both a truck and a bus for the load calculation.",
         [*QUESTION, says("9000", "9,000", "9 000", "9 t"), says("12000", "12,000", "12 000", "12 t")],
         [call("asset_properties", category="truck"), call("asset_properties", category="bus")], tags=COMPOUND),
    case("search.direct.trees_and_library_lane", "How many trees are there, and which lane runs closest to the Library entrance?",
         [*QUESTION, says("4", "four"), says("main_eastbound", "eastbound")],
         [call("find_assets", category="tree"), call("find_lanes", near="Library entrance")], tags=COMPOUND),
    case("search.vague.blocking_us_now", "so what's blocking us now?", [*QUESTION, says("truck", "truck_1")],
         [call("find_assets", on_lane=True)],
         setup=(step("Add a truck 30 m ahead of the ego in its lane.",
                     call("add_asset", category="truck", location=at("ego", along_m=30.0)), planned=True),)),
    case("addition.indirect.two_more_cones", "Add another pair of those right beside them.",
         [delta("traffic_cone", 2, 2), near("traffic_cone_1", 10.0, category="traffic_cone", scope="added", require_all=True),
          only("traffic_cone")],
         [call("add_asset", category="traffic_cone", count=2, location=at("traffic_cone_1", "next_to"))],
         setup=(ADD_THREE_CONES_PLANNED,)),
    case("addition.direct.bus_and_rain", "Add a bus at the bus stop and make it rain.",
         [delta("bus", 1, 1), near("bus stop", 12.0, category="bus"), env(weather=["rain"]), only("bus", environment=True)],
         [call("add_asset", category="bus", location=at("bus stop")), call("set_weather", kind="rain", intensity=0.6)],
         tags=COMPOUND),
    case("addition.vague.cones_and_barrier_ahead", "some cones and a barrier up ahead of the ego",
         [delta("traffic_cone", 1, 20), delta("road_barrier", 1, 3),
          relative("in_front_of", "ego", 80.0, category=["traffic_cone", "road_barrier"], require_all=True),
          only("traffic_cone", "road_barrier")],
         [call("add_asset", category="traffic_cone", count=3, location=at("ego", along_m=20.0)),
          call("add_asset", category="road_barrier", location=at("ego", along_m=30.0))], tags=COMPOUND),
    case("addition.erroneous.jaywalker_at_night", "add pedestrian who jaywalk in front ego and make it night",
         [delta("pedestrian", 1, 1), behaviour(["jaywalk", "cross_road"], category="pedestrian"), env(night=True),
          only("pedestrian", environment=True)],
         [call("add_asset", category="pedestrian", behaviour={"kind": "jaywalk", "ahead": 25.0}),
          call("set_time_of_day", time="night")], tags=COMPOUND),
    case("arrangement.direct.parking_row_and_sign", "Park three cars in a row in lot A and put a parking sign at its entrance.",
         [delta("passenger_car", 3, 3), layout("line", category="passenger_car", min_count=3, tolerance=1.5),
          near("parking lot A", 1.0, category="passenger_car", scope="added", require_all=True),
          delta("parking_sign", 1, 1), near("parking lot A entrance", 6.0, category="parking_sign"),
          only("passenger_car", "parking_sign")],
         [call("arrange_assets", categories=["passenger_car"], shape="parking_row", count=3, location=at("parking lot A")),
          call("add_asset", category="parking_sign", location=at("parking lot A entrance"))], tags=COMPOUND),
    case("arrangement.indirect.parade_barriers_and_sign", "Campus Drive is closed north of the junction: barriers side by side across it at y = 25, and a road-works sign to warn drivers before them.",
         [delta("road_barrier", 2, 6), layout("line", category="road_barrier", min_count=2, tolerance=1.5),
          near_point(0.0, 25.0, 5.0, category="road_barrier", require_all=True),
          delta("construction_sign", 1, 2), near_point(0.0, 25.0, 15.0, category="construction_sign"),
          only("road_barrier", "construction_sign")],
         [call("arrange_assets", categories=["road_barrier"], shape="line", count=3, spacing=2.5, heading_deg=0.0,
               location=xy(0.0, 25.0)),
          call("add_asset", category="construction_sign", location=xy(5.5, 18.0))], tags=COMPOUND),
    case("arrangement.vague.bollards_round_new_bench", "now some bollards around it",
         [delta("bollard", 3, 20), near("bench_2", 6.0, category="bollard", scope="added", require_all=True), only("bollard")],
         [call("arrange_assets", categories=["bollard"], shape="ring", count=5, radius=2.0, location=at("bench_2"))],
         setup=(step("Add a bench by the fountain.", call("add_asset", category="bench", location=at("fountain", "next_to")),
                     planned=True),)),
]


ALL_CASES: list[Json] = [*SEARCH, *ADDITION, *ARRANGEMENT, *POSITIONING, *MOVING, *REMOVAL, *APPEARANCE, *EXTRA]


def write_suite(path: Path = SUITE_PATH) -> int:
    """Write every case as one JSON line; returns how many."""
    lines = [json.dumps(c, separators=(",", ":")) for c in ALL_CASES]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return len(lines)


if __name__ == "__main__":
    print(f"wrote {write_suite()} cases to {SUITE_PATH}")
