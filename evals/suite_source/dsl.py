"""Short builders for writing eval cases in Python; `build.py` turns them into JSON Lines.

Only the generated `evals/suites/*.jsonl` ship; this folder is authoring tooling. Every
builder returns plain JSON data, exactly what a suite line holds.
"""

from __future__ import annotations

from typing import Any

Json = dict[str, Any]
VEHICLES = ["passenger_car", "suv"]


# Tool calls (reference plans and setup turns) ----------------------------------------------
def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": {k: v for k, v in args.items() if v is not None}}


def loc(relation: str = "at", target: str | None = None, **kw: Any) -> Json:
    out: Json = {"relation": relation}
    if target is not None:
        out["target"] = target
    out.update({k: v for k, v in kw.items() if v is not None})
    return out


def add(category: str, where: Json | None = None, count: int | None = None, **kw: Any) -> Json:
    return call("add_asset", category=category, count=count, location=where, **kw)


def arrange(categories: list[str], shape: str, where: Json, **kw: Any) -> Json:
    return call("arrange_assets", categories=categories, shape=shape, location=where, **kw)


def behaviour(kind: str, **kw: Any) -> Json:
    return {"kind": kind, **{k: v for k, v in kw.items() if v is not None}}


def step(prompt: str, *calls: Json, planned: bool = False) -> Json:
    return {"prompt": prompt, "calls": list(calls), "planned": planned}


# Checks ------------------------------------------------------------------------------------
def _clean(d: Json) -> Json:
    return {k: v for k, v in d.items() if v is not None}


def delta(category: str | list[str] | None, lo: int | None = None, hi: int | None = None) -> Json:
    return _clean({"kind": "count_delta", "category": category, "min": lo, "max": hi})


def exactly(category: str | list[str] | None, n: int) -> Json:
    return delta(category, n, n)


def count(category: str | list[str] | None, lo: int | None = None, hi: int | None = None) -> Json:
    return _clean({"kind": "count", "category": category, "min": lo, "max": hi})


def _sel(category: Any, asset: str | None, scope: str | None, n: int | None, every: bool | None) -> Json:
    return _clean({"category": category, "asset": asset, "scope": scope, "min_count": n, "require_all": every})


def near(
    category: Any = None,
    target: str | None = None,
    within: float = 10.0,
    *,
    asset: str | None = None,
    point: list[float] | None = None,
    scope: str | None = None,
    n: int | None = None,
    every: bool | None = None,
) -> Json:
    return {
        "kind": "near",
        **_sel(category, asset, scope, n, every),
        **_clean({"target": target, "point": point}),
        "within": within,
    }


def relative(
    relation: str,
    target: str,
    category: Any = None,
    *,
    asset: str | None = None,
    max_distance: float | None = None,
    tolerance_deg: float | None = None,
) -> Json:
    return {
        "kind": "relative",
        **_sel(category, asset, None, None, None),
        "relation": relation,
        "target": target,
        **_clean({"max_distance": max_distance, "tolerance_deg": tolerance_deg}),
    }


def surface(surfaces: list[str], category: Any = None, *, asset: str | None = None) -> Json:
    return {"kind": "on_surface", **_sel(category, asset, None, None, None), "surfaces": surfaces}


def in_lane(
    lane: str | None = None,
    category: Any = None,
    *,
    asset: str | None = None,
    aligned: bool | None = None,
    every: bool | None = None,
) -> Json:
    return {"kind": "in_lane", **_sel(category, asset, None, None, every), **_clean({"lane": lane, "aligned": aligned})}


def shape(
    kind: str,
    category: Any = None,
    *,
    around: str | None = None,
    n: int | None = None,
    tolerance: float | None = None,
    spacing: tuple[float, float] | None = None,
) -> Json:
    lo, hi = spacing if spacing else (None, None)
    return {
        "kind": "arrangement",
        **_sel(category, None, None, n, None),
        "shape": kind,
        **_clean({"around": around, "tolerance": tolerance, "spacing_min": lo, "spacing_max": hi}),
    }


def does(
    kind: str | list[str], category: Any = None, *, asset: str | None = None, scope: str | None = None, **params: Any
) -> Json:
    return {"kind": "behaviour", **_sel(category, asset, scope, None, None), "behaviour": kind, **_clean(params)}


def env(**kw: Any) -> Json:
    return {"kind": "environment", **_clean(kw)}


def looks(
    colour: str | list[str] | None = None,
    category: Any = None,
    *,
    asset: str | None = None,
    material: str | None = None,
    scope: str | None = None,
    every: bool | None = None,
) -> Json:
    return {
        "kind": "appearance",
        **_sel(category, asset, scope, None, every),
        **_clean({"colour": colour, "material": material}),
    }


def moved(
    asset: str,
    lo: float = 0.0,
    hi: float | None = None,
    direction: str | None = None,
    turn: tuple[float | None, float | None] | None = None,
) -> Json:
    t_lo, t_hi = turn if turn else (None, None)
    return _clean(
        {
            "kind": "moved",
            "asset": asset,
            "min_distance": lo,
            "max_distance": hi,
            "direction": direction,
            "turn_min_deg": t_lo,
            "turn_max_deg": t_hi,
        }
    )


def gone(*ids: str) -> Json:
    return {"kind": "exists", "assets": list(ids), "present": False}


