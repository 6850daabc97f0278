"""Worded here, or as practice38 words it after it was measured unseen (never the held-out suite): a thing a clause
is said of ("the bus should drive more carefully", "might the bus be in lot B?") that the scene does not have is
asked about, never added, while a role ("the lead car") still brings one in; a step's way said and not read ("3
metres est", "well away from it") is asked, never guessed; "where the tree is" with several trees is refused; a
story that opens on a steady speed sets the lane behaviour's speed ("and let it ..." a later step, a junction turn
at the junction); "the ego cycles" is a verb; an off-mood retrieval reading is no offer; "except tree 3" spares it;
hail, dust and weather moved to one place are refused; hyphened names, "every one of them", "by about half", "the
5-second mark"; the clock asked as "wah time it is"; a hedged suggestion after a statement; things said bare then
said back are those there; labels (cue 12, step 1), an ellipsis, exposure down to a value, "cloudly"; a measure
asked is no thing; "from A to B, in metres"; a move from one place to another; the driver's "us", "ease off",
"hold it"; "one of cars", "and one bench"; what stays said as how it is; a sign-off particle; people named by
their part; "too much forward" is a way out of place; a place said with a facing it already has; no pattern word hides a
place's name."""

from __future__ import annotations

import math

import pytest
from drivetwin.orchestrator.planning import PlanContext
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.planning.scenario_reading import ScenarioReader
from drivetwin.orchestrator.session import Session
from drivetwin.worlds.scene import DriveLane
from misreading import ruled  # this folder is on sys.path (no __init__.py)


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


