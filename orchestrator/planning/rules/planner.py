"""The rule-based planner: how people phrase scene requests, mapped to Worker tool calls, no LLM.

It is the baseline every LLM is measured against, the fast path of the hybrid planner, and
what makes `drivetwin chat` useful on a fresh install. It repairs spelling against the words
it knows, splits the prompt into clauses, reads what each names (places, lanes, categories,
existing assets), recognises the intent from verbs, idioms and stated goals, fills the slots
from what the world contains, and reports a confidence that says how much it had to guess.
"""

from __future__ import annotations

import itertools
import math
import re
import time
from collections.abc import Iterator
from dataclasses import replace
from typing import Any

from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning.base import Plan, PlanContext, PlanningError, Question, TraceStep
from drivetwin.orchestrator.planning.base import Reading as Choice
from drivetwin.orchestrator.planning.descriptions import unsure
from drivetwin.orchestrator.planning.intent import (
    ADD_WORDS,
    BARE_STATE,
    FEWER_WORDS,
    HABITUAL,
    HOW_THINGS_GO,
    LIVELIER,
    NONE_THERE,
    QUIETER,
    REMINISCED,
    REMOVE_WORDS,
    REPORTED,
    SAID_MISSING,
    WHAT_IF,
    asks,
    commands,
    setting_shown,
    taken_back,
    without_memories,
    without_reason,
    without_salutations,
    wrapped_request,
)
from drivetwin.orchestrator.planning.readings import describe
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules import numbers as nb
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.conditions import condition, topic_first
from drivetwin.orchestrator.planning.rules.edits import (
    FINAL_COUNT,
    TOWARD,
    WAY_GUESSED,
    behaviour_kind,
    behaviour_spec,
    drive_towards,
    edit_existing,
    faced_from,
    kept_at,
    named_at,
    new_pace,
    other_ways,
    recolour,
    referenced,
    remove,
    walk_said,
)
from drivetwin.orchestrator.planning.rules.environment import LAMPS_SWITCHED_AS_SAID, LIGHTS_DOWN, environment, lights
from drivetwin.orchestrator.planning.rules.inflection import inflected
from drivetwin.orchestrator.planning.rules.places import (
    EACH_PLACE,
    EDGE_OF,
    FROM_TO,
    PLACE_SAID,
    Notes,
    cross_section,
    each_place_named,
    location,
    one_lane_named,
    places_called,
    said_a_place,
)
from drivetwin.orchestrator.planning.rules.questions import of_group, plan_question
from drivetwin.orchestrator.planning.rules.reading import Reading, find_count, find_place, is_new, named_as, read
from drivetwin.orchestrator.planning.rules.repeat import (
    SAID_AGAIN_AT,
    correct,
    corrects,
    last_location,
    meant_instead,
    repeat,
    repeats,
    retargeted,
    said_again,
)
from drivetwin.orchestrator.planning.rules.replacing import replace_things, replaces, trades_places
from drivetwin.orchestrator.planning.rules.spelling import ASSET_ID, is_known, repair, vocabulary, without_left_as_it_is
from drivetwin.tools.appearance import COLOURS, hex_colour
from drivetwin.tools.base import ToolCall
from drivetwin.tools.errors import ToolError
from drivetwin.tools.locate import resolve_target
from drivetwin.worlds.catalog import catalog, is_layout_kit, nearest_categories, shared_heads
from drivetwin.worlds.scene import AssetInstance, DriveLane, Scene
from drivetwin.worlds.surface import DRIVABLE, nearest_on_polyline, point_in_polygon, surface_at

PROMPT_VERSION = "rules-2"
# The guess noted when a clause says where but names no place the world has.
_UNRECOGNISED = "the place named was not recognised"
# Readings offered when a place word fits several places.
MAX_READINGS = 3
# Places listed when a place named is not one of the world's.
MAX_PLACES_LISTED = 8
# Confidence when every content word was understood and nothing was guessed.
FULL_CONFIDENCE = 0.95
# How much each unknown content word lowers the confidence.
UNKNOWN_WORD_PENALTY = 0.15
# How much each guess lowers it: a repaired typo, a default for an amount, a skipped clause.
GUESS_PENALTY = 0.2
# Lowest confidence a plan reports (it did produce calls, so not zero).
MIN_CONFIDENCE = 0.05

# Clause breaks: a stop or colon between digits is part of a number or a clock time ("2.5 m",
# "18:30"), not a break; nor is "then" after "who" ("a man who then walks to the bench": one thing). "Then" said
# formally ("and subsequently", "afterwards") breaks as "then" does.
_SPLIT = re.compile(r"((?:[;!?\n]|(?!(?<=\b[Nn][Oo])\.\s*\d)(?:(?<!\d)[.:]|[.:](?!\d)))+|(?<!\bwho),?\s+(?:and then|then|and also|(?:and )?after that|(?:and )?(?:subsequently|afterwards?))\s+)")
_VERBS = (
    "add",
    "make",
    "put",
    "place",
    "remove",
    "delete",
    "set",
    "turn",
    "move",
    "create",
    "change",
    "paint",
    "repaint",
    "colour",
    "color",
    "spawn",
    "switch",
    "arrange",
    "surround",
    "drive",
    "park",
    "have",
    "light",
    "lose",
    "get",
    "take",
    "clear",
    "bring",
    "block",
    "close",
    "stop",
    "reverse",
    "shift",
    "relocate",
    "drop",
    "scatter",
    "install",
    "stand",
    "ring",
    "fence",
    "fix",
    "sort",
    "solve",
    "let",  # "..., and let it drizzle"
)
_STRICT_ADD = (
    "add",
    "create",
    "spawn",
    "insert",
    "install",
    "plant",
    "build",
    "deploy",
    "new",
    "another",
    "more",
    "set up",
    "i want",
    "i need",
    "we need",
    "we want",
    "there should be",
    "give me",
)

# Wishes that ask for a thing when it is new ("I want a bench"), a change when it is there ("I want the bench painted").
_WISHES = ("i want", "i need", "we need", "we want", "there should be", "give me")
_DEFINITE = re.compile(r"\b(?:the|that|this|those|these|our|my)\s+(?:[a-z-]+\s+){0,2}$")
_THE_NEW = re.compile(r"\b(?:the|that|this|those|these|our|my)\s+new(?:er|est)?\b")
# "add a waiter next to the SUV": the thing to add is the word after the count, never the thing
# named as its place ("add a copy next to the SUV" is one more of it)
_ADDED_BEFORE_PLACE = re.compile(
    r"\b(?:add|put|place|create|spawn|insert|bring)\s+(?:in\s+)?(?:a|an|one|two|three|four|five|six|\d+|some|a few|several)\s+"
    r"(?:new\s+)?([a-z]+)\s+(?:right\s+)?(?:next to|beside|near|by|behind|in front of|at|on|around|opposite|across from)\b")
_NO_NEW_NOUN = ("copy", "duplicate", "twin", "clone", "replica", "more", "other", "another", "extra", "one", "ones", "few", "pair", "same",
                "second", "third", "similar", "match")

# Closing a road by its name or kind ("close Main Street at the east gate", "shut the lane").
_CLOSE_ROAD = re.compile(r"^\s*(?:please )?(?:close|block|shut|seal|barricade)(?: off)? (?:the )?(?:[\w-]+ ){0,3}?"
                         r"(?:road|street|lane|avenue|drive|driveway|entrance|access road|car park|parking lot|lot [a-z0-9]|crosswalk|crossing)\b")
# A layout named as the means of a request ("... with a row of bollards", "using a line of cones").
_WITH_LAYOUT = re.compile(r"\b(?:with|using|by putting|by placing) (?:a |an )?(?:[\w-]+ )?(?:row|line|ring|circle|wall|grid) of\b")

# A layout verb with its material after "with" ("line the road to the gate with lamps").
_LAYOUT_VERB_WITH = re.compile(r"^\s*(?:please )?(?:line|ring|surround|encircle|circle|edge|border|fence|flank|cordon|enclose|rope|seal|box|mark)\b.*?\bwith\b")

# A wish said in the negative ("I don't want the bench any more", "we no longer need cones",
# "I'd rather not have a bus"): the thing should go, whatever the verb.
_NEGATED_WISH = re.compile(
    r"\b(?:don'?t|do not|does not|doesn'?t|no longer|rather not|never)\s+(?:\w+\s+)?(?:want|need|like|have|keep)\b"
    r"|^\s*(?:nobody|no one|no-one)\s+(?:\w+\s+)?(?:uses?|needs?|wants?|likes?)\b"  # "nobody uses the bin any more"
)


# The guess noted when a request is only a statement, read as the edit it describes.
STATEMENT_READ = "read a statement of how things are as the request"
# A statement's subject, said as a thing already there ("the truck is in a daft spot", "the trucks
# are blocking the lane"), and one that says it is not there ("the bench is missing", SAID_MISSING): a wish for it.
_DEFINITE_SUBJECT = re.compile(r"^\s*(?:(?:now|still|and|but)\s+)?(?:the|this|that|these|those|our|my)\s+(?P<thing>[a-z' -]+?)\s+(?:is|are|was|were)\b")


# A word right after a step's length that is no filler: the way it was to go, said and not read.
_WORD_AFTER_STEP = re.compile(r"\b\d+(?:\.\d+)?\s*(?:m|metres?|meters?|ft|feet|foot|yards?)\s+(?!(?:please|pls|now|mate|then|thanks|ok|okay|"
                              r"bro|sir|again|more|too|also|or|ish|away|and|so|but|or so|if|at|from|in|on|of|for|with|by|to|the|a|it)\b)[a-z]{2,}\b")


def _spoken_of_as_there(text: str, calls: list[ToolCall], scene: Scene) -> str | None:
    """The category a statement's subject names as already there ("the truck is in a daft spot")
    that the scene has none of and its reading adds: a presupposition, not a wish for one."""
    said = _DEFINITE_SUBJECT.match(text.lower())
    if said is None or SAID_MISSING.search(text.lower()):
        return None
    named = {m.category for m in ph.find_categories(said.group("thing"))}
    added = {c.args.get("category") for c in calls if c.tool == "add_asset"}
    return next((c for c in sorted(named & added) if not scene.count(c)), None)


# A clause that says how things are ("the bench by the stop is in the way"), not what to do.
# So is one that opens on a thing and says what it does ("the test car starts too close", "the two
# trees block the view"), unless it says what should be ("the bus should stop", "it belongs in lot A").
_STATEMENT = re.compile(
    r"\s*(?:(?:now|still|and|but)\s+)?(?:(?:the|this|that|these|those|it|they|there)\b[^,;]*?\b(?:is|are|was|were)\b"
    # "looks like I ended up with two benches there": what the speaker has now, not what to add
    r"|(?:(?:it )?looks like |it seems |seems )?(?:i|we)(?:'ve| have)? (?:ended up with|now have|can see|noticed|spotted)\b"
    r"|(?:it|that|there|they)(?:'s|'re) (?!(?:got to|gotta|going to|supposed to|meant to|time)\b)"
    r"|(?:the|this|that|these|those|whoever|anyone who|everyone who)\s+"
    # "the ego rolls up to the east gate": a story's move to a place is what to stage
    r"(?![^,;]*\b(?:rolls?|pulls?|drives?|walks?|rides?|cycles?|comes?|arrives?|heads?|moves?|goes|wanders?|runs?|steps?)"
    r"\s+(?:up\s+|in\s+|over\s+|out\s+|back\s+)?(?:to|into|onto|towards?|at)\b)"
    r"(?![^,;]*\b(?:should|must|needs?|has to|have to|ought|go|goes|belongs?|wants?|"
    r"will|would|can|could|shall|may|might|let|gets?|to be)\b)[a-z' -]+\s(?:[a-z]+s|block|blocks|sit|stand|stay|face|look)\b"
    # "who put a hydrant on the pavement?": a complaint about what someone did, not a request
    r"|who\s+(?:\w+\s+)?(?:put|left|parked|placed|moved|dumped|stuck|added|thought|decided)\b"
    # "the children can't see the road": what someone cannot do, the trouble, not what to do
    r"|(?:the|these|those|they|he|she|people|drivers|kids|children|pupils|students|cars|we|i)\b[^,;]*?"
    r"\b(?:can't|cannot|can not|couldn't|won't|don't|doesn't)\s+(?:\w+\s+)?(?:see|get|reach|find|pass|hear|fit|cross|walk|spot|tell)\b"
    # "people there must have nowhere to ...", "cars keep getting hidden behind ...": how things go, not a request
    rf"|{HOW_THINGS_GO.pattern}"
    rf"|{REPORTED.pattern}"
    rf"|{REMINISCED.pattern}"
    # "bin is in a dumb spot", "traffic on Main Street is crawling": a thing named bare and how it is
    rf"|(?!(?:{'|'.join(_VERBS)}|please|pls|can|could|would|will|make sure)\b)[a-z]+(?:\s+[a-z]+){{0,4}}\s+(?:is|are)\s+"
    r"(?:in|on|at|too|not|still|way|over|under|blocking|parked|standing|sitting|facing|so|very|really|always|just|kind of|a bit"
    r"|crawling|jammed|gridlocked|busy|quiet|empty|full|crowded|pitch)\b"
    rf"|{HABITUAL.pattern})"
)


# Asking for a described trouble to be put right without saying how ("fix that", "sort it out").
_FIX = re.compile(r"(?:(?:please|pls|just|can you|could you|now)\s+)*(?:fix|sort out|sort (?:it|that|this) out|deal with|"
                  r"do something about|solve|remedy|correct|sort)\b(?:\s+(?:it|that|this|them))?\s*(?:please|pls|now)?\s*[.!?]*$",
                  re.IGNORECASE)
# A clause that asks for what the one before it asked, of other things: "..., and so does the bin",
# "..., same for the benches".
_SO_DOES = re.compile(r"^\s*(?:[a-z]+\s+)??(?:and\s+)?(?:so (?:does|do|is|are|should|must|will|can|has|have)|(?:the )?same (?:goes )?for"
                      r"|likewise(?: for)?|ditto for|also (?=(?:the|that|this|those|these|both|all)\b))")  # "..., and also the bench"
# A clause that asks for the same again of other things ("..., and the bin too", "the bollards as well").
_TOO = re.compile(r"\b(?:too|as well)(?:,?\s+(?:so|to|for|because|since|as)\b[^.!?;]*)?\s*[.!?]*\s*$")  # "..., so they match"
# An ellipsis the sentence goes on after ("the bench by the stop... vanishes"): a pause, not a break.
# What comes after it as a new clause ("... could you park three cars?", "... and then it pours") breaks.
_TRAILING_OFF = re.compile(r"\s*(?:\.{3,}|\u2026)\s*(?=[a-z])(?!(?:could|can|would|will|please|pls|let'?s|and|but|so|then|now"
                           r"|i|we|you|it|they|he|she|there|make|add|put|move|remove|set|turn|paint|take|get|give|have)\b)")
# A sound or word of feeling before a clause ("ugh, it's going the wrong way"): it says nothing.
_INTERJECTION = re.compile(r"^\s*(?:(?:ugh+|argh+|oh+|ah+|hmm+|um+|uh+|erm|well|wow|meh|gosh|great|brilliant|"
                           r"ok|okay|so|right|yeah|hey|huh|damn|dang|whoa|oops)\b\s*[,!.]+\s*)+")


# How many of the things just named, said after a colon: "...: six of them in a row at the crossing".
_SOME_OF_THEM = re.compile(r"\s*(\d+|two|three|four|five|six|seven|eight|nine|ten|twelve|a few|a couple)\s+of\s+them\b", re.IGNORECASE)
# A sentence up to a colon: a command before it ("clear lot B: both sedans and the SUV") is one clause
# with what follows, which says what it acts on.
_COMMAND_COLON = re.compile(r"(?:(?<=^)|(?<=[.!?;]\s))([^.!?;:]+):\s+")


