"""Search Workers: look up assets, landmarks, lanes and asset properties; they never edit."""

from __future__ import annotations

import difflib
import itertools
import math
import re
from collections.abc import Callable
from typing import Literal

from drivetwin.tools.appearance import COLOURS
from drivetwin.tools.base import Tool, ToolArgs, ToolResult
from drivetwin.tools.errors import NotFoundError, ToolArgumentError
from drivetwin.tools.locate import Target, resolve_target
from drivetwin.tools.move import find_asset
from drivetwin.tools.rules import footprint
from drivetwin.worlds.catalog import UnknownCategoryError, catalog, nearest_categories, resolve_category
from drivetwin.worlds.edits import WorldEdit
from drivetwin.worlds.scene import AssetInstance, Landmark, Lane, Scene
from drivetwin.worlds.surface import nearest_on_polyline, point_in_polygon
from pydantic import Field

MAX_LISTED = 20
# A thing that stands beside roads, never on them (a street light, a stop sign), is "on" or
# "along" a road asked about by name when it stands within this of the road's edge.
ROADSIDE_M = 5.0
# Words that name no particular lane ("the northbound lane" means campus_northbound).
_LANE_FILLER = frozenset({"the", "lane", "lanes", "road", "of", "on", "in"})

_NEAREST_TO = (
    "an asset id, landmark or place name, or 'x,y' metres: sort by distance from it and name "
    "the nearest with its distance"
)


def match_lanes(scene: Scene, text: str) -> list[Lane]:
    """The lanes `text` names: a lane id, a road name, or words of either ("northbound")."""
    key = text.strip().lower()
    lanes = scene.roads.lanes
    exact = [ln for ln in lanes if key in (ln.id.lower(), ln.road.lower())]
    if exact:
        return exact
    words = [w for w in key.replace("_", " ").split() if w not in _LANE_FILLER]
    found = [ln for ln in lanes if words and all(w in f"{ln.id} {ln.road}".lower() for w in words)]
    if not found:
        known = ", ".join([ln.id for ln in lanes] + sorted({ln.road for ln in lanes}))
        raise NotFoundError(f"no lane or road like {text!r}; lanes and roads: {known or 'none'}")
    return found


def lane_under(asset: AssetInstance, lanes: list[Lane]) -> Lane | None:
    """The lane (of `lanes`) the asset's footprint stands on, nearest centreline first."""
    best: tuple[float, Lane] | None = None
    for lane in lanes:
        for x, y in [(asset.pose.x, asset.pose.y), *footprint(asset)]:
            d = nearest_on_polyline(x, y, lane.centreline).distance
            if d <= lane.width / 2 and (best is None or d < best[0]):
                best = (d, lane)
    return best[1] if best else None


def lane_beside(asset: AssetInstance, lanes: list[Lane], reach: float = ROADSIDE_M) -> Lane | None:
    """The lane (of `lanes`) whose edge the asset stands within `reach` of, nearest first."""
    gaps = [(nearest_on_polyline(asset.pose.x, asset.pose.y, lane.centreline).distance - lane.width / 2, lane)
            for lane in lanes]
    near = [(gap, lane) for gap, lane in gaps if gap <= reach]
    return min(near, key=lambda g: g[0])[1] if near else None


def _area_of(scene: Scene, a: AssetInstance) -> str:
    """" in parking lot B" for a thing inside a place with an area, for "where is the SUV?"; else ""."""
    inside = [lm.name for lm in scene.landmarks if lm.kind == "area" and landmark_distance(lm, a.pose.x, a.pose.y) == 0.0]
    return f" in {inside[0]}" if inside else ""


def landmark_distance(landmark: Landmark, x: float, y: float) -> float:
    """Metres from (x, y) to a landmark: its point, or the edge of its area (0 inside)."""
    if landmark.kind == "area" and landmark.polygon:
        if point_in_polygon(x, y, landmark.polygon):
            return 0.0
        return nearest_on_polyline(x, y, [*landmark.polygon, landmark.polygon[0]]).distance
    return math.hypot(landmark.position[0] - x, landmark.position[1] - y)


# What each superlative orders by, and whether the most of it comes first.
_MOST = {"tallest": ("height", True), "shortest": ("height", False), "heaviest": ("mass", True), "lightest": ("mass", False),
         "longest": ("length", True), "widest": ("width", True), "biggest": ("volume", True), "smallest": ("volume", False)}


