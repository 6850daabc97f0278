"""The plan-versus-request check: one test per failure class, worded unlike any suite prompt.

Each hands the session a planner whose plan misreads the request (as the issue's measured
planners did) and asserts the outcome is a question or a refusal, never a silent wrong edit.
"""

from __future__ import annotations

from drivetwin.orchestrator.planning import Plan
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.request import read_request
from drivetwin.orchestrator.session import Session
from drivetwin.tools.base import ToolCall
from misreading import Fixed, add  # this folder is on sys.path (no __init__.py)


def submit(campus, registry, planner, prompt):
    session = Session(campus, planner, registry)
    return session, session.submit(prompt)


def test_a_negated_wish_is_not_applied_as_an_addition(campus, registry):
    session, report = submit(campus, registry, Fixed(add("bus")), "honestly I'd rather not have any bus around")
    assert not report.ok and session.scene.count("bus") == campus.count("bus")
    readings = report.question.readings if report.question else []
    assert not readings or readings[0].calls[0].tool == "remove_assets"


def test_asking_for_more_is_not_applied_as_a_removal(campus, registry):
    plan = Fixed(ToolCall(tool="remove_assets", args={"category": "street_light", "count": 1}))
    session, report = submit(campus, registry, plan, "we need more benches out front")
    assert not report.ok and session.scene.count("street_light") == campus.count("street_light")


def test_a_place_named_for_a_removal_limits_it_to_that_place(campus, registry):
    every_car = Fixed(ToolCall(tool="remove_assets", args={"category": "passenger_car"}))
    session, report = submit(campus, registry, every_car, "take away the cars parked inside lot A")
    assert not report.ok
    assert session.scene.count("passenger_car") == campus.count("passenger_car")


def test_a_thing_meant_by_a_place_is_not_put_far_from_it_because_the_plan_names_the_place(campus, registry):
    # the plan names the library, but its distance puts the bench 45 m away: only a distance the
    # person said may take a thing that far from the place they named
    far = ToolCall(tool="add_asset", args={"category": "bench", "count": 1, "location": {
        "relation": "in_front_of", "target": "Library entrance", "distance": 45.0}})
    session, report = submit(campus, registry, Fixed(far), "a bench close to the library would be nice")
    assert not report.ok and session.scene.count("bench") == campus.count("bench")
    session, report = submit(campus, registry, Fixed(far), "a bench 45 metres in front of the library")
    assert report.ok and session.scene.count("bench") == campus.count("bench") + 1


def test_each_thing_of_a_compound_may_stand_at_the_place_or_lane_its_own_call_names(campus, registry):
    plan = Fixed(add("bus", location={"relation": "in_lane", "target": "main_westbound"}),
                 add("bench", location={"relation": "at", "target": "fountain"}))
    session, report = submit(campus, registry, plan, "one bus on Main Street plus a seat by the fountain")
    assert report.ok and session.scene.count("bus") == campus.count("bus") + 1


def test_a_described_thing_is_not_built_as_another_category(campus, registry):
    session, report = submit(campus, registry, Fixed(add("passenger_car")),
                             "drop in something folks can toss their rubbish into")
    assert not report.ok and session.scene.count("passenger_car") == campus.count("passenger_car")


def test_a_number_the_plan_ignores_is_not_applied_silently(campus, registry):
    session, report = submit(campus, registry, Fixed(add("traffic_cone")), "set out 7 traffic cones")
    assert not report.ok and session.scene.count("traffic_cone") == campus.count("traffic_cone")


def test_a_question_changes_nothing_and_is_offered_as_a_lookup(campus, registry):
    session, report = submit(campus, registry, Fixed(add("bench")), "are there any benches near the library?")
    assert not report.ok and session.scene.count("bench") == campus.count("bench")
    assert report.question is not None
    assert all(c.tool == "find_assets" for c in report.question.readings[0].calls)


def test_a_question_about_places_is_not_answered_about_the_ego(campus, registry):
    ego_facts = Fixed(ToolCall(tool="asset_properties", args={"asset": "ego"}))
    _, report = submit(campus, registry, ego_facts, "what building sits closest to our test vehicle?")
    assert not report.ok


def test_a_plan_that_does_what_was_said_is_applied(campus, registry):
    session, report = submit(campus, registry, Fixed(add("bench", count=2)), "could you set down 2 benches")
    assert report.ok and session.scene.count("bench") == campus.count("bench") + 2


def test_the_refusal_says_what_was_not_understood_and_what_is_possible(context):
    verdict = review("put 12 cones out", Plan(calls=[add("bench")], planner="x"), context)
    assert verdict.action in ("ask", "refuse")
    assert verdict.problems and "12" in " ".join(verdict.problems)


def test_request_signals_read_polarity_question_and_place(campus):
    request = read_request("Which parked cars are in parking lot B?", campus)
    assert request.question and request.place == "parking lot B" and request.state == "parked"
    assert read_request("no longer want the cones", campus).polarity == "remove"


def test_a_description_of_a_passenger_carrier_is_not_met_by_a_car(session):
    report = session.submit("add a big vehicle that carries lots of passengers near the library")
    assert not report.ok and "bus" in (report.error or (report.question.text if report.question else ""))
    assert session.scene.count("passenger_car") == 2


def test_a_thing_the_world_has_no_word_for_is_not_met_by_another_edit(campus, registry):
    daytime = Fixed(ToolCall(tool="set_time_of_day", args={"time": "daytime"}))
    session, report = submit(campus, registry, daytime, "please add a camel beside the library for open day")
    assert not report.ok and session.scene == campus and "there is no 'camel'" in (report.error or "")
    trees = Fixed(add("tree", location={"relation": "at", "target": "fountain"}))
    _, report = submit(campus, registry, trees, "we want a hovercraft at the fountain")
    assert not report.ok and "there is no 'hovercraft'" in (report.error or "")
    # a word that only describes, counts or measures a thing the world has is no unknown thing
    bench = Fixed(add("bench", location={"relation": "at", "target": "fountain"}, count=3))
    for prompt in ("add a wooden bench at the fountain", "add three benches at the fountain",
                   "add a heap of benches at the fountain", "add a bright-red park bench at the fountain"):
        _, report = submit(campus, registry, bench, prompt)
        assert "there is no" not in (report.error or ""), prompt
