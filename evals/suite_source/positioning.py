"""Positioning cases: an existing asset put at a new place (a landmark, a lane, a point)."""

from __future__ import annotations

from typing import Any

from dsl import (
    Json,
    add,
    call,
    case,
    count,
    delta,
    in_lane,
    loc,
    looks,
    near,
    only,
    relative,
    surface,
)

JTEKT = "JTEKT building entrance"


def _p(cid: str, grade: str, prompt: str, checks: list[Json], ref: list[Json], **kw: Any) -> Json:
    return case(f"positioning.{grade}.{cid}", "positioning", grade, prompt, checks, ref, **kw)


def place(asset: str, where: Json, **kw: Any) -> Json:
    return call("place_asset", asset=asset, location=where, **kw)


BENCH_FOUNTAIN = [near(asset="bench_1", target="fountain", within=10), only(assets=("bench_1",))]
BENCH_FOUNTAIN_REF = [place("bench_1", loc("next_to", "fountain"))]
SUV_JTEKT = [near(asset="suv_1", target=JTEKT, within=12), only(assets=("suv_1",))]
SUV_JTEKT_REF = [place("suv_1", loc("at", JTEKT))]
CAR1_WEST = [in_lane("main_westbound", asset="passenger_car_1", aligned=True), only(assets=("passenger_car_1",))]
CAR1_WEST_REF = [place("passenger_car_1", loc("in_lane", "main_westbound"))]
BIN_LIBRARY = [
    surface(["sidewalk"], asset="trash_bin_1"),
    near(asset="trash_bin_1", target="Library entrance", within=15),
    only(assets=("trash_bin_1",)),
]
BIN_LIBRARY_REF = [place("trash_bin_1", loc("on_sidewalk", "Library entrance"))]
EGO_WEST = [in_lane("main_westbound", asset="ego"), only(assets=("ego",))]
EGO_WEST_REF = [place("ego", loc("in_lane", "main_westbound"))]
HYDRANT_UNION = [
    near(asset="fire_hydrant_1", target="Student Union entrance", within=10),
    relative("in_front_of", "Student Union entrance", asset="fire_hydrant_1"),
    only(assets=("fire_hydrant_1",)),
]
HYDRANT_UNION_REF = [place("fire_hydrant_1", loc("in_front_of", "Student Union entrance"))]
BENCH_LEFT = [relative("left_of", "Library entrance", asset="bench_1", max_distance=10), only(assets=("bench_1",))]
BENCH_LEFT_REF = [place("bench_1", loc("left_of", "Library entrance"))]
CAR2_LOT_A = [near(asset="passenger_car_2", target="parking lot A", within=1), only(assets=("passenger_car_2",))]
CAR2_LOT_A_REF = [place("passenger_car_2", loc("at", "parking lot A"))]
STOP_NORTH = [
    near(asset="stop_sign_1", target="north crosswalk", within=8),
    surface(["sidewalk"], asset="stop_sign_1"),
    only(assets=("stop_sign_1",)),
]
STOP_NORTH_REF = [place("stop_sign_1", loc("on_sidewalk", "north crosswalk"))]
SUV_POINT = [near(asset="suv_1", point=[40.0, -20.0], within=2), only(assets=("suv_1",))]
SUV_POINT_REF = [place("suv_1", loc("absolute", x=40.0, y=-20.0))]
TREE_STOP = [near("tree", "bus stop", 6), count("tree", 4, 4), only("tree")]
TREE_STOP_REF = [place("tree_1", loc("behind", "bus stop"))]


