"""What a request says, read from its words: the signals the plan check holds a plan to.

Polarity (add or take away), whether it asks a question (in any mood: "which ...", "list
the lanes", "could you tell me ..."), the categories and numbers it names, the place, lane and
state (parked, moving) it limits itself to. A small general vocabulary, not the planners'
phrase lists: the check must read a request the planners misread, so it cannot share their
reading of it.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Literal

from drivetwin.orchestrator.planning.intent import (
    ADD_WORDS,
    HOW_THINGS_GO,
    REMINISCED,
    REMOVE_WORDS,
    REPORTED,
    TAG_QUESTION,
    WHAT_IF,
    asks,
    commands,
    excepted,
    taken_back,
    without_reason,
    without_salutations,
)
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules import numbers as nb
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.clock import clock_time
from drivetwin.orchestrator.planning.rules.conditions import condition
from drivetwin.orchestrator.planning.rules.numbers import numbers_in
from drivetwin.orchestrator.planning.rules.reading import (
    FIRST_PERSON_EGO,
    find_lane,
    find_place,
    labelled,
    named_as,
    numbered_picks,
    without_beneficiaries,
    without_goals,
    without_order,
)
from drivetwin.orchestrator.planning.rules.replacing import swap_said
from drivetwin.orchestrator.planning.rules.spelling import repair
from drivetwin.worlds.scene import Scene

# Number words that state an amount; vague ones ("a few", "some", "a couple") are not checked.
_AMOUNTS = {w: n for w, n in ph.NUMBER_WORDS.items() if w not in ("a", "an", "one", "single", "pair", "couple",
                                                                   "few", "some", "several")}
_PLACE_TOPIC = re.compile(r"\b(landmarks?|places?|buildings?|entrances?)\b")
# A category word after these describes the thing asked for ("a vehicle that carries passengers",
# "a bench for pedestrians") rather than naming it.
# ("the same with barriers": what to do it with, not a description)
# ("warn drivers with a sign", "mark it off with cones", "close the lane with barriers": what it is done with)
_DESCRIBING = re.compile(r"[a-z](?<!same)(?<!again)\s+(that|which|who|for|carrying|carries|full of)\b[^,.;:]*$"
                         r"|[a-z](?<!same)(?<!again)(?<!\bit)(?<!them)(?<!off)(?<!up)(?<!drivers)(?<!traffic)(?<!people)(?<!road)"
                         r"(?<!lane)(?<!area)\s+with\b[^,.;:]*$")
_LANE_WORDS = re.compile(r"\b(lanes?|[a-z]+bound|[a-z]+_(?:north|south|east|west)bound)\b")
_PARKED = re.compile(r"\bparked\b")
_SHIFT = re.compile(r"\b\S+ (?:more )?hours? (?:later|earlier)\b"
                    r"|\b(?:clock|time)s?\s+(?:forwards?|on|ahead|back|backwards?)\s+(?:by\s+)?\S+\s+hours?\b")  # "the clock back 2 hours"
# "moving" said of the thing, not denied ("not moving", "stopped driving")
# Moving as what a thing should be doing, not which ones: "the SUV needs to be driving down Main Street".
_TO_BE_MOVING = re.compile(r"\b(?:to be|should be|must be|start|keep|be)\s+(?:\w+\s+)?(?:driving|moving|travelling|traveling|riding)\b")
_MOVING = re.compile(r"(?<!not )(?<!n't )(?<!never )(?<!stop )(?<!stopped )\b(driving|moving|travelling|traveling|riding)\b"
                     # "a car that brakes suddenly", "a van which slows down": what it does as it goes
                     r"|\b(?:that|which|who)\s+(?:\w+ly\s+)?(?:brakes?|slows?|swerves?|speeds?|accelerates?|drives?|rides?"
                     r"|overtakes?|merges?|reverses?|cuts?|changes? lanes?)\b"
                     # "a slow truck ahead of the ego", "a speeding car": how fast it goes
                     r"|\b(?:slow|slow-moving|speeding|fast-moving)\s+(?:[a-z]+\s+)?(?:car|truck|lorry|bus|van|vehicle|suv|bike|cyclist|motorbike|motorcycle)s?\b")


@dataclass(frozen=True)
class Request:
    """The signals read from a request's words."""

    text: str
    question: bool
    polarity: Literal["add", "remove"] | None
    categories: frozenset[str]
    numbers: tuple[float, ...]
    place: str | None
    lane: str | None
    state: Literal["parked", "moving"] | None
    about_places: bool = False
    low: str = ""
    masked: str = ""
    excepted: tuple[str, ...] = ()  # what the request says it does not mean (", not the ego")


# Words that ask: in a sentence ending with a question mark, the request is a question, unless that
# sentence asks for something to be done ("It's too dark to see where they're going. Can you brighten it?").
_QUESTION_WORD = re.compile(r"\b(?:where|wheres|which|what|whats|how|hows|who|whose|when|why)\b")
_ASKED_TO_DO = re.compile(r"\s*(?:\W*\w+\W+){0,3}?(?:can|could|would|will)\s+(?:you|we|i)\b")


