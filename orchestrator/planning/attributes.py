"""What a request says about the things it names, held against what a plan makes of them.

coverage.py asks whether a plan acts on each thing named at all; this module asks whether it
gives them what the words ask: how many ("ten people"), on which lane or surface ("in the
westbound lane", "on the sidewalk"), in what look ("wooden", "paint it red"), and how strong
the weather is ("light snow", "raining hard"). The vocabularies come from the Workers' own
argument types and the world (lanes, surfaces, colours, materials), not from a suite's
wording. Each finding is a sentence in plain words; check.py turns them into a question.
"""

from __future__ import annotations

import itertools
import math
import re
from collections import Counter
from collections.abc import Iterable

import numpy as np
from drivetwin.orchestrator.planning.coverage import named_in
from drivetwin.orchestrator.planning.intent import FEWER_WORDS, WEATHER_HEDGED
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules import numbers as nb
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.tools.appearance import COLOURS
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.scene import AssetInstance, Scene
from drivetwin.worlds.surface import lane_at, nearest_on_polyline, surface_at

# Surfaces a request can put things on, by the words people use for them.
_ON_SURFACE = re.compile(r"\b(?:on|onto|along) (?:the |a )?(sidewalk|side walk|pavement|footpath|kerb|curb)\b")
# How far (m) from a lane's centre line an asset still counts as in that lane.
LANE_SLACK_M = 0.5
# Layouts named in words (the arrange Worker's line and ring) and spacings ("4 m apart"), judged
# on three or more new things: the smaller spread of a line is at most LINE_SPREAD of its
# length, a ring's radii vary by at most RING_SPREAD, a spacing is held within a quarter.
MIN_LAYOUT = 3
_AROUND = re.compile(r"\b(around|round|surround\w*|encircl\w*|ring(?:ed)? off|cordon(?:ed)? off)\b")
LINE_SPREAD, RING_SPREAD, SPACING_TOLERANCE = 0.25, 0.25, 0.25
# "Facing east": a heading said as a compass direction; a heading may be off by this much.
_FACING = re.compile(r"\b(?:facing|face|pointing|heading|pointed)\s+(?:to(?:wards?)?\s+)?(?:the\s+)?(north|south|east|west)\b")
HEADING_SLACK_DEG = 30.0
# "In front of the SUV", "behind us": the side of an asset, judged for things more than this
# far from it (closer, the side of a footprint is a matter of metres' rounding).
_SIDE = re.compile(r"\b(in front of|ahead of|behind)\s+(?:the\s+|our\s+)?([a-z0-9_]+(?: [a-z0-9_]+)?)")
MIN_SIDE_M = 1.0
_EGO_WORDS = ("ego", "us", "me", "ego_vehicle", "ego_car", "car_under_test")
# Weather strength: words that ask for little or for much, and where the tool's scale splits.
_LIGHT = re.compile(rf"\b(light|gentle|slight|soft|a bit of|a little)\s+(rain|snow|fog|drizzle|shower|mist)|\bdrizzl|{WEATHER_HEDGED.pattern}")
_HEAVY = re.compile(r"\b(heavy|hard|strong|thick|dense|torrential|pouring|downpour|blizzard)\b")
STRENGTH_SPLIT = 0.5
# Words that ask for a look change when a colour is named ("paint the bus red", "make it blue").
_RECOLOUR = re.compile(r"\b(?:(?:re)?paint|(?:re)?colou?r|spray)(?:s|ed|ing)?\b|\b(?:make|turn|change)\b")

# A thing asked to be another size. No Worker changes a thing's size (each stands at its
# catalog size), so no plan accounts for it: "make the bench twice as big", "shrink the bus".
_SIZE = (r"(?:a (?:bit|little|lot) |much |slightly )?(?:bigger|larger|smaller|taller|shorter|wider|narrower|huge|tiny|enormous"
         r"|(?:twice|three times|\d+ times) (?:as )?(?:big|large|tall|wide|bigger|larger)|(?:half|double) (?:the|its|their) size)")
