"""When a scenario request's action starts: its trigger clause and its delay, as add_event's `when`.

A request is an action clause and, around it, a condition ("when the ego is 15 m behind",
"once the ego closes to 20 m", "as our car nears the junction", "if the time to collision
drops under 3 s") or a time ("after 3 s", "two seconds in", "4 s into the run"). `split`
separates them; `read_trigger` reads the condition into the scenario Workers' TriggerSpec
(tools/scenario.py): a distance or time to collision between two actors, an actor reaching a
place, another event ending. A condition that names nobody ("when 15 m behind it") is the
acting actor's own, measured against what the action is done to, else the ego. A delay after
a condition ("2 s after the ego gets close") is something no Worker can play, so it is
refused, not read as a delay from the start.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.orchestrator.planning.rules.numbers import finite
from drivetwin.orchestrator.planning.scenario_actors import ROLE_WORDS, candidates
from drivetwin.orchestrator.planning.scenario_manoeuvres import _COMPILED, _unit_number
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Scene

# "As the ego approaches" / "gets close": the distance at which it counts as approaching or
# close; at the campus's 5 m/s an approach of 30 m leaves 6 s, close 15 m leaves 3 s.
APPROACH_M, CLOSE_M = 30.0, 15.0
# "Dangerously close": a time to collision this short (s) is the usual critical threshold.
DANGER_TTC_S = 2.0
# "After a bit" / "shortly": a delay long enough to see the scene settle first (s).
VAGUE_DELAY_S = 3.0

TRIGGER = re.compile(r"\b(as soon as|whenever|when|once|as|if|until)\b|\b(?:just\s+)?before\b"
                     r"(?=[^,.;]*\b(?:gets?|reach(?:es)?|arrives?|comes?)\b)")
_SECONDS = r"(?:s|secs?|seconds?)"
# The start of the run, which a delay may be counted from ("4 s into the run", "2 s after the start").
_START = (r"(?:the (?:start|beginning)|(?:the |our |my )?(?:run|scenario|simulation|test|clip|drive|ride|journey|lesson|take|shot"
          r"|recording|sequence)(?: starts| begins)?|it (?:starts|begins))")
DELAY = re.compile(rf"\b(?:after|in|at)\s+(?:t\s*=\s*)?(\d+(?:\.\d+)?)\s*{_SECONDS}\b"
                   rf"|\b(\d+(?:\.\d+)?)\s*{_SECONDS}\s+(?:in\b(?!to)|into {_START}|after {_START}|from {_START})"
                   r"|\b(after a (?:bit|while|moment)|shortly|in a (?:bit|moment|while)|a bit later|soon)\b")
# "2 s after the ego gets close": a delay counted from a condition, not from the start.
_DELAY_AFTER_CONDITION = re.compile(rf"\b\d+(?:\.\d+)?\s*{_SECONDS}\s+after\b(?! {_START})")
_MODAL = re.compile(r"\b(should|will|must|has to|needs to|is to|to)\b")
_ROLE = re.compile(r"\b(" + "|".join(sorted(ROLE_WORDS, key=len, reverse=True)) + r")\b")
NOT_POSSIBLE_DELAY = ("a manoeuvre cannot wait a time after a condition; it can start when the condition holds "
                       "(a distance, a time to collision, reaching a place, another event ending) or a number of "
                       "seconds after the scenario starts")


@dataclass(frozen=True)
class Timing:
    """An action clause with what starts it: a condition clause, or a delay from the start."""

    action: str
    trigger: str | None
    delay: float | None
    vague: bool  # the delay was "after a bit", not a number


def split(low: str) -> Timing:
    """The action clause, the trigger clause (or None) and the delay from the start (or None)."""
    if _DELAY_AFTER_CONDITION.search(low):
        raise PlanningError(NOT_POSSIBLE_DELAY)
    delay: float | None = None
    vague = False
    found = DELAY.search(low)
    if found:
        delay = float(found.group(1) or found.group(2)) if not found.group(3) else VAGUE_DELAY_S
        vague = found.group(3) is not None
        low = (low[: found.start()] + " " + low[found.end():]).strip(" ,")
    marker = TRIGGER.search(low)
    while marker is not None and marker.group(1) == "as" and re.match(r"\s*(well|a|an|soon|much|far)\b", low[marker.end():]):
        marker = TRIGGER.search(low, marker.end())
    if marker is None:
        return Timing(low, None, delay, vague)
    before, after = low[: marker.start()].strip(" ,"), low[marker.end():].strip()
    if before and re.search(r"[a-z]", before) and not re.fullmatch(r"(then|and|so|but)", before):
        return Timing(before, re.split(r"\s*[,;.]\s*|\bthen\b", after)[0], delay, vague)
    comma = re.search(r"\s*[,;]\s*|\bthen\b", after)
    if comma:
        return Timing(after[comma.end():].strip(), after[: comma.start()], delay, vague)
    modal = [m for m in _MODAL.finditer(after)]
    if modal:
        articles = [a for a in re.finditer(r"\b(the|a|an|that)\b", after[: modal[0].start()])]
        if len(articles) > 1:
            cut = articles[-1].start()
            return Timing(after[cut:], after[:cut], delay, vague)
    raise PlanningError(f"I could not tell where the condition ends in {low!r}; put a comma after it, "
                        "e.g. 'when the ego is 20 m away, the car brakes'")


def _mask_ego(text: str) -> str:
    for word in ph.EGO_WORDS:
        text = re.sub(rf"(?<![a-z]){re.escape(word)}(?![a-z])", " ego ", text)
    return re.sub(r"\s+", " ", text)


def mentions(text: str, actor: AssetInstance, scene: Scene, pronoun: str | None = None) -> list[str]:
    """The asset ids a clause names, in order: the ego, ids, pronouns, categories. A pronoun
    stands for `pronoun` when given (the thing an action is done to), else for the actor."""
    text = _mask_ego(text)
    found: list[tuple[int, str]] = [(m.start(), EGO_ID) for m in re.finditer(r"\bego\b", text)]
    found += [(m.start(), pronoun or actor.id) for m in re.finditer(r"\b(it|its|itself|that one|them|her|him)\b", text)]
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


def read_trigger(trigger: str, actor: AssetInstance, scene: Scene, done_to: str | None = None) -> tuple[dict[str, Any], int]:
    """The add_event `when` for a trigger clause, and how many defaults it needed. `done_to` is
    what the action is done to ("overtakes it": the truck): a condition naming nobody is the
    actor's distance from it, else from the ego."""
    named = mentions(trigger, actor, scene)
    if named:
        watched = named[0]
        other = next((i for i in named[1:] if i != watched), actor.id if watched != actor.id else done_to or EGO_ID)
    else:
        watched, other = actor.id, done_to or EGO_ID
    seconds = _unit_number(trigger, r"s|secs?|seconds?")
    metres = _unit_number(trigger, r"m|metres?|meters?")
    if _TTC.search(trigger):
        stated = seconds is not None
        value = finite(seconds, "a time to collision in seconds") if seconds is not None else DANGER_TTC_S
        return {"kind": "time_to_collision", "actor": watched, "other": other, "seconds": value}, 0 if stated else 1
    from drivetwin.orchestrator.planning.rules.reading import find_place

    place = find_place(scene, f" {trigger} ")
    if metres is not None:
        if place is not None and len(named) < 2 and not re.search(r"\b(it|its|them|her|him)\b", trigger):
            raise PlanningError(f"a manoeuvre cannot start at a distance from a place ({place[0]}); it can start when "
                                "an actor reaches the place, or at a distance between two actors")
        rule = "greater" if re.search(r"\b(more than|further|farther|beyond|over|at least)\b", trigger) else "less"
        return {"kind": "distance", "actor": watched, "other": other,
                "metres": finite(metres, "a distance in metres"), "rule": rule}, 0
    if _REACH.search(trigger) and place is not None and not _APPROACH.search(trigger):
        return {"kind": "reach", "actor": watched, "place": place[0]}, 0
    if _ENDED.search(trigger) and watched != actor.id:
        earlier = [e.name for a, e in scene.storyboard.events() if a == watched]
        if earlier:
            return {"kind": "after_event", "event": earlier[-1]}, 0
    if _APPROACH.search(trigger):
        return approach(watched, other, trigger), 1
    raise PlanningError(f"I could not tell when it should happen from {trigger!r}; a manoeuvre can start after a "
                        "number of seconds, when two actors are a distance apart or a time to collision away, "
                        "when an actor reaches a place, or when another event ends")


