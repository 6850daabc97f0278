"""Planning a question: what it asks for, in what relation, to what anchor; search calls only.

A question names what it wants (a landmark, assets of a category or any, lanes, a property such
as mass, size, colour or position), often a relation (nearest or closest to X, around or near X
within N m, on or blocking a lane or road, the lanes of a road) and an anchor (an asset id, the
ego, a landmark, a category with one instance there, the place of an earlier clause or turn). The
structure is read from the clause's `Reading` (rules/reading.py) and a few relation words; what
it names is never guessed from a phrase list. A compound question ("how heavy is X, and which Y is
nearest to it?") is one search per part, and a later part's "it" is what an earlier part was about
or found. A question never changes the scene: every call here is a search Worker's.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from typing import Any, Literal

from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning.intent import ASKED_ABOUT, PLACE_KIND, WHICH_KIND
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.edits import named_at, picked_by_what_it_stands_by
from drivetwin.orchestrator.planning.rules.environment import environment
from drivetwin.orchestrator.planning.rules.places import Notes, places_called, side_alone, side_lane
from drivetwin.orchestrator.planning.rules.reading import Reading, place_kind_said, read
from drivetwin.orchestrator.planning.rules.spelling import is_known, vocabulary
from drivetwin.tools.base import ToolCall
from drivetwin.tools.errors import ToolError
from drivetwin.tools.search import FindAssets, FindAssetsArgs
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.scene import EGO_ID, Scene

# Radius of a search "around" a place when the question gives none, metres: the campus's things
# that belong to a place (a bench at a stop, trees at a fountain) stand within it.
SEARCH_NEAR_M = 20.0
# What stands "at" or "in" an area (a lot, a quad): inside it or this close to its edge.
AREA_NEAR_M = 3.0

# A new question inside a clause: "..., and which landmark is closest to it".
_NEXT_PART = re.compile(r",?\s+(?:and|also|plus)\s+(?=(?:which|what|where|how|is|are|does|do|who|any)\b)")
# Relations, strongest first. Each is structure (a comparison, an obstruction, a neighbourhood),
# not a phrasing of a particular request.
_NEAREST = re.compile(r"\b(?:nearest|closest|most near|most close|nearer|closer|how far|(?P<furthest>furthest|farthest|most distant))\b")
_ON_LANE = re.compile(
    r"\b(?:block\w*|obstruct\w*|occupy\w*|in (?:the|its|our|their|my|his|her) way"
    r"|(?:on|in|across|along) (?:the |a |any |our )?(?:[a-z]+ )?(?:lanes?|roads?|streets?|carriageway))\b"
    # "is the road clear ahead of the ego", "is our lane free": whether anything stands on it
    r"|\b(?:lanes?|roads?|streets?|way) (?:\w+ ){0,4}?(?:clear|free|empty|open|passable)\b"  # "the road ahead (of the ego) clear"
)
# How far from a thing the road is looked along when a question names it ("is the road clear ahead of the ego").
ROAD_AHEAD_M = 40.0
# "of" after a word for an amount or a list ("the number of benches") names what is counted.
_AROUND = re.compile(r"\b(?:around|near|nearby|close to|next to|beside|by|at|in|inside|within|"
                     r"(?<!number )(?<!count )(?<!list )(?<!names )(?<!amount )(?<!total )of)\b")
_WITHIN = re.compile(r"\bwithin\s+(?:about\s+)?(\d+(?:\.\d+)?)\s*(?:m|metres?|meters?)\b")
_PREPOSITION = re.compile(r"\b(?:to|from|of)\b")
# A distance asked between two things ("how far is X from Y", "the distance between X and Y",
# "how far apart are X and Y"): one thing named is measured from the asker. A superlative asks
# which thing is nearest instead, and a range ("within 20 m") asks what is around.
# A way asked between two places ("which way is the fountain from here"): what a distance says too.
_WAY = r"which way|what way|(?:which|what) direction"
# A journey's length asked with "how long" ("how long is the walk from A to B", "how long a drive is it
# from the gate to lot B"): a distance, not a thing's length.
_JOURNEY = re.compile(r"\bhow long (?:\w+ ){0,6}?(?:walk|walking|drive|driving|ride|cycle|journey|trip)\b")
_DISTANCE = re.compile(rf"{_JOURNEY.pattern}|"
                       r"\b(?:how far|distance|measure (?:from|between)|far apart|far away|far off|far from|gap between|"
                       rf"{_WAY}|"  # the distance says the way too
                       r"stone'?s throw (?:from|to|of)|(?:a |long |short )?walk (?:from|to)|how many (?:metres|"
                       r"meters|feet|yards) (?:from|to|between|apart))\b|\bfar\s*\??\s*$"
                       r"|\bfrom\b.*\bto\b.*\bin (?:metres|meters|feet|yards)\W*$"  # "from us to the crosswalk, in metres"
                       r"|\bmeasure (?:the |a )?[a-z_0-9]+(?: [a-z_0-9]+)? (?:to|and) ")  # "measure the bench to the bin"
_SUPERLATIVE = re.compile(r"\b(?:nearest|closest|furthest|farthest|most near|most close|nearer|closer)\b")
_ENDS = re.compile(r"\b(?:from|to|and|between|apart)\b")
_ASKER_ALONE = re.compile(r"^\W*(?:me|us|i|we|here)\W*$")
# A road named as where things are, by its name ("the stop signs on Campus Drive").
_ALONG = re.compile(r"\b(?:on|along|alongside|beside|lining|lines?|down)\s+(?:the\s+)?[a-z]+\s+(?:street|drive|road|avenue|lane|way|st|rd|ave)\b")
# Lights said alone with a place after them: the street lights there (not "traffic lights", "headlights").
_LIGHTS_BY = re.compile(r"(?<!street )(?<!traffic )(?<!vehicle )(?<!car )(?<!head)\b(?:lights|lamps)(?=\s+(?:near|by|around|at|next to|close to|beside)\b)")
# A thing named after "anything ... that would" is what the anything acts on, not what is looked for.
_AFFECTED = re.compile(r"\b(?:anything|something|stuff|whatever)\b.*\b(?:that|which)\s+(?:would|could|might|will|can|may|is|are|blocks?|forces?|stops?|gets?)\b")
_ANYTHING = re.compile(r"\b(?:any|anything|something|anyone|anybody|someone|somebody|what|whatever|stuff)\b")
# How full a place is ("how busy is the car park", "is the bus stop crowded"): what stands there.
_BUSY = re.compile(r"\b(?:busy|busier|full|crowded|packed|empty|quiet|occupied|deserted|free spaces?|room left)\b")
# What a question can ask for by kind rather than by name.
_LANE_KIND = re.compile(r"\blanes?\b")
# A lane named as where something is: the object of "on", "in", "along" ("in the northbound lane").
_LANE_AS_PLACE = re.compile(r"\b(?:on|in|along|across|into|onto|block\w*|occupy\w*|obstruct\w*)\s+(?:(?:the|a|any|our|its|either)\s+)?(?:\S+\s+)?$")
_ROAD_KIND = re.compile(r"\b(?:roads?|streets?)\b")
_PLACE_KIND = PLACE_KIND
_ANY_KIND = re.compile(rf"\b(?:{'|'.join(lx.GENERIC_THINGS)}|what|what's|whats|who)\b")
_WHERE = re.compile(r"\b(?:where|located|location|position|coordinates)\b")
# Properties beyond the size and mass words of the lexicon: look, pose and motion.
_PROPERTY = re.compile(r"\b(?:colou?r|which way|heading|facing|how fast|speed|pace|behaviou?r|doing|pose|yaw)\b")
# Words that point back: to an earlier part or clause ("it", "there") or to the asker ("us").
_BACK = re.compile(r"\b(?:it|its|them|they|those ones|that one|that spot|that place|here)\b"
                   r"|(?<!is )(?<!are )(?<!was )(?<!were )\bthere\b(?!\s*(?:is|are|was|were|'s|be)\b)")
_PLURAL_BACK = re.compile(r"\b(?:they|them|those|these)\b")
_PLACE_POINTERS = frozenset({"there", "here", "that spot", "that place"})
# A clause that only points back at what earlier ones asked about ("how many of each"); "where are
# they" after a clause that only names them is their own question.
_OF_EACH = re.compile(r"\b(?:each|both)\b")
_ASKER = re.compile(r"\b(?:(?:to|from|near|nearest|closest|around|by|of|beside) (me|us)|where am i|where are we)\b")
_DEFINITE = re.compile(r"\b(?:the|that|this|our|my|your)\s+(?:[a-z]+\s+){0,2}$")

Kind = Literal["asset", "landmark", "lane", "point"]


@dataclass(frozen=True)
class Anchor:
    """What a relation is measured from: an asset id (the ego included), a landmark, a lane, x,y."""

    kind: Kind
    name: str


@dataclass(frozen=True)
class Part:
    """One question's search, what a later "it" refers to, and the assets it finds."""

    call: ToolCall
    referent: Anchor | None
    found: tuple[str, ...] = ()


