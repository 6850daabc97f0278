"""What the request itself names, read once per prompt, to ground the managers' grammars.

A 135M model given every category, place and number of the world picks a plausible wrong
one ("a stop sign at the north crosswalk" became a pedestrian sign right of it; "2 m east"
became 2 m left). The request's own words say which categories, places, assets, relations
and numbers it names; where it names some, the Jr. manager's schema offers only those, and
the Sr. manager's requirement kinds follow what the words ask for (a question is a search,
a command is not). Where the request names none of a kind, nothing is narrowed.
"""

from __future__ import annotations

import re
from contextlib import suppress
from dataclasses import dataclass
from typing import Literal

from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.orchestrator.planning.intent import ADD_WORDS, REMOVE_WORDS
from drivetwin.orchestrator.planning.request import read_request
from drivetwin.orchestrator.planning.retrieval.slots import read_slots
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.clock import clock_time
from drivetwin.orchestrator.planning.rules.numbers import NUMBER, SPEED_UNIT, numbers_in, speed_said, spelt_measures
from drivetwin.orchestrator.planning.scenario_manoeuvres import manoeuvres_said
from drivetwin.orchestrator.planning.scenario_reading import describes_behaviour_over_time
from drivetwin.tools.appearance import COLOURS
from drivetwin.tools.base import FAMILIES, Family
from drivetwin.worlds.scene import Scene

# Slot kinds whose value is a number said in the request, and what they measure.
_NUMBER_SLOTS = ("count", "distance", "radius", "speed", "x", "y")
# Relation words the slot reader leaves out as too vague for adapting an example ("at",
# "around", "by"), still worth a relation here; first match wins.
_PLAIN_RELATIONS: tuple[tuple[str, str], ...] = (
    (r"\baround\b|\bring\b|\bcircle\b|\bsurround", "at"),
    (r"\b(sidewalk|side walk|pavement|footpath|footway|walkway|kerb|curb)\b", "on_sidewalk"),
    (r"\b(centre|center|middle) of the (scene|world|map|campus)\b", "scene_centre"),
    (r"\bx\s*=|\bcoordinates?\b", "absolute"),
    (r"\b(in|on) (the )?(lane|road|street)\b|\w+bound\b", "in_lane"),
    (r"\bby\b|\bnear\b|\bclose to\b", "next_to"),
    (r"\bat\b", "at"),
)
# Families that take something away or restyle it: all a plain removal can need.
_TAKING_AWAY: tuple[Family, ...] = ("remove", "appearance", "move", "position")
# Families a request that adds or puts something can need (never a removal).
_PUTTING: tuple[Family, ...] = ("add", "arrange", "position", "move", "appearance")
# Families a one-clause request for new things can need ("add a parked SUV in lot A" never moves the SUV there).
_NEW_ONLY: tuple[Family, ...] = ("add", "arrange", "appearance")
# Words that only ever ask for new things.
_STRICT_NEW = re.compile(r"\b(add|create|spawn|insert|another|extra)\b")
# Words and marks that join clauses: a request with one may hold several requirements.
CLAUSE_JOINS = re.compile(r"\b(and|also|then|plus|as well)\b|[,;+&]")
# Amounts said in words rather than figures ("a few", "a couple of", "loads of").
_VAGUE_AMOUNT = re.compile(r"\b(pair|couple|few|handful|bunch|several|dozen|lots|loads|plenty|heaps)\b(?= of\b| (?:more |extra |new |little |small |big )?[a-z]+s\b)")
# Words for closing a way off, which an arrangement does ("block the road", "cordon off the rubble").
_BARRIER = re.compile(r"\b(block\w*|clos(e|es|ing)|cordon\w*|fenc(e|es|ing)|barricad\w*|seal\w*|mark(s|ing)? (off|out)|line\w*|rows?)\b")
# Families for a thing that is already there (the ego, "car 1"): it is not added again.
_EXISTING: tuple[Family, ...] = ("position", "move", "appearance")
# Questions the request reader misses: misspelt openers ("wheres", "were is").
_QUESTION = re.compile(
    r"^\s*(wheres|were (is|are)|whats|wat|wich|hw|how (many|much)|is (there|any|some)\w*|are there|tel+ me|list)\b"
)
# Direction words -> the move field they set and its sign ("1.5 m south" is north -1.5).
DIRECTIONS: tuple[tuple[str, str, int], ...] = (
    (r"\beast(ward)?s?\b", "east", 1),
    (r"\bwest(ward)?s?\b", "east", -1),
    (r"\bnorth(ward)?s?\b", "north", 1),
    (r"\bsouth(ward)?s?\b", "north", -1),
    (r"\b(forwards?|ahead|further on)\b", "forward", 1),
    (r"\b(back(wards?)?|reverse)\b", "forward", -1),
    (r"\bleft\b", "left", 1),
    (r"\bright\b", "left", -1),
)
# Words that ask for a behaviour; without one, a new asset just stands where it is put.
_WAYS_OF_GOING = (r"driv\w*|park(ed|s)?|stall\w*|circl\w*|loop\w*|skidpad|cross(es|ing)?|jaywalk\w*|walk(s|ing)?"
                  r"|cut\w*|follow\w*|patrol\w*|lap\w*|cruis\w*|travel\w*|rid(e|es|ing)|speed|km/h|mph|m/s")
