"""A vehicle's way to a place: out of where it stands, along the lanes and their connections, and off.

A vehicle sent somewhere (follow_path `to`) drives the roads: out of where it stands (straight
ahead, then turning no tighter than it can steer), onto a lane, along lane centrelines,
through junction boxes by `junction_route`'s lane connections or turning back in the box, and
off the lane near the place; or straight there, where that is cheaper. A straight line from a
drop-off to a gate cuts across verges, sidewalks and grass and through whatever stands there,
and the vehicle, which stops for anything in its path, waited in front of the first street
light for good. Where no such way exists it is refused: a route that cannot arrive is worse
than none.

Everything driven off the lanes is checked clear of buildings and of everything that stands
still, so the vehicle's obstacle rays find nothing on it.
"""

from __future__ import annotations

import heapq
import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

from drivetwin.tools.errors import RuleViolation
from drivetwin.tools.footprint_grid import Footprint, footprint_of
from drivetwin.tools.turns import Departure, departures, fillet, u_turn
from drivetwin.worlds.behaviours import SENSE_SIDES, STOP_GAP_M
from drivetwin.worlds.catalog import category
from drivetwin.worlds.routes import NoJunctionError, PolylineRoute, junction_route
from drivetwin.worlds.scene import AssetInstance, Parked, Scene
from drivetwin.worlds.surface import SceneSurface, nearest_on_polyline, point_in_polygon
from drivetwin.worlds.vehicles import AckermannGeometry

__all__ = ["driving_route"]

Point = tuple[float, float]

# A metre off the lanes (over a verge, a kerb, a car park) counts as this many along one: a
# vehicle keeps to the road unless cutting across saves more than two thirds of the way.
OFF_LANE_COST = 3.0
# A bend off the lanes (from where the vehicle faces onto a leg, from a leg onto a lane and off
# it) counts this many metres per radian: a leg meeting a lane at 45° beats a shorter one at
# 90°, which the vehicle, cutting the corner at speed, overshoots into what stands beyond.
BEND_COST_M = 10.0
# A leg off a way out of where the vehicle stands bends at most this much (rad) from where it
# then faces: a sharper turn is one of the ways out, drawn at a radius it can steer and checked
# clear, not a corner it would cut through whatever stands inside it.
LEG_BEND_RAD = math.pi / 4 + 1e-6
# No leg bends more than this (rad) from a lane onto it or off it onto a lane: turning back is
# a U-turn's, drawn and checked.
SHARPEST_BEND_RAD = math.pi * 0.75
# Turns are swept with the body this far (m) clear of walls and of what stands still (straight
# legs keep LEG_CLEARANCE_M beside it; a turn's corners are drawn as they go).
BODY_MARGIN_M = 0.3
# Turning back in a junction box counts this many metres on top of its length: a vehicle
# turns round only where the roads offer no way on.
U_TURN_COST_M = 30.0
# What is driven off the lanes passes this far (m) beyond the vehicle's half width from anything
# standing still: its side obstacle rays (±0.8 m) miss it, and so do its corners where it cuts a bend.
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


