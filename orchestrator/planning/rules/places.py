"""Where a clause puts something, for the rule planner: relations, targets, lanes, "there".

A relation word ("next to", "behind", "by") takes the thing named right after it as its
target: an existing asset ("next to the bench at the bus stop" is the bench there), else a
place. "There" is the last place this prompt named, else the last edit's focus in memory.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.reading import SIDE_OF, Reading, find_place, lane_of_side, road_kinds_spelt
from drivetwin.tools.arrange import row_start
from drivetwin.tools.errors import ToolError
from drivetwin.tools.locate import Location, resolve_anchor
from drivetwin.tools.search import across_points, beyond_nearest
from drivetwin.worlds.catalog import Category, catalog
from drivetwin.worlds.scene import AssetInstance, Landmark, Lane, Scene
from drivetwin.worlds.surface import lane_at, nearest_on_polyline, point_along, point_in_polygon, polyline_length
from pydantic import ValidationError

RELATIONS = (
    (("in front of", "ahead of", "front of", "infront", "in front"), "in_front_of"),
    (("behind",), "behind"),
    (("left of", "to the left"), "left_of"),
    (("right of", "to the right"), "right_of"),
    (("next to", "beside", "alongside", "by the", "close to", "closer to", "each side of", "either side of", "both sides of"), "next_to"),  # "on each side of the bench"
    (("under the", "underneath the", "beneath the", "in the shade of"), "next_to"),  # what stands under a tree stands by its trunk
)
_DISTANCE_SIDE = re.compile(r"\b(?:m|metres?|meters?|ft|feet)\s+(ahead|behind|back|further on|down the road)\b")
# Words that say a place was meant; when none resolves, the rules guessed the place.
PLACE_WORDS = (
    "near",
    "next to",
    "beside",
    "by",
    "at",
    "in front of",
    "behind",
    "outside",
    "around",
    "close to",
    "closer to",
    "over by",
    "on",
    "in",
    "to the",
)
_CENTRE = (
    "centre of the scene",
    "centre of the map",
    "scene centre",
    "middle of the scene",
    "centre of the world",
    "middle of the map",
    "centre of campus",
    "in the centre",
    "in the middle",
    "centre of the campus",
    "centre of scene",
    "middle of scene",
    "the origin",  # the map frame's (0, 0)
)


@dataclass
class Notes:
    """What the planner had to guess while reading a prompt; each guess lowers its confidence."""

    guesses: list[str] = field(default_factory=list)
    # The prompt's own context: the place and the assets its earlier clauses named.
    place: dict[str, Any] | None = None
    scene_set: dict[str, Any] | None = None  # the place a clause that asks nothing named ("lot A looks empty.")
    subject: list[str] = field(default_factory=list)
    named: list[str] = field(default_factory=list)  # the subject before new things became it
    earlier: list[str] = field(default_factory=list)  # the subjects before it, newest first
    coming: list[str] = field(default_factory=list)  # ids its earlier clauses' new things will get

    def adding(self, scene: Scene, category: str, count: int) -> None:
        """Note the ids the Worker will give `count` new things of `category` (category_N, the
        smallest N free), so that a later clause's "next to it" can name them."""
        n = 0
        for _ in range(count):
            n += 1
            while scene.asset(f"{category}_{n}") is not None or f"{category}_{n}" in self.coming:
                n += 1
            self.coming.append(f"{category}_{n}")

    def guess(self, why: str) -> None:
        self.guesses.append(why)


def relation_of(low: str) -> str:
    """The spatial relation a clause states ("at" when none)."""
    for words, rel in RELATIONS:
        if any(f" {w} " in low for w in words):
            return rel
    # "40 m ahead", "a few metres back": a distance said with a side, the thing to go by unsaid
    side = _DISTANCE_SIDE.search(low)
    if side is not None:
        return "behind" if side.group(1) in ("behind", "back") else "in_front_of"
    return "at"


def relation_objects(r: Reading) -> list[str]:
    """The ids the clause names as where something goes ("next to bench_1", "behind the suv_1"), in order."""
    words = "|".join(re.escape(w).replace(r"\ ", r"\s+") for ws, _ in RELATIONS for w in ws if not w.endswith(" the"))
    return [i for i in r.ids if re.search(rf"\b(?:{words}|near|by|at|to)\s+(?:the\s+)?{re.escape(i).replace('_', '[_ ]')}\b", r.low)]


def _asset_after_relation(r: Reading, scene: Scene, exclude: list[str], memory: Memory) -> str | None:
    # "next to the bench at the bus stop": the bench nearest that stop; "near the hydrant" too. The
    # relation said first is the one meant: "beside the bin that's next to the bench" is by the bin.
    objects = [i for i in relation_objects(r) if i not in exclude]
    if objects:
        return objects[0]  # "place trash_bin_1 next to bench_1": by that one
    said = sorted((pos, word) for words in [*(w for w, _ in RELATIONS), ("near", "nearby", "at the")] for word in words
                  if (pos := r.low.find(f" {word} ")) >= 0)
    for pos, word in said:
        later = [m for m in r.mentions if m.start > pos]
        if word == "at the" and later and places_called(scene, r.low[later[0].start : later[0].end].split()[-1]):
            continue  # "at the stop": the one place called that (the bus stop), not the stop sign
        # The thing right after the relation is its object: not one a place or words come between.
        between = r.low[pos + len(word) + 2 : later[0].start] if later else ""
        if not later or len(between.split()) > 3 or pos < r.landmark_at < later[0].start:
            continue
        present = [a for a in scene.assets if a.category == later[0].category and a.id not in exclude]
        if not present:
            continue
        point = _anchor_point(r, scene, later[1:], exclude)
        if point is not None:
            present.sort(key=lambda a: math.dist((a.pose.x, a.pose.y), point))
        elif len(present) > 1:  # "next to that bench": the one the last turn added or moved, if it did
            recent = memory.last_touched()
            present.sort(key=lambda a: a.id not in recent)
        return present[0].id
    return None


def _anchor_point(r: Reading, scene: Scene, after: list[ph.Mention], exclude: list[str]) -> tuple[float, float] | None:
    """Where the words after a relation's object say it is: the place named, or, in a chain
    ("the bin that's next to the bench by the bus stop"), the next thing named nearest that place."""
    landmark = scene.landmark(r.landmark) if r.landmark else None
    point = landmark.position if landmark is not None else None
    things = [a for a in scene.assets if after and a.category == after[0].category and a.id not in exclude]
    if not things:
        return point
    if point is not None:
        nearest = min(things, key=lambda a: math.dist((a.pose.x, a.pose.y), point))
        return nearest.pose.x, nearest.pose.y
    return (things[0].pose.x, things[0].pose.y) if len(things) == 1 else None


# Things laid "from X to Y": between the two, not at either.
FROM_TO = re.compile(r"\bfrom\s+(?P<a>.+?)\s+(?:to|up to|as far as|until)\s+(?P<b>.+)$")
# Where a request says a thing should go ("at the bus stp", "around the helipad", "by the eest gate"),
# and sayings that only look like it ("at the moment", "by the way").
PLACE_SAID = re.compile(r"\b(?:at|by|near|next to|beside|around|round|outside|in front of|behind|opposite|close to"
                        r"|(?:north|south|east|west)(?:[\s-]?(?:east|west))? of)"
                         r"\s+the\s+(?!(?:moment|same time|end of the day|way|time|least|most|latest|earliest|start|end)\b)"
                         r"([a-z][a-z ]{1,30}?)\s*(?:[,.;!?]|$|\b(?:and|please|pls|plz|with|so|for|to|now)\b)")
