"""The Scene: the single source of truth for a drivetwin world.

Everything else (MuJoCo model and data, the renderer, sensors) is a view rebuilt or patched
from a Scene. Units are SI: metres, seconds, radians, kilograms. The world frame is
right-handed with z up; yaw is measured from +x towards +y.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Annotated, Any, Literal

from drivetwin.worlds.asset_table import asset_table
from drivetwin.worlds.json_input import MAX_SCENE_FILE_BYTES, JsonInputError, parse_json, read_text_file
from drivetwin.worlds.storyboard import Storyboard
from pydantic import (
    AfterValidator,
    BaseModel,
    ConfigDict,
    Field,
    ValidationError,
    field_validator,
    model_validator,
)

SCHEMA_VERSION: Literal[1] = 1

# Limits on what a Scene may hold; Workers refuse edits that would exceed them.
# 10,000: MuJoCo pools keep edits at a few ms at 5,000 assets (drivetwin bench edits), and
# compiling twice that many bodies still fits in memory and a few seconds on 2 cores.
MAX_ASSETS = 10_000
# Coordinates beyond this are certainly a mistake (a campus is a few hundred metres).
MAX_COORDINATE_M = 10_000.0


def _finite(value: float) -> float:
    if not math.isfinite(value):
        raise ValueError("must be a finite number (not NaN or infinity)")
    if abs(value) > MAX_COORDINATE_M:
        raise ValueError(f"must be within ±{MAX_COORDINATE_M:g} m")
    return value


Finite = Annotated[float, AfterValidator(_finite)]
Vec2 = tuple[Finite, Finite]
Positive = Annotated[float, Field(gt=0.0, allow_inf_nan=False)]
Fraction = Annotated[float, Field(ge=0.0, le=1.0, allow_inf_nan=False)]


class SceneModel(BaseModel):
    """Base for every Scene part: strict about unknown fields, compared by value."""

    # No float is ever infinite or NaN: pydantic would save either as `null`.
    model_config = ConfigDict(extra="forbid", validate_assignment=True, frozen=False, allow_inf_nan=False)


class Pose(SceneModel):
    """A planar pose on the ground: position in metres, heading (yaw) in radians."""

    x: Finite
    y: Finite
    z: Finite = 0.0
    yaw: Finite = 0.0

    @field_validator("yaw")
    @classmethod
    def _wrap_yaw(cls, yaw: float) -> float:
        return canonical_yaw(yaw)

    @property
    def xy(self) -> tuple[float, float]:
        return (self.x, self.y)


# Yaw is kept to 12 decimals (a nanoradian): enough for any pose, and a value that is
# already canonical comes back bit for bit, so save -> load -> save is byte-identical.
YAW_DECIMALS = 12
_YAW_LIMIT = round(math.pi, YAW_DECIMALS)


def canonical_yaw(yaw: float) -> float:
    """`yaw` wrapped into (-pi, pi] and rounded; a canonical value maps to itself exactly."""
    wrapped = round(math.remainder(yaw, math.tau), YAW_DECIMALS)
    if wrapped > _YAW_LIMIT:
        wrapped = round(wrapped - math.tau, YAW_DECIMALS)
    elif wrapped <= -_YAW_LIMIT:
        wrapped = round(wrapped + math.tau, YAW_DECIMALS)
    return wrapped + 0.0  # -0.0 becomes 0.0


class Bounds(SceneModel):
    """The rectangle of ground the world covers."""

    xmin: Finite
    xmax: Finite
    ymin: Finite
    ymax: Finite

    @model_validator(mode="after")
    def _ordered(self) -> Bounds:
        if self.xmin >= self.xmax or self.ymin >= self.ymax:
            raise ValueError("bounds need xmin < xmax and ymin < ymax")
        return self

    def contains(self, x: float, y: float, margin: float = 0.0) -> bool:
        return (
            self.xmin + margin <= x <= self.xmax - margin
            and self.ymin + margin <= y <= self.ymax - margin
        )

    @property
    def centre(self) -> tuple[float, float]:
        return ((self.xmin + self.xmax) / 2, (self.ymin + self.ymax) / 2)


class Ground(SceneModel):
    """The ground plane's physical and visual properties."""

    friction: Positive = 1.0
    rgba: tuple[Fraction, Fraction, Fraction, Fraction] = (0.35, 0.42, 0.3, 1.0)


