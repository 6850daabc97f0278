"""Terse shell-like requests, memories told beside a request, colours shared out, grids by their
size, places that are not there and stops at a place, tried in this file's own words on the
packaged campus world: "del cone" removes, "ls bench" lists, "cnt trees" counts; "back in my
day ..." is never acted on; "one car green and the other white" paints two; "a 2-by-3 lattice"
is a grid of six; "cordon off the gymnasium" is no ring at the map centre; "the test car halts
short of the crossing" comes to rest before it (MuJoCo)."""

from __future__ import annotations

import itertools

import pytest
from drivetwin.orchestrator.planning.base import Plan, PlanContext, Question, Reading
from drivetwin.orchestrator.planning.check import review
from drivetwin.orchestrator.planning.intent import asks, without_memories
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules.spelling import repair
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.simulation import Simulation
from drivetwin.worlds.storyboard import ReachPositionCondition


def _kinds(session, category):
    return [a.id for a in session.scene.assets if a.category == category]


def test_shell_words_remove_list_and_count(session):
    assert session.submit("add 2 cones at the main intersection").ok
    listed = session.submit("ls bench")
    assert listed.ok and listed.plan is not None and [c.tool for c in listed.plan.calls] == ["find_assets"]
    counted = session.submit("cnt trees")
    assert counted.ok and counted.answer is not None and "4" in counted.answer
    assert session.submit("del bin").ok
    assert not _kinds(session, "trash_bin")


def test_a_terse_arrow_and_plus_read_as_to_and_and():
    scene = build_campus()
    assert repair("cones x2 -> lot B", scene).text == "cones x2 to lot B"
    assert repair("switch street + vehicle lights on", scene).text == "switch street and vehicle lights on"
    assert repair("move the the bin", scene).text == "move the bin"


def test_a_misspelt_tens_word_is_read_before_the_number():
    assert repair("spin it ninty degrees", build_campus()).text.startswith("spin it 90")


@pytest.mark.parametrize("words", [
    "Back in my day there was a kiosk here. Put a bench by the fountain.",
    "When I was young we'd race round the quad; reminds me of summer. Put a bench by the fountain.",
])
def test_a_memory_told_beside_a_request_is_left_out(words):
    assert without_memories(words).strip() == "Put a bench by the fountain."


def test_a_memory_alone_is_kept_so_that_something_is_read():
    assert without_memories("Back in my day there was a kiosk here.") == "Back in my day there was a kiosk here."


def test_what_the_speaker_remembers_names_nothing_to_add(session):
    result = session.submit("In my day a lorry stood at the east gate every morning. Put a bench by the fountain.")
    assert result.ok, result.error
    assert not _kinds(session, "truck") and len(_kinds(session, "bench")) == 2


def test_two_colours_shared_out_paint_one_thing_each(session):
    result = session.submit("make one of the cars green and the other white")
    assert result.ok, result.error
    looks = {a.id: a.appearance.rgba for a in session.scene.assets if a.category == "passenger_car"}
    assert len(set(looks.values())) == 2 and None not in looks.values()


def test_the_colour_asked_for_is_the_one_after_the_thing_not_the_one_picking_it():
    assert md.colours_asked("paint the blue bench yellow") == ["yellow"]
    assert md.colours_asked("the bin is grey, colour it red and the bench brown") == ["red", "brown"]


@pytest.mark.parametrize(("words", "said"), [
    ("paint the bench purple and teal", "purple"),  # a colour named that the plan does not give
    ("take out the lamps along one side of Campus Drive", "which side"),  # a side left unnamed is asked for
])
def test_what_the_plan_cannot_honour_is_refused_saying_why(session, words, said):
    before = session.scene
    result = session.submit(words)
    assert not result.ok and said in (result.error or "")
    assert session.scene == before


def test_a_lattice_of_rows_by_columns_is_a_grid(session):
    result = session.submit("lay out a 2-by-3 lattice of bollards in lot A")
    assert result.ok, result.error
    assert result.plan is not None
    (call,) = result.plan.calls
    assert call.args["shape"] == "grid" and call.args["count"] == 6 and call.args["columns"] == 3


def test_things_wanted_around_with_nothing_to_go_round_are_no_ring(session):
    result = session.submit("we could do with a couple more benches around")
    assert result.ok and result.plan is not None
    assert [c.tool for c in result.plan.calls] == ["add_asset"]


