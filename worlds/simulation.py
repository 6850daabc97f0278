"""The live simulation: a MujocoWorld stepped at a fixed dt with behaviours, in the background.

Edits arrive as whole Scenes through `apply`; they take the lock, so they land between two
physics steps. Readers (renderer, sensors) take the same lock to read `world.model` and
`world.data`, which are replaced on every recompile: read them through `world` each time.
"""

from __future__ import annotations

import logging
import threading
import time as wallclock
from collections import deque

import mujoco
from drivetwin.worlds.behaviours import BehaviourRunner, UnknownLaneError, runner_for
from drivetwin.worlds.mujoco_adapter import DEFAULT_TIMESTEP, MujocoWorld, UpdateStats, scene_diff
from drivetwin.worlds.scenario_player import StoryboardPlayer
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Pose, Scene

__all__ = ["DEFAULT_CONTROL_EVERY", "Simulation", "TracePoint"]

log = logging.getLogger(__name__)

# Behaviours run every 4 physics steps: 50 Hz at the default 5 ms step, as fast as a real
# vehicle's steering and speed loops and a quarter of the Python cost per simulated second.
DEFAULT_CONTROL_EVERY = 4
# A trace keeps this many control ticks per asset (about 6.7 minutes at 50 Hz).
TRACE_LENGTH = 20_000
# The background loop holds the lock for at most this many steps at a time, so an edit or
# a render waits at most a few milliseconds.
STEPS_PER_LOCK = 8
# Behind real time by more than this, the loop stops trying to catch up (it re-anchors).
MAX_LAG_S = 0.25

TracePoint = tuple[float, float, float, float]  # (time, x, y, yaw)


