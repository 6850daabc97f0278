"""Jr. managers: one per tool family, from one Requirement to one checked ToolCall.

The requirement's free words are grounded first (catalog, landmarks, memory); strong
matches narrow the schema's enums, all matches become hints in the prompt and lines in the
trace. The answer is parsed by the tool's own pydantic model and dry-run against the scene
after the calls planned before it; a refusal goes back to the model as a message.
"""

from __future__ import annotations

import re
import time
from dataclasses import dataclass, field
from typing import Any

from drivetwin.orchestrator.backends import Backend, Message
from drivetwin.orchestrator.planning.base import PlanContext, PlanningError, TraceStep
from drivetwin.orchestrator.planning.grounding import Grounder, Match
from drivetwin.orchestrator.planning.llm.demos import fits, jr_demos
from drivetwin.orchestrator.planning.llm.jr_schema import (
    COORDINATE_FIELDS,
    COUNT_FIELDS,
    NUMBER_FIELDS,
    TURN_FIELDS,
    WorldNames,
    call_schema,
    signature,
)
from drivetwin.orchestrator.planning.llm.managers import CALL_TIMEOUT_S, Answer, Requirement, ask
from drivetwin.orchestrator.planning.llm.request_names import RequestNames, read_names
from drivetwin.orchestrator.planning.llm.review_hint import review_problems
from drivetwin.orchestrator.planning.scenario_reading import SCENARIO_TOOLS
from drivetwin.prompts.templates import as_json, jr_examples, render
from drivetwin.tools.base import Family, Tool, ToolCall
from drivetwin.tools.errors import ToolError
from drivetwin.worlds.scene import Lane, Scene

JR_MAX_TOKENS = 200
# Few-shot examples per call, chosen by meaning from the family's bank.
JR_EXAMPLES = 3
# Nearest demonstrations looked at per example shown, to find ones the grammar allows.
DEMO_POOL = 4
# A grounded name this sure narrows the enum to the grounded names; below it, it is a hint.
NARROW_SCORE = 0.75
# Grounded alternatives kept in a narrowed enum (the best one plus near misses).
NARROW_KEEP = 3

# Matches below this are noise ("night" spells like "light") and are not shown at all.
MATCH_FLOOR = 0.6

# Words in the request that say which relation a location has; first match wins.
RELATION_WORDS: tuple[tuple[str, str], ...] = (
    (r"in front of|ahead of|before", "in_front_of"),
    (r"behind|in back of", "behind"),
    (r"left of", "left_of"),
    (r"right of", "right_of"),
    (r"next to|beside|by the|near|around|close to", "next_to"),
    (r"sidewalk|pavement|footpath", "on_sidewalk"),
    (r"in (the )?lane|on the road", "in_lane"),
    (r"\bat\b|\bin\b", "at"),
)
# move_asset's displacement fields, one per axis a direction word can name.
MOVE_DIRECTIONS = ("forward", "left", "east", "north")
_PLACE_FAMILIES: tuple[Family, ...] = ("add", "arrange", "position", "move", "search")
_ASSET_FAMILIES: tuple[Family, ...] = ("remove", "position", "move", "appearance", "search")


@dataclass
class Grounding:
    """What a requirement's words were grounded to, and the names its schema allows."""

    names: WorldNames
    matches: list[Match] = field(default_factory=list)
    relation: str | None = None
    # The request describes something happening over time: only storyboard tools can do it.
    over_time: bool = False
    # Tools the request gives no words for (a light's phases where no traffic light is named).
    unfit: frozenset[str] = frozenset()

    def lines(self) -> list[str]:
        found = [str(m) for m in self.matches]
        if self.relation:
            found.append(f"relation words -> {self.relation}")
        return found


def _narrow(full: list[str], matches: list[Match]) -> list[str]:
    strong = [m.name for m in matches if m.score >= NARROW_SCORE and m.name in full]
    return list(dict.fromkeys(strong)) if strong else full


