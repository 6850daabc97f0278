"""The twenty-second practice suite: 276 cases in the words of nine new kinds of user, from the campus world alone.

`python -m drivetwin.evals.practice22_source` writes `suites/practice22.jsonl` (tag `practice22`, ids
`practice22.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`): a paramedic or ambulance crew member ("the casualty", "blues and
twos", "scene safety", "stage the van at the lot A entrance", "the RV point", "fend-off position", "the crew",
"shouts", "late calls"), a school crossing patrol officer ("my lollipop", "the little ones", "see them across",
"home time crossing", "8:45 when the children arrive", "the lights have changed, she can go"), a taxi driver
("a fare", "the rank", "my pick-up", "a punter", "cutting it up", "the rat run", "the night shift", "drunk
fares"), a cycling-advocacy volunteer ("a close pass", "dooring risk", "riders filtering up the inside",
"light segregation", "a makeshift protected lane", "sightlines for riders", "cycle parking"), an Irish speaker
("grand", "that yoke", "give it a lash", "so it is", "in a press", "the guards", "would ye ever", "a soft
day", "it's after getting rained on", "fierce dark"), an American Southern speaker ("y'all", "fixin' to",
"might could", "over yonder", "a ways", "reckon", "set a spell", "mosey", "real purty"), a data scientist
writing key=value and JSON-ish fragments ("weather=rain intensity=0.8", "{add: traffic_cone, n: 4, at: main
gate}", "drop trees where dist(fountain) < 20", "expected after step: Δ(suv_1) ≈ 6 m north", "tod=dawn"), a
sports commentator narrating play-by-play ("and here comes the bus!", "the SUV makes a break for it", "shown
the red card", "what a move", "the stewards bring out the barriers", "a guard of honour"), and a person typing
fragments with emoji and abbreviations ("rm bin thx 🗑️", "🔶 cone x5 line @ main gate", "🪑 ⬅️ 3m", "⏪ ego 10m
pls", "🚗1 blocking the 🅿️ exit → scoot fwd 5m", "☀️ or 🌙 rn?"). Prompts mix short chat turns with
one-to-three sentence requests, reasons instead of instructions, hedges, fragments with no verb, pronouns and
references back to earlier turns ("that rider", "the little ones", "bit more traffic round it", "same_as_prev",
"the first one at the stop"), numbers in words and digits, units (metres, m/s, km/h), relations (next to,
behind, in front of, beside, across, round), scopes (a lane, a lot, a side of Main Street, "x > 0", "the
west one"), behaviours (speeds, braking short of the west crosswalk, a held red light, a timed red phase, left
and right turns at the crossroads, lane changes, reversing, circling, crossing, jaywalking, driving to a
place), weather and clock times ("8:45 in the morning", "about eleven at night", "arond 2 in the mornin",
"dusk"), questions (which must change nothing) and exceptions ("but leave the SUV", "all the trees except the
one beside the fountain", "leve the other 2"). The erroneous grade carries realistic typos and dictation slips,
several to a prompt ("hw far frm the bus stp", "libary entrence", "stop sing", "pedestrain crosing", "wether",
"qurey", "categroy=street_ligth", "barirers acros the westbund lane", "of" for off, dialect as it is typed).

Counts: 7 tasks x 4 grades; search, moving and arrangement hold 11 cases in every grade, addition,
removal, positioning and appearance 9 (276 in all). 35 cases are multi-turn (22 with a planned earlier
turn that has calls), 28 compound (the prompt asks two things, the reference makes two calls or more),
and 22 (8.0 %) impossible, tagged `impossible`, where the right outcome is a refusal that changes
nothing: the distance to the nearest A&E department, to the guards' station, the taxi rank; an ambulance,
seventy cars in lot B, a horse and buggy; removing the test car (the ego), Main Street, the Library building;
the bin inside the Library "in a press", a bench on the Engineering Hall roof, the SUV at x = 150 off the map;
scooting the fountain east, the SUV at 250 km/h, a tree doing donuts; a ring of 150 cones, twelve buses in a
row, a bollard ring of 100 m radius, bollards along a bike lane that does not exist; 25:30, a hailstorm,
painting the Library.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with
`alternatives` where a request has two fair readings (the emoji arrow as west or as the bench's own left,
reversing by a shift or a reverse manoeuvre, slowing by speed or by a braking event, a pen around either
child, darker by the clock or by exposure, woodsy as a wood material or a brown paint), and a `reference`
plan that passes; a plan that does nothing fails every case that is not impossible. The suite was written
from the campus world, the asset catalog, the Worker tools and the eval checks only, by someone who had not
read the planners, their lexicons, their prompt examples or any other suite's cases.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

Json = dict[str, Any]

TAG = "practice22"

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
LIGHT_SW, LIGHT_NE = "traffic_light_1", "traffic_light_2"  # (-9.5, -6.2) and (9.5, 6.2)
TREE_LIBRARY, TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A = "tree_1", "tree_2", "tree_3", "tree_4"
# tree_1 (-26, -12) behind the bus stop, towards the Library; tree_2 (70, 45) 7 m from the fountain;
# tree_3 (85, 25) 18 m south-east of the fountain; tree_4 (-85, 50) just north of lot A.
LAMP_LOT_A = "street_light_1"  # (-80, 5.8), the lamp nearest the lot A entrance
LAMP_BUS_STOP = "street_light_4"  # (-38, -5.8), the lamp nearest the bus stop
LAMP_STOP_SIGN = "street_light_6"  # (-13, -5.8), right beside the stop sign, by the west crosswalk
LAMP_BACK_GATE_SOUTH = "street_light_12"  # (92, -5.8), the last lamp on the south side, by the east gate
# Lamps 1, 3, ... 11 stand on Main Street's north side (y = 5.8), 2, 4, ... 12 on its south side.
NORTH_LAMPS = tuple(f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11))  # x -80, -50, -25, 25, 50, 80
NORTH_WEST_LAMPS = ("street_light_1", "street_light_3", "street_light_5")  # north side, west of Campus Drive
SOUTH_LAMPS = tuple(f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12))  # x -68, -38, -13, 37, 62, 92
SOUTH_EAST_LAMPS = ("street_light_8", "street_light_10", "street_light_12")  # south side, east of Campus Drive

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
# Sidewalks: Main Street's south and north sides, west and east of Campus Drive.
SOUTH_WEST_WALK, NORTH_WEST_WALK = "main_south_west", "main_north_west"
SOUTH_EAST_WALK, NORTH_EAST_WALK = "main_south_east", "main_north_east"

CONE, BARRIER, RUBBLE, BOLLARD = "traffic_cone", "road_barrier", "cement_rubble", "bollard"
CAR, SUV_KIND, BUS, TRUCK, ROBOT = "passenger_car", "suv", "bus", "truck", "ackermann_robot"
BIKE, MOTORBIKE, PERSON = "bicycle", "motorcycle", "pedestrian"
TREE, BENCH_KIND, BIN_KIND, LAMP = "tree", "bench", "trash_bin", "street_light"
PED_SIGN, WORK_SIGN, STOP_KIND, SIGNAL = "pedestrian_sign", "construction_sign", "stop_sign", "traffic_light"
HYDRANT_KIND, PARK_SIGN = "fire_hydrant", "parking_sign"
CARS = [CAR, SUV_KIND]
MOTOR_TRAFFIC = [CAR, SUV_KIND, BUS, TRUCK, MOTORBIKE]
SEGREGATION = [BOLLARD, CONE]  # light segregation for a cycle lane: posts or cones

NOON = {"time_from": "11:30", "time_to": "12:30"}  # the world's clock, pinned where a prompt leaves it
CLEAR = {"weather": ["clear"]}
# Colours that stand out against a grey road (the cones' own orange is no change; a tolerance of 0.15 keeps
# orange from passing for gold).
STANDS_OUT = ["red", "yellow", "pink", "cyan", "green", "purple", "gold", "white"]
TAXI_YELLOW = ["yellow", "gold", "orange"]

# Who is speaking: each case names its voice in `notes`.
MEDIC = (
    "voice: paramedic / ambulance crew member (casualty, blues and twos, scene safety, stage at, RV point, the crew)"
)
LOLLIPOP = "voice: school crossing patrol officer (the lollipop, the little ones, crossing times, see them across)"
CABBIE = "voice: taxi driver (fare, rank, pick-up, punter, cutting up, rat run)"
CYCLIST = "voice: cycling-advocacy volunteer (bike lanes, close pass, dooring, filtering, segregation, riders)"
IRISH = "voice: Irish speaker (grand, yoke, give it a lash, so it is, press, the guards, ye, sure)"
SOUTHERN = "voice: American Southern speaker (y'all, fixin' to, might could, over yonder, a ways, reckon)"
DATA = "voice: data scientist writing key=value and JSON-ish fragments (weather=rain intensity=0.8, {cones: 4})"
COMMENTATOR = "voice: sports commentator narrating play-by-play (and the SUV pulls away!, what a move, here comes)"
EMOJI = "voice: person typing fragments with emoji and abbreviations (🚗➡️ lot B pls, cone x3 @ gate, rm bin thx)"


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


# --- Earlier turns and the ids they make ---------------------------------------------------------
TRUCK_ID, PED_ID, PED_2, BUS_ID = "truck_1", "pedestrian_1", "pedestrian_2", "bus_1"
RUBBLE_ID, ROBOT_ID, BIKE_ID, NEW_CAR = "cement_rubble_1", "ackermann_robot_1", "bicycle_1", "passenger_car_3"
WEST_CROSSWALK_LINE = (-13.0, -1.75)  # the near edge of the west crosswalk, in the ego's lane
JUNCTION_CENTRE_LINE = (0.0, -1.75)  # the middle of the crossroads, in the ego's lane
SOUTH_WEST_KERB = (-11.5, -5.6)  # the south end of the west crosswalk, on the pavement

VAN_RV_PLANNED = turn(
    "Stage our van at the lot A entrance, that's the RV point for the crew.",
    add(TRUCK, 1, loc("at", LOT_A_ENTRANCE)),
    planned=True,
)
VAN_RV_GIVEN = turn(
    "Stage the van at the lot A entrance for now, that's the RV point.", add(TRUCK, 1, loc("at", LOT_A_ENTRANCE))
)
RUBBLE_RIDER_PLANNED = turn(
    "Drop a pile of rubble in the eastbound lane about 30 m ahead of the test car.",
    add(RUBBLE, 1, ahead_of(EGO, 30)),
    planned=True,
)
CHILD_PLANNED = turn(
    "A child waiting on the pavement by the west crosswalk, please.",
    add(PERSON, 1, loc("on_sidewalk", WEST_CROSSWALK)),
    planned=True,
)
SUV_UNION_GIVEN = turn("The SUV pulls out and parks up by the Student Union entrance!", place(SUV, loc("at", UNION)))
BUS_IRISH_PLANNED = turn(
    "Put a bus in at the bus stop there, good man.", add(BUS, 1, loc("at", BUS_STOP)), planned=True
)
CASUALTY_WESTBOUND_PLANNED = turn(
    "Casualty's lying in the westbound lane outside Engineering Hall — put a person down there.",
    add(PERSON, 1, loc("in_lane", ENGINEERING, lane=WESTBOUND)),
    planned=True,
)
CAB_WESTBOUND_PLANNED = turn(
    "Put a car driving the westbound lane of Main Street, that's my cab.",
    add(CAR, 1, behaviour=drive(lane=WESTBOUND)),
    planned=True,
)
BARRIERS_LOT_B_PLANNED = turn(
    "add: {category: road_barrier, n: 2, at: 'lot B entrance'}",
    add(BARRIER, 2, loc("at", LOT_B_ENTRANCE)),
    planned=True,
)
BUS_PULLS_IN_GIVEN = turn("And the number 4 bus pulls in at the bus stop!", add(BUS, 1, loc("at", BUS_STOP)))
CONES_CROSSING_PLANNED = turn(
    "Put three cones on the west crosswalk to mark it while the children cross.",
    add(CONE, 3, loc("at", WEST_CROSSWALK)),
    planned=True,
)
DEBRIS_MEDIC_PLANNED = turn(
    "There's debris from the crash in the eastbound lane, 25 m ahead of the ego.",
    add(RUBBLE, 1, ahead_of(EGO, 25)),
    planned=True,
)
CONES_PICK_UP_PLANNED = turn(
    "Put four cones at the lot B entrance to keep my pick-up spot free.",
    add(CONE, 4, loc("at", LOT_B_ENTRANCE)),
    planned=True,
)
WORKS_EASTBOUND_GIVEN = turn(
    "Put two barriers and three cones in the eastbound lane by the bus stop.",
    add(BARRIER, 2, loc("in_lane", BUS_STOP, lane=EASTBOUND)),
    add(CONE, 3, loc("in_lane", BUS_STOP, lane=EASTBOUND)),
)
PEDS_FOUNTAIN_GIVEN = turn("spawn: pedestrian n=2 at fountain", add(PERSON, 2, loc("at", FOUNTAIN)))
RUBBLE_COMMENTATOR_PLANNED = turn(
    "Disaster! There's rubble all over the eastbound lane, 40 metres ahead of the ego!",
    add(RUBBLE, 1, ahead_of(EGO, 40)),
    planned=True,
)
CASUALTY_LANE_PLANNED = turn(
    "Casualty's lying in the eastbound lane 20 metres ahead of the ego — put a person there.",
    add(PERSON, 1, loc("in_lane", EGO, distance=20)),
    planned=True,
)
TRUCK_JTEKT_PLANNED = turn(
    "Y'all add a box truck parked at the JTEKT entrance.", add(TRUCK, 1, loc("at", JTEKT)), planned=True
)
ROBOT_LOT_A_PLANNED = turn(
    "A little robot rolls out into lot A — put one there!", add(ROBOT, 1, loc("at", LOT_A)), planned=True
)
BUS_JUNCTION_GIVEN = turn("Stick a bus in the middle of the crossroads.", add(BUS, 1, loc("at", JUNCTION)))
CHILD_KERB_GIVEN = turn(
    "A child's waiting on the south pavement at the west crosswalk.", add(PERSON, 1, xy(*SOUTH_WEST_KERB))
)
RIDER_AHEAD_PLANNED = turn(
    "Put a cyclist riding the eastbound lane 25 m ahead of the ego.",
    add(BIKE, 1, ahead_of(EGO, 25), behaviour=drive(lane=EASTBOUND)),
    planned=True,
)
TWO_KIDS_KERB_GIVEN = turn(
    "Two children waiting on the south pavement at the west crossing.", add(PERSON, 2, xy(*SOUTH_WEST_KERB))
)
ROBOT_DATA_PLANNED = turn("spawn: ackermann_robot n=1 at lot A", add(ROBOT, 1, loc("at", LOT_A)), planned=True)
BIKE_GATE_PLANNED = turn("Put a bike parked at the main gate.", add(BIKE, 1, loc("at", MAIN_GATE)), planned=True)
PED_BUS_STOP_GIVEN = turn("🚶 x1 @ bus stop", add(PERSON, 1, loc("at", BUS_STOP)))
CASUALTY_EAST_GATE_GIVEN = turn(
    "Casualty lying in the westbound lane by the east gate.",
    add(PERSON, 1, loc("in_lane", EAST_GATE, lane=WESTBOUND)),
)
RUBBLE_EAST_GATE_PLANNED = turn(
    "There's rubble from the crash in the westbound lane near the east gate.",
    add(RUBBLE, 1, loc("in_lane", EAST_GATE, lane=WESTBOUND)),
    planned=True,
)
KIDS_AT_BUS_STOP_GIVEN = turn("Two children waiting at the bus stop.", add(PERSON, 2, loc("at", BUS_STOP)))
KIDS_ON_CROSSING_PLANNED = turn(
    "Put two of the little ones at the west crosswalk, waiting to go over.",
    add(PERSON, 2, loc("at", WEST_CROSSWALK)),
    planned=True,
)
RUBBLE_SOUTHERN_GIVEN = turn(
    "There's a heap of rubble in the eastbound lane 30 metres ahead of the ego.", add(RUBBLE, 1, ahead_of(EGO, 30))
)
VAN_LOT_B_PLANNED = turn("Stage the van in lot B for the crew.", add(TRUCK, 1, loc("at", LOT_B)), planned=True)
BIKE_EASTBOUND_PLANNED = turn(
    "Add a cyclist riding the eastbound lane from the main gate.",
    add(BIKE, 1, loc("at", MAIN_GATE), behaviour=drive(lane=EASTBOUND)),
    planned=True,
)
CONES_MORNING_PLANNED = turn(
    "Put three cones on the west crosswalk for the morning crossing.",
    add(CONE, 3, loc("at", WEST_CROSSWALK)),
    planned=True,
)
RAIN_FIRST_HALF_GIVEN = turn("It's chucking it down for the first half!", weather("rain", 0.9))


# --- Search: questions that change nothing, whose answer names the right thing --------------------
SEARCH_CASES: list[Json] = [
    # direct
    ask(
        "direct",
        "rv_point_distance_and_lamp",
        MEDIC,
        "How far is the lot A entrance from the main gate, and which street light is nearest the entrance? "
        "I'm briefing the crew on the RV point.",
        ["15.4", LAMP_LOT_A],
        [measure(LOT_A_ENTRANCE, MAIN_GATE), find(category=LAMP, nearest_to=LOT_A_ENTRANCE)],
    ),
    ask(
        "direct",
        "signal_by_my_crossing",
        LOLLIPOP,
        "Which traffic light is closest to the west crosswalk? That's where I stand with my lollipop.",
        [LIGHT_SW],
        [find(category=SIGNAL, nearest_to=WEST_CROSSWALK)],
    ),
    ask(
        "direct",
        "cars_sat_in_lot_b",
        CABBIE,
        "How many cars are sat in lot B at the minute? Count the SUV an' all.",
        ["3"],
        [find(category="cars", near=LOT_B, within=1)],
    ),
    ask(
        "direct",
        "ego_lane_and_crossing_gap",
        CYCLIST,
        "Which lane is the ego in, and how far is it from the west crosswalk?",
        [EASTBOUND, "48.5"],
        [lanes(near=EGO), measure(WEST_CROSSWALK, EGO)],
    ),
    ask(
        "direct",
        "main_street_widths",
        CYCLIST,
        "List the lanes on Main Street with their widths; I'm checking whether there's room for a cycle lane.",
        [EASTBOUND, WESTBOUND, "3.5"],
        [lanes(road="Main Street")],
    ),
    ask(
        "direct",
        "bin_nearest_the_seat",
        IRISH,
        "Where's the nearest bin to the bench at the bus stop, like?",
        [BIN],
        [find(category=BIN_KIND, nearest_to=BENCH)],
    ),
    ask(
        "direct",
        "weather_and_clock",
        SOUTHERN,
        "What's the weather doin' out there right now, and what time is it?",
        ["clear", "12:00"],
        [environment()],
    ),
    ask(
        "direct",
        "suv_fields",
        DATA,
        "query: asset=suv_1 fields=[x, y, heading, behaviour]",
        ["23.0", "-42.0", "parked"],
        [properties(asset=SUV)],
    ),
    ask(
        "direct",
        "ego_pace",
        COMMENTATOR,
        "And the ego car's coming down Main Street — what sort of pace is it doing?",
        [],
        [properties(asset=EGO)],
        any_of=["5 m/s", "18 km/h"],
    ),
    ask(
        "direct",
        "hydrant_where",
        EMOJI,
        "🚒 hydrant where? coords pls",
        ["16.0", "5.5"],
        [find(category=HYDRANT_KIND)],
    ),
    impossible(
        "search",
        "direct",
        "distance_to_a_and_e",
        MEDIC,
        "How far is it from the ego to the nearest A&E department?",
        [measure("A&E department", EGO)],
    ),
    # indirect
    ask(
        "indirect",
        "light_for_a_night_casualty",
        MEDIC,
        "We'll be working a casualty at the bus stop after dark — is there a street light close enough to light it?",
        [LAMP_BUS_STOP],
        [find(category=LAMP, nearest_to=BUS_STOP)],
    ),
    ask(
        "indirect",
        "van_eta_to_library",
        MEDIC,
        "How far's our van from the Library entrance? The crew want an idea how long it'll take on foot.",
        ["46.7"],
        [measure(TRUCK_ID, LIBRARY)],
        setup=[VAN_RV_PLANNED],
    ),
    ask(
        "indirect",
        "walk_for_little_legs",
        LOLLIPOP,
        "The little ones walk from the bus stop to the west crosswalk every morning. Is that a long way for them?",
        ["19.3"],
        [measure(BUS_STOP, WEST_CROSSWALK)],
    ),
    ask(
        "indirect",
        "dont_cut_up_the_test_car",
        CABBIE,
        "Which lane's that test car in? I don't want to go cutting it up.",
        [EASTBOUND],
        [lanes(near=EGO)],
    ),
    ask(
        "indirect",
        "punter_at_the_gate",
        CABBIE,
        "I've a punter waiting at the main gate — which of the parked cars is closest to go and get them?",
        [CAR_1],
        [find(category=CAR, nearest_to=MAIN_GATE)],
    ),
    ask(
        "indirect",
        "forced_out_into_traffic",
        CYCLIST,
        "Is there anything sitting in the carriageway now that would force a rider out into the traffic?",
        [RUBBLE_ID],
        [find(on_lane=True)],
        setup=[RUBBLE_RIDER_PLANNED],
    ),
    impossible(
        "search",
        "indirect",
        "guards_station",
        IRISH,
        "Would ye ever tell me how far the guards' station is from the main gate? I might need them.",
        [measure("garda station", MAIN_GATE)],
    ),
    ask(
        "indirect",
        "suv_far_from_doors",
        SOUTHERN,
        "I reckon that SUV's parked a ways from anything. Which building entrance is closest to it?",
        [UNION],
        [landmarks(nearest_to=SUV, query="entrance")],
    ),
    ask(
        "indirect",
        "features_for_night_model",
        DATA,
        "features for the night-visibility model: n_street_lights=?, n_trees=?",
        ["12", "4"],
        [find(category=LAMP), find(category=TREE)],
    ),
    ask(
        "indirect",
        "gap_between_ego_and_suv",
        COMMENTATOR,
        "There's a huge gap between the ego and that SUV in the car park — how much ground is there between them?",
        ["92.2"],
        [measure(SUV, EGO)],
    ),
    ask(
        "indirect",
        "dark_yet_or_nah",
        EMOJI,
        "need 🌙 for my test — is it dark yet or nah",
        ["12:00"],
        [environment()],
    ),
    # vague
    ask(
        "vague",
        "lights_by_the_stop",
        MEDIC,
        "lights near the bus stop?? thinking scene lighting for the crew later",
        [LAMP_BUS_STOP],
        [find(category=LAMP, near=BUS_STOP, within=15)],
    ),
    ask(
        "vague",
        "which_lot_for_rv",
        MEDIC,
        "RV point... lot A or lot B, whichever's nearer the Library",
        [LOT_A],
        [landmarks(nearest_to=LIBRARY, query="lot")],
    ),
    ask(
        "vague",
        "that_little_one",
        LOLLIPOP,
        "that little one — still waiting? where exactly",
        [PED_ID],
        [find(category=PERSON)],
        setup=[CHILD_PLANNED],
    ),
    ask(
        "vague",
        "signs_the_little_ones_see",
        LOLLIPOP,
        "signs near my crossing? the little ones need to be able to see them",
        [STOP_SIGN],
        [find(category="signs", near=WEST_CROSSWALK, within=10)],
    ),
    ask(
        "vague",
        "nearest_the_way_out",
        CABBIE,
        "the three in lot B... which one's nearest the way out onto Main Street",
        [CAR_2],
        [find(category="cars", nearest_to=LOT_B_ENTRANCE)],
    ),
    ask(
        "vague",
        "lamps_for_night_rides",
        CYCLIST,
        "lamps along Main St... how many, roughly? night rides",
        ["12"],
        [find(category=LAMP, lane="Main Street")],
    ),
    ask(
        "vague",
        "seat_yoke_facing",
        IRISH,
        "the seat yoke by the bus stop — which way is it facing, like?",
        [],
        [properties(asset=BENCH)],
        any_of=["180", "west"],
    ),
    ask(
        "vague",
        "green_stuff_yonder",
        SOUTHERN,
        "somethin' green over yonder by the fountain... trees?",
        [TREE_FOUNTAIN],
        [find(category=TREE, near=FOUNTAIN, within=15)],
    ),
    ask("vague", "env_short", DATA, "env?", ["clear", "12:00"], [environment()]),
    ask(
        "vague",
        "where_the_suv_got_to",
        COMMENTATOR,
        "and where's the SUV got to now — how far off the Union doors?",
        ["5.2"],
        [measure(SUV, UNION)],
        setup=[SUV_UNION_GIVEN],
    ),
    ask("vague", "sun_or_moon", EMOJI, "☀️ or 🌙 rn?", ["12:00"], [environment()]),
    # erroneous
    ask(
        "erroneous",
        "bus_stop_to_library",
        MEDIC,
        "hw far frm the bus stp to the libary entrence? need an eta for the crew",
        ["14.5"],
        [measure(BUS_STOP, LIBRARY)],
    ),
    ask(
        "erroneous",
        "crossing_for_the_bus_kids",
        LOLLIPOP,
        "wich crosing is closest to the bus stop for the littel ones getting off",
        [WEST_CROSSWALK],
        [landmarks(nearest_to=BUS_STOP, query="crosswalk")],
    ),
    impossible(
        "search",
        "erroneous",
        "taxi_rank",
        CABBIE,
        "wheres the taxi rnak on this campus, need to pull up for a fare",
        [landmarks(query="taxi rank")],
    ),
    ask(
        "erroneous",
        "speed_limit_for_riders",
        CYCLIST,
        "whats the speed limt on main stret, for the riders?",
        [],
        [lanes(road="Main Street")],
        any_of=["8 m/s", "29 km/h"],
    ),
    ask(
        "erroneous",
        "trees_and_the_nearest",
        IRISH,
        "how many tress is there on the campus at all, and wich one is nearest the libary dore?",
        ["4", TREE_LIBRARY],
        [find(category=TREE), find(category=TREE, nearest_to=LIBRARY)],
    ),
    ask(
        "erroneous",
        "bus_to_library_door",
        IRISH,
        "hw far is that bus from the libary dore now, would ye say?",
        ["17.4"],
        [measure(BUS_ID, LIBRARY)],
        setup=[BUS_IRISH_PLANNED],
    ),
    ask(
        "erroneous",
        "hydrant_to_jtekt",
        SOUTHERN,
        "how fur is that fire hydrnt from the JTEKT door, y'all reckon?",
        ["23.5"],
        [measure(HYDRANT, JTEKT)],
    ),
    ask(
        "erroneous",
        "fixin_to_rain",
        SOUTHERN,
        "is it fixin to rain or waht, whats the wether doin",
        ["clear"],
        [environment()],
    ),
    ask(
        "erroneous",
        "nearest_lamp_query",
        DATA,
        "qurey: nearst_to=ego, categroy=street_ligth",
        ["street_light_2"],
        [find(category=LAMP, nearest_to=EGO)],
    ),
    ask(
        "erroneous",
        "stop_sign_gap_and_pace",
        COMMENTATOR,
        "whats teh distnace between the ego and the stop sing as it aproaches — and how quick is it gong?",
        ["46.7"],
        [measure(STOP_SIGN, EGO), properties(asset=EGO)],
        any_of=["5 m/s", "18 km/h"],
    ),
    ask(
        "erroneous",
        "campus_drive_lanes",
        EMOJI,
        "lanes on campus drv?? 🛣️ nd which way thy go",
        [NORTHBOUND, SOUTHBOUND],
        [lanes(road="Campus Drive")],
    ),
]


# --- Addition --------------------------------------------------------------------------------------
ADDITION_CASES: list[Json] = [
    # direct
    case(
        "addition",
        "direct",
        "van_and_crew_at_rv",
        MEDIC,
        "Add a van parked at the lot A entrance — that's our RV point — and a crew member standing beside it.",
        [
            delta(TRUCK, 1, 1),
            delta(PERSON, 1, 1),
            near(LOT_A_ENTRANCE, 12, TRUCK),
            near(TRUCK_ID, 6, PERSON),
            only(TRUCK, PERSON),
        ],
        [add(TRUCK, 1, loc("at", LOT_A_ENTRANCE)), add(PERSON, 1, loc("next_to", TRUCK_ID))],
    ),
    impossible(
        "addition",
        "direct",
        "ambulance",
        MEDIC,
        "Add an ambulance outside the Student Union entrance with its blues on.",
        [add("ambulance", 1, loc("at", UNION))],
    ),
    case(
        "addition",
        "direct",
        "child_over_the_crossing",
        LOLLIPOP,
        "Add a child walking across the west crosswalk, from the south pavement to the north one.",
        [
            delta(PERSON, 1, 1),
            does("cross_road", PERSON, crosses_lane=EASTBOUND),
            near(WEST_CROSSWALK, 8, PERSON),
            only(PERSON),
        ],
        [add(PERSON, 1, loc("at", WEST_CROSSWALK), behaviour={"kind": "cross_road"})],
    ),
    case(
        "addition",
        "direct",
        "cab_heading_west",
        CABBIE,
        "Put a car driving west on Main Street from the east gate at 10 m/s — that's me off to a pick-up.",
        [
            delta(CAR, 1, 1),
            does("drive_lane", CAR, lane=WESTBOUND, speed_min=9, speed_max=11),
            near(EAST_GATE, 25, CAR),
            only(CAR),
        ],
        [add(CAR, 1, loc("at", EAST_GATE), behaviour=drive(10, WESTBOUND))],
    ),
    case(
        "addition",
        "direct",
        "rider_ahead_of_ego",
        CYCLIST,
        "Add a cyclist riding in the eastbound lane 15 m ahead of the ego, at 4 m/s.",
        [
            delta(BIKE, 1, 1),
            does("drive_lane", BIKE, lane=EASTBOUND, speed_min=3.5, speed_max=4.5),
            relative("in_front_of", EGO, BIKE, max_distance=25),
            only(BIKE),
        ],
        [add(BIKE, 1, ahead_of(EGO, 15), behaviour=drive(4, EASTBOUND))],
    ),
    case(
        "addition",
        "direct",
        "bench_at_library",
        IRISH,
        "Put a bench outside the Library entrance there so people can sit down.",
        [delta(BENCH_KIND, 1, 1), near(LIBRARY, 8, BENCH_KIND), only(BENCH_KIND)],
        [add(BENCH_KIND, 1, loc("at", LIBRARY))],
    ),
    case(
        "addition",
        "direct",
        "pickup_in_lot_b",
        SOUTHERN,
        "Y'all add a pickup truck parked in lot B.",
        [delta(TRUCK, 1, 1), near(LOT_B, 1, TRUCK), does("parked", TRUCK), only(TRUCK)],
        [add(TRUCK, 1, loc("at", LOT_B))],
    ),
    case(
        "addition",
        "direct",
        "cones_kv",
        DATA,
        "{add: traffic_cone, n: 4, at: main gate}",
        [delta(CONE, 4, 4), near(MAIN_GATE, 15, CONE, every=True), only(CONE)],
        [add(CONE, 4, loc("at", MAIN_GATE))],
    ),
    case(
        "addition",
        "direct",
        "bus_pulls_in",
        COMMENTATOR,
        "And here comes the bus, pulling in at the bus stop! Add a bus there.",
        [delta(BUS, 1, 1), near(BUS_STOP, 10, BUS), only(BUS)],
        [add(BUS, 1, loc("at", BUS_STOP))],
    ),
    # indirect
    case(
        "addition",
        "indirect",
        "casualty_at_bus_stop",
        MEDIC,
        "We've a casualty down by the bus stop — I need a person lying there for the crew to work on.",
        [delta(PERSON, 1, 1), near(BUS_STOP, 6, PERSON), only(PERSON)],
        [add(PERSON, 1, loc("at", BUS_STOP))],
    ),
    case(
        "addition",
        "indirect",
        "drivers_miss_my_crossing",
        LOLLIPOP,
        "Drivers keep missing my crossing; they need a warning sign on the pavement beside the west crosswalk.",
        [
            delta(PED_SIGN, 1, 1),
            near(WEST_CROSSWALK, 10, PED_SIGN),
            on(["sidewalk", "ground"], PED_SIGN),
            only(PED_SIGN),
        ],
        [add(PED_SIGN, 1, loc("on_sidewalk", WEST_CROSSWALK))],
    ),
    case(
        "addition",
        "indirect",
        "fare_outside_jtekt",
        CABBIE,
        "Got a fare waiting outside the JTEKT building — can you stick them there so I've someone to pick up?",
        [delta(PERSON, 1, 1), near(JTEKT, 8, PERSON), only(PERSON)],
        [add(PERSON, 1, loc("at", JTEKT))],
    ),
    case(
        "addition",
        "indirect",
        "close_pass_test",
        CYCLIST,
        "I want to test a close pass: a cyclist in the eastbound lane 20 m ahead of the ego, and a car coming up "
        "behind the ego in that same lane.",
        [
            delta(BIKE, 1, 1),
            delta(CAR, 1, 1),
            in_lane(EASTBOUND, BIKE),
            in_lane(EASTBOUND, CAR),
            relative("in_front_of", EGO, BIKE, max_distance=30),
            relative("behind", EGO, CAR, max_distance=30),
            only(BIKE, CAR),
        ],
        [
            add(BIKE, 1, ahead_of(EGO, 20), behaviour=drive(lane=EASTBOUND)),
            add(CAR, 1, ahead_of(EGO, -15), behaviour=drive(lane=EASTBOUND)),
        ],
    ),
    impossible(
        "addition",
        "indirect",
        "packed_lot_b",
        DATA,
        "target_density(lot B) = packed -> add passenger_car n=70",
        [add(CAR, 70, loc("at", LOT_B))],
    ),
    case(
        "addition",
        "indirect",
        "set_a_spell_in_the_shade",
        SOUTHERN,
        "Folks need somewhere to set a spell in the shade of that tree by the fountain.",
        [delta(BENCH_KIND, 1, 1), near(TREE_FOUNTAIN, 6, BENCH_KIND), only(BENCH_KIND)],
        [add(BENCH_KIND, 1, loc("next_to", TREE_FOUNTAIN))],
    ),
    case(
        "addition",
        "indirect",
        "jaywalk_scenario",
        DATA,
        "scenario jw_01 requires actor_type=pedestrian, behaviour=jaywalk, path crosses ego lane",
        [delta(PERSON, 1, 1), does("jaywalk", PERSON, crosses_lane=EASTBOUND), only(PERSON)],
        [add(PERSON, 1, behaviour={"kind": "jaywalk"})],
    ),
    case(
        "addition",
        "indirect",
        "robot_on_the_pitch",
        COMMENTATOR,
        "Oh, and a little robot has scuttled onto the pitch in lot A — what a moment! We need to see that.",
        [delta(ROBOT, 1, 1), near(LOT_A, 1, ROBOT), only(ROBOT)],
        [add(ROBOT, 1, loc("at", LOT_A))],
    ),
    case(
        "addition",
        "indirect",
        "bin_overflowing",
        EMOJI,
        "🗑️ overflowing @ bus stop… need another 1 nxt to it",
        [delta(BIN_KIND, 1, 1), near(BIN, 4, BIN_KIND), only(BIN_KIND)],
        [add(BIN_KIND, 1, loc("next_to", BIN))],
    ),
    # vague
    case(
        "addition",
        "vague",
        "cones_near_casualty",
        MEDIC,
        "scene safety... a few cones by them, nothing mad",
        [delta(CONE, 2, 6), near(PED_ID, 8, CONE, every=True), only(CONE)],
        [add(CONE, 3, loc("next_to", PED_ID))],
        setup=[CASUALTY_WESTBOUND_PLANNED],
    ),
    case(
        "addition",
        "vague",
        "couple_of_little_ones",
        LOLLIPOP,
        "the little ones... couple of them by the bus stop, waiting on me",
        [delta(PERSON, 2, 3), near(BUS_STOP, 8, PERSON, every=True), only(PERSON)],
        [add(PERSON, 2, loc("at", BUS_STOP))],
    ),
    case(
        "addition",
        "vague",
        "feels_dead_out_there",
        CABBIE,
        "bit more traffic round it, feels dead out there",
        [delta(MOTOR_TRAFFIC, 1, 6), does("drive_lane", MOTOR_TRAFFIC, scope="added"), only(*MOTOR_TRAFFIC)],
        [add(CAR, 2, behaviour=drive(lane=WESTBOUND))],
        setup=[CAB_WESTBOUND_PLANNED],
    ),
    case(
        "addition",
        "vague",
        "dooring_risk",
        CYCLIST,
        "dooring risk... a parked car at the kerb where riders go, eastbound side, bus stop-ish",
        [delta(CAR, 1, 1), near(BUS_STOP, 12, CAR), does("parked", CAR), only(CAR)],
        [add(CAR, 1, loc("at", BUS_STOP))],
    ),
    case(
        "addition",
        "vague",
        "rubbish_yoke",
        IRISH,
        "one of them yokes for the rubbish by the Engineering Hall, if ye would",
        [delta(BIN_KIND, 1, 1), near(ENGINEERING, 8, BIN_KIND), only(BIN_KIND)],
        [add(BIN_KIND, 1, loc("at", ENGINEERING))],
    ),
    impossible(
        "addition",
        "vague",
        "horse_and_buggy",
        SOUTHERN,
        "might could use a horse an' buggy over yonder by the fountain",
        [add("horse", 1, loc("at", FOUNTAIN))],
    ),
    case(
        "addition",
        "vague",
        "peds_and_bikes_delta",
        DATA,
        "pedestrians += 3; bikes += 2; loc = fountain",
        [
            delta(PERSON, 3, 3),
            delta(BIKE, 2, 2),
            near(FOUNTAIN, 12, PERSON, every=True),
            near(FOUNTAIN, 12, BIKE, every=True),
            only(PERSON, BIKE),
        ],
        [add(PERSON, 3, loc("at", FOUNTAIN)), add(BIKE, 2, loc("at", FOUNTAIN))],
    ),
    case(
        "addition",
        "vague",
        "crowd_gathering",
        COMMENTATOR,
        "and the crowd's gathering by the JTEKT doors... a few more faces there",
        [delta(PERSON, 2, 6), near(JTEKT, 12, PERSON, every=True), only(PERSON)],
        [add(PERSON, 3, loc("at", JTEKT))],
    ),
    case(
        "addition",
        "vague",
        "moto_zoom",
        EMOJI,
        "🏍️ x1 eastbound, zoom zoom",
        [delta(MOTORBIKE, 1, 1), does("drive_lane", MOTORBIKE, lane=EASTBOUND), only(MOTORBIKE)],
        [add(MOTORBIKE, 1, behaviour=drive(lane=EASTBOUND))],
    ),
    # erroneous
    case(
        "addition",
        "erroneous",
        "van_at_union",
        MEDIC,
        "ad a van at the studnet union entrence, we stage there for the cassualty",
        [delta(TRUCK, 1, 1), near(UNION, 12, TRUCK), only(TRUCK)],
        [add(TRUCK, 1, loc("at", UNION))],
    ),
    case(
        "addition",
        "erroneous",
        "sign_at_north_crossing",
        LOLLIPOP,
        "put a pedestrain crosing sign up by the north crosswlak so the drivers slow down for the kids",
        [delta(PED_SIGN, 1, 1), near(NORTH_CROSSWALK, 10, PED_SIGN), only(PED_SIGN)],
        [add(PED_SIGN, 1, loc("on_sidewalk", NORTH_CROSSWALK))],
    ),
    case(
        "addition",
        "erroneous",
        "cabs_and_a_van",
        CABBIE,
        "stikc 2 cabs in lot b an a van an all, for the lads of the rank",
        [
            delta(CAR, 2, 2),
            delta(TRUCK, 1, 1),
            near(LOT_B, 1, [CAR, TRUCK], scope="added", every=True),
            only(CAR, TRUCK),
        ],
        [add(CAR, 2, loc("at", LOT_B)), add(TRUCK, 1, loc("at", LOT_B))],
    ),
    case(
        "addition",
        "erroneous",
        "bike_by_the_bench",
        CYCLIST,
        "add a bike parkd next to teh bench at the bus stpo",
        [delta(BIKE, 1, 1), near(BENCH, 5, BIKE), only(BIKE)],
        [add(BIKE, 1, loc("next_to", BENCH))],
    ),
    case(
        "addition",
        "erroneous",
        "lamp_by_the_bench",
        IRISH,
        "stick a lamp post up besdie the bench there, its fierce drak at nite",
        [delta(LAMP, 1, 1), near(BENCH, 6, LAMP, scope="added"), only(LAMP)],
        [add(LAMP, 1, loc("next_to", BENCH))],
    ),
    case(
        "addition",
        "erroneous",
        "trees_and_a_bench",
        SOUTHERN,
        "fixin to add 2 trees by teh libary and a bench betwen em",
        [
            delta(TREE, 2, 2),
            delta(BENCH_KIND, 1, 1),
            near(LIBRARY, 12, TREE, scope="added", every=True),
            near(LIBRARY, 12, BENCH_KIND, scope="added"),
            only(TREE, BENCH_KIND),
        ],
        [add(TREE, 2, loc("at", LIBRARY)), add(BENCH_KIND, 1, loc("at", LIBRARY))],
    ),
    case(
        "addition",
        "erroneous",
        "signs_same_as_barriers",
        DATA,
        "{catgory: contruction_sign, cnt: 2, loc: same_as_prev}",
        [delta(WORK_SIGN, 2, 2), near(LOT_B_ENTRANCE, 12, WORK_SIGN, every=True), only(WORK_SIGN)],
        [add(WORK_SIGN, 2, loc("at", LOT_B_ENTRANCE))],
        setup=[BARRIERS_LOT_B_PLANNED],
    ),
    case(
        "addition",
        "erroneous",
        "second_bus",
        COMMENTATOR,
        "and a secnd bus joins the fray, comming in behind the first one at the stop!",
        [delta(BUS, 1, 1), relative("behind", BUS_ID, BUS, max_distance=25), only(BUS)],
        [add(BUS, 1, ahead_of(BUS_ID, -15))],
        setup=[BUS_PULLS_IN_GIVEN],
    ),
    case(
        "addition",
        "erroneous",
        "robots_lot_a",
        EMOJI,
        "robto x2 @ lto A plz thx 🤖🤖",
        [delta(ROBOT, 2, 2), near(LOT_A, 1, ROBOT, every=True), only(ROBOT)],
        [add(ROBOT, 2, loc("at", LOT_A))],
    ),
]


# --- Removal ---------------------------------------------------------------------------------------
REMOVAL_CASES: list[Json] = [
    # direct
    case(
        "removal",
        "direct",
        "bench_for_the_stretcher",
        MEDIC,
        "Remove the bench at the bus stop — we need the room to get the stretcher through.",
        [gone(BENCH), only(assets=[BENCH])],
        [remove(BENCH)],
    ),
    case(
        "removal",
        "direct",
        "stop_sign_at_my_corner",
        LOLLIPOP,
        "Please remove the stop sign on the corner by the west crosswalk; I stop the traffic there myself.",
        [gone(STOP_SIGN), only(assets=[STOP_SIGN])],
        [remove(STOP_SIGN)],
    ),
    impossible(
        "removal",
        "direct",
        "test_car_off_my_rank",
        CABBIE,
        "Remove the test car from the scene completely, it's sat on my rank.",
        [remove(EGO)],
    ),
    case(
        "removal",
        "direct",
        "sedans_but_not_the_suv",
        CYCLIST,
        "Remove the two sedans parked in lot B, but leave the SUV where it is.",
        [gone(CAR_1, CAR_2), kept(SUV), only(assets=[CAR_1, CAR_2])],
        [remove(CAR_1, CAR_2)],
    ),
    case(
        "removal",
        "direct",
        "trees_bar_the_fountain_one",
        IRISH,
        "Take out all the trees except the one beside the fountain, so.",
        [gone(TREE_LIBRARY, TREE_LOT_A), kept(TREE_FOUNTAIN), delta(TREE, -3, -3), only(TREE)],
        [remove(TREE_LIBRARY, TREE_EAST, TREE_LOT_A)],
    ),
    case(
        "removal",
        "direct",
        "hydrant_and_stop_sign",
        SOUTHERN,
        "Y'all remove that fire hydrant by the JTEKT building, and the stop sign down by the crosswalk too.",
        [gone(HYDRANT, STOP_SIGN), only(assets=[HYDRANT, STOP_SIGN])],
        [remove(HYDRANT), remove(STOP_SIGN)],
    ),
    case(
        "removal",
        "direct",
        "south_east_lamps_kv",
        DATA,
        "remove: {category: street_light, side: south, x: '> 0'}",
        [
            gone(*SOUTH_EAST_LAMPS),
            kept("street_light_2", "street_light_4", "street_light_6"),
            only(assets=list(SOUTH_EAST_LAMPS)),
        ],
        [remove(*SOUTH_EAST_LAMPS)],
    ),
    case(
        "removal",
        "direct",
        "north_east_signal_down",
        COMMENTATOR,
        "And the traffic light on the north-east corner is coming down! Remove it.",
        [gone(LIGHT_NE), kept(LIGHT_SW), only(assets=[LIGHT_NE])],
        [remove(LIGHT_NE)],
    ),
    case(
        "removal",
        "direct",
        "rm_bin_and_tree",
        EMOJI,
        "rm bin thx 🗑️ … n the 🌳 behind the bus stop",
        [gone(BIN, TREE_LIBRARY), only(assets=[BIN, TREE_LIBRARY])],
        [remove(BIN), remove(TREE_LIBRARY)],
    ),
    # indirect
    case(
        "removal",
        "indirect",
        "clear_run_through_lot_b",
        MEDIC,
        "The crew need a clear run through lot B to get the trolley in — none of those parked cars can stay.",
        [gone(CAR_1, SUV, CAR_2), only(assets=[CAR_1, SUV, CAR_2])],
        [remove(CAR_1, SUV, CAR_2)],
    ),
    case(
        "removal",
        "indirect",
        "children_all_across",
        LOLLIPOP,
        "The children are all across now, so the crossing doesn't need marking any more.",
        [delta(CONE, -3, -3), count(CONE, 0, 0), only(CONE)],
        [remove(category=CONE)],
        setup=[CONES_CROSSING_PLANNED],
    ),
    case(
        "removal",
        "indirect",
        "lamp_where_i_pull_in",
        CABBIE,
        "That lamp post by the lot A entrance is right where I pull in for pick-ups; I'd be better off without it.",
        [gone(LAMP_LOT_A), only(assets=[LAMP_LOT_A])],
        [remove(LAMP_LOT_A)],
    ),
    impossible(
        "removal",
        "indirect",
        "car_free_campus",
        CYCLIST,
        "Honestly the best cycling infrastructure is no cars at all — take Main Street out of the map entirely.",
        [remove("Main Street")],
    ),
    case(
        "removal",
        "indirect",
        "nobody_sits_there",
        IRISH,
        "Sure nobody ever sits on that bench at the bus stop, it's only in the way of people waiting.",
        [gone(BENCH), only(assets=[BENCH])],
        [remove(BENCH)],
    ),
    case(
        "removal",
        "indirect",
        "blinding_lamps",
        SOUTHERN,
        "Them street lights on the north side, west of the crossroads, are blindin' folks. We don't need 'em.",
        [gone(*NORTH_WEST_LAMPS), kept("street_light_7"), only(assets=list(NORTH_WEST_LAMPS))],
        [remove(*NORTH_WEST_LAMPS)],
    ),
    case(
        "removal",
        "indirect",
        "ablation_no_furniture",
        DATA,
        "ablation B: run without street furniture at the bus stop (drop the seat; drop the bin)",
        [gone(BENCH, BIN), only(assets=[BENCH, BIN])],
        [remove(BENCH), remove(BIN)],
    ),
    case(
        "removal",
        "indirect",
        "red_card_suv",
        COMMENTATOR,
        "The SUV's been shown the red card — it's off the field for good!",
        [gone(SUV), kept(CAR_1, CAR_2), only(assets=[SUV])],
        [remove(SUV)],
    ),
    case(
        "removal",
        "indirect",
        "tree_in_my_shot",
        EMOJI,
        "🌳 by lot A blocks my 📷 view of the lot 😤",
        [gone(TREE_LOT_A), only(assets=[TREE_LOT_A])],
        [remove(TREE_LOT_A)],
    ),
    # vague
    case(
        "removal",
        "vague",
        "scene_is_safe",
        MEDIC,
        "debris — clear it, scene's safe now",
        [delta(RUBBLE, -1, -1), only(RUBBLE)],
        [remove(category=RUBBLE)],
        setup=[DEBRIS_MEDIC_PLANNED],
    ),
    case(
        "removal",
        "vague",
        "tall_light_on_my_corner",
        LOLLIPOP,
        "the tall light on the south corner by my crossing… dazzles the little ones, not needed really",
        [delta([LAMP, SIGNAL], -1, -1), only(assets=[LAMP_STOP_SIGN, LIGHT_SW])],
        [remove(LAMP_STOP_SIGN)],
        alternatives=[[gone(LAMP_STOP_SIGN)], [gone(LIGHT_SW)]],
    ),
    case(
        "removal",
        "vague",
        "fare_gone_bin_the_cones",
        CABBIE,
        "them cones... bin the lot, fare's gone",
        [count(CONE, 0, 0), delta(CONE, -4, -4), only(CONE)],
        [remove(category=CONE)],
        setup=[CONES_PICK_UP_PLANNED],
    ),
    case(
        "removal",
        "vague",
        "sightlines_tree",
        CYCLIST,
        "the tree behind the bus stop... sightlines for riders, meh. lose it?",
        [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
        [remove(TREE_LIBRARY)],
    ),
    case(
        "removal",
        "vague",
        "useless_lamp_yoke",
        IRISH,
        "that last lamp down the far end by the back gate, south side — useless yoke",
        [gone(LAMP_BACK_GATE_SOUTH), only(assets=[LAMP_BACK_GATE_SOUTH])],
        [remove(LAMP_BACK_GATE_SOUTH)],
    ),
    case(
        "removal",
        "vague",
        "ol_car_east_end",
        SOUTHERN,
        "that ol' car on the east end of the row over yonder… reckon it can go",
        [gone(CAR_2), kept(CAR_1, SUV), only(assets=[CAR_2])],
        [remove(CAR_2)],
    ),
    case(
        "removal",
        "vague",
        "trees_near_fountain",
        DATA,
        "drop trees where dist(fountain) < 20",
        [gone(TREE_FOUNTAIN, TREE_EAST), kept(TREE_LIBRARY, TREE_LOT_A), only(assets=[TREE_FOUNTAIN, TREE_EAST])],
        [remove(TREE_FOUNTAIN, TREE_EAST)],
    ),
    case(
        "removal",
        "vague",
        "signals_not_needed",
        COMMENTATOR,
        "and the signals… not needed for this one, surely — both of them, off",
        [gone(LIGHT_SW, LIGHT_NE), only(SIGNAL)],
        [remove(LIGHT_SW, LIGHT_NE)],
    ),
    case(
        "removal",
        "vague",
        "hydrant_x",
        EMOJI,
        "🚒 thing ❌",
        [gone(HYDRANT), only(assets=[HYDRANT])],
        [remove(HYDRANT)],
    ),
    # erroneous
    case(
        "removal",
        "erroneous",
        "lamp_crew_walk_into",
        MEDIC,
        "remvoe the strret light by the bus stp, the crew keep walkin into it",
        [gone(LAMP_BUS_STOP), only(assets=[LAMP_BUS_STOP])],
        [remove(LAMP_BUS_STOP)],
    ),
    case(
        "removal",
        "erroneous",
        "bin_kids_tip_over",
        LOLLIPOP,
        "plese take the rubish bin awya from the bus stop the kids keep tiping it over",
        [gone(BIN), only(assets=[BIN])],
        [remove(BIN)],
    ),
    case(
        "removal",
        "erroneous",
        "suv_takin_two_spaces",
        CABBIE,
        "get rid of tha suv in lot b its takin up 2 spaces, leve the other 2",
        [gone(SUV), kept(CAR_1, CAR_2), only(assets=[SUV])],
        [remove(SUV)],
    ),
    case(
        "removal",
        "erroneous",
        "clear_the_cycle_route",
        CYCLIST,
        "remove teh barriers AND the cones from the eastboud lane, its a cycle route",
        [count(BARRIER, 0, 0), count(CONE, 0, 0), only(BARRIER, CONE)],
        [remove(category=BARRIER), remove(category=CONE)],
        setup=[WORKS_EASTBOUND_GIVEN],
    ),
    impossible(
        "removal",
        "erroneous",
        "library_eyesore",
        IRISH,
        "get rid of the libary building altogther, its an eyesore so it is",
        [remove("Library")],
    ),
    case(
        "removal",
        "erroneous",
        "south_side_lamps",
        SOUTHERN,
        "git rid of all them streetlights on the south side of main stret",
        [gone(*SOUTH_LAMPS), kept(*NORTH_LAMPS), only(assets=list(SOUTH_LAMPS))],
        [remove(*SOUTH_LAMPS)],
    ),
    case(
        "removal",
        "erroneous",
        "delete_two_peds",
        DATA,
        "delte: pedestrain_1, pedestrain_2",
        [gone(PED_ID, PED_2), only(PERSON)],
        [remove(PED_ID, PED_2)],
        setup=[PEDS_FOUNTAIN_GIVEN],
    ),
    case(
        "removal",
        "erroneous",
        "rubble_cleared",
        COMMENTATOR,
        "and the rubbel is cleard from the lane — what a clean-up job!",
        [delta(RUBBLE, -1, -1), only(RUBBLE)],
        [remove(category=RUBBLE)],
        setup=[RUBBLE_COMMENTATOR_PLANNED],
    ),
    case(
        "removal",
        "erroneous",
        "west_car_lot_b",
        EMOJI,
        "rm 1st car in lot b (the wesst one) 🚗❌",
        [gone(CAR_1), kept(SUV, CAR_2), only(assets=[CAR_1])],
        [remove(CAR_1)],
    ),
]


# --- Positioning -----------------------------------------------------------------------------------
POSITIONING_CASES: list[Json] = [
    # direct
    case(
        "positioning",
        "direct",
        "van_to_new_rv",
        MEDIC,
        "Put the van right in front of the Student Union entrance; that's the new RV point.",
        [near(UNION, 12, asset=TRUCK_ID), only(assets=[TRUCK_ID])],
        [place(TRUCK_ID, loc("in_front_of", UNION))],
        setup=[VAN_RV_GIVEN],
    ),
    case(
        "positioning",
        "direct",
        "stop_sign_to_north_crossing",
        LOLLIPOP,
        "Put the stop sign on the pavement next to the north crosswalk.",
        [
            near(NORTH_CROSSWALK, 8, asset=STOP_SIGN),
            on(["sidewalk", "ground"], asset=STOP_SIGN),
            only(assets=[STOP_SIGN]),
        ],
        [place(STOP_SIGN, loc("on_sidewalk", NORTH_CROSSWALK))],
    ),
    case(
        "positioning",
        "direct",
        "suv_behind_ego",
        CABBIE,
        "Park the SUV right behind the ego in the eastbound lane.",
        [relative("behind", EGO, asset=SUV, max_distance=15), in_lane(EASTBOUND, asset=SUV), only(assets=[SUV])],
        [place(SUV, loc("behind", EGO))],
    ),
    case(
        "positioning",
        "direct",
        "bench_out_of_the_riders_way",
        CYCLIST,
        "Put the bench on the north pavement of Main Street in front of Engineering Hall, out of the riders' way.",
        [near(ENGINEERING, 15, asset=BENCH), on(["sidewalk"], asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("on_sidewalk", ENGINEERING))],
    ),
    case(
        "positioning",
        "direct",
        "bin_and_bench_at_library",
        IRISH,
        "Put the bin next to the Library entrance, and the bench beside the bin, so.",
        [near(LIBRARY, 6, asset=BIN), near(BIN, 4, asset=BENCH), only(assets=[BIN, BENCH])],
        [place(BIN, loc("next_to", LIBRARY)), place(BENCH, loc("next_to", BIN))],
    ),
    case(
        "positioning",
        "direct",
        "bench_by_the_fountain",
        SOUTHERN,
        "Y'all set the bench over by the fountain.",
        [near(FOUNTAIN, 6, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("at", FOUNTAIN))],
    ),
    case(
        "positioning",
        "direct",
        "bin_xy",
        DATA,
        "place(id=trash_bin_1, x=-45.0, y=-9.0)",
        [near(None, 1, asset=BIN, point=(-45.0, -9.0)), only(assets=[BIN])],
        [place(BIN, xy(-45.0, -9.0))],
    ),
    case(
        "positioning",
        "direct",
        "ego_on_the_grid",
        COMMENTATOR,
        "The ego lines up on the grid: put it in the westbound lane by the east gate!",
        [in_lane(WESTBOUND, asset=EGO, aligned=True), near(EAST_GATE, 15, asset=EGO), only(assets=[EGO])],
        [place(EGO, loc("in_lane", EAST_GATE, lane=WESTBOUND))],
    ),
    case(
        "positioning",
        "direct",
        "hydrant_to_library",
        EMOJI,
        "🚒 hydrant → nxt to library entrance",
        [near(LIBRARY, 6, asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, loc("next_to", LIBRARY))],
    ),
    # indirect
    case(
        "positioning",
        "indirect",
        "casualty_off_the_carriageway",
        MEDIC,
        "For scene safety the casualty has to come off the carriageway and onto the pavement.",
        [on(["sidewalk"], asset=PED_ID), near(None, 8, asset=PED_ID, point=(-40.0, -1.75)), only(PERSON)],
        [place(PED_ID, loc("on_sidewalk", PED_ID))],
        setup=[CASUALTY_LANE_PLANNED],
    ),
    case(
        "positioning",
        "indirect",
        "somewhere_to_sit_at_crossing",
        LOLLIPOP,
        "The children wait at the west crossing and there's nowhere to sit — the bench would be better on the "
        "pavement there.",
        [near(WEST_CROSSWALK, 10, asset=BENCH), on(["sidewalk", "ground"], asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("on_sidewalk", WEST_CROSSWALK))],
    ),
    case(
        "positioning",
        "indirect",
        "pick_up_at_library",
        CABBIE,
        "My pick-up's at the Library — the first sedan in lot B should be waiting in the drop-off right outside it.",
        [near(LIBRARY, 10, asset=CAR_1), only(assets=[CAR_1])],
        [place(CAR_1, loc("in_front_of", LIBRARY))],
    ),
    case(
        "positioning",
        "indirect",
        "dooring_zone",
        CYCLIST,
        "Parked cars by the lot edge are how riders get doored — the first sedan in lot B would be safer over in "
        "lot A.",
        [near(LOT_A, 1, asset=CAR_1), only(assets=[CAR_1])],
        [place(CAR_1, loc("at", LOT_A))],
    ),
    impossible(
        "positioning",
        "indirect",
        "bin_in_out_of_the_rain",
        IRISH,
        "The bin's after getting rained on — put it inside in the Library, in a press or somewhere dry, so.",
        [place(BIN, xy(-41.0, -30.0))],
    ),
    case(
        "positioning",
        "indirect",
        "truck_blocking_doors",
        SOUTHERN,
        "Reckon that truck's blockin' the doors — it'd sit better over in lot A.",
        [near(LOT_A, 1, asset=TRUCK_ID), only(assets=[TRUCK_ID])],
        [place(TRUCK_ID, loc("at", LOT_A))],
        setup=[TRUCK_JTEKT_PLANNED],
    ),
    case(
        "positioning",
        "indirect",
        "bench_constraint",
        DATA,
        "constraint: dist(bench_1, tree_4) <= 3 m; currently ~115 m, violated",
        [near(TREE_LOT_A, 3, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("next_to", TREE_LOT_A))],
    ),
    case(
        "positioning",
        "indirect",
        "robot_photo_finish",
        COMMENTATOR,
        "And the robot needs to be right up at the front of Engineering Hall for the photo finish!",
        [near(ENGINEERING, 14, asset=ROBOT_ID), only(assets=[ROBOT_ID])],
        [place(ROBOT_ID, loc("in_front_of", ENGINEERING))],
        setup=[ROBOT_LOT_A_PLANNED],
    ),
    case(
        "positioning",
        "indirect",
        "hydrant_in_the_way",
        EMOJI,
        "🚒 hydrant in the way of the 🚲 riders 😬 → by the JTEKT doors instead",
        [near(JTEKT, 6, asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, loc("at", JTEKT))],
    ),
    # vague
    case(
        "positioning",
        "vague",
        "bin_over_by_engineering",
        IRISH,
        "that bin... it'd be better off over by the Engineering Hall, so",
        [near(ENGINEERING, 6, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("at", ENGINEERING))],
    ),
    case(
        "positioning",
        "vague",
        "bench_afternoon_lot",
        LOLLIPOP,
        "the bench — by the north crossing instead? the afternoon lot wait there",
        [near(NORTH_CROSSWALK, 10, asset=BENCH), only(assets=[BENCH])],
        [place(BENCH, loc("on_sidewalk", NORTH_CROSSWALK))],
    ),
    case(
        "positioning",
        "vague",
        "suv_rank_jtekt",
        CABBIE,
        "suv — rank — jtekt. cheers",
        [near(JTEKT, 10, asset=SUV), only(assets=[SUV])],
        [place(SUV, loc("at", JTEKT))],
    ),
    case(
        "positioning",
        "vague",
        "bench_off_the_path",
        CYCLIST,
        "bench is kinda in the riders' way... somewhere off the path, by the tree behind the stop?",
        [near(TREE_LIBRARY, 5, asset=BENCH), moved(BENCH, 1.0), only(assets=[BENCH])],
        [place(BENCH, loc("next_to", TREE_LIBRARY))],
    ),
    case(
        "positioning",
        "vague",
        "hydrant_by_the_stop",
        IRISH,
        "the fire hydrant there — beside the bus stop would be grand",
        [near(BUS_STOP, 5, asset=HYDRANT), only(assets=[HYDRANT])],
        [place(HYDRANT, loc("at", BUS_STOP))],
    ),
    impossible(
        "positioning",
        "vague",
        "bench_on_the_roof",
        SOUTHERN,
        "that bench... might could go up top the Engineering Hall roof, nice view from up yonder",
        [place(BENCH, xy(-40.0, 28.0))],
    ),
    case(
        "positioning",
        "vague",
        "suv_and_car_to_lot_a",
        DATA,
        "suv_1 -> lot A; passenger_car_2 -> lot A",
        [near(LOT_A, 1, asset=SUV), near(LOT_A, 1, asset=CAR_2), only(assets=[SUV, CAR_2])],
        [place(SUV, loc("at", LOT_A)), place(CAR_2, loc("at", LOT_A))],
    ),
    case(
        "positioning",
        "vague",
        "bin_back_by_the_bench",
        COMMENTATOR,
        "and the bin's wandered off... no, it's fine — back right beside the bench where it belongs!",
        [near(BENCH, 2.5, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("next_to", BENCH))],
    ),
    case(
        "positioning",
        "vague",
        "stop_sign_by_ne_signal",
        EMOJI,
        "🛑 → nxt to 🚦 NE",
        [near(LIGHT_NE, 3, asset=STOP_SIGN), only(assets=[STOP_SIGN])],
        [place(STOP_SIGN, loc("next_to", LIGHT_NE))],
    ),
    # erroneous
    case(
        "positioning",
        "erroneous",
        "response_car_to_jtekt",
        MEDIC,
        "put the fist car in lot b infront of the JTEKT bulding, its the response car",
        [near(JTEKT, 10, asset=CAR_1), only(assets=[CAR_1])],
        [place(CAR_1, loc("in_front_of", JTEKT))],
    ),
    case(
        "positioning",
        "erroneous",
        "stop_sign_across_the_road",
        LOLLIPOP,
        "cna you put the stop sing on the other side of the road, the north pavment by the west crosing",
        [near(None, 7, asset=STOP_SIGN, point=(-12.0, 5.5)), only(assets=[STOP_SIGN])],
        [place(STOP_SIGN, xy(-13.5, 5.6))],
    ),
    case(
        "positioning",
        "erroneous",
        "pick_up_in_lot_a",
        CABBIE,
        "park the fisrt car in lot A by the entrnace, thats my pikc up spot",
        [near(LOT_A, 1, asset=CAR_1), near(LOT_A_ENTRANCE, 16, asset=CAR_1), only(assets=[CAR_1])],
        [place(CAR_1, xy(-85.0, 17.0))],
    ),
    case(
        "positioning",
        "erroneous",
        "bin_by_the_stop_sign",
        CYCLIST,
        "put teh bin by the stop sing, its in the way of riders waitng at the bus stpo",
        [near(STOP_SIGN, 3, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("next_to", STOP_SIGN))],
    ),
    case(
        "positioning",
        "erroneous",
        "bus_out_of_the_junction",
        IRISH,
        "put the bus at the bus stp there, its after parkin in the middle of the junciton",
        [near(BUS_STOP, 8, asset=BUS_ID), only(assets=[BUS_ID])],
        [place(BUS_ID, loc("at", BUS_STOP))],
        setup=[BUS_JUNCTION_GIVEN],
    ),
    case(
        "positioning",
        "erroneous",
        "suv_and_bin_at_library",
        SOUTHERN,
        "set that suv rite in frnot of the libary an the bin next to it",
        [near(LIBRARY, 10, asset=SUV), near(SUV, 4, asset=BIN), only(assets=[SUV, BIN])],
        [place(SUV, loc("in_front_of", LIBRARY)), place(BIN, loc("next_to", SUV))],
    ),
    impossible(
        "positioning",
        "erroneous",
        "suv_off_the_map",
        DATA,
        "plcae(suv_1, x=150, y=0)",
        [place(SUV, xy(150.0, 0.0))],
    ),
    case(
        "positioning",
        "erroneous",
        "ego_noses_in",
        COMMENTATOR,
        "and teh ego noses in rihgt in front of the SUV in the car park — what a move",
        [relative("in_front_of", SUV, asset=EGO, max_distance=12), only(assets=[EGO])],
        [place(EGO, loc("in_front_of", SUV))],
    ),
    case(
        "positioning",
        "erroneous",
        "bin_to_lot_b_entrance",
        EMOJI,
        "bin ➡️ lot b entrnce plz 🙏",
        [near(LOT_B_ENTRANCE, 6, asset=BIN), only(assets=[BIN])],
        [place(BIN, loc("at", LOT_B_ENTRANCE))],
    ),
]


# --- Moving: shifts, turns and behaviours ----------------------------------------------------------
MOVING_CASES: list[Json] = [
    # direct
    case(
        "moving",
        "direct",
        "stop_before_west_crosswalk",
        MEDIC,
        "Make the ego brake to a stop before the west crosswalk — we're working a casualty on it.",
        [stops_before(EGO, *WEST_CROSSWALK_LINE), only()],
        [event(EGO, "stop", reach(WEST_CROSSWALK), rate=3.0)],
    ),
    case(
        "moving",
        "direct",
        "reverse_ten_metres",
        EMOJI,
        "⏪ ego 10m pls, need room in front of it",
        [only(assets=[EGO])],
        [move(EGO, forward=-10.0)],
        alternatives=[[moved(EGO, 9, 11, "backward")], [event_played(EGO, "reverse", 5)]],
    ),
    case(
        "moving",
        "direct",
        "hold_red_for_the_children",
        LOLLIPOP,
        "Hold the south-west traffic light on red for the whole run while the children cross.",
        [stops_before(EGO, *WEST_CROSSWALK_LINE, seconds=25), only()],
        [hold(LIGHT_SW, "red")],
    ),
    case(
        "moving",
        "direct",
        "suv_forward_ten",
        CABBIE,
        "Move the SUV forward 10 metres.",
        [moved(SUV, 9, 11, "forward"), only(assets=[SUV])],
        [move(SUV, forward=10.0)],
    ),
    case(
        "moving",
        "direct",
        "right_turn_past_the_riders",
        CYCLIST,
        "Turn the ego right at the crossroads at 4 m/s — I want to see how it treats riders on the corner.",
        [reaches(EGO, "-1.75, -25", 40, within=4.0), only()],
        [manoeuvre(EGO, "junction_turn", turn="right", speed=4.0)],
    ),
    case(
        "moving",
        "direct",
        "car_off_down_eastbound",
        IRISH,
        "Have the first car in lot B drive off down the eastbound lane at 8 m/s.",
        [does("drive_lane", asset=CAR_1, lane=EASTBOUND, speed_min=7.5, speed_max=8.5), only(assets=[CAR_1])],
        [behave(CAR_1, "drive_lane", lane=EASTBOUND, speed=8.0)],
    ),
    case(
        "moving",
        "direct",
        "suv_face_east",
        IRISH,
        "Turn the SUV round so it's facing east, there.",
        [moved(SUV, 0, 3, turn_min=80, turn_max=100), only(assets=[SUV])],
        [move(SUV, turn_deg=-90.0)],
    ),
    case(
        "moving",
        "direct",
        "suv_circles",
        SOUTHERN,
        "Y'all make that SUV drive in circles in lot B, radius 8 metres.",
        [does("circle", asset=SUV, radius_min=7.5, radius_max=8.5), only(assets=[SUV])],
        [behave(SUV, "circle", radius=8.0)],
    ),
    case(
        "moving",
        "direct",
        "ego_speed_and_suv_circle",
        DATA,
        "ego.behaviour=drive_lane(lane=main_eastbound, speed=10); suv_1.behaviour=circle(r=6)",
        [
            does("drive_lane", asset=EGO, lane=EASTBOUND, speed_min=9.5, speed_max=10.5),
            does("circle", asset=SUV, radius_min=5.5, radius_max=6.5),
            only(assets=[EGO, SUV]),
        ],
        [behave(EGO, "drive_lane", lane=EASTBOUND, speed=10.0), behave(SUV, "circle", radius=6.0)],
    ),
    case(
        "moving",
        "direct",
        "left_turn_and_suv_away",
        COMMENTATOR,
        "And the ego takes the left at the crossroads — and the SUV pulls away down the westbound lane!",
        [
            reaches(EGO, NORTH_CROSSWALK, 40, within=4.0),
            does("drive_lane", asset=SUV, lane=WESTBOUND),
            only(assets=[SUV]),
        ],
        [manoeuvre(EGO, "junction_turn", turn="left"), behave(SUV, "drive_lane", lane=WESTBOUND)],
    ),
    case(
        "moving",
        "direct",
        "bench_left_three",
        EMOJI,
        "🪑 ⬅️ 3m",
        [only(assets=[BENCH])],
        [move(BENCH, east=-3.0)],
        alternatives=[[moved(BENCH, 2, 4, "forward")], [moved(BENCH, 2, 4, "left")]],
    ),
    # indirect
    case(
        "moving",
        "indirect",
        "blues_and_twos",
        MEDIC,
        "We're on blues and twos — the ego needs to be doing 15 m/s down Main Street.",
        [does("drive_lane", asset=EGO, speed_min=14, speed_max=16), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=15.0)],
    ),
    case(
        "moving",
        "indirect",
        "crew_to_the_rv",
        MEDIC,
        "The crew are heading for the RV point — the first sedan in lot B should make its own way to the lot A "
        "entrance.",
        [does("follow_path", asset=CAR_1), only(assets=[CAR_1])],
        [behave(CAR_1, "follow_path", to=LOT_A_ENTRANCE)],
    ),
    case(
        "moving",
        "indirect",
        "lights_have_changed",
        LOLLIPOP,
        "The lights have changed and the little one at my crossing is ready — she can go now.",
        [does("cross_road", asset=PED_ID, crosses_lane=EASTBOUND), only(PERSON)],
        [behave(PED_ID, "cross_road")],
        setup=[CHILD_KERB_GIVEN],
    ),
    case(
        "moving",
        "indirect",
        "children_cross_by_the_stop",
        LOLLIPOP,
        "The children cross by the bus stop, so anything driving past it has to be going slowly — keep the ego "
        "under 3 m/s.",
        [does("drive_lane", asset=EGO, speed_min=0.5, speed_max=3.0), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=2.5)],
    ),
    case(
        "moving",
        "indirect",
        "rat_run_north",
        CABBIE,
        "The first car in lot B is my cab doing the rat run — it needs to be heading up Campus Drive northbound.",
        [does("drive_lane", asset=CAR_1, lane=NORTHBOUND), only(assets=[CAR_1])],
        [behave(CAR_1, "drive_lane", lane=NORTHBOUND)],
    ),
    case(
        "moving",
        "indirect",
        "overtake_with_room",
        CYCLIST,
        "The ego's about to overtake that rider — it has to move fully into the other lane 2 seconds in, not "
        "squeeze past.",
        [event_played(EGO, "lane_change", 6), only()],
        [manoeuvre(EGO, "lane_change", 2.0, side="left")],
        setup=[RIDER_AHEAD_PLANNED],
    ),
    case(
        "moving",
        "indirect",
        "suv_out_driving",
        IRISH,
        "Sure the SUV's been parked there all day — it'd want to be out driving the westbound lane at this stage.",
        [does("drive_lane", asset=SUV, lane=WESTBOUND), only(assets=[SUV])],
        [behave(SUV, "drive_lane", lane=WESTBOUND)],
    ),
    impossible(
        "moving",
        "indirect",
        "scoot_the_fountain",
        SOUTHERN,
        "That fountain's sittin' right in my view — y'all scoot it a ways east.",
        [move(FOUNTAIN, east=10.0)],
    ),
    case(
        "moving",
        "indirect",
        "expected_displacement",
        DATA,
        "expected after step: Δ(suv_1) ≈ 6 m north, heading unchanged",
        [moved(SUV, 5, 7, "forward", turn_max=5), only(assets=[SUV])],
        [move(SUV, north=6.0)],
    ),
    case(
        "moving",
        "indirect",
        "break_for_the_union",
        COMMENTATOR,
        "The SUV makes a break for it — it's heading for the Student Union doors!",
        [does("follow_path", asset=SUV), only(assets=[SUV])],
        [behave(SUV, "follow_path", to=UNION)],
    ),
    case(
        "moving",
        "indirect",
        "blocking_the_exit",
        EMOJI,
        "🚗1 blocking the 🅿️ exit → scoot fwd 5m",
        [moved(CAR_1, 4, 6, "forward"), only(assets=[CAR_1])],
        [move(CAR_1, forward=5.0)],
    ),
    # vague
    case(
        "moving",
        "vague",
        "slower_casualty_ahead",
        MEDIC,
        "ego... slower, casualty up ahead",
        [only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=2.5)],
        alternatives=[
            [does("drive_lane", asset=EGO, speed_max=4.5)],
            [event_played(EGO, "change_speed", 12)],
            [event_played(EGO, "stop", 15)],
        ],
    ),
    case(
        "moving",
        "vague",
        "fend_off_ahead",
        MEDIC,
        "the sedan on the end… fend-off position ahead of the ego, 20 m or so",
        [
            relative("in_front_of", EGO, asset=CAR_1, max_distance=40),
            in_lane(EASTBOUND, asset=CAR_1),
            only(assets=[CAR_1]),
        ],
        [move(CAR_1, relative_to=EGO, along_m=20.0)],
    ),
    case(
        "moving",
        "vague",
        "both_over_now",
        LOLLIPOP,
        "the kids... over the road now, both of them",
        [does("cross_road", PERSON, min_count=2), only(PERSON)],
        [behave(PED_ID, "cross_road"), behave(PED_2, "cross_road")],
        setup=[TWO_KIDS_KERB_GIVEN],
    ),
    case(
        "moving",
        "vague",
        "spin_it_round",
        CABBIE,
        "suv. spin it round.",
        [moved(SUV, 0, 3, turn_min=150), only(assets=[SUV])],
        [move(SUV, turn_deg=180.0)],
    ),
    case(
        "moving",
        "vague",
        "test_car_crawling",
        CABBIE,
        "test car's crawlin'... get a shift on?",
        [does("drive_lane", asset=EGO, speed_min=6.0), only(assets=[EGO])],
        [behave(EGO, "drive_lane", speed=10.0)],
    ),
    case(
        "moving",
        "vague",
        "more_room_for_riders",
        CYCLIST,
        "riders filtering up the inside... ego gives them room? hop over into the other lane a few secs in",
        [event_played(EGO, "lane_change", 8), only()],
        [manoeuvre(EGO, "lane_change", 3.0, side="left")],
    ),
    case(
        "moving",
        "vague",
        "give_it_a_lash_round",
        IRISH,
        "the last car at the east end there, give it a lash round the car park in circles",
        [does("circle", asset=CAR_2), only(assets=[CAR_2])],
        [behave(CAR_2, "circle")],
    ),
    case(
        "moving",
        "vague",
        "scoot_on_up",
        SOUTHERN,
        "that SUV might could scoot on up a ways",
        [moved(SUV, 2, 20, "forward"), only(assets=[SUV])],
        [move(SUV, forward=6.0)],
    ),
    case(
        "moving",
        "vague",
        "robot_mode_circle",
        DATA,
        "robot: mode=circle r=4 (same place)",
        [does("circle", asset=ROBOT_ID, radius_min=3.5, radius_max=4.5), only(ROBOT)],
        [behave(ROBOT_ID, "circle", radius=4.0)],
        setup=[ROBOT_DATA_PLANNED],
    ),
    impossible(
        "moving",
        "vague",
        "suv_at_250",
        COMMENTATOR,
        "and the SUV absolutely flies — 250 km/h down Main Street!",
        [behave(SUV, "drive_lane", lane=EASTBOUND, speed=69.4)],
    ),
    impossible(
        "moving",
        "vague",
        "tree_donuts",
        EMOJI,
        "🌳 do donuts lol 🍩🍩",
        [behave(TREE_LIBRARY, "circle")],
    ),
    # erroneous
    case(
        "moving",
        "erroneous",
        "brake_at_the_junction",
        MEDIC,
        "make teh ego brake hrad as it gets to the main junciton, theres a casulaty in it",
        [stops_before(EGO, *JUNCTION_CENTRE_LINE, seconds=25), only()],
        [event(EGO, "stop", reach(JUNCTION), rate=6.0)],
    ),
    case(
        "moving",
        "erroneous",
        "first_car_forward",
        SOUTHERN,
        "mosey that 1st car in lot b up 10m foward y'all, its blokin the way out",
        [moved(CAR_1, 9, 11, "forward"), only(assets=[CAR_1])],
        [move(CAR_1, forward=10.0)],
    ),
    case(
        "moving",
        "erroneous",
        "slow_near_the_school_crossing",
        LOLLIPOP,
        "cna the ego slow donw to 2 m/s near the scool crosing plz",
        [only(assets=[EGO])],
        [event(EGO, "change_speed", reach(WEST_CROSSWALK), speed=2.0)],
        alternatives=[[does("drive_lane", asset=EGO, speed_max=2.2)], [event_played(EGO, "change_speed", 20)]],
    ),
    case(
        "moving",
        "erroneous",
        "red_for_thirty",
        LOLLIPOP,
        "hold the trafic light on the south west corner on red for 30 secs so the kids can get acros",
        [stops_before(EGO, *WEST_CROSSWALK_LINE, seconds=25), only()],
        [
            call(
                "set_light_phases",
                light=LIGHT_SW,
                phases=[{"state": "red", "duration": 30.0}, {"state": "green", "duration": 30.0}],
            )
        ],
    ),
    case(
        "moving",
        "erroneous",
        "ego_on_the_rat_run",
        CABBIE,
        "stick the ego on campus drvie goin north at 8ms, rat run innit",
        [does("drive_lane", asset=EGO, lane=NORTHBOUND, speed_min=7.5, speed_max=8.5), only(assets=[EGO])],
        [behave(EGO, "drive_lane", lane=NORTHBOUND, speed=8.0)],
    ),
    case(
        "moving",
        "erroneous",
        "bike_behind_the_ego",
        CYCLIST,
        "the bike shuold ride down the eastbond lane behind the ego at 5ms",
        [does("drive_lane", asset=BIKE_ID, lane=EASTBOUND, speed_min=4.5, speed_max=5.5), only(BIKE)],
        [behave(BIKE_ID, "drive_lane", lane=EASTBOUND, speed=5.0)],
        setup=[BIKE_GATE_PLANNED],
    ),
    case(
        "moving",
        "erroneous",
        "lash_up_to_jtekt",
        IRISH,
        "giv the suv a lash up to the JTEKT bulding there, drivin like",
        [does("follow_path", asset=SUV), only(assets=[SUV])],
        [behave(SUV, "follow_path", to=JTEKT)],
    ),
    case(
        "moving",
        "erroneous",
        "back_it_up",
        SOUTHERN,
        "fixin to back that SUV up 3 metres, reckin it's too far foward",
        [only(assets=[SUV])],
        [move(SUV, forward=-3.0)],
        alternatives=[[moved(SUV, 2, 4, "backward")], [event_played(SUV, "reverse", 5)]],
    ),
    case(
        "moving",
        "erroneous",
        "ego_turn_kv",
        DATA,
        "ego.trun_deg=90 (anticlokwise)",
        [moved(EGO, 0, 1, turn_min=80, turn_max=100), only(assets=[EGO])],
        [move(EGO, turn_deg=90.0)],
    ),
    case(
        "moving",
        "erroneous",
        "joins_westbound",
        COMMENTATOR,
        "and passenger car 1 pulls awya and joins the westbund traffic!",
        [does("drive_lane", asset=CAR_1, lane=WESTBOUND), only(assets=[CAR_1])],
        [behave(CAR_1, "drive_lane", lane=WESTBOUND)],
    ),
    case(
        "moving",
        "erroneous",
        "jaywalk_pls",
        EMOJI,
        "🚶‍♀️ jaywlk in frnt of teh ego plz",
        [does("jaywalk", asset=PED_ID, crosses_lane=EASTBOUND), only(PERSON)],
        [behave(PED_ID, "jaywalk")],
        setup=[PED_BUS_STOP_GIVEN],
    ),
]


# --- Arrangement: several new things laid out together ---------------------------------------------
ARRANGEMENT_CASES: list[Json] = [
    # direct
    case(
        "arrangement",
        "direct",
        "ring_round_the_casualty",
        MEDIC,
        "Put a ring of six cones round the casualty for scene safety, and a road-works sign beside them.",
        [
            delta(CONE, 6, 6),
            layout("ring", CONE, 6, around=PED_ID),
            delta(WORK_SIGN, 1, 1),
            near(PED_ID, 12, WORK_SIGN),
            only(CONE, WORK_SIGN),
        ],
        [arrange(CONE, "ring", loc("at", PED_ID), count=6), add(WORK_SIGN, 1, loc("next_to", PED_ID))],
        setup=[CASUALTY_EAST_GATE_GIVEN],
    ),
    impossible(
        "arrangement",
        "direct",
        "cordon_of_150",
        MEDIC,
        "Cone off the whole scene: a ring of 150 cones round the RV point at the lot A entrance.",
        [arrange(CONE, "ring", loc("at", LOT_A_ENTRANCE), count=150)],
    ),
    case(
        "arrangement",
        "direct",
        "cones_across_the_crossing",
        LOLLIPOP,
        "Put a line of five cones across the road at the west crosswalk while the children cross.",
        [delta(CONE, 5, 5), layout("line", CONE, 5), near(WEST_CROSSWALK, 8, CONE, every=True), only(CONE)],
        [arrange(CONE, "line", loc("at", WEST_CROSSWALK), count=5, heading_deg=90.0)],
    ),
    case(
        "arrangement",
        "direct",
        "posts_round_the_bench",
        LOLLIPOP,
        "Put four bollards in a ring round the bench at the bus stop so cars can't mount the pavement there.",
        [delta(BOLLARD, 4, 4), layout("ring", BOLLARD, 4, around=BENCH), only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", BENCH), count=4)],
    ),
    case(
        "arrangement",
        "direct",
        "rank_in_lot_a",
        CABBIE,
        "Park four cars side by side in lot A — that's the rank — and put a parking sign by the lot A entrance.",
        [
            delta(CAR, 4, 4),
            layout("line", CAR, 4),
            near(LOT_A, 1, CAR, every=True),
            delta(PARK_SIGN, 1, 1),
            near(LOT_A_ENTRANCE, 10, PARK_SIGN),
            only(CAR, PARK_SIGN),
        ],
        [arrange(CAR, "parking_row", loc("at", LOT_A), count=4), add(PARK_SIGN, 1, loc("at", LOT_A_ENTRANCE))],
    ),
    case(
        "arrangement",
        "direct",
        "protected_lane_bollards",
        CYCLIST,
        "Line the right-hand edge of the eastbound lane by the bus stop with eight bollards, as a makeshift "
        "protected lane.",
        [
            delta(BOLLARD, 8, 8),
            layout("line", BOLLARD, 8),
            in_lane(EASTBOUND, BOLLARD),
            near(BUS_STOP, 25, BOLLARD, every=True),
            only(BOLLARD),
        ],
        [arrange(BOLLARD, "lane_edge", loc("at", BUS_STOP, lane=EASTBOUND), count=8)],
    ),
    case(
        "arrangement",
        "direct",
        "benches_round_the_fountain",
        IRISH,
        "Put a ring of six benches around the fountain there.",
        [delta(BENCH_KIND, 6, 6), layout("ring", BENCH_KIND, 6, around=FOUNTAIN), only(BENCH_KIND)],
        [arrange(BENCH_KIND, "ring", loc("at", FOUNTAIN), count=6)],
    ),
    case(
        "arrangement",
        "direct",
        "row_of_trees_engineering",
        SOUTHERN,
        "Y'all plant a row of five trees on the grass in front of Engineering Hall, runnin' east to west.",
        [delta(TREE, 5, 5), layout("line", TREE, 5), near(ENGINEERING, 12, TREE, every=True), only(TREE)],
        [arrange(TREE, "line", xy(-40.0, 10.0), count=5, heading_deg=0.0)],
    ),
    case(
        "arrangement",
        "direct",
        "cone_grid_kv",
        DATA,
        "layout=grid category=traffic_cone n=9 cols=3 at=lot B",
        [delta(CONE, 9, 9), near(LOT_B, 1, CONE, every=True), layout("cluster", CONE, 9, tolerance=6.0), only(CONE)],
        [arrange(CONE, "grid", loc("at", LOT_B), count=9, columns=3)],
    ),
    case(
        "arrangement",
        "direct",
        "stewards_barriers_in_front",
        COMMENTATOR,
        "And the stewards bring out the barriers — a line of three across the eastbound lane in front of the ego!",
        [
            delta(BARRIER, 3, 3),
            layout("line", BARRIER, 3),
            relative("in_front_of", EGO, BARRIER, max_distance=15, every=True),
            only(BARRIER),
        ],
        [arrange(BARRIER, "line", loc("in_front_of", EGO), count=3)],
    ),
    case(
        "arrangement",
        "direct",
        "cone_line_at_gate",
        EMOJI,
        "🔶 cone x5 line @ main gate",
        [delta(CONE, 5, 5), layout("line", CONE, 5), near(MAIN_GATE, 12, CONE, every=True), only(CONE)],
        [arrange(CONE, "line", loc("at", MAIN_GATE), count=5)],
    ),
    # indirect
    case(
        "arrangement",
        "indirect",
        "landing_spot_lot_b",
        MEDIC,
        "The crew need a landing spot marked out in the middle of lot B — cones in a circle about ten metres across.",
        [layout("ring", CONE, 6, around=LOT_B, tolerance=2.0), near(LOT_B, 1, CONE, every=True), only(CONE)],
        [arrange(CONE, "ring", loc("at", LOT_B), radius=5.0, count=10)],
    ),
    case(
        "arrangement",
        "indirect",
        "debris_coned_off",
        MEDIC,
        "Traffic can't be driving into that debris while the crew work on it — it needs coning off all the way round.",
        [layout("ring", CONE, 4, around=RUBBLE_ID), only(CONE)],
        [arrange(CONE, "ring", loc("at", RUBBLE_ID))],
        setup=[RUBBLE_EAST_GATE_PLANNED],
    ),
    case(
        "arrangement",
        "indirect",
        "safe_waiting_pen",
        LOLLIPOP,
        "The children need a safe pen while they wait at the bus stop so nobody can drive at them — posts all "
        "round them.",
        [only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", PED_ID))],
        setup=[KIDS_AT_BUS_STOP_GIVEN],
        alternatives=[
            [layout("ring", BOLLARD, 4, around=PED_ID)],
            [layout("ring", BOLLARD, 4, around=PED_2)],
            [layout("ring", BOLLARD, 4, around=BUS_STOP, tolerance=2.0)],
        ],
    ),
    case(
        "arrangement",
        "indirect",
        "proper_rank_at_jtekt",
        CABBIE,
        "I want a proper rank outside the JTEKT building: three cabs lined up nose to tail on the drop-off.",
        [delta(CAR, 3, 3), layout("line", CAR, 3), near(JTEKT, 10, CAR, every=True), only(CAR)],
        [arrange(CAR, "line", loc("at", JTEKT), count=3)],
    ),
    impossible(
        "arrangement",
        "indirect",
        "rank_of_twelve_buses",
        CABBIE,
        "For the rank I'm after, twelve buses lined up along the westbound lane.",
        [arrange(BUS, "line", loc("at", WESTBOUND), count=12)],
    ),
    case(
        "arrangement",
        "indirect",
        "light_segregation_westbound",
        CYCLIST,
        "Riders get close-passed on the westbound lane past the JTEKT building; some light segregation along "
        "that lane's edge would help.",
        [
            layout("line", SEGREGATION, 5),
            in_lane(WESTBOUND, SEGREGATION),
            near(JTEKT, 30, SEGREGATION, every=True),
            only(*SEGREGATION),
        ],
        [arrange(BOLLARD, "lane_edge", loc("at", JTEKT, lane=WESTBOUND), count=8)],
    ),
    case(
        "arrangement",
        "indirect",
        "somewhere_for_the_lads",
        IRISH,
        "The lads want somewhere to sit outside the Engineering Hall; a row of benches would be grand.",
        [layout("line", BENCH_KIND, 3), near(ENGINEERING, 12, BENCH_KIND, every=True), only(BENCH_KIND)],
        [arrange(BENCH_KIND, "line", loc("at", ENGINEERING), count=4)],
    ),
    case(
        "arrangement",
        "indirect",
        "posts_round_the_fountain",
        SOUTHERN,
        "Folks keep drivin' onto the grass round the fountain — reckon it needs some posts all around it.",
        [layout("ring", BOLLARD, 4, around=FOUNTAIN), only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=8)],
    ),
    impossible(
        "arrangement",
        "indirect",
        "enclosure_radius_100",
        DATA,
        "requirement: fountain fully enclosed; ring(category=bollard) with radius_m=100",
        [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), radius=100.0)],
    ),
    case(
        "arrangement",
        "indirect",
        "crowd_at_north_crossing",
        COMMENTATOR,
        "The crowd's spilling onto the road at the north crossing — the stewards need a line of barriers there to "
        "hold them back.",
        [layout("line", BARRIER, 3), near(NORTH_CROSSWALK, 12, BARRIER, every=True), only(BARRIER)],
        [arrange(BARRIER, "line", loc("at", NORTH_CROSSWALK), count=4)],
    ),
    case(
        "arrangement",
        "indirect",
        "lot_b_looks_empty",
        EMOJI,
        "lot B looks empty for the demo 🅿️😬 … a row of 3 🚗?",
        [delta(CAR, 3, 3), layout("line", CAR, 3), near(LOT_B, 1, CAR, every=True), only(CAR)],
        [arrange(CAR, "parking_row", loc("at", LOT_B), count=3)],
    ),
    # vague
    case(
        "arrangement",
        "vague",
        "cones_round_the_junction",
        EMOJI,
        "🔶🔶 ring @ junction middle?? 🚑 working there",
        [layout("ring", CONE, 4, around=JUNCTION, tolerance=2.0), only(CONE)],
        [arrange(CONE, "ring", loc("at", JUNCTION))],
    ),
    case(
        "arrangement",
        "vague",
        "cones_round_the_little_ones",
        LOLLIPOP,
        "and cones round them... the little ones, I mean, so nobody drives into them",
        [only(CONE)],
        [arrange(CONE, "ring", loc("at", PED_ID))],
        setup=[KIDS_ON_CROSSING_PLANNED],
        alternatives=[
            [layout("ring", CONE, 4, around=PED_ID)],
            [layout("ring", CONE, 4, around=PED_2)],
        ],
    ),
    case(
        "arrangement",
        "vague",
        "more_cabs_on_the_rank",
        CABBIE,
        "more cabs on the rank… a row of em, lot A",
        [delta(CAR, 3, 8), layout("line", CAR, 3), near(LOT_A, 1, CAR, every=True), only(CAR)],
        [arrange(CAR, "parking_row", loc("at", LOT_A))],
    ),
    case(
        "arrangement",
        "vague",
        "segregation_by_the_library",
        CYCLIST,
        "bit of segregation? eastbound, by the library-ish",
        [
            layout("line", SEGREGATION, 4),
            in_lane(EASTBOUND, SEGREGATION),
            near(LIBRARY, 25, SEGREGATION, every=True),
            only(*SEGREGATION),
        ],
        [arrange(BOLLARD, "lane_edge", loc("at", LIBRARY, lane=EASTBOUND))],
    ),
    case(
        "arrangement",
        "vague",
        "cycle_parking_union",
        CYCLIST,
        "cycle parking?? a row of bikes by the union doors maybe",
        [layout("line", BIKE, 3), near(UNION, 12, BIKE, every=True), only(BIKE)],
        [arrange(BIKE, "line", loc("at", UNION), count=5)],
    ),
    case(
        "arrangement",
        "vague",
        "barrier_yokes_back_gate",
        IRISH,
        "a few of them barrier yokes across the road at the back gate, so nobody gets in",
        [layout("line", BARRIER, 3), near(EAST_GATE, 10, BARRIER, every=True), only(BARRIER)],
        [arrange(BARRIER, "line", loc("at", EAST_GATE), count=4)],
    ),
    case(
        "arrangement",
        "vague",
        "ring_of_trees_purty",
        SOUTHERN,
        "them trees… might could use a ring of 'em round the fountain, real purty",
        [layout("ring", TREE, 4, around=FOUNTAIN), only(TREE)],
        [arrange(TREE, "ring", loc("at", FOUNTAIN))],
    ),
    case(
        "arrangement",
        "vague",
        "cone_line_kv",
        DATA,
        "cones: line, n=6, loc=lot A entrance",
        [delta(CONE, 6, 6), layout("line", CONE, 6), near(LOT_A_ENTRANCE, 12, CONE, every=True), only(CONE)],
        [arrange(CONE, "line", loc("at", LOT_A_ENTRANCE), count=6)],
    ),
    case(
        "arrangement",
        "vague",
        "posts_round_hydrant_kv",
        DATA,
        "bollard{n:4} ring(hydrant)",
        [delta(BOLLARD, 4, 4), layout("ring", BOLLARD, 4, around=HYDRANT), only(BOLLARD)],
        [arrange(BOLLARD, "ring", loc("at", HYDRANT), count=4)],
    ),
    case(
        "arrangement",
        "vague",
        "guard_of_honour",
        COMMENTATOR,
        "and a guard of honour for the ego… bollards alongside it? a line, anyway",
        [layout("line", BOLLARD, 4), near(EGO, 6, BOLLARD, every=True), only(BOLLARD)],
        [arrange(BOLLARD, "line", loc("next_to", EGO), count=5)],
    ),
    case(
        "arrangement",
        "vague",
        "barriers_at_junction",
        EMOJI,
        "🚧🚧🚧 @ junction + ⚠️ sign",
        [
            delta(BARRIER, 3, 3),
            layout("line", BARRIER, 3),
            near(JUNCTION, 3, BARRIER, every=True),
            delta(WORK_SIGN, 1, 1),
            near(JUNCTION, 12, WORK_SIGN),
            only(BARRIER, WORK_SIGN),
        ],
        [arrange(BARRIER, "line", loc("at", JUNCTION), count=3), add(WORK_SIGN, 1, loc("at", JUNCTION))],
    ),
    # erroneous
    case(
        "arrangement",
        "erroneous",
        "road_closed_east_gate",
        MEDIC,
        "put a line of 4 barirers acros the westbund lane by the east gate, road closed for the incidnet",
        [delta(BARRIER, 4, 4), layout("line", BARRIER, 4), near(EAST_GATE, 12, BARRIER, every=True), only(BARRIER)],
        [arrange(BARRIER, "line", loc("at", EAST_GATE), count=4)],
    ),
    case(
        "arrangement",
        "erroneous",
        "other_crews_beside_van",
        MEDIC,
        "now a row of 3 cars parkd beside the van, the other crews",
        [delta(CAR, 3, 3), layout("line", CAR, 3), near(TRUCK_ID, 12, CAR, every=True), only(CAR)],
        [arrange(CAR, "parking_row", loc("next_to", TRUCK_ID), count=3)],
        setup=[VAN_LOT_B_PLANNED],
    ),
    case(
        "arrangement",
        "erroneous",
        "cones_across_north_crossing",
        LOLLIPOP,
        "put 4 cones in a lnie across the raod at the north crosing, kids crossing",
        [delta(CONE, 4, 4), layout("line", CONE, 4), near(NORTH_CROSSWALK, 8, CONE, every=True), only(CONE)],
        [arrange(CONE, "line", loc("at", NORTH_CROSSWALK), count=4, heading_deg=0.0)],
    ),
    case(
        "arrangement",
        "erroneous",
        "three_cabs_lot_b",
        CABBIE,
        "park 3 cabs side by side in lot b next to the others",
        [delta(CAR, 3, 3), layout("line", CAR, 3), near(LOT_B, 1, CAR, scope="added", every=True), only(CAR)],
        [arrange(CAR, "parking_row", loc("at", LOT_B), count=3)],
    ),
    impossible(
        "arrangement",
        "erroneous",
        "protected_bike_lane",
        CYCLIST,
        "line the bike lnae on main stret with bolards, the protected one",
        [arrange(BOLLARD, "lane_edge", loc("at", "bike lane", lane="bike_lane"))],
    ),
    case(
        "arrangement",
        "erroneous",
        "row_of_trees_library",
        IRISH,
        "a row of 5 trees along by the libary there, sure it'd be lovley",
        [delta(TREE, 5, 5), layout("line", TREE, 5), near(LIBRARY, 15, TREE, every=True), only(TREE)],
        [arrange(TREE, "line", loc("at", LIBRARY), count=5)],
    ),
    case(
        "arrangement",
        "erroneous",
        "cones_round_the_rubble",
        SOUTHERN,
        "y'all set a ring of conez round that rubbel, someones fixin to hit it",
        [layout("ring", CONE, 4, around=RUBBLE_ID), only(CONE)],
        [arrange(CONE, "ring", loc("at", RUBBLE_ID))],
        setup=[RUBBLE_SOUTHERN_GIVEN],
    ),
    case(
        "arrangement",
        "erroneous",
        "bollard_line_kv",
        DATA,
        "arange: {category: bollard, shpae: line, n: 6, at: 'north crosswlak'}",
        [
            delta(BOLLARD, 6, 6),
            layout("line", BOLLARD, 6),
            near(NORTH_CROSSWALK, 12, BOLLARD, every=True),
            only(BOLLARD),
        ],
        [arrange(BOLLARD, "line", loc("at", NORTH_CROSSWALK), count=6)],
    ),
    case(
        "arrangement",
        "erroneous",
        "wall_behind_the_ego",
        COMMENTATOR,
        "and they've formd a wall — a line of 3 barriers behnd the ego, nothing getting past!",
        [
            delta(BARRIER, 3, 3),
            layout("line", BARRIER, 3),
            relative("behind", EGO, BARRIER, max_distance=15, every=True),
            only(BARRIER),
        ],
        [arrange(BARRIER, "line", loc("behind", EGO), count=3)],
    ),
    case(
        "arrangement",
        "erroneous",
        "fans_line_the_route",
        COMMENTATOR,
        "and the fans line the route — 6 peple in a line along the pavment by the JTEKT bulding",
        [delta(PERSON, 6, 6), layout("line", PERSON, 6), near(JTEKT, 15, PERSON, every=True), only(PERSON)],
        [arrange(PERSON, "line", loc("on_sidewalk", JTEKT), count=6)],
    ),
    case(
        "arrangement",
        "erroneous",
        "cones_lot_b_entrance",
        EMOJI,
        "cones x4 in a lien @ lot b entrnce 🔶🔶🔶🔶",
        [delta(CONE, 4, 4), layout("line", CONE, 4), near(LOT_B_ENTRANCE, 10, CONE, every=True), only(CONE)],
        [arrange(CONE, "line", loc("at", LOT_B_ENTRANCE), count=4)],
    ),
]


# --- Appearance: weather, clock, lights and looks --------------------------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case(
        "appearance",
        "direct",
        "night_and_heavy_rain",
        MEDIC,
        "Set it to night with heavy rain — that's what most of our call-outs look like.",
        [env(weather=["rain"], intensity_min=0.7, night=True), only(env=True)],
        [clock("22:00"), weather("rain", 0.9)],
    ),
    case(
        "appearance",
        "direct",
        "school_arrival_time",
        LOLLIPOP,
        "Set the time to 8:45 in the morning, when the children arrive for school.",
        [env(time_from="08:40", time_to="08:50", **CLEAR), only(env=True)],
        [clock("08:45")],
    ),
    case(
        "appearance",
        "direct",
        "cab_black",
        CABBIE,
        "Paint the first car in lot B black — that's my cab.",
        [looks("black", asset=CAR_1), only(assets=[CAR_1])],
        [paint([CAR_1], colour="black")],
    ),
    case(
        "appearance",
        "direct",
        "bike_bright_yellow",
        CYCLIST,
        "Make that cyclist's bike bright yellow so drivers can see it.",
        [looks("yellow", asset=BIKE_ID), only(assets=[BIKE_ID])],
        [paint([BIKE_ID], colour="yellow")],
        setup=[BIKE_EASTBOUND_PLANNED],
    ),
    case(
        "appearance",
        "direct",
        "heavy_fog",
        IRISH,
        "Put a heavy fog down on the place, so — proper Irish weather.",
        [env(weather=["fog"], intensity_min=0.7, **NOON), only(env=True)],
        [weather("fog", 0.9)],
    ),
    case(
        "appearance",
        "direct",
        "suv_red",
        SOUTHERN,
        "Y'all paint that SUV red.",
        [looks("red", asset=SUV), only(assets=[SUV])],
        [paint([SUV], colour="red")],
    ),
    case(
        "appearance",
        "direct",
        "rain_kv",
        DATA,
        "weather=rain intensity=0.8",
        [env(weather=["rain"], intensity_min=0.75, intensity_max=0.85, **NOON), only(env=True)],
        [weather("rain", 0.8)],
    ),
    case(
        "appearance",
        "direct",
        "floodlights_on",
        COMMENTATOR,
        "And the floodlights come on! Street lights on, and it's eight o'clock in the evening.",
        [env(street_lights="on", time_from="19:45", time_to="20:15", **CLEAR), only(env=True)],
        [lighting(street_lights="on"), clock("20:00")],
    ),
    impossible("appearance", "direct", "half_past_twenty_five", EMOJI, "⏰ 25:30 pls", [clock("25:30")]),
    # indirect
    case(
        "appearance",
        "indirect",
        "shouts_at_dusk",
        MEDIC,
        "Most of our shouts on this road come in at dusk, just as the light's going — set the scene up for that.",
        [env(time_from="18:30", time_to="21:00", **CLEAR), only(env=True)],
        [clock("dusk")],
    ),
    case(
        "appearance",
        "indirect",
        "cones_that_stand_out",
        LOLLIPOP,
        "The little ones can't pick those cones out against the road — they want to be a colour that really "
        "stands out.",
        [looks(STANDS_OUT, CONE, every=True, min_count=3, tolerance=0.15), only(CONE)],
        [paint(category=CONE, colour="yellow")],
        setup=[CONES_MORNING_PLANNED],
    ),
    case(
        "appearance",
        "indirect",
        "night_shift",
        CABBIE,
        "I do the night shift, that's when the punters come out — make it about eleven at night.",
        [env(time_from="22:30", time_to="23:30", **CLEAR), only(env=True)],
        [clock("23:00")],
    ),
    case(
        "appearance",
        "indirect",
        "riders_in_the_murk",
        CYCLIST,
        "Riders get hit when drivers can't see them in the murk — give me a foggy early morning to test that.",
        [env(weather=["fog"], time_from="05:00", time_to="09:30"), only(env=True)],
        [weather("fog", 0.6), clock("07:00")],
    ),
    impossible(
        "appearance",
        "indirect",
        "hailstorm",
        IRISH,
        "Sure it's not proper Irish weather without a bit of hail — give us a hailstorm there.",
        [weather("hail")],
    ),
    case(
        "appearance",
        "indirect",
        "mail_car_white",
        SOUTHERN,
        "That SUV's fixin' to be the mail car, so it oughta be white like the real ones.",
        [looks("white", asset=SUV), only(assets=[SUV])],
        [paint([SUV], colour="white")],
    ),
    case(
        "appearance",
        "indirect",
        "degraded_visibility",
        DATA,
        "exp_03: visibility degraded via snowfall; all other env params unchanged",
        [env(weather=["snow"], **NOON), only(env=True)],
        [weather("snow")],
    ),
    case(
        "appearance",
        "indirect",
        "night_match",
        COMMENTATOR,
        "It's a night match under the lights, folks — kick-off at nine in the evening!",
        [env(time_from="20:45", time_to="21:15", **CLEAR), only(env=True)],
        [clock("21:00")],
    ),
    case(
        "appearance",
        "indirect",
        "headlights_on",
        EMOJI,
        "🚗💡 on pls, can't see 👀",
        [env(vehicle_lights="on", **NOON), only(env=True)],
        [lighting(vehicle_lights="on")],
    ),
    # vague
    case(
        "appearance",
        "vague",
        "late_calls",
        MEDIC,
        "bit darker… like when we get the late calls",
        [only(env=True)],
        [clock("22:00")],
        alternatives=[[env(night=True)], [env(exposure_max=0.8)]],
    ),
    case(
        "appearance",
        "vague",
        "home_time",
        LOLLIPOP,
        "home time crossing... the afternoon one",
        [env(time_from="14:30", time_to="16:30", **CLEAR), only(env=True)],
        [clock("15:15")],
    ),
    case(
        "appearance",
        "vague",
        "taxi_yellow_ish",
        CABBIE,
        "the SUV... flashier. New York cab-ish",
        [looks(TAXI_YELLOW, asset=SUV), only(assets=[SUV])],
        [paint([SUV], colour="yellow")],
    ),
    case(
        "appearance",
        "vague",
        "wet_not_a_downpour",
        CYCLIST,
        "rain? wet roads for the dooring test — not a downpour though",
        [env(weather=["rain"], intensity_min=0.05, intensity_max=0.7, **NOON), only(env=True)],
        [weather("rain", 0.4)],
    ),
    case(
        "appearance",
        "vague",
        "soft_day",
        IRISH,
        "a grand soft day… bit of drizzle, like",
        [env(weather=["rain"], intensity_max=0.5, **NOON), only(env=True)],
        [weather("rain", 0.3)],
    ),
    case(
        "appearance",
        "vague",
        "woodsy_benches",
        SOUTHERN,
        "them benches… somethin' more woodsy lookin'",
        [only(BENCH_KIND)],
        [paint(category=BENCH_KIND, material="wood")],
        alternatives=[
            [looks(category=BENCH_KIND, material="wood", every=True)],
            [looks("brown", BENCH_KIND, every=True)],
        ],
    ),
    case(
        "appearance",
        "vague",
        "tod_dawn",
        DATA,
        "tod=dawn",
        [env(time_from="05:30", time_to="07:00", **CLEAR), only(env=True)],
        [clock("dawn")],
    ),
    case(
        "appearance",
        "vague",
        "clouds_roll_in",
        COMMENTATOR,
        "and the clouds roll in over the ground…",
        [env(weather=["cloudy"], **NOON), only(env=True)],
        [weather("cloudy")],
    ),
    case(
        "appearance",
        "vague",
        "snowflakes",
        EMOJI,
        "❄️❄️❄️",
        [env(weather=["snow"], **NOON), only(env=True)],
        [weather("snow")],
    ),
    # erroneous
    case(
        "appearance",
        "erroneous",
        "response_car_yellow",
        MEDIC,
        "paint the fist car in lot b yelow like our response cars",
        [looks("yellow", asset=CAR_1), only(assets=[CAR_1])],
        [paint([CAR_1], colour="yellow")],
    ),
    impossible(
        "appearance",
        "erroneous",
        "paint_the_library",
        LOLLIPOP,
        "can you paint the libary bulding bright yelow so the kids can find it",
        [paint(["Library"], colour="yellow")],
    ),
    case(
        "appearance",
        "erroneous",
        "two_in_the_morning",
        CABBIE,
        "make it nite time, arond 2 in the mornin, thats when the drunk fares come out",
        [env(time_from="01:30", time_to="02:30", **CLEAR), only(env=True)],
        [clock("02:00")],
    ),
    case(
        "appearance",
        "erroneous",
        "street_lights_potholes",
        CYCLIST,
        "turn the stret lights on, riders cant see the potholes in the drak",
        [env(street_lights="on"), only(env=True)],
        [lighting(street_lights="on")],
    ),
    case(
        "appearance",
        "erroneous",
        "council_green_bench",
        IRISH,
        "pant the bnech grene there, the council colour, so it is",
        [looks("green", asset=BENCH), only(assets=[BENCH])],
        [paint([BENCH], colour="green")],
    ),
    case(
        "appearance",
        "erroneous",
        "rainin_and_headlights",
        SOUTHERN,
        "make it rainin' an turn them car headlites on y'all, cant hardly see nothin",
        [env(weather=["rain"], vehicle_lights="on"), only(env=True)],
        [weather("rain"), lighting(vehicle_lights="on")],
    ),
    case(
        "appearance",
        "erroneous",
        "snow_and_clock_kv",
        DATA,
        "wether=snow intesity=0.3; tiem=17:00",
        [
            env(weather=["snow"], intensity_min=0.2, intensity_max=0.4, time_from="16:45", time_to="17:15"),
            only(env=True),
        ],
        [weather("snow", 0.3), clock("17:00")],
    ),
    case(
        "appearance",
        "erroneous",
        "second_half_sun",
        COMMENTATOR,
        "and the sun comes out — clear skys for the secnd half!",
        [env(weather=["clear"], **NOON), only(env=True)],
        [weather("clear")],
        setup=[RAIN_FIRST_HALF_GIVEN],
    ),
    case(
        "appearance",
        "erroneous",
        "stop_sign_purple",
        EMOJI,
        "🛑 sing → purpel plz 💜",
        [looks("purple", asset=STOP_SIGN), only(assets=[STOP_SIGN])],
        [paint([STOP_SIGN], colour="purple")],
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
