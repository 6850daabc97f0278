"""What a scenario request's action clause asks for: a manoeuvre and its numbers, or a light's phases.

One reader per manoeuvre kind turns the words of the action clause ("brakes hard", "cuts in
leaving an 8 m gap", "turns left at the junction", "10 s green, 3 s amber, 15 s red") into the
arguments of the scenario Workers' `ManoeuvreSpec` (tools/scenario.py); numbers and their
units are read with the rule planner's number parser, so "1e2 m" is 100 m and "nan" refused.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.orchestrator.planning.rules.numbers import Number, finite, numbers_in, speed_said

# Braking rates, m/s²: "hard"/"suddenly" is an emergency stop (about 0.6 g), plain braking a
# firm stop, "gently" a comfortable one.
HARD_BRAKE, FIRM_BRAKE, GENTLE_BRAKE = 6.0, 4.0, 2.0
# A light held in one state stays there for this long (s): longer than any suite scenario.
HOLD_S = 60.0
# A light cycle's amber phase (s) when only the cycle length is given; "make the light work"
# cycles green and red this long each (s).
AMBER_S, DEFAULT_PHASE_S = 3.0, 20.0
# Speeds readings offer when "faster"/"slower" names no target (factor of the current speed).
FASTER, SLOWER = 1.6, 0.5

_LIGHT_STATE = r"(red|amber|yellow|orange|green)"
_STATE = {"yellow": "amber", "orange": "amber"}


@dataclass
class Manoeuvre:
    """What the action clause asks: a manoeuvre spec, or a light's phases, and its defaults."""

    kind: str
    spec: dict[str, Any] = field(default_factory=dict)
    phases: list[dict[str, Any]] | None = None
    defaults: int = 0
    # Readings to ask between when a word the manoeuvre needs was not said (turn which way).
    choices: list[tuple[str, dict[str, Any]]] = field(default_factory=list)
    verb_at: int = 0


