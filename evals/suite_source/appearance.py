"""Appearance cases: weather, time of day, lighting, and the colours and materials of assets."""

from __future__ import annotations

from typing import Any

from dsl import (
    NIGHT,
    RAIN,
    Json,
    add,
    call,
    case,
    env,
    exactly,
    loc,
    looks,
    near,
    only,
    step,
)

BRIGHT = ["red", "yellow", "orange", "pink", "green", "cyan", "white", "gold", "blue", "purple"]


def _l(cid: str, grade: str, prompt: str, checks: list[Json], ref: list[Json], **kw: Any) -> Json:
    return case(f"appearance.{grade}.{cid}", "appearance", grade, prompt, checks, ref, **kw)


def weather(kind: str, intensity: float | None = None) -> Json:
    return call("set_weather", kind=kind, intensity=intensity)


def clock(time: str) -> Json:
    return call("set_time_of_day", time=time)


def paint(colour: str | None = None, *ids: str, category: str | None = None, material: str | None = None) -> Json:
    return call("set_asset_appearance", assets=list(ids) or None, category=category, colour=colour, material=material)


SKY = only(environment=True)
RAINY = [env(weather=["rain"]), SKY]
FOGGY = [env(weather=["fog"]), SKY]
SNOWY = [env(weather=["snow"]), SKY]
DAY = [env(night=False), SKY]
NIGHTTIME = [env(night=True), SKY]
CLEAR = [env(weather=["clear"]), SKY]
RED_SUV = [looks("red", asset="suv_1"), only("suv")]
GREEN_BINS = [looks("green", "trash_bin", scope="all", every=True), only("trash_bin")]
TIME_1830 = [env(time_from="18:25", time_to="18:35"), SKY]
LIGHTS_ON = [env(street_lights="on"), SKY]
HEAVY_RAIN = [env(weather=["rain"], intensity_min=0.7), SKY]
WOOD_BENCH = [looks(None, asset="bench_1", material="wood"), only("bench")]


