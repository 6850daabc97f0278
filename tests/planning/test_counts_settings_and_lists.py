"""Readings and checks from one round's unseen suite, each worded here unlike any suite prompt: an
inventory asked for, a signal's colour, people named as the setting, counts said as pieces or as "a
couple", acknowledgements, hedged commands, weather strengths said several ways, markdown lists, a
pair measured, and the last word of a place's name mistyped."""

from __future__ import annotations

import math

from drivetwin.orchestrator.planning.intent import asks
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from misreading import Fixed, add, call, held, ruled  # this folder is on sys.path (no __init__.py)


def _said(report) -> str:
    return report.error or (report.question.text if report.question else "")


def test_an_inventory_asked_for_changes_nothing(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("can I get a stock take of the cars in lot B")
    assert report.ok and report.answer is not None and "suv_1" in report.answer
    assert session.scene == campus


def test_a_signals_colour_is_never_paint(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    session.submit("the ego should sit at a red light by the north crosswalk")
    assert session.scene.asset("ego").appearance == campus.asset("ego").appearance


def test_people_named_as_the_setting_are_never_added(campus, registry):
    plan = Fixed(add("pedestrian", count=3, location={"relation": "at", "target": "Student Union entrance"}))
    assert "setting" in _said(held(campus, registry, plan, "move the bin to where the students hang out, the Student Union"))
    plan = Fixed(add("pedestrian", count=2, location={"relation": "at", "target": "bus stop"}))
    assert "pedestrian" in _said(held(campus, registry, plan, "the commuters at the bus stop say there's nowhere to sit"))
    scene = ruled(campus, registry, "people will want to rest by the fountain, add two benches there").scene
    assert sum(a.category == "bench" for a in scene.assets) == 3


def test_counts_said_as_a_couple_as_pieces_and_as_one_more(campus, registry):
    scene = ruled(campus, registry, "far too many lamp posts along the south side. lose a couple").scene
    assert sum(a.category == "street_light" for a in scene.assets) == sum(a.category == "street_light" for a in campus.assets) - 2
    scene = ruled(campus, registry, "add 3 pcs of cone by the east gate", "nice one! another one of those by the main gate").scene
    assert sum(a.category == "traffic_cone" for a in scene.assets) == 4
    scene = ruled(campus, registry, "add too trees by the fountain").scene
    assert sum(a.category == "tree" for a in scene.assets) == sum(a.category == "tree" for a in campus.assets) + 2


def test_a_command_hedged_or_dared_is_a_request(campus, registry):
    for said in ("the ego is crawling. maybe speed it up a bit?", "turn the bench round a bit, perhaps?",
                 "would it hurt you to add a bench by the fountain?", "the bus has sat there all day. maybe it could go?"):
        assert not asks(said.lower()), said
    bench = ruled(campus, registry, "nudge the bench along a touch").scene.asset("bench_1")
    start = campus.asset("bench_1")
    assert 0.3 < math.dist((bench.pose.x, bench.pose.y), (start.pose.x, start.pose.y)) <= 2.0


def test_weather_strength_said_several_ways(campus, registry):
    assert ruled(campus, registry, "snow please. proper heavy").scene.environment.weather.intensity > 0.8
    assert ruled(campus, registry, "weather change to rain, big rain").scene.environment.weather.intensity > 0.8
    thinned = ruled(campus, registry, "thick fog", "fog now way too thick").scene.environment.weather
    assert thinned.kind == "fog" and thinned.intensity < 0.8
    assert ruled(campus, registry, "heavy rain", "close the rain please").scene.environment.weather.kind == "clear"


def test_a_markdown_list_is_read_line_by_line(campus, registry):
    weather = ruled(campus, registry, "- weather: rain\n- intensity: low").scene.environment.weather
    assert weather.kind == "rain" and weather.intensity < 0.5
    scene = ruled(campus, registry, "1. add a bench by the fountain\n2. make it night").scene
    assert sum(a.category == "bench" for a in scene.assets) == 2 and scene.environment.time_of_day != campus.environment.time_of_day


def test_two_of_a_kind_measured_against_each_other(campus, registry):
    report = Session(campus, RulePlanner(), registry).submit("how far apart are the two traffic lights?")
    assert report.ok and report.answer is not None and "22.7" in report.answer


def test_the_last_word_of_a_place_mistyped(campus, registry):
    scene = ruled(campus, registry, "put a bench by the main gait").scene
    gate = next(lm for lm in campus.landmarks if lm.name == "main gate").position
    new = [a for a in scene.assets if a.category == "bench" and campus.asset(a.id) is None]
    assert len(new) == 1 and math.dist((new[0].pose.x, new[0].pose.y), gate[:2]) < 12


def test_one_new_thing_a_distance_away_is_never_one_moved(campus, registry):
    plan = Fixed(call("place_asset", asset="passenger_car_1",
                      location={"relation": "in_front_of", "target": "ego", "distance": 30.0}))
    assert "new passenger car" in _said(held(campus, registry, plan, "stick one car 30 m ahead of the ego in its lane"))


def test_a_thing_picked_out_by_what_it_stands_by(campus, registry):
    def nearest(category: str, point: tuple[float, float]) -> str:
        return min((a for a in campus.assets if a.category == category), key=lambda a: math.dist((a.pose.x, a.pose.y), point)).id

    stop = next(lm for lm in campus.landmarks if lm.name == "bus stop").position[:2]
    lamp = nearest("street_light", stop)
    scene = ruled(campus, registry, "colour the street lamp that's right by the bus stop green").scene
    assert [a.id for a in scene.assets if a.appearance != (campus.asset(a.id) or a).appearance] == [lamp]
    sign = campus.asset("stop_sign_1")
    by_sign = nearest("street_light", (sign.pose.x, sign.pose.y))
    scene = ruled(campus, registry, "take away the lamp post next to the stop sign").scene
    assert scene.asset(by_sign) is None and sum(a.category == "street_light" for a in scene.assets) == sum(
        a.category == "street_light" for a in campus.assets) - 1
    union = next(lm for lm in campus.landmarks if lm.name == "Student Union entrance").position[:2]
    moved = ruled(campus, registry, "shift the lamp post beside the stop sign over to the Student Union entrance").scene.asset(by_sign)
    assert moved is not None and math.dist((moved.pose.x, moved.pose.y), union) < 15


def test_a_layout_asked_for_in_the_passive_and_a_thing_just_one_way_of_a_place(campus, registry):
    lot_a = next(lm for lm in campus.landmarks if lm.name == "parking lot A").position[:2]
    tree = min((a for a in campus.assets if a.category == "tree" and a.pose.y > lot_a[1]),
               key=lambda a: math.dist((a.pose.x, a.pose.y), lot_a))
    scene = ruled(campus, registry, "That tree just north of lot A is protected. It has to be fenced off all the way round.").scene
    assert scene.asset(tree.id).pose == tree.pose  # the tree stays where it stands
    ring = [a for a in scene.assets if campus.asset(a.id) is None]
    assert len(ring) >= 4 and all(math.dist((a.pose.x, a.pose.y), (tree.pose.x, tree.pose.y)) < 8 for a in ring)
    painted = ruled(campus, registry, "paint the tree just north of lot A gold").scene
    assert [a.id for a in painted.assets if a.appearance != (campus.asset(a.id) or a).appearance] == [tree.id]


def test_a_word_of_the_speakers_own_for_putting_and_words_said_together(campus, registry):
    scene = ruled(campus, registry, "toss two bollards in lot A and a bench by the Library").scene
    assert sum(a.category == "bollard" for a in scene.assets) == sum(a.category == "bollard" for a in campus.assets) + 2
    assert sum(a.category == "bench" for a in scene.assets) == 2
    scene = ruled(campus, registry, "get all the cars outta lot B").scene
    assert not any(a.category in ("passenger_car", "suv") for a in scene.assets)
    lamps = sum(a.category == "street_light" for a in campus.assets)
    scene = ruled(campus, registry, "way too many lamp posts. take off some").scene  # never a turn at a junction
    assert 0 < lamps - sum(a.category == "street_light" for a in scene.assets) < lamps
    scene = ruled(campus, registry, "add 4 pcs of cone by the east gate", "cones too many, remove two piece").scene
    assert sum(a.category == "traffic_cone" for a in scene.assets) == 2


def test_pulled_off_site_kept_things_markdown_marks_and_intensifiers(campus, registry):
    scene = ruled(campus, registry, "pull the SUV off site please").scene
    assert scene.asset("suv_1") is None and scene.asset("passenger_car_1") is not None
    scene = ruled(campus, registry, "pull both passenger cars from lot B but keep the SUV").scene
    assert scene.asset("suv_1") is not None and not any(a.category == "passenger_car" for a in scene.assets)
    scene = ruled(campus, registry, "pul the bench from the bus stop").scene  # as near "pull" as "put": never an addition
    assert sum(a.category == "bench" for a in scene.assets) <= 1
    moved = ruled(campus, registry, "- move: `bench_1`\n- to: **the fountain**").scene.asset("bench_1")
    fountain = next(lm for lm in campus.landmarks if lm.name == "fountain").position[:2]
    assert moved is not None and math.dist((moved.pose.x, moved.pose.y), fountain) < 12
    scene = ruled(campus, registry, "lot A looks too much empty, put a couple of cars there").scene
    assert sum(a.category == "passenger_car" for a in scene.assets) == 4


def test_lamps_opened_closed_and_killed(campus, registry):
    assert ruled(campus, registry, "open the street lights please").scene.environment.lighting.street_lights == "on"
    assert ruled(campus, registry, "lights on", "ok now close the street lamps").scene.environment.lighting.street_lights == "off"
    assert ruled(campus, registry, "lights on", "kill the lamps").scene.environment.lighting.street_lights == "off"


def test_too_empty_is_how_it_is_and_em_is_them(campus, registry):
    scene = ruled(campus, registry, "the Library front is way too empty, needs a tree or two").scene
    assert sum(a.category == "tree" for a in scene.assets) > sum(a.category == "tree" for a in campus.assets)
    scene = ruled(campus, registry, "line up some bollards by the east gate - five of 'em").scene
    assert sum(a.category == "bollard" for a in scene.assets) == sum(a.category == "bollard" for a in campus.assets) + 5


def test_a_thing_said_where_it_stands_then_wished_gone(campus, registry):
    scene = ruled(campus, registry, "that SUV has been sitting in lot B all week. perhaps it doesn't need to be there?").scene
    assert scene.asset("suv_1") is None and scene.asset("passenger_car_1") is not None


def test_list_lines_of_their_own_and_a_place_off_the_map(campus, registry):
    scene = ruled(campus, registry, "- bench colour: teal\n- bin colour: teal too").scene
    assert all(scene.asset(i).appearance != campus.asset(i).appearance for i in ("bench_1", "trash_bin_1"))
    report = held(campus, registry, Fixed(call("place_asset", asset="bench_1", location={"relation": "at", "target": "main gate"})),
                  "move the bench past the main gate, right off the edge of the map")
    assert "off the map" in _said(report)


def test_two_things_wished_for_together(campus, registry):
    scene = ruled(campus, registry, "the pavers start at the JTEKT entrance tomorrow, so we need a cone and a roadworks sign there").scene
    assert sum(a.category == "traffic_cone" for a in scene.assets) == 1
    assert sum(a.category == "construction_sign" for a in scene.assets) == 1


def test_a_thing_picked_across_the_road_and_two_as_near(campus, registry):
    bench = campus.asset("bench_1")
    over = min((a for a in campus.assets if a.category == "street_light" and a.pose.y > 0),
               key=lambda a: abs(a.pose.x - bench.pose.x))
    scene = ruled(campus, registry, "recolour the lamp directly opposite the bench purple").scene
    assert [a.id for a in scene.assets if a.appearance != (campus.asset(a.id) or a).appearance] == [over.id]
    report = Session(campus, RulePlanner(), registry).submit("paint the car beside the SUV silver")  # one each side of it
    assert not report.ok and "which" in _said(report)
    scene = ruled(campus, registry, "paint the car beside the SUV on the east side silver").scene
    assert [a.id for a in scene.assets if a.appearance != (campus.asset(a.id) or a).appearance] == ["passenger_car_2"]


def test_a_question_about_the_thing_by_a_place(campus, registry):
    stop = next(lm for lm in campus.landmarks if lm.name == "bus stop").position[:2]
    lamp = min((a for a in campus.assets if a.category == "street_light"), key=lambda a: math.dist((a.pose.x, a.pose.y), stop))
    report = Session(campus, RulePlanner(), registry).submit("what colour is the street lamp next to the bus stop?")
    assert report.ok and report.answer is not None and report.answer.startswith(lamp.id)


def test_a_thing_picked_by_the_way_it_stands_from_another(campus, registry):
    for said, meant in (("repaint the sedan just west of the SUV orange", "passenger_car_1"),
                        ("repaint the car to the east of the SUV orange", "passenger_car_2")):
        scene = ruled(campus, registry, said).scene
        assert [a.id for a in scene.assets if a.appearance != (campus.asset(a.id) or a).appearance] == [meant], said


def test_a_thing_left_as_it_is_is_not_acted_on(campus, registry):
    scene = ruled(campus, registry, "take the bench away. leave the bin where it is").scene
    assert scene.asset("bench_1") is None and scene.asset("trash_bin_1") == campus.asset("trash_bin_1")
    scene = ruled(campus, registry, "keep both cars as they are and get rid of the SUV").scene
    assert scene.asset("suv_1") is None
    assert all(scene.asset(i) == campus.asset(i) for i in ("passenger_car_1", "passenger_car_2"))
    scene = ruled(campus, registry, "leave the SUV alone, paint the bench green").scene
    assert scene.asset("suv_1") == campus.asset("suv_1") and scene.asset("bench_1").appearance != campus.asset("bench_1").appearance
