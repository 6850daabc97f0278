"""The scenario reader: requests that describe behaviour over time, as storyboard calls.

"The lead car brakes hard when the ego is 15 m behind it" is a trigger clause ("when ...",
"once ...", "as ...", "after 3 seconds", "two seconds in") and an action clause (an actor, a
manoeuvre verb and its numbers). The reader splits the two, finds the actor with
scenario_actors, reads the manoeuvre and the trigger into the scenario Workers' arguments
(tools/scenario.py: add_event, add_manoeuvre, set_light_phases), and dry-runs the calls. What
the words leave open that matters (which of two cars, turn which way) becomes a question with
the readings; what the Workers refuse (a bench cannot brake, no lane on the ego's right)
is a PlanningError saying why and what is possible. It never falls back to a static edit.
"""

from __future__ import annotations

import re
import time
from dataclasses import replace
from functools import cache
from typing import Any

from drivetwin.orchestrator.planning.base import Plan, PlanContext, PlanningError, Question, Reading, TraceStep
from drivetwin.orchestrator.planning.intent import asks, without_reason_first
from drivetwin.orchestrator.planning.readings import describe
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.spelling import edits, english_words, repair
from drivetwin.orchestrator.planning.scenario_actors import ROLE_WORDS, candidates, frame, head_category, motion
from drivetwin.orchestrator.planning.scenario_manoeuvres import (
    _COMPILED,
    _LIGHT_STATE,
    _LIGHT_WORDS,
    FASTER,
    HOLD_S,
    SLOWER,
    Manoeuvre,
    asks_unsupported,
    read_manoeuvre,
    refuse_unsupported,
)
from drivetwin.orchestrator.planning.scenario_newcomer import arrive, as_story, brings_in, hazard_story, parked_only
from drivetwin.orchestrator.planning.scenario_triggers import (
    DELAY,
    NOT_POSSIBLE_DELAY,
    TRIGGER,
    Timing,
    approach,
    mentions,
    read_trigger,
    split,
    steps,
)
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.scene import EGO_ID, AssetInstance, DriveLane, Scene

SCENARIO_TOOLS = ("add_event", "add_manoeuvre", "set_light_phases")
# Confidence of a reading whose every part was stated; each default the reader had to supply
# ("brakes" with no rate, "as the ego approaches" with no distance) costs DEFAULT_COST.
STATED_CONFIDENCE, DEFAULT_COST = 0.95, 0.1
_NUMBER_WORDS = {w: n for w, n in ph.NUMBER_WORDS.items()
                 if w not in ("a", "an", "single", "pair", "couple", "few", "some", "several")}
# The few words of this reader that the rule lexicon's spelling repair does not know.
_VOCABULARY = ("when", "once", "collision", "oncoming", "middle", "approaches", "overtakes", "seconds",
               "junction", "crossroads", "brakes", "pedestrian", "reverses", "accelerates", "behind")
_UNIT = r"(?:m|metres?|meters?|s|secs?|seconds?|km/h|kph|mph|m/s)"
_ADDING = re.compile(r"^\s*(please\s+)?(add|put|place|spawn|create|insert|bring in)\b")


def normalised(prompt: str, scene: Scene) -> str:
    """Lower-case words with typos repaired, number words as digits and units spaced ("15m")."""
    prompt = without_reason_first(prompt).strip() or prompt  # "my learner needs practice, so have the ego brake ...": what to do
    repaired = repair(re.sub(r"\b[uU][\s-]?turn", "uturn", prompt), scene)  # "U-turn" is one word, not "a turn"
    text = repaired.text
    for change in repaired.repairs:  # the lexicon's repair does not know manoeuvre verbs ("swerve")
        was, _, now = change.partition(" -> ")
        if was.lower().startswith(_MANOEUVRE_STEMS):
            text = re.sub(rf"\b{re.escape(now)}\b", was, text, count=1)
    low = ph.normalise(text)
    low = re.sub(r"[a-z]{3,}", lambda m: _repair_word(m.group(0)), low)
    low = re.sub(r"\b(" + "|".join(_NUMBER_WORDS) + r")\b(?=\s*(?:" + _UNIT[3:-1] + r"|,|$| and| " + _LIGHT_STATE + r"))",
                 lambda m: str(_NUMBER_WORDS[m.group(1)]), low)
    low = re.sub(r"(\d)(m|s|secs?|sec|seconds?|metres?)\b", r"\1 \2", low)
    low = re.sub(r"\b(?:metres?|meters?) (?:a|per|1) (?:second|sec)\b", "m/s", low)  # "4 metres a second"
    low = re.sub(r"\b(?:a |the )?(left|right) turn((?: [a-z]+){0,4}?) for (?:the ego|us|me)\b", r"the ego turns \1\2", low)  # "right turn for us"
    low = hazard_story(_stop_at_place(low, scene))
    return re.sub(r"\s+", " ", low.replace("²", "2").replace("^2", "2").replace(".", " . ")).strip()


