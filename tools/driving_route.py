"""A vehicle's way to a place: onto a lane, along the lanes and their connections, and off.

A vehicle sent somewhere (follow_path `to`) drives the roads: from where it stands onto a lane,
along lane centrelines, through junction boxes by `junction_route`'s lane connections and
into a lane's successors, and off the lane near the place; or straight there, where that is
cheaper. A straight line from a drop-off to a gate cuts across verges, sidewalks and grass
and through whatever stands there, and the vehicle, which stops for anything in its path,
waited in front of the first street light for good.

The legs off the lanes are checked clear of buildings and of everything that stands still,
so the vehicle's obstacle rays find nothing on them.
"""

from __future__ import annotations

import heapq
import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

from drivetwin.tools.footprint_grid import Footprint, footprint_of
from drivetwin.worlds.catalog import category
from drivetwin.worlds.routes import NoJunctionError, PolylineRoute, junction_route
from drivetwin.worlds.scene import AssetInstance, Parked, Scene
from drivetwin.worlds.surface import SceneSurface, nearest_on_polyline, point_in_polygon

__all__ = ["driving_route"]

Point = tuple[float, float]

# A metre off the lanes (over a verge, a kerb, a car park) counts as this many along one: a
# vehicle keeps to the road unless cutting across saves more than two thirds of the way.
OFF_LANE_COST = 3.0
# A bend off the lanes (from where the vehicle faces onto a leg, from a leg onto a lane and off
# it) counts this many metres per radian: a leg meeting a lane at 45° beats a shorter one at
# 90°, which the vehicle, cutting the corner at speed, overshoots into what stands beyond.
BEND_COST_M = 10.0
# Legs off the lanes pass this far (m) beyond the vehicle's half width from anything standing
# still: its side obstacle rays (±0.8 m) miss it, and so do its corners where it cuts a bend.
LEG_CLEARANCE_M = 1.0
# A leg is checked every this many metres along it.
LEG_STEP_M = 0.5
# Legs onto (or off) a lane meet it abeam the place and at points this far apart along it,
# ahead of the start (or back from the place), up to this many beyond 45°.
JOIN_STEP_M = 4.0
JOIN_TRIES = 8
# Lanes joined or left straight from a place: those passing within this many metres more than
# the nearest one (further ones are reached along the lanes, or not worth the leg).
JOIN_SLACK_M = 20.0
# Points of a route closer than this (m) to the one before are dropped (pure pursuit steers
# towards a point metres ahead; a stub of a segment only gives it a spurious heading).
MIN_SPACING_M = 0.5


@dataclass(frozen=True)
class _Link:
    """A way from lane `src` at arc length `s_in` into lane `dst` at `s_out` (a turn, a successor)."""

    src: int
    s_in: float
    dst: int
    s_out: float
    points: list[Point]
    length: float


def driving_route(scene: Scene, asset: AssetInstance, goal: Point) -> list[Point]:
    """Waypoints (world metres) for vehicle `asset` driving from where it stands to `goal`.

    The cheapest of: straight there, and onto a lane, along the lanes and off to `goal`, where
    a metre off the lanes counts OFF_LANE_COST metres and no leg off them comes within
    LEG_CLEARANCE_M of a building or of something standing still. With no such way (no lanes,
    every leg blocked) it is the straight line, as before there were lanes to follow.
    """
    start = (asset.pose.x, asset.pose.y)
    legs = _Legs(scene, asset)
    routes = [PolylineRoute(lane.centreline) for lane in scene.roads.lanes if lane.kind == "driving"]
    tie = itertools.count()
    queue: list[tuple[float, int, int, float, list[Point]]] = []  # cost, tie, lane (-1: arrived), s, points
    yaw = asset.pose.yaw
    if (direct := legs.cost(start, goal)) is not None:
        queue.append((direct + _bend_cost([yaw, _heading(start, goal)], math.dist(start, goal)), next(tie), -1, 0.0,
                      [start, goal]))
    for i in _lanes_near(routes, start):
        queue += [(cost, next(tie), i, s, [start, routes[i].point(s)])
                  for s, cost in _clear_legs(legs, routes[i], start, yaw)]
    leaves = {i: _clear_legs(legs, routes[i], goal, None) for i in _lanes_near(routes, goal)}
    heapq.heapify(queue)
    links = _links(scene, routes) if queue else []
    seen: set[tuple[int, float]] = set()
    while queue:
        cost, _, i, s, points = heapq.heappop(queue)
        if i < 0:
            return _tidy(points)
        if (i, round(s, 1)) in seen:
            continue
        seen.add((i, round(s, 1)))
        route = routes[i]
        for s_off, off in leaves.get(i, []):
            if s_off >= s - 1e-6:
                heapq.heappush(queue, (cost + s_off - s + off, next(tie), -1, 0.0,
                                       [*points, *_along(route, s, s_off), goal]))
        for link in links:
            if link.src == i and link.s_in >= s - 1e-6:
                heapq.heappush(queue, (cost + link.s_in - s + link.length, next(tie), link.dst, link.s_out,
                                       [*points, *_along(route, s, link.s_in), *link.points]))
    return [start, goal]


