"""Removal cases: the right assets gone, everything else left alone."""

from __future__ import annotations

from typing import Any

from dsl import (
    CAR_AT_JTEKT,
    CONES,
    CONES_AT_JTEKT,
    PEDESTRIAN,
    ROBOT,
    RUBBLE,
    TRUCK_AT_UNION,
    TWO_PEDESTRIANS,
    VEHICLES,
    Json,
    add,
    behaviour,
    call,
    case,
    count,
    delta,
    exactly,
    gone,
    loc,
    near,
    only,
    step,
)


def _r(cid: str, grade: str, prompt: str, checks: list[Json], ref: list[Json], **kw: Any) -> Json:
    return case(f"removal.{grade}.{cid}", "removal", grade, prompt, checks, ref, **kw)


def rm(*ids: str) -> Json:
    return call("remove_assets", assets=list(ids))


def rm_all(category: str, near: str | None = None, n: int | None = None) -> Json:
    return call("remove_assets", category=category, near=near, count=n)


BENCH = [gone("bench_1"), exactly("bench", -1), only("bench")]
LOT_B_CARS = [gone("passenger_car_1", "passenger_car_2"), only(*VEHICLES)]
LOT_B_REF = [rm("passenger_car_1", "passenger_car_2")]
HYDRANT = [gone("fire_hydrant_1"), only("fire_hydrant")]
STOP = [gone("stop_sign_1"), only("stop_sign")]
BIN = [gone("trash_bin_1"), only("trash_bin")]
SUV = [gone("suv_1"), only("suv")]
TREE_FOUNTAIN = [gone("tree_2"), exactly("tree", -1), only("tree")]
CONES_GONE = [count("traffic_cone", 0, 0), only("traffic_cone")]
RUBBLE_GONE = [count("cement_rubble", 0, 0), only("cement_rubble")]
LIGHT = [gone("street_light_4"), exactly("street_light", -1), only("street_light")]
PEDS_GONE = [count("pedestrian", 0, 0), only("pedestrian")]
MAINTENANCE = [RUBBLE, CONES]
ROBOT_CIRCLING = step(
    "add a robot doing skidpad circles in parking lot B",
    add("ackermann_robot", loc("at", "parking lot B"), behaviour=behaviour("circle")),
)
THREE_PEDS = step("add three pedestrians at the bus stop", add("pedestrian", loc("at", "bus stop"), count=3))