# A question about how the world is now, not a wish ("is it raining?"; "bit of drizzle?" asks for it).
_ASKS_HOW_IT_IS = re.compile(r"\s*(?:(?:so|ok|and|hey)\W+)*(?:what|what's|whats|how|hows|is|are|was|does|do|which|when|tell me|can you tell)\b")
# The settings a question can ask about by their general words.
# Things switched with the lights setting, and a question about whether they are on.
_SWITCHED = frozenset({"street_light"})
_ON_OFF = re.compile(r"\b(?:on or off|off or on|switched on|turned on|lit|on|off)\s*[?.!]*\s*(?:right now|now|at the moment)?\s*[?.!]*\s*$"
                     r"|\b(?:are|is) (?:the |all the |any of the )?(?:street ?)?(?:lights?|lamps?) (?:on|off|lit)\b")
# A clause of a question that is only a setting's word ("time + weather?", "the weather?").
# ("lights?" alone asks for the street lights, things of the scene.)
_SETTING_ALONE = re.compile(r"\W*(?:and\s+|the\s+)*(?:weather|time|environment|conditions)"
                            r"(?:\W+(?:and\W+)?(?:the\s+)?(?:weather|time|lighting|environment|conditions))*\W*$")
_SETTING = re.compile(r"\b(?:weather|time of day|what time|the time|the hour|how (?:dark|bright|light)|(?:how|what)(?:'s| is) the (?:light|lighting|visibility)"
                      r"|lights? (?:on|off)|lit|environment|conditions|(?:it|things) like out(?: there| here|side)?)\b")


# The clock asked with any question word, however spelt: "wat time is it", "wah time it is inna di scene".
_CLOCK_ASKED = re.compile(r"\W*[a-z']+\s+time\s+(?:is it|it is|it be|now)\b")