def driving_route(scene: Scene, asset: AssetInstance, goal: Point, place: str | None = None) -> list[Point]:
    """Waypoints (world metres) for vehicle `asset` driving from where it stands to `goal`.

    The cheapest of: out of where it stands and straight there, and out, onto a lane, along
    the lanes and off to `goal`, where a metre off the lanes counts OFF_LANE_COST metres and
    nothing driven off them comes within LEG_CLEARANCE_M of a building or of something
    standing still. Raises RuleViolation, saying why, where there is no such way (`place`
    names the goal in the message).
    """
    legs = _Legs(scene, asset, goal)
    routes = [PolylineRoute(lane.centreline) for lane in scene.roads.lanes if lane.kind == "driving"]
    tie = itertools.count()
    # cost, tie, lane (-1: arrived), arc length s on it, lane metres after s that a bend onto
    # it still takes (nothing turns off the lane before), points
    queue: list[tuple[float, int, int, float, float, list[Point]]] = []
    ways_out = departures(legs.sweep, (asset.pose.x, asset.pose.y), asset.pose.yaw, legs.turn_radius)
    for out in ways_out:
        spent = OFF_LANE_COST * out.length + BEND_COST_M * out.turned
        if _steerable(out.point, goal, out.heading, None, legs.turn_radius, LEG_BEND_RAD) and (
                direct := legs.cost(out.point, goal)) is not None:
            queue.append((spent + direct + _bend_cost([out.heading, _heading(out.point, goal)], math.dist(out.point, goal)),
                          next(tie), -1, 0.0, 0.0, [*out.points, goal]))
        for i in _lanes_near(routes, out.point):
            queue += [(spent + leg.cost, next(tie), i, leg.s, leg.bend_room, [*out.points, routes[i].point(leg.s)])
                      for leg in _clear_legs(legs, routes[i], out.point, out.heading)]
    leaves = {i: _clear_legs(legs, routes[i], goal, None) for i in _lanes_near(routes, goal)}
    heapq.heapify(queue)
    links = _links(scene, routes, legs) if queue else []
    seen: set[tuple[int, float, float]] = set()
    while queue:
        cost, _, i, s, settling, points = heapq.heappop(queue)
        if i < 0:
            return _tidy(points)
        if (i, round(s, 1), round(settling)) in seen:
            continue
        seen.add((i, round(s, 1), round(settling)))
        route = routes[i]
        for leave in leaves.get(i, []):
            if leave.s >= s + settling + leave.bend_room - 1e-6:
                heapq.heappush(queue, (cost + leave.s - s + leave.cost, next(tie), -1, 0.0, 0.0,
                                       [*points, *_along(route, s, leave.s), goal]))
        for link in links:
            if link.src == i and link.s_in >= s + settling - 1e-6:
                heapq.heappush(queue, (cost + link.s_in - s + link.length, next(tie), link.dst, link.s_out, 0.0,
                                       [*points, *_along(route, s, link.s_in), *link.points]))
    raise RuleViolation("route", _no_way(asset, goal, place, ways_out, bool(seen), any(leaves.values())))


def _no_way(asset: AssetInstance, goal: Point, place: str | None, ways_out: Sequence[Departure],
            on_lanes: bool, off_lanes: bool) -> str:
    """Why `asset` cannot drive to `goal`, in one line."""
    where = place or f"({goal[0]:.1f}, {goal[1]:.1f})"
    if len(ways_out) <= 1 and not on_lanes:
        why = ("it is hemmed in where it stands (it drives forwards only, turning no tighter than it "
               "can steer); move it or turn it first")
    elif not on_lanes:
        why = "no clear way from where it stands onto a lane that leads there"
    elif not off_lanes:
        why = "no clear way off the lanes to it (something stands in the way, or it is off the roads)"
    else:
        why = "the lanes it can reach do not lead there"
    return f"{asset.id} cannot drive to {where}: {why}"