@pytest.mark.parametrize("words", [
    "cordon off the gymnasium entrance with cones",
    "set the tea table on the roof of the Student Union",
    "a line of bollards inside the tall brick building, the Engineering one",
    "put the bin on the roof of the Student Union",  # a roof, however it is said
    "stand a bollard on top of the libary roof",
    "the bench up on the engineering hall roof please",
])
def test_a_place_not_there_or_inside_or_on_a_building_changes_nothing(session, words):
    before = session.scene
    assert not session.submit(words).ok
    assert session.scene == before


def test_a_state_asked_with_is_it_is_a_question_and_is_it_possible_is_a_request():
    assert asks("is it snowing at the moment")
    assert not asks("is it possible to make it snow")


def test_sending_people_away_never_adds_people(session):
    before = session.scene
    assert not session.submit("get the crowd away from the bus stop").ok
    assert session.scene == before


def test_a_fixed_thing_told_to_walk_is_refused(session):
    before = session.scene
    assert not session.submit("make the hydrant stroll to the library").ok
    assert session.scene == before


def test_a_thing_picked_by_its_place_goes_where_it_is_sent(session):
    result = session.submit("carry the tree by lot A to the library")
    assert result.ok, result.error
    assert result.plan is not None and result.plan.calls[0].args["asset"] == "tree_4"


def test_things_named_together_share_the_place_said_last(session):
    result = session.submit("put a bollard and a cone outside the Engineering Hall entrance")
    assert result.ok, result.error
    assert result.plan is not None
    assert [c.args["location"]["target"] for c in result.plan.calls] == ["Engineering Hall entrance"] * 2


def test_the_one_after_and_is_another_of_the_thing_named_first(session):
    result = session.submit("delete the tree by lot A and the one near the fountain")
    assert result.ok, result.error
    assert len(_kinds(session, "tree")) == 2


def test_a_stop_at_a_crossing_comes_to_rest_before_it(session):
    """The Worker starts the brake early enough for the car's front to stop short of the painted
    crossing (MuJoCo run); a stop on reaching a point with no crossing keeps the plain radius."""
    asked = session.submit("the test car halts short of the west crosswalk")
    assert asked.question is not None, "the rule planner's static reading is questioned; the stop is offered"
    result = session.choose(1)
    assert result.ok, result.error
    (_, event), = session.scene.storyboard.events()
    assert isinstance(event.start, ReachPositionCondition) and event.start.tolerance > 8.0
    sim = Simulation(session.scene)
    sim.run_for(20.0)
    ego = sim.poses()["ego"]
    crossing_edge = -13.25  # the crossing's paint starts here along the ego's lane
    assert ego.x + 2.25 < crossing_edge, "the front stopped short of the paint"
    assert ego.x > -30.0, "and not far short of it"


def test_it_after_a_question_about_one_thing_is_that_thing(session):
    assert session.submit("where is the hydrant?").ok
    result = session.submit("paint it orange")
    assert result.ok, result.error
    assert result.plan is not None and result.plan.calls[0].args["assets"] == ["fire_hydrant_1"]


@pytest.mark.parametrize(("words", "fixed"), [
    ("truck.speed = 6", "set truck speed to 6"),  # a programmer's shorthand
    ("hydrant.position = (12, 6)", "move hydrant to (12, 6)"),
    ("radius=4 // please", "radius 4 please"),
    ("move it 2 the gate", "move it to the gate"),
    ("get rid o' the bins", "get rid of the bins"),  # everyday slips of small words
    ("line cones up in front of are car", "line cones up in front of our car"),
    ("park it ahead the bus", "park it ahead of the bus"),
])
def test_shorthand_and_slips_of_small_words_read_as_meant(words, fixed):
    assert repair(words, build_campus()).text == fixed


def test_a_bare_speed_is_in_metres_per_second(session):
    result = session.submit("ego.speed = 7")
    assert result.ok, result.error
    assert result.plan is not None and result.plan.calls[0].args["behaviour"]["speed"] == 7.0


def test_a_year_said_in_passing_is_no_amount(session):
    assert session.submit("snow like the winter of 2010, heavy").ok
    assert session.submit("fog, thick, the way it came in 95").ok


def test_the_same_look_for_things_added_with_as_well_and_a_reason(session):
    result = session.submit("paint the bench red, and the bin as well so they go together")
    assert result.ok, result.error
    assert result.plan is not None and {c.args["colour"] for c in result.plan.calls} == {"red"} and len(result.plan.calls) == 2


