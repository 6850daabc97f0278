"""The plan check, continued: a thing the words only turn to face a place is never carried there,
and a thing asked to be built, installed or set up that this world has no word for is never
swapped for another thing the request names (worded unlike any suite prompt)."""

from __future__ import annotations

from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from misreading import Fixed, add, applied, call, held  # this folder is on sys.path (no __init__.py)


def test_a_thing_turned_toward_a_place_is_not_carried_there(campus, registry):
    carried = Fixed(call("place_asset", asset="trash_bin_1", location={"relation": "at", "target": "Library entrance"}))
    report = held(campus, registry, carried, "could you angle the bin at the Library entrance")
    assert "turn" in (report.error or "")
    held(campus, registry, carried, "rotate the trash bin towards the Library entrance a little")


def test_a_thing_turned_in_place_or_moved_when_asked_still_applies(campus, registry):
    turned = Fixed(call("move_asset", asset="trash_bin_1", turn_deg=90.0))
    scene = applied(campus, registry, turned, "swivel the bin to face the Library entrance").scene
    assert scene.asset("trash_bin_1").pose.x == campus.asset("trash_bin_1").pose.x
    carried = Fixed(call("place_asset", asset="trash_bin_1", location={"relation": "next_to", "target": "Library entrance"}))
    applied(campus, registry, carried, "shift the bin over to the Library entrance and turn it to face the road")


def test_a_thing_built_that_the_world_lacks_is_not_swapped_for_another(campus, registry):
    beneficiary = Fixed(add("bus", location={"relation": "at", "target": "bus stop"}))
    report = held(campus, registry, beneficiary, "install a ticket kiosk for the bus at the bus stop")
    assert "kiosk" in (report.error or "")
    held(campus, registry, Fixed(add("bicycle")), "could you construct a velodrome for the bicycle riders")


def test_a_thing_built_that_the_world_has_is_added(campus, registry):
    scene = applied(campus, registry, Fixed(add("road_barrier", count=2, location={"relation": "at", "target": "bus stop"})),
                    "set up two barriers at the bus stop").scene
    assert sum(a.category == "road_barrier" for a in scene.assets) == 2


def test_a_move_whose_way_is_not_read_asks_which_way(campus, registry):
    session = Session(campus, RulePlanner(), registry)
    report = session.submit("shift the trash bin 2 metres kerbwards, thanks")
    assert not report.ok and report.question is not None and session.scene == campus
    offered = [r.text for r in report.question.readings]
    assert any("left 2 m" in t for t in offered) and any("right 2 m" in t for t in offered)
    report = session.submit("shift the trash bin 2 metres to the east")
    assert report.ok, report.error or report.question
    assert session.scene.asset("trash_bin_1").pose.x == campus.asset("trash_bin_1").pose.x + 2.0
    report = session.submit("shift the trash bin a little")  # no way said: any way is what was asked
    assert report.ok, report.error or report.question