# One thing's distance to either of two ("is the SUV closer to the library or the union?") or two
# things' distance to one ("which is nearer the bench, the bin or the tree?").
_EITHER_OF_TWO = re.compile(r"\b(?:closer|nearer|further|farther)\s+(?:to\s+|from\s+)?(?P<a>[^,?.!]+?)\s+or\s+(?P<b>[^,?.!]+)")
_TWO_TO_ONE = re.compile(r"\b(?:closer|nearer|further|farther)\s+(?:to\s+|from\s+)?(?P<s>[^,?.!]+),\s*(?P<a>[^,?.!]+?)\s+or\s+(?P<b>[^,?.!]+)")


def _two_distances(r: Reading, scene: Scene) -> list[ToolCall] | None:
    """measure_distance from the one thing or place a comparison is about to each of the two it
    names with "or"; None when the clause compares no such two."""
    two = _TWO_TO_ONE.search(r.low)
    if two is not None:
        subject = named_at(scene, f" {two.group('s')}", [])
    elif (two := _EITHER_OF_TWO.search(r.low)) is not None:
        before = re.sub(r"^\s*(?:so\s+|and\s+|then\s+)?(?:is|are|was|were|would|will)\s+", " ", r.low[: two.start()])
        subject = named_at(scene, f" {before.strip()}", [])
    else:
        return None
    ends = [named_at(scene, f" {two.group(k).strip()}", [subject or ""]) for k in ("a", "b")]
    if subject is None or None in ends or len({subject, *ends}) < 3:
        return None
    return [ToolCall(tool="measure_distance", args={"a": subject, "b": end}) for end in ends if end is not None]


# "which is closer to the ego, the bench or the bin?": two things named, each measured from the one place.
_COMPARED = re.compile(r"\bwhich(?: one)?\b.*\b(?:closer|nearer|further|farther)\b.*\bor\b")
MAX_COMPARED = 4


def plan_question(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall]:
    """The search calls that answer a question clause: one per part of a compound question."""
    if not r.mentions and (bare := _LIGHTS_BY.search(r.text.lower())) is not None:  # "lights near the bus stop?": the lamps there
        r = read(r.text[: bare.start()] + "street lights" + r.text[bare.end() :], scene)
    added = _just_added(r, scene, memory)
    if added:  # "where is the vehicle I just added?": that one, of whatever kind the group word covers
        return [ToolCall(tool="asset_properties", args={"asset": i}) for i in added]
    texts = [t for t in _NEXT_PART.split(r.text) if t.strip(" ,")]
    if len(texts) > 1:  # "which way and how": a part that names nothing belongs to the question before
        readings = [read(t, scene) for t in texts]
        kept = [t for t, reading in zip(texts, readings, strict=True) if not _names_nothing(reading)
                or _BACK.search(reading.masked) or reading.has(lx.PROPERTY_WORDS) or _PROPERTY.search(reading.low)
                or _SETTING_ALONE.match(reading.low) or _SETTING.search(reading.low)]
        texts = kept if kept else texts[:1]
    kinds = list(dict.fromkeys(m.category for m in r.mentions))
    compared = _COMPARED.search(r.low)
    if compared is not None and len(kinds) >= 2:
        # "which is further from the ego, the bench or the bin?": how far each is, the nearest of its kind
        reference = r.landmark or next(iter(r.ids), None) or "ego"
        return [ToolCall(tool="find_assets", args={"category": k, "nearest_to": reference}) for k in kinds[:MAX_COMPARED]]
    between = _two_distances(r, scene)
    if between is not None:  # "is the SUV closer to the library or the union?": how far it is from each place
        return between
    if len(texts) == 1 and len(kinds) > 1 and not r.ids and (r.has(lx.PROPERTY_WORDS) or _PROPERTY.search(r.low)):
        # "the weights of both a truck and a bus": the property of each thing named
        return [_property(replace(r, mentions=[m for m in r.mentions if m.category == k][:1]), scene, None).call
                for k in kinds]
    earlier: Anchor | None = None
    origin: Anchor | None = None  # what the last "nearest" question measured from
    calls: list[ToolCall] = []
    for text in texts:
        reading = r if texts == [r.text] else read(text, scene)  # a part kept alone is read alone
        part = _plan_part(reading, scene, memory, notes, earlier, origin)
        if part is None:
            continue
        near = part.call.args.get("nearest_to") if part.call.tool == "find_assets" else None
        if isinstance(near, str):  # "the nearest hydrant to the Library, and how far is it": from the Library
            origin = Anchor("landmark" if scene.landmark(near) is not None else "asset", near)
        calls.append(_on_side(of_group(part.call, reading), reading, scene))
        earlier = part.referent or earlier
        if part.found:
            notes.subject = list(part.found)  # what a later clause's "them" or "each" means
    if calls and _SETTING.search(r.low) and not any(c.tool == "describe_environment" for c in calls):
        calls.append(ToolCall(tool="describe_environment", args={}))  # "a count of everything, and the weather too"
    return calls


def _on_side(call: ToolCall, r: Reading, scene: Scene) -> ToolCall:
    """A search on the side the words name: with no road named ("the trees on the east side"), the
    side of the road nearest each; of things that line a road named ("the street lights on the north
    side of Main Street"), those beside that side's lane."""
    if call.tool != "find_assets" or any(k in call.args for k in ("lane", "near", "nearest_to", "side")):
        return call
    way = side_alone(r.low)
    if way is not None:  # "any trees on the east side?": the side of the road nearest each
        return call.model_copy(update={"args": {**call.args, "side": way}})
    category = str(call.args.get("category"))
    lane = side_lane(r.low, scene) if category in catalog() and catalog()[category].placement == "sidewalk" else None
    # a car "on the east side of Campus Drive" may stand anywhere east, not only by the kerb
    return call if lane is None else call.model_copy(update={"args": {**call.args, "lane": lane}})