_RESIZED = re.compile(rf"\b(?:make|makes|making|turn|get)\s+(?P<thing>[^,.;!?]{{1,40}}?)\s+(?P<size>{_SIZE})"
                      r"(?=\s*(?:$|[,.;!?]|than\b|please\b|and\b|so\b|now\b|too\b|for\b|instead\b))"
                      r"|\b(?:resize|rescale|enlarge|shrink|scale up|scale down|upscale)\s+(?P<shrunk>[^,.;!?]{1,40})")
# What is made longer or wider that is no thing: a layout, a gap, a stretch of time or a place.
_NO_SIZED_THING = re.compile(r"\b(?:gap|gaps|space|spacing|distance|ring|circle|line|row|queue|crowd|group|cluster|grid|area|zone"
                             r"|radius|margin|buffer|wait|pause|stop|trip|route|journey|time|rain|snow|fog|storm|lot|lane|road"
                             r"|street|crossing|crosswalk|view|picture|image|frame)s?\b")


def resized(low: str) -> list[str]:
    """A thing said to become bigger or smaller, which no Worker can do: said plainly."""
    for m in _RESIZED.finditer(low):
        thing = ph.normalise(m.group("thing") or m.group("shrunk"))
        named = ph.find_categories(thing)
        # the words up to the thing and the one after it: "the gap between the cones", "the cone line"
        head = re.match(r"\s*\S*", thing[named[0].end :]) if named else None
        if named and head is not None and not _NO_SIZED_THING.search(thing[: named[0].end] + head.group(0)):
            size = m.group("size") or "another size"
            return [f"you asked for the {named[0].category.replace('_', ' ')} to be {size}, but things keep the size they "
                    "come in; I can move, turn or paint them, or put another kind in their place"]
    return []


def counts_named(masked: str) -> dict[str, int]:
    """The number said right before each category named ("ten people", "4 bins"): how many of
    that category the request asks for."""
    out: dict[str, int] = {}
    for m in named_in(masked):
        amount = _count_before(m.before)
        if amount is not None:
            out[m.category] = amount
    return out


# Words of amount that say no number ("some of the cars", "a couple of benches" as a guess).
_VAGUE_AMOUNTS = ("pair", "couple", "few", "several", "some")


def _count_before(before: str) -> int | None:
    """The amount said just before a thing's name: "one of the" (partitive), "ten", "4" (two or more)."""
    partitive = md.partitive_count(before)
    if partitive is not None:
        return None if md.partitive_word(before) in _VAGUE_AMOUNTS else partitive
    word = (before.split()[-1:] or [""])[0]
    amount = int(word) if word.isdigit() else ph.NUMBER_WORDS.get(word)
    return amount if amount is not None and amount >= 2 and word not in _VAGUE_AMOUNTS else None


def wrong_counts(masked: str, added: Iterable[AssetInstance], per: int = 1) -> list[str]:
    """Categories the plan adds a different number of than the request says (`per` place, when it
    says that many at each of several places)."""
    made = Counter(a.category for a in added)
    more = _more_unnamed(masked)
    return [f"you asked for {n} {c.replace('_', ' ')}" + (f" at each of {per} places" if per > 1 else "")
            + f", but the plan adds {made[c]}" for c, n in counts_named(masked).items()
            if made[c] and made[c] not in (n * per, n + more)]


def wrong_removals(masked: str, removed: Iterable[AssetInstance]) -> list[str]:
    """Categories the plan removes a different number of than the request says ("one of the traffic
    lights", "two cones"); not an amount to be left ("down to two cones", "keep one")."""
    gone = Counter(a.category for a in removed)
    indexed = ph.normalise(masked)  # the text find_categories indexes
    out = []
    for c, n in counts_named(masked).items():
        said = next((m for m in ph.find_categories(masked) if m.category == c and _count_before(indexed[: m.start]) == n), None)
        if said is None or re.search(r"\b(?:to|only|just|leave|leaving|keep|keeping|but|except|save)\s+(?:\w+\s+){0,3}$", indexed[: said.start]):
            continue
        word = ph.singular(indexed[said.start : said.end].strip())  # "three cars": the SUV is a car too
        kinds = {k for k, cat in catalog().items() if word in cat.tags} if word in md.catalog_tags() else {c}
        taken = sum(gone[k] for k in kinds | {c})
        if taken and taken != n:
            out.append(f"you asked to take away {n} {word}{'s' if n > 1 else ''}, but the plan removes {taken}")
    return out


