"""Readings worded here, none from a suite, found by typing slips into requests of my own (see
test_keyboard_slips.py): a slip that is an English word after the first word of a thing's name, a
letter typed twice, two letters swapped (a plural and a number kept), a slip in "in front of" and in
an hour; and two things no Worker does or that were half done: a thing made another size is refused
in plain words, and traffic lights said in the plural are all set."""

from __future__ import annotations

from drivetwin.orchestrator.planning import PlanContext
from drivetwin.orchestrator.planning.rules import spelling
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.planning.scenario_reading import ScenarioReader
from drivetwin.orchestrator.session import Session
from misreading import Fixed, call, held, ruled  # this folder is on sys.path (no __init__.py)


def _of(scene, category: str) -> list:
    return [a for a in scene.assets if a.category == category]


def test_a_word_after_the_first_word_of_a_things_name_is_that_name(campus, registry):
    scene = ruled(campus, registry, "add three traffic cons in front of the library").scene
    assert len(_of(scene, "traffic_cone")) == 3 and _of(scene, "passenger_car") == _of(campus, "passenger_car")
    assert len(_of(ruled(campus, registry, "add two trafic cones by the stop sigh").scene, "traffic_cone")) == 2
    # after a whole name the next word is its own: "pale" stays pale, never a light pole
    assert "pale" in spelling.repair("make the street light pale blue", campus).text


def test_a_letter_typed_twice_is_no_ending_on_a_shorter_word(campus, registry):
    assert ruled(campus, registry, "set the time to half past seven in the evenning").scene.environment.time_of_day == "19:30"


def test_two_letters_swapped_keep_every_letter_typed(campus, registry):
    assert len(_of(ruled(campus, registry, "add trhee traffic cones in front of the library").scene, "traffic_cone")) == 3
    slipped = ruled(campus, registry, "remove the trese near the fountain").scene
    assert {a.id for a in _of(slipped, "tree")} == {a.id for a in _of(ruled(campus, registry, "remove the trees near the fountain").scene, "tree")}
    painted = ruled(campus, registry, "paint evry tree orange").scene  # every, not "very": its first letter kept
    assert all(t.appearance.rgba[:3] != (0.0, 0.0, 0.0) and t.appearance.rgba[0] > 0.9 for t in _of(painted, "tree"))
    assert spelling.repair("place a barrier aceoss the westbound lane", campus).text == "place a barrier across the westbound lane"


def test_slips_in_in_front_of_and_in_an_hour(campus, registry):
    slipped = ruled(campus, registry, "put a box truck in font of the library").scene.asset("truck_1")
    clean = ruled(campus, registry, "put a box truck in front of the library").scene.asset("truck_1")
    assert (slipped.pose.x, slipped.pose.y) == (clean.pose.x, clean.pose.y)
    assert ruled(campus, registry, "set the time to half past seen in the evening").scene.environment.time_of_day == "19:30"
    assert ruled(campus, registry, "set the clock to a quarter to nien").scene.environment.time_of_day == "08:45"


def test_a_thing_made_another_size_is_refused_saying_so(campus, registry):
    for said in ("make the bench twice as big", "make the traffic light by the crosswalk bigger", "shrink the bus"):
        session = Session(campus, RulePlanner(), registry)
        report = session.submit(said)
        assert not report.ok and session.scene == campus, said  # the light had been moved to the crosswalk
        assert "keep the size they come in" in (report.error or ""), said
    # a size word that picks a thing, or a layout made longer, is no resizing
    assert ruled(campus, registry, "make the bench by the bigger tree red").scene.asset("bench_1").appearance.rgba[0] > 0.7


def test_traffic_lights_said_in_the_plural_are_all_set(campus, registry):
    context = PlanContext(scene=campus, registry=registry)
    for said in ("make the traffic lights red", "set both signals to red"):
        plan = ScenarioReader().plan(said, context)
        assert sorted(c.args["light"] for c in plan.calls) == ["traffic_light_1", "traffic_light_2"], said
        assert all(c.args["phases"][0]["state"] == "red" for c in plan.calls)
    (one,) = ScenarioReader().plan("turn the traffic light green", context).calls  # one said: the one the ego meets
    assert one.tool == "set_light_phases"


def test_a_plan_that_changes_nothing_says_what_it_read(campus, registry):
    report = held(campus, registry, Fixed(call("move_asset", asset="bench_1", forward=0.0)), "leave the bench where it is but face it west")
    assert "move bench_1" in (report.error or "") and "already that way" in (report.error or "")


def test_a_three_letter_thing_with_its_last_letter_lost_after_a_or_the(campus, registry):
    scene = ruled(campus, registry, "could you plant a tre near the library").scene
    assert len(_of(scene, "tree")) == 5
    assert spelling.repair("add a van by the gate", campus).text == "add a van by the gate"  # a word read here stays
