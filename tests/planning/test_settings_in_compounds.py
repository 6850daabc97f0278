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
