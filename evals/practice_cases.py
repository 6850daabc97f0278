"""The case-writing helpers the later practice suites share (practice20 to practice22): calls as
the Worker tools take them, checks as the eval harness reads them, and a `Suite` that names each
case by its suite's tag. Each suite's source keeps its own world constants, voices and cases."""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

Json = dict[str, Any]

EGO = "ego"


# --- Calls -------------------------------------------------------------------------------------
def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def loc(relation: str = "at", target: str | None = None, **extra: Any) -> Json:
    out: Json = {"relation": relation}
    if target is not None:
        out["target"] = target
    out.update(extra)
    return out


def xy(x: float, y: float) -> Json:
    return {"relation": "absolute", "x": x, "y": y}


def ahead_of(target: str, metres: float, **extra: Any) -> Json:
    """A spot `metres` ahead of a target along its lane or sidewalk (negative: behind)."""
    return loc("at", target, along_m=metres, **extra)


def add(category: str, count: int = 1, where: Json | None = None, **extra: Any) -> Json:
    args: Json = {"category": category}
    if count != 1:
        args["count"] = count
    if where is not None:
        args["location"] = where
    args.update(extra)
    return call("add_asset", **args)


def drive(speed: float | None = None, lane: str | None = None) -> Json:
    """A drive_lane behaviour for add_asset."""
    out: Json = {"kind": "drive_lane"}
    if speed is not None:
        out["speed"] = speed
    if lane is not None:
        out["lane"] = lane
    return out


def remove(*assets: str, **extra: Any) -> Json:
    args: Json = {"assets": list(assets)} if assets else {}
    args.update(extra)
    return call("remove_assets", **args)


def place(asset: str, where: Json, **extra: Any) -> Json:
    return call("place_asset", asset=asset, location=where, **extra)


def move(asset: str, **extra: Any) -> Json:
    return call("move_asset", asset=asset, **extra)


def behave(asset: str, kind: str, **extra: Any) -> Json:
    return call("set_behaviour", asset=asset, behaviour={"kind": kind, **extra})


def manoeuvre(actor: str, kind: str, at_time: float = 0.0, **extra: Any) -> Json:
    return call("add_manoeuvre", actor=actor, manoeuvre={"kind": kind, **extra}, at_time=at_time)


def event(actor: str, kind: str, when: Json, **extra: Any) -> Json:
    """A manoeuvre started by a trigger (reach a place, a distance, a time)."""
    return call("add_event", actor=actor, manoeuvre={"kind": kind, **extra}, when=when)


def arrange(categories: str | list[str], shape: str, where: Json, **extra: Any) -> Json:
    cats = [categories] if isinstance(categories, str) else categories
    return call("arrange_assets", categories=cats, shape=shape, location=where, **extra)


def paint(assets: Sequence[str] = (), category: str | None = None, **look: Any) -> Json:
    args: Json = {}
    if assets:
        args["assets"] = list(assets)
    if category is not None:
        args["category"] = category
    args.update(look)
    return call("set_asset_appearance", **args)


def weather(kind: str, intensity: float | None = None) -> Json:
    return call("set_weather", kind=kind) if intensity is None else call("set_weather", kind=kind, intensity=intensity)


def clock(time: str) -> Json:
    return call("set_time_of_day", time=time)


def lighting(**settings: Any) -> Json:
    return call("set_lighting", **settings)


def find(**args: Any) -> Json:
    return call("find_assets", **args)


def measure(a: str, b: str = EGO) -> Json:
    return call("measure_distance", a=a, b=b)


def landmarks(**args: Any) -> Json:
    return call("find_landmarks", **args)


def lanes(**args: Any) -> Json:
    return call("find_lanes", **args)


def properties(**args: Any) -> Json:
    return call("asset_properties", **args)


def environment() -> Json:
    return call("describe_environment")


def turn(prompt: str, *calls: Json, planned: bool = False) -> Json:
    """An earlier turn: replayed as given, or planned by the planner under test."""
    out: Json = {"prompt": prompt, "calls": list(calls)}
    if planned:
        out["planned"] = True
    return out


def planned(step: Json) -> Json:
    """The same earlier turn, planned by the planner under test (its calls are only the reference)."""
    return {**step, "planned": True}


