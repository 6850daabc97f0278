"""Readings worded here, none from a suite: a thing spoken of as there when the scene has none, a
road's name mistyped, a place cleared and filled, "a new one" of the kind just named, a word several
kinds share, things there laid out, and a thing wished less of a quality."""

from __future__ import annotations

import math

import pytest
from drivetwin.orchestrator.planning import PlanningError
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from misreading import Fixed, add, call, held, ruled  # this folder is on sys.path (no __init__.py)


def _kinds(scene, category: str) -> int:
    return sum(a.category == category for a in scene.assets)


def _refused(campus, registry, prompt: str) -> str:
    return held(campus, registry, RulePlanner(), prompt).error or ""


def test_a_thing_spoken_of_as_there_is_never_added_when_there_is_none(campus, registry):
    for said in ("the truck is in a daft spot", "the trucks are blocking the westbound lane", "the bus is parked badly"):
        assert "as if it were there" in _refused(campus, registry, said), said
    # said to be missing, it is wanted
    assert _kinds(ruled(campus, registry, "the truck isn't there anymore").scene, "truck") == 1


def test_the_last_word_of_a_roads_name_mistyped(campus, registry):
    scene = ruled(campus, registry, "four cones spaced 3m apart on campus drve").scene
    cones = [a for a in scene.assets if a.category == "traffic_cone"]
    assert len(cones) == 4 and all(abs(c.pose.x) < 4 for c in cones)  # Campus Drive runs north-south through x = 0


def test_taking_away_what_a_place_does_not_hold_is_refused(campus, registry):
    said = _refused(campus, registry, "delete the cars in lot A")  # the cars stand in lot B
    assert "no cars at parking lot A" in said


def test_a_place_cleared_then_filled(campus, registry):
    scene = ruled(campus, registry, "empty lot B and put two buses there").scene
    assert _kinds(scene, "bus") == 2 and _kinds(scene, "suv") == 0 and _kinds(scene, "passenger_car") == 0
    # what is cleared away is what stood there; the check still holds a plan that clears elsewhere
    stray = Fixed(call("remove_assets", assets=["bench_1"]), add("bus", count=2, location={"relation": "at", "target": "parking lot B"}))
    assert "bench" in (held(campus, registry, stray, "empty lot B and put two buses there").error or "")


def test_a_new_one_is_of_the_kind_just_named(campus, registry):
    scene = ruled(campus, registry, "take the bin away and put a fresh one by the library").scene
    (bin_,) = [a for a in scene.assets if a.category == "trash_bin"]
    library = next(lm for lm in scene.landmarks if lm.name == "Library entrance")
    assert math.dist((bin_.pose.x, bin_.pose.y), library.position) < 8 < math.dist(
        (campus.asset("trash_bin_1").pose.x, campus.asset("trash_bin_1").pose.y), library.position)
    scene = ruled(campus, registry, "lose the bench", "now add a replacement one next to the fountain").scene
    (bench,) = [a for a in scene.assets if a.category == "bench"]
    fountain = next(lm for lm in scene.landmarks if lm.name == "fountain")
    assert math.dist((bench.pose.x, bench.pose.y), fountain.position) < 8
    scene = ruled(campus, registry, "three cones at the main gate please", "add a roadworks sign beside the last one").scene
    sign = next(a for a in scene.assets if a.category == "construction_sign")
    last = scene.asset("traffic_cone_3")
    assert last is not None and math.dist((sign.pose.x, sign.pose.y), (last.pose.x, last.pose.y)) < 3
    with pytest.raises(PlanningError, match="say what to add"):
        RulePlanner().plan("add a new one at the fountain", Session(campus, RulePlanner(), registry).context())


def test_a_thing_wished_less_of_a_quality_is_neither_removed_nor_guessed(campus, registry):
    for said in ("can the SUV be made a little less flashy", "make the bench a bit less shiny"):
        assert "not how it should" in _refused(campus, registry, said), said
    scene = ruled(campus, registry, "make the SUV less flashy, paint it grey").scene
    assert scene.asset("suv_1") is not None and scene.asset("suv_1").appearance != campus.asset("suv_1").appearance


