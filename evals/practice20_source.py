"""The twentieth practice suite: 276 cases in the words of nine new kinds of user, from the campus world alone.

`python -m drivetwin.evals.practice20_source` writes `suites/practice20.jsonl` (tag `practice20`, ids
`practice20.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`): a police collision investigator ("Vehicle A", "Vehicle B",
"the point of impact", "skid marks", "the reporting party", "for the collision report"), a sailor or pilot in
nautical and aviation words ("port", "starboard", "abeam", "dead ahead", "dead astern", "bring her about",
"berth", "moored", "knots", "two cables"), an Australian ("ute", "servo", "footpath", "arvo", "wheelie
bin", "chuck a u-ey", "roos", "mate"), a food-truck owner talking about "my truck", customers, regulars and
a pitch, an ex-military voice ("affirmative", "oscar mike", "12 o'clock", "6 o'clock", "grid ref", "stand
down", "sitrep", "klicks"), a cognitive-science grad student running a pedestrian-behaviour study
(participants, conditions, trials, a pre-registration), a poet or novelist writing flowery, figurative
requests ("a crown of steel", "like commas in a long sentence", "the last amber of the day"), someone who
corrects themselves mid-request ("three traffic cones — sorry, four", "the bin — no, the bench", "five no
six"), and someone writing with heavy negation and double negatives ("don't not put cones there", "nothing
but", "anywhere except where it is now", "no more than two", "isn't not red"). Prompts mix short chat
turns with one-to-three sentence requests, reasons and hedges, references back to earlier turns ("that
hydrant", "those cones", "another one of those", "same again by the library", "and the distance from
there?"), numbers in words and digits, units (metres, km/h, m/s, knots, klicks), relations (next to,
beside, in front of, behind, ahead of, abeam, round), scopes (a lane, a lot, a footpath, a landmark),
behaviours (speeds, braking to a stop before a crosswalk, turning at the crossroads, a lane change,
circling, crossing, jaywalking, riding somewhere), weather and clock times ("0200 hours", "half six",
"arvo"), questions (which must change nothing), and exceptions ("every car in lot B except the SUV",
"every tree except the one by the library"). The erroneous grade carries realistic typos and dictation
swaps ("vehical", "fountian", "hale" for hail, "nots" for knots, "trail" for trial, "cue" for queue),
dropped words and non-native grammar ("which lane its in?", "put 4 custmers in a cue").

Counts: 7 tasks x 4 grades; search, moving and arrangement hold 11 cases in every grade, addition,
removal, positioning and appearance 9 (276 in all). 33 cases are multi-turn (17 with a planned earlier
turn that has calls), 22 compound (the prompt asks two things, the reference makes two calls or more),
and 22 (8.0 %) impossible, tagged `impossible`, where the right outcome is a refusal that changes
nothing: the distance to a servo, a harbour master's office, roos; a kangaroo, a thousand participants, a
truck 5 klicks north at y = 5000 m; removing the ego, the footpath, the fountain; the bench inside the
Library, the SUV at y = -300 m, a tree on Engineering Hall's roof; 200 knots, moving the bus stop, a bench
that drives, reversing 300 m; 500 cones, a ring two cables across, a ring inside the Library; 2500 hours,
a tartan bench, hail.

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

TAG = "practice20"

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
SOUTH_LAMPS = (
    "street_light_2",
    "street_light_4",
    "street_light_6",
    "street_light_8",
    "street_light_10",
    "street_light_12",
)  # Main Street's south side, x -68, -38, -13, 37, 62, 92

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
# Sidewalks ("footpaths", "footways"): Main Street's south and north sides, west and east of Campus Drive.
SOUTH_WEST_WALK, NORTH_WEST_WALK = "main_south_west", "main_north_west"
SOUTH_EAST_WALK, NORTH_EAST_WALK = "main_south_east", "main_north_east"
KNOT = 0.5144  # metres per second

CONE, BARRIER, RUBBLE, BOLLARD = "traffic_cone", "road_barrier", "cement_rubble", "bollard"
CAR, SUV_KIND, BUS, TRUCK, ROBOT = "passenger_car", "suv", "bus", "truck", "ackermann_robot"
BIKE, MOTORBIKE, PERSON = "bicycle", "motorcycle", "pedestrian"
TREE, BENCH_KIND, BIN_KIND, LAMP = "tree", "bench", "trash_bin", "street_light"
PED_SIGN, WORK_SIGN, STOP_KIND, SIGNAL = "pedestrian_sign", "construction_sign", "stop_sign", "traffic_light"
HYDRANT_KIND, PARK_SIGN = "fire_hydrant", "parking_sign"
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
ANY_COLOUR = [
    "red",
    "green",
    "blue",
    "yellow",
    "orange",
    "white",
    "black",
    "grey",
    "silver",
    "purple",
    "pink",
    "brown",
    "cyan",
    "teal",
    "beige",
    "gold",
    "navy",
    "maroon",
]
AUTUMN = ["orange", "brown", "red", "gold", "yellow", "maroon"]

# Who is speaking: each case names its voice in `notes`.
COP = "voice: police collision investigator (Vehicle A, point of impact, skid marks, the reporting party)"
SAIL = "voice: sailor or pilot using nautical and aviation words (port, starboard, bearing, abeam, dead ahead, knots)"
AUS = "voice: Australian English speaker (ute, servo, footpath, arvo, wheelie bin, bottle-o)"
TRUCKIE = "voice: food-truck owner talking about my truck, customers and a pitch"
MIL = "voice: ex-military (affirmative, oscar mike, 12 o'clock, grid ref, stand down)"
STUDY = "voice: cognitive-science grad student running a pedestrian-behaviour study (participants, conditions, trials)"
POET = "voice: poet or novelist writing flowery, figurative requests"
SELF = "voice: someone who corrects themselves mid-request (no wait, sorry, I mean)"
NEG = "voice: someone writing with heavy negation and double negatives (don't not, nothing but, anything except)"


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


def event(actor: str, kind: str, when: Json, **extra: Any) -> Json:
    """A manoeuvre started by a trigger (reach a place, a distance, a time)."""
    return call("add_event", actor=actor, manoeuvre={"kind": kind, **extra}, when=when)


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
def _selecting(
    kind: str,
    category: str | list[str] | None,
    asset: str | None,
    scope: str | None,
    min_count: int | None,
    require_all: bool | None,
    **extra: Any,
) -> Json:
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


def near(
    target: str | None,
    within: float,
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    scope: str | None = None,
    min_count: int | None = None,
    every: bool = False,
    point: tuple[float, float] | None = None,
) -> Json:
    out = _selecting("near", category, asset, scope, min_count, True if every else None, within=within)
    if point is not None:
        out["point"] = list(point)
    else:
        out["target"] = target
    return out


def relative(
    relation: str,
    target: str,
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    max_distance: float | None = None,
    tolerance_deg: float | None = None,
    every: bool = False,
) -> Json:
    return _selecting(
        "relative",
        category,
        asset,
        None,
        None,
        True if every else None,
        relation=relation,
        target=target,
        max_distance=max_distance,
        tolerance_deg=tolerance_deg,
    )


def on(
    surfaces: list[str], category: str | list[str] | None = None, *, asset: str | None = None, scope: str | None = None
) -> Json:
    return _selecting("on_surface", category, asset, scope, None, None, surfaces=surfaces)


def in_lane(
    lane: str | None,
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    scope: str | None = None,
    aligned: bool | None = None,
) -> Json:
    return _selecting("in_lane", category, asset, scope, None, None, lane=lane, aligned=aligned)


def layout(
    shape: str,
    category: str | list[str],
    min_count: int,
    *,
    around: str | None = None,
    tolerance: float | None = None,
    spacing_min: float | None = None,
    spacing_max: float | None = None,
    scope: str | None = None,
) -> Json:
    return _selecting(
        "arrangement",
        category,
        None,
        scope,
        min_count,
        None,
        shape=shape,
        around=around,
        tolerance=tolerance,
        spacing_min=spacing_min,
        spacing_max=spacing_max,
    )


def does(
    behaviour: str | list[str],
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    scope: str | None = None,
    min_count: int | None = None,
    **params: Any,
) -> Json:
    return _selecting("behaviour", category, asset, scope, min_count, None, behaviour=behaviour, **params)


def env(**fields: Any) -> Json:
    return {"kind": "environment", **fields}


def looks(
    colour: str | list[str] | None = None,
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    scope: str | None = None,
    tolerance: float | None = None,
    material: str | None = None,
    every: bool = False,
    min_count: int | None = None,
) -> Json:
    return _selecting(
        "appearance",
        category,
        asset,
        scope,
        min_count,
        True if every else None,
        colour=colour,
        colour_tolerance=tolerance,
        material=material,
    )


def moved(
    asset: str,
    lo: float = 0.0,
    hi: float | None = None,
    direction: str | None = None,
    turn_min: float | None = None,
    turn_max: float | None = None,
) -> Json:
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
    return {"kind": "scenario", "seconds": seconds, "expect": [{"kind": "event", "actor": actor, "manoeuvre": kind}]}


def stops_before(actor: str, x: float, y: float, seconds: float = 20.0) -> Json:
    """Run the scene: `actor` never crosses the point (x, y) it drives towards and ends stopped."""
    return {
        "kind": "scenario",
        "seconds": seconds,
        "expect": [{"kind": "stopped_before", "actor": actor, "line": [x, y]}],
    }


def reaches(actor: str, place: str, seconds: float, within: float = 4.0) -> Json:
    """Run the scene: `actor` comes within `within` metres of `place`."""
    return {
        "kind": "scenario",
        "seconds": seconds,
        "expect": [{"kind": "reached", "actor": actor, "place": place, "within": within}],
    }


# --- Cases -------------------------------------------------------------------------------------
def case(
    task: str,
    grade: str,
    name: str,
    voice: str,
    prompt: str,
    checks: list[Json],
    reference: list[Json],
    *,
    setup: Sequence[Json] = (),
    alternatives: Sequence[list[Json]] = (),
    tags: Sequence[str] = (),
) -> Json:
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


def impossible(
    task: str, grade: str, name: str, voice: str, prompt: str, reference: list[Json], *, setup: Sequence[Json] = ()
) -> Json:
    """A request the world cannot do: the right outcome is a refusal that changes nothing.

    The reference is the call a literal reading makes, which the Workers refuse."""
    return case(task, grade, name, voice, prompt, [refused(), only()], reference, setup=setup, tags=("impossible",))


# --- Search: questions that must change nothing, whose answer names the right thing -----------
def ask(
    grade: str,
    name: str,
    voice: str,
    prompt: str,
    answer: Sequence[str],
    reference: list[Json],
    *,
    any_of: Sequence[str] = (),
    setup: Sequence[Json] = (),
) -> Json:
    """A question: the answer names what is asked for and the scene stays as it was."""
    return case(
        "search", grade, name, voice, prompt, [says(all_of=answer, any_of=any_of), only()], reference, setup=setup
    )


# Earlier turns several cases share.
TRUCK_AT_JTEKT = turn(
    "Park my truck in front of the JTEKT building entrance, in the drop-off.",
    add(TRUCK, 1, loc("in_front_of", JTEKT)),
    planned=True,
)
TRUCK_IN_LOT_B = turn("Add my food truck in lot B, parked.", add(TRUCK, 1, loc("at", LOT_B)))
TRUCK_ID = "truck_1"

SEARCH_CASES: list[Json] = [
    # direct
    ask(
        "direct",
        "hydrant_range",
        COP,
        "For the collision report: state the straight-line distance from Vehicle A (the ego) to the fire hydrant on "
        "the north footway of Main Street.",
        ["76.3"],
        [measure(HYDRANT)],
    ),
    ask(
        "direct",
        "bearing_to_bus_stop",
        SAIL,
        "Give me range and bearing from the ego to the bus stop.",
        ["30.2"],
        [measure(EGO, BUS_STOP)],
        any_of=["east"],
    ),
    ask(
        "direct",
        "wheelie_bins",
        AUS,
        "How many wheelie bins are there on campus, and where are they?",
        ["trash_bin_1", "-33.5"],
        [find(category=BIN_KIND)],
    ),
    ask(
        "direct",
        "lot_by_union",
        TRUCKIE,
        "Which parking lot is closest to the Student Union entrance? That's where my lunch crowd comes from.",
        ["parking lot B"],
        [landmarks(nearest_to=UNION)],
    ),
    ask(
        "direct",
        "signals_sitrep",
        MIL,
        "Sitrep: list every traffic signal on the grid, with positions.",
        ["traffic_light_1", "traffic_light_2"],
        [find(category=SIGNAL)],
    ),
    ask(
        "direct",
        "lane_width",
        STUDY,
        "What is the width of one lane of Main Street? I need it for the crossing-distance variable in my study.",
        ["3.5"],
        [lanes(road="Main Street")],
    ),
    ask(
        "direct",
        "bench_coordinates",
        POET,
        "Where, exactly, does the bench keep its vigil beside the bus stop? Give me its coordinates.",
        ["-26", "-6.9"],
        [properties(asset=BENCH)],
    ),
    ask(
        "direct",
        "suv_to_union",
        SELF,
        "How far is the SUV from the ego — no, sorry, from the Student Union entrance, not the ego.",
        ["21.5"],
        [measure(SUV, UNION)],
    ),
    ask(
        "direct",
        "lamp_not_south",
        NEG,
        "Don't change anything. Which street light, not counting any on the south side, stands nearest the lot A "
        "entrance?",
        ["street_light_1"],
        [find(category=LAMP, nearest_to=LOT_A_ENTRANCE)],
    ),
    ask(
        "direct",
        "vehicle_a_lane_speed",
        COP,
        "Vehicle A is the ego. What lane is it travelling in, and at what speed, and what's the weather at the scene?",
        ["main_eastbound", "5", "clear"],
        [properties(asset=EGO), environment()],
    ),
    impossible(
        "search",
        "direct",
        "servo_distance",
        AUS,
        "How far's the nearest servo from the ego? Might need to fill up.",
        [measure("servo")],
    ),
    # indirect
    ask(
        "indirect",
        "moored_in_lot_b",
        SAIL,
        "Before I bring anything alongside in lot B I'd want to know what's already moored in there.",
        [CAR_1, SUV, CAR_2],
        [find(near=LOT_B, within=1)],
    ),
    ask(
        "indirect",
        "landmark_by_grid_ref",
        MIL,
        "Need the name of the nearest landmark to grid ref 60, 40 before we move out.",
        ["fountain"],
        [landmarks(nearest_to="60, 40")],
    ),
    ask(
        "indirect",
        "crosswalks_for_preregistration",
        STUDY,
        "My pre-registration has to say how many marked crosswalks the site has, so I'd like them listed.",
        ["west crosswalk", "north crosswalk"],
        [landmarks(query="crosswalk")],
    ),
    ask(
        "indirect",
        "bin_by_the_stop",
        TRUCKIE,
        "My customers always wait at the bus stop with their food, so it'd help to know whether there's a bin within "
        "ten metres of it.",
        ["trash_bin_1"],
        [find(category=BIN_KIND, near=BUS_STOP, within=10)],
    ),
    ask(
        "indirect",
        "what_sky",
        POET,
        "I long to know what sky the campus wears this hour — its weather, and its time.",
        ["clear", "12:00"],
        [environment()],
    ),
    ask(
        "indirect",
        "ute_north",
        AUS,
        "If I sent a ute north up Campus Drive, which lane would it be in? Just asking, don't add one.",
        ["campus_northbound"],
        [lanes(road="Campus Drive")],
    ),
    ask(
        "indirect",
        "no_tree_by_fountain",
        NEG,
        "I'm not asking you to add or remove anything; I just don't know whether there's no tree within ten metres of "
        "the fountain.",
        ["tree_2"],
        [find(category=TREE, near=FOUNTAIN, within=10)],
    ),
    ask(
        "indirect",
        "hydrant_to_crosswalk",
        COP,
        "The reporting party states the hydrant was struck near the north crosswalk. For my diagram I need the "
        "distance between the hydrant and that crosswalk.",
        ["17.1"],
        [measure(HYDRANT, NORTH_CROSSWALK)],
    ),
    ask(
        "indirect",
        "lamp_by_the_stop",
        SELF,
        "I need the lamp nearest the library, or actually — the one nearest the bus stop, that's the one I care about.",
        ["street_light_4"],
        [find(category=LAMP, nearest_to=BUS_STOP)],
    ),
    ask(
        "indirect",
        "where_is_my_truck",
        TRUCKIE,
        "Hang on, where did my truck end up? I want to tell my regulars where to find it.",
        [TRUCK_ID],
        [find(category=TRUCK)],
        setup=[TRUCK_AT_JTEKT],
    ),
    impossible(
        "search",
        "indirect",
        "harbour_master",
        SAIL,
        "I'd like the range from the ego to the harbour master's office, if you'd be so kind.",
        [measure("harbour master's office")],
    ),
    # vague
    ask(
        "vague",
        "bus_stop_company",
        POET,
        "What keeps the bus stop company?",
        [BENCH, BIN],
        [find(near=BUS_STOP, within=10)],
    ),
    ask("vague", "weather_sitrep", MIL, "Weather sitrep.", ["clear"], [environment()]),
    ask("vague", "parked_by_union", TRUCKIE, "Anything parked near the union?", [SUV], [find(near=UNION, within=30)]),
    ask("vague", "vehicle_a_where", COP, "Vehicle A — position?", ["-60"], [properties(asset=EGO)]),
    ask(
        "vague",
        "lanes_for_site",
        STUDY,
        "Lanes, for the site description?",
        [EASTBOUND, WESTBOUND, NORTHBOUND, SOUTHBOUND],
        [lanes()],
    ),
    ask("vague", "lamp_posts", AUS, "How many lamp posts have we got?", ["12"], [find(category=LAMP)]),
    ask(
        "vague",
        "nearest_to_ego",
        NEG,
        "Nothing but the nearest thing to the ego, please.",
        ["street_light_2"],
        [find(nearest_to=EGO)],
    ),
    ask("vague", "bench_not_bin", SELF, "the bin — no, the bench. how far from the ego?", ["34.4"], [measure(BENCH)]),
    ask(
        "vague",
        "abeam_the_fountain",
        SAIL,
        "What's lying abeam the fountain?",
        ["tree_2"],
        [find(near=FOUNTAIN, within=15)],
    ),
    ask(
        "vague",
        "that_truck_again",
        TRUCKIE,
        "And the distance from there to the ego?",
        ["102.2"],
        [measure(TRUCK_ID)],
        setup=[TRUCK_IN_LOT_B, turn("Where's my truck now?", find(category=TRUCK))],
    ),
    impossible("search", "vague", "any_roos", AUS, "Any roos about?", [find(category="kangaroo")]),
    # erroneous
    ask(
        "erroneous",
        "sign_to_crosswalk",
        COP,
        "wats the distnce betwen the stop sign and the west crosswalk, for the statment",
        ["5.9"],
        [measure(STOP_SIGN, WEST_CROSSWALK)],
    ),
    ask(
        "erroneous",
        "lamp_by_east_gate",
        SAIL,
        "wich lamp is closest too the east gate, over",
        ["street_light_12"],
        [find(category=LAMP, nearest_to=EAST_GATE)],
    ),
    ask(
        "erroneous",
        "wheely_bins",
        AUS,
        "hw many wheely bins r there, and the bench, where its at",
        ["trash_bin_1", "bench_1"],
        [find(category=BIN_KIND), find(category=BENCH_KIND)],
    ),
    ask(
        "erroneous",
        "jtekt_to_lot_b",
        TRUCKIE,
        "hw far is the JTEKT entrence from the lot B entrence, for my truk run",
        ["20.8"],
        [measure(JTEKT, LOT_B_ENTRANCE)],
    ),
    ask(
        "erroneous",
        "nerest_tree",
        MIL,
        "req grid ref of the nerest tree to the ego, over",
        ["tree_1", "-26"],
        [find(category=TREE, nearest_to=EGO)],
    ),
    ask(
        "erroneous",
        "landmark_by_stop",
        STUDY,
        "wich landmark is closest to the bus stp? for the particpant start points",
        ["Library entrance"],
        [landmarks(nearest_to=BUS_STOP)],
    ),
    ask(
        "erroneous",
        "fountian_to_libary",
        POET,
        "how far dose the fountian sit from the libary, in meters of longing",
        ["128.4"],
        [measure(FOUNTAIN, LIBRARY)],
    ),
    ask(
        "erroneous",
        "car_two_not_one",
        SELF,
        "how far is car 1 from, no sory, car 2 from the ego",
        ["95.9"],
        [measure(CAR_2)],
    ),
    ask(
        "erroneous",
        "no_other_bench",
        NEG,
        "dont move nothing, just tell me, isnt there no bench besides the one at the bus stop?",
        ["bench_1"],
        [find(category=BENCH_KIND)],
    ),
    ask(
        "erroneous",
        "were_my_truk",
        TRUCKIE,
        "were is my truk now? which lane its in?",
        [TRUCK_ID],
        [properties(asset=TRUCK_ID)],
        setup=[
            turn(
                "Put my food truck at the lot B entrance so customers see it from the road.",
                add(TRUCK, 1, loc("at", LOT_B_ENTRANCE)),
                planned=True,
            )
        ],
    ),
    ask(
        "erroneous",
        "wether_and_heading",
        SAIL,
        "hows the wether up top, and wich way does the fountian lie from the ego",
        ["clear", "east"],
        [environment(), measure(EGO, FOUNTAIN)],
    ),
]

# --- Addition: new assets of the right kind, in the right number and place --------------------
PARTICIPANT_AT_WEST = turn(
    "Add one participant standing at the west crosswalk for condition A.",
    add(PERSON, 1, loc("at", WEST_CROSSWALK)),
    planned=True,
)

ADDITION_CASES: list[Json] = [
    # direct
    case(
        "addition",
        "direct",
        "cones_by_stop_sign",
        SELF,
        "Add three traffic cones next to the stop sign — sorry, four. Four cones.",
        [delta(CONE, 4, 4), near(STOP_SIGN, 8, CONE, every=True), only(CONE)],
        [add(CONE, 4, loc("next_to", STOP_SIGN))],
    ),
    case(
        "addition",
        "direct",
        "participant_at_bus_stop",
        STUDY,
        "Add one participant — a pedestrian — standing at the bus stop.",
        [delta(PERSON, 1, 1), near(BUS_STOP, 5, PERSON), only(PERSON)],
        [add(PERSON, 1, loc("at", BUS_STOP))],
    ),
    case(
        "addition",
        "direct",
        "ute_in_lot_a",
        AUS,
        "Chuck a ute in the car park at lot A, parked.",
        [delta([TRUCK, CAR], 1, 1), near(LOT_A, 1, [TRUCK, CAR]), does("parked", [TRUCK, CAR]), only(TRUCK, CAR)],
        [add(TRUCK, 1, loc("at", LOT_A))],
    ),
    case(
        "addition",
        "direct",
        "food_truck_at_jtekt",
        TRUCKIE,
        "Add a truck — my food truck — parked in front of the JTEKT building entrance.",
        [delta(TRUCK, 1, 1), near(JTEKT, 10, TRUCK), only(TRUCK)],
        [add(TRUCK, 1, loc("in_front_of", JTEKT))],
    ),
    case(
        "addition",
        "direct",
        "barrier_at_twelve",
        MIL,
        "Place one road barrier at the ego's 12 o'clock, 20 metres out.",
        [
            delta(BARRIER, 1, 1),
            relative("in_front_of", EGO, BARRIER, max_distance=26, tolerance_deg=20),
            in_lane(EASTBOUND, BARRIER),
            only(BARRIER),
        ],
        [add(BARRIER, 1, ahead_of(EGO, 20))],
    ),
    case(
        "addition",
        "direct",
        "bicycles_by_library",
        POET,
        "Add two bicycles resting by the Library entrance, like commas in a long sentence.",
        [delta(BIKE, 2, 2), near(LIBRARY, 8, BIKE, every=True), only(BIKE)],
        [add(BIKE, 2, loc("at", LIBRARY))],
    ),
    case(
        "addition",
        "direct",
        "car_dead_ahead",
        SAIL,
        "Add a car dead ahead of the ego, fifteen metres off, in the same lane.",
        [
            delta(CAR, 1, 1),
            relative("in_front_of", EGO, CAR, max_distance=20, tolerance_deg=20),
            in_lane(EASTBOUND, CAR),
            only(CAR),
        ],
        [add(CAR, 1, ahead_of(EGO, 15))],
    ),
    case(
        "addition",
        "direct",
        "rubble_and_sign",
        COP,
        "Add cement rubble at the point of impact, the centre of the intersection, and a construction sign on the "
        "corner by the stop sign.",
        [
            delta(RUBBLE, 1, 1),
            near(JUNCTION, 1, RUBBLE),
            delta(WORK_SIGN, 1, 1),
            near(STOP_SIGN, 6, WORK_SIGN),
            only(RUBBLE, WORK_SIGN),
        ],
        [add(RUBBLE, 1, loc("at", JUNCTION)), add(WORK_SIGN, 1, loc("next_to", STOP_SIGN))],
    ),
    impossible(
        "addition",
        "direct",
        "kangaroo",
        AUS,
        "Add a kangaroo hopping across Main Street.",
        [add("kangaroo", 1, loc("at", WEST_CROSSWALK))],
    ),
    # indirect
    case(
        "addition",
        "indirect",
        "cones_north_crosswalk",
        NEG,
        "I don't want nobody driving into the workers at the north crosswalk, so don't not put cones there — five of "
        "them.",
        [delta(CONE, 5, 5), near(NORTH_CROSSWALK, 8, CONE, every=True), only(CONE)],
        [add(CONE, 5, loc("at", NORTH_CROSSWALK))],
    ),
    case(
        "addition",
        "indirect",
        "customers_by_hydrant",
        TRUCKIE,
        "My lunch crowd needs to look real: I'd like three customers waiting next to the hydrant.",
        [delta(PERSON, 3, 3), near(HYDRANT, 6, PERSON, every=True), only(PERSON)],
        [add(PERSON, 3, loc("next_to", HYDRANT))],
    ),
    case(
        "addition",
        "indirect",
        "condition_b_north",
        STUDY,
        "Condition B is the same, only at the north crosswalk, so I need one more participant there.",
        [delta(PERSON, 1, 1), near(NORTH_CROSSWALK, 5, PERSON, scope="added"), only(PERSON)],
        [add(PERSON, 1, loc("at", NORTH_CROSSWALK))],
        setup=[PARTICIPANT_AT_WEST],
    ),
    case(
        "addition",
        "indirect",
        "debris_at_skid_marks",
        COP,
        "The skid marks begin about 25 m ahead of Vehicle A, and whatever the driver swerved for should be there "
        "too — some debris in the lane.",
        [
            delta(RUBBLE, 1, 1),
            relative("in_front_of", EGO, RUBBLE, max_distance=31, tolerance_deg=20),
            in_lane(EASTBOUND, RUBBLE),
            only(RUBBLE),
        ],
        [add(RUBBLE, 1, ahead_of(EGO, 25))],
    ),
    case(
        "addition",
        "indirect",
        "light_for_lot_a",
        POET,
        "The lot A entrance languishes in shadow; one more street light there would lift its gloom.",
        [delta(LAMP, 1, 1), near(LOT_A_ENTRANCE, 8, LAMP, scope="added"), only(LAMP)],
        [add(LAMP, 1, loc("at", LOT_A_ENTRANCE))],
    ),
    case(
        "addition",
        "indirect",
        "bus_alongside_stop",
        SAIL,
        "The shuttle stop looks deserted. A bus lying alongside it, with two passengers waiting to board, would make "
        "it believable.",
        [
            delta(BUS, 1, 1),
            near(BUS_STOP, 10, BUS),
            delta(PERSON, 2, 2),
            near(BUS_STOP, 8, PERSON, every=True),
            only(BUS, PERSON),
        ],
        [add(BUS, 1, loc("at", BUS_STOP)), add(PERSON, 2, loc("at", BUS_STOP))],
    ),
    case(
        "addition",
        "indirect",
        "bins_for_union",
        AUS,
        "The Student Union crowd leave rubbish everywhere, so it'd be good to have two wheelie bins out front.",
        [delta(BIN_KIND, 2, 2), near(UNION, 8, BIN_KIND, every=True), only(BIN_KIND)],
        [add(BIN_KIND, 2, loc("in_front_of", UNION))],
    ),
    case(
        "addition",
        "indirect",
        "recon_robot",
        MIL,
        "Recon asset required in lot B: a mid-scale robot, staged and parked.",
        [delta(ROBOT, 1, 1), near(LOT_B, 1, ROBOT), only(ROBOT)],
        [add(ROBOT, 1, loc("at", LOT_B))],
    ),
    case(
        "addition",
        "indirect",
        "quay_by_fountain",
        SAIL,
        "The quay by the fountain looks bare: a couple of benches to sit and watch the water from, and a bin for "
        "the gulls' leftovers, would do it.",
        [
            delta(BENCH_KIND, 2, 2),
            delta(BIN_KIND, 1, 1),
            near(FOUNTAIN, 8, [BENCH_KIND, BIN_KIND], scope="added", every=True),
            only(BENCH_KIND, BIN_KIND),
        ],
        [add(BENCH_KIND, 2, loc("next_to", FOUNTAIN)), add(BIN_KIND, 1, loc("next_to", FOUNTAIN))],
    ),
    # vague
    case(
        "addition",
        "vague",
        "few_participants",
        STUDY,
        "A few participants by the library, please.",
        [delta(PERSON, 2, 6), near(LIBRARY, 10, PERSON, every=True), only(PERSON)],
        [add(PERSON, 3, loc("at", LIBRARY))],
    ),
    case(
        "addition",
        "vague",
        "something_green",
        POET,
        "Plant something green and tall beside the bench at the bus stop.",
        [delta(TREE, 1, 1), near(BENCH, 6, TREE), only(TREE)],
        [add(TREE, 1, loc("next_to", BENCH))],
    ),
    case(
        "addition",
        "vague",
        "more_traffic",
        MIL,
        "More traffic on Main. Oscar mike.",
        [delta(MOTOR_TRAFFIC, 1, None), only(*MOTOR_TRAFFIC)],
        [add(CAR, 2, loc("in_lane", EGO, lane=WESTBOUND), behaviour=drive(lane=WESTBOUND))],
        alternatives=[[does("drive_lane", MOTOR_TRAFFIC, scope="added", lane=lane)] for lane in (EASTBOUND, WESTBOUND)],
    ),
    case(
        "addition",
        "vague",
        "not_many_cones",
        NEG,
        "Not a lot of cones — no more than two — at the lot B entrance.",
        [delta(CONE, 1, 2), near(LOT_B_ENTRANCE, 8, CONE, every=True), only(CONE)],
        [add(CONE, 2, loc("at", LOT_B_ENTRANCE))],
    ),
    case(
        "addition",
        "vague",
        "truck_at_east_gate",
        TRUCKIE,
        "My truck, east gate, somewhere there.",
        [delta(TRUCK, 1, 1), near(EAST_GATE, 15, TRUCK), only(TRUCK)],
        [add(TRUCK, 1, loc("at", EAST_GATE))],
    ),
    case(
        "addition",
        "vague",
        "pushbike_on_footpath",
        AUS,
        "Pushbike on the footpath by the bus stop, mate.",
        [delta(BIKE, 1, 1), near(BUS_STOP, 6, BIKE), only(BIKE)],
        [add(BIKE, 1, loc("on_sidewalk", BUS_STOP))],
    ),
    case(
        "addition",
        "vague",
        "witness_on_corner",
        COP,
        "Need a witness by the traffic light on the south-west corner.",
        [delta(PERSON, 1, 1), near(LIGHT_SW, 5, PERSON), only(PERSON)],
        [add(PERSON, 1, loc("next_to", LIGHT_SW))],
    ),
    case(
        "addition",
        "vague",
        "another_of_those",
        SELF,
        "another one of those. no — two more.",
        [delta(BENCH_KIND, 2, 2), near(FOUNTAIN, 15, BENCH_KIND, scope="added", every=True), only(BENCH_KIND)],
        [add(BENCH_KIND, 2, loc("next_to", FOUNTAIN))],
        setup=[turn("Add a bench next to the fountain.", add(BENCH_KIND, 1, loc("next_to", FOUNTAIN)))],
    ),
    impossible(
        "addition",
        "vague",
        "thousand_participants",
        STUDY,
        "All my participants at the north crosswalk — a thousand of them.",
        [add(PERSON, 1000, loc("at", NORTH_CROSSWALK))],
    ),
    # erroneous
    case(
        "addition",
        "erroneous",
        "for_cones_no_five",
        SELF,
        "ad for cones, no wait five, at the lot B entrence",
        [delta(CONE, 5, 5), near(LOT_B_ENTRANCE, 8, CONE, every=True), only(CONE)],
        [add(CONE, 5, loc("at", LOT_B_ENTRANCE))],
    ),
    case(
        "addition",
        "erroneous",
        "bench_benaeth_tree",
        POET,
        "lay a bench benaeth the tree by the fountian",
        [delta(BENCH_KIND, 1, 1), near(TREE_FOUNTAIN, 6, BENCH_KIND), only(BENCH_KIND)],
        [add(BENCH_KIND, 1, loc("next_to", TREE_FOUNTAIN))],
    ),
    case(
        "addition",
        "erroneous",
        "participant_trail_3",
        STUDY,
        "add two particpant at the engeneering hall entrence for trail 3, and a nother one at the libary",
        [delta(PERSON, 3, 3), near(ENGINEERING, 6, PERSON, min_count=2), near(LIBRARY, 6, PERSON), only(PERSON)],
        [add(PERSON, 2, loc("at", ENGINEERING)), add(PERSON, 1, loc("at", LIBRARY))],
    ),
    case(
        "addition",
        "erroneous",
        "bench_and_wheely_bin",
        AUS,
        "put a bench out the front of the libary, an a wheely bin rite next to it",
        [
            delta(BENCH_KIND, 1, 1),
            delta(BIN_KIND, 1, 1),
            near(LIBRARY, 8, BENCH_KIND, scope="added"),
            near(LIBRARY, 10, BIN_KIND, scope="added"),
            only(BENCH_KIND, BIN_KIND),
        ],
        [add(BENCH_KIND, 1, loc("in_front_of", LIBRARY)), add(BIN_KIND, 1, loc("next_to", "bench_2"))],
    ),
    case(
        "addition",
        "erroneous",
        "truk_library_drop_of",
        TRUCKIE,
        "add my food truk parked at the library drop of",
        [delta(TRUCK, 1, 1), near(LIBRARY, 10, TRUCK), only(TRUCK)],
        [add(TRUCK, 1, loc("in_front_of", LIBRARY))],
    ),
    case(
        "addition",
        "erroneous",
        "barriers_six_oclock",
        MIL,
        "emplace 2 barriers at the ego 6 oclock, 15 meter",
        [
            delta(BARRIER, 2, 2),
            relative("behind", EGO, BARRIER, max_distance=22, tolerance_deg=20, every=True),
            only(BARRIER),
        ],
        [add(BARRIER, 2, ahead_of(EGO, -15))],
    ),
    case(
        "addition",
        "erroneous",
        "motorbike_port",
        SAIL,
        "add a motorbike on the ego's port side, abeem of it",
        [delta(MOTORBIKE, 1, 1), relative("left_of", EGO, MOTORBIKE, max_distance=8), only(MOTORBIKE)],
        [add(MOTORBIKE, 1, loc("left_of", EGO))],
    ),
    case(
        "addition",
        "erroneous",
        "parking_sign_lot",
        COP,
        "instal a parkin sign at the lot A entrace, for the diagram",
        [delta(PARK_SIGN, 1, 1), near(LOT_A_ENTRANCE, 8, PARK_SIGN), only(PARK_SIGN)],
        [add(PARK_SIGN, 1, loc("at", LOT_A_ENTRANCE))],
    ),
    impossible(
        "addition",
        "erroneous",
        "five_klicks_north",
        MIL,
        "add 1 truck 5 klicks north of the ego, grid ref -60, 5000",
        [add(TRUCK, 1, xy(-60, 5000))],
    ),
]

# --- Removal: the right things gone, the rest kept ----------------------------------------------
REMOVAL_CASES: list[Json] = [
    # direct
    case(
        "removal",
        "direct",
        "bench_not_bin",
        SELF,
        "Remove the bin at the bus stop — no, not the bin, the bench.",
        [gone(BENCH), kept(BIN), only(assets=[BENCH])],
        [remove(BENCH)],
    ),
    case(
        "removal",
        "direct",
        "destroyed_hydrant",
        COP,
        "Remove the fire hydrant; the reporting party says it was destroyed in the collision.",
        [gone(HYDRANT), only(assets=[HYDRANT])],
        [remove(HYDRANT)],
    ),
    case(
        "removal",
        "direct",
        "stand_down_stop_sign",
        MIL,
        "Stop sign: stand down. Remove it from the grid.",
        [gone(STOP_SIGN), only(assets=[STOP_SIGN])],
        [remove(STOP_SIGN)],
    ),
    case(
        "removal",
        "direct",
        "cars_but_suv",
        NEG,
        "Remove every car in lot B except the SUV.",
        [gone(CAR_1, CAR_2), kept(SUV), only(assets=[CAR_1, CAR_2])],
        [remove(CAR_1, CAR_2)],
    ),
    case(
        "removal",
        "direct",
        "fell_the_tree",
        POET,
        "Fell the tree that stands guard just north of lot A.",
        [gone(TREE_LOT_A), kept(TREE_LIBRARY, TREE_FOUNTAIN, TREE_EAST), only(assets=[TREE_LOT_A])],
        [remove(TREE_LOT_A)],
    ),
    case(
        "removal",
        "direct",
        "bin_off_footpath",
        AUS,
        "Get rid of the wheelie bin on the footpath.",
        [gone(BIN), only(assets=[BIN])],
        [remove(BIN)],
    ),
    case(
        "removal",
        "direct",
        "starboard_lamps",
        SAIL,
        "Remove all the street lights on the starboard side of Main Street as you head east.",
        [
            gone(*SOUTH_LAMPS),
            kept(*NORTH_WEST_LAMPS, "street_light_7", "street_light_9", "street_light_11"),
            only(assets=SOUTH_LAMPS),
        ],
        [remove(*SOUTH_LAMPS)],
    ),
    case(
        "removal",
        "direct",
        "suv_and_move_car",
        TRUCKIE,
        "Remove the SUV from lot B, it's sitting on my pitch, and put the first car over in lot A.",
        [gone(SUV), near(LOT_A, 1, asset=CAR_1), only(assets=[SUV, CAR_1])],
        [remove(SUV), place(CAR_1, loc("at", LOT_A))],
    ),
    impossible(
        "removal", "direct", "remove_the_ego", MIL, "Remove the ego vehicle from the grid entirely.", [remove(EGO)]
    ),
    # indirect
    case(
        "removal",
        "indirect",
        "condition_a_done",
        STUDY,
        "Condition A is finished, so those cones need to go.",
        [count(CONE, 0, 0), only(CONE)],
        [remove(category=CONE)],
        setup=[
            turn(
                "Put four cones at the west crosswalk for condition A.",
                add(CONE, 4, loc("at", WEST_CROSSWALK)),
                planned=True,
            )
        ],
    ),
    case(
        "removal",
        "indirect",
        "open_sky_for_fountain",
        POET,
        "The fountain deserves an open sky; the tree crowding it shouldn't be there.",
        [gone(TREE_FOUNTAIN), kept(TREE_LIBRARY, TREE_LOT_A), only(assets=[TREE_FOUNTAIN, TREE_EAST])],
        [remove(TREE_FOUNTAIN)],
    ),
    case(
        "removal",
        "indirect",
        "hydrant_blocks_pitch",
        TRUCKIE,
        "My truck can't park on Main Street with a hydrant right there, so that hydrant has to go.",
        [gone(HYDRANT), only(assets=[HYDRANT])],
        [remove(HYDRANT)],
    ),
    case(
        "removal",
        "indirect",
        "glare_by_lot_a",
        SAIL,
        "The lamp by lot A's entrance throws glare across the water — the road, I mean — so I'd rather not have it.",
        [gone(LAMP_LOT_A), only(assets=[LAMP_LOT_A])],
        [remove(LAMP_LOT_A)],
    ),
    case(
        "removal",
        "indirect",
        "bench_obstructed_view",
        COP,
        "The bench at the bus stop obstructed the reporting party's view, and it wasn't there on the day, so it "
        "shouldn't be in the reconstruction.",
        [gone(BENCH), only(assets=[BENCH])],
        [remove(BENCH)],
    ),
    case(
        "removal",
        "indirect",
        "sedans_are_clutter",
        AUS,
        "The two sedans in lot B are just clutter, mate. I'd lose 'em.",
        [gone(CAR_1, CAR_2), kept(SUV), only(assets=[CAR_1, CAR_2])],
        [remove(CAR_1, CAR_2)],
    ),
    case(
        "removal",
        "indirect",
        "lamps_compromise_concealment",
        MIL,
        "North-side lamps west of Campus Drive are compromising concealment. Need them gone.",
        [gone(*NORTH_WEST_LAMPS), kept(*SOUTH_LAMPS, "street_light_7"), only(assets=NORTH_WEST_LAMPS)],
        [remove(*NORTH_WEST_LAMPS)],
    ),
    case(
        "removal",
        "indirect",
        "council_says_no",
        TRUCKIE,
        "Council says I can't trade at the east gate, so my truck's got to leave.",
        [gone(TRUCK_ID), only(TRUCK)],
        [remove(category=TRUCK)],
        setup=[turn("Add my truck at the east gate.", add(TRUCK, 1, loc("at", EAST_GATE)))],
    ),
    impossible(
        "removal",
        "indirect",
        "cracked_footpath",
        AUS,
        "The footpath on the south side is all cracked, so I'd want it pulled out.",
        [remove(SOUTH_WEST_WALK)],
    ),
    # vague
    case(
        "removal",
        "vague",
        "nothing_but_the_bench",
        NEG,
        "Nothing at the bus stop but the bench should stay.",
        [gone(BIN), kept(BENCH), only(assets=[BIN, TREE_LIBRARY, LAMP_BUS_STOP])],
        [remove(BIN)],
    ),
    case(
        "removal",
        "vague",
        "clear_lot_b",
        SAIL,
        "Clear lot B.",
        [gone(CAR_1, SUV, CAR_2), only(assets=[CAR_1, SUV, CAR_2])],
        [remove(CAR_1, SUV, CAR_2)],
    ),
    case(
        "removal",
        "vague",
        "lone_tree",
        POET,
        "Take away the lone tree behind the bus stop.",
        [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
        [remove(TREE_LIBRARY)],
    ),
    case(
        "removal",
        "vague",
        "dismiss_them",
        STUDY,
        "Okay, that's the trial. Dismiss them.",
        [count(PERSON, 0, 0), only(PERSON)],
        [remove(category=PERSON)],
        setup=[turn("Three participants at the bus stop, please.", add(PERSON, 3, loc("at", BUS_STOP)))],
    ),
    case(
        "removal",
        "vague",
        "lose_the_signal",
        MIL,
        "Lose the signal at the north-east corner.",
        [gone(LIGHT_NE), kept(LIGHT_SW), only(assets=[LIGHT_NE])],
        [remove(LIGHT_NE)],
    ),
    case(
        "removal",
        "vague",
        "couple_of_lamps_east",
        AUS,
        "Ditch a couple of those lamp posts down the eastern end.",
        [delta(LAMP, -3, -2), kept(*NORTH_WEST_LAMPS, *SOUTH_LAMPS[:3], "street_light_7"), only(LAMP)],
        [remove("street_light_11", "street_light_12")],
    ),
    case(
        "removal",
        "vague",
        "vehicle_b_out",
        COP,
        "Vehicle B: remove.",
        [gone(CAR_2), kept(CAR_1, SUV), only(assets=[CAR_2])],
        [remove(CAR_2)],
        setup=[
            turn(
                "For this report, Vehicle B is passenger car 2, the car at the east end of the row in lot B.",
                properties(asset=CAR_2),
            )
        ],
    ),
    case(
        "removal",
        "vague",
        "just_two_left",
        SELF,
        "fewer cones. half — no, leave just two.",
        [count(CONE, 2, 2), only(CONE)],
        [remove(category=CONE, count=4)],
        setup=[turn("Six cones at the lot B entrance.", add(CONE, 6, loc("at", LOT_B_ENTRANCE)))],
    ),
    impossible(
        "removal",
        "vague",
        "silence_the_fountain",
        POET,
        "Let the fountain fall silent: take it away.",
        [remove("fountain")],
    ),
    # erroneous
    case(
        "removal",
        "erroneous",
        "bench_bus_stopp",
        AUS,
        "get rid of teh bench at the bus stopp and the bin too",
        [gone(BENCH, BIN), only(assets=[BENCH, BIN])],
        [remove(BENCH, BIN)],
    ),
    case(
        "removal",
        "erroneous",
        "rubel_cleared",
        COP,
        "remvoe the rubel from the intersecton, scene is cleard",
        [count(RUBBLE, 0, 0), only(RUBBLE)],
        [remove(category=RUBBLE)],
        setup=[
            turn(
                "Add cement rubble at the point of impact in the middle of the intersection.",
                add(RUBBLE, 1, loc("at", JUNCTION)),
            )
        ],
    ),
    case(
        "removal",
        "erroneous",
        "trees_but_library",
        NEG,
        "remove evry tree except the one by the libary, dont touch nothing else",
        [
            gone(TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A),
            kept(TREE_LIBRARY),
            only(assets=[TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A]),
        ],
        [remove(TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A)],
    ),
    case(
        "removal",
        "erroneous",
        "lamp_neerest_library",
        SAIL,
        "remove lamp neerest to the libary entrence",
        [delta(LAMP, -1, -1), gone(LAMP_BUS_STOP), only(assets=[LAMP_BUS_STOP])],
        [remove(LAMP_BUS_STOP)],
    ),
    case(
        "removal",
        "erroneous",
        "uproot_tre",
        POET,
        "uproot the tre by the fountan, the nearest one",
        [gone(TREE_FOUNTAIN), kept(TREE_EAST), only(assets=[TREE_FOUNTAIN])],
        [remove(TREE_FOUNTAIN)],
    ),
    case(
        "removal",
        "erroneous",
        "signal_neutralise",
        MIL,
        "trafic light south west corner, neutralise. remove",
        [gone(LIGHT_SW), kept(LIGHT_NE), only(assets=[LIGHT_SW])],
        [remove(LIGHT_SW)],
    ),
    case(
        "removal",
        "erroneous",
        "truk_wrong_spot",
        TRUCKIE,
        "sory, take my truk away agian, wrong spot",
        [count(TRUCK, 0, 0), only(TRUCK)],
        [remove(category=TRUCK)],
        setup=[TRUCK_AT_JTEKT],
    ),
    case(
        "removal",
        "erroneous",
        "trail_over",
        STUDY,
        "remov the bin from the bus stop, particpants kept using it, trail over",
        [gone(BIN), only(assets=[BIN])],
        [remove(BIN)],
    ),
    case(
        "removal",
        "erroneous",
        "bin_takes_bench_spot",
        SELF,
        "remove the bin, no wait keep the bin — remove the bech instead, and put the bin were the bench was",
        [gone(BENCH), kept(BIN), near(None, 1.5, asset=BIN, point=(-26, -6.9)), only(assets=[BENCH, BIN])],
        [remove(BENCH), place(BIN, xy(-26, -6.9))],
    ),
]

# --- Positioning: an existing asset put somewhere named --------------------------------------
PED_ID = "pedestrian_1"

POSITIONING_CASES: list[Json] = [
    # direct
    case(
        "positioning",
        "direct",
        "vehicle_b_at_jtekt",
        COP,
        "Place the SUV (Vehicle B) in front of the JTEKT building entrance, where it came to rest.",
        [near(JTEKT, 10, asset=SUV), only(assets=[SUV])],
        [place(SUV, loc("in_front_of", JTEKT))],
    ),
    case(
        "positioning",
        "direct",
        "bench_by_fountain",
        POET,
        "Set the bench beside the fountain, where it may listen to the water.",
        [near(FOUNTAIN, 5, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("next_to", FOUNTAIN))],
    ),
    case(
        "positioning",
        "direct",
        "hydrant_grid_ref",
        MIL,
        "Relocate the fire hydrant to grid ref 30, 5.5.",
        [near(None, 1, asset=HYDRANT, point=(30, 5.5)), only(assets=[HYDRANT])],
        [place(HYDRANT, xy(30, 5.5))],
    ),
    case(
        "positioning",
        "direct",
        "bin_to_lot_a_entrance",
        AUS,
        "Move the wheelie bin up to the lot A entrance.",
        [near(LOT_A_ENTRANCE, 6, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("at", LOT_A_ENTRANCE))],
    ),
    case(
        "positioning",
        "direct",
        "car_on_port_beam",
        SAIL,
        "Put passenger car 1 on the ego's port beam.",
        [relative("left_of", EGO, asset=CAR_1, max_distance=8), only(assets=[CAR_1])],
        [place(CAR_1, loc("left_of", EGO))],
    ),
    case(
        "positioning",
        "direct",
        "waiting_bench_to_north_crosswalk",
        STUDY,
        "Put the bench, where participants sit between trials, next to the north crosswalk.",
        [near(NORTH_CROSSWALK, 6, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("next_to", NORTH_CROSSWALK))],
    ),
    case(
        "positioning",
        "direct",
        "truck_to_lot_b",
        TRUCKIE,
        "Now put my truck in lot B. That's my pitch.",
        [near(LOT_B, 1, asset=TRUCK_ID), only(assets=[TRUCK_ID])],
        [place(TRUCK_ID, loc("at", LOT_B))],
        setup=[turn("Add my truck at the east gate.", add(TRUCK, 1, loc("at", EAST_GATE)), planned=True)],
    ),
    case(
        "positioning",
        "direct",
        "stop_sign_anywhere_but",
        NEG,
        "Put the stop sign anywhere except where it is now: next to the north crosswalk, and nowhere else.",
        [near(NORTH_CROSSWALK, 6, asset=STOP_SIGN), only(assets=[STOP_SIGN])],
        [place(STOP_SIGN, loc("next_to", NORTH_CROSSWALK))],
    ),
    impossible(
        "positioning",
        "direct",
        "bench_indoors",
        SELF,
        "Place the bench at -40, -30 — wait, is that inside the Library? Yes, good, that's right: I want it indoors.",
        [place(BENCH, xy(-40, -30))],
    ),
    # indirect
    case(
        "positioning",
        "indirect",
        "bin_where_customers_are",
        TRUCKIE,
        "My customers toss their wrappers everywhere near the JTEKT entrance, so the bin from the bus stop would be "
        "better off there.",
        [near(JTEKT, 6, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("at", JTEKT))],
    ),
    case(
        "positioning",
        "indirect",
        "suv_at_point_of_impact",
        COP,
        "Vehicle B, the SUV, came to rest at the point of impact in the middle of the intersection; the "
        "reconstruction should show it there.",
        [near(JUNCTION, 1, asset=SUV), only(assets=[SUV])],
        [place(SUV, loc("at", JUNCTION))],
    ),
    case(
        "positioning",
        "indirect",
        "hydrant_off_station",
        SAIL,
        "That hydrant is off station. Its proper berth is on the north footway just west of the west crosswalk, at "
        "-14, 5.5.",
        [near(None, 1.5, asset=HYDRANT, point=(-14, 5.5)), on(["sidewalk"], asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, xy(-14, 5.5))],
    ),
    case(
        "positioning",
        "indirect",
        "bench_in_the_shade",
        POET,
        "The bench bakes in the sun; it would be happier in the shade of the tree north of lot A.",
        [near(TREE_LOT_A, 5, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("next_to", TREE_LOT_A))],
    ),
    case(
        "positioning",
        "indirect",
        "car_to_lot_a",
        AUS,
        "Reckon the first car in lot B would be better off over in lot A, closer to the uni's west end.",
        [near(LOT_A, 1, asset=CAR_1), only(assets=[CAR_1])],
        [place(CAR_1, loc("at", LOT_A))],
    ),
    case(
        "positioning",
        "indirect",
        "next_trial_start",
        STUDY,
        "For the next trial the participant needs to start at the library entrance instead.",
        [near(LIBRARY, 5, asset=PED_ID), only(assets=[PED_ID])],
        [place(PED_ID, loc("at", LIBRARY))],
        setup=[
            turn(
                "Add a participant on the south footpath next to the stop sign.",
                add(PERSON, 1, loc("next_to", STOP_SIGN)),
                planned=True,
            )
        ],
    ),
    case(
        "positioning",
        "indirect",
        "illuminate_engineering",
        MIL,
        "Sector at the Engineering Hall entrance lacks illumination. Relocate the lamp nearest the bus stop there, "
        "and the bin alongside it.",
        [near(ENGINEERING, 8, asset=LAMP_BUS_STOP), near(ENGINEERING, 8, asset=BIN), only(assets=[LAMP_BUS_STOP, BIN])],
        [place(LAMP_BUS_STOP, loc("at", ENGINEERING)), place(BIN, loc("next_to", ENGINEERING))],
    ),
    case(
        "positioning",
        "indirect",
        "stop_sign_wrong_place",
        SELF,
        "The stop sign's in the wrong place; it belongs by the lot A — sorry, the lot B entrance.",
        [near(LOT_B_ENTRANCE, 6, asset=STOP_SIGN), only(assets=[STOP_SIGN])],
        [place(STOP_SIGN, loc("next_to", LOT_B_ENTRANCE))],
    ),
    impossible(
        "positioning",
        "indirect",
        "suv_off_the_map",
        NEG,
        "It wouldn't be wrong to not keep the SUV on the map at all — put it at 0, -300.",
        [place(SUV, xy(0, -300))],
    ),
    # vague
    case(
        "positioning",
        "vague",
        "bench_anywhere_but",
        NEG,
        "The bench: anywhere but the bus stop. The library entrance won't not do.",
        [near(LIBRARY, 6, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("at", LIBRARY))],
    ),
    case(
        "positioning",
        "vague",
        "suv_grid_centre",
        MIL,
        "SUV to the centre of the grid.",
        [near(JUNCTION, 1, asset=SUV), only(assets=[SUV])],
        [place(SUV, loc("scene_centre"))],
    ),
    case(
        "positioning",
        "vague",
        "over_by_the_union",
        TRUCKIE,
        "Hmm, nobody comes to lot A. Over by the union?",
        [near(UNION, 10, asset=TRUCK_ID), only(assets=[TRUCK_ID])],
        [place(TRUCK_ID, loc("in_front_of", UNION))],
        setup=[turn("Park my truck in lot A.", add(TRUCK, 1, loc("at", LOT_A)))],
    ),
    case(
        "positioning",
        "vague",
        "hydrant_keeps_company",
        POET,
        "Let the hydrant keep company with the fountain.",
        [near(FOUNTAIN, 5, asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, loc("next_to", FOUNTAIN))],
    ),
    case(
        "positioning",
        "vague",
        "bin_dumb_spot",
        AUS,
        "Bin's in a dumb spot. Over by the stop sign?",
        [near(STOP_SIGN, 4, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("next_to", STOP_SIGN))],
    ),
    case(
        "positioning",
        "vague",
        "berth_car_two",
        SAIL,
        "Second car: berth her at the east gate.",
        [near(EAST_GATE, 12, asset=CAR_2), only(assets=[CAR_2])],
        [place(CAR_2, loc("at", EAST_GATE))],
    ),
    case(
        "positioning",
        "vague",
        "robot_to_point_of_impact",
        COP,
        "Robot to the point of impact: the west crosswalk.",
        [near(WEST_CROSSWALK, 5, asset="ackermann_robot_1"), only(assets=["ackermann_robot_1"])],
        [place("ackermann_robot_1", loc("at", WEST_CROSSWALK))],
        setup=[turn("Add the delivery robot in lot B.", add(ROBOT, 1, loc("at", LOT_B)))],
    ),
    case(
        "positioning",
        "vague",
        "by_the_hydrant_not_bin",
        SELF,
        "the bench — put it by the bin, er, the fire hydrant, not the bin",
        [near(HYDRANT, 4, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("next_to", HYDRANT))],
    ),
    impossible(
        "positioning",
        "vague",
        "tree_on_the_roof",
        STUDY,
        "Tree on the roof of Engineering Hall, for the 'occluded' condition: about -40, 28.",
        [place(TREE_LOT_A, xy(-40, 28))],
    ),
    # erroneous
    case(
        "positioning",
        "erroneous",
        "suv_infront_union",
        COP,
        "plase vehicle B, the suv, infront of the studnet union",
        [near(UNION, 10, asset=SUV), only(assets=[SUV])],
        [place(SUV, loc("in_front_of", UNION))],
    ),
    case(
        "positioning",
        "erroneous",
        "bech_by_library",
        POET,
        "sit the bech nex too the libary doors, in the quiet",
        [near(LIBRARY, 6, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("next_to", LIBRARY))],
    ),
    case(
        "positioning",
        "erroneous",
        "stop_sign_grid",
        MIL,
        "stop sign relocate grid -20 -5.5 asap",
        [near(None, 1, asset=STOP_SIGN, point=(-20, -5.5)), only(assets=[STOP_SIGN])],
        [place(STOP_SIGN, xy(-20, -5.5))],
    ),
    case(
        "positioning",
        "erroneous",
        "wheelie_bin_union",
        AUS,
        "moove the wheelie bin to the union entrnce",
        [near(UNION, 6, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("at", UNION))],
    ),
    case(
        "positioning",
        "erroneous",
        "suv_ded_astern",
        SAIL,
        "put the suv ded astern of the ego, 10 meter bak",
        [
            relative("behind", EGO, asset=SUV, max_distance=14, tolerance_deg=20),
            in_lane(EASTBOUND, asset=SUV),
            only(assets=[SUV]),
        ],
        [place(SUV, ahead_of(EGO, -10))],
    ),
    case(
        "positioning",
        "erroneous",
        "truk_pich",
        TRUCKIE,
        "put my truk at the libary drop of, thats my new pich",
        [near(LIBRARY, 10, asset=TRUCK_ID), only(assets=[TRUCK_ID])],
        [place(TRUCK_ID, loc("in_front_of", LIBRARY))],
        setup=[turn("Add my truck at the lot A entrance.", add(TRUCK, 1, loc("at", LOT_A_ENTRANCE)), planned=True)],
    ),
    case(
        "positioning",
        "erroneous",
        "hydrant_not_anywere",
        NEG,
        "dont leave the hydrant were it is, put it next the bus stop not anywere else",
        [near(BUS_STOP, 5, asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, loc("next_to", BUS_STOP))],
    ),
    case(
        "positioning",
        "erroneous",
        "bin_for_trail_2",
        STUDY,
        "plase the bin by the libary entrence, the particpants need it there in trail 2",
        [near(LIBRARY, 6, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("at", LIBRARY))],
    ),
    case(
        "positioning",
        "erroneous",
        "bin_and_sign_by_hydrant",
        NEG,
        "put the bin nex to the hydrant an the stop sign nex to the bin, dont move nothing else",
        [near(HYDRANT, 4, asset=BIN), near(HYDRANT, 6, asset=STOP_SIGN), only(assets=[BIN, STOP_SIGN])],
        [place(BIN, loc("next_to", HYDRANT)), place(STOP_SIGN, loc("next_to", BIN))],
    ),
]

# --- Moving: an asset shifted, turned, or set going ------------------------------------------
ROBOT_ID, BIKE_ID = "ackermann_robot_1", "bicycle_1"
DRIVING_TRUCK = turn(
    "Add my truck on Main Street heading east, driving.",
    add(TRUCK, 1, ahead_of(EGO, 20), behaviour=drive(lane=EASTBOUND)),
    planned=True,
)

MOVING_CASES: list[Json] = [
    # direct
    case(
        "moving",
        "direct",
        "ego_advance",
        MIL,
        "Ego: advance ten metres, twelve o'clock.",
        [moved(EGO, 9, 11, "forward"), only(assets=[EGO])],
        [move(EGO, forward=10)],
    ),
    case(
        "moving",
        "direct",
        "car_rolled_back",
        COP,
        "Move passenger car 1 back by 3 metres; the skid marks show it rolled back after the impact.",
        [moved(CAR_1, 2.5, 3.5, "backward"), only(assets=[CAR_1])],
        [move(CAR_1, forward=-3)],
    ),
    case(
        "moving",
        "direct",
        "bring_suv_about",
        SAIL,
        "Bring the SUV about: turn her 180 degrees where she lies.",
        [moved(SUV, 0, 0.5, turn_min=170), only(assets=[SUV])],
        [move(SUV, turn_deg=180)],
    ),
    case(
        "moving",
        "direct",
        "ego_speed_six",
        SELF,
        "Set the ego's speed to 8 — no, 6 metres per second.",
        [does("drive_lane", asset=EGO, speed_min=5.9, speed_max=6.1), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=6, lane=EASTBOUND)],
    ),
    case(
        "moving",
        "direct",
        "participant_crosses",
        STUDY,
        "Add a participant who crosses the road at the west crosswalk.",
        [delta(PERSON, 1, 1), does("cross_road", PERSON, scope="added", crosses_lane=EASTBOUND), only(PERSON)],
        [add(PERSON, 1, loc("at", WEST_CROSSWALK), behaviour={"kind": "cross_road"})],
    ),
    case(
        "moving",
        "direct",
        "bench_toward_morning",
        POET,
        "Slide the bench two metres east, toward the morning.",
        [moved(BENCH, 1.5, 2.5, "backward"), only(assets=[BENCH])],
        [move(BENCH, east=2)],
    ),
    case(
        "moving",
        "direct",
        "car_two_westbound",
        AUS,
        "Make the second car drive west along Main Street at 5 m/s.",
        [does("drive_lane", asset=CAR_2, lane=WESTBOUND, speed_min=4.9, speed_max=5.1), only(assets=[CAR_2])],
        [behave(CAR_2, "drive_lane", lane=WESTBOUND, speed=5)],
    ),
    case(
        "moving",
        "direct",
        "truck_turns_left",
        TRUCKIE,
        "Make my truck turn left at the crossroads.",
        [event_played(TRUCK_ID, "junction_turn", 10), only(TRUCK)],
        [manoeuvre(TRUCK_ID, "junction_turn", turn="left")],
        setup=[DRIVING_TRUCK],
    ),
    impossible(
        "moving",
        "direct",
        "two_hundred_knots",
        SAIL,
        "Ego: make your speed 200 knots.",
        [behave(EGO, "drive_lane", speed=round(200 * KNOT, 1), lane=EASTBOUND)],
    ),
    case(
        "moving",
        "direct",
        "hydrant_exactly_one_metre",
        NEG,
        "Don't leave the hydrant where it is: shift it no more and no less than one metre north.",
        [moved(HYDRANT, 0.8, 1.2, "left"), only(assets=[HYDRANT])],
        [move(HYDRANT, north=1)],
    ),
    case(
        "moving",
        "direct",
        "car_one_circles",
        MIL,
        "Car 1: drive circles, radius five metres. Execute.",
        [does("circle", asset=CAR_1, radius_min=4.9, radius_max=5.1), only(assets=[CAR_1])],
        [behave(CAR_1, "circle", radius=5)],
    ),
    # indirect
    case(
        "moving",
        "indirect",
        "stopped_short_of_crosswalk",
        COP,
        "The skid marks end just short of the west crosswalk: Vehicle A braked and came to a stop before it. Set the "
        "scenario up that way.",
        [stops_before(EGO, -13.0, -1.75, 20), only(assets=[EGO])],
        [event(EGO, "stop", {"kind": "reach", "place": WEST_CROSSWALK}, rate=4)],
    ),
    case(
        "moving",
        "indirect",
        "jaywalker_condition",
        STUDY,
        "Condition C tests drivers' reactions, so I need a participant who jaywalks out in front of the ego.",
        [delta(PERSON, 1, 1), does("jaywalk", PERSON, scope="added"), only(PERSON)],
        [add(PERSON, 1, behaviour={"kind": "jaywalk"})],
    ),
    case(
        "moving",
        "indirect",
        "suv_under_way",
        SAIL,
        "The SUV has been tied up in lot B long enough; I'd like her under way eastbound on Main Street.",
        [does("drive_lane", asset=SUV, lane=EASTBOUND), only(assets=[SUV])],
        [behave(SUV, "drive_lane", lane=EASTBOUND)],
    ),
    case(
        "moving",
        "indirect",
        "truck_blocking_doors",
        TRUCKIE,
        "My truck's blocking the path the union crowd walk along, so it needs to pull forward about five metres.",
        [moved(TRUCK_ID, 4, 6, "forward"), only(assets=[TRUCK_ID])],
        [move(TRUCK_ID, forward=5)],
        setup=[TRUCK_IN_LOT_B],
    ),
    case(
        "moving",
        "indirect",
        "ego_drifts_slowly",
        POET,
        "Let the ego drift as slowly as a thought half-formed — a walking pace, no more than two metres a second.",
        [does("drive_lane", asset=EGO, speed_min=0.5, speed_max=2.0), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=2, lane=EASTBOUND)],
    ),
    case(
        "moving",
        "indirect",
        "car_one_convoy",
        MIL,
        "Car 1 is required on the eastbound lane for convoy duty. Get it oscar mike at 6 metres a second.",
        [does("drive_lane", asset=CAR_1, lane=EASTBOUND, speed_min=5.9, speed_max=6.1), only(assets=[CAR_1])],
        [behave(CAR_1, "drive_lane", lane=EASTBOUND, speed=6)],
    ),
    case(
        "moving",
        "indirect",
        "cyclist_nowhere_else",
        NEG,
        "The cyclist shouldn't just stand there doing nothing; have it ride to the library entrance and nowhere else.",
        [does("follow_path", asset=BIKE_ID), reaches(BIKE_ID, LIBRARY, 30), only(assets=[BIKE_ID])],
        [behave(BIKE_ID, "follow_path", to=LIBRARY)],
        setup=[turn("Add a cyclist at the bus stop.", add(BIKE, 1, loc("at", BUS_STOP)))],
    ),
    case(
        "moving",
        "indirect",
        "suv_too_far_back",
        SELF,
        "The SUV is too far back in its bay, so it needs to come forward two metres — no, three.",
        [moved(SUV, 2.5, 3.5, "forward"), only(assets=[SUV])],
        [move(SUV, forward=3)],
    ),
    case(
        "moving",
        "indirect",
        "hook_a_right",
        AUS,
        "Want the ego to hook a right at the lights so it heads down towards the union, and pick up to 7 m/s first.",
        [
            event_played(EGO, "junction_turn", 10),
            does("drive_lane", asset=EGO, speed_min=6.9, speed_max=7.1),
            only(assets=[EGO]),
        ],
        [behave(EGO, "drive_lane", speed=7, lane=EASTBOUND), manoeuvre(EGO, "junction_turn", turn="right")],
    ),
    case(
        "moving",
        "indirect",
        "cyclist_from_driveway",
        COP,
        "The reporting party says a cyclist came out of the lot B driveway and rode west along Main Street at about "
        "4 m/s; that cyclist needs to be in the reconstruction.",
        [
            delta(BIKE, 1, 1),
            does("drive_lane", BIKE, scope="added", lane=WESTBOUND, speed_min=3.5, speed_max=4.5),
            near(LOT_B_ENTRANCE, 15, BIKE),
            only(BIKE),
        ],
        [add(BIKE, 1, loc("at", LOT_B_ENTRANCE), behaviour=drive(4, WESTBOUND))],
    ),
    impossible(
        "moving",
        "indirect",
        "bus_stop_further_east",
        COP,
        "The reporting party insists the bus stop was further east at the time, so it needs moving 20 metres east.",
        [move("bus stop", east=20)],
    ),
    # vague
    case(
        "moving",
        "vague",
        "ego_faster",
        MIL,
        "Ego: faster.",
        [does("drive_lane", asset=EGO, speed_min=5.5), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=8, lane=EASTBOUND)],
    ),
    case(
        "moving",
        "vague",
        "bench_toward_road",
        POET,
        "Nudge the bench a little closer to the road.",
        [moved(BENCH, 0.3, 2.5, "right"), only(assets=[BENCH])],
        [move(BENCH, north=1)],
    ),
    case(
        "moving",
        "vague",
        "swing_car_two",
        SAIL,
        "Swing car two round.",
        [moved(CAR_2, 0, 2, turn_min=90), only(assets=[CAR_2])],
        [move(CAR_2, turn_deg=180)],
    ),
    case(
        "moving",
        "vague",
        "hydrant_off_kerb",
        NEG,
        "Hydrant — not so close to the kerb.",
        [moved(HYDRANT, 0.3, 3, "left"), only(assets=[HYDRANT])],
        [move(HYDRANT, north=1)],
    ),
    case(
        "moving",
        "vague",
        "trial_start",
        STUDY,
        "Trial start: participant crosses.",
        [does("cross_road", asset=PED_ID), only(assets=[PED_ID])],
        [behave(PED_ID, "cross_road")],
        setup=[turn("Add a participant at the north crosswalk.", add(PERSON, 1, loc("at", NORTH_CROSSWALK)))],
    ),
    case(
        "moving",
        "vague",
        "car_two_up_a_bit",
        TRUCKIE,
        "Shift car 2 up a bit, would you? My truck needs the room.",
        [moved(CAR_2, 1, 8, "forward"), only(assets=[CAR_2])],
        [move(CAR_2, forward=3)],
    ),
    case(
        "moving",
        "vague",
        "vehicle_a_halt",
        COP,
        "Vehicle A: bring to a halt.",
        [only(assets=[EGO])],
        [manoeuvre(EGO, "stop")],
        alternatives=[[event_played(EGO, "stop", 5)], [does("parked", asset=EGO)]],
    ),
    case(
        "moving",
        "vague",
        "suv_bit_left",
        AUS,
        "SUV, bit to the left.",
        [moved(SUV, 0.3, 3, "left"), only(assets=[SUV])],
        [move(SUV, left=1)],
    ),
    case(
        "moving",
        "vague",
        "just_circles",
        SELF,
        "robot — make it go round. circles, no, figure e— no, just circles.",
        [does("circle", asset=ROBOT_ID), only(assets=[ROBOT_ID])],
        [behave(ROBOT_ID, "circle")],
        setup=[turn("Put a robot in lot A.", add(ROBOT, 1, loc("at", LOT_A)), planned=True)],
    ),
    impossible(
        "moving",
        "vague",
        "bench_wanders",
        POET,
        "Let the bench wander the roads like a lost poet.",
        [behave(BENCH, "drive_lane")],
    ),
    case(
        "moving",
        "vague",
        "break_left",
        MIL,
        "Ego, break left.",
        [event_played(EGO, "lane_change", 5), only(assets=[EGO])],
        [manoeuvre(EGO, "lane_change", side="left")],
    ),
    # erroneous
    case(
        "moving",
        "erroneous",
        "ego_knots",
        SAIL,
        "ego ahed at twelve nots, steady as she gose",
        [does("drive_lane", asset=EGO, speed_min=6.0, speed_max=6.3), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=round(12 * KNOT, 2), lane=EASTBOUND)],
    ),
    case(
        "moving",
        "erroneous",
        "car_two_skid",
        COP,
        "car 2 moved foward 4 meters per the skidmark evidense",
        [moved(CAR_2, 3.5, 4.5, "forward"), only(assets=[CAR_2])],
        [move(CAR_2, forward=4)],
    ),
    case(
        "moving",
        "erroneous",
        "suv_quater_turn",
        MIL,
        "suv rotate 90 degres left, then hold",
        [moved(SUV, 0, 0.5, turn_min=80, turn_max=100), only(assets=[SUV])],
        [move(SUV, turn_deg=90)],
    ),
    case(
        "moving",
        "erroneous",
        "car_one_drives",
        SELF,
        "make car 1 drive east on main, at 4, no 5 m/s, sory",
        [does("drive_lane", asset=CAR_1, lane=EASTBOUND, speed_min=4.9, speed_max=5.1), only(assets=[CAR_1])],
        [behave(CAR_1, "drive_lane", lane=EASTBOUND, speed=5)],
    ),
    case(
        "moving",
        "erroneous",
        "particpant_north",
        STUDY,
        "add a particpant that crosses at the north crosswlak, trail 4",
        [delta(PERSON, 1, 1), does("cross_road", PERSON, scope="added", crosses_lane=NORTHBOUND), only(PERSON)],
        [add(PERSON, 1, loc("at", NORTH_CROSSWALK), behaviour={"kind": "cross_road"})],
    ),
    case(
        "moving",
        "erroneous",
        "bin_wander",
        POET,
        "let the bin wandr two metre west, like a leaf",
        [moved(BIN, 1.5, 2.5), only(assets=[BIN])],
        [move(BIN, east=-2)],
    ),
    case(
        "moving",
        "erroneous",
        "car_chucks_a_uey",
        AUS,
        "get car 1 to chuck a u-ey where its parkd, 180",
        [moved(CAR_1, 0, 1, turn_min=170), only(assets=[CAR_1])],
        [move(CAR_1, turn_deg=180)],
    ),
    case(
        "moving",
        "erroneous",
        "ego_not_slower",
        NEG,
        "the ego shoudnt go no slower then 25 km/h, set it to exactly that",
        [does("drive_lane", asset=EGO, speed_min=6.9, speed_max=7.0), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=6.94, lane=EASTBOUND)],
    ),
    case(
        "moving",
        "erroneous",
        "truk_forwards",
        TRUCKIE,
        "drive my truk forwards 4 meter, customers cant see it",
        [moved(TRUCK_ID, 3, 5, "forward"), only(assets=[TRUCK_ID])],
        [move(TRUCK_ID, forward=4)],
        setup=[turn("Put my truck in lot A.", add(TRUCK, 1, loc("at", LOT_A)), planned=True)],
    ),
    impossible(
        "moving",
        "erroneous",
        "reverse_300",
        COP,
        "reverce vehicle A 300 meters back from the point of impakt",
        [manoeuvre(EGO, "reverse", distance=300)],
    ),
    case(
        "moving",
        "erroneous",
        "pushbike_to_stop",
        AUS,
        "chuck a pushbike at the libary that rides to teh bus stop",
        [delta(BIKE, 1, 1), does("follow_path", BIKE, scope="added"), reaches(BIKE, BUS_STOP, 30), only(BIKE)],
        [add(BIKE, 1, loc("at", LIBRARY), behaviour={"kind": "follow_path", "to": BUS_STOP})],
    ),
]

# --- Arrangement: several assets in a line, a ring, a row or a grid ---------------------------
RUBBLE_ID = "cement_rubble_1"
RUBBLE_AT_JUNCTION = turn(
    "Add cement rubble at the point of impact, the middle of the intersection.",
    add(RUBBLE, 1, loc("at", JUNCTION)),
    planned=True,
)

ARRANGEMENT_CASES: list[Json] = [
    # direct
    case(
        "arrangement",
        "direct",
        "cones_at_west_crosswalk",
        COP,
        "Lay a line of six traffic cones at the west crosswalk to mark the scene.",
        [delta(CONE, 6, 6), layout("line", CONE, 6), near(WEST_CROSSWALK, 10, CONE, every=True), only(CONE)],
        [arrange(CONE, "line", loc("at", WEST_CROSSWALK), count=6)],
    ),
    case(
        "arrangement",
        "direct",
        "crown_of_steel",
        POET,
        "Ring the fountain with eight bollards, a crown of steel.",
        [delta(BOLLARD, 8, 8), layout("ring", BOLLARD, 8, around=FOUNTAIN), only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=8)],
    ),
    case(
        "arrangement",
        "direct",
        "cars_side_by_side",
        AUS,
        "Line up four cars side by side in lot A, parked.",
        [delta(CAR, 4, 4), layout("line", CAR, 4), near(LOT_A, 1, CAR, every=True), only(CAR)],
        [arrange(CAR, "parking_row", loc("at", LOT_A), count=4)],
    ),
    case(
        "arrangement",
        "direct",
        "queue_by_hydrant",
        TRUCKIE,
        "Put a queue of five customers in a line next to the hydrant; my truck parks just there at lunch.",
        [delta(PERSON, 5, 5), layout("line", PERSON, 5), near(HYDRANT, 10, PERSON, every=True), only(PERSON)],
        [arrange(PERSON, "line", loc("next_to", HYDRANT), count=5)],
    ),
    case(
        "arrangement",
        "direct",
        "barriers_at_twelve",
        MIL,
        "Establish a line of three barriers across the road at the ego's 12 o'clock.",
        [
            delta(BARRIER, 3, 3),
            layout("line", BARRIER, 3),
            relative("in_front_of", EGO, BARRIER, max_distance=20, every=True),
            only(BARRIER),
        ],
        [arrange(BARRIER, "line", loc("in_front_of", EGO), count=3)],
    ),
    case(
        "arrangement",
        "direct",
        "crowd_grid",
        STUDY,
        "Arrange nine participants in a 3 by 3 grid in lot B for the crowd condition.",
        [delta(PERSON, 9, 9), near(LOT_B, 1, PERSON, every=True), only(PERSON)],
        [arrange(PERSON, "grid", loc("at", LOT_B), count=9, columns=3)],
    ),
    case(
        "arrangement",
        "direct",
        "starboard_edge_cones",
        SAIL,
        "Set a row of eight cones along the starboard edge of the eastbound lane, starting abeam the main gate.",
        [delta(CONE, 8, 8), layout("line", CONE, 8), in_lane(EASTBOUND, CONE), near(MAIN_GATE, 40, CONE), only(CONE)],
        [arrange(CONE, "lane_edge", loc("at", MAIN_GATE, lane=EASTBOUND), count=8)],
    ),
    case(
        "arrangement",
        "direct",
        "ring_six_no_five",
        SELF,
        "Put a ring of five — sorry, six — cones in the middle of the crossroads.",
        [delta(CONE, 6, 6), layout("ring", CONE, 6, around=JUNCTION), near(JUNCTION, 1, CONE, every=True), only(CONE)],
        [arrange(CONE, "ring", loc("at", JUNCTION), count=6)],
    ),
    case(
        "arrangement",
        "direct",
        "exactly_three_benches",
        NEG,
        "Add benches in a line on the footpath by the library: no more than three, and no fewer than three.",
        [
            delta(BENCH_KIND, 3, 3),
            layout("line", BENCH_KIND, 3),
            near(LIBRARY, 15, BENCH_KIND, every=True),
            only(BENCH_KIND),
        ],
        [arrange(BENCH_KIND, "line", loc("on_sidewalk", LIBRARY), count=3)],
    ),
    case(
        "arrangement",
        "direct",
        "bollards_across_lot_b",
        AUS,
        "Put a line of five bollards across the lot B entrance, and a parking sign beside them.",
        [
            delta(BOLLARD, 5, 5),
            layout("line", BOLLARD, 5),
            near(LOT_B_ENTRANCE, 10, BOLLARD, every=True),
            delta(PARK_SIGN, 1, 1),
            near(LOT_B_ENTRANCE, 10, PARK_SIGN),
            only(BOLLARD, PARK_SIGN),
        ],
        [arrange(BOLLARD, "line", loc("at", LOT_B_ENTRANCE), count=5), add(PARK_SIGN, 1, loc("at", LOT_B_ENTRANCE))],
    ),
    impossible(
        "arrangement",
        "direct",
        "five_hundred_cones",
        MIL,
        "Deploy 500 cones in a grid in lot B.",
        [arrange(CONE, "grid", loc("at", LOT_B), count=500)],
    ),
    # indirect
    case(
        "arrangement",
        "indirect",
        "cordon_the_rubble",
        COP,
        "The scene needs cordoning off: I'd like the rubble ringed by cones so nobody drives through it.",
        [delta(CONE, 4, None), layout("ring", CONE, 4, around=RUBBLE_ID), only(CONE)],
        [arrange(CONE, "ring", loc("at", RUBBLE_ID))],
        setup=[RUBBLE_AT_JUNCTION],
    ),
    case(
        "arrangement",
        "indirect",
        "bollard_quay",
        SAIL,
        "For a bit of a quayside feel, a line of six bollards along the north footway by Engineering Hall would do "
        "nicely.",
        [delta(BOLLARD, 6, 6), layout("line", BOLLARD, 6), near(ENGINEERING, 15, BOLLARD, every=True), only(BOLLARD)],
        [arrange(BOLLARD, "line", loc("on_sidewalk", ENGINEERING), count=6)],
    ),
    case(
        "arrangement",
        "indirect",
        "weekday_car_park",
        AUS,
        "Lot B looks empty for a weekday, which isn't right. It could use a row of four more cars parked up.",
        [delta(CAR, 4, 4), layout("line", CAR, 4), near(LOT_B, 1, CAR, every=True, scope="added"), only(CAR)],
        [arrange(CAR, "parking_row", loc("at", LOT_B), count=4)],
    ),
    case(
        "arrangement",
        "indirect",
        "regulars_round_fountain",
        TRUCKIE,
        "My regulars like to stand round the fountain eating, so I'd want six of them in a circle there.",
        [delta(PERSON, 6, 6), layout("ring", PERSON, 6, around=FOUNTAIN), only(PERSON)],
        [arrange(PERSON, "ring", loc("at", FOUNTAIN), count=6)],
    ),
    case(
        "arrangement",
        "indirect",
        "checkpoint_at_gate",
        MIL,
        "We need a checkpoint at the main gate: three barriers in a line across the road, plus a stop sign.",
        [
            delta(BARRIER, 3, 3),
            layout("line", BARRIER, 3),
            near(MAIN_GATE, 10, BARRIER, every=True),
            delta(STOP_KIND, 1, 1),
            near(MAIN_GATE, 12, STOP_KIND),
            only(BARRIER, STOP_KIND),
        ],
        [arrange(BARRIER, "line", loc("at", MAIN_GATE), count=3), add(STOP_KIND, 1, loc("on_sidewalk", MAIN_GATE))],
    ),
    case(
        "arrangement",
        "indirect",
        "single_file_condition",
        STUDY,
        "Participants need to wait single-file on the south footway for the queueing condition — five of them, by "
        "the bus stop.",
        [delta(PERSON, 5, 5), layout("line", PERSON, 5), near(BUS_STOP, 10, PERSON, every=True), only(PERSON)],
        [arrange(PERSON, "line", loc("on_sidewalk", BUS_STOP), count=5)],
    ),
    case(
        "arrangement",
        "indirect",
        "procession_of_trees",
        POET,
        "The road to the east gate feels naked. A procession of four trees on the grass north of it, six metres "
        "apart, about 85, 10, would clothe it.",
        [
            delta(TREE, 4, 4),
            layout("line", TREE, 4, spacing_min=5, spacing_max=7),
            near(EAST_GATE, 30, TREE, every=True),
            only(TREE),
        ],
        [arrange(TREE, "line", xy(85, 10), count=4, spacing=6, heading_deg=0)],
    ),
    case(
        "arrangement",
        "indirect",
        "work_zone_cones",
        NEG,
        "I'd not want the ego to not see the work zone, so cones along the edge of its lane, not fewer than six, "
        "starting 20 m ahead of it.",
        [delta(CONE, 6, None), layout("line", CONE, 6), in_lane(EASTBOUND, CONE), only(CONE)],
        [arrange(CONE, "lane_edge", ahead_of(EGO, 20), count=6)],
    ),
    case(
        "arrangement",
        "indirect",
        "same_row_at_lot_b",
        SELF,
        "Same again — I mean the same row of signs — at the lot B entrance too.",
        [
            delta(WORK_SIGN, 3, 3),
            layout("line", WORK_SIGN, 3),
            near(LOT_B_ENTRANCE, 10, WORK_SIGN, every=True, scope="added"),
            only(WORK_SIGN),
        ],
        [arrange(WORK_SIGN, "line", loc("at", LOT_B_ENTRANCE), count=3)],
        setup=[
            turn(
                "Put three construction signs in a row at the lot A entrance.",
                arrange(WORK_SIGN, "line", loc("at", LOT_A_ENTRANCE), count=3),
                planned=True,
            )
        ],
    ),
    case(
        "arrangement",
        "indirect",
        "crowding_condition",
        STUDY,
        "For the crowding condition I need five participants lined up along the footway by the Engineering Hall "
        "entrance, and the stop sign ringed with four bollards so nobody leans on it between trials.",
        [
            delta(PERSON, 5, 5),
            layout("line", PERSON, 5),
            near(ENGINEERING, 12, PERSON, every=True),
            delta(BOLLARD, 4, 4),
            layout("ring", BOLLARD, 4, around=STOP_SIGN),
            only(PERSON, BOLLARD),
        ],
        [
            arrange(PERSON, "line", loc("on_sidewalk", ENGINEERING), count=5),
            arrange(BOLLARD, "ring", loc("at", STOP_SIGN), count=4),
        ],
    ),
    impossible(
        "arrangement",
        "indirect",
        "two_cable_ring",
        SAIL,
        "A ring of bollards around the fountain, two cables across — about 370 metres — would feel like home.",
        [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), radius=185)],
    ),
    # vague
    case(
        "arrangement",
        "vague",
        "cones_line_lot_b",
        MIL,
        "Cones. Line. Lot B entrance.",
        [delta(CONE, 3, None), layout("line", CONE, 3), near(LOT_B_ENTRANCE, 10, CONE, every=True), only(CONE)],
        [arrange(CONE, "line", loc("at", LOT_B_ENTRANCE))],
    ),
    case(
        "arrangement",
        "vague",
        "circle_round_bench",
        STUDY,
        "Participants in a circle round the bench.",
        [delta(PERSON, 4, None), layout("ring", PERSON, 4, around=BENCH), only(PERSON)],
        [arrange(PERSON, "ring", loc("at", BENCH))],
    ),
    case(
        "arrangement",
        "vague",
        "fence_of_posts",
        POET,
        "A little fence of posts before the library.",
        [delta(BOLLARD, 3, None), layout("line", BOLLARD, 3), near(LIBRARY, 10, BOLLARD, every=True), only(BOLLARD)],
        [arrange(BOLLARD, "line", loc("in_front_of", LIBRARY))],
    ),
    case(
        "arrangement",
        "vague",
        "row_of_utes",
        AUS,
        "Row of utes at lot A.",
        [
            delta([TRUCK, CAR], 2, None),
            layout("line", [TRUCK, CAR], 2),
            near(LOT_A, 1, [TRUCK, CAR], every=True),
            only(TRUCK, CAR),
        ],
        [arrange(TRUCK, "parking_row", loc("at", LOT_A))],
    ),
    case(
        "arrangement",
        "vague",
        "channel_markers",
        SAIL,
        "Channel markers down the eastbound lane.",
        [delta(MARKERS, 3, None), layout("line", MARKERS, 3), in_lane(EASTBOUND, MARKERS), only(*MARKERS)],
        [arrange(CONE, "lane_edge", loc("at", EASTBOUND))],
    ),
    case(
        "arrangement",
        "vague",
        "bins_round_pitch",
        TRUCKIE,
        "Bins round my pitch.",
        [delta(BIN_KIND, 3, None), layout("ring", BIN_KIND, 3, around=TRUCK_ID), only(BIN_KIND)],
        [arrange(BIN_KIND, "ring", loc("at", TRUCK_ID))],
        setup=[TRUCK_IN_LOT_B],
    ),
    case(
        "arrangement",
        "vague",
        "barricade_north_crosswalk",
        COP,
        "Barricade the north crosswalk.",
        [
            delta(BARRIER, 2, None),
            layout("line", BARRIER, 2),
            near(NORTH_CROSSWALK, 10, BARRIER, every=True),
            only(BARRIER),
        ],
        [arrange(BARRIER, "line", loc("at", NORTH_CROSSWALK))],
    ),
    case(
        "arrangement",
        "vague",
        "not_more_than_nine",
        NEG,
        "Nothing fancy: cones in a grid in lot A, not more than nine.",
        [delta(CONE, 2, 9), near(LOT_A, 1, CONE, every=True), only(CONE)],
        [arrange(CONE, "grid", loc("at", LOT_A), count=9)],
    ),
    case(
        "arrangement",
        "vague",
        "circle_no_line",
        SELF,
        "circle of — wait, line. a line of bollards by the bus stop.",
        [delta(BOLLARD, 3, None), layout("line", BOLLARD, 3), near(BUS_STOP, 10, BOLLARD, every=True), only(BOLLARD)],
        [arrange(BOLLARD, "line", loc("at", BUS_STOP))],
    ),
    impossible(
        "arrangement",
        "vague",
        "ring_in_library_heart",
        POET,
        "A ring of trees within the very heart of the Library, round -41, -30.",
        [arrange(TREE, "ring", xy(-41, -30), radius=5, count=6)],
    ),
    case(
        "arrangement",
        "vague",
        "same_by_library",
        TRUCKIE,
        "Same again by the library.",
        [
            delta(PERSON, 5, 5),
            layout("line", PERSON, 5),
            near(LIBRARY, 10, PERSON, every=True, scope="added"),
            only(PERSON),
        ],
        [arrange(PERSON, "line", loc("at", LIBRARY), count=5)],
        setup=[
            turn(
                "Put five customers in a line by the JTEKT entrance, like they're queueing for my truck.",
                arrange(PERSON, "line", loc("at", JTEKT), count=5),
                planned=True,
            )
        ],
    ),
    # erroneous
    case(
        "arrangement",
        "erroneous",
        "lien_of_barriers",
        COP,
        "put a lien of 4 barriers acros main st behind vehical A, to close the road",
        [
            delta(BARRIER, 4, 4),
            layout("line", BARRIER, 4),
            relative("behind", EGO, BARRIER, max_distance=20, every=True),
            only(BARRIER),
        ],
        [arrange(BARRIER, "line", loc("behind", EGO), count=4)],
    ),
    case(
        "arrangement",
        "erroneous",
        "ring_of_bins",
        POET,
        "encircel the old tree by the libary with 5 bins, like a wreth",
        [delta(BIN_KIND, 5, 5), layout("ring", BIN_KIND, 5, around=TREE_LIBRARY), only(BIN_KIND)],
        [arrange(BIN_KIND, "ring", loc("at", TREE_LIBRARY), count=5)],
    ),
    case(
        "arrangement",
        "erroneous",
        "motorbikes_row",
        AUS,
        "3 motorbikes in a row in lot b, parkd side by side",
        [delta(MOTORBIKE, 3, 3), layout("line", MOTORBIKE, 3), near(LOT_B, 1, MOTORBIKE, every=True), only(MOTORBIKE)],
        [arrange(MOTORBIKE, "parking_row", loc("at", LOT_B), count=3)],
    ),
    case(
        "arrangement",
        "erroneous",
        "cone_ring_robot",
        MIL,
        "set up perimiter of cones round the robot, 6 of them, now",
        [delta(CONE, 6, 6), layout("ring", CONE, 6, around=ROBOT_ID), only(CONE)],
        [arrange(CONE, "ring", loc("at", ROBOT_ID), count=6)],
        setup=[turn("Stage a robot in lot A.", add(ROBOT, 1, loc("at", LOT_A)))],
    ),
    case(
        "arrangement",
        "erroneous",
        "grid_of_bikes",
        STUDY,
        "arange 6 bikes in grid at lot a, 3 colums, for condtion E",
        [delta(BIKE, 6, 6), near(LOT_A, 1, BIKE, every=True), only(BIKE)],
        [arrange(BIKE, "grid", loc("at", LOT_A), count=6, columns=3)],
    ),
    case(
        "arrangement",
        "erroneous",
        "westbund_cones",
        SAIL,
        "row of 6 cones on the westbund lane edge by the east gate",
        [delta(CONE, 6, 6), layout("line", CONE, 6), in_lane(WESTBOUND, CONE), near(EAST_GATE, 40, CONE), only(CONE)],
        [arrange(CONE, "lane_edge", loc("at", EAST_GATE, lane=WESTBOUND), count=6)],
    ),
    case(
        "arrangement",
        "erroneous",
        "lot_a_ring_five_six",
        SELF,
        "ring of cones in the midle of lot a, five no six",
        [delta(CONE, 6, 6), layout("ring", CONE, 6, around=LOT_A), near(LOT_A, 1, CONE, every=True), only(CONE)],
        [arrange(CONE, "ring", loc("at", LOT_A), count=6)],
    ),
    case(
        "arrangement",
        "erroneous",
        "not_less_then_four",
        NEG,
        "line of bollard on the footpath by the bus stop, not more then four not less",
        [delta(BOLLARD, 4, 4), layout("line", BOLLARD, 4), near(BUS_STOP, 10, BOLLARD, every=True), only(BOLLARD)],
        [arrange(BOLLARD, "line", loc("on_sidewalk", BUS_STOP), count=4)],
    ),
    case(
        "arrangement",
        "erroneous",
        "custmers_cue",
        TRUCKIE,
        "put 4 custmers in a cue next to my truk",
        [delta(PERSON, 4, 4), layout("line", PERSON, 4), near(TRUCK_ID, 10, PERSON, every=True), only(PERSON)],
        [arrange(PERSON, "line", loc("next_to", TRUCK_ID), count=4)],
        setup=[TRUCK_AT_JTEKT],
    ),
    case(
        "arrangement",
        "erroneous",
        "suv_ringed_at_impact",
        COP,
        "move vehical B (the suv) to the intersecton center, the point of impakt, and put a ring of 6 cones round it",
        [
            near(JUNCTION, 1, asset=SUV),
            delta(CONE, 6, 6),
            layout("ring", CONE, 6, around=SUV),
            only(CONE, assets=[SUV]),
        ],
        [place(SUV, loc("at", JUNCTION)), arrange(CONE, "ring", loc("at", SUV), count=6)],
    ),
    case(
        "arrangement",
        "erroneous",
        "bolards_accross",
        AUS,
        "put 5 bolards accross the lot a entrace, stop the hoons",
        [
            delta(BOLLARD, 5, 5),
            layout("line", BOLLARD, 5),
            near(LOT_A_ENTRANCE, 10, BOLLARD, every=True),
            only(BOLLARD),
        ],
        [arrange(BOLLARD, "line", loc("at", LOT_A_ENTRANCE), count=5)],
    ),
]

# --- Appearance: colours, materials, weather, clock and lights -----------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case(
        "appearance",
        "direct",
        "squall",
        SAIL,
        "Set the weather to heavy rain, a proper squall.",
        [env(weather=["rain"], intensity_min=0.7, **NOON), only(env=True)],
        [weather("rain", 0.9)],
    ),
    case(
        "appearance",
        "direct",
        "arvo",
        AUS,
        "Make it arvo — three o'clock.",
        [env(time_from="14:45", time_to="15:15", **CLEAR), only(env=True)],
        [clock("15:00")],
    ),
    case(
        "appearance",
        "direct",
        "suv_paint_transfer",
        COP,
        "Paint the SUV (Vehicle B) red, to match the paint transfer found at the point of impact.",
        [looks("red", asset=SUV), only(assets=[SUV])],
        [paint([SUV], colour="red")],
    ),
    case(
        "appearance",
        "direct",
        "bench_brand_yellow",
        TRUCKIE,
        "Paint the bus stop bench yellow. My customers sit there to eat, and yellow's my brand colour.",
        [looks("yellow", asset=BENCH), only(assets=[BENCH])],
        [paint([BENCH], colour="yellow")],
    ),
    case(
        "appearance",
        "direct",
        "zero_two_hundred",
        MIL,
        "Set time to 0200 hours.",
        [env(time_from="01:50", time_to="02:10", **CLEAR), only(env=True)],
        [clock("02:00")],
    ),
    case(
        "appearance",
        "direct",
        "condition_d_fog",
        STUDY,
        "Condition D is low visibility: set dense fog.",
        [env(weather=["fog"], intensity_min=0.7, **NOON), only(env=True)],
        [weather("fog", 0.9)],
    ),
    case(
        "appearance",
        "direct",
        "gild_the_bench",
        POET,
        "Gild the bench: paint it gold, and let its wood be wood.",
        [looks("gold", asset=BENCH), only(assets=[BENCH])],
        [paint([BENCH], colour="gold", material="wood")],
    ),
    case(
        "appearance",
        "direct",
        "lights_off_no_on",
        SELF,
        "Turn the street lights off — no, on. On.",
        [env(street_lights="on", **NOON), only(env=True)],
        [lighting(street_lights="on")],
    ),
    impossible("appearance", "direct", "twenty_five_hundred", MIL, "Set the clock to 2500 hours.", [clock("25:00")]),
    # indirect
    case(
        "appearance",
        "indirect",
        "last_amber_of_day",
        POET,
        "I want the scene bathed in the last amber of the day, as the sun slips down behind the roofs.",
        [env(time_from="17:30", time_to="20:30", **CLEAR), only(env=True)],
        [clock("sunset")],
    ),
    case(
        "appearance",
        "indirect",
        "sign_nothing_but_pink",
        NEG,
        "The stop sign isn't not red, but I'd want it no colour other than bright pink, and nothing else changed.",
        [looks("pink", asset=STOP_SIGN), only(assets=[STOP_SIGN])],
        [paint([STOP_SIGN], colour="pink")],
    ),
    case(
        "appearance",
        "indirect",
        "wet_road_surface",
        COP,
        "At the time of the incident the road surface was wet from steady rain and it was getting dark, about 7:30 "
        "pm; reproduce those conditions.",
        [env(weather=["rain"], intensity_min=0.3, time_from="19:15", time_to="19:45"), only(env=True)],
        [weather("rain", 0.6), clock("19:30")],
    ),
    case(
        "appearance",
        "indirect",
        "truck_like_my_logo",
        TRUCKIE,
        "Customers can't spot my truck; it needs to be bright orange like my logo.",
        [looks("orange", asset=TRUCK_ID), only(assets=[TRUCK_ID])],
        [paint([TRUCK_ID], colour="orange")],
        setup=[turn("Add my truck at the east gate.", add(TRUCK, 1, loc("at", EAST_GATE)), planned=True)],
    ),
    case(
        "appearance",
        "indirect",
        "darkness_for_mission",
        MIL,
        "Mission requires darkness: make it night, and kill the street lights.",
        [env(night=True, street_lights="off", weather=["clear"]), only(env=True)],
        [clock("night"), lighting(street_lights="off")],
    ),
    case(
        "appearance",
        "indirect",
        "sunrise_condition",
        STUDY,
        "The early-morning condition runs at sunrise, around half six.",
        [env(time_from="06:15", time_to="06:45", **CLEAR), only(env=True)],
        [clock("06:30")],
    ),
    case(
        "appearance",
        "indirect",
        "too_glary",
        AUS,
        "It's a bit glary for a Melbourne day. Overcast would suit it.",
        [env(weather=["cloudy"], **NOON), only(env=True)],
        [weather("cloudy")],
    ),
    case(
        "appearance",
        "indirect",
        "navigating_by_horn",
        SAIL,
        "We'd be navigating by foghorn in this: thick fog, visibility next to nothing.",
        [env(weather=["fog"], intensity_min=0.8, **NOON), only(env=True)],
        [weather("fog", 1.0)],
    ),
    impossible(
        "appearance",
        "indirect",
        "tartan_bench",
        SELF,
        "I'd like the bench in blue — sorry, tartan, a proper tartan.",
        [paint([BENCH], colour="tartan")],
    ),
    # vague
    case(
        "appearance",
        "vague",
        "melancholy",
        POET,
        "Something melancholy.",
        [only(env=True)],
        [weather("rain", 0.5)],
        alternatives=[[env(weather=[*WET_OR_WHITE, "cloudy"])], [env(night=True)]],
    ),
    case(
        "appearance",
        "vague",
        "snow_in_aus",
        AUS,
        "Snow? In Aus? Go on then.",
        [env(weather=["snow"], **NOON), only(env=True)],
        [weather("snow")],
    ),
    case(
        "appearance",
        "vague",
        "afternoon_trials",
        STUDY,
        "Afternoon trials.",
        [env(time_from="12:30", time_to="18:30", **CLEAR), only(env=True)],
        [clock("afternoon")],
    ),
    case(
        "appearance",
        "vague",
        "black_out",
        MIL,
        "Black out.",
        [only(env=True)],
        [clock("night"), lighting(street_lights="off", vehicle_lights="off")],
        alternatives=[[env(night=True)], [env(street_lights="off", vehicle_lights="off", exposure_max=0.6)]],
    ),
    case(
        "appearance",
        "vague",
        "some_colour_lot_b",
        SAIL,
        "Give the cars in lot B some colour.",
        [looks(ANY_COLOUR, CARS, min_count=2), only(*CARS)],
        [paint([CAR_1, SUV, CAR_2], colour="blue")],
    ),
    case(
        "appearance",
        "vague",
        "make_it_pop",
        TRUCKIE,
        "Make my truck pop.",
        [looks(BRIGHT, asset=TRUCK_ID), only(assets=[TRUCK_ID])],
        [paint([TRUCK_ID], colour="red")],
        setup=[TRUCK_AT_JTEKT],
    ),
    case(
        "appearance",
        "vague",
        "snow_no_rain",
        SELF,
        "snow — no, rain. light rain.",
        [env(weather=["rain"], intensity_max=0.5, **NOON), only(env=True)],
        [weather("rain", 0.3)],
    ),
    case(
        "appearance",
        "vague",
        "nothing_but_clear",
        NEG,
        "No more rain. Nothing but clear skies.",
        [env(weather=["clear"], **NOON), only(env=True)],
        [weather("clear")],
        setup=[turn("Make it rain.", weather("rain", 0.6))],
    ),
    case(
        "appearance",
        "vague",
        "wintry_and_late",
        POET,
        "Something wintry, and late.",
        [env(weather=["snow"], time_from="17:00", time_to="03:00"), only(env=True)],
        [weather("snow"), clock("evening")],
    ),
    # erroneous
    case(
        "appearance",
        "erroneous",
        "hevy_snow",
        SAIL,
        "set wether to hevy snow, a real blizard",
        [env(weather=["snow"], intensity_min=0.7, **NOON), only(env=True)],
        [weather("snow", 0.9)],
    ),
    case(
        "appearance",
        "erroneous",
        "arvo_five",
        AUS,
        "make it 5 in the arvo pls an cloudy",
        [env(weather=["cloudy"], time_from="16:45", time_to="17:15"), only(env=True)],
        [clock("17:00"), weather("cloudy")],
    ),
    case(
        "appearance",
        "erroneous",
        "car_one_silver",
        COP,
        "pait vehical C, the car 1, silvr as per the witnes",
        [looks("silver", asset=CAR_1), only(assets=[CAR_1])],
        [paint([CAR_1], colour="silver")],
    ),
    case(
        "appearance",
        "erroneous",
        "headlights_on",
        MIL,
        "vehical lihgts on, all units, affirmitive",
        [env(vehicle_lights="on", **NOON), only(env=True)],
        [lighting(vehicle_lights="on")],
    ),
    case(
        "appearance",
        "erroneous",
        "participant_vests",
        STUDY,
        "make the particpants ware yelow, so condtion F is visable",
        [looks("yellow", PERSON, every=True), only(PERSON)],
        [paint(category=PERSON, colour="yellow")],
        setup=[turn("Add three participants at the west crosswalk.", add(PERSON, 3, loc("at", WEST_CROSSWALK)))],
    ),
    case(
        "appearance",
        "erroneous",
        "midnite",
        POET,
        "let midnite fall over evrything, a deep blu dark",
        [env(night=True, time_from="23:30", time_to="00:30", weather=["clear"]), only(env=True)],
        [clock("midnight")],
    ),
    case(
        "appearance",
        "erroneous",
        "bins_green_no_black",
        SELF,
        "paint the bins grean, no wait, black",
        [looks("black", BIN_KIND, every=True), only(BIN_KIND)],
        [paint(category=BIN_KIND, colour="black")],
    ),
    case(
        "appearance",
        "erroneous",
        "not_not_green",
        NEG,
        "make the hydrant not red, green, and dont make nothing else green",
        [looks("green", asset=HYDRANT), only(assets=[HYDRANT])],
        [paint([HYDRANT], colour="green")],
    ),
    impossible(
        "appearance", "erroneous", "hale_on_roof", TRUCKIE, "make it hale, ice on my truk roof", [weather("hail")]
    ),
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