def _clauses(prompt: str, places: tuple[str, ...] = (), reasons: bool = False) -> list[tuple[str, bool, bool]]:
    """The clauses of a prompt, each with whether it was asked as a question and whether it only
    introduces what follows its colon ("our robot needs a warning: put ..."); without the clauses
    that say why unless `reasons`."""
    prompt = without_salutations(prompt) or prompt  # "Good afternoon. ...": manners, not a time of day
    kept = without_memories(prompt) if reasons else without_reason(prompt).strip() or prompt  # a memory is never a request
    kept = _COMMAND_COLON.sub(lambda m: f"{m.group(1)}, " if commands(m.group(1).lower()) else m.group(0), kept)
    kept = _ASKING_LABEL.sub("tell me ", kept)  # "query: asset=suv_1 fields=[x, y]": a look-up
    parts = _SPLIT.split(_TRAILING_OFF.sub(" ", kept))
    out: list[tuple[str, bool, bool]] = []
    lead = ""  # the last clause's words up to its verb, for a clause that only names another thing
    for i in range(0, len(parts), 2):
        text = parts[i].strip()
        text = text if reasons else without_reason(text).strip() or text
        if not text:
            continue
        why, colon, then = text.partition(": ")
        if colon and then.strip() and not reasons:  # "it spoils the view: let's take it away" (see without_reason)
            out.append((why, False, True))
            text = then
        said = _said_first(text, places) if not reasons else None
        if said is not None:  # "it's too dark, make it day": how it is, then what to do
            out.append((said[0], False, True))
            text = said[1]
        if out and (_AMOUNT_ONLY.match(text.lower()) or (_TOO_MANY_SAID.match(out[-1][0].lower()) and _THEM.search(text.lower())))\
                and ph.find_categories(out[-1][0]) and not ph.find_categories(text) \
                and not commands(out[-1][0].lower()):  # "Put a bench there. Then add 2.": two more, a request of its own
            out[-1] = (f"{out[-1][0]}, {text}", out[-1][1], False)  # "Too many lamp posts. Lose a few.": a few of them
            continue
        counted = _SOME_OF_THEM.match(text) if out else None
        named = ph.find_categories(out[-1][0]) if counted is not None else []
        unplaced = re.sub("|".join(rf"\b{re.escape(p)}\b" for p in places) or "$^", " ", text.lower())  # "the bus stop" is no stop sign
        if counted is not None and named and not ph.find_categories(unplaced):
            # "The children will line up to cross: six of them in a row at the west crossing": six children there
            noun = ph.normalise(out[-1][0])[named[-1].start : named[-1].end].strip()
            out[-1] = (out[-1][0], out[-1][1], True)  # what came before only introduces them
            text = f"{counted.group(1)} {noun}{text[counted.end() :]}"
        if _SUBJECTLESS.match(text.lower()):
            text = f"it {text}"  # "bin's in a dumb spot. needs to be by the library door": it needs to
        # (a verb inside a place's name is none: "the bench at the bus stop" has no "stop" to do)
        verb = _VERB_AT.search(re.sub("|".join(rf"\b{re.escape(p)}\b" for p in places) or "$^", lambda m: " " * len(m.group(0)), text.lower()))
        if verb is None and lead and re.search(r"and also", parts[i - 1]) and ph.find_categories(text):
            text = f"{lead} {text}"  # "remove the hydrant and also the bin": the bin is removed too
            look = re.search(rf"\s((?:{'|'.join(COLOURS)}))\s*[.!]*\s*$", out[-1][0].lower()) if out else None
            if look is not None and not re.search(rf"\b(?:{'|'.join(COLOURS)})\b", text.lower()):
                text = f"{text} {look.group(1)}"  # "paint the bin red, and also the bench": red too
        elif verb is not None:
            particle = re.match(r"\s+(?:away|out|off|down|rid of)\b", text[verb.end() :], re.IGNORECASE)
            lead = text[: verb.end() + (particle.end() if particle else 0)]  # "take away the SUV ..., and also the bench": away too
        # "Could you put the hydrant by the sign, and the bin beside the bench?": a request, every part of it
        asked = i + 1 < len(parts) and "?" in parts[i + 1] and asks(f"{text.lower()}?")
        intro = i + 2 < len(parts) and ":" in parts[i + 1] and bool(parts[i + 2].strip())
        pieces = [q for p in re.split(rf"\s+and\s+(?=(?:{'|'.join(_VERBS)}|give (?:me|us))\b)", text) for q in _comma_and(p)]
        pieces = [q for p in pieces for q in _SAME_AT.split(p)]  # "..., and the same at lot B": a clause of its own
        pieces = [q for p in pieces for q in _WHY_AFTER.split(p)] if commands(text.lower()) else pieces  # "..., it's a trip hazard at night"
        pieces = [q for p in pieces for q in _lights_apart(p)]  # "a car pulling in, with its headlights on"
        # "get the SUV to pull out and drive off east": the one named before does the second thing too
        pieces = [f"have it {q}" if n and _GOES_ON.match(q) and ph.find_categories(pieces[n - 1]) and not ph.find_categories(q) else q
                  for n, q in enumerate(pieces)]
        out.extend((c, asked, intro) for p in pieces if p.strip(" ,") for c in _conjuncts(p.strip(" ,"), places))
    return out


# How things are, said after a command as its reason: "get rid of the fountain, it's a trip hazard at night".
# ("..., that's our courier" names what was added: see named_as)
_WHY_AFTER = re.compile(r",\s+(?=(?:it|they|there)(?:'s|'re| is| are) (?!(?:got to|gotta|going to|supposed to|meant to|time)\b)"
                        r"|that(?:'s| is) (?:where|why|because|how|what)\b)")
# The same again said after an edit in one breath: "cones across the lot A entrance, and the same at lot B".
_SAME_AT = re.compile(rf"(?:,\s*|\s+)(?:and\s+|then\s+)*(?={SAID_AGAIN_AT})")
# Lights said as a detail of a thing: "a car pulling in, with its headlights on", "the ego: faster, and its
# headlights on" switches them too.
_WITH_LIGHTS = re.compile(r",?\s+(?:with|and) (?:its|their|the|her|his) (headlights|vehicle lights) (?:switched |turned )?(on|off|lit|illuminated|blazing)\b"
                          r"(?=\s*(?:[,.;!?]|$))")


def _lights_apart(piece: str) -> list[str]:
    """The piece, and the lights it says a thing has as a request of their own ("headlights on")."""
    said = _WITH_LIGHTS.search(piece)
    state = "off" if said is not None and said.group(2) == "off" else "on"
    return [piece] if said is None else [piece[: said.start()] + piece[said.end() :], f"{said.group(1)} {state}"]


# A label that says what follows it is a look-up: "query: ...", "status: ...".
_ASKING_LABEL = re.compile(r"^\s*(?:query|lookup|look ?up|info|status|report)\s*:\s*", re.IGNORECASE)
# A second motion said with no one to do it: "... and drive off east", "... and head for the gate".
_GOES_ON = re.compile(r"\s*(?:drive|drives|head|heads|go|goes|continue|continues|cruise|cruises|turn|turns|stop|stops|park|parks"
                      r"|brake|brakes|slow|slows|speed|speeds|accelerate|accelerates|reverse|reverses)\b(?!\s+(?:it|them|the|a|an)\b)")
# A sentence that only says how many, its thing named in the one before: "Lose a few.", "Take three away."
_AMOUNT_ONLY = re.compile(r"\s*(?:(?:please|just|so|now|then|ok|okay)\s+)*[a-z]+(?:\s+rid\s+of)?\s+(?:another\s+|all\s+)?"
                          rf"(?:\d+|a few|a couple|(?:(?:down\s+)?(?:to|by)\s+)?(?:a\s+)?half|{'|'.join(w for w in ph.NUMBER_WORDS if w not in ('a', 'an'))})"
                          r"(?:\s+more)?(?:\s+(?:away|off|out|in|down))?(?:\s+(?:please|too))?\s*[.!?]*\s*$")  # "... Reduce to half."
# Too many of a thing, said on its own, then what to do about them: "Too many cones now. Thin them out."
_TOO_MANY_SAID = re.compile(r"\s*(?:(?:there are|there's|we have|we've got|way|far|just|so|still)\s+)*too many\b")
_THEM = re.compile(r"\b(?:them|those|these)\b")
# A sentence whose subject went unsaid, the thing the one before named: "needs to be by the door".
_SUBJECTLESS = re.compile(r"\s*(?:needs?|has|have|should|must|ought|wants?)\s+(?:to\s+)?(?:be|go|stand|sit|move|face)\b")
# A new look asked for ("paint ...", "repaint ...", "recolour ..."), and a building's parts.
_REPAINT = re.compile(r"\b(?:paint|repaint|recolou?r|colou?r)\b")
_BUILDING = re.compile(r"\b(?:walls?|facade|façade|building|roof|doors?|windows?)\b")
# A command after a comma: "..., make it day", "..., please give me some clouds".
_COMMA_COMMAND = re.compile(rf",\s+(?=(?:(?:please|pls|just|so|now|then|let'?s)\s+)*(?:{'|'.join(_VERBS)}|give)\b)")


# A command after a comma that sends a thing away from where it is, saying no place of its own.
_AWAY_AFTER = re.compile(r",\s+(?=[^,;]*\b(?:elsewhere|somewhere else|out of (?:the|my|our|their) (?:way|view|shot|sight))\b)",
                         re.IGNORECASE)


def _said_first(text: str, places: tuple[str, ...]) -> tuple[str, str] | None:
    """A statement of how things are that names nothing, and the command after its comma ("it's
    too dark, make it day"); None where the statement names a thing or place the command may
    mean ("Campus Drive feels empty, make it livelier", "the bench is in the way, move it")."""
    away = _AWAY_AFTER.search(text)
    if away is not None and _STATEMENT.match(text[: away.start()].lower()) and not any(
            re.search(rf"\b{re.escape(p)}\b", text[away.end() :].lower()) for p in places):
        # "the SUV is blocking the Library, can it be somewhere else?": the place said is where it is, not where to
        return text[: away.start()], text[away.end() :]
    cut = _COMMA_COMMAND.search(text)
    if cut is None or not _STATEMENT.match(low := text[: cut.start()].lower()):
        return None
    named = (ph.find_categories(low) or "_" in low or ph.has_any(low, ph.EGO_WORDS)
             or any(re.search(rf"\b{re.escape(p)}\b", low) for p in places)
             or re.search(r"\b(?:street|road|lane|drive|avenue|lot|car park|crossing)\b", low))
    return None if named else (text[: cut.start()], text[cut.end() :])


def _comma_and(text: str) -> list[str]:
    """"ego a bit forward, and the bench the other way round": two requests, each naming its own
    thing, joined by a comma and "and" with no verb between."""
    if md.layout_said(text.lower()):
        return [text]  # "a ring of cones, and barriers too": one layout of both
    parts = re.split(r",\s*and\s+", text)
    named = [bool(ph.find_categories(p) or ph.has_any(p.lower(), ph.EGO_WORDS) or "_" in p) for p in parts]
    return parts if len(parts) > 1 and all(named) else [text]


# "and the trash bin", "plus a pedestrian", "+ two cones", "and both cars": a second thing for the
# same verb (kept only where every part names a thing).
_CONJUNCT = re.compile(r"\s*(?:,\s*)?(?:\band\b|\bplus\b|\+|&)\s+(?=[a-z0-9])")
_VERB_AT = re.compile(rf"\b(?:{'|'.join(_VERBS)})\b(?! sign\b)")  # "the stop sign" names a thing, no verb
# A list of things by commas, each with its own words ("paint the bench red, the bin blue and ...").
# ("..., 20 metres ahead of the ego" is where the thing goes, not a second thing)
_LISTED = re.compile(r"\s*,\s+(?=(?:the|a|an|one|two|three|four|five|\d+)\s)"
                     r"(?!\S+\s+(?:m|metres?|meters?|ft|feet|foot|yards?|km|kilomet\w*)\b)")
# More of the thing just named, its noun left out: "another two", "two more", "one more", "another".
_MORE_OF = re.compile(r"^\s*(?:another(?:\s+(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten))?"
                      r"|(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+more)\b", re.IGNORECASE)

# Where the last of several things named goes ("... and a bin by the Student Union entrance"), said after it.
_PLACE_TAIL = re.compile(r"\s((?:by|at|near|next to|beside|outside|in front of|behind|in|on|inside|around|to)\s+(?:the\s+)?\S.*)$",
                         re.IGNORECASE)
# "..., and the one by the library", "and the other one at the gate": another of the thing named first.
# A route said ("from the main gate to the Engineering Hall"), and its length asked after it ("how far is that?").
_ROUTE_SAID = re.compile(r"\bfrom (?:the )?[a-z][\w ]{2,40}? to (?:the )?[a-z][\w ]{2,40}?(?=\s+(?:every|each|daily|most|in the|at|on|then|and)\b|\s*$)")
_HOW_FAR_THAT = re.compile(r"(?:[\w ]{0,20}?,?\s*)?how (?:far|long) is (?:that|it|the walk|the route|the trip|that walk)\s*\??", re.IGNORECASE)
# One more of what was just added, described: "a blue one next to it", "and an older one by the gate".
_ONE_MORE_DESCRIBED = re.compile(r"(?:^|[,;.]|\band\b|\badd\b|\bput\b|\bplus\b)\s*(?:also\s+)?(?:a|an)\s+(?:[a-z]+\s+){0,2}?one\b(?![-\w])")
_ONE_OF = re.compile(r"^\s*(the(?: other)?|that|this)\s+one\b", re.IGNORECASE)


# Which of the things just named is meant, said after a comma: "..., the one by the fountain" (with
# "and" it is another one: see _ONE_OF).
_THE_ONE = re.compile(r",\s*(?:i mean\s+|namely\s+)?the one\s+(?=(?:(?:north|south)[\s-]?(?:east|west)|north|south|east|west|near|nearest"
                      r"|closest|furthest|farthest|by|next|beside|behind|in|on|at|outside|opposite)\b)", re.IGNORECASE)


# A second amount of things after "and": "... and 2 barriers at the north crosswalk".
_COUNTED_AND = re.compile(r",?\s+and\s+(?=(?:\d+|two|three|four|five|six|seven|eight|nine|ten|a couple of|a few)\s+[a-z])", re.IGNORECASE)


# A wish that governs the things after it as a verb does: "I need", "we want", "I'd like".
_WISHED = re.compile(r"\b(?:need|needs|want|wants|would like|'d like)\b")


def _conjuncts(clause: str, places: tuple[str, ...] = ()) -> list[str]:
    """A clause whose verb governs two things ("remove the hydrant and the bin", "put the bench at
    the fountain and the bin at the bus stop"), as one clause per thing, each with the verb.

    Only where both parts name a category and nothing lays them out together ("a ring of cones and
    barriers", "between the bus and the truck" stay one clause).
    """
    clause = _THE_ONE.sub(" ", clause)  # "remove the tree on the quad, the one east of the fountain": which tree
    low = clause.lower()
    for name in places:  # "the bus stop" has no verb in it
        low = re.sub(rf"\b{re.escape(name)}\b", lambda m: " " * len(m.group(0)), low)
    verb = _VERB_AT.search(low) or _WISHED.search(low)  # "I need a barrier and a roadworks sign there": both wished for
    # "5 cones in a line at the west crosswalk and 2 barriers at the north crosswalk": each counted and placed, two requests
    second = _COUNTED_AND.search(clause, verb.end()) if verb is not None else None
    if verb is not None and second is not None and (noun := _first_noun(clause[: second.start()])):
        first, rest = clause[: second.start()], clause[second.end() :]
        if not ph.find_categories(rest):  # "3 cones at the main gate and 2 at the east gate": 2 cones
            amount = re.match(r"\s*(?:a couple of|a few|\S+)", rest)
            rest = f"{rest[: amount.end()]} {noun}{rest[amount.end() :]}" if amount else rest
        if _PLACE_TAIL.search(first) and _PLACE_TAIL.search(rest) and ph.find_categories(rest):
            return [first, f"{clause[: verb.end()]} {rest}"]
    # "a line of cones and barriers" is one layout; "the car at the end of the row" names one of a row there
    if verb is None or any(w in low for w in (*lx.ARRANGE_WORDS, "between", " grid", "mix")) or re.search(r"(?<!\bthe) (?:line|row)\b", low):
        return [clause]
    cuts = sorted([m for m in (*_CONJUNCT.finditer(clause), *_LISTED.finditer(clause)) if m.start() > verb.end()],
                  key=lambda m: m.start())
    parts, start = [], 0
    for cut in cuts:
        if cut.start() >= start:
            parts.append(clause[start : cut.start()])
            start = cut.end()
    parts.append(clause[start:])
    noun = _first_noun(parts[0])
    if noun:  # "two cones at the main gate and another two at the east gate": more of the same thing
        parts[1:] = [_ONE_OF.sub(lambda m: f"{m.group(1)} {noun}", _MORE_OF.sub(lambda m: f"{m.group(0)} {noun}", p, count=1), count=1)
                     if not ph.find_categories(p) else p for p in parts[1:]]
    if len(parts) < 2 or not all(ph.find_categories(p) or ph.has_any(p.lower(), ph.EGO_WORDS)
                                 or ASSET_ID.search(p) for p in parts):
        return [clause]  # each part names a thing ("park the SUV in lot A and the ego in lot B")
    particle = re.match(r"\s+(?:out|away|off|down|up|rid of)\b", clause[verb.end():], re.IGNORECASE)
    lead = clause[: verb.end() + (particle.end() if particle else 0)]  # "take out the hydrant and the sign": both taken out
    apart = None if particle else re.search(r"\b(away|out|off)\b", clause[verb.end() : cuts[0].start()], re.IGNORECASE)
    if apart is not None:  # "take the cars away from lot B, the sedans and the SUV": each taken away
        lead = f"{lead} {apart.group(1)}"
    tail = re.search(r"\s+(away|out|off|down)\s*[.!]*\s*$", parts[-1], re.IGNORECASE)
    if tail is not None and particle is None and apart is None:  # "take car 1 and car 2 away": both taken away
        parts[:-1] = [f"{p} {tail.group(1)}" for p in parts[:-1]]
    colour = re.search(rf"\s+((?:{'|'.join(COLOURS)}))\s*[.!]*\s*$", parts[-1].lower())
    if colour is not None and not any(re.search(rf"\b(?:{'|'.join(COLOURS)})\b", p.lower()) for p in parts[:-1]):
        parts[:-1] = [f"{p} {colour.group(1)}" for p in parts[:-1]]  # "paint the bench and the bin red": both red
    where = _PLACE_TAIL.search(parts[-1])
    if where is not None and not any(_PLACE_TAIL.search(p) or ASSET_ID.search(p) for p in parts[:-1]):
        parts[:-1] = [f"{p} {where.group(1)}" for p in parts[:-1]]  # "put a bench and a bin by the union": both by it
    return [parts[0], *(f"{lead} {p}" for p in parts[1:])]


def _first_noun(text: str) -> str:
    """The words naming the first thing `text` names, as said ("cones"); "" when it names none."""
    said = ph.find_categories(text)
    return ph.normalise(text)[said[0].start : said[0].end].strip() if said else ""  # the text find_categories indexes