class _Legs:
    """The legs a vehicle may drive off the lanes, and what each costs."""

    def __init__(self, scene: Scene, asset: AssetInstance) -> None:
        self.surface = SceneSurface(scene)
        cat = category(asset.category)
        self.reach = cat.width * asset.scale / 2 + LEG_CLEARANCE_M
        # Whatever moves will have moved on; what stands still stops the vehicle.
        self.obstacles = [footprint_of(a) for a in scene.all_assets()
                          if a.id != asset.id and isinstance(a.behaviour, Parked)]

    def cost(self, a: Point, b: Point) -> float | None:
        """OFF_LANE_COST per metre from `a` to `b`, or None where the leg is blocked.

        Something already within reach of an end (a bench the vehicle is parked beside, the
        thing it goes to) does not block: the leg leaves it or ends at it.
        """
        length = math.dist(a, b)
        near = [fp for fp in self.obstacles
                if _segment_distance((fp.x, fp.y), a, b) <= fp.radius + self.reach
                and not any(_clearance(fp, p) < self.reach for p in (a, b))]
        n = max(1, math.ceil(length / LEG_STEP_M))
        for k in range(n + 1):
            p = (a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n)
            if self.surface.building_at(*p) is not None or any(_clearance(fp, p) < self.reach for fp in near):
                return None
        return OFF_LANE_COST * length


def _lanes_near(routes: Sequence[PolylineRoute], place: Point) -> list[int]:
    """The lanes (indexes) passing within JOIN_SLACK_M more than the nearest one of `place`."""
    gaps = [r.distance_to(*place) for r in routes]
    return [i for i, gap in enumerate(gaps) if gap <= min(gaps, default=0.0) + JOIN_SLACK_M]


def _clear_legs(legs: _Legs, route: PolylineRoute, place: Point, yaw: float | None) -> list[tuple[float, float]]:
    """The clear legs between `place` and `route`, as (arc length on the route, cost with
    its bends): onto the route from `place`, where the vehicle faces `yaw`, or with no yaw
    off it to `place`. They meet the route abeam `place` and every JOIN_STEP_M further along
    it (joining) or back up it (leaving), to JOIN_TRIES steps past 45°."""
    s_abeam = route.project(*place)
    steps = math.ceil(route.distance_to(*place) / JOIN_STEP_M) + JOIN_TRIES
    found = []
    for k in range(steps):
        s = s_abeam + k * JOIN_STEP_M if yaw is not None else s_abeam - k * JOIN_STEP_M
        if not 0.0 <= s <= route.length:
            break
        on_lane, lane_yaw = route.point(s), route.heading(s)
        leg = (place, on_lane) if yaw is not None else (on_lane, place)
        cost = legs.cost(*leg)
        if cost is not None:
            bends = [yaw, _heading(*leg), lane_yaw] if yaw is not None else [lane_yaw, _heading(*leg)]
            found.append((s, cost + _bend_cost(bends, math.dist(*leg))))
    return found


def _heading(a: Point, b: Point) -> float:
    return math.atan2(b[1] - a[1], b[0] - a[0])


def _bend_cost(headings: Sequence[float], length: float) -> float:
    """BEND_COST_M per radian turned through `headings` in turn (a leg's heading is left out
    where the leg, `length` metres long, is too short to have one)."""
    if length < MIN_SPACING_M:
        headings = [headings[0], headings[-1]] if len(headings) == 3 else []
    return BEND_COST_M * sum(abs(math.remainder(b - a, math.tau)) for a, b in itertools.pairwise(headings))


