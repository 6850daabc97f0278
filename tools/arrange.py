"""Arrange Worker: lay out several new assets (or ones already there) as a line, a ring, a grid or along a lane edge."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Literal

from drivetwin.tools.add import new_asset
from drivetwin.tools.along import along_point
from drivetwin.tools.base import CategoryName, Tool, ToolArgs, ToolResult
from drivetwin.tools.errors import NotFoundError, RuleViolation
from drivetwin.tools.locate import SEARCH_RADIUS_M, Location, resolve_anchor, resolve_target
from drivetwin.tools.move import find_asset, follow_placement
from drivetwin.tools.rules import check_placement, footprint
from drivetwin.worlds.catalog import category, is_layout_kit, placeable_categories
from drivetwin.worlds.edits import AddAsset, UpdateAsset, WorldEdit
from drivetwin.worlds.scene import AssetInstance, Pose, Scene
from drivetwin.worlds.surface import nearest_on_polyline, point_along, point_in_polygon, polyline_length
from pydantic import Field

Shape = Literal["line", "ring", "grid", "lane_edge", "parking_row"]
# Free space kept around a ring's target (added to the target's own half-length).
RING_CLEARANCE_M = 1.5
MAX_ARRANGED = 100
# A ring encloses what already stands this close to its centre (the rubble and its cones).
ENCLOSE_WITHIN_M = 6.0
# Gap between a ring and the outermost thing it encloses.
RING_GAP_M = 0.5
# A lane lined "by" a target must pass this close to it; further off it lines another place.
LANE_EDGE_REACH_M = 25.0
# Centre-to-centre spacing of parking bays: a standard car-park bay is 2.4-2.7 m wide.
PARKING_BAY_WIDTH_M = 2.7
# A parked row keeps at least this much between neighbours' sides (doors must open).
PARKING_SIDE_GAP_M = 0.6
# Row positions tried across a parking lot, on a grid this fine.
PARKING_SEARCH_STEP_M = 1.0
# A ring with no count asked for may leave out the positions its things cannot stand on (grass
# round a bench by the road) when at least this share of it, and MIN_RING things, still stand.
RING_KEPT_SHARE = 0.5
MIN_RING = 4
DEFAULT_ROW = 4
DEFAULT_LINE = 5


class ArrangeArgs(ToolArgs):
    categories: list[CategoryName] = Field(
        min_length=1, max_length=4,
        description="one category (homogeneous) or several used in turn (mixed)",
    )
    shape: Shape = Field(
        description="line, ring (around the target), grid, lane_edge, or parking_row: vehicles side by "
        "side at parking-bay spacing, all facing the same way, on a free stretch of a parking lot"
    )
    count: int | None = Field(None, ge=1, le=MAX_ARRANGED, description="how many in all")
    location: Location = Field(
        description="the target to ring around, where the layout starts, or the parking lot for a parking_row"
    )
    radius: float | None = Field(None, gt=0.5, le=60.0, description="ring radius, metres")
    spacing: float | None = Field(None, gt=0.1, le=30.0, description="gap between centres, metres")
    heading_deg: float | None = Field(
        None, ge=-360.0, le=360.0, description="line direction (default: across the path of an in_front_of/behind target, a "
        "line that closes up to fit or is refused; elsewhere along it); for parking_row the way the vehicles face"
    )
    columns: int | None = Field(None, ge=1, le=20, description="grid columns")
    label: str = Field("", max_length=80)
    assets: list[str] = Field(
        default_factory=list, max_length=MAX_ARRANGED,
        description="ids of assets already there to lay out, moved into the layout instead of adding new ones "
        "(then the count is theirs and categories is ignored)",
    )



def _enclosing_radius(scene: Scene, centre: tuple[float, float], widths: list[float], kin: str | None,
                      moving: frozenset[str] = frozenset()) -> float:
    """A ring radius that clears what stands near `centre` and belongs inside: work-zone kit and
    the posts of an earlier ring (the rubble and its cones, a ring of bollards) and things of the
    ringed thing's kind, not a bench beside a tree."""
    radius = 0.0
    for asset in scene.assets:
        if asset.id in moving:  # the trees laid round the fountain are what the ring is made of
            continue
        distance = math.hypot(asset.pose.x - centre[0], asset.pose.y - centre[1])
        inside = asset.category == kin or is_layout_kit(asset.category)
        if distance <= ENCLOSE_WITHIN_M and inside:
            reach = distance + category(asset.category).footprint_radius * asset.scale
            radius = max(radius, reach + RING_GAP_M + max(widths) / 2)
    return radius


