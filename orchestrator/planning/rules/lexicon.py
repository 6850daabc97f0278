"""The rule planner's word lists: how people say each intent, weather, time, behaviour and goal.

These are plain English, not suite strings: the verbs and idioms a person uses for removing,
moving, turning or stopping things, words that state a goal rather than an action ("I want to
test the wipers" means rain), and nouns for things the catalog names differently ("greenery").
"""

from __future__ import annotations

# Word tables read best as paragraphs of phrases, not one phrase a line.
# fmt: off

SEARCH_STARTS = ("where", "remind me", "how many", "how much", "find", "list", "show me", "how many", "how much", "which", "what", "what's",
                 "is there", "are there", "locate", "search", "tell me", "i'd like to know",
                 "i would like to know", "do we have", "do you see", "any", "count", "give me",
                 "can you tell", "could you tell", "can you show")
PROPERTY_WORDS = ("mass", "masses", "weight", "weights", "weigh", "weighs", "how heavy", "size", "how big", "how long",
                  "how tall", "how wide", "dimensions", "properties", "length", "width", "height")
REMOVE_WORDS = ("remove", "delete", "get rid of", "get rid", "take away", "take out", "clear away", "erase",
                "eliminate", "despawn", "clear out", "destroy", "lose", "ditch", "scrap", "decommission", "strike",
                "throw away", "throw out", "take down", "dispose of", "clean up", "banish", "rip out", "tear out",
                "tidy up", "clear the", "clear it", "clear them", "clear lot", "clear parking lot", "empty", "emptied", "cleared of", "no more", "none left", "none of", "without any", "gone")
# "X is over", "the pedestrians went home": the goal is that X is gone.
GONE_WORDS = ("is over", "are over", "is finished", "are finished", "is done", "are done",
              "went home", "go home", "have left", "has left", "were collected", "was collected",
              "were removed", "are gone", "is gone", "should be empty", "should be clear", "was a mistake", "were a mistake",
              "no longer needed", "not needed", "out of scope", "be empty", "to be empty", "cleared", "been collected")
FEWER_WORDS = ("too many", "fewer", "less", "thin out", "one less", "so much", "as much", "that much")
ADD_WORDS = ("add", "create", "spawn", "place", "put", "insert", "set up", "install", "plant",
             "build", "bring in", "drop in", "give me", "i want", "i need", "we need", "we want",
             "there should be", "need a", "need some", "want a", "want some", "make a", "make some",
             "have a", "deploy", "station", "position a", "get a", "get some", "throw in")
MOVE_WORDS = ("move", "shift", "relocate", "put", "place", "send", "bring", "take", "push", "pull",
              "slide", "nudge", "scoot", "drag", "teleport", "reposition", "park", "transfer", "should be", "would be",
              "belongs", "wants its", "closer to", "over to", " to the ", "to ")
REVERSE_WORDS = ("reverse", "back up", "back out", "backwards", "backward", "back off", "go back")
SHIFT_VERBS = ("move", "shift", "nudge", "push", "slide", "budge", "relocate", "drag", "carry", "shove", "teleport")  # only ever a move
TURN_WORDS = ("turn", "turned", "rotate", "rotated", "spin", "flip", "face", "faces", "facing", "wrong way", "other way",
              "around", "about face")
STOP_WORDS = ("stop", "halt", "wait", "stand still", "stay put", "stay where", "freeze", "hold",
              "brake", "pause", "stationary", "stay")
SIDE_WORDS = (("forward", "forward", 1), ("forwards", "forward", 1), ("ahead", "forward", 1),
              ("back", "forward", -1), ("backward", "forward", -1), ("left", "left", 1),
              ("right", "left", -1), ("aside", "left", 1), ("over", "left", 1))