def _own_words(kind: str, head: str) -> set[str]:
    """The words of a kind's names other than the head they share ("stop", "roadworks", "work zone")."""
    return {w for phrase in catalog()[kind].words for w in phrase.lower().replace("_", " ").split() if w != head}


# "Less" right after a thing, then a word for how it is: "make the SUV less flashy", "the bench a bit
# less shiny": how the thing is, never fewer of them ("fewer cars", "less of the cones", "less than two").
_LESS_OF_A_KIND = re.compile(r"\s+(?:(?:be|made|look|looks|seem|seems|a|bit|little|lot|touch|much|slightly|way|far|somewhat)\s+){0,4}less\s+(?!of\b|than\b|(?:fast|quick|slow|speedy|rapid)\w*\b)[a-z]+")


# One of a kind said before, with no noun of its own: "a new one", "a replacement one", "the last one".
_A_NEW_ONE = re.compile(r"\b(an?\s+(?:brand[\s-]new|new|fresh|replacement|different|spare|better|nicer)\s+"
                        # ("paint the second one blue" is of the last turn's things, read elsewhere; "next to the last one" is here)
                        r"|(?:next to|beside|by|behind|near|in front of|opposite)\s+the\s+(?:last|first|second|third|final)\s+)one\b",
                        re.IGNORECASE)


def _kind_said_last(memory: Memory) -> str | None:
    """The kind of thing the latest turn still in the scene acted on ("remove the bin", then
    "put a new one at the bus stop"), from its calls; None when it named none."""
    turns = memory.live_turns()
    try:
        calls = turns[-1].tool_calls() if turns else []
    except (ValueError, SyntaxError):
        return None
    for call in calls:
        ids = [call.args.get("asset"), *(call.args.get("assets") or [])]
        said = call.args.get("category") or next((i.rsplit("_", 1)[0] for i in ids if isinstance(i, str) and "_" in i), None)
        if isinstance(said, str) and said in catalog():
            return said
    return None


class RulePlanner:
    """Keyword-and-slot planner over the Worker tools."""

    name = "rules"

    @staticmethod
    def _read(
        clauses: list[tuple[str, bool, bool]], context: PlanContext, notes: Notes
    ) -> tuple[list[ToolCall], list[str], list[str], list[ToolCall]]:
        """Each clause's calls: those of requests, the unknown words in them, the clauses that
        asked nothing, and the calls of clauses that only describe or introduce."""
        scene = context.scene
        calls: list[ToolCall] = []
        unknown: list[str] = []
        skipped: list[str] = []
        described: list[ToolCall] = []
        previous: list[ToolCall] = []  # the calls of the last clause that asked for something
        kind: str | None = None  # what "a new one" is one of: the clause before's, else (read only when asked) the last turn's
        route: str | None = None  # the last "from A to B" a clause said
        for clause, asked, intro in clauses:
            clause, name = named_as(clause)  # "add a pedestrian at the gate, that's our steward"
            if asked and route is not None and _HOW_FAR_THAT.fullmatch(clause.strip()):
                clause = f"how far is it {route}"  # "I walk from the stop to the library daily. How far is that?"
            said_route = _ROUTE_SAID.search(clause.lower())
            route = said_route.group(0) if said_route is not None else route
            reading = read(clause, scene)
            new_one = _A_NEW_ONE.search(clause)
            if new_one is not None and (kind := kind or _kind_said_last(context.memory)) is not None:
                # "remove the bin and put a new one at the bus stop": a new bin
                clause = f"{clause[: new_one.end(1)]}{kind.replace('_', ' ')}{clause[new_one.end() :]}"
                reading = read(clause, scene)
            kind = reading.mentions[0].category if reading.mentions else kind
            coming = len(notes.coming)
            if name and not reading.mentions and calls and calls[-1].tool == "add_asset":  # "... at the gate. That's our steward."
                calls[-1] = _labelled_as(calls[-1], name)
                continue
            look = next((c for c in reversed(calls) if c.tool == "set_asset_appearance"), None)
            if look is not None and _TOO.search(reading.low) and reading.mentions and not any(
                    reading.has((c,)) for c in COLOURS):
                # "the bench as yellow as a banana, and the bin next to it too": the same look for the bin
                things = referenced(reading, scene, context.memory, notes)
                if things:
                    style = {k: v for k, v in look.args.items() if k in ("colour", "material")}
                    calls.append(ToolCall(tool="set_asset_appearance", args={"assets": things, **style}))
                    continue
            # "..., and so does the bin", "..., and the bench too": the clause before, done to them
            if previous and reading.mentions and (_SO_DOES.match(reading.low) or (
                    _TOO.search(reading.low) and _VERB_AT.search(reading.low) is None)):
                things = referenced(reading, scene, context.memory, notes)
                again = retargeted(previous, things) if things else []
                if again:  # "the bench has to go, and so does the bin": the clause before, done to the bin
                    calls.extend(again)
                    continue
            if previous and said_again(reading):  # "cones across the lot A entrance, and the same at lot B"
                again = repeat(reading, scene, context.memory, notes, earlier=previous)
                calls.extend(again)
                previous = again
                continue
            statement = bool(intro or _STATEMENT.match(_INTERJECTION.sub("", reading.low))) and not asked
            try:
                clause_calls = _plan_clause(reading, asked, scene, context.memory, notes)
            except PlanningError:
                if not statement or len(clauses) == 1:
                    raise
                continue  # "..., that's where the works are": how things are, said as context, asks nothing of its own
            if reading.landmark:
                notes.place = {"relation": "at", "target": reading.landmark}
            if clause_calls is None:
                skipped.append(clause)
                notes.scene_set = notes.place if reading.landmark else notes.scene_set
                continue
            if statement:
                described.extend(clause_calls)  # "the bench by the stop is in the way": context, unless all there is
                if set(notes.subject) & set(notes.coming[coming:]):
                    notes.subject = notes.named  # nor is it what a later "it" means
                del notes.coming[coming:]  # what it would add is not coming
                # "who put a hydrant by the crossroads? get rid of it": the one there is what "it" means;
                # "cars keep getting hidden behind that bin ... get rid of it": the one thing it names singly
                notes.subject = _already_there(clause_calls, scene) or _named_singly(reading, scene) or notes.subject
                continue
            if _BARE_NAMING.match(reading.low) and _VERB_AT.search(reading.low) is None and clause_calls and all(
                    c.tool == "place_asset" and c.args.get("asset") in _named_in(calls) for c in clause_calls):
                continue  # "a ring of bollards round the tree by the Library. The tree near the Library.": which tree
            if name:
                clause_calls = [_labelled_as(c, name) if c.tool == "add_asset" else c for c in clause_calls]
            calls.extend(clause_calls)
            previous = clause_calls
            unknown += _unknown_words(clause, scene)
        return calls, unknown, skipped, described

    def _which_place(self, prompt: str, context: PlanContext, left_out: list[ToolCall] | None = None) -> Plan | None:
        """A question offering the request at each place its place word may mean, when it names
        a kind of place several places are ("by the gate"), or the request at the one place called
        that ("at the stop"); None when it does neither. `left_out`: the plan that dropped the place,
        and so no reading (the place named changing nothing is no reading of it)."""
        for start, end, kind, places in _kinds_of_place(prompt.lower(), context.scene):
            plans = []
            for name in places[:MAX_READINGS]:
                text = prompt[:start] + f"the {name}" + prompt[end:]
                try:
                    reading = self._plan(text, context, which_place=False)
                except PlanningError:
                    continue
                if reading.calls and _UNRECOGNISED not in reading.trace[0].output:
                    plans.append(reading)
            if left_out is not None and all(p.calls == left_out for p in plans):
                plans = []  # the place named changes nothing: no reading of it
            if len(places) == 1 and plans:
                return plans[0]  # "at the stop": the one place called that, the bus stop
            readings = [Choice(text=describe(p.calls), calls=p.calls) for p in plans]
            if len(readings) >= 2:
                step = TraceStep(level="rules", input=prompt, output=f"{kind!r} names {', '.join(places)}; asking")
                return Plan(calls=[], planner=self.name, confidence=0.0, prompt_version=PROMPT_VERSION, trace=[step],
                            question=Question(text=f"Which {kind} do you mean?", readings=readings))
        return None

    def _which_thing(self, prompt: str, context: PlanContext) -> Plan | None:
        """A question offering the request with each of the two names a description comes near
        when it comes no nearer one than the other; None when every description is clear."""
        for said in unsure(prompt, context.scene)[:1]:
            plans = []
            for name in (said.name, said.runner_up):
                try:
                    plans.append(self._plan(prompt[: said.start] + said.said_as(name) + prompt[said.end :], context, which_place=False))
                except PlanningError:
                    continue
            readings = [Choice(text=describe(p.calls), calls=p.calls) for p in plans if p.calls and p.question is None]
            if len(readings) >= 2:
                step = TraceStep(level="rules", input=prompt, output=f"{said.said!r} is near {said.name} and {said.runner_up}; asking")
                names = " or ".join(said.said_as(n) for n in (said.name, said.runner_up))
                return Plan(calls=[], planner=self.name, confidence=0.0, prompt_version=PROMPT_VERSION, trace=[step],
                            question=Question(text=f"By {said.said!r}, do you mean {names}?", readings=readings))
        return None

    def _what_fills(self, prompt: str, context: PlanContext) -> Plan | None:
        """A question offering a few things to add where a request only says a place is bare or
        empty and names nothing to put there ("the junction looks a bit bare", "it feels too
        empty near the fountain"); None for any other request."""
        low = ph.normalise(prompt)
        if not BARE_STATE.search(low) or ph.find_categories(low) or asks(low.strip()) or LIVELIER.search(low) \
                or any(commands(part) and not re.search(r"\b(?:something|some things|stuff|anything)\b", part)
                       for part in re.split(r"[,.;!]+|\band\b|\bso\b", low)):
            return None  # "main street feels deserted, make it livelier": the request says what to do ("put something there" does not)
        place = find_place(context.scene, low)
        where = f" near the {place[0]}" if place is not None else ""
        readings = self._offered([f"add {offer}{where}" for offer in _FILLERS_OFFERED], context)
        if len(readings) < 2:
            return None
        step = TraceStep(level="rules", input=prompt, output="a place said to be bare, nothing named for it; asking")
        return Plan(calls=[], planner=self.name, confidence=0.0, prompt_version=PROMPT_VERSION, trace=[step],
                    question=Question(text=f"What should I add{where or ' there'}?", readings=readings))

    def _offered(self, texts: list[str], context: PlanContext) -> list[Choice]:
        """The readings of `texts` the rules plan without a question of their own, to offer in one."""
        readings = []
        for text in texts:
            try:
                reading = self._plan(text, context, which_place=False)
            except PlanningError:
                continue
            if reading.calls and reading.question is None:
                readings.append(Choice(text=describe(reading.calls), calls=reading.calls))
        return readings

    def _which_kind(self, prompt: str, context: PlanContext) -> Plan | None:
        """A question where a new thing is named only by a word several kinds end in ("add a sign
        next to the bench": a stop, construction, pedestrian or parking sign?), offering the
        request with each kind; None when no such word is said, or a word of one kind is."""
        heads = shared_heads()
        said = re.search(rf"\b(?:an?|one|two|three|four|five|some|another|\d+)\s+(?:(?:new|small|big|little|extra|more)\s+)?"
                         rf"(?P<head>{'|'.join(heads)})(?P<plural>s)?\b", prompt, re.IGNORECASE) if heads else None
        if said is None or not (ADD_WORDS.search(prompt.lower()) or _WISHED.search(prompt.lower())):
            return None
        kinds = heads[said.group("head").lower()]
        if any(re.search(rf"\b{re.escape(w)}\b", prompt, re.IGNORECASE) for k in kinds for w in _own_words(k, said.group("head"))):
            return None  # "a sign for the roadworks", "a sign telling drivers to stop": the kind is said
        names = [kind.replace("_", " ") + (said.group("plural") or "") for kind in kinds[:MAX_READINGS]]
        readings = self._offered([prompt[: said.start("head")] + name + prompt[said.end() :] for name in names], context)
        if len(readings) < 2:
            return None
        head = said.group("head").lower()
        step = TraceStep(level="rules", input=prompt, output=f"{head!r} names {', '.join(kinds)}; asking")
        return Plan(calls=[], planner=self.name, confidence=0.0, prompt_version=PROMPT_VERSION, trace=[step],
                    question=Question(text=f"Which {head}: {', '.join(k.replace('_', ' ') for k in kinds)}?", readings=readings))

    def _each_place(self, prompt: str, context: PlanContext) -> Plan | None:
        """The request done at each place of a kind it says every one of ("a stop sign at every
        crosswalk", "cones at both gates"); None when it says no such thing."""
        said = EACH_PLACE.search(prompt.lower())
        places = each_place_named(context.scene, prompt.lower())
        if said is None or len(places) < 2:
            return None
        parts = [self.plan(prompt[: said.start("said")] + f"the {name}" + prompt[said.end("said") :], context) for name in places]
        if any(c.tool not in ("add_asset", "arrange_assets") for p in parts for c in p.calls):
            return None  # "paint the bench at every crosswalk": the places pick things out, they are no destinations
        step = TraceStep(level="rules", input=prompt, output=f"at each of {', '.join(places)}: "
                         + "; ".join(p.trace[0].output for p in parts))
        return Plan(calls=[c for p in parts for c in p.calls], planner=self.name, confidence=min(p.confidence for p in parts),
                    prompt_version=PROMPT_VERSION, trace=[step])

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        return self._plan(prompt, context)

    def _plan(self, prompt: str, context: PlanContext, which_place: bool = True) -> Plan:
        """The plan; `which_place`: whether a place word several places share may be asked about
        (not while reading one of the places offered, which would ask again without end)."""
        prompt = without_left_as_it_is(prompt)  # "..., leave the two cars where they are": nothing to ask of them
        each = self._each_place(prompt, context)
        if each is not None:
            return each
        if which_place and (doubt := self._which_thing(prompt, context)) is not None:
            return doubt  # "the big vehicle that carries lots of passengers": a bus or a truck?
        if which_place and (offer := self._what_fills(prompt, context)) is not None:
            return offer  # "the junction looks a bit bare": people, trees or benches there?
        if which_place and (offer := self._which_kind(prompt, context)) is not None:
            return offer  # "add a sign next to the bench": a stop sign, a construction sign, ...?
        started = time.perf_counter()
        scene = context.scene
        repaired = repair(prompt, scene)
        notes = Notes()
        for fix in repaired.repairs:
            notes.guess(f"spelling {fix}")
        places = tuple(n.lower() for lm in scene.landmarks for n in lm.names())
        text = repaired.text
        if (given := condition(text, scene)) is not None:  # "if there's a bus, paint it yellow"
            text = given.request if given.met else given.question  # no bus: whether there is one
        text = _as_meant(text)  # "put the bench by the fountain... no wait, scrap that, just turn it round"
        if _ONLY_FORBIDS.match(text):  # "don't move the SUV": a thing not to do, and nothing to do
            raise PlanningError(f"you said what not to do ({text.strip()!r}) and nothing to do instead, so nothing was changed")
        text = topic_first(text, scene) or text  # "the tree near the fountain, move it 3 m north"
        clauses = _clauses(text, places)
        if not clauses:
            raise PlanningError("the prompt has no request in it")
        spelling = list(notes.guesses)
        calls, unknown, skipped, described = self._read(clauses, context, notes)
        if not calls and not described and (whole := _clauses(repaired.text, places, reasons=True)) != clauses:
            # "we're filming the late shift, so it has to be night": what read as the reason is the request
            notes = Notes(guesses=spelling)
            calls, unknown, skipped, described = self._read(whole, context, notes)
        if not calls and any(_FIX.match(clause.strip()) for clause in skipped):
            # "it's pitch dark, fix that": what was described is the trouble, not what is wanted
            raise PlanningError(
                "I can tell what is wrong, but not what you want instead; say how it should be, "
                "e.g. 'make it daytime', 'remove the cones'"
            )
        from_statement = not calls and bool(described)
        if from_statement and (absent := _spoken_of_as_there(text, described, scene)):
            raise PlanningError(f"you spoke of the {absent.replace('_', ' ')} as if it were there, but the scene has none, "
                                f"so nothing was changed; say 'add a {absent.replace('_', ' ')} ...' to add one")
        if from_statement:
            # "the bench by the stop is in the way", and nothing else: what it says is a guess at the wish;
            # never to put a thing where the statement says it already is ("the bin is in the middle of the pavement")
            calls = [] if any(_said_where_it_is(c, scene) for c in described) else described  # none of its placements is a wish
            notes.guess(STATEMENT_READ)
        calls = _alike(calls, text.lower(), scene, context.memory)  # "another exactly like it"
        calls = _not_removed_twice(calls, scene)  # "clear the cars out of lot B: both sedans and the SUV"
        calls = _cleared_first(calls, scene)  # "could the bench go, and the bin be moved to where the bench was"
        calls = _not_restated(calls, text.lower())  # "turn it around ... turn it all the way around, the ego car"
        calls = _not_put_where_it_is(calls, scene)  # "the SUV sits in lot B doing nothing. maybe it doesn't need to exist?"
        if calls and asks(text.lower()) and not any(commands(clause.lower()) for clause, _, _ in clauses):
            # "a driver mentioned a stop sign by the crossing; I want to confirm it's there": what the
            # story names is what the question is about, never something to add
            calls = [of_group(c, read(text, scene)) for c in _as_searches(calls)]  # "how many cars": SUVs too
        if not calls and skipped:
            strange = [w for clause in skipped for w in _unknown_words(clause, scene)]
            first = f"there is no {strange[0]!r} in this world that I know of; " if strange else ""
            raise PlanningError(
                f"{first}I could not tell what to do with {skipped[0]!r}; I can add, move, remove, arrange and "
                "restyle things, find them, and set the weather and time, e.g. 'add 3 traffic cones "
                "in front of the JTEKT building entrance', 'make it rain', 'remove the bus'"
            )
        # "the bench is too near the road. Put it more far from it": the command it could not read is
        # the wish, never the statement beside it read as one, nor a plan without the action said
        dropped = next((clause for clause in skipped if _DROPPED_ACTION.search(clause.lower())
                        or (from_statement and commands(clause.lower()) and _SAYS_WHERE.search(clause.lower()))), None)
        # a clause not read that says something (a word not known, or where: not a heading such as "Stage
        # the fleet: ...", nor a pointer back such as "give me one of those"), beside a word not known in
        # what was read: too little read to act on unasked (on practice suites 10-14 and 24-28 at 9e72caa,
        # plans with a clause unread and a word unknown were 11 wrong edits and 5 right)
        telling = [clause for clause in skipped if not re.search(rf"{re.escape(clause.strip())}\s*:", text)
                   and (_unknown_words(clause, scene) or _SAYS_WHERE.search(clause.lower()))]
        changes = any(context.registry.get(c.tool).family != "search" for c in calls)  # a question's story is no part of what to do
        if dropped is None and telling and unknown and not from_statement and changes:
            dropped = telling[0]
        if calls and dropped is not None:  # "have the suv pull out and follow the ego": never the pulling out alone, silently
            step = TraceStep(level="rules", input=prompt, output=f"{describe(calls)}, but {dropped!r} not read; asking")
            return Plan(calls=[], planner=self.name, confidence=0.0, prompt_version=PROMPT_VERSION, trace=[step],
                        question=Question(text=f"I could not read {dropped!r}. Do only this: {describe(calls)}?",
                                          readings=[Choice(text=describe(calls), calls=calls)]))
        for clause in skipped:
            notes.guess(f"ignored {clause!r}")
        left_out = _kind_of_place_left_out(text, calls, scene) if calls else None
        if _UNRECOGNISED in notes.guesses or left_out:
            question = self._which_place(prompt, context, left_out=calls if left_out is not None else None) if which_place else None
            if question is not None:
                return question  # "put a cone by the gate": the main gate or the east gate?
            if left_out is not None and _UNRECOGNISED not in notes.guesses:  # "make the ego stop at the gate"
                raise PlanningError(f"'the {left_out[0]}' may be the {' or the '.join(left_out[1])}; say which")
            # "by the red building": said where, and no place of the world fits; never put it just anywhere
            names = ", ".join(lm.name for lm in scene.landmarks[:MAX_PLACES_LISTED])
            said = PLACE_SAID.search(text.lower())
            what = f"{said.group(1)!r}" if said else "the place you named"
            missing = [m.category for m in ph.find_categories(said.group(1)) if not scene.count(m.category)] if said else []
            if missing:  # "beside the truck" with no truck: the thing is missing, not unknown
                raise PlanningError(f"there is no {missing[0].replace('_', ' ')} in the scene to put it by; add one first, "
                                    f"or name a place such as {names}")
            raise PlanningError(f"I do not know {what} in this world; places here include {names}")
        # "shift it 2 m kerbside": a way said and not read is never guessed (with none said, as in "shift the bin a
        # little", any way is what was asked)
        respelt = any(g.startswith("spelling ") for g in notes.guesses)  # "5 m aftwards", read as "towards"
        # "shift the bench 3 metres est", "shift it well away from it" (the junction said in a clause before)
        way_unread = _WORD_AFTER_STEP.search(text.lower()) is not None or TOWARD.search(text.lower()) is not None
        if WAY_GUESSED in notes.guesses and (unknown or respelt or way_unread) and (ways := other_ways(calls)):
            step = TraceStep(level="rules", input=prompt, output=f"{describe(calls)}, but the way to move not read; asking")
            return Plan(calls=[], planner=self.name, confidence=0.0, prompt_version=PROMPT_VERSION, trace=[step],
                        question=Question(text="Which way should it move?",
                                          readings=[Choice(text=describe(way), calls=way) for way in ways]))
        confidence = FULL_CONFIDENCE - UNKNOWN_WORD_PENALTY * len(unknown) - GUESS_PENALTY * len(notes.guesses)
        why = "; ".join([*notes.guesses, *(f"unknown word {w!r}" for w in unknown)]) or "understood every word"
        step = TraceStep(
            level="rules",
            input=prompt,
            output="; ".join(str(c) for c in calls) + f" ({why})",
            seconds=time.perf_counter() - started,
        )
        return Plan(
            calls=calls,
            planner=self.name,
            confidence=max(MIN_CONFIDENCE, confidence),
            prompt_version=PROMPT_VERSION,
            trace=[step],
        )


