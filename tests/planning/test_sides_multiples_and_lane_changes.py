"""Worded here (none from a suite): a question about the things on one side of the road with no road named (the
side of the road nearest each), or on the side of a road named of a kind that stands anywhere (refused: the
search cannot say that); "2 more of them" adds two; "double the number of benches" adds as many as there are and
a multiple of none is refused; a lane change or a distance said that a storyboard leaves out is refused;
someone's thing set to do something ("have my guy ...") is never a new one; a thing lost to the eye ("it blends
into the grass") is made to stand out, never removed; a dark colour is no dark; "a number of" things is some,
not a count asked; a manner said before where a drive goes; the ones who wait or want are the setting, not
things to add; "a blue one next to it" is one more; "the first one" after one more is the earlier one; what is
kept said first is excepted from the rest; "them" before things, "feets", "rides forth to", "so much" snow; a
polite "might"; what a walk is for is its setting; "tre 4" is tree_4; "on which lane" asks the lane; a time said
after a second step is that step's; "banish", "rip out"; a bright colour is no daylight; "most far" is furthest;
how far after a route said is its length; "every other one" is half of them; each put where the other is is a
swap; a thing that should not be on the sidewalk never goes onto one; a ticket's criteria under a few-word
heading say what to build."""

from __future__ import annotations

from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from misreading import Fixed, add, call, held, ruled  # this folder is on sys.path (no __init__.py)


def _north(scene) -> set[str]:
    return {a.id for a in scene.assets if a.category == "street_light" and a.pose.y > 0}


def test_a_side_said_alone_in_a_question_is_the_side_of_the_one_road_that_has_it(campus, registry):
    for said in ("how many street lights are on the north side?", "which lamp posts stand on the south side of the road?"):
        report = Session(campus, RulePlanner(), registry).submit(said)
        assert report.ok and report.plan is not None, said
        wanted = _north(campus) if "north" in said else {a.id for a in campus.assets if a.category == "street_light"} - _north(campus)
        assert f"{len(wanted)} street_light(s) found" in (report.answer or ""), (said, report.answer)
        assert all(i in (report.answer or "") for i in wanted), said


