"""A newcomer to a story: the actor a scenario request brings in rather than names.

"A pedestrian steps out in front of the ego" in a scene with no pedestrian, "a car ahead
brakes hard when the ego gets close" where the only cars are parked in a lot, "add a cyclist
that crosses when the ego is 20 m away": the request describes an actor and what it does,
and expects it to be there. The newcomer is added where its manoeuvre happens, as the ego
sees it: a walker waiting on the kerb ahead of the ego, on its right; a vehicle ahead in the
ego's lane, a little slower so that the ego closes in (the usual "lead vehicle" of a braking
scenario); one that overtakes behind the ego, a little faster; one that cuts in beside it,
in the lane next to the ego's going its way. Only an indefinite description ("a", "someone")
or a role ("the lead car") brings one in: "the bus brakes" with no bus is still refused, and
a description with a place of its own ("a kid by the bench") is left to the person to place.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.orchestrator.planning.scenario_actors import ALONG, NEXT_LANE_M, frame, head_category
from drivetwin.orchestrator.planning.scenario_manoeuvres import _COMPILED, read_manoeuvre
from drivetwin.orchestrator.planning.scenario_triggers import TRIGGER
from drivetwin.orchestrator.transaction import TransactionError, execute
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import EGO_ID, AssetInstance, DriveLane, Scene
from drivetwin.worlds.surface import nearest_on_polyline

# A walker who is to step into the ego's road waits on the kerb this far ahead of the ego.
WALKER_AHEAD_M = 35.0
# A vehicle the ego meets starts this far ahead of it in its lane...
LEAD_AHEAD_M = 25.0
# ...at this share of the ego's speed, so that a trigger on the ego closing in comes (25 m at
# 5 m/s against 3 m/s: 15 m apart after 5 s).
LEAD_SPEED_SHARE = 0.6
# A thing someone comes out from behind stands this far at most to the side of the ego's line.
ROADSIDE_M = 15.0
# One that overtakes starts this far behind the ego, this much faster.
FOLLOW_BEHIND_M = 15.0
OVERTAKE_EXTRA_MS = 3.0
# The speed a newcomer drives at when the ego stands still.
STILL_EGO_SPEED_MS = 5.0
# The manoeuvres only a moving vehicle makes: a parked car does not "brake" or "cut in".
MOVERS_ONLY = frozenset({"brake", "stop", "cut_in", "overtake", "lane_change", "junction_turn", "change_speed"})

# A description that brings an actor in, not one that names an actor already there.
_INDEFINITE = re.compile(r"^(?:a|an|some|another|one)\s|^some(?:one|body)\b")
_ROLE = re.compile(r"\b(?:lead|leading|preceding|ahead|in front)\b")
# Words that give the newcomer a place of its own, which this module does not read.
_OWN_PLACE = re.compile(r"\b(?:at|near|by|next to|beside|on|in|from|behind|outside|opposite|across)\b")
# "runs out from behind the bus": where a walker waits, out of the ego's sight.
_FROM_BEHIND = re.compile(r"\bbehind (?P<what>(?:the |a |an |that |this )?[a-z_ ]+?)(?=\s+(?:in front|into|onto|across|and|when|as|once|after|just)\b|[,.;]|$)")
# The ego made to stop for a newcomer: "the ego has to brake for a kid running into the road".
_STOP_FOR = re.compile(r"\bego(?: car| vehicle)?\s+(?:(?:to|has|have|needs?|must|should|will|would|is going|gets?)\s+)*"
                       r"(?:stop|brake|yield|give way|slow down|swerve|react)\w*\s+(?:hard\s+|suddenly\s+|sharply\s+)?"
                       r"(?:for|because of|to avoid)\s+(?P<who>(?:a|an|some)\s+[a-z]+(?:\s+(?!(?:who|that|when|as|once|if|so|and|to|at|in|on|by|near|from|[a-z]+ing)\b)[a-z]+)?|someone|somebody)"
                       r"(?P<rest>[^.;]*)")
# "add a pedestrian that crosses ...": the thing added and what it does.
_ADD_WHO = re.compile(r"^\s*(?:please\s+)?(?:add|put|place|spawn|create|insert|bring in)\s+(?P<who>(?:a|an|one|another)\s+[a-z ]+?)"
                      r"\s+(?:that|who|which)\s+(?:will\s+|should\s+|then\s+)?(?P<does>.+)$")


@dataclass(frozen=True)
class Arrival:
    """The call that adds the newcomer, its id and the scene with it in."""

    call: ToolCall
    id: str
    scene: Scene


def as_story(low: str) -> str | None:
    """ "add a pedestrian that crosses when the ego is 20 m away" as the story it tells ("a
    pedestrian crosses when ..."); None when the request is no such add."""
    said = _ADD_WHO.match(low)
    return f"{said.group('who')} {said.group('does')}" if said is not None else None


def hazard_story(low: str) -> str:
    """ "I need the ego to have to stop for someone walking out" as the story that makes it so:
    "someone crosses the road in front of the ego" (with any trigger said); `low` when the
    request is no such thing. The ego is the system under test: what it must react to is the
    edit, never the ego stopping by itself."""
    said = _STOP_FOR.search(low)
    if said is None:
        return low
    who = said.group("who")
    head = head_category(who)
    if head is None or (category(head).motion != "walker" and head != "bicycle"):
        return low
    when = TRIGGER.search(said.group("rest"))
    return f"{who} crosses the road in front of the ego" + (f" {said.group('rest')[when.start() :]}" if when else "")


def brings_in(subject: str) -> bool:
    """Whether `subject` describes a newcomer: indefinite or a role, with no place of its own."""
    low = subject.strip()
    return bool(_INDEFINITE.match(low) or _ROLE.search(low)) and not _OWN_PLACE.search(low.replace("in front", ""))


def arrive(subject: str, action: str, scene: Scene, registry: ToolRegistry) -> Arrival:
    """The newcomer `subject` describes, added where the manoeuvre `action` says happens;
    PlanningError when nothing the catalog holds fits it or the world has no room for it."""
    head = head_category(subject)
    ego = scene.asset(EGO_ID)
    if head is None or ego is None:
        raise PlanningError(f"there is no {subject.strip()} in the scene, and I cannot tell what to bring in")
    motion = category(head).motion
    if motion == "walker":
        where: dict[str, Any] = {"relation": "at", "target": EGO_ID, "along_m": WALKER_AHEAD_M, "side": "right"}
        hidden = _FROM_BEHIND.search(action)
        if hidden is not None:  # "darts out from behind the bench": it waits there, out of sight
            where = {"relation": "behind", "target": _the_one(hidden.group("what"), scene)}
        call = ToolCall(tool="add_asset", args={"category": head, "location": where})
    elif motion == "vehicle":
        overtakes = any(kind == "overtake" and words.search(action) for kind, words in _COMPILED)  # read as a lane change
        call = _vehicle(head, "overtake" if overtakes else read_manoeuvre(action, motion).kind, scene)
    else:
        raise PlanningError(f"a {head.replace('_', ' ')} does not move by itself; add a vehicle or a pedestrian")
    try:
        run = execute(registry, scene, [call])
    except TransactionError as exc:
        raise PlanningError(f"there is no {head.replace('_', ' ')} in the scene, and no room to bring one in: {exc}") from exc
    new_id = str(run.results[0].data["ids"][0])
    return Arrival(call=call, id=new_id, scene=run.after)


def _the_one(words: str, scene: Scene) -> str:
    """The asset `words` name ("the bench", "the tree") that a newcomer hides behind: the only
    one, else the one by the ego's road ahead of it."""
    kind = head_category(words)
    found = [a for a in scene.all_assets() if a.category == kind and a.id != EGO_ID]
    if len(found) > 1:
        seen = [(frame(a, scene.ego), a) for a in found]
        found = sorted((a for f, a in seen if f.ahead > 0 and abs(f.left) <= ROADSIDE_M), key=lambda a: frame(a, scene.ego).ahead)[:1]
    if not found:
        what = re.sub(r"^(?:the|a|an|that|this)\s+", "", words.strip()) or "thing"
        raise PlanningError(f"there is no {what} by the ego's road ahead of it for someone to come out from behind")
    return found[0].id


def _vehicle(head: str, manoeuvre: str, scene: Scene) -> ToolCall:
    ego = scene.ego
    lane = ego.behaviour.lane if isinstance(ego.behaviour, DriveLane) else None
    speed = ego.behaviour.speed if isinstance(ego.behaviour, DriveLane) and ego.behaviour.speed else STILL_EGO_SPEED_MS
    if manoeuvre == "overtake":
        where: dict[str, Any] = {"relation": "at", "target": EGO_ID, "along_m": -FOLLOW_BEHIND_M}
        speed += OVERTAKE_EXTRA_MS
    elif manoeuvre == "cut_in":
        lane = _lane_beside(scene)
        where = {"relation": "in_lane", "target": EGO_ID, "lane": lane}
    else:
        where = {"relation": "at", "target": EGO_ID, "along_m": LEAD_AHEAD_M}
        speed *= LEAD_SPEED_SHARE
    drive: dict[str, Any] = {"kind": "drive_lane", "speed": round(speed, 1), **({"lane": lane} if lane else {})}
    return ToolCall(tool="add_asset", args={"category": head, "location": where, "behaviour": drive})


def _lane_beside(scene: Scene) -> str:
    """The lane next to the ego's going its way, for a vehicle to cut in from."""
    ego = scene.ego
    for lane in scene.roads.lanes:
        near = nearest_on_polyline(ego.pose.x, ego.pose.y, lane.centreline)
        lateral = abs(-(near.x - ego.pose.x) * math.sin(ego.pose.yaw) + (near.y - ego.pose.y) * math.cos(ego.pose.yaw))
        if math.cos(near.heading - ego.pose.yaw) > ALONG and NEXT_LANE_M[0] <= lateral <= NEXT_LANE_M[1]:
            return lane.id
    raise PlanningError("there is no lane beside the ego's going its way for a vehicle to cut in from")


def parked_only(actors: list[AssetInstance], manoeuvre: str) -> bool:
    """Whether every candidate is parked and the manoeuvre needs one moving ("a car brakes")."""
    return manoeuvre in MOVERS_ONLY and all(a.behaviour.kind == "parked" for a in actors)


__all__ = ["MOVERS_ONLY", "Arrival", "arrive", "as_story", "brings_in", "hazard_story", "parked_only"]