def test_things_there_are_laid_out_not_added_nor_one_of_them_moved(campus, registry):
    scene = ruled(campus, registry, "please get the cars in lot B lined up in a row").scene
    assert len(scene.assets) == len(campus.assets)
    vehicles = [scene.asset(i) for i in ("passenger_car_1", "passenger_car_2", "suv_1")]
    assert all(v is not None and v.pose != campus.asset(v.id).pose for v in vehicles)
    scene = ruled(campus, registry, "can all the trees go in a circle around the fountain").scene
    fountain = next(lm for lm in scene.landmarks if lm.name == "fountain")
    trees = [a for a in scene.assets if a.category == "tree"]
    assert len(trees) == 4 and all(math.dist((t.pose.x, t.pose.y), fountain.position) < 8 for t in trees)
    # new ones, said so, are still added
    scene = ruled(campus, registry, "a row of three new cones at the east gate").scene
    assert _kinds(scene, "traffic_cone") == 3


def test_not_both_of_two_things_never_takes_both(campus, registry):
    said = _refused(campus, registry, "honestly we do not need both of the benches")
    assert "which of the benches should go" in said


def test_a_walker_counted_along_the_way_on_one_sidewalk(campus, registry):
    scene = ruled(campus, registry, "a pedestrian on the left-hand footpath twenty metres ahead of the ego").scene
    walker = next(a for a in scene.assets if a.category == "pedestrian")
    ego = campus.asset("ego")
    assert 15 < walker.pose.x - ego.pose.x < 25 and walker.pose.y > 4  # the north sidewalk, left of the eastbound ego


def test_a_pace_word_mistyped_is_a_pace(campus, registry):
    from drivetwin.orchestrator.planning.rules.spelling import repair

    assert repair("have the ego drive fater", campus).text.endswith("faster")
    assert repair("the truck is way too slwoer", campus).text.endswith("slower")


def test_a_word_several_kinds_share_is_asked_about_never_read_as_the_thing_beside_it(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("could you add a sign beside the bench")
    assert not report.ok and report.question is not None and "stop sign" in report.question.text
    assert session.scene == campus  # it had added a second bench
    readings = {c.args["category"] for r in report.question.readings for c in r.calls}
    assert "bench" not in readings and len(readings) >= 2
    # a kind said in full is not asked about
    scene = ruled(campus, registry, "add a pedestrian sign beside the bench").scene
    assert _kinds(scene, "pedestrian_sign") == 1


def test_where_a_statement_says_a_thing_is_is_never_where_it_goes(campus, registry):
    # "the middle of the pavement" is no centre of the map, and the bin stands on the pavement already
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("that bin is in the middle of the pavement")
    assert not report.ok and session.scene == campus


def test_were_for_where_before_it_was(campus, registry):
    scene = ruled(campus, registry, "take out the hydrant and stick a bench were it was").scene
    bench = next(a for a in scene.assets if a.category == "bench" and a.id != "bench_1")
    hydrant = campus.asset("fire_hydrant_1")
    assert math.dist((bench.pose.x, bench.pose.y), (hydrant.pose.x, hydrant.pose.y)) < 1.5


def test_a_line_across_a_road_said_by_its_name_spans_it(campus, registry):
    scene = ruled(campus, registry, "three barriers across Campus Drive north of the junction").scene
    barriers = [a for a in scene.assets if a.category == "road_barrier"]
    assert len(barriers) == 3 and len({round(b.pose.y, 1) for b in barriers}) == 1  # across the north-south road
    assert max(b.pose.x for b in barriers) > 1 and min(b.pose.x for b in barriers) < -1  # both lanes


def test_whether_the_road_ahead_is_clear_looks_at_what_stands_on_it(campus, registry):
    session = ruled(campus, registry, "add a car 20 m ahead of the ego")
    report = session.submit("is the road clear in front of the ego?")
    assert report.ok and report.answer is not None and "passenger_car_3" in report.answer
    assert "ego (" not in report.answer  # what is near the ego is not the ego
    assert [c.tool for c in report.plan.calls] == ["find_assets"]


def test_whether_something_can_be_seen_is_a_question(campus, registry):
    for said in ("can you see any cyclists", "do we spot anything near the fountain"):
        session = Session(campus, RulePlanner(), registry)
        report = session.submit(said)
        assert report.ok and report.answer is not None and session.scene == campus, said  # it had added three


def test_a_statement_of_where_things_are_moves_none_of_them(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("the trees round the fountain are in my way")
    assert not report.ok and session.scene == campus  # every tree, the far ones too, had been moved in front of it
