"""The seventeenth practice suite: 263 cases in the words of nine new kinds of user, from the campus world alone.

`python -m drivetwin.evals.practice17_source` writes `suites/practice17.jsonl` (tag `practice17`, ids
`practice17.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`): an insurance claims adjuster reconstructing an incident
("vehicle 2", "at the time of the incident", "for the report"), a British user (pavement, car park,
lorry, zebra crossing, bin, lamp post, give way, "bung a tree in"), a city council member talking
about residents and their complaints, a rideshare driver ("pax", "my car", "pickup spot"), a
kindergarten teacher planning a road-safety walk with the children, a lawyer writing precise,
over-qualified sentences ("at the material time", "my client maintains", "one (1) bicycle"), a
screen-reader user whose messages are long, with filler and restatements, a robotics PhD student in
ROS and frames jargon (map frame, x forward, yaw, waypoints, setpoints, "spawn", "rm", metres as
"m"), and a user who code-switches with a few Spanish words ("por favor", "la calle", "el coche").
Prompts mix short chat turns with one-to-three sentence requests, reasons and hedges, references
back to earlier turns ("that one", "the same again", "the other one", "the item to which I have just
referred"), numbers in words and digits, units (metres, feet, m/s, km/h, mph), relations (next to,
in front of, behind, ahead of, along, across the road from, between), scopes (a lane, a lot, a
sidewalk, a side of a road, a landmark), behaviours (speeds, stopping, giving way, crossing, walking
somewhere, circling, patrolling), weather and clock times, questions (which must change nothing),
negation and exceptions ("all but the SUV", "except the one nearest the bus stop", "no longer want
the rain"). The erroneous grade carries realistic typos, autocorrect and dictation swaps ("Student
Onion", "fire hide rant", "eggo"), run-together and doubled words, dropped words and non-native
grammar.

Counts: 7 tasks x 4 grades, 9 or 10 cases in every cell (263 in all). 33 cases are multi-turn (14 with
a planned earlier turn that has calls), 18 compound (the reference makes two calls or more, the
prompt asks two things), and 21 (8.0 %) impossible, tagged `impossible`, where the right outcome is a
refusal that changes nothing: the distance to a petrol station, to a duck pond, where the gas station
is; fifteen lorries, speed humps, a postbox; removing the ego, the fountain, a bus that is not there;
the SUV at a map point inside the JTEKT Building, the bench on the Library's roof, the hydrant at
y = -100 (off the map); shifting the Library, 180 km/h, a tree walking across the road; 120 bollards,
a ring of 80 m radius, cones inside the Library; 26:00, a brick-red Library, a glow-in-the-dark SUV.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with
`alternatives` where a request has two fair readings, and a `reference` plan that passes; a plan
that does nothing fails every case. The suite was written from the campus world, the asset catalog,
the Worker tools and the eval checks only, by someone who had not read the planners, their lexicons,
their prompt examples or any other suite's cases.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

Json = dict[str, Any]

TAG = "practice17"

# --- The campus world, as these cases use it --------------------------------------------------
# Main Street runs east-west (eastbound lane y = -1.75, westbound y = +1.75, kerbs at y = +-3.5,
# sidewalks at y = +-5.5); Campus Drive runs north-south (northbound x = +1.75, southbound -1.75).
# The world spans x -110..110 and y -90..90; it is noon and clear.
EGO = "ego"  # the test car: drives main_eastbound at 5 m/s from (-60, -1.75), facing east
BENCH = "bench_1"  # at the bus stop, (-26, -6.9), facing west
BIN = "trash_bin_1"  # on the bus-stop sidewalk, (-33.5, -5.5)
HYDRANT = "fire_hydrant_1"  # north sidewalk of Main Street just east of the crossroads, (16, 5.5)
STOP_SIGN = "stop_sign_1"  # south sidewalk before the west crosswalk, (-13.5, -5.5), facing east
CAR_1, SUV, CAR_2 = "passenger_car_1", "suv_1", "passenger_car_2"  # lot B, x 19 / 23 / 27, y -42, facing north
PARKED = (CAR_1, SUV, CAR_2)
LIGHT_SW, LIGHT_NE = "traffic_light_1", "traffic_light_2"  # (-9.5, -6.2) and (9.5, 6.2)
TREE_LIBRARY, TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A = "tree_1", "tree_2", "tree_3", "tree_4"
# tree_1 (-26, -12) behind the bus stop, towards the Library; tree_2 (70, 45) 7 m from the fountain;
# tree_3 (85, 25) south-east of the fountain; tree_4 (-85, 50) just north of lot A.
TREES = (TREE_LIBRARY, TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A)
LAMP_LOT_A = "street_light_1"  # (-80, 5.8), the lamp nearest the lot A entrance
LAMP_BUS_STOP = "street_light_4"  # (-38, -5.8), the lamp nearest the bus stop
# Lamps 1, 3, ... 11 stand on Main Street's north side (y = 5.8), 2, 4, ... 12 on its south side.
NORTH_WEST_LAMPS = ("street_light_1", "street_light_3", "street_light_5")  # north side, west of Campus Drive
SOUTH_LAMPS = ("street_light_2", "street_light_4", "street_light_6", "street_light_8", "street_light_10",
               "street_light_12")  # Main Street's south side, x -68, -38, -13, 37, 62, 92

LOT_A, LOT_B = "parking lot A", "parking lot B"  # areas: x -100..-70, y 14..44; x 15..62, y -46..-12
LOT_A_ENTRANCE, LOT_B_ENTRANCE = "parking lot A entrance", "parking lot B entrance"  # (-85, 3.5), (47, -3.5)
LIBRARY = "Library entrance"  # (-41, -15), faces north onto the library drop-off
JTEKT = "JTEKT building entrance"  # (37.5, 15), faces south onto the JTEKT drop-off
ENGINEERING = "Engineering Hall entrance"  # (-40, 15), faces south
UNION = "Student Union entrance"  # (42.5, -51), faces north onto lot B
MAIN_GATE, EAST_GATE = "main gate", "east gate"  # (-100, 0) and (100, 0)
JUNCTION = "main intersection"  # the crossroads box, x and y -9..9
BUS_STOP = "bus stop"  # (-30, -5.5) on the south sidewalk of Main Street, faces north
FOUNTAIN = "fountain"  # (75, 40), north-east, on grass
WEST_CROSSWALK, NORTH_CROSSWALK = "west crosswalk", "north crosswalk"  # (-11.5, 0), (0, 11.5)

EASTBOUND, WESTBOUND = "main_eastbound", "main_westbound"
NORTHBOUND, SOUTHBOUND = "campus_northbound", "campus_southbound"

CONE, BARRIER, RUBBLE, BOLLARD = "traffic_cone", "road_barrier", "cement_rubble", "bollard"
CAR, SUV_KIND, BUS, TRUCK, ROBOT = "passenger_car", "suv", "bus", "truck", "ackermann_robot"
BIKE, MOTORBIKE, PERSON = "bicycle", "motorcycle", "pedestrian"
TREE, BENCH_KIND, BIN_KIND, LAMP = "tree", "bench", "trash_bin", "street_light"
PED_SIGN, WORK_SIGN, STOP_KIND, SIGNAL = "pedestrian_sign", "construction_sign", "stop_sign", "traffic_light"
HYDRANT_KIND = "fire_hydrant"
CARS = [CAR, SUV_KIND]
VEHICLES = [CAR, SUV_KIND, BUS, TRUCK, MOTORBIKE, ROBOT, BIKE]
MOTOR_TRAFFIC = [CAR, SUV_KIND, BUS, TRUCK, MOTORBIKE]
MARKERS = [CONE, BOLLARD, BARRIER]
OBSTACLES = [CONE, BARRIER, RUBBLE, BOLLARD, WORK_SIGN]
VULNERABLE = [PERSON, BIKE, MOTORBIKE]

NOON = {"time_from": "11:30", "time_to": "12:30"}  # the world's clock, pinned where a prompt leaves it
CLEAR = {"weather": ["clear"]}
BRIGHT = ["red", "yellow", "orange", "pink", "cyan", "green", "purple", "gold", "white"]  # colours that stand out
WET_OR_WHITE = ["rain", "fog", "snow"]
# Every colour the Workers name: an asset painted any colour at all matches one of these.
ANY_COLOUR = ["red", "green", "blue", "yellow", "orange", "white", "black", "grey", "silver", "purple", "pink",
              "brown", "cyan", "teal", "beige", "gold", "navy", "maroon"]
AUTUMN = ["orange", "brown", "red", "gold", "yellow", "maroon"]

# Who is speaking: each case names its voice in `notes`.
ADJUSTER = "voice: insurance claims adjuster reconstructing an incident"
BRIT = "voice: British user (pavement, car park, lorry, zebra crossing, bin, lamp post, give way)"
COUNCIL = "voice: city council member talking about residents and complaints"
RIDESHARE = "voice: rideshare driver"
TEACHER = "voice: kindergarten teacher planning a road-safety walk"
LAWYER = "voice: lawyer writing precise, over-qualified sentences"
SCREEN = "voice: screen-reader user (long messages, filler and restatements)"
ROBOTICIST = "voice: robotics PhD student in ROS and frames jargon"
SPANGLISH = "voice: user code-switching with a few Spanish words"


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


def ahead_of(target: str, metres: float, **extra: Any) -> Json:
    """A spot `metres` ahead of a target along its lane or sidewalk (negative: behind)."""
    return loc("at", target, along_m=metres, **extra)


def add(category: str, count: int = 1, where: Json | None = None, **extra: Any) -> Json:
    args: Json = {"category": category}
    if count != 1:
        args["count"] = count
    if where is not None:
        args["location"] = where
    args.update(extra)
    return call("add_asset", **args)


def drive(speed: float | None = None, lane: str | None = None) -> Json:
    """A drive_lane behaviour for add_asset."""
    out: Json = {"kind": "drive_lane"}
    if speed is not None:
        out["speed"] = speed
    if lane is not None:
        out["lane"] = lane
    return out


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


def manoeuvre(actor: str, kind: str, at_time: float = 0.0, **extra: Any) -> Json:
    return call("add_manoeuvre", actor=actor, manoeuvre={"kind": kind, **extra}, at_time=at_time)


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
             max_distance: float | None = None, tolerance_deg: float | None = None, every: bool = False) -> Json:
    return _selecting("relative", category, asset, None, None, True if every else None, relation=relation,
                      target=target, max_distance=max_distance, tolerance_deg=tolerance_deg)


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


def refused() -> Json:
    return {"kind": "status", "accepted": False}


def event_played(actor: str, kind: str, seconds: float) -> Json:
    """The storyboard gives `actor` (an id or a category) a manoeuvre of `kind` that starts within `seconds`."""
    return {"kind": "scenario", "seconds": seconds,
            "expect": [{"kind": "event", "actor": actor, "manoeuvre": kind}]}


def stops_before(actor: str, x: float, y: float, seconds: float = 20.0) -> Json:
    """Run the scene: `actor` never crosses the point (x, y) it drives towards and ends stopped."""
    return {"kind": "scenario", "seconds": seconds,
            "expect": [{"kind": "stopped_before", "actor": actor, "line": [x, y]}]}


def reaches(actor: str, place: str, seconds: float, within: float = 4.0) -> Json:
    """Run the scene: `actor` comes within `within` metres of `place`."""
    return {"kind": "scenario", "seconds": seconds,
            "expect": [{"kind": "reached", "actor": actor, "place": place, "within": within}]}


# --- Cases -------------------------------------------------------------------------------------
def case(task: str, grade: str, name: str, voice: str, prompt: str, checks: list[Json], reference: list[Json], *,
         setup: Sequence[Json] = (), alternatives: Sequence[list[Json]] = (), tags: Sequence[str] = ()) -> Json:
    """One case; `multi_turn` and `compound` tags follow from its setup and its reference."""
    all_tags = [TAG, *tags]
    if setup:
        all_tags.append("multi_turn")
    if len(reference) >= 2:
        all_tags.append("compound")
    out: Json = {"id": f"{TAG}.{task}.{grade}.{name}", "world": "campus"}
    if setup:
        out["setup"] = list(setup)
    out.update({"prompt": prompt, "task": task, "grade": grade, "tags": all_tags, "checks": checks})
    if alternatives:
        out["alternatives"] = [list(alt) for alt in alternatives]
    out["reference"] = reference
    out["notes"] = voice
    return out


def impossible(task: str, grade: str, name: str, voice: str, prompt: str, reference: list[Json], *,
               setup: Sequence[Json] = ()) -> Json:
    """A request the world cannot do: the right outcome is a refusal that changes nothing.

    The reference is the call a literal reading makes, which the Workers refuse."""
    return case(task, grade, name, voice, prompt, [refused(), only()], reference, setup=setup, tags=("impossible",))



# --- Search: questions that must change nothing, whose answer names the right thing -----------
SEARCH_CASES: list[Json] = [
    # direct
    case("search", "direct", "nearest_hydrant_and_distance", ADJUSTER,
         "Identify the fire hydrant closest to the ego vehicle and state its distance from the ego in metres.",
         [says(all_of=["fire_hydrant_1", "76.3"]), only()],
         [find(category=HYDRANT_KIND, nearest_to=EGO)]),
    case("search", "direct", "lamp_post_by_bus_stop", BRIT,
         "Which lamp post is nearest the bus stop?",
         [says(all_of=["street_light_4"]), only()],
         [find(category=LAMP, nearest_to=BUS_STOP)]),
    case("search", "direct", "ego_lane_id", ROBOTICIST,
         "which lane id is ego localised in right now? just need the string for my launch file",
         [says(all_of=["main_eastbound"]), only()],
         [lanes(near=EGO)]),
    case("search", "direct", "lamps_along_main_street", COUNCIL,
         "How many street lights are there along Main Street in total?",
         [says(any_of=["12", "twelve"]), only()],
         [find(category=LAMP, lane="Main Street")]),
    case("search", "direct", "weather_and_clock", RIDESHARE,
         "whats the weather doing and what time is it in the sim rn",
         [says(all_of=["clear"], any_of=["12:00", "noon", "midday"]), only()],
         [environment()]),
    case("search", "direct", "library_to_union", LAWYER,
         "Please state, in metres, the straight-line distance between the Library entrance and the "
         "Student Union entrance.",
         [says(any_of=["90.9", "91"]), only()],
         [measure(LIBRARY, UNION)]),
    case("search", "direct", "signals_and_stop_sign", SCREEN,
         "Hi, sorry, quick question, I can't see the screen so I'm relying on you for this one. Which "
         "traffic lights are there in the scene, their names I mean, the signals. And is there a stop sign "
         "as well? So, the traffic lights, and any stop sign. Please don't change anything.",
         [says(all_of=["traffic_light_1", "traffic_light_2", "stop_sign_1"]), only()],
         [find(category=SIGNAL), find(category=STOP_KIND)]),
    case("search", "direct", "suv_lot_after_paint", SPANGLISH,
         "Gracias. Y ahora, ¿dónde está el SUV? Which parking lot is it in?",
         [says(any_of=["lot B", "parking lot B"]), only()],
         [properties(asset=SUV)],
         setup=[turn("Pinta el SUV de amarillo, por favor.", paint([SUV], colour="yellow"), planned=True)]),
    impossible("search", "direct", "petrol_station_distance", ADJUSTER,
               "State the distance between the ego vehicle and the petrol station on Main Street.",
               [measure("petrol station", EGO)]),
    # indirect
    case("search", "indirect", "tree_id_and_ego_gap", ADJUSTER,
         "Two things for the report. There's a tree behind the bus stop that may have blocked the view — I "
         "need its ID in the scene. And how far was the ego from the bus stop?",
         [says(all_of=["tree_1", "30.2"]), only()],
         [find(category=TREE, nearest_to=BUS_STOP), measure(BUS_STOP, EGO)]),
    case("search", "indirect", "bin_near_library", BRIT,
         "I'm after a bin near the Library entrance — is there one about, and how far off is it?",
         [says(all_of=["trash_bin_1"], any_of=["12.1", "12"]), only()],
         [find(category=BIN_KIND, nearest_to=LIBRARY)]),
    case("search", "indirect", "hydrant_for_jtekt_residents", COUNCIL,
         "Residents by the JTEKT building insist there's no fire hydrant anywhere near them. I'd like to be "
         "able to tell them where the closest one actually is.",
         [says(all_of=["fire_hydrant_1"]), only()],
         [find(category=HYDRANT_KIND, nearest_to=JTEKT)]),
    case("search", "indirect", "gate_for_union_dropoff", RIDESHARE,
         "pax wants dropping at the union building. which gate do i come in by to be closest?",
         [says(all_of=["east gate"]), only()],
         [landmarks(query="gate", nearest_to=UNION)]),
    case("search", "indirect", "walk_stop_to_zebra", TEACHER,
         "We'll walk the little ones from the bus stop to the zebra crossing. I'd like to know roughly how far "
         "that is before I promise them it isn't far!",
         [says(any_of=["19.3", "19"]), only()],
         [measure(BUS_STOP, WEST_CROSSWALK)]),
    case("search", "indirect", "eastbound_limit_kmh", LAWYER,
         "In order to establish the limit applicable to my client's lane of travel, I require the posted speed "
         "limit on the eastbound lane of Main Street, expressed in kilometres per hour.",
         [says(any_of=["29 km/h", "29", "28.8"]), only()],
         [lanes(road="Main Street")]),
    case("search", "indirect", "suv_pose_for_tf", ROBOTICIST,
         "need suv_1's pose in the map frame (x, y, yaw) so i can hardcode a static tf",
         [says(all_of=["23", "-42", "90"]), only()],
         [properties(asset=SUV)]),
    case("search", "indirect", "somewhere_to_sit", SPANGLISH,
         "Mi abuela is waiting for el bus and her knees are bad — is there anywhere for her to sit at the stop?",
         [says(any_of=["bench", "bench_1"]), only()],
         [find(category=BENCH_KIND, near=BUS_STOP, within=10)]),
    case("search", "indirect", "that_bin_to_bus_stop", LAWYER,
         "And for the avoidance of doubt, how far is that receptacle from the bus stop?",
         [says(any_of=["3.5"]), only()],
         [measure(BIN, BUS_STOP)],
         setup=[turn("Identify the refuse receptacle nearest to the Library entrance.",
                     find(category=BIN_KIND, nearest_to=LIBRARY))]),
    impossible("search", "indirect", "duck_pond_distance", TEACHER,
               "At the end of the walk I've promised the children a look at the duck pond. How far is it from "
               "the Library?",
               [measure("duck pond", LIBRARY)]),
    # vague
    case("search", "vague", "by_the_fountain", TEACHER,
         "what's over by the fountain?",
         [says(any_of=["tree", "trees", "tree_2", "tree_3"]), only()],
         [find(near=FOUNTAIN, within=20)]),
    case("search", "vague", "the_other_light", RIDESHARE,
         "and the other one, where's that?",
         [says(any_of=["traffic_light_2"]), only()],
         [find(category=SIGNAL)],
         setup=[turn("which traffic light is closest to me", find(category=SIGNAL, nearest_to=EGO))]),
    case("search", "vague", "what_is_it_like_out", BRIT,
         "what's it like out there?",
         [says(any_of=["clear", "sunny", "dry", "fine"]), only()],
         [environment()]),
    case("search", "vague", "lamp_by_lot_a", ROBOTICIST,
         "lamp near lot A?",
         [says(any_of=["street_light_1"]), only()],
         [find(category=LAMP, nearest_to=LOT_A)]),
    case("search", "vague", "whats_around_me", SCREEN,
         "Um, so, what's around me? Around the ego car, I mean. Just roughly what's nearby, nothing fancy, "
         "just what's close to me.",
         [says(any_of=["street_light_2", "street_light_3", "lot A", "Library"]), only()],
         [find(nearest_to=EGO, within=15)]),
    case("search", "vague", "how_far_the_gate", COUNCIL,
         "how far's the gate from the test car?",
         [says(any_of=["40", "40.0", "160", "160.0"]), only()],
         [measure(MAIN_GATE, EGO)]),
    case("search", "vague", "anything_in_the_road", ADJUSTER,
         "Anything in the road?",
         [says(any_of=["ego", "nothing", "clear"]), only()],
         [find(on_lane=True)]),
    case("search", "vague", "is_it_dark_yet", SPANGLISH,
         "¿ya es de noche? is it dark yet or what",
         [says(any_of=["12:00", "day", "daytime", "noon", "midday"]), only()],
         [environment()]),
    case("search", "vague", "what_signage", LAWYER,
         "What signage is present?",
         [says(any_of=["stop_sign_1", "stop sign"]), only()],
         [find(category="signs")]),
    # erroneous
    case("search", "erroneous", "wher_hydrant", RIDESHARE,
         "wher is teh fire hydrnat",
         [says(any_of=["fire_hydrant_1", "16"]), only()],
         [find(category=HYDRANT_KIND)]),
    case("search", "erroneous", "how_many_benchs", TEACHER,
         "hw many benchs r there?",
         [says(any_of=["1", "one"]), only()],
         [find(category=BENCH_KIND)]),
    case("search", "erroneous", "robot_pose_typo", ROBOTICIST,
         "whats teh robots pose in map frmae, x y only",
         [says(all_of=["-85", "29"]), only()],
         [properties(asset="ackermann_robot_1")],
         setup=[turn("spawn an ackermann robot in lot A", add(ROBOT, where=loc("at", LOT_A)))]),
    case("search", "erroneous", "libary_to_bustop", BRIT,
         "distnace from the libary to the bustop?",
         [says(any_of=["14.5"]), only()],
         [measure(LIBRARY, BUS_STOP)]),
    case("search", "erroneous", "lot_b_entrance_where", LAWYER,
         "Kindly advise the the location of of the parking lot B entrance.",
         [says(any_of=["47", "-3.5", "Main Street"]), only()],
         [landmarks(query=LOT_B_ENTRANCE)]),
    case("search", "erroneous", "cuantos_coches", SPANGLISH,
         "cuantos coches hay en el lot B? how many carss",
         [says(any_of=["3", "three"]), only()],
         [find(category="cars")]),
    case("search", "erroneous", "car_two_heading", COUNCIL,
         "whats the heading of passanger car 2, is it facing north like the othres?",
         [says(any_of=["90", "north"]), only()],
         [properties(asset=CAR_2)]),
    case("search", "erroneous", "stop_sigh", SCREEN,
         "Is there a stop sigh near the crosswalk? Sorry, stop sign, my screen reader reads it out funny. The "
         "west crosswalk. Is there a stop sign near it?",
         [says(all_of=["stop_sign_1"]), only()],
         [find(category=STOP_KIND, nearest_to=WEST_CROSSWALK)]),
    impossible("search", "erroneous", "gas_staton", RIDESHARE,
               "wheres the gas staton, need to fill up before my next ride",
               [landmarks(query="gas station")]),
]


# --- Addition ----------------------------------------------------------------------------------
ADDITION_CASES: list[Json] = [
    # direct
    case("addition", "direct", "bin_on_library_pavement", BRIT,
         "Put a bin on the pavement outside the Library entrance.",
         [delta(BIN_KIND, 1, 1), near(LIBRARY, 12, BIN_KIND), on(["sidewalk"], BIN_KIND), only(BIN_KIND)],
         [add(BIN_KIND, where=loc("on_sidewalk", LIBRARY))]),
    case("addition", "direct", "white_sedan_eastbound", RIDESHARE,
         "add a white sedan driving east on main street at 10 m/s",
         [delta(CAR, 1, 1), does("drive_lane", CAR, lane=EASTBOUND, speed_min=9, speed_max=11),
          looks("white", CAR), only(CAR)],
         [add(CAR, behaviour=drive(10, EASTBOUND), colour="white")]),
    case("addition", "direct", "two_waiting_and_a_bench", TEACHER,
         "Add two pedestrians waiting at the bus stop, and a bench for them to sit on.",
         [delta(PERSON, 2, 2), delta(BENCH_KIND, 1, 1), near(BUS_STOP, 6, PERSON, min_count=2),
          near(BUS_STOP, 8, BENCH_KIND), only(PERSON, BENCH_KIND)],
         [add(PERSON, 2, loc("at", BUS_STOP)), add(BENCH_KIND, where=loc("next_to", BUS_STOP))]),
    case("addition", "direct", "crossing_sign_north", COUNCIL,
         "Install a pedestrian crossing sign beside the north crosswalk.",
         [delta(PED_SIGN, 1, 1), near(NORTH_CROSSWALK, 8, PED_SIGN), only(PED_SIGN)],
         [add(PED_SIGN, where=loc("at", NORTH_CROSSWALK))]),
    case("addition", "direct", "bicycle_by_hydrant", LAWYER,
         "Please add one (1) bicycle, parked, on the north sidewalk of Main Street, in the immediate vicinity "
         "of the fire hydrant.",
         [delta(BIKE, 1, 1), near(HYDRANT, 4, BIKE), on(["sidewalk"], BIKE), does("parked", BIKE), only(BIKE)],
         [add(BIKE, where=loc("on_sidewalk", HYDRANT))]),
    case("addition", "direct", "robot_at_map_point", ROBOTICIST,
         "spawn an ackermann robot at x=1.75, y=24 (map frame) in campus_northbound, drive_lane at 2 m/s",
         [delta(ROBOT, 1, 1), in_lane(NORTHBOUND, ROBOT), near(None, 3, ROBOT, point=(1.75, 24)),
          does("drive_lane", ROBOT, lane=NORTHBOUND, speed_min=1.5, speed_max=2.5), only(ROBOT)],
         [add(ROBOT, where=xy(1.75, 24), behaviour=drive(2, NORTHBOUND))]),
    case("addition", "direct", "camion_lot_b", SPANGLISH,
         "Añade un camión — a truck — parked in lot B, por favor.",
         [delta(TRUCK, 1, 1), near(LOT_B, 0.5, TRUCK), does("parked", TRUCK), only(TRUCK)],
         [add(TRUCK, where=loc("at", LOT_B))]),
    case("addition", "direct", "tree_by_fountain", SCREEN,
         "Hello again. I would like to add a tree. A single tree, next to the fountain please, the fountain up "
         "in the north east. So just the one tree, next to the fountain. Thank you so much.",
         [delta(TREE, 1, 1), near(FOUNTAIN, 8, TREE), only(TREE)],
         [add(TREE, where=loc("next_to", FOUNTAIN))]),
    impossible("addition", "direct", "fifteen_lorries", BRIT,
               "Add fifteen lorries along Main Street.",
               [add(TRUCK, 15, loc("in_lane", WESTBOUND))]),
    # indirect
    case("addition", "indirect", "van_and_cyclist_jtekt", ADJUSTER,
         "At the time of the incident a delivery van was double-parked in front of the JTEKT building entrance, "
         "and a cyclist was riding past it westbound on Main Street. Recreate both.",
         [delta(TRUCK, 1, 1), near(JTEKT, 12, TRUCK), delta(BIKE, 1, 1),
          does("drive_lane", BIKE, lane=WESTBOUND), only(TRUCK, BIKE)],
         [add(TRUCK, where=loc("in_front_of", JTEKT)),
          add(BIKE, where=loc("in_lane", JTEKT, lane=WESTBOUND), behaviour=drive(lane=WESTBOUND))]),
    case("addition", "indirect", "crossing_guard", TEACHER,
         "I want the children to meet a crossing guard — could someone be standing at the zebra crossing, "
         "ready to help them over?",
         [delta(PERSON, 1, 1), near(WEST_CROSSWALK, 6, PERSON), only(PERSON)],
         [add(PERSON, where=loc("at", WEST_CROSSWALK))]),
    case("addition", "indirect", "union_seating", COUNCIL,
         "We keep getting complaints that there's nowhere to sit while you wait for the shuttle outside the "
         "Student Union. Can we sort that out?",
         [delta(BENCH_KIND, 1, 3), near(UNION, 10, BENCH_KIND), only(BENCH_KIND)],
         [add(BENCH_KIND, where=loc("at", UNION))]),
    case("addition", "indirect", "slow_bus_to_overtake", RIDESHARE,
         "wanna practise overtaking. give me something big and slow to get stuck behind, like a bus in my "
         "lane up ahead doing 3 m/s",
         [delta(BUS, 1, 1), in_lane(EASTBOUND, BUS), does("drive_lane", BUS, speed_max=4),
          relative("in_front_of", EGO, BUS, max_distance=80, tolerance_deg=20), only(BUS)],
         [add(BUS, where=ahead_of(EGO, 30), behaviour=drive(3, EASTBOUND))]),
    case("addition", "indirect", "cyclist_on_footway", LAWYER,
         "My client maintains that a cyclist was present on the southern footway adjacent to the bus stop. "
         "The scene should reflect that assertion.",
         [delta(BIKE, 1, 1), near(BUS_STOP, 8, BIKE), on(["sidewalk"], BIKE), only(BIKE)],
         [add(BIKE, where=loc("on_sidewalk", BUS_STOP))]),
    case("addition", "indirect", "knee_high_obstacle", ROBOTICIST,
         "need a static obstacle for a planner test: something knee-high sitting in campus_southbound, ~20 m "
         "south of the junction box",
         [delta(OBSTACLES, 1, 3), in_lane(SOUTHBOUND, OBSTACLES), near(None, 8, OBSTACLES, point=(-1.75, -29)),
          only(*OBSTACLES)],
         [add(CONE, where=xy(-1.75, -29))]),
    case("addition", "indirect", "hija_learning_to_ride", SPANGLISH,
         "Mi hija is learning to ride — quiero a kid on a bike going round in circles in parking lot A.",
         [delta(BIKE, 1, 1), does("circle", BIKE), near(LOT_A, 1, BIKE), only(BIKE, PERSON)],
         [add(BIKE, where=loc("at", LOT_A), behaviour={"kind": "circle"})]),
    case("addition", "indirect", "car_down_campus_drive", SCREEN,
         "Okay so what I'm after, and sorry, this is a long one, is a bit more going on around the main "
         "intersection. Traffic, basically. Could there be a car coming down Campus Drive from the north, "
         "heading south towards the junction? Just a normal car. One car, going south on Campus Drive.",
         [delta(CARS, 1, 1), does("drive_lane", CARS, lane=SOUTHBOUND), near(None, 42, CARS, point=(-1.75, 50)),
          only(*CARS)],
         [add(CAR, behaviour=drive(lane=SOUTHBOUND))]),
    case("addition", "indirect", "a_friend_for_her", TEACHER,
         "She'll need a friend to walk with — could there be another one right beside her?",
         [delta(PERSON, 1, 1), near("pedestrian_1", 3, PERSON), only(PERSON)],
         [add(PERSON, where=loc("next_to", "pedestrian_1"))],
         setup=[turn("Add a pedestrian at the bus stop.", add(PERSON, where=loc("at", BUS_STOP)))]),
    impossible("addition", "indirect", "speed_humps", COUNCIL,
               "Residents on Campus Drive are begging for traffic calming. Install three speed humps on Campus "
               "Drive, north of the junction.",
               [add("speed hump", 3, loc("in_lane", NORTHBOUND))]),
    # vague
    case("addition", "vague", "more_traffic", RIDESHARE,
         "more traffic pls, it's dead out here. couple cars and a bus or something",
         [delta(CARS, 2, 3), delta([BUS, TRUCK, MOTORBIKE], 1, 2), does("drive_lane", MOTOR_TRAFFIC, min_count=3),
          only(*MOTOR_TRAFFIC)],
         [add(CAR, 2, behaviour=drive(lane=WESTBOUND)), add(BUS, behaviour=drive(lane=EASTBOUND))]),
    case("addition", "vague", "people_round_the_library", TEACHER,
         "some people around the library?",
         [delta(PERSON, 2, None), near(LIBRARY, 15, PERSON, min_count=2), only(PERSON)],
         [add(PERSON, 3, loc("at", LIBRARY))]),
    case("addition", "vague", "tree_by_the_car_park", BRIT,
         "bit bare by the car park, bung a tree in",
         [delta(TREE, 1, 1), only(TREE)],
         [add(TREE, where=loc("next_to", LOT_B))],
         alternatives=[[near(LOT_B, 8, TREE)], [near(LOT_A, 8, TREE)]]),
    case("addition", "vague", "bus_stop_too_dark", COUNCIL,
         "Residents say the bus stop is far too dark after hours. Fix it with something permanent.",
         [delta(LAMP, 1, None), near(BUS_STOP, 8, LAMP), only(LAMP)],
         [add(LAMP, where=loc("at", BUS_STOP))]),
    case("addition", "vague", "agents_crossing", ROBOTICIST,
         "add a couple dynamic agents crossing at the west crosswalk",
         [delta(VULNERABLE, 2, 2), does("cross_road", VULNERABLE, min_count=2),
          near(WEST_CROSSWALK, 8, VULNERABLE, min_count=2), only(*VULNERABLE)],
         [add(PERSON, 2, loc("at", WEST_CROSSWALK), behaviour={"kind": "cross_road"})]),
    case("addition", "vague", "obras_en_la_calle", SPANGLISH,
         "ponme algo de obras en la calle principal, whatever, lo que sea",
         [delta(OBSTACLES, 1, None), only(*OBSTACLES)],
         [add(CONE, 3, ahead_of(EGO, 25))],
         alternatives=[[near(EASTBOUND, 6, OBSTACLES, every=True)], [near(WESTBOUND, 6, OBSTACLES, every=True)]]),
    case("addition", "vague", "something_for_walkers", SCREEN,
         "I feel like the scene is a little bit empty. Maybe just add something, something people would use "
         "when they're out walking, somewhere to sit or to throw rubbish, I don't mind which, around the bus "
         "stop or thereabouts. Whatever you think.",
         [delta([BENCH_KIND, BIN_KIND], 1, None), near(BUS_STOP, 12, [BENCH_KIND, BIN_KIND]),
          only(BENCH_KIND, BIN_KIND)],
         [add(BENCH_KIND, where=loc("next_to", BUS_STOP))]),
    case("addition", "vague", "additional_vehicles_lot_a", LAWYER,
         "Insofar as is practicable, additional vehicles should be present in parking lot A.",
         [delta(VEHICLES, 2, None), near(LOT_A, 1, VEHICLES, min_count=2), only(*VEHICLES)],
         [add(CAR, 3, loc("at", LOT_A))]),
    case("addition", "vague", "a_witness", ADJUSTER,
         "Put a witness somewhere with a view of the junction.",
         [delta(PERSON, 1, 1), near(JUNCTION, 15, PERSON), only(PERSON)],
         [add(PERSON, where=loc("on_sidewalk", JUNCTION))]),
    case("addition", "vague", "same_again_lot_a", RIDESHARE,
         "same again at the lot A entrance",
         [delta(CARS, 1, 1), near(LOT_A_ENTRANCE, 8, CARS), only(*CARS)],
         [add(CAR, where=loc("at", LOT_A_ENTRANCE))],
         setup=[turn("drop a car at the lot B entrance like it's waiting on a fare",
                     add(CAR, where=loc("at", LOT_B_ENTRANCE)), planned=True)]),
    # erroneous
    case("addition", "erroneous", "street_lihgt_crosswalk", ADJUSTER,
         "Add a street lihgt next to the west crosswalk; there was one there on the nigth of the incident.",
         [delta(LAMP, 1, 1), near(WEST_CROSSWALK, 8, LAMP), only(LAMP)],
         [add(LAMP, where=loc("at", WEST_CROSSWALK))]),
    case("addition", "erroneous", "motorbik_westbond", RIDESHARE,
         "add a motorbik driving in the westbond lane",
         [delta(MOTORBIKE, 1, 1), does("drive_lane", MOTORBIKE, lane=WESTBOUND), only(MOTORBIKE)],
         [add(MOTORBIKE, behaviour=drive(lane=WESTBOUND))]),
    case("addition", "erroneous", "kids_libary_enterance", TEACHER,
         "pls add 3 kids holding hands near the libary enterance",
         [delta(PERSON, 3, 3), near(LIBRARY, 8, PERSON, min_count=3), only(PERSON)],
         [add(PERSON, 3, loc("at", LIBRARY))]),
    case("addition", "erroneous", "benc_engeneering", COUNCIL,
         "instal a new benc outside engeneering hall",
         [delta(BENCH_KIND, 1, 1), near(ENGINEERING, 8, BENCH_KIND), only(BENCH_KIND)],
         [add(BENCH_KIND, where=loc("at", ENGINEERING))]),
    case("addition", "erroneous", "stop_sign_norht", LAWYER,
         "Add a stop sign at the the norht crosswalk, on the approahc side for southbound traffic.",
         [delta(STOP_KIND, 1, 1), near(NORTH_CROSSWALK, 8, STOP_KIND), only(STOP_KIND)],
         [add(STOP_KIND, where=loc("at", NORTH_CROSSWALK))]),
    case("addition", "erroneous", "spwan_cones_ahead", ROBOTICIST,
         "spwan 2 cones 10m infront of ego in its lane",
         [delta(CONE, 2, 2), in_lane(EASTBOUND, CONE),
          relative("in_front_of", EGO, CONE, max_distance=20, tolerance_deg=30, every=True), only(CONE)],
         [add(CONE, 2, ahead_of(EGO, 10))]),
    case("addition", "erroneous", "otra_bici", SPANGLISH,
         "otra mas, iguall, porfa",
         [delta(BIKE, 1, 1), near(LOT_A, 1, BIKE), only(BIKE)],
         [add(BIKE, where=loc("at", LOT_A))],
         setup=[turn("añade una bici en el parking lot A", add(BIKE, where=loc("at", LOT_A)))]),
    case("addition", "erroneous", "hydrant_student_onion", SCREEN,
         "Could you add a fire hydrant near the Student Onion. Sorry, my dictation did that, the Student Union. "
         "A fire hydrant near the Student Union entrance, please.",
         [delta(HYDRANT_KIND, 1, 1), near(UNION, 8, HYDRANT_KIND), only(HYDRANT_KIND)],
         [add(HYDRANT_KIND, where=loc("at", UNION))]),
    impossible("addition", "erroneous", "postbox_libary", BRIT,
               "pop a postbox outside the libary would you",
               [add("postbox", where=loc("at", LIBRARY))]),
]


# --- Removal -----------------------------------------------------------------------------------
REMOVAL_CASES: list[Json] = [
    # direct
    case("removal", "direct", "bin_by_bus_stop", BRIT,
         "Remove the bin by the bus stop.",
         [gone(BIN), only(assets=[BIN])],
         [remove(BIN)]),
    case("removal", "direct", "stop_sign_west_crosswalk", COUNCIL,
         "Remove the stop sign at the west crosswalk.",
         [gone(STOP_SIGN), only(assets=[STOP_SIGN])],
         [remove(STOP_SIGN)]),
    case("removal", "direct", "tree_behind_bus_stop", TEACHER,
         "Please take away the tree behind the bus stop.",
         [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
         [remove(TREE_LIBRARY)]),
    case("removal", "direct", "suv_in_lot_b", RIDESHARE,
         "delete the suv in lot b",
         [gone(SUV), only(assets=[SUV])],
         [remove(SUV)]),
    case("removal", "direct", "rm_two_lamps_add_bollard", ROBOTICIST,
         "rm street_light_1 and street_light_3, then spawn a bollard where street_light_1 was",
         [gone("street_light_1", "street_light_3"), delta(BOLLARD, 1, 1),
          near(None, 1.5, BOLLARD, point=(-80, 5.8)), only(BOLLARD, assets=["street_light_1", "street_light_3"])],
         [remove("street_light_1", "street_light_3"), add(BOLLARD, where=xy(-80, 5.8))]),
    case("removal", "direct", "quita_hydrant", SPANGLISH,
         "Quita el fire hydrant, por favor.",
         [gone(HYDRANT), only(assets=[HYDRANT])],
         [remove(HYDRANT)]),
    case("removal", "direct", "the_one_bench", SCREEN,
         "Please remove the bench. The bench at the bus stop, there's only one I think. Remove that bench, "
         "please.",
         [gone(BENCH), only(assets=[BENCH])],
         [remove(BENCH)]),
    case("removal", "direct", "two_cars_out_suv_red", ADJUSTER,
         "Remove both passenger cars from lot B, and mark the SUV in red as vehicle 2.",
         [gone(CAR_1, CAR_2), kept(SUV), looks("red", asset=SUV), only(assets=[CAR_1, CAR_2, SUV])],
         [remove(CAR_1, CAR_2), paint([SUV], colour="red")]),
    impossible("removal", "direct", "ego_in_its_entirety", LAWYER,
               "Remove the ego vehicle from the scene in its entirety.",
               [remove(EGO)]),
    # indirect
    case("removal", "indirect", "signals_went_in_later", ADJUSTER,
         "The photos from the day show no traffic signals at that crossroads; they were only put in afterwards. "
         "Take them out of the reconstruction.",
         [gone(LIGHT_SW, LIGHT_NE), only(assets=[LIGHT_SW, LIGHT_NE])],
         [remove(category=SIGNAL)]),
    case("removal", "indirect", "that_lamp_post", BRIT,
         "Right, that one keeps getting clipped by lorries turning in, so it'll have to go.",
         [gone(LAMP_LOT_A), only(assets=[LAMP_LOT_A])],
         [remove(LAMP_LOT_A)],
         setup=[turn("Which lamp post is nearest the car park A entrance?",
                     find(category=LAMP, nearest_to=LOT_A_ENTRANCE))]),
    case("removal", "indirect", "leafy_tree_lot_a", COUNCIL,
         "We've had a stream of complaints about the tree just north of lot A dropping leaves all over "
         "residents' cars. They want it gone.",
         [gone(TREE_LOT_A), only(assets=[TREE_LOT_A])],
         [remove(TREE_LOT_A)]),
    case("removal", "indirect", "pickup_spot_clear", RIDESHARE,
         "those parked cars in lot b are sitting right where i do pickups. clear out all but the suv, that "
         "one's my buddy's",
         [gone(CAR_1, CAR_2), kept(SUV), only(assets=[CAR_1, CAR_2])],
         [remove(CAR_1, CAR_2)]),
    case("removal", "indirect", "bench_out_bin_in_its_place", TEACHER,
         "The bench at the bus stop is right in the children's way. Could it go, and the bin be moved to "
         "where the bench was, so they have a clear path past?",
         [gone(BENCH), near(None, 1.5, asset=BIN, point=(-26, -6.9)), only(assets=[BENCH, BIN])],
         [remove(BENCH), place(BIN, xy(-26, -6.9))]),
    case("removal", "indirect", "hydrant_not_present", LAWYER,
         "It is my client's position that no fire hydrant was present at the material time; the scene should "
         "be amended accordingly.",
         [gone(HYDRANT), only(assets=[HYDRANT])],
         [remove(HYDRANT)]),
    case("removal", "indirect", "lidar_hates_foliage", ROBOTICIST,
         "my lidar sim chokes on foliage, strip all the vegetation out of the map",
         [count(TREE, 0, 0), gone(*TREES), only(TREE)],
         [remove(category=TREE)]),
    case("removal", "indirect", "bin_in_my_way", SCREEN,
         "So when I explore the scene I keep bumping into the bin by the bus stop, in my head I mean, it's "
         "always in the way of my route along that sidewalk. I don't need it there. I don't need it at all, "
         "actually, the bin.",
         [gone(BIN), only(assets=[BIN])],
         [remove(BIN)]),
    impossible("removal", "indirect", "fountain_antisocial", COUNCIL,
               "The fountain has become a magnet for antisocial behaviour and residents want it gone. Please "
               "remove it.",
               [remove("fountain")]),
    # vague
    case("removal", "vague", "lose_a_couple_lamps", RIDESHARE,
         "too many lamps on the south side, lose a couple",
         [delta(LAMP, -3, -2), only(assets=list(SOUTH_LAMPS))],
         [remove("street_light_2", "street_light_4")]),
    case("removal", "vague", "pavement_clutter", BRIT,
         "clear the clutter off the pavement by the bus stop",
         [delta([BIN_KIND, BENCH_KIND], None, -1), only(assets=[BIN, BENCH, LAMP_BUS_STOP])],
         [remove(BIN, BENCH)]),
    case("removal", "vague", "fewer_trees", TEACHER,
         "fewer trees please",
         [delta(TREE, -3, -1), only(TREE)],
         [remove(TREE_EAST)]),
    case("removal", "vague", "residents_hate_that_one", COUNCIL,
         "Actually, residents hate that one. Just take it out.",
         [gone(LIGHT_NE), kept(LIGHT_SW), only(assets=[LIGHT_NE])],
         [remove(LIGHT_NE)],
         setup=[turn("Paint the traffic light on the north-east corner yellow so residents can spot it in the "
                     "model.", paint([LIGHT_NE], colour="yellow"), planned=True)]),
    case("removal", "vague", "kill_what_i_spawned", ROBOTICIST,
         "ok kill the stuff i just spawned",
         [count(CONE, 0, 0), delta(CONE, -3, -3), only(CONE)],
         [remove(category=CONE)],
         setup=[turn("spawn 3 cones 20 m ahead of ego", add(CONE, 3, ahead_of(EGO, 20)))]),
    case("removal", "vague", "los_coches_todos", SPANGLISH,
         "quita los coches, todos",
         [delta(CARS, -3, -3), gone(*PARKED), only(*CARS)],
         [remove(*PARKED)]),
    case("removal", "vague", "item_referred_to", LAWYER,
         "Remove the item to which I have just referred.",
         [gone(BIN), only(assets=[BIN])],
         [remove(BIN)],
         setup=[turn("Where precisely is the refuse receptacle nearest to the Library entrance?",
                     find(category=BIN_KIND, nearest_to=LIBRARY))]),
    case("removal", "vague", "cars_not_involved", ADJUSTER,
         "Now get rid of the cars that weren't involved.",
         [gone(CAR_1, CAR_2), kept(SUV), only(assets=[CAR_1, CAR_2])],
         [remove(CAR_1, CAR_2)],
         setup=[turn("The SUV in lot B is vehicle 2 in this claim. Paint it red so it stands out.",
                     paint([SUV], colour="red"), planned=True)]),
    impossible("removal", "vague", "bus_blocking_me", RIDESHARE,
               "get rid of the bus that's blocking me",
               [remove(category=BUS)]),
    # erroneous
    case("removal", "erroneous", "lamp_post_nearst_stop", BRIT,
         "remvoe the lamp post nearst the bus stop",
         [gone(LAMP_BUS_STOP), only(assets=[LAMP_BUS_STOP])],
         [remove(LAMP_BUS_STOP)]),
    case("removal", "erroneous", "delte_suv", RIDESHARE,
         "delte the suv",
         [gone(SUV), only(assets=[SUV])],
         [remove(SUV)]),
    case("removal", "erroneous", "stop_sing", TEACHER,
         "can u take away the stop sing near the crossing",
         [gone(STOP_SIGN), only(assets=[STOP_SIGN])],
         [remove(STOP_SIGN)]),
    case("removal", "erroneous", "all_treees_but_fountian", COUNCIL,
         "remove all the treees but the one by the fountian",
         [gone(TREE_LIBRARY, TREE_EAST, TREE_LOT_A), kept(TREE_FOUNTAIN), only(TREE)],
         [remove(TREE_LIBRARY, TREE_EAST, TREE_LOT_A)]),
    case("removal", "erroneous", "south_west_signal", LAWYER,
         "Remove the the traffic light on the south-west corner of the intersecton.",
         [gone(LIGHT_SW), kept(LIGHT_NE), only(assets=[LIGHT_SW])],
         [remove(LIGHT_SW)]),
    case("removal", "erroneous", "delet_all_cones", ROBOTICIST,
         "delet all trafic cones",
         [count(CONE, 0, 0), delta(CONE, None, -1), only(CONE)],
         [remove(category=CONE)],
         setup=[turn("drop a 3x3 grid of cones in lot b", arrange(CONE, "grid", loc("at", LOT_B), count=9, columns=3),
                     planned=True)]),
    case("removal", "erroneous", "quitar_la_bench", SPANGLISH,
         "quitar la bench de el bus stop pls",
         [gone(BENCH), only(assets=[BENCH])],
         [remove(BENCH)]),
    case("removal", "erroneous", "fire_hide_rant", SCREEN,
         "Can you take away the fire hide rant. Sorry, the fire hydrant, the voice thing typed it wrong. The "
         "fire hydrant, remove it please.",
         [gone(HYDRANT), only(assets=[HYDRANT])],
         [remove(HYDRANT)]),
    case("removal", "erroneous", "vehicle_three", ADJUSTER,
         "Remove vehicle 3 (passanger car 2, the one at the east end of the row in lot B).",
         [gone(CAR_2), kept(CAR_1, SUV), only(assets=[CAR_2])],
         [remove(CAR_2)]),
]


# --- Positioning: an existing asset put somewhere named ------------------------------------------
POSITIONING_CASES: list[Json] = [
    # direct
    case("positioning", "direct", "suv_ahead_of_ego", ADJUSTER,
         "Position the SUV in the eastbound lane of Main Street, fifteen metres ahead of the ego.",
         [in_lane(EASTBOUND, asset=SUV), relative("in_front_of", EGO, asset=SUV, max_distance=25, tolerance_deg=20),
          moved(SUV, 5), only(assets=[SUV])],
         [place(SUV, ahead_of(EGO, 15))]),
    case("positioning", "direct", "bin_by_lot_a_lamp", BRIT,
         "Put the bin next to the lamp post at the car park A entrance.",
         [near(LAMP_LOT_A, 2.5, asset=BIN), moved(BIN, 5), only(assets=[BIN])],
         [place(BIN, loc("next_to", LAMP_LOT_A))]),
    case("positioning", "direct", "bench_and_bin_at_union", COUNCIL,
         "Put the bench at the Student Union entrance, and the bin right beside it.",
         [near(UNION, 6, asset=BENCH), near(BENCH, 3, asset=BIN), moved(BIN, 5), only(assets=[BENCH, BIN])],
         [place(BENCH, loc("at", UNION)), place(BIN, loc("next_to", BENCH))]),
    case("positioning", "direct", "me_at_lot_b_entrance", RIDESHARE,
         "put my car at the lot B entrance",
         [near(LOT_B_ENTRANCE, 8, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("at", LOT_B_ENTRANCE))]),
    case("positioning", "direct", "stop_sign_before_library", TEACHER,
         "Place the stop sign in front of the Library entrance.",
         [near(LIBRARY, 8, asset=STOP_SIGN), only(assets=[STOP_SIGN])],
         [place(STOP_SIGN, loc("in_front_of", LIBRARY))]),
    case("positioning", "direct", "hydrant_beside_bus_stop", LAWYER,
         "Relocate the fire hydrant to the southern sidewalk, immediately adjacent to the bus stop.",
         [near(BUS_STOP, 4, asset=HYDRANT), on(["sidewalk"], asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("next_to", BUS_STOP))]),
    case("positioning", "direct", "hydrant_between_stop_and_sign", SCREEN,
         "Could you put the fire hydrant between the bus stop and the stop sign, please? On that sidewalk, "
         "in between those two. The fire hydrant, between the bus stop and the stop sign.",
         [near(None, 6, asset=HYDRANT, point=(-21.75, -5.5)), on(["sidewalk"], asset=HYDRANT),
          only(assets=[HYDRANT])],
         [place(HYDRANT, xy(-21.75, -5.5))]),
    case("positioning", "direct", "suv_al_lot_a", SPANGLISH,
         "Pon el SUV en el parking lot A, por favor.",
         [near(LOT_A, 0.5, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("at", LOT_A))]),
    case("positioning", "direct", "bench_by_fountain_tree", SCREEN,
         "Could you put the bench next to the tree by the fountain. The bench that's at the bus stop, I mean. "
         "Next to the tree that's near the fountain, please.",
         [near(TREE_FOUNTAIN, 3, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("next_to", TREE_FOUNTAIN))]),
    impossible("positioning", "direct", "suv_at_map_point_in_jtekt", ROBOTICIST,
               "place suv_1 at x=30, y=25 in the map frame",
               [place(SUV, xy(30, 25))]),
    # indirect
    case("positioning", "indirect", "suv_short_of_crosswalk", ADJUSTER,
         "The claimant's SUV came to rest in the eastbound lane just short of the west crosswalk. Set it up "
         "that way for the diagram.",
         [in_lane(EASTBOUND, asset=SUV), near(WEST_CROSSWALK, 10, asset=SUV),
          relative("left_of", WEST_CROSSWALK, asset=SUV, max_distance=12), only(assets=[SUV])],
         [place(SUV, xy(-18, -1.75), yaw_deg=0)]),
    case("positioning", "indirect", "bench_across_from_stop", BRIT,
         "The bench would be far more use on the other pavement, directly across the road from the bus stop.",
         [near(None, 4, asset=BENCH, point=(-30, 5.5)), on(["sidewalk"], asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, xy(-30, 5.5))]),
    case("positioning", "indirect", "hydrant_visible_engineering", COUNCIL,
         "Residents complain the fire hydrant is tucked away where nobody sees it; it would be far more visible "
         "right by the Engineering Hall entrance.",
         [near(ENGINEERING, 6, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", ENGINEERING))]),
    case("positioning", "indirect", "start_shift_east_gate", RIDESHARE,
         "wanna start my shift from the east gate, pointed into campus",
         [near(EAST_GATE, 12, asset=EGO), in_lane(WESTBOUND, asset=EGO, aligned=True), only(assets=[EGO])],
         [place(EGO, xy(95, 1.75), yaw_deg=180)]),
    case("positioning", "indirect", "stop_sign_where_we_cross", TEACHER,
         "On our walk the children will cross at the north crossing, not the west one, so the stop sign ought "
         "to be there with us.",
         [near(NORTH_CROSSWALK, 6, asset=STOP_SIGN), only(assets=[STOP_SIGN])],
         [place(STOP_SIGN, loc("at", NORTH_CROSSWALK))]),
    case("positioning", "indirect", "bin_alleged_at_lot_b", LAWYER,
         "It is alleged that the refuse bin stood at the entrance to parking lot B at the material time; the "
         "model ought to reflect that allegation.",
         [near(LOT_B_ENTRANCE, 5, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", LOT_B_ENTRANCE))]),
    case("positioning", "indirect", "ego_south_end_northbound", ROBOTICIST,
         "for this test the ego has to start at the south end of campus_northbound, yaw 90 (facing north)",
         [in_lane(NORTHBOUND, asset=EGO, aligned=True), near(None, 15, asset=EGO, point=(1.75, -85)),
          only(assets=[EGO])],
         [place(EGO, xy(1.75, -80), yaw_deg=90)]),
    case("positioning", "indirect", "arbol_to_fountain", SPANGLISH,
         "El árbol by the bus stop me tapa la vista de los coches — better ponerlo al lado del fountain.",
         [near(FOUNTAIN, 8, asset=TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
         [place(TREE_LIBRARY, loc("next_to", FOUNTAIN))]),
    case("positioning", "indirect", "suv_somewhere_i_know", SCREEN,
         "Okay. I keep losing track of it though. If it could sit right in front of the JTEKT building entrance, "
         "that's somewhere I know, that would be so helpful. In front of the JTEKT entrance.",
         [near(JTEKT, 10, asset=SUV), relative("in_front_of", JTEKT, asset=SUV, max_distance=15),
          only(assets=[SUV])],
         [place(SUV, loc("in_front_of", JTEKT))],
         setup=[turn("Where is the SUV at the moment?", properties(asset=SUV))]),
    impossible("positioning", "indirect", "bench_on_library_roof", BRIT,
               "The bench would have a cracking view from the roof of the Library — pop it up there, would you?",
               [place(BENCH, xy(-41, -30))]),
    # vague
    case("positioning", "vague", "near_the_cafeteria", RIDESHARE,
         "put me somewhere near the cafeteria",
         [near(UNION, 12, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("at", UNION))]),
    case("positioning", "vague", "bench_back_on_pavement", BRIT,
         "Oh that's daft, the bench has ended up in the road. Shove it back on the pavement.",
         [on(["sidewalk"], asset=BENCH), moved(BENCH, 1), only(assets=[BENCH])],
         [place(BENCH, loc("on_sidewalk", BUS_STOP))],
         setup=[turn("Put the bench in the eastbound lane by the bus stop.", place(BENCH, xy(-26, -1.75)))]),
    case("positioning", "vague", "bin_near_junction", COUNCIL,
         "Move the bin somewhere near the junction, where residents will actually use it.",
         [near(JUNCTION, 8, asset=BIN), moved(BIN, 1), only(assets=[BIN])],
         [place(BIN, loc("on_sidewalk", JUNCTION))]),
    case("positioning", "vague", "bench_facing_fountain", TEACHER,
         "the bench should be somewhere the children can sit and look at the fountain",
         [near(FOUNTAIN, 12, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("in_front_of", FOUNTAIN))]),
    case("positioning", "vague", "suv_proximate_library", LAWYER,
         "The SUV should be positioned at a suitable location proximate to the Library.",
         [near(LIBRARY, 15, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("at", LIBRARY))]),
    case("positioning", "vague", "robot_to_origin", ROBOTICIST,
         "ok now put the robot at the origin",
         [near(None, 3, asset="ackermann_robot_1", point=(0, 0)), only(assets=["ackermann_robot_1"])],
         [place("ackermann_robot_1", xy(0, 0))],
         setup=[turn("spawn an ackermann robot in lot A", add(ROBOT, where=loc("at", LOT_A)))]),
    case("positioning", "vague", "basura_near_library", SPANGLISH,
         "pon la basura más cerca de la library",
         [near(LIBRARY, 8, asset=BIN), moved(BIN, 1), only(assets=[BIN])],
         [place(BIN, loc("at", LIBRARY))]),
    case("positioning", "vague", "tree_over_with_the_others", SCREEN,
         "Hi, so, the tree, the one by the bus stop. I'd like it somewhere else, over by the other trees maybe, "
         "the ones out east by the fountain. Wherever makes sense over there, I don't mind exactly.",
         [near(None, 25, asset=TREE_LIBRARY, point=(77, 35)), only(assets=[TREE_LIBRARY])],
         [place(TREE_LIBRARY, loc("next_to", TREE_EAST))]),
    case("positioning", "vague", "vehicle_two_back", ADJUSTER,
         "Hmm, no. Put vehicle 2 back where it was parked.",
         [near(None, 2, asset=SUV, point=(23, -42)), moved(SUV, 1), only(assets=[SUV])],
         [place(SUV, xy(23, -42), yaw_deg=90)],
         setup=[turn("Vehicle 2 is the SUV. Put it in the eastbound lane just before the west crosswalk.",
                     place(SUV, xy(-18, -1.75), yaw_deg=0), planned=True)]),
    # erroneous
    case("positioning", "erroneous", "bench_same_place", BRIT,
         "nice, now teh bench as well, smae place",
         [near(LAMP_LOT_A, 5, asset=BENCH), moved(BENCH, 5), only(assets=[BENCH])],
         [place(BENCH, loc("next_to", LAMP_LOT_A))],
         setup=[turn("Put the bin next to the lamp post at the car park A entrance.",
                     place(BIN, loc("next_to", LAMP_LOT_A)), planned=True)]),
    case("positioning", "erroneous", "park_me_lot_a", RIDESHARE,
         "park me in lot A plz thx",
         [near(LOT_A, 0.5, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("at", LOT_A))]),
    case("positioning", "erroneous", "bench_fornt_libary", TEACHER,
         "can the bench go in fornt of the libary",
         [near(LIBRARY, 8, asset=BENCH), relative("in_front_of", LIBRARY, asset=BENCH, max_distance=10),
          only(assets=[BENCH])],
         [place(BENCH, loc("in_front_of", LIBRARY))]),
    case("positioning", "erroneous", "hydrnat_jtekt", COUNCIL,
         "relocate the hydrnat to outsdie the JTEKT bulding",
         [near(JTEKT, 8, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", JTEKT))]),
    case("positioning", "erroneous", "suv_roadside_hydrant", LAWYER,
         "Place the SUV adjacent too the fire hydrant, on the the road side of it.",
         [near(HYDRANT, 5, asset=SUV), in_lane(None, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("in_lane", HYDRANT))]),
    case("positioning", "erroneous", "tp_two_cars", ROBOTICIST,
         "tp passenger_car_2 to x=40 y=-20 and passanger_car_1 to x=40 y=-25",
         [near(None, 1, asset=CAR_2, point=(40, -20)), near(None, 1, asset=CAR_1, point=(40, -25)),
          only(assets=[CAR_1, CAR_2])],
         [place(CAR_2, xy(40, -20)), place(CAR_1, xy(40, -25))]),
    case("positioning", "erroneous", "bench_en_frente_union", SPANGLISH,
         "pon el bench en frente del Student Union porfa",
         [near(UNION, 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("in_front_of", UNION))]),
    case("positioning", "erroneous", "passenger_car_one_bus_stop", SCREEN,
         "Put the sedan, the passenger car one I mean, passenger car won, next to the bus stop please. Next to "
         "the bus stop.",
         [near(BUS_STOP, 6, asset=CAR_1), only(assets=[CAR_1])],
         [place(CAR_1, loc("in_lane", BUS_STOP))]),
    impossible("positioning", "erroneous", "hydrant_off_map", SPANGLISH,
               "pon el hydrant en x=0, y=-100 porfa",
               [place(HYDRANT, xy(0, -100))]),
]


# --- Moving: shifts, turns, behaviours and timed manoeuvres ------------------------------------------
MOVING_CASES: list[Json] = [
    # direct
    case("moving", "direct", "ego_ten_forward", ADJUSTER,
         "Move the ego ten metres forward.",
         [moved(EGO, 9, 11, "forward"), only(assets=[EGO])],
         [move(EGO, forward=10)]),
    case("moving", "direct", "bin_six_feet_west", BRIT,
         "Shift the bin about six feet west along the pavement, towards the lamp post.",
         [moved(BIN, 1.4, 2.3, "backward"), only(assets=[BIN])],
         [move(BIN, east=-1.83)]),
    case("moving", "direct", "rotate_bench", COUNCIL,
         "Rotate the bench ninety degrees.",
         [moved(BENCH, 0, 0.5, turn_min=80, turn_max=100), only(assets=[BENCH])],
         [move(BENCH, turn_deg=90)]),
    case("moving", "direct", "ego_twelve_ms", RIDESHARE,
         "make my car do 12 m/s",
         [does("drive_lane", asset=EGO, lane=EASTBOUND, speed_min=11.5, speed_max=12.5), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=12, lane=EASTBOUND)]),
    case("moving", "direct", "she_crosses_at_west", TEACHER,
         "Now have that person walk across the road at the west crosswalk.",
         [does("cross_road", asset="pedestrian_1", crosses_lane=EASTBOUND), only(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "cross_road")],
         setup=[turn("Add a pedestrian at the bus stop.", add(PERSON, where=loc("at", BUS_STOP)), planned=True)]),
    case("moving", "direct", "car1_westbound_five", LAWYER,
         "Cause passenger_car_1 to drive in the westbound lane of Main Street at five metres per second.",
         [does("drive_lane", asset=CAR_1, lane=WESTBOUND, speed_min=4.5, speed_max=5.5), only(assets=[CAR_1])],
         [behave(CAR_1, "drive_lane", lane=WESTBOUND, speed=5)]),
    case("moving", "direct", "ego_plus_x", ROBOTICIST,
         "ego: translate +5 m along x, keep yaw",
         [moved(EGO, 4.5, 5.5, "forward", turn_max=5), only(assets=[EGO])],
         [move(EGO, east=5)]),
    case("moving", "direct", "suv_adelante_y_gira", SPANGLISH,
         "Mueve el SUV tres metros hacia adelante, y después gíralo noventa grados, por favor.",
         [moved(SUV, 2.5, 3.5, "forward", turn_min=80, turn_max=100), only(assets=[SUV])],
         [move(SUV, forward=3), move(SUV, turn_deg=90)]),
    case("moving", "direct", "ego_turn_around", SCREEN,
         "Could you turn the ego car around, so it faces the other way? Turn it all the way around, the ego "
         "car. Facing the opposite way.",
         [moved(EGO, 0, 6, turn_min=170), only(assets=[EGO])],
         [move(EGO, turn_deg=180)]),
    impossible("moving", "direct", "shift_the_library", BRIT,
               "Shift the Library twenty metres north, would you.",
               [move("Library", north=20)]),
    # indirect
    case("moving", "indirect", "suv_pulls_out_ego_speed", ADJUSTER,
         "Witnesses say vehicle 2, the SUV, pulled out of its bay and drove off west along Main Street, while "
         "the ego was doing about 8 m/s. Reproduce both.",
         [does("drive_lane", asset=SUV, lane=WESTBOUND), does("drive_lane", asset=EGO, speed_min=7.5, speed_max=8.5),
          only(assets=[SUV, EGO])],
         [behave(SUV, "drive_lane", lane=WESTBOUND), behave(EGO, "drive_lane", speed=8, lane=EASTBOUND)]),
    case("moving", "indirect", "give_way_at_crossroads", BRIT,
         "The ego ought to give way at the crossroads — have it pull up before it gets there.",
         [stops_before(EGO, -9.0, -1.75), only(assets=[EGO])],
         [manoeuvre(EGO, "stop", at_time=6)]),
    case("moving", "indirect", "thirty_mph", COUNCIL,
         "Residents complain the test car dawdles along and holds the buses up. Have it do 30 mph.",
         [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=13.4, lane=EASTBOUND)],
         alternatives=[[does("drive_lane", asset=EGO, speed_min=12.9, speed_max=13.9)],
                       [event_played(EGO, "change_speed", 3)]]),
    case("moving", "indirect", "heading_back_west", RIDESHARE,
         "passenger's waiting back the other way, swing me round so i'm heading west",
         [moved(EGO, 0, 10, turn_min=150), only(assets=[EGO])],
         [place(EGO, xy(-60, 1.75), yaw_deg=180)]),
    case("moving", "indirect", "bus_round_and_round", TEACHER,
         "The children would love to watch it drive round and round the car park.",
         [does("circle", asset="bus_1"), only(assets=["bus_1"])],
         [behave("bus_1", "circle")],
         setup=[turn("Add a school bus in lot B.", add(BUS, where=loc("at", LOT_B)))]),
    case("moving", "indirect", "suv_rolled_forward", LAWYER,
         "The record should show that the SUV had rolled forward approximately five metres out of its parking "
         "space.",
         [moved(SUV, 4, 6, "forward"), only(assets=[SUV])],
         [move(SUV, forward=5)]),
    case("moving", "indirect", "zero_setpoint", ROBOTICIST,
         "send ego a 0 m/s setpoint, it should be stationary for this run",
         [only(assets=[EGO])],
         [behave(EGO, "parked")],
         alternatives=[[does("parked", asset=EGO)], [event_played(EGO, "stop", 2)]]),
    case("moving", "indirect", "coche_uno_al_union", SPANGLISH,
         "El coche número uno — quiero que vaya hasta el Student Union.",
         [only(assets=[CAR_1])],
         [behave(CAR_1, "follow_path", to=UNION)],
         alternatives=[[does("follow_path", asset=CAR_1)], [event_played(CAR_1, "follow_route", 3)]]),
    case("moving", "indirect", "double_the_speed", SCREEN,
         "So the scenario I'm imagining is the ego car going a bit quicker than it is now. I think right now "
         "it's going quite slowly. Maybe double? Double its current speed, please.",
         [does("drive_lane", asset=EGO, speed_min=9.5, speed_max=10.5), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=10, lane=EASTBOUND)]),
    impossible("moving", "indirect", "one_eighty_kmh", RIDESHARE,
               "running late, make me do 180 km/h down Main Street",
               [behave(EGO, "drive_lane", speed=50, lane=EASTBOUND)]),
    # vague
    case("moving", "vague", "scoot_me_up", RIDESHARE,
         "scoot me up a bit",
         [moved(EGO, 0.5, 30, "forward"), only(assets=[EGO])],
         [move(EGO, forward=3)]),
    case("moving", "vague", "nudge_the_bin", BRIT,
         "nudge the bin over a touch",
         [moved(BIN, 0.1, 3), only(assets=[BIN])],
         [move(BIN, left=0.5)]),
    case("moving", "vague", "slow_it_down", COUNCIL,
         "Slow the test car down, residents are nervous.",
         [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=3, lane=EASTBOUND)],
         alternatives=[[does("drive_lane", asset=EGO, speed_max=4.6)], [event_played(EGO, "change_speed", 3)]]),
    case("moving", "vague", "then_to_the_library", TEACHER,
         "and then she should head over to the library",
         [reaches("pedestrian_1", LIBRARY, 25), only(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "follow_path", to=LIBRARY)],
         setup=[turn("Add a pedestrian at the bus stop.", add(PERSON, where=loc("at", BUS_STOP)), planned=True)]),
    case("moving", "vague", "ego_modestly_forward", LAWYER,
         "The ego's position should be adjusted modestly in its direction of travel.",
         [moved(EGO, 0.5, 20, "forward"), only(assets=[EGO])],
         [move(EGO, forward=3)]),
    case("moving", "vague", "robot_patrols_lot", ROBOTICIST,
         "now have it patrol the lot. couple of waypoints, whatever, as long as it stays in lot B",
         [only(assets=["ackermann_robot_1"])],
         [behave("ackermann_robot_1", "follow_path", waypoints=[[30, -20], [50, -20], [50, -35], [30, -35]])],
         setup=[turn("spawn an ackermann robot in lot B", add(ROBOT, where=loc("at", LOT_B)))],
         alternatives=[[does("follow_path", asset="ackermann_robot_1")],
                       [does("circle", asset="ackermann_robot_1", centre_near=LOT_B)],
                       [event_played("ackermann_robot_1", "follow_route", 3)]]),
    case("moving", "vague", "suv_poquito_adelante", SPANGLISH,
         "el SUV, muévelo un poquito pa'lante",
         [moved(SUV, 0.3, 6, "forward"), only(assets=[SUV])],
         [move(SUV, forward=1.5)]),
    case("moving", "vague", "the_new_bin_aside", SCREEN,
         "Thanks. Um, the thing we just added, could it move a little? Like a step or two to the side. Just a "
         "little, to the side.",
         [moved("trash_bin_2", 0.3, 5), only(assets=["trash_bin_2"])],
         [move("trash_bin_2", left=1)],
         setup=[turn("Please add a trash bin next to the bench at the bus stop.",
                     add(BIN_KIND, where=loc("next_to", BENCH)), planned=True)]),
    case("moving", "vague", "faster_than_that", ADJUSTER,
         "No — vehicle 1 was going faster than that.",
         [only(assets=["passenger_car_3"])],
         [behave("passenger_car_3", "drive_lane", speed=10, lane=WESTBOUND)],
         setup=[turn("Vehicle 1 is a car heading west on Main Street at 5 m/s. Add it.",
                     add(CAR, behaviour=drive(5, WESTBOUND)))],
         alternatives=[[does("drive_lane", asset="passenger_car_3", speed_min=5.5)],
                       [event_played("passenger_car_3", "change_speed", 3)]]),
    # erroneous
    case("moving", "erroneous", "lorry_forwrd", BRIT,
         "move the lorry forwrd 5 metres",
         [moved("truck_1", 4, 6, "forward"), only(assets=["truck_1"])],
         [move("truck_1", forward=5)],
         setup=[turn("Put a lorry in car park A.", add(TRUCK, where=loc("at", LOT_A)), planned=True)]),
    case("moving", "erroneous", "eight_insted_of_five", RIDESHARE,
         "make my car go 8 m/s insted of 5",
         [does("drive_lane", asset=EGO, speed_min=7.5, speed_max=8.5), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=8, lane=EASTBOUND)]),
    case("moving", "erroneous", "midle_car_back_out", TEACHER,
         "can the car in the midle of lot B back out a litle",
         [only(assets=[SUV])],
         [move(SUV, forward=-3)],
         alternatives=[[moved(SUV, 0.5, 8, "backward")], [event_played(SUV, "reverse", 5)]]),
    case("moving", "erroneous", "bentch_face_street", COUNCIL,
         "turn the bentch so it faces the the street",
         [moved(BENCH, 0, 1, turn_min=80, turn_max=100), only(assets=[BENCH])],
         [move(BENCH, turn_deg=-90)]),
    case("moving", "erroneous", "lane_chnage_left", LAWYER,
         "Cause the ego to perfom a lane chnage to the left at two seconds.",
         [event_played(EGO, "lane_change", 5), only()],
         [manoeuvre(EGO, "lane_change", at_time=2, side="left")]),
    case("moving", "erroneous", "suv_cirlce", ROBOTICIST,
         "set suv_1 behavour to cirlce, r=6m, somewhere in lot B",
         [does("circle", asset=SUV, radius_min=5.5, radius_max=6.5, centre_near=LOT_B), only(assets=[SUV])],
         [behave(SUV, "circle", radius=6)]),
    case("moving", "erroneous", "peaton_cruza", SPANGLISH,
         "que el peatón cruze la calle ahora, porfa",
         [only(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "cross_road")],
         setup=[turn("Pon un peatón en la acera norte, cerca del hydrant.",
                     add(PERSON, where=loc("next_to", HYDRANT)))],
         alternatives=[[does(["cross_road", "jaywalk"], asset="pedestrian_1")],
                       [event_played("pedestrian_1", "cross_road", 3)]]),
    case("moving", "erroneous", "eggo_stop", SCREEN,
         "Please make the eggo car stop at about five seconds in. The eggo, sorry, ego. Stop at five seconds.",
         [event_played(EGO, "stop", 8), only()],
         [manoeuvre(EGO, "stop", at_time=5)]),
    impossible("moving", "erroneous", "tree_walk_acros", TEACHER,
               "for the story bit, can the tree by the bus stop walk acros the road like in the book",
               [behave(TREE_LIBRARY, "cross_road")]),
]


# --- Arrangement: several new things laid out as a line, ring, grid, row or lane edge ----------
ARRANGEMENT_CASES: list[Json] = [
    # direct
    case("arrangement", "direct", "five_cones_across_lane", ADJUSTER,
         "Place five cones in a line across the eastbound lane, twenty metres ahead of the ego.",
         [layout("line", CONE, 5), delta(CONE, 5, 5),
          relative("in_front_of", EGO, CONE, max_distance=30, tolerance_deg=20, every=True), only(CONE)],
         [arrange(CONE, "line", loc("in_front_of", EGO, distance=20), count=5)]),
    case("arrangement", "direct", "bollards_along_library_kerb", BRIT,
         "Line six bollards along the kerb in front of the Library.",
         [layout("line", BOLLARD, 6), delta(BOLLARD, 6, 6), near(LIBRARY, 13, BOLLARD, every=True), only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("in_front_of", LIBRARY), count=6)]),
    case("arrangement", "direct", "bollard_ring_fountain", COUNCIL,
         "Install a ring of bollards around the fountain.",
         [layout("ring", BOLLARD, 4, around=FOUNTAIN), delta(BOLLARD, 4, None), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", FOUNTAIN))]),
    case("arrangement", "direct", "four_cars_row_lot_a", RIDESHARE,
         "line up 4 cars in a parking row in lot A",
         [delta(CARS, 4, 4), layout("line", CARS, 4), near(LOT_A, 0.5, CARS, every=True), only(*CARS)],
         [arrange(CAR, "parking_row", loc("at", LOT_A), count=4)]),
    case("arrangement", "direct", "bollards_along_stop_sidewalk", TEACHER,
         "Please put a row of five bollards along the sidewalk at the bus stop.",
         [layout("line", BOLLARD, 5), delta(BOLLARD, 5, 5), near(BUS_STOP, 6, BOLLARD, every=True),
          on(["sidewalk"], BOLLARD), only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("on_sidewalk", BUS_STOP), count=5)]),
    case("arrangement", "direct", "eight_cone_ring_at_point", LAWYER,
         "Arrange eight (8) traffic cones in a ring of radius three metres, centred on the point x = 40, "
         "y = -25.",
         [layout("ring", CONE, 8, around="40, -25"), delta(CONE, 8, 8),
          near(None, 3.6, CONE, point=(40, -25), every=True), only(CONE)],
         [arrange(CONE, "ring", xy(40, -25), count=8, radius=3)]),
    case("arrangement", "direct", "cone_grid_3x3", ROBOTICIST,
         "grid of 9 cones, 3x3, 2 m spacing, centred on map (40, -30)",
         [layout("cluster", CONE, 9, tolerance=3.2), delta(CONE, 9, 9),
          near(None, 3.5, CONE, point=(40, -30), every=True), only(CONE)],
         [arrange(CONE, "grid", xy(40, -30), count=9, columns=3, spacing=2)]),
    case("arrangement", "direct", "barreras_across_campus_drive", SPANGLISH,
         "Pon una línea de barriers across Campus Drive, north of the intersection, around y = 20, por favor.",
         [layout("line", BARRIER, 2), delta(BARRIER, 2, None), in_lane(None, BARRIER),
          near(None, 5, BARRIER, point=(0, 20), every=True), only(BARRIER)],
         [arrange(BARRIER, "line", xy(0, 20), count=3, heading_deg=0)]),
    case("arrangement", "direct", "bollard_ring_library_tree", SCREEN,
         "I'd like a ring of bollards around the tree by the Library, please. The tree near the Library. A ring "
         "of bollards going all the way around it.",
         [layout("ring", BOLLARD, 4, around=TREE_LIBRARY), delta(BOLLARD, 4, None), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", TREE_LIBRARY))]),
    impossible("arrangement", "direct", "hundred_twenty_bollards", ROBOTICIST,
               "arrange 120 bollards in a grid in lot A",
               [arrange(BOLLARD, "grid", loc("at", LOT_A), count=120)]),
    # indirect
    case("arrangement", "indirect", "westbound_coned_for_works", ADJUSTER,
         "At the time, the westbound lane east of the junction was coned off along its edge for roadworks. Set "
         "that up.",
         [layout("line", CONE, 5), in_lane(WESTBOUND, CONE), near(None, 40, CONE, point=(48, 1.75), every=True),
          only(CONE)],
         [arrange(CONE, "lane_edge", loc("at", LOT_B_ENTRANCE, lane=WESTBOUND))]),
    case("arrangement", "indirect", "market_lorries_and_cones", BRIT,
         "It's the Saturday market in car park A, so the traders' three lorries want parking in a tidy row, "
         "and a line of cones across the entrance so nobody else drives in.",
         [delta(TRUCK, 3, 3), layout("line", TRUCK, 3), near(LOT_A, 0.5, TRUCK, every=True),
          delta(CONE, 3, None), near(LOT_A_ENTRANCE, 8, CONE, every=True), only(TRUCK, CONE)],
         [arrange(TRUCK, "parking_row", loc("at", LOT_A), count=3),
          arrange(CONE, "line", xy(-85, 9), count=5, heading_deg=0)]),
    case("arrangement", "indirect", "verge_bollards_engineering", COUNCIL,
         "Residents are sick of people parking on the verge outside Engineering Hall. We need a physical line "
         "of bollards there to stop it.",
         [layout("line", BOLLARD, 4), near(ENGINEERING, 10, BOLLARD, every=True), only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("in_front_of", ENGINEERING), count=6)]),
    case("arrangement", "indirect", "block_lot_b_entrance", RIDESHARE,
         "block off the lot B entrance with cones so nobody else pulls in while i'm loading",
         [layout("line", CONE, 3), delta(CONE, 3, None), near(LOT_B_ENTRANCE, 5, CONE, every=True), only(CONE)],
         [arrange(CONE, "line", xy(47, -6), count=5, heading_deg=0)]),
    case("arrangement", "indirect", "weaving_grid_lot_a", TEACHER,
         "The children are going to practise weaving safely between things — could we have a little grid of "
         "cones in lot A for them?",
         [layout("cluster", CONE, 4, tolerance=8), delta(CONE, 4, None), near(LOT_A, 0.5, CONE, every=True),
          only(CONE)],
         [arrange(CONE, "grid", loc("at", LOT_A), count=9)]),
    case("arrangement", "indirect", "crosswalk_approach_delineated", LAWYER,
         "For demonstrative purposes, the approach to the west crosswalk ought to be delineated by a line of "
         "cones along the edge of the eastbound lane, commencing thirty metres before the crosswalk.",
         [layout("line", CONE, 5), in_lane(EASTBOUND, CONE), near(WEST_CROSSWALK, 31, CONE, every=True),
          only(CONE)],
         [arrange(CONE, "lane_edge", ahead_of(WEST_CROSSWALK, -30, lane=EASTBOUND))]),
    case("arrangement", "indirect", "robot_corridor", ROBOTICIST,
         "need a corridor for the robot: two parallel lines of cones in lot B, ~3 m apart, running along x "
         "(east)",
         [delta(CONE, 8, None), near(LOT_B, 0.5, CONE, every=True), only(CONE)],
         [arrange(CONE, "line", xy(38, -25), count=6, heading_deg=0, spacing=2),
          arrange(CONE, "line", xy(38, -28), count=6, heading_deg=0, spacing=2)]),
    case("arrangement", "indirect", "fiesta_benches", SPANGLISH,
         "Para la fiesta del barrio necesitamos sitting — pon benches en una fila cerca del fountain.",
         [layout("line", BENCH_KIND, 3), near(FOUNTAIN, 12, BENCH_KIND, every=True), only(BENCH_KIND)],
         [arrange(BENCH_KIND, "line", loc("in_front_of", FOUNTAIN), count=4)]),
    case("arrangement", "indirect", "close_southbound_barriers", SCREEN,
         "So when I go through the scene I'd like to know where the construction zone is. Could there be "
         "barriers, a line of them, closing off the southbound lane of Campus Drive, south of the junction? "
         "Closing off that lane.",
         [layout("line", BARRIER, 2), delta(BARRIER, 2, None), in_lane(SOUTHBOUND, BARRIER),
          near(None, 25, BARRIER, point=(-1.75, -35), every=True), only(BARRIER)],
         [arrange(BARRIER, "line", xy(-1.75, -25), count=2, heading_deg=0, spacing=2)]),
    impossible("arrangement", "indirect", "ring_eighty_metres", COUNCIL,
               "Residents want the whole campus core fenced off — ring the crossroads with barriers at an 80 "
               "metre radius.",
               [arrange(BARRIER, "ring", loc("at", JUNCTION), radius=80)]),
    # vague
    case("arrangement", "vague", "cones_round_the_rubble", RIDESHARE,
         "stick some cones round it",
         [layout("ring", CONE, 4, around="cement_rubble_1"), delta(CONE, 4, None), only(CONE)],
         [arrange(CONE, "ring", loc("at", "cement_rubble_1"))],
         setup=[turn("someone's dumped rubble in lot b, put some there", add(RUBBLE, where=loc("at", LOT_B)))]),
    case("arrangement", "vague", "tidy_row_of_bikes", BRIT,
         "tidy row of bikes by the union, ta",
         [layout("line", BIKE, 3), delta(BIKE, 3, None), near(UNION, 12, BIKE, every=True), only(BIKE)],
         [arrange(BIKE, "line", loc("at", UNION), count=5)]),
    case("arrangement", "vague", "keep_cars_off_fountain", COUNCIL,
         "Residents have seen cars driving right up onto the fountain area. Put something round it.",
         [layout("ring", [BOLLARD, BARRIER, CONE], 3, around=FOUNTAIN), delta([BOLLARD, BARRIER, CONE], 3, None),
          near(FOUNTAIN, 10, [BOLLARD, BARRIER, CONE], every=True), only(BOLLARD, BARRIER, CONE)],
         [arrange(BOLLARD, "ring", loc("at", FOUNTAIN))]),
    case("arrangement", "vague", "obstacle_course", TEACHER,
         "cones for a little obstacle course in the car park?",
         [delta(CONE, 3, None), only(CONE)],
         [arrange(CONE, "grid", loc("at", LOT_B), count=6)],
         alternatives=[[near(LOT_B, 0.5, CONE, every=True)], [near(LOT_A, 0.5, CONE, every=True)]]),
    case("arrangement", "vague", "orderly_barriers_east_gate", LAWYER,
         "The scene would benefit from a number of barriers arranged in an orderly fashion at the east gate.",
         [layout("line", BARRIER, 2), delta(BARRIER, 2, None), near(EAST_GATE, 10, BARRIER, every=True),
          only(BARRIER)],
         [arrange(BARRIER, "line", loc("at", EAST_GATE), count=3)]),
    case("arrangement", "vague", "ring_wherever", ROBOTICIST,
         "ring of cones wherever there's room, don't care where",
         [layout("ring", CONE, 4), delta(CONE, 4, None), only(CONE)],
         [arrange(CONE, "ring", loc("at", LOT_B))]),
    case("arrangement", "vague", "barreras_por_la_library", SPANGLISH,
         "unas barreras por la library, lo que sea",
         [delta(BARRIER, 2, None), near(LIBRARY, 12, BARRIER, every=True), only(BARRIER)],
         [arrange(BARRIER, "line", loc("in_front_of", LIBRARY), count=3)]),
    case("arrangement", "vague", "pattern_west_car_park", SCREEN,
         "Could you set up a few cones, in some kind of pattern, I'm not fussy which, somewhere in the car park "
         "on the west side. The west car park.",
         [delta(CONE, 3, None), near(LOT_A, 0.5, CONE, every=True), only(CONE)],
         [arrange(CONE, "grid", loc("at", LOT_A), count=6)]),
    case("arrangement", "vague", "police_coned_round_it", ADJUSTER,
         "Police then coned all round it.",
         [layout("ring", CONE, 4, around="truck_1"), delta(CONE, 4, None), only(CONE)],
         [arrange(CONE, "ring", loc("at", "truck_1"))],
         setup=[turn("The claimant's lorry was parked in lot B. Add it, parked.", add(TRUCK, where=loc("at", LOT_B)),
                     planned=True)]),
    # erroneous
    impossible("arrangement", "erroneous", "cones_in_side_libary", BRIT,
               "stick a line of cones in side the libary, down the middle of the reading room",
               [arrange(CONE, "line", xy(-41, -30), count=5)]),
    case("arrangement", "erroneous", "cones_lin_behind_me", RIDESHARE,
         "put like 5 cones in a lin behind my car",
         [layout("line", CONE, 5), relative("behind", EGO, CONE, max_distance=15, every=True), only(CONE)],
         [arrange(CONE, "line", loc("behind", EGO), count=5)]),
    case("arrangement", "erroneous", "benchs_round_fountian", TEACHER,
         "can we hav a circle of benchs round the fountian for story time",
         [layout("ring", BENCH_KIND, 4, around=FOUNTAIN), delta(BENCH_KIND, 4, None), only(BENCH_KIND)],
         [arrange(BENCH_KIND, "ring", loc("at", FOUNTAIN))]),
    case("arrangement", "erroneous", "same_agian_libary", COUNCIL,
         "and teh same agian outside the libary pls",
         [layout("line", BOLLARD, 4), delta(BOLLARD, 4, None), near(LIBRARY, 10, BOLLARD, every=True),
          only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("in_front_of", LIBRARY), count=5)],
         setup=[turn("Install a line of bollards outside Engineering Hall.",
                     arrange(BOLLARD, "line", loc("in_front_of", ENGINEERING), count=5))]),
    case("arrangement", "erroneous", "barriers_alongside_east_gate", LAWYER,
         "Arrange four (4) barriers in a line alongside the the eastbound lane, near to the the east gate.",
         [layout("line", BARRIER, 4), delta(BARRIER, 4, 4), in_lane(EASTBOUND, BARRIER),
          near(EAST_GATE, 15, BARRIER, every=True), only(BARRIER)],
         [arrange(BARRIER, "lane_edge", loc("at", EAST_GATE, lane=EASTBOUND), count=4)]),
    case("arrangement", "erroneous", "cone_ring_arround_point", ROBOTICIST,
         "spawn cone ring r=4m arround (40,-30)",
         [layout("ring", CONE, 4, around="40, -30"), near(None, 4.6, CONE, point=(40, -30), every=True),
          only(CONE)],
         [arrange(CONE, "ring", xy(40, -30), radius=4)]),
    case("arrangement", "erroneous", "fila_de_camiones", SPANGLISH,
         "haz una fila de 3 camiones en el parkin lot B",
         [delta(TRUCK, 3, 3), layout("line", TRUCK, 3), near(LOT_B, 0.5, TRUCK, every=True), only(TRUCK)],
         [arrange(TRUCK, "parking_row", loc("at", LOT_B), count=3)]),
    case("arrangement", "erroneous", "cones_acros_in_front", SCREEN,
         "Please put a line of cones acros the road in front of the eggo car. In front of the ego car I mean, "
         "sorry. A line of cones across the road.",
         [layout("line", CONE, 3), relative("in_front_of", EGO, CONE, max_distance=20, every=True), only(CONE)],
         [arrange(CONE, "line", loc("in_front_of", EGO))]),
    case("arrangement", "erroneous", "staight_line_westbound", ADJUSTER,
         "Pls arange six cones in a staight line along the westbound lane by the JTEKT entrance.",
         [layout("line", CONE, 6), delta(CONE, 6, 6), in_lane(WESTBOUND, CONE), near(JTEKT, 25, CONE, every=True),
          only(CONE)],
         [arrange(CONE, "lane_edge", loc("at", JTEKT, lane=WESTBOUND), count=6)]),
]


# --- Appearance: weather, clock, lights and the looks of assets --------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case("appearance", "direct", "rain_heavily", BRIT,
         "Make it rain heavily.",
         [env(weather=["rain"], intensity_min=0.75, **NOON), only(env=True)],
         [weather("rain", 0.9)]),
    case("appearance", "direct", "eleven_pm", RIDESHARE,
         "set the time to 11pm",
         [env(time_from="22:45", time_to="23:15", **CLEAR), only(env=True)],
         [clock("23:00")]),
    case("appearance", "direct", "bench_green", COUNCIL,
         "Paint the bench green.",
         [looks("green", asset=BENCH), only(assets=[BENCH])],
         [paint([BENCH], colour="green")]),
    case("appearance", "direct", "school_bus_yellow", TEACHER,
         "Make the school bus yellow, like a real one.",
         [looks("yellow", asset="bus_1"), only(assets=["bus_1"])],
         [paint(["bus_1"], colour="yellow")],
         setup=[turn("Add a school bus at the bus stop.", add(BUS, where=loc("in_lane", BUS_STOP)), planned=True)]),
    case("appearance", "direct", "moderate_fog", LAWYER,
         "Set the weather to fog, of moderate intensity.",
         [env(weather=["fog"], intensity_min=0.45, intensity_max=0.75, **NOON), only(env=True)],
         [weather("fog", 0.6)]),
    case("appearance", "direct", "lights_on_exposure", ROBOTICIST,
         "street lights: on. exposure: 0.8.",
         [env(street_lights="on", exposure_min=0.75, exposure_max=0.85, **NOON), only(env=True)],
         [lighting(street_lights="on", exposure=0.8)]),
    case("appearance", "direct", "suv_de_rojo", SPANGLISH,
         "Pinta el SUV de rojo, por favor.",
         [looks("red", asset=SUV), only(assets=[SUV])],
         [paint([SUV], colour="red")]),
    case("appearance", "direct", "lamps_black_but_one", SCREEN,
         "Could you make all of the street lights black, please, except the one nearest the bus stop? So every "
         "street light black, apart from that one. That one stays as it is.",
         [looks("black", LAMP, every=True, min_count=11), kept(LAMP_BUS_STOP),
          only(assets=[f"street_light_{n}" for n in range(1, 13) if n != 4])],
         [paint([f"street_light_{n}" for n in range(1, 13) if n != 4], colour="black")]),
    case("appearance", "direct", "clock_and_light_rain", ADJUSTER,
         "Set the time to 17:45 and the weather to light rain.",
         [env(weather=["rain"], intensity_max=0.45, time_from="17:30", time_to="18:00"), only(env=True)],
         [clock("17:45"), weather("rain", 0.3)]),
    impossible("appearance", "direct", "clock_twenty_six", ROBOTICIST,
               "set sim clock to 26:00",
               [clock("26:00")]),
    # indirect
    case("appearance", "indirect", "dusk_drizzle", ADJUSTER,
         "The incident happened just after dusk, in a steady drizzle. Match those conditions.",
         [env(weather=["rain"], intensity_max=0.5, time_from="19:00", time_to="21:30"), only(env=True)],
         [clock("20:15"), weather("rain", 0.3)]),
    case("appearance", "indirect", "pea_souper", BRIT,
         "It's a proper pea-souper out there this morning — can we have the scene looking like that?",
         [env(weather=["fog"], intensity_min=0.6), only(env=True)],
         [weather("fog", 0.9)]),
    case("appearance", "indirect", "street_at_night_lit", COUNCIL,
         "Residents want to see what the street looks like at night with the lamps lit.",
         [env(night=True), only(env=True)],
         [clock("22:00")],
         alternatives=[[env(street_lights="on")], [env(street_lights="auto")]]),
    case("appearance", "indirect", "sun_in_my_eyes", RIDESHARE,
         "sun's right in my eyes, can we get some cloud",
         [env(weather=["cloudy"]), only(env=True)],
         [weather("cloudy")]),
    case("appearance", "indirect", "cheerful_bin", TEACHER,
         "The children won't notice the bin at the bus stop unless it's bright and cheerful.",
         [looks(BRIGHT, asset=BIN), only(assets=[BIN])],
         [paint([BIN], colour="yellow")]),
    case("appearance", "indirect", "suv_silver_on_record", LAWYER,
         "My client's vehicle, the SUV, was, as a matter of record, silver in colour; the model ought to be "
         "consistent with that record.",
         [looks("silver", asset=SUV, tolerance=0.15), only(assets=[SUV])],
         [paint([SUV], colour="silver")]),
    case("appearance", "indirect", "low_light_camera", ROBOTICIST,
         "need low-light conditions to stress-test the camera pipeline",
         [only(env=True)],
         [clock("21:00")],
         alternatives=[[env(night=True)], [env(exposure_max=0.6)]]),
    case("appearance", "indirect", "quiero_nieve", SPANGLISH,
         "Hace un frío que pela — make it look like that, quiero nieve.",
         [env(weather=["snow"]), only(env=True)],
         [weather("snow")]),
    case("appearance", "indirect", "tell_the_cars_apart", SCREEN,
         "I can't tell the cars apart from the descriptions alone. If the two passenger cars could be different "
         "colours from each other, say one blue and one orange, that would really help me.",
         [only(assets=[CAR_1, CAR_2])],
         [paint([CAR_1], colour="blue"), paint([CAR_2], colour="orange")],
         alternatives=[[looks("blue", asset=CAR_1), looks("orange", asset=CAR_2)],
                       [looks("orange", asset=CAR_1), looks("blue", asset=CAR_2)]]),
    impossible("appearance", "indirect", "library_brick_red", COUNCIL,
               "For the heritage consultation, residents want to see the Library building painted brick red.",
               [paint(["Library"], colour="maroon")]),
    # vague
    case("appearance", "vague", "rough_night", RIDESHARE,
         "make it look like a rough night out",
         [env(night=True, weather=WET_OR_WHITE), only(env=True)],
         [clock("23:00"), weather("rain", 0.8)]),
    case("appearance", "vague", "bit_grim", BRIT,
         "bit grim out, isn't it. make the scene look it",
         [env(weather=["cloudy", "rain", "fog"]), only(env=True)],
         [weather("cloudy")]),
    case("appearance", "vague", "brighten_benches", COUNCIL,
         "Brighten up the benches.",
         [only(BENCH_KIND)],
         [paint(category=BENCH_KIND, colour="yellow")],
         alternatives=[[looks(BRIGHT, BENCH_KIND)], [looks(None, BENCH_KIND, material="glossy")]]),
    case("appearance", "vague", "cones_easier_to_see", TEACHER,
         "make the cones easier to see",
         [looks(BRIGHT, CONE, every=True, min_count=3), only(CONE)],
         [paint(category=CONE, colour="yellow")],
         setup=[turn("Put three cones at the lot A entrance.", add(CONE, 3, loc("at", LOT_A_ENTRANCE)),
                     planned=True)]),
    case("appearance", "vague", "winter", LAWYER,
         "The ambient conditions should be altered so as to reflect the season in question, namely winter.",
         [env(weather=["snow"]), only(env=True)],
         [weather("snow")]),
    case("appearance", "vague", "darker_pls", ROBOTICIST,
         "darker pls",
         [only(env=True)],
         [lighting(exposure=0.6)],
         alternatives=[[env(exposure_max=0.9)], [env(night=True)]]),
    case("appearance", "vague", "ego_otro_color", SPANGLISH,
         "el coche del ego, otro color, lo que sea",
         [looks(ANY_COLOUR, "ego_vehicle", tolerance=0.3), only(assets=[EGO])],
         [paint([EGO], colour="blue")]),
    case("appearance", "vague", "just_getting_light", SCREEN,
         "Could you make it feel like early morning? When it's just getting light. So early morning, just "
         "getting light outside.",
         [env(time_from="05:00", time_to="07:30"), only(env=True)],
         [clock("06:00")]),
    case("appearance", "vague", "dry_on_the_day", ADJUSTER,
         "Scrap that, we no longer want the rain. It was dry on the day.",
         [env(weather=["clear", "cloudy"]), only(env=True)],
         [weather("clear")],
         setup=[turn("Make it rain.", weather("rain"))]),
    # erroneous
    case("appearance", "erroneous", "mkae_it_snwo", BRIT,
         "mkae it snwo",
         [env(weather=["snow"]), only(env=True)],
         [weather("snow")]),
    case("appearance", "erroneous", "make_it_nite", RIDESHARE,
         "can u make it nite",
         [env(night=True), only(env=True)],
         [clock("22:00")]),
    case("appearance", "erroneous", "other_one_to", COUNCIL,
         "and the othre one to pls, same colour",
         [only(assets=[CAR_2, SUV])],
         [paint([CAR_2], colour="blue")],
         setup=[turn("Paint passenger car 1 blue, it's the one residents reported.", paint([CAR_1], colour="blue"))],
         alternatives=[[looks("blue", asset=CAR_2)], [looks("blue", asset=SUV)]]),
    case("appearance", "erroneous", "autum_trees", TEACHER,
         "make the trees more autum coloured, orang maybe",
         [looks(AUTUMN, TREE, every=True, min_count=4), only(TREE)],
         [paint(category=TREE, colour="orange")]),
    case("appearance", "erroneous", "seven_thirty_morning", LAWYER,
         "Set the the time of of day to 7:30 in the morning.",
         [env(time_from="07:15", time_to="07:45"), only(env=True)],
         [clock("07:30")]),
    case("appearance", "erroneous", "strret_lights_off", ROBOTICIST,
         "turn off strret lights and set exposre 1.5",
         [env(street_lights="off", exposure_min=1.4, exposure_max=1.6), only(env=True)],
         [lighting(street_lights="off", exposure=1.5)]),
    case("appearance", "erroneous", "llueva_poquito", SPANGLISH,
         "que llueva un poquito, ligth rain nomás",
         [env(weather=["rain"], intensity_max=0.45), only(env=True)],
         [weather("rain", 0.3)]),
    case("appearance", "erroneous", "bench_out_of_would", SCREEN,
         "Could you make the bench out of would. Sorry, wood, the material wood. The bench at the bus stop, "
         "made of wood.",
         [looks(None, asset=BENCH, material="wood"), only(assets=[BENCH])],
         [paint([BENCH], material="wood")]),
    impossible("appearance", "erroneous", "suv_glow_in_teh_dark", TEACHER,
               "can the SUV glow in teh dark so the kids spot it easy",
               [paint([SUV], colour="glow-in-the-dark")]),
]


ALL_CASES: list[Json] = [
    *SEARCH_CASES,
    *ADDITION_CASES,
    *REMOVAL_CASES,
    *POSITIONING_CASES,
    *MOVING_CASES,
    *ARRANGEMENT_CASES,
    *APPEARANCE_CASES,
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
