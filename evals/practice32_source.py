"""The thirty-second practice suite: 364 cases from eight new kinds of user, none used by an earlier suite, from the campus world alone.

`python -m drivetwin.evals.practice32_source` writes `suites/practice32.jsonl` (tag `practice32`, ids
`practice32.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`; 40 to 50 cases each): a museum curator ("de-accession the bench",
"the installation has closed", "strike the cones", "visitors", "sightlines", "wayfinding signs", "in situ", "a
bronze statue on a plinth", "display vitrines", "the catalogue cover", "our bronze collection", "a more contemplative
spot", "a pleasing composition"), a Brazilian Portuguese speaker writing English ("How many cars have in the parking
B?", "the semaphore of the north-east corner", "the car of the east side of the row", "more fast", "put him in 9
meters per second", "the stop of bus", "7 hour of the night", "I don't want it more", "lixeira", "desculpa", "obra",
"pessoa", "more two"), an electrician or tradesperson ("lamp standards", "a column putting in", "isolate the
signals", "kill the street lights", "the luminaires", "overhead lines", "a trench going in", "I'll be digging round
that hydrant", "stick", "give us", "cheers", "mate"), a Mandarin Chinese speaker writing English ("Fire hydrant
where?", "distance how much?", "open the street light", "close the fog", "cone 6 piece one line", "Barrier 3 piece",
"Stop sign around need protect", "Rain too big, make small", "the bus I add, it stand where?"), someone who writes
in markdown ("- add: 1 bus", "- where: east gate", "**Goal:**", "**Issue:** ... **Expected:** ...", "1. bench ->
Library entrance", "`trash_bin_1`", "- q1: ... - q2: ..."), a sarcastic, frustrated user ("Would it kill you to add a
trash can", "Oh sure, a bus stop with no bus. Very realistic", "LOT A. Not B.", "Riveting", "Like this
conversation", "Was that so hard?"), a warehouse or logistics manager ("stage", "dispatch", "cycle count", "stock
take", "headcount", "send the pickers home", "clear the yard", "inbound trucks", "a holding row", "marshal the
traffic", "the yard cameras", "a forklift", "pallets", "the loading dock") and a New Zealander ("eh", "chuck", "bro",
"sweet as", "bugger all shade", "munted", "stuffed", "a wee circle", "a tiki tour", "heaps more people", "choice",
"yeah nah", "pissing down", "bucketing down", "a typical Wellington day", "a proper southerly with hail", "the
dairy", "a chilly bin", "the ute").

Prompts describe things instead of naming them ("the lamp post right next to the stop sign", "the lamp post on the
south side right by the bus stop", "the car at the east end of the lot B row", "the traffic light on the north-east
corner", "the tree just north of lot A", "the trees round the fountain", "whatever stands closest to the fountain",
"the second bench, the new one", "the car in front", "that debris", "him", "it", "those cones"), turn on negation and
polarity ("leave the two cars", "keep the SUV", "the original stays", "leave the lamps", "the rest can stay", "not
black", "nobody will ever see it", "not too strong", "I don't want it more", "yeah nah") and name places and scopes
(lanes and roads, "25 m ahead of the ego", "20 m behind the ego, same lane", "15 meter in front of the ego, right
side", "ten metres ahead on the right-hand footpath", "across the eastbound lane", "the westbound lane level with the
JTEKT entrance", "Campus Drive south of the crossing", "the north-east corner of the crossroads", "the south footpath
west of the junction", "x=40, y=-20", "the far side of campus", "within twenty metres of the fountain"). They carry
clock times in several forms ("16:45", "05:30", "21:15", "22:00", "7 hour of the night", "quarter past ten at night",
"just after sunrise", "late afternoon", "dusk", "after dark", "early evening", "24:45") and weather with strengths
(strong rain, light fog, proper heavy snow, "big snow", moderate rain, "pissing down", "bucketing down", "rain too
big", thick fog closed, "a little bit the weather", hail and a rainbow), numbers in words and digits with units ("7 meters per
second", "3 m/s", "four", "fifty metres", "12 metres", "15m", "2 m apart", "three'll do", "6 piece", "eleven",
"twelve", "a hundred and fifty", "180 kilometre per hour", "exposure 1.2"), questions (which must change nothing:
their checks hold the scene unchanged and their reference answers with a search) and behaviours over time: speeds up
and down, a stop at four seconds and a lead car stopping dead at six, lane changes at three, four and five seconds,
a left turn at the crossing, a red light the ego waits at before the west crosswalk, a lead car braking as the ego
closes to twelve or fifteen metres, a cut-in, walkers crossing at the north crosswalk or stepping out in front of
the ego, cars, a truck and a walker driving or walking to the east gate, the main gate, the lot B entrance, the
Library and the fountain, circles in lot B, backing up. The erroneous grade carries realistic typos, slips and
non-native grammar ("fountian", "Libary entrence", "wich", "nearst", "stop sgin", "hydarnt", "teh", "wether",
"heavey", "wieghbridge", "east gait", "Main Stret", "directon", "too traffic lights", "rounabout", "bech", "bycicle",
"pedestrain", "conse", "motorcyle", "too trucks", "moring", "rubish", "Engneering", "buss", "remvoe", "trafic",
"delet", "passanger", "secnd", "hidrant", "nerest", "Studant", "hydrnat", "stopp", "postion", "ahaed", "crossin",
"buildng", "degress", "revers", "cirlces", "dispach", "crawlin", "wset", "esat", "brak", "Arange", "strait", "acros",
"agian", "crosing", "rign", "arround", "squre", "burgandy", "lihgts", "swich", "strenght", "nigth", "exposre",
"yelow", "stret lights", "quater").

Counts: 7 tasks x 4 grades, every cell 13 cases (364 in all). 51 cases are multi-turn (32 with a planned earlier turn
that has calls), with references back: "it", "him", "that truck", "that sign", "the car in front", "that debris",
"those cones", "the car I just add", "the bus I add", "the truck that I put", "the second bench", "another one of
those", "a couple more of them there", "more two in the same place", "same thing, also at the east gate", "same
layout again in lot B", "do the same in the parking B", "the same again at the north crossing"; and corrections
("Desculpa, I put in the wrong place", "Ah no, I changed of idea. Take it off", "No, I don't like. Put another color,
more happy", "Right, now kill the street lights", "Fog already too thick. Close the fog"). 24 are compound (the
reference makes two calls or more; 20 of them put two requests in one prompt, the other four ask one thing that takes
two calls: clearing the yard of cones and a barrier, a cut-in, a foggy and a snowy morning), and 28 (7.7 %) are impossible, tagged
`impossible`, where the right outcome is a refusal that changes nothing: a dairy, a loading dock, a museum, a
roundabout; a forklift, a bronze statue, a chilly bin, eleven buses; the Engineering Hall and Library buildings, the
north crosswalk, the ego; the SUV on the JTEKT roof, the bench inside the Library's reading room, inside the JTEKT
building or off the map past the east gate; a tree walking, a stop sign chasing the ego, a traffic light lapping lot
B, the ego at 180 km/h; pallets, a ring of 150 bollards, display vitrines, twelve buses in a row; hail, a pink
Library building, 24:45, a rainbow.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with `alternatives`
where a request has two fair readings (a new speed on the lane behaviour or by a change-of-speed manoeuvre, backing
up by a shift or a reverse manoeuvre, braking by a stop or a slow-down, a crossing as a behaviour or a manoeuvre, a
cut-in by any kind of vehicle, setting a parked vehicle off by any driving behaviour or manoeuvre, "more light" by
exposure, street lights or daylight, "atmosphere" and "darker" by the clock, the exposure or the weather, "some
shape" or "a pleasing composition" as a line, a ring or a cluster, more traffic "on Main Street" in either lane, a
bench "under the trees" by any of the four, a hydrant "next to a building" at any of the four entrances, a car
"nearer a gate" at either gate, a bad winter shift by snow or thick fog, easing the rain by lighter rain or clear
skies). Environment checks of cases with no earlier turns also hold the weather and the clock they do not mention as
the campus ships them (`pin_environment`). The `reference` plan of every case passes; a plan that does nothing fails
every case, questions and impossible ones included (its empty plan is accepted and answers nothing), whether or not
its planned earlier turns were done. Simple wrong plans (another place, another count, another colour or weather,
another asset, a call left out, another case's plan) fail all but the readings the wording leaves open. Every id and
coordinate was checked against worlds/campus.py and the search Workers' answers on the shipped campus. The suite was
written from the campus world, the asset catalog, the Worker tools' argument schemas and the eval checks only, by
someone who had not read the planners, their lexicons, their prompt examples or any other suite's cases
(practice30's and practice31's sources were read for their format only).
"""

from __future__ import annotations

from drivetwin.evals.practice_cases import (
    EGO,
    Json,
    Suite,
    add,
    ahead_of,
    arrange,
    backs_up,
    behave,
    clock,
    count,
    darker,
    delta,
    does,
    drive,
    env,
    environment,
    event,
    event_played,
    find,
    gets_going,
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
    new_speed,
    on,
    only,
    paint,
    place,
    properties,
    reaches,
    remove,
    says,
    slows_down,
    some_in_lane,
    stops_before,
    turn,
    walks_over,
    weather,
    xy,
)

TAG = "practice32"
S = Suite(TAG)
case = S.case
impossible = S.impossible
ask = S.ask

# --- The campus as it ships: ids and places the cases name (checked against worlds/campus.py) -------------
SUV = "suv_1"  # the middle vehicle of the row of three in lot B, (23, -42), facing north
CAR_W = "passenger_car_1"  # the west end of that row, (19, -42)
CAR_E = "passenger_car_2"  # the east end of that row, (27, -42)
LOT_B_ROW = [CAR_W, SUV, CAR_E]
BENCH = "bench_1"  # south footway just east of the bus stop, (-26, -6.9), facing west
BIN = "trash_bin_1"  # south footway just west of the bus stop, (-33.5, -5.5), facing east
HYDRANT = "fire_hydrant_1"  # north footway east of the crossroads, (16, 5.5), facing east
STOP = "stop_sign_1"  # south footway just west of the west crosswalk, (-13.5, -5.5)
LIGHT_SW = "traffic_light_1"  # south-west corner of the crossroads, (-9.5, -6.2)
LIGHT_NE = "traffic_light_2"  # north-east corner, (9.5, 6.2)
TREE_LIBRARY = "tree_1"  # between the bus stop and the Library, (-26, -12)
TREE_FOUNTAIN_NW = "tree_2"  # north-west of the fountain, (70, 45), 7.1 m from it
TREE_FOUNTAIN_SE = "tree_3"  # south-east of the fountain, (85, 25), 18 m from it
TREE_LOT_A = "tree_4"  # just north of lot A, (-85, 50)
TREES = [TREE_LIBRARY, TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE, TREE_LOT_A]
NORTH_LAMPS = [f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11)]  # y = 5.8; x = -80, -50, -25, 25, 50, 80
SOUTH_LAMPS = [f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12)]  # y = -5.8; x = -68, -38, -13, 37, 62, 92
LAMP_BY_BUS_STOP = "street_light_4"  # (-38, -5.8): 8 m from the bus stop, 9.7 m from the Library entrance
LAMP_BY_STOP_SIGN = "street_light_6"  # (-13, -5.8): 0.6 m from the stop sign, at the west crosswalk
LAMP_NE = "street_light_7"  # (25, 5.8): east of the hydrant on the north footway
LAMP_BY_FOUNTAIN = "street_light_11"  # (80, 5.8): 34.6 m from the fountain, the nearest to it
EAST = "main_eastbound"  # y = -1.75; the ego drives it at 5 m/s from x = -60
WEST = "main_westbound"  # y = 1.75
NORTH = "campus_northbound"  # x = 1.75
SOUTH = "campus_southbound"  # x = -1.75
ROBOT = "ackermann_robot"
TRAFFIC = ["passenger_car", "suv", "bus", "truck", "motorcycle", ROBOT]
CARS = ["passenger_car", "suv"]
CORDON = ["traffic_cone", "road_barrier", "bollard"]
SIGNS = ["pedestrian_sign", "construction_sign", "stop_sign", "parking_sign"]
PEOPLE = ["pedestrian", "bicycle"]
FURNITURE = ["bench", "trash_bin", "tree", "bollard"]
ENTRANCES = ["Library entrance", "Engineering Hall entrance", "JTEKT building entrance", "Student Union entrance"]
BRIGHT = ["red", "green", "blue", "yellow", "orange", "purple", "pink", "cyan", "teal", "gold"]
MUTED = ["white", "black", "grey", "silver", "brown", "beige", "navy", "maroon"]
ALL_COLOURS = [*BRIGHT, *MUTED]
COOL = ["blue", "cyan", "teal", "navy", "green", "purple"]
# What comes first when the cases add one: the next free number of each category.
NEW_CAR = "passenger_car_3"
NEW_WALKER = "pedestrian_1"
NEW_TRUCK = "truck_1"
NEW_BUS = "bus_1"
NEW_BENCH = "bench_2"
NEW_SIGN = "construction_sign_1"
RUBBLE = "cement_rubble_1"

# --- Voices (each case names its own in `notes`) -----------------------------------------------------------
CURATOR = (
    "museum curator: 'installation', 'de-accession', 'the collection', 'visitors', 'sightlines', 'wayfinding', "
    "'in situ', 'plinth', 'conservation team', 'the catalogue', measured and formal"
)
BRAZIL = (
    "Brazilian Portuguese speaker writing English: 'put' for every verb, 'of' for possession ('the car of the east "
    "side'), 'more fast', 'semaphore' for traffic light, 'have' for 'there is', 'in the parking B', hours as '7 "
    "of the night', Portuguese words slipping in ('lixeira', 'desculpa', 'obra')"
)
SPARKY = (
    "electrician / tradesperson: 'lamp standard', 'column', 'isolate', 'kill the lights', 'stick', 'chuck', 'mate', "
    "'the job', 'footpath', 'give us', 'cheers', practical reasons about digging and cabling"
)
MANDARIN = (
    "Mandarin Chinese speaker writing English: topic first ('The bench, put to fountain'), no articles or plurals, "
    "measure words ('3 piece'), 'open / close the light', 'already', 'can or not', 'there' after places"
)
MARKDOWN = (
    "someone who writes in markdown: bullet lists ('- add: ...'), numbered steps, **bold** labels, `code` ids, "
    "key: value pairs"
)
SARCASTIC = (
    "sarcastic, frustrated user: 'oh great', 'surely', 'was that so hard', rhetorical questions, mock praise, "
    "capitals for emphasis, the request buried in the complaint"
)
WAREHOUSE = (
    "warehouse / logistics manager: 'stage', 'dispatch', 'yard', 'bay', 'inbound / outbound', 'pull', 'headcount', "
    "'cycle count', 'stock take', 'pickers', 'marshal the traffic', shift times"
)
KIWI = (
    "New Zealander: 'eh', 'chuck', 'sweet as', 'heaps', 'bugger all', 'yeah nah', 'munted', 'tiki tour', 'wee', "
    "'carpark', 'footpath', 'ute', 'bro', 'reckon', 'choice', 'pissing down', 'chilly bin', 'the dairy'"
)


# --- Helpers ----------------------------------------------------------------------------------------------
def any_shape(category: str | list[str], least: int, tolerance: float = 1.0) -> list[list[Json]]:
    """Fair readings of 'some shape' or 'a nice composition': a line, a ring or a tight cluster."""
    return [
        [layout("line", category, least, tolerance=tolerance)],
        [layout("ring", category, least, tolerance=tolerance)],
        [layout("cluster", category, least, tolerance=6.0)],
    ]


