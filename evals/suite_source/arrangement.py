"""Arrangement cases: several assets laid out as a line or a ring, with spacing, in context."""

from __future__ import annotations

from typing import Any

from dsl import (
    CONES,
    RUBBLE,
    Json,
    arrange,
    case,
    delta,
    in_lane,
    loc,
    near,
    only,
    shape,
    step,
)

JTEKT = "JTEKT building entrance"
BLOCKERS = ["traffic_cone", "road_barrier", "cement_rubble", "bollard", "construction_sign"]


def _g(cid: str, grade: str, prompt: str, checks: list[Json], ref: list[Json], **kw: Any) -> Json:
    return case(f"arrangement.{grade}.{cid}", "arrangement", grade, prompt, checks, ref, **kw)


CONE_LINE = [
    delta("traffic_cone", 6, 6),
    shape("line", "traffic_cone", tolerance=1.0),
    in_lane("main_westbound", "traffic_cone", every=True),
    near("traffic_cone", JTEKT, 25, every=True),
    only("traffic_cone"),
]
CONE_LINE_REF = [arrange(["traffic_cone"], "line", loc("in_lane", JTEKT), count=6)]
BOLLARD_RING = [
    delta("bollard", 8, 8),
    shape("ring", "bollard", around="fountain"),
    near("bollard", "fountain", 8, every=True),
    only("bollard"),
]
BOLLARD_RING_REF = [arrange(["bollard"], "ring", loc("at", "fountain"), count=8)]
CONE_RING = [
    delta("traffic_cone", 3),
    shape("ring", "traffic_cone", around="cement_rubble_1", tolerance=1.5),
    near("traffic_cone", "cement_rubble_1", 8, every=True),
    only("traffic_cone"),
]
CONE_RING_REF = [arrange(["traffic_cone"], "ring", loc("at", "cement_rubble_1"))]
BOLLARD_ROW = [
    delta("bollard", 5, 5),
    shape("line", "bollard", spacing=(1.7, 2.3)),
    near("bollard", "Engineering Hall entrance", 8, every=True),
    only("bollard"),
]
BOLLARD_ROW_REF = [arrange(["bollard"], "line", loc("in_front_of", "Engineering Hall entrance"), count=5, spacing=2.0)]
BENCH_GRID = [
    delta("bench", 4, 4),
    shape("cluster", "bench", tolerance=8),
    near("bench", "parking lot A", 1, every=True),
    only("bench"),
]
BENCH_GRID_REF = [arrange(["bench"], "grid", loc("at", "parking lot A"), count=4)]
TREE_LINE = [
    delta("tree", 4, 4),
    shape("line", "tree", spacing=(3.5, 4.5)),
    near("tree", "Student Union entrance", 12, every=True),
    only("tree"),
]
TREE_LINE_REF = [arrange(["tree"], "line", loc("in_front_of", "Student Union entrance"), count=4, spacing=4.0)]
GATE_CONES = [
    delta("traffic_cone", 5, 5),
    shape("line", "traffic_cone"),
    near("traffic_cone", "east gate", 8, every=True),
    only("traffic_cone"),
]
GATE_CONES_REF = [arrange(["traffic_cone"], "line", loc("in_front_of", "east gate"), count=5)]
BARRIER_RING = [
    delta("road_barrier", 6, 6),
    shape("ring", "road_barrier", around="cement_rubble_1", tolerance=1.5),
    near("road_barrier", "cement_rubble_1", 10, every=True),
    only("road_barrier"),
]
BARRIER_RING_REF = [arrange(["road_barrier"], "ring", loc("at", "cement_rubble_1"), count=6)]
GATE_BOLLARDS = [
    delta("bollard", 6, 6),
    shape("line", "bollard"),
    near("bollard", "main gate", 8, every=True),
    only("bollard"),
]
GATE_BOLLARDS_REF = [arrange(["bollard"], "line", loc("in_front_of", "main gate"), count=6)]
LANE_EDGE = [
    delta("traffic_cone", 8, 8),
    shape("line", "traffic_cone", tolerance=0.5),
    in_lane("main_eastbound", "traffic_cone", every=True),
    near("traffic_cone", "bus stop", 30, every=True),
    only("traffic_cone"),
]
LANE_EDGE_REF = [arrange(["traffic_cone"], "lane_edge", loc("at", "bus stop"), count=8)]
MAINT_CONES = [delta("traffic_cone", 3), near("traffic_cone", "cement_rubble_1", 8, every=True), only("traffic_cone")]
AROUND_THERE = [delta("road_barrier", 2), near("road_barrier", "cement_rubble_1", 12, every=True), only("road_barrier")]
AROUND_THERE_REF = [arrange(["road_barrier"], "ring", loc("at", "cement_rubble_1"), radius=5.0, count=8)]