# More of the thing just named with its noun left out ("two cones at the gate and another two at
# the fountain", "three more by the library"): the amount after "another", or before "more".
# ("... and 2 at the east gate": two more of them, placed)
_MORE_SAID = re.compile(r"\banother\s+(\d+|[a-z]+)\b|\b(\d+|[a-z]+)\s+more\b"
                        r"|\band\s+(\d+|[a-z]+)\s+(?=(?:at|by|near|in|on|next|beside|outside|behind)\b)")


def _more_unnamed(masked: str) -> int:
    """How many more of the thing named before the words ask for without naming it again."""
    total = 0
    for m in _MORE_SAID.finditer(masked):
        word = m.group(1) or m.group(2) or m.group(3)
        amount = int(word) if word.isdigit() else ph.NUMBER_WORDS.get(word)
        if amount is not None and not ph.find_categories(" ".join(masked[m.end() :].split()[:2])):
            total += amount
    return total


def off_lane(lane_id: str, scene: Scene, placed: Iterable[AssetInstance]) -> list[str]:
    """Assets placed away from the one lane the request names."""
    lane = scene.roads.lane(lane_id)
    if lane is None:
        return []
    far = [a.id for a in placed if a.id != "ego" and not _in_lane(scene, a, lane_id)]
    return [f"you named lane {lane_id}, but the plan puts {', '.join(far)} outside it"] if far else []


def _in_lane(scene: Scene, asset: AssetInstance, lane_id: str) -> bool:
    found = lane_at(scene, asset.pose.x, asset.pose.y)
    if found is not None:
        return found.id == lane_id
    lane = scene.roads.lane(lane_id)
    near = nearest_on_polyline(asset.pose.x, asset.pose.y, lane.centreline) if lane is not None else None
    return near is None or lane is None or near.distance <= lane.width / 2 + LANE_SLACK_M


def off_surface(low: str, scene: Scene, placed: Iterable[AssetInstance]) -> list[str]:
    """Assets not on the sidewalk that the request puts on one."""
    said = _ON_SURFACE.search(low)
    if said is None:
        return []
    placed = list(placed)
    before = ph.find_categories(low[: said.start()])  # "a bus at the stop and a pedestrian on the sidewalk": the pedestrian
    if before and any(a.category == before[-1].category for a in placed):
        placed = [a for a in placed if a.category == before[-1].category]
    wrong = [a.id for a in placed if a.id != "ego" and surface_at(scene, a.pose.x, a.pose.y) != "sidewalk"]
    return [f"you said on the sidewalk, but the plan puts {', '.join(wrong)} elsewhere"] if wrong else []


def look_left_out(low: str, calls: tuple[ToolCall, ...]) -> list[str]:
    """A material, or a colour asked for as a change, that no call sets."""
    set_to = {str(c.args["colour"]) for c in calls if c.args.get("colour")}
    if any(c.tool == "set_asset_appearance" or c.args.get("colour") for c in calls):
        missing = [w for w in md.colours_asked(low) if w not in set_to and not (w in ("grey", "gray") and set_to & {"grey", "gray"})]
        return [f"you asked for {missing[0]}, but the plan does not paint anything {missing[0]}"] if missing and set_to else []
    for m in reversed(ph.find_categories(low)):  # "broken concrete" names rubble, not a material
        low = low[: m.start] + " " * (m.end - m.start) + low[m.end :]
    words = re.findall(r"[a-z]+", low)
    material = md.material_said(low)
    if material is not None and md.material_said(_descriptions_of(calls)) != material:  # "short steel posts": bollards, steel as made
        return [f"you asked for {material}, but the plan does not change how anything looks"]
    colours = [w for w in words if w in COLOURS]
    if colours and _RECOLOUR.search(low):
        return [f"you asked for {colours[0]}, but the plan does not change how anything looks"]
    return []


def _descriptions_of(calls: tuple[ToolCall, ...]) -> str:
    """The catalog's descriptions of what the calls add ("a short steel bollard": made of steel as it comes)."""
    kinds = [k for c in calls for k in [c.args.get("category"), *c.args.get("categories", [])] if isinstance(k, str)]
    return " ".join(catalog()[k].description for k in kinds if k in catalog())