class _Legs:
    """What a vehicle may drive off the lanes, and what each leg costs."""

    def __init__(self, scene: Scene, asset: AssetInstance, goal: Point) -> None:
        self.surface = SceneSurface(scene)
        self.buildings = [building.footprint for building in scene.buildings]
        cat = category(asset.category)
        self.reach = cat.width * asset.scale / 2 + LEG_CLEARANCE_M
        self.turn_radius = AckermannGeometry.of(asset).min_turn_radius
        # Whatever moves will have moved on; what stands still stops the vehicle. Something
        # within reach of where it starts or ends (a bench it is parked beside, the thing it
        # goes to) blocks nothing: the vehicle leaves it or ends at it.
        still = [footprint_of(a) for a in scene.all_assets() if a.id != asset.id and isinstance(a.behaviour, Parked)]
        self.ends = [(asset.pose.x, asset.pose.y), goal]
        self.obstacles = [fp for fp in still if all(_clearance(fp, p) >= self.reach for p in self.ends)]
        # Walls are kept at the same reach, except where the vehicle starts or ends beside one
        # (a door is a metre from its wall): there only its centre must stay out.
        length, half_width = cat.length * asset.scale, cat.width * asset.scale / 2
        self.end_room = length / 2 + LEG_CLEARANCE_M
        # The body as three discs along it, for sweeping turns: from the rear axle (which pure
        # pursuit keeps on the route) to each disc's centre, and their radius. A fourth covers
        # what its obstacle rays see STOP_GAP_M ahead of its front, where it would stop for good.
        wheelbase = AckermannGeometry.of(asset).wheelbase
        self.discs = [(wheelbase / 2 + k * length / 3, math.hypot(length / 6, half_width) + BODY_MARGIN_M)
                      for k in (-1, 0, 1)]
        self.discs.append((wheelbase / 2 + length / 2 + STOP_GAP_M / 2,
                           math.hypot(STOP_GAP_M / 2, max(SENSE_SIDES) * half_width) + BODY_MARGIN_M))

    def sweep(self, points: Sequence[Point]) -> bool:
        """Whether the vehicle, its rear axle driven along `points` (a turn), keeps its body
        BODY_MARGIN_M clear of buildings and of what stands still, and the STOP_GAP_M its
        obstacle rays watch ahead of its front as well."""
        return all(self._clear(a, b, self.discs) for a, b in itertools.pairwise(points) if math.dist(a, b) > 1e-9)

    def cost(self, a: Point, b: Point) -> float | None:
        """OFF_LANE_COST per metre from `a` to `b`, or None where the leg is blocked."""
        return OFF_LANE_COST * math.dist(a, b) if self._clear(a, b, [(0.0, self.reach)]) else None

    def _clear(self, a: Point, b: Point, discs: Sequence[tuple[float, float]]) -> bool:
        """Whether discs (metres ahead of a point on a-b, radius) moved along a-b every
        LEG_STEP_M keep out of buildings and clear of what stands still (near where the
        vehicle starts or ends, only out of the buildings)."""
        length = math.dist(a, b)
        heading = _heading(a, b)  # a leg of no length: its one point (discs ahead need a heading)
        ux, uy = math.cos(heading), math.sin(heading)
        widest = max(abs(d) + room for d, room in discs)
        near = [fp for fp in self.obstacles if _segment_distance((fp.x, fp.y), a, b) <= fp.radius + widest]
        middle = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        walls = [self.buildings[k] for k in self.surface.index.buildings.near(*middle, length / 2 + widest)]
        n = max(1, math.ceil(length / LEG_STEP_M))
        for k in range(n + 1):
            px, py = a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n
            for d, room in discs:
                p = (px + d * ux, py + d * uy)
                at_end = any(math.dist(p, end) < self.end_room for end in self.ends)
                if any(_within(p, wall, 0.0 if at_end else room) for wall in walls):
                    return False
                if any(math.dist((fp.x, fp.y), p) <= fp.radius + room and _clearance(fp, p) < room for fp in near):
                    return False
        return True


def _lanes_near(routes: Sequence[PolylineRoute], place: Point) -> list[int]:
    """The lanes (indexes) passing within JOIN_SLACK_M more than the nearest one of `place`."""
    gaps = [r.distance_to(*place) for r in routes]
    return [i for i, gap in enumerate(gaps) if gap <= min(gaps, default=0.0) + JOIN_SLACK_M]


@dataclass(frozen=True)
class _Leg:
    """A clear leg between a place and a lane: where it meets the lane (arc length), its cost
    with its bends, and the lane metres its bend at the lane takes (R·tan(θ/2))."""

    s: float
    cost: float
    bend_room: float


def _clear_legs(legs: _Legs, route: PolylineRoute, place: Point, yaw: float | None) -> list[_Leg]:
    """The clear legs between `place` and `route`: onto the route from `place`, where the
    vehicle faces `yaw`, or with no yaw off it to `place`. They meet the route abeam `place`
    and every JOIN_STEP_M further along it (joining) or back up it (leaving), to JOIN_TRIES
    steps past 45°."""
    s_abeam = route.project(*place)
    steps = math.ceil(route.distance_to(*place) / JOIN_STEP_M) + JOIN_TRIES
    found = []
    for k in range(steps):
        s = s_abeam + k * JOIN_STEP_M if yaw is not None else s_abeam - k * JOIN_STEP_M
        if not 0.0 <= s <= route.length:
            break
        on_lane, lane_yaw = route.point(s), route.heading(s)
        leg = (place, on_lane) if yaw is not None else (on_lane, place)
        if not (_steerable(*leg, yaw, lane_yaw, legs.turn_radius, LEG_BEND_RAD) if yaw is not None
                else _steerable(*leg, lane_yaw, None, legs.turn_radius)):
            continue
        cost = legs.cost(*leg)
        if cost is not None and legs.sweep(_rounded(*leg, yaw, lane_yaw, legs.turn_radius)):
            bends = [yaw, _heading(*leg), lane_yaw] if yaw is not None else [lane_yaw, _heading(*leg)]
            at_lane = 0.0 if math.dist(*leg) < MIN_SPACING_M else _bend(lane_yaw, _heading(*leg))
            found.append(_Leg(s, cost + _bend_cost(bends, math.dist(*leg)), legs.turn_radius * math.tan(at_lane / 2)))
    return found