def _ring(args: ArrangeArgs, scene: Scene, sizes: list[float], widths: list[float]) -> list[Pose]:
    anchor = resolve_anchor(scene, Location(relation="at", target=args.location.target)
                            if args.location.target else args.location, 0.0)
    target_half = 0.0
    kin = None
    if args.location.target:
        t = resolve_target(scene, args.location.target)
        target_half = t.half_length
        ringed = scene.asset(t.name) if t.kind == "asset" else None
        kin = ringed.category if ringed is not None else None
        # A ring around an asset encloses the asset and its neighbours added with it.
        anchor_xy = (t.x, t.y) if t.kind == "asset" else (anchor.x, anchor.y)
    else:
        anchor_xy = (anchor.x, anchor.y)
    largest = max(sizes)
    radius = args.radius or max(
        target_half + RING_CLEARANCE_M + largest / 2, _enclosing_radius(scene, anchor_xy, widths, kin, frozenset(args.assets)), 2.0
    )
    count = args.count or max(4, int(2 * math.pi * radius / (largest + (args.spacing or 1.0))))
    step = 2 * math.pi / count
    return [
        Pose(x=anchor_xy[0] + radius * math.cos(k * step), y=anchor_xy[1] + radius * math.sin(k * step),
             yaw=k * step + math.pi / 2)
        for k in range(count)
    ]


def _line(args: ArrangeArgs, scene: Scene, sizes: list[float], widths: list[float]) -> list[Pose]:
    anchor = resolve_anchor(scene, args.location, max(sizes) / 2)
    across = args.location.relation in ("in_front_of", "behind")
    # A line in front of something runs across its path (a cordon), elsewhere along it.
    default = anchor.heading + (math.pi / 2 if across else 0.0)
    return _line_at(args, anchor.x, anchor.y, default, sizes, from_anchor=False)


def _turned_line(args: ArrangeArgs, scene: Scene, sizes: list[float], widths: list[float]) -> list[Pose]:
    """The same line turned a quarter: along a path where across it does not fit, and back."""
    anchor = resolve_anchor(scene, args.location, max(sizes) / 2)
    across = args.location.relation in ("in_front_of", "behind")
    # Along the path in front of (behind) something, the line starts there and runs away from it.
    heading = anchor.heading + (math.pi if args.location.relation == "behind" else 0.0)
    return _line_at(args, anchor.x, anchor.y, heading if across else anchor.heading + math.pi / 2, sizes, across)


def _line_at(
    args: ArrangeArgs, x: float, y: float, default: float, sizes: list[float], from_anchor: bool
) -> list[Pose]:
    heading = math.radians(args.heading_deg) if args.heading_deg is not None else default
    spacing = args.spacing or max(sizes) + LINE_GAP_M
    count = args.count or DEFAULT_LINE
    start = 0.0 if from_anchor else -(count - 1) / 2 * spacing
    c, s = math.cos(heading), math.sin(heading)
    return [Pose(x=x + (start + k * spacing) * c, y=y + (start + k * spacing) * s, yaw=heading) for k in range(count)]


def _grid(args: ArrangeArgs, scene: Scene, sizes: list[float], widths: list[float]) -> list[Pose]:
    anchor = resolve_anchor(scene, args.location, max(sizes) / 2)
    count = args.count or 9
    cols = args.columns or max(1, round(math.sqrt(count)))
    rows = math.ceil(count / cols)
    spacing = args.spacing or max(sizes) + 1.0
    heading = math.radians(args.heading_deg) if args.heading_deg is not None else anchor.heading
    c, s = math.cos(heading), math.sin(heading)
    poses = []
    for k in range(count):
        i, j = k % cols, k // cols
        u, v = (i - (cols - 1) / 2) * spacing, (j - (rows - 1) / 2) * spacing
        poses.append(Pose(x=anchor.x + u * c - v * s, y=anchor.y + u * s + v * c, yaw=heading))
    return poses