def _as_meant(text: str) -> str:
    """The request without what the speaker took back (intent.taken_back), its pronouns still
    meaning what the words taken back named ("put the bench by the fountain... scrap that, just
    turn it round": it is the bench)."""
    rest, dropped = taken_back(text)
    named = ph.find_categories(dropped)
    if named and not ph.find_categories(rest) and re.search(r"\b(?:it|them|that one|those)\b", rest.lower()):
        said = ph.normalise(dropped)[named[0].start : named[0].end].strip()
        return f"the {said}, {rest}"
    return rest


# A new thing said to be like one there: "another one exactly like it", "a copy of that one".
_LIKE_IT = re.compile(r"\b(?:(?:exactly|just) like|identical to|(?:the )?same as|a copy of|matching"
                      r"|(?:another|one more|a second)(?: one)? like) "  # "and another one like it next to it"
                      r"(?:it|that|this|that one|this one|the (?:other|last|first) one)\b")


# What a thing does that a copy of it does too (a path or a circle's centre is its own).
_COPIED_DOINGS = ("drive_lane", "cross_road", "jaywalk")


def _alike(calls: list[ToolCall], low: str, scene: Scene, memory: Memory) -> list[ToolCall]:
    """Additions said to be like a thing there, given its colour and what it is doing (a car
    "just like it" behind one driving east drives east too): the thing their place names when it
    is of their kind, else the last one of their kind added."""
    if not _LIKE_IT.search(low):
        return calls
    out = []
    for call in calls:
        category = call.args.get("category")
        where = call.args.get("location") or {}
        target = scene.asset(str(where.get("target"))) if isinstance(where, dict) else None
        if target is None or target.category != category:
            target = next((a for i in reversed(memory.last_added(str(category))) if (a := scene.asset(i)) is not None), None)
        rgba = target.appearance.rgba if target is not None else None
        if call.tool == "add_asset" and rgba is not None and "colour" not in call.args:
            call = call.model_copy(update={"args": {**call.args, "colour": hex_colour(rgba)}})
        doing = target.behaviour.model_dump() if target is not None else {}
        if call.tool == "add_asset" and doing.get("kind") in _COPIED_DOINGS and "behaviour" not in call.args:
            copied = {k: v for k, v in doing.items() if k in ("kind", "lane", "speed") and v is not None}
            call = call.model_copy(update={"args": {**call.args, "behaviour": copied}})
        out.append(call)
    return out


def _as_searches(calls: list[ToolCall]) -> list[ToolCall]:
    """A question's calls with each addition a story named made a search for its kind at its place,
    weather, time or lighting it names a look at the environment ("confirm whether it is raining"),
    a thing it places a look at the thing, and a search for anything there dropped beside a search
    for a kind there."""
    if not any((c.tool == "add_asset" and c.args.get("category")) or c.tool in _ENVIRONMENT_SET or c.tool in _PLACING for c in calls):
        return calls
    out: list[ToolCall] = []
    for call in calls:
        if call.tool in _ENVIRONMENT_SET:
            call = ToolCall(tool="describe_environment", args={})
        elif call.tool in _PLACING and isinstance(call.args.get("asset"), str):
            call = ToolCall(tool="asset_properties", args={"asset": call.args["asset"]})  # "can't recall if I parked it in lot A"
        elif call.tool == "add_asset" and call.args.get("category"):
            where = call.args.get("location") or {}
            target = where.get("target") if isinstance(where, dict) else None
            args: dict[str, Any] = {"category": call.args["category"]}
            if target:
                args |= {"near": target, "within": DESCRIBED_NEAR_M}
            call = ToolCall(tool="find_assets", args=args)
        if call not in out:
            out.append(call)
    kinds = [c.args for c in out if c.tool == "find_assets" and c.args.get("category")]
    # "anything near the crossing" beside "a stop sign near the crossing": the search for the kind
    return [c for c in out if not (c.tool == "find_assets" and not c.args.get("category") and set(c.args) <= {"near", "within"}
                                   and any(c.args.get("near") == k.get("near") for k in kinds))]


def _said_where_it_is(call: ToolCall, scene: Scene) -> bool:
    """Whether `call` puts a thing where it already stands: on a sidewalk it is on, or at a place
    it is within DESCRIBED_NEAR_M of (a statement's place is where the thing is, not where to go)."""
    where, thing = call.args.get("location"), scene.asset(str(call.args.get("asset")))
    if call.tool != "place_asset" or thing is None or not isinstance(where, dict):
        return False
    if where.get("relation") == "on_sidewalk" and "target" not in where:
        return surface_at(scene, thing.pose.x, thing.pose.y) == "sidewalk"
    place = scene.landmark(str(where.get("target"))) if where.get("relation") != "absolute" else None
    return place is not None and (math.dist((thing.pose.x, thing.pose.y), place.position) <= DESCRIBED_NEAR_M
                                  or (place.polygon is not None and point_in_polygon(thing.pose.x, thing.pose.y, place.polygon)))


def _not_put_where_it_is(calls: list[ToolCall], scene: Scene) -> list[ToolCall]:
    """`calls` without a placement of a thing in the area it already stands in, where another call
    acts on it too: a statement of where it is ("the SUV sits there in lot B"), read before the request."""
    def idle(call: ToolCall) -> bool:
        where, thing = call.args.get("location"), scene.asset(str(call.args.get("asset")))
        place = scene.landmark(str(where.get("target"))) if isinstance(where, dict) and where.get("relation") == "at" else None
        return (call.tool == "place_asset" and thing is not None and place is not None and place.polygon is not None
                and point_in_polygon(thing.pose.x, thing.pose.y, place.polygon)
                and sum(c.args.get("asset") == thing.id or thing.id in (c.args.get("assets") or []) for c in calls) > 1)

    return [c for c in calls if not idle(c)]


# What sets the weather, the time or the lights: in a question, what the environment is now.
_ENVIRONMENT_SET = ("set_weather", "set_time_of_day", "set_lighting")
# What puts a thing somewhere: in a question, where it is now.
_PLACING = ("place_asset", "move_asset")
# How far from the place a statement names the thing it describes may stand ("a hydrant by the crossroads").
DESCRIBED_NEAR_M = 20.0


def _not_removed_twice(calls: list[ToolCall], scene: Scene) -> list[ToolCall]:
    """`calls` without a removal of what an earlier call already takes away (a request that names
    its things again after a colon or a comma): the ids left to take, or no call when none are."""
    gone: set[str] = set()
    out = []
    for call in calls:
        if call.tool != "remove_assets":
            out.append(call)
            continue
        named = call.args.get("assets")
        if isinstance(named, list):
            left = [i for i in named if i not in gone]
            gone |= set(left)
            if left:
                out.append(call if left == named else ToolCall(tool=call.tool, args={**call.args, "assets": left}))
            continue
        kind = [a.id for a in scene.assets if a.category == call.args.get("category")]
        if kind and set(kind) <= gone:
            continue  # every one of that kind is already going
        if call.args.get("near") is None and int(call.args.get("count") or len(kind)) >= len(kind):
            gone |= set(kind)  # "remove the bench ... remove that bench": the only one goes once
        out.append(call)
    return out


# A clause that only names a thing and where it is: "the tree near the Library." (no modal, no verb).
_BARE_NAMING = re.compile(r"\s*(?:the|that|this)\s+(?!.*\b(?:should|must|needs?|has to|have to|ought|will|would|can|could"
                          r"|be|is|are|was|were|goes|go|belongs?|wants?)\b)")


def _named_in(calls: list[ToolCall]) -> set[str]:
    """The ids `calls` act on or place things by."""
    out: set[str] = set()
    for call in calls:
        where = call.args.get("location")
        out |= {str(i) for i in call.args.get("assets") or []} | {str(call.args.get("asset"))}
        out |= {str(where.get("target"))} if isinstance(where, dict) else set()
    return out


# Words that ask for an edit a second time: "turn it 90 degrees, then another 90".
_AGAIN = re.compile(r"\b(?<!hello )(?<!hi )(?<!me )(?:again|another|twice|once more|more|repeat|second)\b")  # not "hello again"


def _fuller(later: ToolCall, call: ToolCall) -> bool:
    """Whether `later` sets the same thing the same behaviour as `call`, saying more of it."""
    said, more = call.args.get("behaviour"), later.args.get("behaviour")
    return (later.tool == "set_behaviour" and later.args.get("asset") == call.args.get("asset")
            and isinstance(said, dict) and isinstance(more, dict) and said.items() < more.items())


def _not_restated(calls: list[ToolCall], low: str) -> list[ToolCall]:
    """`calls` without an edit the request says again in other words (a restatement: "turn the
    ego around ... turn it all the way around"; "a line of cones across the road in front of the
    ego ... a line of cones across the road"), unless it asks for it again."""
    if _AGAIN.search(low):
        return calls
    adds = [c for c in calls if c.tool == "add_asset"]
    located = {(c.args.get("category"), c.args.get("count", 1)) for c in adds if c.args.get("location")}
    placed = {(c.args.get("category"), str(c.args.get("location"))) for c in adds if c.args.get("location")}
    out: list[ToolCall] = []
    for n, call in enumerate(calls):
        if call.tool == "set_behaviour" and any(_fuller(later, call) for later in calls[n + 1 :]):
            continue  # "pull out and drive off east along Main Street": the one that says the lane
        if call.tool == "add_asset" and not call.args.get("location") and (call.args.get("category"), call.args.get("count", 1)) in located:
            continue  # "I'd like to add a tree. A single tree, next to the fountain": the one placed
        if call.tool == "place_asset" and any(str(call.args.get("location")) == where and str(call.args.get("asset", "")).startswith(f"{kind}_")
                                              for kind, where in placed):
            continue  # "... so just the one tree, next to the fountain": the new one, said again
        if any(call.tool == c.tool and call.args == c.args for c in out):
            continue
        where = call.args.get("location")
        vaguer = call.tool == "arrange_assets" and isinstance(where, dict) and where.get("relation") == "scene_centre"
        if vaguer and any(c.tool == call.tool and c.args.get("categories") == call.args.get("categories")
                          and c.args.get("shape") == call.args.get("shape") for c in out):
            continue  # the same layout said again without its place: the one placed
        out.append(call)
    return out


# Where a thing stood, to the centimetre: a call putting something there waits for its removal.
STOOD_THERE_M = 0.05


def _cleared_first(calls: list[ToolCall], scene: Scene) -> list[ToolCall]:
    """`calls` with each removal moved before an earlier call that puts something where the
    removed thing stands ("could the bench go, and the bin be moved to where the bench was")."""
    out = list(calls)
    for i, call in enumerate(calls):
        where = call.args.get("location")
        if not isinstance(where, dict) or where.get("relation") != "absolute":
            continue
        spot = (float(where.get("x") or 0.0), float(where.get("y") or 0.0))
        for later in calls[i + 1 :]:
            gone = [scene.asset(str(a)) for a in later.args.get("assets") or []] if later.tool == "remove_assets" else []
            if any(a is not None and math.dist((a.pose.x, a.pose.y), spot) < STOOD_THERE_M for a in gone):
                out.remove(later)
                out.insert(out.index(call), later)
    return out


def _named_singly(r: Reading, scene: Scene) -> list[str]:
    """The one thing a statement names in the singular that the scene has one of ("that wheelie bin"
    among "cars" and "kids"), as a list; [] when it names no such one thing."""
    ones = {a.id for m in r.mentions if not m.plural
            for a in [x for x in scene.assets if x.category == m.category] if scene.count(m.category) == 1}
    return sorted(ones) if len(ones) == 1 else []


def _already_there(described: list[ToolCall], scene: Scene) -> list[str]:
    """The things a statement describes as if new ("who put a hydrant by the crossroads", "I ended
    up with two benches at the fountain") that the scene already has at that place: for each
    addition, as many of its kind there as it says, nearest first."""
    found: list[str] = []
    for call in described:
        where = call.args.get("location") or {}
        landmark = scene.landmark(str(where.get("target"))) if call.tool == "add_asset" and isinstance(where, dict) else None
        same = [a for a in scene.assets if a.category == call.args.get("category")]
        count = int(call.args.get("count", 1))
        if landmark is None or not same:
            continue
        # "I ended up with two benches at the fountain": the two there nearest it, when there are that many
        there = sorted((a for a in same if math.dist((a.pose.x, a.pose.y), landmark.position) <= DESCRIBED_NEAR_M),
                       key=lambda a: math.dist((a.pose.x, a.pose.y), landmark.position))
        if len(there) >= count:
            found.extend(a.id for a in there[:count])
    return found