def cases() -> list[Json]:
    rubble = [RUBBLE]
    maint = [RUBBLE, CONES]
    mt = ["multi_turn"]
    paper = ["paper", "multi_turn"]
    return [
        # direct
        _g(
            "cone_line",
            "direct",
            "Place 6 traffic cones in a line in the westbound lane outside the JTEKT building entrance.",
            CONE_LINE,
            CONE_LINE_REF,
        ),
        _g("bollard_ring", "direct", "Put 8 bollards in a ring around the fountain.", BOLLARD_RING, BOLLARD_RING_REF),
        _g(
            "cone_ring",
            "direct",
            "Place traffic cones in a ring around the cement rubble.",
            CONE_RING,
            CONE_RING_REF,
            setup=rubble,
            tags=mt,
        ),
        _g(
            "bollard_row",
            "direct",
            "Put 5 bollards in a row in front of the Engineering Hall entrance, 2 metres apart.",
            BOLLARD_ROW,
            BOLLARD_ROW_REF,
        ),
        _g("bench_grid", "direct", "Arrange 4 benches in a grid in parking lot A.", BENCH_GRID, BENCH_GRID_REF),
        _g(
            "tree_line",
            "direct",
            "Place 4 trees in a line in front of the Student Union entrance, 4 metres apart.",
            TREE_LINE,
            TREE_LINE_REF,
        ),
        _g(
            "gate_cones",
            "direct",
            "Put 5 traffic cones in a line across Main Street at the east gate.",
            GATE_CONES,
            GATE_CONES_REF,
        ),
        _g(
            "barrier_ring",
            "direct",
            "Arrange 6 road barriers in a ring around the cement rubble.",
            BARRIER_RING,
            BARRIER_RING_REF,
            setup=rubble,
            tags=mt,
        ),
        _g(
            "gate_bollards",
            "direct",
            "Put 6 bollards in a line in front of the main gate.",
            GATE_BOLLARDS,
            GATE_BOLLARDS_REF,
        ),
        _g(
            "lane_edge",
            "direct",
            "Line the edge of lane main_eastbound with 8 traffic cones, starting at the bus stop.",
            LANE_EDGE,
            LANE_EDGE_REF,
        ),
        _g(
            "small_ring",
            "direct",
            "Arrange 12 bollards in a ring of radius 4 m around the fountain.",
            [
                delta("bollard", 12, 12),
                shape("ring", "bollard", around="fountain"),
                near("bollard", "fountain", 5, every=True),
                only("bollard"),
            ],
            [arrange(["bollard"], "ring", loc("at", "fountain"), count=12, radius=4.0)],
        ),
        # indirect
        _g(
            "mark_maintenance",
            "indirect",
            "add traffic cones to mark the maintenance",
            MAINT_CONES,
            [arrange(["traffic_cone"], "ring", loc("at", "cement_rubble_1"))],
            setup=rubble,
            tags=paper,
        ),
        _g(
            "around_there",
            "indirect",
            "also add road barriers around there",
            AROUND_THERE,
            AROUND_THERE_REF,
            setup=maint,
            tags=paper,
        ),
        _g(
            "close_gate",
            "indirect",
            "Close Main Street at the east gate.",
            [delta(BLOCKERS, 3), near(BLOCKERS, "east gate", 10, n=3), only(*BLOCKERS)],
            GATE_CONES_REF,
        ),
        _g(
            "protect_fountain",
            "indirect",
            "The fountain needs protecting with some bollards all the way around it.",
            [delta("bollard", 4), shape("ring", "bollard", around="fountain"), only("bollard")],
            BOLLARD_RING_REF,
        ),
        _g(
            "lecture",
            "indirect",
            "Set up seating for an outdoor lecture in parking lot A.",
            [delta("bench", 3), near("bench", "parking lot A", 1, every=True), only("bench")],
            BENCH_GRID_REF,
        ),
        _g(
            "guide_cones",
            "indirect",
            "Keep drivers away from the kerb at the bus stop with cones along the lane.",
            [
                delta("traffic_cone", 3),
                shape("line", "traffic_cone"),
                in_lane("main_eastbound", "traffic_cone", every=True),
                near("traffic_cone", "bus stop", 30),
                only("traffic_cone"),
            ],
            LANE_EDGE_REF,
        ),
        _g(
            "avenue",
            "indirect",
            "Plant an avenue of trees in front of the Student Union.",
            [
                delta("tree", 3),
                shape("line", "tree", tolerance=1.5),
                near("tree", "Student Union entrance", 15, every=True),
                only("tree"),
            ],
            TREE_LINE_REF,
        ),
        _g(
            "work_zone",
            "indirect",
            "Mark off the work zone around the rubble with barriers.",
            [
                delta("road_barrier", 3),
                shape("ring", "road_barrier", around="cement_rubble_1", tolerance=2.0),
                only("road_barrier"),
            ],
            BARRIER_RING_REF,
            setup=rubble,
            tags=mt,
        ),
        _g(
            "stop_gate",
            "indirect",
            "Stop cars from driving in through the main gate with a row of bollards.",
            [
                delta("bollard", 3),
                shape("line", "bollard"),
                near("bollard", "main gate", 10, every=True),
                only("bollard"),
            ],
            GATE_BOLLARDS_REF,
        ),
        _g(
            "no_go_lane",
            "indirect",
            "Make the eastbound lane by the bus stop a no-go zone with cones.",
            [
                delta("traffic_cone", 3),
                in_lane("main_eastbound", "traffic_cone", every=True),
                near("traffic_cone", "bus stop", 30),
                only("traffic_cone"),
            ],
            LANE_EDGE_REF,
        ),
        # vague
        _g("cones_rubble", "vague", "cones around the rubble", MAINT_CONES, CONE_RING_REF, setup=rubble, tags=mt),
        _g(
            "bollards_fountain",
            "vague",
            "some bollards around the fountain",
            [delta("bollard", 2), near("bollard", "fountain", 10, every=True), only("bollard")],
            BOLLARD_RING_REF,
        ),
        _g(
            "barriers_gate",
            "vague",
            "barriers at the east gate",
            [delta("road_barrier", 2), near("road_barrier", "east gate", 12, every=True), only("road_barrier")],
            [arrange(["road_barrier"], "line", loc("in_front_of", "east gate"), count=3)],
        ),
        _g(
            "tree_row",
            "vague",
            "a row of trees somewhere",
            [delta("tree", 3), shape("line", "tree", tolerance=1.5), only("tree")],
            TREE_LINE_REF,
        ),
        _g(
            "benches_lot_a",
            "vague",
            "benches in lot A",
            [delta("bench", 2), near("bench", "parking lot A", 1, every=True), only("bench")],
            BENCH_GRID_REF,
        ),
        _g(
            "line_of_cones",
            "vague",
            "line of cones",
            [delta("traffic_cone", 3), shape("line", "traffic_cone"), only("traffic_cone")],
            CONE_LINE_REF,
        ),
        _g(
            "circle_bollards",
            "vague",
            "circle of bollards",
            [delta("bollard", 3), shape("ring", "bollard"), only("bollard")],
            BOLLARD_RING_REF,
        ),
        _g(
            "block_road",
            "vague",
            "block the road near the intersection",
            [delta(BLOCKERS, 2), near(BLOCKERS, "main intersection", 25, n=2), only(*BLOCKERS)],
            [arrange(["road_barrier"], "line", loc("in_front_of", "west crosswalk"), count=4)],
        ),
        _g(
            "cones_jtekt",
            "vague",
            "a few cones in front of JTEKT",
            [delta("traffic_cone", 2), near("traffic_cone", JTEKT, 15, every=True), only("traffic_cone")],
            CONE_LINE_REF,
        ),
        _g(
            "fence_off",
            "vague",
            "fence off the work area",
            [],
            BARRIER_RING_REF,
            setup=rubble,
            tags=mt,
            alternatives=[
                [
                    delta("road_barrier", 2),
                    near("road_barrier", "cement_rubble_1", 12, every=True),
                    only("road_barrier"),
                ],
                [
                    delta("traffic_cone", 3),
                    near("traffic_cone", "cement_rubble_1", 12, every=True),
                    only("traffic_cone"),
                ],
            ],
        ),
        # erroneous
        _g(
            "cone_line",
            "erroneous",
            "put 6 trafic cone in line on westbound lane front of jtekt",
            CONE_LINE,
            CONE_LINE_REF,
        ),
        _g("bollard_ring", "erroneous", "8 bolards in circle around the fontain", BOLLARD_RING, BOLLARD_RING_REF),
        _g(
            "cone_ring",
            "erroneous",
            "put cones in ring around cement rubbel",
            CONE_RING,
            CONE_RING_REF,
            setup=rubble,
            tags=mt,
        ),
        _g("bench_grid", "erroneous", "arange 4 bench like grid in parking lot a", BENCH_GRID, BENCH_GRID_REF),
        _g(
            "tree_line",
            "erroneous",
            "place 4 tree in line infront student union 4 meter between",
            TREE_LINE,
            TREE_LINE_REF,
        ),
        _g("gate_cones", "erroneous", "put 5 cone across main street on east gate", GATE_CONES, GATE_CONES_REF),
        _g(
            "barrier_ring",
            "erroneous",
            "arrange 6 road barier in ring around the rubble",
            BARRIER_RING,
            BARRIER_RING_REF,
            setup=rubble,
            tags=mt,
        ),
        _g(
            "gate_bollards",
            "erroneous",
            "6 bollard in row in front of main gate please",
            GATE_BOLLARDS,
            GATE_BOLLARDS_REF,
        ),
        _g(
            "mark_maintenance",
            "erroneous",
            "add trafic cones for mark the maintenence",
            MAINT_CONES,
            [arrange(["traffic_cone"], "ring", loc("at", "cement_rubble_1"))],
            setup=rubble,
            tags=paper,
        ),
        _g(
            "around_there",
            "erroneous",
            "also add road bariers arround there",
            AROUND_THERE,
            AROUND_THERE_REF,
            setup=maint,
            tags=paper,
        ),
        _g(
            "paper_sequence",
            "indirect",
            "also add road barriers around there",
            AROUND_THERE,
            AROUND_THERE_REF,
            setup=[{**RUBBLE, "planned": True}, {**CONES, "planned": True}],
            tags=["paper", "multi_turn"],
            notes="The paper's three-turn maintenance scene, every turn planned by the planner.",
        ),
        _g(
            "rubble_and_cones",
            "direct",
            "Add cement rubble at the centre of the scene and surround it with traffic cones.",
            [
                delta("cement_rubble", 1, 1),
                delta("traffic_cone", 3),
                near("traffic_cone", "main intersection", 12, every=True),
                only("cement_rubble", "traffic_cone"),
            ],
            [*RUBBLE["calls"], *CONE_RING_REF],
            tags=["compound"],
        ),
        _g(
            "cones_planned",
            "indirect",
            "now put barriers behind the cones as well",
            [delta("road_barrier", 2), near("road_barrier", "cement_rubble_1", 12, every=True), only("road_barrier")],
            AROUND_THERE_REF,
            setup=[RUBBLE, step("add traffic cones around it", *CONES["calls"], planned=True)],
            tags=["multi_turn"],
        ),
    ]
