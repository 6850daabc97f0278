"""A turn said with the junction it is taken at is a junction turn over time, however the way is
put ("to the right", "take the left"), and a polite "could ...?" asks for it rather than about it.
Driven through the default planner (rules, retrieval, scenario reader) for real."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.hybrid import make_hybrid
from drivetwin.orchestrator.planning.scenario_reading import describes_behaviour_over_time
from drivetwin.orchestrator.session import Session


@pytest.mark.parametrize(("prompt", "turn"), [
    ("this time round the ego should take the right at the crossroads", "right"),
    ("make the ego go left at the junction, not straight on", "left"),
    ("sorry to ask, could the ego turn right at the intersection?", "right"),
])
def test_a_turn_at_the_junction_is_a_manoeuvre(campus, registry, prompt, turn):
    session = Session(campus, make_hybrid(), registry)
    report = session.submit(prompt)
    assert report.ok, report.error or report.question
    calls = report.plan.calls
    assert [c.tool for c in calls] == ["add_manoeuvre"]
    assert calls[0].args["manoeuvre"] == {"kind": "junction_turn", "turn": turn}
    assert session.scene.asset("ego").pose == campus.asset("ego").pose  # nothing teleported or turned on the spot


def test_a_turn_that_is_no_junction_turn_is_not_read_as_one(campus):
    assert not describes_behaviour_over_time("turn the bench to the right", campus)
    assert not describes_behaviour_over_time("put a cone on the right at the junction", campus)
    assert not describes_behaviour_over_time("which lane goes left at the junction?", campus)


def test_a_turn_the_scenario_reader_cannot_place_is_not_done_on_the_spot(campus, registry):
    # the junction is in the trigger ("once it gets to"), the way in the action: no static stand-in
    session = Session(campus, make_hybrid(), registry)
    report = session.submit("have the ego swing to the left once it gets to the junction")
    assert not report.ok
    assert session.scene == campus
