"""Does a plan cover every content phrase of a request? The signals check.py adds to polarity.

The plan-versus-request check (check.py) weighs what a plan does against what the words ask.
This module reads the structural signals that need more than a word: which named things the
plan leaves out altogether ("the hydrant and the bin" done as the hydrant only), a definite
reference to something that exists answered by adding another ("the SUV behind us" adds an
SUV), weather and clock times named but not set, a plural or bare removal done on only one
of many, and a place whose name the world does not know ("near the gym"). Each finding is a
sentence in plain words; check.py turns findings into a question or a refusal.
"""

from __future__ import annotations

import itertools
import math
import re
from collections import Counter
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning.answers import SEARCH_TOOLS
from drivetwin.orchestrator.planning.intent import (
    ADD_WORDS,
    ASKED_ABOUT,
    BARE_STATE,
    FEWER_WORDS,
    FORBIDDEN,
    HABITUAL,
    HOW_THINGS_GO,
    KEEP_SOME,
    NONE_THERE,
    PLACE_KIND,
    SAID_MISSING,
    WOULD_HELP,
    asks,
)
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.clock import clock_time
from drivetwin.orchestrator.planning.rules.edits import OFF_THE_ROAD, TIE_M
from drivetwin.orchestrator.planning.rules.environment import TIME_NOT_SET
from drivetwin.orchestrator.planning.rules.numbers import spelt_counts
from drivetwin.orchestrator.planning.rules.places import BETWEEN, BY_IT, PLACE_SAID, point_named, road_said, side_of
from drivetwin.orchestrator.planning.rules.reading import numbered_absent, numbered_picks, used_as_verb
from drivetwin.orchestrator.planning.rules.spelling import ASSET_ID, edits, english_words, is_known, vocabulary
from drivetwin.tools.appearance import TIME_PRESETS
from drivetwin.tools.base import ToolCall
from drivetwin.tools.search import compass_of, lane_under
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.scene import AssetInstance, Lane, Scene

# Words before a category that point at one already in the scene ("the SUV", "those cones").
_DEFINITE = ("the", "that", "this", "those", "these", "our", "my", "his", "her", "their", "your", "all", "every", "each", "both")
# What comes before a thing named bare as a clause's topic: nothing, a stop, a filler, a wish.
_BARE_TOPIC = re.compile(r"(?:^|[,.;:!?]|\b(?:ok|okay|so|and|then|now|hmm|um|want|need))\s*$")
# Verbs a thing is said bare after by a speaker who drops articles, and any article at all ("put" and
# "place" make new things as often as they move those there: "put bench near fountain" is asked about).
_BARE_VERBS = ("make", "move", "paint", "colour", "color", "shift", "park", "bring", "take", "turn")
_ARTICLE = re.compile(r"\b(?:a|an|the)\b")
# Words that ask for a new one even after a definite article ("the new bench", "another").
_NEW = re.compile(
    r"\b(add|adds|added|adding|new|another|(?<!out )(?<!apart )more(?!\s+[a-z]+(?:al|ful|ive|ous|ic|ible|able|ly|er|y)\b)(?! apart| spread)"
    r"|extra|create|spawn|"
    r"insert|second|additional|"
    r"copy|duplicate|row of|line of|ring of|grid of)\b"
)
# Prepositions after which a request names a place ("near the gym", "on the moon").
_PLACE_PREPOSITION = re.compile(
    r"\b(?:near|at|by|around|round|beside|next to|behind|in front of|inside|outside|into|onto|on|to|towards|"
    r"along|alongside|across|through|past|beyond|"
    r"(?:cordon|block|fence|close|seal|rope|tape)(?:s|ed|ing)? off|surround(?:s|ed|ing)?|encircl(?:e|es|ed|ing)|"  # "cordon off the ..."
    r"(?:far|away|distance|metres|meters|m)\b(?:[^,.;?]{0,40}?\s)?from|"  # "how far is the ego from the ..."
    r"close to|opposite|where is|where's|where are|between[^,.;?]{0,40}?\band|"
    r"(?:middle|centre|center|edge|corner|far end|far side) of)\s+the (?=([a-z][a-z' -]*))"  # "the middle of the lake"; (a look-ahead: "from the
)  # library to the pool" is read for both places; a known place masked to blanks is no name: "to the   anymore")
# Arguments by which a call says where: a repaired place name ends up in one of them.
_PLACE_ARG = re.compile(r"'(?:location|near|nearest_to|furthest_from|lane|asset|assets|target|x|y)':")
# Words after "the" that are part of a relation, not a place ("on the right", "to the north").
_RELATION_WORDS = frozenset(
    [
        "right",
        "left",
        "north",
        "south",
        "east",
        "west",
        "side",
        "middle",
        "centre",
        "center",
        "edge",
        "end",
        "corner",
        "way",
        "moment",
        "front",
        "back",
        "rear",
        "top",
        "bottom",
        "same",
        "other",
        "opposite",
        "far",
        "near",
        "first",
        "last",
        "next",
        "road",
        "street",
        "lane",
        "sidewalk",
        "pavement",
        "footway",
        "footpath",
        "walkway",
        "verge",
        "kerb",
        "curb",
        "ground",
        "scene",
        "world",
        "campus",
        "area",
        "spot",
        "place",
        "crossing",
        "intersection",
        "junction",
        "road's",
    ]
)
# Weather kinds a request names directly (a goal such as "test the wipers" is read by the planner).
_WEATHER_NAMES = ("rain", "snow", "fog", "cloud", "overcast", "drizzle", "downpour", "clear sky", "clear skies", "sunny", "sunshine")
# The kind of weather each of those names asks for, and words before a name that deny it or
# complain of it or say how it is now ("no rain", "it's too sunny", "it's raining, make it sunny").
_KIND_OF_WEATHER = {"rain": "rain", "drizzle": "rain", "downpour": "rain", "snow": "snow", "fog": "fog",
                    "cloud": "cloudy", "overcast": "cloudy",
                    "sunny": "clear", "sunshine": "clear", "clear sk": "clear"}
_WEATHER_DENIED = re.compile(r"(?:\b(?:no|not|without|stop|too|less|rid of|instead of|any more|anymore|than|it'?s|it is|currently|clear|lift"
                             r"|remove|kill|cancel|off|close|shut)\b"  # "turn off the fog", "off the rain", "close the rain": switched off
                             r"|n't\b)[^,.;]*$")  # "clear the fog", "lift the fog": away with it
_WEATHER_ENDED = re.compile(r"\w*(?:\s+\S+){0,3}?\s+(?:stops?|ends?|clears?|go(?:es)? away|lets? up|off)\b")
# Clock times said by name: the time tool has presets for them, checked as parts of the day.
_NAMED_TIMES = ("midnight", "noon", "midday")
# Parts of the day a request names as a time to set; "this morning" is when, not what.
_DAY_PART = re.compile(r"(?<!this )\b(morning|afternoon|evening|night|midnight|noon|midday|dusk|dawn|sunset|sunrise)\b")
# Words that open background ("where people relax", "before I plan the pedestrian test"):
# a category named after them is circumstance, not something the plan must act on.
_BACKGROUND = re.compile(r"\b(where|when|while|before|after|because|so that|so|since|until|unless"
                         r"|to (?:catch|board|meet|visit|watch))\b")  # "he walks to the stop to catch the bus": its purpose
# A reason said before ", so ..." ("the visitors are from JTEKT, so ..."): its things are the setting.
_SO_AFTER = re.compile(r"[^.;!?]*,\s*so\b")
_STATE_VERB = re.compile(r"\b(?:is|are|was|were|come|comes|came)\b")
_OUGHT = re.compile(r"[^,.;]*\b(?:should|must|needs? to|has to|have to|ought to|(?:i|we)(?:'d| would)? (?:need|want|like)|" + WOULD_HELP + r")\b")  # "..., so maybe two benches would help"
# A thing named after a preposition of place ("from behind the parked bus", "next to a bench")
# is where something is, not something the plan must act on.
_LOCATIVE = re.compile(
    r"\b(behind|beside|next to|in front of|near|around|by|past|alongside|opposite|across from|beyond"
    r"|(?:on|to) the (?:left|right|(?:north|south|east|west)(?:ern)?|far|other) (?:side )?of"  # "the car on the left of the SUV"
    r"|(?:the )?way of"  # "in the way of the people who walk": where it stands, not what to act on
    r"|across (?:the )?(?:road|street) from|(?:to the )?(?:north|south|east|west)(?:ern)?(?: side)? of"  # "the sedan east of the SUV"
    r"|towards?|(?:closer|nearer) to|nearer|(?:further|farther)(?: away)? from|away from"  # "5 m closer to the bench": where, not what
    r"|same colou?r as|colou?red like|match(?:es|ing)?(?: the colou?r of)?)\s+"  # "the same colour as the bus": a model, not what
    r"(?:(?:the|a|an|that|this|those|these|its|their|our)\s+)?(?:[a-z]+\s+)?$"
)
# A thing said to be left as it is: "keep the SUV.", "leave the two cars where they are", "leave the bench alone".
_SPARED_BEFORE = re.compile(r"\b(?:keep|keeping|leave|leaving)\s+(?:the|that|this|those|these|our|my|both|all)?\s*(?:two|three|\d+)?\s*(?:[a-z]+\s+)?$")
_SPARED_AFTER = re.compile(r"\w*\s*(?:[,.;!?]|$|where (?:it|they)|alone\b|as (?:it|they)|in place\b|untouched\b|be\b)")
# Category names that are also the planner's verbs ("stop the ego"): not a thing named.
_VERB_NAMES = frozenset(
    w for table in (lx.STOP_WORDS, lx.MOVE_WORDS, lx.TURN_WORDS, lx.REMOVE_WORDS) for w in table if " " not in w
)


# A move shorter than this has no direction worth judging (a nudge to clear an overlap).
MIN_MOVE_M = 0.2
# How far from the named direction a move may point: settling onto a lane or a free spot bends it.
DIRECTION_SLACK_DEG = 50.0


# Words that point back at what the last turn made or touched, when a request names nothing.
_BACK = re.compile(r"\b(them|those|these|they|it|there|the same|same again|that one|more|another|again)\b")
_PLURAL_POINTERS = ("them", "those", "these", "they")
# "There" is where the last turn worked, give or take a parking lot or a crossing.
THERE_RADIUS_M = 30.0


