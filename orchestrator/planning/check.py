"""The plan-versus-request check: before a plan is applied, does it do what the words say?

A planner can turn "I no longer want the bus" into an added bus, or "remove the parked cars"
into removing a driving one too, with full confidence. The check reads a few general signals
from the request (polarity, the categories and descriptions it names, its numbers, the place
and scope it names, whether it is a question) and compares them with what a dry run of the
plan actually does. A plan that accounts for all of them is applied; otherwise the session
asks one short question offering the readings that do fit (repaired ones built here, and the
planner's alternatives), and when none fits it refuses, saying first what it did not
understand and what it can do.
"""

from __future__ import annotations

import math
import re
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from typing import Any, Literal

from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning.answers import SEARCH_TOOLS, unanswered
from drivetwin.orchestrator.planning.attributes import (
    denied_set,
    group_left_behind,
    layouts_merged,
    look_left_out,
    names_group,
    not_around,
    off_lane,
    off_surface,
    resized,
    some_of_all,
    weather_strength,
    wrong_counts,
    wrong_heading,
    wrong_layout,
    wrong_removals,
    wrong_side,
)
from drivetwin.orchestrator.planning.base import Plan, PlanContext, Question, Reading
from drivetwin.orchestrator.planning.coverage import (
    LAMPS_SWITCHED,
    MIN_MOVE_M,
    Scope,
    absent_but_added,
    all_when_some,
    ambiguous_pick,
    asked_which_but_changed,
    away_from_thing,
    back_reference,
    circumstance_added,
    definite_but_added,
    described_not_destination,
    environment_left_out,
    environment_unasked,
    excepted_ids,
    excepted_touched,
    indefinite_but_moved,
    inside_building,
    landmark_thing_changed,
    lane_way,
    missing_categories,
    named_things,
    numbered_passed_over,
    off_the_road,
    off_the_side,
    partial_removal,
    picked_but_other,
    picked_by_thing,
    place_dropped,
    place_moved,
    possessed_added,
    trouble_added,
    unknown_places,
    unknown_things,
    unnamed_added,
    unnamed_compass_places,
    unpointed,
    wrong_direction,
    wrong_lane_way,
)
from drivetwin.orchestrator.planning.grounding import GroundingUnavailable, embed, nearest_landmark
from drivetwin.orchestrator.planning.intent import (
    ADD_WORDS,
    BARE_STATE,
    FEWER_WORDS,
    HOW_THINGS_GO,
    KEEP_SOME,
    LIVELIER,
    QUIETER,
    REMOVE_WORDS,
    WHICH_KIND,
    asks,
    commands,
    without_contrast,
)
from drivetwin.orchestrator.planning.readings import describe
from drivetwin.orchestrator.planning.request import Request, read_request
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.edits import EVERY_OTHER, FINAL_COUNT, FURTHEST, TOO_CONSPICUOUS, kept_at
from drivetwin.orchestrator.planning.rules.environment import HEAVY_INTENSITY, LIGHT_INTENSITY, said_weaker
from drivetwin.orchestrator.planning.rules.numbers import CAR_LENGTH_M, SPEED_UNIT, YARD_M, numbers_in, spelt_measures
from drivetwin.orchestrator.planning.rules.places import (
    BETWEEN,
    FROM_TO,
    each_place_named,
    point_named,
    says_other_place,
    side_of,
)
from drivetwin.orchestrator.planning.rules.reading import counted_kinds, find_place
from drivetwin.orchestrator.planning.rules.repeat import SAID_AGAIN_AT
from drivetwin.orchestrator.planning.rules.spelling import ASSET_ID
from drivetwin.orchestrator.planning.scenario_review import missed_scenario, read_as_scenario
from drivetwin.orchestrator.transaction import TransactionError, TransactionResult, execute
from drivetwin.tools.appearance import TIME_PRESETS
from drivetwin.tools.base import ToolCall
from drivetwin.tools.errors import ToolError
from drivetwin.tools.locate import resolve_target
from drivetwin.tools.search import most_of
from drivetwin.worlds.catalog import LAYOUT_KIT_TAGS, catalog, placeable_categories, shared_heads
from drivetwin.worlds.scene import WEATHER_KINDS, AssetInstance, Scene
from drivetwin.worlds.surface import lane_at, nearest_on_polyline, point_in_polygon

Action = Literal["apply", "ask", "refuse"]
# Metres from a named place within which an edit counts as "at" it (a parking lot or a building
# front is tens of metres across; the campus's places are 60 m or more apart).
PLACE_RADIUS_M = 30.0
# Within this of a thing a plan puts something by, it stands by that thing.
BY_A_THING_M = 8.0
# A description grounds to a category only when MiniLM is at least this sure and the plan's
# category scores at least this much less (a plain synonym scores 1.0 and is read directly).
DESCRIPTION_SCORE, DESCRIPTION_MARGIN = 0.45, 0.08
# Tolerance when matching a number of the request with one of the plan (rounding, unit maths).
NUMBER_TOLERANCE = 0.02
# Unit conversions a planner may apply to a number, each when its unit is said: km/h and mph to m/s,
# feet, yards, car lengths and centimetres to metres, per cent (ten metres is not "3 m" read as ten feet).
UNIT_FACTORS = {r"km|kph|kilomet": 1 / 3.6, r"mph|mile": 0.44704, r"\bf(?:ee)?t\b|\bfoot\b": 0.3048, r"%|per ?cent|\bcm\b|centimet": 0.01,
                r"\byards?\b|\byds?\b": YARD_M, r"(?:car|vehicle)[- ]lengths?": CAR_LENGTH_M}
QUERY_TOOLS = tuple(sorted(SEARCH_TOOLS))
# Workers that write the storyboard: their readings are the scenario reader's to judge.
SCENARIO_TOOLS = ("add_event", "add_manoeuvre", "set_light_phases")
MAX_READINGS = 3
# The catalog's tags of what a layout may add unnamed: markers, blocks, signs, roadworks.
_LAYOUT_KIT = LAYOUT_KIT_TAGS | {"sign"}
# Sending things off: "get the crowd away from the gate", "move those people away" (never more of them).
_AWAY = re.compile(r"\b(?:get|move|send|shoo|clear|chase)\s+(?:the|those|these|that|them|it|all)\b(?:\s+[\w-]+){0,2}?\s+away\b")
# A place beyond the world's edge: "well off the map", "outside the world", "past the edge of the map".
_OFF_THE_MAP = re.compile(r"\b(?:off|outside|beyond|past)\s+(?:of\s+)?(?:the\s+)?(?:edge\s+of\s+(?:the\s+)?)?(?:map|world)\b")
# Things to be kept away, said as the object of a verb of deterring ("something to keep people off the
# grass", "deter cyclists from the footpath", "to stop cars parking there"): never what the plan adds.
# ("keep the walker waiting" is having one; kept, it must be kept off, out or away.)
# (a verb, not "the bus stop with cones": no article before it, no preposition after)
_KEPT_AWAY = re.compile(r"(?<!\bthe )(?<!\ba )(?<!\bbus )(?<!\bshuttle )\b(?:(?P<keep>keep|keeps|keeping)|stop|stops|stopping|prevent|prevents"
                        r"|preventing|deter|deters|deterring|discourage|discourages|discouraging|ban|bans|banning|bar|bars|barring|warn off"
                        r"|scare (?:off|away))\s+(?:(?:the|any|all|those|these|other)\s+)?(?:(?!(?:with|at|by|in|on|near|for|to|from|and|of)\b)[a-z]+\s+)?$")
# What things named keep doing, a nuisance: "joggers keep cutting through", "cars are always parking there".
_KEEPS_DOING = re.compile(r"\s+(?:(?:are|is)\s+)?(?:always|constantly|forever|continually|keeps?(?: on)?)\s+[a-z]+ing\b")
_KEPT_OFF = re.compile(r"\s+(?:[a-z]+\s+)?(?:off|away|out|from|back|clear)\b")
# Words asking for one more of a thing there: what answers them adds.
_ANOTHER_ONE = re.compile(r"\b(?:a copy|copies|duplicate|clone|another one|one more|a second one)\b")
# Weather this world cannot make, that a plan setting rain or fog would stand in for unasked.
_WEATHER_NOT_HERE = re.compile(r"\b(?:hail\w*|dust ?storms?|sand ?storms?|dust|sand|tornado\w*|twisters?|volcanic ash|ash ?clouds?)\b")
# Weather said to be moved to one place: "nudge that rain cloud over towards the east gate".
_WEATHER_PUT = re.compile(r"\b(?:move|moving|nudge|shift|push|drag|put|place|steer|send|blow)\w*\s+(?:the\s+|that\s+|this\s+|some\s+)?"
                          r"(?:rain ?|storm ?|snow ?)?(?:clouds?|fog ?bank|storm|rain|fog|snow)\s+(?:\w+\s+){0,2}?(?:towards?|to|over|onto|into|above)\s+"
                          r"(?!(?:the\s+)?(?:scene|campus|world|map|whole|everything|everywhere|us|here|all)\b)")
# A question about the scene's settings ("time + weather?", "what's the weather doing"): the
# environment is what it must look up.
_SETTING_ASKED = re.compile(r"\b(?:weather|what time|the time|time of day|lighting|exposure)\b")
# The units a length on the campus is said in (a distance in km is read as a speed's unit elsewhere).
_LENGTH_UNITS = r"m|metres?|meters?|ft|feet|foot|yards?"
# A distance said ("20 m north of the library", "ten feet behind it"): only then may a thing the
# plan puts by a named place stand further than PLACE_RADIUS_M from it.
_DISTANCE_SAID = re.compile(rf"\d\s*(?:{_LENGTH_UNITS}|km)\b")
# Tools that act on a list of assets as well as on one.
_GROUP_TOOLS = ("move_asset", "remove_assets", "set_asset_appearance")

# Command verbs and fillers dropped before grounding a description on its nouns.
_VERB = re.compile(r"\b(please|i'?d like|i want|we need|add|put|place|create|spawn|remove|delete|get rid of|"
                   r"there should be|could you|can you|a|an|the|some|one|two|three)\b")


@dataclass
class Verdict:
    """What to do with a plan: apply it, ask which reading was meant, or refuse (and why)."""

    action: Action
    problems: list[str] = field(default_factory=list)
    question: Question | None = None
    message: str | None = None
    # The dry run of the plan's own calls on the scene it was reviewed against: the session
    # commits it as it is instead of running the same transaction a second time.
    outcome: TransactionResult | None = None
    # The calls to apply instead of the plan's, when all that was wrong with it is something the
    # request said it did not mean ("..., except the ones on the south side") and the check found
    # which things those are: the plan without them (`outcome` is their dry run).
    calls: list[ToolCall] | None = None


# A thing said to be on its way somewhere: "a bus going east", "a truck heading north".
_HEADING = re.compile(r"\b(?:going|heading|cruising)(?= (?:to |towards? )?(?:the )?(?:north|south|east|west))")
# A distance asked between two things named: "how far is the library from the gate".
_HOW_FAR_FROM = re.compile(r"\bhow far (?:away )?(?:is|are|'s)\s+(?P<a>[^?.,;]+?)\s+from\s+(?P<b>[^?.,;]+)")
# Going on foot, said of a thing: only what moves by itself can ("make the bin stroll off").
_WALK_VERB = re.compile(r"\b(?:walk|walks|walking|walked|stroll\w*|wander\w*|march\w*|jog\w*|hop(?:s|ped|ping)?|waddl\w*)\b")
# Words that ask a thing to drive or ride.
_DRIVE_VERB = re.compile(r"\b(?:drive|drives|driving|drove|ride|rides|riding|rode)\b(?! (?:lane|way|through))")


@dataclass(frozen=True)
class Effect:
    """What a plan does, from a dry run: assets added, removed and changed, and its numbers."""

    calls: tuple[ToolCall, ...]
    added: tuple[AssetInstance, ...]
    removed: tuple[AssetInstance, ...]
    changed: tuple[AssetInstance, ...]
    environment: bool
    outcome: TransactionResult | None = None

    @property
    def edits(self) -> bool:
        return bool(self.added or self.removed or self.changed or self.environment)


