"""The parts every check shares: its result, its base model and the selection of assets."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Annotated, Literal, TypeVar

from drivetwin.evals.outcome import (
    CaseOutcome,
    describe_selection,
    select,
)
from drivetwin.worlds.catalog import catalog, nearest_categories
from drivetwin.worlds.scene import AssetInstance
from pydantic import AfterValidator, BaseModel, ConfigDict, Field

Scope = Literal["touched", "added", "all"]

_CatT = TypeVar("_CatT", str, list[str], None)


@dataclass(frozen=True)
class CheckResult:
    """Whether one check passed, and why not (or what it saw) in words."""

    kind: str
    passed: bool
    reason: str


class BaseCheck(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:  # pragma: no cover - abstract
        raise NotImplementedError

    def _result(self, passed: bool, reason: str) -> CheckResult:
        kind: str = getattr(self, "kind")  # noqa: B009 - every concrete check defines it
        return CheckResult(kind, passed, reason)


def known_categories(value: _CatT) -> _CatT:
    names: list[str] = [value] if isinstance(value, str) else list(value or [])
    for name in names:
        if name not in catalog():
            near = ", ".join(nearest_categories(name))
            raise ValueError(f"unknown category {name!r}; nearest: {near}")
    return value


CategoryRef = Annotated[str | list[str] | None, AfterValidator(known_categories)]


class SelectingCheck(BaseCheck):
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

    def _judge(self, outcome: CaseOutcome, test: Callable[[AssetInstance], tuple[bool, str]], what: str) -> CheckResult:
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


def describe_range(lo: int | float | None, hi: int | float | None) -> str:
    if lo is not None and hi is not None:
        return f"{lo:g}" if lo == hi else f"{lo:g}..{hi:g}"
    if lo is not None:
        return f">= {lo:g}"
    return f"<= {hi:g}" if hi is not None else "any"