# A place said by a word several places' names end in ("by the gate", "outside the building").
# A new vehicle said to keep the ego's pace: "same speed", "at our speed", "keeping pace with us".
_SAME_PACE = re.compile(r"\b(?:(?:the )?same speed|same pace|at (?:our|its|the ego'?s) (?:speed|pace)|keeping pace|keeps pace)\b")
# A request that only says what not to do: "don't move the SUV", "please do not paint the bench".
_ONLY_FORBIDS = re.compile(r"^\s*(?:please\s+)?(?:don'?t|do not|never|no need to)\s+(?:move|touch|paint|remove|delete|add|put|change|turn|"
                           r"rotate|park|drive|shift|place|recolou?r)\b[^,;.!?]*[.!]?\s*$", re.IGNORECASE)
_THE_KIND = re.compile(r"(?:\b(?:by|near|next to|beside|at|outside|in front of|behind|opposite|to|around|from)\s+|^\s*)"
                       r"(?P<said>the\s+(?:[a-z]+\s+)?(?P<kind>[a-z]+))\b")  # ("the crossing needs someone waiting": the subject)


# How far a shade goes: towards black for darker, towards white for lighter.
_SHADES = {"darker": 0.6, "deeper": 0.7, "lighter": -0.4, "paler": -0.4, "brighter": -0.3}


def _shade_of_last_paint(r: Reading, scene: Scene, memory: Memory) -> list[ToolCall] | None:
    """The things the last turn painted, each its colour made darker or lighter as the words say;
    None unless the words say only a shade and the last turn painted something."""
    said = md.SHADE_ALONE.match(r.low.strip())
    last = memory.live_turns()[-1:]
    if said is None or not last or not any(c.startswith("set_asset_appearance") for c in last[0].calls):
        return None
    factor = _SHADES[said.group(1)]
    calls: dict[str, list[str]] = {}
    for i in last[0].touched:
        asset = scene.asset(i)
        if asset is None or asset.appearance.rgba is None:
            continue
        rgb = [float(c) * factor if factor > 0 else float(c) + (1.0 - float(c)) * -factor for c in asset.appearance.rgba[:3]]
        calls.setdefault(hex_colour((*rgb, 1.0)), []).append(i)
    return [ToolCall(tool="set_asset_appearance", args={"assets": ids, "colour": colour}) for colour, ids in calls.items()] or None


def _kind_of_place_left_out(text: str, calls: list[ToolCall], scene: Scene) -> tuple[str, list[str]] | None:
    """The kind of place the words name that several places are ("stop at the gate", "at the
    crossing"), and those places, when the plan goes to none of them: the place was dropped,
    never to be guessed; None otherwise."""
    low = text.lower()
    for start, end, kind, places in _kinds_of_place(low, scene):
        if len(places) >= 2 and scene.landmark(low[start + 4 : end]) is None and not _goes_to(calls, places):
            return kind, places
    return None


def _kinds_of_place(low: str, scene: Scene) -> Iterator[tuple[int, int, str, list[str]]]:
    """Each "the <kind>" after a relation that names a kind of place, as (start, end, kind, the
    places of that kind): the last word when it is one ("by the red gate"), else the word before
    it ("closest to the gate red")."""
    for said in _THE_KIND.finditer(low):
        words = list(re.finditer(r"[a-z]{3,}", low[said.start("said") : said.end("said")]))[1:]  # ("the kerb a little": no lot A)
        for word in reversed(words):
            places = places_called(scene, word.group(0))
            if places:
                yield said.start("said"), said.start("said") + word.end(), word.group(0), places
                break


def _goes_to(calls: list[ToolCall], places: list[str]) -> bool:
    said_in_calls = " ".join(str(c.args) for c in calls).lower()
    return any(p.lower() in said_in_calls for p in places)


def _unknown_words(clause: str, scene: Scene) -> list[str]:
    vocab = vocabulary(scene)
    ids = {a.id for a in scene.all_assets()}
    content = [w for w in ph.tokens(clause) if len(w) > 2 and not w.replace(".", "").isdigit()]
    return [w for w in content if w not in ids and not is_known(w.strip("'-."), vocab)]


def _more_of_a_thing(r: Reading) -> bool:
    """Whether "more" asks for more things ("more cones", "two more there"), not more of a quality
    ("more realistic")."""
    for said in re.finditer(r"\bmore\b", r.low):
        if re.search(r"\b(?:out|up|down|off|over|away|apart|back|it|them|that|this)\s+$", r.low[: said.start()]):
            continue  # "make it stand out more", "spread them more": more of how, not of what
        after = r.low[said.end() :]
        if not after.strip() or re.match(r"\s+(?:of|there|here|please|too|like|next|by|near|beside|around"
                                         r"|along|across|exactly like|just like|behind|ahead|in front|outside|\d)\b", after):
            return True
        if any(0 <= m.start - said.end() <= 2 for m in r.mentions):
            return True
    return False


def _changes_them(r: Reading) -> bool:
    """Whether the words say how to change things ("cones blue", "trees at the quad, 5 m west")."""
    return (ph.find_distance(r.text) is not None or md.compass_direction(r.masked) is not None
            or any(r.has((c,)) for c in COLOURS) or md.material_said(r.masked) is not None)


# What "give me ..." asks for when it asks for information.
_INFO_NOUNS = ("list|number|count|tally|inventory|names?|positions?|locations?|coordinates|overview|summary|rundown|info|information|details|ids?"
               "|distances?|gaps?|speeds?|headings?|sizes?|dimensions|weights?|mass|whereabouts")


def _is_question(r: Reading, asked: bool) -> bool:
    words = r.low.strip().removeprefix("so ").removeprefix("ok ").removeprefix("now ").strip()
    starts = any(re.match(rf"{re.escape(w)}\b", words) for w in lx.SEARCH_STARTS)
    # "Could you put a shuttle at the stop?" is a command put politely, question mark or not.
    command = re.sub(r"^(?:(?:please|pls|kindly|can|could|would|will|maybe|perhaps)\s+(?:you\s+)?(?:please\s+)?)+", "", words)
    if re.match(r"(add|put|place|create|remove|delete|move|make|set|turn|paint|spawn)\b", command) or wrapped_request(words) \
            or setting_shown(words):  # "show me the street at eleven at night": set so, to be seen
        return False
    if re.match(rf"give (?:me|us)\b(?!\s+(?:a |an |the )?(?:[a-z]+ )?(?:{_INFO_NOUNS})\b)", command):  # "a rough count"
        return False  # "give me some rain" asks for rain; "give me a list of ..." for information
    within = re.search(r"(\s,\s*(where|which|what)|how many|how much)\b", r.low)
    # "I need the number of trees", "tell me which cars ...": the check's reading of a question
    return starts or (asked and asks(words + " ?")) or bool(within) or asks(words)


# A clause that only names things already there ("the cars...", "that bench,"): the topic of the next.
# It may say which ones by where they are: "the tree which is near the fountain, ...".
_TOPIC = re.compile(r"\s*(?:(?:the|those|these|that|this|our|my|all|both|of|and)\s+)*(?:§\s*)+"
                    r"(?:(?:which|that|who)(?:'s|\s+is|\s+are|\s+stands?|\s+sits?)?\s+(?:near|by|next to|at|in|on|beside|"
                    r"close to|behind|in front of)\s+(?:the\s+)?(?:§\s*)+)?[.,!\s]*")


def _without_mentions(r: Reading) -> str:
    out = r.masked  # the places blanked too, the same length as r.low
    for m in r.mentions:
        out = out[: m.start] + "§" * (m.end - m.start) + out[m.end :]
    return out


# A livelier look asked for with no colour said: "a bit more colourful", "make it pop".
_BRIGHTER_LOOK = re.compile(r"\b(?:more |less drab|less dull)?(?:colou?rful|vibrant|vivid|eye-catching|cheerful|jazzier|snazzier|flashier|flashy)\b"
                            r"|\bmake (?:it|them|the [a-z ]+?) pop\b|\b(?:a |some )?(?:different|another|new|other) colou?r\b")


# What may follow the switch word of "lamps off": the end, or words that say nothing of where.
_SWITCH_ENDS = r"(?=\s*(?:$|[,.!;?]|\b(?:please|pls|plz|now|thanks|all|again|too|and|for|so|at|when|during|while|then|tonight)\b))"


def _plan_clause(r: Reading, asked: bool, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall] | None:
    if (bare := BARE_STATE.search(r.masked)) is not None:  # "lot A looks empty": how it is, not "empty it"
        r = replace(r, masked=r.masked[: bare.start()] + " " * (bare.end() - bare.start()) + r.masked[bare.end() :])
    if r.has(lx.PROMPT_INJECTION) and not (r.mentions or r.ego or r.ids):
        raise PlanningError(
            f"{r.text!r} is not a scene edit; the world's rules always apply and cannot be switched off"
        )
    if re.match(rf"\s*({'|'.join(lx.FILLER_STARTS)})\b", r.low) and not r.mentions and not r.ids:
        return None  # "before I add anything": a circumstance, not a request
    if _REPAINT.search(r.low) and (r.landmark or _BUILDING.search(r.masked)) and not (r.mentions or r.ids or r.ego):
        raise PlanningError(f"the buildings and places of this world keep their look; I can restyle the things in it "
                            f"(colour or material), e.g. 'paint the bench by {r.landmark or 'the bus stop'} yellow'")
    if WHAT_IF.search(r.low):
        return None  # "I want to see what happens if a child runs out": what the test is for, not yet a request
    if repeats(r, memory):  # "repeat that outside Engineering Hall", "ditto for the bus", "and the bin too"
        return repeat(r, scene, memory, notes)
    if corrects(r):  # "actually, make that five": the last edit's things, as many as that
        return correct(r, scene, memory)
    meant_instead(r)  # "oops, I meant bins": never a new request for bins
    if _is_question(r, asked):
        looked_up = plan_question(r, scene, memory, notes)
        if [(c.tool, c.args) for c in looked_up] == [("find_assets", {})] and not (r.mentions or r.ids or r.ego or r.landmark):
            # "Bit of drizzle?": a question about nothing in the scene that names a setting asks for it
            return environment(r, scene.environment) or looked_up
        return looked_up
    if (swap := replaces(r)) is not None:  # "swap the bench for a bin": it goes, a bin stands there
        return replace_things(swap, scene, memory, notes)
    if (traded := trades_places(r, scene, memory, notes)) is not None:  # "swap the bench and the bin": each where the other stood
        return traded
    paced = new_pace(r, scene, notes, memory)
    if paced is not None:  # "set the ego's speed to 8 m/s", "could the truck go a bit slower?"
        return paced
    following = _follow(r, scene, memory, notes)
    if following is not None:  # "let the parked car follow the ego": behind it in its lane, at its pace
        return following
    if r.mentions and _TOPIC.fullmatch(_without_mentions(r)):
        referenced(r, scene, memory, notes)  # "the cars... where are they?": what the next clause is about
        return []
    final = _to_count(r, scene, memory, notes)
    if final is not None:  # "there should be exactly four cones in lot A": as many as that, no more
        return final
    # The removal words the plan check reads polarity by ("take it out", "without the bin") count too.
    less_of = next((m for m in r.mentions if _LESS_OF_A_KIND.match(r.low[m.end :])), None)  # "make the SUV less flashy"
    how_it_is = less_of is not None
    if less_of is not None and not md.colours_asked(r.low):  # "less flashy", "less red" (a colour not wanted is none asked)
        # what it should be less of is said, and not what it should be: never a guess (nor fewer of them)
        thing = less_of.category.replace("_", " ")
        raise PlanningError(f"I can tell how the {thing} should not be, not how it should; say a colour or finish, "
                            f"e.g. 'paint the {thing} grey' or 'give the {thing} a matte finish'")
    taken_away = bool(REMOVE_WORDS.search(r.low.strip())) and not how_it_is
    fewer = bool(FEWER_WORDS.search(r.low)) and not how_it_is
    filled = _FILL_WITH.search(r.low) is not None  # "fill the empty half of lot B with cars" adds
    # "tidy the benches up into a row": a layout to tidy them into, not a tidying away
    tidied = re.search(r"\b(?:tidy|tidied|clean|cleaned|neaten)\b", r.low) is not None and md.layout_said(r.masked) is not None
    if (r.has(lx.REMOVE_WORDS) or r.has(lx.GONE_WORDS) or fewer or _NEGATED_WISH.search(r.low) or taken_away) and not (filled or tidied):
        removed = remove(r, scene, memory, notes)
        if removed is not None:
            return removed
    # "turn the lamps on", and a state wished for: "the street lights must be on", "lamps should be lit";
    # "put the lamps on the sidewalk" says where, and "lamps off, please" still switches
    switch = re.search(rf"\b(turn|switch|flick)\s+(on|off)\b|\b(turn|switch|put|flick|make)\b.*\b(on|off)\b{_SWITCH_ENDS}"
                       r"|\b(be|stay|kept|left)\s+(?:\w+\s+)?(on|off|lit|working)\b"
                       rf"|\b(switched|turned|flicked)\s+(on|off)\b{_SWITCH_ENDS}"  # "have the street lamps switched on"
                       rf"|\b((?:street\s?|vehicle\s|car\s|head)?lights?|(?:street\s?)?lamps?)\s+(on|off)\b{_SWITCH_ENDS}", r.low)
    switch = switch or LIGHTS_DOWN.search(r.low) or LAMPS_SWITCHED_AS_SAID.search(r.low)  # "the street lamps are out": off
    # "a car pulling in, with its headlights on": the car is what is asked for, its lights a detail
    adds_a_thing = any(m.category != "street_light" and not m.plural and re.search(r"\b(?:a|an|one)\s+(?:\w+\s+)?$", r.low[: m.start])
                       for m in r.mentions)
    if switch and not adds_a_thing and not re.search(r"\d\s*(deg|°)", r.low):  # "turn the lamps on" does not rotate a lamp
        if lights(r) is not None:
            return environment(r, scene.environment)
        if any(m.category == "street_light" for m in r.mentions):
            return [ToolCall(tool="set_lighting", args={"street_lights": "off" if "off" in switch.groups() else "on"})]
    shaded = _shade_of_last_paint(r, scene, memory) if not (r.mentions or r.ids or r.ego) else None
    if shaded:  # "paint the bench yellow" then "nah, darker": that colour darker, not the night
        return shaded
    if not (r.mentions or r.ids or r.ego) and notes.subject and any(r.has((c,)) for c in COLOURS):
        colour = recolour(r, scene, memory, notes)  # "...; bright yellow would do": a look for the thing just named
        if colour is not None:
            return colour
    if (not r.mentions and not r.ids and not r.ego) or r.has(("weather", "time of day")):
        env = environment(r, scene.environment)
        if env:
            return env
    gone = taken_away or fewer or r.has(lx.REMOVE_WORDS) or r.has(lx.GONE_WORDS)
    if not (r.mentions or r.ids or r.ego or gone) and r.has(lx.WORKS_WORDS):
        return _work_zone(r, scene, memory, notes)  # "set up roadworks by the east gate", "make it look like a building site"
    roads = "|".join(re.escape(ph.normalise(n).strip()) for n in {lane.road for lane in scene.roads.lanes if lane.road})
    across = _ACROSS_ROAD.search(r.low) or (roads and re.search(rf"\b(?:across|spanning) (?:the )?(?:whole )?(?:{roads})\b", r.low))
    closure = across and r.mentions and all(_closes_roads(m.category) for m in r.mentions)  # "3 barriers across Campus Drive"
    closure = closure or (_SEALED_OFF.search(r.low) is not None and _way_through(r, scene))
    if (r.has(lx.BLOCK_WORDS) or _CLOSE_ROAD.search(r.low) or closure) and not r.ids:
        return [_block(r, scene, memory, notes)]
    instrument = _WITH_LAYOUT.search(r.low) or _LAYOUT_VERB_WITH.search(r.low)
    if instrument is not None and any(m.start > instrument.start() for m in r.mentions):
        # "stop cars driving in through the gate with a row of bollards": the row is what to build
        if instrument.re is _LAYOUT_VERB_WITH:  # "ring the hydrant with cones", "cordon off the bench with cones":
            laid = [m for m in r.mentions if m.start > instrument.end()]  # cones, not the barriers "cordon off" names
            verb = re.match(r"\s*(?:please )?[\w-]+", r.low)
            ringed = [m for m in r.mentions if verb is not None and verb.end() <= m.start < instrument.end()]  # the hydrant, the bench
        else:
            laid = [m for m in r.mentions if m.start > instrument.start()]
            around = _AROUND.search(r.low[: instrument.start()])
            # "cordon the tree by the library off using a row of bollards": what is ringed stays named
            ringed = [m for m in r.mentions if around is not None and around.start() < m.start < instrument.start()]
        return _both_sides(_arrange(replace(r, mentions=[*laid, *ringed]), scene, memory, notes), r, scene)
    if _SPREAD_OUT.search(r.low) and md.layout_said(r.masked) is None and not r.has(lx.ADD_WORDS):
        # "spread the cones out a bit more", "space them further apart": those there, never more of them
        spread = [a for i in referenced(r, scene, memory, notes) if (a := scene.asset(i)) is not None and a.id != "ego"]
        if len(spread) >= 2:
            return _spread_out(spread)
    # "the new fire hydrant" is the one just added, not one more; "I want the bench painted" wants it changed
    first = r.mentions[0] if r.mentions else None
    definite = first is not None and scene.count(first.category) > 0 and bool(_DEFINITE.search(r.low[: first.start]))
    said_add = tuple(w for w in _STRICT_ADD if w != "more" and not (definite and w in _WISHES))
    strict_add = ph.has_any(_THE_NEW.sub(" ", r.masked), said_add) or _more_of_a_thing(r) or filled
    mention = r.mentions[0] if r.mentions else None
    added = _ADDED_BEFORE_PLACE.search(r.low)
    if (added is not None and mention is not None and mention.start >= added.end() and added.group(1) not in _NO_NEW_NOUN
            and added.group(1) not in lx.GRAMMAR):
        noun = added.group(1)  # "add a waiter next to the SUV": no waiter, and never a second SUV
        raise PlanningError(f"unknown asset {noun!r}; nearest: {', '.join(nearest_categories(noun))}")
    # "there's no bin outside the JTEKT building": one wanted there, never the one elsewhere moved
    strict_add = strict_add or (mention is not None and NONE_THERE.search(r.low[: mention.start]) is not None
                                and not any(commands(part) for part in re.split(r"[,.;!]+|\band\b|\bso\b", r.low)))
    # ("there is no bench in lot B, move the bench there": that one)
    # A bare plural ("benches in lot A") asks for new ones where fewer than two are there.
    present = mention is not None and scene.count(mention.category) >= (2 if mention.plural else 1)
    fresh = mention is not None and is_new(r, mention, strict_add, present)
    if (mention is not None and mention.plural and not fresh and not _VERB_AT.search(r.low)
            and not ph.tokens(r.low[: mention.start]) and r.landmark and not _changes_them(r)):
        fresh = True  # "trees along one side of lot A": a bare plural and no verb asks for some
    recent = [i for i in memory.last_added() if scene.asset(i) is not None]
    if mention is None and recent and (_more_of_a_thing(r) or r.has(("another",)) or _ONE_MORE_DESCRIBED.search(r.low)):
        # "put two more there", "one more like that, but blue": more of what the last turn added
        last = scene.asset(recent[-1])
        assert last is not None
        said = re.search(r"\b(?:more|another)\b", r.low)
        at = said.end() if said is not None else len(r.low)
        amount = re.match(r"\s+(?:\d+|[a-z]+)(?=\s+of\b|\s+(?:those|them|these)\b)", r.low[at:])  # "another pair of those"
        # "another": one; "another pair of those": more; "another one of those": one
        described = _ONE_MORE_DESCRIBED.search(r.low) if said is None else None  # "a blue one next to it": one
        plural = (said is None and described is None) or (said is not None and said.group(0) == "more") or (
            amount is not None and amount.group(0).strip() not in ("1", "one"))
        at += amount.end() if amount is not None else 0
        counted = re.search(r"\b(\d+|[a-z]+)\s+$", r.low[: said.start()]) if said is not None else None
        if said is not None and counted is not None and (counted.group(1).isdigit() or counted.group(1) in ph.NUMBER_WORDS):
            at = said.start()  # the amount is said before "more": "2 more next to them"
            plural = counted.group(1) not in ("1", "one")
        named = ph.Mention(last.category, at, at, plural=plural)
        return _add(replace(r, mentions=[named]), scene, memory, notes)
    moved_only = r.has(lx.SHIFT_VERBS) and not r.has(("paint", "repaint", "colour", "color", "recolour", "make", "turn", "look"))
    if not fresh and not r.has(("add", "create", "spawn", "place a", "put a")) and not moved_only:  # "move that wooden seat": which seat
        colour = recolour(r, scene, memory, notes)
        if colour is not None:
            return colour
    if mention is None and QUIETER.search(r.low):
        return _quieter(r, scene, memory, notes)  # "make it a bit quieter out there": fewer of what moves, never a move
    if mention is not None and not strict_add and (lined := _laid_out_there(r, mention, scene, memory, notes)) is not None:
        return lined  # "line up the cars in lot B", "move the trees into a circle round the fountain": those there
    if not fresh:
        existing = edit_existing(r, scene, memory, notes)
        if existing is not None:
            return existing
    if mention is not None and _BRIGHTER_LOOK.search(r.low) and present and not strict_add and not r.has(lx.ADD_WORDS):
        fresh = False  # "bench little more colourful": the bench there, a look not said
    if (r.has(("paint", "repaint", "recolour", "recolor")) or _BRIGHTER_LOOK.search(r.low)) and not fresh:
        # a thing to paint is one that is there; a colour not understood is asked, never an add
        raise PlanningError(f"which colour? I know {', '.join(COLOURS)}")
    if mention is None and LIVELIER.search(r.low):
        return _livelier(r, scene, memory, notes)
    if mention is None:
        if r.has(lx.GENERIC_THINGS):
            return environment(r, scene.environment) or None  # "we want to put something there": an intention
        if r.has(("add", "create", "spawn", "place", "put", "insert")) and not r.has(("it", "them", "there")):
            verbs = ("add", "create", "spawn", "place", "put", "insert", "one", "new", "another")
            noun = next((w for w in reversed(ph.tokens(r.masked)) if w.isalpha() and w not in lx.GRAMMAR and w not in verbs), None)
            if noun is None and r.landmark and not re.search(r"\bones?\b", r.low):  # "add a pedestrian crossing at the north crosswalk": a place the map has
                raise PlanningError(f"'{r.landmark}' is a place on the map, not a thing I can add; I can put things at it, "
                                    f"e.g. 'add a bench at the {r.landmark}'")
            if noun is None:  # "add a new one at the gate", with nothing said before
                raise PlanningError("say what to add, e.g. 'add a bench at the fountain'")
            raise PlanningError(f"unknown asset {noun!r}; nearest: {', '.join(nearest_categories(noun))}")
        env = environment(r, scene.environment)
        return env or None
    # (a verb of it in any form: "it must be cordoned off", "ringed with cones")
    arranged = r.has(tuple(w for w in lx.ARRANGE_WORDS if w != "around")) or (r.has(("around",)) and not _AROUND_LOOSE.search(r.low)) \
        or inflected(_LAYOUT_VERBS).search(r.masked) is not None
    laid_out = (arranged or md.layout_said(r.masked) is not None  # "line up 4 bins"
                or _AROUND_BY.search(r.low) is not None  # "the fountain should be ringed by six benches"
                or _ROUND_IT.search(r.low) is not None
                or (mention.plural and (r.has(("along",)) or _LINING.search(r.low) is not None))  # "trees along one side of lot A"
                or ((mention.plural or (find_count(r, mention) or 1) > 1 or r.has(("every",)))
                    and nb.spacing_said(r.low) is not None))  # "four cones 8 m apart", "a cone every 5 m": a line
    moving = behaviour_kind(r, catalog()[mention.category]) not in (None, "parked")  # a row may be parked
    if (laid_out and not moving) or r.has(("to mark",)):
        row = _arrange(r, scene, memory, notes)
        # "six cones in a row and a sign next to them": the row, then the sign beside it (a ring's centre stays)
        once = [c for c in _said_once(r, scene) if c in row.args["categories"]] if row.args["shape"] != "ring" else []
        row = _arrange(replace(r, mentions=[m for m in r.mentions if m.category not in once]), scene, memory, notes) if once else row
        beside = [ToolCall(tool="add_asset", args={"category": c, "count": 1, "location": row.args["location"]}) for c in once]
        return [*_both_sides(row, r, scene), *beside]
    if _unknown_verb(r, scene) is not None and not strict_add and not r.has(lx.ADD_WORDS) and scene.count(mention.category):
        return None  # "quita el fire hydrant", "strip all the vegetation out": a verb not known is never "add"
    return _add(r, scene, memory, notes)


