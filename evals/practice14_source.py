"""The fourteenth practice suite: 250 cases in everyday wording, written from the campus world alone.

`python -m drivetwin.evals.practice14_source` writes `suites/practice14.jsonl` (tag `practice14`, ids
`practice14.<task>.<grade>.<name>`), one JSON object per line, from the plain case list below.

Voices: a parent helping a teenager get ready for a driving test, an insurance claims handler
retelling what a customer said happened, a film or game previs artist blocking a shot, a road-safety
charity volunteer, a robotics PhD student testing a delivery robot, a local radio traffic reporter,
a software tester poking at limits, odd inputs and contradictions, and a busy manager typing
one-handed on a phone. Prompts mix short chat turns with one-to-three sentence descriptions, stories
that carry the request, reasons, hedges, follow-ups that point back ("the other one", "both of
those", "same again but on the other side"), numbers in words and digits, metres, feet, yards and
car lengths, rough amounts, clock times and parts of the day, weather, negation and exceptions,
scopes (a lane, a lot, a sidewalk, a crossing, a landmark, a side of a road), relations, and
questions of many shapes (which must change nothing). The erroneous grade carries realistic typing
slips, autocorrect swaps, missing spaces, dropped words and non-native grammar.

Counts: 7 tasks x 4 grades, every cell 8 or 9 cases (250 in all: 61 direct, 63 each indirect, vague
and erroneous); 45 multi-turn cases (13 with a planned earlier turn), 18 compound ones (the reference
makes two calls or more), and 24 (9.6 %) impossible ones, tagged `impossible`, where the right outcome
is a refusal that changes nothing: a hospital, parking lot C, a tram, a roundabout, a giraffe, 500
cones; removing Main Street, the Library, the zebra crossings or the ego; the SUV at x = 300 or 2 km
past the east gate, a car inside the Student Union, a bench on the Library's roof; 300 km/h, a driving
tree or stop sign, shifting the crossroads; a 150 m or 200 m ring, a grid of 250 cones; 25:30, a
meteor shower, hail.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with
`alternatives` where a request has two fair readings, and a `reference` plan that passes. The
suite was written from the campus world, the asset catalog, the Worker tools and the eval checks
only, by someone who had not read the planners, their lexicons, their prompt examples or any other
suite's cases.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

Json = dict[str, Any]

TAG = "practice14"

# --- The campus world, as these cases use it --------------------------------------------------
# Main Street runs east-west (eastbound lane y = -1.75, westbound y = +1.75, kerbs at y = +-3.5,
# sidewalks at y = +-5.5); Campus Drive runs north-south (northbound x = +1.75, southbound -1.75).
EGO = "ego"  # drives main_eastbound at 5 m/s from (-60, -1.75), facing east
BENCH = "bench_1"  # at the bus stop, (-26, -6.9), facing west
BIN = "trash_bin_1"  # beside the bus stop, (-33.5, -5.5)
HYDRANT = "fire_hydrant_1"  # north sidewalk just east of the crossroads, (16, 5.5)
STOP_SIGN = "stop_sign_1"  # before the west crosswalk, (-13.5, -5.5), facing east
CAR_1, SUV, CAR_2 = "passenger_car_1", "suv_1", "passenger_car_2"  # parked in lot B at x 19 / 23 / 27, y -42
PARKED = (CAR_1, SUV, CAR_2)
LIGHT_SW, LIGHT_NE = "traffic_light_1", "traffic_light_2"  # (-9.5, -6.2) and (9.5, 6.2)
TREE_LIBRARY, TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A = "tree_1", "tree_2", "tree_3", "tree_4"
# tree_1 (-26, -12) by the library and bus stop; tree_2 (70, 45) 7 m from the fountain;
# tree_3 (85, 25) 18 m from it; tree_4 (-85, 50) just north of lot A.
LAMP_LOT_A = "street_light_1"  # (-80, 5.8), 5.5 m from the lot A entrance
LAMP_BUS_STOP = "street_light_4"  # (-38, -5.8), the lamp nearest the bus stop
# Lamps 1, 3, ... 11 stand on Main Street's north side (y = 5.8), 2, 4, ... 12 on its south side.
SOUTH_SIDE_LAMPS = tuple(f"street_light_{n}" for n in range(2, 13, 2))

LOT_A, LOT_B = "parking lot A", "parking lot B"  # areas: x -100..-70, y 14..44; x 15..62, y -46..-12
LOT_A_ENTRANCE, LOT_B_ENTRANCE = "parking lot A entrance", "parking lot B entrance"  # (-85, 3.5), (47, -3.5)
LIBRARY = "Library entrance"  # (-41, -15), faces north onto the library drop-off
JTEKT = "JTEKT building entrance"  # (37.5, 15), faces south onto the JTEKT drop-off
ENGINEERING = "Engineering Hall entrance"  # (-40, 15), faces south
UNION = "Student Union entrance"  # (42.5, -51), faces north
MAIN_GATE, EAST_GATE = "main gate", "east gate"  # (-100, 0) and (100, 0)
JUNCTION = "main intersection"  # the crossroads box, x and y -9..9
BUS_STOP = "bus stop"  # (-30, -5.5) on the south sidewalk of Main Street
FOUNTAIN = "fountain"  # (75, 40), north-east, on grass
WEST_CROSSWALK, NORTH_CROSSWALK = "west crosswalk", "north crosswalk"  # (-11.5, 0), (0, 11.5)

EASTBOUND, WESTBOUND = "main_eastbound", "main_westbound"
NORTHBOUND, SOUTHBOUND = "campus_northbound", "campus_southbound"

CONE, BARRIER, RUBBLE, BOLLARD = "traffic_cone", "road_barrier", "cement_rubble", "bollard"
CAR, SUV_KIND, BUS, TRUCK, ROBOT = "passenger_car", "suv", "bus", "truck", "ackermann_robot"
BIKE, MOTORBIKE, PERSON = "bicycle", "motorcycle", "pedestrian"
CARS = [CAR, SUV_KIND]
MARKERS = [CONE, BOLLARD, BARRIER]
TRAFFIC = [CAR, SUV_KIND, BUS, TRUCK, MOTORBIKE]

NOON = {"time_from": "11:30", "time_to": "12:30"}  # the world's clock, pinned where a prompt leaves it
CLEAR = {"weather": ["clear"]}
BRIGHT_COLOURS = ["red", "yellow", "orange", "pink", "cyan", "green", "purple"]  # not the cars' own blue


# --- Calls -------------------------------------------------------------------------------------
def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def loc(relation: str = "at", target: str | None = None, **extra: Any) -> Json:
    out: Json = {"relation": relation}
    if target is not None:
        out["target"] = target
    out.update(extra)
    return out


def xy(x: float, y: float) -> Json:
    return {"relation": "absolute", "x": x, "y": y}


def add(category: str, count: int = 1, where: Json | None = None, **extra: Any) -> Json:
    args: Json = {"category": category}
    if count != 1:
        args["count"] = count
    if where is not None:
        args["location"] = where
    args.update(extra)
    return call("add_asset", **args)


def remove(*assets: str, **extra: Any) -> Json:
    args: Json = {"assets": list(assets)} if assets else {}
    args.update(extra)
    return call("remove_assets", **args)


def place(asset: str, where: Json, **extra: Any) -> Json:
    return call("place_asset", asset=asset, location=where, **extra)


def move(asset: str, **extra: Any) -> Json:
    return call("move_asset", asset=asset, **extra)


def behave(asset: str, kind: str, **extra: Any) -> Json:
    return call("set_behaviour", asset=asset, behaviour={"kind": kind, **extra})


def arrange(categories: str | list[str], shape: str, where: Json, **extra: Any) -> Json:
    cats = [categories] if isinstance(categories, str) else categories
    return call("arrange_assets", categories=cats, shape=shape, location=where, **extra)


def paint(assets: Sequence[str] = (), category: str | None = None, **look: Any) -> Json:
    args: Json = {}
    if assets:
        args["assets"] = list(assets)
    if category is not None:
        args["category"] = category
    args.update(look)
    return call("set_asset_appearance", **args)


def weather(kind: str, intensity: float | None = None) -> Json:
    return call("set_weather", kind=kind) if intensity is None else call("set_weather", kind=kind, intensity=intensity)


def clock(time: str) -> Json:
    return call("set_time_of_day", time=time)


def lighting(**settings: Any) -> Json:
    return call("set_lighting", **settings)


def find(**args: Any) -> Json:
    return call("find_assets", **args)


def measure(a: str, b: str = EGO) -> Json:
    return call("measure_distance", a=a, b=b)


def landmarks(**args: Any) -> Json:
    return call("find_landmarks", **args)


def lanes(**args: Any) -> Json:
    return call("find_lanes", **args)


def properties(**args: Any) -> Json:
    return call("asset_properties", **args)


def environment() -> Json:
    return call("describe_environment")


def turn(prompt: str, *calls: Json, planned: bool = False) -> Json:
    """An earlier turn: replayed as given, or planned by the planner under test."""
    out: Json = {"prompt": prompt, "calls": list(calls)}
    if planned:
        out["planned"] = True
    return out


# --- Checks ------------------------------------------------------------------------------------
def _selecting(kind: str, category: str | list[str] | None, asset: str | None, scope: str | None,
               min_count: int | None, require_all: bool | None, **extra: Any) -> Json:
    out: Json = {"kind": kind}
    if category is not None:
        out["category"] = category
    if asset is not None:
        out["asset"] = asset
    if scope is not None:
        out["scope"] = scope
    if min_count is not None:
        out["min_count"] = min_count
    if require_all is not None:
        out["require_all"] = require_all
    out.update({k: v for k, v in extra.items() if v is not None})
    return out


def only(*categories: str, assets: Iterable[str] = (), env: bool = False) -> Json:
    """Nothing changed but assets of these categories or ids (and the environment if allowed)."""
    out: Json = {"kind": "unchanged_except"}
    if categories:
        out["categories"] = list(categories)
    ids = list(assets)
    if ids:
        out["assets"] = ids
    if env:
        out["environment"] = True
    return out


def delta(category: str | list[str], lo: int | None, hi: int | None) -> Json:
    out: Json = {"kind": "count_delta", "category": category}
    if lo is not None:
        out["min"] = lo
    if hi is not None:
        out["max"] = hi
    return out


def count(category: str | list[str], lo: int | None, hi: int | None) -> Json:
    out: Json = {"kind": "count", "category": category}
    if lo is not None:
        out["min"] = lo
    if hi is not None:
        out["max"] = hi
    return out


def near(target: str | None, within: float, category: str | list[str] | None = None, *, asset: str | None = None,
         scope: str | None = None, min_count: int | None = None, every: bool = False,
         point: tuple[float, float] | None = None) -> Json:
    out = _selecting("near", category, asset, scope, min_count, True if every else None, within=within)
    if point is not None:
        out["point"] = list(point)
    else:
        out["target"] = target
    return out


def relative(relation: str, target: str, category: str | list[str] | None = None, *, asset: str | None = None,
             max_distance: float | None = None, tolerance_deg: float | None = None) -> Json:
    return _selecting("relative", category, asset, None, None, None, relation=relation, target=target,
                      max_distance=max_distance, tolerance_deg=tolerance_deg)


def on(surfaces: list[str], category: str | list[str] | None = None, *, asset: str | None = None,
       scope: str | None = None) -> Json:
    return _selecting("on_surface", category, asset, scope, None, None, surfaces=surfaces)


def in_lane(lane: str | None, category: str | list[str] | None = None, *, asset: str | None = None,
            scope: str | None = None, aligned: bool | None = None) -> Json:
    return _selecting("in_lane", category, asset, scope, None, None, lane=lane, aligned=aligned)


def layout(shape: str, category: str | list[str], min_count: int, *, around: str | None = None,
           tolerance: float | None = None, spacing_min: float | None = None, spacing_max: float | None = None,
           scope: str | None = None) -> Json:
    return _selecting("arrangement", category, None, scope, min_count, None, shape=shape, around=around,
                      tolerance=tolerance, spacing_min=spacing_min, spacing_max=spacing_max)


def does(behaviour: str | list[str], category: str | list[str] | None = None, *, asset: str | None = None,
         scope: str | None = None, min_count: int | None = None, **params: Any) -> Json:
    return _selecting("behaviour", category, asset, scope, min_count, None, behaviour=behaviour, **params)


def env(**fields: Any) -> Json:
    return {"kind": "environment", **fields}


def looks(colour: str | list[str] | None = None, category: str | list[str] | None = None, *,
          asset: str | None = None, scope: str | None = None, tolerance: float | None = None,
          material: str | None = None, every: bool = False, min_count: int | None = None) -> Json:
    return _selecting("appearance", category, asset, scope, min_count, True if every else None, colour=colour,
                      colour_tolerance=tolerance, material=material)


def moved(asset: str, lo: float = 0.0, hi: float | None = None, direction: str | None = None,
          turn_min: float | None = None, turn_max: float | None = None) -> Json:
    out: Json = {"kind": "moved", "asset": asset, "min_distance": lo}
    if hi is not None:
        out["max_distance"] = hi
    if direction is not None:
        out["direction"] = direction
    if turn_min is not None:
        out["turn_min_deg"] = turn_min
    if turn_max is not None:
        out["turn_max_deg"] = turn_max
    return out


def gone(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": False}


def kept(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": True}


def says(all_of: Sequence[str] = (), any_of: Sequence[str] = (), none_of: Sequence[str] = ()) -> Json:
    out: Json = {"kind": "answer_contains"}
    if all_of:
        out["all_of"] = list(all_of)
    if any_of:
        out["any_of"] = list(any_of)
    if none_of:
        out["none_of"] = list(none_of)
    return out


def accepted() -> Json:
    return {"kind": "status", "accepted": True}


def refused() -> Json:
    return {"kind": "status", "accepted": False}


def event_played(actor: str, manoeuvre: str, seconds: float) -> Json:
    return {"kind": "scenario", "seconds": seconds,
            "expect": [{"kind": "event", "actor": actor, "manoeuvre": manoeuvre}]}


# --- Cases -------------------------------------------------------------------------------------
def case(task: str, grade: str, name: str, prompt: str, checks: Sequence[Json], reference: Sequence[Json], *,
         setup: Sequence[Json] = (), alternatives: Sequence[Sequence[Json]] = (), compound: bool = False,
         tags: Sequence[str] = (), notes: str = "") -> Json:
    """One case; `multi_turn` and `compound` tags follow from its setup and reference."""
    labels = [TAG]
    if setup:
        labels.append("multi_turn")
    if compound:
        if len(reference) < 2:
            raise ValueError(f"{name}: a compound case needs two calls or more")
        labels.append("compound")
    labels += tags
    out: Json = {"id": f"{TAG}.{task}.{grade}.{name}", "world": "campus"}
    if setup:
        out["setup"] = list(setup)
    out.update(prompt=prompt, task=task, grade=grade, tags=labels, checks=list(checks))
    if alternatives:
        out["alternatives"] = [list(alt) for alt in alternatives]
    out["reference"] = list(reference)
    if notes:
        out["notes"] = notes
    return out


def impossible(task: str, grade: str, name: str, prompt: str, failing: Json, *, setup: Sequence[Json] = (),
               notes: str = "") -> Json:
    """A request the world cannot do: the right outcome is a refusal that changes nothing."""
    return case(task, grade, name, prompt, [refused(), only()], [failing], setup=setup, tags=["impossible"],
                notes=notes)


def question(task: str, grade: str, name: str, prompt: str, answer: Json, reference: Sequence[Json], *,
             setup: Sequence[Json] = (), compound: bool = False, alternatives: Sequence[Sequence[Json]] = (),
             notes: str = "") -> Json:
    """A question: it is answered and changes nothing."""
    return case(task, grade, name, prompt, [accepted(), answer, only()], reference, setup=setup,
                compound=compound, alternatives=alternatives, notes=notes)


# Earlier turns used by several cases.
RUBBLE_WESTBOUND = turn("Drop a pile of rubble in the westbound lane near the east gate.",
                        add(RUBBLE, where=loc("in_lane", EAST_GATE, lane=WESTBOUND, distance=10)))
TRUCK_IN_LOT_A = turn("Park a delivery truck in lot A.", add(TRUCK, where=loc("at", LOT_A)))
ROBOT_IN_LOT_A = turn("Add my delivery robot in parking lot A.", add(ROBOT, where=loc("at", LOT_A)))
ROBOT_IN_LOT_B = turn("Add a small robot in lot B.", add(ROBOT, where=loc("at", LOT_B)))
BUS_IN_LOT_B = turn("Park a bus in lot B.", add(BUS, where=loc("at", LOT_B)))
PERSON_AT_WEST_CROSSWALK = turn("Add a pedestrian at the west crosswalk.", add(PERSON, where=loc("at", WEST_CROSSWALK)))
PERSON_AT_BUS_STOP = turn("Put someone waiting at the bus stop.", add(PERSON, where=loc("at", BUS_STOP)))


def search_cases() -> list[Json]:
    t = "search"
    return [
        # direct
        question(t, "direct", "cars_in_lot_b", "How many cars are parked in parking lot B right now?",
                 says(any_of=["3", "three"]), [find(category="cars", near=LOT_B, within=40)]),
        question(t, "direct", "nearest_place_to_hydrant", "What's the closest named place to the fire hydrant?",
                 says(any_of=["main intersection", "intersection", "crossroads", "junction"]),
                 [landmarks(nearest_to=HYDRANT)]),
        question(t, "direct", "ego_to_library", "How far is our car from the library entrance?",
                 says(any_of=["23.2", "23.1", "23"]), [measure(LIBRARY)]),
        question(t, "direct", "lamps_on_main_street", "How many street lights are there along Main Street?",
                 says(any_of=["12", "twelve"]), [find(category="street_light", lane="Main Street")]),
        question(t, "direct", "weather_and_time", "What are the weather and the time of day set to at the moment?",
                 says(all_of=["clear"], any_of=["12:00", "noon", "midday"]), [environment()]),
        question(t, "direct", "vehicle_nearest_ego", "Which vehicle is closest to the ego car, and how far away is it?",
                 says(all_of=[CAR_1], any_of=["88.7", "88.6", "89"]), [find(category="vehicles", nearest_to=EGO)]),
        question(t, "direct", "campus_drive_lanes", "List the lanes on Campus Drive and the direction each one runs.",
                 says(all_of=[NORTHBOUND, SOUTHBOUND]), [lanes(road="Campus Drive")]),
        question(t, "direct", "trees_near_fountain", "Are there any trees within 20 metres of the fountain?",
                 says(all_of=[TREE_FOUNTAIN, TREE_EAST], none_of=[TREE_LIBRARY, TREE_LOT_A]),
                 [find(category="tree", near=FOUNTAIN, within=20)]),
        impossible(t, "direct", "distance_to_hospital", "How far is the ego from the hospital?",
                   measure("hospital"), notes="the campus has no hospital"),
        # indirect
        question(t, "indirect", "stop_sign_before_junction",
                 "My son's test route goes east along Main Street from where the car starts. Before we go, is "
                 "there a stop sign he'll pass on the way to the junction, and where is it?",
                 says(all_of=[STOP_SIGN]), [find(category="stop_sign", nearest_to=EGO)]),
        question(t, "indirect", "claim_suv_bay",
                 "The customer says she parked right next to a big SUV in the student car park. I need to "
                 "confirm where that SUV is standing.",
                 says(any_of=[SUV, "23.0, -42.0", "23, -42"]), [find(category="suv")]),
        question(t, "indirect", "robot_lane_width",
                 "I'm sizing my delivery robot's path planner and need to know how wide the lanes on Main "
                 "Street are.",
                 says(any_of=["3.5"]), [lanes(road="Main Street")]),
        question(t, "indirect", "previs_ego_lane",
                 "Blocking the opening shot: I need to know which lane the ego is sitting in before I place "
                 "the camera.",
                 says(all_of=[EASTBOUND]), [lanes(near=EGO)]),
        question(t, "indirect", "radio_anything_blocking",
                 "Listeners keep ringing in about Main Street. Is anything actually sitting in a traffic lane "
                 "at the moment, apart from our own test car?",
                 says(all_of=["cement_rubble_1"]), [find(on_lane=True)], setup=[RUBBLE_WESTBOUND]),
        question(t, "indirect", "charity_bus_stop_to_crossing",
                 "For our leaflet on crossing safely: how far would someone at the bus stop have to walk to "
                 "get to the nearest crosswalk?",
                 says(any_of=["19.3", "19"]), [measure(BUS_STOP, WEST_CROSSWALK)]),
        question(t, "indirect", "manager_truck_still_there",
                 "client on the phone asking if the delivery truck is still in lot A, can u check",
                 says(all_of=["truck_1"]), [find(category="truck", near=LOT_A, within=30)], setup=[TRUCK_IN_LOT_A]),
        question(t, "indirect", "tester_things_by_bus_stop",
                 "Exploratory check on the search: how many assets of any kind are within 10 m of the bus "
                 "stop? I want to compare it with what I counted by eye.",
                 says(any_of=["4", "four"]), [find(near=BUS_STOP, within=10)]),
        impossible(t, "indirect", "free_spaces_lot_c",
                   "My daughter wants to practise reversing into a bay in parking lot C tonight. How many free "
                   "spaces does it have?",
                   find(near="parking lot C"), notes="there are lots A and B only"),
        # vague
        question(t, "vague", "around_the_fountain", "what's around the fountain?",
                 says(all_of=[TREE_FOUNTAIN]), [find(near=FOUNTAIN, within=15)]),
        question(t, "vague", "parked_near_union", "anything parked near the student union?",
                 says(any_of=list(PARKED)), [find(category="cars", near=UNION, within=30)]),
        question(t, "vague", "where_is_ego", "where's the ego at",
                 says(any_of=["-60", EASTBOUND]), [properties(asset=EGO)]),
        question(t, "vague", "what_time", "what time is it in there",
                 says(any_of=["12:00", "noon", "midday"]), [environment()]),
        question(t, "vague", "how_many_people", "how many people are out and about?",
                 says(any_of=["3", "three"]), [find(category="pedestrian")],
                 setup=[turn("Put three people by the fountain.", add(PERSON, 3, loc("at", FOUNTAIN)))]),
        question(t, "vague", "which_way_library", "which way's the library from the car?",
                 says(any_of=["south-east", "southeast", "south east"]), [measure(EGO, LIBRARY)]),
        question(t, "vague", "lights_at_crossroads", "the traffic lights at the crossroads, where exactly are they?",
                 says(all_of=[LIGHT_SW, LIGHT_NE]), [find(category="traffic_light")]),
        question(t, "vague", "bins_and_benches", "bins and benches near the bus stop?",
                 says(all_of=[BIN, BENCH]),
                 [find(category="trash_bin", near=BUS_STOP, within=15), find(category="bench", near=BUS_STOP, within=15)],
                 compound=True),
        question(t, "vague", "how_many_lanes", "how many lanes has this map got",
                 says(any_of=["4", "four"]), [lanes()]),
        # erroneous
        question(t, "erroneous", "cars_student_car_park", "hw many cars r in the stundent car park",
                 says(any_of=["3", "three"]), [find(category="cars", near=LOT_B, within=40)]),
        question(t, "erroneous", "lamp_nearest_bus_stop", "wich lamp post is closest too the bus stpo?",
                 says(all_of=[LAMP_BUS_STOP]), [find(category="street_light", nearest_to=BUS_STOP)]),
        question(t, "erroneous", "distance_to_east_gate", "whats the distnace from the ego to the east gate",
                 says(any_of=["160", "160.0"]), [measure(EAST_GATE)]),
        question(t, "erroneous", "hydrant_near_north_crossing", "is their a fire hydrent near the north crosswalk",
                 says(all_of=[HYDRANT]), [find(category="fire_hydrant", near=NORTH_CROSSWALK, within=25)]),
        question(t, "erroneous", "jtekt_entrance_where", "were is the JTEKT bulding entrence",
                 says(any_of=["37.5"]), [landmarks(query="JTEKT")]),
        question(t, "erroneous", "tree_most_near_library", "Please tell me the tree which is most near to library.",
                 says(all_of=[TREE_LIBRARY]), [find(category="tree", nearest_to=LIBRARY)]),
        question(t, "erroneous", "how_much_benches", "how much benchs are there in total",
                 says(any_of=[BENCH, "one", "1 bench"]), [find(category="bench")]),
        question(t, "erroneous", "what_wether", "what wether is it set too?",
                 says(all_of=["clear"]), [environment()]),
        question(t, "erroneous", "suv_colour_we_made", "wat colour did we make the suv again?",
                 says(any_of=["red", "0.8"]), [properties(asset=SUV)],
                 setup=[turn("Paint the SUV red.", paint([SUV], colour="red"))]),
    ]


def addition_cases() -> list[Json]:
    t = "addition"
    return [
        # direct
        case(t, "direct", "two_cones_library_dropoff", "Put two traffic cones in the library drop-off bay.",
             [delta(CONE, 2, 2), near(LIBRARY, 10, CONE, every=True), on(["drivable"], CONE), only(CONE)],
             [add(CONE, 2, loc("in_front_of", LIBRARY))]),
        case(t, "direct", "bus_and_people_at_stop", "Add a bus at the bus stop and two pedestrians waiting next to it.",
             [delta(BUS, 1, 1), delta(PERSON, 2, 2), near(BUS_STOP, 10, BUS), near(BUS_STOP, 10, PERSON, every=True),
              only(BUS, PERSON)],
             [add(BUS, where=loc("at", BUS_STOP)), add(PERSON, 2, loc("on_sidewalk", BUS_STOP))], compound=True),
        case(t, "direct", "pedestrian_west_crosswalk", "Add a pedestrian standing at the west crosswalk.",
             [delta(PERSON, 1, 1), near(WEST_CROSSWALK, 6, PERSON), only(PERSON)],
             [add(PERSON, where=loc("at", WEST_CROSSWALK))]),
        case(t, "direct", "robot_lot_a", "Add one Ackermann robot in parking lot A.",
             [delta(ROBOT, 1, 1), near(LOT_A, 1, ROBOT), only(ROBOT)], [add(ROBOT, where=loc("at", LOT_A))]),
        case(t, "direct", "three_bikes_jtekt", "Add three bicycles by the JTEKT building entrance.",
             [delta(BIKE, 3, 3), near(JTEKT, 12, BIKE, every=True), only(BIKE)], [add(BIKE, 3, loc("at", JTEKT))]),
        case(t, "direct", "barrier_lot_b_entrance", "Put a road barrier at the parking lot B entrance.",
             [delta(BARRIER, 1, 1), near(LOT_B_ENTRANCE, 8, BARRIER), on(["drivable"], BARRIER), only(BARRIER)],
             [add(BARRIER, where=loc("at", LOT_B_ENTRANCE))]),
        case(t, "direct", "truck_driving_west", "Add a delivery truck driving west along Main Street.",
             [delta(TRUCK, 1, 1), does("drive_lane", TRUCK, lane=WESTBOUND), only(TRUCK)],
             [add(TRUCK, behaviour={"kind": "drive_lane", "lane": WESTBOUND})]),
        case(t, "direct", "tree_engineering", "Plant a tree near the Engineering Hall entrance.",
             [delta("tree", 1, 1), near(ENGINEERING, 12, "tree"), only("tree")],
             [add("tree", where=loc("at", ENGINEERING))]),
        impossible(t, "direct", "tram_main_street", "Add a tram on Main Street.",
                   add("tram", where=loc("in_lane", EASTBOUND)), notes="no tram in the catalog"),
        # indirect
        case(t, "indirect", "kerb_by_library",
             "My son keeps clipping the kerb by the library drop-off. Can we put something there so he learns "
             "to take that turn wider?",
             [delta(MARKERS, 1, 10), near(LIBRARY, 12, MARKERS, every=True), only(*MARKERS)],
             [add(CONE, 3, loc("in_front_of", LIBRARY))]),
        case(t, "indirect", "claim_cyclist_and_van",
             "The customer says a cyclist came out of nowhere at the north crosswalk while a van was waiting "
             "there. Can we set that up so we can look at it?",
             [delta(BIKE, 1, 1), delta(TRUCK, 1, 1), near(NORTH_CROSSWALK, 8, BIKE), near(NORTH_CROSSWALK, 15, TRUCK),
              only(BIKE, TRUCK)],
             [add(BIKE, where=loc("at", NORTH_CROSSWALK)), add(TRUCK, where=xy(-1.75, 20))],
             compound=True),
        case(t, "indirect", "previs_car_at_jtekt_kerb",
             "The shot opens on the JTEKT drop-off with a car waiting at the kerb. Can I get that in?",
             [delta(CARS, 1, 1), near(JTEKT, 12, CARS), on(["drivable"], CARS), only(*CARS)],
             [add(CAR, where=loc("in_front_of", JTEKT))]),
        case(t, "indirect", "robot_obstacle_lot_b",
             "My delivery robot has to learn to go around junk on the ground. A pile of debris just inside the "
             "lot B entrance would be ideal.",
             [delta(RUBBLE, 1, 1), near(LOT_B_ENTRANCE, 12, RUBBLE), only(RUBBLE)],
             [add(RUBBLE, where=xy(47, -8))]),
        case(t, "indirect", "charity_kids_bus_stop",
             "We want to show drivers how easy it is to miss people waiting for the bus. Could there be a "
             "couple of them standing at the stop?",
             [delta(PERSON, 2, 3), near(BUS_STOP, 8, PERSON, every=True), only(PERSON)],
             [add(PERSON, 2, loc("on_sidewalk", BUS_STOP))]),
        case(t, "indirect", "manager_seat_union",
             "people keep saying there's nowhere to sit outside the student union",
             [delta("bench", 1, 3), near(UNION, 12, "bench", every=True), only("bench")],
             [add("bench", where=loc("at", UNION))]),
        case(t, "indirect", "tester_dark_north_crossing",
             "Testing the night renders, the stretch of Campus Drive by the north crosswalk comes out pitch "
             "black. It's crying out for another lamp post there.",
             [delta("street_light", 1, 2), near(NORTH_CROSSWALK, 12, "street_light", every=True), only("street_light")],
             [add("street_light", where=loc("on_sidewalk", NORTH_CROSSWALK))]),
        case(t, "indirect", "radio_broken_down_lorry",
             "Breaking: a lorry has broken down in the eastbound lane about twenty yards inside the main gate. "
             "Put that in so we can describe the tailback.",
             [delta(TRUCK, 1, 1), in_lane(EASTBOUND, TRUCK), near(MAIN_GATE, 30, TRUCK), only(TRUCK)],
             [add(TRUCK, where=loc("in_lane", MAIN_GATE, lane=EASTBOUND, distance=18))]),
        impossible(t, "indirect", "roundabout_for_test",
                   "Her test centre has loads of roundabouts, so could you build one at the main intersection "
                   "for her to practise on?",
                   add("roundabout", where=loc("at", JUNCTION)), notes="a roundabout is road layout, not an asset"),
        # vague
        case(t, "vague", "some_cones_east_gate", "some cones by the east gate pls",
             [delta(CONE, 2, 8), near(EAST_GATE, 12, CONE, every=True), on(["drivable"], CONE), only(CONE)],
             [add(CONE, 3, loc("at", EAST_GATE))]),
        case(t, "vague", "people_at_fountain", "a few people hanging about by the fountain",
             [delta(PERSON, 2, 6), near(FOUNTAIN, 12, PERSON, every=True), only(PERSON)],
             [add(PERSON, 3, loc("at", FOUNTAIN))]),
        case(t, "vague", "bit_of_traffic", "the streets look dead, needs a bit of traffic",
             [delta(TRAFFIC, 2, 12), does("drive_lane", TRAFFIC, scope="added", min_count=2), only(*TRAFFIC)],
             [add(CAR, 3, behaviour={"kind": "drive_lane", "lane": WESTBOUND})]),
        case(t, "vague", "somewhere_to_sit_library", "somewhere to sit near the library?",
             [delta("bench", 1, 2), near(LIBRARY, 12, "bench", every=True), only("bench")],
             [add("bench", where=loc("at", LIBRARY))]),
        case(t, "vague", "robot_sensible_spot", "stick a robot somewhere sensible for testing, a car park or something",
             [delta(ROBOT, 1, 1), only(ROBOT)], [add(ROBOT, where=loc("at", LOT_B))],
             alternatives=[[near(LOT_A, 1, ROBOT)], [near(LOT_B, 1, ROBOT)]]),
        case(t, "vague", "block_campus_drive_north", "block off a bit of Campus Drive north of the junction",
             [delta(MARKERS, 1, 12), near(None, 20, MARKERS, every=True, point=(0.0, 22.0)),
              on(["lane", "crossing", "paved"], MARKERS), only(*MARKERS)],
             [add(BARRIER, 2, loc("in_lane", NORTHBOUND, distance=20))]),
        case(t, "vague", "more_green_lot_a", "more green around lot A",
             [delta("tree", 1, 6), near(LOT_A, 10, "tree", every=True), only("tree")],
             [add("tree", 2, loc("next_to", TREE_LOT_A))]),
        case(t, "vague", "hydrant_by_library", "could do with a hydrant somewhere near the library",
             [delta("fire_hydrant", 1, 1), near(LIBRARY, 15, "fire_hydrant"), only("fire_hydrant")],
             [add("fire_hydrant", where=loc("at", LIBRARY))]),
        impossible(t, "vague", "five_hundred_cones", "loads of cones everywhere, like 500",
                   add(CONE, 500), notes="a scene holds at most 200 cones"),
        # erroneous
        case(t, "erroneous", "cone_infront_ego", "add a trafic cone infront of the ego",
             [delta(CONE, 1, 1), relative("in_front_of", EGO, CONE, max_distance=20), only(CONE)],
             [add(CONE, where=loc("in_front_of", EGO))]),
        case(t, "erroneous", "pedestrains_bus_stpo", "put 2 pedestrains at the bus stpo",
             [delta(PERSON, 2, 2), near(BUS_STOP, 8, PERSON, every=True), only(PERSON)],
             [add(PERSON, 2, loc("on_sidewalk", BUS_STOP))]),
        case(t, "erroneous", "motorbike_lotb", "ad a motorbike parkd at lotB",
             [delta(MOTORBIKE, 1, 1), near(LOT_B, 1, MOTORBIKE), only(MOTORBIKE)],
             [add(MOTORBIKE, where=loc("at", LOT_B))]),
        case(t, "erroneous", "bust_union", "Add a bust at the Student Union entrance so the students can get home",
             [delta(BUS, 1, 1), near(UNION, 15, BUS), only(BUS)], [add(BUS, where=loc("at", UNION))],
             notes="autocorrect turned 'bus' into 'bust'"),
        case(t, "erroneous", "cones_dropped_the", "add three cones the west crosswalk",
             [delta(CONE, 3, 3), near(WEST_CROSSWALK, 8, CONE, every=True), only(CONE)],
             [add(CONE, 3, loc("at", WEST_CROSSWALK))]),
        case(t, "erroneous", "addabench_fountain", "addabench near the fountain",
             [delta("bench", 1, 1), near(FOUNTAIN, 10, "bench"), only("bench")], [add("bench", where=loc("at", FOUNTAIN))]),
        case(t, "erroneous", "truck_must_to_park", "I want that you put a truck in the lot B, it must to be park.",
             [delta(TRUCK, 1, 1), near(LOT_B, 1, TRUCK), does("parked", TRUCK), only(TRUCK)],
             [add(TRUCK, where=loc("at", LOT_B))]),
        case(t, "erroneous", "same_again_other_side", "same again but on the other side of teh road",
             [delta(CONE, 3, 3), in_lane(WESTBOUND, CONE, scope="added"), near(BUS_STOP, 15, CONE, scope="added", every=True),
              only(CONE)],
             [add(CONE, 3, loc("in_lane", BUS_STOP, lane=WESTBOUND))],
             setup=[turn("Put three cones in the eastbound lane by the bus stop.",
                         add(CONE, 3, loc("in_lane", BUS_STOP, lane=EASTBOUND)), planned=True)]),
        impossible(t, "erroneous", "giraf_fountain", "add a giraf next to the fountian",
                   add("giraffe", where=loc("next_to", FOUNTAIN)), notes="no animals in the catalog"),
    ]


def removal_cases() -> list[Json]:
    t = "removal"
    return [
        # direct
        case(t, "direct", "bench_and_bin_bus_stop", "Remove the bench and the bin at the bus stop.",
             [gone(BENCH, BIN), only(assets=[BENCH, BIN])], [remove(BENCH), remove(BIN)], compound=True),
        case(t, "direct", "suv_out_of_lot_b", "Take the SUV out of lot B.", [gone(SUV), only(assets=[SUV])], [remove(SUV)]),
        case(t, "direct", "tree_by_library", "Delete the tree next to the library.",
             [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])], [remove(TREE_LIBRARY)]),
        case(t, "direct", "all_the_cones", "Remove all the traffic cones.",
             [count(CONE, 0, 0), delta(CONE, None, -4), only(CONE)], [remove(category=CONE)],
             setup=[turn("Put four cones at the east gate.", add(CONE, 4, loc("at", EAST_GATE)))]),
        case(t, "direct", "two_cars_not_suv", "Remove the two passenger cars in lot B but leave the SUV where it is.",
             [gone(CAR_1, CAR_2), kept(SUV), only(assets=[CAR_1, CAR_2])], [remove(CAR_1, CAR_2)]),
        case(t, "direct", "those_pedestrians", "Now remove those pedestrians.",
             [count(PERSON, 0, 0), delta(PERSON, None, -1), only(PERSON)], [remove(category=PERSON)],
             setup=[turn("Add three pedestrians at the fountain.", add(PERSON, 3, loc("at", FOUNTAIN)), planned=True)]),
        case(t, "direct", "the_trash_bin", "Remove the trash bin.", [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
        impossible(t, "direct", "main_street", "Remove Main Street.", remove("Main Street"),
                   notes="roads are not assets"),
        # indirect
        case(t, "indirect", "previs_hydrant_in_the_way",
             "The hydrant by the junction is right where my camera dolly needs to go. Can it disappear?",
             [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
        case(t, "indirect", "parent_judge_junction",
             "He needs to learn to judge the junction on the west side by himself, without the stop sign "
             "telling him what to do.",
             [gone(STOP_SIGN), only(assets=[STOP_SIGN])], [remove(STOP_SIGN)]),
        case(t, "indirect", "claim_no_lamp_at_lot_a",
             "The customer swears there was no lamp post right by the lot A entrance that night. Let's make "
             "the scene match her account.",
             [gone(LAMP_LOT_A), delta("street_light", -1, -1), only(assets=[LAMP_LOT_A])], [remove(LAMP_LOT_A)]),
        case(t, "indirect", "charity_roadworks_done",
             "Volunteers tell me the roadworks at the west crosswalk finished yesterday, so those signs "
             "shouldn't be there any more.",
             [count("construction_sign", 0, 0), only("construction_sign")], [remove(category="construction_sign")],
             setup=[turn("Put two roadworks signs by the west crosswalk.",
                         add("construction_sign", 2, loc("at", WEST_CROSSWALK)))]),
        case(t, "indirect", "robot_empty_lot_b",
             "I want lot B completely empty of cars so my robot has the whole space to itself.",
             [gone(*PARKED), only(assets=PARKED)], [remove(*PARKED)]),
        case(t, "indirect", "radio_debris_cleared", "Good news for drivers: the debris on Main Street has been cleared.",
             [count(RUBBLE, 0, 0), delta(RUBBLE, None, -1), only(RUBBLE)], [remove(category=RUBBLE)],
             setup=[turn("Put some rubble in the westbound lane of Main Street near the east gate.",
                         add(RUBBLE, where=loc("in_lane", EAST_GATE, lane=WESTBOUND, distance=10)), planned=True)]),
        case(t, "indirect", "manager_fountain_trees_messy",
             "the trees round the fountain make the demo look messy, lose them",
             [gone(TREE_FOUNTAIN), kept(TREE_LIBRARY, TREE_LOT_A), only(assets=[TREE_FOUNTAIN, TREE_EAST])],
             [remove(TREE_FOUNTAIN, TREE_EAST)],
             notes="tree_3 is 18 m off, so lose it or keep it; tree_2 is 7 m off"),
        case(t, "indirect", "tester_two_benches",
             "Looks like I ended up with two benches at the fountain after that last step; one is plenty.",
             [delta("bench", -1, -1), kept(BENCH), only(assets=["bench_2", "bench_3"])], [remove("bench_3")],
             setup=[turn("Put two benches at the fountain.", add("bench", 2, loc("at", FOUNTAIN)))]),
        impossible(t, "indirect", "library_blocks_view",
                   "The library building blocks drivers' view of the crossing. Please take it away.",
                   remove("library"), notes="buildings cannot be removed"),
        # vague
        case(t, "vague", "thin_out_bus_stop", "the bus stop's a bit cluttered, thin it out",
             [delta(["bench", "trash_bin", "street_light", "tree"], -3, -1),
              only(assets=[BENCH, BIN, LAMP_BUS_STOP, TREE_LIBRARY])],
             [remove(BIN)]),
        case(t, "vague", "cones_gone", "cones. gone.", [count(CONE, 0, 0), only(CONE)], [remove(category=CONE)],
             setup=[turn("Cone off the lot A entrance with five cones.", add(CONE, 5, loc("at", LOT_A_ENTRANCE)))]),
        case(t, "vague", "scrap_the_second", "scrap the second one",
             [gone("truck_2"), kept("truck_1"), only(assets=["truck_2"])], [remove("truck_2")],
             setup=[TRUCK_IN_LOT_A, turn("And another one in lot B.", add(TRUCK, where=loc("at", LOT_B)))]),
        case(t, "vague", "fewer_lamps_north_side", "fewer lamp posts on the north side of Main Street, it's overkill",
             [delta("street_light", -6, -1), kept(*SOUTH_SIDE_LAMPS), only("street_light")],
             [remove("street_light_3", "street_light_7", "street_light_11")]),
        case(t, "vague", "no_people_please", "no people please",
             [count(PERSON, 0, 0), only(PERSON)], [remove(category=PERSON)],
             setup=[turn("Add four pedestrians at the bus stop.", add(PERSON, 4, loc("on_sidewalk", BUS_STOP)),
                         planned=True)]),
        case(t, "vague", "clear_the_junction", "clear the junction",
             [count(CONE, 0, 0), count(RUBBLE, 0, 0), only(CONE, RUBBLE)], [remove(category=CONE), remove(category=RUBBLE)],
             setup=[turn("Put a pile of rubble in the middle of the junction with three cones round it.",
                         add(RUBBLE, where=xy(0, 0)), add(CONE, 3, loc("at", JUNCTION)))],
             compound=True),
        case(t, "vague", "tree_up_by_lot_a", "the tree up by lot A can go",
             [gone(TREE_LOT_A), only(assets=[TREE_LOT_A])], [remove(TREE_LOT_A)]),
        case(t, "vague", "both_of_those", "changed my mind, get rid of both of those",
             [gone("bench_2", "trash_bin_2"), kept(BENCH, BIN), only(assets=["bench_2", "trash_bin_2"])],
             [remove("bench_2", "trash_bin_2")],
             setup=[turn("Put a bench and a bin by the fountain.", add("bench", where=loc("at", FOUNTAIN)),
                         add("trash_bin", where=loc("next_to", FOUNTAIN)))]),
        impossible(t, "vague", "zebra_crossings", "get rid of the zebra crossings",
                   remove("crossing_west", "crossing_east", "crossing_south", "crossing_north"),
                   notes="crossings are road markings, not assets"),
        # erroneous
        case(t, "erroneous", "sotp_sign_and_hydrant", "remvoe the sotp sign and the hydrant",
             [gone(STOP_SIGN, HYDRANT), only(assets=[STOP_SIGN, HYDRANT])], [remove(STOP_SIGN), remove(HYDRANT)],
             compound=True),
        case(t, "erroneous", "teh_suv_parking_b", "take out teh suv from parking b",
             [gone(SUV), only(assets=[SUV])], [remove(SUV)]),
        case(t, "erroneous", "bench_not_need", "remove bench at the bus stop, is not need any more",
             [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
        case(t, "erroneous", "light_north_east_coner", "remove the traffic light on the north east coner of the junction",
             [gone(LIGHT_NE), kept(LIGHT_SW), only(assets=[LIGHT_NE])], [remove(LIGHT_NE)]),
        case(t, "erroneous", "cones_nort_keep_libary", "remove the cones at the nort crosswalk but keep the libary ones",
             [gone("traffic_cone_1", "traffic_cone_2", "traffic_cone_3"), kept("traffic_cone_4", "traffic_cone_5"),
              only(CONE)],
             [remove("traffic_cone_1", "traffic_cone_2", "traffic_cone_3")],
             setup=[turn("Three cones at the north crosswalk.", add(CONE, 3, loc("at", NORTH_CROSSWALK))),
                    turn("And two in the library drop-off.", add(CONE, 2, loc("in_front_of", LIBRARY)))]),
        case(t, "erroneous", "tee_by_library", "Remove the tee by the library", [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
             [remove(TREE_LIBRARY)], notes="autocorrect: tee for tree"),
        case(t, "erroneous", "removeall_trees", "removeall the trees", [count("tree", 0, 0), only("tree")],
             [remove(category="tree")]),
        case(t, "erroneous", "fire_hydrnat_pls", "delete fire hydrnat pls", [gone(HYDRANT), only(assets=[HYDRANT])],
             [remove(HYDRANT)]),
        impossible(t, "erroneous", "ego_not_needed", "remove the ego car its not needed for this one", remove(EGO),
                   notes="the ego cannot be removed"),
    ]


def positioning_cases() -> list[Json]:
    t = "positioning"
    return [
        # direct
        case(t, "direct", "bench_fountain_bin_beside", "Put the bench next to the fountain and the bin beside the bench.",
             [near(FOUNTAIN, 5, asset=BENCH), near(BENCH, 4, asset=BIN), delta(["bench", "trash_bin"], 0, 0),
              only(assets=[BENCH, BIN])],
             [place(BENCH, loc("next_to", FOUNTAIN)), place(BIN, loc("next_to", BENCH))], compound=True),
        case(t, "direct", "suv_into_lot_a", "Move the SUV into parking lot A.",
             [near(LOT_A, 0.5, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", LOT_A))]),
        case(t, "direct", "bin_library_entrance", "Place the trash bin at the Library entrance.",
             [near(LIBRARY, 5, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", LIBRARY))]),
        case(t, "direct", "cone_ten_yards_ahead_of_ego", "Put a traffic cone ten yards ahead of the ego, in its lane.",
             [delta(CONE, 1, 1), in_lane(EASTBOUND, CONE), near(None, 3, CONE, point=(-50.86, -1.75)), only(CONE)],
             [add(CONE, where=loc("at", EGO, along_m=9.14))]),
        case(t, "direct", "person_left_of_bus", "Put a pedestrian on the left side of the bus.",
             [delta(PERSON, 1, 1), relative("left_of", "bus_1", PERSON, max_distance=10), only(PERSON)],
             [add(PERSON, where=loc("left_of", "bus_1"))],
             setup=[turn("Add a bus at the bus stop.", add(BUS, where=loc("at", BUS_STOP)), planned=True)]),
        case(t, "direct", "ego_at_main_gate", "Place the ego at the main gate, in the eastbound lane.",
             [near(MAIN_GATE, 10, asset=EGO), in_lane(EASTBOUND, asset=EGO), only(assets=[EGO])],
             [place(EGO, loc("in_lane", MAIN_GATE, lane=EASTBOUND))]),
        case(t, "direct", "hydrant_behind_stop_sign", "Put the fire hydrant behind the stop sign.",
             [only(assets=[HYDRANT])], [place(HYDRANT, loc("behind", STOP_SIGN))],
             alternatives=[[relative("behind", STOP_SIGN, asset=HYDRANT, max_distance=5)],
                           [near(None, 1.5, asset=HYDRANT, point=(-13.5, -7.0))]],
             notes="behind by the sign's own facing (west of it), or on its far side from the road (south)"),
        case(t, "direct", "car_at_coordinates", "Place passenger_car_1 at x = 40, y = -30.",
             [near(None, 0.5, asset=CAR_1, point=(40.0, -30.0)), only(assets=[CAR_1])], [place(CAR_1, xy(40, -30))]),
        impossible(t, "direct", "suv_off_the_map", "Put the SUV at x 300, y 0.", place(SUV, xy(300, 0)),
                   notes="the world spans x -110..110"),
        # indirect
        case(t, "indirect", "teen_pull_out_past_suv",
             "My son needs practice pulling out past a parked car, so could the SUV be sitting in the JTEKT "
             "drop-off?",
             [near(JTEKT, 10, asset=SUV), on(["drivable"], asset=SUV), only(assets=[SUV])],
             [place(SUV, loc("at", JTEKT))]),
        case(t, "indirect", "claim_bike_in_front_of_stop",
             "The claimant says the bicycle was right in front of the bus stop when she pulled away.",
             [near(BUS_STOP, 6, asset="bicycle_1"), delta(BIKE, 0, 0), only(assets=["bicycle_1"])],
             [place("bicycle_1", loc("in_front_of", BUS_STOP))],
             setup=[turn("Add a bicycle in lot B.", add(BIKE, where=loc("at", LOT_B)))]),
        case(t, "indirect", "previs_hero_car_at_exit",
             "Now get the hero car waiting at the lot B exit, ready to pull out onto Main Street.",
             [near(LOT_B_ENTRANCE, 10, CAR), delta(CAR, 0, 0), only(CAR)],
             [place("passenger_car_3", loc("at", LOT_B_ENTRANCE))],
             setup=[turn("Add a red car in parking lot A; that's our hero car.",
                         add(CAR, where=loc("at", LOT_A), colour="red"), planned=True)]),
        case(t, "indirect", "robot_start_north_crossing", "For this run I want the robot starting from the north crosswalk.",
             [near(NORTH_CROSSWALK, 6, asset="ackermann_robot_1"), only(assets=["ackermann_robot_1"])],
             [place("ackermann_robot_1", loc("at", NORTH_CROSSWALK))], setup=[ROBOT_IN_LOT_A]),
        case(t, "indirect", "charity_bin_back_by_tree",
             "The bin sits right where kids wait for the bus. It'd be safer tucked next to the tree by the "
             "library instead.",
             [near(TREE_LIBRARY, 3, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", TREE_LIBRARY))]),
        case(t, "indirect", "radio_lorry_in_junction", "We're hearing the delivery lorry is now stuck slap bang in the middle of the junction.",
             [near(JUNCTION, 1, asset="truck_1"), delta(TRUCK, 0, 0), only(assets=["truck_1"])],
             [place("truck_1", loc("at", JUNCTION))], setup=[turn("Park a delivery lorry in lot B.", add(TRUCK, where=loc("at", LOT_B)))]),
        case(t, "indirect", "tester_south_west_corner",
             "Checking the edges: the bench should sit in the far south-west corner of the map, just inside "
             "the boundary.",
             [near(None, 8, asset=BENCH, point=(-110.0, -90.0)), only(assets=[BENCH])], [place(BENCH, xy(-107, -87))]),
        case(t, "indirect", "manager_ego_east_gate", "need the ego sat at the east gate facing into campus for the 3pm demo",
             [near(EAST_GATE, 12, asset=EGO), in_lane(WESTBOUND, asset=EGO, aligned=True), only(assets=[EGO])],
             [place(EGO, loc("in_lane", EAST_GATE, lane=WESTBOUND))]),
        impossible(t, "indirect", "car_inside_union",
                   "The customer says her car ended up inside the Student Union. Put passenger car 1 in there.",
                   place(CAR_1, xy(42.5, -63.5)), notes="a car cannot stand inside a building"),
        # vague
        case(t, "vague", "bench_in_the_shade", "bench somewhere in the shade",
             [delta("bench", 0, 1), only("bench")], [place(BENCH, loc("next_to", TREE_FOUNTAIN))],
             alternatives=[[near(tree, 4, "bench")] for tree in (TREE_LIBRARY, TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A)],
             notes="moving the bench or adding one in the shade both do"),
        case(t, "vague", "car_closer_to_library", "bring one of the parked cars closer to the library",
             [near(LIBRARY, 15, CARS), delta(CARS, 0, 0), only(*CARS)], [place(CAR_1, loc("at", LIBRARY))]),
        case(t, "vague", "ego_near_junction", "start the ego somewhere near the junction instead",
             [near(JUNCTION, 15, asset=EGO), moved(EGO, 10), only(assets=[EGO])], [place(EGO, xy(-20, -1.75))]),
        case(t, "vague", "robot_over_by_jtekt", "hmm, put it over by the JTEKT building instead",
             [near(JTEKT, 12, ROBOT), delta(ROBOT, 0, 0), only(ROBOT)], [place("ackermann_robot_1", loc("at", JTEKT))],
             setup=[turn("Add a robot in lot A.", add(ROBOT, where=loc("at", LOT_A)), planned=True)]),
        case(t, "vague", "hydrant_by_library_instead", "the hydrant looks odd where it is, stick it by the library instead",
             [near(LIBRARY, 12, asset=HYDRANT), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", LIBRARY))]),
        case(t, "vague", "cones_other_side", "hmm, those two cones belong on the other side of the road",
             [in_lane(WESTBOUND, CONE, scope="all"), delta(CONE, 0, 0), only(CONE)],
             [place("traffic_cone_1", loc("in_lane", BUS_STOP, lane=WESTBOUND)),
              place("traffic_cone_2", loc("in_lane", BUS_STOP, lane=WESTBOUND))],
             setup=[turn("Two cones in the eastbound lane by the bus stop.",
                         add(CONE, 2, loc("in_lane", BUS_STOP, lane=EASTBOUND)))]),
        case(t, "vague", "bus_at_its_stop", "the bus should really be at its stop",
             [near(BUS_STOP, 10, asset="bus_1"), delta(BUS, 0, 0), only(assets=["bus_1"])],
             [place("bus_1", loc("at", BUS_STOP))], setup=[BUS_IN_LOT_B]),
        case(t, "vague", "suv_blocking_junction", "put the SUV somewhere it'd block the junction",
             [near(JUNCTION, 1, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", JUNCTION))]),
        impossible(t, "vague", "bench_on_library_roof", "stick the bench up on the library roof",
                   place(BENCH, xy(-41, -30)), notes="nothing stands on a building"),
        # erroneous
        case(t, "erroneous", "bench_nxt_fountian", "put the bench nxt to the fountian",
             [near(FOUNTAIN, 5, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", FOUNTAIN))]),
        case(t, "erroneous", "suv_lot_a_and_ego_gate", "plase the suv in to lot A and ego at the main gate",
             [near(LOT_A, 0.5, asset=SUV), near(MAIN_GATE, 10, asset=EGO), only(assets=[SUV, EGO])],
             [place(SUV, loc("at", LOT_A)), place(EGO, loc("in_lane", MAIN_GATE, lane=EASTBOUND))], compound=True),
        case(t, "erroneous", "ego_east_gate_westbond", "put ego at east gate in westbond lane",
             [near(EAST_GATE, 12, asset=EGO), in_lane(WESTBOUND, asset=EGO), only(assets=[EGO])],
             [place(EGO, loc("in_lane", EAST_GATE, lane=WESTBOUND))]),
        case(t, "erroneous", "bin_near_to_north_crosswalk", "The trash bin, you place it near to the north crosswalk please.",
             [near(NORTH_CROSSWALK, 6, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", NORTH_CROSSWALK))]),
        case(t, "erroneous", "cone_20m_a_head", "put a cone 20m a head of the ego",
             [delta(CONE, 1, 1), near(None, 4, CONE, point=(-40.0, -1.75)), in_lane(EASTBOUND, CONE), only(CONE)],
             [add(CONE, where=loc("at", EGO, along_m=20))]),
        case(t, "erroneous", "hydrent_infront_jtekt", "move hydrent infront the JTEKT enterance",
             [near(JTEKT, 6, asset=HYDRANT), only(assets=[HYDRANT])], [place(HYDRANT, loc("in_front_of", JTEKT))]),
        case(t, "erroneous", "car_2_coordinates_spaces", "place passenger car 2 at x=-40 y =-10",
             [near(None, 0.5, asset=CAR_2, point=(-40.0, -10.0)), only(assets=[CAR_2])], [place(CAR_2, xy(-40, -10))]),
        case(t, "erroneous", "robber_west_crosswalk", "place the robber at the west crosswalk",
             [near(WEST_CROSSWALK, 6, asset="ackermann_robot_1"), only(assets=["ackermann_robot_1"])],
             [place("ackermann_robot_1", loc("at", WEST_CROSSWALK))], setup=[ROBOT_IN_LOT_B],
             notes="autocorrect: robber for robot"),
        impossible(t, "erroneous", "suv_2km_east", "place the suv 2 km east of the east gate", place(SUV, xy(2100, 0)),
                   notes="off the map"),
    ]


def moving_cases() -> list[Json]:
    t = "moving"
    return [
        # direct
        case(t, "direct", "ego_forward_20", "Move the ego forward 20 metres.",
             [moved(EGO, 18, 22, "forward"), only(assets=[EGO])], [move(EGO, forward=20)]),
        case(t, "direct", "suv_turn_around", "Turn the SUV around 180 degrees.",
             [moved(SUV, 0, 0.5, turn_min=170), only(assets=[SUV])], [move(SUV, turn_deg=180)]),
        case(t, "direct", "cars_east_and_west",
             "Make passenger car 1 drive east along Main Street and passenger car 2 drive west.",
             [does("drive_lane", asset=CAR_1, lane=EASTBOUND), does("drive_lane", asset=CAR_2, lane=WESTBOUND),
              only(assets=[CAR_1, CAR_2])],
             [behave(CAR_1, "drive_lane", lane=EASTBOUND), behave(CAR_2, "drive_lane", lane=WESTBOUND)], compound=True),
        case(t, "direct", "ego_speed_10", "Set the ego's speed to 10 m/s.",
             [does("drive_lane", asset=EGO, speed_min=9.5, speed_max=10.5), only(assets=[EGO])],
             [behave(EGO, "drive_lane", lane=EASTBOUND, speed=10)]),
        case(t, "direct", "pedestrian_cross_west", "Make the pedestrian cross the road at the west crosswalk.",
             [does("cross_road", asset="pedestrian_1", crosses_lane=EASTBOUND), only(assets=["pedestrian_1"])],
             [behave("pedestrian_1", "cross_road")], setup=[PERSON_AT_WEST_CROSSWALK]),
        case(t, "direct", "bench_east_5", "Shift the bench 5 metres east.",
             [moved(BENCH, 4.5, 5.5), near(None, 1, asset=BENCH, point=(-21.0, -6.9)), only(assets=[BENCH])],
             [move(BENCH, east=5)]),
        case(t, "direct", "robot_circle_radius_4", "Make the robot drive in a circle of radius 4 metres in lot B.",
             [does("circle", asset="ackermann_robot_1", radius_min=3.5, radius_max=4.5, centre_near=LOT_B),
              only(assets=["ackermann_robot_1"])],
             [behave("ackermann_robot_1", "circle", radius=4, centre=LOT_B)], setup=[ROBOT_IN_LOT_B]),
        case(t, "direct", "ego_stops_at_5s", "Make the ego brake to a stop five seconds into the scenario.",
             [event_played(EGO, "stop", 8), only()], [call("add_manoeuvre", actor=EGO, manoeuvre={"kind": "stop"}, at_time=5)]),
        impossible(t, "direct", "ego_300_kmh", "Make the ego drive at 300 km/h.",
                   behave(EGO, "drive_lane", lane=EASTBOUND, speed=83.3), notes="speeds stop at 40 m/s"),
        # indirect
        case(t, "indirect", "teen_back_suv_up",
             "He always parks too far forward. Back the SUV up about ten feet in its bay so he can see what "
             "right looks like.",
             [moved(SUV, 2.5, 3.6, "backward"), only(assets=[SUV])], [move(SUV, forward=-3.05)]),
        case(t, "indirect", "claim_suv_pulled_out",
             "According to the customer, the SUV had pulled out of the car park and was heading west on Main "
             "Street.",
             [does("drive_lane", asset=SUV, lane=WESTBOUND), only(assets=[SUV])],
             [behave(SUV, "drive_lane", lane=WESTBOUND)]),
        case(t, "indirect", "previs_back_and_slow",
             "For the tracking shot the ego should start ten metres further back and be rolling at about "
             "three metres a second.",
             [moved(EGO, 9, 11, "backward"), does("drive_lane", asset=EGO, speed_min=2.5, speed_max=3.5),
              only(assets=[EGO])],
             [move(EGO, forward=-10), behave(EGO, "drive_lane", lane=EASTBOUND, speed=3)], compound=True),
        case(t, "indirect", "robot_round_and_round",
             "I'm measuring odometry drift, so I need the robot going round and round in lot A for a while.",
             [does("circle", asset="ackermann_robot_1", centre_near=LOT_A), only(assets=["ackermann_robot_1"])],
             [behave("ackermann_robot_1", "circle", centre=LOT_A)], setup=[ROBOT_IN_LOT_A]),
        case(t, "indirect", "charity_step_out",
             "We want drivers to see what happens when someone steps out without looking. Have the person at "
             "the bus stop dart across in front of the ego.",
             [does("jaywalk", asset="pedestrian_1"), only(assets=["pedestrian_1"])],
             [behave("pedestrian_1", "jaywalk")], setup=[PERSON_AT_BUS_STOP]),
        case(t, "indirect", "radio_walking_pace",
             "Traffic on Main Street is crawling this morning; the ego should be down to about two metres a "
             "second.",
             [does("drive_lane", asset=EGO, speed_min=1.5, speed_max=2.5), only(assets=[EGO])],
             [behave(EGO, "drive_lane", lane=EASTBOUND, speed=2)]),
        case(t, "indirect", "manager_car_wrong_way", "the car nearest the union is facing the wrong way for the photo, spin it",
             [moved(CAR_2, 0, 2, turn_min=150), only(assets=[CAR_2])], [move(CAR_2, turn_deg=180)]),
        case(t, "indirect", "tester_nudge_left_stays_in_lane",
             "Try nudging the ego one metre to its left; I expect it to stay inside its lane.",
             [moved(EGO, 0.8, 1.2, "left"), in_lane(EASTBOUND, asset=EGO), only(assets=[EGO])], [move(EGO, left=1)]),
        impossible(t, "indirect", "tree_drives_round",
                   "For the dream sequence, the tree by the library should drive round and round the junction.",
                   behave(TREE_LIBRARY, "circle", centre=JUNCTION), notes="a tree cannot drive"),
        # vague
        case(t, "vague", "ego_bit_forward", "nudge the ego forward a car length or so",
             [moved(EGO, 3, 7, "forward"), only(assets=[EGO])], [move(EGO, forward=4.6)]),
        case(t, "vague", "truck_too_fast", "that truck's going way too fast, ease it off",
             [does("drive_lane", asset="truck_1", speed_min=0.5, speed_max=7), only(assets=["truck_1"])],
             [behave("truck_1", "drive_lane", lane=EASTBOUND, speed=4)],
             setup=[turn("Add a truck driving east on Main Street at 8 m/s.",
                         add(TRUCK, behaviour={"kind": "drive_lane", "lane": EASTBOUND, "speed": 8}))]),
        case(t, "vague", "get_them_moving", "get them walking across",
             [does(["cross_road", "jaywalk", "follow_path"], PERSON), only(PERSON)], [behave("pedestrian_1", "cross_road")],
             setup=[turn("Add a pedestrian at the north crosswalk.", add(PERSON, where=loc("at", NORTH_CROSSWALK)),
                         planned=True)]),
        case(t, "vague", "the_other_bike_rides_across",
             "the one at the west crosswalk is fine where it is, have the other one ride across",
             [does("cross_road", asset="bicycle_2", crosses_lane=NORTHBOUND), only(assets=["bicycle_2"])],
             [behave("bicycle_2", "cross_road")],
             setup=[turn("Two bikes please, one at the west crosswalk and one at the north crosswalk.",
                         add(BIKE, where=loc("at", WEST_CROSSWALK)), add(BIKE, where=loc("at", NORTH_CROSSWALK)))]),
        case(t, "vague", "bench_no_wait_just_turn",
             "put the bench by the fountain... no wait, scrap that, just turn it round where it is",
             [moved(BENCH, 0, 1, turn_min=150), only(assets=[BENCH])], [move(BENCH, turn_deg=180)],
             notes="the speaker takes back the move; only the turn stands"),
        case(t, "vague", "car_2_go_somewhere", "can passenger car 2 actually go somewhere",
             [does(["drive_lane", "circle", "follow_path"], asset=CAR_2), only(assets=[CAR_2])],
             [behave(CAR_2, "drive_lane", lane=EASTBOUND)]),
        case(t, "vague", "robot_faster", "can it go a bit faster?",
             [does("circle", ROBOT, speed_min=2.5), only(ROBOT)],
             [behave("ackermann_robot_1", "circle", centre=LOT_B, radius=5, speed=3.5)],
             setup=[turn("Have a robot drive round in a circle in lot B.",
                         add(ROBOT, where=loc("at", LOT_B), behaviour={"kind": "circle", "centre": LOT_B}),
                         planned=True)]),
        case(t, "vague", "bin_back_from_kerb", "push the bin back from the kerb a little",
             [moved(BIN, 0.5, 5), near(None, 1.6, asset=BIN, point=(-33.5, -7.5)), only(assets=[BIN])],
             [move(BIN, north=-1.5)]),
        impossible(t, "vague", "shift_crossroads", "shift the whole crossroads a bit north",
                   move(JUNCTION, north=5), notes="the crossroads is road, not an asset"),
        # erroneous
        case(t, "erroneous", "teh_ego_foward", "move teh ego foward 15m",
             [moved(EGO, 13, 17, "forward"), only(assets=[EGO])], [move(EGO, forward=15)]),
        case(t, "erroneous", "suv_2_meter_left", "shift suv 2 meter to it's left",
             [moved(SUV, 1.5, 2.5, "left"), only(assets=[SUV])], [move(SUV, left=2)]),
        case(t, "erroneous", "passanger_northbond", "make passanger car 1 drive on campus drive northbond",
             [does("drive_lane", asset=CAR_1, lane=NORTHBOUND), only(assets=[CAR_1])],
             [behave(CAR_1, "drive_lane", lane=NORTHBOUND)]),
        case(t, "erroneous", "pedestrain_cross_pls", "pedestrain cross road pls at the crossing",
             [does("cross_road", asset="pedestrian_1"), only(assets=["pedestrian_1"])],
             [behave("pedestrian_1", "cross_road")], setup=[PERSON_AT_WEST_CROSSWALK]),
        case(t, "erroneous", "robot_circles_6m", "robot do circles in lot A radius 6m",
             [does("circle", asset="ackermann_robot_1", radius_min=5.5, radius_max=6.5), only(assets=["ackermann_robot_1"])],
             [behave("ackermann_robot_1", "circle", radius=6, centre=LOT_A)], setup=[ROBOT_IN_LOT_A]),
        case(t, "erroneous", "slow_truk_3", "slow the truk down to 3 m/s",
             [does("drive_lane", asset="truck_1", speed_min=2.5, speed_max=3.5), only(assets=["truck_1"])],
             [behave("truck_1", "drive_lane", lane=WESTBOUND, speed=3)],
             setup=[turn("Add a truck driving west on Main Street.",
                         add(TRUCK, behaviour={"kind": "drive_lane", "lane": WESTBOUND, "speed": 8}))]),
        case(t, "erroneous", "turn_ego_90_left", "Please to turn the ego 90 degree to left side.",
             [moved(EGO, 0, 1, turn_min=80, turn_max=100), only(assets=[EGO])], [move(EGO, turn_deg=90)]),
        case(t, "erroneous", "beach_3m_north", "Move the beach 3 metres north",
             [moved(BENCH, 2.5, 3.5), near(None, 0.8, asset=BENCH, point=(-26.0, -3.9)), only(assets=[BENCH])],
             [move(BENCH, north=3)], notes="autocorrect: beach for bench"),
        impossible(t, "erroneous", "stop_sign_drive", "make the stop sign drive arond the block",
                   behave(STOP_SIGN, "drive_lane", lane=EASTBOUND), notes="a sign cannot drive"),
    ]


def arrangement_cases() -> list[Json]:
    t = "arrangement"
    return [
        # direct
        case(t, "direct", "cone_line_eastbound_bus_stop",
             "Put a line of six traffic cones along the edge of the eastbound lane, starting at the bus stop.",
             [layout("line", CONE, 6), in_lane(EASTBOUND, CONE, scope="added"), delta(CONE, 6, 6), only(CONE)],
             [arrange(CONE, "lane_edge", loc("at", BUS_STOP, lane=EASTBOUND), count=6)]),
        case(t, "direct", "bollard_ring_fountain", "Put a ring of eight bollards around the fountain.",
             [layout("ring", BOLLARD, 8, around=FOUNTAIN), delta(BOLLARD, 8, 8), only(BOLLARD)],
             [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=8)]),
        case(t, "direct", "row_of_four_lot_a", "Add a row of four parked cars in parking lot A.",
             [layout("line", CARS, 4), near(LOT_A, 0.5, CARS, scope="added", every=True), delta(CARS, 4, 4), only(*CARS)],
             [arrange(CAR, "parking_row", loc("at", LOT_A), count=4)]),
        case(t, "direct", "barriers_across_campus_drive",
             "Put a line of three road barriers across Campus Drive, a few metres north of the north crosswalk.",
             [layout("line", BARRIER, 3), near(None, 6, BARRIER, scope="added", every=True, point=(0.0, 16.0)),
              on(["lane", "crossing", "paved"], BARRIER, scope="added"), only(BARRIER)],
             [arrange(BARRIER, "line", xy(0, 16), count=3, heading_deg=0, spacing=2.3)]),
        case(t, "direct", "grid_of_six_bikes", "Lay out a grid of six bicycles in parking lot B, two rows of three.",
             [layout("cluster", BIKE, 6, tolerance=8), near(LOT_B, 0.5, BIKE, scope="added", every=True),
              delta(BIKE, 6, 6), only(BIKE)],
             [arrange(BIKE, "grid", loc("at", LOT_B), count=6, columns=3)]),
        case(t, "direct", "five_people_sidewalk_bus_stop", "Line up five pedestrians along the sidewalk at the bus stop.",
             [layout("line", PERSON, 5), near(BUS_STOP, 6, PERSON, scope="added", every=True),
              on(["sidewalk"], PERSON, scope="added"), delta(PERSON, 5, 5), only(PERSON)],
             [arrange(PERSON, "line", loc("on_sidewalk", BUS_STOP), count=5)]),
        case(t, "direct", "ring_round_rubble", "Put a ring of cones around the rubble.",
             [layout("ring", CONE, 4, around="cement_rubble_1"), near("cement_rubble_1", 5, CONE, scope="added", every=True),
              only(CONE)],
             [arrange(CONE, "ring", loc("at", "cement_rubble_1"))],
             setup=[turn("Drop a pile of rubble in the middle of the junction.", add(RUBBLE, where=xy(0, 0)), planned=True)]),
        case(t, "direct", "row_lot_a_ring_lot_b",
             "Add a row of three parked cars in lot A, and a ring of six cones around the middle of lot B.",
             [layout("line", CARS, 3), near(LOT_A, 0.5, CARS, scope="added", every=True),
              layout("ring", CONE, 6, around=LOT_B), near(LOT_B, 0.5, CONE, scope="added", every=True),
              only(CAR, SUV_KIND, CONE)],
             [arrange(CAR, "parking_row", loc("at", LOT_A), count=3), arrange(CONE, "ring", loc("at", LOT_B), count=6, radius=4)],
             compound=True),
        impossible(t, "direct", "ring_150m", "Put a ring of cones with a 150 metre radius around the main intersection.",
                   arrange(CONE, "ring", loc("at", JUNCTION), radius=150), notes="rings reach 60 m at most"),
        # indirect
        case(t, "indirect", "teen_slalom_lot_a",
             "Her instructor wants her weaving between cones, so set up a slalom of six cones in lot A, "
             "about fifteen feet apart.",
             [layout("line", CONE, 6, spacing_min=3.5, spacing_max=6), near(LOT_A, 0.5, CONE, scope="added", every=True),
              delta(CONE, 6, 6), only(CONE)],
             [arrange(CONE, "line", loc("at", LOT_A), count=6, spacing=4.6, heading_deg=0)]),
        case(t, "indirect", "claim_queue_at_lights",
             "The claimant was at the back of a queue of three cars waiting at the lights on Main Street, "
             "heading east towards the junction.",
             [layout("line", CARS, 3), in_lane(EASTBOUND, CARS, scope="added", aligned=True),
              near(WEST_CROSSWALK, 25, CARS, scope="added", every=True), delta(CARS, 3, 4), only(*CARS)],
             [arrange(CAR, "line", xy(-22, -1.75), count=3, heading_deg=0, spacing=6)]),
        case(t, "indirect", "previs_crowd_fountain",
             "For the wide shot I need a crowd gathered in a circle round the fountain, about ten people.",
             [layout("ring", PERSON, 8, around=FOUNTAIN), delta(PERSON, 8, 12), only(PERSON)],
             [arrange(PERSON, "ring", loc("at", FOUNTAIN), count=10, radius=5)]),
        case(t, "indirect", "robot_corridor_lot_b",
             "Build my robot a corridor to drive down: two parallel lines of five cones, three metres apart, "
             "in lot B.",
             [delta(CONE, 10, 10), near(LOT_B, 0.5, CONE, scope="added", every=True), layout("cluster", CONE, 10, tolerance=12),
              only(CONE)],
             [arrange(CONE, "line", xy(30, -22), count=5, heading_deg=0, spacing=3),
              arrange(CONE, "line", xy(30, -25), count=5, heading_deg=0, spacing=3)],
             compound=True),
        case(t, "indirect", "charity_bollards_kerb",
             "Outside the library, where the children wait for the bus, we'd like a row of bollards so cars "
             "can't mount the pavement.",
             [layout("line", BOLLARD, 3), delta(BOLLARD, 3, 12), only(BOLLARD)],
             [arrange(BOLLARD, "line", xy(-30, -4.0), count=5, heading_deg=0, spacing=1.5)],
             alternatives=[[near(BUS_STOP, 10, BOLLARD, scope="added", every=True)],
                           [near(LIBRARY, 12, BOLLARD, scope="added", every=True)]]),
        case(t, "indirect", "radio_northbound_closure",
             "Campus Drive northbound is shut south of the junction for resurfacing. Show it coned off along "
             "the lane.",
             [layout("line", CONE, 5), in_lane(NORTHBOUND, CONE, scope="added"),
              near(None, 40, CONE, scope="added", every=True, point=(1.75, -50.0)), only(CONE)],
             [arrange(CONE, "lane_edge", loc("absolute", x=1.75, y=-40, lane=NORTHBOUND), count=8)]),
        case(t, "indirect", "manager_suvs_for_brochure",
             "for the brochure photo we want three new SUVs lined up neatly side by side in lot B",
             [layout("line", SUV_KIND, 3), near(LOT_B, 0.5, SUV_KIND, scope="added", every=True), delta(SUV_KIND, 3, 3),
              only(SUV_KIND)],
             [arrange(SUV_KIND, "parking_row", loc("at", LOT_B), count=3)]),
        case(t, "indirect", "tester_odd_count_lane_edge",
             "Checking odd counts: seven cones along the eastbound lane edge, starting from the main gate.",
             [layout("line", CONE, 7), in_lane(EASTBOUND, CONE, scope="added"), delta(CONE, 7, 7),
              near(MAIN_GATE, 30, CONE, scope="added", every=True), only(CONE)],
             [arrange(CONE, "lane_edge", loc("at", MAIN_GATE, lane=EASTBOUND), count=7)]),
        impossible(t, "indirect", "grid_250_cones", "For the open day, fill lot A with a grid of 250 cones.",
                   arrange(CONE, "grid", loc("at", LOT_A), count=250), notes="at most 200 cones fit a scene"),
        # vague
        case(t, "vague", "cone_that_off", "cone that off",
             [delta(CONE, 3, 12), near("cement_rubble_1", 5, CONE, scope="added", every=True), only(CONE)],
             [arrange(CONE, "ring", loc("at", "cement_rubble_1"))],
             setup=[turn("There's a pile of rubble in lot B, put it in.", add(RUBBLE, where=loc("at", LOT_B)))]),
        case(t, "vague", "bikes_lined_up_jtekt", "bikes lined up by the JTEKT entrance",
             [layout("line", BIKE, 3), near(JTEKT, 12, BIKE, scope="added", every=True), only(BIKE)],
             [arrange(BIKE, "line", loc("at", JTEKT), count=4)]),
        case(t, "vague", "crowd_round_fountain", "crowd round the fountain",
             [layout("cluster", PERSON, 4, tolerance=12), near(FOUNTAIN, 12, PERSON, scope="added", every=True), only(PERSON)],
             [arrange(PERSON, "ring", loc("at", FOUNTAIN), count=8, radius=4)]),
        case(t, "vague", "fence_off_lot_a_entrance", "fence off the lot A entrance",
             [layout("line", [BARRIER, CONE, BOLLARD], 2), near(LOT_A_ENTRANCE, 12, MARKERS, scope="added", every=True),
              only(*MARKERS)],
             [arrange(BARRIER, "line", xy(-85, 9), count=3, heading_deg=0, spacing=2.1)]),
        case(t, "vague", "row_of_cars_lot_b", "a row of cars in lot B",
             [layout("line", CARS, 3), near(LOT_B, 0.5, CARS, scope="added", every=True), delta(CARS, 3, 10), only(*CARS)],
             [arrange(CAR, "parking_row", loc("at", LOT_B), count=4)]),
        case(t, "vague", "trees_in_a_row_engineering", "trees in a row somewhere near the engineering building",
             [layout("line", "tree", 3), near(ENGINEERING, 15, "tree", scope="added", every=True), only("tree")],
             [arrange("tree", "line", loc("at", ENGINEERING), count=3)]),
        case(t, "vague", "surround_it_with_bollards", "surround it with bollards",
             [layout("ring", BOLLARD, 4, around="bench_2"), near("bench_2", 5, BOLLARD, scope="added", every=True),
              only(BOLLARD)],
             [arrange(BOLLARD, "ring", loc("at", "bench_2"))],
             setup=[turn("Put a bench by the fountain.", add("bench", where=loc("at", FOUNTAIN)), planned=True)]),
        case(t, "vague", "line_cones_lot_b_go", "line of cones. lot b. go",
             [layout("line", CONE, 3), near(LOT_B, 0.5, CONE, scope="added", every=True), only(CONE)],
             [arrange(CONE, "line", loc("at", LOT_B), count=5)]),
        case(t, "vague", "barriers_along_westbound_east_gate", "barriers all along the westbound lane near the east gate",
             [layout("line", BARRIER, 3), in_lane(WESTBOUND, BARRIER, scope="added"),
              near(EAST_GATE, 35, BARRIER, scope="added", every=True), only(BARRIER)],
             [arrange(BARRIER, "lane_edge", loc("at", EAST_GATE, lane=WESTBOUND), count=6)]),
        # erroneous
        case(t, "erroneous", "cone_line_eastboud", "put 5 cone in a line along eastboud lane from bus stop",
             [layout("line", CONE, 5), in_lane(EASTBOUND, CONE, scope="added"), delta(CONE, 5, 5), only(CONE)],
             [arrange(CONE, "lane_edge", loc("at", BUS_STOP, lane=EASTBOUND), count=5)]),
        case(t, "erroneous", "rign_of_bollards", "make a rign of bollards arund the fountian, 6 of them",
             [layout("ring", BOLLARD, 6, around=FOUNTAIN), delta(BOLLARD, 6, 6), only(BOLLARD)],
             [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=6)]),
        case(t, "erroneous", "four_cars_row_plz", "4 cars parked in row at lot A plz",
             [layout("line", CARS, 4), near(LOT_A, 0.5, CARS, scope="added", every=True), delta(CARS, 4, 4), only(*CARS)],
             [arrange(CAR, "parking_row", loc("at", LOT_A), count=4)]),
        case(t, "erroneous", "grid_nine_cone", "Make grid of nine cone in parking B, three and three.",
             [layout("cluster", CONE, 9, tolerance=8), near(LOT_B, 0.5, CONE, scope="added", every=True), delta(CONE, 9, 9),
              only(CONE)],
             [arrange(CONE, "grid", loc("at", LOT_B), count=9, columns=3)]),
        case(t, "erroneous", "pedestrans_sidewak_library", "line up 4 pedestrans on the sidewak by library",
             [layout("line", PERSON, 4), on(["sidewalk"], PERSON, scope="added"),
              near(LIBRARY, 15, PERSON, scope="added", every=True), only(PERSON)],
             [arrange(PERSON, "line", loc("on_sidewalk", LIBRARY), count=4)]),
        case(t, "erroneous", "barriers_lot_be_entrance", "Put a line of barriers across the lot be entrance",
             [layout("line", BARRIER, 2), near(LOT_B_ENTRANCE, 8, BARRIER, scope="added", every=True),
              on(["drivable"], BARRIER, scope="added"), only(BARRIER)],
             [arrange(BARRIER, "line", xy(47, -8), count=3, heading_deg=0, spacing=2.1)],
             notes="autocorrect: 'be' for B"),
        case(t, "erroneous", "ring_of_peoples_bus_stop", "ring of peoples around the bus stop, maybe 6",
             [layout("ring", PERSON, 5, around=BUS_STOP), delta(PERSON, 5, 7), only(PERSON)],
             [arrange(PERSON, "ring", loc("at", BUS_STOP), count=6)]),
        case(t, "erroneous", "acircle_of_cones", "acircle of cones round the rubble",
             [layout("ring", CONE, 4, around="cement_rubble_1"), only(CONE)],
             [arrange(CONE, "ring", loc("at", "cement_rubble_1"))],
             setup=[turn("Put some rubble in lot A.", add(RUBBLE, where=loc("at", LOT_A)))]),
        impossible(t, "erroneous", "ring_200m_ego", "put a ring of cones radius 200m around the ego",
                   arrange(CONE, "ring", loc("at", EGO), radius=200), notes="rings reach 60 m at most"),
    ]


def appearance_cases() -> list[Json]:
    t = "appearance"
    return [
        # direct
        case(t, "direct", "time_22", "Set the time to 22:00.",
             [env(time_from="21:55", time_to="22:05", **CLEAR), only(env=True)], [clock("22:00")]),
        case(t, "direct", "heavy_rain", "Make it rain heavily.",
             [env(weather=["rain"], intensity_min=0.7, **NOON), only(env=True)], [weather("rain", 0.9)]),
        case(t, "direct", "light_fog", "Add light fog.",
             [env(weather=["fog"], intensity_min=0.05, intensity_max=0.45, **NOON), only(env=True)], [weather("fog", 0.3)]),
        case(t, "direct", "suv_red", "Paint the SUV red.",
             [looks("red", asset=SUV, tolerance=0.1), only(assets=[SUV])], [paint([SUV], colour="red")]),
        case(t, "direct", "street_lights_on", "Turn the street lights on.",
             [env(street_lights="on", **NOON, **CLEAR), only(env=True)], [lighting(street_lights="on")]),
        case(t, "direct", "bus_yellow", "Make the bus yellow.",
             [looks("yellow", asset="bus_1", tolerance=0.1), only(assets=["bus_1"])], [paint(["bus_1"], colour="yellow")],
             setup=[BUS_IN_LOT_B]),
        case(t, "direct", "snow_at_dusk", "Set snow and make it dusk.",
             [env(weather=["snow"], time_from="18:30", time_to="20:30"), only(env=True)], [weather("snow"), clock("dusk")],
             compound=True),
        impossible(t, "direct", "time_25_30", "Set the time to 25:30.", clock("25:30"), notes="no such clock time"),
        # indirect
        case(t, "indirect", "teen_dark_and_snow",
             "His test is on a winter evening, so I'd like him practising in the dark with snow coming down.",
             [env(weather=["snow"], night=True), only(env=True)], [weather("snow"), clock("21:00")], compound=True),
        case(t, "indirect", "claim_pouring_nine_pm",
             "The customer says it was pouring down and dark when it happened, around nine at night.",
             [env(weather=["rain"], intensity_min=0.6, time_from="20:30", time_to="21:30"), only(env=True)],
             [weather("rain", 0.9), clock("21:00")], compound=True),
        case(t, "indirect", "previs_golden_hour", "The shot's meant to feel like golden hour, just before the sun goes down.",
             [env(time_from="17:00", time_to="20:00", **CLEAR), only(env=True)], [clock("19:00")]),
        case(t, "indirect", "charity_cyclist_hi_vis",
             "We're making a point about being seen: the cyclist should be in bright yellow.",
             [looks("yellow", asset="bicycle_1", tolerance=0.15), only(assets=["bicycle_1"])],
             [paint(["bicycle_1"], colour="yellow")],
             setup=[turn("Add a cyclist at the west crosswalk.", add(BIKE, where=loc("at", WEST_CROSSWALK)))]),
        case(t, "indirect", "radio_fog_eight_am", "This morning's bulletin is all about fog on campus at eight o'clock.",
             [env(weather=["fog"], time_from="07:30", time_to="08:30"), only(env=True)], [weather("fog"), clock("08:00")],
             compound=True),
        case(t, "indirect", "robot_washed_out",
             "The camera images are too washed out for my detector. Can the exposure come down?",
             [env(exposure_max=0.95, **NOON, **CLEAR), only(env=True)], [lighting(exposure=0.7)]),
        case(t, "indirect", "manager_navy_brand", "client's brand colour is navy, do the parked cars in that",
             [looks("navy", CAR, scope="all", tolerance=0.1, every=True), only(*CARS)],
             [paint(list(PARKED), colour="navy")], notes="the SUV may be counted among the cars, or not"),
        case(t, "indirect", "tester_midnight_lamps_failed",
             "I want to see what the ego perceives at midnight when the street lamps have all failed.",
             [env(time_from="23:30", time_to="00:30", street_lights="off"), only(env=True)],
             [clock("00:00"), lighting(street_lights="off")], compound=True),
        impossible(t, "indirect", "meteor_shower",
                   "For the alien invasion shot, give us a meteor shower over the campus.",
                   weather("meteor_shower"), notes="weather is clear, cloudy, rain, fog or snow"),
        # vague
        case(t, "vague", "bit_gloomy", "make it a bit gloomy",
             [only(env=True)], [weather("cloudy", 0.7)],
             alternatives=[[env(weather=["cloudy", "rain", "fog"])], [env(time_from="18:00", time_to="05:00")],
                           [env(exposure_max=0.9)]]),
        case(t, "vague", "later_in_the_day", "later in the day",
             [env(time_from="13:00", time_to="20:30", **CLEAR), only(env=True)], [clock("afternoon")]),
        case(t, "vague", "brighter", "brighter pls",
             [env(exposure_min=1.05, **NOON, **CLEAR), only(env=True)], [lighting(exposure=1.4)]),
        case(t, "vague", "something_wintry", "something wintry",
             [env(weather=["snow"]), only(env=True)], [weather("snow")]),
        case(t, "vague", "make_it_stand_out", "make it stand out more",
             [looks(BRIGHT_COLOURS, asset="passenger_car_3"), only(assets=["passenger_car_3"])],
             [paint(["passenger_car_3"], colour="yellow")],
             setup=[turn("Add a car in front of the JTEKT entrance.", add(CAR, where=loc("in_front_of", JTEKT)),
                         planned=True)]),
        case(t, "vague", "night_mode", "night mode", [env(night=True, **CLEAR), only(env=True)], [clock("night")]),
        case(t, "vague", "tone_rain_down", "tone the rain down",
             [env(weather=["rain"], intensity_min=0.05, intensity_max=0.75), only(env=True)], [weather("rain", 0.4)],
             setup=[turn("Make it rain really hard.", weather("rain", 0.9))]),
        case(t, "vague", "bench_more_natural", "the bench should look more natural",
             [only(assets=[BENCH])], [paint([BENCH], material="wood")],
             alternatives=[[looks(asset=BENCH, material="wood")], [looks(["brown", "green"], asset=BENCH)]]),
        impossible(t, "vague", "hail_lots", "hail. lots of it.", weather("hail", 0.9), notes="no hail in the weather kinds"),
        # erroneous
        case(t, "erroneous", "nihgt_and_lights", "make it nihgt and switch the street lights on",
             [env(night=True, street_lights="on"), only(env=True)], [clock("night"), lighting(street_lights="on")],
             compound=True),
        case(t, "erroneous", "wether_rian", "set wether to rian",
             [env(weather=["rain"], **NOON), only(env=True)], [weather("rain")]),
        case(t, "erroneous", "fogg_keep_dark", "now put some fogg in to, keep it dark",
             [env(weather=["fog"], night=True), only(env=True)], [weather("fog")],
             setup=[turn("Make it night time.", clock("night"), planned=True)]),
        case(t, "erroneous", "suv_blu", "paint suv blu", [looks("blue", asset=SUV, tolerance=0.1), only(assets=[SUV])],
             [paint([SUV], colour="blue")]),
        case(t, "erroneous", "time_too_7_morning", "set time too 7 in the morning",
             [env(time_from="06:45", time_to="07:15", **CLEAR), only(env=True)], [clock("07:00")]),
        case(t, "erroneous", "switch_of_lights", "switch of the street lights",
             [env(street_lights="off", **NOON, **CLEAR), only(env=True)], [lighting(street_lights="off")]),
        case(t, "erroneous", "bench_color_to_be_green", "Please make the color of the bus stop bench to be green.",
             [looks("green", asset=BENCH, tolerance=0.1), only(assets=[BENCH])], [paint([BENCH], colour="green")]),
        case(t, "erroneous", "sub_matte_black", "Make the sub matte black",
             [looks("black", asset=SUV, tolerance=0.1, material="matte"), only(assets=[SUV])],
             [paint([SUV], colour="black", material="matte")], notes="autocorrect: sub for suv"),
        case(t, "erroneous", "vehicel_lights_on", "turn the vehicel lights on, its for a headlight test",
             [env(vehicle_lights="on", **NOON, **CLEAR), only(env=True)], [lighting(vehicle_lights="on")]),
    ]


ALL_CASES: list[Json] = [
    *search_cases(),
    *addition_cases(),
    *removal_cases(),
    *positioning_cases(),
    *moving_cases(),
    *arrangement_cases(),
    *appearance_cases(),
]
SUITE = TAG
SUITE_PATH = Path(__file__).resolve().with_name("suites") / f"{SUITE}.jsonl"


def main() -> None:
    """Write the suite's JSONL, one case a line."""
    SUITE_PATH.parent.mkdir(parents=True, exist_ok=True)
    lines = [json.dumps(c, ensure_ascii=False) for c in ALL_CASES]
    SUITE_PATH.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"wrote {len(lines)} cases to {SUITE_PATH}")


if __name__ == "__main__":
    main()
