"""Edits of what is already in the scene, for the rule planner: remove, move, turn, behave, recolour.

Which assets a clause means comes from, in order: ids and numbered names ("car 2"), the ego,
pronouns resolved within the prompt and then from memory ("it", "the cones you added"), and
categories present in the scene. Group words ("the clutter at the bus stop", "the roadworks",
"parking lot B should be empty") become the assets found there.
"""

from __future__ import annotations

import math
import re
from dataclasses import replace
from typing import Any, NamedTuple

from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning.intent import FEWER_WORDS, KEEP_SOME, REMOVE_WORDS
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules import numbers as nb
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.inflection import inflected
from drivetwin.orchestrator.planning.rules.places import Notes, location, relation_objects, road_said, side_of
from drivetwin.orchestrator.planning.rules.reading import (
    GOAL_REACH,
    GOES_TO,
    Reading,
    destination,
    find_count,
    find_place,
    numbered_picks,
    read,
    says_oncoming,
)
from drivetwin.tools.appearance import COLOURS, hex_colour
from drivetwin.tools.base import ToolCall
from drivetwin.tools.search import lane_under, most_of
from drivetwin.worlds.catalog import Category, catalog
from drivetwin.worlds.scene import AssetInstance, Scene
from drivetwin.worlds.surface import nearest_on_polyline, point_along, polyline_length

# How far from a place its "clutter" or "stuff" reaches, metres (a bus stop's bench and bin).
NEAR_PLACE_M = 8.0
# How far outside a place's area a thing still stands at it (the signals on the crossroads' corners).
EDGE_M = 2.0
# How far from a place without an area its things stand ("the trees at the fountain").
SCOPE_RADIUS_M = 20.0
# Defaults for amounts a person leaves out ("back it up", "shift the bin", "spin it").
DEFAULT_STEP_M = 3.0
SMALL_STEP_M = 1.5
# A turn said to be small ("angle it a little"), in degrees (anticlockwise, as turn_deg counts).
SMALL_TURN_DEG = 15.0
DEFAULT_SPIN_DEG = 90.0
# Words that point at what the conversation is about: pronouns, and a demonstrative with a word
# for any thing ("remove that thing").
_POINTING = ("it", "them", "that one", "those", "they", "its", "him", "her", "that thing", "this thing",
             "that object", "this object", "those things", "these things")
# "get rid of that", "lose this": a demonstrative said last is the thing itself.
_THAT_LAST = re.compile(r"\b(?:that|this)\s*(?:please|pls|now|too|again|as well)?\s*[.!?]*\s*$")
# Words that make what follows a reference point, not the thing acted on ("near from ego").
_ANCHOR_BEFORE = re.compile(r"\b(?:near|from|to|behind|ahead of|in front of|of|by|beside|around|closest to|nearest)\s+(?:the\s+)?$")
# "make the suv stand out": a look meant to be seen, in the colour of safety clothing.
_CONSPICUOUS = ("stand out", "stands out", "hard to miss", "eye-catching", "conspicuous", "easy to spot", "easier to spot", "hi-vis", "high-vis",
                "more visible", "easier to see", "easy to see",
                "something bright", "bright colour", "bright color", "bright colours", "bright colors", "something brighter")
CONSPICUOUS_COLOUR = "orange"
# A thing said to be lost to the eye, which a colour that stands out mends: "now it disappears into
# the grass", "the car blends into the road", "it's hard to see".
UNSEEN = re.compile(r"\b(?:disappear|vanish|blend)(?:s|es|ed|ing)? (?:into|in with|against|among)\b|\bhard to (?:see|spot|make out)\b")
# Standing out said as too much: "too conspicuous", "less eye-catching", "stands out too much", "tone it down".
TOO_CONSPICUOUS = re.compile(r"\b(?:too|less|not (?:so|as)|overly)\s+(?:\w+\s+)?(?:conspicuous|eye-catching|visible|hard to miss|easy to spot)"
                              r"|\bstands? out (?:\w+\s+)?too much\b|\btone (?:it|them|that|this|\w+) down\b|\bblend in\b")
# A motion verb with a side and no amount ("pull forward", "nudge it left", "roll back"), not a
# relation ("left of the bench") or a lane ("the right lane").
_SIDE_MOVE = re.compile(
    r"\b(?:pull|nudge|move|shift|push|roll|inch|edge|creep|slide|budge|bump|scoot|go|come|drive)s?\b(?:\s+[\w']+){0,3}?"
    r"\s+(?:forwards?|ahead|back|backwards?|left|right)\b(?!\s+(?:of|lane|side|hand))"
)
_RECENT = ("you added", "you just added", "that", "those", "these", "the new", "last", "it", "them")


