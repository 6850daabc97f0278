"""Readings of one round, each worded unlike any suite prompt: whether a state holds asked inside a
sentence ("confirm whether it is raining") is answered, never set; weather complained of is made
lighter; a strength said alone after the weather is its strength; a word run together with a letter
the two share; who is parked is the cars; a walker sent across with the thing between verb and
particle."""

from __future__ import annotations

import math

from drivetwin.orchestrator.planning.intent import asks
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from misreading import Fixed, add, call, held, ruled  # this folder is on sys.path (no __init__.py)


def test_whether_the_weather_is_so_is_looked_at_not_set(campus, registry):
    for said in ("Could you confirm wether it is snowing at the moment?", "check if it's foggy out", "see if it is night yet",
                 "I want to know is it snowing", "Verify whether the weather is snowy"):
        session = Session(campus, RulePlanner(), registry)
        report = session.submit(said)
        assert report.ok and report.answer is not None and "weather: clear" in report.answer, said
        assert session.scene.environment == campus.environment, said
    assert not asks("see if you can move the bench to the fountain")


def test_a_question_after_knowing_with_its_to_left_out(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("my supervisor wants know if the bus is parked")
    assert report.ok and report.answer is not None
    assert [a.id for a in session.scene.assets] == [a.id for a in campus.assets]  # no bus added


def test_weather_said_to_be_too_much_is_made_lighter(campus, registry):
    for setup, said in (("thick fog please", "ugh, it's far too foggy now"), ("heavy rain", "the rain feels way too heavy")):
        before = ruled(campus, registry, setup).scene.environment.weather
        after = ruled(campus, registry, setup, said).scene.environment.weather
        assert after.kind == before.kind and after.intensity < before.intensity, said
    assert ruled(campus, registry, "fog please", "ok that fog can be switched off now").scene.environment.weather.kind == "clear"


def test_a_strength_said_alone_after_the_weather(campus, registry):
    assert ruled(campus, registry, "Let it snow. Heavy please.").scene.environment.weather.intensity > 0.8
    assert ruled(campus, registry, "Bring in some mist! Thin.").scene.environment.weather.intensity < 0.4


def test_words_run_together_with_a_letter_they_share(campus, registry):
    scene = ruled(campus, registry, "drop a bin beside the bustop").scene
    bins = [a for a in scene.assets if a.category == "trash_bin" and campus.asset(a.id) is None]
    stop = next(lm for lm in campus.landmarks if lm.name == "bus stop")
    assert len(bins) == 1 and abs(bins[0].pose.x - stop.position[0]) < 10 and abs(bins[0].pose.y - stop.position[1]) < 10


def test_who_is_parked_asks_about_the_cars(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("who's parked over in lot B right now?")
    assert report.ok and report.answer is not None and "suv_1" in report.answer


def test_a_walker_sent_across_with_the_walker_between_verb_and_particle(campus, registry):
    scene = ruled(campus, registry, "walk two pedestrians over the road at the west crosswalk").scene
    walkers = [a for a in scene.assets if a.category == "pedestrian"]
    assert len(walkers) == 2 and all(a.behaviour is not None and a.behaviour.kind == "cross_road" for a in walkers)


def test_doubt_about_what_is_so_is_answered_not_acted_on(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    for said in ("we were wondering whether there's a hydrant anywhere by the crossroads",
                 "I really can't recall if we left the SUV in lot A", "not certain if the bench is still at the bus stop"):
        report = session.submit(said)
        assert report.ok and report.answer is not None, said
    assert session.scene == campus  # nothing added or moved
    assert not asks("I was wondering if you could add a bench by the fountain")
    report = Session(campus, RulePlanner(), registry).submit("remind me again which lane the ego drives in")
    assert report.ok and report.answer is not None and "main_eastbound" in report.answer


def test_a_thing_sent_elsewhere_is_never_sent_to_the_place_it_is_said_to_block(campus, registry):
    for said in ("the tree by the bus stop completely hides the Library from the road, can it be somewhere else?",
                 "the bench sits right in front of the Library entrance, get it out of the way"):
        session = Session(campus, RulePlanner(), registry)
        session.submit(said)
        moved = [a for a in session.scene.assets if (b := campus.asset(a.id)) is not None and a.pose != b.pose]
        entrance = next(lm for lm in campus.landmarks if lm.name == "Library entrance").position
        for a in moved:  # whatever was done, nothing went nearer the place it blocks
            before = campus.asset(a.id)
            assert before is not None
            assert math.dist((a.pose.x, a.pose.y), entrance[:2]) >= math.dist((before.pose.x, before.pose.y), entrance[:2]) - 0.5, said
    moved = ruled(campus, registry, "the bench is an eyesore, put it elsewhere, maybe by the fountain").scene.asset("bench_1")
    fountain = next(lm for lm in campus.landmarks if lm.name == "fountain").position
    assert moved is not None and math.dist((moved.pose.x, moved.pose.y), fountain[:2]) < 15


def test_who_keeps_doing_it_is_the_trouble_never_what_is_added(campus, registry):
    report = held(campus, registry, Fixed(add("pedestrian", count=4, location={"relation": "at", "target": "parking lot A"})),
                  "students are always wandering across lot A, can we put a stop to it")
    assert "trouble" in (report.error or (report.question.text if report.question else ""))


def test_things_counted_as_known_are_those_there_even_in_a_layout(campus, registry):
    row = Fixed(call("arrange_assets", categories=["passenger_car"], count=3, shape="line",
                     location={"relation": "at", "target": "parking lot B"}))
    report = held(campus, registry, row, "the three lot B cars should stand in one straight line instead")
    assert "already there" in (report.error or (report.question.text if report.question else ""))


def test_a_thing_a_side_is_taken_from_is_where_not_what(campus, registry):
    scene = ruled(campus, registry, "make the car on the left of the SUV yellow").scene
    painted = [a.id for a in scene.assets if a.appearance != (campus.asset(a.id) or a).appearance]
    assert painted == ["passenger_car_1"]  # the SUV faces north: its left is the car west of it


def test_is_there_a_way_to_do_it_asks_for_it_done(campus, registry):
    assert not asks("is there any way to make the ego a different colour?")
    assert asks("is there a way to find out where the bus is?")
    session = ruled(campus, registry, "thick fog please", "is there any way to get rid of the fog?")
    assert session.scene.environment.weather.kind == "clear"


def test_a_headcount_and_a_tag_question_ask(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("could you give me a quick headcount of the benches")
    assert report.ok and report.answer is not None and "bench_1" in report.answer
    report = session.submit("the bench is still by the bus stop, isn't it?")
    assert report.ok and report.answer is not None
    assert session.scene == campus
