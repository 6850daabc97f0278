import math

import pytest
from drivetwin.orchestrator.planning import PlanContext, PlanningError
from drivetwin.orchestrator.rule_planner import RulePlanner


def calls_for(scene, registry, prompt):
    return RulePlanner().plan(prompt, PlanContext(scene=scene, registry=registry)).calls


@pytest.mark.parametrize(("prompt", "kind"), [
    ("make it rain", "rain"), ("make it foggy", "fog"), ("make it snow", "snow"),
    ("clear the weather", "clear"), ("heavy rain please", "rain"),
])
def test_weather_prompts_set_the_weather(session, prompt, kind):
    assert session.submit(prompt).ok
    assert session.scene.environment.weather.kind == kind


def test_heavy_and_light_set_the_intensity(session):
    session.submit("make it rain heavily")
    heavy = session.scene.environment.weather.intensity
    session.submit("light fog")
    assert heavy > 0.8 and session.scene.environment.weather.intensity < 0.4


@pytest.mark.parametrize(("prompt", "night"), [("make it night", True), ("make it daytime", False)])
def test_time_prompts_set_the_clock(session, prompt, night):
    session.submit("make it night" if not night else "make it daytime")
    assert session.submit(prompt).ok
    assert session.scene.environment.is_night is night


def test_the_three_turn_maintenance_sequence(session):
    assert session.submit("create cement rubble at the centre of the scene").ok
    assert session.submit("add traffic cones to mark the maintenance").ok
    assert session.submit("also add road barriers around there").ok
    scene = session.scene
    rubble = next(a for a in scene.assets if a.category == "cement_rubble")
    cones = [a for a in scene.assets if a.category == "traffic_cone"]
    barriers = [a for a in scene.assets if a.category == "road_barrier"]
    def dist(a):
        return math.hypot(a.pose.x - rubble.pose.x, a.pose.y - rubble.pose.y)
    assert len(cones) >= 6 and len(barriers) >= 4
    assert max(map(dist, cones)) < min(map(dist, barriers)) < 8.0


def test_parked_car_at_the_jtekt_entrance(session):
    assert session.submit("add a parked car at the JTEKT building entrance").ok
    car = next(a for a in session.scene.assets if a.id == session.memory.last_added()[0])
    entrance = session.scene.landmark("JTEKT building entrance")
    assert car.category == "passenger_car" and car.behaviour.kind == "parked"
    assert math.dist(car.pose.xy, entrance.position) < 6.0


def test_skidpad_robot_and_jaywalker(session):
    assert session.submit("add a mid-scale Ackermann-steered robot performing a skidpad maneuver").ok
    assert session.submit("make a jaywalking pedestrian cut across the ego vehicle's path").ok
    kinds = {a.category: a.behaviour.kind for a in session.scene.assets}
    assert kinds["ackermann_robot"] == "circle" and kinds["pedestrian"] == "jaywalk"


def test_references_to_earlier_assets(session):
    session.submit("add 4 traffic cones in front of the ego vehicle")
    added = session.memory.last_added()
    assert session.submit("remove the cones you added").ok
    assert all(session.scene.asset(i) is None for i in added)


def test_move_an_asset_by_id(session):
    before = session.scene.asset("passenger_car_1").pose
    assert session.submit("move passenger_car_1 3 m forward").ok
    after = session.scene.asset("passenger_car_1").pose
    assert math.isclose(math.hypot(after.x - before.x, after.y - before.y), 3.0, abs_tol=1e-6)


def test_questions_are_answered_without_edits(session):
    before = session.scene
    report = session.submit("where are the street lights?")
    assert report.ok and "street_light_1" in report.answer and session.scene == before


def test_misspelled_prompt_gets_low_confidence(campus, registry):
    plan = RulePlanner().plan("ad a trafic cone nex to the fountian", PlanContext(scene=campus, registry=registry))
    assert plan.confidence < 0.7
    plain = RulePlanner().plan("add a traffic cone next to the fountain", PlanContext(scene=campus, registry=registry))
    assert plain.confidence > 0.9


def test_nonsense_is_a_planning_error(campus, registry):
    with pytest.raises(PlanningError):
        calls_for(campus, registry, "qwerty uiop")
    with pytest.raises(PlanningError, match="unknown asset 'tank'"):
        calls_for(campus, registry, "add a tank")
