"""Worded here (none from a suite): a thing a clause is said of ("the bus should drive more carefully", "might
the bus be in lot B?") that the scene does not have is asked about, never added, while a role ("the lead car")
still brings one in; a step's way said and not read ("3 metres est") is asked, never guessed; "where the tree
is" with several trees is refused, naming one to pick; a story that opens on a steady speed sets the lane
behaviour's speed and times its later steps from the start, a later step said as "let it ..." included; "the ego
cycles" is a verb, never bicycles; a retrieval reading that does what the words do not ask is no offer."""

from __future__ import annotations

from drivetwin.orchestrator.planning import PlanContext
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.planning.scenario_reading import ScenarioReader
from drivetwin.orchestrator.session import Session


def test_a_thing_a_clause_is_said_of_that_the_scene_lacks_is_asked_about_not_added(campus, registry):
    assert campus.count("bus") == 0
    for said in ("the bus should drive more carefully", "might the bus be in lot B?", "let the bus go more slowly"):
        session = Session(campus, RulePlanner(), registry)
        report = session.submit(said)
        assert report.question is not None and "no bus" in report.question.text, (said, report.error)
        assert session.scene == campus, said


def test_a_role_still_brings_one_in(campus, registry):
    session = Session(campus, ScenarioReader(), registry)
    report = session.submit("the lead car brakes hard when the ego gets close")
    assert report.ok, report.error or report.question
    assert session.scene.count("passenger_car") == campus.count("passenger_car") + 1


def test_a_way_said_after_a_steps_length_and_not_read_is_asked(campus, registry):
    for said in ("shift the bench 3 metres est", "shift the bin 2 metres kerbside"):
        session = Session(campus, RulePlanner(), registry)
        report = session.submit(said)
        assert report.question is not None and "which way" in report.question.text.lower(), (said, report.error)
        assert session.scene == campus
    moved = Session(campus, RulePlanner(), registry)  # the way read: done
    assert moved.submit("move the bench 2 metres towards the road").ok


def test_where_one_of_several_is_is_refused_naming_one_to_pick(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("move the bench where the tree is")
    assert not report.ok and report.question is None and "say which one" in (report.error or "")
    assert session.scene == campus
    one = Session(campus, RulePlanner(), registry)  # the one hydrant: beside it
    assert one.submit("put the bench where the hydrant is").ok
    hydrant, bench = one.scene.asset("fire_hydrant_1"), one.scene.asset("bench_1")
    assert hydrant is not None and bench is not None and abs(hydrant.pose.x - bench.pose.x) + abs(hydrant.pose.y - bench.pose.y) < 6


def test_a_story_that_opens_on_a_steady_speed_sets_it_and_times_the_rest_from_the_start(campus, registry):
    context = PlanContext(scene=campus, registry=registry)
    for said in ("the ego drives at 6 m/s and changes to the left lane after 5 seconds",
                 "Ego speed 6 m/s, and let it change to the left lane after 5 seconds"):
        plan = ScenarioReader().plan(said, context)
        assert [c.tool for c in plan.calls] == ["set_behaviour", "add_manoeuvre"], said
        assert plan.calls[0].args["behaviour"]["speed"] == 6.0
        assert plan.calls[1].args["manoeuvre"]["kind"] == "lane_change" and plan.calls[1].args["at_time"] == 5.0
    # said alone, a speed is the lane behaviour's as before; no story is made of it
    report = Session(campus, RulePlanner(), registry).submit("the ego drives at 6 m/s")
    assert report.ok and report.plan is not None and [c.tool for c in report.plan.calls] == ["set_behaviour"]


def test_a_later_step_said_of_it_is_done_by_the_actor_before(campus, registry):
    plan = ScenarioReader().plan("the ego accelerates to 8 m/s and then it brakes hard 3 s later",
                                 PlanContext(scene=campus, registry=registry))
    assert [(c.args["actor"], c.args["manoeuvre"]["kind"]) for c in plan.calls] == [("ego", "change_speed"), ("ego", "stop")]


def test_a_catalog_word_said_as_what_something_does_adds_nothing(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("the ego cycles around the loop")
    assert not report.ok and session.scene.count("bicycle") == campus.count("bicycle")
    assert Session(campus, RulePlanner(), registry).submit("add cycles near the library").ok  # a noun still