def of_group(call: ToolCall, r: Reading) -> ToolCall:
    """A search for a category that the words name as a whole kind ("which vehicles are parked
    there"): made a search for the kind, said in the plural as the Worker takes it."""
    said = call.args.get("category")
    groups = [tag for tag, members in md.groups_said(r.low).items() if said is None or said in members]
    if call.tool != "find_assets" or len(groups) != 1 or (said is None and (r.mentions or "nearest_to" in call.args)):
        return call
    return call.model_copy(update={"args": {**call.args, "category": groups[0] + "s"}})


# A choice between two states of the light or the weather: "day or night?", "in the dark, or still daytime?".
_STATES = r"(?:dark|darkness|daytime|day|daylight|night|night-?time|light|bright|raining|rainy|dry|sunny|foggy|snowing|snowy|wet|clear|cloudy)"
_SETTING_EITHER = re.compile(rf"\b{_STATES}\b[^.?!]*\bor\b[^.?!]*\b{_STATES}\b")
# A place asked for by which of its kind it is: "which car park ...", "which marked pedestrian crossing ...".
_WHICH_PLACE = re.compile(r"\bwhich\s+(?:[a-z]+\s+){0,2}$")
# A superlative of size or weight: "the tallest thing", "which car is the heaviest" (as find_assets orders by).
# Where to cross a road on foot: "where can people cross the road?", "where should I cross?".
_WHERE_TO_CROSS = re.compile(r"\bwhere\s+(?:can|could|should|do|does|would|may|might|are|is)\s+(?:[a-z']+\s+){1,3}?cross\b")
# Where to park: "where could I park a truck?", "where do people leave their cars?" asks for the parking lots.
_WHERE_TO_PARK = re.compile(r"\bwhere\s+(?:can|could|should|do|does|would|may|might|is it ok to)\s+(?:[a-z']+\s+){0,2}?park\b")


