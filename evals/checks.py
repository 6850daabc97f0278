"""Declarative checks on a prompt's outcome: data only, judged against the scenes and answer.

Each check is a pydantic model told apart by `kind`; a suite line holds them as JSON. A
check is never code: it names categories, targets, distances and values, and `evaluate`
turns them into a pass or a fail with a reason a person can act on.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Annotated, Literal, TypeVar

from drivetwin.evals.geometry import (
    ArrangementShape,
    behaviour_matches,
    judge_arrangement,
    matches_colour,
)
from drivetwin.evals.outcome import (
    Outcome,
    TargetNotFound,
    angle_between,
    describe_selection,
    distance_to_target,
    find_target,
    select,
)
from drivetwin.tools.locate import Target
from drivetwin.worlds.catalog import catalog, nearest_categories
from drivetwin.worlds.scene import AssetInstance, WeatherKind
from drivetwin.worlds.surface import DRIVABLE, nearest_on_polyline, surface_at
from pydantic import AfterValidator, BaseModel, ConfigDict, Field, model_validator

Scope = Literal["touched", "added", "all"]
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


_CatT = TypeVar("_CatT", str, list[str], None)


@dataclass(frozen=True)
class CheckResult:
    """Whether one check passed, and why not (or what it saw) in words."""

    kind: str
    passed: bool
    reason: str


class _Check(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    def evaluate(self, outcome: Outcome) -> CheckResult:  # pragma: no cover - abstract
        raise NotImplementedError

    def _result(self, passed: bool, reason: str) -> CheckResult:
        kind: str = getattr(self, "kind")  # noqa: B009 - every concrete check defines it
        return CheckResult(kind, passed, reason)


def _known_categories(value: _CatT) -> _CatT:
    names: list[str] = [value] if isinstance(value, str) else list(value or [])
    for name in names:
        if name not in catalog():
            near = ", ".join(nearest_categories(name))
            raise ValueError(f"unknown category {name!r}; nearest: {near}")
    return value


CategoryRef = Annotated[str | list[str] | None, AfterValidator(_known_categories)]


class _Selecting(_Check):
    """A check about some assets: of categories, or one asset id, within a scope."""

    category: CategoryRef = Field(None, description="catalog category or categories")
    asset: str | None = Field(None, description="one asset id (overrides category and scope)")
    scope: Scope = Field("touched", description="touched: added or changed by the prompt")
    min_count: int = Field(1, ge=0, description="at least this many selected assets must pass")
    require_all: bool = Field(False, description="every selected asset must pass")

    @property
    def categories(self) -> list[str]:
        if self.category is None:
            return []
        return [self.category] if isinstance(self.category, str) else list(self.category)

    def _judge(self, outcome: Outcome, test: Callable[[AssetInstance], tuple[bool, str]], what: str) -> CheckResult:
        chosen = select(outcome, self.categories, self.asset, self.scope)
        who = describe_selection(self.categories, self.asset, self.scope)
        if not chosen:
            return self._result(self.min_count == 0, f"no {who} in the scene to judge")
        verdicts = [(a, *test(a)) for a in chosen]
        good = [a for a, ok, _ in verdicts if ok]
        bad = [(a, why) for a, ok, why in verdicts if not ok]
        enough = len(good) >= self.min_count
        if enough and not (self.require_all and bad):
            return self._result(True, f"{len(good)} of {len(chosen)} {who} {what}")
        example = f"; e.g. {bad[0][0].id} {bad[0][1]}" if bad else ""
        need = "all" if self.require_all else f"at least {self.min_count}"
        return self._result(False, f"{len(good)} of {len(chosen)} {who} {what}, need {need}{example}")


def _count(outcome_scene_assets: list[AssetInstance], categories: list[str]) -> int:
    return sum(1 for a in outcome_scene_assets if not categories or a.category in categories)


class CountCheck(_Check):
    """How many assets of some categories the scene holds after the prompt."""

    kind: Literal["count"] = "count"
    category: CategoryRef = None
    min: int | None = Field(None, ge=0)
    max: int | None = Field(None, ge=0)

    def evaluate(self, outcome: Outcome) -> CheckResult:
        cats = [self.category] if isinstance(self.category, str) else list(self.category or [])
        n = _count(outcome.after.assets, cats)
        ok = (self.min is None or n >= self.min) and (self.max is None or n <= self.max)
        return self._result(ok, f"{n} {'/'.join(cats) or 'assets'} after, wanted {_range(self.min, self.max)}")


class CountDeltaCheck(_Check):
    """How many assets of some categories the prompt added (positive) or removed (negative)."""

    kind: Literal["count_delta"] = "count_delta"
    category: CategoryRef = None
    min: int | None = None
    max: int | None = None

    def evaluate(self, outcome: Outcome) -> CheckResult:
        cats = [self.category] if isinstance(self.category, str) else list(self.category or [])
        delta = _count(outcome.after.assets, cats) - _count(outcome.before.assets, cats)
        ok = (self.min is None or delta >= self.min) and (self.max is None or delta <= self.max)
        return self._result(
            ok,
            f"{'/'.join(cats) or 'assets'} changed by {delta:+d}, wanted {_range(self.min, self.max)}",
        )


def _range(lo: int | float | None, hi: int | float | None) -> str:
    if lo is not None and hi is not None:
        return f"{lo:g}" if lo == hi else f"{lo:g}..{hi:g}"
    if lo is not None:
        return f">= {lo:g}"
    return f"<= {hi:g}" if hi is not None else "any"


class NearCheck(_Selecting):
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

    def evaluate(self, outcome: Outcome) -> CheckResult:
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


class RelativeCheck(_Selecting):
    """Assets in front of, behind, left or right of a target, by the target's own facing."""

    kind: Literal["relative"] = "relative"
    relation: RelationName
    target: str
    max_distance: float = Field(15.0, gt=0.0)
    tolerance_deg: float = Field(60.0, gt=0.0, le=90.0, description="off the exact direction")

    def evaluate(self, outcome: Outcome) -> CheckResult:
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