# Stopping at a place of the world: "have the ego stop at the west crosswalk" is a stop when it gets there.
_STOP_AT = re.compile(r"\b(stops?|stopping|brakes?|braking|halts?|halting|pulls? up)(?:\s+(?:completely|fully|dead|there))?"
                      r"\s+(?:at|before|(?:just|right) before|short of|in front of|ahead of)\s+(?=the\s+)")


# A change of speed at a place: "slow to 5 m/s near the fountain", "speed up at the east gate".
_SPEED_AT = re.compile(r"\b((?:slows?|slowing|speeds?|speeding|accelerates?|accelerating|decelerates?|decelerating)"
                       r"(?:\s+(?:down|up))?(?:\s+to\s+\d+(?:\.\d+)?\s*(?:m/s|km/h|kmh|kph|mph))?)"
                       r"\s+(?:near|at|by|next to|outside|in front of|as it passes)\s+(?=the\s+)")


def _stop_at_place(low: str, scene: Scene) -> str:
    """`low` with "stop at <a landmark>" said as "stop when it gets to <it>", which a reach trigger
    reads, and so a change of speed at one ("slow to 5 m/s near the fountain")."""
    names = [ph.normalise(n).strip() for lm in scene.landmarks for n in lm.names()]
    said = _STOP_AT.search(low)
    if said is not None and any(low[said.end() :].startswith(f"the {n}") for n in names):
        verb = said.group(1) if said.group(1).startswith("brak") else "stop"  # "pull up", "halt": a stop
        return low[: said.start()] + f"{verb} when it gets to " + low[said.end() :]
    said = _SPEED_AT.search(low)
    if said is not None and any(low[said.end() :].startswith(f"the {n}") for n in names):
        return low[: said.start()] + f"{said.group(1)} when it gets to " + low[said.end() :]
    return low


def _repair_word(word: str) -> str:
    if word in _SLIPS:
        return _SLIPS[word]
    if word.startswith(_MANOEUVRE_STEMS):  # "decelerates" is two edits from "accelerates"
        return word
    if word in _VOCABULARY or len(word) < 3 or word in english_words():
        return word
    close = [v for v in _VOCABULARY if edits(word, v) <= (1 if len(word) < 6 else 2) and abs(len(v) - len(word)) <= 2]
    return close[0] if len(close) == 1 and not ph.find_categories(word) and word not in _KNOWN else word


# Real words one edit from the vocabulary that must stay as they are.
_KNOWN = frozenset({"then", "ones", "wheel", "brake", "once", "seconds", "second", "middle", "reverse",
                    "behind", "crossroad", "approach", "approached", "overtake", "collisions", "pedestrians", "junctions"})


# Setting off: what a trigger ("when the ego approaches") times as much as a manoeuvre.
_STARTS_MOVING = re.compile(r"\b(?:pull(?:s|ing)? (?:out|away|off)|(?:drive|drives|driving) (?:off|away)|sets? off|set(?:s|ting)? off"
                            r"|starts? (?:moving|driving|walking|to (?:move|drive|walk))|moves? off|gets? going|departs?|leaves?)\b")


@cache
def _thing_names() -> re.Pattern[str]:
    """The catalog's names of things in more than one word ("stop sign", "halt sign"), longest
    first: a manoeuvre's word inside one names no manoeuvre. Lamps and signals are left out: the
    light words read them."""
    names = {n.replace("_", " ") for e in catalog().values() for n in (e.name, *e.synonyms)}
    kept = sorted((n for n in names if " " in n and not re.search(r"light|lamp|signal", n)), key=len, reverse=True)
    return re.compile(rf"\b(?:{'|'.join(map(re.escape, kept))})s?\b")


