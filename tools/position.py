"""Position Worker: put an existing asset somewhere else, absolutely or relative to a target."""

from __future__ import annotations

import math

from drivetwin.tools.base import Tool, ToolArgs, ToolResult
from drivetwin.tools.locate import Location, find_free_pose, resolve_anchor
from drivetwin.tools.move import find_asset, follow_placement
from drivetwin.worlds.catalog import category
from drivetwin.worlds.edits import UpdateAsset, WorldEdit
from drivetwin.worlds.scene import Scene
from pydantic import Field


class PlaceArgs(ToolArgs):
    asset: str = Field(description="id of the asset to put somewhere else")
    location: Location = Field(
        description="where: absolute x/y (honoured exactly or refused with the reason), relative to a "
        "target, or along_m/side: N m ahead of or behind a target along its lane or sidewalk"
    )
    yaw_deg: float | None = Field(None, ge=-360.0, le=360.0, description="heading, degrees")


class PlaceAsset(Tool[PlaceArgs]):
    name = "place_asset"
    description = (
        "Put an existing asset at a new position: absolute x/y, or relative to a landmark or "
        "asset (in front of, behind, left of, right of, next to), the scene centre, a "
        "sidewalk or a lane, or N m ahead of/behind a target along its lane (along_m, side). A "
        "driving vehicle then drives the lane it stands in, or is parked off every lane."
    )
    family = "position"
    Args = PlaceArgs

    def propose(self, args: PlaceArgs, scene: Scene) -> ToolResult:
        asset = find_asset(scene, args.asset)
        cat = category(asset.category)
        anchor = resolve_anchor(scene, args.location, cat.length * asset.scale / 2, asset.category)
        others = [a for a in scene.all_assets() if a.id != asset.id]
        yaw = math.radians(args.yaw_deg) if args.yaw_deg is not None else None
        pose = find_free_pose(scene, asset, anchor, others, yaw)
        # A driving vehicle drives the lane it is put in, or is parked off every lane.
        after, note = follow_placement(scene, asset.model_copy(update={"pose": pose}))
        edit = WorldEdit(ops=(UpdateAsset(before=asset, after=after),))
        where = f"{anchor.spot.label}, " if anchor.spot else ""
        return ToolResult(edit, f"placed {asset.id} {where}at ({pose.x:.1f}, {pose.y:.1f}){note}",
                          (pose.x, pose.y))