def _lane_edge(args: ArrangeArgs, scene: Scene, sizes: list[float], widths: list[float]) -> list[Pose]:
    """Poses just inside one edge of a lane, spaced along it in its direction of travel.

    The lane is the one named (location.lane, or a lane as the target), else the lane the
    spot along_m ahead of the target is on, else the lane nearest where the row starts. The
    row starts at the target's point of that lane (plus `distance` along it), along_m ahead
    of or behind the target, or where another relation (in front of, absolute x/y...) puts
    it; it keeps to the lane's right edge (the kerb side for right-hand traffic), or the left
    one with side "left", offset_m from the centreline if given.
    """
    location = args.location
    lanes = scene.roads.lanes
    if not lanes:
        raise NotFoundError("this world has no lanes to line")
    target = resolve_target(scene, location.target) if location.target else None
    named = location.lane or (target.lane_id if target is not None and target.kind == "lane" else None)
    lane = None
    if named is not None:
        lane = scene.roads.lane(named)
        if lane is None:
            raise NotFoundError(f"no lane {named!r}; lanes: {', '.join(ln.id for ln in lanes)}")
    if location.along_m is not None:
        if target is None:
            raise NotFoundError("along_m needs a target (an asset, landmark or lane) to go ahead of or behind")
        along = -abs(location.along_m) if location.relation == "behind" else location.along_m
        spot = along_point(
            scene, target.name, target.x, target.y,
            None if target.kind in ("point", "centre") else target.heading, None, along,
            lane_id=lane.id if lane is not None else None, heading_is_facing=target.kind == "asset",
        )
        lane = lane or scene.roads.lane(spot.track.id)
        if lane is None:
            raise NotFoundError(f"{spot.label} is on no lane to line")
        start = spot.arc
    else:
        if target is not None and location.relation in ("in_lane", "at"):
            point = (target.x, target.y)
        else:
            anchor = resolve_anchor(scene, location, max(sizes) / 2)
            point = (anchor.x, anchor.y)
        if lane is None:
            lane = min(lanes, key=lambda ln: nearest_on_polyline(point[0], point[1], ln.centreline).distance)
        near = nearest_on_polyline(point[0], point[1], lane.centreline)
        if target is not None and target.kind != "lane" and near.distance > LANE_EDGE_REACH_M:
            raise RuleViolation(
                "bounds", f"{lane.id} passes {near.distance:.0f} m from {target.name}, too far to line "
                f"it there (at most {LANE_EDGE_REACH_M:g} m); name a lane that runs by {target.name}",
            )
        start = near.arc_length
        if location.relation in ("in_lane", "at"):
            start += location.distance or 0.0
    spacing = args.spacing or 3.0
    count = args.count or 8
    # a start said along the lane ("starting 15 m ahead of the ego") is kept or moved on, never moved back behind it
    start = row_start(scene, lane.centreline, start, spacing, count, onward_only=location.along_m is not None)
    # Right of the direction of travel unless told otherwise, just inside the lane.
    offset = location.offset_m if location.offset_m is not None else lane.width / 2 - max(sizes) / 2 - 0.2
    if location.side == "left":
        offset = -offset
    poses = []
    for k in range(count):
        x, y, heading = point_along(lane.centreline, start + k * spacing)
        poses.append(Pose(x=x + offset * math.sin(heading), y=y - offset * math.cos(heading), yaw=heading))
    return poses


# How far a row along a lane slides, at most, to keep on the lane and out of a junction.
ROW_SLIDE_MAX_M = 25.0


def row_start(scene: Scene, line: list[tuple[float, float]], start: float, spacing: float, count: int,
              onward_only: bool = False) -> float:
    """Where a row along a lane starts: `start`, else the nearest start (ahead or back, by up to
    ROW_SLIDE_MAX_M or the row's length) whose row stays on the lane, short of its ends, and out of
    the areas it crosses (a junction): "line the eastbound lane" is not lined through the crossroads,
    nor "the lane by the main gate" past the world's edge. `onward_only`: a start that was said is
    only ever moved on along the lane, and kept when no later one is clear."""
    length = polyline_length(line)
    row = (count - 1) * spacing
    areas = [lm.polygon for lm in scene.landmarks if lm.kind == "area" and lm.polygon]

    def clear(at: float) -> bool:
        if at < 0.0 or at + row > length:
            return False
        points = (point_along(line, at + k * spacing) for k in range(count))
        return not any(point_in_polygon(x, y, area) for x, y, _ in points for area in areas)

    reach = max(ROW_SLIDE_MAX_M, row)
    steps = int(reach / spacing) if spacing > 0 else 0
    for k in range(steps + 1):
        for at in ((start,) if k == 0 else (start + k * spacing,) if onward_only else (start + k * spacing, start - k * spacing)):
            if clear(at):
                return at
    return start


