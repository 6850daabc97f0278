"""Dormant contacts: resting props far from anything that moves leave MuJoCo's broad phase.

MuJoCo's broad phase sweeps every body that can collide, asleep or welded or not, along one
axis; over thousands of props spread on the ground that grows as N^1.5 (2.8 ms of a 4.1 ms
step at 3,000 props, measured on 2 loaded cores). A prop that is asleep or welded and farther
than WAKE_RADIUS_M from every moving body cannot be touched before the next control tick, so
its contacts are switched off until something that moves comes near. Rays (LIDAR, behaviours)
and the renderer select geoms by group, not by contact flags, so they still see it.
"""

from __future__ import annotations

import mujoco
import numpy as np
import numpy.typing as npt
from drivetwin.worlds.mujoco_pool import BodyPool

__all__ = ["REFRESH_EVERY_TICKS", "WAKE_RADIUS_M", "ContactDormancy"]

# A prop within this distance (along x and y) of a moving body keeps its contacts: a car at
# 30 m/s covers 3 m between two refreshes, a bus is 12 m long, so 25 m leaves a wide margin.
WAKE_RADIUS_M = 25.0
# Control ticks between two refreshes (100 ms at the default 50 Hz control rate).
REFRESH_EVERY_TICKS = 5

IntArray = npt.NDArray[np.int64]


class ContactDormancy:
    """Which props' contacts are switched off; rebuilt from the pool after every edit."""

    def __init__(self) -> None:
        self._built_for: tuple[int, int] | None = None
        self._ticks = 0
        self.props: IntArray = np.zeros(0, np.int64)  # root body of each candidate prop
        self.movers: IntArray = np.zeros(0, np.int64)  # bodies that move (vehicles, walkers, free props)
        self._geoms: IntArray = np.zeros(0, np.int64)
        self._owner: IntArray = np.zeros(0, np.int64)  # prop index of each geom
        self._contype: IntArray = np.zeros(0, np.int64)
        self._conaffinity: IntArray = np.zeros(0, np.int64)
        self.dormant = np.zeros(0, bool)

    def _build(self, pool: BodyPool, model: mujoco.MjModel) -> None:
        props: list[int] = []
        movers: list[int] = []
        geoms: list[int] = []
        owner: list[int] = []
        contype: list[int] = []
        conaffinity: list[int] = []
        for slot in pool.slots.values():
            if slot.asset_id is None:
                continue
            if slot.kind in ("vehicle", "mocap") or len(slot.body_ids) != 1:
                movers.append(slot.body_id)
                continue
            if slot.kind == "free":
                movers.append(slot.body_id)  # it moves while awake (a knocked cone)
            for geom in slot.geoms:
                geoms.append(geom.id)
                owner.append(len(props))
                contype.append(geom.contype)
                conaffinity.append(geom.conaffinity)
            props.append(slot.body_id)
        self.props = np.array(props, np.int64)
        self.movers = np.array(movers, np.int64)
        self._geoms = np.array(geoms, np.int64)
        self._owner = np.array(owner, np.int64)
        self._contype = np.array(contype, np.int64)
        self._conaffinity = np.array(conaffinity, np.int64)
        self.dormant = np.zeros(len(props), bool)

    def reset(self, pool: BodyPool, model: mujoco.MjModel) -> None:
        """Every prop collides again (after an edit: a moved prop must not fall through the
        ground before the next tick); the next `refresh` decides anew."""
        self._built_for = (id(model), pool.version)
        self._build(pool, model)
        self._apply(model)

    def refresh(self, pool: BodyPool, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """Switch off the contacts of props that rest far from every moving body; on the
        others'."""
        stale = self._built_for != (id(model), pool.version)
        if stale:
            self.reset(pool, model)
        self._ticks += 1
        if not len(self.props) or (not stale and self._ticks % REFRESH_EVERY_TICKS):
            return
        trees = model.body_treeid[self.props]
        dynamic = trees >= 0
        resting = ~dynamic  # welded
        resting[dynamic] = data.tree_asleep[trees[dynamic]] >= 0
        movers = self.movers
        mover_trees = model.body_treeid[movers]
        awake = (mover_trees < 0) | (data.tree_asleep[np.maximum(mover_trees, 0)] < 0)
        spots = data.xpos[self.props, :2]
        far = np.ones(len(self.props), bool)
        # A square of side 2 R around each mover (few movers, many props: one pass each).
        for x, y in data.xpos[movers[awake], :2].tolist():
            far &= (np.abs(spots[:, 0] - x) > WAKE_RADIUS_M) | (np.abs(spots[:, 1] - y) > WAKE_RADIUS_M)
        dormant = resting & far
        if np.array_equal(dormant, self.dormant):
            return
        self.dormant = dormant
        self._apply(model)

    def _apply(self, model: mujoco.MjModel) -> None:
        off = self.dormant[self._owner]
        model.geom_contype[self._geoms] = np.where(off, 0, self._contype)
        model.geom_conaffinity[self._geoms] = np.where(off, 0, self._conaffinity)
        # The broad phase filters bodies by the union of their geoms' flags.
        body_contype = np.zeros(len(self.props), np.int64)
        body_conaffinity = np.zeros(len(self.props), np.int64)
        np.bitwise_or.at(body_contype, self._owner, np.where(off, 0, self._contype))
        np.bitwise_or.at(body_conaffinity, self._owner, np.where(off, 0, self._conaffinity))
        model.body_contype[self.props] = body_contype
        model.body_conaffinity[self.props] = body_conaffinity

    def wake(self, body: int) -> None:
        """Count a prop as colliding again (an edit restored its contacts)."""
        hit = np.flatnonzero(self.props == body)
        if len(hit):
            self.dormant[hit[0]] = False

    def is_dormant(self, body: int) -> bool:
        """Whether a prop's contacts are off now."""
        hit = np.flatnonzero(self.props == body)
        return bool(len(hit) and self.dormant[hit[0]])