def _plan_part(r: Reading, scene: Scene, memory: Memory, notes: Notes, earlier: Anchor | None,
               origin: Anchor | None = None) -> Part | None:
    low = r.low
    asked_about = ASKED_ABOUT.search(r.masked)
    if asked_about and not is_known(asked_about.group(1), vocabulary(scene)) and not _PLACE_KIND.fullmatch(asked_about.group(1)) \
            and not any(m.start <= asked_about.start(1) < m.end for m in r.mentions):  # "the nearest landmark" is a place
        # "how many helicopters are parked?", "how far's the nearest servo?", "any roos about?": about
        # a thing this world has no word for, so no count and no nearest thing of another kind
        from drivetwin.orchestrator.planning.base import PlanningError  # rules/__init__ imports the planner

        raise PlanningError(f"there is no {asked_about.group(1)!r} in this world; things here are such as "
                            f"{', '.join(sorted({a.category for a in scene.assets})[:8])}")
    if _names_nothing(r) and ((_ASKS_HOW_IT_IS.match(low) and (_SETTING.search(low) or environment(r, scene.environment)))
                              or _SETTING_ALONE.match(low) or _CLOCK_ASKED.match(low)):
        return Part(ToolCall(tool="describe_environment", args={}), None)  # "is it raining?", "what's the weather like"
    if _SETTING_EITHER.search(low) and not r.mentions:  # "am I doing this run in the dark, or is it still daytime?"
        return Part(ToolCall(tool="describe_environment", args={}), None)
    most = md.SIZE_SUPERLATIVE.search(low)
    if most is not None and not _NEAREST.search(low) and not re.search(r"\b(?:lanes?|roads?|streets?|buildings?|landmarks?|places?)\b", r.masked):
        # "which car is the heaviest?", "the smallest sign": every one of the kind, by its figure
        head = r.mentions[0] if r.mentions else None
        word = ph.singular(r.low[head.start : head.end].strip()) if head is not None else next(
            (w for w in map(ph.singular, ph.tokens(low)) if w in md.catalog_tags()), "")
        kind = f"{word}s" if word in md.catalog_tags() else head.category if head is not None else None
        ranked: dict[str, Any] = {"most": md.most_said(most.group(1)), **({"category": kind} if kind else {})}
        if r.landmark:  # "the heaviest vehicle in lot B": of those there
            ranked.update(near=r.landmark, within=_radius(scene, Anchor("landmark", r.landmark)))
        return Part(ToolCall(tool="find_assets", args=ranked), None)
    if _WHERE_TO_CROSS.search(low) and {m.category for m in r.mentions} <= {"pedestrian"}:
        # "where can people cross the road?": the marked crossings, nearest the place said first
        near = {"nearest_to": r.landmark} if r.landmark else {}
        return Part(ToolCall(tool="find_landmarks", args={"query": "crossing", **near}), None)
    if _WHERE_TO_PARK.search(low):  # "where could I park a truck?": the parking lots, nearest the place said first
        near = {"nearest_to": r.landmark} if r.landmark else {}
        return Part(ToolCall(tool="find_landmarks", args={"query": "parking lot", **near}), None)
    if r.mentions and {m.category for m in r.mentions} <= _SWITCHED and _ON_OFF.search(low):
        return Part(ToolCall(tool="describe_environment", args={}), None)  # "street lamps - on or off right now?"
    named = _named(r, scene)
    back = _back_reference(r, scene, memory, notes, earlier)
    if _names_nothing(r) and _OF_EACH.search(r.masked) and notes.subject:
        return None  # "bins? benches? how many of each": the earlier clauses already ask it
    if _WAY_ASKED.search(low) and re.search(r"\b(?:from|to)\b", low) and (way := _distance(r, scene, back)) is not None:
        return way  # "which way is the fountain from the bus stop": not which way a thing faces
    if _PAIR.search(low) and (both := _BOTH_PLACES.search(low)) is not None and len(two := places_called(scene, ph.singular(both.group(1)))) == 2:
        # "how far apart are the two gates?": the two places of that kind
        return Part(ToolCall(tool="measure_distance", args={"a": two[0], "b": two[1]}), Anchor("landmark", two[0]))
    asks_property = (r.has(lx.PROPERTY_WORDS) or _PROPERTY.search(low) is not None) and not _JOURNEY.search(low)
    if asks_property and not r.mentions and not r.ids and not r.ego and (
            r.lane or _asks_for_lanes(r)):  # "how wide is the lane on Main Street": the lanes' facts
        return Part(_lanes(r, scene, back), None)
    if asks_property:
        return _property(r, scene, named or back)
    if _DISTANCE.search(low) and not _SUPERLATIVE.search(low) and not _WITHIN.search(low):
        measured = _distance(r, scene, back, origin)
        if measured is not None:
            return measured
    nearest = _NEAREST.search(low)
    if nearest is not None and nearest.group(0) == "how far" and (closest := _NEAREST.search(low, nearest.end())) is not None:
        nearest = closest  # "how far away is the closest tree": the closest one, then how far
    if nearest is not None:
        anchor = _anchor_after(r, scene, nearest.end(), back, prefer_preposition=True)
        head = next((m for m in r.mentions if m.start >= nearest.end()), None)
        right_after = head is not None and not r.low[nearest.end() : head.start].strip()  # "nearest bin", not "nearest the bin"
        if anchor is not None and head is not None and right_after and anchor.name == _only_instance(r, scene, head):
            # "where's the nearest bin": nearest the asker, not itself; "the closest bin too the stop": the stop
            later = [e for pos, e in _entities(r, scene, back) if pos > head.end and e.name != anchor.name]
            anchor = later[0] if later else Anchor("asset", EGO_ID)
        if anchor is None and head is not None and right_after:
            anchor = Anchor("asset", EGO_ID)  # "how far away is the closest tree": from the car the scene is seen from
        if anchor is not None:
            return _nearest(r, scene, anchor, furthest=nearest.group("furthest") is not None)
    # "stop signs on Campus Drive", "is anything parked on Campus Drive": what stands on that road
    anything = not r.mentions and _ANYTHING.search(low) is not None
    on_road = (r.mentions or anything) and _road_named(r, scene) is not None and _ALONG.search(low) is not None
    if (_ON_LANE.search(low) is not None or on_road) and not _asks_for_lanes(r):
        args: dict[str, Any] = {"on_lane": True}
        road = _road_named(r, scene) or (back.name if back is not None and back.kind == "lane" else None)
        if road is not None:
            args["lane"] = road
        if r.mentions and not _AFFECTED.search(low[: r.mentions[0].start]):
            args["category"] = r.mentions[0].category  # not "anything in the road that would block a cyclist": who it blocks
        if r.landmark:  # "is the road blocked near the east gate": only that stretch
            args.update(near=r.landmark, within=_radius(scene, Anchor("landmark", r.landmark)))
        elif r.ego and road is None:  # "is the road clear ahead of the ego": its stretch of road
            args.update(near="ego", within=ROAD_AHEAD_M)
        return _found(ToolCall(tool="find_assets", args=args), scene)
    if _asks_for_lanes(r) or (_ROAD_KIND.search(r.masked) and not r.mentions and not r.landmark):
        return Part(_lanes(r, scene, back), None)
    around = _AROUND.search(low)
    anchor = _anchor_after(r, scene, around.end(), back) if around is not None else None
    busy = _BUSY.search(low) is not None
    if anchor is None and r.landmark and (r.mentions or _ANY_KIND.search(r.masked) or busy):
        anchor = Anchor("landmark", r.landmark)  # "what signals control the crossroads", "how busy is lot A"
    if anchor is not None and not _WHERE.search(low):
        kind = place_kind_said(r, scene)
        if (_PLACE_KIND.search(r.masked) or kind) and not r.mentions:  # "which buildings are near the fountain"
            # "is there a crossing near the library": the crossings, nearest first
            return Part(ToolCall(tool="find_landmarks", args={"nearest_to": anchor.name, **({"query": kind} if kind else {})}), anchor)
        if r.mentions or _ANY_KIND.search(r.masked) or anchor.kind != "landmark" or busy:
            return _around(r, scene, anchor)
    return _what_or_where(r, scene, named, back, notes.subject, memory.last_touched())


# A thing said to be the one just made: "the vehicle I just added", "the bench you put", "the cones just added".
_ADDED_BACK = re.compile(r"^\s*(?:that\s+|which\s+)?(?:(?:i|you|we)\s+(?:just\s+|have\s+|'ve\s+)?|just\s+|newly\s+|recently\s+)"
                         r"(?:added|put|placed|made|created|spawned)\b")


def _just_added(r: Reading, scene: Scene, memory: Memory) -> list[str]:
    """The things the last turn added that a thing named as just added means ([] when none is named so)."""
    mention = next((m for m in r.mentions if _ADDED_BACK.match(r.low[m.end :])), None)
    if mention is None:
        return []
    word = ph.singular(r.low[mention.start : mention.end].strip())  # "the vehicle": any kind the catalog tags so
    recent = [i for i in memory.last_added() if (a := scene.asset(i)) is not None
              and (a.category == mention.category or (word in md.catalog_tags() and word in catalog()[a.category].tags))]
    return recent if mention.plural else recent[-1:]