class OnSurfaceCheck(_Selecting):
    """Assets standing on one of some kinds of ground (sidewalk, lane, drivable...)."""

    kind: Literal["on_surface"] = "on_surface"
    surfaces: list[SurfaceName] = Field(min_length=1)
    require_all: bool = True

    def evaluate(self, outcome: Outcome) -> CheckResult:
        allowed = set(self.surfaces)
        if "drivable" in allowed:
            allowed |= set(DRIVABLE)

        def test(a: AssetInstance) -> tuple[bool, str]:
            ground = surface_at(outcome.after, a.pose.x, a.pose.y)
            return ground in allowed, f"stands on {ground}"

        return self._judge(outcome, test, f"on {' or '.join(self.surfaces)}")


class InLaneCheck(_Selecting):
    """Assets inside a lane's strip (a given lane or any), optionally facing along it."""

    kind: Literal["in_lane"] = "in_lane"
    lane: str | None = None
    aligned: bool = False
    require_all: bool = True

    def evaluate(self, outcome: Outcome) -> CheckResult:
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


class ArrangementCheck(_Selecting):
    """The selected assets, together, form a line or a ring (around a target), with spacing."""

    kind: Literal["arrangement"] = "arrangement"
    shape: ArrangementShape
    around: str | None = Field(None, description="ring: target inside the ring")
    scope: Scope = "added"
    min_count: int = Field(3, ge=2)
    tolerance: float = Field(1.0, gt=0.0, description="metres off the ideal line or circle")
    spacing_min: float | None = Field(None, ge=0.0)
    spacing_max: float | None = Field(None, gt=0.0)

    def evaluate(self, outcome: Outcome) -> CheckResult:
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


class BehaviourCheck(_Selecting):
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

    def evaluate(self, outcome: Outcome) -> CheckResult:
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


