"""Property-based: random tool-call sequences keep Scene and MuJoCo consistent; undo is exact."""

from drivetwin.orchestrator.session import Session
from drivetwin.orchestrator.transaction import TransactionError, execute
from drivetwin.tools import ToolCall, ToolRegistry
from drivetwin.worlds.campus import build_campus
from drivetwin.worlds.mujoco_adapter import MujocoWorld, consistency_problems
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

REGISTRY = ToolRegistry.default(plugins=False)
CAMPUS = build_campus()
CATEGORIES = ["traffic_cone", "road_barrier", "passenger_car", "pedestrian", "bench", "bus", "tree"]
TARGETS = ["JTEKT building entrance", "parking lot B", "main gate", "ego", "fountain", "bus stop"]

locations = st.one_of(
    st.builds(lambda x, y: {"relation": "absolute", "x": x, "y": y},
              st.one_of(st.floats(-150, 150), st.just(float("nan"))), st.floats(-120, 120)),
    st.builds(lambda r, t: {"relation": r, "target": t},
              st.sampled_from(["at", "in_front_of", "behind", "left_of", "next_to", "on_sidewalk"]),
              st.sampled_from(TARGETS)),
    st.just({"relation": "scene_centre"}),
)
adds = st.builds(lambda c, n, loc: ToolCall(tool="add_asset", args={"category": c, "count": n, "location": loc}),
                 st.sampled_from(CATEGORIES), st.integers(1, 4), locations)
removes = st.builds(lambda c: ToolCall(tool="remove_assets", args={"category": c, "count": 1}),
                    st.sampled_from(CATEGORIES))
weathers = st.builds(lambda k: ToolCall(tool="set_weather", args={"kind": k}),
                     st.sampled_from(["clear", "rain", "fog", "snow", "hail"]))
moves = st.builds(lambda i, f: ToolCall(tool="move_asset", args={"asset": i, "forward": f}),
                  st.sampled_from(["passenger_car_1", "suv_1", "bench_1", "nope_1"]), st.floats(-20, 20))
calls = st.lists(st.one_of(adds, removes, weathers, moves), min_size=1, max_size=8)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(calls)
def test_random_call_sequences_keep_scene_and_mujoco_consistent(sequence):
    scene = CAMPUS
    world = MujocoWorld.from_scene(scene)
    for call in sequence:
        try:
            scene = execute(REGISTRY, scene, [call]).after
        except TransactionError:
            continue
        world.update(scene)
        assert consistency_problems(scene, world) == []


class _Fixed:
    """A planner that replays given calls: lets hypothesis drive the session directly."""

    name = "fixed"

    def __init__(self) -> None:
        self.calls: list[ToolCall] = []

    def plan(self, prompt, context):
        from drivetwin.orchestrator.planning import Plan

        return Plan(calls=self.calls, planner=self.name)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.lists(st.one_of(adds, removes, weathers, moves), min_size=1, max_size=3), min_size=1, max_size=5))
def test_undo_always_restores_the_previous_scene_exactly(turns):
    planner = _Fixed()
    session = Session(CAMPUS, planner, REGISTRY)
    scenes = [session.scene]
    for turn in turns:
        planner.calls = turn
        report = session.submit("go")
        if report.ok and report.diff:
            scenes.append(session.scene)
        else:
            assert session.scene == scenes[-1]
    while len(scenes) > 1:
        scenes.pop()
        session.undo()
        assert session.scene == scenes[-1]