def dry_run(plan_calls: list[ToolCall], context: PlanContext) -> Effect | None:
    """What the calls would do to the scene, or None when a dry run refuses them."""
    try:
        outcome = execute(context.registry, context.scene, plan_calls)
    except TransactionError:
        return None
    ops = outcome.edit.ops
    return Effect(
        calls=tuple(plan_calls),
        added=tuple(op.asset for op in ops if op.op == "add"),
        removed=tuple(op.before for op in ops if op.op == "remove"),
        changed=tuple(op.after for op in ops if op.op == "update" and op.after != op.before),
        environment=any(op.op in ("environment", "storyboard") for op in ops),
        outcome=outcome,
    )




# Workers that set one thing outright (the time of day, an asset's behaviour or one of its looks): a
# second call setting the same thing to something else undoes the first. (Not the weather nor a place:
# "I can hardly see for the fog ... take the fog away" and "someone left their car across my drop-off,
# shove it over to lot A" are read as the story's state, then the wish, and the last one is meant.)
_SETTERS = ("set_time_of_day", "set_behaviour", "set_asset_appearance")


def overridden(calls: tuple[ToolCall, ...] | list[ToolCall]) -> list[tuple[int, int]]:
    """Pairs (i, j) of calls where call j sets again what call i set, to something else, so that
    the request's first value is lost ("half four ... that time of the morning" read as 04:30 and
    then "morning")."""
    def what(call: ToolCall) -> tuple[str, ...] | None:
        if call.tool not in _SETTERS:
            return None
        if call.tool == "set_time_of_day":
            return (call.tool,)
        asset = call.args.get("asset")
        if not isinstance(asset, str):
            return None
        looks = tuple(sorted(k for k in call.args if k not in ("asset", "assets")))
        return (call.tool, asset, *looks) if call.tool == "set_asset_appearance" else (call.tool, asset)

    out = []
    for j, later in enumerate(calls):
        key = what(later)
        if key is None:
            continue
        for i in range(j):
            if what(calls[i]) != key or calls[i].args == later.args:
                continue
            if later.tool == "set_time_of_day" and _hours_apart(calls[i], later) <= SAME_TIME_H:
                continue  # "a bit earlier ... dusk rather than dark": 19:00, then dusk, is one wish said twice
            out.append((i, j))
    return out


# Two times of day this close are one time said twice, not two wishes.
SAME_TIME_H = 2.0


def _hours_apart(a: ToolCall, b: ToolCall) -> float:
    """Hours between the times two set_time_of_day calls set, round the clock (24 when unreadable)."""
    def hours(call: ToolCall) -> float | None:
        said = str(call.args.get("time", "")).lower()
        clock = re.fullmatch(r"(\d{1,2}):(\d{2})", TIME_PRESETS.get(said, said))
        return int(clock.group(1)) + int(clock.group(2)) / 60 if clock else None

    x, y = hours(a), hours(b)
    return 24.0 if x is None or y is None else min(abs(x - y), 24 - abs(x - y))


# A way closed or blocked off ("close the ego's lane", "its lane is closed off", "block the entrance").
_MOVING = re.compile(r"\b(?:move|put|place|park|shift|drag|bring|drive|push|pull|relocate|position|stand|roll|reverse)\b")
_CLOSING = re.compile(r"\b(?:clos(?:e|es|ed|ing)|block(?:s|ed|ing)?|shut|seal(?:s|ed)?|cordon(?:s|ed)?)\b(?:\s+off)?(?!\s+(?:to|by)\b)")


