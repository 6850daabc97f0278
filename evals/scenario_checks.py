"""Scenario checks: run the scene after the prompt in MuJoCo for a while and judge what happened.

A `scenario` check simulates the outcome scene (storyboard, behaviours, lights; no
rendering) for `seconds`, then judges each assertion on the recorded motion: the smallest
gap between two actors' footprints, whether an actor touched anything, whether an actor
reached a place, whether it stopped before a line, and whether a storyboard event of a
kind was there and started. Actors are named by id ("ego") or by catalog category (the
asset of that category that has storyboard events, else the one the prompt added).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Annotated, Literal

from drivetwin.evals.check_base import BaseCheck, CheckResult
from drivetwin.evals.outcome import CaseOutcome
from drivetwin.tools.errors import ToolError
from drivetwin.tools.locate import resolve_target
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Scene
from pydantic import BaseModel, ConfigDict, Field

if TYPE_CHECKING:
    from drivetwin.worlds.simulation import Simulation

__all__ = ["ScenarioCheck"]

Corners = list[tuple[float, float]]
Track = dict[float, tuple[float, float, float]]  # time -> (x, y, yaw)
# A vehicle counts as stopped below this speed (m/s) over the last half second.
STOPPED_MPS = 0.3
STOP_WINDOW_S = 0.5


class _Assertion(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class MinGap(_Assertion):
    """Two actors' footprints never came closer than `metres` (0: they never touched)."""

    kind: Literal["min_gap"] = "min_gap"
    actor: str = EGO_ID
    other: str
    metres: float = Field(ge=0.0, le=100.0)


class Collision(_Assertion):
    """Whether the actor's footprint overlapped any other asset's during the run."""

    kind: Literal["collision"] = "collision"
    actor: str = EGO_ID
    happens: bool = False


class Reached(_Assertion):
    """The actor came within `within` metres of a place (landmark, asset id or 'x, y')."""

    kind: Literal["reached"] = "reached"
    actor: str
    place: str
    within: float = Field(3.0, gt=0.0, le=100.0)


class StoppedBefore(_Assertion):
    """The actor's front never crossed a line (a point it drives towards) and it ended stopped."""

    kind: Literal["stopped_before"] = "stopped_before"
    actor: str = EGO_ID
    line: tuple[float, float]


class EventPlayed(_Assertion):
    """The storyboard has an event of this manoeuvre (and trigger) for the actor, and it started."""

    kind: Literal["event"] = "event"
    actor: str | None = None
    manoeuvre: str
    trigger: str | None = None
    started: bool = True


Assertion = Annotated[MinGap | Collision | Reached | StoppedBefore | EventPlayed, Field(discriminator="kind")]


class ScenarioCheck(BaseCheck):
    """What happens when the scene after the prompt runs for `seconds` of simulated time."""

    kind: Literal["scenario"] = "scenario"
    seconds: float = Field(gt=0.0, le=60.0)
    expect: list[Assertion] = Field(min_length=1)

    def evaluate(self, outcome: CaseOutcome) -> CheckResult:
        # MuJoCo loads only when a scenario check runs (reading a suite stays light).
        from drivetwin.worlds.simulation import Simulation

        scene = outcome.after
        simulation = Simulation(scene)
        simulation.run_for(self.seconds)
        run = _Run(scene, outcome.before, simulation)
        problems: list[str] = []
        seen: list[str] = []
        for assertion in self.expect:
            ok, why = run.judge(assertion)
            (seen if ok else problems).append(why)
        return self._result(not problems, "; ".join(problems) or "; ".join(seen))