# Verbs of laying things out round or along something, read in any of their forms.
_LAYOUT_VERBS = ("cordon", "surround", "encircle", "ring", "fence", "enclose", "rope off", "tape off")
# Words of something to be done over time that, left unread in a request, leave part of it undone.
_DROPPED_ACTION = re.compile(r"(?<!\bto )\b(?:follow\w*|overtak\w*|brak(?:e|es|ed|ing)|revers\w*|cut(?:s|ting)? in|chang\w* lanes?|"
                             r"slow\w* down|speed\w* up|accelerat\w*|yield\w*|tailgat\w*|swerv\w*)\b")
# Where or which way, said in a command: what a statement beside it cannot stand in for ("the bench
# is too near the road. Put it more far from it"), unlike a command that points back at the statement
# ("a van always waits there. Give me one of those").
_SAYS_WHERE = re.compile(r"\b(?:far|farther|further|away|closer|nearer|near|behind|front|ahead|left|right|north|south|east"
                         r"|west|road|street|lane|pavement|sidewalk|side|back|forward|over)\b")
# What is offered for a place said to be bare: people, greenery, somewhere to sit.
_FILLERS_OFFERED = ("a few pedestrians", "two trees", "a bench")


# Words that may open a command before its verb ("ok so now just ...").
_OPENERS = frozenset({"ok", "okay", "so", "now", "then", "and", "please", "pls", "plz", "just", "right", "well", "oh", "hey", "hi",
                      "hmm", "um", "uh", "erm", "oops", "yeah", "yep"})


def _unknown_verb(r: Reading, scene: Scene) -> str | None:
    """A word before the first thing named that the rule lexicon does not know, when that thing
    is said as one already there ("quita el fire hydrant", "strip all the vegetation"): where
    its verb would be; None otherwise."""
    vocab = vocabulary(scene)
    end = r.mentions[0].start if r.mentions else len(r.low)
    words = [w for w in re.findall(r"[a-z\u00c0-\u024f'-]+|\d+", r.low[:end]) if w not in _OPENERS]
    if not words or not re.search(r"\b(?:the|el|la|los|las|le|les|il|der|die|das|di|da|de|dat|dis|all|every|those|these|that|this|on|about|with|of)\s+(?:[\w-]+\s+){0,2}$",
                                  r.low[:end]):
        return None  # "gimme a cone", "chuck two benches there": a new thing may be what is asked for
    return next((w for w in words if not w.isdigit() and not is_known(w.strip("'-"), vocab)), None)


def _labelled_as(call: ToolCall, name: str) -> ToolCall:
    """An addition of one thing given the person's name for it (more than one are not named)."""
    if int(call.args.get("count") or 1) != 1:
        return call
    return ToolCall(tool=call.tool, args={**call.args, "label": name})


def _said_once(r: Reading, scene: Scene) -> list[str]:
    """Categories a clause names one of ("a sign") beside another it names several of ("six cones"):
    those stand beside the layout, not in it."""
    counts = {m.category: find_count(r, m) or (3 if m.plural else 1) for m in r.mentions}
    if len(counts) < 2 or max(counts.values()) < 2:
        return []
    there = {m.category for m in r.mentions if not is_new(r, m, False, scene.count(m.category) > 0)}  # "from the bench"
    return [c for c, n in counts.items() if n == 1 and c not in there and not any(m.plural for m in r.mentions if m.category == c)]


# Filling a place with things: an addition, whatever the place is called ("the empty half").
_FILL_WITH = re.compile(r"\bfill(?:s|ing)?\s+(?:up\s+)?(?!.*\b(?:remove|delete|clear|take)\b).*\bwith\b")


# So many times the things there: "double the number of benches", "twice as many trees in lot A".
_TIMES_AS_MANY = re.compile(r"\b(double|triple|twice|three times)(?: as many| the (?:number|count|amount) of| the)?\b(?![-\w])(?! (?:it|them|that|this)\b)")
_TIMES = {"double": 2, "twice": 2, "triple": 3, "three times": 3}


def _to_count(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall] | None:
    """The additions or removals that leave the count said of a thing at its place; None where the
    words say no final count or nothing of the kind is there to count against (a plain addition)."""
    said = FINAL_COUNT.search(r.low) or _TIMES_AS_MANY.search(r.low)
    mention = next((m for m in r.mentions if said is not None and m.start >= said.end()), None)
    there = kept_at(scene, mention.category, r.landmark) if mention is not None else []
    times = _TIMES.get(said.group(1) or "", 0) if said is not None and said.re is _TIMES_AS_MANY else 0
    wanted = times * len(there) if times else find_count(r, mention) if mention is not None else None
    if mention is not None and times and not there:
        raise PlanningError(f"there is no {mention.category.replace('_', ' ')} {'there ' if r.landmark else ''}to multiply; say how many to add")
    if mention is None or wanted is None or not there:
        return None
    if wanted == len(there):
        raise PlanningError(f"there are already {wanted} {mention.category} there; nothing to change")
    if wanted < len(there):
        return [ToolCall(tool="remove_assets", args={"assets": there[wanted:]})]
    return _add(replace(r, mentions=[mention]), scene, memory, notes, count=wanted - len(there))


def _livelier(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall]:
    """Traffic that drives where a road is named, people on foot elsewhere (three of them)."""
    road = bool(r.lane) or r.has(("street", "road", "lane", "traffic", "carriageway"))
    category = "passenger_car" if road else "pedestrian"
    notes.guess(f"what makes it busier ({category})")
    named = ph.Mention(category, len(r.low), len(r.low), plural=True)
    calls = _add(replace(r, mentions=[named]), scene, memory, notes)
    if not road:
        return calls
    return [ToolCall(tool="add_asset", args={**calls[0].args, "behaviour": behaviour_spec("drive_lane", r)})]