def _rounded(a: Point, b: Point, yaw: float | None, lane_yaw: float, radius: float) -> list[Point]:
    """The corners of a leg a-b as the vehicle drives them, each turned at `radius` (m): onto
    it from facing `yaw` at `a` and at `b` onto the lane (heading `lane_yaw`), or with no yaw
    at `a` off the lane onto it (`a` on the lane); [] for a leg too short to have a heading."""
    if math.dist(a, b) < MIN_SPACING_M:
        return []
    heading = _heading(a, b)
    if yaw is None:
        return fillet(a, lane_yaw, heading, radius)
    return [*fillet(a, yaw, heading, radius), *fillet(b, heading, lane_yaw, radius)]


def _steerable(a: Point, b: Point, yaw_in: float, yaw_out: float | None, radius: float,
               first_bend: float = SHARPEST_BEND_RAD) -> bool:
    """Whether a vehicle facing `yaw_in` at `a` can drive the leg to `b` and there turn to
    `yaw_out` (None: it stops there), turning no tighter than `radius` (m), and bending at
    most `first_bend` (rad) onto the leg.

    The vehicle rounds each bend in R·tan(θ/2) of the leg: a sharp bend on a short leg has it
    cut through the kerb or overshoot into the far lane. A leg too short to have a heading
    bends at most LEG_BEND_RAD from `yaw_in` to `yaw_out`.
    """
    length = math.dist(a, b)
    if length < MIN_SPACING_M:
        return yaw_out is None or _bend(yaw_in, yaw_out) <= LEG_BEND_RAD
    first = _bend(yaw_in, _heading(a, b))
    bends = [first] + ([] if yaw_out is None else [_bend(_heading(a, b), yaw_out)])
    if first > first_bend or max(bends) > SHARPEST_BEND_RAD:
        return False
    return length >= radius * sum(math.tan(bend / 2) for bend in bends)


def _bend(a: float, b: float) -> float:
    """The angle (rad, 0 to π) turned from heading `a` to heading `b`."""
    return abs(math.remainder(b - a, math.tau))


def _heading(a: Point, b: Point) -> float:
    return math.atan2(b[1] - a[1], b[0] - a[0])


def _bend_cost(headings: Sequence[float], length: float) -> float:
    """BEND_COST_M per radian turned through `headings` in turn (a leg's heading is left out
    where the leg, `length` metres long, is too short to have one)."""
    if length < MIN_SPACING_M:
        headings = [headings[0], headings[-1]] if len(headings) == 3 else []
    return BEND_COST_M * sum(abs(math.remainder(b - a, math.tau)) for a, b in itertools.pairwise(headings))


def _links(scene: Scene, routes: Sequence[PolylineRoute], legs: _Legs) -> list[_Link]:
    """Every way from one lane into another: the turns through each junction box a lane
    crosses (straight on into another lane too), turning back into the lane beside it that
    runs the other way where the box holds the vehicle's turn, and a lane's end into its
    successors."""
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
            for j in near:
                turn_back = u_turn(routes[i], routes[j], box, legs.turn_radius, legs.reach - LEG_CLEARANCE_M)
                if turn_back is not None and legs.sweep(turn_back.points):
                    links.append(_Link(i, turn_back.s_in, j, turn_back.s_out, turn_back.points,
                                       turn_back.length + U_TURN_COST_M))
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


def _within(p: Point, polygon: Sequence[Point], room: float) -> bool:
    """Whether `p` is inside `polygon` or within `room` metres of its edge."""
    return point_in_polygon(p[0], p[1], polygon) or (
        room > 0.0 and nearest_on_polyline(p[0], p[1], [*polygon, polygon[0]]).distance < room)


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