def _names_nothing(r: Reading) -> bool:
    return not (r.mentions or r.ids or r.ego or r.landmark or r.landmark_word or r.lane
                or _LANE_KIND.search(r.masked) or _PLACE_KIND.search(r.masked))


def _named(r: Reading, scene: Scene) -> Anchor | None:
    """The one thing a clause names outright: an asset id, the ego, a landmark."""
    if r.ids:
        return Anchor("asset", r.ids[0])
    if r.ego or _ASKER.search(r.low):
        return Anchor("asset", EGO_ID)
    if r.landmark:
        return Anchor("landmark", r.landmark)
    return None


def _back_reference(r: Reading, scene: Scene, memory: Memory, notes: Notes, earlier: Anchor | None) -> Anchor | None:
    """What "it" or "there" refers to: an earlier part of the question, else for a place word
    ("there") the place an earlier clause or the last edit was at, for a thing ("it", "them")
    the assets an earlier clause found or the last turn added."""
    pointer = _BACK.search(r.masked)
    if pointer is None:
        return None
    if earlier is not None:
        return earlier
    place_meant = pointer.group(0).strip() in _PLACE_POINTERS
    for reference in (_place_referent, _thing_referent) if place_meant else (_thing_referent, _place_referent):
        found = reference(scene, memory, notes)
        if found is not None:
            return found
    return None


def _place_referent(scene: Scene, memory: Memory, notes: Notes) -> Anchor | None:
    if notes.place is not None and notes.place.get("target"):
        target = str(notes.place["target"])
        kind: Kind = "landmark" if scene.landmark(target) else "lane" if scene.roads.lane(target) else "asset"
        return Anchor(kind, target)
    focus = memory.last_focus()
    return Anchor("point", f"{focus[0]:.2f},{focus[1]:.2f}") if focus is not None else None


def _thing_referent(scene: Scene, memory: Memory, notes: Notes) -> Anchor | None:
    present = [i for i in [*notes.subject, *memory.last_added()] if scene.asset(i) is not None]
    return Anchor("asset", present[0]) if present else None


def _entities(r: Reading, scene: Scene, back: Anchor | None) -> list[tuple[int, Anchor]]:
    """Everything a relation could be measured from, with where the clause names it."""
    found: list[tuple[int, Anchor]] = []
    for asset_id in r.ids:
        found.append((max(0, r.low.find(asset_id)), Anchor("asset", asset_id)))
    if r.ego:
        found.append((r.ego_at, Anchor("asset", EGO_ID)))
    asker = _ASKER.search(r.low)
    if asker is not None and not r.ego:
        found.append((asker.start(1) if asker.group(1) else asker.start(), Anchor("asset", EGO_ID)))
    if r.landmark:
        found.append((r.landmark_at, Anchor("landmark", r.landmark)))
    for mention in r.mentions:
        only = _only_instance(r, scene, mention)
        if only is not None:
            found.append((mention.start, Anchor("asset", only)))
    pointer = _BACK.search(r.masked)
    if back is not None and pointer is not None:
        found.append((pointer.start(), back))
    return sorted(found, key=lambda f: f[0])


def _only_instance(r: Reading, scene: Scene, mention: ph.Mention) -> str | None:
    """The asset a definite mention names when the scene holds exactly one of its category."""
    present = [a.id for a in scene.assets if a.category == mention.category]
    if len(present) > 1 and _DEFINITE.search(r.low[: mention.start]):  # "what colour is the lamp by the bus stop?"
        return picked_by_what_it_stands_by(r, scene, mention)
    return present[0] if len(present) == 1 and _DEFINITE.search(r.low[: mention.start]) else None


def _anchor_after(r: Reading, scene: Scene, at: int, back: Anchor | None,
                  prefer_preposition: bool = False) -> Anchor | None:
    """The thing a relation at `at` is measured from: named after its "to/from" ("nearest car
    to the ego"), else right after it, else (for "which landmark is the ego closest to") before."""
    entities = _entities(r, scene, back)
    if prefer_preposition:
        prep = _PREPOSITION.search(r.low, at)
        if prep is not None:
            after = [e for pos, e in entities if pos >= prep.start()]
            if after:
                return after[0]
    after = [e for pos, e in entities if pos >= at]
    if after:
        return after[0]
    before = [e for pos, e in entities if pos < at and prefer_preposition]
    return before[-1] if before else None


def _property(r: Reading, scene: Scene, subject: Anchor | None) -> Part:
    """asset_properties of the thing asked about: an asset named or the only one of a category
    named with "the", else the category; a place's position is its landmark."""
    if r.mentions and not r.ids:
        mention = r.mentions[0]
        only = _only_instance(r, scene, mention)
        if only is not None:
            return Part(ToolCall(tool="asset_properties", args={"asset": only}), Anchor("asset", only))
        return Part(ToolCall(tool="asset_properties", args={"category": mention.category}), None)
    if subject is not None and subject.kind == "landmark":
        return Part(ToolCall(tool="find_landmarks", args={"query": subject.name}), subject)
    asset = subject.name if subject is not None and subject.kind == "asset" else EGO_ID
    return Part(ToolCall(tool="asset_properties", args={"asset": asset}), Anchor("asset", asset))