# --- Checks ------------------------------------------------------------------------------------
def _selecting(
    kind: str,
    category: str | list[str] | None,
    asset: str | None,
    scope: str | None,
    min_count: int | None,
    require_all: bool | None,
    **extra: Any,
) -> Json:
    out: Json = {"kind": kind}
    if category is not None:
        out["category"] = category
    if asset is not None:
        out["asset"] = asset
    if scope is not None:
        out["scope"] = scope
    if min_count is not None:
        out["min_count"] = min_count
    if require_all is not None:
        out["require_all"] = require_all
    out.update({k: v for k, v in extra.items() if v is not None})
    return out


def only(*categories: str, assets: Iterable[str] = (), env: bool = False) -> Json:
    """Nothing changed but assets of these categories or ids (and the environment if allowed)."""
    out: Json = {"kind": "unchanged_except"}
    if categories:
        out["categories"] = list(categories)
    ids = list(assets)
    if ids:
        out["assets"] = ids
    if env:
        out["environment"] = True
    return out


def delta(category: str | list[str], lo: int | None, hi: int | None) -> Json:
    out: Json = {"kind": "count_delta", "category": category}
    if lo is not None:
        out["min"] = lo
    if hi is not None:
        out["max"] = hi
    return out


def count(category: str | list[str], lo: int | None, hi: int | None) -> Json:
    out: Json = {"kind": "count", "category": category}
    if lo is not None:
        out["min"] = lo
    if hi is not None:
        out["max"] = hi
    return out


def near(
    target: str | None,
    within: float,
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    scope: str | None = None,
    min_count: int | None = None,
    every: bool = False,
    point: tuple[float, float] | None = None,
) -> Json:
    out = _selecting("near", category, asset, scope, min_count, True if every else None, within=within)
    if point is not None:
        out["point"] = list(point)
    else:
        out["target"] = target
    return out


def relative(
    relation: str,
    target: str,
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    max_distance: float | None = None,
    tolerance_deg: float | None = None,
    every: bool = False,
) -> Json:
    return _selecting(
        "relative",
        category,
        asset,
        None,
        None,
        True if every else None,
        relation=relation,
        target=target,
        max_distance=max_distance,
        tolerance_deg=tolerance_deg,
    )


def on(
    surfaces: list[str], category: str | list[str] | None = None, *, asset: str | None = None, scope: str | None = None
) -> Json:
    return _selecting("on_surface", category, asset, scope, None, None, surfaces=surfaces)


def in_lane(
    lane: str | None,
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    scope: str | None = None,
    aligned: bool | None = None,
) -> Json:
    return _selecting("in_lane", category, asset, scope, None, None, lane=lane, aligned=aligned)


def layout(
    shape: str,
    category: str | list[str],
    min_count: int,
    *,
    around: str | None = None,
    tolerance: float | None = None,
    spacing_min: float | None = None,
    spacing_max: float | None = None,
    scope: str | None = None,
) -> Json:
    return _selecting(
        "arrangement",
        category,
        None,
        scope,
        min_count,
        None,
        shape=shape,
        around=around,
        tolerance=tolerance,
        spacing_min=spacing_min,
        spacing_max=spacing_max,
    )


def does(
    behaviour: str | list[str],
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    scope: str | None = None,
    min_count: int | None = None,
    **params: Any,
) -> Json:
    return _selecting("behaviour", category, asset, scope, min_count, None, behaviour=behaviour, **params)


def env(**fields: Any) -> Json:
    return {"kind": "environment", **fields}


def looks(
    colour: str | list[str] | None = None,
    category: str | list[str] | None = None,
    *,
    asset: str | None = None,
    scope: str | None = None,
    tolerance: float | None = None,
    material: str | None = None,
    every: bool = False,
    min_count: int | None = None,
) -> Json:
    return _selecting(
        "appearance",
        category,
        asset,
        scope,
        min_count,
        True if every else None,
        colour=colour,
        colour_tolerance=tolerance,
        material=material,
    )


def moved(
    asset: str,
    lo: float = 0.0,
    hi: float | None = None,
    direction: str | None = None,
    turn_min: float | None = None,
    turn_max: float | None = None,
) -> Json:
    out: Json = {"kind": "moved", "asset": asset, "min_distance": lo}
    if hi is not None:
        out["max_distance"] = hi
    if direction is not None:
        out["direction"] = direction
    if turn_min is not None:
        out["turn_min_deg"] = turn_min
    if turn_max is not None:
        out["turn_max_deg"] = turn_max
    return out


