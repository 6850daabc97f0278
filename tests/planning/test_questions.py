"""Questions are answered about what they ask: the kind of thing wanted, the relation and the
anchor, one search per part; and the review stops a plan that answers a neighbouring question.
Every prompt here is worded for this file, not taken from a suite."""

from __future__ import annotations

from drivetwin.orchestrator.planning import Plan
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.orchestrator.transaction import execute
from drivetwin.tools.base import ToolCall
from misreading import Fixed, call  # this folder is on sys.path (no __init__.py)


def planned(context, prompt):
    return [(c.tool, c.args) for c in RulePlanner().plan(prompt, context).calls]


def problems(context, prompt, *calls):
    verdict = review(prompt, Plan(calls=list(calls), planner="fixed"), context)
    return verdict.action, " ".join(verdict.problems)


# What the rule planner asks the search Workers for, by question shape.


def test_a_landmark_closest_to_a_named_asset_is_ranked_from_that_asset(context):
    assert planned(context, "which named place lies closest to traffic_light_1?") == [
        ("find_landmarks", {"nearest_to": "traffic_light_1"})]


def test_the_nearest_thing_of_a_kind_is_ranked_from_the_ego(context):
    assert planned(context, "which tree stands closest to our car?") == [
        ("find_assets", {"category": "tree", "nearest_to": "ego"})]


def test_how_far_a_place_is_from_the_ego_measures_between_the_two(context):
    assert planned(context, "how far away is the fountain from the ego vehicle?") == [
        ("measure_distance", {"a": "fountain", "b": "ego"})]


def test_a_distance_between_two_named_things_is_measured_between_them(context):
    assert planned(context, "what's the gap between the bus stop and the east gate, roughly?") == [
        ("measure_distance", {"a": "bus stop", "b": "east gate"})]
    assert planned(context, "how many metres from the hydrant to the bench?") == [
        ("measure_distance", {"a": "fire_hydrant_1", "b": "bench_1"})]


def test_one_thing_named_in_a_distance_question_is_measured_from_the_asker(context):
    assert planned(context, "how far off is the Student Union from me") == [
        ("measure_distance", {"a": "Student Union entrance", "b": "ego"})]


def test_a_distance_to_the_nearest_of_a_kind_still_ranks_that_kind(context):
    assert planned(context, "how far is the closest tree from the ego?") == [
        ("find_assets", {"category": "tree", "nearest_to": "ego"})]


def test_how_wide_or_long_a_road_is_lists_its_lanes(context):
    assert planned(context, "how wide is Campus Drive?") == [("find_lanes", {"road": "Campus Drive"})]


def test_things_within_a_stated_radius_of_a_place_use_that_radius(context):
    assert planned(context, "which street lights stand within 12 m of the library?") == [
        ("find_assets", {"category": "street_light", "near": "Library entrance", "within": 12.0})]


def test_things_in_an_area_are_searched_over_the_whole_area(context):
    [(tool, args)] = planned(context, "how many cars sit in parking lot B?")
    assert tool == "find_assets" and args["category"] == "cars" and args["near"] == "parking lot B"
    # "cars" is the catalog's car tag: sedans and SUVs alike; the search measures to the lot's edge (0 inside)
    found = execute(context.registry, context.scene, [ToolCall(tool=tool, args=args)]).results[0]
    assert set(found.data["ids"]) == {"passenger_car_1", "passenger_car_2", "suv_1"}
    assert args["within"] <= 5.0, "the lot, not the roads round it"


def test_what_blocks_a_named_road_searches_what_stands_on_that_road(context):
    assert planned(context, "is something obstructing Main Street?") == [
        ("find_assets", {"on_lane": True, "lane": "Main Street"})]


def test_a_lane_named_as_a_place_searches_what_stands_in_it(context):
    assert planned(context, "what is stopped in the southbound lane?") == [
        ("find_assets", {"on_lane": True, "lane": "campus_southbound"})]


def test_an_obstruction_near_a_place_is_searched_only_there(context):
    [(tool, args)] = planned(context, "is the road blocked by the west gate?")
    assert tool == "find_assets" and args["on_lane"] and args["near"] == "main gate"


def test_the_lane_an_asset_is_in_is_the_lane_nearest_it(context):
    assert planned(context, "which lane is the SUV in?") == [("find_lanes", {"near": "suv_1"})]


def test_the_lanes_of_a_road_are_listed_by_that_road(context):
    assert planned(context, "what lanes make up Campus Drive?") == [("find_lanes", {"road": "Campus Drive"})]


