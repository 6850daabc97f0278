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
from dataclasses import dataclass
from typing import Any

from drivetwin.orchestrator.planning.base import Plan, PlanContext, PlanningError, Question, Reading, TraceStep
from drivetwin.orchestrator.planning.readings import describe
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.numbers import finite
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
    _unit_number,
    read_manoeuvre,
)
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Scene

SCENARIO_TOOLS = ("add_event", "add_manoeuvre", "set_light_phases")
# Confidence of a reading whose every part was stated; each default the reader had to supply
# ("brakes" with no rate, "as the ego approaches" with no distance) costs DEFAULT_COST.
STATED_CONFIDENCE, DEFAULT_COST = 0.95, 0.1
# "As the ego approaches" / "gets close": the distance at which it counts as approaching or
# close; at the campus's 5 m/s an approach of 30 m leaves 6 s, close 15 m leaves 3 s.
APPROACH_M, CLOSE_M = 30.0, 15.0
# "Dangerously close": a time to collision this short (s) is the usual critical threshold.
DANGER_TTC_S = 2.0
# "After a bit" / "shortly": a delay long enough to see the scene settle first (s).
VAGUE_DELAY_S = 3.0
_NUMBER_WORDS = {w: n for w, n in ph.NUMBER_WORDS.items()
                 if w not in ("a", "an", "single", "pair", "couple", "few", "some", "several")}