class EnvironmentCheck(_Check):
    """Weather, time of day and lighting after the prompt."""

    kind: Literal["environment"] = "environment"
    weather: list[WeatherKind] | None = None
    intensity_min: float | None = Field(None, ge=0.0, le=1.0)
    intensity_max: float | None = Field(None, ge=0.0, le=1.0)
    night: bool | None = Field(None, description="night: before 06:30 or from 19:00")
    time_from: str | None = Field(None, pattern=r"^\d\d:\d\d$", description="HH:MM, wraps midnight")
    time_to: str | None = Field(None, pattern=r"^\d\d:\d\d$")
    street_lights: Literal["auto", "on", "off"] | None = None
    vehicle_lights: Literal["auto", "on", "off"] | None = None
    exposure_min: float | None = None
    exposure_max: float | None = None

    def evaluate(self, outcome: Outcome) -> CheckResult:
        env = outcome.after.environment
        w, light = env.weather, env.lighting
        problems = []
        if self.weather is not None and w.kind not in self.weather:
            problems.append(f"weather is {w.kind}, wanted {' or '.join(self.weather)}")
        if self.intensity_min is not None and w.intensity < self.intensity_min:
            problems.append(f"intensity {w.intensity:.2f} < {self.intensity_min:g}")
        if self.intensity_max is not None and w.intensity > self.intensity_max:
            problems.append(f"intensity {w.intensity:.2f} > {self.intensity_max:g}")
        if self.night is not None and env.is_night != self.night:
            problems.append(f"time {env.time_of_day} is {'night' if env.is_night else 'day'}")
        if self.time_from is not None or self.time_to is not None:
            lo, hi = _hours(self.time_from or "00:00"), _hours(self.time_to or "23:59")
            h = env.hours
            inside = lo <= h <= hi if lo <= hi else (h >= lo or h <= hi)
            if not inside:
                problems.append(f"time {env.time_of_day} not in {self.time_from}..{self.time_to}")
        for name in ("street_lights", "vehicle_lights"):
            want, got = getattr(self, name), getattr(light, name)
            if want is not None and got != want:
                problems.append(f"{name} {got}, wanted {want}")
        if self.exposure_min is not None and light.exposure < self.exposure_min:
            problems.append(f"exposure {light.exposure:g} < {self.exposure_min:g}")
        if self.exposure_max is not None and light.exposure > self.exposure_max:
            problems.append(f"exposure {light.exposure:g} > {self.exposure_max:g}")
        seen = f"{w.kind} {w.intensity:.1f}, {env.time_of_day}"
        return self._result(not problems, "; ".join(problems) or f"environment ok ({seen})")


def _hours(clock: str) -> float:
    hh, mm = clock.split(":")
    return int(hh) + int(mm) / 60.0


class AppearanceCheck(_Selecting):
    """Assets with a colour (by name or #rrggbb, within a tolerance) and/or a material."""

    kind: Literal["appearance"] = "appearance"
    colour: str | list[str] | None = None
    colour_tolerance: float = Field(0.2, gt=0.0, le=1.0, description="per RGB channel")
    material: str | None = None

    def evaluate(self, outcome: Outcome) -> CheckResult:
        colours = [self.colour] if isinstance(self.colour, str) else list(self.colour or [])

        def test(a: AssetInstance) -> tuple[bool, str]:
            look = a.appearance
            if colours and not any(matches_colour(look.rgba, c, self.colour_tolerance) for c in colours):
                return False, f"has colour {look.rgba or 'default'}"
            if self.material is not None and look.material != self.material:
                return False, f"is {look.material}"
            return True, "looks right"

        return self._judge(outcome, test, f"looking {'/'.join(colours)} {self.material or ''}".strip())


class MovedCheck(_Check):
    """An existing asset moved a distance, in a direction of its own frame, and/or turned."""

    kind: Literal["moved"] = "moved"
    asset: str
    min_distance: float = Field(0.0, ge=0.0)
    max_distance: float | None = Field(None, gt=0.0)
    direction: Direction | None = None
    turn_min_deg: float | None = Field(None, ge=0.0, le=180.0)
    turn_max_deg: float | None = Field(None, ge=0.0, le=180.0)

    def evaluate(self, outcome: Outcome) -> CheckResult:
        a, b = outcome.before.asset(self.asset), outcome.after.asset(self.asset)
        if a is None or b is None:
            return self._result(False, f"asset {self.asset} is not in the scene before and after")
        dx, dy = b.pose.x - a.pose.x, b.pose.y - a.pose.y
        d = math.hypot(dx, dy)
        turn = math.degrees(angle_between(b.pose.yaw, a.pose.yaw))
        problems = []
        if d < self.min_distance or (self.max_distance is not None and d > self.max_distance):
            problems.append(f"moved {d:.1f} m, wanted {_range(self.min_distance, self.max_distance)}")
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