_BEHAVIOUR = re.compile(rf"\b(mov(e|es|ing)|{_WAYS_OF_GOING})\b")
# Behaviour words but "move" itself ("move the bin to the gate" only puts it there), and going somewhere.
_MOTION = re.compile(rf"\b(moving|{_WAYS_OF_GOING})\b"
                     r"|\b(go(es|ing)?|head(s|ing)?|set(s|ting)? off) (over |back |across |up |down |off |out )?(to|towards?|into|for)\b")
# "the", "that", ... just before a thing's name, a colour or size allowed ("the red bench").
_DEFINITE = re.compile(rf"\b(the|that|this|its|our|my|your|their|his|her)\s+((?:{'|'.join(COLOURS)}|big|small|little|large|old)\s+)?$")
# "a", "some", an amount just before a thing's name ("a couple of cars", "two little cones").
_INDEFINITE = re.compile(r"\b(an?|one|two|three|four|five|six|seven|eight|nine|ten|\d+|some|several|few|couple( of)?|pair( of)?"
                         r"|another|more|extra|new)\s+([a-z]+\s+)?$")
# Verbs that act on things already there: with one, "a car" may be one of the cars there.
_ACTS_ON = re.compile(r"\b(mov(e|es|ing)|shift\w*|relocat\w*|drag\w*|push\w*|pull\w*|take|bring|send|swap\w*|paint\w*"
                      r"|recolou?r\w*|turn\w*|rotat\w*|spin\w*|revers\w*|make|get|have|let)\b")
# What a question asks about -> the lookup that answers it; a distance asked is only measured.
_LOOKUPS: tuple[tuple[str, str], ...] = (
    (r"\b(weather|rain\w*|snow\w*|fog\w*|sunny|cloud\w*|wet|dry|time|clock|dark|bright|lights? (on|off))\b",
     "describe_environment"),
    (r"\blanes?\b", "find_lanes"),
    (r"\b(landmarks?|places?|buildings?|entrances?|gates?|crossings?|crosswalks?|car parks?|parking lots?)\b",
     "find_landmarks"),
)
_DISTANCE = re.compile(r"\bhow far\b|\bdistance\b|\bfar (away )?from\b")
# Words -> the behaviour they ask for; a way of going said with a place may be a path to it.
_BEHAVIOUR_KINDS: tuple[tuple[str, str], ...] = (
    (r"\b(circl\w*|loop\w*|laps?|doughnuts?|skidpad|(a)?round and (a)?round)\b", "circle"),
    (r"\b(jaywalk\w*|steps? out|darts? out)\b", "jaywalk"),
    (r"\bcross(es|ed|ing)?\b(?! ?roads?| ?walks?)|\bover to the other side\b", "cross_road"),
    (r"\bpark(ed|s)?\b|\bstationary\b", "parked"),
    (r"\b(driv\w*|cruis\w*|moving|rid(e|es|ing)|go(es|ing)?|head(s|ing)?|km/h|mph|m/s)\b", "drive_lane"),
)
# Words that pick one of several things by a place ("the tree by the bus stop", "the lamp that's at the gate").
_QUALIFIER = re.compile(r"\s*(?:,\s*the one\s+|(?:that|which)(?:'s| is| stands)\s+|standing\s+)?"
                        r"(?:by|near|next to|beside|at|outside|in front of|behind|on|closest to|nearest)\s+(?:the\s+)?")