def _figure(asset: AssetInstance, key: str) -> float:
    """An asset's height, length or width (m) or volume (m³), its kind's scaled as it is, or its mass (kg)."""
    kind = catalog()[asset.category]
    if key == "mass":
        return round(asset.physics.mass, 1)
    if key == "volume":
        return round(kind.length * kind.width * kind.height * asset.scale**3, 2)
    return round(float(getattr(kind, key)) * asset.scale, 2)


def most_of(most: str, assets: list[AssetInstance]) -> list[AssetInstance]:
    """The ones of `assets` a superlative picks ("tallest": the greatest height), several where
    they tie, each by its kind's figures scaled as it is."""
    if not assets:
        return []
    key, first = _MOST[most]
    best = (max if first else min)(_figure(a, key) for a in assets)
    return [a for a in assets if _figure(a, key) == best]


def _alike(landmark: Landmark, scene: Scene) -> list[Landmark]:
    """The landmark and those of its kind (point or area) whose names share a word of its name that
    is no letter: the two crosswalks, the two parking lots (not a lot's entrance, a point)."""
    words = {w for w in landmark.name.lower().split() if len(w) > 1}
    return [lm for lm in scene.landmarks if lm.kind == landmark.kind and words & {w for w in lm.name.lower().split() if len(w) > 1}]


def _is_reference(t: Target, names: list[str]) -> bool:
    return t.name.lower() in (n.lower() for n in names)


class FindAssetsArgs(ToolArgs):
    category: str | None = Field(None, description="category or a word for it, e.g. 'cones', or a kind in the plural, e.g. 'vehicles'")
    near: str | None = Field(None, description="landmark or asset to measure distance from (an asset itself is left out)")
    within: float | None = Field(None, gt=0.0, le=1000.0, description="metres from `near` (or `nearest_to`)")
    nearest_to: str | None = Field(None, description=_NEAREST_TO + " (the reference asset itself is left out)")
    furthest_from: str | None = Field(None, description="as nearest_to, the furthest first: an asset id, landmark or place name")
    most: Literal["tallest", "shortest", "heaviest", "lightest", "longest", "widest", "biggest", "smallest"] | None = Field(
        None, description="order by size or mass, the most first, and name it with its figure (e.g. 'heaviest')")
    on_lane: bool = Field(False, description="only assets standing on a lane (on the road, e.g. blocking it)")
    side: Literal["north", "south", "east", "west"] | None = Field(
        None, description="only assets on that side of the road nearest each (north of a road that runs east-west)")
    lane: str | None = Field(
        None, description="only assets on this lane id or road, e.g. campus_northbound, Main Street, northbound "
        "(with a category that stands beside roads, such as street lights: those along it)"
    )


def _group(word: str) -> frozenset[str] | None:
    """The categories a catalog tag said in the plural names ("vehicles", "signs"), if it is one."""
    low = word.strip().lower()
    if not low.endswith("s"):
        return None  # "vehicle" alone is read as the catalog reads it
    members = frozenset(name for name, entry in catalog().items() if low.removesuffix("s") in entry.tags)
    return members if len(members) > 1 else None


# Unit vectors of the compass words (metres east, metres north).
COMPASS_VECTORS = {"east": (1.0, 0.0), "west": (-1.0, 0.0), "north": (0.0, 1.0), "south": (0.0, -1.0)}
# A road runs across a compass direction when its heading is within 60 degrees of square to it.
ACROSS_COS = 0.5


def across_points(scene: Scene, way: str) -> list[tuple[float, float]]:
    """Lane centreline points where the road runs across compass direction `way` (the north side
    is judged from roads that run east-west, not from a crossing street)."""
    dx, dy = COMPASS_VECTORS[way]
    points: list[tuple[float, float]] = []
    for lane in scene.roads.lanes:
        for (x0, y0), (x1, y1) in itertools.pairwise(lane.centreline):
            length = math.hypot(x1 - x0, y1 - y0)
            if length > 0 and abs((x1 - x0) * dx + (y1 - y0) * dy) / length < ACROSS_COS:
                points += [(x0, y0), (x1, y1)]
    return points or [p for lane in scene.roads.lanes for p in lane.centreline]