class _Run:
    """One simulated run of a scene, with the lookups the assertions need."""

    def __init__(self, scene: Scene, before: Scene, simulation: Simulation) -> None:
        self.scene, self.before, self.simulation = scene, before, simulation
        self.tracks: dict[str, Track] = {}

    def actor(self, name: str) -> AssetInstance | None:
        found = self.scene.asset(name)
        if found is not None:
            return found
        of_kind = [a for a in self.scene.all_assets() if a.category == name]
        acting = self.scene.storyboard.actors()
        for pool in ([a for a in of_kind if a.id in acting], [a for a in of_kind if self.before.asset(a.id) is None], of_kind):
            if pool:
                return pool[-1]
        return None

    def track(self, asset: AssetInstance) -> Track:
        if asset.id not in self.tracks:
            points = self.simulation.trace(asset.id)
            self.tracks[asset.id] = {round(t, 3): (x, y, yaw) for t, x, y, yaw in points}
        return self.tracks[asset.id]

    def pose_at(self, asset: AssetInstance, time: float) -> tuple[float, float, float]:
        track = self.track(asset)
        return track.get(time) or (asset.pose.x, asset.pose.y, asset.pose.yaw)

    def judge(self, assertion: Assertion) -> tuple[bool, str]:
        if isinstance(assertion, EventPlayed):
            return self._event(assertion)
        actor = self.actor(assertion.actor or EGO_ID)
        if actor is None:
            return False, f"no actor {assertion.actor!r} in the scene"
        if isinstance(assertion, MinGap):
            other = self.actor(assertion.other)
            if other is None:
                return False, f"no actor {assertion.other!r} in the scene"
            gap = min((_gap(self._corners(actor, t), self._corners(other, t)) for t in self.times(actor)), default=math.inf)
            return gap >= assertion.metres, f"smallest gap {actor.id}-{other.id} {gap:.1f} m (wanted >= {assertion.metres:g})"
        if isinstance(assertion, Collision):
            hit = self._first_contact(actor)
            said = f"{actor.id} touched {hit}" if hit else f"{actor.id} touched nothing"
            return (hit is not None) == assertion.happens, said
        if isinstance(assertion, Reached):
            return self._reached(actor, assertion)
        return self._stopped_before(actor, assertion)

    def times(self, actor: AssetInstance) -> list[float]:
        return sorted(self.track(actor)) or [0.0]

    def _corners(self, asset: AssetInstance, time: float) -> Corners:
        x, y, yaw = self.pose_at(asset, time)
        return footprint(asset, x, y, yaw)

    def _first_contact(self, actor: AssetInstance) -> str | None:
        reach = category(actor.category).length * actor.scale + 15.0
        for time in self.times(actor):
            mine = self._corners(actor, time)
            ax, ay, _ = self.pose_at(actor, time)
            for other in self.scene.all_assets():
                if other.id == actor.id:
                    continue
                ox, oy, _ = self.pose_at(other, time)
                if math.hypot(ox - ax, oy - ay) < reach and _gap(mine, self._corners(other, time)) == 0.0:
                    return other.id
        return None

    def _reached(self, actor: AssetInstance, assertion: Reached) -> tuple[bool, str]:
        try:
            target = resolve_target(self.scene, assertion.place)
        except ToolError as exc:
            return False, str(exc)
        nearest = min(math.hypot(x - target.x, y - target.y) for x, y, _ in
                      [self.pose_at(actor, t) for t in self.times(actor)])
        return nearest <= assertion.within, f"{actor.id} came within {nearest:.1f} m of {target.name}"

    def _stopped_before(self, actor: AssetInstance, assertion: StoppedBefore) -> tuple[bool, str]:
        times = self.times(actor)
        lx, ly = assertion.line
        x0, y0, _ = self.pose_at(actor, times[0])
        # The line's side: the direction from the actor's start towards the line point.
        heading = math.atan2(ly - y0, lx - x0)
        front = category(actor.category).length * actor.scale / 2
        worst = -math.inf
        for t in times:
            x, y, yaw = self.pose_at(actor, t)
            fx, fy = x + front * math.cos(yaw), y + front * math.sin(yaw)
            worst = max(worst, (fx - lx) * math.cos(heading) + (fy - ly) * math.sin(heading))
        late = [t for t in times if t >= times[-1] - STOP_WINDOW_S]
        (xa, ya, _), (xb, yb, _) = self.pose_at(actor, late[0]), self.pose_at(actor, late[-1])
        speed = math.hypot(xb - xa, yb - ya) / max(late[-1] - late[0], 1e-9)
        ok = worst < 0.0 and speed < STOPPED_MPS
        return ok, f"{actor.id}'s front came {-worst:.1f} m short of the line, ending at {speed:.1f} m/s"

    def _event(self, assertion: EventPlayed) -> tuple[bool, str]:
        actor = None if assertion.actor is None else self.actor(assertion.actor)
        records = self.simulation.player.records.values()
        matching = [r for r in records if r.event.action.kind == assertion.manoeuvre
                    and (actor is None or r.actor == actor.id)
                    and (assertion.trigger is None or r.event.start.kind == assertion.trigger)]
        who = actor.id if actor else "any actor"
        if not matching:
            return False, f"no {assertion.manoeuvre} event for {who}" + (f" on a {assertion.trigger} trigger" if assertion.trigger else "")
        started = [r for r in matching if r.started is not None]
        failed = "; ".join(r.failed for r in matching if r.failed)
        ok = bool(started) == assertion.started
        return ok, f"{assertion.manoeuvre} of {who} {'started' if started else 'never started'}" + (f" ({failed})" if failed else "")


def footprint(asset: AssetInstance, x: float, y: float, yaw: float) -> Corners:
    """The four corners of an asset's ground rectangle at a pose."""
    shape = category(asset.category)
    half_l, half_w = shape.length * asset.scale / 2, shape.width * asset.scale / 2
    c, s = math.cos(yaw), math.sin(yaw)
    return [(x + dx * c - dy * s, y + dx * s + dy * c)
            for dx, dy in ((half_l, half_w), (-half_l, half_w), (-half_l, -half_w), (half_l, -half_w))]


def _separated(a: Corners, b: Corners) -> bool:
    """Separating-axis test for two convex quadrilaterals."""
    for poly in (a, b):
        for i in range(4):
            (x1, y1), (x2, y2) = poly[i], poly[(i + 1) % 4]
            nx, ny = y2 - y1, x1 - x2
            pa = [nx * px + ny * py for px, py in a]
            pb = [nx * px + ny * py for px, py in b]
            if max(pa) < min(pb) or max(pb) < min(pa):
                return True
    return False


def _point_segment(p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / max(dx * dx + dy * dy, 1e-12)))
    return math.hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1])


def _gap(a: Corners, b: Corners) -> float:
    """Distance between two footprints (0 when they overlap)."""
    if not _separated(a, b):
        return 0.0
    return min(
        min(_point_segment(p, q[i], q[(i + 1) % 4]) for p in pts for i in range(4))
        for pts, q in ((a, b), (b, a))
    )