def names_group(low: str) -> bool:
    """Whether the words name a group by its catalog tag in the plural ("the vehicles")."""
    return bool(md.groups_said(low))


def group_left_behind(low: str, removed: Iterable[AssetInstance], candidates: Iterable[AssetInstance]) -> list[str]:
    """A removal of a group named by its catalog tag in the plural ("the vehicles in lot B",
    "all the signs") that leaves members of other categories of that group among `candidates`
    (the assets in the named scope)."""
    gone = list(removed)
    if not gone:
        return []
    out = []
    for tag, members in md.groups_said(low).items():
        if re.search(rf"\b(?:those|these)\s+(?:\w+\s+)?{re.escape(tag)}s\b", low):
            continue  # "so those signs shouldn't be there": the ones just talked of, not every sign
        if re.search(rf"\b(?:\w+)\s+of\s+(?:(?:the|those|these|our|my|its)\s+)?(?:\w+\s+)?{re.escape(tag)}s\b", low) or FEWER_WORDS.search(low):
            continue  # "one of the cars in lot B" ("one of cars", the article dropped), "fewer cars": some of them, as many as said
        ids = {a.id for a in gone}
        left = [a.id for a in candidates if a.category in members and a.id not in ids and a.id != "ego"]
        if left and any(a.category in members for a in gone):
            out.append(f"you said {tag}s, but the plan leaves {', '.join(left)}")
    return out


# A layout said as a thing of its own: "a row of bollards", "a ring of cones".
_A_LAYOUT = re.compile(r"\b(?:a|an|one|another)\s+(line|row|ring|circle|grid|square)\s+of\b")


def layouts_merged(masked: str, calls: Iterable[ToolCall]) -> list[str]:
    """Two layouts asked for ("a row of bollards at lot A and a ring of cones at the fountain")
    laid out as one of both kinds."""
    said = [m.group(1) for m in _A_LAYOUT.finditer(masked)]
    arranged = [c for c in calls if c.tool == "arrange_assets"]
    if len(said) < 2 or len(arranged) != 1 or len(arranged[0].args.get("categories", [])) < 2:
        return []
    return [f"you asked for a {said[0]} and a {said[1]}, but the plan lays out one {arranged[0].args.get('shape', 'layout')} of both"]


def wrong_layout(masked: str, added: Iterable[AssetInstance]) -> list[str]:
    """New things the request lays out ("in a row", "a ring of", "4 m apart") that the plan
    places otherwise: judged on where they end up, whichever Worker put them there."""
    placed = [a for a in added if a.id != "ego"]
    kinds = Counter(a.category for a in placed)  # "six cones in a row and a sign by them": the row is the cones
    placed = [a for a in placed if kinds[a.category] > 1 or len(kinds) == 1] or placed
    if len(placed) < MIN_LAYOUT:
        return []
    points = np.array([[a.pose.x, a.pose.y] for a in placed])
    centred = points - points.mean(axis=0)
    out = []
    said = md.layout_said(masked)
    if said in ("line", "row") and md.BOTH_SIDES.search(masked) is None:  # a row each side is two lines
        spread = np.linalg.svd(centred, compute_uv=False)
        if spread[0] <= 0 or spread[1] / spread[0] > LINE_SPREAD:
            out.append(f"you asked for a {said}, but the plan scatters them")
    if said in ("ring", "circle"):
        radii = np.hypot(centred[:, 0], centred[:, 1])
        if radii.mean() <= 0 or radii.std() / radii.mean() > RING_SPREAD:
            out.append(f"you asked for a {said}, but the plan does not put them round a centre")
    wanted = nb.spacing_said(masked)
    if wanted is not None:
        # each one's nearest neighbour: the spacing of a line and of a grid's rows alike
        apart = np.hypot(*(centred[:, None, :] - centred[None, :, :]).transpose(2, 0, 1))
        np.fill_diagonal(apart, np.inf)
        gap = float(np.median(apart.min(axis=1)))
        if abs(gap - wanted) > SPACING_TOLERANCE * wanted:
            out.append(f"you asked for {wanted:g} m apart, but the plan spaces them {gap:.1f} m")
    return out