def problems_of(request: Request, effect: Effect, context: PlanContext) -> list[str]:
    """Each way the plan's effect fails to account for the request, in plain words."""
    out: list[str] = []
    scene = context.scene
    for i, j in overridden(effect.calls):
        out.append(f"the plan sets the same thing twice ({describe([effect.calls[i]])}, then {describe([effect.calls[j]])}), "
                   "so the first is lost")
    if request.question and effect.edits:
        out.append("you asked a question, but the plan would change the scene")
    looks_up_places = any(c.tool in ("find_landmarks", "measure_distance") or "nearest_to" in c.args or "furthest_from" in c.args
                          for c in effect.calls)
    if request.question and request.about_places and not effect.edits and not looks_up_places:
        out.append("you asked about places, but the plan looks up something else")
    if not request.question and effect.calls and not effect.edits:
        # "rotate the stop sign to face east" when it does: say what was read, which the scene already has
        done = "only looks things up" if all(c.tool in QUERY_TOOLS for c in effect.calls) else "changes nothing: the scene is already that way"
        out.append(f"you asked for a change, but the plan ({describe(list(effect.calls))}) {done}")
    beside_itself = [c.args["asset"] for c in effect.calls if c.tool == "place_asset" and isinstance(c.args.get("location"), dict)
                     and c.args["location"].get("target") == c.args.get("asset") and c.args["location"].get("relation") in ("at", "next_to")
                     and "distance" not in c.args["location"]]  # "the nearest sidewalk", "2 m in front of where it is" say a place
    if beside_itself:  # "could it potter about a bit?" read as a place beside where it stands: a move that says nothing
        out.append(f"the plan puts {', '.join(beside_itself)} next to itself, which is no place you named")
    if not request.question and not effect.calls and (request.categories or request.place or request.polarity or commands(request.low)):
        out.append("you asked for a change, but the plan does nothing")  # "block off lot B's entrance" read as no call at all
    if request.question and not effect.edits:
        said = " ".join(str(c.args) for c in effect.calls).lower().replace("_", " ")
        out += [f"you asked about {name}, but the plan looks up something else"
                for name in _topics(request, scene) if not _looked_up(name, said, effect.calls, scene)]
        unlooked = _kind_not_looked_up(request, effect.calls, scene)
        if unlooked is not None:  # "the sign with eight sides: in which street is it?" answered about the lanes' traffic
            out.append(f"you asked about the {unlooked}, but the plan looks up something else")
        if _WHAT_LIES_BETWEEN.search(request.low) and not any(c.tool == "measure_distance" for c in effect.calls):
            out.append("you asked what lies between two places, which no search can tell; I can list what is near one place "
                       "or measure the distance between them")  # "what's between the library and the fountain?"
        side = side_of(request.low, scene)
        searches = [c for c in effect.calls if c.tool == "find_assets"]
        if side is not None and searches and not any({"lane", "near", "nearest_to", "furthest_from", "side"} & set(c.args) for c in searches):
            out.append(f"you asked about the {side[0]}, but the plan searches the whole scene")  # "how many cars are on the north side?"
    if request.question and _SETTING_ASKED.search(request.low) and not any(
            c.tool in ("describe_environment", "set_weather", "set_time_of_day") for c in effect.calls):
        out.append("you asked about the weather, the time or the lighting, but the plan looks up something else")
    from_ego = any(c.tool == "measure_distance" and "ego" in (c.args.get("a"), c.args.get("b")) for c in effect.calls)
    two_ends = re.search(r"\b(?:from|between|and)\b", request.masked)  # "how far is X from Y": neither is the asker
    # "I'll walk from the stop to the fountain", "how far is the library from the gate? we ..."
    named_ends = FROM_TO.search(request.masked) or BETWEEN.search(request.masked) or _HOW_FAR_FROM.search(request.masked)
    ends_not_ego = named_ends is not None and not any(re.search(r"\b(?:ego|here|i|me|my|we|us|our)\b", end)
                                                     for end in named_ends.groupdict().values())
    if from_ego and two_ends and (ends_not_ego or not re.search(r"\b(?:ego|here|i|me|my|we|us|our)\b", request.masked)):
        out.append("the plan measures from the ego, which your words do not name")  # "how far is the hosptial from the gate"
    out += unanswered(request, effect.calls, scene)  # the question asked, not a neighbouring one
    if any(c.tool == "set_weather" for c in effect.calls):
        # "make a hail storm" is no rain (as typed too: a slip repair may have made it "rainstorm")
        if (unmade := _WEATHER_NOT_HERE.search(request.low) or _WEATHER_NOT_HERE.search(request.text.lower())) is not None:
            out.append(f"this world has no {unmade.group(0)}; its weather is {', '.join(WEATHER_KINDS)}")
        if _WEATHER_PUT.search(request.low):  # "nudge that rain cloud towards the east gate"
            out.append("the weather covers the whole scene; it cannot be moved to one place")
    if any(c.tool in SCENARIO_TOOLS for c in effect.calls):
        out += _lane_change_left_out(request.low, list(effect.calls))
    if (both := _added_then_removed(effect)):  # nothing comes of it
        out.append("the plan adds " + _names(both) + " and takes it away again")
    if _MOVE_ONLY.search(request.low) and effect.added and not effect.changed and not effect.removed and not ADD_WORDS.search(request.low):
        out.append("you asked to move something, but the plan only adds " + _names(effect.added))  # "reposition that traffic"
    # A request that only takes away never adds, and one that only adds never removes; with
    # words of both ("swap", "replace", "instead"), each half is judged by what it names.
    says_add = bool(ADD_WORDS.search(request.low))
    # what a layout adds unasked is its own business, never a thing the request wants gone
    added = [a for a in effect.added if a.category not in _companions(effect) or a.category in request.categories]
    if request.polarity == "remove" and added and (not effect.removed or not says_add):
        out.append("you asked to take something away, but the plan adds " + _names(added))
    elif request.polarity == "remove" and not effect.removed and not added and _moved(effect):
        out.append("you asked to take something away, but the plan only moves " + _names(_moved(effect)))
    elif request.polarity == "remove" and not effect.removed and not added and _REMOVE_VERB.search(request.low) and effect.changed:
        out.append("you asked to remove something, but the plan removes nothing and changes " + _names(effect.changed))
    if _SMALL_MOVE.search(request.low) and request.place is None and not request.numbers:
        shifted = {a.id: metres for a in _moved(effect) if (metres := _far_moved(a, effect)) > SMALL_MOVE_M}
        if shifted:
            out.append(f"you asked for a small move, but the plan moves {', '.join(shifted)} {max(shifted.values()):.0f} m")
    if request.polarity == "remove" and not effect.removed and any(
            c.tool == "set_lighting" and c.args.get("street_lights") == "on" for c in effect.calls):
        out.append("you asked for less, but the plan switches the street lights on")  # "fewer lights over there"
    if _CLOSING.search(request.low) and not _MOVING.search(request.low) and _moved(effect) and not effect.added and not effect.removed:
        # "close the ego's lane 30 m ahead of it" read as a move of the ego: closing takes things put across the way
        out.append("you asked to close or block something off, but the plan only moves " + _names(_moved(effect)))
    one_lamp = sorted(set(re.findall(r"\bstreet_light_\d+\b", request.low)))
    if one_lamp and len(one_lamp) < scene.count("street_light") and any(
            c.tool == "set_lighting" and c.args.get("street_lights") in ("on", "off") for c in effect.calls):
        # "turn off street light 1": the lamps are switched all together, never one of them alone
        out.append(f"the street lights are switched all together, not one by one, but you named {', '.join(one_lamp)}; "
                   "say 'turn the street lights off' (or on) for all of them")
    going = HOW_THINGS_GO.match(request.low.strip())
    said_of = {m.category for m in ph.find_categories(going.group(0))} if going is not None else set()
    if going is not None and any(a.category in said_of for a in effect.added):
        # "kids can't see the cars": how it is for them, never more of them
        out.append("you said how things are for " + ", ".join(sorted(said_of)) + ", but the plan adds more of them")
    said = ph.normalise(request.text.lower())  # "..., to keep people off the grass" is a reason the request drops
    kept_away = {m.category for m in ph.find_categories(request.text.lower()) if (verb := _KEPT_AWAY.search(said[max(0, m.start - 30) : m.start]))
                 and (not verb.group("keep") or _KEPT_OFF.match(said, m.end))}
    if (more := [a for a in effect.added if a.category in kept_away]) and not request.question:
        out.append("you asked to keep " + ", ".join(sorted(c.replace("_", " ") for c in kept_away)) + " away, but the plan adds " + _names(more))
    # "joggers keep cutting through lot A, fence it off": who keeps doing it is the trouble, never what to add
    doers = {m.category for m in ph.find_categories(request.text.lower()) if _KEEPS_DOING.match(said, m.end)
             and not ADD_WORDS.search(said[max(0, m.start - 20) : m.start])}
    if (more := [a for a in effect.added if a.category in doers]) and not request.question:
        out.append("you named " + ", ".join(sorted(c.replace("_", " ") for c in doers)) + " as the trouble (they keep at it), but the plan adds "
                   + _names(more))
    if _OFF_THE_MAP.search(request.low) and _moved(effect) and not request.question:  # "somewhere well off the map"
        out.append("you asked for a place off the map, but the world ends at its edge; the plan moves " + _names(_moved(effect)))
    if _AWAY.search(request.low) and effect.added and not request.question:  # "get the crowd away from the gate"
        out.append("you asked for things to go away, but the plan adds " + _names(effect.added))
    if LIVELIER.search(request.low) and effect.removed and not request.question:  # "liven them up"
        out.append("you asked for more life, but the plan takes away " + _names(effect.removed))
    if QUIETER.search(request.low) and (effect.added or (effect.changed and not effect.removed)) and not request.question:
        out.append("you asked for less going on, but the plan " + ("adds " + _names(effect.added) if effect.added else "only moves things"))
    if BARE_STATE.search(request.low) and effect.removed and not request.question:
        # "the bus stop feels empty": what is missing is wanted, never the rest taken away
        out.append("you said it is empty, but the plan takes away " + _names(effect.removed))
    if _ANOTHER_ONE.search(request.low) and not effect.added and _moved(effect) and not request.question:
        out.append("you asked for another one, but the plan only moves " + _names(_moved(effect)))  # "a copy of that one by the gate"
    if ((_LOOKS_MORE_OR_LESS.search(request.low) or TOO_CONSPICUOUS.search(request.low)) and (effect.removed or effect.added) and not request.question
            and not LIVELIER.search(request.low) and not QUIETER.search(request.low)  # "look less crowded" is fewer
            and not _TOO_MANY.search(request.low)  # "too many cones, they're too visible"
            and not _look_made_with(request.low, effect)):  # "look tidier with some greenery": the greenery is the means
        # "make the SUV look a bit less aggressive": how it looks, not how many there are
        out.append("you asked how something looks, but the plan " + ("removes " + _names(effect.removed) if effect.removed else "adds " + _names(effect.added)))
    cleared = request.place is not None and _CLEARS.search(request.low) is not None \
        and all(_near(scene, a, request.place) for a in effect.removed)  # "empty lot B and put two buses there"
    if request.polarity == "add" and effect.removed and (not effect.added or not (REMOVE_WORDS.search(request.low) or cleared)):
        out.append("you asked for more, but the plan removes " + _names(effect.removed))
    touched = [*effect.added, *effect.removed, *(a for a in effect.changed if a.id != "ego")]
    if request.categories and touched:
        grouped = {c for members in md.groups_said(request.low).values() for c in members}  # "the vehicles"
        grouped |= counted_kinds(request.low)  # "the second car from the left": SUVs are cars too
        grouped |= {k for head, kinds in shared_heads().items() if re.search(rf"\b{head}s?\b", request.low) for k in kinds}  # "a sign"
        grouped |= {a.category for a in context.scene.all_assets() if re.search(rf"\b{a.id}\b", request.low)}  # by id
        grouped |= _concepts_said(request.low)  # "a chair next to the SUV": somewhere to sit
        strays = {a.category for a in touched} - request.categories - grouped - _companions(effect)
        if cleared:  # "clear lot B and put 2 buses there": what stood there
            strays -= {a.category for a in effect.removed} - {a.category for a in effect.added}
        if strays:
            out.append(f"you named {', '.join(sorted(request.categories))}, but the plan touches {', '.join(sorted(strays))}")
    if not request.categories and effect.added and not _companions(effect):
        # What a new thing should be is described; what to clear away is often only implied.
        plan_categories = {a.category for a in effect.added}
        try:  # "the bus stop" describes no bus; "traffic" is the word for cars the plan adds
            meant = None if _concepts_said(request.low) & plan_categories else described_category(request.masked, plan_categories)
        except GroundingUnavailable:
            meant = None  # without MiniLM a description cannot be judged; the other signals remain
        if meant is not None:
            out.append(f"your words describe a {meant.replace('_', ' ')}, but the plan uses "
                       + ", ".join(sorted(plan_categories)))
    totals = set(_totals(request, effect).values())  # "there should be exactly four cones": how many are left
    factors = [1.0, *(f for unit, f in UNIT_FACTORS.items() if re.search(unit, request.low))]
    used = _numbers_used(effect, scene, request.place, ego=" ego " in request.masked) if request.numbers else []
    missing = [n for n in request.numbers if not _accounts_for(n, used, factors) and n not in totals]
    if missing and effect.calls:
        out.append("the plan leaves out " + ", ".join(f"{n:g}" for n in missing))
    if request.place is not None and effect.edits and not effect.environment:
        last = {a.id: a for a in [*effect.added, *effect.changed]}  # where each ends up, after every call
        beyond = side_of(request.low, scene) if _COMPASS_OF.search(request.low) else None
        replaced = {a.category for a in effect.added if _near(scene, a, request.place)}  # "remove the bench and put a new one in lot A"
        far = [a for a in [*last.values(), *(a for a in effect.removed if a.category not in replaced)] if a.id != "ego"
               and not _near(scene, a, request.place)
               and not (_DISTANCE_SAID.search(spelt_measures(request.low)) and _names_target(effect, request.place))
               and not _at_a_target(scene, effect, a, request.categories)  # a compound's other place, lane or thing
               and not _brought_closer(scene, a, request.place)  # "3 m towards the fountain"
               and not FURTHEST.search(request.low)  # "the tree furthest from the library"
               and not _NEAREST_OF.search(request.low)  # "the lamp post nearest the fountain", however far that is
               and not _heads_to(scene, a, request.place)  # "make him walk to the library"
               and not (beyond is not None and beyond[1](a))  # "the lamps east of the crossroads": that side of it
               and not FROM_TO.search(request.low)  # "cones from the ego to the crossroads": between the two
               and not (_FACE_SAID.search(request.low) and _turned_to_face(scene, a, request.place))  # "turn the bench to face the fountain"
               and not ((says_other_place(request.low, scene) or _MOVED_AWAY.search(request.low))
                        and _near(scene, scene.asset(a.id) or a, request.place))]  # "... in the wrong car park"
        if far:
            out.append(f"you named {request.place}, but the plan acts on {_names(far)} away from it")
    out += _coverage(request, effect, scene, context.memory)
    out += _attributes(request, effect, scene)
    out += wrong_direction(request.masked, scene, _moved(effect))
    out += wrong_lane_way(request.masked, scene, [*effect.added, *effect.changed])
    out += _wrong_way_to(request, scene, _moved(effect))
    out += _not_the_extreme(request, effect, scene)
    out += _not_the_biggest(request, effect, scene)
    out += _moved_to_turn(request, effect)
    if _TOO_FAST.search(request.low):  # "cars are going way too fast here": slower, never parked ones set going
        started = [a for a in effect.changed if (was := scene.asset(a.id)) is not None
                   and was.behaviour.kind == "parked" and a.behaviour.kind != "parked"]
        out += [f"you said things go too fast, but the plan sets {_names(started)} going"] if started else []
    if _BY_ITSELF.search(request.low):  # "make the bin reverse out of the way by itself": a prop has no motor
        out += [f"a {a.category.replace('_', ' ')} cannot move by itself; I can move it where you say"
                for a in _moved(effect)[:1] if catalog()[a.category].motion == "prop"]
    if (other := _outermost(request, effect, scene)) is not None:
        out.append(f"you picked one by where it stands, which is {other[1].id}, but the plan acts on {other[0].id}")
    out += _not_between(request, scene, [*effect.added, *_moved(effect)])
    out += _amount_words_left_out(request, effect, scene)
    out += _already_there(effect, scene)
    out += described_not_destination(request.low, effect.calls, scene)
    if request.state is not None and (effect.removed or effect.changed):
        before = [scene.asset(a.id) or a for a in effect.changed]  # as it was: "the parked SUV to pull out"
        wrong = [a for a in [*effect.removed, *before] if a.id != "ego"
                 and (a.behaviour.kind == "parked") != (request.state == "parked") and a.category in request.categories]
        if wrong:
            out.append(f"you said {request.state} ones, but the plan also takes {_names(wrong)}")
    if (request.state == "moving" or _HEADING.search(request.low)) and not request.question:
        # "going north" of a row of trees is the way the row runs: only what moves is said to be going
        movers = {c for c in request.categories
                  if request.state == "moving" or (c in catalog() and catalog()[c].motion != "prop")}
        standing = [a for a in effect.added if a.category in movers and a.behaviour.kind == "parked"]
        if standing and len(standing) == len([a for a in effect.added if a.category in request.categories]):
            out.append(f"you said moving ones, but the plan adds {_names(standing)} standing still")
    on_foot = _ON_FOOT.search(request.low)
    if on_foot and not request.question:  # "a pedestrian walking toward the gate" is not one standing there
        walkers = [a for a in effect.added if catalog()[a.category].motion == "walker"]
        if walkers and all(a.behaviour.kind == "parked" for a in walkers):
            out.append(f"you said {on_foot.group(1)}, but the plan adds {_names(walkers)} standing still")
    roads = "|".join(re.escape(ph.normalise(lane.road).strip()) for lane in scene.roads.lanes if lane.road)
    unnamed = re.sub(rf"\b(?:{roads})\b", " ", request.low) if roads else request.low  # "Campus Drive" asks no one to drive
    if _DRIVE_VERB.search(unnamed) and not request.question:
        # "make the bench drive": what cannot drive is not moved into a lane instead
        touched = [a for a in [*effect.added, *effect.changed] if a.id != "ego"]
        still = [a for a in touched if a.category in catalog() and not catalog()[a.category].drives]
        drivers = [c for c in request.categories if c in catalog() and catalog()[c].drives]  # "stop cars driving in"
        if still and len(still) == len(touched) and not drivers:
            out.append(f"you asked for driving, but {_names(still)} cannot drive; vehicles, robots and riders can")
    if _WALK_VERB.search(unnamed) and not request.question:  # "make the tree walk over to the fountain"
        touched = [a for a in [*effect.added, *effect.changed] if a.id != "ego"]
        props = [a for a in touched if a.category in catalog() and catalog()[a.category].motion == "prop"]
        if props and len(props) == len(touched):
            out.append(f"you asked for walking, but {_names(props)} cannot move by itself; people, riders and vehicles can")
    return out


def _coverage(request: Request, effect: Effect, scene: Scene, memory: Memory) -> list[str]:
    """What the plan leaves out of the request (see coverage.py): named things, existing ones
    added anew, weather and times, all of a plural, places the world does not know."""
    scope = _scope(effect)
    named = named_things(request.masked, request.categories, scene)
    single = not re.search(r",|;| and | also ", request.low)
    if request.question and single and any(c.tool in ("find_lanes", "find_landmarks") for c in effect.calls):
        named = set()  # "which lane would a car use": the lanes are the topic, the car its setting
    named -= _setting_kinds(request, effect.calls, scene) if request.question else set()
    counted = counted_kinds(request.low)  # "the second car from the left" may be any kind called a car
    out = [f"you named {c.replace('_', ' ')}, but the plan does nothing with it"
           for c in missing_categories(named, scope, scene)
           if not (c in counted and any(a.category in counted for a in scope.touched))]
    out += [f"you referred to the {c.replace('_', ' ')} already there, but the plan adds another"
            for c in definite_but_added(request.masked, scope, scene)]
    out += trouble_added(request.masked, scope, scene)
    out += [f"you asked which {c.replace('_', ' ')}, but the plan changes the scene" for c in asked_which_but_changed(request.masked, scope)]
    if not request.question:
        out += environment_left_out(request.low, effect.calls)
    out += environment_unasked(request.low, request.masked, effect.calls)
    # a number, a place, a lane, a state, "fewer" or a side limits how many go
    limited = bool(request.numbers or request.place or request.lane or request.state or FEWER_WORDS.search(request.low)
                   or md.outer_direction(request.low) or request.excepted  # "the westernmost lamp", "not the ego"
                   or EVERY_OTHER.search(request.low)  # "every second street light"
                   or side_of(request.low, scene) is not None)  # "the lamps west of Campus Drive"
    out += partial_removal(request.masked, scope, scene, limited)
    out += all_when_some(request.masked, scope, scene)
    out += [f"you asked for a new {c.replace('_', ' ')}, but the plan moves one that is there"
            for c in indefinite_but_moved(request.masked, scope, scene)]
    if effect.added or effect.changed:
        out += inside_building(request.low, scene)
    out += away_from_thing(request.masked, scope, scene)
    out += landmark_thing_changed(request.masked, scope)
    out += off_the_side(request.low, scope, scene)
    out += back_reference(request.masked, request.categories, scope, memory, scene, bool(request.numbers))
    if request.place is None and request.lane is None and (strays := unpointed(request.masked, scope, scene)):
        out.append(f"the plan changes {_names(strays)}, which your words do not point at")
    if unasked := unnamed_added(request.masked, scope):
        out.append(f"the plan adds {_names(unasked)}, which your words do not name")
    kit = _companions(effect)
    out += [f"you spoke of {c.replace('_', ' ')} only as the setting, but the plan adds some"
            for c in circumstance_added(request.masked, scope, scene) if c not in kit]
    out += [f"you spoke of your {c.replace('_', ' ')}, but the plan adds one; say 'add' if you want one"
            for c in possessed_added(request.masked, scope)]
    out += unknown_places(request.masked, effect.calls, scene)
    out += place_moved(request.low, scope, scene)
    out += unnamed_compass_places(request.low, scene)
    out += place_dropped(request.low, effect.calls)
    out += unknown_things(request.masked, effect.calls, scene, answered=request.question and bool(scope.calls)
                          and all(c.tool in QUERY_TOOLS for c in scope.calls))
    out += picked_but_other(request.masked, scope, scene)
    out += numbered_passed_over(request.masked, scope, scene)
    if request.place is None and not request.question:
        out += off_the_road(request.low, scope, scene)
    out += excepted_touched(request.excepted, _kinds_named(request), scope, scene, without_contrast(request.low), memory.last_added())
    return out


