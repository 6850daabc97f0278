"""Whether a plan's searches answer the question asked, not a neighbouring one.

The plan-versus-request review (check.py) already holds a question to changing nothing and to
the places and roads it names. This holds it to what it asks about: a question about what is
nearest something must compare distances, one about what blocks or stands on the road must look
at what stands on the lanes, a question about a thing's mass, size or colour must describe that
thing, a question in two parts ("..., and which ...?") must be answered twice, and only a
question after everything there is is answered by a list of everything. Like
request.py it reads the words with its own small structural vocabulary, not the planners'
phrase lists: it must catch the question a planner misread, so it cannot share that reading.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from drivetwin.orchestrator.planning.request import Request
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import builtin_tools
from drivetwin.worlds.catalog import resolve_category
from drivetwin.worlds.scene import EGO_ID, Scene

# The Workers a question may be answered with: anything else is an edit, judged elsewhere.
SEARCH_TOOLS = frozenset(tool.name for tool in builtin_tools() if tool.family == "search")

# A comparison of distances: "which X is nearest/closest to Y", "how far is X from Y".
_NEAREST = re.compile(r"\b(nearest|closest|nearer|closer|most near|how far)\b")
# An obstruction, or things standing on the carriageway.
_OBSTRUCTION = re.compile(r"\b(block\w*|obstruct\w*|in (the|its|our|their|my) way)\b")
_ON_ROAD = re.compile(r"\b(on|in|along|across) the ([a-z]+ )?(lanes?|roads?|streets?)\b")
# The lanes themselves asked for ("which lanes does X have", "list the lanes on X").
_LANES_ASKED = re.compile(r"(^|\b(which|what|list|name|show me|tell me)\s+(the\s+|all\s+)?)lanes?\b")
# A property of a thing (not its position: a list of where things are answers "where").
_PROPERTY = re.compile(r"\b(mass|weigh\w*|how heavy|heavy is|size of|what size|how big|how long is|how tall|"
                       r"how wide|dimensions?|colou?r)\b")
# A second question joined to the first: "..., and which landmark is closest to it".
# What describe_environment answers at once: the weather, the time of day, the lighting.
ENVIRONMENT_PARTS = 3
_SECOND_PART = re.compile(r",?\s+and\s+(which|what|where|how (many|much|heavy|big|far)|is there|are there)\b")
# A question after everything there is ("what's in the scene?", "list all of it", "is there
# anything about?"): only such a question is answered by a search with nothing to narrow it.
_EVERYTHING = re.compile(r"\b(all|every\w*|any\w*|some\w*|things?|stuff|assets?|objects?|items?|list|inventory|scene|world|"
                         r"here|there|around|about)\b")


def unanswered(request: Request, calls: Sequence[ToolCall], scene: Scene) -> list[str]:
    """Each way a question's search calls fail to answer what it asks, in plain words.

    [] for a request that is not a question, or a plan that edits (check.py judges those)."""
    if not request.question or not calls or any(c.tool not in SEARCH_TOOLS for c in calls):
        return []
    low = request.low
    out: list[str] = []
    if _NEAREST.search(low) and not any(_compares_distances(c) for c in calls):
        out.append("you asked what is nearest, but the plan compares no distances")
    if _asks_what_stands_on_road(low) and not any(_looks_on_lanes(c) for c in calls):
        out.append("you asked what is on the road, but the plan does not look at what stands on the lanes")
    out += _describes_another(request, calls, scene)
    if all(c.tool == "find_assets" and not c.args for c in calls) and not _EVERYTHING.search(low) \
            and len({m.category for m in ph.find_categories(low.replace("_", " "))}) < 2:  # "n_street_lights=?, n_trees=?": one list answers both
        # "current scenario time?" read as a list of every asset: what was asked is not in it
        out.append("you asked about something in particular, but the plan lists everything in the scene")
    seconds = [found[0] for found in _SECOND_PART.findall(low)]
    if any(c.tool == "find_assets" for c in calls):  # a list of the things found says how many and where
        which_ones = re.search(r"\band which(?: ones?| of them| are they| they are| is it)?\s*[?.!]*\s*$", low) is not None
        # "how many, and which ones?": the list names them
        seconds = [word for word in seconds if word not in ("where", "how many") and not (word == "which" and which_ones)]
    parts = 1 + len(seconds)
    distinct = list({str(c): c for c in calls}.values())  # the same lookup twice answers once
    answered = sum(ENVIRONMENT_PARTS if c.tool == "describe_environment" else 1 for c in distinct)
    if answered < parts:
        out.append(f"you asked {parts} things, but the plan answers {len(calls)}")
    return out


def _compares_distances(call: ToolCall) -> bool:
    # find_assets near X and find_lanes near X rank by distance too.
    return call.tool == "measure_distance" or "nearest_to" in call.args or "furthest_from" in call.args or (
        call.tool in ("find_assets", "find_lanes") and "near" in call.args)


def _asks_what_stands_on_road(low: str) -> bool:
    return bool(_OBSTRUCTION.search(low)) or (bool(_ON_ROAD.search(low)) and not _LANES_ASKED.search(low.strip()))


def _looks_on_lanes(call: ToolCall) -> bool:
    return call.tool == "find_assets" and bool(call.args.get("on_lane") or call.args.get("lane"))


def _describes_another(request: Request, calls: Sequence[ToolCall], scene: Scene) -> list[str]:
    """A property asked of the things named, answered about something else (or not at all)."""
    if not _PROPERTY.search(request.low):
        return []
    ids = set(ph.find_asset_ids(scene, request.low))
    if re.search(r"\bego\b", request.masked):
        ids.add(EGO_ID)
    categories = set(request.categories) | {a.category for i in ids if (a := scene.asset(i)) is not None}
    if not categories and not ids:
        return []  # nothing named that the check can read: the planner's reading stands
    described = [c for c in calls if c.tool == "asset_properties"]
    if not described:
        return [f"you asked about the {_said(ids, categories)}, but the plan describes nothing"]
    for call in described:
        asset = scene.asset(str(call.args["asset"])) if call.args.get("asset") else None
        category = asset.category if asset is not None else resolve_category(str(call.args.get("category", "")))
        if (asset is not None and asset.id in ids) or category in categories:
            return []
    return [f"you asked about the {_said(ids, categories)}, but the plan describes "
            + ", ".join(str(c.args.get("asset") or c.args.get("category")) for c in described)]


def _said(ids: set[str], categories: set[str]) -> str:
    return ", ".join(sorted(ids) or sorted(c.replace("_", " ") for c in categories))


__all__ = ["SEARCH_TOOLS", "unanswered"]