WEATHER_WORDS: dict[str, tuple[str, ...]] = {
    "rain": ("rain", "raining", "rainy", "drizzle", "drizzling", "downpour", "storm", "stormy", "wet",
             "showers", "pouring", "pour", "pours", "thunderstorm", "monsoon", "wipers", "wiper", "umbrella", "puddles", "precipitation", "soaked", "drenched", "sodden"),
    "fog": ("fog", "foggy", "mist", "misty", "haze", "hazy", "visibility", "murky", "smog"),
    "snow": ("snow", "snowy", "snowing", "snowstorm", "blizzard", "snowfall", "wintry", "winter", "icy", "sleet"),
    "cloudy": ("cloudy", "overcast", "clouds", "grey sky", "gloomy"),
    "clear": ("clear weather", "clear the weather", "clear sky", "sunny", "make it clear", "sun",
              "sunshine", "stop raining", "stop the rain", "no rain", "fine weather", "clear skies",
              "weather clear", "weather nice", "clear up", "clears up", "nice weather", "nicer weather",
              "better weather", "good weather", "dry", "blue sky", "stops raining", "lovely day", "nice day", "beautiful day"),
}
HEAVY = ("heavy", "heavily", "hard", "dense", "thick", "torrential", "strong", "intense", "lot of", "a lot",
         "blizzard", "downpour", "deluge", "cloudburst", "pouring", "pour", "monsoon", "storm", "very", "really", "poor", "bad", "terrible",
         "barely", "low visibility", "almost nothing", "next to nothing", "near zero", "like crazy", "like mad", "so much")
LIGHT = ("light", "lightly", "slight", "little", "bit of", "drizzle", "thin", "some", "gentle", "gently", "softly")
# (words, preset) in order: the first that matches wins, so "midnight" beats "night".
TIME_PRESETS = ((("midnight",), "midnight"), (("night", "nighttime", "night time", "nite", "dark", "darker",
                 "late at night", "sun has gone down", "after the sun goes down", "once the sun goes down", "after dark"), "night"),
                (("evening", "after work"), "evening"), (("dusk", "twilight", "getting dark"), "dusk"),
                (("sunset", "golden hour", "golden-hour", "sun going down", "sun is going down", "sun goes down", "sun setting", "sun is setting"), "sunset"), (("dawn", "first light"), "dawn"),
                (("sunrise", "sun coming up", "sun comes up", "early morning", "first thing"), "sunrise"),
                (("morning", "breakfast"), "morning"), (("afternoon",), "afternoon"),
                (("noon", "midday", "lunchtime", "lunch time", "lunch"), "noon"),
                (("daytime", "day time", "day", "daylight", "bright", "brighter"), "daytime"))
LIGHTS_WORDS = ("street lights", "streetlights", "street lamps", "headlights", "vehicle lights",
                "light up", "lights", "lamps", "lit")
ARRANGE_WORDS = ("around", "surround", "ring", "circle of", "encircle", "mark", "cordon", "enclose",
                 "line of", "row of", "in a line", "in a row", "in line", "in row", "grid", "along the",
                 "in circle", "in a circle", "fence off", "cordon off", "block off", "rows of",
                 "arrange", "arranged", "lay out", "laid out", "across the", "across", "like a grid", "formation", "slalom")
# Saying these about a road means: put barriers across it.
BLOCK_WORDS = ("block the road", "block the street", "close the road", "close the street",
               "block the lane", "close the lane", "shut the road", "road closed", "closed for",
               "block off", "close off", "road needs to be closed", "be closed")