def _links(scene: Scene, routes: Sequence[PolylineRoute]) -> list[_Link]:
    """Every way from one lane into another: the turns through each junction box a lane
    crosses (straight on into another lane too) and a lane's end into its successors."""
    driving = [lane for lane in scene.roads.lanes if lane.kind == "driving"]
    index = {lane.id: i for i, lane in enumerate(driving)}
    links: list[_Link] = []
    for i, (lane, route) in enumerate(zip(driving, routes, strict=True)):
        end = route.point(route.length)
        links += [_Link(i, route.length, j, 0.0, [routes[j].point(0.0)], math.dist(end, routes[j].point(0.0)))
                  for j in (index[name] for name in lane.successors if name in index)]
    for box in (area.polygon for area in scene.roads.paved if area.kind == "intersection"):
        # Only lanes that come near a box can cross it (a large map has thousands elsewhere).
        near = [i for i, lane in enumerate(driving) if _bounds_meet(lane.centreline, box)]
        lanes = [(driving[i].id, driving[i].centreline) for i in near]
        for i in near:
            x, y = routes[i].point(0.0)
            for turn in ("left", "right", "straight"):
                try:
                    path, s_exit = junction_route(lanes, [box], x, y, routes[i].heading(0.0), turn)
                except NoJunctionError:
                    continue
                link = _turn_link(i, routes[i], routes, path, s_exit, path.project(x, y))
                if link.dst not in (i, -1):  # straight on along its own lane is the lane itself
                    links.append(link)
    return links


def _bounds_meet(a: Sequence[Sequence[float]], b: Sequence[Sequence[float]]) -> bool:
    """Whether the bounding boxes of two point lists overlap."""
    return (min(p[0] for p in a) <= max(p[0] for p in b) and min(p[0] for p in b) <= max(p[0] for p in a)
            and min(p[1] for p in a) <= max(p[1] for p in b) and min(p[1] for p in b) <= max(p[1] for p in a))


def _turn_link(i: int, route: PolylineRoute, routes: Sequence[PolylineRoute], path: PolylineRoute,
               s_exit: float, s_here: float) -> _Link:
    """The link a junction route makes from lane `i`: its points from the box's entry (on lane
    `i`) to the exit, into the lane that runs on from there (dst -1 where none does)."""
    curve = [(float(p[0]), float(p[1])) for p in path.waypoints if s_here < path.project(p[0], p[1]) <= s_exit + 1e-6]
    exit_point, heading = path.point(s_exit), path.heading(s_exit)
    onto = [(r.distance_to(*exit_point), j) for j, r in enumerate(routes)
            if math.cos(r.heading(r.project(*exit_point)) - heading) > math.cos(math.pi / 4)]
    j = min(onto)[1] if onto and min(onto)[0] < 0.5 else -1
    s_in = route.project(*curve[0]) if curve else route.project(*exit_point)
    length = s_exit - path.project(*curve[0]) if curve else 0.0
    return _Link(i, s_in, j, routes[j].project(*exit_point) if j >= 0 else 0.0, curve, length)


def _along(route: PolylineRoute, s0: float, s1: float) -> list[Point]:
    """The route's corners strictly between arc lengths s0 and s1, and its point at s1."""
    corners = [(float(p[0]), float(p[1])) for p in route.waypoints]
    travelled = itertools.accumulate((math.dist(a, b) for a, b in itertools.pairwise(corners)), initial=0.0)
    return [p for p, s in zip(corners, travelled, strict=True) if s0 < s < s1] + [route.point(s1)]


def _tidy(points: list[Point]) -> list[Point]:
    """`points` to the centimetre, without those closer than MIN_SPACING_M to the last kept
    (the first and the last are always kept)."""
    kept = [points[0]]
    for p in points[1:-1]:
        if math.dist(p, kept[-1]) >= MIN_SPACING_M:
            kept.append(p)
    if len(kept) > 1 and math.dist(kept[-1], points[-1]) < MIN_SPACING_M:
        kept.pop()
    kept.append(points[-1])
    return [(round(x, 2), round(y, 2)) for x, y in kept]


def _clearance(fp: Footprint, p: Point) -> float:
    """Metres from `p` to footprint `fp`'s rectangle (0 inside it)."""
    if point_in_polygon(p[0], p[1], fp.corners):
        return 0.0
    return nearest_on_polyline(p[0], p[1], [*fp.corners, fp.corners[0]]).distance


def _segment_distance(p: Point, a: Point, b: Point) -> float:
    """Metres from `p` to the segment a-b."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    span = dx * dx + dy * dy
    t = 0.0 if span == 0.0 else min(1.0, max(0.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / span))
    return math.dist(p, (a[0] + t * dx, a[1] + t * dy))
