"""The thirty-third practice suite: 342 cases from eight new kinds of user, none used by an earlier suite, from the campus world alone.

`python -m drivetwin.evals.practice33_source` writes `suites/practice33.jsonl` (tag `practice33`, ids
`practice33.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`; 32 to 50 cases each): a land surveyor ("set out", "re-site", "on a bearing
of 090", "a baering of 270", "chainage 20 from the ego", "chainage 40", "easting 16, northing 5.5", "offset", "3 m
centres", "my survey line", "sightlines", "carriageways", "the instrument can't see through this"), a Korean speaker
writing English ("Please ... for me", "chair" for a bench, "How many bench is in this map?", "8 person stand in one
line", "The person I added before, where is standing now?", "The bicycle I add before", "night 9 o'clock", "Ego car speed
is how much now? And lane what?", "yellow dust day"), a fat-fingered phone typist ("benvh by tge library", "rhe
fountain", "tge east gate", "wheee", "remive", "cobes", "arounf", "mvoe", "thr bench at the fountsin", "rian", "stret
lights", autocorrect's "beach" for the bench, "fire hydrangea" and "dribe", "lol", "idc", "ppl", "main st"), a chef
("86 the bench", "86 the bin and 86 the hydrant. Behind!", "fire one bench", "Heard?", "yes chef", "all day" for in
total, "mise en place", "on the pass", "the walk-in", "lot A's dead tonight", "wrong station"), a Filipino English
speaker ("po", "pls", "kindly", "Ma'am", "Sir", "the CR", "open the headlights", "close the street lights", "for a
while", "already", "na", "a sari-sari store", "our Christmas theme"), a festival steward or crowd marshal ("egress",
"punters", "muster point", "stand down the barriers", "hand-marshalled", "hi-vis", "a sterile zone", "a barrier line",
"a queue line", "presence at the east gate", "doors open", "a portaloo block", "crowd-crush risk", "the first aid
tent"), a Welsh English speaker ("now in a minute", "tidy", "a cwtch", "cwtchy", "lush", "by there", "isn't it", "is it",
"mun", "our Nan", "our Cerys", "there's lovely", "poor dab", "mind", "a proper wet Welsh afternoon") and a retired bus
driver who wraps each request in anecdotes ("Forty years I drove the 14", "I reversed into one just like it in '92",
"the airport shuttle", "first bus out of the depot was always ten to six", "the skid pan at the training school", "the
old Routemasters", "the M4 in '81", "scraping the windscreen of the 14").

Prompts describe things instead of naming them ("the car at the west end of the lot B row", "the car on the east end
of the lot B row", "the tree just north of lot A", "the tree nearest the fountain", "the lamp post by the bus stop, the
south side one", "the lamp column nearest the fountain", "the traffic light on the north-east corner", "the stop
sign's jammed right up against that lamp post", "whatever stands closest to the Student Union entrance", "the bench
besides it", "the second bus", "opposite side of bus stop, across the road", "the car in front", "that steward", "the
truck I added", "it", "them"), turn on negation and polarity ("Keep the SUV, 86 the other two", "the SUV will stay",
"it's not coming back", "not just stay", "nobody touches it", "we don't need it",
"actually nah") and name places and scopes (lanes and roads, "15 meter in front of ego car, same lane", "20 meter
behind of ego", "25m ahead of the ego", "chainage 30 ahead of the ego in its lane", "15 m ahead of the ego on the
left-hand footpath", "across the eastbound lane 30m ahead", "the westbound lane near the JTEKT entrance", "Campus Drive,
north of the crossing", "Campus Drive south of the crossing", "the north side of Main Street", "the north footpath",
"within 25 metres of the fountain", "easting -90 northing 20", "easting 30, northing -20"). They carry clock times in
several forms ("07:15", "22:30", "18:40", "06:45", "half past seven in the evening", "ten to six", "night 9 o'clock",
"quarter to ate in the morning", "late-night", "evening time", "overcast and early", "a winter's morning on the first
run") and weather with strengths (heavy rain, light fog, moderate snow, "raining cats and dogs", "foggy, heavey", "snow,
but little bit only", "a light dusting", "a bit rough", "moody", "grey and miserable"), numbers in words and digits
with units ("6 meter per second", "sevn metres a second", "8 m/s", "3 m", "2 m", "90 degrees", "180 degres", "five
seconds", "6 secnds", "3 secnds off hitting it", "ten metres off its tail", "tow bollards", "to barriers", "for cars",
"six cones ... at 3 m centres", "2 m cnetres", "a couple", "a few", "half", "exposre to 0.8", "200 miles an hour",
"120 cones", "twenty of 'em", "radius 80 m"), questions (which must change nothing: their checks hold the scene
unchanged and their reference answers with a search) and behaviours over time: speeds up and down, stops at five and
six seconds, lane changes at three and four seconds (the ego's, and the car in front's), a right turn at the
crossroads, a red light the ego waits at before the west crosswalk, a lead car braking as the ego closes to ten metres
or three seconds from it, a cut-in from the next lane, a walker crossing at the north crosswalk or somewhere in front of
the ego, a steward walking to the Library or the north crossing, cars driving to the lot B entrance, the main gate and
the east gate, circles in lots A and B, backing up. The erroneous grade carries realistic typos, slips, homophones and
non-native grammar in category names ("benvh", "conse", "cobes", "buss", "barirers", "tress", "sing", "stop sing",
"firehydrant", "pedestrain", "passanger", "beach", "hydrangea"), place names ("tge library", "fountian", "fountsin",
"nroth", "nort", "wset", "esat gate", "east gaet", "east gat", "main gait", "mian gate", "Libary", "Studnet Union",
"Enginering", "Engneering", "entrace", "crosswlak", "crosing", "intersecion", "bus stpo", "lot B entrnace"), verbs
("remive", "Remvoe", "mvoe", "dribe", "stopp"), numbers and units ("tow", "to", "for", "sevn", "secnds", "degres",
"cnetres", "ate") and other words ("distnace", "wich", "wheee", "hw", "anticlockwsie", "baering", "lnie", "acros",
"arounf", "agian", "rian", "stret lights", "purpel", "heavey", "mauroon", "exposre", "vehical", "clcok", "hial").

Counts: 7 tasks x 4 grades; every cell holds 11 to 13 cases, and arrangement (every grade) and the vague and erroneous
grades of every task hold 13 (342 in all: direct 81, indirect 79, vague 91, erroneous 91). 47 cases are multi-turn (33
with a planned earlier turn that has calls), with references back: "it", "them", "that steward", "the car in front",
"the person I added before", "the bicycle I add before", "the truck I added", "the car i just added", "the bollards i
put", "the second bus", "2 more of those there", "a bin to go with it", "same again at the main gaet", "same again at
the jtekt entrance", "same agian at the west crosswlak", "Do the same by the main gate"; and corrections ("Wrong station,
chef", "actually nah get rid of it", "nah, make it blu instead", "That barrier's needed at the east gate now"). 23 are
compound (the reference makes two calls or more; 21 of them put two requests in one prompt, one asks two questions, and
one - the cut-in - asks one thing that takes two calls), and 28 (8.2 %) are impossible, tagged `impossible`, where the
right outcome is a refusal that changes nothing: the CR, the walk-in, the bus depot, the first aid tent; a sari-sari
store, a portaloo block, a convenience store, a phone box; the Student Union building, the fountain, the crossroads,
the ego; the bench in the Student Union's canteen or on the Library roof, the SUV on top of Engineering Hall, the
fountain moved; a bin driving laps, 200 mph, a tree dancing round the fountain, a bench driving round it; 120 cones in
a ring, a row of tents, twenty buses, a ring of 80 m radius; a thunderstorm with lightning, a cream Library building,
yellow dust, hail.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with `alternatives`
where a request has two fair readings (a new speed on the lane behaviour or by a change-of-speed manoeuvre, backing up
by a shift or a reverse manoeuvre, braking by a stop or a slow-down, a crossing as a behaviour or a manoeuvre, a cut-in
by any kind of vehicle, setting a parked vehicle off by any driving behaviour or manoeuvre, "more light" by exposure,
street lights or daylight, "moody" and "too bright" by the clock, the exposure or the weather, "a cone thing", "some
kind of cordon" or "in nice order" as a line, a ring or a cluster, a hydrant "by a building entrance" at any of the four
entrances, a bench "near the trees" by any of the four, a hydrant "in with the lamp posts on the south side" by any of
the six, giving the stop sign room by moving it or the lamp post, "kit out the fountain area" with a bench or a bin,
traffic on Campus Drive in either lane, "something warm" for the bench as a warm colour or wood, "cheer it up" as clear
skies or a trace of rain). Environment checks of cases with no earlier turns also hold the weather and the clock they
do not mention as the campus ships them (`pin_environment`). Cones stand only on roads, crossings and paved ground, so
cone layouts are asked for in the lots, on the roads and round the crossroads, and rings on the footways are of
bollards. The `reference` plan of every case passes; a plan that does nothing fails every case, questions and
impossible ones included (its empty plan is accepted and answers nothing), whether or not its planned earlier turns
were done, and another case's reference plan (of the same task, one and three cases on) fails all but the cases whose
wording leaves that reading open. Every id and coordinate was checked against worlds/campus.py and the search Workers'
answers on the shipped campus. A truly ambiguous request cannot be written as expecting a clarifying question (a trial
that asks is never a pass), so the vague cases accept every sensible reading instead. The suite was written from the
campus world, the asset catalog, the Worker tools' argument schemas and the eval checks only, by someone who had not
read the planners, their lexicons, their prompt examples or any other suite's cases (practice31's and practice32's
sources were read for their format only).
"""

from __future__ import annotations

from drivetwin.evals.practice_cases import (
    EGO,
    Json,
    Suite,
    add,
    ahead_of,
    any_shape,
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
    relative,
    remove,
    says,
    slows_down,
    some_in_lane,
    stops_before,
    timed_event,
    turn,
    walks_over,
    weather,
    xy,
)

TAG = "practice33"
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
STOP = "stop_sign_1"  # south footway just west of the west crosswalk, (-13.5, -5.5), facing east
LIGHT_SW = "traffic_light_1"  # south-west corner of the crossroads, (-9.5, -6.2)
LIGHT_NE = "traffic_light_2"  # north-east corner, (9.5, 6.2)
TREE_LIBRARY = "tree_1"  # between the bus stop and the Library, (-26, -12)
TREE_FOUNTAIN_NW = "tree_2"  # north-west of the fountain, (70, 45), 7.1 m from it: the nearest tree to it
TREE_FOUNTAIN_SE = "tree_3"  # south-east of the fountain, (85, 25), 18 m from it
TREE_LOT_A = "tree_4"  # just north of lot A, (-85, 50)
TREES = [TREE_LIBRARY, TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE, TREE_LOT_A]
NORTH_LAMPS = [f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11)]  # y = 5.8; x = -80, -50, -25, 25, 50, 80
SOUTH_LAMPS = [f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12)]  # y = -5.8; x = -68, -38, -13, 37, 62, 92
LAMP_BY_LIBRARY = "street_light_4"  # (-38, -5.8): by the bus stop, 9.7 m from the Library entrance, the nearest to it
LAMP_BY_STOP_SIGN = "street_light_6"  # (-13, -5.8): 0.6 m from the stop sign, at the west crosswalk
LAMP_BY_ENGINEERING = "street_light_3"  # (-50, 5.8): 13.6 m from the Engineering Hall entrance, the nearest to it
LAMP_BY_FOUNTAIN = "street_light_11"  # (80, 5.8): 34.6 m from the fountain, the nearest to it
EAST = "main_eastbound"  # y = -1.75; the ego drives it at 5 m/s from x = -60
WEST = "main_westbound"  # y = 1.75
NORTH = "campus_northbound"  # x = 1.75
SOUTH = "campus_southbound"  # x = -1.75
ROBOT = "ackermann_robot"
TRAFFIC = ["passenger_car", "suv", "bus", "truck", "motorcycle", ROBOT]
CARS = ["passenger_car", "suv"]
CORDON = ["traffic_cone", "road_barrier", "bollard"]
MARKERS = [*CORDON, "construction_sign"]
PEOPLE = ["pedestrian", "bicycle"]
ENTRANCES = ["Library entrance", "Engineering Hall entrance", "JTEKT building entrance", "Student Union entrance"]
BRIGHT = ["red", "green", "blue", "yellow", "orange", "purple", "pink", "cyan", "teal", "gold"]
MUTED = ["white", "black", "grey", "silver", "brown", "beige", "navy", "maroon"]
ALL_COLOURS = [*BRIGHT, *MUTED]
WARM = ["red", "orange", "brown", "maroon", "gold", "beige", "yellow", "#8b4513", "#a0522d"]
HI_VIS = ["orange", "yellow", "#ccff00", "#ff6600"]
ROUGH = ["cloudy", "rain", "fog", "snow"]
# What comes first when the cases add one: the next free number of each category.
NEW_CAR = "passenger_car_3"
NEW_WALKER = "pedestrian_1"
NEW_TRUCK = "truck_1"
NEW_BUS = "bus_1"
NEW_BENCH = "bench_2"
NEW_SIGN = "construction_sign_1"
NEW_BARRIER = "road_barrier_1"
NEW_BIKE = "bicycle_1"
RUBBLE = "cement_rubble_1"

# --- Voices (each case names its own in `notes`) -----------------------------------------------------------
SURVEYOR = (
    "land surveyor: bearings ('on a bearing of 090'), chainage along the road from the ego, offsets left and right of "
    "the centreline, eastings and northings for x and y, 'set out', 'peg', 're-site', 'datum', precise and numeric"
)
KOREAN = (
    "Korean speaker writing English: polite 'please ... for me', dropped articles and plurals, 'chair' for bench, "
    "'how about', topic first, counting words ('4 person'), 'night 9 o'clock', tense slips ('I add before')"
)
THUMBS = (
    "fat-fingered phone typist: all lower case, no punctuation, adjacent-key typos ('benvh', 'tge', 'cobes'), "
    "missing spaces, autocorrect swaps ('beach' for bench, 'hydrangea' for hydrant, 'dribe' for drive), 'lol', 'idc'"
)
CHEF = (
    "chef / kitchen voice: '86 it' (take it away), 'fire' (start, put out), 'heard', 'yes chef', 'all day' (in total), "
    "'on the pass', 'in the weeds', 'behind!', 'walk-in', 'covers', 'mise en place', short barked orders"
)
FILIPINO = (
    "Filipino English speaker: 'pls', 'kindly', 'po', 'ma'am/sir', 'open/close the lights' for on/off, 'CR' for the "
    "toilet, 'for a while' (wait a moment), 'later' and 'already', polite and warm"
)
STEWARD = (
    "festival steward / crowd marshal: 'punters', 'egress', 'pinch point', 'cordon', 'barrier line', 'sterile area', "
    "'muster point', 'stand down', 'copy that', 'front of house', 'hi-vis', 'doors', crowd-flow reasons"
)
WELSH = (
    "Welsh English speaker: 'now in a minute', 'tidy' (good, proper), 'cwtch' (cuddle, snug corner), 'lush', "
    "'by there / by here', 'isn't it' and 'is it' tags, 'mun', 'there's lovely', 'our Nan', 'mind'"
)
BUS_DRIVER = (
    "retired bus driver who rambles: anecdotes from forty years on the buses ('back in '87 on the number 14...') "
    "wrapped round the request, depot and route words, 'in my day', the request often last"
)