def approach(watched: str, other: str, words: str = "approach") -> dict[str, Any]:
    """The trigger of an approach said without a distance: APPROACH_M, or CLOSE_M for "close"."""
    near = APPROACH_M if re.search(r"\bapproach|\bthere\b", words) else CLOSE_M
    return {"kind": "distance", "actor": watched, "other": other, "metres": near}


# "and then", ", then", "and", "after that": where a second step of the same story may start.
_THEN = re.compile(r"\s*,?\s*\b(?:and then|then|and after that|after that|and afterwards|and)\b\s*")
_LATER = re.compile(rf"\b(\d+(?:\.\d+)?)\s*{_SECONDS}\s+later\b|\b(?:later|afterwards)\b")
# A later step's verb starts within this many characters of its connector ("and the ego then brakes").
_STEP_SUBJECT_CHARS = 40


def steps(action: str) -> tuple[str, list[tuple[str, float | None]]]:
    """The first step of an action clause, and each later step with its delay after the one
    before it (None: right when it ends). "accelerates to 8 m/s and brakes hard 3 s later":
    ("accelerates to 8 m/s", [("brakes hard", 3.0)]). Walking out and stopping in the road is
    one manoeuvre, not two steps."""
    verbs = [m.start() for kind, words in _COMPILED if kind != "light" for m in words.finditer(action)]
    if not verbs or any(kind == "stop_mid_road" and words.search(action) for kind, words in _COMPILED):
        return action, []
    cuts = []
    for connector in _THEN.finditer(action, min(verbs)):
        follows = [v for v in verbs if connector.end() <= v < connector.end() + _STEP_SUBJECT_CHARS]
        before = [v for v in verbs if v < connector.start()]
        if follows and before and not _THEN.search(action[connector.end():min(follows)]):
            cuts.append(connector)
    if not cuts:
        return action, []
    first = action[: cuts[0].start()].strip()
    later: list[tuple[str, float | None]] = []
    for n, cut in enumerate(cuts):
        words = action[cut.end(): cuts[n + 1].start() if n + 1 < len(cuts) else len(action)]
        gap = _LATER.search(words)
        seconds = float(gap.group(1)) if gap and gap.group(1) else None
        later.append(((words[: gap.start()] + words[gap.end():]).strip(" ,") if gap else words.strip(" ,"), seconds))
    return first, later


__all__ = [
    "APPROACH_M",
    "CLOSE_M",
    "DANGER_TTC_S",
    "DELAY",
    "NOT_POSSIBLE_DELAY",
    "TRIGGER",
    "VAGUE_DELAY_S",
    "Timing",
    "approach",
    "mentions",
    "read_trigger",
    "split",
    "steps",
]
