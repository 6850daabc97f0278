"""describe_environment: the weather, the clock and the lights as they are, changing nothing."""

from __future__ import annotations

from collections.abc import Callable

from drivetwin.tools import ToolResult
from drivetwin.worlds.scene import Environment, Lighting, Scene, Weather

Caller = Callable[..., ToolResult]


def test_a_clear_noon_says_so_and_changes_nothing(call: Caller, campus: Scene) -> None:
    result = call(campus, "describe_environment")
    assert result.edit.empty
    assert result.text.startswith("weather: clear; time of day: 12:00 (day)")
    assert "street lights off (they light at night)" in result.text


def test_fog_at_night_with_lamps_forced_off_reads_as_it_is(call: Caller, campus: Scene) -> None:
    foggy = campus.model_copy(update={"environment": Environment(
        time_of_day="22:30", weather=Weather(kind="fog", intensity=0.7), lighting=Lighting(street_lights="off"))})
    result = call(foggy, "describe_environment")
    assert "weather: fog (intensity 0.7); time of day: 22:30 (night)" in result.text
    assert "street lights off" in result.text and "vehicle lights on (they light at night)" in result.text
    assert result.data["environment"]["weather"]["kind"] == "fog"