# A place said as the side of it things are on: "east of the crossroads".
_COMPASS_OF = re.compile(r"\b(?:north|south|east|west)(?:ern)?\s+of\b")
# On foot or pedal, said of what is added: "a jogger running along Main Street" (not "stop walking").
_ON_FOOT = re.compile(r"(?<!not )(?<!n't )(?<!never )(?<!stop )(?<!no )\b(walking|jogging|running|strolling|wandering|jaywalking|jaywalks"
                      r"|pacing|cycling|pedalling|pedaling|(?:walks|strolls|jogs|wanders|hurries|runs|heads|rides)(?= (?:to|towards?|across|along|over|for|from|into|up|down)\b))\b")


def _attributes(request: Request, effect: Effect, scene: Scene) -> list[str]:
    """What the plan gives the things named (see attributes.py): counts, lane, surface, look,
    weather strength."""
    placed = [*effect.added, *_moved(effect)]
    each = each_place_named(scene, request.low)  # "two cones at each gate": two at every one of them
    # "six bollards on each side of it": that many on either side, two sides
    per = max(1, len(each)) * (2 if md.EACH_SIDE.search(request.low) else 1)
    per *= 1 + len(re.findall(SAID_AGAIN_AT, request.low))  # "two cones by the library and the same by the stop"
    out = [] if _totals(request, effect) else wrong_counts(
        request.masked, [a for a in effect.added if a.category not in _companions(effect)], per)
    if request.polarity == "remove" and not effect.added and not request.excepted and not KEEP_SOME.search(request.low):
        out += wrong_removals(request.masked, effect.removed)  # "one of the traffic lights": one, not both
    centres = {place: centre for place in each if (centre := _centre(scene, place)) is not None}
    if effect.added and centres:  # each new thing counts for the one of those places it stands nearest
        served = {min(centres, key=lambda p: math.dist((a.pose.x, a.pose.y), centres[p])) for a in effect.added}
        out += [f"you said every one of {', '.join(each)}, but the plan puts nothing at {place}"
                for place in centres if place not in served]
    out += wrong_layout(request.masked, effect.added)
    out += layouts_merged(request.masked, effect.calls)
    out += _layout_of_one(request.masked, effect.calls) + _layout_of_the_place(request, effect.calls, scene)
    out += _off_the_road_named(request, effect, scene) + _light_painted(request, effect.calls, scene)
    # around what the layout names ("around the tree just north of lot A"), else the place named
    ringed = [str(c.args["location"]["target"]) for c in effect.calls if c.tool == "arrange_assets"
              and isinstance(c.args.get("location"), dict) and c.args["location"].get("target")]
    around = ringed[0] if ringed else request.place
    if around is not None and effect.added:
        out += not_around(request.low, _centre(scene, around), effect.added)
    out += wrong_heading(request.low, placed)
    out += wrong_side(request.low, scene, effect.added)
    if not effect.removed and not effect.added and not request.excepted:  # "all but the SUV" is not all
        out += some_of_all(request.masked, [a for a in effect.changed if a.id != "ego"], scene, request.place, PLACE_RADIUS_M)
    if request.lane is not None and placed and not request.question:  # a work zone's sign stands beside the lane it closes
        out += off_lane(request.lane, scene, [a for a in placed if a.category not in _companions(effect) or a.category in request.categories])
    out += off_surface(request.low, scene, placed)
    if not request.question or effect.edits:  # "could the library be painted red?" asks for an edit
        out += look_left_out(request.low, effect.calls)
    if request.place is not None and effect.removed and names_group(request.low) and not KEEP_SOME.search(request.low) \
            and not (request.numbers and len(effect.removed) in request.numbers):  # "two cars in lot B": two of them
        near = _nearness(scene, request.place)
        spared = excepted_ids(request.excepted, _kinds_named(request), scene, without_contrast(request.low))  # "..., but keep the SUV"
        out += group_left_behind(request.low, effect.removed,
                                 [a for a in scene.all_assets() if near(a) and a.id not in spared])
    if request.polarity == "remove":  # "I don't want any rain any more" never makes it rain
        now = scene.environment.weather
        unwanted = [str(c.args.get("kind")) for c in effect.calls if c.tool == "set_weather"
                    and c.args.get("kind") not in (None, "clear")
                    # "remove the hydrant and make it rain": the removing is the other clause's
                    and REMOVE_WORDS.search(_clause_saying(request.low, str(c.args.get("kind"))))
                    # "less foggy, please": the same weather, lighter, is what was asked
                    and not (c.args.get("kind") == now.kind and float(c.args.get("intensity", 1.0)) < now.intensity
                             and said_weaker(request.low))]
        out += [f"you said no {kind}, but the plan sets {kind}" for kind in unwanted]
    return out + weather_strength(request.low, effect.calls) + denied_set(request.low, effect.calls) + resized(request.low)


def described_category(text: str, plan_categories: set[str]) -> str | None:
    """The category a description names ("something people throw rubbish into" is a trash bin),
    when MiniLM, comparing the words with each category's catalog description, is clearly
    surer of it than of every category the plan uses; else None."""
    names, vectors = _category_descriptions()
    query = embed([_VERB.sub(" ", ph.normalise(text))])[0]
    scores = dict(zip(names, (float(v) for v in vectors @ query), strict=True))
    best = max(scores, key=lambda n: scores[n])
    if best in plan_categories or scores[best] < DESCRIPTION_SCORE:
        return None
    if all(scores.get(c, 0.0) <= scores[best] - DESCRIPTION_MARGIN for c in plan_categories):
        return best
    return None


def _concepts_said(low: str) -> set[str]:
    """The categories the request names by a word for what they are to people ("traffic", "litter")."""
    said = set()
    for word, category in sorted(((w, c) for c, ws in lx.CONCEPTS.items() for w in ws), key=lambda p: -len(p[0])):
        low, found = re.subn(rf"\b{re.escape(word)}\b", " ", low)  # "foot traffic" is people, not cars
        said |= {category} if found else set()
    return said


@cache
def _category_descriptions() -> tuple[tuple[str, ...], Any]:
    names = tuple(placeable_categories())
    texts = [f"{n.replace('_', ' ')}: {catalog()[n].description}" for n in names]
    return names, embed(texts)


# Where one clause of a request ends and the next begins.
_CLAUSE_BREAK = re.compile(r"[,;.!?]|\b(?:and|then|but|also)\b")


def _clause_saying(low: str, word: str) -> str:
    """The clause of the request that says `word` (from its start): '' when none does."""
    said = re.search(rf"\b{re.escape(word)}", low)
    if said is None:
        return ""
    start = max((m.end() for m in _CLAUSE_BREAK.finditer(low, 0, said.start())), default=0)
    end = next((m.start() for m in _CLAUSE_BREAK.finditer(low, said.end())), len(low))
    return low[start:end]


def _companions(effect: Effect) -> set[str]:
    # Arrangements add what a layout needs (a work zone's cones, barriers, posts and signs); the
    # check only weighs what was asked for by name. A bench in a line of cones is no such kit.
    if not any(c.tool == "arrange_assets" for c in effect.calls):
        return set()
    return {a.category for a in effect.added if a.category in catalog() and set(catalog()[a.category].tags) & _LAYOUT_KIT}


def _topics(request: Request, scene: Scene) -> list[str]:
    """The place and the roads a request names in full: what a question is about."""
    roads = sorted({lane.road for lane in scene.roads.lanes if lane.road})
    named = [road for road in roads if re.search(rf"\b{re.escape(ph.normalise(road).strip())}\b", request.low)]
    return [*([request.place] if request.place else []), *named]


# A thing's word run straight into another noun, which it then only describes ("student car park").
_MODIFIES_NEXT = re.compile(r"\s*(?:car park|parking|lot|park|area|zone|stop|lane|road|street|entrance|building|hall|side)\b")


@cache
def _places_and_ego(names: tuple[str, ...]) -> re.Pattern[str]:
    """One world's place names and the words for the ego, as one pattern."""
    # the longest first, and no "the ego": "the ego car" is blanked as "the" and "ego car", never leaving "car"
    said = [ph.normalise(n).strip() for n in names] + [w for w in ph.EGO_WORDS if not w.startswith("the ")]
    return re.compile(rf"(?<![a-z])(?:{'|'.join(re.escape(w) for w in sorted(said, key=len, reverse=True))})(?![a-z])")


def _kind_not_looked_up(request: Request, calls: tuple[ToolCall, ...], scene: Scene) -> str | None:
    """The kinds of thing a question points at ("the hydrant"), when none of the plan's lookups names one of them, by
    its category, a thing of it, or a group holding it ("cars"); None when one does, or when the
    plan looks at the weather and the time instead ("dark enough for the street lights?")."""
    # places and the ego blanked, the length kept: "the bus stop" is no stop sign, "the ego car" no car
    blanked = _places_and_ego(tuple(n for lm in scene.landmarks for n in lm.names()))
    text = blanked.sub(lambda m: " " * len(m.group(0)), request.low)
    low, said = ph.normalise(text), ph.normalise(request.low)  # the texts the mentions' offsets count in
    mentions = [m for m in ph.find_categories(text)
                if re.search(r"\b(?:the|that|this|those|these|our|my)\s+(?:[a-z]+\s+){0,2}$", low[: m.start])
                and not _MODIFIES_NEXT.match(said[m.end :])]  # "the student car park": a word said of a place
    pointed = {m.category for m in mentions} - _setting_kinds(request, calls, scene)
    # "the vehicle I just added": a word the catalog tags kinds with stands for each of them
    tagged = {c for m in mentions if (word := ph.singular(low[m.start : m.end].strip())) in md.catalog_tags()
              for c, kind in catalog().items() if word in kind.tags}
    if not pointed or not calls or any(c.tool == "describe_environment" for c in calls):
        return None  # "which lane would a car use": a car in general, not one to look up
    said = " ".join(str(c.args) for c in calls).lower()
    looked = {c for c in catalog() if re.search(rf"(?<![a-z]){c}(?![a-z])", said)}
    looked |= {a.category for a in scene.all_assets() if re.search(rf"(?<![a-z0-9_]){a.id}(?![0-9])", said)}
    looked |= {c for members in md.groups_said(said.replace("_", " ")).values() for c in members}
    return None if pointed & looked or tagged & looked else " or ".join(sorted(pointed)).replace("_", " ")


def _setting_kinds(request: Request, calls: tuple[ToolCall, ...], scene: Scene) -> set[str]:
    """Kinds a question names as its setting: none of them in the scene, when the plan finds the kind
    said after "which" ("my students wait at the stop: which bench is closest to them?": the students
    are no pedestrians to look up)."""
    low = ph.normalise(request.masked)
    named = ph.find_categories(request.masked)
    asked = {m.category for m in named if WHICH_KIND.search(low[: m.start])}
    if not any(c.tool == "find_assets" and c.args.get("category") in asked for c in calls):
        return set()
    return {m.category for m in named if m.category not in asked and not any(a.category == m.category for a in scene.assets)}