# Words for how things look or for the weather, the time and the light: without any, no appearance edit.
_LOOKS = re.compile(r"\b(paint\w*|colou?r\w*|look\w*|light\w*|lamp\w*|bright\w*|dark\w*|dim\w*|night\w*|day\w*|morning|"
                    r"evening|afternoon|dusk|dawn|sunset|sunrise|noon|midnight|sun\w*|weather|rain\w*|snow\w*|fog\w*|cloud\w*|wet|"
                    r"storm\w*|sleet|hail|drizzl\w*|mist\w*|overcast|grim|gloom\w*|winter|summer|shin\w*|matte|metal\w*|wood\w*|"
                    r"plastic|material|finish|exposure|time|clock|o'clock|a\.m\.|p\.m\.)\b|\d:\d\d")  # "am" alone is "I am"
# Speeds (m/s) closer than this are one speed read twice ("12 mph" converted by two readers).
SAME_SPEED = 0.05
# A length's unit right after its number.
_LENGTH_UNIT = re.compile(r"\s*(m|metres?|meters?|mtrs?|km|kilometres?|kilometers?)\b(?!/)")
# Words that ask for a heading or a turn.
_TURNING = re.compile(r"\b(turn\w*|rotat\w*|fac(e|es|ing)|head(ing)?|degrees?|deg|yaw|spin\w*|angle)\b|°")
# Layout words -> the arrange shapes they mean.
SHAPES: tuple[tuple[str, tuple[str, ...]], ...] = (
    (r"\b(ring|circle|around|surround\w*|encircl\w*)\b", ("ring",)),
    (r"\b(grid|block|rows and columns|square)\b", ("grid",)),
    (r"\b(side by side|parking row|parked in a row)\b", ("parking_row",)),
    (r"\b(line|row|column|queue|file)\b", ("line", "parking_row")),
    (r"\b(edge|kerb|curb|along the lane)\b", ("lane_edge",)),
)