# Verbs of moving sideways into a lane ("drifts into the ego's lane", "changes into the left lane").
_SIDEWAYS = r"(?:mov|drift|veer|pull|steer|wander|chang|switch|go|goe|head)\w*"
# Each manoeuvre: its words (a regex over the action clause) and whether walkers or vehicles do it.
_MANOEUVRES: tuple[tuple[str, str], ...] = (
    ("light", r"\b(red|amber|yellow|orange|green|cycles?|phases?|work|working|stop|wait|halt)\b"),
    # not denied ("shouldn't just stand there") nor read across a colon
    ("stop_mid_road", r"(?<!n't )(?<!not )(?<!n't just )(?<!not just )\b(stop|stops|freeze|freezes|stand|stands|halts?|waits?)\b"
                      r"[^,.;:]*\b(middle|midle|road|street|there)\b"
                      r"|\b(in|into) the (road|street)\b[^,.;:]*\b(stops?|freezes?|stands?)\b"),
    ("cut_in", r"\bcut(?:s|ting)? in\b|\bswerv\w* into\b|\bmerg\w* (?:in|into)\b|\bpulls? in front\b"),
    ("overtake", r"\bovertakes?\b|\bpull\w* out\b[^,.;]*\bpass\b|\bto pass\b"),
    ("lane_change", r"\bchang\w* lanes?\b|\blane change\b|\binto the lane (?:on|to) (?:its|the) (?:left|right)\b"
                    r"|\b(?:swing|swung|slid|slide)\w* (?:over )?(?:in)?to (?:the )?(?:left|right)(?:-hand)? lane\b"  # not "swing left at the junction"
                    rf"|\b{_SIDEWAYS}(?: over| back)? (?:in)?to (?:the |its |their |our )?(?:left|right)\b"
                    rf"|\b{_SIDEWAYS}(?: over| back)? (?:in)?to (?:the |its |their |our )?(?:[a-z_0-9]+'s |lane of )?(?:lane|path)\b"),
    # "turn off the street lights" switches lights, it turns off no road
    ("junction_turn", r"\bturn\w*\s+(?:the\s+|our\s+|that\s+|this\s+)?(?:test\s+)?(?:ego|thing|car|suv|bus|truck|van|lorry|vehicle|cab|taxi"
                      r"|motorbike|motorcycle|robot)(?:_\d+)?\s+(?:left|right)\s+(?:at|into|onto|on)\s+(?:the\s+)?(?:crossroads|junction"
                      r"|intersection|lights|place)\b"
                      # (said in the passive it is switched: "the fog can be turned off")
                      r"|\b(?<!be )(?<!been )(?<!being )(?:turn\w*|take\w*|hang\w*|hook\w*|chuck\w*|pull\w* a|make\w* a)(?: a| off)?\s+(?:left|right|off(?! (?:all )?(?:the |those |these )?(?:[a-z]+ )?[a-z]*(?:lights?|lamps?)\b)(?! (?:some|a few|a couple|several|half|most|one|two|three|four|five|\d+)\b)(?! (?:all |every )?(?:the |those |these |them\b|it\b)(?!\s*(?:main|campus|road|street|drive|highway|motorway)\b)))\b|\bturn\w* at\b"
                      r"|\bgo(?:es)? straight\b|\bstraight (?:on|through|across|over|ahead)\b"
                      # a way to turn said with the junction it is taken at, in one clause: "turn the test
                      # car to the right at the junction", "take the left at the crossroads"
                      r"|\b(?:turn|take|go|head|hang|swing|bear|hook)\w*\b[^.,;!?]{0,30}?\b(?:left|right)\b[^.,;!?]{0,20}?"
                      r"\b(?:at|into|onto|through|gets? to|reach\w*)\s+(?:the\s+)?(?:crossroads|junction|intersection|place)\b"),
    ("reverse", r"\brevers\w*|\bback(?:s|ing)? (?:up|out)\b"),
    ("change_speed", r"\bspeed\w* up\b|\bspeed up\b|\baccelerat\w*|\bgo(?:es)? faster\b|\bslow\w* (?:down|to)\b"
                     r"|\bdecelerat\w*|\bgo(?:es)? slower\b"
                     r"|\b(?:reduc|lower|drop|cut|decreas|increas|rais|chang)\w*\s+(?:the\s+|its\s+|their\s+|his\s+|her\s+)?speed\b"),
    ("brake", r"\bbrak\w*|\bslam\w* on\b"),
    ("stop", r"\bbrak\w*|\bstop\w*|\bhalt\w*|\bslam\w*|\bcome\w* to a (?:stop|halt|standstill)\b"),
    ("cross_road", r"\bcross(?:es|ed|ing)?\b(?! ?roads?| ?walks?)|\bcut(?:s|ting)? across\b|\bwalk\w* (?:straight |right |just )?(?:out|across|into)\b|\bsteps? (?:straight |right |just )?out\b|\b(?:run|runs|dart\w*) (?:straight |right |just )?(?:out|across)\b"
                   r"|\bjaywalk\w*"),
    # "drives at 6 m/s", "ego speed 6 m/s": a steady speed, a step of a story when another step follows
    ("keep_lane", r"\b(?:keep\w* (?:its|their|the) lane|driv\w* on|cruis\w*)\b"
                  r"|\b(?:driv\w*|go(?:es)?|travel\w*|mov(?:e|es)|roll\w*) (?:along |steadily |on )?at (?=\d)|\bspeed (?:of |at |to |is )?(?=\d)"
                  r"|\b\d+(?:\.\d+)? ?(?:m/s|km/h|kph|mph)(?=\s*(?:,|and\b|then\b|after that\b|$))"),
)
_COMPILED = tuple((kind, re.compile(words)) for kind, words in _MANOEUVRES)
# A light alone is a traffic light when pointed at ("the light turns red"); "light rain", "light stuff" are not.
_LIGHT_WORDS = re.compile(r"\b(traffic (lights?|signals?)|lights|(?:(?<=the )|(?<=that )|(?<=this )|(?<=each ))light|signals?|traffic_light_\d+)\b")


