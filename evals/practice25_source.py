"""The twenty-fifth practice suite: 307 cases in plain, everyday English from eight kinds of ordinary user, from the campus world alone.

`python -m drivetwin.evals.practice25_source` writes `suites/practice25.jsonl` (tag `practice25`, ids
`practice25.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`), none used by an earlier suite: a parent helping a child with a school
project ("My daughter wants a few people waiting where the shuttle stops", "She doesn't want the tree next to the
library in her picture", "Her project is about winter"), a city councillor ("Residents have asked for somewhere to sit
outside the building where the books are kept", "thin them out a little", "Make the student car park emptier"), an
insurance assessor reconstructing an incident ("the insured vehicle", "It happened in driving rain just after half past
five in the evening", "When the insured vehicle closes to within 15 metres of the car in front, have that car brake
hard"), a video-game modder ("spawn", "despawn", "tp", "NPC traffic", "do donuts in the car park", "night mode pls"), a
nurse on a break (short and friendly: "could you lose the seat by the shuttle stop", "make it feel like the end of a
late shift, about quarter to midnight"), a bus company dispatcher ("Line up three of our coaches nose to tail along the
kerb", "Get a bus out on the road", "where's the stop?"), a journalist (precise questions for facts and numbers: "Which
stretch of road is the test car on, and which way is it travelling?", "Of all the building doors, which one is closest
to where the two main roads cross?") and a newcomer to the software who asks whether and how ("Can I make the test car
back up 5 metres?", "How do I change how something looks? Could you make the rubbish bin the colour of a fire engine?").

Prompts describe things instead of naming them ("the tall boxy four-by-four", "the little red water post near the
crossroads", "the red octagonal sign by the western zebra crossing", "the leafy thing by the library", "the building
where the students buy their lunch", "the sedan nearest the union", "the signal pole on the north-east corner", "short
metal posts", "those orange road markers"), turn on negation and polarity ("She doesn't want...", "every parked car
except the big one", "the two saloon cars but leave the sport utility vehicle", "fewer trees", "make main street
busier", "emptier", "less fog", "slow our car down", "the weather nicer"), and name places and scopes (lanes, "the
opposing lane", "20 metres ahead of the test vehicle", "10 metres behind", "the south side of Main Street", "the other
side of the road", "the west car park", "the sedan on the left end of the row", "the lamp post closest to the Library's
front doors", "the furthest lamp from where the shuttle stops"). They carry clock times ("7:45 in the morning",
"17:20", "quarter to midnight", "eleven at night", "the moment the sun goes down", "first thing in the morning",
"0630", "quater past nine at night", "dusk"), weather with strengths (heavy rain, a light fog, moderate snow, a thick
layer of snow, a drizzle, "not to thick", "a bit harder than that"), numbers in words and digits with units (metres,
m/s, km/h: "three metres", "12 m/s", "about 7 km/h", "30 kmh", "90 degrees"), counts, questions (which must change
nothing: their checks hold the scene unchanged and their reference answers with a search), and behaviours: speeds,
braking at the bus stop, at the west crosswalk and for a lead car, a red light held, a car tailing the test car, lane
changes round cones and to overtake, left and right turns at the crossroads, crossings at a crosswalk, circling lot B,
and driving or walking to a place. The erroneous grade carries realistic typos and dropped words ("how mnay trees are
ther on the campus", "spwan 2 pedestrains at the north crosswalk", "delte all the street lihgts on the north side",
"put the suv 25m ahed of the insurd car in its lane", "prak 3 busses side by side in lot a", "make it nite and put the
headlihgts on").

Counts: 7 tasks x 4 grades, 10 to 12 cases in every cell (307 in all; search direct and erroneous and moving direct
and erroneous hold 12, addition vague, removal direct and erroneous, positioning indirect and vague hold 10, the rest
11). 38 cases are multi-turn (20 with a planned earlier turn that has calls), with references back: "it", "them",
"that van", "the one we just added", "another one like it", "how many did that put down?", corrections "Actually she
only wants one of those new benches", "No wait, put her over by the fountain instead". 22 are compound (two requests
in one prompt; the reference makes two calls or more), and 24 (7.8 %) impossible, tagged `impossible`, where the right
outcome is a refusal that changes nothing: the hospital, a bus depot, a coffee machine, a train station; a helicopter,
a hot-air balloon, two hundred cars at once, a tram; removing the Student Union building, Campus Drive, Main Street,
our own car (the ego); the SUV at x = 400 (off the map) or inside the Library, a bus that is not there; driving to the
hospital, a bus that is not there pulling away, a tree following the ego; fifteen buses in a row, tram tracks, a
helipad; 26:30, a sandstorm, a tornado.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with `alternatives`
where a request has two fair readings (a speed set on the lane behaviour or by a change-of-speed manoeuvre, a crossing
as a behaviour or a manoeuvre, backing up by a shift or a reverse manoeuvre, heading for the main gate in the lane or
along a path, any tree for shade, either sedan to the other car park, a cordon as a ring or a line, darker by weather,
clock or exposure, less fog or none, brighter by the clock, exposure or street lights), and a `reference` plan that
passes; a plan that does nothing fails every case that is not impossible, whether or not its earlier turns were done.
The suite was written from the campus world, the asset catalog, the Worker tools and the eval checks only, by someone
who had not read the planners, their lexicons, their prompt examples or any other suite's cases.
"""

from __future__ import annotations

from drivetwin.evals.practice_cases import (
    EGO,
    Json,
    Suite,
    add,
    ahead_of,
    arrange,
    behave,
    clock,
    count,
    delta,
    does,
    drive,
    env,
    environment,
    event,
    event_played,
    find,
    gone,
    hold,
    in_lane,
    kept,
    landmarks,
    lanes,
    layout,
    lighting,
    loc,
    looks,
    manoeuvre,
    measure,
    move,
    moved,
    near,
    on,
    only,
    paint,
    place,
    properties,
    reach,
    reaches,
    relative,
    remove,
    turn,
    weather,
    xy,
)

TAG = "practice25"
S = Suite(TAG)
case = S.case
impossible = S.impossible
ask = S.ask

# --- The campus as it ships: the ids and places the cases name -----------------------------------
SUV = "suv_1"  # the middle one of the three parked in lot B, all facing north
CAR1 = "passenger_car_1"  # the west sedan of that row
CAR2 = "passenger_car_2"  # the east sedan, nearest the Student Union and lot B's exit
BENCH = "bench_1"  # by the bus stop
BIN = "trash_bin_1"  # by the bus stop
HYDRANT = "fire_hydrant_1"  # north sidewalk of Main Street, just east of the crossroads
STOP = "stop_sign_1"  # south sidewalk, before the west crosswalk
LIGHT_WEST = "traffic_light_1"  # south-west corner of the crossroads; governs the eastbound lane
LIGHT_EAST = "traffic_light_2"  # north-east corner
TREE_LIBRARY = "tree_1"
TREE_FOUNTAIN = "tree_2"
TREE_QUAD = "tree_3"
TREE_LOT_A = "tree_4"
TREES = [TREE_LIBRARY, TREE_FOUNTAIN, TREE_QUAD, TREE_LOT_A]
NORTH_LAMPS = [f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11)]
SOUTH_LAMPS = [f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12)]
EAST = "main_eastbound"
WEST = "main_westbound"
NORTH = "campus_northbound"
SOUTH = "campus_southbound"
TRAFFIC = ["passenger_car", "suv", "bus", "truck", "motorcycle"]
PARKED_CARS = ["passenger_car", "suv"]
WORKS = ["traffic_cone", "road_barrier", "construction_sign", "cement_rubble", "bollard"]
CORDON = ["traffic_cone", "road_barrier", "bollard"]
BRIGHT = ["yellow", "orange", "red", "white", "pink", "cyan", "green", "gold", "blue"]

# --- Voices (each case names its own in `notes`) -----------------------------------------------------
PARENT = "parent helping a child with a school project: 'my daughter wants', 'for his model', explains why"
COUNCILLOR = "city councillor: residents, safety and the look of the street; measured, civic wording"
ASSESSOR = "insurance assessor reconstructing an incident: 'the insured vehicle', 'at the time', factual"
MODDER = "video-game modder: 'spawn', 'despawn', 'tp', 'NPC', 'prop'; casual and technical"
NURSE = "nurse on a break: short, friendly, a bit tired; 'quick one', 'could you just'"
DISPATCHER = "bus company dispatcher: buses, stops, lanes and timings; brisk, radio-like"
JOURNALIST = "journalist: precise questions for a story, wants facts, numbers and names"
NEWCOMER = "newcomer to the software: asks whether and how, many questions, polite"


# --- Earlier turns several cases start from -----------------------------------------------------------
def asked(step: Json) -> Json:
    """The same earlier turn, planned by the planner under test (its calls are only the reference)."""
    return {**step, "planned": True}


CONES_AHEAD = turn(
    "Put four cones in our lane roughly 25 metres in front of the test car.", add("traffic_cone", 4, ahead_of(EGO, 25))
)
RUBBLE_AHEAD = turn(
    "Drop a heap of broken concrete in the eastbound lane 30 metres ahead of our car.",
    add("cement_rubble", where=ahead_of(EGO, 30)),
)
RAIN_HARD = turn("Heavy rain, please.", weather("rain", 0.9))
FOG_THICK = turn("Thick fog over everything.", weather("fog", 0.9))
NIGHT = turn("Set the clock to ten at night.", clock("22:00"))
BUS_AT_STOP = turn(
    "Put a bus in the eastbound lane at the bus stop.", add("bus", where=loc("in_lane", "bus stop", lane=EAST))
)
WALKER_WEST = turn(
    "Add a pedestrian on the south corner of the west crosswalk.", add("pedestrian", where=xy(-11.5, -6.0))
)
WALKER_NORTH = turn(
    "Put a pedestrian on the pavement by the north crosswalk.",
    add("pedestrian", where=loc("on_sidewalk", "north crosswalk")),
)
WALKER_LIBRARY = turn(
    "Add a pedestrian outside the Library entrance.", add("pedestrian", where=loc("at", "Library entrance"))
)
BENCH_LIBRARY = turn(
    "Put a bench in front of the library.", add("bench", where=loc("in_front_of", "Library entrance"))
)
BENCH_FOUNTAIN = turn("Add a bench by the fountain.", add("bench", where=loc("next_to", "fountain")))
VAN_EAST_GATE = turn(
    "Add a broken-down van in the westbound lane by the east gate.",
    add("truck", where=loc("in_lane", "east gate", lane=WEST)),
)
SLOW_CAR_AHEAD = turn(
    "Add a car 30 metres ahead of the test car, driving east at 2 metres per second.",
    add("passenger_car", where=ahead_of(EGO, 30), behaviour=drive(2.0, EAST)),
)


def halts(actor: str, line: tuple[float, float], place: str, within: float, seconds: float = 20.0) -> Json:
    """Run the scene: `actor` never crosses `line` (a point it drives towards) and ends stopped, having come
    within `within` metres of `place` (so a stop on the spot, far short of it, does not count)."""
    return {
        "kind": "scenario",
        "seconds": seconds,
        "expect": [
            {"kind": "stopped_before", "actor": actor, "line": list(line)},
            {"kind": "reached", "actor": actor, "place": place, "within": within},
        ],
    }


def ego_speed(lo: float, hi: float) -> list[list[Json]]:
    """Fair readings of a new speed for the ego: on its lane behaviour, or by a change-of-speed manoeuvre."""
    return [
        [does("drive_lane", asset=EGO, speed_min=lo, speed_max=hi)],
        [event_played(EGO, "change_speed", 3.0)],
    ]