# "as it is", "as they are", "as is": how a thing is left, never a moment things happen at.
_AS_IT_IS = re.compile(r"\bas (?:it|they|that|this) (?:is|are|was|were|stands?)\b|\bas is\b")
# Lamps or lights switched on or off ("have the lamps turned off"); not "turn off at the junction".
_LAMPS_SWITCHED = re.compile(r"\b(?:(?:street ?|head|vehicle |car )?lights?|(?:street ?)?lamps?|lamp posts?)\s+(?:\w+\s+)?"
                             r"(?:turned|switched|flicked|turn|switch)\s+(?:on|off)\b")
# A command that puts a thing somewhere, not a description of what it does.
_PLACING = re.compile(r"\s*(?:(?:please|pls|now|just|can you|could you)\s+)*(?:move|put|place|shift|set|stand|drag|carry|relocate|bring)\b")


def describes_behaviour_over_time(text: str, scene: Scene | None = None) -> bool:
    """Whether the words describe something happening over time: a trigger ("when the ego is
    15 m away", "after 3 seconds") with an action, or a manoeuvre only a storyboard can play
    (braking, cutting in, changing lanes, overtaking, turning at a junction, a traffic light
    changing or cycling). With the scene, typos are repaired first. A request to add an asset
    that only names its behaviour ("add a car overtaking") is not, nor is a question."""
    low = normalised(text, scene) if scene is not None else ph.normalise(text)
    low = re.sub(r"[a-z]+", lambda m: _SLIPS.get(m.group(0), m.group(0)), low)
    for name in (n for place in (scene.landmarks if scene is not None else []) for n in place.names()):
        low = re.sub(rf"\b{re.escape(ph.normalise(name).strip())}\b", " place ", low)  # "bus stop" is no stop
    low = _thing_names().sub(" thing ", low)  # "the stop sign" is no stop
    low = _AS_IT_IS.sub(" ", low)  # "leave the bin as it is": no "as the ego approaches"
    low = _LAMPS_SWITCHED.sub(" ", low)  # "the lamps turned off": switched, not a turn at the junction
    trigger = bool(TRIGGER.search(low) and re.search(r"\b(ego|it|car|m|metres?|meters?|seconds?|approach\w*)\b", low)) \
        or bool(DELAY.search(low))
    manoeuvre = any(words.search(low) for kind, words in _COMPILED[1:])
    if _ADDING.match(low) and not trigger:
        return False
    # "can the ego turn left at the crossroads?" asks for it to be done; "the light goes red?" asks
    polite = re.match(r"\s*(?:[a-z' ]{0,25},\s*)?(?:(?:sorry|please|so|ok|okay)\W+)*(?:can|could|would|will)\b", low) is not None
    if re.match(r"\s*(what|which|where|how|is|are|does|do)\b", low) or (low.rstrip().endswith("?") and not polite) or asks(low):
        return False
    light = bool(_LIGHT_WORDS.search(re.sub(r"\bstreet lights?\b", " ", low))) and not re.search(
        r"\b(paint|colou?r|recolou?r|move|remove|add|put|turn (it )?(on|off))\w*\b", low)
    light_change = light and bool(re.search(rf"\b{_LIGHT_STATE}\b|\b(cycle|phases?|work|working)\b"
                                            r"|\b(stop|wait)\w*\b[^,.;]*\bat (the|a) (red )?(traffic )?lights?\b", low))
    # A crossing aimed at the ego ("in front of the ego", "out from behind the bus") is timed
    # against the ego's approach, which only a storyboard event can do.
    # "Jaywalk" names the static behaviour that already waits for the ego (set_behaviour).
    crossing = re.sub(r"\bjaywalk\w*", " ", low)
    at_the_ego = bool(_AT_THE_EGO.search(low)) and any(
        words.search(crossing) for kind, words in _COMPILED if kind in ("cross_road", "stop_mid_road"))
    starts = bool(_STARTS_MOVING.search(low))  # "the suv pulls out as the ego approaches": then, not now
    # "move the bin onto the sidewalk" puts a thing somewhere; "the car mounts the kerb" is a manoeuvre
    unsupported = asks_unsupported(low) and not _PLACING.match(low)
    # "When the ego comes, someone on foot must go over the street ...": an action timed against the ego, however said
    ego_when = _EGO_WHEN.match(low)
    timed = ego_when is not None and bool(_MOTION.search(ego_when.group("rest")))
    return (trigger and (manoeuvre or starts)) or timed or light_change or at_the_ego or unsupported or any(
        words.search(low) for kind, words in _COMPILED if kind in _ONLY_STORYBOARD)