def _looked_up(topic: str, said: str, calls: tuple[ToolCall, ...], scene: Scene) -> bool:
    """Whether the plan's lookups are about `topic`: name it, name one of its lanes (a road), or
    look at a thing standing there (a place: "how heavy is the SUV in lot B")."""
    place = scene.landmark(topic)
    names = [topic, *(lane.id for lane in scene.roads.lanes if lane.road == topic), *(place.names() if place is not None else [])]
    if any(n.lower().replace("_", " ") in said for n in names):  # by any of its names ("the pedestrian crossing")
        return True
    if place is None:
        return False
    looked_at = [str(i) for c in calls for i in ([c.args["asset"]] if "asset" in c.args else c.args.get("assets", []))]
    return any((a := scene.asset(i)) is not None and math.dist((a.pose.x, a.pose.y), place.position) <= PLACE_RADIUS_M
               for i in looked_at)


# Words saying a thing should leave the place named: "it is in the wrong car park", "it belongs
# elsewhere", "it shouldn't be in lot B".
_MOVED_AWAY = re.compile(r"\b(?:wrong|belongs?|should(?:n't| not) be|out of|away from)\b")


def _already_there(effect: Effect, scene: Scene) -> list[str]:
    """A thing put where it already stands, and nothing else done to it: nobody asks for that, so
    the words that picked it out were read as where it should go ("it is in the wrong car park; it
    belongs in the western one" read as the car park it is in, "the tree adjacent to the bus stop
    has to go" put next to the bus stop, "the cars on Campus Drive have to go" put in its lane)."""
    out = []
    touched = [str(c.args.get("asset")) for c in effect.calls if c.tool not in QUERY_TOOLS]
    after = effect.outcome.after if effect.outcome else scene
    for call in effect.calls:
        where = call.args.get("location")
        thing = scene.asset(str(call.args.get("asset")))
        if call.tool != "place_asset" or not isinstance(where, dict) or thing is None or touched.count(thing.id) > 1:
            continue
        moved = after.asset(thing.id) or thing
        stands = _standing_at(scene, thing, moved, where, touched)
        if stands is not None:
            out.append(f"{thing.id} already stands {stands}")
    return out


def _added_then_removed(effect: Effect) -> list[AssetInstance]:
    """Things the plan adds and then takes away again (one taken away and then added anew, as
    "make that five" does with the last turn's three, is no such thing)."""
    added: dict[str, AssetInstance] = {}
    out = []
    for op in effect.outcome.edit.ops if effect.outcome else ():
        if op.op == "add":
            added[op.asset.id] = op.asset
        elif op.op == "remove" and op.before.id in added:
            out.append(added.pop(op.before.id))
    return out


def _standing_at(scene: Scene, thing: AssetInstance, moved: AssetInstance, where: dict[str, Any], touched: list[str]) -> str | None:
    """Where `thing` already stands, said as `where` says it, if it already stands there: in the
    area named, in the lane named, or by the landmark or unmoved thing named (and `moved`, where
    the plan puts it, is no nearer); None when it does not or `where` asks for a distance, a side,
    a heading or a spot along a lane."""
    if any(where.get(k) is not None for k in ("distance", "along_m", "side", "offset_m", "x", "y", "heading")):
        return None
    relation, target = where.get("relation"), str(where.get("target") or "")
    place = scene.landmark(target)
    if relation == "at" and place is not None and place.polygon:
        return f"in {place.name}" if _near(scene, thing, place.name) else None
    if relation == "in_lane" and where.get("lane") is None:
        lane = lane_at(scene, thing.pose.x, thing.pose.y)
        return f"in {lane.id}" if lane is not None and lane.id == target else None
    if relation in ("at", "next_to") and target and not target.lower().startswith("ego"):
        try:
            spot = resolve_target(scene, target)
        except ToolError:
            return None
        # by a place, it is at it ("the bin at the bus stop smells, take it away" is no move to the bus stop);
        # by a thing, only a move no nearer leaves it as it was ("the bench right up against the bin" is nearer)
        was, now = (math.dist((a.pose.x, a.pose.y), (spot.x, spot.y)) for a in (thing, moved))
        nearer = now < was - 1.0 and (spot.kind == "asset" or relation == "next_to")
        if spot.kind in ("landmark", "asset") and spot.polygon is None and target not in touched and was <= BY_A_THING_M and not nearer:
            return f"by {target}"
    return None


_TOO_MANY = re.compile(r"\b(?:too many|fewer)\b")
# A pace complained of ("cars are going way too fast here"): never a reason to set parked things going.
_TOO_FAST = re.compile(r"\btoo (?:fast|quick(?:ly)?)\b|\bspeeding\b")
# A thing said to go of itself ("make the bin reverse out of the way by itself"), which only what has a motor or legs can.
_BY_ITSELF = re.compile(r"\b(?:revers\w*|driv\w*|roll\w*|back(?:s|ed|ing)? up|go|goes|leav\w*|walk\w*)\b[^,.;]*"
                        r"\b(?:by (?:it|them)sel(?:f|ves)|on (?:its|their) own|under (?:its|their) own (?:power|steam))\b")
# Verbs that only ever move what is there: "reposition that traffic", "relocate the bins".
_MOVE_ONLY = re.compile(r"\b(?:reposition|repositions|relocate|relocates|move|moves|shift|shifts|transfer|shunt|budge|nudge)\b")
# How a thing should look, said as more or less of a quality: "look a bit less aggressive", "seem more friendly".
_LOOKS_MORE_OR_LESS = re.compile(r"\b(?:look|looks|looking|appear|appears|seem|seems)\s+(?:(?:a (?:bit|little|touch|lot)|a little bit"
                                 r"|slightly|much|far|way|somewhat|even|rather)\s+)?(?:less|more)\b")


# Said of a move, words for a small one ("nudge the bench a little"); a move longer than this is no small one.
_SMALL_MOVE = re.compile(r"\b(?:" + "|".join(re.escape(w) for w in md.SMALL_MOVE) + r")\b")
SMALL_MOVE_M = 5.0
# Verbs that only ever take a thing out of the scene ("remove the extra actors", never a change of what they do).
_REMOVE_VERB = re.compile(r"\b(?:remove|delete|get rid of|eliminate|erase|discard|despawn)\b")


def _far_moved(asset: AssetInstance, effect: Effect) -> float:
    """How far the plan moves `asset` from where it stood, in metres."""
    before = effect.outcome.before.asset(asset.id) if effect.outcome else None
    return math.dist((asset.pose.x, asset.pose.y), (before.pose.x, before.pose.y)) if before is not None else 0.0


def _moved(effect: Effect) -> list[AssetInstance]:
    """The existing assets (the ego included) the plan moves; one given a new behaviour is put
    where its route starts, which is no move in a direction the person named."""
    before = effect.outcome.before if effect.outcome else None
    return [a for a in effect.changed if before is not None and (old := before.asset(a.id)) is not None
            and a.pose != old.pose and a.behaviour == old.behaviour]


def _names(assets: tuple[AssetInstance, ...] | list[AssetInstance]) -> str:
    counts = Counter(a.category for a in assets)
    return ", ".join(f"{n} {c}" for c, n in counts.items())


def _numbers_in_args(value: Any) -> list[float]:
    if isinstance(value, bool):
        return []
    if isinstance(value, int | float):
        return [float(value)]
    if isinstance(value, str):
        return [n.value for n in numbers_in(value)]
    if isinstance(value, dict):
        return [n for v in value.values() for n in _numbers_in_args(v)]
    if isinstance(value, list | tuple):
        return [n for v in value for n in _numbers_in_args(v)]
    return []


def _numbers_used(effect: Effect, scene: Scene, place: str | None, ego: bool = False) -> list[float]:
    """Every number the plan can be said to account for: its arguments and what they come to
    (with `ego`, how far what it adds stands from the ego: "a line of cones 20 m ahead of the ego")."""
    # how many things the plan adds, takes and changes, and how many calls it makes ("two things for my notes: ...")
    counts = [float(len(effect.added)), float(len(effect.removed)), float(len(effect.changed)), float(len(effect.calls))]
    # "the two sedans and the SUV": how many of each kind the plan takes, adds or changes
    counts += [float(n) for group in (effect.added, effect.removed, effect.changed)
               for n in Counter(a.category for a in group).values()]
    # "I ended up with two benches at the gate, one is plenty": how many of a kind it takes stood there
    near = _nearness(scene, place) if place else (lambda a: True)
    counts += [float(sum(1 for a in scene.assets if a.category == kind and near(a))) for kind in {a.category for a in effect.removed}]
    # "the car number 2": the number in the id of a thing the plan names
    counts += [float(m.group(1)) for c in effect.calls for v in c.args.values() for i in (v if isinstance(v, list) else [v])
               if isinstance(i, str) and (m := re.search(r"_(\d+)$", i)) and scene.asset(i) is not None]
    # "how far apart are the two gates": how many places the plan names
    counts.append(float(len({v for c in effect.calls for v in c.args.values() if isinstance(v, str) and scene.landmark(v) is not None})))
    # a grid of 12 in 4 columns is 3 rows
    counts += [float(math.ceil(int(c.args["count"]) / int(c.args["columns"]))) for c in effect.calls
               if isinstance(c.args.get("count"), int) and isinstance(c.args.get("columns"), int) and c.args["columns"] > 0]
    used = [n for c in effect.calls for n in _numbers_in_args(c.args)] + counts
    used += _reach(effect, scene)  # "starting 20 m ahead of our car": where a layout begins and ends
    if ego and effect.added and scene.asset("ego") is not None:
        me = scene.ego.pose
        xs, ys = [a.pose.x for a in effect.added], [a.pose.y for a in effect.added]
        used.append(float(round(math.dist((me.x, me.y), (sum(xs) / len(xs), sum(ys) / len(ys))))))
        # "on the north pavement 10 m behind the ego": how far along its heading, the pavement beside it
        used.append(float(round(abs((sum(xs) / len(xs) - me.x) * math.cos(me.yaw) + (sum(ys) / len(ys) - me.y) * math.sin(me.yaw)))))
    used += [math.hypot(float(c.args.get("east", 0)), float(c.args.get("north", 0)))  # a move at a slant
             for c in effect.calls if c.tool == "move_asset" and "east" in c.args and "north" in c.args]
    return used


def _figures_left_out(request: Request, calls: list[ToolCall]) -> list[float]:
    """The speeds and distances the request says that none of the calls' arguments hold, in the
    unit said ("drive at 36 km/h and stop before the crossing" read as the stop alone leaves out
    36; "a stopped car 35 m ahead" read as the ego stopping leaves out 35). Not times: a
    storyboard's times and gaps are sums of what is said ("brakes 4 s later" is at 5 s)."""
    used = [n for c in calls for n in _numbers_in_args(c.args)]
    # a newcomer's place ahead is where it will be when it starts: a sum again ("steps out 15 m ahead after 3 s")
    figures = (_SPEED_SAID,) if any("location" in c.args for c in calls) else (_SPEED_SAID, _DISTANCE_FIGURE)
    measures = [(float(m.group(1)), m.group(2)) for said in figures for m in said.finditer(request.low)]
    return [n for n, unit in measures
            if not _accounts_for(n, used, [1.0, *(f for said, f in UNIT_FACTORS.items() if re.search(said, unit))])]


# Asking what stands between two places (not how far apart they are).
_WHAT_LIES_BETWEEN = re.compile(r"\b(?:what|anything|something|which \w+)(?:'s|\s+is|\s+are|\s+stands?|\s+lies?|\s+sits?)?\s+"
                                r"(?:(?:parked|standing|placed|located|there)\s+)?(?:right\s+|in\s+)?between\b(?![^?.]*\b(?:distance|far|long|gap)\b)")


def _lane_change_left_out(low: str, calls: list[ToolCall]) -> list[str]:
    """A move into another lane said ("swings into the left lane at 6 s") that no call makes."""
    said = _LANE_CHANGE_SAID.search(low)
    kinds = {str(c.args.get("manoeuvre", {}).get("kind")) for c in calls if isinstance(c.args.get("manoeuvre"), dict)}
    kept = said is not None and re.search(r"\b(?:keep|stay|stick|remain)\w*\s+(?:\w+\s+)?$", low[: said.start()])  # "keeping to the left lane"
    if said is None or kept or kinds & {"lane_change", "cut_in", "overtake"}:
        return []
    return [f"you said '{said.group(0).strip()}', but the plan changes no lane"]


