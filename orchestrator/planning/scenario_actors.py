"""Who acts in a scenario request: "the lead car", "the oncoming truck", "the car in the left
lane", "the cyclist", "the person behind the bus", an asset id, the ego.

A description is a head noun (a catalog category, found with the rule lexicon, or a role word
such as "cyclist" or "someone") and qualifiers read against the scene as the ego sees it:
ahead of it in its lane, coming towards it, in the lane to its left or right, crossing its
road, on a named road, behind another asset, parked or moving. Every asset the description
fits is returned; the caller asks which was meant when more than one does.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial

from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Scene

# Lateral distance (m) within which an asset counts as in the ego's lane: half a lane width
# plus slack for a car not yet centred (the campus lanes are 3.5 m wide).
SAME_LANE_M = 2.5
# The lane beside the ego's is one lane width (3.5 m) away; this band takes it and not the next.
NEXT_LANE_M = (2.0, 5.5)
# |cos| of the heading difference above which two actors drive along the same line.
ALONG = 0.7
# An asset "behind" another is within this lateral band of its line (a lane and a half).
BEHIND_BAND_M = 5.0

# Role words that are not catalog names but say what acts.
ROLE_WORDS: dict[str, str] = {
    "cyclist": "bicycle", "bicyclist": "bicycle", "biker": "bicycle", "rider": "bicycle",
    "someone": "pedestrian", "somebody": "pedestrian", "walker": "pedestrian", "child": "pedestrian",
    "kid": "pedestrian", "jogger": "pedestrian",
    "traffic lights": "traffic_light", "lights": "traffic_light", "light": "traffic_light",
    "signal": "traffic_light", "signals": "traffic_light", "traffic signal": "traffic_light",
}
# Head nouns that name any vehicle rather than one category.
ANY_VEHICLE = re.compile(r"\b(vehicle|vehicles|car|cars|auto)\b")
_ID = re.compile(r"\b([a-z]+(?:_[a-z]+)*_\d+)\b")


@dataclass(frozen=True)
class Frame:
    """Where an asset is seen from a reference asset: ahead, to the left, heading agreement."""

    ahead: float
    left: float
    along: float  # cos of the heading difference: 1 same way, -1 opposite, 0 crossing


def frame(of: AssetInstance, seen_from: AssetInstance) -> Frame:
    dx, dy = of.pose.x - seen_from.pose.x, of.pose.y - seen_from.pose.y
    yaw = seen_from.pose.yaw
    return Frame(dx * math.cos(yaw) + dy * math.sin(yaw), -dx * math.sin(yaw) + dy * math.cos(yaw),
                 math.cos(of.pose.yaw - yaw))


def motion(asset: AssetInstance) -> str:
    return category(asset.category).motion


def head_category(words: str) -> str | None:
    """The category a noun phrase names: the first catalog name, synonym or role word in it
    ("the car on the side road runs the red light" names a car, not a light)."""
    named: list[tuple[int, str]] = []
    if not re.search(r"\bstreet lights?\b", words):
        for role, name in sorted(ROLE_WORDS.items(), key=lambda r: -len(r[0])):
            named += [(m.start(), name) for m in re.finditer(rf"\b{role}\b", words)]
    # find_categories reads its own normalised copy (one leading space): its spans are one on.
    named += [(m.start - 1, m.category) for m in ph.find_categories(words)]
    return min(named)[1] if named else None


def own_words(words: str) -> str:
    """The words that describe the head itself, not the thing it is placed against."""
    return re.split(r"\b(?:from behind|behind|next to|beside|hidden|stuck)\b", words)[0]


def _road_of(scene: Scene, asset: AssetInstance) -> str | None:
    lane = getattr(asset.behaviour, "lane", None)
    for candidate in scene.roads.lanes:
        if candidate.id == lane:
            return candidate.road.lower()
    return None


def qualifiers(words: str, scene: Scene) -> list[tuple[str, Callable[[AssetInstance], bool]]]:
    """The tests a description's qualifiers put on a candidate, each with its words."""
    ego = scene.asset(EGO_ID)
    out: list[tuple[str, Callable[[AssetInstance], bool]]] = []
    behind = re.search(r"\bbehind (?:the |a |an )?([a-z_ ]+)", words)
    words = own_words(words)  # "the parked bus" in "the person behind the parked bus" is the bus's
    if ego is not None:
        if re.search(r"\b(lead|ahead|in front|leading|preceding)\b", words) and not re.search(r"\bbehind\b", words):
            out.append(("ahead of the ego", lambda a: frame(a, ego).ahead > 0 and abs(frame(a, ego).left) < SAME_LANE_M))
        if re.search(r"\b(oncoming|towards|toward|other way|opposite)\b", words):
            out.append(("coming towards the ego", lambda a: frame(a, ego).along < -ALONG))
        for side, sign in (("left", 1.0), ("right", -1.0)):
            if re.search(rf"\b{side}(-hand)? lane\b", words):
                out.append((f"in the {side} lane", partial(_beside, ego=ego, sign=sign)))
        if re.search(r"\b(side road|cross traffic|crossing road|from the (south|north)|up from|down from)\b", words):
            out.append(("on the road across the ego's", lambda a: abs(frame(a, ego).along) < 1 - ALONG))
        if re.search(r"\bovertak\w*|\bpassing\b", words):
            out.append(("overtaking", lambda a: a.behaviour.kind != "parked" and frame(a, ego).along > ALONG
                        and abs(frame(a, ego).left) >= SAME_LANE_M))
    for lane in scene.roads.lanes:
        if lane.road.lower() in words:
            road = lane.road.lower()
            out.append((f"on {lane.road}", partial(_on_road, scene=scene, road=road)))
            break
    if behind:
        anchor = head_category(behind.group(1))
        others = [a for a in scene.all_assets() if a.category == anchor]
        if len(others) == 1:
            out.append((f"behind the {anchor}", partial(_behind, anchor=others[0])))
    if re.search(r"\bparked\b", words):
        out.append(("parked", lambda a: a.behaviour.kind == "parked"))
    elif re.search(r"\b(moving|driving|travelling|traveling)\b", words):
        out.append(("moving", lambda a: a.behaviour.kind != "parked"))
    return out