def test_one_named_by_its_number_after_except_is_spared(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    assert session.submit("remove all the trees except tree 3").ok
    assert [a.id for a in session.scene.assets if a.category == "tree"] == ["tree_3"]
    # a kind not read ("tress"): tree 3 is never the one removed
    typo = Session(campus, RulePlanner(), registry)
    report = typo.submit("Remove all the tress exept tree 3.")
    assert typo.scene.asset("tree_3") is not None, report.plan.calls if report.plan else None


def test_weather_this_world_cannot_make_or_put_in_one_place_is_refused(campus, registry):
    for said in ("make a hail storm, please", "give us a dust storm", "nudge that rain cloud over towards the east gate"):
        session = Session(campus, RulePlanner(), registry)
        report = session.submit(said)
        assert not report.ok and session.scene == campus, said
    assert "hail" in (Session(campus, RulePlanner(), registry).submit("make a hail storm, please").error or "")
    stormy = Session(campus, RulePlanner(), registry)
    assert stormy.submit("make it a thunderstorm").ok and stormy.scene.environment.weather.kind == "rain"
    poured = Session(campus, RulePlanner(), registry)
    assert poured.submit("make it like the monsoon, it should pour").ok and poured.scene.environment.weather.intensity >= 0.75


def test_hyphened_names_every_one_of_them_and_about_half(campus, registry):
    session = ruled(campus, registry, "add a trash-bin by the library")
    assert session.scene.count("trash_bin") == campus.count("trash_bin") + 1
    assert ruled(campus, registry, "add 3 cones at the Library entrance", "throw every one of them out").scene.count("traffic_cone") == 0
    assert ruled(campus, registry, "set 8 barriers in lot A", "reduce the barriers by about half").scene.count("road_barrier") == 4


def test_well_away_is_a_long_way_and_away_from_what_was_not_read_is_asked(campus, registry):
    hydrant = campus.asset("fire_hydrant_1")
    assert hydrant is not None
    moved = ruled(campus, registry, "move the hydrant well away from the junction").scene.asset("fire_hydrant_1")
    assert moved is not None and math.dist((moved.pose.x, moved.pose.y), (hydrant.pose.x, hydrant.pose.y)) >= 9
    session = Session(campus, RulePlanner(), registry)  # "it" is the junction, said in the clause before
    report = session.submit("the hydrant's too close to the junction - shift it somewhere well away from it")
    assert report.question is not None and session.scene == campus


def test_the_clock_asked_in_any_spelling_and_a_hedged_suggestion_after_a_statement(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("Wah time it is inna di scene right now?")
    assert report.ok and "12:00" in (report.answer or "")
    people = ruled(campus, registry, "the bus stop looks lonely - maybe a couple of people waiting there?")
    assert people.scene.count("pedestrian") == campus.count("pedestrian") + 2
    asked = Session(campus, RulePlanner(), registry).submit("which car is nearest the fountain, maybe a sedan?")
    assert asked.ok and asked.plan is not None and all(c.tool == "find_assets" for c in asked.plan.calls)


def test_an_unknown_verb_after_a_dialect_article_adds_nothing(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    session.submit("Tek out di stop sign.")
    assert session.scene.count("stop_sign") <= campus.count("stop_sign")


def test_things_said_bare_then_said_of_as_they_are_are_those_there(campus, registry):
    session = ruled(campus, registry, "add 5 bollards at the JTEKT entrance")
    before = session.scene
    report = session.submit("put bollards in a row, they look messy")
    assert not (report.ok and session.scene.count("bollard") > before.count("bollard"))
    cars = ruled(campus, registry, "add a car in the ego's lane, 30 metres in front of it, going 2 m/s")
    count = cars.scene.count("passenger_car")
    cars.submit("Car in front make slower na.")
    assert cars.scene.count("passenger_car") == count


def test_steps_numbered_and_cues_are_labels_and_an_ellipsis_is_a_pause(campus, registry):
    session = ruled(campus, registry, "Step 1: remove passenger car 1. Step 2: remove the SUV.")
    assert session.scene.asset("passenger_car_1") is None and session.scene.asset("passenger_car_2") is not None
    assert session.scene.count("suv") == campus.count("suv") - 1
    lit = ruled(campus, registry, "LX cue 12: street lights on... go.")
    assert lit.scene.environment.lighting.street_lights == "on" and lit.scene.count("street_light") == campus.count("street_light")


def test_exposure_down_to_a_value_and_a_slipped_weather_word(campus, registry):
    assert ruled(campus, registry, "Exposure down to 0.6, it's too brigth.").scene.environment.lighting.exposure == 0.6
    assert ruled(campus, registry, "Make it cloudly please").scene.environment.weather.kind == "cloudy"


def test_a_measure_asked_is_no_thing_and_from_a_to_b_in_metres_is_a_distance(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("how many kilograms does the SUV weigh?")
    assert report.ok and "2100 kg" in (report.answer or "")
    report = Session(campus, RulePlanner(), registry).submit("from the bus stop to the fountain, in metres")
    assert report.ok and report.plan is not None and [c.tool for c in report.plan.calls] == ["measure_distance"]


def test_a_thing_moved_from_one_place_to_another_goes_to_the_second(campus, registry):
    bench = ruled(campus, registry, "move the bench from the bus stop to the fountain").scene.asset("bench_1")
    fountain = campus.landmark("fountain")
    assert bench is not None and fountain is not None
    assert math.dist((bench.pose.x, bench.pose.y), fountain.position) < 10


def test_the_drivers_us_ease_off_and_hold_it(campus, registry):
    slowed = ruled(campus, registry, "slow us down a bit").scene.asset("ego")
    assert slowed is not None and isinstance(slowed.behaviour, DriveLane) and slowed.behaviour.speed < 5.0
    held = ruled(campus, registry, "Us: 8 metres a second, hold it.").scene.asset("ego")
    assert held is not None and isinstance(held.behaviour, DriveLane) and held.behaviour.speed == 8.0
    eased = Session(campus, ScenarioReader(), registry).submit("ease off, we're carrying too much speed")
    assert eased.ok and eased.plan is not None and eased.plan.calls[0].args["manoeuvre"]["kind"] == "change_speed"


def test_a_turn_said_as_a_noun_and_a_speed_before_a_junction_turn(campus, registry):
    context = PlanContext(scene=campus, registry=registry)
    plan = ScenarioReader().plan("right turn at the junction for the ego", context)
    assert [(c.tool, c.args["manoeuvre"]) for c in plan.calls] == [("add_manoeuvre", {"kind": "junction_turn", "turn": "right"})]
    plan = ScenarioReader().plan("Ego, stand by: four metres a second, then turn right at the junction. Go.", context)
    assert [c.tool for c in plan.calls] == ["set_behaviour", "add_manoeuvre"] and plan.calls[0].args["behaviour"]["speed"] == 4.0
    assert "after_previous" not in plan.calls[1].args  # the turn comes at the junction
    # a brake after a cruise still waits for it
    plan = ScenarioReader().plan("the ego cruises at 4 m/s and then brakes", context)
    assert plan.calls[-1].args.get("after_previous") is True
    plan = ScenarioReader().plan("Ego: reduce speed to 2 m/s at t = 4 s", context)
    assert plan.calls[0].args["manoeuvre"]["kind"] == "change_speed" and plan.calls[0].args["at_time"] == 4.0


def test_weather_said_as_typed_is_judged_as_typed(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    assert not session.submit("Set the weather to a hailstorm.").ok and session.scene == campus


def test_one_of_them_said_without_an_article_and_one_more_after_and(campus, registry):
    session = ruled(campus, registry, "Remove one of cars from lot B, which one - no matter.")
    lot_b = [a for a in campus.assets if a.category in ("passenger_car", "suv")]
    assert len([a for a in session.scene.assets if a.category in ("passenger_car", "suv")]) == len(lot_b) - 1
    both = ruled(campus, registry, "put two trash bins at the east gate and one bench at the main gate")
    assert both.scene.count("bench") == campus.count("bench") + 1 and both.scene.asset("bench_1") == campus.asset("bench_1")
    moved = ruled(campus, registry, "move one bench to the main gate")
    assert moved.scene.count("bench") == campus.count("bench") and moved.scene.asset("bench_1") != campus.asset("bench_1")


def test_what_stays_said_as_how_it_is_is_kept(campus, registry):
    session = ruled(campus, registry, "Remove tree 1 and tree 4, other trees leave.")
    assert sorted(a.id for a in session.scene.assets if a.category == "tree") == ["tree_2", "tree_3"]
    lamp = ruled(campus, registry, "Remove the stop sign. Lamp stays.")
    assert lamp.scene.count("stop_sign") == 0 and lamp.scene.count("street_light") == campus.count("street_light")
    suv = ruled(campus, registry, "the other cars stay where they are, move the SUV to lot A")
    assert suv.scene.asset("passenger_car_1") == campus.asset("passenger_car_1")


def test_measure_one_thing_to_another_and_every_asset_near_a_place(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("Measure the bench to the bin.")
    assert report.ok and report.plan is not None and [c.tool for c in report.plan.calls] == ["measure_distance"]
    report = Session(campus, RulePlanner(), registry).submit("list every asset within 12 metres of the fountain")
    assert report.ok and report.plan is not None and report.plan.calls[0].tool == "find_assets"
    assert "category" not in report.plan.calls[0].args


def test_a_cue_after_an_ellipsis_and_a_sign_off_particle_change_nothing_more(campus, registry):
    session = ruled(campus, registry, "Stand by to add one motorcycle next to the Engineering Hall entrance... and go.")
    bike = next(a for a in session.scene.assets if a.category == "motorcycle")
    assert bike.behaviour.kind == "parked"  # "go" was the cue, not a drive
    lamps = ruled(campus, registry, "set the time to 21:00", "Now lamp on na, very dark.")
    assert lamps.scene.environment.lighting.street_lights == "on" and lamps.scene.count("street_light") == campus.count("street_light")
    kept = ruled(campus, registry, "Remove the SUV in lot B krub, car keep.")
    assert kept.scene.count("suv") == campus.count("suv") - 1 and kept.scene.count("passenger_car") == campus.count("passenger_car")


def test_people_named_by_their_part_and_a_time_said_as_a_mark(campus, registry):
    ring = ruled(campus, registry, "Give me a ring of extras around the ego.")
    assert ring.scene.count("pedestrian") >= campus.count("pedestrian") + 3
    assert ruled(campus, registry, "add a spectator by the fountain").scene.count("pedestrian") == campus.count("pedestrian") + 1
    plan = ScenarioReader().plan("At the 5-second mark, the ego comes to a stop.", PlanContext(scene=campus, registry=registry))
    assert plan.calls[0].args["manoeuvre"]["kind"] == "stop" and plan.calls[0].args["at_time"] == 5.0


def test_too_much_a_way_is_where_it_is_out_of_place_and_never_fewer(campus, registry):
    for said in ("the SUV is too much forward", "the bench is too much left"):
        session = Session(campus, RulePlanner(), registry)
        report = session.submit(said)
        assert not (report.ok and session.scene.count(said.split()[1].lower()) < campus.count(said.split()[1].lower())), said
    backed = ruled(campus, registry, "SUV is parked too much forward, need back it about 2 metre.").scene.asset("suv_1")
    suv = campus.asset("suv_1")
    assert backed is not None and suv is not None
    heading = (math.cos(suv.pose.yaw), math.sin(suv.pose.yaw))
    assert (backed.pose.x - suv.pose.x) * heading[0] + (backed.pose.y - suv.pose.y) * heading[1] == pytest.approx(-2.0, abs=0.1)


def test_a_place_said_with_a_facing_it_already_has_is_still_a_move(campus, registry):
    ego = ruled(campus, registry, "Start position: put us at x minus 90, y minus 1.75, eastbound lane, facing east.").scene.asset("ego")
    assert ego is not None and (ego.pose.x, ego.pose.y) == pytest.approx((-90.0, -1.75), abs=0.01)
    report = Session(campus, RulePlanner(), registry).submit("turn the ego to face east")
    assert not report.ok and "already faces east" in (report.error or "")


def test_no_word_the_planner_knows_hides_a_place_of_the_world(campus, registry):
    # every name and alias of every place is read as that place: a word of some pattern ("finish", "stop", "gate")
    # that swallowed part of a name would put the bench somewhere else (the scene's centre is a relation of its own)
    context = PlanContext(scene=campus, registry=registry)
    for place in campus.landmarks:
        for name in place.names():
            if name.lower().startswith("scene cent"):
                continue
            plan = RulePlanner().plan(f"add a bench at the {name}", context)
            assert [c.args["location"].get("target") for c in plan.calls] == [place.name], name