def present(*ids: str) -> Json:
    return {"kind": "exists", "assets": list(ids), "present": True}


def only(*categories: str, assets: tuple[str, ...] = (), environment: bool = False) -> Json:
    """Nothing else changed: only these categories / asset ids (and the weather if allowed)."""
    return _clean(
        {
            "kind": "unchanged_except",
            "categories": list(categories) or None,
            "assets": list(assets) or None,
            "environment": environment or None,
        }
    )


def says(*, any_of: list[str] | None = None, all_of: list[str] | None = None, none_of: list[str] | None = None) -> Json:
    return {"kind": "answer_contains", **_clean({"any_of": any_of, "all_of": all_of, "none_of": none_of})}


def accepted() -> Json:
    return {"kind": "status", "accepted": True}


# Cases -------------------------------------------------------------------------------------
# Shorthands the later practice suites share (practice4, practice5) ---------------------------
def refused() -> Json:
    return {"kind": "status", "accepted": False}


def nothing_changed() -> Json:
    return only()


def every(check: Json, n: int | None = None) -> Json:
    """The same selecting check, passed by every selected asset (and at least n of them)."""
    out = {**check, "require_all": True}
    if n is not None:
        out["min_count"] = n
    return out


def added(check: Json) -> Json:
    return {**check, "scope": "added"}


def ring(category: Any, around: str | None = None, n: int = 3) -> Json:
    return shape("ring", category, around=around, n=n, tolerance=1.5)


def line(category: Any, n: int = 3, spacing: tuple[float, float] | None = None) -> Json:
    return shape("line", category, n=n, tolerance=1.0, spacing=spacing)


def drives(category: Any = None, *, asset: str | None = None, lane: str | None = None,
           speed: tuple[float | None, float | None] = (None, None), every_one: bool = False) -> Json:
    out = does("drive_lane", category, asset=asset, lane=lane, speed_min=speed[0], speed_max=speed[1])
    return {**out, "require_all": True} if every_one else out


def place(asset: str, where: Json, yaw: float | None = None) -> Json:
    return call("place_asset", asset=asset, location=where, yaw_deg=yaw)


def shift(asset: str | None = None, **kw: Any) -> Json:
    return call("move_asset", asset=asset, **kw)


def act(asset: str, kind: str, **kw: Any) -> Json:
    return call("set_behaviour", asset=asset, behaviour=behaviour(kind, **kw))


def remove(*ids: str, **kw: Any) -> Json:
    return call("remove_assets", assets=list(ids) if ids else None, **kw)


def find(**kw: Any) -> Json:
    return call("find_assets", **kw)


def marks(**kw: Any) -> Json:
    return call("find_landmarks", **kw)


def weather(kind: str, intensity: float | None = None) -> Json:
    return call("set_weather", kind=kind, intensity=intensity)


def clock(time: str) -> Json:
    return call("set_time_of_day", time=time)


def lights(**kw: Any) -> Json:
    return call("set_lighting", **kw)


def paint(*ids: str, category: str | None = None, colour: str | None = None, material: str | None = None) -> Json:
    return call("set_asset_appearance", assets=list(ids) if ids else None, category=category,
                colour=colour, material=material)


def case(
    cid: str,
    task: str,
    grade: str,
    prompt: str,
    checks: list[Json],
    reference: list[Json],
    *,
    setup: list[Json] | None = None,
    tags: list[str] | None = None,
    alternatives: list[list[Json]] | None = None,
    notes: str = "",
) -> Json:
    out: Json = {"id": cid, "world": "campus"}
    if setup:
        out["setup"] = setup
    out.update({"prompt": prompt, "task": task, "grade": grade})
    if tags:
        out["tags"] = tags
    out["checks"] = checks
    if alternatives:
        out["alternatives"] = alternatives
    out["reference"] = reference
    if notes:
        out["notes"] = notes
    return out


# Setup turns used by many cases ------------------------------------------------------------
RUBBLE = step("create cement rubble at the centre of the scene", add("cement_rubble", loc("at", "main intersection")))
CONES = step(
    "add traffic cones to mark the maintenance",
    arrange(["traffic_cone"], "ring", loc("at", "cement_rubble_1"), label="maintenance"),
)
NIGHT = step("make it night", call("set_time_of_day", time="night"))
RAIN = step("make it rain", call("set_weather", kind="rain"))
PEDESTRIAN = step("add a pedestrian at the bus stop", add("pedestrian", loc("at", "bus stop")))
ROBOT = step("add a robot in parking lot B", add("ackermann_robot", loc("at", "parking lot B")))
CAR_AT_JTEKT = step(
    "add a parked car at the JTEKT building entrance",
    add("passenger_car", loc("at", "JTEKT building entrance"), behaviour=behaviour("parked")),
)
TRUCK_AT_UNION = step(
    "add a delivery truck at the Student Union entrance", add("truck", loc("at", "Student Union entrance"))
)
CONES_AT_JTEKT = step(
    "add five traffic cones in front of the JTEKT building entrance",
    arrange(["traffic_cone"], "line", loc("in_front_of", "JTEKT building entrance"), count=5),
)
TWO_PEDESTRIANS = step(
    "add two pedestrians near the Library entrance", add("pedestrian", loc("at", "Library entrance"), count=2)
)