def read_request(prompt: str, scene: Scene) -> Request:
    """The request's signals: polarity, categories, numbers, place, lane, state and mood."""
    repaired = taken_back(repair(prompt, scene).text)[0]  # "..., no wait, scrap that, ...": what follows
    given = condition(repaired, scene)  # "if there's a bus, paint it yellow": the bus there, or a question
    repaired = given.request if given is not None and given.met else repaired
    low = ph.normalise(without_reason(without_salutations(repaired) or repaired)).strip()
    low = ph.normalise(named_as(low)[0]).strip()  # "..., that's our crash vehicle": a name given, no vehicle asked for
    for ident, start, end in reversed(labelled(scene, low)):  # "the steward": the thing the person named so
        low = low[:start] + ident + low[end:]
    for ident, start, end in reversed(numbered_picks(scene, low)):  # "car 2": that one, not two cars
        low = low[:start] + " " + ident + " " + low[end:]
    place = _named_place(scene, low)
    masked = low if place is None else low[: place[1]] + " " + low[place[2] :]
    for word in ph.EGO_WORDS:  # "the ego car" is the ego, not a car asked for
        masked = re.sub(rf"(?<![a-z]){re.escape(word)}(?![a-z])", " ego ", masked)
    masked = FIRST_PERSON_EGO.sub(lambda m: m.group(0)[: m.start(1) - m.start()] + "ego", masked)  # "behind us"
    masked = without_order(masked)  # "the third car from the west": which one, not which way
    # "I want to see what happens if a child runs out ...": the case to see, not what to do
    masked = re.sub(r"[^.!?]*", lambda m: " " * len(m.group(0)) if WHAT_IF.search(m.group(0)) else m.group(0), masked)
    # A lane is named by its id, or by a direction said of a lane ("the westbound lane"), not by a
    # compass word alone ("2 m east", "facing north").
    lane = find_lane(scene, masked) if _LANE_WORDS.search(masked) else None
    # "🚒 hydrant where? coords pls", "lanes on campus drv?? and which way they go": a question mark and a
    # question word, with no command, ask however the words run
    # (one that opens on its question word is asks()' to judge: "how would the campus look at 7pm?" asks to see it)
    # (nor where another sentence gives a command: "who put a hydrant by the crossroads? get rid of it")
    marked = not any(commands(part) for part in re.split(r"[.!?]+", low)) and any(
        _QUESTION_WORD.search(sentence) and not _QUESTION_WORD.match(sentence.strip(" ,;:-—")) and not _ASKED_TO_DO.match(sentence)
        for sentence in re.findall(r"[^.!?]*\?", low))
    # "no trucks anywhere, right?": a tag asks whether what was said is so (the reason stripper drops it)
    tagged = TAG_QUESTION.search(ph.normalise(repaired).strip()) is not None and not commands(low)
    question = asks(low) or marked or tagged or (given is not None and not given.met)  # with no bus, whether there is one
    polarity: Literal["add", "remove"] | None = (
        "remove" if REMOVE_WORDS.search(low) else "add" if ADD_WORDS.search(low) else None
    )
    # The place stands in as "lot" so a word naming it ("the student car park") is read as its name.
    kinds_text = masked if place is None else low[: place[1]] + " lot " + low[place[2] :]
    for word in ph.EGO_WORDS:
        kinds_text = re.sub(rf"(?<![a-z]){re.escape(word)}(?![a-z])", " ego ", kinds_text)
    # "cars keep getting hidden behind that bin", "people keep saying ...": who things go so for is no thing asked for
    kinds_text = HOW_THINGS_GO.sub(lambda m: " " * len(m.group(0)), kinds_text)
    kinds_text = re.sub(rf"{REPORTED.pattern}[^.;!?]*", lambda m: " " * len(m.group(0)), kinds_text)  # what others say
    kinds_text = re.sub(rf"{REMINISCED.pattern}[^.;!?]*", lambda m: " " * len(m.group(0)), kinds_text)  # what the speaker remembers
    swapped = swap_said(low) is not None  # "replace the bench with a bin": the bin is asked for, not a description
    categories = frozenset(m.category for m in without_goals(kinds_text, without_beneficiaries(kinds_text, ph.find_categories(kinds_text)))
                           if (swapped or not _DESCRIBING.search(kinds_text[: m.start])) and not _described_head(kinds_text, m))
    exact = re.sub(r"\S+ or \S+", lambda m: " " * len(m.group(0)), _without_checked_amounts(masked))  # "a tree or two"
    numbers = tuple(n.value for n in numbers_in(exact) if not _is_reference(masked, n.start))
    numbers += tuple(float(_AMOUNTS[w.group(0)]) for w in re.finditer(r"[a-z]+(?:-[a-z]+)?", exact)
                     if w.group(0) in _AMOUNTS and not _is_reference(masked, w.start()))
    state: Literal["parked", "moving"] | None = (
        "parked" if _PARKED.search(low) else "moving" if _MOVING.search(low) and not md.SET_GOING.search(low)
        and not _TO_BE_MOVING.search(low) else None
    )
    return Request(prompt, question, polarity, categories, numbers, place[0] if place else None,
                   lane[0] if lane and not lane[3] else None, state, bool(_PLACE_TOPIC.search(masked)), low, masked,
                   tuple(excepted(repaired)))