def not_around(low: str, centre: tuple[float, float] | None, added: Iterable[AssetInstance]) -> list[str]:
    """New things put "around" a place or thing (a ring, a cordon) that stand on one side of it:
    the widest empty arc seen from its centre must be under half a turn."""
    placed = [a for a in added if a.id != "ego"]
    said = _AROUND.search(low)
    if centre is None or len(placed) < MIN_LAYOUT or said is None:
        return []
    if said.group(1).endswith(" off") and _in_a_line(placed):
        return []  # "cordon off the east gate": a way through closed by a line across it
    angles = sorted(math.atan2(a.pose.y - centre[1], a.pose.x - centre[0]) for a in placed)
    gaps = [b - a for a, b in itertools.pairwise(angles)] + [angles[0] + math.tau - angles[-1]]
    if max(gaps) >= math.pi:
        empty = math.degrees(max(gaps))
        return [f"you asked for them around it, but the plan leaves an empty side of {empty:.0f} degrees"]
    return []


def _in_a_line(placed: list[AssetInstance]) -> bool:
    centred = np.array([(a.pose.x, a.pose.y) for a in placed]) - np.mean([(a.pose.x, a.pose.y) for a in placed], axis=0)
    spread = np.linalg.svd(centred, compute_uv=False)
    return bool(spread[0] > 0 and spread[1] / spread[0] <= LINE_SPREAD)


def wrong_heading(low: str, placed: Iterable[AssetInstance]) -> list[str]:
    """Things the request has face a compass direction ("facing east") that the plan turns
    elsewhere."""
    said = [m.group(1) for m in _FACING.finditer(low)]
    if not said:
        return []
    # "a bus heading east and a lorry heading west": each faces one of the ways said
    wants = [math.atan2(md.COMPASS_VECTORS[w][1], md.COMPASS_VECTORS[w][0]) for w in said]
    slack = math.radians(HEADING_SLACK_DEG)
    off = [a.id for a in placed if all(abs(math.remainder(a.pose.yaw - want, math.tau)) > slack for want in wants)]
    return [f"you said facing {' or '.join(dict.fromkeys(said))}, but the plan turns {', '.join(off)} another way"] if off else []


def wrong_side(low: str, scene: Scene, added: Iterable[AssetInstance]) -> list[str]:
    """New things put "in front of" or "behind" an asset (a car, the ego: assets face a way)
    that end up on its other side."""
    out = []
    for m in _SIDE.finditer(low):
        anchor = _asset_named(scene, m.group(2))
        if anchor is None:
            continue
        ahead = m.group(1) in ("in front of", "ahead of")
        for a in added:
            dx, dy = a.pose.x - anchor.pose.x, a.pose.y - anchor.pose.y
            along = dx * math.cos(anchor.pose.yaw) + dy * math.sin(anchor.pose.yaw)
            if math.hypot(dx, dy) > MIN_SIDE_M and (along < 0) == ahead:
                out.append(f"you said {m.group(1)} {anchor.id}, but the plan puts {a.id} on its other side")
    return out


def _asset_named(scene: Scene, words: str) -> AssetInstance | None:
    """The asset the words after "in front of" name: an id ("passenger_car_2"), the ego, or a
    category of which the world holds exactly one ("the bus", not "the bus stop")."""
    said = words.split()
    for phrase in (" ".join(said), said[0]):
        key = phrase.replace(" ", "_")
        if key in _EGO_WORDS:
            return scene.asset("ego")
        if (found := scene.asset(key)) is not None:
            return found
        indexed = ph.normalise(phrase)  # the text find_categories indexes
        kinds = [m.category for m in ph.find_categories(phrase) if indexed[m.start : m.end] == indexed.strip()]
        same = [a for a in scene.all_assets() if kinds and a.category == kinds[0]]
        if len(same) == 1:
            return same[0]
    return None


def some_of_all(masked: str, changed: Iterable[AssetInstance], scene: Scene, place: str | None = None,
                reach: float = 30.0) -> list[str]:
    """A change asked of all of a category ("make every bench wooden", "all the cars red") that
    the plan makes to only some of them; with a place named, all of them there (within `reach`)."""
    done = Counter(a.category for a in changed)
    landmark = scene.landmark(place) if place else None
    out = []
    for m in named_in(masked):
        if not re.search(r"\b(all|every|each)( one)?( of)?( the| those| these)?\s*$", m.before):
            continue
        there = scene.count(m.category) if landmark is None else sum(
            1 for a in scene.assets
            if a.category == m.category and math.dist((a.pose.x, a.pose.y), landmark.position) <= reach)
        if 0 < done[m.category] < there:
            out.append(f"you said all {m.category.replace('_', ' ')}s, but the plan changes {done[m.category]} of the {there}")
    return out


