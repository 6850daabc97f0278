"""Readings and checks of one round, each worded unlike any suite prompt: a thing picked by its size
among a kind or a group ("the biggest vehicle"), a want said as what would do good ("..., so maybe
two benches would help"), how a thing should look never read as how many there are, and a thing
put where it already stands with nothing else done to it."""

from __future__ import annotations

from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.tools.search import most_of
from misreading import Fixed, add, applied, call, held  # this folder is on sys.path (no __init__.py)


def _ruled(campus, registry, prompt: str) -> Session:
    session = Session(campus, RulePlanner(), registry)
    report = session.submit(prompt)
    assert report.ok, report.error or report.question
    return session


def test_the_search_tools_figures_pick_by_size_with_ties_kept(campus):
    cars = [a for a in campus.assets if a.category in ("passenger_car", "suv")]
    assert [a.id for a in most_of("biggest", cars)] == ["suv_1"]
    assert sorted(a.id for a in most_of("smallest", cars)) == ["passenger_car_1", "passenger_car_2"]
    assert most_of("heaviest", []) == []


def test_the_biggest_of_a_group_is_the_one_acted_on(campus, registry):
    gone = _ruled(campus, registry, "could you get rid of the largest vehicle please").scene
    assert gone.asset("suv_1") is None and gone.asset("passenger_car_1") is not None and gone.asset("passenger_car_2") is not None
    painted = _ruled(campus, registry, "give the heaviest of the cars a yellow paint job").scene
    assert painted.asset("suv_1").appearance.rgba is not None
    assert painted.asset("passenger_car_1").appearance.rgba is None


def test_a_plan_acting_on_others_than_the_size_picks_is_held(campus, registry):
    every_car = Fixed(call("remove_assets", assets=["passenger_car_1", "passenger_car_2", "suv_1"]))
    report = held(campus, registry, every_car, "bin the biggest cars for me")
    assert "biggest" in (report.error or "") and "suv" in (report.error or "")
    wrong_one = Fixed(call("set_asset_appearance", assets=["passenger_car_2"], colour="green"))
    held(campus, registry, wrong_one, "green for the bulkiest... no, the largest vehicle")
    applied(campus, registry, Fixed(call("set_asset_appearance", assets=["suv_1"], colour="green")), "paint the largest vehicle green")


def test_a_want_said_as_what_would_help_is_the_request(campus, registry):
    session = _ruled(campus, registry, "the quad is gloomy at night so three more lamps might be handy by the fountain")
    lamps = [a for a in session.scene.assets if a.category == "street_light"]
    assert len(lamps) == len([a for a in campus.assets if a.category == "street_light"]) + 3
    assert session.scene.environment == campus.environment
    benches = _ruled(campus, registry, "folks wait ages at the bus stop, so two benches might help there").scene
    assert sum(a.category == "bench" for a in benches.assets) == 3
    # a reason that says what would follow is still a reason
    reason = _ruled(campus, registry, "put a bench by the fountain so people could rest").scene
    assert sum(a.category == "bench" for a in reason.assets) == 2


def test_how_a_thing_should_look_is_never_how_many(campus, registry):
    report = held(campus, registry, Fixed(call("remove_assets", category="suv", count=1)), "can the SUV appear slightly less menacing")
    assert "looks" in (report.error or "")
    held(campus, registry, Fixed(add("suv")), "have the SUV seem a lot more rugged")
    # a look said of how busy a place is counts things
    applied(campus, registry, Fixed(add("passenger_car", count=2, behaviour={"kind": "drive_lane"})), "make Main Street look busier")


def test_a_thing_put_where_it_already_stands_is_held(campus, registry):
    same_lane = Fixed(call("place_asset", asset="ego", location={"relation": "in_lane", "target": "main_eastbound"}))
    report = held(campus, registry, same_lane, "the ego in the eastbound lane dawdles, sort that out")
    assert "ego already stands in main_eastbound" in (report.error or "")
    parked = Fixed(call("place_asset", asset="suv_1", location={"relation": "at", "target": "parking lot B"}))
    report = held(campus, registry, parked, "the SUV in lot B is blocking the bay, sort it out")
    assert "suv_1 already stands in parking lot B" in (report.error or "")


def test_a_move_nearer_or_a_thing_also_changed_still_applies(campus, registry):
    nearer = Fixed(call("place_asset", asset="bench_1", location={"relation": "next_to", "target": "trash_bin_1"}))
    applied(campus, registry, nearer, "put the bench right up against the bin")
    driven = Fixed(call("place_asset", asset="ego", location={"relation": "in_lane", "target": "main_eastbound"}),
                   call("set_behaviour", asset="ego", behaviour={"kind": "drive_lane", "speed": 8.0}))
    applied(campus, registry, driven, "the ego should drive along the eastbound lane at 8 m/s")


def test_what_is_to_be_kept_away_is_never_added(campus, registry):
    walkers = Fixed(add("pedestrian", count=3, location={"relation": "next_to", "target": "fountain"}))
    report = held(campus, registry, walkers, "could we have something by the fountain to keep students off the flower beds")
    assert "keep pedestrian away" in (report.error or "")
    held(campus, registry, Fixed(add("bicycle", count=2)), "I'd like to discourage bikes from using the Library footway")
    # kept waiting is no keeping away
    applied(campus, registry, Fixed(add("pedestrian", location={"relation": "at", "target": "west crosswalk"})),
            "add a pedestrian at the west crosswalk and keep the pedestrian waiting there")


def test_halving_things_said_as_a_verb_takes_half_away(campus, registry):
    trees = _ruled(campus, registry, "please halve the trees").scene
    assert sum(a.category == "tree" for a in trees.assets) == 2
    lamps = _ruled(campus, registry, "cut the number of street lamps in half").scene
    assert sum(a.category == "street_light" for a in lamps.assets) == 6
    # a speed halved is no thing taken away
    report = Session(campus, RulePlanner(), registry).submit("cut the speed of the ego in half")
    assert not (report.ok and report.plan is not None and any(c.tool == "remove_assets" for c in report.plan.calls))


def test_standing_out_too_much_is_never_more_orange_nor_gone(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("that SUV is far too eye-catching, tone it down a bit")
    assert not (report.ok and session.scene.asset("suv_1").appearance.rgba is not None and
                session.scene.asset("suv_1").appearance.rgba[:3] == (0.95, 0.5, 0.05))
    report = held(campus, registry, Fixed(call("remove_assets", category="trash_bin", count=1)), "the bin sticks out, it stands out too much")
    assert "looks" in (report.error or "")
    applied(campus, registry, Fixed(call("set_asset_appearance", assets=["suv_1"], colour="orange")), "make the SUV stand out more")
