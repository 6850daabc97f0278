"""The scenario suite: triggered manoeuvres, lights and junction turns, judged by simulating them.

build.py writes it to evals/suites/scenarios.jsonl. Each family
sets its actors up with replayed calls (the same start for every planner), then asks for
the event in four grades of wording. Checks: the prompt is accepted, no asset changes (a
scenario is not a teleport or a repaint), the storyboard holds the event and it started,
and what happens over the simulated seconds (gaps, collisions, places reached, stops).
Cases a drivetwin actor cannot do (a cyclist turning at the junction: walkers do not take
lane connections) expect a refusal.
"""

from __future__ import annotations

from typing import Any

Json = dict[str, Any]
GRADES = ("direct", "indirect", "vague", "erroneous")
EAST_STOP_LINE = [-14.0, -1.75]


def call(tool: str, **args: Any) -> Json:
    return {"tool": tool, "args": args}


def add(category: str, x: float, y: float, yaw_deg: float = 0.0, behaviour: Json | None = None) -> Json:
    args: Json = {"category": category, "location": {"relation": "absolute", "x": x, "y": y}, "yaw_deg": yaw_deg}
    if behaviour is not None:
        args["behaviour"] = behaviour
    return call("add_asset", **args)


def setup(prompt: str, *calls: Json) -> Json:
    return {"prompt": prompt, "calls": list(calls), "planned": False}


def event(manoeuvre: str, actor: str | None = None, trigger: str | None = None, started: bool = True) -> Json:
    found: Json = {"kind": "event", "manoeuvre": manoeuvre, "started": started}
    if actor is not None:
        found["actor"] = actor
    if trigger is not None:
        found["trigger"] = trigger
    return found


def scenario(seconds: float, *expect: Json) -> Json:
    return {"kind": "scenario", "seconds": seconds, "expect": list(expect)}


ACCEPTED: list[Json] = [{"kind": "status", "accepted": True}, {"kind": "unchanged_except"}]
REFUSED: list[Json] = [{"kind": "status", "accepted": False}, {"kind": "unchanged_except"}]
NO_CRASH = {"kind": "collision", "actor": "ego", "happens": False}

LEAD = setup("add a car driving ahead of the ego in its lane",
             add("passenger_car", -40.0, -1.75, 0.0, {"kind": "drive_lane", "lane": "main_eastbound", "speed": 2.0}))
OVERTAKER = setup("add a car overtaking in the left lane",
                  add("passenger_car", -45.0, 1.75, 0.0, {"kind": "follow_path", "waypoints": [[-45.0, 1.75], [100.0, 1.75]], "speed": 7.0}))
BUS_AND_WALKER = setup(
    "park a bus on the far side of the road and put a pedestrian behind it",
    add("bus", -35.0, 2.0, 180.0), add("pedestrian", -27.5, 6.0, -90.0))
ONCOMING = setup("add an oncoming car on Main Street",
                 add("passenger_car", 30.0, 1.75, 180.0, {"kind": "drive_lane", "lane": "main_westbound", "speed": 5.0}))
CROSS_TRAFFIC = setup("add a car coming up Campus Drive from the south",
                      add("passenger_car", 1.75, -45.0, 90.0, {"kind": "drive_lane", "lane": "campus_northbound", "speed": 5.0}))
SLOW_TRUCK = setup("add a slow truck coming towards the ego",
                   add("truck", 45.0, 1.75, 180.0, {"kind": "drive_lane", "lane": "main_westbound", "speed": 2.5}))
CAR_BEHIND_TRUCK = setup("add a car behind the truck",
                         add("passenger_car", 62.0, 1.75, 180.0, {"kind": "drive_lane", "lane": "main_westbound", "speed": 6.0}))
KERB_WALKER = setup("put a pedestrian on the kerb ahead of the ego", add("pedestrian", -20.0, -6.0, 90.0))
CYCLIST = setup("add a cyclist on Main Street", add("bicycle", -30.0, -3.0, 0.0))