@dataclass(frozen=True)
class RequestNames:
    """The world's names and the numbers a request states, in the order it states them."""

    categories: tuple[str, ...] = ()
    # Asset ids named as the thing acted on ("the car 1", "the SUV's" ids come from categories).
    assets: tuple[str, ...] = ()
    # Landmarks, lanes and asset ids named as a place (after a relation word, or as a landmark).
    places: tuple[str, ...] = ()
    relations: tuple[str, ...] = ()
    numbers: tuple[float, ...] = ()
    # Of the numbers, those said as lengths ("25 m ahead", "ten metres") and as coordinates ("x=40"): no count.
    lengths: tuple[float, ...] = ()
    coordinates: tuple[tuple[str, float], ...] = ()
    # Numbers said as angles ("90 degrees"): only a heading or a turn takes them; speeds
    # ("6 m/s", "20 km/h", as m/s) only a speed.
    angles: tuple[float, ...] = ()
    speeds: tuple[float, ...] = ()
    weathers: tuple[str, ...] = ()
    # The weather's strength said ("a light drizzle", "thick fog"), 0-1.
    intensities: tuple[float, ...] = ()
    colours: tuple[str, ...] = ()
    # A clock time said ("7am", "quarter to five", "18:30"), as HH:MM: the only time a Jr. manager may set.
    times: tuple[str, ...] = ()
    # Move fields the request's direction words set, with their sign.
    directions: tuple[tuple[str, int], ...] = ()
    shapes: tuple[str, ...] = ()
    behaviour: bool = False
    turning: bool = False
    question: bool = False
    polarity: Literal["add", "remove"] | None = None
    # One clause whose verb only ever asks for new things ("add ...", "spawn ...").
    new_only: bool = False
    # Categories said of things already there, of which there are several ("the tree by the bus stop").
    existing: tuple[str, ...] = ()
    # Says a layout or a barrier ("in a row", "around", "block the road"): only then an arrangement.
    laid_out: bool = False
    # Says how far, which way, how fast or how something behaves ("3 m east", "drive", "turn"):
    # without any of it, "move the bin to the gate" puts the bin there, the move tools cannot.
    motion: bool = False
    # Describes something happening over time ("brake when the ego is 15 m away"): a storyboard.
    over_time: bool = False
    # The manoeuvres its words name ("brakes" is a stop, "changes lanes" a lane change).
    manoeuvres: tuple[str, ...] = ()
    # The behaviours its words ask for ("round and round" is a circle); () when it names none.
    behaviours: tuple[str, ...] = ()
    # Says how something looks, or the weather, the time or the light: only then an appearance edit.
    looks: bool = True
    # The lookups that answer what a question asks about ("how far" is measured); () when it names none.
    lookups: tuple[str, ...] = ()

    def kinds(self) -> list[Family]:
        """The requirement kinds the request's mood allows, in the Sr. manager's order: a
        question is a search (misspelt openers, "wheres the pool", are read as questions here
        too), a command without a removal word takes nothing away, an asset that exists is
        not added again."""
        if self.question:
            return ["search"]
        if self.over_time and self.assets and self.polarity is None:
            return ["move"]  # "have the ego stop after 3 s": only a storyboard plays it
        if (self.weathers or self.times) and not (self.categories or self.assets or self.existing or self.places):
            return ["appearance"]  # "make it rain", "make it 14:45": a setting, nothing to add or move
        if self.polarity == "remove":
            kinds = list(_TAKING_AWAY)
        elif (self.assets or self.existing) and set(self.categories) <= set(self.existing):
            kinds = list(_EXISTING)
        elif self.polarity == "add" or self.new_only:
            kinds = list(_NEW_ONLY if self.new_only else _PUTTING)
        else:
            # No removal word: nothing is taken away; and no question, so nothing is only looked up
            # ("a couple of cars parked up in lot A", "I'd like somewhere to rest by the doors").
            kinds = [f for f in FAMILIES if f not in ("remove", "search")]
        # "put the bus at the stop", "three cones 20 m ahead": no layout said, no arrangement of many;
        # a shape said ("in a circle round the fountain") is an arrangement, not things added one by one
        kinds = [f for f in kinds if f != "arrange" or self.laid_out] or kinds
        kinds = [f for f in kinds if f != "add" or not self.shapes or "arrange" not in kinds]
        # No distance, direction, speed or behaviour said: the move tools would change nothing; a way of
        # going said ("drive over to the library", "round and round") is no teleport.
        kinds = [f for f in kinds if f != "move" or self.motion or self.over_time] or kinds
        going = set(self.behaviours) & {"drive_lane", "follow_path", "circle", "cross_road", "jaywalk"}
        kinds = [f for f in kinds if f != "position" or not going or "move" not in kinds]
        # No word for a colour, the weather, the time or the light: no appearance edit ("something to do" is no headlights)
        return [f for f in kinds if f != "appearance" or self.looks] or kinds


def _relation(low: str, said: list[str]) -> list[str]:
    """The relations said, with the plainer one the slot reader leaves out ("at the west
    crossing" beside "in front of the ego")."""
    found = next((rel for pattern, rel in _PLAIN_RELATIONS if re.search(pattern, low)), None)
    if found == "on_sidewalk":  # "on the footway by the gate": by the gate, on the footway there
        said = [r for r in said if r not in ("next_to", "at")]
    # No relation word at all ("cones x3 lot A"): the thing goes at the place named.
    return list(dict.fromkeys([*said, *([found] if found else [])])) or ["at"]


def _definite(low: str, scene: Scene) -> list[tuple[str, bool, tuple[str, str] | None]]:
    """Each category the request names, in order, whether it says "the"/"that" of it ("the
    bench", "that truck": a thing already there, not a new one), and which one of those there
    the place said right after it picks ("the tree by the bus stop": the one nearest the stop), with that place."""
    said = ph.normalise(low)  # where find_categories counts from
    return [(m.category, definite, _qualified(said[m.end :], m.category, scene) if definite else None)
            for m in ph.find_categories(low) for definite in [_DEFINITE.search(said[: m.start]) is not None and not m.plural]]


