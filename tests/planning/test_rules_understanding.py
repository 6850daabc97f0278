"""The rule planner reads general structures, not more phrases: negated wishes, switching
lamps, a lookup radius, and contractions written without their apostrophe."""

from __future__ import annotations

from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.planning.rules.spelling import repair


def tools_of(context, prompt: str) -> list[tuple[str, dict[str, object]]]:
    return [(c.tool, c.args) for c in RulePlanner().plan(prompt, context).calls]


def test_a_negated_wish_removes_instead_of_adding(context):
    ((tool, _args),) = tools_of(context, "we really do not need that bench")
    assert tool == "remove_assets"


def test_switching_lamps_on_sets_the_lighting_instead_of_rotating_one(context):
    assert tools_of(context, "switch those lamp posts on") == [("set_lighting", {"street_lights": "on"})]


def test_a_lookup_radius_in_metres_is_passed_to_the_search(context):
    ((tool, args),) = tools_of(context, "what benches are within 12 m of the fountain?")
    assert tool == "find_assets" and args["within"] == 12.0


def test_a_contraction_without_its_apostrophe_is_not_repaired(campus):
    assert repair("i dont think so, it isnt", campus).repairs == []


def test_lamps_named_as_a_circumstance_are_not_switched(context):
    calls = tools_of(context, "we can drop the cones by the fountain, the street lamps cover that corner anyway")
    assert all(tool != "set_lighting" for tool, _ in calls)