CAR = "passenger_car_3"  # the first car a setup adds (the campus has passenger_car_1 and _2)
FAMILIES: list[Json] = [
    {
        "name": "lead_brakes", "setup": [LEAD],
        "prompts": ("The lead car brakes hard when the ego is 15 m behind it.",
                    "make the car in front of the ego slam on its brakes once the ego closes to 15 metres",
                    "the car ahead should suddenly brake",
                    "teh lead car brkaes hard wen the ego is 15m behnd it"),
        "reference": [call("add_event", actor=CAR, manoeuvre={"kind": "stop", "rate": 6},
                           when={"kind": "distance", "actor": "ego", "other": CAR, "metres": 15})],
        "checks": [scenario(12.0, event("stop", "passenger_car"), NO_CRASH,
                            {"kind": "min_gap", "actor": "ego", "other": "passenger_car", "metres": 1.0})],
    },
    {
        "name": "lead_brakes_ttc", "setup": [LEAD],
        "prompts": ("The lead car brakes when its time to collision with the ego drops below 3 seconds.",
                    "once the ego is 3 s from hitting the car ahead, that car should stop",
                    "have the car in front stop when the ego gets dangerously close",
                    "lead car stop wen time to colision with ego under 3 sec"),
        "reference": [call("add_event", actor=CAR, manoeuvre={"kind": "stop", "rate": 4},
                           when={"kind": "time_to_collision", "actor": "ego", "other": CAR, "seconds": 3})],
        "checks": [scenario(12.0, event("stop", "passenger_car"), NO_CRASH)],
    },
    {
        "name": "cut_in", "setup": [OVERTAKER],
        "prompts": ("The car in the left lane cuts in front of the ego leaving an 8 m gap after 2 seconds.",
                    "two seconds in, have the overtaking car swerve into the ego's lane 8 metres ahead of it",
                    "make the other car cut in on the ego",
                    "the car in the left lane cut in front of ego with 8m gap aftr 2 secs"),
        "reference": [call("add_manoeuvre", actor=CAR, manoeuvre={"kind": "cut_in", "target": "ego", "gap": 8},
                           at_time=2)],
        "checks": [scenario(9.0, event("cut_in", "passenger_car"), NO_CRASH,
                            {"kind": "reached", "actor": "passenger_car", "place": "20, -1.75", "within": 25.0})],
    },
    {
        "name": "pedestrian_behind_bus", "setup": [BUS_AND_WALKER],
        "prompts": ("The pedestrian steps out from behind the parked bus when the ego is 25 m away.",
                    "when the ego gets within 25 metres, the person hidden behind the bus should walk out across the road",
                    "someone should step out from behind the bus in front of the ego",
                    "pedestrain step out from behnd the bus wen ego is 25 m away"),
        "reference": [call("add_event", actor="pedestrian_1", manoeuvre={"kind": "cross_road", "speed": 2.0},
                           when={"kind": "distance", "actor": "ego", "other": "pedestrian_1", "metres": 25})],
        # Whether the ego avoids the walker is the system under test's business (drivetwin's
        # ego only brakes for what its rays see): the case checks that the scene plays.
        "checks": [scenario(14.0, event("cross_road", "pedestrian"),
                            {"kind": "reached", "actor": "pedestrian", "place": "-27.5, -1.75", "within": 1.5})],
    },
    {
        "name": "oncoming_turns_left", "setup": [ONCOMING],
        "prompts": ("The oncoming car turns left at the junction across the ego's path.",
                    "have the car coming towards the ego turn left at the crossroads, cutting across its lane",
                    "the oncoming car should turn off at the junction",
                    "the oncomming car turn left at junktion acros the ego path"),
        "reference": [call("add_manoeuvre", actor=CAR, manoeuvre={"kind": "junction_turn", "turn": "left"})],
        "checks": [scenario(14.0, event("junction_turn", "passenger_car"), NO_CRASH,
                            {"kind": "reached", "actor": "passenger_car", "place": "-1.75, -25", "within": 4.0})],
    },
    {
        "name": "cross_traffic_turns_left", "setup": [CROSS_TRAFFIC],
        "prompts": ("The car on Campus Drive turns left at the junction in front of the ego.",
                    "the car coming up from the south should take a left at the crossroads, across the ego's path",
                    "make the car on the side road turn at the junction",
                    "car on campus drive turn left at the junktion infront of ego"),
        "reference": [call("add_manoeuvre", actor=CAR, manoeuvre={"kind": "junction_turn", "turn": "left"})],
        "checks": [scenario(14.0, event("junction_turn", "passenger_car"), NO_CRASH,
                            {"kind": "reached", "actor": "passenger_car", "place": "-25, 1.75", "within": 4.0})],
    },
    {
        "name": "red_light", "setup": [],
        "prompts": ("Make the traffic light on Main Street red so the ego has to stop.",
                    "the ego should have to wait at a red light at the crossroads",
                    "stop the ego at the lights",
                    "make the trafic light red so ego stop"),
        "reference": [call("set_light_phases", light="traffic_light_1", phases=[{"state": "red", "duration": 60}])],
        "checks": [scenario(16.0, {"kind": "stopped_before", "actor": "ego", "line": EAST_STOP_LINE})],
    },
    {
        "name": "light_turns_red", "setup": [],
        "prompts": ("The traffic light turns red when the ego is 30 m from it.",
                    "as the ego approaches the crossroads the light should change to red",
                    "the light should go red just before the ego gets there",
                    "traffic lite turn red wen ego 30m from it"),
        "reference": [call("add_event", actor="traffic_light_1", manoeuvre={"kind": "set_light", "state": "red"},
                           when={"kind": "distance", "actor": "ego", "other": "traffic_light_1", "metres": 30})],
        "checks": [scenario(16.0, event("set_light", trigger="distance"),
                            {"kind": "stopped_before", "actor": "ego", "line": EAST_STOP_LINE})],
    },
    {
        "name": "light_cycle", "setup": [],
        "prompts": ("Give the Main Street traffic light a cycle of 10 s green, 3 s amber and 15 s red.",
                    "the lights at the crossroads should cycle: green ten seconds, amber three, red fifteen",
                    "make the traffic light work",
                    "traffic lite cycle 10s green 3s amber 15s red"),
        "reference": [call("set_light_phases", light="traffic_light_1", phases=[
            {"state": "green", "duration": 10}, {"state": "amber", "duration": 3}, {"state": "red", "duration": 15}])],
        "checks": [scenario(14.0, NO_CRASH, {"kind": "reached", "actor": "ego", "place": "0, -1.75", "within": 3.0})],
    },
    {
        "name": "oncoming_overtaker", "setup": [SLOW_TRUCK, CAR_BEHIND_TRUCK],
        "prompts": ("The car behind the oncoming truck overtakes it when it is 15 m behind the truck.",
                    "have the car stuck behind the slow truck pull out into the ego's lane to pass it",
                    "the car behind the truck should overtake",
                    "car behnd the oncomming truck overtake it wen 15m behind"),
        "reference": [call("add_event", actor=CAR, manoeuvre={"kind": "lane_change", "side": "left"},
                           when={"kind": "distance", "actor": CAR, "other": "truck_1", "metres": 15})],
        "checks": [scenario(8.0, event("lane_change", "passenger_car"),
                            {"kind": "reached", "actor": "passenger_car", "place": "30, -1.75", "within": 8.0})],
    },
    {
        "name": "stop_mid_road", "setup": [KERB_WALKER],
        "prompts": ("The pedestrian walks into the road and stops in the middle when the ego is 30 m away.",
                    "once the ego is thirty metres off, the person on the kerb should step out and freeze in the road",
                    "the pedestrian should wander into the road and just stand there",
                    "pedestrain walk in road and stop in midle wen ego 30m away"),
        "reference": [call("add_event", actor="pedestrian_1", manoeuvre={"kind": "stop_mid_road"},
                           when={"kind": "distance", "actor": "ego", "other": "pedestrian_1", "metres": 30})],
        "checks": [scenario(14.0, event("stop_mid_road", "pedestrian"), NO_CRASH,
                            {"kind": "min_gap", "actor": "ego", "other": "pedestrian", "metres": 0.3})],
    },
    {
        "name": "ego_speeds_up", "setup": [],
        "prompts": ("After 2 seconds the ego speeds up to 8 m/s at 2 m/s².",
                    "two seconds in, the ego should accelerate to 8 metres per second",
                    "make the ego go faster after a bit",
                    "aftr 2 sec ego speed up to 8 m/s"),
        "reference": [call("add_manoeuvre", actor="ego", manoeuvre={"kind": "change_speed", "speed": 8, "rate": 2},
                           at_time=2)],
        "checks": [scenario(10.0, event("change_speed", "ego"),
                            {"kind": "reached", "actor": "ego", "place": "5, -1.75", "within": 4.0})],
    },
]

