"""The fifteenth practice suite: 250 cases in the words of nine new kinds of user, from the campus world alone.

`python -m drivetwin.evals.practice15_source` writes `suites/practice15.jsonl` (tag `practice15`, ids
`practice15.<task>.<grade>.<name>`), one JSON object per line, from the plain case list below.

Voices: a stunt coordinator planning a car-chase rehearsal ("hero car", "picture car", "marks",
"take two"), a city arborist (canopy, root zones, planting, felling), an accessibility auditor
checking the campus for wheelchair users (clear paths, kerbs, somewhere to rest), a delivery-van
dispatcher ("units", "bays", "staging", "the drop"), an elderly first-time computer user who writes
long polite messages, a teenager texting in slang and abbreviations, a translator whose English is
formal and slightly odd, a data scientist building edge cases, and a tired night-shift QA engineer.
Prompts mix short chat turns with one-to-three sentence requests, stories that carry the request,
reasons, hedges, references back to earlier turns, numbers in words and digits, metres, feet and car
lengths, relations (beside, across from, between, behind, in front of, along), scopes (a lane, a lot,
a sidewalk, a side of a road, a landmark), behaviours of vehicles and pedestrians (speeds, circling,
stopping, crossing), weather and clock times, questions (which must change nothing), negation and
exceptions. The erroneous grade carries realistic typos, autocorrect swaps, missing spaces, dropped
words and non-native grammar.

Counts: 7 tasks x 4 grades, 250 in all (65 direct, 64 indirect, 63 vague, 58 erroneous): search,
addition, removal, positioning and appearance hold 8 or 9 cases a cell, and moving and arrangement,
weighted a little, 9 or 10. 34 cases are multi-turn (15 with a planned earlier turn), 18
compound (the reference makes two calls or more), and 20 (8 %) impossible, tagged `impossible`, where
the right outcome is a refusal that changes nothing: a campus hospital, an oak grove, a camera
helicopter, 75 pedestrians at once, a palm tree inside the Library; removing the crossroads, the
fountain or the ego; a tree on the JTEKT roof, the hero car at x = 250, the SUV inside the Student
Union; 300 km/h, a tree driving circles, a bench moved 500 m east; a 100 m ring, a grid of 150 cones;
a see-through hero car, hail, 26:15, a repainted Library.

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

TAG = "practice15"

# --- The campus world, as these cases use it --------------------------------------------------
# Main Street runs east-west (eastbound lane y = -1.75, westbound y = +1.75, kerbs at y = +-3.5,
# sidewalks at y = +-5.5); Campus Drive runs north-south (northbound x = +1.75, southbound -1.75).
# The world spans x -110..110 and y -90..90; it is noon and clear.
EGO = "ego"  # the hero car: drives main_eastbound at 5 m/s from (-60, -1.75), facing east
BENCH = "bench_1"  # at the bus stop, (-26, -6.9), facing west
BIN = "trash_bin_1"  # on the bus-stop sidewalk, (-33.5, -5.5)
HYDRANT = "fire_hydrant_1"  # north sidewalk of Main Street just east of the crossroads, (16, 5.5)
STOP_SIGN = "stop_sign_1"  # south sidewalk before the west crosswalk, (-13.5, -5.5), facing east
CAR_1, SUV, CAR_2 = "passenger_car_1", "suv_1", "passenger_car_2"  # lot B, x 19 / 23 / 27, y -42, facing north
PARKED = (CAR_1, SUV, CAR_2)
LIGHT_SW, LIGHT_NE = "traffic_light_1", "traffic_light_2"  # (-9.5, -6.2) and (9.5, 6.2)
TREE_BUS_STOP, TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A = "tree_1", "tree_2", "tree_3", "tree_4"
# tree_1 (-26, -12) behind the bus stop, by the Library; tree_2 (70, 45) beside the fountain;
# tree_3 (85, 25) south-east of the fountain; tree_4 (-85, 50) just north of lot A.
TREES = (TREE_BUS_STOP, TREE_FOUNTAIN, TREE_EAST, TREE_LOT_A)
LAMP_LOT_A = "street_light_1"  # (-80, 5.8), beside the lot A entrance
LAMP_BUS_STOP = "street_light_4"  # (-38, -5.8), the lamp nearest the bus stop
# Lamps 1, 3, ... 11 stand on Main Street's north side (y = 5.8), 2, 4, ... 12 on its south side.
NORTH_SIDE_LAMPS = tuple(f"street_light_{n}" for n in range(1, 12, 2))
SOUTH_SIDE_LAMPS = tuple(f"street_light_{n}" for n in range(2, 13, 2))

LOT_A, LOT_B = "parking lot A", "parking lot B"  # areas: x -100..-70, y 14..44; x 15..62, y -46..-12
LOT_A_ENTRANCE, LOT_B_ENTRANCE = "parking lot A entrance", "parking lot B entrance"  # (-85, 3.5), (47, -3.5)
LIBRARY = "Library entrance"  # (-41, -15), faces north onto the library drop-off
JTEKT = "JTEKT building entrance"  # (37.5, 15), faces south onto the JTEKT drop-off
ENGINEERING = "Engineering Hall entrance"  # (-40, 15), faces south
UNION = "Student Union entrance"  # (42.5, -51), faces north onto lot B
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
TREE, BENCH_KIND, BIN_KIND, LAMP = "tree", "bench", "trash_bin", "street_light"
PED_SIGN, WORK_SIGN, STOP_KIND, SIGNAL = "pedestrian_sign", "construction_sign", "stop_sign", "traffic_light"
HYDRANT_KIND = "fire_hydrant"
CARS = [CAR, SUV_KIND]
MARKERS = [CONE, BOLLARD, BARRIER]
OBSTACLES = [CONE, BARRIER, RUBBLE, BOLLARD]
TRAFFIC = [CAR, SUV_KIND, BUS, TRUCK, MOTORBIKE]

NOON = {"time_from": "11:30", "time_to": "12:30"}  # the world's clock, pinned where a prompt leaves it
CLEAR = {"weather": ["clear"]}
BRIGHT = ["red", "yellow", "orange", "pink", "cyan", "green", "purple", "gold"]  # colours that stand out
DARK = ["black", "navy", "maroon", "brown", "grey", "teal"]


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


def move_group(assets: Sequence[str], **extra: Any) -> Json:
    return call("move_asset", assets=list(assets), **extra)


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


def accepted() -> Json:
    return {"kind": "status", "accepted": True}


def refused() -> Json:
    return {"kind": "status", "accepted": False}


def event_played(actor: str, kind: str, seconds: float) -> Json:
    """The storyboard gives `actor` (an id or a category) a manoeuvre of `kind` that starts within `seconds`."""
    return {"kind": "scenario", "seconds": seconds,
            "expect": [{"kind": "event", "actor": actor, "manoeuvre": kind}]}


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
TRUCK_IN_LOT_A = turn("Stage one of our vans in parking lot A.", add(TRUCK, where=loc("at", LOT_A)))
CONES_AHEAD = turn("put 4 cones in the road 20 m in front of the ego",
                   add(CONE, 4, where=loc("in_front_of", EGO, distance=20)))
PERSON_AT_BUS_STOP = turn("Add a woman waiting at the bus stop.", add(PERSON, where=loc("at", BUS_STOP)))
CAR_AHEAD = turn("Put a car 25 metres ahead of the ego in its lane, driving at 5 m/s.",
                 add(CAR, where=loc("at", EGO, along_m=25), behaviour=drive(5)))


def search_cases() -> list[Json]:
    t = "search"
    return [
        # direct
        question(t, "direct", "count_street_lights", "How many street lights are there in the scene?",
                 says(any_of=["12", "twelve"]), [find(category=LAMP)]),
        question(t, "direct", "list_vehicles_with_positions",
                 "List every vehicle in the world with its coordinates, please. I'm writing the test matrix.",
                 says(all_of=[CAR_1, SUV, CAR_2]), [find(category="vehicles")]),
        question(t, "direct", "distance_ego_to_union",
                 "What's the straight-line distance from the ego car to the Student Union entrance?",
                 says(any_of=["113.7", "114", "113"]), [measure(UNION)]),
        question(t, "direct", "where_are_the_trees",
                 "Where are the trees? Give me the position of each one.",
                 says(all_of=["-26", "70", "85", "-85"]), [find(category=TREE)]),
        question(t, "direct", "weather_and_time", "What is the weather, and what time is it in the scene?",
                 says(all_of=["clear", "12:00"]), [environment()]),
        question(t, "direct", "distance_of_new_bus",
                 "Please inform me at what distance the bus is standing from the ego.",
                 says(any_of=["30", "30.0"]), [measure("bus_1")],
                 setup=[turn("Please add one bus at the bus stop.", add(BUS, where=loc("at", BUS_STOP)))]),
        question(t, "direct", "closest_to_fountain", "which object is closest to the fountain",
                 says(all_of=[TREE_FOUNTAIN]), [find(nearest_to=FOUNTAIN)]),
        question(t, "direct", "hero_car_behaviour",
                 "Hero car check before the walk-through: what is the ego doing right now, and in which lane?",
                 says(all_of=[EASTBOUND], any_of=["drive_lane", "driving", "drives"]),
                 [properties(asset=EGO), find(category="ego_vehicle", on_lane=True)], compound=True),
        question(t, "direct", "count_trees_and_time",
                 "Two things: how many trees are there, and what's the time of day?",
                 says(any_of=["4", "four"], all_of=["12:00"]), [find(category=TREE), environment()], compound=True),
        # indirect
        question(t, "indirect", "benches_for_a_rest",
                 "I was wondering, before I change anything at all, whether there are any benches in this "
                 "little town of yours, and if so, where I might find them? Thank you so much.",
                 says(any_of=[BENCH, "bus stop", "-26"]), [find(category=BENCH_KIND)]),
        question(t, "indirect", "van_run_lot_b_to_union",
                 "One of my drivers will shuttle parcels from the lot B entrance to the Student Union doors. "
                 "How long is that run, as the crow flies?",
                 says(any_of=["47.7", "48", "47"]), [measure(LOT_B_ENTRANCE, UNION)]),
        question(t, "indirect", "anything_within_five_m_of_bus_stop",
                 "A wheelchair user will wait at the bus stop. I need to know what stands within five metres "
                 "of that spot.",
                 says(all_of=["bench", "trash bin"]), [find(near=BUS_STOP, within=5)]),
        question(t, "indirect", "signals_for_sampling",
                 "For my sampling frame I need the number of signalised poles, the actual traffic lights, "
                 "nothing else.",
                 says(any_of=["2", "two"]), [find(category=SIGNAL)]),
        question(t, "indirect", "canopy_spacing_library",
                 "I'm checking canopy spacing around the Library. Which tree is nearest its entrance, and how "
                 "far off is it?",
                 says(all_of=[TREE_BUS_STOP]), [find(category=TREE, nearest_to=LIBRARY)]),
        question(t, "indirect", "night_or_day",
                 "before i mess w the lights, is it night or day in there rn",
                 says(any_of=["day", "12:00", "noon", "midday"]), [environment()]),
        question(t, "indirect", "hydrant_side_of_street",
                 "I should be grateful to learn on which side of the principal street the fire hydrant is "
                 "standing, and where exactly.",
                 says(any_of=["5.5", "north"]), [find(category=HYDRANT_KIND)]),
        question(t, "indirect", "did_the_van_land_in_lot_a",
                 "ok so did the van from before actually end up in lot A? where is it exactly",
                 says(any_of=["truck_1", "truck"]), [find(category=TRUCK)], setup=[TRUCK_IN_LOT_A]),
        impossible(t, "indirect", "route_to_hospital",
                   "A van has to make an urgent drop at the campus hospital. How far is it from the ego?",
                   measure("hospital"), notes="there is no hospital on the campus"),
        # vague
        question(t, "vague", "what_is_by_the_fountain", "What is there to look at near the fountain, dear?",
                 says(all_of=["tree"]), [find(near=FOUNTAIN, within=20)]),
        question(t, "vague", "whats_in_lot_b", "whats even in lot b lol",
                 says(any_of=[SUV, CAR_1, CAR_2]), [find(near=LOT_B, within=25)]),
        question(t, "vague", "env_sanity_check", "sanity check. environment?",
                 says(all_of=["clear"]), [environment()]),
        question(t, "vague", "where_can_vans_park", "where can my drivers park around here?",
                 says(any_of=["parking lot A", "lot A", "parking lot B", "lot B"]), [landmarks(query="parking")]),
        question(t, "vague", "longest_straight", "what's the longest straight we've got for a run-up?",
                 says(any_of=["220", "Main Street"]), [lanes()]),
        question(t, "vague", "object_inventory", "give me the object inventory",
                 says(any_of=["25", "26"]), [find()]),
        question(t, "vague", "places_of_the_town", "I would be glad to know which places this town possesses.",
                 says(all_of=["fountain", "bus stop"]), [landmarks()]),
        question(t, "vague", "how_much_greenery", "how much greenery have we got?",
                 says(any_of=["4", "four"]), [find(category=TREE)]),
        question(t, "vague", "weather_after_my_change",
                 "and what's it like out there now?",
                 says(all_of=["rain"]), [environment()],
                 setup=[turn("Make it rain, please. A proper downpour.", weather("rain", 0.9), planned=True)]),
        # erroneous
        question(t, "erroneous", "cars_in_lot_b", "hw many cars r parked in lot b",
                 says(any_of=["2", "3", "two", "three"]), [find(category="vehicles", near=LOT_B, within=25)]),
        question(t, "erroneous", "where_is_bus_stop", "Could you plese tell me were the bus stop is located",
                 says(any_of=["-30", "Main Street"]), [landmarks(query="bus stop")]),
        question(t, "erroneous", "distance_to_east_gate", "Kindly to tell me the distnace from ego until east gate.",
                 says(any_of=["160", "160.0"]), [measure(EAST_GATE)]),
        question(t, "erroneous", "whats_the_weather", "whats teh weahter rn",
                 says(all_of=["clear"]), [environment()]),
        question(t, "erroneous", "nearest_lamp_lot_a", "nearest lamppost to lot A entrnace?",
                 says(all_of=[LAMP_LOT_A]), [find(category=LAMP, nearest_to=LOT_A_ENTRANCE)]),
        question(t, "erroneous", "cone_count", "count of trafic cones currently =?",
                 says(any_of=["0", "no", "none", "zero"]), [find(category=CONE)]),
        question(t, "erroneous", "how_many_vans_now", "how many vans r there now??",
                 says(any_of=["2", "two"]), [find(category=TRUCK)],
                 setup=[turn("park two delivery vans in lot A", add(TRUCK, 2, where=loc("at", LOT_A)), planned=True)]),
        impossible(t, "erroneous", "oak_grove_distance", "how far is teh oak grove from the libary?",
                   measure("oak grove", LIBRARY), notes="there is no oak grove"),
    ]


BUS_AT_STOP = turn("put a bus at the bus stop", add(BUS, where=loc("at", BUS_STOP)), planned=True)
BENCH_BY_FOUNTAIN = turn("Please put a bench beside the fountain.", add(BENCH_KIND, where=loc("next_to", FOUNTAIN)),
                         planned=True)


def addition_cases() -> list[Json]:
    t = "addition"
    return [
        # direct
        case(t, "direct", "truck_at_lot_b_entrance", "Add a delivery truck at the parking lot B entrance.",
             [delta(TRUCK, 1, 1), near(LOT_B_ENTRANCE, 8, TRUCK), only(TRUCK)],
             [add(TRUCK, where=loc("at", LOT_B_ENTRANCE))]),
        case(t, "direct", "car_25m_ahead_driving",
             "Add a car 25 m ahead of the hero car (that's the ego), same lane, driving at 5 m/s.",
             [delta(CARS, 1, 1), in_lane(EASTBOUND, CARS), relative("in_front_of", EGO, CARS, max_distance=35,
                                                                   tolerance_deg=20),
              does("drive_lane", CARS, speed_min=4.5, speed_max=5.5), only(CAR, SUV_KIND)],
             [add(CAR, where=loc("at", EGO, along_m=25), behaviour=drive(5))]),
        case(t, "direct", "tree_next_to_fountain", "Plant a tree next to the fountain.",
             [delta(TREE, 1, 1), near(FOUNTAIN, 6, TREE), only(TREE)],
             [add(TREE, where=loc("next_to", FOUNTAIN))]),
        case(t, "direct", "bench_on_library_sidewalk", "Add a bench on the sidewalk outside the Library entrance.",
             [delta(BENCH_KIND, 1, 1), near(LIBRARY, 12, BENCH_KIND), on(["sidewalk"], BENCH_KIND), only(BENCH_KIND)],
             [add(BENCH_KIND, where=loc("on_sidewalk", LIBRARY))]),
        case(t, "direct", "two_people_by_the_bus", "ok now add 2 ppl waiting next to the bus",
             [delta(PERSON, 2, 2), near(BUS_STOP, 12, PERSON, every=True), only(PERSON)],
             [add(PERSON, 2, where=loc("next_to", "bus_1"))], setup=[BUS_AT_STOP]),
        case(t, "direct", "bus_at_bus_stop_polite",
             "Good afternoon. I would like, if it is no trouble at all, to add one bus at the bus stop. "
             "Thank you kindly, Margaret.",
             [delta(BUS, 1, 1), near(BUS_STOP, 10, BUS), only(BUS)],
             [add(BUS, where=loc("at", BUS_STOP))]),
        case(t, "direct", "motorcycle_and_cyclist",
             "Spawn one motorcycle in the westbound lane of Main Street driving at 15 m/s, plus one cyclist in "
             "the eastbound lane at 6.",
             [delta(MOTORBIKE, 1, 1), delta(BIKE, 1, 1), in_lane(WESTBOUND, MOTORBIKE),
              does("drive_lane", MOTORBIKE, speed_min=14, speed_max=16, lane=WESTBOUND),
              does("drive_lane", BIKE, speed_min=5.5, speed_max=6.5, lane=EASTBOUND), only(MOTORBIKE, BIKE)],
             [add(MOTORBIKE, where=loc("in_lane", WESTBOUND), behaviour=drive(15, WESTBOUND)),
              add(BIKE, where=loc("in_lane", EASTBOUND), behaviour=drive(6, EASTBOUND))], compound=True),
        case(t, "direct", "hydrant_beside_jtekt", "Please add a fire hydrant beside the JTEKT building entrance.",
             [delta(HYDRANT_KIND, 1, 1), near(JTEKT, 5, HYDRANT_KIND), only(HYDRANT_KIND)],
             [add(HYDRANT_KIND, where=loc("next_to", JTEKT))]),
        case(t, "direct", "cone_at_coordinates", "add one more cone at x=20, y=-1.75",
             [delta(CONE, 1, 1), near(None, 1, CONE, point=(20, -1.75)), only(CONE)],
             [add(CONE, where=xy(20, -1.75))], setup=[CONES_AHEAD]),
        # indirect
        case(t, "indirect", "picture_car_and_extra_at_library",
             "For the chase we need a parked picture car waiting at the Library drop-off for the hero car to "
             "swerve round, and one extra standing right beside it.",
             [delta(CARS, 1, 1), delta(PERSON, 1, 1), near(LIBRARY, 10, CARS), near(LIBRARY, 12, PERSON),
              does("parked", CARS), only(CAR, SUV_KIND, PERSON)],
             [add(CAR, where=loc("at", LIBRARY)), add(PERSON, where=loc("next_to", "passenger_car_3"))],
             compound=True),
        case(t, "indirect", "somewhere_to_rest_at_bus_stop",
             "Wheelchair users waiting for the shuttle have nowhere to rest. Give them somewhere to sit at "
             "the bus stop.",
             [delta(BENCH_KIND, 1, None), near(BUS_STOP, 8, BENCH_KIND), only(BENCH_KIND)],
             [add(BENCH_KIND, where=loc("at", BUS_STOP))]),
        case(t, "indirect", "van_due_at_jtekt",
             "I've got a van due at JTEKT in five minutes, have it already parked at their doors.",
             [delta(TRUCK, 1, 1), near(JTEKT, 10, TRUCK), only(TRUCK)],
             [add(TRUCK, where=loc("at", JTEKT))]),
        case(t, "indirect", "two_shade_trees_fountain",
             "The lawn round the fountain looks bare, to be honest. It could take two more shade trees.",
             [delta(TREE, 2, 2), near(FOUNTAIN, 15, TREE, every=True), only(TREE)],
             [add(TREE, 2, where=loc("at", FOUNTAIN))]),
        case(t, "indirect", "jaywalker_20m_ahead",
             "I need an edge case where a pedestrian steps out into the road about 20 m in front of the ego, "
             "not at a crossing.",
             [delta(PERSON, 1, 1), does("jaywalk", PERSON, crosses_lane=EASTBOUND), only(PERSON)],
             [add(PERSON, behaviour={"kind": "jaywalk", "ahead": 20})]),
        case(t, "indirect", "grandson_wants_eastbound_traffic",
             "My grandson says the street is far too empty for his driving practice. Could you please put some "
             "more cars driving along Main Street going east? Three would be lovely. Thank you, dear.",
             [delta(CARS, 3, 3), in_lane(EASTBOUND, CARS), does("drive_lane", CARS, min_count=3, lane=EASTBOUND),
              only(CAR, SUV_KIND)],
             [add(CAR, 3, where=loc("in_lane", EASTBOUND), behaviour=drive(lane=EASTBOUND))]),
        case(t, "indirect", "cyclist_northward",
             "It would be needed that a cyclist is present, riding in the northward direction on Campus Drive.",
             [delta(BIKE, 1, 1), does("drive_lane", BIKE, lane=NORTHBOUND), only(BIKE)],
             [add(BIKE, where=loc("in_lane", NORTHBOUND), behaviour=drive(lane=NORTHBOUND))]),
        case(t, "indirect", "one_more_cone_for_repro",
             "the cones from the last step aren't enough for the repro. need one more right next to them",
             [delta(CONE, 1, 1), near(None, 5, CONE, scope="added", point=(-40, -1.75)), only(CONE)],
             [add(CONE, where=loc("next_to", "traffic_cone_1"))], setup=[CONES_AHEAD]),
        impossible(t, "indirect", "camera_helicopter",
                   "We want an aerial angle on the chase, so park the camera helicopter over the crossroads.",
                   add("helicopter", where=loc("at", JUNCTION)), notes="the catalog has no helicopter"),
        # vague
        case(t, "vague", "some_traffic", "add sum traffic",
             [delta(TRAFFIC, 1, None), does("drive_lane", TRAFFIC), only(*TRAFFIC)],
             [add(CAR, 2, where=loc("in_lane", WESTBOUND), behaviour=drive(lane=WESTBOUND))]),
        case(t, "vague", "something_for_the_rubbish",
             "Thank you, that looks lovely. Could you put something next to it for people's rubbish, so they "
             "can tidy up after themselves?",
             [delta(BIN_KIND, 1, 1), near(FOUNTAIN, 10, BIN_KIND), only(BIN_KIND)],
             [add(BIN_KIND, where=loc("next_to", "bench_2"))], setup=[BENCH_BY_FOUNTAIN]),
        case(t, "vague", "somewhere_to_sit_library", "somewhere to sit near the library?",
             [delta(BENCH_KIND, 1, None), near(LIBRARY, 15, BENCH_KIND), only(BENCH_KIND)],
             [add(BENCH_KIND, where=loc("at", LIBRARY))]),
        case(t, "vague", "bodies_on_sidewalk",
             "Need a few bodies on the sidewalk for background action during the chase.",
             [delta(PERSON, 2, 8), on(["sidewalk"], PERSON), only(PERSON)],
             [add(PERSON, 3, where=loc("on_sidewalk", BUS_STOP))]),
        case(t, "vague", "another_unit_next_to_it", "and another one next to it pls",
             [delta(TRUCK, 1, 1), near("truck_1", 8, TRUCK, scope="added"), only(TRUCK)],
             [add(TRUCK, where=loc("next_to", "truck_1"))], setup=[TRUCK_IN_LOT_A]),
        case(t, "vague", "sign_for_the_crossing",
             "And perhaps a little something to make the crossing safer for the children? A sign, maybe?",
             [delta(PED_SIGN, 1, None), near(JUNCTION, 10, PED_SIGN), only(PED_SIGN)],
             [add(PED_SIGN, where=loc("at", WEST_CROSSWALK))]),
        case(t, "vague", "robot_on_the_road", "throw a robot on the road somewhere",
             [delta(ROBOT, 1, 1), in_lane(None, ROBOT), only(ROBOT)],
             [add(ROBOT, where=loc("in_lane", NORTHBOUND))]),
        case(t, "vague", "more_obstacles_junction", "need more obstacles near the junction",
             [delta(OBSTACLES, 1, None), near(JUNCTION, 20, OBSTACLES, every=True), only(*OBSTACLES)],
             [add(BARRIER, 2, where=loc("at", JUNCTION))]),
        case(t, "vague", "persons_walking_over_street",
             "Some persons should be walking over the street at the crossing.",
             [delta(PERSON, 1, None), does(["cross_road", "jaywalk"], PERSON), only(PERSON)],
             [add(PERSON, 2, where=loc("at", WEST_CROSSWALK), behaviour={"kind": "cross_road"})]),
        # erroneous
        case(t, "erroneous", "bsu_at_bus_stpo", "put a bsu at the bus stpo",
             [delta(BUS, 1, 1), near(BUS_STOP, 10, BUS), only(BUS)],
             [add(BUS, where=loc("at", BUS_STOP))]),
        case(t, "erroneous", "bench_by_fountian", "Please ad one more bench by the fountian, thank you.",
             [delta(BENCH_KIND, 1, 1), near(FOUNTAIN, 6, BENCH_KIND), only(BENCH_KIND)],
             [add(BENCH_KIND, where=loc("next_to", FOUNTAIN))]),
        case(t, "erroneous", "truck_which_is_parking", "Add please one truck which is parking in the lot A.",
             [delta(TRUCK, 1, 1), near(LOT_A, 1, TRUCK), does("parked", TRUCK), only(TRUCK)],
             [add(TRUCK, where=loc("at", LOT_A))]),
        case(t, "erroneous", "add3_cones_infront", "add3 cones infront of ego",
             [delta(CONE, 3, 3), relative("in_front_of", EGO, CONE, max_distance=30), only(CONE)],
             [add(CONE, 3, where=loc("in_front_of", EGO, distance=15))]),
        case(t, "erroneous", "trcuk_westboud_10",
             "need a delivery trcuk in the westboud lane headed west at 10m/s",
             [delta(TRUCK, 1, 1), does("drive_lane", TRUCK, lane=WESTBOUND, speed_min=9, speed_max=11), only(TRUCK)],
             [add(TRUCK, where=loc("in_lane", WESTBOUND), behaviour=drive(10, WESTBOUND))]),
        case(t, "erroneous", "motorcyle_behnd_ego",
             "add a motorcyle behnd the ego car, two car lenghts back, driving same speed as it",
             [delta(MOTORBIKE, 1, 1), relative("behind", EGO, MOTORBIKE, max_distance=20, tolerance_deg=25),
              does("drive_lane", MOTORBIKE, speed_min=4.5, speed_max=5.5), only(MOTORBIKE)],
             [add(MOTORBIKE, where=loc("behind", EGO, distance=10), behaviour=drive(5))]),
        impossible(t, "erroneous", "palm_insde_library", "plant a palm tree insde the Library atrium",
                   add(TREE, where=xy(-41, -30)), notes="a spot inside a building"),
        impossible(t, "erroneous", "spawn_75_pedestrans", "spawn 75 pedestrans at the junction",
                   add(PERSON, 75, where=loc("at", JUNCTION)), notes="past the limit of one add and of the catalog"),
    ]


JUNK_AT_BUS_STOP = turn("Dump some cones and a couple of barriers by the bus stop for the roadworks scene.",
                        add(CONE, 4, where=loc("at", BUS_STOP)), add(BARRIER, 2, where=loc("at", BUS_STOP)))
PEOPLE_AT_BUS_STOP = turn("add 3 ppl at the bus stop", add(PERSON, 3, where=loc("at", BUS_STOP)), planned=True)
TWO_VANS_LOT_A = turn("Stage two vans in lot A for the morning round.", add(TRUCK, 2, where=loc("at", LOT_A)),
                      planned=True)
OTHER_LAMPS = tuple(f"street_light_{n}" for n in range(1, 13) if n != 4)


def removal_cases() -> list[Json]:
    t = "removal"
    return [
        # direct
        case(t, "direct", "fell_tree_3", "Remove tree_3, the one south-east of the fountain.",
             [gone(TREE_EAST), kept(TREE_FOUNTAIN), only(assets=[TREE_EAST])], [remove(TREE_EAST)]),
        case(t, "direct", "bin_at_bus_stop", "Take away the trash bin at the bus stop.",
             [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
        case(t, "direct", "suv_from_lot_b", "Remove the SUV from lot B.",
             [gone(SUV), kept(CAR_1, CAR_2), only(assets=[SUV])], [remove(SUV)]),
        case(t, "direct", "north_side_lamps", "delete all street lights on the north side of Main Street",
             [gone(*NORTH_SIDE_LAMPS), kept(*SOUTH_SIDE_LAMPS), only(assets=NORTH_SIDE_LAMPS)],
             [remove(*NORTH_SIDE_LAMPS)]),
        case(t, "direct", "clear_parked_cars", "Clear the parked cars out of lot B: both sedans and the SUV.",
             [gone(*PARKED), only(assets=PARKED)], [remove(*PARKED)]),
        case(t, "direct", "remove_stop_sign", "remove the stop sign",
             [gone(STOP_SIGN), only(assets=[STOP_SIGN])], [remove(STOP_SIGN)]),
        impossible(t, "direct", "fountain_noise",
                   "Would you please take away the fountain? The noise of the water bothers me terribly. "
                   "With many thanks, Arthur.",
                   remove("fountain"), notes="the fountain is a landmark, not an asset"),
        case(t, "direct", "remove_old_hydrant",
             "Please remove the old fire hydrant, the one near the crossroads, not the new one.",
             [gone(HYDRANT), kept("fire_hydrant_2"), only(assets=[HYDRANT])], [remove(HYDRANT)],
             setup=[turn("Please add a second fire hydrant beside the JTEKT entrance.",
                         add(HYDRANT_KIND, where=loc("next_to", JTEKT)))]),
        case(t, "direct", "all_lamps_but_bus_stop",
             "Remove every street light except the one nearest the bus stop.",
             [gone(*OTHER_LAMPS), kept(LAMP_BUS_STOP), only(assets=OTHER_LAMPS)], [remove(*OTHER_LAMPS)]),
        # indirect
        case(t, "indirect", "lamp_where_hero_swings_out",
             "The lamp post at the lot A entrance is right where the hero car swings out. Get rid of it.",
             [gone(LAMP_LOT_A), only(assets=[LAMP_LOT_A])], [remove(LAMP_LOT_A)]),
        case(t, "indirect", "clear_bus_stop_for_wheelchairs",
             "The bus stop sidewalk has to be clear for wheelchairs: the bin has to go, and the bench as well.",
             [gone(BIN, BENCH), only(assets=[BIN, BENCH])], [remove(BIN), remove(BENCH)], compound=True),
        case(t, "indirect", "diseased_tree_by_library",
             "The tree behind the bus stop, by the Library, is diseased and has to come down.",
             [gone(TREE_BUS_STOP), only(assets=[TREE_BUS_STOP])], [remove(TREE_BUS_STOP)]),
        case(t, "indirect", "suv_hogs_middle_bay",
             "My drivers keep moaning that the SUV hogs the middle bay in lot B. Tow it away.",
             [gone(SUV), kept(CAR_1, CAR_2), only(assets=[SUV])], [remove(SUV)]),
        case(t, "indirect", "cones_block_repro", "those cones from the last step are blocking my repro, lose them",
             [count(CONE, 0, 0), only(CONE)], [remove(category=CONE)], setup=[CONES_AHEAD]),
        case(t, "indirect", "empty_street_baseline",
             "For the empty-street baseline I need zero parked vehicles anywhere. The ego stays, obviously.",
             [count(CARS, 0, 0), kept(EGO), only(CAR, SUV_KIND)], [remove(*PARKED)]),
        case(t, "indirect", "stop_sign_confuses_me",
             "That stop sign near the crossing confuses me every single time I look at it. I would much rather "
             "it were not there at all, if that is allowed.",
             [gone(STOP_SIGN), only(assets=[STOP_SIGN])], [remove(STOP_SIGN)]),
        case(t, "indirect", "hydrant_disturbs_view",
             "The hydrant is disturbing the view onto the crossroads; it should be taken away.",
             [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
        case(t, "indirect", "keep_just_one_person", "nvm thats too many ppl, keep just one",
             [delta(PERSON, -2, -2), count(PERSON, 1, 1), only(PERSON)], [remove(category=PERSON, count=2)],
             setup=[PEOPLE_AT_BUS_STOP]),
        # vague
        case(t, "vague", "thin_out_trees", "thin out the trees a bit",
             [delta(TREE, -3, -1), only(TREE)], [remove(TREE_EAST)]),
        case(t, "vague", "clear_out_lot_b", "clear out lot b",
             [gone(*PARKED), only(CAR, SUV_KIND)], [remove(*PARKED)]),
        case(t, "vague", "junk_by_bus_stop", "ok get rid of all that junk by the bus stop",
             [count(CONE, 0, 0), count(BARRIER, 0, 0), kept(BENCH, BIN), only(CONE, BARRIER)],
             [remove(category=CONE), remove(category=BARRIER)], setup=[JUNK_AT_BUS_STOP], compound=True),
        case(t, "vague", "signage_west_crosswalk", "lose the signage round the west crosswalk",
             [gone(STOP_SIGN), only(assets=[STOP_SIGN, LIGHT_SW])], [remove(STOP_SIGN)]),
        case(t, "vague", "fewer_cars_lot_b", "fewer cars in lot B",
             [delta(CARS, -3, -1), only(CAR, SUV_KIND)], [remove(CAR_2)]),
        case(t, "vague", "fewer_poles",
             "It all feels so crowded on the main road. Could we have a little less in the way of poles along "
             "the street, do you think?",
             [delta([LAMP, SIGNAL, STOP_KIND], None, -1), only(LAMP, SIGNAL, STOP_KIND)],
             [remove(category=LAMP, near=BUS_STOP, count=2)]),
        case(t, "vague", "van_called_out", "one of them got called out. pull it",
             [delta(TRUCK, -1, -1), only(TRUCK)], [remove(category=TRUCK, count=1)], setup=[TWO_VANS_LOT_A]),
        case(t, "vague", "drop_the_greenery", "drop the greenery",
             [count(TREE, 0, 0), only(TREE)], [remove(category=TREE)]),
        # erroneous
        case(t, "erroneous", "delet_suv_n_stop_sign", "delet the suv n the stop sign pls",
             [gone(SUV, STOP_SIGN), only(assets=[SUV, STOP_SIGN])], [remove(SUV), remove(STOP_SIGN)], compound=True),
        case(t, "erroneous", "remvoe_tree_2", "remvoe tree_2",
             [gone(TREE_FOUNTAIN), only(assets=[TREE_FOUNTAIN])], [remove(TREE_FOUNTAIN)]),
        case(t, "erroneous", "bench_awy_from_bustop", "Please take the bench awy from the bustop, its in the way.",
             [only(assets=[BENCH])], [remove(BENCH)],
             alternatives=[[gone(BENCH)], [moved(BENCH, 5)]]),
        case(t, "erroneous", "all_of_the_cone_on_road",
             "Remove please all of the cone which are standing on the road.",
             [count(CONE, 0, 0), only(CONE)], [remove(category=CONE)], setup=[CONES_AHEAD]),
        case(t, "erroneous", "sedans_outta_lot_b", "pull both sedans outta lot B but leave teh suv",
             [gone(CAR_1, CAR_2), kept(SUV), only(assets=[CAR_1, CAR_2])], [remove(CAR_1, CAR_2)]),
        case(t, "erroneous", "vehicles_at_car_park", "The vehicles at the car park, these should not be existing anymore.",
             [gone(*PARKED), kept(EGO), only(CAR, SUV_KIND)], [remove(*PARKED)]),
        impossible(t, "erroneous", "remove_intersection", "remove the main intersection, we need one long straigth road",
                   remove(JUNCTION), notes="roads and the crossroads are not assets"),
        impossible(t, "erroneous", "remove_teh_ego", "remove teh ego vehicle for this run",
                   remove(EGO), notes="the ego cannot be removed"),
    ]


BUS_IN_LOT_A = turn("add a bus in lot A", add(BUS, where=loc("at", LOT_A)), planned=True)
ROBOT_IN_LOT_B = turn("add a robot in lot b", add(ROBOT, where=loc("at", LOT_B)), planned=True)


def positioning_cases() -> list[Json]:
    t = "positioning"
    return [
        # direct
        case(t, "direct", "suv_at_lot_b_entrance", "Place the SUV at the parking lot B entrance.",
             [near(LOT_B_ENTRANCE, 8, asset=SUV), only(assets=[SUV])],
             [place(SUV, loc("at", LOT_B_ENTRANCE))]),
        case(t, "direct", "ego_on_first_mark", "Put the ego at x = -90, y = -1.75. That's our first mark.",
             [near(None, 1, asset=EGO, point=(-90, -1.75)), only(assets=[EGO])],
             [place(EGO, xy(-90, -1.75))]),
        case(t, "direct", "bench_onto_library_sidewalk",
             "Move the bench onto the sidewalk in front of the Library entrance.",
             [near(LIBRARY, 12, asset=BENCH), on(["sidewalk"], asset=BENCH), only(assets=[BENCH])],
             [place(BENCH, loc("on_sidewalk", LIBRARY))]),
        case(t, "direct", "transplant_tree_4", "Transplant tree_4 to the spot next to the fountain.",
             [near(FOUNTAIN, 6, asset=TREE_LOT_A), only(assets=[TREE_LOT_A])],
             [place(TREE_LOT_A, loc("next_to", FOUNTAIN))]),
        case(t, "direct", "car_1_northbound", "put passenger_car_1 in the northbound lane of campus drive",
             [in_lane(NORTHBOUND, asset=CAR_1), only(assets=[CAR_1])],
             [place(CAR_1, loc("in_lane", NORTHBOUND))]),
        case(t, "direct", "bin_next_to_bench", "place trash_bin_1 next to bench_1",
             [near(BENCH, 2.5, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", BENCH))]),
        case(t, "direct", "hydrant_by_sign_bin_by_bench",
             "Could you put the fire hydrant beside the stop sign, please, and the rubbish bin beside the bench? "
             "Thank you.",
             [near(STOP_SIGN, 3, asset=HYDRANT), near(BENCH, 2.5, asset=BIN), only(assets=[HYDRANT, BIN])],
             [place(HYDRANT, loc("next_to", STOP_SIGN)), place(BIN, loc("next_to", BENCH))], compound=True),
        case(t, "direct", "car_2_behind_ego",
             "Please position passenger_car_2 behind the ego, at a distance of approximately two car lengths.",
             [relative("behind", EGO, asset=CAR_2, max_distance=16, tolerance_deg=30), only(assets=[CAR_2])],
             [place(CAR_2, loc("behind", EGO, distance=9))]),
        case(t, "direct", "suv_exact_facing_east", "Set suv_1 at exactly (30, -1.75), facing east.",
             [near(None, 1, asset=SUV, point=(30, -1.75)), in_lane(EASTBOUND, asset=SUV, aligned=True),
              only(assets=[SUV])],
             [place(SUV, xy(30, -1.75), yaw_deg=0)]),
        # indirect
        case(t, "indirect", "hero_car_at_main_gate", "For take one the hero car should start right at the main gate.",
             [near(MAIN_GATE, 8, asset=EGO), only(assets=[EGO])], [place(EGO, loc("at", MAIN_GATE))]),
        case(t, "indirect", "bench_outside_engineering",
             "People coming out of Engineering Hall need a bench right outside the door, not way over by the "
             "bus stop.",
             [only(BENCH_KIND)], [place(BENCH, loc("at", ENGINEERING))],
             alternatives=[[near(ENGINEERING, 8, asset=BENCH)],
                           [delta(BENCH_KIND, 1, 1), near(ENGINEERING, 8, BENCH_KIND, scope="added")]]),
        case(t, "indirect", "van_staged_at_union",
             "That van needs to be staged at the Student Union doors for the 9 o'clock drop.",
             [near(UNION, 12, TRUCK), only(TRUCK)], [place("truck_1", loc("at", UNION))], setup=[TRUCK_IN_LOT_A]),
        case(t, "indirect", "replant_tree_by_engineering",
             "The tree up by lot A is too close to the cars' turning circle. Replant it beside the Engineering "
             "Hall entrance instead.",
             [near(ENGINEERING, 8, asset=TREE_LOT_A), only(assets=[TREE_LOT_A])],
             [place(TREE_LOT_A, loc("next_to", ENGINEERING))]),
        case(t, "indirect", "swap_suv_and_car_1",
             "Edge case for the bay detector: swap the SUV and passenger_car_1, so each one sits in the other's "
             "bay.",
             [near(None, 0.6, asset=SUV, point=(19, -42)), near(None, 0.6, asset=CAR_1, point=(23, -42)),
              only(assets=[SUV, CAR_1])],
             [place(CAR_1, xy(19, -30)), place(SUV, xy(19, -42), yaw_deg=90), place(CAR_1, xy(23, -42), yaw_deg=90)],
             compound=True),
        case(t, "indirect", "hydrant_where_firefighters_reach",
             "the hydrant should be by the library so the firefighters can actually reach it lol",
             [near(LIBRARY, 10, asset=HYDRANT), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", LIBRARY))]),
        case(t, "indirect", "husband_sat_by_fountain",
             "My late husband always sat by the fountain in the afternoons. Could the bench be put there, please?",
             [near(FOUNTAIN, 6, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", FOUNTAIN))]),
        case(t, "indirect", "stop_sign_to_north_crosswalk",
             "It is desired that the stop sign stands at the north crosswalk instead of at its present place.",
             [near(NORTH_CROSSWALK, 8, asset=STOP_SIGN), only(assets=[STOP_SIGN])],
             [place(STOP_SIGN, loc("at", NORTH_CROSSWALK))]),
        case(t, "indirect", "that_bus_to_bus_stop", "now put that bus at the bus stop, where it belongs",
             [near(BUS_STOP, 10, BUS), only(BUS)], [place("bus_1", loc("at", BUS_STOP))], setup=[BUS_IN_LOT_A]),
        # vague
        case(t, "vague", "hero_car_somewhere_quiet", "park the hero car somewhere quiet, off the main road",
             [on(["paved"], asset=EGO), does("parked", asset=EGO), only(assets=[EGO])],
             [place(EGO, loc("at", LOT_A))]),
        case(t, "vague", "bench_somewhere_nicer", "the bench is in a dumb spot, put it somewhere nicer",
             [moved(BENCH, 2), only(assets=[BENCH])], [place(BENCH, loc("next_to", FOUNTAIN))]),
        case(t, "vague", "lonely_tree_joins_others",
             "the lonely tree in the far corner should join the others over by the fountain",
             [near(FOUNTAIN, 20, asset=TREE_LOT_A), only(assets=[TREE_LOT_A])],
             [place(TREE_LOT_A, loc("next_to", FOUNTAIN))]),
        case(t, "vague", "bin_out_of_walking_path", "the bin's in a bad spot. get it out of the walking path",
             [moved(BIN, 0.5), on(["ground", "paved"], asset=BIN), only(assets=[BIN])],
             [place(BIN, xy(-33.5, -8.5))]),
        case(t, "vague", "car_2_closer_to_union", "park car 2 a bit closer to the union",
             [near(UNION, 12, asset=CAR_2), only(assets=[CAR_2])], [place(CAR_2, loc("at", UNION))]),
        impossible(t, "vague", "suv_inside_student_union",
                   "stash the suv somewhere inside the student union building, out of sight for the reveal",
                   place(SUV, xy(42, -63)), notes="a spot inside a building"),
        case(t, "vague", "bin_near_student_union",
             "Would you be so kind as to put the rubbish bin somewhere near the Student Union? People there "
             "must have nowhere to throw their wrappers.",
             [near(UNION, 10, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", UNION))]),
        case(t, "vague", "hydrant_nearer_east_gate",
             "The hydrant I would like to have in a place more near to the east gate.",
             [near(EAST_GATE, 15, asset=HYDRANT), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", EAST_GATE))]),
        case(t, "vague", "truck_somewhere_else_lot",
             "that van's in the wrong lot, put it in the other one",
             [near(LOT_B, 1, TRUCK), only(TRUCK)], [place("truck_1", loc("at", LOT_B))], setup=[TRUCK_IN_LOT_A]),
        # erroneous
        case(t, "erroneous", "suv_infront_of_ego", "put teh suv infront of the ego",
             [relative("in_front_of", EGO, asset=SUV, max_distance=25, tolerance_deg=30), only(assets=[SUV])],
             [place(SUV, loc("in_front_of", EGO))]),
        case(t, "erroneous", "bench_next_to_libary", "Plese put the bench next to the libary door.",
             [near(LIBRARY, 6, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", LIBRARY))]),
        case(t, "erroneous", "ego_on_lane_northbound",
             "Position the ego vehicle on the lane northbound of Campus Drive, please.",
             [in_lane(NORTHBOUND, asset=EGO), only(assets=[EGO])], [place(EGO, loc("in_lane", NORTHBOUND))]),
        case(t, "erroneous", "suv_at_lot_a_entrnace", "park the suv at lot A entrnace",
             [near(LOT_A_ENTRANCE, 8, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", LOT_A_ENTRANCE))]),
        case(t, "erroneous", "placetrash_bin_coords", "placetrash_bin_1 at x=10,y=-20",
             [near(None, 1, asset=BIN, point=(10, -20)), only(assets=[BIN])], [place(BIN, xy(10, -20))]),
        case(t, "erroneous", "robot_next_2_suv", "move teh robot next 2 the suv",
             [near(SUV, 3, ROBOT), only(ROBOT)], [place("ackermann_robot_1", loc("next_to", SUV))],
             setup=[ROBOT_IN_LOT_B]),
        impossible(t, "erroneous", "tree_on_jtekt_roof", "put tree_2 on top of teh JTEKT buildng roof",
                   place(TREE_FOUNTAIN, xy(37, 30)), notes="a spot on (inside the footprint of) a building"),
        impossible(t, "erroneous", "hero_car_x250", "place the hero car at x=250 y=0 for teh run up",
                   place(EGO, xy(250, 0)), notes="off the map: x runs -110..110"),
    ]


VAN_IN_LOT_A_DRIVEWAY = turn("A van is waiting in the lot A driveway, nose pointing into the lot.",
                             add(TRUCK, where=xy(-85, 10), yaw_deg=90))
PERSON_AT_NORTH_CROSSWALK = turn("Add a wheelchair user waiting at the north crosswalk.",
                                 add(PERSON, where=loc("at", NORTH_CROSSWALK)))
WOMAN_AT_BUS_STOP_PLANNED = turn("Add a woman waiting at the bus stop, please.", add(PERSON, where=loc("at", BUS_STOP)),
                                 planned=True)
TRUCK_AHEAD_PARKED = turn("put a truck 40 m ahead of the ego in its lane, just parked there",
                          add(TRUCK, where=loc("at", EGO, along_m=40)), planned=True)
PICTURE_CAR_WESTBOUND = turn("Put a picture car, just an ordinary sedan, in the westbound lane up by the east gate, "
                             "driving at 8 m/s.",
                             add(CAR, where=loc("in_lane", EAST_GATE, lane=WESTBOUND), behaviour=drive(8, WESTBOUND)),
                             planned=True)


def moving_cases() -> list[Json]:
    t = "moving"
    return [
        # direct
        case(t, "direct", "ego_forward_15", "Move the ego forward 15 metres.",
             [moved(EGO, 13, 17, "forward"), only(assets=[EGO])], [move(EGO, forward=15)]),
        case(t, "direct", "suv_5m_north", "Shift the SUV 5 m north.",
             [moved(SUV, 4, 6, "forward"), only(assets=[SUV])], [move(SUV, north=5)]),
        impossible(t, "direct", "bench_500m_east", "move bench_1 500 m east",
                   move(BENCH, east=500), notes="500 m east of x = -26 is far off the map"),
        case(t, "direct", "turn_ego_around", "turn the ego around",
             [moved(EGO, 0, 3, turn_min=150), only(assets=[EGO])], [move(EGO, turn_deg=180)]),
        case(t, "direct", "ego_speed_12", "Set the ego's speed to 12 m/s.",
             [does("drive_lane", asset=EGO, speed_min=11.5, speed_max=12.5), only(assets=[EGO])],
             [behave(EGO, "drive_lane", speed=12)]),
        case(t, "direct", "car_1_circle_8m",
             "Please make passenger_car_1 drive in a circle of 8 metres radius in parking lot B.",
             [does("circle", asset=CAR_1, radius_min=7, radius_max=9, centre_near=LOT_B), only(assets=[CAR_1])],
             [behave(CAR_1, "circle", radius=8, centre=LOT_B)]),
        case(t, "direct", "bin_two_metres_west",
             "Please would you move the rubbish bin two metres to the west? Thank you very much.",
             [moved(BIN, 1.5, 2.5, "backward"), only(assets=[BIN])], [move(BIN, east=-2)]),
        case(t, "direct", "tree_1_four_m_east", "Move tree_1 four metres east.",
             [moved(TREE_BUS_STOP, 3.5, 4.5, "forward"), only(assets=[TREE_BUS_STOP])], [move(TREE_BUS_STOP, east=4)]),
        case(t, "direct", "hero_car_stops_at_4s",
             "Have the hero car brake to a full stop four seconds into the take.",
             [event_played(EGO, "stop", 6), only(assets=[EGO])], [manoeuvre(EGO, "stop", at_time=4)]),
        case(t, "direct", "suv_drives_westbound_8",
             "Put the SUV in the westbound lane and have it drive at 8 m/s toward the main gate.",
             [in_lane(WESTBOUND, asset=SUV), does("drive_lane", asset=SUV, speed_min=7.5, speed_max=8.5, lane=WESTBOUND),
              only(assets=[SUV])],
             [place(SUV, loc("in_lane", WESTBOUND)), behave(SUV, "drive_lane", speed=8, lane=WESTBOUND)], compound=True),
        # indirect
        case(t, "indirect", "more_run_up", "The hero car needs another 60 feet of run-up before its mark, so back it up.",
             [moved(EGO, 16, 21, "backward"), only(assets=[EGO])], [move(EGO, forward=-18.3)]),
        case(t, "indirect", "van_pulls_into_lot_a",
             "Van driver radioed: he's blocking the lot A entrance and needs to pull 10 metres further in.",
             [moved("truck_1", 8, 12, "forward"), near(LOT_A, 1, asset="truck_1"), only(assets=["truck_1"])],
             [move("truck_1", forward=10)], setup=[VAN_IN_LOT_A_DRIVEWAY]),
        case(t, "indirect", "bin_back_off_sidewalk",
             "The bin sticks out into the wheelchair path. Nudge it a metre and a half back off the sidewalk, "
             "toward the Library.",
             [moved(BIN, 1, 2, "right"), only(assets=[BIN])], [move(BIN, north=-1.5)]),
        case(t, "indirect", "suv_slow_laps_lot_b",
             "Edge case: the SUV should be doing slow laps, radius 6 m, round the middle of lot B.",
             [does("circle", asset=SUV, radius_min=5, radius_max=7, speed_max=5, centre_near=LOT_B), only(assets=[SUV])],
             [behave(SUV, "circle", radius=6, speed=3, centre=LOT_B)]),
        case(t, "indirect", "car_in_front_dawdles",
             "My grandson says the car in front of him dawdles along at five. Could it go ten instead, please?",
             [does("drive_lane", asset="passenger_car_3", speed_min=9.5, speed_max=10.5),
              only(assets=["passenger_car_3"])],
             [behave("passenger_car_3", "drive_lane", speed=10)], setup=[CAR_AHEAD]),
        case(t, "indirect", "ego_zoom_20_suv_donuts",
             "ego's way too slow, make it zoom like 20. and get the suv doing donuts in lot b while ur at it",
             [does("drive_lane", asset=EGO, speed_min=19, speed_max=21), does("circle", asset=SUV, centre_near=LOT_B),
              only(assets=[EGO, SUV])],
             [behave(EGO, "drive_lane", speed=20), behave(SUV, "circle", radius=8, centre=LOT_B)], compound=True),
        case(t, "indirect", "ego_lane_left_after_2s",
             "The car of the ego shall change one lane to the left after two seconds have passed.",
             [event_played(EGO, "lane_change", 5), only(assets=[EGO])],
             [manoeuvre(EGO, "lane_change", at_time=2, side="left")]),
        case(t, "indirect", "ped_should_walk_at_t3",
             "repro: the person at the north crosswalk should start walking across at t=3. currently just stands there",
             [does("cross_road", asset="pedestrian_1", crosses_lane=NORTHBOUND), only(assets=["pedestrian_1"])],
             [behave("pedestrian_1", "cross_road", start_time=3)], setup=[PERSON_AT_NORTH_CROSSWALK]),
        case(t, "indirect", "tree_drips_sap_on_bench",
             "The tree behind the bus stop drips sap all over the bench. Shift it a couple of metres further "
             "from the bench.",
             [only(assets=[TREE_BUS_STOP])], [move(TREE_BUS_STOP, north=-2)],
             alternatives=[[moved(TREE_BUS_STOP, 1.5, 4, "right")], [moved(TREE_BUS_STOP, 1.5, 4, "forward")],
                           [moved(TREE_BUS_STOP, 1.5, 4, "backward")]]),
        case(t, "indirect", "picture_car_turns_left", "Good. Now have that picture car turn left at the junction.",
             [event_played(CAR, "junction_turn", 20), only(CAR)],
             [manoeuvre("passenger_car_3", "junction_turn", turn="left")], setup=[PICTURE_CAR_WESTBOUND]),
        # vague
        case(t, "vague", "ego_up_a_lil", "move the ego up a lil",
             [moved(EGO, 0.5, 15, "forward"), only(assets=[EGO])], [move(EGO, forward=3)]),
        case(t, "vague", "get_suv_moving", "get the suv moving",
             [does(["drive_lane", "circle", "follow_path"], asset=SUV), only(assets=[SUV])],
             [behave(SUV, "circle", radius=8, centre=LOT_B)]),
        case(t, "vague", "hero_car_quicker", "make the hero car a bit quicker",
             [does("drive_lane", asset=EGO, speed_min=5.5, speed_max=15), only(assets=[EGO])],
             [behave(EGO, "drive_lane", speed=8)]),
        case(t, "vague", "she_should_go_somewhere", "she should actually go somewhere, not just stand there",
             [does(["cross_road", "jaywalk", "follow_path"], asset="pedestrian_1"), only(assets=["pedestrian_1"])],
             [behave("pedestrian_1", "follow_path", waypoints=[[-30, -5.5], [-15, -5.5]])],
             setup=[WOMAN_AT_BUS_STOP_PLANNED]),
        case(t, "vague", "nudge_tree_2", "nudge tree_2 off the path a touch",
             [moved(TREE_FOUNTAIN, 0.3, 3), only(assets=[TREE_FOUNTAIN])], [move(TREE_FOUNTAIN, east=-1)]),
        case(t, "vague", "boxy_car_round_and_round",
             "The big boxy car in the car park, could it go for a little drive, just round and round?",
             [does("circle", CARS), only(CAR, SUV_KIND)], [behave(SUV, "circle", radius=8, centre=LOT_B)]),
        case(t, "vague", "perturb_ego_start", "perturb the ego's start position slightly",
             [moved(EGO, 0.2, 10), only(assets=[EGO])], [move(EGO, forward=2)]),
        case(t, "vague", "ego_stops_sometime", "The ego should stop itself at some moment.",
             [only(assets=[EGO])], [manoeuvre(EGO, "stop", at_time=10)],
             alternatives=[[event_played(EGO, "stop", 30)], [does("parked", asset=EGO)]]),
        case(t, "vague", "truck_just_sitting", "truck's just sitting there. make it go",
             [does("drive_lane", TRUCK), only(TRUCK)], [behave("truck_1", "drive_lane", speed=6)],
             setup=[TRUCK_AHEAD_PARKED]),
        # erroneous
        case(t, "erroneous", "mvoe_ego_back_5", "mvoe the ego back 5m",
             [moved(EGO, 4, 6, "backward"), only(assets=[EGO])], [move(EGO, forward=-5)]),
        case(t, "erroneous", "trun_suv_90_left", "trun suv_1 90 degress left",
             [moved(SUV, 0, 1, turn_min=80, turn_max=100), only(assets=[SUV])], [move(SUV, turn_deg=90)]),
        case(t, "erroneous", "ego_slower_3_secnd", "Please make the ego car go slower, perhaps 3 metres a secnd.",
             [does("drive_lane", asset=EGO, speed_min=2.5, speed_max=3.5), only(assets=[EGO])],
             [behave(EGO, "drive_lane", speed=3)]),
        case(t, "erroneous", "bench_two_meter_east", "Make to move the bench for two meter in the east direction.",
             [moved(BENCH, 1.5, 2.5, "backward"), only(assets=[BENCH])], [move(BENCH, east=2)]),
        case(t, "erroneous", "suv_circel_lot_b", "have the suv circel lot b at 4 ms",
             [does("circle", asset=SUV, speed_min=3.5, speed_max=4.5, centre_near=LOT_B), only(assets=[SUV])],
             [behave(SUV, "circle", radius=8, speed=4, centre=LOT_B)]),
        case(t, "erroneous", "ego_fwd_then_face_north", "ego: move 10m fwd, then face north",
             [moved(EGO, 9, 11, "forward", turn_min=80, turn_max=100), only(assets=[EGO])],
             [move(EGO, forward=10), move(EGO, turn_deg=90)], compound=True),
        case(t, "erroneous", "bin_1m_sout", "pls moev the trash bin 1 m sout, off the side walk",
             [moved(BIN, 0.5, 1.5, "right"), only(assets=[BIN])], [move(BIN, north=-1)]),
        impossible(t, "erroneous", "hero_car_300kmh", "make the hero car do 300 km/h down main st",
                   behave(EGO, "drive_lane", speed=83.3), notes="past the 40 m/s limit"),
        impossible(t, "erroneous", "tree_drives_circle", "teh tree by the fountain should drive round it in a cirlce",
                   behave(TREE_FOUNTAIN, "circle", centre=FOUNTAIN, radius=6), notes="a tree cannot drive"),
    ]


BARRIERS_AT_EAST_GATE = turn("line of 3 barriers across Main Street at the east gate",
                             arrange(BARRIER, "line", loc("at", EAST_GATE), count=3))
CONES_ACROSS_WESTBOUND = turn("Please place four cones in a line across the westbound lane near the east gate.",
                              arrange(CONE, "line", loc("in_lane", EAST_GATE, lane=WESTBOUND), count=4, heading_deg=90),
                              planned=True)
THREE_PICTURE_CARS = turn("Line up three picture cars side by side in lot A, parked.",
                          arrange(CAR, "parking_row", loc("at", LOT_A), count=3), planned=True)
VANS = [f"truck_{n}" for n in range(1, 5)]


def arrangement_cases() -> list[Json]:
    t = "arrangement"
    return [
        # direct
        case(t, "direct", "cone_line_30m_and_sign",
             "Put a line of six cones across the eastbound lane 30 m ahead of the hero car, and a road-work "
             "sign on the sidewalk next to them.",
             [delta(CONE, 6, 6), layout("line", CONE, 6), near(None, 5, CONE, every=True, point=(-30, -1.75)),
              delta(WORK_SIGN, 1, 1), near(None, 8, WORK_SIGN, point=(-30, -1.75)), only(CONE, WORK_SIGN)],
             [arrange(CONE, "line", loc("in_front_of", EGO, distance=30), count=6),
              add(WORK_SIGN, where=loc("on_sidewalk", "traffic_cone_1"))], compound=True),
        case(t, "direct", "bollards_along_engineering_sidewalk",
             "Place a row of five bollards, five feet apart, along the sidewalk in front of Engineering Hall.",
             [delta(BOLLARD, 5, 5), layout("line", BOLLARD, 5, spacing_min=1.2, spacing_max=1.8),
              near(ENGINEERING, 12, BOLLARD, every=True), only(BOLLARD)],
             [arrange(BOLLARD, "line", loc("on_sidewalk", ENGINEERING), count=5, spacing=1.5, heading_deg=0)]),
        case(t, "direct", "five_trees_north_edge_lot_a",
             "Plant five trees in a row along the north edge of lot A, 6 m apart.",
             [delta(TREE, 5, 5), layout("line", TREE, 5, spacing_min=5, spacing_max=7),
              near(None, 16, TREE, every=True, point=(-85, 44)), only(TREE)],
             [arrange(TREE, "line", xy(-85, 41), count=5, spacing=6, heading_deg=0)]),
        case(t, "direct", "three_trucks_side_by_side", "Park a row of three trucks side by side in lot A.",
             [delta(TRUCK, 3, 3), layout("line", TRUCK, 3), near(LOT_A, 1, TRUCK, every=True), only(TRUCK)],
             [arrange(TRUCK, "parking_row", loc("at", LOT_A), count=3)]),
        case(t, "direct", "grid_of_cones_lot_b", "Create a 3 by 3 grid of traffic cones in the centre of lot B.",
             [delta(CONE, 9, 9), near(LOT_B, 1, CONE, every=True), layout("cluster", CONE, 9, tolerance=6),
              only(CONE)],
             [arrange(CONE, "grid", loc("at", LOT_B), count=9, columns=3)]),
        case(t, "direct", "bollard_circle_fountain", "make a circle of 8 bollards round the fountain",
             [delta(BOLLARD, 8, 8), layout("ring", BOLLARD, 8, around=FOUNTAIN), only(BOLLARD)],
             [arrange(BOLLARD, "ring", loc("at", FOUNTAIN), count=8, radius=4)]),
        case(t, "direct", "barriers_across_east_gate", "line of 3 barriers across Main Street at the east gate. go",
             [delta(BARRIER, 3, 3), layout("line", BARRIER, 3), near(EAST_GATE, 10, BARRIER, every=True), only(BARRIER)],
             [arrange(BARRIER, "line", loc("at", EAST_GATE), count=3)]),
        case(t, "direct", "five_benches_line_fountain",
             "Could you set out five benches in a straight line beside the fountain, please?",
             [delta(BENCH_KIND, 5, 5), layout("line", BENCH_KIND, 5), near(FOUNTAIN, 10, BENCH_KIND, every=True,
                                                                           scope="added"),
              only(BENCH_KIND)],
             [arrange(BENCH_KIND, "line", loc("next_to", FOUNTAIN), count=5)]),
        case(t, "direct", "six_pedestrians_line_jtekt",
             "Please arrange six pedestrians in a line on the sidewalk in front of the JTEKT building entrance.",
             [delta(PERSON, 6, 6), layout("line", PERSON, 6), near(JTEKT, 15, PERSON, every=True),
              on(["sidewalk"], PERSON), only(PERSON)],
             [arrange(PERSON, "line", loc("on_sidewalk", JTEKT), count=6)]),
        case(t, "direct", "skidpad_ring_lot_b",
             "Ring of 10 cones, radius 12, around the middle of lot B. That's our skidpad.",
             [delta(CONE, 10, 10), layout("ring", CONE, 10, around=LOT_B, spacing_min=6, spacing_max=9), only(CONE)],
             [arrange(CONE, "ring", loc("at", LOT_B), count=10, radius=12)],
             setup=[turn("Clear lot B for the skidpad, tow all three cars.", remove(*PARKED))]),
        # indirect
        case(t, "indirect", "barrier_wall_campus_drive_north",
             "We need a barrier wall closing Campus Drive north of the junction, so nobody wanders into the chase.",
             [delta(BARRIER, 2, None), layout("line", BARRIER, 2), in_lane(None, BARRIER),
              near(None, 27, BARRIER, every=True, point=(0, 35)), only(BARRIER)],
             [arrange(BARRIER, "line", xy(0, 25), count=3, heading_deg=0)]),
        case(t, "indirect", "bollards_line_bus_stop_kerb",
             "Wheelchair users need a protected waiting area, so line the kerb at the bus stop with bollards. "
             "Five of them.",
             [delta(BOLLARD, 5, 5), layout("line", BOLLARD, 5), near(BUS_STOP, 6, BOLLARD, every=True), only(BOLLARD)],
             [arrange(BOLLARD, "line", loc("at", BUS_STOP), count=5, spacing=1.5, heading_deg=0)]),
        case(t, "indirect", "fleet_lined_up_orange",
             "Tomorrow's fleet: four vans lined up ready to go in lot B, all in our company orange.",
             [delta(TRUCK, 4, 4), layout("line", TRUCK, 4), near(LOT_B, 1, TRUCK, every=True),
              looks("orange", TRUCK, scope="added", every=True, min_count=4), only(TRUCK)],
             [arrange(TRUCK, "parking_row", loc("at", LOT_B), count=4), paint(VANS, colour="orange")], compound=True),
        case(t, "indirect", "dense_crowd_sample",
             "I need a dense crowd sample: a tight cluster of eight people on the lawn by the fountain.",
             [delta(PERSON, 8, 8), layout("cluster", PERSON, 8, tolerance=6), near(FOUNTAIN, 12, PERSON, every=True),
              only(PERSON)],
             [arrange(PERSON, "grid", loc("at", FOUNTAIN), count=8, columns=4, spacing=1)]),
        case(t, "indirect", "street_trees_campus_drive_east",
             "Replace the missing street trees: a row of four along the east side of Campus Drive, south of "
             "Main Street.",
             [delta(TREE, 4, 4), layout("line", TREE, 4), near(None, 22, TREE, every=True, point=(9, -22)),
              near(LOT_B, 8, TREE, every=True), only(TREE)],
             [arrange(TREE, "line", xy(9, -18), count=4, spacing=7, heading_deg=-90)]),
        case(t, "indirect", "memorial_circle_of_benches",
             "We're having a little memorial gathering by the fountain on Sunday. Could the benches be set in a "
             "circle around it? Six should do nicely.",
             [layout("ring", BENCH_KIND, 6, around=FOUNTAIN, scope="touched"), only(BENCH_KIND)],
             [arrange(BENCH_KIND, "ring", loc("at", FOUNTAIN), count=6, radius=4)]),
        case(t, "indirect", "eastbound_lane_closure", "need like a lane closure on eastbound, cones along the edge, 8 of em",
             [delta(CONE, 8, 8), layout("line", CONE, 8), in_lane(EASTBOUND, CONE), only(CONE)],
             [arrange(CONE, "lane_edge", loc("in_lane", EASTBOUND), count=8)]),
        case(t, "indirect", "same_barriers_at_main_gate", "same again at the main gate",
             [delta(BARRIER, 3, 3), layout("line", BARRIER, 3), near(MAIN_GATE, 10, BARRIER, every=True, scope="added"),
              only(BARRIER)],
             [arrange(BARRIER, "line", loc("at", MAIN_GATE), count=3)], setup=[BARRIERS_AT_EAST_GATE]),
        case(t, "indirect", "same_cone_line_eastbound",
             "I thank you. Now kindly the same line also across the eastbound lane, at the same place.",
             [delta(CONE, 4, 4), layout("line", CONE, 4), in_lane(EASTBOUND, CONE, scope="added"),
              near(EAST_GATE, 15, CONE, every=True, scope="added"), only(CONE)],
             [arrange(CONE, "line", loc("in_lane", EAST_GATE, lane=EASTBOUND), count=4, heading_deg=90)],
             setup=[CONES_ACROSS_WESTBOUND]),
        # vague
        case(t, "vague", "obstacle_course_lot_a", "make a lil obstacle course in lot a",
             [delta(OBSTACLES, 3, None), near(LOT_A, 1, OBSTACLES, every=True), only(*OBSTACLES)],
             [arrange(CONE, "line", loc("at", LOT_A), count=6, spacing=3)]),
        case(t, "vague", "set_up_a_skidpad", "set up a skidpad",
             [delta([CONE, BOLLARD], 4, None), layout("ring", [CONE, BOLLARD], 4), only(CONE, BOLLARD)],
             [arrange(CONE, "ring", loc("at", LOT_B), count=8, radius=10)]),
        case(t, "vague", "block_library_sidewalk", "block off the sidewalk by the library for repairs",
             [delta([BOLLARD, WORK_SIGN, CONE, BARRIER], 2, None),
              near(None, 12, [BOLLARD, WORK_SIGN, CONE, BARRIER], every=True, point=(-41, -5.5)),
              only(BOLLARD, WORK_SIGN, CONE, BARRIER)],
             [arrange(BOLLARD, "line", loc("on_sidewalk", LIBRARY), count=4, spacing=2, heading_deg=0)]),
        case(t, "vague", "line_up_some_vans", "line up some vans",
             [delta(TRUCK, 2, None), layout("line", TRUCK, 2), only(TRUCK)],
             [arrange(TRUCK, "parking_row", loc("at", LOT_B), count=3)]),
        case(t, "vague", "start_an_avenue", "start me an avenue somewhere, a row of trees will do for now",
             [delta(TREE, 3, None), layout("line", TREE, 3), only(TREE)],
             [arrange(TREE, "line", xy(72, 9), count=4, spacing=7, heading_deg=0)]),
        case(t, "vague", "scatter_of_cones_lot_b", "random-ish scatter of cones in lot B, like 6",
             [delta(CONE, 6, 6), near(LOT_B, 1, CONE, every=True), only(CONE)], [add(CONE, 6, where=loc("at", LOT_B))]),
        case(t, "vague", "welcoming_bus_stop",
             "Could you make the bus stop feel more welcoming? A few benches in a row would be nice.",
             [delta(BENCH_KIND, 2, None), layout("line", BENCH_KIND, 2), near(BUS_STOP, 12, BENCH_KIND, every=True,
                                                                            scope="added"),
              only(BENCH_KIND)],
             [arrange(BENCH_KIND, "line", xy(-30, -8.5), count=3, spacing=2.5, heading_deg=0)]),
        case(t, "vague", "wall_off_road_ahead", "wall off the road in front of the ego",
             [delta([BARRIER, CONE], 2, None), layout("line", [BARRIER, CONE], 2),
              relative("in_front_of", EGO, [BARRIER, CONE], max_distance=40), only(BARRIER, CONE)],
             [arrange(BARRIER, "line", loc("in_front_of", EGO, distance=20), count=3)]),
        case(t, "vague", "seats_in_round_form_union", "Some seats put in a round form near the Student Union, please.",
             [delta(BENCH_KIND, 3, None), layout("ring", BENCH_KIND, 3), near(UNION, 20, BENCH_KIND, every=True),
              only(BENCH_KIND)],
             [arrange(BENCH_KIND, "ring", xy(42.5, -38), count=3, radius=5)]),
        case(t, "vague", "make_it_five", "Actually, make it five.",
             [delta(CARS, 2, 2), near(LOT_A, 1, CARS, every=True, scope="added"), only(CAR, SUV_KIND)],
             [arrange(CAR, "parking_row", loc("at", LOT_A), count=2)], setup=[THREE_PICTURE_CARS]),
        # erroneous
        case(t, "erroneous", "cones_lien_across_road", "put 5 cones in a lien across teh road infront of the ego",
             [delta(CONE, 5, 5), layout("line", CONE, 5), relative("in_front_of", EGO, CONE, max_distance=40),
              only(CONE)],
             [arrange(CONE, "line", loc("in_front_of", EGO, distance=20), count=5)]),
        case(t, "erroneous", "bencehs_cirlce_fountian", "Plese put four bencehs in a cirlce around the fountian.",
             [delta(BENCH_KIND, 4, 4), layout("ring", BENCH_KIND, 4, around=FOUNTAIN), only(BENCH_KIND)],
             [arrange(BENCH_KIND, "ring", loc("at", FOUNTAIN), count=4, radius=4)]),
        case(t, "erroneous", "trucks_one_row_parking_b",
             "Arrange please the trucks, three of them in one row, in the parking B.",
             [delta(TRUCK, 3, 3), layout("line", TRUCK, 3), near(LOT_B, 1, TRUCK, every=True), only(TRUCK)],
             [arrange(TRUCK, "parking_row", loc("at", LOT_B), count=3)]),
        case(t, "erroneous", "grid_2x3_bollards", "grid 2x3 of bollards @ lot A pls",
             [delta(BOLLARD, 6, 6), near(LOT_A, 1, BOLLARD, every=True), layout("cluster", BOLLARD, 6, tolerance=6),
              only(BOLLARD)],
             [arrange(BOLLARD, "grid", loc("at", LOT_A), count=6, columns=3)]),
        case(t, "erroneous", "vans_nose_to_tail_east_gate",
             "line up 3 vans in teh westbound lane by the east gate, nose to tail",
             [delta(TRUCK, 3, 3), layout("line", TRUCK, 3), in_lane(WESTBOUND, TRUCK), only(TRUCK)],
             [arrange(TRUCK, "line", loc("in_lane", EAST_GATE, lane=WESTBOUND), count=3, spacing=10, heading_deg=180)]),
        case(t, "erroneous", "tres_streight_line_main_st",
             "plant 4 tres in a streight line along the north side of main st, east of teh JTEKT building",
             [delta(TREE, 4, 4), layout("line", TREE, 4), near(None, 20, TREE, every=True, point=(75, 9)), only(TREE)],
             [arrange(TREE, "line", xy(72, 9), count=4, spacing=7, heading_deg=0)]),
        case(t, "erroneous", "bolards_round_hydrant", "ring of bolards round the hydrant, 4 of them, 2m out",
             [delta(BOLLARD, 4, 4), layout("ring", BOLLARD, 4, around=HYDRANT), near(HYDRANT, 3, BOLLARD, every=True),
              only(BOLLARD)],
             [arrange(BOLLARD, "ring", loc("at", HYDRANT), count=4, radius=2)]),
        impossible(t, "erroneous", "ring_100m_radius", "ring of 12 cones with a 100m radius round the junction",
                   arrange(CONE, "ring", loc("at", JUNCTION), count=12, radius=100),
                   notes="past the 60 m ring limit, and far off the map"),
        impossible(t, "erroneous", "grid_150_cones", "arrange 150 cones in a grid at lot B",
                   arrange(CONE, "grid", loc("at", LOT_B), count=150), notes="past the limit of one layout"),
    ]


HEAVY_RAIN = turn("make it rain hard", weather("rain", 0.9))
DUSK_PLANNED = turn("Give me dusk for the next take.", clock("dusk"), planned=True)


def appearance_cases() -> list[Json]:
    t = "appearance"
    return [
        # direct
        case(t, "direct", "paint_ego_red", "Paint the ego vehicle red.",
             [looks("red", asset=EGO, tolerance=0.1), only(assets=[EGO])], [paint([EGO], colour="red")]),
        case(t, "direct", "time_2300", "set time to 23:00",
             [env(time_from="22:50", time_to="23:10", **CLEAR), only(env=True)], [clock("23:00")]),
        case(t, "direct", "heavy_snow", "Make it snow, heavily.",
             [env(weather=["snow"], intensity_min=0.7, **NOON), only(env=True)], [weather("snow", 0.9)]),
        case(t, "direct", "suv_white_matte", "Colour the SUV white with a matte finish.",
             [looks("white", asset=SUV, tolerance=0.1, material="matte"), only(assets=[SUV])],
             [paint([SUV], colour="white", material="matte")]),
        case(t, "direct", "street_lights_on", "Turn the street lights on.",
             [env(street_lights="on", **NOON, **CLEAR), only(env=True)], [lighting(street_lights="on")]),
        case(t, "direct", "street_lights_pink", "make all the street lights pink lol",
             [looks("pink", LAMP, scope="all", every=True, min_count=12), only(LAMP)], [paint(category=LAMP, colour="pink")]),
        case(t, "direct", "fog_04", "Set fog with intensity 0.4.",
             [env(weather=["fog"], intensity_min=0.35, intensity_max=0.45, **NOON), only(env=True)], [weather("fog", 0.4)]),
        case(t, "direct", "night_and_street_lights",
             "Please make it night time, and turn the street lights on so I can still see everything.",
             [env(night=True, street_lights="on", **CLEAR), only(env=True)],
             [clock("night"), lighting(street_lights="on")], compound=True),
        case(t, "direct", "new_hydrant_yellow",
             "Please colour the new fire hydrant yellow, and leave the old one as it is.",
             [looks("yellow", asset="fire_hydrant_2", tolerance=0.1), only(assets=["fire_hydrant_2"])],
             [paint(["fire_hydrant_2"], colour="yellow")],
             setup=[turn("Please add a fire hydrant beside the JTEKT building entrance.",
                         add(HYDRANT_KIND, where=loc("next_to", JTEKT)), planned=True)]),
        # indirect
        case(t, "indirect", "golden_hour_glossy_hero",
             "We're shooting the chase at golden hour, so set the clock to just before sunset, and give the hero "
             "car a glossy finish so it catches the light.",
             [env(time_from="17:30", time_to="19:35", **CLEAR), looks(asset=EGO, material="glossy"),
              only(assets=[EGO], env=True)],
             [clock("19:00"), paint([EGO], material="glossy")], compound=True),
        case(t, "indirect", "thick_fog_low_vision",
             "I need to check how visible the crossings are for low-vision users in poor conditions, so give me "
             "thick fog.",
             [env(weather=["fog"], intensity_min=0.7, **NOON), only(env=True)], [weather("fog", 0.9)]),
        case(t, "indirect", "van_in_company_orange", "That's one of ours, so it should be in company orange.",
             [looks("orange", TRUCK), only(TRUCK)], [paint(["truck_1"], colour="orange")], setup=[TRUCK_IN_LOT_A]),
        case(t, "indirect", "autumn_brown_trees",
             "It's autumn inspection season: make the trees look brown, like dead leaves, and bring in some grey "
             "cloud.",
             [looks("brown", TREE, scope="all", every=True, min_count=4), env(weather=["cloudy"], **NOON),
              only(TREE, env=True)],
             [paint(category=TREE, colour="brown"), weather("cloudy")], compound=True),
        case(t, "indirect", "exposure_half",
             "Low-light edge case: drop the camera exposure to 0.5 and leave everything else alone.",
             [env(exposure_min=0.45, exposure_max=0.55, **NOON, **CLEAR), only(env=True)], [lighting(exposure=0.5)]),
        case(t, "indirect", "too_bright_late_evening", "its too bright lol make it like late evening",
             [only(env=True)], [clock("21:30")],
             alternatives=[[env(time_from="20:00", time_to="23:59", **CLEAR)], [env(exposure_max=0.8, **CLEAR)]]),
        case(t, "indirect", "bench_hard_to_see",
             "My eyes are not what they were, and the bench is hard to make out against the pavement. Could it "
             "be a bright colour? Yellow, perhaps.",
             [looks("yellow", asset=BENCH, tolerance=0.1), only(assets=[BENCH])], [paint([BENCH], colour="yellow")]),
        case(t, "indirect", "light_rain_wished", "It is wished that the weather becomes rainy, but only in a light manner.",
             [env(weather=["rain"], intensity_min=0.05, intensity_max=0.45, **NOON), only(env=True)],
             [weather("rain", 0.3)]),
        case(t, "indirect", "stop_the_rain", "ok now stop the rain",
             [env(weather=["clear", "cloudy"], **NOON), only(env=True)], [weather("clear")], setup=[HEAVY_RAIN]),
        # vague
        case(t, "vague", "make_it_spooky", "make it spooky",
             [only(env=True)], [clock("midnight"), weather("fog", 0.6)],
             alternatives=[[env(night=True)], [env(weather=["fog"])]]),
        case(t, "vague", "hero_car_pops", "the hero car needs to pop on camera",
             [looks(BRIGHT, asset=EGO), only(assets=[EGO])], [paint([EGO], colour="yellow")]),
        impossible(t, "vague", "library_brighter",
                   "paint the library walls something brighter so partially sighted visitors can find it",
                   paint(["library"], colour="yellow"), notes="buildings are not assets and cannot be repainted"),
        case(t, "vague", "hydrant_stand_out", "make the hydrant stand out more",
             [looks(BRIGHT, asset=HYDRANT), only(assets=[HYDRANT])], [paint([HYDRANT], colour="yellow")]),
        case(t, "vague", "bad_day_delivery_weather", "weather for a bad-day delivery run",
             [env(weather=["rain", "snow", "fog"]), only(env=True)], [weather("rain", 0.7)]),
        case(t, "vague", "dawn_condition", "give me a dawn condition",
             [env(time_from="05:00", time_to="07:00", **CLEAR), only(env=True)], [clock("dawn")]),
        case(t, "vague", "sunny_morning", "Could it be a nice sunny morning, please?",
             [env(time_from="06:00", time_to="11:00", **CLEAR), only(env=True)], [clock("morning")]),
        case(t, "vague", "suv_darker_colour", "The SUV I would prefer in some darker colour.",
             [looks(DARK, asset=SUV), only(assets=[SUV])], [paint([SUV], colour="navy")]),
        case(t, "vague", "lights_all_on", "lights. all of them. on.",
             [env(street_lights="on", vehicle_lights="on", **NOON), only(env=True)],
             [lighting(street_lights="on", vehicle_lights="on")]),
        # erroneous
        case(t, "erroneous", "suv_bleu", "paint teh suv bleu",
             [looks("blue", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="blue")]),
        case(t, "erroneous", "car_in_front_silver", "The car in front, please to colour it in silver.",
             [looks("silver", asset="passenger_car_3", tolerance=0.1), only(assets=["passenger_car_3"])],
             [paint(["passenger_car_3"], colour="silver")], setup=[CAR_AHEAD]),
        case(t, "erroneous", "tiem_0300", "set tiem to 0300",
             [env(time_from="02:50", time_to="03:10", **CLEAR), only(env=True)], [clock("03:00")]),
        case(t, "erroneous", "sky_cloudly", "make teh sky cloudly",
             [env(weather=["cloudy"], **NOON), only(env=True)], [weather("cloudy")]),
        case(t, "erroneous", "proper_night_headlights",
             "bit darker than that, proper nite, and switch teh car headlights on",
             [env(time_from="21:00", time_to="05:00", vehicle_lights="on", **CLEAR), only(env=True)],
             [clock("night"), lighting(vehicle_lights="on")], setup=[DUSK_PLANNED], compound=True),
        impossible(t, "erroneous", "hero_car_see_thru", "make the hero car see-thru for the stunt double shot",
                   paint([EGO], colour="transparent"), notes="no transparent colour"),
        impossible(t, "erroneous", "hail_storm", "set weather to hail storm plz, need to see canopy damage",
                   weather("hail"), notes="the weather kinds are clear, cloudy, rain, fog and snow"),
        impossible(t, "erroneous", "time_2615", "for the edge case set teh time to 26:15",
                   clock("26:15"), notes="no such clock time"),
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