def _qualified(after: str, category: str, scene: Scene) -> tuple[str, str] | None:
    """The thing of `category` nearest the landmark that `after` (the words right after its name)
    names with "by", "near", "at" ..., and that landmark; None when no landmark is named so."""
    said = _QUALIFIER.match(after)
    if said is None:
        return None
    rest = after[said.end() :]
    place = next((lm for lm in scene.landmarks for name in lm.names() if rest.startswith(ph.normalise(name).strip())), None)
    there = [a for a in scene.all_assets() if a.category == category]
    if place is None or not there:
        return None
    x, y = place.position
    return min(there, key=lambda a: (a.pose.x - x) ** 2 + (a.pose.y - y) ** 2).id, place.name


def _only_new(low: str) -> bool:
    """Whether every thing the request names is said with "a", "some" or an amount ("a couple of
    cars parked up in lot A") and no verb acts on things already there ("move a car to lot A")."""
    said = ph.normalise(low)
    mentions = ph.find_categories(low)
    return bool(mentions) and _ACTS_ON.search(said) is None and all(
        _INDEFINITE.search(said[: m.start]) is not None for m in mentions)


def _without_places(low: str, scene: Scene) -> str:
    """`low` with every landmark's names blanked."""
    for name in sorted({n.lower() for place in scene.landmarks for n in place.names()}, key=len, reverse=True):
        low = re.sub(rf"\b{re.escape(name)}\b", " ", low)
    return low


def _behaviours(low: str, somewhere: bool) -> tuple[str, ...]:
    """The behaviours `low` (its places blanked) asks for; driving with a place said may be a path there."""
    found = [kind for pattern, kind in _BEHAVIOUR_KINDS if re.search(pattern, low)]
    return tuple(found + (["follow_path"] if "drive_lane" in found and somewhere else []))


def _lookups(low: str, things: bool) -> tuple[str, ...]:
    """The lookups that answer what `low` asks about: a distance is measured; things named are
    found or described; weather and time, lanes, places each have their own."""
    if _DISTANCE.search(low):
        return ("measure_distance",)
    found = [tool for pattern, tool in _LOOKUPS if re.search(pattern, low)]
    things = things or re.search(r"\b(any(one|body)|some(one|body)|people|persons?|walk\w*|vehicles?|traffic)\b", low) is not None
    return tuple(found + (["find_assets", "asset_properties"] if things else []))


