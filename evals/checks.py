"""Declarative checks on a prompt's outcome: data only, judged against the scenes and answer.

Each check is a pydantic model told apart by `kind`; a suite line holds them as JSON. A
check is never code: it names categories, targets, distances and values, and `evaluate`
turns them into a pass or a fail with a reason a person can act on.
"""

from __future__ import annotations

from typing import Annotated, Literal

from drivetwin.evals.asset_checks import (
    AppearanceCheck,
    ArrangementCheck,
    BehaviourCheck,
    InLaneCheck,
    MovedCheck,
    NearCheck,
    OnSurfaceCheck,
    RelativeCheck,
)
from drivetwin.evals.check_base import (
    BaseCheck,
    CategoryRef,
    CheckResult,
    describe_range,
    known_categories,
)
from drivetwin.evals.outcome import (
    CaseOutcome,
)
from drivetwin.evals.scenario_checks import ScenarioCheck
from drivetwin.worlds.scene import AssetInstance, WeatherKind
from pydantic import AfterValidator, Field


def _count(outcome_scene_assets: list[AssetInstance], categories: list[str]) -> int:
    return sum(1 for a in outcome_scene_assets if not categories or a.category in categories)


class CountCheck(BaseCheck):
    """How many assets of some categories the scene holds after the prompt."""

    kind: Literal["count"] = "count"
    category: CategoryRef = None
    min: int | None = Field(None, ge=0)
    max: int | None = Field(None, ge=0)

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        cats = [self.category] if isinstance(self.category, str) else list(self.category or [])
        n = _count(outcome.after.assets, cats)
        ok = (self.min is None or n >= self.min) and (self.max is None or n <= self.max)
        return self._result(ok, f"{n} {'/'.join(cats) or 'assets'} after, wanted {describe_range(self.min, self.max)}")


class CountDeltaCheck(BaseCheck):
    """How many assets of some categories the prompt added (positive) or removed (negative)."""

    kind: Literal["count_delta"] = "count_delta"
    category: CategoryRef = None
    min: int | None = None
    max: int | None = None

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        cats = [self.category] if isinstance(self.category, str) else list(self.category or [])
        delta = _count(outcome.after.assets, cats) - _count(outcome.before.assets, cats)
        ok = (self.min is None or delta >= self.min) and (self.max is None or delta <= self.max)
        return self._result(
            ok,
            f"{'/'.join(cats) or 'assets'} changed by {delta:+d}, wanted {describe_range(self.min, self.max)}",
        )


class EnvironmentCheck(BaseCheck):
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

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
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


class ExistsCheck(BaseCheck):
    """Named assets are (or are no longer) in the scene after the prompt."""

    kind: Literal["exists"] = "exists"
    assets: list[str] = Field(min_length=1)
    present: bool = True

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        wrong = [i for i in self.assets if (outcome.after.asset(i) is not None) != self.present]
        state = "present" if self.present else "gone"
        return self._result(not wrong, f"not {state}: {', '.join(wrong)}" if wrong else f"all {state}")


class UnchangedExceptCheck(BaseCheck):
    """Nothing changed except assets of the listed categories or ids (and weather if allowed)."""

    kind: Literal["unchanged_except"] = "unchanged_except"
    categories: Annotated[list[str], AfterValidator(known_categories)] = Field(default_factory=list)
    assets: list[str] = Field(default_factory=list)
    environment: bool = False

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        by_id = {a.id: a for a in [*outcome.before.all_assets(), *outcome.after.all_assets()]}
        moved = outcome.added_ids() | outcome.removed_ids() | outcome.changed_ids()
        extra = sorted(i for i in moved if i not in self.assets and by_id[i].category not in self.categories)
        if not self.environment and outcome.before.environment != outcome.after.environment:
            extra.append("environment")
        return self._result(not extra, f"also changed: {', '.join(extra[:6])}" if extra else "nothing else changed")


class AnswerContainsCheck(BaseCheck):
    """The session's answer mentions words or numbers (case-insensitive, whole words)."""

    kind: Literal["answer_contains"] = "answer_contains"
    all_of: list[str] = Field(default_factory=list)
    any_of: list[str] = Field(default_factory=list)
    none_of: list[str] = Field(default_factory=list)

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
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


class StatusCheck(BaseCheck):
    """Whether the session accepted the prompt (applied or answered it) or refused it."""

    kind: Literal["status"] = "status"
    accepted: bool = True

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
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
    | StatusCheck
    | ScenarioCheck,
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
    "scenario",
)