# --- Search: questions change nothing; the answer names what was asked for ---------------------------
SEARCH_CASES: list[Json] = [
    # direct
    ask("direct", "count_street_lights", JOURNALIST, "How many street lights are there on the campus?", ["12"],
        [find(category="street_light")]),
    ask("direct", "lamp_nearest_bus_stop", NEWCOMER, "Which lamp post is the closest one to the bus stop?",
        ["street_light_4"], [find(category="street_light", nearest_to="bus stop")]),
    ask("direct", "ego_to_library", ASSESSOR, "What is the distance between the test vehicle and the Library entrance right now?",
        ["23.2"], [measure("Library entrance")]),
    ask("direct", "suv_lane", DISPATCHER, "Which lane is the SUV in at the moment?", ["parking lot B"],
        [lanes(near=SUV)]),
    ask("direct", "weather_now", COUNCILLOR, "What is the weather set to at the moment?", ["clear"], [environment()]),
    ask("direct", "list_vehicles", MODDER, "List every vehicle in the scene.", [CAR1, CAR2, SUV],
        [find(category="vehicles")]),
    ask("direct", "scene_time", PARENT, "What time of day is it in the scene?", ["12:00"], [environment()]),
    ask("direct", "bench_near_stop", NURSE, "Is there a bench anywhere near the bus stop?", [BENCH],
        [find(category="bench", near="bus stop", within=15)]),
    impossible("search", "direct", "hospital_distance", JOURNALIST, "How far is the hospital from the main gate?",
               [measure("hospital", "main gate")]),
    ask("direct", "campus_drive_lanes", NEWCOMER, "What lanes does Campus Drive have?", [NORTH, SOUTH],
        [lanes(road="Campus Drive")]),
    ask("direct", "trees_and_nearest_fountain", JOURNALIST,
        "How many trees are there, and which one stands closest to the fountain?", ["4", TREE_FOUNTAIN],
        [find(category="tree"), find(category="tree", nearest_to="fountain")]),
    ask("direct", "place_nearest_hydrant", ASSESSOR, "Which named place is closest to the fire hydrant?",
        ["main intersection"], [landmarks(nearest_to=HYDRANT)]),
    # indirect
    ask("indirect", "furthest_lamp_from_shuttle", PARENT,
        "For his project he needs to know which of the tall road lamps is furthest from where the shuttle stops.",
        ["street_light_12"], [find(category="street_light", nearest_to="bus stop")]),
    ask("indirect", "car_park_for_union", DISPATCHER,
        "Which car park is nearest the building where the students buy their lunch?", ["parking lot B"],
        [landmarks(query="parking lot", nearest_to="Student Union entrance")]),
    ask("indirect", "ego_to_water_outlet", ASSESSOR,
        "How far is the insured vehicle from the water outlet the fire brigade would connect to?", ["76.3"],
        [measure(HYDRANT)]),
    ask("indirect", "seat_near_shuttle", NURSE, "Anywhere to sit down near where the shuttle picks people up?",
        [BENCH], [find(category="bench", near="bus stop", within=15)]),
    ask("indirect", "npc_cars_in_south_lot", MODDER,
        "How many NPC cars are sitting in the car park south of Main Street, and which ones?", [CAR1, CAR2, SUV],
        [find(category="vehicles", near="parking lot B", within=1)]),
    ask("indirect", "ego_road_and_direction", JOURNALIST,
        "Which stretch of road is the test car on, and which way is it travelling?", [EAST],
        [lanes(near=EGO)]),
    ask("indirect", "entrance_nearest_junction", COUNCILLOR,
        "Of all the building doors, which one is closest to where the two main roads cross?",
        ["JTEKT building entrance"], [landmarks(query="entrance", nearest_to="main intersection")]),
    ask("indirect", "count_halt_signs", NEWCOMER,
        "How many of the red eight-sided signs that tell drivers to halt are there?", ["1", STOP],
        [find(category="stop_sign")]),
    ask("indirect", "books_to_engineering", PARENT,
        "How far apart are the front doors of the book building and the engineering building?", ["30.0"],
        [measure("Library entrance", "Engineering Hall entrance")]),
    impossible("search", "indirect", "depot_to_stop", DISPATCHER,
               "How far is it from our bus depot to the stop on Main Street?", [measure("bus depot", "bus stop")]),
    ask("indirect", "signal_nearest_insured", ASSESSOR,
        "Which of the red-amber-green signal poles is closest to the car we are testing?", [LIGHT_WEST],
        [find(category="traffic_light", nearest_to=EGO)]),
    # vague
    ask("vague", "anywhere_to_sit", NURSE, "anything to sit on round here?", [BENCH],
        [find(category="bench", nearest_to=EGO)]),
    ask("vague", "props_at_crossroads", MODDER, "what props are around the crossroads?", [LIGHT_WEST, LIGHT_EAST],
        [find(near="main intersection", within=8)]),
    ask("vague", "dark_yet", COUNCILLOR, "Is it dark yet?", ["12:00"], [environment()], any_of=["day"]),
    ask("vague", "about_middle_car", JOURNALIST, "What can you tell me about the big car in the middle of that row?",
        [SUV], [properties(asset=SUV)], any_of=["2100", "parked"]),
    ask("vague", "where_stop", DISPATCHER, "where's the stop?", ["bus stop"], [landmarks(query="bus stop")]),
    ask("vague", "car_to_junction", PARENT, "how far is our car from the big junction?", [],
        [measure("main intersection")], any_of=["60.0", "51.0"]),
    ask("vague", "near_me", NEWCOMER, "What's close to my car at the moment?", ["street_light_2"],
        [find(nearest_to=EGO, within=25)]),
    ask("vague", "how_many_cones_then", MODDER, "how many did that put down?", ["4"],
        [find(category="traffic_cone")], setup=[asked(CONES_AHEAD)]),
    ask("vague", "closest_bin", ASSESSOR, "Where's the closest bin?", [BIN],
        [find(category="trash_bin", nearest_to=EGO)]),
    impossible("search", "vague", "coffee_machine", NURSE, "where's the nearest coffee machine?",
               [find(category="coffee machine", nearest_to=EGO)]),
    ask("vague", "time_and_weather", MODDER, "what's the time and weather like?", ["12:00", "clear"],
        [environment()]),
    # erroneous
    ask("erroneous", "count_trees_typos", JOURNALIST, "how mnay trees are ther on the campus", ["4"],
        [find(category="tree")]),
    ask("erroneous", "lamp_near_library_typos", NEWCOMER, "whcih lamp is closet to the libary?", ["street_light_4"],
        [find(category="street_light", nearest_to="Library entrance")]),
    ask("erroneous", "stop_to_east_gate_typos", DISPATCHER, "distnace from bus stpo to east gate?", ["130.1"],
        [measure("bus stop", "east gate")]),
    ask("erroneous", "stop_to_both_gates_typos", DISPATCHER,
        "how far is the bus stop from the east gate, and from the main gaet?", ["130.1", "70.2"],
        [measure("bus stop", "east gate"), measure("bus stop", "main gate")]),
    ask("erroneous", "raining_typos", NURSE, "is it rainnig out?", ["clear"], [environment()]),
    ask("erroneous", "our_lane_typos", PARENT, "wat lane is are car in", [EAST], [lanes(near=EGO)]),
    ask("erroneous", "cars_lot_b_typos", MODDER, "list all teh parked cars in lot b", [CAR1, CAR2, SUV],
        [find(category="vehicles", near="parking lot B", within=1)]),
    ask("erroneous", "sign_to_crosswalk_typos", ASSESSOR, "how far from the stop sing to the west crosswlak",
        ["5.9"], [measure(STOP, "west crosswalk")]),
    ask("erroneous", "count_benches_typos", COUNCILLOR, "how many benchs are there in total", ["1", BENCH],
        [find(category="bench")]),
    impossible("search", "erroneous", "train_station_typos", JOURNALIST,
               "how far is the trian station from the main gate", [measure("train station", "main gate")]),
    ask("erroneous", "still_raining_typos", NURSE, "is it stil raining hard?", ["rain"], [environment()],
        setup=[RAIN_HARD]),
    ask("erroneous", "bus_lane_typos", DISPATCHER, "wich lane is the bus in", [EAST], [lanes(near="bus_1")],
        setup=[asked(BUS_AT_STOP)]),
]