def referenced(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[str]:
    """Existing assets a clause refers to, or [] when it names none."""
    found = _referenced(r, scene, memory, notes)
    if found:
        if notes.subject and notes.subject != found:
            notes.earlier = [*notes.subject, *notes.earlier]
        notes.subject = found
    return found


def _referenced(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[str]:
    moved = [i for i in r.ids if i not in relation_objects(r)]  # "move trash_bin_1 next to bench_1": the bench is where
    if moved:
        return moved
    if not r.mentions and _ANY_NEAREST.search(r.low):  # "whatever is closest to the ego": of every kind
        point = _point_of(r, scene, memory)
        pool = [a.id for a in scene.assets if a.id != "ego"]
        if point is None or not pool:
            return []
        at: tuple[float, float] = point
        return [min(pool, key=lambda i: _distance_to(scene, i, at))]
    # "put the SUV behind the ego": the thing named first is what moves, the ego where it goes.
    ego_anchors = (bool(r.mentions) and r.mentions[0].start < r.ego_at) or bool(
        _ANCHOR_BEFORE.search(r.low[: max(r.ego_at, 0)]))  # "everything near the ego": the ego is where
    if r.ego and not ego_anchors and not r.has(lx.BEHAVIOUR_WORDS["jaywalk"]):
        return ["ego"]
    if r.mentions:
        mention = r.mentions[0]
        name = mention.category
        recent = [i for i in memory.last_added(name) if scene.asset(i) is not None]
        other = _THE_OTHER_N.search(r.low[: mention.start]) if mention.plural else None
        if other is not None:  # "the other two cones": of that kind, those the last edit left alone
            touched = memory.last_touched()
            left = [a.id for a in scene.assets if a.category == name and a.id not in touched]
            many = int(other.group(1)) if other.group(1).isdigit() else ph.NUMBER_WORDS.get(other.group(1), 0)
            if len(left) != many or len(left) == scene.count(name):
                raise ph_error(f"which {many} {name.replace('_', ' ')}s? say them by number, e.g. '{name.replace('_', ' ')} 1 and 2'")
            return left
        if recent and r.has(_RECENT):
            return recent if mention.plural else recent[-1:]
        # "the vehicles": every category of the group the catalog tags so, not only the one named
        kinds = next((set(m) for m in md.groups_said(r.low).values() if name in m), {name})
        present = [a.id for a in scene.assets if a.category in kinds]
        if _scoped_by_place(r, mention, anywhere=bool(REMOVE_WORDS.search(r.low))):
            present = _at_place(scene, str(r.landmark), present)
        state = _STATE_BEFORE.search(r.low[: mention.start]) or _STATE_AFTER.match(r.low[mention.end :])
        if state is not None:  # "the parked cars", "the cars that are moving": those doing so now
            still = state.group(1) in ("parked", "stationary", "stopped")
            present = [i for i in present if (a := scene.asset(i)) is not None and (a.behaviour.kind == "parked") == still]
        side = side_of(r.low, scene)
        if side is not None:  # "the street lights on the south side": those on that side
            present = [i for i in present if (a := scene.asset(i)) is not None and side[1](a)]
            centre = _point_of(r, scene, memory) if not mention.plural else None
            if centre is not None:  # "the tree just north of lot A": of those that way, the one nearest it first
                present = _nearest_first(scene, present, centre)[0]
        if not present:
            return []
        if _EVERY_OTHER.search(r.low[: mention.start]) and len(present) > 2:  # "every second street light": alternate ones
            return alternate(scene, present)
        sized = _SIZE_PICKED.search(r.low[: mention.start]) or _SIZE_OF.match(r.low[mention.end :])
        # "the biggest vehicle", "the car that's largest", "the tallest of the trees"
        if sized is not None and (not mention.plural or " of " in sized.group(0)):
            picked = most_of(md.most_said(sized.group(1)), [a for i in present if (a := scene.asset(i)) is not None])
            if len(picked) == 1:
                return [picked[0].id]
            present = [a.id for a in picked]  # several as big: the rest of the reading picks among them
        nearest = _NEAREST_TO.match(r.low[mention.end :])
        furthest = _FURTHEST_FROM.match(r.low[mention.end :])
        if (nearest or furthest) and not mention.plural:  # "the car nearest the Student Union", "... furthest from"
            point = _point_of(r, scene, memory)
            if point is not None:
                return [(max if furthest else min)(present, key=lambda i: _distance_to(scene, i, point))]
        tied: list[str] = []
        way = _WAY_OF_AFTER.match(r.low[mention.end :]) if not mention.plural and len(present) > 1 else None
        there = _anchor_after(r, scene, mention, mention.end + way.end()) if way is not None else None
        if there is not None and way is not None and (r.landmark is None or r.landmark_at < mention.end + way.end()):
            # "the sedan east of the SUV": of those that way of it, the nearest
            dx, dy = _COMPASS[way.group(1)]
            beyond = [i for i in present if (a := scene.asset(i)) is not None and (a.pose.x - there[0]) * dx + (a.pose.y - there[1]) * dy > 0]
            if beyond:
                return _nearest_first(scene, beyond, there)[0][:1]
        by_point = _by_point(r, scene, mention) if len(present) > 1 else None
        if by_point is not None:  # "the lamp post by the bus stop", "the tree that's next to the bench": the one nearest it
            present, tied = _nearest_first(scene, present, by_point)
            if len(tied) == 1:  # two as near ("the car next to the SUV", one each side): the words after pick, or it is asked
                return tied
        if _ONE_OF.search(r.low[: mention.start]):  # "move one of the cars to lot A": one, never all of them
            return recent[-1:] if recent else present[:1]
        if mention.plural or r.has(("all", "every", "each", "both")):
            return present
        outermost = _outermost(r, scene, mention, present)
        if outermost is not None:
            return [outermost]
        if tied and not recent:  # two as near and nothing else to pick by: which is the person's to say
            raise ph_error(f"which {name.replace('_', ' ')}? {' and '.join(tied)} stand as near it; say which, "
                           f"e.g. 'the one on the east side'")
        return recent[-1:] if recent else present[:1]
    nth = _NTH_ONE.search(r.low)
    recent = [i for i in memory.last_added() if scene.asset(i) is not None]
    if nth is not None and recent:  # "paint the second one blue": of the things the last turn added, in order
        place = _ORDINALS.index(nth.group(1))
        kind = recent[0].rsplit("_", 1)[0]
        added = [i for t in memory.live_turns() for i in t.added if i.rsplit("_", 1)[0] == kind and scene.asset(i) is not None]
        recent = added if len(recent) == 1 and len(added) > 1 else recent  # "another one", then "the first one": the earlier one
        if place >= len(recent) and nth.group(1) != "last":
            raise ph_error(f"the last turn added {len(recent)}; there is no {nth.group(1)} one")
        return [recent[-1] if nth.group(1) == "last" else recent[place]]
    if r.has(_POINTING) or _THAT_LAST.search(r.low):
        if notes.subject:
            return notes.subject
        # "move the bench to the fountain" then "actually, put it back by the bus stop": what the last edit touched
        return _asked_about(memory, scene) or [i for i in memory.last_touched() if scene.asset(i) is not None]
    return []


# A size word said just before the thing ("the biggest vehicle", "the tallest green tree", "the biggest
# of the cars") or after it ("the car that is largest").
_SIZE_PICKED = re.compile(md.SIZE_SUPERLATIVE.pattern + r"\s+(?:(?:of (?:the|all the|those|these) )|[a-z]+\s+)?$")
_SIZE_OF = re.compile(r"\s+(?:that is|that's|which is)\s+(?:the\s+)?" + md.SIZE_SUPERLATIVE.pattern.removeprefix(r"\b"))


# One picked from a group: "one of the cars", "just one of those family cars".
_ONE_OF = re.compile(r"\b(?:one|any one|just one|only one|either) of (?:the |those |these |our |my )?(?:[a-z]+\s+){0,2}$")
# A state said of the things named: "the parked cars", "the cars that are moving".
_STATE_BEFORE = re.compile(r"\b(parked|stationary|stopped|moving|driving)\s+$")
_STATE_AFTER = re.compile(r"\s+(?:that are |which are |that's |currently |still )(parked|stationary|moving|driving)\b")  # not "get the suv moving"


def _asked_about(memory: Memory, scene: Scene) -> list[str]:
    """The one thing the question just answered was about ("which one's the SUV?" then "make it
    yellow"): an asset it named, or the only one of the kind it looked up; [] when not one."""
    named: set[str] = set()
    for call in memory.last_asked():
        if isinstance(call.args.get("asset"), str):
            named.add(str(call.args["asset"]))
        elif call.tool == "find_assets" and isinstance(call.args.get("category"), str):
            named |= {a.id for a in scene.assets if a.category == call.args["category"]}
    return sorted(named) if len(named) == 1 and scene.asset(next(iter(named))) is not None else []


# Every other one of a row: "every second street light", "every other cone".
EVERY_OTHER = re.compile(r"\bevery (?:second|other|2nd)\b")
_EVERY_OTHER = re.compile(EVERY_OTHER.pattern + r"\s+$")  # said right before the thing
# Things further than this across their line stand in another row ("the lamps on the north side" and the south).
ROW_APART_M = 2.0


def alternate(scene: Scene, ids: list[str]) -> list[str]:
    """Every second one of the things (the second, fourth, ...), counted along each row they stand
    in: rows run along the line the things spread most, told apart by how far across it they stand;
    things in no row of three are counted along that line all together."""
    things = [a for i in ids if (a := scene.asset(i)) is not None]
    mx = sum(a.pose.x for a in things) / len(things)
    my = sum(a.pose.y for a in things) / len(things)
    sxx = sum((a.pose.x - mx) ** 2 for a in things)
    syy = sum((a.pose.y - my) ** 2 for a in things)
    sxy = sum((a.pose.x - mx) * (a.pose.y - my) for a in things)
    angle = 0.5 * math.atan2(2 * sxy, sxx - syy)  # the line they spread most along
    ux, uy = math.cos(angle), math.sin(angle)
    along = {a.id: a.pose.x * ux + a.pose.y * uy for a in things}
    across = {a.id: -a.pose.x * uy + a.pose.y * ux for a in things}
    rows: list[list[AssetInstance]] = []
    for a in sorted(things, key=lambda a: across[a.id]):
        if rows and abs(across[a.id] - across[rows[-1][-1].id]) <= ROW_APART_M:
            rows[-1].append(a)
        else:
            rows.append([a])
    if all(len(row) < 3 for row in rows):
        rows = [things]
    return [a.id for row in rows for a in sorted(row, key=lambda a: along[a.id])[1::2]]


# Those of a kind the last edit left alone: "the other two cones", "the other 3 benches".
_THE_OTHER_N = re.compile(r"\bthe other (\d+|[a-z]+) $")
# One of the things just added, by its place in the order they were added: "the second one", "the last of them".
_ORDINALS = ("first", "second", "third", "fourth", "fifth", "sixth", "last")
_NTH_ONE = re.compile(rf"\bthe ({'|'.join(_ORDINALS)}) (?:one|of them|of those)\b")


# Anything at all, picked out by what it is nearest: "whatever is closest to the ego", "the nearest
# object to the fountain", "the thing nearest the gate".
_ANY_NEAREST = re.compile(r"\b(?:(?:whatever|anything|something|the (?:thing|object|item|prop))\s+(?:that'?s |which is |that is |is )?"
                          r"(?:nearest|closest)|the (?:nearest|closest) (?:thing|object|item|prop))\b")
# The one furthest from something: "the tree furthest from the library", "the lamp farthest away from the ego".
FURTHEST = re.compile(r"\b(?:furthest|farthest|most distant)(?: away)? from\b")  # "furthest east" is a side, not this
# Every one of the things said: "get rid of them all", "all of them", "every single one".
_ALL_OF_THEM = re.compile(r"\b(?:them|those|these|they) all\b|\ball (?:of )?(?:them|those|these)\b|\bevery (?:one|single)\b")
# The one of several there further from the place: "the tree by the fountain that's further away", "the far one".
_FURTHER_ONE = re.compile(r"\b(?:further|farther) (?:away|off|out|back)\b|\bthe (?:far|farther|further|more distant) one\b")
_FURTHEST_FROM = re.compile(r"\s*(?:that is |which is |that's )?" + FURTHEST.pattern)  # right after the thing named
# Backing a thing up with the thing said between: "back that SUV up 3 metres", "back it up a bit".
_BACK_IT_UP = re.compile(r"\bback (?:(?:it|them|that|this|the|our|my|[a-z]+_\d+)\s+)(?:[a-z]+\s+){0,2}?up\b")
# A thing picked out by the place it is nearest, said just before the place: "the lamp nearest the bus stop".
_PICKED_NEAREST = re.compile(r"\b(?:nearest|closest)(?: to)?\s+(?:the\s+)?$")
# A thing picked out by what it is nearest ("the car nearest the union", "the bin closest to the ego").
_NEAREST_TO = re.compile(r"\s*(?:that is |which is |that's )?(?:nearest|closest)(?: to)?\b")


def _point_of(r: Reading, scene: Scene, memory: Memory) -> tuple[float, float] | None:
    """Where the place or the ego the clause names is."""
    landmark = scene.landmark(r.landmark) if r.landmark else None
    if landmark is not None:
        return landmark.position[0], landmark.position[1]
    ego = scene.asset("ego") if r.ego else None
    return (ego.pose.x, ego.pose.y) if ego is not None else None


# A thing picked out by what it stands by, said right after it: "the lamp post (that's) (right) by the bus stop".
_BY_AFTER = re.compile(r"\s*(?:(?:that'?s|that is|which is|standing|sitting|right|just|directly)\s+)*"
                       r"(?:by|near|next to|beside|close to|outside|from|(?P<over>opposite|across (?:the )?(?:road|street) from))\s+")
# A thing picked out by the way it stands from another: "the sedan (just) east of the SUV", "the car to the west of it".
_WAY_OF_AFTER = re.compile(r"\s*(?:(?:that'?s|which is|just|right|directly|to the)\s+)*(north|south|east|west)(?:ern)?\s+of\s+")
_COMPASS = {"north": (0.0, 1.0), "south": (0.0, -1.0), "east": (1.0, 0.0), "west": (-1.0, 0.0)}
# Two things nearer than this to each other's distance from what they are picked by are as near.
TIE_M = 0.5


def _anchor_after(r: Reading, scene: Scene, mention: ph.Mention, at: int) -> tuple[float, float] | None:
    """Where the place, the ego or the one thing of a kind said right at `at` (after "by") stands;
    None when what is said there is none of those or one of several."""
    lead = _leading_article(r.low[at:])
    if r.landmark is not None and at <= r.landmark_at <= at + lead:
        return _point_of(r, scene, Memory())
    said = r.low[at + lead :]  # another place than the clause's own ("the lamp by the bus stop ... closer to the Library")
    place = next((lm for lm in scene.landmarks for n in lm.names() if said.startswith(ph.normalise(n).strip() + " ")
                  or said.rstrip(" .!?") == ph.normalise(n).strip()), None)
    if place is not None:
        return place.position[0], place.position[1]
    if r.ego and at <= r.ego_at <= at + lead:
        ego = scene.asset("ego")
        return (ego.pose.x, ego.pose.y) if ego is not None else None
    after = next((m for m in r.mentions if at <= m.start <= at + lead and m is not mention), None)
    there = [a for a in scene.assets if after is not None and a.category == after.category]
    return (there[0].pose.x, there[0].pose.y) if len(there) == 1 else None


def _leading_article(text: str) -> int:
    """How long the article opening `text` is, with the space after it ("the bus stop": 4)."""
    said = _LEADING_ARTICLE.match(text)
    return said.end() if said is not None else 0


_LEADING_ARTICLE = re.compile(r"(?:the|a|an|that|this|our)\s+")


def picked_by_what_it_stands_by(r: Reading, scene: Scene, mention: ph.Mention) -> str | None:
    """The one thing of the mention's kind picked out by what it stands by ("the lamp by the bus
    stop", "the lamp opposite the bench"): the nearest to it; None when none is said or two are as near."""
    point = _by_point(r, scene, mention)
    tied = _nearest_first(scene, [a.id for a in scene.assets if a.category == mention.category], point)[1] if point else []
    return tied[0] if len(tied) == 1 else None


def _by_point(r: Reading, scene: Scene, mention: ph.Mention) -> tuple[float, float] | None:
    """Where what a singular mention is picked out by stands ("the lamp by the bus stop"), or its
    mirror over the road ("the lamp opposite the bench"); None when no such words follow it."""
    by = _BY_AFTER.match(r.low[mention.end :]) if not mention.plural else None
    point = _anchor_after(r, scene, mention, mention.end + by.end()) if by is not None else None
    return _across_the_road_at(scene, point) if point is not None and by is not None and by.group("over") else point


def _nearest_first(scene: Scene, ids: list[str], point: tuple[float, float]) -> tuple[list[str], list[str]]:
    """`ids` nearest `point` first, and those of them as near as the nearest (within TIE_M)."""
    ordered = sorted(ids, key=lambda i: _distance_to(scene, i, point))
    best = _distance_to(scene, ordered[0], point) if ordered else 0.0
    return ordered, [i for i in ordered if _distance_to(scene, i, point) <= best + TIE_M]


def _without_description(r: Reading, scene: Scene) -> Reading | None:
    """The clause without what picks its thing out ("the lamp post [by the stop sign] to the
    Engineering Hall"), when a place to go to is said after it; None when none is."""
    mention = r.mentions[0] if r.mentions else None
    by = _BY_AFTER.match(r.low[mention.end :]) if mention is not None else None
    if mention is None or by is None or _anchor_after(r, scene, mention, mention.end + by.end()) is None:
        return None
    at = mention.end + by.end()
    rest = r.masked[at:]
    lead = _leading_article(rest)
    after = next((m for m in r.mentions if at <= m.start <= at + lead and m is not mention), None)
    blank = re.match(r"[\s\u00a7]*(?:ego\b)?[\s\u00a7]*", rest[lead:])  # a place or the ego, blanked in the masked words
    end = after.end if after is not None else at + lead + (blank.end() if blank is not None else 0)
    left = read(r.low[: mention.end] + " " + r.low[end:], scene)
    return left if _GOES_AFTER.search(left.low[mention.end :]) else None


# Where a thing is to go, said after what picks it out: "to", "over to", "into", "closer to".
_GOES_AFTER = re.compile(r"\b(?:to|into|onto|towards?)\s+(?:the|a|an|lot|parking|[a-z]+_\d)")


def _distance_to(scene: Scene, asset_id: str, point: tuple[float, float]) -> float:
    asset = scene.asset(asset_id)
    return math.inf if asset is None else math.dist((asset.pose.x, asset.pose.y), point)


def _outermost(r: Reading, scene: Scene, mention: ph.Mention, present: list[str]) -> str | None:
    """The one of `present` furthest the way the words after its mention point ("the signal on
    the north-east corner of the crossroads", "the western one"), among those at the place named
    if any are; None when they point no way or there is no choice."""
    ones = _outermost_ones(r, scene, present, 1)
    return ones[0] if ones else None


def _outermost_ones(r: Reading, scene: Scene, present: list[str], count: int) -> list[str]:
    """The `count` of `present` furthest the way the words point ("a couple of those lamp posts
    down the eastern end"), furthest first; none when they point no way or there is no choice."""
    way = md.outer_direction(r.masked)
    if way is None or len(present) <= count:
        return []
    pool = (_at_place(scene, r.landmark, present) if r.landmark else []) or present
    things = sorted((a for i in pool if (a := scene.asset(i)) is not None), key=lambda a: -(a.pose.x * way[0] + a.pose.y * way[1]))
    return [a.id for a in things[:count]]


# Between a thing and a place, words that make the place where the thing is ("the cars in lot B"),
# not where it should go ("move the cars to lot B").
_SCOPE = re.compile(r"\s*(?:that are |which are |standing |parked )?(?:in|at|inside|by|near|on|around|from|of)\s+(?:the\s+)?$")


# "Keep just two" of the things at a place: those within this of it are the ones counted.
KEEP_RADIUS_M = 30.0
# Some of what was just named: "take away 3 of them", "two of those".
_SOME_OF_THEM = re.compile(r"\b(\d+|[a-z]+) of (?:them|those|these)\b")


# A side left unnamed: "along one side of Main Street", "on either side".
_ONE_SIDE = re.compile(r"\b(?:one|a|either|some) side\b")


def _amount(word: str) -> int:
    return int(word) if word.isdigit() else ph.NUMBER_WORDS.get(word, 0)


def _kept(r: Reading) -> int | None:
    """How many the words keep ("keep just two", "leave one of them"), or None."""
    keep = KEEP_SOME.search(r.low)
    return None if keep is None else _amount(keep.group(1))


def _but_kept(r: Reading, ids: list[str]) -> list[str]:
    """`ids` less the number the words keep ("leave just one of them": all but the first)."""
    left = _kept(r)
    return ids if left is None else ids[left:]


# A count the scene should end with: "there should be exactly four cones in lot A", "we want only two benches".
FINAL_COUNT = re.compile(r"\b(?:there (?:should|must|has to|needs to|is to|are to) be|(?:i|we)(?: want| need| would like| ?'d like))"
                         r"\s+(?:(?:exactly|only|just|a total of)\s+|(?=[^,.;!?]*\b(?:in total|altogether|in all|all told)\b))")


# Half of the things named ("half the trees", "half of those cones").
_HALF = re.compile(r"\bhalf (?:of )?(?:the|those|these|them|all(?: the)?|our|its)\b[^,;]*$")
# Thinned out: fewer, by about half ("thin the cones out", "thin them out").
_THINNED = re.compile(r"\bthin(?:s|ned|ning)? (?:\w+ ){0,2}out\b")
# Fewer by half with no things named after the verb ("reduce to half", "cut them down to half", "halve them"):
# spelling's _HALVE and _IN_HALF rewrite the forms that name them ("halve the cones") as "remove half of".
_HALVED = re.compile(r"\b(?:reduce|cut|bring|trim)\w*\s+(?:(?:it|them|those|these|that)\s+)?(?:down\s+)?(?:to|by)\s+(?:about\s+|roughly\s+|around\s+|nearly\s+)?(?:a\s+|one\s+)?half\b"
                     r"|\bhalve[ds]?\s+(?:it|them|those|these|that)\b")


def kept_at(scene: Scene, category: str, place: str | None) -> list[str]:
    """The things of `category` a count kept or wished for at `place` counts (anywhere without
    one), nearest the place first."""
    landmark = scene.landmark(place) if place else None
    there = [(0.0 if landmark is None else math.dist(landmark.position, (a.pose.x, a.pose.y)), a.id)
             for a in scene.assets if a.category == category]
    return [i for d, i in sorted(there) if d <= KEEP_RADIUS_M]


def _scoped_by_place(r: Reading, mention: ph.Mention, anywhere: bool = False) -> bool:
    """Whether the clause names its things by where they are ("every vehicle in lot B"); with
    `anywhere`, a place said anywhere in it does ("the quad without trees": a removal has no
    destination)."""
    if r.landmark is None or not (mention.plural or r.has(("all", "every", "each"))):
        return False
    if re.search(r"\b(?:north|south|east|west)(?:ern)?\s+of\s+(?:the\s+)?$", r.low[: max(0, r.landmark_at)]):
        return False  # "the lamps east of the crossroads": a side of it (side_of), not those at it
    if anywhere or (0 <= r.landmark_at < mention.start and not r.masked[r.landmark_at : mention.start].strip(" §")):
        return True  # a removal's place, or one said right before the things ("the lot B cars")
    return r.landmark_at >= mention.end and bool(_SCOPE.fullmatch(r.low[mention.end : r.landmark_at] + " "))


def _at_place(scene: Scene, place: str, ids: list[str], reach: float | None = None) -> list[str]:
    """Those of `ids` standing at a place: inside its area, or within `reach` of its point (by
    default near an area's point, further from a place without one), nearest first."""
    landmark = scene.landmark(place)
    if landmark is None:
        return []
    if reach is None:
        reach = NEAR_PLACE_M if landmark.polygon is not None else SCOPE_RADIUS_M
    out = []
    for i in ids:
        a = scene.asset(i)
        if a is None:
            continue
        distance = math.dist((a.pose.x, a.pose.y), landmark.position)
        if (landmark.polygon is not None and _inside((a.pose.x, a.pose.y), landmark.polygon, EDGE_M)) or distance <= reach:
            out.append((distance, i))
    return [i for _, i in sorted(out)]


def _inside(point: tuple[float, float], polygon: list[tuple[float, float]], margin: float = 0.0) -> bool:
    xs, ys = [p[0] for p in polygon], [p[1] for p in polygon]
    return min(xs) - margin <= point[0] <= max(xs) + margin and min(ys) - margin <= point[1] <= max(ys) + margin


# The road as where things are taken from: "off the road", "out of our lane".
OFF_THE_ROAD = re.compile(r"\b(?:off|from|on|in|out of|blocking)\s+(?:the|our|my|this|that)\s+(?:\S+\s+)?(?:road|roads|lane|lanes|street)\b"
                          r"|^\s*(?:please\s+)?clear\s+(?:the|our|my|this|that)\s+(?:\S+\s+)?(?:road|roads|lane|lanes|street)\s*(?:please\s*)?[.!]*\s*$")


# Between two things of one list: "the seat and the bin", "benches, bins".
_LIST_GAP = re.compile(r"\s*(?:,|and|plus|&|, and)\s*(?:(?:the|a|an|those|these|that|this|all|both)\s+)?")


def _listed(r: Reading) -> list[ph.Mention]:
    """The things of different kinds a clause lists together from its first one on."""
    listed = r.mentions[:1]
    for m in r.mentions[1:]:
        if m.category == listed[-1].category or not _LIST_GAP.fullmatch(r.low[listed[-1].end : m.start]):
            break
        listed.append(m)
    return listed


# Not both of two things ("we don't need both cars", "no need for both benches"): one of them, not both.
_NOT_BOTH = re.compile(r"\b(?:don'?t|do not|dont|doesn'?t|does not|no need for|not)\s+(?:\w+\s+){0,2}both\s+(?:of\s+)?(?:the\s+|those\s+|these\s+)?$")


def remove(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall] | None:
    """remove_assets calls for a clause that asks for removal, or None when it names nothing."""
    # "clear lot B a little": some of what is there, not all of it
    fewer = bool(FEWER_WORDS.search(r.low)) or (r.has(("clear", "empty", "declutter", "tidy")) and r.has(md.SMALL))
    gone = r.has(lx.GONE_WORDS)
    if r.ids or (r.ego and not r.mentions and not _ANCHOR_BEFORE.search(r.low[: max(r.ego_at, 0)])):
        return [ToolCall(tool="remove_assets", args={"assets": r.ids or ["ego"]})]
    if not r.mentions:
        if r.has(lx.WORKS_WORDS):
            works = [c.name for c in catalog().values() if "maintenance" in c.tags and scene.count(c.name)]
            return [ToolCall(tool="remove_assets", args={"category": c}) for c in works] or None
        parked_said = r.has(lx.BEHAVIOUR_WORDS["parked"])
        if r.landmark and (r.has(("nobody", "no one", "no-one")) or (parked_said and r.has(("nothing",)))):
            # "nobody should be parked at X", "nothing parked in X": the vehicles there; "... standing at X": the walkers
            motion = "vehicle" if parked_said else "walker"
            there = [a.id for a in scene.assets if catalog()[a.category].motion == motion and a.category != "ego_vehicle"]
            ids = _at_place(scene, r.landmark, there, reach=NEAR_PLACE_M)
            return [ToolCall(tool="remove_assets", args={"assets": ids})] if ids else None
        if r.landmark and (r.has(lx.GENERIC_THINGS) or gone or r.has(("empty", "clear"))):
            keep_permanent = fewer or r.has(("everything",))
            parked = r.has(lx.BEHAVIOUR_WORDS["parked"])  # "whatever is parked in lot A": the vehicles
            clutter = [a.id for a in scene.assets if "light" not in (tags := catalog()[a.category].tags)
                       and (keep_permanent or "permanent" not in tags)
                       and (not parked or catalog()[a.category].motion == "vehicle")]
            ids = _at_place(scene, r.landmark, clutter, reach=NEAR_PLACE_M)
            notes.guess(f"what counts as the things at {r.landmark}")
            if not ids:
                raise ph_error(f"there is nothing{' parked' if parked else ''} at {r.landmark} to take away")
            return [ToolCall(tool="remove_assets", args={"assets": ids[:1] if fewer else ids})]
        if OFF_THE_ROAD.search(r.low) and (r.has(lx.GENERIC_THINGS) or gone or r.has(("clear",))):
            # "clear the junk off the road", "the lane should be open again", "clear the road": what stands on it
            lanes = [lane] if r.lane and not r.lane_guessed and (lane := scene.roads.lane(r.lane)) else scene.roads.lanes
            ids = [a.id for a in scene.assets if catalog()[a.category].motion == "prop" and lane_under(a, lanes)]
            if not ids:
                raise ph_error("nothing stands on the road to take away; parked and driving vehicles are left as they are")
            return [ToolCall(tool="remove_assets", args={"assets": ids})]
        ids = referenced(r, scene, memory, notes)
        road = road_said(r.low, scene)
        mapped = r.landmark or (r.lane if r.lane and not r.lane_guessed else road[0] if road is not None else None)
        if not ids and mapped and not r.has(lx.GENERIC_THINGS) and not _PRONOUN.search(r.masked) and _kept(r) is None:
            # "remove the library", "remove the eastbound lane": the map itself, which only its maker changes
            raise ph_error(f"{mapped} is part of the map, which stays as it is: I can take away things placed in it, "
                           f"such as the {', '.join(sorted({a.category.replace('_', ' ') for a in scene.assets})[:4])}")
        if not ids and _kept(r) is not None:  # "way too many cones. keep just the one": of those just made
            ids = notes.subject or [i for i in memory.last_added() if scene.asset(i) is not None]
        ids = _but_kept(r, ids)  # "too many, just leave one of them"
        if _HALF.search(r.low):  # "lose about half of them": the newest half
            ids = ids[len(ids) - max(1, len(ids) // 2):]
        said = None if _kept(r) is not None else _SOME_OF_THEM.search(r.low)  # "take away 3 of them": the newest 3
        some = _amount(said.group(1)) if said else 0
        ids = ids[-some:] if 0 < some < len(ids) else ids
        return [ToolCall(tool="remove_assets", args={"assets": ids})] if ids else None
    listed = _listed(r)
    if len(listed) > 1:  # "the seat and the bin there should both go": each of them
        return [c for m in listed for c in remove(replace(r, mentions=[m]), scene, memory, notes) or []] or None
    mention = r.mentions[0]
    name = mention.category
    if _EVERY_OTHER.search(r.low[: mention.start]):  # "get rid of every second street light": the alternate ones, never a count
        return [ToolCall(tool="remove_assets", args={"assets": ids})] if (ids := referenced(r, scene, memory, notes)) else None
    if _NOT_BOTH.search(r.low[: mention.start]):  # "we don't need both cars": one of them goes, and which is theirs to say
        word = r.low[mention.start : mention.end]
        raise ph_error(f"which of the {word} should go? name it, e.g. 'remove the {word.rstrip('s')} on the left'")
    recent = [i for i in memory.last_added(name) if scene.asset(i) is not None]
    count = find_count(r, mention)
    if count and count >= scene.count(name) > 1 and _VAGUE_PART.search(r.low) and not r.has(("all", "every", "each")):
        count = scene.count(name) - 1  # "too many people there, remove some": some of three is never all three
    halved = bool((count is None and (_HALF.search(r.low[: mention.start]) or _THINNED.search(r.low))) or _HALVED.search(r.low))
    if halved:  # "half the trees have to go", "cut them by half", "thin them out": half of them
        count = max(1, len(kept_at(scene, name, r.landmark)) // 2)
    if recent and r.has(("you added", "you just added", "the new", "that", "those")):
        # "remove two of those cones": that many of them, the newest first; "leave one of those": all but one
        chosen = recent[-count:] if count and count < len(recent) and _kept(r) is None else _but_kept(r, recent)
        return [ToolCall(tool="remove_assets", args={"assets": chosen})] if chosen else None
    by = _BY_AFTER.match(r.low[mention.end :]) if not mention.plural and count in (None, 1) else None
    # (by the clause's own place, the removal says so itself: near it, below)
    by = by if by is None or not (r.landmark is not None and 0 <= r.landmark_at - mention.end - by.end() <= 5) else None
    if by is not None and _anchor_after(r, scene, mention, mention.end + by.end()) is not None:
        return [ToolCall(tool="remove_assets", args={"assets": referenced(r, scene, memory, notes)[:1]})]  # "the lamp by the stop sign"
    args: dict[str, Any] = {"category": name}
    grouped = any(name in members for members in md.groups_said(r.low).values())
    if grouped and count and r.landmark and not fewer and _kept(r) is None:
        at = _at_place(scene, r.landmark, referenced(r, scene, memory, notes))
        if len(at) == count:  # "all three cars in lot B": the three there, whichever kind of car each is
            return [ToolCall(tool="remove_assets", args={"assets": at})]
    if (grouped or _scoped_by_place(r, mention, anywhere=True)) and (count is None or _kept(r) is not None) and not fewer:
        # "the vehicles in lot B": every one there, of every category the words cover ("..., just leave one": all but one)
        ids = _but_kept(r, referenced(r, scene, memory, notes))
        if not ids and r.landmark:  # "lose the trees by lot A", "remove the cars in lot A" with none there: never an addition
            word = r.low[mention.start : mention.end] if grouped else name.replace("_", " ")
            raise ph_error(f"there is no {word} at {r.landmark} to take away")
        return [ToolCall(tool="remove_assets", args={"assets": ids})] if ids else None
    road = road_said(r.low, scene)
    if _ONE_SIDE.search(r.low) and side_of(r.low, scene) is None:  # "along one side of Main Street": which one is the person's to say
        raise ph_error(f"which side{' of ' + road[0] if road else ''}? say the north, south, east or west side")
    if road is not None and not r.landmark:  # "no street lights on Campus Drive": those by it, or none
        ids = [a.id for a in scene.assets if a.category == name and road[1](a)]
        if not ids:
            raise ph_error(f"there is no {name.replace('_', ' ')} on {road[0]} to take away")
        count = max(1, len(ids) // 2) if halved else count  # "half the lamps on Campus Drive": half of those
        return [ToolCall(tool="remove_assets", args={"assets": _some(ids, count, fewer, notes)})]
    side = side_of(r.low, scene)
    if side is not None:  # "the street lights on the north side of Main Street": those there
        ids = [a.id for a in scene.assets if a.category == name and side[1](a)]
        if not ids:
            raise ph_error(f"there is no {name.replace('_', ' ')} on the {side[0]} to take away")
        count = max(1, len(ids) // 2) if halved else count  # "half the street lights on the south side": three of six
        point = _point_of(r, scene, memory)
        if not mention.plural and count is None and not r.has(("all", "every", "each", "both")) and len(ids) > 1:
            outermost = _outermost(r, scene, mention, ids)  # "the westernmost street light on the north side"
            if outermost is not None:
                return [ToolCall(tool="remove_assets", args={"assets": [outermost]})]
            if point is None:  # "the street light on the north side of Main Street": one of six
                raise ph_error(f"which {name.replace('_', ' ')}? on the {side[0]} there are {', '.join(ids)}")
            from_here: tuple[float, float] = point
            ids, count = sorted(ids, key=lambda i: _distance_to(scene, i, from_here)), 1  # "the tree north of lot A": the one nearest it
        return [ToolCall(tool="remove_assets", args={"assets": _some(ids, count, fewer, notes)})]
    ends = _outermost_ones(r, scene, [a.id for a in scene.assets if a.category == name], count or 1) \
        if not mention.plural or count else []
    if ends:  # "the western one", "a couple of those lamp posts down the eastern end"
        return [ToolCall(tool="remove_assets", args={"assets": ends})]
    left = _kept(r)
    if left is not None:  # "keep just two": all but that many of those in scope
        in_scope = len(kept_at(scene, name, r.landmark))
        if in_scope <= left:
            return None
        count = in_scope - left
    elif fewer and not _ALL_OF_THEM.search(r.low):  # "too many trees, get rid of them all": all ("it all looks ..." is none of them)
        count = count or 1
    elif gone or r.has(("all", "every", "none", "no more")):
        count = None
    elif not mention.plural:
        count = count or 1
    if r.landmark and _FURTHER_ONE.search(r.low):  # "the tree by the fountain that's further away": the far one of those there
        there = _at_place(scene, r.landmark, [a.id for a in scene.assets if a.category == name], reach=SCOPE_RADIUS_M)
        if len(there) >= 2:
            return [ToolCall(tool="remove_assets", args={"assets": there[::-1][: count or 1]})]
    point = _point_of(r, scene, memory) if FURTHEST.search(r.low) else None
    if point is not None:  # "the tree furthest from the library": the Worker ranks by nearness only
        far = sorted((a.id for a in scene.assets if a.category == name), key=lambda i: -_distance_to(scene, i, point))
        return [ToolCall(tool="remove_assets", args={"assets": far[: count or 1]})] if far else None
    if count:
        args["count"] = count
    if r.landmark:
        args["near"] = r.landmark
    elif count and r.ego and name != "ego_vehicle":
        args["near"] = "ego"  # "the two lamps closest to the ego"
    elif count and memory.last_focus() is not None and recent:
        args["near"] = recent[0]
    present = [a.id for a in scene.assets if a.category == name]
    if count == 1 and len(present) == 1:
        notes.subject = present  # "remove the hydrant, then put a bench where it was": that one
    return [ToolCall(tool="remove_assets", args=args)]


def _some(ids: list[str], count: int | None, fewer: bool, notes: Notes) -> list[str]:
    """Which of `ids` go: as many as said, else all, but only some when fewer are asked for ("too
    many lamps along Main Street": every other one, a guess, never every one)."""
    if count:
        return ids[:count]
    if fewer:
        notes.guess("how many fewer")
        return ids[1::2] or ids[:1]
    return ids


# "one blue and the other orange", "one red, one white": two colours shared out over things of a kind.
_ONE_AND_OTHER = re.compile(r"\bone\b[^.;]*?(?:\band|,|\bbut)\s+(?:(the other|another|one|the second)|the rest|the others)\b")


def recolour(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall] | None:
    """set_asset_appearance for "paint the bus red", "the bins should blend in with the grass",
    "make the benches wooden"."""
    asked = md.colours_asked(r.low)  # "paint the red car blue": blue
    paired = _colour_each(r, asked)
    if paired:  # "the SUV should be red and the bench green": each its own colour
        calls = [c for m, said in paired for c in recolour(replace(r, mentions=[m], low=r.low.replace(said, " " * len(said)) + f" {said}"),
                                                         scene, memory, notes) or []]
        if len(calls) == len(paired):
            return calls
    unwanted = set(md.NOT_THAT_COLOUR.findall(r.low))  # "make the hydrant less red": never red
    colour = asked[-1] if asked else next((c for c in COLOURS if r.has((c,)) and c not in unwanted and not md.SIGNAL_STATE.search(r.low)), None)
    if colour is None and r.has(("blend in", "match", "same colour as", "colour of", "coloured like")):
        colour = next((c for w, c in lx.COLOUR_OF.items() if r.has((w,))), None)
    if colour is None and (r.has(_CONSPICUOUS) or UNSEEN.search(r.low)) and not TOO_CONSPICUOUS.search(r.low):  # "it stands out too much": less, never more
        colour = CONSPICUOUS_COLOUR
    like = _COLOUR_FROM.search(r.low) if colour is None else None
    source = named_at(scene, f" {r.low[like.end():]}", []) if like is not None else None
    model = scene.asset(source) if source is not None else None
    if model is not None and model.appearance.rgba is not None:  # "the SUV the same colour as the bus": the bus's colour
        colour = hex_colour(model.appearance.rgba)
    material = md.material_said(r.masked)
    if colour is None and material is None:
        return None
    ids = [i for i in referenced(r, scene, memory, notes) if model is None or i != model.id]
    if not ids and not r.mentions and notes.subject:
        ids = notes.subject  # "the ego should be hard to miss; bright yellow would do": the earlier clause's thing
    if not ids:
        if r.mentions and r.has(("paint", "recolour", "colour")):
            raise ph_error(f"there is no {r.mentions[0].category} in the scene to recolour")
        return None
    look = {k: v for k, v in (("colour", colour), ("material", material)) if v is not None}
    shared = _ONE_AND_OTHER.search(r.low)
    if shared is not None and len(asked) == 2 and r.mentions:
        kind = [a.id for a in scene.assets if a.category == r.mentions[0].category]
        them = ids if len(ids) > 1 else kind
        if len(them) > 1:  # "paint one car blue and the other orange": the first, then the other (or the rest)
            return [ToolCall(tool="set_asset_appearance", args={"assets": them[:1], "colour": asked[0]}),
                    ToolCall(tool="set_asset_appearance", args={"assets": them[1:2] if shared.group(1) else them[1:], "colour": asked[1]})]
    if r.mentions and _HALF.search(r.low[: r.mentions[0].start]) and len(ids) > 1:  # "paint half the lamps red": the first half
        return [ToolCall(tool="set_asset_appearance", args={"assets": ids[: len(ids) // 2], **look})]
    every = {a.id for a in scene.assets if r.mentions and a.category == r.mentions[0].category}
    if r.mentions and r.mentions[0].plural and not r.ids and len(ids) > 1 and set(ids) == every:
        # "paint the cones orange": every one of a kind; "the cars in lot B" (an SUV too) are those named
        return [ToolCall(tool="set_asset_appearance", args={"category": r.mentions[0].category, **look})]
    return [ToolCall(tool="set_asset_appearance", args={"assets": ids, **look})]


def _colour_each(r: Reading, asked: list[str]) -> list[tuple[ph.Mention, str]]:
    """Things each said with its own colour after it ("the SUV should be red and the bench green"),
    as (thing, colour) pairs in the order said; [] unless things and colours take turns."""
    if len(asked) < 2 or len(r.mentions) != len(asked):
        return []
    colours = list(re.finditer(rf"\b(?:{'|'.join(asked)})\b", r.low))
    order = sorted([(m.start, "thing") for m in r.mentions] + [(c.start(), "colour") for c in colours])
    if [kind for _, kind in order] != ["thing", "colour"] * len(asked) or len(colours) != len(asked):
        return []
    return [(m, c.group(0)) for m, c in zip(sorted(r.mentions, key=lambda m: m.start), colours, strict=True)]


def ph_error(message: str) -> Exception:
    from drivetwin.orchestrator.planning.base import PlanningError

    return PlanningError(message)


# On foot over a road or a crossing ("walking across the north crosswalk", "hurrying over the road").
_GOING_ACROSS = re.compile(r"\b(?:walk|run|hurr|dash|dart|jog|head|go|stroll|step|wander|strid|march|ambl|saunter|trot|sprint)"
                           r"\w*\s+(?:(?:out|off|straight|right|on)\s+)?(?:across|over)\s+(?:the\s+)?"
                           r"(?:road|street|crossing|crosswalk|zebra|junction|intersection|§)"
                           # "go over to the other side": of the road it stands by
                           r"|\b(?:walk|go|get|head|cross|make (?:his|her|their|its) way)\w*\s+(?:over\s+|across\s+)?to\s+the\s+(?:other|far)\s+side\b"
                           r"(?!\s+of\s+(?:the\s+)?(?!road|street)[a-z])")

def _without_things(r: Reading) -> str:
    """The clause's masked words with the things it names, and their articles and numbers, left out:
    a verb and its particle said round the thing ("walk a pedestrian across the crosswalk") read together."""
    out = r.masked
    for m in sorted(r.mentions, key=lambda m: -m.start):
        start = _ARTICLE_BEFORE.search(out, 0, m.start)
        out = out[: start.start() if start is not None else m.start] + out[m.end :]
    return re.sub(r"\s+", " ", out)


# An article or number just before a thing's word ("a", "the", "two", "3").
_ARTICLE_BEFORE = re.compile(r"\b(?:a|an|the|one|two|three|four|five|some|\d+)\s+$")

# Going somewhere on foot or on wheels ("walk to the fountain", "stroll along the sidewalk", "drive down Main Street").
_GOING_TO = re.compile(r"\b(?:walk|stroll|jog|march|wander|drive|drove|driving)\w*\s+(?:to|towards?|along|around|down|up|off)\b")

# What "leave" leaves somewhere ("leave it at the union", "leave a car in lot A"): a place to stay.
_LEFT_AT = re.compile(r"\s+(?:it|them|that|this|those|these|(?:the|that|this|a|an|one|another|some|two|three|their|his|her|my|our|your)"
                      r" [a-z_]+(?: [a-z_]+)?)\s+"
                      r"(?:at|by|near|in|on|outside|next|beside|behind|there|here|§)")


def behaviour_kind(r: Reading, category: Category | None = None) -> str | None:
    """The behaviour a clause names, if it suits an asset of `category`."""
    for kind in ("jaywalk", "circle", "cross_road", "drive_lane", "parked"):
        said = inflected(lx.BEHAVIOUR_WORDS[kind]).search(ph.normalise(r.masked)) if kind == "drive_lane" else None
        said = said or (re.search(r"\bjaywalk\w*", r.masked) if kind == "jaywalk" else None)  # "jaywalks", "jaywalked"
        if said and said.group(0).startswith("head") and r.has(lx.BEHAVIOUR_WORDS["parked"]):
            said = None  # "park a car in lot A, heading north": which way it faces
        if said and said.group(0).startswith("leav") and _LEFT_AT.match(ph.normalise(r.masked)[said.end() :]):
            said = None  # "leave it at the Student Union": where it stays
        plain = kind != "drive_lane" and r.has(lx.BEHAVIOUR_WORDS[kind])  # the driving words are read inflected
        # "someone crossing at the west crosswalk": the walker named, then what it is doing
        doing = kind == "cross_road" and any(re.match(r"\s*crossing\b", r.low[m.end :]) for m in r.mentions)
        across = kind == "cross_road" and bool(_GOING_ACROSS.search(r.masked) or _GOING_ACROSS.search(_without_things(r)))
        if not said and not plain and not doing and not across:
            continue
        if category is not None and (
            (kind in ("jaywalk", "cross_road") and category.motion != "walker")
            or (kind in ("circle", "drive_lane") and not category.drives)
        ):
            continue
        return kind
    if category is not None and category.drives and (ph.find_speed(r.text) or says_oncoming(r.low)):
        return "drive_lane"  # "a car in front of the ego doing 12 m/s", "a car coming the other way": a thing on the move
    return None


def behaviour_spec(kind: str, r: Reading, scene: Scene | None = None) -> dict[str, Any]:
    """The BehaviourSpec arguments for `kind` with what the clause says (speed, radius, lane; with
    `scene`, a speed said against the ego's: "going slower than we are")."""
    spec: dict[str, Any] = {"kind": kind}
    speed = ph.find_speed(r.text)
    than = _THAN_EGO.search(r.low) if speed is None and scene is not None and scene.asset("ego") is not None else None
    if than is not None and scene is not None:
        now = getattr(scene.ego.behaviour, "speed", None) or DEFAULT_PACE_MS
        speed = round(now / PACE_FACTOR if than.group(1) == "slower" else now * PACE_FACTOR, 2)
    if speed:
        spec["speed"] = speed
    if kind == "circle":
        radius = nb.radius_said(r.low)
        if radius is not None:
            spec["radius"] = radius
        if r.has(("clockwise",)) and not r.has(("anticlockwise", "counterclockwise", "counter-clockwise")):
            spec["clockwise"] = True
        if r.landmark:
            spec["centre"] = r.landmark  # "circles in lot B": round that place, not where it stands
    if kind == "drive_lane" and r.lane:
        spec["lane"] = r.lane
    return spec


# A new speed for one thing that is there: "set the ego's speed to 8 m/s", "the truck should be doing
# about 10 m/s", "could the ego go a bit slower?" (by PACE_FACTOR when no speed is said).
_PACE_SAID = re.compile(r"\b(?:speed|pace|doing|going|go|goes|drive|drives|driving|travel(?:s|ling|ing)?|move|moves|moving"
                        r"|cruise|cruising|ride|rides|riding|walk|walks|walking|slow|slows|slowed|slowing)\b")
# ("reduce ego speed", "raise the ego's speed": whose speed said between)
_WHOSE_SPEED = r"(?:(?:its|the|their|his|her|our)\s+)?(?:[a-z_0-9]+(?:'s)?\s+)?speed"
_SLOWER = re.compile(rf"\b(?:slower|slow (?:[a-z_0-9']+ ){{0,3}}?down|less fast|(?:reduce|lower|decrease|cut) {_WHOSE_SPEED}"
                     r"|more (?:gently|calmly|carefully|cautiously|slowly))\b")  # "might the ego proceed a little more gently?"
_FASTER = re.compile(rf"\b(?:faster|quicker|speed (?:[a-z_0-9']+ ){{0,3}}?up|(?:increase|raise) {_WHOSE_SPEED})\b")
PACE_FACTOR = 1.5
# A speed said as a bare number after a change of pace: "slow it to 3", "speed up to 6, please".
_BARE_PACE = re.compile(r"\b(?:down |up )?to (\d+(?:\.\d+)?)\b(?!\s*(?:[%°:/]|\.\d|m\b|ms\b|metres?|meters?|km|kph|mph|s\b|secs?\b|seconds?"
                        r"|minutes?|hours?|o'?clock|am\b|pm\b|times\b|of\b|cars?\b|people\b))")
# A pace said against the ego's: "going slower than we are", "a bit faster than our car".
_THAN_EGO = re.compile(r"\b(slower|faster|quicker)\s+than\s+(?:we|us|me|i|the ego|ego|our car|my car|our vehicle)\b")
# A speed said as a multiple of the one now: "double its speed", "halve the truck's speed".
_TIMES = {"double": 2.0, "twice": 2.0, "triple": 3.0, "halve": 0.5, "half": 0.5}
_TIMES_SAID = re.compile(r"\b(double|twice|triple|halve|half)\b(?=[^.;!?]*\b(?:speed|pace|fast|quick)\w*\b)")
# A moving thing's speed when its behaviour does not say one (the Workers' own default).
DEFAULT_PACE_MS = 5.0
_ADDING = ("add", "spawn", "put", "place", "create", "insert", "another", "new")


def new_pace(r: Reading, scene: Scene, notes: Notes, memory: Memory) -> list[ToolCall] | None:
    """set_behaviour keeping what one thing there does, at the speed said (or slower, faster);
    None when the clause says no speed, adds things, names several, or asks for another behaviour.
    "It" with nothing named in the request is the one thing the last turn made or changed."""
    speed = ph.find_speed(r.text)
    times = _TIMES_SAID.search(r.low) if speed is None else None
    slower = _SLOWER.search(r.low) is not None or (times is not None and _TIMES[times.group(1)] < 1)
    faster = _FASTER.search(r.low) is not None or (times is not None and _TIMES[times.group(1)] > 1)
    bare = _BARE_PACE.search(r.low) if speed is None and (slower or faster or re.search(r"\bslow\b", r.low)) else None
    if bare is not None:  # "slow it to 3", "speed the ego up to 6": metres a second, the speed the Workers take
        speed = float(bare.group(1))
        notes.guess("a speed said without its unit, read as m/s")
    if (speed is None and slower == faster) or (speed is not None and not _PACE_SAID.search(r.low)) or r.has(_ADDING):
        return None
    if r.ids or (r.ego and not r.mentions):
        ids = r.ids or ["ego"]
    elif len(r.mentions) == 1 and not r.mentions[0].plural:
        ids = [a.id for a in scene.assets if a.category == r.mentions[0].category]
    else:
        ids = notes.subject if not r.mentions and not r.ego else []  # "..., it should be doing 10 m/s"
        if not ids and not r.mentions and not r.ego and r.has(("it", "he", "she")):  # "can it go a bit faster?"
            ids = list(dict.fromkeys(i for i in memory.last_touched() if scene.asset(i) is not None))
    found = scene.asset(ids[0]) if len(ids) == 1 else None
    if found is None:
        return None
    category = catalog()[found.category]
    now = found.behaviour
    kind = now.kind if now.kind != "parked" else "drive_lane" if category.drives else None
    allowed = {None, kind, "parked"} if now.kind == "parked" else {None, kind}  # "the parked suv": its state now
    asked = behaviour_kind(r, category)
    if asked == "drive_lane" and not re.search(r"\b(?:drive|drives|driving|lane|road|street)\b", r.low):
        asked = None  # "can it go a bit faster?": going is the pace, not a drive along a lane
    if kind is None or asked not in allowed:
        return None  # "make the suv circle at 5 m/s": another behaviour, planned as one
    current = getattr(now, "speed", None) or DEFAULT_PACE_MS  # a parked thing has none
    if speed is None and times is not None:  # "double its current speed": twice what it does now
        speed = round(current * _TIMES[times.group(1)], 2)
    elif speed is None:
        notes.guess("how much slower" if slower else "how much faster")
        speed = round(current / PACE_FACTOR if slower else current * PACE_FACTOR, 2)
    spec = {**now.model_dump(exclude_none=True), "kind": kind, "speed": speed}
    if isinstance(spec.get("centre"), (tuple, list)):  # a circle's centre as the Worker takes it: "x,y"
        spec["centre"] = ",".join(f"{float(v):g}" for v in spec["centre"])
    if kind == "drive_lane" and r.lane:
        spec["lane"] = r.lane
    notes.subject = [found.id]
    return [ToolCall(tool="set_behaviour", args={"asset": found.id, "behaviour": spec})]


# A colour said as another thing's: "the same colour as the bus", "to match the bench".
_COLOUR_FROM = re.compile(r"\b(?:same colou?r as|colou?r of|colou?red like|match(?:es|ing)?(?: the colou?r of)?)\s+")
# An amount said vaguely: "some", "a few" of them.
_VAGUE_PART = re.compile(r"\b(?:some|several|a few|a handful)\b")  # ("a couple" is two, even of two)
# A thing pointed back at ("remove it", "get rid of them"): never a place of the map.
_PRONOUN = re.compile(r"\b(?:it|them|those|these|that one|this one)\b")
# Waiting somewhere, as a thing standing still does ("wait at the bus stop", "stand by the fountain"); never
# "stop at the crosswalk", which is what a moving thing does when it gets there.
_WAITS = re.compile(r"\b(?:wait|waits|waiting|stand|stands|standing|queue|queues|queueing|linger|lingers|idle|idles|idling)\b")
# "Up" said of moving a thing that drives: forward, as a queue moves up.
_UP = re.compile(r"\b(?:move|moves|moved|inch|edge|creep|roll|bring|shift)\s+(?:\S+\s+){0,3}up\b(?!\s+(?:to|the|north))")


TOWARD = re.compile(r"\b(?:towards?|in the direction of|(?:closer|nearer)(?: to)?|(?P<away>(?:further|farther|more|well|back)(?: away)? from|away from))\b")


# A thing moved "well away" or "far from" another, no distance said, goes this far.
FAR_STEP_M = 10.0
_WELL_AWAY = re.compile(r"\b(?:well|far|way|right|a long way|a good (?:way|distance)|much further|much farther) (?:away )?from\b")
# A thing moved "a bit closer" to another, no distance said, stops at least this far from it.
TOWARD_CLEARANCE_M = 1.5
# A thing moved closer to the road stops this far short of its edge.
KERB_MARGIN_M = 0.5
# The road as such, after "closer to": "closer to the road", "nearer the kerb".
_ROAD_AFTER = re.compile(r"\s+(?:to\s+)?(?:the\s+)?(?:road|street|kerb|curb|carriageway|traffic|lane)\b")


def _toward(r: Reading, scene: Scene, ids: list[str], shift: float | None, vague: bool = False) -> dict[str, float] | None:
    """East and north for moving `ids` `shift` metres toward the place, road or ego named after
    "toward" or "closer to" (away from it after "further from" or "away from"), from the middle of
    where they stand; None when the words say no such move."""
    said = TOWARD.search(r.low)
    things = [a for i in ids if (a := scene.asset(i)) is not None]
    if said is None or shift is None or not things or md.compass_direction(r.masked) is not None:
        return None  # "one metre north, away from the road": the compass way says it
    x = sum(a.pose.x for a in things) / len(things)
    y = sum(a.pose.y for a in things) / len(things)
    landmark = scene.landmark(r.landmark) if r.landmark and r.landmark_at > said.start() else None
    lane = scene.roads.lane(r.lane) if r.lane else None
    # "5 m closer to the bench": the nearest one there is of the thing named after the word
    named = [a for m in r.mentions if m.start > said.start() for a in scene.assets if a.category == m.category and a.id not in ids]
    named += [a for i in r.ids if i not in ids and r.low.find(i.replace("_", " ")) > said.start() and (a := scene.asset(i)) is not None]
    if landmark is not None:
        goal = landmark.position
    elif named:
        nearest = min(named, key=lambda a: math.dist((a.pose.x, a.pose.y), (x, y)))
        goal = (nearest.pose.x, nearest.pose.y)
    elif lane is not None:  # the nearest point of the road, any of its lanes
        lanes = [ln for ln in scene.roads.lanes if ln.road == lane.road] if lane.road else [lane]
        near = min((nearest_on_polyline(x, y, ln.centreline) for ln in lanes), key=lambda p: p.distance)
        goal = (near.x, near.y)
    elif r.ego and "ego" not in ids:
        goal = (scene.ego.pose.x, scene.ego.pose.y)
    elif _ROAD_AFTER.match(r.low, said.end()) and scene.roads.lanes:  # "closer to the road": its nearest lane
        lane, near = min(((ln, nearest_on_polyline(x, y, ln.centreline)) for ln in scene.roads.lanes), key=lambda p: p[1].distance)
        goal = (near.x, near.y)
        if not said.group("away"):  # up to the kerb, never onto the road
            shift = min(shift, max(0.0, near.distance - lane.width / 2 - KERB_MARGIN_M))
    else:
        return None
    gap = math.dist((x, y), goal)
    if gap < 1e-6 or shift <= 0.0:
        return None
    if vague and said.group(0).startswith(("closer", "nearer")) and not r.has(("nudge", "budge", "inch", "scoot")):
        # "a bit closer to the bench": a step people see, half the way there at most
        shift = max(shift, min(gap / 2, gap - TOWARD_CLEARANCE_M))
    if vague and said.group("away") and _WELL_AWAY.search(r.low):  # "somewhere well away from the junction": a long way
        shift = max(shift, FAR_STEP_M)
    step = -shift if said.group("away") else shift
    return {"east": round(step * (goal[0] - x) / gap, 2), "north": round(step * (goal[1] - y) / gap, 2)}


# A thing a thing should face: "so it faces the road", "turn it to face the fountain", "facing the ego".
# The back said to face something: "so its back end faces the road", "rear facing the kerb", "with its back to".
_BACK_FACES = re.compile(r"\b(?:back|rear|tail|boot|backside)(?:\s+end)?\s+(?:fac(?:e|es|ing)|point(?:s|ing)?)\b")
# "face away from the road": the other way from it
_FACES_AWAY = re.compile(r"\b(?:fac(?:e|es|ing)|point(?:s|ed|ing)?|turn(?:s|ed)?)\s+away\s+from\b")
_FACES = re.compile(r"\b(?:fac(?:e|es|ing)|point(?:s|ed|ing)?(?:\s+(?:it|them|the\s+\w+|\w+_\d+|ego))?)\s+(?:away\s+from\s+|towards?\s+|onto\s+|at\s+)?"
                    r"(?:the\s+)?(?:(?P<road>road|street|lane|traffic|kerb|curb|carriageway)"
                    r"|(?P<ego>ego|our car|my car)|(?P<place>§))")


def _faced_point(r: Reading, scene: Scene, thing: AssetInstance) -> tuple[float, float] | None:
    """The point the words say a thing should face: the nearest point of a road, the ego or the
    place named; None when they name none."""
    said = _FACES.search(r.masked)
    if said is None:
        return None
    if said.group("road"):
        lanes = [lane for lane in scene.roads.lanes if not r.lane or lane.id == r.lane]
        near = min((nearest_on_polyline(thing.pose.x, thing.pose.y, lane.centreline) for lane in lanes),
                   key=lambda p: p.distance, default=None)
        return (near.x, near.y) if near is not None else None
    ego = scene.asset("ego")
    if said.group("ego") or (r.ego and not r.landmark and r.ego_at >= said.start()):  # the ego is blanked like a place
        return (ego.pose.x, ego.pose.y) if ego is not None and thing.id != "ego" else None
    landmark = scene.landmark(r.landmark) if r.landmark else None
    return (landmark.position[0], landmark.position[1]) if landmark is not None else None


# The words that say a thing faces something, in plain text: "facing the fountain", "to face the road".
_FACES_PLAIN = re.compile(r"\b(?:fac(?:e|es|ing)|point(?:s|ed|ing)?)\s+(?:towards?\s+|onto\s+|at\s+)?(?!away\b)")


def faced_from(r: Reading, scene: Scene, x: float, y: float) -> tuple[float, float] | None:
    """The point the words say a new thing standing at (x, y) should face: the nearest point of a
    road, the ego or a place named right after "facing"; None when they say it faces nothing
    ("facing north" is md.facing_direction's); a PlanningError when what it faces is not read."""
    plain = _FACES_PLAIN.search(r.low)
    if plain is None or _FACES_AWAY.search(r.low) or _BACK_FACES.search(r.low):
        return None
    after = r.low[plain.end() :]
    if re.match(r"(?:the\s+)?(?:road|street|lane|traffic|kerb|curb|carriageway)\b", after):
        near = min((nearest_on_polyline(x, y, lane.centreline) for lane in scene.roads.lanes), key=lambda p: p.distance, default=None)
        return (near.x, near.y) if near is not None else None
    ego = scene.asset("ego")
    if re.match(r"(?:the\s+)?(?:ego|our car|my car)\b", after):
        return (ego.pose.x, ego.pose.y) if ego is not None else None
    faced = re.split(r"[,;.]|\b(?:at|in|on|by|near|next to|beside|outside|and|so|with)\b", after, maxsplit=1)[0]  # "the library at the fountain"
    place = find_place(scene, f" {faced} ")
    landmark = scene.landmark(place[0]) if place is not None else None
    if landmark is not None:
        return landmark.position[0], landmark.position[1]
    if re.match(r"the\s+[a-z]", after) and md.facing_direction(r.low) is None:
        raise ph_error(f"I could not tell what it should face from {r.low[plain.start() :].strip()!r}; it can face "
                       "a compass point, the road, the ego or a place, e.g. 'facing the fountain'")
    return None


# Driving the other way: "going the other way", "in the opposite direction".
_OTHER_WAY = re.compile(r"\b(?:go|goes|going|drive|drives|driving|head|heading|travel\w*|run|running)\s+(?:\w+\s+)?"
                        r"(?:the\s+)?(?:other|opposite)\s+(?:way|direction)\b|\bin the opposite direction\b")


def _lane_back(found: AssetInstance, scene: Scene) -> str | None:
    """For a vehicle driving a lane, its road's lane that runs the other way; else None."""
    if found.behaviour.kind != "drive_lane":
        return None
    lane = scene.roads.lane(found.behaviour.lane)
    if lane is None:
        return None
    here = nearest_on_polyline(found.pose.x, found.pose.y, lane.centreline)
    back = [other for other in scene.roads.lanes if other.road == lane.road and other.id != lane.id
            and math.cos(nearest_on_polyline(found.pose.x, found.pose.y, other.centreline).heading - here.heading) < -0.5]
    return min(back, key=lambda o: nearest_on_polyline(found.pose.x, found.pose.y, o.centreline).distance).id if back else None


def _turn_for(r: Reading, scene: Scene, thing: AssetInstance, deg: re.Match[str] | None, facing: str | None,
              notes: Notes) -> float:
    """How far to turn `thing` (degrees, anticlockwise) for what the words say: an angle, to face a
    point or a compass way (from where it points now), round, or a small or default turn."""
    faced = _faced_point(r, scene, thing) if facing is None else None
    if deg:  # "45 degrees clockwise", "30 to the right": turn_deg counts anticlockwise
        right = r.has(("right", "clockwise")) and not r.has(("anticlockwise", "counterclockwise", "counter-clockwise"))
        return -float(deg.group(1)) if right else float(deg.group(1))
    if faced is not None:  # "so it faces the road": towards its nearest point; "its back faces the road": away
        heading = math.degrees(math.atan2(faced[1] - thing.pose.y, faced[0] - thing.pose.x))
        heading += 180.0 if _BACK_FACES.search(r.masked) or _FACES_AWAY.search(r.masked) else 0.0
        return round((heading - math.degrees(thing.pose.yaw) + 180.0) % 360.0 - 180.0, 1)
    if facing is not None:  # "turned to face north": the turn from where it points now to that compass heading
        east, north = md.COMPASS_VECTORS[facing]
        return round((math.degrees(math.atan2(north, east) - thing.pose.yaw) + 180.0) % 360.0 - 180.0, 1)
    if r.has(("around", "round", "wrong way", "other way", "opposite way", "opposite direction", "flip", "about")):  # "spin the bench round"
        return 180.0
    notes.guess("how far to turn")
    if r.has(md.SMALL_MOVE):  # "turn the suv a little to the left", "just a touch": a small turn, that way
        return -SMALL_TURN_DEG if r.has(("right", "clockwise")) and not r.has(("anticlockwise", "counterclockwise")) else SMALL_TURN_DEG
    return DEFAULT_SPIN_DEG


def edit_existing(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall] | None:
    """Move, turn, stop, set the behaviour of or place assets already there; None if not that."""
    ids = referenced(r, scene, memory, notes)
    if not ids:
        return None
    asset = ids[0]
    found = scene.asset(asset)
    motion = catalog()[found.category].motion if found is not None else None
    picked = find_place(scene, r.low)
    sent = destination(scene, r.low, picked)
    if sent is not None and picked is not None:  # "move the tree by lot A over to the fountain": lot A picks it, the fountain is where it goes
        mark = scene.landmark(picked[0])
        pool = [a for a in scene.assets if r.mentions and a.category == r.mentions[0].category]
        if mark is not None and pool and not r.ids and not r.mentions[0].plural:
            found = min(pool, key=lambda a: math.dist((a.pose.x, a.pose.y), mark.position))
            asset, ids, notes.subject = found.id, [found.id], [found.id]
        r = replace(r, landmark=sent[0], landmark_at=sent[1])
    elif picked is not None and r.landmark == picked[0] and _PICKED_NEAREST.search(r.low[: picked[1]]):
        r = replace(r, landmark=None)  # "move the tree closest to the library 5 m east": which tree, not where to
    metres = ph.find_distance(r.text)
    if r.has(lx.REVERSE_WORDS) or _BACK_IT_UP.search(r.low):  # "back that SUV up 3 metres"
        if metres is None:
            notes.guess("how far to reverse")
        step = metres or (SMALL_STEP_M if r.has(md.SMALL_MOVE) else DEFAULT_STEP_M)
        return [ToolCall(tool="move_asset", args={"asset": asset, "forward": -abs(step)})]
    if r.has(lx.STOP_WORDS) and motion in ("vehicle", "walker") and not r.has(("stop sign",)):
        where = location(r, scene, memory, notes, exclude=ids) if _WAITS.search(r.low) and r.landmark else None
        if where is not None and found is not None and found.behaviour.kind == "parked":
            # "make the bus wait at the bus stop": one standing elsewhere goes there to wait
            return [ToolCall(tool="place_asset", args={"asset": asset, "location": where})]
        return [ToolCall(tool="set_behaviour", args={"asset": asset, "behaviour": {"kind": "parked"}})]
    back = _lane_back(found, scene) if found is not None and _OTHER_WAY.search(r.low) else None
    if back is not None:  # "the ego should be going the other way down Main Street": the road's lane that runs back
        return [ToolCall(tool="set_behaviour", args={"asset": asset, "behaviour": {"kind": "drive_lane", "lane": back}})]
    if found is not None and found.category == "street_light" and _SWITCHED.search(r.low):  # "turn off street light 1"
        raise ph_error("the street lights are switched all together, not one by one; say 'turn the street lights off' "
                       "(or on) for all of them")
    deg = re.search(r"(-?\d+(?:\.\d+)?)\s*(?:deg|°)", r.low) or (_bare_angle(r.low, scene) if r.has(("turn", "rotate", "spin")) else None)
    facing = md.facing_direction(r.masked)
    faced = _faced_point(r, scene, found) if facing is None and found is not None else None
    if facing is not None or faced is not None or (
        r.has(lx.TURN_WORDS)
        and (deg or not r.has(("drive", "driving", "walk", "circle", "circles")))
        and (deg or r.has(("turn", "turned", "rotate", "rotated", "spin", "flip", "wrong way", "other way", "faces", "face")))
    ):
        # each thing named is turned: "turn the cars in lot B to face south" is all three, each its own way round
        things = [a for i in ids if (a := scene.asset(i)) is not None] or ([found] if found is not None else [])
        turns = [(thing.id, _turn_for(r, scene, thing, deg, facing, notes)) for thing in things] if things else [(asset, None)]
        wanted = [(i, angle) for i, angle in turns if angle is None or abs(angle) >= 1.0]
        placed = ph.find_coordinates(r.low) is not None or r.landmark is not None  # "put us at x -90, y -1.75, facing east"
        if not wanted and not placed:
            way = facing or "that way"  # "suv_1 already faces north"
            raise ph_error(f"{', '.join(i for i, _ in turns)} already face{'s' if len(turns) == 1 else ''} {way}")
        if wanted:
            return [ToolCall(tool="move_asset", args={"asset": i, "turn_deg": angle if angle is not None else DEFAULT_SPIN_DEG})
                    for i, angle in wanted]
        # it faces that way already: where it goes is the request
    kind = behaviour_kind(r, catalog()[found.category] if found is not None else None)
    if kind is None and motion not in (None, "vehicle", "walker") and (_GOING_ACROSS.search(r.masked) or _GOING_TO.search(r.masked)
                                                                       or re.search(r"\bfollow(?:s|ing)?\b", r.masked)):
        # "can the tree by the bus stop walk across the road": a fixed thing goes nowhere by itself
        raise ph_error(f"a {found.category.replace('_', ' ') if found else 'thing'} cannot walk or drive; only pedestrians, "
                       "riders, vehicles and robots move by themselves. I can put it somewhere else instead")
    if kind is None and found is not None and catalog()[found.category].drives and md.SET_GOING.search(r.low):
        kind = "drive_lane"  # "get the suv moving": off it drives
    drive = drive_towards(r, scene, found) if found is not None and kind in (None, "drive_lane") and catalog()[found.category].drives else None
    if drive is not None and found is not None and catalog()[found.category].motion == "vehicle":
        notes.subject = [asset]  # "the suv drives to the main gate": into the lane that leads there, where it stands
        return [ToolCall(tool="set_behaviour", args={"asset": asset, "behaviour": drive[0]})]
    vehicle = found is not None and kind in (None, "drive_lane") and catalog()[found.category].motion == "vehicle"
    went = GOES_TO.search(r.low)  # "could the suv go to the other car park": where it is to be, not a drive
    if vehicle and went is not None and not re.match(r"(?:go|goes|going|gone|went)\b", went.group(0)) \
            and (route := walk_said(r, scene, exclude=ids)) is not None and route.start is None:
        # "the suv makes its way to the library entrance", where no lane leads: there by path, never a jump there
        speed = ph.find_speed(r.text)
        behaviour = {"kind": "follow_path", "to": route.behaviour["to"], **({"speed": speed} if speed else {})}
        return [ToolCall(tool="set_behaviour", args={"asset": asset, "behaviour": behaviour})]
    rider = found is not None and kind == "drive_lane" and catalog()[found.category].motion == "walker"
    if rider and (ride := walk_said(r, scene, exclude=ids)) is not None:  # "have the cyclist ride to the library": by path
        return [ToolCall(tool="set_behaviour", args={"asset": asset, "behaviour": ride.behaviour})]
    if kind == "drive_lane" and r.landmark and not r.lane and r.has(("go", "goes")):
        kind = None  # "could the car go in lot A?": a place to be, not a lane to drive
    if kind == "drive_lane" and r.has(("go", "goes")) and _STEP_SAID.search(r.low):
        kind = None  # "could it go forward a tiny bit?": a step, not a drive
    if kind is not None and kind != "parked":
        # "make the cars move": each of them, those that can
        movers = [i for i in ids if (a := scene.asset(i)) is not None and (kind != "drive_lane" or catalog()[a.category].drives)]
        plural = bool(r.mentions and r.mentions[0].plural) or _EACH_OF_THEM.search(r.low) is not None
        going = movers if plural and len(movers) > 1 else [asset]  # "both of them cross": the two
        notes.subject = going
        return [ToolCall(tool="set_behaviour", args={"asset": i, "behaviour": behaviour_spec(kind, r)}) for i in going]
    # "8 m ahead of the ego" places it relative to the ego; "8 m ahead" shifts it from where it is.
    scoped = (bool(r.mentions) and _scoped_by_place(r, r.mentions[0])) or (not r.mentions and bool(_ANY_NEAREST.search(r.low)))
    anchored = (r.landmark and not scoped) or (r.ego and "ego" not in ids) or any(i not in ids for i in r.ids)
    small = r.has(md.SMALL_MOVE)
    shift = metres if metres is not None else (SMALL_STEP_M if small else None)
    if shift is None and _SIDE_MOVE.search(r.low):
        notes.guess("how far to move")  # "the SUV should pull forward a few metres"
        shift = DEFAULT_STEP_M
    moved: dict[str, Any] = {"asset": asset} if len(ids) == 1 else {"assets": ids}
    if shift is None and (away := TOWARD.search(r.low)) is not None and (away.group("away") or _ROAD_AFTER.match(r.low, away.end())) \
            and md.compass_direction(r.masked) is None:
        notes.guess("how far to move it")  # "push the bin further from the bus stop", "closer to the road": a step, never onto it
        shift = DEFAULT_STEP_M
    toward = _toward(r, scene, ids, shift, vague=metres is None)
    if toward is not None:  # "4 m toward Main Street": straight at it, from where they stand
        return [ToolCall(tool="move_asset", args={**moved, **toward})]
    compass = md.compass_vector(r.masked)
    if compass is not None and shift is not None and not anchored:
        east, north = compass  # "4 m north-east": both ways at once
        return [ToolCall(tool="move_asset", args={**moved, "east": round(east * shift, 2), "north": round(north * shift, 2)})]
    drives = found is not None and catalog()[found.category].drives
    if drives and _UP.search(r.low) and not anchored:  # "move our car up a bit": on along its way
        return [ToolCall(tool="move_asset", args={**moved, "forward": shift or DEFAULT_STEP_M})]
    # "it's parked too far forward, back it 2 m": the way it is too far is the trouble, not the way to go
    said_ways = _TOO_FAR_WAY.sub(" ", r.masked)
    for word, key, sign in lx.SIDE_WORDS:
        if shift is not None and ph.has_any(said_ways, (word,)) and not anchored:
            return [ToolCall(tool="move_asset", args={**moved, key: sign * shift})]
    kind_of = found.category if found is not None else asset.rpartition("_")[0] if asset in notes.coming else None  # one an earlier clause adds
    walker = kind_of in catalog() and catalog()[kind_of].motion == "walker"
    walk = walk_said(r, scene, exclude=ids) if walker and not scoped else None
    if walk is not None:  # "make him walk to the library": on foot from where he stands; "the pedestrians": each
        walkers = [i for i in ids if (a := scene.asset(i)) is not None and catalog()[a.category].motion == "walker"]
        plural = bool(r.mentions and r.mentions[0].plural) or _EACH_OF_THEM.search(r.low) is not None
        return [ToolCall(tool="set_behaviour", args={"asset": i, "behaviour": walk.behaviour})
                for i in (walkers if plural and len(walkers) > 1 else [asset])]
    across = _across_the_road(scene, found) if found is not None and _OTHER_SIDE.search(r.low) else None
    if across is not None:  # "stick the hydrant on the other side of the road": where it stands, mirrored over the road
        return [ToolCall(tool="place_asset", args={"asset": asset, "location": {"relation": "absolute", "x": across[0], "y": across[1]}})]
    # the place said which, not where to ("move the lamp post by the stop sign to the Engineering Hall")
    where = None if scoped else location(_without_description(r, scene) or r, scene, memory, notes, exclude=ids)
    if where is not None:
        # "move them to the gate": each of them, side by side; a layout ("in one line") is not one place
        group = ids if where.get("relation") != "absolute" and md.layout_said(r.low) is None else [asset]
        notes.subject = group
        return [ToolCall(tool="place_asset", args={"asset": i, "location": where}) for i in group]
    if kind == "parked":
        return [ToolCall(tool="set_behaviour", args={"asset": asset, "behaviour": {"kind": "parked"}})]
    if r.has(lx.SHIFT_VERBS):
        if (said := _DESTINATION.search(r.low)) is not None:  # a place it goes to, said but not found: never a guess
            raise ph_error(f"I could not tell where {said.group(0)!r} is; name a place of this world or say how far which way")
        notes.guess(WAY_GUESSED)
        step = metres or (SMALL_STEP_M if r.has(md.SMALL_MOVE) else DEFAULT_STEP_M)
        every = [scene.asset(i) for i in ids]
        along = all(a is not None and catalog()[a.category].drives for a in every)  # a car moves on along its way
        return [ToolCall(tool="move_asset", args={**moved, "forward" if along else "left": step})]
    return None


# A way said as how far out of place a thing is: "too far forward", "too much to the left".
_TOO_FAR_WAY = re.compile(r"\btoo (?:much |far |)(?:to the )?(?:forwards?|backwards?|back|left|right|over)\b")


# The guess the rules note when a move says no way to go ("move the bench 3 m", "shift it kerbside"): the planner asks.
WAY_GUESSED = "where to move it"


def other_ways(calls: list[ToolCall]) -> list[list[ToolCall]]:
    """`calls` with their one move by a step, as made on WAY_GUESSED, taken each way it could
    have meant: ahead and back for a thing that drives, left, right and ahead for others."""
    moves = [i for i, c in enumerate(calls) if c.tool == "move_asset" and len({"forward", "left"} & set(c.args)) == 1]
    if len(moves) != 1:
        return []
    i = moves[0]
    key = "forward" if "forward" in calls[i].args else "left"
    step = abs(float(calls[i].args[key]))
    ways = [("forward", step), ("forward", -step)] if key == "forward" else [("left", step), ("left", -step), ("forward", step)]
    rest = {k: v for k, v in calls[i].args.items() if k != key}
    return [[*calls[:i], calls[i].model_copy(update={"args": {**rest, k: v}}), *calls[i + 1 :]] for k, v in ways]


# The far side of the road a thing stands by: "on the other side of the road", "across the street" (the
# articles may be left out: "to other side of road").
_OTHER_SIDE = re.compile(r"\b(?:on|to|onto|over to) (?:the )?other side of (?:the )?(?:road|street)\b|\bacross the (?:road|street) from where it is\b")


def _across_the_road(scene: Scene, thing: AssetInstance) -> tuple[float, float] | None:
    """Where `thing` stands mirrored over the middle of the road it is beside: the point as far
    past the road's centre as it stands before it; None with no road near."""
    return _across_the_road_at(scene, (thing.pose.x, thing.pose.y))


def _across_the_road_at(scene: Scene, point: tuple[float, float]) -> tuple[float, float] | None:
    """`point` mirrored over the middle of the road nearest it; None with no road."""
    x, y = point
    lanes = scene.roads.lanes
    if not lanes:
        return None
    nearest = min(lanes, key=lambda ln: nearest_on_polyline(x, y, ln.centreline).distance)
    feet = [nearest_on_polyline(x, y, ln.centreline) for ln in lanes if ln.road == nearest.road]
    cx, cy = sum(f.x for f in feet) / len(feet), sum(f.y for f in feet) / len(feet)
    return round(2 * cx - x, 2), round(2 * cy - y, 2)


# Words that say a behaviour is for every one referred to: "both of them", "them all".
_EACH_OF_THEM = re.compile(r"\b(?:both|all of them|them all|each of them|every one of them|the (?:two|three|four|five) of them)\b")


# Where the walk starts, when said: "walks from the bus stop to the library".
_FROM = re.compile(r"\bfrom\s+")
# Speeds on foot, m/s: a walk, and a run or a bike.
WALK_MS, FAST_WALK_MS = 1.4, 3.5
_FAST = ("run", "runs", "running", "ran", "rode", "jog", "jogs", "jogging", "hurry", "hurries", "hurrying", "rush", "rushes", "rushing",
         "sprint", "sprints", "sprinting", "ride", "rides", "riding", "cycle", "cycles", "cycling")


class Walk(NamedTuple):
    """A walk the words say: the follow_path behaviour to where it goes, and where it starts if said."""

    behaviour: dict[str, Any]
    start: str | None


def named_at(scene: Scene, text: str, exclude: list[str]) -> str | None:
    """The place, asset or ego named at the start of `text` ("the fountain", "bench_1", "our car")."""
    place = find_place(scene, text[: GOAL_REACH + 24])  # the first place said, not a longer one later
    if place is not None and place[1] <= GOAL_REACH:
        return place[0]
    if re.match(r"\s*(?:the |our )?(?:ego|ego car|ego vehicle|our car|test vehicle)\b", text):
        return "ego"
    ids = [i for i in ph.find_asset_ids(scene, text.replace(" ", "  ")) if i in ph.tokens(text[:GOAL_REACH + 12])]
    ids = [i for i in ids if i not in exclude]
    if ids:
        return ids[0]
    head = ph.find_categories(text[:GOAL_REACH + 12])
    if head and head[0].start <= GOAL_REACH:
        present = [a.id for a in scene.assets if a.category == head[0].category and a.id not in exclude]
        return present[0] if len(present) == 1 else None
    return None


def walk_said(r: Reading, scene: Scene, exclude: list[str]) -> Walk | None:
    """The walk to a place a clause says of a walker ("a woman walking towards the fountain",
    "he runs from the bus stop to the library"); None when it names no going to a place."""
    going = GOES_TO.search(r.low)
    if going is None:
        return None
    goal = named_at(scene, r.low[going.end() :], exclude)
    if goal is None:
        return None
    said_from = _FROM.search(r.low)
    start = None
    if said_from is not None:  # "from the bus stop to the library": the words up to where it goes
        upto = r.low.find(" to", said_from.end()) if said_from.start() < going.end() else -1
        start = named_at(scene, r.low[said_from.end() : upto if upto > 0 else None], exclude)
    speed = ph.find_speed(r.text) or (FAST_WALK_MS if r.has(_FAST) else WALK_MS)
    return Walk({"kind": "follow_path", "to": goal, "speed": speed}, start if start != goal else None)


# A vehicle heading for a place starts this far before it along a lane that leads there.
DRIVE_LEAD_M = 25.0
# ...a lane that passes within this of the place.
DRIVE_REACH_M = 12.0


def drive_towards(r: Reading, scene: Scene, mover: AssetInstance | None = None) -> tuple[dict[str, Any], dict[str, Any]] | None:
    """For a vehicle heading for a place ("a truck heading for the main gate", "the suv drives to
    the main gate"): a drive along the lane that leads there, and where a new one starts,
    DRIVE_LEAD_M before it (the `mover` that is there joins the lane where it stands); None when
    no place is said or no lane leads there."""
    walk = walk_said(r, scene, exclude=[mover.id] if mover is not None else [])
    goal = (walk and scene.landmark(walk.behaviour["to"])) or (walk and scene.asset(walk.behaviour["to"]))
    if walk is None or goal is None:
        return None
    gx, gy = goal.position if not isinstance(goal, AssetInstance) else (goal.pose.x, goal.pose.y)
    leading = []
    for lane in scene.roads.lanes:
        near = nearest_on_polyline(gx, gy, lane.centreline)
        start = DRIVE_LEAD_M if mover is None else nearest_on_polyline(mover.pose.x, mover.pose.y, lane.centreline).arc_length
        # one there already that drives to a place part way along a lane stops there (by path, see
        # edit_existing); driving the lane would take it past, so only a lane that ends there is driven
        past = mover is not None and polyline_length(lane.centreline) - near.arc_length > DRIVE_REACH_M
        if near.distance <= DRIVE_REACH_M and near.arc_length >= max(start, DRIVE_REACH_M) and not past:
            leading.append((near.distance, lane))
    if not leading:
        return None
    lane = min(leading, key=lambda pair: pair[0])[1]
    x, y, _ = point_along(lane.centreline, nearest_on_polyline(gx, gy, lane.centreline).arc_length - DRIVE_LEAD_M)
    speed = ph.find_speed(r.text)
    behaviour = {"kind": "drive_lane", "lane": lane.id, **({"speed": speed} if speed else {})}
    return behaviour, {"relation": "in_lane", "target": f"{x:.1f}, {y:.1f}", "lane": lane.id}


# Where a thing is to go, said after the verb ("move it to the gym", "shift the bench over to the
# quad"): when no place of the world is found there, the move is not guessed.
_DESTINATION = re.compile(r"\b(?:to|into|onto|over to|up to|across to)\s+(?:the|a|an|that|this)\s+[a-z]+")


# A short step said with its way ("forward a tiny bit", "back 2 m", "left slightly").
_STEP_SAID = re.compile(r"\b(?:forwards?|ahead|back(?:wards?)?|left|right)\b(?:\s+(?:by\s+)?)(?:an?\s+(?:tiny\s+|little\s+|wee\s+)?"
                        r"(?:bit|little|touch)|slightly|\d+(?:\.\d+)?\s*(?:m|metres?|meters?)\b)")


# A figure with no unit after it ("rotate the hydrant 45ish", "turn it 30"): for a turn, degrees.
_BARE_FIGURE = re.compile(rf"({nb.NUMBER})(?:-?ish)?(?!\s*(?:m\b|metres?|meters?|km|s\b|sec|seconds?|mph|kph|kmh|%|x\b))")


# A thing switched on or off ("turn off street light 1", "switch lamp 3 on"): never a turn of it.
_SWITCHED = re.compile(r"\b(?:turn|switch|flip|shut|flick)\w*\s+(?:[\w']+\s+){0,4}?(?:on|off|out)\b")


def _bare_angle(low: str, scene: Scene) -> re.Match[str] | None:
    """The one unitless figure of a turn request, when there is exactly one (the number of "car 1"
    picks the car out: "turn car 1 to face north" says no angle)."""
    picks = numbered_picks(scene, low)
    found = [m for m in _BARE_FIGURE.finditer(low) if not any(start <= m.start() < end for _, start, end in picks)]
    return found[0] if len(found) == 1 else None


__all__ = ["FURTHEST", "TOO_CONSPICUOUS", "behaviour_kind", "behaviour_spec", "edit_existing", "recolour", "referenced", "remove"]
