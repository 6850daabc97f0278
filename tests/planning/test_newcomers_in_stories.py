"""Stories that bring their actor in, and a slip after a command verb read as a thing, tried in
this file's own words on the packaged campus world: "a pedestrian steps out in front of the ego"
with no pedestrian there adds one on the kerb ahead and has it cross as the ego comes; "the lead
car brakes when the ego gets close" adds a slower car ahead in the ego's lane; "the ego has to stop
for someone walking out" is the walker, never the ego parked; "add a coner by the bench" is a cone,
not a second bench; "cone that off" rings what the last turn added, and asks when there is nothing
to ring; a ring round a thing by the road leaves out the grass it cannot stand on."""

from __future__ import annotations

import itertools
import math

import pytest
from drivetwin.orchestrator.planning.base import Plan, PlanContext, PlanningError
from drivetwin.orchestrator.planning.registry import make_planner
from drivetwin.orchestrator.planning.rules.spelling import english_words, is_known, repair, vocabulary
from drivetwin.orchestrator.planning.scenario_reading import ScenarioReader
from drivetwin.orchestrator.session import Session
from drivetwin.orchestrator.transaction import TransactionError, execute
from drivetwin.tools.base import ToolCall
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.scene import DriveLane, Scene
from drivetwin.worlds.simulation import Simulation
from drivetwin.worlds.surface import surface_at

REGISTRY = ToolRegistry.default(plugins=False)


def _plan(prompt: str, scene: Scene | None = None) -> Plan:
    return ScenarioReader().plan(prompt, PlanContext(scene=scene or build_campus(), registry=REGISTRY))


def _after(plan: Plan, scene: Scene | None = None) -> Scene:
    return execute(REGISTRY, scene or build_campus(), plan.calls).after


def _newcomer(before: Scene, after: Scene, category: str):
    old = {a.id for a in before.assets}
    (new,) = [a for a in after.assets if a.category == category and a.id not in old]
    return new


# --- a walker brought in to cross ----------------------------------------------------------------


def test_someone_stepping_out_in_front_of_the_ego_is_brought_in_on_the_kerb_ahead_and_crosses_as_it_comes():
    campus = build_campus()
    plan = _plan("a pedestrian steps out in front of the ego", campus)
    after = _after(plan, campus)
    walker = _newcomer(campus, after, "pedestrian")
    assert surface_at(after, walker.pose.x, walker.pose.y) == "sidewalk"
    assert walker.pose.x > campus.ego.pose.x + 20.0 and walker.pose.y < 0.0  # ahead, on the ego's right
    ((actor, event),) = after.storyboard.events()
    assert actor == walker.id and event.action.kind == "cross_road"
    assert event.start.kind == "distance"  # as the ego comes, not at once


def test_a_walker_brought_in_really_steps_into_the_ego_lane_once_the_ego_comes():
    campus = build_campus()
    after = _after(_plan("someone runs across the road in front of the ego", campus), campus)
    walker = _newcomer(campus, after, "pedestrian")
    simulation = Simulation(after)
    seen: list[tuple[float, float]] = []  # (the ego's distance behind the walker, the walker's y)
    for _ in range(24):
        simulation.run_for(0.5)
        seen.append((simulation.pose(walker.id).x - simulation.pose().x, simulation.pose(walker.id).y))
    assert seen[0][1] < -3.5  # on the kerb while the ego is far off
    in_lane = [gap for gap, y in seen if abs(y + 1.75) < 1.0]
    assert in_lane and 0.0 < in_lane[0] < 30.0  # then in the ego's lane, ahead of it, as it comes


def test_add_a_walker_that_crosses_when_the_ego_is_near_is_the_add_and_the_story():
    plan = _plan("add a pedestrian that crosses in front of the ego when it is 20 m away")
    assert [c.tool for c in plan.calls] == ["add_asset", "add_event"]
    assert plan.calls[1].args["when"]["metres"] == 20.0


def test_out_from_behind_a_thing_waits_behind_the_one_by_the_egos_road():
    campus = build_campus()
    after = _after(_plan("a kid runs out from behind the tree into the road when the ego is 20 m away", campus), campus)
    walker = _newcomer(campus, after, "pedestrian")
    tree = campus.asset("tree_1")  # of the four trees, the one beside Main Street ahead of the ego
    assert tree is not None and math.dist((walker.pose.x, walker.pose.y), (tree.pose.x, tree.pose.y)) < 4.0


def test_the_ego_having_to_stop_for_someone_is_the_someone_never_the_ego_parked():
    campus = build_campus()
    for prompt in ("I need the ego to have to stop for someone walking out",
                   "I want the ego to have to brake for a kid running into the road",
                   "the ego should brake hard for a cyclist when it is 25 m away"):
        after = _after(_plan(prompt, campus), campus)
        assert isinstance(after.ego.behaviour, DriveLane), prompt  # the ego still drives: it is what is tested
        ((actor, event),) = after.storyboard.events()
        assert actor != "ego" and event.action.kind == "cross_road", prompt


# --- a vehicle brought in ------------------------------------------------------------------------


def test_the_lead_car_braking_brings_in_a_slower_car_ahead_in_the_ego_lane():
    campus = build_campus()
    after = _after(_plan("the lead car brakes hard when the ego gets close", campus), campus)
    lead = _newcomer(campus, after, "passenger_car")
    assert isinstance(lead.behaviour, DriveLane) and lead.behaviour.lane == "main_eastbound"
    assert lead.behaviour.speed is not None and campus.ego.behaviour.speed is not None
    assert lead.behaviour.speed < campus.ego.behaviour.speed  # the ego closes in, so the trigger comes
    assert 15.0 <= lead.pose.x - campus.ego.pose.x <= 40.0 and lead.pose.y == pytest.approx(-1.75, abs=0.3)
    ((actor, event),) = after.storyboard.events()
    assert actor == lead.id and event.action.kind in ("stop", "change_speed")


