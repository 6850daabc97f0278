"""Viewpoints of the hybrid renderer: the campus overview and a chase camera behind an asset."""

from __future__ import annotations

import math

from drivetwin.worlds.mujoco_adapter import MujocoWorld
from drivetwin.worlds.scene import EGO_ID, Scene

from .camera import Camera

__all__ = ["chase_camera", "default_camera"]

# Default overview: look at the main landmark from this far back and this high up.
OVERVIEW_DISTANCE_M, OVERVIEW_HEIGHT_M, OVERVIEW_FOVY_DEG = 45.0, 22.0, 60.0
OVERVIEW_LANDMARK = "main intersection"
CHASE_BACK_M, CHASE_UP_M, CHASE_AHEAD_M = 8.0, 3.5, 10.0


def default_camera(scene: Scene, width: int = 640, height: int = 360) -> Camera:
    """An elevated overview of the campus centre (its main landmark, else the bounds' centre)."""
    landmark = scene.landmark(OVERVIEW_LANDMARK)
    cx, cy = landmark.position if landmark is not None else scene.bounds.centre
    # Look from the south-east so the sun (south by day) lights the faces we see.
    back = OVERVIEW_DISTANCE_M / math.sqrt(2)
    eye = (cx + back, cy - back, OVERVIEW_HEIGHT_M)
    return Camera.from_look_at(eye, (cx, cy, 0.0), width=width, height=height,
                               fovy_deg=OVERVIEW_FOVY_DEG)  # fmt: skip


def chase_camera(world: MujocoWorld, asset_id: str = EGO_ID, *, width: int = 640, height: int = 360) -> Camera:
    """A camera behind and above an asset's live pose, looking past it along its heading."""
    pose = world.body_pose(asset_id)
    heading = (math.cos(pose.yaw), math.sin(pose.yaw))
    eye = (pose.x - CHASE_BACK_M * heading[0], pose.y - CHASE_BACK_M * heading[1],
           pose.z + CHASE_UP_M)  # fmt: skip
    target = (
        pose.x + CHASE_AHEAD_M * heading[0],
        pose.y + CHASE_AHEAD_M * heading[1],
        pose.z + 0.5,
    )
    return Camera.from_look_at(eye, target, width=width, height=height, fovy_deg=OVERVIEW_FOVY_DEG)