def weather_strength(low: str, calls: tuple[ToolCall, ...]) -> list[str]:
    """Weather said to be light or heavy that the plan sets at the other end of the scale."""
    set_to = [c.args.get("intensity") for c in calls if c.tool == "set_weather"]
    strengths = [float(s) for s in set_to if isinstance(s, int | float) and math.isfinite(s)]
    if not strengths:
        return []
    # "not too strong", "not to thick"; "the fog is far too thick": a strength denied or complained of
    low = re.sub(r"\b(?:not (?:too |to |so |very |a |that )?|too )(?:much )?(?=heavy|hard|strong|thick|dense|downpour|deluge|blizzard)", "un", low)
    if (_LIGHT.search(low) or "unstrong" in low or "unheavy" in low) and strengths[-1] > STRENGTH_SPLIT:
        return [f"you asked for light weather, but the plan sets intensity {strengths[-1]:g}"]
    if _HEAVY.search(low) and strengths[-1] < STRENGTH_SPLIT:
        return [f"you asked for heavy weather, but the plan sets intensity {strengths[-1]:g}"]
    return []


# Weather by its everyday words (this check's own small vocabulary), and a word that denies what
# follows it: "just not sunny", "not a rainy day", "no snow please", "without the fog".
_WEATHER_SAID = {"clear": r"sunny|sunshine|sun|clear|fine", "rain": r"rain\w*|wet|showers?|drizzl\w*",
                 "snow": r"snow\w*", "fog": r"fog\w*|mist\w*", "cloudy": r"cloud\w*|overcast"}
_DENIES = r"\b(?:not|no|never|without|n't)\s+(?:(?:a|an|any|the|too|so|very|that|really|at all|just|in|on|into|for|with)\s+){0,2}"


# Behaviours by their everyday words: "get it moving, and not round and round the car park".
_BEHAVIOUR_SAID = {"circle": r"round and round|circl\w*|loops?|laps?", "parked": r"park\w*|stationary|standing still",
                   "drive_lane": r"driv\w*"}


def denied_set(low: str, calls: tuple[ToolCall, ...]) -> list[str]:
    """A weather, colour or behaviour the words deny ("could it be less nice, just not sunny",
    "not red", "not round and round the car park") that the plan sets all the same."""
    out = []
    for call in calls:
        behaviour = call.args.get("behaviour") if call.tool in ("set_behaviour", "add_asset") else None
        words = _WEATHER_SAID.get(str(call.args.get("kind"))) if call.tool == "set_weather" else \
            _BEHAVIOUR_SAID.get(str(behaviour.get("kind"))) if isinstance(behaviour, dict) else None
        if words:
            said = re.search(rf"{_DENIES}({words})\b", low)
        elif call.tool == "set_asset_appearance" and isinstance(colour := call.args.get("colour"), str):
            said = re.search(rf"{_DENIES}({re.escape(colour.lower())})\b", low)
        else:
            continue
        if said is not None:
            out.append(f"you said not {said.group(1)}, but the plan sets {describe_setting(call)}")
    return out


def describe_setting(call: ToolCall) -> str:
    """What a weather, behaviour or look call sets, in words ("the weather clear", "the behaviour
    circle", "the colour red")."""
    if call.tool == "set_weather":
        return f"the weather {call.args.get('kind')}"
    if isinstance(behaviour := call.args.get("behaviour"), dict):
        return f"the behaviour {behaviour.get('kind')}"
    return f"the colour {call.args.get('colour')}"


__all__ = [
    "counts_named",
    "denied_set",
    "group_left_behind",
    "look_left_out",
    "names_group",
    "not_around",
    "off_lane",
    "off_surface",
    "some_of_all",
    "weather_strength",
    "wrong_counts",
    "wrong_heading",
    "wrong_layout",
    "wrong_side",
]