class Simulation:
    """Owns a MujocoWorld and the behaviour runners of its assets; steps them together."""

    def __init__(
        self,
        scene: Scene,
        dt: float = DEFAULT_TIMESTEP,
        control_every: int = DEFAULT_CONTROL_EVERY,
    ) -> None:
        if dt <= 0.0 or control_every < 1:
            raise ValueError("dt must be positive and control_every at least 1")
        self.lock = threading.Lock()
        self.world = MujocoWorld.from_scene(scene, timestep=dt)
        self.dt = dt
        self.control_every = control_every
        self.warnings: list[str] = []
        self.last_update: UpdateStats | None = None
        self._runners: dict[str, BehaviourRunner] = {}
        self._traces: dict[str, deque[TracePoint]] = {}
        self._steps = 0
        self._thread: threading.Thread | None = None
        self._stop = threading.Event()
        self._error: BaseException | None = None
        for asset in scene.all_assets():
            self._make_runner(asset, scene)
        self._bind_all()
        # Plays the storyboard: starts manoeuvres (replacing runners) and sets light states.
        self.player = StoryboardPlayer(scene, start_time=self.time)

    # Runners --------------------------------------------------------------------------------
    def _make_runner(self, asset: AssetInstance, scene: Scene) -> None:
        self._runners.pop(asset.id, None)
        self._traces.pop(asset.id, None)
        try:
            runner = runner_for(asset, scene)
        except UnknownLaneError as exc:
            self.warnings.append(f"{exc}; it stays parked")
            log.warning("%s; it stays parked", exc)
            return
        if runner is not None:
            self._runners[asset.id] = runner
            self._traces[asset.id] = deque(maxlen=TRACE_LENGTH)

    def _bind_all(self) -> None:
        for runner in self._runners.values():
            runner.bind(self.world)

    # Editing --------------------------------------------------------------------------------
    def apply(self, scene: Scene) -> UpdateStats:
        """Make the live world match `scene` between two steps; unchanged assets keep moving."""
        with self.lock:
            old = self.world.scene
            stats = self.world.update(scene)
            ego_changed = old.ego.behaviour != scene.ego.behaviour
            # Edits share unchanged assets between scenes: only the others are looked at.
            gone, came = scene_diff(old, scene)
            for asset in came.values():
                if gone.get(asset.id) != asset:
                    self._make_runner(asset, scene)
            if ego_changed:  # jaywalkers watch the ego's lane, so they are redone with it
                for asset in scene.assets:
                    if asset.behaviour.kind == "jaywalk" and asset.id not in came:
                        self._make_runner(asset, scene)
            for asset_id in set(gone) - set(came):
                self._runners.pop(asset_id, None)
                self._traces.pop(asset_id, None)
            self._bind_all()
            if old.storyboard != scene.storyboard:
                self.player = StoryboardPlayer(scene, start_time=float(self.world.data.time))
            self.player.scene = scene
            self.last_update = stats
            return stats

    # Stepping -------------------------------------------------------------------------------
    def _control(self) -> None:
        world = self.world
        now = float(world.data.time)
        period = self.dt * self.control_every
        world.refresh_contacts()  # resting props far from movers leave the broad phase
        self.player.control(world, now, self._runners)
        for runner in self._runners.values():
            runner.control(world, now, period)
        for asset_id in self._runners:
            x, y, _, yaw = world.planar_pose(asset_id)
            self._traces.setdefault(asset_id, deque(maxlen=TRACE_LENGTH)).append((now, x, y, yaw))

    def _step_unlocked(self, n: int) -> None:
        model, data = self.world.model, self.world.data
        for _ in range(n):
            if self._steps % self.control_every == 0:
                self._control()
                model, data = self.world.model, self.world.data
            mujoco.mj_step(model, data)
            self._steps += 1

    def step(self, n: int = 1) -> None:
        """Advance the physics n steps of dt now, running behaviours on control ticks."""
        with self.lock:
            self._step_unlocked(n)

    def run_for(self, seconds: float) -> None:
        """Advance the simulation by `seconds` of simulated time (synchronously)."""
        self.step(max(0, round(seconds / self.dt)))

    # Background loop --------------------------------------------------------------------------
    def start(self, realtime: bool = True) -> None:
        """Step in a background thread, paced to the wall clock when `realtime`."""
        if self._thread is not None and self._thread.is_alive():
            return
        self._stop.clear()
        self._error = None
        self._thread = threading.Thread(target=self._loop, args=(realtime,), name="drivetwin-physics", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        """Stop the background loop and wait for it; re-raises an error it died of."""
        thread = self._thread
        if thread is not None:
            self._stop.set()
            thread.join()
            self._thread = None
        if self._error is not None:
            error, self._error = self._error, None
            raise RuntimeError("the physics loop stopped with an error") from error

    @property
    def running(self) -> bool:
        return self._thread is not None and self._thread.is_alive()

    def _loop(self, realtime: bool) -> None:
        anchor_wall = wallclock.perf_counter()
        anchor_sim = self.time
        try:
            while not self._stop.is_set():
                with self.lock:
                    self._step_unlocked(STEPS_PER_LOCK)
                    sim_time = float(self.world.data.time)
                if not realtime:
                    # Let an editing or rendering thread take the lock between chunks.
                    wallclock.sleep(0)
                    continue
                ahead = (sim_time - anchor_sim) - (wallclock.perf_counter() - anchor_wall)
                if ahead > 0.0:
                    self._stop.wait(ahead)
                elif ahead < -MAX_LAG_S:
                    anchor_wall, anchor_sim = wallclock.perf_counter(), sim_time
        except BaseException as exc:  # kept for stop() to re-raise in the caller's thread
            log.exception("physics loop failed")
            self._error = exc

    # Reading --------------------------------------------------------------------------------
    @property
    def time(self) -> float:
        """Simulated seconds since the world was built."""
        return float(self.world.data.time)

    @property
    def scene(self) -> Scene:
        return self.world.scene

    def poses(self) -> dict[str, Pose]:
        """The current simulated pose of every asset, ego included."""
        with self.lock:
            return {a.id: self.world.body_pose(a.id) for a in self.world.scene.all_assets()}

    def pose(self, asset_id: str = EGO_ID) -> Pose:
        with self.lock:
            return self.world.body_pose(asset_id)

    def trace(self, asset_id: str) -> list[TracePoint]:
        """The recorded (time, x, y, yaw) of a moving asset at each control tick; [] if none."""
        with self.lock:
            return list(self._traces.get(asset_id, ()))