def beyond_nearest(points: list[tuple[float, float]], way: str) -> Callable[[AssetInstance], bool]:
    """Whether a thing stands beyond the nearest of `points` in compass direction `way`."""
    dx, dy = COMPASS_VECTORS[way]

    def past(a: AssetInstance) -> bool:
        near = min(points, key=lambda p: math.hypot(a.pose.x - p[0], a.pose.y - p[1]))
        return (a.pose.x - near[0]) * dx + (a.pose.y - near[1]) * dy > 0

    return past


class FindAssets(Tool[FindAssetsArgs]):
    name = "find_assets"
    description = (
        "List assets in the scene, optionally of a category, within a distance of a place, "
        "standing on a lane or road (on_lane, lane), or nearest first to an asset, place or x,y (nearest_to), or furthest first (furthest_from)."
    )
    family = "search"
    Args = FindAssetsArgs

    def propose(self, args: FindAssetsArgs, scene: Scene) -> ToolResult:
        pool = scene.all_assets()
        group = _group(args.category) if args.category else None
        if group is not None:  # "vehicles", "signs": every category of that kind
            pool = [a for a in pool if a.category in group]
        elif args.category:
            name = resolve_category(args.category)
            if name is None:
                raise UnknownCategoryError(args.category, nearest_categories(args.category))
            pool = [a for a in pool if a.category == name]
        if args.side is not None:  # "the street lights on the north side", "any trees on the east side?"
            on_that_side = beyond_nearest(across_points(scene, args.side), args.side)
            pool = [a for a in pool if on_that_side(a)]
        lanes_of: dict[str, str] = {}
        beside: set[str] = set()
        if args.on_lane or args.lane:
            lanes = match_lanes(scene, args.lane) if args.lane else scene.roads.lanes
            for a in pool:
                lane = lane_under(a, lanes)
                if lane is None and args.lane and args.category and catalog()[a.category].placement == "sidewalk":
                    # "the street lights along Main Street": a kind that stands beside the road
                    lane = lane_beside(a, lanes)
                    beside.add(a.id)
                if lane is not None:
                    lanes_of[a.id] = lane.id
            pool = [a for a in pool if a.id in lanes_of]
        reference = args.nearest_to or args.furthest_from or args.near
        t = resolve_target(scene, reference) if reference else None
        area = scene.landmark(t.name) if t is not None and t.kind == "area" else None

        def gap(a: AssetInstance) -> float:  # to a place's area, its edge (0 inside), as measure_distance has it
            assert t is not None
            return landmark_distance(area, a.pose.x, a.pose.y) if area is not None else math.hypot(a.pose.x - t.x, a.pose.y - t.y)

        if t is not None:
            pool = [a for a in pool if not (t.kind == "asset" and a.id == t.name)]  # what is near the ego is not the ego
            pool.sort(key=lambda a: (gap(a), math.hypot(a.pose.x - t.x, a.pose.y - t.y)), reverse=bool(args.furthest_from))
            beyond = pool[0] if pool else None
            if args.within is not None:
                pool = [a for a in pool if gap(a) <= args.within]
        if args.most is not None:  # "which car is the heaviest": by the catalog's figures, times each one's scale
            key, first = _MOST[args.most]
            pool.sort(key=lambda a: _figure(a, key), reverse=first)
        what = args.category or "asset"
        if t is not None and args.within is not None and not pool and beyond is not None:
            # "lamp near lot A?" with none that close: none within it, and the nearest there is
            away = gap(beyond)
            return ToolResult(WorldEdit(), f"no {what} within {args.within:g} m of {t.name}; the nearest is {beyond.id} at "
                              f"({beyond.pose.x:.1f}, {beyond.pose.y:.1f}), {away:.1f} m away",
                              data={"ids": [], "nearest": beyond.id, "distances": {beyond.id: round(away, 2)}})
        distances = {a.id: gap(a) for a in pool} if t else {}

        def line(a: AssetInstance) -> str:
            where = f" {'beside' if a.id in beside else 'in'} {lanes_of[a.id]}" if a.id in lanes_of else _area_of(scene, a)
            away = f", {distances[a.id]:.1f} m away" if a.id in distances else ""
            return f"{a.id} ({a.category}) at ({a.pose.x:.1f}, {a.pose.y:.1f}){where}{away}"

        lines = [line(a) for a in pool[:MAX_LISTED]]
        more = f" (+{len(pool) - MAX_LISTED} more)" if len(pool) > MAX_LISTED else ""
        text = f"{len(pool)} {what}(s) found" + (": " + "; ".join(lines) + more if pool else "")
        if args.most is not None and pool:
            key, _ = _MOST[args.most]
            unit = "kg" if key == "mass" else "m³" if key == "volume" else "m"
            text = f"{args.most} {what}: {pool[0].id} ({pool[0].category}), {_figure(pool[0], key):g} {unit}. {text}"
        elif (args.nearest_to or args.furthest_from) and t is not None:
            most = "furthest" if args.furthest_from else "nearest"
            head = (f"{most} {what} {'from' if args.furthest_from else 'to'} {t.name}: {pool[0].id}, {distances[pool[0].id]:.1f} m away"
                    if pool else f"no {what} near {t.name}")
            text = f"{head}. {text}"
        data: dict[str, object] = {"ids": [a.id for a in pool]}
        if distances:
            data["distances"] = {a.id: round(distances[a.id], 2) for a in pool}
        if lanes_of:
            data["lanes"] = {a.id: lanes_of[a.id] for a in pool}
        return ToolResult(WorldEdit(), text, data=data)