def _nearest(r: Reading, scene: Scene, anchor: Anchor, furthest: bool = False) -> Part:
    """What is nearest the anchor (or `furthest` from it), of the kind asked for: a landmark, a lane, assets."""
    # "my students wait at the stop: which bench is closest to them?": the kind said after "which" is the one asked for
    asked = [m for m in r.mentions if WHICH_KIND.search(r.low[: m.start])]
    mentions = asked[:1] or r.mentions
    kind_at = {m.start: m for m in mentions}
    lane = _LANE_KIND.search(r.masked)
    kind_word = place_kind_said(r, scene)
    # "what's the nearest building to the suv": the kind is "building", the superlative the question's own
    kind_word = re.sub(r"^(?:the\s+)?(?:nearest|closest|furthest|farthest)\s+", "", kind_word) if kind_word else kind_word
    place = _PLACE_KIND.search(r.masked) or (re.search(re.escape(kind_word), r.masked) if kind_word else None)
    subject_landmark = r.landmark if r.landmark and r.landmark != anchor.name else None
    firsts = [(m.start, "category") for m in kind_at.values() if _only_instance(r, scene, m) != anchor.name]
    firsts += [(lane.start(), "lane")] if lane else []
    firsts += [(place.start(), "landmark")] if place else []
    firsts += [(r.landmark_at, "landmark")] if subject_landmark else []
    kind = min(firsts)[1] if firsts else "any"
    if kind == "lane":
        return Part(ToolCall(tool="find_lanes", args={"near": anchor.name}), anchor)
    if kind == "landmark":
        args: dict[str, Any] = {"nearest_to": anchor.name}
        if subject_landmark or kind_word:  # "how far is the bus stop from us", "which gate is nearest"
            args["query"] = subject_landmark or kind_word
        said = _WHICH_PLACE.search(r.low[: r.landmark_at]) if subject_landmark else None
        mark = scene.landmark(subject_landmark) if said is not None and subject_landmark else None
        alias = next((n for n in mark.names() if r.low.startswith(ph.normalise(n).strip(), r.landmark_at)), None) if mark else None
        if alias is not None:  # "which car park is closest": the place called so, and those of its kind (the Worker compares them)
            args["query"] = alias
        return Part(ToolCall(tool="find_landmarks", args=args), anchor)
    args = {"furthest_from" if furthest else "nearest_to": anchor.name}
    category = next((m.category for m in mentions if _only_instance(r, scene, m) != anchor.name), None)
    if category is not None:
        args = {"category": category, **args}
    within = _WITHIN.search(r.low)
    if within is not None:
        args["within"] = float(within.group(1))
    return _found(ToolCall(tool="find_assets", args=args), scene)


def _distance(r: Reading, scene: Scene, back: Anchor | None, origin: Anchor | None = None) -> Part | None:
    """measure_distance between the two things a clause names, each read on its own side of
    "from", "to", "and" or "between"; one thing named is measured from the asker (the ego), or
    from the `origin` an earlier "nearest" question measured from when it is the thing found."""
    kinds = {m.category for m in r.mentions}
    pair = [a.id for a in scene.assets if a.category in kinds] if len(kinds) == 1 and _PAIR.search(r.low) else []
    if len(pair) == 2:  # "distance between the two traffic lights": the two there are
        return Part(ToolCall(tool="measure_distance", args={"a": pair[0], "b": pair[1]}), Anchor("asset", pair[0]))
    ends: list[Anchor] = []
    for piece in _ENDS.split(r.text.lower()):
        if _ASKER_ALONE.match(piece):
            found: Anchor | None = Anchor("asset", EGO_ID)
        else:
            side = read(piece, scene)
            only = next((i for m in side.mentions if (i := _only_instance(side, scene, m)) is not None), None)
            found = _named(side, scene) or (Anchor("asset", only) if only else None)
            if found is None and _BACK.search(side.masked):
                found = back
        if found is not None and found not in ends:
            ends.append(found)
    if not ends:
        return None
    asker = len(ends) == 1
    if asker:
        if ends[0].name == EGO_ID:
            return None
        ends.append(origin if origin is not None and ends[0] == back and origin != back else Anchor("asset", EGO_ID))
    low = r.text.lower()
    if _WAY_ASKED.search(low) and (asker or (re.search(r"\bfrom\b", low) and not re.search(r"\bfrom\b.*\bto\b", low))):
        ends.reverse()  # "which way is the fountain from the bus stop": from the stop (or the asker) to the fountain
    return Part(ToolCall(tool="measure_distance", args={"a": ends[0].name, "b": ends[1].name}), ends[0])


_WAY_ASKED = re.compile(rf"\b(?:{_WAY})\b")
# Two things of one kind measured against each other: "between the two lights", "how far apart are both cars".
# The two places of a kind: "the two gates", "both entrances".
_BOTH_PLACES = re.compile(r"\b(?:the two|both(?: the)?|the 2|the pair of)\s+([a-z]+)\b")
_PAIR = re.compile(r"\b(?:between|apart)\b.*\b(?:the two|both|the 2|the pair of)\b|\b(?:the two|both|the 2)\b.*\bapart\b")


# A question about people: "who is near the fountain?", "who's waiting at the stop?".
_WHO = re.compile(r"\s*(?:who|who's|whos)\b")
# What only vehicles do: "who's parked up in the car park?" asks about the cars.
_DRIVEN = re.compile(r"\b(?:park(?:ed|s|ing)|driv\w*|drove)\b")


def _around(r: Reading, scene: Scene, anchor: Anchor) -> Part:
    """Assets (of the category named, if any) within a radius of the anchor, nearest first."""
    args: dict[str, Any] = {}
    category = next((m.category for m in r.mentions if _only_instance(r, scene, m) != anchor.name), None)
    if category is None and _WHO.match(r.low) and not _DRIVEN.search(r.low):
        category = "pedestrian"  # "who is standing near the fountain?": people, not the trees ("who's parked ...": whatever is)
    if category is not None:
        args["category"] = category
    # An asset is left out of its own neighbourhood: nearest_to excludes it, near would list it.
    args["nearest_to" if anchor.kind == "asset" else "near"] = anchor.name
    within = _WITHIN.search(r.low)
    args["within"] = float(within.group(1)) if within else _radius(scene, anchor)
    return _found(ToolCall(tool="find_assets", args=args), scene)


