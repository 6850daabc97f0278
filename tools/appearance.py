"""Appearance Workers: time of day, weather, lighting, and the colours and materials of assets."""

from __future__ import annotations

import re
from typing import Literal

from drivetwin.tools.base import CategoryName, Tool, ToolArgs, ToolResult
from drivetwin.tools.errors import NotFoundError, RuleViolation
from drivetwin.tools.move import find_asset
from drivetwin.worlds.edits import SetEnvironment, UpdateAsset, WorldEdit
from drivetwin.worlds.scene import Lighting, Scene, Weather, WeatherKind
from pydantic import Field

COLOURS: dict[str, tuple[float, float, float, float]] = {
    "red": (0.8, 0.1, 0.1, 1.0), "green": (0.15, 0.6, 0.2, 1.0), "blue": (0.15, 0.3, 0.85, 1.0),
    "yellow": (0.95, 0.85, 0.1, 1.0), "orange": (0.95, 0.5, 0.05, 1.0),
    "white": (0.95, 0.95, 0.95, 1.0), "black": (0.05, 0.05, 0.05, 1.0),
    "grey": (0.5, 0.5, 0.5, 1.0), "gray": (0.5, 0.5, 0.5, 1.0), "silver": (0.75, 0.75, 0.78, 1.0),
    "purple": (0.5, 0.2, 0.6, 1.0), "pink": (0.95, 0.5, 0.7, 1.0), "brown": (0.45, 0.3, 0.15, 1.0),
    "cyan": (0.1, 0.8, 0.85, 1.0), "teal": (0.1, 0.5, 0.5, 1.0), "beige": (0.85, 0.8, 0.65, 1.0),
    "gold": (0.85, 0.7, 0.2, 1.0), "navy": (0.05, 0.1, 0.4, 1.0), "maroon": (0.45, 0.05, 0.1, 1.0),
}
_HEX = re.compile(r"^#?([0-9a-fA-F]{6})$")

TIME_PRESETS: dict[str, str] = {
    "dawn": "06:00", "sunrise": "06:30", "morning": "09:00", "day": "12:00", "daytime": "12:00",
    "noon": "12:00", "midday": "12:00", "afternoon": "15:00", "sunset": "19:30",
    "dusk": "20:00", "evening": "21:00", "night": "22:00", "nighttime": "22:00",
    "midnight": "00:00",
}


def hex_colour(rgba: tuple[float, ...]) -> str:
    """'#rrggbb' for an RGBA colour: how a colour read off one asset is given to another."""
    return "#" + "".join(f"{round(float(c) * 255):02x}" for c in rgba[:3])


def resolve_colour(text: str) -> tuple[float, float, float, float]:
    """An RGBA colour from a name ('red') or '#rrggbb'."""
    key = text.strip().lower()
    if key in COLOURS:
        return COLOURS[key]
    match = _HEX.match(key)
    if match:
        value = int(match.group(1), 16)
        return ((value >> 16) / 255.0, ((value >> 8) & 255) / 255.0, (value & 255) / 255.0, 1.0)
    raise RuleViolation("colour", f"unknown colour {text!r}; use #rrggbb or one of: {', '.join(COLOURS)}")


class TimeArgs(ToolArgs):
    time: str = Field(description="24-hour 'HH:MM' or one of: " + ", ".join(TIME_PRESETS))


class SetTimeOfDay(Tool[TimeArgs]):
    name = "set_time_of_day"
    description = "Set the clock time of the scene (daytime, night, dusk, or 'HH:MM')."
    family = "appearance"
    Args = TimeArgs

    def propose(self, args: TimeArgs, scene: Scene) -> ToolResult:
        clock = TIME_PRESETS.get(args.time.strip().lower(), args.time.strip())
        if re.fullmatch(r"\d:\d\d", clock):
            clock = "0" + clock
        try:
            after = scene.environment.model_copy(update={"time_of_day": clock})
            after = type(after).model_validate(after.model_dump())
        except ValueError as exc:
            raise RuleViolation(
                "time", f"unknown time {args.time!r}; use 'HH:MM' or one of: {', '.join(TIME_PRESETS)}"
            ) from exc
        edit = WorldEdit(ops=(SetEnvironment(before=scene.environment, after=after),))
        return ToolResult(edit, f"time of day is now {clock}")


class WeatherArgs(ToolArgs):
    kind: WeatherKind
    intensity: float | None = Field(
        None, ge=0.0, le=1.0, description="0 trace .. 1 extreme (light 0.3, moderate 0.6, heavy 0.9)"
    )


class SetWeather(Tool[WeatherArgs]):
    name = "set_weather"
    description = "Set the weather: clear, cloudy, rain, fog or snow, with an intensity 0..1."
    family = "appearance"
    Args = WeatherArgs

    def propose(self, args: WeatherArgs, scene: Scene) -> ToolResult:
        intensity = 0.0 if args.kind == "clear" else (args.intensity if args.intensity is not None else 0.6)
        weather = Weather(kind=args.kind, intensity=intensity)
        after = scene.environment.model_copy(update={"weather": weather})
        edit = WorldEdit(ops=(SetEnvironment(before=scene.environment, after=after),))
        return ToolResult(edit, f"weather is now {args.kind} ({intensity:.1f})")


class LightingArgs(ToolArgs):
    street_lights: Literal["auto", "on", "off"] | None = None
    vehicle_lights: Literal["auto", "on", "off"] | None = None
    exposure: float | None = Field(None, gt=0.0, le=4.0)


class SetLighting(Tool[LightingArgs]):
    name = "set_lighting"
    description = "Switch street lights or vehicle lights on/off/auto, or change exposure."
    family = "appearance"
    Args = LightingArgs

    def propose(self, args: LightingArgs, scene: Scene) -> ToolResult:
        changes = args.model_dump(exclude_none=True)
        lighting = Lighting.model_validate({**scene.environment.lighting.model_dump(), **changes})
        after = scene.environment.model_copy(update={"lighting": lighting})
        edit = WorldEdit(ops=(SetEnvironment(before=scene.environment, after=after),))
        return ToolResult(edit, f"lighting: {lighting.model_dump()}")


class AssetLookArgs(ToolArgs):
    assets: list[str] = Field(default_factory=list, description="asset ids to change")
    category: CategoryName | None = Field(None, description="or: every asset of this category")
    colour: str | None = Field(None, description="colour name or #rrggbb")
    material: Literal["default", "matte", "metal", "glossy", "plastic", "wood", "concrete"] | None = None


class SetAssetAppearance(Tool[AssetLookArgs]):
    name = "set_asset_appearance"
    description = "Change the colour and/or material of assets (by id, or a whole category)."
    family = "appearance"
    Args = AssetLookArgs

    def propose(self, args: AssetLookArgs, scene: Scene) -> ToolResult:
        targets = [find_asset(scene, a) for a in args.assets]
        if args.category:
            targets += [a for a in scene.all_assets() if a.category == args.category and a not in targets]
        if not targets:
            raise NotFoundError("name the assets to change (ids) or a category that is in the scene")
        if args.colour is None and args.material is None:
            raise RuleViolation("appearance", "give a colour, a material, or both")
        ops = []
        for asset in targets:
            look = asset.appearance
            if args.colour is not None:
                look = look.model_copy(update={"rgba": resolve_colour(args.colour)})
            if args.material is not None:
                look = look.model_copy(update={"material": args.material})
            ops.append(UpdateAsset(before=asset, after=asset.model_copy(update={"appearance": look})))
        ids = ", ".join(a.id for a in targets)
        return ToolResult(WorldEdit(ops=tuple(ops)), f"changed the look of {ids}")
