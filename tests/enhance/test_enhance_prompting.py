"""Prompts built from the Scene's environment."""

from __future__ import annotations

import pytest
from drivetwin.worlds.enhance import build_prompts
from drivetwin.worlds.scene import Environment, Weather


def env(time: str = "12:00", kind: str = "clear", intensity: float = 0.0) -> Environment:
    return Environment(time_of_day=time, weather=Weather(kind=kind, intensity=intensity))


def test_a_default_scene_asks_for_a_clear_midday_photo() -> None:
    prompt = build_prompts().prompt
    assert "midday" in prompt and "clear sky" in prompt and "photo" in prompt


def test_a_rainy_night_asks_for_night_and_heavy_rain() -> None:
    prompt = build_prompts(env("22:30", "rain", 0.9)).prompt
    assert "night" in prompt and "heavy rain" in prompt and "wet asphalt" in prompt


@pytest.mark.parametrize(
    ("kind", "intensity", "words"),
    [
        ("fog", 0.5, "moderate fog"),
        ("snow", 0.1, "light snowfall"),
        ("cloudy", 0.9, "overcast"),
        ("cloudy", 0.2, "partly cloudy"),
    ],
)
def test_weather_kind_and_intensity_appear_in_the_prompt(
    kind: str, intensity: float, words: str
) -> None:
    assert words in build_prompts(env("10:00", kind, intensity)).prompt


@pytest.mark.parametrize(
    ("time", "words"),
    [("07:00", "dawn"), ("09:30", "morning"), ("16:00", "afternoon"), ("18:30", "dusk")],
)
def test_time_of_day_appears_in_the_prompt(time: str, words: str) -> None:
    assert words in build_prompts(env(time)).prompt


def test_the_negative_prompt_fights_layout_changes() -> None:
    negative = build_prompts(env("22:00", "snow", 1.0)).negative
    for words in ("moved objects", "extra vehicles", "changed perspective", "cartoon"):
        assert words in negative
