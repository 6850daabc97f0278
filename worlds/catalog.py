"""The asset catalog: what can be placed in a world, with real sizes, masses and words for it.

Each category is built from a few primitive parts (boxes, cylinders, spheres). The same parts
become the category's trimesh mesh (for rendering and export) and its MuJoCo geoms (for
collision), so what is drawn is what collides.

Reconstructed assets join the catalog too: every asset package found on DRIVETWIN_ASSETS and in
the user's asset folder (see drivetwin.worlds.reconstruct.package) becomes a Category whose
`package` names its folder. Its one box part is the bounding box (for footprints and overlap
checks); MuJoCo collides its convex hulls and the hybrid renderer draws its fitted splats.
"""

from __future__ import annotations

import difflib
import os
from collections.abc import Iterable
from functools import cache, lru_cache
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

PartShape = Literal["box", "cylinder", "sphere"]
Placement = Literal["road", "sidewalk", "drivable", "anywhere"]
Motion = Literal["static", "vehicle", "walker", "prop"]


class Part(BaseModel):
    """A primitive piece of an asset, in the asset's frame (x forward, z up, origin on ground).

    `size` is half-extents for a box, (radius, half-height) for a cylinder, (radius,) for a
    sphere, in metres.
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    shape: PartShape
    size: tuple[float, ...]
    pos: tuple[float, float, float]
    rgba: tuple[float, float, float, float]
    # Axis of a cylinder: "z" upright, "y" for wheels whose axle is sideways.
    axis: Literal["x", "y", "z"] = "z"
    # Wheels are parts too: a vehicle's wheels become hinged bodies in MuJoCo.
    role: Literal["body", "wheel"] = "body"


class Category(BaseModel):
    """One kind of asset: its size, mass, how it may be placed and what people call it."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    name: str
    description: str
    length: float  # along x, metres
    width: float  # along y, metres
    height: float  # metres
    mass: float  # kilograms
    synonyms: tuple[str, ...] = ()
    tags: tuple[str, ...] = ()
    placement: Placement = "anywhere"
    motion: Motion = "prop"
    max_count: int = 100
    parts: tuple[Part, ...] = Field(min_length=1)
    # Vehicles: distance between axles and the largest steering angle (radians).
    wheelbase: float | None = None
    max_steer: float | None = None
    # Folder of the asset package a reconstructed category comes from; None for built-ins.
    package: str | None = None

    @property
    def footprint_radius(self) -> float:
        """Radius of the circle that bounds the footprint; used for overlap checks."""
        return float(0.5 * (self.length**2 + self.width**2) ** 0.5)

    @property
    def words(self) -> tuple[str, ...]:
        """Every word or phrase that names this category."""
        return (self.name, self.name.replace("_", " "), *self.synonyms)


def _box(hx: float, hy: float, hz: float, x: float, y: float, z: float, rgba: tuple[float, ...]) -> Part:
    return Part(shape="box", size=(hx, hy, hz), pos=(x, y, z), rgba=_rgba(rgba))


def _cyl(r: float, hh: float, x: float, y: float, z: float, rgba: tuple[float, ...]) -> Part:
    return Part(shape="cylinder", size=(r, hh), pos=(x, y, z), rgba=_rgba(rgba))


def _ball(r: float, x: float, y: float, z: float, rgba: tuple[float, ...]) -> Part:
    return Part(shape="sphere", size=(r,), pos=(x, y, z), rgba=_rgba(rgba))


def _rgba(values: tuple[float, ...]) -> tuple[float, float, float, float]:
    r, g, b, *rest = values
    return (r, g, b, rest[0] if rest else 1.0)


def _wheels(wheelbase: float, track: float, radius: float, width: float) -> tuple[Part, ...]:
    tyre = (0.08, 0.08, 0.08)
    return tuple(
        Part(
            shape="cylinder",
            size=(radius, width / 2),
            pos=(x, y, radius),
            rgba=_rgba(tyre),
            axis="y",
            role="wheel",
        )
        for x in (wheelbase / 2, -wheelbase / 2)
        for y in (track / 2, -track / 2)
    )