class Lane(SceneModel):
    """One lane of a road: traffic flows along the centreline, from its first point."""

    id: str
    road: str
    centreline: list[Vec2] = Field(min_length=2)
    width: Positive = 3.5
    speed_limit: Positive = 8.0
    # Imported road maps (drivetwin.worlds.opendrive) fill these; the defaults keep older
    # scene files loading. OpenDRIVE lane types kept as lanes: traffic drives in "driving".
    kind: Literal["driving", "shoulder", "border", "parking"] = "driving"
    # Height of the road surface at each centreline point, metres; None: flat at z = 0.
    elevation: list[Finite] | None = None
    # Lanes that traffic may continue into from this lane's end (through junctions).
    successors: list[str] = Field(default_factory=list)

    @model_validator(mode="after")
    def _elevation_per_point(self) -> Lane:
        if self.elevation is not None and len(self.elevation) != len(self.centreline):
            raise ValueError(f"lane {self.id!r}: elevation needs one height per centreline point")
        return self


class Sidewalk(SceneModel):
    """A walkway beside a road, as a polyline with a width."""

    id: str
    polyline: list[Vec2] = Field(min_length=2)
    width: Positive = 2.0


class Crossing(SceneModel):
    """A marked pedestrian crossing: a straight strip from one kerb to the other."""

    id: str
    start: Vec2
    end: Vec2
    width: Positive = 3.0


class PavedArea(SceneModel):
    """Drivable paving that is not a lane: an intersection box, a parking lot, a drop-off."""

    id: str
    kind: Literal["intersection", "parking", "plaza", "driveway"]
    polygon: list[Vec2] = Field(min_length=3)


class RoadNetwork(SceneModel):
    """Lanes, sidewalks, crossings and other paved areas of a world."""

    lanes: list[Lane] = Field(default_factory=list)
    sidewalks: list[Sidewalk] = Field(default_factory=list)
    crossings: list[Crossing] = Field(default_factory=list)
    paved: list[PavedArea] = Field(default_factory=list)

    def lane(self, lane_id: str) -> Lane | None:
        return next((lane for lane in self.lanes if lane.id == lane_id), None)


class Building(SceneModel):
    """A static building: a polygon footprint extruded to a height. Nothing may be inside."""

    id: str
    name: str
    footprint: list[Vec2] = Field(min_length=3)
    height: Positive = 10.0
    rgba: tuple[Fraction, Fraction, Fraction, Fraction] = (0.75, 0.72, 0.68, 1.0)


class Landmark(SceneModel):
    """A named place people refer to: a point (with a facing) or an area (a polygon)."""

    name: str
    aliases: list[str] = Field(default_factory=list)
    kind: Literal["point", "area"] = "point"
    position: Vec2
    # Direction a visitor faces when standing at the landmark looking out (e.g. away from
    # a building entrance); "in front of" the landmark is along this heading.
    heading: Finite = 0.0
    polygon: list[Vec2] | None = None
    description: str = ""

    @model_validator(mode="after")
    def _area_has_polygon(self) -> Landmark:
        if self.kind == "area" and (self.polygon is None or len(self.polygon) < 3):
            raise ValueError(f"area landmark {self.name!r} needs a polygon of 3+ points")
        return self

    def names(self) -> list[str]:
        return [self.name, *self.aliases]


class PhysicsProps(SceneModel):
    """How an asset takes part in the physics."""

    mass: Positive
    friction: Positive = 1.0
    # A static asset is welded to the world; a dynamic one is a free body.
    dynamic: bool = True


class Appearance(SceneModel):
    """How an asset looks: a colour override and a material name."""

    rgba: tuple[Fraction, Fraction, Fraction, Fraction] | None = None
    material: Literal["default", "matte", "metal", "glossy", "plastic", "wood", "concrete"] = (
        "default"
    )


class Parked(SceneModel):
    """Stays where it was put."""

    kind: Literal["parked"] = "parked"


class DriveLane(SceneModel):
    """Drives along a lane's centreline at a speed; loops back to the start at its end."""

    kind: Literal["drive_lane"] = "drive_lane"
    lane: str
    speed: Annotated[float, Field(gt=0.0, le=40.0)] = 5.0


class FollowPath(SceneModel):
    """Follows a polyline of waypoints at a speed, once or looping."""

    kind: Literal["follow_path"] = "follow_path"
    waypoints: list[Vec2] = Field(min_length=2)
    speed: Annotated[float, Field(gt=0.0, le=40.0)] = 1.4
    loop: bool = False
    start_time: Annotated[float, Field(ge=0.0)] = 0.0