# Words before a category that ask for one not there yet ("a tree", "some cones", "another").
_INDEFINITE = frozenset(["a", "an", "some", "another", "new", "extra", "more", "additional"])
# "Inside the library", "into the JTEKT building": a building named after a word of containment.
_INSIDE = re.compile(r"\b(?:inside|into|within|(?:on |up |up on )?top of|(?:on |onto |up on )?(?:the )?(?:roof|rooftop) (?:of|from)|atop)(?: of)?"
                     r"\s+(?:the\s+)?([a-z][a-z ]*)"
                     r"|\b(?:on|onto|up on|up top|on top|atop)\s+(?:the\s+)?(?!the\b|roof\b)([a-z][a-z ]*?)(?:'s)?\s+(?:roof|rooftop)\b")  # "up on the library('s) roof"


@dataclass(frozen=True)
class Scope:
    """What a plan touches, as the coverage checks need it."""

    calls: tuple[ToolCall, ...]
    touched: tuple[AssetInstance, ...]
    removed: tuple[AssetInstance, ...]
    added: tuple[AssetInstance, ...]


@dataclass(frozen=True)
class Named:
    """A category the words name, with the text before it (in find_categories' own spelling)."""

    category: str
    plural: bool
    before: str
    after: str = ""

    def last_words(self, n: int) -> list[str]:
        return self.before.split()[-n:]


def named_in(masked: str) -> list[Named]:
    """Each category the words name, in order, with what comes before it ("the", "ten", "all")."""
    indexed = ph.normalise(masked)  # the text find_categories indexes
    return [Named(m.category, m.plural, indexed[: m.start], indexed[m.end :]) for m in ph.find_categories(masked)]


def _ids_of(scene: Scene, category: str) -> set[str]:
    return {a.id for a in scene.all_assets() if a.category == category}


def named_things(masked: str, categories: Iterable[str], scene: Scene) -> set[str]:
    """The categories a plan must act on: not ones named as background, as a verb, as the
    head of a compound ("suv car"), or as the start of a misspelt place ("bus stpo")."""
    wanted = set(categories)
    mentions = ph.find_categories(masked)
    masked = ph.normalise(masked)  # the text find_categories indexes
    places = [ph.normalise(n).strip() for lm in scene.landmarks for n in lm.names()]
    out = set()
    for i, m in enumerate(mentions):
        said = masked[m.start : m.end].strip()
        rest = re.findall(r"[a-z0-9']+", masked[m.start :])
        near_place = any(  # ("a car parked on the street": a word of its own, never "car park" misspelt)
            len(p.split()) > len(said.split()) and edits(" ".join(rest[: len(p.split())]), p) <= 2
            and all(w == v or w not in english_words() for w, v in zip(rest[: len(p.split())], p.split(), strict=False)) for p in places
        )
        compound = i > 0 and not masked[mentions[i - 1].end : m.start].strip()
        missing = NONE_THERE.search(masked[: m.start]) is not None  # "people keep dropping cans, there's no bin": wanted
        if (m.category not in wanted or (_in_background(masked, m.start) and not missing) or said in _VERB_NAMES
                or HABITUAL.match(masked, m.start) or FORBIDDEN.match(masked, m.end) or used_as_verb(masked, m.start, m.end)):
            continue
        if _LOCATIVE.search(masked[max(0, m.start - 40) : m.start]):
            continue
        if _SPARED_BEFORE.search(masked[max(0, m.start - 30) : m.start]) and _SPARED_AFTER.match(masked, m.end):
            continue  # "..., keep the SUV", "leave the two cars where they are": not to be touched
        if _SO_AFTER.match(masked, m.end) and _STATE_VERB.search(masked, m.end, m.end + 30):
            continue  # "the visitors are from JTEKT, so the SUV goes ...": who the reason is about
        if not (near_place or compound):
            out.add(m.category)
    return out


def _in_background(masked: str, at: int) -> bool:
    """Whether a word at `at` is said inside a clause of time, place or reason; "so" that leads to
    what should happen ("..., so the seat and the bin should go") leads to the request itself."""
    halfway = None if asks(masked) else BETWEEN.search(masked)  # "a bin between the bench and the sign": where it goes, not what
    sentence = masked[max(masked.rfind(".", 0, at), masked.rfind("?", 0, at), masked.rfind("!", 0, at)) + 1 :]
    if HOW_THINGS_GO.match(sentence.strip()):
        return True  # "people there must have nowhere to throw their wrappers": who the request is for
    return any(not (w.group(1) == "so" and _OUGHT.match(masked, w.end()))
               for w in _BACKGROUND.finditer(masked[:at])) or (halfway is not None and halfway.start("a") <= at < halfway.end("b"))


# Workers that set or tell the lights setting, which is what the lamps' being on or off is.
_LIGHTING_TOOLS = ("set_lighting", "describe_environment")


def missing_categories(categories: Iterable[str], scope: Scope, scene: Scene) -> list[str]:
    """Categories the request names that the plan neither touches nor names in any call."""
    said = " ".join(str(c.args) for c in scope.calls).lower()
    kinds = {c for members in md.groups_said(said).values() for c in members}  # a search for "vehicles"
    out = []
    for category in sorted(categories):
        if any(a.category == category for a in scope.touched) or category in kinds:
            continue
        if "light" in catalog()[category].tags and any(c.tool in _LIGHTING_TOOLS for c in scope.calls):
            continue  # "are the street lamps on?": the lights setting is what says
        if catalog()[category].motion == "vehicle" and any("vehicle_lights" in c.args for c in scope.calls):
            continue  # "the headlights on all the cars": every vehicle's lights are one setting
        if category in said or any(re.search(rf"\b{re.escape(i)}\b", said) for i in _ids_of(scene, category)):
            continue
        out.append(category)
    return out


# A pronoun pointing back at things just named, as the object of what is to be done ("... park them").
_POINTED_BACK = re.compile(r"\b(?:them|those|these|they)\b(?!\s+(?:ones\b|[a-z]+s\b))")


def _asks_for_new(masked: str) -> bool:
    """Whether a word asks for a new thing ("add", "another", "more cones"); "more" before a word
    that names no thing is a comparative ("some more nice colour", "more far from the road")."""
    def comparative(m: re.Match[str]) -> str:
        word = m.group(1)
        thing = ph.find_categories(f"{word} {m.group(2) or ''}") or word in _MORE_THINGS or word.isdigit() or word in ph.NUMBER_WORDS
        return m.group(0) if thing else f"rather {word} {m.group(2) or ''}"

    return _NEW.search(re.sub(r"\bmore\s+([a-z]+)(?:\s+([a-z]+))?", comparative, masked)) is not None


# Words after "more" that still ask for things: "more of them", "more people", "more please".
_MORE_THINGS = frozenset({"of", "than", "and", "then", "please", "ones", "one", "them", "people", "things", "stuff",
                          "traffic", "here", "there", "in", "at", "on", "by", "near", "to", "for", "like", "too"})


def asked_which_but_changed(masked: str, scope: Scope) -> list[str]:
    """Kinds the words ask about ("work out which bench is nearest", "what trees stand by the lot")
    that the plan adds, changes or takes away without looking anything up: a thing asked which is
    looked up, not edited (a command about it names it otherwise: "paint whichever bench is
    nearest"; a plan that looks up, then edits, answers and acts: "which car is nearest? paint it")."""
    if any(c.tool in SEARCH_TOOLS for c in scope.calls):
        return []
    asked = {m.category for m in named_in(masked)
             if any(w in ("which", "what") for w in m.last_words(2)) or m.last_words(3)[:2] == ["which", "of"]}
    return sorted({a.category for a in (*scope.added, *scope.touched, *scope.removed) if a.category in asked})


# A superlative of place said right after a thing's word: "lamp post nearest the fountain".
_PICKED_AFTER = re.compile(r"\s*(?:(?:that|which)(?:'s| is)\s+)?(?:nearest|closest|furthest|farthest)\b")