_NUMBER_WORDS |= {"thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "eleven": 11, "eighteen": 18}
# The few words of this reader that the rule lexicon's spelling repair does not know.
_VOCABULARY = ("when", "once", "collision", "oncoming", "middle", "approaches", "overtakes", "seconds",
               "junction", "crossroads", "brakes", "pedestrian", "reverses", "accelerates", "behind")
_UNIT = r"(?:m|metres?|meters?|s|secs?|seconds?|km/h|kph|mph|m/s)"
_TRIGGER = re.compile(r"\b(as soon as|whenever|when|once|as|if|until)\b|\b(?:just\s+)?before\b"
                      r"(?=[^,.;]*\b(?:gets?|reach(?:es)?|arrives?|comes?)\b)")
_DELAY = re.compile(r"\b(?:after|in|at)\s+(?:t\s*=\s*)?(\d+(?:\.\d+)?)\s*(?:s|secs?|seconds?)\b"
                    r"|\b(\d+(?:\.\d+)?)\s*(?:s|secs?|seconds?)\s+in\b"
                    r"|\b(after a (?:bit|while|moment)|shortly|in a (?:bit|moment|while)|a bit later|soon)\b")
_MODAL = re.compile(r"\b(should|will|must|has to|needs to|is to|to)\b")
_ADDING = re.compile(r"^\s*(please\s+)?(add|put|place|spawn|create|insert|bring in)\b")


def normalised(prompt: str, scene: Scene) -> str:
    """Lower-case words with typos repaired, number words as digits and units spaced ("15m")."""
    repaired = repair(prompt, scene)
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
    return re.sub(r"\s+", " ", low.replace("²", "2").replace("^2", "2").replace(".", " . ")).strip()


def _repair_word(word: str) -> str:
    if word in _SLIPS:
        return _SLIPS[word]
    if word in _VOCABULARY or len(word) < 3 or word in english_words():
        return word
    close = [v for v in _VOCABULARY if edits(word, v) <= (1 if len(word) < 6 else 2) and abs(len(v) - len(word)) <= 2]
    return close[0] if len(close) == 1 and not ph.find_categories(word) and word not in _KNOWN else word


# Real words one edit from the vocabulary that must stay as they are.
_KNOWN = frozenset({"then", "ones", "wheel", "brake", "once", "seconds", "second", "middle", "reverse",
                    "behind", "crossroad", "approach", "approached", "overtake", "collisions", "pedestrians", "junctions"})


def describes_behaviour_over_time(text: str, scene: Scene | None = None) -> bool:
    """Whether the words describe something happening over time: a trigger ("when the ego is
    15 m away", "after 3 seconds") with an action, or a manoeuvre only a storyboard can play
    (braking, cutting in, changing lanes, overtaking, turning at a junction, a traffic light
    changing or cycling). With the scene, typos are repaired first. A request to add an asset
    that only names its behaviour ("add a car overtaking") is not, nor is a question."""
    low = normalised(text, scene) if scene is not None else ph.normalise(text)
    low = re.sub(r"[a-z]+", lambda m: _SLIPS.get(m.group(0), m.group(0)), low)
    trigger = bool(_TRIGGER.search(low) and re.search(r"\b(ego|it|car|m|metres?|meters?|seconds?|approach\w*)\b", low)) \
        or bool(_DELAY.search(low))
    manoeuvre = any(words.search(low) for kind, words in _COMPILED[1:])
    if _ADDING.match(low) and not trigger:
        return False
    if re.match(r"\s*(what|which|where|how|is|are|does|do)\b", low) or low.rstrip().endswith("?"):
        return False
    light = bool(_LIGHT_WORDS.search(re.sub(r"\bstreet lights?\b", " ", low))) and not re.search(
        r"\b(paint|colou?r|recolou?r|move|remove|add|put|turn (it )?(on|off))\w*\b", low)
    light_change = light and bool(re.search(rf"\b{_LIGHT_STATE}\b|\b(cycle|phases?|work|working)\b"
                                            r"|\b(stop|wait)\w*\b[^,.;]*\bat (the|a) (red )?(traffic )?lights?\b", low))
    return (trigger and manoeuvre) or light_change or any(
        words.search(low) for kind, words in _COMPILED if kind in _ONLY_STORYBOARD)


# Manoeuvres no static behaviour can stand for (a bare "stop", "cross" or "reverse" can).
_ONLY_STORYBOARD = frozenset({"cut_in", "overtake", "lane_change", "junction_turn", "change_speed", "brake"})


def split(low: str) -> tuple[str, str | None, float | None, bool]:
    """(action clause, trigger clause or None, delay in seconds or None, whether the delay is vague)."""
    delay: float | None = None
    vague = False
    found = _DELAY.search(low)
    if found:
        delay = float(found.group(1) or found.group(2)) if not found.group(3) else VAGUE_DELAY_S
        vague = found.group(3) is not None
        low = (low[: found.start()] + " " + low[found.end():]).strip(" ,")
    marker = _TRIGGER.search(low)
    while marker is not None and marker.group(1) == "as" and re.match(r"\s*(well|a|an|soon|much|far)\b", low[marker.end():]):
        marker = _TRIGGER.search(low, marker.end())
    if marker is None:
        return low, None, delay, vague
    before, after = low[: marker.start()].strip(" ,"), low[marker.end():].strip()
    if before and re.search(r"[a-z]", before) and not re.fullmatch(r"(then|and|so|but)", before):
        return before, re.split(r"\s*[,;.]\s*|\bthen\b", after)[0], delay, vague
    comma = re.search(r"\s*[,;]\s*|\bthen\b", after)
    if comma:
        return after[comma.end():].strip(), after[: comma.start()], delay, vague
    modal = [m for m in _MODAL.finditer(after)]
    if modal:
        articles = [a for a in re.finditer(r"\b(the|a|an|that)\b", after[: modal[0].start()])]
        if len(articles) > 1:
            cut = articles[-1].start()
            return after[cut:], after[:cut], delay, vague
    raise PlanningError(f"I could not tell where the condition ends in {low!r}; put a comma after it, "
                        "e.g. 'when the ego is 20 m away, the car brakes'")


# Slips that are words of their own ("wen"), so only a trigger reader would repair them.
_SLIPS = {"wen": "when", "whn": "when", "wehn": "when", "onse": "once", "aftr": "after", "untill": "until"}
# Stems of manoeuvre verbs the rule lexicon's spelling repair would turn into other words.
_MANOEUVRE_STEMS = ("swerv", "merg", "brak", "overtak", "revers", "accelerat", "decelerat", "jaywalk", "dart", "slam")
_ROLE = re.compile(r"\b(" + "|".join(sorted(ROLE_WORDS, key=len, reverse=True)) + r")\b")


def _mask_ego(text: str) -> str:
    for word in ph.EGO_WORDS:
        text = re.sub(rf"(?<![a-z]){re.escape(word)}(?![a-z])", " ego ", text)
    return re.sub(r"\s+", " ", text)


def mentions(text: str, actor: AssetInstance, scene: Scene) -> list[str]:
    """The asset ids a clause names, in order: the ego, ids, pronouns (the actor), categories."""
    text = _mask_ego(text)
    found: list[tuple[int, str]] = [(m.start(), EGO_ID) for m in re.finditer(r"\bego\b", text)]
    found += [(m.start(), actor.id) for m in re.finditer(r"\b(it|its|itself|that one)\b", text)]
    found += [(m.start(), m.group(1)) for m in re.finditer(r"\b([a-z]+(?:_[a-z]+)*_\d+)\b", text)
              if scene.asset(m.group(1)) is not None]
    # find_categories reads its own normalised copy (one leading space): its spans are one on.
    named = [(m.start - 1, m.category) for m in ph.find_categories(text)]
    named += [(m.start(), ROLE_WORDS[m.group(1)]) for m in _ROLE.finditer(text)]
    for start, head in named:
        if any(abs(start - s) < 2 for s, _ in found):
            continue
        if actor.category == head:
            found.append((start, actor.id))
        else:
            pool, _ = candidates(text[start:], scene, moving_manoeuvre=False)
            if pool:
                found.append((start, pool[0].id))
    ordered = [i for _, i in sorted(found)]
    return [i for n, i in enumerate(ordered) if n == 0 or ordered[n - 1] != i]


_TTC = re.compile(r"time.to.collision|\bttc\b|from (?:hitting|colliding|crashing|reaching|impact)|dangerously close"
                  r"|about to (?:hit|collide)")
_APPROACH = re.compile(r"\bapproach\w*|\b(?:gets?|comes?|is|draws?) (?:close|near|nearer|closer)\b|\bnears\b|\bcloses in\b"
                       r"|\bgets? there\b|\bcomes? near\b|\bgets? within\b|\bclos\w* (?:to|on)\b")
_REACH = re.compile(r"\b(?:reach\w*|gets? to|arriv\w* at|enters?|passes)\b")
_ENDED = re.compile(r"\b(?:has )?(?:stopp?ed|stops|finish\w*|ends|is done|has ended)\b")


def read_trigger(trigger: str, actor: AssetInstance, scene: Scene) -> tuple[dict[str, Any], int]:
    """The add_event `when` for a trigger clause, and how many defaults it needed."""
    named = mentions(trigger, actor, scene)
    watched = named[0] if named else EGO_ID
    other = next((i for i in named[1:] if i != watched), actor.id if watched != actor.id else EGO_ID)
    seconds = _unit_number(trigger, r"s|secs?|seconds?")
    metres = _unit_number(trigger, r"m|metres?|meters?")
    if _TTC.search(trigger):
        stated = seconds is not None
        value = finite(seconds, "a time to collision in seconds") if seconds is not None else DANGER_TTC_S
        return {"kind": "time_to_collision", "actor": watched, "other": other, "seconds": value}, 0 if stated else 1
    if metres is not None:
        rule = "greater" if re.search(r"\b(more than|further|farther|beyond|over|at least)\b", trigger) else "less"
        return {"kind": "distance", "actor": watched, "other": other,
                "metres": finite(metres, "a distance in metres"), "rule": rule}, 0
    from drivetwin.orchestrator.planning.rules.reading import find_place

    place = find_place(scene, f" {trigger} ")
    if _REACH.search(trigger) and place is not None and not _APPROACH.search(trigger):
        return {"kind": "reach", "actor": watched, "place": place[0]}, 0
    if _ENDED.search(trigger) and watched != actor.id:
        earlier = [e.name for a, e in scene.storyboard.events() if a == watched]
        if earlier:
            return {"kind": "after_event", "event": earlier[-1]}, 0
    if _APPROACH.search(trigger):
        near = APPROACH_M if re.search(r"\bapproach|\bthere\b", trigger) else CLOSE_M
        return {"kind": "distance", "actor": watched, "other": other, "metres": near}, 1
    raise PlanningError(f"I could not tell when it should happen from {trigger!r}; a manoeuvre can start after a "
                        "number of seconds, when two actors are a distance apart or a time to collision away, "
                        "when an actor reaches a place, or when another event ends")


# What the scenario Workers can do, for refusals.
POSSIBLE = ("a scenario can make a vehicle brake, change speed, change lanes, cut in, turn at the junction or "
            "reverse, a pedestrian cross the road or stop in it, and a traffic light change or cycle, each at a "
            "time, at a distance or time to collision between two actors, or when an actor reaches a place")
_LEADING = re.compile(r"^(?:and |then |so |now )?(?:please )?(?:i want |i'd like |we need )?"
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
        if _ADDING.match(low):
            raise PlanningError("this adds an asset; add it first, then describe what it does over time")
        action, trigger, delay, vague = split(low)
        action = _LEADING.sub("", action.strip(" ,.")).strip()
        if _is_light_request(action):
            actors, verb_at = _lights_meant(action, scene), 0
            kind = "light"
        else:
            verb_at = _first_verb(action)
            subject = _TRAILING_MODAL.sub("", action[:verb_at]).strip() or "the ego"
            verb_at = len(_TRAILING_MODAL.sub("", action[:verb_at]))  # "should suddenly brake": the adverb counts
            actors, what = candidates(subject, scene, moving_manoeuvre=True)
            if not actors:
                raise PlanningError(f"there is no {what} in the scene to act; {POSSIBLE}")
            kind = motion(actors[0])
        manoeuvre = read_manoeuvre(action[verb_at:] if kind != "light" else action, kind)
        readings: list[tuple[str, list[ToolCall], int]] = []
        for actor in actors[:3]:
            for text, spec in manoeuvre.choices or [("", manoeuvre.spec)]:
                spec = _with_speed(spec, actor, text)
                calls, defaults = _calls(actor, manoeuvre, spec, trigger, delay, action, scene)
                readings.append((text, calls, defaults + manoeuvre.defaults + int(vague)))
        fine = [(t, c, d) for t, c, d in readings if context.check(c) is None]
        step = TraceStep(level="scenario", input=f"action {action!r}; trigger {trigger!r}; delay {delay}",
                         output=f"{len(fine)} of {len(readings)} readings accepted by a dry run",
                         seconds=time.perf_counter() - started)
        if not fine:
            refused = context.check(readings[0][1]) or "refused"
            raise PlanningError(f"{refused}; {POSSIBLE}")
        if len(fine) > 1:
            question = Question(text="Which did you mean?", readings=[
                Reading(text=describe(c), calls=c) for _, c, _ in fine[:3]])
            return Plan(calls=[], planner=self.name, confidence=0.0, question=question, trace=[step])
        _, calls, defaults = fine[0]
        guessed = defaults + int(len(readings) > 1)
        return Plan(calls=calls, planner=self.name, confidence=max(0.0, STATED_CONFIDENCE - DEFAULT_COST * guessed),
                    trace=[step])


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
    starts = [m.start() for kind, words in _COMPILED if kind != "light" for m in [words.search(action)] if m]
    if not starts:
        if not strict:
            return len(action)
        raise PlanningError(f"I could not tell what should happen in {action!r}; {POSSIBLE}")
    return min(starts)


def _lights_meant(action: str, scene: Scene) -> list[AssetInstance]:
    """The light named by id, else the one the ego meets next (ahead of it, on its right)."""
    lights = [a for a in scene.assets if a.category == "traffic_light"]
    named = [a for a in lights if a.id in action]
    if named:
        return named
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


def _calls(actor: AssetInstance, manoeuvre: Manoeuvre, spec: dict[str, Any], trigger: str | None,
           delay: float | None, action: str, scene: Scene) -> tuple[list[ToolCall], int]:
    if manoeuvre.kind == "light" and manoeuvre.phases is not None:
        return [ToolCall(tool="set_light_phases", args={"light": actor.id, "phases": manoeuvre.phases})], 0
    if manoeuvre.kind == "set_light" and trigger is None and delay is None:
        phases = [{"state": spec["state"], "duration": HOLD_S}]
        return [ToolCall(tool="set_light_phases", args={"light": actor.id, "phases": phases})], 0
    if spec.get("kind") == "cut_in":
        after = action[action.find("in front of"):] if "in front of" in action else ""
        targets = [i for i in mentions(after, actor, scene) if i != actor.id]
        spec = {**spec, "target": targets[0] if targets else EGO_ID}
    if trigger is not None:
        when, defaults = read_trigger(trigger, actor, scene)
        return [ToolCall(tool="add_event", args={"actor": actor.id, "manoeuvre": spec, "when": when})], defaults
    args: dict[str, Any] = {"actor": actor.id, "manoeuvre": spec}
    if delay:
        args["at_time"] = delay
    return [ToolCall(tool="add_manoeuvre", args=args)], 0


@dataclass(frozen=True)
class MissedScenario:
    """A plan that answers a scenario request with a static edit: the problem, and either a
    question offering the scenario reading or a refusal saying what is possible."""

    problem: str
    question: Question | None
    message: str | None


def missed_scenario(prompt: str, plan: Plan, context: PlanContext) -> MissedScenario | None:
    """None when the plan may stand; else what to ask or say instead of a static edit."""
    if not plan.calls or any(c.tool in SCENARIO_TOOLS for c in plan.calls) or not describes_behaviour_over_time(
        prompt, context.scene
    ):
        return None
    problem = "you described something that happens over time, but the plan is a static edit"
    try:
        reading = ScenarioReader().plan(prompt, context)
    except PlanningError as exc:
        return MissedScenario(problem, None, f"I did not do it: {problem}, and {exc}")
    if reading.question is not None:
        return MissedScenario(problem, reading.question, None)
    text = f"I am not sure what you meant: {problem}. Did you mean this?"
    return MissedScenario(problem, Question(text=text, readings=[Reading(text=describe(reading.calls),
                                                                         calls=reading.calls)]), None)


__all__ = ["POSSIBLE", "SCENARIO_TOOLS", "MissedScenario", "ScenarioReader", "describes_behaviour_over_time",
           "missed_scenario", "read_trigger", "split"]
