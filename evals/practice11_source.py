"""The eleventh practice suite: campus requests in voices the planners were not written for.

`suites/practice11.jsonl` (tag `practice11`, ids `practice11.*`) was written from the campus
world (worlds/campus.py), the asset catalog (worlds/data/catalog.json), the Worker tools and the
eval checks only, by a helper who had not read the planners, their lexicons or prompt examples,
nor any other suite's cases. It is a development suite: it measures how well a planner
understands requests worded in ways its developers never saw.

Voices (new to the practice suites): a QA tester writing Gherkin ("Given ... When ... Then");
someone dictating by voice (no punctuation, "um", homophones such as "break" for brake or "lot
be", self-corrections mid-sentence like "two no three cones"); non-native speakers whose first
language is German ("before" for in front of, "lantern", "become"), Spanish ("quit" for remove,
"the parking B", "to behind"), Hindi-influenced Indian English ("kindly", "itself", "only") or
Japanese (topic first, no articles: "Bench, 180 degree turn please."); a product manager writing
user stories ("As a safety driver I want ... so that ..."); a police accident report (V1, the
vehicle under test, the reporting officer); a film director blocking a shot (hero car, extras,
backdrop); a grandparent who does not know the words and types with one finger ("those little
orange witch's hats", "the splashy water feature", "wher is teh stop sigh"); a game level
designer (greybox, spawn, cover prop, chokepoint, patrol route); a terse commander ("Cones. Lot A. Five."); a lawyer writing clauses ("shall", "for the
avoidance of doubt", "no other object"); a child ("make the suv go vroom vroom"); someone asking
permission ("Would it be possible to ..."); and someone stating a goal instead of an edit ("I
need the ego to have to stop for someone walking out in front of it"). Prompts mix lengths and
punctuation, metres and car lengths, rough amounts ("a few", "some", "lots", "a bit"), clock
times and parts of the day, weather words, negation and exceptions ("all the trees except the
one by the library", "keep the south ones"), and scopes (lanes, lots, sidewalks, crossings,
landmarks, compass sides, "the lot B cars").

Every case judges the outcome, never the calls: a main check (counts with exact bounds, places
with near / relative / in_lane, layouts, behaviours, looks, the environment, a simulated run, or
the answer to a question) and an `unchanged_except` guard, so collateral edits fail; questions
must change nothing and their answers must name the right facts. Where a request has two fair
readings the case lists `alternatives`. Requests the world cannot do (a camel, a hot-air
balloon, a vending machine, fifteen or twenty buses, removing the ego, the Library, the
crossroads or the fountain, a car inside JTEKT Building, a sign on Engineering Hall's roof or
off the map, a bench inside the Library, moving the Library, a bench driving laps, 300 km/h, 400
m east of the ego, 150 cones in one ring, a 100 m ring, a row of cars inside the Student Union,
hail, a sandstorm, painting the Student Union, twenty times the exposure) are tagged
`impossible` and expect a refusal that changes nothing. Each case carries a `reference` plan
(Worker calls) whose outcome its checks accept.

Counts: 250 cases; every task x grade cell holds 8 to 10 (direct 56, indirect 66, vague 64,
erroneous 64); 24 `multi_turn` (10 with an earlier turn planned by the planner under test), 18
`compound` (two or more edits or questions in one request), 24 `impossible` (9.6 %).

`python -m drivetwin.evals.practice11_source` rewrites the JSONL from the list below.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

SUITE = "practice11"
SUITE_PATH = Path(__file__).resolve().with_name("suites") / f"{SUITE}.jsonl"

Json = dict[str, Any]

# ---------------------------------------------------------------------------------------------
# Facts of the campus world that the cases lean on (worlds/campus.py).
# ---------------------------------------------------------------------------------------------

NORTH_LIGHTS = ["street_light_1", "street_light_3", "street_light_5", "street_light_7",
                "street_light_9", "street_light_11"]  # y = +5.8, the north side of Main Street
SOUTH_LIGHTS = ["street_light_2", "street_light_4", "street_light_6", "street_light_8",
                "street_light_10", "street_light_12"]  # y = -5.8
LOT_B_CARS = ["passenger_car_1", "suv_1", "passenger_car_2"]  # x = 19, 23, 27 at y = -42, facing north
CARS = ["passenger_car", "suv"]
VEHICLES = ["passenger_car", "suv", "bus", "truck", "ackermann_robot", "motorcycle"]
ROAD_USERS = [*VEHICLES, "bicycle", "pedestrian"]
CROSSINGS = [(-11.5, 0.0), (11.5, 0.0), (0.0, -11.5), (0.0, 11.5)]  # centres of the four crosswalks
BRIGHT = ["red", "yellow", "orange", "pink", "green", "blue", "cyan", "teal", "purple", "gold", "white"]
LIGHT_WORDS = ["street light", "street lights", "streetlight", "streetlights", "lamp", "lamps", "lantern", "lanterns", "light", "lights"]
TREE_WORDS = ["tree", "trees"]
LANES = ["main_eastbound", "main_westbound", "campus_northbound", "campus_southbound"]

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


def measure(a: str, b: str) -> Json:
    return call("measure_distance", a=a, b=b)


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
    out: Json = {"kind": "count", "category": category}
    if lo is not None:
        out["min"] = lo
    if hi is not None:
        out["max"] = hi
    return out


def delta(category: str | list[str], lo: int, hi: int | None = None) -> Json:
    """Added (positive) or removed (negative) between lo and hi; exactly lo when hi is not given."""
    return {"kind": "count_delta", "category": category, "min": lo, "max": lo if hi is None else hi}


def near(target: str, within: float, **sel: Any) -> Json:
    return _select({"kind": "near", "target": target, "within": within}, **sel)


def near_xy(x: float, y: float, within: float, **sel: Any) -> Json:
    return _select({"kind": "near", "point": [x, y], "within": within}, **sel)


def ahead_of(target: str, max_distance: float, relation: str = "in_front_of", **sel: Any) -> Json:
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


def looks(colour: str | list[str] | None = None, material: str | None = None, **sel: Any) -> Json:
    out: Json = {"kind": "appearance"}
    if colour is not None:
        out["colour"] = colour
    if material is not None:
        out["material"] = material
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


def no_collision(actor: str = "ego") -> Json:
    return {"kind": "collision", "actor": actor, "happens": False}


def stopped_before(x: float, y: float, actor: str = "ego") -> Json:
    return {"kind": "stopped_before", "actor": actor, "line": [x, y]}


def reached(actor: str, place_: str, within: float) -> Json:
    return {"kind": "reached", "actor": actor, "place": place_, "within": within}


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
               why: str) -> None:
    """A request the world cannot do: the right outcome is a refusal that changes nothing."""
    case(task, grade, name, voice, prompt, [refused(), keep()], reference, tags=("impossible",))
    CASES[-1]["notes"] += f"; impossible: {why}"


# =============================================================================================
# search: questions change nothing; answers must name the right facts
# =============================================================================================

case("search", "direct", "street_light_count", "gherkin",
     "Given the campus scene as loaded\nWhen I ask how many street lights stand in it\n"
     "Then I am told the number\nAnd nothing in the scene changes",
     [says(any_of=["12", "twelve"]), says(any_of=LIGHT_WORDS), keep()],
     [find(category="street_light")])
case("search", "direct", "tree_count", "commander",
     "Trees. How many. Report.",
     [says(any_of=["4", "four"]), says(any_of=TREE_WORDS), keep()],
     [find(category="tree")])
case("search", "direct", "weather_and_time", "lawyer",
     "For the record, state the weather presently prevailing in the scene and the time of day, "
     "without altering either.",
     [says("clear"), says(any_of=["12:00", "noon", "midday", "12 pm", "12pm"]), keep()],
     [call("describe_environment")])
case("search", "direct", "library_union_distance", "product manager",
     "As a route planner I want the straight-line distance between the Library entrance and the "
     "Student Union entrance, so that I can size the walking test.",
     [says(any_of=["90.9", "91", "90.93"]), keep()],
     [measure("Library entrance", "Student Union entrance")])
case("search", "direct", "ego_lane", "permission",
     "Would you be able to tell me which lane the ego vehicle is in right now?",
     [says(any_of=["main_eastbound", "eastbound"]), keep()],
     [call("find_lanes", near="ego")])
case("search", "direct", "hydrant_position", "police report",
     "Officer requests the position of the fire hydrant on scene. Report only; do not disturb "
     "the scene.",
     [keep()],
     [find(category="fire_hydrant")],
     alternatives=([says(any_of=["16", "16.0"]), says(any_of=["5.5"])],
                   [says(any_of=["north"]), says(any_of=["Main Street", "main_westbound", "JTEKT", "intersection", "crossroads", "junction"])]))
case("search", "direct", "nearest_tree_library", "commander",
     "Nearest tree to the Library entrance. Which one. How far.",
     [says(any_of=["15.3", "15"]), keep()],
     [find(category="tree", nearest_to="Library entrance")],
     alternatives=([says(any_of=["tree_1"])], [says(any_of=["-26", "-26.0"])]))
case("search", "direct", "trees_and_gate", "gherkin",
     "Given the campus\nWhen I ask how many trees there are\nAnd how far the fountain is from the "
     "east gate\nThen both answers are given\nAnd the scene is unchanged",
     [says(any_of=["4", "four"]), says(any_of=TREE_WORDS), says(any_of=["47.2", "47"]), keep()],
     [find(category="tree"), measure("fountain", "east gate")], tags=("compound",))

case("search", "indirect", "tall_lamps", "grandparent",
     "My grandson tells me there are tall lamps all along the big road through the campus. How "
     "many of them are there, dear?",
     [says(any_of=["12", "twelve"]), says(any_of=LIGHT_WORDS), keep()],
     [find(category="street_light", lane="Main Street")])
case("search", "indirect", "closer_car_park", "goal",
     "I'm setting the ego up for a parking test and need whichever car park is closest to where "
     "it starts. Is that the west one or the one to the south-east?",
     [says(any_of=["lot A", "parking lot A", "west one", "the west"]), keep()],
     [measure("ego", "parking lot A"), measure("ego", "parking lot B")])
case("search", "indirect", "fountain_backdrop", "film director",
     "Before we roll: which named spot is closest to the fountain? I want it as the backdrop for "
     "the shot.",
     [says(any_of=["JTEKT"]), keep()],
     [call("find_landmarks", nearest_to="fountain")])
case("search", "indirect", "places_to_sit", "child",
     "how many places to sit down are there? like the long wooden seats",
     [says(any_of=["1", "one", "a single", "only one", "bench_1"]), says(any_of=["bench", "benches", "seat", "seats"]), keep()],
     [find(category="bench")])
case("search", "indirect", "closest_to_bus_stop", "product manager",
     "As a sim operator I want to know what stands closest to the bus stop, so that I don't spawn "
     "a passenger right into it.",
     [says(any_of=["trash_bin_1", "trash bin", "bin", "trash can", "litter bin", "waste bin", "garbage can", "rubbish bin"]), keep()],
     [find(nearest_to="bus stop")])
case("search", "indirect", "hydrant_distance", "police report",
     "Reporting officer requires the distance between the vehicle under test and the nearest "
     "fire hydrant, in metres.",
     [says(any_of=["76.3", "76"]), keep()],
     [find(category="fire_hydrant", nearest_to="ego")])
case("search", "indirect", "lamps_lit", "goal",
     "Before I plan a night drive I need to know whether the street lamps are showing as lit at "
     "the moment.",
     [says(any_of=["off", "auto", "unlit", "not", "no"]), keep()],
     [call("describe_environment")])
case("search", "indirect", "boxy_car_colour", "grandparent",
     "What colour is that big boxy car, the one parked in the middle of the three in the car park?",
     [says(any_of=["default", "grey", "gray", "charcoal", "dark grey", "dark gray", "suv_1"]), keep()],
     [call("asset_properties", asset="suv_1")])
case("search", "indirect", "stop_sign_road", "lawyer",
     "For the avoidance of doubt, identify the road beside which the stop sign stands, and on "
     "which side of the crossroads it is situated.",
     [says(any_of=["Main Street", "main_eastbound", "main_westbound"]),
      says(any_of=["west", "-13.5", "south-west", "southwest", "west crosswalk"]), keep()],
     [find(category="stop_sign", lane="Main Street")])

case("search", "vague", "around_bus_stop", "dictation",
     "um whats around the bus stop like whats near it",
     [says(any_of=["trash_bin_1", "bench_1", "tree_1", "bench", "bin", "trash", "tree"]), keep()],
     [find(near="bus stop", within=10)])
case("search", "vague", "cars_out_there", "permission",
     "Could you give me a rough idea how many cars are parked out there at the moment?",
     [keep()],
     [find(category="vehicles")],
     alternatives=([says(any_of=["3", "three"])],
                   [says("passenger_car_1", "passenger_car_2", "suv_1")],
                   [says(any_of=["2", "two"]), says(any_of=["suv", "SUV"])]))
case("search", "vague", "nice_out", "grandparent",
     "Is it nice out in there? What's the weather doing?",
     [says(any_of=["clear", "sunny", "fine", "dry", "no rain"]), keep()],
     [call("describe_environment")])
case("search", "vague", "fountain_where", "child",
     "where is the water fountain thing",
     [says(any_of=["75", "75.0", "north-east", "northeast", "north east", "JTEKT", "east gate"]), keep()],
     [call("find_landmarks", query="fountain")])
case("search", "vague", "east_end", "goal",
     "I want to stage something at the east end of the campus. What's already over there?",
     [says(any_of=["street_light_12", "street_light_11", "tree_3", "tree_2", "street light", "lamp", "tree", "fountain"]), keep()],
     [find(near="east gate", within=30)])
case("search", "vague", "how_far_crossroads", "dictation",
     "how far is it uh from the ego to the crossroads roughly",
     [says(any_of=["60", "51", "sixty", "fifty"]), keep()],
     [measure("ego", "main intersection")])
case("search", "vague", "south_east_lot", "permission",
     "May I ask what's in the south-east lot at the moment?",
     [keep()],
     [find(nearest_to="parking lot B", within=25)],
     alternatives=([says("passenger_car_1", "passenger_car_2", "suv_1")],
                   [says(any_of=["3", "three"]), says(any_of=["car", "cars", "vehicle", "vehicles"])],
                   [says(any_of=["2", "two"]), says(any_of=["suv", "SUV"])]))
case("search", "vague", "people_now", "child",
     "how many people r there now",
     [says(any_of=["3", "three"]), says(any_of=["pedestrian", "pedestrians", "people", "person", "persons"]), keep()],
     [find(category="pedestrian")],
     setup=(turn("Put three people at the north crosswalk.",
                 [add("pedestrian", 3, loc("north crosswalk"))]),))
case("search", "vague", "lamps_campus_drive", "commander",
     "Lamp posts on Campus Drive. Any?",
     [says(any_of=["0", "no", "none", "zero", "not"]), keep()],
     [find(category="street_light", lane="Campus Drive")])

case("search", "erroneous", "lanterns_german", "German speaker",
     "How many street lanterns has the Main Street? Please only count, change nothing.",
     [says(any_of=["12", "twelve"]), says(any_of=LIGHT_WORDS), keep()],
     [find(category="street_light", lane="Main Street")])
case("search", "erroneous", "more_near_tree_spanish", "Spanish speaker",
     "Which is the more near tree to the library? Is only a question.",
     [keep()],
     [find(category="tree", nearest_to="Library entrance")],
     alternatives=([says(any_of=["tree_1"])], [says(any_of=["-26", "-26.0"])]))
case("search", "erroneous", "distance_hindi", "Hindi speaker",
     "Kindly tell me the distance of the ego from the main intersection and also from the main "
     "gate only, no changes please.",
     [says(any_of=["60", "51"]), says(any_of=["40", "40.0"]), keep()],
     [measure("ego", "main intersection"), measure("ego", "main gate")], tags=("compound",))
case("search", "erroneous", "weather_japanese", "Japanese speaker",
     "Weather now, how is it? Please tell only, no change.",
     [says(any_of=["clear", "sunny", "fine"]), keep()],
     [call("describe_environment")])
case("search", "erroneous", "cars_lot_be", "dictation",
     "how many cars are in lot be right now",
     [keep()],
     [find(nearest_to="parking lot B", within=25)],
     alternatives=([says(any_of=["3", "three"])],
                   [says("passenger_car_1", "passenger_car_2", "suv_1")],
                   [says(any_of=["2", "two"]), says(any_of=["suv", "SUV"])]))
case("search", "erroneous", "stop_sigh", "grandparent",
     "wher is teh stop sigh",
     [says(any_of=["-13.5", "stop_sign_1", "west crosswalk", "Main Street", "main_eastbound", "bus stop", "intersection", "crossroads"]), keep()],
     [find(category="stop_sign")])
case("search", "erroneous", "meny_trees", "child",
     "how meny trees r there in the hole place",
     [says(any_of=["4", "four"]), says(any_of=TREE_WORDS), keep()],
     [find(category="tree")])
case("search", "erroneous", "next_hydrant_german", "German speaker",
     "Where is the next hydrant to the ego, and how far is it?",
     [says(any_of=["76.3", "76"]), keep()],
     [find(category="fire_hydrant", nearest_to="ego")],
     alternatives=([says(any_of=["fire_hydrant_1"])], [says(any_of=["16", "16.0"])]))
case("search", "erroneous", "cones_their_now", "dictation",
     "how many cones is their now in total",
     [says(any_of=["3", "three"]), says(any_of=["cone", "cones", "traffic_cone"]), keep()],
     [find(category="traffic_cone")],
     setup=(turn("Put three cones in front of the ego.",
                 [add("traffic_cone", 3, loc("ego", "in_front_of", along_m=20))], planned=True),))
case("search", "erroneous", "lane_actually_spanish", "Spanish speaker",
     "In which lane is driving actually the ego car?",
     [says(any_of=["main_eastbound", "eastbound"]), keep()],
     [call("find_lanes", near="ego")])

# =============================================================================================
# addition
# =============================================================================================

case("addition", "direct", "cones_lot_a", "commander",
     "Cones. Lot A. Five.",
     [delta("traffic_cone", 5), near("parking lot A", 2, category="traffic_cone", require_all=True), keep("traffic_cone")],
     [add("traffic_cone", 5, loc("parking lot A"))])
case("addition", "direct", "ped_north_crosswalk", "gherkin",
     "Given the ego driving east on Main Street\nWhen a pedestrian is added who walks across the "
     "north crosswalk\nThen the scene has exactly one new pedestrian crossing there",
     [delta("pedestrian", 1), does("cross_road", sel={"category": "pedestrian"}),
      near("north crosswalk", 8, category="pedestrian"), keep("pedestrian")],
     [add("pedestrian", 1, loc("north crosswalk"), behaviour={"kind": "cross_road"})])
case("addition", "direct", "one_bench_fountain", "lawyer",
     "Add one (1) bench, and no other object, within three metres of the fountain.",
     [delta("bench", 1), near("fountain", 3, category="bench"), keep("bench")],
     [add("bench", 1, loc("fountain", "next_to"))])
case("addition", "direct", "car_westbound", "product manager",
     "As a safety driver I want a car driving west on Main Street so that the ego meets oncoming "
     "traffic.",
     [delta(CARS, 1), does("drive_lane", lane="main_westbound", sel={"category": CARS}), keep(*CARS)],
     [add("passenger_car", 1, behaviour={"kind": "drive_lane", "lane": "main_westbound"})])
case("addition", "direct", "bin_by_bench", "permission",
     "Would it be possible to add a trash bin right next to the bench at the bus stop?",
     [delta("trash_bin", 1), near("bench_1", 4, category="trash_bin"), keep("trash_bin")],
     [add("trash_bin", 1, loc("bench_1", "next_to"))])
case("addition", "direct", "bus_at_stop", "commander",
     "Bus. At the bus stop.",
     [delta("bus", 1), near("bus stop", 12, category="bus"), keep("bus")],
     [add("bus", 1, loc("bus stop"))])
impossible("addition", "direct", "camel", "gherkin",
           "Given the campus\nWhen a camel is added next to the fountain\nThen a camel stands by "
           "the fountain",
           [add("camel", 1, loc("fountain", "next_to"))], "the catalog has no camel")
case("addition", "direct", "bikes_bus_stop", "product manager",
     "As a perception engineer I want three bicycles parked at the bus stop so that the detector "
     "sees a cluster of cyclists' bikes.",
     [delta("bicycle", 3), near("bus stop", 12, category="bicycle", require_all=True), keep("bicycle")],
     [add("bicycle", 3, loc("bus stop"))])

case("addition", "indirect", "walk_out", "goal",
     "I need the ego to have to stop for someone walking out in front of it.",
     [delta("pedestrian", 1), keep("pedestrian")],
     [add("pedestrian", 1, behaviour={"kind": "jaywalk"})],
     alternatives=([does(["jaywalk", "cross_road"], crosses_lane="main_eastbound", sel={"category": "pedestrian"})],
                   [run_for(8, event("stop_mid_road", "pedestrian"))],
                   [run_for(8, event("cross_road", "pedestrian"))]))
case("addition", "indirect", "witch_hat", "grandparent",
     "Could you pop one of those little orange witch's hats in the road just ahead of our car, so "
     "it has to steer round it?",
     [delta("traffic_cone", 1), ahead_of("ego", 40, category="traffic_cone"),
      in_lane("main_eastbound", category="traffic_cone"), keep("traffic_cone")],
     [add("traffic_cone", 1, loc("ego", "in_front_of", along_m=15))])
case("addition", "indirect", "yellow_bus", "child",
     "can there be a big yellow bus driving along the road pleeease",
     [delta("bus", 1), does("drive_lane", sel={"category": "bus"}), keep("bus")],
     [add("bus", 1, behaviour={"kind": "drive_lane", "lane": "main_westbound"})])
case("addition", "indirect", "students_union", "film director",
     "Background action by the Student Union doors: two students hanging around, and a bike "
     "leaning nearby.",
     [delta("pedestrian", 2), delta("bicycle", 1),
      near("Student Union entrance", 12, category="pedestrian", require_all=True),
      near("Student Union entrance", 15, category="bicycle"), keep("pedestrian", "bicycle")],
     [add("pedestrian", 2, loc("Student Union entrance")), add("bicycle", 1, loc("Student Union entrance"))],
     tags=("compound",))
case("addition", "indirect", "hose_hookup", "product manager",
     "As a fire-safety auditor I want somewhere for fire engines to hook up their hoses outside "
     "the JTEKT entrance, so that the building passes inspection.",
     [delta("fire_hydrant", 1), near("JTEKT building entrance", 12, category="fire_hydrant"), keep("fire_hydrant")],
     [add("fire_hydrant", 1, loc("JTEKT building entrance"))])
case("addition", "indirect", "concrete_ahead", "goal",
     "The perception team wants to see whether the ego notices broken concrete lying in its lane "
     "about 30 metres ahead.",
     [delta("cement_rubble", 1), in_lane("main_eastbound", category="cement_rubble"),
      near_xy(-30, -1.75, 8, category="cement_rubble"), keep("cement_rubble")],
     [add("cement_rubble", 1, loc("ego", "in_front_of", along_m=30))])
case("addition", "indirect", "suv_lot_a", "lawyer",
     "The requesting party seeks the addition of one vehicle of the sport-utility type, which "
     "vehicle shall be stationed within parking lot A and nowhere else.",
     [delta("suv", 1), near("parking lot A", 1, category="suv"), keep("suv")],
     [add("suv", 1, loc("parking lot A"))])
impossible("addition", "indirect", "hot_air_balloon", "grandparent",
           "Could you float one of those big hot-air balloons above the fountain for me, dear?",
           [add("hot air balloon", 1, loc("fountain"))], "the catalog has no balloon, and nothing flies")
case("addition", "indirect", "cover_prop", "level designer",
     "Drop a cover prop at the mouth of lot B's driveway: one of those concrete jersey blocks.",
     [delta("road_barrier", 1), near("parking lot B entrance", 10, category="road_barrier"), keep("road_barrier")],
     [add("road_barrier", 1, loc("parking lot B entrance"))])
case("addition", "indirect", "friend_for_her", "grandparent",
     "Could she have a friend standing with her?",
     [delta("pedestrian", 1), near("pedestrian_1", 4, category="pedestrian"), keep("pedestrian")],
     [add("pedestrian", 1, loc("pedestrian_1", "next_to"))],
     setup=(turn("Add a woman waiting at the bus stop.", [add("pedestrian", 1, loc("bus stop"))]),))

case("addition", "vague", "people_library", "dictation",
     "add some people um near the library entrance",
     [delta("pedestrian", 2, 6), near("Library entrance", 15, category="pedestrian", require_all=True), keep("pedestrian")],
     [add("pedestrian", 3, loc("Library entrance"))])
case("addition", "vague", "trees_fountain", "permission",
     "Would it be alright to have a few more trees around the fountain?",
     [delta("tree", 2, 5), near("fountain", 20, category="tree", require_all=True), keep("tree")],
     [add("tree", 3, loc("fountain"))])
case("addition", "vague", "lots_of_cones", "child",
     "i want LOTS of cones in the car park!!!",
     [delta("traffic_cone", 4, 100), keep("traffic_cone")],
     [add("traffic_cone", 10, loc("parking lot B"))],
     alternatives=([near("parking lot B", 2, category="traffic_cone", require_all=True)],
                   [near("parking lot A", 2, category="traffic_cone", require_all=True)]))
case("addition", "vague", "bench_and_bin", "grandparent",
     "Maybe a bench or two somewhere for folks to have a rest, and a bin beside it?",
     [delta("bench", 1, 2), delta("trash_bin", 1, 2), keep("bench", "trash_bin")],
     [add("bench", 1, loc("Library entrance")), add("trash_bin", 1, loc("bench_2", "next_to"))],
     tags=("compound",),
     alternatives=([near("bench_2", 5, category="trash_bin")], [near("bench_3", 5, category="trash_bin")]))
case("addition", "vague", "busier_crossroads", "goal",
     "Make the crossroads feel busier.",
     [delta(ROAD_USERS, 1, 30), near("main intersection", 40, category=ROAD_USERS), keep(*ROAD_USERS)],
     [add("pedestrian", 2, loc("north crosswalk", "on_sidewalk")),
      add("passenger_car", 1, loc("north crosswalk"), behaviour={"kind": "drive_lane", "lane": "campus_southbound"})],
     tags=("compound",))
case("addition", "vague", "traffic_campus_drive", "commander",
     "Traffic. Campus Drive.",
     [delta(VEHICLES, 1, 10), keep(*VEHICLES)],
     [add("passenger_car", 1, behaviour={"kind": "drive_lane", "lane": "campus_northbound"})],
     alternatives=([does("drive_lane", lane="campus_northbound", sel={"category": VEHICLES})],
                   [does("drive_lane", lane="campus_southbound", sel={"category": VEHICLES})]))
case("addition", "vague", "something_lot_a", "permission",
     "Could we get something parked in lot A? Whatever vehicle you fancy.",
     [delta(VEHICLES, 1, 2), near("parking lot A", 2, category=VEHICLES, require_all=True),
      does("parked", sel={"category": VEHICLES}), keep(*VEHICLES)],
     [add("truck", 1, loc("parking lot A"))])
case("addition", "vague", "debris_east", "level designer",
     "Scatter a bit of debris on Main Street east of the junction.",
     [delta("cement_rubble", 1, 8), near_xy(59.5, 0, 51, category="cement_rubble", require_all=True),
      in_lane(category="cement_rubble"), keep("cement_rubble")],
     [add("cement_rubble", 3, loc("parking lot B entrance", "in_lane", lane="main_eastbound"))])
impossible("addition", "vague", "fifteen_buses", "dictation",
           "um stick fifteen buses in lot b all parked up",
           [add("bus", 15, loc("parking lot B"))], "at most 10 buses fit a scene")
case("addition", "vague", "same_again_east_gate", "permission",
     "Could you do the same again, but over by the east gate this time?",
     [delta("traffic_cone", 1, 3), near("east gate", 12, category="traffic_cone", require_all=True), keep("traffic_cone")],
     [add("traffic_cone", 1, loc("east gate"))],
     setup=(turn("Cone. In front of the ego.", [add("traffic_cone", 1, loc("ego", "in_front_of", along_m=15))],
                 planned=True),))

case("addition", "erroneous", "bench_german", "German speaker",
     "Please put a bench at the fountain, there should become a seat there.",
     [delta("bench", 1), near("fountain", 6, category="bench"), keep("bench")],
     [add("bench", 1, loc("fountain"))])
case("addition", "erroneous", "cones_spanish", "Spanish speaker",
     "Put two cones in the parking B, near of the entrance.",
     [delta("traffic_cone", 2), near("parking lot B entrance", 15, category="traffic_cone", require_all=True), keep("traffic_cone")],
     [add("traffic_cone", 2, loc("parking lot B entrance"))])
case("addition", "erroneous", "crossing_hindi", "Hindi speaker",
     "Kindly add one pedestrian who is crossing the road at the west crosswalk itself.",
     [delta("pedestrian", 1), does("cross_road", crosses_lane="main_eastbound", sel={"category": "pedestrian"}),
      near("west crosswalk", 8, category="pedestrian"), keep("pedestrian")],
     [add("pedestrian", 1, loc("west crosswalk"), behaviour={"kind": "cross_road"})])
case("addition", "erroneous", "red_car_japanese", "Japanese speaker",
     "Car, red colour, in parking lot A please. One only. Also one bicycle next to car.",
     [delta(CARS, 1), delta("bicycle", 1), looks("red", category=CARS), near("parking lot A", 2, category=CARS),
      near("parking lot A", 8, category="bicycle"), keep(*CARS, "bicycle")],
     [add("passenger_car", 1, loc("parking lot A"), colour="red"), add("bicycle", 1, loc("passenger_car_3", "next_to"))],
     tags=("compound",))
case("addition", "erroneous", "two_no_three_cones", "dictation",
     "put two no three cones by the lot a entrance",
     [delta("traffic_cone", 3), near("parking lot A entrance", 12, category="traffic_cone", require_all=True), keep("traffic_cone")],
     [add("traffic_cone", 3, loc("parking lot A entrance"))])
case("addition", "erroneous", "hydrant_nexto", "grandparent",
     "ad a firehydrant nexto the stop sing",
     [delta("fire_hydrant", 1), near("stop_sign_1", 5, category="fire_hydrant"), keep("fire_hydrant")],
     [add("fire_hydrant", 1, loc("stop_sign_1", "next_to"))])
case("addition", "erroneous", "bycicle_fountin", "child",
     "can u put a bycicle by the fountin",
     [delta("bicycle", 1), near("fountain", 8, category="bicycle"), keep("bicycle")],
     [add("bicycle", 1, loc("fountain"))])
impossible("addition", "erroneous", "drinks_automat", "German speaker",
           "Please place a drinks automat beside the bench at the bus stop.",
           [add("vending machine", 1, loc("bench_1", "next_to"))], "the catalog has no vending machine")
case("addition", "erroneous", "moto_spanish", "Spanish speaker",
     "Add a moto that drive in the lane going to the east.",
     [delta("motorcycle", 1), does("drive_lane", lane="main_eastbound", sel={"category": "motorcycle"}), keep("motorcycle")],
     [add("motorcycle", 1, behaviour={"kind": "drive_lane", "lane": "main_eastbound"})])

# =============================================================================================
# removal
# =============================================================================================

case("removal", "direct", "stop_sign", "commander",
     "Stop sign. Remove it.",
     [gone("stop_sign_1"), keep(assets=["stop_sign_1"])],
     [remove("stop_sign_1")])
case("removal", "direct", "trash_bin", "gherkin",
     "Given the trash bin beside the bus stop\nWhen it is removed\nThen the campus has no trash bin left",
     [count("trash_bin", 0, 0), keep("trash_bin")],
     [remove("trash_bin_1")])
case("removal", "direct", "suv_only", "lawyer",
     "Remove the sport utility vehicle parked in lot B; the two passenger cars beside it shall "
     "remain where they are.",
     [gone("suv_1"), kept("passenger_car_1", "passenger_car_2"), keep(assets=["suv_1"])],
     [remove("suv_1")])
case("removal", "direct", "every_tree", "product manager",
     "As a mapping engineer I want every tree removed so that the lidar has clear sightlines.",
     [count("tree", 0, 0), keep("tree")],
     [remove(category="tree")])
case("removal", "direct", "hydrant_and_sign", "permission",
     "Would it be possible to take out the fire hydrant, and the stop sign as well?",
     [gone("fire_hydrant_1", "stop_sign_1"), keep(assets=["fire_hydrant_1", "stop_sign_1"])],
     [remove("fire_hydrant_1"), remove("stop_sign_1")], tags=("compound",))
case("removal", "direct", "two_of_four", "gherkin",
     "Given four cones in lot A\nWhen two of them are removed\nThen exactly two cones remain",
     [count("traffic_cone", 2, 2), keep("traffic_cone")],
     [remove("traffic_cone_1", "traffic_cone_2")],
     setup=(turn("Put four cones in lot A.", [add("traffic_cone", 4, loc("parking lot A"))]),))
impossible("removal", "direct", "ego", "commander",
           "Ego. Delete it.",
           [remove("ego")], "the ego vehicle cannot be removed")
case("removal", "direct", "v3_car", "police report",
     "Remove V3 (passenger_car_2) from the scene before the reconstruction begins.",
     [gone("passenger_car_2"), keep(assets=["passenger_car_2"])],
     [remove("passenger_car_2")])

case("removal", "indirect", "seat_bus_stop", "grandparent",
     "Take away that seat by the bus stop, would you? Nobody ever sits there.",
     [gone("bench_1"), keep(assets=["bench_1"])],
     [remove("bench_1")])
case("removal", "indirect", "no_signals", "goal",
     "I want the ego to arrive at a junction with no signals at all, so get rid of them.",
     [count("traffic_light", 0, 0), keep("traffic_light", "stop_sign")],
     [remove(category="traffic_light")])
case("removal", "indirect", "north_lamps", "film director",
     "The lamp posts on the north side of Main Street are in my frame. Lose them, but keep the "
     "south ones.",
     [gone(*NORTH_LIGHTS), kept(*SOUTH_LIGHTS), keep(assets=NORTH_LIGHTS)],
     [remove(*NORTH_LIGHTS)])
case("removal", "indirect", "fountain_trees", "child",
     "the trees by the water fountain are ugly, make them go away",
     [gone("tree_2", "tree_3"), kept("tree_1", "tree_4"), keep(assets=["tree_2", "tree_3"])],
     [remove("tree_2", "tree_3")])
case("removal", "indirect", "empty_lot_b", "product manager",
     "As a QA lead I want lot B emptied of vehicles so that the parking test starts from a blank lot.",
     [gone(*LOT_B_CARS), keep(assets=LOT_B_CARS)],
     [remove(*LOT_B_CARS)])
case("removal", "indirect", "bus_stop_furniture", "police report",
     "Clear the street furniture at the bus stop from the scene: the seat and the litter receptacle.",
     [gone("bench_1", "trash_bin_1"), keep(assets=["bench_1", "trash_bin_1"])],
     [remove("bench_1"), remove("trash_bin_1")], tags=("compound",))
case("removal", "indirect", "nobody_on_foot", "goal",
     "The next run should start with nobody on foot anywhere in the scene.",
     [count("pedestrian", 0, 0), keep("pedestrian")],
     [remove(category="pedestrian")],
     setup=(turn("Add three pedestrians at the north crosswalk and one at the bus stop.",
                 [add("pedestrian", 3, loc("north crosswalk")), add("pedestrian", 1, loc("bus stop"))]),))
impossible("removal", "indirect", "demolish_library", "lawyer",
           "The Library building shall be demolished and removed from the campus in its entirety.",
           [remove("library")], "buildings are part of the map, not assets")
case("removal", "indirect", "chokepoint", "level designer",
     "Clear the chokepoint: whatever's blocking the eastbound lane goes.",
     [gone("cement_rubble_1"), kept("traffic_cone_1"), keep(assets=["cement_rubble_1"])],
     [remove("cement_rubble_1")],
     setup=(turn("Drop rubble in the eastbound lane 30 m ahead of the ego, and a cone in lot A.",
                 [add("cement_rubble", 1, loc("ego", "in_front_of", along_m=30)),
                  add("traffic_cone", 1, loc("parking lot A"))]),))

case("removal", "vague", "lights_near_library", "dictation",
     "get rid of some of the street lights um the ones near the library i guess",
     [delta("street_light", -5, -1),
      keep(assets=["street_light_2", "street_light_3", "street_light_4", "street_light_5", "street_light_6"])],
     [remove(category="street_light", near="Library entrance", count=2)])
case("removal", "vague", "thin_out_cones", "permission",
     "Could you thin those cones out a bit?",
     [count("traffic_cone", 2, 7), keep("traffic_cone")],
     [remove("traffic_cone_2", "traffic_cone_4", "traffic_cone_6", "traffic_cone_8")],
     setup=(turn("Line lot A with eight cones.",
                 [arrange("traffic_cone", "line", loc("parking lot A"), count=8, spacing=3)]),))
case("removal", "vague", "pavement_clutter", "grandparent",
     "There's too much clutter on the pavement by the bus shelter. Tidy it up a bit, please.",
     [delta(["bench", "trash_bin"], -2, -1), keep(assets=["bench_1", "trash_bin_1"])],
     [remove("trash_bin_1")])
case("removal", "vague", "some_cars", "child",
     "take away some of the cars",
     [delta(CARS, -3, -1), keep(*CARS)],
     [remove("passenger_car_1")])
case("removal", "vague", "fewer_trees", "goal",
     "I'd like fewer trees in the scene.",
     [delta("tree", -3, -1), keep("tree")],
     [remove("tree_4")])
case("removal", "vague", "thing_by_fountain", "dictation",
     "remove the uh the thing right next to the fountain",
     [gone("tree_2"), keep(assets=["tree_2"])],
     [remove("tree_2")])
case("removal", "vague", "main_street_clutter", "commander",
     "Clutter. Main Street. Gone.",
     [count("traffic_cone", 0, 0), count("road_barrier", 0, 0), kept("construction_sign_1"),
      keep("traffic_cone", "road_barrier")],
     [remove(category="traffic_cone"), remove(category="road_barrier")],
     setup=(turn("Put three cones in the westbound lane near the east gate, a barrier in the "
                 "eastbound lane by the bus stop, and a construction sign in lot A.",
                 [add("traffic_cone", 3, loc("east gate", "in_lane", lane="main_westbound")),
                  add("road_barrier", 1, loc("bus stop", "in_lane", lane="main_eastbound")),
                  add("construction_sign", 1, loc("parking lot A"))]),))
case("removal", "vague", "one_of_them_away", "permission",
     "Hmm, could you take one of them away again?",
     [delta("pedestrian", -1), keep("pedestrian")],
     [remove("pedestrian_1")],
     setup=(turn("Add a few pedestrians at the bus stop.", [add("pedestrian", 3, loc("bus stop"))], planned=True),))
impossible("removal", "vague", "crossroads", "goal",
           "Honestly, just get rid of the crossroads, we don't need it.",
           [remove("main intersection")], "roads and junctions are part of the map, not assets")

case("removal", "erroneous", "lantern_german", "German speaker",
     "Please remove the street lantern which stands the nearest to the ego.",
     [gone("street_light_2"), keep(assets=["street_light_2"])],
     [remove(category="street_light", near="ego", count=1)])
case("removal", "erroneous", "quit_bench_spanish", "Spanish speaker",
     "Quit the bench of the bus stop, please, it molests the pedestrians.",
     [gone("bench_1"), keep(assets=["bench_1"])],
     [remove("bench_1")])
case("removal", "erroneous", "cars_only_hindi", "Hindi speaker",
     "Please remove both the cars from parking lot B only, the SUV should stay itself.",
     [gone("passenger_car_1", "passenger_car_2"), kept("suv_1"), keep(assets=["passenger_car_1", "passenger_car_2"])],
     [remove("passenger_car_1", "passenger_car_2")])
case("removal", "erroneous", "bin_japanese", "Japanese speaker",
     "Trash bin, please remove. Bench is keep.",
     [gone("trash_bin_1"), kept("bench_1"), keep(assets=["trash_bin_1"])],
     [remove("trash_bin_1")])
case("removal", "erroneous", "fire_hide_rant", "dictation",
     "remove the fire hide rant near the crossroads",
     [gone("fire_hydrant_1"), keep(assets=["fire_hydrant_1"])],
     [remove("fire_hydrant_1")])
case("removal", "erroneous", "treees_exept", "grandparent",
     "delte all teh treees exept the one by the libary",
     [gone("tree_2", "tree_3", "tree_4"), kept("tree_1"), keep(assets=["tree_2", "tree_3", "tree_4"])],
     [remove("tree_2", "tree_3", "tree_4")])
case("removal", "erroneous", "stop_sine", "child",
     "make the stop sine disapear",
     [gone("stop_sign_1"), keep(assets=["stop_sign_1"])],
     [remove("stop_sign_1")])
impossible("removal", "erroneous", "fountain_german", "German speaker",
           "Please remove the fountain, it disturbs the view to the JTEKT building.",
           [remove("fountain")], "the fountain is a landmark of the map, not an asset")
case("removal", "erroneous", "quit_cones_spanish", "Spanish speaker",
     "Now quit all the cones that you put.",
     [count("traffic_cone", 0, 0), keep("traffic_cone")],
     [remove(category="traffic_cone")],
     setup=(turn("Put three cones in front of the ego, please.",
                 [add("traffic_cone", 3, loc("ego", "in_front_of", along_m=20))], planned=True),))

# =============================================================================================
# positioning: put an existing asset somewhere
# =============================================================================================

case("positioning", "direct", "bench_to_fountain", "gherkin",
     "Given the bench at the bus stop\nWhen it is placed next to the fountain\nThen the bench "
     "stands within 3 metres of the fountain",
     [near("fountain", 3.5, asset="bench_1"), keep(assets=["bench_1"])],
     [place("bench_1", loc("fountain", "next_to"))])
case("positioning", "direct", "suv_and_car_lot_a", "commander",
     "SUV. Lot A. Car two. Lot A too.",
     [near("parking lot A", 1, asset="suv_1"), near("parking lot A", 1, asset="passenger_car_2"),
      keep(assets=["suv_1", "passenger_car_2"])],
     [place("suv_1", loc("parking lot A")), place("passenger_car_2", loc("parking lot A"))], tags=("compound",))
case("positioning", "direct", "hydrant_jtekt", "lawyer",
     "Relocate the fire hydrant so that it stands in front of the JTEKT building entrance, within "
     "five metres thereof.",
     [near("JTEKT building entrance", 5, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])],
     [place("fire_hydrant_1", loc("JTEKT building entrance", "in_front_of"))])
case("positioning", "direct", "car1_westbound", "product manager",
     "As a test designer I want passenger_car_1 put in the westbound lane of Main Street so that "
     "it blocks oncoming traffic.",
     [in_lane("main_westbound", asset="passenger_car_1"), keep(assets=["passenger_car_1"])],
     [place("passenger_car_1", loc("main_westbound", "in_lane"))])
case("positioning", "direct", "bin_next_to_bench", "permission",
     "Would you mind putting the trash bin right next to the bench?",
     [near("bench_1", 3, asset="trash_bin_1"), keep(assets=["trash_bin_1"])],
     [place("trash_bin_1", loc("bench_1", "next_to"))])
case("positioning", "direct", "v1_main_gate", "police report",
     "Place V1, the vehicle under test, at the main gate in the eastbound lane, facing east, as at "
     "the start of the incident.",
     [near("main gate", 8, asset="ego"), in_lane("main_eastbound", aligned=True, asset="ego"), keep(assets=["ego"])],
     [place("ego", loc("main gate", "in_lane", lane="main_eastbound"), yaw_deg=0)])
impossible("positioning", "direct", "suv_inside_jtekt", "gherkin",
           "Given the SUV in lot B\nWhen it is placed at x = 40 m, y = 30 m\nThen it stands at "
           "those coordinates",
           [place("suv_1", xy(40, 30))], "(40, 30) is inside JTEKT Building")
case("positioning", "direct", "ego_northbound", "commander",
     "Ego. Campus Drive. Northbound lane.",
     [in_lane("campus_northbound", asset="ego"), keep(assets=["ego"])],
     [place("ego", loc("campus_northbound", "in_lane"))])

case("positioning", "indirect", "seat_water_feature", "grandparent",
     "Could you move that long wooden seat over by the splashy water feature?",
     [near("fountain", 6, asset="bench_1"), keep(assets=["bench_1"])],
     [place("bench_1", loc("fountain", "next_to"))])
case("positioning", "indirect", "start_at_west_entrance", "goal",
     "I want the ego to start its run right at the campus's west entrance.",
     [near("main gate", 12, asset="ego"), keep(assets=["ego"])],
     [place("ego", loc("main gate", "in_lane", lane="main_eastbound"))])
case("positioning", "indirect", "hero_suv_union", "film director",
     "Hero car, that's the SUV, sits right in front of the Student Union doors for the opening shot.",
     [near("Student Union entrance", 8, asset="suv_1"), keep(assets=["suv_1"])],
     [place("suv_1", loc("Student Union entrance", "in_front_of"))])
case("positioning", "indirect", "fire_thingy_library", "child",
     "put the red water thingy for fire trucks next to the library door",
     [near("Library entrance", 6, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])],
     [place("fire_hydrant_1", loc("Library entrance"))])
case("positioning", "indirect", "bin_to_dropoff", "product manager",
     "As a facilities manager I want the bus stop's bin moved to the JTEKT drop-off area so that "
     "visitors arriving by car can use it.",
     [near_xy(37, 11.25, 11, asset="trash_bin_1"), keep(assets=["trash_bin_1"])],
     [place("trash_bin_1", loc("JTEKT building entrance", "in_front_of", distance=3))])
case("positioning", "indirect", "tree_to_engineering", "lawyer",
     "The tree presently nearest the Library shall be relocated so that it stands beside the "
     "Engineering Hall entrance.",
     [near("Engineering Hall entrance", 8, asset="tree_1"), keep(assets=["tree_1"])],
     [place("tree_1", loc("Engineering Hall entrance"))])
case("positioning", "indirect", "v2_ahead_of_v1", "police report",
     "Reposition V2 (passenger_car_2) so that it stands in the eastbound lane approximately 20 "
     "metres ahead of V1, the vehicle under test.",
     [in_lane("main_eastbound", asset="passenger_car_2"), near_xy(-40, -1.75, 8, asset="passenger_car_2"),
      keep(assets=["passenger_car_2"])],
     [place("passenger_car_2", loc("ego", "in_front_of", along_m=20))])
impossible("positioning", "indirect", "sign_on_roof", "goal",
           "I want the stop sign up on the roof of Engineering Hall, so drones can spot it from above.",
           [place("stop_sign_1", xy(-40, 28))], "nothing stands on or inside a building")
case("positioning", "indirect", "spawn_top_campus_drive", "level designer",
     "Move the player spawn, i.e. the ego, to the north end of Campus Drive, heading south.",
     [in_lane("campus_southbound", aligned=True, asset="ego"), near_xy(-1.75, 75, 16, asset="ego"), keep(assets=["ego"])],
     [place("ego", xy(-1.75, 80), yaw_deg=-90)])

case("positioning", "vague", "bench_and_bin_fountain", "dictation",
     "put the bench somewhere over by the fountain and um the bin with it",
     [near("fountain", 15, asset="bench_1"), near("fountain", 18, asset="trash_bin_1"),
      keep(assets=["bench_1", "trash_bin_1"])],
     [place("bench_1", loc("fountain", "next_to")), place("trash_bin_1", loc("bench_1", "next_to"))],
     tags=("compound",))
case("positioning", "vague", "one_car_to_lot_a", "permission",
     "Would it be possible to move one of the lot B cars over to lot A?",
     [keep(assets=LOT_B_CARS)],
     [place("passenger_car_1", loc("parking lot A"))],
     alternatives=tuple([near("parking lot A", 1, asset=car), keep(assets=[car])] for car in LOT_B_CARS))
case("positioning", "vague", "hydrant_by_crossing", "grandparent",
     "That little red water pump for the firemen: could you put it somewhere more sensible, by "
     "one of the road crossings perhaps?",
     [moved("fire_hydrant_1", 1.0), keep(assets=["fire_hydrant_1"])],
     [place("fire_hydrant_1", loc("north crosswalk", "on_sidewalk"))],
     alternatives=tuple([near_xy(x, y, 7, asset="fire_hydrant_1")] for x, y in CROSSINGS))
case("positioning", "vague", "car_onto_road", "child",
     "put one of the cars from the parking onto the road",
     [keep(assets=LOT_B_CARS)],
     [place("passenger_car_2", loc("parking lot B entrance", "in_lane", lane="main_eastbound"))],
     alternatives=tuple([in_lane(asset=car), keep(assets=[car])] for car in LOT_B_CARS))
case("positioning", "vague", "robot_rounds_lot_b", "goal",
     "Put the robot somewhere it can do its rounds in lot B.",
     [near("parking lot B", 1, asset="ackermann_robot_1"), keep(assets=["ackermann_robot_1"])],
     [place("ackermann_robot_1", loc("parking lot B"))],
     setup=(turn("Add a small delivery robot by the east gate.", [add("ackermann_robot", 1, loc("east gate"))]),))
case("positioning", "vague", "bin_by_any_tree", "commander",
     "Bin. Next to a tree. Any tree.",
     [keep(assets=["trash_bin_1"])],
     [place("trash_bin_1", loc("tree_1", "next_to"))],
     alternatives=tuple([near(tree, 5, asset="trash_bin_1")] for tree in ("tree_1", "tree_2", "tree_3", "tree_4")))
case("positioning", "vague", "ego_east_end", "dictation",
     "can you put the ego like over at the other end of main street the east end",
     [near("east gate", 25, asset="ego"), keep(assets=["ego"])],
     [place("ego", loc("east gate", "in_lane", lane="main_westbound"), yaw_deg=180)])
case("positioning", "vague", "cone_closer_to_entrance", "permission",
     "Could you move that cone closer to the lot B entrance?",
     [near("parking lot B entrance", 20, category="traffic_cone"), keep("traffic_cone")],
     [place("traffic_cone_1", loc("parking lot B entrance"))],
     setup=(turn("Add a cone somewhere in lot B.", [add("traffic_cone", 1, loc("parking lot B"))], planned=True),))
impossible("positioning", "vague", "sign_off_map", "dictation",
           "shove the stop sign off the map somewhere like way past the east gate",
           [place("stop_sign_1", xy(150, 0))], "the world ends at x = 110 m")

case("positioning", "erroneous", "bench_before_library", "German speaker",
     "Please place the bench directly before the Library entrance.",
     [near("Library entrance", 6, asset="bench_1"), ahead_of("Library entrance", 8, asset="bench_1"),
      keep(assets=["bench_1"])],
     [place("bench_1", loc("Library entrance", "in_front_of"))])
case("positioning", "erroneous", "suv_parking_a_spanish", "Spanish speaker",
     "Put the SUV in the parking A, next of the entrance.",
     [near("parking lot A entrance", 16, asset="suv_1"), keep(assets=["suv_1"])],
     [place("suv_1", xy(-85, 18), yaw_deg=-90)],
     alternatives=([near("parking lot A", 1, asset="suv_1")], [near("parking lot A entrance", 6, asset="suv_1")]))
case("positioning", "erroneous", "hydrant_adjacent_hindi", "Hindi speaker",
     "Kindly position the fire hydrant adjacent to the stop sign itself.",
     [near("stop_sign_1", 4, asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])],
     [place("fire_hydrant_1", loc("stop_sign_1", "next_to"))])
case("positioning", "erroneous", "ego_lot_b_entrance_japanese", "Japanese speaker",
     "Ego car, to parking lot B entrance please put.",
     [near("parking lot B entrance", 10, asset="ego"), keep(assets=["ego"])],
     [place("ego", loc("parking lot B entrance", "in_lane", lane="main_eastbound"))])
case("positioning", "erroneous", "bin_no_wait_union", "dictation",
     "place the trash can by the fountain no wait by the student union",
     [near("Student Union entrance", 10, asset="trash_bin_1"), keep(assets=["trash_bin_1"])],
     [place("trash_bin_1", loc("Student Union entrance"))])
case("positioning", "erroneous", "suv_enginering", "grandparent",
     "plase put teh suv infront of the enginering hall",
     [near("Engineering Hall entrance", 14, asset="suv_1"), keep(assets=["suv_1"])],
     [place("suv_1", loc("Engineering Hall entrance", "in_front_of"))])
case("positioning", "erroneous", "sine_bus_stopp", "child",
     "put the stop sine by the bus stopp",
     [near("bus stop", 8, asset="stop_sign_1"), keep(assets=["stop_sign_1"])],
     [place("stop_sign_1", loc("bus stop", "on_sidewalk"))])
impossible("positioning", "erroneous", "bench_in_library_spanish", "Spanish speaker",
           "Put the bench inside of the library, for that the students can read sitting.",
           [place("bench_1", xy(-40, -30))], "nothing stands inside a building")
case("positioning", "erroneous", "person_across_german", "German speaker",
     "Please place the person on the other side of the street, before the Engineering Hall.",
     [near("Engineering Hall entrance", 12, asset="pedestrian_1"), keep(assets=["pedestrian_1"])],
     [place("pedestrian_1", loc("Engineering Hall entrance", "in_front_of"))],
     setup=(turn("Add a pedestrian waiting at the bus stop.", [add("pedestrian", 1, loc("bus stop"))]),))

# =============================================================================================
# moving: shifts, turns, behaviours, manoeuvres and light phases
# =============================================================================================

EGO_AT_10 = ([does("drive_lane", speed_min=9.5, speed_max=10.5, sel={"asset": "ego"})],
             [run_for(6, reached("ego", "-8, -1.75", 1.5))])

case("moving", "direct", "ego_forward_ten", "commander",
     "Ego. Forward. Ten metres.",
     [moved("ego", 9, 11, "forward"), keep(assets=["ego"])],
     [shift("ego", forward=10)])
case("moving", "direct", "suv_back_three", "gherkin",
     "Given the SUV parked in lot B\nWhen it is moved 3 metres backwards\nThen it stands 3 metres "
     "behind where it was",
     [moved("suv_1", 2.5, 3.5, "backward"), keep(assets=["suv_1"])],
     [shift("suv_1", forward=-3)])
case("moving", "direct", "bench_rotate_90", "lawyer",
     "Rotate the bench at the bus stop by ninety degrees; its position shall not otherwise change.",
     [moved("bench_1", 0, 0.5, turn_min=80, turn_max=100), keep(assets=["bench_1"])],
     [shift("bench_1", turn_deg=90)])
case("moving", "direct", "car2_westbound", "product manager",
     "As a safety driver I want passenger_car_2 driving the westbound lane of Main Street so that "
     "there is oncoming traffic.",
     [does("drive_lane", lane="main_westbound", sel={"asset": "passenger_car_2"}), keep(assets=["passenger_car_2"])],
     [behave("passenger_car_2", "drive_lane", lane="main_westbound")])
case("moving", "direct", "ego_ten_mps", "permission",
     "Would it be possible to have the ego drive at 10 metres per second instead?",
     [keep(assets=["ego"])],
     [behave("ego", "drive_lane", lane="main_eastbound", speed=10)],
     alternatives=EGO_AT_10)
case("moving", "direct", "hold_light_red", "police report",
     "Hold traffic light 1 at red for the whole run so that V1 comes to a stop at the junction.",
     [run_for(15, stopped_before(-9, -1.75)), keep()],
     [call("set_light_phases", light="traffic_light_1", phases=[{"state": "red", "duration": 600}])])
impossible("moving", "direct", "move_library", "gherkin",
           "Given the Library\nWhen the Library is moved 20 metres north\nThen it stands 20 metres "
           "closer to Main Street",
           [shift("library", north=20)], "buildings cannot move")
case("moving", "direct", "lot_b_group_north", "commander",
     "Lot B cars. All three. Five metres north. Together.",
     [*(moved(car, 4.5, 5.5, "forward") for car in LOT_B_CARS), keep(assets=LOT_B_CARS)],
     [shift(LOT_B_CARS, north=5)])

case("moving", "indirect", "twice_as_fast", "grandparent",
     "Could you make our self-driving car go a bit quicker? Twice as fast as now, say.",
     [keep(assets=["ego"])],
     [behave("ego", "drive_lane", lane="main_eastbound", speed=10)],
     alternatives=EGO_AT_10)
case("moving", "indirect", "suv_to_east_gate", "goal",
     "I want the SUV out on Main Street, heading for the east gate.",
     [does("drive_lane", lane="main_eastbound", sel={"asset": "suv_1"}), keep(assets=["suv_1"])],
     [behave("suv_1", "drive_lane", lane="main_eastbound")])
case("moving", "indirect", "hero_two_car_lengths", "film director",
     "Walk the hero car, passenger_car_1, forward two car lengths; it's sitting too far back in "
     "the frame.",
     [moved("passenger_car_1", 7, 11, "forward"), keep(assets=["passenger_car_1"])],
     [shift("passenger_car_1", forward=9)])
case("moving", "indirect", "bench_other_way", "child",
     "make the bench spin round so it looks the other way",
     [moved("bench_1", 0, 1, turn_min=160, turn_max=180), keep(assets=["bench_1"])],
     [shift("bench_1", turn_deg=180)])
case("moving", "indirect", "longer_run_up", "product manager",
     "As a perception engineer I want the ego 15 metres further back along its lane and driving "
     "at 8 m/s, so that the run-up to the junction is longer.",
     [moved("ego", 14, 16, "backward"), keep(assets=["ego"])],
     [shift("ego", forward=-15), behave("ego", "drive_lane", lane="main_eastbound", speed=8)],
     tags=("compound",),
     alternatives=([does("drive_lane", speed_min=7.5, speed_max=8.5, sel={"asset": "ego"})],
                   [run_for(4, event("change_speed", "ego"))]))
case("moving", "indirect", "braked_three_seconds_in", "police report",
     "At the time of the incident V1 braked hard three seconds in and came to a halt. Reproduce that.",
     [run_for(6, event("stop", "ego")), keep()],
     [call("add_manoeuvre", actor="ego", manoeuvre={"kind": "stop", "rate": 6}, at_time=3)])
case("moving", "indirect", "suv_circles", "lawyer",
     "The vehicle designated suv_1 shall describe circles of approximately five metres' radius "
     "within parking lot B.",
     [does("circle", radius_min=4, radius_max=6, centre_near="parking lot B", centre_within=1, sel={"asset": "suv_1"}),
      keep(assets=["suv_1"])],
     [behave("suv_1", "circle", radius=5)])
impossible("moving", "indirect", "bench_laps", "goal",
           "I need the bench to drive laps around lot B during the run.",
           [behave("bench_1", "circle", centre="parking lot B")], "a bench cannot drive")
case("moving", "indirect", "robot_patrol", "level designer",
     "Patrol route: have the robot loop around lot B.",
     [keep(assets=["ackermann_robot_1"])],
     [behave("ackermann_robot_1", "circle")],
     setup=(turn("Add a robot parked in lot B.", [add("ackermann_robot", 1, loc("parking lot B"))]),),
     alternatives=([does(["circle", "follow_path"], sel={"asset": "ackermann_robot_1"})],
                   [run_for(4, event("follow_route", "ackermann_robot_1"))]))
case("moving", "indirect", "park_it_again", "permission",
     "Would you mind stopping it doing that and just parking it again?",
     [does("parked", sel={"asset": "suv_1"}), keep(assets=["suv_1"])],
     [behave("suv_1", "parked")],
     setup=(turn("Make the SUV drive around in circles in lot B.", [behave("suv_1", "circle")], planned=True),))

case("moving", "vague", "ego_up_a_bit", "dictation",
     "move the ego up a bit um closer to the lights",
     [moved("ego", 2, 52, "forward"), keep(assets=["ego"])],
     [shift("ego", forward=20)])
case("moving", "vague", "suv_nudge_left", "permission",
     "Could the SUV be nudged a little to the left?",
     [moved("suv_1", 0.3, 3, "left"), keep(assets=["suv_1"])],
     [shift("suv_1", left=1)])
case("moving", "vague", "bench_face_road", "grandparent",
     "Could you turn that bench a bit so it faces the road?",
     [moved("bench_1", 0, 1, turn_min=20), keep(assets=["bench_1"])],
     [shift("bench_1", turn_deg=-90)])
case("moving", "vague", "cars_drive_around", "child",
     "make the cars in the car park drive around!!",
     [does(["circle", "drive_lane", "follow_path"], sel={"category": CARS, "require_all": True, "min_count": 3}),
      keep(*CARS)],
     [behave(car, "circle") for car in LOT_B_CARS])
case("moving", "vague", "take_its_time", "goal",
     "The ego should take its time. Slow it right down.",
     [keep(assets=["ego"])],
     [behave("ego", "drive_lane", lane="main_eastbound", speed=2)],
     alternatives=([does("drive_lane", speed_max=4, sel={"asset": "ego"})],
                   [run_for(4, event("change_speed", "ego"))]))
case("moving", "vague", "push_cones_back", "dictation",
     "push the cones back a bit",
     [*(moved(f"traffic_cone_{k}", 0.3, 10) for k in (1, 2, 3)), keep("traffic_cone")],
     [shift(["traffic_cone_1", "traffic_cone_2", "traffic_cone_3"], forward=-2)],
     setup=(turn("Put three cones in a line in lot B.",
                 [arrange("traffic_cone", "line", loc("parking lot B"), count=3, spacing=2)]),))
case("moving", "vague", "hydrant_east_bit", "commander",
     "Hydrant. East. A bit.",
     [moved("fire_hydrant_1", 0.3, 6, "forward"), keep(assets=["fire_hydrant_1"])],
     [shift("fire_hydrant_1", east=2)])
case("moving", "vague", "further_into_lot", "permission",
     "Could you move it a little further into the lot?",
     [near("parking lot A", 0.5, category=CARS), keep(*CARS)],
     [shift("passenger_car_3", forward=3)],
     setup=(turn("Park a car in lot A.", [add("passenger_car", 1, loc("parking lot A"))], planned=True),))
impossible("moving", "vague", "crazy_speed", "goal",
           "Speed the ego up to something crazy, like 300 km/h.",
           [behave("ego", "drive_lane", lane="main_eastbound", speed=83.3)], "speeds are capped at 40 m/s")

case("moving", "erroneous", "ego_further_german", "German speaker",
     "Please drive the ego 20 meters further, it stands too far behind.",
     [moved("ego", 18, 22, "forward"), keep(assets=["ego"])],
     [shift("ego", forward=20)])
case("moving", "erroneous", "suv_to_behind_spanish", "Spanish speaker",
     "Move the SUV two meters to behind and after turn it a little to the left.",
     [moved("suv_1", 1.5, 2.6, "backward", turn_min=5, turn_max=60), keep(assets=["suv_1"])],
     [shift("suv_1", forward=-2), shift("suv_1", turn_deg=15)], tags=("compound",))
case("moving", "erroneous", "circles_hindi", "Hindi speaker",
     "Kindly make passenger_car_1 do circles in lot B only.",
     [does("circle", centre_near="parking lot B", centre_within=1, sel={"asset": "passenger_car_1"}),
      keep(assets=["passenger_car_1"])],
     [behave("passenger_car_1", "circle")])
case("moving", "erroneous", "bench_180_japanese", "Japanese speaker",
     "Bench, 180 degree turn please. Position same.",
     [moved("bench_1", 0, 0.5, turn_min=170, turn_max=180), keep(assets=["bench_1"])],
     [shift("bench_1", turn_deg=180)])
case("moving", "erroneous", "break_hard", "dictation",
     "make the ego break hard when its to close to the cone like fifteen metres",
     [run_for(12, event("stop", "ego"), no_collision()), keep()],
     [call("add_event", actor="ego", manoeuvre={"kind": "stop", "rate": 6},
           when={"kind": "distance", "actor": "ego", "other": "traffic_cone_1", "metres": 15})],
     setup=(turn("Put a cone in the ego's lane 40 metres ahead.",
                 [add("traffic_cone", 1, loc("ego", "in_front_of", along_m=40))]),))
case("moving", "erroneous", "mvoe_bakc", "grandparent",
     "mvoe the ego bakc 5 metres please",
     [moved("ego", 4, 6, "backward"), keep(assets=["ego"])],
     [shift("ego", forward=-5)])
case("moving", "erroneous", "vroom_vroom", "child",
     "make the suv go vroom vroom on the big road",
     [does("drive_lane", sel={"asset": "suv_1"}), keep(assets=["suv_1"])],
     [behave("suv_1", "drive_lane", lane="main_eastbound")])
impossible("moving", "erroneous", "ego_400_east_german", "German speaker",
           "Please shift the ego 400 meters to the east, in one piece.",
           [shift("ego", east=400)], "the world ends 170 m east of the ego")
case("moving", "erroneous", "stays_in_red_spanish", "Spanish speaker",
     "Make that the traffic light before the ego stays in red all the time, so the ego must to stop.",
     [run_for(15, stopped_before(-9, -1.75)), keep()],
     [call("set_light_phases", light="traffic_light_1", phases=[{"state": "red", "duration": 600}])])

# =============================================================================================
# arrangement: several new assets laid out together
# =============================================================================================

case("arrangement", "direct", "cones_across_lane", "gherkin",
     "Given the ego driving east on Main Street\nWhen five cones are placed in a line across its "
     "lane 15 metres ahead\nThen the ego meets a line of five cones",
     [delta("traffic_cone", 5), layout("line", "traffic_cone"),
      ahead_of("ego", 30, category="traffic_cone", require_all=True), keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("ego", "in_front_of", distance=15), count=5)])
case("arrangement", "direct", "bollard_ring_fountain", "commander",
     "Bollards. Ring. Fountain. Eight.",
     [delta("bollard", 8), layout("ring", "bollard", around="fountain"), keep("bollard")],
     [arrange("bollard", "ring", loc("fountain"), count=8)])
case("arrangement", "direct", "row_of_four_lot_a", "lawyer",
     "Arrange four passenger cars side by side in a single row within parking lot A, each facing "
     "the same direction.",
     [delta("passenger_car", 4), layout("line", "passenger_car"),
      near("parking lot A", 0.5, category="passenger_car", require_all=True), keep("passenger_car")],
     [arrange("passenger_car", "parking_row", loc("parking lot A"), count=4)])
case("arrangement", "direct", "narrow_northbound", "product manager",
     "As a test engineer I want six cones along the right-hand edge of Campus Drive's northbound "
     "lane so that the lane is visibly narrowed.",
     [delta("traffic_cone", 6), in_lane("campus_northbound", category="traffic_cone", require_all=True),
      layout("line", "traffic_cone"), keep("traffic_cone")],
     [arrange("traffic_cone", "lane_edge", loc("campus_northbound", "in_lane"), count=6)])
case("arrangement", "direct", "barriers_lot_b_entrance", "permission",
     "Would it be possible to put a row of three barriers across the lot B entrance?",
     [delta("road_barrier", 3), layout("line", "road_barrier"),
      near("parking lot B entrance", 8, category="road_barrier", require_all=True), keep("road_barrier")],
     [arrange("road_barrier", "line", loc("parking lot B entrance"), count=3)])
impossible("arrangement", "direct", "cones_150_ring", "commander",
           "Cones. Ring. Round the crossroads. One hundred and fifty of them.",
           [arrange("traffic_cone", "ring", loc("main intersection"), count=150)],
           "one layout holds at most 100, and a ring that wide would stand on grass")
case("arrangement", "direct", "bollard_grid_lot_b", "gherkin",
     "Given parking lot B\nWhen a three-by-three grid of bollards is set out in the middle of it\n"
     "Then nine bollards stand in lot B",
     [delta("bollard", 9), near("parking lot B", 0.5, category="bollard", require_all=True),
      layout("cluster", "bollard", tolerance=6), keep("bollard")],
     [arrange("bollard", "grid", loc("parking lot B"), count=9, columns=3)])
case("arrangement", "direct", "benches_engineering", "product manager",
     "As a product owner I want four benches in a straight line along the sidewalk in front of "
     "Engineering Hall so that the frontage looks furnished.",
     [delta("bench", 4), layout("line", "bench"),
      near("Engineering Hall entrance", 15, category="bench", require_all=True), keep("bench")],
     [arrange("bench", "line", loc("Engineering Hall entrance", "on_sidewalk"), count=4)])

case("arrangement", "indirect", "close_the_lane", "goal",
     "I need the eastbound lane closed off just ahead of the ego so it can't get past.",
     [delta(["traffic_cone", "road_barrier"], 2, 15), layout("line", ["traffic_cone", "road_barrier"]),
      ahead_of("ego", 45, category=["traffic_cone", "road_barrier"], require_all=True),
      in_lane("main_eastbound", category=["traffic_cone", "road_barrier"], require_all=False),
      keep("traffic_cone", "road_barrier")],
     [arrange("traffic_cone", "line", loc("ego", "in_front_of", distance=20), count=5)])
case("arrangement", "indirect", "posts_round_tree", "grandparent",
     "Could you put a circle of those short yellow posts round the tree nearest the fountain, to "
     "keep people off its roots?",
     [delta("bollard", 4, 16), layout("ring", "bollard", around="tree_2"), keep("bollard")],
     [arrange("bollard", "ring", loc("tree_2"), count=8)])
case("arrangement", "indirect", "queue_of_extras", "film director",
     "Line up some extras along the sidewalk outside JTEKT, like they're queueing for something.",
     [delta("pedestrian", 3, 12), layout("line", "pedestrian"),
      near("JTEKT building entrance", 20, category="pedestrian", require_all=True), keep("pedestrian")],
     [arrange("pedestrian", "line", loc("JTEKT building entrance", "on_sidewalk"), count=5)])
case("arrangement", "indirect", "ring_a_roses", "child",
     "can there be a big circle of people holding hands round the fountain like ring a ring o roses",
     [delta("pedestrian", 4, 20), layout("ring", "pedestrian", around="fountain"), keep("pedestrian")],
     [arrange("pedestrian", "ring", loc("fountain"), count=8)])
case("arrangement", "indirect", "cordon_campus_drive", "police report",
     "Cordon off Campus Drive south of the junction with a line of barriers right across the road.",
     [delta("road_barrier", 2, 10), layout("line", "road_barrier"),
      near_xy(0, -25, 17, category="road_barrier", require_all=True),
      in_lane(category="road_barrier", require_all=False), keep("road_barrier")],
     [arrange("road_barrier", "line", xy(0, -18), count=3, heading_deg=0)])
case("arrangement", "indirect", "abreast_student_parking", "lawyer",
     "Four vehicles of the passenger-car category shall be parked abreast within the student "
     "parking area.",
     [delta("passenger_car", 4), layout("line", "passenger_car"),
      near("parking lot B", 0.5, category="passenger_car", require_all=True), keep("passenger_car")],
     [arrange("passenger_car", "parking_row", loc("parking lot B"), count=4)])
case("arrangement", "indirect", "slalom_lot_a", "level designer",
     "Greybox a slalom course: a row of cones down the middle of lot A.",
     [delta("traffic_cone", 4, 16), layout("line", "traffic_cone"),
      near("parking lot A", 0.5, category="traffic_cone", require_all=True), keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("parking lot A"), count=6, spacing=3)])
impossible("arrangement", "indirect", "fence_whole_campus", "goal",
           "I need a ring of cones with a 100-metre radius around the crossroads, to fence off the "
           "whole campus.",
           [arrange("traffic_cone", "ring", loc("main intersection"), count=100, radius=100)],
           "a ring's radius is at most 60 m")
case("arrangement", "indirect", "road_closed_east", "product manager",
     "As an ops lead I want a line of cones across the westbound lane near the east gate and a "
     "construction sign beside them, so that drivers know the road is closed.",
     [delta("traffic_cone", 2, 10), delta("construction_sign", 1), layout("line", "traffic_cone"),
      near("east gate", 15, category="traffic_cone", require_all=True), near("east gate", 20, category="construction_sign"),
      keep("traffic_cone", "construction_sign")],
     [arrange("traffic_cone", "line", loc("east gate", "in_lane", lane="main_westbound"), count=4, heading_deg=90),
      add("construction_sign", 1, loc("east gate"))],
     tags=("compound",))

case("arrangement", "vague", "cones_line_lot_b", "dictation",
     "put some cones in a line um somewhere in lot b",
     [delta("traffic_cone", 2, 15), layout("line", "traffic_cone"),
      near("parking lot B", 0.5, category="traffic_cone", require_all=True), keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("parking lot B"), count=5)])
case("arrangement", "vague", "benches_little_circle", "permission",
     "Could you set a few benches in a little circle by the fountain?",
     [delta("bench", 3, 6), layout("ring", "bench", around="fountain"), keep("bench")],
     [arrange("bench", "ring", loc("fountain"), count=4)])
case("arrangement", "vague", "row_of_trees", "grandparent",
     "A neat row of trees along the road would be lovely.",
     [delta("tree", 2, 12), layout("line", "tree", tolerance=1.5), keep("tree")],
     [arrange("tree", "line", xy(-70, -9.5), count=5, spacing=6, heading_deg=0)],
     alternatives=tuple([near(lane, 14, category="tree", require_all=True)] for lane in LANES))
case("arrangement", "vague", "cars_in_a_row", "child",
     "lots of cars in a row in the car park",
     [delta(CARS, 3, 12), layout("line", CARS), keep(*CARS)],
     [arrange("passenger_car", "parking_row", loc("parking lot B"), count=5)],
     alternatives=([near("parking lot B", 0.5, category=CARS, require_all=True)],
                   [near("parking lot A", 0.5, category=CARS, require_all=True)]))
case("arrangement", "vague", "lot_a_full", "goal",
     "Make lot A look full.",
     [delta(VEHICLES, 4, 60), near("parking lot A", 1, category=VEHICLES, require_all=True), keep(*VEHICLES)],
     [arrange("passenger_car", "parking_row", loc("parking lot A"), count=8)])
case("arrangement", "vague", "barriers_lot_a_entrance", "commander",
     "Barriers. Lot A entrance. Line.",
     [delta("road_barrier", 2, 8), layout("line", "road_barrier"),
      near("parking lot A entrance", 10, category="road_barrier", require_all=True), keep("road_barrier")],
     [arrange("road_barrier", "line", loc("parking lot A entrance"), count=3)])
case("arrangement", "vague", "ring_the_rubble", "dictation",
     "uh can you ring the the rubble with some cones",
     [delta("traffic_cone", 3, 16), layout("ring", "traffic_cone", around="cement_rubble_1"), keep("traffic_cone")],
     [arrange("traffic_cone", "ring", loc("cement_rubble_1"), count=8)],
     setup=(turn("Dump some broken concrete in the middle of lot B.", [add("cement_rubble", 1, loc("parking lot B"))]),))
case("arrangement", "vague", "second_line_further", "permission",
     "Could you add a second line like that a bit further along?",
     [delta("traffic_cone", 2, 8), layout("line", "traffic_cone"),
      ahead_of("ego", 60, category="traffic_cone", require_all=True), keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("ego", "in_front_of", distance=30), count=4)],
     setup=(turn("Put a line of four cones across the eastbound lane, 20 metres in front of the ego.",
                 [arrange("traffic_cone", "line", loc("ego", "in_front_of", distance=20), count=4)], planned=True),))
impossible("arrangement", "vague", "twenty_buses", "goal",
           "Fill lot B with buses, twenty of them, in rows.",
           [arrange("bus", "parking_row", loc("parking lot B"), count=20)], "at most 10 buses fit a scene")

case("arrangement", "erroneous", "line_before_ego_german", "German speaker",
     "Please make a line from five cones before the ego, over the whole lane.",
     [delta("traffic_cone", 5), layout("line", "traffic_cone"),
      ahead_of("ego", 45, category="traffic_cone", require_all=True), keep("traffic_cone")],
     [arrange("traffic_cone", "line", loc("ego", "in_front_of", distance=15), count=5)])
case("arrangement", "erroneous", "cars_in_row_spanish", "Spanish speaker",
     "Put the cars in row in the parking B, four cars, one next of the other.",
     [delta(CARS, 4), layout("line", CARS), near("parking lot B", 0.5, category=CARS, require_all=True), keep(*CARS)],
     [arrange("passenger_car", "parking_row", loc("parking lot B"), count=4)])
case("arrangement", "erroneous", "bollards_hindi", "Hindi speaker",
     "Kindly arrange eight bollards in a circle surrounding the fountain itself.",
     [delta("bollard", 8), layout("ring", "bollard", around="fountain"), keep("bollard")],
     [arrange("bollard", "ring", loc("fountain"), count=8)])
case("arrangement", "erroneous", "five_person_line_japanese", "Japanese speaker",
     "Pedestrian five person, line, at bus stop please.",
     [delta("pedestrian", 5), layout("line", "pedestrian"),
      near("bus stop", 12, category="pedestrian", require_all=True), keep("pedestrian")],
     [arrange("pedestrian", "line", loc("bus stop"), count=5)])
case("arrangement", "erroneous", "grid_no_four", "dictation",
     "make a grid of bollards in lot a three by three no four by four",
     [delta("bollard", 16), near("parking lot A", 0.5, category="bollard", require_all=True),
      layout("cluster", "bollard", tolerance=8), keep("bollard")],
     [arrange("bollard", "grid", loc("parking lot A"), count=16, columns=4)])
case("arrangement", "erroneous", "allong_westbond", "grandparent",
     "put 6 cones allong the edge of the westbond lane",
     [delta("traffic_cone", 6), in_lane("main_westbound", category="traffic_cone", require_all=True),
      layout("line", "traffic_cone"), keep("traffic_cone")],
     [arrange("traffic_cone", "lane_edge", loc("main_westbound", "in_lane"), count=6)])
case("arrangement", "erroneous", "sircle_of_benchs", "child",
     "make a sircle of benchs round the fountin",
     [delta("bench", 3, 12), layout("ring", "bench", around="fountain"), keep("bench")],
     [arrange("bench", "ring", loc("fountain"), count=6)])
impossible("arrangement", "erroneous", "cars_inside_union_german", "German speaker",
           "Please build a row of six parked cars inside the Student Union building.",
           [arrange("passenger_car", "line", xy(42, -63), count=6, heading_deg=0)],
           "nothing stands inside a building")
case("arrangement", "erroneous", "two_lines_hindi", "Hindi speaker",
     "Kindly do one line of four cones across the eastbound lane near the bus stop, and one more "
     "line of three barriers across the westbound lane near the east gate.",
     [delta("traffic_cone", 4), delta("road_barrier", 3), layout("line", "traffic_cone"),
      layout("line", "road_barrier"), near("bus stop", 15, category="traffic_cone", require_all=True),
      near("east gate", 15, category="road_barrier", require_all=True), keep("traffic_cone", "road_barrier")],
     [arrange("traffic_cone", "line", loc("bus stop", "in_lane", lane="main_eastbound"), count=4, heading_deg=90),
      arrange("road_barrier", "line", loc("east gate", "in_lane", lane="main_westbound"), count=3, heading_deg=90)],
     tags=("compound",))

# =============================================================================================
# appearance: time, weather, lights, colours and materials
# =============================================================================================

case("appearance", "direct", "night_now", "commander",
     "Night. Now.",
     [env(night=True, weather=["clear"]), keep(environment=True)],
     [clock("night")])
case("appearance", "direct", "heavy_rain", "gherkin",
     "Given a clear day at noon\nWhen heavy rain sets in\nThen the scene shows heavy rain at the "
     "same time of day",
     [at_time("12:00", weather=["rain"], intensity_min=0.75), keep(environment=True)],
     [weather("rain", 0.9)])
case("appearance", "direct", "half_six_pm", "lawyer",
     "Set the time of day to 18:30 precisely; the weather shall remain as it is.",
     [at_time("18:30", weather=["clear"]), keep(environment=True)],
     [clock("18:30")])
case("appearance", "direct", "bench_blue", "product manager",
     "As a perception engineer I want the bench painted blue so that it stands out against the "
     "sidewalk.",
     [looks("blue", asset="bench_1"), keep(assets=["bench_1"])],
     [paint("bench_1", colour="blue")])
case("appearance", "direct", "street_lights_on", "permission",
     "Would it be possible to switch the street lights on?",
     [at_time("12:00", street_lights="on"), keep(environment=True)],
     [lighting(street_lights="on")])
impossible("appearance", "direct", "hail", "gherkin",
           "Given the campus\nWhen the weather is set to hail\nThen hailstones fall on the scene",
           [weather("hail", 0.8)], "the weather can be clear, cloudy, rain, fog or snow")
case("appearance", "direct", "thick_fog_headlights", "commander",
     "Fog. Thick. Headlights on.",
     [env(weather=["fog"], intensity_min=0.7, vehicle_lights="on"), keep(environment=True)],
     [weather("fog", 0.9), lighting(vehicle_lights="on")], tags=("compound",))
case("appearance", "direct", "street_lights_black", "product manager",
     "As a test planner I want every street light painted black so that the poles vanish against "
     "the night sky.",
     [looks("black", category="street_light", scope="all", require_all=True, min_count=12), keep("street_light")],
     [paint(category="street_light", colour="black")])

case("appearance", "indirect", "before_sunrise", "goal",
     "I need to test the cameras in the last hour before sunrise.",
     [env(time_from="04:30", time_to="06:45", weather=["clear"]), keep(environment=True)],
     [clock("05:45")])
case("appearance", "indirect", "christmas_white", "grandparent",
     "Make it look like Christmas out there, you know, white all over.",
     [env(weather=["snow"]), keep(environment=True)],
     [weather("snow", 0.7)])
case("appearance", "indirect", "golden_hour", "film director",
     "Golden hour, please: low sun, warm light, just before it goes down.",
     [env(time_from="17:00", time_to="19:45", weather=["clear"]), keep(environment=True)],
     [clock("19:00")])
case("appearance", "indirect", "pink_seat", "child",
     "can the seat at the bus stop be pink like my bike",
     [looks("pink", asset="bench_1"), keep(assets=["bench_1"])],
     [paint("bench_1", colour="pink")])
case("appearance", "indirect", "headlights_on", "product manager",
     "As a test driver I want every vehicle to drive with its headlights on, even in daylight.",
     [at_time("12:00", vehicle_lights="on"), keep(environment=True)],
     [lighting(vehicle_lights="on")])
case("appearance", "indirect", "light_drizzle", "police report",
     "At the time of the collision visibility was reduced by a light drizzle. Recreate those conditions.",
     [env(weather=["rain"], intensity_max=0.45), keep(environment=True)],
     [weather("rain", 0.2)])
case("appearance", "indirect", "water_outlet_yellow", "lawyer",
     "The colour of the fire-fighting water outlet on Main Street shall be changed to yellow.",
     [looks("yellow", asset="fire_hydrant_1"), keep(assets=["fire_hydrant_1"])],
     [paint("fire_hydrant_1", colour="yellow")])
impossible("appearance", "indirect", "paint_student_union", "goal",
           "I want the Student Union to look brand new, so paint the whole building white.",
           [paint("student_union", colour="white")], "buildings are part of the map and cannot be painted")
case("appearance", "indirect", "metal_bins", "level designer",
     "Re-skin the trash bins as metal props.",
     [looks(material="metal", category="trash_bin", scope="all", require_all=True), keep("trash_bin")],
     [paint(category="trash_bin", material="metal")])
case("appearance", "indirect", "dusk_not_night", "permission",
     "Actually, would you mind making it a bit earlier? Dusk rather than pitch dark.",
     [env(time_from="17:30", time_to="21:15"), keep(environment=True)],
     [clock("dusk")],
     setup=(turn("Make it night.", [clock("night")], planned=True),))

case("appearance", "vague", "darker_evening_ish", "dictation",
     "make it um darker like evening-ish",
     [keep(environment=True)],
     [clock("evening")],
     alternatives=([env(time_from="17:30", time_to="23:59")], [env(exposure_max=0.8)]))
case("appearance", "vague", "anything_but_sun", "permission",
     "Could we have some weather, please? Anything but sunshine.",
     [env(weather=["cloudy", "rain", "fog", "snow"]), keep(environment=True)],
     [weather("cloudy")])
case("appearance", "vague", "cheerful_cars", "grandparent",
     "Brighten up those dull cars in the car park with some nice cheerful colours.",
     [looks(BRIGHT, category=CARS, require_all=True, min_count=3), keep(*CARS)],
     [paint(category="passenger_car", colour="red"), paint(category="suv", colour="yellow")])
case("appearance", "vague", "snowy", "child",
     "make it snowy!!!",
     [env(weather=["snow"]), keep(environment=True)],
     [weather("snow")])
case("appearance", "vague", "gloomy", "goal",
     "The scene should feel gloomy.",
     [keep(environment=True)],
     [weather("cloudy", 0.8)],
     alternatives=([env(weather=["cloudy", "rain", "fog", "snow"])], [env(night=True)], [env(exposure_max=0.8)]))
case("appearance", "vague", "all_lights_on", "commander",
     "Lights. All of them. On.",
     [env(street_lights="on", vehicle_lights="on"), keep(environment=True)],
     [lighting(street_lights="on", vehicle_lights="on")])
case("appearance", "vague", "cones_something_bright", "dictation",
     "paint the uh the cones something bright",
     [looks(BRIGHT, category="traffic_cone", require_all=True, min_count=4), keep("traffic_cone")],
     [paint(category="traffic_cone", colour="yellow")],
     setup=(turn("Put four cones in lot A.", [add("traffic_cone", 4, loc("parking lot A"))]),))
case("appearance", "vague", "bus_green_ish", "permission",
     "Could it be a different colour? Something green-ish, maybe.",
     [looks(["green", "teal"], category="bus"), keep("bus")],
     [paint(category="bus", colour="green")],
     setup=(turn("Add a bus at the bus stop.", [add("bus", 1, loc("bus stop"))], planned=True),))
impossible("appearance", "vague", "twenty_times_brighter", "commander",
           "Brightness. Twenty times normal.",
           [lighting(exposure=20)], "exposure is at most 4")

case("appearance", "erroneous", "little_snow_german", "German speaker",
     "Please make the weather to snow, but only a little bit.",
     [env(weather=["snow"], intensity_max=0.45), keep(environment=True)],
     [weather("snow", 0.3)])
case("appearance", "erroneous", "suv_red_spanish", "Spanish speaker",
     "Put the SUV of color red, please.",
     [looks("red", asset="suv_1"), keep(assets=["suv_1"])],
     [paint("suv_1", colour="red")])
case("appearance", "erroneous", "seven_pm_hindi", "Hindi speaker",
     "Kindly change the timing to 7 PM itself.",
     [at_time("19:00", weather=["clear"]), keep(environment=True)],
     [clock("19:00")])
case("appearance", "erroneous", "bench_green_bin_black_japanese", "Japanese speaker",
     "Bench colour, green please. And trash bin, black colour.",
     [looks("green", asset="bench_1"), looks("black", asset="trash_bin_1"), keep(assets=["bench_1", "trash_bin_1"])],
     [paint("bench_1", colour="green"), paint("trash_bin_1", colour="black")], tags=("compound",))
case("appearance", "erroneous", "reign_heavy", "dictation",
     "make it reign really heavy",
     [env(weather=["rain"], intensity_min=0.75), keep(environment=True)],
     [weather("rain", 0.9)])
case("appearance", "erroneous", "stret_lights_of", "grandparent",
     "trun teh stret lights of",
     [env(street_lights="off"), keep(environment=True)],
     [lighting(street_lights="off")])
case("appearance", "erroneous", "nite_and_foggy", "child",
     "make it nite time and foggy",
     [env(night=True, weather=["fog"]), keep(environment=True)],
     [clock("night"), weather("fog")], tags=("compound",))
impossible("appearance", "erroneous", "sandstorm_german", "German speaker",
           "Please make the weather to a sandstorm, like in the desert.",
           [weather("sandstorm", 0.8)], "the weather can be clear, cloudy, rain, fog or snow")
case("appearance", "erroneous", "gold_and_dusk_spanish", "Spanish speaker",
     "Put all the street lights of color gold and the hour in the dusk.",
     [looks("gold", category="street_light", scope="all", require_all=True, min_count=12),
      env(time_from="18:30", time_to="21:00"), keep("street_light", environment=True)],
     [paint(category="street_light", colour="gold"), clock("dusk")], tags=("compound",))

# ---------------------------------------------------------------------------------------------

ALL_CASES: list[Json] = [json.loads(json.dumps(c)) for c in CASES]


def main() -> None:
    SUITE_PATH.parent.mkdir(parents=True, exist_ok=True)
    text = "".join(json.dumps(c, ensure_ascii=False) + "\n" for c in ALL_CASES)
    SUITE_PATH.write_text(text, encoding="utf-8")
    print(f"wrote {len(ALL_CASES)} cases to {SUITE_PATH}")


if __name__ == "__main__":
    main()