# --- Helpers ----------------------------------------------------------------------------------------------


def brighter() -> list[list[Json]]:
    """Fair readings of 'more light': a higher exposure, the street lights on, or daylight again."""
    return [[env(exposure_min=1.1)], [env(street_lights="on")], [env(time_from="07:00", time_to="17:30")]]


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


# The ego (eastbound at 5 m/s from x = -60) halts short of the west crosswalk: its front never passes x = -13.
EGO_HALTS_AT_WEST_CROSSWALK = stops_before(EGO, -13.0, -1.75, 20.0)


# --- Earlier turns several cases start from ---------------------------------------------------------------
LEAD_CAR_35 = turn(
    "Put a car 35 m ahead of the ego in its lane, driving at 2 m/s.",
    add("passenger_car", where=ahead_of(EGO, 35), behaviour=drive(2.0, EAST)),
)
RUBBLE_40 = turn("Some rubble 40 m ahead of the ego in its lane.", add("cement_rubble", where=ahead_of(EGO, 40)))
HEAVY_FOG = turn("Thick fog.", weather("fog", 0.9))
HEAVY_SNOW = turn("Heavy snow.", weather("snow", 0.9))
LIGHT_RAIN = turn("Light rain, please.", weather("rain", 0.3))
STREET_LIGHTS_ON = turn("Street lights on.", lighting(street_lights="on"))
LATE_NIGHT = turn("Set the time to 23:00.", clock("23:00"))
BARRIERS_EAST_GATE = turn("Put three barriers at the east gate.", add("road_barrier", 3, loc("at", "east gate")))


# --- Search: questions change nothing; the answer names what was asked for ---------------------------------
SEARCH_CASES: list[Json] = [
    # direct
    ask("direct", "library_to_jtekt", SURVEYOR,
        "Give me the straight-line distance from the Library entrance to the JTEKT entrance, to a tenth of a metre.",
        ["84"], [measure("Library entrance", "JTEKT building entrance")]),
    ask("direct", "how_many_street_light", KOREAN, "Please tell me, how many street light are in this map?",
        ["12", "street_light_1", "street_light_12"], [find(category="street_light")]),
    ask("direct", "bin_closest_bus_stop", THUMBS, "which bin is closest to the bus stop", [BIN],
        [find(category="trash_bin", nearest_to="bus stop")]),
    ask("direct", "benches_and_bins", THUMBS, "how many benches are there and how many bins", [BENCH, BIN],
        [find(category="bench"), find(category="trash_bin")]),
    ask("direct", "cars_lot_b_all_day", CHEF, "Cars in lot B, all day - how many and which, chef?", [CAR_W, SUV, CAR_E],
        [find(category="vehicles", near="parking lot B", within=1)]),
    ask("direct", "what_time_po", FILIPINO, "Good morning po. What time is it in the scene right now?", ["12:00"],
        [environment()]),
    ask("direct", "gate_to_gate", STEWARD, "What's the distance from the main gate to the east gate? It's for the egress plan.",
        ["200"], [measure("main gate", "east gate")]),
    ask("direct", "main_street_lanes", WELSH, "What lanes has Main Street got, then?", [EAST, WEST], [lanes(road="Main Street")]),
    ask("direct", "bus_stop_to_library", BUS_DRIVER,
        "Forty years I drove the 14 and I could find every stop in the dark. So where's the bus stop in this thing, "
        "and how far is it from the Library doors?", ["14.5"], [measure("bus stop", "Library entrance")]),
    ask("direct", "heaviest_lot_b", KOREAN, "Which one is the most heavy vehicle in parking lot B?", [SUV, "2100"],
        [find(near="parking lot B", within=1, most="heaviest")]),
    ask("direct", "lamp_nearest_engineering", SURVEYOR,
        "Which street light stands nearest the Engineering Hall entrance, and at what offset?",
        [LAMP_BY_ENGINEERING, "13.6"], [find(category="street_light", nearest_to="Engineering Hall entrance")]),
    impossible("search", "direct", "cr_distance", FILIPINO, "Sir, how far is the CR from the Library po?",
               [measure("CR", "Library entrance")]),
    # indirect
    ask("indirect", "chainage_ego_east_gate", SURVEYOR,
        "I'm setting out a peg line from the ego to the east gate and need the chainage between the two.", ["160"],
        [measure("east gate")]),
    ask("indirect", "chair_near_library", KOREAN,
        "I want to sit down and rest after study in library. Is there any chair close to there?", [BENCH],
        [find(category="bench", nearest_to="Library entrance")]),
    ask("indirect", "night_or_day_screenshots", THUMBS,
        "need to know if its night or day in there before i send screenshots to my boss", ["12:00"], [environment()]),
    ask("indirect", "mise_en_place_signals", CHEF,
        "Mise en place before I touch a thing: what signals are on the corners of the crossroads?", [LIGHT_SW, LIGHT_NE],
        [find(category="traffic_light")]),
    ask("indirect", "ego_lane_for_report", FILIPINO, "Kindly confirm po which lane the ego is using, for my report.",
        [EAST], [properties(asset=EGO)]),
    case("search", "indirect", "muster_point_fountain", STEWARD,
         "We're putting the muster point at the fountain. What's already standing within 25 metres of it?",
         [says(all_of=[TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE], none_of=[TREE_LIBRARY, TREE_LOT_A]), only()],
         [find(near="fountain", within=25)]),
    ask("indirect", "bike_lock_lamp_library", WELSH,
        "Our Cerys wants to lock her bike to a lamp post by the Library doors. Which one's closest, is it?",
        [LAMP_BY_LIBRARY], [find(category="street_light", nearest_to="Library entrance")]),
    case("search", "indirect", "lane_by_bus_stop", BUS_DRIVER,
         "When I did the school runs we always pulled in tight to the kerb at the stop. Which lane runs nearest the "
         "bus stop here?", [says(all_of=[EAST, "Main Street"], none_of=[WEST, NORTH, SOUTH]), only()], [lanes(near="bus stop")]),
    ask("indirect", "ego_heading_and_speed", SURVEYOR,
        "Before I set out anything around it I need the ego's bearing and its speed.", ["0 deg", "5"],
        [properties(asset=EGO)]),
    ask("indirect", "person_added_before", KOREAN, "The person I added before, where is standing now?", [NEW_WALKER],
        [find(category="pedestrian")],
        setup=[turn("Please add one person at Student Union entrance.",
                    add("pedestrian", where=loc("at", "Student Union entrance")), planned=True)]),
    impossible("search", "indirect", "walk_in_distance", CHEF,
               "I'm sending a runner to the walk-in. How far is the walk-in from the Student Union?",
               [measure("walk-in fridge", "Student Union entrance")]),
    # vague
    ask("vague", "whats_round_fountain", THUMBS, "whats around the fountain", [TREE_FOUNTAIN_NW],
        [find(near="fountain", within=20)]),
    ask("vague", "by_there_bus_stop", WELSH, "What's by there at the bus stop, then?", [BENCH, BIN],
        [find(near="bus stop", within=10)]),
    ask("vague", "weather_rundown", CHEF, "Give me the rundown on the weather, chef.", ["clear"], [environment()]),
    ask("vague", "near_library_po", FILIPINO, "Sir, what things are near the Library entrance po?", [LAMP_BY_LIBRARY],
        [find(near="Library entrance", within=15)]),
    ask("vague", "headcount_on_site", STEWARD, "Give me a headcount of everyone on site.",
        ["pedestrian_1", "pedestrian_5"], [find(category="pedestrian")],
        setup=[turn("Put five people at the fountain.", add("pedestrian", 5, loc("next_to", "fountain")), planned=True)]),
    ask("vague", "road_inventory", SURVEYOR, "Run me a quick inventory of the carriageways.", [EAST, WEST, NORTH, SOUTH],
        [lanes()]),
    ask("vague", "ego_situation", KOREAN, "What is the situation of ego car now?", [EAST, "5"], [properties(asset=EGO)]),
    ask("vague", "vehicles_knocking_about", BUS_DRIVER,
        "In my day this place was heaving with buses, you couldn't move for them. What vehicles have you got knocking "
        "about now, then?", [CAR_W, SUV, CAR_E], [find(category="vehicles")]),
    ask("vague", "raining_or_what", THUMBS, "is it raining or what", ["clear"], [environment()]),
    ask("vague", "near_the_junction", CHEF, "What have I got round the junction?", [LIGHT_SW, LIGHT_NE],
        [find(near="main intersection", within=15)]),
    ask("vague", "dark_yet", WELSH, "Is it dark out there yet, or still light?", ["12:00"], [environment()]),
    ask("vague", "where_cones_went", FILIPINO, "Where did the cones go po?",
        ["traffic_cone_1", "traffic_cone_2", "traffic_cone_3"], [find(category="traffic_cone")],
        setup=[turn("Kindly add three cones at the west crosswalk po.", add("traffic_cone", 3, loc("at", "west crosswalk")),
                    planned=True)]),
    impossible("search", "vague", "depot_distance", BUS_DRIVER,
               "Where's the depot got to? Used to be you couldn't miss it. How far is the depot from the main gate?",
               [measure("bus depot", "main gate")]),
    # erroneous
    ask("erroneous", "rhe_fountain_tge_gate", THUMBS, "how far is rhe fountain from tge east gate", ["47.2"],
        [measure("fountain", "east gate")]),
    ask("erroneous", "how_many_bench_is", KOREAN, "How many bench is in this map? Where they are?", [BENCH, "-26"],
        [find(category="bench")]),
    ask("erroneous", "distnace_lot_b_entrnace", SURVEYOR, "Whats the distnace from the ego to the lot B entrnace?",
        ["107"], [measure("parking lot B entrance")]),
    ask("erroneous", "wich_tree_fountian", CHEF, "wich tree is closest to the fountian, chef", [TREE_FOUNTAIN_NW],
        [find(category="tree", nearest_to="fountain")]),
    ask("erroneous", "traffic_light_intersecion", FILIPINO, "Sir pls how many traffic light in the intersecion po",
        [LIGHT_SW, LIGHT_NE], [find(category="traffic_light")]),
    ask("erroneous", "bus_stpo_crosswalk", STEWARD, "Distance form the bus stpo to the west crosswalk?", ["19.3"],
        [measure("bus stop", "west crosswalk")]),
    ask("erroneous", "carpark_nearer_libary", WELSH, "Which carpark's nearer the Libary, A or B, is it?", ["parking lot A"],
        [landmarks(query="parking lot", nearest_to="Library entrance")]),
    ask("erroneous", "weather_doin", BUS_DRIVER,
        "the weather, whats it doin now? my knees say rain but they said that in 1979 an all", ["clear"], [environment()]),
    ask("erroneous", "wheee_bench", THUMBS, "wheee is the bench", [BENCH], [find(category="bench")]),
    ask("erroneous", "ego_speed_how_much", KOREAN, "Ego car speed is how much now? And lane what?", ["5", EAST],
        [properties(asset=EGO)]),
    ask("erroneous", "bearing_engineering_jtekt", SURVEYOR,
        "Bearing and distance from the Engineering Hall entrence to the JTEKT entrance please", ["77.5", "east"],
        [measure("Engineering Hall entrance", "JTEKT building entrance")]),
    ask("erroneous", "benches_all_day", CHEF, "hw many benches all day now", [BENCH, "bench_2", "bench_3"],
        [find(category="bench")],
        setup=[turn("Fire two benches at the fountain.", add("bench", 2, loc("next_to", "fountain")), planned=True)]),
    impossible("search", "erroneous", "first_aid_tent", STEWARD, "How far is the fisrt aid tent from the main gate?",
               [measure("first aid tent", "main gate")]),
]