# --- Addition: new things where and as asked ------------------------------------------------------------
ADDITION_CASES: list[Json] = [
    # direct
    case("addition", "direct", "walkers_outside_library", MODDER,
         "Spawn three pedestrians on the sidewalk outside the library.",
         [delta("pedestrian", 3, 3), near("Library entrance", 15, "pedestrian", every=True),
          on(["sidewalk"], "pedestrian"), only("pedestrian")],
         [add("pedestrian", 3, loc("on_sidewalk", "Library entrance"))]),
    case("addition", "direct", "two_benches_fountain", PARENT, "Please add two benches next to the fountain.",
         [delta("bench", 2, 2), near("fountain", 10, "bench", every=True), only("bench")],
         [add("bench", 2, loc("next_to", "fountain"))]),
    case("addition", "direct", "bus_at_stop", DISPATCHER, "Put a bus in the eastbound lane at the bus stop.",
         [delta("bus", 1, 1), in_lane(EAST, "bus"), near("bus stop", 12, "bus"), only("bus")],
         [add("bus", where=loc("in_lane", "bus stop", lane=EAST))]),
    case("addition", "direct", "stop_sign_north_crossing", COUNCILLOR,
         "Add a stop sign on the pavement beside the north crosswalk.",
         [delta("stop_sign", 1, 1), near("north crosswalk", 10, "stop_sign"), on(["sidewalk"], "stop_sign"),
          only("stop_sign")],
         [add("stop_sign", where=loc("on_sidewalk", "north crosswalk"))]),
    case("addition", "direct", "silver_sedan_east_10", ASSESSOR,
         "Add a silver sedan driving east along Main Street at 10 metres per second.",
         [delta("passenger_car", 1, 1), does("drive_lane", "passenger_car", lane=EAST, speed_min=9.5, speed_max=10.5),
          looks("silver", "passenger_car"), only("passenger_car")],
         [add("passenger_car", behaviour=drive(10.0, EAST), colour="silver")]),
    case("addition", "direct", "bin_beside_bench", NURSE, "Add a wheelie bin beside the bench at the bus stop.",
         [delta("trash_bin", 1, 1), near(BENCH, 3, "trash_bin", scope="added"), only("trash_bin")],
         [add("trash_bin", where=loc("next_to", BENCH))]),
    case("addition", "direct", "motorbike_lot_a", NEWCOMER, "Can you add a motorbike in parking lot A?",
         [delta("motorcycle", 1, 1), near("parking lot A", 1, "motorcycle"), only("motorcycle")],
         [add("motorcycle", where=loc("at", "parking lot A"))]),
    case("addition", "direct", "five_cyclists_north", JOURNALIST,
         "Add five cyclists riding north up Campus Drive.",
         [delta("bicycle", 5, 5), does("drive_lane", "bicycle", lane=NORTH, min_count=5), only("bicycle")],
         [add("bicycle", 5, loc("in_lane", "main intersection", lane=NORTH), behaviour=drive(lane=NORTH))]),
    impossible("addition", "direct", "helicopter_roof", MODDER, "Spawn a helicopter on the roof of the JTEKT Building.",
               [add("helicopter", where=loc("at", "JTEKT Building"))]),
    case("addition", "direct", "cones_and_sign_library", COUNCILLOR,
         "Add two cones and a roadworks sign in front of the library.",
         [delta("traffic_cone", 2, 2), delta("construction_sign", 1, 1),
          near("Library entrance", 15, ["traffic_cone", "construction_sign"], every=True),
          only("traffic_cone", "construction_sign")],
         [add("traffic_cone", 2, loc("in_front_of", "Library entrance")),
          add("construction_sign", where=loc("in_front_of", "Library entrance"))]),
    case("addition", "direct", "tree_engineering", PARENT, "Add a tree in front of the Engineering Hall entrance.",
         [delta("tree", 1, 1), near("Engineering Hall entrance", 8, "tree", scope="added"), only("tree")],
         [add("tree", where=loc("in_front_of", "Engineering Hall entrance"))]),
    # indirect
    case("addition", "indirect", "people_waiting_shuttle", PARENT,
         "My daughter wants a few people waiting where the shuttle stops. Three would be perfect.",
         [delta("pedestrian", 3, 3), near("bus stop", 10, "pedestrian", every=True), only("pedestrian")],
         [add("pedestrian", 3, loc("on_sidewalk", "bus stop"))]),
    case("addition", "indirect", "bus_and_waiting_people", PARENT,
         "For his model, could there be a bus at the stop and a couple of people waiting to get on it?",
         [delta("bus", 1, 1), delta("pedestrian", 2, 2), near("bus stop", 12, ["bus", "pedestrian"], every=True),
          only("bus", "pedestrian")],
         [add("bus", where=loc("in_lane", "bus stop", lane=EAST)), add("pedestrian", 2, loc("on_sidewalk", "bus stop"))]),
    case("addition", "indirect", "seat_outside_books", COUNCILLOR,
         "Residents have asked for somewhere to sit outside the building where the books are kept.",
         [delta("bench", 1, 1), near("Library entrance", 10, "bench", scope="added"), only("bench")],
         [add("bench", where=loc("in_front_of", "Library entrance"))]),
    case("addition", "indirect", "lorry_opposite_lane", ASSESSOR,
         "Place a goods lorry standing in the opposing lane, about 30 metres ahead of the insured vehicle.",
         [delta("truck", 1, 1), in_lane(WEST, "truck"), near(None, 8, "truck", point=(-30.0, 1.75)), only("truck")],
         [add("truck", where=ahead_of(EGO, 30, lane=WEST))]),
    case("addition", "indirect", "markers_at_bumper", MODDER,
         "drop a couple of those orange road markers right in front of our car's bumper",
         [delta("traffic_cone", 2, 2), relative("in_front_of", EGO, "traffic_cone", max_distance=15, every=True),
          only("traffic_cone")],
         [add("traffic_cone", 2, loc("in_front_of", EGO))]),
    case("addition", "indirect", "coach_west_car_park", DISPATCHER,
         "I need one of our long passenger vehicles parked in the car park at the west end of Main Street.",
         [delta("bus", 1, 1), near("parking lot A", 1, "bus"), only("bus")],
         [add("bus", where=loc("at", "parking lot A"))]),
    case("addition", "indirect", "push_bike_union", NURSE, "pop a push bike by the doors of the union building",
         [delta("bicycle", 1, 1), near("Student Union entrance", 8, "bicycle"), only("bicycle")],
         [add("bicycle", where=loc("at", "Student Union entrance"))]),
    case("addition", "indirect", "four_by_four_student_lot", JOURNALIST,
         "Add a big four-wheel-drive parked in the student car park.",
         [delta("suv", 1, 1), near("parking lot B", 1, "suv", scope="added"), only("suv")],
         [add("suv", where=loc("at", "parking lot B"))]),
    case("addition", "indirect", "p_sign_lot_a", NEWCOMER,
         "Is it possible to add one of those signs with a big P on it, near where cars drive into lot A?",
         [delta("parking_sign", 1, 1), near("parking lot A entrance", 8, "parking_sign"), only("parking_sign")],
         [add("parking_sign", where=loc("at", "parking lot A entrance"))]),
    impossible("addition", "indirect", "balloon_over_fountain", PARENT,
               "For his project could you float a hot-air balloon above the fountain?",
               [add("hot_air_balloon", where=loc("at", "fountain"))]),
    case("addition", "indirect", "bin_next_to_new_bench", COUNCILLOR, "Now put a bin right next to the one you added.",
         [delta("trash_bin", 1, 1), near("bench_2", 3, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("next_to", "bench_2"))], setup=[asked(BENCH_FOUNTAIN)]),
    # vague
    case("addition", "vague", "some_npc_traffic", MODDER, "make main street busier, spawn some NPC traffic",
         [delta(TRAFFIC, 2, None), does("drive_lane", TRAFFIC, min_count=2), only(*TRAFFIC)],
         [add("passenger_car", 3, loc("in_lane", "main gate", lane=EAST), behaviour=drive(lane=EAST))]),
    case("addition", "vague", "few_more_people", PARENT, "can we have a few more people about?",
         [delta("pedestrian", 2, 8), only("pedestrian")],
         [add("pedestrian", 3, loc("on_sidewalk", "main intersection"))]),
    case("addition", "vague", "fill_union_lot", COUNCILLOR,
         "The car park by the union looks deserted; fill it up a bit.",
         [delta(PARKED_CARS, 2, None), near("parking lot B", 1, PARKED_CARS, scope="added", every=True),
          only(*PARKED_CARS)],
         [add("passenger_car", 3, loc("at", "parking lot B"))]),
    case("addition", "vague", "bench_fountain_maybe", NURSE, "could do with a bench near the fountain",
         [delta("bench", 1, 2), near("fountain", 12, "bench", scope="added"), only("bench")],
         [add("bench", where=loc("next_to", "fountain"))]),
    case("addition", "vague", "bus_on_road", DISPATCHER, "Get a bus out on the road.",
         [delta("bus", 1, 1), only("bus")],
         [add("bus", behaviour=drive(lane=EAST))],
         alternatives=[[does("drive_lane", "bus")], [in_lane(None, "bus")]]),
    case("addition", "vague", "roadworks_junction", JOURNALIST, "Add a bit of roadwork near the junction.",
         [delta(WORKS, 1, None), near("main intersection", 20, WORKS, every=True), only(*WORKS)],
         [add("construction_sign", where=loc("at", "main intersection")),
          add("traffic_cone", 3, loc("at", "main intersection"))]),
    case("addition", "vague", "someone_walking", NEWCOMER, "Could I get someone walking around somewhere?",
         [delta("pedestrian", 1, 3), does(["follow_path", "cross_road", "jaywalk"], "pedestrian"), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "bus stop"), behaviour={"kind": "follow_path", "to": "Library entrance"})]),
    case("addition", "vague", "car_behind_ours", ASSESSOR, "Put another car behind ours.",
         [delta(PARKED_CARS, 1, 1), relative("behind", EGO, PARKED_CARS, max_distance=20), only(*PARKED_CARS)],
         [add("passenger_car", where=loc("behind", EGO))]),
    impossible("addition", "vague", "two_hundred_cars", MODDER, "spawn like two hundred cars everywhere",
               [add("passenger_car", 200)]),
    case("addition", "vague", "another_like_it", PARENT, "and another one like it next to it",
         [delta("passenger_car", 1, 1), near("passenger_car_3", 5, "passenger_car", scope="added"),
          looks("red", "passenger_car", scope="added"), only("passenger_car")],
         [add("passenger_car", where=loc("next_to", "passenger_car_3"), colour="red")],
         setup=[asked(turn("Add a red car in lot A.", add("passenger_car", where=loc("at", "parking lot A"), colour="red")))]),
    # erroneous
    case("addition", "erroneous", "bench_library_typos", NURSE, "add a bench outsde the libary pls",
         [delta("bench", 1, 1), near("Library entrance", 10, "bench", scope="added"), only("bench")],
         [add("bench", where=loc("in_front_of", "Library entrance"))]),
    case("addition", "erroneous", "walkers_north_crossing_typos", MODDER, "spwan 2 pedestrains at the north crosswalk",
         [delta("pedestrian", 2, 2), near("north crosswalk", 8, "pedestrian", every=True), only("pedestrian")],
         [add("pedestrian", 2, loc("on_sidewalk", "north crosswalk"))]),
    case("addition", "erroneous", "bus_lot_b_typos", DISPATCHER, "pu a bus in lot B, parkd",
         [delta("bus", 1, 1), near("parking lot B", 1, "bus"), only("bus")],
         [add("bus", where=loc("at", "parking lot B"))]),
    case("addition", "erroneous", "three_trees_fountain_typos", PARENT, "add thre trees near the fountian",
         [delta("tree", 3, 3), near("fountain", 15, "tree", scope="added", every=True), only("tree")],
         [add("tree", 3, loc("next_to", "fountain"))]),
    case("addition", "erroneous", "truck_west_typos", JOURNALIST, "add a truk driving west at 8 m/s",
         [delta("truck", 1, 1), does("drive_lane", "truck", lane=WEST, speed_min=7.5, speed_max=8.5), only("truck")],
         [add("truck", behaviour=drive(8.0, WEST))]),
    case("addition", "erroneous", "crossing_sign_typos", COUNCILLOR, "ad a pedestrain crossing sign by the west crosswalk",
         [delta("pedestrian_sign", 1, 1), near("west crosswalk", 10, "pedestrian_sign"), only("pedestrian_sign")],
         [add("pedestrian_sign", where=loc("on_sidewalk", "west crosswalk"))]),
    case("addition", "erroneous", "motorbike_ahead_typos", ASSESSOR,
         "place a motorbkie 15 m ahaed of the insured vehcle in its lane",
         [delta("motorcycle", 1, 1), in_lane(EAST, "motorcycle"), near(None, 4, "motorcycle", point=(-45.0, -1.75)),
          only("motorcycle")],
         [add("motorcycle", where=ahead_of(EGO, 15))]),
    case("addition", "erroneous", "cone_east_gate_typos", NEWCOMER, "how do i add a cone? could yo put one at the east gate",
         [delta("traffic_cone", 1, 1), near("east gate", 8, "traffic_cone"), only("traffic_cone")],
         [add("traffic_cone", where=loc("at", "east gate"))]),
    case("addition", "erroneous", "truck_lot_a_night_typos", MODDER, "spawn a truck in lot a and make it nigth",
         [delta("truck", 1, 1), near("parking lot A", 1, "truck"), env(night=True), only("truck", env=True)],
         [add("truck", where=loc("at", "parking lot A")), clock("night")]),
    impossible("addition", "erroneous", "tram_typos", DISPATCHER, "add a tram runing down main stret",
               [add("tram", behaviour=drive(lane=EAST))]),
    case("addition", "erroneous", "two_more_cones_typos", ASSESSOR, "ad two more of thme next to the others",
         [delta("traffic_cone", 2, 2), near("traffic_cone_1", 8, "traffic_cone", scope="added", every=True),
          only("traffic_cone")],
         [add("traffic_cone", 2, loc("next_to", "traffic_cone_1"))], setup=[CONES_AHEAD]),
]

# --- Removal: what was meant goes, everything else stays -------------------------------------------------
CONES_NORTH = turn("Add three cones at the north crosswalk.", add("traffic_cone", 3, loc("at", "north crosswalk")))
BENCHES_FOUNTAIN = turn("Add two benches by the fountain.", add("bench", 2, loc("next_to", "fountain")))
WALKERS_LIBRARY = turn("Add four pedestrians near the library.", add("pedestrian", 4, loc("on_sidewalk", "Library entrance")))
BARRIERS_EAST_GATE = turn("Add two barriers at the east gate.", add("road_barrier", 2, loc("at", "east gate")))

