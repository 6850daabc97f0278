"""The eighteenth practice suite: 284 cases in the words of nine new kinds of user, from the campus world alone.

`python -m drivetwin.evals.practice18_source` writes `suites/practice18.jsonl` (tag `practice18`, ids
`practice18.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`): an event planner setting up a campus open day (stewards,
the marquee, "the welcome point"), a landscape architect (planting, hardscape, sightlines, frontage), a
retired bus driver who tells stories of his old route and depot, a software developer writing terse
pseudo-code ("cones x5 -> lot A", "del bin", "ego.speed = 8", "rm obstacles"), a mathematician in
geometric language (evenly spaced on a circle, an equilateral triangle, a 3-by-4 lattice, collinear,
a midpoint, a centroid, a translation by a vector), a sports coach (drills, warm-up laps, slaloms,
"set out markers"), a farmer new to cities who names things by how they look ("them short stubby posts",
"orange witch hats", "the big boxy one", "that squat red water-tap thing"), an emergency-services
trainer staging a drill (casualty vehicle, cordon, triage, crews), and a tourist writing careful
textbook English. Prompts mix short chat turns with one-to-three sentence requests, reasons and
hedges, references back to earlier turns ("remove it", "that one", "the other two", "do the same in
lot A", "get them going"), numbers in words and digits, units (metres, m/s, miles an hour), relations
(next to, beside, in front of, behind, ahead of, under, round), scopes (a lane, a lot, a sidewalk, a
side of a road, a landmark), behaviours (speeds, stopping, braking, turning, circling, crossing,
walking somewhere), weather and clock times, questions (which must change nothing), and exceptions
("keep the test car and our crash truck"). The erroneous grade carries realistic typos, autocorrect
and dictation swaps ("student onion", "trash been", "the sub in the car lot", "eggo"), run-together
and doubled words, dropped words and non-native grammar ("Please to add two trafic cone in front the
ego car").

Counts: 7 tasks x 4 grades, at least 9 cases in every cell; arrangement holds 12 in every grade,
search 12 indirect and 13 vague, removal 13 vague, moving 13 indirect and 12 vague (284 in all). 31
cases are multi-turn (17 with a planned earlier turn that has calls), 18 compound (the prompt asks two
things, the reference makes two calls or more), and 23 (8.1 %) impossible, tagged `impossible`, where
the right outcome is a refusal that changes nothing: the distance to a railway station or a helipad,
where the barn is; infinitely many bollards, an ambulance; removing the Library, a crowd that is not
there, the ego; the bench at y = 200 (off the map) or on the Library's roof, the SUV at the Library's
centroid, a bus that is not there; rotating the Library, a hydrant that runs, a thousand miles an
hour, 300 m north; 150 barriers, a hospital entrance, cones inside the JTEKT Building, a ring of 80 m
radius; 25:00, a purple sky, an ultraviolet SUV.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with
`alternatives` where a request has two fair readings, and a `reference` plan that passes; a plan
that does nothing fails every case that is not impossible. The suite was written from the campus
world, the asset catalog, the Worker tools and the eval checks only, by someone who had not read the
planners, their lexicons, their prompt examples or any other suite's cases.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

Json = dict[str, Any]

TAG = "practice18"

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
EVENT = "voice: event planner setting up a campus open day (stewards, marquee, the welcome point)"
LANDSCAPE = "voice: landscape architect (planting, hardscape, sightlines)"
DRIVER = "voice: retired bus driver who tells stories"
DEV = "voice: software developer writing terse pseudo-code-ish requests"
MATH = "voice: mathematician using geometric language"
COACH = "voice: sports coach (drills, lines, setting out markers)"
FARMER = "voice: farmer new to cities, describing things by how they look"
EMS = "voice: emergency-services trainer staging a drill"
TOURIST = "voice: tourist writing careful textbook English"


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


# --- Search: questions that must change nothing, whose answer names the right thing -----------
SEARCH_CASES: list[Json] = [
    # direct
    case("search", "direct", "how_many_trees", TOURIST,
         "How many trees are there on the campus, please?",
         [says(any_of=["4", "four"]), only()],
         [find(category=TREE)]),
    case("search", "direct", "ls_street_light", DEV,
         "ls street_light; ls tree",
         [says(all_of=["12", "street light 12", "tree 4"]), only()],
         [find(category=LAMP), find(category=TREE)]),
    case("search", "direct", "euclidean_fountain_gate", MATH,
         "What is the Euclidean distance between the fountain and the main gate?",
         [says(any_of=["179.5", "180", "179"]), only()],
         [measure(FOUNTAIN, MAIN_GATE)]),
    case("search", "direct", "hydrant_coordinates", EMS,
         "Where exactly is the fire hydrant? Give me its coordinates.",
         [says(all_of=["16"]), only()],
         [find(category=HYDRANT_KIND)]),
    case("search", "direct", "weather_now", COACH,
         "what's the weather doing right now?",
         [says(any_of=["clear", "sunny", "dry"]), only()],
         [environment()]),
    case("search", "direct", "test_car_lane", DRIVER,
         "Which lane is the test car in?",
         [says(any_of=["eastbound"]), only()],
         [properties(asset=EGO)]),
    case("search", "direct", "named_places", LANDSCAPE,
         "List the named places on this site.",
         [says(all_of=["fountain", "Library entrance", "main gate"]), only()],
         [landmarks()]),
    case("search", "direct", "scene_clock", EVENT,
         "What time is it in the scene at the moment?",
         [says(any_of=["12:00", "noon", "midday"]), only()],
         [environment()]),
    case("search", "direct", "distance_and_weather", TOURIST,
         "How far is the Library entrance from the bus stop, and what is the weather like?",
         [says(any_of=["14.5", "14", "15"]), says(any_of=["clear", "sunny"]), only()],
         [measure(LIBRARY, BUS_STOP), environment()]),
    # indirect
    case("search", "indirect", "bin_near_welcome_point", EVENT,
         "Visitors will want to toss their coffee cups at the welcome point by the bus stop. Is there a bin "
         "anywhere close to it?",
         [says(all_of=["trash bin 1"]), only()],
         [find(category=BIN_KIND, near=BUS_STOP, within=15)]),
    case("search", "indirect", "tree_nearest_library_doors", LANDSCAPE,
         "Before I plan the shade, tell me which tree stands nearest the Library's doors.",
         [says(all_of=["tree 1"]), only()],
         [find(category=TREE, nearest_to=LIBRARY)]),
    case("search", "indirect", "stop_to_east_gate", DRIVER,
         "Back when I drove the number 9 we'd count the lamp posts from the stop to the end of the line. "
         "How far is it from the bus stop to the east gate these days?",
         [says(any_of=["130.1", "130"]), only()],
         [measure(BUS_STOP, EAST_GATE)]),
    case("search", "indirect", "landmark_closest_fountain", MATH,
         "Determine which named landmark minimises the distance to the fountain.",
         [says(all_of=["JTEKT"]), only()],
         [landmarks(nearest_to=FOUNTAIN)]),
    case("search", "indirect", "whats_on_eastbound", DEV,
         "need ids of everything currently on lane main_eastbound",
         [says(all_of=["ego"]), only()],
         [find(lane=EASTBOUND)]),
    case("search", "indirect", "seat_near_fountain", COACH,
         "My runners warm up by the fountain. Which seat is the closest one for them to rest on, and how far "
         "off is it?",
         [says(all_of=["bench 1"]), only()],
         [find(category=BENCH_KIND, nearest_to=FOUNTAIN)]),
    case("search", "indirect", "striped_poles_with_lights", FARMER,
         "Them poles at the crossroads with the red, yellow and green lamps on them, how many of them are there?",
         [says(any_of=["2", "two"]), says(all_of=["traffic light 1"]), only()],
         [find(category=SIGNAL)]),
    case("search", "indirect", "hydrant_to_crossroads", EMS,
         "For the drill briefing I need to say how far the hydrant is from the middle of the crossroads, and "
         "which lamp post stands nearest to it.",
         [says(any_of=["16.9", "17"]), says(all_of=["street light 7"]), only()],
         [measure(HYDRANT, JUNCTION), find(category=LAMP, nearest_to=HYDRANT)]),
    case("search", "indirect", "parking_near_engineering", TOURIST,
         "I shall visit the Engineering Hall tomorrow. Which parking area lies nearer to it?",
         [says(all_of=["parking lot A"]), only()],
         [landmarks(query="parking lot", nearest_to=ENGINEERING)]),
    case("search", "indirect", "lane_widths_for_shuttle", EVENT,
         "We're running a shuttle along Main Street for the open day. How wide are its lanes, roughly?",
         [says(all_of=["3.5"]), only()],
         [lanes(road="Main Street")]),
    case("search", "indirect", "middle_car_doing", DRIVER,
         "Three cars in the lot B, like the three on my old depot forecourt. What's the middle one up to?",
         [says(any_of=["parked"]), says(any_of=["suv 1", "suv"]), only()],
         [properties(asset=SUV)]),
    impossible("search", "indirect", "railway_station_distance", TOURIST,
               "I must catch a train later. How far is the railway station from the main gate?",
               [measure("railway station", MAIN_GATE)]),
    # vague
    case("search", "vague", "what_to_see", TOURIST,
         "What is there to see around here?",
         [says(any_of=["fountain", "Library", "JTEKT", "Student Union"]), only()],
         [landmarks()]),
    case("search", "vague", "status", DEV,
         "env?",
         [says(any_of=["clear"]), only()],
         [environment()]),
    case("search", "vague", "whats_on_the_road", FARMER,
         "what's out on the road right now",
         [says(all_of=["ego"]), only()],
         [find(on_lane=True)]),
    case("search", "vague", "anything_by_bus_stop", COACH,
         "Anything in the way round the bus stop?",
         [says(any_of=["bench 1", "trash bin 1"]), only()],
         [find(near=BUS_STOP, within=10)]),
    case("search", "vague", "two_signals_apart", MATH,
         "How far apart are the two signals?",
         [says(any_of=["22.7", "23"]), only()],
         [measure(LIGHT_SW, LIGHT_NE)]),
    case("search", "vague", "visibility", EMS,
         "How's the visibility out there?",
         [says(any_of=["clear"]), only()],
         [environment()]),
    case("search", "vague", "the_greenery", LANDSCAPE,
         "Show me the greenery.",
         [says(all_of=["tree 1", "tree 4"]), only()],
         [find(category=TREE)]),
    case("search", "vague", "where_buses_stop", DRIVER,
         "Where do the buses stop nowadays?",
         [says(all_of=["-30"]), only()],
         [landmarks(query="bus stop")]),
    case("search", "vague", "whos_parked_where", EVENT,
         "Who's parked where?",
         [says(all_of=["suv 1", "passenger car 1", "passenger car 2"]), only()],
         [find(category="vehicles")]),
    case("search", "vague", "is_it_daytime", FARMER,
         "is it still daylight?",
         [says(any_of=["day", "12:00"]), only()],
         [environment()]),
    case("search", "vague", "somewhere_to_sit", TOURIST,
         "Is there somewhere to sit?",
         [says(all_of=["bench 1"]), only()],
         [find(category=BENCH_KIND)]),
    case("search", "vague", "how_many_of_them_now", COACH,
         "ok how many have we got now?",
         [says(any_of=["5", "five"]), only()],
         [find(category=CONE)],
         setup=[turn("Set out five cones in a line in lot B.", arrange(CONE, "line", loc("at", LOT_B), count=5),
                     planned=True)]),
    impossible("search", "vague", "where_is_the_barn", FARMER,
               "where's the barn?",
               [landmarks(query="barn")]),
    # erroneous
    case("search", "erroneous", "cnt_cones", DEV,
         "cnt cones pls",
         [says(any_of=["3", "three"]), only()],
         [find(category=CONE)],
         setup=[turn("cones x3 -> lot A", add(CONE, 3, loc("at", LOT_A)))]),
    case("search", "erroneous", "where_fontain", TOURIST,
         "Where is situate the fontain, please?",
         [says(all_of=["75"]), only()],
         [landmarks(query="fountain")]),
    case("search", "erroneous", "libary_to_student_onion", DRIVER,
         "hows far from the libary to the student onion building",
         [says(any_of=["90.9", "91"]), only()],
         [measure(LIBRARY, UNION)]),
    case("search", "erroneous", "wich_lane_suv", COACH,
         "wich lane is the suv in",
         [says(any_of=["no lane", "parking lot B"]), only()],
         [lanes(near=SUV)]),
    case("search", "erroneous", "how_many_peple", FARMER,
         "how many peple walkin about now",
         [says(any_of=["2", "two"]), only()],
         [find(category=PERSON)],
         setup=[turn("put two folk at the bus stop", add(PERSON, 2, loc("at", BUS_STOP)))]),
    case("search", "erroneous", "distnace_tree1_tree3", MATH,
         "whats the distnace betwen tree 1 and tree 3",
         [says(any_of=["117", "117.0"]), only()],
         [measure(TREE_LIBRARY, TREE_EAST)]),
    case("search", "erroneous", "wether_for_open_day", EVENT,
         "is it gonna rain on our open day?? whats the wether set to",
         [says(any_of=["clear"]), only()],
         [environment()]),
    case("search", "erroneous", "bench_closets_to_bin", LANDSCAPE,
         "which bench is closets to the bin",
         [says(all_of=["bench 1"]), only()],
         [find(category=BENCH_KIND, nearest_to=BIN)]),
    impossible("search", "erroneous", "teh_helipad", EMS,
               "how far is teh helipad from the libary",
               [measure("helipad", LIBRARY)]),
]


# --- Addition: new things where and as asked ---------------------------------------------------
ADDITION_CASES: list[Json] = [
    # direct
    case("addition", "direct", "bench_at_bus_stop", EVENT,
         "Put a bench at the bus stop for the stewards.",
         [delta(BENCH_KIND, 1, 1), near(BUS_STOP, 6, BENCH_KIND), only(BENCH_KIND)],
         [add(BENCH_KIND, where=loc("at", BUS_STOP))]),
    case("addition", "direct", "cones_x5_lot_a", DEV,
         "cones x5 -> lot A",
         [delta(CONE, 5, 5), near(LOT_A, 1, CONE, every=True), only(CONE)],
         [add(CONE, 5, loc("at", LOT_A))]),
    case("addition", "direct", "tree_beside_fountain", LANDSCAPE,
         "Plant a tree beside the fountain.",
         [delta(TREE, 1, 1), near(FOUNTAIN, 8, TREE), only(TREE)],
         [add(TREE, where=loc("next_to", FOUNTAIN))]),
    case("addition", "direct", "two_bikes_by_jtekt", COACH,
         "Add two bicycles on the sidewalk in front of the JTEKT building.",
         [delta(BIKE, 2, 2), near(JTEKT, 15, BIKE, every=True), only(BIKE)],
         [add(BIKE, 2, loc("on_sidewalk", JTEKT))]),
    case("addition", "direct", "truck_in_lot_b", EMS,
         "Add a truck parked in lot B and a pedestrian standing next to it.",
         [delta(TRUCK, 1, 1), near(LOT_B, 1, TRUCK), delta(PERSON, 1, 1), near("truck_1", 4, PERSON),
          only(TRUCK, PERSON)],
         [add(TRUCK, where=loc("at", LOT_B)), add(PERSON, where=loc("next_to", "truck_1"))]),
    case("addition", "direct", "pedestrian_library_entrance", TOURIST,
         "Please add one pedestrian standing at the Library entrance.",
         [delta(PERSON, 1, 1), near(LIBRARY, 5, PERSON), only(PERSON)],
         [add(PERSON, where=loc("at", LIBRARY))]),
    case("addition", "direct", "bus_east_at_ten", FARMER,
         "Add a bus driving east on Main Street at 10 metres a second.",
         [delta(BUS, 1, 1), does("drive_lane", BUS, lane=EASTBOUND, speed_min=9.5, speed_max=10.5), only(BUS)],
         [add(BUS, where=loc("in_lane", EASTBOUND), behaviour=drive(10, EASTBOUND))]),
    case("addition", "direct", "bench_and_bin_at_stop", DRIVER,
         "Put a bench and a bin by the Student Union entrance.",
         [delta(BENCH_KIND, 1, 1), delta(BIN_KIND, 1, 1), near(UNION, 8, BENCH_KIND), near(UNION, 8, BIN_KIND),
          only(BENCH_KIND, BIN_KIND)],
         [add(BENCH_KIND, where=loc("at", UNION)), add(BIN_KIND, where=loc("at", UNION))]),
    case("addition", "direct", "three_bollards_at_point", MATH,
         "Add 3 bollards at the point (-20, 60).",
         [delta(BOLLARD, 3, 3), near(None, 3, BOLLARD, every=True, point=(-20, 60)), only(BOLLARD)],
         [add(BOLLARD, 3, xy(-20, 60))]),
    # indirect
    case("addition", "indirect", "rubbish_by_marquee", EVENT,
         "The marquee crowd outside the Engineering Hall entrance will need somewhere to throw their rubbish.",
         [delta(BIN_KIND, 1, 3), near(ENGINEERING, 10, BIN_KIND), only(BIN_KIND)],
         [add(BIN_KIND, where=loc("at", ENGINEERING))]),
    case("addition", "indirect", "shade_in_lot_a", LANDSCAPE,
         "Lot A is a heat island in summer. It needs a shade tree inside it.",
         [delta(TREE, 1, 3), near(LOT_A, 2, TREE), only(TREE)],
         [add(TREE, where=loc("at", LOT_A))]),
    case("addition", "indirect", "coach_waiting_at_stop", DRIVER,
         "Reminds me of my old route: I'd sit at the stop with the engine ticking over, waiting for the "
         "students. Could we have one of those waiting at the bus stop?",
         [delta(BUS, 1, 1), near(BUS_STOP, 10, BUS), only(BUS)],
         [add(BUS, where=loc("at", BUS_STOP))]),
    case("addition", "indirect", "blocked_southbound", EMS,
         "For the drill the southbound lane of Campus Drive has to be blocked by a broken-down lorry, so the "
         "crews have to work around it.",
         [delta(TRUCK, 1, 1), in_lane(SOUTHBOUND, TRUCK), only(TRUCK)],
         [add(TRUCK, where=loc("in_lane", SOUTHBOUND))]),
    case("addition", "indirect", "ball_collector_fountain", COACH,
         "I need a helper standing by the fountain to collect the balls during the drill.",
         [delta(PERSON, 1, 1), near(FOUNTAIN, 6, PERSON), only(PERSON)],
         [add(PERSON, where=loc("at", FOUNTAIN))]),
    case("addition", "indirect", "someone_walking_to_stop", TOURIST,
         "It would be agreeable if someone were walking from the Library entrance to the bus stop.",
         [delta(PERSON, 1, 1), does("follow_path", PERSON), reaches(PERSON, BUS_STOP, 25, within=3.0), only(PERSON)],
         [add(PERSON, where=loc("at", LIBRARY), behaviour={"kind": "follow_path", "to": BUS_STOP})]),
    case("addition", "indirect", "post_for_bikes_union", FARMER,
         "Back home we'd tie the horse to a post. There's nothing to lean a bike on at the Student Union, put "
         "one of them short stubby posts there.",
         [delta(BOLLARD, 1, 2), near(UNION, 6, BOLLARD), only(BOLLARD)],
         [add(BOLLARD, where=loc("at", UNION))]),
    case("addition", "indirect", "second_npc_for_cut_in", DEV,
         "need another npc sedan for the cut-in test; park it in lot B for now",
         [delta(CAR, 1, 1), near(LOT_B, 1, CAR, scope="added"), only(CAR)],
         [add(CAR, where=loc("at", LOT_B))]),
    case("addition", "indirect", "two_cubed_cones", MATH,
         "I want the number of cones in the junction box to equal two cubed, starting from none.",
         [delta(CONE, 8, 8), near(JUNCTION, 1, CONE, every=True), only(CONE)],
         [add(CONE, 8, loc("at", JUNCTION))]),
    # vague
    case("addition", "vague", "few_more_bins", EVENT,
         "We'll need a few more bins around.",
         [delta(BIN_KIND, 2, 6), only(BIN_KIND)],
         [add(BIN_KIND, 3, loc("at", BUS_STOP))]),
    case("addition", "vague", "more_green", LANDSCAPE,
         "More green, please.",
         [delta(TREE, 1, 10), only(TREE)],
         [add(TREE, 3, loc("at", FOUNTAIN))]),
    case("addition", "vague", "set_out_markers", COACH,
         "Set out some markers.",
         [delta(MARKERS, 2, 30), only(*MARKERS)],
         [add(CONE, 6, loc("at", LOT_B))]),
    case("addition", "vague", "folk_about", FARMER,
         "Can we have some folk about?",
         [delta(PERSON, 2, 20), only(PERSON)],
         [add(PERSON, 3, loc("at", BUS_STOP))]),
    case("addition", "vague", "spawn_traffic", DEV,
         "spawn traffic",
         [delta(MOTOR_TRAFFIC, 1, 20), does("drive_lane", MOTOR_TRAFFIC), only(*MOTOR_TRAFFIC)],
         [add(CAR, 3, loc("in_lane", WESTBOUND), behaviour=drive(lane=WESTBOUND))]),
    case("addition", "vague", "life_at_bus_stop", DRIVER,
         "The bus stop looks dead. Bit of life there, like the old days.",
         [delta([PERSON, BUS, BIKE], 1, 20), near(BUS_STOP, 12, [PERSON, BUS, BIKE]), only(PERSON, BUS, BIKE)],
         [add(PERSON, 2, loc("at", BUS_STOP))]),
    case("addition", "vague", "something_to_sit_on", TOURIST,
         "Something to sit on near the fountain would be most welcome.",
         [delta(BENCH_KIND, 1, 3), near(FOUNTAIN, 10, BENCH_KIND), only(BENCH_KIND)],
         [add(BENCH_KIND, where=loc("next_to", FOUNTAIN))]),
    case("addition", "vague", "debris_on_road", EMS,
         "Scatter some debris on the road for the crews to deal with.",
         [delta(RUBBLE, 1, 10), in_lane(None, RUBBLE), only(RUBBLE)],
         [add(RUBBLE, 3, loc("in_lane", EASTBOUND))]),
    impossible("addition", "vague", "infinitely_many_bollards", MATH,
               "Add infinitely many bollards.",
               [add(BOLLARD, 100000)]),
    # erroneous
    case("addition", "erroneous", "add_bench_at_libary", DEV,
         "add_asset(bench, @libary)",
         [delta(BENCH_KIND, 1, 1), near(LIBRARY, 6, BENCH_KIND), only(BENCH_KIND)],
         [add(BENCH_KIND, where=loc("at", LIBRARY))]),
    case("addition", "erroneous", "trafic_cone_front_ego", TOURIST,
         "Please to add two trafic cone in front the ego car.",
         [delta(CONE, 2, 2), relative("in_front_of", EGO, CONE, max_distance=25, every=True), only(CONE)],
         [add(CONE, 2, loc("in_front_of", EGO))]),
    case("addition", "erroneous", "firehydrant_by_tree", FARMER,
         "put a firehydrant near the tree by the libary",
         [delta(HYDRANT_KIND, 1, 1), near(TREE_LIBRARY, 6, HYDRANT_KIND), only(HYDRANT_KIND)],
         [add(HYDRANT_KIND, where=loc("next_to", TREE_LIBRARY))]),
    case("addition", "erroneous", "ad_4_cones_lot_b", COACH,
         "ad 4 cones on the the parking lot B",
         [delta(CONE, 4, 4), near(LOT_B, 1, CONE, every=True), only(CONE)],
         [add(CONE, 4, loc("at", LOT_B))]),
    case("addition", "erroneous", "shuttel_bus_station", DRIVER,
         "put a shuttel bus at the bus stop, sorry the bus station, same thing",
         [delta(BUS, 1, 1), near(BUS_STOP, 10, BUS), only(BUS)],
         [add(BUS, where=loc("at", BUS_STOP))]),
    impossible("addition", "erroneous", "ambulence_at_crossroads", EMS,
               "add a ambulence at the crossroads, lights going",
               [add("ambulance", where=loc("at", JUNCTION))]),
    case("addition", "erroneous", "too_trees_east_gate", LANDSCAPE,
         "plant too trees at the east gate",
         [delta(TREE, 2, 2), near(EAST_GATE, 12, TREE, every=True), only(TREE)],
         [add(TREE, 2, loc("at", EAST_GATE))]),
    case("addition", "erroneous", "pedestrain_sign_cross_walk", EVENT,
         "we need a pedestrain sign at the west cross walk for the visiters",
         [delta(PED_SIGN, 1, 1), near(WEST_CROSSWALK, 8, PED_SIGN), only(PED_SIGN)],
         [add(PED_SIGN, where=loc("at", WEST_CROSSWALK))]),
    case("addition", "erroneous", "bollard_at_x40", MATH,
         "add a bollard at x = 40 y =-30",
         [delta(BOLLARD, 1, 1), near(None, 0.5, BOLLARD, point=(40, -30)), only(BOLLARD)],
         [add(BOLLARD, where=xy(40, -30))]),
]


# --- Removal: the right things gone, nothing else ----------------------------------------------
REMOVAL_CASES: list[Json] = [
    # direct
    case("removal", "direct", "del_bin", DEV,
         "del bin",
         [gone(BIN), only(assets=[BIN])],
         [remove(BIN)]),
    case("removal", "direct", "bench_at_bus_stop", EVENT,
         "Remove the bench at the bus stop.",
         [gone(BENCH), only(assets=[BENCH])],
         [remove(BENCH)]),
    case("removal", "direct", "tree_next_to_fountain", LANDSCAPE,
         "Take out the tree next to the fountain.",
         [gone(TREE_FOUNTAIN), kept(TREE_EAST), only(assets=[TREE_FOUNTAIN])],
         [remove(TREE_FOUNTAIN)]),
    case("removal", "direct", "fire_hydrant", EMS,
         "Remove it.",
         [gone(HYDRANT), only(assets=[HYDRANT])],
         [remove(HYDRANT)],
         setup=[turn("Where's the fire hydrant?", find(category=HYDRANT_KIND), planned=True)]),
    case("removal", "direct", "stop_sign", TOURIST,
         "Please remove the stop sign.",
         [gone(STOP_SIGN), only(assets=[STOP_SIGN])],
         [remove(STOP_SIGN)]),
    case("removal", "direct", "suv_in_lot_b", COACH,
         "Get rid of the SUV in lot B and the tree up by lot A.",
         [gone(SUV, TREE_LOT_A), kept(CAR_1, CAR_2), only(assets=[SUV, TREE_LOT_A])],
         [remove(SUV), remove(TREE_LOT_A)]),
    case("removal", "direct", "all_parked_cars", DRIVER,
         "Remove all three parked cars from lot B.",
         [gone(*PARKED), only(assets=PARKED)],
         [remove(*PARKED)]),
    case("removal", "direct", "all_the_trees", FARMER,
         "Take away all the trees.",
         [count(TREE, 0, 0), only(TREE)],
         [remove(category=TREE)]),
    impossible("removal", "direct", "remove_the_library", TOURIST,
               "Please remove the Library building; it obstructs the view.",
               [remove("library")]),
    # indirect
    case("removal", "indirect", "marquee_where_bench_is", EVENT,
         "The welcome marquee goes up exactly where the bench at the bus stop is, so the bench can't stay.",
         [only(assets=[BENCH])],
         [remove(BENCH)],
         alternatives=[[gone(BENCH)], [moved(BENCH, 3.0)]]),
    case("removal", "indirect", "sightline_library_tree", LANDSCAPE,
         "The sightline from the Library entrance out to Main Street is blocked by a tree. Clear it.",
         [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
         [remove(TREE_LIBRARY)]),
    case("removal", "indirect", "middle_one_annoyed_me", DRIVER,
         "Those parked cars in lot B always got on my nerves, the middle one most of all. Let's lose it.",
         [gone(SUV), kept(CAR_1, CAR_2), only(assets=[SUV])],
         [remove(SUV)]),
    case("removal", "indirect", "hydrant_trip_hazard", EMS,
         "The hydrant east of the crossroads is a trip hazard for our stretcher run.",
         [only(assets=[HYDRANT])],
         [remove(HYDRANT)],
         alternatives=[[gone(HYDRANT)], [moved(HYDRANT, 3.0)]]),
    case("removal", "indirect", "bin_in_drill_lane", COACH,
         "My sprint lane runs along the pavement past the bus stop and the bin is right in it.",
         [only(assets=[BIN])],
         [remove(BIN)],
         alternatives=[[gone(BIN)], [moved(BIN, 2.0)]]),
    case("removal", "indirect", "eight_sided_sign", FARMER,
         "That red eight-sided sign by the crossing keeps confusing me. I don't want it.",
         [gone(STOP_SIGN), only(assets=[STOP_SIGN])],
         [remove(STOP_SIGN)]),
    case("removal", "indirect", "lamp_spoils_photograph", TOURIST,
         "The lamp post closest to the bus stop spoils my photograph. Could it be taken away?",
         [gone(LAMP_BUS_STOP), only(assets=[LAMP_BUS_STOP])],
         [remove(LAMP_BUS_STOP)]),
    case("removal", "indirect", "revert_cone_spawn", DEV,
         "revert that cone spawn, wrong lot",
         [count(CONE, 0, 0), only(CONE)],
         [remove(category=CONE)],
         setup=[turn("cones x4 -> lot A", add(CONE, 4, loc("at", LOT_A)), planned=True)]),
    case("removal", "indirect", "lamps_with_positive_x", MATH,
         "Consider the street lights whose x-coordinate is positive, east of the origin at the crossroads. "
         "I want that set to be empty.",
         [gone("street_light_7", "street_light_8", "street_light_9", "street_light_10", "street_light_11",
               "street_light_12"), delta(LAMP, -6, -6), only(LAMP)],
         [remove("street_light_7", "street_light_8", "street_light_9", "street_light_10", "street_light_11",
                 "street_light_12")]),
    # vague
    case("removal", "vague", "clutter_off_bus_stop", EVENT,
         "Clear the clutter off the bus stop pavement before the visitors arrive.",
         [delta([BENCH_KIND, BIN_KIND], -2, -1), only(BENCH_KIND, BIN_KIND)],
         [remove(BENCH, BIN)]),
    case("removal", "vague", "thin_out_trees", LANDSCAPE,
         "Thin the trees out a bit.",
         [delta(TREE, -3, -1), only(TREE)],
         [remove(TREE_EAST)]),
    case("removal", "vague", "get_them_out_of_there", DRIVER,
         "Get them out of there, the lot's meant to be empty for the coaches.",
         [gone(*PARKED), only(assets=PARKED)],
         [remove(*PARKED)],
         setup=[turn("What's parked in lot B?", find(category="vehicles", near=LOT_B, within=30))]),
    case("removal", "vague", "get_rid_of_markers", COACH,
         "Right, drill's done. Get rid of the markers.",
         [count(CONE, 0, 0), only(CONE)],
         [remove(category=CONE)],
         setup=[turn("Set out 6 cones in a line in lot A.", arrange(CONE, "line", loc("at", LOT_A), count=6),
                     planned=True)]),
    case("removal", "vague", "couple_of_lamps", FARMER,
         "Too many of them poles with lamps on top. Take a couple away.",
         [delta(LAMP, -3, -2), only(LAMP)],
         [remove(category=LAMP, count=2)]),
    case("removal", "vague", "rm_obstacles", DEV,
         "rm obstacles",
         [count(OBSTACLES, 0, 0), only(*OBSTACLES)],
         [remove("cement_rubble_1", "road_barrier_1", "road_barrier_2")],
         setup=[turn("rubble + 2 barriers on main_eastbound @ x=-30",
                     add(RUBBLE, where=xy(-30, -1.75)), add(BARRIER, 2, loc("in_lane", EASTBOUND)))]),
    case("removal", "vague", "vehicles_not_in_drill", EMS,
         "Clear away the vehicles that aren't part of the drill; keep the test car and our crash truck.",
         [gone(*PARKED), kept("truck_1", EGO), only(assets=PARKED)],
         [remove(*PARKED)],
         setup=[turn("Put a truck in the southbound lane of Campus Drive, that's our crash vehicle.",
                     add(TRUCK, where=loc("in_lane", SOUTHBOUND)), planned=True)]),
    case("removal", "vague", "some_of_the_seating", TOURIST,
         "There is now rather too much seating by the fountain. Please take some of it away.",
         [delta(BENCH_KIND, -3, -1), only(BENCH_KIND)],
         [remove(category=BENCH_KIND, near=FOUNTAIN, count=2)],
         setup=[turn("Please put three benches by the fountain.", add(BENCH_KIND, 3, loc("next_to", FOUNTAIN)))]),
    case("removal", "vague", "one_side_of_main_street", MATH,
         "Remove the street lights along one side of Main Street.",
         [delta(LAMP, -6, -6), only(LAMP)],
         [remove(*SOUTH_LAMPS)],
         alternatives=[[gone(*SOUTH_LAMPS)],
                       [gone("street_light_1", "street_light_3", "street_light_5", "street_light_7",
                             "street_light_9", "street_light_11")]]),
    impossible("removal", "vague", "crowd_at_main_gate", EVENT,
               "Get the crowd away from the main gate.",
               [remove(category=PERSON, near=MAIN_GATE)]),
    case("removal", "vague", "thing_by_water_feature", FARMER,
         "That big leafy thing by the water feature, get it gone.",
         [gone(TREE_FOUNTAIN), only(assets=[TREE_FOUNTAIN])],
         [remove(TREE_FOUNTAIN)]),
    case("removal", "vague", "stuff_off_the_road", COACH,
         "Take that stuff off the road, we need it clear for the run.",
         [count([BARRIER, RUBBLE], 0, 0), only(BARRIER, RUBBLE)],
         [remove("road_barrier_1", "road_barrier_2", "cement_rubble_1")],
         setup=[turn("Put two barriers and some rubble in the westbound lane.",
                     add(BARRIER, 2, loc("in_lane", WESTBOUND)), add(RUBBLE, where=loc("in_lane", WESTBOUND)))]),
    case("removal", "vague", "the_other_ones_too", DRIVER,
         "And the other two while you're at it.",
         [gone(CAR_1, CAR_2), only(assets=[CAR_1, CAR_2])],
         [remove(CAR_1, CAR_2)],
         setup=[turn("Take the SUV out of lot B.", remove(SUV), planned=True)]),
    # erroneous
    case("removal", "erroneous", "rm_f_hydrnat", DEV,
         "rm -f hydrnat",
         [gone(HYDRANT), only(assets=[HYDRANT])],
         [remove(HYDRANT)]),
    case("removal", "erroneous", "bin_near_of_bus_stop", TOURIST,
         "Please to remove the bin what is near of the bus stop.",
         [gone(BIN), only(assets=[BIN])],
         [remove(BIN)]),
    case("removal", "erroneous", "git_rid_of_sub", FARMER,
         "git rid of the sub in the car lot, the big boxy one",
         [gone(SUV), only(assets=[SUV])],
         [remove(SUV)]),
    case("removal", "erroneous", "the_the_bench_broke", DRIVER,
         "remove the the bench by the bus stop its broke",
         [gone(BENCH), only(assets=[BENCH])],
         [remove(BENCH)]),
    case("removal", "erroneous", "remvoe_tree_lot_a", LANDSCAPE,
         "remvoe the tree up by lot A and the the one by the libary",
         [gone(TREE_LOT_A, TREE_LIBRARY), only(assets=[TREE_LOT_A, TREE_LIBRARY])],
         [remove(TREE_LOT_A), remove(TREE_LIBRARY)]),
    case("removal", "erroneous", "streetlight_closest_too_gate", EVENT,
         "can you remove the streetlight closest too the main gate",
         [gone(LAMP_LOT_A), only(assets=[LAMP_LOT_A])],
         [remove(LAMP_LOT_A)]),
    impossible("removal", "erroneous", "remove_teh_ego", EMS,
               "remove teh ego car from the scene for this drill",
               [remove(EGO)]),
    case("removal", "erroneous", "take_of_all_cones", COACH,
         "take of all the cones now pls",
         [count(CONE, 0, 0), only(CONE)],
         [remove(category=CONE)],
         setup=[turn("put 5 cones in the car park", add(CONE, 5, loc("at", LOT_B)))]),
    case("removal", "erroneous", "lihgt_south_west", MATH,
         "delete the traffic lihgt at the south-west corner of the junction",
         [gone(LIGHT_SW), kept(LIGHT_NE), only(assets=[LIGHT_SW])],
         [remove(LIGHT_SW)]),
]


# --- Positioning: an existing thing put somewhere new ------------------------------------------
POSITIONING_CASES: list[Json] = [
    # direct
    case("positioning", "direct", "bench_next_to_engineering", EVENT,
         "Put the bench next to the Engineering Hall entrance, and the bin beside it.",
         [near(ENGINEERING, 6, asset=BENCH), moved(BENCH, 5), near(ENGINEERING, 8, asset=BIN), moved(BIN, 5),
          only(assets=[BENCH, BIN])],
         [place(BENCH, loc("next_to", ENGINEERING)), place(BIN, loc("next_to", BENCH))]),
    case("positioning", "direct", "bin_pos_assign", DEV,
         "bin.pos = (10, -20)",
         [near(None, 0.5, asset=BIN, point=(10, -20)), only(assets=[BIN])],
         [place(BIN, xy(10, -20))]),
    case("positioning", "direct", "lot_a_tree_to_fountain", LANDSCAPE,
         "Move the tree by lot A over to the fountain.",
         [near(FOUNTAIN, 8, asset=TREE_LOT_A), only(assets=[TREE_LOT_A])],
         [place(TREE_LOT_A, loc("next_to", FOUNTAIN))]),
    case("positioning", "direct", "suv_westbound_lane", EMS,
         "Put the SUV in the westbound lane of Main Street.",
         [in_lane(WESTBOUND, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("in_lane", WESTBOUND))]),
    case("positioning", "direct", "bin_beside_library", TOURIST,
         "Please place the trash bin beside the Library entrance.",
         [near(LIBRARY, 5, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("next_to", LIBRARY))]),
    case("positioning", "direct", "car2_to_lot_a", COACH,
         "Put passenger car 2 in lot A.",
         [near(LOT_A, 1, asset=CAR_2), only(assets=[CAR_2])],
         [place(CAR_2, loc("at", LOT_A))]),
    case("positioning", "direct", "hydrant_by_bus_stop", FARMER,
         "Put the fire hydrant by the bus stop.",
         [near(BUS_STOP, 6, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", BUS_STOP))]),
    case("positioning", "direct", "bin_at_midpoint", MATH,
         "Place the bin at the midpoint of the segment joining the bench and the stop sign.",
         [near(None, 1.5, asset=BIN, point=(-19.75, -6.2)), only(assets=[BIN])],
         [place(BIN, xy(-19.75, -6.2))]),
    impossible("positioning", "direct", "bench_at_0_200", DRIVER,
               "Put the bench at the point 0, 200. That's where my old depot used to be.",
               [place(BENCH, xy(0, 200))]),
    # indirect
    case("positioning", "indirect", "welcome_point_main_gate", EVENT,
         "The welcome point is at the main gate this year, so the stewards' bench belongs there, not at the bus stop.",
         [near(MAIN_GATE, 10, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", MAIN_GATE))]),
    case("positioning", "indirect", "library_tree_to_lawn", LANDSCAPE,
         "The tree in front of the Library blocks the view of the doors from the street. It would do better on "
         "the fountain lawn.",
         [near(FOUNTAIN, 10, asset=TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
         [place(TREE_LIBRARY, loc("next_to", FOUNTAIN))]),
    case("positioning", "indirect", "bin_by_the_stop_sign", DRIVER,
         "In my day the bin stood right up against the stop sign by the crossing, handy for the lads waiting. "
         "Can we have it back like that?",
         [near(STOP_SIGN, 3, asset=BIN), moved(BIN, 5), only(assets=[BIN])],
         [place(BIN, loc("next_to", STOP_SIGN))]),
    case("positioning", "indirect", "casualty_car_in_crossroads", EMS,
         "Passenger car 1 is our casualty vehicle; for the drill it has to sit in the middle of the crossroads.",
         [near(JUNCTION, 1, asset=CAR_1), only(assets=[CAR_1])],
         [place(CAR_1, loc("at", JUNCTION))]),
    case("positioning", "indirect", "pace_car_ahead_of_ego", COACH,
         "The SUV is our pace car. It should start just ahead of the test car, same lane.",
         [relative("in_front_of", EGO, asset=SUV, max_distance=25), in_lane(EASTBOUND, asset=SUV),
          only(assets=[SUV])],
         [place(SUV, loc("in_front_of", EGO))]),
    case("positioning", "indirect", "hydrant_photo_fountain", TOURIST,
         "I wish to photograph the hydrant with the fountain behind it. Could it be stood close to the fountain?",
         [near(FOUNTAIN, 8, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("next_to", FOUNTAIN))]),
    case("positioning", "indirect", "bench_under_the_tree", FARMER,
         "That bench at the bus stop sits out in the sun all day. Set it down in the shade right under the "
         "tree behind it.",
         [near(TREE_LIBRARY, 2, asset=BENCH), moved(BENCH, 1), only(assets=[BENCH])],
         [place(BENCH, loc("next_to", TREE_LIBRARY))]),
    case("positioning", "indirect", "ego_spawn_lot_b_entrance", DEV,
         "ego spawn should be lot B entrance, not the west end",
         [near(LOT_B_ENTRANCE, 6, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("at", LOT_B_ENTRANCE))]),
    impossible("positioning", "indirect", "suv_at_library_centroid", MATH,
               "Position the SUV at the centroid of the Library's footprint, the point (-41, -30).",
               [place(SUV, xy(-41, -30))]),
    # vague
    case("positioning", "vague", "bin_near_marquee", EVENT,
         "Shift the bin somewhere near the marquee, it's going up on the lawn by the fountain.",
         [near(FOUNTAIN, 12, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("next_to", FOUNTAIN))]),
    case("positioning", "vague", "bench_closer_to_trees", LANDSCAPE,
         "The bench would read better nestled in against a tree.",
         [moved(BENCH, 1), only(assets=[BENCH])],
         [place(BENCH, loc("next_to", TREE_LIBRARY))],
         alternatives=[[near(t, 2, asset=BENCH)] for t in TREES]),
    case("positioning", "vague", "car_somewhere_sensible", DRIVER,
         "That car's been stood in the road for ages, like a broken-down coach on a Monday. Put it somewhere "
         "more sensible.",
         [moved(CAR_2, 3), only(assets=[CAR_2])],
         [place(CAR_2, loc("at", LOT_A))],
         setup=[turn("Put passenger car 2 in the eastbound lane at x = -20.", place(CAR_2, xy(-20, -1.75)))],
         alternatives=[[near(LOT_A, 1, asset=CAR_2)], [near(LOT_B, 1, asset=CAR_2)]]),
    case("positioning", "vague", "ego_to_far_end", COACH,
         "Ego to the far end for the next rep.",
         [near(EAST_GATE, 20, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("in_lane", EAST_GATE, lane=EASTBOUND))]),
    case("positioning", "vague", "water_tap_nearer_buildings", FARMER,
         "That squat red water-tap thing on the pavement ought to be up closer to one of the big buildings.",
         [moved(HYDRANT, 3), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", JTEKT))],
         alternatives=[[near(b, 6, asset=HYDRANT)] for b in
                       ("JTEKT Building", "Engineering Hall", "Library", "Student Union")]),
    case("positioning", "vague", "suv_somewhere_on_main", DEV,
         "relocate suv -> somewhere on main st",
         [only(assets=[SUV])],
         [place(SUV, loc("in_lane", WESTBOUND))],
         alternatives=[[in_lane(EASTBOUND, asset=SUV)], [in_lane(WESTBOUND, asset=SUV)]]),
    case("positioning", "vague", "bench_with_a_view", TOURIST,
         "Could the bench be put somewhere with a pleasant view of the fountain?",
         [near(FOUNTAIN, 15, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("next_to", FOUNTAIN))]),
    case("positioning", "vague", "a_car_at_the_union", EMS,
         "Park one of the cars outside the Student Union for the scenario.",
         [only(assets=PARKED)],
         [place(CAR_1, loc("at", UNION))],
         alternatives=[[near(UNION, 8, asset=c)] for c in PARKED]),
    case("positioning", "vague", "that_one_by_the_library", EVENT,
         "Actually, put that one by the Library entrance instead.",
         [near(LIBRARY, 6, asset="bench_2"), only(assets=["bench_2"])],
         [place("bench_2", loc("next_to", LIBRARY))],
         setup=[turn("Add a bench at the bus stop for the stewards.", add(BENCH_KIND, where=loc("at", BUS_STOP)),
                     planned=True)]),
    impossible("positioning", "vague", "bench_on_library_roof", FARMER,
               "Put that bench up top of the library, on the roof, so folk can see far.",
               [place(BENCH, xy(-41, -30))]),
    # erroneous
    case("positioning", "erroneous", "mv_bench_fountian", DEV,
         "mv bench @fountian",
         [near(FOUNTAIN, 6, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("next_to", FOUNTAIN))]),
    case("positioning", "erroneous", "car_number_2_lot_a", TOURIST,
         "Please put the car number 2 to the lot A, it is more better there.",
         [near(LOT_A, 1, asset=CAR_2), only(assets=[CAR_2])],
         [place(CAR_2, loc("at", LOT_A))]),
    case("positioning", "erroneous", "bin_rite_next_to_bench", FARMER,
         "put the bin rite next to the bench at the bus stop",
         [near(BENCH, 2, asset=BIN), moved(BIN, 1), only(assets=[BIN])],
         [place(BIN, loc("next_to", BENCH))]),
    case("positioning", "erroneous", "hydrant_lirbary_entrence", DRIVER,
         "stick the hydrant by the lirbary entrence",
         [near(LIBRARY, 6, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("next_to", LIBRARY))]),
    case("positioning", "erroneous", "the_the_suv_lot_a", EVENT,
         "put the the SUV in lot A for the VIP parking",
         [near(LOT_A, 1, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("at", LOT_A))]),
    case("positioning", "erroneous", "tree_3_to_the_east_gate", LANDSCAPE,
         "relocate tree 3 to the the east gate, its to close to the fountain",
         [near(EAST_GATE, 10, asset=TREE_EAST), only(assets=[TREE_EAST])],
         [place(TREE_EAST, loc("at", EAST_GATE))]),
    case("positioning", "erroneous", "strat_of_westbond", COACH,
         "put the ego at the strat of the westbond lane",
         [in_lane(WESTBOUND, asset=EGO, aligned=True), near(EAST_GATE, 20, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("in_lane", EAST_GATE, lane=WESTBOUND), yaw_deg=180)]),
    impossible("positioning", "erroneous", "plase_the_bus", EMS,
               "plase the bus at teh crossroads for the drill",
               [place("bus_1", loc("at", JUNCTION))]),
    case("positioning", "erroneous", "bin_at_x_minus10", MATH,
         "place the bin at x=-10,y=-30 exactly",
         [near(None, 0.5, asset=BIN, point=(-10, -30)), only(assets=[BIN])],
         [place(BIN, xy(-10, -30))]),
]


# --- Moving: shifts, turns, speeds, stops and walks ---------------------------------------------
MOVING_CASES: list[Json] = [
    # direct
    case("moving", "direct", "ego_speed_eq_8", DEV,
         "ego.speed = 8",
         [does("drive_lane", asset=EGO, speed_min=7.8, speed_max=8.2), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=8, lane=EASTBOUND)]),
    case("moving", "direct", "bench_three_m_east", EVENT,
         "Move the bench 3 metres east.",
         [moved(BENCH, 2.5, 3.5, direction="backward"), only(assets=[BENCH])],
         [move(BENCH, east=3)]),
    case("moving", "direct", "turn_suv_around", COACH,
         "Turn the SUV around 180 degrees where it stands.",
         [moved(SUV, 0, 1.0, turn_min=170), only(assets=[SUV])],
         [move(SUV, turn_deg=180)]),
    case("moving", "direct", "tree3_five_north", LANDSCAPE,
         "Shift tree 3 five metres north and tree 4 two metres east.",
         [moved(TREE_EAST, 4.5, 5.5, direction="left"), moved(TREE_LOT_A, 1.5, 2.5, direction="forward"),
          only(assets=[TREE_EAST, TREE_LOT_A])],
         [move(TREE_EAST, north=5), move(TREE_LOT_A, east=2)]),
    case("moving", "direct", "ego_stop", EMS,
         "Make the ego stop.",
         [stops_before(EGO, -48, -1.75, 12), only(assets=[EGO])],
         [manoeuvre(EGO, "stop")]),
    case("moving", "direct", "car1_westbound_six", TOURIST,
         "Please make passenger car 1 drive in the westbound lane at 6 metres per second.",
         [does("drive_lane", asset=CAR_1, lane=WESTBOUND, speed_min=5.8, speed_max=6.2), only(assets=[CAR_1])],
         [behave(CAR_1, "drive_lane", speed=6, lane=WESTBOUND)]),
    case("moving", "direct", "bin_two_west", FARMER,
         "Move the bin two metres west.",
         [moved(BIN, 1.5, 2.5, direction="backward"), only(assets=[BIN])],
         [move(BIN, east=-2)]),
    case("moving", "direct", "ego_left_at_crossroads", DRIVER,
         "Have the test car speed up to 7 metres a second and turn left at the crossroads.",
         [event_played(EGO, "junction_turn", 15), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=7, lane=EASTBOUND), manoeuvre(EGO, "junction_turn", turn="left", speed=7)],
         alternatives=[[does("drive_lane", asset=EGO, speed_min=6.8, speed_max=7.2)],
                       [event_played(EGO, "change_speed", 10)]]),
    impossible("moving", "direct", "rotate_library", LANDSCAPE,
               "Rotate the Library 90 degrees so its front looks at the fountain.",
               [move("library", turn_deg=90)]),
    # indirect
    case("moving", "indirect", "walking_pace_for_visitors", EVENT,
         "Visitors will be wandering along Main Street all day, so the test car should crawl, no faster than "
         "someone walking.",
         [does("drive_lane", asset=EGO, speed_min=0.3, speed_max=2.0), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=1.4, lane=EASTBOUND)]),
    case("moving", "indirect", "bench_quarter_turn", LANDSCAPE,
         "The bench looks west along the pavement. I'd rather it looked out across the road, so give it a "
         "quarter turn to face north.",
         [moved(BENCH, 0, 0.5, turn_min=80, turn_max=100), only(assets=[BENCH])],
         [move(BENCH, turn_deg=-90)]),
    case("moving", "indirect", "car2_loops_lot_b", DRIVER,
         "On the old route we'd go round the depot loop between runs. Have passenger car 2 drive circles in "
         "lot B, about six metres across.",
         [does("circle", asset=CAR_2, radius_min=2.5, radius_max=3.5), only(assets=[CAR_2])],
         [behave(CAR_2, "circle", radius=3)]),
    case("moving", "indirect", "person_steps_out", EMS,
         "Now the drill starts: have that person step out into the road in front of the test car.",
         [does(["jaywalk", "cross_road"], asset="pedestrian_1", crosses_lane=EASTBOUND),
          only(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "jaywalk")],
         setup=[turn("Put a pedestrian on the south pavement by the bus stop.", add(PERSON, where=loc("at", BUS_STOP)))]),
    case("moving", "indirect", "suv_warm_up_laps", COACH,
         "Warm-up laps: the SUV should go round and round in the car park it's in.",
         [does("circle", asset=SUV, centre_near=LOT_B, centre_within=1.0), only(assets=[SUV])],
         [behave(SUV, "circle")]),
    case("moving", "indirect", "courteous_halt", TOURIST,
         "I should like the test vehicle to halt before the west crosswalk, as a courteous driver would.",
         [stops_before(EGO, -13.5, -1.75, 25), only()],
         [call("set_light_phases", light=LIGHT_SW, phases=[{"state": "red", "duration": 600}])]),
    case("moving", "indirect", "middle_car_wrong_way", FARMER,
         "The middle car of the three is facing the wrong way for getting out of the lot. Spin it round.",
         [moved(SUV, 0, 1.5, turn_min=150), only(assets=[SUV])],
         [move(SUV, turn_deg=180)]),
    case("moving", "indirect", "ego_lane_change_t3", DEV,
         "ego: lane_change(left) @ t=3s",
         [event_played(EGO, "lane_change", 6), only(assets=[EGO])],
         [manoeuvre(EGO, "lane_change", at_time=3, side="left")]),
    case("moving", "indirect", "translate_bin_vector", MATH,
         "Translate the bin by the vector (4, 3), in metres east and north.",
         [moved(BIN, 4.5, 5.5, direction="forward"), only(assets=[BIN])],
         [move(BIN, east=4, north=3)]),
    case("moving", "indirect", "steward_walks_to_stop", EVENT,
         "Now have the steward walk over to the bus stop to greet the shuttle.",
         [does("follow_path", asset="pedestrian_1"), reaches("pedestrian_1", BUS_STOP, 40),
          only(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "follow_path", to=BUS_STOP)],
         setup=[turn("Add a pedestrian at the Engineering Hall entrance, that's our steward.",
                     add(PERSON, where=loc("at", ENGINEERING)), planned=True)]),
    case("moving", "indirect", "suv_out_cruising_west", LANDSCAPE,
         "I want to judge the street frontage from a moving car: take the SUV out of the lot and have it "
         "cruise westbound along Main Street, slowly, 3 m/s.",
         [does("drive_lane", asset=SUV, lane=WESTBOUND, speed_min=2.5, speed_max=3.5), only(assets=[SUV])],
         [behave(SUV, "drive_lane", speed=3, lane=WESTBOUND)]),
    case("moving", "indirect", "then_have_it_stop", EMS,
         "Good. Then five seconds in, it has to brake to a stop, like it's seen the casualty.",
         [event_played("bus_1", "stop", 8), only()],
         [manoeuvre("bus_1", "stop", at_time=5)],
         setup=[turn("Add a bus driving east on Main Street from the main gate.",
                     add(BUS, where=loc("in_lane", MAIN_GATE, lane=EASTBOUND), behaviour=drive(lane=EASTBOUND)),
                     planned=True)]),
    impossible("moving", "indirect", "hydrant_runs_across", EMS,
               "For the drill, make the fire hydrant run across the road.",
               [behave(HYDRANT, "cross_road")]),
    # vague
    case("moving", "vague", "slow_down_a_bit", EVENT,
         "Slow the test car down a bit for the open day.",
         [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=3, lane=EASTBOUND)],
         alternatives=[[does("drive_lane", asset=EGO, speed_min=0.5, speed_max=4.6)],
                       [event_played(EGO, "change_speed", 3)]]),
    case("moving", "vague", "ego_faster", DEV,
         "ego faster",
         [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=8, lane=EASTBOUND)],
         alternatives=[[does("drive_lane", asset=EGO, speed_min=5.5)], [event_played(EGO, "change_speed", 3)]]),
    case("moving", "vague", "nudge_the_bench", LANDSCAPE,
         "Nudge the bench a little.",
         [moved(BENCH, 0.2, 3), only(assets=[BENCH])],
         [move(BENCH, forward=1)]),
    case("moving", "vague", "get_that_bus_moving", DRIVER,
         "Get that bus moving, it's been sat there long enough.",
         [does(["drive_lane", "follow_path"], asset="bus_1"), only(assets=["bus_1"])],
         [behave("bus_1", "drive_lane")],
         setup=[turn("Put a bus at the bus stop.", add(BUS, where=loc("at", BUS_STOP)))]),
    case("moving", "vague", "cars_circling", COACH,
         "Get the cars in lot B circling.",
         [does("circle", CARS, min_count=1), only(assets=PARKED)],
         [behave(CAR_1, "circle")]),
    case("moving", "vague", "folk_cross_the_road", FARMER,
         "Make them folk cross over the road.",
         [does(["cross_road", "jaywalk", "follow_path"], PERSON), only(PERSON)],
         [behave("pedestrian_1", "cross_road"), behave("pedestrian_2", "cross_road")],
         setup=[turn("Put two folk on the pavement near the crossing.", add(PERSON, 2, loc("at", WEST_CROSSWALK)))]),
    case("moving", "vague", "parked_cars_forward", TOURIST,
         "Could the parked cars move forward a little, please?",
         [moved(CAR_1, 0.5, 6, direction="forward"), moved(SUV, 0.5, 6, direction="forward"),
          moved(CAR_2, 0.5, 6, direction="forward"), only(assets=PARKED)],
         [call("move_asset", assets=list(PARKED), forward=2)]),
    case("moving", "vague", "ego_out_of_the_way", EMS,
         "Get the test car out of the way, the crews need the road.",
         [moved(EGO, 3), only(assets=[EGO])],
         [place(EGO, loc("at", LOT_A))]),
    case("moving", "vague", "suv_right_angle", MATH,
         "Rotate the SUV through a right angle.",
         [moved(SUV, 0, 1.0, turn_min=80, turn_max=100), only(assets=[SUV])],
         [move(SUV, turn_deg=90)]),
    case("moving", "vague", "get_them_going", COACH,
         "Get them going.",
         [does(["follow_path", "cross_road", "jaywalk"], asset="pedestrian_1"), only(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "follow_path", to=EAST_GATE)],
         setup=[turn("Put a runner by the fountain.", add(PERSON, where=loc("at", FOUNTAIN)), planned=True)]),
    case("moving", "vague", "test_car_up_a_bit", DRIVER,
         "Move the test car up a bit, like pulling forward to the next stand.",
         [moved(EGO, 1, 30, direction="forward"), only(assets=[EGO])],
         [move(EGO, forward=8)]),
    impossible("moving", "vague", "thousand_miles_an_hour", FARMER,
               "Make the test car go a thousand miles an hour.",
               [behave(EGO, "drive_lane", speed=447, lane=EASTBOUND)]),
    # erroneous
    case("moving", "erroneous", "ego_sped_12", DEV,
         "ego.sped = 12 //m/s",
         [does("drive_lane", asset=EGO, speed_min=11.8, speed_max=12.2), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=12, lane=EASTBOUND)]),
    case("moving", "erroneous", "bench_two_meter_north", TOURIST,
         "Please to move the bench two meter to the north direction.",
         [moved(BENCH, 1.5, 2.5, direction="right"), only(assets=[BENCH])],
         [move(BENCH, north=2)]),
    case("moving", "erroneous", "suv_backend_to_road", FARMER,
         "turn the suv round so its back end faces the road",
         [moved(SUV, 0, 1.5, turn_min=150), only(assets=[SUV])],
         [move(SUV, turn_deg=180)]),
    case("moving", "erroneous", "eggo_stop_red_lihgt", DRIVER,
         "make the test car stop at the lights, red lihgt for the eastbound",
         [stops_before(EGO, -13.5, -1.75, 25), only()],
         [call("set_light_phases", light=LIGHT_SW, phases=[{"state": "red", "duration": 600}])]),
    case("moving", "erroneous", "the_the_bin_esat", EVENT,
         "move the the bin 5 meters esat",
         [moved(BIN, 4.5, 5.5, direction="forward"), only(assets=[BIN])],
         [move(BIN, east=5)]),
    case("moving", "erroneous", "car_one_loops_radius_4", COACH,
         "have the car one drive loops in the lot radius 4m",
         [does("circle", asset=CAR_1, radius_min=3.5, radius_max=4.5), only(assets=[CAR_1])],
         [behave(CAR_1, "circle", radius=4)]),
    case("moving", "erroneous", "ego_brak_hard_5s", EMS,
         "make ego brak hard at 5 secs in",
         [event_played(EGO, "stop", 8), stops_before(EGO, -25, -1.75, 15), only()],
         [manoeuvre(EGO, "stop", at_time=5, rate=6)]),
    case("moving", "erroneous", "tree_4_fourty_five", LANDSCAPE,
         "rotate tree 4 by fourty five degrees",
         [moved(TREE_LOT_A, 0, 0.5, turn_min=40, turn_max=50), only(assets=[TREE_LOT_A])],
         [move(TREE_LOT_A, turn_deg=45)]),
    impossible("moving", "erroneous", "bin_300_north", MATH,
               "move the bin 300 metres nroth",
               [move(BIN, north=300)]),
]


# --- Arrangement: several new things laid out as a line, a ring or a block ----------------------
ARRANGEMENT_CASES: list[Json] = [
    # direct
    case("arrangement", "direct", "cones_x6_line_eastbound", DEV,
         "cones x6, line along main_eastbound, spacing=3m",
         [layout("line", CONE, 6, spacing_min=2.5, spacing_max=3.5), in_lane(EASTBOUND, CONE), only(CONE)],
         [arrange(CONE, "lane_edge", loc("in_lane", EASTBOUND), count=6, spacing=3)]),
    case("arrangement", "direct", "eight_bollards_on_circle", MATH,
         "Place 8 bollards evenly spaced on a circle of radius 5 m centred on the fountain.",
         [layout("ring", BOLLARD, 8, around=FOUNTAIN, spacing_min=3.3, spacing_max=4.3), delta(BOLLARD, 8, 8),
          only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=8, radius=5)]),
    case("arrangement", "direct", "five_cones_line_lot_b", COACH,
         "Set out 5 cones in a straight line in lot B.",
         [layout("line", CONE, 5), delta(CONE, 5, 5), near(LOT_B, 1, CONE, every=True), only(CONE)],
         [arrange(CONE, "line", loc("at", LOT_B), count=5)]),
    case("arrangement", "direct", "ring_cones_round_rubble", EMS,
         "Put a ring of cones around the rubble.",
         [layout("ring", CONE, 4, around="cement_rubble_1"), only(CONE)],
         [arrange(CONE, "ring", loc("at", "cement_rubble_1"))],
         setup=[turn("Drop a pile of rubble in the eastbound lane at x = -40.", add(RUBBLE, where=xy(-40, -1.75)))]),
    case("arrangement", "direct", "four_benches_front_jtekt", EVENT,
         "Line up 4 benches in a row in front of the JTEKT building entrance.",
         [layout("line", BENCH_KIND, 4), delta(BENCH_KIND, 4, 4), near(JTEKT, 10, BENCH_KIND, every=True),
          only(BENCH_KIND)],
         [arrange(BENCH_KIND, "line", loc("in_front_of", JTEKT), count=4)]),
    case("arrangement", "direct", "six_trees_south_pavement", LANDSCAPE,
         "Plant a row of 6 trees along the south sidewalk of Main Street, east of the crossroads, 8 m apart.",
         [layout("line", TREE, 6, spacing_min=7, spacing_max=9), delta(TREE, 6, 6), only(TREE)],
         [arrange(TREE, "line", loc("at", "main_south_east"), count=6, spacing=8)]),
    case("arrangement", "direct", "three_by_three_bollards", TOURIST,
         "Please arrange nine bollards in a three by three grid in parking lot A.",
         [layout("cluster", BOLLARD, 9, tolerance=6), delta(BOLLARD, 9, 9), near(LOT_A, 1, BOLLARD, every=True),
          only(BOLLARD)],
         [arrange(BOLLARD, "grid", loc("at", LOT_A), count=9, columns=3)]),
    case("arrangement", "direct", "four_cars_side_by_side", FARMER,
         "Put 4 cars side by side in lot A, like they're parked for market day.",
         [layout("line", CAR, 4), delta(CAR, 4, 4), near(LOT_A, 1, CAR, every=True), only(CAR)],
         [arrange(CAR, "parking_row", loc("at", LOT_A), count=4)]),
    case("arrangement", "direct", "line_westbound_eight_cones", DRIVER,
         "Line the westbound lane with 8 cones.",
         [layout("line", CONE, 8), in_lane(WESTBOUND, CONE), delta(CONE, 8, 8), only(CONE)],
         [arrange(CONE, "lane_edge", loc("in_lane", WESTBOUND), count=8)]),
    case("arrangement", "direct", "barrier_x4_across_lot_b_entrance", DEV,
         "barrier x4, line across lot_b entrance; + 1 construction_sign next to it",
         [layout("line", BARRIER, 4), delta(BARRIER, 4, 4), near(LOT_B_ENTRANCE, 8, BARRIER, every=True),
          delta(WORK_SIGN, 1, 1), near(LOT_B_ENTRANCE, 10, WORK_SIGN), only(BARRIER, WORK_SIGN)],
         [arrange(BARRIER, "line", loc("in_front_of", LOT_B_ENTRANCE), count=4),
          add(WORK_SIGN, where=loc("next_to", LOT_B_ENTRANCE))]),
    case("arrangement", "direct", "lattice_3_by_4", MATH,
         "Form a 3-by-4 lattice of traffic cones in lot B with a lattice spacing of 2 m.",
         [layout("cluster", CONE, 12, tolerance=5, spacing_min=1.8, spacing_max=2.2), delta(CONE, 12, 12),
          near(LOT_B, 1, CONE, every=True), only(CONE)],
         [arrange(CONE, "grid", loc("at", LOT_B), count=12, columns=4, spacing=2)]),
    impossible("arrangement", "direct", "150_barriers_line", EMS,
               "Put 150 barriers in a line across the eastbound lane.",
               [arrange(BARRIER, "line", loc("in_lane", EASTBOUND), count=150)]),
    # indirect
    case("arrangement", "indirect", "queue_line_welcome_point", EVENT,
         "Visitors will queue at the welcome point by the bus stop. Mark the queue with five bollards along the "
         "pavement there.",
         [layout("line", BOLLARD, 5), delta(BOLLARD, 5, 5), near(BUS_STOP, 12, BOLLARD, every=True), only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("at", BUS_STOP), count=5)]),
    case("arrangement", "indirect", "shade_island_lot_a", LANDSCAPE,
         "Lot A bakes in summer. I'd like a shaded island in the middle of it: six trees planted round its "
         "centre, about 8 m out.",
         [layout("ring", TREE, 6, around=LOT_A), delta(TREE, 6, 6), near(LOT_A, 1, TREE, every=True), only(TREE)],
         [arrange(TREE, "ring", loc("at", LOT_A), count=6, radius=8)]),
    case("arrangement", "indirect", "cones_round_breakdown", DRIVER,
         "When a coach broke down we'd put cones all round it so nobody clipped it. There's a lorry stopped in "
         "the middle of the crossroads now. Do the same for it.",
         [layout("ring", CONE, 4, around="truck_1"), only(CONE)],
         [arrange(CONE, "ring", loc("at", "truck_1"))],
         setup=[turn("Put a truck in the middle of the crossroads.", add(TRUCK, where=xy(0, 0)))]),
    case("arrangement", "indirect", "cordon_campus_drive_north", EMS,
         "The triage area needs a cordon: barriers in a line right across Campus Drive, north of the crossroads.",
         [layout("line", BARRIER, 3), near(NORTH_CROSSWALK, 20, BARRIER, every=True), in_lane(None, BARRIER),
          only(BARRIER)],
         [arrange(BARRIER, "line", xy(0, 20), count=3, heading_deg=0)]),
    case("arrangement", "indirect", "shuttle_run_markers", COACH,
         "Shuttle-run drill: I need a marker every 5 metres down the eastbound lane starting from the main gate, "
         "eight of them.",
         [layout("line", CONE, 8, spacing_min=4.5, spacing_max=5.5), in_lane(EASTBOUND, CONE),
          near(MAIN_GATE, 45, CONE, every=True), only(CONE)],
         [arrange(CONE, "lane_edge", loc("in_lane", MAIN_GATE, lane=EASTBOUND), count=8, spacing=5)]),
    case("arrangement", "indirect", "bench_circle_for_photo", TOURIST,
         "For my photograph I should like six benches facing the fountain from all sides, as in a circle.",
         [layout("ring", BENCH_KIND, 6, around=FOUNTAIN), delta(BENCH_KIND, 6, 6), only(BENCH_KIND)],
         [arrange(BENCH_KIND, "ring", loc("at", FOUNTAIN), count=6, radius=4)]),
    case("arrangement", "indirect", "fence_round_lot_a_tree", FARMER,
         "Like a fence round a paddock: put them short posts all the way round the tree up by lot A.",
         [layout("ring", BOLLARD, 4, around=TREE_LOT_A), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", TREE_LOT_A))]),
    case("arrangement", "indirect", "parking_row_suvs", DEV,
         "need a parking_row of 3 suvs in lot A, nose north, for the perception test",
         [layout("line", SUV_KIND, 3), delta(SUV_KIND, 3, 3), near(LOT_A, 1, SUV_KIND, scope="added", every=True),
          only(SUV_KIND)],
         [arrange(SUV_KIND, "parking_row", loc("at", LOT_A), count=3, heading_deg=90)]),
    case("arrangement", "indirect", "equilateral_triangle_cones", MATH,
         "Three cones at the vertices of an equilateral triangle of side 6 m, centred on the middle of the "
         "crossroads.",
         [layout("ring", CONE, 3, around=JUNCTION, spacing_min=5.5, spacing_max=6.5), delta(CONE, 3, 3), only(CONE)],
         [arrange(CONE, "ring", loc("at", JUNCTION), count=3, radius=3.46)]),
    case("arrangement", "indirect", "keep_people_off_vip_bench", EVENT,
         "And keep people off it until the VIPs arrive: ring it with bollards.",
         [layout("ring", BOLLARD, 4, around="bench_2"), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", "bench_2"))],
         setup=[turn("Put a bench next to the fountain for the VIPs.", add(BENCH_KIND, where=loc("next_to", FOUNTAIN)),
                     planned=True)]),
    case("arrangement", "indirect", "avenue_south_pavement_west", LANDSCAPE,
         "The south pavement between the main gate and the bus stop reads as bare tarmac. An avenue of five "
         "trees along it would fix that.",
         [layout("line", TREE, 5), delta(TREE, 5, 5), on(["sidewalk", "ground"], TREE),
          near(None, 40, TREE, every=True, point=(-65, -5.5)), only(TREE)],
         [arrange(TREE, "line", xy(-63, -5.5), count=5, heading_deg=0, spacing=10)]),
    impossible("arrangement", "indirect", "cordon_hospital_entrance", EMS,
               "Drill scenario: cordon off the hospital entrance with a ring of cones.",
               [arrange(CONE, "ring", loc("at", "hospital entrance"))]),
    # vague
    case("arrangement", "vague", "row_of_seats_stewards", EVENT,
         "Could we have a row of seats for the stewards?",
         [layout("line", BENCH_KIND, 3), only(BENCH_KIND)],
         [arrange(BENCH_KIND, "line", loc("at", BUS_STOP), count=4)]),
    case("arrangement", "vague", "cones_in_circle_somewhere", DEV,
         "cones in a circle, anywhere",
         [layout("ring", CONE, 4), only(CONE)],
         [arrange(CONE, "ring", loc("at", LOT_B), count=8, radius=4)]),
    case("arrangement", "vague", "set_up_a_slalom", COACH,
         "Set up a slalom.",
         [layout("line", [CONE, BOLLARD], 4), only(CONE, BOLLARD)],
         [arrange(CONE, "line", loc("at", LOT_B), count=6, spacing=3)]),
    case("arrangement", "vague", "rhythm_along_lot_a", LANDSCAPE,
         "Give the edge of lot A some rhythm with a line of trees.",
         [layout("line", TREE, 3), near(LOT_A, 10, TREE, every=True), only(TREE)],
         [arrange(TREE, "line", xy(-85, 10), count=5, heading_deg=0, spacing=5)]),
    case("arrangement", "vague", "buses_like_a_depot", DRIVER,
         "Park a few buses in a row somewhere, like the old depot.",
         [layout("line", BUS, 2), delta(BUS, 2, 6), only(BUS)],
         [arrange(BUS, "parking_row", loc("at", LOT_A), count=3)]),
    case("arrangement", "vague", "witch_hats_in_a_ring", FARMER,
         "Put a bunch of them orange witch hats in a ring on the big paved yard by the student building.",
         [layout("ring", CONE, 4), near(LOT_B, 2, CONE, every=True), only(CONE)],
         [arrange(CONE, "ring", loc("at", LOT_B), count=8, radius=4)]),
    case("arrangement", "vague", "bollards_neatly_near_library", TOURIST,
         "Might you arrange some bollards neatly somewhere near the Library?",
         [delta(BOLLARD, 3, 30), near(LIBRARY, 15, BOLLARD, every=True), only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("in_front_of", LIBRARY), count=5)]),
    case("arrangement", "vague", "block_the_road_properly", EMS,
         "Block the road off properly.",
         [layout("line", [BARRIER, CONE], 2), in_lane(None, [BARRIER, CONE]), only(BARRIER, CONE)],
         [arrange(BARRIER, "line", xy(-40, 0), count=3, heading_deg=90)]),
    case("arrangement", "vague", "some_collinear_cones", MATH,
         "Produce some collinear cones.",
         [layout("line", CONE, 3), only(CONE)],
         [arrange(CONE, "line", loc("at", LOT_B), count=4)]),
    case("arrangement", "vague", "same_in_lot_a", COACH,
         "Now do the same over in lot A.",
         [layout("line", CONE, 5), delta(CONE, 5, 5), near(LOT_A, 1, CONE, scope="added", every=True), only(CONE)],
         [arrange(CONE, "line", loc("at", LOT_A), count=5)],
         setup=[turn("Put five cones in a line in lot B.", arrange(CONE, "line", loc("at", LOT_B), count=5),
                     planned=True)]),
    case("arrangement", "vague", "same_with_bins", EVENT,
         "Same again with bins, please, over by the JTEKT entrance.",
         [layout("line", BIN_KIND, 4), delta(BIN_KIND, 4, 4), near(JTEKT, 10, BIN_KIND, every=True), only(BIN_KIND)],
         [arrange(BIN_KIND, "line", loc("in_front_of", JTEKT), count=4)],
         setup=[turn("Line up four benches in front of the Engineering Hall entrance.",
                     arrange(BENCH_KIND, "line", loc("in_front_of", ENGINEERING), count=4), planned=True)]),
    impossible("arrangement", "vague", "witch_hats_inside_glass_building", FARMER,
               "Put a row of them orange witch hats inside the big glass building, the JTEKT one.",
               [arrange(CONE, "line", xy(37.5, 29), count=5)]),
    # erroneous
    case("arrangement", "erroneous", "cones_x8_rign_rubble", DEV,
         "cones x8 rign around rubble_1",
         [layout("ring", CONE, 8, around="cement_rubble_1"), delta(CONE, 8, 8), only(CONE)],
         [arrange(CONE, "ring", loc("at", "cement_rubble_1"), count=8)],
         setup=[turn("rubble -> main st centreline @ x=30", add(RUBBLE, where=xy(30, 0)))]),
    case("arrangement", "erroneous", "line_five_bollard_library", TOURIST,
         "Please to make a line of five bollard in front the Library entrance.",
         [layout("line", BOLLARD, 5), delta(BOLLARD, 5, 5), near(LIBRARY, 10, BOLLARD, every=True), only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("in_front_of", LIBRARY), count=5)]),
    case("arrangement", "erroneous", "posts_circel_founten", FARMER,
         "put them short posts in a circel round the founten",
         [layout("ring", BOLLARD, 4, around=FOUNTAIN), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", FOUNTAIN))]),
    case("arrangement", "erroneous", "strait_line_lot_a_2m", COACH,
         "set out 6 cones in a strait line in lot A, 2 meter apart",
         [layout("line", CONE, 6, spacing_min=1.8, spacing_max=2.2), delta(CONE, 6, 6),
          near(LOT_A, 1, CONE, every=True), only(CONE)],
         [arrange(CONE, "line", loc("at", LOT_A), count=6, spacing=2)]),
    case("arrangement", "erroneous", "east_bound_ten_of_em", DRIVER,
         "line the east bound lane with cones, ten of em",
         [layout("line", CONE, 10), in_lane(EASTBOUND, CONE), delta(CONE, 10, 10), only(CONE)],
         [arrange(CONE, "lane_edge", loc("in_lane", EASTBOUND), count=10)]),
    case("arrangement", "erroneous", "benchs_in_a_row_fountain", EVENT,
         "cud you put 4 benchs in a row by the the fountain",
         [layout("line", BENCH_KIND, 4), delta(BENCH_KIND, 4, 4), near(FOUNTAIN, 12, BENCH_KIND, every=True),
          only(BENCH_KIND)],
         [arrange(BENCH_KIND, "line", loc("in_front_of", FOUNTAIN), count=4)]),
    case("arrangement", "erroneous", "trees_south_edge_lot_a", LANDSCAPE,
         "plant a line of trees along the the south edge of lot A, four of them, 5m appart",
         [layout("line", TREE, 4, spacing_min=4.5, spacing_max=5.5), delta(TREE, 4, 4),
          near(LOT_A, 6, TREE, every=True), only(TREE)],
         [arrange(TREE, "line", xy(-85, 10), count=4, heading_deg=0, spacing=5)]),
    case("arrangement", "erroneous", "barriers_acros_westbund", EMS,
         "put barriers in a line acros the westbund lane near the east gate, 3 of them",
         [layout("line", BARRIER, 3), delta(BARRIER, 3, 3), near(EAST_GATE, 25, BARRIER, every=True),
          only(BARRIER)],
         [arrange(BARRIER, "line", xy(90, 0), count=3, heading_deg=90, spacing=2.2)]),
    impossible("arrangement", "erroneous", "cirlce_radius_80", MATH,
               "arange 12 cones evenly on a cirlce of radius 80 m about the crossroads",
               [arrange(CONE, "ring", loc("at", JUNCTION), count=12, radius=80)]),
    case("arrangement", "erroneous", "grid_4x4_bollards", DEV,
         "grid 4x4 bollards @lotB spacing=2",
         [layout("cluster", BOLLARD, 16, tolerance=5, spacing_min=1.8, spacing_max=2.2), delta(BOLLARD, 16, 16),
          near(LOT_B, 1, BOLLARD, every=True), only(BOLLARD)],
         [arrange(BOLLARD, "grid", loc("at", LOT_B), count=16, columns=4, spacing=2)]),
    case("arrangement", "erroneous", "cones_behind_it_like_4", EVENT,
         "put cones in a line behind it pls, like 4",
         [layout("line", CONE, 4), delta(CONE, 4, 4), relative("behind", "bus_1", CONE, max_distance=20, every=True),
          only(CONE)],
         [arrange(CONE, "line", loc("behind", "bus_1"), count=4)],
         setup=[turn("Add a bus at the bus stop for the shuttle.", add(BUS, where=loc("at", BUS_STOP)), planned=True)]),
    case("arrangement", "erroneous", "line_and_ring_compound", COACH,
         "cones in a line in lot B, 5 of em, and a ring of posts round the fountian too",
         [layout("line", CONE, 5), near(LOT_B, 1, CONE, every=True), layout("ring", BOLLARD, 4, around=FOUNTAIN),
          only(CONE, BOLLARD)],
         [arrange(CONE, "line", loc("at", LOT_B), count=5), arrange(BOLLARD, "ring", loc("at", FOUNTAIN))]),
]


# --- Appearance: weather, clock, lights, colours and materials ----------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case("appearance", "direct", "rain_lightly", EVENT,
         "Make it rain lightly.",
         [env(weather=["rain"], intensity_max=0.45), only(env=True)],
         [weather("rain", 0.3)]),
    case("appearance", "direct", "time_eq_1830", DEV,
         "time = 18:30",
         [env(time_from="18:15", time_to="18:45"), only(env=True)],
         [clock("18:30")]),
    case("appearance", "direct", "benches_green", LANDSCAPE,
         "Paint the benches green, and the bins as well so they match the planting.",
         [looks("green", BENCH_KIND, every=True), looks("green", BIN_KIND, every=True), only(BENCH_KIND, BIN_KIND)],
         [paint(category=BENCH_KIND, colour="green"), paint(category=BIN_KIND, colour="green")]),
    case("appearance", "direct", "suv_yellow", COACH,
         "Make it yellow.",
         [looks("yellow", asset=SUV), only(assets=[SUV])],
         [paint([SUV], colour="yellow")],
         setup=[turn("Which one's the SUV?", properties(asset=SUV), planned=True)]),
    case("appearance", "direct", "half_past_seven_evening", TOURIST,
         "Please set the time to half past seven in the evening.",
         [env(time_from="19:15", time_to="19:45"), only(env=True)],
         [clock("19:30")]),
    case("appearance", "direct", "snow_heavily", FARMER,
         "Make it snow heavily.",
         [env(weather=["snow"], intensity_min=0.75), only(env=True)],
         [weather("snow", 0.9)]),
    case("appearance", "direct", "street_lights_on", EMS,
         "Turn the street lights on.",
         [env(street_lights="on"), only(env=True)],
         [lighting(street_lights="on")]),
    case("appearance", "direct", "car2_red_and_dusk", DRIVER,
         "Paint passenger car 2 red and make it dusk.",
         [looks("red", asset=CAR_2), env(time_from="18:30", time_to="21:00"), only(assets=[CAR_2], env=True)],
         [paint([CAR_2], colour="red"), clock("dusk")]),
    impossible("appearance", "direct", "clock_25_00", COACH,
               "Set the clock to 25:00 so we get an extra hour of training.",
               [clock("25:00")]),
    # indirect
    case("appearance", "indirect", "open_day_starts_at_nine", EVENT,
         "Our open day kicks off at nine in the morning; set the scene up to match.",
         [env(time_from="08:45", time_to="09:15"), only(env=True)],
         [clock("09:00")]),
    case("appearance", "indirect", "planting_in_autumn", LANDSCAPE,
         "I want to see how the planting reads in autumn.",
         [looks(AUTUMN, TREE, every=True, min_count=4), only(TREE)],
         [paint(category=TREE, colour="orange")]),
    case("appearance", "indirect", "night_shift", DRIVER,
         "Reminds me of the night shift, empty roads and the lamps buzzing. Make it like that, proper dark.",
         [env(night=True), only(env=True)],
         [clock("23:00")]),
    case("appearance", "indirect", "drill_in_thick_fog", EMS,
         "The drill happens at night in thick fog; set that up.",
         [env(weather=["fog"], intensity_min=0.6, night=True), only(env=True)],
         [weather("fog", 0.9), clock("22:00")]),
    case("appearance", "indirect", "hydrant_stand_out", COACH,
         "Right, make that stand out so the players don't trip over it.",
         [looks(BRIGHT, asset=HYDRANT), only(assets=[HYDRANT])],
         [paint([HYDRANT], colour="yellow")],
         setup=[turn("Is there a hydrant near the crossroads?", find(category=HYDRANT_KIND, near=JUNCTION, within=30),
                     planned=True)]),
    case("appearance", "indirect", "rainy_afternoon", TOURIST,
         "I would like the scene to resemble a rainy afternoon.",
         [env(weather=["rain"], time_from="13:00", time_to="17:30"), only(env=True)],
         [weather("rain"), clock("15:00")]),
    case("appearance", "indirect", "bins_like_my_barn", FARMER,
         "The bins ought to look like they're made of planks, like my barn.",
         [looks(None, BIN_KIND, material="wood", every=True), only(BIN_KIND)],
         [paint(category=BIN_KIND, material="wood")]),
    case("appearance", "indirect", "night_test_all_lights", DEV,
         "night test: time 22:00, force street + vehicle lights on",
         [env(night=True, street_lights="on", vehicle_lights="on"), only(env=True)],
         [clock("22:00"), lighting(street_lights="on", vehicle_lights="on")]),
    case("appearance", "indirect", "stop_sign_rgb", MATH,
         "Colour the stop sign with the RGB triple (0, 0, 255).",
         [looks("#0000ff", asset=STOP_SIGN, tolerance=0.3), only(assets=[STOP_SIGN])],
         [paint([STOP_SIGN], colour="#0000ff")]),
    # vague
    case("appearance", "vague", "bit_gloomier", EVENT,
         "Can it look a bit gloomier? The marquee photos are too cheerful.",
         [only(env=True)],
         [weather("cloudy")],
         alternatives=[[env(weather=["cloudy", "rain", "fog", "snow"])], [env(time_from="17:00", time_to="06:30")],
                       [env(exposure_max=0.9)]]),
    case("appearance", "vague", "brighten_benches", LANDSCAPE,
         "Brighten up the benches.",
         [looks(BRIGHT, BENCH_KIND, every=True), only(BENCH_KIND)],
         [paint(category=BENCH_KIND, colour="yellow")]),
    case("appearance", "vague", "the_wee_hours", DRIVER,
         "Make it the wee hours, when I'd do the first run.",
         [env(time_from="00:00", time_to="05:30"), only(env=True)],
         [clock("04:00")]),
    case("appearance", "vague", "bad_weather", COACH,
         "Bad weather, please, we train in anything.",
         [env(weather=WET_OR_WHITE), only(env=True)],
         [weather("rain")]),
    case("appearance", "vague", "could_it_be_evening", TOURIST,
         "Could it be evening?",
         [env(time_from="17:00", time_to="22:30"), only(env=True)],
         [clock("evening")]),
    case("appearance", "vague", "darker_pls", DEV,
         "darker pls",
         [only(env=True)],
         [lighting(exposure=0.6)],
         alternatives=[[env(exposure_max=0.9)], [env(night=True)], [env(time_from="17:00", time_to="06:30")]]),
    case("appearance", "vague", "liven_up_cars", FARMER,
         "Them cars in the lot are awful dull. Liven them up.",
         [looks(BRIGHT, CARS, every=True, min_count=3), only(assets=PARKED)],
         [paint(list(PARKED), colour="orange")]),
    case("appearance", "vague", "poor_visibility", EMS,
         "Make the visibility poor.",
         [env(weather=WET_OR_WHITE, intensity_min=0.5), only(env=True)],
         [weather("fog", 0.8)]),
    impossible("appearance", "vague", "paint_the_sky", EVENT,
               "Paint the sky purple for the open day.",
               [paint(["sky"], colour="purple")]),
    # erroneous
    case("appearance", "erroneous", "the_othre_two_to", DRIVER,
         "and the othre two to, same colour",
         [looks("red", asset=SUV), looks("red", asset=CAR_2), only(assets=[SUV, CAR_2])],
         [paint([SUV, CAR_2], colour="red")],
         setup=[turn("Paint passenger car 1 red, like my old route bus.", paint([CAR_1], colour="red"), planned=True)]),
    case("appearance", "erroneous", "snwo_half", DEV,
         "weather=snwo, intensity=0.5",
         [env(weather=["snow"], intensity_min=0.4, intensity_max=0.6), only(env=True)],
         [weather("snow", 0.5)]),
    case("appearance", "erroneous", "time_to_be_sunset", TOURIST,
         "Please make the time of the day to be sunset.",
         [env(time_from="18:30", time_to="20:15"), only(env=True)],
         [clock("sunset")]),
    case("appearance", "erroneous", "trash_been_blue", FARMER,
         "paint the trash been blue",
         [looks("blue", asset=BIN), only(assets=[BIN])],
         [paint([BIN], colour="blue")]),
    case("appearance", "erroneous", "rane_heavy", DRIVER,
         "make it rane, heavy like, the way it came down in 87",
         [env(weather=["rain"], intensity_min=0.75), only(env=True)],
         [weather("rain", 0.9)]),
    case("appearance", "erroneous", "benchs_yelow", EVENT,
         "can u paint the benchs yelow for the open day",
         [looks("yellow", BENCH_KIND, every=True), only(BENCH_KIND)],
         [paint(category=BENCH_KIND, colour="yellow")]),
    case("appearance", "erroneous", "lamp_posts_metal_finnish", LANDSCAPE,
         "make the lamp posts a metal finnish",
         [looks(None, LAMP, material="metal", every=True, min_count=12), only(LAMP)],
         [paint(category=LAMP, material="metal")]),
    case("appearance", "erroneous", "turn_of_streetlights", COACH,
         "turn of the streetlights",
         [env(street_lights="off"), only(env=True)],
         [lighting(street_lights="off")]),
    case("appearance", "erroneous", "time_2_midnite", EMS,
         "set time 2 midnite",
         [env(time_from="23:45", time_to="00:15"), only(env=True)],
         [clock("00:00")]),
    impossible("appearance", "erroneous", "suv_ultraviolett", MATH,
               "paint the suv the colour ultraviolett",
               [paint([SUV], colour="ultraviolet")]),
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