# --- Addition: new things where they were asked for, and nothing else touched ------------------------------
ADDITION_CASES: list[Json] = [
    # direct
    case("addition", "direct", "cone_at_coordinates", SURVEYOR, "Set out one traffic cone at easting 30, northing -20.",
         [delta("traffic_cone", 1, 1), near(None, 1.0, "traffic_cone", point=(30.0, -20.0)), only("traffic_cone")],
         [add("traffic_cone", where=xy(30.0, -20.0))]),
    case("addition", "direct", "bus_at_bus_stop", KOREAN, "Please add one bus at the bus stop for me.",
         [delta("bus", 1, 1), near("bus stop", 15, "bus"), only("bus")],
         [add("bus", where=loc("in_lane", "bus stop", lane=EAST))]),
    case("addition", "direct", "two_bikes_library", THUMBS, "add 2 bikes at the library",
         [delta("bicycle", 2, 2), near("Library entrance", 12, "bicycle", min_count=2), only("bicycle")],
         [add("bicycle", 2, loc("at", "Library entrance"))]),
    case("addition", "direct", "fire_bench_jtekt", CHEF, "Fire one bench at the JTEKT entrance. Heard?",
         [delta("bench", 1, 1), near("JTEKT building entrance", 10, "bench"), only("bench")],
         [add("bench", where=loc("at", "JTEKT building entrance"))]),
    case("addition", "direct", "bin_student_union", FILIPINO, "Kindly add one trash bin near the Student Union entrance po.",
         [delta("trash_bin", 1, 1), near("Student Union entrance", 10, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("at", "Student Union entrance"))]),
    case("addition", "direct", "barrier_north_crosswalk", STEWARD, "Drop one barrier at the north crosswalk.",
         [delta("road_barrier", 1, 1), near("north crosswalk", 10, "road_barrier"), only("road_barrier")],
         [add("road_barrier", where=loc("at", "north crosswalk"))]),
    case("addition", "direct", "tree_engineering", WELSH, "Pop a tree by the Engineering Hall entrance now in a minute, will you?",
         [delta("tree", 1, 1), near("Engineering Hall entrance", 12, "tree"), only("tree")],
         [add("tree", where=loc("next_to", "Engineering Hall entrance"))]),
    case("addition", "direct", "shuttle_east_gate", BUS_DRIVER,
         "I did the airport shuttle for six years, lovely run that, till they cut it. Put a shuttle bus at the east gate "
         "for old times' sake, and a bench at the bus stop for the regulars.",
         [delta("bus", 1, 1), near("east gate", 15, "bus"), delta("bench", 1, 1), near("bus stop", 10, "bench", scope="added"),
          only("bus", "bench")],
         [add("bus", where=loc("at", "east gate")), add("bench", where=loc("on_sidewalk", "bus stop"))]),
    case("addition", "direct", "two_signs_two_places", SURVEYOR,
         "Set out a construction sign at the Library entrance and a parking sign at the lot A entrance.",
         [delta("construction_sign", 1, 1), delta("parking_sign", 1, 1), near("Library entrance", 10, "construction_sign"),
          near("parking lot A entrance", 10, "parking_sign"), only("construction_sign", "parking_sign")],
         [add("construction_sign", where=loc("at", "Library entrance")),
          add("parking_sign", where=loc("at", "parking lot A entrance"))]),
    case("addition", "direct", "motorcycle_fifteen_ahead", KOREAN, "Add a motorcycle 15 meter in front of ego car, same lane please.",
         [delta("motorcycle", 1, 1), in_lane(EAST, "motorcycle"), near(None, 4, "motorcycle", point=(-45.0, -1.75)),
          only("motorcycle")],
         [add("motorcycle", where=ahead_of(EGO, 15))]),
    impossible("addition", "direct", "sari_sari_store", FILIPINO, "Pls add one sari-sari store beside the bus stop po.",
               [add("sari-sari store", where=loc("next_to", "bus stop"))]),
    # indirect
    case("addition", "indirect", "queue_rubbish", STEWARD,
         "The punters queueing at the Student Union have nowhere to put their rubbish.",
         [delta("trash_bin", 1, None), near("Student Union entrance", 12, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("at", "Student Union entrance"))]),
    case("addition", "indirect", "nan_needs_a_rest", WELSH,
         "Nowhere to sit by the fountain, mun, and our Nan needs a rest after the walk up.",
         [delta("bench", 1, None), near("fountain", 12, "bench"), only("bench")],
         [add("bench", where=loc("next_to", "fountain"))]),
    case("addition", "indirect", "nobody_at_the_stop", BUS_DRIVER,
         "A stop with nobody at it - in forty years I never once pulled into an empty stop at nine in the morning. "
         "Nobody's waiting at the bus stop in here.",
         [delta("pedestrian", 1, None), near("bus stop", 10, "pedestrian"), only("pedestrian")],
         [add("pedestrian", 2, loc("on_sidewalk", "bus stop"))]),
    case("addition", "indirect", "dark_outside_engineering", CHEF,
         "It's pitch black outside the Engineering Hall doors after service, chef. Can't see my hand.",
         [delta("street_light", 1, None), near("Engineering Hall entrance", 12, "street_light", scope="added"),
          only("street_light")],
         [add("street_light", where=loc("at", "Engineering Hall entrance"))]),
    case("addition", "indirect", "slow_truck_ahead", KOREAN,
         "I want test how ego react when slow truck is in front, about 30 meter, same lane.",
         [delta("truck", 1, 1), in_lane(EAST, "truck"), near(None, 4, "truck", point=(-30.0, -1.75)), only("truck")],
         [add("truck", where=ahead_of(EGO, 30), behaviour=drive(2.0, EAST))]),
    case("addition", "indirect", "levelling_warning_sign", SURVEYOR,
         "I'll be levelling on the west crosswalk all morning; drivers need warning there's work on.",
         [delta("construction_sign", 1, None), near("west crosswalk", 12, "construction_sign"), only("construction_sign")],
         [add("construction_sign", where=loc("at", "west crosswalk"))]),
    case("addition", "indirect", "cans_jtekt", THUMBS, "ppl keep dropping cans outside the jtekt building theres no bin",
         [delta("trash_bin", 1, None), near("JTEKT building entrance", 10, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("at", "JTEKT building entrance"))]),
    case("addition", "indirect", "someone_to_follow", FILIPINO,
         "Ma'am, the ego needs someone to follow po. One car in front of it, around 25 meters, same lane.",
         [delta(CARS, 1, 1), in_lane(EAST, CARS), near(None, 5, CARS, point=(-35.0, -1.75)), only(*CARS)],
         [add("passenger_car", where=ahead_of(EGO, 25), behaviour=drive(3.0, EAST))]),
    case("addition", "indirect", "cwtch_with_a_book", WELSH, "Now somebody sat on it for a cwtch with a book.",
         [delta("pedestrian", 1, 1), near(NEW_BENCH, 4, "pedestrian"), only("pedestrian")],
         [add("pedestrian", where=loc("next_to", NEW_BENCH))],
         setup=[turn("Put a bench by the Library entrance, there's lovely.",
                     add("bench", where=loc("at", "Library entrance")), planned=True)]),
    case("addition", "indirect", "lunch_crowd_union", CHEF,
         "Lunch rush at the Student Union - they need somewhere to sit and somewhere to chuck the wrappers.",
         [delta("bench", 1, None), delta("trash_bin", 1, None), near("Student Union entrance", 12, "bench"),
          near("Student Union entrance", 12, "trash_bin"), only("bench", "trash_bin")],
         [add("bench", where=loc("at", "Student Union entrance")),
          add("trash_bin", where=loc("next_to", "Student Union entrance"))]),
    impossible("addition", "indirect", "portaloo_block", STEWARD,
               "The queue at the main gate needs a portaloo block before doors open.",
               [add("portaloo", where=loc("at", "main gate"))]),
    # vague
    case("addition", "vague", "more_ppl_fountain", THUMBS, "more ppl at the fountain",
         [delta("pedestrian", 2, None), near("fountain", 15, "pedestrian", min_count=2), only("pedestrian")],
         [add("pedestrian", 4, loc("next_to", "fountain"))]),
    case("addition", "vague", "greenery_union", WELSH, "Make the Student Union look a bit more tidy with some greenery.",
         [delta("tree", 1, None), near("Student Union entrance", 15, "tree"), only("tree")],
         [add("tree", 2, loc("at", "Student Union entrance"))]),
    case("addition", "vague", "lot_a_dead", CHEF, "Lot A's dead tonight, chef. Get some cars in there.",
         [delta(CARS, 2, None), near("parking lot A", 2, CARS, min_count=2), only(*CARS)],
         [add("passenger_car", 3, loc("at", "parking lot A"))]),
    case("addition", "vague", "presence_east_gate", STEWARD, "Need a bit more presence at the east gate.",
         [delta("pedestrian", 1, None), near("east gate", 15, "pedestrian"), only("pedestrian")],
         [add("pedestrian", 2, loc("at", "east gate"))]),
    case("addition", "vague", "bus_stop_lively", KOREAN, "Bus stop is too lonely. Please make more lively.",
         [delta("pedestrian", 1, None), near("bus stop", 12, "pedestrian"), only("pedestrian")],
         [add("pedestrian", 3, loc("on_sidewalk", "bus stop"))]),
    case("addition", "vague", "mark_chainage_twenty", SURVEYOR, "Mark chainage 20 from the ego somehow.",
         [delta(MARKERS, 1, None), near(None, 6, MARKERS, point=(-40.0, -1.75)), only(*MARKERS)],
         [add("traffic_cone", where=ahead_of(EGO, 20))]),
    case("addition", "vague", "campus_drive_sunday", BUS_DRIVER,
         "Campus Drive looks like a Sunday morning before the football. Bit of traffic on it wouldn't hurt.",
         [delta(TRAFFIC, 1, None), does(["drive_lane", "follow_path"], TRAFFIC), only(*TRAFFIC)],
         [add("passenger_car", 2, loc("in_lane", "north crosswalk", lane=NORTH), behaviour=drive(6.0, NORTH))],
         alternatives=[[near(NORTH, 3, TRAFFIC)], [near(SOUTH, 3, TRAFFIC)]]),
    case("addition", "vague", "parking_b_empty_po", FILIPINO, "Ma'am, parking B is so empty already. Kindly add some cars po.",
         [delta(CARS, 2, None), near("parking lot B", 2, CARS, scope="added", min_count=2), only(*CARS)],
         [add("passenger_car", 2, loc("at", "parking lot B"))]),
    case("addition", "vague", "two_more_of_those", THUMBS, "2 more of those there pls",
         [delta("traffic_cone", 2, 2), near("north crosswalk", 10, "traffic_cone", scope="added", min_count=2),
          only("traffic_cone")],
         [add("traffic_cone", 2, loc("at", "north crosswalk"))],
         setup=[turn("put a cone at the north crosswalk", add("traffic_cone", where=loc("at", "north crosswalk")),
                     planned=True)]),
    case("addition", "vague", "bin_to_go_with_it", WELSH, "And a bin to go with it, now in a minute.",
         [delta("trash_bin", 1, 1), near(NEW_BENCH, 6, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("next_to", NEW_BENCH))],
         setup=[turn("Put a bench by the JTEKT entrance.", add("bench", where=loc("at", "JTEKT building entrance")),
                     planned=True)]),
    case("addition", "vague", "library_seating", CHEF, "The Library front needs a bit of seating. Nothing fancy.",
         [delta("bench", 1, None), near("Library entrance", 12, "bench", scope="added"), only("bench")],
         [add("bench", where=loc("at", "Library entrance"))]),
    case("addition", "vague", "kit_out_fountain", STEWARD,
         "Kit out the fountain area for the crowds - bins, seating, whatever you reckon.",
         [delta(["bench", "trash_bin"], 1, None), only("bench", "trash_bin")],
         [add("bench", where=loc("next_to", "fountain")), add("trash_bin", where=loc("next_to", "fountain"))],
         alternatives=[[near("fountain", 15, "bench", scope="added")], [near("fountain", 15, "trash_bin", scope="added")]]),
    impossible("addition", "vague", "convenience_store", KOREAN,
               "Please add some convenience store near bus stop, for snack.",
               [add("convenience store", where=loc("next_to", "bus stop"))]),
    # erroneous
    case("addition", "erroneous", "benvh_tge_library", THUMBS, "add a benvh by tge library",
         [delta("bench", 1, 1), near("Library entrance", 10, "bench"), only("bench")],
         [add("bench", where=loc("at", "Library entrance"))]),
    case("addition", "erroneous", "three_pedestrian_stand", KOREAN, "Please add three pedestrian at fountain, they stand there.",
         [delta("pedestrian", 3, 3), near("fountain", 12, "pedestrian", min_count=3), only("pedestrian")],
         [add("pedestrian", 3, loc("next_to", "fountain"))]),
    case("addition", "erroneous", "tow_bollards_east_gaet", SURVEYOR, "Set out tow bollards at the east gaet.",
         [delta("bollard", 2, 2), near("east gate", 12, "bollard", min_count=2), only("bollard")],
         [add("bollard", 2, loc("at", "east gate"))]),
    case("addition", "erroneous", "fire_four_conse", CHEF, "fire 4 conse at the nroth crosswalk",
         [delta("traffic_cone", 4, 4), near("north crosswalk", 10, "traffic_cone", min_count=4), only("traffic_cone")],
         [add("traffic_cone", 4, loc("at", "north crosswalk"))]),
    case("addition", "erroneous", "firehydrant_enginering", FILIPINO,
         "Pls add one firehydrant beside the Enginering Hall entrance po",
         [delta("fire_hydrant", 1, 1), near("Engineering Hall entrance", 12, "fire_hydrant"), only("fire_hydrant")],
         [add("fire_hydrant", where=loc("at", "Engineering Hall entrance"))]),
    case("addition", "erroneous", "to_barriers_union", STEWARD, "Need to barriers at the Student Union entrace.",
         [delta("road_barrier", 2, 2), near("Student Union entrance", 12, "road_barrier", min_count=2), only("road_barrier")],
         [add("road_barrier", 2, loc("at", "Student Union entrance"))]),
    case("addition", "erroneous", "tree_by_there_fountian", WELSH, "Put a tree by there at the fountian, tidy.",
         [delta("tree", 1, 1), near("fountain", 12, "tree", scope="added"), only("tree")],
         [add("tree", where=loc("next_to", "fountain"))]),
    case("addition", "erroneous", "buss_main_gait", BUS_DRIVER,
         "put a buss at the main gait like the old days, we used to queue four deep there at shift change",
         [delta("bus", 1, 1), near("main gate", 15, "bus"), only("bus")], [add("bus", where=loc("at", "main gate"))]),
    case("addition", "erroneous", "bollard_fire_hydrangea", THUMBS, "add a bollard by the fire hydrangea",
         [delta("bollard", 1, 1), near(HYDRANT, 5, "bollard"), only("bollard")], [add("bollard", where=loc("next_to", HYDRANT))]),
    case("addition", "erroneous", "car_twenty_behind_of", KOREAN, "Add car 20 meter behind of ego, same lane please.",
         [delta(CARS, 1, 1), in_lane(EAST, CARS), near(None, 5, CARS, point=(-80.0, -1.75)), only(*CARS)],
         [add("passenger_car", where=ahead_of(EGO, -20))]),
    case("addition", "erroneous", "stop_and_pedestrain_signs", SURVEYOR,
         "Set out a stop sign at the wset crosswalk and a pedestrain sign at the north one.",
         [delta("stop_sign", 1, 1), delta("pedestrian_sign", 1, 1), near("west crosswalk", 10, "stop_sign", scope="added"),
          near("north crosswalk", 10, "pedestrian_sign"), only("stop_sign", "pedestrian_sign")],
         [add("stop_sign", where=loc("on_sidewalk", "west crosswalk")),
          add("pedestrian_sign", where=loc("on_sidewalk", "north crosswalk"))]),
    case("addition", "erroneous", "same_again_main_gaet", CHEF, "same again at the main gaet, yes chef",
         [delta("bus", 1, 1), near("main gate", 15, "bus", scope="added"), only("bus")],
         [add("bus", where=loc("at", "main gate"))],
         setup=[turn("Fire a bus at the east gate.", add("bus", where=loc("at", "east gate")), planned=True)]),
    impossible("addition", "erroneous", "phone_boks", WELSH, "Pop a red phone boks by the bus stop, like the old days.",
               [add("phone box", where=loc("next_to", "bus stop"))]),
]