BEHAVIOUR_WORDS: dict[str, tuple[str, ...]] = {
    "jaywalk": ("jaywalk", "jaywalking", "jaywalker", "cut across", "cuts across", "cutting across",
                "run across", "runs across", "darts across", "dart across", "dash across", "dashes across", "ego's path",
                "ego vehicle's path", "in front of the ego", "step out", "steps out", "steps onto the road", "step onto the road", "runs out", "run out", "darts out", "dart out"),
    "circle": ("skidpad", "skid pad", "circle", "circles", "circling", "donut", "donuts",
               "doughnut", "loop around", "round and round", "loops", "in a loop", "laps", "doing laps", "lapping"),
    "cross_road": ("cross the road", "crossing the road", "cross the street", "crossing the street",
                   "crosses the road", "crosses the street", "at the crosswalk", "on the crosswalk",
                   "get across", "go across", "walk across", "cross", "crosses", "crossing over",
                   "use the zebra", "uses the zebra", "across the road", "across the street", "over the road", "walking over the", "walk over the", "walks over the"),
    # matched with their inflections ("drive" is "drives", "driving"; "set off" is "setting off"; see edits.py)
    "drive_lane": ("drive", "drove", "move along", "cruise", "leave", "head", "pull away", "pull out", "go",
                   "start moving", "get going", "set off", "travel", "ride", "pedal", "cycle along", "roll along", "under way", "underway", "proceed", "crawl"),
    "parked": ("parked", "park", "parking", "stationary", "stopped"),
}
# Mass or collective nouns for catalog things: the words a person uses, not the catalog's.
CONCEPTS: dict[str, tuple[str, ...]] = {
    "tree": ("greenery", "vegetation", "shrub", "shrubs", "bush", "bushes", "foliage", "palm"),
    "bench": ("somewhere to sit", "to sit", "can sit", "sit down", "seat", "seats", "chairs", "chair"),  # not "sit" said of a thing ("the car should sit")
    "construction_sign": ("warn", "warned", "warning", "warning sign", "heads-up"),
    "road_barrier": ("fence off", "cordon off", "barriers", "block the road", "block off"),
    "pedestrian": ("foot traffic", "crowd", "passers-by", "someone", "somebody", "anyone", "anybody", "guy"),
    "trash_bin": ("rubbish", "litter", "garbage", "wrappers", "to throw"), "passenger_car": ("traffic",),  # after "foot traffic"
}
# Collective nouns that state a count by themselves: "a pair of" is two, "a row of" is not one.
COLLECTIVE_COUNTS = {"pair": 2, "couple": 2, "few": 3, "handful": 4, "bunch": 5, "lot": 6, "lots": 6, "load": 6, "loads": 6, "plenty": 6, "heaps": 6,
                     "tons": 6, "masses": 6, "dozens": 24, "row": 0, "line": 0, "ring": 0, "circle": 0, "group": 0, "set": 0, "cluster": 0, "crowd": 8}
ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "last": -1, "other": 2}
# Things whose colour people name instead of the colour.
COLOUR_OF = {"grass": "green", "leaves": "green", "sky": "blue", "sea": "blue", "snow": "white",
             "fire": "red", "blood": "red", "sun": "yellow", "banana": "yellow", "coal": "black",
             "night": "black", "chocolate": "brown", "wood": "brown", "asphalt": "grey", "road": "grey"}
# Words naming a group of any things ("the clutter at the bus stop").
GENERIC_THINGS = ("clutter", "stuff", "things", "junk", "mess", "everything", "objects", "items",
                  "obstacles", "anything", "something", "whatever")
# Maintenance words: what "the roadworks" or "the work area" are made of.
WORKS_WORDS = ("roadworks", "road works", "roadwork", "the works", "maintenance", "construction",
               "work area", "work zone", "building site", "worksite", "traffic control", "traffic management")
FILLER_STARTS = ("before", "after", "once", "when", "while", "since", "because", "as soon as")
PROMPT_INJECTION = ("ignore", "pretend", "disregard", "jailbreak", "system prompt", "bypass")
# Common words that carry no slot: knowing them is not "understanding less".
GRAMMAR = frozenset(
    """the and that this those these there here also with into from for its it's all any every
    please pls plz can you could would want need let's let front behind left right next beside
    near nearby centre middle scene map world campus sidewalk pavement lane road street maintenance
    construction work works performing doing manoeuvre maneuver mid-scale ackermann-steered path
    vehicle's across new another more them they their forward backward back metres meters metre meter m
    turn rotate degrees degree colour paint on off weather time o'clock speed radius clockwise
    entrance added you just was were again instead put look like heavier lighter intensity visible
    around there a an to of in at by is are be it i we me my our us some make have has had do does
    did will shall should must may might as if then now so but or not no yes up down over under out
    away onto on near its it one two three please bit little lot few many much how what where
    which who why when while before after thanks thank ok okay kindly side way up please go get
    put set give want like into via per each both either other same spot place area bay we're i'm you're they're that's
    outside inside between towards toward closer close far next along through west east north
    south westbound eastbound northbound southbound westwards eastwards northwards southwards
    coloured colored painted paint recolour just really very quite rather too so than test straight""".split()  # noqa: SIM905 - a paragraph of words
)
# fmt: on