def _vehicle(
    name: str,
    description: str,
    length: float,
    width: float,
    height: float,
    mass: float,
    colour: tuple[float, ...],
    *,
    wheelbase: float,
    wheel_radius: float,
    synonyms: tuple[str, ...],
    tags: tuple[str, ...] = (),
    cabin: float = 0.55,
    max_steer: float = 0.6,
    max_count: int = 60,
) -> Category:
    clearance = wheel_radius * 0.9
    body_h = (height - clearance) * (1 - cabin * 0.45)
    parts = [
        _box(length / 2, width / 2, body_h / 2, 0.0, 0.0, clearance + body_h / 2, colour),
        _box(
            length * cabin / 2,
            width * 0.45,
            (height - clearance - body_h) / 2,
            -length * 0.05,
            0.0,
            clearance + body_h + (height - clearance - body_h) / 2,
            (0.15, 0.2, 0.25),
        ),
        *_wheels(wheelbase, width - 0.25, wheel_radius, 0.22),
    ]
    return Category(
        name=name,
        description=description,
        length=length,
        width=width,
        height=height,
        mass=mass,
        synonyms=synonyms,
        tags=("vehicle", *tags),
        placement="drivable",
        motion="vehicle",
        max_count=max_count,
        parts=tuple(parts),
        wheelbase=wheelbase,
        max_steer=max_steer,
    )


ORANGE = (0.95, 0.45, 0.05)
WHITE = (0.95, 0.95, 0.95)
GREY = (0.5, 0.5, 0.5)
RED = (0.8, 0.1, 0.1)
GREEN = (0.2, 0.55, 0.2)
BROWN = (0.45, 0.3, 0.15)
YELLOW = (0.95, 0.8, 0.1)
DARK = (0.15, 0.15, 0.15)