def cases() -> list[Json]:
    return [
        # direct
        _p("bench_fountain", "direct", "Put the bench next to the fountain.", BENCH_FOUNTAIN, BENCH_FOUNTAIN_REF),
        _p("suv_jtekt", "direct", "Place the SUV at the JTEKT building entrance.", SUV_JTEKT, SUV_JTEKT_REF),
        _p("car1_lane", "direct", "Put passenger_car_1 in lane main_westbound.", CAR1_WEST, CAR1_WEST_REF),
        _p(
            "bin_library",
            "direct",
            "Place the trash bin on the sidewalk near the Library entrance.",
            BIN_LIBRARY,
            BIN_LIBRARY_REF,
        ),
        _p("ego_lane", "direct", "Put the ego vehicle in lane main_westbound.", EGO_WEST, EGO_WEST_REF),
        _p(
            "hydrant_union",
            "direct",
            "Place the fire hydrant in front of the Student Union entrance.",
            HYDRANT_UNION,
            HYDRANT_UNION_REF,
        ),
        _p("bench_left", "direct", "Put the bench to the left of the Library entrance.", BENCH_LEFT, BENCH_LEFT_REF),
        _p("car2_lot_a", "direct", "Place passenger_car_2 in parking lot A.", CAR2_LOT_A, CAR2_LOT_A_REF),
        _p(
            "stop_north",
            "direct",
            "Put the stop sign on the sidewalk by the north crosswalk.",
            STOP_NORTH,
            STOP_NORTH_REF,
        ),
        _p("suv_point", "direct", "Position the SUV at x=40, y=-20.", SUV_POINT, SUV_POINT_REF),
        _p(
            "tree_stop",
            "direct",
            "Put tree_1 behind the bus stop.",
            [near(asset="tree_1", target="bus stop", within=6), only(assets=("tree_1",))],
            TREE_STOP_REF,
        ),
        # indirect
        _p(
            "bench_relax",
            "indirect",
            "The bench would be better by the fountain where people relax.",
            BENCH_FOUNTAIN,
            BENCH_FOUNTAIN_REF,
        ),
        _p(
            "suv_visitors",
            "indirect",
            "Our SUV should be waiting for the JTEKT visitors at their entrance.",
            SUV_JTEKT,
            SUV_JTEKT_REF,
        ),
        _p(
            "car1_west",
            "indirect",
            "Passenger car one belongs on the westbound side of Main Street.",
            CAR1_WEST,
            CAR1_WEST_REF,
        ),
        _p(
            "bin_walkway",
            "indirect",
            "The trash bin belongs at the library, on the walkway.",
            BIN_LIBRARY,
            BIN_LIBRARY_REF,
        ),
        _p(
            "ego_other_side",
            "indirect",
            "Let the test start with our car in the westbound lane of Main Street.",
            EGO_WEST,
            EGO_WEST_REF,
        ),
        _p(
            "hydrant_door",
            "indirect",
            "The Student Union wants its hydrant by the front door.",
            [HYDRANT_UNION[0], HYDRANT_UNION[2]],
            HYDRANT_UNION_REF,
        ),
        _p(
            "bench_readers",
            "indirect",
            "Readers leaving the library should find the bench right beside the entrance.",
            [near(asset="bench_1", target="Library entrance", within=8), only(assets=("bench_1",))],
            BENCH_LEFT_REF,
        ),
        _p("car2_west_lot", "indirect", "Park the second car over in the west lot.", CAR2_LOT_A, CAR2_LOT_A_REF),
        _p(
            "stop_north_crossing",
            "indirect",
            "The stop sign should protect the north crossing instead.",
            [STOP_NORTH[0], STOP_NORTH[2]],
            STOP_NORTH_REF,
        ),
        _p(
            "shade",
            "indirect",
            "The bus stop needs shade: one of the trees should stand just behind it.",
            TREE_STOP,
            TREE_STOP_REF,
        ),
        # vague
        _p("bench_fountain", "vague", "bench by the fountain", BENCH_FOUNTAIN, BENCH_FOUNTAIN_REF),
        _p("suv_jtekt", "vague", "suv to jtekt", SUV_JTEKT, SUV_JTEKT_REF),
        _p(
            "bin_library",
            "vague",
            "put the bin somewhere near the library",
            [near(asset="trash_bin_1", target="Library entrance", within=15), only(assets=("trash_bin_1",))],
            BIN_LIBRARY_REF,
        ),
        _p(
            "hydrant_union",
            "vague",
            "the hydrant should be over by the union",
            [
                near(asset="fire_hydrant_1", target="Student Union entrance", within=12),
                only(assets=("fire_hydrant_1",)),
            ],
            HYDRANT_UNION_REF,
        ),
        _p(
            "car1_road",
            "vague",
            "car 1 onto the road",
            [in_lane(None, asset="passenger_car_1"), only(assets=("passenger_car_1",))],
            CAR1_WEST_REF,
        ),
        _p(
            "bench_closer",
            "vague",
            "bench closer to the library",
            [near(asset="bench_1", target="Library entrance", within=10), only(assets=("bench_1",))],
            BENCH_LEFT_REF,
        ),
        _p("stop_north", "vague", "stop sign to the north crossing", [STOP_NORTH[0], STOP_NORTH[2]], STOP_NORTH_REF),
        _p("car2_lot_a", "vague", "the second car goes in lot A", CAR2_LOT_A, CAR2_LOT_A_REF),
        _p(
            "tree_behind_stop",
            "vague",
            "a tree behind the bus stop please",
            [],
            TREE_STOP_REF,
            alternatives=[
                [near("tree", "bus stop", 6), count("tree", 4, 4), only("tree")],
                [delta("tree", 1, 1), near("tree", "bus stop", 6), only("tree")],
            ],
        ),
        _p("ego_west", "vague", "ego to the westbound side", EGO_WEST, EGO_WEST_REF),
        # erroneous
        _p("bench_fountain", "erroneous", "put the bench nexto fountain", BENCH_FOUNTAIN, BENCH_FOUNTAIN_REF),
        _p("suv_jtekt", "erroneous", "place suv in jtekt entrence", SUV_JTEKT, SUV_JTEKT_REF),
        _p("car1_lane", "erroneous", "put passanger car 1 on lane main westbond", CAR1_WEST, CAR1_WEST_REF),
        _p("bin_library", "erroneous", "place trash bin on sidewalk near of library", BIN_LIBRARY, BIN_LIBRARY_REF),
        _p("hydrant_union", "erroneous", "put hidrant infront of student union", HYDRANT_UNION, HYDRANT_UNION_REF),
        _p("bench_left", "erroneous", "place bench at left of libary entrance", BENCH_LEFT, BENCH_LEFT_REF),
        _p("car2_lot_a", "erroneous", "park the passenger car 2 on parking lot a", CAR2_LOT_A, CAR2_LOT_A_REF),
        _p("stop_north", "erroneous", "put stop sing on sidewalk by north crosswalk", STOP_NORTH, STOP_NORTH_REF),
        _p("suv_point", "erroneous", "place the suv to x 40 y -20", SUV_POINT, SUV_POINT_REF),
        _p("ego_lane", "erroneous", "put ego car on main westbound lane", EGO_WEST, EGO_WEST_REF),
        _p(
            "paint_and_park",
            "direct",
            "Paint the SUV yellow and park it at the JTEKT entrance.",
            [SUV_JTEKT[0], looks("yellow", asset="suv_1"), only(assets=("suv_1",))],
            [call("set_asset_appearance", assets=["suv_1"], colour="yellow"), *SUV_JTEKT_REF],
            tags=["compound"],
        ),
        _p(
            "robot_to_lot_a",
            "direct",
            "Now put it in parking lot A.",
            [near(asset="ackermann_robot_1", target="parking lot A", within=1), only(assets=("ackermann_robot_1",))],
            [place("ackermann_robot_1", loc("at", "parking lot A"))],
            setup=[
                {
                    "prompt": "Add a robot in parking lot B.",
                    "calls": [add("ackermann_robot", loc("at", "parking lot B"))],
                    "planned": True,
                }
            ],
            tags=["multi_turn"],
        ),
    ]
