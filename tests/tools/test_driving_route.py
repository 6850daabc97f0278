"""A vehicle sent to a place (follow_path `to`) drives there by the lanes, clear of what stands still."""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable

import pytest
from drivetwin.tools import RuleViolation, ToolResult
from drivetwin.tools.locate import resolve_target
from drivetwin.worlds.catalog import category
from drivetwin.worlds.scene import AssetInstance, FollowPath, Scene
from drivetwin.worlds.simulation import Simulation
from drivetwin.worlds.surface import lane_at, nearest_on_polyline, point_in_polygon

Caller = Callable[..., ToolResult]
# "Got there": within a few metres (a car going to a door stops short of the wall behind it).
REACHED_M = 4.0
# Simulated seconds a car at the default 4 m/s gets for a trip of up to about 200 m (the longest
# trips of the campus, lot A to the Student Union, arrive in about 50 s).
TRIP_S = 70.0
# Of the pairs below, the share whose car arrives. The sweep at the end of this file (each
# parked car and a car added at each landmark, sent to every other landmark) has all 241 arrive,
# the last in 52 s (the 14 from the fountain cannot start: a car cannot stand on the grass).
# Before, when a car with no way by the roads got the straight line, 188 of the 227 without the
# intersection's did.
ARRIVAL_SHARE = 1.0
# Starts and goals across the campus: out of a row of parked cars, turning back in the
# junction or on the road, into a lot, to a door, a gate, an area and the grass.
PAIRS = [
    ("passenger_car_1", "Library entrance"),
    ("passenger_car_2", "Engineering Hall entrance"),
    ("suv_1", "Student Union entrance"),
    ("parking lot A", "east gate"),
    ("parking lot A", "main intersection"),
    ("parking lot B", "parking lot A entrance"),
    ("bus stop", "main gate"),
    ("Engineering Hall entrance", "parking lot B"),
    ("east gate", "fountain"),
    ("main gate", "JTEKT building entrance"),
    ("north crosswalk", "Library entrance"),
    ("Student Union entrance", "west crosswalk"),
]


def _send(call: Caller, scene: Scene, start: str, goal: str) -> tuple[Scene, AssetInstance]:
    """A car sent to `goal`: the parked one called `start`, or a new one added at the place `start`."""
    behaviour = {"kind": "follow_path", "to": goal}
    if scene.asset(start) is not None:
        result = call(scene, "set_behaviour", asset=start, behaviour=behaviour)
        car_id = start
    else:
        result = call(scene, "add_asset", category="passenger_car", location={"relation": "at", "target": start},
                      behaviour=behaviour)
        car_id = result.data["ids"][0]
    after = result.edit.apply(scene)
    car = after.asset(car_id)
    assert car is not None and isinstance(car.behaviour, FollowPath)
    return after, car


def _closest_approach(scene: Scene, car: AssetInstance, place: str) -> float:
    """How near (m) the car came to `place` in at most TRIP_S simulated seconds."""
    return _trip(scene, car, place)[0]


def _trip(scene: Scene, car: AssetInstance, place: str) -> tuple[float, float]:
    """How near (m) the car came to `place` in at most TRIP_S simulated seconds, and when it
    first came within REACHED_M (inf if it never did)."""
    target = resolve_target(scene, place)
    simulation = Simulation(scene)
    for _ in range(int(TRIP_S / 5.0)):
        simulation.run_for(5.0)
        gaps = [(math.dist((x, y), (target.x, target.y)), t) for t, x, y, _ in simulation.trace(car.id)]
        arrived = [t for gap, t in gaps if gap <= REACHED_M]
        if arrived:
            return min(gaps)[0], arrived[0]
    return min(gaps)[0], math.inf


@pytest.mark.parametrize(("start", "goal"), [
    ("Library entrance", "east gate"),  # the straight line ran into street_light_8 and stalled there
    ("main gate", "Student Union entrance"),  # a right turn at the crossroads; straight on is the Library
])
def test_a_car_sent_to_a_place_gets_there_in_mujoco(call: Caller, campus: Scene, start: str, goal: str) -> None:
    scene, car = _send(call, campus, start, goal)
    nearest = _closest_approach(scene, car, goal)
    assert nearest <= REACHED_M, f"{car.id} came no nearer than {nearest:.1f} m to the {goal}"


def test_a_car_leaving_the_library_drop_off_keeps_clear_of_the_street_lights(call: Caller, campus: Scene) -> None:
    _, car = _send(call, campus, "Library entrance", "east gate")
    assert isinstance(car.behaviour, FollowPath)
    half_width = category(car.category).width / 2
    for light in (a for a in campus.assets if a.category == "street_light"):
        for a, b in itertools.pairwise(car.behaviour.waypoints):
            assert nearest_on_polyline(light.pose.x, light.pose.y, [a, b]).distance > half_width + 1.0, light.id


def test_a_car_sent_to_a_place_drives_along_the_lane_that_leads_there(call: Caller, campus: Scene) -> None:
    _, car = _send(call, campus, "Library entrance", "east gate")
    assert isinstance(car.behaviour, FollowPath)
    on_eastbound = [p for p in car.behaviour.waypoints if p[1] == pytest.approx(-1.75)]
    assert on_eastbound and max(x for x, _ in on_eastbound) - min(x for x, _ in on_eastbound) > 100.0
    assert car.behaviour.waypoints[-1] == pytest.approx((100.0, 0.0))