def cases() -> list[Json]:
    mt = ["multi_turn"]
    return [
        # direct
        _r("bench", "direct", "Remove the bench at the bus stop.", BENCH, [rm("bench_1")]),
        _r("lot_b_cars", "direct", "Remove the passenger cars from parking lot B.", LOT_B_CARS, LOT_B_REF),
        _r("hydrant", "direct", "Remove the fire hydrant.", HYDRANT, [rm("fire_hydrant_1")]),
        _r("stop_sign", "direct", "Remove the stop sign near the west crosswalk.", STOP, [rm("stop_sign_1")]),
        _r("bin", "direct", "Remove the trash bin.", BIN, [rm("trash_bin_1")]),
        _r("suv", "direct", "Remove the SUV.", SUV, [rm("suv_1")]),
        _r("tree_2", "direct", "Remove tree_2.", TREE_FOUNTAIN, [rm("tree_2")]),
        _r(
            "tree_fountain",
            "direct",
            "Remove the tree next to the fountain.",
            TREE_FOUNTAIN,
            [rm_all("tree", "fountain", 1)],
        ),
        _r(
            "cones",
            "direct",
            "Remove all the traffic cones.",
            CONES_GONE,
            [rm_all("traffic_cone")],
            setup=[CONES_AT_JTEKT],
            tags=mt,
        ),
        _r(
            "rubble",
            "direct",
            "Remove the cement rubble at the intersection.",
            RUBBLE_GONE,
            [rm_all("cement_rubble")],
            setup=[RUBBLE],
            tags=mt,
        ),
        _r(
            "street_light",
            "direct",
            "Remove the street light closest to the bus stop.",
            LIGHT,
            [rm_all("street_light", "bus stop", 1)],
        ),
        _r(
            "pedestrians",
            "direct",
            "Remove the two pedestrians.",
            PEDS_GONE,
            [rm_all("pedestrian")],
            setup=[TWO_PEDESTRIANS],
            tags=mt,
        ),
        # indirect
        _r(
            "cluttered_stop", "indirect", "The bus stop is too cluttered, get rid of the bench.", BENCH, [rm("bench_1")]
        ),
        _r(
            "empty_lot",
            "indirect",
            "Parking lot B should be empty for the robot test.",
            [gone("passenger_car_1", "passenger_car_2", "suv_1"), only(*VEHICLES)],
            [rm("passenger_car_1", "passenger_car_2", "suv_1")],
        ),
        _r(
            "maintenance_done",
            "indirect",
            "The maintenance is finished, clear the roadworks away.",
            [count("traffic_cone", 0, 0), count("cement_rubble", 0, 0), only("traffic_cone", "cement_rubble")],
            [rm_all("traffic_cone"), rm_all("cement_rubble")],
            setup=MAINTENANCE,
            tags=[*mt, "paper"],
        ),
        _r(
            "hydrant_view",
            "indirect",
            "The hydrant is blocking the view at the corner, lose it.",
            HYDRANT,
            [rm("fire_hydrant_1")],
        ),
        _r(
            "no_stop_sign",
            "indirect",
            "We no longer need a stop sign at the west crosswalk; the lights handle it.",
            STOP,
            [rm("stop_sign_1")],
        ),
        _r(
            "nobody_parked",
            "indirect",
            "Nobody should be parked at the JTEKT entrance.",
            [gone("passenger_car_3"), only(*VEHICLES)],
            [rm("passenger_car_3")],
            setup=[CAR_AT_JTEKT],
            tags=mt,
        ),
        _r(
            "robot_over",
            "indirect",
            "The robot test is over.",
            [count("ackermann_robot", 0, 0), only("ackermann_robot")],
            [rm_all("ackermann_robot")],
            setup=[ROBOT_CIRCLING],
            tags=mt,
        ),
        _r(
            "peds_home",
            "indirect",
            "The pedestrians went home.",
            PEDS_GONE,
            [rm_all("pedestrian")],
            setup=[TWO_PEDESTRIANS],
            tags=mt,
        ),
        _r(
            "truck_left",
            "indirect",
            "That delivery truck has left.",
            [count("truck", 0, 0), only("truck")],
            [rm_all("truck")],
            setup=[TRUCK_AT_UNION],
            tags=mt,
        ),
        _r(
            "clear_junction",
            "indirect",
            "Clear the road at the intersection so traffic can flow again.",
            [count("cement_rubble", 0, 0), only("cement_rubble", "traffic_cone")],
            [rm_all("cement_rubble")],
            setup=[RUBBLE],
            tags=mt,
        ),
        _r(
            "bins_collected",
            "indirect",
            "The bins were collected; there should be none left.",
            [count("trash_bin", 0, 0), only("trash_bin")],
            [rm_all("trash_bin")],
        ),
        # vague
        _r(
            "clutter",
            "vague",
            "get rid of the clutter at the bus stop",
            [delta(["bench", "trash_bin"], None, -1), only("bench", "trash_bin", "street_light")],
            [rm("bench_1", "trash_bin_1")],
        ),
        _r("fewer_cars", "vague", "fewer cars", [delta(VEHICLES, None, -1), only(*VEHICLES)], [rm("passenger_car_1")]),
        _r("that_thing", "vague", "remove that thing", RUBBLE_GONE, [rm_all("cement_rubble")], setup=[RUBBLE], tags=mt),
        _r(
            "clean_up",
            "vague",
            "clean up",
            [delta(["traffic_cone", "cement_rubble"], None, -1), only("traffic_cone", "cement_rubble")],
            [rm_all("traffic_cone"), rm_all("cement_rubble")],
            setup=MAINTENANCE,
            tags=mt,
        ),
        _r("too_many_trees", "vague", "too many trees", [delta("tree", None, -1), only("tree")], [rm("tree_4")]),
        _r("no_hydrant", "vague", "no hydrant", HYDRANT, [rm("fire_hydrant_1")]),
        _r(
            "lose_robot",
            "vague",
            "lose the robot",
            [count("ackermann_robot", 0, 0), only("ackermann_robot")],
            [rm_all("ackermann_robot")],
            setup=[ROBOT],
            tags=mt,
        ),
        _r(
            "less_fountain",
            "vague",
            "less stuff near the fountain",
            [delta(None, None, -1), only("tree", "bench", "trash_bin", "street_light")],
            [rm("tree_2")],
            alternatives=[[gone("tree_2")], [gone("tree_3")]],
        ),
        _r(
            "some_peds",
            "vague",
            "remove some pedestrians",
            [delta("pedestrian", None, -1), only("pedestrian")],
            [rm_all("pedestrian", None, 2)],
            setup=[THREE_PEDS],
            tags=mt,
        ),
        _r(
            "clear_lot",
            "vague",
            "clear the lot",
            [delta(VEHICLES, None, -1), only(*VEHICLES)],
            [rm("passenger_car_1", "passenger_car_2", "suv_1")],
        ),
        _r(
            "that_truck",
            "vague",
            "get that truck out of here",
            [count("truck", 0, 0), only("truck")],
            [rm_all("truck")],
            setup=[TRUCK_AT_UNION],
            tags=mt,
        ),
        _r("pedestrian_gone", "vague", "no pedestrian", PEDS_GONE, [rm_all("pedestrian")], setup=[PEDESTRIAN], tags=mt),
        # erroneous
        _r("bench", "erroneous", "remove bench at bus stpo", BENCH, [rm("bench_1")]),
        _r("lot_b_cars", "erroneous", "delet all passenger car from parking lot b", LOT_B_CARS, LOT_B_REF),
        _r("hydrant", "erroneous", "remove fire hidrant pls", HYDRANT, [rm("fire_hydrant_1")]),
        _r("stop_sign", "erroneous", "take away stop sing near west crosswalk", STOP, [rm("stop_sign_1")]),
        _r("bin", "erroneous", "remove trashbin", BIN, [rm("trash_bin_1")]),
        _r("suv", "erroneous", "remove the suv car pls", SUV, [rm("suv_1")]),
        _r("tree_fountain", "erroneous", "remove tree near fontain", TREE_FOUNTAIN, [rm_all("tree", "fountain", 1)]),
        _r(
            "cones",
            "erroneous",
            "remove all traffic cone",
            CONES_GONE,
            [rm_all("traffic_cone")],
            setup=[CONES_AT_JTEKT],
            tags=mt,
        ),
        _r(
            "rubble",
            "erroneous",
            "removing the cement rubbles on intersection",
            RUBBLE_GONE,
            [rm_all("cement_rubble")],
            setup=[RUBBLE],
            tags=mt,
        ),
        _r(
            "street_light",
            "erroneous",
            "remove the street lite most close to bus stop",
            LIGHT,
            [rm_all("street_light", "bus stop", 1)],
        ),
        _r(
            "pedestrians",
            "erroneous",
            "remove the 2 pedestrain",
            PEDS_GONE,
            [rm_all("pedestrian")],
            setup=[TWO_PEDESTRIANS],
            tags=mt,
        ),
        _r(
            "bench_bike",
            "direct",
            "Remove the bench at the bus stop and put a bicycle there instead.",
            [gone("bench_1"), exactly("bicycle", 1), near("bicycle", "bus stop", 10), only("bench", "bicycle")],
            [rm("bench_1"), add("bicycle", loc("at", "bus stop"))],
            tags=["compound"],
        ),
    ]
