"""An example drivetwin plugin: `close_lane` puts a taper of cones across a lane.

It shows the whole Worker contract: a pydantic argument model (its JSON Schema is what an
LLM sees), a `propose` step that returns a WorldEdit without touching the scene, and the
shared placement rules that `Tool.apply` runs before anything is applied.
"""

from __future__ import annotations

import math

from drivetwin.tools import (
    AddAsset,
    NotFoundError,
    Pose,
    Scene,
    Tool,
    ToolArgs,
    ToolResult,
    WorldEdit,
    nearest_on_polyline,
    new_asset,
    point_along,
)
from pydantic import Field

# A taper of cones spaced like a real lane closure on a low-speed road.
CONE_SPACING_M = 2.0


class CloseLaneArgs(ToolArgs):
    lane: str = Field(description="id of the lane to close, e.g. main_eastbound")
    at_x: float = Field(description="x (metres) where the closure starts")
    at_y: float = Field(description="y (metres) where the closure starts")
    cones: int = Field(5, ge=2, le=20)


class CloseLane(Tool[CloseLaneArgs]):
    name = "close_lane"
    description = "Close a lane with a diagonal taper of traffic cones starting at a point."
    family = "arrange"
    Args = CloseLaneArgs

    def propose(self, args: CloseLaneArgs, scene: Scene) -> ToolResult:
        lane = scene.roads.lane(args.lane)
        if lane is None:
            raise NotFoundError(f"no lane {args.lane!r}; lanes: {', '.join(ln.id for ln in scene.roads.lanes)}")
        start = nearest_on_polyline(args.at_x, args.at_y, lane.centreline).arc_length
        ops = []
        taken: set[str] = set()
        for k in range(args.cones):
            x, y, heading = point_along(lane.centreline, start + k * CONE_SPACING_M)
            # From the right edge of the lane to its left edge: a taper across it.
            offset = -lane.width / 2 + 0.3 + (lane.width - 0.6) * k / (args.cones - 1)
            cone = new_asset(scene, "traffic_cone", taken, label="lane closure")
            taken.add(cone.id)
            pose = Pose(x=x - offset * math.sin(heading), y=y + offset * math.cos(heading), yaw=heading)
            ops.append(AddAsset(asset=cone.model_copy(update={"pose": pose})))
        return ToolResult(WorldEdit(ops=tuple(ops)), f"closed {lane.id} with {args.cones} cones",
                          (args.at_x, args.at_y), {"ids": [op.asset.id for op in ops]})