# Away from a sidewalk ("shove it somewhere off the sidewalk", "get it off the pavement"): not onto one.
_OFF_SIDEWALK = re.compile(r"\b(?:off|away from|clear of|not on|(?:should|must|ought to|can)(?:n'?t| not)(?: be)? on|(?:is|are)(?:n'?t| not) meant to be on)"
                           r" (?:of )?(?:the |that |this )?(?:sidewalk|pavement|footpath|kerb|curb)\b")  # "the hydrant shouldn't be on the sidewalk"
# A thing moved off the road with no place said: "move the truck off the carriageway", "get him out of the road".
_OFF_ROAD = re.compile(r"\b(?:off|out of|clear of) (?:of )?(?:the |that |this |our )?(?:road|roadway|carriageway|street|lane|traffic)\b")


def _off_the_road(scene: Scene, mover: AssetInstance) -> dict[str, Any]:
    """Where a thing moved off the road goes: a vehicle to the nearest parking lot (a place whose
    spot is on parking), a walker to the sidewalk nearest it."""
    lots = [lm for lm in scene.landmarks if any(area.kind == "parking" and point_in_polygon(*lm.position, area.polygon)
                                                for area in scene.roads.paved)]
    if catalog()[mover.category].motion == "vehicle" and lots:
        nearest = min(lots, key=lambda lm: math.dist(lm.position, (mover.pose.x, mover.pose.y)))
        return {"relation": "at", "target": nearest.name}
    return {"relation": "on_sidewalk", "target": mover.id}


# A relation to what an earlier clause of the prompt adds: "a rover at the gate and a sign next to it".
_GOES_WITH = re.compile(r"\bto (?:go (?:along )?with|match|pair with|accompany)\s+(?:it|them|him|her)\b")
BY_IT = re.compile(rf"\b(?:next to|beside|by|near|behind|in front of|ahead of|alongside|around|opposite|(?:left|right) of)\s+(?:it|them|him|her)\b"
                   rf"|{_GOES_WITH.pattern}"  # "a bin to go with it": beside it
                   r"|\b(?:to |waiting to )?(?:get|getting|climb|climbing|board|boarding)\s+(?:on|onto|into|in|aboard)?\s*(?:it|them)\b")  # "waiting to get on it"
# "There" after a turn that put things somewhere: beside the one of them within this of its focus.
THERE_BESIDE_M = 6.0


_THE_ONE = re.compile(r"\b(?:in|at|to|into|over to)\s+the\s+\w+\s+one\b")
_THE_OTHER = re.compile(r"\bthe other ([a-z]+(?: [a-z]+)?)")


def point_named(scene: Scene, where: str) -> tuple[float, float] | None:
    """The point a few words name: the ego, a landmark, an asset by its id, else the one thing of
    a kind the scene has ("the bench"); None when they name none of these."""
    ego = scene.asset("ego")
    if ego is not None and (ph.has_any(where, ph.EGO_WORDS) or re.search(r"\bego\b", where)):
        return ego.pose.x, ego.pose.y
    place = find_place(scene, where)
    if place is not None:
        landmark = scene.landmark(place[0])
        if landmark is not None:
            return landmark.position[0], landmark.position[1]
    for asset in scene.all_assets():
        if re.search(rf"\b{re.escape(asset.id)}\b", where):
            return asset.pose.x, asset.pose.y
    for mention in ph.find_categories(where):
        found = [a for a in scene.all_assets() if a.category == mention.category]
        if len(found) == 1:
            return found[0].pose.x, found[0].pose.y
    return None


# A point between two things: "between the library and the bus stop", "halfway between the bench and the sign".
BETWEEN = re.compile(r"\b(?:halfway |midway |half way |right )?(?:in )?between\s+(?P<a>.+?)\s+and\s+(?P<b>.+?)"
                     r"(?=\s*(?:[,.;!?]|$|\b(?:please|pls|so|for|then|now)\b))")


def between(scene: Scene, low: str) -> dict[str, Any] | None:
    """The point halfway between the two things the words say something goes between, as an
    absolute Location; None when they say no "between"; a PlanningError when they name a side
    this world has no one point for."""
    said = BETWEEN.search(low)
    if said is None:
        return None
    ends = [point_named(scene, f" {said.group(side)} ") for side in ("a", "b")]
    for side, other in ((0, 1), (1, 0)):  # "between Main Street and the hall": the road where it is nearest the hall
        known = ends[other]
        road = _road_named(scene, said.group("ab"[side]))
        if ends[side] is None and known is not None and road:
            near = min((nearest_on_polyline(known[0], known[1], lane.centreline) for lane in road), key=lambda p: p.distance)
            ends[side] = (near.x, near.y)
    if ends[0] is None or ends[1] is None:
        from drivetwin.orchestrator.planning.base import PlanningError

        unknown = said.group("a") if ends[0] is None else said.group("b")
        raise PlanningError(f"I could not tell where {unknown.strip()!r} is, to put something between; name a place or one thing")
    return {"relation": "absolute", "x": round((ends[0][0] + ends[1][0]) / 2, 2), "y": round((ends[0][1] + ends[1][1]) / 2, 2)}


# Across the road from a place or thing: "across from the JTEKT entrance", "opposite the bus stop",
# "on the other side of the road from the bench".
ACROSS_FROM = re.compile(r"\b(?:(?:right |directly |just )?(?:across|over) (?:the (?:road|street) )?from|opposite(?: to)?(?!\s+(?:traffic\s+)?lanes?\b)"
                         r"|on the (?:other|opposite|far) side of the (?:road|street) from)\s+(?P<what>.+?)(?=\s*(?:[,.;!?]|$|\b(?:please|pls|so|for|then|now|and)\b))")
# How far past the road's middle the far side is: its half width and a sidewalk's half.
FAR_SIDE_BEYOND_M = 2.0


def across_from(scene: Scene, low: str, on_road: bool = False) -> dict[str, Any] | None:
    """The point across the nearest road from the place or thing the words name: as far past the
    road's middle as it stands before it, at most to the far sidewalk (for what stands `on_road`,
    the far lane's middle); None when they say no such thing."""
    said = ACROSS_FROM.search(low)
    point = point_named(scene, f" {said.group('what')} ") if said else None
    if point is None or not scene.roads.lanes:
        return None
    lane = min(scene.roads.lanes, key=lambda ln: nearest_on_polyline(point[0], point[1], ln.centreline).distance)
    road = [ln for ln in scene.roads.lanes if ln.road == lane.road] if lane.road else [lane]
    feet = [nearest_on_polyline(point[0], point[1], ln.centreline) for ln in road]
    mx, my = sum(f.x for f in feet) / len(feet), sum(f.y for f in feet) / len(feet)
    away = math.dist(point, (mx, my))
    if away < 0.5:
        return None  # on the road's middle: no side to be across from
    half = sum(ln.width for ln in road) / 2
    far = half - min(ln.width for ln in road) / 2 if on_road else min(away, half + FAR_SIDE_BEYOND_M)
    ux, uy = (mx - point[0]) / away, (my - point[1]) / away
    return {"relation": "absolute", "x": round(mx + ux * far, 2), "y": round(my + uy * far, 2)}


