import math

import pytest
from drivetwin.orchestrator.planning import PlanContext, PlanningError
from drivetwin.orchestrator.planning.rules.planner import RulePlanner


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


def plan_for(scene, registry, prompt):
    return RulePlanner().plan(prompt, PlanContext(scene=scene, registry=registry))


def test_typos_are_repaired_against_known_words(campus, registry):
    calls = calls_for(campus, registry, "plase ad two benchs beside the libary")
    assert calls[0].tool == "add_asset"
    assert calls[0].args["category"] == "bench" and calls[0].args["count"] == 2
    assert calls[0].args["location"]["target"] == "Library entrance"


def test_run_together_words_are_split(campus, registry):
    calls = calls_for(campus, registry, "delete the firehydrant")
    assert calls == [c for c in calls if c.tool == "remove_assets"] and calls[0].args["category"] == "fire_hydrant"


@pytest.mark.parametrize("verb", ["get rid of", "take away", "ditch", "throw out"])
def test_removal_idioms_remove(campus, registry, verb):
    calls = calls_for(campus, registry, f"{verb} the rubbish bin")
    assert calls[0].tool == "remove_assets" and calls[0].args["category"] == "trash_bin"


def test_a_place_name_is_not_read_as_its_words(campus, registry):
    calls = calls_for(campus, registry, "drop a bollard by the shuttle stop")
    assert calls[0].args["category"] == "bollard" and calls[0].args["location"]["target"] == "bus stop"


def test_a_numbered_name_means_the_existing_asset(campus, registry):
    calls = calls_for(campus, registry, "have car number 1 back up a little")
    assert calls == calls_for(campus, registry, "back up car 1 a little")
    assert calls[0].tool == "move_asset" and calls[0].args["asset"] == "passenger_car_1"
    assert calls[0].args["forward"] < 0


def test_the_definite_article_moves_what_is_there_and_a_adds(campus, registry):
    moved = calls_for(campus, registry, "the SUV belongs in lot A")
    added = calls_for(campus, registry, "an SUV in lot A")
    assert moved[0].tool == "place_asset" and moved[0].args["asset"] == "suv_1"
    assert added[0].tool == "add_asset"


def test_a_stated_goal_becomes_the_environment_it_needs(campus, registry):
    assert calls_for(campus, registry, "we are checking how the sensors cope with puddles")[0].args["kind"] == "rain"
    assert calls_for(campus, registry, "the sunshine should come back")[0].args["kind"] == "clear"


def test_one_clause_can_set_time_and_weather(campus, registry):
    tools = {c.tool for c in calls_for(campus, registry, "a foggy night run please")}
    assert tools == {"set_weather", "set_time_of_day"}


def test_a_finished_activity_clears_its_things(campus, registry):
    calls = calls_for(campus, registry, "the trees are no longer needed")
    assert calls[0].tool == "remove_assets" and calls[0].args == {"category": "tree"}


def test_stop_as_a_verb_is_not_a_stop_sign(campus, registry):
    calls = calls_for(campus, registry, "halt our car")
    assert calls[0].tool == "set_behaviour" and calls[0].args["behaviour"]["kind"] == "parked"
    assert calls_for(campus, registry, "stop the ego")[0].args["asset"] == "ego"


def test_a_row_of_is_not_one(campus, registry):
    calls = calls_for(campus, registry, "plant a row of oaks outside the engineering building")
    assert calls[0].tool == "arrange_assets" and calls[0].args["shape"] == "line"
    assert calls[0].args.get("count") != 1


def test_a_question_inside_a_sentence_is_answered(campus, registry):
    calls = calls_for(campus, registry, "I wonder how many lamp posts there are")
    assert calls[0].tool == "find_assets" and calls[0].args["category"] == "street_light"


def test_there_refers_to_the_place_named_earlier_in_the_prompt(campus, registry):
    calls = calls_for(campus, registry, "remove the bin at the bus stop, then put a bench there")
    assert calls[1].tool == "add_asset" and calls[1].args["location"]["target"] == "bus stop"


def test_confidence_stays_high_when_every_word_is_understood(campus, registry):
    assert plan_for(campus, registry, "add 2 road barriers behind the bus stop").confidence > 0.9


def test_confidence_drops_when_the_rules_guessed(campus, registry):
    repaired = plan_for(campus, registry, "remove the benh")
    defaulted = plan_for(campus, registry, "spin the bench")
    assert max(repaired.confidence, defaulted.confidence) < 0.8


def test_a_place_the_world_lacks_is_refused_by_name_not_guessed(campus, registry):
    with pytest.raises(PlanningError, match="'gizmo'"):
        plan_for(campus, registry, "add a cone near the gizmo")


def test_an_impossible_request_is_still_refused(campus, registry):
    with pytest.raises(PlanningError, match="unknown asset 'spaceship'"):
        calls_for(campus, registry, "put a spaceship at the fountain")