class Circle(SceneModel):
    """Drives a circle (a skidpad manoeuvre) around a centre at a radius and speed."""

    kind: Literal["circle"] = "circle"
    centre: Vec2
    radius: Annotated[float, Field(gt=0.5, le=200.0)] = 5.0
    speed: Annotated[float, Field(gt=0.0, le=30.0)] = 2.0
    clockwise: bool = False


class CrossRoad(SceneModel):
    """Walks across a road from one side to the other, starting at a simulation time."""

    kind: Literal["cross_road"] = "cross_road"
    start: Vec2
    end: Vec2
    speed: Annotated[float, Field(gt=0.0, le=10.0)] = 1.4
    start_time: Annotated[float, Field(ge=0.0)] = 0.0


class Jaywalk(SceneModel):
    """Crosses the ego vehicle's lane ahead of it, away from any crossing.

    The walker waits at the kerb until the ego is `trigger_distance` metres from the
    crossing point, then walks across at `speed`.
    """

    kind: Literal["jaywalk"] = "jaywalk"
    start: Vec2
    end: Vec2
    speed: Annotated[float, Field(gt=0.0, le=10.0)] = 1.8
    trigger_distance: Annotated[float, Field(gt=0.0, le=200.0)] = 20.0


Behaviour = Annotated[
    Parked | DriveLane | FollowPath | Circle | CrossRoad | Jaywalk,
    Field(discriminator="kind"),
]
BEHAVIOUR_KINDS = ("parked", "drive_lane", "follow_path", "circle", "cross_road", "jaywalk")

_ASSET_ID = re.compile(r"^[a-z][a-z0-9_]{0,63}$")


class AssetInstance(SceneModel):
    """One placed asset: a catalog category at a pose, with physics, looks and behaviour."""

    id: str
    category: str
    pose: Pose
    scale: Annotated[float, Field(gt=0.05, le=20.0)] = 1.0
    physics: PhysicsProps
    appearance: Appearance = Field(default_factory=Appearance)
    behaviour: Behaviour = Field(default_factory=Parked)
    # Words the user used for it ("the maintenance cones"); helps later references.
    label: str = ""

    @field_validator("id")
    @classmethod
    def _id_shape(cls, value: str) -> str:
        if not _ASSET_ID.match(value):
            raise ValueError("asset ids are lower_snake_case, start with a letter, ≤ 64 chars")
        return value


EGO_ID = "ego"


def asset_order(asset: AssetInstance) -> tuple[str, int, str]:
    """Sort key of assets: by category-like prefix, then the number (cone_2 before cone_10)."""
    prefix, _, number = asset.id.rpartition("_")
    return (prefix, int(number), asset.id) if number.isdigit() else (asset.id, -1, asset.id)

WeatherKind = Literal["clear", "cloudy", "rain", "fog", "snow"]
WEATHER_KINDS: tuple[str, ...] = ("clear", "cloudy", "rain", "fog", "snow")
_CLOCK = re.compile(r"^([01]\d|2[0-3]):([0-5]\d)$")


class Weather(SceneModel):
    """Weather kind and intensity (0 = trace, 1 = as heavy as it gets)."""

    kind: WeatherKind = "clear"
    intensity: Fraction = 0.0

    @model_validator(mode="after")
    def _clear_has_no_intensity(self) -> Weather:
        if self.kind == "clear" and self.intensity != 0.0:
            object.__setattr__(self, "intensity", 0.0)
        return self


class Lighting(SceneModel):
    """Lighting beyond what the clock implies."""

    street_lights: Literal["auto", "on", "off"] = "auto"
    vehicle_lights: Literal["auto", "on", "off"] = "auto"
    exposure: Annotated[float, Field(gt=0.0, le=4.0)] = 1.0


class Environment(SceneModel):
    """Time of day, weather and lighting."""

    time_of_day: str = "12:00"
    weather: Weather = Field(default_factory=Weather)
    lighting: Lighting = Field(default_factory=Lighting)

    @field_validator("time_of_day")
    @classmethod
    def _clock_time(cls, value: str) -> str:
        if not _CLOCK.match(value):
            raise ValueError("time of day is a 24-hour clock time 'HH:MM', e.g. '21:30'")
        return value

    @property
    def hours(self) -> float:
        """The clock time as fractional hours since midnight."""
        hh, mm = self.time_of_day.split(":")
        return int(hh) + int(mm) / 60.0

    @property
    def is_night(self) -> bool:
        return self.hours < 6.5 or self.hours >= 19.0


