"""Add Worker: put new assets of a catalog category into the world."""

from __future__ import annotations

import math

from drivetwin.tools.appearance import resolve_colour
from drivetwin.tools.base import CategoryName, Tool, ToolArgs, ToolResult
from drivetwin.tools.errors import RuleViolation
from drivetwin.tools.locate import Location, find_free_pose, resolve_anchor
from drivetwin.tools.move import BehaviourSpec, resolve_behaviour
from drivetwin.tools.rules import check_placement
from drivetwin.worlds.catalog import category, placeable_categories
from drivetwin.worlds.edits import AddAsset, WorldEdit
from drivetwin.worlds.scene import Appearance, AssetInstance, PhysicsProps, Pose, Scene
from pydantic import Field

# One call adds at most this many; bigger layouts are several calls or an arrangement.
MAX_PER_CALL = 50


def new_asset(scene: Scene, category_name: str, taken: set[str], label: str = "",
              colour: str | None = None, dynamic: bool | None = None) -> AssetInstance:
    """A fresh asset of a category at the origin, with an id not in the scene nor in `taken`."""
    cat = category(category_name)
    n = 1
    while f"{cat.name}_{n}" in taken or scene.asset(f"{cat.name}_{n}") is not None:
        n += 1
    is_dynamic = dynamic if dynamic is not None else cat.motion in ("vehicle", "walker", "prop")
    appearance = Appearance(rgba=resolve_colour(colour)) if colour else Appearance()
    return AssetInstance(
        id=f"{cat.name}_{n}", category=cat.name, pose=Pose(x=0.0, y=0.0),
        physics=PhysicsProps(mass=cat.mass, dynamic=is_dynamic), appearance=appearance, label=label,
    )


class AddArgs(ToolArgs):
    category: CategoryName = Field(description="asset category from the catalog, e.g. traffic_cone")
    count: int = Field(1, ge=1, le=MAX_PER_CALL, description="how many to add")
    location: Location = Field(
        default_factory=lambda: Location(relation="scene_centre"),
        description="where to put it (default: the scene centre)",
    )
    behaviour: BehaviourSpec | None = Field(None, description="what it does (default: parked)")
    yaw_deg: float | None = Field(None, ge=-360.0, le=360.0, description="heading, degrees")
    colour: str | None = Field(None, description="a colour name such as red, or #rrggbb")
    label: str = Field("", max_length=80, description="the user's words for it")


class AddAssetTool(Tool[AddArgs]):
    name = "add_asset"
    description = (
        "Add new assets of one category at a location (relative to a landmark, asset, lane, "
        "sidewalk, the scene centre, or absolute x/y), optionally with a behaviour."
    )
    family = "add"
    Args = AddArgs

    def propose(self, args: AddArgs, scene: Scene) -> ToolResult:
        cat = category(args.category)
        if cat.name not in placeable_categories():
            raise RuleViolation("protected", f"{cat.name} cannot be added; the world has exactly one")
        placed: list[AssetInstance] = []
        others = scene.all_assets()
        anchor = resolve_anchor(scene, args.location, cat.length / 2)
        # A behaviour that decides where the asset starts (a skidpad circle, a crossing) uses
        # the location only when the caller gave one.
        hint = (anchor.x, anchor.y) if "location" in args.model_fields_set else None
        yaw = math.radians(args.yaw_deg) if args.yaw_deg is not None else None
        for _ in range(args.count):
            template = new_asset(scene, cat.name, {a.id for a in placed}, args.label, args.colour)
            start: Pose | None = None
            if args.behaviour is not None:
                behaviour, start = resolve_behaviour(scene, template, args.behaviour, hint)
                template = template.model_copy(update={"behaviour": behaviour})
            if start is not None:
                pose = start
                check_placement(scene, template.model_copy(update={"pose": pose}), [*others, *placed])
            else:
                pose = find_free_pose(scene, template, anchor, [*others, *placed], yaw)
            asset = template.model_copy(update={"pose": pose})
            if args.behaviour is not None and args.behaviour.kind == "drive_lane":
                behaviour, snapped = resolve_behaviour(scene, asset, args.behaviour)
                asset = asset.model_copy(update={"behaviour": behaviour, "pose": snapped or pose})
            placed.append(asset)
        edit = WorldEdit(ops=tuple(AddAsset(asset=a) for a in placed))
        cx = sum(a.pose.x for a in placed) / len(placed)
        cy = sum(a.pose.y for a in placed) / len(placed)
        where = f" near {anchor.near.name}" if anchor.near else ""
        ids = ", ".join(a.id for a in placed)
        return ToolResult(edit, f"added {ids}{where} around ({cx:.1f}, {cy:.1f})", (cx, cy),
                          {"ids": [a.id for a in placed]})