def timed_event(actor: str, kind: str, seconds: float, passes: tuple[float, float]) -> Json:
    """Run the scene: `actor` has a `kind` manoeuvre started by a clock (time) trigger within `seconds`, and
    first gets as far as `passes` (so the manoeuvre did not start at once)."""
    return {
        "kind": "scenario",
        "seconds": seconds,
        "expect": [
            {"kind": "event", "actor": actor, "manoeuvre": kind, "trigger": "simulation_time"},
            {"kind": "reached", "actor": actor, "place": f"{passes[0]:g}, {passes[1]:g}", "within": 3.0},
        ],
    }


def brighter() -> list[list[Json]]:
    """Fair readings of 'more light': a higher exposure, the street lights on, or daylight again."""
    return [[env(exposure_min=1.1)], [env(street_lights="on")], [env(time_from="07:00", time_to="17:30")]]


# The ego (eastbound at 5 m/s from x = -60) halts short of the west crosswalk: its front never passes x = -13.
EGO_HALTS_AT_WEST_CROSSWALK = stops_before(EGO, -13.0, -1.75, 20.0)


# --- Earlier turns several cases start from ---------------------------------------------------------------
LEAD_CAR_35 = turn(
    "Put a car 35 m ahead of the ego in its lane, driving at 2 m/s.",
    add("passenger_car", where=ahead_of(EGO, 35), behaviour=drive(2.0, EAST)),
)
LEAD_CAR_20_PARKED = turn("Park a car in the ego's lane 20 m ahead.", add("passenger_car", where=ahead_of(EGO, 20)))
RUBBLE_30 = turn("Put some broken concrete in the ego's lane 30 m ahead.", add("cement_rubble", where=ahead_of(EGO, 30)))
RUBBLE_LOT_B = turn("Leave a pile of rubble in lot B.", add("cement_rubble", where=loc("at", "parking lot B")))
HEAVY_RAIN = turn("Heavy rain.", weather("rain", 0.9))
STREET_LIGHTS_ON = turn("Street lights on.", lighting(street_lights="on"))
CONES_4_NORTH = turn("Four cones at the north crosswalk.", add("traffic_cone", 4, loc("at", "north crosswalk")))
CONES_5_NORTH = turn("Five cones at the north crosswalk.", add("traffic_cone", 5, loc("at", "north crosswalk")))
TRUCK_MAIN_GATE = turn("A truck at the main gate.", add("truck", where=loc("at", "main gate")))


# --- Search: questions change nothing; the answer names what was asked for ---------------------------------
SEARCH_CASES: list[Json] = [
    # direct
    ask("direct", "fountain_to_east_gate", CURATOR,
        "For the visitor guide: how far is the fountain from the east gate, in metres?", ["47.2"],
        [measure("fountain", "east gate")]),
    ask("direct", "cars_in_parking_b", BRAZIL, "How many cars have in the parking B?", [CAR_W, SUV, CAR_E],
        [find(category="vehicles", near="parking lot B", within=1)]),
    ask("direct", "lamp_standards_main_street", SPARKY, "How many lamp standards are there along Main Street, all up?",
        ["12", "street_light_1", "street_light_12"], [find(category="street_light", lane="Main Street")]),
    ask("direct", "hydrant_where", MANDARIN, "Fire hydrant where? Give me coordinate.", [HYDRANT, "16", "5.5"],
        [find(category="fire_hydrant")]),
    ask("direct", "campus_drive_lanes", MARKDOWN,
        "- question: which lanes does Campus Drive have?\n- format: lane ids, no edits", [NORTH, SOUTH],
        [lanes(road="Campus Drive")]),
    ask("direct", "main_street_limit", SARCASTIC,
        "Since apparently nothing in here is labelled: what's the speed limit on Main Street?", ["8"],
        [lanes(road="Main Street")]),
    ask("direct", "cycle_count_benches", WAREHOUSE, "Cycle count: how many benches have we got on site, and which?",
        [BENCH], [find(category="bench")]),
    ask("direct", "ego_to_bus_stop", KIWI, "How far's the ego from the bus stop, eh?", ["30.2"], [measure("bus stop")]),
    ask("direct", "two_nearest_lookups", MARKDOWN,
        "- q1: which tree is nearest the JTEKT entrance (with distance)?\n- q2: which street light is nearest the "
        "fountain?", [TREE_FOUNTAIN_NW, "44.2", LAMP_BY_FOUNTAIN],
        [find(category="tree", nearest_to="JTEKT building entrance"),
         find(category="street_light", nearest_to="fountain")]),
    ask("direct", "library_to_union", MANDARIN, "Library entrance to Student Union entrance, distance how much?",
        ["90.9"], [measure("Library entrance", "Student Union entrance")]),
    ask("direct", "lamp_nearest_fountain", SPARKY, "Which street light's closest to the fountain?",
        [LAMP_BY_FOUNTAIN, "34.6"], [find(category="street_light", nearest_to="fountain")]),
    ask("direct", "headcount_bus_stop", WAREHOUSE, "Headcount: how many people are standing at the bus stop now?",
        ["pedestrian_1", "pedestrian_2", "pedestrian_3"],
        [find(category="pedestrian", near="bus stop", within=12)],
        setup=[turn("Stage three people at the bus stop.", add("pedestrian", 3, loc("on_sidewalk", "bus stop")),
                    planned=True)]),
    impossible("search", "direct", "dairy_distance", KIWI, "How far's the dairy from the east gate, bro?",
               [measure("dairy", "east gate")]),
    # indirect
    ask("indirect", "wayfinding_library_union", CURATOR,
        "I'm drafting the wayfinding signs between the Library and the Student Union. What distance should they "
        "quote, door to door as the crow flies?", ["90.9"], [measure("Library entrance", "Student Union entrance")]),
    ask("indirect", "lamp_post_for_bicycle", BRAZIL,
        "I want to leave my bicycle close to the stop of bus, but only with light. Which lamp post stays more close "
        "from there?", [LAMP_BY_BUS_STOP, "8"], [find(category="street_light", nearest_to="bus stop")]),
    ask("indirect", "signals_to_isolate", SPARKY,
        "Got to isolate the signals before I open them up. How many traffic lights am I dealing with, and where?",
        [LIGHT_SW, LIGHT_NE], [find(category="traffic_light")]),
    ask("indirect", "ego_lane_and_speed", MANDARIN, "I want know our car now is drive in which lane, and how fast.",
        [EAST, "5"], [properties(asset=EGO)]),
    ask("indirect", "before_i_edit", MARKDOWN,
        "## Before I edit anything\n- need: current time of day\n- need: current weather\n- don't change anything yet",
        ["12:00", "clear"], [environment()]),
    ask("indirect", "where_is_the_bin", SARCASTIC,
        "I'd love to move the bin, but first I'd have to find the thing. Where exactly did you hide it?",
        [BIN, "-33.5"], [find(category="trash_bin")]),
    ask("indirect", "route_main_gate_lot_b", WAREHOUSE,
        "Planning a delivery run from the main gate to lot B. What's the straight-line distance?", ["141.5"],
        [measure("main gate", "parking lot B")]),
    ask("indirect", "carpark_for_the_ute", KIWI,
        "Reckon I'll leave the ute in whichever carpark's closer to the Engineering Hall. Which one's that?",
        ["parking lot A"], [landmarks(query="parking lot", nearest_to="Engineering Hall entrance")]),
    case("search", "indirect", "before_commissioning", CURATOR,
         "Before I commission a new piece for the courtyard, I need to know what already stands within twenty metres "
         "of the fountain.",
         [says(all_of=[TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE], none_of=[TREE_LIBRARY, TREE_LOT_A]), only()],
         [find(near="fountain", within=20)]),
    case("search", "indirect", "lane_by_hydrant", SPARKY,
         "I'll be digging round that hydrant next week and have to cone off whatever lane's closest. Which lane is it?",
         [says(all_of=[WEST], none_of=[EAST, NORTH, SOUTH]), only()], [lanes(near=HYDRANT)]),
    ask("indirect", "where_bus_stand", MANDARIN, "Just now the bus I add, it stand where?", [NEW_BUS],
        [find(category="bus")],
        setup=[turn("Add one bus at east gate.", add("bus", where=loc("at", "east gate")), planned=True)]),
    ask("indirect", "still_a_monsoon", SARCASTIC,
        "So, is it still pouring in there, or has the monsoon finally been cancelled?", ["rain"], [environment()],
        setup=[HEAVY_RAIN]),
    impossible("search", "indirect", "loading_dock", WAREHOUSE,
               "I'm routing the trucks in to the loading dock. How far is the dock from the east gate?",
               [measure("loading dock", "east gate")]),
    # vague
    ask("vague", "inventory_bus_stop", MARKDOWN, "- inventory: whatever stands around the bus stop\n- changes: none",
        [BENCH, BIN], [find(near="bus stop", within=10)]),
    ask("vague", "around_the_crossing", BRAZIL, "What have around the crossing of the two streets?", [LIGHT_SW, LIGHT_NE],
        [find(near="main intersection", within=15)]),
    ask("vague", "lighting_situation", SPARKY, "What's the lighting situation like out there?", ["off"],
        [environment()]),
    ask("vague", "parking_b_have_what", MANDARIN, "Parking lot B inside have what thing?", [CAR_W, SUV, CAR_E],
        [find(near="parking lot B", within=1)]),
    ask("vague", "on_the_roads", MARKDOWN, "- what's standing on the road lanes right now?\n- just list it, no changes",
        [EGO], [find(on_lane=True)]),
    ask("vague", "landmarks_on_offer", SARCASTIC,
        "Go on then, tell me what this wonderful world has in the way of landmarks.", ["fountain", "east gate", "bus stop"],
        [landmarks()]),
    ask("vague", "stock_take_vehicles", WAREHOUSE, "Quick stock take of the vehicles on site.", [SUV, CAR_W, CAR_E],
        [find(category="vehicles")]),
    ask("vague", "weather_doing", KIWI, "What's the weather doing, eh?", ["clear"], [environment()]),
    ask("vague", "ego_finish", CURATOR, "What does the ego look like at present - its finish, its colour?", ["default"],
        [properties(asset=EGO)]),
    ask("vague", "what_hour", SARCASTIC, "What time is it even meant to be in there? Or is that a secret too?", ["12:00"],
        [environment()]),
    ask("vague", "where_cones_ended_up", KIWI, "Where'd those cones end up, eh?",
        ["traffic_cone_1", "traffic_cone_2", "traffic_cone_3", "traffic_cone_4"], [find(category="traffic_cone")],
        setup=[turn("Chuck four cones at the north crossing.", add("traffic_cone", 4, loc("at", "north crosswalk")),
                    planned=True)]),
    ask("vague", "staged_by_lot_b_entrance", WAREHOUSE, "What's staged round the lot B entrance?",
        ["street_light_8", "street_light_9"], [find(near="parking lot B entrance", within=15)]),
    impossible("search", "vague", "museum_where", MANDARIN, "The museum where? How far from library?",
               [measure("museum", "Library entrance")]),
    # erroneous
    ask("erroneous", "fountian_libary", CURATOR, "How far is the fountian from the Libary entrence?", ["128.4"],
        [measure("fountain", "Library entrance")]),
    ask("erroneous", "tree_more_near_parking_a", BRAZIL, "Wich is the tree more near of the parking A?", [TREE_LOT_A],
        [find(category="tree", nearest_to="parking lot A")]),
    ask("erroneous", "lamp_nearst_stop_sgin", SPARKY, "wheres the nearst lamp post to the stop sgin", [LAMP_BY_STOP_SIGN, "0.6"],
        [find(category="street_light", nearest_to=STOP)]),
    ask("erroneous", "how_many_tree", MANDARIN, "How many tree in this map? Each one where?", TREES,
        [find(category="tree")]),
    ask("erroneous", "hydarnt_from_ego", MARKDOWN, "1. find the hydarnt\n2. tell me how far it is from teh ego",
        ["76.3"], [measure(HYDRANT)]),
    ask("erroneous", "wether_classified", SARCASTIC, "Oh brilliant. Whats the wether doing now, or is that classified?",
        ["clear"], [environment()]),
    ask("erroneous", "suv_wieght", WAREHOUSE, "How heavey is the SUV? Need it for the wieghbridge.", ["2100"],
        [properties(asset=SUV)]),
    ask("erroneous", "east_gait_distance", KIWI, "how far to the east gait from the ego bro", ["160"],
        [measure("east gate")]),
    ask("erroneous", "lanes_main_stret", CURATOR, "Which lanes run along Main Stret?", [EAST, WEST],
        [lanes(road="Main Street")]),
    ask("erroneous", "where_stay_truck", BRAZIL, "Where stay the truck that I put?", [NEW_TRUCK], [find(category="truck")],
        setup=[turn("Put one truck in the parking A.", add("truck", where=loc("at", "parking lot A")), planned=True)]),
    ask("erroneous", "ego_face_directon", MANDARIN, "Ego car face which directon now?", ["0 deg"],
        [properties(asset=EGO)]),
    ask("erroneous", "too_traffic_lights", WAREHOUSE, "Distance between the too traffic lights?", ["22.7"],
        [measure(LIGHT_SW, LIGHT_NE)]),
    impossible("search", "erroneous", "rounabout", SARCASTIC, "Great. And how far is the rounabout from here? Oh wait.",
               [measure("roundabout")]),
]