def ground_requirement(
    requirement: Requirement, prompt: str, context: PlanContext, grounder: Grounder, said: RequestNames | None = None
) -> Grounding:
    """Ground the requirement's words and narrow the world's names where grounding is sure;
    then narrow again to what the request itself names (`said`, read from `prompt` if None)."""
    scene, memory = context.scene, context.memory
    said = said if said is not None else read_names(prompt, scene)
    names = WorldNames.of(scene)
    matches: list[Match] = []
    kind = requirement.kind
    what, where = requirement.what.strip(), requirement.where.strip()
    if what and kind in ("add", "arrange", "search", "remove", "appearance"):
        category = grounder.rank(what, "category", scene, NARROW_KEEP)
        # Weather and time words are no asset: only a sure match counts for appearance.
        floor = NARROW_SCORE if kind == "appearance" else MATCH_FLOOR
        category = [m for m in category if m.score >= floor]
        matches += category
        names.categories = _narrow(names.categories, category)
    referred: list[str] = []
    if what and kind in _ASSET_FAMILIES:
        assets = grounder.asset_reference(what, memory, scene)
        matches += assets[:NARROW_KEEP]
        referred = [m.name for m in assets if m.how == "memory"]
        names.assets = _narrow(names.assets, assets) if assets else names.assets
    pointed: list[str] = []
    if where and kind in _PLACE_FAMILIES:
        place = grounder.place_reference(where, memory, scene)
        pointed = [place.name] if place is not None else []
        ranked = [place] if place is not None else grounder.rank(where, "place", scene, NARROW_KEEP)
        ranked += [] if place is not None else grounder.rank(where, "asset", scene, 1)
        ranked = [m for m in ranked if m.score >= MATCH_FLOOR]
        matches += ranked
        names.places = _narrow(names.places, ranked)
    _narrow_to_request(names, said, scene, referred, pointed)
    sure_category = len(names.categories) < len(WorldNames.of(scene).categories)
    names.omitted = names.omitted | _unasked_fields(kind, said, sure_category)
    names.required = _stated_fields(kind, said)
    if kind == "search" and len(names.ends) >= 2:  # "how far is the bench from the bus stop": both ends
        names.required = names.required | {"b"}
    if kind == "move" and len(names.assets) == 1:  # the one thing named is the one to move
        names.required = names.required | {"asset"}
    relation = next((rel for pattern, rel in RELATION_WORDS if re.search(pattern, prompt.lower())), None)
    lights = "traffic_light" in said.categories or any(a in names.lights for a in said.assets)
    unfit = set() if lights else {"set_light_phases"}
    if kind == "search" and said.lookups:  # "how far ..." is measured, never listed as landmarks
        unfit |= {t.name for t in context.registry.family("search")} - set(said.lookups)
    return Grounding(names, matches, relation, said.over_time, frozenset(unfit))


def _unasked_fields(kind: Family, said: RequestNames, sure_category: bool) -> frozenset[str]:
    """Optional fields the request gives no words for, which a small model fills anyway (a
    beige stop sign that drives a lane; "2 m east" as 2 m left)."""
    unasked: set[str] = set()
    if not said.colours and kind != "appearance":
        unasked |= {"colour", "state"}  # a light's state is a colour too
    if not any(name == "left" for name, _ in said.directions):
        unasked.add("side")  # "change lanes" without a side: the tool asks, the model guesses
    if not said.behaviour and kind == "add":
        unasked.add("behaviour")
    if said.directions and kind == "move":
        unasked |= set(MOVE_DIRECTIONS) - {name for name, _ in said.directions}
    if not said.numbers:
        unasked |= NUMBER_FIELDS - TURN_FIELDS - ({"speed"} if said.speeds else set())
    elif all(n in said.lengths or n in dict(said.coordinates).values() for n in said.numbers):
        unasked |= COUNT_FIELDS  # "25 m ahead", "x=40" say no count
    if "absolute" not in said.relations:
        unasked |= COORDINATE_FIELDS  # no "x=40" nor "coordinates": a count is no coordinate
    if not said.turning and not said.angles:
        unasked |= TURN_FIELDS
    if said.assets and not said.categories and kind in ("appearance", "remove"):
        unasked.add("category")  # "car 1", not every car
    if not said.categories and kind == "search" and not sure_category:
        unasked.add("category")  # "what is around the ego?" asks about everything there
    return frozenset(unasked)


def _stated_fields(kind: Family, said: RequestNames) -> frozenset[str]:
    """Fields the request states a value for, which a small model still leaves out
    ("move the hydrant 2 m east" as a move of nothing, "a motorbike at 7 m/s" with no speed)."""
    speed = frozenset({"speed", "behaviour"} if said.speeds and kind in ("add", "move") else ())
    if kind == "move" and said.angles and not said.numbers:
        return frozenset({"turn_deg"}) | speed
    if not said.numbers:
        return speed
    if kind == "move" and said.directions:
        return frozenset(name for name, _ in said.directions) | speed
    counts = [n for n in said.numbers if n not in said.lengths and n not in dict(said.coordinates).values()]
    if kind in ("add", "arrange") and any(n.is_integer() and n > 1 for n in counts):
        return frozenset({"count"}) | speed
    return speed