# Manoeuvres no static behaviour can stand for (a bare "stop", "cross" or "reverse" can).
_ONLY_STORYBOARD = frozenset({"cut_in", "overtake", "lane_change", "junction_turn", "change_speed", "brake",
                              "stop_mid_road"})
# A sentence that opens with when the ego does something ("When the ego comes, ..."), and what follows it.
_EGO_WHEN = re.compile(r"\s*(?:when|once|as soon as|whenever)\s+(?:the\s+|our\s+)?ego\b[^,;.]*[,;]\s*(?P<rest>[^.;]*)")
_MOTION = re.compile(r"\b(?:go(?:es)?|walk\w*|run\w*|step\w*|mov(?:e|es|ing)|head\w*|dash\w*|dart\w*|cross\w*|pull\w*|drive\w*"
                     r"|ride\w*|stop\w*|brake\w*)\b")
_AT_THE_EGO = re.compile(r"\b(?:in front of|ahead of|into the path of|across the path of) (?:the )?ego\b|\bego's (?:path|lane)\b"
                         r"|\bout from behind\b|\bfrom behind (?:the|a|an)\b")


# Slips that are words of their own ("wen"), so only a trigger reader would repair them.
_SLIPS = {"wen": "when", "whn": "when", "wehn": "when", "onse": "once", "aftr": "after", "untill": "until"}
# Stems of manoeuvre verbs the rule lexicon's spelling repair would turn into other words.
_MANOEUVRE_STEMS = ("swerv", "merg", "brak", "overtak", "revers", "accelerat", "decelerat", "jaywalk", "dart", "slam",
                    "drift", "veer", "uturn")


_ROLE = re.compile(r"\b(" + "|".join(sorted(ROLE_WORDS, key=len, reverse=True)) + r")\b")
# What the scenario Workers can do, for refusals.
POSSIBLE = ("a scenario can make a vehicle brake, change speed, change lanes, cut in, turn at the junction or "
            "reverse, a pedestrian cross the road or stop in it, and a traffic light change or cycle, each at a "
            "time, at a distance or time to collision between two actors, or when an actor reaches a place")
# Openings before the action: "and then", "sorry, can ...", "please make", "I want", "could you have".
_LEADING = re.compile(r"^(?:(?:and|then|so|now|sorry|ok|okay|please)\s*,?\s+)*(?:[a-z' ]{0,25},\s+(?=(?:can|could|would|will)\b))?"
                      r"(?:(?:can|could|would|will)\s+(?:you\s+)?(?:please\s+)?)?"
                      r"(?:(?:i |we )?(?:want|need) |i'd like |(?:i|we) (?:should|would) like |we'd like )?"
                      r"(?:make|have|let|get|see that|ensure)?\s*")
_TRAILING_MODAL = re.compile(r"(?:\s*\b(?:should|will|must|has to|needs to|is going to|is to|to|would|suddenly|then|just"
                             r"|also|quickly|slowly|gently|hard|abruptly))+\s*$")