def manoeuvres_said(text: str) -> list[str]:
    """The manoeuvres whose words `text` (lower case) says, a traffic light's change left out."""
    return [kind for kind, words in _COMPILED if kind != "light" and words.search(text)]


def _unit_number(text: str, units: str) -> Number | None:
    for number in numbers_in(text):
        if re.match(rf"\s*(?:{units})(?![a-z])", text[number.end:]):
            return number
    return None


def read_manoeuvre(action: str, actor_kind: str) -> Manoeuvre:
    """The manoeuvre an action clause names, for an actor that is a vehicle, walker or light."""
    found = [(match.start(), kind) for kind, words in _COMPILED for match in [words.search(action)] if match
             and (kind == "light") == (actor_kind == "light") and (kind != "stop_mid_road" or actor_kind == "walker")]
    if found:
        # The first verb is the manoeuvre ("turns left at the crossroads, cutting across its lane");
        # a walker's walk-out-and-stop is one manoeuvre however its verbs are ordered.
        at, kind = min(found, key=lambda f: (f[1] != "stop_mid_road", f[0]))
        reading: Manoeuvre = getattr(_Readers, kind)(action)
        reading.verb_at = at
        return reading
    raise PlanningError(f"I could not tell what should happen in {action!r}; a scenario can make an actor brake, "
                        "change speed, change lanes, cut in, turn at the junction, cross the road, stop, reverse, "
                        "or change a traffic light")