def _build() -> tuple[Category, ...]:
    return (
        _vehicle(
            "ego_vehicle",
            "the ego vehicle under test: a sedan with sensors on the roof",
            4.6, 1.85, 1.6, 1600.0, (0.9, 0.9, 0.95),
            wheelbase=2.8, wheel_radius=0.33,
            synonyms=("ego", "ego car", "ego vehicle", "our car", "the test vehicle"),
            tags=("ego",), max_count=1,
        ),
        _vehicle(
            "passenger_car",
            "a four-door passenger car (sedan)",
            4.5, 1.8, 1.45, 1400.0, (0.2, 0.35, 0.75),
            wheelbase=2.7, wheel_radius=0.32,
            synonyms=("car", "sedan", "automobile", "vehicle", "saloon", "hatchback", "auto"),
        ),
        _vehicle(
            "suv",
            "a sport utility vehicle",
            4.8, 1.95, 1.8, 2100.0, (0.25, 0.25, 0.28),
            wheelbase=2.85, wheel_radius=0.38,
            synonyms=("suv", "sport utility vehicle", "crossover", "jeep", "4x4"),
        ),
        _vehicle(
            "bus",
            "a city or campus shuttle bus",
            12.0, 2.55, 3.2, 12000.0, (0.95, 0.75, 0.1),
            wheelbase=6.0, wheel_radius=0.5, cabin=0.9,
            synonyms=("bus", "coach", "shuttle", "shuttle bus", "school bus", "transit bus"),
            max_count=10,
        ),
        _vehicle(
            "truck",
            "a box truck for deliveries",
            8.0, 2.5, 3.4, 9000.0, (0.85, 0.85, 0.85),
            wheelbase=4.5, wheel_radius=0.5, cabin=0.25,
            synonyms=("truck", "lorry", "box truck", "delivery truck", "van", "pickup"),
            max_count=10,
        ),
        _vehicle(
            "ackermann_robot",
            "a mid-scale Ackermann-steered research robot (about 1:4 scale)",
            1.2, 0.6, 0.55, 60.0, (0.1, 0.5, 0.6),
            wheelbase=0.8, wheel_radius=0.12, cabin=0.4, max_steer=0.5,
            synonyms=(
                "robot", "rover", "mid-scale robot", "ackermann robot",
                "ackermann-steered robot", "mid-scale ackermann-steered robot",
                "autonomous robot", "small vehicle", "hunter robot",
            ),
            tags=("robot",), max_count=20,
        ),
        Category(
            name="bicycle",
            description="a bicycle, ridden or parked",
            length=1.75, width=0.6, height=1.1, mass=15.0,
            synonyms=("bike", "bicycle", "cycle", "push bike"),
            tags=("vehicle", "vulnerable"),
            placement="anywhere", motion="walker", max_count=40,
            parts=(
                _box(0.55, 0.04, 0.04, 0.0, 0.0, 0.6, RED),
                Part(shape="cylinder", size=(0.34, 0.02), pos=(0.55, 0.0, 0.34), rgba=_rgba(DARK), axis="y"),
                Part(shape="cylinder", size=(0.34, 0.02), pos=(-0.55, 0.0, 0.34), rgba=_rgba(DARK), axis="y"),
                _box(0.05, 0.3, 0.02, 0.5, 0.0, 1.05, DARK),
            ),
        ),
        Category(
            name="pedestrian",
            description="a person walking",
            length=0.5, width=0.6, height=1.75, mass=75.0,
            synonyms=(
                "pedestrian", "person", "people", "walker", "human", "man", "woman",
                "jaywalker", "passer-by", "student", "ped",
            ),
            tags=("vulnerable", "person"),
            placement="anywhere", motion="walker", max_count=60,
            parts=(
                _cyl(0.1, 0.42, 0.0, 0.12, 0.42, (0.2, 0.2, 0.35)),
                _cyl(0.1, 0.42, 0.0, -0.12, 0.42, (0.2, 0.2, 0.35)),
                _box(0.14, 0.24, 0.3, 0.0, 0.0, 1.14, (0.7, 0.2, 0.2)),
                _ball(0.12, 0.0, 0.0, 1.6, (0.85, 0.65, 0.5)),
            ),
        ),
        Category(
            name="traffic_cone",
            description="an orange traffic cone, 70 cm",
            length=0.36, width=0.36, height=0.7, mass=3.0,
            synonyms=("cone", "traffic cone", "pylon", "safety cone", "road cone", "witch hat"),
            tags=("maintenance", "temporary", "marker"),
            placement="drivable", max_count=200,
            parts=(
                _box(0.18, 0.18, 0.02, 0.0, 0.0, 0.02, DARK),
                _cyl(0.13, 0.17, 0.0, 0.0, 0.21, ORANGE),
                _cyl(0.085, 0.12, 0.0, 0.0, 0.5, WHITE),
                _cyl(0.045, 0.04, 0.0, 0.0, 0.66, ORANGE),
            ),
        ),
        Category(
            name="road_barrier",
            description="a plastic water-filled road barrier, 2 m long",
            length=2.0, width=0.5, height=1.0, mass=60.0,
            synonyms=("barrier", "road barrier", "jersey barrier", "roadblock", "barricade", "fence"),
            tags=("maintenance", "temporary", "block"),
            placement="drivable", max_count=100,
            parts=(
                _box(1.0, 0.25, 0.25, 0.0, 0.0, 0.25, RED),
                _box(1.0, 0.15, 0.25, 0.0, 0.0, 0.75, WHITE),
            ),
        ),
        Category(
            name="cement_rubble",
            description="a pile of broken cement and debris",
            length=1.6, width=1.4, height=0.6, mass=400.0,
            synonyms=("rubble", "cement rubble", "debris", "concrete debris", "rocks", "pothole debris", "construction debris"),
            tags=("maintenance", "obstacle"),
            placement="drivable", max_count=30,
            parts=(
                _box(0.8, 0.7, 0.15, 0.0, 0.0, 0.15, GREY),
                _box(0.45, 0.4, 0.15, 0.15, -0.1, 0.45, (0.6, 0.58, 0.55)),
                _ball(0.25, -0.45, 0.35, 0.25, (0.55, 0.55, 0.5)),
            ),
        ),
        Category(
            name="construction_sign",
            description="a portable 'road work ahead' sign on an A-frame",
            length=0.6, width=0.9, height=1.4, mass=12.0,
            synonyms=("construction sign", "road work sign", "work zone sign", "maintenance sign", "roadworks sign"),
            tags=("maintenance", "temporary", "sign"),
            placement="anywhere", max_count=40,
            parts=(
                _box(0.3, 0.45, 0.03, 0.0, 0.0, 0.03, DARK),
                _box(0.02, 0.45, 0.45, 0.0, 0.0, 0.9, ORANGE),
                _box(0.02, 0.03, 0.4, 0.0, 0.0, 0.4, GREY),
            ),
        ),
        Category(
            name="pedestrian_sign",
            description="a pedestrian crossing warning sign on a pole",
            length=0.3, width=0.7, height=2.6, mass=15.0,
            synonyms=("pedestrian sign", "crosswalk sign", "pedestrian crossing sign", "zebra crossing sign"),
            tags=("sign", "permanent"),
            placement="sidewalk", max_count=40,
            parts=(
                _cyl(0.04, 1.0, 0.0, 0.0, 1.0, GREY),
                _box(0.02, 0.35, 0.35, 0.0, 0.0, 2.25, YELLOW),
                _box(0.15, 0.15, 0.02, 0.0, 0.0, 0.02, GREY),
            ),
        ),
        Category(
            name="stop_sign",
            description="an octagonal stop sign on a pole",
            length=0.3, width=0.75, height=2.5, mass=15.0,
            synonyms=("stop sign", "stop", "halt sign"),
            tags=("sign", "permanent"),
            placement="sidewalk", max_count=40,
            parts=(
                _cyl(0.04, 1.0, 0.0, 0.0, 1.0, GREY),
                Part(shape="cylinder", size=(0.37, 0.02), pos=(0.0, 0.0, 2.12), rgba=_rgba(RED), axis="x"),
                _box(0.15, 0.15, 0.02, 0.0, 0.0, 0.02, GREY),
            ),
        ),
        Category(
            name="street_light",
            description="a street light, 6 m pole with a lamp",
            length=1.5, width=0.4, height=6.0, mass=120.0,
            synonyms=("street light", "streetlight", "lamp post", "lamppost", "street lamp", "light pole"),
            tags=("light", "permanent"),
            placement="sidewalk", max_count=60,
            parts=(
                _cyl(0.08, 3.0, 0.0, 0.0, 3.0, GREY),
                _box(0.6, 0.06, 0.05, 0.6, 0.0, 5.9, GREY),
                _box(0.2, 0.15, 0.06, 1.1, 0.0, 5.82, (1.0, 0.95, 0.7)),
            ),
        ),
        Category(
            name="traffic_light",
            description="a three-aspect traffic light on a pole",
            length=0.4, width=0.4, height=3.5, mass=80.0,
            synonyms=("traffic light", "traffic signal", "stoplight", "signal", "traffic lights"),
            tags=("light", "sign", "permanent"),
            placement="sidewalk", max_count=30,
            parts=(
                _cyl(0.07, 1.4, 0.0, 0.0, 1.4, GREY),
                _box(0.15, 0.18, 0.5, 0.0, 0.0, 3.0, DARK),
                _ball(0.1, 0.14, 0.0, 3.3, RED),
                _ball(0.1, 0.14, 0.0, 3.0, YELLOW),
                _ball(0.1, 0.14, 0.0, 2.7, GREEN),
            ),
        ),
        Category(
            name="trash_bin",
            description="a wheelie trash bin",
            length=0.6, width=0.6, height=1.05, mass=20.0,
            synonyms=("trash bin", "bin", "garbage can", "trash can", "dustbin", "waste bin", "rubbish bin", "litter bin"),
            tags=("street furniture",),
            placement="anywhere", max_count=60,
            parts=(
                _box(0.3, 0.3, 0.5, 0.0, 0.0, 0.5, (0.1, 0.35, 0.15)),
                _box(0.31, 0.31, 0.025, 0.0, 0.0, 1.025, (0.08, 0.25, 0.1)),
            ),
        ),
        Category(
            name="tree",
            description="a deciduous tree, about 6 m tall",
            length=3.0, width=3.0, height=6.0, mass=800.0,
            synonyms=("tree", "oak", "maple", "plant", "shade tree"),
            tags=("vegetation", "permanent"),
            placement="anywhere", max_count=100,
            parts=(
                _cyl(0.2, 1.5, 0.0, 0.0, 1.5, BROWN),
                _ball(1.5, 0.0, 0.0, 4.4, GREEN),
            ),
        ),
        Category(
            name="bench",
            description="a park bench for three",
            length=1.8, width=0.65, height=0.85, mass=45.0,
            synonyms=("bench", "park bench", "seat", "seating"),
            tags=("street furniture",),
            placement="anywhere", max_count=60,
            parts=(
                _box(0.9, 0.25, 0.03, 0.0, 0.0, 0.45, BROWN),
                _box(0.9, 0.03, 0.2, 0.0, -0.29, 0.68, BROWN),
                _box(0.04, 0.28, 0.22, 0.8, 0.0, 0.22, DARK),
                _box(0.04, 0.28, 0.22, -0.8, 0.0, 0.22, DARK),
            ),
        ),
        Category(
            name="fire_hydrant",
            description="a red fire hydrant",
            length=0.4, width=0.4, height=0.8, mass=90.0,
            synonyms=("fire hydrant", "hydrant", "fireplug", "fire plug"),
            tags=("street furniture", "permanent"),
            placement="sidewalk", max_count=40,
            parts=(
                _cyl(0.13, 0.32, 0.0, 0.0, 0.32, RED),
                _ball(0.14, 0.0, 0.0, 0.66, RED),
                Part(shape="cylinder", size=(0.05, 0.18), pos=(0.0, 0.0, 0.45), rgba=_rgba(RED), axis="y"),
            ),
        ),
        Category(
            name="parking_sign",
            description="a blue parking sign on a pole",
            length=0.3, width=0.6, height=2.4, mass=12.0,
            synonyms=("parking sign", "p sign", "parking signpost"),
            tags=("sign", "permanent"),
            placement="sidewalk", max_count=30,
            parts=(
                _cyl(0.04, 1.0, 0.0, 0.0, 1.0, GREY),
                _box(0.02, 0.3, 0.3, 0.0, 0.0, 2.1, (0.1, 0.3, 0.8)),
            ),
        ),
        Category(
            name="motorcycle",
            description="a motorcycle or scooter",
            length=2.1, width=0.8, height=1.2, mass=200.0,
            synonyms=("motorcycle", "motorbike", "scooter", "moped", "bike rider"),
            tags=("vehicle", "vulnerable"),
            placement="drivable", motion="walker", max_count=30,
            parts=(
                _box(0.7, 0.2, 0.2, 0.0, 0.0, 0.6, DARK),
                Part(shape="cylinder", size=(0.32, 0.06), pos=(0.7, 0.0, 0.32), rgba=_rgba(DARK), axis="y"),
                Part(shape="cylinder", size=(0.32, 0.06), pos=(-0.7, 0.0, 0.32), rgba=_rgba(DARK), axis="y"),
                _box(0.05, 0.35, 0.03, 0.55, 0.0, 1.15, GREY),
            ),
        ),
        Category(
            name="bollard",
            description="a short steel bollard",
            length=0.25, width=0.25, height=1.0, mass=40.0,
            synonyms=("bollard", "post", "pillar", "stanchion"),
            tags=("block", "permanent"),
            placement="anywhere", max_count=100,
            parts=(_cyl(0.12, 0.5, 0.0, 0.0, 0.5, YELLOW),),
        ),
    )


