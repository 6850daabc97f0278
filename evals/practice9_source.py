"""practice9: the tenth practice suite, prompts in voices the planners have not met.

Run `python -m drivetwin.evals.practice9_source` to write `suites/practice9.jsonl` from the
case list below; a test checks that the two agree.

The suite asks the seven tasks (search, addition, removal, positioning, moving, arrangement,
appearance) at four grades (direct, indirect, vague, erroneous) on the campus world, in the
words of people a developer would not write like:

- a game or level designer: spawn, despawn, prop, set dressing, grid-snap;
- someone from another simulator (CARLA / ROS habits): spawn_actor, destroy the actor,
  set_transform, teleport, x/y in metres;
- a safety engineer writing operational-design-domain specs: "ODD condition: ...", occluder,
  VRU, target object;
- a terse power user: "+2 benches @ fountain", "rm all bins", "mv ego 5m fwd", "tod=dusk";
- someone who picks things by ordinal, comparison or superlative: the second car from the
  left, the car nearest the Student Union, the biggest vehicle, the other one;
- a photographer or artist talking composition and mood: frame the shot, moody, warmer light;
- a rambling message with the request buried in chit-chat;
- loose or wrong names said with confidence (post for bollard, fence for barrier, pylon for
  cone, dumpster for bin) and brand or slang names (a Vespa, a black cab);
- someone who states constraints and preferences: no more than six, at least 20 m away, keep
  the SUV;
- second-language speakers with literal translations ("near of", "make appear", "the car of
  the middle").

Every case judges the outcome, never the calls: a main check (counts with exact bounds,
places by `near` / `relative` / `on_surface`, layouts, behaviours, looks, answers) and an
`unchanged_except` guard so collateral edits fail. Questions change nothing and must name
the right facts. About 8 % ask for what the world cannot do (an unknown category, colour,
weather or place, a spot inside a building or off the map, a count past the limits); the
right outcome is a refusal that changes nothing. Multi-turn cases build their starting
scene in earlier turns, some of them planned by the planner under test. In all: 210 cases,
24 multi-turn (8 with a planned earlier turn), 19 compound, 16 impossible.

World facts the cases lean on (campus): cars in lot B face north, west to east
passenger_car_1 (x 19), suv_1 (x 23), passenger_car_2 (x 27); the ego drives
main_eastbound from (-60, -1.75); twelve street lights, odd ids on the north side of Main
Street; bench_1 and trash_bin_1 by the bus stop; tree_1 by the library, tree_2 and tree_3 by
the fountain, tree_4 north of lot A.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

SUITE_PATH = Path(__file__).resolve().parent / "suites" / "practice9.jsonl"
SUITE = "practice9"

Json = dict[str, Any]


# Calls -------------------------------------------------------------------------------------
def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def where(relation: str = "at", target: str | None = None, **extra: Any) -> Json:
    """A Location: a relation to a target, or absolute x/y."""
    loc: Json = {"relation": relation}
    if target is not None:
        loc["target"] = target
    loc.update(extra)
    return loc


def xy(x: float, y: float) -> Json:
    return where("absolute", x=x, y=y)


def add(category: str, count: int = 1, location: Json | None = None, **extra: Any) -> Json:
    args: Json = {"category": category, "count": count}
    if location is not None:
        args["location"] = location
    args.update(extra)
    return call("add_asset", **args)


def remove(*ids: str, **extra: Any) -> Json:
    args: Json = {"assets": list(ids)} if ids else {}
    args.update(extra)
    return call("remove_assets", **args)


def place(asset: str, location: Json, **extra: Any) -> Json:
    return call("place_asset", asset=asset, location=location, **extra)


def move(asset: str, **extra: Any) -> Json:
    return call("move_asset", asset=asset, **extra)


def behave(asset: str, kind: str, **spec: Any) -> Json:
    return call("set_behaviour", asset=asset, behaviour={"kind": kind, **spec})


def arrange(categories: str | list[str], shape: str, location: Json, **extra: Any) -> Json:
    cats = [categories] if isinstance(categories, str) else categories
    return call("arrange_assets", categories=cats, shape=shape, location=location, **extra)


def look(*ids: str, **extra: Any) -> Json:
    args: Json = {"assets": list(ids)} if ids else {}
    args.update(extra)
    return call("set_asset_appearance", **args)


def clock(time: str) -> Json:
    return call("set_time_of_day", time=time)


def weather(kind: str, intensity: float | None = None) -> Json:
    return call("set_weather", kind=kind) if intensity is None else call("set_weather", kind=kind, intensity=intensity)


def lights(**extra: Any) -> Json:
    return call("set_lighting", **extra)


def find(**extra: Any) -> Json:
    return call("find_assets", **extra)


# Checks ------------------------------------------------------------------------------------
def only(*categories: str, assets: tuple[str, ...] | list[str] = (), env: bool = False) -> Json:
    """Nothing changed but these categories / ids (and the environment when `env`)."""
    check: Json = {"kind": "unchanged_except"}
    if categories:
        check["categories"] = list(categories)
    if assets:
        check["assets"] = list(assets)
    if env:
        check["environment"] = True
    return check


NOTHING = only()
ACCEPTED = {"kind": "status", "accepted": True}
REFUSED = {"kind": "status", "accepted": False}


def delta(category: str | list[str], low: int, high: int | None = None) -> Json:
    return {"kind": "count_delta", "category": category, "min": low, "max": low if high is None else high}


def count(category: str | list[str], low: int | None = None, high: int | None = None) -> Json:
    check: Json = {"kind": "count", "category": category}
    if low is not None:
        check["min"] = low
    if high is not None:
        check["max"] = high
    return check


def _select(check: Json, category: str | list[str] | None, asset: str | None, scope: str | None,
            require_all: bool, min_count: int | None) -> Json:
    if asset is not None:
        check["asset"] = asset
    if category is not None:
        check["category"] = category
    if scope is not None:
        check["scope"] = scope
    if require_all:
        check["require_all"] = True
    if min_count is not None:
        check["min_count"] = min_count
    return check


def near(target: str | tuple[float, float], within: float, category: str | list[str] | None = None,
         asset: str | None = None, scope: str | None = None, require_all: bool = True,
         min_count: int | None = None) -> Json:
    check: Json = {"kind": "near", "within": within}
    if isinstance(target, tuple):
        check["point"] = list(target)
    else:
        check["target"] = target
    return _select(check, category, asset, scope, require_all, min_count)


def relative(relation: str, target: str, category: str | list[str] | None = None, asset: str | None = None,
             max_distance: float = 15.0, tolerance_deg: float = 60.0, require_all: bool = True) -> Json:
    check: Json = {"kind": "relative", "relation": relation, "target": target,
                   "max_distance": max_distance, "tolerance_deg": tolerance_deg}
    return _select(check, category, asset, None, require_all, None)


def on(surfaces: list[str], category: str | list[str] | None = None, asset: str | None = None) -> Json:
    return _select({"kind": "on_surface", "surfaces": surfaces}, category, asset, None, False, None)


def in_lane(lane: str | None, category: str | list[str] | None = None, asset: str | None = None,
            aligned: bool = False) -> Json:
    check: Json = {"kind": "in_lane"}
    if lane is not None:
        check["lane"] = lane
    if aligned:
        check["aligned"] = True
    return _select(check, category, asset, None, False, None)


def layout(shape: str, category: str | list[str], min_count: int = 3, tolerance: float = 1.0,
           around: str | None = None, **extra: Any) -> Json:
    check: Json = {"kind": "arrangement", "shape": shape, "category": category, "scope": "added",
                   "min_count": min_count, "tolerance": tolerance}
    if around is not None:
        check["around"] = around
    check.update(extra)
    return check


def doing(behaviour: str | list[str], category: str | list[str] | None = None, asset: str | None = None,
          **extra: Any) -> Json:
    check: Json = {"kind": "behaviour", "behaviour": behaviour}
    check.update(extra)
    return _select(check, category, asset, None, True, None)


def env(**extra: Any) -> Json:
    return {"kind": "environment", **extra}


def colour(colours: str | list[str] | None, category: str | list[str] | None = None, asset: str | None = None,
           require_all: bool = True, min_count: int | None = None, material: str | None = None,
           scope: str | None = None) -> Json:
    check: Json = {"kind": "appearance"}
    if colours is not None:
        check["colour"] = colours
    if material is not None:
        check["material"] = material
    return _select(check, category, asset, scope, require_all, min_count)


def moved(asset: str, low: float = 0.0, high: float | None = None, direction: str | None = None,
          turn: tuple[float, float] | None = None) -> Json:
    check: Json = {"kind": "moved", "asset": asset, "min_distance": low}
    if high is not None:
        check["max_distance"] = high
    if direction is not None:
        check["direction"] = direction
    if turn is not None:
        check["turn_min_deg"], check["turn_max_deg"] = turn
    return check


def gone(*ids: str) -> Json:
    return {"kind": "exists", "assets": list(ids), "present": False}


def kept(*ids: str) -> Json:
    return {"kind": "exists", "assets": list(ids), "present": True}


def says(all_of: tuple[str, ...] | list[str] = (), any_of: tuple[str, ...] | list[str] = (),
         none_of: tuple[str, ...] | list[str] = ()) -> Json:
    check: Json = {"kind": "answer_contains"}
    if all_of:
        check["all_of"] = list(all_of)
    if any_of:
        check["any_of"] = list(any_of)
    if none_of:
        check["none_of"] = list(none_of)
    return check


def step(prompt: str, calls: list[Json], planned: bool = False) -> Json:
    out: Json = {"prompt": prompt, "calls": calls}
    if planned:
        out["planned"] = True
    return out


# Cases -------------------------------------------------------------------------------------
ALL_CASES: list[Json] = []


def case(task: str, grade: str, name: str, prompt: str, reference: list[Json], checks: list[Json],
         *, tags: tuple[str, ...] = (), setup: list[Json] | None = None,
         alternatives: list[list[Json]] | None = None, notes: str = "") -> None:
    tag_list = [SUITE, *tags]
    if setup and "multi_turn" not in tag_list:
        tag_list.append("multi_turn")
    item: Json = {"id": f"{SUITE}.{task}.{grade}.{name}"}
    if setup:
        item["setup"] = setup
    item.update(prompt=prompt, task=task, grade=grade, tags=tag_list, checks=checks)
    if alternatives:
        item["alternatives"] = alternatives
    item["reference"] = reference
    if notes:
        item["notes"] = notes
    ALL_CASES.append(item)


def question(grade: str, name: str, prompt: str, reference: list[Json], *answer: Json,
             tags: tuple[str, ...] = (), setup: list[Json] | None = None) -> None:
    """A search case: the answer names the facts, and nothing in the scene changes."""
    case("search", grade, name, prompt, reference, [*answer, ACCEPTED, NOTHING], tags=tags, setup=setup)


def impossible(task: str, grade: str, name: str, prompt: str, reference: list[Json], notes: str,
               setup: list[Json] | None = None) -> None:
    """A request the world cannot carry out: refused, and nothing changed."""
    case(task, grade, name, prompt, reference, [REFUSED, NOTHING], tags=("impossible",), setup=setup,
         notes=notes)


C, M = ("compound",), ("multi_turn",)
LOT_B_CARS = ("passenger_car_1", "suv_1", "passenger_car_2")
NORTH_LIGHTS = tuple(f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11))
SOUTH_LIGHTS = tuple(f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12))
CONES_AT_LIBRARY = step("put 3 cones in front of the Library entrance",
                        [add("traffic_cone", 3, where("in_front_of", "Library entrance"))])
BUS_AT_STOP = step("add a bus at the bus stop", [add("bus", 1, where("at", "bus stop"))])
RUBBLE_ON_MAIN = step("drop some rubble on the centre line of Main Street near the east end",
                      [add("cement_rubble", 1, xy(60.0, 0.0))])

# --- search ---------------------------------------------------------------------------------
question("direct", "power_count_lights", "count(street_light) — total?",
         [find(category="street_light")], says(any_of=["12", "twelve"]))
question("direct", "power_ls_vehicles_lot_b", "ls vehicles @ lot B",
         [find(category="vehicles", near="parking lot B", within=30)],
         says(all_of=["passenger_car_1", "suv_1", "passenger_car_2"]))
question("direct", "carla_get_traffic_lights", "world.get_actors().filter('traffic_light') -> ids and x/y please",
         [find(category="traffic_light")], says(all_of=["traffic_light_1", "traffic_light_2"]))
question("direct", "odd_hydrant_to_north_crosswalk",
         "Target object inventory: distance in metres from the fire hydrant to the north crosswalk?",
         [call("measure_distance", a="fire_hydrant_1", b="north crosswalk")], says(any_of=["17.1", "17"]))
question("direct", "photo_time_and_weather",
         "Before I set up: what time is it in the scene and what's the weather doing?",
         [call("describe_environment")], says(all_of=["clear"], any_of=["12:00", "noon", "midday"]))
question("direct", "l2_lanes_of_campus_drive", "Please tell me which lanes has the Campus Drive.",
         [call("find_lanes", road="Campus Drive")], says(all_of=["campus_northbound", "campus_southbound"]))

question("indirect", "ordinal_second_car_from_left", "Which one is the second car from the left in lot B?",
         [find(category="vehicles", near="parking lot B", within=30), call("asset_properties", asset="suv_1")],
         says(all_of=["suv_1"]))
question("indirect", "compare_car_nearest_union", "Which car is parked closest to the Student Union?",
         [find(category="vehicles", nearest_to="Student Union entrance")],
         says(all_of=["passenger_car_2"]))
question("indirect", "photo_landmark_nearest_fountain",
         "I want the fountain in the foreground with a building entrance behind it — which entrance is closest to the fountain?",
         [call("find_landmarks", nearest_to="fountain")], says(all_of=["JTEKT"]))
question("indirect", "odd_list_vrus", "ODD check: list every VRU present in the scene right now.",
         [find(category="vrus")], says(any_of=["0", "no", "none", "zero"]))
question("indirect", "ramble_bin_near_bus_stop",
         "hey so I was walking past the engineering building earlier, gorgeous day, anyway the reason "
         "I'm messaging — is there a bin anywhere near the bus stop in the twin? how far from it?",
         [find(category="trash_bin", nearest_to="bus stop")],
         says(any_of=["trash_bin_1", "bin"]), says(any_of=["3.5"]))
question("indirect", "constraint_hydrant_within_20m",
         "Is there a fire hydrant within 20 m of the main intersection? yes/no and which one",
         [find(category="fire_hydrant", near="main intersection", within=20)],
         says(any_of=["fire_hydrant_1", "yes"]))
question("indirect", "ros_ego_transform", "echo the ego's current pose: x, y, yaw",
         [call("asset_properties", asset="ego")], says(all_of=["-60"], any_of=["-1.8", "-1.75"]))
question("indirect", "l2_lane_of_ego", "In which lane is driving the ego car now?",
         [find(category="ego_vehicle", on_lane=True)], says(any_of=["main_eastbound", "eastbound"]))

question("vague", "whats_by_the_library", "what's around the library?",
         [find(near="Library entrance", within=13)],
         says(any_of=["street_light_4", "trash_bin_1", "bin", "street light", "bench", "bus stop"]))
question("vague", "is_it_dark", "is it dark out?", [call("describe_environment")],
         says(any_of=["day", "12:00", "no", "noon", "daytime"]))
question("vague", "superlative_furthest_tree", "which tree's the furthest out from our car?",
         [find(category="tree", nearest_to="ego")], says(all_of=["tree_3"]))
question("vague", "designer_props_on_map", "what props have we got on the map so far?",
         [find()], says(any_of=["street_light", "street light", "tree", "bench", "traffic_light"]))
question("vague", "photo_light_for_shoot", "how's the light for a shoot at the moment?",
         [call("describe_environment")], says(any_of=["12:00", "noon", "midday", "day", "clear"]))
question("vague", "any_robots", "any robots about?", [find(category="ackermann_robot")],
         says(any_of=["0", "no", "none", "zero"]))
question("vague", "walk_bus_stop_to_union", "how far's the walk from the bus stop over to the union?",
         [call("measure_distance", a="bus stop", b="Student Union entrance")], says(any_of=["85.6", "86", "85"]))

question("erroneous", "typo_count_traffic_lights", "how mnay trafic lights r there",
         [find(category="traffic_light")], says(any_of=["2", "two"]))
question("erroneous", "typo_lane_nearest_fountain", "wich lane is closest to teh fountain?",
         [call("find_lanes", near="fountain")], says(any_of=["main_westbound", "westbound"]))
question("erroneous", "typo_lot_a_to_lot_b", "distnace between lot A and lot B plz, and how many cars r in B",
         [call("measure_distance", a="parking lot A", b="parking lot B"),
          find(category="vehicles", near="parking lot B", within=30)],
         says(any_of=["136.4", "136", "116.7", "117"]), says(any_of=["3", "three"]), tags=C)
question("erroneous", "l2_where_bench_stands", "The bench, where is it stand? Near of which place?",
         [find(category="bench"), call("find_landmarks", nearest_to="bench_1")],
         says(any_of=["bus stop", "library"]))
question("erroneous", "typo_ego_to_west_crosswalk", "hw far is ego frm the west crosswlak",
         [call("measure_distance", a="ego", b="west crosswalk")], says(any_of=["48.5", "48", "49"]))
question("erroneous", "typo_suv_colour", "wht colour is the suv rn",
         [call("asset_properties", asset="suv_1")], says(any_of=["default", "grey", "gray", "dark", "charcoal"]))
question("erroneous", "typo_raining", "is it rainin on campus?", [call("describe_environment")],
         says(any_of=["clear", "no", "not"]))
question("erroneous", "typo_where_stop_sign", "were is the stop sing?", [find(category="stop_sign")],
         says(any_of=["stop_sign_1", "-13.5"]))
question("indirect", "power_cones_just_added", "how many pylons did we just put down, and where?",
         [find(category="traffic_cone")], says(any_of=["3", "three"]), says(any_of=["library", "traffic_cone_1", "-15", "-13"]),
         setup=[CONES_AT_LIBRARY])
question("vague", "planned_vehicles_now", "so how many vehicles in the scene now, ego included?",
         [find(category="vehicles")], says(any_of=["5", "five"]),
         setup=[step("spawn a bus at the bus stop", [add("bus", 1, where("at", "bus stop"))], planned=True)])

# --- addition -------------------------------------------------------------------------------
case("addition", "direct", "designer_spawn_cones_library", "Spawn 3 traffic cones in front of the Library entrance.",
     [add("traffic_cone", 3, where("in_front_of", "Library entrance"))],
     [delta("traffic_cone", 3), near("Library entrance", 8, "traffic_cone", scope="added"),
      relative("in_front_of", "Library entrance", "traffic_cone", max_distance=10), only("traffic_cone")])
case("addition", "direct", "carla_spawn_bus_xy", "spawn_actor('bus') at x=-30, y=-1.75 (metres), yaw 0",
     [add("bus", 1, xy(-30.0, -1.75), yaw_deg=0)],
     [delta("bus", 1), near((-30.0, -1.75), 1.5, "bus", scope="added"), in_lane("main_eastbound", "bus", aligned=True),
      only("bus")])
case("addition", "direct", "power_two_benches_fountain", "+2 benches @ fountain",
     [add("bench", 2, where("at", "fountain"))],
     [delta("bench", 2), near("fountain", 8, "bench", scope="added"), only("bench")])
case("addition", "direct", "odd_ped_on_sidewalk_bus_stop",
     "ODD condition: one pedestrian standing on the sidewalk at the bus stop.",
     [add("pedestrian", 1, where("on_sidewalk", "bus stop"))],
     [delta("pedestrian", 1), near("bus stop", 6, "pedestrian", scope="added"), on(["sidewalk"], "pedestrian"),
      only("pedestrian")])
case("addition", "direct", "l2_hydrant_near_of_engineering",
     "Please add one fire hydrant on the sidewalk near to the Engineering Hall entrance.",
     [add("fire_hydrant", 1, where("on_sidewalk", "Engineering Hall entrance"))],
     [delta("fire_hydrant", 1), near("Engineering Hall entrance", 12, "fire_hydrant", scope="added"),
      on(["sidewalk"], "fire_hydrant"), only("fire_hydrant")])
case("addition", "direct", "slang_vespa_jtekt", "Add a Vespa in front of the JTEKT entrance.",
     [add("motorcycle", 1, where("in_front_of", "JTEKT building entrance"))],
     [delta("motorcycle", 1), near("JTEKT building entrance", 8, "motorcycle", scope="added"),
      on(["drivable"], "motorcycle"), only("motorcycle")])

case("addition", "indirect", "designer_dress_bus_stop",
     "Need some set dressing at the bus stop for people waiting: a bench and a bin.",
     [add("bench", 1, where("next_to", "bus stop")), add("trash_bin", 1, where("next_to", "bus stop"))],
     [delta("bench", 1), delta("trash_bin", 1), near("bus stop", 8, ["bench", "trash_bin"], scope="added"),
      only("bench", "trash_bin")], tags=C)
case("addition", "indirect", "odd_aeb_target_truck",
     "Target object for the AEB run: a stationary box truck in the ego's lane, 40 m ahead of it.",
     [add("truck", 1, where("at", "ego", along_m=40))],
     [delta("truck", 1), in_lane("main_eastbound", "truck"), near((-20.0, -1.75), 5, "truck", scope="added"),
      doing("parked", "truck"), only("truck")])
case("addition", "indirect", "photo_frame_doors_with_trees",
     "Frame the Engineering Hall doors for me: one tree either side of the entrance.",
     [add("tree", 1, where("left_of", "Engineering Hall entrance", distance=5)),
      add("tree", 1, where("right_of", "Engineering Hall entrance", distance=5))],
     [delta("tree", 2), near("Engineering Hall entrance", 9, "tree", scope="added"),
      relative("left_of", "Engineering Hall entrance", "tree", max_distance=10, tolerance_deg=70, require_all=False),
      relative("right_of", "Engineering Hall entrance", "tree", max_distance=10, tolerance_deg=70, require_all=False),
      only("tree")], tags=C)
case("addition", "indirect", "carla_vru_jaywalker", "Need a VRU actor that jaywalks in front of the ego.",
     [add("pedestrian", 1, behaviour={"kind": "jaywalk"})],
     [delta(["pedestrian", "bicycle", "motorcycle"], 1), doing("jaywalk", ["pedestrian", "bicycle", "motorcycle"]),
      only("pedestrian", "bicycle", "motorcycle")])
case("addition", "indirect", "ramble_one_more_car_northbound",
     "ok so the client came back and they loved the crossroads shot but they think the road looks too "
     "empty, like nobody's driving?? could we get one more car going up Campus Drive northbound, nothing fancy",
     [add("passenger_car", 1, where("in_lane", "campus_northbound"), behaviour={"kind": "drive_lane", "lane": "campus_northbound"})],
     [delta(["passenger_car", "suv"], 1), doing("drive_lane", ["passenger_car", "suv"], lane="campus_northbound"),
      only("passenger_car", "suv")])
case("addition", "indirect", "loose_dumpster_union", "Drop a dumpster next to the Student Union entrance.",
     [add("trash_bin", 1, where("next_to", "Student Union entrance"))],
     [delta("trash_bin", 1), near("Student Union entrance", 6, "trash_bin", scope="added"), only("trash_bin")])
case("addition", "indirect", "constraint_posts_lot_a", "Two posts at the lot A entrance, no more than two.",
     [add("bollard", 2, where("at", "parking lot A entrance"))],
     [delta("bollard", 2), near("parking lot A entrance", 6, "bollard", scope="added"), only("bollard")])
case("addition", "indirect", "ordinal_moped_behind_third_car",
     "Park a moped just behind the third car in lot B, counting from the west.",
     [add("motorcycle", 1, where("behind", "passenger_car_2"))],
     [delta("motorcycle", 1), near("passenger_car_2", 5, "motorcycle", scope="added"),
      relative("behind", "passenger_car_2", "motorcycle", max_distance=8), only("motorcycle")])

case("addition", "vague", "pylons_by_hydrant", "drop a few pylons by the hydrant",
     [add("traffic_cone", 3, where("next_to", "fire_hydrant_1"))],
     [delta("traffic_cone", 2, 6), near("fire_hydrant_1", 8, "traffic_cone", scope="added"), only("traffic_cone")])
case("addition", "vague", "liven_up_quad", "liven up the quad a bit, some people hanging around",
     [add("pedestrian", 3, where("at", "fountain"))],
     [delta("pedestrian", 2, 10), near("fountain", 15, "pedestrian", scope="added"), only("pedestrian")])
case("addition", "vague", "superlative_seat_biggest_building",
     "put somewhere to sit by the biggest building",
     [add("bench", 1, where("next_to", "Library entrance"))],
     [delta("bench", 1), only("bench")],
     alternatives=[[near("Library entrance", 12, "bench", scope="added")],
                   [near("Engineering Hall entrance", 12, "bench", scope="added")]],
     notes="the library has the largest footprint, Engineering Hall is the tallest")
case("addition", "vague", "odd_light_traffic_main_street", "ODD condition: light traffic on Main Street.",
     [add("passenger_car", 2, where("in_lane", "main_westbound"), behaviour={"kind": "drive_lane", "lane": "main_westbound"})],
     [delta(["passenger_car", "suv", "truck", "bus", "motorcycle"], 1, 5),
      doing("drive_lane", ["passenger_car", "suv", "truck", "bus", "motorcycle"]),
      only("passenger_car", "suv", "truck", "bus", "motorcycle")],
     alternatives=[[doing("drive_lane", ["passenger_car", "suv", "truck", "bus", "motorcycle"], lane="main_westbound")],
                   [doing("drive_lane", ["passenger_car", "suv", "truck", "bus", "motorcycle"], lane="main_eastbound")]])
case("addition", "vague", "photo_backdrop_behind_bench",
     "something tall and green behind the bench please, for the backdrop",
     [add("tree", 1, where("behind", "bench_1"))],
     [delta("tree", 1), near("bench_1", 6, "tree", scope="added"), only("tree")])
case("addition", "vague", "l2_bikes_near_of_library", "Put there some bikes near of the library, for the students.",
     [add("bicycle", 3, where("next_to", "Library entrance"))],
     [delta("bicycle", 2, 8), near("Library entrance", 12, "bicycle", scope="added"), only("bicycle")])
case("addition", "vague", "designer_npc_cars_lot_a", "spawn a couple of npc cars in lot A",
     [add("passenger_car", 2, where("at", "parking lot A"))],
     [delta(["passenger_car", "suv"], 2), near("parking lot A", 1, ["passenger_car", "suv"], scope="added"),
      only("passenger_car", "suv")])

case("addition", "erroneous", "typo_cones_libary", "ad 4 cones infront of the libary",
     [add("traffic_cone", 4, where("in_front_of", "Library entrance"))],
     [delta("traffic_cone", 4), near("Library entrance", 8, "traffic_cone", scope="added"), only("traffic_cone")])
case("addition", "erroneous", "typo_spwan_bus", "plz spwan a bus at teh bus stp",
     [add("bus", 1, where("at", "bus stop"))],
     [delta("bus", 1), near("bus stop", 10, "bus", scope="added"), on(["drivable"], "bus"), only("bus")])
case("addition", "erroneous", "typo_tree_next_fountain", "put a tre next to the fountan",
     [add("tree", 1, where("next_to", "fountain"))],
     [delta("tree", 1), near("fountain", 8, "tree", scope="added"), only("tree")])
case("addition", "erroneous", "typo_two_trashcans_compound",
     "add a trashcan by the bench, and anotehr one by the stop sign",
     [add("trash_bin", 1, where("next_to", "bench_1")), add("trash_bin", 1, where("next_to", "stop_sign_1"))],
     [delta("trash_bin", 2), near("bench_1", 5, "trash_bin", scope="added", require_all=False),
      near("stop_sign_1", 5, "trash_bin", scope="added", require_all=False), only("trash_bin")], tags=C)
impossible("addition", "erroneous", "l2_ambulance_not_in_catalog", "Make appear one ambulanse near of the main gate.",
           [add("ambulance", 1, where("at", "main gate"))], "no ambulance in the catalog")
impossible("addition", "erroneous", "typo_300_cones", "add 300 conse along main st",
           [add("traffic_cone", 300, where("in_lane", "main_eastbound"))], "a scene holds at most 200 traffic cones")
impossible("addition", "vague", "helicopter_on_roof", "spawn a helicopter on the JTEKT roof, for the drone shot vibe",
           [add("helicopter", 1, xy(37.5, 29.0))], "no helicopter in the catalog, and the roof is inside the building")
impossible("addition", "indirect", "hydrant_middle_of_crossroads",
           "Put a hydrant in the dead centre of the crossroads, exactly 0,0.",
           [add("fire_hydrant", 1, xy(0.0, 0.0))], "a hydrant belongs on a sidewalk or verge, not in the junction")
case("addition", "vague", "planned_cones_behind_truck", "now put a couple of cones behind it",
     [add("traffic_cone", 2, where("behind", "truck_1"))],
     [delta("traffic_cone", 2), near("truck_1", 9, "traffic_cone", scope="added"), only("traffic_cone")],
     setup=[step("spawn a delivery truck in lot B", [add("truck", 1, where("at", "parking lot B"))], planned=True)])
case("addition", "indirect", "another_bus_behind", "add another one right behind it",
     [add("bus", 1, where("behind", "bus_1"))],
     [delta("bus", 1), near("bus_1", 8, "bus", scope="added"), relative("behind", "bus_1", "bus", max_distance=20, tolerance_deg=35),
      only("bus")],
     setup=[BUS_AT_STOP])
case("addition", "erroneous", "planned_friend_for_ped", "give him a freind standing next to him",
     [add("pedestrian", 1, where("next_to", "pedestrian_1"))],
     [delta("pedestrian", 1), near("pedestrian_1", 4, "pedestrian", scope="added"), only("pedestrian")],
     setup=[step("add a pedestrian on the sidewalk by the west crosswalk",
                 [add("pedestrian", 1, where("on_sidewalk", "west crosswalk"))], planned=True)])

# --- removal --------------------------------------------------------------------------------
case("removal", "direct", "carla_destroy_stop_sign", "destroy the actor stop_sign_1",
     [remove("stop_sign_1")], [gone("stop_sign_1"), delta("stop_sign", -1), only(assets=["stop_sign_1"])])
case("removal", "direct", "power_rm_all_bins", "rm all bins",
     [remove(category="trash_bin")], [count("trash_bin", 0, 0), delta("trash_bin", -3), only("trash_bin")],
     setup=[step("two more bins at the fountain", [add("trash_bin", 2, where("at", "fountain"))])])
case("removal", "direct", "designer_despawn_suv", "Despawn the SUV in lot B.",
     [remove("suv_1")], [gone("suv_1"), kept("passenger_car_1", "passenger_car_2"), only(assets=["suv_1"])])
case("removal", "direct", "odd_remove_hydrant", "Remove the fire hydrant from the scene.",
     [remove("fire_hydrant_1")], [gone("fire_hydrant_1"), only(assets=["fire_hydrant_1"])])
case("removal", "direct", "l2_tree_near_of_library", "Please remove the tree that is near of the Library.",
     [remove("tree_1")], [gone("tree_1"), kept("tree_2", "tree_3", "tree_4"), only(assets=["tree_1"])])
case("removal", "direct", "delete_both_traffic_lights", "Delete both traffic lights.",
     [remove(category="traffic_light")], [gone("traffic_light_1", "traffic_light_2"), only("traffic_light")])

case("removal", "indirect", "ordinal_second_car_from_left", "Get rid of the second car from the left in lot B.",
     [remove("suv_1")], [gone("suv_1"), only(assets=["suv_1"])])
case("removal", "indirect", "superlative_light_nearest_bus_stop", "Take away the street light closest to the bus stop.",
     [remove(category="street_light", near="bus stop", count=1)],
     [gone("street_light_4"), delta("street_light", -1), only(assets=["street_light_4"])])
case("removal", "indirect", "ramble_lose_bin_by_bus_stop",
     "So the render for the safety board is tomorrow and honestly I'm a bit stressed, the library shot "
     "looks cluttered. I think it's the bin by the bus stop? Just lose that one thing, leave everything else.",
     [remove("trash_bin_1")], [gone("trash_bin_1"), only(assets=["trash_bin_1"])])
case("removal", "indirect", "carla_destroy_all_cones", "destroy every actor of type static.prop.trafficcone",
     [remove(category="traffic_cone")], [count("traffic_cone", 0, 0), delta("traffic_cone", -4), only("traffic_cone")],
     setup=[step("4 cones in front of the Library entrance", [add("traffic_cone", 4, where("in_front_of", "Library entrance"))])])
case("removal", "indirect", "odd_remove_occluding_truck",
     "Remove the occluder between the ego and the west crosswalk (the parked box truck).",
     [remove("truck_1")], [gone("truck_1"), only(assets=["truck_1"])],
     setup=[step("park a truck in the eastbound lane at x=-35", [add("truck", 1, xy(-35.0, -1.75), yaw_deg=0)])])
case("removal", "indirect", "loose_posts_lot_a", "Pull out the posts by the lot A entrance.",
     [remove(category="bollard", near="parking lot A entrance", count=3)],
     [gone("bollard_1", "bollard_2", "bollard_3"), kept("bollard_4"), delta("bollard", -3), only("bollard")],
     setup=[step("three bollards at the lot A entrance", [add("bollard", 3, where("at", "parking lot A entrance"))]),
            step("and one bollard by the fountain", [add("bollard", 1, where("next_to", "fountain"))])])
case("removal", "indirect", "constraint_keep_the_suv", "Remove the cars from lot B, but keep the SUV.",
     [remove("passenger_car_1", "passenger_car_2")],
     [gone("passenger_car_1", "passenger_car_2"), kept("suv_1"), only("passenger_car")])
case("removal", "indirect", "clear_bench_and_bin", "Clear out the bench and the bin at the bus stop.",
     [remove("bench_1"), remove("trash_bin_1")],
     [gone("bench_1", "trash_bin_1"), only(assets=["bench_1", "trash_bin_1"])], tags=C)

case("removal", "vague", "declutter_library_sidewalk", "declutter the sidewalk by the library a bit",
     [remove("bench_1", "trash_bin_1")],
     [delta(["bench", "trash_bin"], -2, -1), only("bench", "trash_bin")])
case("removal", "vague", "lose_quad_greenery", "lose the greenery around the quad",
     [remove("tree_2", "tree_3")], [gone("tree_2"), kept("tree_1", "tree_4"), only("tree")])
case("removal", "vague", "signage_at_crossroads", "get rid of the signage at the crossroads",
     [remove("stop_sign_1")], [gone("stop_sign_1"), only("stop_sign", "traffic_light")])
case("removal", "vague", "too_many_cones", "too many cones now, take some away",
     [remove(category="traffic_cone", count=3)],
     [delta("traffic_cone", -5, -1), only("traffic_cone")],
     setup=[step("6 cones in front of the Library entrance", [add("traffic_cone", 6, where("in_front_of", "Library entrance"))])])
case("removal", "vague", "photo_north_lamps_skyline",
     "the lamp posts on the north side of Main Street ruin the skyline in my shot, kill them",
     [remove(*NORTH_LIGHTS)], [gone(*NORTH_LIGHTS), kept(*SOUTH_LIGHTS), only("street_light")])
case("removal", "vague", "planned_despawn_them", "nah scrap that, despawn them",
     [remove(category="traffic_cone")], [count("traffic_cone", 0, 0), only("traffic_cone")],
     setup=[step("spawn five cones in a row in front of the JTEKT entrance",
                 [arrange("traffic_cone", "line", where("in_front_of", "JTEKT building entrance"), count=5)], planned=True)])
case("removal", "vague", "l2_all_what_is_parking_lot_b", "Take off from the scene all what is parking in lot B.",
     [remove(*LOT_B_CARS)], [gone(*LOT_B_CARS), only("passenger_car", "suv")])

case("removal", "erroneous", "typo_stop_sgin", "remvoe the stop sgin", [remove("stop_sign_1")],
     [gone("stop_sign_1"), only(assets=["stop_sign_1"])])
case("removal", "erroneous", "typo_hidrant", "delet the hidrant pls", [remove("fire_hydrant_1")],
     [gone("fire_hydrant_1"), only(assets=["fire_hydrant_1"])])
case("removal", "erroneous", "typo_two_trees_compound", "tak away the tree nexto the libary and the one up by lot A",
     [remove("tree_1"), remove("tree_4")], [gone("tree_1", "tree_4"), kept("tree_2", "tree_3"), only("tree")], tags=C)
case("removal", "erroneous", "l2_remove_traffics_lights", "Please to remove the traffics lights, both of them.",
     [remove("traffic_light_1", "traffic_light_2")], [gone("traffic_light_1", "traffic_light_2"), only("traffic_light")])
case("removal", "erroneous", "planned_ramble_bike_delet",
     "ok so, the bike i added earlier, i dont want it anymore, delet",
     [remove(category="bicycle")], [count("bicycle", 0, 0), delta("bicycle", -1), only("bicycle")],
     setup=[step("add a bicycle next to the bench", [add("bicycle", 1, where("next_to", "bench_1"))], planned=True)])
case("removal", "erroneous", "power_rm_cones_keep_jtekt", "rm cones @ libary, keep the ones @ JTEKT",
     [remove(category="traffic_cone", near="Library entrance", count=3)],
     [gone("traffic_cone_1", "traffic_cone_2", "traffic_cone_3"), kept("traffic_cone_4", "traffic_cone_5"),
      only("traffic_cone")],
     setup=[CONES_AT_LIBRARY,
            step("2 cones in front of the JTEKT entrance", [add("traffic_cone", 2, where("in_front_of", "JTEKT building entrance"))])])
impossible("removal", "erroneous", "typo_remove_missing_bus", "remvoe the bus from the bus stop",
           [remove(category="bus")], "there is no bus in the scene")
impossible("removal", "vague", "remove_the_ego", "honestly just delete our own car from the scene, the ego, gone",
           [remove("ego")], "the ego vehicle cannot be removed")
case("removal", "vague", "photo_unframe_and_relight", "strip the quad bare and make it overcast for the moody version",
     [remove("tree_2", "tree_3"), weather("cloudy", 0.6)],
     [gone("tree_2", "tree_3"), kept("tree_1", "tree_4"), env(weather=["cloudy"]), only("tree", env=True)], tags=C)

# --- positioning ----------------------------------------------------------------------------
case("positioning", "direct", "carla_set_transform_bench", "set_transform(bench_1, x=70, y=38)",
     [place("bench_1", xy(70.0, 38.0))], [near((70.0, 38.0), 0.5, asset="bench_1"), only(assets=["bench_1"])])
case("positioning", "direct", "designer_bench_front_jtekt", "Move the bench so it sits in front of the JTEKT building entrance.",
     [place("bench_1", where("in_front_of", "JTEKT building entrance"))],
     [near("JTEKT building entrance", 6, asset="bench_1"), relative("in_front_of", "JTEKT building entrance", asset="bench_1", max_distance=8),
      only(assets=["bench_1"])])
case("positioning", "direct", "power_tp_ego_lot_b_entrance", "tp ego -> lot B entrance",
     [place("ego", where("at", "parking lot B entrance"))],
     [near("parking lot B entrance", 8, asset="ego"), only(assets=["ego"])])
case("positioning", "direct", "odd_suv_in_westbound_by_jtekt",
     "Place the SUV in lane main_westbound, level with the JTEKT building entrance.",
     [place("suv_1", where("in_lane", "JTEKT building entrance", lane="main_westbound"))],
     [in_lane("main_westbound", asset="suv_1"), near("JTEKT building entrance", 15, asset="suv_1"), only(assets=["suv_1"])])
case("positioning", "direct", "l2_bin_at_side_of_fountain", "Please put the trash bin at the side of the fountain.",
     [place("trash_bin_1", where("next_to", "fountain"))],
     [near("fountain", 6, asset="trash_bin_1"), only(assets=["trash_bin_1"])])
case("positioning", "direct", "ros_ego_pose_xy", "set the ego's pose to x=-20 y=-1.75 yaw=0",
     [place("ego", xy(-20.0, -1.75), yaw_deg=0)],
     [near((-20.0, -1.75), 0.5, asset="ego"), in_lane("main_eastbound", asset="ego", aligned=True), only(assets=["ego"])])

case("positioning", "indirect", "ordinal_westernmost_car_union", "Put the westernmost car of lot B in front of the Student Union entrance.",
     [place("passenger_car_1", where("in_front_of", "Student Union entrance"))],
     [near("Student Union entrance", 12, asset="passenger_car_1"), only(assets=["passenger_car_1"])])
case("positioning", "indirect", "odd_hydrant_occluder_east_gate",
     "The hydrant is an occluder for the VRU at the north crossing; relocate it to the sidewalk by the east gate.",
     [place("fire_hydrant_1", where("on_sidewalk", "east gate"))],
     [near("east gate", 8, asset="fire_hydrant_1"), on(["sidewalk"], asset="fire_hydrant_1"), only(assets=["fire_hydrant_1"])])
case("positioning", "indirect", "ramble_dean_bench_fountain",
     "hiya! the dean is visiting next week haha and she's going to sit at the fountain in the demo, so that "
     "bench by the bus stop, could it go over next to the fountain? thanks!!",
     [place("bench_1", where("next_to", "fountain"))], [near("fountain", 6, asset="bench_1"), only(assets=["bench_1"])])
case("positioning", "indirect", "photo_suv_framed_by_jtekt_doors",
     "For the hero shot I want the SUV framed by the JTEKT doors, park it right in front of them.",
     [place("suv_1", where("in_front_of", "JTEKT building entrance"))],
     [near("JTEKT building entrance", 10, asset="suv_1"), relative("in_front_of", "JTEKT building entrance", asset="suv_1", max_distance=12),
      only(assets=["suv_1"])])
case("positioning", "indirect", "swap_bench_and_bin_east_gate",
     "Swap things round: the bench goes over by the east gate, and the bin right next to it.",
     [place("bench_1", where("at", "east gate")), place("trash_bin_1", where("next_to", "bench_1"))],
     [near("east gate", 10, asset="bench_1"), near("east gate", 12, asset="trash_bin_1"),
      only(assets=["bench_1", "trash_bin_1"])], tags=C)
case("positioning", "indirect", "constraint_hydrant_campus_drive_20m",
     "Put the hydrant on a Campus Drive sidewalk north of the crossroads, at least 20 m from it.",
     [place("fire_hydrant_1", xy(5.5, 35.0))],
     [on(["sidewalk"], asset="fire_hydrant_1"), near((0.0, 55.0), 35, asset="fire_hydrant_1"),
      near("campus_northbound", 6, asset="fire_hydrant_1"), only(assets=["fire_hydrant_1"])])
case("positioning", "indirect", "planned_van_to_lot_a", "hmm, put it in lot A instead",
     [place("truck_1", where("at", "parking lot A"))],
     [near("parking lot A", 1, "truck", scope="all"), delta("truck", 0), only("truck")],
     setup=[step("add a white van next to the Engineering Hall entrance",
                 [add("truck", 1, where("next_to", "Engineering Hall entrance"), colour="white")], planned=True)])
case("positioning", "direct", "bus_to_lot_b", "Put the bus in lot B.",
     [place("bus_1", where("at", "parking lot B"))], [near("parking lot B", 1, asset="bus_1"), only(assets=["bus_1"])],
     setup=[BUS_AT_STOP])

case("positioning", "vague", "bench_somewhere_quieter", "get the bench out of the way of the bus stop, somewhere quieter",
     [place("bench_1", where("next_to", "fountain"))], [moved("bench_1", 10), only(assets=["bench_1"])])
case("positioning", "vague", "ego_start_of_main_street", "stick the ego back at the start of Main Street",
     [place("ego", where("in_lane", "main gate", lane="main_eastbound"))],
     [near("main gate", 15, asset="ego"), in_lane("main_eastbound", asset="ego"), only(assets=["ego"])])
case("positioning", "vague", "suv_near_union", "park the SUV somewhere near the union building",
     [place("suv_1", where("at", "Student Union entrance"))],
     [near("Student Union entrance", 12, asset="suv_1"), moved("suv_1", 5), only(assets=["suv_1"])])
case("positioning", "vague", "designer_hydrant_lot_b_entrance", "move the hydrant closer to the lot B entrance-ish",
     [place("fire_hydrant_1", where("next_to", "parking lot B entrance"))],
     [near("parking lot B entrance", 8, asset="fire_hydrant_1"), only(assets=["fire_hydrant_1"])])
case("positioning", "vague", "l2_bin_more_near_library_door", "The bin, bring it more near to the library door.",
     [place("trash_bin_1", where("next_to", "Library entrance"))],
     [near("Library entrance", 5, asset="trash_bin_1"), only(assets=["trash_bin_1"])])
case("positioning", "vague", "ordinal_last_car_to_lot_a", "the last car in that row in lot B, put it over in lot A",
     [place("passenger_car_2", where("at", "parking lot A"))], [delta(["passenger_car", "suv"], 0), only("passenger_car")],
     alternatives=[[near("parking lot A", 1, asset="passenger_car_2"), only(assets=["passenger_car_2"])],
                   [near("parking lot A", 1, asset="passenger_car_1"), only(assets=["passenger_car_1"])]],
     notes="last from the west or from the east: either end car")
impossible("positioning", "vague", "bench_inside_library", "put the bench inside the library, like in the reading room",
           [place("bench_1", xy(-41.0, -30.0))], "the spot is inside the library's footprint")

case("positioning", "erroneous", "typo_bech_fountian", "pleace the bech next to teh fountian",
     [place("bench_1", where("next_to", "fountain"))], [near("fountain", 6, asset="bench_1"), only(assets=["bench_1"])])
case("positioning", "erroneous", "typo_hydrnt_sidewalk_jtekt", "put the hydrnt on the sidewalk infront of JTEKT",
     [place("fire_hydrant_1", where("on_sidewalk", "JTEKT building entrance"))],
     [near("JTEKT building entrance", 11, asset="fire_hydrant_1"), on(["sidewalk"], asset="fire_hydrant_1"),
      only(assets=["fire_hydrant_1"])])
case("positioning", "erroneous", "l2_stop_sign_other_side", "Please, the stop sign put at the other side of the road, on the north sidewalk.",
     [place("stop_sign_1", xy(-13.5, 5.5))],
     [near((-13.5, 5.5), 4, asset="stop_sign_1"), on(["sidewalk", "ground"], asset="stop_sign_1"), only(assets=["stop_sign_1"])])
case("positioning", "erroneous", "typo_secnd_car_library", "put the secnd car from the left infront of the library entrence",
     [place("suv_1", where("in_front_of", "Library entrance"))],
     [near("Library entrance", 10, asset="suv_1"), relative("in_front_of", "Library entrance", asset="suv_1", max_distance=12),
      only(assets=["suv_1"])])
case("positioning", "erroneous", "typo_ego_campus_northbound", "plz put tha ego in lane campus_northbound, 20 m south of the crossroad",
     [place("ego", xy(1.75, -20.0), yaw_deg=90)],
     [in_lane("campus_northbound", asset="ego", aligned=True), near((1.75, -20.0), 8, asset="ego"), only(assets=["ego"])])
case("positioning", "erroneous", "typo_bench_and_bin_compound", "move teh bench to the fountian and the bin to the east gaet",
     [place("bench_1", where("next_to", "fountain")), place("trash_bin_1", where("at", "east gate"))],
     [near("fountain", 6, asset="bench_1"), near("east gate", 8, asset="trash_bin_1"),
      only(assets=["bench_1", "trash_bin_1"])], tags=C)
impossible("positioning", "erroneous", "typo_suv_on_jtekt_roof", "put the suv on the roof of teh JTEKT bulding",
           [place("suv_1", xy(37.5, 29.0))], "the roof is inside the building's footprint")
impossible("positioning", "erroneous", "carla_transform_off_map", "set_tranform(suv_1, x=250, y=0)",
           [place("suv_1", xy(250.0, 0.0))], "x = 250 is outside the world (x in [-110, 110])")

# --- moving ---------------------------------------------------------------------------------
case("moving", "direct", "power_mv_ego_fwd", "mv ego 5m fwd", [move("ego", forward=5)],
     [moved("ego", 4, 6, "forward"), only(assets=["ego"])])
case("moving", "direct", "carla_teleport_car_east", "Teleport passenger_car_2 3 m east.", [move("passenger_car_2", east=3)],
     [moved("passenger_car_2", 2.5, 3.5, "right"), only(assets=["passenger_car_2"])])
case("moving", "direct", "designer_rotate_bench", "Rotate the bench 90 degrees.", [move("bench_1", turn_deg=90)],
     [moved("bench_1", 0, 0.5, turn=(80, 100)), only(assets=["bench_1"])])
case("moving", "direct", "odd_suv_drive_eastbound_8", "Set the SUV to drive lane main_eastbound at 8 m/s.",
     [behave("suv_1", "drive_lane", lane="main_eastbound", speed=8)],
     [doing("drive_lane", asset="suv_1", lane="main_eastbound", speed_min=7.5, speed_max=8.5), only(assets=["suv_1"])])
case("moving", "direct", "l2_ego_go_backward", "Make the ego car to go 10 metres backward.", [move("ego", forward=-10)],
     [moved("ego", 9, 11, "backward"), only(assets=["ego"])])
case("moving", "direct", "turn_ego_face_west", "Turn the ego around to face west.", [move("ego", turn_deg=180)],
     [moved("ego", 0, 1, turn=(170, 180)), only(assets=["ego"])])

case("moving", "indirect", "ordinal_third_car_forward", "Nudge the third car from the west 2 m forward.",
     [move("passenger_car_2", forward=2)], [moved("passenger_car_2", 1.5, 2.5, "forward"), only(assets=["passenger_car_2"])])
case("moving", "indirect", "ramble_bin_back_toward_library",
     "so we did the run yesterday and the ego kept clipping the bin lol. anyway can you shift the bin a "
     "metre and a half back towards the library so there's more room?",
     [move("trash_bin_1", north=-1.5)], [moved("trash_bin_1", 1, 2, "right"), only(assets=["trash_bin_1"])])
case("moving", "indirect", "odd_ped_cross_north", "The VRU should cross the road at the north crosswalk.",
     [behave("pedestrian_1", "cross_road")],
     [doing("cross_road", "pedestrian", crosses_lane="campus_northbound"), only("pedestrian")],
     setup=[step("a pedestrian on the sidewalk at the north crosswalk", [add("pedestrian", 1, where("on_sidewalk", "north crosswalk"))])])
case("moving", "indirect", "carla_autopilot_southbound", "ego.set_autopilot(True), route: campus_southbound",
     [behave("ego", "drive_lane", lane="campus_southbound")],
     [doing("drive_lane", asset="ego", lane="campus_southbound"), only(assets=["ego"])])
case("moving", "indirect", "photo_suv_slow_loops", "For a sense of motion, have the SUV do slow loops in lot B.",
     [behave("suv_1", "circle", speed=2)],
     [doing("circle", asset="suv_1", speed_max=4, centre_near="parking lot B", centre_within=10), only(assets=["suv_1"])])
case("moving", "indirect", "compare_car_nearest_union_right", "Move the car that's closest to the Student Union 4 m to its right.",
     [move("passenger_car_2", left=-4)], [moved("passenger_car_2", 3.5, 4.5, "right"), only(assets=["passenger_car_2"])])
case("moving", "indirect", "bench_east_then_face_north", "Shift the bench 2 m east and turn it to face north.",
     [move("bench_1", east=2), move("bench_1", turn_deg=-90)],
     [moved("bench_1", 1.5, 2.5, turn=(80, 100)), only(assets=["bench_1"])], tags=C)
case("moving", "indirect", "planned_faster_car", "make it go faster, 12 m/s",
     [behave("passenger_car_3", "drive_lane", lane="main_westbound", speed=12)],
     [doing("drive_lane", "passenger_car", speed_min=11, speed_max=13), only("passenger_car")],
     setup=[step("spawn a car driving in lane main_westbound near the east gate",
                 [add("passenger_car", 1, where("in_lane", "east gate", lane="main_westbound"),
                      behaviour={"kind": "drive_lane", "lane": "main_westbound"})], planned=True)])

case("moving", "vague", "scoot_ego_up", "scoot the ego up a bit", [move("ego", forward=3)],
     [moved("ego", 0.5, 15, "forward"), only(assets=["ego"])])
case("moving", "vague", "get_bus_moving", "get that bus moving", [behave("bus_1", "drive_lane")],
     [doing("drive_lane", asset="bus_1"), only(assets=["bus_1"])], setup=[BUS_AT_STOP])
case("moving", "vague", "suv_drive_around", "make the SUV drive around",
     [behave("suv_1", "circle")], [doing(["drive_lane", "circle", "follow_path"], asset="suv_1"), only(assets=["suv_1"])])
case("moving", "vague", "designer_grid_snap_hydrant", "grid-snap the hydrant one tile north, a metre or so",
     [move("fire_hydrant_1", north=1)], [moved("fire_hydrant_1", 0.5, 3, "left"), only(assets=["fire_hydrant_1"])])
case("moving", "vague", "l2_car_of_middle_back", "The car of the middle in lot B, make it go a little back.",
     [move("suv_1", forward=-2)], [moved("suv_1", 0.5, 5, "backward"), only(assets=["suv_1"])])
case("moving", "vague", "photo_angle_ego", "the ego looks too squarely placed, angle it a little",
     [move("ego", turn_deg=15)], [moved("ego", 0, 1, turn=(3, 60)), only(assets=["ego"])])
impossible("moving", "vague", "bench_do_laps", "have the bench do laps around the quad",
           [behave("bench_1", "circle", centre="fountain")], "a bench cannot drive")

case("moving", "erroneous", "typo_mvoe_ego_foward", "mvoe the ego 10m foward", [move("ego", forward=10)],
     [moved("ego", 9, 11, "forward"), only(assets=["ego"])])
case("moving", "erroneous", "typo_trun_suv", "trun the suv 180 degres", [move("suv_1", turn_deg=180)],
     [moved("suv_1", 0, 1, turn=(170, 180)), only(assets=["suv_1"])])
case("moving", "erroneous", "l2_car_of_left_westbund", "make the car of the left in lot B drive on main_westbund",
     [behave("passenger_car_1", "drive_lane", lane="main_westbound")], [delta(["passenger_car", "suv"], 0), only("passenger_car")],
     alternatives=[[doing("drive_lane", asset="passenger_car_1", lane="main_westbound"), only(assets=["passenger_car_1"])],
                   [doing("drive_lane", asset="passenger_car_2", lane="main_westbound"), only(assets=["passenger_car_2"])]],
     notes="left as the cars face (west) or as seen from the road (east)")
case("moving", "erroneous", "typo_shfit_bin_left", "shfit the bin 2 m to the left", [move("trash_bin_1", left=2)],
     [moved("trash_bin_1", 1.5, 2.5, "left"), only(assets=["trash_bin_1"])])
case("moving", "erroneous", "typo_bik_cross_west", "make the bik cross at the west crosswalk",
     [behave("bicycle_1", "cross_road")],
     [doing("cross_road", "bicycle", crosses_lane="main_eastbound"), only("bicycle")],
     setup=[step("add a bicycle next to the stop sign", [add("bicycle", 1, where("next_to", "stop_sign_1"))])])
case("moving", "erroneous", "typo_ego_fwd_and_suv_turn", "move ego 3m frwd and trun the suv 90 deg",
     [move("ego", forward=3), move("suv_1", turn_deg=90)],
     [moved("ego", 2.5, 3.5, "forward"), moved("suv_1", 0, 0.5, turn=(80, 100)), only(assets=["ego", "suv_1"])], tags=C)
impossible("moving", "erroneous", "typo_ego_500m_east", "mov ego 500m east",
           [move("ego", east=500)], "500 m east is off the map (the campus is 220 m wide)")

# --- arrangement ----------------------------------------------------------------------------
case("arrangement", "direct", "line_cones_jtekt", "Arrange 5 traffic cones in a line in front of the JTEKT building entrance.",
     [arrange("traffic_cone", "line", where("in_front_of", "JTEKT building entrance"), count=5)],
     [delta("traffic_cone", 5), layout("line", "traffic_cone", 5), near("JTEKT building entrance", 10, "traffic_cone", scope="added"),
      only("traffic_cone")])
case("arrangement", "direct", "ring_benches_fountain", "Put 6 benches in a ring around the fountain, radius 5 m.",
     [arrange("bench", "ring", where("at", "fountain"), count=6, radius=5)],
     [delta("bench", 6), layout("ring", "bench", 6, around="fountain"), near("fountain", 7, "bench", scope="added"), only("bench")])
case("arrangement", "direct", "power_grid_cones_lot_a", "grid 3x3 cones @ lot A",
     [arrange("traffic_cone", "grid", where("at", "parking lot A"), count=9, columns=3)],
     [delta("traffic_cone", 9), layout("cluster", "traffic_cone", 9, tolerance=5), near("parking lot A", 1, "traffic_cone", scope="added"),
      only("traffic_cone")])
case("arrangement", "direct", "carla_parking_row_lot_a", "spawn 4 vehicle.sedan actors as a parking row in lot A",
     [arrange("passenger_car", "parking_row", where("at", "parking lot A"), count=4)],
     [delta("passenger_car", 4), layout("line", "passenger_car", 4), near("parking lot A", 1, "passenger_car", scope="added"),
      only("passenger_car")])
case("arrangement", "direct", "odd_lane_edge_cones_bus_stop",
     "Line the right edge of main_eastbound with 6 cones, starting at the bus stop.",
     [arrange("traffic_cone", "lane_edge", where("at", "bus stop", lane="main_eastbound"), count=6)],
     [delta("traffic_cone", 6), layout("line", "traffic_cone", 6), in_lane("main_eastbound", "traffic_cone"),
      near("bus stop", 20, "traffic_cone", scope="added"), only("traffic_cone")])
case("arrangement", "direct", "l2_line_bollards_lot_b_entrance", "Please make a line of 4 bollards at the parking lot B entrance.",
     [arrange("bollard", "line", where("at", "parking lot B entrance"), count=4)],
     [delta("bollard", 4), layout("line", "bollard", 4), near("parking lot B entrance", 8, "bollard", scope="added"), only("bollard")])

BLOCKERS = ["road_barrier", "traffic_cone", "bollard"]
case("arrangement", "indirect", "odd_close_lot_b_driveway", "Close the lot B driveway to traffic for the work zone.",
     [arrange("road_barrier", "line", where("at", "parking lot B entrance"), count=3)],
     [delta(BLOCKERS, 2, 10), layout("line", BLOCKERS, 2), near("parking lot B entrance", 8, BLOCKERS, scope="added"),
      only(*BLOCKERS)])
case("arrangement", "indirect", "designer_benches_round_fountain", "Set dressing for the quad: benches all the way round the fountain.",
     [arrange("bench", "ring", where("at", "fountain"), count=6, radius=5)],
     [delta("bench", 4, 16), layout("ring", "bench", 4, around="fountain"), only("bench")])
case("arrangement", "indirect", "ramble_row_three_cars_lot_b",
     "the shoot went great btw!! one thing, the car park looks kinda dead in the wide shot... could you park "
     "a row of three cars in lot B? next to the ones already there is fine",
     [arrange("passenger_car", "parking_row", where("at", "parking lot B"), count=3)],
     [delta(["passenger_car", "suv"], 3), layout("line", ["passenger_car", "suv"], 3),
      near("parking lot B", 1, ["passenger_car", "suv"], scope="added"), only("passenger_car", "suv")])
case("arrangement", "indirect", "photo_lead_the_eye_cones",
     "Lead the eye from the bus stop towards the west crosswalk with cones along the kerb of the eastbound lane.",
     [arrange("traffic_cone", "lane_edge", where("at", "bus stop", lane="main_eastbound"), count=6, spacing=3)],
     [delta("traffic_cone", 3, 12), layout("line", "traffic_cone", 3), in_lane("main_eastbound", "traffic_cone"),
      near("bus stop", 20, "traffic_cone", scope="added"), only("traffic_cone")])
case("arrangement", "indirect", "constraint_ring_rubble_max_six", "A ring of cones around the rubble, no more than 6 cones.",
     [arrange("traffic_cone", "ring", where("at", "cement_rubble_1"), count=6)],
     [delta("traffic_cone", 3, 6), layout("ring", "traffic_cone", 3, around="cement_rubble_1"), only("traffic_cone")],
     setup=[RUBBLE_ON_MAIN])
case("arrangement", "indirect", "loose_fence_library_dropoff", "Fence off the library drop-off with a row of fences.",
     [arrange("road_barrier", "line", where("in_front_of", "Library entrance"), count=4)],
     [delta("road_barrier", 2, 8), layout("line", "road_barrier", 2), near("Library entrance", 10, "road_barrier", scope="added"),
      only("road_barrier")])
case("arrangement", "indirect", "ordinal_cones_across_ahead_of_ego", "Line up four cones across the road 15 m ahead of the ego.",
     [arrange("traffic_cone", "line", where("in_front_of", "ego", distance=15), count=4)],
     [delta("traffic_cone", 4), layout("line", "traffic_cone", 4),
      relative("in_front_of", "ego", "traffic_cone", max_distance=20, tolerance_deg=20), only("traffic_cone")])
case("arrangement", "indirect", "work_zone_jtekt_compound",
     "Work zone at the JTEKT drop-off: a line of cones in front of the entrance plus a road-work sign next to it.",
     [arrange("traffic_cone", "line", where("in_front_of", "JTEKT building entrance"), count=5),
      add("construction_sign", 1, where("next_to", "JTEKT building entrance"))],
     [delta("construction_sign", 1), delta("traffic_cone", 3, 10), layout("line", "traffic_cone", 3),
      near("JTEKT building entrance", 10, ["traffic_cone", "construction_sign"], scope="added"),
      only("traffic_cone", "construction_sign")], tags=C)

case("arrangement", "vague", "cone_off_the_rubble", "cone off the rubble",
     [arrange("traffic_cone", "ring", where("at", "cement_rubble_1"))],
     [delta("traffic_cone", 3, 20), layout("ring", "traffic_cone", 3, around="cement_rubble_1"), only("traffic_cone")],
     setup=[RUBBLE_ON_MAIN])
case("arrangement", "vague", "row_of_bins_library_sidewalk", "a row of bins along the sidewalk by the library",
     [arrange("trash_bin", "line", where("on_sidewalk", "Library entrance"), count=4)],
     [delta("trash_bin", 3, 10), layout("line", "trash_bin", 3), near("Library entrance", 15, "trash_bin", scope="added"),
      only("trash_bin")])
case("arrangement", "vague", "designer_cars_in_row_lot_a", "some set dressing in lot A, cars in a row",
     [arrange("passenger_car", "parking_row", where("at", "parking lot A"))],
     [delta(["passenger_car", "suv"], 2, 10), layout("line", ["passenger_car", "suv"], 2),
      near("parking lot A", 1, ["passenger_car", "suv"], scope="added"), only("passenger_car", "suv")])
case("arrangement", "vague", "photo_symmetric_trees_engineering",
     "something symmetrical along the front of Engineering Hall, a line of trees maybe",
     [arrange("tree", "line", where("at", "Engineering Hall entrance"), count=5)],
     [delta("tree", 3, 9), layout("line", "tree", 3), near("Engineering Hall entrance", 15, "tree", scope="added"), only("tree")])
case("arrangement", "vague", "l2_cones_circle_around_bus", "Put some cones making a circle around the bus, please.",
     [arrange("traffic_cone", "ring", where("at", "bus_1"))],
     [delta("traffic_cone", 3, 40), layout("ring", "traffic_cone", 3, around="bus_1"), only("traffic_cone")],
     setup=[step("park a bus in lot B", [add("bus", 1, where("at", "parking lot B"))])])
case("arrangement", "vague", "barricade_north_crosswalk", "barricade the north crosswalk",
     [arrange("road_barrier", "line", where("at", "north crosswalk"), count=3)],
     [delta(BLOCKERS, 2, 12), layout("line", BLOCKERS, 2, tolerance=1.5), near("north crosswalk", 8, BLOCKERS, scope="added"),
      only(*BLOCKERS)])
case("arrangement", "vague", "busy_lot_a_compound", "make lot A look busy: a row of cars and a few people walking about",
     [arrange("passenger_car", "parking_row", where("at", "parking lot A"), count=4),
      add("pedestrian", 3, where("at", "parking lot A"))],
     [delta(["passenger_car", "suv"], 2, 10), layout("line", ["passenger_car", "suv"], 2), delta("pedestrian", 2, 8),
      near("parking lot A", 3, ["passenger_car", "suv", "pedestrian"], scope="added"),
      only("passenger_car", "suv", "pedestrian")], tags=C)
impossible("arrangement", "vague", "bench_grid_in_reading_room", "bench grid in the library's reading room, 2 by 3",
           [arrange("bench", "grid", xy(-41.0, -30.0), count=6, columns=2)], "the reading room is inside the library")

case("arrangement", "erroneous", "typo_line_cones_libary", "arange 5 cones in a lien infront of the libary",
     [arrange("traffic_cone", "line", where("in_front_of", "Library entrance"), count=5)],
     [delta("traffic_cone", 5), layout("line", "traffic_cone", 5), near("Library entrance", 10, "traffic_cone", scope="added"),
      only("traffic_cone")])
case("arrangement", "erroneous", "typo_ring_benchs_fountan", "ring of 6 benchs arround the fountan",
     [arrange("bench", "ring", where("at", "fountain"), count=6, radius=5)],
     [delta("bench", 6), layout("ring", "bench", 6, around="fountain"), only("bench")])
case("arrangement", "erroneous", "typo_parkng_row_suvs", "parkng row of 3 suvs in lot B pls",
     [arrange("suv", "parking_row", where("at", "parking lot B"), count=3)],
     [delta("suv", 3), layout("line", "suv", 3), near("parking lot B", 1, "suv", scope="added"), only("suv")])
case("arrangement", "erroneous", "typo_grid_bollards_east_gate", "make a grid off 4 bollards at the eest gate",
     [arrange("bollard", "grid", where("at", "east gate"), count=4, columns=2)],
     [delta("bollard", 4), layout("cluster", "bollard", 4, tolerance=3), near("east gate", 10, "bollard", scope="added"),
      only("bollard")])
case("arrangement", "erroneous", "typo_cones_and_benches_compound",
     "line of 4 cones infront of JTEKT and a ring of 6 benches around the fontain",
     [arrange("traffic_cone", "line", where("in_front_of", "JTEKT building entrance"), count=4),
      arrange("bench", "ring", where("at", "fountain"), count=6, radius=5)],
     [delta("traffic_cone", 4), delta("bench", 6), layout("line", "traffic_cone", 4), layout("ring", "bench", 6, around="fountain"),
      near("JTEKT building entrance", 10, "traffic_cone", scope="added"), only("traffic_cone", "bench")], tags=C)
case("arrangement", "erroneous", "l2_line_barrier_lot_a", "Please do a line of barrier at the entrence of lot A, 3 pieces.",
     [arrange("road_barrier", "line", where("at", "parking lot A entrance"), count=3)],
     [delta("road_barrier", 3), layout("line", "road_barrier", 3), near("parking lot A entrance", 8, "road_barrier", scope="added"),
      only("road_barrier")])
impossible("arrangement", "erroneous", "typo_ring_round_helipad", "put a ring of cones arround the helipad",
           [arrange("traffic_cone", "ring", where("at", "helipad"))], "the campus has no helipad")
impossible("arrangement", "erroneous", "typo_250_pylons", "line of 250 pylons down main stret",
           [arrange("traffic_cone", "lane_edge", where("in_lane", "main_eastbound"), count=250)],
           "a scene holds at most 200 traffic cones")

# --- appearance -----------------------------------------------------------------------------
case("appearance", "direct", "power_tod_dusk", "tod=dusk", [clock("dusk")],
     [env(time_from="18:30", time_to="21:00"), only(env=True)])
case("appearance", "direct", "odd_heavy_rain", "ODD condition: precipitation = rain, intensity heavy.", [weather("rain", 0.9)],
     [env(weather=["rain"], intensity_min=0.75), only(env=True)])
case("appearance", "direct", "carla_set_weather_fog", "world.set_weather(fog), density 0.5", [weather("fog", 0.5)],
     [env(weather=["fog"], intensity_min=0.4, intensity_max=0.6), only(env=True)])
case("appearance", "direct", "designer_suv_red", "Make the SUV red.", [look("suv_1", colour="red")],
     [colour("red", asset="suv_1"), only(assets=["suv_1"])])
case("appearance", "direct", "l2_switch_on_street_lights", "Please switch on the street lights.", [lights(street_lights="on")],
     [env(street_lights="on"), only(env=True)])
case("appearance", "direct", "paint_benches_blue", "Paint all the benches blue.", [look(category="bench", colour="blue")],
     [colour("blue", "bench", scope="all"), only("bench")])

case("appearance", "indirect", "photo_golden_hour", "Golden hour please, that warm light just before sunset.",
     [clock("18:45")], [env(time_from="17:00", time_to="19:45"), only(env=True)])
case("appearance", "indirect", "photo_moody_overcast_late", "Moody: overcast sky and a late-evening clock.",
     [weather("cloudy", 0.7), clock("21:30")],
     [env(weather=["cloudy"], time_from="19:00", time_to="23:59"), only(env=True)], tags=C)
case("appearance", "indirect", "odd_night_lights_failed", "ODD condition: night-time, street lighting failed.",
     [clock("22:00"), lights(street_lights="off")], [env(night=True, street_lights="off"), only(env=True)], tags=C)
case("appearance", "indirect", "ramble_ego_pink",
     "my kid says the ego looks boring lol, she wants it pink. fine by me honestly, I've got bigger problems, "
     "the render farm is down again",
     [look("ego", colour="pink")], [colour("pink", asset="ego"), only(assets=["ego"])])
case("appearance", "indirect", "ordinal_car_nearest_union_yellow", "Paint the car nearest the Student Union yellow.",
     [look("passenger_car_2", colour="yellow")], [colour("yellow", asset="passenger_car_2"), only(assets=["passenger_car_2"])])
case("appearance", "indirect", "slang_ego_black_cab", "Make the ego look like a London black cab.",
     [look("ego", colour="black")], [colour("black", asset="ego"), only(assets=["ego"])])
case("appearance", "indirect", "constraint_light_snow", "Make it snow, but keep it light, nothing over 0.3.",
     [weather("snow", 0.25)], [env(weather=["snow"], intensity_min=0.05, intensity_max=0.3), only(env=True)])
case("appearance", "indirect", "planned_school_bus_yellow", "make it school-bus yellow",
     [look("bus_1", colour="yellow")], [colour("yellow", "bus", min_count=1), delta("bus", 0), only("bus")],
     setup=[step("spawn a bus at the bus stop", [add("bus", 1, where("at", "bus stop"))], planned=True)])

case("appearance", "vague", "feel_like_winter", "make it feel like winter", [weather("snow", 0.5)],
     [env(weather=["snow"]), only(env=True)])
case("appearance", "vague", "darker_please", "darker please", [clock("21:00")], [only(env=True)],
     alternatives=[[env(night=True)], [env(exposure_max=0.9)], [env(time_from="19:00", time_to="06:30")]])
case("appearance", "vague", "photo_warmer_light", "warmer light", [clock("18:30")], [only(env=True)],
     alternatives=[[env(time_from="17:00", time_to="20:30")], [env(time_from="05:30", time_to="09:30")]],
     notes="low sun in the evening or the morning")
case("appearance", "vague", "cars_too_samey", "the cars in lot B look too samey",
     [look("passenger_car_1", colour="red")],
     [colour(None, ["passenger_car", "suv"], require_all=False, min_count=1), only("passenger_car", "suv")])
case("appearance", "vague", "rainy_ish", "make the scene rainy-ish", [weather("rain", 0.4)],
     [env(weather=["rain"]), only(env=True)])
case("appearance", "vague", "hi_vis_posts", "give those posts a hi-vis look",
     [look(category="bollard", colour="orange")], [colour(["orange", "yellow"], "bollard", scope="all"), only("bollard")],
     setup=[step("three bollards at the lot A entrance", [add("bollard", 3, where("at", "parking lot A entrance"))])])
case("appearance", "vague", "ramble_sunrise_and_fog",
     "ok last thing before I log off, the director wants that early misty morning feel, you know the one",
     [clock("06:30"), weather("fog", 0.5)],
     [env(weather=["fog"], time_from="05:00", time_to="09:00"), only(env=True)], tags=C)
impossible("appearance", "indirect", "sandstorm_weather", "ODD condition: sandstorm, visibility 50 m.",
           [weather("sandstorm", 0.8)], "the weather kinds are clear, cloudy, rain, fog and snow")

case("appearance", "erroneous", "typo_nite_time", "mak it nite time", [clock("night")], [env(night=True), only(env=True)])
case("appearance", "erroneous", "typo_suv_gren", "paint the suv gren", [look("suv_1", colour="green")],
     [colour("green", asset="suv_1"), only(assets=["suv_1"])])
case("appearance", "erroneous", "typo_stret_lights_on", "trun on the stret lights", [lights(street_lights="on")],
     [env(street_lights="on"), only(env=True)])
case("appearance", "erroneous", "typo_heavy_fog", "set wether to fogy, heavy", [weather("fog", 0.9)],
     [env(weather=["fog"], intensity_min=0.75), only(env=True)])
case("appearance", "erroneous", "typo_rain_and_7am", "make it rainy and set tiem to 7am", [weather("rain", 0.6), clock("07:00")],
     [env(weather=["rain"], time_from="06:45", time_to="07:15"), only(env=True)], tags=C)
case("appearance", "erroneous", "l2_five_of_afternoon_lamps_off", "Put the time on the 5 of the afternoon and do the lamps off.",
     [clock("17:00"), lights(street_lights="off")], [env(time_from="16:45", time_to="17:15", street_lights="off"), only(env=True)],
     tags=C)
case("appearance", "erroneous", "typo_traffic_lites_black", "paint both traffic lite poles black",
     [look("traffic_light_1", "traffic_light_2", colour="black")],
     [colour("black", "traffic_light", scope="all"), only("traffic_light")])
impossible("appearance", "erroneous", "typo_bench_infrared", "paint the bnech in infrared colour",
           [look("bench_1", colour="infrared")], "infrared is not a colour the renderer knows")


def write_suite(path: Path = SUITE_PATH) -> None:
    ids = [c["id"] for c in ALL_CASES]
    duplicates = sorted({i for i in ids if ids.count(i) > 1})
    if duplicates:
        raise ValueError(f"duplicate case ids: {duplicates}")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("".join(json.dumps(c, separators=(",", ":")) + "\n" for c in ALL_CASES), encoding="utf-8")


if __name__ == "__main__":
    write_suite()
    print(f"wrote {len(ALL_CASES)} cases to {SUITE_PATH}")