def _quieter(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall]:
    """About half of what moves about (the vehicles driving, else the people on foot), the
    newest first: what makes a place busy, taken away."""
    recent = memory.last_added()
    for motion in ("vehicle", "walker"):
        movers = [a.id for a in scene.assets if catalog()[a.category].motion == motion and a.behaviour.kind != "parked"]
        if motion == "walker":
            movers = [a.id for a in scene.assets if a.category == "pedestrian"]
        if movers:
            movers.sort(key=lambda i: (i not in recent, -recent.index(i) if i in recent else 0))
            notes.guess(f"what makes it quieter ({motion}s)")
            return [ToolCall(tool="remove_assets", args={"assets": movers[: max(1, len(movers) // 2)]})]
    raise PlanningError("nothing here is moving about to make it quieter; say what to take away, e.g. 'remove the bus'")


def _maintenance_target(scene: Scene, memory: Memory) -> str | None:
    """The obstacle a "mark the maintenance" request most likely means: the newest one."""
    tagged = [
        a
        for a in scene.assets
        if "maintenance" in catalog()[a.category].tags and "obstacle" in catalog()[a.category].tags
    ]
    if not tagged:
        return None
    focus = memory.last_focus()
    if focus is not None:
        tagged.sort(key=lambda a: math.hypot(a.pose.x - focus[0], a.pose.y - focus[1]))
        return tagged[0].id
    return tagged[-1].id


# A thing that stands on sidewalks goes on the one by a place when it is at most this far off.
SIDEWALK_REACH_M = 12.0


def _sidewalk_gap(scene: Scene, point: tuple[float, float]) -> float:
    """How far the nearest sidewalk is from a point (infinite in a world without sidewalks)."""
    return min((nearest_on_polyline(point[0], point[1], w.polyline).distance for w in scene.roads.sidewalks),
               default=math.inf)


def _fallback_place(memory: Memory) -> dict[str, Any]:
    focus = memory.last_focus()
    return (
        {"relation": "absolute", "x": round(focus[0], 2), "y": round(focus[1], 2)}
        if focus
        else {"relation": "scene_centre"}
    )


# A cordon of no kind said, round a thing or place off the road, is of bollards: barriers stand on roads.
_GROUND_CORDON = "bollard"
_BARRIERS_SAID = re.compile(r"\b(?:barriers?|barricades?|jersey)\b")


def _stands_off_road(scene: Scene, where: dict[str, Any] | None) -> bool:
    """Whether the thing or place a layout goes round stands where barriers may not (grass, ground)."""
    try:
        target = resolve_target(scene, str((where or {}).get("target") or ""))
    except ToolError:
        return False
    return surface_at(scene, target.x, target.y) not in DRIVABLE


def _beside_last(scene: Scene, memory: Memory) -> dict[str, Any] | None:
    """Beside the last thing added and still there: where "more cones" go (the Worker spreads them)."""
    recent = [i for i in memory.last_added() if scene.asset(i) is not None]
    return {"relation": "next_to", "target": recent[-1]} if recent else None


def _block(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> ToolCall:
    """A line of barriers (or the named things) across the road, or the lot's driveway, at the
    place named: every lane of the road there ("close Main Street east of the crossroads")."""
    # What is kept out ("closed to traffic") is not what the line is made of.
    layout = [m for m in r.mentions if _closes_roads(m.category)]
    made_of = [m for m in layout if re.search(r"\bwith (?:\w+ ){0,4}$", r.low[: m.start])]  # "with a row of those cones"
    layout = made_of or layout  # "cordon off the gate with cones": cones, not the barriers "cordon off" names
    kinds = [m.category for m in layout] or ["road_barrier"]
    where = location(r, scene, memory, notes, compass=False) or _fallback_place(memory)
    args: dict[str, Any] = {"categories": kinds[:4], "shape": "line", "location": where}
    count = find_count(r, layout[0]) if layout else None
    across = cross_section(r, scene, where) if where.get("relation") not in ("absolute", "in_front_of", "behind") else None
    if across is not None:
        spacing = CLOSURE_SPACING_M.get(kinds[0], CLOSURE_SPACING_DEFAULT_M)
        length = catalog()[kinds[0]].length
        # Unless told, one every `spacing` metres, at least three where three fit (a line), two at least.
        fit = int((across.width + CLOSURE_GAP_M) // (length + CLOSURE_GAP_M))
        count = count or max(2, min(fit, max(3, round(across.width / spacing))))
        args["location"] = {"relation": "absolute", "x": across.x, "y": across.y}
        args["heading_deg"] = across.heading_deg
        # Every lane covered, none overhung, and neighbours never overlapping (two barriers in one lane).
        args["spacing"] = round(max(min(across.width / count, spacing), length + CLOSURE_GAP_M), 2)
    if count:
        args["count"] = count
    return ToolCall(tool="arrange_assets", args=args)


# A road said by its kind, not its name ("the road", "the lane ahead"): a way through.
_ROAD_SAID = re.compile(r"\b(?:road|street|lane|carriageway)\b")
# Closing a way through off: "fence off the lot A entrance", "seal off the east gate with cones".
_SEALED_OFF = re.compile(r"\b(?:fenc|cordon|seal|rop|barricad)(?:e|es|ed|ing)?\s+(?:[\w-]+\s+){0,4}?off\b")


def _way_through(r: Reading, scene: Scene) -> bool:
    """Whether the place named is a way through that a line closes (a road, a lane, a gate or a
    lot's entrance), not a thing or a place that a fence rings (a tree, the fountain, a lot)."""
    if r.ids or any(not _closes_roads(m.category) for m in r.mentions):
        return False
    if r.landmark is None:  # "cone off the road ahead": the road, wherever it was said to be
        return r.lane is not None or _ROAD_SAID.search(r.masked) is not None
    place = scene.landmark(r.landmark)
    lots = [lm.name for lm in scene.landmarks if lm.kind == "area"]
    return place is not None and (place.name.endswith(" gate") or any(place.name == f"{lot} entrance" for lot in lots))


# A vehicle told to follow another: "let the parked car follow the ego", "the SUV should tail passenger_car_1".
_FOLLOWS = re.compile(r"\b(?:follows?|following|tails?|tailing|trails?|trailing|shadows?|shadowing)\s+(?:behind\s+)?(?:the\s+)?")
# How far behind the vehicle it follows a follower starts, metres.
FOLLOW_GAP_M = 12.0


def _follow(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall] | None:
    """A vehicle put behind the one it is to follow, driving that one's lane at its speed; None when
    the clause asks no one vehicle to follow another."""
    said = _FOLLOWS.search(r.low)
    if said is None:
        return None
    after = r.low[said.end() :]
    lead = "ego" if re.match(r"(?:ego\b|us\b|me\b)", after) or ph.has_any(f" {after[:20]} ", ph.EGO_WORDS) else None
    lead = lead or next((i for i in r.ids if re.match(re.escape(i).replace("_", "[_ ]"), after)), None)
    if lead is None:
        later = [m for m in r.mentions if m.start >= said.end()]
        kind = [a for a in scene.assets if later and a.category == later[0].category]
        lead = kind[0].id if len(kind) == 1 else None
    before = replace(r, mentions=[m for m in r.mentions if m.start < said.start()], ids=[i for i in r.ids if i != lead],
                     ego=r.ego and lead != "ego")
    followers = [i for i in referenced(before, scene, memory, notes) if i != lead]
    leader = scene.asset(lead) if lead else None
    follower = scene.asset(followers[0]) if len(followers) == 1 else None
    if leader is None or follower is None or not catalog()[follower.category].drives:
        return None
    if not isinstance(leader.behaviour, DriveLane):
        raise PlanningError(f"{leader.id} is {leader.behaviour.kind.replace('_', ' ')}, so there is no way to follow it; "
                            f"make it drive a lane first, or put {follower.id} behind it")
    behaviour = {"kind": "drive_lane", "lane": leader.behaviour.lane, "speed": leader.behaviour.speed}
    return [ToolCall(tool="place_asset", args={"asset": follower.id, "location": {"relation": "behind", "target": leader.id,
                                                                                 "distance": FOLLOW_GAP_M}}),
            ToolCall(tool="set_behaviour", args={"asset": follower.id, "behaviour": behaviour})]


# What roadworks said with no things named are made of: a line of cones, and a sign beside them.
WORK_ZONE_CONES = 5
# Metres east of a line of cones said by coordinates that its sign stands (beside, not on, the middle cone).
WORK_ZONE_SIGN_M = 3.0


def _work_zone(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall]:
    """Roadworks asked for by name alone, at the place said: a line of cones marked as
    maintenance and a construction sign next to it; asked where when no place is said."""
    where = location(r, scene, memory, notes) or (dict(notes.place) if notes.place else None)
    if where is None:
        raise PlanningError("where should the roadworks go? name a place, e.g. 'roadworks by the east gate'")
    cones = ToolCall(tool="arrange_assets", args={"categories": ["traffic_cone"], "shape": "line", "count": WORK_ZONE_CONES,
                                                   "location": where, "label": "maintenance"})
    beside = ({**where, "relation": "next_to"} if where.get("target") else
              {**where, "x": float(where.get("x") or 0.0) + WORK_ZONE_SIGN_M} if where.get("relation") == "absolute" else where)
    sign = ToolCall(tool="add_asset", args={"category": "construction_sign", "label": "maintenance", "location": beside})
    return [cones, sign]


def _closes_roads(category: str) -> bool:
    """Whether a line of these can close a road: work-zone or blocking kit that may stand in a lane
    (cones, barriers, bollards, rubble), not a tree whose shadow falls "across the road"."""
    kind = catalog()[category]
    return kind.motion == "prop" and kind.placement != "sidewalk" and is_layout_kit(category)


# A line laid across the road, or one meant to stop traffic: a closure ("5 cones across the street").
_ACROSS_ROAD = re.compile(r"\b(?:across|over|spanning) (?:the )?(?:whole |both |all (?:the )?|each of the |every )?(?:[a-z]+bound )?"
                          r"(?:road|street|carriageway|lanes?)\b"
                          r"|\bso (?:that )?(?:nobody|no one|no cars?|nothing|no traffic) can (?:drive|get|pass|go)\b")
# Spacing of a closure's line: barriers end to end, anything smaller (cones, bollards) closer.
CLOSURE_SPACING_M = {"road_barrier": 2.5}
CLOSURE_SPACING_DEFAULT_M = 1.5
# The least gap between neighbours of a closure's line.
CLOSURE_GAP_M = 0.1


# "a grid with 3 columns"; "colum" is how the word is often typed.
_COLUMNS = re.compile(r"\b(\d+|[a-z]+)\s+(?:columns?|colums?|cols?)\b")
# "a 3 by 3 grid", "four-by-four", "2x3": rows by columns.
_GRID_SIZE = re.compile(r"\b(\d{1,2}|[a-z]+)\s*(?:-?\s*by\s*-?|x|\*|\s+rows?\s+of\s+)\s*(\d{1,2}|[a-z]+)\b")
# "Same again but bollards": the last turn's amount, of what this turn names.
_SAME_AGAIN = re.compile(r"\b(?:same (?:again|as before|thing)|the same but|again but)\b")


# "... with barriers", "with a few cones": what a layout is made of, named after its place.
_WITH = re.compile(r"\bwith\s+(?:[\w-]+\s+){0,3}$")
# The fewest things a vaguely counted grid holds: two rows of two.
GRID_MIN = 4
# What a ring is laid around comes after these: "around the rubble", "round the tree", "surround the bin",
# "cordon the debris off (with cones)".
_AROUND = re.compile(r"\b(?:a?round|surround(?:s|ed|ing)?|encircl(?:e|es|ed|ing)|cordon|enclose|rope|fence|seal|box)\b"
                     r"|^\s*(?:please\s+)?ring\b")  # "ring the hydrant with cones" (never "a ring of cones round it")
# The passive names the layout after "by" and what it surrounds before: "the fountain ringed by six benches".
_AROUND_BY = re.compile(r"\b(?:ring|encircl|surround|circl)ed\s+(?:all\s+round\s+)?by\b")
# "Around" with nothing to go round ("a few more bins around", "cones around here"): here and there, not a ring.
_AROUND_LOOSE = re.compile(r"\baround\s*(?:$|[.,!?;]|(?:here|somewhere|the (?:place|campus|scene|map)|campus)\b)")
_ROUND_IT = re.compile(r"\b(?:all\s+)?round\s+(?:it|them|that|this|the|its|[a-z]+_\d+)\b")  # "stick some cones round it": a ring
# ("some of those short metal posts": a vague part of a kind, its words describing the kind)
_VAGUE_AMOUNT = re.compile(r"\b(?:some|several|a few|a number of)\s+(?:of\s+(?:the|those|these|them|our)\s+)?(?:[\w-]+\s+){0,2}$")


def _grid_size(low: str) -> tuple[int, int, int, int] | None:
    """A grid's rows and columns ("a 3 by 3 grid", "four-by-four grid", "grid 2x3") and where."""
    if md.layout_said(low) != "grid":
        return None
    said = _GRID_SIZE.search(low)
    if said is None:
        return None
    rows, columns = (int(w) if w.isdigit() else ph.NUMBER_WORDS.get(w, 0) for w in said.group(1, 2))
    return (rows, columns, said.start(), said.end()) if rows > 0 and columns > 0 else None


# A line "from X to Y": its ends, a little short of each (never on top of what it runs from).
FROM_TO_END_GAP_M = 3.0
# With no spacing said, a line from one place to another has things this far apart, at most this many.
FROM_TO_SPACING_M = 5.0
MAX_FROM_TO = 50


def _from_to(r: Reading, scene: Scene) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The two ends of a line said "from X to Y" (places, things or the ego), each a little
    short of what it names; None when the words name no two such ends."""
    said = FROM_TO.search(r.low)
    if said is None:
        return None
    points = []
    for part in (said.group("a"), said.group("b")):
        name = named_at(scene, f" {part}", [])
        thing = scene.ego if name == "ego" else scene.asset(name) if name else None
        mark = scene.landmark(name) if name and thing is None else None
        if thing is None and mark is None:
            return None
        points.append((thing.pose.x, thing.pose.y) if thing is not None else mark.position if mark is not None else (0.0, 0.0))
    (x1, y1), (x2, y2) = points
    length = math.dist(points[0], points[1])
    if length <= 2 * FROM_TO_END_GAP_M:
        return None
    ux, uy = (x2 - x1) / length, (y2 - y1) / length
    gap = FROM_TO_END_GAP_M
    return (x1 + ux * gap, y1 + uy * gap), (x2 - ux * gap, y2 - uy * gap)


# The things a layout is made of, pointed at as those there: "the cars", "both benches", "all the cones".
_THOSE_THERE = re.compile(r"\b(?:the|those|these|both|all|our|my)\s+(?:(?:the|of|two|three|four|five|six|\d+)\s+){0,2}$")


# New things said to face one another: no one heading says it.
_EACH_OTHER = re.compile(r"\b(?:fac(?:e|es|ing)|point(?:s|ing)?(?: at)?)\s+(?:each other|one another)\b")


def _faced_where(r: Reading, scene: Scene, where: dict[str, Any] | None) -> float | None:
    """The heading (degrees) of a new thing the words say faces something ("facing the road", "facing
    the fountain"), seen from where it goes; None when they say none."""
    if _EACH_OTHER.search(r.low):
        raise PlanningError("I cannot turn new things to face each other as I add them; add them, then turn each, "
                            "e.g. 'turn bench_2 to face bench_3'")
    target = where.get("target") if where is not None else None
    try:
        spot = (float(where["x"]), float(where["y"])) if where is not None and "x" in where and "y" in where else (
            (resolve_target(scene, str(target)).x, resolve_target(scene, str(target)).y) if target else None)
    except ToolError:
        return None
    faced = faced_from(r, scene, *spot) if spot is not None else None
    if faced is None or spot is None or math.dist(faced, spot) < 0.5:
        return None
    return round(math.degrees(math.atan2(faced[1] - spot[1], faced[0] - spot[0])), 1)


# Things there moved further apart: "spread the cars in lot B out", "space the benches further apart".
_SPREAD_OUT = re.compile(r"\b(?:spread|space|fan)\b(?:\s+[\w-]+){0,6}?\s+(?:out|apart)\b|\b(?:further|farther|more)\s+apart\b")
# Spread out, things stand this much further apart than they do (at least a metre more).
SPREAD_FACTOR = 1.5


def _spread_out(laid: list[AssetInstance]) -> list[ToolCall]:
    """The things moved apart along the line they stand on, about their middle, each facing as it
    does: the outermost first, so that none passes through another."""
    pts = [(a.pose.x, a.pose.y) for a in laid]
    far = max(((p, q) for p in pts for q in pts), key=lambda pq: math.dist(*pq))
    ux, uy = far[1][0] - far[0][0], far[1][1] - far[0][1]
    norm = math.hypot(ux, uy) or 1.0
    ux, uy = ux / norm, uy / norm
    along = {a.id: a.pose.x * ux + a.pose.y * uy for a in laid}
    middle = sum(along.values()) / len(along)
    order = sorted(laid, key=lambda a: along[a.id])
    gaps = [along[b.id] - along[a.id] for a, b in itertools.pairwise(order)]
    gap = sum(gaps) / len(gaps)
    stretch = max(gap * SPREAD_FACTOR, gap + 1.0) / gap if gap > 0 else 1.0
    calls = []
    for a in sorted(laid, key=lambda a: -abs(along[a.id] - middle)):  # (the middle one, if any, stays: a move of nothing)
        shift = (along[a.id] - middle) * (stretch - 1.0)
        calls.append(ToolCall(tool="move_asset", args={"asset": a.id, "east": round(shift * ux, 2), "north": round(shift * uy, 2)}))
    return calls


def _laid_out_there(r: Reading, mention: ph.Mention, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall] | None:
    """Things already there moved into the layout the words ask for ("line up the cars in lot B",
    "arrange the trees in a ring around the fountain"), never new ones added nor one of them moved;
    None when the words ask for no layout of several things there."""
    shape = md.layout_said(r.masked)
    if shape is None or not mention.plural or _THOSE_THERE.search(r.low[: mention.start]) is None:
        return None
    there = referenced(r, scene, memory, notes)
    if len(there) < 2 or any(i == "ego" for i in there):
        return None
    row = _arrange(r, scene, memory, notes)
    args = {k: v for k, v in row.args.items() if k != "count"}
    laid = [i for i in there if (a := scene.asset(i)) is not None and a.category in catalog()]
    args["categories"] = list(dict.fromkeys(a.category for i in laid if (a := scene.asset(i)) is not None))[:4]
    if args.get("location") == {"relation": "scene_centre"}:  # "line up the trees": where they stand, not at the crossroads
        spots = [(a.pose.x, a.pose.y) for i in laid if (a := scene.asset(i)) is not None]
        cx, cy = sum(x for x, _ in spots) / len(spots), sum(y for _, y in spots) / len(spots)
        x, y = min(spots, key=lambda p: math.hypot(p[0] - cx, p[1] - cy))
        args["location"] = {"relation": "absolute", "x": round(x, 1), "y": round(y, 1)}
    return [ToolCall(tool="arrange_assets", args={**args, "assets": laid})]


def _arrange(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> ToolCall:
    size = _grid_size(r.low)
    mentions = [m for m in r.mentions if size is None or not size[2] <= m.start < size[3]]  # "four-by-four" is no SUV here
    r = replace(r, mentions=mentions)
    around = _AROUND.search(r.low)
    around_pos = around.start() if around else -1
    by = _AROUND_BY.search(r.low)

    def laid_out(m: ph.Mention) -> bool:  # "around the rubble with barriers", "surround the bin with cones"
        if by is not None:
            return m.start > by.start()
        return around_pos < 0 or m.start < around_pos or bool(_WITH.search(r.low[: m.start]))

    fresh = [m for m in mentions if is_new(r, m, False, scene.count(m.category) > 0)]  # "... from the bench": not laid out
    layout = [m.category for m in mentions if laid_out(m) and (m in fresh or not fresh)] or [mentions[0].category]
    layout = list(dict.fromkeys(layout))
    args: dict[str, Any] = {"categories": layout[:4]}
    first = next(m for m in mentions if m.category == layout[0]) if any(laid_out(m) for m in mentions) else mentions[0]
    count = find_count(r, first) or (len(memory.last_added()) if _SAME_AGAIN.search(r.low) else None)
    if _VAGUE_AMOUNT.search(r.low[: first.start]) and r.has(("all the way", "all around", "surround", "encircle")):
        count = None  # "some bollards all the way around it": as many as the ring needs
    if count == 1 and md.layout_said(" ".join(r.low[: mentions[0].start].split()[-3:])):
        count = None  # "a little grid of benches": the article counts the layout, not the benches
    if count == 1 and r.has(("every",)):
        count = None  # "a barrier every 10 m": one at each step, not one in all
    if count:
        args["count"] = count
    rows_of = md.rows_said(r.low)
    vehicles = all(catalog()[c].motion == "vehicle" for c in layout)
    parking = r.has(("parked", "side by side", "car park", "parking")) or "parking" in str(r.landmark or notes.place)
    if rows_of >= 2 and count:  # "six benches in two rows": a grid of two rows, three to a row
        args["shape"], args["columns"] = "grid", math.ceil(count / rows_of)
    elif vehicles and parking and (r.has(("row", "rows", "line", "side by side", "next to each other")) or r.has(lx.ARRANGE_WORDS)):
        args["shape"] = "parking_row"  # "a row of parked cars in lot B": side by side in bays
    elif _LINING.search(r.low) and not r.has(("across",)):
        args["shape"] = "lane_edge"  # "line the road near the gate with cones", "cones along the kerb"
    elif (r.has(("rows", "across", "slalom")) and md.layout_said(r.low) != "grid") or md.layout_said(r.low) in ("line", "row") or (
            md.layout_said(r.low) is None and nb.spacing_said(r.low) is not None):
        args["shape"] = "line"
    elif md.layout_said(r.low) == "grid":
        args["shape"] = "grid"
        if _VAGUE_AMOUNT.search(r.low[: first.start]) and int(args.get("count") or GRID_MIN) < GRID_MIN:
            args["count"] = GRID_MIN  # "some bollards in a grid": two by two at least, not three
        columns = _COLUMNS.search(r.low)
        if size is not None:  # "a 3 by 3 grid": nine, three to a row
            args["count"], args["columns"] = size[0] * size[1], size[1]
        elif columns is not None:
            said = columns.group(1)
            args["columns"] = int(said) if said.isdigit() else ph.NUMBER_WORDS.get(said, 0) or None
    elif r.has(("along the lane", "along the road", "lane edge", "along the edge", "along the kerb")):
        args["shape"] = "lane_edge"
    elif r.has(("along",)):
        args["shape"] = "line"  # "benches along the north side of lot B"
    else:
        args["shape"] = "ring"
    if args["shape"] == "ring" and _VAGUE_AMOUNT.search(r.low[: first.start]) and not re.search(r"\ba few\s+(?:[\w-]+\s+){0,2}$", r.low[: first.start]):
        args.pop("count", None)  # "some bollards round the tree": as many as the ring needs ("a few" are three)
    where = location(r, scene, memory, notes)
    if args["shape"] == "lane_edge" and where is not None and where.get("relation") == "on_sidewalk" and r.landmark:
        where = {"relation": "at", "target": r.landmark}
    if args["shape"] == "ring":
        targets = [m for m in mentions if m.category not in layout]
        if around is not None and r.landmark and 0 <= around_pos < r.landmark_at:
            # "6 benches around the fountain, and a bin next to it": the place said after "around", not a thing said later
            targets = [m for m in targets if m.start < r.landmark_at]
        # The first thing named that stands here ("cordon off" names barriers, none of them standing)
        named = next(([a for a in scene.assets if a.category == t.category] for t in targets if scene.count(t.category)), [])
        if named and r.landmark and (mark := scene.landmark(r.landmark)) is not None:  # "the tree by the fountain"
            named.sort(key=lambda a: -math.hypot(a.pose.x - mark.position[0], a.pose.y - mark.position[1]))
        if named:
            where = {"relation": "at", "target": named[-1].id}
        elif where is None and r.has(("it", "them")) and notes.subject and scene.asset(notes.subject[0]) is not None:
            where = {"relation": "at", "target": notes.subject[0]}  # "the hydrant is being serviced: ring it with bollards"
        elif (where is None or where.get("relation") == "absolute") and r.has(("it", "them", "that", "this")) and (
                recent := [i for i in memory.last_touched() if (a := scene.asset(i)) is not None and a.category not in layout]):
            where = {"relation": "at", "target": recent[0]}  # "cordon it off": what the last turn touched, not where it stood
        elif where is None and notes.place is None and r.has(("it", "them", "that", "this")) and not r.has(lx.WORKS_WORDS):
            # "cone that off" with nothing before it to ring: never a ring in the middle of the map
            raise PlanningError(f"I cannot tell what to put the {' and '.join(c.replace('_', ' ') + 's' for c in layout)} "
                                "around; name the thing or place, e.g. 'cone off the bench'")
        elif where is None or r.has(lx.WORKS_WORDS):
            focus_target = _maintenance_target(scene, memory)
            if focus_target is not None and where is None:
                where = {"relation": "at", "target": focus_target}
    if where is None and notes.place is None and (
            said_a_place(r) or any(places_called(scene, m.group("kind")) for m in _THE_KIND.finditer(r.low))):
        notes.guess(_UNRECOGNISED)  # "line up six people at the stop": which place is asked, never the middle of the map
    # "the student car park should look busy: a row of six cars": the place of the clause before
    args["location"] = where or (dict(notes.place) if notes.place else None) or _fallback_place(memory)
    if args["categories"] == ["road_barrier"] and args["shape"] == "ring" and not _BARRIERS_SAID.search(r.low) \
            and _stands_off_road(scene, args["location"]):
        args["categories"] = [_GROUND_CORDON]  # "cordon off the fountain": on the grass, with what stands there
    if r.has(("slalom",)):  # cones a car weaves between: a few, well apart, down the middle of the lane
        if args.get("count") == 1:
            args.pop("count")  # "a cone slalom": one slalom, not one cone
        args.setdefault("count", SLALOM_CONES)
        args["spacing"] = SLALOM_SPACING_M
        place = args["location"] or {}
        if place.get("relation") == "in_lane" and scene.roads.lane(str(place.get("target"))) is not None:
            args["shape"], args["location"] = "lane_edge", {**place, "side": "right", "offset_m": 0.0}
    edge = EDGE_OF.search(r.low)
    if args["shape"] == "line" and edge is not None and args["location"].get("relation") == "absolute":
        args["heading_deg"] = 90.0 if edge.group(1) in ("east", "west") else 0.0  # along that edge of the area
    if args["shape"] == "parking_row" and edge is not None and args["location"].get("relation") == "absolute":
        args["heading_deg"] = 0.0 if edge.group(1) in ("east", "west") else 90.0  # side by side along that edge, facing across it
    spacing = nb.spacing_said(r.low)
    if spacing is not None:
        args["spacing"] = spacing
    radius = nb.radius_said(r.low)
    if radius is not None:
        args["radius"] = radius
    if r.has(("maintenance", "construction")):
        args["label"] = "maintenance"
    ends = _from_to(r, scene) if args["shape"] == "line" else None
    if ends is not None:  # "cones every 3 m from the ego to the crossroads": a line between the two, as many as fit
        (x1, y1), (x2, y2) = ends
        length = math.dist(ends[0], ends[1])
        if "count" not in args:
            args["count"] = max(2, min(MAX_FROM_TO, int(length / float(args.get("spacing") or FROM_TO_SPACING_M)) + 1))
        args["spacing"] = round(length / (int(args["count"]) - 1), 2)
        args["location"] = {"relation": "absolute", "x": round((x1 + x2) / 2, 2), "y": round((y1 + y2) / 2, 2)}
        args["heading_deg"] = round(math.degrees(math.atan2(y2 - y1, x2 - x1)), 1)
        return ToolCall(tool="arrange_assets", args=args)
    along = _heading_along(r, scene, args)
    length = (int(args.get("count") or 5) - 1) * float(args.get("spacing") or 0.0)
    place = args["location"] or {}
    if along is not None and "along_m" in place:  # "starting 20 m ahead of our car" in a lane: from there on
        along_m = float(place["along_m"])
        args["heading_deg"], args["location"] = along, {**place, "along_m": round(along_m + math.copysign(length / 2, along_m), 1)}
    elif along is not None:  # the line starts where it was said to and runs on ahead (or back) from there
        start = float(place.get("distance") or LINE_START_M)
        args["heading_deg"], args["location"] = along, {**place, "distance": round(start + length / 2, 1)}
    elif args["shape"] == "line" and place.get("relation") in ("in_front_of", "behind") and "distance" not in place and (
            (driver := scene.asset(str(place.get("target")))) is not None and catalog()[driver.category].drives):
        args["location"] = {**place, "distance": LINE_ACROSS_M}  # across a vehicle's way, where it can be seen coming
    return ToolCall(tool="arrange_assets", args=args)


# A slalom unless told otherwise: this many cones, this far apart.
SLALOM_CONES, SLALOM_SPACING_M = 6, 5.0
# Lining a road, a lane or its edge: "line the road with cones", "the edges of the bus lane", "along the kerb".
_LINING = re.compile(
    r"\bline[sd]?\s+(?:the\s+|both\s+|each\s+|either\s+|our\s+)?(?:[a-z]+\s+){0,2}?(?:roads?|lanes?|streets?|kerbs?|curbs?|edges?)\b"
    r"|\b(?:edges?|kerbs?|curbs?) of (?:the |that |this |our )?(?:[a-z]+\s+){0,2}?(?:lanes?|roads?|streets?)\b"
    r"|\balong (?:the |both |each |either )?(?:edges?|kerbs?|curbs?)\b|\blane edges?\b"
)


def _both_sides(call: ToolCall, r: Reading, scene: Scene) -> list[ToolCall]:
    """A lane_edge row said on both sides, as one row per edge: a lane named alone is lined on its
    left and right; a road, at each lane's kerb. Anything else is returned as it is."""
    both = md.BOTH_SIDES.search(r.low)
    if call.args.get("shape") != "lane_edge" or both is None:
        return [call]
    place = dict(call.args["location"])
    lane = scene.roads.lane(str(place.get("lane") or place.get("target") or "")) or (scene.roads.lane(r.lane) if r.lane else None)
    if lane is None:
        x, y = _point_of(scene, place)
        if x is None or y is None:
            return [call]
        lane = min(scene.roads.lanes, key=lambda ln: nearest_on_polyline(x, y, ln.centreline).distance)
    count = call.args.get("count")
    if count and "each" not in both.group(0):  # "ten cones on both sides": five a side
        count = math.ceil(int(count) / 2)
    sides: list[dict[str, Any]]
    if one_lane_named(r) or not lane.road:
        sides = [{**place, "lane": lane.id, "side": side} for side in ("right", "left")]
    else:
        sides = [{**place, "lane": ln.id} for ln in scene.roads.lanes if ln.road == lane.road]
    if place.get("target") == lane.id:
        sides = [{**side, "target": side["lane"]} for side in sides]
    return [ToolCall(tool=call.tool, args={**call.args, "location": side, **({"count": count} if count else {})}) for side in sides]


def _point_of(scene: Scene, place: dict[str, Any]) -> tuple[float | None, float | None]:
    """The point a place's target stands at (a landmark or an asset), else (x, y) as given."""
    target = str(place.get("target") or "")
    mark = scene.landmark(target) if target else None
    if mark is not None:
        return mark.position
    thing = scene.ego if target == "ego" else scene.asset(target) if target else None
    if thing is not None:
        return thing.pose.x, thing.pose.y
    return place.get("x"), place.get("y")


# A line longer than this does not fit across a two-lane road (7 m): one said "ahead of" a thing runs along its path.
ACROSS_MAX_M = 6.5
# Metres from the thing to the first of a line along its path, when the words give none.
LINE_START_M = 4.0
# Metres ahead of (or behind) a thing that a line across its way stands, when the words give none.
LINE_ACROSS_M = 10.0


def _heading_along(r: Reading, scene: Scene, args: dict[str, Any]) -> float | None:
    """The heading of the thing a line is ahead of or behind, when the line runs along its path
    ("8 cones in a line 4 m apart ahead of the ego", "a slalom down the lane"); else None."""
    where = args.get("location") or {}
    ahead = where.get("relation") in ("in_front_of", "behind") or (where.get("relation") == "in_lane" and "along_m" in where)
    if args.get("shape") != "line" or not ahead or r.has(("across",)):
        return None
    length = (int(args.get("count") or 5) - 1) * float(args.get("spacing") or 0.0)
    if length <= ACROSS_MAX_M and not r.has(("slalom", "along", "down the lane", "down the road", "down the middle")):
        return None
    target = scene.ego if where.get("target") == "ego" else scene.asset(str(where.get("target")))
    return round(math.degrees(target.pose.yaw), 1) if target is not None else None


# A road said to be too quiet: what is added to it is traffic.
_ROAD_TOO_QUIET = re.compile(r"\b(?:quiet|empty|dead|deserted|lifeless|no traffic)\b")


def _add(r: Reading, scene: Scene, memory: Memory, notes: Notes, count: int | None = None) -> list[ToolCall]:
    """add_asset for the first thing the clause names: `count` of them, else as many as it says."""
    mention = r.mentions[0]
    concepts = {w for words in lx.CONCEPTS.values() for w in words}
    named = [m for m in r.mentions[1:] if m.category == mention.category and r.low[m.start : m.end].strip() not in concepts]
    if r.low[mention.start : mention.end].strip() in concepts and named:
        mention = named[0]  # "warn drivers with a road-works sign": the sign said, not the warning
    word = r.low[mention.start : mention.end].strip()
    mass = word.endswith(("ing", "ery")) and word not in lx.CONCEPTS["construction_sign"]  # "seating": several; "a warning": one
    again = len(memory.last_added()) if _SAME_AGAIN.search(r.low) else None
    count = count or find_count(r, mention) or again or (3 if mention.plural or mass else 1)
    # The count is passed as said: the Worker refuses what is too many, in words.
    args: dict[str, Any] = {"category": mention.category, "count": count}
    category = catalog()[mention.category]
    kind = behaviour_kind(r, category)
    if kind is None and word == "traffic":
        kind = "drive_lane"  # "more traffic on Main Street": vehicles that drive, not parked ones
    if kind is None and category.motion == "vehicle" and r.lane and _ROAD_TOO_QUIET.search(r.low):
        kind = "drive_lane"  # "Main Street so quiet, add some cars": traffic, driving
    pace = _SAME_PACE.search(r.low) if category.drives else None
    if kind is None and pace is not None:
        kind = "drive_lane"  # "a car 25 m ahead of it, same lane, same speed": one the ego follows, driving
    walk = walk_said(r, scene, exclude=[]) if category.motion == "walker" and kind in (None, "drive_lane") else None
    drive = drive_towards(r, scene) if category.drives and category.motion == "vehicle" and kind in (None, "drive_lane") else None
    if walk is not None:  # "a man walking towards the fountain": on his way there, from where said or some way off
        kind, args["behaviour"] = "follow_path", walk.behaviour
    elif drive is not None:  # "a truck heading for the main gate": in the lane that leads there, some way before it
        kind, args["behaviour"] = "drive_lane", drive[0]
    elif kind is not None:
        args["behaviour"] = behaviour_spec(kind, r, scene)
        ego_speed = getattr(scene.ego.behaviour, "speed", None) if scene.ego is not None else None
        if pace is not None and kind == "drive_lane" and ego_speed and "speed" not in args["behaviour"]:
            args["behaviour"]["speed"] = ego_speed
    where = location(r, scene, memory, notes) if walk is None or walk.start is None else {"relation": "at", "target": walk.start}
    where = drive[1] if drive is not None else where
    if walk is not None and where is not None and where.get("target") == walk.behaviour["to"]:
        where = None  # "a man walking to the fountain": where he goes, not where he stands; he starts some way off
    if where is None and again is not None:  # "same again but bollards": where the last ones went
        where = last_location(memory)
    if where is not None and kind == "jaywalk" and where.get("target") == "ego":
        where = None  # the jaywalk behaviour places the walker in the ego's path itself
    mark = scene.landmark(str(where.get("target"))) if where is not None else None
    if where is not None and category.placement == "sidewalk" and where.get("relation") == "at" and mark is not None \
            and (_sidewalk_gap(scene, mark.position) <= SIDEWALK_REACH_M
                 or surface_at(scene, mark.position[0], mark.position[1]) != "ground"):
        # a hydrant "at the library" goes on the sidewalk by it; where none is near, on the ground by the place
        where = {"relation": "on_sidewalk", "target": where["target"]}
    if where is None and kind is None and memory.last_focus() is not None and r.has(("also", "more", "another")):
        where = _beside_last(scene, memory) or _fallback_place(memory)
    if where is None and notes.place is not None and (r.has(("there", "instead")) or (notes.coming and r.has(("for them", "for it")))):
        where = dict(notes.place)  # "two people waiting at the stop, and a bench for them": there too
    if where is None and notes.scene_set is not None and kind in (None, "parked"):
        where = dict(notes.scene_set)  # "lot A looks empty in the renders. fix with 3 parked cars": there
    kind_of_place = any(places_called(scene, m.group("kind")) for m in _THE_KIND.finditer(r.low))  # "at the entrance"
    if where is None and (said_a_place(r) or kind_of_place) and kind is None:
        notes.guess(_UNRECOGNISED)
    if where is not None:
        args["location"] = where
        notes.place = where
    colour = next((c for c in COLOURS if r.has((c,))), None)
    if colour is not None:
        args["colour"] = colour
    facing = md.facing_direction(r.masked)
    if facing is not None:  # "a stop sign at the north crosswalk facing south": turned that way
        east, north = md.COMPASS_VECTORS[facing]
        args["yaw_deg"] = round(math.degrees(math.atan2(north, east)), 1)
    elif (faced := _faced_where(r, scene, where)) is not None:  # "a bench at the bus stop facing the fountain"
        args["yaw_deg"] = faced
    sides = _EACH_SIDE.search(r.low) if where is not None and where.get("relation") in ("at", "next_to") else None
    calls = [ToolCall(tool="add_asset", args=args)]
    if sides is not None and where is not None and where.get("target"):  # "a bin on each side of the door": one left, one right
        near = {"target": where["target"], "distance": where.get("distance", SIDE_GAP_M)}
        if find_count(r, mention) is None:  # "bins either side of the bench": one a side, not a handful
            count = 1
            args["count"] = count
        calls = [ToolCall(tool="add_asset", args={**args, "location": {"relation": side, **near}}) for side in ("left_of", "right_of")]
        count *= 2
    notes.adding(scene, mention.category, count)
    notes.named, notes.subject = notes.subject, notes.coming[-count:]  # "add a car, make it red": "it" is the new car
    return calls


# "On each side of", "either side of", "flanking": one lot on the left of the place and one on its right.
_EACH_SIDE = re.compile(r"\b(?:(?:on )?(?:each|either|both) sides?(?: of)?|flank(?:ing|ed)?|to (?:the )?left and (?:the )?right of)\b")
SIDE_GAP_M = 2.0
