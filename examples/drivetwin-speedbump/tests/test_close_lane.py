"""The example plugin works as an installed plugin would: through the registry."""

from drivetwin.orchestrator.transaction import execute
from drivetwin.tools import RuleViolation, ToolCall, ToolRegistry, lane_at
from drivetwin.worlds.campus import build_campus
from drivetwin_speedbump import CloseLane


def test_close_lane_tapers_cones_across_the_lane():
    registry = ToolRegistry.default(plugins=False)
    registry.register(CloseLane(), source="plugin test")
    scene = build_campus()
    after = execute(registry, scene, [ToolCall(tool="close_lane", args={"lane": "main_westbound", "at_x": 40, "at_y": 2})]).after
    cones = [a for a in after.assets if a.label == "lane closure"]
    assert len(cones) == 5
    assert all(lane_at(after, c.pose.x, c.pose.y).id == "main_westbound" for c in cones)
    ys = [c.pose.y for c in cones]
    assert max(ys) - min(ys) > 2.0  # it crosses the lane, not along it


def test_close_lane_is_refused_where_the_rules_say_no():
    registry = ToolRegistry.default(plugins=False)
    registry.register(CloseLane())
    scene = build_campus()
    ego = scene.ego.pose
    try:
        execute(registry, scene, [ToolCall(tool="close_lane", args={"lane": "main_eastbound", "at_x": ego.x - 1, "at_y": ego.y})])
    except Exception as exc:  # the transaction wraps the Worker's refusal
        assert isinstance(exc.error, RuleViolation) and "overlap ego" in str(exc)
    else:
        raise AssertionError("a closure through the ego vehicle must be refused")