def gone(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": False}


def kept(*assets: str) -> Json:
    return {"kind": "exists", "assets": list(assets), "present": True}


def says(all_of: Sequence[str] = (), any_of: Sequence[str] = (), none_of: Sequence[str] = ()) -> Json:
    out: Json = {"kind": "answer_contains"}
    if all_of:
        out["all_of"] = list(all_of)
    if any_of:
        out["any_of"] = list(any_of)
    if none_of:
        out["none_of"] = list(none_of)
    return out


def refused() -> Json:
    return {"kind": "status", "accepted": False}


def event_played(actor: str, kind: str, seconds: float) -> Json:
    """The storyboard gives `actor` (an id or a category) a manoeuvre of `kind` that starts within `seconds`."""
    return {"kind": "scenario", "seconds": seconds, "expect": [{"kind": "event", "actor": actor, "manoeuvre": kind}]}


def ego_speed_between(lo: float, hi: float) -> list[list[Json]]:
    """Fair readings of a new ego speed: its lane behaviour at that speed, or a change-of-speed manoeuvre."""
    return [
        [does("drive_lane", asset=EGO, speed_min=lo, speed_max=hi)],
        [event_played(EGO, "change_speed", 3.0)],
    ]


def new_speed(actor: str, lo: float, hi: float) -> list[list[Json]]:
    """Fair readings of a new speed: the lane behaviour at that speed, or a change-of-speed manoeuvre."""
    return [
        [does("drive_lane", asset=actor, speed_min=lo, speed_max=hi)],
        [event_played(actor, "change_speed", 3.0)],
    ]


def slows_down(actor: str, seconds: float = 20.0) -> list[list[Json]]:
    """Fair readings of braking: a stop, or a change of speed (down), started within `seconds`."""
    return [[event_played(actor, "stop", seconds)], [event_played(actor, "change_speed", seconds)]]


def backs_up(asset: str, lo: float, hi: float) -> list[list[Json]]:
    """Fair readings of backing up: a shift backwards, or a reverse manoeuvre."""
    return [[moved(asset, lo, hi, "backward")], [event_played(asset, "reverse", 3.0)]]


def walks_over(lane: str | None = None, seconds: float = 10.0) -> list[list[Json]]:
    """Fair readings of a walker going over the road: a crossing or jaywalk behaviour, or a crossing manoeuvre."""
    return [
        [does(["cross_road", "jaywalk"], "pedestrian", crosses_lane=lane)],
        [event_played("pedestrian", "cross_road", seconds)],
    ]


def gets_going(asset: str) -> list[list[Json]]:
    """Fair readings of setting a parked vehicle off: a driving behaviour of any kind, or a manoeuvre."""
    return [
        [does(["drive_lane", "follow_path", "circle"], asset=asset)],
        [event_played(asset, "keep_lane", 3.0)],
        [event_played(asset, "follow_route", 3.0)],
        [event_played(asset, "change_speed", 3.0)],
    ]


def some_in_lane(lane: str, category: str | list[str]) -> Json:
    """At least one of the added or changed assets of these categories stands in `lane` (a block across it)."""
    return {"kind": "in_lane", "category": category, "lane": lane, "require_all": False}


def darker() -> list[list[Json]]:
    """Fair readings of 'darker': a clock time from early evening to before dawn, or a lower exposure."""
    return [[env(time_from="17:30", time_to="06:00")], [env(exposure_max=0.85)]]


def stops_before(actor: str, x: float, y: float, seconds: float = 20.0) -> Json:
    """Run the scene: `actor` never crosses the point (x, y) it drives towards and ends stopped."""
    return {
        "kind": "scenario",
        "seconds": seconds,
        "expect": [{"kind": "stopped_before", "actor": actor, "line": [x, y]}],
    }


def any_shape(category: str | list[str], least: int, tolerance: float = 1.0) -> list[list[Json]]:
    """Fair readings of 'a pattern', 'some shape' or 'a nice composition': a line, a ring or a tight cluster."""
    return [
        [layout("line", category, least, tolerance=tolerance)],
        [layout("ring", category, least, tolerance=tolerance)],
        [layout("cluster", category, least, tolerance=6.0)],
    ]


def timed_event(actor: str, kind: str, seconds: float, passes: tuple[float, float]) -> Json:
    """Run the scene: `actor` has a `kind` manoeuvre started by a clock (time) trigger within `seconds`, and
    first gets as far as `passes` (so the manoeuvre did not start at once)."""
    return {
        "kind": "scenario",
        "seconds": seconds,
        "expect": [
            {"kind": "event", "actor": actor, "manoeuvre": kind, "trigger": "simulation_time"},
            {"kind": "reached", "actor": actor, "place": f"{passes[0]:g}, {passes[1]:g}", "within": 3.0},
        ],
    }


def reaches(actor: str, place: str, seconds: float, within: float = 4.0) -> Json:
    """Run the scene: `actor` comes within `within` metres of `place`."""
    return {
        "kind": "scenario",
        "seconds": seconds,
        "expect": [{"kind": "reached", "actor": actor, "place": place, "within": within}],
    }


# --- Cases -------------------------------------------------------------------------------------
class Suite:
    """Cases of one suite, their ids and tags led by its tag."""

    def __init__(self, tag: str) -> None:
        self.tag = tag

    @property
    def path(self) -> Path:
        """Where the suite's JSONL lives: `suites/<tag>.jsonl` beside the sources."""
        return Path(__file__).resolve().with_name("suites") / f"{self.tag}.jsonl"

    def write(self, cases: list[Json]) -> None:
        """Write the suite's JSONL, one case a line."""
        self.path.parent.mkdir(parents=True, exist_ok=True)
        lines = [json.dumps(c, ensure_ascii=False) for c in cases]
        self.path.write_text("\n".join(lines) + "\n", encoding="utf-8")
        print(f"wrote {len(lines)} cases to {self.path}")

    def case(
        self,
        task: str,
        grade: str,
        name: str,
        voice: str,
        prompt: str,
        checks: list[Json],
        reference: list[Json],
        *,
        setup: Sequence[Json] = (),
        alternatives: Sequence[list[Json]] = (),
        tags: Sequence[str] = (),
    ) -> Json:
        """One case; `multi_turn` and `compound` tags follow from its setup and its reference."""
        all_tags = [self.tag, *tags]
        if setup:
            all_tags.append("multi_turn")
        if len(reference) >= 2:
            all_tags.append("compound")
        out: Json = {"id": f"{self.tag}.{task}.{grade}.{name}", "world": "campus"}
        if setup:
            out["setup"] = list(setup)
        out.update({"prompt": prompt, "task": task, "grade": grade, "tags": all_tags, "checks": checks})
        if alternatives:
            out["alternatives"] = [list(alt) for alt in alternatives]
        out["reference"] = reference
        out["notes"] = voice
        return out

    def impossible(
        self,
        task: str,
        grade: str,
        name: str,
        voice: str,
        prompt: str,
        reference: list[Json],
        *,
        setup: Sequence[Json] = (),
    ) -> Json:
        """A request the world cannot do: the right outcome is a refusal that changes nothing.

        The reference is the call a literal reading makes, which the Workers refuse."""
        return self.case(
            task, grade, name, voice, prompt, [refused(), only()], reference, setup=setup, tags=("impossible",)
        )

    # Search: questions that must change nothing, whose answer names the right thing.
    def ask(
        self,
        grade: str,
        name: str,
        voice: str,
        prompt: str,
        answer: Sequence[str],
        reference: list[Json],
        *,
        any_of: Sequence[str] = (),
        setup: Sequence[Json] = (),
    ) -> Json:
        """A question: the answer names what is asked for and the scene stays as it was."""
        return self.case(
            "search", grade, name, voice, prompt, [says(all_of=answer, any_of=any_of), only()], reference, setup=setup
        )


def hold(light: str, state: str, seconds: float = 600.0) -> Json:
    """A traffic light held in one state for `seconds`."""
    return call("set_light_phases", light=light, phases=[{"state": state, "duration": seconds}])


def reach(place: str, actor: str = EGO) -> Json:
    """A trigger: `actor` reaches `place`."""
    return {"kind": "reach", "actor": actor, "place": place}