def _road_named(scene: Scene, words: str) -> list[Any]:
    """The lanes of the road or the one lane the words name ("Main Street", "the westbound lane")."""
    low = ph.normalise(words)
    road = [lane for lane in scene.roads.lanes if lane.road and ph.normalise(lane.road).strip() in low]
    return road or [lane for lane in scene.roads.lanes if lane.id.replace("_", " ") in low]


def places_called(scene: Scene, word: str) -> list[str]:
    """The landmarks one of whose names ends in `word` ("gate": the main gate and the east gate)."""
    return [lm.name for lm in scene.landmarks if any(ph.tokens(ph.normalise(n))[-1:] == [word] for n in lm.names())]


# The far side of a thing from the one moved: "on the other side of the bench", "to the opposite side of the bin".
_OTHER_SIDE_OF = re.compile(r"\b(?:on|to|round to|over to)\s+the\s+(?:other|opposite|far)\s+side\s+of\s+")


def _mirrored(scene: Scene, exclude: list[str], after: str) -> tuple[float, float] | None:
    """Where the thing moved would stand as far past the one thing named in `after` as it stands
    before it now; None unless a thing is moved and one thing there is named (a road is no thing)."""
    mover = scene.asset(exclude[0]) if exclude else None
    named = ph.find_categories(f" {after} ")
    if mover is None or not named or named[0].start > 8:
        return None
    there = [a for a in scene.assets if a.category == named[0].category and a.id != mover.id]
    if len(there) != 1:
        return None
    pivot = there[0].pose
    return 2 * pivot.x - mover.pose.x, 2 * pivot.y - mover.pose.y


# Any place of a kind, left to choose: "near any building", "by the nearest entrance", "to a gate".
_ANY_OF_KIND = re.compile(r"\b(near|by|next to|beside|to|at|outside|in front of|in)\s+(?:any|an?|the nearest|the closest|whichever)\s+(?:[a-z]+\s+)?"
                          r"(building|entrance|gate|crossing|crosswalk|car park|lot)\b")


# A compass end or part of a road: "the southern end of Campus Drive", "the north part of the road".
_ROAD_PART = re.compile(r"\b(north|south|east|west)(?:ern)?\s+(end|half|part|stretch|section|bit)\b(?!\s+of\s+(?:the\s+)?(?:lot|car park|parking|quad|campus(?! drive)|map|scene)\b)")


def _road_part(scene: Scene, lane: Lane, compass: str, end: bool, lane_said: str | None) -> dict[str, Any]:
    """The spot in the road's lanes furthest that way (near its end, or half way there from the
    road's middle for a part of it); in the lane said, if one was."""
    ux, uy = _UNIT[compass]
    lanes = [ln for ln in scene.roads.lanes if ln.road == lane.road] if lane_said is None else [lane]
    spots = []
    for ln in lanes or [lane]:
        length = sum(math.dist(p, q) for p, q in itertools.pairwise(ln.centreline))
        for arc in ((min(LANE_END_M, length / 2), max(length - LANE_END_M, length / 2)) if end else (length / 4, 3 * length / 4)):
            x, y, _ = point_along(ln.centreline, arc)
            spots.append((x * ux + y * uy, x, y, ln.id))
    _, x, y, lane_id = max(spots)
    return {"relation": "in_lane", "target": f"{x:.1f}, {y:.1f}", "lane": lane_id}


# Either end of a lane or road: "the start of Main Street westbound", "the far end of the lane".
_LANE_END = re.compile(r"\b(start|beginning|entry|end) of\b")
# The end of the road a thing is on, said without naming it: "back at the start of the road".
_OWN_ROAD = re.compile(r"\b(?:start|beginning|end) of (?:the|its|this|our|my) (?:road|street|lane)\b")
# How far into a lane "its start" (or short of its end) is.
LANE_END_M = 10.0


# Every place of a kind: "at every crosswalk", "by each of the gates", "outside both entrances".
EACH_PLACE = re.compile(r"\b(?:at|by|near|next to|beside|outside|in front of|behind|on|around)\s+"
                        r"(?P<said>(?:every|each|all|both)(?: of)?(?: the)?\s+(?P<kind>[a-z]+?)s?)\b")


def each_place_named(scene: Scene, low: str) -> list[str]:
    """The places of the kind the words say every one of ("at every crosswalk": the west and the
    north crosswalk); [] when they say none, or the kind is no kind of place of this world."""
    said = EACH_PLACE.search(low)
    places = places_called(scene, said.group("kind")) if said is not None else []
    both = said is not None and said.group("said").startswith("both")
    return [] if both and len(places) != 2 else places  # "both entrances" where there are six: which two is not said


def says_other_place(low: str, scene: Scene) -> bool:
    """Whether the words name "the other" place: "the other one", "the other lot", "the other car
    park" (a name, or its head word: its last, or the one before a label such as "lot A")."""
    said = _THE_OTHER.search(low)
    if said is None:
        return False
    heads = {"one"}
    for name in (n.lower() for lm in scene.landmarks for n in lm.names()):
        words = ph.tokens(name)
        heads |= {name, words[-1]} | ({words[-2]} if len(words) > 1 and len(words[-1]) <= 2 else set())
    first = said.group(1).split()[0]
    return said.group(1) in heads or first in heads
# How near a place a thing must stand to be at it, when the place has no area.
AT_PLACE_M = 15.0


def _places_like(scene: Scene, moving: list[str]) -> tuple[Landmark, list[Landmark]] | None:
    """The place the first of `moving` stands at, and the places most like it (names sharing the
    most words, not one named after it such as its entrance); None when it stands at none."""
    asset = scene.asset(moving[0])
    if asset is None:
        return None
    x, y = asset.pose.x, asset.pose.y
    at = [lm for lm in scene.landmarks if (point_in_polygon(x, y, lm.polygon) if lm.polygon
                                           else math.dist((x, y), lm.position) <= AT_PLACE_M)]
    if not at:
        return None
    here = at[0]
    words = [set(ph.tokens(n)) for n in here.names()]

    def likeness(lm: Landmark) -> float:
        return max(len(a & set(ph.tokens(n))) / len(a | set(ph.tokens(n))) for a in words for n in lm.names())

    others = [lm for lm in scene.landmarks if lm is not here
              and not any(here.name.lower() in n.lower() for n in lm.names())]
    best = max((likeness(lm) for lm in others), default=0.0)
    return here, [lm for lm in others if best > 0 and likeness(lm) == best]


def _other_place(scene: Scene, moving: list[str]) -> str | None:
    """The place most like the one the first of `moving` stands at ("the other lot")."""
    found = _places_like(scene, moving)
    return found[1][0].name if found is not None and len(found[1]) == 1 else None


def _outer_place(scene: Scene, moving: list[str], way: tuple[float, float]) -> str | None:
    """Of the place the first of `moving` stands at and those like it, the one furthest `way`
    ("it belongs in the western one")."""
    found = _places_like(scene, moving)
    if found is None or not found[1]:
        return None
    return max([found[0], *found[1]], key=lambda lm: lm.position[0] * way[0] + lm.position[1] * way[1]).name