def _row_at(x: float, y: float, heading: float, spacing: float, count: int) -> list[Pose]:
    """`count` poses side by side, centred on (x, y), facing `heading`."""
    across = heading + math.pi / 2
    start = -(count - 1) / 2 * spacing
    return [Pose(x=x + (start + k * spacing) * math.cos(across), y=y + (start + k * spacing) * math.sin(across),
                 yaw=heading) for k in range(count)]


def _row_fits(scene: Scene, poses: list[Pose], templates: list[AssetInstance],
              area: list[tuple[float, float]] | None, moving: frozenset[str] = frozenset()) -> bool:
    row = [t.model_copy(update={"pose": p}) for p, t in zip(poses, templates, strict=True)]
    # The cheap test first: a row that sticks out of the lot needs no rule checks.
    if area is not None and not all(point_in_polygon(x, y, area) for a in row for x, y in footprint(a)):
        return False
    placed: list[AssetInstance] = []
    others = [a for a in scene.all_assets() if a.id not in moving]
    for asset in row:
        try:
            check_placement(scene, asset, [*others, *placed])
        except RuleViolation:
            return False
        placed.append(asset)
    return True


def _parking_row(args: ArrangeArgs, scene: Scene, sizes: list[float], widths: list[float]) -> list[Pose]:
    """The free row of parked vehicles nearest the location, inside its parking lot if it names one."""
    anchor = resolve_anchor(scene, args.location, max(sizes) / 2)
    heading = math.radians(args.heading_deg) if args.heading_deg is not None else anchor.heading
    spacing = args.spacing or max(PARKING_BAY_WIDTH_M, max(widths) + PARKING_SIDE_GAP_M)
    count = args.count or DEFAULT_ROW
    templates = ([find_asset(scene, i) for i in args.assets] if args.assets
                 else [new_asset(scene, args.categories[k % len(args.categories)], set()) for k in range(count)])
    # Distinct ids, so the row's members are told apart by the overlap rule.
    templates = [t.model_copy(update={"id": f"{t.id}_row{k}"}) for k, t in enumerate(templates)]
    area = anchor.area
    reach = SEARCH_RADIUS_M
    if area is not None:
        reach = max(max(p[0] for p in area) - min(p[0] for p in area), max(p[1] for p in area) - min(p[1] for p in area))
    steps = int(reach / PARKING_SEARCH_STEP_M)
    centres = sorted(
        ((anchor.x + i * PARKING_SEARCH_STEP_M, anchor.y + j * PARKING_SEARCH_STEP_M)
         for i in range(-steps, steps + 1) for j in range(-steps, steps + 1)),
        key=lambda p: math.hypot(p[0] - anchor.x, p[1] - anchor.y),
    )
    if area is not None:
        centres = [c for c in centres if point_in_polygon(c[0], c[1], area)]

    def first_fit(n: int) -> list[Pose] | None:
        for cx, cy in centres:
            poses = _row_at(cx, cy, heading, spacing, n)
            if _row_fits(scene, poses, templates[:n], area, frozenset(args.assets)):
                return poses
        return None

    row = first_fit(count)
    if row is not None:
        return row
    fit = next((n for n in range(count - 1, 0, -1) if first_fit(n) is not None), 0)
    where = anchor.near.name if anchor.near else f"({anchor.x:.1f}, {anchor.y:.1f})"
    raise RuleViolation(
        "no_space", f"no free row for {count} parked {'/'.join(args.categories)} at {spacing:g} m "
        f"bays in {where}; {fit} fit side by side",
    )


# A line across a path closes up to fit, its neighbours keeping at least this gap, in steps of
# LINE_CLOSE_UP_STEP_M from the default gap (LINE_GAP_M).
LINE_GAP_M = 0.5
LINE_MIN_GAP_M = 0.1
LINE_CLOSE_UP_STEP_M = 0.1


def _closed_up(args: ArrangeArgs, sizes: list[float]) -> list[tuple[ArrangeArgs, str]]:
    """The line as asked, then (when no spacing was asked for) the same line ever more closely
    spaced down to LINE_MIN_GAP_M between neighbours, each with the note saying so."""
    if args.spacing is not None:
        return [(args, "")]
    default = max(sizes) + LINE_GAP_M
    steps = round((LINE_GAP_M - LINE_MIN_GAP_M) / LINE_CLOSE_UP_STEP_M)
    out = [(args, "")]
    for k in range(1, steps + 1):
        spacing = round(default - k * LINE_CLOSE_UP_STEP_M, 6)
        note = f", closed up to {spacing:g} m spacing (from {default:g} m) to fit across"
        out.append((args.model_copy(update={"spacing": spacing}), note))
    return out