@cache
def _builtin() -> dict[str, Category]:
    return {c.name: c for c in _build()}


# Packaged categories are found again when these variables change (tests, a new session).
_DISCOVERY_ENV = ("DRIVETWIN_ASSETS", "DRIVETWIN_CACHE", "HOME")


@lru_cache(maxsize=8)
def _catalog_for(discovery_key: tuple[str, ...]) -> dict[str, Category]:
    from drivetwin.worlds.reconstruct.package import packaged_categories

    merged = dict(_builtin())
    for cat in packaged_categories():
        # A package may not shadow a built-in category (the Workers' rules rely on those).
        merged.setdefault(cat.name, cat)
    return merged


def catalog() -> dict[str, Category]:
    """Every category by name: the built-in ones, then those of the asset packages found."""
    return _catalog_for(tuple(os.environ.get(name, "") for name in _DISCOVERY_ENV))


def refresh_catalog() -> None:
    """Look for asset packages again (after one was written into a folder already searched)."""
    _catalog_for.cache_clear()


def category(name: str) -> Category:
    """The category called `name`, or UnknownCategoryError naming the nearest ones."""
    # Built-ins first: a package may not shadow one, and the rules ask this on every overlap
    # test (hundreds of thousands of times in one refused free-spot search), so the common
    # case must not read the environment that package discovery depends on.
    found = _builtin().get(name) or catalog().get(name)
    if found is None:
        raise UnknownCategoryError(name, nearest_categories(name))
    return found