class FindLandmarksArgs(ToolArgs):
    query: str | None = Field(None, description="words of a landmark name; empty lists all")
    nearest_to: str | None = Field(None, description=_NEAREST_TO + " (the reference landmark itself is left out)")


class FindLandmarks(Tool[FindLandmarksArgs]):
    name = "find_landmarks"
    description = (
        "List the named places of the world (entrances, gates, parking lots) or find one; "
        "nearest_to sorts them by distance from an asset, place or x,y and names the nearest."
    )
    family = "search"
    Args = FindLandmarksArgs

    def propose(self, args: FindLandmarksArgs, scene: Scene) -> ToolResult:
        if args.nearest_to:
            return self._nearest(args, scene, args.nearest_to)
        marks = self._matching(args, scene)
        lines = [f"{lm.name} at ({lm.position[0]:.1f}, {lm.position[1]:.1f})" for lm in marks]
        return ToolResult(WorldEdit(), f"{len(marks)} landmark(s): " + "; ".join(lines),
                          data={"names": [lm.name for lm in marks]})

    def _nearest(self, args: FindLandmarksArgs, scene: Scene, reference: str) -> ToolResult:
        t = resolve_target(scene, reference)
        marks = self._matching(args, scene)
        if len(marks) == 1 and args.query and scene.landmark(args.query) is marks[0] and args.query.lower() != marks[0].name.lower():
            # "which car park is nearest ...": a kind of place, said by one's other name; its like are compared with it
            marks = _alike(marks[0], scene)
        marks = [lm for lm in marks if not (t.kind in ("landmark", "area") and _is_reference(t, lm.names()))]
        if not marks:
            raise NotFoundError(f"no other landmark to compare with {t.name}")
        ranked = sorted(marks, key=lambda lm: landmark_distance(lm, t.x, t.y))
        distances = {lm.name: landmark_distance(lm, t.x, t.y) for lm in ranked}
        best = ranked[0]
        lines = [f"{lm.name} {distances[lm.name]:.1f} m" for lm in ranked[:MAX_LISTED]]
        text = (f"nearest landmark to {t.name}: {best.name}, {distances[best.name]:.1f} m away "
                f"at ({best.position[0]:.1f}, {best.position[1]:.1f}). By distance: " + "; ".join(lines))
        return ToolResult(WorldEdit(), text, data={
            "names": [lm.name for lm in ranked],
            "distances": {k: round(v, 2) for k, v in distances.items()},
        })

    def _matching(self, args: FindLandmarksArgs, scene: Scene) -> list[Landmark]:
        """The landmarks `query` names (all of them without a query)."""
        marks = scene.landmarks
        if args.query:
            exact = scene.landmark(args.query)
            q = args.query.lower()
            # a word every one of a kind is called by ("crosswalk", "gate") is all of them, though one has it as its alias
            kind = [lm for lm in marks if any(re.search(rf"\b{re.escape(q)}\b", n.lower()) for n in lm.names())]
            if q.strip() in ("building", "buildings") and scene.buildings:  # every building's own place, whatever it is called
                return [lm for lm in marks if any(b.name.lower() in n.lower() for b in scene.buildings for n in lm.names())]
            if exact is not None and (len(kind) < 2 or " " in q.strip()):
                marks = [exact]
            else:
                marks = [lm for lm in marks if any(q in n.lower() or n.lower() in q for n in lm.names())]
                if not marks:
                    names = [n for lm in scene.landmarks for n in lm.names()]
                    near = difflib.get_close_matches(args.query, names, n=3, cutoff=0.3)
                    raise NotFoundError(f"no landmark like {args.query!r}; nearest: {', '.join(near)}")
        return marks


