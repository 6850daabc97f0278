"""Search Workers: look up assets, landmarks, lanes and asset properties; they never edit."""

from __future__ import annotations

import difflib
import math

from drivetwin.tools.base import Tool, ToolArgs, ToolResult
from drivetwin.tools.errors import NotFoundError
from drivetwin.tools.locate import resolve_target
from drivetwin.tools.move import find_asset
from drivetwin.worlds.catalog import UnknownCategoryError, catalog, nearest_categories, resolve_category
from drivetwin.worlds.edits import WorldEdit
from drivetwin.worlds.scene import Scene
from pydantic import Field

MAX_LISTED = 20


class FindAssetsArgs(ToolArgs):
    category: str | None = Field(None, description="category or a word for it, e.g. 'cones'")
    near: str | None = Field(None, description="landmark or asset to measure distance from")
    within: float | None = Field(None, gt=0.0, le=1000.0, description="metres from `near`")


class FindAssets(Tool[FindAssetsArgs]):
    name = "find_assets"
    description = "List assets in the scene, optionally of a category and within a distance of a place."
    family = "search"
    Args = FindAssetsArgs

    def propose(self, args: FindAssetsArgs, scene: Scene) -> ToolResult:
        pool = scene.all_assets()
        if args.category:
            name = resolve_category(args.category)
            if name is None:
                raise UnknownCategoryError(args.category, nearest_categories(args.category))
            pool = [a for a in pool if a.category == name]
        if args.near:
            t = resolve_target(scene, args.near)
            pool.sort(key=lambda a: math.hypot(a.pose.x - t.x, a.pose.y - t.y))
            if args.within is not None:
                pool = [a for a in pool if math.hypot(a.pose.x - t.x, a.pose.y - t.y) <= args.within]
        what = args.category or "asset"
        lines = [f"{a.id} ({a.category}) at ({a.pose.x:.1f}, {a.pose.y:.1f})" for a in pool[:MAX_LISTED]]
        more = f" (+{len(pool) - MAX_LISTED} more)" if len(pool) > MAX_LISTED else ""
        text = f"{len(pool)} {what}(s) found" + (": " + "; ".join(lines) + more if pool else "")
        return ToolResult(WorldEdit(), text, data={"ids": [a.id for a in pool]})


class FindLandmarksArgs(ToolArgs):
    query: str | None = Field(None, description="words of a landmark name; empty lists all")


class FindLandmarks(Tool[FindLandmarksArgs]):
    name = "find_landmarks"
    description = "List the named places of the world (entrances, gates, parking lots) or find one."
    family = "search"
    Args = FindLandmarksArgs

    def propose(self, args: FindLandmarksArgs, scene: Scene) -> ToolResult:
        marks = scene.landmarks
        if args.query:
            exact = scene.landmark(args.query)
            if exact is not None:
                marks = [exact]
            else:
                q = args.query.lower()
                marks = [lm for lm in marks if any(q in n.lower() or n.lower() in q for n in lm.names())]
                if not marks:
                    names = [n for lm in scene.landmarks for n in lm.names()]
                    near = difflib.get_close_matches(args.query, names, n=3, cutoff=0.3)
                    raise NotFoundError(f"no landmark like {args.query!r}; nearest: {', '.join(near)}")
        lines = [f"{lm.name} at ({lm.position[0]:.1f}, {lm.position[1]:.1f})" for lm in marks]
        return ToolResult(WorldEdit(), f"{len(marks)} landmark(s): " + "; ".join(lines),
                          data={"names": [lm.name for lm in marks]})


class FindLanesArgs(ToolArgs):
    road: str | None = Field(None, description="road name to filter by")
    near: str | None = Field(None, description="landmark or asset to find the nearest lane to")


class FindLanes(Tool[FindLanesArgs]):
    name = "find_lanes"
    description = "List lanes (id, road, direction, width), or the lane nearest a place."
    family = "search"
    Args = FindLanesArgs

    def propose(self, args: FindLanesArgs, scene: Scene) -> ToolResult:
        from drivetwin.worlds.surface import nearest_on_polyline

        lanes = [ln for ln in scene.roads.lanes if not args.road or args.road.lower() in ln.road.lower()]
        if args.near:
            t = resolve_target(scene, args.near)
            lanes.sort(key=lambda ln: nearest_on_polyline(t.x, t.y, ln.centreline).distance)
            lanes = lanes[:1]
        lines = []
        for ln in lanes:
            (x1, y1), (x2, y2) = ln.centreline[0], ln.centreline[-1]
            heading = math.degrees(math.atan2(y2 - y1, x2 - x1))
            lines.append(f"{ln.id} on {ln.road}, heading {heading:.0f} deg, {ln.width:g} m wide")
        return ToolResult(WorldEdit(), f"{len(lanes)} lane(s): " + "; ".join(lines),
                          data={"lanes": [ln.id for ln in lanes]})


class PropertiesArgs(ToolArgs):
    asset: str | None = Field(None, description="asset id to describe")
    category: str | None = Field(None, description="or: a catalog category to describe")


class AssetProperties(Tool[PropertiesArgs]):
    name = "asset_properties"
    description = "Describe an asset (pose, behaviour, mass, colour) or a catalog category (size, mass, words)."
    family = "search"
    Args = PropertiesArgs

    def propose(self, args: PropertiesArgs, scene: Scene) -> ToolResult:
        if args.asset:
            a = find_asset(scene, args.asset)
            text = (f"{a.id}: {a.category} at ({a.pose.x:.1f}, {a.pose.y:.1f}), yaw "
                    f"{math.degrees(a.pose.yaw):.0f} deg, mass {a.physics.mass:g} kg, "
                    f"behaviour {a.behaviour.kind}, colour {a.appearance.rgba or 'default'}")
            return ToolResult(WorldEdit(), text, data={"asset": a.model_dump()})
        if args.category:
            name = resolve_category(args.category)
            if name is None:
                raise UnknownCategoryError(args.category, nearest_categories(args.category))
            c = catalog()[name]
            text = (f"{c.name}: {c.description}; {c.length:g}x{c.width:g}x{c.height:g} m, "
                    f"{c.mass:g} kg; also called {', '.join(c.synonyms[:6])}")
            return ToolResult(WorldEdit(), text, data={"category": c.name})
        raise NotFoundError("name an asset id or a category to describe")