class ScenarioReader:
    """Plans requests that describe behaviour over time as add_event / add_manoeuvre /
    set_light_phases calls; raises PlanningError when the words are not such a scenario."""

    name = "scenario"

    def plan(self, prompt: str, context: PlanContext) -> Plan:
        """The storyboard calls for `prompt`, a question when it names several readings, or
        PlanningError saying what could not be read and what is possible."""
        started = time.perf_counter()
        scene = context.scene
        low = normalised(prompt, scene)
        story = as_story(low)  # "add a pedestrian that crosses when ...": a newcomer's story
        if _ADDING.match(low) and story is None:
            raise PlanningError("this adds an asset; add it first, then describe what it does over time")
        timing = split(story or low)
        refuse_unsupported(timing.action)
        first, later = steps(_LEADING.sub("", timing.action.strip(" ,.")).strip())
        timing, later = _delay_of_a_later_step(story or low, timing, later)
        timing, late_trigger = _trigger_of_a_later_step(story or low, timing, later)
        arrived: list[ToolCall] = []
        try:
            readings = _stories(first, later, timing, scene, late_trigger)
        except _NoActor as missing:
            if not brings_in(missing.subject):
                raise
            # "a pedestrian steps out in front of the ego" with none there: one is brought in
            arrival = arrive(missing.subject, first[missing.verb_at :], scene, context.registry)
            arrived = [arrival.call]
            readings = _stories(f"{arrival.id} {first[missing.verb_at :]}", later, timing, arrival.scene, late_trigger)
        readings = [([*arrived, *calls], defaults) for calls, defaults in readings]
        fine = [(c, d) for c, d in readings if context.check(c) is None]
        step = TraceStep(level="scenario", input=f"action {first!r}; then {later}; trigger {timing.trigger!r}; "
                         f"delay {timing.delay}", output=f"{len(fine)} of {len(readings)} readings accepted by a dry run",
                         seconds=time.perf_counter() - started)
        if not fine:
            refused = context.check(readings[0][0]) or "refused"
            raise PlanningError(f"{refused}; {POSSIBLE}")
        if len(fine) > 1:
            question = Question(text="Which did you mean?", readings=[
                Reading(text=describe(c), calls=c) for c, _ in fine[:3]])
            return Plan(calls=[], planner=self.name, confidence=0.0, question=question, trace=[step])
        calls, defaults = fine[0]
        guessed = defaults + int(len(readings) > 1)
        return Plan(calls=calls, planner=self.name, confidence=max(0.0, STATED_CONFIDENCE - DEFAULT_COST * guessed),
                    trace=[step])


def _delay_of_a_later_step(said: str, timing: Timing, later: list[tuple[str, float | None]]) -> tuple[Timing, list[tuple[str, float | None]]]:
    """The story's time said after its second step ("cruises at 4 m/s and swings into the left lane
    at 6 s"): the second step's, counted from the start; the first starts at once."""
    delay = DELAY.search(said)
    if not later or timing.delay is None or timing.vague or timing.trigger is not None or later[0][1] is not None or delay is None:
        return timing, later
    second = said.find(later[0][0][:12])
    if second < 0 or delay.start() < second:
        return timing, later
    return replace(timing, delay=None), [(later[0][0], timing.delay), *later[1:]]


def _trigger_of_a_later_step(said: str, timing: Timing, later: list[tuple[str, float | None]]) -> tuple[Timing, str | None]:
    """The story's condition said after its second step ("drive at 36 km/h and stop before the west
    crosswalk"): the second step's, the first starting at once; None when it is the first step's."""
    if timing.trigger is None or len(later) != 1 or later[0][1] is not None:
        return timing, None
    second, at = said.find(later[0][0][:12]), said.find(timing.trigger)
    if second < 0 or at < second:
        return timing, None
    return replace(timing, trigger=None), timing.trigger


