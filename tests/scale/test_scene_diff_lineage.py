"""MuJoCo's scene diff takes an edit's own record of what left and came when the newer scene was
made from the older by an edit; it must give exactly what comparing every asset gives."""

from __future__ import annotations

from drivetwin.orchestrator.transaction import execute
from drivetwin.tools import ToolRegistry
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.edits import lineage
from drivetwin.worlds.mujoco_adapter import scene_diff
from drivetwin.worlds.scene import Scene


def compared(old: Scene, new: Scene) -> tuple[dict[str, object], dict[str, object]]:
    # The definition: assets (by identity) that only one of the two scenes holds.
    before, after = {id(a): a for a in old.all_assets()}, {id(a): a for a in new.all_assets()}
    return ({a.id: a for k, a in before.items() if k not in after}, {a.id: a for k, a in after.items() if k not in before})


def test_the_lineage_shortcut_gives_the_same_diff_as_comparing_every_asset():
    registry = ToolRegistry.default(plugins=False)
    scene = build_campus()
    steps = [
        [ToolCall(tool="add_asset", args={"category": "traffic_cone", "count": 3,
                                          "location": {"relation": "in_front_of", "target": "ego", "distance": 12}})],
        [ToolCall(tool="move_asset", args={"asset": "bench_1", "east": 1.0})],
        [ToolCall(tool="remove_assets", args={"category": "trash_bin"})],
        [ToolCall(tool="move_asset", args={"asset": "ego", "forward": 2.0}),
         ToolCall(tool="remove_assets", args={"assets": ["traffic_cone_1"]})],
    ]
    for calls in steps:
        result = execute(registry, scene, calls)
        new = result.after
        if len(calls) == 1:
            assert lineage(new).parent is lineage(scene)  # one edit: the shortcut's case
        assert scene_diff(scene, new) == compared(scene, new)
        assert scene_diff(new, scene) == compared(new, scene)  # backwards: the full comparison
        scene = new