REMOVAL_CASES: list[Json] = [
    # direct
    case("removal", "direct", "bench_bus_stop", COUNCILLOR, "Remove the bench at the bus stop.",
         [gone(BENCH), only("bench")], [remove(BENCH)]),
    case("removal", "direct", "despawn_car_2", MODDER, "Despawn passenger_car_2.",
         [gone(CAR2), kept(CAR1, SUV), only(assets=[CAR2])], [remove(CAR2)]),
    case("removal", "direct", "bin_bus_stop", NURSE, "Could you take away the bin by the bus stop?",
         [gone(BIN), only("trash_bin")], [remove(BIN)]),
    case("removal", "direct", "stop_sign_west", ASSESSOR, "Remove the stop sign before the west crosswalk.",
         [gone(STOP), only("stop_sign")], [remove(STOP)]),
    case("removal", "direct", "all_cars_lot_b", DISPATCHER, "Remove all the parked cars from lot B.",
         [gone(CAR1, SUV, CAR2), only(*PARKED_CARS)], [remove(CAR1, SUV, CAR2)]),
    case("removal", "direct", "tree_by_library", PARENT, "She doesn't want the tree next to the library in her picture. Please remove it.",
         [gone(TREE_LIBRARY), kept(TREE_FOUNTAIN, TREE_QUAD, TREE_LOT_A), only("tree")], [remove(TREE_LIBRARY)]),
    case("removal", "direct", "hydrant_and_rain", JOURNALIST, "Remove the fire hydrant and make it rain lightly.",
         [gone(HYDRANT), env(weather=["rain"], intensity_min=0.1, intensity_max=0.45), only("fire_hydrant", env=True)],
         [remove(HYDRANT), weather("rain", 0.3)]),
    impossible("removal", "direct", "union_building", COUNCILLOR, "Remove the Student Union building.",
               [remove("Student Union")]),
    case("removal", "direct", "remove_them_cones", NEWCOMER, "How do I get rid of them now? Please remove those cones.",
         [delta("traffic_cone", -3, -3), only("traffic_cone")],
         [remove("traffic_cone_1", "traffic_cone_2", "traffic_cone_3")], setup=[asked(CONES_NORTH)]),
    case("removal", "direct", "south_side_lamps", MODDER, "Delete every street light on the south side of Main Street.",
         [gone(*SOUTH_LAMPS), kept(*NORTH_LAMPS), only("street_light")], [remove(*SOUTH_LAMPS)]),
    # indirect
    case("removal", "indirect", "little_red_water_post", PARENT,
         "Could you take out the little red water post near the crossroads? It spoils her drawing.",
         [gone(HYDRANT), only("fire_hydrant")], [remove(HYDRANT)]),
    case("removal", "indirect", "octagon_by_zebra", COUNCILLOR,
         "Take down the red octagonal sign by the western zebra crossing.",
         [gone(STOP), only("stop_sign")], [remove(STOP)]),
    case("removal", "indirect", "boxy_four_by_four", DISPATCHER,
         "Clear the tall boxy four-by-four out of the student car park.",
         [gone(SUV), kept(CAR1, CAR2), only("suv")], [remove(SUV)]),
    case("removal", "indirect", "saloons_not_suv", ASSESSOR,
         "Remove the two saloon cars but leave the sport utility vehicle where it is.",
         [gone(CAR1, CAR2), kept(SUV), only("passenger_car")], [remove(CAR1, CAR2)]),
    case("removal", "indirect", "seat_and_bin_stop", NURSE, "could you take the seat and the bin away from the shuttle stop",
         [gone(BENCH, BIN), only("bench", "trash_bin")], [remove(BENCH), remove(BIN)]),
    case("removal", "indirect", "seat_shuttle_stop", NURSE, "could you lose the seat by the shuttle stop",
         [gone(BENCH), only("bench")], [remove(BENCH)]),
    case("removal", "indirect", "signal_north_east", MODDER, "delete the signal pole on the north-east corner of the junction",
         [gone(LIGHT_EAST), kept(LIGHT_WEST), only("traffic_light")], [remove(LIGHT_EAST)]),
    case("removal", "indirect", "lamp_closest_library", JOURNALIST,
         "Remove the lamp post that stands closest to the Library's front doors.",
         [gone("street_light_4"), delta("street_light", -1, -1), only("street_light")],
         [remove(category="street_light", near="Library entrance", count=1)]),
    case("removal", "indirect", "all_greenery", NEWCOMER,
         "Is there a way to take out all the greenery? I'd like every tree gone, please.",
         [gone(*TREES), only("tree")], [remove(category="tree")]),
    impossible("removal", "indirect", "campus_drive_road", DISPATCHER,
               "Take Campus Drive out altogether, we're rerouting the buses.", [remove(NORTH, SOUTH)]),
    case("removal", "indirect", "only_one_bench", PARENT,
         "Actually she only wants one of those new benches; take the other one away.",
         [delta("bench", -1, -1), kept(BENCH), count("bench", 2, 2), only("bench")],
         [remove("bench_3")], setup=[asked(BENCHES_FOUNTAIN)]),
    # vague
    case("removal", "vague", "thin_out_lamps", COUNCILLOR, "There are too many lamp posts on this road; thin them out a little.",
         [delta("street_light", -9, -1), only("street_light")],
         [remove("street_light_3", "street_light_7", "street_light_10")]),
    case("removal", "vague", "despawn_npc_cars", MODDER, "despawn all the NPC cars",
         [gone(CAR1, SUV, CAR2), only(*PARKED_CARS)], [remove(CAR1, SUV, CAR2)]),
    case("removal", "vague", "that_bin", NURSE, "get rid of that bin", [gone(BIN), only("trash_bin")], [remove(BIN)]),
    case("removal", "vague", "clear_road_ahead", DISPATCHER, "Clear the road in front of the test car.",
         [delta("traffic_cone", -4, -4), only("traffic_cone")],
         [remove(category="traffic_cone")], setup=[CONES_AHEAD]),
    case("removal", "vague", "cones_gone_lights_on", COUNCILLOR,
         "Those cones can go now, and let's have the street lights on.",
         [delta("traffic_cone", -4, -4), env(street_lights="on"), only("traffic_cone", env=True)],
         [remove(category="traffic_cone"), lighting(street_lights="on")], setup=[CONES_AHEAD]),
    case("removal", "vague", "fewer_trees", PARENT, "fewer trees please, there are too many for her drawing",
         [delta("tree", -3, -1), only("tree")], [remove(TREE_QUAD, TREE_LOT_A)]),
    case("removal", "vague", "most_parked_keep_big", JOURNALIST, "Take away every parked car except the big one.",
         [gone(CAR1, CAR2), kept(SUV), only("passenger_car")], [remove(CAR1, CAR2)]),
    case("removal", "vague", "whatever_blocks_lane", ASSESSOR, "Remove whatever is blocking the eastbound lane.",
         [gone("cement_rubble_1"), only("cement_rubble")], [remove("cement_rubble_1")], setup=[RUBBLE_AHEAD]),
    case("removal", "vague", "undo_people", NEWCOMER, "Can I take the people back off again? Just remove them, please.",
         [delta("pedestrian", -4, -4), only("pedestrian")], [remove(category="pedestrian")],
         setup=[asked(WALKERS_LIBRARY)]),
    impossible("removal", "vague", "despawn_own_car", MODDER, "despawn our own car, don't need it", [remove(EGO)]),
    case("removal", "vague", "emptier_car_park", COUNCILLOR, "Make the student car park emptier.",
         [delta(PARKED_CARS, None, -1), only(*PARKED_CARS)], [remove(CAR1, CAR2)]),
    # erroneous
    case("removal", "erroneous", "tree_fountain_typos", NURSE, "remvoe the tree by the fountian",
         [gone(TREE_FOUNTAIN), kept(TREE_LIBRARY, TREE_QUAD, TREE_LOT_A), only("tree")], [remove(TREE_FOUNTAIN)]),
    case("removal", "erroneous", "suv_typos", MODDER, "despwan the suv", [gone(SUV), only("suv")], [remove(SUV)]),
    case("removal", "erroneous", "bench_shuttle_typos", DISPATCHER, "take awya the bench next to teh shuttle stop",
         [gone(BENCH), only("bench")], [remove(BENCH)]),
    case("removal", "erroneous", "north_lamps_typos", PARENT, "delte all the street lihgts on the north side",
         [gone(*NORTH_LAMPS), kept(*SOUTH_LAMPS), only("street_light")], [remove(*NORTH_LAMPS)]),
    case("removal", "erroneous", "both_signals_typos", JOURNALIST, "remove both trafic lights",
         [gone(LIGHT_WEST, LIGHT_EAST), only("traffic_light")], [remove(LIGHT_WEST, LIGHT_EAST)]),
    case("removal", "erroneous", "hydrant_typos", COUNCILLOR, "get rid of teh fire hydarnt",
         [gone(HYDRANT), only("fire_hydrant")], [remove(HYDRANT)]),
    case("removal", "erroneous", "sedans_keep_suv_typos", ASSESSOR, "remov the two sedans in lot B, keep the suv",
         [gone(CAR1, CAR2), kept(SUV), only("passenger_car")], [remove(CAR1, CAR2)]),
    impossible("removal", "erroneous", "main_street_typos", NEWCOMER, "can you remove main stret?", [remove("Main Street")]),
    case("removal", "erroneous", "bus_away_typos", DISPATCHER, "take the buss away agian",
         [gone("bus_1"), delta("bus", -1, -1), only("bus")], [remove("bus_1")], setup=[BUS_AT_STOP]),
    case("removal", "erroneous", "one_barrier_typos", MODDER, "remvoe one of the barriers",
         [delta("road_barrier", -1, -1), only("road_barrier")], [remove("road_barrier_2")],
         setup=[asked(BARRIERS_EAST_GATE)]),
]

# --- Positioning: an existing thing put at a named place -------------------------------------------------
WALKER_STOP = turn("Add a pedestrian at the bus stop.", add("pedestrian", where=loc("on_sidewalk", "bus stop")))
VAN_LOT_A = turn("Add a white van parked in lot A.", add("truck", where=loc("at", "parking lot A"), colour="white"))
BIKE_LOT_A = turn("spawn a motorbike in lot A", add("motorcycle", where=loc("at", "parking lot A")))
SHADE = [TREE_LIBRARY, TREE_FOUNTAIN, TREE_QUAD, TREE_LOT_A]