# A place said by its compass side of a named place ("north of the crossroads", "20 m west of the
# fountain"), how far unsaid: just past the place, beyond a junction's crossings (11.5 m from the
# campus crossroads' centre) and the 10-15 m a place's name covers.
COMPASS_OFFSET_M = 15.0
# "a little north of", "just south of": a few metres past the place.
LITTLE_OFFSET_M = 5.0
_A_LITTLE = re.compile(r"\b(?:a little|a bit|slightly|just|a touch|a few (?:metres|meters|steps))\s*(?:to the\s*)?$")
_COMPASS_OF = re.compile(r"\b(?:due\s+)?(north|south|east|west)\s+of\s+(?:the\s+)?(?=\S)")


def _compass_of(r: Reading, scene: Scene) -> dict[str, Any] | None:
    """An absolute point the words put at a compass side of the place they name, on the lane they
    name if any; None when they say no such side."""
    said = _COMPASS_OF.search(r.low)
    if said is None or not r.landmark or r.landmark_at < said.end() - 1:
        return None
    landmark = scene.landmark(r.landmark)
    if landmark is None:
        return None
    east, north = md.COMPASS_VECTORS[said.group(1)]
    metres = ph.find_distance(r.low[: said.start()])
    little = _A_LITTLE.search(r.low[: said.start()])  # "a little north of the north crosswalk": just past it
    away = metres if metres is not None else LITTLE_OFFSET_M if little else COMPASS_OFFSET_M
    x, y = landmark.position[0] + east * away, landmark.position[1] + north * away
    said_lane = r.lane and not r.lane_guessed and re.search(r"\b(?:lanes?|[a-z]+bound)\b", r.low)
    lane = scene.roads.lane(r.lane) if said_lane and r.lane else None
    if lane is not None:  # "the northbound lane ..., north of the crossroads": that lane, there
        on = nearest_on_polyline(x, y, lane.centreline)
        x, y = on.x, on.y
    # the distance said stays in the call, so what was said can be seen in what is done
    return {"relation": "absolute", "x": round(x, 2), "y": round(y, 2), **({"distance": metres} if metres else {})}


# A compass side of an area ("the north edge of lot A", "the east end of the lot"): just inside its
# boundary that way.
EDGE_OF = re.compile(r"\b(north|south|east|west)(?:ern)?\s+(?:side|edge|end|half|corner|part|fringe|border)\s+of\s+(?:the\s+)?(?=\S)")
EDGE_INSET_M = 3.0


def _edge_of(r: Reading, scene: Scene) -> dict[str, Any] | None:
    """An absolute point just inside the side of the area the words name, or just past a place's
    point that way ("the west side of the library"); None when they name no side of a place (a side
    of a road is its lane: see side_lane)."""
    said = EDGE_OF.search(r.low)
    if said is None or not r.landmark or r.landmark_at < said.end() - 1:
        return None
    area = scene.landmark(r.landmark)
    if area is None:
        return None
    dx, dy = md.COMPASS_VECTORS[said.group(1)]
    if area.kind != "area" or not area.polygon:
        x, y = area.position
        return {"relation": "absolute", "x": round(x + dx * LITTLE_OFFSET_M, 2), "y": round(y + dy * LITTLE_OFFSET_M, 2)}
    cx, cy = area.position
    reach = max((x - cx) * dx + (y - cy) * dy for x, y in area.polygon)
    away = max(0.0, reach - EDGE_INSET_M)
    return {"relation": "absolute", "x": round(cx + dx * away, 2), "y": round(cy + dy * away, 2)}


# "past the junction", "beyond the east gate" in a lane the words name: further along that lane,
# the way its traffic runs.
_PAST = re.compile(r"\b(?:past|beyond|after)\s+(?:the\s+)?(?=\S)")
PAST_OFFSET_M = 25.0


def _past_along_lane(r: Reading, scene: Scene) -> dict[str, Any] | None:
    """A point in the lane named, past the place named along the lane's direction (the Worker's
    in_lane distance is metres ahead of the lane's point nearest the place); None when the words
    say no such thing."""
    said = _PAST.search(r.low)
    if said is None or not r.landmark or r.landmark_at < said.end() - 1 or not r.lane or r.lane_guessed:
        return None
    lane, landmark = scene.roads.lane(r.lane), scene.landmark(r.landmark)
    if lane is None or landmark is None:
        return None
    metres = ph.find_distance(r.low[: said.start()])
    away = metres if metres is not None else LITTLE_OFFSET_M if _A_LITTLE.search(r.low[: said.start()]) else PAST_OFFSET_M
    on = nearest_on_polyline(landmark.position[0], landmark.position[1], lane.centreline)
    ahead = min(away, polyline_length(lane.centreline) - on.arc_length)  # never off the lane's end
    return {"relation": "in_lane", "target": landmark.name, "lane": lane.id, "distance": round(ahead, 2)}


# A sidewalk named by its side: "the north sidewalk", "the pavement on the south side of Main Street".
_SIDEWALK_WORD = r"(?:sidewalk|side walk|pavement|footpath|footway|walkway)"
_SIDEWALK_OF_SIDE = re.compile(rf"\b(north|south|east|west)(?:ern)?(?:[- ]side)?\s+{_SIDEWALK_WORD}\b"
                               rf"|\b{_SIDEWALK_WORD}\s+on\s+(?:the\s+)?(north|south|east|west)(?:ern)?\s+side\b")


def _placed_kind(r: Reading, scene: Scene, exclude: list[str]) -> Category | None:
    """The kind of what the clause puts somewhere: the first thing named, else the thing moved."""
    moved = scene.asset(exclude[0]) if exclude else None
    name = r.mentions[0].category if r.mentions else moved.category if moved is not None else None
    return catalog().get(name) if name is not None else None


def _off_road(r: Reading, scene: Scene, exclude: list[str]) -> bool:
    """Whether what the clause puts somewhere stands off the road: a walker, a bench, a sign (not a
    cone, a car or a bike)."""
    kind = _placed_kind(r, scene, exclude)
    return kind is not None and kind.placement != "drivable" and "vehicle" not in kind.tags


# A sidewalk belongs to the road whose lane is at most this far from its middle.
SIDEWALK_ROAD_M = 12.0