class FindLanesArgs(ToolArgs):
    road: str | None = Field(None, description="road name to filter by")
    near: str | None = Field(None, description="landmark or asset to find the nearest lane to")


class FindLanes(Tool[FindLanesArgs]):
    name = "find_lanes"
    description = "List lanes (id, road, direction, width, length), or the lane nearest a place."
    family = "search"
    Args = FindLanesArgs

    def propose(self, args: FindLanesArgs, scene: Scene) -> ToolResult:
        from drivetwin.worlds.surface import nearest_on_polyline

        lanes = [ln for ln in scene.roads.lanes if not args.road or args.road.lower() in ln.road.lower()]
        lead = ""
        if args.near:
            t = resolve_target(scene, args.near)
            lanes.sort(key=lambda ln: nearest_on_polyline(t.x, t.y, ln.centreline).distance)
            lanes = lanes[:1]
            thing = scene.asset(t.name) if t.kind == "asset" else None
            if thing is not None and lane_under(thing, scene.roads.lanes) is None:
                lead = f"{thing.id} stands {_standing_in(scene, thing)}; the nearest lane: "  # "which lane is the SUV in"
        lines = []
        for ln in lanes:
            (x1, y1), (x2, y2) = ln.centreline[0], ln.centreline[-1]
            heading = math.degrees(math.atan2(y2 - y1, x2 - x1))
            length = sum(math.dist(p, q) for p, q in zip(ln.centreline, ln.centreline[1:], strict=False))
            lines.append(f"{ln.id} on {ln.road}, heading {heading:.0f} deg, {ln.width:g} m wide, {length:.0f} m long, "
                         f"speed limit {ln.speed_limit:g} m/s ({ln.speed_limit * 3.6:.0f} km/h)")
        return ToolResult(WorldEdit(), f"{lead}{len(lanes)} lane(s): " + "; ".join(lines),
                          data={"lanes": [ln.id for ln in lanes]})


class MeasureArgs(ToolArgs):
    a: str = Field(description="one end: an asset id, landmark or place name, lane id, 'ego' or 'x,y' metres")
    b: str = Field("ego", description="the other end, named the same way (default: the ego)")


class MeasureDistance(Tool[MeasureArgs]):
    name = "measure_distance"
    description = "How far apart two things or places are (straight line, metres) and which way b lies from a."
    family = "search"
    Args = MeasureArgs

    def propose(self, args: MeasureArgs, scene: Scene) -> ToolResult:
        a, b = resolve_target(scene, args.a), resolve_target(scene, args.b)
        if (a.x, a.y) == (b.x, b.y) and a.name == b.name:
            raise ToolArgumentError(f"{args.a!r} and {args.b!r} are the same place; name two things to measure between")
        dx, dy = b.x - a.x, b.y - a.y
        metres = math.hypot(dx, dy)
        text = f"from {a.name} to {b.name}: {metres:.1f} m in a straight line, to the {compass_of(dx, dy)}"
        edge = _edge_distance(scene, a, b)
        if edge is not None and edge < metres - 0.05:
            text += f"; {edge:.1f} m from the edge of the area"
        return ToolResult(WorldEdit(), text, data={"metres": round(metres, 2), "from": a.name, "to": b.name})


def compass_of(dx: float, dy: float) -> str:
    """The compass point (of eight) that the vector (dx east, dy north) points to."""
    names = ("east", "north-east", "north", "north-west", "west", "south-west", "south", "south-east")
    return names[round(math.degrees(math.atan2(dy, dx)) / 45.0) % 8]


