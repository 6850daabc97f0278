"""The nineteenth practice suite: 276 cases in the words of nine new kinds of user, from the campus world alone.

`python -m drivetwin.evals.practice19_source` writes `suites/practice19.jsonl` (tag `practice19`, ids
`practice19.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`): a wedding photographer planning shots (golden hour, the
couple, the first dance, framing), a 10-year-old child typing short, excited and misspelt requests
("make it rane", "wich car", "are car"), a physics teacher in SI units (velocities, uniform acceleration
at 1 m/s², coordinates, the origin, stopping distance), an autonomous-vehicle safety operator writing
disengagement reports ("takeover #14", "the ODD", "the AV", "the ped", "repro"), a real-estate agent
describing curb appeal (frontage, buyers, greenery), a museum curator (formal and precise, "the
installation", "kindly"), a Scottish English speaker ("wee", "aye", "ootwith", "the now", "forrit",
"fower", "dreich"), a phone user whose autocorrect swaps words ("the beach" for the bench, "cines" for
cones, "the bun" for the bin, "the hydrogen" for the hydrant, "the pedestal" for the pedestrian, "the
ferret wheel"), and a logistics planner who writes numbered lists and tables ("| item | qty | where |",
"1. passenger_car_1: fwd 3 m", "truck: go"). Prompts mix short chat turns with one-to-three sentence
requests, reasons and hedges, references back to earlier turns ("that truck", "those", "remove 1 of
them", "another one just like that", "same again in lot A", "put the SUV near it"), numbers in words
and digits, units (metres, m/s, m/s², seconds), relations (next to, beside, in front of, behind,
ahead of, round), scopes (a lane, a lot, a sidewalk, a landmark), behaviours (speeds, braking to a stop
at a time or before a sign, accelerating, reversing, turning at the crossroads, circling, crossing,
walking somewhere), weather and clock times, questions (which must change nothing), and exceptions
("every bench except the one at the bus stop", "all but the one by the fountain", "suv stay"). The
erroneous grade carries realistic typos, autocorrect and dictation swaps ("for cars" for four cars,
"golden our"), run-together and doubled words ("the the", "infront"), dropped words and non-native
grammar ("Kindly to place hydrant beside of the north crosswalk").

Counts: 7 tasks x 4 grades; search, moving and arrangement hold 11 cases in every grade, addition,
removal, positioning and appearance 9 (276 in all). 31 cases are multi-turn (15 with a planned earlier
turn that has calls), 18 compound (the prompt asks two things, the reference makes two calls or
more), and 22 (8.0 %) impossible, tagged `impossible`, where the right outcome is a refusal that
changes nothing: the distance to a helipad, a swimming pool or a "ferret wheel"; a dragon, a dog, a
thousand cars; removing the Library, the sun, the sidewalks; the bench on the Library's roof, the SUV
in the JTEKT Building's lobby, the hydrant at y = 400 m; 300 m/s, a hydrant that runs in circles,
moving the bus stop, a Library that drives; 500 cones, a ring of 90 m radius, a ring inside
Engineering Hall; 27:00, an invisible SUV, a purple sky.

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

TAG = "practice19"

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
PHOTO = "voice: wedding photographer planning shots (golden hour, the couple, framing)"
KID = "voice: a 10-year-old child typing (short, excited, misspelt)"
PHYS = "voice: physics teacher (vectors, velocities, accelerations, SI units)"
AVOP = "voice: autonomous-vehicle safety operator writing disengagement reports (takeover, ODD, the AV)"
AGENT = "voice: real-estate agent describing curb appeal"
CURATOR = "voice: museum curator (formal, precise, the installation)"
SCOT = "voice: Scottish English speaker (wee, aye, outwith, the now)"
AUTO = "voice: phone user whose autocorrect swaps words (beach for bench, cines for cones)"
LOGI = "voice: logistics planner writing numbered lists and tables"


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
def ask(grade: str, name: str, voice: str, prompt: str, answer: Sequence[str], reference: list[Json], *,
        any_of: Sequence[str] = (), setup: Sequence[Json] = ()) -> Json:
    """A question: the answer names what is asked for and the scene stays as it was."""
    return case("search", grade, name, voice, prompt, [says(all_of=answer, any_of=any_of), only()], reference,
                setup=setup)


TRUCK_AT_LOT_B = turn("Bring a delivery truck in at the lot B entrance.", add(TRUCK, 1, loc("at", LOT_B_ENTRANCE)),
                      planned=True)

SEARCH_CASES: list[Json] = [
    # direct
    ask("direct", "fountain_where", PHOTO,
        "Where exactly is the fountain? I'm scouting it for the couple's portraits.",
        ["75"], [landmarks(query="fountain")]),
    ask("direct", "bench_bin_distance", PHYS,
        "What is the straight-line distance, in metres, between the bench and the trash bin?",
        ["7.6"], [measure(BENCH, BIN)]),
    ask("direct", "vehicles_list", AVOP,
        "List every vehicle in the scene apart from the AV.",
        [CAR_1, SUV, CAR_2], [find(category="vehicles")]),
    ask("direct", "lamp_lot_a", AGENT,
        "Which street light is closest to the parking lot A entrance?",
        [LAMP_LOT_A], [find(category=LAMP, nearest_to=LOT_A_ENTRANCE)]),
    ask("direct", "weather_and_time", CURATOR,
        "Kindly state the present weather and the time of day. Make no alterations.",
        ["clear", "12:00"], [environment()]),
    ask("direct", "lot_b_count", LOGI,
        "Q1. Vehicles currently in parking lot B: which ones?",
        [CAR_1, SUV, CAR_2], [find(category="vehicles", near=LOT_B, within=25)]),
    ask("direct", "ego_lane", SCOT,
        "Which lane's the test car in the now?",
        ["main_eastbound"], [lanes(near=EGO)]),
    ask("direct", "fountain_from_car", KID,
        "how far is the fountain from our car??",
        ["141.3"], [measure(FOUNTAIN, EGO)]),
    ask("direct", "tree_library", AUTO,
        "Which tree is nearest the Library entrance? Just asking, don't change anything.",
        [TREE_LIBRARY], [find(category=TREE, nearest_to=LIBRARY)]),
    impossible("search", "direct", "helipad_distance", PHYS,
               "What is the distance from the test car to the helipad, in metres?",
               [measure("helipad", EGO)]),
    ask("direct", "ego_speed", AVOP,
        "What's the AV's current speed per the sim?",
        ["5 m/s"], [properties(asset=EGO)]),
    # indirect
    ask("indirect", "seat_bus_stop", PHOTO,
        "Guests will want to sit during the golden-hour shots by the bus stop. Is there any seating round there?",
        [BENCH], [find(category=BENCH_KIND, near=BUS_STOP, within=15)]),
    ask("indirect", "hydrant_hunt", KID,
        "is there a fire hydrant anywhere?? i want to find it",
        [HYDRANT], [find(category=HYDRANT_KIND)]),
    ask("indirect", "to_stop_sign", PHYS,
        "If the test car keeps its present velocity, how far must it travel before it draws level with the stop sign?",
        ["46.7"], [measure(STOP_SIGN, EGO)]),
    ask("indirect", "first_signal", AVOP,
        "For the disengagement report I need the ID of the first traffic signal the AV meets going east.",
        [LIGHT_SW], [find(category=SIGNAL, nearest_to=EGO)]),
    case("search", "indirect", "library_union_and_bench", AGENT,
         "Buyers always ask how far the Library is from the Student Union. And is there anywhere to sit near "
         "the bus stop?",
         [says(all_of=["90.9", BENCH]), only()],
         [measure(LIBRARY, UNION), find(category=BENCH_KIND, near=BUS_STOP, within=15)]),
    ask("indirect", "within_ten_bus_stop", CURATOR,
        "Before the installation is sited, I should like to know which objects stand within ten metres of the bus stop.",
        [BIN, BENCH, TREE_LIBRARY, LAMP_BUS_STOP], [find(near=BUS_STOP, within=10)]),
    ask("indirect", "bin_for_litter", SCOT,
        "Is there a bin near the bus stop, or will folk just be droppin' their litter?",
        [BIN], [find(category=BIN_KIND, near=BUS_STOP, within=15)]),
    ask("indirect", "leg_distance", LOGI,
        "Route check:\n1. depot = lot B entrance\n2. drop = JTEKT entrance\nLeg 1->2 distance?",
        ["20.8"], [measure(LOT_B_ENTRANCE, JTEKT)]),
    ask("indirect", "lamp_for_backdrop", PHOTO,
        "I'd love a lamp post glowing behind the couple at the fountain. Which one's nearest it?",
        ["street_light_11"], [find(category=LAMP, nearest_to=FOUNTAIN)]),
    impossible("search", "indirect", "swimming_pool", AGENT,
               "Clients love a pool. How far is the swimming pool from the Student Union?",
               [measure("swimming pool", UNION)]),
    ask("indirect", "truck_leg", LOGI,
        "Before dispatch: how far is that truck from the JTEKT entrance?",
        ["truck_1"], [measure("truck_1", JTEKT)], setup=[TRUCK_AT_LOT_B]),
    # vague
    ask("vague", "near_fountain", KID,
        "whats near the fountain",
        [TREE_FOUNTAIN], [find(near=FOUNTAIN, within=20)]),
    ask("vague", "around_library", PHOTO,
        "What's around the Library entrance, roughly?",
        [LAMP_BUS_STOP, BIN], [find(near=LIBRARY, within=20)]),
    ask("vague", "where_cars", PHYS,
        "And the cars: where are they, in coordinates?",
        [SUV], [find(category="vehicles")]),
    ask("vague", "in_path", AVOP,
        "Anything on the road with the AV right now?",
        ["ego"], [find(on_lane=True)]),
    ask("vague", "whats_parked", AGENT,
        "So what's parked out there?",
        [SUV, CAR_1], [find(category="vehicles", near=LOT_B, within=25)]),
    ask("vague", "describe_setting", CURATOR,
        "Describe the setting, please.",
        [], [environment()], any_of=["clear", "12:00", "noon", "Library", "fountain", BENCH, "ego"]),
    ask("vague", "nearest_bench", SCOT,
        "Whit's the nearest thing tae the wee bench?",
        [TREE_LIBRARY], [find(nearest_to=BENCH)]),
    case("search", "vague", "signs_and_lights", LOGI,
         "inventory pls:\n1. signs\n2. street lights",
         [says(all_of=[STOP_SIGN, "street_light_12"]), only()],
         [find(category="signs"), find(category=LAMP)]),
    ask("vague", "where_bus_stop", KID,
        "where is the bus stop",
        ["-30"], [landmarks(query="bus stop")]),
    ask("vague", "cones_count", AVOP,
        "How many cones now?",
        ["traffic_cone_4"], [find(category=CONE)],
        setup=[turn("Put 4 cones in the AV's lane about 20 m ahead of it.", add(CONE, 4, ahead_of(EGO, 20)),
                    planned=True)]),
    ask("vague", "nearest_lamp_car", KID,
        "wheres the nearest lamp to our car",
        ["street_light_2"], [find(category=LAMP, nearest_to=EGO)]),
    # erroneous
    ask("erroneous", "beach_bun", AUTO,
        "How far is the beach from the bun at the bus stop?",
        ["7.6"], [measure(BENCH, BIN)]),
    ask("erroneous", "car_union", KID,
        "wich car is closest to the studnet union",
        [CAR_2], [find(category="vehicles", nearest_to=UNION)]),
    ask("erroneous", "hydrant_light", PHYS,
        "Waht is the distnace betwen the hydrant and the nearest trafic light?",
        ["6.5"], [measure(HYDRANT, LIGHT_NE)]),
    ask("erroneous", "av_lane", AVOP,
        "whcih lane is the av in, need it for the takover report",
        ["main_eastbound"], [lanes(near=EGO)]),
    ask("erroneous", "sunny", AGENT,
        "Whats the weather doing, is it sunny for the the open house photos?",
        ["clear"], [environment()]),
    ask("erroneous", "tree_fountain", CURATOR,
        "Kindly identify the the tree closest to to the fountain.",
        [TREE_FOUNTAIN], [find(category=TREE, nearest_to=FOUNTAIN)]),
    ask("erroneous", "gates", SCOT,
        "Hoo far's the main gate fae the east gate?",
        ["200"], [measure(MAIN_GATE, EAST_GATE)]),
    case("search", "erroneous", "bins_benches", LOGI,
         "qty chk: bins + benchs near bustop?",
         [says(all_of=[BIN, BENCH]), only()],
         [find(category=BIN_KIND, near=BUS_STOP, within=15), find(category=BENCH_KIND, near=BUS_STOP, within=15)]),
    ask("erroneous", "library_steps", PHOTO,
        "wheres the libary entrence, want to shoot the couple on the steps",
        ["-41"], [landmarks(query="Library entrance")]),
    impossible("search", "erroneous", "ferret_wheel", AUTO,
               "How far is our car from the ferret wheel?",
               [measure("ferris wheel", EGO)]),
    ask("erroneous", "rain_or_sun", KID,
        "is it raining or sunny rn",
        ["clear"], [environment()],
        setup=[turn("hi!! this is so cool")]),
]


# --- Addition: new assets of the right kind, in the right number and place --------------------
ADDITION_CASES: list[Json] = [
    # direct
    case("addition", "direct", "benches_fountain", PHOTO,
         "Add two benches next to the fountain for the bridal party.",
         [delta(BENCH_KIND, 2, 2), near(FOUNTAIN, 8, BENCH_KIND, scope="added", every=True), only(BENCH_KIND)],
         [add(BENCH_KIND, 2, loc("next_to", FOUNTAIN))]),
    case("addition", "direct", "bus_on_road", KID,
         "add a bus!!! on the road in front of our car",
         [delta(BUS, 1, 1), on(["drivable"], BUS, scope="added"), only(BUS)],
         [add(BUS, 1, ahead_of(EGO, 40))]),
    case("addition", "direct", "pedestrian_15m", PHYS,
         "Place a single pedestrian 15 metres ahead of the test car, on the right-hand sidewalk.",
         [delta(PERSON, 1, 1), on(["sidewalk"], PERSON, scope="added"), near(EGO, 25, PERSON, scope="added"),
          only(PERSON)],
         [add(PERSON, 1, ahead_of(EGO, 15, side="right"))]),
    case("addition", "direct", "suv_westbound", AVOP,
         "Spawn one SUV in the westbound lane, driving at 8 m/s.",
         [delta(SUV_KIND, 1, 1), in_lane(WESTBOUND, SUV_KIND, scope="added"),
          does("drive_lane", SUV_KIND, scope="added", speed_min=7.5, speed_max=8.5), only(SUV_KIND)],
         [add(SUV_KIND, 1, loc("at", WESTBOUND), behaviour=drive(8, WESTBOUND))]),
    case("addition", "direct", "tree_jtekt", AGENT,
         "Put a tree by the JTEKT building entrance to soften the frontage.",
         [delta(TREE, 1, 1), near(JTEKT, 10, TREE, scope="added"), only(TREE)],
         [add(TREE, 1, loc("next_to", JTEKT))]),
    case("addition", "direct", "bin_by_bench", CURATOR,
         "Please install one trash bin beside the bench at the bus stop.",
         [delta(BIN_KIND, 1, 1), near(BENCH, 4, BIN_KIND, scope="added"), only(BIN_KIND)],
         [add(BIN_KIND, 1, loc("next_to", BENCH))]),
    case("addition", "direct", "bollard_gate", SCOT,
         "Pit a wee bollard at the main gate, would ye.",
         [delta(BOLLARD, 1, 1), near(MAIN_GATE, 8, BOLLARD, scope="added"), only(BOLLARD)],
         [add(BOLLARD, 1, loc("at", MAIN_GATE))]),
    case("addition", "direct", "table_cones_barriers", LOGI,
         "Add:\n| item | qty | where |\n| cone | 3 | lot B entrance |\n| barrier | 2 | lot B entrance |",
         [delta(CONE, 3, 3), delta(BARRIER, 2, 2), near(LOT_B_ENTRANCE, 12, CONE, scope="added", every=True),
          near(LOT_B_ENTRANCE, 12, BARRIER, scope="added", every=True), only(CONE, BARRIER)],
         [add(CONE, 3, loc("at", LOT_B_ENTRANCE)), add(BARRIER, 2, loc("at", LOT_B_ENTRANCE))]),
    impossible("addition", "direct", "dragon", KID,
               "add a dragon next to the fountain!!!",
               [add("dragon", 1, loc("next_to", FOUNTAIN))]),
    # indirect
    case("addition", "indirect", "seat_and_bin", PHOTO,
         "Guests will need somewhere to sit and somewhere to drop their confetti wrappers by the fountain.",
         [delta(BENCH_KIND, 1, None), delta(BIN_KIND, 1, None), near(FOUNTAIN, 10, BENCH_KIND, scope="added"),
          near(FOUNTAIN, 10, BIN_KIND, scope="added"), only(BENCH_KIND, BIN_KIND)],
         [add(BENCH_KIND, 1, loc("next_to", FOUNTAIN)), add(BIN_KIND, 1, loc("next_to", FOUNTAIN))]),
    case("addition", "indirect", "someone_crossing", KID,
         "i want a person to run across the road in front of our car",
         [delta(PERSON, 1, 1), does(["jaywalk", "cross_road"], PERSON, scope="added"), only(PERSON)],
         [add(PERSON, 1, behaviour={"kind": "jaywalk"})]),
    case("addition", "indirect", "lead_vehicle", PHYS,
         "To show relative motion, the test car needs a vehicle to follow: same lane, 20 m ahead, moving at 4 m/s.",
         [delta(CARS, 1, 1), in_lane(EASTBOUND, CARS, scope="added"),
          does("drive_lane", CARS, scope="added", speed_min=3.5, speed_max=4.5), only(*CARS)],
         [add(CAR, 1, ahead_of(EGO, 20), behaviour=drive(4, EASTBOUND))]),
    case("addition", "indirect", "cyclist_overtake", AVOP,
         "Next run needs a cyclist sharing the road ahead of the AV so we can test the overtake.",
         [delta(BIKE, 1, 1), near(EGO, 60, BIKE, scope="added"), only(BIKE)],
         [add(BIKE, 1, ahead_of(EGO, 25))]),
    case("addition", "indirect", "greenery_lot_a", AGENT,
         "Lot A looks bare and grey. Buyers like a bit of greenery in a car park.",
         [delta(TREE, 1, None), near(LOT_A, 3, TREE, scope="added"), only(TREE)],
         [add(TREE, 2, loc("at", LOT_A))]),
    case("addition", "indirect", "rest_engineering", CURATOR,
         "Visitors arriving at Engineering Hall will require somewhere to rest before the installation.",
         [delta(BENCH_KIND, 1, None), near(ENGINEERING, 10, BENCH_KIND, scope="added"), only(BENCH_KIND)],
         [add(BENCH_KIND, 1, loc("next_to", ENGINEERING))]),
    case("addition", "indirect", "bus_for_stop", SCOT,
         "The bus stop's nae use wi'oot a bus. Could ye bring one in?",
         [delta(BUS, 1, 1), near(BUS_STOP, 20, BUS, scope="added"), on(["drivable"], BUS, scope="added"), only(BUS)],
         [add(BUS, 1, loc("at", BUS_STOP))]),
    case("addition", "indirect", "delivery_truck", LOGI,
         "Delivery scheduled 09:30 at the JTEKT drop-off. Need the truck on site.",
         [delta(TRUCK, 1, 1), near(JTEKT, 20, TRUCK, scope="added"), only(TRUCK, env=True)],
         [add(TRUCK, 1, loc("at", JTEKT))]),
    impossible("addition", "indirect", "thousand_cars", AGENT,
               "To show just how spacious lot B is, fill it with a thousand cars.",
               [add(CAR, 1000, loc("at", LOT_B))]),
    # vague
    case("addition", "vague", "more_people", KID,
         "more people!!",
         [delta(PERSON, 1, None), only(PERSON)],
         [add(PERSON, 3, loc("at", BUS_STOP))]),
    case("addition", "vague", "props_fountain", PHOTO,
         "Could use a few more props around the fountain.",
         [near(FOUNTAIN, 15, scope="added", min_count=2),
          only(BENCH_KIND, TREE, BIN_KIND, LAMP, BOLLARD, PERSON, CONE, BIKE)],
         [add(BENCH_KIND, 2, loc("next_to", FOUNTAIN))]),
    case("addition", "vague", "moving_object", PHYS,
         "Add a moving object.",
         [delta([*VEHICLES, PERSON], 1, None),
          does(["drive_lane", "follow_path", "circle", "cross_road", "jaywalk"], [*VEHICLES, PERSON], scope="added"),
          only(*VEHICLES, PERSON)],
         [add(CAR, 1, ahead_of(EGO, 30), behaviour=drive(6))]),
    case("addition", "vague", "some_traffic", AVOP,
         "Add some traffic.",
         [delta(MOTOR_TRAFFIC, 1, None), only(*MOTOR_TRAFFIC)],
         [add(CAR, 2, loc("at", WESTBOUND))]),
    case("addition", "vague", "curb_appeal_library", AGENT,
         "It needs more curb appeal out front of the Library.",
         [delta([TREE, BENCH_KIND, LAMP, BIN_KIND, BOLLARD], 1, None),
          near(LIBRARY, 15, [TREE, BENCH_KIND, LAMP, BIN_KIND, BOLLARD], scope="added"),
          only(TREE, BENCH_KIND, LAMP, BIN_KIND, BOLLARD)],
         [add(TREE, 2, loc("in_front_of", LIBRARY))]),
    case("addition", "vague", "mark_crosswalk", CURATOR,
         "Something to mark the north crosswalk, if you would.",
         [near(NORTH_CROSSWALK, 10, [PED_SIGN, CONE, BOLLARD], scope="added"), only(PED_SIGN, CONE, BOLLARD)],
         [add(PED_SIGN, 1, loc("next_to", NORTH_CROSSWALK))]),
    case("addition", "vague", "more_life", SCOT,
         "Gie the place a wee bit mair life, aye?",
         [delta([*VEHICLES, PERSON, TREE, BENCH_KIND], 1, None), only(*VEHICLES, PERSON, TREE, BENCH_KIND)],
         [add(PERSON, 3, loc("at", BUS_STOP))]),
    case("addition", "vague", "few_cones_lot_a", LOGI,
         "cones. lot A. a few.",
         [delta(CONE, 2, 6), near(LOT_A, 3, CONE, scope="added", every=True), only(CONE)],
         [add(CONE, 3, loc("at", LOT_A))]),
    case("addition", "vague", "another_like_it", PHOTO,
         "Another one just like that, please.",
         [delta(CAR, 1, 1), looks("red", CAR, scope="added"), near(LOT_B, 5, CAR, scope="added"), only(CAR)],
         [add(CAR, 1, loc("at", LOT_B), colour="red")],
         setup=[turn("Add a red car in lot B for the getaway shot.", add(CAR, 1, loc("at", LOT_B), colour="red"),
                     planned=True)]),
    # erroneous
    case("addition", "erroneous", "three_cines", AUTO,
         "Add three cines in front of the ego car",
         [delta(CONE, 3, 3), near(EGO, 30, CONE, scope="added", every=True),
          relative("in_front_of", EGO, CONE, max_distance=30), only(CONE)],
         [add(CONE, 3, ahead_of(EGO, 10))]),
    impossible("addition", "erroneous", "dogg", KID,
               "ad a dogg at the bus stop",
               [add("dog", 1, loc("at", BUS_STOP))]),
    case("addition", "erroneous", "car_at_xy", PHYS,
         "Add a car at x = 40 m, y = -1.75m travling east at 6 m/s",
         [delta(CARS, 1, 1), near(None, 3, CARS, scope="added", point=(40, -1.75)),
          does("drive_lane", CARS, scope="added", speed_min=5.5, speed_max=6.5), only(*CARS)],
         [add(CAR, 1, xy(40, -1.75), behaviour=drive(6, EASTBOUND))]),
    case("addition", "erroneous", "pedestrain_bus_stop", AVOP,
         "pls spawn a pedestrain on the south side walk near the bus stop for the takeover scenrio",
         [delta(PERSON, 1, 1), near(BUS_STOP, 10, PERSON, scope="added"), on(["sidewalk"], PERSON, scope="added"),
          only(PERSON)],
         [add(PERSON, 1, loc("on_sidewalk", BUS_STOP))]),
    case("addition", "erroneous", "bench_union", AGENT,
         "Add a a bench infront of the the Student Union",
         [delta(BENCH_KIND, 1, 1), near(UNION, 10, BENCH_KIND, scope="added"), only(BENCH_KIND)],
         [add(BENCH_KIND, 1, loc("in_front_of", UNION))]),
    case("addition", "erroneous", "lamps_library", CURATOR,
         "Kindly to place two lamp post either side the Library entrance.",
         [delta(LAMP, 2, 2), near(LIBRARY, 12, LAMP, scope="added", every=True), only(LAMP)],
         [add(LAMP, 2, loc("next_to", LIBRARY))]),
    case("addition", "erroneous", "twa_motorbikes", SCOT,
         "Pit twa motorbikes in the car park B, cheers",
         [delta(MOTORBIKE, 2, 2), near(LOT_B, 2, MOTORBIKE, scope="added", every=True), only(MOTORBIKE)],
         [add(MOTORBIKE, 2, loc("at", LOT_B))]),
    case("addition", "erroneous", "truk", LOGI,
         "add truk x1 @ lot b entrnce",
         [delta(TRUCK, 1, 1), near(LOT_B_ENTRANCE, 12, TRUCK, scope="added"), only(TRUCK)],
         [add(TRUCK, 1, loc("at", LOT_B_ENTRANCE))]),
    case("addition", "erroneous", "tree_and_bench", KID,
         "add a tree and a bench by the founten",
         [delta(TREE, 1, 1), delta(BENCH_KIND, 1, 1), near(FOUNTAIN, 10, TREE, scope="added"),
          near(FOUNTAIN, 10, BENCH_KIND, scope="added"), only(TREE, BENCH_KIND)],
         [add(TREE, 1, loc("next_to", FOUNTAIN)), add(BENCH_KIND, 1, loc("next_to", FOUNTAIN))]),
]


# --- Removal: the right things gone, the rest kept ----------------------------------------------
REMOVAL_CASES: list[Json] = [
    # direct
    case("removal", "direct", "bin_out_of_shot", PHOTO,
         "Take the trash bin out of the bus-stop shots, please.",
         [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "direct", "stop_sign", KID,
         "delete the stop sign",
         [gone(STOP_SIGN), only(assets=[STOP_SIGN])], [remove(STOP_SIGN)]),
    case("removal", "direct", "suv", PHYS,
         "Remove the SUV from the scene.",
         [gone(SUV), kept(CAR_1, CAR_2), only(assets=[SUV])], [remove(SUV)]),
    case("removal", "direct", "lot_b_cars", AVOP,
         "Remove all parked vehicles from lot B before the next run.",
         [gone(*PARKED), kept(EGO), only(assets=list(PARKED))], [remove(*PARKED)]),
    case("removal", "direct", "fountain_tree", AGENT,
         "Remove the tree right next to the fountain; it hides the view.",
         [gone(TREE_FOUNTAIN), kept(TREE_EAST), only(assets=[TREE_FOUNTAIN])], [remove(TREE_FOUNTAIN)]),
    case("removal", "direct", "lamp_bus_stop", CURATOR,
         "Please remove the street light nearest the bus stop.",
         [gone(LAMP_BUS_STOP), only(assets=[LAMP_BUS_STOP])], [remove(LAMP_BUS_STOP)]),
    case("removal", "direct", "bench", SCOT,
         "Get rid o' the bench at the bus stop.",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "direct", "car_2", LOGI,
         "1. remove passenger_car_2\n2. keep the rest as is",
         [gone(CAR_2), kept(CAR_1, SUV), only(assets=[CAR_2])], [remove(CAR_2)]),
    impossible("removal", "direct", "library_building", CURATOR,
               "Please remove the Library building entirely.",
               [remove("Library")]),
    # indirect
    case("removal", "indirect", "hydrant_eyesore", PHOTO,
         "The hydrant's a real eyesore in the street portraits.",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)],
         alternatives=[[gone(HYDRANT)], [moved(HYDRANT, 2.0)]]),
    case("removal", "indirect", "boring_trees", KID,
         "i dont want any trees they are boring",
         [gone(*TREES), only(assets=list(TREES))], [remove(*TREES)]),
    case("removal", "indirect", "empty_lot_b", PHYS,
         "For the thought experiment, parking lot B must be completely empty of vehicles.",
         [gone(*PARKED), only(assets=list(PARKED))], [remove(*PARKED)]),
    case("removal", "indirect", "bollard_takeover", AVOP,
         "Takeover #7 was caused by that bollard in the AV's lane. Clear it for the rerun.",
         [count(BOLLARD, 0, 0), only(BOLLARD)], [remove(category=BOLLARD)],
         setup=[turn("Add a bollard 20 m ahead of the AV in its lane.", add(BOLLARD, 1, ahead_of(EGO, 20)))]),
    case("removal", "indirect", "cluttered_lot", AGENT,
         "Lot B looks cluttered with those three cars sitting in it.",
         [gone(*PARKED), only(assets=list(PARKED))], [remove(*PARKED)]),
    case("removal", "indirect", "sightline", CURATOR,
         "The stop sign obstructs the sightline from the crossroads to the installation; it is not required.",
         [gone(STOP_SIGN), only(assets=[STOP_SIGN])], [remove(STOP_SIGN)]),
    case("removal", "indirect", "tripping_bin", SCOT,
         "Folk keep trippin' o'er that wee bin at the bus stop.",
         [only(assets=[BIN])], [remove(BIN)],
         alternatives=[[gone(BIN)], [moved(BIN, 1.0)]]),
    case("removal", "indirect", "cones_back_to_depot", LOGI,
         "Job at lot A is finished. Those cones can go back to the depot.",
         [count(CONE, 0, 0), only(CONE)], [remove(category=CONE)],
         setup=[turn("add 6 cones in a line in lot A", arrange(CONE, "line", loc("at", LOT_A), count=6))]),
    impossible("removal", "indirect", "the_sun", AVOP,
               "Glare caused the last takeover, so delete the sun for this run.",
               [remove("sun")]),
    # vague
    case("removal", "vague", "the_cars", KID,
         "get rid of the cars",
         [gone(*PARKED), kept(EGO), only(assets=list(PARKED))], [remove(*PARKED)]),
    case("removal", "vague", "clutter_bus_stop", PHOTO,
         "Clear out the clutter at the bus stop.",
         [gone(BIN), only(assets=[BIN, BENCH, LAMP_BUS_STOP, TREE_LIBRARY])], [remove(BIN)]),
    case("removal", "vague", "obstacles", PHYS,
         "Remove the obstacles, please; then the car can accelerate uniformly.",
         [count(CONE, 0, 0), count(RUBBLE, 0, 0), only(CONE, RUBBLE)],
         [remove(category=CONE), remove(category=RUBBLE)],
         setup=[turn("Put three cones 20 m ahead of the car and some rubble 35 m ahead.",
                     add(CONE, 3, ahead_of(EGO, 20)), add(RUBBLE, 1, ahead_of(EGO, 35)))]),
    case("removal", "vague", "extra_actors", AVOP,
         "Remove the extra actors.",
         [gone("pedestrian_1", "pedestrian_2", "passenger_car_3"), kept(*PARKED),
          only(PERSON, assets=["passenger_car_3"])],
         [remove("pedestrian_1", "pedestrian_2", "passenger_car_3")],
         setup=[turn("Add two pedestrians at the bus stop and a car 30 m ahead of the AV.",
                     add(PERSON, 2, loc("at", BUS_STOP)), add(CAR, 1, ahead_of(EGO, 30)))]),
    case("removal", "vague", "couple_of_lights", AGENT,
         "Lose a couple of those street lights.",
         [delta(LAMP, -2, -2), only(LAMP)], [remove(category=LAMP, count=2)]),
    case("removal", "vague", "fewer_trees", CURATOR,
         "Fewer trees, please.",
         [delta(TREE, -3, -1), only(TREE)], [remove(TREE_EAST, TREE_LOT_A)]),
    case("removal", "vague", "that_thing", SCOT,
         "Och, get that thing oot the road.",
         [count(RUBBLE, 0, 0), only(RUBBLE)], [remove(category=RUBBLE)],
         setup=[turn("Drop some rubble in the lane 25 m ahead of the test car.", add(RUBBLE, 1, ahead_of(EGO, 25)))]),
    case("removal", "vague", "one_of_them", LOGI,
         "remove 1 of them.",
         [delta(TRUCK, -1, -1), only(TRUCK)], [remove(category=TRUCK, count=1)],
         setup=[turn("add 2 trucks in lot B", add(TRUCK, 2, loc("at", LOT_B)), planned=True)]),
    impossible("removal", "vague", "sidewalks", KID,
               "remove all the sidewalks",
               [remove(category="sidewalk")]),
    # erroneous
    case("removal", "erroneous", "beach", AUTO,
         "Remove the beach at the bus stop",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "erroneous", "hidrant", KID,
         "delet the fire hidrant",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "erroneous", "suv_and_red_car", PHYS,
         "Remove the the suv and and the red car",
         [gone(SUV, CAR_1), kept(CAR_2), only(assets=[SUV, CAR_1])], [remove(SUV), remove(CAR_1)],
         setup=[turn("Paint passenger_car_1 red.", paint([CAR_1], colour="red"))]),
    case("removal", "erroneous", "cones_av_lane", AVOP,
         "remvoe all cones from AV lane pls, ODD violation",
         [count(CONE, 0, 0), only(CONE)], [remove(category=CONE)],
         setup=[turn("add 4 cones 20 m ahead of the AV", add(CONE, 4, ahead_of(EGO, 20)))]),
    case("removal", "erroneous", "lamp_lot_a", AGENT,
         "Take away the lamp post near lot A entrace",
         [gone(LAMP_LOT_A), only(assets=[LAMP_LOT_A])], [remove(LAMP_LOT_A)]),
    case("removal", "erroneous", "benches_except", CURATOR,
         "Please to remove every bench exept the one at the bus stop.",
         [gone("bench_2", "bench_3"), kept(BENCH), only(BENCH_KIND)], [remove("bench_2", "bench_3")],
         setup=[turn("Add two benches next to the fountain.", add(BENCH_KIND, 2, loc("next_to", FOUNTAIN)))]),
    case("removal", "erroneous", "trees_but_fountain", SCOT,
         "Tak the trees oot, aw but the yin by the fountain",
         [gone(TREE_LIBRARY, TREE_EAST, TREE_LOT_A), kept(TREE_FOUNTAIN), only(TREE)],
         [remove(TREE_LIBRARY, TREE_EAST, TREE_LOT_A)]),
    case("removal", "erroneous", "signals", LOGI,
         "rm: traffic_light_1, traffic_light_2 (both signals) - keep stop sgn",
         [gone(LIGHT_SW, LIGHT_NE), kept(STOP_SIGN), only(assets=[LIGHT_SW, LIGHT_NE])],
         [remove(LIGHT_SW, LIGHT_NE)]),
    case("removal", "erroneous", "hydrogen", AUTO,
         "Delete the hydrogen by the crossroads, it blocks the sidewalk",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
]


# --- Positioning: an existing asset put somewhere named --------------------------------------
PED_AT_BUS_STOP = turn("Add a pedestrian at the bus stop.", add(PERSON, 1, loc("at", BUS_STOP)))

POSITIONING_CASES: list[Json] = [
    # direct
    case("positioning", "direct", "bench_fountain", PHOTO,
         "Put the bench right next to the fountain.",
         [near(FOUNTAIN, 5, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", FOUNTAIN))]),
    case("positioning", "direct", "bin_stop_sign", KID,
         "put the bin next to the stop sign",
         [near(STOP_SIGN, 3, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", STOP_SIGN))]),
    case("positioning", "direct", "suv_coordinates", PHYS,
         "Place the SUV at coordinates (40, 1.75).",
         [near(None, 1.5, asset=SUV, point=(40, 1.75)), only(assets=[SUV])], [place(SUV, xy(40, 1.75))]),
    case("positioning", "direct", "car_in_av_lane", AVOP,
         "Position passenger_car_1 in the AV's lane, 30 m ahead of it.",
         [in_lane(EASTBOUND, asset=CAR_1), near(None, 5, asset=CAR_1, point=(-30, -1.75)), only(assets=[CAR_1])],
         [place(CAR_1, ahead_of(EGO, 30))]),
    case("positioning", "direct", "hydrant_jtekt", AGENT,
         "Move the fire hydrant over to the JTEKT entrance.",
         [near(JTEKT, 12, asset=HYDRANT), moved(HYDRANT, 5), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("next_to", JTEKT))]),
    case("positioning", "direct", "bin_library", CURATOR,
         "Kindly relocate the trash bin to the Library entrance.",
         [near(LIBRARY, 5, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", LIBRARY))]),
    case("positioning", "direct", "bench_main_gate", SCOT,
         "Shift the bench ower tae the main gate.",
         [near(MAIN_GATE, 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", MAIN_GATE))]),
    case("positioning", "direct", "suv_lot_a", LOGI,
         "| asset | to |\n| suv_1 | lot A |",
         [near(LOT_A, 1, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", LOT_A))]),
    impossible("positioning", "direct", "bench_roof", CURATOR,
               "Please position the bench on the roof of the Library.",
               [place(BENCH, xy(-41, -30))]),
    # indirect
    case("positioning", "indirect", "sit_at_fountain", PHOTO,
         "The couple want to sit at the fountain for the sunset portraits.",
         [near(FOUNTAIN, 6, BENCH_KIND), only(BENCH_KIND, env=True)], [place(BENCH, loc("next_to", FOUNTAIN))]),
    case("positioning", "indirect", "bin_where_bench", KID,
         "the bin should be right by the bench so people can put there rubish in",
         [near(BENCH, 3, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", BENCH))]),
    case("positioning", "indirect", "suv_obstacle", PHYS,
         "For the braking demonstration the stationary obstacle will be the SUV, sitting in the eastbound lane "
         "40 m ahead of the test car.",
         [in_lane(EASTBOUND, asset=SUV), near(None, 5, asset=SUV, point=(-20, -1.75)), only(assets=[SUV])],
         [place(SUV, ahead_of(EGO, 40))]),
    case("positioning", "indirect", "ped_crosswalk", AVOP,
         "The ped needs to be standing at the west crosswalk for the takeover repro.",
         [near(WEST_CROSSWALK, 4, asset="pedestrian_1"), only(assets=["pedestrian_1"])],
         [place("pedestrian_1", loc("at", WEST_CROSSWALK))], setup=[PED_AT_BUS_STOP]),
    case("positioning", "indirect", "lamp_greets", AGENT,
         "Buyers come in past the lot A entrance first, so the lamp post at the bus stop should greet them there.",
         [near(LOT_A_ENTRANCE, 8, asset=LAMP_BUS_STOP), only(assets=[LAMP_BUS_STOP])],
         [place(LAMP_BUS_STOP, loc("next_to", LOT_A_ENTRANCE))]),
    case("positioning", "indirect", "forecourt", CURATOR,
         "The installation requires a clear forecourt before lot B; the two passenger cars would be better "
         "placed in parking lot A.",
         [near(LOT_A, 1, asset=CAR_1), near(LOT_A, 1, asset=CAR_2), only(assets=[CAR_1, CAR_2])],
         [place(CAR_1, loc("at", LOT_A)), place(CAR_2, loc("at", LOT_A))]),
    case("positioning", "indirect", "bin_wrong_place", SCOT,
         "Thon bin's in the wrang place. It should be by the hydrant.",
         [near(HYDRANT, 3, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", HYDRANT))]),
    case("positioning", "indirect", "truck_loading_bay", LOGI,
         "Truck's loading bay is the JTEKT entrance; position it there.",
         [near(JTEKT, 15, asset="truck_1"), only(TRUCK)], [place("truck_1", loc("at", JTEKT))],
         setup=[TRUCK_AT_LOT_B]),
    impossible("positioning", "indirect", "suv_lobby", AGENT,
               "Stage the SUV inside the JTEKT Building's lobby for the brochure.",
               [place(SUV, xy(37, 28))]),
    # vague
    case("positioning", "vague", "bench_somewhere", KID,
         "put the bench somewhere better",
         [moved(BENCH, 1.0), only(assets=[BENCH])], [place(BENCH, loc("next_to", FOUNTAIN))]),
    case("positioning", "vague", "suv_photogenic", PHOTO,
         "Park the SUV somewhere more photogenic.",
         [moved(SUV, 1.0), only(assets=[SUV])], [place(SUV, loc("at", LOT_A))]),
    case("positioning", "vague", "car_origin", PHYS,
         "Put the car at the origin.",
         [only(assets=list(PARKED))], [place(CAR_1, xy(0, 0))],
         alternatives=[[near(None, 3, asset=CAR_1, point=(0, 0))], [near(None, 3, asset=CAR_2, point=(0, 0))],
                       [near(None, 3, asset=SUV, point=(0, 0))]]),
    case("positioning", "vague", "ped_back", AVOP,
         "Put the ped back on the sidewalk.",
         [on(["sidewalk"], asset="pedestrian_1"), only(assets=["pedestrian_1"])],
         [place("pedestrian_1", loc("on_sidewalk", "pedestrian_1"))],
         setup=[turn("Add a pedestrian standing in the AV's lane 20 m ahead.", add(PERSON, 1, xy(-40, -1.75)))]),
    case("positioning", "vague", "bin_round_back", AGENT,
         "The bin's spoiling the bus stop view. Stick it round the back somewhere.",
         [moved(BIN, 2.0), only(assets=[BIN])], [place(BIN, loc("behind", BUS_STOP))]),
    case("positioning", "vague", "bench_nearer_library", CURATOR,
         "The bench would sit better nearer the Library entrance.",
         [near(LIBRARY, 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", LIBRARY))]),
    case("positioning", "vague", "car_off_crossing", SCOT,
         "Thon car's sat right on the crossin'. Shift it somewhere.",
         [moved("passenger_car_3", 4.0), only(assets=["passenger_car_3"])],
         [place("passenger_car_3", loc("at", LOT_A))],
         setup=[turn("Put a car on the west crosswalk.", add(CAR, 1, xy(-11.5, -1.75)))]),
    case("positioning", "vague", "suv_near_it", LOGI,
         "put the SUV near it",
         [near("truck_1", 10, asset=SUV), only(assets=[SUV])], [place(SUV, loc("next_to", "truck_1"))],
         setup=[turn("add a truck in lot A", add(TRUCK, 1, loc("at", LOT_A)), planned=True)]),
    case("positioning", "vague", "stop_sign_bench", KID,
         "put the stop sign by the bench",
         [near(BENCH, 4, asset=STOP_SIGN), only(assets=[STOP_SIGN])], [place(STOP_SIGN, loc("next_to", BENCH))]),
    # erroneous
    case("positioning", "erroneous", "beach_fountain", AUTO,
         "Put the beach next to the fountain",
         [near(FOUNTAIN, 5, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", FOUNTAIN))]),
    case("positioning", "erroneous", "stop_sine", KID,
         "put the stop sine next to the bus stopp",
         [near(BUS_STOP, 5, asset=STOP_SIGN), only(assets=[STOP_SIGN])], [place(STOP_SIGN, loc("next_to", BUS_STOP))]),
    case("positioning", "erroneous", "suv_xy", PHYS,
         "Plase the SUV at x=-20 m, y = -1.75 m (in the the eastbound lane)",
         [near(None, 1.5, asset=SUV, point=(-20, -1.75)), only(assets=[SUV])], [place(SUV, xy(-20, -1.75))]),
    case("positioning", "erroneous", "car_2_cut_in", AVOP,
         "position car 2 in front of AV at 15m for the cut in repro",
         [in_lane(EASTBOUND, asset=CAR_2), near(None, 5, asset=CAR_2, point=(-45, -1.75)), only(assets=[CAR_2])],
         [place(CAR_2, ahead_of(EGO, 15))]),
    case("positioning", "erroneous", "tree_library", AGENT,
         "Put the the tree by the libary entrance, frames the door nice",
         [near(LIBRARY, 6, TREE), only(TREE)], [place(TREE_LIBRARY, loc("next_to", LIBRARY))]),
    case("positioning", "erroneous", "hydrant_north_crosswalk", CURATOR,
         "Kindly to place hydrant beside of the north crosswalk.",
         [near(NORTH_CROSSWALK, 6, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("next_to", NORTH_CROSSWALK))]),
    case("positioning", "erroneous", "bin_outwith", SCOT,
         "Pit the bin ootwith the bus stop, ower by the lamp post at lot A",
         [near(LAMP_LOT_A, 4, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", LAMP_LOT_A))]),
    case("positioning", "erroneous", "cars_lot_a", LOGI,
         "pos: passenger_car_1 -> lotA, passenger_car_2 -> lotA",
         [near(LOT_A, 1, asset=CAR_1), near(LOT_A, 1, asset=CAR_2), only(assets=[CAR_1, CAR_2])],
         [place(CAR_1, loc("at", LOT_A)), place(CAR_2, loc("at", LOT_A))]),
    impossible("positioning", "erroneous", "hydrant_off_map", PHYS,
               "Place the hydrant at x = 20 m, y = 400 m.",
               [place(HYDRANT, xy(20, 400))]),
]


# --- Moving: an asset shifted, turned, or set going ------------------------------------------
MOVING_CASES: list[Json] = [
    # direct
    case("moving", "direct", "bench_forward", PHOTO,
         "Move the bench two metres forward.",
         [moved(BENCH, 1.5, 2.5, "forward"), only(assets=[BENCH])], [move(BENCH, forward=2)]),
    case("moving", "direct", "faster_10", KID,
         "make our car go faster like 10",
         [does("drive_lane", asset=EGO, speed_min=9.5, speed_max=10.5), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=10)]),
    case("moving", "direct", "speed_12", PHYS,
         "Set the test car's speed to 12 m/s.",
         [does("drive_lane", asset=EGO, speed_min=11.5, speed_max=12.5), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=12)]),
    case("moving", "direct", "stop_at_10s", AVOP,
         "Have the AV brake to a full stop at t = 10 s.",
         [event_played(EGO, "stop", 15), only(assets=[EGO])], [manoeuvre(EGO, "stop", at_time=10)]),
    case("moving", "direct", "bench_face_road", AGENT,
         "Turn the bench a quarter turn so it faces the road.",
         [moved(BENCH, 0, 1.0, turn_min=60, turn_max=120), only(assets=[BENCH])], [move(BENCH, turn_deg=-90)]),
    case("moving", "direct", "stop_sign_180", CURATOR,
         "Please rotate the stop sign through 180 degrees.",
         [moved(STOP_SIGN, 0, 1.0, turn_min=170), only(assets=[STOP_SIGN])], [move(STOP_SIGN, turn_deg=180)]),
    case("moving", "direct", "suv_forrit", SCOT,
         "Shift the SUV five metres forrit.",
         [moved(SUV, 4, 6, "forward"), only(assets=[SUV])], [move(SUV, forward=5)]),
    case("moving", "direct", "both_cars_forward", LOGI,
         "1. passenger_car_1: fwd 3 m\n2. passenger_car_2: fwd 3 m",
         [moved(CAR_1, 2.5, 3.5, "forward"), moved(CAR_2, 2.5, 3.5, "forward"), only(assets=[CAR_1, CAR_2])],
         [move(CAR_1, forward=3), move(CAR_2, forward=3)]),
    case("moving", "direct", "suv_circle", PHYS,
         "Make the SUV drive a circle of radius 8 m about the centre of parking lot B.",
         [does("circle", asset=SUV, radius_min=7, radius_max=9), only(assets=[SUV])],
         [behave(SUV, "circle", radius=8, centre=LOT_B)]),
    impossible("moving", "direct", "speed_300", AVOP,
               "Set AV speed to 300 m/s for the high-speed ODD test.",
               [behave(EGO, "drive_lane", speed=300)]),
    case("moving", "direct", "bin_right", AUTO,
         "Move the bin 3 metres to its right.",
         [moved(BIN, 2.5, 3.5, "right"), only(assets=[BIN])], [move(BIN, left=-3)]),
    # indirect
    case("moving", "indirect", "bench_from_bin", PHOTO,
         "The bench is too close to the bin for a clean frame.",
         [only(assets=[BENCH, BIN])], [move(BENCH, forward=-3)],
         alternatives=[[moved(BENCH, 1.0)], [moved(BIN, 1.0)]]),
    case("moving", "indirect", "stop_at_sign", KID,
         "i want our car to stop before the stop sign!!",
         [stops_before(EGO, -13.5, -1.75, 20), only(assets=[EGO])],
         [event(EGO, "stop", {"kind": "reach", "place": "-25, -1.75"}, rate=3)]),
    case("moving", "indirect", "uniform_acceleration", PHYS,
         "Demonstrate uniform acceleration: take the test car from its present 5 m/s up to 10 m/s at 1 m/s², "
         "starting at t = 2 s.",
         [event_played(EGO, "change_speed", 10), only(assets=[EGO])],
         [manoeuvre(EGO, "change_speed", at_time=2, speed=10, rate=1)]),
    case("moving", "indirect", "ped_crosses", AVOP,
         "Repro of takeover #14: the ped at the bus stop walks across Main Street in front of the AV.",
         [does(["cross_road", "jaywalk", "follow_path"], asset="pedestrian_1", crosses_lane=EASTBOUND),
          only(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "cross_road")], setup=[PED_AT_BUS_STOP]),
    case("moving", "indirect", "suv_out_of_line", AGENT,
         "The SUV sticks out of the line of cars; nudge it forward a few metres so the frontage looks tidy.",
         [moved(SUV, 1.5, 10, "forward"), only(assets=[SUV])], [move(SUV, forward=3)]),
    case("moving", "indirect", "suv_circulates", CURATOR,
         "For the duration of the exhibition the parked SUV ought to circulate slowly around parking lot B.",
         [does("circle", asset=SUV, speed_max=5), only(assets=[SUV])],
         [behave(SUV, "circle", radius=8, centre=LOT_B, speed=3)]),
    case("moving", "indirect", "slow_school_run", SCOT,
         "The test motor's gaun far too fast for a school run past the bus stop. Slow it right doon.",
         [does("drive_lane", asset=EGO, speed_max=4.5), only(assets=[EGO])], [behave(EGO, "drive_lane", speed=3)]),
    case("moving", "indirect", "truck_departs", LOGI,
         "Truck departs at T+5 s, cruising at 6 m/s.",
         [only(TRUCK)], [behave("truck_1", "drive_lane", speed=6, start_time=5)],
         alternatives=[[does("drive_lane", TRUCK, speed_min=5.5, speed_max=6.5)],
                       [event_played("truck_1", "change_speed", 10)]],
         setup=[turn("add a truck 30 m ahead of the ego in its lane", add(TRUCK, 1, ahead_of(EGO, 30)),
                     planned=True)]),
    case("moving", "indirect", "where_after_4s", PHYS,
         "At 5 m/s for 4 s the test car covers a certain distance. Put the car where it would be then.",
         [moved(EGO, 18, 22, "forward"), only(assets=[EGO])], [move(EGO, forward=20)]),
    impossible("moving", "indirect", "hydrant_runs", KID,
               "make the fire hydrant run around in circles!!",
               [behave(HYDRANT, "circle", radius=3)]),
    case("moving", "indirect", "oncoming_7", AVOP,
         "Oncoming traffic for the ODD test should be doing 7 m/s. Set that.",
         [does("drive_lane", CAR, speed_min=6.5, speed_max=7.5), only(CAR)],
         [behave("passenger_car_3", "drive_lane", speed=7, lane=WESTBOUND)],
         setup=[turn("Add a car in the westbound lane.", add(CAR, 1, loc("at", WESTBOUND)), planned=True)]),
    # vague
    case("moving", "vague", "cars_move", KID,
         "make the cars move",
         [does(["drive_lane", "circle", "follow_path"], CARS), only(*CARS)],
         [behave(SUV, "circle", radius=8, centre=LOT_B)]),
    case("moving", "vague", "nudge_bench", PHOTO,
         "Nudge the bench a touch.",
         [moved(BENCH, 0.3, 3), only(assets=[BENCH])], [move(BENCH, forward=1)]),
    case("moving", "vague", "some_acceleration", PHYS,
         "Give the test car some acceleration.",
         [only(assets=[EGO])], [manoeuvre(EGO, "change_speed", speed=10, rate=2)],
         alternatives=[[event_played(EGO, "change_speed", 10)], [does("drive_lane", asset=EGO, speed_min=5.5)]]),
    case("moving", "vague", "av_stop", AVOP,
         "AV should stop.",
         [only(assets=[EGO])], [manoeuvre(EGO, "stop")],
         alternatives=[[event_played(EGO, "stop", 20)], [does("parked", asset=EGO)]]),
    case("moving", "vague", "bench_round", AGENT,
         "Turn the bench round a bit.",
         [moved(BENCH, 0, 1.0, turn_min=15), only(assets=[BENCH])], [move(BENCH, turn_deg=45)]),
    case("moving", "vague", "suv_back", CURATOR,
         "A little further back, the SUV.",
         [moved(SUV, 0.5, 5, "backward"), only(assets=[SUV])], [move(SUV, forward=-1.5)]),
    case("moving", "vague", "suv_movin", SCOT,
         "Get thon SUV movin', it's been sat there aw day.",
         [does(["drive_lane", "circle", "follow_path"], asset=SUV), only(assets=[SUV])],
         [behave(SUV, "circle", radius=8, centre=LOT_B)]),
    case("moving", "vague", "truck_go", LOGI,
         "truck: go",
         [does(["drive_lane", "follow_path", "circle"], TRUCK), only(TRUCK)],
         [behave("truck_1", "drive_lane", speed=6)],
         setup=[turn("add a truck at the lot B entrance", add(TRUCK, 1, loc("at", LOT_B_ENTRANCE)), planned=True)]),
    case("moving", "vague", "slower", PHYS,
         "Slower.",
         [does("drive_lane", asset=EGO, speed_max=9), only(assets=[EGO])], [behave(EGO, "drive_lane", speed=5)],
         setup=[turn("Set the test car to 10 m/s.", behave(EGO, "drive_lane", speed=10))]),
    impossible("moving", "vague", "bus_stop_east", CURATOR,
               "Kindly move the bus stop three metres east.",
               [move("bus stop", east=3)]),
    case("moving", "vague", "go_backwards", KID,
         "our car should go backwards",
         [only(assets=[EGO])], [manoeuvre(EGO, "reverse", distance=5)],
         alternatives=[[event_played(EGO, "reverse", 10)], [moved(EGO, 1.0, None, "backward")]]),
    # erroneous
    case("moving", "erroneous", "beach_back", AUTO,
         "Move the beach 2 meters backward",
         [moved(BENCH, 1.5, 2.5, "backward"), only(assets=[BENCH])], [move(BENCH, forward=-2)]),
    case("moving", "erroneous", "suv_cirkle", KID,
         "make the suv go in a cirkle",
         [does("circle", asset=SUV), only(assets=[SUV])], [behave(SUV, "circle", radius=8, centre=LOT_B)]),
    case("moving", "erroneous", "velocity_too_8", PHYS,
         "Set the the test car velocity too 8 m/s",
         [does("drive_lane", asset=EGO, speed_min=7.5, speed_max=8.5), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=8)]),
    case("moving", "erroneous", "brake_hard_6s", AVOP,
         "make AV brake hard at t=6s, full stop, repro of takover",
         [event_played(EGO, "stop", 10), only(assets=[EGO])], [manoeuvre(EGO, "stop", at_time=6, rate=6)]),
    case("moving", "erroneous", "suv_forwards", AGENT,
         "Scoot the the SUV forwards 3 metre",
         [moved(SUV, 2.5, 3.5, "forward"), only(assets=[SUV])], [move(SUV, forward=3)]),
    case("moving", "erroneous", "bench_ninety", CURATOR,
         "Please to rotate the bench ninety degree towards the street.",
         [moved(BENCH, 0, 1.0, turn_min=60, turn_max=120), only(assets=[BENCH])], [move(BENCH, turn_deg=-90)]),
    case("moving", "erroneous", "ego_nudge", SCOT,
         "Gie the test car a wee nudge forrit, twa metres like",
         [moved(EGO, 1.5, 2.5, "forward"), only(assets=[EGO])], [move(EGO, forward=2)]),
    case("moving", "erroneous", "cars_fwd_suv_stay", LOGI,
         "car_1 fwd 4m; car_2 fwd 4m; suv stay",
         [moved(CAR_1, 3.5, 4.5, "forward"), moved(CAR_2, 3.5, 4.5, "forward"), only(assets=[CAR_1, CAR_2])],
         [move(CAR_1, forward=4), move(CAR_2, forward=4)]),
    impossible("moving", "erroneous", "library_drive", AUTO,
               "Make the library drive at 5 m/s down Main Street",
               [behave("Library", "drive_lane", speed=5)]),
    case("moving", "erroneous", "turn_left", KID,
         "make are car turn left at the crosroads",
         [event_played(EGO, "junction_turn", 20), only(assets=[EGO])], [manoeuvre(EGO, "junction_turn", turn="left")]),
    case("moving", "erroneous", "pedestal_walk", AUTO,
         "Make the pedestal walk to the library entrance",
         [does("follow_path", PERSON), only(PERSON)], [behave("pedestrian_1", "follow_path", to=LIBRARY)],
         setup=[turn("Add a pedestrian at the bus stop.", add(PERSON, 1, loc("at", BUS_STOP)), planned=True)]),
]


# --- Arrangement: several assets in a line, a ring, a row or a grid ---------------------------
ARRANGEMENT_CASES: list[Json] = [
    # direct
    case("arrangement", "direct", "benches_ring", PHOTO,
         "Arrange four benches in a ring around the fountain.",
         [delta(BENCH_KIND, 4, 4), layout("ring", BENCH_KIND, 4, around=FOUNTAIN), only(BENCH_KIND)],
         [arrange(BENCH_KIND, "ring", loc("at", FOUNTAIN), count=4, radius=5)]),
    case("arrangement", "direct", "line_five", KID,
         "make a line of 5 cones on the road",
         [delta(CONE, 5, 5), layout("line", CONE, 5), on(["drivable"], CONE, scope="added"), only(CONE)],
         [arrange(CONE, "line", ahead_of(EGO, 20), count=5)]),
    case("arrangement", "direct", "spaced_4m", PHYS,
         "Place 5 cones in a straight line along the eastbound lane, 4 m apart, starting 20 m ahead of the test car.",
         [delta(CONE, 5, 5), layout("line", CONE, 5, spacing_min=3.5, spacing_max=4.5),
          in_lane(EASTBOUND, CONE, scope="added"), only(CONE)],
         [arrange(CONE, "line", ahead_of(EGO, 20), count=5, spacing=4)]),
    case("arrangement", "direct", "lane_edge_8", AVOP,
         "Line the edge of the AV's lane with 8 cones ahead of it.",
         [delta(CONE, 8, 8), layout("line", CONE, 8), near(EGO, 80, CONE, scope="added", every=True), only(CONE)],
         [arrange(CONE, "lane_edge", ahead_of(EGO, 15), count=8)]),
    case("arrangement", "direct", "three_cars_row", AGENT,
         "Park three cars side by side in parking lot A.",
         [delta(CARS, 3, 3), layout("line", CARS, 3), near(LOT_A, 1, CARS, scope="added", every=True), only(*CARS)],
         [arrange(CAR, "parking_row", loc("at", LOT_A), count=3)]),
    case("arrangement", "direct", "bollard_ring", CURATOR,
         "Please arrange eight bollards in a ring around the fountain.",
         [delta(BOLLARD, 8, 8), layout("ring", BOLLARD, 8, around=FOUNTAIN), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=8, radius=6)]),
    case("arrangement", "direct", "cone_ring_junction", SCOT,
         "Pit a ring o' six cones roond the middle o' the crossroads.",
         [delta(CONE, 6, 6), layout("ring", CONE, 6, around=JUNCTION), only(CONE)],
         [arrange(CONE, "ring", loc("at", JUNCTION), count=6, radius=4)]),
    case("arrangement", "direct", "barrier_table", LOGI,
         "| item | qty | layout | where |\n| barrier | 4 | line | lot B entrance |",
         [delta(BARRIER, 4, 4), layout("line", BARRIER, 4, tolerance=1.5),
          near(LOT_B_ENTRANCE, 15, BARRIER, scope="added", every=True), only(BARRIER)],
         [arrange(BARRIER, "line", loc("at", LOT_B_ENTRANCE), count=4)]),
    case("arrangement", "direct", "grid_3x3", PHYS,
         "Arrange nine cones in a 3 by 3 grid in parking lot A with 3 m spacing.",
         [delta(CONE, 9, 9), layout("cluster", CONE, 9, tolerance=5.5), near(LOT_A, 1, CONE, scope="added", every=True),
          only(CONE)],
         [arrange(CONE, "grid", loc("at", LOT_A), count=9, columns=3, spacing=3)]),
    impossible("arrangement", "direct", "cones_500", LOGI,
               "line of 500 cones along Main St, eastbound",
               [arrange(CONE, "line", loc("at", EASTBOUND), count=500)]),
    case("arrangement", "direct", "bollards_library", AUTO,
         "Put a line of 4 bollards in front of the Library entrance.",
         [delta(BOLLARD, 4, 4), layout("line", BOLLARD, 4), near(LIBRARY, 12, BOLLARD, scope="added", every=True),
          only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("in_front_of", LIBRARY), count=4)]),
    # indirect
    case("arrangement", "indirect", "guests_circle", PHOTO,
         "For the first-dance shot I want guests standing in a circle around the fountain. Say eight of them.",
         [delta(PERSON, 8, 8), layout("ring", PERSON, 8, around=FOUNTAIN), only(PERSON)],
         [arrange(PERSON, "ring", loc("at", FOUNTAIN), count=8, radius=6)]),
    case("arrangement", "indirect", "slalom", KID,
         "i want to do a slalom with cones on the road in front of our car!!",
         [delta(CONE, 4, None), layout("line", CONE, 4), on(["drivable"], CONE, scope="added"), only(CONE)],
         [arrange(CONE, "line", ahead_of(EGO, 20), count=5, spacing=6)]),
    case("arrangement", "indirect", "stopping_marks", PHYS,
         "To measure stopping distance, mark the eastbound lane with a cone every 5 m from 10 m to 30 m ahead "
         "of the car.",
         [delta(CONE, 5, 5), layout("line", CONE, 5, spacing_min=4.5, spacing_max=5.5),
          in_lane(EASTBOUND, CONE, scope="added"), only(CONE)],
         [arrange(CONE, "line", ahead_of(EGO, 10), count=5, spacing=5)]),
    case("arrangement", "indirect", "close_westbound", AVOP,
         "Work zone for the ODD test: close the westbound lane with a row of barriers near the east gate.",
         [delta(BARRIER, 3, None), layout("line", BARRIER, 3, tolerance=1.5), in_lane(WESTBOUND, BARRIER, scope="added"),
          near(EAST_GATE, 30, BARRIER, scope="added"), only(BARRIER)],
         [arrange(BARRIER, "line", loc("in_lane", EAST_GATE, lane=WESTBOUND), count=4)]),
    case("arrangement", "indirect", "fill_row_lot_b", AGENT,
         "Show buyers how much parking there is: fill a row in lot B with four more cars.",
         [delta(CARS, 4, 4), layout("line", CARS, 4), near(LOT_B, 1, CARS, scope="added", every=True), only(*CARS)],
         [arrange(CAR, "parking_row", loc("at", LOT_B), count=4)]),
    case("arrangement", "indirect", "perimeter", CURATOR,
         "The installation's perimeter should be delineated by bollards encircling the fountain at roughly seven "
         "metres.",
         [delta(BOLLARD, 4, None), layout("ring", BOLLARD, 4, around=FOUNTAIN), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=10, radius=7)]),
    case("arrangement", "indirect", "sponsored_walk", SCOT,
         "The weans are daein' a sponsored walk. Line a few o' them up along the pavement by the bus stop.",
         [delta(PERSON, 3, None), layout("line", PERSON, 3), near(BUS_STOP, 15, PERSON, scope="added", every=True),
          only(PERSON)],
         [arrange(PERSON, "line", loc("at", BUS_STOP), count=5)]),
    case("arrangement", "indirect", "them_in_line", LOGI,
         "now put them in a line, 2 m apart.",
         [count(CONE, 4, 4), layout("line", CONE, 4, scope="all", spacing_min=1.5, spacing_max=2.5), only(CONE)],
         [remove(category=CONE), arrange(CONE, "line", loc("at", LOT_A), count=4, spacing=2)],
         setup=[turn("add 4 cones in lot A", add(CONE, 4, loc("at", LOT_A)), planned=True)]),
    case("arrangement", "indirect", "roundabout_island", PHYS,
         "Model a roundabout's central island: six bollards on a 4 m radius at the main intersection.",
         [delta(BOLLARD, 6, 6), layout("ring", BOLLARD, 6, around=JUNCTION), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", JUNCTION), count=6, radius=4)]),
    impossible("arrangement", "indirect", "ring_90m", CURATOR,
               "The installation requires a ring of barriers of ninety metres' radius about the fountain.",
               [arrange(BARRIER, "ring", loc("at", FOUNTAIN), radius=90, count=12)]),
    case("arrangement", "indirect", "bike_start_line", AUTO,
         "The kids' bike race needs a start line: five bikes side by side in lot A.",
         [delta(BIKE, 5, 5), layout("line", BIKE, 5), near(LOT_A, 1, BIKE, scope="added", every=True), only(BIKE)],
         [arrange(BIKE, "line", loc("at", LOT_A), count=5)]),
    # vague
    case("arrangement", "vague", "cones_circle", KID,
         "cones in a circle!!",
         [delta(CONE, 4, None), layout("ring", CONE, 4), only(CONE)],
         [arrange(CONE, "ring", loc("at", LOT_A), count=6, radius=4)]),
    case("arrangement", "vague", "symmetrical", PHOTO,
         "Something symmetrical around the fountain would look lovely.",
         [layout("ring", [BENCH_KIND, TREE, BOLLARD, LAMP, PERSON, CONE, BIN_KIND], 4, around=FOUNTAIN),
          only(BENCH_KIND, TREE, BOLLARD, LAMP, PERSON, CONE, BIN_KIND)],
         [arrange(BENCH_KIND, "ring", loc("at", FOUNTAIN), count=4, radius=5)]),
    case("arrangement", "vague", "line_them_up", PHYS,
         "Line them up.",
         [count(CONE, 4, 4), layout("line", CONE, 4, scope="all", tolerance=0.5), only(CONE)],
         [remove(category=CONE), arrange(CONE, "line", loc("at", LOT_A), count=4)],
         setup=[turn("Drop a cone at the crossroads, two in lot A and one in lot B.",
                     add(CONE, 1, loc("at", JUNCTION)), add(CONE, 2, loc("at", LOT_A)), add(CONE, 1, loc("at", LOT_B)))]),
    case("arrangement", "vague", "work_zone", AVOP,
         "Set up a work zone.",
         [delta(OBSTACLES, 3, None), on(["drivable"], OBSTACLES, scope="added"), only(*OBSTACLES)],
         [arrange(CONE, "lane_edge", ahead_of(EGO, 20), count=6)]),
    case("arrangement", "vague", "busy_row", AGENT,
         "Make a car park look busy. A proper row of cars.",
         [delta(CARS, 3, None), layout("line", CARS, 3), only(*CARS)],
         [arrange(CAR, "parking_row", loc("at", LOT_A), count=5)],
         alternatives=[[near(LOT_A, 1, CARS, scope="added", every=True)],
                       [near(LOT_B, 1, CARS, scope="added", every=True)]]),
    case("arrangement", "vague", "formal_row", CURATOR,
         "A formal row of benches before the Library, please.",
         [delta(BENCH_KIND, 3, None), layout("line", BENCH_KIND, 3), near(LIBRARY, 15, BENCH_KIND, scope="added"),
          only(BENCH_KIND)],
         [arrange(BENCH_KIND, "line", loc("in_front_of", LIBRARY), count=4)]),
    case("arrangement", "vague", "circle_o_folk", SCOT,
         "Mak a wee circle o' folk.",
         [delta(PERSON, 4, None), layout("ring", PERSON, 4), only(PERSON)],
         [arrange(PERSON, "ring", loc("at", FOUNTAIN), count=6, radius=4)]),
    case("arrangement", "vague", "bollard_grid", LOGI,
         "stage bollards: grid, lot B",
         [delta(BOLLARD, 4, None), layout("cluster", BOLLARD, 4, tolerance=12),
          near(LOT_B, 1, BOLLARD, scope="added", every=True), only(BOLLARD)],
         [arrange(BOLLARD, "grid", loc("at", LOT_B), count=6, columns=3)]),
    case("arrangement", "vague", "same_again", AVOP,
         "Same again in lot A.",
         [delta(CONE, 4, None), layout("ring", CONE, 4, around=LOT_A), only(CONE)],
         [arrange(CONE, "ring", loc("at", LOT_A), count=6, radius=5)],
         setup=[turn("Put a ring of 6 cones around the middle of the main intersection.",
                     arrange(CONE, "ring", loc("at", JUNCTION), count=6, radius=5), planned=True)]),
    case("arrangement", "vague", "big_circle_people", KID,
         "make a big circle of people",
         [delta(PERSON, 4, None), layout("ring", PERSON, 4), only(PERSON)],
         [arrange(PERSON, "ring", loc("at", FOUNTAIN), count=8, radius=8)]),
    case("arrangement", "vague", "radius_four", PHYS,
         "A circle of radius four, please. Cones.",
         [delta(CONE, 4, None), layout("ring", CONE, 4), only(CONE)],
         [arrange(CONE, "ring", loc("at", LOT_B), count=8, radius=4)]),
    # erroneous
    case("arrangement", "erroneous", "cines_ring", AUTO,
         "Put 6 cines in a ring in the middle of lot B",
         [delta(CONE, 6, 6), layout("ring", CONE, 6, around=LOT_B), only(CONE)],
         [arrange(CONE, "ring", loc("at", LOT_B), count=6, radius=5)]),
    case("arrangement", "erroneous", "lin_cones", KID,
         "put cones in a lin in front of are car",
         [delta(CONE, 3, None), layout("line", CONE, 3), near(EGO, 60, CONE, scope="added", every=True), only(CONE)],
         [arrange(CONE, "line", ahead_of(EGO, 15), count=5)]),
    case("arrangement", "erroneous", "strait_barriers", PHYS,
         "Arange 4 barriers in a strait line along the the westbound lane near the east gate",
         [delta(BARRIER, 4, 4), layout("line", BARRIER, 4, tolerance=1.5), in_lane(WESTBOUND, BARRIER, scope="added"),
          only(BARRIER)],
         [arrange(BARRIER, "line", loc("in_lane", EAST_GATE, lane=WESTBOUND), count=4)]),
    case("arrangement", "erroneous", "lane_edge_6", AVOP,
         "pls line up 6 cone along lane edge ahead the AV, takeover repro",
         [delta(CONE, 6, 6), layout("line", CONE, 6), near(EGO, 60, CONE, scope="added", every=True), only(CONE)],
         [arrange(CONE, "lane_edge", ahead_of(EGO, 20), count=6)]),
    case("arrangement", "erroneous", "for_cars", AGENT,
         "Line up for cars in lot A nice and neat",
         [delta(CARS, 4, 4), layout("line", CARS, 4), near(LOT_A, 1, CARS, scope="added", every=True), only(*CARS)],
         [arrange(CAR, "parking_row", loc("at", LOT_A), count=4)]),
    case("arrangement", "erroneous", "five_bollard_circle", CURATOR,
         "Kindly to arrange the five bollard in circle around of the fountain.",
         [delta(BOLLARD, 5, 5), layout("ring", BOLLARD, 5, around=FOUNTAIN), only(BOLLARD)],
         [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=5, radius=5)]),
    case("arrangement", "erroneous", "fower_bollards", SCOT,
         "Pit a line o' fower bollards ootside the Student Union, cheers",
         [delta(BOLLARD, 4, 4), layout("line", BOLLARD, 4), near(UNION, 12, BOLLARD, scope="added", every=True),
          only(BOLLARD)],
         [arrange(BOLLARD, "line", loc("in_front_of", UNION), count=4)]),
    case("arrangement", "erroneous", "grid_2x3", LOGI,
         "grid 2x3 cones lotB spacing 3m",
         [delta(CONE, 6, 6), layout("cluster", CONE, 6, tolerance=5), near(LOT_B, 1, CONE, scope="added", every=True),
          only(CONE)],
         [arrange(CONE, "grid", loc("at", LOT_B), count=6, columns=3, spacing=3)]),
    case("arrangement", "erroneous", "circel_sunset", PHOTO,
         "Can you set up a circel of six people round the fountain for the the group shot, and make it sunset?",
         [delta(PERSON, 6, 6), layout("ring", PERSON, 6, around=FOUNTAIN), env(time_from="18:30", time_to="20:30"),
          only(PERSON, env=True)],
         [arrange(PERSON, "ring", loc("at", FOUNTAIN), count=6, radius=5), clock("19:30")]),
    impossible("arrangement", "erroneous", "ring_in_hall", AUTO,
               "Arrange 4 cones in a ring inside the Engineering Hall",
               [arrange(CONE, "ring", xy(-40, 28), count=4, radius=3)]),
    case("arrangement", "erroneous", "barels_east_gate", KID,
         "now do the same with barriers but by the east gate",
         [delta(BARRIER, 3, None), layout("line", BARRIER, 3, tolerance=1.5), near(EAST_GATE, 30, BARRIER, scope="added"),
          only(BARRIER)],
         [arrange(BARRIER, "line", loc("in_lane", EAST_GATE, lane=WESTBOUND), count=5)],
         setup=[turn("put 5 cones in a line in front of our car", arrange(CONE, "line", ahead_of(EGO, 20), count=5),
                     planned=True)]),
]


# --- Appearance: colours, materials, weather, clock and lights -----------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case("appearance", "direct", "golden_hour", PHOTO,
         "Set the time to 19:30 for golden hour.",
         [env(time_from="19:15", time_to="19:45"), only(env=True)], [clock("19:30")]),
    case("appearance", "direct", "snow", KID,
         "make it snow!!!",
         [env(weather=["snow"]), only(env=True)], [weather("snow")]),
    case("appearance", "direct", "suv_red", PHYS,
         "Paint the SUV red.",
         [looks("red", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="red")]),
    case("appearance", "direct", "rain_night", AVOP,
         "Set weather to heavy rain and the time to 23:00 for the ODD edge case.",
         [env(weather=["rain"], intensity_min=0.6, time_from="22:45", time_to="23:15"), only(env=True)],
         [weather("rain", 0.9), clock("23:00")]),
    case("appearance", "direct", "bench_white", AGENT,
         "Paint the bench white.",
         [looks("white", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="white")]),
    case("appearance", "direct", "bin_black", CURATOR,
         "Please render the trash bin in black.",
         [looks("black", asset=BIN), only(assets=[BIN])], [paint([BIN], colour="black")]),
    case("appearance", "direct", "fog", SCOT,
         "Make it foggy, aye.",
         [env(weather=["fog"]), only(env=True)], [weather("fog")]),
    case("appearance", "direct", "cars_blue", LOGI,
         "| asset | colour |\n| passenger_car_1 | blue |\n| passenger_car_2 | blue |",
         [looks("blue", asset=CAR_1), looks("blue", asset=CAR_2), only(assets=[CAR_1, CAR_2])],
         [paint([CAR_1, CAR_2], colour="blue")]),
    impossible("appearance", "direct", "clock_27", PHYS,
               "Set the clock to 27:00.",
               [clock("27:00")]),
    # indirect
    case("appearance", "indirect", "moody_evening", PHOTO,
         "The couple want a moody evening feel, with the street lamps glowing.",
         [env(night=True), only(env=True)], [clock("21:00"), lighting(street_lights="on")]),
    case("appearance", "indirect", "fire_truck", KID,
         "i want the suv to look like a fire truck",
         [looks("red", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="red")]),
    case("appearance", "indirect", "wet_roads", PHYS,
         "We're discussing reduced friction on wet roads, so the scene should show precipitation.",
         [env(weather=["rain", "snow"]), only(env=True)], [weather("rain")]),
    case("appearance", "indirect", "dusk_takeover", AVOP,
         "The last takeover was at dusk with the sun low; replicate that for the rerun.",
         [env(time_from="18:00", time_to="21:00"), only(env=True)], [clock("20:00")]),
    case("appearance", "indirect", "bench_wood", AGENT,
         "The bench looks tired; buyers like a fresh natural-wood look.",
         [looks(asset=BENCH, material="wood"), only(assets=[BENCH])], [paint([BENCH], material="wood")]),
    case("appearance", "indirect", "stop_sign_metal", CURATOR,
         "The stop sign should be rendered in brushed metal to harmonise with the installation.",
         [looks(asset=STOP_SIGN, material="metal"), only(assets=[STOP_SIGN])], [paint([STOP_SIGN], material="metal")]),
    case("appearance", "indirect", "dreich", SCOT,
         "It's far too bonny out. Make it look like a proper dreich Glasgow day.",
         [env(weather=["rain", "cloudy", "fog"]), only(env=True)], [weather("rain")]),
    case("appearance", "indirect", "hi_vis", LOGI,
         "Hi-vis needed: recolour those to yellow.",
         [looks("yellow", CONE, every=True), only(CONE)], [paint(category=CONE, colour="yellow")],
         setup=[turn("add 3 cones at the lot B entrance", add(CONE, 3, loc("at", LOT_B_ENTRANCE)), planned=True)]),
    impossible("appearance", "indirect", "invisible_suv", AGENT,
               "Paint the SUV invisible so buyers can see the building behind it.",
               [paint([SUV], colour="invisible")]),
    # vague
    case("appearance", "vague", "night_time", KID,
         "make it night time",
         [env(night=True), only(env=True)], [clock("22:00")]),
    case("appearance", "vague", "softer_light", PHOTO,
         "Softer light, please.",
         [only(env=True)], [weather("cloudy")],
         alternatives=[[env(weather=["cloudy", "fog"])], [env(time_from="05:30", time_to="09:30")],
                       [env(time_from="16:30", time_to="20:30")], [env(exposure_max=0.9)]]),
    case("appearance", "vague", "car_colour", PHYS,
         "Change the colour of the car.",
         [looks(ANY_COLOUR, [CAR, SUV_KIND, "ego_vehicle"]), only(CAR, SUV_KIND, "ego_vehicle")],
         [paint([CAR_1], colour="green")]),
    case("appearance", "vague", "bad_weather", AVOP,
         "Bad weather, please.",
         [env(weather=["rain", "fog", "snow", "cloudy"]), only(env=True)], [weather("rain")]),
    case("appearance", "vague", "brighten", AGENT,
         "Brighten things up a bit.",
         [only(BENCH_KIND, BIN_KIND, LAMP, HYDRANT_KIND, STOP_KIND, TREE, env=True)], [lighting(exposure=1.4)],
         alternatives=[[env(exposure_min=1.1)],
                       [looks(BRIGHT, [BENCH_KIND, BIN_KIND, LAMP, HYDRANT_KIND, STOP_KIND, TREE])]]),
    case("appearance", "vague", "autumnal", CURATOR,
         "Something more autumnal for the trees, please.",
         [looks(AUTUMN, TREE), only(TREE)], [paint(category=TREE, colour="orange")]),
    case("appearance", "vague", "bit_o_colour", SCOT,
         "Gie the SUV a bit o' colour.",
         [looks(ANY_COLOUR, asset=SUV), only(assets=[SUV])], [paint([SUV], colour="purple")]),
    case("appearance", "vague", "cones_orange", LOGI,
         "cones -> orange",
         [looks("orange", CONE, every=True), only(CONE)], [paint(category=CONE, colour="orange")],
         setup=[turn("add 3 blue cones in lot A", add(CONE, 3, loc("at", LOT_A), colour="blue"))]),
    impossible("appearance", "vague", "purple_sky", KID,
               "make the sky purple",
               [weather("purple sky")]),
    # erroneous
    case("appearance", "erroneous", "beach_green", AUTO,
         "Paint the beach green",
         [looks("green", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="green")]),
    case("appearance", "erroneous", "rane", KID,
         "make it rane",
         [env(weather=["rain"]), only(env=True)], [weather("rain")]),
    case("appearance", "erroneous", "sunrize", PHYS,
         "Set the time of of day to 06:00 (sunrize)",
         [env(time_from="05:45", time_to="06:45"), only(env=True)], [clock("06:00")]),
    case("appearance", "erroneous", "wether_fog", AVOP,
         "set wether to fog, light intensty",
         [env(weather=["fog"], intensity_max=0.5), only(env=True)], [weather("fog", 0.3)]),
    case("appearance", "erroneous", "bin_grey", AGENT,
         "Paint the the bin grey so it dont stand out",
         [looks("grey", asset=BIN), only(assets=[BIN])], [paint([BIN], colour="grey")]),
    case("appearance", "erroneous", "street_light_on", CURATOR,
         "Kindly to turn on the street light for the evening reception.",
         [only(env=True)], [lighting(street_lights="on")],
         alternatives=[[env(street_lights="on")], [env(night=True)]]),
    case("appearance", "erroneous", "yella_snaw", SCOT,
         "Pent the hydrant yella, an' mak it snaw",
         [looks("yellow", asset=HYDRANT), env(weather=["snow"]), only(assets=[HYDRANT], env=True)],
         [paint([HYDRANT], colour="yellow"), weather("snow")]),
    case("appearance", "erroneous", "trk_wite", LOGI,
         "trk colour -> wite, company livery",
         [looks("white", TRUCK), only(TRUCK)], [paint(["truck_1"], colour="white")],
         setup=[TRUCK_AT_LOT_B]),
    case("appearance", "erroneous", "golden_our", PHOTO,
         "Make it golden our, 7:30 in the evening",
         [env(time_from="19:15", time_to="19:45"), only(env=True)], [clock("19:30")]),
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