class _Readers:
    """One reader per manoeuvre kind: the Worker's spec from the action clause's words."""

    @staticmethod
    def light(action: str) -> Manoeuvre:
        states: list[tuple[str, re.Match[str] | None]] = [(_STATE.get(m.group(1), m.group(1)), m) for m in re.finditer(rf"\b{_LIGHT_STATE}\b", action)]
        numbers = numbers_in(action)
        if len(states) > 1 or re.search(r"\b(cycle|phases?|work|working)\b", action):
            phases = _phases(action, states, numbers)
            return Manoeuvre("light", phases=phases, defaults=0 if numbers else 1)
        if not states and re.search(r"\b(stop|wait|halt)\b", action):
            states = [("red", None)]  # "stop the ego at the lights": a light held red stops it
        if not states:
            raise PlanningError("say which colour the light should show: red, amber or green")
        return Manoeuvre("set_light", {"kind": "set_light", "state": states[0][0]})

    @staticmethod
    def stop_mid_road(action: str) -> Manoeuvre:
        return Manoeuvre("stop_mid_road", {"kind": "stop_mid_road"})

    @staticmethod
    def cut_in(action: str) -> Manoeuvre:
        spec: dict[str, Any] = {"kind": "cut_in"}
        gap = _unit_number(action, r"m|metres?|meters?")
        if gap is not None:
            spec["gap"] = finite(gap, "a gap in metres")
        return Manoeuvre("cut_in", spec, defaults=0 if gap else 1)

    @staticmethod
    def overtake(action: str) -> Manoeuvre:
        # Traffic keeps right: a car overtakes through the lane on its left.
        return Manoeuvre("lane_change", {"kind": "lane_change", "side": "left"})

    @staticmethod
    def lane_change(action: str) -> Manoeuvre:
        side = re.search(r"\b(left|right)\b", action)
        if side is None:
            return Manoeuvre("lane_change", choices=[
                (f"change lanes to the {s}", {"kind": "lane_change", "side": s}) for s in ("left", "right")])
        return Manoeuvre("lane_change", {"kind": "lane_change", "side": side.group(1)})

    @staticmethod
    def junction_turn(action: str) -> Manoeuvre:
        turn = re.search(r"\b(left|right|straight)\b", action)
        spec: dict[str, Any] = {"kind": "junction_turn"}
        speed = _speed(action)
        if speed is not None:
            spec["speed"] = speed
        if turn is None:  # "turns off" leaves the road it is on: not straight on
            ways = ("left", "right") if re.search(r"\bturn\w* off\b", action) else ("left", "right", "straight")
            return Manoeuvre("junction_turn", choices=[(f"turn {t} at the junction", {**spec, "turn": t}) for t in ways])
        return Manoeuvre("junction_turn", {**spec, "turn": turn.group(1)})

    @staticmethod
    def reverse(action: str) -> Manoeuvre:
        distance = _unit_number(action, r"m|metres?|meters?")
        spec: dict[str, Any] = {"kind": "reverse"}
        if distance is not None:
            spec["distance"] = finite(distance, "a distance in metres")
        return Manoeuvre("reverse", spec, defaults=0 if distance else 1)

    @staticmethod
    def change_speed(action: str) -> Manoeuvre:
        if re.search(r"\bto (?:a )?(?:stop|halt|standstill|rest)\b", action):  # "slows to a stop"
            return _Readers.stop(action)
        speed, rate = _speed(action), _rate(action)
        spec: dict[str, Any] = {"kind": "change_speed", **({"rate": rate} if rate is not None else {})}
        if speed is None and rate is not None and re.search(r"\bdecelerat", action):
            return Manoeuvre("stop", {"kind": "stop", "rate": rate})  # a deceleration with no end speed ends at rest
        if speed is None:
            faster = not re.search(r"\bslow|\bdecelerat", action)
            return Manoeuvre("change_speed", spec, choices=[("faster" if faster else "slower", spec)])
        return Manoeuvre("change_speed", {**spec, "speed": speed}, defaults=0 if rate else 1)

    @staticmethod
    def brake(action: str) -> Manoeuvre:
        return _Readers.stop(action)

    @staticmethod
    def stop(action: str) -> Manoeuvre:
        speed = _speed(action)
        rate = _rate(action)
        if speed is not None and speed > 0:  # "brakes to 2 m/s" slows down, it does not stop
            return Manoeuvre("change_speed", {"kind": "change_speed", "speed": speed, "rate": rate or FIRM_BRAKE})
        if rate is None:
            hard = re.search(r"\b(hard|harshly|sharply|suddenly|sudden|slam\w*|emergency|full)\b", action)
            gentle = re.search(r"\b(gently|gradually|softly|slowly|smoothly)\b", action)
            rate = HARD_BRAKE if hard else GENTLE_BRAKE if gentle else FIRM_BRAKE
            return Manoeuvre("stop", {"kind": "stop", "rate": rate}, defaults=0 if hard or gentle else 1)
        return Manoeuvre("stop", {"kind": "stop", "rate": rate})

    @staticmethod
    def cross_road(action: str) -> Manoeuvre:
        speed = _speed(action)
        running = re.search(r"\b(run\w*|dart\w*|dash\w*|sprint\w*)\b", action)
        return Manoeuvre("cross_road", {"kind": "cross_road", **({"speed": speed} if speed else
                                                                 {"speed": 3.0} if running else {})})

    @staticmethod
    def keep_lane(action: str) -> Manoeuvre:
        speed = _speed(action)
        return Manoeuvre("keep_lane", {"kind": "keep_lane", **({"speed": speed} if speed is not None else {})},
                         defaults=0 if speed is not None else 1)


def _speed(text: str) -> float | None:
    """A speed in m/s from "8 m/s", "30 km/h", "20 mph" (not an acceleration "2 m/s2")."""
    for number in numbers_in(text):
        unit = re.match(r"\s*(m/s|km/h|kph|kmh|mph|metres per second|meters per second)(?!2|\s*squared)", text[number.end:])
        if unit:
            value = finite(number, "a speed")
            factor = {"km/h": 1 / 3.6, "kph": 1 / 3.6, "kmh": 1 / 3.6, "mph": 0.44704}.get(unit.group(1), 1.0)
            return round(value * factor, 3)
    bare = speed_said(text)  # "faster, like 10": the simulator's unit
    return round(float(bare.group(1)), 3) if bare is not None and not bare.group(2) else None