def _edge_distance(scene: Scene, a: Target, b: Target) -> float | None:
    """When one end is an area (a parking lot), the distance from the other end to its edge."""
    for area, other in ((a, b), (b, a)):
        landmark = scene.landmark(area.name) if area.kind == "area" else None
        if landmark is not None and landmark.polygon:
            return landmark_distance(landmark, other.x, other.y)
    return None


class EnvironmentArgs(ToolArgs):
    pass


class DescribeEnvironment(Tool[EnvironmentArgs]):
    name = "describe_environment"
    description = "Describe the weather, the time of day and the lights now (it changes nothing)."
    family = "search"
    Args = EnvironmentArgs

    def propose(self, args: EnvironmentArgs, scene: Scene) -> ToolResult:
        env = scene.environment
        weather = env.weather.kind if env.weather.kind == "clear" else f"{env.weather.kind} (intensity {env.weather.intensity:g})"
        text = (f"weather: {weather}; time of day: {env.time_of_day} ({'night' if env.is_night else 'day'}); "
                f"street lights {_lamps(env.lighting.street_lights, env.is_night)}, "
                f"vehicle lights {_lamps(env.lighting.vehicle_lights, env.is_night)}; exposure {env.lighting.exposure:g}")
        return ToolResult(WorldEdit(), text, data={"environment": env.model_dump()})


def _lamps(setting: str, night: bool) -> str:
    """Whether lights set so are lit now: "auto" ones are lit at night."""
    if setting != "auto":
        return setting
    return "on (they light at night)" if night else "off (they light at night)"


def _doing(a: AssetInstance) -> str:
    """What an asset's behaviour does, with its speed and where ("drive_lane in main_eastbound at 5 m/s")."""
    b = a.behaviour
    speed = getattr(b, "speed", None)
    said = b.kind + (f" in {b.lane}" if hasattr(b, "lane") else "") + (f" round ({b.centre[0]:g}, {b.centre[1]:g})"
                                                                       if hasattr(b, "centre") else "")
    return said + (f" at {speed:g} m/s" if speed is not None else "")


def _standing_in(scene: Scene, a: AssetInstance) -> str:
    """The lane an asset stands in, else the area (a parking lot) or that it is in no lane."""
    lane = lane_under(a, scene.roads.lanes)
    if lane is not None:
        return f"in lane {lane.id}"
    area = next((lm.name for lm in scene.landmarks if lm.kind == "area" and lm.polygon
                 and point_in_polygon(a.pose.x, a.pose.y, lm.polygon)), None)
    return f"in no lane ({area})" if area else "in no lane"


def _colour_name(rgba: tuple[float, float, float, float] | None) -> str:
    """A colour by its name where it is one of the named ones, else its RGBA; "default" when unset."""
    if rgba is None:
        return "default"
    return next((name for name, value in COLOURS.items() if value == tuple(rgba)), str(tuple(rgba)))


class PropertiesArgs(ToolArgs):
    asset: str | None = Field(None, description="asset id to describe")
    category: str | None = Field(None, description="or: a catalog category to describe")


class AssetProperties(Tool[PropertiesArgs]):
    name = "asset_properties"
    description = "Describe an asset (pose, behaviour, mass, colour) or a catalog category (size, mass, words)."
    family = "search"
    Args = PropertiesArgs

    def propose(self, args: PropertiesArgs, scene: Scene) -> ToolResult:
        if args.asset:
            a = find_asset(scene, args.asset)
            text = (f"{a.id}: {a.category} at ({a.pose.x:.1f}, {a.pose.y:.1f}), {_standing_in(scene, a)}, yaw "
                    f"{math.degrees(a.pose.yaw):.0f} deg, mass {a.physics.mass:g} kg, "
                    f"behaviour {_doing(a)}, colour {_colour_name(a.appearance.rgba)}")
            return ToolResult(WorldEdit(), text, data={"asset": a.model_dump()})
        if args.category:
            name = resolve_category(args.category)
            if name is None:
                raise UnknownCategoryError(args.category, nearest_categories(args.category))
            c = catalog()[name]
            text = (f"{c.name}: {c.description}; {c.length:g}x{c.width:g}x{c.height:g} m, "
                    f"{c.mass:g} kg; also called {', '.join(c.synonyms[:6])}")
            return ToolResult(WorldEdit(), text, data={"category": c.name})
        raise NotFoundError("name an asset id or a category to describe")