def _stories(first: str, later: list[tuple[str, float | None]], timing: Timing, scene: Scene,
             late_trigger: str | None = None) -> list[tuple[list[ToolCall], int]]:
    """Each reading of the story's calls with the defaults it needed: its first step, then each later
    one (the last on `late_trigger`, a condition said after it, when there is one)."""
    readings: list[tuple[list[ToolCall], int]] = []
    for actor, manoeuvre, spec, done_to in _readings(first, scene):
        calls, defaults = _calls(actor, manoeuvre, spec, timing, done_to, scene)
        for words, gap in later:  # "..., and let it change to the left lane": "it change to the left lane"
            calls = _followed_by(calls, actor, _LET.sub("", words), gap, scene)
        if late_trigger is not None and (doer := scene.asset(str(calls[-1].args.get("actor")))) is not None:
            when, guessed = read_trigger(late_trigger, doer, scene, None)  # "... and stop before the west crosswalk"
            calls = [*calls[:-1], ToolCall(tool="add_event", args={"actor": doer.id, "manoeuvre": calls[-1].args["manoeuvre"], "when": when})]
            defaults += guessed
        readings.append((calls, defaults + manoeuvre.defaults + int(timing.vague)))
    readings = [(_steady_speed_as_setting(calls, scene), defaults) for calls, defaults in readings]
    lit = [calls for calls, _ in readings if [c.tool for c in calls] == ["set_light_phases"]]
    if len(lit) == len(readings) > 1 and len({c[0].args["light"] for c in lit}) == len(lit) and _is_light_request(first) \
            and (_EVERY_LIGHT.search(first) or all(c[0].args["light"] in first for c in lit)):
        return [([c for calls in lit for c in calls], max(d for _, d in readings))]  # every light said: all of them at once
    return readings


# A later step said as what to allow or make happen: "and let it change lanes", "then have the car brake".
_LET = re.compile(r"^\s*(?:let|have|make|get)\s+(?=(?:it|him|her|them|the|that|this)\b)")


def _steady_speed_as_setting(calls: list[ToolCall], scene: Scene) -> list[ToolCall]:
    """A story that opens on a steady speed from the start ("drives at 6 m/s and changes to the
    left lane at 5 s", "4 m/s, then turn right at the junction"), with its later steps timed from
    the start or the same actor's next: that speed is the lane behaviour's, set now, as "the ego
    drives at 6 m/s" alone sets it, and the steps after it come at their times or places."""
    first, rest = calls[0], calls[1:]
    spec = first.args.get("manoeuvre", {})
    actor = scene.asset(str(first.args.get("actor")))
    if first.tool != "add_manoeuvre" or spec.get("kind") != "keep_lane" or "speed" not in spec or first.args.get("at_time") \
            or not rest or actor is None or not isinstance(actor.behaviour, DriveLane) \
            or any("at_time" not in c.args and "when" not in c.args and not (c.args.get("after_previous") and c.args.get("actor") == actor.id
                                                                            and c.args["manoeuvre"].get("kind") == "junction_turn") for c in rest):
        return calls
    behaviour = {**actor.behaviour.model_dump(), "speed": spec["speed"]}
    # "4 m/s, then turn right at the junction": the turn comes where the junction is (a brake after a cruise stays next)
    rest = [ToolCall(tool=c.tool, args={k: v for k, v in c.args.items() if k != "after_previous"}) for c in rest]
    return [ToolCall(tool="set_behaviour", args={"asset": actor.id, "behaviour": behaviour}), *rest]


class _NoActor(PlanningError):
    """No actor in the scene fits the subject (`subject`, its verb at `verb_at` of the action)."""

    def __init__(self, message: str, subject: str, verb_at: int) -> None:
        super().__init__(message)
        self.subject, self.verb_at = subject, verb_at


def _readings(action: str, scene: Scene, doer: AssetInstance | None = None
              ) -> list[tuple[AssetInstance, Manoeuvre, dict[str, Any], str | None]]:
    """Each (actor, manoeuvre, spec, what it is done to) the action clause may mean, up to three
    actors; a clause with no subject is done by `doer` (the actor of the step before), else the ego."""
    if _is_light_request(action):
        actors, verb_at, kind = _lights_meant(action, scene), 0, "light"
    else:
        verb_at = _first_verb(action)
        subject = _TRAILING_MODAL.sub("", action[:verb_at]).strip()
        verb_at = len(_TRAILING_MODAL.sub("", action[:verb_at]))  # "should suddenly brake": the adverb counts
        if (not subject or subject in ("it", "he", "she", "they")) and doer is not None:  # "... and then it brakes"
            actors, what = [doer], doer.id
        else:
            actors, what = candidates(subject or "the ego", scene, moving_manoeuvre=True)
            heads = [m.start() for m in re.finditer(r"\b(?:the|our|my|that)\b", subject)]
            if not actors and heads and heads[-1] > 0:  # "this time round the ego ...": the thing named last
                actors, _ = candidates(subject[heads[-1]:], scene, moving_manoeuvre=True)
        if not actors or (brings_in(subject) and parked_only(actors, read_manoeuvre(action[verb_at:], motion(actors[0])).kind)):
            raise _NoActor(f"there is no {what} in the scene to act; {POSSIBLE}", subject, verb_at)
        kind = motion(actors[0])
    manoeuvre = read_manoeuvre(action[verb_at:] if kind != "light" else action, kind)
    out = []
    for actor in actors[:3]:
        done_to = _done_to(action, verb_at, actor, scene) if kind != "light" else None
        choices = manoeuvre.choices or [("", manoeuvre.spec)]
        if manoeuvre.kind == "lane_change" and manoeuvre.choices and done_to is not None:
            choices = [c for c in choices if c[1]["side"] == _side_of(done_to, actor, scene)] or choices
        out += [(actor, manoeuvre, _with_speed(spec, actor, text), done_to) for text, spec in choices]
    return out


