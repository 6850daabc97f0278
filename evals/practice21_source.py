"""The twenty-first practice suite: 276 cases in the words of nine new kinds of user, from the campus world alone.

`python -m drivetwin.evals.practice21_source` writes `suites/practice21.jsonl` (tag `practice21`, ids
`practice21.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`): a fire-brigade officer ("the appliance", "the incident", "hose
lay", "the access has to be kept clear", "cone off the hydrant"), a meteorologist in precise weather words
("light drizzle", "overcast", "visibility's poor", "a fog bank at dawn", "racing the squall", "a pea-souper",
"golden hour", "my anemometer"), a stage and film lighting technician ("kill the street lights", "strike the
lamp", "practicals", "on cue at 5 seconds", "flaring into the lens", "dim the lot", "background action"), a
construction site foreman ("plant's arriving", "set out", "the works", "segregating the works from traffic",
"the lads", "site wagon"), an Indian English speaker ("kindly", "do the needful", "prepone", "one more", "itself",
"only", "I am wanting"), an irritated user writing in capitals with exclamation marks and repetition ("WHERE IS
THE SUV?? ... WHERE IS IT!!!"), a civil servant in passive, bureaucratic prose ("it is requested that", "the said
vehicle", "forthwith", "pursuant to", "refuse receptacle", "shall be withdrawn from service"), a board-gamer in
grid and game-move words ("my knight", "a knight's move for the bin", "castle the bench and the bin", "advance
the SUV a couple of spaces", "capture", "a rank of pawns"; the reference turns squares into metres the prompt
gives), and a Scottish speaker ("wee", "aye", "outwith", "the noo", "the morn", "messages", "the close",
"motors", "bar the big yin", "dreich", "get shot o' it"). Prompts mix short chat turns with one-to-three
sentence requests, reasons and hedges, references back to earlier turns ("that debris", "my knight", "one
more, same place", "put it back where it was", "the middle one of those three"), numbers in words and digits,
units (metres, m/s, km/h, centimetres, squares of a stated size), relations (next to, behind, in front of,
beside, across, round), scopes (a lane, a lot, a footway, a side of Main Street, a landmark), behaviours
(speeds, braking short of a crosswalk, a held red light, a turn at the crossroads, a lane change, reversing,
circling, crossing on a trigger, driving to a place), weather and clock times ("6:30 in the evening", "the back
o' four", "5:45 am"), questions (which must change nothing) and exceptions ("all the barriers except the one by
the main gate", "every tree except the one by the library", "the motors bar the big yin"). The erroneous grade
carries realistic typos and slips ("hydrnt", "fountian", "teh", "rian", "whether" for weather, "que" for cue,
"castel", "there" for their, dropped letters and words, non-native grammar, dialect spelt as it is typed).

Counts: 7 tasks x 4 grades; search, moving and arrangement hold 11 cases in every grade, addition,
removal, positioning and appearance 9 (276 in all). 36 cases are multi-turn (20 with a planned earlier
turn that has calls), 24 compound (the prompt asks two things, the reference makes two calls or more),
and 22 (8.0 %) impossible, tagged `impossible`, where the right outcome is a refusal that changes
nothing: the distance to a fire station, to the Town Hall, to the chippy; an excavator, a fire engine, a haze
machine, seventy more cars; removing the ego, the west crosswalk, the Student Union building; the SUV at
x = 150 off the board, a street lamp on the JTEKT building's roof, the bin inside the Library; a tree driving in
circles, the SUV at 250 km/h, the SUV 300 m east; a barrier ring of 100 m radius, a ring round a castle outwith
the campus, twelve buses in a row; hail, exposure 10, repainting the Library.

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

TAG = "practice21"

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
FIRE = "voice: fire-brigade officer (appliances, hydrants, access route, keep clear, the incident)"
MET = "voice: meteorologist using precise weather words (drizzle, overcast, visibility, fog bank, squall, golden hour)"
GAFFER = "voice: stage and film lighting technician (lamps, dimming, kill the lights, practicals, cues, strike)"
FOREMAN = "voice: construction site foreman (plant, barriers, set out, the works, segregate, the lads)"
DESI = "voice: Indian English speaker (kindly, do the needful, prepone, one more, itself, only)"
CAPS = "voice: irritated user writing in capitals with exclamation marks and repetition"
CIVIL = (
    "voice: civil servant writing in passive, bureaucratic language (it is requested that, the said vehicle, forthwith)"
)
GAMER = (
    "voice: board-gamer using grid and game-move metaphors (squares, pieces, knight's move, castle, advance one space)"
)
SCOT = "voice: Scottish speaker (wee, aye, outwith, the now, messages, close, the morn, motors)"


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


def hold(light: str, state: str, seconds: float = 600.0) -> Json:
    """A traffic light held in one state for `seconds`."""
    return call("set_light_phases", light=light, phases=[{"state": state, "duration": seconds}])


def reach(place: str, actor: str = EGO) -> Json:
    """A trigger: `actor` reaches `place`."""
    return {"kind": "reach", "actor": actor, "place": place}


NORTH_LAMPS = tuple(f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11))  # Main Street's north side, west to east
LAMP_HYDRANT = "street_light_7"  # (25, 5.8), the lamp nearest the hydrant
LAMP_STOP_SIGN = "street_light_6"  # (-13, -5.8), right beside the stop sign
ROBOT_ID, RUBBLE_ID, TRUCK_ID = "ackermann_robot_1", "cement_rubble_1", "truck_1"
NEW_CAR, NEW_BENCH, PED_ID = "passenger_car_3", "bench_2", "pedestrian_1"
WEST_CROSSWALK_LINE = (-13.0, -1.75)  # the near edge of the west crosswalk, in the ego's lane

# Earlier turns several cases share.
KNIGHT = "My knight is one of those little robots — put one in lot A."
KNIGHT_PLANNED = turn(KNIGHT, add(ROBOT, 1, loc("at", LOT_A)), planned=True)
KNIGHT_GIVEN = turn(KNIGHT, add(ROBOT, 1, loc("at", LOT_A)))
DEBRIS = "Drop some debris in the eastbound lane about 25 m ahead of the ego."
DEBRIS_PLANNED = turn(DEBRIS, add(RUBBLE, 1, ahead_of(EGO, 25)), planned=True)
DEBRIS_GIVEN = turn(DEBRIS, add(RUBBLE, 1, ahead_of(EGO, 25)))
BUS_IN = "Pit a bus in at the bus stop."
BUS_IN_PLANNED = turn(BUS_IN, add(BUS, 1, loc("at", BUS_STOP)), planned=True)
LORRY = "Get a lorry parked up in lot A."
LORRY_PLANNED = turn(LORRY, add(TRUCK, 1, loc("at", LOT_A)), planned=True)
LORRY_GIVEN = turn(LORRY, add(TRUCK, 1, loc("at", LOT_A)))

SEARCH_CASES: list[Json] = [
    # direct
    ask(
        "direct",
        "hydrant_for_library",
        FIRE,
        "Nearest hydrant to the Library entrance, and how far is it?",
        ["fire_hydrant_1", "60.6"],
        [find(category=HYDRANT_KIND, nearest_to=LIBRARY)],
    ),
    ask(
        "direct",
        "observation_after_fog",
        MET,
        "Give me the current observation: what's the weather doing now?",
        ["fog"],
        [environment()],
        setup=[turn("Bring a fog bank in over the campus, fairly thick.", weather("fog", 0.7), planned=True)],
    ),
    ask(
        "direct",
        "lamp_count",
        GAFFER,
        "How many street lamps have we got on the whole set?",
        ["12"],
        [find(category=LAMP)],
    ),
    ask(
        "direct",
        "campus_drive_lanes",
        FOREMAN,
        "What lanes are there on Campus Drive? I need them for the traffic management plan.",
        ["campus_northbound", "campus_southbound"],
        [lanes(road="Campus Drive")],
    ),
    ask(
        "direct",
        "bus_stop_to_library",
        DESI,
        "Kindly tell me the distance between the bus stop and the Library entrance.",
        ["14.5"],
        [measure(BUS_STOP, LIBRARY)],
    ),
    ask(
        "direct",
        "where_is_suv",
        CAPS,
        "WHERE IS THE SUV?? I CAN'T FIND IT ANYWHERE!!! WHERE IS IT!!!",
        ["23", "-42"],
        [find(category=SUV_KIND)],
    ),
    ask(
        "direct",
        "vehicles_in_lot_b",
        CIVIL,
        "It is requested that the vehicles presently parked in car park B be listed, together with their designations.",
        ["passenger_car_1", "suv_1", "passenger_car_2"],
        [find(category="vehicles", near=LOT_B, within=1)],
    ),
    ask(
        "direct",
        "piece_by_stop_sign",
        GAMER,
        "Which piece on the board is standing closest to the stop sign?",
        [LAMP_STOP_SIGN],
        [find(nearest_to=STOP_SIGN)],
    ),
    ask(
        "direct",
        "bus_stop_to_gate",
        SCOT,
        "How far's the bus stop fae the main gate?",
        ["70.2"],
        [measure(BUS_STOP, MAIN_GATE)],
    ),
    ask(
        "direct",
        "ego_lane",
        DESI,
        "Kindly tell me in which lane the ego is driving.",
        ["main_eastbound"],
        [properties(asset=EGO)],
    ),
    impossible(
        "search",
        "direct",
        "fire_station",
        FIRE,
        "How far is the fire station from the hydrant on Main Street?",
        [measure("fire station", HYDRANT)],
    ),
    # indirect
    ask(
        "indirect",
        "hose_lay_to_incident",
        FIRE,
        "If we hook up to the hydrant for that job, how long a hose lay is it to the car?",
        ["21.8"],
        [measure(NEW_CAR, HYDRANT)],
        setup=[
            turn(
                "Stage the incident: a car stopped in the westbound lane outside the JTEKT entrance.",
                add(CAR, 1, loc("in_lane", JTEKT, lane=WESTBOUND)),
            )
        ],
    ),
    ask(
        "indirect",
        "weather_station_site",
        MET,
        "I want a temporary weather station at whichever named place is closest to where the ego starts. Which place is that?",
        ["parking lot A"],
        [landmarks(nearest_to=EGO)],
    ),
    ask(
        "indirect",
        "lamp_for_bench",
        GAFFER,
        "Before I light the bench at the bus stop I need to know which street lamp is closest to it.",
        ["street_light_4"],
        [find(category=LAMP, nearest_to=BENCH)],
    ),
    ask(
        "indirect",
        "on_main_street",
        FOREMAN,
        "Before we close any of Main Street I need to know what's actually standing on the carriageway right now.",
        ["ego"],
        [find(lane="Main Street")],
    ),
    ask(
        "indirect",
        "nearer_lot",
        DESI,
        "I am wanting to send my guests to the parking nearer to Engineering Hall. Which one is nearer, lot A or lot B?",
        ["parking lot A"],
        [measure(LOT_A, ENGINEERING), measure(LOT_B, ENGINEERING)],
    ),
    ask(
        "indirect",
        "bus_stop_again",
        CAPS,
        "I KEEP LOSING THE BUS STOP ON THE MAP!!! JUST TELL ME WHERE IT IS. AGAIN!!!",
        ["-30", "-5.5"],
        [landmarks(query=BUS_STOP)],
    ),
    ask(
        "indirect",
        "suv_colour_confirmed",
        CIVIL,
        "Confirmation is requested that the said vehicle now carries the approved colour; its present colour is to be stated.",
        ["silver"],
        [properties(asset=SUV)],
        setup=[turn("The sport utility vehicle is to be repainted silver.", paint([SUV], colour="silver"))],
    ),
    ask(
        "indirect",
        "ego_to_bus_stop",
        GAMER,
        "I'm planning my next move — how many metres are there between my ego piece and the bus stop?",
        ["30.2"],
        [measure(BUS_STOP)],
    ),
    ask(
        "indirect",
        "bin_near_stop",
        SCOT,
        "Is there a bin anywhere near the bus stop? Folk'll want tae chuck their rubbish when they get aff.",
        ["trash_bin_1"],
        [find(category=BIN_KIND, near=BUS_STOP, within=10)],
    ),
    ask(
        "indirect",
        "street_lights_by_themselves",
        GAFFER,
        "We go to night later on. Do the street lights come up by themselves, or do I have to bring them in on a cue?",
        [],
        [environment()],
        any_of=["auto", "at night"],
    ),
    impossible(
        "search",
        "indirect",
        "town_hall",
        CIVIL,
        "The distance between the Town Hall and the Library is to be furnished for the purposes of the survey.",
        [measure("Town Hall", LIBRARY)],
    ),
    # vague
    ask("vague", "hydrant", FIRE, "hydrant?", ["16", "5.5"], [find(category=HYDRANT_KIND)]),
    ask("vague", "sky", MET, "sky conditions?", ["clear"], [environment()]),
    ask(
        "vague",
        "lamps_by_bench",
        GAFFER,
        "lamps near the bench?",
        ["street_light_4"],
        [find(category=LAMP, near=BENCH, within=15)],
    ),
    ask(
        "vague",
        "lot_b_contents",
        FOREMAN,
        "anything parked up in lot B?",
        ["suv_1"],
        [find(near=LOT_B, within=1)],
    ),
    ask("vague", "ego_to_library", DESI, "distance from ego to library only?", ["23.2"], [measure(LIBRARY)]),
    ask(
        "vague",
        "trees_and_bench",
        CAPS,
        "TREES?? HOW MANY!!! AND WHERE'S THE BENCH GONE!!!",
        ["4", "-26"],
        [find(category=TREE), find(category=BENCH_KIND)],
    ),
    ask("vague", "stop_sign", CIVIL, "Location of the stop sign, please.", ["-13.5"], [find(category=STOP_KIND)]),
    ask(
        "vague",
        "where_knight",
        GAMER,
        "where's my knight now?",
        [],
        [find(category=ROBOT)],
        any_of=[ROBOT_ID, "parking lot A", "lot A"],
        setup=[KNIGHT_PLANNED],
    ),
    ask("vague", "wee_bench", SCOT, "where's the wee bench?", ["-26"], [find(category=BENCH_KIND)]),
    ask(
        "vague",
        "main_street_lanes",
        SCOT,
        "Main Street — whit lanes has it got?",
        ["main_eastbound", "main_westbound"],
        [lanes(road="Main Street")],
    ),
    impossible(
        "search", "vague", "chippy", SCOT, "how far's the chippy at the end o' the close fae here?", [measure("chippy")]
    ),
    # erroneous
    ask(
        "erroneous",
        "nearst_hydrnt",
        FIRE,
        "wher is the nearst hydrnt to the bus stpo and how far",
        ["47.3"],
        [find(category=HYDRANT_KIND, nearest_to=BUS_STOP)],
    ),
    ask(
        "erroneous",
        "whether",
        MET,
        "whats the whether doing rite now, any rian or fogg?",
        ["clear"],
        [environment()],
    ),
    ask(
        "erroneous",
        "north_lamps",
        GAFFER,
        "how many lamp posts r on the nrth side of main st",
        ["street_light_1", "street_light_11"],
        [find(category=LAMP, lane=WESTBOUND)],
        any_of=["6", "six"],
    ),
    ask(
        "erroneous",
        "lot_a_gaet",
        FOREMAN,
        "hw far is the lot a entrnace from the main gaet",
        ["15.4"],
        [measure(LOT_A_ENTRANCE, MAIN_GATE)],
    ),
    ask(
        "erroneous",
        "bus_hevy",
        DESI,
        "kindly tel me how hevy is one bus, we are planing to add",
        ["12000"],
        [properties(category=BUS)],
    ),
    ask(
        "erroneous",
        "libary_where",
        CAPS,
        "WHERE IS TEH LIBRARY ENTRANCE!!!! WHERE!!! I'VE LOOKED EVERYWHERE!!!",
        ["-41", "-15"],
        [landmarks(query=LIBRARY)],
    ),
    ask(
        "erroneous",
        "ego_hydrant",
        CIVIL,
        "The distnace betwen the ego vehical and the said hydrant is to be reported.",
        ["76.3"],
        [measure(HYDRANT)],
    ),
    ask(
        "erroneous",
        "bin_squre",
        GAMER,
        "wich squre is the trash bin on? give me its coordnates",
        ["-33.5", "-5.5"],
        [find(category=BIN_KIND)],
    ),
    ask(
        "erroneous",
        "motors_car_park",
        SCOT,
        "hoo mony motors are in teh car park the noo",
        ["suv_1"],
        [find(category="vehicles", near="car park", within=1)],
        any_of=["3", "three"],
    ),
    ask(
        "erroneous",
        "tiem_after_clock",
        MET,
        "wats the tiem in the sceen now",
        ["19:30"],
        [environment()],
        setup=[turn("Set the scene clock to 19:30 for the golden-hour run.", clock("19:30"), planned=True)],
    ),
    ask(
        "erroneous",
        "pice_by_fountian",
        GAMER,
        "whos the closest pice to the fountian",
        ["tree_2"],
        [find(nearest_to=FOUNTAIN)],
    ),
]

ADDITION_CASES: list[Json] = [
    # direct
    case(
        "addition",
        "direct",
        "incident_car_ahead",
        FIRE,
        "Put a car stopped in the eastbound lane 20 metres ahead of the ego — that's our incident vehicle.",
        [
            delta(CAR, 1, 1),
            relative("in_front_of", EGO, CAR, max_distance=26, tolerance_deg=20),
            in_lane(EASTBOUND, CAR, scope="added"),
            does("parked", CAR, scope="added"),
            only(CAR),
        ],
        [add(CAR, 1, ahead_of(EGO, 20))],
    ),
    case(
        "addition",
        "direct",
        "shelterer_and_drizzle",
        MET,
        "Add a pedestrian sheltering at the bus stop, and give me a light drizzle.",
        [
            delta(PERSON, 1, 1),
            near(BUS_STOP, 5, PERSON, scope="added"),
            env(weather=["rain"], intensity_max=0.45, **NOON),
            only(PERSON, env=True),
        ],
        [add(PERSON, 1, loc("at", BUS_STOP)), weather("rain", 0.2)],
    ),
    case(
        "addition",
        "direct",
        "two_practicals",
        GAFFER,
        "Add two more street lamps at the bus stop — I want them as practicals in the shot.",
        [delta(LAMP, 2, 2), near(BUS_STOP, 8, LAMP, scope="added", min_count=2), only(LAMP)],
        [add(LAMP, 2, loc("at", BUS_STOP))],
    ),
    case(
        "addition",
        "direct",
        "sign_before_crossing",
        FOREMAN,
        "Set out a roadworks sign on the south footway just before the west crosswalk.",
        [
            delta(WORK_SIGN, 1, 1),
            near(None, 4.5, WORK_SIGN, scope="added", point=(-13.0, -5.5)),
            on(["sidewalk", "ground"], WORK_SIGN, scope="added"),
            only(WORK_SIGN),
        ],
        [add(WORK_SIGN, 1, xy(-15.5, -5.5))],
    ),
    case(
        "addition",
        "direct",
        "one_more_bench",
        DESI,
        "Kindly add one more bench next to the bench at the bus stop.",
        [delta(BENCH_KIND, 1, 1), near(BENCH, 4, BENCH_KIND, scope="added"), only(BENCH_KIND)],
        [add(BENCH_KIND, 1, loc("next_to", BENCH))],
    ),
    case(
        "addition",
        "direct",
        "bus_at_the_stop",
        CAPS,
        "ADD A BUS AT THE BUS STOP. A BUS. AT THE BUS STOP. HOW HARD IS THAT!!!",
        [delta(BUS, 1, 1), near(BUS_STOP, 8, BUS, scope="added"), only(BUS)],
        [add(BUS, 1, loc("at", BUS_STOP))],
    ),
    case(
        "addition",
        "direct",
        "one_cone_lot_b",
        CIVIL,
        "It is requested that one (1) traffic cone be positioned at the entrance to car park B.",
        [delta(CONE, 1, 1), near(LOT_B_ENTRANCE, 4, CONE, scope="added"), only(CONE)],
        [add(CONE, 1, loc("at", LOT_B_ENTRANCE))],
    ),
    case(
        "addition",
        "direct",
        "pawn_on_square",
        GAMER,
        "New piece on the board: a pedestrian on the square at x 40, y -20.",
        [delta(PERSON, 1, 1), near(None, 1.5, PERSON, scope="added", point=(40.0, -20.0)), only(PERSON)],
        [add(PERSON, 1, xy(40, -20))],
    ),
    impossible(
        "addition",
        "direct",
        "excavator",
        FOREMAN,
        "Get an excavator in at lot A for the dig.",
        [add("excavator", 1, loc("at", LOT_A))],
    ),
    # indirect
    case(
        "addition",
        "indirect",
        "casualty_by_debris",
        FIRE,
        "Now we need a casualty on the road right beside that debris.",
        [delta(PERSON, 1, 1), near(RUBBLE_ID, 4, PERSON, scope="added"), only(PERSON)],
        [add(PERSON, 1, loc("next_to", RUBBLE_ID))],
        setup=[DEBRIS_PLANNED],
    ),
    case(
        "addition",
        "indirect",
        "crossers_in_the_wet",
        MET,
        "I want to see how the ego copes with people crossing in the wet: two pedestrians walking over the west "
        "crosswalk, in moderate rain.",
        [
            delta(PERSON, 2, 2),
            does("cross_road", PERSON, scope="added", min_count=2),
            env(weather=["rain"], intensity_min=0.4, intensity_max=0.8, **NOON),
            only(PERSON, env=True),
        ],
        [add(PERSON, 2, loc("at", WEST_CROSSWALK), behaviour={"kind": "cross_road"}), weather("rain", 0.6)],
    ),
    case(
        "addition",
        "indirect",
        "car_pulling_in_lights",
        GAFFER,
        "The lot A entrance looks dead in frame. I want a car just pulling in there, with its headlights on.",
        [
            delta(CAR, 1, 1),
            near(LOT_A_ENTRANCE, 12, CAR, scope="added"),
            env(vehicle_lights="on", weather=["clear"], **NOON),
            only(CAR, env=True),
        ],
        [add(CAR, 1, loc("at", LOT_A_ENTRANCE)), lighting(vehicle_lights="on")],
    ),
    case(
        "addition",
        "indirect",
        "lorry_for_plant",
        FOREMAN,
        "Plant's arriving tomorrow, so I need a delivery lorry sat in lot A ready to unload the barriers.",
        [delta(TRUCK, 1, 1), near(LOT_A, 0.5, TRUCK, scope="added"), only(TRUCK)],
        [add(TRUCK, 1, loc("at", LOT_A))],
    ),
    case(
        "addition",
        "indirect",
        "cyclist_opposite",
        DESI,
        "Kindly do the needful so that the ego meets one cyclist coming from the opposite side on Main Street.",
        [delta(BIKE, 1, 1), does("drive_lane", BIKE, scope="added", lane=WESTBOUND), only(BIKE)],
        [add(BIKE, 1, behaviour=drive(lane=WESTBOUND))],
    ),
    case(
        "addition",
        "indirect",
        "someone_steps_out",
        CAPS,
        "THE EGO NEVER HAS ANYONE TO DEAL WITH!!! GIVE IT SOMEBODY STEPPING OUT IN FRONT OF IT. NOT AT A CROSSING!!!",
        [delta(PERSON, 1, 1), does("jaywalk", PERSON, scope="added"), only(PERSON)],
        [add(PERSON, 1, behaviour={"kind": "jaywalk"})],
    ),
    case(
        "addition",
        "indirect",
        "seating_and_receptacle",
        CIVIL,
        "It is requested that provision be made for seating outside the Student Union entrance for the benefit of "
        "visitors, together with a refuse receptacle.",
        [
            delta(BENCH_KIND, 1, 1),
            delta(BIN_KIND, 1, 1),
            near(UNION, 8, BENCH_KIND, scope="added"),
            near(UNION, 8, BIN_KIND, scope="added"),
            only(BENCH_KIND, BIN_KIND),
        ],
        [add(BENCH_KIND, 1, loc("at", UNION)), add(BIN_KIND, 1, loc("at", UNION))],
    ),
    case(
        "addition",
        "indirect",
        "blocker_by_stop_sign",
        GAMER,
        "I need a blocker on that side: put a bollard on the square right in front of the stop sign.",
        [
            delta(BOLLARD, 1, 1),
            relative("in_front_of", STOP_SIGN, BOLLARD, max_distance=4, tolerance_deg=45),
            only(BOLLARD),
        ],
        [add(BOLLARD, 1, loc("in_front_of", STOP_SIGN))],
    ),
    impossible(
        "addition",
        "indirect",
        "fire_engine",
        FIRE,
        "For the drill I want a fire engine pulled up beside the hydrant, pump running.",
        [add("fire_engine", 1, loc("next_to", HYDRANT))],
    ),
    # vague
    case(
        "addition",
        "vague",
        "casualty_in_junction",
        FIRE,
        "casualty in the junction",
        [delta(PERSON, 1, 1), near(JUNCTION, 3, PERSON, scope="added"), only(PERSON)],
        [add(PERSON, 1, loc("at", JUNCTION))],
    ),
    case(
        "addition",
        "vague",
        "couple_watching_sky",
        MET,
        "couple of folk at the bus stop, watching the sky",
        [delta(PERSON, 2, 2), near(BUS_STOP, 8, PERSON, scope="added", min_count=2), only(PERSON)],
        [add(PERSON, 2, loc("at", BUS_STOP))],
    ),
    case(
        "addition",
        "vague",
        "lamp_by_bin",
        SCOT,
        "anither lamp by the bin",
        [delta(LAMP, 1, 1), near(BIN, 4, LAMP, scope="added"), only(LAMP)],
        [add(LAMP, 1, loc("next_to", BIN))],
    ),
    case(
        "addition",
        "vague",
        "rubble_lot_b",
        FOREMAN,
        "bit of rubble in lot B",
        [delta(RUBBLE, 1, 3), near(LOT_B, 0.5, RUBBLE, scope="added"), only(RUBBLE)],
        [add(RUBBLE, 1, loc("at", LOT_B))],
    ),
    case(
        "addition",
        "vague",
        "one_more_same_place",
        DESI,
        "one more, same place only",
        [delta(BENCH_KIND, 1, 1), near(FOUNTAIN, 10, BENCH_KIND, scope="added"), only(BENCH_KIND)],
        [add(BENCH_KIND, 1, loc("at", FOUNTAIN))],
        setup=[turn("Kindly add one bench near the fountain.", add(BENCH_KIND, 1, loc("at", FOUNTAIN)), planned=True)],
    ),
    case(
        "addition",
        "vague",
        "more_people_sidewalks",
        CAPS,
        "MORE PEOPLE!!! ON THE SIDEWALKS!!! IT'S A GHOST TOWN!!!",
        [delta(PERSON, 2, 30), on(["sidewalk"], PERSON, scope="added"), only(PERSON)],
        [add(PERSON, 4, loc("on_sidewalk", EGO))],
    ),
    case(
        "addition",
        "vague",
        "receptacle_bus_stop",
        CIVIL,
        "Additional refuse receptacle: bus stop.",
        [delta(BIN_KIND, 1, 1), near(BUS_STOP, 5, BIN_KIND, scope="added"), only(BIN_KIND)],
        [add(BIN_KIND, 1, loc("at", BUS_STOP))],
    ),
    case(
        "addition",
        "vague",
        "another_knight",
        GAMER,
        "another piece like that, right next to it",
        [delta(ROBOT, 1, 1), near(ROBOT_ID, 4, ROBOT, scope="added"), only(ROBOT)],
        [add(ROBOT, 1, loc("next_to", ROBOT_ID))],
        setup=[KNIGHT_GIVEN],
    ),
    impossible(
        "addition",
        "vague",
        "haze_machine",
        GAFFER,
        "haze machine behind the bench",
        [add("haze_machine", 1, loc("behind", BENCH))],
    ),
    # erroneous
    case(
        "addition",
        "erroneous",
        "car_blokcing_entrence",
        FIRE,
        "ad a parked car blokcing the lot b entrence",
        [delta(CAR, 1, 1), near(LOT_B_ENTRANCE, 6, CAR, scope="added"), only(CAR)],
        [add(CAR, 1, loc("at", LOT_B_ENTRANCE))],
    ),
    case(
        "addition",
        "erroneous",
        "jogger_drizzel",
        MET,
        "ad a jogger on the north sidewlk west of the junktion and make it drizzel",
        [
            delta(PERSON, 1, 1),
            on(["sidewalk"], PERSON, scope="added"),
            near(WESTBOUND, 4.5, PERSON, scope="added"),
            env(weather=["rain"], intensity_max=0.45, **NOON),
            only(PERSON, env=True),
        ],
        [add(PERSON, 1, loc("at", NORTH_WEST_WALK)), weather("rain", 0.2)],
    ),
    case(
        "addition",
        "erroneous",
        "lamp_lot_a_entrnace",
        GAFFER,
        "add a lamp post at the lot a entrnace, its to dark there for the shot",
        [delta(LAMP, 1, 1), near(LOT_A_ENTRANCE, 8, LAMP, scope="added"), only(LAMP)],
        [add(LAMP, 1, loc("at", LOT_A_ENTRANCE))],
    ),
    case(
        "addition",
        "erroneous",
        "two_barriers_entrence",
        FOREMAN,
        "need 2 barriers set out by the lot a entrence",
        [delta(BARRIER, 2, 2), near(LOT_A_ENTRANCE, 10, BARRIER, scope="added", min_count=2), only(BARRIER)],
        [add(BARRIER, 2, loc("at", LOT_A_ENTRANCE))],
    ),
    case(
        "addition",
        "erroneous",
        "truk_lot_b",
        CAPS,
        "ADD A TRUK IN LOT B!!! A TRUK!!! IN LOT B!!!",
        [delta(TRUCK, 1, 1), near(LOT_B, 0.5, TRUCK, scope="added"), only(TRUCK)],
        [add(TRUCK, 1, loc("at", LOT_B))],
    ),
    case(
        "addition",
        "erroneous",
        "motorcylce_westbund",
        CIVIL,
        "A motorcylce is to be introduced in the westbund lane, procceding west at normal speed.",
        [delta(MOTORBIKE, 1, 1), does("drive_lane", MOTORBIKE, scope="added", lane=WESTBOUND), only(MOTORBIKE)],
        [add(MOTORBIKE, 1, behaviour=drive(lane=WESTBOUND))],
    ),
    case(
        "addition",
        "erroneous",
        "pawn_by_bench",
        GAMER,
        "plce a pawn — a pedestrain — on the squre next to the bench",
        [delta(PERSON, 1, 1), near(BENCH, 4, PERSON, scope="added"), only(PERSON)],
        [add(PERSON, 1, loc("next_to", BENCH))],
    ),
    case(
        "addition",
        "erroneous",
        "wheen_o_folk",
        SCOT,
        "an a wheen o folk waitin on it at teh stoap wi thier messages",
        [delta(PERSON, 2, 8), near(BUS_STOP, 10, PERSON, scope="added", min_count=2), only(PERSON)],
        [add(PERSON, 3, loc("at", BUS_STOP))],
        setup=[BUS_IN_PLANNED],
    ),
    impossible(
        "addition",
        "erroneous",
        "seventy_cars",
        DESI,
        "kindly add seventy car in lot B itself for the function",
        [add(CAR, 70, loc("at", LOT_B))],
    ),
]

REMOVAL_CASES: list[Json] = [
    # direct
    case(
        "removal",
        "direct",
        "car_nearest_union",
        FIRE,
        "Remove the car parked nearest the Student Union entrance.",
        [gone(CAR_2), only(assets=[CAR_2])],
        [remove(CAR_2)],
    ),
    case(
        "removal",
        "direct",
        "two_trees_by_fountain",
        MET,
        "Remove the two trees nearest the fountain — they're sheltering my anemometer.",
        [gone(TREE_FOUNTAIN, TREE_EAST), only(assets=[TREE_FOUNTAIN, TREE_EAST])],
        [remove(TREE_FOUNTAIN, TREE_EAST)],
    ),
    case(
        "removal",
        "direct",
        "strike_bus_stop_lamp",
        GAFFER,
        "Strike the street lamp at the bus stop.",
        [gone(LAMP_BUS_STOP), only(assets=[LAMP_BUS_STOP])],
        [remove(LAMP_BUS_STOP)],
    ),
    case(
        "removal",
        "direct",
        "bench_for_resurfacing",
        FOREMAN,
        "Take the bench out at the bus stop, we're resurfacing that bit of footway.",
        [gone(BENCH), only(assets=[BENCH])],
        [remove(BENCH)],
    ),
    case(
        "removal",
        "direct",
        "lamp_by_stop_sign",
        DESI,
        "Kindly remove the lamp post next to the stop sign only.",
        [gone(LAMP_STOP_SIGN), kept(STOP_SIGN), only(assets=[LAMP_STOP_SIGN])],
        [remove(LAMP_STOP_SIGN)],
    ),
    case(
        "removal",
        "direct",
        "bin_asked_three_times",
        CAPS,
        "REMOVE THE TRASH BIN. JUST REMOVE IT!!! I'VE ASKED THREE TIMES!!!",
        [gone(BIN), only(assets=[BIN])],
        [remove(BIN)],
    ),
    case(
        "removal",
        "direct",
        "suv_forthwith",
        CIVIL,
        "The sport utility vehicle in car park B is to be removed forthwith.",
        [gone(SUV), only(assets=[SUV])],
        [remove(SUV)],
    ),
    case(
        "removal",
        "direct",
        "capture_east_tree",
        GAMER,
        "Capture the tree nearest the east gate — take it off the board.",
        [gone(TREE_EAST), only(assets=[TREE_EAST])],
        [remove(TREE_EAST)],
    ),
    impossible(
        "removal",
        "direct",
        "ego_out",
        CAPS,
        "REMOVE THE EGO CAR!!! GET IT OUT OF MY SCENE!!! OUT!!!",
        [remove(EGO)],
    ),
    # indirect
    case(
        "removal",
        "indirect",
        "car_on_hydrant",
        FIRE,
        "That car's blocking the hydrant and the access has to be kept clear. Get it off the scene altogether.",
        [gone(NEW_CAR), only(assets=[NEW_CAR])],
        [remove(NEW_CAR)],
        setup=[turn("Park a car right beside the hydrant.", add(CAR, 1, loc("next_to", HYDRANT)), planned=True)],
    ),
    case(
        "removal",
        "indirect",
        "tree_shading_lot_a",
        MET,
        "My sky camera in lot A is in shade half the day — lose the tree on the north edge of the lot.",
        [gone(TREE_LOT_A), only(assets=[TREE_LOT_A])],
        [remove(TREE_LOT_A)],
    ),
    case(
        "removal",
        "indirect",
        "lamp_flaring",
        GAFFER,
        "The lamp by the lot A entrance is flaring into the lens. Lose it.",
        [gone(LAMP_LOT_A), only(assets=[LAMP_LOT_A])],
        [remove(LAMP_LOT_A)],
    ),
    case(
        "removal",
        "indirect",
        "works_finished",
        FOREMAN,
        "Works are finished on the south side, so the cones and the sign can all come away now.",
        [count(CONE, 0, 0), count(WORK_SIGN, 0, 0), only(CONE, WORK_SIGN)],
        [remove(category=CONE), remove(category=WORK_SIGN)],
        setup=[
            turn(
                "Set out four cones and a roadworks sign on the south side by the bus stop.",
                add(CONE, 4, loc("in_lane", BUS_STOP, lane=EASTBOUND)),
                add(WORK_SIGN, 1, loc("at", BUS_STOP)),
            )
        ],
    ),
    case(
        "removal",
        "indirect",
        "dustbin_on_footpath",
        DESI,
        "Kindly do the needful, the dustbin is obstructing the footpath near the bus stop.",
        [only(assets=[BIN])],
        [remove(BIN)],
        alternatives=[[gone(BIN)], [moved(BIN, 1.0)]],
    ),
    case(
        "removal",
        "indirect",
        "empty_lot_b_and_bin",
        CAPS,
        "WHY ARE THERE STILL CARS IN LOT B?!?! I WANT IT EMPTY!!! AND GET RID OF THAT STUPID BIN WHILE YOU'RE AT IT!!!",
        [gone(*PARKED, BIN), only(assets=[*PARKED, BIN])],
        [remove(*PARKED), remove(BIN)],
    ),
    case(
        "removal",
        "indirect",
        "bus_stop_furniture",
        CIVIL,
        "Pursuant to the review of street furniture, the bench and the refuse receptacle at the bus stop shall be "
        "withdrawn from service.",
        [gone(BENCH, BIN), only(assets=[BENCH, BIN])],
        [remove(BENCH, BIN)],
    ),
    case(
        "removal",
        "indirect",
        "middle_cone",
        GAMER,
        "Take the middle one of those three off the board.",
        [gone("traffic_cone_2"), kept("traffic_cone_1", "traffic_cone_3"), only(assets=["traffic_cone_2"])],
        [remove("traffic_cone_2")],
        setup=[
            turn(
                "Put three cones in a row in front of the stop sign.",
                arrange(CONE, "line", loc("in_front_of", STOP_SIGN), count=3),
            )
        ],
    ),
    case(
        "removal",
        "indirect",
        "tree_blocking_view",
        SCOT,
        "The wee tree by the library's blocking the view o' the bus stop fae the road. Get shot o' it.",
        [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
        [remove(TREE_LIBRARY)],
    ),
    # vague
    case(
        "removal",
        "vague",
        "clear_the_cones",
        FIRE,
        "incident's over. clear the cones.",
        [count(CONE, 0, 0), only(CONE)],
        [remove(category=CONE)],
        setup=[
            turn(
                "Cone off the hydrant: a few cones in the road beside it.",
                arrange(CONE, "lane_edge", loc("at", HYDRANT), count=4),
                planned=True,
            )
        ],
    ),
    case(
        "removal",
        "vague",
        "fewer_trees",
        MET,
        "fewer trees — they mess with my wind readings",
        [delta(TREE, -4, -1), only(TREE)],
        [remove(TREE_FOUNTAIN)],
    ),
    case(
        "removal",
        "vague",
        "strike_south_lamps",
        GAFFER,
        "strike the lamps on the south side",
        [gone(*SOUTH_LAMPS), kept(*NORTH_LAMPS), only(assets=SOUTH_LAMPS)],
        [remove(*SOUTH_LAMPS)],
    ),
    case(
        "removal",
        "vague",
        "one_car_only",
        DESI,
        "remove one car only",
        [delta([CAR, SUV_KIND], -1, -1), only(CAR, SUV_KIND)],
        [remove(CAR_1)],
    ),
    case(
        "removal",
        "vague",
        "north_lamps",
        CAPS,
        "LAMPS!!! WAY TOO MANY LAMPS ON THE NORTH SIDE!!! GET RID OF THEM!!!",
        [gone(*NORTH_LAMPS), kept(*SOUTH_LAMPS), only(assets=NORTH_LAMPS)],
        [remove(*NORTH_LAMPS)],
    ),
    case(
        "removal",
        "vague",
        "stop_sign_removal",
        CIVIL,
        "Removal of the stop sign at the west crossing.",
        [gone(STOP_SIGN), only(assets=[STOP_SIGN])],
        [remove(STOP_SIGN)],
    ),
    case(
        "removal",
        "vague",
        "benches_off_board",
        GAMER,
        "clear every bench off the board",
        [count(BENCH_KIND, 0, 0), only(BENCH_KIND)],
        [remove(category=BENCH_KIND)],
    ),
    case(
        "removal",
        "vague",
        "shot_o_the_bin",
        SCOT,
        "get shot o' the bin",
        [gone(BIN), only(assets=[BIN])],
        [remove(BIN)],
    ),
    impossible(
        "removal",
        "vague",
        "rip_up_crosswalk",
        FOREMAN,
        "rip up the west crosswalk, it's getting resurfaced",
        [remove(WEST_CROSSWALK)],
    ),
    # erroneous
    case(
        "removal",
        "erroneous",
        "suv_acess_route",
        FIRE,
        "remvoe the suv from lot b, its parked on the acess route",
        [gone(SUV), only(assets=[SUV])],
        [remove(SUV)],
    ),
    case(
        "removal",
        "erroneous",
        "tree_nere_libary",
        MET,
        "take away the tree nere the libary, it blocks the sky veiw",
        [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
        [remove(TREE_LIBRARY)],
    ),
    case(
        "removal",
        "erroneous",
        "lamp_by_hydrnt",
        GAFFER,
        "strke the lamp closest the hydrnt",
        [gone(LAMP_HYDRANT), only(assets=[LAMP_HYDRANT])],
        [remove(LAMP_HYDRANT)],
    ),
    case(
        "removal",
        "erroneous",
        "barriers_exept_gate",
        FOREMAN,
        "remoev all the barriers exept the one by the main gate",
        [
            gone("road_barrier_1", "road_barrier_2"),
            kept("road_barrier_3"),
            only(assets=["road_barrier_1", "road_barrier_2"]),
        ],
        [remove("road_barrier_1", "road_barrier_2")],
        setup=[
            turn(
                "Set out two barriers at the lot A entrance and one by the main gate.",
                add(BARRIER, 2, loc("at", LOT_A_ENTRANCE)),
                add(BARRIER, 1, loc("at", MAIN_GATE)),
            )
        ],
    ),
    case(
        "removal",
        "erroneous",
        "two_lamps_entrence",
        DESI,
        "kindly remove the two lamp post near the lot A entrence itself",
        [gone(LAMP_LOT_A, "street_light_2"), only(assets=[LAMP_LOT_A, "street_light_2"])],
        [remove(LAMP_LOT_A, "street_light_2")],
    ),
    case(
        "removal",
        "erroneous",
        "all_teh_cones",
        CAPS,
        "REMOVE ALL TEH TRAFIC CONES!!!! ALL OF THEM!!! NOW!!!",
        [count(CONE, 0, 0), only(CONE)],
        [remove(category=CONE)],
        setup=[
            turn(
                "Put a line of cones along the westbound lane edge.",
                arrange(CONE, "lane_edge", loc("at", WESTBOUND), count=6),
                planned=True,
            )
        ],
    ),
    case(
        "removal",
        "erroneous",
        "pice_on_bus_stop_squre",
        GAMER,
        "captuer the pice on the bus stop squre",
        [delta([BENCH_KIND, BIN_KIND], -1, -1), only(BENCH_KIND, BIN_KIND)],
        [remove(BIN)],
        alternatives=[[gone(BIN)], [gone(BENCH)]],
    ),
    case(
        "removal",
        "erroneous",
        "motors_bar_big_yin",
        SCOT,
        "get rid o the motors in teh car prak bar the big yin",
        [gone(CAR_1, CAR_2), kept(SUV), only(assets=[CAR_1, CAR_2])],
        [remove(CAR_1, CAR_2)],
    ),
    impossible(
        "removal",
        "erroneous",
        "union_demolishd",
        CIVIL,
        "The Studnet Union bulding is to be demolishd forthwith.",
        [remove("Student Union")],
    ),
]

POSITIONING_CASES: list[Json] = [
    # direct
    case(
        "positioning",
        "direct",
        "suv_outside_jtekt",
        FIRE,
        "Put the SUV in the westbound lane outside the JTEKT entrance — it's playing the incident vehicle.",
        [in_lane(WESTBOUND, asset=SUV), near(JTEKT, 16, asset=SUV), only(assets=[SUV])],
        [place(SUV, loc("in_lane", JTEKT, lane=WESTBOUND))],
    ),
    case(
        "positioning",
        "direct",
        "observer_bench_overcast",
        MET,
        "Move the bench over to the fountain for an observer, and make it overcast — I want a squall line building.",
        [near(FOUNTAIN, 6, asset=BENCH), env(weather=["cloudy", "rain"], **NOON), only(assets=[BENCH], env=True)],
        [place(BENCH, loc("at", FOUNTAIN)), weather("cloudy", 0.7)],
    ),
    case(
        "positioning",
        "direct",
        "bin_by_stop_sign",
        SCOT,
        "Pit the bin next tae the stop sign.",
        [near(STOP_SIGN, 3, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("next_to", STOP_SIGN))],
    ),
    case(
        "positioning",
        "direct",
        "site_wagon_lot_a",
        FOREMAN,
        "Put the SUV at the lot A entrance, it's our site wagon now.",
        [near(LOT_A_ENTRANCE, 8, asset=SUV), only(assets=[SUV])],
        [place(SUV, loc("at", LOT_A_ENTRANCE))],
    ),
    case(
        "positioning",
        "direct",
        "car1_library",
        DESI,
        "Kindly place the car at the west end of lot B in front of the Library entrance.",
        [relative("in_front_of", LIBRARY, asset=CAR_1, max_distance=12), only(assets=[CAR_1])],
        [place(CAR_1, loc("in_front_of", LIBRARY))],
    ),
    case(
        "positioning",
        "direct",
        "bench_back",
        CAPS,
        "NO!!! PUT THE BENCH BACK AT THE BUS STOP WHERE IT WAS!!! BACK!!!",
        [near(BUS_STOP, 5, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, xy(-26.0, -6.9))],
        setup=[turn("Move the bench to the fountain.", place(BENCH, loc("at", FOUNTAIN)))],
    ),
    case(
        "positioning",
        "direct",
        "bin_to_engineering",
        CIVIL,
        "The refuse receptacle shall be relocated to the entrance of Engineering Hall.",
        [near(ENGINEERING, 5, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("at", ENGINEERING))],
    ),
    case(
        "positioning",
        "direct",
        "ego_back_square",
        GAMER,
        "Put the ego on the square at x -80, y -1.75, further back from its start line.",
        [near(None, 1.5, asset=EGO, point=(-80.0, -1.75)), only(assets=[EGO])],
        [place(EGO, xy(-80, -1.75))],
    ),
    impossible(
        "positioning",
        "direct",
        "suv_off_board",
        GAMER,
        "Move the SUV to the square at x 150, y 0 — just off the east edge of the board.",
        [place(SUV, xy(150, 0))],
    ),
    # indirect
    case(
        "positioning",
        "indirect",
        "hydrant_for_library",
        FIRE,
        "If the Library ever goes up we want water right at its front door — put the hydrant there.",
        [near(LIBRARY, 8, asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, loc("at", LIBRARY))],
    ),
    case(
        "positioning",
        "indirect",
        "ego_from_east_gate",
        MET,
        "Later I'll roll a fog bank in from the west, so start the ego in the westbound lane just inside the east "
        "gate, heading into it.",
        [in_lane(WESTBOUND, asset=EGO, aligned=True), near(EAST_GATE, 15, asset=EGO), only(assets=[EGO])],
        [place(EGO, loc("in_lane", EAST_GATE, lane=WESTBOUND))],
    ),
    case(
        "positioning",
        "indirect",
        "bench_in_the_pool",
        GAFFER,
        "The bench wants to sit in the pool of light under the lamp by the lot A entrance.",
        [near(LAMP_LOT_A, 3, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("next_to", LAMP_LOT_A))],
    ),
    case(
        "positioning",
        "indirect",
        "suv_clear_of_bays",
        FOREMAN,
        "The works need the lot B bays clear, so park the SUV up by the Student Union entrance instead.",
        [near(UNION, 10, asset=SUV), only(assets=[SUV])],
        [place(SUV, loc("at", UNION))],
    ),
    case(
        "positioning",
        "indirect",
        "truck_for_books",
        DESI,
        "The truck itself should be at the Library entrance for unloading the books. Kindly place it there.",
        [near(LIBRARY, 12, asset=TRUCK_ID), only(assets=[TRUCK_ID])],
        [place(TRUCK_ID, loc("in_front_of", LIBRARY))],
        setup=[turn("Kindly add one delivery truck in lot A.", add(TRUCK, 1, loc("at", LOT_A)), planned=True)],
    ),
    case(
        "positioning",
        "indirect",
        "stop_sign_wrong_side",
        CAPS,
        "THE STOP SIGN IS ON THE WRONG SIDE!!! IT GOES ON THE NORTH SIDE BY THE WEST CROSSWALK!!! NORTH!!!",
        [
            near(None, 3.5, asset=STOP_SIGN, point=(-12.5, 5.5)),
            on(["sidewalk", "ground"], asset=STOP_SIGN),
            only(assets=[STOP_SIGN]),
        ],
        [place(STOP_SIGN, xy(-13.5, 5.5))],
    ),
    case(
        "positioning",
        "indirect",
        "cars_to_lot_a",
        CIVIL,
        "It is requested that the two saloon cars presently in car park B be stationed in car park A so that car park "
        "B may be inspected.",
        [near(LOT_A, 0.5, asset=CAR_1), near(LOT_A, 0.5, asset=CAR_2), only(assets=[CAR_1, CAR_2])],
        [place(CAR_1, loc("at", LOT_A)), place(CAR_2, loc("at", LOT_A))],
    ),
    case(
        "positioning",
        "indirect",
        "ego_mid_board",
        GAMER,
        "I want my ego piece to start the game right in the middle of the board.",
        [near(JUNCTION, 1, asset=EGO), only(assets=[EGO])],
        [place(EGO, loc("scene_centre"))],
    ),
    impossible(
        "positioning",
        "indirect",
        "lamp_on_roof",
        GAFFER,
        "Rig the street lamp by the bus stop up on the JTEKT building's roof, I want it as a top light.",
        [place(LAMP_BUS_STOP, xy(37.5, 29))],
    ),
    # vague
    case(
        "positioning",
        "vague",
        "hydrant_by_fountain",
        FIRE,
        "hydrant over by the fountain",
        [near(FOUNTAIN, 6, asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, loc("at", FOUNTAIN))],
    ),
    case(
        "positioning",
        "vague",
        "bench_open_sky",
        MET,
        "bench somewhere with open sky — lot A?",
        [near(LOT_A, 1, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("at", LOT_A))],
    ),
    case(
        "positioning",
        "vague",
        "bin_out_of_shot",
        GAFFER,
        "bin out of shot, over in lot B",
        [near(LOT_B, 1, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("at", LOT_B))],
    ),
    case(
        "positioning",
        "vague",
        "suv_to_gate",
        FOREMAN,
        "SUV to the gate",
        [only(assets=[SUV])],
        [place(SUV, loc("at", MAIN_GATE))],
        alternatives=[[near(MAIN_GATE, 12, asset=SUV)], [near(EAST_GATE, 12, asset=SUV)]],
    ),
    case(
        "positioning",
        "vague",
        "bench_near_library",
        DESI,
        "bench near library only",
        [near(LIBRARY, 6, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("at", LIBRARY))],
    ),
    case(
        "positioning",
        "vague",
        "car_to_lot_a",
        CAPS,
        "CAR TO LOT A!!! NOW!!!",
        [near(LOT_A, 0.5, [CAR, SUV_KIND]), only(CAR, SUV_KIND)],
        [place(CAR_1, loc("at", LOT_A))],
    ),
    case(
        "positioning",
        "vague",
        "hydrant_north_crosswalk",
        CIVIL,
        "Relocation of the hydrant: north crosswalk.",
        [near(NORTH_CROSSWALK, 6, asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, loc("at", NORTH_CROSSWALK))],
    ),
    case(
        "positioning",
        "vague",
        "knight_to_lot_b",
        GAMER,
        "knight to lot B",
        [near(LOT_B, 0.5, asset=ROBOT_ID), only(assets=[ROBOT_ID])],
        [place(ROBOT_ID, loc("at", LOT_B))],
        setup=[KNIGHT_PLANNED],
    ),
    impossible(
        "positioning",
        "vague",
        "bin_inside_library",
        DESI,
        "keep the bin inside the library itself",
        [place(BIN, xy(-41, -30))],
    ),
    # erroneous
    case(
        "positioning",
        "erroneous",
        "hydarnt_back",
        FIRE,
        "put the hydarnt back on the north sidewak by the junktion where it was",
        [near(None, 5, asset=HYDRANT, point=(16.0, 5.5)), on(["sidewalk"], asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, xy(16, 5.5))],
        setup=[turn("Move the hydrant over to the fountain.", place(HYDRANT, loc("at", FOUNTAIN)))],
    ),
    case(
        "positioning",
        "erroneous",
        "ego_main_gaet",
        MET,
        "put the ego at the main gaet facing east, redy for the fog run",
        [near(MAIN_GATE, 12, asset=EGO), in_lane(EASTBOUND, asset=EGO, aligned=True), only(assets=[EGO])],
        [place(EGO, loc("in_lane", MAIN_GATE, lane=EASTBOUND))],
    ),
    case(
        "positioning",
        "erroneous",
        "bin_behnd_bench",
        GAFFER,
        "put the bin behnd the bench",
        [relative("behind", BENCH, asset=BIN, max_distance=4), only(assets=[BIN])],
        [place(BIN, loc("behind", BENCH))],
    ),
    case(
        "positioning",
        "erroneous",
        "stop_sign_entrence",
        FOREMAN,
        "shfit the stop sign to the lot b entrence",
        [near(LOT_B_ENTRANCE, 6, asset=STOP_SIGN), only(assets=[STOP_SIGN])],
        [place(STOP_SIGN, loc("at", LOT_B_ENTRANCE))],
    ),
    case(
        "positioning",
        "erroneous",
        "suv_infront_jtekt",
        DESI,
        "kindly put the suv infront of JTEKT enterance itself",
        [relative("in_front_of", JTEKT, asset=SUV, max_distance=12), only(assets=[SUV])],
        [place(SUV, loc("in_front_of", JTEKT))],
    ),
    case(
        "positioning",
        "erroneous",
        "bin_at_teh_library",
        CAPS,
        "PUT TEH TRASH BIN AT TEH LIBRARY!!! TEH LIBRARY!!!",
        [near(LIBRARY, 6, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("at", LIBRARY))],
    ),
    case(
        "positioning",
        "erroneous",
        "bench_east_gate",
        CIVIL,
        "The bench is to be relocted to the vicinty of the east gate.",
        [near(EAST_GATE, 10, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("at", EAST_GATE))],
    ),
    case(
        "positioning",
        "erroneous",
        "castel_bench_bin",
        GAMER,
        "castel the bench and the bin — swap there squares",
        [
            near(None, 2.5, asset=BIN, point=(-26.0, -6.9)),
            near(None, 2.5, asset=BENCH, point=(-33.5, -5.5)),
            only(assets=[BENCH, BIN]),
        ],
        [place(BIN, xy(-28.0, -6.9)), place(BENCH, xy(-33.5, -5.5))],
    ),
    case(
        "positioning",
        "erroneous",
        "naw_ootside_library",
        SCOT,
        "naw, no there — pit it ootside the library insteid",
        [near(LIBRARY, 6, asset=NEW_BENCH), only(assets=[NEW_BENCH])],
        [place(NEW_BENCH, loc("at", LIBRARY))],
        setup=[turn("Pit a bench by the fountain.", add(BENCH_KIND, 1, loc("at", FOUNTAIN)), planned=True)],
    ),
]

MOVING_CASES: list[Json] = [
    # direct
    case(
        "moving",
        "direct",
        "suv_out_of_bay",
        SCOT,
        "Shift the SUV five metres forrit, oot o' its bay.",
        [moved(SUV, 4.5, 5.5, "forward"), only(assets=[SUV])],
        [move(SUV, forward=5)],
    ),
    case(
        "moving",
        "direct",
        "ego_slow_in_fog",
        MET,
        "Drop the ego to 3 m/s and bring the visibility down with a moderate fog.",
        [
            does("drive_lane", asset=EGO, speed_min=2.9, speed_max=3.1, lane=EASTBOUND),
            env(weather=["fog"], **NOON),
            only(assets=[EGO], env=True),
        ],
        [behave(EGO, "drive_lane", speed=3.0), weather("fog", 0.5)],
    ),
    case(
        "moving",
        "direct",
        "cue_brake",
        GAFFER,
        "On cue at 5 seconds, the ego brakes to a stop.",
        [event_played(EGO, "stop", 8), only()],
        [manoeuvre(EGO, "stop", 5.0)],
    ),
    case(
        "moving",
        "direct",
        "bench_quarter_turn",
        FOREMAN,
        "Give the bench a quarter turn so it faces the road.",
        [moved(BENCH, 0.0, 0.5, turn_min=80, turn_max=100), only(assets=[BENCH])],
        [move(BENCH, turn_deg=-90)],
    ),
    case(
        "moving",
        "direct",
        "overtake_left",
        DESI,
        "Kindly make the ego do one lane change to the left at 3 seconds, for overtaking.",
        [event_played(EGO, "lane_change", 6), only()],
        [manoeuvre(EGO, "lane_change", 3.0, side="left")],
    ),
    case(
        "moving",
        "direct",
        "suv_circles",
        CAPS,
        "MAKE THE SUV DRIVE IN CIRCLES IN LOT B!!! CIRCLES!!!",
        [does("circle", asset=SUV, centre_near=LOT_B), only(assets=[SUV])],
        [behave(SUV, "circle")],
    ),
    case(
        "moving",
        "direct",
        "ego_36_and_stop",
        CIVIL,
        "The ego vehicle shall proceed eastbound at 36 km/h and shall come to a stop before the west crosswalk.",
        [
            does("drive_lane", asset=EGO, speed_min=9.8, speed_max=10.2),
            stops_before(EGO, *WEST_CROSSWALK_LINE, seconds=20),
            only(assets=[EGO]),
        ],
        [behave(EGO, "drive_lane", speed=10.0, lane=EASTBOUND), event(EGO, "stop", reach(WEST_CROSSWALK))],
    ),
    case(
        "moving",
        "direct",
        "bin_one_square",
        GAMER,
        "Move the bin one square east — call a square two metres.",
        [near(None, 0.5, asset=BIN, point=(-31.5, -5.5)), only(assets=[BIN])],
        [move(BIN, east=2)],
    ),
    case(
        "moving",
        "direct",
        "bench_shove_left",
        SCOT,
        "Shove the bench a metre and a half tae its left.",
        [moved(BENCH, 1.3, 1.7, "left"), only(assets=[BENCH])],
        [move(BENCH, left=1.5)],
    ),
    case(
        "moving",
        "direct",
        "ego_short_of_crosswalk",
        FIRE,
        "Have the ego pull up short of the west crosswalk.",
        [stops_before(EGO, *WEST_CROSSWALK_LINE, seconds=20), only()],
        [event(EGO, "stop", reach(WEST_CROSSWALK))],
    ),
    impossible(
        "moving",
        "direct",
        "tree_circles",
        CAPS,
        "MAKE THE TREE BY THE LIBRARY DRIVE IN CIRCLES!!! THE TREE!!! CIRCLES!!!",
        [behave(TREE_LIBRARY, "circle")],
    ),
    # indirect
    case(
        "moving",
        "indirect",
        "suv_pull_out_east",
        FIRE,
        "The appliance needs room in lot B, so get the SUV to pull out and drive off east along Main Street.",
        [does("drive_lane", asset=SUV, lane=EASTBOUND), only(assets=[SUV])],
        [behave(SUV, "drive_lane", lane=EASTBOUND)],
    ),
    case(
        "moving",
        "indirect",
        "poor_visibility_speed",
        MET,
        "Visibility's poor out there today; nobody should be doing more than about 2 m/s. Get the ego down to that.",
        [does("drive_lane", asset=EGO, speed_min=1.5, speed_max=2.05), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=2.0)],
    ),
    case(
        "moving",
        "indirect",
        "hold_red",
        GAFFER,
        "For this take the traffic light on the Library corner stays red the whole time, so the ego has to sit and wait at it.",
        [stops_before(EGO, *WEST_CROSSWALK_LINE, seconds=20), only()],
        [hold(LIGHT_SW, "red")],
    ),
    case(
        "moving",
        "indirect",
        "lorry_backing_out",
        FOREMAN,
        "The lorry's backing out of its spot — have it reverse 10 metres at the start.",
        [event_played(TRUCK_ID, "reverse", 5), only()],
        [manoeuvre(TRUCK_ID, "reverse", 0.0, distance=10)],
        setup=[LORRY_PLANNED],
    ),
    case(
        "moving",
        "indirect",
        "prepone_braking",
        DESI,
        "Kindly prepone the braking: the ego should brake at 2 seconds only.",
        [event_played(EGO, "stop", 3), only()],
        [manoeuvre(EGO, "stop", 2.0)],
        setup=[turn("Make the ego brake to a stop at 6 seconds.", manoeuvre(EGO, "stop", 6.0))],
    ),
    case(
        "moving",
        "indirect",
        "ego_crawling",
        CAPS,
        "THE EGO IS CRAWLING!!! IT NEEDS TO DO 12 METRES A SECOND!!! 12!!!",
        [does("drive_lane", asset=EGO, speed_min=11.9, speed_max=12.1), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=12.0)],
    ),
    case(
        "moving",
        "indirect",
        "car1_rear_inspection",
        CIVIL,
        "It is requested that the westernmost saloon car in car park B be advanced four metres from its present bay "
        "so that its rear may be inspected.",
        [moved(CAR_1, 3.5, 4.5, "forward"), only(assets=[CAR_1])],
        [move(CAR_1, forward=4)],
    ),
    case(
        "moving",
        "indirect",
        "knights_move_bin",
        GAMER,
        "Knight's move for the bin: two squares north and one east, a square being a metre.",
        [near(None, 0.5, asset=BIN, point=(-32.5, -3.5)), only(assets=[BIN])],
        [move(BIN, north=2, east=1)],
    ),
    case(
        "moving",
        "indirect",
        "ego_up_campus_drive",
        SCOT,
        "Ah want the ego tae turn left at the crossroads an' head up Campus Drive.",
        [event_played(EGO, "junction_turn", 15), only()],
        [manoeuvre(EGO, "junction_turn", 0.0, turn="left")],
    ),
    case(
        "moving",
        "indirect",
        "step_out_at_30",
        FIRE,
        "When the ego gets within 30 metres of them, they step out and cross.",
        [event_played(PED_ID, "cross_road", 15), only()],
        [event(PED_ID, "cross_road", {"kind": "distance", "actor": EGO, "other": PED_ID, "metres": 30})],
        setup=[
            turn(
                "Put a pedestrian waiting at the west crosswalk.",
                add(PERSON, 1, loc("at", WEST_CROSSWALK)),
                planned=True,
            )
        ],
    ),
    impossible(
        "moving",
        "indirect",
        "suv_250kmh",
        CIVIL,
        "The said vehicle, the sport utility vehicle, shall proceed along Main Street at 250 km/h.",
        [behave(SUV, "drive_lane", speed=69.4, lane=EASTBOUND)],
    ),
    # vague
    case(
        "moving",
        "vague",
        "ego_slower",
        SCOT,
        "ego slower, eh",
        [does("drive_lane", asset=EGO, speed_min=0.5, speed_max=4.5), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=3.0)],
    ),
    case(
        "moving",
        "vague",
        "racing_the_squall",
        MET,
        "ego faster — we're racing the squall, so let's have it: heavy rain",
        [
            does("drive_lane", asset=EGO, speed_min=5.5),
            env(weather=["rain"], intensity_min=0.7, **NOON),
            only(assets=[EGO], env=True),
        ],
        [behave(EGO, "drive_lane", speed=8.0), weather("rain", 0.9)],
    ),
    case(
        "moving",
        "vague",
        "bench_nudge_left",
        GAFFER,
        "nudge the bench left a touch",
        [moved(BENCH, 0.1, 1.5, "left"), only(assets=[BENCH])],
        [move(BENCH, left=0.5)],
    ),
    case(
        "moving",
        "vague",
        "suv_out_the_road",
        SCOT,
        "SUV oot the road",
        [moved(SUV, 2.0), only(assets=[SUV])],
        [move(SUV, forward=6)],
    ),
    case(
        "moving",
        "vague",
        "ego_round_lot_a",
        DESI,
        "ego should go round and round in lot A only",
        [does("circle", asset=EGO, centre_near=LOT_A), only(assets=[EGO])],
        [behave(EGO, "circle", centre=LOT_A)],
    ),
    case(
        "moving",
        "vague",
        "turn_car_around",
        CAPS,
        "TURN THE CAR AROUND!!! AROUND!!!",
        [only(CAR, SUV_KIND, "ego_vehicle")],
        [move(CAR_1, turn_deg=180)],
        alternatives=[
            [moved(CAR_1, 0.0, 1.0, turn_min=150)],
            [moved(CAR_2, 0.0, 1.0, turn_min=150)],
            [moved(SUV, 0.0, 1.0, turn_min=150)],
            [moved(EGO, 0.0, 1.0, turn_min=150)],
        ],
    ),
    case(
        "moving",
        "vague",
        "brake_at_crosswalk",
        CIVIL,
        "Braking of the ego at the west crosswalk.",
        [stops_before(EGO, *WEST_CROSSWALK_LINE, seconds=20), only()],
        [event(EGO, "stop", reach(WEST_CROSSWALK))],
    ),
    case(
        "moving",
        "vague",
        "advance_suv",
        GAMER,
        "advance the SUV a couple of spaces",
        [moved(SUV, 1.0, 12.0, "forward"), only(assets=[SUV])],
        [move(SUV, forward=5)],
    ),
    case(
        "moving",
        "vague",
        "bin_wee_shove",
        SCOT,
        "gie the bin a wee shove tae the left",
        [moved(BIN, 0.1, 2.0, "left"), only(assets=[BIN])],
        [move(BIN, left=0.5)],
    ),
    case(
        "moving",
        "vague",
        "crawl_in_pea_souper",
        MET,
        "ego down to a crawl then",
        [does("drive_lane", asset=EGO, speed_max=3.0), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=1.5)],
        setup=[turn("Put a proper pea-souper of a fog over the whole campus.", weather("fog", 0.9), planned=True)],
    ),
    impossible("moving", "vague", "suv_300_east", GAMER, "SUV 300 metres east", [move(SUV, east=300)]),
    # erroneous
    case(
        "moving",
        "erroneous",
        "suv_drve_west",
        FIRE,
        "make the suv drve out of lot b and head west on main st",
        [does("drive_lane", asset=SUV, lane=WESTBOUND), only(assets=[SUV])],
        [behave(SUV, "drive_lane", lane=WESTBOUND)],
    ),
    case(
        "moving",
        "erroneous",
        "ego_4_visibilty",
        MET,
        "the ego shoud slow down to 4 m/s, visibilty is poor",
        [does("drive_lane", asset=EGO, speed_min=3.9, speed_max=4.1), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=4.0)],
    ),
    case(
        "moving",
        "erroneous",
        "suv_backs_on_que",
        GAFFER,
        "on que at 3 secs the suv backs up 5 m",
        [event_played(SUV, "reverse", 6), only()],
        [manoeuvre(SUV, "reverse", 3.0, distance=5)],
    ),
    case(
        "moving",
        "erroneous",
        "bench_forwrd",
        FOREMAN,
        "move the bench 3m forwrd",
        [moved(BENCH, 2.7, 3.3, "forward"), only(assets=[BENCH])],
        [move(BENCH, forward=3)],
    ),
    case(
        "moving",
        "erroneous",
        "suv_90_degree",
        DESI,
        "kindly turn the suv by 90 degree itself",
        [moved(SUV, 0.0, 1.0, turn_min=85, turn_max=95), only(assets=[SUV])],
        [move(SUV, turn_deg=90)],
    ),
    case(
        "moving",
        "erroneous",
        "teh_ego_stop",
        CAPS,
        "MAKE TEH EGO STOP!!! STOP!!! AT 4 SECONDS!!!",
        [event_played(EGO, "stop", 6), only()],
        [manoeuvre(EGO, "stop", 4.0)],
    ),
    case(
        "moving",
        "erroneous",
        "reduced_sped_lights",
        CIVIL,
        "The ego vehical is to procede at a reduced sped of three and a half metres per second, with its "
        "head lamps illuminated.",
        [
            does("drive_lane", asset=EGO, speed_min=3.4, speed_max=3.6),
            env(vehicle_lights="on", weather=["clear"], **NOON),
            only(assets=[EGO], env=True),
        ],
        [behave(EGO, "drive_lane", speed=3.5), lighting(vehicle_lights="on")],
    ),
    case(
        "moving",
        "erroneous",
        "rook_suv",
        GAMER,
        "slide the rook — the SUV — 3 squres north, 1 squre = 2 m",
        [near(None, 0.6, asset=SUV, point=(23.0, -36.0)), only(assets=[SUV])],
        [move(SUV, north=6)],
    ),
    case(
        "moving",
        "erroneous",
        "slow_it_doon",
        SCOT,
        "the ego's gaun far too fast, slow it doon tae 3 metres a secnd",
        [does("drive_lane", asset=EGO, speed_min=2.9, speed_max=3.1), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=3.0)],
    ),
    case(
        "moving",
        "erroneous",
        "suv_faceing_sooth",
        SCOT,
        "turn teh suv roond so its faceing sooth",
        [moved(SUV, 0.0, 1.0, turn_min=170), only(assets=[SUV])],
        [move(SUV, turn_deg=180)],
    ),
    case(
        "moving",
        "erroneous",
        "lorry_to_entrence",
        FOREMAN,
        "get the lorry to drive over to the lot b entrence",
        [does("follow_path", asset=TRUCK_ID), only(assets=[TRUCK_ID])],
        [behave(TRUCK_ID, "follow_path", to=LOT_B_ENTRANCE)],
        setup=[LORRY_GIVEN],
    ),
]

ARRANGEMENT_CASES: list[Json] = [
    # direct
    case(
        "arrangement",
        "direct",
        "bollards_round_hydrant",
        FIRE,
        "Put a ring of bollards round the hydrant so nobody can park up against it.",
        [layout("ring", BOLLARD, 4, around=HYDRANT), only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", HYDRANT))],
    ),
    case(
        "arrangement",
        "direct",
        "sensor_posts_north",
        MET,
        "Line up five sensor posts — bollards will do — along the north footway east of the junction, 3 m apart.",
        [
            delta(BOLLARD, 5, 5),
            layout("line", BOLLARD, 5, spacing_min=2.7, spacing_max=3.3),
            on(["sidewalk"], BOLLARD, scope="added"),
            near(WESTBOUND, 5, BOLLARD, scope="added", every=True),
            only(BOLLARD),
        ],
        [arrange(BOLLARD, "line", loc("at", NORTH_EAST_WALK), count=5, spacing=3)],
    ),
    case(
        "arrangement",
        "direct",
        "lamps_south_footway",
        GAFFER,
        "Run a line of six street lamps along the south footway east of the junction, 8 m apart.",
        [
            delta(LAMP, 6, 6),
            layout("line", LAMP, 6, spacing_min=7.5, spacing_max=8.5),
            on(["sidewalk", "ground"], LAMP, scope="added"),
            near(EASTBOUND, 5, LAMP, scope="added", every=True),
            only(LAMP),
        ],
        [arrange(LAMP, "line", loc("at", SOUTH_EAST_WALK), count=6, spacing=8)],
    ),
    case(
        "arrangement",
        "direct",
        "barriers_and_sign",
        FOREMAN,
        "Set out two barriers across the eastbound lane 30 m ahead of the ego, and a roadworks sign on the footway "
        "beside them.",
        [
            delta(BARRIER, 2, 2),
            layout("line", BARRIER, 2),
            in_lane(EASTBOUND, BARRIER, scope="added"),
            relative("in_front_of", EGO, BARRIER, max_distance=36, tolerance_deg=20, every=True),
            delta(WORK_SIGN, 1, 1),
            near(None, 8, WORK_SIGN, scope="added", point=(-30.0, -1.75)),
            only(BARRIER, WORK_SIGN),
        ],
        [
            arrange(BARRIER, "line", loc("in_front_of", EGO, distance=30), count=2),
            add(WORK_SIGN, 1, xy(-30, -5.5)),
        ],
    ),
    case(
        "arrangement",
        "direct",
        "parking_row_lot_a",
        DESI,
        "Kindly park 4 cars side by side in one row in lot A.",
        [
            delta(CAR, 4, 4),
            layout("line", CAR, 4),
            near(LOT_A, 0.5, CAR, scope="added", every=True),
            only(CAR),
        ],
        [arrange(CAR, "parking_row", loc("at", LOT_A), count=4)],
    ),
    case(
        "arrangement",
        "direct",
        "eight_cones_westbound",
        CAPS,
        "CONES ALONG THE EDGE OF THE WESTBOUND LANE!!! EIGHT OF THEM!!! EIGHT!!!",
        [delta(CONE, 8, 8), layout("line", CONE, 8), in_lane(WESTBOUND, CONE, scope="added"), only(CONE)],
        [arrange(CONE, "lane_edge", loc("at", WESTBOUND), count=8)],
    ),
    case(
        "arrangement",
        "direct",
        "bollard_cordon_fountain",
        CIVIL,
        "A cordon of six bollards shall be established around the fountain.",
        [delta(BOLLARD, 6, 6), layout("ring", BOLLARD, 6, around=FOUNTAIN), only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=6)],
    ),
    case(
        "arrangement",
        "direct",
        "cone_grid_lot_b",
        GAMER,
        "Set up a 3 by 3 grid of cones in lot B, squares 2 m across.",
        [
            delta(CONE, 9, 9),
            layout("cluster", CONE, 9, tolerance=3.2, spacing_min=1.8, spacing_max=2.2),
            near(LOT_B, 0.5, CONE, scope="added", every=True),
            only(CONE),
        ],
        [arrange(CONE, "grid", loc("at", LOT_B), count=9, columns=3, spacing=2)],
    ),
    case(
        "arrangement",
        "direct",
        "ring_mid_crossroads",
        SCOT,
        "Pit a ring o' cones roond the middle o' the crossroads, aye, the big junction.",
        [layout("ring", CONE, 4, around=JUNCTION), near(JUNCTION, 0.5, CONE, scope="added", every=True), only(CONE)],
        [arrange(CONE, "ring", loc("at", JUNCTION))],
    ),
    case(
        "arrangement",
        "direct",
        "ten_cones_from_bus_stop",
        SCOT,
        "Line the eastbound lane edge wi' ten cones fae the bus stop, 5 m apart.",
        [
            delta(CONE, 10, 10),
            layout("line", CONE, 10, spacing_min=4.5, spacing_max=5.5),
            in_lane(EASTBOUND, CONE, scope="added"),
            near(BUS_STOP, 50, CONE, scope="added", every=True),
            only(CONE),
        ],
        [arrange(CONE, "lane_edge", loc("at", BUS_STOP), count=10, spacing=5)],
    ),
    impossible(
        "arrangement",
        "direct",
        "barrier_ring_100m",
        FOREMAN,
        "Set out a ring of barriers with a 100 m radius round the fountain.",
        [arrange(BARRIER, "ring", loc("at", FOUNTAIN), radius=100)],
    ),
    # indirect
    case(
        "arrangement",
        "indirect",
        "cordon_the_incident",
        FIRE,
        "That's the incident scene now — cordon it off with cones the whole way round.",
        [layout("ring", CONE, 4, around=RUBBLE_ID), only(CONE)],
        [arrange(CONE, "ring", loc("at", RUBBLE_ID))],
        setup=[DEBRIS_GIVEN],
    ),
    case(
        "arrangement",
        "indirect",
        "transect_lot_a",
        MET,
        "I need a transect across lot A: a straight run of sensor posts every 4 m, seven in all.",
        [
            delta(BOLLARD, 7, 7),
            layout("line", BOLLARD, 7, spacing_min=3.6, spacing_max=4.4),
            near(LOT_A, 0.5, BOLLARD, scope="added", every=True),
            only(BOLLARD),
        ],
        [arrange(BOLLARD, "line", loc("at", LOT_A), count=7, spacing=4)],
    ),
    case(
        "arrangement",
        "indirect",
        "queue_of_extras_at_dusk",
        GAFFER,
        "Background action for the dusk scene: queue five extras in a line at the bus stop, and take the light "
        "down to dusk.",
        [
            delta(PERSON, 5, 5),
            layout("line", PERSON, 5),
            near(BUS_STOP, 8, PERSON, scope="added", every=True),
            env(time_from="18:30", time_to="21:00", weather=["clear"]),
            only(PERSON, env=True),
        ],
        [arrange(PERSON, "line", loc("at", BUS_STOP), count=5), clock("dusk")],
    ),
    case(
        "arrangement",
        "indirect",
        "segregate_the_works",
        FOREMAN,
        "We're segregating the works from traffic: barriers all along the westbound lane edge by the JTEKT entrance, "
        "six of them.",
        [
            delta(BARRIER, 6, 6),
            layout("line", BARRIER, 6),
            in_lane(WESTBOUND, BARRIER, scope="added"),
            near(JTEKT, 25, BARRIER, scope="added", every=True),
            only(BARRIER),
        ],
        [arrange(BARRIER, "lane_edge", loc("at", JTEKT), count=6)],
    ),
    case(
        "arrangement",
        "indirect",
        "seating_for_function",
        DESI,
        "Kindly arrange the seating for the function — four benches in a row only, near the Student Union.",
        [
            delta(BENCH_KIND, 4, 4),
            layout("line", BENCH_KIND, 4),
            near(UNION, 12, BENCH_KIND, scope="added", every=True),
            only(BENCH_KIND),
        ],
        [arrange(BENCH_KIND, "line", loc("at", UNION), count=4)],
    ),
    case(
        "arrangement",
        "indirect",
        "signs_and_edge_cones",
        CAPS,
        "DRIVERS KEEP MISSING THE ROADWORKS!!! FOUR SIGNS IN A ROW ON THE SOUTH SIDEWALK WEST OF THE JUNCTION!!! "
        "AND CONES ALONG THE LANE EDGE THERE TOO!!!",
        [
            delta(WORK_SIGN, 4, 4),
            layout("line", WORK_SIGN, 4),
            on(["sidewalk"], WORK_SIGN, scope="added"),
            near(EASTBOUND, 5, WORK_SIGN, scope="added", every=True),
            layout("line", CONE, 3),
            in_lane(EASTBOUND, CONE, scope="added"),
            only(WORK_SIGN, CONE),
        ],
        [
            arrange(WORK_SIGN, "line", loc("at", SOUTH_WEST_WALK), count=4),
            arrange(CONE, "lane_edge", loc("at", SOUTH_WEST_WALK), count=6),
        ],
    ),
    case(
        "arrangement",
        "indirect",
        "no_access_lot_a",
        CIVIL,
        "Measures shall be taken to prevent vehicular access to car park A by means of a row of bollards across its "
        "entrance.",
        [layout("line", BOLLARD, 3), near(LOT_A_ENTRANCE, 6, BOLLARD, scope="added", every=True), only(BOLLARD)],
        [arrange(BOLLARD, "line", loc("in_front_of", LOT_A_ENTRANCE))],
    ),
    case(
        "arrangement",
        "indirect",
        "rank_of_pawns",
        GAMER,
        "Lay my pawns out like a rank on a chessboard: eight cones in a straight row across lot B, 2 m apart.",
        [
            delta(CONE, 8, 8),
            layout("line", CONE, 8, spacing_min=1.8, spacing_max=2.2),
            near(LOT_B, 0.5, CONE, scope="added", every=True),
            only(CONE),
        ],
        [arrange(CONE, "line", loc("at", LOT_B), count=8, spacing=2)],
    ),
    case(
        "arrangement",
        "indirect",
        "race_round_fountain",
        SCOT,
        "We're haein' a wee race roond the fountain the morn — mark the course oot wi' a ring o' bollards.",
        [layout("ring", BOLLARD, 4, around=FOUNTAIN), only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", FOUNTAIN))],
    ),
    case(
        "arrangement",
        "indirect",
        "nobody_parks_at_hydrant",
        FIRE,
        "Nobody is to park against that hydrant. Cone off the road alongside it.",
        [
            layout("line", CONE, 3),
            in_lane(WESTBOUND, CONE, scope="added"),
            near(HYDRANT, 10, CONE, scope="added", every=True),
            only(CONE),
        ],
        [arrange(CONE, "lane_edge", loc("at", HYDRANT), count=4)],
    ),
    impossible(
        "arrangement",
        "indirect",
        "castle_ring",
        SCOT,
        "Pit a ring o' cones roond the castle for the tourists, aye, the one just outwith the campus.",
        [arrange(CONE, "ring", loc("at", "castle"))],
    ),
    # vague
    case(
        "arrangement",
        "vague",
        "cones_round_it",
        FIRE,
        "cones round it",
        [layout("ring", CONE, 4, around=RUBBLE_ID), only(CONE)],
        [arrange(CONE, "ring", loc("at", RUBBLE_ID))],
        setup=[DEBRIS_PLANNED],
    ),
    case(
        "arrangement",
        "vague",
        "posts_across_quad",
        MET,
        "a few posts in a line across the quad",
        [layout("line", BOLLARD, 3), near(FOUNTAIN, 12, BOLLARD, scope="added", every=True), only(BOLLARD)],
        [arrange(BOLLARD, "line", loc("at", FOUNTAIN))],
    ),
    case(
        "arrangement",
        "vague",
        "lamps_row_fountain",
        GAFFER,
        "few lamps in a row by the fountain",
        [layout("line", LAMP, 3), near(FOUNTAIN, 12, LAMP, scope="added", every=True), only(LAMP)],
        [arrange(LAMP, "line", loc("at", FOUNTAIN), count=3)],
    ),
    case(
        "arrangement",
        "vague",
        "barriers_lot_b_entrance",
        FOREMAN,
        "barriers in a line across the lot B entrance",
        [layout("line", BARRIER, 2), near(LOT_B_ENTRANCE, 8, BARRIER, scope="added", every=True), only(BARRIER)],
        [arrange(BARRIER, "line", loc("in_front_of", LOT_B_ENTRANCE))],
    ),
    case(
        "arrangement",
        "vague",
        "cars_row_lot_b",
        DESI,
        "cars in a row in lot B only",
        [layout("line", CAR, 3), near(LOT_B, 0.5, CAR, scope="added", every=True), only(CAR)],
        [arrange(CAR, "parking_row", loc("at", LOT_B), count=4)],
    ),
    case(
        "arrangement",
        "vague",
        "cones_line_ego",
        CAPS,
        "CONES. LINE. IN FRONT OF THE EGO. NOW!!!",
        [
            layout("line", CONE, 3),
            relative("in_front_of", EGO, CONE, max_distance=25, tolerance_deg=45, every=True),
            only(CONE),
        ],
        [arrange(CONE, "line", loc("in_front_of", EGO))],
    ),
    case(
        "arrangement",
        "vague",
        "benches_row_fountain",
        CIVIL,
        "Seating arrangement: benches, row, fountain.",
        [layout("line", BENCH_KIND, 3), near(FOUNTAIN, 12, BENCH_KIND, scope="added", every=True), only(BENCH_KIND)],
        [arrange(BENCH_KIND, "line", loc("at", FOUNTAIN), count=4)],
    ),
    case(
        "arrangement",
        "vague",
        "cone_grid_lot_a",
        GAMER,
        "cones in a grid, lot A",
        [layout("cluster", CONE, 4, tolerance=12), near(LOT_A, 0.5, CONE, scope="added", every=True), only(CONE)],
        [arrange(CONE, "grid", loc("at", LOT_A))],
    ),
    case(
        "arrangement",
        "vague",
        "bins_row_library",
        SCOT,
        "a wee row o' bins ootside the library",
        [layout("line", BIN_KIND, 3), near(LIBRARY, 10, BIN_KIND, scope="added", every=True), only(BIN_KIND)],
        [arrange(BIN_KIND, "line", loc("at", LIBRARY), count=4)],
    ),
    case(
        "arrangement",
        "vague",
        "ring_round_truck",
        CAPS,
        "RING!!! OF CONES!!! AROUND THE TRUCK!!!",
        [layout("ring", CONE, 4, around=TRUCK_ID), only(CONE)],
        [arrange(CONE, "ring", loc("at", TRUCK_ID))],
        setup=[turn("PUT A TRUCK IN LOT A!!!", add(TRUCK, 1, loc("at", LOT_A)), planned=True)],
    ),
    case(
        "arrangement",
        "vague",
        "cones_both_lot_entrances",
        SCOT,
        "cones across the lot A entrance, an' the same at lot B",
        [
            delta(CONE, 6, 40),
            near(LOT_A_ENTRANCE, 6, CONE, scope="added", min_count=3),
            near(LOT_B_ENTRANCE, 6, CONE, scope="added", min_count=3),
            only(CONE),
        ],
        [
            arrange(CONE, "line", loc("in_front_of", LOT_A_ENTRANCE)),
            arrange(CONE, "line", loc("in_front_of", LOT_B_ENTRANCE)),
        ],
    ),
    # erroneous
    case(
        "arrangement",
        "erroneous",
        "cones_acros_lot_b",
        FIRE,
        "line of cones acros the lot b entrnce, keep the acess shut",
        [layout("line", CONE, 3), near(LOT_B_ENTRANCE, 6, CONE, scope="added", every=True), only(CONE)],
        [arrange(CONE, "line", loc("in_front_of", LOT_B_ENTRANCE))],
    ),
    case(
        "arrangement",
        "erroneous",
        "posts_arround_tree",
        MET,
        "ring of 6 posts arround the tree by the fountian for the anemometers",
        [delta(BOLLARD, 6, 6), layout("ring", BOLLARD, 6, around=TREE_FOUNTAIN), only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", TREE_FOUNTAIN), count=6)],
    ),
    case(
        "arrangement",
        "erroneous",
        "lamps_north_junktion",
        GAFFER,
        "put 4 lamp posts in a row along teh north sidewalk east of the junktion",
        [
            delta(LAMP, 4, 4),
            layout("line", LAMP, 4),
            on(["sidewalk", "ground"], LAMP, scope="added"),
            near(WESTBOUND, 5, LAMP, scope="added", every=True),
            only(LAMP),
        ],
        [arrange(LAMP, "line", loc("at", NORTH_EAST_WALK), count=4)],
    ),
    case(
        "arrangement",
        "erroneous",
        "barrirs_by_libary",
        FOREMAN,
        "set out 5 barrirs along the eastbond lane edge by the libary",
        [
            delta(BARRIER, 5, 5),
            layout("line", BARRIER, 5),
            in_lane(EASTBOUND, BARRIER, scope="added"),
            near(LIBRARY, 25, BARRIER, scope="added", every=True),
            only(BARRIER),
        ],
        [arrange(BARRIER, "lane_edge", loc("at", LIBRARY), count=5)],
    ),
    case(
        "arrangement",
        "erroneous",
        "circle_middle_lot_b",
        CAPS,
        "PUT CONES IN A CIRCLE IN TEH MIDDLE OF LOT B!!! A CIRCLE!!!",
        [layout("ring", CONE, 4), near(LOT_B, 0.5, CONE, scope="added", every=True), only(CONE)],
        [arrange(CONE, "ring", loc("at", LOT_B))],
    ),
    case(
        "arrangement",
        "erroneous",
        "benchs_north_side",
        CIVIL,
        "A row of benchs is to be instaled along the north side walk, west of the junciton.",
        [
            layout("line", BENCH_KIND, 3),
            on(["sidewalk", "ground"], BENCH_KIND, scope="added"),
            near(WESTBOUND, 5, BENCH_KIND, scope="added", every=True),
            only(BENCH_KIND),
        ],
        [arrange(BENCH_KIND, "line", loc("at", NORTH_WEST_WALK), count=4)],
    ),
    case(
        "arrangement",
        "erroneous",
        "pawns_north_crosswlak",
        GAMER,
        "set up a row of 5 pawns — pedestrains — across the north crosswlak",
        [
            delta(PERSON, 5, 5),
            layout("line", PERSON, 5),
            near(NORTH_CROSSWALK, 8, PERSON, scope="added", every=True),
            only(PERSON),
        ],
        [arrange(PERSON, "line", loc("at", NORTH_CROSSWALK), count=5)],
    ),
    case(
        "arrangement",
        "erroneous",
        "queue_on_pavment",
        SCOT,
        "noo a line o folk queuin fer it on the pavment",
        [layout("line", PERSON, 3), near(BUS_STOP, 10, PERSON, scope="added", every=True), only(PERSON)],
        [arrange(PERSON, "line", loc("at", BUS_STOP), count=5)],
        setup=[BUS_IN_PLANNED],
    ),
    case(
        "arrangement",
        "erroneous",
        "barriers_round_rubbel",
        FOREMAN,
        "ring of barriers round the rubbel",
        [layout("ring", BARRIER, 4, around=RUBBLE_ID), only(BARRIER)],
        [arrange(BARRIER, "ring", loc("at", RUBBLE_ID))],
        setup=[DEBRIS_GIVEN],
    ),
    case(
        "arrangement",
        "erroneous",
        "bollards_tree_library",
        DESI,
        "kindly put one ring of bollards around the tree near library itself",
        [layout("ring", BOLLARD, 4, around=TREE_LIBRARY), only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", TREE_LIBRARY))],
    ),
    impossible(
        "arrangement",
        "erroneous",
        "twelve_buses",
        DESI,
        "kindly arrange 12 buses in a row in lot B itself",
        [arrange(BUS, "parking_row", loc("at", LOT_B), count=12)],
    ),
]

APPEARANCE_CASES: list[Json] = [
    # direct
    case(
        "appearance",
        "direct",
        "hydrant_high_vis",
        FIRE,
        "Paint the hydrant yellow — it's the new high-visibility scheme.",
        [looks("yellow", asset=HYDRANT), only(assets=[HYDRANT])],
        [paint([HYDRANT], colour="yellow")],
    ),
    case(
        "appearance",
        "direct",
        "light_drizzle",
        MET,
        "Set a light drizzle, please.",
        [env(weather=["rain"], intensity_max=0.45, **NOON), only(env=True)],
        [weather("rain", 0.2)],
    ),
    case(
        "appearance",
        "direct",
        "kill_street_lights",
        GAFFER,
        "Kill the street lights.",
        [env(street_lights="off", weather=["clear"], **NOON), only(env=True)],
        [lighting(street_lights="off")],
    ),
    case(
        "appearance",
        "direct",
        "bench_orange",
        FOREMAN,
        "Paint the bench orange so the lads stop walking into it.",
        [looks("orange", asset=BENCH), only(assets=[BENCH])],
        [paint([BENCH], colour="orange")],
    ),
    case(
        "appearance",
        "direct",
        "half_six_evening",
        DESI,
        "Kindly make the time 6:30 in the evening.",
        [env(time_from="18:15", time_to="18:45", weather=["clear"]), only(env=True)],
        [clock("18:30")],
    ),
    case(
        "appearance",
        "direct",
        "night_not_day",
        CAPS,
        "MAKE IT NIGHT!!! NIGHT!!! NOT DAY!!!",
        [env(night=True, weather=["clear"]), only(env=True)],
        [clock("night")],
    ),
    case(
        "appearance",
        "direct",
        "suv_silver",
        CIVIL,
        "It is requested that the sport utility vehicle be repainted in silver.",
        [looks("silver", asset=SUV, tolerance=0.12), only(assets=[SUV])],
        [paint([SUV], colour="silver")],
    ),
    case(
        "appearance",
        "direct",
        "knight_red",
        GAMER,
        "Make my knight red so I can pick it out on the board.",
        [looks("red", asset=ROBOT_ID), only(assets=[ROBOT_ID])],
        [paint([ROBOT_ID], colour="red")],
        setup=[KNIGHT_PLANNED],
    ),
    impossible(
        "appearance",
        "direct",
        "hail_shower",
        MET,
        "Give me a hail shower — proper hailstones, two centimetres across.",
        [weather("hail")],
    ),
    # indirect
    case(
        "appearance",
        "indirect",
        "night_exercise",
        FIRE,
        "We're running the night-time incident exercise: get the scene dark and make sure the street lights are on.",
        [env(night=True, weather=["clear"]), only(env=True)],
        [clock("22:00"), lighting(street_lights="on")],
        alternatives=[[env(street_lights="on")], [env(street_lights="auto")]],
    ),
    case(
        "appearance",
        "indirect",
        "fog_bank_at_dawn",
        MET,
        "Now roll a fog bank in on top of that.",
        [env(weather=["fog"], time_from="05:00", time_to="07:00"), only(env=True)],
        [weather("fog", 0.7)],
        setup=[turn("Set the clock to dawn — I'm studying how fog forms at first light.", clock("dawn"), planned=True)],
    ),
    case(
        "appearance",
        "indirect",
        "golden_hour",
        GAFFER,
        "We're shooting golden hour this evening. Give me that low, warm light.",
        [env(time_from="17:30", time_to="20:15", weather=["clear"]), only(env=True)],
        [clock("19:00")],
    ),
    case(
        "appearance",
        "indirect",
        "site_wagon_livery",
        FOREMAN,
        "The SUV's our site wagon now and our livery's yellow, so sort it out to match.",
        [looks("yellow", asset=SUV), only(assets=[SUV])],
        [paint([SUV], colour="yellow")],
    ),
    case(
        "appearance",
        "indirect",
        "prepone_two_hours",
        DESI,
        "Kindly prepone the scene time by two hours only.",
        [env(time_from="09:45", time_to="10:15", weather=["clear"]), only(env=True)],
        [clock("10:00")],
    ),
    case(
        "appearance",
        "indirect",
        "too_dark",
        CAPS,
        "I CAN'T SEE ANYTHING!!! IT'S TOO DARK!!! FIX IT!!! FIX IT!!!",
        [only(env=True)],
        [clock("12:00")],
        setup=[turn("Make it midnight.", clock("00:00"))],
        alternatives=[[env(night=False)], [env(exposure_min=1.2)], [env(street_lights="on")]],
    ),
    case(
        "appearance",
        "indirect",
        "winter_readiness",
        CIVIL,
        "For the purposes of the winter readiness assessment, conditions of heavy snowfall are to be simulated.",
        [env(weather=["snow"], intensity_min=0.7, **NOON), only(env=True)],
        [weather("snow", 0.9)],
    ),
    case(
        "appearance",
        "indirect",
        "two_teams",
        GAMER,
        "I need to tell the two teams apart: paint the two cars in lot B blue and the SUV white.",
        [looks("blue", asset=CAR_1), looks("blue", asset=CAR_2), looks("white", asset=SUV), only(assets=PARKED)],
        [paint([CAR_1, CAR_2], colour="blue"), paint([SUV], colour="white")],
    ),
    impossible(
        "appearance",
        "indirect",
        "exposure_ten",
        GAFFER,
        "Push the exposure right up to 10 — I want the whole frame blown out.",
        [lighting(exposure=10)],
    ),
    # vague
    case(
        "appearance",
        "vague",
        "smoky",
        FIRE,
        "smoky out there, like something's burning upwind",
        [env(weather=["fog"], **NOON), only(env=True)],
        [weather("fog", 0.5)],
    ),
    case(
        "appearance",
        "vague",
        "overcast",
        MET,
        "overcast",
        [env(weather=["cloudy"], **NOON), only(env=True)],
        [weather("cloudy")],
    ),
    case(
        "appearance",
        "vague",
        "lights_down",
        GAFFER,
        "lights down a touch — dim the lot",
        [only(env=True)],
        [lighting(exposure=0.7)],
        alternatives=[[env(exposure_max=0.9)], [env(time_from="17:00", time_to="21:30")]],
    ),
    case(
        "appearance",
        "vague",
        "hi_vis_barriers",
        FOREMAN,
        "hi-vis the barriers",
        [looks(["orange", "yellow"], BARRIER, scope="all", every=True, min_count=3), only(BARRIER)],
        [paint(category=BARRIER, colour="orange")],
        setup=[
            turn(
                "Set out three barriers across the lot B entrance.",
                arrange(BARRIER, "line", loc("in_front_of", LOT_B_ENTRANCE), count=3),
            )
        ],
    ),
    case(
        "appearance",
        "vague",
        "bench_colourful",
        DESI,
        "bench little more colourful only",
        [looks(BRIGHT, asset=BENCH), only(assets=[BENCH])],
        [paint([BENCH], colour="red")],
    ),
    case(
        "appearance",
        "vague",
        "heavy_rain",
        CAPS,
        "RAIN!!! HEAVY!!! NOW!!!",
        [env(weather=["rain"], intensity_min=0.7, **NOON), only(env=True)],
        [weather("rain", 0.9)],
    ),
    case(
        "appearance",
        "vague",
        "dusk",
        CIVIL,
        "Dusk conditions.",
        [env(time_from="18:30", time_to="21:00", weather=["clear"]), only(env=True)],
        [clock("dusk")],
    ),
    case(
        "appearance",
        "vague",
        "black_pieces",
        GAMER,
        "black pieces: the cars",
        [looks("black", CAR, scope="all", every=True, min_count=2), only(CAR, SUV_KIND)],
        [paint(category=CAR, colour="black")],
    ),
    case(
        "appearance",
        "vague",
        "dreich",
        SCOT,
        "make it a dreich day",
        [env(weather=["cloudy", "rain", "fog"], **NOON), only(env=True)],
        [weather("rain", 0.3)],
    ),
    # erroneous
    case(
        "appearance",
        "erroneous",
        "hydrnat_red_agian",
        FIRE,
        "paint the hydrnat red agian, the yelow didnt work",
        [looks("red", asset=HYDRANT), only(assets=[HYDRANT])],
        [paint([HYDRANT], colour="red")],
        setup=[turn("Paint the hydrant yellow.", paint([HYDRANT], colour="yellow"))],
    ),
    case(
        "appearance",
        "erroneous",
        "befor_sunrise",
        MET,
        "set the tiem to 5:45 am, just befor sunrise",
        [env(time_from="05:30", time_to="06:00", weather=["clear"]), only(env=True)],
        [clock("05:45")],
    ),
    case(
        "appearance",
        "erroneous",
        "street_lihgts_on",
        GAFFER,
        "trun on the street lihgts",
        [env(street_lights="on", weather=["clear"], **NOON), only(env=True)],
        [lighting(street_lights="on")],
    ),
    case(
        "appearance",
        "erroneous",
        "rian_light",
        FOREMAN,
        "make it rian, light stuff, the lads can keep working",
        [env(weather=["rain"], intensity_max=0.45, **NOON), only(env=True)],
        [weather("rain", 0.3)],
    ),
    case(
        "appearance",
        "erroneous",
        "bench_and_bin_green",
        DESI,
        "kindly make the bus stop bench in green colour itself, and dustbin also green",
        [looks("green", asset=BENCH), looks("green", asset=BIN), only(assets=[BENCH, BIN])],
        [paint([BENCH], colour="green"), paint([BIN], colour="green")],
    ),
    case(
        "appearance",
        "erroneous",
        "fog_go_away",
        CAPS,
        "MAKE TEH FOG GO AWAY!!! CLEAR SKY!!! CLEAR!!!",
        [env(weather=["clear"], **NOON), only(env=True)],
        [weather("clear")],
        setup=[turn("Thick fog.", weather("fog", 0.9))],
    ),
    case(
        "appearance",
        "erroneous",
        "trees_gold_exept",
        GAMER,
        "paint all teh trees gold exept the one by the libary — they're the treasure squares",
        [looks("gold", TREE, every=True, min_count=3), only(assets=[TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A])],
        [paint([TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A], colour="gold")],
    ),
    case(
        "appearance",
        "erroneous",
        "snaw_back_o_four",
        SCOT,
        "mak it snaw, no too heavey mind, an pit the clock tae the back o four",
        [env(weather=["snow"], intensity_max=0.5, time_from="16:00", time_to="16:45"), only(env=True)],
        [weather("snow", 0.3), clock("16:10")],
    ),
    impossible(
        "appearance",
        "erroneous",
        "libary_beige",
        CIVIL,
        "The Libary facade is to be repainted in beige.",
        [paint(["Library"], colour="beige")],
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
