"""Readings and checks of one round, continued, each worded unlike any suite prompt: weather switched
off as lamps are, "of" typed for "off", a lot named by the radio alphabet, articles left out, who a
request is for, a thing said to be by a place it already stands at, and plans that come to nothing."""

from __future__ import annotations

from drivetwin.orchestrator.planning.intent import asks
from drivetwin.orchestrator.planning.retrieval.slots import read_slots
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from misreading import Fixed, add, applied, call, held, ruled  # this folder is on sys.path (no __init__.py)


def test_weather_switched_off_is_clear_weather(campus, registry):
    for said in ("could you shut off the snow", "right, off the rain now", "switch the fog off now"):
        session = ruled(campus, registry, "heavy snow please" if "snow" in said else "make it rain" if "rain" in said else "thick fog", said)
        assert session.scene.environment.weather.kind == "clear", said
    # the slots the example bank is adapted by read it so too: "cancel the fog" is clear weather
    assert ("weather", "clear") in read_slots("cancel the fog please", campus).found
    assert ("weather", "fog") in read_slots("bring on the fog please", campus).found


def test_of_typed_for_off_after_what_switches(campus, registry):
    assert ruled(campus, registry, "lamps of thanks").scene.environment.lighting.street_lights == "off"
    report = Session(campus, RulePlanner(), registry).submit("what are the street lamps made of?")
    assert report.ok and report.answer is not None  # a question, nothing switched


def test_a_lot_named_by_the_radio_alphabet(campus, registry):
    scene = ruled(campus, registry, "two cones in lot bravo").scene
    cones = [a for a in scene.assets if a.category == "traffic_cone"]
    assert len(cones) == 2 and all(15 <= a.pose.x <= 62 and -46 <= a.pose.y <= -12 for a in cones)


def test_a_thing_said_without_articles_is_asked_about_not_added_anew(campus, registry):
    report = held(campus, registry, Fixed(add("suv")), "paint SUV green colour")
    said = report.error or (report.question.text if report.question else "")
    assert "already there" in said
    moved = ruled(campus, registry, "shift hydrant onto other side of street").scene
    assert moved.asset("fire_hydrant_1").pose.y < 0 < campus.asset("fire_hydrant_1").pose.y


def test_who_a_request_is_for_is_not_added(campus, registry):
    report = held(campus, registry, Fixed(add("pedestrian")), "my daughter's kid wants somewhere shady to sit by the fountain")
    assert "pedestrian" in (report.error or (report.question.text if report.question else ""))
    assert asks("my manager wants know whether the lamps are lit")


def test_plans_that_come_to_nothing_are_held(campus, registry):
    to_and_fro = Fixed(add("bench", location={"relation": "at", "target": "fountain"}), call("remove_assets", assets=["bench_2"]))
    report = held(campus, registry, to_and_fro, "sort the bench situation by the fountain")
    assert "takes it away again" in (report.error or "")
    report = held(campus, registry, Fixed(add("passenger_car", count=2)), "relocate those cars to lot A")
    assert "only adds" in (report.error or "")


def test_a_thing_by_the_place_it_is_said_to_be_at_is_not_moved_there(campus, registry):
    at_stop = Fixed(call("place_asset", asset="bench_1", location={"relation": "at", "target": "bus stop"}))
    report = held(campus, registry, at_stop, "that bench at the bus stop is rotten, do something about it")
    assert "already stands by bus stop" in (report.error or "")
    applied(campus, registry, Fixed(call("place_asset", asset="bench_1", location={"relation": "at", "target": "fountain"})),
            "take the bench over to the fountain")


def test_struck_as_a_set_is_struck(campus, registry):
    scene = ruled(campus, registry, "strike both the hydrant and the bin").scene
    assert scene.asset("fire_hydrant_1") is None and scene.asset("trash_bin_1") is None


def test_radio_words_the_station_called_and_numbers_digit_by_digit(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("Control, say position of the bench")
    assert report.ok and report.answer is not None and "bench_1" in report.answer
    scene = ruled(campus, registry, "three cones in a line across the eastbound lane, two-zero metres ahead of the ego").scene
    cones = [a for a in scene.assets if a.category == "traffic_cone"]
    ego = campus.asset("ego")
    assert len(cones) == 3 and all(abs(a.pose.x - (ego.pose.x + 20.0)) < 3.0 for a in cones)


def test_some_of_them_is_no_number_to_hold_a_removal_to(campus, registry):
    scene = ruled(campus, registry, "could you lose some of the cars").scene
    left = [a for a in scene.assets if a.category in ("passenger_car", "suv")]
    assert 0 < len(left) < 3


def test_a_wish_for_what_a_thing_could_do_is_a_request(campus, registry):
    assert not asks("maybe the bench could... sit over by the fountain?")
    assert not asks("i wonder if the suv could head to lot a?")
    assert asks("could the truck fit in lot a?")  # what it is able to do is asked
    scene = ruled(campus, registry, "perhaps the bin might move over by the fountain? anywhere there's fine").scene
    bin_ = scene.asset("trash_bin_1")
    assert abs(bin_.pose.x - 75.0) < 15 and abs(bin_.pose.y - 40.0) < 15
