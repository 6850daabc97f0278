"""The thirteenth practice suite: everyday requests from people who would really use the tool.

`suites/practice13.jsonl` (250 cases, ids `practice13.<task>.<grade>.<name>`, tag `practice13`)
is a development suite written in the voices of ordinary users of a driving-scene tool: a
driving-school instructor setting up a lesson, a fleet safety manager reproducing a near miss
one of the company's drivers reported ("one of our drivers said ..."), a city council transport
officer checking a road-works plan, a UX designer or product manager preparing a demo, a
journalist or blogger trying the tool out, a retired hobbyist, and a second-year student intern
working from a test sheet. Prompts mix short chat turns ("more cones", "now make it dusk",
"lose the SUV") with one-to-three sentence descriptions of the scene wanted, use everyday words
for things (a lamp, a bin, a lorry, a kid on a bike, the car park by the main gate), refer back
to earlier turns ("them", "the ones I just added", "the red one"), give numbers in words and
digits, metres, car lengths and miles an hour, rough amounts ("a few", "a couple", "a
handful"), clock times and parts of the day, weather words, negation and exceptions ("but leave
the SUV", "SUV included"), scopes (a lane, a lot, one side of a road, east of the junction) and
relations (in front of, behind, next to, N m ahead of the car along its lane), and ask questions
of many shapes that must change nothing. The erroneous grade carries realistic typing slips:
swapped, missing and doubled letters, real-word swaps ("too", "their", "form"), missing spaces,
dropped words and non-native grammar.

Every task x grade cell holds 8 or 9 cases (7 tasks x 4 grades; search-vague and
moving-erroneous hold 8); 35 cases are `multi_turn` (16 with a `planned` earlier turn that the
planner under test plans itself), 18 are `compound` (two or more edits or questions in one
request), and 22 (8.8 %) are `impossible`: things the world
cannot do (a bus shelter, a deer, a portaloo, a hospital or a petrol station, a thousand people,
a car on the Library roof, a bench inside the JTEKT Building, a hydrant 500 m past the east gate,
removing Campus Drive, the Student Union or our own car, moving Engineering Hall, a bench doing
doughnuts, 300 km/h, a 200 m ring, 150 barriers or 120 cones in one layout, 28:00, a hurricane,
painting the Student Union), where the right outcome is a refusal that changes nothing.

Every case judges the outcome, never the calls: a main check plus an `unchanged_except` guard,
with `alternatives` where a request has two fair readings, and bounds a reasonable person would
accept ("a few" is 2 to 5). Every case carries a reference plan of Worker calls that passes it.
The suite was written from the campus world, the asset catalog, the Worker tools and the checks
only, by someone who had not read the planners, their lexicons, their prompt examples or any
other suite's cases. `python -m drivetwin.evals.practice13_source` rewrites the JSONL.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

Json = dict[str, Any]

SUITE = "practice13"
SUITE_PATH = Path(__file__).resolve().with_name("suites") / f"{SUITE}.jsonl"

# --- Facts of the campus world (worlds/campus.py) -------------------------------------------
EGO = "ego"  # drives main_eastbound at 5 m/s from (-60, -1.75)
BENCH = "bench_1"  # at the bus stop, (-26, -6.9)
BIN = "trash_bin_1"  # at the bus stop, (-33.5, -5.5)
HYDRANT = "fire_hydrant_1"  # Main Street north side, (16, 5.5)
STOP_SIGN = "stop_sign_1"  # by the west crosswalk, (-13.5, -5.5)
CAR_1 = "passenger_car_1"  # lot B, (19, -42), the west end of the row
CAR_2 = "passenger_car_2"  # lot B, (27, -42), nearest the Student Union
SUV = "suv_1"  # lot B, (23, -42), facing north
TREE_BY_LIBRARY = "tree_1"  # (-26, -12), just north-east of the Library
FOUNTAIN_TREES = ("tree_2", "tree_3")  # (70, 45) and (85, 25)
TREE_NORTH_OF_LOT_A = "tree_4"  # (-85, 50)
TREES = ("tree_1", "tree_2", "tree_3", "tree_4")
LIGHTS_NORTH = tuple(f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11))  # y = 5.8
LIGHTS_SOUTH = tuple(f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12))  # y = -5.8
LIGHTS_WEST = tuple(f"street_light_{n}" for n in range(1, 7))  # x < 0
LIGHTS_EAST = tuple(f"street_light_{n}" for n in range(7, 13))  # x > 0
LAMP_BY_BUS_STOP = "street_light_4"  # (-38, -5.8), 8 m from the bus stop
SIGNAL_SOUTH = "traffic_light_1"  # (-9.5, -6.2)
SIGNAL_NORTH = "traffic_light_2"  # (9.5, 6.2)

LIBRARY = "Library entrance"  # (-41, -15), faces north onto its paved drop-off
JTEKT = "JTEKT building entrance"  # (37.5, 15), faces south onto its paved drop-off
ENGINEERING = "Engineering Hall entrance"  # (-40, 15), faces south
UNION = "Student Union entrance"  # (42.5, -51), faces north towards lot B
MAIN_GATE = "main gate"  # (-100, 0)
EAST_GATE = "east gate"  # (100, 0)
JUNCTION = "main intersection"  # the paved box -9..9 x -9..9
LOT_A = "parking lot A"  # -100..-70 x 14..44
LOT_B = "parking lot B"  # 15..62 x -46..-12
LOT_A_ENTRANCE = "parking lot A entrance"  # (-85, 3.5)
LOT_B_ENTRANCE = "parking lot B entrance"  # (47, -3.5)
BUS_STOP = "bus stop"  # (-30, -5.5), on Main Street's south sidewalk
FOUNTAIN = "fountain"  # (75, 40), on grass: cones (road things) cannot stand there
WEST_CROSSWALK = "west crosswalk"  # (-11.5, 0), across Main Street
NORTH_CROSSWALK = "north crosswalk"  # (0, 11.5), across Campus Drive

EASTBOUND = "main_eastbound"
WESTBOUND = "main_westbound"
NORTHBOUND = "campus_northbound"
SOUTHBOUND = "campus_southbound"

VEHICLES = ["passenger_car", "suv", "bus", "truck", "motorcycle"]
ROADWORKS = ["traffic_cone", "road_barrier", "construction_sign", "cement_rubble"]


# --- Checks -----------------------------------------------------------------------------------
def _who(category: str | list[str] | None, asset: str | None, scope: str | None) -> Json:
    out: Json = {}
    if category is not None:
        out["category"] = category
    if asset is not None:
        out["asset"] = asset
    if scope is not None:
        out["scope"] = scope
    return out


def unchanged(*categories: str, assets: tuple[str, ...] | list[str] = (), env: bool = False) -> Json:
    """Nothing changed but these categories / ids (and the environment when `env`)."""
    out: Json = {"kind": "unchanged_except"}
    if categories:
        out["categories"] = list(categories)
    if assets:
        out["assets"] = list(assets)
    if env:
        out["environment"] = True
    return out


def delta(category: str | list[str], lo: int, hi: int | None = None) -> Json:
    return {"kind": "count_delta", "category": category, "min": lo, "max": lo if hi is None else hi}


def total(category: str | list[str], lo: int, hi: int | None = None) -> Json:
    return {"kind": "count", "category": category, "min": lo, "max": lo if hi is None else hi}


def near(target: str, within: float, category: str | list[str] | None = None, asset: str | None = None,
         scope: str | None = "added", require_all: bool = True, min_count: int = 1) -> Json:
    out: Json = {"kind": "near", "target": target, "within": within,
                 **_who(category, asset, None if asset else scope)}
    if require_all and not asset:
        out["require_all"] = True
    if min_count != 1:
        out["min_count"] = min_count
    return out


def near_point(x: float, y: float, within: float, category: str | list[str] | None = None,
               asset: str | None = None, scope: str | None = "added") -> Json:
    out: Json = {"kind": "near", "point": [x, y], "within": within, **_who(category, asset, None if asset else scope)}
    if not asset:
        out["require_all"] = True
    return out


def relative(relation: str, target: str, max_distance: float, category: str | None = None,
             asset: str | None = None, scope: str | None = "added", tolerance_deg: float = 60.0) -> Json:
    out: Json = {"kind": "relative", "relation": relation, "target": target, "max_distance": max_distance,
                 "tolerance_deg": tolerance_deg, **_who(category, asset, None if asset else scope)}
    if not asset:
        out["require_all"] = True
    return out


def surface(surfaces: list[str], category: str | list[str] | None = None, asset: str | None = None,
            scope: str | None = "added") -> Json:
    return {"kind": "on_surface", "surfaces": surfaces, **_who(category, asset, None if asset else scope)}


def in_lane(lane: str | None, category: str | list[str] | None = None, asset: str | None = None,
            scope: str | None = "added", aligned: bool = False) -> Json:
    out: Json = {"kind": "in_lane", **_who(category, asset, None if asset else scope)}
    if lane is not None:
        out["lane"] = lane
    if aligned:
        out["aligned"] = True
    return out


def layout(shape: str, category: str | list[str], min_count: int = 3, around: str | None = None,
           tolerance: float = 1.0, spacing: tuple[float | None, float | None] = (None, None),
           scope: str = "added") -> Json:
    out: Json = {"kind": "arrangement", "shape": shape, "category": category, "min_count": min_count,
                 "tolerance": tolerance}
    if scope != "added":
        out["scope"] = scope
    if around is not None:
        out["around"] = around
    if spacing[0] is not None:
        out["spacing_min"] = spacing[0]
    if spacing[1] is not None:
        out["spacing_max"] = spacing[1]
    return out


def does(behaviour: str | list[str], category: str | list[str] | None = None, asset: str | None = None,
         scope: str | None = "added", require_all: bool = True, **params: Any) -> Json:
    out: Json = {"kind": "behaviour", "behaviour": behaviour, **_who(category, asset, None if asset else scope),
                 **params}
    if require_all and not asset:
        out["require_all"] = True
    return out


def env(**params: Any) -> Json:
    return {"kind": "environment", **params}


def at_time(clock: str) -> Json:
    return env(time_from=clock, time_to=clock)


NOON = at_time("12:00")  # the world's own time: pinned where a request does not touch it
CLEAR = env(weather=["clear"])  # the world's own weather


def look(colour: str | list[str] | None = None, material: str | None = None,
         category: str | list[str] | None = None, asset: str | None = None, scope: str | None = "touched",
         tolerance: float | None = None) -> Json:
    out: Json = {"kind": "appearance", **_who(category, asset, None if asset else scope)}
    if colour is not None:
        out["colour"] = colour
    if tolerance is not None:
        out["colour_tolerance"] = tolerance
    if material is not None:
        out["material"] = material
    if not asset:
        out["require_all"] = True
    return out


def moved(asset: str, lo: float = 0.0, hi: float | None = None, direction: str | None = None,
          turn: tuple[float | None, float | None] = (None, None)) -> Json:
    out: Json = {"kind": "moved", "asset": asset, "min_distance": lo}
    if hi is not None:
        out["max_distance"] = hi
    if direction is not None:
        out["direction"] = direction
    if turn[0] is not None:
        out["turn_min_deg"] = turn[0]
    if turn[1] is not None:
        out["turn_max_deg"] = turn[1]
    return out


def gone(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": False}


def kept(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets)}


def says(all_of: tuple[str, ...] = (), any_of: tuple[str, ...] = (), none_of: tuple[str, ...] = ()) -> Json:
    out: Json = {"kind": "answer_contains"}
    if all_of:
        out["all_of"] = list(all_of)
    if any_of:
        out["any_of"] = list(any_of)
    if none_of:
        out["none_of"] = list(none_of)
    return out


def event(manoeuvre: str, actor: str, seconds: float = 8.0) -> Json:
    """The storyboard holds a `manoeuvre` of `actor` that starts within `seconds` of simulation."""
    return {"kind": "scenario", "seconds": seconds,
            "expect": [{"kind": "event", "actor": actor, "manoeuvre": manoeuvre}]}


REFUSED: Json = {"kind": "status", "accepted": False}


# --- Calls ------------------------------------------------------------------------------------
def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def where(relation: str = "at", target: str | None = None, **more: Any) -> Json:
    out: Json = {"relation": relation}
    if target is not None:
        out["target"] = target
    out.update(more)
    return out


def spot(x: float, y: float) -> Json:
    return {"relation": "absolute", "x": x, "y": y}


def add(category: str, count: int = 1, location: Json | None = None, **more: Any) -> Json:
    args: Json = {"category": category}
    if count != 1:
        args["count"] = count
    if location is not None:
        args["location"] = location
    args.update(more)
    return {"tool": "add_asset", "args": args}


def drive(lane: str | None = None, speed: float | None = None) -> Json:
    out: Json = {"kind": "drive_lane"}
    if lane is not None:
        out["lane"] = lane
    if speed is not None:
        out["speed"] = speed
    return out


def arrange(categories: str | list[str], shape: str, location: Json, count: int | None = None, **more: Any) -> Json:
    args: Json = {"categories": [categories] if isinstance(categories, str) else categories, "shape": shape,
                  "location": location}
    if count is not None:
        args["count"] = count
    args.update(more)
    return {"tool": "arrange_assets", "args": args}


def place(asset: str, location: Json, **more: Any) -> Json:
    return {"tool": "place_asset", "args": {"asset": asset, "location": location, **more}}


def move(asset: str, **more: Any) -> Json:
    return {"tool": "move_asset", "args": {"asset": asset, **more}}


def behave(asset: str, kind: str, **more: Any) -> Json:
    return {"tool": "set_behaviour", "args": {"asset": asset, "behaviour": {"kind": kind, **more}}}


def remove(*assets: str, **more: Any) -> Json:
    args: Json = {}
    if assets:
        args["assets"] = list(assets)
    args.update(more)
    return {"tool": "remove_assets", "args": args}


def paint(*assets: str, **more: Any) -> Json:
    args: Json = {}
    if assets:
        args["assets"] = list(assets)
    args.update(more)
    return {"tool": "set_asset_appearance", "args": args}


def clock(time: str) -> Json:
    return call("set_time_of_day", time=time)


def weather(kind: str, intensity: float | None = None) -> Json:
    return call("set_weather", kind=kind) if intensity is None else call("set_weather", kind=kind, intensity=intensity)


def lights(**more: Any) -> Json:
    return call("set_lighting", **more)


def find(**more: Any) -> Json:
    return call("find_assets", **more)


def measure(a: str, b: str) -> Json:
    return call("measure_distance", a=a, b=b)


ENVIRONMENT = call("describe_environment")


# --- Cases ------------------------------------------------------------------------------------
def turn(prompt: str, *calls: Json, planned: bool = False) -> Json:
    """An earlier turn: replayed as given, or (`planned`) planned by the planner under test."""
    out: Json = {"prompt": prompt, "calls": list(calls)}
    if planned:
        out["planned"] = True
    return out


def case(task: str, grade: str, name: str, prompt: str, checks: list[Json], reference: list[Json], *,
         setup: tuple[Json, ...] = (), alternatives: tuple[list[Json], ...] = (), tags: tuple[str, ...] = ()) -> Json:
    out: Json = {"id": f"{SUITE}.{task}.{grade}.{name}", "world": "campus"}
    if setup:
        out["setup"] = list(setup)
    out.update(prompt=prompt, task=task, grade=grade,
               tags=[SUITE, *(["multi_turn"] if setup else []), *tags], checks=checks)
    if alternatives:
        out["alternatives"] = list(alternatives)
    out["reference"] = reference
    return out


def impossible(task: str, grade: str, name: str, prompt: str, attempt: Json, *,
               setup: tuple[Json, ...] = ()) -> Json:
    """A request the world cannot do: the right outcome is a refusal that changes nothing."""
    return case(task, grade, name, prompt, [REFUSED, unchanged()], [attempt], setup=setup, tags=("impossible",))


def question(grade: str, name: str, prompt: str, answer: Json, reference: list[Json], *,
             setup: tuple[Json, ...] = (), tags: tuple[str, ...] = ()) -> Json:
    """A search case: the answer says it, and nothing in the scene changes."""
    return case("search", grade, name, prompt, [answer, unchanged()], reference, setup=setup, tags=tags)


COMPOUND = ("compound",)
LIBRARY_CONES = turn("Put three cones in front of the library entrance.",
                     add("traffic_cone", 3, where("in_front_of", LIBRARY)))


SEARCH = [
    # direct
    question("direct", "lamps_main_street",
             "How many street lamps are there along Main Street? I want to talk my learner through the lighting.",
             says(all_of=("12",)), [find(category="street_light", lane="Main Street")]),
    question("direct", "nearest_bin_bus_stop", "Where's the nearest bin to the bus stop?",
             says(any_of=(BIN,)), [find(category="trash_bin", nearest_to=BUS_STOP)]),
    question("direct", "ego_to_junction", "How far is our test car from the junction right now?",
             says(any_of=("60", "51")), [measure(EGO, JUNCTION)]),
    question("direct", "campus_drive_lanes", "Which lanes does Campus Drive have?",
             says(all_of=("northbound", "southbound")), [call("find_lanes", road="Campus Drive")]),
    question("direct", "cars_in_lot_b", "List the cars parked in lot B, please.",
             says(all_of=(CAR_1, CAR_2)), [find(category="cars", near=LOT_B, within=25)]),
    question("direct", "hydrant_near_jtekt", "Is there a fire hydrant within 30 metres of the JTEKT entrance?",
             says(any_of=(HYDRANT,)), [find(category="fire_hydrant", near=JTEKT, within=30)]),
    question("direct", "signals_at_junction", "How many traffic lights are there at the main crossroads?",
             says(all_of=(SIGNAL_SOUTH, SIGNAL_NORTH)), [find(category="traffic_light", near=JUNCTION, within=15)]),
    question("direct", "closest_place_fountain", "What's the closest named place to the fountain?",
             says(any_of=("JTEKT",)), [call("find_landmarks", nearest_to=FOUNTAIN)]),
    question("direct", "lamps_and_nearest",
             "How many street lights are there in total, and which one is closest to the bus stop?",
             says(all_of=("12", LAMP_BY_BUS_STOP)),
             [find(category="street_light"), find(category="street_light", nearest_to=BUS_STOP)], tags=COMPOUND),
    # indirect
    question("indirect", "what_by_bus_stop",
             "One of our drivers says she nearly clipped something standing by the bus stop. "
             "I'd like to know what's actually there.",
             says(all_of=(BENCH, BIN)), [find(near=BUS_STOP, within=10)]),
    question("indirect", "campus_drive_clear",
             "Our crew needs Campus Drive empty before they start, so I need to know whether anything "
             "is standing in the road there.",
             says(any_of=("0", "no", "nothing", "none"), none_of=(EASTBOUND,)),
             [find(on_lane=True, lane="Campus Drive")]),
    question("indirect", "car_parks_apart",
             "For my piece I'd like to mention how far apart the two car parks are.",
             says(any_of=("136.4", "136", "116.7", "117")), [measure(LOT_A, LOT_B)]),
    question("indirect", "way_to_main_gate",
             "My grandson wants to walk from the library to the main gate. Which direction should he head?",
             says(any_of=("west",)), [measure(LIBRARY, MAIN_GATE)]),
    question("indirect", "ego_lane_for_report",
             "My supervisor asked me to write down which lane the ego car is driving in.",
             says(any_of=(EASTBOUND, "eastbound")), [find(category="ego_vehicle", on_lane=True)]),
    question("indirect", "doors_apart",
             "I'm scripting the demo voice-over and need the straight-line distance from the Engineering Hall "
             "doors to the JTEKT doors.",
             says(any_of=("77.5", "78")), [measure(ENGINEERING, JTEKT)]),
    question("indirect", "stop_sign_confirm",
             "A driver mentioned a stop sign near the west crosswalk. I want to confirm it's really in the model.",
             says(any_of=(STOP_SIGN,)), [find(category="stop_sign", near=WEST_CROSSWALK, within=15)]),
    question("indirect", "distance_and_weather",
             "Two things for my notes: how far the Library entrance is from the Student Union entrance, "
             "and what the weather's doing.",
             says(all_of=("clear",), any_of=("90.9", "91")), [measure(LIBRARY, UNION), ENVIRONMENT], tags=COMPOUND),
    question("indirect", "cones_in_lot_a",
             "Can you check the cones really went down where I asked? My learner needs them for the drill.",
             says(any_of=("traffic_cone_1", "4")), [find(category="traffic_cone", near=LOT_A, within=30)],
             setup=(turn("Put four cones in parking lot A.", add("traffic_cone", 4, where("at", LOT_A))),)),
    # vague
    question("vague", "whats_ahead", "what's in the way up ahead?",
             says(any_of=("cement_rubble_1", "rubble")), [find(on_lane=True, lane=EASTBOUND)],
             setup=(turn("Drop some rubble in the road 30 metres in front of our car.",
                         add("cement_rubble", 1, where("at", EGO, along_m=30))),)),
    question("vague", "around_fountain", "what's around the fountain", says(all_of=("tree_2",)),
             [find(near=FOUNTAIN, within=20)]),
    question("vague", "time_weather", "time + weather?", says(all_of=("12:00", "clear")), [ENVIRONMENT]),
    question("vague", "nearest_lamp_library", "nearest lamp to the library?", says(any_of=(LAMP_BY_BUS_STOP,)),
             [find(category="street_light", nearest_to=LIBRARY)]),
    question("vague", "anyone_about", "time, weather, and is anyone walking about?",
             says(all_of=("12:00", "clear"), any_of=("0", "no", "nobody", "none")),
             [ENVIRONMENT, find(category="pedestrian")], tags=COMPOUND),
    question("vague", "is_it_dark", "is it dark out there now?", says(any_of=("21:00", "(night)")), [ENVIRONMENT],
             setup=(turn("Set it to nine in the evening.", clock("21:00"), planned=True),)),
    question("vague", "bench_there_now", "is it there now?", says(any_of=("bench_2",)),
             [find(category="bench", near=EAST_GATE, within=20)],
             setup=(turn("put a bench by the east gate", add("bench", 1, where("at", EAST_GATE)), planned=True),)),
    impossible("search", "vague", "bus_shelter_nearest", "nearest bus shelter to the library?",
               find(category="bus shelter", nearest_to=LIBRARY)),
    # erroneous
    question("erroneous", "lamps_main_street", "how many stret lights along main stret?",
             says(all_of=("12",)), [find(category="street_light", lane="Main Street")]),
    question("erroneous", "nearest_bin", "wheres the closest bin too the bus stop", says(any_of=(BIN,)),
             [find(category="trash_bin", nearest_to=BUS_STOP)]),
    question("erroneous", "ego_to_junction", "how far is the ego form the junciton?", says(any_of=("60", "51")),
             [measure(EGO, JUNCTION)]),
    question("erroneous", "weather_now", "whats teh weather like rigth now", says(any_of=("clear",)), [ENVIRONMENT]),
    question("erroneous", "hydrant_jtekt", "is their a hydrant near the JTEKT entrence?", says(any_of=(HYDRANT,)),
             [find(category="fire_hydrant", near=JTEKT, within=30)]),
    question("erroneous", "ego_lane", "which lane dose the ego drive in", says(any_of=(EASTBOUND, "eastbound")),
             [find(category="ego_vehicle", on_lane=True)]),
    question("erroneous", "cars_lot_b", "how many car are park in lot B?", says(any_of=(CAR_1, CAR_2)),
             [find(category="cars", near=LOT_B, within=25)]),
    question("erroneous", "cones_count", "how many cone is there now", says(all_of=("4",)),
             [find(category="traffic_cone")],
             setup=(turn("Put four cones at the entrance to lot A.", add("traffic_cone", 4, where("at", LOT_A_ENTRANCE))),)),
    impossible("search", "erroneous", "hospital_distance", "how far is the hosptial from the main gate",
               measure("hospital", MAIN_GATE)),
]


ADDITION = [
    # direct
    case("addition", "direct", "cones_library", "Put three traffic cones in front of the Library entrance.",
         [delta("traffic_cone", 3), near(LIBRARY, 10, "traffic_cone"), unchanged("traffic_cone")],
         [add("traffic_cone", 3, where("in_front_of", LIBRARY))]),
    case("addition", "direct", "cyclist_ahead",
         "Add a cyclist riding east on Main Street, about 20 metres ahead of our car.",
         [delta("bicycle", 1), does("drive_lane", "bicycle", lane=EASTBOUND),
          relative("in_front_of", EGO, 30, "bicycle", tolerance_deg=20), unchanged("bicycle")],
         [add("bicycle", 1, where("at", EGO, along_m=20), behaviour=drive(EASTBOUND))]),
    case("addition", "direct", "sign_north_crosswalk", "Add a road works sign next to the north crosswalk.",
         [delta("construction_sign", 1), near(NORTH_CROSSWALK, 8, "construction_sign"), unchanged("construction_sign")],
         [add("construction_sign", 1, where("next_to", NORTH_CROSSWALK))]),
    case("addition", "direct", "red_suv_lot_a", "Add a red SUV, parked, in parking lot A.",
         [delta("suv", 1), near(LOT_A, 1, "suv"), look("red", category="suv", scope="added"),
          does("parked", "suv"), unchanged("suv")],
         [add("suv", 1, where("at", LOT_A), colour="red")]),
    case("addition", "direct", "bus_westbound", "Add a bus driving along Main Street in the westbound lane.",
         [delta("bus", 1), does("drive_lane", "bus", lane=WESTBOUND), unchanged("bus")],
         [add("bus", 1, behaviour=drive(WESTBOUND))]),
    case("addition", "direct", "bench_fountain", "Put a bench beside the fountain.",
         [delta("bench", 1), near(FOUNTAIN, 6, "bench"), unchanged("bench")],
         [add("bench", 1, where("at", FOUNTAIN))]),
    case("addition", "direct", "two_people_bus_stop", "Add two pedestrians waiting at the bus stop.",
         [delta("pedestrian", 2), near(BUS_STOP, 6, "pedestrian"), unchanged("pedestrian")],
         [add("pedestrian", 2, where("at", BUS_STOP))]),
    case("addition", "direct", "bus_and_lorry", "Add a bus heading east on Main Street and a lorry heading west.",
         [delta("bus", 1), delta("truck", 1), does("drive_lane", "bus", lane=EASTBOUND),
          does("drive_lane", "truck", lane=WESTBOUND), unchanged("bus", "truck")],
         [add("bus", 1, behaviour=drive(EASTBOUND)), add("truck", 1, behaviour=drive(WESTBOUND))], tags=COMPOUND),
    impossible("addition", "direct", "bus_shelter", "Put a bus shelter at the bus stop.",
               add("bus shelter", 1, where("at", BUS_STOP))),
    # indirect
    case("addition", "indirect", "near_miss_cyclist",
         "One of our drivers says a kid on a bike shot across the crossing just before the junction, right in "
         "front of him. It was drizzling and getting on for 6pm. Can you set that up?",
         [delta("bicycle", 1), does(["cross_road", "follow_path", "jaywalk"], "bicycle", crosses_lane=EASTBOUND),
          near(WEST_CROSSWALK, 10, "bicycle"), env(weather=["rain"], intensity_max=0.5, time_from="17:00",
                                                  time_to="18:30"),
          unchanged("bicycle", env=True)],
         [add("bicycle", 1, where("at", WEST_CROSSWALK), behaviour={"kind": "cross_road"}),
          weather("rain", 0.25), clock("17:50")], tags=COMPOUND),
    case("addition", "indirect", "signs_library",
         "We're resurfacing outside the library next week, so I'll need a couple of warning signs put up by "
         "its entrance.",
         [delta("construction_sign", 2, 3), near(LIBRARY, 10, "construction_sign"), unchanged("construction_sign")],
         [add("construction_sign", 2, where("in_front_of", LIBRARY))]),
    case("addition", "indirect", "car_to_park_beside",
         "My learner needs something to practise parking beside. Could you leave a car in lot A for her?",
         [delta(["passenger_car", "suv"], 1), near(LOT_A, 1, ["passenger_car", "suv"]),
          unchanged("passenger_car", "suv")],
         [add("passenger_car", 1, where("at", LOT_A))]),
    case("addition", "indirect", "students_at_union",
         "The demo feels empty. I'd like a handful of students hanging around outside the Student Union doors.",
         [delta("pedestrian", 3, 7), near(UNION, 12, "pedestrian"), unchanged("pedestrian")],
         [add("pedestrian", 4, where("at", UNION))]),
    case("addition", "indirect", "oncoming_lorry",
         "I want readers to see how the car copes with a lorry coming towards it on Main Street.",
         [delta("truck", 1), does("drive_lane", "truck", lane=WESTBOUND), unchanged("truck")],
         [add("truck", 1, behaviour=drive(WESTBOUND))]),
    case("addition", "indirect", "tree_east_gate",
         "It looks a bit bare over by the east gate. A tree there would be lovely.",
         [delta("tree", 1), near(EAST_GATE, 12, "tree"), unchanged("tree")],
         [add("tree", 1, where("at", EAST_GATE))]),
    case("addition", "indirect", "debris_ahead",
         "The test sheet says there's debris lying in the ego's lane roughly 40 m ahead of it.",
         [delta("cement_rubble", 1, 3), in_lane(EASTBOUND, "cement_rubble"),
          relative("in_front_of", EGO, 55, "cement_rubble", tolerance_deg=20), unchanged("cement_rubble")],
         [add("cement_rubble", 1, where("at", EGO, along_m=40))]),
    case("addition", "indirect", "another_blue_car",
         "Lovely. Now another one exactly like it, just behind it.",
         [delta("passenger_car", 1), look("blue", category="passenger_car", scope="added"),
          near(JTEKT, 20, "passenger_car"), unchanged("passenger_car")],
         [add("passenger_car", 1, where("behind", "passenger_car_3"), colour="blue")],
         setup=(turn("Add a blue car in front of the JTEKT entrance.",
                     add("passenger_car", 1, where("in_front_of", JTEKT), colour="blue"), planned=True),)),
    impossible("addition", "indirect", "deer",
               "One of our drivers swears a deer ran out on Campus Drive. Can you put one in for the reconstruction?",
               add("deer", 1, where("in_lane", NORTHBOUND))),
    # vague
    case("addition", "vague", "more_cones", "more cones",
         [delta("traffic_cone", 1, 10), near(LIBRARY, 15, "traffic_cone"), unchanged("traffic_cone")],
         [add("traffic_cone", 3, where("in_front_of", LIBRARY))], setup=(LIBRARY_CONES,)),
    case("addition", "vague", "few_people_bus_stop", "a few people at the bus stop",
         [delta("pedestrian", 2, 5), near(BUS_STOP, 8, "pedestrian"), unchanged("pedestrian")],
         [add("pedestrian", 3, where("at", BUS_STOP))]),
    case("addition", "vague", "traffic_campus_drive", "some traffic on Campus Drive",
         [delta(VEHICLES, 1, 10), does("drive_lane", VEHICLES), unchanged(*VEHICLES)],
         [add("passenger_car", 2, where("in_lane", NORTHBOUND), behaviour=drive(NORTHBOUND))],
         alternatives=([does("drive_lane", VEHICLES, require_all=False, lane=NORTHBOUND)],
                       [does("drive_lane", VEHICLES, require_all=False, lane=SOUTHBOUND)])),
    case("addition", "vague", "lamp_by_bench", "a lamp by the bench",
         [delta("street_light", 1), near(BENCH, 6, "street_light"), unchanged("street_light")],
         [add("street_light", 1, where("next_to", BENCH))]),
    case("addition", "vague", "bin_or_two_library", "a bin or two by the library",
         [delta("trash_bin", 1, 2), near(LIBRARY, 10, "trash_bin"), unchanged("trash_bin")],
         [add("trash_bin", 1, where("at", LIBRARY))]),
    case("addition", "vague", "someone_crossing", "someone crossing at the west crosswalk",
         [delta("pedestrian", 1), does(["cross_road", "follow_path"], "pedestrian", crosses_lane=EASTBOUND),
          near(WEST_CROSSWALK, 8, "pedestrian"), unchanged("pedestrian")],
         [add("pedestrian", 1, where("at", WEST_CROSSWALK), behaviour={"kind": "cross_road"})]),
    case("addition", "vague", "truck_lot_b", "a truck somewhere in lot B",
         [delta("truck", 1), near(LOT_B, 1, "truck"), unchanged("truck")],
         [add("truck", 1, where("at", LOT_B))]),
    case("addition", "vague", "roadworks_junction", "bit of roadworks clutter near the junction",
         [delta(ROADWORKS, 1, 15), near(JUNCTION, 15, ROADWORKS), unchanged(*ROADWORKS)],
         [add("traffic_cone", 4, where("at", JUNCTION)), add("construction_sign", 1, where("next_to", "traffic_cone_1"))]),
    impossible("addition", "vague", "thousand_people", "loads of people outside the Student Union, like a thousand",
               add("pedestrian", 1000, where("at", UNION))),
    # erroneous
    case("addition", "erroneous", "cones_library", "ad 2 cones infront of the libary door",
         [delta("traffic_cone", 2), near(LIBRARY, 10, "traffic_cone"), unchanged("traffic_cone")],
         [add("traffic_cone", 2, where("in_front_of", LIBRARY))]),
    case("addition", "erroneous", "bike_north_crosswalk", "put a bycicle on the north crosswalk",
         [delta("bicycle", 1), near(NORTH_CROSSWALK, 8, "bicycle"), unchanged("bicycle")],
         [add("bicycle", 1, where("at", NORTH_CROSSWALK))]),
    case("addition", "erroneous", "truck_west", "add a trcuk driving west on mian street",
         [delta("truck", 1), does("drive_lane", "truck", lane=WESTBOUND), unchanged("truck")],
         [add("truck", 1, behaviour=drive(WESTBOUND))]),
    case("addition", "erroneous", "bench_fountain", "can you put one bench nearby of the foutain",
         [delta("bench", 1), near(FOUNTAIN, 6, "bench"), unchanged("bench")],
         [add("bench", 1, where("at", FOUNTAIN))]),
    case("addition", "erroneous", "person_bus_stop", "add pedestrain waiting at the bustop",
         [delta("pedestrian", 1), near(BUS_STOP, 6, "pedestrian"), unchanged("pedestrian")],
         [add("pedestrian", 1, where("at", BUS_STOP))]),
    case("addition", "erroneous", "blue_next_to_red", "add anotehr one but blue, next too it",
         [delta(["passenger_car", "suv"], 1), look("blue", category=["passenger_car", "suv"], scope="added"),
          near(LOT_A, 3, ["passenger_car", "suv"]), unchanged("passenger_car", "suv")],
         [add("passenger_car", 1, where("next_to", "passenger_car_3"), colour="blue")],
         setup=(turn("Put a red car in parking lot A.", add("passenger_car", 1, where("at", LOT_A), colour="red"),
                     planned=True),)),
    case("addition", "erroneous", "bus_and_truck", "add a bus going east on main st and a truk going west",
         [delta("bus", 1), delta("truck", 1), does("drive_lane", "bus", lane=EASTBOUND),
          does("drive_lane", "truck", lane=WESTBOUND), unchanged("bus", "truck")],
         [add("bus", 1, behaviour=drive(EASTBOUND)), add("truck", 1, behaviour=drive(WESTBOUND))], tags=COMPOUND),
    case("addition", "erroneous", "barriers_jtekt", "put two barier in front off the JTEKT enterance",
         [delta("road_barrier", 2), near(JTEKT, 10, "road_barrier"), unchanged("road_barrier")],
         [add("road_barrier", 2, where("in_front_of", JTEKT))]),
    impossible("addition", "erroneous", "car_on_library_roof", "park a car on top of the libary roof",
               add("passenger_car", 1, spot(-41.0, -30.0))),
]


REMOVAL = [
    # direct
    case("removal", "direct", "bench_bus_stop", "Remove the bench at the bus stop.",
         [gone(BENCH), unchanged(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "direct", "suv_lot_b", "Remove the SUV from parking lot B.",
         [gone(SUV), unchanged(assets=[SUV])], [remove(SUV)]),
    case("removal", "direct", "all_trees", "Delete all the trees.",
         [total("tree", 0), unchanged("tree")], [remove(category="tree")]),
    case("removal", "direct", "hydrant", "Take the fire hydrant out.",
         [gone(HYDRANT), unchanged(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "direct", "lamp_nearest_bus_stop", "Remove the street light nearest the bus stop.",
         [gone(LAMP_BY_BUS_STOP), unchanged(assets=[LAMP_BY_BUS_STOP])],
         [remove(category="street_light", near=BUS_STOP, count=1)]),
    case("removal", "direct", "two_of_the_cones", "Remove two of the cones.",
         [delta("traffic_cone", -2), unchanged("traffic_cone")], [remove(category="traffic_cone", count=2)],
         setup=(turn("Put five cones in front of the library entrance.",
                     add("traffic_cone", 5, where("in_front_of", LIBRARY))),)),
    case("removal", "direct", "stop_sign", "Remove the stop sign by the west crosswalk.",
         [gone(STOP_SIGN), unchanged(assets=[STOP_SIGN])], [remove(STOP_SIGN)]),
    case("removal", "direct", "cars_not_suv", "Remove both cars in lot B but leave the SUV.",
         [gone(CAR_1, CAR_2), kept(SUV), unchanged(assets=[CAR_1, CAR_2])], [remove(CAR_1, CAR_2)]),
    impossible("removal", "direct", "campus_drive", "Remove Campus Drive.", remove("Campus Drive")),
    # indirect
    case("removal", "indirect", "tree_blocks_view",
         "A driver said the tree next to the library hides the road from view. I want to see the scene without it.",
         [gone(TREE_BY_LIBRARY), unchanged(assets=[TREE_BY_LIBRARY])], [remove(TREE_BY_LIBRARY)]),
    case("removal", "indirect", "clear_lot_b",
         "The parked cars in lot B keep distracting my learners. Clear the lot out, SUV included.",
         [gone(CAR_1, CAR_2, SUV), unchanged("passenger_car", "suv")], [remove(CAR_1, CAR_2, SUV)]),
    case("removal", "indirect", "bin_taken_away",
         "The council is taking the bin at the bus stop away, so it shouldn't be in the model any more.",
         [gone(BIN), unchanged(assets=[BIN])], [remove(BIN)]),
    case("removal", "indirect", "no_lights_east",
         "For the demo I don't want any street lights east of the junction.",
         [gone(*LIGHTS_EAST), kept(*LIGHTS_WEST), unchanged("street_light")], [remove(*LIGHTS_EAST)]),
    case("removal", "indirect", "signals_fail",
         "I'm writing about what happens when signals fail, so show me the junction with no traffic lights at all.",
         [gone(SIGNAL_SOUTH, SIGNAL_NORTH), unchanged("traffic_light")], [remove(category="traffic_light")]),
    case("removal", "indirect", "cones_too_much",
         "Those cones are a bit much. I'd rather they weren't there at all.",
         [total("traffic_cone", 0), unchanged("traffic_cone")], [remove(category="traffic_cone")],
         setup=(turn("Put four cones in a row in front of the library.",
                     arrange("traffic_cone", "line", where("in_front_of", LIBRARY), 4), planned=True),)),
    case("removal", "indirect", "fountain_trees_for_benches",
         "The trees by the fountain block my view of it. Take them away and put a couple of benches there "
         "instead so I can sit.",
         [gone(*FOUNTAIN_TREES), delta("bench", 2, 3), near(FOUNTAIN, 10, "bench"),
          unchanged("bench", assets=FOUNTAIN_TREES)],
         [remove(*FOUNTAIN_TREES), add("bench", 2, where("at", FOUNTAIN))], tags=COMPOUND),
    case("removal", "indirect", "lorry_gone",
         "In the dashcam footage the lorry has already gone, so it shouldn't be in here either.",
         [total("truck", 0), unchanged("truck")], [remove(category="truck")],
         setup=(turn("Put a lorry in our lane 30 metres ahead of us.", add("truck", 1, where("at", EGO, along_m=30))),)),
    impossible("removal", "indirect", "student_union",
               "The Student Union is due to be knocked down, so take the building out of the model.",
               remove("Student Union")),
    # vague
    case("removal", "vague", "fewer_trees", "fewer trees",
         [delta("tree", -3, -1), unchanged("tree")], [remove(category="tree", count=2)]),
    case("removal", "vague", "too_many_cones", "too many cones",
         [delta("traffic_cone", -5, -1), unchanged("traffic_cone")], [remove(category="traffic_cone", count=3)],
         setup=(turn("Put six cones in front of the library.", add("traffic_cone", 6, where("in_front_of", LIBRARY))),)),
    case("removal", "vague", "bus_stop_clutter", "clear the clutter away from the bus stop",
         [delta(["bench", "trash_bin"], -2, -1), unchanged("bench", "trash_bin")], [remove(BENCH, BIN)]),
    case("removal", "vague", "lose_suv", "lose the SUV", [gone(SUV), unchanged(assets=[SUV])], [remove(SUV)]),
    case("removal", "vague", "no_people_after_all", "actually, no people",
         [total("pedestrian", 0), unchanged("pedestrian")], [remove(category="pedestrian")],
         setup=(turn("Add a few people at the bus stop.", add("pedestrian", 3, where("at", BUS_STOP)), planned=True),)),
    case("removal", "vague", "north_side_lamps", "the lamps on the north side of Main Street, get rid of them",
         [gone(*LIGHTS_NORTH), kept(*LIGHTS_SOUTH), unchanged("street_light")], [remove(*LIGHTS_NORTH)]),
    case("removal", "vague", "parked_cars", "strip out the parked cars",
         [gone(CAR_1, CAR_2), unchanged("passenger_car", "suv")], [remove(CAR_1, CAR_2, SUV)]),
    case("removal", "vague", "one_less_fountain_tree", "one less tree by the fountain",
         [delta("tree", -1), unchanged(assets=FOUNTAIN_TREES)], [remove("tree_2")]),
    impossible("removal", "vague", "our_car", "just get rid of our car, it's in the way", remove(EGO)),
    # erroneous
    case("removal", "erroneous", "bench", "remvoe the bench by the bus stpo",
         [gone(BENCH), unchanged(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "erroneous", "trees_but_library", "delet all the tree's exept the one by the libary",
         [gone("tree_2", "tree_3", TREE_NORTH_OF_LOT_A), kept(TREE_BY_LIBRARY), unchanged("tree")],
         [remove("tree_2", "tree_3", TREE_NORTH_OF_LOT_A)]),
    case("removal", "erroneous", "suv", "take away the suv from parkinglot B",
         [gone(SUV), unchanged(assets=[SUV])], [remove(SUV)]),
    case("removal", "erroneous", "hydrant", "remove the hydrent",
         [gone(HYDRANT), unchanged(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "erroneous", "cars_not_suv", "remove the too cars in lot B, not the suv",
         [gone(CAR_1, CAR_2), kept(SUV), unchanged(assets=[CAR_1, CAR_2])], [remove(CAR_1, CAR_2)]),
    case("removal", "erroneous", "stop_sign", "pls remove stop sing next to crosswalk",
         [gone(STOP_SIGN), unchanged(assets=[STOP_SIGN])], [remove(STOP_SIGN)]),
    case("removal", "erroneous", "my_cones", "remove all the cone's i put",
         [total("traffic_cone", 0), unchanged("traffic_cone")], [remove(category="traffic_cone")],
         setup=(turn("Put four cones in parking lot A.", add("traffic_cone", 4, where("at", LOT_A))),)),
    case("removal", "erroneous", "bench_and_bin", "remove bench and also the bin, both from bus stop",
         [gone(BENCH, BIN), unchanged(assets=[BENCH, BIN])], [remove(BENCH), remove(BIN)], tags=COMPOUND),
    case("removal", "erroneous", "south_signal", "remove traffic light near to junction which is on south side",
         [gone(SIGNAL_SOUTH), kept(SIGNAL_NORTH), unchanged(assets=[SIGNAL_SOUTH])], [remove(SIGNAL_SOUTH)]),
]


POSITIONING = [
    # direct
    case("positioning", "direct", "bench_jtekt", "Put the bench in front of the JTEKT building entrance.",
         [near(JTEKT, 8, asset=BENCH), unchanged(assets=[BENCH])], [place(BENCH, where("in_front_of", JTEKT))]),
    case("positioning", "direct", "suv_lot_a", "Move the SUV over to parking lot A.",
         [near(LOT_A, 1, asset=SUV), unchanged(assets=[SUV])], [place(SUV, where("at", LOT_A))]),
    case("positioning", "direct", "bin_next_to_bench", "Put the rubbish bin right next to the bench.",
         [near(BENCH, 2.5, asset=BIN), unchanged(assets=[BIN])], [place(BIN, where("next_to", BENCH))]),
    case("positioning", "direct", "ego_northbound",
         "Put the ego in the northbound lane of Campus Drive, about 25 m south of the junction.",
         [in_lane(NORTHBOUND, asset=EGO, aligned=True), near_point(1.75, -25.0, 10, asset=EGO),
          unchanged(assets=[EGO])],
         [place(EGO, spot(1.75, -25.0))]),
    case("positioning", "direct", "hydrant_engineering",
         "Place the fire hydrant on the pavement outside the Engineering Hall entrance.",
         [near(ENGINEERING, 12, asset=HYDRANT), surface(["sidewalk", "ground"], asset=HYDRANT),
          unchanged(assets=[HYDRANT])],
         [place(HYDRANT, where("on_sidewalk", ENGINEERING))]),
    case("positioning", "direct", "bin_and_bench",
         "Put the bin next to the fire hydrant and the bench in front of the Library entrance.",
         [near(HYDRANT, 3, asset=BIN), near(LIBRARY, 8, asset=BENCH), unchanged(assets=[BIN, BENCH])],
         [place(BIN, where("next_to", HYDRANT)), place(BENCH, where("in_front_of", LIBRARY))], tags=COMPOUND),
    case("positioning", "direct", "suv_behind_ego", "Place the SUV 15 metres behind the ego, in the same lane.",
         [in_lane(EASTBOUND, asset=SUV), relative("behind", EGO, 25, asset=SUV, tolerance_deg=20),
          unchanged(assets=[SUV])],
         [place(SUV, where("behind", EGO, along_m=-15))]),
    case("positioning", "direct", "person_to_crosswalk", "Put the pedestrian on the west crosswalk.",
         [near(WEST_CROSSWALK, 5, asset="pedestrian_1"), unchanged(assets=["pedestrian_1"])],
         [place("pedestrian_1", where("at", WEST_CROSSWALK))],
         setup=(turn("Add a pedestrian at the bus stop.", add("pedestrian", 1, where("at", BUS_STOP)), planned=True),)),
    impossible("positioning", "direct", "bench_inside_jtekt", "Put the bench inside the JTEKT Building.",
               place(BENCH, spot(37.0, 29.0))),
    # indirect
    case("positioning", "indirect", "suv_driveway_mouth",
         "In the real incident the SUV was sitting right at the mouth of lot B's driveway, and that's where I "
         "need it to be.",
         [near(LOT_B_ENTRANCE, 10, asset=SUV), unchanged(assets=[SUV])], [place(SUV, where("at", LOT_B_ENTRANCE))]),
    case("positioning", "indirect", "learner_starts_in_lot_a",
         "I'd like my learner to start off in the car park by the main gate rather than out on the road.",
         [near(LOT_A, 1, asset=EGO), unchanged(assets=[EGO])], [place(EGO, where("at", LOT_A))]),
    case("positioning", "indirect", "bin_to_union",
         "The bin is being moved to the Student Union doors permanently.",
         [near(UNION, 6, asset=BIN), unchanged(assets=[BIN])], [place(BIN, where("at", UNION))]),
    case("positioning", "indirect", "bench_south_of_fountain",
         "The bench would look better in the demo sitting just south of the fountain.",
         [relative("in_front_of", FOUNTAIN, 10, asset=BENCH), unchanged(assets=[BENCH])],
         [place(BENCH, where("in_front_of", FOUNTAIN))]),
    case("positioning", "indirect", "lorry_at_junction",
         "Readers should see the lorry waiting at the junction, not tucked away in the car park.",
         [near(JUNCTION, 12, asset="truck_1"), unchanged(assets=["truck_1"])],
         [place("truck_1", where("at", JUNCTION))],
         setup=(turn("Put a lorry in parking lot A.", add("truck", 1, where("at", LOT_A))),)),
    case("positioning", "indirect", "tree_for_shade",
         "My wife thinks the tree by the library would give more shade over in lot B.",
         [near(LOT_B, 2, asset=TREE_BY_LIBRARY), unchanged(assets=[TREE_BY_LIBRARY])],
         [place(TREE_BY_LIBRARY, where("at", LOT_B))]),
    case("positioning", "indirect", "stop_sign_campus_side",
         "The spec puts the stop sign at the north crosswalk on Campus Drive, not where it is on Main Street.",
         [near(NORTH_CROSSWALK, 8, asset=STOP_SIGN), unchanged(assets=[STOP_SIGN])],
         [place(STOP_SIGN, where("next_to", NORTH_CROSSWALK))]),
    case("positioning", "indirect", "cyclist_was_at_north",
         "Our driver now says the cyclist was actually waiting at the north crossing.",
         [near(NORTH_CROSSWALK, 6, "bicycle", scope="touched"), unchanged("bicycle")],
         [place("bicycle_1", where("at", NORTH_CROSSWALK))],
         setup=(turn("Add a cyclist on the pavement by the bus stop.",
                     add("bicycle", 1, where("on_sidewalk", BUS_STOP)), planned=True),)),
    impossible("positioning", "indirect", "petrol_station",
               "The SUV should be at the petrol station, where the driver had just filled up.",
               place(SUV, where("at", "petrol station"))),
    # vague
    case("positioning", "vague", "bin_by_hydrant", "bin over by the hydrant",
         [near(HYDRANT, 4, asset=BIN), unchanged(assets=[BIN])], [place(BIN, where("next_to", HYDRANT))]),
    case("positioning", "vague", "suv_onto_street", "SUV out of the lot and onto the street",
         [in_lane(None, asset=SUV), unchanged(assets=[SUV])], [place(SUV, where("in_lane", LOT_B_ENTRANCE))]),
    case("positioning", "vague", "ego_east_gate", "ego over to the east gate end",
         [near(EAST_GATE, 15, asset=EGO), unchanged(assets=[EGO])], [place(EGO, where("at", EAST_GATE))]),
    case("positioning", "vague", "bin_to_junction", "the bin, somewhere near the junction",
         [near(JUNCTION, 8, asset=BIN), surface(["sidewalk", "ground"], asset=BIN), unchanged(assets=[BIN])],
         [place(BIN, where("next_to", SIGNAL_SOUTH))]),
    case("positioning", "vague", "stop_sign_opposite", "stop sign to the other side of the road, opposite where it is",
         [near_point(-13.5, 5.5, 5, asset=STOP_SIGN), unchanged(assets=[STOP_SIGN])],
         [place(STOP_SIGN, spot(-13.5, 5.5))]),
    case("positioning", "vague", "people_to_fountain", "the people, by the fountain instead",
         [near(FOUNTAIN, 10, "pedestrian", scope="all"), unchanged("pedestrian")],
         [place("pedestrian_1", where("at", FOUNTAIN)), place("pedestrian_2", where("at", FOUNTAIN))],
         setup=(turn("Add two pedestrians at the bus stop.", add("pedestrian", 2, where("at", BUS_STOP))),)),
    case("positioning", "vague", "suv_nearer_library", "park the suv closer to the library",
         [near(LIBRARY, 20, asset=SUV), unchanged(assets=[SUV])], [place(SUV, where("at", LIBRARY))]),
    case("positioning", "vague", "lorry_east_gate_instead", "hmm, east gate instead",
         [near(EAST_GATE, 15, "truck", scope="touched"), unchanged("truck")],
         [place("truck_1", where("at", EAST_GATE))],
         setup=(turn("Put a lorry in lot A.", add("truck", 1, where("at", LOT_A)), planned=True),)),
    case("positioning", "vague", "red_by_blue", "put the red one next to the blue one",
         [near("passenger_car_4", 4, asset="passenger_car_3"), unchanged(assets=["passenger_car_3"])],
         [place("passenger_car_3", where("next_to", "passenger_car_4"))],
         setup=(turn("Add a red car in front of the Library entrance.",
                     add("passenger_car", 1, where("in_front_of", LIBRARY), colour="red")),
                turn("Add a blue car in front of the JTEKT entrance.",
                     add("passenger_car", 1, where("in_front_of", JTEKT), colour="blue")))),
    # erroneous
    case("positioning", "erroneous", "bench_jtekt", "put the bech in frnt of the JTEKT entrance",
         [near(JTEKT, 8, asset=BENCH), unchanged(assets=[BENCH])], [place(BENCH, where("in_front_of", JTEKT))]),
    case("positioning", "erroneous", "suv_lot_a", "place suv in parking lot a",
         [near(LOT_A, 1, asset=SUV), unchanged(assets=[SUV])], [place(SUV, where("at", LOT_A))]),
    case("positioning", "erroneous", "hydrant_between", "put the hydrant inbetween the bench and teh bin",
         [near_point(-29.75, -6.2, 2.5, asset=HYDRANT), unchanged(assets=[HYDRANT])],
         [place(HYDRANT, spot(-29.75, -6.2))]),
    case("positioning", "erroneous", "ego_lot_b", "place the ego in to lot B",
         [near(LOT_B, 1, asset=EGO), unchanged(assets=[EGO])], [place(EGO, where("at", LOT_B))]),
    case("positioning", "erroneous", "hydrant_engineering", "put hydrant on the side walk by engineering hal",
         [near(ENGINEERING, 12, asset=HYDRANT), surface(["sidewalk", "ground"], asset=HYDRANT),
          unchanged(assets=[HYDRANT])],
         [place(HYDRANT, where("on_sidewalk", ENGINEERING))]),
    case("positioning", "erroneous", "stop_sign_north", "i want stop sign be near of north crosswalk",
         [near(NORTH_CROSSWALK, 8, asset=STOP_SIGN), unchanged(assets=[STOP_SIGN])],
         [place(STOP_SIGN, where("next_to", NORTH_CROSSWALK))]),
    case("positioning", "erroneous", "tree_to_lot_b", "move teh tree from near libary to the lot B",
         [near(LOT_B, 2, asset=TREE_BY_LIBRARY), unchanged(assets=[TREE_BY_LIBRARY])],
         [place(TREE_BY_LIBRARY, where("at", LOT_B))]),
    case("positioning", "erroneous", "suv_behind_ego", "put the suv behind of our car, 15m, same lane",
         [in_lane(EASTBOUND, asset=SUV), relative("behind", EGO, 25, asset=SUV, tolerance_deg=20),
          unchanged(assets=[SUV])],
         [place(SUV, where("behind", EGO, along_m=-15))]),
    impossible("positioning", "erroneous", "hydrant_off_map", "put the hydrnat 500 meters past the east gate",
               place(HYDRANT, spot(600.0, 0.0))),
]


MOVING = [
    # direct
    case("moving", "direct", "suv_forward", "Move the SUV 5 metres forward.",
         [moved(SUV, 4, 6, "forward"), unchanged(assets=[SUV])], [move(SUV, forward=5)]),
    case("moving", "direct", "bench_around", "Turn the bench around.",
         [moved(BENCH, 0, 1.5, turn=(150, None)), unchanged(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    case("moving", "direct", "ego_10", "Make the ego drive at 10 m/s.",
         [does("drive_lane", asset=EGO, lane=EASTBOUND, speed_min=9.5, speed_max=10.5), unchanged(assets=[EGO])],
         [behave(EGO, "drive_lane", lane=EASTBOUND, speed=10)]),
    case("moving", "direct", "bin_east", "Move the rubbish bin 3 metres east.",
         [moved(BIN, 2.5, 3.5, "forward"), unchanged(assets=[BIN])], [move(BIN, east=3)]),
    case("moving", "direct", "left_car_circles", "Make the leftmost parked car in lot B drive round in circles.",
         [does("circle", asset=CAR_1, centre_near=LOT_B), unchanged(assets=[CAR_1])],
         [behave(CAR_1, "circle")]),
    case("moving", "direct", "stop_sign_west", "Shift the stop sign 2 metres west.",
         [moved(STOP_SIGN, 1.5, 2.5, "backward"), unchanged(assets=[STOP_SIGN])], [move(STOP_SIGN, east=-2)]),
    case("moving", "direct", "ego_back", "Move the ego back 10 metres.",
         [moved(EGO, 9, 11, "backward"), unchanged(assets=[EGO])], [move(EGO, forward=-10)]),
    case("moving", "direct", "person_crosses", "Make the pedestrian cross the road at the west crosswalk.",
         [does("cross_road", asset="pedestrian_1", crosses_lane=EASTBOUND), unchanged(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "cross_road")],
         setup=(turn("Add a pedestrian at the west crosswalk.", add("pedestrian", 1, where("at", WEST_CROSSWALK))),)),
    impossible("moving", "direct", "ego_300kmh", "Make the ego drive at 300 km/h.",
               behave(EGO, "drive_lane", lane=EASTBOUND, speed=83.3)),
    # indirect
    case("moving", "indirect", "suv_pulls_out",
         "Our driver says the SUV pulled out of its bay and headed east along Main Street while she was doing "
         "about 12 m/s. Set both of those up.",
         [does("drive_lane", asset=SUV, lane=EASTBOUND), does("drive_lane", asset=EGO, speed_min=11, speed_max=13),
          unchanged(assets=[SUV, EGO])],
         [behave(SUV, "drive_lane", lane=EASTBOUND), behave(EGO, "drive_lane", lane=EASTBOUND, speed=12)],
         tags=COMPOUND),
    case("moving", "indirect", "walking_pace",
         "I want my learner to creep up to the junction at little more than walking pace.",
         [does("drive_lane", asset=EGO, lane=EASTBOUND, speed_min=0.5, speed_max=3.5), unchanged(assets=[EGO])],
         [behave(EGO, "drive_lane", lane=EASTBOUND, speed=2)]),
    case("moving", "indirect", "sweeper_room",
         "The SUV needs to pull a car length further into its bay so the street sweeper can get by behind it.",
         [moved(SUV, 3.5, 6.5, "forward"), unchanged(assets=[SUV])], [move(SUV, forward=5)]),
    case("moving", "indirect", "bench_faces_other_way",
         "In the demo the bench looks odd the way it's facing. Could it face the opposite way?",
         [moved(BENCH, 0, 1.5, turn=(150, None)), unchanged(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    case("moving", "indirect", "someone_steps_out",
         "I'd like to watch that person step out in front of our car away from any crossing.",
         [does("jaywalk", asset="pedestrian_1", crosses_lane=EASTBOUND), unchanged(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "jaywalk")],
         setup=(turn("Add a pedestrian at the bus stop.", add("pedestrian", 1, where("at", BUS_STOP))),)),
    case("moving", "indirect", "thirty_mph",
         "The test car seems to be dawdling. Could it do about 30 miles an hour?",
         [does("drive_lane", asset=EGO, lane=EASTBOUND, speed_min=12.5, speed_max=14.5), unchanged(assets=[EGO])],
         [behave(EGO, "drive_lane", lane=EASTBOUND, speed=13.4)]),
    case("moving", "indirect", "circles_near_union",
         "Step 4 of the test sheet: the parked car closest to the Student Union starts driving round in circles "
         "in the car park.",
         [does("circle", asset=CAR_2), unchanged(assets=[CAR_2])], [behave(CAR_2, "circle")]),
    case("moving", "indirect", "lorry_brakes",
         "Then, three seconds in, the lorry slammed its brakes on.",
         [event("stop", "truck"), unchanged("truck")],
         [call("add_manoeuvre", actor="truck_1", manoeuvre={"kind": "stop", "rate": 6}, at_time=3)],
         setup=(turn("Put a lorry on Main Street ahead of our car, going the same way.",
                     add("truck", 1, where("at", EGO, along_m=40), behaviour=drive(EASTBOUND)), planned=True),)),
    impossible("moving", "indirect", "engineering_hall",
               "Our plans have Engineering Hall set further back from the road, so shift it 5 m north.",
               move("Engineering Hall", north=5)),
    # vague
    case("moving", "vague", "ego_faster", "ego a bit faster",
         [does("drive_lane", asset=EGO, lane=EASTBOUND, speed_min=6, speed_max=15), unchanged(assets=[EGO])],
         [behave(EGO, "drive_lane", lane=EASTBOUND, speed=8)]),
    case("moving", "vague", "suv_forward_little", "suv forward a little",
         [moved(SUV, 0.5, 5, "forward"), unchanged(assets=[SUV])], [move(SUV, forward=2)]),
    case("moving", "vague", "bench_other_way", "bench the other way round",
         [moved(BENCH, 0, 1.5, turn=(150, None)), unchanged(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    case("moving", "vague", "slow_the_bus", "slow it right down",
         [does("drive_lane", "bus", scope="all", speed_max=3), unchanged("bus")],
         [behave("bus_1", "drive_lane", lane=EASTBOUND, speed=2)],
         setup=(turn("Add a bus driving east on Main Street.", add("bus", 1, behaviour=drive(EASTBOUND)), planned=True),)),
    case("moving", "vague", "bin_along", "the bin, a couple of metres along",
         [moved(BIN, 1, 4), unchanged(assets=[BIN])], [move(BIN, east=2)]),
    case("moving", "vague", "suv_driving", "get the SUV driving around",
         [does(["drive_lane", "circle", "follow_path"], asset=SUV), unchanged(assets=[SUV])],
         [behave(SUV, "circle")]),
    case("moving", "vague", "ego_back_up", "ego, back it up a bit",
         [unchanged(assets=[EGO])], [move(EGO, forward=-4)],
         alternatives=([moved(EGO, 1, 10, "backward")], [event("reverse", EGO)])),
    case("moving", "vague", "cyclist_crosses", "have them cross",
         [does(["cross_road", "follow_path", "jaywalk"], "bicycle", scope="touched"), unchanged("bicycle")],
         [behave("bicycle_1", "cross_road")],
         setup=(turn("Add a cyclist at the north crosswalk.", add("bicycle", 1, where("at", NORTH_CROSSWALK)),
                     planned=True),)),
    impossible("moving", "vague", "bench_doughnuts", "the bench, make it do doughnuts",
               behave(BENCH, "circle")),
    # erroneous
    case("moving", "erroneous", "suv_forward_feet", "mvoe the suv 15 feet foward",
         [moved(SUV, 4, 5.5, "forward"), unchanged(assets=[SUV])], [move(SUV, forward=4.6)]),
    case("moving", "erroneous", "bench_around", "turn the bench arround 180",
         [moved(BENCH, 0, 1.5, turn=(150, None)), unchanged(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    case("moving", "erroneous", "cones_east", "shift the ones i just added 2 metres east",
         [moved("traffic_cone_1", 1.5, 2.5, "right"), moved("traffic_cone_2", 1.5, 2.5, "right"),
          moved("traffic_cone_3", 1.5, 2.5, "right"), unchanged("traffic_cone")],
         [call("move_asset", assets=["traffic_cone_1", "traffic_cone_2", "traffic_cone_3"], east=2)],
         setup=(LIBRARY_CONES,)),
    case("moving", "erroneous", "ego_back", "ego go back 10 metre please",
         [moved(EGO, 9, 11, "backward"), unchanged(assets=[EGO])], [move(EGO, forward=-10)]),
    case("moving", "erroneous", "circle_near_union", "make car in lot B closest to student union drive in circle",
         [does("circle", asset=CAR_2), unchanged(assets=[CAR_2])], [behave(CAR_2, "circle")]),
    case("moving", "erroneous", "person_crosses", "make the pedestrain cross the raod",
         [does(["cross_road", "jaywalk", "follow_path"], asset="pedestrian_1"), unchanged(assets=["pedestrian_1"])],
         [behave("pedestrian_1", "cross_road")],
         setup=(turn("Add a pedestrian at the west crosswalk.", add("pedestrian", 1, where("at", WEST_CROSSWALK))),)),
    case("moving", "erroneous", "suv_east", "the suv shoud drive on main street going east",
         [does("drive_lane", asset=SUV, lane=EASTBOUND), unchanged(assets=[SUV])],
         [behave(SUV, "drive_lane", lane=EASTBOUND)]),
    case("moving", "erroneous", "bench_and_bin", "turn bench arround and move the bin 2m west",
         [moved(BENCH, 0, 1.5, turn=(150, None)), moved(BIN, 1.5, 2.5, "backward"), unchanged(assets=[BENCH, BIN])],
         [move(BENCH, turn_deg=180), move(BIN, east=-2)], tags=COMPOUND),
]


ARRANGEMENT = [
    # direct
    case("arrangement", "direct", "cones_across_ego", "Put a line of five cones across the ego's lane, 30 metres ahead of it.",
         [delta("traffic_cone", 5), layout("line", "traffic_cone", 5),
          relative("in_front_of", EGO, 40, "traffic_cone", tolerance_deg=20), unchanged("traffic_cone")],
         [arrange("traffic_cone", "line", where("in_front_of", EGO, distance=30), 5)]),
    case("arrangement", "direct", "bollard_ring_fountain", "Make a ring of bollards around the fountain.",
         [layout("ring", "bollard", 4, around=FOUNTAIN), unchanged("bollard")],
         [arrange("bollard", "ring", where("at", FOUNTAIN))]),
    case("arrangement", "direct", "row_cars_lot_a", "Put a row of three cars in parking lot A.",
         [delta(["passenger_car", "suv"], 3), layout("line", ["passenger_car", "suv"], 3, spacing=(2.2, 4.0)),
          near(LOT_A, 1, ["passenger_car", "suv"]), unchanged("passenger_car", "suv")],
         [arrange("passenger_car", "parking_row", where("at", LOT_A), 3)]),
    case("arrangement", "direct", "barriers_library", "Place six barriers in a line in front of the Library entrance.",
         [delta("road_barrier", 6), layout("line", "road_barrier", 6), near(LIBRARY, 12, "road_barrier"),
          unchanged("road_barrier")],
         [arrange("road_barrier", "line", where("in_front_of", LIBRARY), 6)]),
    case("arrangement", "direct", "cones_westbound_edge",
         "Set out eight cones along the edge of the westbound lane near the JTEKT entrance.",
         [delta("traffic_cone", 8), layout("line", "traffic_cone", 8), in_lane(WESTBOUND, "traffic_cone"),
          near(JTEKT, 30, "traffic_cone"), unchanged("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", where("at", JTEKT, lane=WESTBOUND), 8)]),
    case("arrangement", "direct", "bollard_grid_union", "Put a grid of nine bollards at the Student Union entrance.",
         [delta("bollard", 9), layout("cluster", "bollard", 9, tolerance=6), near(UNION, 10, "bollard"),
          unchanged("bollard")],
         [arrange("bollard", "grid", where("at", UNION), 9)]),
    case("arrangement", "direct", "benches_ring_tree", "Arrange four benches in a ring around the tree just north of lot A.",
         [delta("bench", 4), layout("ring", "bench", 4, around=TREE_NORTH_OF_LOT_A), unchanged("bench")],
         [arrange("bench", "ring", where("at", TREE_NORTH_OF_LOT_A), 4)]),
    case("arrangement", "direct", "cones_and_sign_east_gate",
         "Line five cones across the westbound lane near the east gate, and put a road works sign next to them.",
         [delta("traffic_cone", 5), layout("line", "traffic_cone", 5), near(EAST_GATE, 12, "traffic_cone"),
          delta("construction_sign", 1), near(EAST_GATE, 15, "construction_sign"),
          unchanged("traffic_cone", "construction_sign")],
         [arrange("traffic_cone", "line", spot(95.0, 1.75), 5, heading_deg=90, spacing=0.8),
          add("construction_sign", 1, where("next_to", "traffic_cone_5"))], tags=COMPOUND),
    impossible("arrangement", "direct", "ring_200m", "Make a ring of bollards 200 metres across around the fountain.",
               arrange("bollard", "ring", where("at", FOUNTAIN), radius=100)),
    # indirect
    case("arrangement", "indirect", "library_lane_closure",
         "The plan closes the eastbound lane outside the library for a day, so I need cones marking it off "
         "along the lane's edge there.",
         [delta("traffic_cone", 4, 30), layout("line", "traffic_cone", 4), in_lane(EASTBOUND, "traffic_cone"),
          near(LIBRARY, 30, "traffic_cone"), unchanged("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", where("at", LIBRARY, lane=EASTBOUND), 8)]),
    case("arrangement", "indirect", "bay_parking_drill",
         "For the bay-parking drill my learner needs three cars side by side in lot A to park between.",
         [delta(["passenger_car", "suv"], 3), layout("line", ["passenger_car", "suv"], 3, spacing=(2.2, 4.0)),
          near(LOT_A, 1, ["passenger_car", "suv"]), unchanged("passenger_car", "suv")],
         [arrange("passenger_car", "parking_row", where("at", LOT_A), 3)]),
    case("arrangement", "indirect", "barriers_north_crossing",
         "One of our vans went into a line of barriers on Campus Drive just north of the north crossing. "
         "Rebuild it with three barriers across the road there.",
         [delta("road_barrier", 3), layout("line", "road_barrier", 3), near(NORTH_CROSSWALK, 10, "road_barrier"),
          surface(["drivable"], "road_barrier"), unchanged("road_barrier")],
         [arrange("road_barrier", "line", spot(0.0, 16.0), 3, heading_deg=0, spacing=2.3)]),
    case("arrangement", "indirect", "people_round_fountain",
         "The demo opens on the fountain, and I'd like people standing all the way round it.",
         [layout("ring", "pedestrian", 4, around=FOUNTAIN), unchanged("pedestrian")],
         [arrange("pedestrian", "ring", where("at", FOUNTAIN), 8)]),
    case("arrangement", "indirect", "closure_south",
         "Show me what closing Campus Drive south of the junction would look like.",
         [layout("line", ["road_barrier", "traffic_cone"], 3, tolerance=1.5),
          near_point(0.0, -20.0, 12, ["road_barrier", "traffic_cone"]),
          surface(["drivable"], ["road_barrier", "traffic_cone"]), unchanged("road_barrier", "traffic_cone")],
         [arrange("road_barrier", "line", spot(0.0, -20.0), 3, heading_deg=0, spacing=2.3)]),
    case("arrangement", "indirect", "benches_circle_fountain",
         "I'd love some benches round the fountain in a circle, so people can sit and chat.",
         [layout("ring", "bench", 3, around=FOUNTAIN), unchanged("bench")],
         [arrange("bench", "ring", where("at", FOUNTAIN), 6)]),
    case("arrangement", "indirect", "sheet_row_six",
         "Scenario sheet, row 6: five cones along the right-hand edge of the northbound lane, starting just south "
         "of the junction and running away from it.",
         [delta("traffic_cone", 5), layout("line", "traffic_cone", 5), in_lane(NORTHBOUND, "traffic_cone"),
          near_point(1.75, -20.0, 12, "traffic_cone"), unchanged("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", spot(1.75, -25.0), 5, spacing=3)]),
    case("arrangement", "indirect", "cones_round_lorry",
         "In the photo from the scene there were cones all the way round the lorry. Can you do that?",
         [layout("ring", "traffic_cone", 4, around="truck_1"), unchanged("traffic_cone")],
         [arrange("traffic_cone", "ring", where("at", "truck_1"), 10)],
         setup=(turn("Put a lorry in lot B.", add("truck", 1, where("at", LOT_B)), planned=True),)),
    impossible("arrangement", "indirect", "barriers_150",
               "The road-works plan calls for 150 barriers in one line down Main Street.",
               arrange("road_barrier", "line", where("in_lane", EASTBOUND), 150)),
    # vague
    case("arrangement", "vague", "cones_round_rubble", "cones round it",
         [layout("ring", "traffic_cone", 4, around="cement_rubble_1"), unchanged("traffic_cone")],
         [arrange("traffic_cone", "ring", where("at", "cement_rubble_1"), 8)],
         setup=(turn("Drop some rubble in the middle of the junction.", add("cement_rubble", 1, where("at", JUNCTION))),)),
    case("arrangement", "vague", "row_cars_lot_b", "a row of cars in lot B",
         [delta(["passenger_car", "suv"], 2, 10), layout("line", ["passenger_car", "suv"], 2, spacing=(2.2, 4.0)),
          near(LOT_B, 1, ["passenger_car", "suv"]), unchanged("passenger_car", "suv")],
         [arrange("passenger_car", "parking_row", where("at", LOT_B), 4)]),
    case("arrangement", "vague", "barriers_east_gate", "barriers across the road by the east gate",
         [layout("line", "road_barrier", 2), near(EAST_GATE, 12, "road_barrier"), surface(["drivable"], "road_barrier"),
          unchanged("road_barrier")],
         [arrange("road_barrier", "line", spot(100.0, 0.0), 3, heading_deg=90, spacing=2.3)]),
    case("arrangement", "vague", "bins_ring_tree", "bins in a circle round the tree north of lot A",
         [layout("ring", "trash_bin", 4, around=TREE_NORTH_OF_LOT_A), unchanged("trash_bin")],
         [arrange("trash_bin", "ring", where("at", TREE_NORTH_OF_LOT_A), 6)]),
    case("arrangement", "vague", "bollards_library", "bollards in a line along the library drop-off",
         [delta("bollard", 3, 12), layout("line", "bollard", 3), near(LIBRARY, 12, "bollard"), unchanged("bollard")],
         [arrange("bollard", "line", where("in_front_of", LIBRARY), 6, heading_deg=0)]),
    case("arrangement", "vague", "bikes_row_bus_stop", "some bikes in a row at the bus stop",
         [delta("bicycle", 2, 10), layout("line", "bicycle", 2), near(BUS_STOP, 12, "bicycle"), unchanged("bicycle")],
         [arrange("bicycle", "line", where("at", BUS_STOP), 4)]),
    case("arrangement", "vague", "same_again_bins", "same again but with bins",
         [layout("ring", "trash_bin", 4, around=FOUNTAIN), unchanged("trash_bin")],
         [arrange("trash_bin", "ring", where("at", FOUNTAIN), 8)],
         setup=(turn("Put a ring of bollards around the fountain.", arrange("bollard", "ring", where("at", FOUNTAIN)),
                     planned=True),)),
    case("arrangement", "vague", "ring_and_evening", "bollards round the fountain, and make it evening",
         [layout("ring", "bollard", 4, around=FOUNTAIN), env(time_from="17:30", time_to="22:00", weather=["clear"]),
          unchanged("bollard", env=True)],
         [arrange("bollard", "ring", where("at", FOUNTAIN)), clock("evening")], tags=COMPOUND),
    impossible("arrangement", "vague", "portaloos", "a row of portaloos by the junction",
               arrange("portaloo", "line", where("at", JUNCTION), 4)),
    # erroneous
    case("arrangement", "erroneous", "cones_across_ego", "put 5 cone in a line accross the road infront the ego, 30 m",
         [delta("traffic_cone", 5), layout("line", "traffic_cone", 5),
          relative("in_front_of", EGO, 40, "traffic_cone", tolerance_deg=20), unchanged("traffic_cone")],
         [arrange("traffic_cone", "line", where("in_front_of", EGO, distance=30), 5)]),
    case("arrangement", "erroneous", "bollard_ring", "make ring of bolards aroud the fountian",
         [layout("ring", "bollard", 4, around=FOUNTAIN), unchanged("bollard")],
         [arrange("bollard", "ring", where("at", FOUNTAIN))]),
    case("arrangement", "erroneous", "row_cars_lot_a", "can u make row of 3 car for parking pratice in lot a",
         [delta(["passenger_car", "suv"], 3), layout("line", ["passenger_car", "suv"], 3, spacing=(2.2, 4.0)),
          near(LOT_A, 1, ["passenger_car", "suv"]), unchanged("passenger_car", "suv")],
         [arrange("passenger_car", "parking_row", where("at", LOT_A), 3)]),
    case("arrangement", "erroneous", "barriers_library", "six barier in line in fornt of library entrance",
         [delta("road_barrier", 6), layout("line", "road_barrier", 6), near(LIBRARY, 12, "road_barrier"),
          unchanged("road_barrier")],
         [arrange("road_barrier", "line", where("in_front_of", LIBRARY), 6)]),
    case("arrangement", "erroneous", "cones_westbound_edge", "8 cones allong edge of westbond lane near JTEKT",
         [delta("traffic_cone", 8), layout("line", "traffic_cone", 8), in_lane(WESTBOUND, "traffic_cone"),
          near(JTEKT, 30, "traffic_cone"), unchanged("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", where("at", JTEKT, lane=WESTBOUND), 8)]),
    case("arrangement", "erroneous", "bollard_grid", "grid of 9 bolards at student union",
         [delta("bollard", 9), layout("cluster", "bollard", 9, tolerance=6), near(UNION, 10, "bollard"),
          unchanged("bollard")],
         [arrange("bollard", "grid", where("at", UNION), 9)]),
    case("arrangement", "erroneous", "benches_ring_tree", "4 bench in circle arround tree north of lot A",
         [delta("bench", 4), layout("ring", "bench", 4, around=TREE_NORTH_OF_LOT_A), unchanged("bench")],
         [arrange("bench", "ring", where("at", TREE_NORTH_OF_LOT_A), 4)]),
    case("arrangement", "erroneous", "bikes_row", "put bikes in row of five next the bus stop",
         [delta("bicycle", 5), layout("line", "bicycle", 5), near(BUS_STOP, 12, "bicycle"), unchanged("bicycle")],
         [arrange("bicycle", "line", where("at", BUS_STOP), 5)]),
    impossible("arrangement", "erroneous", "cones_120", "make a circle of 120 cone around the junction",
               arrange("traffic_cone", "ring", where("at", JUNCTION), 120)),
]


APPEARANCE = [
    # direct
    case("appearance", "direct", "time_1830", "Set the time to 18:30.",
         [at_time("18:30"), CLEAR, unchanged(env=True)], [clock("18:30")]),
    case("appearance", "direct", "heavy_rain", "Make it rain heavily.",
         [env(weather=["rain"], intensity_min=0.7), NOON, unchanged(env=True)], [weather("rain", 0.9)]),
    case("appearance", "direct", "suv_yellow", "Paint the SUV yellow.",
         [look("yellow", asset=SUV), unchanged(assets=[SUV])], [paint(SUV, colour="yellow")]),
    case("appearance", "direct", "lamps_on", "Turn the street lights on.",
         [env(street_lights="on"), NOON, CLEAR, unchanged(env=True)], [lights(street_lights="on")]),
    case("appearance", "direct", "fog_and_night", "Make it foggy and set it to night time.",
         [env(weather=["fog"], night=True), unchanged(env=True)], [weather("fog"), clock("night")], tags=COMPOUND),
    case("appearance", "direct", "cones_orange", "Make all the cones orange.",
         [look("orange", category="traffic_cone", scope="all"), unchanged("traffic_cone")],
         [paint(category="traffic_cone", colour="orange")],
         setup=(turn("Put four cones at the entrance of lot A.", add("traffic_cone", 4, where("at", LOT_A_ENTRANCE))),)),
    case("appearance", "direct", "light_snow", "Set the weather to light snow.",
         [env(weather=["snow"], intensity_min=0.05, intensity_max=0.45), NOON, unchanged(env=True)],
         [weather("snow", 0.3)]),
    case("appearance", "direct", "bench_wood", "Make the bench wooden.",
         [look(material="wood", asset=BENCH), unchanged(assets=[BENCH])], [paint(BENCH, material="wood")]),
    impossible("appearance", "direct", "time_2800", "Set the clock to 28:00.", clock("28:00")),
    # indirect
    case("appearance", "indirect", "autumn_mist",
         "Tomorrow's lesson is about poor visibility. Give me the kind of misty early morning you get in autumn.",
         [env(weather=["fog"], time_from="05:00", time_to="09:30"), unchanged(env=True)],
         [weather("fog", 0.6), clock("07:00")], tags=COMPOUND),
    case("appearance", "indirect", "after_sunset",
         "The near miss happened just after sunset, so the light should be fading.",
         [env(time_from="18:45", time_to="21:30"), CLEAR, unchanged(env=True)], [clock("20:00")]),
    case("appearance", "indirect", "works_overnight",
         "The works will be done overnight, so it needs to be dark with the street lamps on.",
         [env(night=True, weather=["clear"]), unchanged(env=True)], [clock("23:00"), lights(street_lights="on")],
         alternatives=([env(street_lights="on")], [env(street_lights="auto")]), tags=COMPOUND),
    case("appearance", "indirect", "brand_blue",
         "Our brand colour is blue; could the test car match it for the demo?",
         [look("blue", asset=EGO), unchanged(assets=[EGO])], [paint(EGO, colour="blue")]),
    case("appearance", "indirect", "snowstorm",
         "I'm writing about winter driving and want this looking like a proper snowstorm.",
         [env(weather=["snow"], intensity_min=0.7), NOON, unchanged(env=True)], [weather("snow", 0.9)]),
    case("appearance", "indirect", "brighter",
         "My eyes aren't what they were. Could the whole picture be a bit brighter?",
         [env(exposure_min=1.1, exposure_max=2.5), NOON, CLEAR, unchanged(env=True)], [lights(exposure=1.4)]),
    case("appearance", "indirect", "overcast_no_rain", "The dataset needs overcast skies, but no rain.",
         [env(weather=["cloudy"]), NOON, unchanged(env=True)], [weather("cloudy")]),
    case("appearance", "indirect", "silver_suv",
         "The driver remembers the car that cut her off being silver, so the SUV should look like that.",
         [look(["silver", "grey"], asset=SUV, tolerance=0.12), unchanged(assets=[SUV])], [paint(SUV, colour="silver")]),
    impossible("appearance", "indirect", "union_green",
               "For the hero shot, could the Student Union building be painted bright green?",
               paint("Student Union", colour="green")),
    # vague
    case("appearance", "vague", "dusk_after_rain", "now make it dusk",
         [env(time_from="18:30", time_to="21:00", weather=["rain"]), unchanged(env=True)], [clock("dusk")],
         setup=(turn("Make it rain lightly.", weather("rain", 0.3), planned=True),)),
    case("appearance", "vague", "wetter", "wetter",
         [env(weather=["rain"], intensity_min=0.4), NOON, unchanged(env=True)], [weather("rain", 0.6)],
         setup=(turn("Make it drizzle.", weather("rain", 0.2)),)),
    case("appearance", "vague", "darker", "darker please",
         [unchanged(env=True)], [clock("21:00")],
         alternatives=([env(time_from="17:30", time_to="06:00")], [env(exposure_max=0.9)])),
    case("appearance", "vague", "cones_yellow", "make them yellow",
         [look("yellow", category="traffic_cone", scope="all"), unchanged("traffic_cone")],
         [paint(category="traffic_cone", colour="yellow")],
         setup=(turn("Add two cones at the bus stop.", add("traffic_cone", 2, where("at", BUS_STOP)), planned=True),)),
    case("appearance", "vague", "winter_morning", "make it feel like a winter morning",
         [env(weather=["snow", "fog"], time_from="05:00", time_to="11:00"), unchanged(env=True)],
         [weather("snow", 0.5), clock("07:30")], tags=COMPOUND),
    case("appearance", "vague", "lights_on", "lights on",
         [NOON, CLEAR, unchanged(env=True)], [lights(street_lights="on")],
         alternatives=([env(street_lights="on")], [env(vehicle_lights="on")])),
    case("appearance", "vague", "gloomy", "a bit gloomy",
         [unchanged(env=True)], [weather("cloudy")],
         alternatives=([env(weather=["cloudy", "fog", "rain"])], [env(time_from="17:00", time_to="21:30")],
                       [env(exposure_max=0.9)])),
    case("appearance", "vague", "red_bench", "red bench",
         [look("red", asset=BENCH), unchanged(assets=[BENCH])], [paint(BENCH, colour="red")]),
    impossible("appearance", "vague", "hurricane", "hurricane please", weather("hurricane", 0.9)),
    # erroneous
    case("appearance", "erroneous", "time_1830", "set teh time too 18:30",
         [at_time("18:30"), CLEAR, unchanged(env=True)], [clock("18:30")]),
    case("appearance", "erroneous", "heavy_rain", "make it rainning realy heavy",
         [env(weather=["rain"], intensity_min=0.7), NOON, unchanged(env=True)], [weather("rain", 0.9)]),
    case("appearance", "erroneous", "too_sunny", "its to sunny, make it cloudy pls",
         [env(weather=["cloudy"]), NOON, unchanged(env=True)], [weather("cloudy")]),
    case("appearance", "erroneous", "lamps_on", "turn on the stret lights",
         [env(street_lights="on"), NOON, CLEAR, unchanged(env=True)], [lights(street_lights="on")]),
    case("appearance", "erroneous", "fog_night", "make foggy and nigth",
         [env(weather=["fog"], night=True), unchanged(env=True)], [weather("fog"), clock("night")], tags=COMPOUND),
    case("appearance", "erroneous", "bench_wood", "chnage the bench to wood",
         [look(material="wood", asset=BENCH), unchanged(assets=[BENCH])], [paint(BENCH, material="wood")]),
    case("appearance", "erroneous", "bus_yellow_shiny", "make the bus yelow and shiny",
         [look("yellow", "glossy", asset="bus_1"), unchanged(assets=["bus_1"])],
         [paint("bus_1", colour="yellow", material="glossy")],
         setup=(turn("Add a bus driving west on Main Street.", add("bus", 1, behaviour=drive(WESTBOUND))),)),
    case("appearance", "erroneous", "ego_blue", "make the ego blu",
         [look("blue", asset=EGO), unchanged(assets=[EGO])], [paint(EGO, colour="blue")]),
    case("appearance", "erroneous", "half_seven", "i want it is evening, like half past seven",
         [env(time_from="19:15", time_to="19:45"), CLEAR, unchanged(env=True)], [clock("19:30")]),
]


ALL_CASES: list[Json] = [*SEARCH, *ADDITION, *REMOVAL, *POSITIONING, *MOVING, *ARRANGEMENT, *APPEARANCE]


def main() -> None:
    SUITE_PATH.write_text("".join(json.dumps(c, ensure_ascii=False) + "\n" for c in ALL_CASES), encoding="utf-8")
    print(f"wrote {len(ALL_CASES)} cases to {SUITE_PATH}")


if __name__ == "__main__":
    main()