def _across_variants(args: ArrangeArgs, sizes: list[float]) -> list[tuple[ArrangeArgs, str]]:
    """A line across a path as asked, closed up; where no count was asked, then fewer (down to
    two), each closed up in turn: "a row of barriers ahead of the ego" spans the road it can."""
    variants = _closed_up(args, sizes)
    if args.count is None:
        for count in range(DEFAULT_LINE - 1, 1, -1):
            fewer = args.model_copy(update={"count": count})
            variants += [(v, f"{note}, {count} to fit across (no count was asked)") for v, note in _closed_up(fewer, sizes)]
    return variants


def _across_refusal(args: ArrangeArgs, sizes: list[float], first: RuleViolation) -> RuleViolation:
    """Why a line across a path cannot be built as asked, and what can be."""
    count = args.count or DEFAULT_LINE
    tightest = args.spacing if args.spacing is not None else max(sizes) + LINE_MIN_GAP_M
    word = "in front of" if args.location.relation == "in_front_of" else "behind"
    where = args.location.target or "it"
    return RuleViolation(
        first.rule, f"a line of {count} {'/'.join(args.categories)} across the path {word} {where} "
        f"does not fit, even {tightest:g} m apart and shifted up to {LAYOUT_SHIFT_MAX_M:g} m "
        f"({first}); ask for fewer, or for a line along the road (heading_deg)",
    )


Placer = Callable[[ArrangeArgs, Scene, list[Pose]], list[AssetInstance]]


def _first_fit(
    place: Placer, args: ArrangeArgs, scene: Scene, groups: list[list[tuple[list[Pose], str]]],
    shifts: list[tuple[float, float]], refusals: list[RuleViolation],
) -> tuple[list[AssetInstance], list[Pose], str] | None:
    """The first layout that fits: group by group, each group's candidates in turn at each shift
    (a line as asked, slid a little along its sidewalk, before it is turned across it); every
    refusal is appended to `refusals`."""
    for group in groups:
        for candidate, note in group:
            for dx, dy in shifts:
                poses = [p.model_copy(update={"x": p.x + dx, "y": p.y + dy}) for p in candidate]
                try:
                    return place(args, scene, poses), poses, note
                except RuleViolation as exc:
                    refusals.append(exc)
    return None


# Shifts of a whole layout tried where it does not fit as anchored: none first, then nearest first
# in eight directions, up to LAYOUT_SHIFT_MAX_M.
LAYOUT_SHIFT_MAX_M = 6.0
_SHIFTS = [(0.0, 0.0)] + [
    (d * math.cos(k * math.pi / 4), d * math.sin(k * math.pi / 4))
    for d in (1.0, 2.0, 3.0, 4.0, 5.0, LAYOUT_SHIFT_MAX_M) for k in range(8)
]

LAYOUTS = {"ring": _ring, "line": _line, "grid": _grid, "lane_edge": _lane_edge, "parking_row": _parking_row}