def sidewalk_of_side(r: Reading, scene: Scene, exclude: list[str]) -> dict[str, Any] | None:
    """The Location on the sidewalk the words name by its compass side ("on the north sidewalk of
    Main Street", "a bench on the south side of Main Street"): of the road named (else any), the sidewalk on that side nearest the place, thing
    or ego the clause names; on it, at the point nearest that. None when no such sidewalk is named."""
    said = _SIDEWALK_OF_SIDE.search(r.low)
    side = SIDE_OF.search(r.low) if said is None and _off_road(r, scene, exclude) else None
    if said is None and (side is None or lane_of_side(r.low, scene) is None):
        return None  # "the north side of Main Street" is its sidewalk for a bench or a walker, not for a cone
    way = said.group(1) or said.group(2) if said is not None else side.group(1) if side is not None else "north"
    dx, dy = md.COMPASS_VECTORS[way]
    roads = {lane.road for lane in scene.roads.lanes if lane.road and re.search(
        rf"\b{re.escape(ph.normalise(lane.road).strip())}\b", road_kinds_spelt(r.low))}
    lanes = [lane for lane in scene.roads.lanes if not roads or lane.road in roads]
    sides = []
    for walk in scene.roads.sidewalks:
        mx, my, _ = point_along(walk.polyline, polyline_length(walk.polyline) / 2)
        road = min(lanes, key=lambda lane: nearest_on_polyline(mx, my, lane.centreline).distance, default=None)
        near = nearest_on_polyline(mx, my, road.centreline) if road is not None else None
        if near is not None and near.distance <= SIDEWALK_ROAD_M and (mx - near.x) * dx + (my - near.y) * dy > 0.5 * near.distance:
            sides.append(walk)  # the road's nearest lane lies the other way: this walk is on that side
    # by the place or thing named, else where the thing moved stands, else by the ego
    # ... or the one thing of its kind the clause names after what it puts ("... in the vicinity of the fire hydrant")
    named = next((a.id for m in r.mentions[1:] if scene.count(m.category) == 1 for a in scene.assets
                  if a.category == m.category and a.id not in exclude), None)
    anchor = r.landmark or next((i for i in r.ids if i not in exclude), None) or named or next(iter(exclude), "ego")
    mark, thing = scene.landmark(anchor), scene.asset(anchor)
    if not sides or (mark is None and thing is None):
        return None
    x, y = mark.position if mark is not None else (thing.pose.x, thing.pose.y) if thing is not None else (0.0, 0.0)
    past = _COMPASS_OF.search(r.low)
    if past is not None and mark is not None:  # "on the north side of Main Street, east of the JTEKT building": past it
        ux, uy = _UNIT[past.group(1)]
        x, y = x + ux * BEYOND_PLACE_M, y + uy * BEYOND_PLACE_M
    metres, relation = ph.find_distance(r.text), relation_of(r.low)
    ahead = thing is not None and metres is not None and relation in ("in_front_of", "behind")
    if ahead and thing is not None and metres is not None:  # "on the south footway, 20 m ahead of the ego": counted along its heading
        sign = 1.0 if relation == "in_front_of" else -1.0
        x, y = x + math.cos(thing.pose.yaw) * metres * sign, y + math.sin(thing.pose.yaw) * metres * sign
    walk = min(sides, key=lambda w: nearest_on_polyline(x, y, w.polyline).distance)
    if anchor == "ego" and past is None and not ahead:
        return {"relation": "on_sidewalk", "target": walk.id}
    on = nearest_on_polyline(x, y, walk.polyline)
    if thing is not None and anchor == named and on.distance <= walk.width:
        return {"relation": "on_sidewalk", "target": thing.id}  # it stands on that sidewalk: by it, there
    return {"relation": "on_sidewalk", "target": f"{on.x:.1f}, {on.y:.1f}"}