def test_the_suv_parked_in_lot_b_sent_to_the_main_gate_gets_there(call: Caller, campus: Scene) -> None:
    """Between two parked cars it pulls out ahead before it turns; Campus Drive and a left turn
    take it to Main Street westbound (it got the straight line through the Library)."""
    scene, suv = _send(call, campus, "suv_1", "main gate")
    assert isinstance(suv.behaviour, FollowPath)
    library = next(b for b in campus.buildings if b.id == "library")
    assert not any(point_in_polygon(x, y, library.footprint) for x, y in suv.behaviour.waypoints)
    nearest = _closest_approach(scene, suv, "main gate")
    assert nearest <= REACHED_M, f"the SUV came no nearer than {nearest:.1f} m to the main gate"


def test_cars_sent_from_lots_and_roadside_places_to_landmarks_arrive(call: Caller, campus: Scene) -> None:
    missed = []
    for start, goal in PAIRS:
        scene, car = _send(call, campus, start, goal)
        nearest = _closest_approach(scene, car, goal)
        if nearest > REACHED_M:
            missed.append(f"{start} -> {goal}: {nearest:.1f} m")
    share = 1.0 - len(missed) / len(PAIRS)
    assert share >= ARRIVAL_SHARE, f"{share:.0%} arrived; missed: {'; '.join(missed)}"


def test_a_car_facing_away_from_where_it_goes_turns_back_in_the_junction(call: Caller, campus: Scene) -> None:
    """At the bus stop it faces east in the eastbound lane; the main gate is west."""
    _, car = _send(call, campus, "bus stop", "main gate")
    assert isinstance(car.behaviour, FollowPath)
    box = next(area.polygon for area in campus.roads.paved if area.kind == "intersection")
    turning = [(x, y) for x, y in car.behaviour.waypoints if point_in_polygon(x, y, box)]
    assert any(x > 0.0 for x, _ in turning), "it should swing round inside the crossroads box"
    assert car.behaviour.waypoints[-2][1] == pytest.approx(1.75), "and come back along the westbound lane"


@pytest.mark.parametrize("behaviour", [None, {"kind": "follow_path", "to": "Library entrance"}])
def test_a_car_added_at_a_gate_faces_along_the_lane_running_in(call: Caller, campus: Scene,
                                                               behaviour: dict[str, str] | None) -> None:
    """It stood across the road (parallel to the gate) and stalled there."""
    result = call(campus, "add_asset", category="passenger_car", location={"relation": "at", "target": "east gate"},
                  behaviour=behaviour)
    car = result.edit.apply(campus).asset(result.data["ids"][0])
    assert car is not None and lane_at(campus, car.pose.x, car.pose.y) is not None
    assert math.cos(car.pose.yaw - math.pi) == pytest.approx(1.0), "westbound, into the campus"


def test_a_car_hemmed_in_where_it_stands_is_refused_in_one_line(call: Caller, campus: Scene) -> None:
    """A barrier just ahead of the SUV in its row: it drives forwards only, so there is no way out."""
    added = call(campus, "add_asset", category="road_barrier", location={"relation": "absolute", "x": 23.0, "y": -38.5})
    scene = added.edit.apply(campus)
    with pytest.raises(RuleViolation, match=r"^suv_1 cannot drive to main gate: it is hemmed in") as refused:
        call(scene, "set_behaviour", asset="suv_1", behaviour={"kind": "follow_path", "to": "main gate"})
    assert "\n" not in str(refused.value)


def _sweep() -> None:
    """Every parked car and a car added at every landmark of the campus, sent to every other
    landmark and simulated: how many arrive (`python tests/tools/test_driving_route.py`)."""
    from drivetwin.evals.trial import fresh_world
    from drivetwin.tools import ToolCall, ToolError
    from drivetwin.tools.registry import ToolRegistry

    registry = ToolRegistry.default(plugins=False)
    campus = fresh_world("campus")

    def call(scene: Scene, tool: str, **args: object) -> ToolResult:
        return registry.run(ToolCall(tool=tool, args=args), scene)

    parked = [a.id for a in campus.assets if category(a.category).motion == "vehicle"]
    places = [landmark.name for landmark in campus.landmarks]
    outcomes: dict[str, list[str]] = {"arrived": [], "missed": [], "refused": [], "cannot stand there": []}
    longest = 0.0
    for start, goal in itertools.product([*parked, *places], places):
        if start == goal:
            continue
        try:
            scene, car = _send(call, campus, start, goal)
        except ToolError as exc:
            kind = "refused" if "cannot drive" in str(exc) else "cannot stand there"
            outcomes[kind].append(f"{start} -> {goal}: {exc}")
            continue
        nearest, seconds = _trip(scene, car, goal)
        outcomes["arrived" if nearest <= REACHED_M else "missed"].append(f"{start} -> {goal}: {nearest:.1f} m")
        longest = max(longest, seconds if nearest <= REACHED_M else 0.0)
    for kind, pairs in outcomes.items():
        print(f"{kind}: {len(pairs)}")
    print(f"the longest trip arrived in {longest:.0f} s")
    for kind in ("missed", "refused"):
        print(*outcomes[kind], sep="\n")


if __name__ == "__main__":
    _sweep()
