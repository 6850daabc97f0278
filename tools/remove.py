"""Remove Worker: take assets out of the world, by id or by category near a place."""

from __future__ import annotations

import math

from drivetwin.tools.base import CategoryName, Tool, ToolArgs, ToolResult
from drivetwin.tools.errors import NotFoundError, RuleViolation
from drivetwin.tools.locate import resolve_target
from drivetwin.tools.move import find_asset
from drivetwin.worlds.edits import RemoveAsset, WorldEdit
from drivetwin.worlds.scene import EGO_ID, AssetInstance, Scene
from pydantic import Field


class RemoveArgs(ToolArgs):
    assets: list[str] = Field(default_factory=list, description="ids of assets to remove")
    category: CategoryName | None = Field(None, description="or: remove assets of this category")
    near: str | None = Field(None, description="only those nearest this landmark or asset")
    count: int | None = Field(None, ge=1, le=500, description="how many (default: all matching)")


class RemoveAssets(Tool[RemoveArgs]):
    name = "remove_assets"
    description = (
        "Remove assets by id, or by category (optionally only the N nearest a landmark or "
        "asset). The ego vehicle cannot be removed."
    )
    family = "remove"
    Args = RemoveArgs

    def propose(self, args: RemoveArgs, scene: Scene) -> ToolResult:
        chosen: list[AssetInstance] = [find_asset(scene, a) for a in args.assets]
        if args.category is not None:
            name = args.category
            pool = [a for a in scene.assets if a.category == name and a not in chosen]
            if not pool:
                raise NotFoundError(f"there is no {name} in the scene to remove")
            if args.near is not None:
                t = resolve_target(scene, args.near)
                pool.sort(key=lambda a: math.hypot(a.pose.x - t.x, a.pose.y - t.y))
            chosen += pool[: args.count] if args.count else pool
        elif args.count is not None and not args.assets:
            raise NotFoundError("say which assets to remove: ids, or a category")
        if not chosen:
            raise NotFoundError("name the assets to remove (ids) or a category")
        if any(a.id == EGO_ID for a in chosen):
            raise RuleViolation("protected", "the ego vehicle cannot be removed; move it instead")
        unique = list({a.id: a for a in chosen}.values())
        edit = WorldEdit(ops=tuple(RemoveAsset(before=a) for a in unique))
        cx = sum(a.pose.x for a in unique) / len(unique)
        cy = sum(a.pose.y for a in unique) / len(unique)
        return ToolResult(edit, f"removed {', '.join(a.id for a in unique)}", (cx, cy),
                          {"ids": [a.id for a in unique]})