def location(
    r: Reading, scene: Scene, memory: Memory, notes: Notes, exclude: list[str] | None = None, compass: bool = True
) -> dict[str, Any] | None:
    """The Location a clause describes, or None when it names no place; `compass`: a compass side
    of the place ("north of the crossroads") is a point past it (a closure reads that side itself)."""
    exclude = exclude or []
    coords = ph.find_coordinates(r.text)
    if coords is not None:
        return {"relation": "absolute", "x": coords[0], "y": coords[1]}
    other_side = _OTHER_SIDE_OF.search(r.low)
    mirror = _mirrored(scene, exclude, r.low[other_side.end() :]) if other_side is not None else None
    if mirror is not None:  # "put the bin on the other side of the bench": as far past it, the other way
        return {"relation": "absolute", "x": round(mirror[0], 2), "y": round(mirror[1], 2)}
    any_one = _ANY_OF_KIND.search(r.low)
    mover = scene.asset(exclude[0]) if exclude else None
    places = [] if any_one is None or mover is None else [lm.name for b in scene.buildings if (lm := scene.landmark(f"{b.name} entrance"))] \
        if any_one.group(2) == "building" else places_called(scene, any_one.group(2))  # a building: by its entrance
    if mover is not None and len(places) >= 2:  # "move the bench near any building": the one nearest it
        closest = min(places, key=lambda p: math.dist(scene.landmark(p).position, (mover.pose.x, mover.pose.y)))  # type: ignore[union-attr]
        return {"relation": relation_of(r.low), "target": closest}
    of_place = (r.landmark and re.search(r"\b(?:middle|centre) of (?:the )?(?!scene|map|world|campus)[a-z]", r.low)) or re.search(
        r"\b(?:middle|centre) of (?:the |a |that |this )?(?:pavement|sidewalk|footpath|path|road|street|lane|crossing|crosswalk|junction"
        r"|walkway|driveway|entrance|lot|car park|way)\b", r.low)  # "the middle of the pavement" is no centre of the map
    if (r.has(_CENTRE) or any(c in r.low for c in _CENTRE)) and not of_place:  # "the middle of lot B" is lot B
        return {"relation": "scene_centre"}
    halfway = between(scene, r.low)
    if halfway is not None:  # "a tree between the library and the bus stop"
        return halfway
    kind = _placed_kind(r, scene, exclude)
    facing = across_from(scene, r.low, on_road=kind is not None and kind.placement == "drivable")
    if facing is not None:  # "a car parked across from the JTEKT entrance": the road's far side
        return facing
    by_thing = where_thing(r, scene, exclude)
    if by_thing is not None:  # "put the bus where the suv is now": beside it
        return by_thing
    was = _WHERE_IT_WAS.search(r.low)
    before = next((spot for i in exclude if (spot := memory.stood_before(i)) is not None), None) if was else None
    if before is not None:  # "put the bench back where it was": where it stood before it was last moved
        return {"relation": "absolute", "x": round(before[0], 2), "y": round(before[1], 2)}
    gone = next((scene.asset(i) for i in notes.subject if scene.asset(i) is not None), None) if was else None
    if gone is not None:  # "remove the hydrant, then add a bench where it was": the spot it stood on
        return {"relation": "absolute", "x": round(gone.pose.x, 2), "y": round(gone.pose.y, 2)}
    walkway = sidewalk_of_side(r, scene, exclude)
    if walkway is not None:  # "on the north sidewalk of Main Street": that sidewalk, not a lane of the road
        return walkway
    offset = (_edge_of(r, scene) or _compass_of(r, scene) or _past_along_lane(r, scene)) if compass else None
    if offset is not None:  # "north of the crossroads", "20 m west of the fountain", "in the northbound lane, north of ..."
        return offset
    # A road named only as context ("across Main Street at the east gate") yields to the place.
    if not r.lane and exclude and _OWN_ROAD.search(r.low) and (mover := scene.asset(exclude[0])) is not None \
            and (runs := lane_at(scene, mover.pose.x, mover.pose.y)) is not None:
        r = replace(r, lane=runs.id)  # "put our car back at the start of the road": the lane it is in
    if (
        r.lane
        and not (r.lane_guessed and r.landmark)
        and (r.has(("lane", "side", "road", "street", "drive", "driving")) or not r.landmark)
    ):
        if r.lane_guessed:
            notes.guess(f"which lane of the road ({r.lane})")
        metres, relation = ph.find_distance(r.text), relation_of(r.low)
        anchor = r.landmark or next((i for i in r.ids if i not in exclude), None) or ("ego" if r.ego and "ego" not in exclude else None)
        if anchor and metres is not None and relation in ("in_front_of", "behind"):
            # "in the eastbound lane 30 m ahead of the ego": that lane, counted along it from the anchor
            along = metres if relation == "in_front_of" else -metres
            return {"relation": "in_lane", "target": anchor, "along_m": along, **({} if r.lane_guessed else {"lane": r.lane})}
        thing = scene.asset(anchor) if anchor and anchor != r.landmark else None
        runs = lane_at(scene, thing.pose.x, thing.pose.y) if thing is not None else None
        if thing is not None and runs is not None and runs.id == r.lane and relation in ("in_front_of", "behind"):
            return {"relation": relation, "target": thing.id}  # "right behind the ego in the eastbound lane": its lane, by it
        if r.landmark:  # "the eastbound lane by the east gate": that lane, where it passes the place
            return {"relation": "in_lane", "target": r.landmark, **({} if r.lane_guessed else {"lane": r.lane})}
        lane = scene.roads.lane(r.lane)
        part = _ROAD_PART.search(r.low)
        if part is not None and lane is not None:  # "the southern end of Campus Drive", "the north part of it"
            return _road_part(scene, lane, part.group(1), part.group(2) == "end", None if r.lane_guessed else r.lane)
        end = _LANE_END.search(r.low)
        if end is not None and lane is not None:  # "at the start of Main Street westbound": near where the lane begins
            length = sum(math.dist(p, q) for p, q in itertools.pairwise(lane.centreline))
            arc = min(LANE_END_M, length / 2) if end.group(1) in ("start", "beginning", "entry") else max(length - LANE_END_M, length / 2)
            x, y, _ = point_along(lane.centreline, arc)
            return {"relation": "in_lane", "target": f"{x:.1f}, {y:.1f}", "lane": r.lane}
        return {"relation": "in_lane", "target": r.lane}
    target: str | None = _asset_after_relation(r, scene, exclude, memory)
    if target is None and r.landmark is None and notes.place is not None and r.has(("its entrance", "the entrance")):
        # "... in lot A and a sign at its entrance": the entrance of the place just named
        entrance = scene.landmark(f"{notes.place.get('target')} entrance")
        target = entrance.name if entrance is not None else None
    other = _other_place(scene, exclude) if exclude and says_other_place(r.low, scene) else None
    if exclude and r.landmark and target in (None, r.landmark) and _LEAVING.search(r.low[: max(r.landmark_at, 0)]):
        # "get the SUV out of lot B, anywhere", "park it anywhere but lot B": the place most like it, else asked
        other = other or _other_place(scene, exclude)
        if other is None:
            from drivetwin.orchestrator.planning.base import PlanningError

            raise PlanningError(f"where should it go instead of {r.landmark}? name a place, e.g. 'by the east gate'")
    way = md.outer_direction(r.low) if exclude and r.landmark is None and _THE_ONE.search(r.low) else None
    other = other or (_outer_place(scene, exclude, way) if way is not None else None)  # "the western one"
    if other is not None and (target is None or target == r.landmark):
        target = other  # "park one of those cars in the other lot", "the other car park"
    ids = [i for i in r.ids if i not in exclude]
    if target is None and r.landmark:
        target = r.landmark
    elif target is None and ids:
        target = ids[0]
    elif target is None and r.ego and "ego" not in exclude:
        target = "ego"
    if target is None and BY_IT.search(r.low):
        # "... and a sign next to it": what an earlier clause adds, else the thing it or the last turn named
        # ("move the bench to the fountain and the bin next to it": the bench, the subject before the bin)
        named = [i for i in [*notes.subject, *notes.earlier, *memory.last_touched()]
                 if i not in exclude and scene.asset(i) is not None]
        if notes.coming or named:
            on_walk = r.has(("sidewalk", "pavement", "footpath")) and not _OFF_SIDEWALK.search(r.low)  # "on the sidewalk next to it"
            said = relation_of(r.low)
            said = "next_to" if said == "at" and _GOES_WITH.search(r.low) else said  # "a bin to go with it": beside it
            by_it: dict[str, Any] = {"relation": "on_sidewalk" if on_walk else said,
                                     "target": (notes.coming or named)[-1 if notes.coming else 0]}
            metres = ph.find_distance(r.text)
            if metres is not None and by_it["relation"] in ("in_front_of", "behind", "left_of", "right_of", "next_to"):
                by_it["distance"] = metres  # "a car 25 m ahead of it"
            return by_it
    if target is None and r.has(("there", "same place", "same spot", "same location", "same position", "nearby", "around it", "near it", "that spot")):
        if notes.place is not None:
            return dict(notes.place)
        focus = memory.last_focus()
        if focus is not None:
            # beside what the last turn put there (a free spot), not exactly on top of it
            beside = [a for a in scene.assets if math.dist((a.pose.x, a.pose.y), focus) <= THERE_BESIDE_M]
            if beside:
                nearest = min(beside, key=lambda a: math.dist((a.pose.x, a.pose.y), focus))
                return {"relation": "next_to", "target": nearest.id}
            return {"relation": "absolute", "x": round(focus[0], 2), "y": round(focus[1], 2)}
    if _OFF_SIDEWALK.search(r.low) and target is None:
        from drivetwin.orchestrator.planning.base import PlanningError

        raise PlanningError("I can put things on a sidewalk, in a lane or by a place, but not just 'off the sidewalk'; "
                            "say where it should go instead, e.g. 'next to the bench by the library'")
    if _OFF_ROAD.search(r.low) and target is None and mover is not None and catalog()[mover.category].motion in ("vehicle", "walker"):
        return _off_the_road(scene, mover)  # "get the truck off the road": parked in the nearest lot; a walker onto the sidewalk
    if r.has(("sidewalk", "side walk", "pavement", "footpath", "footway", "walkway", "kerb", "curb")) and not _OFF_SIDEWALK.search(r.low):
        metres, relation = ph.find_distance(r.text), relation_of(r.low)
        if target is not None and scene.asset(target) is not None and metres is not None and relation in ("in_front_of", "behind"):
            # "15 m ahead of the ego on the right-hand pavement": counted along its way, on that side's sidewalk
            side = _HAND.search(r.low)
            return {"relation": "on_sidewalk", "target": target, "along_m": metres if relation == "in_front_of" else -metres,
                    **({"side": side.group(1)} if side else {})}
        return {"relation": "on_sidewalk", **({"target": target} if target else {})}
    if r.has(("in the lane", "on the road", "in lane", "on the street", "onto the road", "onto the street", "into the lane")):
        if target is not None and scene.asset(target) is not None and relation_of(r.low) in ("in_front_of", "behind"):
            return {"relation": relation_of(r.low), "target": target}  # "on the road ahead of the ego": in its lane, ahead
        if target is None and exclude and scene.asset(exclude[0]) is not None:
            target = exclude[0]  # "get the SUV out onto the road": the lane nearest where it stands
        return {"relation": "in_lane", **({"target": target} if target else {})}
    if target is None:
        return None
    found: dict[str, Any] = {"relation": relation_of(r.low), "target": target}
    metres = ph.find_distance(r.text)
    hand = _SIDE_OF_WAY.search(r.low)
    if hand is not None and found["relation"] in ("at", "next_to") and scene.asset(target) is not None:
        found["relation"] = f"{hand.group(1)}_of"  # "a cyclist on its right": beside it, that side
    if hand is not None and found["relation"] in ("in_front_of", "behind") and scene.asset(target) is not None:
        # "a bike 10 m ahead of the ego on the left side": counted along its way, at that edge
        along = metres if metres is not None else SIDE_AHEAD_M
        return {**found, "along_m": along if found["relation"] == "in_front_of" else -along, "side": hand.group(1)}
    if metres is not None and found["relation"] != "at":
        found["distance"] = metres
    return found