# A relative clause right after a noun: it says what the thing is ("a vehicle that carries ...").
_DESCRIBED = re.compile(r"\s+(?:that|which|who|with|for|carrying|carries|full of)\b")


def _described_head(masked: str, m: ph.Mention) -> bool:
    """A word for a whole group ("vehicle", "sign") whose clause after it describes the thing
    meant: the description names the category, not the group word."""
    indexed = ph.normalise(masked)  # the text find_categories indexes
    word = ph.singular(indexed[m.start : m.end].strip())
    return word in md.catalog_tags() and bool(_DESCRIBED.match(indexed[m.end :]))


def _named_place(scene: Scene, low: str) -> tuple[str, int, int] | None:
    """A place the request names in full (a name or alias), not one guessed from a single word."""
    found = find_place(scene, f" {low} ")
    if found is None:
        return None
    said = re.sub(r"\b(the|a|an)\s+(?=[a-z0-9])", "", f" {low} "[found[1] : found[2]].strip())
    landmark = scene.landmark(found[0])
    names = [re.sub(r"\b(the|a|an)\s+(?=[a-z0-9])", "", ph.normalise(n).strip()) for n in (landmark.names() if landmark else [])]
    return (found[0], max(0, found[1] - 1), max(0, found[2] - 1)) if said in names else None


def _without_checked_amounts(text: str) -> str:
    # A clock time is checked by what the time tool sets (coverage.py), and a spacing ("4 m
    # apart") by where things end up (attributes.py), not number by number.
    text = nb.SPACING.sub(lambda m: " " * len(m.group(0)), text)
    text = _SHIFT.sub(lambda m: " " * len(m.group(0)), text)  # "2 hours later": a time, checked as one
    said = clock_time(text)
    return text if said is None else text[: said.start] + " " * (said.end - said.start) + text[said.end :]


def _is_reference(text: str, start: int) -> bool:
    # "car 2", "lot 3", "the 2nd": a number that names something rather than an amount.
    before = text[:start].split()[-1:]
    if text[:start].rstrip().endswith("#") or re.search(r"\b(?:takeover|ticket|issue|case|run|bug|jira|incident)\s*#?\s*$", text[:start]):
        return True  # "takeover #7", "ticket 12": which one, not how many
    if re.search(r"\b(?:instead of|rather than|in place of|(?:faster|slower|quicker|bigger|smaller) than)\s*$", text[:start]):
        return True  # "8 m/s instead of 5", "faster than 5": what it is now, not what is wanted
    if re.match(r"[\d.,e+-]*\s*(m|metres?|meters?|km|kph|mph|degrees?|deg|seconds?|s)\b", text[start:]):
        return False  # "the truck 8 m ahead": an amount with its unit
    if _YEAR.match(text, start) or (re.search(r"\b(?:in|since|of|back in)\s+'?$", text[:start]) and _PAST.search(text[:start])
                                    and re.match(r"'?\d{2}\s*(?:[.!?,;]|$)", text[start:])):
        return True  # "in 1987", "the way it came down in 87": a year, not an amount
    part = _PARTS_COUNTED.match(text, start)
    if re.search(r"\b(?:with|having|has|have)\s+$", text[:start]) and part is not None and not ph.find_categories(part.group(1)):
        return True  # "the sign with eight sides", "a van with two doors": what it is like, not how many to make
    if before == ["take"] and re.match(r"[\w.,]*\s+(?:away|out|off)\b", text[start:]):
        return False  # "take two away": an amount, not a film's take 2
    return bool(before) and before[0].isalpha() and bool(ph.find_categories(before[0]) or before[0] in _LABELS)


# A number and the plural noun it counts, when that noun is no unit or layout of a plan ("eight sides";
# not "3 rows", "4 m", "5 seconds").
_PARTS_COUNTED = re.compile(r"[\w.,]*\s+(?!(?:rows|columns|lines|metres|meters|seconds|minutes|hours|degrees|laps|times|gaps|spaces|steps)\b)"
                            r"([a-z]{3,}s)\b")
# A year: "in 1987", "the summer of 2003".
_YEAR = re.compile(r"(?:19|20)\d{2}\b(?!\s*(?:m\b|metres?|meters?|km|cones?|s\b|seconds?))")
# Words of a time gone by, which a bare two-digit year follows ("the way it came down in 87").
_PAST = re.compile(r"\b(?:came|was|were|had|did|happened|used to|went|fell|back)\b")
# Words a number after names rather than counts: "lot 3", "condition 11", "take 2", "step 4".
_LABELS = frozenset(["lot", "no", "condition", "case", "step", "scenario", "test", "run", "take", "item", "row",
                     "shot", "scene", "variant", "trial", "phase", "version", "iteration", "cue", "act", "episode",
                     "chapter", "section", "part", "task", "page", "camera", "cam"])


__all__ = ["Request", "read_request"]