def _rate(text: str) -> float | None:
    number = _unit_number(text, r"m/s2|m/s\s*squared|metres per second squared|g\b")
    if number is None:
        return None
    value = finite(number, "an acceleration")
    return round(value * 9.81, 2) if re.match(r"\s*g\b", text[number.end:]) else value


def _phases(action: str, states: list[tuple[str, re.Match[str] | None]], numbers: list[Number]) -> list[dict[str, Any]]:
    """A light's cycle from "10 s green, 3 s amber, 15 s red", "green 10 s, ...", or "a 30 s cycle"."""
    spans = [(state, at) for state, at in states if at is not None]
    if not spans or not numbers:
        total = next((n.value for n in numbers), None)
        side = (total - AMBER_S) / 2 if total is not None and total > AMBER_S * 2 else DEFAULT_PHASE_S
        return [{"state": "green", "duration": side}, {"state": "amber", "duration": AMBER_S},
                {"state": "red", "duration": side}]
    number_first = numbers[0].start < spans[0][1].start()
    phases = []
    for state, at in spans:
        if number_first:
            near = [n for n in numbers if n.end <= at.start()]
            chosen = near[-1] if near else None
        else:
            near = [n for n in numbers if n.start >= at.end()]
            chosen = near[0] if near else None
        if chosen is None:
            raise PlanningError(f"say how long the light stays {state}, e.g. '{state} 10 s'")
        phases.append({"state": state, "duration": finite(chosen, f"how long it stays {state}")})
    return phases


# Things scenario descriptions ask for that no Worker can play, each with what is possible instead.
_UNSUPPORTED: tuple[tuple[re.Pattern[str], str], ...] = (
    (re.compile(r"\b(?:runs?|running|jumps?|jumping|ignor\w*|go(?:es)? through|driv\w* through|blows?) (?:the |a )?red\b"
                r"|\bred.light runner\b"),
     "vehicles on their routes always stop at a red light, so none can run one; a light can be held red, turn "
     "red at a time or distance, or cycle"),
    (re.compile(r"\bu.?turn\w*|\bturn\w* (?:a)?round\b|\bthree.point turn\b"),
     "a vehicle cannot turn round; it can turn left or right or go straight at the junction, or reverse"),
    (re.compile(r"\b(?:onto|on to|up onto|up on|mounts?|mounting) (?:the )?(?:pavement|sidewalk|kerb|curb|verge|grass)\b"),
     "a vehicle stays on the road; it can brake, change speed, change lanes, cut in, turn at the junction or reverse"),
    (re.compile(r"\b(?:make|makes|let|lets|have|has|get|gets|send|sends)\b[^,.;!?]{0,40}?\b(?P<said>fly|soar|levitate)\b(?!-?tip)"),
     "nothing in this world leaves the ground; I can move a thing to a place, or make a vehicle drive or a person walk there"),
    (re.compile(r"\b(?:honk\w*|hoot\w*|sounds? (?:its|the) horn|flash\w* (?:its |the )?(?:head)?lights|signals? left|signals? right)\b"),
     "actors have no horn or indicators in this simulation; they can only move"),
    (re.compile(r"\b(?:crash\w*|collid\w*|smash\w*|ram\w*|slams?) into\b|\b(?:hits?|rear.ends?) the\b"),
     "a collision is an outcome, not a manoeuvre: I can set up the manoeuvres that lead to one (a lead car braking, "
     "a cut-in, a walker stepping out) and the simulation shows whether they collide"),
)


def refuse_unsupported(action: str) -> None:
    """PlanningError naming what is possible when the words ask for a manoeuvre no Worker can play."""
    for words, instead in _UNSUPPORTED:
        found = words.search(action)
        if found:
            said = found.groupdict().get("said") or found.group(0)  # "make the tree fly": 'fly'
            raise PlanningError(f"I cannot make anything {said!r}: {instead}")


def asks_unsupported(action: str) -> bool:
    """Whether the words ask for a manoeuvre no Worker can play (see refuse_unsupported)."""
    return any(words.search(action) for words, _ in _UNSUPPORTED)