class ExistsCheck(_Check):
    """Named assets are (or are no longer) in the scene after the prompt."""

    kind: Literal["exists"] = "exists"
    assets: list[str] = Field(min_length=1)
    present: bool = True

    def evaluate(self, outcome: Outcome) -> CheckResult:
        wrong = [i for i in self.assets if (outcome.after.asset(i) is not None) != self.present]
        state = "present" if self.present else "gone"
        return self._result(not wrong, f"not {state}: {', '.join(wrong)}" if wrong else f"all {state}")


class UnchangedExceptCheck(_Check):
    """Nothing changed except assets of the listed categories or ids (and weather if allowed)."""

    kind: Literal["unchanged_except"] = "unchanged_except"
    categories: Annotated[list[str], AfterValidator(_known_categories)] = Field(default_factory=list)
    assets: list[str] = Field(default_factory=list)
    environment: bool = False

    def evaluate(self, outcome: Outcome) -> CheckResult:
        by_id = {a.id: a for a in [*outcome.before.all_assets(), *outcome.after.all_assets()]}
        moved = outcome.added_ids() | outcome.removed_ids() | outcome.changed_ids()
        extra = sorted(i for i in moved if i not in self.assets and by_id[i].category not in self.categories)
        if not self.environment and outcome.before.environment != outcome.after.environment:
            extra.append("environment")
        return self._result(not extra, f"also changed: {', '.join(extra[:6])}" if extra else "nothing else changed")


class AnswerContainsCheck(_Check):
    """The session's answer mentions words or numbers (case-insensitive, whole words)."""

    kind: Literal["answer_contains"] = "answer_contains"
    all_of: list[str] = Field(default_factory=list)
    any_of: list[str] = Field(default_factory=list)
    none_of: list[str] = Field(default_factory=list)

    def evaluate(self, outcome: Outcome) -> CheckResult:
        from drivetwin.evals.geometry import mentions

        text = outcome.answer_text
        missing = [w for w in self.all_of if not mentions(text, w)]
        problems = [f"does not mention {', '.join(missing)}"] if missing else []
        if self.any_of and not any(mentions(text, w) for w in self.any_of):
            problems.append(f"mentions none of {', '.join(self.any_of)}")
        wrong = [w for w in self.none_of if mentions(text, w)]
        if wrong:
            problems.append(f"wrongly mentions {', '.join(wrong)}")
        short = text.strip().replace("\n", " | ")[:120]
        return self._result(not problems, "; ".join(problems) + f" (answer: {short!r})" if problems else "answer ok")


class StatusCheck(_Check):
    """Whether the session accepted the prompt (applied or answered it) or refused it."""

    kind: Literal["status"] = "status"
    accepted: bool = True

    def evaluate(self, outcome: Outcome) -> CheckResult:
        got = "accepted" if outcome.accepted else f"refused ({outcome.error})"
        return self._result(outcome.accepted == self.accepted, f"the prompt was {got}")


Check = Annotated[
    CountCheck
    | CountDeltaCheck
    | NearCheck
    | RelativeCheck
    | OnSurfaceCheck
    | InLaneCheck
    | ArrangementCheck
    | BehaviourCheck
    | EnvironmentCheck
    | AppearanceCheck
    | MovedCheck
    | ExistsCheck
    | UnchangedExceptCheck
    | AnswerContainsCheck
    | StatusCheck,
    Field(discriminator="kind"),
]
CHECK_KINDS: tuple[str, ...] = (
    "count",
    "count_delta",
    "near",
    "relative",
    "on_surface",
    "in_lane",
    "arrangement",
    "behaviour",
    "environment",
    "appearance",
    "moved",
    "exists",
    "unchanged_except",
    "answer_contains",
    "status",
)
