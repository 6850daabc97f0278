"""Comparing and describing candidate plans: when two planners mean the same, and how to
say a plan in plain words when the person has to choose between readings.

Two candidates agree when their calls are the same once each tool's defaults are filled in,
or when a dry run gives the same outcome: the same kinds of asset added at nearly the same
places, the same assets removed or changed, the same environment after.
"""

from __future__ import annotations

import json
import math
from typing import Any

from drivetwin.orchestrator.transaction import TransactionError, TransactionResult, execute
from drivetwin.tools.base import ToolCall
from drivetwin.tools.errors import ToolError
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.edits import AddAsset, RemoveAsset, SetEnvironment, UpdateAsset, WorldEdit
from drivetwin.worlds.scene import Scene

# Added or moved assets this close count as "the same place": free-spot search puts two
# readings of "by the library" a few metres apart.
SAME_PLACE_M = 8.0


def canonical(calls: list[ToolCall], registry: ToolRegistry) -> list[str]:
    """Each call as JSON with the tool's defaults dropped and its label ignored, sorted."""
    out = []
    for call in calls:
        try:
            args = registry.get(call.tool).parse(call.args).model_dump(mode="json", exclude_defaults=True)
        except ToolError:
            args = dict(call.args)
        args.pop("label", None)
        out.append(json.dumps({"tool": call.tool, "args": args}, sort_keys=True))
    return sorted(out)


def dry_run(calls: list[ToolCall], registry: ToolRegistry, scene: Scene) -> TransactionResult | str:
    """The outcome of `calls` on a copy of `scene`, or the refusal's message."""
    try:
        return execute(registry, scene, calls)
    except TransactionError as exc:
        return str(exc)


def _ops(edit: WorldEdit) -> list[tuple[str, str, Any]]:
    ops: list[tuple[str, str, Any]] = []
    for op in edit.ops:
        if isinstance(op, AddAsset):
            ops.append(("add", op.asset.category, (op.asset.pose.x, op.asset.pose.y)))
        elif isinstance(op, RemoveAsset):
            ops.append(("remove", op.before.id, None))
        elif isinstance(op, UpdateAsset):
            after = op.after
            ops.append(
                (
                    "update",
                    after.id,
                    (after.pose.x, after.pose.y, after.behaviour.kind, after.appearance.model_dump_json()),
                )
            )
        elif isinstance(op, SetEnvironment):
            ops.append(("environment", "", op.after.model_dump_json()))
        else:
            ops.append((op.op, "", op.model_dump_json()))
    return sorted(ops, key=lambda o: (o[0], o[1]))


def _close(a: Any, b: Any) -> bool:
    if isinstance(a, tuple) and isinstance(b, tuple) and len(a) == len(b) and len(a) >= 2:
        near = math.dist(a[:2], b[:2]) <= SAME_PLACE_M
        return near and a[2:] == b[2:]
    return bool(a == b)


def same_outcome(a: TransactionResult, b: TransactionResult) -> bool:
    """Whether two dry runs did the same thing (see the module's note); questions (no edit)
    agree when they asked the same tools."""
    if a.edit.empty and b.edit.empty:
        return sorted(r.text for r in a.results) == sorted(r.text for r in b.results)
    left, right = _ops(a.edit), _ops(b.edit)
    return len(left) == len(right) and all(
        x[0] == y[0] and x[1] == y[1] and _close(x[2], y[2]) for x, y in zip(left, right, strict=True)
    )


def describe(calls: list[ToolCall]) -> str:
    """A plan in a few plain words, for a numbered choice ("add 3 traffic cones in front of
    Library entrance; make it rain")."""
    return "; ".join(_describe(c) for c in calls) or "change nothing"


def _where(location: Any) -> str:
    if not isinstance(location, dict):
        return ""
    relation = str(location.get("relation", "at")).replace("_", " ")
    if relation == "absolute":
        return f"at x={location.get('x')}, y={location.get('y')}"
    distance = f"{location['distance']:g} m " if isinstance(location.get("distance"), (int, float)) else ""
    target = location.get("target")
    return f"{distance}{relation} {target}" if target else relation


def _things(name: Any, n: int) -> str:
    return f"{n} {str(name).replace('_', ' ')}{'s' if n != 1 else ''}"


def _describe(call: ToolCall) -> str:
    a = call.args
    if call.tool == "add_asset":
        how = f", {a['behaviour'].get('kind', '')}".replace("_", " ") if isinstance(a.get("behaviour"), dict) else ""
        colour = f"{a['colour']} " if a.get("colour") else ""
        n = int(a.get("count", 1))
        return f"add {n} {colour}{_things(a.get('category'), n)[len(str(n)) + 1:]} {_where(a.get('location'))}{how}".strip()
    if call.tool == "arrange_assets":
        cats = ", ".join(str(c).replace("_", " ") for c in a.get("categories", []))
        return f"a {a.get('shape')} of {a.get('count') or 'some'} {cats} {_where(a.get('location'))}".strip()
    if call.tool == "remove_assets":
        which = ", ".join(a.get("assets", [])) or (
            f"{a.get('count') or 'all'} {str(a.get('category', '')).replace('_', ' ')}"
            + (f" nearest {a['near']}" if a.get("near") else "")
        )
        return f"remove {which}"
    if call.tool == "place_asset":
        return f"put {a.get('asset')} {_where(a.get('location'))}"
    if call.tool == "move_asset":
        # each way said as a person says it: "back 3 m", not "forward -3"
        ways = {"forward": ("forward", "back"), "left": ("left", "right"), "east": ("east", "west"), "north": ("north", "south")}
        parts = [f"{ways[k][v < 0]} {abs(v):g} m" if k in ways else f"turn {v:g} degrees" for k, v in a.items()
                 if k in (*ways, "turn_deg") and v]
        return f"move {a.get('asset') or ', '.join(a.get('assets', []))} " + ", ".join(parts)
    if call.tool == "set_behaviour":
        kind = a.get("behaviour", {}).get("kind", "") if isinstance(a.get("behaviour"), dict) else ""
        return f"make {a.get('asset')} {str(kind).replace('_', ' ')}"
    if call.tool == "set_weather":
        return f"weather {a.get('kind')}" + (
            f" (intensity {a['intensity']:g})" if a.get("intensity") is not None else ""
        )
    if call.tool == "set_time_of_day":
        return f"time of day {a.get('time')}"
    if call.tool == "set_asset_appearance":
        which = ", ".join(a.get("assets", [])) or f"every {str(a.get('category', '')).replace('_', ' ')}"
        return f"paint {which} {a.get('colour') or a.get('material')}"
    if call.tool == "measure_distance":
        return f"measure the distance from {a.get('a')} to {a.get('b', 'ego')}"
    if call.tool.startswith("find_") or call.tool == "asset_properties":
        said = ", ".join(f"{v}" for v in a.values() if v is not None)
        return f"look up {call.tool.removeprefix('find_').replace('_', ' ')}" + (f" ({said})" if said else "")
    return str(call)


__all__ = ["SAME_PLACE_M", "canonical", "describe", "dry_run", "same_outcome"]