def test_trees_round_a_place_some_metres_out_are_a_ring_of_that_radius(session):
    result = session.submit("five trees round its middle, 6 m out, in lot B")
    assert result.ok, result.error
    assert result.plan is not None
    (call,) = result.plan.calls
    assert call.args["shape"] == "ring" and call.args["radius"] == 6.0


def test_a_thing_given_a_name_is_found_by_it_later(session):
    added = session.submit("put a cyclist by the fountain, that's our courier")
    assert added.ok, added.error
    (courier,) = [a for a in session.scene.assets if a.label == "courier"]
    result = session.submit("now send the courier over to the library")
    assert result.ok, result.error
    assert result.plan is not None and result.plan.calls[0].args["asset"] == courier.id


def test_a_name_that_holds_a_thing_word_asks_for_no_such_thing(session):
    result = session.submit("add a truck in lot A, that's our rescue vehicle")
    assert result.ok, result.error
    assert result.plan is not None and len(result.plan.calls) == 1
    assert [a.category for a in session.scene.assets if a.label == "rescue vehicle"] == ["truck"]


def test_a_road_said_short_is_that_road():
    assert repair("park it on campus dr. please", build_campus()).text == "park it on Campus Drive please"


def test_both_kinds_of_lights_said_switch_both(session):
    result = session.submit("flick the street + vehicle lights on")
    assert result.ok, result.error
    lights = session.scene.environment.lighting
    assert lights.street_lights == "on" and lights.vehicle_lights == "on"


def test_a_back_said_to_face_a_place_turns_the_thing_away_from_it(session):
    toward = session.submit("turn the bench so it faces the road")
    assert toward.ok and toward.plan is not None
    session.undo()
    away = session.submit("turn the bench so its back faces the road")
    assert away.ok and away.plan is not None
    turned = toward.plan.calls[0].args["turn_deg"] - away.plan.calls[0].args["turn_deg"]
    assert abs(abs(turned) - 180.0) < 1.0


def test_a_verb_and_its_particle_are_not_run_together_into_a_thing():
    assert repair("have the kids cross over the road", build_campus()).text == "have the kids cross over the road"
    assert repair("put a cone on the side walk", build_campus()).text == "put a cone on the sidewalk"
    assert repair("make him jay walk", build_campus()).text == "make him jaywalk", "a behaviour's word is still joined"


def _two_readings(sure: float, *readings: list[ToolCall]) -> Plan:
    question = Question(text="Did you mean:", readings=[Reading(text=str(i), calls=calls, confidence=sure)
                                                        for i, calls in enumerate(readings)])
    return Plan(calls=[], planner="hybrid", confidence=0.0, question=question)


def test_of_two_readings_the_one_the_request_does_not_rule_out_is_applied():
    context = PlanContext(scene=build_campus(), registry=ToolRegistry.default(plugins=False))
    move = [ToolCall(tool="place_asset", args={"asset": "bench_1", "location": {"relation": "next_to", "target": "fountain"}})]
    add = [ToolCall(tool="add_asset", args={"category": "bench", "location": {"relation": "next_to", "target": "fountain"}})]
    verdict = review("kindly set the bench down beside the fountain", _two_readings(0.95, add, move), context)
    assert verdict.action == "apply" and verdict.calls == move
    unsure = review("kindly set the bench down beside the fountain", _two_readings(0.5, add, move), context)
    assert unsure.action == "ask", "a reading its planner was unsure of is still offered, not applied"


def test_of_two_readings_one_that_acts_on_a_thing_not_named_is_still_asked_about():
    context = PlanContext(scene=build_campus(), registry=ToolRegistry.default(plugins=False))
    bin_moved = [ToolCall(tool="place_asset", args={"asset": "trash_bin_1", "location": {"relation": "at", "target": "fountain"}})]
    bench_moved = [ToolCall(tool="place_asset", args={"asset": "bench_1", "location": {"relation": "at", "target": "fountain"}})]
    verdict = review("that thing over there, to the fountain with it", _two_readings(0.95, bin_moved, bench_moved), context)
    assert verdict.action != "apply"


def test_a_thing_said_with_its_number_is_that_one_not_a_new_one(session):
    result = session.submit("put passenger car 1 in lot A")
    assert result.ok, result.error
    assert not [a for a in session.scene.assets if a.category == "passenger_car" and a.id not in ("passenger_car_1", "passenger_car_2")]