class ArrangeAssets(Tool[ArrangeArgs]):
    name = "arrange_assets"
    description = (
        "Add several assets laid out as a line, a ring around a target, a grid, along a "
        "lane's edge, or as a parking_row of vehicles side by side in a parking lot; one "
        "category or a mix used in turn; or lay out assets already there (assets), moved into it."
    )
    family = "arrange"
    Args = ArrangeArgs

    def propose(self, args: ArrangeArgs, scene: Scene) -> ToolResult:
        if args.assets:  # "line up the cars in lot B": those there, moved into the layout
            members = [find_asset(scene, i) for i in dict.fromkeys(args.assets)]
            if any(m.id == "ego" for m in members):
                raise RuleViolation("protected", "the ego is placed on its own (place_asset), not laid out with others")
            member_kinds = list(dict.fromkeys(m.category for m in members))[:4]
            args = args.model_copy(update={"assets": [m.id for m in members], "count": len(members), "categories": member_kinds})
        for name in args.categories:
            if name not in placeable_categories():
                raise RuleViolation("protected", f"{name} cannot be arranged")
        cats = [category(c) for c in args.categories]
        sizes = [c.length for c in cats]
        widths = [c.width for c in cats]
        # A line in front of or behind something runs across its path (a cordon): that is what
        # was asked, so it is never turned; where it does not fit it closes up, then is refused.
        across = (args.shape == "line" and args.heading_deg is None
                  and args.location.relation in ("in_front_of", "behind"))
        groups: list[list[tuple[list[Pose], str]]]
        if across:
            groups = [[(_line(variant, scene, sizes, widths), note)]
                      for variant, note in _across_variants(args, sizes)]
        else:
            groups = [[(LAYOUTS[args.shape](args, scene, sizes, widths), "")]]
            if args.shape == "line" and args.heading_deg is None:
                # No direction asked for: the other way round if this one does not fit, said so.
                groups[0].append((_turned_line(args, scene, sizes, widths),
                                  ", turned a quarter because the line as anchored did not fit"))
        refusals: list[RuleViolation] = []
        # Where a line or grid does not fit as anchored (a line at an entrance running into the
        # wall), the nearest shift of the whole layout that does, unless coordinates pinned it; a
        # ring stays round its centre.
        movable = args.shape in ("line", "grid") and args.location.relation != "absolute"
        shifts = _SHIFTS if movable else [(0.0, 0.0)]
        fitted = _first_fit(self._placed, args, scene, groups, shifts, refusals)
        if fitted is None and args.shape == "ring" and args.count is None:
            fitted = self._partial_ring(args, scene, groups[0][0][0])  # "cones around the bench": on the paving
        if fitted is None:
            if across:
                raise _across_refusal(args, sizes, refusals[0])
            raise refusals[0]
        placed, poses, note = fitted
        if args.assets:
            before = {a.id: a for a in scene.all_assets()}
            edit = WorldEdit(ops=tuple(UpdateAsset(before=before[a.id], after=a) for a in placed))
        else:
            edit = WorldEdit(ops=tuple(AddAsset(asset=a) for a in placed))
        cx = sum(p.x for p in poses) / len(poses)
        cy = sum(p.y for p in poses) / len(poses)
        kinds = "/".join(c.name for c in cats)
        moved = f" ({', '.join(args.assets)}, moved)" if args.assets else ""
        return ToolResult(edit, f"arranged {len(placed)} {kinds}{moved} as a {args.shape} at ({cx:.1f}, {cy:.1f}){note}",
                          (cx, cy), {"ids": [a.id for a in placed]})

    @classmethod
    def _partial_ring(cls, args: ArrangeArgs, scene: Scene, poses: list[Pose]
                      ) -> tuple[list[AssetInstance], list[Pose], str] | None:
        """A ring with no count asked for, without the positions where its things cannot stand
        (a cone on the grass round a bench by the road), when at least RING_KEPT_SHARE of it
        stands; None when any other rule refuses a position or too little is left."""
        kept: list[Pose] = []
        for pose in poses:
            try:
                cls._placed(args, scene, [*kept, pose])
            except RuleViolation as exc:
                if exc.rule != "surface":
                    return None
                continue
            kept.append(pose)
        if len(kept) < max(MIN_RING, math.ceil(RING_KEPT_SHARE * len(poses))):
            return None
        left_out = len(poses) - len(kept)
        return cls._placed(args, scene, kept), kept, (
            f", leaving out {left_out} of the ring's {len(poses)} positions where it cannot stand" if left_out else "")

    @staticmethod
    def _placed(args: ArrangeArgs, scene: Scene, poses: list[Pose]) -> list[AssetInstance]:
        """The new assets at `poses` (or those laid out, moved there), each checked against the
        scene and the ones before it."""
        cats = [category(c) for c in args.categories]
        placed: list[AssetInstance] = []
        others = [a for a in scene.all_assets() if a.id not in args.assets]
        for k, pose in enumerate(poses):
            if args.assets:
                asset = follow_placement(scene, find_asset(scene, args.assets[k]).model_copy(update={"pose": pose}))[0]
            else:
                template = new_asset(scene, cats[k % len(cats)].name, {a.id for a in placed}, args.label)
                asset = template.model_copy(update={"pose": pose})
            try:
                check_placement(scene, asset, [*others, *placed])
            except RuleViolation as exc:
                raise RuleViolation(exc.rule, f"{args.shape} position {k + 1} of {len(poses)}: {exc}") from exc
            placed.append(asset)
        return placed