def test_a_side_said_alone_of_a_kind_that_stands_anywhere_is_the_side_of_the_road_nearest_each(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("any trees out on the east side?")
    east = sorted(a.id for a in campus.assets if a.category == "tree" and a.pose.x > 0)
    assert report.ok and f"{len(east)} tree(s) found" in (report.answer or "") and all(t in (report.answer or "") for t in east)


def test_a_side_the_search_cannot_say_is_refused_not_answered_for_the_whole_scene(campus, registry):
    report = held(campus, registry, Fixed(call("find_assets", category="cars")), "how many cars are on the north side of Main Street?")
    assert "north side" in (report.error or "") and "whole scene" in (report.error or "")


def test_more_of_them_adds_the_number_said(campus, registry):
    session = ruled(campus, registry, "add 3 traffic cones in front of the JTEKT building entrance", "add 2 more of them")
    assert session.scene.count("traffic_cone") == 5


def test_a_multiple_of_the_things_there_adds_that_many_more(campus, registry):
    benches = campus.count("bench")
    assert ruled(campus, registry, "double the number of benches").scene.count("bench") == 2 * benches
    assert ruled(campus, registry, "could we have twice as many trees").scene.count("tree") == 2 * campus.count("tree")
    assert ruled(campus, registry, "reduce the number of street lights").scene.count("street_light") < campus.count("street_light")
    # none to multiply: a refusal, never the default few
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("triple the number of cones")
    assert not report.ok and session.scene.count("traffic_cone") == 0
    # a word that only begins with one is none: "double-park a car" parks one
    assert ruled(campus, registry, "double-park a car in lot B").scene.count("passenger_car") == campus.count("passenger_car") + 1


def test_a_lane_change_a_storyboard_leaves_out_is_refused(campus, registry):
    plan = Fixed(call("add_manoeuvre", actor="ego", manoeuvre={"kind": "keep_lane", "speed": 4.0}, at_time=6.0))
    report = held(campus, registry, plan, "the ego rolls at 4 m/s and hops into the left lane at 6 s")
    assert "changes no lane" in (report.error or "")
    # where the scenario reader reads the lane change, it is offered instead
    report = held(campus, registry, plan, "the ego rolls at 4 m/s and slides into the left lane at 6 s")
    assert report.question is not None and "lane_change" in str([r.calls for r in report.question.readings])


def test_a_distance_a_storyboard_leaves_out_is_refused(campus, registry):
    plan = Fixed(call("add_manoeuvre", actor="ego", manoeuvre={"kind": "stop", "rate": 4.0}))
    report = held(campus, registry, plan, "the test needs a car standing still in the ego's lane 35 m ahead")
    assert "35" in (report.error or "")


def test_someones_thing_set_to_do_something_is_never_a_new_one(campus, registry):
    session = ruled(campus, registry, "put a pedestrian by the fountain")
    session.planner = Fixed(add("pedestrian"))
    before = session.scene
    report = session.submit("have my guy wander off somewhere else")
    assert not report.ok and session.scene == before
    assert "your pedestrian" in (report.error or "")


def test_a_thing_lost_to_the_eye_is_made_to_stand_out_never_removed(campus, registry):
    session = ruled(campus, registry, "paint the bench green", "hmm, now it blends into the grass")
    bench = session.scene.asset("bench_1")
    assert bench is not None and bench.appearance.rgba is not None and bench.appearance.rgba[0] > 0.5  # orange, not green
    assert ruled(campus, registry, "make the bench vanish").scene.asset("bench_1") is None  # a vanishing asked for still removes


def test_a_dark_colour_is_no_dark_and_when_a_thing_is_hard_to_see_is_no_time_asked(campus, registry):
    session = ruled(campus, registry, "paint the SUV black", "that dark colour makes it hard to see at night, change it")
    assert session.scene.environment.time_of_day == campus.environment.time_of_day
    suv = session.scene.asset("suv_1")
    assert suv is not None and suv.appearance.rgba is not None and suv.appearance.rgba[0] > 0.5
    assert ruled(campus, registry, "make it dark").scene.environment.time_of_day != campus.environment.time_of_day


def test_a_number_of_things_is_some_of_them_not_a_count_asked(campus, registry):
    added = ruled(campus, registry, "set out a decent number of bollards in a line at the Engineering Hall entrance").scene
    assert added.count("bollard") >= 2
    report = Session(campus, RulePlanner(), registry).submit("number of benches?")
    assert report.ok and "bench(s) found" in (report.answer or "")


def test_a_drive_to_a_place_with_a_manner_said_between_still_goes_there(campus, registry):
    session = ruled(campus, registry, "let passenger car 1 drive gently to the Library entrance")
    car, goal = session.scene.asset("passenger_car_1"), session.scene.landmark("Library entrance")
    assert car is not None and goal is not None and car.behaviour.kind == "follow_path"
    assert abs(car.behaviour.waypoints[-1][0] - goal.position[0]) + abs(car.behaviour.waypoints[-1][1] - goal.position[1]) < 10.0


def test_the_ones_who_wait_or_want_are_the_setting_never_added(campus, registry):
    report = held(campus, registry, Fixed(add("pedestrian", location={"relation": "at", "target": "Student Union entrance"})),
                  "students always wait outside the Student Union and the only bench is far away at the bus stop")
    assert "only as the setting" in (report.error or "")
    # asked for, they are added
    session = Session(campus, Fixed(add("pedestrian", location={"relation": "at", "target": "fountain"})), registry)
    assert session.submit("add a pedestrian at the fountain, students wait there").ok


def test_a_setting_named_with_its_value_is_set_not_asked_about(campus, registry):
    assert ruled(campus, registry, "time 18:15").scene.environment.time_of_day == "18:15"
    report = Session(campus, RulePlanner(), registry).submit("weather and time?")
    assert report.ok and "time of day: 12:00" in (report.answer or "")


def test_what_lies_between_two_places_is_refused_saying_what_can_be_asked(campus, registry):
    report = held(campus, registry, Fixed(call("find_landmarks", nearest_to="fountain", query="library")),
                  "anything standing between the library and the fountain?")
    assert "between two places" in (report.error or "") and "measure the distance" in (report.error or "")
    asked = Session(campus, RulePlanner(), registry).submit("how far apart are the bench and the bin? the distance between them")
    assert asked.ok and "m in a straight line" in (asked.answer or "")


def test_a_described_one_after_an_addition_is_one_more_of_it(campus, registry):
    session = ruled(campus, registry, "add a red car in lot A", "add a blue one next to it")
    assert session.scene.count("passenger_car") == campus.count("passenger_car") + 2
    newest = session.scene.asset("passenger_car_4")
    assert newest is not None and newest.appearance.rgba is not None and newest.appearance.rgba[2] > 0.5  # blue
    red = session.scene.asset("passenger_car_3")
    assert red is not None and red.appearance.rgba is not None and red.appearance.rgba[0] > 0.5  # still red


def test_the_first_one_after_one_more_is_the_earlier_one(campus, registry):
    session = ruled(campus, registry, "add a car in lot A", "and another one next to it", "move the first one 2 m north")
    first, second = session.scene.asset("passenger_car_3"), session.scene.asset("passenger_car_4")
    assert first is not None and second is not None
    assert abs(first.pose.y - ruled(campus, registry, "add a car in lot A").scene.asset("passenger_car_3").pose.y - 2.0) < 0.01


def test_what_is_kept_said_first_is_excepted_from_the_rest(campus, registry):
    report = held(campus, registry, Fixed(call("remove_assets", assets=["tree_2"])),
                  "leave the trees, clear everything else around the fountain")
    assert "not the trees" in (report.error or "")
    session = ruled(campus, registry, "keep the bench, get rid of the rest of the stuff at the bus stop")
    assert session.scene.asset("bench_1") is not None and session.scene.asset("trash_bin_1") is None


def test_dialect_and_learner_forms_read_as_meant(campus, registry):
    # "them" for "those" before things; "feets" as feet; "forth" before where a drive goes; "so much" snow is heavy
    session = ruled(campus, registry, "chuck four bollards at the Library", "them bollards want to be in a ring round the hydrant")
    assert session.scene.count("bollard") == 4
    spaced = ruled(campus, registry, "put 5 cones in a line at the bus stop, 10 feets apart").scene
    xs = sorted((a.pose.x, a.pose.y) for a in spaced.assets if a.category == "traffic_cone")
    assert abs(((xs[1][0] - xs[0][0]) ** 2 + (xs[1][1] - xs[0][1]) ** 2) ** 0.5 - 3.05) < 0.1
    assert ruled(campus, registry, "the SUV rides forth to the Library").scene.asset("suv_1").behaviour.kind == "follow_path"
    assert ruled(campus, registry, "back home the snow is so much in winter, make it like that").scene.environment.weather.intensity >= 0.75


def test_a_polite_might_asks_for_the_change(campus, registry):
    ego = ruled(campus, registry, "might the ego proceed a little more gently?").scene.ego
    assert ego is not None and ego.behaviour.speed < campus.ego.behaviour.speed


def test_what_a_walk_is_for_is_its_setting(campus, registry):
    session = ruled(campus, registry, "add a man at the Library entrance")
    session.planner = Fixed(add("bus", behaviour={"kind": "drive_lane"}))
    before = session.scene
    report = session.submit("he has to walk to the bus stop to catch the bus")
    assert not report.ok and session.scene == before and "setting" in (report.error or "")


def test_a_short_slip_before_a_things_number_names_that_thing(campus, registry):
    moved = ruled(campus, registry, "tre 4 now stands beside the fountain").scene.asset("tree_4")
    fountain = campus.landmark("fountain")
    assert moved is not None and fountain is not None
    assert abs(moved.pose.x - fountain.position[0]) + abs(moved.pose.y - fountain.position[1]) < 6.0
    report = Session(campus, RulePlanner(), registry).submit("move tre 9 north")  # no tree_9: no guess
    assert not report.ok and "'tre'" in (report.error or "")


def test_which_lane_asked_after_the_thing_is_the_lane_asked(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("the ego is on which lane now?")
    assert report.ok and "main_eastbound on Main Street" in (report.answer or "")


def test_a_time_said_after_the_second_step_is_the_second_steps(campus, registry):
    from drivetwin.orchestrator.planning import PlanContext
    from drivetwin.orchestrator.planning.scenario_reading import ScenarioReader

    plan = ScenarioReader().plan("the ego cruises at 7 m/s and slides into the left lane after 5 s", PlanContext(scene=campus, registry=registry))
    # the steady speed it opens on is the lane behaviour's, set now (see test_absent_subjects_and_unread_ways.py)
    assert [c.tool for c in plan.calls] == ["set_behaviour", "add_manoeuvre"]
    assert plan.calls[0].args["behaviour"] == {"kind": "drive_lane", "lane": "main_eastbound", "speed": 7.0}
    assert plan.calls[1].args["manoeuvre"]["kind"] == "lane_change" and plan.calls[1].args["at_time"] == 5.0


def test_banished_or_ripped_out_is_removed_and_a_bright_colour_is_no_daylight(campus, registry):
    assert ruled(campus, registry, "rip out the fire hydrant").scene.count("fire_hydrant") == campus.count("fire_hydrant") - 1
    assert ruled(campus, registry, "banish the bench from the bus stop").scene.asset("bench_1") is None
    bench = ruled(campus, registry, "give the bench some bright colour").scene.asset("bench_1")
    assert bench is not None and bench.appearance.rgba is not None
    report = Session(campus, RulePlanner(), registry).submit("the bench needs a bright color")
    assert not (report.ok and report.plan is not None and any(c.tool == "set_time_of_day" for c in report.plan.calls))


def test_most_far_is_furthest(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("which tree is the most far from the bus stop?")
    assert report.ok and (report.answer or "").startswith("furthest tree from bus stop")


def test_how_far_after_a_route_said_is_the_routes_length(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("My son strolls from the bus stop to the library each day. How long is that?")
    assert report.ok and "from bus stop to Library entrance" in (report.answer or "")


def test_every_other_one_is_half_and_each_where_the_other_is_is_a_swap(campus, registry):
    lamps = campus.count("street_light")
    assert ruled(campus, registry, "take away every other street light").scene.count("street_light") == lamps - lamps // 2
    assert ruled(campus, registry, "too many street lights, leave every other one").scene.count("street_light") == lamps - lamps // 2
    swapped = ruled(campus, registry, "put the bin where the bench is and the bench where the bin is").scene
    bench, bin_ = campus.asset("bench_1"), campus.asset("trash_bin_1")
    assert (swapped.asset("trash_bin_1").pose.x, swapped.asset("bench_1").pose.x) == (bench.pose.x, bin_.pose.x)


def test_a_thing_that_should_not_be_on_the_sidewalk_never_goes_onto_one(campus, registry):
    from drivetwin.worlds.surface import surface_at

    session = Session(campus, RulePlanner(), registry)
    session.submit("the hydrant shouldn't be on the sidewalk")  # it had been moved onto another sidewalk
    hydrant = session.scene.asset("fire_hydrant_1")
    assert hydrant is not None
    assert session.scene == campus or surface_at(session.scene, hydrant.pose.x, hydrant.pose.y) != "sidewalk"


def test_a_tickets_criteria_say_what_to_build_under_a_few_word_heading(campus, registry):
    session = ruled(campus, registry, "Title: barrier row / Acceptance: 3 road barriers, one line, 2 m spacing, in parking lot A")
    assert session.scene.count("road_barrier") == 3
    moved = ruled(campus, registry, "Summary: shift bench_1 / Expected: bench stands at the Student Union entrance").scene.asset("bench_1")
    union = campus.landmark("Student Union entrance")
    assert moved is not None and union is not None
    assert abs(moved.pose.x - union.position[0]) + abs(moved.pose.y - union.position[1]) < 6.0
