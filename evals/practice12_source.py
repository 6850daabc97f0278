"""The twelfth practice suite: campus requests worded the way everyday users of the tool write them.

`suites/practice12.jsonl` (tag `practice12`, ids `practice12.*`) was written from the campus world
(worlds/campus.py), the asset catalog (worlds/data/catalog.json), the Worker tools and the eval
checks only, by a helper who had not read the planners, their lexicons or prompt examples, nor any
other suite's cases. It is a development suite: it measures how well a planner understands
requests worded in ways its developers never saw.

Voices: ordinary people who use the tool every day and write as they naturally would, in plain
English: a simulation / test engineer setting up a run ("run-up", "for the AEB test", "background
traffic"); an ADAS student working on a thesis or write-up; a QA tester checking a scene before a
run ("just want to confirm ..."); a researcher preparing a study (night-driving, occlusion,
glare); a team lead asking quickly for something on behalf of others ("marketing wants ...",
"for the demo"); and a newcomer on their first day, unsure of the names of things ("um", "I
guess", "the pole thing"). Prompts run from three words to three sentences and use everyday
words for things (van, lamp post, bin, bike, scooter, seat, the pole by the hydrant, the sign
telling cars to halt), references back to earlier turns ("it", "those", "the people I added",
"same again"), polite and blunt forms, metres, feet and car lengths, rough amounts ("a couple",
"a handful", "about half", "a bit"), clock times and parts of the day, weather words, negation and
exceptions ("but leave the SUV", "except the suv"), scopes (a lane, a lot, a sidewalk, a
crosswalk, a landmark, the north or south side of a road) and questions of many shapes, which
must change nothing. The erroneous grade carries the slips of quick typing: swapped, missing and
doubled letters ("teh", "stret", "snwo"), phone autocorrect turning one real word into another
("dear" for deer, "closet" for closest, "pain" for paint, "sliver" for silver, "too" for to),
missing spaces ("infront", "nxet to"), dropped words and small grammar slips.

Every case judges the outcome, never the calls: a main check (counts with exact bounds, places
with near / relative / in_lane, layouts, behaviours, looks, the environment, a simulated run, or
the answer to a question) and an `unchanged_except` guard, so collateral edits fail. Where a
request has two fair readings the case lists `alternatives`. Requests the world cannot do (a
mailbox, a ticket machine, a deer, a hospital, a petrol station, a gym, the north gate, a bench
on the Library's roof, the SUV 150 m north of the crossroads, tennis courts, removing the east
gate, the north crosswalk, a bus that is not there or the ego, moving Campus Drive or the bus
stop, 100 mph, a bin driving laps, 150 cones in a ring, a 150 m ring, twelve buses, painting the
crosswalk stripes or the road, a double rainbow) are tagged `impossible` and expect a refusal
that changes nothing. Each case carries a `reference` plan (Worker calls) whose outcome its checks
accept.

Counts: 250 cases; every task x grade cell holds 8 to 9 (direct 63, indirect 63, vague 62,
erroneous 62); 30 `multi_turn` (12 with an earlier turn planned by the planner under test), 18
`compound` (two or more edits or questions in one request), 24 `impossible` (9.6 %).

`python -m drivetwin.evals.practice12_source` rewrites the JSONL from the list below.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

SUITE = "practice12"
SUITE_PATH = Path(__file__).resolve().with_name("suites") / f"{SUITE}.jsonl"

Json = dict[str, Any]

# ---------------------------------------------------------------------------------------------
# Facts of the campus world the cases lean on (worlds/campus.py).
# ---------------------------------------------------------------------------------------------

# Street lights: odd ids on the north side of Main Street (y = 5.8), even ids on the south side.
NORTH_LIGHTS = ["street_light_1", "street_light_3", "street_light_5", "street_light_7",
                "street_light_9", "street_light_11"]
SOUTH_LIGHTS = ["street_light_2", "street_light_4", "street_light_6", "street_light_8",
                "street_light_10", "street_light_12"]
# Lot B's row, west to east at y = -42, facing north: a sedan, the SUV, a sedan.
LOT_B_SEDANS = ["passenger_car_1", "passenger_car_2"]
LOT_B_CARS = ["passenger_car_1", "suv_1", "passenger_car_2"]
CARS = ["passenger_car", "suv"]
VEHICLES = ["passenger_car", "suv", "bus", "truck", "ackermann_robot", "motorcycle", "bicycle"]
# Things a person might put down to block a lane or a driveway.
BLOCKERS = ["road_barrier", "traffic_cone", "bollard", "construction_sign", "cement_rubble"]
# Things that would do as an obstacle for the ego to brake for.
OBSTACLES = [*BLOCKERS, "passenger_car", "suv", "truck"]
BRIGHT = ["red", "yellow", "orange", "pink", "green", "cyan", "purple", "gold", "blue", "teal"]
NOTHING = ["0", "no", "none", "zero", "nothing", "not", "empty"]


# ---------------------------------------------------------------------------------------------
# Spelling helpers: each returns the JSON of one call, location, check or case, nothing more.
# ---------------------------------------------------------------------------------------------


def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def loc(target: str | None = None, relation: str = "at", **extra: Any) -> Json:
    """A Location: a relation to a target (landmark, asset id, lane), plus distance, along_m..."""
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


def remove(*ids: str, **extra: Any) -> Json:
    args: Json = {"assets": list(ids)} if ids else {}
    args.update(extra)
    return call("remove_assets", **args)


def place(asset: str, where: Json, **extra: Any) -> Json:
    return call("place_asset", asset=asset, location=where, **extra)


def shift(asset: str | list[str], **extra: Any) -> Json:
    if isinstance(asset, list):
        return call("move_asset", assets=asset, **extra)
    return call("move_asset", asset=asset, **extra)


def behave(asset: str, kind: str, **spec: Any) -> Json:
    return call("set_behaviour", asset=asset, behaviour={"kind": kind, **spec})


def arrange(categories: str | list[str], shape: str, where: Json, **extra: Any) -> Json:
    cats = [categories] if isinstance(categories, str) else list(categories)
    return call("arrange_assets", categories=cats, shape=shape, location=where, **extra)


def paint(*ids: str, **extra: Any) -> Json:
    args: Json = {"assets": list(ids)} if ids else {}
    args.update(extra)
    return call("set_asset_appearance", **args)


def clock(time: str) -> Json:
    return call("set_time_of_day", time=time)


def weather(kind: str, intensity: float | None = None) -> Json:
    return call("set_weather", kind=kind, **({} if intensity is None else {"intensity": intensity}))


def lighting(**extra: Any) -> Json:
    return call("set_lighting", **extra)


def find(**extra: Any) -> Json:
    return call("find_assets", **extra)


def landmarks(**extra: Any) -> Json:
    return call("find_landmarks", **extra)


def lanes(**extra: Any) -> Json:
    return call("find_lanes", **extra)


def measure(a: str, b: str) -> Json:
    return call("measure_distance", a=a, b=b)


def props(**extra: Any) -> Json:
    return call("asset_properties", **extra)


def describe() -> Json:
    return call("describe_environment")


def turn(prompt: str, calls: list[Json], planned: bool = False) -> Json:
    """An earlier turn: replayed as given, or (planned) planned by the planner under test."""
    step: Json = {"prompt": prompt, "calls": calls}
    if planned:
        step["planned"] = True
    return step


# Checks ---------------------------------------------------------------------------------------


def _select(check: Json, category: str | list[str] | None = None, asset: str | None = None,
            scope: str | None = None, require_all: bool | None = None, min_count: int | None = None) -> Json:
    if category is not None:
        check["category"] = category
    if asset is not None:
        check["asset"] = asset
    if scope is not None:
        check["scope"] = scope
    if require_all is not None:
        check["require_all"] = require_all
    if min_count is not None:
        check["min_count"] = min_count
    return check


def count(category: str | list[str], lo: int | None = None, hi: int | None = None) -> Json:
    """The scene holds lo..hi of these after the prompt (exactly lo when hi is not given)."""
    out: Json = {"kind": "count", "category": category}
    if lo is not None:
        out["min"] = lo
        out["max"] = lo if hi is None else hi
    elif hi is not None:
        out["max"] = hi
    return out


def delta(category: str | list[str], lo: int, hi: int | None = None) -> Json:
    """Added (positive) or removed (negative) between lo and hi; exactly lo when hi is not given."""
    return {"kind": "count_delta", "category": category, "min": lo, "max": lo if hi is None else hi}


def near(target: str, within: float, **sel: Any) -> Json:
    return _select({"kind": "near", "target": target, "within": within}, **sel)


def near_xy(x: float, y: float, within: float, **sel: Any) -> Json:
    return _select({"kind": "near", "point": [x, y], "within": within}, **sel)


def relative(relation: str, target: str, max_distance: float, **sel: Any) -> Json:
    return _select({"kind": "relative", "relation": relation, "target": target,
                    "max_distance": max_distance}, **sel)


def on(*surfaces: str, **sel: Any) -> Json:
    return _select({"kind": "on_surface", "surfaces": list(surfaces)}, **sel)


def in_lane(lane: str | None = None, aligned: bool = False, **sel: Any) -> Json:
    out: Json = {"kind": "in_lane"}
    if lane is not None:
        out["lane"] = lane
    if aligned:
        out["aligned"] = True
    return _select(out, **sel)


def layout(shape: str, category: str | list[str], around: str | None = None, **extra: Any) -> Json:
    out: Json = {"kind": "arrangement", "shape": shape, "category": category}
    if around is not None:
        out["around"] = around
    out.update(extra)
    return out


def does(behaviour: str | list[str], *, sel: Json | None = None, **params: Any) -> Json:
    return _select({"kind": "behaviour", "behaviour": behaviour, **params}, **(sel or {}))


def env(**params: Any) -> Json:
    return {"kind": "environment", **params}


def at_time(hhmm: str, **params: Any) -> Json:
    """The environment at exactly this clock time (and whatever else is pinned)."""
    return env(time_from=hhmm, time_to=hhmm, **params)


def looks(colour: str | list[str] | None = None, material: str | None = None,
          tolerance: float | None = None, **sel: Any) -> Json:
    out: Json = {"kind": "appearance"}
    if colour is not None:
        out["colour"] = colour
    if material is not None:
        out["material"] = material
    if tolerance is not None:
        out["colour_tolerance"] = tolerance
    return _select(out, **sel)


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


def gone(*ids: str) -> Json:
    return {"kind": "exists", "assets": list(ids), "present": False}


def kept(*ids: str) -> Json:
    return {"kind": "exists", "assets": list(ids), "present": True}


def keep(*categories: str, assets: list[str] | tuple[str, ...] = (), environment: bool = False) -> Json:
    """Nothing changed but assets of these categories or ids (and the environment if allowed)."""
    out: Json = {"kind": "unchanged_except"}
    if categories:
        out["categories"] = list(categories)
    if assets:
        out["assets"] = list(assets)
    if environment:
        out["environment"] = True
    return out


def says(*all_of: str, any_of: list[str] | tuple[str, ...] = (), none_of: list[str] | tuple[str, ...] = ()) -> Json:
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


def run_for(seconds: float, *expect: Json) -> Json:
    return {"kind": "scenario", "seconds": seconds, "expect": list(expect)}


def event(manoeuvre: str, actor: str | None = None) -> Json:
    out: Json = {"kind": "event", "manoeuvre": manoeuvre}
    if actor is not None:
        out["actor"] = actor
    return out


def stopped_before(x: float, y: float, actor: str = "ego") -> Json:
    return {"kind": "stopped_before", "actor": actor, "line": [x, y]}


def no_collision(actor: str = "ego") -> Json:
    return {"kind": "collision", "actor": actor, "happens": False}


# Cases -----------------------------------------------------------------------------------------

CASES: list[Json] = []


def case(task: str, grade: str, name: str, voice: str, prompt: str, checks: list[Json], reference: list[Json],
         *, tags: tuple[str, ...] = (), setup: tuple[Json, ...] = (), alternatives: tuple[list[Json], ...] = ()) -> None:
    """One case, appended to CASES; multi_turn is tagged from the setup."""
    all_tags = [SUITE, *tags]
    if setup and "multi_turn" not in all_tags:
        all_tags.append("multi_turn")
    out: Json = {"id": f"{SUITE}.{task}.{grade}.{name}", "world": "campus"}
    if setup:
        out["setup"] = list(setup)
    out.update({"prompt": prompt, "task": task, "grade": grade, "tags": all_tags, "checks": checks})
    if alternatives:
        out["alternatives"] = list(alternatives)
    out["reference"] = reference
    out["notes"] = f"voice: {voice}"
    CASES.append(out)


def impossible(task: str, grade: str, name: str, voice: str, prompt: str, reference: list[Json],
               why: str, *, setup: tuple[Json, ...] = ()) -> None:
    """A request the world cannot do: the right outcome is a refusal that changes nothing."""
    case(task, grade, name, voice, prompt, [refused(), keep()], reference, tags=("impossible",), setup=setup)
    CASES[-1]["notes"] += f"; impossible: {why}"


# =============================================================================================
# search: questions change nothing; answers must name the right facts
# =============================================================================================

# direct --------------------------------------------------------------------------------------
case("search", "direct", "north_side_lamps", "QA tester",
     "How many street lights are there on the north side of Main Street?",
     [says(any_of=["6", "six"]), keep()],
     [find(category="street_light", lane="main_westbound")])
case("search", "direct", "lights_and_weather", "simulation engineer",
     "Are the street lights on at the moment, and what's the weather doing?",
     [says("clear"), says(any_of=["off", "auto"]), keep()],
     [describe()])
case("search", "direct", "ego_to_east_gate", "researcher",
     "How far is the ego vehicle from the east gate?",
     [says(any_of=["160", "160.0"]), keep()],
     [measure("ego", "east gate")])
case("search", "direct", "sedan_nearest_union", "newcomer",
     "Which of the parked cars is closest to the Student Union entrance?",
     [says("passenger_car_2"), keep()],
     [find(category="cars", nearest_to="Student Union entrance")])
case("search", "direct", "campus_drive_lanes", "team lead",
     "List the lanes on Campus Drive, please.",
     [says("campus_northbound", "campus_southbound"), keep()],
     [lanes(road="Campus Drive")])
case("search", "direct", "cones_after_adding", "QA tester",
     "How many cones are in the scene now?",
     [says(any_of=["4", "four"]), keep()],
     [find(category="traffic_cone")],
     setup=(turn("Put four cones at the entrance to lot A.",
                 [add("traffic_cone", 4, loc("parking lot A entrance"))], planned=True),))
case("search", "direct", "place_nearest_bus_stop", "ADAS student",
     "What's the nearest named place to the bus stop?",
     [says("Library"), keep()],
     [landmarks(nearest_to="bus stop")])
case("search", "direct", "northbound_length", "simulation engineer",
     "How long is the northbound lane on Campus Drive?",
     [says("180"), keep()],
     [lanes(road="Campus Drive")])
impossible("search", "direct", "ego_to_hospital", "researcher",
           "How far is the ego from the hospital?",
           [measure("ego", "hospital")], "the campus has no hospital")

# indirect ------------------------------------------------------------------------------------
case("search", "indirect", "pole_by_hydrant", "team lead",
     "Someone says there's a pole right next to the fire hydrant that gets in the camera's way. "
     "I need to know what's standing closest to it.",
     [says(any_of=["traffic_light_2", "traffic light"]), keep()],
     [find(nearest_to="fire_hydrant_1")])
case("search", "indirect", "car_parks_apart", "ADAS student",
     "For my write-up I need the straight-line distance between the two car parks.",
     [says(any_of=["136.4", "136", "116.7", "117"]), keep()],
     [measure("parking lot A", "parking lot B")])
case("search", "indirect", "no_leftover_bus", "QA tester",
     "Yesterday somebody left a bus in the scene and it broke my run. I just want to be sure there "
     "isn't one in there now.",
     [says(any_of=NOTHING), keep()],
     [find(category="bus")])
case("search", "indirect", "lamp_by_library", "researcher",
     "For the night-driving study I need to know which street light stands nearest the library doors.",
     [says("street_light_4"), keep()],
     [find(category="street_light", nearest_to="Library entrance")])
case("search", "indirect", "place_names", "newcomer",
     "It's my first day and I don't know what the places around here are called. Can you tell me?",
     [says("fountain", "bus stop", "main gate"), keep()],
     [landmarks()])
case("search", "indirect", "ego_to_stop_sign", "simulation engineer",
     "Our perception test kicks off when the ego can see the stop sign, so I need to know how far "
     "the car is from the sign right now.",
     [says(any_of=["46.7", "47", "46.6", "46.5"]), keep()],
     [measure("ego", "stop_sign_1")])
case("search", "indirect", "suv_doing", "team lead",
     "I'm deciding whether the SUV needs a script. Is it moving, or just sitting there?",
     [says(any_of=["parked", "stationary", "not moving", "sitting"]), keep()],
     [props(asset="suv_1")])
case("search", "indirect", "lot_a_empty", "QA tester",
     "People say lot A looks empty in the renders. I'd like to confirm there are no vehicles parked in it.",
     [says(any_of=NOTHING), keep()],
     [find(category="vehicles", near="parking lot A", within=3)])
impossible("search", "indirect", "petrol_station", "researcher",
           "I need the position of the petrol station for my route file.",
           [landmarks(query="petrol station")], "the campus has no petrol station")

# vague ---------------------------------------------------------------------------------------
case("search", "vague", "trees_round_fountain", "newcomer",
     "um, are there any trees near the fountain or something?",
     [says(any_of=["tree_2", "2", "two"]), keep()],
     [find(category="tree", near="fountain", within=20)])
case("search", "vague", "lot_b_to_jtekt", "team lead",
     "Roughly how far is lot B from the JTEKT building?",
     [says(any_of=["44", "44.0", "27", "27.0"]), keep()],
     [measure("parking lot B", "JTEKT building entrance")])
case("search", "vague", "around_bus_stop", "QA tester",
     "what's around the bus stop, roughly?",
     [says("bench"), says(any_of=["bin", "trash"]), keep()],
     [find(near="bus stop", within=10)])
case("search", "vague", "dark_or_day", "ADAS student",
     "Is it kind of dark in the sim right now, or still daytime?",
     [says(any_of=["12:00", "noon", "midday", "daytime"]), keep()],
     [describe()])
case("search", "vague", "ego_lane", "simulation engineer",
     "Which lane is the ego in, more or less?",
     [says(any_of=["main_eastbound", "eastbound"]), keep()],
     [lanes(near="ego")])
case("search", "vague", "people_at_stop", "researcher",
     "So how many people are hanging about near the bus stop now, roughly?",
     [says(any_of=["3", "three"]), keep()],
     [find(category="pedestrian", near="bus stop", within=15)],
     setup=(turn("Add three pedestrians at the bus stop.", [add("pedestrian", 3, loc("bus stop"))]),))
case("search", "vague", "closest_to_ego", "newcomer",
     "what's the closest thing to the ego, ish",
     [says("street_light_2"), keep()],
     [find(nearest_to="ego")])
case("search", "vague", "count_and_weather", "team lead",
     "Give me a rough count of everything in the scene, and the weather while you're at it.",
     [says(any_of=["26", "25", "twenty-six", "twenty-five"]), says("clear"), keep()],
     [find(), describe()], tags=("compound",))
case("search", "vague", "nearer_lot", "QA tester",
     "which car park is nearer the ego, roughly?",
     [says(any_of=["lot A", "parking lot A"]), keep()],
     [measure("ego", "parking lot A"), measure("ego", "parking lot B")])

# erroneous -----------------------------------------------------------------------------------
case("search", "erroneous", "stret_lights_nroth", "QA tester",
     "how many stret lights on the nroth side of main steet",
     [says(any_of=["6", "six"]), keep()],
     [find(category="street_light", lane="main_westbound")])
case("search", "erroneous", "wether_now", "newcomer",
     "whats teh wether like right now",
     [says("clear"), keep()],
     [describe()])
case("search", "erroneous", "distnace_jtekt", "simulation engineer",
     "distnace from ego to the JTEKT entrence?",
     [says(any_of=["98.9", "99"]), keep()],
     [measure("ego", "JTEKT building entrance")])
case("search", "erroneous", "closet_car", "ADAS student",
     "which car is closet to the cafeteria",
     [says("passenger_car_2"), keep()],
     [find(category="cars", nearest_to="Student Union entrance")])
case("search", "erroneous", "trees_libary", "researcher",
     "How mnay trees arethere near the libary?",
     [says(any_of=["tree_1", "1", "one"]), keep()],
     [find(category="tree", near="Library entrance", within=25)])
case("search", "erroneous", "were_suv", "team lead",
     "were is the suv parked and is it moving",
     [says(any_of=["23", "-42", "lot B", "parking lot B"]),
      says(any_of=["parked", "stationary", "not moving"]), keep()],
     [props(asset="suv_1")])
case("search", "erroneous", "landmark_east_gate", "QA tester",
     "whats the closest landmark to teh east gate",
     [says(any_of=["parking lot B", "lot B", "fountain"]), keep()],
     [landmarks(nearest_to="east gate")])
case("search", "erroneous", "stil_foggy", "simulation engineer",
     "is it stil foggy or did that not take?",
     [says("fog"), keep()],
     [describe()],
     setup=(turn("Make it foggy.", [weather("fog")], planned=True),))
impossible("search", "erroneous", "gym_entrence", "newcomer",
           "how far is the ego from the gym entrence?",
           [measure("ego", "gym entrance")], "the campus has no gym")

# =============================================================================================
# addition: new assets of the right kind and number, where they were asked for
# =============================================================================================

# direct --------------------------------------------------------------------------------------
case("addition", "direct", "bus_at_stop", "simulation engineer",
     "Add a bus at the bus stop.",
     [delta("bus", 1), near("bus stop", 10, category="bus", scope="added"), keep("bus")],
     [add("bus", where=loc("bus stop"))])
case("addition", "direct", "cones_and_sign_lot_b", "QA tester",
     "Put three traffic cones at the entrance to lot B, and a roadworks sign next to them.",
     [delta("traffic_cone", 3), delta("construction_sign", 1),
      near("parking lot B entrance", 8, category="traffic_cone", scope="added", require_all=True),
      near("parking lot B entrance", 10, category="construction_sign", scope="added"),
      keep("traffic_cone", "construction_sign")],
     [add("traffic_cone", 3, loc("parking lot B entrance")),
      add("construction_sign", where=loc("parking lot B entrance"))], tags=("compound",))
case("addition", "direct", "benches_fountain", "newcomer",
     "Please add two benches near the fountain.",
     [delta("bench", 2), near("fountain", 10, category="bench", scope="added", require_all=True), keep("bench")],
     [add("bench", 2, loc("fountain"))])
case("addition", "direct", "person_outside_engineering", "researcher",
     "Add a pedestrian on the sidewalk outside Engineering Hall.",
     [delta("pedestrian", 1), near("Engineering Hall entrance", 15, category="pedestrian", scope="added"),
      on("sidewalk", category="pedestrian", scope="added"), keep("pedestrian")],
     [add("pedestrian", where=loc("Engineering Hall entrance", "on_sidewalk"))])
case("addition", "direct", "van_lot_a", "team lead",
     "Add a delivery van parked in lot A.",
     [delta("truck", 1), near("parking lot A", 1, category="truck", scope="added"),
      does("parked", sel={"category": "truck", "scope": "added"}), keep("truck")],
     [add("truck", where=loc("parking lot A"))])
case("addition", "direct", "cyclist_east", "ADAS student",
     "Add a cyclist riding east along Main Street.",
     [delta("bicycle", 1), does("drive_lane", lane="main_eastbound", sel={"category": "bicycle", "scope": "added"}),
      keep("bicycle")],
     [add("bicycle", behaviour={"kind": "drive_lane", "lane": "main_eastbound"})])
case("addition", "direct", "car_southbound", "simulation engineer",
     "Add a car driving south on Campus Drive.",
     [delta(CARS, 1), does("drive_lane", lane="campus_southbound", sel={"category": CARS, "scope": "added"}),
      keep(*CARS)],
     [add("passenger_car", behaviour={"kind": "drive_lane", "lane": "campus_southbound"})])
case("addition", "direct", "cones_lot_b_and_barrier", "QA tester",
     "Add five cones in parking lot B and one barrier at its entrance.",
     [delta("traffic_cone", 5), delta("road_barrier", 1),
      near("parking lot B", 1, category="traffic_cone", scope="added", require_all=True),
      near("parking lot B entrance", 8, category="road_barrier", scope="added"),
      keep("traffic_cone", "road_barrier")],
     [add("traffic_cone", 5, loc("parking lot B")), add("road_barrier", where=loc("parking lot B entrance"))],
     tags=("compound",))
impossible("addition", "direct", "mailbox", "researcher",
           "Add a mailbox next to the bench.",
           [add("mailbox", where=loc("bench_1", "next_to"))], "the catalog has no mailbox")

# indirect ------------------------------------------------------------------------------------
case("addition", "indirect", "something_to_brake_for", "simulation engineer",
     "The ego needs something to brake for: an obstacle in its lane roughly 100 feet ahead of it.",
     [delta(OBSTACLES, 1, 5), in_lane("main_eastbound", category=OBSTACLES, scope="added"),
      near_xy(-30.0, -1.75, 10, category=OBSTACLES, scope="added", require_all=True), keep(*OBSTACLES)],
     [add("cement_rubble", where=loc("ego", along_m=30))])
case("addition", "indirect", "crowd_at_stop", "team lead",
     "We're testing how the ego copes with a crowd at the bus stop, so we need a handful of people "
     "waiting there.",
     [delta("pedestrian", 3, 7), near("bus stop", 10, category="pedestrian", scope="added", require_all=True),
      keep("pedestrian")],
     [add("pedestrian", 5, loc("bus stop"))])
case("addition", "indirect", "jtekt_delivery", "ADAS student",
     "The JTEKT drop-off should look like it's getting a delivery.",
     [delta("truck", 1, 2), near("JTEKT building entrance", 12, category="truck", scope="added", require_all=True),
      keep("truck")],
     [add("truck", where=loc("JTEKT building entrance"))])
case("addition", "indirect", "crosswalk_too_dark", "QA tester",
     "Night runs show the west crosswalk is too dark, it needs one more lamp post.",
     [delta("street_light", 1), near("west crosswalk", 12, category="street_light", scope="added"),
      keep("street_light")],
     [add("street_light", where=loc("west crosswalk"))])
case("addition", "indirect", "truck_hides_crosswalk", "researcher",
     "For the occlusion case I want a parked truck hiding the west crosswalk from the ego as it "
     "drives east towards it.",
     [delta("truck", 1), in_lane(category="truck", scope="added"),
      near_xy(-24.0, -1.75, 12, category="truck", scope="added"), keep("truck")],
     [add("truck", where=xy(-22.0, -1.75), yaw_deg=0)])
case("addition", "indirect", "somewhere_to_sit", "newcomer",
     "Students keep asking where they can sit while they wait for the shuttle.",
     [delta("bench", 1, 2), near("bus stop", 8, category="bench", scope="added", require_all=True), keep("bench")],
     [add("bench", where=loc("bus stop"))])
case("addition", "indirect", "background_traffic_west", "simulation engineer",
     "I'd like a bit of background traffic: a couple of cars heading west on Main Street.",
     [delta(CARS, 2, 3),
      does("drive_lane", lane="main_westbound", sel={"category": CARS, "scope": "added", "require_all": True,
                                                      "min_count": 2}),
      keep(*CARS)],
     [add("passenger_car", 2, behaviour={"kind": "drive_lane", "lane": "main_westbound"})])
case("addition", "indirect", "block_lot_a_driveway", "team lead",
     "Maintenance is closing the lot A driveway today, so something has to block it.",
     [delta(BLOCKERS, 1, 8), near("parking lot A entrance", 8, category=BLOCKERS, scope="added", require_all=True),
      keep(*BLOCKERS)],
     [add("road_barrier", 2, xy(-85.0, 9.0), yaw_deg=0)])
impossible("addition", "indirect", "ticket_machine", "QA tester",
           "The parking test needs a ticket machine at the lot B entrance.",
           [add("ticket_machine", where=loc("parking lot B entrance"))], "the catalog has no ticket machine")

# vague ---------------------------------------------------------------------------------------
case("addition", "vague", "trees_round_quad", "newcomer",
     "can we get a few more trees somewhere around the quad?",
     [delta("tree", 2, 4), near("fountain", 20, category="tree", scope="added", require_all=True), keep("tree")],
     [add("tree", 3, loc("fountain"))])
case("addition", "vague", "cones_by_junction", "ADAS student",
     "add some cones near the intersection, maybe 4 or so",
     [delta("traffic_cone", 3, 5), near("main intersection", 12, category="traffic_cone", scope="added",
                                        require_all=True), keep("traffic_cone")],
     [add("traffic_cone", 4, loc("main intersection"))])
case("addition", "vague", "bike_by_library", "simulation engineer",
     "Stick a bike somewhere near the library.",
     [delta("bicycle", 1), near("Library entrance", 20, category="bicycle", scope="added"), keep("bicycle")],
     [add("bicycle", where=loc("Library entrance"))])
case("addition", "vague", "people_at_jtekt", "team lead",
     "Maybe a couple of people hanging around the JTEKT entrance?",
     [delta("pedestrian", 2, 3), near("JTEKT building entrance", 12, category="pedestrian", scope="added",
                                      require_all=True), keep("pedestrian")],
     [add("pedestrian", 2, loc("JTEKT building entrance"))])
case("addition", "vague", "any_car_lot_b", "QA tester",
     "add a car, whatever kind, just somewhere in lot B",
     [delta(CARS, 1), near("parking lot B", 1, category=CARS, scope="added"), keep(*CARS)],
     [add("passenger_car", where=loc("parking lot B"))])
case("addition", "vague", "debris_campus_north", "researcher",
     "I think we need a bit of debris on Campus Drive, north of the crossroads.",
     [delta("cement_rubble", 1, 3),
      near("campus_northbound", 4, category="cement_rubble", scope="added", require_all=True),
      near_xy(0.0, 45.0, 36, category="cement_rubble", scope="added", require_all=True), keep("cement_rubble")],
     [add("cement_rubble", where=loc("north crosswalk", "in_lane", lane="campus_northbound", distance=15))])
case("addition", "vague", "few_barriers_east", "simulation engineer",
     "Could use a few barriers in the eastbound lane somewhere past the junction.",
     [delta("road_barrier", 2, 5), in_lane("main_eastbound", category="road_barrier", scope="added"),
      near_xy(50.0, -1.75, 41, category="road_barrier", scope="added", require_all=True), keep("road_barrier")],
     [add("road_barrier", 3, loc("main_eastbound", "in_lane", distance=30))])
case("addition", "vague", "lamp_by_that_bench", "newcomer",
     "and maybe a lamp post near that bench too i guess",
     [delta("street_light", 1), near("bench_2", 10, category="street_light", scope="added"), keep("street_light")],
     [add("street_light", where=loc("bench_2", "next_to"))],
     setup=(turn("Add a bench outside the JTEKT entrance.", [add("bench", where=loc("JTEKT building entrance"))]),))
case("addition", "vague", "few_buses_lot_a", "QA tester",
     "add a few buses to lot A, three or so",
     [delta("bus", 2, 4), near("parking lot A", 1, category="bus", scope="added", require_all=True), keep("bus")],
     [add("bus", 3, loc("parking lot A"))])

# erroneous -----------------------------------------------------------------------------------
case("addition", "erroneous", "tuck_lot_b", "QA tester",
     "add a tuck in lot b",
     [delta("truck", 1), near("parking lot B", 1, category="truck", scope="added"), keep("truck")],
     [add("truck", where=loc("parking lot B"))])
case("addition", "erroneous", "pedestrains_bus_stpo", "newcomer",
     "plese add two pedestrains at the bus stpo",
     [delta("pedestrian", 2), near("bus stop", 8, category="pedestrian", scope="added", require_all=True),
      keep("pedestrian")],
     [add("pedestrian", 2, loc("bus stop"))])
case("addition", "erroneous", "cones_infront_ego", "simulation engineer",
     "add 3 cones infront of the ego",
     [delta("traffic_cone", 3),
      relative("in_front_of", "ego", 25, category="traffic_cone", scope="added", require_all=True),
      keep("traffic_cone")],
     [add("traffic_cone", 3, loc("ego", "in_front_of"))])
case("addition", "erroneous", "scooter_union", "ADAS student",
     "Add a scooter parked by the Student Union enterance",
     [delta("motorcycle", 1), near("Student Union entrance", 10, category="motorcycle", scope="added"),
      keep("motorcycle")],
     [add("motorcycle", where=loc("Student Union entrance"))])
case("addition", "erroneous", "suv_drivng_north", "team lead",
     "Can you ad a SUV drivng north on Campus Drive",
     [delta("suv", 1), does("drive_lane", lane="campus_northbound", sel={"category": "suv", "scope": "added"}),
      keep("suv")],
     [add("suv", behaviour={"kind": "drive_lane", "lane": "campus_northbound"})])
case("addition", "erroneous", "bench_nxet_bin", "researcher",
     "put a bench nxet to the trash bin",
     [delta("bench", 1), near("trash_bin_1", 4, category="bench", scope="added"), keep("bench")],
     [add("bench", where=loc("trash_bin_1", "next_to"))])
case("addition", "erroneous", "constuction_sign", "QA tester",
     "add a constuction sign at the lot A driveway",
     [delta("construction_sign", 1), near("parking lot A entrance", 10, category="construction_sign", scope="added"),
      keep("construction_sign")],
     [add("construction_sign", where=loc("parking lot A entrance"))])
case("addition", "erroneous", "cone_behind_truck", "simulation engineer",
     "put a cone rigth behind it",
     [delta("traffic_cone", 1), relative("behind", "truck_1", 12, category="traffic_cone", scope="added"),
      keep("traffic_cone")],
     [add("traffic_cone", where=loc("truck_1", "behind"))],
     setup=(turn("Add a truck in lot B.", [add("truck", where=loc("parking lot B"))], planned=True),))
impossible("addition", "erroneous", "dear_crossing", "newcomer",
           "add a dear crossing the road near the east gate",
           [add("deer", where=loc("east gate"))], "the catalog has no animals ('dear' is autocorrect for deer)")

# =============================================================================================
# removal: the right assets gone, everything else still there
# =============================================================================================

# direct --------------------------------------------------------------------------------------
case("removal", "direct", "bench", "QA tester",
     "Remove the bench.",
     [gone("bench_1"), delta("bench", -1), keep("bench")],
     [remove("bench_1")])
case("removal", "direct", "suv_lot_b", "simulation engineer",
     "Delete the SUV in lot B.",
     [gone("suv_1"), kept(*LOT_B_SEDANS), keep(assets=["suv_1"])],
     [remove("suv_1")])
case("removal", "direct", "north_side_lights", "team lead",
     "Remove all the street lights on the north side of Main Street.",
     [gone(*NORTH_LIGHTS), kept(*SOUTH_LIGHTS), keep("street_light")],
     [remove(*NORTH_LIGHTS)])
case("removal", "direct", "tree_nearest_fountain", "researcher",
     "Remove the tree closest to the fountain.",
     [gone("tree_2"), kept("tree_1", "tree_3", "tree_4"), keep("tree")],
     [remove(category="tree", near="fountain", count=1)])
case("removal", "direct", "hydrant_and_stop_sign", "newcomer",
     "Please take out the fire hydrant and the stop sign.",
     [gone("fire_hydrant_1", "stop_sign_1"), keep("fire_hydrant", "stop_sign")],
     [remove("fire_hydrant_1"), remove("stop_sign_1")], tags=("compound",))
case("removal", "direct", "sedans_not_suv", "QA tester",
     "Remove both sedans from lot B but leave the SUV where it is.",
     [gone(*LOT_B_SEDANS), kept("suv_1"), keep("passenger_car")],
     [remove(*LOT_B_SEDANS)])
case("removal", "direct", "stop_sign", "ADAS student",
     "Take the stop sign away.",
     [gone("stop_sign_1"), keep("stop_sign")],
     [remove("stop_sign_1")])
case("removal", "direct", "two_of_the_cones", "simulation engineer",
     "Now remove two of them.",
     [delta("traffic_cone", -2), count("traffic_cone", 3), keep("traffic_cone")],
     [remove(category="traffic_cone", count=2)],
     setup=(turn("Put five cones in lot B.", [add("traffic_cone", 5, loc("parking lot B"))], planned=True),))
impossible("removal", "direct", "east_gate", "team lead",
           "Delete the east gate.",
           [remove("east gate")], "the east gate is a place on the map, not an asset")

# indirect ------------------------------------------------------------------------------------
case("removal", "indirect", "bench_in_the_shot", "simulation engineer",
     "The bench by the bus stop keeps turning up in the blind-spot camera test. I don't want it in the scene.",
     [gone("bench_1"), keep("bench")],
     [remove("bench_1")])
case("removal", "indirect", "tree_shadows", "researcher",
     "The tree right next to the library throws shadows across the road that confuse my lane detector.",
     [gone("tree_1"), kept("tree_2", "tree_3", "tree_4"), keep("tree")],
     [remove("tree_1")])
case("removal", "indirect", "lot_b_empty", "team lead",
     "Lot B has to be completely empty for the parking test.",
     [gone(*LOT_B_CARS), keep(*CARS)],
     [remove(*LOT_B_CARS)])
case("removal", "indirect", "lights_by_junction_west", "QA tester",
     "The two street lights closest to the crossroads on the west side clutter the junction test, "
     "so they need to go.",
     [gone("street_light_5", "street_light_6"), delta("street_light", -2), keep("street_light")],
     [remove("street_light_5", "street_light_6")])
case("removal", "indirect", "halt_sign", "newcomer",
     "There's a sign near the west crosswalk telling cars to halt. We don't need it.",
     [gone("stop_sign_1"), keep("stop_sign")],
     [remove("stop_sign_1")])
case("removal", "indirect", "bin_never_emptied", "ADAS student",
     "Nobody ever empties the bin by the bus stop, so let's just lose it.",
     [gone("trash_bin_1"), keep("trash_bin")],
     [remove("trash_bin_1")])
case("removal", "indirect", "people_confuse_tracker", "simulation engineer",
     "The people I added are confusing the tracker, I don't need them any more.",
     [count("pedestrian", 0), keep("pedestrian")],
     [remove(category="pedestrian")],
     setup=(turn("Add three pedestrians at the JTEKT entrance.", [add("pedestrian", 3, loc("JTEKT building entrance"))]),))
case("removal", "indirect", "clean_baseline", "team lead",
     "For a clean baseline run I want no other vehicles in the scene apart from our own car.",
     [count([*VEHICLES], 0), kept("ego"), keep(*VEHICLES)],
     [remove(*LOT_B_CARS, "truck_1", "bus_1")],
     setup=(turn("Add a truck driving west on Main Street and a bus in lot A.",
                 [add("truck", behaviour={"kind": "drive_lane", "lane": "main_westbound"}),
                  add("bus", where=loc("parking lot A"))]),))
impossible("removal", "indirect", "north_crosswalk", "researcher",
           "The north crosswalk keeps tripping my crossing detector; take it out of the map.",
           [remove("north crosswalk")], "crosswalks are part of the road network, not assets")

# vague ---------------------------------------------------------------------------------------
case("removal", "vague", "lights_near_east_gate", "newcomer",
     "maybe take out a couple of the street lights near the east gate?",
     [gone("street_light_12"), delta("street_light", -3, -2), kept(*NORTH_LIGHTS[:4], *SOUTH_LIGHTS[:4]),
      keep("street_light")],
     [remove(category="street_light", near="east gate", count=2)])
case("removal", "vague", "thin_trees_fountain", "ADAS student",
     "There are too many trees around the fountain, thin them out a bit.",
     [delta("tree", -1), kept("tree_1", "tree_4"), keep("tree")],
     [remove(category="tree", near="fountain", count=1)])
case("removal", "vague", "most_cars_lot_b", "QA tester",
     "Clear most of the cars out of lot B, just leave one.",
     [delta(CARS, -2), count(CARS, 1), keep(*CARS)],
     [remove("passenger_car_1", "passenger_car_2")])
case("removal", "vague", "junk_ahead", "simulation engineer",
     "get rid of that junk in front of the ego, i think it's rubble or something",
     [count("cement_rubble", 0), keep("cement_rubble", "traffic_cone")],
     [remove(category="cement_rubble")],
     setup=(turn("Add two piles of rubble in the eastbound lane 30 m ahead of the ego, and three cones in lot A.",
                 [add("cement_rubble", 2, loc("ego", along_m=30)), add("traffic_cone", 3, loc("parking lot A"))]),))
case("removal", "vague", "about_half_the_people", "team lead",
     "that's a few too many, lose about half of them",
     [delta("pedestrian", -4, -2), keep("pedestrian")],
     [remove(category="pedestrian", count=3)],
     setup=(turn("Put six people on the sidewalk outside the library.",
                 [add("pedestrian", 6, loc("Library entrance", "on_sidewalk"))], planned=True),))
case("removal", "vague", "lamp_by_stop_sign", "newcomer",
     "the lamp near the stop sign, can you get rid of it or whatever",
     [gone("street_light_6"), delta("street_light", -1), keep("street_light")],
     [remove("street_light_6")])
case("removal", "vague", "pole_thing_by_hydrant", "researcher",
     "There's some pole thing near the hydrant, I don't want it.",
     [delta(["street_light", "traffic_light"], -1), keep("street_light", "traffic_light")],
     [remove("traffic_light_2")],
     alternatives=([gone("traffic_light_2")], [gone("street_light_7")]))
case("removal", "vague", "trees_out_by_lot_a", "QA tester",
     "can we lose whatever trees are out by lot A",
     [gone("tree_4"), delta("tree", -1), keep("tree")],
     [remove("tree_4")])
impossible("removal", "vague", "that_bus_somewhere", "team lead",
           "umm remove the bus, I think there's one somewhere?",
           [remove(category="bus")], "the scene has no bus to remove")

# erroneous -----------------------------------------------------------------------------------
case("removal", "erroneous", "remvoe_bnech", "QA tester",
     "remvoe the bnech",
     [gone("bench_1"), keep("bench")],
     [remove("bench_1")])
case("removal", "erroneous", "delte_suv", "simulation engineer",
     "delte the suv pls",
     [gone("suv_1"), keep(assets=["suv_1"])],
     [remove("suv_1")])
case("removal", "erroneous", "tre_libary", "researcher",
     "take out the tre next to the libary",
     [gone("tree_1"), kept("tree_2", "tree_3", "tree_4"), keep("tree")],
     [remove("tree_1")])
case("removal", "erroneous", "hydrnat_and_bench", "newcomer",
     "can u remove the fire hydrnat and teh bench",
     [gone("fire_hydrant_1", "bench_1"), keep("fire_hydrant", "bench")],
     [remove("fire_hydrant_1"), remove("bench_1")], tags=("compound",))
case("removal", "erroneous", "souht_side_lights", "team lead",
     "remove all street lights on the souht side of main st",
     [gone(*SOUTH_LIGHTS), kept(*NORTH_LIGHTS), keep("street_light")],
     [remove(*SOUTH_LIGHTS)])
case("removal", "erroneous", "cars_exept_suv", "ADAS student",
     "remove the cars in lot B exept the suv",
     [gone(*LOT_B_SEDANS), kept("suv_1"), keep("passenger_car")],
     [remove(*LOT_B_SEDANS)])
case("removal", "erroneous", "cones_agian", "QA tester",
     "remove all the cones agian",
     [count("traffic_cone", 0), keep("traffic_cone")],
     [remove(category="traffic_cone")],
     setup=(turn("Add six cones along the eastbound lane.",
                 [arrange("traffic_cone", "lane_edge", loc("main_eastbound", "in_lane"), count=6)], planned=True),))
impossible("removal", "erroneous", "ego_vehical", "newcomer",
           "remove the ego vehical please, we dont need it",
           [remove("ego")], "the ego vehicle cannot be removed")

# =============================================================================================
# positioning: an existing asset put somewhere new, nothing else touched
# =============================================================================================

# direct --------------------------------------------------------------------------------------
case("positioning", "direct", "bench_to_fountain", "QA tester",
     "Put the bench next to the fountain.",
     [near("fountain", 6, asset="bench_1"), keep(assets=["bench_1"])],
     [place("bench_1", loc("fountain"))])
case("positioning", "direct", "bin_to_library", "newcomer",
     "Move the trash bin to the library entrance.",
     [near("Library entrance", 5, asset="trash_bin_1"), keep(assets=["trash_bin_1"])],
     [place("trash_bin_1", loc("Library entrance"))])
case("positioning", "direct", "suv_into_lot_a", "simulation engineer",
     "Park the SUV in lot A.",
     [near("parking lot A", 1, asset="suv_1"), does("parked", sel={"asset": "suv_1"}), keep(assets=["suv_1"])],
     [place("suv_1", loc("parking lot A"))])
case("positioning", "direct", "ego_northbound_south", "researcher",
     "Put the ego in the northbound lane of Campus Drive, south of the crossroads.",
     [in_lane("campus_northbound", aligned=True, asset="ego"), near_xy(1.75, -50.0, 41, asset="ego"),
      keep(assets=["ego"])],
     [place("ego", xy(1.75, -40.0), yaw_deg=90)])
case("positioning", "direct", "hydrant_to_jtekt", "team lead",
     "Move the fire hydrant to the sidewalk in front of the JTEKT building.",
     [near("JTEKT building entrance", 12, asset="fire_hydrant_1"), on("sidewalk", asset="fire_hydrant_1"),
      keep(assets=["fire_hydrant_1"])],
     [place("fire_hydrant_1", loc("JTEKT building entrance", "on_sidewalk"))])
case("positioning", "direct", "suv_behind_ego", "ADAS student",
     "Put the SUV right behind the ego.",
     [relative("behind", "ego", 15, asset="suv_1"), keep(assets=["suv_1"])],
     [place("suv_1", loc("ego", "behind"))])
case("positioning", "direct", "bench_and_bin_union", "simulation engineer",
     "Put the bench in front of the Student Union entrance, and the bin next to it.",
     [near("Student Union entrance", 6, asset="bench_1"), near("bench_1", 3, asset="trash_bin_1"),
      keep(assets=["bench_1", "trash_bin_1"])],
     [place("bench_1", loc("Student Union entrance", "in_front_of")), place("trash_bin_1", loc("bench_1", "next_to"))],
     tags=("compound",))
case("positioning", "direct", "stop_sign_north_crosswalk", "QA tester",
     "Move the stop sign to the north crosswalk.",
     [near("north crosswalk", 8, asset="stop_sign_1"), keep(assets=["stop_sign_1"])],
     [place("stop_sign_1", loc("north crosswalk"))])
impossible("positioning", "direct", "hydrant_north_gate", "researcher",
           "Put the fire hydrant at the north gate.",
           [place("fire_hydrant_1", loc("north gate"))], "the campus has a main (west) gate and an east gate, no north gate")

# indirect ------------------------------------------------------------------------------------
case("positioning", "indirect", "bench_into_shade", "newcomer",
     "The bench is out in full sun. People would rather sit under the tree by the library.",
     [near("tree_1", 2.5, asset="bench_1"), moved("bench_1", 0.5), keep(assets=["bench_1"])],
     [place("bench_1", loc("tree_1", "next_to"))])
case("positioning", "indirect", "suv_pickup_union", "team lead",
     "The SUV is meant to be picking someone up from the Student Union, so it should be waiting by the entrance.",
     [near("Student Union entrance", 10, asset="suv_1"), moved("suv_1", 1), keep(assets=["suv_1"])],
     [place("suv_1", loc("Student Union entrance"))])
case("positioning", "indirect", "hydrant_for_library", "QA tester",
     "In the last drill the fire crew couldn't get to the hydrant, it should be right outside the library.",
     [near("Library entrance", 11, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])],
     [place("fire_hydrant_1", loc("Library entrance", "on_sidewalk"))])
case("positioning", "indirect", "ego_starts_lot_b", "simulation engineer",
     "The next scenario starts with the ego parked in lot B, can you set that up?",
     [near("parking lot B", 1, asset="ego"), does("parked", sel={"asset": "ego"}), keep(assets=["ego"])],
     [place("ego", loc("parking lot B"))])
case("positioning", "indirect", "bin_for_visitors", "researcher",
     "Visitors come in through the main gate and there's nowhere to throw their rubbish.",
     [near("main gate", 12, category="trash_bin"), delta("trash_bin", 0, 1), keep("trash_bin")],
     [place("trash_bin_1", loc("main gate"))])
case("positioning", "indirect", "cyclist_waits_north", "team lead",
     "That cyclist should be waiting at the north crosswalk instead.",
     [near("north crosswalk", 8, asset="bicycle_1"), keep(assets=["bicycle_1"])],
     [place("bicycle_1", loc("north crosswalk"))],
     setup=(turn("Add a cyclist near the east gate.", [add("bicycle", where=loc("east gate"))]),))
case("positioning", "indirect", "truck_for_jtekt", "team lead",
     "Actually the delivery is for JTEKT, so the truck should be at their entrance.",
     [near("JTEKT building entrance", 10, asset="truck_1"), keep(assets=["truck_1"])],
     [place("truck_1", loc("JTEKT building entrance"))],
     setup=(turn("Add a truck in lot A.", [add("truck", where=loc("parking lot A"))]),))
case("positioning", "indirect", "ped_ready_to_cross", "ADAS student",
     "I want the pedestrian waiting at the west crosswalk, ready to cross.",
     [near("west crosswalk", 6, asset="pedestrian_1"), keep(assets=["pedestrian_1"])],
     [place("pedestrian_1", loc("west crosswalk"))],
     setup=(turn("Add a pedestrian at the bus stop.", [add("pedestrian", where=loc("bus stop"))]),))
impossible("positioning", "indirect", "suv_150m_north", "researcher",
           "Our long-range radar test needs the SUV about 150 metres north of the crossroads.",
           [place("suv_1", xy(0.0, 150.0))], "the map ends 90 m north of the crossroads")

# vague ---------------------------------------------------------------------------------------
case("positioning", "vague", "bench_over_by_lot_a", "newcomer",
     "put the bench somewhere over by lot A, wherever",
     [near("parking lot A", 6, asset="bench_1"), keep(assets=["bench_1"])],
     [place("bench_1", loc("parking lot A"))])
case("positioning", "vague", "suv_ahead_of_ego", "simulation engineer",
     "Stick the SUV somewhere in front of the ego, not too far.",
     [relative("in_front_of", "ego", 40, asset="suv_1"), keep(assets=["suv_1"])],
     [place("suv_1", loc("ego", "in_front_of", distance=20))])
case("positioning", "vague", "hydrant_round_union", "QA tester",
     "the hydrant should be somewhere around the Student Union",
     [near("Student Union entrance", 15, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])],
     [place("fire_hydrant_1", loc("Student Union entrance"))])
case("positioning", "vague", "bin_beside_bench", "ADAS student",
     "move the bin closer to the bench, like right beside it",
     [near("bench_1", 1.5, asset="trash_bin_1"), keep(assets=["trash_bin_1"])],
     [place("trash_bin_1", loc("bench_1", "next_to"))])
case("positioning", "vague", "ped_to_fountain_ish", "researcher",
     "hmm, put them over by the fountain-ish instead",
     [near("fountain", 10, category="pedestrian", scope="all", require_all=True), keep("pedestrian")],
     [place("pedestrian_1", loc("fountain"))],
     setup=(turn("Add a pedestrian at the main gate.", [add("pedestrian", where=loc("main gate"))], planned=True),))
case("positioning", "vague", "a_sedan_to_lot_a", "team lead",
     "Move one of the sedans in lot B over to the other lot, doesn't matter which.",
     [delta("passenger_car", 0), keep("passenger_car")],
     [place("passenger_car_1", loc("parking lot A"))],
     alternatives=([near("parking lot A", 1, asset="passenger_car_1"), kept("passenger_car_2"),
                    keep(assets=["passenger_car_1"])],
                   [near("parking lot A", 1, asset="passenger_car_2"), kept("passenger_car_1"),
                    keep(assets=["passenger_car_2"])]))
case("positioning", "vague", "stop_sign_nearer_corner", "ADAS student",
     "the stop sign feels a bit far from the crossroads, bring it closer to the corner",
     [near("main intersection", 3, asset="stop_sign_1"), moved("stop_sign_1", 0.5), keep(assets=["stop_sign_1"])],
     [place("stop_sign_1", xy(-10.5, -8.0))])
case("positioning", "vague", "hydrant_near_east_gate", "newcomer",
     "can the hydrant go somewhere near the east gate instead",
     [near("east gate", 12, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])],
     [place("fire_hydrant_1", loc("east gate"))])
impossible("positioning", "vague", "tennis_courts", "simulation engineer",
           "put the suv somewhere over by the tennis courts",
           [place("suv_1", loc("tennis courts"))], "the campus has no tennis courts")

# erroneous -----------------------------------------------------------------------------------
case("positioning", "erroneous", "bench_fontain", "QA tester",
     "put the bench by the fontain",
     [near("fountain", 6, asset="bench_1"), keep(assets=["bench_1"])],
     [place("bench_1", loc("fountain"))])
case("positioning", "erroneous", "bin_libary_entrence", "newcomer",
     "move the trash bin to the libary entrence",
     [near("Library entrance", 5, asset="trash_bin_1"), keep(assets=["trash_bin_1"])],
     [place("trash_bin_1", loc("Library entrance"))])
case("positioning", "erroneous", "prak_suv_and_ego", "simulation engineer",
     "prak the SUV in lot A and the ego in lot b",
     [near("parking lot A", 1, asset="suv_1"), near("parking lot B", 1, asset="ego"),
      keep(assets=["suv_1", "ego"])],
     [place("suv_1", loc("parking lot A")), place("ego", loc("parking lot B"))], tags=("compound",))
case("positioning", "erroneous", "hydrant_side_walk", "researcher",
     "put the hydrant on the side walk infront of JTEKT",
     [near("JTEKT building entrance", 12, asset="fire_hydrant_1"), on("sidewalk", asset="fire_hydrant_1"),
      keep(assets=["fire_hydrant_1"])],
     [place("fire_hydrant_1", loc("JTEKT building entrance", "on_sidewalk"))])
case("positioning", "erroneous", "ego_shoud_start_lot_b", "team lead",
     "ego shoud start in lot B, parked",
     [near("parking lot B", 1, asset="ego"), does("parked", sel={"asset": "ego"}), keep(assets=["ego"])],
     [place("ego", loc("parking lot B"))])
case("positioning", "erroneous", "stopsign_nroth", "ADAS student",
     "move the stopsign over to the nroth crosswalk",
     [near("north crosswalk", 8, asset="stop_sign_1"), keep(assets=["stop_sign_1"])],
     [place("stop_sign_1", loc("north crosswalk"))])
case("positioning", "erroneous", "it_frnot_of_union", "QA tester",
     "now put it in frnot of the student union",
     [near("Student Union entrance", 6, asset="bench_2"), kept("bench_1"), keep(assets=["bench_2"])],
     [place("bench_2", loc("Student Union entrance", "in_front_of"))],
     setup=(turn("Add a bench by the bus stop.", [add("bench", where=loc("bus stop"))], planned=True),))
case("positioning", "erroneous", "plce_suv_ahead", "simulation engineer",
     "plce the suv in front of teh ego, about 20 m",
     [relative("in_front_of", "ego", 30, asset="suv_1"), near_xy(-40.0, -1.75, 8, asset="suv_1"),
      keep(assets=["suv_1"])],
     [place("suv_1", loc("ego", "in_front_of", distance=20))])
impossible("positioning", "erroneous", "bench_on_libary_roof", "newcomer",
           "put the bench on teh roof of the libary",
           [place("bench_1", xy(-41.0, -30.0))], "nothing can stand on or inside a building")

# =============================================================================================
# moving: shifts, turns, behaviours and timed manoeuvres of assets already in the scene
# =============================================================================================

# direct --------------------------------------------------------------------------------------
case("moving", "direct", "bench_west_and_turn", "QA tester",
     "Move the bench 3 metres west and turn it 90 degrees.",
     [near_xy(-29.0, -6.9, 0.8, asset="bench_1"), moved("bench_1", 2.5, 3.5, turn_min=80, turn_max=100),
      keep(assets=["bench_1"])],
     [shift("bench_1", east=-3), shift("bench_1", turn_deg=90)], tags=("compound",))
case("moving", "direct", "suv_forward_15_feet", "simulation engineer",
     "Move the SUV forward 15 feet.",
     [moved("suv_1", 4.1, 5.1, "forward"), keep(assets=["suv_1"])],
     [shift("suv_1", forward=4.6)])
case("moving", "direct", "ego_8_and_suv_west", "researcher",
     "Set the ego's speed to 8 m/s and have the SUV drive west on Main Street.",
     [does("drive_lane", lane="main_eastbound", speed_min=7.9, speed_max=8.1, sel={"asset": "ego"}),
      does("drive_lane", lane="main_westbound", sel={"asset": "suv_1"}), keep(assets=["ego", "suv_1"])],
     [behave("ego", "drive_lane", lane="main_eastbound", speed=8),
      behave("suv_1", "drive_lane", lane="main_westbound")], tags=("compound",))
case("moving", "direct", "west_sedan_north", "ADAS student",
     "Make the sedan at the west end of the lot B row drive north on Campus Drive.",
     [does("drive_lane", lane="campus_northbound", sel={"asset": "passenger_car_1"}),
      keep(assets=["passenger_car_1"])],
     [behave("passenger_car_1", "drive_lane", lane="campus_northbound")])
case("moving", "direct", "ped_walks_across", "team lead",
     "Have that pedestrian walk across the crosswalk.",
     [does("cross_road", crosses_lane="main_eastbound", sel={"asset": "pedestrian_1"}),
      near("west crosswalk", 8, asset="pedestrian_1"), keep(assets=["pedestrian_1"])],
     [behave("pedestrian_1", "cross_road")],
     setup=(turn("Add a pedestrian at the west crosswalk.", [add("pedestrian", where=loc("west crosswalk"))]),))
case("moving", "direct", "bench_half_turn", "newcomer",
     "Spin the bench round 180 degrees.",
     [moved("bench_1", 0.0, 0.5, turn_min=170), keep(assets=["bench_1"])],
     [shift("bench_1", turn_deg=180)])
case("moving", "direct", "ego_brakes_at_sign", "simulation engineer",
     "Make the ego brake to a stop when it gets within 15 m of the stop sign.",
     [run_for(15, event("stop", "ego"), stopped_before(-13.5, -1.75)), keep()],
     [call("add_event", actor="ego", manoeuvre={"kind": "stop", "rate": 4},
           when={"kind": "distance", "actor": "ego", "other": "stop_sign_1", "metres": 15})])
case("moving", "direct", "east_sedan_circles", "QA tester",
     "Make the sedan on the east end of the lot B row drive in circles in the lot.",
     [does("circle", centre_near="parking lot B", centre_within=1, sel={"asset": "passenger_car_2"}),
      keep(assets=["passenger_car_2"])],
     [behave("passenger_car_2", "circle")])
impossible("moving", "direct", "shift_campus_drive", "researcher",
           "Shift Campus Drive 5 metres east.",
           [shift("Campus Drive", east=5)], "roads are part of the map and cannot be moved")

# indirect ------------------------------------------------------------------------------------
case("moving", "indirect", "more_run_up", "simulation engineer",
     "There isn't enough run-up for the braking test, the ego should start 20 m further back.",
     [moved("ego", 18, 22, "backward"), in_lane("main_eastbound", asset="ego"), keep(assets=["ego"])],
     [shift("ego", forward=-20)])
case("moving", "indirect", "suv_joins_traffic", "team lead",
     "The SUV needs to join the traffic on Main Street heading east.",
     [does("drive_lane", lane="main_eastbound", sel={"asset": "suv_1"}), keep(assets=["suv_1"])],
     [behave("suv_1", "drive_lane", lane="main_eastbound")])
case("moving", "indirect", "ped_steps_out", "researcher",
     "For the AEB test I want that pedestrian to step out in front of the ego, away from any crossing.",
     [does("jaywalk", sel={"asset": "pedestrian_1"}), keep(assets=["pedestrian_1"])],
     [behave("pedestrian_1", "jaywalk")],
     setup=(turn("Add a pedestrian at the bus stop.", [add("pedestrian", where=loc("bus stop"))]),))
case("moving", "indirect", "school_zone_crawl", "QA tester",
     "We're simulating a school zone, so the ego should crawl along at about 3 m/s.",
     [does("drive_lane", speed_min=2.5, speed_max=3.5, sel={"asset": "ego"}), keep(assets=["ego"])],
     [behave("ego", "drive_lane", lane="main_eastbound", speed=3)])
case("moving", "indirect", "skidpad_suv", "ADAS student",
     "I'm testing tyre grip on a skidpad: the SUV should do laps of 8 m radius in lot B.",
     [does("circle", radius_min=7.5, radius_max=8.5, centre_near="parking lot B", centre_within=1,
           sel={"asset": "suv_1"}), keep(assets=["suv_1"])],
     [behave("suv_1", "circle", radius=8)])
case("moving", "indirect", "truck_too_slow", "simulation engineer",
     "The truck is too slow for the overtaking test, it should be doing about 10 m/s.",
     [does("drive_lane", lane="main_westbound", speed_min=9, speed_max=11, sel={"asset": "truck_1"}),
      keep(assets=["truck_1"])],
     [behave("truck_1", "drive_lane", lane="main_westbound", speed=10)],
     setup=(turn("Add a truck driving west on Main Street.",
                 [add("truck", behaviour={"kind": "drive_lane", "lane": "main_westbound"})]),))
case("moving", "indirect", "red_for_the_ego", "team lead",
     "For the red-light test the ego has to meet a red at the crossroads, so keep the light on its side red.",
     [run_for(20, stopped_before(-13.0, -1.75), no_collision()), keep()],
     [call("set_light_phases", light="traffic_light_1", phases=[{"state": "red", "duration": 600}])])
case("moving", "indirect", "ego_off_the_lamp", "simulation engineer",
     "The ego starts right next to a lamp post that shows up in every frame; move it 10 m up the lane.",
     [moved("ego", 9, 11, "forward"), in_lane("main_eastbound", asset="ego"), keep(assets=["ego"])],
     [shift("ego", forward=10)])
impossible("moving", "indirect", "ego_100_mph", "QA tester",
           "The speed-limit test needs the ego doing 100 miles an hour.",
           [behave("ego", "drive_lane", lane="main_eastbound", speed=44.7)], "speeds are capped at 40 m/s (about 90 mph)")

# vague ---------------------------------------------------------------------------------------
case("moving", "vague", "bench_bit_east", "newcomer",
     "move the bench a little bit east",
     [moved("bench_1", 0.3, 4, "backward"), keep(assets=["bench_1"])],
     [shift("bench_1", east=1.5)])
case("moving", "vague", "nudge_suv", "simulation engineer",
     "nudge the SUV forward a few feet",
     [moved("suv_1", 0.3, 2.5, "forward"), keep(assets=["suv_1"])],
     [shift("suv_1", forward=1.0)])
case("moving", "vague", "ego_bit_slower", "researcher",
     "Could the ego go a bit slower?",
     [does("drive_lane", lane="main_eastbound", speed_min=1.0, speed_max=4.6, sel={"asset": "ego"}),
      keep(assets=["ego"])],
     [behave("ego", "drive_lane", lane="main_eastbound", speed=3.5)])
case("moving", "vague", "a_sedan_on_the_road", "team lead",
     "get one of the lot B sedans driving around on the roads somewhere",
     [does("drive_lane", sel={"category": "passenger_car", "scope": "touched"}), delta("passenger_car", 0),
      keep("passenger_car")],
     [behave("passenger_car_2", "drive_lane", lane="main_eastbound")],
     alternatives=([kept("passenger_car_1"), keep(assets=["passenger_car_2"])],
                   [kept("passenger_car_2"), keep(assets=["passenger_car_1"])]))
case("moving", "vague", "walk_to_other_side", "QA tester",
     "make them walk over to the other side or whatever",
     [does(["cross_road", "follow_path"], sel={"category": "pedestrian", "scope": "touched"}), keep("pedestrian")],
     [behave("pedestrian_1", "cross_road")],
     setup=(turn("Put a pedestrian at the north crosswalk.", [add("pedestrian", where=loc("north crosswalk"))],
                 planned=True),))
case("moving", "vague", "ego_back_two_cars", "ADAS student",
     "move the ego back like two car lengths",
     [moved("ego", 7, 11, "backward"), keep(assets=["ego"])],
     [shift("ego", forward=-9)])
case("moving", "vague", "donuts_lot_a", "simulation engineer",
     "have one of the cars do donuts in lot A or something",
     [does("circle", centre_near="parking lot A", centre_within=1, sel={"category": CARS, "scope": "touched"}),
      delta(CARS, 0, 1), keep(*CARS)],
     [behave("passenger_car_1", "circle", centre="parking lot A")])
case("moving", "vague", "truck_other_way", "newcomer",
     "turn the truck round so it faces the other way",
     [moved("truck_1", 0.0, 3.0, turn_min=150), keep(assets=["truck_1"])],
     [shift("truck_1", turn_deg=180)],
     setup=(turn("Add a truck in lot A.", [add("truck", where=loc("parking lot A"))]),))
impossible("moving", "vague", "bin_laps", "QA tester",
           "could the bin kind of drive itself round lot B or something",
           [behave("trash_bin_1", "circle", centre="parking lot B")], "a trash bin cannot drive")

# erroneous -----------------------------------------------------------------------------------
case("moving", "erroneous", "mvoe_bench_wesst", "QA tester",
     "mvoe the bench 2 meters wesst",
     [near_xy(-28.0, -6.9, 0.6, asset="bench_1"), moved("bench_1", 1.5, 2.5), keep(assets=["bench_1"])],
     [shift("bench_1", east=-2)])
case("moving", "erroneous", "suv_forwrd_3m", "simulation engineer",
     "move teh SUV forwrd 3m",
     [moved("suv_1", 2.5, 3.5, "forward"), keep(assets=["suv_1"])],
     [shift("suv_1", forward=3)])
case("moving", "erroneous", "ego_sped_6", "researcher",
     "set teh ego sped to 6 m/s",
     [does("drive_lane", lane="main_eastbound", speed_min=5.9, speed_max=6.1, sel={"asset": "ego"}),
      keep(assets=["ego"])],
     [behave("ego", "drive_lane", lane="main_eastbound", speed=6)])
case("moving", "erroneous", "suv_driev_west", "ADAS student",
     "make the suv driev west on main stret",
     [does("drive_lane", lane="main_westbound", sel={"asset": "suv_1"}), keep(assets=["suv_1"])],
     [behave("suv_1", "drive_lane", lane="main_westbound")])
case("moving", "erroneous", "pedestrain_jay_walk", "team lead",
     "make the pedestrain jay walk infront of the ego",
     [does("jaywalk", sel={"asset": "pedestrian_1"}), keep(assets=["pedestrian_1"])],
     [behave("pedestrian_1", "jaywalk")],
     setup=(turn("Add a pedestrian on the sidewalk outside Engineering Hall.",
                 [add("pedestrian", where=loc("Engineering Hall entrance", "on_sidewalk"))]),))
case("moving", "erroneous", "rotate_bench_degress", "newcomer",
     "rotate the bench 90 degress",
     [moved("bench_1", 0.0, 0.5, turn_min=80, turn_max=100), keep(assets=["bench_1"])],
     [shift("bench_1", turn_deg=90)])
case("moving", "erroneous", "lot_b_cars_nroth", "QA tester",
     "shift all three cars in lot B two metres nroth",
     [moved("passenger_car_1", 1.5, 2.5, "forward"), moved("suv_1", 1.5, 2.5, "forward"),
      moved("passenger_car_2", 1.5, 2.5, "forward"), keep(assets=LOT_B_CARS)],
     [shift(LOT_B_CARS, north=2)])
case("moving", "erroneous", "brake_after_4_secnods", "simulation engineer",
     "make the ego brake hard after 4 secnods",
     [run_for(10, event("stop", "ego"), stopped_before(-31.0, -1.75)), keep()],
     [call("add_manoeuvre", actor="ego", manoeuvre={"kind": "stop", "rate": 6}, at_time=4)])
impossible("moving", "erroneous", "bus_stop_closer", "newcomer",
           "move teh bus stop closer to the main gate",
           [shift("bus stop", east=-20)], "the bus stop is a place on the map, not an asset")

# =============================================================================================
# arrangement: several new assets laid out together (lines, rings, rows, grids, lane edges)
# =============================================================================================

# direct --------------------------------------------------------------------------------------
case("arrangement", "direct", "cone_line_ahead_of_ego", "simulation engineer",
     "Put a line of five cones across the eastbound lane, 20 m in front of the ego.",
     [delta("traffic_cone", 5), layout("line", "traffic_cone"),
      near_xy(-40.0, -1.75, 4, category="traffic_cone", scope="added", require_all=True),
      # across the lane: a cone in its south half (y <= -2.3) and one in its north half (y >= -1.2)
      near_xy(-40.0, -22.3, 20, category="traffic_cone", scope="added", min_count=1),
      near_xy(-40.0, 18.8, 20, category="traffic_cone", scope="added", min_count=1), keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("ego", "in_front_of", distance=20), count=5)])
case("arrangement", "direct", "bench_circle_fountain", "newcomer",
     "Arrange six benches in a circle around the fountain.",
     [delta("bench", 6), layout("ring", "bench", around="fountain", min_count=6), keep("bench")],
     [arrange("bench", "ring", loc("fountain"), count=6, radius=4)])
case("arrangement", "direct", "car_row_lot_a", "QA tester",
     "Park a row of four cars side by side in lot A.",
     [delta(CARS, 4), layout("line", CARS, min_count=4),
      near("parking lot A", 1, category=CARS, scope="added", require_all=True),
      does("parked", sel={"category": CARS, "scope": "added", "require_all": True}), keep(*CARS)],
     [arrange("passenger_car", "parking_row", loc("parking lot A"), count=4)])
case("arrangement", "direct", "westbound_edge_cones", "researcher",
     "Line the edge of the westbound lane with six cones, 3 m apart.",
     [delta("traffic_cone", 6), layout("line", "traffic_cone", min_count=6, spacing_min=2.5, spacing_max=3.5),
      in_lane("main_westbound", category="traffic_cone", scope="added"), keep("traffic_cone")],
     [arrange("traffic_cone", "lane_edge", loc("main_westbound", "in_lane"), count=6, spacing=3)])
case("arrangement", "direct", "bin_grid_lot_b", "team lead",
     "Put a 2 by 2 grid of trash bins in the middle of lot B.",
     [delta("trash_bin", 4), layout("cluster", "trash_bin", min_count=4, tolerance=3),
      near("parking lot B", 1, category="trash_bin", scope="added", require_all=True), keep("trash_bin")],
     [arrange("trash_bin", "grid", loc("parking lot B"), count=4, columns=2)])
case("arrangement", "direct", "barriers_and_sign_lot_b", "ADAS student",
     "Block the lot B entrance with a line of three barriers and put a roadworks sign next to them.",
     [delta("road_barrier", 3), delta("construction_sign", 1), layout("line", "road_barrier"),
      near("parking lot B entrance", 8, category="road_barrier", scope="added", require_all=True),
      near("parking lot B entrance", 12, category="construction_sign", scope="added"),
      keep("road_barrier", "construction_sign")],
     [arrange("road_barrier", "line", xy(47.0, -8.0), count=3, heading_deg=0, spacing=2.1),
      add("construction_sign", where=loc("road_barrier_3", "next_to"))], tags=("compound",))
case("arrangement", "direct", "cone_ring_round_rubble", "simulation engineer",
     "Now put a ring of eight cones around it.",
     [delta("traffic_cone", 8), layout("ring", "traffic_cone", around="cement_rubble_1", min_count=8),
      keep("traffic_cone")],
     [arrange("traffic_cone", "ring", loc("cement_rubble_1"), count=8)],
     setup=(turn("Drop a pile of rubble in the middle of lot B.", [add("cement_rubble", where=loc("parking lot B"))],
                 planned=True),))
case("arrangement", "direct", "bike_row_library", "QA tester",
     "Put four bicycles in a row on the sidewalk outside the library.",
     [delta("bicycle", 4), layout("line", "bicycle", min_count=4),
      near("Library entrance", 15, category="bicycle", scope="added", require_all=True),
      on("sidewalk", category="bicycle", scope="added"), keep("bicycle")],
     [arrange("bicycle", "line", loc("Library entrance", "on_sidewalk"), count=4)])
impossible("arrangement", "direct", "ring_150_cones", "researcher",
           "Arrange 150 cones in a ring around lot A.",
           [arrange("traffic_cone", "ring", loc("parking lot A"), count=150)],
           "one layout holds at most 100 assets")

# indirect ------------------------------------------------------------------------------------
case("arrangement", "indirect", "close_westbound_roadworks", "team lead",
     "There are roadworks on the westbound lane east of the junction, so close that lane off properly "
     "for the lane-change test.",
     [delta(BLOCKERS, 3, 20), layout("line", BLOCKERS, tolerance=1.5),
      in_lane("main_westbound", category=BLOCKERS, scope="added"),
      near_xy(35.0, 1.75, 27, category=BLOCKERS, scope="added", require_all=True), keep(*BLOCKERS)],
     [arrange("traffic_cone", "line", xy(30.0, 1.75), count=4, heading_deg=90, spacing=0.9)])
case("arrangement", "indirect", "parking_assist_gap", "QA tester",
     "The parking-assist test needs the ego to find a gap between parked cars in lot B, so add three "
     "more cars parked in a row there.",
     [delta(CARS, 3), layout("line", CARS, min_count=3),
      near("parking lot B", 1, category=CARS, scope="added", require_all=True),
      does("parked", sel={"category": CARS, "scope": "added", "require_all": True}), keep(*CARS)],
     [arrange("passenger_car", "parking_row", loc("parking lot B"), count=3)])
case("arrangement", "indirect", "people_round_bench", "researcher",
     "For the pedestrian-detection study I need a group of about six people standing in a ring around "
     "the bench.",
     [delta("pedestrian", 5, 7), layout("ring", "pedestrian", around="bench_1", min_count=5), keep("pedestrian")],
     [arrange("pedestrian", "ring", loc("bench_1"), count=6)])
case("arrangement", "indirect", "fence_round_tree", "newcomer",
     "Students keep climbing the tree by the library, so it needs fencing off all the way round.",
     [delta(["bollard", "road_barrier"], 4, 20), layout("ring", ["bollard", "road_barrier"], around="tree_1", min_count=4),
      keep("bollard", "road_barrier")],
     [arrange("bollard", "ring", loc("tree_1"), count=8, radius=3)])
case("arrangement", "indirect", "ego_must_stop", "simulation engineer",
     "The ego should be forced to stop, so block the road ahead of it with barriers right across.",
     [delta("road_barrier", 2, 6), layout("line", "road_barrier", min_count=2),
      relative("in_front_of", "ego", 60, category="road_barrier", scope="added", require_all=True),
      in_lane("main_eastbound", category="road_barrier", scope="added", require_all=False),
      in_lane("main_westbound", category="road_barrier", scope="added", require_all=False), keep("road_barrier")],
     [arrange("road_barrier", "line", loc("ego", "in_front_of", distance=25), count=3)])
case("arrangement", "indirect", "same_in_lot_b", "team lead",
     "Do the same in lot B.",
     [delta(CARS, 3), layout("line", CARS, min_count=3),
      near("parking lot B", 1, category=CARS, scope="added", require_all=True), keep(*CARS)],
     [arrange("passenger_car", "parking_row", loc("parking lot B"), count=3)],
     setup=(turn("Park a row of three cars in lot A.",
                 [arrange("passenger_car", "parking_row", loc("parking lot A"), count=3)]),))
case("arrangement", "indirect", "lamps_to_jtekt", "QA tester",
     "The sidewalk outside the JTEKT entrance is pitch black at night. It needs a row of lamps.",
     [delta("street_light", 2, 6), layout("line", "street_light", min_count=2),
      near("JTEKT building entrance", 20, category="street_light", scope="added", require_all=True),
      keep("street_light")],
     [arrange("street_light", "line", loc("JTEKT building entrance", "on_sidewalk"), count=3)])
case("arrangement", "indirect", "robot_slalom_lot_a", "ADAS student",
     "I'm setting up a slalom for the robot: a straight line of cones down the middle of lot A, about 4 m apart.",
     [delta("traffic_cone", 4, 12), layout("line", "traffic_cone", min_count=4, spacing_min=3.5, spacing_max=4.5),
      near("parking lot A", 1, category="traffic_cone", scope="added", require_all=True), keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("parking lot A"), count=6, spacing=4)])
impossible("arrangement", "indirect", "ring_150m_radius", "researcher",
           "For a long-range radar sweep I need cones in a circle 150 m out from the crossroads.",
           [arrange("traffic_cone", "ring", loc("main intersection"), count=40, radius=150)],
           "a ring's radius is at most 60 m, and the map is only 180 m across")

# vague ---------------------------------------------------------------------------------------
case("arrangement", "vague", "cones_line_lot_b_entrance", "newcomer",
     "put some cones in a line near the lot B entrance i guess",
     [delta("traffic_cone", 3, 8), layout("line", "traffic_cone"),
      near("parking lot B entrance", 10, category="traffic_cone", scope="added", require_all=True),
      keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("parking lot B entrance"), count=5)])
case("arrangement", "vague", "people_circle_fountain", "team lead",
     "maybe a small circle of people round the fountain?",
     [delta("pedestrian", 3, 10), layout("ring", "pedestrian", around="fountain"), keep("pedestrian")],
     [arrange("pedestrian", "ring", loc("fountain"), count=6, radius=4)])
case("arrangement", "vague", "few_cars_lined_up", "QA tester",
     "line up a few cars somewhere in lot A",
     [delta(CARS, 2, 5), layout("line", CARS, min_count=2),
      near("parking lot A", 1, category=CARS, scope="added", require_all=True), keep(*CARS)],
     [arrange("passenger_car", "parking_row", loc("parking lot A"), count=3)])
case("arrangement", "vague", "barriers_round_it", "simulation engineer",
     "then some barriers around it, roughly",
     [delta("road_barrier", 3, 12), layout("ring", "road_barrier", around="cement_rubble_1"), keep("road_barrier")],
     [arrange("road_barrier", "ring", loc("cement_rubble_1"), count=6)],
     setup=(turn("Put a pile of rubble in the middle of the crossroads.",
                 [add("cement_rubble", where=loc("main intersection"))], planned=True),))
case("arrangement", "vague", "bins_bunch_union", "researcher",
     "Could you put a bunch of bins together near the Student Union, like 5ish?",
     [delta("trash_bin", 4, 6), layout("cluster", "trash_bin", min_count=4, tolerance=4),
      near("Student Union entrance", 15, category="trash_bin", scope="added", require_all=True), keep("trash_bin")],
     [arrange("trash_bin", "grid", loc("Student Union entrance"), count=5)])
case("arrangement", "vague", "signs_along_eastbound", "ADAS student",
     "a few roadworks signs lined up along the eastbound lane past the junction would be good",
     [delta("construction_sign", 2, 6), layout("line", "construction_sign", min_count=2),
      near("main_eastbound", 4, category="construction_sign", scope="added", require_all=True),
      near_xy(50.0, -1.75, 41, category="construction_sign", scope="added", require_all=True),
      keep("construction_sign")],
     [arrange("construction_sign", "lane_edge", loc("main_eastbound", "in_lane", distance=30), count=3)])
case("arrangement", "vague", "slalom_lot_b", "simulation engineer",
     "Set up a slalom-type line of cones for the robot in lot B, whatever spacing",
     [delta("traffic_cone", 4, 12), layout("line", "traffic_cone", min_count=4),
      near("parking lot B", 1, category="traffic_cone", scope="added", require_all=True), keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("parking lot B"), count=6, spacing=3)])
case("arrangement", "vague", "benches_along_stop", "newcomer",
     "maybe a few benches in a row along the sidewalk by the bus stop?",
     [delta("bench", 2, 5), layout("line", "bench", min_count=2),
      near("bus stop", 12, category="bench", scope="added", require_all=True), keep("bench")],
     [arrange("bench", "line", loc("bus stop", "on_sidewalk"), count=3)])

# erroneous -----------------------------------------------------------------------------------
case("arrangement", "erroneous", "lien_cones_westbound", "QA tester",
     "put a lien of 4 cones acros the westbound lane near the east gate",
     [delta("traffic_cone", 4), layout("line", "traffic_cone", min_count=4),
      in_lane("main_westbound", category="traffic_cone", scope="added"),
      near("east gate", 15, category="traffic_cone", scope="added", require_all=True), keep("traffic_cone")],
     [arrange("traffic_cone", "line", xy(90.0, 1.75), count=4, heading_deg=90, spacing=0.9)])
case("arrangement", "erroneous", "arange_benchs_circel", "newcomer",
     "arange 5 benchs in a circel around the fountain",
     [delta("bench", 5), layout("ring", "bench", around="fountain", min_count=5), keep("bench")],
     [arrange("bench", "ring", loc("fountain"), count=5, radius=4)])
case("arrangement", "erroneous", "row_of_cras", "simulation engineer",
     "park a row of 3 cras in lot b",
     [delta(CARS, 3), layout("line", CARS, min_count=3),
      near("parking lot B", 1, category=CARS, scope="added", require_all=True), keep(*CARS)],
     [arrange("passenger_car", "parking_row", loc("parking lot B"), count=3)])
case("arrangement", "erroneous", "grid_cones_teh_middle", "researcher",
     "make a 3x3 grid of cones in teh middle of lot A",
     [delta("traffic_cone", 9), layout("cluster", "traffic_cone", min_count=9, tolerance=6),
      near_xy(-85.0, 29.0, 8, category="traffic_cone", scope="added", require_all=True), keep("traffic_cone")],
     [arrange("traffic_cone", "grid", loc("parking lot A"), count=9, columns=3)])
case("arrangement", "erroneous", "eastbond_every_5m", "team lead",
     "line the eastbond lane with cones every 5 m, like 8 of them",
     [delta("traffic_cone", 8), layout("line", "traffic_cone", min_count=8, spacing_min=4.5, spacing_max=5.5),
      in_lane("main_eastbound", category="traffic_cone", scope="added"), keep("traffic_cone")],
     [arrange("traffic_cone", "lane_edge", loc("main_eastbound", "in_lane"), count=8, spacing=5)])
case("arrangement", "erroneous", "barriers_accross_lot_a", "ADAS student",
     "put barriers accross the lot A entrence to close it",
     [delta("road_barrier", 2, 6), layout("line", "road_barrier", min_count=2),
      near("parking lot A entrance", 8, category="road_barrier", scope="added", require_all=True),
      keep("road_barrier")],
     [arrange("road_barrier", "line", xy(-85.0, 10.0), count=3, heading_deg=0, spacing=2.1)])
case("arrangement", "erroneous", "ring_pedestirans_bench", "QA tester",
     "make a ring of 6 pedestirans around the bench",
     [delta("pedestrian", 6), layout("ring", "pedestrian", around="bench_1", min_count=6), keep("pedestrian")],
     [arrange("pedestrian", "ring", loc("bench_1"), count=6)])
case("arrangement", "erroneous", "same_thign_lot_b", "simulation engineer",
     "same thign at the lot b entrance pls",
     [delta("traffic_cone", 5), layout("line", "traffic_cone", min_count=5),
      near("parking lot B entrance", 10, category="traffic_cone", scope="added", require_all=True),
      keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("parking lot B entrance"), count=5)],
     setup=(turn("Put a line of five cones across the lot A entrance.",
                 [arrange("traffic_cone", "line", loc("parking lot A entrance"), count=5)]),))
impossible("arrangement", "erroneous", "row_12_busses", "newcomer",
           "put a row of 12 busses in lot B",
           [arrange("bus", "parking_row", loc("parking lot B"), count=12)], "a scene holds at most 10 buses")

# =============================================================================================
# appearance: colours and materials of assets, and the time, weather and lights of the scene
# =============================================================================================

# direct --------------------------------------------------------------------------------------
case("appearance", "direct", "suv_red", "QA tester",
     "Paint the SUV red.",
     [looks("red", asset="suv_1"), keep(assets=["suv_1"])],
     [paint("suv_1", colour="red")])
case("appearance", "direct", "half_ten_lights_on", "simulation engineer",
     "Set the time to 22:30 and turn the street lights on.",
     [at_time("22:30", street_lights="on"), keep(environment=True)],
     [clock("22:30"), lighting(street_lights="on")], tags=("compound",))
case("appearance", "direct", "heavy_snow", "researcher",
     "Make it snow heavily.",
     [env(weather=["snow"], intensity_min=0.75, time_from="12:00", time_to="12:00"), keep(environment=True)],
     [weather("snow", 0.9)])
case("appearance", "direct", "headlights_on", "team lead",
     "Turn the vehicle headlights on.",
     [env(vehicle_lights="on", street_lights="auto"), keep(environment=True)],
     [lighting(vehicle_lights="on")])
case("appearance", "direct", "sedans_white_suv_black", "ADAS student",
     "Make both sedans in lot B white and the SUV black.",
     [looks("white", asset="passenger_car_1"), looks("white", asset="passenger_car_2"), looks("black", asset="suv_1"),
      keep(assets=LOT_B_CARS)],
     [paint(*LOT_B_SEDANS, colour="white"), paint("suv_1", colour="black")], tags=("compound",))
case("appearance", "direct", "bench_wood", "newcomer",
     "Give the bench a wooden finish.",
     [looks(material="wood", asset="bench_1"), keep(assets=["bench_1"])],
     [paint("bench_1", material="wood")])
case("appearance", "direct", "fog_at_dusk", "simulation engineer",
     "Make it foggy and set the time to dusk.",
     [env(weather=["fog"], time_from="18:30", time_to="21:00"), keep(environment=True)],
     [weather("fog"), clock("dusk")], tags=("compound",))
case("appearance", "direct", "light_rain", "researcher",
     "Set light rain.",
     [env(weather=["rain"], intensity_min=0.05, intensity_max=0.45), keep(environment=True)],
     [weather("rain", 0.3)])
impossible("appearance", "direct", "crosswalk_stripes_yellow", "QA tester",
           "Paint the crosswalk stripes yellow.",
           [paint("west crosswalk", colour="yellow")], "road markings are part of the map, not assets")

# indirect ------------------------------------------------------------------------------------
case("appearance", "indirect", "properly_dark", "simulation engineer",
     "The next test is a night drive, so I need it properly dark outside.",
     [env(night=True, weather=["clear"]), keep(environment=True)],
     [clock("night")])
case("appearance", "indirect", "ego_stands_out", "QA tester",
     "The ego blends into the road in the top-down renders. Give it a colour that really stands out.",
     [looks(BRIGHT, asset="ego"), keep(assets=["ego"])],
     [paint("ego", colour="orange")])
case("appearance", "indirect", "low_sun_glare", "researcher",
     "My glare study needs the sun low in the sky, just after sunrise.",
     [env(time_from="06:00", time_to="08:00"), keep(environment=True)],
     [clock("sunrise")])
case("appearance", "indirect", "pouring_for_wipers", "ADAS student",
     "I'm testing wipers and wet-road braking, so it should be pouring.",
     [env(weather=["rain"], intensity_min=0.75), keep(environment=True)],
     [weather("rain", 0.9)])
case("appearance", "indirect", "lot_b_company_blue", "team lead",
     "Marketing wants every car in lot B in our company blue.",
     [looks(["blue", "navy"], category=CARS, scope="all", require_all=True, min_count=3), keep(*CARS)],
     [paint(*LOT_B_CARS, colour="blue")])
case("appearance", "indirect", "cones_stand_out", "QA tester",
     "The cones disappear against the asphalt in the camera images, they need to stand out more.",
     [looks([c for c in BRIGHT if c not in ("orange", "gold")] + ["white"], category="traffic_cone", scope="all",
            require_all=True, min_count=5), keep("traffic_cone")],
     [paint(category="traffic_cone", colour="yellow")],
     setup=(turn("Put five cones across the westbound lane near the east gate.",
                 [arrange("traffic_cone", "line", xy(90.0, 1.75), count=5, heading_deg=90, spacing=0.8)]),))
case("appearance", "indirect", "reflection_test", "newcomer",
     "We're testing headlight reflections on wet paint, so the cars need their lights on.",
     [env(vehicle_lights="on"), keep(environment=True)],
     [lighting(vehicle_lights="on")])
case("appearance", "indirect", "renders_blown_out", "simulation engineer",
     "The renders are blown out, everything's far too bright. Tone it down.",
     [env(exposure_min=0.1, exposure_max=0.9, time_from="12:00", time_to="12:00"), keep(environment=True)],
     [lighting(exposure=0.6)])
impossible("appearance", "indirect", "double_rainbow", "team lead",
           "The demo needs a double rainbow over the campus after the rain.",
           [weather("rainbow")], "weather can be clear, cloudy, rain, fog or snow; there is no rainbow")

# vague ---------------------------------------------------------------------------------------
case("appearance", "vague", "evening_ish", "newcomer",
     "make it kinda evening-ish",
     [env(time_from="17:00", time_to="22:00", weather=["clear"]), keep(environment=True)],
     [clock("evening")])
case("appearance", "vague", "bit_of_rain", "researcher",
     "add some weather, like a bit of rain maybe",
     [env(weather=["rain"], intensity_min=0.05, intensity_max=0.6), keep(environment=True)],
     [weather("rain", 0.3)])
case("appearance", "vague", "bench_darker", "QA tester",
     "could the bench be a darker colour, I don't mind which",
     [looks(["#1a1a1a", "maroon"], tolerance=0.3, asset="bench_1"), keep(assets=["bench_1"])],
     [paint("bench_1", colour="black")])
case("appearance", "vague", "bit_gloomy", "simulation engineer",
     "make it look a bit gloomy",
     [keep(environment=True)],
     [weather("cloudy", 0.6)],
     alternatives=([env(weather=["cloudy", "fog", "rain"])], [env(exposure_max=0.9)],
                   [env(time_from="17:30", time_to="21:30")]))
case("appearance", "vague", "night_and_lamps", "team lead",
     "it should be night with the lamps on, whatever time works",
     [env(night=True), keep(environment=True)],
     [clock("night"), lighting(street_lights="on")],
     tags=("compound",), alternatives=([env(street_lights="on")], [env(street_lights="auto")]))
case("appearance", "vague", "trucks_bright_yellow", "QA tester",
     "make them some bright colour, yellow maybe",
     [looks("yellow", category="truck", scope="all", require_all=True, min_count=2), keep("truck")],
     [paint(category="truck", colour="yellow")],
     setup=(turn("Add two trucks in lot A.", [add("truck", 2, loc("parking lot A"))], planned=True),))
case("appearance", "vague", "ease_off_fog", "researcher",
     "the fog's a bit much, ease off it a little",
     [env(weather=["fog"], intensity_min=0.2, intensity_max=0.8), keep(environment=True)],
     [weather("fog", 0.5)],
     setup=(turn("Make it really foggy.", [weather("fog", 0.95)]),))
case("appearance", "vague", "suv_shiny", "ADAS student",
     "maybe make the SUV look kind of shiny?",
     [keep(assets=["suv_1"])],
     [paint("suv_1", material="glossy")],
     alternatives=([looks(material="glossy", asset="suv_1")], [looks(material="metal", asset="suv_1")]))
case("appearance", "vague", "cloudy_afternoon", "newcomer",
     "something like a cloudy afternoon would be nice",
     [env(weather=["cloudy"], time_from="13:00", time_to="17:30"), keep(environment=True)],
     [weather("cloudy"), clock("afternoon")], tags=("compound",))

# erroneous -----------------------------------------------------------------------------------
case("appearance", "erroneous", "pain_suv_red", "QA tester",
     "pain the suv red",
     [looks("red", asset="suv_1"), keep(assets=["suv_1"])],
     [paint("suv_1", colour="red")])
case("appearance", "erroneous", "time_too_9pm", "simulation engineer",
     "set time too 9pm",
     [at_time("21:00"), keep(environment=True)],
     [clock("21:00")])
case("appearance", "erroneous", "make_it_snwo", "researcher",
     "make it snwo",
     [env(weather=["snow"]), keep(environment=True)],
     [weather("snow")])
case("appearance", "erroneous", "headlihgts_on", "team lead",
     "turn on the headlihgts on all the cars",
     [env(vehicle_lights="on"), keep(environment=True)],
     [lighting(vehicle_lights="on")])
case("appearance", "erroneous", "paitn_bench_green", "newcomer",
     "paitn the bench green",
     [looks("green", asset="bench_1"), keep(assets=["bench_1"])],
     [paint("bench_1", colour="green")])
case("appearance", "erroneous", "cones_yelow", "ADAS student",
     "make the cones yelow",
     [looks("yellow", category="traffic_cone", scope="all", require_all=True, min_count=4), keep("traffic_cone")],
     [paint(category="traffic_cone", colour="yellow")],
     setup=(turn("Put four cones at the lot B entrance.", [add("traffic_cone", 4, loc("parking lot B entrance"))]),))
case("appearance", "erroneous", "heavy_rian_nigth", "simulation engineer",
     "heavy rian at nigth please",
     [env(weather=["rain"], intensity_min=0.75, night=True), keep(environment=True)],
     [weather("rain", 0.9), clock("night")], tags=("compound",))
case("appearance", "erroneous", "lot_b_cars_sliver", "team lead",
     "make all cars in lot b sliver",
     [looks("silver", category=CARS, scope="all", require_all=True, min_count=3), keep(*CARS)],
     [paint(*LOT_B_CARS, colour="silver")])
impossible("appearance", "erroneous", "pant_road_red", "QA tester",
           "pant the road surface red at the crossroads",
           [paint("main intersection", colour="red")], "the road surface is part of the map, not an asset")

# ---------------------------------------------------------------------------------------------

ALL_CASES: list[Json] = [json.loads(json.dumps(c)) for c in CASES]


def main() -> None:
    SUITE_PATH.parent.mkdir(parents=True, exist_ok=True)
    text = "".join(json.dumps(c, ensure_ascii=False) + "\n" for c in ALL_CASES)
    SUITE_PATH.write_text(text, encoding="utf-8")
    print(f"wrote {len(ALL_CASES)} cases to {SUITE_PATH}")


if __name__ == "__main__":
    main()