def _narrow_to_request(
    names: WorldNames, said: RequestNames, scene: Scene, referred: list[str], pointed: list[str]
) -> None:
    """Keep only the names the request states, where it states any of that kind; what the
    conversation points at ("them", "there") is kept too, the request cannot name it. Grounding
    the manager's paraphrase narrowed `names` already: the request's own words win over it."""
    world = WorldNames.of(scene)

    def keep(narrowed: list[str], stated: list[str], every: list[str]) -> list[str]:
        stated = [n for n in dict.fromkeys(stated) if n in every]
        if not stated:
            return narrowed
        return [n for n in narrowed if n in stated] or stated

    of_categories = [a.id for a in scene.all_assets() if a.category in said.categories]
    names.categories = keep(names.categories, list(said.categories), world.categories)
    names.assets = keep(names.assets, [*said.assets, *of_categories, *referred], world.assets)
    names.places = keep(names.places, [*said.places, *pointed], world.places)
    names.relations = list(said.relations)
    names.numbers = list(said.numbers)
    names.lengths = list(said.lengths)
    names.ends = list(dict.fromkeys([*said.places, *said.assets]))
    names.coordinates = list(said.coordinates)
    ways = [(name, sign) for name, sign in said.directions if name in ("east", "north")]
    names.lanes = [lane.id for lane in scene.roads.lanes if ways and _heads(lane, ways)] or names.lanes
    names.angles = list(said.angles)
    names.speeds = list(said.speeds)
    names.weathers = list(said.weathers)
    names.intensities = list(said.intensities)
    names.colours = list(said.colours)
    names.times = list(said.times)
    names.shapes = list(said.shapes)
    names.manoeuvres = list(said.manoeuvres)
    names.behaviours = list(said.behaviours)
    names.signs = dict(said.directions)


def _heads(lane: Lane, ways: list[tuple[str, int]]) -> bool:
    """Whether `lane`'s traffic goes mostly the compass way said ("driving north")."""
    (x0, y0), (x1, y1) = lane.centreline[0], lane.centreline[-1]
    east, north = x1 - x0, y1 - y0
    return any(sign * (east if name == "east" else north) > abs(north if name == "east" else east) for name, sign in ways)


def render_requirement(requirement: Requirement, grounding: Grounding) -> str:
    """The requirement as the Jr. manager reads it, after arrows the names its schema allows
    for each side (the grounded ones first), so the prompt never points at a name it forbids."""
    names = grounding.names
    allowed = {"category": names.categories, "asset": names.assets, "place": names.places}

    def side(label: str, text: str, kinds: tuple[str, ...]) -> str:
        hits = [m.name for m in grounding.matches if m.text == text and m.kind in kinds and m.name in allowed[m.kind]]
        for kind in kinds:
            if not hits and len(allowed[kind]) <= NARROW_KEEP:
                hits = list(allowed[kind])
        return f"{label}: {text}" + (f" -> {', '.join(dict.fromkeys(hits[:NARROW_KEEP]))}" if hits else "")

    what = ("category",) if requirement.kind in ("add", "arrange") else ("category", "asset")
    return " | ".join(
        [
            requirement.kind,
            side("what", requirement.what, what),
            side("where", requirement.where, ("place",)),
            f"how: {requirement.how}",
        ]
    )