def placeable_categories() -> list[str]:
    """Categories a Worker may add (everything but the ego vehicle)."""
    return [name for name, c in catalog().items() if "ego" not in c.tags]


def nearest_categories(text: str, limit: int = 3) -> list[str]:
    """Category names whose words are closest in spelling to `text`."""
    key = text.strip().lower().replace("_", " ")
    scored: dict[str, float] = {}
    for cat in catalog().values():
        for word in cat.words:
            ratio = difflib.SequenceMatcher(None, key, word.lower()).ratio()
            scored[cat.name] = max(scored.get(cat.name, 0.0), ratio)
    ranked = sorted(scored, key=lambda n: -scored[n])
    return ranked[:limit]


def resolve_category(text: str, allowed: Iterable[str] | None = None) -> str | None:
    """The category that `text` names exactly (name or synonym, any case), or None."""
    key = text.strip().lower().replace("_", " ")
    candidates: tuple[str, ...] = (key,)
    if key.endswith("s") and key[:-1]:
        candidates = (key, key[:-1], key[:-2] if key.endswith("es") else key)
    pool = set(allowed) if allowed is not None else None
    for cat in catalog().values():
        if pool is not None and cat.name not in pool:
            continue
        words = {w.lower() for w in cat.words}
        if any(c in words for c in candidates):
            return cat.name
    return None


class UnknownCategoryError(KeyError):
    """A category name that the catalog does not have."""

    def __init__(self, name: str, nearest: list[str]) -> None:
        self.name = name
        self.nearest = nearest
        super().__init__(name)

    def __str__(self) -> str:
        return f"unknown asset {self.name!r}; nearest: {', '.join(self.nearest)}"