def test_every_kind_of_car_at_a_place_counted_out(session):
    result = session.submit("get rid of the three cars parked in lot B")
    assert result.ok, result.error
    assert session.scene.asset("suv_1") is None and session.scene.asset("passenger_car_1") is None


def test_things_wished_livelier_are_never_taken_away():
    context = PlanContext(scene=build_campus(), registry=ToolRegistry.default(plugins=False))
    plan = Plan(calls=[ToolCall(tool="remove_assets", args={"category": "passenger_car"})], planner="x", confidence=0.9)
    verdict = review("the cars parked in lot B look so drab, liven them up", plan, context)
    assert verdict.action != "apply" and any("more life" in p for p in verdict.problems)


@pytest.mark.parametrize("words", [
    "kindly state the weather at present, make no alterations",
    "please identify the bench nearest the fountain",
    "is it foggy out there",
])
def test_asked_to_state_or_identify_is_a_question(words):
    assert asks(words)


def test_things_of_a_kind_told_to_move_all_drive_spaced_along_the_lane(session):
    result = session.submit("make the cars go")
    assert result.ok, result.error
    drivers = [a for a in session.scene.assets if a.behaviour.kind == "drive_lane" and a.id != "ego"]
    assert {a.id for a in drivers} == {"passenger_car_1", "passenger_car_2", "suv_1"}
    ys = sorted(a.pose.y for a in drivers)
    assert min(b - a for a, b in itertools.pairwise(ys)) > 6.0, "spaced along the lane, not stacked"


def test_the_same_again_made_of_other_things(session):
    assert session.submit("put four cones in a row in lot A").ok
    result = session.submit("now the same with bollards by the east gate")
    assert result.ok, result.error
    assert result.plan is not None and result.plan.calls[0].args["categories"] == ["bollard"]


def test_a_light_strength_said_as_such_is_light(session):
    assert session.submit("fog please, low intensity").ok
    assert session.scene.environment.weather.intensity <= 0.5


def test_the_av_is_the_ego(session):
    result = session.submit("put a bollard 12 m ahead of the AV")
    assert result.ok, result.error
    assert result.plan is not None and result.plan.calls[0].args["location"]["target"] == "ego"


def test_a_place_name_no_plan_repairs_into_is_refused(session):
    before = session.scene
    assert not session.submit("how far is the bench from the planetarium?").ok
    assert session.scene == before


def test_a_ticket_number_is_no_amount_and_a_terse_keep_spares(session):
    assert session.submit("ticket #12: the hydrant has to go").ok
    result = session.submit("rm: trash_bin_1, bench_1 - keep stop sign")
    assert result.ok, result.error
    assert session.scene.asset("stop_sign_1") is not None and session.scene.asset("bench_1") is None


def test_coordinates_with_their_unit_and_the_origin(session):
    result = session.submit("add a bollard at x = 30 m, y = 9 m")
    assert result.ok, result.error
    assert result.plan is not None and result.plan.calls[0].args["location"] == {"relation": "absolute", "x": 30.0, "y": 9.0}
    origin = session.submit("put a cone at the origin")
    assert origin.ok, origin.error
    assert origin.plan is not None and origin.plan.calls[0].args["location"] == {"relation": "scene_centre"}


def test_a_bare_number_said_with_faster_or_slower_is_the_speed():
    from drivetwin.orchestrator.planning.rules.phrases import find_speed

    assert find_speed("go faster, like 9") == 9.0
    assert find_speed("slow it down to about 2") == 2.0
    assert find_speed("three times faster") is None


def test_what_is_in_an_area_is_what_stands_on_it(session):
    result = session.submit("which things are in parking lot B?")
    assert result.ok and result.answer is not None
    assert all(i in result.answer for i in ("passenger_car_1", "passenger_car_2", "suv_1")) and "ego" not in result.answer


@pytest.mark.parametrize("prompt", ["coordinates of the hydrant nearest the fountain", "req location of the bench, over",
                                    "need the whereabouts of the suv", "I need the ID of the nearest bin"])
def test_where_a_thing_is_asked_bare_is_a_question_that_changes_nothing(session, campus, prompt):
    assert asks(prompt.lower())
    report = session.submit(prompt)
    assert session.scene == campus
    assert report.ok and report.answer, report.error


