"""A question about how the world is now ("is it raining?", "what's the weather like") is answered
with a description and sets nothing, while a wish said as a question ("bit of drizzle?") still
sets it; and a statement that names nothing before a command ("it's too dark, make it day") is
only the reason for it. The wording is this file's own, on the packaged campus world."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("prompt", ["what's the weather doing out there?", "is it snowing in the scene?",
                                    "so what time of day have we got", "how dark is it at the moment?"])
def test_a_question_about_the_settings_describes_them_and_sets_nothing(session, campus, prompt):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert [c.tool for c in report.plan.calls] == ["describe_environment"]
    assert "weather: clear" in (report.answer or "")
    assert session.scene.environment == campus.environment


def test_a_wish_asked_as_a_question_still_sets_it(session):
    report = session.submit("A touch of drizzle?")
    assert report.ok, report.error
    assert session.scene.environment.weather.kind == "rain"


@pytest.mark.parametrize(("prompt", "kind"), [("it's far too bright, give me some clouds", "cloudy"),
                                              ("this is dull, please make it snow", "snow")])
def test_a_statement_naming_nothing_before_a_command_is_its_reason(session, prompt, kind):
    report = session.submit(prompt)
    assert report.ok, report.error
    assert session.scene.environment.weather.kind == kind


def test_a_statement_naming_a_place_stays_with_the_command_that_means_it(session, campus):
    report = session.submit("main street feels deserted, make it livelier")
    assert report.ok, report.error
    added = [session.scene.asset(i) for i in session.memory.last_added()]
    assert added and all(a.behaviour is not None and a.behaviour.lane.startswith("main_") for a in added)