def cases() -> list[Json]:
    paper = ["paper"]
    night, rain = [NIGHT], [RAIN]
    mt = ["multi_turn"]
    return [
        # direct (the paper's weather and time prompts first)
        _l("rain", "direct", "make it rain", RAINY, [weather("rain")], tags=paper),
        _l("fog", "direct", "make it foggy", FOGGY, [weather("fog")], tags=paper),
        _l("snow", "direct", "make it snow", SNOWY, [weather("snow")], tags=paper),
        _l("daytime", "direct", "make it daytime", DAY, [clock("daytime")], setup=night, tags=[*paper, *mt]),
        _l("night", "direct", "make it night", NIGHTTIME, [clock("night")], tags=paper),
        _l("clear", "direct", "clear the weather", CLEAR, [weather("clear")], setup=rain, tags=[*paper, *mt]),
        _l("red_suv", "direct", "Paint the SUV red.", RED_SUV, [paint("red", "suv_1")]),
        _l(
            "green_bins", "direct", "Make all the trash bins green.", GREEN_BINS, [paint("green", category="trash_bin")]
        ),
        _l("time_1830", "direct", "Set the time to 18:30.", TIME_1830, [clock("18:30")]),
        _l(
            "street_lights",
            "direct",
            "Turn the street lights on.",
            LIGHTS_ON,
            [call("set_lighting", street_lights="on")],
        ),
        _l("heavy_rain", "direct", "Make it rain heavily.", HEAVY_RAIN, [weather("rain", 0.9)]),
        _l("wood_bench", "direct", "Make the bench wooden.", WOOD_BENCH, [paint(None, "bench_1", material="wood")]),
        # indirect
        _l("wipers", "indirect", "I want to test the wipers.", [env(weather=["rain", "snow"]), SKY], [weather("rain")]),
        _l(
            "poor_visibility",
            "indirect",
            "Visibility should be really poor this morning.",
            [env(weather=["fog", "rain", "snow"], intensity_min=0.5), SKY],
            [weather("fog", 0.8)],
        ),
        _l("after_sunset", "indirect", "Let's see how the sensors cope after sunset.", NIGHTTIME, [clock("night")]),
        _l("sun_back", "indirect", "Bring the sun back out.", CLEAR, [weather("clear")], setup=rain, tags=mt),
        _l("winter", "indirect", "It's a winter scenario: the roads should be white.", SNOWY, [weather("snow")]),
        _l(
            "fire_engine",
            "indirect",
            "The SUV should be the colour of a fire engine.",
            RED_SUV,
            [paint("red", "suv_1")],
        ),
        _l(
            "light_streets",
            "indirect",
            "Drivers can barely see anything; light up the streets.",
            [env(street_lights="on"), SKY],
            [call("set_lighting", street_lights="on")],
            setup=night,
            tags=mt,
        ),
        _l(
            "lunchtime",
            "indirect",
            "Let's do the test at lunchtime.",
            [env(time_from="11:00", time_to="14:00"), SKY],
            [clock("12:30")],
            setup=night,
            tags=mt,
        ),
        _l(
            "blend_in",
            "indirect",
            "The bins should blend in with the grass.",
            GREEN_BINS,
            [paint("green", category="trash_bin")],
        ),
        _l(
            "golden_hour",
            "indirect",
            "Switch to a golden-hour shot.",
            [env(time_from="16:30", time_to="20:30"), SKY],
            [clock("sunset")],
        ),
        _l(
            "night_rain",
            "indirect",
            "We need a night drive in the rain.",
            [env(weather=["rain"], night=True), SKY],
            [clock("night"), weather("rain")],
            tags=["compound"],
        ),
        # vague
        _l("rainy", "vague", "rainy", RAINY, [weather("rain")]),
        _l(
            "darker",
            "vague",
            "darker",
            [SKY],
            [clock("dusk")],
            alternatives=[
                [env(time_from="18:00", time_to="06:00")],
                [env(exposure_max=0.9)],
                [env(weather=["cloudy", "fog", "rain"])],
            ],
        ),
        _l("snowy", "vague", "snowy please", SNOWY, [weather("snow")]),
        _l("fog", "vague", "fog", FOGGY, [weather("fog")]),
        _l("nicer", "vague", "nicer weather", [env(weather=["clear"]), SKY], [weather("clear")], setup=rain, tags=mt),
        _l(
            "suv_stand_out",
            "vague",
            "make the suv stand out",
            [looks(BRIGHT, asset="suv_1", material=None), only("suv")],
            [paint("yellow", "suv_1")],
        ),
        _l("evening", "vague", "evening", [env(time_from="17:00", time_to="22:30"), SKY], [clock("evening")]),
        _l(
            "morning",
            "vague",
            "morning",
            [env(time_from="05:00", time_to="11:00"), SKY],
            [clock("morning")],
            setup=night,
            tags=mt,
        ),
        _l(
            "lights_on",
            "vague",
            "lights on",
            [SKY],
            [call("set_lighting", street_lights="on")],
            alternatives=[[env(street_lights="on")], [env(vehicle_lights="on")]],
        ),
        _l(
            "blue_bins",
            "vague",
            "blue bins",
            [looks("blue", "trash_bin", scope="all"), only("trash_bin")],
            [paint("blue", category="trash_bin")],
        ),
        # erroneous
        _l("rain", "erroneous", "make it rainy wether", RAINY, [weather("rain")]),
        _l("fog", "erroneous", "make foggy pls", FOGGY, [weather("fog")]),
        _l("snow", "erroneous", "make snowing", SNOWY, [weather("snow")]),
        _l("daytime", "erroneous", "make it day time", DAY, [clock("daytime")], setup=night, tags=mt),
        _l("night", "erroneous", "make it nite", NIGHTTIME, [clock("night")]),
        _l("clear", "erroneous", "clear the wheather", CLEAR, [weather("clear")], setup=rain, tags=mt),
        _l("red_suv", "erroneous", "paint suv in red colour", RED_SUV, [paint("red", "suv_1")]),
        _l(
            "green_bins", "erroneous", "make all trash bin to green", GREEN_BINS, [paint("green", category="trash_bin")]
        ),
        _l("time_1830", "erroneous", "set time to 18:30 o clock", TIME_1830, [clock("18:30")]),
        _l("street_lights", "erroneous", "turn on street light", LIGHTS_ON, [call("set_lighting", street_lights="on")]),
        _l("heavy_rain", "erroneous", "make rain heavy", HEAVY_RAIN, [weather("rain", 0.9)]),
        _l(
            "bus_yellow",
            "indirect",
            "now paint it yellow",
            [looks("yellow", "bus", scope="all"), only("bus")],
            [paint("yellow", "bus_1")],
            setup=[step("Add a bus at the bus stop.", add("bus", loc("at", "bus stop")), planned=True)],
            tags=["multi_turn"],
        ),
        _l(
            "car_and_night",
            "direct",
            "add a parked car at the JTEKT building entrance and make it night",
            [
                env(night=True),
                exactly(["passenger_car", "suv"], 1),
                near(["passenger_car", "suv"], "JTEKT building entrance", 12),
                only("passenger_car", "suv", environment=True),
            ],
            [clock("night"), add("passenger_car", loc("at", "JTEKT building entrance"))],
            tags=["compound", "paper"],
        ),
    ]