_LANE_CHANGE_SAID = re.compile(r"\b(?:in)?to the (?:left|right)(?:[- ]hand)? lane\b|\bchang\w* lanes?\b|\blane change\b")
_SPEED_SAID = re.compile(rf"(\d+(?:\.\d+)?)\s*{SPEED_UNIT}", re.IGNORECASE)  # the readers' own units of speed
_DISTANCE_FIGURE = re.compile(rf"(\d+(?:\.\d+)?)\s*({_LENGTH_UNITS})\b(?!\s*(?:/|per\b|an hour))")  # a distance, no speed


def _accounts_for(number: float, used: list[float], factors: list[float]) -> bool:
    """Whether `number`, in one of the units said (`factors`), is among the numbers `used`."""
    return math.isfinite(number) and any(
        math.isclose(abs(number) * f, abs(u), rel_tol=NUMBER_TOLERANCE, abs_tol=NUMBER_TOLERANCE) for u in used for f in factors)


def _totals(request: Request, effect: Effect) -> dict[str, int]:
    """How many of each kind the plan adds or removes stand at the request's place after it, where
    the request says the count the scene should end with ("there should be exactly four cones", "all but three")."""
    if effect.outcome is None or not (FINAL_COUNT.search(request.low) or KEEP_SOME.search(request.low)):
        return {}
    kinds = {a.category for a in [*effect.added, *effect.removed]}
    return {k: len(kept_at(effect.outcome.after, k, request.place)) for k in kinds}


def _reach(effect: Effect, scene: Scene) -> list[float]:
    """How far the nearest and the furthest of what each layout adds stand from what it is laid
    out from, to the metre."""
    out = []
    for call in effect.calls:
        target = call.args.get("location", {}).get("target") if isinstance(call.args.get("location"), dict) else None
        centre = _centre(scene, str(target)) if call.tool == "arrange_assets" and target else None
        if centre is None or not effect.added:
            continue
        gaps = [math.dist(centre, (a.pose.x, a.pose.y)) for a in effect.added]
        out += [float(round(min(gaps))), float(round(max(gaps)))]
    return out


def _centre(scene: Scene, place: str) -> tuple[float, float] | None:
    try:
        target = resolve_target(scene, place)
    except ToolError:
        return None
    return target.x, target.y


# Amounts said without a number: "half the lamps", "benches at both ends", "a cone on each side of it".
_HALF_SAID = re.compile(r"\bhalf (?:of )?(?:the|those|these|them|all)\b")
_SEVERAL_SAID = re.compile(r"\bboth\b|\b(?:each|every|all four|all the) (?:side|sides|corner|corners|end|ends)\b")


def _amount_words_left_out(request: Request, effect: Effect, scene: Scene) -> list[str]:
    """A plan that acts on every one of the one kind the request says half of, or adds a single
    thing where it says both, or each side, corner or end."""
    out = []
    acted = [a for a in [*effect.removed, *effect.changed] if a.id != "ego"]
    if _HALF_SAID.search(request.low) and len(request.categories) == 1 and len(acted) > 1:
        kind = next(iter(request.categories))
        every = [a for a in scene.assets if a.category == kind]
        if len(every) > 1 and {a.id for a in acted} >= {a.id for a in every}:
            out.append(f"you said half of the {kind.replace('_', ' ')}s, but the plan acts on all {len(every)}")
    if (said := _SEVERAL_SAID.search(request.low)) is not None and len(effect.added) == 1 and not request.question:
        out.append(f"you said {said.group(0)}, but the plan adds one {effect.added[0].category.replace('_', ' ')}")
    return out


def _not_between(request: Request, scene: Scene, placed: list[AssetInstance]) -> list[str]:
    """Things a plan puts nearer one end than the middle of what the request says they go between."""
    said = BETWEEN.search(request.low)
    if said is None or request.question:
        return []
    ends = [end for side in ("a", "b") if (end := point_named(scene, f" {said.group(side)} ")) is not None]
    if len(ends) < 2:
        return []
    middle = ((ends[0][0] + ends[1][0]) / 2, (ends[0][1] + ends[1][1]) / 2)
    off = [a.id for a in placed if a.id != "ego" and math.dist((a.pose.x, a.pose.y), middle)
           > min(math.dist((a.pose.x, a.pose.y), end) for end in ends)]
    return [f"you said between {said.group('a')} and {said.group('b')}, but the plan puts {', '.join(off)} nearer one of them"] if off else []


# One thing picked out by being nearest or furthest: "the tree furthest from the library".
_EXTREME = re.compile(r"\b(?:(?P<near>nearest|closest)(?! one\b)|(?P<far>furthest|farthest|most distant)(?= (?:away )?from\b))\b")


def _not_the_extreme(request: Request, effect: Effect, scene: Scene) -> list[str]:
    """A plan that acts on one thing of the one kind named where the request picks it as the
    nearest or furthest from a place or the ego, and that thing is not it."""
    said = _EXTREME.search(request.masked)
    acted = [a for a in [*effect.removed, *effect.changed] if a.id != "ego"]
    if said is None or request.question or len(request.categories) != 1 or len(acted) != 1:
        return []
    kind = next(iter(request.categories))
    ego = scene.asset("ego")
    after = find_place(scene, request.low[said.end() :])  # "... there. Put the lamp closest to the fountain there": the fountain
    place = after[0] if after is not None else request.place
    centre = _centre(scene, place) if place is not None else (
        (ego.pose.x, ego.pose.y) if ego is not None and re.search(r"\bego\b", request.low[said.end():]) else None)
    pool = [a for a in scene.assets if a.category == kind]
    if centre is None or acted[0].category != kind or len(pool) < 2:
        return []
    pick = (max if said.group("far") else min)(pool, key=lambda a: math.dist((a.pose.x, a.pose.y), centre))
    if pick.id == acted[0].id:
        return []
    return [f"you said the {said.group(0)} {kind.replace('_', ' ')}, which is {pick.id}, but the plan acts on {acted[0].id}"]


def _not_the_biggest(request: Request, effect: Effect, scene: Scene) -> list[str]:
    """A plan that acts on things of the kind a size word picks among ("the biggest vehicle", "the
    tallest of the trees") other than the ones it picks (the search tool's figures say which)."""
    said = md.SIZE_SUPERLATIVE.search(request.masked)
    if said is None or request.question:
        return []
    after = request.masked[said.end() : said.end() + 40]
    group = next(iter(md.groups_said(request.masked[said.start() : said.end() + 40]).values()), None)
    named = ph.find_categories(after)
    kinds = set(group) if group else {named[0].category} if named else set()
    acted = [a for a in [*effect.removed, *effect.changed] if a.id != "ego" and a.category in kinds]
    picks = most_of(md.most_said(said.group(1)), [a for a in scene.assets if a.category in kinds])
    wrong = [a for a in acted if a.id not in {p.id for p in picks}]
    if not wrong:
        return []
    return [f"you said the {said.group(1)} one, which is {_names(picks)}, but the plan also acts on {_names(wrong)}"]


def _outermost(request: Request, effect: Effect, scene: Scene) -> tuple[AssetInstance, AssetInstance] | None:
    """(the one acted on, the one meant) where the request picks one thing of a kind by the side or
    corner it stands at ("only the north-east one goes", "the westernmost lamp"), among those at the
    place named, and a plan acts on another; None when it acts on the one meant or picks none."""
    way = md.outer_direction(request.low)
    acted = [a for a in [*effect.removed, *effect.changed] if a.id != "ego"]
    if way is None or request.question or len(acted) != 1:
        return None
    pool = [a for a in scene.assets if a.category == acted[0].category
            and (request.place is None or _near(scene, a, request.place))]
    if len(pool) < 2:
        return None
    pick = max(pool, key=lambda a: a.pose.x * way[0] + a.pose.y * way[1])
    return None if pick.id == acted[0].id else (acted[0], pick)


# "Further from the bus stop", "closer to the library": the way the distance to the place must go.
_NEAREST_OF = re.compile(r"\b(?:nearest|closest)\b")
_NEARER = re.compile(r"\b(?:closer|nearer)(?: to)?\b|\btowards?\b")
_FURTHER = re.compile(r"\b(?:further|farther|more)(?: away)? from\b|\baway from\b"
                      # "the SUV blocks my view of the Library, can it be somewhere else?": away from the place said,
                      # unless another place is said after it ("put it elsewhere, by the fountain")
                      r"|\b(?:elsewhere|somewhere else|out of (?:the|my|our|their) (?:way|view|shot|sight))\b"
                      r"(?![^.;!?]*\b(?:to|by|near|next to|beside|at|in|into|onto|outside|behind)\s+(?:the|lot|parking)\b)")


def _wrong_way_to(request: Request, scene: Scene, moved: list[AssetInstance]) -> list[str]:
    """Things a plan moves the other way from the one place the request says they should be
    nearer to or further from ("push the bin further from the bus stop" never brings it nearer)."""
    nearer, further = _NEARER.search(request.low), _FURTHER.search(request.low)
    if bool(nearer) == bool(further):
        return []
    said = nearer or further
    assert said is not None
    # "3 m towards the bench": by the place, or else the nearest of the kind of thing named after the word
    after_word = {m.category for m in ph.find_categories(request.masked[said.end() :])}
    out = []
    for after in moved:
        before = scene.asset(after.id)
        others = [a for a in scene.assets if a.category in after_word and a.id != after.id]
        if before is None or after.id == request.place:
            continue
        if request.place is not None:
            centre, name = _centre(scene, request.place), request.place
        elif others:
            closest = min(others, key=lambda a: math.dist((a.pose.x, a.pose.y), (before.pose.x, before.pose.y)))
            centre, name = (closest.pose.x, closest.pose.y), closest.id
        else:
            continue
        if centre is None:
            continue
        change = math.dist((after.pose.x, after.pose.y), centre) - math.dist((before.pose.x, before.pose.y), centre)
        if (change < -MIN_MOVE_M) if further else (change > MIN_MOVE_M):
            way = "nearer to" if further else "further from"
            out.append(f"you said {'further from' if further else 'closer to'} {name}, but the plan moves {after.id} {way} it")
    return out


_FACE_SAID = re.compile(r"\bfac(?:e|es|ing)\b|\bpoint(?:s|ed|ing)?\b(?=[^,.;]*\b(?:at|towards?)\b)")
# A thing turned to face a way where it stands: "orient the bench towards the fountain", "angle the camera car at the
# gate", "turn the SUV to face the road" (the words after say which way, never where to).
_TURNED_TOWARD = re.compile(r"\b(?:orient\w*|turn|turns|turned|rotate[sd]?|angle[sd]?|swivel\w*|spin)\b[^,.;]*?\b(?:towards?|to face|at)\b")
_MOVE_SAID = re.compile(r"\b(?:" + "|".join(re.escape(w) for w in lx.MOVE_WORDS) + r")\b")


def _moved_to_turn(request: Request, effect: Effect) -> list[str]:
    """Things carried off where the words only turn them to face a place ("orient the bench towards
    the fountain" never puts the bench in the fountain)."""
    turned = _TURNED_TOWARD.search(request.low)
    if turned is None or _MOVE_SAID.search(request.low):
        return []
    far = [a for a in effect.changed if a.id != "ego" and _far_moved(a, effect) > SMALL_MOVE_M]
    return [f"you asked to turn {_names(far)} to face a way where it stands, but the plan moves it"] if far else []


# How far off the heading to a place a thing may point and still face it.
FACING_SLACK_DEG = 20.0


def _turned_to_face(scene: Scene, asset: AssetInstance, place: str) -> bool:
    """Whether the plan turns an asset that was there, without moving it, to face the place."""
    before, centre = scene.asset(asset.id), _centre(scene, place)
    if before is None or centre is None or (before.pose.x, before.pose.y) != (asset.pose.x, asset.pose.y):
        return False
    heading = math.atan2(centre[1] - asset.pose.y, centre[0] - asset.pose.x)
    return abs(math.degrees(math.remainder(heading - asset.pose.yaw, 2 * math.pi))) <= FACING_SLACK_DEG


def _heads_to(scene: Scene, asset: AssetInstance, place: str) -> bool:
    """Whether the asset is given a path that ends at the place."""
    centre = _centre(scene, place)
    path = getattr(asset.behaviour, "waypoints", None)
    if centre is None or not path:
        return False
    return math.dist(tuple(path[-1]), centre) <= PLACE_RADIUS_M / 2