def _done_to(action: str, verb_at: int, actor: AssetInstance, scene: Scene) -> str | None:
    """What the action is done to ("overtakes it", "into the ego's lane"): the first thing named
    after the verb; a pronoun there is the last thing the subject named besides the actor."""
    named_in_subject = [i for i in mentions(action[:verb_at], actor, scene) if i != actor.id]
    pronoun = named_in_subject[-1] if named_in_subject else None
    after = [i for i in mentions(action[verb_at:], actor, scene, pronoun=pronoun) if i != actor.id]
    return after[0] if after else None


def _side_of(other_id: str, actor: AssetInstance, scene: Scene) -> str | None:
    other = scene.asset(other_id)
    if other is None:
        return None
    return "left" if frame(other, actor).left > 0 else "right"


def _is_light_request(action: str) -> bool:
    words = re.sub(r"\bstreet lights?\b", " ", action)
    if not _LIGHT_WORDS.search(words):
        return False
    subject = words[: _first_verb(words, strict=False)]
    head = head_category(subject) if subject.strip() else None
    if head not in (None, "traffic_light") and not re.match(r"\s*(the )?ego\b", subject):
        return False  # "the car stops at the red light": the car acts
    return bool(re.search(rf"\b{_LIGHT_STATE}\b|\b(cycle|phases?|work|working|stop|wait|halt)\b", words))


def _first_verb(action: str, strict: bool = True) -> int:
    # A verb word between an article and the subject's noun describes it ("the crossing car").
    noun = re.search(r"\b(?:the|a|an|that|this) (?:[a-z]+ )?(?=ego\b|[a-z]+_\d+\b)", action)
    verbs = [m for kind, words in _COMPILED if kind != "light" for m in words.finditer(action)]
    # A noun inside a verb's own words ("slows to a stop") is not the subject.
    found = [m.start - 1 for m in ph.find_categories(action) if not any(v.start() <= m.start - 1 < v.end() for v in verbs)]
    role = _ROLE.search(action)
    head = min([*found[:1], *(m.end() for m in [noun] if m), *(m.start() for m in [role] if m)], default=0)
    starts = [m.start() for m in verbs
              if m.start() >= head or not re.search(r"\b(?:the|a|an|that|this)\s+(?:[a-z]+\s+)?$", action[: m.start()])]
    if not starts:
        if not strict:
            return len(action)
        raise PlanningError(f"I could not tell what should happen in {action!r}; {POSSIBLE}")
    return min(starts)


# Traffic lights said in the plural ("make the traffic lights red", "both signals"): every one of them.
_EVERY_LIGHT = re.compile(r"\b(?:traffic (?:lights|signals)|signals|(?:both|all|all the) (?:traffic )?(?:lights|signals)"
                          r"|every (?:traffic )?(?:light|signal))\b")


def _lights_meant(action: str, scene: Scene) -> list[AssetInstance]:
    """The light named by id, every light when they are said in the plural, else the one the ego
    meets next (ahead of it, on its right)."""
    lights = [a for a in scene.assets if a.category == "traffic_light"]
    named = [a for a in lights if a.id in action]
    if named or (lights and _EVERY_LIGHT.search(action)):
        return named or lights
    ego = scene.asset(EGO_ID)
    if ego is None or not lights:
        if not lights:
            raise PlanningError("there is no traffic light in this world to change")
        return lights
    ahead = [a for a in lights if frame(a, ego).ahead > 0 and frame(a, ego).left < 0]
    return sorted(ahead, key=lambda a: frame(a, ego).ahead)[:1] or lights