# --- Addition: new things where they were asked for, and nothing else touched ------------------------------
ADDITION_CASES: list[Json] = [
    # direct
    case("addition", "direct", "bench_for_visitors", CURATOR, "Please install one bench beside the fountain for visitors.",
         [delta("bench", 1, 1), near("fountain", 10, "bench"), only("bench")],
         [add("bench", where=loc("next_to", "fountain"))]),
    case("addition", "direct", "motorbikes_and_bin", KIWI, "Chuck two motorbikes in lot A and a bin by the Library, eh.",
         [delta("motorcycle", 2, 2), near("parking lot A", 2, "motorcycle", min_count=2), delta("trash_bin", 1, 1),
          near("Library entrance", 10, "trash_bin"), only("motorcycle", "trash_bin")],
         [add("motorcycle", 2, loc("at", "parking lot A")), add("trash_bin", where=loc("at", "Library entrance"))]),
    case("addition", "direct", "column_student_union", SPARKY, "Stick a new street light in by the Student Union entrance.",
         [delta("street_light", 1, 1), near("Student Union entrance", 12, "street_light"), only("street_light")],
         [add("street_light", where=loc("at", "Student Union entrance"))]),
    case("addition", "direct", "three_cone_north", MANDARIN, "Help me add three cone at north crosswalk.",
         [delta("traffic_cone", 3, 3), near("north crosswalk", 10, "traffic_cone", min_count=3), only("traffic_cone")],
         [add("traffic_cone", 3, loc("at", "north crosswalk"))]),
    case("addition", "direct", "bus_east_gate_list", MARKDOWN, "- add: 1 bus\n- where: east gate\n- behaviour: parked",
         [delta("bus", 1, 1), near("east gate", 15, "bus"), only("bus")], [add("bus", where=loc("at", "east gate"))]),
    case("addition", "direct", "bin_engineering", SARCASTIC,
         "Would it kill you to add a trash can at the Engineering Hall entrance?",
         [delta("trash_bin", 1, 1), near("Engineering Hall entrance", 8, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("at", "Engineering Hall entrance"))]),
    case("addition", "direct", "truck_main_gate", KIWI, "Chuck a truck at the main gate, cheers.",
         [delta("truck", 1, 1), near("main gate", 15, "truck"), only("truck")], [add("truck", where=loc("at", "main gate"))]),
    case("addition", "direct", "tree_library", KIWI, "Chuck a tree next to the Library entrance, eh.",
         [delta("tree", 1, 1), near("Library entrance", 12, "tree"), only("tree")],
         [add("tree", where=loc("next_to", "Library entrance"))]),
    case("addition", "direct", "crossing_sign_west", MARKDOWN,
         "- add: pedestrian crossing sign\n- where: west crosswalk\n- why: people should know where to cross",
         [delta("pedestrian_sign", 1, 1), near("west crosswalk", 10, "pedestrian_sign"), only("pedestrian_sign")],
         [add("pedestrian_sign", where=loc("at", "west crosswalk"))]),
    case("addition", "direct", "car_25_in_front", BRAZIL, "Put one car 25 meters in front of the ego, in the same lane.",
         [delta(CARS, 1, 1), in_lane(EAST, CARS), near(None, 5, CARS, point=(-35.0, -1.75)), only(*CARS)],
         [add("passenger_car", where=ahead_of(EGO, 25))]),
    case("addition", "direct", "truck_and_bus_gates", WAREHOUSE, "Stage a truck at the east gate and a bus at the main gate.",
         [delta("truck", 1, 1), delta("bus", 1, 1), near("east gate", 15, "truck"), near("main gate", 15, "bus"),
          only("truck", "bus")],
         [add("truck", where=loc("at", "east gate")), add("bus", where=loc("at", "main gate"))]),
    case("addition", "direct", "another_at_jtekt", KIWI, "Sweet. Another one of those at the JTEKT entrance, cheers.",
         [delta("bench", 1, 1), near("JTEKT building entrance", 10, "bench", scope="added"), only("bench")],
         [add("bench", where=loc("at", "JTEKT building entrance"))],
         setup=[turn("Chuck a bench by the fountain.", add("bench", where=loc("next_to", "fountain")), planned=True)]),
    impossible("addition", "direct", "forklift", WAREHOUSE, "Add a forklift at the lot B entrance.",
               [add("forklift", where=loc("at", "parking lot B entrance"))]),
    # indirect
    case("addition", "indirect", "library_rest_feet", CURATOR,
         "Visitors leaving the Library have nowhere at all to rest their feet.",
         [delta("bench", 1, None), near("Library entrance", 12, "bench"), only("bench")],
         [add("bench", where=loc("at", "Library entrance"))]),
    case("addition", "indirect", "bus_people_sit", BRAZIL,
         "The people who wait the bus need to sit, and one only bench is not enough for everybody.",
         [delta("bench", 1, None), near("bus stop", 12, "bench", scope="added"), only("bench")],
         [add("bench", where=loc("on_sidewalk", "bus stop"))]),
    case("addition", "indirect", "jtekt_pitch_black", SPARKY,
         "That stretch outside the JTEKT doors is pitch black at night. Needs a column putting in.",
         [delta("street_light", 1, None), near("JTEKT building entrance", 12, "street_light"), only("street_light")],
         [add("street_light", where=loc("at", "JTEKT building entrance"))]),
    case("addition", "indirect", "engineering_need_green", MANDARIN,
         "Engineering Hall front there too empty, need some green plant.",
         [delta("tree", 1, None), near("Engineering Hall entrance", 15, "tree"), only("tree")],
         [add("tree", where=loc("next_to", "Engineering Hall entrance"))]),
    case("addition", "indirect", "slow_vehicle_goal", MARKDOWN,
         "**Goal:** see how the ego handles a slow vehicle ahead\n- vehicle: any car\n- gap: ~40 m, same lane",
         [delta(TRAFFIC, 1, 1), in_lane(EAST, TRAFFIC), near(None, 8, TRAFFIC, point=(-20.0, -1.75)), only(*TRAFFIC)],
         [add("passenger_car", where=ahead_of(EGO, 40), behaviour=drive(2.0, EAST))]),
    case("addition", "indirect", "bus_stop_no_bus", SARCASTIC,
         "Oh sure, a bus stop with no bus. Very realistic. Fix it.",
         [delta("bus", 1, 1), near("bus stop", 15, "bus"), only("bus")],
         [add("bus", where=loc("in_lane", "bus stop", lane=EAST))]),
    case("addition", "indirect", "packaging_student_union", WAREHOUSE,
         "Our inbound drivers need somewhere to bin the packaging by the Student Union doors.",
         [delta("trash_bin", 1, None), near("Student Union entrance", 10, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("at", "Student Union entrance"))]),
    case("addition", "indirect", "fountain_bugger_all_shade", KIWI,
         "The kids down at the fountain reckon there's bugger all shade.",
         [delta("tree", 1, None), near("fountain", 15, "tree", scope="added"), only("tree")],
         [add("tree", where=loc("next_to", "fountain"))]),
    case("addition", "indirect", "fire_marshal_hydrant", CURATOR,
         "The fire marshal insists on a hydrant near the Engineering Hall entrance before the exhibition opens.",
         [delta("fire_hydrant", 1, 1), near("Engineering Hall entrance", 12, "fire_hydrant"), only("fire_hydrant")],
         [add("fire_hydrant", where=loc("at", "Engineering Hall entrance"))]),
    case("addition", "indirect", "somebody_sitting_close", BRAZIL, "Now I need somebody sitting close of it.",
         [delta("pedestrian", 1, 1), near(NEW_BENCH, 4, "pedestrian"), only("pedestrian")],
         [add("pedestrian", where=loc("next_to", NEW_BENCH))],
         setup=[turn("Put a bench in the front of the Student Union.",
                     add("bench", where=loc("at", "Student Union entrance")), planned=True)]),
    case("addition", "indirect", "works_at_library", SPARKY,
         "We're opening the ground up at the Library entrance, so I need a barrier and a roadworks sign there.",
         [delta("road_barrier", 1, 1), delta("construction_sign", 1, 1),
          near("Library entrance", 12, ["road_barrier", "construction_sign"], min_count=2),
          only("road_barrier", "construction_sign")],
         [add("road_barrier", where=loc("at", "Library entrance")),
          add("construction_sign", where=loc("next_to", "Library entrance"))]),
    case("addition", "indirect", "van_waiting_behind", WAREHOUSE,
         "We need a delivery van waiting 20 m behind the ego, same lane.",
         [delta("truck", 1, 1), in_lane(EAST, "truck"), near(None, 5, "truck", point=(-80.0, -1.75)), only("truck")],
         [add("truck", where=ahead_of(EGO, -20))]),
    impossible("addition", "indirect", "bronze_statue", CURATOR,
               "The courtyard needs a bronze statue on a plinth beside the fountain, as its centrepiece.",
               [add("statue", where=loc("next_to", "fountain"))]),
    # vague
    case("addition", "vague", "animate_union_forecourt", CURATOR,
         "The Student Union forecourt feels under-populated. Animate it a little.",
         [delta("pedestrian", 1, None), near("Student Union entrance", 15, "pedestrian"), only("pedestrian")],
         [add("pedestrian", 3, loc("at", "Student Union entrance"))]),
    case("addition", "vague", "parking_a_empty", BRAZIL, "The parking A is too much empty, put some cars there.",
         [delta(CARS, 2, None), near("parking lot A", 2, CARS, min_count=2), only(*CARS)],
         [add("passenger_car", 3, loc("at", "parking lot A"))]),
    case("addition", "vague", "more_light_bus_stop", SPARKY, "Needs a bit more light down by the bus stop.",
         [only("street_light", env=True)], [add("street_light", where=loc("on_sidewalk", "bus stop"))],
         alternatives=[[delta("street_light", 1, None), near("bus stop", 15, "street_light")], *brighter()[:2]]),
    case("addition", "vague", "bus_stop_more_people", MANDARIN, "Bus stop there, more people please.",
         [delta("pedestrian", 1, None), near("bus stop", 12, "pedestrian"), only("pedestrian")],
         [add("pedestrian", 3, loc("on_sidewalk", "bus stop"))]),
    case("addition", "vague", "traffic_main_street", MARKDOWN, "- add some traffic\n- on Main Street\n- moving, not parked",
         [delta(TRAFFIC, 1, None), does(["drive_lane", "follow_path"], TRAFFIC), only(*TRAFFIC)],
         [add("passenger_car", 2, loc("in_lane", "east gate", lane=WEST), behaviour=drive(6.0, WEST))],
         alternatives=[[near(EAST, 3, TRAFFIC)], [near(WEST, 3, TRAFFIC)]]),
    case("addition", "vague", "ghost_town_lot_b", SARCASTIC,
         "Lot B looks like a ghost town. Maybe put a couple of cars in it? Just a thought.",
         [delta(CARS, 2, 3), near("parking lot B", 2, CARS, scope="added", min_count=2), only(*CARS)],
         [add("passenger_car", 2, loc("at", "parking lot B"))]),
    case("addition", "vague", "marshal_cones_lot_b", WAREHOUSE,
         "Put a few cones out near the lot B entrance to marshal the traffic.",
         [delta("traffic_cone", 3, None), near("parking lot B entrance", 12, "traffic_cone", min_count=3),
          only("traffic_cone")],
         [add("traffic_cone", 4, loc("at", "parking lot B entrance"))]),
    case("addition", "vague", "heaps_people_fountain", KIWI, "Heaps more people round the fountain would be choice.",
         [delta("pedestrian", 3, None), near("fountain", 15, "pedestrian", min_count=3), only("pedestrian")],
         [add("pedestrian", 5, loc("next_to", "fountain"))]),
    case("addition", "vague", "somewhere_to_sit_jtekt", CURATOR,
         "Somewhere to sit near the JTEKT entrance, please - nothing elaborate.",
         [delta("bench", 1, None), near("JTEKT building entrance", 12, "bench"), only("bench")],
         [add("bench", where=loc("at", "JTEKT building entrance"))]),
    case("addition", "vague", "more_two_same_place", BRAZIL, "Put more two in the same place.",
         [delta("traffic_cone", 2, 2), near("Library entrance", 12, "traffic_cone", scope="added", min_count=2),
          only("traffic_cone")],
         [add("traffic_cone", 2, loc("at", "Library entrance"))],
         setup=[turn("Put two cones in the front of the Library.", add("traffic_cone", 2, loc("at", "Library entrance")),
                     planned=True)]),
    case("addition", "vague", "couple_more_bollards", SPARKY, "Give us a couple more of them there.",
         [delta("bollard", 2, 3), near("JTEKT building entrance", 12, "bollard", scope="added", min_count=2),
          only("bollard")],
         [add("bollard", 2, loc("at", "JTEKT building entrance"))],
         setup=[turn("Stick a bollard at the JTEKT entrance.", add("bollard", where=loc("at", "JTEKT building entrance")),
                     planned=True)]),
    case("addition", "vague", "bus_stop_depressing", SARCASTIC,
         "The bus stop is depressing. Another bench, a bin, anything. Both, ideally.",
         [delta("bench", 1, None), delta("trash_bin", 1, None), near("bus stop", 12, "bench", scope="added"),
          near("bus stop", 12, "trash_bin", scope="added"), only("bench", "trash_bin")],
         [add("bench", where=loc("on_sidewalk", "bus stop")), add("trash_bin", where=loc("at", "bus stop"))]),
    impossible("addition", "vague", "chilly_bin", KIWI, "Chuck a chilly bin full of beers by the fountain, mate.",
               [add("chilly bin", where=loc("next_to", "fountain"))]),
    # erroneous
    case("addition", "erroneous", "bech_engineering", CURATOR, "Kindly add a bech beside the Engineering Hall entrence.",
         [delta("bench", 1, 1), near("Engineering Hall entrance", 10, "bench"), only("bench")],
         [add("bench", where=loc("next_to", "Engineering Hall entrance"))]),
    case("addition", "erroneous", "bycicle_library", BRAZIL, "Put one bycicle in the front of the libary.",
         [delta("bicycle", 1, 1), near("Library entrance", 10, "bicycle"), only("bicycle")],
         [add("bicycle", where=loc("at", "Library entrance"))]),
    case("addition", "erroneous", "lamp_post_libary_doors", SPARKY, "stick a lamp post by the libary doors",
         [delta("street_light", 1, 1), near("Library entrance", 12, "street_light", scope="added"), only("street_light")],
         [add("street_light", where=loc("at", "Library entrance"))]),
    case("addition", "erroneous", "two_pedestrain_sidewalk", MANDARIN, "Add two pedestrain at bus stop, stand on sidewalk.",
         [delta("pedestrian", 2, 2), near("bus stop", 10, "pedestrian", min_count=2), on(["sidewalk"], "pedestrian"),
          only("pedestrian")],
         [add("pedestrian", 2, loc("on_sidewalk", "bus stop"))]),
    case("addition", "erroneous", "five_conse_lot_b", MARKDOWN, "1. add 5 conse\n2. put them in lot b",
         [delta("traffic_cone", 5, 5), near("parking lot B", 2, "traffic_cone", min_count=5), only("traffic_cone")],
         [add("traffic_cone", 5, loc("at", "parking lot B"))]),
    case("addition", "erroneous", "one_motorcyle", SARCASTIC,
         "Can you add ONE motorcyle at the east gate without breaking everything?",
         [delta("motorcycle", 1, 1), near("east gate", 15, "motorcycle"), only("motorcycle")],
         [add("motorcycle", where=loc("at", "east gate"))]),
    case("addition", "erroneous", "too_trucks_lot_a", WAREHOUSE, "Stage too trucks in lot A for the moring run.",
         [delta("truck", 2, 2), near("parking lot A", 3, "truck", min_count=2), only("truck")],
         [add("truck", 2, loc("at", "parking lot A"))]),
    case("addition", "erroneous", "rubish_bin_bus_stop", KIWI, "chuck a rubish bin by the bus stop eh",
         [delta("trash_bin", 1, 1), near("bus stop", 10, "trash_bin", scope="added"), only("trash_bin")],
         [add("trash_bin", where=loc("at", "bus stop"))]),
    case("addition", "erroneous", "hydarnt_jtekt", CURATOR, "Add a fire hydarnt at the JTEKT entrence, as the fire officer requested.",
         [delta("fire_hydrant", 1, 1), near("JTEKT building entrance", 10, "fire_hydrant"), only("fire_hydrant")],
         [add("fire_hydrant", where=loc("at", "JTEKT building entrance"))]),
    case("addition", "erroneous", "pessoa_on_sidewalk", BRAZIL,
         "Put one pessoa - sorry, one person - standing in the sidewalk 15 meter in front of the ego, right side.",
         [delta("pedestrian", 1, 1), near(None, 4, "pedestrian", point=(-45.0, -5.5)), on(["sidewalk"], "pedestrian"),
          only("pedestrian")],
         [add("pedestrian", where=ahead_of(EGO, 15, side="right"))]),
    case("addition", "erroneous", "same_thing_east_gate", MANDARIN, "Same thing, also put one at east gate plese.",
         [delta("bus", 1, 1), near("east gate", 15, "bus", scope="added"), only("bus")],
         [add("bus", where=loc("at", "east gate"))],
         setup=[turn("Add bus at main gate.", add("bus", where=loc("at", "main gate")), planned=True)]),
    case("addition", "erroneous", "tree_n_bench_engneering", KIWI, "chuck a tree n a bench by the Engneering Hall",
         [delta("tree", 1, 1), delta("bench", 1, 1), near("Engineering Hall entrance", 15, "tree"),
          near("Engineering Hall entrance", 15, "bench"), only("tree", "bench")],
         [add("tree", where=loc("next_to", "Engineering Hall entrance")),
          add("bench", where=loc("at", "Engineering Hall entrance"))]),
    impossible("addition", "erroneous", "eleven_buss", BRAZIL, "Put eleven buss in the parking B for the excursion.",
               [add("bus", 11, loc("at", "parking lot B"))]),
]


