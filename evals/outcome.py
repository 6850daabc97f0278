"""What a case's prompt produced, and the scene queries that checks are judged with.

A check never sees the planner's calls: it sees the scene before the prompt, the scene after
it and the words the session answered with. That keeps grading about outcomes, so two
different plans that build the same scene grade the same.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

from drivetwin.tools.errors import ToolError
from drivetwin.tools.locate import Target, resolve_target
from drivetwin.worlds.scene import AssetInstance, Scene
from drivetwin.worlds.surface import nearest_on_polyline, point_in_polygon


@dataclass(frozen=True)
class CaseOutcome:
    """The scene before and after a case's prompt, whether it was accepted, and its answer."""

    before: Scene
    after: Scene
    accepted: bool = True
    answer: str = ""
    error: str | None = None
    # Result texts of each call (search answers included), searched by answer checks too.
    results: tuple[str, ...] = field(default_factory=tuple)

    @property
    def answer_text(self) -> str:
        """Everything the session said back, as one text."""
        return "\n".join([self.answer, *self.results])

    def added_ids(self) -> set[str]:
        """Ids of assets that exist after the prompt and did not before."""
        before = {a.id for a in self.before.all_assets()}
        return {a.id for a in self.after.all_assets() if a.id not in before}

    def removed_ids(self) -> set[str]:
        """Ids of assets that existed before the prompt and do not after."""
        after = {a.id for a in self.after.all_assets()}
        return {a.id for a in self.before.all_assets() if a.id not in after}

    def changed_ids(self) -> set[str]:
        """Ids of assets present before and after whose state differs in any way."""
        before = {a.id: a for a in self.before.all_assets()}
        return {a.id for a in self.after.all_assets() if a.id in before and before[a.id] != a}

    def touched_ids(self) -> set[str]:
        """Ids of assets the prompt added or changed (removed ones are no longer there)."""
        return self.added_ids() | self.changed_ids()


class TargetNotFound(LookupError):
    """A check names a landmark, asset, lane or building that the scene does not have."""


def find_target(outcome: CaseOutcome, name: str) -> Target:
    """The named target in the scene after the prompt, or before it if it has since gone."""
    for scene in (outcome.after, outcome.before):
        try:
            return resolve_target(scene, name)
        except ToolError:
            continue
    raise TargetNotFound(f"no landmark, asset, lane or building called {name!r}")


def distance_to_target(x: float, y: float, target: Target, scene: Scene) -> float:
    """Metres from (x, y) to a target: 0 inside an area, else to its outline, point or lane."""
    if target.polygon is not None:
        if point_in_polygon(x, y, target.polygon):
            return 0.0
        ring = [*target.polygon, target.polygon[0]]
        return float(nearest_on_polyline(x, y, ring).distance)
    if target.lane_id is not None:
        lane = scene.roads.lane(target.lane_id)
        if lane is not None:
            return float(nearest_on_polyline(x, y, lane.centreline).distance)
    # An asset target is measured from its edge: "next to the bus" is near its side too.
    gap: float = math.hypot(x - target.x, y - target.y) - target.half_length
    return max(0.0, gap)


def angle_between(a: float, b: float) -> float:
    """The absolute difference of two headings, in radians within [0, pi]."""
    return abs(math.remainder(a - b, 2 * math.pi))


def select(
    outcome: CaseOutcome,
    categories: Sequence[str],
    asset: str | None,
    scope: str,
) -> list[AssetInstance]:
    """The assets after the prompt that a check is about (ego included where it qualifies).

    `scope` "touched" keeps assets the prompt added or changed, "added" only new ones and
    "all" every asset; naming an `asset` id picks that asset whatever the scope.
    """
    if asset is not None:
        found = outcome.after.asset(asset)
        return [found] if found is not None else []
    pool = outcome.after.all_assets()
    if scope == "touched":
        keep = outcome.touched_ids()
        pool = [a for a in pool if a.id in keep]
    elif scope == "added":
        keep = outcome.added_ids()
        pool = [a for a in pool if a.id in keep]
    chosen: list[AssetInstance] = [a for a in pool if not categories or a.category in categories]
    return chosen


def describe_selection(categories: Sequence[str], asset: str | None, scope: str) -> str:
    """Words for what a check selected, for failure reasons."""
    if asset is not None:
        return f"asset {asset}"
    what = "/".join(categories) if categories else "asset"
    return {"touched": f"added or changed {what}", "added": f"new {what}", "all": what}[scope]
