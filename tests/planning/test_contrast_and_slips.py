"""What a request says it does not mean ("..., not the ego", "except the one by the fountain",
"rather than in the lot"), and small slips of everyday writing: "is their a", "45ish", "a couple
of metres", "far too bright", "must not show up". Read alike by the rule planner and the plan
check; the wording is this file's own, run on the packaged campus world."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.base import Plan, PlanContext
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.intent import REMOVE_WORDS, excepted, without_reason
from drivetwin.orchestrator.planning.request import read_request
from drivetwin.orchestrator.planning.rules.numbers import numbers_in, spelt_measures
from drivetwin.orchestrator.planning.rules.phrases import normalise
from drivetwin.orchestrator.planning.rules.spelling import repair
from drivetwin.tools.base import ToolCall


@pytest.mark.parametrize(
    ("text", "kept", "said"),
    [
        ("recolour all vehicles green, but not the ego", "recolour all vehicles green", ["the ego"]),
        ("clear the benches except for the one near the library", "clear the benches", ["the one near the library"]),
        ("the robot should wait by the union rather than in the car park", "the robot should wait by the union",
         ["in the car park"]),
        ("park suv_1 in lot b instead of leaving it on the road", "park suv_1 in lot b", ["leaving it on the road"]),
    ],
)
def test_a_clause_naming_what_is_not_meant_is_read_apart(text, kept, said):
    assert without_reason(text) == kept
    assert excepted(text) == said


@pytest.mark.parametrize("text", ["swap in a bench instead of the bin", "Nope, not the bench - the bin",
                                  "make it drizzle but not too heavily"])
def test_a_swap_a_correction_said_first_or_a_denied_strength_is_no_exception(text):
    assert excepted(text) == []


def _context(campus, registry):
    return PlanContext(campus, registry)


def test_a_plan_that_changes_what_the_request_excepts_is_applied_without_it(campus, registry):
    calls = [ToolCall(tool="set_asset_appearance", args={"assets": ["passenger_car_1", "passenger_car_2", "suv_1"],
                                                         "colour": "green"})]
    verdict = review("give every car a green paint job except passenger_car_1", Plan(calls=calls, planner="t"),
                     _context(campus, registry))
    assert verdict.action == "apply" and "not passenger_car_1" in verdict.problems[0]
    assert verdict.calls is not None and verdict.calls[0].args["assets"] == ["passenger_car_2", "suv_1"]
    assert verdict.outcome is not None and verdict.outcome.after.asset("passenger_car_1") == campus.asset("passenger_car_1")


def test_a_group_edit_by_kind_spares_the_excepted_one_in_the_session(session, campus):
    report = session.submit("recolour every sedan orange apart from passenger_car_2")
    assert report.ok, report.error
    assert session.scene.asset("passenger_car_2") == campus.asset("passenger_car_2")
    assert session.scene.asset("passenger_car_1") != campus.asset("passenger_car_1")


def test_a_thing_excepted_by_where_it_stands_is_the_one_of_its_kind_nearest_there(campus, registry):
    trees = sorted(campus.assets, key=lambda a: (a.pose.x - 75.0) ** 2 + (a.pose.y - 40.0) ** 2)
    by_fountain = next(a.id for a in trees if a.category == "tree")
    verdict = review("chop down every tree apart from the one beside the fountain",
                     Plan(calls=[ToolCall(tool="remove_assets", args={"category": "tree"})], planner="t"),
                     _context(campus, registry))
    assert verdict.action == "apply" and by_fountain in verdict.problems[0]
    assert verdict.calls is not None
    kept = verdict.calls[0].args["assets"]  # applied without the one the words spare
    assert by_fountain not in kept and kept


def test_a_plan_that_leaves_the_excepted_thing_alone_is_applied(campus, registry):
    calls = [ToolCall(tool="set_asset_appearance", args={"assets": ["passenger_car_1", "passenger_car_2"], "colour": "teal"})]
    verdict = review("paint the two sedans teal, not the suv", Plan(calls=calls, planner="t"), _context(campus, registry))
    assert verdict.action == "apply", verdict.problems


def test_the_session_never_touches_the_excepted_ego(session, campus):
    report = session.submit("start the parked ones moving, not the ego")
    ego = session.scene.ego
    assert ego is not None and campus.ego is not None
    assert ego.behaviour == campus.ego.behaviour and ego.pose == campus.ego.pose
    assert report.ok or report.question is not None or report.error


def test_their_for_there_after_is_makes_a_question(session, campus):
    assert repair("is their a hydrant near the bus stop", campus).text.startswith("is there a hydrant")
    assert repair("their are benches by the fountain", campus).text.startswith("there are benches")
    assert repair("park it in their lot", campus).text == "park it in their lot"
    report = session.submit("is their a bench anywhere near the library")
    assert report.ok and session.scene.assets == campus.assets


def test_must_not_show_up_asks_for_the_thing_gone(campus):
    assert REMOVE_WORDS.search("those barrels must not appear in tomorrow's run")
    assert REMOVE_WORDS.search("the bin shouldn't be there at all")
    assert not REMOVE_WORDS.search("the robot must not drive through the fountain")
    assert read_request("that hydrant should not be in the scene", campus).polarity == "remove"


def test_a_figure_said_roughly_is_that_figure(session, campus):
    assert [n.value for n in numbers_in("spin it 30ish")] == [30.0]
    report = session.submit("spin the hydrant 60ish")
    hydrant, before = session.scene.asset("fire_hydrant_1"), campus.asset("fire_hydrant_1")
    assert report.ok and hydrant is not None and before is not None
    assert abs(abs(hydrant.pose.yaw - before.pose.yaw) - 1.0472) < 0.01  # 60 degrees, not a default half turn


def test_a_vague_measure_is_a_small_figure():
    assert spelt_measures("shift it a couple of metres left") == "shift it 2 metres left"
    assert spelt_measures("wait a few seconds") == "wait 3 seconds"
    assert spelt_measures("a couple of cones") == "a couple of cones"  # a count stays vague


def test_too_bright_turns_the_exposure_down_and_keeps_the_time(session, campus):
    report = session.submit("honestly the picture is way too bright")
    assert report.ok
    assert session.scene.environment.lighting.exposure < campus.environment.lighting.exposure
    assert session.scene.environment.time_of_day == campus.environment.time_of_day


def test_where_an_unknown_thing_appears_is_refused_by_its_name(session, campus):
    report = session.submit("where do the hovercraft usually show up?")
    assert not report.ok and "hovercraft" in (report.error or "")
    assert session.scene.assets == campus.assets


def test_a_thing_near_another_thing_stands_by_it(session, campus):
    report = session.submit("drop a cone near the hydrant")
    hydrant = campus.asset("fire_hydrant_1")
    cone = next(a for a in session.scene.assets if a.category == "traffic_cone" and campus.asset(a.id) is None)
    assert report.ok and hydrant is not None
    assert ((cone.pose.x - hydrant.pose.x) ** 2 + (cone.pose.y - hydrant.pose.y) ** 2) ** 0.5 < 12.0


def test_a_door_of_a_building_is_its_entrance(session, campus):
    assert normalise("by the JTEKT doors").strip() == "by the jtekt entrance"
    report = session.submit("stand a bench outside the engineering hall doors")
    entrance = campus.landmark("Engineering Hall entrance")
    bench = next(a for a in session.scene.assets if a.category == "bench" and campus.asset(a.id) is None)
    assert report.ok and entrance is not None
    assert ((bench.pose.x - entrance.position[0]) ** 2 + (bench.pose.y - entrance.position[1]) ** 2) ** 0.5 < 15.0


def test_a_thing_called_him_is_it(campus):
    assert repair("the hydrant, shift him to the library", campus).text == "the hydrant, shift it to the library"
    assert repair("paint her bike blue", campus).text == "paint her bike blue"


def test_a_second_thing_after_and_also_gets_the_same_verb(session, campus):
    report = session.submit("delete the hydrant and also the bench")
    assert report.ok
    assert session.scene.asset("fire_hydrant_1") is None and not session.scene.count("bench")


@pytest.mark.parametrize("said", ["VRUs", "NPCs", "actors"])
def test_the_domain_words_for_road_users_name_groups(session, said):
    report = session.submit(f"how many {said} are in the scene right now?")
    assert report.ok and report.answer and "found" in report.answer
    assert "there is no" not in report.answer


def test_a_labelled_query_with_its_question_inside_asks(session, campus):
    report = session.submit("Check: which benches stand near the library? Report ids only.")
    assert report.ok and report.answer and session.scene.assets == campus.assets


def test_excepted_ones_on_a_side_are_those_of_their_kind_that_way(campus, registry):
    lights = [a for a in campus.assets if a.category == "street_light"]
    mid = sum(a.pose.x for a in lights) / len(lights)
    west = sorted(a.id for a in lights if a.pose.x < mid)
    verdict = review("take down the lamp posts, not the western ones",
                     Plan(calls=[ToolCall(tool="remove_assets", args={"category": "street_light"})], planner="t"),
                     _context(campus, registry))
    assert verdict.action == "apply" and verdict.calls is not None
    removed = verdict.calls[0].args["assets"]
    assert west and not set(west) & set(removed) and len(removed) == len(lights) - len(west)
    said_as_a_side = review("take down the lamp posts except the ones on the west side",
                            Plan(calls=[ToolCall(tool="remove_assets", args={"category": "street_light"})], planner="t"),
                            _context(campus, registry))
    assert said_as_a_side.calls == verdict.calls


def test_an_exception_this_world_cannot_pick_out_is_never_guessed_past(campus, registry):
    verdict = review("tow away one car from lot b, not the ones sitting at the far corners",
                     Plan(calls=[ToolCall(tool="remove_assets", args={"assets": ["passenger_car_2"]})], planner="t"),
                     _context(campus, registry))
    assert verdict.action != "apply" and "cannot tell which" in verdict.problems[0]


def test_things_that_stand_beside_a_road_are_counted_along_it(session, campus):
    report = session.submit("how many lamp posts line Main Street")
    beside = [a for a in campus.assets if a.category == "street_light"]
    assert report.ok and report.answer and report.answer.startswith(f"{len(beside)} street_light")
    assert "beside main_" in report.answer


def test_how_busy_a_place_is_lists_what_stands_there(session, campus):
    report = session.submit("how crowded is the bus stop at the moment")
    assert report.ok and report.answer and "bench_1" in report.answer
    assert session.scene.assets == campus.assets


def test_is_anything_asks_whatever_the_punctuation(session, campus):
    report = session.submit("is anything sitting on Main Street")
    assert report.ok and report.answer and "found" in report.answer
    assert session.scene.assets == campus.assets


def test_could_it_go_a_tiny_bit_forward_is_a_small_step(session, campus):
    assert session.submit("park a car at the library").ok
    car = next(a for a in session.scene.assets if a.category == "passenger_car" and campus.asset(a.id) is None)
    report = session.submit("that car, could it go forward a tiny bit?")
    after = session.scene.asset(car.id)
    assert report.ok and after is not None and after.behaviour.kind == car.behaviour.kind
    assert 0.2 <= ((after.pose.x - car.pose.x) ** 2 + (after.pose.y - car.pose.y) ** 2) ** 0.5 <= 2.0


@pytest.mark.parametrize(("said", "kind"), [("bit of snow?", "snow"), ("a touch of fog, perhaps?", "fog")])
def test_an_amount_of_weather_offered_with_a_question_mark_asks_for_it(session, said, kind):
    report = session.submit(said)
    assert report.ok and session.scene.environment.weather.kind == kind


def test_a_real_question_with_a_question_mark_still_changes_nothing(session, campus):
    report = session.submit("how many bins stand near the library?")
    assert report.ok and report.answer and session.scene.assets == campus.assets
