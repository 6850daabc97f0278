"""The sixteenth practice suite: 252 cases in the words of nine new kinds of user, from the campus world alone.

`python -m drivetwin.evals.practice16_source` writes `suites/practice16.jsonl` (tag `practice16`, ids
`practice16.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`): a driving-school instructor setting up lessons for a
learner, a film-location scout dressing and lighting shots, a traffic engineer who talks in MUTCD and
standards jargon (channelizing devices, tapers, R1-1, luminaires, signal heads, EB/WB approaches), a
parent worried about the school run, a games modder used to console commands ("spawn", "tp",
"despawn", "rm -rf"), a non-native speaker writing through a machine translator, a voice-dictation
user (homophones such as "buy" for by, "read" for red, "four" for for, no punctuation), a hurried
manager writing terse one-liners, and a safety-case auditor (hazards, evidence, ODD, claims).
Prompts mix short chat turns with one-to-three sentence requests, reasons and hedges, references
back to earlier turns ("that one", "the same again"), numbers in words and digits, units (metres,
feet, km/h, mph), relations (next to, in front of, behind, ahead of, along), scopes (a lane, a lot,
a sidewalk, a side of a road, a landmark), behaviours (speeds, stopping, crossing, circling),
weather and clock times, questions (which must change nothing), negation and exceptions. The
erroneous grade carries realistic typos, autocorrect and dictation swaps, run-together words,
dropped words and non-native grammar.

Counts: 7 tasks x 4 grades, 9 cases in every cell (252 in all). 34 cases are multi-turn (18 with
a planned earlier turn that has calls), 17 compound (the reference makes two calls or more), and
21 (8.3 %) impossible, tagged `impossible`, where the right outcome is a refusal that changes
nothing: a hospital, a tram, a speed camera, a playground, 15 buses, a tree inside the JTEKT
Building; removing the ego, the Library or a bus that is not there; the SUV inside the Student
Union, a bench at x = 300 (off the map), moving the fountain; 250 km/h, a tree driving circles,
moving the Library; 150 cones, a 100 m ring, cones inside Engineering Hall; hail, 25:30 and a
repainted Library.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with
`alternatives` where a request has two fair readings, and a `reference` plan that passes. The suite
was written from the campus world, the asset catalog, the Worker tools and the eval checks only, by
someone who had not read the planners, their lexicons, their prompt examples or any other suite's
cases.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

Json = dict[str, Any]

TAG = "practice16"

# --- The campus world, as these cases use it --------------------------------------------------
# Main Street runs east-west (eastbound lane y = -1.75, westbound y = +1.75, kerbs at y = +-3.5,
# sidewalks at y = +-5.5); Campus Drive runs north-south (northbound x = +1.75, southbound -1.75).
# The world spans x -110..110 and y -90..90; it is noon and clear.
EGO = "ego"  # the learner's / test car: drives main_eastbound at 5 m/s from (-60, -1.75), facing east
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

# Who is speaking: each case's `notes` names its voice.
INSTRUCTOR = "voice: driving-school instructor setting up a lesson"
SCOUT = "voice: film-location scout"
ENGINEER = "voice: traffic engineer in MUTCD and standards jargon"
PARENT = "voice: parent worried about the school run"
MODDER = "voice: games modder used to console commands"
TRANSLATED = "voice: non-native speaker writing through a machine translator"
DICTATION = "voice: voice-dictation user (homophones, no punctuation)"
MANAGER = "voice: hurried manager writing terse one-liners"
AUDITOR = "voice: safety-case auditor"


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


# --- Search: questions, which must change nothing ------------------------------------------------
SEARCH_CASES: list[Json] = [
    # direct
    case("search", "direct", "ego_lane", INSTRUCTOR,
         "Which lane is the ego car driving in right now?",
         [says(any_of=["main_eastbound"]), only()],
         [lanes(near=EGO)]),
    case("search", "direct", "hydrant_to_signal", ENGINEER,
         "What's the distance between fire_hydrant_1 and traffic_light_2?",
         [says(any_of=["6.5", "6.54"]), only()],
         [measure(HYDRANT, LIGHT_NE)]),
    case("search", "direct", "list_cars", MODDER,
         "list cars",
         [says(all_of=[CAR_1, CAR_2]), only()],
         [find(category="cars")]),
    case("search", "direct", "time_and_weather", SCOUT,
         "What time of day is it in the scene, and what's the weather doing?",
         [says(all_of=["clear"], any_of=["12:00", "noon"]), only()],
         [environment()]),
    case("search", "direct", "lamps_on_main", PARENT,
         "How many street lights are there along Main Street?",
         [says(any_of=["12", "twelve"]), only()],
         [find(category="street lights", lane="Main Street")]),
    case("search", "direct", "nearest_landmark_to_ego", AUDITOR,
         "Which named landmark is nearest to the ego vehicle?",
         [says(any_of=["parking lot A", "lot A", "Library entrance"]), only()],  # by edge, or by centre
         [landmarks(nearest_to=EGO)]),
    case("search", "direct", "campus_drive_limit", MANAGER,
         "speed limit on campus drive?",
         [says(any_of=["8 m/s", "29 km/h", "29"]), only()],
         [lanes(road="Campus Drive")]),
    case("search", "direct", "stop_sign_where", INSTRUCTOR,
         "Where exactly is the stop sign? I want to walk my learner through it.",
         [says(any_of=[STOP_SIGN, "-13.5"]), only()],
         [find(category="stop sign")]),
    case("search", "direct", "two_questions", SCOUT,
         "Two things before the recce: what's the weather, and how far is the bus stop from the ego?",
         [says(all_of=["clear"], any_of=["30.2", "30"]), only()],
         [environment(), measure(BUS_STOP)]),
    # indirect
    case("search", "indirect", "seat_at_shuttle", PARENT,
         "My son waits for the shuttle every morning. Is there anywhere for him to sit near where it stops?",
         [says(any_of=[BENCH]), only()],
         [find(category="bench", near=BUS_STOP, within=15)]),
    case("search", "indirect", "eb_regulatory_speed", ENGINEER,
         "What's the posted regulatory speed on the EB travel lane of Main Street, in km/h?",
         [says(any_of=["29", "28.8"]), only()],
         [lanes(road="Main Street")]),
    case("search", "indirect", "camera_spot_fountain", SCOUT,
         "I want a wide that frames the fountain. What's the closest named spot I could park the camera truck by?",
         [says(any_of=["JTEKT", "east gate"]), only()],
         [landmarks(nearest_to=FOUNTAIN)]),
    case("search", "indirect", "anything_in_lanes", AUDITOR,
         "For the hazard log: is anything occupying a travel lane at the moment, apart from our own vehicle?",
         [says(any_of=["ego", "1 asset", "no other", "nothing"], none_of=[CAR_1, CAR_2, SUV]), only()],
         [find(on_lane=True)]),
    case("search", "indirect", "lane_and_road_to_bus_stop", INSTRUCTOR,
         "Before my learner pulls away: which lane are we sitting in, and how much road is there between us and the bus stop?",
         [says(all_of=["main_eastbound"], any_of=["30.2", "30.0", "30", "28"]), only()],
         [lanes(near=EGO), measure(BUS_STOP)]),
    case("search", "indirect", "prop_next_to_hydrant", MODDER,
         "whats the closest entity to fire_hydrant_1? need the id",
         [says(any_of=[LIGHT_NE]), only()],
         [find(nearest_to=HYDRANT)]),
    case("search", "indirect", "how_strong_rain", TRANSLATED,
         "It rains now, but how much strong? Tell me the number of it.",
         [says(any_of=["0.9", "90"]), only()],
         [environment()],
         setup=[turn("Please make rain, strong one.", weather("rain", 0.9))]),
    case("search", "indirect", "walk_lot_to_lot", MANAGER,
         "courier parks in the west lot, walks to student parking. how far is that",
         [says(any_of=["136.4", "136", "116.7", "117"]), only()],
         [measure(LOT_A, LOT_B)]),
    case("search", "indirect", "tree_to_shoot_under", SCOUT,
         "Is there a tree anywhere near the Library I could shoot under?",
         [says(any_of=[TREE_LIBRARY]), only()],
         [find(category="tree", near=LIBRARY, within=30)]),
    # vague
    case("search", "vague", "whats_in_lot_b", MANAGER,
         "what have we got in lot B",
         [says(all_of=[CAR_1, SUV, CAR_2]), only()],
         [find(near=LOT_B, within=30)]),
    case("search", "vague", "around_fountain", SCOUT,
         "Anything interesting around the fountain?",
         [says(any_of=[TREE_FOUNTAIN]), only()],
         [find(near=FOUNTAIN, within=20)]),
    case("search", "vague", "whats_it_called", MODDER,
         "whats it called",
         [says(any_of=["truck_1"]), only()],
         [find(category="truck")],
         setup=[turn("spawn a truck in lot A", add(TRUCK, where=loc("at", LOT_A)), planned=True)]),
    case("search", "vague", "where_our_car", INSTRUCTOR,
         "where's our car at",
         [says(any_of=["-60", "main_eastbound"]), only()],
         [properties(asset=EGO)]),
    case("search", "vague", "where_to_cross", PARENT,
         "Where can people cross the road around here?",
         [says(any_of=["west crosswalk", "north crosswalk", "crossing_west", "crossing_north"]), only()],
         [landmarks(query="crosswalk")]),
    case("search", "vague", "which_roads", TRANSLATED,
         "Which roads has this place?",
         [says(all_of=["Main Street", "Campus Drive"]), only()],
         [lanes()]),
    case("search", "vague", "whats_by_the_stop", DICTATION,
         "whats near the bus stop",
         [says(any_of=[BENCH, BIN]), only()],
         [find(near=BUS_STOP, within=10)]),
    case("search", "vague", "signal_inventory", ENGINEER,
         "Signal head inventory, please.",
         [says(all_of=[LIGHT_SW, LIGHT_NE]), only()],
         [find(category="traffic light")]),
    impossible("search", "vague", "hospital_distance", PARENT,
               "If one of the kids gets hurt, how far is it from here to the hospital?",
               [measure("hospital")]),
    # erroneous
    case("search", "erroneous", "ego_to_gate", DICTATION,
         "how far is the ego form the main gate",
         [says(any_of=["40", "40.0"]), only()],
         [measure(MAIN_GATE)]),
    case("search", "erroneous", "hydrant_of_fire", TRANSLATED,
         "Where is located the hydrant of fire?",
         [says(any_of=[HYDRANT, "16"]), only()],
         [find(category="fire hydrant")]),
    case("search", "erroneous", "find_suv", MODDER,
         "/find suv nearlotb",
         [says(any_of=[SUV]), only()],
         [find(category="suv", near=LOT_B)]),
    case("search", "erroneous", "witch_lane_suv", DICTATION,
         "witch lane is the suv in",
         [says(any_of=["no lane", "parking lot B", "lot B"]), only()],
         [lanes(near=SUV)]),
    case("search", "erroneous", "conse_count", MANAGER,
         "how many conse out there now",
         [says(any_of=["3", "three"]), only()],
         [find(category="cone")],
         setup=[turn("3 cones at lot A entrance", add(CONE, 3, loc("at", LOT_A_ENTRANCE)))]),
    case("search", "erroneous", "crosing_libary", PARENT,
         "is ther a crosing anywhere near the libary",
         [says(any_of=["west crosswalk", "crossing_west"]), only()],
         [landmarks(query="crosswalk", nearest_to=LIBRARY)]),
    case("search", "erroneous", "suv_mass", AUDITOR,
         "Confrim the mass of the SUV for the crash-energy calc",
         [says(any_of=["2100", "2,100", "2.1"]), only()],
         [properties(asset=SUV)]),
    case("search", "erroneous", "south_side_lamps", ENGINEER,
         "how mnay luminaires on the south side of main st",
         [says(any_of=["6", "six"], none_of=[f"street_light_{n}" for n in range(1, 12, 2)]), only()],
         [find(category="street lights", lane=EASTBOUND)]),
    impossible("search", "erroneous", "tram_lane", MODDER,
               "wich lane is teh tram in",
               [lanes(near="tram")]),
]


# --- Addition ------------------------------------------------------------------------------------
ADDITION_CASES: list[Json] = [
    # direct
    case("addition", "direct", "pedestrian_at_bus_stop", INSTRUCTOR,
         "Add a pedestrian on the sidewalk next to the bus stop.",
         [delta(PERSON, 1, 1), near(BUS_STOP, 6, PERSON), on(["sidewalk"], PERSON), only(PERSON)],
         [add(PERSON, where=loc("on_sidewalk", BUS_STOP))]),
    case("addition", "direct", "barriers_ahead_of_ego", ENGINEER,
         "Place two road barriers in the eastbound lane, 40 metres ahead of the ego.",
         [delta(BARRIER, 2, 2), in_lane(EASTBOUND, BARRIER, scope="added"),
          near(None, 10, BARRIER, point=(-20.0, -1.75), every=True), only(BARRIER)],
         [add(BARRIER, 2, ahead_of(EGO, 40))]),
    case("addition", "direct", "cones_lot_a_entrance", MODDER,
         "spawn 3 traffic cones at the lot A entrance",
         [delta(CONE, 3, 3), near(LOT_A_ENTRANCE, 8, CONE, every=True), only(CONE)],
         [add(CONE, 3, loc("at", LOT_A_ENTRANCE))]),
    case("addition", "direct", "red_car_jtekt", SCOUT,
         "Put a red car, parked, in front of the JTEKT Building entrance.",
         [delta(CARS, 1, 1), near(JTEKT, 10, CARS), looks("red", CARS), does("parked", CARS), only(*CARS)],
         [add(CAR, where=loc("in_front_of", JTEKT), colour="red")]),
    case("addition", "direct", "school_bus_westbound", PARENT,
         "Add a school bus driving in the westbound lane of Main Street.",
         [delta(BUS, 1, 1), does("drive_lane", BUS, lane=WESTBOUND), only(BUS)],
         [add(BUS, behaviour=drive(lane=WESTBOUND))]),
    case("addition", "direct", "bin_and_lamp_by_new_bench", PARENT,
         "Now add a rubbish bin next to that bench, and a street light beside it too so it isn't dark in the evenings.",
         [delta(BIN_KIND, 1, 1), delta(LAMP, 1, 1), near("bench_2", 8, BIN_KIND), near("bench_2", 10, LAMP),
          only(BIN_KIND, LAMP)],
         [add(BIN_KIND, where=loc("next_to", "bench_2")), add(LAMP, where=loc("next_to", "bench_2"))],
         setup=[turn("Add a bench by the fountain.", add(BENCH_KIND, where=loc("at", FOUNTAIN)))]),
    case("addition", "direct", "tree_engineering", TRANSLATED,
         "Please add one tree beside the entrance of the Engineering Hall.",
         [delta(TREE, 1, 1), near(ENGINEERING, 10, TREE), only(TREE)],
         [add(TREE, where=loc("at", ENGINEERING))]),
    case("addition", "direct", "ped_signs_two_crosswalks", AUDITOR,
         "Add a pedestrian crossing sign at the west crosswalk and another one at the north crosswalk.",
         [delta(PED_SIGN, 2, 2), near(WEST_CROSSWALK, 8, PED_SIGN), near(NORTH_CROSSWALK, 8, PED_SIGN), only(PED_SIGN)],
         [add(PED_SIGN, where=loc("at", WEST_CROSSWALK)), add(PED_SIGN, where=loc("at", NORTH_CROSSWALK))]),
    impossible("addition", "direct", "speed_camera", ENGINEER,
               "Install an automated speed-enforcement camera on the westbound approach to the crossroads.",
               [add("speed_camera", where=loc("in_lane", JUNCTION, lane=WESTBOUND))]),
    # indirect
    case("addition", "indirect", "warn_drivers_at_crosswalk", PARENT,
         "Drivers coming up to the west crosswalk need some warning that children cross there.",
         [delta(PED_SIGN, 1, 2), near(WEST_CROSSWALK, 15, PED_SIGN), only(PED_SIGN)],
         [add(PED_SIGN, where=loc("at", WEST_CROSSWALK))]),
    case("addition", "indirect", "channelize_eb_approach", ENGINEER,
         "Channelize the EB approach to the crossroads: four channelizing devices in the eastbound lane "
         "just upstream of the west crosswalk.",
         [delta([CONE, BOLLARD, BARRIER], 4, 4), in_lane(EASTBOUND, [CONE, BOLLARD, BARRIER], scope="added"),
          near(WEST_CROSSWALK, 15, [CONE, BOLLARD, BARRIER], every=True), only(CONE, BOLLARD, BARRIER)],
         [add(CONE, 4, ahead_of(WEST_CROSSWALK, -6, lane=EASTBOUND))]),
    case("addition", "indirect", "extras_at_union", SCOUT,
         "For the establishing shot I need a bit of life at the Student Union doors, a couple of students hanging about.",
         [delta(PERSON, 2, 3), near(UNION, 10, PERSON, every=True), only(PERSON)],
         [add(PERSON, 2, loc("at", UNION))]),
    case("addition", "indirect", "slow_car_to_overtake", INSTRUCTOR,
         "My learner needs something to practise overtaking on: put a slow vehicle about six car lengths ahead "
         "of us in our lane, going slower than we are.",
         [delta(MOTOR_TRAFFIC, 1, 1), does("drive_lane", MOTOR_TRAFFIC, lane=EASTBOUND, speed_max=4.9),
          relative("in_front_of", EGO, MOTOR_TRAFFIC, max_distance=100, tolerance_deg=20), only(*MOTOR_TRAFFIC)],
         [add(TRUCK, where=ahead_of(EGO, 27), behaviour=drive(speed=3.0, lane=EASTBOUND))]),
    case("addition", "indirect", "vru_at_library", AUDITOR,
         "To evidence the pedestrian-detection claim I need one vulnerable road user standing on the "
         "sidewalk in front of the Library.",
         [delta(VULNERABLE, 1, 1), near(LIBRARY, 12, VULNERABLE), on(["sidewalk"], VULNERABLE), only(*VULNERABLE)],
         [add(PERSON, where=loc("on_sidewalk", LIBRARY))]),
    case("addition", "indirect", "lot_a_looks_empty", MANAGER,
         "lot A looks empty in the renders. fix with 3 parked cars",
         [delta(CARS, 3, 3), near(LOT_A, 1, CARS, every=True), only(*CARS)],
         [add(CAR, 3, loc("at", LOT_A))]),
    case("addition", "indirect", "same_again_library", INSTRUCTOR,
         "Same again at the Library entrance, please.",
         [delta(PERSON, 1, 1), near(LIBRARY, 10, PERSON, scope="added"), only(PERSON)],
         [add(PERSON, where=loc("at", LIBRARY))],
         setup=[turn("Add a pedestrian waiting at the bus stop.", add(PERSON, where=loc("at", BUS_STOP)), planned=True)]),
    case("addition", "indirect", "light_library_dropoff", DICTATION,
         "we need something to light up the library drop off at night put it right by the library doors",
         [delta(LAMP, 1, 1), near(LIBRARY, 12, LAMP), only(LAMP)],
         [add(LAMP, where=loc("at", LIBRARY))]),
    impossible("addition", "indirect", "tree_inside_jtekt", TRANSLATED,
               "For shadow in the inside, please to put one tree in the middle of the JTEKT Building, inside of it.",
               [add(TREE, where=xy(37.5, 29.0))]),
    # vague
    case("addition", "vague", "people_waiting", SCOUT,
         "Can we get some people waiting at the bus stop?",
         [delta(PERSON, 2, 8), near(BUS_STOP, 10, PERSON, every=True), only(PERSON)],
         [add(PERSON, 3, loc("at", BUS_STOP))]),
    case("addition", "vague", "bit_of_traffic", INSTRUCTOR,
         "Add a bit of traffic for the lesson.",
         [delta(MOTOR_TRAFFIC, 1, 10), does("drive_lane", MOTOR_TRAFFIC, scope="added"), only(*MOTOR_TRAFFIC)],
         [add(CAR, 2, loc("in_lane", WESTBOUND), behaviour=drive(lane=WESTBOUND))]),
    case("addition", "vague", "more_trees", MANAGER,
         "more trees",
         [delta(TREE, 1, 12), on(["ground", "sidewalk"], TREE, scope="added"), only(TREE)],
         [add(TREE, 3, loc("at", FOUNTAIN))]),
    case("addition", "vague", "stop_cars_on_grass", PARENT,
         "Something so people can't drive onto the grass around the fountain, please.",
         [delta([BOLLARD, BARRIER, CONE], 1, 20), near(FOUNTAIN, 15, [BOLLARD, BARRIER, CONE], every=True),
          only(BOLLARD, BARRIER, CONE)],
         [add(BOLLARD, 4, loc("at", FOUNTAIN))]),
    case("addition", "vague", "two_more_like_that", SCOUT,
         "Lovely. Two more like that.",
         [delta(CARS, 2, 2), near(LOT_A, 1, CARS, scope="added", every=True),
          looks("red", CARS, scope="added", every=True), only(*CARS)],
         [add(CAR, 2, loc("at", LOT_A), colour="red")],
         setup=[turn("Put a red car in lot A.", add(CAR, where=loc("at", LOT_A), colour="red"), planned=True)]),
    case("addition", "vague", "work_zone_signage", ENGINEER,
         "Some work-zone signage on the westbound approach, please.",
         [delta(WORK_SIGN, 1, 4), near(None, 25, WORK_SIGN, point=(25.0, 3.0), every=True), only(WORK_SIGN)],
         [add(WORK_SIGN, where=loc("on_sidewalk", HYDRANT))]),
    case("addition", "vague", "obstacle_for_ego", AUDITOR,
         "Give the ego an obstacle to deal with.",
         [delta(OBSTACLES, 1, 5), in_lane(EASTBOUND, OBSTACLES, scope="added"),
          relative("in_front_of", EGO, OBSTACLES, max_distance=100, tolerance_deg=20), only(*OBSTACLES)],
         [add(RUBBLE, where=ahead_of(EGO, 30))]),
    case("addition", "vague", "car_in_car_park", DICTATION,
         "put a car in the car park",
         [delta(CARS, 1, 1), only(*CARS)],
         [add(CAR, where=loc("at", LOT_B))],
         alternatives=[[near(LOT_B, 1, CARS)], [near(LOT_A, 1, CARS)]]),
    impossible("addition", "vague", "playground", PARENT,
               "Maybe a little playground by the fountain for the kids to wait at?",
               [add("playground", where=loc("at", FOUNTAIN))]),
    # erroneous
    case("addition", "erroneous", "trcuk_east_gate", MODDER,
         "spwan a trcuk at teh east gate",
         [delta(TRUCK, 1, 1), near(EAST_GATE, 12, TRUCK), only(TRUCK)],
         [add(TRUCK, where=loc("at", EAST_GATE))]),
    case("addition", "erroneous", "two_tree_fountain", TRANSLATED,
         "Please add two tree at the side of fountain.",
         [delta(TREE, 2, 2), near(FOUNTAIN, 12, TREE, every=True), only(TREE)],
         [add(TREE, 2, loc("at", FOUNTAIN))]),
    case("addition", "erroneous", "for_cones_buy_stop_sign", DICTATION,
         "add for cones buy the stop sign",
         [delta(CONE, 4, 4), near(STOP_SIGN, 10, CONE, every=True), only(CONE)],
         [add(CONE, 4, loc("next_to", STOP_SIGN))]),
    case("addition", "erroneous", "benchs_lot_a", MANAGER,
         "add 2 benchs lotA",
         [delta(BENCH_KIND, 2, 2), near(LOT_A, 3, BENCH_KIND, every=True), only(BENCH_KIND)],
         [add(BENCH_KIND, 2, loc("at", LOT_A))]),
    case("addition", "erroneous", "crossing_guard", PARENT,
         "pls ad a crosing gaurd there too",
         [delta(PERSON, 1, 1), near(NORTH_CROSSWALK, 8, PERSON), only(PERSON)],
         [add(PERSON, where=loc("at", NORTH_CROSSWALK))],
         setup=[turn("Add a pedestrian crossing sign at the north crosswalk.",
                     add(PED_SIGN, where=loc("at", NORTH_CROSSWALK)), planned=True)]),
    case("addition", "erroneous", "parkd_car_behind_ego", INSTRUCTOR,
         "ad a parkd car behind the ego so my lerner has to check her mirrors",
         [delta(CARS, 1, 1), relative("behind", EGO, CARS, max_distance=25, tolerance_deg=30), does("parked", CARS),
          only(*CARS)],
         [add(CAR, where=loc("behind", EGO))]),
    case("addition", "erroneous", "stopsign_lot_b", ENGINEER,
         "instal a stopsign at the lot B entrnace for exiting traffic",
         [delta(STOP_KIND, 1, 1), near(LOT_B_ENTRANCE, 10, STOP_KIND), only(STOP_KIND)],
         [add(STOP_KIND, where=loc("at", LOT_B_ENTRANCE))]),
    case("addition", "erroneous", "jaywalker", AUDITOR,
         "Add a jaywalker crosing infront of the ego vehcile",
         [delta(PERSON, 1, 1), does("jaywalk", PERSON, crosses_lane=EASTBOUND), only(PERSON)],
         [add(PERSON, behaviour={"kind": "jaywalk"})]),
    impossible("addition", "erroneous", "fifteen_buses", MANAGER,
               "add 15 busses on main st asap",
               [add(BUS, 15, loc("in_lane", EASTBOUND), behaviour=drive(lane=EASTBOUND))]),
]


# --- Removal -------------------------------------------------------------------------------------
_CONES_AT_LOT_A = turn("spawn 5 cones at lot A", add(CONE, 5, loc("at", LOT_A)), planned=True)
_ROADWORKS_AHEAD = turn(
    "Put some rubble in our lane about 30 metres ahead, with a few cones before it.",
    add(RUBBLE, where=ahead_of(EGO, 30)), add(CONE, 3, ahead_of(EGO, 22)),
)

REMOVAL_CASES: list[Json] = [
    # direct
    case("removal", "direct", "despawn_suv", MODDER,
         "despawn suv_1",
         [gone(SUV), kept(CAR_1, CAR_2), only(assets=[SUV])],
         [remove(SUV)]),
    case("removal", "direct", "tree_4", AUDITOR,
         "Remove tree_4 from the scene configuration.",
         [gone(TREE_LOT_A), kept(TREE_LIBRARY, TREE_FOUNTAIN, TREE_EAST), only(assets=[TREE_LOT_A])],
         [remove(TREE_LOT_A)]),
    case("removal", "direct", "r1_stop_sign", ENGINEER,
         "Remove the R1-1 stop sign on the south-west corner of the crossroads.",
         [gone(STOP_SIGN), only(assets=[STOP_SIGN])],
         [remove(STOP_SIGN)]),
    case("removal", "direct", "tree_by_fountain", SCOUT,
         "Take out the tree right next to the fountain, the other trees stay.",
         [gone(TREE_FOUNTAIN), kept(TREE_LIBRARY, TREE_EAST, TREE_LOT_A), only(assets=[TREE_FOUNTAIN])],
         [remove(TREE_FOUNTAIN)]),
    case("removal", "direct", "parked_cars_lot_b", PARENT,
         "Remove all the parked cars from lot B.",
         [gone(CAR_1, CAR_2), only(assets=list(PARKED))],
         [remove(*PARKED)]),  # the SUV is a car too, but a reader may keep it: both pass
    case("removal", "direct", "trash_bin", MANAGER,
         "delete the trash bin",
         [gone(BIN), only(assets=[BIN])],
         [remove(BIN)]),
    case("removal", "direct", "hydrant_and_stop_sign", TRANSLATED,
         "Please remove the fire hydrant, and remove also the stop sign.",
         [gone(HYDRANT, STOP_SIGN), only(assets=[HYDRANT, STOP_SIGN])],
         [remove(HYDRANT), remove(STOP_SIGN)]),
    case("removal", "direct", "lamp_nearest_bus_stop", DICTATION,
         "remove the street light nearest the bus stop",
         [gone(LAMP_BUS_STOP), count(LAMP, 11, 11), only(assets=[LAMP_BUS_STOP])],
         [remove(category=LAMP, near=BUS_STOP, count=1)]),
    impossible("removal", "direct", "despawn_ego", MODDER,
               "despawn ego",
               [remove(EGO)]),
    # indirect
    case("removal", "indirect", "tree_blocks_sightline", SCOUT,
         "The tree between the bus stop and the Library blocks my sightline to the Library doors. Lose it.",
         [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
         [remove(TREE_LIBRARY)]),
    case("removal", "indirect", "bin_hides_cars", PARENT,
         "Cars keep getting hidden behind that wheelie bin at the bus stop so the kids can't see them coming. "
         "Can you get rid of it?",
         [gone(BIN), only(assets=[BIN])],
         [remove(BIN)]),
    case("removal", "indirect", "decommission_north_west_lamps", ENGINEER,
         "Decommission the luminaires on the north side of Main Street west of Campus Drive.",
         [gone(*NORTH_WEST_LAMPS), count(LAMP, 9, 9), only(assets=list(NORTH_WEST_LAMPS))],
         [remove(*NORTH_WEST_LAMPS)]),
    case("removal", "indirect", "uncontrolled_intersection", ENGINEER,
         "We're testing an uncontrolled intersection, so take the signal control out of the crossroads.",
         [gone(LIGHT_SW, LIGHT_NE), only(assets=[LIGHT_SW, LIGHT_NE])],
         [remove(LIGHT_SW, LIGHT_NE)]),
    case("removal", "indirect", "suv_distracts", INSTRUCTOR,
         "My learner keeps staring at that big boxy thing parked in lot B. Take it away, leave the two saloons.",
         [gone(SUV), kept(CAR_1, CAR_2), only(assets=[SUV])],
         [remove(SUV)]),
    case("removal", "indirect", "sign_not_in_matrix", AUDITOR,
         "That sign isn't in the approved test matrix; strip it back out.",
         [count(PED_SIGN, 0, 0), only(PED_SIGN)],
         [remove(category=PED_SIGN)],
         setup=[turn("Add a pedestrian crossing sign next to the west crosswalk.",
                     add(PED_SIGN, where=loc("at", WEST_CROSSWALK)))]),
    case("removal", "indirect", "demo_lot_b_empty", MANAGER,
         "lot B has to be empty for the demo",
         [gone(*PARKED), only(assets=list(PARKED))],
         [remove(*PARKED)]),
    case("removal", "indirect", "lamp_by_parking_a", TRANSLATED,
         "The lamp which stands most near to the entrance of the parking A, please to remove it.",
         [gone(LAMP_LOT_A), count(LAMP, 11, 11), only(assets=[LAMP_LOT_A])],
         [remove(LAMP_LOT_A)]),
    impossible("removal", "indirect", "ugly_library", SCOUT,
               "The Library building is ruining every angle. Can we just get rid of it?",
               [remove("Library")]),
    # vague
    case("removal", "vague", "bus_stop_clutter", MANAGER,
         "too much clutter at the bus stop, clean it up",
         [delta([BENCH_KIND, BIN_KIND, LAMP, TREE], -4, -1),
          only(assets=[BENCH, BIN, LAMP_BUS_STOP, TREE_LIBRARY])],
         [remove(BENCH, BIN)]),
    case("removal", "vague", "fewer_lamps", SCOUT,
         "Can we lose some of the street lights? They're all over my shot.",
         [delta(LAMP, -12, -1), only(LAMP)],
         [remove(category=LAMP, near=EGO, count=3)]),
    case("removal", "vague", "nuke_the_roadblock", MODDER,
         "nuke all that",
         [count([CONE, BARRIER], 0, 0), only(CONE, BARRIER)],
         [remove(category=CONE), remove(category=BARRIER)],
         setup=[turn("spawn a roadblock: 4 cones and 2 barriers 25m ahead of the ego",
                     add(CONE, 4, ahead_of(EGO, 25)), add(BARRIER, 2, ahead_of(EGO, 32)), planned=True)]),
    case("removal", "vague", "fewer_parked_cars", PARENT,
         "Fewer parked cars, please, it's hard to see the children between them.",
         [delta(CARS, -3, -1), only(*CARS)],
         [remove(CAR_2)]),
    case("removal", "vague", "clear_the_road", INSTRUCTOR,
         "Clear the road for my learner.",
         [count([RUBBLE, CONE], 0, 0), only(RUBBLE, CONE)],
         [remove(category=RUBBLE), remove(category=CONE)],
         setup=[_ROADWORKS_AHEAD]),
    case("removal", "vague", "temporary_traffic_control", ENGINEER,
         "Remove the temporary traffic control.",
         [count([CONE, WORK_SIGN], 0, 0), only(CONE, WORK_SIGN)],
         [remove(category=CONE), remove(category=WORK_SIGN)],
         setup=[turn("Put a construction sign and six cones along the westbound lane by the JTEKT drop-off.",
                     add(WORK_SIGN, where=loc("at", JTEKT)),
                     arrange(CONE, "lane_edge", loc("at", JTEKT, lane=WESTBOUND), count=6))]),
    case("removal", "vague", "drop_extra_actor", AUDITOR,
         "Drop the extra actor; the pedestrian stays.",
         [count(BUS, 0, 0), count(PERSON, 1, 1), only(BUS)],
         [remove(category=BUS)],
         setup=[turn("Add a pedestrian at the north crosswalk and a bus driving westbound.",
                     add(PERSON, where=loc("at", NORTH_CROSSWALK)), add(BUS, behaviour=drive(lane=WESTBOUND)),
                     planned=True)]),
    case("removal", "vague", "too_much_green", TRANSLATED,
         "Remove some trees, it is too much green for the picture.",
         [delta(TREE, -4, -1), only(TREE)],
         [remove(TREE_FOUNTAIN, TREE_EAST)]),
    case("removal", "vague", "get_rid_of_that", DICTATION,
         "actually get rid of that",
         [count(TRUCK, 0, 0), only(TRUCK)],
         [remove(category=TRUCK)],
         setup=[turn("add a delivery truck at the JTEKT entrance", add(TRUCK, where=loc("at", JTEKT)), planned=True)]),
    # erroneous
    case("removal", "erroneous", "rm_rf_cones", MODDER,
         "rm -rf teh cones",
         [count(CONE, 0, 0), only(CONE)],
         [remove(category=CONE)],
         setup=[_CONES_AT_LOT_A]),
    case("removal", "erroneous", "bench_of_bus_stop", TRANSLATED,
         "Please remove the bench of the bus stop place.",
         [gone(BENCH), only(assets=[BENCH])],
         [remove(BENCH)]),
    case("removal", "erroneous", "fire_hide_rent", DICTATION,
         "remove the fire hide rent",
         [gone(HYDRANT), only(assets=[HYDRANT])],
         [remove(HYDRANT)]),
    case("removal", "erroneous", "both_trafic_lights", MANAGER,
         "delte both trafic lights",
         [gone(LIGHT_SW, LIGHT_NE), only(assets=[LIGHT_SW, LIGHT_NE])],
         [remove(category=SIGNAL)]),
    case("removal", "erroneous", "suv_carpark", PARENT,
         "remvoe the suv from the carpark pls",
         [gone(SUV), only(assets=[SUV])],
         [remove(SUV)]),
    case("removal", "erroneous", "tree_by_libary", INSTRUCTOR,
         "take awya the tree by the libary",
         [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
         [remove(TREE_LIBRARY)]),
    case("removal", "erroneous", "stop_sing", ENGINEER,
         "remove teh stop sing at the west crosswalk",
         [gone(STOP_SIGN), only(assets=[STOP_SIGN])],
         [remove(STOP_SIGN)]),
    case("removal", "erroneous", "keep_the_suv", AUDITOR,
         "remvoe the two passanger cars but keep the SUV",
         [gone(CAR_1, CAR_2), kept(SUV), only(assets=[CAR_1, CAR_2])],
         [remove(category=CAR)]),
    impossible("removal", "erroneous", "delete_the_bus", MANAGER,
               "delet the bus its in the way",
               [remove(category=BUS)]),
]


# --- Positioning ---------------------------------------------------------------------------------
POSITIONING_CASES: list[Json] = [
    # direct
    case("positioning", "direct", "suv_in_front_of_library", INSTRUCTOR,
         "Put the SUV in front of the Library entrance.",
         [near(LIBRARY, 10, asset=SUV), relative("in_front_of", LIBRARY, asset=SUV, max_distance=12), only(assets=[SUV])],
         [place(SUV, loc("in_front_of", LIBRARY))]),
    case("positioning", "direct", "tp_bench_fountain", MODDER,
         "tp bench_1 to the fountain",
         [near(FOUNTAIN, 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", FOUNTAIN))]),
    case("positioning", "direct", "stop_sign_north_crosswalk", ENGINEER,
         "Relocate stop_sign_1 to the sidewalk at the north crosswalk.",
         [near(NORTH_CROSSWALK, 8, asset=STOP_SIGN), on(["sidewalk", "ground"], asset=STOP_SIGN), only(assets=[STOP_SIGN])],
         [place(STOP_SIGN, loc("on_sidewalk", NORTH_CROSSWALK))]),
    case("positioning", "direct", "car_2_jtekt_dropoff", SCOUT,
         "Move passenger_car_2 to the JTEKT drop-off.",
         [near(JTEKT, 10, asset=CAR_2), only(assets=[CAR_2])],
         [place(CAR_2, loc("at", JTEKT))]),
    case("positioning", "direct", "bench_to_union", PARENT,
         "Put the bench next to the Student Union entrance.",
         [near(UNION, 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", UNION))]),
    case("positioning", "direct", "bin_lot_a_entrance", MANAGER,
         "no. trash bin to lot A entrance",
         [near(LOT_A_ENTRANCE, 8, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", LOT_A_ENTRANCE))],
         setup=[turn("bin to the fountain", place(BIN, loc("at", FOUNTAIN)))]),
    case("positioning", "direct", "hydrant_engineering", TRANSLATED,
         "Please place the fire hydrant near to the entrance of Engineering Hall.",
         [near(ENGINEERING, 10, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", ENGINEERING))]),
    case("positioning", "direct", "ego_at_east_gate", AUDITOR,
         "Position the ego vehicle at the east gate, in the westbound lane, so the run starts there.",
         [near(EAST_GATE, 15, asset=EGO), in_lane(WESTBOUND, asset=EGO, aligned=True), only(assets=[EGO])],
         [place(EGO, loc("in_lane", EAST_GATE, lane=WESTBOUND))]),
    case("positioning", "direct", "car_1_in_front_of_suv", DICTATION,
         "put passenger car one right in front of the suv",
         [relative("in_front_of", SUV, asset=CAR_1, max_distance=12, tolerance_deg=40), moved(CAR_1, 3),
          only(assets=[CAR_1])],
         [place(CAR_1, loc("in_front_of", SUV))]),
    # indirect
    case("positioning", "indirect", "suv_in_gate_shot", SCOUT,
         "I want the SUV sitting in the background of the east gate shot.",
         [near(EAST_GATE, 15, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("at", EAST_GATE))]),
    case("positioning", "indirect", "bench_back_from_kerb", PARENT,
         "The bench is too close to the road where the little ones wait. Move it back onto the grass behind the bus stop.",
         [relative("behind", BUS_STOP, asset=BENCH, max_distance=8), on(["ground"], asset=BENCH), moved(BENCH, 0.5),
          only(assets=[BENCH])],
         [place(BENCH, loc("behind", BUS_STOP))]),
    case("positioning", "indirect", "stop_sign_wrong_approach", ENGINEER,
         "The R1-1 is posted on the wrong approach. It should govern westbound traffic entering the crossroads "
         "from the east, so put it on the right-hand side for them, just before the east crosswalk.",
         [near(None, 6, asset=STOP_SIGN, point=(13.5, 5.5)), on(["sidewalk", "ground"], asset=STOP_SIGN),
          only(assets=[STOP_SIGN])],
         [place(STOP_SIGN, xy(13.5, 5.5))]),
    case("positioning", "indirect", "bus_belongs_at_stop", AUDITOR,
         "Correction for the record: that bus belongs at the bus stop, not the gate.",
         [near(BUS_STOP, 12, asset="bus_1"), only(assets=["bus_1"])],
         [place("bus_1", loc("at", BUS_STOP))],
         setup=[turn("Add a bus at the east gate.", add(BUS, where=loc("at", EAST_GATE)))]),
    case("positioning", "indirect", "start_from_map_edge", MODDER,
         "yo put the ego at the main gate so the run starts from the edge of the map",
         [near(MAIN_GATE, 12, asset=EGO), in_lane(None, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("in_lane", MAIN_GATE, lane=EASTBOUND))]),
    case("positioning", "indirect", "hydrant_occludes_crosswalk", AUDITOR,
         "For the occlusion scenario the hydrant has to stand right beside the west crosswalk, where it can hide "
         "someone about to step out.",
         [near(WEST_CROSSWALK, 8, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("on_sidewalk", WEST_CROSSWALK))]),
    case("positioning", "indirect", "bin_by_library_door", MANAGER,
         "bin's in a dumb spot. needs to be by the library door",
         [near(LIBRARY, 8, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", LIBRARY))]),
    case("positioning", "indirect", "bicycle_not_at_gate", TRANSLATED,
         "The bicycle which we added, it must stand in front of the Engineering Hall, not at the gate.",
         [near(ENGINEERING, 10, BIKE, scope="all"), count(BIKE, 1, 1), only(BIKE)],
         [place("bicycle_1", loc("in_front_of", ENGINEERING))],
         setup=[turn("Please add one bicycle at the main gate.", add(BIKE, where=loc("at", MAIN_GATE)))]),
    case("positioning", "indirect", "person_to_bus_stop", DICTATION,
         "actually put that person on the sidewalk by the bus stop instead",
         [near(BUS_STOP, 8, PERSON, scope="all"), on(["sidewalk"], PERSON, scope="all"), count(PERSON, 1, 1),
          only(PERSON)],
         [place("pedestrian_1", loc("on_sidewalk", BUS_STOP))],
         setup=[turn("add a person standing by the fountain", add(PERSON, where=loc("at", FOUNTAIN)), planned=True)]),
    # vague
    case("positioning", "vague", "one_car_onto_main_street", SCOUT,
         "Take one of the parked cars out of lot B and leave it somewhere along Main Street, anywhere's fine.",
         [near(EASTBOUND, 4, CARS), delta(CARS, 0, 0), only(*CARS)],
         [place(SUV, loc("in_lane", LOT_B_ENTRANCE, lane=EASTBOUND))]),
    case("positioning", "vague", "lesson_starts_at_library", INSTRUCTOR,
         "Put our car somewhere near the Library so the lesson starts there.",
         [near(LIBRARY, 15, asset=EGO), moved(EGO, 3), only(assets=[EGO])],
         [place(EGO, loc("in_lane", LIBRARY, lane=EASTBOUND))]),
    case("positioning", "vague", "hydrant_next_to_it", MODDER,
         "now tp the hydrant next to it",
         [near("bench_2", 6, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("next_to", "bench_2"))],
         setup=[turn("spawn a bench at the lot B entrance", add(BENCH_KIND, where=loc("at", LOT_B_ENTRANCE)),
                     planned=True)]),
    case("positioning", "vague", "bench_towards_gate", PARENT,
         "Could the bench go over towards the main gate? That's where the kids actually wait.",
         [near(MAIN_GATE, 12, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", MAIN_GATE))]),
    case("positioning", "vague", "hydrant_jtekt_frontage", ENGINEER,
         "Put the hydrant somewhere on the JTEKT frontage.",
         [near(JTEKT, 12, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", JTEKT))]),
    case("positioning", "vague", "suv_other_lot", AUDITOR,
         "Move the SUV somewhere it can't be confused with the ego. The other car park, say.",
         [near(LOT_A, 1, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("at", LOT_A))]),
    case("positioning", "vague", "bench_lot_a_wherever", MANAGER,
         "bench -> lot A, wherever",
         [near(LOT_A, 2, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", LOT_A))]),
    case("positioning", "vague", "car_near_gate", TRANSLATED,
         "The car, put it to other place, near of the gate.",
         [delta(CARS, 0, 0), only(*CARS)],
         [place(CAR_1, loc("at", MAIN_GATE))],
         alternatives=[[near(MAIN_GATE, 15, CARS)], [near(EAST_GATE, 15, CARS)]]),
    impossible("positioning", "vague", "move_the_fountain", SCOUT,
               "Honestly the fountain would look better next to the Library. Can you shift it over there?",
               [place("fountain", loc("at", LIBRARY))]),
    # erroneous
    case("positioning", "erroneous", "tp_suv_lota", MODDER,
         "tp suv_1 lotA",
         [near(LOT_A, 1, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("at", LOT_A))]),
    case("positioning", "erroneous", "bench_buy_fountain", DICTATION,
         "put the bench buy the fountain",
         [near(FOUNTAIN, 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", FOUNTAIN))]),
    case("positioning", "erroneous", "bench_and_bin_fountian", MANAGER,
         "mvoe the bench to the fountian and the bin nxt to it",
         [near(FOUNTAIN, 8, asset=BENCH), near(BENCH, 5, asset=BIN), only(assets=[BENCH, BIN])],
         [place(BENCH, loc("at", FOUNTAIN)), place(BIN, loc("next_to", BENCH))]),
    case("positioning", "erroneous", "suv_infront_union", PARENT,
         "plz put the suv infront of the studnet union",
         [near(UNION, 10, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("in_front_of", UNION))]),
    case("positioning", "erroneous", "ego_lot_b_entrence", INSTRUCTOR,
         "palce the ego at lot B entrence",
         [near(LOT_B_ENTRANCE, 8, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("at", LOT_B_ENTRANCE))]),
    case("positioning", "erroneous", "bin_noth_crosswalk", ENGINEER,
         "relocte the trash recepticle to the noth crosswalk",
         [near(NORTH_CROSSWALK, 8, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("on_sidewalk", NORTH_CROSSWALK))]),
    case("positioning", "erroneous", "hydrant_coordinates", AUDITOR,
         "Posiiton the hydrant at x=20 y=-8",
         [near(None, 1, asset=HYDRANT, point=(20.0, -8.0)), only(assets=[HYDRANT])],
         [place(HYDRANT, xy(20, -8))]),
    impossible("positioning", "erroneous", "suv_inside_union", TRANSLATED,
               "Please to put the SUV inside of the Student Union building, in the middle.",
               [place(SUV, xy(42.5, -63.5))]),
    impossible("positioning", "erroneous", "bench_off_map", MODDER,
               "tp bench_1 300 0",
               [place(BENCH, xy(300, 0))]),
]


# --- Moving: shifts, turns, behaviours and timed manoeuvres --------------------------------------
def ego_speed(lo: float, hi: float) -> list[list[Json]]:
    """Two fair readings of a new ego speed: its lane behaviour at that speed, or a timed speed change."""
    return [[does("drive_lane", asset=EGO, speed_min=lo, speed_max=hi)], [event_played(EGO, "change_speed", 2)]]


MOVING_CASES: list[Json] = [
    # direct
    case("moving", "direct", "ego_forward_20", INSTRUCTOR,
         "Move the ego 20 metres forward.",
         [moved(EGO, 18, 22, "forward"), only(assets=[EGO])],
         [move(EGO, forward=20)]),
    case("moving", "direct", "suv_5m_north", MODDER,
         "move suv_1 5m north",
         [moved(SUV, 4.5, 5.5, "forward"), only(assets=[SUV])],
         [move(SUV, north=5)]),
    case("moving", "direct", "ego_30_kmh", ENGINEER,
         "Set the ego's speed to 30 km/h.",
         [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=8.33, lane=EASTBOUND)],
         alternatives=ego_speed(8.0, 8.7)),
    case("moving", "direct", "car_1_turn_around", SCOUT,
         "Turn passenger_car_1 around, 180 degrees, so it faces the other way.",
         [moved(CAR_1, 0, 1, turn_min=170), only(assets=[CAR_1])],
         [move(CAR_1, turn_deg=180)]),
    case("moving", "direct", "suv_drives_northbound", PARENT,
         "Make the SUV drive up Campus Drive in the northbound lane.",
         [does("drive_lane", asset=SUV, lane=NORTHBOUND), only(assets=[SUV])],
         [behave(SUV, "drive_lane", lane=NORTHBOUND)]),
    case("moving", "direct", "speed_that_one_up", MANAGER,
         "speed that one up to 12 m/s",
         [only(CAR)],
         [behave("passenger_car_3", "drive_lane", speed=12, lane=EASTBOUND)],
         setup=[turn("add a car driving in the eastbound lane",
                     add(CAR, where=loc("in_lane", EASTBOUND), behaviour=drive(lane=EASTBOUND)), planned=True)],
         alternatives=[[does("drive_lane", CAR, scope="touched", speed_min=11.5, speed_max=12.5)],
                       [event_played(CAR, "change_speed", 2)]]),
    case("moving", "direct", "ego_stop_at_5s", AUDITOR,
         "Command the ego to come to a stop at t = 5 s.",
         [event_played(EGO, "stop", 7), only()],
         [manoeuvre(EGO, "stop", 5)]),
    case("moving", "direct", "bench_two_metres_west", DICTATION,
         "move the bench two meters west",
         [moved(BENCH, 1.5, 2.5, "forward"), only(assets=[BENCH])],
         [move(BENCH, east=-2)]),
    impossible("moving", "direct", "ego_250_kmh", MANAGER,
               "ego to 250 km/h",
               [behave(EGO, "drive_lane", speed=69.4, lane=EASTBOUND)]),
    # indirect
    case("moving", "indirect", "emergency_stop_drill", INSTRUCTOR,
         "My learner needs to practise an emergency stop, so have the ego brake hard about ten seconds into the drive.",
         [event_played(EGO, "stop", 12), only()],
         [manoeuvre(EGO, "stop", 10, rate=6)]),
    case("moving", "indirect", "child_darts_out", PARENT,
         "I want to see what happens if a child runs out in front of our car. Make that child dart across the road.",
         [does(["jaywalk", "cross_road"], PERSON, scope="all", crosses_lane=EASTBOUND), count(PERSON, 1, 1),
          only(PERSON)],
         [behave("pedestrian_1", "jaywalk")],
         setup=[turn("Add a child standing at the bus stop.", add(PERSON, where=loc("at", BUS_STOP)), planned=True)]),
    case("moving", "indirect", "ego_15_mph", ENGINEER,
         "Reduce the ego's operating speed to 15 mph.",
         [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=6.7, lane=EASTBOUND)],
         alternatives=ego_speed(6.4, 7.0)),
    case("moving", "indirect", "suv_tracking_shot", SCOUT,
         "For the tracking shot the SUV needs to be driving down Main Street, heading west.",
         [does("drive_lane", asset=SUV, lane=WESTBOUND), only(assets=[SUV])],
         [behave(SUV, "drive_lane", lane=WESTBOUND)]),
    case("moving", "indirect", "suv_clear_bay_line", AUDITOR,
         "The SUV is over the bay line. Nudge it back ten feet so it clears.",
         [moved(SUV, 2.5, 3.5, "backward"), only(assets=[SUV])],
         [move(SUV, forward=-3)]),
    case("moving", "indirect", "lead_car_brakes", INSTRUCTOR,
         "Now make it brake to a halt about eight seconds in, so my learner has to react.",
         [event_played(CAR, "stop", 10), only()],
         [manoeuvre("passenger_car_3", "stop", 8)],
         setup=[turn("Add a car driving in our lane, a little way ahead of us.",
                     add(CAR, where=ahead_of(EGO, 25), behaviour=drive(lane=EASTBOUND)), planned=True)]),
    case("moving", "indirect", "bus_stops_at_crossroads", TRANSLATED,
         "The bus which we added, it must stop when it arrives at the crossroads.",
         [event_played(BUS, "stop", 25), only()],
         [call("add_event", actor="bus_1", manoeuvre={"kind": "stop"}, when={"kind": "reach", "actor": "bus_1",
                                                                          "place": JUNCTION})],
         setup=[turn("Please add one bus which drives on Main Street to the west, from the east gate.",
                     add(BUS, where=loc("in_lane", EAST_GATE, lane=WESTBOUND), behaviour=drive(lane=WESTBOUND)))]),
    case("moving", "indirect", "ego_other_way", DICTATION,
         "the ego should be going the other way down main street",
         [does("drive_lane", asset=EGO, lane=WESTBOUND), only(assets=[EGO])],
         [behave(EGO, "drive_lane", lane=WESTBOUND)]),
    impossible("moving", "indirect", "possessed_tree", MODDER,
               "make tree_2 drive in circles like its possessed",
               [behave(TREE_FOUNTAIN, "circle")]),
    # vague
    case("moving", "vague", "ego_bit_faster", INSTRUCTOR,
         "Make the ego go a bit faster.",
         [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=7, lane=EASTBOUND)],
         alternatives=ego_speed(5.5, 12.0)),
    case("moving", "vague", "suv_moving", MODDER,
         "get the suv moving",
         [does(["drive_lane", "circle", "follow_path"], asset=SUV), only(assets=[SUV])],
         [behave(SUV, "circle")]),
    case("moving", "vague", "background_motion", SCOUT,
         "Give me some motion in the background: have one of the parked cars pull out and drive off.",
         [does(["drive_lane", "circle", "follow_path"], CARS, scope="touched"), only(*CARS)],
         [behave(CAR_2, "drive_lane", lane=EASTBOUND)]),
    case("moving", "vague", "slow_for_school", PARENT,
         "Slow our car down, it's going far too fast for somewhere children walk.",
         [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=3, lane=EASTBOUND)],
         alternatives=ego_speed(0.1, 4.5)),
    case("moving", "vague", "hydrant_further_from_crosswalk", ENGINEER,
         "Shift the hydrant a little further from the east crosswalk.",
         [moved(HYDRANT, 0.5, 8, "forward"), only(assets=[HYDRANT])],
         [move(HYDRANT, east=2)]),
    case("moving", "vague", "back_suv_up", AUDITOR,
         "Back the SUV up a little.",
         [only(assets=[SUV])],
         [move(SUV, forward=-2)],
         alternatives=[[moved(SUV, 0.5, 6, "backward")], [event_played(SUV, "reverse", 2)]]),
    case("moving", "vague", "spin_bench", MANAGER,
         "spin the bench round",
         [moved(BENCH, 0, 0.5, turn_min=45), only(assets=[BENCH])],
         [move(BENCH, turn_deg=180)]),
    case("moving", "vague", "person_walks_over_street", TRANSLATED,
         "Make that the person walks over the street.",
         [count(PERSON, 1, 1), only(PERSON)],
         [behave("pedestrian_1", "cross_road")],
         setup=[turn("Please add one person at the north crosswalk.", add(PERSON, where=loc("at", NORTH_CROSSWALK)))],
         alternatives=[[does(["cross_road", "jaywalk"], PERSON)], [event_played(PERSON, "cross_road", 5)]]),
    case("moving", "vague", "car_up_a_bit", DICTATION,
         "move our car up a bit",
         [moved(EGO, 1, 20, "forward"), only(assets=[EGO])],
         [move(EGO, forward=5)]),
    # erroneous
    case("moving", "erroneous", "suv_10m_foward", MODDER,
         "mvoe suv_1 10m foward",
         [moved(SUV, 9, 11, "forward"), only(assets=[SUV])],
         [move(SUV, forward=10)]),
    case("moving", "erroneous", "bench_90_degree", TRANSLATED,
         "Please to turn the bench for 90 degree.",
         [moved(BENCH, 0, 0.5, turn_min=80, turn_max=100), only(assets=[BENCH])],
         [move(BENCH, turn_deg=90)]),
    case("moving", "erroneous", "ego_break_ten_seconds", DICTATION,
         "make the ego break at ten seconds",
         [event_played(EGO, "stop", 12), only()],
         [manoeuvre(EGO, "stop", 10)]),
    case("moving", "erroneous", "car2_westbond_ego_8", MANAGER,
         "car2 drive westbond main st, ego to 8m/s",
         [does("drive_lane", asset=CAR_2, lane=WESTBOUND), only(assets=[CAR_2, EGO])],
         [behave(CAR_2, "drive_lane", lane=WESTBOUND), behave(EGO, "drive_lane", speed=8, lane=EASTBOUND)],
         alternatives=ego_speed(7.8, 8.2)),
    case("moving", "erroneous", "suv_slowley_circels", PARENT,
         "can the suv go round the lot slowley in circels",
         [does("circle", asset=SUV, speed_max=3.0), only(assets=[SUV])],
         [behave(SUV, "circle", speed=1.5)]),
    case("moving", "erroneous", "stop_sign_3m_west", ENGINEER,
         "shif the stop sign 3m west",
         [moved(STOP_SIGN, 2.5, 3.5, "backward"), only(assets=[STOP_SIGN])],
         [move(STOP_SIGN, east=-3)]),
    case("moving", "erroneous", "pedestrain_accross", SCOUT,
         "mkae the pedestrain walk accross at the west crosswalk",
         [count(PERSON, 1, 1), only(PERSON)],
         [behave("pedestrian_1", "cross_road")],
         setup=[turn("add a pedestrian by the west crosswalk", add(PERSON, where=loc("at", WEST_CROSSWALK)),
                     planned=True)],
         alternatives=[[does(["cross_road", "jaywalk"], PERSON, crosses_lane=EASTBOUND)],
                       [event_played(PERSON, "cross_road", 5)]]),
    case("moving", "erroneous", "reverse_suv_4m", AUDITOR,
         "reverse teh SUV 4 m",
         [only(assets=[SUV])],
         [move(SUV, forward=-4)],
         alternatives=[[moved(SUV, 3, 5, "backward")], [event_played(SUV, "reverse", 2)]]),
    impossible("moving", "erroneous", "move_the_library", DICTATION,
               "move the library fifty meters north its in the weigh",
               [move("Library", north=50)]),
]


# --- Arrangement: several new assets laid out together -------------------------------------------
ARRANGEMENT_CASES: list[Json] = [
    # direct
    case("arrangement", "direct", "cone_taper_eastbound", ENGINEER,
         "Place a line of 6 traffic cones along the right edge of the eastbound lane, starting 20 m ahead of the ego.",
         [delta(CONE, 6, 6), layout("line", CONE, 6, tolerance=1.0), in_lane(EASTBOUND, CONE, scope="added"),
          relative("in_front_of", EGO, CONE, max_distance=60, tolerance_deg=15, every=True), only(CONE)],
         [arrange(CONE, "lane_edge", ahead_of(EGO, 20, lane=EASTBOUND), count=6)]),
    case("arrangement", "direct", "bollard_ring_tree_2", MODDER,
         "spawn a ring of 8 bollards around tree_2",
         [delta(BOLLARD, 8, 8), layout("ring", BOLLARD, 8, around=TREE_FOUNTAIN), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", TREE_FOUNTAIN), count=8)]),
    case("arrangement", "direct", "parking_row_lot_a", INSTRUCTOR,
         "Put four cars in a parking row in lot A for reverse-parking practice.",
         [delta(CARS, 4, 4), layout("line", CARS, 4, tolerance=1.0), near(LOT_A, 1, CARS, every=True), only(*CARS)],
         [arrange(CAR, "parking_row", loc("at", LOT_A), count=4)]),
    case("arrangement", "direct", "five_extras_in_line", SCOUT,
         "Arrange five pedestrians in a line on the sidewalk by the bus stop.",
         [delta(PERSON, 5, 5), layout("line", PERSON, 5, tolerance=1.0), near(BUS_STOP, 12, PERSON, every=True),
          only(PERSON)],
         [arrange(PERSON, "line", loc("on_sidewalk", BUS_STOP), count=5)]),
    case("arrangement", "direct", "bollards_in_front_of_library", PARENT,
         "Put a line of five bollards in front of the Library entrance.",
         [delta(BOLLARD, 5, 5), layout("line", BOLLARD, 5, tolerance=1.0), near(LIBRARY, 10, BOLLARD, every=True),
          only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("in_front_of", LIBRARY), count=5)]),
    impossible("arrangement", "direct", "grid_of_150_cones", MANAGER,
               "grid of 150 cones in lot B",
               [arrange(CONE, "grid", loc("at", LOT_B), count=150, columns=15)]),
    case("arrangement", "direct", "ring_round_rubble", TRANSLATED,
         "Please arrange a ring of six traffic cones around the rubble.",
         [delta(CONE, 6, 6), layout("ring", CONE, 6, around="cement_rubble_1"), only(CONE)],
         [arrange(CONE, "ring", loc("at", "cement_rubble_1"), count=6)],
         setup=[turn("Please put one pile of rubble in the middle of the crossroads.",
                     add(RUBBLE, where=loc("at", JUNCTION)))]),
    case("arrangement", "direct", "barriers_across_eastbound", AUDITOR,
         "Lay out three road barriers in a line across the road, 30 m ahead of the ego.",
         [delta(BARRIER, 3, 3), layout("line", BARRIER, 3, tolerance=1.0),
          near(None, 8, BARRIER, point=(-30.0, 0.0), every=True), only(BARRIER)],
         [arrange(BARRIER, "line", loc("in_front_of", EGO, distance=30), count=3)]),
    case("arrangement", "direct", "three_cones_row_and_sign", DICTATION,
         "put three cones in a row at the lot a entrance and a road work sign next to them",
         [delta(CONE, 3, 3), layout("line", CONE, 3, tolerance=1.0), near(LOT_A_ENTRANCE, 10, CONE, every=True),
          delta(WORK_SIGN, 1, 1), near(LOT_A_ENTRANCE, 12, WORK_SIGN), only(CONE, WORK_SIGN)],
         [arrange(CONE, "line", loc("at", LOT_A_ENTRANCE), count=3), add(WORK_SIGN, where=loc("at", LOT_A_ENTRANCE))]),
    # indirect
    case("arrangement", "indirect", "wb_lane_closure_taper", ENGINEER,
         "Set up a lane-closure taper on the westbound lane by the JTEKT drop-off, eight channelizers.",
         [delta(CONE, 8, 8), layout("line", CONE, 8, tolerance=1.5), in_lane(WESTBOUND, CONE, scope="added"),
          near(JTEKT, 25, CONE, every=True), only(CONE)],
         [arrange(CONE, "lane_edge", loc("at", JTEKT, lane=WESTBOUND), count=8)]),
    case("arrangement", "indirect", "posts_at_union_pickup", PARENT,
         "The pick-up spot outside the Student Union doors needs a row of posts between it and the car park.",
         [delta(BOLLARD, 3, 12), layout("line", BOLLARD, 3, tolerance=1.0), near(UNION, 10, BOLLARD, every=True),
          only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("in_front_of", UNION), count=4)]),
    case("arrangement", "indirect", "slalom_lot_a", INSTRUCTOR,
         "Set up a slalom for my learner in lot A: cones in a straight line, about five metres apart.",
         [delta(CONE, 3, 12), layout("line", CONE, 3, tolerance=1.0, spacing_min=4.0, spacing_max=6.0),
          near(LOT_A, 0.5, CONE, every=True), only(CONE)],
         [arrange(CONE, "line", loc("at", LOT_A), count=5, spacing=5)]),
    case("arrangement", "indirect", "busy_lot_b", SCOUT,
         "Background dressing: I want lot B to look busy. Fill the empty end with a row of parked cars.",
         [delta(CARS, 3, 10), layout("line", CARS, 3, tolerance=1.0), near(LOT_B, 0.5, CARS, every=True), only(*CARS)],
         [arrange(CAR, "parking_row", loc("at", LOT_B), count=5)]),
    case("arrangement", "indirect", "fence_off_fountain", MODDER,
         "fence off the fountain with posts so nobody can walk in",
         [delta(BOLLARD, 4, 40), layout("ring", BOLLARD, 4, around=FOUNTAIN), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=10)]),
    case("arrangement", "indirect", "work_zone_hazard", AUDITOR,
         "Create the work-zone hazard: a pile of rubble where lot B's driveway meets Main Street, ringed by cones.",
         [delta(RUBBLE, 1, 1), near(LOT_B_ENTRANCE, 6, RUBBLE), layout("ring", CONE, 4, around="cement_rubble_1"),
          only(RUBBLE, CONE)],
         [add(RUBBLE, where=loc("at", LOT_B_ENTRANCE)), arrange(CONE, "ring", loc("at", "cement_rubble_1"), count=6)]),
    case("arrangement", "indirect", "bike_rack_lot_a", MANAGER,
         "lot A needs a bike rack. 6 bikes side by side",
         [delta(BIKE, 6, 6), layout("line", BIKE, 6, tolerance=1.0), near(LOT_A, 2, BIKE, every=True), only(BIKE)],
         [arrange(BIKE, "parking_row", loc("at", LOT_A), count=6)]),
    case("arrangement", "indirect", "cones_from_east_gate", TRANSLATED,
         "We wish the cones standing in one row along the side of the westbound lane, beginning from the east gate, ten pieces.",
         [delta(CONE, 10, 10), layout("line", CONE, 10, tolerance=1.5), in_lane(WESTBOUND, CONE, scope="added"),
          near(EAST_GATE, 40, CONE, every=True), only(CONE)],
         [arrange(CONE, "lane_edge", loc("at", EAST_GATE, lane=WESTBOUND), count=10)]),
    case("arrangement", "indirect", "block_northbound", DICTATION,
         "block off the northbound lane with a line of barriers across it just past the north crosswalk",
         [delta(BARRIER, 2, 6), layout("line", BARRIER, 2, tolerance=1.0),
          near(None, 8, BARRIER, point=(1.75, 16.0), every=True), only(BARRIER)],
         [arrange(BARRIER, "line", xy(1.5, 16), count=2, heading_deg=0)]),
    # vague
    case("arrangement", "vague", "chase_ring_lot_b", SCOUT,
         "Some cones in a ring somewhere in lot B for the car-chase beat.",
         [delta(CONE, 4, 30), layout("ring", CONE, 4), near(LOT_B, 0.5, CONE, every=True), only(CONE)],
         [arrange(CONE, "ring", loc("at", LOT_B), count=8, radius=4)]),
    case("arrangement", "vague", "channelize_up_to_it", ENGINEER,
         "Now channelize the approach to it.",
         [delta([CONE, BOLLARD, BARRIER], 3, 30), layout("line", [CONE, BOLLARD, BARRIER], 3, tolerance=1.5),
          in_lane(EASTBOUND, [CONE, BOLLARD, BARRIER], scope="added"),
          near("construction_sign_1", 30, [CONE, BOLLARD, BARRIER], every=True), only(CONE, BOLLARD, BARRIER)],
         [arrange(CONE, "lane_edge", ahead_of(EGO, 12, lane=EASTBOUND), count=5)],
         setup=[turn("Post a construction sign in the eastbound lane 30 m ahead of the ego.",
                     add(WORK_SIGN, where=ahead_of(EGO, 30)), planned=True)]),
    case("arrangement", "vague", "posts_round_library_tree", PARENT,
         "Put a few posts round the tree by the Library so the kids don't run straight out from behind it.",
         [delta(BOLLARD, 3, 20), layout("ring", BOLLARD, 3, around=TREE_LIBRARY), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", TREE_LIBRARY), count=6)]),
    case("arrangement", "vague", "line_across_road", MODDER,
         "line of stuff across the road lol",
         [delta(OBSTACLES, 2, 20), layout("line", OBSTACLES, 2, tolerance=1.0), on(["drivable"], OBSTACLES, scope="added"),
          only(*OBSTACLES)],
         [arrange(BARRIER, "line", loc("in_front_of", EGO, distance=25), count=3)]),
    case("arrangement", "vague", "row_of_occluders", AUDITOR,
         "Add a row of parked vehicles somewhere, as occluders.",
         [delta(VEHICLES, 3, 20), layout("line", VEHICLES, 3, tolerance=1.0), only(*VEHICLES)],
         [arrange(CAR, "parking_row", loc("at", LOT_B), count=4)]),
    case("arrangement", "vague", "bunch_of_cones_grid", MANAGER,
         "cones. lot B. bunch of them in a grid",
         [delta(CONE, 4, 60), layout("cluster", CONE, 4, tolerance=10.0), near(LOT_B, 0.5, CONE, every=True), only(CONE)],
         [arrange(CONE, "grid", loc("at", LOT_B), count=12, columns=4)]),
    case("arrangement", "vague", "order_of_trees_east_gate", TRANSLATED,
         "Please to make some order of trees along the road near the east gate.",
         [delta(TREE, 3, 20), layout("line", TREE, 3, tolerance=1.5), near(EAST_GATE, 30, TREE, every=True),
          on(["ground", "sidewalk"], TREE, scope="added"), only(TREE)],
         [arrange(TREE, "line", loc("on_sidewalk", EAST_GATE), count=3, spacing=4)]),
    case("arrangement", "vague", "cones_around_that", DICTATION,
         "put some cones around that",
         [delta(CONE, 3, 20), layout("ring", CONE, 3, around="cement_rubble_1"), only(CONE)],
         [arrange(CONE, "ring", loc("at", "cement_rubble_1"), count=6)],
         setup=[turn("drop some rubble in the middle of lot b", add(RUBBLE, where=loc("at", LOT_B)), planned=True)]),
    impossible("arrangement", "vague", "hundred_metre_ring", ENGINEER,
               "Encircle the whole crossroads with cones at a 100 m radius.",
               [arrange(CONE, "ring", loc("at", JUNCTION), radius=100, count=60)]),
    # erroneous
    case("arrangement", "erroneous", "cone_rign_lot_b_entrence", MODDER,
         "spwan 6 cone in a rign around the lot b entrence",
         [delta(CONE, 6, 6), layout("ring", CONE, 6, around=LOT_B_ENTRANCE), only(CONE)],
         [arrange(CONE, "ring", loc("at", LOT_B_ENTRANCE), count=6)]),
    case("arrangement", "erroneous", "for_cones_westbound", DICTATION,
         "put for cones in a line along the westbound lane buy the east gate",
         [delta(CONE, 4, 4), layout("line", CONE, 4, tolerance=1.5), in_lane(WESTBOUND, CONE, scope="added"),
          near(EAST_GATE, 30, CONE, every=True), only(CONE)],
         [arrange(CONE, "lane_edge", loc("at", EAST_GATE, lane=WESTBOUND), count=4)]),
    case("arrangement", "erroneous", "parkng_row_lotb", MANAGER,
         "parkng row 5 cars lotB",
         [delta(CARS, 5, 5), layout("line", CARS, 5, tolerance=1.0), near(LOT_B, 0.5, CARS, every=True), only(*CARS)],
         [arrange(CAR, "parking_row", loc("at", LOT_B), count=5)]),
    case("arrangement", "erroneous", "circel_round_bench", PARENT,
         "cn u put a circel of bollards round the bench at the bus stop",
         [delta(BOLLARD, 3, 20), layout("ring", BOLLARD, 3, around=BENCH), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", BENCH), count=6)]),
    case("arrangement", "erroneous", "same_agian_tree_3", MODDER,
         "same agian round tree_3",
         [delta(BOLLARD, 8, 8), layout("ring", BOLLARD, 8, around=TREE_EAST), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", TREE_EAST), count=8)],
         setup=[turn("spawn a ring of 8 bollards around tree_2", arrange(BOLLARD, "ring", loc("at", TREE_FOUNTAIN), count=8))]),
    case("arrangement", "erroneous", "taper_allong_eastboud", ENGINEER,
         "instal 8 cones as a taper allong the eastboud lane edge near the libary",
         [delta(CONE, 8, 8), layout("line", CONE, 8, tolerance=1.5), in_lane(EASTBOUND, CONE, scope="added"),
          near(LIBRARY, 30, CONE, every=True), only(CONE)],
         [arrange(CONE, "lane_edge", loc("at", LIBRARY, lane=EASTBOUND), count=8)]),
    case("arrangement", "erroneous", "pedestrains_round_fountian", SCOUT,
         "ring of 5 pedestrains around the fountian",
         [delta(PERSON, 5, 5), layout("ring", PERSON, 5, around=FOUNTAIN), only(PERSON)],
         [arrange(PERSON, "ring", loc("at", FOUNTAIN), count=5)]),
    case("arrangement", "erroneous", "calibartion_grid", AUDITOR,
         "grid 3x3 of cones at lotA for the sensor calibartion",
         [delta(CONE, 9, 9), layout("cluster", CONE, 9, tolerance=6.0), near(LOT_A, 0.5, CONE, every=True), only(CONE)],
         [arrange(CONE, "grid", loc("at", LOT_A), count=9, columns=3)]),
    impossible("arrangement", "erroneous", "cones_in_engineering", TRANSLATED,
               "Please make a line of five cones inside of the Engineering Hall, in the hall.",
               [arrange(CONE, "line", xy(-40, 28), count=5, heading_deg=0)]),
]


# --- Appearance: time, weather, lights and the looks of assets -----------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case("appearance", "direct", "time_1930", SCOUT,
         "Set the time to 19:30.",
         [env(time_from="19:15", time_to="19:45", **CLEAR), only(env=True)],
         [clock("19:30")]),
    case("appearance", "direct", "weather_rain", MODDER,
         "weather rain",
         [env(weather=["rain"], **NOON), only(env=True)],
         [weather("rain")]),
    case("appearance", "direct", "fog_0_8", ENGINEER,
         "Set the weather to fog, intensity 0.8.",
         [env(weather=["fog"], intensity_min=0.75, intensity_max=0.85, **NOON), only(env=True)],
         [weather("fog", 0.8)]),
    case("appearance", "direct", "night_and_lamps", INSTRUCTOR,
         "Make it night-time and switch the street lights on.",
         [env(night=True, street_lights="on", **CLEAR), only(env=True)],
         [clock("night"), lighting(street_lights="on")]),
    case("appearance", "direct", "suv_yellow_instead", PARENT,
         "Actually, no. Paint the SUV yellow instead.",
         [looks("yellow", asset=SUV), only(assets=[SUV])],
         [paint([SUV], colour="yellow")],
         setup=[turn("Paint the SUV red.", paint([SUV], colour="red"))]),
    case("appearance", "direct", "street_lights_on", MANAGER,
         "street lights on",
         [env(street_lights="on", **NOON, **CLEAR), only(env=True)],
         [lighting(street_lights="on")]),
    case("appearance", "direct", "bench_green", TRANSLATED,
         "Please make the bench of green colour.",
         [looks("green", asset=BENCH), only(assets=[BENCH])],
         [paint([BENCH], colour="green")]),
    case("appearance", "direct", "passenger_cars_blue", DICTATION,
         "make the passenger cars blue",
         [looks("blue", CAR, scope="all", every=True, min_count=2), only(CAR)],
         [paint(category=CAR, colour="blue")]),
    impossible("appearance", "direct", "hail", ENGINEER,
               "Set the precipitation type to hail.",
               [weather("hail")]),
    # indirect
    case("appearance", "indirect", "golden_hour", SCOUT,
         "I want golden-hour light for this shot.",
         [only(env=True)],
         [clock("19:00")],
         alternatives=[[env(time_from="16:30", time_to="20:30")], [env(time_from="05:30", time_to="08:00")]]),
    case("appearance", "indirect", "dark_wet_school_run", PARENT,
         "I want to see what the school run is like on a dark, wet winter morning.",
         [env(weather=["rain"], time_from="05:00", time_to="08:30"), only(env=True)],
         [weather("rain"), clock("06:30")]),
    case("appearance", "indirect", "dense_fog", ENGINEER,
         "Model a low-visibility condition consistent with dense fog.",
         [env(weather=["fog"], intensity_min=0.7, **NOON), only(env=True)],
         [weather("fog", 0.9)]),
    case("appearance", "indirect", "headlights_lesson", INSTRUCTOR,
         "Today's lesson is all about headlights, so the car lights need to be on.",
         [env(vehicle_lights="on"), only(env=True)],
         [lighting(vehicle_lights="on")]),
    case("appearance", "indirect", "ego_distinguishable", AUDITOR,
         "The ego must be visually distinguishable from the NPC vehicles. Make it orange.",
         [looks("orange", asset=EGO), only(assets=[EGO])],
         [paint([EGO], colour="orange")]),
    case("appearance", "indirect", "shuttle_company_colours", MANAGER,
         "client wants that shuttle in company colours. navy",
         [looks("navy", BUS, every=True), only(BUS)],
         [paint(category=BUS, colour="navy")],
         setup=[turn("add a shuttle bus at the bus stop", add(BUS, where=loc("at", BUS_STOP)))]),
    case("appearance", "indirect", "london_weather", TRANSLATED,
         "Make so that the weather is like in London: grey sky and a little of rain.",
         [only(env=True)],
         [weather("rain", 0.3)],
         alternatives=[[env(weather=["rain"], intensity_max=0.5)], [env(weather=["cloudy"])]]),
    case("appearance", "indirect", "sun_coming_up", DICTATION,
         "i want to test the camera when the sun is just coming up",
         [env(time_from="05:30", time_to="07:30"), only(env=True)],
         [clock("sunrise")]),
    impossible("appearance", "indirect", "library_repaint", SCOUT,
               "The Library's brick clashes with the palette of the film. Paint the whole building blue.",
               [paint(["Library"], colour="blue")]),
    # vague
    case("appearance", "vague", "moodier", SCOUT,
         "Make it moodier.",
         [only(env=True)],
         [weather("fog", 0.5)],
         alternatives=[[env(weather=["cloudy", "fog", "rain", "snow"])], [env(night=True)],
                       [env(time_from="17:00", time_to="05:30")], [env(exposure_max=0.9)]]),
    case("appearance", "vague", "harder_conditions", INSTRUCTOR,
         "Make the conditions harder for my learner.",
         [only(env=True)],
         [weather("rain", 0.7)],
         alternatives=[[env(weather=WET_OR_WHITE)], [env(night=True)]]),
    case("appearance", "vague", "adverse_weather", ENGINEER,
         "Give me adverse weather.",
         [env(weather=WET_OR_WHITE), only(env=True)],
         [weather("rain", 0.8)]),
    case("appearance", "vague", "suv_easier_to_spot", PARENT,
         "Could the SUV be made easier to spot?",
         [looks(BRIGHT, asset=SUV), only(assets=[SUV])],
         [paint([SUV], colour="orange")]),
    case("appearance", "vague", "lights_on_too", MODDER,
         "lights on too",
         [env(night=True), only(env=True)],
         [lighting(street_lights="on")],
         setup=[turn("set time 22:00", clock("22:00"), planned=True)],
         alternatives=[[env(street_lights="on")], [env(vehicle_lights="on")]]),
    case("appearance", "vague", "worst_visibility", AUDITOR,
         "Worst-case visibility, please.",
         [only(env=True)],
         [weather("fog", 1.0)],
         alternatives=[[env(weather=["fog"], intensity_min=0.7)], [env(night=True)],
                       [env(weather=WET_OR_WHITE, intensity_min=0.8)]]),
    case("appearance", "vague", "less_gloomy", MANAGER,
         "less gloomy pls",
         [only(env=True)],
         [weather("clear")],
         setup=[turn("fog 0.8", weather("fog", 0.8))],
         alternatives=[[env(weather=["clear"])], [env(intensity_max=0.5)], [env(exposure_min=1.2)]]),
    case("appearance", "vague", "happier_cars", TRANSLATED,
         "Make the cars of other colour, more happy.",
         [looks(BRIGHT, CARS, scope="touched"), only(*CARS)],
         [paint(category=CAR, colour="yellow")]),
    case("appearance", "vague", "time_later", DICTATION,
         "change the time to later",
         [env(time_from="12:15", time_to="23:59", **CLEAR), only(env=True)],
         [clock("afternoon")]),
    # erroneous
    case("appearance", "erroneous", "same_colur_other_car", TRANSLATED,
         "Same colur please also for the other pasenger car.",
         [looks("green", asset=CAR_2), only(assets=[CAR_2])],
         [paint([CAR_2], colour="green")],
         setup=[turn("Please paint the passenger car 1 in green.", paint([CAR_1], colour="green"), planned=True)]),
    case("appearance", "erroneous", "bench_read", DICTATION,
         "paint the bench read",
         [looks("red", asset=BENCH), only(assets=[BENCH])],
         [paint([BENCH], colour="red")]),
    case("appearance", "erroneous", "turn_of_street_lights", MANAGER,
         "turn of the street lights",
         [env(street_lights="off"), only(env=True)],
         [lighting(street_lights="off")]),
    case("appearance", "erroneous", "rainy_evning", PARENT,
         "mkae it rainy and dark like at 6 in the evning",
         [env(weather=["rain"], time_from="17:45", time_to="18:15"), only(env=True)],
         [weather("rain"), clock("18:00")]),
    case("appearance", "erroneous", "ego_whtie_at_nite", INSTRUCTOR,
         "cange the ego colour to whtie and make it nite so we can see it in the dark",
         [looks("white", asset=EGO), env(night=True), only(assets=[EGO], env=True)],
         [paint([EGO], colour="white"), clock("night")]),
    case("appearance", "erroneous", "exposur_0_5", ENGINEER,
         "set exposur to 0.5",
         [env(exposure_min=0.45, exposure_max=0.55, **NOON, **CLEAR), only(env=True)],
         [lighting(exposure=0.5)]),
    case("appearance", "erroneous", "metalic_silver_suv", SCOUT,
         "mak the suv look metalic silver",
         [looks("silver", asset=SUV, material="metal"), only(assets=[SUV])],
         [paint([SUV], colour="silver", material="metal")]),
    case("appearance", "erroneous", "tiem_and_rian", AUDITOR,
         "set tiem to 23:00 and heavy rian",
         [env(weather=["rain"], intensity_min=0.8, time_from="22:45", time_to="23:15"), only(env=True)],
         [clock("23:00"), weather("rain", 0.9)]),
    impossible("appearance", "erroneous", "clock_25_30", MANAGER,
               "clock to 25:30 pls",
               [clock("25:30")]),
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