class Scene(SceneModel):
    """A whole world: ground, roads, buildings, landmarks, assets, ego and environment."""

    schema_version: Literal[1] = SCHEMA_VERSION
    name: str
    description: str = ""
    bounds: Bounds
    ground: Ground = Field(default_factory=Ground)
    roads: RoadNetwork = Field(default_factory=RoadNetwork)
    buildings: list[Building] = Field(default_factory=list)
    landmarks: list[Landmark] = Field(default_factory=list)
    ego: AssetInstance
    assets: list[AssetInstance] = Field(default_factory=list)
    environment: Environment = Field(default_factory=Environment)
    # What happens over time (OpenSCENARIO-like); empty for a still scene.
    storyboard: Storyboard = Field(default_factory=Storyboard)
    # The world package folder (drivetwin.worlds.packages) this world was loaded
    # from: its terrain collides in MuJoCo and its splats are the renderer's background.
    package: str | None = None

    @model_validator(mode="after")
    def _consistent(self) -> Scene:
        if self.ego.id != EGO_ID:
            raise ValueError(f"the ego vehicle's id must be {EGO_ID!r}")
        ids = [asset.id for asset in self.assets]
        if len(set(ids)) != len(ids) or EGO_ID in ids:
            raise ValueError("asset ids must be unique and differ from the ego's")
        if len(self.assets) > MAX_ASSETS:
            raise ValueError(f"a scene holds at most {MAX_ASSETS} assets")
        # One canonical order, so that equal scenes compare equal whatever edits built them.
        self.__dict__["assets"] = sorted(self.assets, key=asset_order)
        return self

    # Lookups ----------------------------------------------------------------------------
    def asset(self, asset_id: str) -> AssetInstance | None:
        """The asset (or the ego) with this id, or None."""
        if asset_id == EGO_ID:
            return self.ego
        return asset_table(self.assets).by_id.get(asset_id)  # a table beside the list, not a scan

    def all_assets(self) -> list[AssetInstance]:
        """Every asset including the ego vehicle, ego first."""
        return [self.ego, *self.assets]

    def landmark(self, name: str) -> Landmark | None:
        """The landmark whose name or alias matches `name` (case-insensitive)."""
        key = name.strip().lower()
        for landmark in self.landmarks:
            if key in (n.lower() for n in landmark.names()):
                return landmark
        return None

    def count(self, category: str) -> int:
        return asset_table(self.assets).count(category)

    def next_id(self, category: str) -> str:
        """A fresh id for a new asset of `category`: category_N with the smallest free N."""
        taken = asset_table(self.assets).by_id
        n = 1
        while f"{category}_{n}" in taken:
            n += 1
        return f"{category}_{n}"

    # Persistence ------------------------------------------------------------------------
    def to_json(self) -> str:
        return self.model_dump_json(indent=2)

    def save(self, path: str | Path) -> None:
        """Write the scene as JSON atomically (a crash never leaves half a file)."""
        target = Path(path)
        tmp = target.with_suffix(target.suffix + ".tmp")
        tmp.write_text(self.to_json(), encoding="utf-8")
        tmp.replace(target)

    @classmethod
    def load(cls, path: str | Path) -> Scene:
        """Read a scene saved with `save`; a damaged file raises SceneFileError."""
        try:
            text = read_text_file(path, "scene file", MAX_SCENE_FILE_BYTES)
        except JsonInputError as exc:
            raise SceneFileError(str(exc)) from exc
        return cls.from_json(text, source=str(path))

    @classmethod
    def from_json(cls, text: str, source: str = "<text>") -> Scene:
        try:
            data: Any = parse_json(text, source)
        except JsonInputError as exc:
            raise SceneFileError(str(exc)) from exc
        try:
            return cls.model_validate(data)
        except ValidationError as exc:
            first = exc.errors()[0]
            where = ".".join(str(p) for p in first["loc"])
            raise SceneFileError(
                f"{source} is not a valid scene: {exc.error_count()} error(s), "
                f"first at {where or 'top level'}: {first['msg']}"
            ) from exc


class SceneFileError(ValueError):
    """A scene file that cannot be read, parsed or validated."""


def scene_json_schema() -> dict[str, Any]:
    """The published JSON Schema of a saved Scene."""
    schema = Scene.model_json_schema()
    schema["$id"] = f"https://drivetwin.dev/schema/scene-v{SCHEMA_VERSION}.json"
    return schema