def _with_speed(spec: dict[str, Any], actor: AssetInstance, choice: str) -> dict[str, Any]:
    """A speed change with no target speed: FASTER or SLOWER times the actor's current speed."""
    if spec.get("kind") != "change_speed" or "speed" in spec:
        return spec
    now = float(getattr(actor.behaviour, "speed", 0.0) or 5.0)
    return {**spec, "speed": round(now * (SLOWER if choice == "slower" else FASTER), 1)}


def _followed_by(calls: list[ToolCall], actor: AssetInstance, words: str, gap: float | None,
                 scene: Scene) -> list[ToolCall]:
    """`calls` with the next step of the story added: `gap` seconds after a timed step, or
    right when the step before ends (the same actor's next manoeuvre, or another actor's
    event on the end of it). A time after a step that waits for a condition cannot be played."""
    (doer, _, spec, _), *_ = _readings(words, scene, doer=actor)
    before = calls[-1]
    if gap is not None:
        if before.tool != "add_manoeuvre" or before.args.get("after_previous"):
            raise PlanningError(NOT_POSSIBLE_DELAY)
        at = float(before.args.get("at_time", 0.0)) + gap
        return [*calls, ToolCall(tool="add_manoeuvre", args={"actor": doer.id, "manoeuvre": spec, "at_time": at})]
    if before.tool == "set_light_phases":
        raise PlanningError("a light's cycle has no end to wait for; say when the next step starts")
    if doer.id == str(before.args["actor"]):
        return [*calls, ToolCall(tool="add_manoeuvre", args={"actor": doer.id, "manoeuvre": spec, "after_previous": True})]
    name = scene.storyboard.next_event_name(f"{before.args['actor']}_{before.args['manoeuvre']['kind']}")
    named = ToolCall(tool=before.tool, args={**before.args, "name": name})
    return [*calls[:-1], named, ToolCall(tool="add_event", args={
        "actor": doer.id, "manoeuvre": spec, "when": {"kind": "after_event", "event": name}})]


def _calls(actor: AssetInstance, manoeuvre: Manoeuvre, spec: dict[str, Any], timing: Timing, done_to: str | None,
           scene: Scene) -> tuple[list[ToolCall], int]:
    """The first step's call and how many defaults its trigger needed."""
    trigger, delay = timing.trigger, timing.delay
    if manoeuvre.kind == "light" and manoeuvre.phases is not None:
        return [ToolCall(tool="set_light_phases", args={"light": actor.id, "phases": manoeuvre.phases})], 0
    if manoeuvre.kind == "set_light" and trigger is None and delay is None:
        phases = [{"state": spec["state"], "duration": HOLD_S}]
        return [ToolCall(tool="set_light_phases", args={"light": actor.id, "phases": phases})], 0
    if spec.get("kind") == "cut_in":
        spec = {**spec, "target": done_to or EGO_ID}
    if trigger is not None:
        when, defaults = read_trigger(trigger, actor, scene, done_to)
        return [ToolCall(tool="add_event", args={"actor": actor.id, "manoeuvre": spec, "when": when})], defaults
    if delay is None and spec.get("kind") in _INTO_THE_ROAD and scene.asset(EGO_ID) is not None:
        # A walker stepping into the road in a scenario does it as the ego comes, not at once.
        when = approach(EGO_ID, actor.id)
        return [ToolCall(tool="add_event", args={"actor": actor.id, "manoeuvre": spec, "when": when})], 1
    args: dict[str, Any] = {"actor": actor.id, "manoeuvre": spec}
    if delay:
        args["at_time"] = delay
    return [ToolCall(tool="add_manoeuvre", args=args)], 0


# Walker manoeuvres into the ego's road; with no time said they start on the ego's approach.
_INTO_THE_ROAD = frozenset({"cross_road", "stop_mid_road"})


__all__ = ["POSSIBLE", "SCENARIO_TOOLS", "ScenarioReader", "describes_behaviour_over_time", "normalised"]