def _radius(scene: Scene, anchor: Anchor) -> float:
    """How far "around" a place reaches, as the search measures it (to an area's edge, 0 inside):
    SEARCH_NEAR_M from a place's point; round an area, about as far from its middle, but never
    less than its own ground and AREA_NEAR_M past its edge (a lot, not the road beside it)."""
    landmark = scene.landmark(anchor.name) if anchor.kind == "landmark" else None
    if landmark is None or not landmark.polygon:
        return SEARCH_NEAR_M
    extent = max(math.dist(landmark.position, corner) for corner in landmark.polygon)
    return max(AREA_NEAR_M, math.floor((SEARCH_NEAR_M - extent) * 10) / 10)


def _asks_for_lanes(r: Reading) -> bool:
    """Whether the lanes themselves are what is asked for ("which lanes does X have", "the lanes
    of X"), not the place of what stands on them ("is anything in the northbound lane")."""
    lane = _LANE_KIND.search(r.masked)
    if lane is not None and re.search(r"\b(?:which|what)\s+$", r.masked[: lane.start()]):
        return True  # "the ego is on which lane now?": the lane is what is asked
    return lane is not None and not _LANE_AS_PLACE.search(r.masked[: lane.start()])


def _road_named(r: Reading, scene: Scene) -> str | None:
    """The road a clause names ("Campus Drive"), or the lane id when it names one lane."""
    if r.lane is None:
        return None
    lane = scene.roads.lane(r.lane)
    if lane is None or not r.lane_guessed:
        return r.lane
    return lane.road or r.lane


def _lanes(r: Reading, scene: Scene, back: Anchor | None) -> ToolCall:
    """find_lanes: the lanes of a road named, else the lane nearest a place or asset named."""
    road = _road_named(r, scene)
    if road is not None:
        lane = scene.roads.lane(road)
        return ToolCall(tool="find_lanes", args={"road": lane.road if lane is not None and lane.road else road})
    only = next((i for m in r.mentions if (i := _only_instance(r, scene, m)) is not None), None)
    near = _named(r, scene) or (Anchor("asset", only) if only else None) or back  # "which lane is the SUV in"
    return ToolCall(tool="find_lanes", args={"near": near.name} if near is not None else {})


def _what_or_where(r: Reading, scene: Scene, named: Anchor | None, back: Anchor | None,
                   notes_subject: list[str], recent: list[str]) -> Part:
    """A question with no relation: the thing named, where it is or how many there are (of the
    kind the last turn made or changed, when the question names none: "how many are there now?")."""
    if r.mentions:
        args: dict[str, Any] = {"category": r.mentions[0].category}
        if r.landmark:
            args.update(near=r.landmark, within=_radius(scene, Anchor("landmark", r.landmark)))
        return _found(ToolCall(tool="find_assets", args=args), scene)
    if named is not None and named.kind == "asset":
        return Part(ToolCall(tool="asset_properties", args={"asset": named.name}), named)
    if named is not None:
        return Part(ToolCall(tool="find_landmarks", args={"query": named.name}), named)
    if r.landmark_word:
        return Part(ToolCall(tool="find_landmarks", args={"query": r.landmark_word}), None)
    if _PLACE_KIND.search(r.masked):
        return Part(ToolCall(tool="find_landmarks", args={}), None)
    several = [a for i in notes_subject if (a := scene.asset(i)) is not None]
    kind = md.kind_of({a.category for a in several}) if len(several) > 1 and _PLURAL_BACK.search(r.masked) else None
    if kind is not None:  # "the cars... where are they?": all of them
        return _found(ToolCall(tool="find_assets", args={"category": kind}), scene)
    last = md.kind_of({a.category for i in recent if (a := scene.asset(i)) is not None}) if recent else None
    if kind is None and last is not None and re.search(r"\bhow many\b", r.low) and not _ANY_KIND.search(r.masked):
        return _found(ToolCall(tool="find_assets", args={"category": last}), scene)
    if back is not None and back.kind == "asset" and not _ANY_KIND.search(r.masked):
        return Part(ToolCall(tool="asset_properties", args={"asset": back.name}), back)  # "where is it now"
    if back is not None and back.kind == "landmark" and _WHERE.search(r.low):
        return Part(ToolCall(tool="find_landmarks", args={"query": back.name}), back)  # "where exactly is it"
    if back is not None:  # "anything around there": the earlier place
        return _around(r, scene, back)
    return Part(ToolCall(tool="find_assets", args={}), None)


def _found(call: ToolCall, scene: Scene) -> Part:
    """An asset search, with the first asset it finds as what a later "it" refers to."""
    try:
        result = FindAssets().propose(FindAssetsArgs.model_validate(call.args), scene)
    except (ToolError, KeyError, ValueError):
        return Part(call, None)  # the Worker will refuse it in its own words when it runs
    ids = result.data.get("ids") if result.data else None
    # The ego is the asker, not what "it" means ("is anything on the lanes, and what is near it").
    found = tuple(str(i) for i in ids if i != EGO_ID) if isinstance(ids, list) else ()
    return Part(call, Anchor("asset", found[0]) if found else None, found)


__all__ = ["SEARCH_NEAR_M", "of_group", "plan_question"]