def read_names(prompt: str, scene: Scene) -> RequestNames:
    """What `prompt` names in `scene`: categories, assets, places, relations, numbers, mood."""
    slots = read_slots(prompt, scene).found
    request = read_request(prompt, scene)
    categories: list[str] = []
    assets: list[str] = []
    places: list[str] = []
    relations: list[str] = []
    numbers: list[float] = list(request.numbers)
    angles: list[float] = []
    speeds: list[float] = []
    weathers: list[str] = []
    colours: list[str] = []
    existing: list[str] = []
    intensities: list[float] = []
    qualifiers: list[str] = []  # places said only to pick a thing ("the tree by the bus stop")
    coordinates: list[tuple[str, float]] = []
    low = prompt.lower()
    mentions = _definite(low, scene)
    for kind, value in slots:
        if kind == "category":
            at = next((i for i, (said, _, _) in enumerate(mentions) if said == value), None)
            definite, which = (mentions[at][1], mentions[at][2]) if at is not None else (False, None)
            mentions = mentions if at is None else mentions[at + 1 :]
            qualifiers += [which[1]] if which else []
            there = [which[0]] if which else [a.id for a in scene.all_assets() if a.category == value]
            if definite and there and relations:
                places += there  # "next to the bench": the bench there (or one of the trees there) is the place
            elif definite and len(there) == 1 and _STRICT_NEW.search(low) is None:
                assets += there  # "put the trash bin next to ...", "the tree by the bus stop": that one moves
            else:
                categories.append(value)
                existing += [value] if definite and there and _STRICT_NEW.search(low) is None else []
        elif kind == "asset":
            # An asset after a relation word is where something goes ("in front of the ego").
            (places if relations else assets).append(value)
        elif kind in ("place", "lane"):
            places.append(value)
        elif kind == "relation":
            relations.append(value)
        elif kind == "angle":
            angles.append(float(value))
        elif kind == "speed":
            speeds.append(float(value))
        elif kind == "weather":
            weathers.append(str(value))
        elif kind == "intensity":
            intensities.append(float(value))
        elif kind in _NUMBER_SLOTS:
            numbers.append(float(value))
            coordinates += [(kind, float(value))] if kind in ("x", "y") else []
        elif kind == "colour" and re.search(rf"\b{value}\b", prompt.lower()):  # said, not implied by a thing
            colours.append(value)
    # "a few cones", "a couple of the lamps": the amount the rule planner reads for the words, a count to copy
    numbers += [float(lx.COLLECTIVE_COUNTS.get(w) or ph.NUMBER_WORDS[w]) for w in _VAGUE_AMOUNT.findall(request.low)]
    # A speed however its unit is written ("forty kilometres an hour", "at 8 ms"), as the rules read it, in m/s;
    # its figures (the unit's "an hour" too) are no count or length
    figures = spelt_measures(low)
    said = [*re.finditer(rf"({NUMBER})\s*{SPEED_UNIT}", figures), *[m for m in [speed_said(figures)] if m]]
    said_speeds = [n.value for m in said for n in numbers_in(m.group(0))]
    with suppress(PlanningError):
        speed = ph.find_speed(figures)
        speeds += [speed] if speed is not None and all(abs(speed - v) > SAME_SPEED for v in speeds) else []
    numbers = [n for n in numbers if n not in angles and n not in said_speeds and n not in speeds]
    # The request reader also reads "car" in "car 1" as a category: that car is an asset named.
    named_kinds = {found.category for a in [*assets, *places] if (found := scene.asset(a)) is not None}
    # The request reader's categories, but those only said inside a place's name ("the bus stop").
    unplaced = _without_places(low, scene)  # "the east gate" says no way to go, "the bus stop" no stop sign
    outside = {m.category for m in ph.find_categories(unplaced)}
    categories += sorted((request.categories & outside) - set(categories) - named_kinds)
    if request.place is not None:
        places.append(request.place)
    places = [p for p in places if p not in qualifiers] or places  # the bus stop picked the tree; it is no destination
    removal = REMOVE_WORDS.search(request.low) is not None and ADD_WORDS.search(request.low) is None
    shapes = next((shape for pattern, shape in SHAPES if re.search(pattern, low)), ())
    directions = tuple(dict.fromkeys((name, sign) for pattern, name, sign in DIRECTIONS if re.search(pattern, unplaced)))
    clock = clock_time(request.low)
    return RequestNames(
        categories=tuple(dict.fromkeys(categories)),
        assets=tuple(dict.fromkeys(assets)),
        places=tuple(dict.fromkeys(places)),
        relations=tuple(_relation(low, relations)),
        numbers=tuple(dict.fromkeys(numbers)),
        lengths=tuple(dict.fromkeys(n.value for n in numbers_in(low) if _LENGTH_UNIT.match(low, n.end))),
        coordinates=tuple(dict.fromkeys(coordinates)),
        colours=tuple(dict.fromkeys(colours)),
        times=(str(clock),) if clock is not None and clock.valid else (),
        directions=directions,
        shapes=shapes,
        behaviour=_BEHAVIOUR.search(low) is not None,
        turning=_TURNING.search(low) is not None,
        question=request.question or _QUESTION.match(low) is not None,
        angles=tuple(dict.fromkeys(angles)),
        speeds=tuple(dict.fromkeys(speeds)),
        weathers=tuple(dict.fromkeys(weathers)),
        intensities=tuple(dict.fromkeys(intensities)),
        polarity="remove" if removal else request.polarity if request.polarity == "add" else None,
        new_only=(_STRICT_NEW.search(request.low) is not None or _only_new(low)) and CLAUSE_JOINS.search(request.low) is None,
        laid_out=bool(shapes) or _BARRIER.search(low) is not None,
        existing=tuple(dict.fromkeys(existing)),
        motion=bool(numbers or angles or speeds or directions or _MOTION.search(low)),
        over_time=describes_behaviour_over_time(prompt, scene),
        manoeuvres=tuple(manoeuvres_said(unplaced)),
        lookups=_lookups(low, bool(categories or assets)),
        looks=bool(colours or weathers or clock is not None or _LOOKS.search(unplaced)),
        behaviours=_behaviours(unplaced, bool(places)),
    )


__all__ = ["CLAUSE_JOINS", "DIRECTIONS", "SHAPES", "RequestNames", "read_names"]
