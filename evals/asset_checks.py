"""Checks on where assets are and what they do: near, relative, surface, lane, layout, motion, looks."""

from __future__ import annotations

import math
from typing import Literal

from drivetwin.evals.check_base import (
    BaseCheck,
    CheckResult,
    Scope,
    SelectingCheck,
    describe_range,
)
from drivetwin.evals.geometry import (
    ArrangementShape,
    behaviour_matches,
    judge_arrangement,
    matches_colour,
)
from drivetwin.evals.outcome import (
    CaseOutcome,
    TargetNotFound,
    angle_between,
    describe_selection,
    distance_to_target,
    find_target,
    select,
)
from drivetwin.tools.locate import Target
from drivetwin.worlds.scene import AssetInstance
from drivetwin.worlds.surface import DRIVABLE, nearest_on_polyline, surface_at
from pydantic import Field, model_validator

SurfaceName = Literal["building", "lane", "crossing", "paved", "sidewalk", "ground", "drivable"]
RelationName = Literal["in_front_of", "behind", "left_of", "right_of"]
Direction = Literal["forward", "backward", "left", "right"]
# A lane-aligned vehicle may sit this far off the lane's heading (it turns, or parks askew).
LANE_ALIGN_TOLERANCE_DEG = 30.0
# A move "forward" may deviate this much from the asset's original heading.
MOVE_DIRECTION_TOLERANCE_DEG = 45.0
_RELATION_OFFSET = {
    "in_front_of": 0.0,
    "behind": math.pi,
    "left_of": math.pi / 2,
    "right_of": -math.pi / 2,
}
_DIRECTION_OFFSET = {
    "forward": 0.0,
    "backward": math.pi,
    "left": math.pi / 2,
    "right": -math.pi / 2,
}


class NearCheck(SelectingCheck):
    """Assets within a distance of a landmark, asset, lane or building, or of a point."""

    kind: Literal["near"] = "near"
    target: str | None = Field(None, description="landmark, asset id, lane id or building")
    point: tuple[float, float] | None = Field(None, description="or: x, y in metres")
    within: float = Field(10.0, gt=0.0, description="metres from the target's point or outline")

    @model_validator(mode="after")
    def _one_place(self) -> NearCheck:
        if (self.target is None) == (self.point is None):
            raise ValueError("a near check needs exactly one of target and point")
        return self

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        if self.point is not None:
            x, y = self.point
            target = Target(f"({x:g}, {y:g})", "centre", x, y, 0.0)
        else:
            try:
                target = find_target(outcome, str(self.target))
            except TargetNotFound as exc:
                return self._result(False, str(exc))

        def test(a: AssetInstance) -> tuple[bool, str]:
            d = distance_to_target(a.pose.x, a.pose.y, target, outcome.after)
            return d <= self.within, f"is {d:.1f} m away"

        return self._judge(outcome, test, f"within {self.within:g} m of {target.name}")


class RelativeCheck(SelectingCheck):
    """Assets in front of, behind, left or right of a target, by the target's own facing."""

    kind: Literal["relative"] = "relative"
    relation: RelationName
    target: str
    max_distance: float = Field(15.0, gt=0.0)
    tolerance_deg: float = Field(60.0, gt=0.0, le=90.0, description="off the exact direction")

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        try:
            target = find_target(outcome, self.target)
        except TargetNotFound as exc:
            return self._result(False, str(exc))
        want = target.heading + _RELATION_OFFSET[self.relation]

        def test(a: AssetInstance) -> tuple[bool, str]:
            dx, dy = a.pose.x - target.x, a.pose.y - target.y
            d = math.hypot(dx, dy)
            if d > self.max_distance:
                return False, f"is {d:.1f} m away"
            if d < 1e-6:
                return False, "stands on the target itself"
            off = math.degrees(angle_between(math.atan2(dy, dx), want))
            return off <= self.tolerance_deg, f"is {off:.0f} deg off that direction"

        words = self.relation.replace("_", " ")
        return self._judge(outcome, test, f"{words} {self.target}")


class OnSurfaceCheck(SelectingCheck):
    """Assets standing on one of some kinds of ground (sidewalk, lane, drivable...)."""

    kind: Literal["on_surface"] = "on_surface"
    surfaces: list[SurfaceName] = Field(min_length=1)
    require_all: bool = True

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        allowed = set(self.surfaces)
        if "drivable" in allowed:
            allowed |= set(DRIVABLE)

        def test(a: AssetInstance) -> tuple[bool, str]:
            ground = surface_at(outcome.after, a.pose.x, a.pose.y)
            return ground in allowed, f"stands on {ground}"

        return self._judge(outcome, test, f"on {' or '.join(self.surfaces)}")


class InLaneCheck(SelectingCheck):
    """Assets inside a lane's strip (a given lane or any), optionally facing along it."""

    kind: Literal["in_lane"] = "in_lane"
    lane: str | None = None
    aligned: bool = False
    require_all: bool = True

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        lanes = outcome.after.roads.lanes
        if self.lane is not None:
            lanes = [ln for ln in lanes if ln.id == self.lane]
            if not lanes:
                return self._result(False, f"the world has no lane {self.lane!r}")

        def test(a: AssetInstance) -> tuple[bool, str]:
            for lane in lanes:
                near = nearest_on_polyline(a.pose.x, a.pose.y, lane.centreline)
                if near.distance > lane.width / 2:
                    continue
                off = math.degrees(angle_between(a.pose.yaw, near.heading))
                if self.aligned and off > LANE_ALIGN_TOLERANCE_DEG:
                    return False, f"is in {lane.id} but faces {off:.0f} deg off it"
                return True, f"is in {lane.id}"
            return False, f"at ({a.pose.x:.1f}, {a.pose.y:.1f}) is in no such lane"

        return self._judge(outcome, test, f"in lane {self.lane or '(any)'}")