# --- Removal: the named things gone, everything else kept ---------------------------------------------------
REMOVAL_CASES: list[Json] = [
    # direct
    case("removal", "direct", "deaccession_bench", CURATOR, "Please de-accession the bench at the bus stop.",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "direct", "semaphore_north_east", BRAZIL, "Remove the semaphore of the north-east corner, please.",
         [gone(LIGHT_NE), kept(LIGHT_SW), only(assets=[LIGHT_NE])], [remove(LIGHT_NE)]),
    case("removal", "direct", "lamp_by_stop_sign", SPARKY,
         "Take out the lamp post at the west crosswalk - the one right next to the stop sign.",
         [gone(LAMP_BY_STOP_SIGN), kept(STOP), only(assets=[LAMP_BY_STOP_SIGN])], [remove(LAMP_BY_STOP_SIGN)]),
    case("removal", "direct", "delete_hydrant", MANDARIN, "Please delete the fire hydrant.",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "direct", "remove_trash_bin_id", MARKDOWN, "- remove: `trash_bin_1`\n- keep: everything else",
         [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "direct", "stop_sign_and_bench", SARCASTIC,
         "Get rid of the stop sign, and while you're at it the bench too. Yes, really. No, I don't need a lecture.",
         [gone(STOP, BENCH), only(assets=[STOP, BENCH])], [remove(STOP), remove(BENCH)]),
    case("removal", "direct", "pull_suv_keep_cars", WAREHOUSE, "Pull the SUV out of lot B. Leave the two cars where they are.",
         [gone(SUV), kept(CAR_W, CAR_E), only(assets=[SUV])], [remove(SUV)]),
    case("removal", "direct", "all_trees", KIWI, "Get rid of all the trees, eh.", [count("tree", 0, 0), only("tree")],
         [remove(category="tree")]),
    case("removal", "direct", "bin_and_hydrant", MARKDOWN, "- remove: the bin\n- remove: the hydrant\n- reason: clutter",
         [gone(BIN, HYDRANT), only(assets=[BIN, HYDRANT])], [remove(BIN), remove(HYDRANT)]),
    case("removal", "direct", "all_cars_lot_b", KIWI, "Clear all the cars outta lot B, bro.",
         [gone(*LOT_B_ROW), only(assets=LOT_B_ROW)], [remove(*LOT_B_ROW)]),
    case("removal", "direct", "north_columns", SPARKY, "Take down all six lamp posts on the north side of Main Street.",
         [gone(*NORTH_LAMPS), kept(*SOUTH_LAMPS), only(assets=NORTH_LAMPS)], [remove(*NORTH_LAMPS)]),
    case("removal", "direct", "truck_off_site", WAREHOUSE, "Pull the truck off site.",
         [count("truck", 0, 0), delta("truck", -1, -1), only("truck")], [remove(NEW_TRUCK)], setup=[TRUCK_MAIN_GATE]),
    impossible("removal", "direct", "engineering_hall", CURATOR,
               "Remove the Engineering Hall; we need the space for a sculpture garden.", [remove("engineering")]),
    # indirect
    case("removal", "indirect", "tree_obscures_facade", CURATOR,
         "The tree by the Library obscures the facade we want visitors to photograph.",
         [gone(TREE_LIBRARY), kept(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE, TREE_LOT_A), only(assets=[TREE_LIBRARY])],
         [remove(TREE_LIBRARY)]),
    case("removal", "indirect", "hydrant_in_the_way", BRAZIL,
         "The hydrant is in the middle of the way of the people who walk. I don't want it more.",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "indirect", "signals_decommissioned", SPARKY,
         "Both sets of traffic signals are being decommissioned for the new junction layout.",
         [gone(LIGHT_SW, LIGHT_NE), only("traffic_light")], [remove(LIGHT_SW, LIGHT_NE)]),
    case("removal", "indirect", "bench_nobody_use", MANDARIN, "The bench at bus stop, nobody use. Not need anymore.",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "indirect", "stop_sign_confuses", MARKDOWN,
         "**Problem:** the stop sign confuses the test drivers\n**Fix:** it shouldn't be in the scene",
         [gone(STOP), only(assets=[STOP])], [remove(STOP)]),
    case("removal", "indirect", "suv_doing_nothing", SARCASTIC,
         "Love how the SUV just sits there in lot B doing absolutely nothing. Maybe it doesn't need to exist?",
         [gone(SUV), kept(CAR_W, CAR_E), only(assets=[SUV])], [remove(SUV)]),
    case("removal", "indirect", "clear_lot_b_for_staging", WAREHOUSE,
         "Lot B's needed for staging tomorrow, so the three cars sitting in it have to be cleared.",
         [gone(*LOT_B_ROW), only(assets=LOT_B_ROW)], [remove(*LOT_B_ROW)]),
    case("removal", "indirect", "munted_lamp_post", KIWI,
         "That lamp post on the south side right by the bus stop is munted, get it outta there.",
         [gone(LAMP_BY_BUS_STOP), only(assets=[LAMP_BY_BUS_STOP])], [remove(LAMP_BY_BUS_STOP)]),
    case("removal", "indirect", "installation_closed", CURATOR,
         "The installation at the Library has closed; please strike the cones.",
         [delta("traffic_cone", -3, -3), count("traffic_cone", 0, 0), only("traffic_cone")],
         [remove(category="traffic_cone")],
         setup=[turn("Place three cones at the Library entrance.", add("traffic_cone", 3, loc("at", "Library entrance")),
                     planned=True)]),
    case("removal", "indirect", "obra_finished", BRAZIL, "The obra finished, so the rubble is not more necessary.",
         [gone(RUBBLE), only("cement_rubble")], [remove(RUBBLE)], setup=[RUBBLE_30]),
    case("removal", "indirect", "trees_in_the_lines", SPARKY,
         "The trees round the fountain are growing into the overhead lines, they've got to come out.",
         [gone(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE), kept(TREE_LIBRARY, TREE_LOT_A), only("tree")],
         [remove(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE)]),
    case("removal", "indirect", "send_pickers_home", WAREHOUSE, "Shift's over - send all the pickers home.",
         [delta("pedestrian", -4, -4), count("pedestrian", 0, 0), only("pedestrian")], [remove(category="pedestrian")],
         setup=[turn("Stage four workers at the Student Union entrance.",
                     add("pedestrian", 4, loc("at", "Student Union entrance")), planned=True)]),
    impossible("removal", "indirect", "north_crosswalk_pointless", SARCASTIC,
               "The north crosswalk is pointless, obviously. Nobody uses it. Delete it.", [remove("crossing_north")]),
    # vague
    case("removal", "vague", "declutter_ne_corner", CURATOR,
         "Declutter the north-east corner of the crossroads a touch.",
         [delta(["traffic_light", "fire_hydrant", "street_light"], None, -1),
          only(assets=[LIGHT_NE, HYDRANT, LAMP_NE])],
         [remove(HYDRANT)]),
    case("removal", "vague", "too_many_lamp_posts", BRAZIL, "Have too many lamp posts. Take off some.",
         [delta("street_light", -11, -1), only("street_light")], [remove("street_light_3", "street_light_10")]),
    case("removal", "vague", "thin_the_cones", SPARKY, "Thin the cones out a bit, there's way too many of 'em.",
         [delta("traffic_cone", -5, -1), only("traffic_cone")], [remove(category="traffic_cone", count=3)],
         setup=[turn("Stick six cones in lot A.", add("traffic_cone", 6, loc("at", "parking lot A")), planned=True)]),
    case("removal", "vague", "parking_b_too_many", MANDARIN, "Parking B car too many, remove some.",
         [delta(CARS, -2, -1), only(*CARS)], [remove(CAR_E)]),
    case("removal", "vague", "library_area_cluttered", MARKDOWN,
         "- the area just outside the Library entrance feels cluttered\n- take something away",
         [delta(["street_light", "trash_bin", "tree"], None, -1), only(assets=[LAMP_BY_BUS_STOP, BIN, TREE_LIBRARY])],
         [remove(BIN)]),
    case("removal", "vague", "trees_everywhere", SARCASTIC,
         "Fantastic, trees everywhere. Maybe lose one or two? If that's not too much to ask.",
         [delta("tree", -2, -1), only("tree")], [remove(TREE_LOT_A)]),
    case("removal", "vague", "headcount_by_half", WAREHOUSE, "Too many bodies. Cut the headcount by half.",
         [delta("pedestrian", -2, -2), only("pedestrian")], [remove(category="pedestrian", count=2)],
         setup=[turn("Stage four pickers at the Student Union entrance.",
                     add("pedestrian", 4, loc("at", "Student Union entrance")), planned=True)]),
    case("removal", "vague", "lose_a_couple_cars", KIWI, "Bit too many cars about, eh. Lose a couple.",
         [delta(CARS, -2, -2), only(*CARS)], [remove(CAR_W, CAR_E)]),
    case("removal", "vague", "closest_to_fountain", SARCASTIC,
         "Something's crowding the fountain. Whatever's closest to it - yes, that one - lose it.",
         [gone(TREE_FOUNTAIN_NW), only(assets=[TREE_FOUNTAIN_NW])], [remove(TREE_FOUNTAIN_NW)]),
    case("removal", "vague", "ah_no_take_off", BRAZIL, "Ah no, I changed of idea. Take it off.",
         [count("bicycle", 0, 0), delta("bicycle", -1, -1), only("bicycle")], [remove("bicycle_1")],
         setup=[turn("Put one bicycle in the bus stop.", add("bicycle", where=loc("at", "bus stop")), planned=True)]),
    case("removal", "vague", "south_footway_furniture", SPARKY,
         "Get rid of the street furniture along the south footpath west of the junction - bins, benches, that sort of "
         "thing. Leave the lamps.",
         [gone(BENCH, BIN), kept(*SOUTH_LAMPS), only(assets=[BENCH, BIN, STOP])], [remove(BENCH, BIN)]),
    case("removal", "vague", "clear_the_yard", WAREHOUSE, "Right, clear the yard.",
         [count("traffic_cone", 0, 0), count("road_barrier", 0, 0), delta("traffic_cone", -5, -5), delta("road_barrier", -1, -1),
          only("traffic_cone", "road_barrier")],
         [remove(category="traffic_cone"), remove(category="road_barrier")],
         setup=[turn("Stage five cones and a barrier in lot A.", add("traffic_cone", 5, loc("at", "parking lot A")),
                     add("road_barrier", where=loc("at", "parking lot A")), planned=True)]),
    impossible("removal", "vague", "get_rid_of_ego", KIWI, "Yeah nah, just get rid of the ego, eh. Don't need it.",
               [remove(EGO)]),
    # erroneous
    case("removal", "erroneous", "remvoe_hydrant_footpath", CURATOR, "Please remvoe the hydrant from the north footpath.",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "erroneous", "lixeira_bus_stop", BRAZIL, "Remove the lixeira - the trash - of the bus stop.",
         [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "erroneous", "trafic_light_south_west", SPARKY, "pull the trafic light on the south west corner",
         [gone(LIGHT_SW), kept(LIGHT_NE), only(assets=[LIGHT_SW])], [remove(LIGHT_SW)]),
    case("removal", "erroneous", "street_lamp_south_side", MANDARIN, "Remove all street lamp at south side of Main Street.",
         [gone(*SOUTH_LAMPS), kept(*NORTH_LAMPS), only(assets=SOUTH_LAMPS)], [remove(*SOUTH_LAMPS)]),
    case("removal", "erroneous", "delet_the_suv", MARKDOWN, "1. delet the suv\n2. thats it",
         [gone(SUV), kept(CAR_W, CAR_E), only(assets=[SUV])], [remove(SUV)]),
    case("removal", "erroneous", "delet_the_bench", SARCASTIC, "Delet the bench. Was that so hard? Apparently yes.",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "erroneous", "pul_passanger_cars", WAREHOUSE, "Pul the two passanger cars from lot B, keep the SUV.",
         [gone(CAR_W, CAR_E), kept(SUV), only(assets=[CAR_W, CAR_E])], [remove(CAR_W, CAR_E)]),
    case("removal", "erroneous", "tree_by_lot_a_stuffed", KIWI, "get rid of the tree up by lot A eh, its stuffed",
         [gone(TREE_LOT_A), kept(TREE_LIBRARY, TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE), only(assets=[TREE_LOT_A])],
         [remove(TREE_LOT_A)]),
    case("removal", "erroneous", "secnd_bench", CURATOR,
         "Remove the secnd bench - the new one. The original stays in situ.",
         [gone(NEW_BENCH), kept(BENCH), delta("bench", -1, -1), only("bench")], [remove(NEW_BENCH)],
         setup=[turn("Add a bench beside the fountain.", add("bench", where=loc("next_to", "fountain")), planned=True)]),
    case("removal", "erroneous", "stop_sign_and_hidrant", BRAZIL, "Remove the stop sign and the hidrant, both.",
         [gone(STOP, HYDRANT), only(assets=[STOP, HYDRANT])], [remove(STOP), remove(HYDRANT)]),
    case("removal", "erroneous", "cone_too_many_three", MANDARIN, "Cone too many, remove three piece.",
         [delta("traffic_cone", -3, -3), only("traffic_cone")], [remove(category="traffic_cone", count=3)],
         setup=[CONES_5_NORTH]),
    case("removal", "erroneous", "lamp_nerest_fountian", SPARKY,
         "take down the lamp post nerest the fountian, the rest can stay",
         [gone(LAMP_BY_FOUNTAIN), only(assets=[LAMP_BY_FOUNTAIN])], [remove(LAMP_BY_FOUNTAIN)]),
    impossible("removal", "erroneous", "libary_building", WAREHOUSE, "Remove the Libary building, we need the floor space.",
               [remove("library")]),
]


# --- Positioning: an existing thing put somewhere else ------------------------------------------------------
POSITIONING_CASES: list[Json] = [
    # direct
    case("positioning", "direct", "relocate_bench_fountain", CURATOR, "Relocate the bench to the fountain, please.",
         [near("fountain", 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "direct", "suv_parking_a", MANDARIN, "SUV, put to parking lot A.",
         [near("parking lot A", 2, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    case("positioning", "direct", "column_to_engineering", SPARKY,
         "Move the lamp post that's by the stop sign up to the Engineering Hall entrance.",
         [near("Engineering Hall entrance", 12, asset=LAMP_BY_STOP_SIGN), only(assets=[LAMP_BY_STOP_SIGN])],
         [place(LAMP_BY_STOP_SIGN, loc("at", "Engineering Hall entrance"))]),
    case("positioning", "direct", "bin_to_library", MANDARIN, "The trash bin, put to Library entrance.",
         [near("Library entrance", 8, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", "Library entrance"))]),
    case("positioning", "direct", "car_1_coordinates", MARKDOWN, "- asset: `passenger_car_1`\n- new position: x=40, y=-20",
         [near(None, 1.5, asset=CAR_W, point=(40.0, -20.0)), only(assets=[CAR_W])], [place(CAR_W, xy(40.0, -20.0))]),
    case("positioning", "direct", "hydrant_student_union", SARCASTIC,
         "Put the hydrant by the Student Union entrance. You know, near a building. Where hydrants go.",
         [near("Student Union entrance", 8, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", "Student Union entrance"))]),
    case("positioning", "direct", "suv_lot_b_entrance", WAREHOUSE,
         "Reposition the SUV to the lot B entrance, ready for dispatch.",
         [near("parking lot B entrance", 10, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "parking lot B entrance"))]),
    case("positioning", "direct", "bench_student_union", KIWI, "Shift the bench over to the Student Union, eh.",
         [near("Student Union entrance", 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", "Student Union entrance"))]),
    case("positioning", "direct", "bin_beside_bench", MARKDOWN, "- move: `trash_bin_1`\n- to: right beside the bench",
         [near(BENCH, 3, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", BENCH))]),
    case("positioning", "direct", "east_car_thirty_ahead", BRAZIL,
         "Put the car of the east side of the row in the parking B at 30 meters in front of the ego.",
         [in_lane(EAST, asset=CAR_E), near(None, 4, asset=CAR_E, point=(-30.0, -1.75)), only(assets=[CAR_E])],
         [place(CAR_E, ahead_of(EGO, 30))]),
    case("positioning", "direct", "bench_then_bin", MARKDOWN, "1. bench -> Library entrance\n2. bin -> right next to the bench",
         [near("Library entrance", 8, asset=BENCH), near(BENCH, 4, asset=BIN), only(assets=[BENCH, BIN])],
         [place(BENCH, loc("at", "Library entrance")), place(BIN, loc("next_to", BENCH))]),
    case("positioning", "direct", "truck_into_lot_b", WAREHOUSE, "Move that truck into lot B.",
         [near("parking lot B", 3, "truck"), delta("truck", 0, 0), only("truck")],
         [place(NEW_TRUCK, loc("at", "parking lot B"))],
         setup=[turn("Stage a truck at the east gate.", add("truck", where=loc("at", "east gate")), planned=True)]),
    impossible("positioning", "direct", "suv_on_jtekt_roof", KIWI,
               "Put the SUV up on the roof of the JTEKT building, she'll be right.", [place(SUV, xy(37.0, 30.0))]),
    # indirect
    case("positioning", "indirect", "admire_the_fountain", SARCASTIC,
         "Genius idea, a bench at the bus stop staring at nothing. People would actually sit by the fountain, you know.",
         [near("fountain", 10, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "indirect", "engineering_no_trash", BRAZIL,
         "The students of Engineering complain they have nowhere to throw the trash. The bin need to stay there.",
         [near("Engineering Hall entrance", 8, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", "Engineering Hall entrance"))]),
    case("positioning", "indirect", "hydrant_where_i_dig", SPARKY,
         "That hydrant's right where I need to dig on the north footpath. Stick it by the Library instead.",
         [near("Library entrance", 10, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", "Library entrance"))]),
    case("positioning", "indirect", "suv_pick_up_guest", MANDARIN, "SUV should wait at east gate, for pick up guest.",
         [near("east gate", 12, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "east gate"))]),
    case("positioning", "indirect", "stop_sign_wrong_crossing", MARKDOWN,
         "**Issue:** the stop sign is at the wrong crossing\n**Expected:** it stands at the north crosswalk",
         [near("north crosswalk", 8, asset=STOP), only(assets=[STOP])], [place(STOP, loc("on_sidewalk", "north crosswalk"))]),
    case("positioning", "indirect", "bin_where_people_are", SARCASTIC,
         "Because obviously the best place for a bin is miles from anyone. Put it where people actually go - the "
         "Student Union.",
         [near("Student Union entrance", 8, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", "Student Union entrance"))]),
    case("positioning", "indirect", "suv_blocking_staging", WAREHOUSE,
         "The SUV is blocking my staging area in lot B. Park it over in lot A.",
         [near("parking lot A", 2, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    case("positioning", "indirect", "bench_too_close_road", KIWI,
         "The bench is way too close to the road. Reckon it'd be sweet as by the Library doors.",
         [near("Library entrance", 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("at", "Library entrance"))]),
    case("positioning", "indirect", "sign_follows_exhibition", CURATOR,
         "The exhibition has moved, so the sign must follow it to the JTEKT entrance.",
         [near("JTEKT building entrance", 10, "construction_sign"), delta("construction_sign", 0, 0),
          only("construction_sign")],
         [place(NEW_SIGN, loc("at", "JTEKT building entrance"))],
         setup=[turn("Place a construction sign at the Library entrance.",
                     add("construction_sign", where=loc("at", "Library entrance")), planned=True)]),
    case("positioning", "indirect", "west_car_disturbing", BRAZIL,
         "The car of the west end of the row is disturbing me. I prefer it in the parking A.",
         [near("parking lot A", 2, asset=CAR_W), only(assets=[CAR_W])], [place(CAR_W, loc("at", "parking lot A"))]),
    case("positioning", "indirect", "push_car_out_fifty", SPARKY,
         "Car ahead's too close for this test. Push it out to fifty metres in front of the ego.",
         [in_lane(EAST, asset=NEW_CAR), near(None, 5, asset=NEW_CAR, point=(-10.0, -1.75)), only(assets=[NEW_CAR])],
         [place(NEW_CAR, ahead_of(EGO, 50))], setup=[LEAD_CAR_20_PARKED]),
    case("positioning", "indirect", "collection_at_main_gate", WAREHOUSE,
         "Cars for collection wait at the main gate. Passenger car 2 is due out.",
         [near("main gate", 12, asset=CAR_E), only(assets=[CAR_E])], [place(CAR_E, loc("at", "main gate"))]),
    impossible("positioning", "indirect", "bench_reading_room", CURATOR,
               "Put the bench inside the Library's reading room for the exhibit.", [place(BENCH, xy(-41.0, -30.0))]),
    # vague
    case("positioning", "vague", "bench_contemplative", CURATOR,
         "Find the bench a more contemplative spot, perhaps somewhere under the trees.",
         [only(assets=[BENCH]), moved(BENCH, 2.0)], [place(BENCH, loc("next_to", TREE_FOUNTAIN_NW))],
         alternatives=[[near(tree, 8, asset=BENCH)] for tree in TREES]),
    case("positioning", "vague", "suv_near_library", BRAZIL, "Put the SUV in some place near of the library.",
         [near("Library entrance", 15, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "Library entrance"))]),
    case("positioning", "vague", "bin_off_footpath", SPARKY,
         "Shift the bin somewhere off the footpath, it's in everyone's way.",
         [moved(BIN, 1.0), on(["ground", "paved"], asset=BIN), only(assets=[BIN])], [place(BIN, xy(-20.0, -9.0))]),
    case("positioning", "vague", "hydrant_any_place", MANDARIN, "Hydrant move to other place, anywhere OK.",
         [moved(HYDRANT, 2.0), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", "Library entrance"))]),
    case("positioning", "vague", "suv_other_side_campus", MARKDOWN,
         "- the SUV\n- put it somewhere on the far side of campus from where it is now\n- exact spot doesn't matter",
         [moved(SUV, 80.0), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    case("positioning", "vague", "hydrant_useful", SARCASTIC,
         "Could the hydrant maybe live somewhere it'd actually be useful? Like next to a building, for instance?",
         [moved(HYDRANT, 2.0), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", "JTEKT building entrance"))],
         alternatives=[[near(entrance, 12, asset=HYDRANT)] for entrance in ENTRANCES]),
    case("positioning", "vague", "car_nearer_the_exit", WAREHOUSE, "Park passenger car 1 somewhere nearer a gate.",
         [moved(CAR_W, 10.0), only(assets=[CAR_W])], [place(CAR_W, loc("at", "east gate"))],
         alternatives=[[near("main gate", 20, asset=CAR_W)], [near("east gate", 20, asset=CAR_W)]]),
    case("positioning", "vague", "bench_round_jtekt", KIWI, "Reckon the bench'd be better off somewhere round the JTEKT building, eh.",
         [near("JTEKT building entrance", 15, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", "JTEKT building entrance"))]),
    case("positioning", "vague", "bin_nearer_bench", CURATOR, "The bin would sit better a little nearer the bench, I think.",
         [near(BENCH, 4, asset=BIN), moved(BIN, 1.0), only(assets=[BIN])], [place(BIN, loc("next_to", BENCH))]),
    case("positioning", "vague", "him_close_fountain", BRAZIL, "Put him in some place close of the fountain.",
         [near("fountain", 12, "pedestrian"), delta("pedestrian", 0, 0), only("pedestrian")],
         [place(NEW_WALKER, loc("next_to", "fountain"))],
         setup=[turn("Put one person in the bus stop.", add("pedestrian", where=loc("on_sidewalk", "bus stop")),
                     planned=True)]),
    case("positioning", "vague", "column_nearer_library", SPARKY,
         "The lamp post right by the bus stop wants to be a bit closer to the Library doors.",
         [near("Library entrance", 9, asset=LAMP_BY_BUS_STOP), moved(LAMP_BY_BUS_STOP, 1.0), only(assets=[LAMP_BY_BUS_STOP])],
         [place(LAMP_BY_BUS_STOP, loc("at", "Library entrance"))]),
    case("positioning", "vague", "bus_any_bay_lot_b", WAREHOUSE, "Move it somewhere in lot B. Any bay will do.",
         [near("parking lot B", 3, "bus"), delta("bus", 0, 0), only("bus")], [place(NEW_BUS, loc("at", "parking lot B"))],
         setup=[turn("Stage a bus at the main gate.", add("bus", where=loc("at", "main gate")), planned=True)]),
    impossible("positioning", "vague", "bench_off_the_map", MARKDOWN,
               "- move: the bench\n- to: somewhere out past the east gate, well off the map is fine",
               [place(BENCH, xy(150.0, 0.0))]),
    # erroneous
    case("positioning", "erroneous", "bech_engineering", CURATOR, "Kindly relocate the bech to the Engineering Hall entrence.",
         [near("Engineering Hall entrance", 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", "Engineering Hall entrance"))]),
    case("positioning", "erroneous", "suv_front_student_union", BRAZIL, "Put the suv in front the Studant Union.",
         [near("Student Union entrance", 10, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("at", "Student Union entrance"))]),
    case("positioning", "erroneous", "hydrnat_bus_stopp", SPARKY, "move the hydrnat to the bus stopp",
         [near("bus stop", 8, asset=HYDRANT), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", "bus stop"))]),
    case("positioning", "erroneous", "bench_fountian_side", MANDARIN, "Bench put to fountian side.",
         [near("fountain", 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "erroneous", "teh_bin_jtekt", MARKDOWN, "1. move teh bin\n2. to the JTEKT entrence",
         [near("JTEKT building entrance", 8, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", "JTEKT building entrance"))]),
    case("positioning", "erroneous", "lot_a_not_b", SARCASTIC, "Put the SUV in lot A. LOT A. Not B. Is thta clear enough?",
         [near("parking lot A", 2, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    case("positioning", "erroneous", "pasenger_car_est_gate", WAREHOUSE, "Relocate pasenger car 2 to the est gate for pickup.",
         [near("east gate", 10, asset=CAR_E), only(assets=[CAR_E])], [place(CAR_E, loc("at", "east gate"))]),
    case("positioning", "erroneous", "stop_sign_north_crossin", KIWI, "shift the stop sign up to the north crossin eh",
         [near("north crosswalk", 8, asset=STOP), only(assets=[STOP])], [place(STOP, loc("on_sidewalk", "north crosswalk"))]),
    case("positioning", "erroneous", "hydrant_ten_ahead_right", CURATOR,
         "Please postion the hydrant ten metres ahaed of the ego, on the right-hand footpath.",
         [near(None, 4, asset=HYDRANT, point=(-50.0, -5.5)), on(["sidewalk"], asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, ahead_of(EGO, 10, side="right"))]),
    case("positioning", "erroneous", "desculpa_wrong_place", BRAZIL, "Desculpa, I put in the wrong place. Move it to the Libary.",
         [near("Library entrance", 10, asset=NEW_BENCH), kept(BENCH), delta("bench", 0, 0), only("bench")],
         [place(NEW_BENCH, loc("at", "Library entrance"))],
         setup=[turn("Put one bench in the fountain.", add("bench", where=loc("next_to", "fountain")), planned=True)]),
    case("positioning", "erroneous", "suv_twenty_meter_front", MANDARIN, "SUV put 20 meter front of ego car, same lane.",
         [in_lane(EAST, asset=SUV), near(None, 4, asset=SUV, point=(-40.0, -1.75)), only(assets=[SUV])],
         [place(SUV, ahead_of(EGO, 20))]),
    case("positioning", "erroneous", "bench_n_bin_union", KIWI, "shift the bench n the bin over to the Studnet Union eh",
         [near("Student Union entrance", 10, asset=BENCH), near("Student Union entrance", 10, asset=BIN),
          only(assets=[BENCH, BIN])],
         [place(BENCH, loc("at", "Student Union entrance")), place(BIN, loc("next_to", "Student Union entrance"))]),
    impossible("positioning", "erroneous", "bench_plant_room", SPARKY,
               "stick the bench inside the JTEKT buildng, down in the plant room", [place(BENCH, xy(37.0, 30.0))]),
]


# --- Moving: shifts, turns and what things do over time -----------------------------------------------------
MOVING_CASES: list[Json] = [
    # direct
    case("moving", "direct", "bench_opposite_way", CURATOR, "Turn the bench to face the opposite direction.",
         [moved(BENCH, 0, 1, turn_min=160), only(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    case("moving", "direct", "ego_more_fast_seven", BRAZIL, "Make the ego go more fast, 7 meters per second.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=7.0, lane=EAST)], alternatives=new_speed(EGO, 6.5, 7.5)),
    case("moving", "direct", "nudge_bin_east", SPARKY, "Nudge the bin two metres east.",
         [moved(BIN, 1.5, 2.5, "forward"), only(assets=[BIN])], [move(BIN, east=2)]),
    case("moving", "direct", "ego_four_second_stop", MANDARIN, "Ego car, at 4 second, stop.",
         [timed_event(EGO, "stop", 8.0, (-41.0, -1.75)), only(assets=[EGO])], [manoeuvre(EGO, "stop", at_time=4.0)]),
    case("moving", "direct", "left_lane_at_four", MARKDOWN, "- actor: ego\n- action: change to the left lane\n- when: t = 4 s",
         [event_played(EGO, "lane_change", 7.0), only(assets=[EGO])],
         [manoeuvre(EGO, "lane_change", at_time=4.0, side="left")]),
    case("moving", "direct", "suv_drive_east_gate", SARCASTIC, "Make the SUV drive to the east gate. Surely it can manage that.",
         [reaches(SUV, "east gate", 60.0, 8.0), only(assets=[SUV])], [behave(SUV, "follow_path", to="east gate")]),
    case("moving", "direct", "dispatch_car_1_main_gate", WAREHOUSE, "Dispatch passenger car 1 to the main gate.",
         [reaches(CAR_W, "main gate", 60.0, 10.0), only(assets=[CAR_W])], [behave(CAR_W, "follow_path", to="main gate")]),
    case("moving", "direct", "ego_three_ms", KIWI, "Slow the ego right down to 3 m/s, eh.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=3.0, lane=EAST)], alternatives=new_speed(EGO, 2.5, 3.5)),
    case("moving", "direct", "suv_forward_bin_east", MARKDOWN, "- SUV: 5 m forward\n- bin: 1 m east",
         [moved(SUV, 4, 6, "forward"), moved(BIN, 0.5, 1.5, "forward"), only(assets=[SUV, BIN])],
         [move(SUV, forward=5), move(BIN, east=1)]),
    case("moving", "direct", "suv_circles_parking_b", BRAZIL, "The SUV must do circles in the parking B.",
         [does("circle", asset=SUV, centre_near="parking lot B"), only(assets=[SUV])],
         [behave(SUV, "circle", centre="parking lot B", radius=6.0)]),
    case("moving", "direct", "speed_then_lane_change", MARKDOWN,
         "1. ego speed: 6 m/s\n2. at t = 5 s: ego changes to the left lane",
         [event_played(EGO, "lane_change", 8.0), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=6.0, lane=EAST), manoeuvre(EGO, "lane_change", at_time=5.0, side="left")],
         alternatives=new_speed(EGO, 5.5, 6.5)),
    case("moving", "direct", "truck_to_lot_b_entrance", WAREHOUSE, "Send it to the lot B entrance.",
         [reaches("truck", "parking lot B entrance", 60.0, 10.0), only("truck")],
         [behave(NEW_TRUCK, "follow_path", to="parking lot B entrance")],
         setup=[turn("Stage a truck at the main gate.", add("truck", where=loc("at", "main gate")), planned=True)]),
    impossible("moving", "direct", "tree_walks", CURATOR, "Have the tree by the Library walk over to the fountain.",
               [behave(TREE_LIBRARY, "follow_path", to="fountain")]),
    # indirect
    case("moving", "indirect", "red_light_film", CURATOR,
         "For the film in our gallery we need the ego waiting at a red light before the west crosswalk.",
         [EGO_HALTS_AT_WEST_CROSSWALK, only("traffic_light", assets=[EGO])], [hold(LIGHT_SW, "red")]),
    case("moving", "indirect", "test_taking_forever", BRAZIL,
         "The ego is too slow, the test is taking forever. Put him in 9 meters per second.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=9.0, lane=EAST)], alternatives=new_speed(EGO, 8.5, 9.5)),
    case("moving", "indirect", "lead_car_brakes_twelve", SPARKY,
         "Need the car in front to jump on its brakes once the ego's within twelve metres of it.",
         [only(assets=[NEW_CAR])],
         [event(NEW_CAR, "stop", {"kind": "distance", "metres": 12.0, "actor": EGO, "other": NEW_CAR}, rate=7.0)],
         setup=[LEAD_CAR_35], alternatives=slows_down(NEW_CAR)),
    case("moving", "indirect", "pedestrian_suddenly_cross", MANDARIN,
         "I want see how ego react when pedestrian suddenly cross the road in front of it.",
         [delta("pedestrian", 1, None), only("pedestrian")], [add("pedestrian", behaviour={"kind": "jaywalk"})],
         alternatives=walks_over(EAST, 20.0)),
    case("moving", "indirect", "cut_in_from_left", MARKDOWN,
         "**Scenario:** cut-in\n- someone pulls in right in front of the ego from the other lane",
         [only(*TRAFFIC)],
         [add("passenger_car", where=ahead_of(EGO, -10, side="left"), behaviour=drive(8.0)),
          manoeuvre(NEW_CAR, "cut_in", at_time=2.0, gap=8.0)],
         alternatives=[[event_played(category, "cut_in", 10.0)] for category in TRAFFIC]),
    case("moving", "indirect", "suv_go_somewhere_library", SARCASTIC,
         "The SUV has been parked there for an eternity. Maybe it could go somewhere? The Library, say?",
         [reaches(SUV, "Library entrance", 60.0, 12.0), only(assets=[SUV])],
         [behave(SUV, "follow_path", to="Library entrance")]),
    case("moving", "indirect", "outbound_east_gate", WAREHOUSE,
         "Outbound run: the car at the east end of the lot B row heads out to the east gate.",
         [reaches(CAR_E, "east gate", 60.0, 8.0), only(assets=[CAR_E])], [behave(CAR_E, "follow_path", to="east gate")]),
    case("moving", "indirect", "ego_tearing_along", KIWI, "The ego's tearing along a bit quick, eh - bring it back to four.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=4.0, lane=EAST)], alternatives=new_speed(EGO, 3.5, 4.5)),
    case("moving", "indirect", "guide_walks_to_fountain", CURATOR,
         "Our guide should then walk the visitor over to the fountain.",
         [reaches("pedestrian", "fountain", 50.0, 5.0), only("pedestrian")],
         [behave(NEW_WALKER, "follow_path", to="fountain")],
         setup=[turn("Place a person at the JTEKT entrance.", add("pedestrian", where=loc("at", "JTEKT building entrance")),
                     planned=True)]),
    case("moving", "indirect", "turn_left_crossing", BRAZIL, "I need that the ego turns to the left in the crossing.",
         [reaches(EGO, "1.75, 20", 30.0, 4.0), only(assets=[EGO])], [manoeuvre(EGO, "junction_turn", turn="left")]),
    case("moving", "indirect", "bin_back_from_kerb", SPARKY,
         "Bin's sat too close to the kerb. Shift it back a couple of metres, away from the road.",
         [moved(BIN, 1.5, 2.5, "right"), only(assets=[BIN])], [move(BIN, north=-2)]),
    case("moving", "indirect", "lead_stops_dead_six", WAREHOUSE, "The traffic ahead should stop dead at six seconds in.",
         [event_played(NEW_CAR, "stop", 10.0), only(assets=[NEW_CAR])],
         [manoeuvre(NEW_CAR, "stop", at_time=6.0, rate=7.0)], setup=[LEAD_CAR_35]),
    impossible("moving", "indirect", "stop_sign_chases_ego", SARCASTIC,
               "Oh, and make the stop sign chase the ego around. That'd be fun.",
               [behave(STOP, "follow_path", to="ego")]),
    # vague
    case("moving", "vague", "suv_wander", CURATOR, "Let the SUV wander the grounds a little.", [only(assets=[SUV])],
         [behave(SUV, "follow_path", to="fountain")], alternatives=gets_going(SUV)),
    case("moving", "vague", "ego_little_more_slow", SARCASTIC,
         "Sure, let the ego race around like it's late for something. Maybe slow it down a bit?", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=3.5, lane=EAST)], alternatives=new_speed(EGO, 0.5, 4.6)),
    case("moving", "vague", "shift_bench_touch", SPARKY, "Shift the bench a touch, would you.",
         [moved(BENCH, 0.3, 2.0), only(assets=[BENCH])], [move(BENCH, forward=1)]),
    case("moving", "vague", "ego_faster_a_bit", MANDARIN, "Ego car go faster a bit.", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=7.0, lane=EAST)], alternatives=new_speed(EGO, 5.5, 10.0)),
    case("moving", "vague", "someone_crosses", MARKDOWN, "- someone crosses the road\n- where: doesn't matter",
         [delta("pedestrian", 1, None), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "north crosswalk"), behaviour={"kind": "cross_road"})],
         alternatives=walks_over(None)),
    case("moving", "vague", "bench_staring_down_footpath", SARCASTIC,
         "The bench stares straight down the footpath. Riveting. Angle it a bit, maybe?",
         [moved(BENCH, 0, 1.5, turn_min=10, turn_max=120), only(assets=[BENCH])], [move(BENCH, turn_deg=-45)]),
    case("moving", "vague", "car_2_moving", WAREHOUSE, "Get passenger car 2 moving.", [only(assets=[CAR_E])],
         [behave(CAR_E, "follow_path", to="east gate")], alternatives=gets_going(CAR_E)),
    case("moving", "vague", "ego_back_up_wee_bit", KIWI, "Back the ego up a wee bit, eh.", [only(assets=[EGO])],
         [move(EGO, forward=-3)], alternatives=backs_up(EGO, 0.5, 6.0)),
    case("moving", "vague", "bin_toward_kerb", CURATOR, "The bin could come forward a little, towards the kerb.",
         [moved(BIN, 0.3, 2.5, "left"), only(assets=[BIN])], [move(BIN, north=1)]),
    case("moving", "vague", "now_make_him_walk", BRAZIL, "Now make him walk to some place.", [only("pedestrian")],
         [behave(NEW_WALKER, "follow_path", to="bus stop")],
         alternatives=[[does(["follow_path", "cross_road", "jaywalk"], "pedestrian")],
                       [event_played("pedestrian", "cross_road", 10.0)]],
         setup=[turn("Put one person in the Library entrance.", add("pedestrian", where=loc("at", "Library entrance")),
                     planned=True)]),
    case("moving", "vague", "car_in_front_do_something", SPARKY,
         "That car in front - make it do something, I need to see how the ego reacts.", [only(assets=[NEW_CAR])],
         [event(NEW_CAR, "stop", {"kind": "time", "seconds": 4.0}, rate=6.0)], setup=[LEAD_CAR_35],
         alternatives=[[event_played(NEW_CAR, kind, 20.0)] for kind in ("stop", "change_speed", "lane_change", "cut_in")]),
    case("moving", "vague", "suv_tiki_tour", KIWI, "Send the SUV on a bit of a tiki tour round the campus.",
         [only(assets=[SUV])], [behave(SUV, "follow_path", to="east gate")], alternatives=gets_going(SUV)),
    impossible("moving", "vague", "signal_laps_lot_b", WAREHOUSE,
               "Get the traffic light on the south-west corner doing laps of lot B.",
               [behave(LIGHT_SW, "circle", centre="parking lot B")]),
    # erroneous
    case("moving", "erroneous", "ninety_degress", CURATOR, "Rotate the bench ninety degress anticlockwise.",
         [moved(BENCH, 0, 1, turn_min=80, turn_max=100), only(assets=[BENCH])], [move(BENCH, turn_deg=90)]),
    case("moving", "erroneous", "change_for_left_lane", BRAZIL, "Make the ego to change for the left lane in 3 seconds.",
         [event_played(EGO, "lane_change", 6.0), only(assets=[EGO])],
         [manoeuvre(EGO, "lane_change", at_time=3.0, side="left")]),
    case("moving", "erroneous", "hydrant_three_east", SPARKY, "shift the hydrant 3 metres esat",
         [moved(HYDRANT, 2.5, 3.5, "forward"), only(assets=[HYDRANT])], [move(HYDRANT, east=3)]),
    case("moving", "erroneous", "suv_east_gate_drive", MANDARIN, "SUV go to east gate, drive.",
         [reaches(SUV, "east gate", 60.0, 8.0), only(assets=[SUV])], [behave(SUV, "follow_path", to="east gate")]),
    case("moving", "erroneous", "ego_revers_four", MARKDOWN, "- actor: ego\n- action: revers 4 m", [only(assets=[EGO])],
         [move(EGO, forward=-4)], alternatives=backs_up(EGO, 3.5, 4.5)),
    case("moving", "erroneous", "suv_cirlces", SARCASTIC, "Make the SUV go in cirlces. Round and round. Like this conversation.",
         [does("circle", asset=SUV), only(assets=[SUV])], [behave(SUV, "circle", centre="parking lot B", radius=6.0)]),
    case("moving", "erroneous", "dispach_suv_entrence", WAREHOUSE, "dispach the suv to the lot B entrence",
         [reaches(SUV, "parking lot B entrance", 40.0, 6.0), only(assets=[SUV])],
         [behave(SUV, "follow_path", to="parking lot B entrance")]),
    case("moving", "erroneous", "ego_crawlin_eight", KIWI, "speed the ego up to 8 m/s eh, its crawlin",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=8.0, lane=EAST)], alternatives=new_speed(EGO, 7.5, 8.5)),
    case("moving", "erroneous", "bench_round_bin_wset", CURATOR, "Turn the bench round, and move the bin one metre wset.",
         [moved(BENCH, 0, 1, turn_min=160), moved(BIN, 0.5, 1.5, "backward"), only(assets=[BENCH, BIN])],
         [move(BENCH, turn_deg=180), move(BIN, east=-1)]),
    case("moving", "erroneous", "pedestrian_crosswalk_north", BRAZIL,
         "Put one pedestrian for cross the street in the crosswalk of the north.",
         [delta("pedestrian", 1, None), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "north crosswalk"), behaviour={"kind": "cross_road"})],
         alternatives=walks_over(NORTH)),
    case("moving", "erroneous", "car_just_add_main_gate", MANDARIN, "The car I just add, make it drive to main gate.",
         [reaches("passenger_car", "main gate", 60.0, 10.0), only("passenger_car")],
         [behave(NEW_CAR, "follow_path", to="main gate")],
         setup=[turn("Add one car in parking B.", add("passenger_car", where=loc("at", "parking lot B")), planned=True)]),
    case("moving", "erroneous", "brak_fifteen_off", KIWI, "n make the car in front brak when were 15m off it",
         [only(assets=[NEW_CAR])],
         [event(NEW_CAR, "stop", {"kind": "distance", "metres": 15.0, "actor": EGO, "other": NEW_CAR}, rate=6.0)],
         setup=[LEAD_CAR_35], alternatives=slows_down(NEW_CAR)),
    impossible("moving", "erroneous", "ego_180_km", MANDARIN, "Ego car speed go 180 kilometre per hour.",
               [behave(EGO, "drive_lane", speed=50.0, lane=EAST)]),
]


# --- Arrangement: several new things laid out in a shape, where asked ----------------------------------------
ARRANGEMENT_CASES: list[Json] = [
    # direct
    case("arrangement", "direct", "bollards_round_library_tree", CURATOR,
         "Arrange a protective ring of bollards around the tree by the Library.",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around=TREE_LIBRARY), only("bollard")],
         [arrange("bollard", "ring", loc("at", TREE_LIBRARY))]),
    case("arrangement", "direct", "five_cones_line_b", BRAZIL, "Put 5 cones in line in the parking B.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5), near("parking lot B", 2, "traffic_cone", min_count=5),
          only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B"), count=5)]),
    case("arrangement", "direct", "barriers_across_eastbound", SPARKY,
         "Line two barriers up across the eastbound lane, 25 m ahead of the ego.",
         [delta("road_barrier", 2, 2), layout("line", "road_barrier", 2), some_in_lane(EAST, "road_barrier"),
          near(None, 6, "road_barrier", point=(-35.0, -1.75), min_count=2), only("road_barrier")],
         [arrange("road_barrier", "line", ahead_of(EGO, 25), count=2, heading_deg=90)]),
    case("arrangement", "direct", "four_bench_row_union", MANDARIN, "Put 4 bench in one row near Student Union.",
         [delta("bench", 4, 4), layout("line", "bench", 4), near("Student Union entrance", 15, "bench", min_count=4),
          only("bench")],
         [arrange("bench", "line", loc("at", "Student Union entrance"), count=4)]),
    case("arrangement", "direct", "ring_round_ne_signal", MARKDOWN,
         "- shape: ring\n- items: bollards x6\n- around: the traffic light on the north-east corner",
         [delta("bollard", 6, 6), layout("ring", "bollard", 6, around=LIGHT_NE), only("bollard")],
         [arrange("bollard", "ring", loc("at", LIGHT_NE), count=6)]),
    case("arrangement", "direct", "three_trees_library_front", SARCASTIC,
         "Put three trees in a line along the Library front. Straight. A line. You can manage a line, right?",
         [delta("tree", 3, 3), layout("line", "tree", 3), near("Library entrance", 15, "tree", min_count=3), only("tree")],
         [arrange("tree", "line", loc("at", "Library entrance"), count=3)]),
    case("arrangement", "direct", "four_cars_bays_lot_a", WAREHOUSE, "Park four cars side by side in lot A, standard bays.",
         [delta(CARS, 4, 4), layout("line", CARS, 4), near("parking lot A", 2, CARS, min_count=4), only(*CARS)],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot A"), count=4)]),
    case("arrangement", "direct", "eight_cones_north_crossing", KIWI,
         "Chuck a ring of cones round the north crossing, eh - eight of 'em.",
         [delta("traffic_cone", 8, 8), layout("ring", "traffic_cone", 8, around="north crosswalk"), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "north crosswalk"), count=8)]),
    case("arrangement", "direct", "three_benches_fountain", MARKDOWN,
         "1. three benches\n2. in a row\n3. next to the fountain",
         [delta("bench", 3, 3), layout("line", "bench", 3), near("fountain", 15, "bench", min_count=3), only("bench")],
         [arrange("bench", "line", loc("next_to", "fountain"), count=3)]),
    case("arrangement", "direct", "barriers_and_sign_library", BRAZIL,
         "Put 4 barriers in line in the front of the Library, and one sign of construction.",
         [delta("road_barrier", 4, 4), layout("line", "road_barrier", 4),
          near("Library entrance", 12, "road_barrier", min_count=4), delta("construction_sign", 1, 1),
          near("Library entrance", 12, "construction_sign"), only("road_barrier", "construction_sign")],
         [arrange("road_barrier", "line", loc("at", "Library entrance"), count=4),
          add("construction_sign", where=loc("next_to", "Library entrance"))]),
    case("arrangement", "direct", "ten_cones_two_apart", SPARKY, "Lay out 10 cones in a straight line in lot A, 2 m apart.",
         [delta("traffic_cone", 10, 10), layout("line", "traffic_cone", 10, spacing_min=1.8, spacing_max=2.2),
          near("parking lot A", 2, "traffic_cone", min_count=10), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot A"), count=10, spacing=2.0)]),
    case("arrangement", "direct", "same_layout_lot_b", WAREHOUSE, "Same layout again in lot B.",
         [delta(CARS, 3, 3), layout("line", CARS, 3), near("parking lot B", 2, CARS, scope="added", min_count=3),
          only(*CARS)],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot B"), count=3)],
         setup=[turn("Park three cars side by side in lot A.",
                     arrange("passenger_car", "parking_row", loc("at", "parking lot A"), count=3), planned=True)]),
    impossible("arrangement", "direct", "row_of_pallets", WAREHOUSE, "Lay a row of six pallets along the lot B entrance.",
               [arrange("pallet", "line", loc("at", "parking lot B entrance"), count=6)]),
    # indirect
    case("arrangement", "indirect", "heritage_tree_cordon", CURATOR,
         "The tree just north of lot A is a heritage specimen. It must be cordoned off all the way round.",
         [delta(CORDON, 4, None), layout("ring", CORDON, 4, around=TREE_LOT_A), only(*CORDON)],
         [arrange("bollard", "ring", loc("at", TREE_LOT_A))]),
    case("arrangement", "indirect", "close_campus_drive_south", BRAZIL,
         "The cars cannot enter in Campus Drive south of the crossing. Put barriers in line to close it.",
         [delta("road_barrier", 2, None), layout("line", "road_barrier", 2), some_in_lane(NORTH, "road_barrier"),
          some_in_lane(SOUTH, "road_barrier"), near(None, 10, "road_barrier", point=(0.0, -20.0), min_count=2),
          only("road_barrier")],
         [arrange("road_barrier", "line", xy(0.0, -20.0), count=3, heading_deg=0)]),
    case("arrangement", "indirect", "trench_westbound_jtekt", SPARKY,
         "Got a trench going in on the westbound lane level with the JTEKT entrance. Cone it off so nobody drives in.",
         [delta(CORDON, 3, None), some_in_lane(WEST, CORDON), near(None, 10, CORDON, point=(37.5, 1.75), min_count=3),
          only(*CORDON, "construction_sign")],
         [arrange("traffic_cone", "line", xy(37.5, 1.75), count=4, heading_deg=90)], alternatives=any_shape(CORDON, 3)),
    case("arrangement", "indirect", "protect_stop_sign", MANDARIN, "Stop sign around need protect, car maybe hit it.",
         [delta(CORDON, 4, None), layout("ring", CORDON, 4, around=STOP), only(*CORDON)],
         [arrange("bollard", "ring", loc("at", STOP), count=6)]),
    case("arrangement", "indirect", "lane_closure_test", MARKDOWN,
         "**Test:** lane closure\n- the eastbound lane is closed ~35 m ahead of the ego\n- use whatever blocks it",
         [delta(CORDON, 3, None), some_in_lane(EAST, CORDON), near(None, 8, CORDON, point=(-25.0, -1.75), min_count=2),
          only(*CORDON, "construction_sign")],
         [arrange("traffic_cone", "line", ahead_of(EGO, 35), count=5, heading_deg=90)]),
    case("arrangement", "indirect", "park_on_bus_stop", SARCASTIC,
         "Yes, let's just let everyone park in front of the bus stop. Great plan. Or - wild idea - block the lane "
         "there off?",
         [delta(CORDON, 3, None), near("bus stop", 12, CORDON, min_count=3), some_in_lane(EAST, CORDON), only(*CORDON)],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "bus stop", lane=EAST), count=4)],
         alternatives=any_shape(CORDON, 3)),
    case("arrangement", "indirect", "channel_inbound_trucks", WAREHOUSE,
         "Inbound trucks queue at the east gate. Run a line of cones along the westbound lane there to channel them.",
         [delta("traffic_cone", 3, None), layout("line", "traffic_cone", 3), some_in_lane(WEST, "traffic_cone"),
          near("east gate", 20, "traffic_cone", min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "east gate", lane=WEST), count=5)]),
    case("arrangement", "indirect", "kids_slalom_lot_b", KIWI,
         "The kids want a slalom in lot B. Reckon six cones in a line would do it.",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6), near("parking lot B", 2, "traffic_cone", min_count=6),
          only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B"), count=6)]),
    case("arrangement", "indirect", "conservation_rubble", CURATOR,
         "The conservation team left rubble in lot B. Ring it off so that no one trips.",
         [delta(CORDON, 3, None), layout("ring", CORDON, 3, around=RUBBLE), only(*CORDON)],
         [arrange("traffic_cone", "ring", loc("at", RUBBLE), count=8)], setup=[RUBBLE_LOT_B]),
    case("arrangement", "indirect", "graduation_photo_line", BRAZIL,
         "For the photo of the graduation, put 6 persons in line in the front of the Library.",
         [delta("pedestrian", 6, 6), layout("line", "pedestrian", 6), near("Library entrance", 12, "pedestrian", min_count=6),
          only("pedestrian")],
         [arrange("pedestrian", "line", loc("at", "Library entrance"), count=6)]),
    case("arrangement", "indirect", "fence_sign_bollards", SPARKY, "Now fence that sign off with bollards all the way round.",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around=NEW_SIGN), only("bollard")],
         [arrange("bollard", "ring", loc("at", NEW_SIGN), count=6)],
         setup=[turn("Stick a roadworks sign at the Student Union entrance.",
                     add("construction_sign", where=loc("at", "Student Union entrance")), planned=True)]),
    case("arrangement", "indirect", "holding_row_trucks", WAREHOUSE, "Set up a holding row for three trucks in lot B.",
         [delta("truck", 3, 3), layout("line", "truck", 3), near("parking lot B", 3, "truck", min_count=3), only("truck")],
         [arrange("truck", "parking_row", loc("at", "parking lot B"), count=3)]),
    impossible("arrangement", "indirect", "hundred_fifty_bollards", KIWI,
               "Go hard - chuck a ring of a hundred and fifty bollards round the fountain, eh.",
               [arrange("bollard", "ring", loc("at", "fountain"), count=150)]),
    # vague
    case("arrangement", "vague", "seating_composition", CURATOR,
         "Arrange some seating around the fountain in a pleasing composition.",
         [delta("bench", 2, None), near("fountain", 15, "bench", min_count=2), only("bench")],
         [arrange("bench", "ring", loc("at", "fountain"), count=4)], alternatives=any_shape("bench", 2, 1.5)),
    case("arrangement", "vague", "organization_cones_a", BRAZIL, "Make some organization with cones in the parking A.",
         [delta("traffic_cone", 3, None), near("parking lot A", 2, "traffic_cone", min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot A"), count=6)], alternatives=any_shape("traffic_cone", 3)),
    case("arrangement", "vague", "round_the_debris", SPARKY, "Set out something round that debris so nobody clips it.",
         [delta(CORDON, 3, None), layout("ring", CORDON, 3, around=RUBBLE), only(*CORDON)],
         [arrange("bollard", "ring", loc("at", RUBBLE), count=6)], setup=[RUBBLE_30]),
    case("arrangement", "vague", "bench_library_arrange_nice", MANDARIN, "Some bench near Library, arrange nice.",
         [delta("bench", 2, None), near("Library entrance", 15, "bench", min_count=2), only("bench")],
         [arrange("bench", "line", loc("at", "Library entrance"), count=3)], alternatives=any_shape("bench", 2, 1.5)),
    case("arrangement", "vague", "bollards_some_shape_east_gate", MARKDOWN,
         "- some bollards\n- any shape\n- by the east gate",
         [delta("bollard", 3, None), near("east gate", 15, "bollard", min_count=3), only("bollard")],
         [arrange("bollard", "line", loc("at", "east gate"), count=5)], alternatives=any_shape("bollard", 3)),
    case("arrangement", "vague", "block_west_crossing", SARCASTIC,
         "Block off the west crossing or whatever. I genuinely do not care how.",
         [delta(CORDON, 2, None), near("west crosswalk", 10, CORDON, min_count=2), only(*CORDON)],
         [arrange("traffic_cone", "line", loc("at", "west crosswalk"), count=5)], alternatives=any_shape(CORDON, 2)),
    case("arrangement", "vague", "staging_grid_lot_b", WAREHOUSE, "Mark out a staging grid in lot B.",
         [delta("traffic_cone", 4, None), layout("cluster", "traffic_cone", 4, tolerance=10.0),
          near("parking lot B", 2, "traffic_cone", min_count=4), only("traffic_cone")],
         [arrange("traffic_cone", "grid", loc("at", "parking lot B"), count=9, columns=3, spacing=3.0)]),
    case("arrangement", "vague", "wee_circle_library_tree", KIWI,
         "Make a wee circle of something round the tree by the Library, eh.",
         [delta([*CORDON, *FURNITURE, *PEOPLE], 4, None),
          layout("ring", [*CORDON, *FURNITURE, *PEOPLE], 4, around=TREE_LIBRARY), only(*CORDON, *FURNITURE, *PEOPLE)],
         [arrange("bollard", "ring", loc("at", TREE_LIBRARY))]),
    case("arrangement", "vague", "frame_it_with_trees", CURATOR, "Frame it with a few trees.",
         [delta("tree", 2, None), near(NEW_BENCH, 12, "tree", min_count=2), only("tree")],
         [arrange("tree", "line", loc("at", NEW_BENCH), count=3)],
         setup=[turn("Install a bench at the JTEKT entrance.", add("bench", where=loc("at", "JTEKT building entrance")),
                     planned=True)]),
    case("arrangement", "vague", "same_in_parking_b", BRAZIL, "Do the same in the parking B.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5),
          near("parking lot B", 2, "traffic_cone", scope="added", min_count=5), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B"), count=5)],
         setup=[turn("Put five cones in line in the parking A.",
                     arrange("traffic_cone", "line", loc("at", "parking lot A"), count=5), planned=True)]),
    case("arrangement", "vague", "bollards_along_kerb_engineering", SPARKY,
         "Few bollards along the kerb outside Engineering Hall, keep the cars off the footpath.",
         [delta("bollard", 3, None), layout("line", "bollard", 3), near("Engineering Hall entrance", 15, "bollard",
                                                                        min_count=3), only("bollard")],
         [arrange("bollard", "line", xy(-40.0, 7.5), count=5, heading_deg=0)]),
    case("arrangement", "vague", "ring_of_cones_round_it", WAREHOUSE, "Put a ring of cones round it.",
         [delta("traffic_cone", 4, None), layout("ring", "traffic_cone", 4, around=NEW_TRUCK), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", NEW_TRUCK), count=10)],
         setup=[turn("Stage a truck in lot A.", add("truck", where=loc("at", "parking lot A")), planned=True)]),
    impossible("arrangement", "vague", "display_vitrines", CURATOR,
               "Arrange a semicircle of display vitrines before the Library entrance.",
               [arrange("display case", "ring", loc("at", "Library entrance"), count=6)]),
    # erroneous
    case("arrangement", "erroneous", "bollards_strait_line_union", CURATOR,
         "Arange five bollards in a strait line before the Student Union entrance.",
         [delta("bollard", 5, 5), layout("line", "bollard", 5), near("Student Union entrance", 12, "bollard", min_count=5),
          only("bollard")],
         [arrange("bollard", "line", loc("in_front_of", "Student Union entrance"), count=5)]),
    case("arrangement", "erroneous", "eight_cones_circle_b", BRAZIL, "Put 8 cones in circle around of the parking B.",
         [delta("traffic_cone", 8, 8), layout("ring", "traffic_cone", 8, around="parking lot B"),
          near("parking lot B", 2, "traffic_cone", min_count=8), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "parking lot B"), count=8, radius=7.0)]),
    case("arrangement", "erroneous", "four_cones_acros_westbound", SPARKY, "line up 4 cones acros the westbound lane by the east gate",
         [delta("traffic_cone", 4, 4), layout("line", "traffic_cone", 4), some_in_lane(WEST, "traffic_cone"),
          near("east gate", 15, "traffic_cone", min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "line", xy(92.0, 1.75), count=4, heading_deg=90)]),
    case("arrangement", "erroneous", "cone_six_piece_line", MANDARIN, "Make cone 6 piece one line, in parking A.",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6), near("parking lot A", 2, "traffic_cone", min_count=6),
          only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot A"), count=6)]),
    case("arrangement", "erroneous", "rign_bollards_fountian", MARKDOWN,
         "1. rign of bollards\n2. arround the fountian\n3. 8 of them",
         [delta("bollard", 8, 8), layout("ring", "bollard", 8, around="fountain"), only("bollard")],
         [arrange("bollard", "ring", loc("at", "fountain"), count=8)]),
    case("arrangement", "erroneous", "three_benchs_jtekt", SARCASTIC,
         "Three benchs in a row by the JTEKT entrnace. Shouldn't be rocket science.",
         [delta("bench", 3, 3), layout("line", "bench", 3), near("JTEKT building entrance", 15, "bench", min_count=3),
          only("bench")],
         [arrange("bench", "line", loc("at", "JTEKT building entrance"), count=3)]),
    case("arrangement", "erroneous", "five_cars_tight_bays", WAREHOUSE, "park 5 cars side by side in lot b, tight bays",
         [delta(CARS, 5, 5), layout("line", CARS, 5), near("parking lot B", 2, CARS, scope="added", min_count=5), only(*CARS)],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot B"), count=5)]),
    case("arrangement", "erroneous", "trees_union_frontage", KIWI,
         "chuck a line of trees along the Studnet Union frontage eh, three'll do",
         [delta("tree", 3, 3), layout("line", "tree", 3), near("Student Union entrance", 15, "tree", min_count=3),
          only("tree")],
         [arrange("tree", "line", loc("at", "Student Union entrance"), count=3)]),
    case("arrangement", "erroneous", "bollards_squre_grid", CURATOR, "Place four bollards in a squre grid beside the fountain.",
         [delta("bollard", 4, 4), layout("cluster", "bollard", 4, tolerance=5.0), near("fountain", 12, "bollard", min_count=4),
          only("bollard")],
         [arrange("bollard", "grid", loc("next_to", "fountain"), count=4, columns=2)]),
    case("arrangement", "erroneous", "cones_circle_around_of_it", BRAZIL, "Put cones in circle around of it.",
         [delta("traffic_cone", 4, None), layout("ring", "traffic_cone", 4, around=NEW_CAR), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", NEW_CAR), count=10)],
         setup=[turn("Put one car in the middle of the parking A.", add("passenger_car", where=loc("at", "parking lot A")),
                     planned=True)]),
    case("arrangement", "erroneous", "barrier_three_piece_sign", MANDARIN,
         "Barrier 3 piece one line near east gate, also one construction sign there.",
         [delta("road_barrier", 3, 3), layout("line", "road_barrier", 3), near("east gate", 15, "road_barrier", min_count=3),
          delta("construction_sign", 1, 1), near("east gate", 15, "construction_sign"),
          only("road_barrier", "construction_sign")],
         [arrange("road_barrier", "line", loc("at", "east gate"), count=3),
          add("construction_sign", where=loc("next_to", "east gate"))]),
    case("arrangement", "erroneous", "same_agian_north_crosing", SPARKY, "and the same agian at the north crosing",
         [delta("traffic_cone", 4, 4), layout("line", "traffic_cone", 4),
          near("north crosswalk", 10, "traffic_cone", scope="added", min_count=4), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "north crosswalk"), count=4)],
         setup=[turn("Line up four cones at the west crosswalk.",
                     arrange("traffic_cone", "line", loc("at", "west crosswalk"), count=4))]),
    impossible("arrangement", "erroneous", "twelve_buses_row", SARCASTIC,
               "Arange twelve buses in a nice neat row in lot B. Go on, I dare you.",
               [arrange("bus", "parking_row", loc("at", "parking lot B"), count=12)]),
]


# --- Appearance: looks, weather, clock and lights ------------------------------------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case("appearance", "direct", "time_16_45", CURATOR, "Set the time to 16:45, please; the light in the galleries is best then.",
         [env(time_from="16:40", time_to="16:50"), only(env=True)], [clock("16:45")]),
    case("appearance", "direct", "rain_strong", BRAZIL, "Put rain, strong.",
         [env(weather=["rain"], intensity_min=0.75), only(env=True)], [weather("rain", 0.9)]),
    case("appearance", "direct", "street_lights_on", SPARKY, "Switch the street lights on.",
         [env(street_lights="on"), only(env=True)], [lighting(street_lights="on")]),
    case("appearance", "direct", "open_the_street_light", MANDARIN, "Please open the street light.",
         [env(street_lights="on"), only(env=True)], [lighting(street_lights="on")]),
    case("appearance", "direct", "light_fog_list", MARKDOWN, "- weather: fog\n- intensity: light",
         [env(weather=["fog"], intensity_max=0.4), only(env=True)], [weather("fog", 0.3)]),
    case("appearance", "direct", "suv_red", SARCASTIC, "Paint the SUV red. It's one colour, how hard can it be.",
         [looks("red", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="red")]),
    case("appearance", "direct", "clock_0530", WAREHOUSE, "Set the clock to 05:30 for the early shift.",
         [env(time_from="05:25", time_to="05:35"), only(env=True)], [clock("05:30")]),
    case("appearance", "direct", "proper_heavy_snow", KIWI, "Make it snow, eh. Proper heavy.",
         [env(weather=["snow"], intensity_min=0.75), only(env=True)], [weather("snow", 0.9)]),
    case("appearance", "direct", "bench_and_bin_maroon", MARKDOWN, "- bench colour: maroon\n- bin colour: maroon as well",
         [looks("maroon", asset=BENCH), looks("maroon", asset=BIN), only(assets=[BENCH, BIN])],
         [paint([BENCH], colour="maroon"), paint([BIN], colour="maroon")]),
    case("appearance", "direct", "ego_color_white", BRAZIL, "Put the ego in color white.",
         [looks("white", asset=EGO), only(assets=[EGO])], [paint([EGO], colour="white")]),
    case("appearance", "direct", "time_and_lamps", MARKDOWN, "- time: 21:15\n- street lights: on",
         [env(time_from="21:10", time_to="21:20", street_lights="on"), only(env=True)],
         [clock("21:15"), lighting(street_lights="on")]),
    case("appearance", "direct", "kill_street_lights", SPARKY, "Right, now kill the street lights.",
         [env(street_lights="off"), only(env=True)], [lighting(street_lights="off")], setup=[STREET_LIGHTS_ON]),
    impossible("appearance", "direct", "southerly_hail", KIWI, "Give us a proper southerly with hail, eh.",
               [weather("hail", 0.8)]),
    # indirect
    case("appearance", "indirect", "catalogue_cover_sunrise", CURATOR,
         "We're photographing the courtyard for the catalogue cover and need the soft light just after sunrise.",
         [env(time_from="05:30", time_to="08:00"), only(env=True)], [clock("06:45")]),
    case("appearance", "indirect", "winter_morning_snow", MANDARIN,
         "Want test car in winter morning, snow is falling.",
         [env(weather=["snow"], time_from="05:30", time_to="11:30"), only(env=True)], [weather("snow", 0.6), clock("08:00")]),
    case("appearance", "indirect", "night_test_luminaires", SPARKY,
         "Running a night test on the new luminaires, so set it up for after dark.",
         [env(night=True), only(env=True)], [clock("22:00")]),
    case("appearance", "indirect", "foggy_morning", MANDARIN, "Tomorrow test need bad visibility, like foggy morning.",
         [env(weather=["fog"], intensity_min=0.3, time_from="05:00", time_to="11:30"), only(env=True)],
         [weather("fog", 0.7), clock("07:00")]),
    case("appearance", "indirect", "camera_glare", MARKDOWN,
         "**Context:** testing the camera against glare\n**Need:** low sun, late afternoon",
         [env(time_from="16:00", time_to="19:45"), only(env=True)], [clock("18:00")]),
    case("appearance", "indirect", "bench_stand_out", SARCASTIC,
         "Oh good, the bench is the exact colour of the pavement. Nobody will ever see it. Make it stand out.",
         [looks(BRIGHT, asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="yellow")]),
    case("appearance", "indirect", "night_shift_lights", WAREHOUSE,
         "Night shift starts at 22:00 - set the scene for it, and the vehicles should run with their lights on.",
         [env(time_from="21:55", time_to="22:05", vehicle_lights="on"), only(env=True)],
         [clock("22:00"), lighting(vehicle_lights="on")]),
    case("appearance", "indirect", "wellington_day", KIWI,
         "Reckon it's a typical Wellington day - blowing a gale and absolutely pissing down.",
         [env(weather=["rain"], intensity_min=0.7), only(env=True)], [weather("rain", 0.9)]),
    case("appearance", "indirect", "bronze_collection", CURATOR,
         "The SUV's finish should evoke our bronze collection.",
         [looks(["#cd7f32", "orange", "brown", "gold"], asset=SUV), only(assets=[SUV])],
         [paint([SUV], colour="#cd7f32", material="metal")]),
    case("appearance", "indirect", "too_dark_cant_see", BRAZIL, "Is too dark now, I can't see nothing. Put more light.",
         [only(env=True)], [lighting(street_lights="on")], alternatives=brighter(),
         setup=[turn("Put the hour in 22:00.", clock("22:00"))]),
    case("appearance", "indirect", "cones_visible_night", SPARKY,
         "Those cones need to be seen by drivers at night. Make 'em all orange.",
         [looks("orange", "traffic_cone", every=True, min_count=4), only("traffic_cone")],
         [paint(category="traffic_cone", colour="orange")], setup=[CONES_4_NORTH]),
    case("appearance", "indirect", "cameras_washing_out", WAREHOUSE,
         "The yard cameras are washing out - it's far too bright in there.",
         [only(env=True)], [lighting(exposure=0.7)],
         alternatives=[[env(exposure_max=0.95)], [env(time_from="17:30", time_to="06:00")]]),
    impossible("appearance", "indirect", "pink_library", SARCASTIC,
               "Sure, and while you're at it, make the Library bright pink. The building, yes.",
               [paint(["library"], colour="pink")]),
    # vague
    case("appearance", "vague", "more_atmospheric", SARCASTIC,
         "Wow, clear skies at noon. Thrilling. Could it have some atmosphere, maybe?",
         [only(env=True)], [weather("fog", 0.5)],
         alternatives=[*darker(), [env(weather=["fog", "rain", "cloudy", "snow"])]]),
    case("appearance", "vague", "weather_more_ugly", BRAZIL, "Make the weather more ugly.",
         [env(weather=["cloudy", "rain", "fog", "snow"]), only(env=True)], [weather("rain", 0.6)]),
    case("appearance", "vague", "bit_gloomy", SPARKY, "Sort the lighting out out there, it's a bit gloomy.",
         [env(time_from="07:00", time_to="17:30"), only(env=True)], [lighting(exposure=1.3)], alternatives=brighter()[:2]),
    case("appearance", "vague", "weather_little_change", MANDARIN, "Change a little bit the weather, not too strong.",
         [env(weather=["cloudy", "rain", "fog", "snow"], intensity_max=0.7), only(env=True)], [weather("cloudy", 0.4)]),
    case("appearance", "vague", "dusk_ish", MARKDOWN, "- mood: dusk-ish\n- anything that reads as early evening",
         [env(time_from="17:30", time_to="21:30"), only(env=True)], [clock("19:30")]),
    case("appearance", "vague", "suv_not_default_not_black", SARCASTIC,
         "Could the SUV be any colour other than 'default boring'? Any colour. Except black.",
         [looks([c for c in ALL_COLOURS if c != "black"], asset=SUV), only(assets=[SUV])], [paint([SUV], colour="teal")]),
    case("appearance", "vague", "bad_winter_shift", WAREHOUSE,
         "Make conditions rough for the drivers, like a bad winter shift.", [only(env=True)], [weather("snow", 0.8)],
         alternatives=[[env(weather=["snow"])], [env(weather=["fog"], intensity_min=0.5)]]),
    case("appearance", "vague", "bucketing_down_all_week", KIWI,
         "Sort the weather out, it's been bucketing down all week.", [only(env=True)], [weather("clear")],
         alternatives=[[env(weather=["clear", "cloudy"])], [env(weather=["rain"], intensity_max=0.4)]],
         setup=[HEAVY_RAIN]),
    case("appearance", "vague", "cooler_palette_bench", CURATOR, "Perhaps a cooler palette for the bench.",
         [looks(COOL, asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="teal")]),
    case("appearance", "vague", "color_more_happy", BRAZIL, "No, I don't like. Put another color, more happy.",
         [looks(BRIGHT, asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="yellow")],
         setup=[turn("Put the bench in color grey.", paint([BENCH], colour="grey"), planned=True)]),
    case("appearance", "vague", "darker_see_lamps", SPARKY, "Make it darker out, I want to see the lamps doing their job.",
         [only(env=True)], [clock("21:00")], alternatives=darker()),
    case("appearance", "vague", "rain_too_big", MANDARIN, "Rain too big, make small.", [only(env=True)],
         [weather("rain", 0.3)],
         alternatives=[[env(weather=["rain"], intensity_max=0.5)], [env(weather=["clear", "cloudy"])]],
         setup=[HEAVY_RAIN]),
    impossible("appearance", "vague", "overnight_24_45", WAREHOUSE, "Set the clock to 24:45 for the overnight shift.",
               [clock("24:45")]),
    # erroneous
    case("appearance", "erroneous", "bench_burgandy", CURATOR, "Kindly make the bench burgandy.",
         [looks(["maroon", "#800020"], asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="#800020")]),
    case("appearance", "erroneous", "seven_of_the_night", BRAZIL, "Put the time in 7 hour of the night.",
         [env(time_from="18:55", time_to="19:05"), only(env=True)], [clock("19:00")]),
    case("appearance", "erroneous", "swich_vehicle_lihgts", SPARKY, "swich on the vehicle lihgts",
         [env(vehicle_lights="on"), only(env=True)], [lighting(vehicle_lights="on")]),
    case("appearance", "erroneous", "big_snow", MANDARIN, "Weather change to snowing, big snow.",
         [env(weather=["snow"], intensity_min=0.75), only(env=True)], [weather("snow", 0.9)]),
    case("appearance", "erroneous", "wether_rain_moderate", MARKDOWN, "- wether: rain\n- strenght: moderate",
         [env(weather=["rain"], intensity_min=0.45, intensity_max=0.75), only(env=True)], [weather("rain", 0.6)]),
    case("appearance", "erroneous", "make_it_nigth", SARCASTIC, "Make it nigth. Please. I'm begging you.",
         [env(night=True), only(env=True)], [clock("22:00")]),
    case("appearance", "erroneous", "exposre_one_two", WAREHOUSE, "Set exposre to 1.2 for the yard cams.",
         [env(exposure_min=1.15, exposure_max=1.25), only(env=True)], [lighting(exposure=1.2)]),
    case("appearance", "erroneous", "hydrant_yelow", KIWI, "paint the hydrant yelow eh",
         [looks("yellow", asset=HYDRANT), only(assets=[HYDRANT])], [paint([HYDRANT], colour="yellow")]),
    case("appearance", "erroneous", "dusk_stret_lights", CURATOR, "Please make it dusk and turn the stret lights on.",
         [env(time_from="18:00", time_to="21:00", street_lights="on"), only(env=True)],
         [clock("20:00"), lighting(street_lights="on")]),
    case("appearance", "erroneous", "three_cars_silver", BRAZIL, "Put the 3 cars of the parking B in the color silver.",
         [looks("silver", asset=CAR_W), looks("silver", asset=SUV), looks("silver", asset=CAR_E), only(assets=LOT_B_ROW)],
         [paint(LOT_B_ROW, colour="silver")]),
    case("appearance", "erroneous", "close_the_fog", MANDARIN, "Fog already too thick. Close the fog.",
         [env(weather=["clear", "cloudy"]), only(env=True)], [weather("clear")],
         setup=[turn("Make heavy fog.", weather("fog", 0.9))]),
    case("appearance", "erroneous", "quater_past_ten", SPARKY, "cheers. now set teh time to quater past ten at night",
         [env(time_from="22:10", time_to="22:20"), only(env=True)], [clock("22:15")], setup=[STREET_LIGHTS_ON]),
    impossible("appearance", "erroneous", "rainbow_sky", BRAZIL, "Put a rainbow in the sky, please, for the foto.",
               [weather("rainbow", 0.5)]),
]



def pin_environment(cases: list[Json]) -> list[Json]:
    """The cases with the parts of the environment a request does not mention held as the campus ships them.

    An environment check of a case with no earlier turns that says nothing of the weather also wants it clear, and
    one that says nothing of the clock also wants midday, so that a plan that changes the time when asked for the
    street lights (or the weather when asked for the time) fails."""
    for c in cases:
        if c.get("setup"):
            continue
        for check in c["checks"]:
            if check["kind"] != "environment":
                continue
            if "weather" not in check:
                check["weather"] = ["clear"]
            if not {"time_from", "time_to", "night"} & set(check):
                check["time_from"], check["time_to"] = "11:55", "12:05"
    return cases


APPEARANCE_CASES = pin_environment(APPEARANCE_CASES)


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