def definite_but_added(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """Categories referred to as existing ("the SUV", "those benches") that the plan adds anew
    while the scene has them and no word asks for a new one."""
    if _asks_for_new(masked):
        return []
    # "put the cones in a ring": a layout may make the things it arranges; it makes nothing else
    arranged = {c for call in scope.calls if call.tool == "arrange_assets" for c in call.args.get("categories", [])}
    out = []
    asks_to_add = ADD_WORDS.search(masked) is not None
    for m in named_in(masked):
        every = any(w in ("all", "every", "each", "both") for w in m.last_words(3))  # "line up all the cars": those there
        # "the three lot B cars lined up along Main Street": so many of them, counted as known, are those there
        every = every or _COUNTED_BACK.search(" ".join(m.last_words(4))) is not None
        # "stop sign to the other side of the road", "I want stop sign near ...": a thing named
        # bare as the clause's topic, with no word for adding, of which the scene holds one, is that one
        bare = (not m.plural and not asks_to_add and scene.count(m.category) == 1
                and _BARE_TOPIC.search(m.before) is not None)
        # "Car in front make slower na": a thing named bare as the topic, then a verb of changing it, is one there
        bare = bare or (not m.plural and not asks_to_add and scene.count(m.category) > 1 and _BARE_TOPIC.search(m.before) is not None
                        and any(w in _CHANGES_EXISTING for w in m.after.split()[:4]))
        # "make SUV colour blue", "move hydrant to other side of road": with no article at all, as some
        # speakers say it, the one thing of its kind the scene holds is as likely as a new one
        bare = bare or (not m.plural and scene.count(m.category) == 1 and _NEW.search(masked) is None
                        and any(w in _BARE_VERBS for w in m.last_words(1)) and not _ARTICLE.search(masked))
        # "Lamp post nearest the fountain too bright": a thing picked out by where it stands is one already there
        bare = bare or (not asks_to_add and scene.count(m.category) > 0 and _PICKED_AFTER.match(m.after) is not None)
        # "the red bench", but not "give the bus stop a bench": the nearest article is the noun's
        indefinite = m.last_words(1)[-1:] in (["a"], ["an"], ["some"], ["any"])
        # "cars in lot B: park them nose to tail": things said bare, then pointed back at, are those there
        said_back = m.plural and not indefinite and _POINTED_BACK.search(m.after) is not None
        # ("put bollards in a row, they look messy": what they look like now is said of those there)
        pointed_back = said_back and (not asks_to_add or re.search(r"\bthey(?:'re| are| look| seem| were)\b", m.after) is not None)
        if (not (bare or pointed_back or every or (any(w in _DEFINITE for w in m.last_words(2)) and not indefinite)) or not scene.count(m.category)
                or (m.category in arranged and not (every or said_back))):  # "the cars in lot B, line them up": those there
            continue
        replaced = any(a.category == m.category for a in scope.removed)  # "take the bin away and put a fresh one ..."
        if any(a.category == m.category for a in scope.added) and not replaced and m.category not in out:
            out.append(m.category)
    return out


# A definite article and a count before a noun: "the three cars", "those two benches".
_COUNTED_BACK = re.compile(r"\b(?:the|those|these|our|my)\s+(?:\d+|two|three|four|five|six|seven|eight|nine|ten)\b")


# Words right after a singular noun that single one out ("the car nearest the gate", "the tree
# by the bus stop", "the car on the left", "car 2"): the planner's pick is then the words'.
_SINGLES_OUT = re.compile(
    r"\s*(?:(?:directly|right|just|immediately|to the)\s+)?(?:(?:number |no\. |nr |# ?)?(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b(?!\s*(?:m|metres?|meters?|ft|feet|foot|yards?|degrees?|deg|km|kph|mph)\b)|in\b(?!\s+colou?r)|at\b|on\b|"
    r"near|by\b|beside|next|behind|outside|inside|of\b|from\b|closest|nearest|furthest|farthest|that\b|"
    r"which\b|who\b|with\b|parked|driving|moving|standing|across|opposite|(?:north|south)?[\s-]?(?:north|south|east|west)\w*\s+of\b|"
    r"most\b|least\b|[a-z]+est\b|[a-z]+most\b)"
)


def ambiguous_pick(masked: str, scope: Scope, scene: Scene, memory: Memory, place: str | None,
                   near: Callable[[AssetInstance], bool] | None) -> tuple[str, list[AssetInstance]] | None:
    """"The car" said of one of several cars, the words singling none out and no earlier turn
    making one of them the one meant, while the plan acts on some but not all of them: the
    category and every candidate (those at the place named, when the place holds some)."""
    recent = {i for turn in memory.live_turns() for i in (*turn.added, *turn.touched)}
    indexed = ph.normalise(masked)  # the text find_categories indexes
    for m in ph.find_categories(masked):
        if m.plural or indexed[: m.start].split()[-1:] not in (["the"], ["that"], ["this"]):
            continue
        if _SINGLES_OUT.match(indexed[m.end :]):
            continue
        candidates = [a for a in scene.assets if a.category == m.category]
        if any(re.search(rf"\b{re.escape(a.id)}\b", masked) for a in candidates):
            continue  # "the sedan passenger_car_1": singled out by its id
        if near is not None and place is not None and any(near(a) for a in candidates):
            candidates = [a for a in candidates if near(a)]
        acted = {a.id for a in scope.touched if a.category == m.category} - {a.id for a in scope.added}
        if len(candidates) < 2 or any(a.id in recent for a in candidates):
            continue
        if acted and len(acted & {a.id for a in candidates}) < len(candidates):
            return m.category, sorted(candidates, key=lambda a: a.id)
    return None


# Verbs that change a thing already there: "paint the truck", said where there is no truck,
# asks about a thing that is not there rather than for a new one.
_CHANGES_EXISTING = frozenset(["make", "paint", "colour", "color", "recolour", "recolor", "turn", "move", "shift",
                               "push", "pull", "nudge", "rotate", "drive", "slide", "relocate", "spin", "reverse",
                               "space", "spread", "straighten", "rearrange", "reposition", "tidy", "place", "position"])
# Verbs that handle a thing there when no word asks for a new one: "get the pedestrians off the road",
# "have the cyclist ride round", "let the bus go" (with "add"/"we need", "have the bus at the stop" may ask for one).
_HANDLES_EXISTING = frozenset(["get", "have", "let", "take", "send", "tell", "stop"])  # "park the truck in lot A" may ask for one
# Words that say the things were there before: "put the cones back where they were".
_AS_BEFORE = re.compile(r"\b(?:back (?:where|to where|in|into|at|on|to)|where (?:it|they) (?:was|were|used to be)|back in place)\b")


# What comes before "the <thing>" as a clause's subject: nothing, a stop, a joining word, or a
# question's auxiliary ("might the bus be in lot B?")...
_SUBJECT_OPENS = re.compile(r"(?:^|[,.;:!?]|\b(?:and|but|so|then|now|also|might|could|would|should|can|will|may|must|shall|does|did|is|are|has))\s*$")
# ...unless it is said to be missing ("the truck isn't there anymore": one is wanted, SAID_MISSING) or a role
# follows that brings one in ("the car ahead brakes", "the bus in front stops").
_ROLE_AFTER = re.compile(r"\s*(?:ahead|in front|leading|behind)\b")
# The rule lexicon's ways of asking for a thing ("i want", "we need"), as one pattern.
_LEXICON_ADDS = re.compile(rf"(?<![a-z])(?:{'|'.join(re.escape(w) for w in sorted(lx.ADD_WORDS, key=len, reverse=True))})(?![a-z])")


def absent_but_added(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """Categories a verb of change points at as there ("paint the truck red", and with no word asking
    for a new one, "get the pedestrians off the road") that the scene does not have, which the plan
    adds instead."""
    if _NEW.search(masked):
        return []
    out = []
    how = re.sub(r"\bmore\s+[a-z]+(?:ly|ful|ous)\b", "", masked)  # "drive more carefully" asks for no more of anything
    asks_for_new = ADD_WORDS.search(how) is not None or _LEXICON_ADDS.search(how) is not None
    for m in named_in(masked):
        before = m.last_words(2)
        points_at = len(before) == 2 and before[1] in _DEFINITE and (
            before[0] in _CHANGES_EXISTING or bool(_AS_BEFORE.search(masked)) or (before[0] in _HANDLES_EXISTING and not asks_for_new))
        # "the bus should drive more carefully", "might the bus be in lot B?": said of one there
        points_at = points_at or (before[-1:] == ["the"] and not asks_for_new and _SUBJECT_OPENS.search(m.before[: m.before.rfind("the")]) is not None
                                  and not _ROLE_AFTER.match(m.after) and not SAID_MISSING.search(m.after))
        if points_at and not scene.count(m.category) \
                and any(a.category == m.category for a in scope.added) and m.category not in out:
            out.append(m.category)
    return out


def indefinite_but_moved(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """Categories asked for as new ("a tree at lot A", "two benches by the fountain") that the
    plan takes from elsewhere in the scene, moving existing ones and adding none."""
    if all(c.tool == "set_asset_appearance" for c in scope.calls):
        return []  # "paint one car blue": one of those there; a new one is not painted
    new = {a.id for a in [*scope.added, *scope.removed]}
    # per kind: "a tree by the fountain and one bench there" may not add the tree and move a bench
    moved = {a.category for a in scope.touched if a.id != "ego" and a.id not in new} - {a.category for a in scope.added}
    out = []
    for m in named_in(masked):
        before = m.last_words(2)
        # "put tree at lot A": a bare noun after a placing verb may be a new one; the plan may not assume
        asked_new = bool(before) and (before[-1] in _INDEFINITE or before[-1] in ph.NUMBER_WORDS or before[-1].isdigit()
                                      or before[-1] in ("put", "place", "plant", "stick"))
        if before[-2:-1] and before[-2] in ("all", "both", "the", "those", "these", "first", "last", "other", "remaining"):
            asked_new = False  # "all three vehicles", "the two cars", "the last two cones": things already there, counted
        if before[-1:] == ["one"] and before[-2:-1] and before[-2] in _CHANGES_EXISTING - {"place", "position"}:
            asked_new = False  # "move one bench to the gate": one of those there
        if re.match(r"\s*(?:number |no\.? |#)?\d+\b(?!\s*(?:m\b|metres?|meters?|km|ft|feet|foot|yards?|m/s|mph|km/h|kph|seconds?|s\b|%))",
                    m.after):
            asked_new = False  # "put passenger car 2 in lot A": that one, by its number ("one car 25 metres ahead" is new)
        if asked_new and m.category in moved and m.category not in out:
            out.append(m.category)
    return out


# A new thing said to go "near the bench" stands at most this far from one.
NEAR_THING_M = 12.0
_BESIDE = re.compile(r"\b(?:near|by|beside|next to|close to|alongside)\s+(?:the|that|this|our)\s+$")


# A thing picked out by what it stands by, and a place it goes to said after: "the lamp post (that's) by the stop sign ... to the".
_PICKED_BY = re.compile(r"\b(?:the|that|this)\s+[a-z ]{1,20}?\s+(?:(?:that'?s|which is|right|just)\s+)*"
                        r"(?:near|by|beside|next to|close to)\s+(?:the|that|this|our)\s+$")
_GOES_ON_TO = re.compile(r"\b(?:to|into|onto|towards?)\s+(?:the|a|an|lot|parking)\b")


def away_from_thing(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """Things the words put beside a thing there ("stick a bin near the bench", "it should be by
    the hydrant") that the plan puts or leaves far from every thing of that kind."""
    out = []
    removed = {a.id for a in scope.removed}
    beside = [m for m in named_in(masked) if _BESIDE.search(m.before)]
    # with one thing to be by, whatever the plan puts or moves; with more, each clause's own (new) things
    placed = list({a.id: a for a in [*scope.added, *scope.touched] if a.id not in removed}.values()) \
        if len(beside) == 1 else list(scope.added)
    # where each thing stands after the plan: "the bench to the fountain and the bin next to the bench" is the bench moved
    after = {a.id: a for a in [*scene.all_assets(), *scope.added, *scope.touched] if a.id not in removed}
    for m in named_in(masked):
        anchors = [a for a in after.values() if a.category == m.category]
        if not _BESIDE.search(m.before) or not anchors or (_PICKED_BY.search(m.before) and _GOES_ON_TO.search(m.after)):
            continue  # "move the lamp post by the stop sign to the Engineering Hall": which lamp, not where
        far = [a for a in placed if a.category != m.category
               and min(math.hypot(a.pose.x - b.pose.x, a.pose.y - b.pose.y) for b in anchors) > NEAR_THING_M]
        if far:
            out.append(f"you said near the {m.category.replace('_', ' ')}, but the plan puts "
                       f"{', '.join(a.id for a in far)} more than {NEAR_THING_M:g} m from any")
    return out


def landmark_thing_changed(masked: str, scope: Scope) -> list[str]:
    """Things named only to say where something else is ("the orange one next to the bench") that
    the plan removes or changes itself."""
    named = named_in(masked)
    beside = {m.category for m in named if _BESIDE.search(m.before)}
    only_beside = beside - {m.category for m in named if not _BESIDE.search(m.before)}
    added = {a.id for a in scope.added}
    hit = sorted({a.id for a in scope.touched if a.category in only_beside and a.id not in added})
    return [f"you named {', '.join(hit)} to say where the thing is, but the plan changes it"] if hit else []


def off_the_side(low: str, scope: Scope, scene: Scene) -> list[str]:
    """Things the plan touches that are not on the side of a road or place the words name
    ("the street lights on the north side of Main Street")."""
    side = side_of(low, scene)
    if side is None:
        return []
    said, beyond = side
    wrong = sorted({a.id for a in [*scope.removed, *scope.added, *scope.touched] if a.id != "ego" and not beyond(a)})
    if not wrong:
        return []
    return [f"you said the {said}, but the plan takes in " + ", ".join(wrong[:6]) + (" and more" if len(wrong) > 6 else "")]


def inside_building(masked: str, scene: Scene) -> list[str]:
    """Putting something inside a building, which this world's buildings cannot hold."""
    said_words = set(re.findall(r"[a-z]+", masked.lower()))
    named = [b for b in scene.buildings if (words := re.findall(r"[a-z]+", b.name.lower())) and words[0] in said_words]
    for m in _INSIDE.finditer(masked):
        said = m.group(1) or m.group(2)
        for building in scene.buildings:
            name = ph.normalise(building.name).strip()
            # "inside the big glass building, the JTEKT one": a building described, the only one named
            described = named == [building] and re.match(r"(?:[a-z]+ ){0,3}building\b", said) is not None
            if name and (said.startswith(name) or name.startswith(said.strip()) or described):
                return [f"things cannot go inside or on top of the {building.name} in this world, only around it "
                        "(its entrance is the nearest place)"]
    return []


# Any word about the weather, the time, the light or the feel of the day: a plan may change them.
_ENVIRONMENT_SAID = re.compile(r"\b(?:weather|sky|skies|sun\w*|cloud\w*|rain\w*|snow\w*|fog\w*|mist\w*|hail\w*|storm\w*|wet|dry"
                               r"|wind\w*|drizzl\w*|pour\w*|ic[ey]|frost\w*|wint\w*|summer\w*|autumn\w*|spring|season\w*|dreich"
                               r"|time of day|the time|clock|hours?|o'?clock|am|pm|daytime|daylight|daybreak|night\w*|morning|afternoon|evening|noon|midday|midnight|dusk"
                               r"|dawn|sunset|sunrise|dark\w*|\w*light\w*|lit|\w*lamps?|bright\w*|dim\w*|dull|gloom\w*|grey|gray|exposure"
                               r"|mood\w*|atmospher\w*|spooky|eerie|scene|look|feel\w*|vibe|arvo|late|early|golden|blue hour|visib\w*"
                               r"|wiper\w*|umbrella\w*|puddle\w*|slippery|glare|shadow\w*|lunch\w*|breakfast|dinner|commute|rush hour)\b"
                               r"|\d{1,2}[:.]\d\d")


def environment_unasked(low: str, masked: str, calls: tuple[ToolCall, ...]) -> list[str]:
    """Weather, time or lights a plan changes when the words are about a thing and say nothing
    of any of them ("slow the test car down a bit" done by making it cloudy); words about no thing
    may mean the day ("I want to test the wipers", "at lunchtime")."""
    changed = [c.tool for c in calls if c.tool in ("set_weather", "set_time_of_day", "set_lighting")]
    about_a_thing = bool(named_in(masked)) or re.search(r"\bego\b", masked) is not None or ASSET_ID.search(masked) is not None
    if not changed or not about_a_thing or _ENVIRONMENT_SAID.search(low):
        return []
    what = {"set_weather": "the weather", "set_time_of_day": "the time", "set_lighting": "the lights"}
    return [f"the plan changes {what[changed[0]]}, which your words do not mention"]


def environment_left_out(low: str, calls: tuple[ToolCall, ...]) -> list[str]:
    """Weather or time of day the request names that no call sets (or sets to another time)."""
    tools = {c.tool for c in calls}
    out = []
    weather = [w for w in _WEATHER_NAMES if re.search(rf"\b{w}", low)]
    if weather and "set_weather" not in tools:
        out.append(f"you mentioned {weather[0]}, but the plan does not set the weather")
    kinds_set = {str(c.args.get("kind")) for c in calls if c.tool == "set_weather"}
    for name, kind in _KIND_OF_WEATHER.items():
        said = re.search(rf"\b{name}", low)
        if (said and kinds_set and kind not in kinds_set and not _WEATHER_DENIED.search(low[: said.start()][-24:])
                and not _WEATHER_ENDED.match(low[said.end() :])  # "make the rain stop"
                and not (kind == "cloudy" and kinds_set & {"rain", "snow"})):  # rain falls from clouds
            out.append(f"you mentioned {name}, but the plan sets the weather to {', '.join(sorted(kinds_set))}")
            break
    lamps = LAMPS_SWITCHED.search(low)  # "force the street lights on", "switch the lamps off"
    if lamps is not None and not any(c.tool == "set_lighting" and "street_lights" in c.args for c in calls):
        out.append(f"you said the street lights {lamps.group('state') or lamps.group('state2')}, but the plan does not switch them")
    clock = clock_time(low)
    day = _DAY_PART.search(TIME_NOT_SET.sub(" ", low))  # not "all morning", "like a Sunday morning", "not night"
    day_part = day.group(1) if day else None
    # "the quad is too dark at night, it needs a lamp post": the night says when lights are needed
    lights_added = any("street_light" in (c.args.get("category"), *c.args.get("categories", ())) for c in calls)
    if (clock or (day_part and "set_lighting" not in tools and not lights_added)) and "set_time_of_day" not in tools:
        out.append(f"you mentioned {clock.text if clock else day_part}, but the plan does not set the time")
    times = [str(c.args.get("time")) for c in calls if c.tool == "set_time_of_day"]
    if clock is not None and clock.text not in _NAMED_TIMES and times and str(clock) not in times:
        out.append(f"you said {clock.text} ({clock}), but the plan sets the time to {times[0]}")
    parts = [p for p in _DAY_PART.findall(low) if p in _HALF_OF_DAY]
    halves = {_HALF_OF_DAY[p] for p in parts}
    if clock is None and len(halves) == 1 and times:  # "just after sunrise" is never set as sunset
        set_hour = _hour_of(times[-1])
        if set_hour is not None and _half_of(set_hour) not in (None, *halves):
            out.append(f"you said {parts[0]}, but the plan sets the time to {times[-1]}")
    return out


# Street lights switched by name: "turn the street lights on", "force the lamps off", "lamps on".
LAMPS_SWITCHED = re.compile(r"\b(?:street ?lights?|street ?lamps?|lamp ?posts?|lamps)\b(?:\s+\w+){0,2}?\s+(?P<state>on|off)\b"
                             r"(?!\s+(?:the|a|an|its|this|that|each|every|either|both|main|campus)\b)"
                             r"|\b(?:switch|turn|put|force|flip|set)\w*\s+(?P<state2>on|off)\s+(?:all\s+)?(?:the\s+)?(?:street ?lights?|street ?lamps?|lamps)\b")
# The parts of the day on either side of noon, and which a time set falls in.
_HALF_OF_DAY = {"dawn": "morning", "sunrise": "morning", "morning": "morning",
                "sunset": "evening", "dusk": "evening", "evening": "evening", "night": "evening"}


def _hour_of(time: str) -> int | None:
    said = TIME_PRESETS.get(time, time)
    return int(said[:2]) if re.fullmatch(r"\d\d:\d\d", said) else None


def _half_of(hour: int) -> str | None:
    return "morning" if 4 <= hour < 12 else "evening" if hour >= 17 or hour < 4 else None


# Words that keep part of a kind: "some trees", "a few of the cones", "thin them out", "all but one".
_PART_SAID = re.compile(r"\b(?:some|a few|a couple|several|a handful|most|half|fewer)\b")
_THINNED = re.compile(r"\bthin\w*\b(?: \w+)? out\b|\bthin(?:ned)? (?:down|the)\b")


# A thing said to stand in the way ("there's a tree blocking the view of the library"): the one there, a trouble.
_IN_THE_WAY = re.compile(r"\bthere(?:'s| is| are)\s+(?:a|an|some|one|two|the)\s+(?:[a-z]+\s+){0,2}?(?P<thing>[a-z]+)\s+"
                         r"(?:blocking|in the way|obstructing|hiding|covering|in front of|spoiling|ruining)\b")


def trouble_added(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """Kinds the words say stand in the way, of which the plan adds one beside one already there
    (where it puts the new one, the old one stands: that one was meant)."""
    out = []
    for said in _IN_THE_WAY.finditer(masked):
        kinds = {m.category for m in ph.find_categories(f" {said.group('thing')} ")}
        beside = {a.category for a in scope.added if a.category in kinds and any(
            b.category == a.category and math.dist((a.pose.x, a.pose.y), (b.pose.x, b.pose.y)) <= IN_THE_WAY_M for b in scene.assets)}
        out += [f"you said the {k.replace('_', ' ')} there is in the way, but the plan adds another" for k in sorted(beside)]
    return out


# How near a thing said to be in the way a new one of its kind must go for the words to mean the one there.
IN_THE_WAY_M = 20.0


def all_when_some(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """A kind the words take only part of ("take away some trees", "thin them out", "every car in
    lot B bar one") of which the plan removes every one there is."""
    if not scope.removed:
        return []
    removed = Counter(a.category for a in scope.removed)
    every = {c for c, n in removed.items() if n == scene.count(c)}
    if (KEEP_SOME.search(masked) or _THINNED.search(masked)) and every == set(removed) and len(scope.removed) >= 2:
        return [f"you asked to keep some, but the plan removes all {len(scope.removed)}"]  # "all the cars in lot B bar one"
    if FEWER_WORDS.search(masked) and not re.search(r"\b(?:all|every|each|none|any more|anymore|couple|few|one|two|three|four|five|\d+)\b", masked) \
            and every == set(removed) and len(scope.removed) >= 2:
        return [f"you asked for fewer, but the plan removes all {len(scope.removed)}"]  # "we don't need so many lamps"
    partly = {m.category for m in named_in(masked) if _PART_SAID.search(" ".join(m.last_words(3)))}
    return [f"you asked to keep some of the {c.replace('_', ' ')}s, but the plan removes all {removed[c]}"
            for c in sorted(every & partly) if removed[c] >= 2]


def partial_removal(masked: str, scope: Scope, scene: Scene, limited: bool) -> list[str]:
    """A plural or bare category ("remove cones", "get rid of pedestrian") of which the plan
    removes only some, with no number, place or state in the request to say which."""
    if limited or not scope.removed or re.search(r"\b(fewer|less|too many|thin|some|most|(?<!every )(?<!each )one of|a few|half|a couple|a pair|several|a handful)\b", masked):
        return []
    out = []
    for m in named_in(masked):
        before = m.last_words(3)  # "the car", "the red car": one
        single = any(w in ("a", "an", "one", "the", "that", "this") for w in before[-2:]) if before else False
        if single and not m.plural:
            continue
        gone = sum(1 for a in scope.removed if a.category == m.category)
        there = scene.count(m.category)
        if 0 < gone < there:
            out.append(f"you named {m.category.replace('_', ' ')}s, but the plan removes {gone} of the {there}")
    for word, members in md.groups_said(masked).items():  # "get rid of all the signs": every kind called a sign
        if not re.search(rf"\b(?:all|every|each)(?:\s+one)?\s+(?:of\s+)?(?:the\s+|those\s+|these\s+)?(?:\w+\s+)?{word}", masked):
            continue
        called = [c for c in members if word in c.split("_")] or list(members)  # a traffic light is no "sign" to most
        gone = sum(1 for a in scope.removed if a.category in called)
        there = sum(scene.count(c) for c in called)
        if 0 < gone < there:
            out.append(f"you said all the {word}s, but the plan removes {gone} of the {there}")
    return out


# A part of what was pointed at: "about half of them", "some of those", "most of these", "one of them".
_PART_OF = re.compile(r"\b(?:half|most|some|a few|a couple|part|a third|a quarter|one|two|three|four|\d+|either|another) of (?:them|those|these)\b")


def back_reference(masked: str, categories: Iterable[str], scope: Scope, memory: Memory, scene: Scene,
                   counted: bool) -> list[str]:
    """A request that names nothing itself but points back ("move them left", "two more there",
    "drop two of those") done on other things, on fewer than all of them, or somewhere else."""
    pointer = _BACK.search(masked)
    live = memory.live_turns()
    if pointer is None or set(categories) or not live or not scope.touched:
        return []
    last = live[-1]
    earlier = [*last.added, *last.touched]
    kinds = {_category_of(i, scene) for i in earlier} - {None}
    if not kinds:
        return []
    said = pointer.group(1)
    out = []
    around = {str((c.args.get("location") or {}).get("target")) for c in scope.calls if c.tool in ("add_asset", "arrange_assets")}
    placed_by = {a.id for a in scope.added} if around & set(earlier) else set()  # "cordon it off with cones": it is where
    strays = sorted({a.category for a in scope.touched if a.category not in kinds and a.id != "ego" and a.id not in placed_by})
    if strays:
        out.append(f"you said {said!r} after a turn about {', '.join(sorted(str(k) for k in kinds))}, "
                   f"but the plan acts on {', '.join(strays)}")
    existing = [i for i in dict.fromkeys(earlier) if scene.asset(i) is not None]
    acted = {a.id for a in scope.touched}
    acted |= {str(c.args["asset"]) for c in scope.calls if c.tool == "move_asset" and c.args.get("asset")}  # "spread them out": the middle one stays
    counted = counted or KEEP_SOME.search(masked) is not None or _PART_OF.search(masked) is not None  # "just leave one of them"
    if said in _PLURAL_POINTERS and not scope.added and not counted and 0 < len(acted & set(existing)) < len(existing):
        out.append(f"you said {said!r} ({len(existing)} of them), but the plan acts on {len(acted & set(existing))}")
    if said == "there" and last.focus is not None and scope.added:
        fx, fy = last.focus
        far = [a.id for a in scope.added if math.hypot(a.pose.x - fx, a.pose.y - fy) > THERE_RADIUS_M]
        if far:
            out.append(f"you said 'there' (where the last turn worked), but the plan puts {', '.join(far)} elsewhere")
    return out


# Words that point at things without naming their kind ("it", "that thing", "everything there",
# "whatever is parked", "the vehicles"): a plan may act on what they point at.
_POINTS = re.compile(
    r"\b(it|its|him|her|his|he|she|them|those|these|they|this|that|one|ones|thing|things|everything|anything|all|"
    r"whatever|everyone|"
    r"everybody|someone|somebody|person|people|vehicles?|signs?|lights?|"
    + "|".join(re.escape(w) for w in (*lx.GENERIC_THINGS, *lx.WORKS_WORDS)) + r")\b"
)


def unpointed(masked: str, scope: Scope, scene: Scene) -> list[AssetInstance]:
    """Things already there that the plan changes or removes while the words point at nothing:
    no kind, id, place, lane or pointing word ("broken concrete in the lane" done by painting
    a parked car concrete)."""
    acted = [a for a in scope.touched if a.id != "ego" and a not in scope.added]
    if not acted or named_in(masked) or _POINTS.search(masked) or KEEP_SOME.search(masked) or md.groups_said(masked) \
            or md.SHADE_ALONE.match(masked.strip()):  # "nah, darker": what was just painted
        return []
    low = ph.normalise(masked)
    if any(ph.normalise(n).strip() in low for lm in scene.landmarks for n in lm.names()):
        return []
    if OFF_THE_ROAD.search(low.strip()) and all(a in scope.removed and lane_under(a, scene.roads.lanes) for a in acted):
        return []  # "clear the road": what stands on it
    if any(re.search(rf"\b{re.escape(i)}\b", masked) for a in acted for i in (a.id, a.id.replace("_", " "))):
        return []
    # a mass word for their kind points at them ("drop the greenery": the trees)
    return [a for a in acted if not any(re.search(rf"\b{re.escape(w)}\b", low) for w in lx.CONCEPTS.get(a.category, ()))]


# Words that ask for more of what is there, or for more going on, without naming a kind ("two
# more", "same again", "populate the quad", "liven it up"): a plan may add what they ask for.
_MORE_OF = re.compile(r"\b(?:more|another|again|same|extra|copy|copies|duplicate|populate\w*|fill\w*|crowd\w*|busy|busier"
                      r"|livelier|liven|lively|life|activity|traffic|furnish\w*|dress\w*|decorat\w*|something|anything"
                      # closing or marking off a way puts things on it: "close Main Street at the gate"
                      r"|ditto|likewise|repeat\w*|as before|clos\w*|shut\w*|block\w*|barricad\w*|cordon\w*|fence\w*|seal\w*|mark\w*|divert\w*|narrow\w*)\b")


def unnamed_added(masked: str, scope: Scope) -> list[AssetInstance]:
    """New things a plan adds while the words name no kind, point at nothing and give no word for
    theirs ("darker, please" done by adding a pedestrian, "slow the test car down" by adding a bus)."""
    low = ph.normalise(masked)
    if not scope.added or named_in(masked) or _POINTS.search(masked) or _MORE_OF.search(low) or BARE_STATE.search(low):
        return []  # "the junction looks bare": what is missing is wanted, whatever fills it
    return [a for a in scope.added if not any(re.search(rf"\b{re.escape(w)}\b", low) for w in lx.CONCEPTS.get(a.category, ()))]


def circumstance_added(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """Kinds a plan adds that the words name only as the setting of the request, never as what to
    act on (see named_things): "put it where people actually go", "the kids at the fountain reckon
    there's no shade", "a bench next to the tree" done by adding people or a tree."""
    mentions = ph.find_categories(masked)
    acted_on = named_things(masked, {m.category for m in mentions}, scene)
    indexed = ph.normalise(masked)  # the text find_categories indexes
    asked = {m.category for m in mentions if _added_by_verb(indexed, m.start)}  # "..., add two benches there"
    named = {m.category for m in mentions}
    # the ones who wait, want or need, as they are ("students wait at the union for long"): none asked for
    doers = set() if ADD_WORDS.search(indexed) else {m.category for m in mentions if m.plural and re.search(
        _CLAUSE_START + r"(?:the |our |all the |all |many |lots of )?$", indexed[: m.start]) and _DOES_THINGS.match(indexed[m.end :])}
    return [c for c in dict.fromkeys(a.category for a in scope.added)
            if (c in named and c not in acted_on and c not in asked) or c in doers]


# Where a clause starts; what its subject does as it always is (not what a scene should show: "pedestrians cross").
_CLAUSE_START = r"(?:^|[,.;:!?]|\b(?:and|but|so|because|since|as|while|when))\s*"
_DOES_THINGS = re.compile(r"\s*(?:always |often |usually |never |still |all )?(?:wait|keep|have|need|want|complain|like|hate|love)\b")


def _added_by_verb(low: str, at: int) -> bool:
    """Whether a word of adding governs the thing named at `at` in its clause, with no clause of
    time, place or reason between ("add two benches there", not "put it where people go")."""
    start = max(low.rfind(p, 0, at) for p in ",;.!?") + 1
    verbs = [*ADD_WORDS.finditer(low, start, at), *_LEXICON_ADDS.finditer(low, start, at)]
    last = max((v.end() for v in verbs), default=None)
    return last is not None and not _BACKGROUND.search(low[last:at])


# A thing of the speaker's ("my truck", "our van") spoken of, not asked for: the subject of what it
# does or needs ("my truck can't park here", "my truck needs the room"), or after a preposition
# ("ice on my truck roof"). "Park my truck in lot A" and "my truck, east gate" ask for one.
_POSSESSED = re.compile(r"(?:^|[,.;:!?]|\b(?:so|because|since|as|and|but|cos|cause|while|when|if))\s*(?:my|our|his|her|their|your)\s+$")
_POSSESSED_BY = re.compile(r"\b(?:on|in|into|onto|for|like|of|with|to|from|by|near|behind|beside|past|under|than)\s+(?:my|our|his|her|their|your)\s+$")
# Someone's thing set to do something: "have my guy cruise over", "get our car to park".
_HAVE_MY = re.compile(r"\b(?:have|get|let|make|tell)\s+(?:my|our|his|her|their|your)\s+$")
_DOES = re.compile(r"\s*(?:'s\s+\w+ing|(?:\w+\s+)?(?:can|can't|cannot|could|couldn't|needs?|is|isn't|are|aren't|was|wasn't|has|had|have"
                   r"|will|won't|would|wouldn't|should|must|does|doesn't|did|didn't|keeps|gets|got|wants?|takes?))\b")


def possessed_added(masked: str, scope: Scope) -> list[str]:
    """Kinds a plan adds that the words only speak of as someone's ("my truck can't park with a
    hydrant there, so that hydrant has to go" done by adding a truck), with no word of adding."""
    if not scope.added or ADD_WORDS.search(masked):
        return []
    out = []
    low = ph.normalise(masked)
    for category in dict.fromkeys(a.category for a in scope.added):
        said = [n for n in named_in(masked) if n.category == category]
        said += [Named(category, False, low[: m.start()], low[m.end() :])  # "have my guy cruise over": a word for one
                 for word in lx.CONCEPTS.get(category, ()) for m in re.finditer(rf"\b{re.escape(word)}\b", low)]
        if said and all(_POSSESSED_BY.search(n.before) or _HAVE_MY.search(n.before)
                        or (_POSSESSED.search(n.before) and _DOES.match(n.after)) for n in said):
            out.append(category)
    return out


def _category_of(asset_id: str, scene: Scene) -> str | None:
    asset = scene.asset(asset_id)
    return asset.category if asset is not None else None


def wrong_direction(masked: str, scene: Scene, moved: Iterable[AssetInstance]) -> list[str]:
    """Assets a plan moves away from the one compass direction the request names ("2 m east")."""
    word = md.compass_direction(masked)
    if word is None:
        return []
    want_x, want_y = md.COMPASS_VECTORS[word]
    out = []
    for after in moved:
        before = scene.asset(after.id)
        if before is None:
            continue
        dx, dy = after.pose.x - before.pose.x, after.pose.y - before.pose.y
        length = math.hypot(dx, dy)
        if length > MIN_MOVE_M and (dx * want_x + dy * want_y) / length < math.cos(math.radians(DIRECTION_SLACK_DEG)):
            out.append(f"you said {word}, but the plan moves {after.id} {compass_of(dx, dy)}")
    return out


def lane_way(lane: Lane, word: str) -> float:
    """How far `lane`'s traffic goes the compass way `word` names: the cosine between them."""
    (x0, y0), (x1, y1) = lane.centreline[0], lane.centreline[-1]
    want_x, want_y = md.COMPASS_VECTORS[word]
    length = math.hypot(x1 - x0, y1 - y0)
    return ((x1 - x0) * want_x + (y1 - y0) * want_y) / length if length > 0 else 0.0


def wrong_lane_way(masked: str, scene: Scene, driven: Iterable[AssetInstance]) -> list[str]:
    """Things a plan sets driving in a lane whose traffic goes against the one compass direction the
    request names ("car 2 must drive on Campus Drive to the south" put in the northbound lane)."""
    word = md.compass_direction(masked)
    if word is None:
        return []
    out = []
    for asset in driven:
        lane = scene.roads.lane(asset.behaviour.lane) if asset.behaviour.kind == "drive_lane" and asset.behaviour.lane else None
        if lane is not None and lane_way(lane, word) < -math.cos(math.radians(DIRECTION_SLACK_DEG)):
            (x0, y0), (x1, y1) = lane.centreline[0], lane.centreline[-1]
            out.append(f"you said {word}, but the plan drives {asset.id} {compass_of(x1 - x0, y1 - y0)} in {lane.id}")
    return out


def numbered_passed_over(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """Things said by id (the request reader writes "use car 1" as passenger_car_1) that the plan
    leaves alone while it adds, removes or changes another of their kind: the one named was meant."""
    touched = {a.id for a in scope.touched}
    kinds = {a.category for a in scope.touched}
    out = []
    for said in ASSET_ID.finditer(masked):
        asset = scene.asset(said.group(0))
        if asset is not None and asset.id not in touched and asset.category in kinds:
            out.append(f"you named {asset.id}, but the plan leaves it and acts on another {asset.category.replace('_', ' ')}")
    added = {a.id for a in scope.added}
    for name in numbered_absent(scene, masked):  # "rotate bench 4" where the one bench is bench_1
        ident = name.replace(" ", "_")
        kind = ident.rsplit("_", 1)[0]
        if kind in kinds and ident not in added:
            there = sorted((a.id for a in scene.assets if a.category == kind), key=lambda i: (len(i), i))
            out.append(f"there is no {name} here (the scene has {', '.join(there[:6])}{' ...' if len(there) > 6 else ''})")
    return list(dict.fromkeys(out))


# Lanes named by who uses them, and the lane kind that would be ("biking" is no kind this world has).
_LANE_KINDS = {"bike": "biking", "bicycle": "biking", "cycle": "biking", "bus": "bus", "tram": "tram", "parking": "parking"}
_KIND_OF_LANE = re.compile(rf"\b({'|'.join(_LANE_KINDS)}) lane\b")
# A place of a kind named by a letter or number: "lot C", "parking lot 3", "gate 2".
_LETTERED = re.compile(r"\b((?:parking )?lot|building|gate|hall|entrance|crosswalk) ([a-z]|\d+)\b(?!')")


# Where a request names the thing it wants added: the object of a verb of adding ("add a giraffe",
# "needs a double rainbow"), up to four words before a word that ends a noun phrase. A question
# asks after one with ASKED_ABOUT ("how far's the nearest servo", "any roos about?").
# A setting given a value by name: "set the weather to hail", "change the sky to purple".
_SET_TO = re.compile(r"\b(?:set|change|switch)\b[^.,;:!?]*?\bto\s+(?:a\s+|an\s+|some\s+)?([a-z]+)\s*(?=$|[.,;:!?])")
_THING_WANTED = re.compile(
    r"\b(?:add|put|place|spawn|bring|drop|insert|create|build|install|erect|construct|set up|lay out|make (?:me|us)|"
    r"give (?:me|us)|want|need|needs|(?:we|i|you) have)\s+(?:(?:a|an|the|some|one|more|another|few|couple|"
    r"of|\d+)\s+){0,3}((?:[a-z][a-z-]*\s+){0,3}?[a-z]+)(?=\s*(?:$|[,.;:!?]|\s(?:next|near|by|at|on|in|beside|behind|"
    r"between|along|across|over|under|above|below|beneath|opposite|past|beyond|against|within|after|before|outside|inside|"
    r"around|to|for|from|with|into|onto|and|or|so|that|which|who|"
    r"please|here|there|too|as|if|when|where|somewhere|close|right|left|just|then)\b))")

# A second thing in the same breath: "... and a crew member standing beside it".
_AND_A_THING = re.compile(r"\band\s+(?:a|an|some|two|three|four|five|\d+)\s+((?:[a-z][a-z-]*\s+){0,3}?[a-z]+)" + _THING_WANTED.pattern[_THING_WANTED.pattern.index("(?=\\s*(?:$"):])


def unknown_things(masked: str, calls: tuple[ToolCall, ...], scene: Scene, answered: bool = False) -> list[str]:
    """Things asked for that this world has no word for ("add a giraffe", "a mailbox next to the
    bench") and that no call adds: a plan that does something else instead is not what was meant.
    The thing is the phrase's last word ("a double rainbow" is a rainbow); a word that only
    describes a known thing ("a shiny bench") is not one; the words were spelling-repaired already.
    `answered`: the request is a question the plan only answers, so what the asker says they need
    is their story, not a thing asked for (a thing asked about still counts)."""
    vocab = vocabulary(scene)
    said = set(re.findall(r"[a-z]+", " ".join(str(v) for c in calls for k, v in c.args.items()
                                               if k in ("category", "categories", "asset", "assets", "kind")).lower()))
    said |= {w for c in calls for w in c.tool.split("_")}  # "I want the distance between ...": what measure_distance tells
    said |= {w for c in calls for k in c.args for w in k.split("_")}  # "drop the exposure to 0.5": what set_lighting sets
    weathers = {str(c.args.get("kind")) for c in calls if c.tool == "set_weather"}  # "bring a fog bank in": the fog set
    out = []
    for m in _SET_TO.finditer(masked):  # "set the precipitation type to hail": a setting this world has no word for
        if len(m.group(1)) >= 3 and not is_known(m.group(1), vocab) and m.group(1) not in said and m.group(1) not in lx.GRAMMAR:
            out.append(f"there is no {m.group(1)!r} in this world")
    for m in ASKED_ABOUT.finditer(masked):  # answering about another thing is not an answer
        if not is_known(m.group(1), vocab) and m.group(1) not in said and m.group(1) not in lx.GRAMMAR \
                and not PLACE_KIND.fullmatch(m.group(1)):  # "the nearest landmark": a place, not a thing
            out.append(f"there is no {m.group(1)!r} in this world")
    # a question the plan only answers: what the asker needs is their story ("... need an eta for the crew")
    wanted = [] if answered else list(_THING_WANTED.finditer(masked))
    if wanted:  # "add a van at the gate and a crew member beside it": the second thing is asked for too
        wanted += [m for m in _AND_A_THING.finditer(masked, wanted[0].end())]
    for m in wanted:
        phrase = m.group(1).split()
        cut = next((i for i, w in enumerate(phrase) if i and (w in lx.GRAMMAR or w == "of")), len(phrase))
        if phrase[cut:cut + 1] == ["of"]:
            continue  # "a heap of benches", "a pile of rubble": what follows is the thing
        phrase = phrase[:cut]  # "a deer crossing the road": the phrase ends before "the"
        while len(phrase) > 1 and (phrase[-1].endswith(("ly", "ing", "more", "where", "wards", "way"))
                                   or (phrase[-1].endswith("est") and is_known(phrase[-2], vocab))):
            phrase.pop()  # "a low sun shortly after dawn", "a deer crossing", "the sign anymore", "the tree closest": the thing comes before
        word = phrase[-1]
        if phrase[0] == "to" or (len(phrase) == 1 and word.endswith(("ing", "more", "where", "ly"))):
            continue  # "want to be sure", "needs protecting", "don't need anymore": a verb or an adverb, not a thing
        if len(phrase) > 1 and (word.endswith(("ed", "en")) or word in _PARTICIPLES) and word in english_words() \
                and any(is_known(w, vocab) or w == "ego" for w in phrase[:-1]):
            continue  # "I want the ego sat at the gate", "a bench painted green": the thing, then how it is
        if len(word) < 3 or word in lx.GRAMMAR or word in lx.GENERIC_THINGS or word in ph.NUMBER_WORDS \
                or _heads(phrase) or is_known(word, vocab) or word in said or any(w in weathers for w in phrase):  # "a fog bank"
            continue
        out.append(f"there is no {word!r} in this world")
    return list(dict.fromkeys(out))


# Past participles not ending in -ed or -en: "the ego sat at the gate", "the cones left in a row".
_PARTICIPLES = frozenset({"sat", "stood", "left", "kept", "lit", "set", "put", "held", "shut", "spread", "stuck", "laid",
                          "hung", "parked", "built", "lent", "sent", "spent", "bent", "lost", "found"})


def _heads(phrase: list[str]) -> bool:
    """Whether a category's name ends the phrase: "a yellow cab" names one, "a bus shelter"
    names a shelter, not a bus."""
    text = ph.normalise(" ".join(phrase))
    return any(phrase[-1] in text[m.start : m.end].split() or text[m.end :].strip() in ("", "s")
               for m in ph.find_categories(" ".join(phrase)))


# An existing thing picked out by another thing it stands by: "the lamp near the stop sign", "the
# car closest to the hydrant", "that bin next to the bench".
_PICKED_BY_THING = re.compile(
    r"\b(?:the|that|this|those|these)\s+(?P<a>(?:[a-z]+\s+){0,2}?[a-z]+?)\s+(?:(?:that|which|who)(?:'s| is| are)\s+)?"
    r"(?:(?:right|just)\s+)?(?:near|by|next to|beside|behind|in front of|(?:closest|nearest)(?: to)?)\s+"
    r"(?:the|a|an|that|this)\s+(?P<b>(?:[a-z]+\s+){0,2}[a-z]+)\b")
# Within this of the thing named, things said in the plural ("the cones by the bench") are meant.
PICKED_RADIUS_M = 12.0
# Workers that take a thing somewhere: there "the bench next to the tree" may be where it goes.
_PLACING = ("move_asset", "place_asset", "arrange_assets")


def picked_by_thing(masked: str, scene: Scene) -> list[tuple[str, str, set[str]]]:
    """(what was said, category, the ids it picks out) for each thing picked out by another
    thing it stands by: the one of its kind nearest to one of those (or, in the plural, all of
    its kind within PICKED_RADIUS_M of one)."""
    indexed = ph.normalise(masked)
    out = []
    for m in _PICKED_BY_THING.finditer(indexed):
        kinds, refs = ph.find_categories(m.group("a")), ph.find_categories(m.group("b"))
        if not kinds or not refs or kinds[-1].category == refs[0].category:
            continue
        kind, ref = kinds[-1], refs[0].category
        anchors = [(a.pose.x, a.pose.y) for a in scene.all_assets() if a.category == ref]
        mine = [a for a in scene.all_assets() if a.category == kind.category]
        if not anchors or not mine:
            continue

        def gap(asset: AssetInstance, anchors: list[tuple[float, float]] = anchors) -> float:
            return min(math.dist((asset.pose.x, asset.pose.y), p) for p in anchors)

        # (in the singular, any as near as the nearest: "the car next to the SUV" with one each side is either)
        meant = {a.id for a in mine if gap(a) <= PICKED_RADIUS_M} if kind.plural else {
            a.id for a in mine if gap(a) <= min(map(gap, mine)) + TIE_M}
        said = indexed[m.start() : m.start("b") + refs[0].end].strip()  # up to the thing it stands by
        out.append((said, kind.category, meant))
    return out


def off_the_road(low: str, scope: Scope, scene: Scene) -> list[str]:
    """Things the plan takes away that do not stand by the road the words say they are on ("the
    street lights on Campus Drive"); a thing set driving "on Main Street" is where it goes."""
    road = road_said(low, scene)
    if road is None:
        return []
    far = [a.id for a in scope.removed if not road[1](a)]
    return [f"you said on {road[0]}, but the plan acts on {', '.join(far)} away from it"] if far else []


def picked_but_other(masked: str, scope: Scope, scene: Scene) -> list[str]:
    """Things picked out by a thing they stand by ("the lamp near the stop sign") that the plan
    changes or removes others of the same kind in their stead. A plan that takes things
    somewhere is left alone: there "the bench next to the tree" may say where it goes."""
    if any(c.tool in _PLACING for c in scope.calls):
        return []
    acted = [a for a in scope.touched if a not in scope.added]
    out = []
    for said, category, meant in picked_by_thing(masked, scene):
        others = [a.id for a in acted if a.category == category and a.id not in meant]
        if others and meant:
            out.append(f"you said {said!r}, which is {', '.join(sorted(meant))}, but the plan acts on {', '.join(others)}")
    return out


# Where an excepted thing's own words end and the place that picks it out begins ("the one | by the bench").
_PICKED_BY = re.compile(r"\s(?:by|near|next to|beside|at|in|on|behind|in front of|close to|(?:nearest|closest)(?: to)?)\s")
# Within this of the place named, a thing said in the plural ("the ones by the fountain") is excepted.
EXCEPTED_RADIUS_M = 10.0


def excepted_touched(excepted: Iterable[str], categories: Iterable[str], scope: Scope, scene: Scene, main: str = "",
                     recent: Iterable[str] = ()) -> list[str]:
    """Things the request says it does not mean ("..., not the ego", "except the one by the bench")
    that the plan changes or removes (see `excepted_ids`); where the words name a kind but pick out
    none of it this world can find ("not the ones at the ends"), any of that kind the plan touches.
    "The old one" is one of the kinds named the last turn did not add (`recent`)."""
    acted = [a for a in scope.touched if a not in scope.added]
    out = []
    for said in excepted:
        picked = _picked_out(said, set(categories), scene, main)
        if _OLD.search(said) and recent:  # "colour the new hydrant, leave the old one as it is"
            picked = {a.id for a in scene.assets if a.category in set(categories) and a.id not in set(recent)}
        if isinstance(picked, frozenset):
            unsure = sorted(a.id for a in acted if a.category in picked)
            if unsure:
                out.append(f"you said not {said}, and I cannot tell which those are; the plan changes {', '.join(unsure)}")
        elif hit := sorted({a.id for a in acted} & picked):
            out.append(f"you said not {said}, but the plan changes {', '.join(hit)}")
    return out


_OLD = re.compile(r"\b(?:old|older|original|existing)\b")


def excepted_ids(excepted: Iterable[str], categories: Iterable[str], scene: Scene, main: str = "") -> set[str]:
    """The ids of the things excepted. "One(s)" stands for the kinds the rest of the request
    names; a thing picked out by a place is the one of its kind nearest it, by a side ("the west
    ones") those of its kind on that side of the others; of those on the side of the road the
    rest of the request (`main`, lower case) names, when it names one."""
    out: set[str] = set()
    for said in excepted:
        picked = _picked_out(said, set(categories), scene, main)
        out |= set() if isinstance(picked, frozenset) else picked
    return out


# What the excepted thing is doing: "not the moving one", "except the parked ones".
_STATE_SAID = re.compile(r"\b(parked|stationary|stopped|moving|move|driving|drive)\b")
# A side said with no place it is the side of ("on the south side", "at the western end").
_SIDE_ONLY = re.compile(r"\s*(?:on|at|to|along) the (?:north|south|east|west)(?:ern)?(?: side| end| half| edge)?\s*")


def _picked_out(said: str, categories: set[str], scene: Scene, main: str = "") -> set[str] | frozenset[str]:
    """The ids of the things `said` ("the ego", "the suv", "the one by the bench") names in the
    scene, of those on the side the rest of the request names ("the lamps on the north side except
    the one nearest the library"); a frozenset of the kinds it names when it picks out no one of
    them it can find."""
    low = f" {ph.normalise(said)} "
    cut = _PICKED_BY.search(low)
    head, where = (low[: cut.start()], low[cut.start() :]) if cut else (low, "")
    if ph.has_any(head, ph.EGO_WORDS) or re.search(r"\bego\b", head):
        return {"ego"}
    ids = {a.id for a in scene.all_assets() if re.search(rf"\b{re.escape(a.id)}\b", head)}  # not the place's
    ids |= {i for i, _, _ in numbered_picks(scene, head)}  # "except tree 3"
    if ids:
        return ids
    mentions = ph.find_categories(head)
    # "except the two nearest the ego": a number alone stands for that many of the kinds named
    counted = _COUNTED.fullmatch(head.strip())
    amount = _amount_word(counted.group(1)) if counted else None
    alone = amount is not None and not mentions
    kinds = {m.category for m in mentions} or (categories if re.search(r"\bones?\b", head) or alone else set())
    members = [a for a in scene.all_assets() if a.category in kinds and a.id != "ego"]
    state = _STATE_SAID.search(head)
    if state is not None:  # "not the moving one": of its kind, the one moving
        still = state.group(1) in ("parked", "stationary", "stopped")
        members = [a for a in members if (a.behaviour.kind == "parked") == still]
    if _SIDE_ONLY.fullmatch(where):  # "the ones on the south side" are the south ones
        head, where = f"{head} {where}", ""
    side = md.compass_direction(re.sub(r"\b(north|south|east|west)ern\b", r"\1", head))
    if side is not None and members and not where.strip():  # "the west ones": of their kind, those that way
        east, north = md.COMPASS_VECTORS[side]
        mid_x, mid_y = sum(a.pose.x for a in members) / len(members), sum(a.pose.y for a in members) / len(members)
        return {a.id for a in members if (a.pose.x - mid_x) * east + (a.pose.y - mid_y) * north > 0}
    if not where.strip():
        return {a.id for a in members}
    point = point_named(scene, where)
    if point is None or not members:
        return frozenset(kinds)
    road_side = side_of(main, scene) if main else None  # "on the north side except the one nearest X": of those
    if road_side is not None and len(chosen := [a for a in members if road_side[1](a)]) >= 2:
        members = chosen
    by_distance = sorted(members, key=lambda a: math.hypot(a.pose.x - point[0], a.pose.y - point[1]))
    if amount is not None and amount > 1:  # "the two nearest the ego", "the three cones by the gate"
        return {a.id for a in by_distance[:amount]}
    if re.search(r"\bones\b", head) or any(m.plural for m in mentions):
        return {a.id for a in by_distance if math.hypot(a.pose.x - point[0], a.pose.y - point[1]) <= EXCEPTED_RADIUS_M}
    return {by_distance[0].id}


# A number standing alone for things ("the two", "those 3 ones"), not a measure ("40 m").
_COUNTED = re.compile(r"(?:(?:the|those|these)\s+)?([a-z]+|\d+)(?:\s+ones?)?")


def _amount_word(word: str) -> int | None:
    """A whole number written in digits or words ("2", "two"), else None."""
    if word.isdigit():
        return int(word)
    return spelt_counts().get(word)


# Verbs that take a thing somewhere or away: their object is what the plan must act on.
_MOVING_VERB = r"\b(?:move|moving|shift|relocate|drag|slide|push|pull|remove|delete|get rid of|take away|knock down|demolish)\s+(?:the\s+|that\s+|our\s+)?"


# What follows a place said as a verb's object (not "the lot A cars", "the bus stop sign").
_PLACE_ENDS = (r"(?=\s*(?:$|[,.;!?]|(?:to|closer|further|farther|nearer|away|over|up|down|back|next|near|by|towards?|from|out|off"
               r"|and|so|because|please|entirely|completely|altogether|\d)\b))")


def place_moved(low: str, scope: Scope, scene: Scene) -> list[str]:
    """A place of the world (a landmark, a road) said as the thing to move or take away ("move
    the bus stop closer to the gate"): places stay where they are, so a plan that moves or removes
    a thing instead (the stop sign) does something else."""
    if not (scope.removed or scope.touched):
        return []
    places = {n for lm in scene.landmarks for n in lm.names()} | {lane.road for lane in scene.roads.lanes if lane.road}
    for name in sorted(places, key=len, reverse=True):
        said = ph.normalise(name).strip()
        if re.search(_MOVING_VERB + re.escape(said) + _PLACE_ENDS, low):
            return [f"{name} is a place of this world; it stays where it is, but things at it can be moved or removed"]
    return []


# A relation said right after a thing's name, picking it out ("the tree behind the bus stop"), and a
# predicate or a destination right after that ("..., by the library, is diseased", "... to the
# fountain"): where it stands.
_WHERE_IT_STANDS = r"\s+(?:right |just )?(?:behind|next to|beside|by|near|in front of|at|opposite|across from|outside)\s+(?:the\s+)?"
# Verbs that send a thing somewhere, said before it: "put the bin at the bus stop" says where it goes.
_SENDING_VERB = re.compile(r"\b(?:move|put|place|shift|relocate|take|bring|set|stand|position|drag|push|pull|carry|send|stick|pop"
                           r"|plonk|plant|park|drop|slide|nudge|budge|get|have|want|need|like|go|goes|belongs?|should|must|keep|leave"
                           r"|station|locate|reposition|transfer|return)\b")
_PICKED_NEAREST = r"\s+(?:(?:one|that|which is|that is)\s+)?(?:nearest|closest)(?:\s+to)?\s+(?:the\s+)?"
_PREDICATE = re.compile(r"\s*(?:,[^,.;]*,\s*)?(?:(?:is|are|was|were|has|have|had|needs?|must|should|keeps?|looks?|seems?|throws?"
                        r"|blocks?|casts?|gets?|hides?|spoils?|ruins?|drips?)\b"
                        r"|(?:over\s+)?(?:to|into|onto|towards?)\s+(?:the\s+)?[a-z])")  # or where it should go, said after it


def described_not_destination(low: str, calls: tuple[ToolCall, ...], scene: Scene) -> list[str]:
    """Things put at the place the words only pick them out by ("the tree behind the bus stop is
    diseased and has to come down", "the lamp nearest the bus stop"): the plan moves them to where
    they are said to stand."""
    out = []
    indexed = ph.normalise(low)
    mentions = ph.find_categories(low)
    gone = {i for c in calls if c.tool == "remove_assets" for i in c.args.get("assets") or []}  # moved, then gone: moot
    for call in calls:
        where = call.args.get("location") if call.tool == "place_asset" else None
        thing = scene.asset(str(call.args.get("asset"))) if isinstance(where, dict) else None
        target = str(where.get("target") or "") if isinstance(where, dict) else ""
        if thing is None or not target:
            continue
        mark = scene.landmark(target)
        other = scene.asset(target)
        names = ([n for name in mark.names() for n in (ph.normalise(name).strip(), ph.normalise(name).split()[0])] if mark
                 else [other.category.replace("_", " ")] if other else [])
        for m in (m for m in mentions if m.category == thing.category):
            named = "(?:" + "|".join(re.escape(n) for n in names if n and n not in ("the", "a", "an")) + r")\b"
            said = re.match(_WHERE_IT_STANDS + named, indexed[m.end :])
            picked = re.match(_PICKED_NEAREST + named, indexed[m.end :])  # "the lamp nearest the bus stop": which one, whatever follows
            rest = indexed[m.end + said.end() :] if said else ""
            verb = re.sub(r"\b(?:the|a|an|that|this|those|these|my|our|your|please|now|ok|so|and)\b", " ", indexed[: m.start]).strip()
            # "strike the lamp at the bus stop.": a verb that sends nowhere ("the bench at the library" is terse for putting it)
            ends = said is not None and not rest.strip(" .!") and bool(verb) and not _SENDING_VERB.search(indexed[: m.start])
            if names and (picked or (said and _PREDICATE.match(rest)) or ends) and thing.id not in gone:
                said = picked or said
                assert said is not None
                out.append(f"you said where the {thing.category.replace('_', ' ')} stands"
                           f" ({indexed[m.start : m.end + said.end()].strip()!r}), not where it should go")
    return out


def unknown_places(masked: str, calls: tuple[ToolCall, ...], scene: Scene) -> list[str]:
    """Place names the world does not know ("near the gym") that no call mentions, each said with
    what the world has of its kind where it has some ("parking lot c": "there are lot a, lot b")."""
    vocab = vocabulary(scene)
    said = " ".join(str(c.args) for c in calls).lower()
    ids = {a.id for a in scene.all_assets()}
    world = set(ph.tokens(scene.name))  # "the campus hospital": the world's name only says where the place is
    out = []
    for m in _PLACE_PREPOSITION.finditer(masked):
        words = [w for w in re.split(r"[\s-]+", m.group(1)) if w][:3]
        for at, word in enumerate(words):
            rest = list(itertools.takewhile(lambda w: w not in lx.GRAMMAR, words[at + 1 :]))
            place = " ".join([word, *rest])  # "the lakeside promenade for ...": the name, not one word of it
            if {word, *words[at + 1 : at + 2]} & _TIME_HEADS:
                break  # "at the material time", "by the weekend": when, not where
            if word in world:
                continue
            if _CENTRE_SAID.fullmatch(word):
                break  # "at the origin", "the centre": the map's middle
            if word in lx.GRAMMAR or word in _RELATION_WORDS or word in ids or word == "ego" or word.endswith("est") \
                    or re.fullmatch(r"(?:north|south|east|west)(?:ern|erly|ward)?", word):  # "the western car park"
                break  # ("the closest hydrant": a superlative modifies what follows, it names no place)
            if ph.find_categories(word) or is_known(word, vocab):
                break
            if word in said:
                break  # a word the plan uses is accounted for
            if word not in english_words():  # a misspelling is the planner's to repair, but
                # a plan placing nothing, or nowhere like the word, has dropped the place ("the helipad")
                repaired = any(edits(word, w) <= 2 for w in re.findall(r"[a-z]{3,}", said))
                if not _PLACE_ARG.search(said) or not repaired:
                    out.append(f"I do not know the place {place!r}")
                break
            out.append(f"there is no {place!r} in this world")
            break
    names = [ph.normalise(n).strip() for lm in scene.landmarks for n in lm.names()]
    for m in _LETTERED.finditer(masked):  # "parking lot C" where the lots are A and B
        kind = m.group(1)
        if f"{kind} {m.group(2)}" not in names and (alike := sorted({n for n in names if re.fullmatch(rf"{kind} (?:[a-z]|\d+)", n)})):
            out.append(f"there is no {m.group(0).strip()!r} in this world (there are {', '.join(alike)})")
    kinds = {lane.kind for lane in scene.roads.lanes}
    for m in _KIND_OF_LANE.finditer(masked):  # "the bike lane" where every lane is for driving
        if _LANE_KINDS.get(m.group(1)) not in kinds:
            out.append(f"there is no {m.group(0)!r} in this world (lanes here: {', '.join(sorted(kinds))})")
    return list(dict.fromkeys(out))


# Nouns that make a phrase after "at", "by" or "on" a time, not a place: "at the material time".
_TIME_HEADS = frozenset({"time", "times", "moment", "minute", "hour", "day", "night", "weekend", "week", "start", "end",
                         "point", "instant", "second", "stage"})
_CENTRE_SAID = re.compile(r"\b(?:cent(?:re|er)|middle|origin|0\s*,\s*0)\b")


# Where a layout is said to go in words the place readers may not know ("a line of barriers across
# the lot be entrance"): not the scene's centre, which a plan falls back to.
_LAID_SOMEWHERE = re.compile(r"\b(?:across|along|in|into|on|onto|over)\s+the\s+(?!(?:scene|world|map|middle|centre|center|"
                             r"road|roads|street|way|same|lane)\b)([a-z][a-z ]{1,30}?)\s*(?:[,.;!?]|$|\b(?:and|please|with|so|for|now)\b)")


def place_dropped(low: str, calls: tuple[ToolCall, ...]) -> list[str]:
    """A place said for what the plan puts down ("a bus at teh bus stp", "cones around the helipad")
    that the plan puts nowhere in particular (no location, or the scene's centre it never said)."""
    # a jaywalker stands where it crosses: ahead of the ego, which is where "in front of the ego" puts it
    placing = [c for c in calls if c.tool in ("add_asset", "arrange_assets", "place_asset")
               and (c.args.get("behaviour") or {}).get("kind") != "jaywalk"]
    said = PLACE_SAID.search(low) or BY_IT.search(low) or _LAID_SOMEWHERE.search(low)  # "... ahead of it": where the thing named before is
    if not placing or said is None or _CENTRE_SAID.search(low):
        return []
    where = [c.args.get("location") for c in placing]
    if all(not isinstance(w, dict) or w.get("relation") == "scene_centre" for w in where):
        unknown = f"; there is no {said.group(1)!r} in this world that I know of" if said.re is PLACE_SAID else ""
        return [f"you said where ({said.group(0).strip(' ,.;!?')!r}), but the plan puts it nowhere in particular{unknown}"]
    return []


# Words for one kind of place: a crossing is a crosswalk.
_SAME_KIND = {"crossing": "crosswalk", "crossings": "crosswalk", "crosswalks": "crosswalk"}
# A compass word before a word that may be a kind of place ("the south crosswalk", "north gate").
_COMPASSED = re.compile(r"\b(north|south|east|west)[\s-]+([a-z]+)\b")


def unnamed_compass_places(low: str, scene: Scene) -> list[str]:
    """A place said by a compass word where the places of its kind are named by compass words and
    none by that one ("the south crosswalk" where the crosswalks are the west and the north one):
    no place of the world, though its last word alone would name one."""
    names = {_SAME_KIND.get(n.split()[-1], n.split()[-1]).join(n.rsplit(n.split()[-1], 1)) if n.split() else n
             for lm in scene.landmarks for n in (ph.normalise(x).strip() for x in lm.names())}
    out = []
    for m in _COMPASSED.finditer(low):
        way, kind = m.groups()
        kind = _SAME_KIND.get(kind, kind)  # "the west crossing" is the west crosswalk
        named = sorted(n for n in names if n.split()[-1] == kind and n.split()[0] in md.COMPASS_VECTORS)
        if named and not any(n.split()[0] == way for n in named):  # "the west lot" is the west parking lot
            out.append(f"there is no '{way} {kind}' in this world (there are {', '.join(named)})")
    return out


__all__ = [
    "LAMPS_SWITCHED",
    "Named",
    "Scope",
    "absent_but_added",
    "ambiguous_pick",
    "away_from_thing",
    "back_reference",
    "definite_but_added",
    "environment_left_out",
    "environment_unasked",
    "excepted_ids",
    "excepted_touched",
    "indefinite_but_moved",
    "inside_building",
    "landmark_thing_changed",
    "lane_way",
    "missing_categories",
    "named_in",
    "named_things",
    "numbered_passed_over",
    "off_the_side",
    "partial_removal",
    "place_dropped",
    "unknown_places",
    "unknown_things",
    "unnamed_added",
    "unnamed_compass_places",
    "unpointed",
    "wrong_direction",
    "wrong_lane_way",
]
