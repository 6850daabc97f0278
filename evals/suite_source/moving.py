"""Moving cases: shift or turn an asset, or give it a motion (drive, circle, cross, jaywalk)."""

from __future__ import annotations

from typing import Any

from dsl import (
    PEDESTRIAN,
    ROBOT,
    Json,
    behaviour,
    call,
    case,
    does,
    env,
    moved,
    only,
)


def _m(cid: str, grade: str, prompt: str, checks: list[Json], ref: list[Json], **kw: Any) -> Json:
    return case(f"moving.{grade}.{cid}", "moving", grade, prompt, checks, ref, **kw)


def shift(asset: str, forward: float = 0.0, left: float = 0.0, turn: float = 0.0) -> Json:
    return call("move_asset", asset=asset, forward=forward or None, left=left or None, turn_deg=turn or None)


def act(asset: str, kind: str, **kw: Any) -> Json:
    return call("set_behaviour", asset=asset, behaviour=behaviour(kind, **kw))


def just(*ids: str) -> Json:
    return only(assets=ids)


SUV_FWD = [moved("suv_1", 4, 6, "forward"), just("suv_1")]
SUV_FWD_REF = [shift("suv_1", forward=5)]
BENCH_TURN = [moved("bench_1", 0, 0.5, turn=(80, 100)), just("bench_1")]
BENCH_TURN_REF = [shift("bench_1", turn=90)]
CAR1_DRIVE = [does("drive_lane", asset="passenger_car_1", lane="main_westbound"), just("passenger_car_1")]
CAR1_DRIVE_REF = [act("passenger_car_1", "drive_lane", lane="main_westbound")]
EGO_WEST = [does("drive_lane", asset="ego", lane="main_westbound"), just("ego")]
EGO_WEST_REF = [act("ego", "drive_lane", lane="main_westbound")]
BIN_RIGHT = [moved("trash_bin_1", 2, 4, "right"), just("trash_bin_1")]
BIN_RIGHT_REF = [shift("trash_bin_1", left=-3)]
ROBOT_CIRCLE = [does("circle", asset="ackermann_robot_1", radius_min=5.5, radius_max=6.5), just("ackermann_robot_1")]
ROBOT_CIRCLE_REF = [act("ackermann_robot_1", "circle", radius=6.0)]
CAR2_BACK = [moved("passenger_car_2", 2.5, 3.5, "backward"), just("passenger_car_2")]
CAR2_BACK_REF = [shift("passenger_car_2", forward=-3)]
CROSS = [does("cross_road", asset="pedestrian_1", crosses_lane="main_eastbound"), just("pedestrian_1")]
CROSS_REF = [act("pedestrian_1", "cross_road")]
JAYWALK = [does("jaywalk", asset="pedestrian_1", crosses_lane="main_eastbound"), just("pedestrian_1")]
JAYWALK_REF = [act("pedestrian_1", "jaywalk")]
EGO_STOP = [does("parked", asset="ego"), moved("ego", 0, 1), just("ego")]
EGO_STOP_REF = [act("ego", "parked")]