def _beside(asset: AssetInstance, ego: AssetInstance, sign: float) -> bool:
    seen = frame(asset, ego)
    return NEXT_LANE_M[0] < sign * seen.left < NEXT_LANE_M[1] and seen.along > ALONG


def _on_road(asset: AssetInstance, scene: Scene, road: str) -> bool:
    return _road_of(scene, asset) == road


def _behind(asset: AssetInstance, anchor: AssetInstance) -> bool:
    if asset.id == anchor.id:
        return False
    if motion(asset) == "walker":  # a walker hides behind it, on the far side from the road
        return math.dist((asset.pose.x, asset.pose.y), (anchor.pose.x, anchor.pose.y)) < 2 * BEHIND_BAND_M
    seen = frame(asset, anchor)
    return seen.ahead < 0 and abs(seen.left) < BEHIND_BAND_M


def candidates(words: str, scene: Scene, moving_manoeuvre: bool) -> tuple[list[AssetInstance], str]:
    """The assets a noun phrase may name (best first) and a few words saying what was looked for.

    An asset id or the ego is exact. A category with qualifiers keeps the assets that pass
    every qualifier; when the manoeuvre is a driving one, moving assets are preferred to
    parked ones unless the words say parked.
    """
    low = ph.normalise(words).strip()
    ident = _ID.search(low)
    if ident and scene.asset(ident.group(1)) is not None:
        asset = scene.asset(ident.group(1))
        return ([asset] if asset is not None else []), ident.group(1)
    bare = re.sub(r"^(the|a|an|that|this)\s+", "", low)
    if any(bare.startswith(w) for w in ph.EGO_WORDS):
        ego = scene.asset(EGO_ID)
        return ([ego] if ego is not None else []), "the ego"
    head = head_category(own_words(low))
    if head is None:
        return [], low
    pool = [a for a in scene.all_assets() if a.id != EGO_ID and (
        a.category == head or (ANY_VEHICLE.search(low) is not None and head == "passenger_car" and motion(a) == "vehicle"
                               and not re.search(r"\b(truck|bus|suv|van)\b", low)))]
    if head == "passenger_car" and any(a.category == "passenger_car" for a in pool):
        pool = [a for a in pool if a.category == "passenger_car"] or pool
    tests = qualifiers(low, scene)
    for _, test in tests:
        pool = [a for a in pool if test(a)]
    if moving_manoeuvre and not re.search(r"\bparked\b", low):
        pool = [a for a in pool if a.behaviour.kind != "parked"] or pool
    what = " ".join([head.replace("_", " "), *(t for t, _ in tests)])
    return pool, what


__all__ = ["ROLE_WORDS", "Frame", "candidates", "frame", "head_category", "motion", "qualifiers"]
