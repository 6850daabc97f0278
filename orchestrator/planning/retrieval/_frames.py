"""The bank grammar's frames: one kind of request each, worded many ways, with its calls.

A frame draws what the request is about from the world (a category, a landmark, an asset, a
number), builds the Worker calls that do it, and words it with one of its own templates:
plain, polite, indirect, negated or as a question. Each draft also records its slots (what
the words named, in order) so that retrieval can put this request's names in their place,
and the Sr. manager's requirements, so that drafts double as few-shot demonstrations.
The wording is written for the bank from the catalog and the world, not from any eval suite.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from drivetwin.orchestrator.planning.retrieval._words import Words
from drivetwin.tools.appearance import COLOURS

Slot = tuple[str, Any]

# Relation -> ways to say it before a place.
RELATION_WORDS: dict[str, tuple[str, ...]] = {
    "at": ("at", "by the side of", "over at"),
    "next_to": ("next to", "beside", "near", "close to", "by", "alongside", "around"),
    "in_front_of": ("in front of", "ahead of", "just in front of", "facing"),
    "behind": ("behind", "in back of", "at the back of", "round the back of"),
    "left_of": ("to the left of", "left of", "on the left side of"),
    "right_of": ("to the right of", "right of", "on the right side of"),
    "on_sidewalk": ("on the sidewalk at", "on the pavement by", "on the footpath near", "on the kerb by"),
}
ADD_VERBS = (
    "add {n} {thing} {where}",
    "put {n} {thing} {where}",
    "place {n} {thing} {where}",
    "spawn {n} {thing} {where}",
    "drop {n} {thing} {where}",
    "insert {n} {thing} {where}",
    "i'd like {n} {thing} {where}",
    "could you add {n} {thing} {where}?",
    "can we get {n} {thing} {where}",
    "there should be {n} {thing} {where}",
    "we need {n} {thing} {where}",
    "{n} {thing} {where} please",
    "please put {n} {thing} {where}",
    "i want {n} {thing} {where}",
    "{where}, add {n} {thing}",
    "would you mind placing {n} {thing} {where}",
    "let's have {n} {thing} {where}",
    "give me {n} {thing} {where}",
    "stick {n} {thing} {where}",
    "need {n} {thing} {where}",
    "set up {n} {thing} {where}",
    "how about {n} {thing} {where}",
)
REMOVE_VERBS = (
    "remove {the} {thing}{near}",
    "delete {the} {thing}{near}",
    "get rid of {the} {thing}{near}",
    "take away {the} {thing}{near}",
    "clear {the} {thing}{near}",
    "i no longer want {the} {thing}{near}",
    "we don't need {the} {thing}{near} anymore",
    "lose {the} {thing}{near}",
    "drop {the} {thing}{near} from the scene",
    "please remove {the} {thing}{near}",
    "could you delete {the} {thing}{near}?",
    "no more {thing}{near}",
    "there shouldn't be any {thing}{near}",
    "{the} {thing}{near} must go",
    "erase {the} {thing}{near}",
    "can you take out {the} {thing}{near}",
    "pull out {the} {thing}{near}",
    "i don't want {the} {thing}{near} there",
)
PLACE_VERBS = (
    "move {asset} {where}",
    "put {asset} {where}",
    "relocate {asset} {where}",
    "place {asset} {where}",
    "could you move {asset} {where}?",
    "i want {asset} {where}",
    "{asset} should stand {where}",
    "take {asset} and put it {where}",
    "shift {asset} over {where}",
    "bring {asset} {where}",
    "reposition {asset} {where}",
    "park {asset} {where}",
)
SHAPES: dict[str, tuple[str, ...]] = {
    "line": (
        "a line of {n} {thing} {where}",
        "a row of {n} {thing} {where}",
        "{n} {thing} in a line {where}",
        "line up {n} {thing} {where}",
        "{n} {thing} in a row {where}",
        "a straight line of {n} {thing} {where}",
    ),
    "ring": (
        "a ring of {n} {thing} around {place}",
        "a circle of {n} {thing} around {place}",
        "surround {place} with {n} {thing}",
        "{n} {thing} in a circle round {place}",
        "encircle {place} with {n} {thing}",
        "put {n} {thing} all around {place}",
    ),
    "grid": (
        "a grid of {n} {thing} {where}",
        "{n} {thing} in a grid {where}",
        "a block of {n} {thing} {where}",
        "a square pattern of {n} {thing} {where}",
    ),
}
ARRANGE_LEADS = ("", "add ", "make ", "build ", "lay out ", "could you set up ", "i'd like ", "please create ")
MOVE_DIRECTIONS: tuple[tuple[str, str, int], ...] = (
    ("forward", "forward", 1),
    ("ahead", "forward", 1),
    ("backward", "forward", -1),
    ("back", "forward", -1),
    ("to the left", "left", 1),
    ("left", "left", 1),
    ("to the right", "left", -1),
    ("right", "left", -1),
)
MOVE_VERBS = (
    "move {asset} {d} {dir}",
    "shift {asset} {d} {dir}",
    "nudge {asset} {d} {dir}",
    "push {asset} {dir} by {d}",
    "{asset} {d} {dir} please",
    "can you slide {asset} {d} {dir}?",
    "roll {asset} {d} {dir}",
)
TURN_VERBS = (
    "turn {asset} {a} degrees",
    "rotate {asset} by {a} degrees",
    "spin {asset} {a} deg",
    "turn {asset} around {a} degrees",
    "rotate {asset} {a}°",
)
WEATHER: dict[str, tuple[str, ...]] = {
    "rain": ("rain", "raining", "rainy", "wet weather", "showers", "a downpour"),
    "snow": ("snow", "snowing", "snowy", "a snowfall", "wintry"),
    "fog": ("fog", "foggy", "misty", "mist", "hazy", "murky"),
    "cloudy": ("clouds", "cloudy", "overcast", "grey skies"),
    "clear": ("clear", "sunny", "fine weather", "clear skies", "dry"),
}
STRENGTHS: tuple[tuple[str, float], ...] = (
    ("light", 0.3),
    ("slight", 0.3),
    ("gentle", 0.3),
    ("moderate", 0.6),
    ("medium", 0.6),
    ("heavy", 0.9),
    ("thick", 0.9),
    ("strong", 0.9),
    ("torrential", 0.9),
    ("dense", 0.9),
)
WEATHER_VERBS = (
    "make it {w}",
    "i want {w}",
    "switch the weather to {w}",
    "can it be {w}?",
    "let it be {w}",
    "the weather should be {w}",
    "set {w} weather",
    "give us {w}",
    "change weather to {w}",
    "we need {w} for this test",
    "{w} please",
    "turn the weather {w}",
)
TIME_WORDS: tuple[tuple[str, str], ...] = (
    ("dawn", "dawn"),
    ("sunrise", "sunrise"),
    ("early morning", "dawn"),
    ("morning", "morning"),
    ("noon", "noon"),
    ("midday", "noon"),
    ("the afternoon", "afternoon"),
    ("sunset", "sunset"),
    ("dusk", "dusk"),
    ("evening", "evening"),
    ("night", "night"),
    ("nighttime", "night"),
    ("midnight", "midnight"),
    ("daytime", "day"),
    ("broad daylight", "day"),
)
TIME_VERBS = (
    "set the time to {t}",
    "make it {t}",
    "change the clock to {t}",
    "switch to {t}",
    "it should be {t}",
    "go to {t}",
    "jump to {t}",
    "can we have {t}?",
    "time: {t}",
    "put the sun at {t}",
    "let's see it at {t}",
)
SEARCH_WHERE = (
    "whereabouts is {place}?",
    "point me to {place}",
    "find {place}",
    "show me {place}",
    "locate {place}",
    "what are the coordinates of {place}?",
    "how do i find {place}",
    "i can't find {place}, where is it",
    "position of {place}?",
)
SEARCH_COUNT = (
    "how many {things} are there?",
    "count the {things}",
    "how many {things} does the scene have",
    "list all {things}",
    "are there any {things}?",
    "show me every {thing}",
    "what {things} exist?",
    "tell me how many {things} there are, don't change anything",
    "number of {things}?",
)
SEARCH_NEAR = (
    "which {things} are near {place}?",
    "any {things} around {place}?",
    "list {things} close to {place}",
    "what {things} are by {place}",
    "is there a {thing} near {place}?",
    "find {things} next to {place}",
)


@dataclass
class Draft:
    """One generated request: its words, its calls, its task, slots, requirements and tags."""

    request: str
    calls: list[dict[str, Any]]
    task: str
    slots: list[Slot] = field(default_factory=list)
    requirements: list[dict[str, str]] = field(default_factory=list)
    tags: list[str] = field(default_factory=list)


def _call(tool: str, **args: Any) -> dict[str, Any]:
    return {"tool": tool, "args": {k: v for k, v in args.items() if v is not None}}


def _need(kind: str, what: str = "", where: str = "", how: str = "") -> dict[str, str]:
    return {"kind": kind, "what": what, "where": where, "how": how}


def _fill(template: str, **words: str) -> str:
    return " ".join(template.format(**words).split())


def _count_words(w: Words, n: int) -> str:
    return w.pick(("a", "one", "another", "a single")) if n == 1 else w.count(n)


def _article(text: str) -> str:
    return ("an " if text[:1] in "aeiou" else "a ") + text


def _where(w: Words, relation: str | None = None) -> tuple[str, dict[str, Any], list[Slot]]:
    """A place phrase, the Location it means and its slots (relation to a landmark, a lane,
    a distance from a landmark, or coordinates on a lane)."""
    roll = w.rng.random()
    if roll < 0.1 and w.lanes:
        lane = w.pick(w.lanes)
        return (
            f"{w.pick(('in', 'on', 'along'))} {w.lane(lane)}",
            {"relation": "in_lane", "target": lane},
            [("lane", lane)],
        )
    if roll < 0.18 and w.lanes:
        road = w.scene.roads.lanes[w.rng.randrange(len(w.scene.roads.lanes))]
        (x0, y0), (x1, y1) = road.centreline[0], road.centreline[-1]
        t = w.pick((0.2, 0.4, 0.6, 0.8))
        x, y = round(x0 + t * (x1 - x0)), round(y0 + t * (y1 - y0))
        said = w.pick((f"at x={x} y={y}", f"at ({x}, {y})", f"at coordinates {x}, {y}", f"at x {x} and y {y}"))
        return said, {"relation": "absolute", "x": x, "y": y}, [("x", x), ("y", y)]
    place = w.pick(w.landmarks)
    if roll < 0.3:
        d = float(w.pick(("3", "5", "10", "15")))
        rel = w.pick(("in_front_of", "behind"))
        said_rel = "in front of" if rel == "in_front_of" else w.pick(("behind", "back from"))
        return (
            f"{w.metres(d)} {said_rel} {w.place(place)}",
            {"relation": rel, "target": place, "distance": d},
            [("distance", d), ("place", place)],
        )
    relation = relation or w.pick(list(RELATION_WORDS))
    return (
        f"{w.pick(RELATION_WORDS[relation])} {w.place(place)}",
        {"relation": relation, "target": place},
        [("place", place)],
    )


def add(w: Words) -> Draft:
    name = w.pick(list(w.categories))
    n = w.pick((1, 1, 1, 1, 2, 2, 3, 3, 4, 5, 6, 8, 10, 12))
    where, location, place_slots = _where(w)
    thing = w.thing(name, n)
    colour = w.pick(list(COLOURS)) if w.rng.random() < 0.12 else None
    if colour:
        thing = f"{colour} {thing}"
    said_n = _count_words(w, n)
    if n == 1 and said_n == "a":
        said_n, thing = "", _article(thing)
    request = _fill(w.pick(ADD_VERBS), n=said_n, thing=thing, where=where)
    slots: list[Slot] = [("category", name)] + ([("count", n)] if n > 1 else []) + place_slots
    slots += [("colour", colour)] if colour else []
    call = _call("add_asset", category=name, count=n if n > 1 else None, location=location, colour=colour)
    how = (f"{n}" if n > 1 else "") + (f" {colour}" if colour else "")
    return Draft(request, [call], "addition", slots, [_need("add", thing, where, how.strip())])


def add_moving(w: Words) -> Draft:
    movers = {n: c for n, c in w.categories.items() if c.motion == "vehicle"}
    walkers = {n: c for n, c in w.categories.items() if c.motion == "walker" and n == "pedestrian"}
    if w.rng.random() < 0.6 and movers and w.lanes:
        name, lane = w.pick(list(movers)), w.pick(w.lanes)
        said_speed, speed = w.speed(w.rng.choice((3.0, 5.0, 6.0, 8.0, 10.0, 12.0)))
        form = w.pick(
            (
                "add {thing} driving {lane} at {speed}",
                "spawn {thing} that drives {lane} at {speed}",
                "i want {thing} moving {lane}, {speed}",
                "{thing} travelling {lane} at {speed} please",
                "put {thing} going {lane} at about {speed}",
            )
        )
        thing = _article(w.thing(name))
        request = _fill(form, thing=thing, lane=f"along {w.lane(lane)}", speed=said_speed)
        behaviour = {"kind": "drive_lane", "lane": lane, "speed": speed}
        call = _call("add_asset", category=name, location={"relation": "in_lane", "target": lane}, behaviour=behaviour)
        slots: list[Slot] = [("category", name), ("lane", lane), ("speed", speed)]
        return Draft(request, [call], "addition", slots, [_need("add", thing, lane, f"drive {said_speed}")])
    name = w.pick(list(walkers) or ["pedestrian"])
    if w.rng.random() < 0.5:
        form = w.pick(
            (
                "add a {thing} who jaywalks in front of the ego",
                "make {thing} jaywalk ahead of our car",
                "a {thing} should dash across the road in front of the ego vehicle",
                "i need a {thing} stepping out in front of the test car",
                "spawn a jaywalking {thing}",
            )
        )
        call = _call("add_asset", category=name, behaviour={"kind": "jaywalk"})
        request = _fill(form, thing=w.thing(name))
        return Draft(request, [call], "addition", [("category", name)], [_need("add", w.thing(name), "ego", "jaywalk")])
    place = w.pick([p for p in w.landmarks if "cross" in p.lower()] or w.landmarks)
    form = w.pick(
        (
            "add a {thing} who walks across the street at {place}",
            "a {thing} walking over {place}",
            "have a {thing} use {place} to cross",
            "put a {thing} crossing at {place}",
        )
    )
    call = _call(
        "add_asset", category=name, location={"relation": "at", "target": place}, behaviour={"kind": "cross_road"}
    )
    request = _fill(form, thing=w.thing(name), place=w.place(place))
    return Draft(
        request,
        [call],
        "addition",
        [("category", name), ("place", place)],
        [_need("add", w.thing(name), place, "cross the road")],
    )


def remove(w: Words) -> Draft | None:
    present = sorted({a.category for a in w.assets if a.category in w.categories})
    if not present:
        return None
    name = w.pick(present)
    roll = w.rng.random()
    near, slots = "", [("category", name)]
    args: dict[str, Any] = {"category": name}
    many = sum(1 for a in w.assets if a.category == name) > 1
    the = w.pick(("the", "all the", "every", "all")) if many else "the"
    if roll < 0.3 and many:
        place = w.pick(w.landmarks)
        near = f" {w.pick(('near', 'by', 'around', 'close to'))} {w.place(place)}"
        args["near"], args["count"] = place, 1
        slots.append(("place", place))
        the = w.pick(("the", "one", "the one"))
        thing = w.thing(name)
    elif roll < 0.5:
        asset = w.pick([a.id for a in w.assets])
        request = _fill(w.pick(REMOVE_VERBS), the="", thing=w.asset_words(asset), near="")
        return Draft(
            request, [_call("remove_assets", assets=[asset])], "removal", [("asset", asset)], [_need("remove", asset)]
        )
    else:
        thing = w.thing(name, 2) if (many and the != "the") or (many and w.rng.random() < 0.5) else w.thing(name)
    request = _fill(w.pick(REMOVE_VERBS), the=the, thing=thing, near=near)
    return Draft(request, [_call("remove_assets", **args)], "removal", slots, [_need("remove", thing, near.strip())])


def position(w: Words) -> Draft | None:
    if not w.assets:
        return None
    asset = w.pick([a.id for a in w.assets])
    where, location, place_slots = _where(w)
    request = _fill(w.pick(PLACE_VERBS), asset=w.asset_words(asset), where=where)
    return Draft(
        request,
        [_call("place_asset", asset=asset, location=location)],
        "positioning",
        [("asset", asset), *place_slots],
        [_need("position", asset, where)],
    )


def moving(w: Words) -> Draft | None:
    movable = [a.id for a in w.assets] + ["ego"]
    asset = w.pick(movable)
    said = "the ego vehicle" if asset == "ego" else w.asset_words(asset)
    if asset == "ego":
        said = w.pick(("the ego", "the ego vehicle", "our car", "the ego car"))
    roll = w.rng.random()
    if roll < 0.45:
        d = float(w.pick(("1", "2", "3", "4", "5", "6", "8", "10", "15")))
        words, key, sign = MOVE_DIRECTIONS[w.rng.randrange(len(MOVE_DIRECTIONS))]
        request = _fill(w.pick(MOVE_VERBS), asset=said, d=w.metres(d), dir=words)
        call = _call("move_asset", asset=asset, **{key: sign * d})
        return Draft(
            request, [call], "moving", [("asset", asset), ("distance", d)], [_need("move", said, "", f"{words} {d} m")]
        )
    if roll < 0.65:
        a = float(w.pick(("15", "30", "45", "90", "180", "270")))
        request = _fill(w.pick(TURN_VERBS), asset=said, a=f"{a:g}")
        return Draft(
            request,
            [_call("move_asset", asset=asset, turn_deg=a)],
            "moving",
            [("asset", asset), ("angle", a)],
            [_need("move", said, "", f"turn {a:g} degrees")],
        )
    vehicles = [a.id for a in w.assets if w.categories.get(a.category) and w.categories[a.category].motion == "vehicle"]
    if not vehicles or not w.lanes:
        return None
    asset = w.pick(vehicles)
    said = w.asset_words(asset)
    if w.rng.random() < 0.6:
        lane = w.pick(w.lanes)
        said_speed, speed = w.speed(w.rng.choice((4.0, 6.0, 8.0, 10.0)))
        form = w.pick(
            (
                "make {asset} drive {lane} at {speed}",
                "{asset} should start driving {lane} at {speed}",
                "let {asset} go {lane}, {speed}",
                "have {asset} travel {lane} at {speed}",
                "get {asset} moving {lane} at {speed}",
            )
        )
        request = _fill(form, asset=said, lane=f"along {w.lane(lane)}", speed=said_speed)
        call = _call("set_behaviour", asset=asset, behaviour={"kind": "drive_lane", "lane": lane, "speed": speed})
        return Draft(
            request,
            [call],
            "moving",
            [("asset", asset), ("lane", lane), ("speed", speed)],
            [_need("move", said, lane, f"drive {said_speed}")],
        )
    form = w.pick(
        (
            "stop {asset}",
            "park {asset} where it is",
            "{asset} should stay still",
            "make {asset} stand still",
            "{asset} must not move",
            "halt {asset}",
        )
    )
    request = _fill(form, asset=said)
    return Draft(
        request,
        [_call("set_behaviour", asset=asset, behaviour={"kind": "parked"})],
        "moving",
        [("asset", asset)],
        [_need("move", said, "", "parked")],
    )


def arrange(w: Words) -> Draft:
    name = w.pick([n for n, c in w.categories.items() if c.motion == "prop"] or list(w.categories))
    shape = w.pick(list(SHAPES))
    n = w.pick((3, 4, 5, 6, 8, 10, 12))
    place = w.pick(w.landmarks)
    relation = "next_to" if shape == "ring" else w.pick(("in_front_of", "at", "next_to", "behind"))
    where = f"{w.pick(RELATION_WORDS[relation])} {w.place(place)}"
    form = w.pick(SHAPES[shape])
    request = w.pick(ARRANGE_LEADS) + _fill(
        form, n=w.count(n), thing=w.thing(name, n), where=where, place=w.place(place)
    )
    call = _call(
        "arrange_assets",
        categories=[name],
        shape=shape,
        count=n,
        location={"relation": "at" if shape == "ring" else relation, "target": place},
    )
    return Draft(
        request,
        [call],
        "arrangement",
        [("category", name), ("count", n), ("place", place)],
        [_need("arrange", w.thing(name, n), where, f"{shape} of {n}")],
    )


def weather(w: Words) -> Draft:
    kind = w.pick(list(WEATHER))
    said = w.pick(WEATHER[kind])
    intensity = None
    if kind not in ("clear", "cloudy") and w.rng.random() < 0.5:
        strength, intensity = STRENGTHS[w.rng.randrange(len(STRENGTHS))]
        said = f"{strength} {WEATHER[kind][0]}"
    if kind == "clear" and w.rng.random() < 0.4:
        gone = w.pick(("rain", "fog", "snow", "clouds"))
        request = w.pick(
            (
                f"no more {gone}",
                f"stop the {gone}",
                f"i don't want {gone} anymore",
                f"get rid of the {gone}",
                f"the {gone} should stop",
            )
        )
    else:
        request = _fill(w.pick(WEATHER_VERBS), w=said)
    call = _call("set_weather", kind=kind, intensity=intensity)
    slots: list[Slot] = [("weather", kind)] + ([("intensity", intensity)] if intensity is not None else [])
    return Draft(request, [call], "appearance", slots, [_need("appearance", said, "", "")])


def time_of_day(w: Words) -> Draft:
    if w.rng.random() < 0.5:
        said, preset = TIME_WORDS[w.rng.randrange(len(TIME_WORDS))]
        value = preset
    else:
        hour, minute = w.rng.randrange(24), w.pick(("00", "15", "30", "45"))
        value = f"{hour:02d}:{minute}"
        pm = hour >= 12
        twelve = hour % 12 or 12
        said = (
            w.pick((value, f"{twelve}:{minute} {'pm' if pm else 'am'}"))
            if minute != "00"
            else w.pick(
                (
                    value,
                    f"{twelve} {'pm' if pm else 'am'}",
                    f"{twelve}{'pm' if pm else 'am'}",
                    f"{twelve} o'clock {'in the evening' if pm else 'in the morning'}",
                )
            )
        )
    request = _fill(w.pick(TIME_VERBS), t=said)
    return Draft(
        request,
        [_call("set_time_of_day", time=value)],
        "appearance",
        [("time", value)],
        [_need("appearance", said, "", "")],
    )


def lighting(w: Words) -> Draft:
    which = w.pick(("street_lights", "vehicle_lights"))
    state = w.pick(("on", "off"))
    said = (
        w.pick(("street lights", "streetlights", "lamp posts", "street lamps"))
        if which == "street_lights"
        else w.pick(("headlights", "car lights", "vehicle lights", "the cars' lamps"))
    )
    form = w.pick(
        (
            f"turn the {said} {state}",
            f"switch {state} the {said}",
            f"{said} {state} please",
            f"i want the {said} {state}",
            f"can you put the {said} {state}?",
            f"{state} with the {said}",
        )
    )
    return Draft(
        form,
        [_call("set_lighting", **{which: state})],
        "appearance",
        [("lights", state)],
        [_need("appearance", said, "", state)],
    )


def colour(w: Words) -> Draft | None:
    if not w.assets:
        return None
    paint = w.pick(list(COLOURS))
    if w.rng.random() < 0.5:
        asset = w.pick([a.id for a in w.assets])
        said = w.asset_words(asset)
        call, slots = _call("set_asset_appearance", assets=[asset], colour=paint), [("asset", asset), ("colour", paint)]
    else:
        name = w.pick(sorted({a.category for a in w.assets if a.category in w.categories}))
        said = "all " + w.thing(name, 2) if w.rng.random() < 0.5 else "every " + w.thing(name)
        call, slots = (
            _call("set_asset_appearance", category=name, colour=paint),
            [("category", name), ("colour", paint)],
        )
    form = w.pick(
        (
            "paint {x} {c}",
            "make {x} {c}",
            "colour {x} {c}",
            "i want {x} to be {c}",
            "recolour {x} to {c}",
            "{x} should be {c}",
            "can {x} be {c}?",
            "turn {x} {c}",
            "give {x} a {c} paint job",
        )
    )
    return Draft(_fill(form, x=said, c=paint), [call], "appearance", slots, [_need("appearance", said, "", paint)])


def search(w: Words) -> Draft | None:
    roll = w.rng.random()
    if roll < 0.3:
        place = w.pick(w.landmarks)
        request = _fill(w.pick(SEARCH_WHERE), place=w.place(place))
        return Draft(
            request, [_call("find_landmarks", query=place)], "search", [("place", place)], [_need("search", place)]
        )
    name = w.pick(list(w.categories))
    if roll < 0.65:
        request = _fill(w.pick(SEARCH_COUNT), things=w.thing(name, 2), thing=w.thing(name))
        return Draft(
            request,
            [_call("find_assets", category=name)],
            "search",
            [("category", name)],
            [_need("search", w.thing(name, 2))],
        )
    if roll < 0.85:
        place = w.pick(w.landmarks)
        request = _fill(w.pick(SEARCH_NEAR), things=w.thing(name, 2), thing=w.thing(name), place=w.place(place))
        return Draft(
            request,
            [_call("find_assets", category=name, near=place, within=20.0)],
            "search",
            [("category", name), ("place", place)],
            [_need("search", w.thing(name, 2), place)],
        )
    if roll < 0.93:
        place = w.pick(w.landmarks)
        form = w.pick(("which lane is closest to {place}?", "what lane runs by {place}", "nearest lane to {place}?"))
        return Draft(
            _fill(form, place=w.place(place)),
            [_call("find_lanes", near=place)],
            "search",
            [("place", place)],
            [_need("search", "lane", place)],
        )
    form = w.pick(("how big is {x}?", "what is {x}?", "tell me about {x}", "how heavy is {x}", "what size is {x}"))
    if w.assets and w.rng.random() < 0.5:
        asset = w.pick([a.id for a in w.assets])
        return Draft(
            _fill(form, x=w.asset_words(asset)),
            [_call("asset_properties", asset=asset)],
            "search",
            [("asset", asset)],
            [_need("search", asset)],
        )
    return Draft(
        _fill(form, x=_article(w.thing(name))),
        [_call("asset_properties", category=name)],
        "search",
        [("category", name)],
        [_need("search", w.thing(name))],
    )


DISTANCE_FORMS = (
    "how far is {a} from {b}?",
    "distance between {a} and {b}",
    "how far apart are {a} and {b}",
    "what's the distance from {a} to {b}",
    "how many metres from {a} to {b}?",
    "is {a} far from {b}?",
    "measure from {a} to {b}",
    "how far do i have to walk from {a} to {b}",
)
DISTANCE_FROM_EGO = ("how far away is {a}?", "how far is {a} from me", "how far is {a} from the ego", "is {a} far?")


def distance(w: Words) -> Draft | None:
    """A distance asked between two places or things, or from the asker (the ego)."""
    ends = [*w.landmarks, *(a.id for a in w.assets if a.id != "ego")]
    a = w.pick(ends)
    said = w.asset_words(a) if a not in w.landmarks else w.place(a)
    if w.rng.random() < 0.3:
        request, b, slots = _fill(w.pick(DISTANCE_FROM_EGO), a=said), "ego", [_end(w, a)]
    else:
        b = w.pick([e for e in ends if e != a])
        other = w.asset_words(b) if b not in w.landmarks else w.place(b)
        request, slots = _fill(w.pick(DISTANCE_FORMS), a=said, b=other), [_end(w, a), _end(w, b)]
    return Draft(request, [_call("measure_distance", a=a, b=b)], "search", slots, [_need("search", "distance", said)])


# How the world is now, asked: the weather, the clock, the light (answered, never set).
SETTING_QUESTIONS = (
    "is it {weather} at the moment?",
    "{weather} right now or not?",
    "tell me if it's {weather}",
    "what is the weather doing",
    "how's the weather in this scene?",
    "what time of day is it set to",
    "which hour is it in the world?",
    "is it {time} or day at the moment",
    "are the {lamps} lit?",
    "are the {lamps} on at the moment",
    "is it dark in there?",
)


def asked_setting(w: Words) -> Draft:
    """A question about the weather, the time or the lights: a description, nothing set."""
    form = w.pick(SETTING_QUESTIONS)
    weather = w.pick(("raining", "snowing", "foggy", "cloudy", "sunny", "misty", "wet"))
    lamps = w.pick(("street lights", "lamp posts", "headlights"))
    request = form.format(weather=weather, time=w.pick(("night", "evening", "dusk")), lamps=lamps)
    return Draft(request, [_call("describe_environment")], "search", [], [_need("search", "environment")])


def _end(w: Words, name: str) -> Slot:
    return ("place", name) if name in w.landmarks else ("asset", name)


# Frame -> how many drafts of it a bank gets, per world (the bank has >= 3,000 in all).
FRAMES: dict[Callable[[Words], Draft | None], int] = {
    add: 1100,
    add_moving: 250,
    remove: 450,
    position: 350,
    moving: 450,
    arrange: 400,
    weather: 200,
    time_of_day: 150,
    lighting: 60,
    colour: 200,
    search: 450,
}
# Frames added after the bank's first frames, each drawn from a random stream of its own (after
# the joined drafts), so that adding one leaves every earlier example as it was.
LATER_FRAMES: dict[Callable[[Words], Draft | None], int] = {
    distance: 120,
    asked_setting: 60,
}
# Joined drafts: two requests in one ("..., then ..."), for multi-call plans.
COMPOUNDS = 250
JOINERS = (" and ", ", then ", " and also ", ". then ", "; ", " and after that ")

__all__ = ["COMPOUNDS", "FRAMES", "JOINERS", "LATER_FRAMES", "Draft", "Slot"]