POSITIONING_CASES: list[Json] = [
    # direct
    case("positioning", "direct", "suv_to_lot_a", MODDER, "Teleport suv_1 to parking lot A.",
         [near("parking lot A", 1, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    case("positioning", "direct", "two_sedans_two_places", DISPATCHER,
         "Put passenger_car_1 in lot A and passenger_car_2 in the eastbound lane at the bus stop.",
         [near("parking lot A", 1, asset=CAR1), in_lane(EAST, asset=CAR2), near("bus stop", 12, asset=CAR2),
          only(assets=[CAR1, CAR2])],
         [place(CAR1, loc("at", "parking lot A")), place(CAR2, loc("in_lane", "bus stop", lane=EAST))]),
    case("positioning", "direct", "bench_engineering", COUNCILLOR, "Put the bench in front of the Engineering Hall entrance.",
         [near("Engineering Hall entrance", 8, asset=BENCH), moved(BENCH, 5), only(assets=[BENCH])],
         [place(BENCH, loc("in_front_of", "Engineering Hall entrance"))]),
    case("positioning", "direct", "car1_westbound_stop", DISPATCHER,
         "Put passenger_car_1 in the westbound lane opposite the bus stop.",
         [in_lane(WEST, asset=CAR1), near("bus stop", 12, asset=CAR1), only(assets=[CAR1])],
         [place(CAR1, loc("in_lane", "bus stop", lane=WEST))]),
    case("positioning", "direct", "suv_20_ahead", ASSESSOR,
         "Place the SUV 20 metres ahead of the test vehicle, in the same lane.",
         [in_lane(EAST, asset=SUV), near(None, 4, asset=SUV, point=(-40.0, -1.75)), only(assets=[SUV])],
         [place(SUV, ahead_of(EGO, 20))]),
    case("positioning", "direct", "bin_to_library", NURSE, "Move the bin over to the library entrance, would you?",
         [near("Library entrance", 5, asset=BIN), moved(BIN, 3), only(assets=[BIN])],
         [place(BIN, loc("at", "Library entrance"))]),
    case("positioning", "direct", "hydrant_jtekt", PARENT, "Put the fire hydrant on the sidewalk by the JTEKT entrance.",
         [near("JTEKT building entrance", 10, asset=HYDRANT), on(["sidewalk"], asset=HYDRANT), moved(HYDRANT, 3),
          only(assets=[HYDRANT])],
         [place(HYDRANT, loc("on_sidewalk", "JTEKT building entrance"))]),
    case("positioning", "direct", "car2_east_gate", JOURNALIST, "Place passenger_car_2 at the east gate, in the westbound lane.",
         [in_lane(WEST, asset=CAR2), near("east gate", 12, asset=CAR2), only(assets=[CAR2])],
         [place(CAR2, loc("in_lane", "east gate", lane=WEST))]),
    impossible("positioning", "direct", "suv_off_map", MODDER, "teleport the SUV to x 400, y 0", [place(SUV, xy(400, 0))]),
    case("positioning", "direct", "stop_sign_north", NEWCOMER, "Can you put the stop sign next to the north crosswalk instead?",
         [near("north crosswalk", 8, asset=STOP), only(assets=[STOP])],
         [place(STOP, loc("on_sidewalk", "north crosswalk"))]),
    case("positioning", "direct", "her_to_north_crosswalk", PARENT, "Now put her by the north crosswalk.",
         [near("north crosswalk", 8, asset="pedestrian_1"), only("pedestrian")],
         [place("pedestrian_1", loc("on_sidewalk", "north crosswalk"))], setup=[asked(WALKER_STOP)]),
    # indirect
    case("positioning", "indirect", "seat_to_books", PARENT,
         "Move the seat from the shuttle stop to just outside the building with all the books.",
         [near("Library entrance", 8, asset=BENCH), moved(BENCH, 3), only(assets=[BENCH])],
         [place(BENCH, loc("in_front_of", "Library entrance"))]),
    case("positioning", "indirect", "four_by_four_behind_insured", ASSESSOR,
         "Reposition the big four-by-four so it sits in the eastbound lane just behind the insured vehicle.",
         [relative("behind", EGO, asset=SUV, max_distance=15), in_lane(EAST, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("behind", EGO))]),
    case("positioning", "indirect", "litter_bin_union", DISPATCHER, "Move the litter bin up to the doors of the union building.",
         [near("Student Union entrance", 6, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", "Student Union entrance"))]),
    case("positioning", "indirect", "water_outlet_engineering", COUNCILLOR,
         "Relocate the outlet the firefighters draw water from to the pavement outside the engineering building.",
         [near("Engineering Hall entrance", 10, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("on_sidewalk", "Engineering Hall entrance"))]),
    case("positioning", "indirect", "sedan_near_union_east_gate", MODDER,
         "tp the sedan that's closest to the union over to the westbound lane by the east gate",
         [in_lane(WEST, asset=CAR2), near("east gate", 12, asset=CAR2), only(assets=[CAR2])],
         [place(CAR2, loc("in_lane", "east gate", lane=WEST))]),
    case("positioning", "indirect", "leafy_thing_to_fountain", NURSE, "put the leafy thing by the library over near the fountain",
         [near("fountain", 10, asset=TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
         [place(TREE_LIBRARY, loc("next_to", "fountain"))]),
    case("positioning", "indirect", "octagon_to_north_crossing", JOURNALIST,
         "Set the octagonal sign up at the northern zebra crossing instead.",
         [near("north crosswalk", 8, asset=STOP), only(assets=[STOP])],
         [place(STOP, loc("on_sidewalk", "north crosswalk"))]),
    case("positioning", "indirect", "middle_car_west_lot", NEWCOMER,
         "How would I move the car that's parked between the two sedans? Could you put it in the west car park?",
         [near("parking lot A", 1, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    impossible("positioning", "indirect", "suv_inside_library", ASSESSOR,
               "Position the SUV where the claimant says it was: x -40, y -30, which is inside the Library building.",
               [place(SUV, xy(-40, -30))]),
    case("positioning", "indirect", "that_van_behind_insured", ASSESSOR,
         "Now put that van in the eastbound lane, 10 metres behind the insured vehicle.",
         [in_lane(EAST, "truck"), near(None, 5, "truck", point=(-70.0, -1.75)), only("truck")],
         [place("truck_1", loc("behind", EGO, along_m=10))], setup=[asked(VAN_LOT_A)]),
    # vague
    case("positioning", "vague", "bench_in_shade", NURSE, "move the bench somewhere shady",
         [moved(BENCH, 1), only(assets=[BENCH])], [place(BENCH, loc("next_to", TREE_LIBRARY))],
         alternatives=[[near(t, 3, asset=BENCH)] for t in SHADE]),
    case("positioning", "vague", "stop_sign_other_side", COUNCILLOR,
         "The stop sign is in a silly spot; put it somewhere on the other side of the road.",
         [on(["sidewalk"], asset=STOP), near(None, 8, asset=STOP, point=(-13.5, 5.5)), moved(STOP, 8), only(assets=[STOP])],
         [place(STOP, xy(-14.0, 5.5))]),
    case("positioning", "vague", "suv_anywhere_on_road", MODDER, "yeet the SUV onto the road somewhere",
         [in_lane(None, asset=SUV), moved(SUV, 5), only(assets=[SUV])],
         [place(SUV, loc("in_lane", "main intersection", lane=WEST))]),
    case("positioning", "vague", "sedan_near_exit_to_stop", DISPATCHER, "Get the sedan nearest the exit over by the stop.",
         [near("bus stop", 12, asset=CAR2), only(assets=[CAR2])], [place(CAR2, loc("in_lane", "bus stop", lane=EAST))]),
    case("positioning", "vague", "bin_nearer_fountain", PARENT, "Can the bin go nearer the fountain?",
         [near("fountain", 10, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", "fountain"))]),
    case("positioning", "vague", "hydrant_near_library", JOURNALIST, "Put the hydrant somewhere near the library instead.",
         [near("Library entrance", 12, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("on_sidewalk", "Library entrance"))]),
    case("positioning", "vague", "bench_closer_crossroads", NEWCOMER, "Could the bench go a bit closer to the crossroads?",
         [near("main intersection", 12, asset=BENCH), moved(BENCH, 3), only(assets=[BENCH])],
         [place(BENCH, xy(-14.0, -7.5))]),
    case("positioning", "vague", "suv_in_path", ASSESSOR, "Put the SUV up front, in the insured vehicle's path.",
         [relative("in_front_of", EGO, asset=SUV, max_distance=30, tolerance_deg=20), in_lane(EAST, asset=SUV),
          only(assets=[SUV])],
         [place(SUV, loc("in_front_of", EGO))]),
    case("positioning", "vague", "no_wait_fountain", PARENT, "No wait, put her over by the fountain instead.",
         [near("fountain", 8, asset="pedestrian_1"), moved("pedestrian_1", 5), only("pedestrian")],
         [place("pedestrian_1", loc("next_to", "fountain"))], setup=[WALKER_LIBRARY]),
    case("positioning", "vague", "car_somewhere_lot_a", DISPATCHER, "Shift one of the sedans across to the other car park.",
         [only(*PARKED_CARS)], [place(CAR1, loc("at", "parking lot A"))],
         alternatives=[[near("parking lot A", 1, asset=c)] for c in (CAR1, CAR2)]),
    # erroneous
    case("positioning", "erroneous", "bin_library_door_typos", NURSE, "put the bin by the libary door",
         [near("Library entrance", 5, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", "Library entrance"))]),
    case("positioning", "erroneous", "suv_lot_a_typos", MODDER, "tp suv to prking lot A",
         [near("parking lot A", 1, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    case("positioning", "erroneous", "sedan_eastbound_stop_typos", DISPATCHER,
         "put the sdan nearest teh union in the eastbond lane at the bus stop",
         [in_lane(EAST, asset=CAR2), near("bus stop", 12, asset=CAR2), only(assets=[CAR2])],
         [place(CAR2, loc("in_lane", "bus stop", lane=EAST))]),
    case("positioning", "erroneous", "bench_fountain_typos", PARENT, "put the bench infront of the fountian",
         [near("fountain", 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("in_front_of", "fountain"))]),
    case("positioning", "erroneous", "hydrant_library_typos", COUNCILLOR, "move the hydrnat to the sidewlk near the library",
         [near("Library entrance", 12, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("on_sidewalk", "Library entrance"))]),
    case("positioning", "erroneous", "stop_sign_north_typos", JOURNALIST, "place the stop sing at the north crosswak",
         [near("north crosswalk", 8, asset=STOP), only(assets=[STOP])],
         [place(STOP, loc("on_sidewalk", "north crosswalk"))]),
    case("positioning", "erroneous", "suv_25_ahead_typos", ASSESSOR, "put the suv 25m ahed of the insurd car in its lane",
         [in_lane(EAST, asset=SUV), near(None, 4, asset=SUV, point=(-35.0, -1.75)), only(assets=[SUV])],
         [place(SUV, ahead_of(EGO, 25))]),
    case("positioning", "erroneous", "library_tree_engineering_typos", NEWCOMER,
         "can u put the tre by the libary next to the engineering hall entrace",
         [near("Engineering Hall entrance", 10, asset=TREE_LIBRARY), only(assets=[TREE_LIBRARY])],
         [place(TREE_LIBRARY, loc("in_front_of", "Engineering Hall entrance"))]),
    case("positioning", "erroneous", "bench_and_bin_fountain_typos", NEWCOMER,
         "move the bench to the fountian and the bin next to it",
         [near("fountain", 8, asset=BENCH), near(BENCH, 3, asset=BIN), moved(BIN, 5), only(assets=[BENCH, BIN])],
         [place(BENCH, loc("next_to", "fountain")), place(BIN, loc("next_to", BENCH))]),
    impossible("positioning", "erroneous", "no_bus_typos", DISPATCHER, "put the bus at the bus stpo",
               [place("bus_1", loc("in_lane", "bus stop", lane=EAST))]),
    case("positioning", "erroneous", "motorbike_east_gate_typos", MODDER, "now tp it to the east gaet in the westbond lane",
         [in_lane(WEST, "motorcycle"), near("east gate", 12, "motorcycle"), only("motorcycle")],
         [place("motorcycle_1", loc("in_lane", "east gate", lane=WEST))], setup=[asked(BIKE_LOT_A)]),
]

# --- Moving: shifts, turns and behaviours (speeds, braking, following, turning, crossing, going places) ----
CAR_EAST_GATE = turn("Spawn a car in the westbound lane near the east gate.",
                         add("passenger_car", where=loc("in_lane", "east gate", lane=WEST)))
STOPS_AT_BUS_STOP = halts(EGO, (-29.0, -1.75), "bus stop", 7.0)
STOPS_AT_WEST_CROSSING = halts(EGO, (-13.0, -1.75), "west crosswalk", 8.0)
LEAD_BRAKES = event("passenger_car_3", "stop", {"kind": "distance", "actor": EGO, "other": "passenger_car_3", "metres": 15},
                    rate=6.0)

MOVING_CASES: list[Json] = [
    # direct
    case("moving", "direct", "suv_three_forward", MODDER, "Move suv_1 three metres forward.",
         [moved(SUV, 2.5, 3.5, "forward"), only(assets=[SUV])], [move(SUV, forward=3)]),
    case("moving", "direct", "ego_12_ms", ASSESSOR, "Set the insured vehicle's speed to 12 m/s.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=12.0, lane=EAST)], alternatives=ego_speed(11.5, 12.5)),
    case("moving", "direct", "stop_at_bus_stop", DISPATCHER, "Have the test car stop at the bus stop.",
         [STOPS_AT_BUS_STOP, only()], [event(EGO, "stop", reach("bus stop"))]),
    case("moving", "direct", "suv_drive_westbound", NURSE, "Make the SUV drive in the westbound lane.",
         [does("drive_lane", asset=SUV, lane=WEST), only(assets=[SUV])], [behave(SUV, "drive_lane", lane=WEST)]),
    case("moving", "direct", "bench_turn_90", COUNCILLOR, "Turn the bench by the bus stop 90 degrees.",
         [moved(BENCH, 0, 0.5, turn_min=80, turn_max=100), only(assets=[BENCH])], [move(BENCH, turn_deg=90)]),
    case("moving", "direct", "ego_left_at_crossroads", PARENT, "Make the test car turn left at the crossroads.",
         [event_played(EGO, "junction_turn", 2.0), only()], [manoeuvre(EGO, "junction_turn", turn="left")]),
    case("moving", "direct", "car1_north_6", JOURNALIST, "Make passenger_car_1 drive north along Campus Drive at 6 m/s.",
         [does("drive_lane", asset=CAR1, lane=NORTH, speed_min=5.5, speed_max=6.5), only(assets=[CAR1])],
         [behave(CAR1, "drive_lane", lane=NORTH, speed=6.0)]),
    case("moving", "direct", "ego_back_5", NEWCOMER, "Can I make the test car back up 5 metres?",
         [only(assets=[EGO])], [move(EGO, forward=-5)],
         alternatives=[[moved(EGO, 4, 6, "backward")], [event_played(EGO, "reverse", 3.0)]]),
    case("moving", "direct", "sedan_to_lot_b_exit", NEWCOMER,
         "Can a car drive somewhere by itself? Have passenger_car_2 drive to the lot B entrance.",
         [does("follow_path", asset=CAR2), reaches(CAR2, "parking lot B entrance", 20.0, within=4.0), only(assets=[CAR2])],
         [behave(CAR2, "follow_path", to="parking lot B entrance")]),
    case("moving", "direct", "ego_two_left", ASSESSOR, "Move the ego vehicle 2 metres to its left.",
         [moved(EGO, 1.5, 2.5, "left"), only(assets=[EGO])], [move(EGO, left=2)]),
    case("moving", "direct", "walk_him_across", PARENT, "Make him walk across it.",
         [only("pedestrian")], [behave("pedestrian_1", "cross_road")],
         alternatives=[[does("cross_road", "pedestrian", crosses_lane=EAST)], [event_played("pedestrian", "cross_road", 3.0)]],
         setup=[asked(turn("Put a pedestrian on the south side of the west crosswalk.",
                           add("pedestrian", where=xy(-11.5, -6.0))))]),
    case("moving", "direct", "suv_and_car2_speeds", DISPATCHER,
         "Send the SUV east along Main Street at 7 m/s and passenger_car_2 west at 5 m/s.",
         [does("drive_lane", asset=SUV, lane=EAST, speed_min=6.5, speed_max=7.5),
          does("drive_lane", asset=CAR2, lane=WEST, speed_min=4.5, speed_max=5.5), only(assets=[SUV, CAR2])],
         [behave(SUV, "drive_lane", lane=EAST, speed=7.0), behave(CAR2, "drive_lane", lane=WEST, speed=5.0)]),
    # indirect
    case("moving", "indirect", "lead_car_brakes", ASSESSOR,
         "When the insured vehicle closes to within 15 metres of the car in front, have that car brake hard.",
         [event_played("passenger_car_3", "stop", 20.0), only()], [LEAD_BRAKES], setup=[SLOW_CAR_AHEAD]),
    case("moving", "indirect", "four_by_four_to_west_gate", DISPATCHER,
         "Get the four-by-four out on Main Street heading for the main gate.",
         [does(["drive_lane", "follow_path"], asset=SUV), only(assets=[SUV])], [behave(SUV, "drive_lane", lane=WEST)],
         alternatives=[[does("drive_lane", asset=SUV, lane=WEST)], [does("follow_path", asset=SUV)]]),
    case("moving", "indirect", "crawl_7_kmh", NURSE, "make our car crawl along at about 7 km/h",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=2.0, lane=EAST)], alternatives=ego_speed(1.5, 2.5)),
    case("moving", "indirect", "donuts_sedan_union", MODDER,
         "make the sedan nearest the union do donuts in the car park",
         [does("circle", asset=CAR2, centre_near="parking lot B"), only(assets=[CAR2])], [behave(CAR2, "circle")]),
    case("moving", "indirect", "turn_towards_union", COUNCILLOR,
         "Have the test car take the turning towards the Student Union side when it reaches the crossroads.",
         [event_played(EGO, "junction_turn", 2.0), only()], [manoeuvre(EGO, "junction_turn", turn="right")]),
    case("moving", "indirect", "stroll_to_library", PARENT, "Her little figure should stroll over to the library doors.",
         [does("follow_path", "pedestrian"), reaches("pedestrian", "Library entrance", 20.0, within=4.0),
          only("pedestrian")],
         [behave("pedestrian_1", "follow_path", to="Library entrance")], setup=[asked(WALKER_STOP)]),
    case("moving", "indirect", "left_sedan_up_campus_drive", JOURNALIST,
         "The sedan on the left end of the row should pull out and drive up Campus Drive towards the engineering building.",
         [does("drive_lane", asset=CAR1, lane=NORTH), only(assets=[CAR1])], [behave(CAR1, "drive_lane", lane=NORTH)]),
    case("moving", "indirect", "wait_at_red", NEWCOMER,
         "Is there a way to make our car wait at the lights? Keep the signal on our side at red.",
         [STOPS_AT_WEST_CROSSING, only()], [hold(LIGHT_WEST, "red")]),
    impossible("moving", "indirect", "drive_to_hospital", ASSESSOR,
               "Have the insured vehicle drive to the hospital car park, as the claimant says it did.",
               [behave(EGO, "follow_path", to="hospital")]),
    case("moving", "indirect", "tail_our_car", MODDER, "have the four-by-four tail our car down Main Street",
         [does("drive_lane", asset=SUV, lane=EAST), relative("behind", EGO, asset=SUV, max_distance=25, tolerance_deg=20),
          only(assets=[SUV])],
         [place(SUV, loc("behind", EGO, along_m=12)), behave(SUV, "drive_lane", lane=EAST, speed=5.0)]),
    case("moving", "indirect", "swing_round_cones", DISPATCHER,
         "Have our car swing out into the other lane before it gets to them.",
         [event_played(EGO, "lane_change", 3.0), only()], [manoeuvre(EGO, "lane_change", side="left", at_time=1.0)],
         setup=[CONES_AHEAD]),
    # vague
    case("moving", "vague", "get_suv_moving", MODDER, "get the SUV moving",
         [does(["drive_lane", "circle", "follow_path"], asset=SUV), only(assets=[SUV])],
         [behave(SUV, "drive_lane", lane=EAST)]),
    case("moving", "vague", "slow_ours_down", NURSE, "slow our car down a bit", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=3.0, lane=EAST)], alternatives=ego_speed(0.5, 4.5)),
    case("moving", "vague", "speed_test_car_up", DISPATCHER, "Speed the test car up.", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=8.0, lane=EAST)], alternatives=ego_speed(6.0, 40.0)),
    case("moving", "vague", "get_them_across", COUNCILLOR, "Can we get them across the road?", [only("pedestrian")],
         [behave("pedestrian_1", "cross_road")], setup=[WALKER_NORTH],
         alternatives=[[does(["cross_road", "jaywalk"], "pedestrian")], [event_played("pedestrian", "cross_road", 3.0)]]),
    case("moving", "vague", "wiggle_right", PARENT, "Can the car nudge over a little to the right?",
         [moved(EGO, 0.3, 2.0, "right"), only(assets=[EGO])], [move(EGO, left=-1)]),
    case("moving", "vague", "livelier_sedans", JOURNALIST, "Liven things up: get both parked sedans driving.",
         [does("drive_lane", "passenger_car", min_count=2), only(assets=[CAR1, CAR2])],
         [behave(CAR1, "drive_lane", lane=NORTH), behave(CAR2, "drive_lane", lane=EAST)]),
    case("moving", "vague", "back_up_little", ASSESSOR, "Back the insured car up a little.", [only(assets=[EGO])],
         [move(EGO, forward=-3)], alternatives=[[moved(EGO, 0.5, 10, "backward")], [event_played(EGO, "reverse", 3.0)]]),
    case("moving", "vague", "turn_somewhere", NEWCOMER, "How do turns work? Make our car turn somewhere, please.",
         [event_played(EGO, "junction_turn", 2.0), only()], [manoeuvre(EGO, "junction_turn", turn="left")]),
    impossible("moving", "vague", "bus_pull_away", DISPATCHER, "Have the bus pull away from the stop.",
               [behave("bus_1", "drive_lane", lane=EAST)]),
    case("moving", "vague", "make_it_go", MODDER, "ok make it go", [does("drive_lane", "passenger_car"), only("passenger_car")],
         [behave("passenger_car_3", "drive_lane", lane=WEST)], setup=[asked(CAR_EAST_GATE)]),
    case("moving", "vague", "bench_turn_round", PARENT, "Turn the bench round the other way.",
         [moved(BENCH, 0, 0.5, turn_min=150), only(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    # erroneous
    case("moving", "erroneous", "ego_30_kmh_typos", NURSE, "mkae our car go 30 kmh", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=8.33, lane=EAST)], alternatives=ego_speed(7.8, 8.9)),
    case("moving", "erroneous", "suv_four_forward_typos", MODDER, "move teh suv 4 metres fowrad",
         [moved(SUV, 3.5, 4.5, "forward"), only(assets=[SUV])], [move(SUV, forward=4)]),
    case("moving", "erroneous", "right_at_junction_typos", DISPATCHER, "test car turn rigth at the junciton",
         [event_played(EGO, "junction_turn", 2.0), only()], [manoeuvre(EGO, "junction_turn", turn="right")]),
    case("moving", "erroneous", "stop_west_crosswalk_typos", ASSESSOR, "have the insurd vehicle stop at the west crosswlak",
         [STOPS_AT_WEST_CROSSING, only()], [event(EGO, "stop", reach("west crosswalk"))]),
    case("moving", "erroneous", "car1_north_typos", PARENT, "make passenger car 1 drive nroth on campus drive",
         [does("drive_lane", asset=CAR1, lane=NORTH), only(assets=[CAR1])], [behave(CAR1, "drive_lane", lane=NORTH)]),
    case("moving", "erroneous", "bench_45_typos", JOURNALIST, "turn the benchh 45 degres",
         [moved(BENCH, 0, 0.5, turn_min=40, turn_max=50), only(assets=[BENCH])], [move(BENCH, turn_deg=45)]),
    case("moving", "erroneous", "ego_3_ms_typos", COUNCILLOR, "slow the test car to 3 metres a secnd", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=3.0, lane=EAST)], alternatives=ego_speed(2.5, 3.5)),
    case("moving", "erroneous", "suv_circles_typos", NEWCOMER, "can the suv drive in circels in lot b?",
         [does("circle", asset=SUV, centre_near="parking lot B"), only(assets=[SUV])], [behave(SUV, "circle")]),
    case("moving", "erroneous", "faster_and_right_typos", ASSESSOR,
         "speed the insured car up to 10 m/s and have it turn rigth at the junction",
         [event_played(EGO, "junction_turn", 2.0), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=10.0, lane=EAST), manoeuvre(EGO, "junction_turn", turn="right")],
         alternatives=ego_speed(9.5, 10.5)),
    impossible("moving", "erroneous", "tree_follow_typos", MODDER, "make teh tree by the libary follow the ego",
               [behave(TREE_LIBRARY, "follow_path", to=EGO)]),
    case("moving", "erroneous", "walk_across_typos", NURSE, "make her walk accross the road", [only("pedestrian")],
         [behave("pedestrian_1", "cross_road")], setup=[WALKER_WEST],
         alternatives=[[does(["cross_road", "jaywalk"], "pedestrian", crosses_lane=EAST)],
                       [event_played("pedestrian", "cross_road", 3.0)]]),
    case("moving", "erroneous", "overtake_typos", ASSESSOR, "make are car chnage lane to overtake it",
         [event_played(EGO, "lane_change", 3.0), only()], [manoeuvre(EGO, "lane_change", side="left", at_time=1.0)],
         setup=[asked(SLOW_CAR_AHEAD)]),
]

# --- Arrangement: several new things laid out as a line, a ring, a row or a cluster -----------------------
TRUCK_AHEAD = turn("Add a broken-down lorry in our lane 35 metres ahead of the test car.",
                   add("truck", where=ahead_of(EGO, 35)))
RUBBLE_WEST = turn("Add a pile of rubble in the westbound lane near the east gate.",
                   add("cement_rubble", where=loc("in_lane", "east gate", lane=WEST)))

ARRANGEMENT_CASES: list[Json] = [
    # direct
    case("arrangement", "direct", "six_cones_across_30", COUNCILLOR,
         "Put a line of six cones across the eastbound lane 30 metres ahead of the test car.",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6),
          near(None, 8, "traffic_cone", point=(-30.0, -1.75), every=True), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("in_front_of", EGO, along_m=30), count=6)]),
    case("arrangement", "direct", "ring_8_bollards_fountain", MODDER, "Spawn a ring of 8 bollards around the fountain.",
         [delta("bollard", 8, 8), layout("ring", "bollard", 8, around="fountain"), only("bollard")],
         [arrange("bollard", "ring", loc("at", "fountain"), count=8)]),
    case("arrangement", "direct", "three_buses_lot_a", DISPATCHER, "Park a row of three buses side by side in lot A.",
         [delta("bus", 3, 3), layout("line", "bus", 3), near("parking lot A", 1, "bus", every=True), only("bus")],
         [arrange("bus", "parking_row", loc("at", "parking lot A"), count=3)]),
    case("arrangement", "direct", "ten_cones_westbound", PARENT,
         "Line the westbound lane with ten cones, starting at the east gate.",
         [delta("traffic_cone", 10, 10), layout("line", "traffic_cone", 10), in_lane(WEST, "traffic_cone"),
          only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "east gate", lane=WEST), count=10)]),
    case("arrangement", "direct", "three_barriers_jtekt", ASSESSOR,
         "Put three road barriers in a line in front of the JTEKT entrance.",
         [delta("road_barrier", 3, 3), layout("line", "road_barrier", 3),
          near("JTEKT building entrance", 12, "road_barrier", every=True), only("road_barrier")],
         [arrange("road_barrier", "line", loc("in_front_of", "JTEKT building entrance"), count=3)]),
    case("arrangement", "direct", "five_benches_library", NURSE,
         "Could you put five benches in a row along the pavement by the library?",
         [delta("bench", 5, 5), layout("line", "bench", 5), near("Library entrance", 20, "bench", every=True), only("bench")],
         [arrange("bench", "line", loc("on_sidewalk", "Library entrance"), count=5)]),
    case("arrangement", "direct", "grid_nine_cones_lot_b", JOURNALIST, "Arrange nine cones in a grid in parking lot B.",
         [delta("traffic_cone", 9, 9), layout("cluster", "traffic_cone", 9, tolerance=8.0),
          near("parking lot B", 1, "traffic_cone", every=True), only("traffic_cone")],
         [arrange("traffic_cone", "grid", loc("at", "parking lot B"), count=9)]),
    case("arrangement", "direct", "circle_cones_crossroads", NEWCOMER,
         "Could you make a circle of six cones in the middle of the crossroads?",
         [delta("traffic_cone", 6, 6), layout("ring", "traffic_cone", 6, around="main intersection"),
          near("main intersection", 1, "traffic_cone", every=True), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "main intersection"), count=6, radius=4.0)]),
    impossible("arrangement", "direct", "fifteen_buses_row", DISPATCHER, "Park fifteen buses in a row in lot A.",
               [arrange("bus", "parking_row", loc("at", "parking lot A"), count=15)]),
    case("arrangement", "direct", "four_bollards_library_tree", COUNCILLOR, "Ring the tree by the library with four bollards.",
         [delta("bollard", 4, 4), layout("ring", "bollard", 4, around=TREE_LIBRARY), only("bollard")],
         [arrange("bollard", "ring", loc("at", TREE_LIBRARY), count=4)]),
    case("arrangement", "direct", "cones_round_rubble", ASSESSOR, "Put a ring of cones around it.",
         [delta("traffic_cone", 4, None), layout("ring", "traffic_cone", 4, around="cement_rubble_1"), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "cement_rubble_1"))], setup=[RUBBLE_AHEAD]),
    # indirect
    case("arrangement", "indirect", "orange_circle_west_car_park", PARENT,
         "She'd like the little orange cones set out in a circle in the middle of the west car park, eight of them.",
         [delta("traffic_cone", 8, 8), layout("ring", "traffic_cone", 8), near("parking lot A", 1, "traffic_cone", every=True),
          only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "parking lot A"), count=8, radius=4.0)]),
    case("arrangement", "indirect", "block_lot_b_driveway", COUNCILLOR,
         "Block the student car park's driveway with a line of the heavy plastic barriers.",
         [delta("road_barrier", 2, None), layout("line", "road_barrier", 2),
          near("parking lot B entrance", 10, "road_barrier", every=True), only("road_barrier")],
         [arrange("road_barrier", "line", loc("at", "parking lot B entrance"), count=3)]),
    case("arrangement", "indirect", "coaches_nose_to_tail", DISPATCHER,
         "Line up three of our coaches nose to tail along the kerb of the eastbound lane, starting at the bus stop.",
         [delta("bus", 3, 3), layout("line", "bus", 3), in_lane(EAST, "bus"), only("bus")],
         [arrange("bus", "lane_edge", loc("in_lane", "bus stop", lane=EAST, offset_m=0.0), count=3, spacing=14.0)]),
    case("arrangement", "indirect", "concrete_chunks_junction", MODDER,
         "spawn a little cluster of concrete chunks in the middle of the junction, like four",
         [delta("cement_rubble", 4, 4), layout("cluster", "cement_rubble", 4, tolerance=6.0),
          near("main intersection", 3, "cement_rubble", every=True), only("cement_rubble")],
         [arrange("cement_rubble", "grid", loc("at", "main intersection"), count=4)]),
    case("arrangement", "indirect", "work_zone_right_edge", ASSESSOR,
         "Recreate the work zone: five cones along the right-hand edge of the eastbound lane, beginning 20 metres ahead of the insured car.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5), in_lane(EAST, "traffic_cone"),
          near(None, 16, "traffic_cone", point=(-34.0, -1.75), every=True), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", ahead_of(EGO, 20, lane=EAST), count=5)]),
    case("arrangement", "indirect", "metal_posts_round_bench", NURSE, "put some of those short metal posts in a ring round the bench",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around=BENCH), only("bollard")],
         [arrange("bollard", "ring", loc("at", BENCH))]),
    case("arrangement", "indirect", "sedans_side_by_side_west", JOURNALIST,
         "Set out four saloon cars parked side by side in the west car park.",
         [delta("passenger_car", 4, 4), layout("line", "passenger_car", 4), near("parking lot A", 1, "passenger_car", scope="added", every=True),
          only("passenger_car")],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot A"), count=4)]),
    case("arrangement", "indirect", "people_queue_engineering", NEWCOMER,
         "I'd like people standing in a line along the pavement outside the engineering building. Can you do five?",
         [delta("pedestrian", 5, 5), layout("line", "pedestrian", 5), near("Engineering Hall entrance", 15, "pedestrian", every=True),
          only("pedestrian")],
         [arrange("pedestrian", "line", loc("on_sidewalk", "Engineering Hall entrance"), count=5)]),
    case("arrangement", "indirect", "cones_by_stop_and_drizzle", JOURNALIST,
         "Set out four cones along the kerb of the eastbound lane at the bus stop, and give it a drizzle.",
         [delta("traffic_cone", 4, 4), layout("line", "traffic_cone", 4), in_lane(EAST, "traffic_cone"),
          env(weather=["rain"], intensity_min=0.05, intensity_max=0.45), only("traffic_cone", env=True)],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "bus stop", lane=EAST), count=4), weather("rain", 0.2)]),
    impossible("arrangement", "indirect", "tram_tracks_cones", COUNCILLOR, "Line the tram tracks on Main Street with cones.",
               [arrange("traffic_cone", "lane_edge", loc("in_lane", "tram tracks"))]),
    case("arrangement", "indirect", "posts_round_new_bench", PARENT, "Put a ring of the little posts round the bench we just added.",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around="bench_2"), only("bollard")],
         [arrange("bollard", "ring", loc("at", "bench_2"))], setup=[asked(BENCH_LIBRARY)]),
    # vague
    case("arrangement", "vague", "cordon_junction", COUNCILLOR, "Can we cordon off the junction somehow?",
         [delta(CORDON, 4, None), near("main intersection", 12, CORDON, every=True), only(*CORDON)],
         [arrange("road_barrier", "ring", loc("at", "main intersection"), radius=6.0, count=8)],
         alternatives=[[layout("ring", CORDON, 4)], [layout("line", CORDON, 3)]]),
    case("arrangement", "vague", "cones_line_main_street", MODDER, "spawn a bunch of cones in a line somewhere on main street",
         [delta("traffic_cone", 3, None), layout("line", "traffic_cone", 3), in_lane(None, "traffic_cone"), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "bus stop", lane=EAST))]),
    case("arrangement", "vague", "few_buses_lot_a", DISPATCHER, "Park a few buses together in lot A.",
         [delta("bus", 2, 6), layout("line", "bus", 2), near("parking lot A", 1, "bus", every=True), only("bus")],
         [arrange("bus", "parking_row", loc("at", "parking lot A"), count=3)]),
    case("arrangement", "vague", "bollards_round_hydrant", NURSE, "bollards round the hydrant maybe?",
         [delta("bollard", 3, None), layout("ring", "bollard", 3, around=HYDRANT), only("bollard")],
         [arrange("bollard", "ring", loc("at", HYDRANT))]),
    case("arrangement", "vague", "chatting_circle", PARENT, "Make a little circle of people by the fountain, like they're chatting.",
         [delta("pedestrian", 3, None), layout("ring", "pedestrian", 3), near("fountain", 10, "pedestrian", every=True),
          only("pedestrian")],
         [arrange("pedestrian", "ring", loc("at", "fountain"), count=5, radius=2.0)]),
    case("arrangement", "vague", "close_lane_ahead", JOURNALIST, "Put some barriers out to close the eastbound lane ahead of the test car.",
         [delta("road_barrier", 1, None), relative("in_front_of", EGO, "road_barrier", max_distance=40, tolerance_deg=30, every=True),
          only("road_barrier")],
         [arrange("road_barrier", "line", loc("in_front_of", EGO, along_m=25))]),
    case("arrangement", "vague", "work_zone_bus_stop", ASSESSOR, "Mark a work zone with cones along the lane near the bus stop.",
         [delta("traffic_cone", 3, None), layout("line", "traffic_cone", 3), near("bus stop", 30, "traffic_cone", every=True),
          in_lane(None, "traffic_cone"), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "bus stop", lane=EAST), count=6)]),
    case("arrangement", "vague", "few_cones_row", NEWCOMER, "Can you set up a few cones in a row near the crossroads?",
         [delta("traffic_cone", 3, 8), layout("line", "traffic_cone", 3), near("main intersection", 20, "traffic_cone", every=True),
          only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "main intersection"), count=4)]),
    case("arrangement", "vague", "bollards_fountain_dark", MODDER, "chuck some bollards round the fountain and make it dark",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around="fountain"), env(night=True), only("bollard", env=True)],
         [arrange("bollard", "ring", loc("at", "fountain")), clock("night")]),
    case("arrangement", "vague", "few_bollards_round_it", COUNCILLOR, "A few bollards round it?",
         [delta("bollard", 3, None), layout("ring", "bollard", 3, around="bench_2"), only("bollard")],
         [arrange("bollard", "ring", loc("at", "bench_2"))], setup=[BENCH_LIBRARY]),
    case("arrangement", "vague", "cordon_rubble_planned", DISPATCHER, "and cordon it off, would you",
         [delta(CORDON, 3, None), layout("ring", CORDON, 3, around="cement_rubble_1"), only(*CORDON)],
         [arrange("traffic_cone", "ring", loc("at", "cement_rubble_1"))], setup=[asked(RUBBLE_WEST)]),
    # erroneous
    case("arrangement", "erroneous", "circle_bollards_fountain_typos", NURSE, "put 6 bolards in a cirlce round the founatin",
         [delta("bollard", 6, 6), layout("ring", "bollard", 6, around="fountain"), only("bollard")],
         [arrange("bollard", "ring", loc("at", "fountain"), count=6)]),
    case("arrangement", "erroneous", "barriers_jtekt_typos", MODDER, "mkae a row of 3 barriers infront of the JTEKT entarnce",
         [delta("road_barrier", 3, 3), layout("line", "road_barrier", 3),
          near("JTEKT building entrance", 12, "road_barrier", every=True), only("road_barrier")],
         [arrange("road_barrier", "line", loc("in_front_of", "JTEKT building entrance"), count=3)]),
    case("arrangement", "erroneous", "buses_side_by_side_typos", DISPATCHER, "prak 3 busses side by side in lot a",
         [delta("bus", 3, 3), layout("line", "bus", 3), near("parking lot A", 1, "bus", every=True), only("bus")],
         [arrange("bus", "parking_row", loc("at", "parking lot A"), count=3)]),
    case("arrangement", "erroneous", "bollards_library_tree_typos", PARENT, "a ring of bolards round the tree near the libary",
         [delta("bollard", 3, None), layout("ring", "bollard", 3, around=TREE_LIBRARY), only("bollard")],
         [arrange("bollard", "ring", loc("at", TREE_LIBRARY))]),
    case("arrangement", "erroneous", "westbound_eight_cones_typos", JOURNALIST, "line the westbond lane with 8 cones from the east gate",
         [delta("traffic_cone", 8, 8), layout("line", "traffic_cone", 8), in_lane(WEST, "traffic_cone"), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "east gate", lane=WEST), count=8)]),
    case("arrangement", "erroneous", "benches_pavement_typos", COUNCILLOR, "put a row of benchs along the pavment by the library, 4 of them",
         [delta("bench", 4, 4), layout("line", "bench", 4), near("Library entrance", 20, "bench", every=True), only("bench")],
         [arrange("bench", "line", loc("on_sidewalk", "Library entrance"), count=4)]),
    case("arrangement", "erroneous", "six_cones_edge_typos", ASSESSOR,
         "cones along the rigth edge of the eastbund lane, 6 of them, startng 10 m ahead of the insured car",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6), in_lane(EAST, "traffic_cone"),
          near(None, 22, "traffic_cone", point=(-38.0, -1.75), every=True), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", ahead_of(EGO, 10, lane=EAST), count=6)]),
    case("arrangement", "erroneous", "four_cars_row_lot_b_typos", NEWCOMER, "cna you put 4 cars parked in a row in lot b",
         [delta("passenger_car", 4, 4), layout("line", "passenger_car", 4),
          near("parking lot B", 1, "passenger_car", scope="added", every=True), only("passenger_car")],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot B"), count=4)]),
    impossible("arrangement", "erroneous", "helipad_typos", MODDER, "put a ring of cones round the helipd",
               [arrange("traffic_cone", "ring", loc("at", "helipad"))]),
    case("arrangement", "erroneous", "cones_behind_lorry_typos", ASSESSOR, "set up a line of conse across the lane behind the broken down lorry",
         [delta("traffic_cone", 3, None), layout("line", "traffic_cone", 3),
          relative("behind", "truck_1", "traffic_cone", max_distance=12, every=True), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("behind", "truck_1"), count=4)], setup=[TRUCK_AHEAD]),
    case("arrangement", "erroneous", "cone_off_van_typos", DISPATCHER, "cone it off, a line of cones acros the lane behnd the van",
         [delta("traffic_cone", 3, None), layout("line", "traffic_cone", 3),
          relative("behind", "truck_1", "traffic_cone", max_distance=12, every=True), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("behind", "truck_1"), count=4)], setup=[asked(VAN_EAST_GATE)]),
]

