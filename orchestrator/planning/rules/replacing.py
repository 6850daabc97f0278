"""Replacing things: "swap the bench for a bin", "replace the two cones with barriers". The things
named first go and one of the new kind stands where each of them stood, as one edit. The ego
cannot go, so replacing it is refused with what can be done instead."""

from __future__ import annotations

import math
import re

from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.edits import referenced
from drivetwin.orchestrator.planning.rules.places import Notes
from drivetwin.orchestrator.planning.rules.reading import Reading, read
from drivetwin.tools.appearance import COLOURS
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.scene import Scene

# "replace X with Y", "swap X for Y", "substitute Y for X" is not read (its order is the other way).
# "turn the hydrant into a bench", "change the suv to a truck": the same swap, said as a change of kind.
_REPLACE = re.compile(r"^\s*(?:(?:please|pls|can you|could you|would you|now|then|just)\s+)*"
                      r"(?:(?:replace|swap|exchange)\s+(?P<old>.+?)\s+(?:with|for|by)\s+"
                      r"|(?:turn|change|convert|make)\s+(?P<was>.+?)\s+(?:into|to)\s+(?=an?\s))(?P<new>.+?)\s*[.!?]*\s*$")


def replaces(r: Reading) -> re.Match[str] | None:
    """The old and new parts of a clause that asks to replace things, or None."""
    return swap_said(r.low)


def swap_said(low: str) -> re.Match[str] | None:
    """The same for lower-case words ("replace the bench with a bin"), for the plan check; a change
    of kind names a thing on both sides ("change the time to a sunny afternoon" is no swap)."""
    said = _REPLACE.match(low)
    if said is not None and said["was"] and not (ph.find_categories(said["was"]) and ph.find_categories(said["new"])):
        return None
    return said


def replace_things(said: re.Match[str], scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall]:
    """remove_assets for the things named first, and add_asset of the new kind at each one's spot."""
    old, new = read(said["old"] or said["was"], scene), read(said["new"], scene)
    if not new.mentions:
        raise PlanningError(f"say what should stand in place of {(said['old'] or said['was']).strip()}, e.g. 'replace the bench with a bin'")
    category = new.mentions[0].category
    ids = referenced(old, scene, memory, notes)
    if "ego" in ids:
        raise PlanningError(f"the ego vehicle cannot be replaced or removed; I can move it, restyle it, or add a "
                            f"{category.replace('_', ' ')} beside it")
    if not ids:
        raise PlanningError(f"there is no {re.sub(r'^(?:the|a|an|those|these|that|this) ', '', (said['old'] or said['was']).strip())} "
                            "in the scene to replace")
    colour = next((c for c in COLOURS if new.has((c,))), None)
    calls = [ToolCall(tool="remove_assets", args={"assets": ids})]
    for asset_id in ids:
        asset = scene.asset(asset_id)
        if asset is None:
            continue
        where = {"relation": "absolute", "x": round(asset.pose.x, 2), "y": round(asset.pose.y, 2)}
        calls.append(ToolCall(tool="add_asset", args={"category": category, "count": 1, "location": where,
                                                      **({"colour": colour} if colour else {})}))
    return calls


# Two things trading places: "swap the bench and the bin", "the bench and the bin should switch places",
# "exchange the positions of car 1 and car 2" (not "switch the lights on", "swap lanes", "swap X for Y").
_TRADE = re.compile(r"\b(?:swap|switch|exchange|trade)(?:s|ped|ping|ed|ing)?\b(?!\s+(?:on|off|lanes?|to)\b)")
_TRADE_PLACES = re.compile(r"\b(?:swap|switch|exchange|trade)\w*\s+(?:the\s+)?(?:places|positions|spots|round|around|over)\b")


def trades_places(r: Reading, scene: Scene, memory: Memory, notes: Notes) -> list[ToolCall] | None:
    """Two things named trading places, as one edit: the second is set aside, the first put where
    it stood, then the second where the first stood, each keeping its heading; None when the
    clause says no such thing."""
    said = _TRADE.search(r.low)
    if said is None or " and " not in r.low or re.search(r"\b(?:for|with)\b", r.low[said.end() :]):
        return None
    if not _TRADE_PLACES.search(r.low) and not re.match(r"\s+(?:the\s+)?\S+.*\band\b", r.low[said.end() :]):
        return None
    things = list(r.ids) + (["ego"] if r.ego else [])
    for mention in r.mentions:
        present = [a.id for a in scene.assets if a.category == mention.category and a.id not in things]
        if len(present) != 1:
            raise PlanningError(f"which {mention.category.replace('_', ' ')} should trade places? there are {len(present)}")
        things.append(present[0])
    if len(things) != 2:
        return None
    first, second = (scene.asset(i) for i in things)
    if first is None or second is None:
        return None
    notes.subject = things
    return [
        ToolCall(tool="place_asset", args={"asset": second.id, "location": {"relation": "scene_centre"}}),  # out of the way
        ToolCall(tool="place_asset", args={"asset": first.id, "yaw_deg": round(math.degrees(first.pose.yaw), 1), "location": {
            "relation": "absolute", "x": round(second.pose.x, 2), "y": round(second.pose.y, 2)}}),
        ToolCall(tool="place_asset", args={"asset": second.id, "yaw_deg": round(math.degrees(second.pose.yaw), 1), "location": {
            "relation": "absolute", "x": round(first.pose.x, 2), "y": round(first.pose.y, 2)}}),
    ]


__all__ = ["replace_things", "replaces", "swap_said", "trades_places"]