def _brought_closer(scene: Scene, asset: AssetInstance, place: str) -> bool:
    """Whether the plan moves an asset that was there nearer to the place."""
    before, centre = scene.asset(asset.id), _centre(scene, place)
    if before is None or centre is None:
        return False
    return math.dist((asset.pose.x, asset.pose.y), centre) < math.dist((before.pose.x, before.pose.y), centre) - 0.5


def _near(scene: Scene, asset: AssetInstance, place: str) -> bool:
    return _nearness(scene, place)(asset)


def _nearness(scene: Scene, place: str) -> Callable[[AssetInstance], bool]:
    """Whether an asset is at `place` (inside its area, or within PLACE_RADIUS_M), the place
    resolved once; a place the tools cannot resolve cannot be judged against: all are near."""
    try:
        target = resolve_target(scene, place)
    except ToolError:
        return lambda asset: True
    polygon = target.polygon

    def near(asset: AssetInstance) -> bool:
        if polygon is not None and point_in_polygon(asset.pose.x, asset.pose.y, polygon):
            return True
        return math.hypot(asset.pose.x - target.x, asset.pose.y - target.y) <= PLACE_RADIUS_M

    return near


def _at_a_target(scene: Scene, effect: Effect, asset: AssetInstance, named: frozenset[str] = frozenset()) -> bool:
    """Whether the asset ends up at a landmark or on a lane that one of the plan's calls names, or
    by a thing of a kind the request `named` (a compound request names several places: "a bus on
    Main Street and a truck at the JTEKT", "the bin next to the hydrant and the bench at the gate")."""
    def strings(value: Any) -> list[str]:
        if isinstance(value, dict):
            return [s for v in value.values() for s in strings(v)]
        return [value] if isinstance(value, str) else []

    for said in {s for c in effect.calls for s in strings(c.args)}:
        if scene.landmark(said) is not None and _near(scene, asset, said):
            return True
        lane = scene.roads.lane(said)
        if lane is not None and nearest_on_polyline(asset.pose.x, asset.pose.y, lane.centreline).distance <= lane.width:
            return True
        by = scene.asset(said)
        if (by is not None and by.id != asset.id and by.category in named
                and math.dist((by.pose.x, by.pose.y), (asset.pose.x, asset.pose.y)) <= BY_A_THING_M):
            return True
    return False


def _names_target(effect: Effect, place: str) -> bool:
    return any(place.lower() in str(c.args).lower() for c in effect.calls if c.tool not in ("remove_assets",))


def repairs(request: Request, effect: Effect, context: PlanContext) -> list[Reading]:
    """Readings built from the plan's own effect that fit the request better: the opposite
    polarity, only the assets at the place or of the state named, no edit for a question."""
    return [reading for repair in _REPAIRS for reading in repair(request, effect, context.scene)]