# A place said as the one to leave: "out of lot B", "anywhere but the lot", "somewhere other than the gate".
_LEAVING = re.compile(r"\b(?:out of|anywhere (?:but|except|other than|apart from)|somewhere (?:other than|besides|except)|not in)\s+(?:the\s+)?$")


# A hand said of a sidewalk or side: "the right-hand pavement", "on the left footpath".
_HAND = re.compile(r"\b(left|right)(?:[\s-]hand)?(?:\s+(?:side\s+)?(?:sidewalk|side walk|pavement|footpath|footway|walkway|kerb|curb))")


# A hand said of the way itself: "on the left side", "on the right-hand side of the road" (not "on the left of the bin").
_SIDE_OF_WAY = re.compile(r"\bon (?:the |its |his |her |their )?(left|right)(?:[\s-]hand)?(?: side)?"
                          r"(?: of (?:the |its |their )?(?:road|street|lane|carriageway)\b|(?! of\b))")
# How far ahead a thing said only by its side goes ("a bike in front of the ego on the left").
SIDE_AHEAD_M = 10.0


# How far into a driveway from the road a closure stands, and "east of the crossroads" from its centre.
DRIVEWAY_IN_M = 4.5
DRIVEWAY_WIDTH_M = 7.0
BEYOND_PLACE_M = 15.0
_COMPASS_OF = re.compile(r"\b(north|south|east|west)\s+of\b")
_UNIT = {"north": (0.0, 1.0), "south": (0.0, -1.0), "east": (1.0, 0.0), "west": (-1.0, 0.0)}


# A closure of one lane says so: "block the eastbound lane" (not "close Main Street", not "both lanes").
_ONE_LANE = re.compile(r"\b(?<!both )(?<!all )(?<!two )lane\b")


# Where a thing just named stood: "where it was", "where they used to be", "in its old spot".
_WHERE_IT_WAS = re.compile(r"\bwhere (?:it|they|that one|those) (?:was|were|stood|started|began|came from|had been|used to (?:be|stand))\b"
                           r"|\b(?:in|to|at|back to|back in|back at) (?:its|their) (?:old|original|first|former|previous|starting|start) "
                           r"(?:spot|place|position|location|point)s?\b")
# Where another thing is: "put the bus where the suv is now" (beside it), "where the bench was" (its spot).
_WHERE_THING = re.compile(r"\bwhere\s+(?:the|that|this|our)\s+(?P<thing>[a-z_0-9 ]+?)\s+"
                          r"(?P<verb>is|are|stands|sits|is parked|was|were|stood|used to (?:be|stand))\b")


def where_thing(r: Reading, scene: Scene, exclude: list[str]) -> dict[str, Any] | None:
    """The Location of "where the suv is" (beside it) or "where the bench was" (its spot), when one
    thing there is meant; None otherwise."""
    said = _WHERE_THING.search(r.low)
    if said is None:
        return None
    ids = [i for i in r.ids if i not in exclude and said.start("thing") <= r.low.find(i.replace("_", " ")) < said.end("thing")]
    kinds = [m.category for m in r.mentions if said.start("thing") <= m.start < said.end("thing")]
    present = ids or ([a.id for a in scene.assets if a.category == kinds[0] and a.id not in exclude] if kinds else [])
    if len(present) > 1:  # "move the bench where the tree is", with a dozen trees: never a guess at which
        from drivetwin.orchestrator.planning.base import PlanningError

        raise PlanningError(f"there are {len(present)} of {said.group('thing')!r} here; say which one, "
                            f"e.g. 'where {present[0]} is'")
    thing = scene.asset(present[0]) if present else None
    if thing is None:
        return None
    if said.group("verb") in ("was", "were", "stood") or said.group("verb").startswith("used"):
        return {"relation": "absolute", "x": round(thing.pose.x, 2), "y": round(thing.pose.y, 2)}
    return {"relation": "next_to", "target": thing.id}


# The margin a lane's middle keeps from an area it crosses (the junction).
AREA_MARGIN_M = 5.0


def _lane_middle(scene: Scene, lane: Lane) -> tuple[float, float]:
    """The point halfway along a lane, or the nearest one along it a margin clear of the areas it
    crosses (a junction in the middle of the road), as a row of three a margin apart (row_start)."""
    length = polyline_length(lane.centreline)
    start = row_start(scene, lane.centreline, length / 2 - AREA_MARGIN_M, AREA_MARGIN_M, 3)
    x, y, _ = point_along(lane.centreline, start + AREA_MARGIN_M)
    return x, y


def one_lane_named(r: Reading) -> bool:
    """Whether the words name one lane of a road ("the eastbound lane"), not the road or both lanes."""
    return r.lane is not None and _ONE_LANE.search(r.low) is not None


@dataclass(frozen=True)
class CrossSection:
    """Where a line closing a road or driveway stands: its middle, the way it runs, how wide it is."""

    x: float
    y: float
    heading_deg: float
    width: float


def cross_section(r: Reading, scene: Scene, where: dict[str, Any] | None) -> CrossSection | None:
    """The road (or a lot's driveway) a closure at `where` crosses: across every lane of the road
    there, or across the driveway just inside a lot's entrance; None where no road is near."""
    target = str((where or {}).get("target") or "")
    place = scene.landmark(target) if target else None
    entrance = scene.landmark(f"{place.name} entrance") if place is not None and place.kind == "area" else None
    if place is not None and any(lm.kind == "area" and place.name.startswith(f"{lm.name} ") for lm in scene.landmarks):
        entrance = place  # "the lot B driveway" is the entrance's
    if entrance is not None:
        heading = entrance.heading
        x, y = entrance.position
        return CrossSection(round(x - DRIVEWAY_IN_M * math.cos(heading), 2), round(y - DRIVEWAY_IN_M * math.sin(heading), 2),
                            round(math.degrees(heading) + 90.0, 1), DRIVEWAY_WIDTH_M)
    lane = scene.roads.lane(r.lane) if r.lane else None
    spot = _spot_by_a_thing(scene, where) if place is None else None
    if place is not None:
        x, y = place.position
    elif spot is not None:  # "block the eastbound lane 30 m ahead of the ego": there, not the lane's middle
        x, y = spot
    elif lane is not None:
        x, y = _lane_middle(scene, lane)  # "put a barrier across the westbound lane": its middle, off the junction
    else:
        return None
    way = _COMPASS_OF.search(r.masked)
    if way is not None:  # "east of the crossroads": past its edge that way
        dx, dy = _UNIT[way.group(1)]
        x, y = x + BEYOND_PLACE_M * dx, y + BEYOND_PLACE_M * dy
    elif place is not None and place.kind == "area":
        return None  # the middle of a junction or a lot is no road's cross-section
    if lane is None:
        lane = min(scene.roads.lanes, key=lambda ln: nearest_on_polyline(x, y, ln.centreline).distance, default=None)
    if lane is None:
        return None
    # A lane named is closed alone ("block the eastbound lane"); else every lane of the road there.
    road = [ln for ln in scene.roads.lanes if ln.road == lane.road] if lane.road and not one_lane_named(r) else [lane]
    feet = [nearest_on_polyline(x, y, ln.centreline) for ln in road]
    near = nearest_on_polyline(x, y, lane.centreline)
    kept = [(ln, f) for ln, f in zip(road, feet, strict=True) if math.dist((f.x, f.y), (near.x, near.y)) <= ln.width + lane.width]
    mx = sum(f.x for _, f in kept) / len(kept)
    my = sum(f.y for _, f in kept) / len(kept)
    return CrossSection(round(mx, 2), round(my, 2), round(math.degrees(near.heading) + 90.0, 1), sum(ln.width for ln, _ in kept))