def cases() -> list[Json]:
    ped, robot = [PEDESTRIAN], [ROBOT]
    mt = ["multi_turn"]
    return [
        # direct
        _m("suv_forward", "direct", "Move the SUV forward 5 metres.", SUV_FWD, SUV_FWD_REF),
        _m("bench_turn", "direct", "Turn the bench 90 degrees.", BENCH_TURN, BENCH_TURN_REF),
        _m("car1_drive", "direct", "Make passenger_car_1 drive along lane main_westbound.", CAR1_DRIVE, CAR1_DRIVE_REF),
        _m("ego_west", "direct", "Make the ego vehicle drive in lane main_westbound.", EGO_WEST, EGO_WEST_REF),
        _m("bin_right", "direct", "Move the trash bin 3 metres to the right.", BIN_RIGHT, BIN_RIGHT_REF),
        _m(
            "robot_circle",
            "direct",
            "Make the robot drive a circle of radius 6 m.",
            ROBOT_CIRCLE,
            ROBOT_CIRCLE_REF,
            setup=robot,
            tags=mt,
        ),
        _m("car2_reverse", "direct", "Reverse passenger_car_2 by 3 metres.", CAR2_BACK, CAR2_BACK_REF),
        _m(
            "ped_cross",
            "direct",
            "Make pedestrian_1 cross the road at the west crosswalk.",
            CROSS,
            CROSS_REF,
            setup=ped,
            tags=mt,
        ),
        _m(
            "ped_jaywalk",
            "direct",
            "Make pedestrian_1 jaywalk in front of the ego vehicle.",
            JAYWALK,
            JAYWALK_REF,
            setup=ped,
            tags=mt,
        ),
        _m(
            "suv_around",
            "direct",
            "Turn the SUV around.",
            [moved("suv_1", 0, 1, turn=(160, 180)), just("suv_1")],
            [shift("suv_1", turn=180)],
        ),
        _m(
            "car2_north",
            "direct",
            "Make passenger_car_2 drive north on Campus Drive at 8 m/s.",
            [
                does("drive_lane", asset="passenger_car_2", lane="campus_northbound", speed_min=7, speed_max=9),
                just("passenger_car_2"),
            ],
            [act("passenger_car_2", "drive_lane", lane="campus_northbound", speed=8.0)],
        ),
        _m("ego_stop", "direct", "Stop the ego vehicle.", EGO_STOP, EGO_STOP_REF),
        # indirect
        _m(
            "suv_pull_forward",
            "indirect",
            "The SUV should pull forward a few metres.",
            [moved("suv_1", 1, 10, "forward"), just("suv_1")],
            SUV_FWD_REF,
        ),
        _m(
            "bench_wrong_way",
            "indirect",
            "The bench faces the wrong way.",
            [moved("bench_1", 0, 1, turn=(60, 180)), just("bench_1")],
            [shift("bench_1", turn=180)],
        ),
        _m(
            "car1_leaving",
            "indirect",
            "Passenger car one is leaving campus westwards along Main Street.",
            CAR1_DRIVE,
            CAR1_DRIVE_REF,
        ),
        _m(
            "ego_back",
            "indirect",
            "Our test vehicle should come back the other way on Main Street.",
            EGO_WEST,
            EGO_WEST_REF,
        ),
        _m(
            "bin_shift",
            "indirect",
            "The trash bin is in the way at the bus stop; shift it a couple of metres.",
            [moved("trash_bin_1", 1, 6), just("trash_bin_1")],
            BIN_RIGHT_REF,
        ),
        _m(
            "robot_laps",
            "indirect",
            "The robot should be doing skidpad laps.",
            [does("circle", asset="ackermann_robot_1"), just("ackermann_robot_1")],
            [act("ackermann_robot_1", "circle")],
            setup=robot,
            tags=mt,
        ),
        _m(
            "car2_back_out",
            "indirect",
            "Car two needs to back out of its bay.",
            [moved("passenger_car_2", 1, 8, "backward"), just("passenger_car_2")],
            CAR2_BACK_REF,
        ),
        _m(
            "ped_zebra",
            "indirect",
            "pedestrian_1 should use the zebra crossing to get across Main Street.",
            CROSS,
            CROSS_REF,
            setup=ped,
            tags=mt,
        ),
        _m(
            "ped_step_out",
            "indirect",
            "Make the pedestrian step out in front of our car.",
            JAYWALK,
            JAYWALK_REF,
            setup=ped,
            tags=mt,
        ),
        _m("ego_wait", "indirect", "The ego car should just wait where it is.", EGO_STOP, EGO_STOP_REF),
        _m(
            "car2_up_campus",
            "indirect",
            "Send the second car up Campus Drive heading north.",
            [does("drive_lane", asset="passenger_car_2", lane="campus_northbound"), just("passenger_car_2")],
            [act("passenger_car_2", "drive_lane", lane="campus_northbound")],
        ),
        # vague
        _m(
            "nudge_suv",
            "vague",
            "nudge the suv forward",
            [moved("suv_1", 0.3, 10, "forward"), just("suv_1")],
            SUV_FWD_REF,
        ),
        _m(
            "spin_bench",
            "vague",
            "spin the bench",
            [moved("bench_1", 0, 1, turn=(20, 180)), just("bench_1")],
            BENCH_TURN_REF,
        ),
        _m(
            "car1_off",
            "vague",
            "car 1 should drive off",
            [does(["drive_lane", "follow_path"], asset="passenger_car_1"), just("passenger_car_1")],
            CAR1_DRIVE_REF,
        ),
        _m(
            "ego_other_way",
            "vague",
            "ego the other way",
            [just("ego")],
            EGO_WEST_REF,
            alternatives=[
                [does("drive_lane", asset="ego", lane="main_westbound")],
                [moved("ego", 0, 5, turn=(150, 180))],
            ],
        ),
        _m(
            "robot_circles",
            "vague",
            "robot going in circles",
            [does("circle", asset="ackermann_robot_1"), just("ackermann_robot_1")],
            [act("ackermann_robot_1", "circle")],
            setup=robot,
            tags=mt,
        ),
        _m(
            "ped_cross",
            "vague",
            "the pedestrian should cross",
            [does(["cross_road", "jaywalk"], asset="pedestrian_1"), just("pedestrian_1")],
            CROSS_REF,
            setup=ped,
            tags=mt,
        ),
        _m(
            "car2_back",
            "vague",
            "back up car 2 a bit",
            [moved("passenger_car_2", 0.3, 6, "backward"), just("passenger_car_2")],
            CAR2_BACK_REF,
        ),
        _m("shift_bin", "vague", "shift the bin", [moved("trash_bin_1", 0.3, 10), just("trash_bin_1")], BIN_RIGHT_REF),
        _m("stop_our_car", "vague", "stop our car", EGO_STOP, EGO_STOP_REF),
        _m(
            "car2_drive",
            "vague",
            "have the second car drive around",
            [does(["drive_lane", "circle", "follow_path"], asset="passenger_car_2"), just("passenger_car_2")],
            [act("passenger_car_2", "drive_lane", lane="campus_northbound")],
        ),
        # erroneous
        _m("suv_forward", "erroneous", "move suv foward 5 meter", SUV_FWD, SUV_FWD_REF),
        _m("bench_turn", "erroneous", "turn bench 90 degre", BENCH_TURN, BENCH_TURN_REF),
        _m("car1_drive", "erroneous", "make passanger car 1 drive on main westbond lane", CAR1_DRIVE, CAR1_DRIVE_REF),
        _m("ego_west", "erroneous", "ego vehical drive in westbound lane pls", EGO_WEST, EGO_WEST_REF),
        _m("bin_right", "erroneous", "move trashbin 3 meter to right", BIN_RIGHT, BIN_RIGHT_REF),
        _m(
            "robot_circle",
            "erroneous",
            "make the robot to do circle radius 6m",
            ROBOT_CIRCLE,
            ROBOT_CIRCLE_REF,
            setup=robot,
            tags=mt,
        ),
        _m("car2_reverse", "erroneous", "reverse passenger car 2 for 3 meter", CAR2_BACK, CAR2_BACK_REF),
        _m(
            "ped_cross",
            "erroneous",
            "pedestrain 1 cross the road on west crosswalk",
            CROSS,
            CROSS_REF,
            setup=ped,
            tags=mt,
        ),
        _m(
            "ped_jaywalk",
            "erroneous",
            "make pedestrain_1 jay walk infront of ego car",
            JAYWALK,
            JAYWALK_REF,
            setup=ped,
            tags=mt,
        ),
        _m("ego_stop", "erroneous", "stop ego vehicule", EGO_STOP, EGO_STOP_REF),
        _m(
            "fog_and_forward",
            "direct",
            "Make it foggy and move the SUV forward 5 metres.",
            [moved("suv_1", 4, 6, "forward"), env(weather=["fog"]), only(assets=("suv_1",), environment=True)],
            [call("set_weather", kind="fog"), *SUV_FWD_REF],
            tags=["compound"],
        ),
    ]