class JrManager:
    """Plans one requirement of one family into one ToolCall, checked against the scene."""

    def __init__(self, family: Family, backend: Backend, grounder: Grounder, timeout_s: float = CALL_TIMEOUT_S) -> None:
        self.family = family
        self.backend = backend
        self.grounder = grounder
        self.timeout_s = timeout_s

    def offered(self, grounding: Grounding, context: PlanContext) -> list[Tool[Any]]:
        """The family's tools that fit the request: the storyboard's only where it describes
        something over time (the review refuses a static edit for it: "stop after 5 s" is no
        move_asset), a light's phases only where it names a traffic light."""
        tools = [t for t in context.registry.family(self.family) if t.name not in grounding.unfit]
        timed = [t for t in tools if t.name in SCENARIO_TOOLS] if grounding.over_time else []
        return timed or tools

    def messages(
        self, requirement_text: str, grounding: Grounding, context: PlanContext, prompt: str = ""
    ) -> list[Message]:
        tools = self.offered(grounding, context)
        hints = [f"Grounded: {'; '.join(grounding.lines())}"] if grounding.lines() else []
        system = render(
            "jr_manager.txt",
            family=self.family,
            tools="\n".join(signature(t, grounding.names) for t in tools),
            hints="\n".join(hints),
        )
        messages: list[Message] = [Message(role="system", content=system)]
        schema = call_schema(tools, grounding.names)
        near = jr_demos(self.family, prompt or requirement_text, context, JR_EXAMPLES * DEMO_POOL)
        # Only demonstrations this request's grammar allows; the nearest ones if none does.
        demos = [(d.requirement, d.call) for d in near if fits(d.call, schema)][:JR_EXAMPLES]
        demos = demos or [(d.requirement, d.call) for d in near[:JR_EXAMPLES]]
        if not demos:  # no bank, or nothing of this family near: the static examples
            bank = jr_examples().get(self.family, ())
            chosen = self.grounder.nearest(requirement_text, [e.requirement for e in bank], JR_EXAMPLES)
            demos = [(bank[i].requirement, bank[i].call) for i in chosen]
        # Most similar last, nearest the real requirement, where small models copy from.
        for requirement, call in reversed(demos):
            messages.append(Message(role="user", content=requirement))
            messages.append(Message(role="assistant", content=as_json(call)))
        messages.append(Message(role="user", content=requirement_text))
        return messages

    def call(
        self,
        requirement: Requirement,
        prompt: str,
        context: PlanContext,
        planned: list[ToolCall],
        said: RequestNames | None = None,
        last: bool = False,
    ) -> tuple[ToolCall, list[TraceStep]]:
        """The call for `requirement`, valid and accepted by a dry run after `planned`. When it
        is the `last` call of the plan, a plan the plan-vs-request review would not apply goes
        back to the model once, with the review's reasons (then it is left to the session)."""
        started = time.perf_counter()
        grounding = ground_requirement(requirement, prompt, context, self.grounder, said)
        text = render_requirement(requirement, grounding)
        grounded = TraceStep(
            level=f"grounding:{self.family}",
            input=str(requirement),
            output="\n".join(grounding.lines()) or "(nothing to ground)",
            seconds=time.perf_counter() - started,
        )
        tools = self.offered(grounding, context)
        if not tools:
            raise PlanningError(f"no tool of the {self.family!r} family is registered")

        def validate(data: object) -> ToolCall:
            call = ToolCall.model_validate(data)
            try:
                tool = context.registry.get(call.tool)
                if tool.family != self.family:
                    raise ValueError(
                        f"tool {call.tool!r} is not a {self.family} tool; use one of: "
                        + ", ".join(t.name for t in tools)
                    )
                args = tool.parse(call.args).model_dump(mode="json", exclude_unset=True)
            except ToolError as exc:
                raise ValueError(str(exc)) from exc
            checked = ToolCall(tool=call.tool, args=args)
            refusal = context.check([*planned, checked])
            if refusal is not None:
                raise ValueError(f"the world refused it: {refusal}")
            if last and not reviewed:
                problems = review_problems(prompt, [*planned, checked], context)
                if problems:
                    reviewed.append(checked)
                    raise ValueError(f"it does not do what the request says: {'; '.join(problems)}")
            return checked

        reviewed: list[ToolCall] = []  # the call the review sent back (once per plan)

        answer: Answer[ToolCall] = ask(
            self.backend,
            self.messages(text, grounding, context, prompt),
            call_schema(tools, grounding.names),
            validate,
            step=f"Jr. manager ({self.family})",
            max_tokens=JR_MAX_TOKENS,
            timeout_s=self.timeout_s,
        )
        output = str(answer.value)
        if answer.refusals:
            output += "\nrefused on the way: " + " | ".join(answer.refusals)
        step = TraceStep(
            level=f"jr_manager:{self.family}",
            input=text,
            output=output,
            seconds=answer.seconds,
            retries=answer.retries,
            tokens=answer.tokens,
        )
        return answer.value, [grounded, step]


__all__ = ["Grounding", "JrManager", "ground_requirement", "render_requirement"]
