"""The twenty-ninth practice suite: 328 cases in everyday English from eight new kinds of ordinary user, from the campus world alone.

`python -m drivetwin.evals.practice29_source` writes `suites/practice29.jsonl` (tag `practice29`, ids
`practice29.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`), none used by practice27 or practice28: a primary-school teacher planning
a class field trip ("the children", "our coach", "the class needs to line up", "the little ones can't reach it",
"our school colour is yellow"), a motorsport fan ("that's the safety car", "box box", "the pits", "lights out and away
we go", "a pit wall", "donuts", "flat out down the straight", "a chicane"), a Japanese speaker writing English without
articles or plurals ("Which tree is most near to ...", "at front of", "beside of", "three cone", "make little bit busy",
"Robot, please make it moving"), an architect talking about the public realm ("the JTEKT forecourt", "the Student
Union frontage", "soft landscaping", "the desire line", "frame the Library approach", "a rhythm of street trees"), a
bored night-shift tester typing tersely in lower case ("list traffic lights", "rm passenger_car_2", "suv -> 30,-20",
"ego the other way", "dark.", "cone grd lot b 3x3"), a grandparent unfamiliar with computers ("the motor car", "that
thingy the fire brigade uses", "those short posts", "my knees, you see", "dear"), an e-bike courier ("my drop-off",
"where I lock up", "some muppet's left their car", "send the bike off", "pls") and a German engineer writing very
formally ("It is requested that", "shall be positioned", "in their entirety", "at 14.30 hours", "set to 1,5").

Prompts describe things instead of naming them ("the tree between the bus stop and the Library", "the street light
nearest to the Library entrance", "the car at the east end of the row in parking B", "the car in the middle of the
row", "the big car", "the lamp post in front of the Engineering Hall", "the traffic light on the north-east corner",
"the tree north of parking lot A", "that robot", "the debris"), turn on negation
and polarity ("every car in it except the SUV", "lose the bin, but keep the bench", "just keep the one by the
fountain", "keep only ones on north side", "the SUV is to be left unchanged", "a little less", "moderated", "not
orange", "No, not that one"), and name places and scopes (lanes and roads, "40 metres ahead of the ego", "15 meter
behind of ego car in same lane", "35 m ahead of the ego vehicle", "the northern footway of Main Street", "Campus
Drive north of the junction", "across it at the north crosswalk", "the south-west corner of the junction", "x = -10,
y = -25", "1.75,-20", "x=500, y=0"). They carry clock times in several forms ("7 in morning", "time 0200", "21:30",
"six thirty in evening", "22 o'clock", "9 in the morning", "14.30 hours", "three o'clock", "just after sunset",
"late-afternoon"), weather with strengths (a light fog, dense fog, moderate fog, heavy rain, "properly soaked", "lite
rain", "rain littel", some snow, heavy snow, "a little less" snow, "a proper British summer"), numbers in words and
digits with units ("fifteen metres", "10 m/s", "2 metres a second", "6 m/s", "a radius 5 m", "8m radius", "4,5 m",
"300 km/h", "200 bollard", "x5", "3x3"), questions (which must change nothing: their checks hold the scene unchanged
and their reference answers with a search), and behaviours over time: speeds, a stop after five seconds, hard braking
4 seconds in, a lead car braking once the ego is 12 m away, lane changes, left and right turns at the junction, a
signal held at red so the ego halts before the west crosswalk, stopping for the zebra crossing, walkers crossing or
stepping out in front of the ego, a car, a bicycle and pedestrians going to the east gate, the bus stop and the
fountain, circles in lot B with and without a radius, backing up. The erroneous grade carries realistic typos,
dropped words and run-together words ("how many benchs are near the libary", "hw mny streetlights", "distnce from lot
b entrnce", "add a bech by the fountian", "put an suv 20m behnd the ego", "remvoe all tree", "rm trafic lite sw corner
+ the stop sgin", "put the ego ot lot a entrnce", "suv do circels in lot b", "put 4 cones in aline infront of the
library entrence", "turn the stret lamps of", "make the suv invisable").

Counts: 7 tasks x 4 grades, every cell 11 to 14 cases; search, moving and arrangement hold at least 12 in every grade
(328 in all). 51 cases are multi-turn (31 with a planned earlier turn that has calls), with references back: "it",
"them", "that car", "this car", "that robot", "that person", "one of them", "one of those", "the coach", "her", "do the
same again", "make the line longer", "a couple more of those", "One more same one, next to it"; corrections "Oh no,
not there ... Put it back by the bus stop", "sorry i ment purple not orange", "No, not that one, dear. The other one
at the far end", "nah. remove". 27 are compound (two requests in one prompt; the reference makes two calls or more),
and 28 (8.5 %) impossible, tagged `impossible`, where the right outcome is a refusal that changes nothing: a post
office, a tram stop, toilets, a helipad; a post box, a grandstand, 300 cars, a bike rack; removing the Library, the
crossroads, the buildings or the ego; a bench on the Library's roof, the SUV on top of the JTEKT Building, the ego in
the fountain, a bench at x = 500; a walking tree, 300 km/h, a drifting bench, reversing 300 m; 200 bollards, a ring of
grandstands, trees inside the Engineering Hall, 500 cones; rainbow stripes, a sandstorm, hail, an invisible SUV.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with `alternatives`
where a request has two fair readings (a speed set on the lane behaviour or by a change-of-speed manoeuvre, backing up
by a shift or a reverse manoeuvre, a crossing as a behaviour or a manoeuvre, stepping out as a jaywalk, a crossing or
a stop mid-road, heading off by a lane behaviour or a drive to the gate, "somewhere shady" by any of the four trees,
"where the pedestrians cross" at either crosswalk, off the racing line into the other lane or onto paving, brighter
by the clock, the street lights or exposure, "dark" by the clock or exposure, "moderated" rain as lighter rain or
cloud, a cheerful colour on either end car, racing livery as a colour or a finish), and a `reference` plan that
passes; a plan that does nothing fails every case but the questions and the impossible ones, whether or not its
planned earlier turns were done. The suite was written from the campus world, the asset catalog, the Worker tools and
the eval checks only, by someone who had not read the planners, their lexicons, their prompt examples or any other
suite's cases (practice27's and practice28's sources were read for their format only).
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
    ego_speed_between,
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
    planned,
    properties,
    reach,
    reaches,
    relative,
    remove,
    stops_before,
    turn,
    weather,
    xy,
)

TAG = "practice29"
S = Suite(TAG)
case = S.case
impossible = S.impossible
ask = S.ask

# --- The campus as it ships: ids and places the cases name -------------------------------------------
SUV = "suv_1"  # middle of the row of three in lot B, (23, -42), facing north
CAR1 = "passenger_car_1"  # west end of that row, (19, -42)
CAR2 = "passenger_car_2"  # east end of that row, (27, -42)
PARKED = [CAR1, SUV, CAR2]
BENCH = "bench_1"  # south pavement just east of the bus stop, (-26, -6.9), facing west
BIN = "trash_bin_1"  # south pavement just west of the bus stop, (-33.5, -5.5)
HYDRANT = "fire_hydrant_1"  # north pavement of Main Street just east of the crossroads, (16, 5.5)
STOP = "stop_sign_1"  # south pavement just west of the west crosswalk, (-13.5, -5.5)
LIGHT_SW = "traffic_light_1"  # south-west corner of the crossroads, (-9.5, -6.2)
LIGHT_NE = "traffic_light_2"  # north-east corner, (9.5, 6.2)
TREE_BUS = "tree_1"  # between the bus stop and the Library, (-26, -12)
TREE_FOUNT = "tree_2"  # just north-west of the fountain, (70, 45)
TREE_SE = "tree_3"  # south-east of the fountain, (85, 25)
TREE_LOT_A = "tree_4"  # just north of lot A, (-85, 50)
TREES = [TREE_BUS, TREE_FOUNT, TREE_SE, TREE_LOT_A]
NORTH_LAMPS = [f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11)]  # y = 5.8, x = -80, -50, -25, 25, 50, 80
SOUTH_LAMPS = [f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12)]  # y = -5.8, x = -68, -38, -13, 37, 62, 92
LAMP_BY_LIBRARY = "street_light_4"  # (-38, -5.8), the nearest to the Library entrance
LAMP_BY_ENGINEERING = "street_light_3"  # (-50, 5.8), the nearest to the Engineering Hall entrance
EAST = "main_eastbound"
WEST = "main_westbound"
NORTH = "campus_northbound"
SOUTH = "campus_southbound"
ROBOT = "ackermann_robot"
TRAFFIC = ["passenger_car", "suv", "bus", "truck", "motorcycle", ROBOT]
CARS = ["passenger_car", "suv"]
CORDON = ["traffic_cone", "road_barrier", "bollard"]
OBSTACLES = ["traffic_cone", "road_barrier", "cement_rubble", "bollard", "construction_sign", *TRAFFIC]
BRIGHT = ["red", "green", "blue", "yellow", "orange", "purple", "pink", "cyan", "teal", "gold"]
MUTED = ["white", "black", "grey", "silver", "brown", "beige", "navy", "maroon"]
ALL_COLOURS = [*BRIGHT, *MUTED]

# --- Voices (each case names its own in `notes`) -----------------------------------------------------
TEACHER = "primary-school teacher planning a class field trip: 'the children', 'our coach', 'line up', 'the class', careful"
RACEFAN = "motorsport fan: 'the grid', 'pole', 'the pits', 'box box', 'lights out', 'chicane', 'donuts', 'flat out'"
JAPANESE = "Japanese speaker writing English: polite, drops articles and plurals, 'please', 'most near', 'front side of'"
ARCHITECT = "architect talking about the public realm: 'forecourt', 'frontage', 'approach', 'sightline', 'soft landscaping'"
NIGHTSHIFT = "bored night-shift tester typing tersely in lower case: 'rm', 'x5', 'fwd', 'whatever', 'k', no punctuation"
GRANDPARENT = "grandparent unfamiliar with computers: 'my grandson said to type here', 'motor car', 'thingy', 'dear', polite"
COURIER = "e-bike courier: 'my drop', 'the parcel', 'lock up', 'rider', 'muppet', 'pls', fast and informal"
GERMAN = "German engineer writing very formally: 'it is requested that', 'shall be', 'kindly', comma decimals, 'hours'"


# --- Helpers ---------------------------------------------------------------------------------------------
def backed_up(asset: str, lo: float, hi: float) -> list[list[Json]]:
    """Fair readings of backing a vehicle up: a shift backwards, or a reverse manoeuvre."""
    return [[moved(asset, lo, hi, "backward")], [event_played(asset, "reverse", 3.0)]]


def walks_across(lane: str | None = None, seconds: float = 3.0) -> list[list[Json]]:
    """Fair readings of a walker going over the road: a crossing or jaywalk behaviour, or a crossing manoeuvre."""
    return [
        [does(["cross_road", "jaywalk"], "pedestrian", crosses_lane=lane)],
        [event_played("pedestrian", "cross_road", seconds)],
    ]


def steps_out(lane: str | None = None) -> list[list[Json]]:
    """Fair readings of a walker stepping into the road: a jaywalk or crossing, or a crossing or stop mid-road."""
    return [
        [does(["jaywalk", "cross_road"], "pedestrian", crosses_lane=lane)],
        [event_played("pedestrian", "cross_road", 10.0)],
        [event_played("pedestrian", "stop_mid_road", 10.0)],
    ]


def in_lane_some(lane: str, category: str | list[str]) -> Json:
    """At least one of the added or changed assets of these categories stands in `lane` (a cordon across a road)."""
    return {"kind": "in_lane", "category": category, "lane": lane, "require_all": False}


# The ego (eastbound at 5 m/s from x = -60) halts short of the west crosswalk: its front never passes x = -13.
EGO_HALTS_BEFORE_WEST_CROSSWALK = stops_before(EGO, -13.0, -1.75, 20.0)


# --- Earlier turns several cases start from -------------------------------------------------------------
RUBBLE_AHEAD_25 = turn(
    "A lump of broken concrete has landed in the eastbound lane 25 m ahead of the ego.",
    add("cement_rubble", where=ahead_of(EGO, 25)),
)
THREE_AT_BUS_STOP = turn(
    "Put three people on the pavement at the bus stop.", add("pedestrian", 3, loc("on_sidewalk", "bus stop"))
)
FOUR_AT_FOUNTAIN = turn("Add four children by the fountain.", add("pedestrian", 4, loc("next_to", "fountain")))
CAR_AT_JTEKT = turn("Put a car at the JTEKT entrance.", add("passenger_car", where=loc("at", "JTEKT building entrance")))
TWO_BENCHES_LIBRARY = turn("Put two benches by the Library entrance.", add("bench", 2, loc("at", "Library entrance")))
BUS_IN_LOT_A = turn("Put a coach in lot A.", add("bus", where=loc("at", "parking lot A")))
CAR_AHEAD_30 = turn("Put a car 30 m ahead of the ego.", add("passenger_car", where=ahead_of(EGO, 30)))
ROBOT_LOT_B_GATE = turn(
    "Add a delivery robot at the lot B entrance.", add(ROBOT, where=loc("at", "parking lot B entrance"))
)
FOUR_CONES_LIBRARY = turn(
    "Four cones in a line in front of the Library entrance.",
    arrange("traffic_cone", "line", loc("in_front_of", "Library entrance"), count=4),
)
SIX_AT_FOUNTAIN = turn("Put six people at the fountain.", add("pedestrian", 6, loc("next_to", "fountain")))
BUS_WEST_EAST_GATE = turn(
    "Put a bus in the westbound lane by the east gate.", add("bus", where=loc("in_lane", "east gate", lane=WEST))
)
FOUR_BOLLARDS_GATE = turn("Place four bollards at the main gate.", add("bollard", 4, loc("at", "main gate")))
TWO_BUSES_LOT_A = turn("Add two buses at parking lot A.", add("bus", 2, loc("at", "parking lot A")))
THREE_CONES_LIBRARY = turn(
    "Put three cones by the Library entrance.", add("traffic_cone", 3, loc("at", "Library entrance"))
)
THREE_PEOPLE_BUS_STOP = turn(
    "Please put 3 person at bus stop.", add("pedestrian", 3, loc("on_sidewalk", "bus stop"))
)
MOTORBIKE_LIBRARY = turn("Add a motorbike at the Library entrance.", add("motorcycle", where=loc("at", "Library entrance")))
CAR_AT_UNION = turn("Add a car at the Student Union entrance.", add("passenger_car", where=loc("at", "Student Union entrance")))
TRUCK_IN_LOT_A = turn("Add a truck in lot A.", add("truck", where=loc("at", "parking lot A")))
PERSON_ENGINEERING = turn(
    "Put a person at the Engineering Hall entrance.", add("pedestrian", where=loc("at", "Engineering Hall entrance"))
)
CAR_AHEAD_20 = turn("Add a car in the eastbound lane 20 m ahead of the ego.", add("passenger_car", where=ahead_of(EGO, 20)))
BIKE_LOT_B_GATE = turn("Add a bicycle at the lot B entrance.", add("bicycle", where=loc("at", "parking lot B entrance")))
BENCH_TO_FOUNTAIN = turn("Move the bench next to the fountain.", place(BENCH, loc("next_to", "fountain")))
CAR_AT_LIBRARY = turn("Add a car at the Library entrance.", add("passenger_car", where=loc("at", "Library entrance")))
BIKE_LIBRARY = turn("Add a bicycle at the Library entrance.", add("bicycle", where=loc("at", "Library entrance")))
COACH_AT_UNION = turn("Add a coach at the Student Union entrance.", add("bus", where=loc("at", "Student Union entrance")))
WALKER_WEST_XING = turn(
    "Add a child on the pavement by the west crosswalk.", add("pedestrian", where=loc("on_sidewalk", "west crosswalk"))
)
CAR_AHEAD_SLOW = turn(
    "Please add one car 30 meter ahead of ego, driving east 3 m/s.",
    add("passenger_car", where=ahead_of(EGO, 30), behaviour={"kind": "drive_lane", "speed": 3.0, "lane": EAST}),
)
PERSON_LIBRARY = turn("Add a pedestrian at the Library entrance.", add("pedestrian", where=loc("at", "Library entrance")))
LORRY_CRAWLING = turn(
    "A truck in the eastbound lane 40 m ahead of the ego, crawling along at 2 m/s.",
    add("truck", where=ahead_of(EGO, 40), behaviour={"kind": "drive_lane", "speed": 2.0, "lane": EAST}),
)
COACH_WEST_JTEKT = turn(
    "Put a coach in the westbound lane by the JTEKT entrance.",
    add("bus", where=loc("in_lane", "JTEKT building entrance", lane=WEST)),
)
MOTORBIKE_AHEAD_20 = turn(
    "Add a motorbike in the eastbound lane 20 m ahead of the ego.", add("motorcycle", where=ahead_of(EGO, 20))
)
WALKER_SOUTH_30 = turn(
    "Someone on the south pavement 30 m ahead of the ego.", add("pedestrian", where=ahead_of(EGO, 30, side="right"))
)
TWO_AT_JTEKT = turn("Add two pedestrians at the JTEKT entrance.", add("pedestrian", 2, loc("at", "JTEKT building entrance")))
CHILD_AT_JTEKT = turn("Put a child by the JTEKT entrance.", add("pedestrian", where=loc("at", "JTEKT building entrance")))
CONES_LOT_A_GATE = turn(
    "Put five cones in a line at the lot A entrance.",
    arrange("traffic_cone", "line", loc("at", "parking lot A entrance"), count=5),
)
THREE_CONES_LINE_LIBRARY = turn(
    "Put three cones in a line in front of the Library entrance.",
    arrange("traffic_cone", "line", loc("in_front_of", "Library entrance"), count=3),
)
EVENING_21 = turn("Set the time to nine in the evening.", clock("21:00"))
THICK_FOG = turn("Thick fog, please.", weather("fog", 0.9))
COACH_LOT_A = turn("Add a coach at parking lot A.", add("bus", where=loc("at", "parking lot A")))
HEAVY_SNOW = turn("Please make heavy snow.", weather("snow", 0.9))
HEAVY_RAIN = turn("Heavy rain, please.", weather("rain", 0.9))
BENCH_ORANGE = turn("Paint the bench orange.", paint([BENCH], colour="orange"))
CAR1_RED = turn("Paint the car at the west end of the row in lot B red.", paint([CAR1], colour="red"))


# --- Search: questions change nothing; the answer names what was asked for ---------------------------
SEARCH_CASES: list[Json] = [
    # direct
    ask("direct", "bench_count", TEACHER, "How many benches are there on the campus at the moment?", ["1"],
        [find(category="bench")]),
    ask("direct", "main_street_limit_kmh", RACEFAN, "What's the top speed allowed on Main Street, in km/h?", ["29"],
        [lanes(road="Main Street")]),
    ask("direct", "tree_most_near_union", JAPANESE, "Which tree is most near to Student Union entrance, please?",
        [TREE_BUS], [find(category="tree", nearest_to="Student Union entrance")]),
    ask("direct", "engineering_to_jtekt", ARCHITECT,
        "What is the distance between the Engineering Hall entrance and the JTEKT entrance?", ["77.5"],
        [measure("Engineering Hall entrance", "JTEKT building entrance")]),
    ask("direct", "list_signals", NIGHTSHIFT, "list traffic lights", [LIGHT_SW, LIGHT_NE],
        [find(category="traffic_light")]),
    ask("direct", "clock_in_picture", GRANDPARENT, "What time of day is it in the picture, dear?", ["12:00"],
        [environment()]),
    ask("direct", "hydrant_where", COURIER, "where's the fire hydrant at?", [HYDRANT],
        [find(category="fire_hydrant")]),
    ask("direct", "ego_speed_and_lane", GERMAN,
        "Kindly report the present speed and the lane of the ego vehicle.", ["5", EAST], [properties(asset=EGO)]),
    ask("direct", "heaviest_vehicle", TEACHER, "Which of the vehicles here is the heaviest?", [SUV],
        [find(category="vehicles", most="heaviest")]),
    ask("direct", "lane_nearest_jtekt", RACEFAN, "Which lane runs closest to the JTEKT entrance?", [WEST],
        [lanes(near="JTEKT building entrance")]),
    ask("direct", "names_of_gates", JAPANESE, "Please tell me names of all gates.", ["main gate", "east gate"],
        [landmarks(query="gate")]),
    impossible("search", "direct", "post_office_distance", COURIER, "How far is it from the ego to the post office?",
               [measure("post office")]),
    # indirect
    ask("indirect", "crossings_for_walk", TEACHER,
        "I want the children to cross the road safely on our walk. Which crossings are there?",
        ["west crosswalk", "north crosswalk"], [landmarks(query="crosswalk")]),
    ask("indirect", "pole_to_junction_and_limit", RACEFAN,
        "The ego's on pole. How far back from the crossroads is it, and what's the speed limit on that road?",
        ["60.0", "8"], [measure("main intersection"), lanes(road="Main Street")]),
    ask("indirect", "sit_after_library", JAPANESE, "I am tired after library. Where can I sit most near to Library?",
        [BENCH], [find(category="bench", nearest_to="Library entrance")]),
    ask("indirect", "lamp_rhythm_north", ARCHITECT,
        "I'm checking the rhythm of the lighting: how far apart are the two westernmost lamp posts on the north side "
        "of Main Street?", ["30.0"], [measure("street_light_1", "street_light_3")]),
    ask("indirect", "anything_in_road", NIGHTSHIFT, "anything sitting in the lanes besides ego rn", ["cement_rubble_1"],
        [find(on_lane=True)], setup=[RUBBLE_AHEAD_25]),
    ask("indirect", "night_or_day", GRANDPARENT,
        "My eyes aren't what they were. Is it meant to be night-time in there, or daytime?", ["12:00"],
        [environment()]),
    ask("indirect", "parcel_bus_stop_to_union", COURIER,
        "got a parcel for the Student Union. how far's that from the bus stop where I lock up?", ["85.6"],
        [measure("bus stop", "Student Union entrance")]),
    ask("indirect", "visitor_car_park", GERMAN,
        "For a visitor from Stuttgart it must be determined which car park lies closer to the Engineering Hall "
        "entrance.", ["parking lot A"], [landmarks(query="parking lot", nearest_to="Engineering Hall entrance")]),
    ask("indirect", "cars_for_lifts", TEACHER,
        "Parents will be giving lifts home. How many cars are sitting in lot B right now?", ["3"],
        [find(category="cars", near="parking lot B", within=1)]),
    ask("indirect", "gate_to_gate_straight", RACEFAN,
        "Flat out from the main gate to the east gate: how long is that straight?", ["200.0"],
        [measure("main gate", "east gate")]),
    ask("indirect", "ego_direction", JAPANESE, "I want to know ego car is going which lane now.", [EAST],
        [properties(asset=EGO)]),
    impossible("search", "indirect", "tram_stop_distance", GERMAN,
               "For the timetable it must be known how far the tram stop lies from the Library entrance.",
               [measure("tram stop", "Library entrance")]),
    # vague
    ask("vague", "around_library", TEACHER, "What is there around the Library for the children to look at?",
        [], [find(near="Library entrance", within=20)], any_of=[TREE_BUS, BENCH, BIN, LAMP_BY_LIBRARY]),
    ask("vague", "track_conditions", RACEFAN, "Track conditions?", ["clear"], [environment()]),
    ask("vague", "how_many_person", JAPANESE, "How many person is there now?", ["3"],
        [find(category="pedestrian")], setup=[planned(THREE_AT_BUS_STOP)]),
    ask("vague", "furniture_by_bus_stop", ARCHITECT, "What street furniture is there at the bus stop?", [BENCH, BIN],
        [find(near="bus stop", within=8)]),
    ask("vague", "where_ego", NIGHTSHIFT, "ego?", ["-60.0"], [properties(asset=EGO)]),
    ask("vague", "ego_pos_and_weather", NIGHTSHIFT, "ego pos + weather", ["-60.0", "clear"],
        [properties(asset=EGO), environment()]),
    ask("vague", "the_big_motor_car", GRANDPARENT, "Which of the motor cars is the big one?", [SUV],
        [find(category="cars", most="biggest")]),
    ask("vague", "whats_nearest_ego", COURIER, "whats the closest thing to the ego car", ["street_light_2"],
        [find(nearest_to=EGO)]),
    ask("vague", "lighting_situation", GERMAN, "The lighting situation, please.", ["street lights", "exposure"],
        [environment()]),
    impossible("search", "vague", "toilets_for_children", TEACHER, "Where are the toilets for the children?",
               [find(category="toilet")]),
    ask("vague", "how_many_lanes", RACEFAN, "How many lanes we got?", ["4"], [lanes()]),
    ask("vague", "signal_near_ego", JAPANESE, "Signal near ego, which one?", [LIGHT_SW],
        [find(category="traffic_light", nearest_to=EGO)]),
    ask("vague", "how_much_green", ARCHITECT, "How much soft landscaping is there? Trees, I mean.", ["4"],
        [find(category="tree")]),
    # erroneous
    ask("erroneous", "benchs_near_libary", TEACHER, "how many benchs are near the libary", [BENCH],
        [find(category="bench", near="Library entrance", within=20)]),
    ask("erroneous", "wether_on_track", RACEFAN, "whats the wether like on track", ["clear"], [environment()]),
    ask("erroneous", "distanse_to_fontain", JAPANESE, "Please tell distanse from ego to fontain.", ["141.3"],
        [measure("fountain")]),
    ask("erroneous", "north_east_trafic_light", ARCHITECT, "wheres the trafic light on the north-east corner",
        [LIGHT_NE], [find(category="traffic_light")]),
    ask("erroneous", "hw_mny_streetlights", NIGHTSHIFT, "hw mny streetlights", ["12"], [find(category="street_light")]),
    ask("erroneous", "wich_tree_fountian", GRANDPARENT, "wich tree is closest to the fountian", [TREE_FOUNT],
        [find(category="tree", nearest_to="fountain")]),
    ask("erroneous", "distnce_and_bin", COURIER,
        "distnce from lot b entrnce to the east gate? and wheres the nearest bin to the entrnce", ["53.1", BIN],
        [measure("parking lot B entrance", "east gate"), find(category="trash_bin", nearest_to="parking lot B entrance")]),
    ask("erroneous", "suv_colour", GERMAN, "Please state teh colour of the SUV.", ["default"],
        [properties(asset=SUV)]),
    ask("erroneous", "pedestrains_now", TEACHER, "how many pedestrains are their now", ["4"],
        [find(category="pedestrian")], setup=[planned(FOUR_AT_FOUNTAIN)]),
    ask("erroneous", "widest_vehcile", RACEFAN, "which vehcile is the widest", [SUV],
        [find(category="vehicles", most="widest")]),
    ask("erroneous", "lane_widht_campus", JAPANESE, "What is lane widht of Campus Drive?", ["3.5"],
        [lanes(road="Campus Drive")]),
    impossible("search", "erroneous", "dist_to_helipad", NIGHTSHIFT, "dist ego to helipad", [measure("helipad")]),
]


# --- Addition -------------------------------------------------------------------------------------------
ADDITION_CASES: list[Json] = [
    # direct
    case("addition", "direct", "coach_at_union", TEACHER, "Add a coach at the Student Union entrance.",
         [delta("bus", 1, 1), near("Student Union entrance", 12, "bus"), only("bus")],
         [add("bus", where=loc("at", "Student Union entrance"))]),
    case("addition", "direct", "safety_car_40_ahead", RACEFAN,
         "Put a car in the eastbound lane 40 metres ahead of the ego, doing 4 m/s. That's the safety car.",
         [delta("passenger_car", 1, 1), in_lane(EAST, "passenger_car"),
          near(None, 6, "passenger_car", point=(-20.0, -1.75)),
          does("drive_lane", "passenger_car", lane=EAST, speed_min=3.5, speed_max=4.5), only("passenger_car")],
         [add("passenger_car", where=ahead_of(EGO, 40), behaviour={"kind": "drive_lane", "speed": 4.0, "lane": EAST})]),
    case("addition", "direct", "bicycle_front_of_library", JAPANESE, "Please add one bicycle at front of Library entrance.",
         [delta("bicycle", 1, 1), near("Library entrance", 8, "bicycle"), only("bicycle")],
         [add("bicycle", where=loc("in_front_of", "Library entrance"))]),
    case("addition", "direct", "two_trees_jtekt_forecourt", ARCHITECT, "Add two trees on the JTEKT Building's forecourt.",
         [delta("tree", 2, 2), near("JTEKT building entrance", 12, "tree", scope="added", every=True), only("tree")],
         [add("tree", 2, loc("at", "JTEKT building entrance"))]),
    case("addition", "direct", "cone_at_coords", NIGHTSHIFT, "add cone at 1.75,-20",
         [delta("traffic_cone", 1, 1), near(None, 1.0, "traffic_cone", point=(1.75, -20.0)), only("traffic_cone")],
         [add("traffic_cone", where=xy(1.75, -20))]),
    impossible("addition", "direct", "post_box_bus_stop", GRANDPARENT,
               "Could you put a post box by the bus stop, please?", [add("post_box", where=loc("at", "bus stop"))]),
    case("addition", "direct", "robot_lot_b_entrance", COURIER, "add a delivery robot at the lot B entrance",
         [delta(ROBOT, 1, 1), near("parking lot B entrance", 8, ROBOT), only(ROBOT)],
         [add(ROBOT, where=loc("at", "parking lot B entrance"))]),
    case("addition", "direct", "three_on_footway_north_crosswalk", GERMAN,
         "It is requested that three pedestrians be placed on the footway at the north crosswalk.",
         [delta("pedestrian", 3, 3), near("north crosswalk", 10, "pedestrian", scope="added", every=True),
          on(["sidewalk"], "pedestrian"), only("pedestrian")],
         [add("pedestrian", 3, loc("on_sidewalk", "north crosswalk"))]),
    case("addition", "direct", "bench_and_bin_union", TEACHER, "Add a bench and a bin outside the Student Union.",
         [delta("bench", 1, 1), delta("trash_bin", 1, 1), near("Student Union entrance", 10, "bench"),
          near("Student Union entrance", 10, "trash_bin"), only("bench", "trash_bin")],
         [add("bench", where=loc("at", "Student Union entrance")), add("trash_bin", where=loc("at", "Student Union entrance"))]),
    case("addition", "direct", "motorbike_westbound_6", RACEFAN, "Stick a motorbike in the westbound lane doing 6 m/s.",
         [delta("motorcycle", 1, 1), does("drive_lane", "motorcycle", lane=WEST, speed_min=5.5, speed_max=6.5),
          only("motorcycle")],
         [add("motorcycle", behaviour={"kind": "drive_lane", "speed": 6.0, "lane": WEST})]),
    case("addition", "direct", "suv_fifteen_behind_ego", JAPANESE, "Add one SUV 15 meter behind of ego car in same lane.",
         [delta("suv", 1, 1), in_lane(EAST, "suv"), near(None, 4, "suv", point=(-75.0, -1.75)), only("suv")],
         [add("suv", where=ahead_of(EGO, -15))]),
    # indirect
    case("addition", "indirect", "helper_at_west_crosswalk", TEACHER,
         "We need a grown-up to see the children across at the west crosswalk, standing on the pavement there.",
         [delta("pedestrian", 1, 1), near("west crosswalk", 8, "pedestrian"), on(["sidewalk"], "pedestrian"),
          only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "west crosswalk"))]),
    case("addition", "indirect", "marshals_stop_sign_and_hydrant", RACEFAN,
         "Every corner needs a marshal: stick one person by the stop sign and another by the fire hydrant.",
         [delta("pedestrian", 2, 2), near(STOP, 4, "pedestrian"), near(HYDRANT, 4, "pedestrian"), only("pedestrian")],
         [add("pedestrian", where=loc("next_to", STOP)), add("pedestrian", where=loc("next_to", HYDRANT))]),
    case("addition", "indirect", "shade_for_bench", JAPANESE,
         "Bench near bus stop is very hot in the sun. I want some shade for it.",
         [delta("tree", 1, 2), near(BENCH, 5, "tree", scope="added"), only("tree")],
         [add("tree", where=loc("next_to", BENCH))]),
    case("addition", "indirect", "somewhere_to_sit_engineering", ARCHITECT,
         "The approach to the Engineering Hall feels bare: people have nowhere to sit.",
         [delta("bench", 1, 4), near("Engineering Hall entrance", 12, "bench", scope="added", every=True), only("bench")],
         [add("bench", where=loc("at", "Engineering Hall entrance"))]),
    case("addition", "indirect", "block_ego_lane_30", NIGHTSHIFT, "need something blocking ego lane about 30m out",
         [delta(OBSTACLES, 1, None), in_lane(EAST, OBSTACLES, scope="added"),
          near(None, 8, OBSTACLES, scope="added", point=(-30.0, -1.75)), only(*OBSTACLES)],
         [add("cement_rubble", where=ahead_of(EGO, 30))]),
    case("addition", "indirect", "grandsons_bicycle", GRANDPARENT,
         "My grandson cycles to the library. Could you put his bicycle by the Library door for me?",
         [delta("bicycle", 1, 1), near("Library entrance", 8, "bicycle"), only("bicycle")],
         [add("bicycle", where=loc("at", "Library entrance"))]),
    case("addition", "indirect", "oncoming_rider", COURIER,
         "there's always some other rider coming the other way down Main Street. give me a motorbike heading west",
         [delta("motorcycle", 1, 1), does("drive_lane", "motorcycle", lane=WEST), only("motorcycle")],
         [add("motorcycle", behaviour={"kind": "drive_lane", "lane": WEST})]),
    case("addition", "indirect", "roadworks_warning_main_gate", GERMAN,
         "In anticipation of maintenance works, a corresponding warning sign shall be erected at the main gate.",
         [delta("construction_sign", 1, 1), near("main gate", 10, "construction_sign"), only("construction_sign")],
         [add("construction_sign", where=loc("at", "main gate"))]),
    case("addition", "indirect", "coach_drives_in", TEACHER,
         "Our coach comes in through the main gate and along Main Street. Can you show it driving in?",
         [delta("bus", 1, 1), does("drive_lane", "bus", lane=EAST), near("main gate", 30, "bus"), only("bus")],
         [add("bus", where=loc("at", "main gate"), behaviour={"kind": "drive_lane", "speed": 5.0, "lane": EAST})]),
    case("addition", "indirect", "bike_and_bin_library_drop", COURIER,
         "my drop's at the Library. stick a bike by the door and a bin next to it for all the packaging",
         [delta("bicycle", 1, 1), delta("trash_bin", 1, 1), near("Library entrance", 8, "bicycle"),
          near("bicycle_1", 4, "trash_bin", scope="added"), only("bicycle", "trash_bin")],
         [add("bicycle", where=loc("at", "Library entrance")), add("trash_bin", where=loc("next_to", "bicycle_1"))]),
    impossible("addition", "indirect", "grandstand_east_gate", RACEFAN,
               "Build me a grandstand by the finish line at the east gate.",
               [add("grandstand", where=loc("at", "east gate"))]),
    case("addition", "indirect", "one_more_same", JAPANESE, "One more same one, next to it please.",
         [delta("passenger_car", 1, 1), near("passenger_car_3", 6, "passenger_car", scope="added"), only("passenger_car")],
         [add("passenger_car", where=loc("next_to", "passenger_car_3"))], setup=[planned(CAR_AT_JTEKT)]),
    # vague
    case("addition", "vague", "some_children_fountain", TEACHER, "Some children by the fountain, please.",
         [delta("pedestrian", 2, 12), near("fountain", 12, "pedestrian", scope="added", every=True), only("pedestrian")],
         [add("pedestrian", 4, loc("next_to", "fountain"))]),
    case("addition", "vague", "traffic_to_race", RACEFAN, "Give me a bit of traffic to race against.",
         [delta(TRAFFIC, 1, None), does(["drive_lane", "follow_path", "circle"], TRAFFIC, scope="added"), only(*TRAFFIC)],
         [add("passenger_car", 2, ahead_of(EGO, 30), behaviour={"kind": "drive_lane", "speed": 6.0, "lane": EAST})]),
    case("addition", "vague", "something_for_rubbish", JAPANESE, "Something for rubbish near the bench, please.",
         [delta("trash_bin", 1, 1), near(BENCH, 5, "trash_bin", scope="added"), only("trash_bin")],
         [add("trash_bin", where=loc("next_to", BENCH))]),
    case("addition", "vague", "soften_union_frontage", ARCHITECT, "Soften the Student Union frontage a little.",
         [delta("tree", 1, None), near("Student Union entrance", 15, "tree", scope="added", every=True), only("tree")],
         [add("tree", where=loc("at", "Student Union entrance"))]),
    case("addition", "vague", "ped_near_ego", NIGHTSHIFT, "ped. somewhere near ego",
         [delta("pedestrian", 1, 2), near(EGO, 20, "pedestrian", scope="added", every=True), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", EGO))]),
    case("addition", "vague", "few_more_motor_cars", GRANDPARENT,
         "Could we have a few more motor cars in the car park by the Union?",
         [delta(CARS, 2, 8), near("parking lot B", 1, CARS, scope="added", every=True), only(*CARS)],
         [add("passenger_car", 3, loc("at", "parking lot B"))]),
    case("addition", "vague", "something_to_lock_bike_to", COURIER,
         "need something to lock my bike to outside the JTEKT",
         [delta(["bollard", "parking_sign", "street_light", "bench", "pedestrian_sign"], 1, None),
          near("JTEKT building entrance", 12, ["bollard", "parking_sign", "street_light", "bench", "pedestrian_sign"],
               scope="added", every=True),
          only("bollard", "parking_sign", "street_light", "bench", "pedestrian_sign")],
         [add("bollard", where=loc("at", "JTEKT building entrance"))]),
    case("addition", "vague", "signage_west_crosswalk", GERMAN,
         "Adequate signage for pedestrians at the west crosswalk is to be provided.",
         [delta("pedestrian_sign", 1, 4), near("west crosswalk", 10, "pedestrian_sign", scope="added", every=True),
          only("pedestrian_sign")],
         [add("pedestrian_sign", where=loc("at", "west crosswalk"))]),
    case("addition", "vague", "couple_more_of_those", TEACHER, "Lovely. A couple more of those, please.",
         [delta("bench", 2, 3), near("Library entrance", 15, "bench", scope="added", every=True), only("bench")],
         [add("bench", 2, loc("at", "Library entrance"))], setup=[planned(TWO_BENCHES_LIBRARY)]),
    impossible("addition", "vague", "cars_three_hundred", RACEFAN, "Fill the place with cars, like 300 of them.",
               [add("passenger_car", 300)]),
    case("addition", "vague", "little_bit_busy", JAPANESE, "Scene is too empty. Please make it little bit busy with people.",
         [delta("pedestrian", 1, None), only("pedestrian")],
         [add("pedestrian", 4, loc("on_sidewalk", "bus stop"))]),
    # erroneous
    case("addition", "erroneous", "bech_by_fountian", TEACHER, "add a bech by the fountian",
         [delta("bench", 1, 1), near("fountain", 8, "bench", scope="added"), only("bench")],
         [add("bench", where=loc("next_to", "fountain"))]),
    case("addition", "erroneous", "suv_behnd_ego", RACEFAN, "put an suv 20m behnd the ego in the same lane",
         [delta("suv", 1, 1), in_lane(EAST, "suv"), near(None, 4, "suv", point=(-80.0, -1.75)), only("suv")],
         [add("suv", where=ahead_of(EGO, -20))]),
    case("addition", "erroneous", "three_cone_ten_meter", JAPANESE, "Please put three cone in front of ego, 10 meter.",
         [delta("traffic_cone", 3, 3), in_lane(EAST, "traffic_cone"),
          near(None, 8, "traffic_cone", scope="added", point=(-50.0, -1.75), every=True), only("traffic_cone")],
         [add("traffic_cone", 3, ahead_of(EGO, 10))]),
    case("addition", "erroneous", "tre_and_bench_engineering", ARCHITECT,
         "plant a tre next to the Engineerng Hall entrence and put a bench beside it",
         [delta("tree", 1, 1), delta("bench", 1, 1), near("Engineering Hall entrance", 12, "tree"),
          near("tree_5", 5, "bench", scope="added"), only("tree", "bench")],
         [add("tree", where=loc("next_to", "Engineering Hall entrance")), add("bench", where=loc("next_to", "tree_5"))]),
    case("addition", "erroneous", "truk_lot_a", NIGHTSHIFT, "truk in lot a",
         [delta("truck", 1, 1), near("parking lot A", 1, "truck"), only("truck")],
         [add("truck", where=loc("at", "parking lot A"))]),
    case("addition", "erroneous", "pedestiran_zebra", GRANDPARENT, "put a pedestiran on the pavment by the zebra crosing",
         [delta("pedestrian", 1, 1), near("west crosswalk", 8, "pedestrian"), on(["sidewalk"], "pedestrian"),
          only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "west crosswalk"))]),
    case("addition", "erroneous", "scooter_outsde_union", COURIER, "add a scooter outsde the union",
         [delta("motorcycle", 1, 1), near("Student Union entrance", 12, "motorcycle"), only("motorcycle")],
         [add("motorcycle", where=loc("at", "Student Union entrance"))]),
    case("addition", "erroneous", "barier_eastbund_35", GERMAN,
         "Kindly place one barier in the eastbund lane 35 m ahead of the ego vehicel.",
         [delta("road_barrier", 1, 1), in_lane(EAST, "road_barrier"),
          near(None, 5, "road_barrier", point=(-25.0, -1.75)), only("road_barrier")],
         [add("road_barrier", where=ahead_of(EGO, 35))]),
    case("addition", "erroneous", "anothr_coach_next_too", TEACHER, "and anothr one next too it",
         [delta("bus", 1, 1), near("bus_1", 8, "bus", scope="added"), only("bus")],
         [add("bus", where=loc("next_to", "bus_1"))], setup=[planned(BUS_IN_LOT_A)]),
    impossible("addition", "erroneous", "bike_rack_library", COURIER, "ad a bike rack by the library",
               [add("bike_rack", where=loc("at", "Library entrance"))]),
    case("addition", "erroneous", "two_persons_jtekt", JAPANESE, "Put 2 persons at JTEKT entrence, please.",
         [delta("pedestrian", 2, 2), near("JTEKT building entrance", 10, "pedestrian", scope="added", every=True),
          only("pedestrian")],
         [add("pedestrian", 2, loc("at", "JTEKT building entrance"))]),
]


# --- Removal --------------------------------------------------------------------------------------------
REMOVAL_CASES: list[Json] = [
    # direct
    case("removal", "direct", "rubbish_bin", TEACHER, "Please remove the rubbish bin.",
         [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "direct", "stop_sign_out", RACEFAN, "Take the stop sign out.",
         [gone(STOP), only(assets=[STOP])], [remove(STOP)]),
    case("removal", "direct", "tree_near_lot_a", JAPANESE, "Please remove tree which is near parking lot A.",
         [gone(TREE_LOT_A), kept(TREE_BUS, TREE_FOUNT, TREE_SE), only(assets=[TREE_LOT_A])], [remove(TREE_LOT_A)]),
    case("removal", "direct", "hydrant_north_pavement", ARCHITECT, "Remove the fire hydrant from the north pavement.",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "direct", "rm_car_2", NIGHTSHIFT, "rm passenger_car_2",
         [gone(CAR2), kept(CAR1, SUV), only(assets=[CAR2])], [remove(CAR2)]),
    case("removal", "direct", "bench_by_bus_stop", GRANDPARENT, "Please take away the bench by the bus stop.",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "direct", "both_traffic_lights", COURIER, "remove both traffic lights",
         [gone(LIGHT_SW, LIGHT_NE), only("traffic_light")], [remove(category="traffic_light")]),
    case("removal", "direct", "lamp_nearest_library", GERMAN,
         "The street light nearest to the Library entrance shall be removed.",
         [gone(LAMP_BY_LIBRARY), delta("street_light", -1, -1), only(assets=[LAMP_BY_LIBRARY])],
         [remove(category="street_light", near="Library entrance", count=1)]),
    impossible("removal", "direct", "library_building", TEACHER, "Remove the Library building.", [remove("library")]),
    case("removal", "direct", "get_rid_of_that_car", RACEFAN, "Now get rid of that car.",
         [gone("passenger_car_3"), delta("passenger_car", -1, -1), kept(CAR1, CAR2), only("passenger_car")],
         [remove("passenger_car_3")], setup=[planned(CAR_AHEAD_30)]),
    case("removal", "direct", "bench_and_trash_bin", JAPANESE, "Please remove bench and also trash bin, both.",
         [gone(BENCH, BIN), only(assets=[BENCH, BIN])], [remove(BENCH), remove(BIN)]),
    # indirect
    case("removal", "indirect", "trip_hazards", TEACHER,
         "The children could trip over the fire hydrant and that stop sign on our walk. Can they both go?",
         [gone(HYDRANT, STOP), only(assets=[HYDRANT, STOP])], [remove(HYDRANT), remove(STOP)]),
    case("removal", "indirect", "paddock_except_suv", RACEFAN,
         "Lot B's our paddock now: clear out every car in it except the SUV.",
         [gone(CAR1, CAR2), kept(SUV), only(assets=[CAR1, CAR2])], [remove(CAR1, CAR2)]),
    case("removal", "indirect", "tree_blocks_camera", JAPANESE,
         "Tree between bus stop and Library is blocking view of camera. Please delete it.",
         [gone(TREE_BUS), kept(TREE_FOUNT, TREE_SE, TREE_LOT_A), only(assets=[TREE_BUS])], [remove(TREE_BUS)]),
    case("removal", "indirect", "declutter_bus_stop", ARCHITECT, "Declutter the bus stop: lose the bin, but keep the bench.",
         [gone(BIN), kept(BENCH), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "indirect", "stop_sign_fails_detector", NIGHTSHIFT, "stop sign keeps failing the detector test. kill it",
         [gone(STOP), only(assets=[STOP])], [remove(STOP)]),
    case("removal", "indirect", "confusing_light_ne", GRANDPARENT,
         "Those traffic lights at the crossroads confuse me. Could you take away the one on the north-east corner?",
         [gone(LIGHT_NE), kept(LIGHT_SW), only(assets=[LIGHT_NE])], [remove(LIGHT_NE)]),
    case("removal", "indirect", "robot_in_drop_spot", COURIER, "that robot's parked right on my drop-off spot, get rid of it",
         [gone("ackermann_robot_1"), delta(ROBOT, -1, -1), only(ROBOT)], [remove("ackermann_robot_1")],
         setup=[ROBOT_LOT_B_GATE]),
    case("removal", "indirect", "cones_no_longer_required", GERMAN,
         "The cones are no longer required and shall be removed in their entirety.",
         [count("traffic_cone", 0, 0), delta("traffic_cone", -4, -4), only("traffic_cone")],
         [remove(category="traffic_cone")], setup=[planned(FOUR_CONES_LIBRARY)]),
    case("removal", "indirect", "half_the_grown_ups", TEACHER,
         "That's too many grown-ups in the photo. Take half of them away.",
         [delta("pedestrian", -3, -3), only("pedestrian")], [remove(category="pedestrian", count=3)],
         setup=[planned(SIX_AT_FOUNTAIN)]),
    impossible("removal", "indirect", "crossroads_straight_run", RACEFAN,
               "Get rid of the crossroads, I want one long straight run.", [remove("main intersection")]),
    case("removal", "indirect", "car_east_end_not_needed", JAPANESE,
         "Car at the east end of the row in parking B, I don't need it.",
         [gone(CAR2), kept(CAR1, SUV), only(assets=[CAR2])], [remove(CAR2)]),
    # vague
    case("removal", "vague", "rubbish_by_bus_stop", TEACHER, "Get rid of the rubbish thing by the bus stop.",
         [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "vague", "thin_trees_keep_fountain", RACEFAN,
         "Too many trees about. Thin them out, just keep the one by the fountain.",
         [gone(TREE_BUS, TREE_LOT_A), kept(TREE_FOUNT), only(assets=[TREE_BUS, TREE_LOT_A, TREE_SE])],
         [remove(TREE_BUS, TREE_LOT_A, TREE_SE)]),
    case("removal", "vague", "do_not_need_signs", JAPANESE, "I do not need the signs. Please remove.",
         [gone(STOP), only(assets=[STOP, LIGHT_SW, LIGHT_NE])], [remove(STOP)]),
    case("removal", "vague", "clutter_north_pavement", ARCHITECT,
         "Lose the clutter on the north pavement just east of the crossroads.",
         [gone(HYDRANT), only(assets=[HYDRANT, "street_light_7", LIGHT_NE])], [remove(HYDRANT)]),
    case("removal", "vague", "nah_remove", NIGHTSHIFT, "nah. remove",
         [gone("bus_1"), delta("bus", -1, -1), only("bus")], [remove("bus_1")], setup=[planned(BUS_WEST_EAST_GATE)]),
    case("removal", "vague", "fire_brigade_thingy", GRANDPARENT,
         "Could you take away that thingy on the pavement near the crossroads, the one the fire brigade uses?",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "vague", "one_less_car", COURIER, "one less car in lot B pls",
         [delta(CARS, -1, -1), only(assets=PARKED)], [remove(CAR2)]),
    case("removal", "vague", "superfluous_bollards", GERMAN, "These are superfluous. Remove them.",
         [count("bollard", 0, 0), delta("bollard", -4, -4), only("bollard")], [remove(category="bollard")],
         setup=[planned(FOUR_BOLLARDS_GATE)]),
    case("removal", "vague", "only_one_coach_booked", TEACHER,
         "We've only got the one coach booked, so one of those can go.",
         [delta("bus", -1, -1), only("bus")], [remove("bus_2")], setup=[TWO_BUSES_LOT_A]),
    impossible("removal", "vague", "flatten_buildings", RACEFAN,
               "Flatten the buildings, I want the whole place as run-off.", [remove("JTEKT Building")]),
    case("removal", "vague", "lights_only_north_keep", JAPANESE,
         "Street lights are too many. Please make less, keep only ones on north side.",
         [gone(*SOUTH_LAMPS), kept(*NORTH_LAMPS), only(assets=SOUTH_LAMPS)], [remove(*SOUTH_LAMPS)]),
    # erroneous
    case("removal", "erroneous", "remve_bench", TEACHER, "remve the bench pls",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "erroneous", "delet_suv_lot_b", RACEFAN, "delet the suv from lot b",
         [gone(SUV), kept(CAR1, CAR2), only(assets=[SUV])], [remove(SUV)]),
    case("removal", "erroneous", "remvoe_all_tree", JAPANESE, "Please remvoe all tree.",
         [count("tree", 0, 0), only("tree")], [remove(category="tree")]),
    case("removal", "erroneous", "lampost_enginering", ARCHITECT, "remov the lampost in front of the Enginering Hall",
         [gone(LAMP_BY_ENGINEERING), delta("street_light", -1, -1), only(assets=[LAMP_BY_ENGINEERING])],
         [remove(LAMP_BY_ENGINEERING)]),
    case("removal", "erroneous", "rm_lite_and_stop", NIGHTSHIFT, "rm trafic lite sw corner + the stop sgin",
         [gone(LIGHT_SW, STOP), kept(LIGHT_NE), only(assets=[LIGHT_SW, STOP])], [remove(LIGHT_SW), remove(STOP)]),
    case("removal", "erroneous", "car_west_end_row", GRANDPARENT,
         "take awy the motor car at the west end of the row in the car park",
         [gone(CAR1), kept(SUV, CAR2), only(assets=[CAR1])], [remove(CAR1)]),
    case("removal", "erroneous", "rmove_rubble", COURIER, "rmove the rubble in the road pls",
         [gone("cement_rubble_1"), delta("cement_rubble", -1, -1), only("cement_rubble")], [remove("cement_rubble_1")],
         setup=[RUBBLE_AHEAD_25]),
    case("removal", "erroneous", "stopsign_west_crosing", GERMAN, "Removal of the stopsign at the west crosing is requested.",
         [gone(STOP), only(assets=[STOP])], [remove(STOP)]),
    case("removal", "erroneous", "tkae_one_cone", TEACHER, "tkae one of them away",
         [delta("traffic_cone", -1, -1), only("traffic_cone")], [remove("traffic_cone_3")],
         setup=[planned(THREE_CONES_LIBRARY)]),
    impossible("removal", "erroneous", "remvoe_ego", RACEFAN, "remvoe the ego car completly", [remove(EGO)]),
    case("removal", "erroneous", "remove_all_person", JAPANESE, "Now please remove all person.",
         [count("pedestrian", 0, 0), delta("pedestrian", -3, -3), only("pedestrian")],
         [remove(category="pedestrian")], setup=[planned(THREE_PEOPLE_BUS_STOP)]),
]


# --- Positioning ----------------------------------------------------------------------------------------
POSITIONING_CASES: list[Json] = [
    # direct
    case("positioning", "direct", "bench_outside_union", TEACHER, "Put the bench outside the Student Union entrance.",
         [near("Student Union entrance", 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", "Student Union entrance"))]),
    case("positioning", "direct", "ego_middle_lot_b", RACEFAN, "Put the ego in the middle of lot B.",
         [near(None, 8, asset=EGO, point=(38.5, -29.0)), near("parking lot B", 0.5, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("at", "parking lot B"))]),
    case("positioning", "direct", "hydrant_beside_library", JAPANESE, "Please place the fire hydrant beside of Library entrance.",
         [near("Library entrance", 6, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("next_to", "Library entrance"))]),
    case("positioning", "direct", "tree_to_coordinates", ARCHITECT,
         "Relocate the tree by the bus stop to x = -10, y = -25.",
         [near(None, 1.0, asset=TREE_BUS, point=(-10.0, -25.0)), only(assets=[TREE_BUS])],
         [place(TREE_BUS, xy(-10, -25))]),
    case("positioning", "direct", "suv_to_coords", NIGHTSHIFT, "suv -> 30,-20",
         [near(None, 1.0, asset=SUV, point=(30.0, -20.0)), only(assets=[SUV])], [place(SUV, xy(30, -20))]),
    case("positioning", "direct", "dustbin_beside_bench", GRANDPARENT,
         "Would you put the dustbin right beside the bench, please?",
         [near(BENCH, 2.5, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", BENCH))]),
    case("positioning", "direct", "motorbike_to_lot_b_entrance", COURIER, "move it to the lot B entrance",
         [near("parking lot B entrance", 8, asset="motorcycle_1"), only(assets=["motorcycle_1"])],
         [place("motorcycle_1", loc("at", "parking lot B entrance"))], setup=[planned(MOTORBIKE_LIBRARY)]),
    case("positioning", "direct", "car1_before_engineering", GERMAN,
         "Passenger car 1 shall be positioned in front of the Engineering Hall entrance.",
         [relative("in_front_of", "Engineering Hall entrance", asset=CAR1, max_distance=16), only(assets=[CAR1])],
         [place(CAR1, loc("in_front_of", "Engineering Hall entrance"))]),
    case("positioning", "direct", "bench_and_dustbin_library", GRANDPARENT,
         "Could you move the bench next to the Library door, and the dustbin beside the bench?",
         [near("Library entrance", 6, asset=BENCH), near(BENCH, 2.5, asset=BIN), only(assets=[BENCH, BIN])],
         [place(BENCH, loc("next_to", "Library entrance")), place(BIN, loc("next_to", BENCH))]),
    impossible("positioning", "direct", "bench_on_library_roof", TEACHER,
               "Put the bench up on the roof of the Library.", [place(BENCH, xy(-41, -30))]),
    case("positioning", "direct", "suv_in_front_of_ego", RACEFAN,
         "Put the SUV in the eastbound lane right in front of the ego.",
         [relative("in_front_of", EGO, asset=SUV, max_distance=15, tolerance_deg=30), in_lane(EAST, asset=SUV),
          only(assets=[SUV])],
         [place(SUV, loc("in_front_of", EGO))]),
    case("positioning", "direct", "stop_sign_north_crosswalk", JAPANESE, "Please move stop sign to north crosswalk.",
         [near("north crosswalk", 8, asset=STOP), only(assets=[STOP])], [place(STOP, loc("at", "north crosswalk"))]),
    # indirect
    case("positioning", "indirect", "lunch_in_shade", TEACHER,
         "The children will want to eat their lunch in the shade: move the bench under the tree by the fountain, "
         "and put the bin next to the bench.",
         [near(TREE_FOUNT, 4, asset=BENCH), near(BENCH, 3, asset=BIN), only(assets=[BENCH, BIN])],
         [place(BENCH, loc("next_to", TREE_FOUNT)), place(BIN, loc("next_to", BENCH))]),
    case("positioning", "indirect", "box_box_lot_a", RACEFAN, "Box box! Bring the ego into lot A, that's the pits.",
         [near("parking lot A", 0.5, asset=EGO), only(assets=[EGO])], [place(EGO, loc("at", "parking lot A"))]),
    case("positioning", "indirect", "bin_for_union_students", JAPANESE,
         "Students of Student Union throw garbage on ground. Trash bin should be near to their entrance.",
         [near("Student Union entrance", 6, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", "Student Union entrance"))]),
    case("positioning", "indirect", "hydrant_off_axis", ARCHITECT,
         "The hydrant sits awkwardly on the JTEKT approach. Shift it onto the pavement by the Engineering Hall instead.",
         [near("Engineering Hall entrance", 12, asset=HYDRANT), on(["sidewalk"], asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("on_sidewalk", "Engineering Hall entrance"))]),
    case("positioning", "indirect", "start_from_east_gate", NIGHTSHIFT,
         "test runs from the other end today. ego at the east gate, facing in",
         [near("east gate", 15, asset=EGO), in_lane(WEST, asset=EGO, aligned=True), only(assets=[EGO])],
         [place(EGO, loc("in_lane", "east gate", lane=WEST))]),
    case("positioning", "indirect", "bench_watch_fountain", GRANDPARENT,
         "I like to sit and watch the fountain. Could you move the bench over beside it?",
         [near("fountain", 6, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "indirect", "car_across_drop_off", COURIER,
         "some muppet's left their car across my drop-off at the Union. shove it over to lot A",
         [near("parking lot A", 0.5, asset="passenger_car_3"), only(assets=["passenger_car_3"])],
         [place("passenger_car_3", loc("at", "parking lot A"))], setup=[CAR_AT_UNION]),
    case("positioning", "indirect", "lorry_for_unloading", GERMAN,
         "For unloading, the lorry must be positioned directly in front of the JTEKT Building entrance.",
         [relative("in_front_of", "JTEKT building entrance", asset="truck_1", max_distance=12),
          only(assets=["truck_1"])],
         [place("truck_1", loc("in_front_of", "JTEKT building entrance"))], setup=[TRUCK_IN_LOT_A]),
    case("positioning", "indirect", "meets_the_coach", TEACHER,
         "She'll be meeting the coach, so stand her at the bus stop instead.",
         [near("bus stop", 5, asset="pedestrian_1"), only(assets=["pedestrian_1"])],
         [place("pedestrian_1", loc("at", "bus stop"))], setup=[planned(PERSON_ENGINEERING)]),
    impossible("positioning", "indirect", "suv_on_jtekt_roof", RACEFAN,
               "Park the SUV up on top of the JTEKT Building for the promo shot.", [place(SUV, xy(37, 30))]),
    case("positioning", "indirect", "ego_waits_before_crosswalk", JAPANESE,
         "I want ego car waiting just before west crosswalk, in its own lane.",
         [near(None, 7, asset=EGO, point=(-19.0, -1.75)), in_lane(EAST, asset=EGO, aligned=True), only(assets=[EGO])],
         [place(EGO, xy(-18, -1.75))]),
    # vague
    case("positioning", "vague", "bench_somewhere_shady", TEACHER, "Pop the bench somewhere shady.",
         [moved(BENCH, 1.0), only(assets=[BENCH])], [place(BENCH, loc("next_to", TREE_FOUNT))],
         alternatives=[[near(tree, 4, asset=BENCH)] for tree in TREES]),
    case("positioning", "vague", "car_off_racing_line", RACEFAN, "Shift that car off the racing line.",
         [moved("passenger_car_3", 2.0), only(assets=["passenger_car_3"])], [move("passenger_car_3", left=3.5)],
         setup=[CAR_AHEAD_20],
         alternatives=[[in_lane(WEST, asset="passenger_car_3")], [on(["paved"], asset="passenger_car_3")]]),
    case("positioning", "vague", "hydrant_more_far", JAPANESE, "Fire hydrant is too close to road. Please put more far.",
         [near(None, 3.5, asset=HYDRANT, point=(16.0, 10.0)), only(assets=[HYDRANT])], [move(HYDRANT, north=3)]),
    case("positioning", "vague", "tree_frames_library", ARCHITECT,
         "Let the tree by the bus stop frame the Library entrance instead.",
         [near("Library entrance", 6, asset=TREE_BUS), only(assets=[TREE_BUS])],
         [place(TREE_BUS, loc("next_to", "Library entrance"))]),
    case("positioning", "vague", "ego_lot_a_whatever", NIGHTSHIFT, "ego. lot a. whatever spot",
         [near("parking lot A", 0.5, asset=EGO), only(assets=[EGO])], [place(EGO, loc("at", "parking lot A"))]),
    case("positioning", "vague", "big_car_nearer_door", GRANDPARENT,
         "Could the big car be nearer the Library door? My knees, you see.",
         [near("Library entrance", 10, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "Library entrance"))]),
    case("positioning", "vague", "bike_by_union_doors", COURIER, "put it by the union doors instead",
         [near("Student Union entrance", 6, asset="bicycle_1"), only(assets=["bicycle_1"])],
         [place("bicycle_1", loc("at", "Student Union entrance"))], setup=[planned(BIKE_LOT_B_GATE)]),
    case("positioning", "vague", "bin_where_people_cross", GERMAN,
         "The waste bin is poorly situated. It shall be placed where the pedestrians cross the road.",
         [moved(BIN, 1.0), only(assets=[BIN])], [place(BIN, loc("at", "west crosswalk"))],
         alternatives=[[near("west crosswalk", 7, asset=BIN)], [near("north crosswalk", 7, asset=BIN)]]),
    case("positioning", "vague", "not_there_back_by_bus_stop", TEACHER,
         "Oh no, not there, the little ones can't reach it. Put it back by the bus stop.",
         [near("bus stop", 6, asset=BENCH), moved(BENCH, 5.0), only(assets=[BENCH])],
         [place(BENCH, loc("at", "bus stop"))], setup=[planned(BENCH_TO_FOUNTAIN)]),
    impossible("positioning", "vague", "ego_in_the_fountain", RACEFAN, "Park the ego in the fountain for a laugh.",
               [place(EGO, loc("at", "fountain"))]),
    case("positioning", "vague", "car_other_place_jtekt", JAPANESE, "This car, I want other place. Near to JTEKT is good.",
         [near("JTEKT building entrance", 10, asset="passenger_car_3"), only(assets=["passenger_car_3"])],
         [place("passenger_car_3", loc("at", "JTEKT building entrance"))], setup=[CAR_AT_LIBRARY]),
    # erroneous
    case("positioning", "erroneous", "bin_by_lirbary", TEACHER, "put the bin by the lirbary doors",
         [near("Library entrance", 6, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", "Library entrance"))]),
    case("positioning", "erroneous", "ego_ot_lot_a_entrnce", RACEFAN, "put the ego ot lot a entrnce",
         [near("parking lot A entrance", 8, asset=EGO), only(assets=[EGO])],
         [place(EGO, loc("at", "parking lot A entrance"))]),
    case("positioning", "erroneous", "bench_front_side_jtekt", JAPANESE, "Please put bench at front side of JTEKT entrace.",
         [near("JTEKT building entrance", 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("in_front_of", "JTEKT building entrance"))]),
    case("positioning", "erroneous", "tre_lot_a_to_fountian", ARCHITECT, "relocate the tre by lot A to the fountian",
         [near("fountain", 8, asset=TREE_LOT_A), only(assets=[TREE_LOT_A])],
         [place(TREE_LOT_A, loc("next_to", "fountain"))]),
    case("positioning", "erroneous", "suv_westbnd_jtekt", NIGHTSHIFT, "suv into westbnd lane by jtekt",
         [in_lane(WEST, asset=SUV), near("JTEKT building entrance", 16, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("in_lane", "JTEKT building entrance", lane=WEST))]),
    case("positioning", "erroneous", "hydrnt_near_studnet_union", GRANDPARENT,
         "could you put the fire hydrnt near the studnet union please",
         [near("Student Union entrance", 8, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", "Student Union entrance"))]),
    case("positioning", "erroneous", "bike_nroth_crosswalk", COURIER, "put the bike at the nroth crosswalk",
         [near("north crosswalk", 6, asset="bicycle_1"), only(assets=["bicycle_1"])],
         [place("bicycle_1", loc("at", "north crosswalk"))], setup=[planned(BIKE_LIBRARY)]),
    case("positioning", "erroneous", "stopsign_east_crosing", GERMAN,
         "The stopsign shal be positioned at the east crosing, on the southern footway.",
         [near(None, 4, asset=STOP, point=(11.5, -5.5)), on(["sidewalk"], asset=STOP), only(assets=[STOP])],
         [place(STOP, xy(13.5, -5.5))]),
    case("positioning", "erroneous", "coach_too_lot_a", TEACHER, "move the coach too lot A, theres more room",
         [near("parking lot A", 0.5, asset="bus_1"), only(assets=["bus_1"])],
         [place("bus_1", loc("at", "parking lot A"))], setup=[COACH_AT_UNION]),
    impossible("positioning", "erroneous", "bench_x_500", JAPANESE, "Please put bench at x=500, y=0.",
               [place(BENCH, xy(500, 0))]),
    case("positioning", "erroneous", "car1_car2_midle_and_lot_a", NIGHTSHIFT,
         "car1 to midle of crosroads, car2 to lot a",
         [near("main intersection", 1.0, asset=CAR1), near("parking lot A", 0.5, asset=CAR2),
          only(assets=[CAR1, CAR2])],
         [place(CAR1, loc("at", "main intersection")), place(CAR2, loc("at", "parking lot A"))]),
]


# --- Moving: shifts, turns, behaviours and manoeuvres over time -------------------------------------------
MOVING_CASES: list[Json] = [
    # direct
    case("moving", "direct", "ego_forward_fifteen", TEACHER, "Move the ego forward fifteen metres.",
         [moved(EGO, 14.5, 15.5, "forward"), only(assets=[EGO])], [move(EGO, forward=15)]),
    case("moving", "direct", "ego_ten_a_second", RACEFAN, "Set the ego's speed to 10 m/s.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", lane=EAST, speed=10.0)],
         alternatives=ego_speed_between(9.5, 10.5)),
    case("moving", "direct", "suv_turn_180", JAPANESE, "Please turn SUV 180 degree.",
         [moved(SUV, 0, 0.5, turn_min=170), only(assets=[SUV])], [move(SUV, turn_deg=180)]),
    case("moving", "direct", "bench_face_east", ARCHITECT, "Turn the bench round so it faces east, towards the crossroads.",
         [moved(BENCH, 0, 0.5, turn_min=170), only(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    case("moving", "direct", "car2_back_3", NIGHTSHIFT, "car2 back 3m",
         [only(assets=[CAR2])], [move(CAR2, forward=-3)], alternatives=backed_up(CAR2, 2.5, 3.5)),
    case("moving", "direct", "my_car_stops_five_seconds", GRANDPARENT,
         "Could you make my car stop after five seconds, please?",
         [event_played(EGO, "stop", 7.0), only()], [manoeuvre(EGO, "stop", at_time=5.0)]),
    case("moving", "direct", "ego_left_at_junction", COURIER, "ego turns left at the junction",
         [event_played(EGO, "junction_turn", 2.0), only()], [manoeuvre(EGO, "junction_turn", turn="left")]),
    case("moving", "direct", "car1_northbound_3", GERMAN,
         "Passenger car 1 shall drive northbound on Campus Drive at 3 m/s.",
         [does("drive_lane", asset=CAR1, lane=NORTH, speed_min=2.5, speed_max=3.5), only(assets=[CAR1])],
         [behave(CAR1, "drive_lane", lane=NORTH, speed=3.0)]),
    case("moving", "direct", "child_crosses", TEACHER, "Have the child cross the road at the crossing.",
         [only("pedestrian")], [behave("pedestrian_1", "cross_road")], setup=[WALKER_WEST_XING],
         alternatives=walks_across()),
    case("moving", "direct", "suv_donuts_5", RACEFAN, "Make the SUV do donuts in lot B, radius 5 m.",
         [does("circle", asset=SUV, radius_min=4.5, radius_max=5.5, centre_near="parking lot B"), only(assets=[SUV])],
         [behave(SUV, "circle", radius=5.0)]),
    case("moving", "direct", "car2_clockwise_then_forward", GERMAN,
         "Passenger car 2 shall be rotated by 90 degrees clockwise and subsequently moved forward by 4,5 m.",
         [moved(CAR2, 4.0, 5.0, "right", turn_min=80, turn_max=100), only(assets=[CAR2])],
         [move(CAR2, turn_deg=-90), move(CAR2, forward=4.5)]),
    case("moving", "direct", "ego_fwd_5_spd_6", NIGHTSHIFT, "ego fwd 5m then spd 6",
         [moved(EGO, 4.5, 5.5, "forward"), only(assets=[EGO])],
         [move(EGO, forward=5), behave(EGO, "drive_lane", lane=EAST, speed=6.0)], alternatives=ego_speed_between(5.5, 6.5)),
    impossible("moving", "direct", "tree_walks", JAPANESE, "Please make the tree by bus stop walk to the fountain.",
               [behave(TREE_BUS, "follow_path", to="fountain")]),
    case("moving", "direct", "bench_east_and_face_north", ARCHITECT,
         "Shift the bench 3 metres east, then turn it to face north.",
         [moved(BENCH, 2.5, 3.5, "backward", turn_min=80, turn_max=100), only(assets=[BENCH])],
         [move(BENCH, east=3), move(BENCH, turn_deg=-90)]),
    # indirect
    case("moving", "indirect", "crawl_for_children", TEACHER,
         "There will be children about, so the ego should crawl along at 2 metres a second.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", lane=EAST, speed=2.0)],
         alternatives=ego_speed_between(1.5, 2.5)),
    case("moving", "indirect", "suv_lights_out", RACEFAN,
         "Lights out and away we go: the SUV pulls out of lot B and heads east down Main Street.",
         [only(assets=[SUV])], [behave(SUV, "drive_lane", lane=EAST)],
         alternatives=[[does("drive_lane", asset=SUV, lane=EAST)], [reaches(SUV, "east gate", 40.0, within=8.0)]]),
    case("moving", "indirect", "sudden_brake_at_12", JAPANESE,
         "When ego comes 12 meter close to this car, I want the car to make sudden brake.",
         [event_played("passenger_car_3", "stop", 20.0), only()],
         [event("passenger_car_3", "stop", {"kind": "distance", "actor": EGO, "other": "passenger_car_3", "metres": 12},
                rate=7.0)],
         setup=[planned(CAR_AHEAD_SLOW)]),
    case("moving", "indirect", "desire_line_to_bus_stop", ARCHITECT,
         "I want to study the desire line: have that person walk across to the bus stop.",
         [reaches("pedestrian_1", "bus stop", 30.0, within=4.0), only("pedestrian")],
         [behave("pedestrian_1", "follow_path", to="bus stop")], setup=[planned(PERSON_LIBRARY)]),
    case("moving", "indirect", "past_the_slow_truck", NIGHTSHIFT, "ego needs to get past the slow truck. left lane at 3s",
         [event_played(EGO, "lane_change", 5.0), only()], [manoeuvre(EGO, "lane_change", side="left", at_time=3.0)],
         setup=[LORRY_CRAWLING]),
    case("moving", "indirect", "car_goes_home", GRANDPARENT,
         "The motor car at the east end of the row in the car park ought to go home now. Could it drive off to the "
         "east gate?",
         [reaches(CAR2, "east gate", 35.0, within=6.0), only(assets=[CAR2])],
         [behave(CAR2, "follow_path", to="east gate")]),
    case("moving", "indirect", "brake_for_rider", COURIER,
         "a rider's gonna pull out of lot B in front of the ego. have the ego brake hard 4 seconds in",
         [event_played(EGO, "stop", 6.0), only()], [manoeuvre(EGO, "stop", at_time=4.0, rate=6.0)]),
    case("moving", "indirect", "signal_held_red", GERMAN,
         "To examine the stopping behaviour of the ego vehicle, the traffic signal at the south-west corner of the "
         "junction shall be held at red.",
         [EGO_HALTS_BEFORE_WEST_CROSSWALK, only()], [hold(LIGHT_SW, "red")]),
    case("moving", "indirect", "coach_sets_off_home", TEACHER,
         "When it's time to go home, the coach should set off west along Main Street at 5 metres a second.",
         [only("bus")], [behave("bus_1", "drive_lane", lane=WEST, speed=5.0)], setup=[planned(COACH_WEST_JTEKT)],
         alternatives=[[does("drive_lane", asset="bus_1", lane=WEST, speed_min=4.5, speed_max=5.5)],
                       [event_played("bus_1", "keep_lane", 3.0)], [event_played("bus_1", "change_speed", 3.0)]]),
    impossible("moving", "indirect", "ego_300_kmh", RACEFAN, "Ego flat out at 300 km/h down the straight.",
               [behave(EGO, "drive_lane", lane=EAST, speed=83.3)]),
    case("moving", "indirect", "suv_too_forward", JAPANESE, "SUV is too much forward. Please go back 3 meter.",
         [only(assets=[SUV])], [move(SUV, forward=-3)], alternatives=backed_up(SUV, 2.5, 3.5)),
    case("moving", "indirect", "right_turn_at_walking_pace", ARCHITECT,
         "I want to experience the approach to the Student Union from the driver's seat: the ego should turn right at "
         "the crossroads, at a walking pace of 2 m/s.",
         [event_played(EGO, "junction_turn", 2.0), only(assets=[EGO])],
         [behave(EGO, "drive_lane", lane=EAST, speed=2.0), manoeuvre(EGO, "junction_turn", turn="right", speed=2.0)]),
    # vague
    case("moving", "vague", "slower_please", TEACHER, "Slower, please. The children are getting frightened.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", lane=EAST, speed=3.0)],
         alternatives=ego_speed_between(0.5, 4.0)),
    case("moving", "vague", "send_it", RACEFAN, "Send it! Faster!",
         [does("drive_lane", asset="motorcycle_1", speed_min=6.0), only("motorcycle")],
         [behave("motorcycle_1", "drive_lane", lane=EAST, speed=10.0)], setup=[planned(MOTORBIKE_AHEAD_20)]),
    case("moving", "vague", "car1_little_forward", JAPANESE, "Car number 1, please move a little bit forward.",
         [moved(CAR1, 0.5, 6.0, "forward"), only(assets=[CAR1])], [move(CAR1, forward=2)]),
    case("moving", "vague", "bench_toward_fountain", ARCHITECT, "Orient the bench towards the view of the fountain.",
         [moved(BENCH, 0, 0.5, turn_min=120), only(assets=[BENCH])], [move(BENCH, turn_deg=-155)]),
    case("moving", "vague", "ego_other_way", NIGHTSHIFT, "ego the other way",
         [moved(EGO, 0, 8.0, turn_min=150), only(assets=[EGO])], [move(EGO, turn_deg=180)]),
    case("moving", "vague", "round_and_round", GRANDPARENT,
         "Could the big car go round and round in the car park, like at the fair?",
         [does("circle", asset=SUV, centre_near="parking lot B"), only(assets=[SUV])], [behave(SUV, "circle")]),
    case("moving", "vague", "bike_off_to_bus_stop", COURIER, "send the bike off to the bus stop",
         [reaches("bicycle_1", "bus stop", 30.0, within=5.0), only("bicycle")],
         [behave("bicycle_1", "follow_path", to="bus stop")], setup=[planned(BIKE_LIBRARY)]),
    case("moving", "vague", "pedestrian_traverses", GERMAN, "The pedestrian shall traverse the carriageway.",
         [only("pedestrian")], [behave("pedestrian_1", "cross_road")], setup=[WALKER_SOUTH_30],
         alternatives=steps_out()),
    case("moving", "vague", "stop_nicely_for_zebra", TEACHER, "The ego ought to stop nicely for the zebra crossing.",
         [EGO_HALTS_BEFORE_WEST_CROSSWALK, only(assets=[EGO])], [event(EGO, "stop", reach("west crosswalk"))]),
    impossible("moving", "vague", "bench_drifts", RACEFAN, "Make the bench drift round the car park.",
               [behave(BENCH, "circle")]),
    case("moving", "vague", "robot_make_moving", JAPANESE, "Robot, please make it moving.",
         [does(["drive_lane", "circle", "follow_path"], asset="ackermann_robot_1"), only(ROBOT)],
         [behave("ackermann_robot_1", "drive_lane", lane=EAST)], setup=[ROBOT_LOT_B_GATE]),
    case("moving", "vague", "stroll_to_fountain", ARCHITECT,
         "Animate the forecourt a little: have one of them stroll over to the fountain.",
         [only("pedestrian")],
         [behave("pedestrian_1", "follow_path", to="fountain")], setup=[planned(TWO_AT_JTEKT)],
         alternatives=[[reaches("pedestrian_1", "fountain", 45.0, within=4.0)],
                       [reaches("pedestrian_2", "fountain", 45.0, within=4.0)]]),
    # erroneous
    case("moving", "erroneous", "ego_foward_10", TEACHER, "move the ego foward 10 metres",
         [moved(EGO, 9.5, 10.5, "forward"), only(assets=[EGO])], [move(EGO, forward=10)]),
    case("moving", "erroneous", "suv_circels_8", RACEFAN, "suv do circels in lot b, 8m radius",
         [does("circle", asset=SUV, radius_min=7.5, radius_max=8.5, centre_near="parking lot B"), only(assets=[SUV])],
         [behave(SUV, "circle", radius=8.0)]),
    case("moving", "erroneous", "lane_chnage_left_3", JAPANESE, "Please ego do lane chnage to left at 3 second.",
         [event_played(EGO, "lane_change", 5.0), only()], [manoeuvre(EGO, "lane_change", side="left", at_time=3.0)]),
    case("moving", "erroneous", "bench_trun_90", ARCHITECT, "trun the bench 90 degres anticlockwise",
         [moved(BENCH, 0, 0.5, turn_min=80, turn_max=100), only(assets=[BENCH])], [move(BENCH, turn_deg=90)]),
    case("moving", "erroneous", "sped_7_and_left", NIGHTSHIFT, "ego sped 7, trn left at junction",
         [event_played(EGO, "junction_turn", 2.0), only(assets=[EGO])],
         [behave(EGO, "drive_lane", lane=EAST, speed=7.0), manoeuvre(EGO, "junction_turn", turn="left", speed=7.0)]),
    case("moving", "erroneous", "midle_car_bak", GRANDPARENT, "could you move the car in the midle of the row bak a bit",
         [only(assets=[SUV])], [move(SUV, forward=-2)], alternatives=backed_up(SUV, 0.5, 6.0)),
    case("moving", "erroneous", "ped_step_out_infront", COURIER, "make the ped step out infront of the ego",
         [only("pedestrian")], [behave("pedestrian_1", "jaywalk")], setup=[WALKER_SOUTH_30],
         alternatives=steps_out(EAST)),
    case("moving", "erroneous", "car2_shal_drive_westbund", GERMAN,
         "Passenger car 2 shal drive westbund on Main Street with 5 m/s.",
         [does("drive_lane", asset=CAR2, lane=WEST, speed_min=4.5, speed_max=5.5), only(assets=[CAR2])],
         [behave(CAR2, "drive_lane", lane=WEST, speed=5.0)]),
    case("moving", "erroneous", "walk_ovr_to_fountian", TEACHER, "now have her walk ovr to the fountian",
         [reaches("pedestrian_1", "fountain", 45.0, within=4.0), only("pedestrian")],
         [behave("pedestrian_1", "follow_path", to="fountain")], setup=[planned(CHILD_AT_JTEKT)]),
    impossible("moving", "erroneous", "reverse_300", RACEFAN, "reverse the ego 300 metres",
               [move(EGO, forward=-300)]),
    case("moving", "erroneous", "car_numbr_2_turn_left", JAPANESE, "Please make car numbr 2 turning 90 degre to left.",
         [moved(CAR2, 0, 0.5, turn_min=80, turn_max=100), only(assets=[CAR2])], [move(CAR2, turn_deg=90)]),
    case("moving", "erroneous", "teh_ego_rihgt_2_sec", ARCHITECT, "make teh ego turn rihgt at the junction after 2 sec",
         [event_played(EGO, "junction_turn", 4.0), only()], [manoeuvre(EGO, "junction_turn", turn="right", at_time=2.0)]),
]


# --- Arrangement: lines, rows, rings and grids of new things ----------------------------------------------
ARRANGEMENT_CASES: list[Json] = [
    # direct
    case("arrangement", "direct", "five_cones_library", TEACHER, "Put five cones in a line in front of the Library entrance.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5),
          near("Library entrance", 12, "traffic_cone", scope="added", every=True), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("in_front_of", "Library entrance"), count=5)]),
    case("arrangement", "direct", "starting_grid_lot_a", RACEFAN,
         "Line up four cars in a parking row in lot A. That's the starting grid.",
         [delta("passenger_car", 4, 4), layout("line", "passenger_car", 4),
          near("parking lot A", 0.5, "passenger_car", scope="added", every=True), only("passenger_car")],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot A"), count=4)]),
    case("arrangement", "direct", "ring_8_bollard_fountain", JAPANESE, "Please make ring of 8 bollard around fountain.",
         [delta("bollard", 8, 8), layout("ring", "bollard", 8, around="fountain"), only("bollard")],
         [arrange("bollard", "ring", loc("at", "fountain"), count=8)]),
    case("arrangement", "direct", "benches_union_frontage", ARCHITECT,
         "Set out three benches in a row along the Student Union frontage.",
         [delta("bench", 3, 3), layout("line", "bench", 3),
          near("Student Union entrance", 12, "bench", scope="added", every=True), only("bench")],
         [arrange("bench", "line", loc("at", "Student Union entrance"), count=3)]),
    case("arrangement", "direct", "six_cones_eastbound_edge", NIGHTSHIFT, "6 cones along eastbound edge from bus stop",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6), in_lane(EAST, "traffic_cone"),
          near("bus stop", 30, "traffic_cone", scope="added", every=True), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "bus stop", lane=EAST), count=6)]),
    case("arrangement", "direct", "posts_round_bus_stop_tree", GRANDPARENT,
         "Would you put a ring of six of those short posts round the tree by the bus stop, dear?",
         [delta("bollard", 6, 6), layout("ring", "bollard", 6, around=TREE_BUS), only("bollard")],
         [arrange("bollard", "ring", loc("at", TREE_BUS), count=6)]),
    case("arrangement", "direct", "four_bikes_jtekt", COURIER, "put 4 bikes in a row outside the JTEKT",
         [delta("bicycle", 4, 4), layout("line", "bicycle", 4),
          near("JTEKT building entrance", 12, "bicycle", scope="added", every=True), only("bicycle")],
         [arrange("bicycle", "line", loc("at", "JTEKT building entrance"), count=4)]),
    case("arrangement", "direct", "bollards_north_footway", GERMAN,
         "A row of six bollards shall be arranged along the northern footway of Main Street at the JTEKT Building "
         "entrance.",
         [delta("bollard", 6, 6), layout("line", "bollard", 6),
          near("JTEKT building entrance", 16, "bollard", scope="added", every=True), on(["sidewalk"], "bollard"),
          only("bollard")],
         [arrange("bollard", "line", loc("on_sidewalk", "JTEKT building entrance"), count=6)]),
    case("arrangement", "direct", "cones_lot_b_gate_nine_am", TEACHER,
         "Put four cones in a line at the lot B entrance and set the time to 9 in the morning.",
         [delta("traffic_cone", 4, 4), layout("line", "traffic_cone", 4),
          near("parking lot B entrance", 10, "traffic_cone", scope="added", every=True),
          env(time_from="08:55", time_to="09:05"), only("traffic_cone", env=True)],
         [arrange("traffic_cone", "line", loc("at", "parking lot B entrance"), count=4), clock("09:00")]),
    case("arrangement", "direct", "barriers_northbound_edge", RACEFAN,
         "Build a line of 5 barriers along the northbound lane edge of Campus Drive, up by the north crosswalk.",
         [delta("road_barrier", 5, 5), layout("line", "road_barrier", 5), in_lane(NORTH, "road_barrier"),
          near("north crosswalk", 35, "road_barrier", scope="added", every=True), only("road_barrier")],
         [arrange("road_barrier", "lane_edge", loc("in_lane", "north crosswalk", lane=NORTH), count=5)]),
    impossible("arrangement", "direct", "ring_200_bollard", JAPANESE, "Please make ring of 200 bollard around fountain.",
               [arrange("bollard", "ring", loc("at", "fountain"), count=200)]),
    case("arrangement", "direct", "grid_nine_trees_lot_a", ARCHITECT, "Lay out a grid of nine trees in lot A.",
         [delta("tree", 9, 9), layout("cluster", "tree", 9, tolerance=12.0),
          near("parking lot A", 1, "tree", scope="added", every=True), only("tree")],
         [arrange("tree", "grid", loc("at", "parking lot A"), count=9)]),
    # indirect
    case("arrangement", "indirect", "class_lines_up", TEACHER,
         "The class needs to line up outside the Library before we go in: six children in a row, please.",
         [delta("pedestrian", 6, 6), layout("line", "pedestrian", 6),
          near("Library entrance", 12, "pedestrian", scope="added", every=True), only("pedestrian")],
         [arrange("pedestrian", "line", loc("at", "Library entrance"), count=6)]),
    case("arrangement", "indirect", "pit_wall", RACEFAN,
         "I need a pit wall: five barriers down the eastbound lane edge, starting by the lot B entrance.",
         [delta("road_barrier", 5, 5), layout("line", "road_barrier", 5), in_lane(EAST, "road_barrier"),
          near("parking lot B entrance", 30, "road_barrier", scope="added", every=True), only("road_barrier")],
         [arrange("road_barrier", "lane_edge", loc("in_lane", "parking lot B entrance", lane=EAST), count=5)]),
    case("arrangement", "indirect", "protect_fountain_tree", JAPANESE,
         "Children play near tree by fountain. I want to protect it by putting posts around. 6 is enough.",
         [delta("bollard", 6, 6), layout("ring", "bollard", 6, around=TREE_FOUNT), only("bollard")],
         [arrange("bollard", "ring", loc("at", TREE_FOUNT), count=6)]),
    case("arrangement", "indirect", "edge_of_jtekt_forecourt", ARCHITECT,
         "I'd like to define the edge of the JTEKT forecourt with a row of bollards, say seven.",
         [delta("bollard", 7, 7), layout("line", "bollard", 7),
          near("JTEKT building entrance", 12, "bollard", scope="added", every=True), only("bollard")],
         [arrange("bollard", "line", loc("at", "JTEKT building entrance"), count=7)]),
    case("arrangement", "indirect", "close_campus_north", NIGHTSHIFT,
         "need campus drive closed off north of the junction. cones across it at the north crosswalk x5",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5),
          near("north crosswalk", 8, "traffic_cone", scope="added", every=True),
          on(["lane", "crossing"], "traffic_cone"), in_lane_some(NORTH, "traffic_cone"),
          in_lane_some(SOUTH, "traffic_cone"), only("traffic_cone")],
         [arrange("traffic_cone", "line", xy(0, 11.5), count=5, spacing=1.5, heading_deg=0)]),
    case("arrangement", "indirect", "queue_at_bus_stop", GRANDPARENT,
         "There's always a queue of people at the bus stop. Could you show four of them standing in a line?",
         [delta("pedestrian", 4, 4), layout("line", "pedestrian", 4),
          near("bus stop", 8, "pedestrian", scope="added", every=True), only("pedestrian")],
         [arrange("pedestrian", "line", loc("on_sidewalk", "bus stop"), count=4)]),
    case("arrangement", "indirect", "depot_vans_lot_b", COURIER, "the depot: three vans parked side by side in lot B",
         [delta("truck", 3, 3), layout("line", "truck", 3),
          near("parking lot B", 0.5, "truck", scope="added", every=True), only("truck")],
         [arrange("truck", "parking_row", loc("at", "parking lot B"), count=3)]),
    case("arrangement", "indirect", "debris_enclosed", GERMAN,
         "For reasons of safety, the debris shall be enclosed by a ring of cones.",
         [delta("traffic_cone", 4, None), layout("ring", "traffic_cone", 4, around="cement_rubble_1"),
          only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "cement_rubble_1"))], setup=[RUBBLE_AHEAD_25]),
    case("arrangement", "indirect", "waiting_area_round_coach", TEACHER,
         "Mark out a safe waiting area round the coach with a ring of cones.",
         [delta("traffic_cone", 4, None), layout("ring", "traffic_cone", 4, around="bus_1"), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "bus_1"))], setup=[planned(BUS_IN_LOT_A)]),
    impossible("arrangement", "indirect", "ring_of_grandstands", RACEFAN, "Ring the whole track with grandstands.",
               [arrange("grandstand", "ring", loc("at", "main intersection"))]),
    case("arrangement", "indirect", "taxis_waiting_jtekt", JAPANESE,
         "Many taxi are waiting at JTEKT. Please make 3 car standing in line there.",
         [delta(CARS, 3, 3), layout("line", CARS, 3),
          near("JTEKT building entrance", 15, CARS, scope="added", every=True), only(*CARS)],
         [arrange("passenger_car", "line", loc("at", "JTEKT building entrance"), count=3)]),
    case("arrangement", "indirect", "frame_library_approach", ARCHITECT,
         "Frame the Library approach with a row of four trees.",
         [delta("tree", 4, 4), layout("line", "tree", 4),
          near("Library entrance", 12, "tree", scope="added", every=True), only("tree")],
         [arrange("tree", "line", loc("at", "Library entrance"), count=4)]),
    # vague
    case("arrangement", "vague", "safe_line_bus_stop", TEACHER, "Could we have some cones making a safe line by the bus stop?",
         [delta("traffic_cone", 3, None), layout("line", "traffic_cone", 3),
          near("bus stop", 20, "traffic_cone", scope="added", every=True), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "bus stop", lane=EAST), count=5)]),
    case("arrangement", "vague", "chicane_main_street", RACEFAN, "Make me a chicane on Main Street.",
         [delta(CORDON, 3, None), in_lane(None, CORDON), only(*CORDON)],
         [arrange("road_barrier", "lane_edge", loc("in_lane", "bus stop", lane=EAST), count=4)]),
    case("arrangement", "vague", "some_posts_round_stop_sign", JAPANESE, "Some posts around stop sign, please.",
         [delta("bollard", 3, None), layout("ring", "bollard", 3, around=STOP), only("bollard")],
         [arrange("bollard", "ring", loc("at", STOP))]),
    case("arrangement", "vague", "rhythm_of_street_trees", ARCHITECT,
         "Give Campus Drive north of the junction a rhythm of street trees.",
         [delta("tree", 3, None), layout("line", "tree", 3),
          near(None, 45, "tree", scope="added", point=(0.0, 50.0), every=True),
          near(NORTH, 9, "tree", scope="added", every=True), only("tree")],
         [arrange("tree", "line", loc("at", "campus_east_north"), count=5)]),
    case("arrangement", "vague", "block_lot_b_entrance_night", NIGHTSHIFT, "block lot b entrance. and make it night",
         [delta(CORDON, 2, None), near("parking lot B entrance", 10, CORDON, scope="added", every=True),
          env(night=True), only(*CORDON, env=True)],
         [arrange("road_barrier", "line", xy(47, -8), count=3, heading_deg=0), clock("22:00")]),
    case("arrangement", "vague", "pretty_circle_benches", GRANDPARENT,
         "Could you make a pretty circle of benches round the fountain for us old folk?",
         [delta("bench", 3, None), layout("ring", "bench", 3, around="fountain"), only("bench")],
         [arrange("bench", "ring", loc("at", "fountain"))]),
    case("arrangement", "vague", "bikes_parked_neat", COURIER, "bikes all parked up neat by the union",
         [delta("bicycle", 3, None), layout("line", "bicycle", 3),
          near("Student Union entrance", 15, "bicycle", scope="added", every=True), only("bicycle")],
         [arrange("bicycle", "line", loc("at", "Student Union entrance"), count=4)]),
    case("arrangement", "vague", "orderly_vehicles_lot_a_1430", GERMAN,
         "An orderly arrangement of vehicles in parking lot A is desired, at 14.30 hours.",
         [delta(TRAFFIC, 2, None), layout("line", TRAFFIC, 2), near("parking lot A", 0.5, TRAFFIC, scope="added", every=True),
          env(time_from="14:25", time_to="14:35"), only(*TRAFFIC, env=True)],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot A"), count=4), clock("14:30")]),
    case("arrangement", "vague", "same_again_lot_b", TEACHER, "Do the same again at the lot B entrance.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5),
          near("parking lot B entrance", 10, "traffic_cone", scope="added", every=True), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B entrance"), count=5)], setup=[planned(CONES_LOT_A_GATE)]),
    impossible("arrangement", "vague", "trees_inside_engineering", JAPANESE,
               "Please make circle of trees inside the Engineering Hall.",
               [arrange("tree", "ring", loc("at", "Engineering Hall"), count=6, radius=4.0)]),
    case("arrangement", "vague", "soften_lot_b_edge", ARCHITECT, "Soften the edge of lot B along Main Street with some trees in a line.",
         [delta("tree", 3, None), layout("line", "tree", 3),
          near("parking lot B", 6, "tree", scope="added", every=True), only("tree")],
         [arrange("tree", "line", xy(28, -9.5), count=4, spacing=5.0, heading_deg=0)]),
    case("arrangement", "vague", "slalom_eastbound", RACEFAN, "Set up a slalom for the ego down the eastbound lane.",
         [delta("traffic_cone", 3, None), in_lane(EAST, "traffic_cone"), layout("line", "traffic_cone", 3, tolerance=2.0),
          only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", ahead_of(EGO, 20), count=6, spacing=6.0)]),
    # erroneous
    case("arrangement", "erroneous", "cones_in_aline_library", TEACHER, "put 4 cones in aline infront of the library entrence",
         [delta("traffic_cone", 4, 4), layout("line", "traffic_cone", 4),
          near("Library entrance", 12, "traffic_cone", scope="added", every=True), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("in_front_of", "Library entrance"), count=4)]),
    case("arrangement", "erroneous", "barirers_round_rubble", RACEFAN, "ring of barirers round the rubble",
         [delta("road_barrier", 4, None), layout("ring", "road_barrier", 4, around="cement_rubble_1"),
          only("road_barrier")],
         [arrange("road_barrier", "ring", loc("at", "cement_rubble_1"))], setup=[RUBBLE_AHEAD_25]),
    case("arrangement", "erroneous", "three_bench_line_fontain", JAPANESE, "Please 3 bench in line near fontain.",
         [delta("bench", 3, 3), layout("line", "bench", 3), near("fountain", 12, "bench", scope="added", every=True),
          only("bench")],
         [arrange("bench", "line", loc("next_to", "fountain"), count=3)]),
    case("arrangement", "erroneous", "bolards_across_lot_a_entrnce", ARCHITECT, "a row of 5 bolards across the lot A entrnce",
         [delta("bollard", 5, 5), layout("line", "bollard", 5),
          near("parking lot A entrance", 8, "bollard", scope="added", every=True), only("bollard")],
         [arrange("bollard", "line", xy(-85, 8), count=5, heading_deg=0)]),
    case("arrangement", "erroneous", "cone_grd_lot_b", NIGHTSHIFT, "cone grd lot b 3x3",
         [delta("traffic_cone", 9, 9), layout("cluster", "traffic_cone", 9, tolerance=8.0),
          near("parking lot B", 0.5, "traffic_cone", scope="added", every=True), only("traffic_cone")],
         [arrange("traffic_cone", "grid", loc("at", "parking lot B"), count=9, columns=3)]),
    case("arrangement", "erroneous", "circel_postes_hidrant_yelow", GRANDPARENT,
         "make a circel of postes round the fire hidrant and paint them yelow",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around=HYDRANT),
          looks("yellow", "bollard", scope="all", every=True), only("bollard")],
         [arrange("bollard", "ring", loc("at", HYDRANT)), paint(category="bollard", colour="yellow")]),
    case("arrangement", "erroneous", "six_cones_westbund_jtekt", COURIER, "line of 6 cones alng the westbund lane by the JTEKT",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6), in_lane(WEST, "traffic_cone"),
          near("JTEKT building entrance", 30, "traffic_cone", scope="added", every=True), only("traffic_cone")],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "JTEKT building entrance", lane=WEST), count=6)]),
    case("arrangement", "erroneous", "benches_arround_lot_a_tree", GERMAN,
         "A ring of benches is to be arranged arround the tree north of parking lot A.",
         [delta("bench", 3, None), layout("ring", "bench", 3, around=TREE_LOT_A), only("bench")],
         [arrange("bench", "ring", loc("at", TREE_LOT_A))]),
    case("arrangement", "erroneous", "longer_line_three_more", TEACHER, "can you make the line longer? add 3 more on the end",
         [delta("traffic_cone", 3, 3), layout("line", "traffic_cone", 6, scope="all"), only("traffic_cone")],
         [arrange("traffic_cone", "line", xy(-43.58, -13.82), count=3, spacing=0.86, heading_deg=0)],
         setup=[planned(THREE_CONES_LINE_LIBRARY)]),
    impossible("arrangement", "erroneous", "cones_500_stright", RACEFAN, "500 cones down the main stright",
               [arrange("traffic_cone", "lane_edge", loc("in_lane", "main gate", lane=EAST), count=500)]),
    case("arrangement", "erroneous", "persons_circle_arond_fountain", JAPANESE,
         "Please make persons to stand in circle arond fountain, 8 persons.",
         [delta("pedestrian", 8, 8), layout("ring", "pedestrian", 8, around="fountain"), only("pedestrian")],
         [arrange("pedestrian", "ring", loc("at", "fountain"), count=8)]),
    case("arrangement", "erroneous", "tres_front_enginering", ARCHITECT, "a line of three tres along the front of the Enginering Hall",
         [delta("tree", 3, 3), layout("line", "tree", 3),
          near("Engineering Hall entrance", 12, "tree", scope="added", every=True), only("tree")],
         [arrange("tree", "line", loc("at", "Engineering Hall entrance"), count=3)]),
]


# --- Appearance: colours, materials, time of day, weather and lights ---------------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case("appearance", "direct", "bench_blue", TEACHER, "Paint the bench blue.",
         [looks("blue", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="blue")]),
    case("appearance", "direct", "suv_ferrari_red", RACEFAN, "Make the SUV red. Ferrari red.",
         [looks("red", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="red")]),
    case("appearance", "direct", "seven_in_morning", JAPANESE, "Please set the time to 7 in morning.",
         [env(time_from="06:55", time_to="07:05", weather=["clear"]), only(env=True)], [clock("07:00")]),
    case("appearance", "direct", "light_fog", ARCHITECT, "Set a light fog.",
         [env(weather=["fog"], intensity_min=0.1, intensity_max=0.45, time_from="11:55", time_to="12:05"),
          only(env=True)], [weather("fog", 0.3)]),
    case("appearance", "direct", "time_0200", NIGHTSHIFT, "time 0200",
         [env(time_from="01:55", time_to="02:05"), only(env=True)], [clock("02:00")]),
    case("appearance", "direct", "street_lamps_on", GRANDPARENT, "Please switch the street lamps on.",
         [env(street_lights="on"), only(env=True)], [lighting(street_lights="on")]),
    case("appearance", "direct", "heavy_rain_headlights", COURIER, "heavy rain, and put the headlights on",
         [env(weather=["rain"], intensity_min=0.75, vehicle_lights="on"), only(env=True)],
         [weather("rain", 0.9), lighting(vehicle_lights="on")]),
    case("appearance", "direct", "car1_silver_metallic", GERMAN,
         "Passenger car 1 shall be given a silver colour with a metallic finish.",
         [looks("silver", asset=CAR1, material="metal"), only(assets=[CAR1])],
         [paint([CAR1], colour="silver", material="metal")]),
    impossible("appearance", "direct", "bench_rainbow", TEACHER, "Paint the bench in rainbow stripes.",
               [paint([BENCH], colour="rainbow")]),
    case("appearance", "direct", "half_nine_headlights", RACEFAN, "Make it 21:30 and switch the car headlights on.",
         [env(time_from="21:25", time_to="21:35", vehicle_lights="on"), only(env=True)],
         [clock("21:30"), lighting(vehicle_lights="on")]),
    case("appearance", "direct", "both_signals_black", JAPANESE, "Please make both traffic light black color.",
         [looks("black", "traffic_light", scope="all", every=True), only("traffic_light")],
         [paint(category="traffic_light", colour="black")]),
    case("appearance", "direct", "cars_green_suv_alone", GERMAN,
         "All passenger cars shall be painted green; the SUV is to be left unchanged.",
         [looks("green", "passenger_car", scope="all", every=True), only("passenger_car")],
         [paint(category="passenger_car", colour="green")]),
    # indirect
    case("appearance", "indirect", "too_dark_for_children", TEACHER,
         "It's far too dark for the children to see where they're going. Can you brighten things up?",
         [only(env=True)], [clock("12:00")], setup=[EVENING_21],
         alternatives=[[env(night=False)], [env(street_lights="on")], [env(exposure_min=1.2)]]),
    case("appearance", "indirect", "soaked_track", RACEFAN,
         "Let's see how the ego copes with a wet race: make the track properly soaked.",
         [env(weather=["rain"], intensity_min=0.6), only(env=True)], [weather("rain", 0.9)]),
    case("appearance", "indirect", "suv_same_as_my_car", JAPANESE, "My own car is white. I want SUV same as my car.",
         [looks("white", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="white")]),
    case("appearance", "indirect", "blue_hour_with_lamps", ARCHITECT,
         "For the render I want that blue-hour look just after sunset, with the street lights lit.",
         [env(time_from="19:15", time_to="21:00", street_lights="on"), only(env=True)],
         [clock("20:00"), lighting(street_lights="on")],
         ),
    case("appearance", "indirect", "cant_see_a_thing", NIGHTSHIFT, "cant see a thing in this. clear it",
         [env(weather=["clear"]), only(env=True)], [weather("clear")], setup=[THICK_FOG]),
    case("appearance", "indirect", "fire_engine_colour", GRANDPARENT,
         "My grandson loves fire engines. Could the big car be the same colour as one?",
         [looks("red", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="red")]),
    case("appearance", "indirect", "january_run", COURIER, "feels like a january run. give me some snow",
         [env(weather=["snow"]), only(env=True)], [weather("snow", 0.6)]),
    case("appearance", "indirect", "camera_test_visibility", GERMAN,
         "For the test of the camera system, the visibility shall be reduced by means of dense fog.",
         [env(weather=["fog"], intensity_min=0.7), only(env=True)], [weather("fog", 0.9)]),
    case("appearance", "indirect", "coach_school_colours", TEACHER, "Our school colour is yellow. Can the coach match?",
         [looks("yellow", asset="bus_1"), only(assets=["bus_1"])], [paint(["bus_1"], colour="yellow")],
         setup=[planned(COACH_LOT_A)]),
    impossible("appearance", "indirect", "bahrain_sandstorm", RACEFAN, "Make it feel like Bahrain: a proper sandstorm.",
               [weather("sandstorm", 0.9)]),
    case("appearance", "indirect", "fog_away_sunny_three", GRANDPARENT,
         "I can hardly see a thing for the fog, dear. Could you take the fog away and make it a nice sunny afternoon, "
         "say three o'clock?",
         [env(weather=["clear"], time_from="14:55", time_to="15:05"), only(env=True)],
         [weather("clear"), clock("15:00")], setup=[THICK_FOG]),
    case("appearance", "indirect", "after_work_six_thirty", JAPANESE, "I will test after work, around six thirty in evening.",
         [env(time_from="18:25", time_to="18:35"), only(env=True)], [clock("18:30")]),
    # vague
    case("appearance", "vague", "bit_brighter", TEACHER, "Could you make it a bit brighter?",
         [only(env=True)], [lighting(exposure=1.3)],
         alternatives=[[env(exposure_min=1.1)], [env(street_lights="on")]]),
    case("appearance", "vague", "british_summer", RACEFAN, "Make it look like a proper British summer race day.",
         [only(env=True)], [weather("cloudy", 0.6)],
         alternatives=[[env(weather=["cloudy"])], [env(weather=["rain"], intensity_max=0.7)]]),
    case("appearance", "vague", "snow_little_less", JAPANESE, "It is too much. Please little less.",
         [env(weather=["snow"], intensity_min=0.1, intensity_max=0.8), only(env=True)], [weather("snow", 0.5)],
         setup=[planned(HEAVY_SNOW)]),
    case("appearance", "vague", "late_afternoon_warmth", ARCHITECT, "Give the scene a warmer, late-afternoon feel.",
         [env(time_from="15:00", time_to="18:45"), only(env=True)], [clock("17:00")]),
    case("appearance", "vague", "dark", NIGHTSHIFT, "dark.",
         [only(env=True)], [clock("23:00")], alternatives=[[env(night=True)], [env(exposure_max=0.6)]]),
    case("appearance", "vague", "cheerful_end_car", GRANDPARENT,
         "Could the little car at the end of the row be a nicer colour? Something cheerful.",
         [only(assets=[CAR1, CAR2])], [paint([CAR2], colour="yellow")],
         alternatives=[[looks(BRIGHT, asset=CAR1)], [looks(BRIGHT, asset=CAR2)]]),
    case("appearance", "vague", "late_drops_dark", COURIER, "make it like the late drops, proper dark",
         [env(night=True), only(env=True)], [clock("23:30")]),
    case("appearance", "vague", "precipitation_moderated", GERMAN,
         "The precipitation is excessive; it shall be moderated.",
         [only(env=True)], [weather("rain", 0.5)], setup=[HEAVY_RAIN],
         alternatives=[[env(weather=["rain"], intensity_min=0.1, intensity_max=0.75)], [env(weather=["cloudy"])]]),
    case("appearance", "vague", "bench_stand_out", TEACHER, "The bench is hard to spot. Can it stand out a bit more?",
         [looks(BRIGHT, asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="yellow")]),
    impossible("appearance", "vague", "hail_falling", JAPANESE, "Please make hail falling.", [weather("hail", 0.6)]),
    case("appearance", "vague", "racing_livery", RACEFAN, "Give the SUV some proper racing livery.",
         [only(assets=[SUV])], [paint([SUV], colour="red", material="glossy")],
         alternatives=[[looks(ALL_COLOURS, asset=SUV)], [looks(asset=SUV, material="glossy")],
                       [looks(asset=SUV, material="metal")]]),
    case("appearance", "vague", "no_the_other_car", GRANDPARENT,
         "No, not that one, dear. The other one at the far end, the east end.",
         [looks("red", asset=CAR2), only(assets=[CAR1, CAR2])], [paint([CAR2], colour="red")],
         setup=[planned(CAR1_RED)]),
    # erroneous
    case("appearance", "erroneous", "bin_grene", TEACHER, "paint the bin grene",
         [looks("green", asset=BIN), only(assets=[BIN])], [paint([BIN], colour="green")]),
    case("appearance", "erroneous", "suv_yelow", RACEFAN, "suv yelow pls",
         [looks("yellow", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="yellow")]),
    case("appearance", "erroneous", "tim_22_oclock", JAPANESE, "Please set tim to night, 22 o'clock.",
         [env(time_from="21:55", time_to="22:05"), only(env=True)], [clock("22:00")]),
    case("appearance", "erroneous", "moderate_fogg", ARCHITECT, "moderate fogg please",
         [env(weather=["fog"], intensity_min=0.45, intensity_max=0.75), only(env=True)], [weather("fog", 0.6)]),
    case("appearance", "erroneous", "heavy_snw", NIGHTSHIFT, "heavy snw",
         [env(weather=["snow"], intensity_min=0.75), only(env=True)], [weather("snow", 0.9)]),
    case("appearance", "erroneous", "stret_lamps_of", GRANDPARENT, "turn the stret lamps of please dear",
         [env(street_lights="off"), only(env=True)], [lighting(street_lights="off")]),
    case("appearance", "erroneous", "lite_rain", COURIER, "lite rain",
         [env(weather=["rain"], intensity_min=0.1, intensity_max=0.45), only(env=True)], [weather("rain", 0.3)]),
    case("appearance", "erroneous", "exposur_1_5", GERMAN, "The exposur shall be set to 1,5.",
         [env(exposure_min=1.45, exposure_max=1.55), only(env=True)], [lighting(exposure=1.5)]),
    case("appearance", "erroneous", "ment_purple", TEACHER, "sorry i ment purple not orange",
         [looks("purple", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="purple")],
         setup=[planned(BENCH_ORANGE)]),
    impossible("appearance", "erroneous", "suv_invisable", COURIER, "make the suv invisable",
               [paint([SUV], colour="invisible")]),
    case("appearance", "erroneous", "suv_blue_rain_littel", JAPANESE, "Please SUV color blue and also rain littel.",
         [looks("blue", asset=SUV), env(weather=["rain"], intensity_max=0.5), only(assets=[SUV], env=True)],
         [paint([SUV], colour="blue"), weather("rain", 0.3)]),
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