class ArrangementCheck(SelectingCheck):
    """The selected assets, together, form a line or a ring (around a target), with spacing."""

    kind: Literal["arrangement"] = "arrangement"
    shape: ArrangementShape
    around: str | None = Field(None, description="ring: target inside the ring")
    scope: Scope = "added"
    min_count: int = Field(3, ge=2)
    tolerance: float = Field(1.0, gt=0.0, description="metres off the ideal line or circle")
    spacing_min: float | None = Field(None, ge=0.0)
    spacing_max: float | None = Field(None, gt=0.0)

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        chosen = select(outcome, self.categories, self.asset, self.scope)
        if len(chosen) < self.min_count:
            who = describe_selection(self.categories, self.asset, self.scope)
            return self._result(False, f"{len(chosen)} {who}, need at least {self.min_count}")
        centre = None
        if self.around is not None:
            try:
                t = find_target(outcome, self.around)
            except TargetNotFound as exc:
                return self._result(False, str(exc))
            centre = (t.x, t.y)
        ok, why = judge_arrangement(
            [(a.pose.x, a.pose.y) for a in chosen],
            self.shape,
            self.tolerance,
            centre,
            self.spacing_min,
            self.spacing_max,
        )
        return self._result(ok, why)


class BehaviourCheck(SelectingCheck):
    """Assets doing a behaviour, with parameters in ranges (speed, radius, lane, crossing)."""

    kind: Literal["behaviour"] = "behaviour"
    behaviour: str | list[str]
    speed_min: float | None = None
    speed_max: float | None = None
    radius_min: float | None = None
    radius_max: float | None = None
    lane: str | None = None
    clockwise: bool | None = None
    crosses_lane: str | None = Field(None, description="a walk whose path crosses this lane")
    centre_near: str | None = Field(None, description="circle centre within centre_within")
    centre_within: float = Field(20.0, gt=0.0)

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        kinds = [self.behaviour] if isinstance(self.behaviour, str) else self.behaviour
        centre = None
        if self.centre_near is not None:
            try:
                centre = find_target(outcome, self.centre_near)
            except TargetNotFound as exc:
                return self._result(False, str(exc))

        def test(a: AssetInstance) -> tuple[bool, str]:
            verdict: tuple[bool, str] = behaviour_matches(
                a,
                outcome.after,
                kinds,
                speed=(self.speed_min, self.speed_max),
                radius=(self.radius_min, self.radius_max),
                lane=self.lane,
                clockwise=self.clockwise,
                crosses_lane=self.crosses_lane,
                centre=centre,
                centre_within=self.centre_within,
            )
            return verdict

        return self._judge(outcome, test, f"doing {'/'.join(kinds)}")


class AppearanceCheck(SelectingCheck):
    """Assets with a colour (by name or #rrggbb, within a tolerance) and/or a material."""

    kind: Literal["appearance"] = "appearance"
    colour: str | list[str] | None = None
    colour_tolerance: float = Field(0.2, gt=0.0, le=1.0, description="per RGB channel")
    material: str | None = None

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        colours = [self.colour] if isinstance(self.colour, str) else list(self.colour or [])

        def test(a: AssetInstance) -> tuple[bool, str]:
            look = a.appearance
            if colours and not any(matches_colour(look.rgba, c, self.colour_tolerance) for c in colours):
                return False, f"has colour {look.rgba or 'default'}"
            if self.material is not None and look.material != self.material:
                return False, f"is {look.material}"
            return True, "looks right"

        return self._judge(outcome, test, f"looking {'/'.join(colours)} {self.material or ''}".strip())


class MovedCheck(BaseCheck):
    """An existing asset moved a distance, in a direction of its own frame, and/or turned."""

    kind: Literal["moved"] = "moved"
    asset: str
    min_distance: float = Field(0.0, ge=0.0)
    max_distance: float | None = Field(None, gt=0.0)
    direction: Direction | None = None
    turn_min_deg: float | None = Field(None, ge=0.0, le=180.0)
    turn_max_deg: float | None = Field(None, ge=0.0, le=180.0)

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        a, b = outcome.before.asset(self.asset), outcome.after.asset(self.asset)
        if a is None or b is None:
            return self._result(False, f"asset {self.asset} is not in the scene before and after")
        dx, dy = b.pose.x - a.pose.x, b.pose.y - a.pose.y
        d = math.hypot(dx, dy)
        turn = math.degrees(angle_between(b.pose.yaw, a.pose.yaw))
        problems = []
        if d < self.min_distance or (self.max_distance is not None and d > self.max_distance):
            problems.append(f"moved {d:.1f} m, wanted {describe_range(self.min_distance, self.max_distance)}")
        if self.direction is not None and d > 1e-6:
            want = a.pose.yaw + _DIRECTION_OFFSET[self.direction]
            off = math.degrees(angle_between(math.atan2(dy, dx), want))
            if off > MOVE_DIRECTION_TOLERANCE_DEG:
                problems.append(f"moved {off:.0f} deg away from {self.direction}")
        if self.turn_min_deg is not None and turn < self.turn_min_deg:
            problems.append(f"turned {turn:.0f} deg < {self.turn_min_deg:g}")
        if self.turn_max_deg is not None and turn > self.turn_max_deg:
            problems.append(f"turned {turn:.0f} deg > {self.turn_max_deg:g}")
        return self._result(not problems, "; ".join(problems) or f"{self.asset} moved {d:.1f} m")