# --- Appearance: clock, weather, lights and the looks of things -----------------------------------------
RAIN_PLAIN = turn("Make it rain.", weather("rain", 0.5))

APPEARANCE_CASES: list[Json] = [
    # direct
    case("appearance", "direct", "time_0745", COUNCILLOR, "Set the time to 7:45 in the morning.",
         [env(time_from="07:40", time_to="07:50"), only(env=True)], [clock("07:45")]),
    case("appearance", "direct", "heavy_rain", NURSE, "Make it rain heavily.",
         [env(weather=["rain"], intensity_min=0.7), only(env=True)], [weather("rain", 0.9)]),
    case("appearance", "direct", "suv_matte_black", MODDER, "Paint suv_1 matte black.",
         [looks("black", asset=SUV, material="matte"), only(assets=[SUV])], [paint([SUV], colour="black", material="matte")]),
    case("appearance", "direct", "street_lights_on", DISPATCHER, "Turn the street lights on.",
         [env(street_lights="on"), only(env=True)], [lighting(street_lights="on")]),
    case("appearance", "direct", "benches_green", PARENT, "Make all the benches green.",
         [looks("green", "bench", scope="all", every=True), only("bench")], [paint(category="bench", colour="green")]),
    case("appearance", "direct", "light_fog", JOURNALIST, "Set a light fog.",
         [env(weather=["fog"], intensity_min=0.1, intensity_max=0.45), only(env=True)], [weather("fog", 0.3)]),
    case("appearance", "direct", "clock_1720", ASSESSOR, "Set the clock to 17:20, the time of the incident.",
         [env(time_from="17:15", time_to="17:25"), only(env=True)], [clock("17:20")]),
    case("appearance", "direct", "moderate_snow", NEWCOMER, "Can you make it snow? Moderately, please.",
         [env(weather=["snow"], intensity_min=0.45, intensity_max=0.75), only(env=True)], [weather("snow", 0.6)]),
    impossible("appearance", "direct", "time_2630", COUNCILLOR, "Set the time to 26:30.", [clock("26:30")]),
    case("appearance", "direct", "sedans_red_suv_yellow", PARENT, "Paint the two sedans red and the SUV yellow.",
         [looks("red", asset=CAR1), looks("red", asset=CAR2), looks("yellow", asset=SUV), only(*PARKED_CARS)],
         [paint([CAR1, CAR2], colour="red"), paint([SUV], colour="yellow")]),
    case("appearance", "direct", "headlights_on", DISPATCHER, "Switch the vehicle headlights on.",
         [env(vehicle_lights="on"), only(env=True)], [lighting(vehicle_lights="on")]),
    # indirect
    case("appearance", "indirect", "end_of_late_shift", NURSE, "make it feel like the end of a late shift, about quarter to midnight",
         [env(time_from="23:40", time_to="23:50"), only(env=True)], [clock("23:45")]),
    case("appearance", "indirect", "winter_thick_snow", PARENT,
         "Her project is about winter, so cover everything in a thick layer of snow.",
         [env(weather=["snow"], intensity_min=0.7), only(env=True)], [weather("snow", 0.9)]),
    case("appearance", "indirect", "driving_rain_evening", ASSESSOR,
         "It happened in driving rain just after half past five in the evening; set that up.",
         [env(weather=["rain"], intensity_min=0.6, time_from="17:30", time_to="17:50"), only(env=True)],
         [weather("rain", 0.9), clock("17:35")]),
    case("appearance", "indirect", "chrome_four_by_four", MODDER, "give the four-by-four a shiny chrome finish",
         [looks(None, asset=SUV, material="metal"), only(assets=[SUV])], [paint([SUV], colour="silver", material="metal")]),
    case("appearance", "indirect", "eleven_at_night", COUNCILLOR, "Show me how the street looks at eleven at night.",
         [env(time_from="22:55", time_to="23:05"), only(env=True)], [clock("23:00")]),
    case("appearance", "indirect", "grey_overcast_morning", DISPATCHER, "Give me the conditions of a grey, overcast morning.",
         [env(weather=["cloudy"], time_from="06:30", time_to="11:30"), only(env=True)], [weather("cloudy", 0.7), clock("09:00")]),
    case("appearance", "indirect", "sun_goes_down", JOURNALIST, "I want the scene at the moment the sun goes down.",
         [env(time_from="18:30", time_to="20:30"), only(env=True)], [clock("sunset")]),
    case("appearance", "indirect", "bin_fire_engine_colour", NEWCOMER,
         "How do I change how something looks? Could you make the rubbish bin the colour of a fire engine?",
         [looks("red", asset=BIN), only(assets=[BIN])], [paint([BIN], colour="red")]),
    impossible("appearance", "indirect", "sandstorm", JOURNALIST, "For the feature I need a sandstorm blowing through.",
               [weather("sandstorm", 0.8)]),
    case("appearance", "indirect", "new_bench_wood", PARENT, "Make the one we just added look like it's made of wood.",
         [looks(None, asset="bench_2", material="wood"), only(assets=["bench_2"])], [paint(["bench_2"], material="wood")],
         setup=[asked(BENCH_FOUNTAIN)]),
    case("appearance", "indirect", "lamps_shine_daytime", COUNCILLOR,
         "Have the lamps along the road shining even though it's the middle of the day.",
         [env(street_lights="on"), only(env=True)], [lighting(street_lights="on")]),
    # vague
    case("appearance", "vague", "darker_drearier", NURSE, "make it a bit darker and drearier", [only(env=True)],
         [weather("cloudy", 0.7)],
         alternatives=[[env(weather=["cloudy", "rain", "fog", "snow"])], [env(night=True)], [env(exposure_max=0.9)]]),
    case("appearance", "vague", "night_mode", MODDER, "night mode pls", [env(night=True), only(env=True)], [clock("night")]),
    case("appearance", "vague", "bad_weather", COUNCILLOR, "Let's see what it looks like in bad weather.",
         [env(weather=["rain", "fog", "snow"], intensity_min=0.4), only(env=True)], [weather("rain", 0.8)]),
    case("appearance", "vague", "first_thing_morning", DISPATCHER, "Early start for the drivers: make it first thing in the morning.",
         [env(time_from="05:00", time_to="08:00"), only(env=True)], [clock("06:30")]),
    case("appearance", "vague", "brighter_car_colours", PARENT, "Brighter colours on the parked cars, please; they look so dull.",
         [looks(BRIGHT, PARKED_CARS, min_count=2), only(*PARKED_CARS)], [paint([CAR1, SUV, CAR2], colour="yellow")]),
    case("appearance", "vague", "less_fog", JOURNALIST, "Less fog, please.", [only(env=True)], [weather("fog", 0.4)],
         setup=[FOG_THICK],
         alternatives=[[env(weather=["fog"], intensity_max=0.6)], [env(weather=["clear", "cloudy"])]]),
    case("appearance", "vague", "touch_brighter", ASSESSOR, "Make it a touch brighter.", [only(env=True)],
         [lighting(exposure=1.5)], setup=[NIGHT],
         alternatives=[[env(night=False)], [env(exposure_min=1.1)], [env(street_lights="on")]]),
    case("appearance", "vague", "nicer_weather", NEWCOMER, "Can the weather be nicer?", [only(env=True)], [weather("clear")],
         setup=[RAIN_HARD], alternatives=[[env(weather=["clear", "cloudy"])], [env(weather=["rain"], intensity_max=0.4)]]),
    case("appearance", "vague", "moody_fog_dusk", MODDER, "make it moody, fog and dusk",
         [env(weather=["fog"], time_from="18:30", time_to="21:30"), only(env=True)], [weather("fog", 0.6), clock("dusk")]),
    case("appearance", "vague", "sunny_afternoon", NURSE, "warmer feel please, like a sunny afternoon",
         [env(weather=["clear"], time_from="13:00", time_to="17:30"), only(env=True)], [clock("15:00")]),
    case("appearance", "vague", "bit_harder", PARENT, "a bit harder than that", [env(weather=["rain"], intensity_min=0.7), only(env=True)],
         [weather("rain", 0.8)], setup=[asked(RAIN_PLAIN)]),
    # erroneous
    case("appearance", "erroneous", "light_rain_typos", NURSE, "mkae it rain lightly",
         [env(weather=["rain"], intensity_min=0.05, intensity_max=0.45), only(env=True)], [weather("rain", 0.3)]),
    case("appearance", "erroneous", "suv_purple_typos", MODDER, "paint the suv purpel",
         [looks("purple", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="purple")]),
    case("appearance", "erroneous", "time_0630_typos", DISPATCHER, "set teh time to 0630",
         [env(time_from="06:25", time_to="06:35"), only(env=True)], [clock("06:30")]),
    case("appearance", "erroneous", "snow_lots_typos", PARENT, "make it snoww a lot",
         [env(weather=["snow"], intensity_min=0.7), only(env=True)], [weather("snow", 0.9)]),
    case("appearance", "erroneous", "street_lights_off_typos", JOURNALIST, "turn of the street lihgts",
         [env(street_lights="off"), only(env=True)], [lighting(street_lights="off")]),
    case("appearance", "erroneous", "bin_blue_typos", COUNCILLOR, "make the bin bule",
         [looks("blue", asset=BIN), only(assets=[BIN])], [paint([BIN], colour="blue")]),
    case("appearance", "erroneous", "quarter_past_nine_typos", ASSESSOR, "set the tiem to quater past nine at night",
         [env(time_from="21:10", time_to="21:20"), only(env=True)], [clock("21:15")]),
    case("appearance", "erroneous", "fog_not_thick_typos", NEWCOMER, "can you mak it foggy, not to thick",
         [env(weather=["fog"], intensity_min=0.1, intensity_max=0.6), only(env=True)], [weather("fog", 0.4)]),
    impossible("appearance", "erroneous", "tornado_typos", NURSE, "set the wether to tornado", [weather("tornado")]),
    case("appearance", "erroneous", "bus_yellow_typos", DISPATCHER, "paint the bus yelow",
         [looks("yellow", asset="bus_1"), only("bus")], [paint(["bus_1"], colour="yellow")], setup=[BUS_AT_STOP]),
    case("appearance", "erroneous", "night_headlights_typos", ASSESSOR, "make it nite and put the headlihgts on",
         [env(night=True, vehicle_lights="on"), only(env=True)], [clock("night"), lighting(vehicle_lights="on")]),
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
SUITE_PATH = S.path


def main() -> None:
    """Write the suite's JSONL, one case a line."""
    S.write(ALL_CASES)


if __name__ == "__main__":
    main()
