"""Text prompts for the enhancer, built from a Scene's environment (time of day, weather)."""

from __future__ import annotations

from dataclasses import dataclass

from drivetwin.worlds.scene import Environment

# Words that describe a photograph rather than a painting: SDXL follows the medium first.
_STYLE = "photo taken from a car's dashboard camera, street scene, photorealistic, sharp focus"
# The negative prompt fights the two failure modes that break a digital twin: a changed
# layout (objects moved, added, removed) and a non-photographic look.
NEGATIVE_PROMPT = (
    "different layout, moved objects, extra vehicles, extra people, missing objects, "
    "distorted geometry, warped road, bent lines, changed perspective, changed camera angle, "
    "cartoon, painting, illustration, render, cgi, blurry, text, watermark"
)
# Below this a weather intensity reads as "light", above _HEAVY as "heavy".
_LIGHT = 0.34
_HEAVY = 0.67


@dataclass(frozen=True)
class PromptPair:
    """A positive and a negative prompt for one frame."""

    prompt: str
    negative: str


def _time_words(env: Environment) -> str:
    hours = env.hours
    if env.is_night:
        return "at night, dark sky, street lights and headlights glowing"
    if hours < 8.0:
        return "at dawn, low warm sunlight, long shadows"
    if hours < 11.0:
        return "in the morning, soft daylight"
    if hours < 15.0:
        return "at midday, bright daylight"
    if hours < 17.5:
        return "in the afternoon, warm daylight"
    return "at dusk, golden hour, low sun"


def _degree(intensity: float) -> str:
    if intensity < _LIGHT:
        return "light"
    if intensity < _HEAVY:
        return "moderate"
    return "heavy"


def _weather_words(env: Environment) -> str:
    kind = env.weather.kind
    degree = _degree(env.weather.intensity)
    if kind == "clear":
        return "clear sky" if not env.is_night else "clear night sky"
    if kind == "cloudy":
        return f"{'overcast' if degree == 'heavy' else 'partly cloudy'} sky, diffuse light"
    if kind == "rain":
        return f"{degree} rain, wet asphalt with reflections, raindrops"
    if kind == "fog":
        return f"{degree} fog, hazy, reduced visibility, soft distant shapes"
    return f"{degree} snowfall, snow on the ground and on roofs, cold light"


def build_prompts(env: Environment | None = None) -> PromptPair:
    """The prompt pair for a frame of a scene in `env` (default: a clear midday)."""
    env = env if env is not None else Environment()
    prompt = f"{_STYLE}, {_time_words(env)}, {_weather_words(env)}"
    return PromptPair(prompt=prompt, negative=NEGATIVE_PROMPT)