REFUSALS: list[Json] = [
    {"id": "cyclist_turns", "setup": [CYCLIST], "grade": "direct",
     "prompt": "The cyclist turns right at the junction across the ego's path.",
     "reference": [call("add_manoeuvre", actor="bicycle_1", manoeuvre={"kind": "junction_turn", "turn": "right"})]},
    {"id": "bench_brakes", "setup": [], "grade": "erroneous",
     "prompt": "the bench brakes hard when the ego comes near",
     "reference": [call("add_event", actor="bench_1", manoeuvre={"kind": "stop", "rate": 6},
                        when={"kind": "distance", "actor": "ego", "other": "bench_1", "metres": 10})]},
    {"id": "ego_lane_change_right", "setup": [], "grade": "indirect",
     "prompt": "have the ego change into the lane on its right",
     "reference": [call("add_manoeuvre", actor="ego", manoeuvre={"kind": "lane_change", "side": "right"})]},
]


def cases() -> list[Json]:
    out: list[Json] = []
    for family in FAMILIES:
        for grade, prompt in zip(GRADES, family["prompts"], strict=True):
            out.append({
                "id": f"scenario.{grade}.{family['name']}", "world": "campus", "setup": family["setup"],
                "prompt": prompt, "task": "moving", "grade": grade, "tags": ["scenario", family["name"]],
                "checks": [*ACCEPTED, *family["checks"]], "reference": family["reference"],
            })
    for refusal in REFUSALS:
        out.append({
            "id": f"scenario.{refusal['grade']}.refuse_{refusal['id']}", "world": "campus", "setup": refusal["setup"],
            "prompt": refusal["prompt"], "task": "moving", "grade": refusal["grade"],
            "tags": ["scenario", "refusal"], "checks": REFUSED, "reference": refusal["reference"],
            "notes": "drivetwin cannot do this; the right answer is a refusal saying what is possible",
        })
    return out

