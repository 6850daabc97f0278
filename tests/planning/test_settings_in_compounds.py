"""Settings asked for beside other requests, tried in this file's own words on the packaged campus
world: a removal in one clause does not make the weather of the next one unwanted ("take the bin
away and let it drizzle"); lamps "switched on" or "turned off" are the lights setting, never new
lamps nor a turn at the junction; a slip in a setting's own name ("intensty", "exposre") is
repaired to that name, so its figure is used; a clock time written with a colon is the time of
day whatever words stand round it ("07:40, misty")."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.planning.scenario_reading import describes_behaviour_over_time


def test_a_removal_in_one_clause_leaves_the_weather_of_the_next_wanted(session):
    report = session.submit("Take the trash bin away and let it drizzle.")
    assert report.ok, report.error
    assert session.scene.count("trash_bin") == 0
    assert session.scene.environment.weather.kind == "rain"


def test_weather_said_as_unwanted_is_still_never_set(session):
    session.submit("Make it snow.")
    report = session.submit("We don't want snow any more, thanks.")
    assert report.ok, report.error
    assert session.scene.environment.weather.kind != "snow"


@pytest.mark.parametrize(("prompt", "state"), [("Could we have the street lamps switched on while it hails?", "on"),
                                               ("I'd like the lamp posts turned off, please.", "off")])
def test_lamps_switched_on_or_off_are_the_lights_setting(session, prompt, state):
    lamps = session.scene.count("street_light")
    report = session.submit(prompt)
    assert report.ok, report.error
    assert session.scene.count("street_light") == lamps  # none added, none taken away
    assert session.scene.environment.lighting.street_lights == state


def test_lamps_turned_off_are_no_turn_at_the_junction_but_turning_off_at_it_is():
    assert not describes_behaviour_over_time("I'd like the lamp posts turned off, please.")
    assert describes_behaviour_over_time("The ego should turn off left at the junction after 3 seconds.")


@pytest.mark.parametrize(("prompt", "field", "value"), [("snow, intensty 0.35", "intensity", 0.35),
                                                         ("exposre 2.5 please", "exposure", 2.5)])
def test_a_slip_in_a_settings_name_is_repaired_to_it(session, prompt, field, value):
    report = session.submit(prompt)
    assert report.ok, report.error
    env = session.scene.environment
    said = env.weather.intensity if field == "intensity" else env.lighting.exposure
    assert said == pytest.approx(value)


@pytest.mark.parametrize("prompt", ["07:40, misty.", "Reproduce the log conditions: 07:40 and misty."])
def test_a_clock_time_with_a_colon_is_the_time_whatever_surrounds_it(session, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert session.scene.environment.time_of_day == "07:40"
    assert session.scene.environment.weather.kind == "fog"


@pytest.mark.parametrize("prompt", ["Cut down the big tree, the one south-east of the fountain.",
                                    "cut down the tree southeast of the fountain"])
def test_a_thing_told_apart_by_a_point_between_two_compass_points(session, prompt):
    fountain = session.scene.landmark("fountain")
    assert fountain is not None
    trees = {a.id: a for a in session.scene.assets if a.category == "tree"}
    meant = [i for i, a in trees.items() if a.pose.x > fountain.position[0] and a.pose.y < fountain.position[1]]
    assert len(meant) == 1  # the world has one tree that way of the fountain
    report = session.submit(prompt)
    assert report.ok, report.error
    gone = set(trees) - {a.id for a in session.scene.assets if a.category == "tree"}
    assert gone == set(meant)  # that one alone, not the one nearest the fountain


def test_the_one_after_a_comma_says_which_and_the_one_after_and_says_another(session):
    session.submit("Put a cone at the main gate.")
    session.submit("Put a cone at the east gate.")
    report = session.submit("Take away the cone, the one by the east gate.")
    assert report.ok, report.error
    assert session.scene.count("traffic_cone") == 1  # one request about one cone, not two removals
    session.submit("Put a cone at the east gate.")
    report = session.submit("take away the cone at the main gate and the one at the east gate")
    assert report.ok, report.error
    assert session.scene.count("traffic_cone") == 0


def test_a_thing_that_has_to_come_out_is_removed(session):
    report = session.submit("The tree between the bus stop and the Library has to come out.")
    assert report.ok, report.error
    assert "tree_1" not in {a.id for a in session.scene.assets}  # the one between them (-26, -12)
    assert session.scene.count("tree") == 3


def _row_of_cars(scene):
    return sorted((a for a in scene.assets if a.category in ("passenger_car", "suv")), key=lambda a: a.pose.x)


@pytest.mark.parametrize("prompt", ["Get rid of the car in the middle of the row.",
                                    "Take away the car closest to the union building and the one in the middle of the row."])
def test_the_middle_one_of_a_row_is_the_one_between_the_others(session, prompt):
    row = _row_of_cars(session.scene)
    assert len(row) == 3 and max(a.pose.x for a in row) - min(a.pose.x for a in row) < 20  # lot B's row
    report = session.submit(prompt)
    assert report.ok, report.error
    assert row[1].id not in {a.id for a in session.scene.assets}  # an SUV is a car too


def test_no_middle_one_where_the_things_stand_in_no_row(session):
    report = session.submit("Chop down the middle tree.")
    assert not report.ok
    assert session.scene.count("tree") == 4  # the four trees are spread over the campus: none taken at random


@pytest.mark.parametrize("prompt", ["Have passenger_car_2 drive to the lot B entrance.",
                                    "have the sedan closest to the union drive out to the lot B entrance"])
def test_a_car_driving_to_a_place_part_way_along_a_lane_stops_there(session, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    car = session.scene.asset("passenger_car_2")
    entrance = session.scene.landmark("parking lot B entrance")
    assert car is not None and entrance is not None
    assert car.behaviour.kind == "follow_path"  # driving main_eastbound would take it on past the entrance
    gx, gy = car.behaviour.waypoints[-1]
    assert abs(gx - entrance.position[0]) < 3 and abs(gy - entrance.position[1]) < 3


# --- the words of people texting and of learners of English ---------------------------------------


def test_n_between_two_requests_is_and(session):
    report = session.submit("take the bench away n make it snow")
    assert report.ok, report.error
    assert session.scene.count("bench") == 0
    assert session.scene.environment.weather.kind == "snow"


@pytest.mark.parametrize(("prompt", "faster"), [("the test car, more quick please", True), ("make our car more slow", False)])
def test_a_comparative_said_with_more_is_that_comparative(session, prompt, faster):
    ego = session.scene.ego
    assert ego is not None and ego.behaviour.speed is not None
    before = ego.behaviour.speed
    report = session.submit(prompt)
    assert report.ok, report.error
    after = session.scene.ego
    assert after is not None and after.behaviour.speed is not None
    assert (after.behaviour.speed > before) if faster else (after.behaviour.speed < before)


def test_a_name_said_head_first_is_that_name(session):
    report = session.submit("Put two barriers in a line at the JTEKT entrance, and a sign of road works in front of them.")
    assert report.ok, report.error
    assert session.scene.count("construction_sign") == 1  # not left out as words with no thing in them
    report = session.submit("Move the car of test 5 metres forward.")
    assert report.ok, report.error
    assert report.plan is not None and [c.args.get("asset") for c in report.plan.calls] == ["ego"]


@pytest.mark.parametrize("prompt", ["Park the player car in lot B.", "Take the hero car to lot B."])
def test_the_car_a_game_or_film_is_about_is_the_ego(session, prompt):
    cars = session.scene.count("passenger_car")
    report = session.submit(prompt)
    assert report.ok, report.error
    ego = session.scene.ego
    lot = session.scene.landmark("parking lot B")
    assert ego is not None and lot is not None and session.scene.count("passenger_car") == cars
    assert abs(ego.pose.x - lot.position[0]) < 15 and abs(ego.pose.y - lot.position[1]) < 15


def test_headlights_said_after_and_are_switched_too(session):
    report = session.submit("Our car: a bit quicker, and its headlights on.")
    assert report.ok, report.error
    assert session.scene.environment.lighting.vehicle_lights == "on"


def test_a_plan_taking_away_more_than_one_of_the_things_said_is_never_applied(context):
    from drivetwin.orchestrator.planning.base import Plan
    from drivetwin.orchestrator.planning.check import review
    from drivetwin.tools.base import ToolCall

    every = Plan(calls=[ToolCall(tool="remove_assets", args={"category": "traffic_light"})], planner="test", confidence=0.95)
    verdict = review("get rid of one of the traffic lights, any of them", every, context)
    assert verdict.action != "apply" and any("1 traffic light" in p for p in verdict.problems)  # not applied as it stands
    one = Plan(calls=[ToolCall(tool="remove_assets", args={"category": "traffic_light", "count": 1})], planner="test", confidence=0.95)
    assert review("get rid of one of the traffic lights, any of them", one, context).action == "apply"


def test_a_place_with_a_slip_in_it_is_read_as_the_place_typed_right(session):
    report = session.submit("add a persn on the pavment at the west crosing")
    assert report.ok, report.error
    (walker,) = [a for a in session.scene.assets if a.category == "pedestrian"]
    crossing = session.scene.landmark("west crosswalk")
    assert crossing is not None
    assert abs(walker.pose.x - crossing.position[0]) < 6 and abs(walker.pose.y - crossing.position[1]) < 8


def test_the_scene_misspelt_is_the_scene_not_a_number(session):
    report = session.submit("remov the bus stop bench from the sceen")
    assert report.ok, report.error
    assert session.scene.count("bench") == 0


def test_a_thing_numbered_in_words_after_its_name_is_that_one(session):
    report = session.submit("Please, the car two must drive in the westbound lane at 5 metres per second.")
    assert report.ok, report.error  # no question which car: the words say the second
    car = session.scene.asset("passenger_car_2")
    assert car is not None and car.behaviour.kind == "drive_lane" and car.behaviour.speed == pytest.approx(5.0)


def test_a_clock_time_with_stops_in_it_does_not_end_the_sentence(session):
    report = session.submit("For the school-run study, make it 8 a.m. and have the ego drive at 4 m/s.")
    assert report.ok, report.error
    assert session.scene.environment.time_of_day == "08:00"
    ego = session.scene.ego
    assert ego is not None and ego.behaviour.speed == pytest.approx(4.0)


@pytest.mark.parametrize("verb", ["Teleport", "Move"])
def test_a_second_place_named_asks_nothing_of_its_words(session, verb):
    report = session.submit(f"{verb} the ego between the bus stop and the west crossing.")
    assert report.ok, report.error
    ego = session.scene.ego
    stop, crossing = session.scene.landmark("bus stop"), session.scene.landmark("west crosswalk")
    assert ego is not None and stop is not None and crossing is not None
    assert ego.behaviour.kind != "parked"  # the stop of "bus stop" is no stop to make
    assert min(stop.position[0], crossing.position[0]) < ego.pose.x < max(stop.position[0], crossing.position[0])


def test_what_someone_cannot_do_is_the_reason_not_a_request(session):
    people = session.scene.count("pedestrian")
    report = session.submit("Fewer trees, please; the pupils can't see the road.")
    assert report.ok, report.error
    assert session.scene.count("tree") < 4 and session.scene.count("pedestrian") == people  # no pupils added


def test_all_three_said_after_the_things_are_those_things(session):
    report = session.submit("The vehicles parked in lot B are not in the claim; take all three out.")
    assert report.ok, report.error
    assert not [a for a in session.scene.assets if a.category in ("passenger_car", "suv")]


def test_where_a_thing_is_says_the_place_it_stands_in(session):
    report = session.submit("The SUV, where it is?")
    assert report.ok, report.error
    assert report.answer is not None and "suv_1" in report.answer and "in parking lot B" in report.answer


def test_a_walker_at_a_crossing_going_over_to_the_other_side_crosses(session):
    session.submit("Stand a person at the north end of the west crosswalk.")
    report = session.submit("Now have the person at the west crossing go over to the other side.")
    assert report.ok, report.error
    (walker,) = [a for a in session.scene.assets if a.category == "pedestrian"]
    assert walker.behaviour.kind == "cross_road"  # not put down where it already stands


@pytest.mark.parametrize("prompt", ["put cones in a circle round the main gate, six-ish", "Cones in a ring around the main gate please, 6 of them."])
def test_an_amount_said_roughly_or_after_the_thing_is_its_count(session, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert session.scene.count("traffic_cone") == 6


def test_another_row_like_that_repeats_the_last_layout_where_said(session):
    assert session.submit("Park three cars side by side in lot A.").ok
    cars = session.scene.count("passenger_car")
    report = session.submit("now add another row like that in lot B")
    assert report.ok, report.error
    assert session.scene.count("passenger_car") == cars + 3  # the row again, not one more car


def test_how_many_of_them_after_a_colon_counts_the_things_before_it(context):
    from drivetwin.orchestrator.planning.rules.planner import RulePlanner

    plan = RulePlanner().plan("The children will queue to cross: five of them in a row by the bus stop.", context)
    assert [(c.tool, c.args.get("count")) for c in plan.calls] == [("arrange_assets", 5)]
    assert plan.calls[0].args["categories"] == ["pedestrian"]  # not the sentence before read as three walkers