def test_a_rider_sent_to_a_place_goes_there_by_path_not_along_any_lane(session):
    assert session.submit("put a bicycle at the west crosswalk").ok
    report = session.submit("get the cyclist to ride over to the Library entrance")
    assert report.ok, report.error
    behaviour = session.scene.asset("bicycle_1").behaviour
    assert behaviour.kind == "follow_path" and behaviour.speed > 1.4  # a ride, faster than a walk
    library = session.scene.landmark("Library entrance")
    assert library is not None
    end_x, end_y = behaviour.waypoints[-1]
    assert abs(end_x - library.position[0]) + abs(end_y - library.position[1]) < 12.0


@pytest.mark.parametrize(("prompt", "call"), [
    ("a bit dimmer, please", ToolCall(tool="add_asset", args={"category": "pedestrian", "location": {"relation": "at", "target": "fountain"}})),
    ("ease the test car's pace off", ToolCall(tool="add_asset", args={"category": "bus"})),
    ("Kindly tidy up over there.", ToolCall(tool="add_asset", args={"category": "street_light"})),
])
def test_a_plan_that_adds_a_kind_the_words_never_name_is_not_applied(context, prompt, call):
    verdict = review(prompt, Plan(calls=[call], planner="llm"), context)
    assert verdict.action != "apply"
    assert any("which your words do not name" in p for p in verdict.problems)


@pytest.mark.parametrize("prompt", ["a couple more of those, please", "make the quad feel lived-in and busier",
                                    "add some cones", "bring in a bit of foot traffic"])
def test_words_asking_for_more_or_naming_the_kind_let_a_plan_add(context, prompt):
    call = ToolCall(tool="add_asset", args={"category": "traffic_cone" if "cone" in prompt else "pedestrian", "count": 2})
    problems = review(prompt, Plan(calls=[call], planner="rules"), context).problems
    assert not any("which your words do not name" in p for p in problems)


@pytest.mark.parametrize(("prompt", "call", "problem"), [
    ("get rid of the spare vehicles", ToolCall(tool="set_behaviour", args={"asset": "suv_1", "behaviour": {"kind": "drive_lane"}}),
     "removes nothing"),
    ("budge the hydrant over slightly", ToolCall(tool="place_asset", args={"asset": "fire_hydrant_1",
                                                                          "location": {"relation": "at", "target": "north crosswalk"}}),
     "small move"),
    ("have the ego ease off the throttle", ToolCall(tool="set_weather", args={"kind": "fog"}), "do not mention"),
    ("the quad ought to be free of litter bins", ToolCall(tool="add_asset", args={"category": "trash_bin"}), "take something away"),
    ("that bench belongs beside the hydrant", ToolCall(tool="place_asset", args={"asset": "bench_1",
                                                                                "location": {"relation": "at", "target": "east gate"}}),
     "near the fire hydrant"),
])
def test_a_plan_doing_something_else_than_the_words_is_not_applied(context, prompt, call, problem):
    verdict = review(prompt, Plan(calls=[call], planner="llm"), context)
    assert verdict.action != "apply"
    assert any(problem in p for p in verdict.problems), verdict.problems


@pytest.mark.parametrize(("prompt", "call"), [
    ("shift the hydrant a little to the east", ToolCall(tool="move_asset", args={"asset": "fire_hydrant_1", "east": 1.0})),
    ("a murky, foggy look please", ToolCall(tool="set_weather", args={"kind": "fog"})),
    ("switch the headlamps on", ToolCall(tool="set_lighting", args={"vehicle_lights": "on"})),
])
def test_a_plan_doing_what_the_words_say_passes_those_checks(context, prompt, call):
    problems = review(prompt, Plan(calls=[call], planner="rules"), context).problems
    assert not any(p in " ".join(problems) for p in ("removes nothing", "small move", "do not mention")), problems


def test_an_amount_bounded_with_no_more_than_is_never_a_removal(session, campus):
    report = session.submit("nudge the bin no more and no less than two metres east")
    assert report.ok, report.error
    before, after = campus.asset("trash_bin_1"), session.scene.asset("trash_bin_1")
    assert after is not None and after.pose.x == pytest.approx(before.pose.x + 2.0, abs=0.3)
    assert session.submit("put no more than three bollards by the library").ok
    assert 1 <= session.scene.count("bollard") - campus.count("bollard") <= 3