# --- Removal: the right things gone, the rest kept --------------------------------------------------------
REMOVAL_CASES: list[Json] = [
    # direct
    case("removal", "direct", "eighty_six_bench", CHEF, "86 the bench.", [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "direct", "hydrant_at_coordinates", SURVEYOR, "Remove the fire hydrant at easting 16, northing 5.5.",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "direct", "tree_near_library", KOREAN, "Please remove the tree near the library for me.",
         [gone(TREE_LIBRARY), kept(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE, TREE_LOT_A), only(assets=[TREE_LIBRARY])],
         [remove(TREE_LIBRARY)]),
    case("removal", "direct", "delete_stop_sign", THUMBS, "delete the stop sign", [gone(STOP), only(assets=[STOP])],
         [remove(STOP)]),
    case("removal", "direct", "suv_and_bench_po", FILIPINO,
         "Kindly remove the SUV in parking B po, and also the bench at the bus stop.",
         [gone(SUV, BENCH), kept(CAR_W, CAR_E), only(assets=[SUV, BENCH])], [remove(SUV), remove(BENCH)]),
    case("removal", "direct", "clear_both_signals", STEWARD, "Clear both traffic lights off the junction.",
         [gone(LIGHT_SW, LIGHT_NE), only(assets=[LIGHT_SW, LIGHT_NE])], [remove(LIGHT_SW, LIGHT_NE)]),
    case("removal", "direct", "bin_by_bus_stop", WELSH, "Take the bin by the bus stop away, will you.",
         [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "direct", "lamp_like_ninety_two", BUS_DRIVER,
         "That lamp post by the bus stop, the south side one - I reversed into one just like it in '92 and it cost me a "
         "week's wages. Take it out.",
         [gone(LAMP_BY_LIBRARY), kept(*NORTH_LAMPS), only(assets=[LAMP_BY_LIBRARY])], [remove(LAMP_BY_LIBRARY)]),
    case("removal", "direct", "eighty_six_bin_and_hydrant", CHEF, "86 the bin and 86 the hydrant. Behind!",
         [gone(BIN, HYDRANT), only(assets=[BIN, HYDRANT])], [remove(BIN), remove(HYDRANT)]),
    case("removal", "direct", "keep_suv_rest_go", CHEF, "The lot B row's overbooked. Keep the SUV, 86 the other two.",
         [gone(CAR_W, CAR_E), kept(SUV), only(assets=[CAR_W, CAR_E])], [remove(CAR_W, CAR_E)]),
    case("removal", "direct", "stand_down_barriers", STEWARD, "Stand down the barriers.",
         [count("road_barrier", 0, 0), delta("road_barrier", -3, -3), only("road_barrier")],
         [remove(category="road_barrier")], setup=[BARRIERS_EAST_GATE]),
    impossible("removal", "direct", "knock_down_union", WELSH, "Knock down the Student Union, it's an eyesore, mun.",
               [remove("student_union")]),
    # indirect
    case("removal", "indirect", "tree_on_survey_line", SURVEYOR,
         "The tree just north of lot A sits right on my survey line; it has to go.",
         [gone(TREE_LOT_A), kept(TREE_LIBRARY, TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE), only(assets=[TREE_LOT_A])],
         [remove(TREE_LOT_A)]),
    case("removal", "indirect", "broken_chair_bus_stop", KOREAN,
         "Chair at bus stop is broken, nobody can sit on it. Please take away for me.",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "indirect", "suv_blocks_view", THUMBS, "the suv is blocking my view of lot b lol get rid",
         [gone(SUV), kept(CAR_W, CAR_E), only(assets=[SUV])], [remove(SUV)]),
    case("removal", "indirect", "hydrant_trip_hazard", CHEF,
         "That hydrant on the north footpath's a trip hazard for my runners, chef. Nobody needs it.",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "indirect", "stop_sign_confusing_po", FILIPINO,
         "Ma'am, the stop sign near the west crossing is confusing the drivers po. Better if it is not there.",
         [gone(STOP), only(assets=[STOP])], [remove(STOP)]),
    case("removal", "indirect", "hand_marshalled", STEWARD,
         "The signals at the crossroads are off for the event - traffic's being hand-marshalled by my team.",
         [gone(LIGHT_SW, LIGHT_NE), only("traffic_light")], [remove(LIGHT_SW, LIGHT_NE)]),
    case("removal", "indirect", "tree_blocks_reading_room", WELSH,
         "That tree by the Library's blocking all the light from the reading room, it is.",
         [gone(TREE_LIBRARY), kept(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE, TREE_LOT_A), only(assets=[TREE_LIBRARY])],
         [remove(TREE_LIBRARY)]),
    case("removal", "indirect", "abandoned_in_lot_b", BUS_DRIVER,
         "Those three in lot B have been sat there since before I retired, and that was 2009. Abandoned, I tell you. "
         "Nobody's coming back for them.",
         [gone(*LOT_B_ROW), only(assets=LOT_B_ROW)], [remove(*LOT_B_ROW)]),
    case("removal", "indirect", "construction_finished", KOREAN,
         "The construction is finished already, so cones are not needed anymore.",
         [count("traffic_cone", 0, 0), delta("traffic_cone", -4, -4), only("traffic_cone")],
         [remove(category="traffic_cone")],
         setup=[turn("Please add 4 cones at the Library entrance.", add("traffic_cone", 4, loc("at", "Library entrance")),
                     planned=True)]),
    case("removal", "indirect", "delivery_done", CHEF, "Delivery's done. Send the truck on its way, it's not coming back.",
         [count("truck", 0, 0), delta("truck", -1, -1), only("truck")], [remove(NEW_TRUCK)],
         setup=[turn("Fire a truck at the lot B entrance.", add("truck", where=loc("at", "parking lot B entrance")),
                     planned=True)]),
    impossible("removal", "indirect", "fountain_crush_risk", STEWARD,
               "The fountain's a crowd-crush risk at egress. Get it off the site.", [remove("fountain")]),
    # vague
    case("removal", "vague", "lose_couple_lights", THUMBS, "too many lights on main st lose a couple",
         [delta("street_light", -3, -1), only("street_light")], [remove("street_light_1", "street_light_12")]),
    case("removal", "vague", "clutter_by_bus_stop", WELSH, "Tidy up the pavement by the bus stop, there's too much clutter.",
         [delta(["bench", "trash_bin", "street_light"], None, -1), only(assets=[BENCH, BIN, LAMP_BY_LIBRARY])],
         [remove(BIN)]),
    case("removal", "vague", "thin_them_out", CHEF, "Too many cones on the go, chef. Thin them out.",
         [delta("traffic_cone", -5, -1), only("traffic_cone")], [remove(category="traffic_cone", count=3)],
         setup=[turn("Fire six cones in lot B.", add("traffic_cone", 6, loc("at", "parking lot B")), planned=True)]),
    case("removal", "vague", "crossroads_cluttered", STEWARD,
         "The crossroads is too cluttered for crowd flow; strip some of it back.",
         [delta(["traffic_light", "stop_sign", "fire_hydrant", "street_light"], None, -1),
          only(assets=[LIGHT_SW, LIGHT_NE, STOP, HYDRANT, LAMP_BY_STOP_SIGN])],
         [remove(STOP)]),
    case("removal", "vague", "too_many_trees", KOREAN, "There are too many tree. Please remove one.",
         [delta("tree", -1, -1), only("tree")], [remove(TREE_LOT_A)]),
    case("removal", "vague", "closest_to_union", SURVEYOR, "Clear whatever stands closest to the Student Union entrance.",
         [gone(CAR_E), kept(CAR_W, SUV), only(assets=[CAR_E])], [remove(CAR_E)]),
    case("removal", "vague", "lot_b_crowded", BUS_DRIVER,
         "Lot B was always too crowded, even when it was the staff car park. Get a car or two out of it.",
         [delta(CARS, -2, -1), only(*CARS)], [remove(CAR_E)]),
    case("removal", "vague", "fountain_empty_po", FILIPINO,
         "Sir, please remove the people at the fountain po, we need it empty for a while.",
         [count("pedestrian", 0, 0), delta("pedestrian", -3, -3), only("pedestrian")], [remove(category="pedestrian")],
         setup=[turn("Kindly add 3 people at the fountain po.", add("pedestrian", 3, loc("next_to", "fountain")),
                     planned=True)]),
    case("removal", "vague", "actually_nah", THUMBS, "actually nah get rid of it",
         [count("bicycle", 0, 0), delta("bicycle", -1, -1), only("bicycle")], [remove(NEW_BIKE)],
         setup=[turn("put a bike at the bus stop", add("bicycle", where=loc("at", "bus stop")), planned=True)]),
    case("removal", "vague", "one_north_lamp", WELSH, "Lose one of them lamp posts on the north side, there's too many.",
         [delta("street_light", -1, -1), kept(*SOUTH_LAMPS), only(assets=NORTH_LAMPS)], [remove("street_light_5")]),
    case("removal", "vague", "lit_like_a_stadium", STEWARD,
         "The north side of Main Street is lit up like a stadium. Knock a few lamps out.",
         [delta("street_light", -4, -2), kept(*SOUTH_LAMPS), only(assets=NORTH_LAMPS)],
         [remove("street_light_1", "street_light_5", "street_light_9")]),
    case("removal", "vague", "reduce_to_half", KOREAN, "Too many people. Please reduce to half.",
         [delta("pedestrian", -3, -2), only("pedestrian")], [remove(category="pedestrian", count=3)],
         setup=[turn("Add six pedestrians at the Student Union.", add("pedestrian", 6, loc("at", "Student Union entrance")))]),
    impossible("removal", "vague", "crossroads_entirely", BUS_DRIVER,
               "Get rid of the crossroads entirely - we managed with a roundabout and a bobby in my day.",
               [remove("crossroads")]),
    # erroneous
    case("removal", "erroneous", "remive_the_bin", THUMBS, "remive the bin", [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "erroneous", "bench_who_is_near", KOREAN, "Please remove the bench who is near bus stop.",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "erroneous", "remvoe_column_fountian", SURVEYOR, "Remvoe the lamp column nearest the fountian.",
         [gone(LAMP_BY_FOUNTAIN), only(assets=[LAMP_BY_FOUNTAIN])], [remove(LAMP_BY_FOUNTAIN)]),
    case("removal", "erroneous", "teh_hydrant", CHEF, "86 teh hydrant, chef", [gone(HYDRANT), only(assets=[HYDRANT])],
         [remove(HYDRANT)]),
    case("removal", "erroneous", "two_passenger_car_po", FILIPINO,
         "Kindly remove po the two passenger car in the parking B, the SUV will stay.",
         [gone(CAR_W, CAR_E), kept(SUV), only(assets=[CAR_W, CAR_E])], [remove(CAR_W, CAR_E)]),
    case("removal", "erroneous", "trafic_light_north_east", STEWARD, "Remove the trafic light on the north east corner.",
         [gone(LIGHT_NE), kept(LIGHT_SW), only(assets=[LIGHT_NE])], [remove(LIGHT_NE)]),
    case("removal", "erroneous", "tree_nearest_like", WELSH, "Take away the tree by the fountian, the nearest one like.",
         [gone(TREE_FOUNTAIN_NW), kept(TREE_FOUNTAIN_SE), only(assets=[TREE_FOUNTAIN_NW])], [remove(TREE_FOUNTAIN_NW)]),
    case("removal", "erroneous", "stop_sing", BUS_DRIVER,
         "get rid of the stop sing by the west crossing, never stopped anybody anyway, I should know",
         [gone(STOP), only(assets=[STOP])], [remove(STOP)]),
    case("removal", "erroneous", "remove_the_beach", THUMBS, "remove the beach by the bus stop",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "erroneous", "second_bus_too_many", KOREAN, "Remove the second bus please, is too many.",
         [delta("bus", -1, -1), gone("bus_2"), kept(NEW_BUS), only("bus")], [remove("bus_2")],
         setup=[turn("Add 2 bus at east gate.", add("bus", 2, loc("at", "east gate")), planned=True)]),
    case("removal", "erroneous", "tree_and_bench_besides", SURVEYOR,
         "Remove the tree at the Library and the bench besides it.",
         [gone(TREE_LIBRARY, BENCH), only(assets=[TREE_LIBRARY, BENCH])], [remove(TREE_LIBRARY), remove(BENCH)]),
    case("removal", "erroneous", "stand_down_cones_crosing", STEWARD, "Stand down the cones at the west crosing, all of them.",
         [count("traffic_cone", 0, 0), delta("traffic_cone", -4, -4), only("traffic_cone")],
         [remove(category="traffic_cone")],
         setup=[turn("Put four cones at the west crosswalk.", add("traffic_cone", 4, loc("at", "west crosswalk")),
                     planned=True)]),
    impossible("removal", "erroneous", "remove_ego_po", FILIPINO, "Pls remove the ego car po, we dont need it na.",
               [remove(EGO)]),
]


# --- Positioning: an existing thing put somewhere else ------------------------------------------------------
POSITIONING_CASES: list[Json] = [
    # direct
    case("positioning", "direct", "bin_to_coordinates", SURVEYOR, "Re-site the trash bin to easting -20, northing -9.",
         [near(None, 1.0, asset=BIN, point=(-20.0, -9.0)), only(assets=[BIN])], [place(BIN, xy(-20.0, -9.0))]),
    case("positioning", "direct", "bench_front_jtekt", KOREAN, "Please move the bench to the front of the JTEKT building.",
         [near("JTEKT building entrance", 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", "JTEKT building entrance"))]),
    case("positioning", "direct", "suv_in_lot_a", THUMBS, "put the suv in lot a",
         [near("parking lot A", 2, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    case("positioning", "direct", "bench_to_fountain_heard", CHEF, "Bench to the fountain. Heard?",
         [near("fountain", 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "direct", "transfer_hydrant_union", FILIPINO,
         "Kindly transfer the hydrant to the Student Union entrance po.",
         [near("Student Union entrance", 8, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", "Student Union entrance"))]),
    case("positioning", "direct", "stop_sign_north_crosswalk", STEWARD, "Reposition the stop sign to the north crosswalk.",
         [near("north crosswalk", 8, asset=STOP), only(assets=[STOP])],
         [place(STOP, loc("on_sidewalk", "north crosswalk"))]),
    case("positioning", "direct", "bin_engineering_love", WELSH,
         "Shift the bin over by the Engineering Hall entrance for me, love.",
         [near("Engineering Hall entrance", 8, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", "Engineering Hall entrance"))]),
    case("positioning", "direct", "car_one_main_gate", BUS_DRIVER,
         "We always left the relief vehicle at the main gate so the drivers could swap over. Park passenger car 1 at the "
         "main gate.",
         [near("main gate", 12, asset=CAR_W), only(assets=[CAR_W])], [place(CAR_W, loc("at", "main gate"))]),
    case("positioning", "direct", "suv_chainage_car_lot_a", SURVEYOR,
         "Set the SUV at chainage 30 ahead of the ego in its lane, and put passenger car 2 in lot A.",
         [in_lane(EAST, asset=SUV), near(None, 4, asset=SUV, point=(-30.0, -1.75)), near("parking lot A", 2, asset=CAR_E),
          only(assets=[SUV, CAR_E])],
         [place(SUV, ahead_of(EGO, 30)), place(CAR_E, loc("at", "parking lot A"))]),
    case("positioning", "direct", "hydrant_opposite_bus_stop", KOREAN,
         "Please put the hydrant at opposite side of bus stop, across the road, on the footpath.",
         [near(None, 4, asset=HYDRANT, point=(-30.0, 5.5)), on(["sidewalk"], asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, xy(-30.0, 5.5))]),
    impossible("positioning", "direct", "bench_in_canteen", CHEF, "Put the bench inside the Student Union, in the canteen.",
               [place(BENCH, xy(42.0, -62.0))]),
    # indirect
    case("positioning", "indirect", "crowd_at_union", STEWARD,
         "The bin's no use by the bus stop. The crowd will all be at the Student Union.",
         [near("Student Union entrance", 8, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", "Student Union entrance"))]),
    case("positioning", "indirect", "bench_fumes", WELSH,
         "Poor dab, the bench by the road gets all the fumes. It'd be lush by the fountain.",
         [near("fountain", 10, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "indirect", "relief_at_east_gate", BUS_DRIVER,
         "There was always a spare waiting at the east gate in case one broke down on the hill. Have the SUV wait there.",
         [near("east gate", 12, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "east gate"))]),
    case("positioning", "indirect", "hydrant_crowding_pass", CHEF,
         "The hydrant's crowding my pass on the north footpath. Shift it over to the Library.",
         [near("Library entrance", 10, asset=HYDRANT), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", "Library entrance"))]),
    case("positioning", "indirect", "ego_start_main_gate", KOREAN, "I want the ego start from main gate, not from here.",
         [near("main gate", 15, asset=EGO), only(assets=[EGO])], [place(EGO, loc("in_lane", "main gate", lane=EAST))]),
    case("positioning", "indirect", "bench_sightline", SURVEYOR,
         "The bench obstructs my sightline along the south footpath; re-site it beside the Library entrance.",
         [near("Library entrance", 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "Library entrance"))]),
    case("positioning", "indirect", "boss_wants_car_east_gate", THUMBS,
         "my boss wants the car at the west end of the lot b row parked at the east gate instead",
         [near("east gate", 12, asset=CAR_W), kept(SUV, CAR_E), only(assets=[CAR_W])], [place(CAR_W, loc("at", "east gate"))]),
    case("positioning", "indirect", "engineering_no_bin_po", FILIPINO,
         "Ma'am, the students at Engineering have no trash bin and nowhere to sit po. Kindly bring the bin and the bench "
         "from the bus stop.",
         [near("Engineering Hall entrance", 8, asset=BIN), near("Engineering Hall entrance", 10, asset=BENCH),
          only(assets=[BIN, BENCH])],
         [place(BIN, loc("at", "Engineering Hall entrance")), place(BENCH, loc("next_to", "Engineering Hall entrance"))]),
    case("positioning", "indirect", "barrier_for_egress", STEWARD, "That barrier's needed at the east gate now, for egress.",
         [near("east gate", 12, "road_barrier"), delta("road_barrier", 0, 0), only("road_barrier")],
         [place(NEW_BARRIER, loc("at", "east gate"))],
         setup=[turn("Put a barrier at the Library entrance.", add("road_barrier", where=loc("at", "Library entrance")),
                     planned=True)]),
    case("positioning", "indirect", "car_for_the_students", WELSH,
         "The students'll want it by the Student Union, isn't it. Shift it over there.",
         [near("Student Union entrance", 12, asset=NEW_CAR), delta("passenger_car", 0, 0), only("passenger_car")],
         [place(NEW_CAR, loc("at", "Student Union entrance"))],
         setup=[turn("Put a car in lot A.", add("passenger_car", where=loc("at", "parking lot A")), planned=True)]),
    impossible("positioning", "indirect", "bench_on_library_roof", BUS_DRIVER,
               "Best view I ever had was from the top deck. Put the bench up on the Library roof so folk can see out.",
               [place(BENCH, xy(-41.0, -30.0))]),
    # vague
    case("positioning", "vague", "bin_somewhere_better", THUMBS, "move the bin somewhere better",
         [moved(BIN, 1.0), only(assets=[BIN])], [place(BIN, loc("at", "Library entrance"))]),
    case("positioning", "vague", "bench_quiet_cwtch", WELSH,
         "That bench would be tidy in a quiet cwtch somewhere, away from the road.",
         [moved(BENCH, 2.0), on(["ground", "paved"], asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "vague", "suv_out_of_lot_b", CHEF, "Get the SUV out of lot B, anywhere. I need the space.",
         [moved(SUV, 10.0), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    case("positioning", "vague", "hydrant_fire_crews", STEWARD,
         "Put the hydrant by a building entrance, wherever the fire crews would expect it.",
         [moved(HYDRANT, 2.0), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", "Engineering Hall entrance"))],
         alternatives=[[near(entrance, 12, asset=HYDRANT)] for entrance in ENTRANCES]),
    case("positioning", "vague", "suv_near_ego", KOREAN, "Please put SUV somewhere near to ego.",
         [near(EGO, 25, asset=SUV), only(assets=[SUV])], [place(SUV, ahead_of(EGO, 20))]),
    case("positioning", "vague", "bin_jtekt_side", SURVEYOR,
         "Site the bin somewhere sensible on the JTEKT side of Main Street, near the doors.",
         [near("JTEKT building entrance", 15, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", "JTEKT building entrance"))]),
    case("positioning", "vague", "car_two_students_pile_out", BUS_DRIVER,
         "Car 2 could be nearer the Student Union, where the students pile out at four o'clock like a stampede.",
         [near("Student Union entrance", 12, asset=CAR_E), moved(CAR_E, 2.0), only(assets=[CAR_E])],
         [place(CAR_E, loc("at", "Student Union entrance"))]),
    case("positioning", "vague", "bench_shade_po", FILIPINO, "Sir, kindly put the bench near the trees po, for shade.",
         [moved(BENCH, 2.0), only(assets=[BENCH])], [place(BENCH, loc("next_to", TREE_FOUNTAIN_NW))],
         alternatives=[[near(tree, 8, asset=BENCH)] for tree in TREES]),
    case("positioning", "vague", "them_by_fountain", THUMBS, "move them somewhere by the fountain",
         [near("fountain", 12, "pedestrian"), delta("pedestrian", 0, 0), only("pedestrian")],
         [place(NEW_WALKER, loc("next_to", "fountain"))],
         setup=[turn("add a person at the library", add("pedestrian", where=loc("at", "Library entrance")), planned=True)]),
    case("positioning", "vague", "wrong_station", CHEF,
         "Wrong station, chef. Put it where the works actually are - over by the Engineering Hall.",
         [near("Engineering Hall entrance", 12, "construction_sign"), delta("construction_sign", 0, 0),
          only("construction_sign")],
         [place(NEW_SIGN, loc("at", "Engineering Hall entrance"))],
         setup=[turn("Fire a construction sign at the bus stop.", add("construction_sign", where=loc("at", "bus stop")),
                     planned=True)]),
    case("positioning", "vague", "hydrant_by_lamps", WELSH,
         "The hydrant's stuck out on its own by there. Put it in with the lamp posts on the south side, like.",
         [moved(HYDRANT, 2.0), only(assets=[HYDRANT])], [place(HYDRANT, loc("next_to", "street_light_8"))],
         alternatives=[[near(lamp, 5, asset=HYDRANT)] for lamp in SOUTH_LAMPS]),
    case("positioning", "vague", "suv_on_ego_route", STEWARD,
         "Stage the SUV somewhere along the ego's route so it has to deal with it.",
         [in_lane(EAST, asset=SUV), relative("in_front_of", EGO, asset=SUV, max_distance=120, tolerance_deg=20),
          only(assets=[SUV])],
         [place(SUV, ahead_of(EGO, 40))]),
    impossible("positioning", "vague", "fountain_more_center", KOREAN, "Please move fountain to more center of campus.",
               [place("fountain", loc("scene_centre"))]),
    # erroneous
    case("positioning", "erroneous", "thr_bench_fountsin", THUMBS, "put thr bench at the fountsin",
         [near("fountain", 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "erroneous", "bench_union_front", KOREAN, "Bench, please move to Student Union entrance front.",
         [near("Student Union entrance", 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", "Student Union entrance"))]),
    case("positioning", "erroneous", "suv_easting_northign", SURVEYOR, "Place the SUV at easting -90 northign 20.",
         [near(None, 1.5, asset=SUV, point=(-90.0, 20.0)), only(assets=[SUV])], [place(SUV, xy(-90.0, 20.0))]),
    case("positioning", "erroneous", "bin_teh_jtekt", CHEF, "bin to teh JTEKT entrance chef",
         [near("JTEKT building entrance", 8, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", "JTEKT building entrance"))]),
    case("positioning", "erroneous", "suv_front_libary_po", FILIPINO, "Kindly put the suv in front the Libary po.",
         [near("Library entrance", 12, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "Library entrance"))]),
    case("positioning", "erroneous", "hydrant_bus_stpo", STEWARD, "Relocate the hydrant to the bus stpo.",
         [near("bus stop", 8, asset=HYDRANT), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", "bus stop"))]),
    case("positioning", "erroneous", "bin_by_there_libary", WELSH, "Put that bin by there by the Libary, will you.",
         [near("Library entrance", 8, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", "Library entrance"))]),
    case("positioning", "erroneous", "passanger_car_esat_gate", BUS_DRIVER,
         "put the passanger car 1 at the esat gate, that's where the taxis used to wait for the last bus",
         [near("east gate", 12, asset=CAR_W), only(assets=[CAR_W])], [place(CAR_W, loc("at", "east gate"))]),
    case("positioning", "erroneous", "mvoe_suv_ahead", THUMBS, "mvoe the suv 25m ahead of the ego",
         [in_lane(EAST, asset=SUV), near(None, 4, asset=SUV, point=(-35.0, -1.75)), only(assets=[SUV])],
         [place(SUV, ahead_of(EGO, 25))]),
    case("positioning", "erroneous", "bicycle_i_add_before", KOREAN,
         "The bicycle I add before, please move it to library front.",
         [near("Library entrance", 10, "bicycle"), delta("bicycle", 0, 0), only("bicycle")],
         [place(NEW_BIKE, loc("at", "Library entrance"))],
         setup=[turn("Add one bicycle at the bus stop.", add("bicycle", where=loc("at", "bus stop")), planned=True)]),
    case("positioning", "erroneous", "bench_jtekt_bin_rite_next", CHEF,
         "bench to the JTEKT door and the bin rite next to it",
         [near("JTEKT building entrance", 8, asset=BENCH), near(BENCH, 4, asset=BIN), only(assets=[BENCH, BIN])],
         [place(BENCH, loc("at", "JTEKT building entrance")), place(BIN, loc("next_to", BENCH))]),
    case("positioning", "erroneous", "hydrant_left_footpath", SURVEYOR,
         "Set the hydrant 15 m ahaed of the ego on the left-hand footpath.",
         [near(None, 4, asset=HYDRANT, point=(-45.0, 5.5)), on(["sidewalk"], asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, ahead_of(EGO, 15, side="left"))]),
    impossible("positioning", "erroneous", "suv_on_engneering", STEWARD,
               "Put the SUV on top of the Engneering Hall for the camera crew.", [place(SUV, xy(-40.0, 28.0))]),
]


# --- Moving: shifts, turns and what things do over time -----------------------------------------------------
MOVING_CASES: list[Json] = [
    # direct
    case("moving", "direct", "bin_bearing_090", SURVEYOR, "Shift the bin 3 m on a bearing of 090.",
         [moved(BIN, 2.5, 3.5, "forward"), only(assets=[BIN])], [move(BIN, east=3)]),
    case("moving", "direct", "ego_six_meter", KOREAN, "Please make ego speed 6 meter per second.", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=6.0, lane=EAST)], alternatives=new_speed(EGO, 5.5, 6.5)),
    case("moving", "direct", "turn_bench_around", THUMBS, "turn the bench around",
         [moved(BENCH, 0, 1, turn_min=160), only(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    case("moving", "direct", "ego_full_stop_five", CHEF, "Ego: full stop at five seconds. Heard.",
         [timed_event(EGO, "stop", 9.0, (-36.0, -1.75)), only(assets=[EGO])], [manoeuvre(EGO, "stop", at_time=5.0)]),
    case("moving", "direct", "car_one_lot_b_entrance", FILIPINO,
         "Kindly drive passenger car 1 to the lot B entrance po.",
         [reaches(CAR_W, "parking lot B entrance", 40.0, 6.0), only(assets=[CAR_W])],
         [behave(CAR_W, "follow_path", to="parking lot B entrance")]),
    case("moving", "direct", "walk_steward_to_library", STEWARD,
         "Walk a steward from the bus stop to the Library entrance.",
         [delta("pedestrian", 1, 1), reaches("pedestrian", "Library entrance", 30.0, 4.0), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "bus stop"), behaviour={"kind": "follow_path", "to": "Library entrance"})]),
    case("moving", "direct", "left_lane_three_seconds", WELSH, "Change the ego over to the left lane at 3 seconds, will you.",
         [event_played(EGO, "lane_change", 6.0), only(assets=[EGO])],
         [manoeuvre(EGO, "lane_change", at_time=3.0, side="left")]),
    case("moving", "direct", "ego_turn_right_crossroads", BUS_DRIVER,
         "Right-hand turn at the lights, same as the 14 did every morning for thirty years. Make the ego turn right at "
         "the crossroads.",
         [reaches(EGO, "-1.75, -20", 30.0, 4.0), only(assets=[EGO])], [manoeuvre(EGO, "junction_turn", turn="right")]),
    case("moving", "direct", "bench_cw_hydrant_west", SURVEYOR,
         "Rotate the bench 90 degrees clockwise and shift the hydrant 2 m on a bearing of 270.",
         [moved(BENCH, 0, 1, turn_min=80, turn_max=100), moved(HYDRANT, 1.5, 2.5, "backward"),
          only(assets=[BENCH, HYDRANT])],
         [move(BENCH, turn_deg=-90), move(HYDRANT, east=-2)]),
    case("moving", "direct", "car_circle_lot_a", KOREAN, "Please make passenger car 1 drive in circle around parking lot A.",
         [does("circle", asset=CAR_W, centre_near="parking lot A"), only(assets=[CAR_W])],
         [behave(CAR_W, "circle", centre="parking lot A", radius=8.0)]),
    impossible("moving", "direct", "bin_drives_laps", CHEF, "Make the bin drive laps of lot B, chef.",
               [behave(BIN, "circle", centre="parking lot B")]),
    # indirect
    case("moving", "indirect", "held_at_red_crowd", STEWARD,
         "The crowd crosses at the west crosswalk, so the ego has to be held at a red light before it.",
         [EGO_HALTS_AT_WEST_CROSSWALK, only("traffic_light", assets=[EGO])], [hold(LIGHT_SW, "red")]),
    case("moving", "indirect", "going_like_the_clappers", WELSH,
         "The ego's going like the clappers, mun. Slow it to 3, will you.", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=3.0, lane=EAST)], alternatives=new_speed(EGO, 2.5, 3.5)),
    case("moving", "indirect", "chancer_pulls_in", BUS_DRIVER,
         "There was always some chancer who'd pull in right in front of you from the next lane, every single day on "
         "the ring road. Set one of those up for the ego.",
         [only(*TRAFFIC)],
         [add("passenger_car", where=ahead_of(EGO, -10, side="left"), behaviour=drive(8.0)),
          manoeuvre(NEW_CAR, "cut_in", at_time=2.0, gap=8.0)],
         alternatives=[[event_played(category, "cut_in", 10.0)] for category in TRAFFIC]),
    case("moving", "indirect", "slam_on_ten_metres", CHEF,
         "The car in front has to slam on once we're ten metres off its tail. Heard?", [only(assets=[NEW_CAR])],
         [event(NEW_CAR, "stop", {"kind": "distance", "metres": 10.0, "actor": EGO, "other": NEW_CAR}, rate=7.0)],
         setup=[LEAD_CAR_35], alternatives=slows_down(NEW_CAR)),
    case("moving", "indirect", "ego_stop_for_crossing", KOREAN,
         "I want check the ego stop for pedestrian who is crossing at the north crosswalk.",
         [delta("pedestrian", 1, None), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "north crosswalk"), behaviour={"kind": "cross_road"})],
         alternatives=walks_over(NORTH)),
    case("moving", "indirect", "car_two_for_the_crew", SURVEYOR,
         "The crew at the main gate need passenger car 2 brought round to them.",
         [reaches(CAR_E, "main gate", 60.0, 10.0), only(assets=[CAR_E])], [behave(CAR_E, "follow_path", to="main gate")]),
    case("moving", "indirect", "bench_practically_road", THUMBS,
         "the bench is practically in the road lol shove it back from the kerb a couple metres",
         [moved(BENCH, 1.5, 2.5, "left"), only(assets=[BENCH])], [move(BENCH, north=-2)]),
    case("moving", "indirect", "late_po_eight", FILIPINO,
         "Ma'am, the ego is too slow po, we will be late already. Kindly make it 8 m/s.", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=8.0, lane=EAST)], alternatives=new_speed(EGO, 7.5, 8.5)),
    case("moving", "indirect", "steward_to_north_crossing", STEWARD,
         "Send that steward over to cover the north crossing.",
         [reaches("pedestrian", "north crosswalk", 50.0, 4.0), only("pedestrian")],
         [behave(NEW_WALKER, "follow_path", to="north crosswalk")],
         setup=[turn("Put a steward at the JTEKT entrance.", add("pedestrian", where=loc("at", "JTEKT building entrance")),
                     planned=True)]),
    case("moving", "indirect", "car_in_front_swap_lanes", WELSH,
         "That car in front wants to be pulling out into the other lane at 4 seconds, mind.", [only(assets=[NEW_CAR])],
         [manoeuvre(NEW_CAR, "lane_change", at_time=4.0, side="left")],
         alternatives=[[event_played(NEW_CAR, "lane_change", 8.0)]], setup=[LEAD_CAR_35]),
    impossible("moving", "indirect", "two_hundred_mph", BUS_DRIVER,
               "The closest I ever got to flying was the M4 in '81. Make the ego do 200 miles an hour down Main Street.",
               [behave(EGO, "drive_lane", speed=89.0, lane=EAST)]),
    # vague
    case("moving", "vague", "ego_bit_faster", THUMBS, "make the ego go a bit faster", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=7.0, lane=EAST)], alternatives=new_speed(EGO, 5.5, 10.0)),
    case("moving", "vague", "bench_facing_sun", WELSH, "Give the bench a bit of a turn, so it's facing the sun, like.",
         [moved(BENCH, 0, 1.5, turn_min=10, turn_max=180), only(assets=[BENCH])], [move(BENCH, turn_deg=90)]),
    case("moving", "vague", "east_end_car_moving", CHEF, "Get the car on the east end of the lot B row moving, chef.",
         [only(assets=[CAR_E])], [behave(CAR_E, "follow_path", to="parking lot B entrance")], alternatives=gets_going(CAR_E)),
    case("moving", "vague", "someone_crosses_somewhere", STEWARD,
         "Have someone cross the road somewhere so the ego has to deal with them.",
         [delta("pedestrian", 1, None), only("pedestrian")], [add("pedestrian", behaviour={"kind": "jaywalk"})],
         alternatives=walks_over(None, 20.0)),
    case("moving", "vague", "suv_not_just_stay", KOREAN, "Please make SUV go somewhere, not just stay.", [only(assets=[SUV])],
         [behave(SUV, "follow_path", to="east gate")], alternatives=gets_going(SUV)),
    case("moving", "vague", "ease_ego_back", SURVEYOR, "Ease the ego back a touch.", [only(assets=[EGO])],
         [move(EGO, forward=-3)], alternatives=backs_up(EGO, 0.5, 6.0)),
    case("moving", "vague", "calm_the_ego", BUS_DRIVER,
         "The ego's tearing about like a learner on his first day with the big bus. Calm it down a bit.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=3.0, lane=EAST)], alternatives=new_speed(EGO, 0.5, 4.6)),
    case("moving", "vague", "bin_a_little_po", FILIPINO, "Sir, kindly move the bin a little po.",
         [moved(BIN, 0.3, 3.0), only(assets=[BIN])], [move(BIN, east=1)]),
    case("moving", "vague", "car_in_front_annoying", THUMBS, "make the car in front do something annoying",
         [only(assets=[NEW_CAR])], [event(NEW_CAR, "stop", {"kind": "time", "seconds": 4.0}, rate=6.0)], setup=[LEAD_CAR_35],
         alternatives=[[event_played(NEW_CAR, kind, 20.0)] for kind in ("stop", "change_speed", "lane_change", "cut_in")]),
    case("moving", "vague", "wander_off_tidy", WELSH, "Now have them wander off somewhere, tidy.", [only("pedestrian")],
         [behave(NEW_WALKER, "follow_path", to="bus stop")],
         alternatives=[[does(["follow_path", "cross_road", "jaywalk"], "pedestrian")],
                       [event_played("pedestrian", "cross_road", 10.0)]],
         setup=[turn("Put a person by the Library entrance.", add("pedestrian", where=loc("at", "Library entrance")),
                     planned=True)]),
    case("moving", "vague", "stop_sign_some_room", CHEF,
         "The stop sign's jammed right up against that lamp post. Give it some room, chef.",
         [only(assets=[STOP, LAMP_BY_STOP_SIGN])], [move(STOP, east=-2)],
         alternatives=[[moved(STOP, 0.5, 8.0)], [moved(LAMP_BY_STOP_SIGN, 0.5, 8.0)]]),
    case("moving", "vague", "lot_b_too_static", STEWARD, "The lot B row's too static. Get some of it moving.",
         [only(assets=LOT_B_ROW)], [behave(CAR_E, "follow_path", to="east gate")],
         alternatives=[*gets_going(CAR_W), *gets_going(SUV), *gets_going(CAR_E)]),
    impossible("moving", "vague", "tree_dancing", KOREAN, "Please make tree walk around the fountain, like dancing.",
               [behave(TREE_FOUNTAIN_NW, "circle", centre="fountain")]),
    # erroneous
    case("moving", "erroneous", "anticlockwsie", THUMBS, "turn the bench 90 degrees anticlockwsie",
         [moved(BENCH, 0, 1, turn_min=80, turn_max=100), only(assets=[BENCH])], [move(BENCH, turn_deg=90)]),
    case("moving", "erroneous", "change_lane_left_side", KOREAN, "Ego car please change lane to left side after 4 second.",
         [event_played(EGO, "lane_change", 7.0), only(assets=[EGO])],
         [manoeuvre(EGO, "lane_change", at_time=4.0, side="left")]),
    case("moving", "erroneous", "hydrant_baering_270", SURVEYOR, "Shift the hydrant 2 m on a baering of 270.",
         [moved(HYDRANT, 1.5, 2.5, "backward"), only(assets=[HYDRANT])], [move(HYDRANT, east=-2)]),
    case("moving", "erroneous", "sevn_metres_second", CHEF, "Fire the ego up to sevn metres a second.", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=7.0, lane=EAST)], alternatives=new_speed(EGO, 6.5, 7.5)),
    case("moving", "erroneous", "suv_east_gat_po", FILIPINO, "Kindly make the SUV drive to the east gat po.",
         [reaches(SUV, "east gate", 60.0, 8.0), only(assets=[SUV])], [behave(SUV, "follow_path", to="east gate")]),
    case("moving", "erroneous", "ego_stopp_six", STEWARD, "Have the ego stopp at 6 secnds.",
         [timed_event(EGO, "stop", 10.0, (-31.0, -1.75)), only(assets=[EGO])], [manoeuvre(EGO, "stop", at_time=6.0)]),
    case("moving", "erroneous", "back_ego_three_metre", WELSH, "Back the ego up for 3 metre, will you.", [only(assets=[EGO])],
         [move(EGO, forward=-3)], alternatives=backs_up(EGO, 2.5, 3.5)),
    case("moving", "erroneous", "cirkles_skid_pan", BUS_DRIVER,
         "make the suv go round in cirkles in lot B like we did on the skid pan at the training school",
         [does("circle", asset=SUV, centre_near="parking lot B"), only(assets=[SUV])],
         [behave(SUV, "circle", centre="parking lot B", radius=6.0)]),
    case("moving", "erroneous", "dribe_east_gate", THUMBS, "the car i just added make it dribe to the east gate",
         [reaches("passenger_car", "east gate", 60.0, 10.0), only("passenger_car")],
         [behave(NEW_CAR, "follow_path", to="east gate")],
         setup=[turn("add a car at the lot b entrance", add("passenger_car", where=loc("at", "parking lot B entrance")),
                     planned=True)]),
    case("moving", "erroneous", "person_walk_bus_stop", KOREAN, "That person, make walk to bus stop please.",
         [reaches("pedestrian", "bus stop", 30.0, 4.0), only("pedestrian")], [behave(NEW_WALKER, "follow_path", to="bus stop")],
         setup=[turn("Add one person at the Library entrance.", add("pedestrian", where=loc("at", "Library entrance")),
                     planned=True)]),
    case("moving", "erroneous", "forwrd_then_degres", SURVEYOR, "Move the SUV forwrd 4 m, then turn it round 180 degres.",
         [moved(SUV, 3.0, 5.0, "forward", turn_min=160), only(assets=[SUV])],
         [move(SUV, forward=4), move(SUV, turn_deg=180)]),
    case("moving", "erroneous", "brake_three_seconds_off", CHEF,
         "car in front: brake hard when were 3 secnds off hitting it", [only(assets=[NEW_CAR])],
         [event(NEW_CAR, "stop", {"kind": "time_to_collision", "seconds": 3.0, "actor": EGO, "other": NEW_CAR}, rate=7.0)],
         setup=[LEAD_CAR_35], alternatives=slows_down(NEW_CAR)),
    impossible("moving", "erroneous", "bench_round_fountian", WELSH, "Make the bench drive round the fountian, mun.",
               [behave(BENCH, "circle", centre="fountain")]),
]


# --- Arrangement: several new things laid out in a shape, where asked ----------------------------------------
ARRANGEMENT_CASES: list[Json] = [
    # direct
    case("arrangement", "direct", "six_cones_three_centres", SURVEYOR,
         "Set out six cones in a straight line at 3 m centres in lot B.",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6, spacing_min=2.7, spacing_max=3.3),
          near("parking lot B", 2, "traffic_cone", min_count=6), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B"), count=6, spacing=3.0)]),
    case("arrangement", "direct", "five_bollards_library", KOREAN, "Please put 5 bollards in a line in front of Library entrance.",
         [delta("bollard", 5, 5), layout("line", "bollard", 5), near("Library entrance", 12, "bollard", min_count=5),
          only("bollard")],
         [arrange("bollard", "line", loc("in_front_of", "Library entrance"), count=5)]),
    case("arrangement", "direct", "ring_cones_crossroads", THUMBS, "ring of cones around the middle of the crossroads 8 of them",
         [delta("traffic_cone", 8, 8), layout("ring", "traffic_cone", 8, around="main intersection"), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "main intersection"), count=8)]),
    case("arrangement", "direct", "four_benches_union", CHEF, "Line up four benches in a row at the Student Union, chef.",
         [delta("bench", 4, 4), layout("line", "bench", 4), near("Student Union entrance", 15, "bench", min_count=4),
          only("bench")],
         [arrange("bench", "line", loc("at", "Student Union entrance"), count=4)]),
    case("arrangement", "direct", "circle_bollards_library_tree", FILIPINO,
         "Kindly arrange six bollards in a circle around the tree near the library po.",
         [delta("bollard", 6, 6), layout("ring", "bollard", 6, around=TREE_LIBRARY), only("bollard")],
         [arrange("bollard", "ring", loc("at", TREE_LIBRARY), count=6)]),
    case("arrangement", "direct", "barriers_across_campus_north", STEWARD,
         "Run a line of three barriers across Campus Drive, north of the crossing.",
         [delta("road_barrier", 3, 3), layout("line", "road_barrier", 3), some_in_lane(NORTH, "road_barrier"),
          some_in_lane(SOUTH, "road_barrier"), near(None, 10, "road_barrier", point=(0.0, 25.0), min_count=3),
          only("road_barrier")],
         [arrange("road_barrier", "line", xy(0.0, 25.0), count=3, heading_deg=0)]),
    case("arrangement", "direct", "circle_round_stop_sign", WELSH, "Put a circle of bollards round the stop sign, six of them.",
         [delta("bollard", 6, 6), layout("ring", "bollard", 6, around=STOP), only("bollard")],
         [arrange("bollard", "ring", loc("at", STOP), count=6)]),
    case("arrangement", "direct", "three_buses_depot_row", BUS_DRIVER,
         "At the old depot we parked them nose to tail, but side by side looked smarter. Park three buses side by side "
         "in lot A.",
         [delta("bus", 3, 3), layout("line", "bus", 3), near("parking lot A", 3, "bus", min_count=3), only("bus")],
         [arrange("bus", "parking_row", loc("at", "parking lot A"), count=3)]),
    case("arrangement", "direct", "cones_lane_edge_chainage", SURVEYOR,
         "Set out five cones along the edge of the eastbound lane, starting at chainage 20 from the ego.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5), near(EAST, 2.5, "traffic_cone", min_count=5),
          near(None, 15, "traffic_cone", point=(-40.0, -1.75), min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", ahead_of(EGO, 20), count=5)]),
    case("arrangement", "direct", "grid_nine_cones", KOREAN, "Please make grid of 9 cones, 3 column, in parking lot A.",
         [delta("traffic_cone", 9, 9), layout("cluster", "traffic_cone", 9, tolerance=10.0),
          near("parking lot A", 2, "traffic_cone", min_count=9), only("traffic_cone")],
         [arrange("traffic_cone", "grid", loc("at", "parking lot A"), count=9, columns=3)]),
    case("arrangement", "direct", "cones_and_sign_west", CHEF,
         "Four cones in a line at the west crosswalk, and a construction sign beside them.",
         [delta("traffic_cone", 4, 4), layout("line", "traffic_cone", 4), near("west crosswalk", 10, "traffic_cone", min_count=4),
          delta("construction_sign", 1, 1), near("west crosswalk", 12, "construction_sign"),
          only("traffic_cone", "construction_sign")],
         [arrange("traffic_cone", "line", loc("at", "west crosswalk"), count=4),
          add("construction_sign", where=loc("next_to", "west crosswalk"))]),
    case("arrangement", "direct", "same_again_jtekt", THUMBS, "same again at the jtekt entrance",
         [delta("traffic_cone", 4, 4), layout("line", "traffic_cone", 4),
          near("JTEKT building entrance", 12, "traffic_cone", scope="added", min_count=4), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "JTEKT building entrance"), count=4)],
         setup=[turn("put 4 cones in a line at the library", arrange("traffic_cone", "line", loc("at", "Library entrance"),
                                                                    count=4), planned=True)]),
    impossible("arrangement", "direct", "hundred_twenty_cones", STEWARD, "Put a ring of 120 cones round the fountain.",
               [arrange("traffic_cone", "ring", loc("at", "fountain"), count=120)]),
    # indirect
    case("arrangement", "indirect", "crowd_spill_east_gate", STEWARD,
         "The crowd will spill onto Main Street by the east gate at egress; cordon the westbound lane off there.",
         [delta(CORDON, 3, None), some_in_lane(WEST, CORDON), near("east gate", 20, CORDON, min_count=3), only(*CORDON)],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "east gate", lane=WEST), count=5)],
         alternatives=any_shape(CORDON, 3)),
    case("arrangement", "indirect", "kids_climbing_tree", WELSH,
         "The kids keep climbing the tree nearest the fountain. Put something all the way round it, mind.",
         [delta(CORDON, 4, None), layout("ring", CORDON, 4, around=TREE_FOUNTAIN_NW), only(*CORDON)],
         [arrange("bollard", "ring", loc("at", TREE_FOUNTAIN_NW), count=6)]),
    case("arrangement", "indirect", "depot_slalom", BUS_DRIVER,
         "Every new driver did the slalom round the cones in the depot yard before they got a route. Set seven of them "
         "up in a line in lot B for me.",
         [delta("traffic_cone", 7, 7), layout("line", "traffic_cone", 7), near("parking lot B", 2, "traffic_cone", min_count=7),
          only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B"), count=7)]),
    case("arrangement", "indirect", "rubble_on_the_pass", CHEF,
         "There's rubble on the pass, chef. Ring it so nobody drives into it.",
         [delta(CORDON, 3, None), layout("ring", CORDON, 3, around=RUBBLE), only(*CORDON)],
         [arrange("bollard", "ring", loc("at", RUBBLE), count=6)], setup=[RUBBLE_40]),
    case("arrangement", "indirect", "graduation_photo_engineering", KOREAN,
         "Tomorrow is graduation photo. Please 8 person stand in one line in front of Engineering Hall.",
         [delta("pedestrian", 8, 8), layout("line", "pedestrian", 8),
          near("Engineering Hall entrance", 12, "pedestrian", min_count=8), only("pedestrian")],
         [arrange("pedestrian", "line", loc("at", "Engineering Hall entrance"), count=8)]),
    case("arrangement", "indirect", "working_chainage_forty", SURVEYOR,
         "I'm working in the eastbound lane at chainage 40 from the ego; close the lane off there so I'm protected.",
         [delta(CORDON, 3, None), some_in_lane(EAST, CORDON), near(None, 8, CORDON, point=(-20.0, -1.75), min_count=2),
          only(*MARKERS)],
         [arrange("traffic_cone", "line", ahead_of(EGO, 40), count=5, heading_deg=90)]),
    case("arrangement", "indirect", "parking_on_footpath_hydrant", THUMBS,
         "cars keep parking on the north footpath by the hydrant block it off with bollards",
         [delta("bollard", 3, None), layout("line", "bollard", 3), near(HYDRANT, 10, "bollard", min_count=3), only("bollard")],
         [arrange("bollard", "line", loc("next_to", HYDRANT), count=4)]),
    case("arrangement", "indirect", "parade_campus_south", FILIPINO,
         "Ma'am, there will be a parade po on Campus Drive south of the crossing. Kindly block the road with barriers.",
         [delta("road_barrier", 2, None), layout("line", "road_barrier", 2), some_in_lane(NORTH, "road_barrier"),
          some_in_lane(SOUTH, "road_barrier"), near(None, 12, "road_barrier", point=(0.0, -25.0), min_count=2),
          only("road_barrier")],
         [arrange("road_barrier", "line", xy(0.0, -25.0), count=3, heading_deg=0)]),
    case("arrangement", "indirect", "union_queue_tidy", STEWARD,
         "The Student Union queue needs a barrier line to keep it tidy - five barriers should do it.",
         [delta("road_barrier", 5, 5), layout("line", "road_barrier", 5),
          near("Student Union entrance", 15, "road_barrier", min_count=5), only("road_barrier")],
         [arrange("road_barrier", "line", loc("at", "Student Union entrance"), count=5)]),
    case("arrangement", "indirect", "nobody_walks_into_it", WELSH,
         "Put a few bollards all round it so nobody walks into it, tidy.",
         [delta("bollard", 3, None), layout("ring", "bollard", 3, around=NEW_SIGN), only("bollard")],
         [arrange("bollard", "ring", loc("at", NEW_SIGN), count=6)],
         setup=[turn("Put a construction sign at the Library entrance.",
                     add("construction_sign", where=loc("at", "Library entrance")), planned=True)]),
    case("arrangement", "indirect", "nobody_touches_truck", CHEF, "Ring that truck with cones. Nobody touches it.",
         [delta("traffic_cone", 4, None), layout("ring", "traffic_cone", 4, around=NEW_TRUCK), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", NEW_TRUCK), count=10)],
         setup=[turn("Fire a truck in lot A.", add("truck", where=loc("at", "parking lot A")), planned=True)]),
    case("arrangement", "indirect", "coaches_swinging_in", BUS_DRIVER,
         "Coaches swing in wide at the lot B entrance - I've clipped a kerb there myself. Line some cones along it to "
         "guide them.",
         [delta("traffic_cone", 3, None), layout("line", "traffic_cone", 3),
          near("parking lot B entrance", 12, "traffic_cone", min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B entrance"), count=5)]),
    impossible("arrangement", "indirect", "festival_tents", KOREAN,
               "For the festival please put tents in a row at parking lot B, 6 tent.",
               [arrange("tent", "line", loc("at", "parking lot B"), count=6)]),
    # vague
    case("arrangement", "vague", "cone_thing_lot_a", THUMBS, "make a cone thing in lot a",
         [delta("traffic_cone", 3, None), near("parking lot A", 2, "traffic_cone", min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "parking lot A"), count=6)], alternatives=any_shape("traffic_cone", 3)),
    case("arrangement", "vague", "benches_cwtch_fountain", WELSH,
         "Put a few benches round the fountain so folk can have a cwtch.",
         [delta("bench", 2, None), near("fountain", 15, "bench", min_count=2), only("bench")],
         [arrange("bench", "ring", loc("at", "fountain"), count=4)], alternatives=any_shape("bench", 2, 1.5)),
    case("arrangement", "vague", "cordon_by_library", CHEF, "Set up some kind of cordon by the Library.",
         [delta(CORDON, 3, None), near("Library entrance", 15, CORDON, min_count=3), only(*CORDON)],
         [arrange("road_barrier", "line", loc("at", "Library entrance"), count=4)], alternatives=any_shape(CORDON, 3)),
    case("arrangement", "vague", "queue_line_east_gate", STEWARD, "Sort a queue line out at the east gate.",
         [delta([*CORDON, "pedestrian"], 3, None), layout("line", [*CORDON, "pedestrian"], 3),
          near("east gate", 20, [*CORDON, "pedestrian"], min_count=3), only(*CORDON, "pedestrian")],
         [arrange("road_barrier", "line", loc("at", "east gate"), count=4)]),
    case("arrangement", "vague", "union_trees_nice_order", KOREAN,
         "Please make the Student Union front more beautiful with trees, in nice order.",
         [delta("tree", 2, None), near("Student Union entrance", 18, "tree", min_count=2), only("tree")],
         [arrange("tree", "line", loc("at", "Student Union entrance"), count=3)], alternatives=any_shape("tree", 2, 1.5)),
    case("arrangement", "vague", "rough_line_westbound", SURVEYOR,
         "Mark out a rough line across the westbound lane somewhere near the JTEKT entrance.",
         [delta(MARKERS, 2, None), some_in_lane(WEST, MARKERS), near(None, 15, MARKERS, point=(37.5, 1.75), min_count=2),
          only(*MARKERS)],
         [arrange("traffic_cone", "line", xy(37.5, 1.75), count=3, heading_deg=90)], alternatives=any_shape(MARKERS, 2)),
    case("arrangement", "vague", "parked_up_tidy", BUS_DRIVER,
         "The staff car park always had a few cars parked up tidy in it, nose in, no gaps. Lot B wants that look.",
         [delta(CARS, 2, None), layout("line", CARS, 2), near("parking lot B", 2, CARS, scope="added", min_count=2),
          only(*CARS)],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot B"), count=3)]),
    case("arrangement", "vague", "wet_paint_bench", FILIPINO,
         "Ma'am, pls put something around the bench po so nobody sits on it. Wet paint.",
         [delta(CORDON, 3, None), near(BENCH, 6, CORDON, min_count=3), only(*CORDON)],
         [arrange("bollard", "ring", loc("at", BENCH), count=6)], alternatives=any_shape(CORDON, 3)),
    case("arrangement", "vague", "few_cones_around_it", THUMBS, "put a few cones around it too",
         [delta("traffic_cone", 3, None), near(NEW_BARRIER, 6, "traffic_cone", min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", NEW_BARRIER), count=6)], alternatives=any_shape("traffic_cone", 3),
         setup=[turn("add a barrier in lot a", add("road_barrier", where=loc("at", "parking lot A")), planned=True)]),
    case("arrangement", "vague", "same_by_main_gate", WELSH, "Do the same by the main gate now in a minute.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5),
          near("main gate", 15, "traffic_cone", scope="added", min_count=5), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "main gate"), count=5)],
         setup=[turn("Put 5 cones in a line in lot A.", arrange("traffic_cone", "line", loc("at", "parking lot A"), count=5),
                     planned=True)]),
    case("arrangement", "vague", "close_west_crossing_somehow", CHEF, "Close off the west crossing somehow, chef.",
         [delta(CORDON, 2, None), near("west crosswalk", 10, CORDON, min_count=2), only(*CORDON)],
         [arrange("road_barrier", "line", loc("at", "west crosswalk"), count=3)], alternatives=any_shape(CORDON, 2)),
    case("arrangement", "vague", "sterile_zone_north_crossing", STEWARD,
         "Set up a sterile zone around the north crossing for the parade.",
         [delta(CORDON, 4, None), near("north crosswalk", 15, CORDON, min_count=4), only(*CORDON)],
         [arrange("traffic_cone", "ring", loc("at", "north crosswalk"), count=8)],
         alternatives=[[layout("ring", CORDON, 4, around="north crosswalk")], *any_shape(CORDON, 4)]),
    impossible("arrangement", "vague", "twenty_routemasters", BUS_DRIVER,
               "Line up some of the old Routemasters in lot B, twenty of 'em, like the depot on a Sunday.",
               [arrange("bus", "parking_row", loc("at", "parking lot B"), count=20)]),
    # erroneous
    case("arrangement", "erroneous", "six_cobes_lot_b", THUMBS, "6 cobes in a line in lot b",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6), near("parking lot B", 2, "traffic_cone", min_count=6),
          only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B"), count=6)]),
    case("arrangement", "erroneous", "bollards_by_circle_hydrant", KOREAN,
         "Please put 4 bollards by circle around the fire hydrant.",
         [delta("bollard", 4, 4), layout("ring", "bollard", 4, around=HYDRANT), only("bollard")],
         [arrange("bollard", "ring", loc("at", HYDRANT), count=4)]),
    case("arrangement", "erroneous", "lnie_two_cnetres", SURVEYOR, "Set out five cones in a lnie at 2 m cnetres in lot A.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5, spacing_min=1.8, spacing_max=2.2),
          near("parking lot A", 2, "traffic_cone", min_count=5), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot A"), count=5, spacing=2.0)]),
    case("arrangement", "erroneous", "barirers_acros_eastbound", CHEF,
         "line of 3 barirers acros the eastbound lane 30m ahead of ego",
         [delta("road_barrier", 3, 3), layout("line", "road_barrier", 3), some_in_lane(EAST, "road_barrier"),
          near(None, 8, "road_barrier", point=(-30.0, -1.75), min_count=3), only("road_barrier")],
         [arrange("road_barrier", "line", ahead_of(EGO, 30), count=3, heading_deg=90)]),
    case("arrangement", "erroneous", "six_cone_nort_crosswalk", FILIPINO,
         "Kindly put 6 cone in circle at the nort crosswalk po.",
         [delta("traffic_cone", 6, 6), layout("ring", "traffic_cone", 6, around="north crosswalk"), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "north crosswalk"), count=6)]),
    case("arrangement", "erroneous", "barrier_line_mian_gate", STEWARD, "Barrier line of 4 at the mian gate.",
         [delta("road_barrier", 4, 4), layout("line", "road_barrier", 4), near("main gate", 15, "road_barrier", min_count=4),
          only("road_barrier")],
         [arrange("road_barrier", "line", loc("at", "main gate"), count=4)]),
    case("arrangement", "erroneous", "row_of_tress_studnet", WELSH, "Put a row of tress along by the Studnet Union, three of them.",
         [delta("tree", 3, 3), layout("line", "tree", 3), near("Student Union entrance", 15, "tree", min_count=3),
          only("tree")],
         [arrange("tree", "line", loc("at", "Student Union entrance"), count=3)]),
    case("arrangement", "erroneous", "park_for_cars", BUS_DRIVER,
         "park for cars side by side in lot A, proper bays like the staff car park, none of this parking on the grass",
         [delta(CARS, 4, 4), layout("line", CARS, 4), near("parking lot A", 2, CARS, min_count=4), only(*CARS)],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot A"), count=4)]),
    case("arrangement", "erroneous", "bollards_arounf_tree_lot_a", THUMBS, "ring of bollards arounf the tree by lot a",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around=TREE_LOT_A), only("bollard")],
         [arrange("bollard", "ring", loc("at", TREE_LOT_A), count=6)]),
    case("arrangement", "erroneous", "cones_around_of_truck", KOREAN, "Please put cones around of the truck I added.",
         [delta("traffic_cone", 4, None), layout("ring", "traffic_cone", 4, around=NEW_TRUCK), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", NEW_TRUCK), count=10)],
         setup=[turn("Add one truck at parking lot B.", add("truck", where=loc("at", "parking lot B")), planned=True)]),
    case("arrangement", "erroneous", "bollards_east_gaet_sing", SURVEYOR,
         "Set out 4 bollards in a line at the east gaet and a construction sing beside them.",
         [delta("bollard", 4, 4), layout("line", "bollard", 4), near("east gate", 15, "bollard", min_count=4),
          delta("construction_sign", 1, 1), near("east gate", 15, "construction_sign"), only("bollard", "construction_sign")],
         [arrange("bollard", "line", loc("at", "east gate"), count=4),
          add("construction_sign", where=loc("next_to", "east gate"))]),
    case("arrangement", "erroneous", "same_agian_west_crosswlak", CHEF, "same agian at the west crosswlak",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5),
          near("west crosswalk", 10, "traffic_cone", scope="added", min_count=5), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "west crosswalk"), count=5)],
         setup=[turn("Line up five cones at the north crosswalk.",
                     arrange("traffic_cone", "line", loc("at", "north crosswalk"), count=5))]),
    impossible("arrangement", "erroneous", "radius_eighty_fountian", STEWARD,
               "Put a ring of bollards, radius 80 m, arround the fountian.",
               [arrange("bollard", "ring", loc("at", "fountain"), radius=80.0)]),
]


# --- Appearance: looks, weather, clock and lights ------------------------------------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case("appearance", "direct", "time_0715", SURVEYOR, "Set the scene time to 07:15.",
         [env(time_from="07:10", time_to="07:20"), only(env=True)], [clock("07:15")]),
    case("appearance", "direct", "heavy_rain_please", KOREAN, "Please make heavy rain for me.",
         [env(weather=["rain"], intensity_min=0.75), only(env=True)], [weather("rain", 0.9)]),
    case("appearance", "direct", "paint_bench_green", THUMBS, "paint the bench green",
         [looks("green", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="green")]),
    case("appearance", "direct", "street_lights_on_chef", CHEF, "Street lights on, chef.",
         [env(street_lights="on"), only(env=True)], [lighting(street_lights="on")]),
    case("appearance", "direct", "open_vehicle_lights_po", FILIPINO, "Kindly open the headlights of the vehicles po.",
         [env(vehicle_lights="on"), only(env=True)], [lighting(vehicle_lights="on")]),
    case("appearance", "direct", "time_2230", STEWARD, "Set the time to 22:30.",
         [env(time_from="22:25", time_to="22:35"), only(env=True)], [clock("22:30")]),
    case("appearance", "direct", "light_fog_mind", WELSH, "Make it foggy - light fog, mind.",
         [env(weather=["fog"], intensity_max=0.4), only(env=True)], [weather("fog", 0.3)]),
    case("appearance", "direct", "suv_school_bus_yellow", BUS_DRIVER,
         "The school buses were all yellow when I started, before the council went green and cream. Paint the SUV yellow.",
         [looks("yellow", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="yellow")]),
    case("appearance", "direct", "clock_and_moderate_snow", SURVEYOR, "Set the clock to 18:40 and the weather to moderate snow.",
         [env(weather=["snow"], intensity_min=0.45, intensity_max=0.75, time_from="18:35", time_to="18:45"), only(env=True)],
         [clock("18:40"), weather("snow", 0.6)]),
    case("appearance", "direct", "hydrant_blue", KOREAN, "Please change color of the hydrant to blue.",
         [looks("blue", asset=HYDRANT), only(assets=[HYDRANT])], [paint([HYDRANT], colour="blue")]),
    impossible("appearance", "direct", "thunderstorm_lightning", CHEF, "Give me a thunderstorm with lightning, chef.",
               [weather("thunderstorm", 0.9)]),
    # indirect
    case("appearance", "indirect", "doors_half_seven", STEWARD,
         "Doors open at half past seven in the evening. Set the scene for then.",
         [env(time_from="19:25", time_to="19:35"), only(env=True)], [clock("19:30")]),
    case("appearance", "indirect", "wet_welsh_afternoon", WELSH,
         "Make it like a proper wet Welsh afternoon - raining cats and dogs, it is.",
         [env(weather=["rain"], intensity_min=0.7, time_from="12:00", time_to="17:59"), only(env=True)],
         [weather("rain", 0.9)]),
    case("appearance", "indirect", "first_bus_ten_to_six", BUS_DRIVER,
         "First bus out of the depot was always ten to six, rain or shine, thirty-one years. Set the clock to that.",
         [env(time_from="05:45", time_to="05:55"), only(env=True)], [clock("05:50")]),
    case("appearance", "indirect", "cant_see_the_pass", CHEF, "I can't see a thing out there, chef. It's too dark.",
         [only(env=True)], [lighting(street_lights="on")], alternatives=brighter(), setup=[LATE_NIGHT]),
    case("appearance", "indirect", "night_camera_street_light", KOREAN,
         "I want test the camera in night time, with the street light working.",
         [env(night=True, street_lights="on"), only(env=True)], [clock("22:00"), lighting(street_lights="on")]),
    case("appearance", "indirect", "survey_visibility", SURVEYOR,
         "I need clear sightlines for the survey; the instrument can't see through this.",
         [env(weather=["clear", "cloudy"]), only(env=True)], [weather("clear")], setup=[HEAVY_FOG]),
    case("appearance", "indirect", "bollards_invisible_night", THUMBS,
         "the bollards i put are invisible at night make them pop",
         [looks(BRIGHT, "bollard", every=True, min_count=3), only("bollard")], [paint(category="bollard", colour="yellow")],
         setup=[turn("put 3 bollards at the north crosswalk", add("bollard", 3, loc("at", "north crosswalk")), planned=True)]),
    case("appearance", "indirect", "christmas_theme_po", FILIPINO,
         "Ma'am, for our Christmas theme po, the SUV should be red and the bench green.",
         [looks("red", asset=SUV), looks("green", asset=BENCH), only(assets=[SUV, BENCH])],
         [paint([SUV], colour="red"), paint([BENCH], colour="green")]),
    case("appearance", "indirect", "hi_vis_barriers", STEWARD, "Hi-vis on the barriers, please. Nobody can see them.",
         [looks(HI_VIS, "road_barrier", every=True, min_count=3), only("road_barrier")],
         [paint(category="road_barrier", colour="orange")], setup=[BARRIERS_EAST_GATE]),
    case("appearance", "indirect", "light_dusting", WELSH, "That snow's far too much. Just a light dusting, tidy.",
         [env(weather=["snow"], intensity_max=0.4), only(env=True)], [weather("snow", 0.2)], setup=[HEAVY_SNOW]),
    impossible("appearance", "indirect", "library_cream_livery", BUS_DRIVER,
               "The Library could do with a lick of paint. Cream, like the old bus livery, the whole building.",
               [paint(["library"], colour="beige")]),
    # vague
    case("appearance", "vague", "look_moody", THUMBS, "make it look moody", [only(env=True)], [weather("fog", 0.5)],
         alternatives=[*darker(), [env(weather=["fog", "rain", "cloudy", "snow"])]]),
    case("appearance", "vague", "cwtchy_evening", WELSH, "Make it a bit more cwtchy out there, like evening time.",
         [env(time_from="17:30", time_to="21:30"), only(env=True)], [clock("19:00")]),
    case("appearance", "vague", "too_bright_in_here", CHEF, "Turn it down a notch, chef, it's far too bright in here.",
         [only(env=True)], [lighting(exposure=0.7)],
         alternatives=[[env(exposure_max=0.95)], [env(time_from="17:30", time_to="06:00")], [env(weather=["cloudy", "fog"])]]),
    case("appearance", "vague", "rough_for_crowd_test", STEWARD, "Make the weather a bit rough for the crowd test.",
         [env(weather=ROUGH), only(env=True)], [weather("rain", 0.6)]),
    case("appearance", "vague", "ego_something_bright", KOREAN, "Please change the ego color, something bright.",
         [looks(BRIGHT, asset=EGO), only(assets=[EGO])], [paint([EGO], colour="orange")]),
    case("appearance", "vague", "survey_conditions", SURVEYOR, "Give me typical survey-day conditions: overcast and early.",
         [env(weather=["cloudy", "fog"], time_from="05:00", time_to="09:30"), only(env=True)],
         [weather("cloudy", 0.6), clock("07:00")]),
    case("appearance", "vague", "winters_morning_first_run", BUS_DRIVER,
         "Give it the feel of a winter's morning on the first run - I'd be scraping the windscreen of the 14 in the dark.",
         [env(weather=["snow", "fog", "cloudy"], time_from="05:00", time_to="10:00"), only(env=True)],
         [weather("snow", 0.5), clock("06:30")]),
    case("appearance", "vague", "cones_more_visible_po", FILIPINO, "Sir, kindly make the cones more visible po.",
         [looks(BRIGHT, "traffic_cone", every=True, min_count=4), only("traffic_cone")],
         [paint(category="traffic_cone", colour="orange")],
         setup=[turn("Kindly add 4 cones at the Library entrance po.", add("traffic_cone", 4, loc("at", "Library entrance")),
                     planned=True)]),
    case("appearance", "vague", "suv_colour_idc", THUMBS, "change the suv colour idc what",
         [looks(ALL_COLOURS, asset=SUV), only(assets=[SUV])], [paint([SUV], colour="blue")]),
    case("appearance", "vague", "grey_and_miserable", WELSH, "It's grey and miserable out there. Cheer it up, will you.",
         [only(env=True)], [weather("clear")],
         alternatives=[[env(weather=["clear"])], [env(weather=["rain"], intensity_max=0.15)]], setup=[LIGHT_RAIN]),
    case("appearance", "vague", "bench_warm_look", CHEF, "Give the bench a fresh look, chef - something warm.",
         [only(assets=[BENCH])], [paint([BENCH], colour="orange")],
         alternatives=[[looks(WARM, asset=BENCH)], [looks(asset=BENCH, material="wood")]]),
    case("appearance", "vague", "late_night_event", STEWARD, "Set it up for a late-night event.",
         [env(night=True), only(env=True)], [clock("23:00")]),
    impossible("appearance", "vague", "yellow_dust_day", KOREAN, "Please make weather like yellow dust day, 황사.",
               [weather("yellow dust", 0.7)]),
    # erroneous
    case("appearance", "erroneous", "make_it_rian", THUMBS, "make it rian", [env(weather=["rain"]), only(env=True)],
         [weather("rain", 0.6)]),
    case("appearance", "erroneous", "night_nine_oclock", KOREAN, "Please set the time to night 9 o'clock.",
         [env(time_from="20:55", time_to="21:05"), only(env=True)], [clock("21:00")]),
    case("appearance", "erroneous", "clcok_0645", SURVEYOR, "Set the clcok to 06:45.",
         [env(time_from="06:40", time_to="06:50"), only(env=True)], [clock("06:45")]),
    case("appearance", "erroneous", "bin_purpel", CHEF, "make the bin purpel, chef", [looks("purple", asset=BIN), only(assets=[BIN])],
         [paint([BIN], colour="purple")]),
    case("appearance", "erroneous", "close_street_lights_po", FILIPINO, "Kindly close the street lights po, its morning na.",
         [env(street_lights="off"), only(env=True)], [lighting(street_lights="off")], setup=[STREET_LIGHTS_ON]),
    case("appearance", "erroneous", "foggy_heavey", STEWARD, "Make it foggy, heavey.",
         [env(weather=["fog"], intensity_min=0.75), only(env=True)], [weather("fog", 0.9)]),
    case("appearance", "erroneous", "quarter_to_ate", WELSH, "Put the time to quarter to ate in the morning, will you.",
         [env(time_from="07:40", time_to="07:50"), only(env=True)], [clock("07:45")]),
    case("appearance", "erroneous", "mauroon_livery", BUS_DRIVER,
         "paint the suv in the old livery, mauroon it was, the company colours before the buyout",
         [looks(["maroon", "#800000"], asset=SUV), only(assets=[SUV])], [paint([SUV], colour="maroon")]),
    case("appearance", "erroneous", "stret_lights_on", THUMBS, "turn on the stret lights",
         [env(street_lights="on"), only(env=True)], [lighting(street_lights="on")]),
    case("appearance", "erroneous", "snow_little_bit", KOREAN, "Please make snow, but little bit only, not many.",
         [env(weather=["snow"], intensity_max=0.4), only(env=True)], [weather("snow", 0.25)]),
    case("appearance", "erroneous", "exposre_vehical_lights", SURVEYOR,
         "Set exposre to 0.8 and switch the vehical lights on.",
         [env(exposure_min=0.75, exposure_max=0.85, vehicle_lights="on"), only(env=True)],
         [lighting(exposure=0.8), lighting(vehicle_lights="on")]),
    case("appearance", "erroneous", "nah_blu_instead", CHEF, "nah, make it blu instead",
         [looks("blue", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="blue")],
         setup=[turn("Paint the bench grey.", paint([BENCH], colour="grey"), planned=True)]),
    impossible("appearance", "erroneous", "hial_stones", WELSH, "Make it do hial, proper big hailstones, mun.",
               [weather("hail", 0.8)]),
]


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