def test_a_car_braking_is_never_one_parked_in_a_lot():
    campus = build_campus()  # two cars and an SUV stand parked in lot B
    plan = _plan("a car brakes suddenly after 3 seconds", campus)
    actor = plan.calls[-1].args["actor"]
    assert actor not in {a.id for a in campus.assets}


def test_a_car_overtaking_starts_behind_the_ego_and_faster():
    campus = build_campus()
    after = _after(_plan("a car overtakes the ego", campus), campus)
    car = _newcomer(campus, after, "passenger_car")
    assert car.pose.x < campus.ego.pose.x
    assert isinstance(car.behaviour, DriveLane) and (car.behaviour.speed or 0.0) > (campus.ego.behaviour.speed or 0.0)


def test_a_thing_named_as_already_there_is_not_brought_in():
    with pytest.raises(PlanningError, match="no bus"):
        _plan("the bus brakes when the ego gets close")


def test_a_cut_in_with_no_lane_beside_the_ego_says_so():
    with pytest.raises(PlanningError, match="no lane beside the ego"):
        _plan("a car cuts in front of the ego")


def test_the_hybrid_applies_a_story_with_its_newcomer(campus, registry, tmp_path):
    session = Session(campus, make_planner("hybrid"), registry, journal_path=tmp_path / "journal.jsonl")
    result = session.submit("a pedestrian steps out in front of the ego")
    assert result.ok, result.error
    assert [a.category for a in session.scene.assets if a.id not in {b.id for b in campus.assets}] == ["pedestrian"]
    assert len(list(session.scene.storyboard.events())) == 1


# --- a slip after a command verb -----------------------------------------------------------------


def test_a_thing_word_with_er_added_is_a_slip_but_a_comparative_is_a_word():
    vocab = vocabulary(build_campus())
    assert english_words(), "MiniLM's word list ships with the grounding package"
    assert not is_known("coner", vocab)
    assert is_known("closer", vocab) and is_known("wider", vocab)


def test_a_slip_after_add_a_is_the_thing_it_is_as_near_to_as_to_any_other_word():
    campus = build_campus()
    assert "cone" in repair("add a coner by the bench", campus).text
    assert "corner" in repair("at the coner of the lot", campus).text  # no command before it: the place word


def test_add_a_coner_by_the_bench_adds_a_cone_not_a_bench(session):
    before = session.scene
    result = session.submit("add a coner by the bench")
    assert result.ok, result.error
    new = [a.category for a in session.scene.assets if a.id not in {b.id for b in before.assets}]
    assert new == ["traffic_cone"]


# --- rings said by a marker's name ---------------------------------------------------------------


def test_cone_that_off_rings_the_car_the_last_turn_added(session):
    before = session.scene
    assert session.submit("add a car 20 m ahead of the ego").ok
    (car,) = [a for a in session.scene.assets if a.id not in {b.id for b in before.assets}]
    result = session.submit("cone that off")
    assert result.ok, result.error
    cones = [a for a in session.scene.assets if a.category == "traffic_cone"]
    assert len(cones) >= 6
    bearings = sorted(math.atan2(c.pose.y - car.pose.y, c.pose.x - car.pose.x) for c in cones)
    gaps = [b - a for a, b in itertools.pairwise(bearings)] + [bearings[0] + math.tau - bearings[-1]]
    assert max(gaps) < math.pi  # round the car, not beside it


def test_cone_that_off_with_nothing_to_ring_asks_what_and_changes_nothing(session):
    before = session.scene
    result = session.submit("cone that off")
    assert not result.ok and "name the thing" in (result.error or "")
    assert session.scene == before


def test_taking_the_cones_off_the_road_is_no_ring():
    campus = build_campus()
    assert "cordon" not in repair("take the cones off the road", campus).text
    assert repair("please cone off the bench", campus).text.startswith("please cordon off the bench with cones")


def test_cordoning_a_gate_off_with_cones_is_a_line_of_cones_alone(session):
    before = session.scene
    result = session.submit("cordon off the east gate with cones")
    assert result.ok, result.error
    new = {a.category for a in session.scene.assets if a.id not in {b.id for b in before.assets}}
    assert new == {"traffic_cone"}  # not the barriers "cordon off" names when nothing else is said


def test_a_ring_round_a_car_in_its_lane_leaves_out_the_verge_and_says_so(campus):
    with_car = execute(REGISTRY, campus, [ToolCall(tool="add_asset", args={
        "category": "passenger_car", "location": {"relation": "absolute", "x": -40.0, "y": -1.75}})]).after
    done = execute(REGISTRY, with_car, [ToolCall(tool="arrange_assets", args={
        "categories": ["traffic_cone"], "shape": "ring", "location": {"relation": "at", "target": "passenger_car_3"}})])
    cones = [a for a in done.after.assets if a.category == "traffic_cone"]
    assert cones and all(surface_at(done.after, c.pose.x, c.pose.y) != "ground" for c in cones)
    assert "leaving out" in done.results[0].text


def test_a_ring_of_a_count_said_is_never_cut_short(campus):
    with_car = execute(REGISTRY, campus, [ToolCall(tool="add_asset", args={
        "category": "passenger_car", "location": {"relation": "absolute", "x": -40.0, "y": -1.75}})]).after
    with pytest.raises(TransactionError):
        execute(REGISTRY, with_car, [ToolCall(tool="arrange_assets", args={
            "categories": ["traffic_cone"], "shape": "ring", "count": 18,
            "location": {"relation": "at", "target": "passenger_car_3"}})])