def test_a_property_of_the_only_one_there_describes_that_asset(context):
    assert planned(context, "how heavy is the fire hydrant?") == [("asset_properties", {"asset": "fire_hydrant_1"})]


def test_a_property_of_a_kind_describes_its_catalog_entry(context):
    assert planned(context, "how tall would a bus be?") == [("asset_properties", {"category": "bus"})]


def test_around_us_means_around_the_ego_and_leaves_the_ego_out(context):
    [(tool, args)] = planned(context, "anything close to us?")
    assert tool == "find_assets" and args["nearest_to"] == "ego" and "near" not in args


def test_where_am_i_is_asked_of_the_ego(context):
    assert planned(context, "where am i right now?") == [("asset_properties", {"asset": "ego"})]


def test_a_clause_that_only_points_back_at_earlier_questions_adds_no_search(context):
    assert planned(context, "hydrants? bins? count both") == [
        ("find_assets", {"category": "fire_hydrant"}), ("find_assets", {"category": "trash_bin"})]


def test_a_compound_question_gets_one_search_per_part_and_it_means_the_first_subject(context):
    assert planned(context, "what does the SUV weigh, and which landmark is nearest to it?") == [
        ("asset_properties", {"asset": "suv_1"}), ("find_landmarks", {"nearest_to": "suv_1"})]


def test_it_in_a_later_part_is_what_the_first_part_found(session):
    assert session.submit("put a traffic cone in the westbound lane").ok
    cone = next(a.id for a in session.scene.assets if a.category == "traffic_cone")
    calls = planned(session.context(), "are any objects lying on the lanes, and what place is closest to it?")
    assert calls == [("find_assets", {"on_lane": True}), ("find_landmarks", {"nearest_to": cone})]


def test_there_in_a_later_turn_is_the_place_of_the_last_edit(session):
    assert session.submit("put a bench at the fountain").ok
    [(tool, args)] = planned(session.context(), "what else stands around there?")
    x, y = (float(v) for v in args["near"].split(","))
    fountain = session.scene.landmark("fountain").position
    assert tool == "find_assets" and abs(x - fountain[0]) < 10 and abs(y - fountain[1]) < 10


def test_a_question_is_answered_and_changes_nothing(session):
    before = session.scene.model_copy(deep=True)
    report = session.submit("which landmark is closest to the SUV?")
    assert report.ok and "nearest landmark to suv_1" in (report.answer or " ".join(report.results))
    assert session.scene.assets == before.assets


# The review stops a plan that answers a neighbouring question.


def test_a_nearest_question_answered_without_distances_is_not_given(context):
    action, why = problems(context, "which tree stands closest to our car?", call("find_assets", category="tree"))
    assert action != "apply" and "nearest" in why


def test_a_blocking_question_answered_by_listing_lanes_is_not_given(context):
    action, why = problems(context, "is anything obstructing the eastbound lane?", call("find_lanes"))
    assert action != "apply" and "stands on the lanes" in why


def test_a_property_question_answered_about_another_thing_is_not_given(context):
    action, why = problems(context, "what does the SUV weigh?", call("asset_properties", asset="ego"))
    assert action != "apply" and "the suv, but the plan describes ego" in why


def test_a_property_question_answered_by_a_list_is_not_given(context):
    action, why = problems(context, "what colour is the SUV?", call("find_assets", category="suv"))
    assert action != "apply" and "describes nothing" in why


def test_a_two_part_question_answered_once_is_not_given(context):
    prompt = "what does the SUV weigh, and which landmark is nearest to it?"
    action, why = problems(context, prompt, call("asset_properties", asset="suv_1"))
    assert action != "apply" and "2 things" in why


def test_a_plan_that_answers_the_question_asked_is_given(context):
    prompt = "which tree stands closest to our car?"
    assert problems(context, prompt, call("find_assets", category="tree", nearest_to="ego")) == ("apply", "")


def test_a_session_asks_or_refuses_rather_than_answering_about_the_wrong_thing(campus, registry):
    session = Session(campus, Fixed(call("asset_properties", asset="ego")), registry)
    report = session.submit("what does the SUV weigh?")
    assert not report.ok and not report.results


def test_a_measured_distance_answers_how_far_and_the_session_changes_nothing(context, campus, registry):
    action, _ = problems(context, "how far is the library from the fountain?",
                         call("measure_distance", a="Library entrance", b="fountain"))
    assert action == "apply"
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("how far is the library from the fountain?")
    assert report.ok and "128.4 m" in (report.answer or "") and session.scene == campus
