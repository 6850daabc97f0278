"""The thirty-first practice suite: 364 cases from eight new kinds of user, none used by an earlier suite, from the campus world alone.

`python -m drivetwin.evals.practice31_source` writes `suites/practice31.jsonl` (tag `practice31`, ids
`practice31.<task>.<grade>.<name>`), one JSON object per line, from the plain case lists below.

Voices (each case names its own in `notes`; 44 to 47 cases each): an air-traffic controller or pilot on the radio
("Tower, say position of...", "request", "say separation", "affirmative", "negative", "over", "lot Bravo", "lot
Alpha", "Sierra Uniform Victor", "hold short of the west crosswalk", "heading zero niner zero", "one-niner-three-zero
local", "three-zero metres", "expedite", "ceiling and visibility", "so nobody taxis into it"), a theatre stage
director ("strike the bench", "extras", "set dressing", "lighting cue", "on cue", "its new mark", "new blocking",
"upstaging my actors", "Act Two", "plays out to the road", "a practical on the bench", "the designer hates it"), a
Russian speaker writing English ("please to add one bench near fountain", "how much cars is standing", "is need",
"I want sit in shadow", "before I will change anything", "I want that it was yelow", "put it to parking A", "make
ring from hay bales"), a Nigerian-English speaker ("abeg", "on the street light", "off the fog", "e still dey rain?",
"carry am go", "make dem comot", "bring two more motors come", "small small", "well well", "oya make am dey go",
"sharp sharp", "my oga", "yellow like danfo", "hazy like harmattan"), an estate agent ("leafy sells", "kerb appeal",
"a stone's throw from the car park", "sought-after", "the listing photos", "viewers", "the open day", "the money
shot", "period facade", "footfall", "rooftop parking is so sought-after"), a football or PE coach ("set out cones",
"the lads", "sprint channels", "a slalom for dribbling", "a warm-up grid", "reaction drill", "shuttle runs", "agility
ladders", "send two of the lads home"), a tired parent typing one-handed ("where is the suv", "ugh", "idc", "thx",
"pls", "n delet the stop sigh too", "the kid", "make it raim", "200 km/h kid wants it fastt") and a hesitant
over-thinker who hedges and corrects themself ("Or left - no, right. Definitely right", "a biycle - no, two biycles",
"Perhaps lose one? Or two. No - one", "by the Library entrance? Or - no, the Engineering Hall entrance", "not pink",
"reverse 5 metres? Or 3. Three mtres").

Prompts describe things instead of naming them ("the car in the middle of the three in lot B", "the car at the
west end of the lot B row", "the traffic light on the north-east corner", "the tree just north of lot A", "the trees
round the fountain", "the road running north-south", "the other car park", "traffic ahead", "the car in front",
"that obstruction", "the people", "she"), turn on negation and polarity ("just that one, not both", "not the ego,
obviously", "not pink", "nowhere to sit", "no shade at all", "no dey useful again", "negative on those cones", "not
so bright", "fewer cars", "lose half", "most of those cones", "cars must not go") and name places and scopes (lanes
and roads, "the left-hand footway twenty metres ahead of the ego", "15m behind the ego", "20 meter behind of ego in
same lane", "four-zero metres ahead in its lane", "across the eastbound lane", "across westbound lane near east
gate", "Campus Drive north of crossroads", "the north side of Main Street", "the other side of road", "x 30 y -20",
"x minus four zero, y minus one decimal seven five", "x = 900"). They carry clock times in several forms ("18:30",
"half past six in the evening", "one-niner-three-zero local", "golden hour", "late-afternoon glow", "evening time",
"morning", "0630", "23:00", "27:15", "night"), weather with strengths (moderate fog, heavy rain, hevy snow, light
fog, thick fog turned off, heavy rain eased, "marginal", "nothing silly", "wet-weather fixture", "winter
conditions", harmattan haze, a sandstorm and a tornado), numbers in words and digits with units ("seven metres per
second", "3 m/s", "8 meters per second", "200 km/h", "5m", "10 metr", "two metres apart", "1.5m apart", "9 cones,
3x3", "six", "fuor", "sicx"), questions (which must change nothing: their checks hold the scene unchanged and their
reference answers with a search) and behaviours over time: speeds up and down, a stop at four and at five seconds,
lane changes after three, four and five seconds, a right turn at the junction, a red light the ego waits at before
the west crosswalk, a lead car braking as the ego closes to ten or fifteen metres, a cut-in, walkers crossing at the
west and north crosswalks and stepping out as the ego approaches, cars, a bus and a walker driving or walking to the
east gate, the lot B entrance, the Library and the bus stop, circles in lot B, backing up. The erroneous grade
carries realistic typos, autocorrect slips and run-together words ("distnace", "fountian", "lihgts", "stop sing",
"bustop", "neerest", "spead", "benchs", "perhpas", "reqeust thre cones", "crosswlak", "pedestrain", "benhc", "conse",
"buss", "east gat", "biycles", "track" for truck, "anoda", "remvoe the hydrnat", "svu", "stop sigh", "trun the bench
aroudn", "chnage lanes", "cirlces", "3 metres eats", "bolards", "barirers", "sdie", "wether", "Lighitng", "colur
blu", "grene", "raim", "expossure", "dreem").

Counts: 7 tasks x 4 grades, every cell 13 cases (364 in all). 44 cases are multi-turn (29 with a planned earlier turn
that has calls), with references back: "it", "that car", "that traffic", "that obstruction", "that person", "the
people", "she", "those cones", "same again in lot B", "now the same in lot B", "one more of the same at the main
gate", "one more such, but green", "anoda two for the same place", "ring it with cones", "still so bare"; and
corrections ("Sory, I made mistake. Put it near Libary", "The designer hates it. Back to green", "No, not so bright.
Something more calm", "No, I want that it was yelow"). 24 are compound (the reference makes two calls or more; 22 of
them put two requests in one prompt), and 28 (7.7 %) are impossible, tagged `impossible`, where the right outcome is
a refusal that changes nothing: a control tower, a train station, a petrol station, a playground; a hot tub, a
football goal, a swing set, a gazebo; the Student Union and Library buildings, Campus Drive, the ego; the SUV on the
Student Union's roof, the bench inside the Engineering Hall, on the moon or at x = 900; the ego flying or at 200
km/h, a hydrant doing shuttle runs, a bench driving itself; agility ladders, flower pots, hay bales, balloons; a
sandstorm, a glass frontage, a tornado, 27:15.

Every case judges the outcome, never the calls: a main check and an `unchanged_except` guard, with `alternatives`
where a request has two fair readings (a new speed on the lane behaviour or by a change-of-speed manoeuvre, backing
up by a shift or a reverse manoeuvre, braking by a stop or a slow-down, a crossing as a behaviour or a manoeuvre, a
cut-in by any kind of vehicle, setting a parked vehicle off by any driving behaviour or manoeuvre, "a leafier
setting" by any of the four trees, "a pattern", "some sort of shape" or "anyhow" as a line, a ring or a cluster, more
people "on Main Street" by either side, low visibility by fog or by heavy rain or snow, "dark", "moodier" and
"dimmed" by the clock or the exposure (or the weather), "brighter" by exposure or the street lights, "cold" by snow
or fog, easing the rain by lighter rain or clear skies, street lights at 23:00 switched on or left to light at
night), and a `reference` plan that passes; a plan that does nothing fails every case, questions and impossible ones
included (its empty plan is accepted and answers nothing), whether or not its planned earlier turns were done.
Simple wrong plans (another place, another count, another colour or weather, another asset, a call left out) fail
all but the readings the wording leaves open. Every id and coordinate was checked against worlds/campus.py and the
search Workers' answers on the shipped campus. The suite was written from the campus world, the asset catalog, the
Worker tools' argument schemas and the eval checks only, by someone who had not read the planners, their lexicons,
their prompt examples or any other suite's cases (practice29's and practice30's sources were read for their format
only).
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
    reaches,
    relative,
    remove,
    says,
    stops_before,
    turn,
    weather,
    xy,
)

TAG = "practice31"
S = Suite(TAG)
case = S.case
impossible = S.impossible
ask = S.ask

# --- The campus as it ships: ids and places the cases name (checked against worlds/campus.py) -------------
SUV = "suv_1"  # the middle car of the row of three in lot B, (23, -42), facing north
CAR_W = "passenger_car_1"  # the west end of that row, (19, -42)
CAR_E = "passenger_car_2"  # the east end of that row, (27, -42)
LOT_B_ROW = [CAR_W, SUV, CAR_E]
BENCH = "bench_1"  # south footway just east of the bus stop, (-26, -6.9), facing west
BIN = "trash_bin_1"  # south footway just west of the bus stop, (-33.5, -5.5)
HYDRANT = "fire_hydrant_1"  # north footway east of the crossroads, (16, 5.5)
STOP = "stop_sign_1"  # south footway just west of the west crosswalk, (-13.5, -5.5)
LIGHT_SW = "traffic_light_1"  # south-west corner of the crossroads, (-9.5, -6.2)
LIGHT_NE = "traffic_light_2"  # north-east corner, (9.5, 6.2)
TREE_LIBRARY = "tree_1"  # between the bus stop and the Library, (-26, -12)
TREE_FOUNTAIN_NW = "tree_2"  # north-west of the fountain, (70, 45), 7.1 m from it
TREE_FOUNTAIN_SE = "tree_3"  # south-east of the fountain, (85, 25), 18 m from it
TREE_LOT_A = "tree_4"  # north of lot A, (-85, 50)
TREES = [TREE_LIBRARY, TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE, TREE_LOT_A]
NORTH_LAMPS = [f"street_light_{n}" for n in (1, 3, 5, 7, 9, 11)]  # y = 5.8; x = -80, -50, -25, 25, 50, 80
SOUTH_LAMPS = [f"street_light_{n}" for n in (2, 4, 6, 8, 10, 12)]  # y = -5.8; x = -68, -38, -13, 37, 62, 92
LAMP_BY_BENCH = "street_light_4"  # (-38, -5.8), 12.1 m from the bench, the nearest to it
LAMP_BY_LIBRARY = "street_light_4"  # also the nearest to the Library entrance, 9.7 m
LAMP_ACROSS_FROM_BENCH = "street_light_5"  # (-25, 5.8), straight north of the bench across Main Street
LAMP_CROSSWALK = "street_light_6"  # (-13, -5.8), beside the stop sign at the west crosswalk
EAST = "main_eastbound"  # y = -1.75; the ego drives it at 5 m/s from x = -60
WEST = "main_westbound"  # y = 1.75
NORTH = "campus_northbound"  # x = 1.75
SOUTH = "campus_southbound"  # x = -1.75
ROBOT = "ackermann_robot"
TRAFFIC = ["passenger_car", "suv", "bus", "truck", "motorcycle", ROBOT]
CARS = ["passenger_car", "suv"]
CORDON = ["traffic_cone", "road_barrier", "bollard"]
WORKS = ["traffic_cone", "road_barrier", "construction_sign", "bollard"]
SIGNS = ["pedestrian_sign", "construction_sign", "stop_sign", "parking_sign"]
PEOPLE = ["pedestrian", "bicycle"]
FURNITURE = ["bench", "trash_bin", "tree", "bollard"]
BRIGHT = ["red", "green", "blue", "yellow", "orange", "purple", "pink", "cyan", "teal", "gold"]
MUTED = ["white", "black", "grey", "silver", "brown", "beige", "navy", "maroon"]
ALL_COLOURS = [*BRIGHT, *MUTED]
# What comes first when the cases add one: the next free number of each category.
NEW_CAR = "passenger_car_3"
NEW_WALKER = "pedestrian_1"
NEW_TRUCK = "truck_1"
NEW_BUS = "bus_1"
NEW_BENCH = "bench_2"
NEW_SIGN = "construction_sign_1"
RUBBLE = "cement_rubble_1"

# --- Voices (each case names its own in `notes`) -----------------------------------------------------------
PILOT = (
    "air-traffic controller / pilot on the radio: 'affirmative', 'negative', 'wilco', 'say again', phonetic "
    "alphabet ('lot Bravo', 'Sierra Uniform Victor'), 'hold short', headings in degrees, digits read singly, 'niner'"
)
DIRECTOR = (
    "theatre stage director: 'stage left', 'upstage', 'blocking', 'places', 'strike', 'on cue', 'extras', "
    "'set dressing', 'lighting cue', 'the mark'"
)
RUSSIAN = (
    "Russian speaker writing English: dropped articles, 'please to make', unusual word order, aspect and tense "
    "slips ('I want it was'), 'how much cars', 'is need'"
)
NAIJA = (
    "Nigerian-English speaker: 'abeg', 'on the light' / 'off the fog', 'dey', 'oya', 'small small', 'carry am go', "
    "'motor' for car, 'for' as a general preposition, 'no wahala'"
)
REALTOR = (
    "estate agent / realtor: hyperbole, 'charming', 'leafy', 'kerb appeal', 'a stone's throw from', "
    "'sought-after', 'viewings', 'the listing photos'"
)
COACH = (
    "football / PE coach: drills, 'set out cones', 'ladders', 'channels', 'the touchline', 'in pairs', "
    "'the lads', 'slalom', 'warm-up'"
)
PARENT = (
    "tired parent typing one-handed on a phone: lower case, autocorrect slips, half sentences, 'k', 'thx', "
    "'pls', 'the kid'"
)
HEDGER = (
    "hesitant over-thinker: hedges and qualifies ('I suppose it might perhaps be nice if... unless that's "
    "silly'), corrects themself mid-sentence ('or left - no, right')"
)


# --- Helpers ----------------------------------------------------------------------------------------------
def new_speed(actor: str, lo: float, hi: float) -> list[list[Json]]:
    """Fair readings of a new speed: the lane behaviour at that speed, or a change-of-speed manoeuvre."""
    return [
        [does("drive_lane", asset=actor, speed_min=lo, speed_max=hi)],
        [event_played(actor, "change_speed", 3.0)],
    ]


def slows_down(actor: str, seconds: float = 20.0) -> list[list[Json]]:
    """Fair readings of braking: a stop, or a change of speed, started within `seconds`."""
    return [[event_played(actor, "stop", seconds)], [event_played(actor, "change_speed", seconds)]]


def backs_up(asset: str, lo: float, hi: float) -> list[list[Json]]:
    """Fair readings of backing up: a shift backwards, or a reverse manoeuvre."""
    return [[moved(asset, lo, hi, "backward")], [event_played(asset, "reverse", 3.0)]]


def walks_over(lane: str | None = None, seconds: float = 10.0) -> list[list[Json]]:
    """Fair readings of a walker going over the road: a crossing or jaywalk behaviour, or a crossing manoeuvre."""
    return [
        [does(["cross_road", "jaywalk"], "pedestrian", crosses_lane=lane)],
        [event_played("pedestrian", "cross_road", seconds)],
    ]


def gets_going(asset: str) -> list[list[Json]]:
    """Fair readings of setting a parked vehicle off: a driving behaviour of any kind, or a manoeuvre."""
    return [
        [does(["drive_lane", "follow_path", "circle"], asset=asset)],
        [event_played(asset, "keep_lane", 3.0)],
        [event_played(asset, "follow_route", 3.0)],
        [event_played(asset, "change_speed", 3.0)],
    ]


def some_in_lane(lane: str, category: str | list[str]) -> Json:
    """At least one of the added or changed assets of these categories stands in `lane` (a block across it)."""
    return {"kind": "in_lane", "category": category, "lane": lane, "require_all": False}


def darker() -> list[list[Json]]:
    """Fair readings of 'darker': a clock time from early evening to before dawn, or a lower exposure."""
    return [[env(time_from="17:30", time_to="06:00")], [env(exposure_max=0.85)]]


def any_shape(category: str | list[str], least: int, tolerance: float = 1.0) -> list[list[Json]]:
    """Fair readings of 'a pattern' or 'some sort of shape': a line, a ring or a tight cluster."""
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


# The ego (eastbound at 5 m/s from x = -60) halts short of the west crosswalk: its front never passes x = -13.
EGO_HALTS_AT_WEST_CROSSWALK = stops_before(EGO, -13.0, -1.75, 20.0)


# --- Earlier turns several cases start from ---------------------------------------------------------------
LEAD_CAR_30 = turn(
    "Traffic: one car, three-zero metres ahead of the ego in its lane, two metres per second.",
    add("passenger_car", where=ahead_of(EGO, 30), behaviour=drive(2.0, EAST)),
)
LEAD_CAR_45_PARKED = turn(
    "Place a parked car in the ego's lane, four-five metres ahead.", add("passenger_car", where=ahead_of(EGO, 45))
)
RUBBLE_25 = turn("Put a heap of broken concrete in the ego's lane 25 m ahead.", add("cement_rubble", where=ahead_of(EGO, 25)))
RUBBLE_LOT_B = turn("Put some rubble in the middle of parking lot B.", add("cement_rubble", where=loc("at", "parking lot B")))
HEAVY_RAIN = turn("Heavy rain, please.", weather("rain", 0.9))
THICK_FOG = turn("Make it thick fog.", weather("fog", 0.9))
CONES_3_LIBRARY = turn("Three cones outside the Library entrance.", add("traffic_cone", 3, loc("at", "Library entrance")))
BUS_EAST_GATE = turn("Put a bus at the east gate.", add("bus", where=loc("at", "east gate")))
BENCH_AT_LIBRARY = turn("Please to add bench near library.", add("bench", where=loc("at", "Library entrance")))
FOUR_LADS_FOUNTAIN = turn(
    "Four lads standing by the fountain for the warm-up.", add("pedestrian", 4, loc("next_to", "fountain"))
)
WALKER_FOUNTAIN = turn("Put one person for the fountain side.", add("pedestrian", where=loc("next_to", "fountain")))


# --- Search: questions change nothing; the answer names what was asked for ---------------------------------
SEARCH_CASES: list[Json] = [
    # direct
    ask("direct", "hydrant_position", PILOT, "Tower, say position of the fire hydrant, coordinates please.",
        [HYDRANT, "16", "5.5"], [find(category="fire_hydrant")]),
    ask("direct", "signals_rigged", DIRECTOR, "How many traffic lights have we got rigged on this set?",
        [LIGHT_SW, LIGHT_NE], [find(category="traffic_light")]),
    ask("direct", "how_much_cars_b", RUSSIAN, "How much cars is standing in parking B?", [CAR_W, SUV, CAR_E],
        [find(category="vehicles", near="parking lot B", within=1)]),
    ask("direct", "time_for_scene", NAIJA, "Abeg, what time e be for the scene now?", ["12:00"], [environment()]),
    ask("direct", "library_to_bus_stop", REALTOR,
        "How far is the Library entrance from the bus stop, in metres? Buyers will ask.", ["14.5"],
        [measure("Library entrance", "bus stop")]),
    ask("direct", "campus_drive_limit", COACH, "What's the speed limit on Campus Drive?", ["8"],
        [lanes(road="Campus Drive")]),
    ask("direct", "where_suv", PARENT, "where is the suv", [SUV, "23", "-42"], [find(category="suv")]),
    ask("direct", "lane_width", HEDGER,
        "I was wondering, if it's not too much trouble, how wide the lanes on Main Street actually are?", ["3.5"],
        [lanes(road="Main Street")]),
    ask("direct", "ego_to_east_gate", PARENT, "how far r we from the east gate", ["160"],
        [measure("east gate")]),
    ask("direct", "main_street_lanes", HEDGER, "Sorry, this may be obvious, but which lanes does Main Street have?",
        [EAST, WEST],
        [lanes(road="Main Street")]),
    ask("direct", "heaviest_vehicle", HEDGER, "I hope this isn't a strange question - which vehicle is the heaviest?",
        [SUV, "2100"],
        [find(category="vehicles", most="heaviest")]),
    ask("direct", "cones_i_set_out", COACH, "How many cones have I got out now?", ["6"],
        [find(category="traffic_cone")],
        setup=[turn("Set out six cones in lot A.", add("traffic_cone", 6, loc("at", "parking lot A")), planned=True)]),
    impossible("search", "direct", "control_tower", PILOT, "Tower, say distance from the ego to the control tower.",
               [measure("control tower")]),
    # indirect
    ask("indirect", "taxi_north", PILOT,
        "Planning my taxi route: which lane takes me north on Campus Drive?", [NORTH], [lanes(road="Campus Drive")]),
    ask("indirect", "light_the_bench", DIRECTOR,
        "I want a practical on the bench for the bus-stop scene. Which lamp post stands nearest to it?",
        [LAMP_BY_BENCH, "12.1"], [find(category="street_light", nearest_to=BENCH)]),
    ask("indirect", "shade_by_fountain", RUSSIAN, "I want sit in shadow near fountain. Which tree is most close to it?",
        [TREE_FOUNTAIN_NW, "7.1"], [find(category="tree", nearest_to="fountain")]),
    ask("indirect", "day_or_night", NAIJA,
        "My oga wan know whether na day or night for the scene now, abeg check am.", ["day"], [environment()]),
    ask("indirect", "stones_throw", REALTOR,
        "For the brochure I'd love to say the Student Union is a stone's throw from the car park. How far is it, "
        "honestly?", ["22.4"], [measure("Student Union entrance", "parking lot B")]),
    ask("indirect", "gate_to_gate_run", COACH,
        "I'm planning a warm-up jog from the main gate to the east gate. How long a run is that?", ["200"],
        [measure("main gate", "east gate")]),
    ask("indirect", "suv_colour_for_kid", PARENT, "kid wants to know what colour the suv is", ["default"],
        [properties(asset=SUV)]),
    case("search", "indirect", "lane_by_the_bin", HEDGER,
         "I might move the bin later, I'm not sure yet, but first... could you tell me which lane is closest to it? "
         "Only if it's easy.", [says(all_of=[EAST], none_of=[WEST, NORTH, SOUTH]), only()], [lanes(near=BIN)]),
    ask("indirect", "separation_to_traffic", PILOT, "Say separation between the ego and the traffic ahead.", ["30"],
        [measure(NEW_CAR)], setup=[LEAD_CAR_30]),
    ask("indirect", "our_car_speed", RUSSIAN, "Before I will change anything, tell me how fast is going our car now.",
        ["5"], [properties(asset=EGO)]),
    ask("indirect", "nearer_gate", NAIJA,
        "I wan drive out from the campus sharp sharp. Which gate dey nearer the ego?", ["main gate", "40"],
        [landmarks(query="gate", nearest_to=EGO)]),
    ask("indirect", "fountain_and_weather", DIRECTOR,
        "Before we block the courtyard scene I need two things: how far the fountain is from the JTEKT entrance, "
        "and what the weather is set to.", ["45.1", "clear"],
        [measure("fountain", "JTEKT building entrance"), environment()]),
    impossible("search", "indirect", "train_station", REALTOR,
               "Buyers always ask about commuting: how far is the car park from the train station?",
               [measure("train station", "parking lot B")]),
    # vague
    ask("vague", "traffic_near_bus_stop", PILOT, "Tower, say what's in the vicinity of the bus stop.", [BENCH, BIN],
        [find(near="bus stop", within=10)]),
    ask("vague", "locations_on_set", DIRECTOR, "Walk me through the locations we've got on this set.",
        ["fountain", "east gate", "bus stop"], [landmarks()]),
    ask("vague", "near_fountain", RUSSIAN, "What is there near fountain?", [TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE],
        [find(near="fountain", within=20)]),
    ask("vague", "how_weather_dey", NAIJA, "How the weather dey?", ["clear"], [environment()]),
    ask("vague", "parking_situation", REALTOR, "What's the parking situation like on this campus?",
        ["parking lot A", "parking lot B"], [landmarks(query="parking")]),
    ask("vague", "round_north_crossing", COACH, "What's round the north crossing?", [LIGHT_NE],
        [find(near="north crosswalk", within=12)]),
    ask("vague", "whats_by_library", PARENT, "whats by the library", [LAMP_BY_LIBRARY, BIN],
        [find(near="Library entrance", within=15)]),
    ask("vague", "ego_up_to", HEDGER,
        "I'm not entirely sure what I'm asking, really... what is the ego up to at the moment?", ["drive_lane", "5"],
        [properties(asset=EGO)]),
    ask("vague", "conditions", HEDGER,
        "I don't suppose you could tell me how things are looking in there? Weather-wise, time-wise... whatever's "
        "relevant, really.", ["clear", "12:00"], [environment()]),
    ask("vague", "where_it_is_now", RUSSIAN, "And where it is now?", [NEW_BUS], [find(category="bus")],
        setup=[turn("Please to add bus near east gate.", add("bus", where=loc("at", "east gate")), planned=True)]),
    ask("vague", "whos_in_car_park", DIRECTOR, "Who's parked up in the car park?", [CAR_W, SUV, CAR_E],
        [find(category="vehicles", near="parking lot B", within=1)]),
    ask("vague", "still_raining", NAIJA, "E still dey rain?", ["rain"], [environment()],
        setup=[turn("Abeg make rain fall well well.", weather("rain", 0.9), planned=True)]),
    impossible("search", "vague", "petrol_station", HEDGER,
               "Maybe... how far is the, um, the petrol station from here? If there is one?",
               [measure("petrol station")]),
    # erroneous
    ask("erroneous", "fountian_distance", PILOT, "Tower, say distnace from the ego to the fountian, over.", ["141.3"],
        [measure("fountain")]),
    ask("erroneous", "lihgts_on_stret", DIRECTOR, "How mnay street lihgts have we got along Main Stret?",
        ["12"], [find(category="street_light", lane="Main Street")]),
    ask("erroneous", "where_stop_sing", RUSSIAN, "Were is stop sing?", [STOP, "-13.5"], [find(category="stop_sign")]),
    ask("erroneous", "bustop_distance", NAIJA, "Abeg hw far the bustop dey from the ego?", ["30.2"],
        [measure("bus stop")]),
    ask("erroneous", "neerest_tree_libary", REALTOR, "Whats the neerest tree to the Libary entrence?", [TREE_LIBRARY, "15.3"],
        [find(category="tree", nearest_to="Library entrance")]),
    ask("erroneous", "spead_limit_main", COACH, "whats the spead limit on main st", ["8"], [lanes(road="Main Street")]),
    ask("erroneous", "benchs_count", PARENT, "hiw many benchs r there", [BENCH], [find(category="bench")]),
    ask("erroneous", "which_way_ego_faces", HEDGER,
        "I wonder, perhpas, whcih way the ego is facing? Sorry, probably a silly question.", ["0 deg", EAST],
        [properties(asset=EGO)]),
    ask("erroneous", "streetlights_wether", PILOT, "Confirm wether the streetlihgts are on, over.", ["off"],
        [environment()]),
    ask("erroneous", "hydrant_to_bench", PARENT, "how far betwen the hydrant n the bench", ["43.8"],
        [measure(HYDRANT, BENCH)]),
    ask("erroneous", "people_dey_bustop", NAIJA, "how many peple dey for the bus stop now?", ["3"],
        [find(category="pedestrian", near="bus stop", within=12)],
        setup=[turn("Abeg put three people for the bus stop.", add("pedestrian", 3, loc("on_sidewalk", "bus stop")),
                    planned=True)]),
    ask("erroneous", "car_park_closer_jtek", COACH, "which car park is closer to the jtek building", ["parking lot B"],
        [landmarks(query="parking lot", nearest_to="JTEKT building entrance")]),
    impossible("search", "erroneous", "playgrond", PARENT, "how far is the playgrond from the car",
               [measure("playground")]),
]


# --- Addition: new things where they were asked for, and nothing else touched ------------------------------
ADDITION_CASES: list[Json] = [
    # direct
    case("addition", "direct", "bus_east_gate", PILOT, "Request one bus positioned at the east gate, over.",
         [delta("bus", 1, 1), near("east gate", 15, "bus"), only("bus")], [add("bus", where=loc("at", "east gate"))]),
    case("addition", "direct", "three_extras_library", DIRECTOR,
         "Bring on three extras - pedestrians - at the Library entrance.",
         [delta("pedestrian", 3, 3), near("Library entrance", 10, "pedestrian", min_count=3), only("pedestrian")],
         [add("pedestrian", 3, loc("at", "Library entrance"))]),
    case("addition", "direct", "bench_by_fountain", RUSSIAN, "Please to add one bench near fountain.",
         [delta("bench", 1, 1), near("fountain", 10, "bench"), only("bench")],
         [add("bench", where=loc("next_to", "fountain"))]),
    case("addition", "direct", "two_okadas_lot_a", NAIJA, "Abeg add two motorcycles for lot A.",
         [delta("motorcycle", 2, 2), near("parking lot A", 2, "motorcycle", min_count=2), only("motorcycle")],
         [add("motorcycle", 2, loc("at", "parking lot A"))]),
    case("addition", "direct", "tree_student_union", REALTOR,
         "Add a tree beside the Student Union entrance - leafy sells.",
         [delta("tree", 1, 1), near("Student Union entrance", 12, "tree"), only("tree")],
         [add("tree", where=loc("next_to", "Student Union entrance"))]),
    case("addition", "direct", "bin_engineering", COACH,
         "Stick a bin by the Engineering Hall entrance for the empty water bottles.",
         [delta("trash_bin", 1, 1), near("Engineering Hall entrance", 8, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("at", "Engineering Hall entrance"))]),
    case("addition", "direct", "truck_behind_ego", PARENT, "add a truck behind the ego pls 15m",
         [delta("truck", 1, 1), in_lane(EAST, "truck"), near(None, 5, "truck", point=(-75.0, -1.75)), only("truck")],
         [add("truck", where=ahead_of(EGO, -15))]),
    case("addition", "direct", "bicycle_bus_stop", HEDGER,
         "Could we perhaps have, um, a bicycle at the bus stop? Just the one, I think.",
         [delta("bicycle", 1, 1), near("bus stop", 8, "bicycle"), only("bicycle")],
         [add("bicycle", where=loc("at", "bus stop"))]),
    case("addition", "direct", "walker_left_footway", HEDGER,
         "Could there be a pedestrian on the left-hand footway, twenty metres ahead of the ego? Or is that too "
         "close... no, twenty's fine.",
         [delta("pedestrian", 1, 1), near(None, 4, "pedestrian", point=(-40.0, 5.5)), on(["sidewalk"], "pedestrian"),
          only("pedestrian")],
         [add("pedestrian", where=ahead_of(EGO, 20, side="left"))]),
    case("addition", "direct", "bench_and_bin_jtekt", DIRECTOR,
         "Set dressing for the JTEKT entrance: one bench and one bin.",
         [delta("bench", 1, 1), delta("trash_bin", 1, 1), near("JTEKT building entrance", 10, "bench"),
          near("JTEKT building entrance", 10, "trash_bin"), only("bench", "trash_bin")],
         [add("bench", where=loc("at", "JTEKT building entrance")),
          add("trash_bin", where=loc("next_to", "JTEKT building entrance"))]),
    case("addition", "direct", "four_cones_engineering", REALTOR,
         "Add four cones in front of the Engineering Hall entrance for the open-day parking.",
         [delta("traffic_cone", 4, 4), near("Engineering Hall entrance", 15, "traffic_cone", min_count=4),
          only("traffic_cone")],
         [add("traffic_cone", 4, loc("in_front_of", "Engineering Hall entrance"))]),
    case("addition", "direct", "same_again_lot_b", COACH, "Same again in lot B.",
         [delta("traffic_cone", 4, 4), near("parking lot B", 2, "traffic_cone", scope="added", min_count=4),
          only("traffic_cone")],
         [add("traffic_cone", 4, loc("at", "parking lot B"))],
         setup=[turn("Set out four cones in lot A.", add("traffic_cone", 4, loc("at", "parking lot A")), planned=True)]),
    impossible("addition", "direct", "hot_tub_fountain", REALTOR,
               "Add a hot tub beside the fountain - buyers adore a hot tub.",
               [add("hot tub", where=loc("next_to", "fountain"))]),
    # indirect
    case("addition", "indirect", "lead_vehicle_forty", PILOT,
         "We need traffic for the ego to follow: one vehicle, about four-zero metres ahead in its lane.",
         [delta(TRAFFIC, 1, 1), in_lane(EAST, TRAFFIC), near(None, 8, TRAFFIC, point=(-20.0, -1.75)), only(*TRAFFIC)],
         [add("passenger_car", where=ahead_of(EGO, 40))]),
    case("addition", "indirect", "people_waiting_bus", DIRECTOR,
         "The bus-stop scene needs people waiting for a bus that never comes. Give me a small crowd.",
         [delta("pedestrian", 2, None), near("bus stop", 12, "pedestrian", min_count=2), only("pedestrian")],
         [add("pedestrian", 4, loc("on_sidewalk", "bus stop"))]),
    case("addition", "indirect", "nowhere_to_sit_library", RUSSIAN,
         "Students from library want to sit outside, but there is nowhere to sit.",
         [delta("bench", 1, None), near("Library entrance", 12, "bench"), only("bench")],
         [add("bench", where=loc("at", "Library entrance"))]),
    case("addition", "indirect", "union_no_shade", NAIJA,
         "The Student Union side dey hot well well, no shade at all for there.",
         [delta("tree", 1, None), near("Student Union entrance", 15, "tree"), only("tree")],
         [add("tree", where=loc("next_to", "Student Union entrance"))]),
    case("addition", "indirect", "engineering_kerb_appeal", REALTOR,
         "The Engineering Hall frontage has zero kerb appeal. It's crying out for a bit of greenery.",
         [delta("tree", 1, None), near("Engineering Hall entrance", 15, "tree"), only("tree")],
         [add("tree", where=loc("next_to", "Engineering Hall entrance"))]),
    case("addition", "indirect", "bottles_at_fountain", COACH,
         "The lads leave their bottles all over the place round the fountain. Nowhere to chuck them.",
         [delta("trash_bin", 1, None), near("fountain", 12, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("next_to", "fountain"))]),
    case("addition", "indirect", "nappies_library", PARENT, "nowhere to put the nappies by the library doors ugh",
         [delta("trash_bin", 1, None), near("Library entrance", 10, "trash_bin"), only("trash_bin")],
         [add("trash_bin", where=loc("at", "Library entrance"))]),
    case("addition", "indirect", "unannounced_crosswalk", HEDGER,
         "I keep thinking the west crosswalk feels a bit... unannounced? Drivers might not realise it's there. "
         "Something to warn them, maybe, unless that's overkill.",
         [delta(["pedestrian_sign", "stop_sign"], 1, None), near("west crosswalk", 10, ["pedestrian_sign", "stop_sign"]),
          only("pedestrian_sign", "stop_sign")],
         [add("pedestrian_sign", where=loc("at", "west crosswalk"))]),
    case("addition", "indirect", "northbound_traffic", PILOT,
         "The scenario needs one vehicle moving northbound on Campus Drive.",
         [delta(TRAFFIC, 1, 1), does(["drive_lane", "follow_path"], TRAFFIC), near(NORTH, 3, TRAFFIC), only(*TRAFFIC)],
         [add("passenger_car", where=loc("in_lane", "north crosswalk", lane=NORTH), behaviour=drive(6.0, NORTH))]),
    case("addition", "indirect", "someone_on_it", DIRECTOR, "Now someone to sit on it. Well - next to it.",
         [delta("pedestrian", 1, 1), near(NEW_BENCH, 4, "pedestrian"), only("pedestrian")],
         [add("pedestrian", where=loc("next_to", NEW_BENCH))],
         setup=[turn("Put a bench by the fountain.", add("bench", where=loc("next_to", "fountain")), planned=True)]),
    case("addition", "indirect", "repairs_at_jtekt", RUSSIAN,
         "Is needed for repairs near JTEKT entrance: one barrier and one sign of construction.",
         [delta("road_barrier", 1, 1), delta("construction_sign", 1, 1),
          near("JTEKT building entrance", 12, ["road_barrier", "construction_sign"], min_count=2),
          only("road_barrier", "construction_sign")],
         [add("road_barrier", where=loc("at", "JTEKT building entrance")),
          add("construction_sign", where=loc("next_to", "JTEKT building entrance"))]),
    case("addition", "indirect", "two_more_motors", NAIJA,
         "Lot B dey look empty for the photo; bring two more motors come.",
         [delta(CARS, 2, 2), near("parking lot B", 2, CARS, scope="added", min_count=2), only(*CARS)],
         [add("passenger_car", 2, loc("at", "parking lot B"))]),
    impossible("addition", "indirect", "shooting_goal", COACH,
               "We need a full-size goal at the lot A end for shooting practice.",
               [add("football goal", where=loc("at", "parking lot A"))]),
    # vague
    case("addition", "vague", "some_traffic", PILOT, "Tower, the field looks dead. Add some traffic.",
         [delta(TRAFFIC, 1, None), does(["drive_lane", "follow_path", "circle"], TRAFFIC), only(*TRAFFIC)],
         [add("passenger_car", 2, loc("in_lane", "east gate", lane=WEST), behaviour=drive(6.0, WEST))]),
    case("addition", "vague", "dress_fountain", DIRECTOR, "Dress the set around the fountain a bit.",
         [delta([*FURNITURE, *PEOPLE], 1, None), near("fountain", 15, [*FURNITURE, *PEOPLE]),
          only(*FURNITURE, *PEOPLE)],
         [add("bench", 2, loc("next_to", "fountain"))]),
    case("addition", "vague", "more_people_street", REALTOR,
         "Main Street needs more footfall. It's meant to be a buzzing, vibrant neighbourhood.",
         [delta("pedestrian", 1, None), only("pedestrian")], [add("pedestrian", 3, loc("on_sidewalk", "bus stop"))],
         alternatives=[[near(EAST, 6, "pedestrian")], [near(WEST, 6, "pedestrian")]]),
    case("addition", "vague", "bus_stop_busy", NAIJA, "Make the bus stop dey busy small.",
         [delta("pedestrian", 2, None), near("bus stop", 12, "pedestrian", min_count=2), only("pedestrian")],
         [add("pedestrian", 3, loc("on_sidewalk", "bus stop"))]),
    case("addition", "vague", "lot_a_sought_after", REALTOR,
         "Give lot A that sought-after, well-used look. At the moment it's a desert.",
         [delta(TRAFFIC, 2, None), near("parking lot A", 2, TRAFFIC, min_count=2), only(*TRAFFIC)],
         [add("passenger_car", 3, loc("at", "parking lot A"))]),
    case("addition", "vague", "warm_up_cones", COACH, "Put a few cones out in lot A for the warm-up.",
         [delta("traffic_cone", 3, None), near("parking lot A", 2, "traffic_cone", min_count=3), only("traffic_cone")],
         [add("traffic_cone", 5, loc("at", "parking lot A"))]),
    case("addition", "vague", "more_trees", PARENT, "more trees pls its still so bare",
         [delta("tree", 1, None), only("tree")], [add("tree", 2, loc("next_to", "Engineering Hall entrance"))],
         setup=[turn("add a tree by the fountain", add("tree", where=loc("next_to", "fountain")), planned=True)]),
    case("addition", "vague", "life_at_library", HEDGER,
         "Perhaps the Library could do with... something? A bit of life? People, maybe. Or - no, yes, people.",
         [delta("pedestrian", 1, None), near("Library entrance", 15, "pedestrian"), only("pedestrian")],
         [add("pedestrian", 3, loc("at", "Library entrance"))]),
    case("addition", "vague", "one_more_main_gate", PILOT, "Affirmative. One more of the same at the main gate.",
         [delta("bus", 1, 1), near("main gate", 15, "bus", scope="added"), only("bus")],
         [add("bus", where=loc("at", "main gate"))],
         setup=[turn("Request one bus at the east gate.", add("bus", where=loc("at", "east gate")), planned=True)]),
    case("addition", "vague", "people_jtekt_doors", PARENT, "few people by the jtekt doors pls",
         [delta("pedestrian", 1, None), near("JTEKT building entrance", 12, "pedestrian"), only("pedestrian")],
         [add("pedestrian", 3, loc("at", "JTEKT building entrance"))]),
    case("addition", "vague", "one_more_green", RUSSIAN, "And one more such, but green.",
         [delta("bench", 1, 1), looks("green", "bench", scope="added"), near("Library entrance", 12, "bench", scope="added"),
          only("bench")],
         [add("bench", where=loc("at", "Library entrance"), colour="green")], setup=[BENCH_AT_LIBRARY]),
    case("addition", "vague", "security_lot_b_entrance", NAIJA,
         "Put small security for the lot B entrance - some bollards and one sign.",
         [delta("bollard", 2, None), delta(SIGNS, 1, 1), near("parking lot B entrance", 10, "bollard", min_count=2),
          near("parking lot B entrance", 10, SIGNS), only("bollard", *SIGNS)],
         [add("bollard", 2, loc("at", "parking lot B entrance")),
          add("parking_sign", where=loc("next_to", "parking lot B entrance"))]),
    impossible("addition", "vague", "swing_set", PARENT, "add a swing set by the fountain for the kid",
               [add("swing set", where=loc("next_to", "fountain"))]),
    # erroneous
    case("addition", "erroneous", "thre_cones_crosswlak", PILOT, "Tower, reqeust thre cones at the north crosswlak.",
         [delta("traffic_cone", 3, 3), near("north crosswalk", 10, "traffic_cone", min_count=3), only("traffic_cone")],
         [add("traffic_cone", 3, loc("at", "north crosswalk"))]),
    case("addition", "erroneous", "pedestrain_bus_stpo", DIRECTOR, "On cue, bring on a pedestrain at the bus stpo.",
         [delta("pedestrian", 1, 1), near("bus stop", 8, "pedestrian"), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "bus stop"))]),
    case("addition", "erroneous", "tre_enginering", RUSSIAN, "Please to add one tre near Enginering Hall.",
         [delta("tree", 1, 1), near("Engineering Hall entrance", 15, "tree"), only("tree")],
         [add("tree", where=loc("next_to", "Engineering Hall entrance"))]),
    case("addition", "erroneous", "hydrent_libary", HEDGER, "Perhaps one fire hydrent by the Libary? Just the one.",
         [delta("fire_hydrant", 1, 1), near("Library entrance", 12, "fire_hydrant"), only("fire_hydrant")],
         [add("fire_hydrant", where=loc("at", "Library entrance"))]),
    case("addition", "erroneous", "benhc_fountian", REALTOR, "Add a charming benhc by the fountian.",
         [delta("bench", 1, 1), near("fountain", 10, "bench"), only("bench")],
         [add("bench", where=loc("next_to", "fountain"))]),
    case("addition", "erroneous", "six_conse_lot_a", COACH, "set out 6 conse in lot a",
         [delta("traffic_cone", 6, 6), near("parking lot A", 2, "traffic_cone", min_count=6), only("traffic_cone")],
         [add("traffic_cone", 6, loc("at", "parking lot A"))]),
    case("addition", "erroneous", "buss_east_gat", PARENT, "add a buss at the east gat thx",
         [delta("bus", 1, 1), near("east gate", 15, "bus"), only("bus")], [add("bus", where=loc("at", "east gate"))]),
    case("addition", "erroneous", "two_biycles_union", HEDGER,
         "Could I, erm, perhaps add a biycle - no, two biycles - at the studnet union?",
         [delta("bicycle", 2, 2), near("Student Union entrance", 10, "bicycle", min_count=2), only("bicycle")],
         [add("bicycle", 2, loc("at", "Student Union entrance"))]),
    case("addition", "erroneous", "motorcyle_lot_b", REALTOR, "Pop a motorcyle in lot B - it adds charactor.",
         [delta("motorcycle", 1, 1), near("parking lot B", 2, "motorcycle"), only("motorcycle")],
         [add("motorcycle", where=loc("at", "parking lot B"))]),
    case("addition", "erroneous", "track_behind_ego", RUSSIAN, "Add track 20 meter behind of ego in same lane.",
         [delta("truck", 1, 1), in_lane(EAST, "truck"), near(None, 5, "truck", point=(-80.0, -1.75)), only("truck")],
         [add("truck", where=ahead_of(EGO, -20))]),
    case("addition", "erroneous", "anoda_two_cones", NAIJA, "abeg add anoda two for the same place",
         [delta("traffic_cone", 2, 2), near("bus stop", 12, "traffic_cone", scope="added", min_count=2),
          only("traffic_cone")],
         [add("traffic_cone", 2, loc("at", "bus stop"))],
         setup=[turn("Abeg put two cones for the bus stop.", add("traffic_cone", 2, loc("at", "bus stop")), planned=True)]),
    case("addition", "erroneous", "bench_n_bin_libary", PARENT, "add a bench n a bin by the libary pls",
         [delta("bench", 1, 1), delta("trash_bin", 1, 1), near("Library entrance", 10, "bench"),
          near("Library entrance", 10, "trash_bin"), only("bench", "trash_bin")],
         [add("bench", where=loc("at", "Library entrance")), add("trash_bin", where=loc("next_to", "Library entrance"))]),
    impossible("addition", "erroneous", "gazeebo_fountian", REALTOR, "Add a gazeebo beside the fountian, very upmarket.",
               [add("gazebo", where=loc("next_to", "fountain"))]),
]


# --- Removal: the named things gone, everything else kept ---------------------------------------------------
REMOVAL_CASES: list[Json] = [
    # direct
    case("removal", "direct", "hydrant_off_field", PILOT, "Tower, remove the fire hydrant from the field.",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "direct", "strike_bench", DIRECTOR, "Strike the bench at the bus stop.",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "direct", "all_trees", RUSSIAN, "Please to remove all trees.", [count("tree", 0, 0), only("tree")],
         [remove(category="tree")]),
    case("removal", "direct", "stop_sign", NAIJA, "Abeg remove the stop sign.", [gone(STOP), only(assets=[STOP])],
         [remove(STOP)]),
    case("removal", "direct", "lose_the_bin", REALTOR, "Lose the bin by the bus stop.",
         [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "direct", "clear_lot_b", COACH, "Clear the three cars out of lot B.",
         [gone(*LOT_B_ROW), only(assets=LOT_B_ROW)], [remove(*LOT_B_ROW)]),
    case("removal", "direct", "delete_suv", PARENT, "delete the suv", [gone(SUV), kept(CAR_W, CAR_E), only(assets=[SUV])],
         [remove(SUV)]),
    case("removal", "direct", "ne_signal_only", HEDGER,
         "I think... yes, I think I'd like the traffic light on the north-east corner gone. Just that one, not both.",
         [gone(LIGHT_NE), kept(LIGHT_SW), only(assets=[LIGHT_NE])], [remove(LIGHT_NE)]),
    case("removal", "direct", "south_lamps", PILOT,
         "Remove all six lamp posts on the south side of Main Street.",
         [gone(*SOUTH_LAMPS), kept(*NORTH_LAMPS), only(assets=SOUTH_LAMPS)], [remove(*SOUTH_LAMPS)]),
    case("removal", "direct", "strike_hydrant_and_stop", DIRECTOR, "Strike the hydrant and the stop sign.",
         [gone(HYDRANT, STOP), only(assets=[HYDRANT, STOP])], [remove(HYDRANT), remove(STOP)]),
    case("removal", "direct", "remove_bus", PARENT, "ugh remove the bus", [count("bus", 0, 0), delta("bus", -1, -1), only("bus")],
         [remove(NEW_BUS)], setup=[BUS_EAST_GATE]),
    case("removal", "direct", "tree_north_of_lot_a", COACH, "Take out the tree just north of lot A.",
         [gone(TREE_LOT_A), kept(TREE_LIBRARY, TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE), only(assets=[TREE_LOT_A])],
         [remove(TREE_LOT_A)]),
    impossible("removal", "direct", "union_building", NAIJA, "Abeg remove the Student Union building, e dey block view.",
               [remove("student_union")]),
    # indirect
    case("removal", "indirect", "obstruction_north_footway", PILOT,
         "Tower, obstruction reported on the north footway just east of the junction, a hydrant. Request it cleared "
         "from the field.", [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "indirect", "bench_upstaging", DIRECTOR,
         "That bench is upstaging my actors at the bus stop. It has to go.", [gone(BENCH), only(assets=[BENCH])],
         [remove(BENCH)]),
    case("removal", "indirect", "tree_shadow_library", RUSSIAN,
         "Tree near library makes too much shadow on the road. I don't need it anymore.",
         [gone(TREE_LIBRARY), kept(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE, TREE_LOT_A), only(assets=[TREE_LIBRARY])],
         [remove(TREE_LIBRARY)]),
    case("removal", "indirect", "bin_dey_smell", NAIJA, "That bin for the bus stop dey smell, carry am go.",
         [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "indirect", "viewers_lot_b", REALTOR,
         "Viewers will park in lot B on the open day, and those three cars make it look full. Let's free it up.",
         [gone(*LOT_B_ROW), only(assets=LOT_B_ROW)], [remove(*LOT_B_ROW)]),
    case("removal", "indirect", "sprint_channels", COACH,
         "The trees round the fountain are right in my sprint channels.",
         [gone(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE), kept(TREE_LIBRARY, TREE_LOT_A), only("tree")],
         [remove(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE)]),
    case("removal", "indirect", "scary_north_lamps", PARENT, "kid is scared of the lamp posts on the north side lol",
         [gone(*NORTH_LAMPS), kept(*SOUTH_LAMPS), only(assets=NORTH_LAMPS)], [remove(*NORTH_LAMPS)]),
    case("removal", "indirect", "middle_car_bothers", HEDGER,
         "The car in the middle of the three in lot B... I keep looking at it and, honestly, I'd rather it weren't "
         "there. Is that mad?", [gone(SUV), kept(CAR_W, CAR_E), only(assets=[SUV])], [remove(SUV)]),
    case("removal", "indirect", "debris_on_lane", PILOT,
         "Debris on the ego's lane. Request the lane cleared, over.", [gone(RUBBLE), only("cement_rubble")],
         [remove(RUBBLE)], setup=[RUBBLE_25]),
    case("removal", "indirect", "cutting_the_scene", DIRECTOR, "We're cutting the fountain scene. Clear the extras.",
         [delta("pedestrian", -4, -4), count("pedestrian", 0, 0), only("pedestrian")],
         [remove(category="pedestrian")],
         setup=[turn("Put four extras at the fountain.", add("pedestrian", 4, loc("next_to", "fountain")), planned=True)]),
    case("removal", "indirect", "signals_not_needed", RUSSIAN,
         "I want that traffic lights are not in the scene anymore, drivers must decide themselves.",
         [gone(LIGHT_SW, LIGHT_NE), only("traffic_light")], [remove(LIGHT_SW, LIGHT_NE)]),
    case("removal", "indirect", "stop_and_hydrant_useless", NAIJA,
         "The stop sign and that hydrant no dey useful again. Make dem comot.",
         [gone(STOP, HYDRANT), only(assets=[STOP, HYDRANT])], [remove(STOP), remove(HYDRANT)]),
    impossible("removal", "indirect", "campus_drive_view", REALTOR,
               "The road running north-south spoils the view of the quad. Take Campus Drive away completely.",
               [remove("campus_northbound", "campus_southbound")]),
    # vague
    case("removal", "vague", "clutter_bus_stop", PILOT, "Tower, too much clutter near the bus stop. Reduce.",
         [delta(["bench", "trash_bin", "street_light", "tree"], None, -1),
          only(assets=[BENCH, BIN, TREE_LIBRARY, LAMP_BY_LIBRARY])],
         [remove(BENCH, BIN)]),
    case("removal", "vague", "thin_lamps", REALTOR,
         "Thin out the lamp posts a little - it all looks rather municipal for a leafy street.",
         [delta("street_light", -11, -1), only("street_light")],
         [remove("street_light_3", "street_light_7", "street_light_10")]),
    case("removal", "vague", "fewer_cars_b", REALTOR, "Lot B looks cramped. Fewer cars, please.",
         [delta(CARS, None, -1), only(*CARS)], [remove(CAR_E)]),
    case("removal", "vague", "tree_or_two", REALTOR,
         "Lose a tree or two - they hide the Library's gorgeous period facade.",
         [gone(TREE_LIBRARY), delta("tree", -2, -1), only("tree")], [remove(TREE_LIBRARY)]),
    case("removal", "vague", "tidy_west_crosswalk", REALTOR,
         "Tidy up around the west crosswalk - far too much street furniture for the listing photos.",
         [delta(["stop_sign", "street_light", "traffic_light"], None, -1), only(assets=[STOP, LAMP_CROSSWALK, LIGHT_SW])],
         [remove(STOP, LAMP_CROSSWALK)]),
    case("removal", "vague", "lose_half", COACH, "Too many. Lose half.",
         [delta("traffic_cone", -3, -3), only("traffic_cone")], [remove(category="traffic_cone", count=3)],
         setup=[turn("Set out six cones in lot A for the drill.", add("traffic_cone", 6, loc("at", "parking lot A")),
                     planned=True)]),
    case("removal", "vague", "some_of_the_cars", PARENT, "get rid of some of the cars",
         [delta(CARS, -2, -1), only(*CARS)], [remove(CAR_W)]),
    case("removal", "vague", "one_tree_or_two", HEDGER,
         "Maybe there are... a few too many trees? I don't know. Perhaps lose one? Or two. No - one.",
         [delta("tree", -1, -1), only("tree")], [remove(TREE_LOT_A)]),
    case("removal", "vague", "parked_vehicles", HEDGER,
         "I wonder whether the parked cars could all... go? All of them, I think. Not the ego, obviously.",
         [gone(*LOT_B_ROW), only(*CARS)], [remove(*LOT_B_ROW)]),
    case("removal", "vague", "strike_most_cones", DIRECTOR, "Strike most of those cones.",
         [delta("traffic_cone", -2, -2), only("traffic_cone")], [remove(category="traffic_cone", count=2)],
         setup=[CONES_3_LIBRARY]),
    case("removal", "vague", "everything_near_fountain", RUSSIAN, "Remove everything what is near fountain.",
         [gone(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE), only(assets=[TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE])],
         [remove(TREE_FOUNTAIN_NW, TREE_FOUNTAIN_SE)]),
    case("removal", "vague", "people_too_plenty", NAIJA, "The people too plenty, reduce am.",
         [delta("pedestrian", -3, -1), only("pedestrian")], [remove(category="pedestrian", count=2)],
         setup=[turn("Abeg put four people for the bus stop.", add("pedestrian", 4, loc("on_sidewalk", "bus stop")),
                     planned=True)]),
    impossible("removal", "vague", "delete_ego", PARENT, "just delete the ego car, kid doesnt want it",
               [remove(EGO)]),
    # erroneous
    case("removal", "erroneous", "remvoe_hydrnat", PILOT, "Tower, remvoe the hydrnat, over.",
         [gone(HYDRANT), only(assets=[HYDRANT])], [remove(HYDRANT)]),
    case("removal", "erroneous", "strike_teh_bench", DIRECTOR, "Strike teh bench, its blokcing the bus stop.",
         [gone(BENCH), only(assets=[BENCH])], [remove(BENCH)]),
    case("removal", "erroneous", "ligths_north_side", RUSSIAN, "Please remove al the street ligths on north side.",
         [gone(*NORTH_LAMPS), kept(*SOUTH_LAMPS), only(assets=NORTH_LAMPS)], [remove(*NORTH_LAMPS)]),
    case("removal", "erroneous", "remov_svu", NAIJA, "Abeg remov the svu from lot B.",
         [gone(SUV), kept(CAR_W, CAR_E), only(assets=[SUV])], [remove(SUV)]),
    case("removal", "erroneous", "remvoe_trash_bin", REALTOR, "Remvoe the trash bin, it kills the kerb apeal.",
         [gone(BIN), only(assets=[BIN])], [remove(BIN)]),
    case("removal", "erroneous", "trafic_lights_both", COACH, "get rid of the trafic lights both of them",
         [gone(LIGHT_SW, LIGHT_NE), only("traffic_light")], [remove(LIGHT_SW, LIGHT_NE)]),
    case("removal", "erroneous", "delet_stop_sigh", PARENT, "n delet the stop sigh too", [gone(STOP), only(assets=[STOP])],
         [remove(STOP)], setup=[turn("remove the hydrant", remove(HYDRANT), planned=True)]),
    case("removal", "erroneous", "tree_by_libary", HEDGER,
         "I'd perhaps like the tree by the libary removed? If it's not, um, holding anything up.",
         [gone(TREE_LIBRARY), only(assets=[TREE_LIBRARY])], [remove(TREE_LIBRARY)]),
    case("removal", "erroneous", "negatvie_cones", PILOT, "Negatvie on those cones. Remove them all, over.",
         [delta("traffic_cone", -4, -4), count("traffic_cone", 0, 0), only("traffic_cone")],
         [remove(category="traffic_cone")],
         setup=[turn("Request four cones at the north crosswalk.", add("traffic_cone", 4, loc("at", "north crosswalk")),
                     planned=True)]),
    case("removal", "erroneous", "bench_and_bin_stpo", RUSSIAN, "Remove bench and also bin near bus stpo.",
         [gone(BENCH, BIN), only(assets=[BENCH, BIN])], [remove(BENCH), remove(BIN)]),
    case("removal", "erroneous", "stret_lite_south", NAIJA, "Abeg clear all the stret lite for south side.",
         [gone(*SOUTH_LAMPS), kept(*NORTH_LAMPS), only(assets=SOUTH_LAMPS)], [remove(*SOUTH_LAMPS)]),
    case("removal", "erroneous", "sned_two_home", COACH, "sned two of teh lads home",
         [delta("pedestrian", -2, -2), only("pedestrian")], [remove(category="pedestrian", count=2)],
         setup=[FOUR_LADS_FOUNTAIN]),
    impossible("removal", "erroneous", "libary_buidling", DIRECTOR, "Strike the Libary buidling from the set.",
               [remove("library")]),
]


# --- Positioning: an existing thing put somewhere else ------------------------------------------------------
POSITIONING_CASES: list[Json] = [
    # direct
    case("positioning", "direct", "suv_east_gate", PILOT, "Tower, reposition Sierra Uniform Victor to the east gate.",
         [near("east gate", 10, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "east gate"))]),
    case("positioning", "direct", "bench_new_mark", DIRECTOR, "Move the bench to the fountain. That's its new mark.",
         [near("fountain", 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "direct", "bin_student_union", RUSSIAN, "Please to put bin near Student Union entrance.",
         [near("Student Union entrance", 8, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", "Student Union entrance"))]),
    case("positioning", "direct", "hydrant_jtekt", NAIJA, "Abeg carry the hydrant go the JTEKT entrance.",
         [near("JTEKT building entrance", 8, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", "JTEKT building entrance"))]),
    case("positioning", "direct", "west_car_lot_a", REALTOR,
         "Reposition the car at the west end of the lot B row into lot A instead.",
         [near("parking lot A", 2, asset=CAR_W), only(assets=[CAR_W])], [place(CAR_W, loc("at", "parking lot A"))]),
    case("positioning", "direct", "stop_sign_north_crossing", COACH, "Put the stop sign at the north crosswalk.",
         [near("north crosswalk", 8, asset=STOP), on(["sidewalk"], asset=STOP), only(assets=[STOP])],
         [place(STOP, loc("on_sidewalk", "north crosswalk"))]),
    case("positioning", "direct", "suv_coords", PARENT, "put the suv at x 30 y -20",
         [near(None, 1.5, asset=SUV, point=(30.0, -20.0)), only(assets=[SUV])], [place(SUV, xy(30.0, -20.0))]),
    case("positioning", "direct", "bench_engineering_not_library", HEDGER,
         "Would it be all right to put the bench by the Library entrance? Or - no, the Engineering Hall entrance. "
         "Sorry. Engineering.",
         [near("Engineering Hall entrance", 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", "Engineering Hall entrance"))]),
    case("positioning", "direct", "ego_heading_090", PILOT,
         "Position the ego at x minus four zero, y minus one decimal seven five, heading zero niner zero.",
         [near(None, 1, asset=EGO, point=(-40.0, -1.75)), in_lane(EAST, asset=EGO, aligned=True), only(assets=[EGO])],
         [place(EGO, xy(-40.0, -1.75), yaw_deg=0.0)]),
    case("positioning", "direct", "bench_and_bin_blocking", DIRECTOR,
         "New blocking: the bench goes to the JTEKT entrance, and the bin sits beside it.",
         [near("JTEKT building entrance", 8, asset=BENCH), near(BENCH, 4, asset=BIN), only(assets=[BENCH, BIN])],
         [place(BENCH, loc("at", "JTEKT building entrance")), place(BIN, loc("next_to", BENCH))]),
    case("positioning", "direct", "bus_to_parking_a", RUSSIAN, "Put it to parking A.",
         [near("parking lot A", 3, "bus"), delta("bus", 0, 0), only("bus")], [place(NEW_BUS, loc("at", "parking lot A"))],
         setup=[turn("Add bus at main gate.", add("bus", where=loc("at", "main gate")), planned=True)]),
    case("positioning", "direct", "car_2_thirty_ahead", COACH,
         "Put passenger car 2 thirty metres ahead of the ego, same lane.",
         [in_lane(EAST, asset=CAR_E), near(None, 4, asset=CAR_E, point=(-30.0, -1.75)), only(assets=[CAR_E])],
         [place(CAR_E, ahead_of(EGO, 30))]),
    impossible("positioning", "direct", "rooftop_parking", REALTOR,
               "Place the SUV on the roof of the Student Union - rooftop parking is so sought-after.",
               [place(SUV, xy(42.0, -63.0))]),
    # indirect
    case("positioning", "indirect", "suv_meets_party", PILOT,
         "Sierra Uniform Victor is to wait at the east gate for the arriving party.",
         [near("east gate", 12, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "east gate"))]),
    case("positioning", "indirect", "bench_act_two", DIRECTOR,
         "Act Two plays by the fountain, and the bench has to be there for it.",
         [near("fountain", 12, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "indirect", "union_no_bin", RUSSIAN,
         "Students from Union complain there is no place to throw garbage. Bin must be near them.",
         [near("Student Union entrance", 8, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", "Student Union entrance"))]),
    case("positioning", "indirect", "hydrant_blocks_walkers", NAIJA,
         "That hydrant for the corner dey block people wey dey waka. Make e go stay near the Engineering Hall instead.",
         [near("Engineering Hall entrance", 10, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", "Engineering Hall entrance"))]),
    case("positioning", "indirect", "bench_money_shot", REALTOR,
         "The bench would photograph so much better by the fountain. That's where the money shot is.",
         [near("fountain", 10, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "indirect", "east_car_out_of_drill", COACH,
         "The car at the east end of the lot B row is in my drill area. Park it over in lot A.",
         [near("parking lot A", 2, asset=CAR_E), only(assets=[CAR_E])], [place(CAR_E, loc("at", "parking lot A"))]),
    case("positioning", "indirect", "bin_in_kids_way", PARENT,
         "the bin is right where the kid walks at the bus stop. library doors instead",
         [near("Library entrance", 8, asset=BIN), only(assets=[BIN])], [place(BIN, loc("at", "Library entrance"))]),
    case("positioning", "indirect", "stop_sign_strange_place", HEDGER,
         "I keep worrying the stop sign is in a strange place. Perhaps it belongs by the north crosswalk? If that's "
         "where they go.",
         [near("north crosswalk", 8, asset=STOP), only(assets=[STOP])], [place(STOP, loc("on_sidewalk", "north crosswalk"))]),
    case("positioning", "indirect", "reduce_separation", PILOT,
         "Traffic ahead is too far out. Reduce separation to two-zero metres.",
         [in_lane(EAST, asset=NEW_CAR), near(None, 5, asset=NEW_CAR, point=(-40.0, -1.75)), only(assets=[NEW_CAR])],
         [place(NEW_CAR, ahead_of(EGO, 20))], setup=[LEAD_CAR_45_PARKED]),
    case("positioning", "indirect", "bus_wrong_mark", DIRECTOR,
         "It's on the wrong mark. The bus should be pulled up at the bus stop for this scene.",
         [near("bus stop", 10, "bus"), delta("bus", 0, 0), only("bus")],
         [place(NEW_BUS, loc("in_lane", "bus stop", lane=EAST))],
         setup=[turn("Bring a bus on at the east gate.", add("bus", where=loc("at", "east gate")), planned=True)]),
    case("positioning", "indirect", "bench_bin_too_far", RUSSIAN,
         "Bench and bin both are too far from people. They must stand near Library entrance.",
         [near("Library entrance", 10, asset=BENCH), near("Library entrance", 10, asset=BIN), only(assets=[BENCH, BIN])],
         [place(BENCH, loc("at", "Library entrance")), place(BIN, loc("next_to", "Library entrance"))]),
    case("positioning", "indirect", "suv_waits_oga", NAIJA,
         "The SUV suppose dey wait for oga for the main gate.",
         [near("main gate", 12, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "main gate"))]),
    impossible("positioning", "indirect", "indoor_session", COACH,
               "Stick the bench inside the Engineering Hall - we're doing an indoor session.",
               [place(BENCH, xy(-40.0, 28.0))]),
    # vague
    case("positioning", "vague", "suv_near_junction", PILOT, "Reposition the SUV somewhere in the vicinity of the junction.",
         [near("main intersection", 15, asset=SUV), only(assets=[SUV])], [place(SUV, xy(1.75, -20.0))]),
    case("positioning", "vague", "bench_better_spot", DIRECTOR,
         "Find the bench a better spot, somewhere round the Student Union.",
         [near("Student Union entrance", 12, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", "Student Union entrance"))]),
    case("positioning", "vague", "hydrant_other_side", RUSSIAN, "Put hydrant somewhere on other side of road.",
         [near(None, 8, asset=HYDRANT, point=(16.0, -5.5)), on(["sidewalk"], asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, xy(16.0, -5.5))]),
    case("positioning", "vague", "bin_anywhere_fountain", NAIJA, "Put the bin anywhere for the fountain side.",
         [near("fountain", 12, asset=BIN), only(assets=[BIN])], [place(BIN, loc("next_to", "fountain"))]),
    case("positioning", "vague", "bench_leafier", REALTOR, "Give the bench a leafier setting.",
         [only(assets=[BENCH]), moved(BENCH, 2.0)], [place(BENCH, loc("next_to", TREE_FOUNTAIN_NW))],
         alternatives=[[near(tree, 8, asset=BENCH)] for tree in TREES]),
    case("positioning", "vague", "car_other_car_park", COACH, "Park passenger car 1 somewhere in the other car park.",
         [near("parking lot A", 2, asset=CAR_W), only(assets=[CAR_W])], [place(CAR_W, loc("at", "parking lot A"))]),
    case("positioning", "vague", "bin_somewhere_else", PARENT, "move the bin somewhere else idc",
         [moved(BIN, 2.0), only(assets=[BIN])], [place(BIN, loc("at", "Library entrance"))]),
    case("positioning", "vague", "bench_nearer_crossroads", HEDGER,
         "The bench could perhaps sit... somewhere nearer the crossroads? Roughly? I really don't mind exactly where.",
         [near("main intersection", 12, asset=BENCH), moved(BENCH, 3.0), only(assets=[BENCH])],
         [place(BENCH, xy(-12.0, -8.0))]),
    case("positioning", "vague", "truck_into_lot_alpha", PILOT, "Reposition that traffic somewhere in lot Alpha.",
         [near("parking lot A", 3, "truck"), delta("truck", 0, 0), only("truck")],
         [place(NEW_TRUCK, loc("at", "parking lot A"))],
         setup=[turn("Request one truck at the main gate.", add("truck", where=loc("at", "main gate")), planned=True)]),
    case("positioning", "vague", "hydrant_jtekt_area", HEDGER,
         "Perhaps the hydrant could live somewhere over by JTEKT? I don't mind exactly where.",
         [near("JTEKT building entrance", 15, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", "JTEKT building entrance"))]),
    case("positioning", "vague", "suv_near_engineering", HEDGER,
         "Could the SUV go... somewhere near Engineering? Anywhere round there, really.",
         [near("Engineering Hall entrance", 15, asset=SUV), only(assets=[SUV])],
         [place(SUV, loc("in_lane", "Engineering Hall entrance", lane=WEST))]),
    case("positioning", "vague", "person_bus_stop_side", NAIJA,
         "Make that person go stand somewhere for the bus stop side.",
         [near("bus stop", 10, "pedestrian"), delta("pedestrian", 0, 0), only("pedestrian")],
         [place(NEW_WALKER, loc("on_sidewalk", "bus stop"))], setup=[WALKER_FOUNTAIN]),
    impossible("positioning", "vague", "suv_on_the_moon", PARENT, "put the suv somewhere on the moon lol",
               [place(SUV, loc("at", "moon"))]),
    # erroneous
    case("positioning", "erroneous", "suv_east_gat", PARENT, "put the suv by the east gat",
         [near("east gate", 10, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "east gate"))]),
    case("positioning", "erroneous", "bench_fontain", DIRECTOR, "Move the bench to the fontain.",
         [near("fountain", 8, asset=BENCH), only(assets=[BENCH])], [place(BENCH, loc("next_to", "fountain"))]),
    case("positioning", "erroneous", "bin_studnet_union", RUSSIAN, "Put bin to Studnet Union.",
         [near("Student Union entrance", 8, asset=BIN), only(assets=[BIN])],
         [place(BIN, loc("at", "Student Union entrance"))]),
    case("positioning", "erroneous", "hydrant_libary", PARENT, "put the hydrant at the libary entrence",
         [near("Library entrance", 8, asset=HYDRANT), only(assets=[HYDRANT])],
         [place(HYDRANT, loc("at", "Library entrance"))]),
    case("positioning", "erroneous", "bnech_enginering", REALTOR, "Place the bnech by the Enginering Hall entrance.",
         [near("Engineering Hall entrance", 8, asset=BENCH), only(assets=[BENCH])],
         [place(BENCH, loc("at", "Engineering Hall entrance"))]),
    case("positioning", "erroneous", "stop_sgin_crosswlak", COACH, "put the stop sgin at the north crosswlak",
         [near("north crosswalk", 8, asset=STOP), only(assets=[STOP])], [place(STOP, loc("on_sidewalk", "north crosswalk"))]),
    case("positioning", "erroneous", "suv_in_lot_a", PARENT, "put the suv in lot a thx",
         [near("parking lot A", 2, asset=SUV), only(assets=[SUV])], [place(SUV, loc("at", "parking lot A"))]),
    case("positioning", "erroneous", "hydrnat_bus_stpo", HEDGER,
         "Perhaps put the hydrnat by the bus stpo? Or is that a bad idea. No, do it.",
         [near("bus stop", 8, asset=HYDRANT), only(assets=[HYDRANT])], [place(HYDRANT, loc("at", "bus stop"))]),
    case("positioning", "erroneous", "pasenger_car_two_alpha", PILOT, "Reposition pasenger car two to lot Alpha.",
         [near("parking lot A", 2, asset=CAR_E), only(assets=[CAR_E])], [place(CAR_E, loc("at", "parking lot A"))]),
    case("positioning", "erroneous", "sory_mistake_library", RUSSIAN, "Sory, I made mistake. Put it near Libary.",
         [near("Library entrance", 10, asset=NEW_BENCH), kept(BENCH), delta("bench", 0, 0), only("bench")],
         [place(NEW_BENCH, loc("at", "Library entrance"))],
         setup=[turn("Add bench near fountain.", add("bench", where=loc("next_to", "fountain")), planned=True)]),
    case("positioning", "erroneous", "bench_bin_jtekt_entrence", NAIJA,
         "Abeg carry the bench and the bin go the JTEKT entrence.",
         [near("JTEKT building entrance", 10, asset=BENCH), near("JTEKT building entrance", 10, asset=BIN),
          only(assets=[BENCH, BIN])],
         [place(BENCH, loc("at", "JTEKT building entrance")), place(BIN, loc("next_to", "JTEKT building entrance"))]),
    case("positioning", "erroneous", "suv_25_ahaed", COACH, "put the suv 25m ahaed of the ego in its lane",
         [in_lane(EAST, asset=SUV), near(None, 4, asset=SUV, point=(-35.0, -1.75)), only(assets=[SUV])],
         [place(SUV, ahead_of(EGO, 25))]),
    impossible("positioning", "erroneous", "bench_off_stgae", DIRECTOR,
               "Set the bench at x = 900, y = 0 - way off stgae.", [place(BENCH, xy(900.0, 0.0))]),
]


# --- Moving: shifts, turns and what things do over time -----------------------------------------------------
MOVING_CASES: list[Json] = [
    # direct
    case("moving", "direct", "ego_seven_ms", PILOT, "Ego, increase speed to seven metres per second.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=7.0, lane=EAST)], alternatives=new_speed(EGO, 6.5, 7.5)),
    case("moving", "direct", "bench_half_turn", DIRECTOR, "Turn the bench to face the other way - a full half-turn.",
         [moved(BENCH, 0, 1, turn_min=160), only(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    case("moving", "direct", "suv_five_forward", PARENT, "move the suv 5m forward",
         [moved(SUV, 4, 6, "forward"), only(assets=[SUV])], [move(SUV, forward=5)]),
    case("moving", "direct", "ego_stop_at_four", NAIJA, "Abeg make the ego stop when the time reach 4 seconds.",
         [timed_event(EGO, "stop", 8.0, (-41.0, -1.75)), only(assets=[EGO])], [manoeuvre(EGO, "stop", at_time=4.0)]),
    case("moving", "direct", "suv_to_lot_b_entrance", REALTOR, "Have the SUV drive itself out to the lot B entrance.",
         [reaches(SUV, "parking lot B entrance", 40.0, 6.0), only(assets=[SUV])],
         [behave(SUV, "follow_path", to="parking lot B entrance")]),
    case("moving", "direct", "ego_left_lane_three", COACH, "Ego switches to the left lane after three seconds.",
         [event_played(EGO, "lane_change", 6.0), only(assets=[EGO])],
         [manoeuvre(EGO, "lane_change", at_time=3.0, side="left")]),
    case("moving", "direct", "suv_circles", PARENT, "make the suv do circles in the car park",
         [does("circle", asset=SUV, centre_near="parking lot B"), only(assets=[SUV])],
         [behave(SUV, "circle", centre="parking lot B", radius=6.0)]),
    case("moving", "direct", "ego_right_at_junction", HEDGER,
         "Could the ego perhaps turn right at the junction? Or left - no, right. Definitely right.",
         [reaches(EGO, "-1.75, -20", 30.0, 4.0), only(assets=[EGO])], [manoeuvre(EGO, "junction_turn", turn="right")]),
    case("moving", "direct", "ego_three_ms", PARENT, "slow the ego down to 3 m/s pls",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=3.0, lane=EAST)], alternatives=new_speed(EGO, 2.5, 3.5)),
    case("moving", "direct", "bin_east_bench_west", HEDGER,
         "Could the bin shift two metres east, and the bench... one metre west? If that's not too fiddly.",
         [moved(BIN, 1.5, 2.5, "forward"), moved(BENCH, 0.5, 1.5, "forward"), only(assets=[BIN, BENCH])],
         [move(BIN, east=2), move(BENCH, east=-1)]),
    case("moving", "direct", "drive_to_east_gate", RUSSIAN, "Make it drive to east gate.",
         [reaches("passenger_car", "east gate", 60.0, 10.0), only("passenger_car")],
         [behave(NEW_CAR, "follow_path", to="east gate")],
         setup=[turn("Add car in parking A.", add("passenger_car", where=loc("at", "parking lot A")), planned=True)]),
    case("moving", "direct", "walk_north_crosswalk", COACH, "Walk a pedestrian across the north crosswalk.",
         [delta("pedestrian", 1, 1), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "north crosswalk"), behaviour={"kind": "cross_road"})],
         alternatives=walks_over(NORTH)),
    impossible("moving", "direct", "ego_fly", NAIJA, "Make the ego fly go the fountain.",
               [behave(EGO, "fly", to="fountain")]),
    # indirect
    case("moving", "indirect", "hold_short_west_crosswalk", PILOT,
         "Ego is to hold short of the west crosswalk. I want it waiting at a red light.",
         [EGO_HALTS_AT_WEST_CROSSWALK, only("traffic_light", assets=[EGO])], [hold(LIGHT_SW, "red")]),
    case("moving", "indirect", "chase_to_east_gate", DIRECTOR,
         "For the chase scene the SUV should be tearing off towards the east gate.",
         [reaches(SUV, "east gate", 45.0, 8.0), only(assets=[SUV])], [behave(SUV, "follow_path", to="east gate", speed=8.0)]),
    case("moving", "indirect", "students_laughing", RUSSIAN,
         "Our car is going so slow, students are laughing. Make it go 8 meters per second.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=8.0, lane=EAST)], alternatives=new_speed(EGO, 7.5, 8.5)),
    case("moving", "indirect", "bus_go_bus_stop", NAIJA,
         "The bus wey dey east gate suppose dey go the bus stop. Make e start moving.",
         [reaches("bus", "bus stop", 60.0, 12.0), only("bus")], [behave(NEW_BUS, "follow_path", to="bus stop")],
         setup=[turn("Put one bus for east gate, for the westbound lane.",
                     add("bus", where=loc("in_lane", "east gate", lane=WEST)), planned=True)]),
    case("moving", "indirect", "glide_past_library", REALTOR,
         "Buyers should see a car glide up to the Library frontage - send the west-end car from lot B over there.",
         [reaches(CAR_W, "Library entrance", 60.0, 12.0), only(assets=[CAR_W])],
         [behave(CAR_W, "follow_path", to="Library entrance")]),
    case("moving", "indirect", "reaction_drill", COACH,
         "Reaction drill: the car in front slams on its brakes as soon as the ego gets within ten metres.",
         [only(assets=[NEW_CAR])],
         [event(NEW_CAR, "stop", {"kind": "distance", "metres": 10.0, "actor": EGO, "other": NEW_CAR}, rate=7.0)],
         setup=[turn("Put a car 30 m in front of the ego in its lane, jogging along at 2 m/s.",
                     add("passenger_car", where=ahead_of(EGO, 30), behaviour=drive(2.0, EAST)))],
         alternatives=slows_down(NEW_CAR)),
    case("moving", "indirect", "suv_donuts", PARENT, "kid wants the suv to do donuts",
         [does("circle", asset=SUV), only(assets=[SUV])], [behave(SUV, "circle", centre="parking lot B", radius=6.0)]),
    case("moving", "indirect", "touch_quick", HEDGER,
         "I suppose the ego is going a touch quick for my liking... could it maybe do, what, four? Four metres a second?",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=4.0, lane=EAST)], alternatives=new_speed(EGO, 3.5, 4.5)),
    case("moving", "indirect", "crossing_traffic", PILOT,
         "I need a pedestrian crossing in front of the ego on the west crosswalk as it comes up to it.",
         [delta("pedestrian", 1, None), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "west crosswalk")),
          event(NEW_WALKER, "cross_road", {"kind": "distance", "metres": 25.0, "actor": EGO, "other": NEW_WALKER})],
         alternatives=walks_over(EAST, 20.0)),
    case("moving", "indirect", "on_cue_to_bus_stop", DIRECTOR, "On cue, she walks over to the bus stop.",
         [reaches("pedestrian", "bus stop", 40.0, 4.0), only("pedestrian")],
         [behave(NEW_WALKER, "follow_path", to="bus stop")],
         setup=[turn("Put an extra at the Library entrance.", add("pedestrian", where=loc("at", "Library entrance")),
                     planned=True)]),
    case("moving", "indirect", "somebody_cuts_in", RUSSIAN,
         "I want to see how our car reacts when somebody is cutting in right in front of it.",
         [only(*TRAFFIC)],
         [add("passenger_car", where=ahead_of(EGO, -10, side="left"), behaviour=drive(8.0)),
          manoeuvre(NEW_CAR, "cut_in", at_time=2.0, gap=8.0)],
         alternatives=[[event_played(category, "cut_in", 10.0)] for category in TRAFFIC]),
    case("moving", "indirect", "slow_then_left_lane", NAIJA,
         "Make the ego slow down to 3 first, then by 5 seconds make e enter the left lane.",
         [event_played(EGO, "lane_change", 8.0), only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=3.0, lane=EAST), manoeuvre(EGO, "lane_change", at_time=5.0, side="left")],
         alternatives=new_speed(EGO, 2.5, 3.5)),
    impossible("moving", "indirect", "hydrant_shuttle_runs", COACH,
               "Get the fire hydrant doing shuttle runs up and down the footway.",
               [behave(HYDRANT, "follow_path", waypoints=[[16.0, 5.5], [30.0, 5.5]])]),
    # vague
    case("moving", "vague", "expedite", PILOT, "Ego, expedite.", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=8.0, lane=EAST)], alternatives=new_speed(EGO, 6.0, 20.0)),
    case("moving", "vague", "suv_something_to_do", DIRECTOR, "Give the SUV something to do in this scene.",
         [only(assets=[SUV])], [behave(SUV, "circle", centre="parking lot B", radius=6.0)], alternatives=gets_going(SUV)),
    case("moving", "vague", "little_slower", RUSSIAN, "Make our car little slower.", [only(assets=[EGO])],
         [behave(EGO, "drive_lane", speed=3.5, lane=EAST)], alternatives=new_speed(EGO, 0.5, 4.6)),
    case("moving", "vague", "shift_bench_slightly", HEDGER, "Could the bench move... a little? Just slightly?",
         [moved(BENCH, 0.3, 2.0), only(assets=[BENCH])], [move(BENCH, forward=1)]),
    case("moving", "vague", "angle_bench", REALTOR, "Angle the bench a little so it catches the light.",
         [moved(BENCH, 0, 1.5, turn_min=5, turn_max=60), only(assets=[BENCH])], [move(BENCH, turn_deg=25)]),
    case("moving", "vague", "bodies_over_campus_drive", COACH, "Get some bodies moving across Campus Drive.",
         [delta("pedestrian", 1, None), only("pedestrian")],
         [add("pedestrian", 2, loc("on_sidewalk", "north crosswalk"), behaviour={"kind": "cross_road"})],
         alternatives=walks_over(NORTH)),
    case("moving", "vague", "suv_move", PARENT, "make the suv move", [only(assets=[SUV])],
         [behave(SUV, "follow_path", to="east gate")], alternatives=gets_going(SUV)),
    case("moving", "vague", "back_up_a_little", HEDGER,
         "Maybe the ego could... back up? A little? Not far, I'd imagine.", [only(assets=[EGO])],
         [move(EGO, forward=-3)], alternatives=backs_up(EGO, 0.5, 6.0)),
    case("moving", "vague", "something_unexpected", PILOT, "Traffic ahead: do something unexpected.",
         [only(assets=[NEW_CAR])], [event(NEW_CAR, "stop", {"kind": "time", "seconds": 4.0}, rate=6.0)],
         setup=[LEAD_CAR_30],
         alternatives=[[event_played(NEW_CAR, kind, 20.0)] for kind in ("stop", "change_speed", "lane_change", "cut_in")]),
    case("moving", "vague", "bench_faces_road", DIRECTOR, "Swing the bench round so it plays out to the road.",
         [moved(BENCH, 0, 1.5, turn_min=60), relative("in_front_of", BENCH, asset=LAMP_ACROSS_FROM_BENCH, max_distance=15,
                                                       tolerance_deg=45), only(assets=[BENCH])],
         [move(BENCH, turn_deg=-90)]),
    case("moving", "vague", "someone_cross_road", HEDGER,
         "Might someone cross the road, perhaps? Somewhere? I'm not fussy about where.",
         [delta("pedestrian", 1, None), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "west crosswalk"), behaviour={"kind": "cross_road"})],
         alternatives=walks_over(None)),
    case("moving", "vague", "make_am_dey_go", NAIJA, "Oya make am dey go.", [only("bus")],
         [behave(NEW_BUS, "drive_lane", speed=6.0, lane=WEST)], alternatives=gets_going(NEW_BUS),
         setup=[turn("Put one bus for the east gate, for the road.", add("bus", where=loc("in_lane", "east gate", lane=WEST)),
                     planned=True)]),
    impossible("moving", "vague", "bench_drives_itself", HEDGER,
               "Could the bench maybe... drive itself over to the fountain? Is that a thing it can do?",
               [behave(BENCH, "follow_path", to="fountain")]),
    # erroneous
    case("moving", "erroneous", "incrase_speed_six", PILOT, "Ego, incrase speed to six metres per secnd.",
         [only(assets=[EGO])], [behave(EGO, "drive_lane", speed=6.0, lane=EAST)], alternatives=new_speed(EGO, 5.5, 6.5)),
    case("moving", "erroneous", "trun_bench_aroudn", DIRECTOR, "Trun the bench aroudn to face the other way.",
         [moved(BENCH, 0, 1, turn_min=160), only(assets=[BENCH])], [move(BENCH, turn_deg=180)]),
    case("moving", "erroneous", "suv_ten_metr_nort", RUSSIAN, "Move SUV 10 metr to nort.",
         [moved(SUV, 9, 11, "forward"), only(assets=[SUV])], [move(SUV, north=10)]),
    case("moving", "erroneous", "ego_stp_five", NAIJA, "Abeg make the ego stp at 5 secnds.",
         [timed_event(EGO, "stop", 9.0, (-36.0, -1.75)), only(assets=[EGO])], [manoeuvre(EGO, "stop", at_time=5.0)]),
    case("moving", "erroneous", "suv_drvie_east_gaet", REALTOR, "Have the suv drvie to the east gaet.",
         [reaches(SUV, "east gate", 60.0, 8.0), only(assets=[SUV])], [behave(SUV, "follow_path", to="east gate")]),
    case("moving", "erroneous", "chnage_lanes_four", COACH, "ego chnage lanes to the left at 4 secs",
         [event_played(EGO, "lane_change", 7.0), only(assets=[EGO])],
         [manoeuvre(EGO, "lane_change", at_time=4.0, side="left")]),
    case("moving", "erroneous", "suv_cirlces", PARENT, "make the suv go in cirlces",
         [does("circle", asset=SUV), only(assets=[SUV])], [behave(SUV, "circle", centre="parking lot B", radius=6.0)]),
    case("moving", "erroneous", "reverse_three_mtres", HEDGER,
         "Perhpas the ego could reverse 5 metres? Or 3. Three mtres, let's say.", [only(assets=[EGO])],
         [move(EGO, forward=-3)], alternatives=backs_up(EGO, 2.5, 3.5)),
    case("moving", "erroneous", "brake_one_five_behnd", PILOT,
         "Trafic ahead to brake hard when the ego is one-five metres behnd it.", [only(assets=[NEW_CAR])],
         [event(NEW_CAR, "stop", {"kind": "distance", "metres": 15.0, "actor": EGO, "other": NEW_CAR}, rate=7.0)],
         setup=[LEAD_CAR_30], alternatives=slows_down(NEW_CAR)),
    case("moving", "erroneous", "pedestrain_cross_west", RUSSIAN, "Make pedestrain to cross road on west crosswlak.",
         [delta("pedestrian", 1, None), only("pedestrian")],
         [add("pedestrian", where=loc("on_sidewalk", "west crosswalk"), behaviour={"kind": "cross_road"})],
         alternatives=walks_over(EAST)),
    case("moving", "erroneous", "bin_west_bench_round", NAIJA, "Abeg move the bin 2 metre go west and trun the bench round.",
         [moved(BIN, 1.5, 2.5, "backward"), moved(BENCH, 0, 1, turn_min=160), only(assets=[BIN, BENCH])],
         [move(BIN, east=-2), move(BENCH, turn_deg=180)]),
    case("moving", "erroneous", "bin_three_eats", COACH, "shift the bin 3 metres eats",
         [moved(BIN, 2.5, 3.5, "forward"), only(assets=[BIN])], [move(BIN, east=3)]),
    impossible("moving", "erroneous", "two_hundred_kmh", PARENT, "make the ego go 200 km/h kid wants it fastt",
               [behave(EGO, "drive_lane", speed=55.6, lane=EAST)]),
]


# --- Arrangement: several new things laid out in a shape, where asked ----------------------------------------
ARRANGEMENT_CASES: list[Json] = [
    # direct
    case("arrangement", "direct", "cones_across_eastbound", PILOT,
         "Request five cones in a line across the eastbound lane, three-zero metres ahead of the ego.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5), some_in_lane(EAST, "traffic_cone"),
          near(None, 6, "traffic_cone", point=(-30.0, -1.75), min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "line", ahead_of(EGO, 30), count=5, heading_deg=90)]),
    case("arrangement", "direct", "bollard_ring_fountain", DIRECTOR, "Set a ring of bollards round the fountain.",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around="fountain"), only("bollard")],
         [arrange("bollard", "ring", loc("at", "fountain"))]),
    case("arrangement", "direct", "barriers_line_jtekt", RUSSIAN, "Please to put 4 barriers in one line near JTEKT entrance.",
         [delta("road_barrier", 4, 4), layout("line", "road_barrier", 4), near("JTEKT building entrance", 12, "road_barrier",
                                                                             min_count=4), only("road_barrier")],
         [arrange("road_barrier", "line", loc("at", "JTEKT building entrance"), count=4)]),
    case("arrangement", "direct", "bollard_circle_hydrant", NAIJA, "Abeg arrange six bollards for circle round the hydrant.",
         [delta("bollard", 6, 6), layout("ring", "bollard", 6, around=HYDRANT), only("bollard")],
         [arrange("bollard", "ring", loc("at", HYDRANT), count=6)]),
    case("arrangement", "direct", "trees_engineering_front", REALTOR,
         "Line three trees along the front of the Engineering Hall.",
         [delta("tree", 3, 3), layout("line", "tree", 3), near("Engineering Hall entrance", 15, "tree", min_count=3),
          only("tree")],
         [arrange("tree", "line", loc("at", "Engineering Hall entrance"), count=3)]),
    case("arrangement", "direct", "eight_cones_two_apart", COACH,
         "Set out eight cones in a straight line in lot A, two metres apart.",
         [delta("traffic_cone", 8, 8), layout("line", "traffic_cone", 8, spacing_min=1.8, spacing_max=2.2),
          near("parking lot A", 2, "traffic_cone", min_count=8), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot A"), count=8, spacing=2.0)]),
    case("arrangement", "direct", "three_benches_row", PARENT, "put 3 benches in a row by the fountain",
         [delta("bench", 3, 3), layout("line", "bench", 3), near("fountain", 15, "bench", min_count=3), only("bench")],
         [arrange("bench", "line", loc("next_to", "fountain"), count=3)]),
    case("arrangement", "direct", "bollard_circle_stop_sign", HEDGER,
         "Could I have some bollards in a circle around the, um, the stop sign? Six, perhaps.",
         [delta("bollard", 6, 6), layout("ring", "bollard", 6, around=STOP), only("bollard")],
         [arrange("bollard", "ring", loc("at", STOP), count=6)]),
    case("arrangement", "direct", "three_cars_lot_bravo", PILOT, "Park three cars side by side in lot Bravo.",
         [delta(CARS, 3, 3), layout("line", CARS, 3), near("parking lot B", 2, CARS, scope="added", min_count=3),
          only(*CARS)],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot B"), count=3)]),
    case("arrangement", "direct", "cones_and_sign_library", DIRECTOR,
         "A line of five cones in front of the Library entrance, and a construction sign beside them.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5), near("Library entrance", 12, "traffic_cone",
                                                                              min_count=5),
          delta("construction_sign", 1, 1), near("Library entrance", 12, "construction_sign"),
          only("traffic_cone", "construction_sign")],
         [arrange("traffic_cone", "line", loc("in_front_of", "Library entrance"), count=5),
          add("construction_sign", where=loc("next_to", "Library entrance"))]),
    case("arrangement", "direct", "grid_three_by_three", PARENT, "9 cones in a grid in lot a, 3x3",
         [delta("traffic_cone", 9, 9), layout("cluster", "traffic_cone", 9, tolerance=5.0),
          near("parking lot A", 2, "traffic_cone", min_count=9), only("traffic_cone")],
         [arrange("traffic_cone", "grid", loc("at", "parking lot A"), count=9, columns=3)]),
    case("arrangement", "direct", "same_in_lot_b", COACH, "Now the same in lot B.",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6),
          near("parking lot B", 2, "traffic_cone", scope="added", min_count=6), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B"), count=6)],
         setup=[turn("Set out six cones in a line in lot A.",
                     arrange("traffic_cone", "line", loc("at", "parking lot A"), count=6), planned=True)]),
    impossible("arrangement", "direct", "agility_ladders", COACH, "Lay two agility ladders side by side in lot A.",
               [arrange("agility ladder", "line", loc("at", "parking lot A"), count=2)]),
    # indirect
    case("arrangement", "indirect", "lane_closed_forty", PILOT,
         "The eastbound lane is closed ahead of the ego. Block it off about four-zero metres out.",
         [delta(CORDON, 3, None), some_in_lane(EAST, CORDON), near(None, 8, CORDON, point=(-20.0, -1.75), min_count=2),
          only(*CORDON, "construction_sign")],
         [arrange("traffic_cone", "line", ahead_of(EGO, 40), count=5, heading_deg=90)]),
    case("arrangement", "indirect", "crowd_scene_cordon", DIRECTOR, "I need the fountain cordoned off for the crowd scene.",
         [delta(CORDON, 4, None), layout("ring", CORDON, 4, around="fountain"), only(*CORDON)],
         [arrange("bollard", "ring", loc("at", "fountain"))]),
    case("arrangement", "indirect", "workers_at_hydrant", RUSSIAN,
         "Workers will repair hydrant. Is need to close it from all sides so people don't come close.",
         [delta(CORDON, 4, None), layout("ring", CORDON, 4, around=HYDRANT), only(*CORDON)],
         [arrange("bollard", "ring", loc("at", HYDRANT), count=6)]),
    case("arrangement", "indirect", "no_parking_bus_stop", NAIJA,
         "Oya make barrier for the road in front of the bus stop so motor no go park there.",
         [delta(CORDON, 3, None), near("bus stop", 12, CORDON, min_count=3), some_in_lane(EAST, CORDON), only(*CORDON)],
         [arrange("traffic_cone", "lane_edge", loc("in_lane", "bus stop", lane=EAST), count=4)],
         alternatives=any_shape(CORDON, 3)),
    case("arrangement", "indirect", "organised_lot_b", REALTOR,
         "Lot B should look beautifully organised for the viewing: three or four cars parked neatly side by side.",
         [delta(CARS, 3, 4), layout("line", CARS, 3), near("parking lot B", 2, CARS, scope="added", min_count=3),
          only(*CARS)],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot B"), count=4)]),
    case("arrangement", "indirect", "dribbling_slalom", COACH,
         "I need a slalom for dribbling in lot A - six cones, nice and straight.",
         [delta("traffic_cone", 6, 6), layout("line", "traffic_cone", 6), near("parking lot A", 2, "traffic_cone",
                                                                              min_count=6), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot A"), count=6)]),
    case("arrangement", "indirect", "laps_in_lot_b", PARENT,
         "kid wants to run laps in lot b, make her a round track with cones",
         [delta("traffic_cone", 4, None), layout("ring", "traffic_cone", 4, around="parking lot B"),
          near("parking lot B", 2, "traffic_cone", min_count=4), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "parking lot B"), count=10, radius=7.0)]),
    case("arrangement", "indirect", "fountain_at_night", HEDGER,
         "I'm slightly worried people will walk into the fountain at night... maybe something all the way around it? "
         "Bollards, possibly? Unless that's excessive.",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around="fountain"), only("bollard")],
         [arrange("bollard", "ring", loc("at", "fountain"))]),
    case("arrangement", "indirect", "mark_the_obstruction", PILOT, "Mark that obstruction so nobody taxis into it.",
         [delta(CORDON, 4, None), layout("ring", CORDON, 4, around=RUBBLE), only(*CORDON)],
         [arrange("bollard", "ring", loc("at", RUBBLE), count=6)], setup=[RUBBLE_25]),
    case("arrangement", "indirect", "union_queue", DIRECTOR,
         "Queue outside the Student Union for the opening: five extras standing in a row.",
         [delta("pedestrian", 5, 5), layout("line", "pedestrian", 5), near("Student Union entrance", 12, "pedestrian",
                                                                          min_count=5), only("pedestrian")],
         [arrange("pedestrian", "line", loc("at", "Student Union entrance"), count=5)]),
    case("arrangement", "indirect", "close_campus_drive_north", RUSSIAN,
         "Cars must not go on Campus Drive north of crossroads: put barriers in line across it, and also sign of "
         "construction.",
         [delta("road_barrier", 2, None), layout("line", "road_barrier", 2), some_in_lane(NORTH, "road_barrier"),
          some_in_lane(SOUTH, "road_barrier"), near("north crosswalk", 20, "road_barrier", min_count=2),
          delta("construction_sign", 1, 1), near("north crosswalk", 25, "construction_sign"),
          only("road_barrier", "construction_sign")],
         [arrange("road_barrier", "line", xy(0.0, 20.0), count=3, heading_deg=0),
          add("construction_sign", where=xy(5.5, 22.0))]),
    case("arrangement", "indirect", "jtekt_frontage_trees", NAIJA,
         "Make the JTEKT frontage fine well well - plant trees for one line there.",
         [delta("tree", 2, None), layout("line", "tree", 2, tolerance=1.5), near("JTEKT building entrance", 15, "tree",
                                                                                min_count=2), only("tree")],
         [arrange("tree", "line", loc("at", "JTEKT building entrance"), count=3)]),
    impossible("arrangement", "indirect", "flower_pots", REALTOR,
               "For instant kerb appeal, arrange a semicircle of flower pots round the fountain.",
               [arrange("flower pot", "ring", loc("at", "fountain"), count=8)]),
    # vague
    case("arrangement", "vague", "cordon_ahead", PILOT, "Set up a cordon somewhere ahead of the ego.",
         [delta(CORDON, 3, None), some_in_lane(EAST, CORDON),
          relative("in_front_of", EGO, CORDON, max_distance=100, tolerance_deg=30), only(*CORDON, "construction_sign")],
         [arrange("traffic_cone", "line", ahead_of(EGO, 35), count=5, heading_deg=90)],
         alternatives=any_shape(CORDON, 3)),
    case("arrangement", "vague", "pattern_lot_b", REALTOR, "Give lot B a nice pattern of cones for the open-day parking.",
         [delta("traffic_cone", 4, None), near("parking lot B", 2, "traffic_cone", min_count=4), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", "parking lot B"), count=8)], alternatives=any_shape("traffic_cone", 4)),
    case("arrangement", "vague", "order_with_benches", RUSSIAN, "Make some order with benches near fountain.",
         [delta("bench", 2, None), near("fountain", 15, "bench", min_count=2), only("bench")],
         [arrange("bench", "line", loc("next_to", "fountain"), count=3)], alternatives=any_shape("bench", 2)),
    case("arrangement", "vague", "cones_any_shape_lot_a", PARENT, "some cones in lot a any shape idc",
         [delta("traffic_cone", 3, None), near("parking lot A", 2, "traffic_cone", min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot A"), count=5)], alternatives=any_shape("traffic_cone", 3)),
    case("arrangement", "vague", "leafy_approach", REALTOR, "Line the approach to the Engineering Hall with something leafy.",
         [delta("tree", 2, None), layout("line", "tree", 2, tolerance=1.5),
          near("Engineering Hall entrance", 15, "tree", min_count=2), only("tree")],
         [arrange("tree", "line", loc("at", "Engineering Hall entrance"), count=3)]),
    case("arrangement", "vague", "warm_up_grid", COACH, "Set out a warm-up grid in lot A.",
         [delta("traffic_cone", 4, None), layout("cluster", "traffic_cone", 4, tolerance=10.0),
          near("parking lot A", 2, "traffic_cone", min_count=4), only("traffic_cone")],
         [arrange("traffic_cone", "grid", loc("at", "parking lot A"), count=9, columns=3, spacing=3.0)]),
    case("arrangement", "vague", "circle_of_something", PARENT, "make a circle of something round the fountain idk",
         [delta([*CORDON, *FURNITURE, *PEOPLE], 4, None),
          layout("ring", [*CORDON, *FURNITURE, *PEOPLE], 4, around="fountain"), only(*CORDON, *FURNITURE, *PEOPLE)],
         [arrange("bollard", "ring", loc("at", "fountain"))]),
    case("arrangement", "vague", "cones_some_shape", HEDGER,
         "Perhaps some cones... in some sort of shape? By the bus stop? I really don't mind which shape.",
         [delta("traffic_cone", 3, None), near("bus stop", 12, "traffic_cone", min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "bus stop"), count=4)], alternatives=any_shape("traffic_cone", 3)),
    case("arrangement", "vague", "same_again_bravo", PILOT, "Same again in lot Bravo.",
         [delta("traffic_cone", 4, 4), layout("line", "traffic_cone", 4),
          near("parking lot B", 2, "traffic_cone", scope="added", min_count=4), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B"), count=4)],
         setup=[turn("Request a line of four cones in lot Alpha.",
                     arrange("traffic_cone", "line", loc("at", "parking lot A"), count=4), planned=True)]),
    case("arrangement", "vague", "block_north_crosswalk", DIRECTOR, "Block off the north crosswalk while we shoot.",
         [delta(CORDON, 2, None), near("north crosswalk", 10, CORDON, min_count=2), only(*CORDON)],
         [arrange("traffic_cone", "line", loc("at", "north crosswalk"), count=5)], alternatives=any_shape(CORDON, 2)),
    case("arrangement", "vague", "barriers_round_rubble", RUSSIAN, "Put some barriers around place where is rubble.",
         [delta(CORDON, 3, None), layout("ring", CORDON, 3, around=RUBBLE), only(*CORDON)],
         [arrange("road_barrier", "ring", loc("at", RUBBLE))], setup=[RUBBLE_LOT_B]),
    case("arrangement", "vague", "cones_and_sign_library_front", NAIJA,
         "Arrange small cones for line for the Library front, and put one sign there too.",
         [delta("traffic_cone", 3, None), layout("line", "traffic_cone", 3), near("Library entrance", 12, "traffic_cone",
                                                                                min_count=3),
          delta(SIGNS, 1, 1), near("Library entrance", 12, SIGNS), only("traffic_cone", *SIGNS)],
         [arrange("traffic_cone", "line", loc("at", "Library entrance"), count=4),
          add("construction_sign", where=loc("next_to", "Library entrance"))]),
    impossible("arrangement", "vague", "hay_bales", RUSSIAN, "Make ring from hay bales around fountain, like in village.",
               [arrange("hay bale", "ring", loc("at", "fountain"), count=8)]),
    # erroneous
    case("arrangement", "erroneous", "fvie_cones_acros", PILOT,
         "Reqeust a line of fvie cones acros the eastbound lane, two-zero metres ahaed of the ego.",
         [delta("traffic_cone", 5, 5), layout("line", "traffic_cone", 5), some_in_lane(EAST, "traffic_cone"),
          near(None, 6, "traffic_cone", point=(-40.0, -1.75), min_count=3), only("traffic_cone")],
         [arrange("traffic_cone", "line", ahead_of(EGO, 20), count=5, heading_deg=90)]),
    case("arrangement", "erroneous", "rign_of_bolards", DIRECTOR, "Set a rign of bolards round the fountian.",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around="fountain"), only("bollard")],
         [arrange("bollard", "ring", loc("at", "fountain"))]),
    case("arrangement", "erroneous", "barirers_studnet_union", RUSSIAN, "Put 4 barirers in line near Studnet Union.",
         [delta("road_barrier", 4, 4), layout("line", "road_barrier", 4),
          near("Student Union entrance", 12, "road_barrier", min_count=4), only("road_barrier")],
         [arrange("road_barrier", "line", loc("at", "Student Union entrance"), count=4)]),
    case("arrangement", "erroneous", "bolards_round_bench", NAIJA, "Abeg arange 6 bolards for circle round the bench for bus stpo.",
         [delta("bollard", 6, 6), layout("ring", "bollard", 6, around=BENCH), only("bollard")],
         [arrange("bollard", "ring", loc("at", BENCH), count=6)]),
    case("arrangement", "erroneous", "row_of_tress_libary", REALTOR, "Plant a row of tress along the Libary frontage.",
         [delta("tree", 2, None), layout("line", "tree", 2, tolerance=1.5), near("Library entrance", 15, "tree",
                                                                              min_count=2), only("tree")],
         [arrange("tree", "line", loc("at", "Library entrance"), count=3)]),
    case("arrangement", "erroneous", "ten_cones_stright", COACH, "set out 10 cones in a stright line in lot b 1.5m apart",
         [delta("traffic_cone", 10, 10), layout("line", "traffic_cone", 10, spacing_min=1.3, spacing_max=1.7),
          near("parking lot B", 2, "traffic_cone", min_count=10), only("traffic_cone")],
         [arrange("traffic_cone", "line", loc("at", "parking lot B"), count=10, spacing=1.5)]),
    case("arrangement", "erroneous", "posts_cirlce_round_bin", PARENT, "put some posts in a cirlce round the bin pls",
         [delta("bollard", 4, None), layout("ring", "bollard", 4, around=BIN), only("bollard")],
         [arrange("bollard", "ring", loc("at", BIN), count=6)]),
    case("arrangement", "erroneous", "fuor_benches_row", HEDGER,
         "Perhaps fuor benches in a row near the fountian? If they fit, that is.",
         [delta("bench", 4, 4), layout("line", "bench", 4), near("fountain", 15, "bench", min_count=4), only("bench")],
         [arrange("bench", "line", loc("next_to", "fountain"), count=4)]),
    case("arrangement", "erroneous", "fuor_cars_lot_a", REALTOR,
         "Park fuor cars side by sdie in lot A - a car park that's in use sells itself.",
         [delta(CARS, 4, 4), layout("line", CARS, 4), near("parking lot A", 2, CARS, min_count=4), only(*CARS)],
         [arrange("passenger_car", "parking_row", loc("at", "parking lot A"), count=4)]),
    case("arrangement", "erroneous", "ring_it_sicx", DIRECTOR, "Ring it with cones - sicx of them.",
         [delta("traffic_cone", 6, 6), layout("ring", "traffic_cone", 6, around=NEW_SIGN), only("traffic_cone")],
         [arrange("traffic_cone", "ring", loc("at", NEW_SIGN), count=6)],
         setup=[turn("Put a construction sign at the north crosswalk.",
                     add("construction_sign", where=loc("at", "north crosswalk")), planned=True)]),
    case("arrangement", "erroneous", "westbound_line_and_barier", RUSSIAN,
         "Make line of cones acros westbound lane near east gate and also put barier there.",
         [delta("traffic_cone", 3, None), layout("line", "traffic_cone", 3), some_in_lane(WEST, "traffic_cone"),
          near("east gate", 15, "traffic_cone", min_count=3), delta("road_barrier", 1, 1),
          near("east gate", 15, "road_barrier"), only("traffic_cone", "road_barrier")],
         [arrange("traffic_cone", "line", xy(90.0, 1.75), count=4, heading_deg=90),
          add("road_barrier", where=xy(95.0, 1.75))]),
    case("arrangement", "erroneous", "bolards_jtekt_entrence", NAIJA, "abeg put 5 bolards for line front of the JTEKT entrence",
         [delta("bollard", 5, 5), layout("line", "bollard", 5), near("JTEKT building entrance", 12, "bollard",
                                                                    min_count=5), only("bollard")],
         [arrange("bollard", "line", loc("in_front_of", "JTEKT building entrance"), count=5)]),
    impossible("arrangement", "erroneous", "ring_of_baloons", PARENT, "make a ring of baloons round the fountain for the party",
               [arrange("balloon", "ring", loc("at", "fountain"), count=10)]),
]


# --- Appearance: looks, weather, clock and lights ------------------------------------------------------------
APPEARANCE_CASES: list[Json] = [
    # direct
    case("appearance", "direct", "moderate_fog", PILOT, "Set visibility conditions: fog, moderate.",
         [env(weather=["fog"], intensity_min=0.45, intensity_max=0.75), only(env=True)], [weather("fog", 0.6)]),
    case("appearance", "direct", "cue_street_lights", DIRECTOR, "Lighting cue: street lights on.",
         [env(street_lights="on"), only(env=True)], [lighting(street_lights="on")]),
    case("appearance", "direct", "suv_red", RUSSIAN, "Please to make SUV red.",
         [looks("red", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="red")]),
    case("appearance", "direct", "on_the_street_light", NAIJA, "Abeg on the street light.",
         [env(street_lights="on"), only(env=True)], [lighting(street_lights="on")]),
    case("appearance", "direct", "bench_navy", REALTOR, "Paint the bench navy - very on trend this year.",
         [looks("navy", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="navy")]),
    case("appearance", "direct", "heavy_rain", COACH, "Make it rain. Heavy.",
         [env(weather=["rain"], intensity_min=0.75), only(env=True)], [weather("rain", 0.9)]),
    case("appearance", "direct", "make_it_night", PARENT, "make it night", [env(night=True), only(env=True)],
         [clock("22:00")]),
    case("appearance", "direct", "half_six_evening", HEDGER,
         "Could the time be, perhaps, half past six in the evening? So 18:30, I mean.",
         [env(time_from="18:25", time_to="18:35"), only(env=True)], [clock("18:30")]),
    case("appearance", "direct", "one_niner_three_zero", PILOT, "Set time one-niner-three-zero local.",
         [env(time_from="19:25", time_to="19:35"), only(env=True)], [clock("19:30")]),
    case("appearance", "direct", "golden_hour_gold_suv", DIRECTOR, "Golden hour, please, and paint the SUV gold to match.",
         [env(time_from="17:00", time_to="20:30"), looks("gold", asset=SUV), only(assets=[SUV], env=True)],
         [clock("19:00"), paint([SUV], colour="gold")]),
    case("appearance", "direct", "lot_b_cars_white", REALTOR,
         "Make all the cars in lot B white - so much cleaner for the photos.",
         [looks("white", asset=CAR_W), looks("white", asset=SUV), looks("white", asset=CAR_E), only(assets=LOT_B_ROW)],
         [paint(LOT_B_ROW, colour="white")]),
    case("appearance", "direct", "off_the_fog", NAIJA, "Abeg off the fog.",
         [env(weather=["clear", "cloudy"]), only(env=True)], [weather("clear")], setup=[THICK_FOG]),
    impossible("appearance", "direct", "sandstorm", COACH, "Give us a sandstorm for the endurance session.",
               [weather("sandstorm", 0.8)]),
    # indirect
    case("appearance", "indirect", "low_visibility", PILOT, "Ceiling and visibility are far too good for this test.",
         [only(env=True)], [weather("fog", 0.7)],
         alternatives=[[env(weather=["fog"], intensity_min=0.3)], [env(weather=["rain", "snow"], intensity_min=0.6)]]),
    case("appearance", "indirect", "night_scene", DIRECTOR, "This is the night scene; the audience must believe it's late.",
         [env(night=True), only(env=True)], [clock("23:00")]),
    case("appearance", "indirect", "winter_conditions", RUSSIAN, "Our test must be for winter conditions.",
         [env(weather=["snow"]), only(env=True)], [weather("snow", 0.6)]),
    case("appearance", "indirect", "bench_like_danfo", NAIJA, "The bench colour no fine at all. Make e yellow like danfo.",
         [looks("yellow", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="yellow")]),
    case("appearance", "indirect", "late_afternoon_glow", REALTOR,
         "The listing photos need that warm, late-afternoon glow.",
         [env(time_from="15:00", time_to="19:45"), only(env=True)], [clock("17:30")]),
    case("appearance", "indirect", "wet_weather_fixture", COACH,
         "We've a wet-weather fixture on Saturday, so set the conditions for it.",
         [env(weather=["rain"]), only(env=True)], [weather("rain", 0.6)]),
    case("appearance", "indirect", "kid_cant_sleep", PARENT, "kid cant sleep unless its dark in there lol",
         [only(env=True)], [clock("22:00")], alternatives=darker()),
    case("appearance", "indirect", "suv_stand_out", HEDGER,
         "I wonder if the SUV would stand out more if it weren't so... plain? Something bright? Orange? Yes, orange.",
         [looks("orange", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="orange")]),
    case("appearance", "indirect", "vehicle_lights_run", HEDGER,
         "Should the vehicles be showing their lights, do you think? I rather think they should. Yes, let's have that.",
         [env(vehicle_lights="on"), only(env=True)], [lighting(vehicle_lights="on")]),
    case("appearance", "indirect", "designer_hates_it", DIRECTOR, "The designer hates it. Back to green.",
         [looks("green", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="green")],
         setup=[turn("Paint the bench red.", paint([BENCH], colour="red"), planned=True)]),
    case("appearance", "indirect", "night_driving_test", RUSSIAN,
         "For test of night driving: make it 23:00, and lights on streets must be on.",
         [env(time_from="22:55", time_to="23:05"), only(env=True)], [clock("23:00"), lighting(street_lights="on")],
         alternatives=[[env(street_lights="on")], [env(street_lights="auto")]]),
    case("appearance", "indirect", "sun_too_much", NAIJA, "The sun too much for this scene; make e be like evening time.",
         [env(time_from="17:00", time_to="21:30"), only(env=True)], [clock("20:00")]),
    impossible("appearance", "indirect", "glass_library", REALTOR,
               "Give the Library a glass frontage - it would lift the whole street.",
               [paint(["library"], material="glass")]),
    # vague
    case("appearance", "vague", "marginal_weather", PILOT, "Make the weather a bit marginal.",
         [env(weather=["cloudy", "rain", "fog", "snow"]), only(env=True)], [weather("cloudy", 0.6)]),
    case("appearance", "vague", "moodier_act", DIRECTOR, "Something moodier for this act.", [only(env=True)],
         [clock("20:30")],
         alternatives=[*darker(), [env(weather=["fog", "rain", "cloudy"])]]),
    case("appearance", "vague", "more_dark", RUSSIAN, "Make scene more dark.", [only(env=True)], [clock("21:00")],
         alternatives=darker()),
    case("appearance", "vague", "suv_nice_colour", HEDGER,
         "Could the SUV be a different colour? Something nice? I genuinely don't mind which.",
         [looks(ALL_COLOURS, asset=SUV), only(assets=[SUV])], [paint([SUV], colour="teal")]),
    case("appearance", "vague", "brighter_inviting", REALTOR, "Make everything look brighter and more inviting.",
         [only(env=True)], [lighting(exposure=1.3)],
         alternatives=[[env(exposure_min=1.1)], [env(street_lights="on")]]),
    case("appearance", "vague", "bit_of_weather", COACH, "Bit of weather for the session. Nothing silly.",
         [env(weather=["cloudy", "rain", "fog", "snow"], intensity_max=0.7), only(env=True)], [weather("rain", 0.3)]),
    case("appearance", "vague", "look_cold", PARENT, "make it look cold", [only(env=True)], [weather("snow", 0.6)],
         alternatives=[[env(weather=["snow"])], [env(weather=["fog"])]]),
    case("appearance", "vague", "bench_not_pink", HEDGER,
         "Could the bench be, I don't know, a different colour? Any colour. Well - not pink.",
         [looks([c for c in ALL_COLOURS if c != "pink"], asset=BENCH), only(assets=[BENCH])],
         [paint([BENCH], colour="blue")]),
    case("appearance", "vague", "ease_precipitation", PILOT, "Conditions improving. Ease off the precipitation.",
         [only(env=True)], [weather("rain", 0.4)],
         alternatives=[[env(weather=["rain"], intensity_max=0.75)], [env(weather=["clear", "cloudy"])]],
         setup=[HEAVY_RAIN]),
    case("appearance", "vague", "dim_a_touch", HEDGER, "Could it be dimmed, just a touch? Not a lot. A touch.",
         [only(env=True)], [lighting(exposure=0.8)],
         alternatives=[[env(exposure_max=0.95)], [env(time_from="17:30", time_to="06:00")]]),
    case("appearance", "vague", "more_calm_colour", RUSSIAN, "No, not so bright. Something more calm.",
         [looks(MUTED, asset=SUV), only(assets=[SUV])], [paint([SUV], colour="grey")],
         setup=[turn("Make SUV red.", paint([SUV], colour="red"), planned=True)]),
    case("appearance", "vague", "harmattan_morning", NAIJA,
         "Make the weather hazy small like harmattan, and make the time morning.",
         [env(weather=["fog", "cloudy"], intensity_max=0.75, time_from="05:30", time_to="11:30"), only(env=True)],
         [weather("fog", 0.4), clock("08:00")]),
    impossible("appearance", "vague", "tornado", PARENT, "set the weather to tornado lol the kid wants drama",
               [weather("tornado", 0.9)]),
    # erroneous
    case("appearance", "erroneous", "hevy_snow", PILOT, "Set wether to snow, hevy.",
         [env(weather=["snow"], intensity_min=0.75), only(env=True)], [weather("snow", 0.9)]),
    case("appearance", "erroneous", "streetlights_of", DIRECTOR, "Lighitng cue: streetlights of.",
         [env(street_lights="off"), only(env=True)], [lighting(street_lights="off")]),
    case("appearance", "erroneous", "suv_colur_blu", RUSSIAN, "Make SUV colur blu.",
         [looks("blue", asset=SUV), only(assets=[SUV])], [paint([SUV], colour="blue")]),
    case("appearance", "erroneous", "vehicle_lihgts", NAIJA, "Abeg on the vehicle lihgts.",
         [env(vehicle_lights="on"), only(env=True)], [lighting(vehicle_lights="on")]),
    case("appearance", "erroneous", "bnech_grene", REALTOR, "Paint the bnech a nice grene.",
         [looks("green", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="green")]),
    case("appearance", "erroneous", "tiem_0630", COACH, "set the tiem to 0630",
         [env(time_from="06:25", time_to="06:35"), only(env=True)], [clock("06:30")]),
    case("appearance", "erroneous", "make_it_raim", PARENT, "n make it raim pls", [env(weather=["rain"]), only(env=True)],
         [weather("rain", 0.6)], setup=[turn("make it night", clock("22:00"), planned=True)]),
    case("appearance", "erroneous", "littel_fog", HEDGER, "Perhaps a littel fog? Light fog. Very light, relly.",
         [env(weather=["fog"], intensity_max=0.4), only(env=True)], [weather("fog", 0.2)]),
    case("appearance", "erroneous", "expossure_point_eight", HEDGER,
         "Maybe the expossure could come down a bit? To 0.8, say. If that's a sensible number.",
         [env(exposure_min=0.75, exposure_max=0.85), only(env=True)], [lighting(exposure=0.8)]),
    case("appearance", "erroneous", "want_it_was_yelow", RUSSIAN, "No, I want that it was yelow.",
         [looks("yellow", asset=BENCH), only(assets=[BENCH])], [paint([BENCH], colour="yellow")],
         setup=[turn("Make bench red.", paint([BENCH], colour="red"), planned=True)]),
    case("appearance", "erroneous", "suv_blak_lights_on", NAIJA, "Abeg make the suv blak and on the stret lights.",
         [looks("black", asset=SUV), env(street_lights="on"), only(assets=[SUV], env=True)],
         [paint([SUV], colour="black"), lighting(street_lights="on")]),
    case("appearance", "erroneous", "hydrnat_orange", COACH, "make the hydrnat orange so the lads see it",
         [looks("orange", asset=HYDRANT), only(assets=[HYDRANT])], [paint([HYDRANT], colour="orange")]),
    impossible("appearance", "erroneous", "clock_27_15", DIRECTOR, "Set the clock to 27:15 for the dreem sequence.",
               [clock("27:15")]),
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