def _spot_by_a_thing(scene: Scene, where: dict[str, Any] | None) -> tuple[float, float] | None:
    """The point a location relative to a thing (an asset or the ego, not a lane) names, or None."""
    target = str((where or {}).get("target") or "")
    if not target or scene.roads.lane(target) is not None or (scene.asset(target) is None and target != "ego"):
        return None
    try:
        anchor = resolve_anchor(scene, Location.model_validate(where), 0.0)
    except (ToolError, ValidationError):
        return None
    return anchor.x, anchor.y


# A side said with no place ("the lamps on the north side"): the side of the road nearest each thing.
_SIDE_ALONE = re.compile(r"\b(?:on|along|at) the (north|south|east|west)(?:ern)? side\b(?! of)")


# A road said to be where things stand: "the lights on Campus Drive", "cones along Main Street".
_ON_ROAD = r"\b(?:on|along|alongside|lining|beside|by)\s+(?:the\s+)?"
# Within this of a road's lane centrelines a thing stands on or by that road (its kerb and lamps).
ROAD_REACH_M = 8.0


def road_said(low: str, scene: Scene) -> tuple[str, Callable[[AssetInstance], bool]] | None:
    """The road the words say things stand on or along ("on Campus Drive"), and a test of
    whether a thing stands by it; None when they name none (or name a side of it: see side_of)."""
    if SIDE_OF.search(low):
        return None
    low = road_kinds_spelt(low)
    for road in sorted({lane.road for lane in scene.roads.lanes if lane.road}, key=len, reverse=True):
        if re.search(_ON_ROAD + re.escape(ph.normalise(road).strip()) + r"\b", low):
            lines = [lane.centreline for lane in scene.roads.lanes if lane.road == road]
            return road, lambda a, lines=lines: min(nearest_on_polyline(a.pose.x, a.pose.y, ln).distance for ln in lines) <= ROAD_REACH_M
    return None


def side_of(low: str, scene: Scene) -> tuple[str, Callable[[AssetInstance], bool]] | None:
    """The side of a road or place the words name ("on the north side of Main Street", "west of
    Campus Drive", both at once), as words and as a test of whether a thing stands on it (beyond
    the road's middle, or the place, that way); None when they name none."""
    sides = [side for side in (_side_named(low, scene), _compass_of_road(low, scene)) if side is not None]
    if len(sides) < 2:
        return sides[0] if sides else None
    (one, first), (other, second) = sides
    return f"{one}, {other}", lambda a: first(a) and second(a)


def _compass_of_road(low: str, scene: Scene) -> tuple[str, Callable[[AssetInstance], bool]] | None:
    """"West of Campus Drive", "east of the crossroads": beyond that road's middle, or that place, that way."""
    for said in re.finditer(r"\b((?:north|south)[\s-]?(?:east|west)|north|south|east|west)(?:ern)?\s+of\s+(?:the\s+)?([a-z][a-z ]*)", low):
        rest = road_kinds_spelt(said.group(2))
        ways = re.findall(r"north|south|east|west", said.group(1))  # "south-east of the fountain": both
        lanes = [lane for lane in scene.roads.lanes if lane.road and rest.startswith(ph.normalise(lane.road).strip())]
        if lanes and len(ways) == 1:
            return f"{said.group(1)} of {lanes[0].road}", _beyond_middle(lanes, said.group(1))
        found = find_place(scene, f" {rest} ")
        mark = scene.landmark(found[0]) if found is not None else None
        if mark is not None and re.match(r"\s*(?:the\s+)?" + re.escape(ph.normalise(rest).split()[0]), rest):
            tests = [beyond_nearest([mark.position], way) for way in ways]
            return f"{'-'.join(ways)} of {mark.name}", lambda a, tests=tests: all(test(a) for test in tests)
    return None


def _side_named(low: str, scene: Scene) -> tuple[str, Callable[[AssetInstance], bool]] | None:
    said = SIDE_OF.search(low)
    way = side_alone(low)
    if way is not None and (said is None or _SIDE_OF_THE_ROAD.search(low)):
        if not scene.roads.lanes:
            return None
        return f"{way} side of the road", beyond_nearest(across_points(scene, way), way)
    if said is None:
        return None
    rest = road_kinds_spelt(said.group(2))  # "main st" is Main Street
    roads = {lane.road for lane in scene.roads.lanes if lane.road and rest.startswith(ph.normalise(lane.road).strip())}
    lanes = [lane for lane in scene.roads.lanes if lane.road in roads]
    name = next(iter(roads), None)
    if lanes:  # beyond the road's middle: the lane on that side is on that side
        return f"{said.group(1)} side of {name}", _beyond_middle(lanes, said.group(1))
    marks = [lm for lm in scene.landmarks if any(rest.startswith(ph.normalise(n).strip()) for n in lm.names())]
    if not marks:
        return None
    return f"{said.group(1)} side of {marks[0].name}", beyond_nearest([marks[0].position], said.group(1))


def side_lane(low: str, scene: Scene) -> str | None:
    """The lane of a road on the side the words name ("the north side of Main Street": the
    westbound lane, the one furthest north), whose edge what stands on that side lines; None when
    they name no side of a road of two or more lanes."""
    found = lane_of_side(low, scene)
    return found[0].id if found is not None else None


def side_alone(low: str) -> str | None:
    """The compass side the words name with no road or place ("the lamps on the north side", "the
    south side of the road"): the side of the road nearest each thing; None when they name none."""
    said = _SIDE_ALONE.search(low) or _SIDE_OF_THE_ROAD.search(low)
    return said.group(1) if said is not None else None


# A side of the road said with no road named: "the south side of the road".
_SIDE_OF_THE_ROAD = re.compile(r"\b(north|south|east|west)(?:ern)? side of the (?:road|street)\b")


def _beyond_middle(lanes: list[Lane], way: str) -> Callable[[AssetInstance], bool]:
    """Whether a thing stands beyond the middle of a road (between its lanes' nearest points) in
    compass direction `way`."""
    dx, dy = md.COMPASS_VECTORS[way]

    def beyond(a: AssetInstance) -> bool:
        feet = [nearest_on_polyline(a.pose.x, a.pose.y, lane.centreline) for lane in lanes]
        mx, my = sum(f.x for f in feet) / len(feet), sum(f.y for f in feet) / len(feet)
        return (a.pose.x - mx) * dx + (a.pose.y - my) * dy > 0

    return beyond


def said_a_place(r: Reading) -> bool:
    """Whether the clause seems to name a place (for judging an unresolved one a guess)."""
    return bool(re.search(r"\b(near|next to|beside|by|in front of|behind|outside|close to|over by)\b", r.masked))


__all__ = [
    "ACROSS_FROM", "BETWEEN", "BY_IT", "EACH_PLACE", "EDGE_OF", "PLACE_SAID", "PLACE_WORDS", "Notes", "between", "each_place_named", "location", "places_called", "point_named", "relation_objects", "relation_of", "said_a_place", "says_other_place", "side_alone", "side_lane"]