def _either_value(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """A time, behaviour or look set twice: either value said, the rest of the plan kept."""
    out = []
    for i, j in overridden(effect.calls)[:1]:
        for dropped in (j, i):
            calls = [c for k, c in enumerate(effect.calls) if k != dropped]
            out.append(Reading(text=describe(calls), calls=calls))
    return out


def _the_outermost(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """"only the north-east one": that one."""
    if (other := _outermost(request, effect, scene)) is None:
        return []
    picked = [_retargeted(c, other[0].category, {other[0].id}, [other[1].id]) for c in effect.calls]
    kept = [c for c in picked if c is not None]
    return [Reading(text=describe(kept), calls=kept)] if len(kept) == len(picked) else []


def _lamps_switched(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """The street lights switched as the words say ("exposure 1.5 and the street lights on": both)."""
    lamps = LAMPS_SWITCHED.search(request.low)
    if lamps is None or any(c.tool == "set_lighting" and "street_lights" in c.args for c in effect.calls):
        return []
    state = lamps.group("state") or lamps.group("state2")
    lit = [c.model_copy(update={"args": {**c.args, "street_lights": state}}) for c in effect.calls if c.tool == "set_lighting"]
    calls = [*(c for c in effect.calls if c.tool != "set_lighting"), *(lit or [ToolCall(tool="set_lighting", args={"street_lights": state})])]
    return [Reading(text=describe(calls), calls=calls)]


def _layout_in_full(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """A layout of one where a layout is said: as many as the layout takes."""
    if not _layout_of_one(request.masked, effect.calls):
        return []
    calls = [c.model_copy(update={"args": {k: v for k, v in c.args.items() if k != "count"}})
             if c.tool == "arrange_assets" and c.args.get("count") == 1 else c for c in effect.calls]
    return [Reading(text=describe(calls), calls=calls)]


def _weather_as_strong_as_said(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """"a bit cloudy" set as medium: the light one."""
    if not (strength := weather_strength(request.low, effect.calls)):
        return []
    intensity = LIGHT_INTENSITY if "light" in strength[0] else HEAVY_INTENSITY
    calls = [c.model_copy(update={"args": {**c.args, "intensity": intensity}}) if c.tool == "set_weather" else c
             for c in effect.calls]
    return [Reading(text=describe(calls), calls=calls)]


def _lane_the_way_said(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """"drive south": the road's lane going south."""
    if (way := md.compass_direction(request.masked)) is None:
        return []
    turned = [_lane_turned(c, way, scene) for c in effect.calls]
    return [Reading(text=describe(turned), calls=turned)] if turned != list(effect.calls) else []


def _only_the_answer(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """A question that edits: its lookups alone, or one of the kind it names."""
    if not (request.question and effect.edits):
        return []
    queries = [c for c in effect.calls if c.tool in QUERY_TOOLS]
    if request.categories and not queries:
        near = {"near": request.place} if request.place else {}
        queries = [ToolCall(tool="find_assets", args={"category": sorted(request.categories)[0], **near})]
    return [Reading(text="only answer the question, change nothing", calls=queries)] if queries else []


def _the_other_polarity(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """Each addition turned into a removal of that kind (the rest of the plan kept), or a removal
    into an addition."""
    if request.polarity == "remove" and effect.added:
        flipped = [_removal(c, request, scene) if c.tool == "add_asset" else c for c in effect.calls]
        if flipped != list(effect.calls) and all(flipped):
            calls = [c for c in flipped if c is not None]
            return [Reading(text=describe(calls), calls=calls)]
    if request.polarity == "add" and effect.removed and not effect.added:
        category = sorted(request.categories)[0] if request.categories else effect.removed[0].category
        return [Reading(text=f"add a {category.replace('_', ' ')}", calls=[
            ToolCall(tool="add_asset", args={"category": category, "count": 1})])]
    return []


def _a_new_one_there(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """A thing of the kind asked for moved where a new one was meant: a new one there."""
    fresh = [ToolCall(tool="add_asset", args={"category": asset.category, "count": 1, "location": c.args["location"]})
             for c in effect.calls if c.tool == "place_asset" and "location" in c.args
             and (asset := scene.asset(str(c.args.get("asset")))) is not None and asset.category in request.categories]
    return [Reading(text=describe(fresh), calls=fresh)] if fresh and not effect.added else []


def _sparing_the_excepted(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """"every car except the SUV": the plan without it."""
    if request.excepted and (spared := _sparing(effect, excepted_ids(request.excepted, _kinds_named(request), scene,
                                                                      without_contrast(request.low)))):
        return [Reading(text=describe(spared), calls=spared)]
    return []


def _only_where_said(request: Request, effect: Effect, scene: Scene) -> list[Reading]:
    """Removals kept to the one by the thing named, or to the place or state named."""
    out = []
    for _, category, meant in [] if request.question else picked_by_thing(request.masked, scene):
        if any(a.category == category and a.id not in meant for a in effect.removed):
            out.append(Reading(text="remove " + ", ".join(sorted(meant)), calls=[
                ToolCall(tool="remove_assets", args={"assets": sorted(meant)})]))
    if effect.removed and (request.place or request.state):
        keep = [a.id for a in effect.removed
                if (request.place is None or _near(scene, a, request.place))
                and (request.state is None or (a.behaviour.kind == "parked") == (request.state == "parked"))]
        if keep and len(keep) < len(effect.removed):
            out.append(Reading(text="remove only " + ", ".join(keep), calls=[
                ToolCall(tool="remove_assets", args={"assets": keep})]))
    return out


# Each builds readings from the plan's effect; they are offered in this order.
_REPAIRS: tuple[Callable[[Request, Effect, Scene], list[Reading]], ...] = (
    _either_value, _the_outermost, _lamps_switched, _layout_in_full, _weather_as_strong_as_said, _lane_the_way_said,
    _only_the_answer, _the_other_polarity, _a_new_one_there, _sparing_the_excepted, _only_where_said,
)


def _lane_turned(call: ToolCall, way: str, scene: Scene) -> ToolCall:
    """`call` with a drive_lane behaviour in a lane going against `way` moved to the lane of the
    same road that goes `way` (and placed in it, when the call placed it in the first)."""
    behaviour = call.args.get("behaviour")
    if not isinstance(behaviour, dict) or behaviour.get("kind") != "drive_lane":
        return call
    lane = scene.roads.lane(str(behaviour.get("lane")))
    if lane is None or lane_way(lane, way) >= 0:
        return call
    other = next((o for o in scene.roads.lanes if o.road == lane.road and o.kind == "driving" and lane_way(o, way) > 0.5), None)
    if other is None:
        return call
    args = {**call.args, "behaviour": {**behaviour, "lane": other.id}}
    location = args.get("location")
    if isinstance(location, dict) and location.get("target") == lane.id:
        args["location"] = {**location, "target": other.id}
    return call.model_copy(update={"args": args})


# Things "on Main Street" stand within this of one of its lanes' centrelines (its pavements included).
ON_ROAD_M = 10.0


def _off_the_road_named(request: Request, effect: Effect, scene: Scene) -> list[str]:
    """Things a plan removes or changes away from the road the request scopes them to ("remove the
    cars from Main Street" never takes the cars parked in lot B)."""
    # a thing changed may be put on the road ("park the SUV on Main Street"): away if neither before nor after is on it
    acted = [(a, scene.asset(a.id) or a) for a in [*effect.removed, *effect.changed] if a.id != "ego"]
    if not acted or request.place is not None:
        return []
    for lane_road in {lane.road for lane in scene.roads.lanes if lane.road}:
        name = re.escape(ph.normalise(lane_road).strip())
        # ("clear every car off Campus Drive" reads "clear away every car campus drive" once its particle moves)
        if not re.search(rf"\b(?:on|in|along|from|off|down|up)\s+(?:the\s+)?{name}\b|\baway(?:\s+\w+){{1,4}}\s+{name}\b", request.low):
            continue
        lines = [lane.centreline for lane in scene.roads.lanes if lane.road == lane_road]
        ids = {lane.id for lane in scene.roads.lanes if lane.road == lane_road}
        driving = {a.id for a, _ in acted if a.behaviour.kind == "drive_lane" and getattr(a.behaviour, "lane", None) in (None, *ids)}
        away = [after for after, before in acted if after.id not in driving  # "follow the traffic on Main Street": its lane, or one to come
                and all(min(nearest_on_polyline(a.pose.x, a.pose.y, line).distance for line in lines) > ON_ROAD_M for a in (after, before))]
        if away:
            return [f"you said {lane_road}, but the plan acts on {_names(away)} away from it"]
    return []


# A traffic light's red or green said as what it shows: "stay on red", "turn green", "held at red".
_LIGHT_SHOWS = re.compile(r"\b(?:on|stay\w*|go(?:es)?|turn\w*|stuck (?:on|at)|hold\w*|held (?:on|at)|show\w*|at)\s+(?:red|green|amber|yellow)\b")


def _light_painted(request: Request, calls: tuple[ToolCall, ...], scene: Scene) -> list[str]:
    """A traffic light painted red or green where the words ask what it shows ("could the light just stay
    on red"): that is its phase over time (set_light_phases), not the colour of its housing."""
    painted = [str(i) for c in calls if c.tool == "set_asset_appearance" and str(c.args.get("colour")) in ("red", "green", "amber", "yellow")
               for i in [*c.args.get("assets", []), c.args.get("asset")] if i and (a := scene.asset(str(i))) is not None
               and a.category == "traffic_light"]
    if painted and _LIGHT_SHOWS.search(request.low):
        return [f"you asked what {', '.join(painted)} shows, which is its phase over time, but the plan paints it"]
    return []


def _layout_of_one(masked: str, calls: tuple[ToolCall, ...]) -> list[str]:
    """A row, ring or grid said, laid out with one thing: "some seating in a row" read as count 1
    (a layout of one with no layout said is how a plan puts one thing across the road)."""
    if md.layout_said(masked) is None:
        return []
    return [f"the plan lays out a {c.args.get('shape', 'layout')} of one {', '.join(c.args.get('categories', []))}"
            for c in calls if c.tool == "arrange_assets" and c.args.get("count") == 1]


def _layout_of_the_place(request: Request, calls: tuple[ToolCall, ...], scene: Scene) -> list[str]:
    """A layout of the very kind of thing it is laid out by, that kind said once: "a few witnesses
    in a line near the bench" read as a line of benches by the bench."""
    out = []
    for call in calls:
        location = call.args.get("location")
        where = scene.asset(str(location.get("target"))) if call.tool == "arrange_assets" and isinstance(location, dict) else None
        if where is not None and where.category in call.args.get("categories", []) \
                and sum(1 for m in ph.find_categories(request.masked) if m.category == where.category) <= 1:
            out.append(f"you named the {where.category.replace('_', ' ')} as the place, but the plan lays out more of them")
    return out


def _kinds_named(request: Request) -> set[str]:
    """The kinds a request is about, for its "ones" ("..., not the ones at the ends"): the
    categories it asks for, else any it names ("the car who is in the middle")."""
    return set(request.categories) or {m.category for m in ph.find_categories(request.masked)}


def _sparing(effect: Effect, spared: set[str]) -> list[ToolCall]:
    """The plan's calls without what they would do to the `spared` ids ("..., not the ego");
    empty when they touch none of them or nothing else is left to do."""
    acted = {a.id: a for a in [*effect.removed, *effect.changed]}
    out: list[ToolCall] = []
    for call in effect.calls:
        args = dict(call.args)
        if call.tool in _GROUP_TOOLS and "category" in args and "assets" not in args:  # by kind: the ones it took
            kind = args.pop("category")
            args = {k: v for k, v in args.items() if k not in ("count", "near", "within")}
            args["assets"] = [i for i, a in acted.items() if a.category == kind]
        if "assets" in args:
            args["assets"] = [i for i in args["assets"] if i not in spared]
            if not args["assets"]:
                continue
        elif str(args.get("asset", "")) in spared:
            continue
        out.append(call.model_copy(update={"args": args}))
    return out if out and out != list(effect.calls) else []


def _removal(call: ToolCall, request: Request, scene: Scene) -> ToolCall | None:
    """The removal of what `call` would add, near the place named; None when none is there."""
    category = str(call.args.get("category", ""))
    if not scene.count(category):
        return None
    args: dict[str, Any] = {"category": category, **({"near": request.place} if request.place else {})}
    return ToolCall(tool="remove_assets", args=args)


def review(prompt: str, plan: Plan, context: PlanContext) -> Verdict:
    """Apply, ask or refuse: whether `plan` accounts for what `prompt` asks (nothing is applied)."""
    if plan.question is not None:
        return _screened(prompt, plan.question, context)
    # "to know what a truck weighs for my braking calculation" asks; it describes no scenario
    answers = bool(plan.calls) and all(c.tool in QUERY_TOOLS for c in plan.calls) and asks(ph.normalise(prompt).strip())
    if not answers and (missed := missed_scenario(prompt, plan, context)) is not None:  # never a static edit for a scenario
        return Verdict("ask" if missed.question else "refuse", [missed.problem], missed.question, missed.message)
    if read_as_scenario(prompt, plan, context):  # the storyboard's readings are the scenario reader's to judge,
        left_out = _figures_left_out(read_request(prompt, context.scene), plan.calls)  # but every figure said is in them
        problems = ["the plan leaves out " + ", ".join(f"{n:g}" for n in left_out)] if left_out else []
        problems += _lane_change_left_out(ph.normalise(prompt), plan.calls)  # and every lane change said
        if problems:
            return Verdict("refuse", problems, None, refusal(problems, context))
        return Verdict("apply")
    effect = dry_run(plan.calls, context)
    if effect is None:
        return Verdict("apply")  # the transaction refuses it in its own words
    request = read_request(prompt, context.scene)
    found = problems_of(request, effect, context)
    if not found:
        pick = None if request.question else ambiguous_pick(
            request.masked, _scope(effect), context.scene, context.memory, request.place,
            _nearness(context.scene, request.place) if request.place else None)
        if pick is not None:
            return _which_one(*pick, plan, context)
        absent = [] if request.question else absent_but_added(request.masked, _scope(effect), context.scene)
        if absent:
            name = absent[0].replace("_", " ")
            return Verdict("ask", [f"there is no {name} here to change"], Question(
                text=f"There is no {name} in the scene yet. Add one?",
                readings=[Reading(text=describe(plan.calls), calls=list(plan.calls))]))
        return Verdict("apply", outcome=effect.outcome)
    if request.excepted and found == excepted_touched(request.excepted, _kinds_named(request), _scope(effect), context.scene, without_contrast(request.low)):
        spared = _sparing(effect, excepted_ids(request.excepted, _kinds_named(request), context.scene, without_contrast(request.low)))
        kept = dry_run(spared, context) if spared else None
        if kept is not None and not problems_of(request, kept, context):
            return Verdict("apply", found, outcome=kept.outcome, calls=spared)
    fitting: list[Reading] = []
    for reading in [*repairs(request, effect, context), *plan.alternatives]:
        other = dry_run(reading.calls, context)
        if other is not None and not problems_of(request, other, context) and reading not in fitting:
            fitting.append(reading)
    if not fitting:
        return Verdict("refuse", found, None, refusal(found, context))
    mine = Reading(text="as planned: " + "; ".join(str(c) for c in plan.calls), calls=list(plan.calls))
    readings = [*fitting[: MAX_READINGS - 1], mine]
    text = f"I am not sure what you meant: {found[0]}. Which did you mean?"
    return Verdict("ask", found, Question(text=text, readings=readings))


def _which_one(category: str, candidates: list[AssetInstance], plan: Plan, context: PlanContext) -> Verdict:
    """Ask which of several things "the <category>" meant: the nearest two to the ego, and all."""
    ego = context.scene.ego
    ordered = sorted(candidates, key=lambda a: math.dist((a.pose.x, a.pose.y), (ego.pose.x, ego.pose.y)) if ego else 0.0)
    original = {a.id for a in candidates}
    readings = []
    for chosen in [[a.id] for a in ordered[: MAX_READINGS - 1]] + [[a.id for a in ordered]]:
        calls = [_retargeted(c, category, original, chosen) for c in plan.calls]
        effect = dry_run([c for c in calls if c is not None], context) if all(calls) else None
        if effect is not None and {a.id for a in _scope(effect).touched if a.category == category} == set(chosen):
            x, y = _xy(context.scene, chosen[0])
            where = f"{chosen[0]} at ({x:.0f}, {y:.0f}) near {nearest_landmark(context.scene, (x, y))}"
            said = where if len(chosen) == 1 else "both" if len(chosen) == 2 else f"all {len(chosen)}"
            readings.append(Reading(text=f"{said}: {describe([c for c in calls if c is not None])}",
                                    calls=[c for c in calls if c is not None]))
    name = category.replace("_", " ")
    problem = f"there are {len(candidates)} of the {name} kind here and the words do not say which"
    if not readings:
        return Verdict("refuse", [problem], None, refusal([problem], context))
    text = f"Which {name} did you mean? There are {len(candidates)}: {', '.join(a.id for a in ordered)}."
    return Verdict("ask", [problem], Question(text=text, readings=readings[:MAX_READINGS]))


def _retargeted(call: ToolCall, category: str, original: set[str], chosen: list[str]) -> ToolCall | None:
    """`call` made to act on the assets `chosen` instead of whichever of `original` it picked;
    None when the tool takes one asset and several are chosen."""
    args = dict(call.args)
    single = isinstance(args.get("asset"), str) and args["asset"] in original
    listed = any(i in original for i in args.get("assets", []))
    if not (single or listed or (args.get("category") == category and not args.get("assets"))):
        return call
    if single and len(chosen) > 1 and call.tool not in _GROUP_TOOLS:
        return None  # place_asset, set_behaviour: one asset a call
    for key in ("asset", "category", "count", "near"):
        args.pop(key, None)
    if single and len(chosen) == 1:
        args["asset"] = chosen[0]
    else:
        args["assets"] = [*(i for i in call.args.get("assets", []) if i not in original), *chosen]
    return call.model_copy(update={"args": args})


def _scope(effect: Effect) -> Scope:
    return Scope(effect.calls, (*effect.added, *effect.removed, *effect.changed), effect.removed, effect.added)


def _xy(scene: Scene, asset_id: str) -> tuple[float, float]:
    asset = scene.asset(asset_id)
    return (asset.pose.x, asset.pose.y) if asset is not None else (0.0, 0.0)


def _screened(prompt: str, question: Question, context: PlanContext) -> Verdict:
    """A planner's question with the readings this check knows to misread the request taken
    out; when none is left, a refusal that says why the best of them was wrong."""
    if any(c.tool in SCENARIO_TOOLS for r in question.readings for c in r.calls):
        return Verdict("ask", ["the planner could not tell which reading was meant"], question)
    request = read_request(prompt, context.scene)
    kept: list[Reading] = []
    runs: list[Effect] = []
    first_problems: list[str] = []
    for reading in question.readings:
        effect = dry_run(reading.calls, context)
        found = ["a dry run refuses it"] if effect is None else problems_of(request, effect, context)
        if not found and effect is not None:
            kept.append(reading)
            runs.append(effect)
        first_problems = first_problems or found
    if not kept:
        return Verdict("refuse", first_problems, None, refusal(first_problems, context))
    if len(kept) == 1 and len(question.readings) > 1 and kept[0].confidence >= SURE_READING and not request.question \
            and _edits_named(kept[0], request):
        # two planners read it two ways and the request rules one out: the other is what it says
        return Verdict("apply", [f"the other readings misread it: {'; '.join(first_problems)}"],
                       outcome=runs[0].outcome, calls=list(kept[0].calls))
    return Verdict("ask", ["the planner could not tell which reading was meant"],
                   question.model_copy(update={"readings": kept}))


def _look_made_with(low: str, effect: Effect) -> bool:
    """Whether a look is said to come from what the plan adds, named after "with" ("make the Union
    look tidier with some greenery", "nicer with a few benches")."""
    said = re.search(r"\bwith\b(.*)$", low)
    if said is None or not effect.added or effect.removed:
        return False
    named = {m.category for m in ph.find_categories(said.group(1))} | _concepts_said(said.group(1))
    return all(a.category in named for a in effect.added)


# Clearing a place of whatever stands there, said without naming it: "clear lot B", "empty out the car park".
_CLEARS = re.compile(r"\b(?:clear|empty|clean)(?:ed|s|ing)?(?: out| up| off)?\s+(?:the |all of |everything (?:in|at|from|out of) )?(?!away\b)")


# A reading the request leaves standing alone is applied only when its planner was this sure of it.
SURE_READING = 0.8


def _edits_named(reading: Reading, request: Request) -> bool:
    """Whether a reading acts only on things the request names by kind or id (not on others it guessed)."""
    named = set(request.categories) | {m.group(0) for m in ASSET_ID.finditer(request.low)}
    touched = {str(c.args.get("category") or c.args.get("asset") or "") for c in reading.calls}
    touched |= {a.rsplit("_", 1)[0] for a in touched if re.search(r"_\d+$", a)}
    return bool(named) and all(t in named or t.rsplit("_", 1)[0] in named for t in touched if t)


def refusal(problems: list[str], context: PlanContext) -> str:
    """A refusal that says first what was not understood, then what is possible."""
    verbs = sorted({_FAMILY_VERB.get(f, f) for f in (context.registry.get(n).family for n in context.registry.names())})
    can = ", ".join(verbs[:-1]) + f" and {verbs[-1]}" if len(verbs) > 1 else "".join(verbs)
    return (f"I did not do it: {'; '.join(problems)}. I can {can} things in the scene; "
            "say it another way, e.g. naming the thing and the place")


# A Worker family as the verb a person reads in a refusal ("I can add, find and restyle things").
_FAMILY_VERB = {"appearance": "restyle", "search": "find", "position": "place"}


__all__ = ["Effect", "Verdict", "dry_run", "overridden", "problems_of", "refusal", "repairs", "review"]
