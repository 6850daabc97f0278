"""The asset catalog: what can be placed in a world, with real sizes, masses and words for it.

The built-in categories are data (worlds/data/catalog.json, validated by `CatalogFile` when first
used). Each is made of a few primitive parts (boxes, cylinders, spheres). The same parts become
the category's trimesh mesh (for rendering and export) and its MuJoCo geoms (for collision), so
what is drawn is what collides.

Reconstructed assets join the catalog too: every asset package found on DRIVETWIN_ASSETS and in
the user's asset folder (see drivetwin.worlds.packages) becomes a Category whose
`package` names its folder. Its one box part is the bounding box (for footprints and overlap
checks); MuJoCo collides its convex hulls and the hybrid renderer draws its fitted splats.
"""

from __future__ import annotations

import difflib
import os
from collections.abc import Iterable
from functools import cache, lru_cache
from pathlib import Path
from typing import Literal

import numpy as np
from drivetwin.worlds.packages import AssetPackage, AssetPackageError, Placement, discover_packages, package_splats
from drivetwin.worlds.render.splats import SH_C0
from pydantic import BaseModel, ConfigDict, Field, model_validator

PartShape = Literal["box", "cylinder", "sphere"]
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
    def drives(self) -> bool:
        """Whether it can drive a lane or a circle: a vehicle or robot, or a rider (a walker-moved
        thing tagged vehicle: a bicycle, a motorcycle)."""
        return self.motion == "vehicle" or (self.motion == "walker" and "vehicle" in self.tags)

    @property
    def words(self) -> tuple[str, ...]:
        """Every word or phrase that names this category."""
        return (self.name, self.name.replace("_", " "), *self.synonyms)


CATALOG_FILE = Path(__file__).with_name("data") / "catalog.json"


class CatalogFile(BaseModel):
    """The built-in catalog as data: every category with its parts, validated on load."""

    model_config = ConfigDict(frozen=True, extra="forbid", populate_by_name=True)

    schema_name: Literal["drivetwin.catalog/1"] = Field(alias="schema")
    categories: tuple[Category, ...] = Field(min_length=1)

    @model_validator(mode="after")
    def _unique_names(self) -> CatalogFile:
        names = [c.name for c in self.categories]
        repeated = sorted({n for n in names if names.count(n) > 1})
        if repeated:
            raise ValueError(f"category names must be unique; repeated: {', '.join(repeated)}")
        return self


@cache
def _builtin() -> dict[str, Category]:
    data = CatalogFile.model_validate_json(CATALOG_FILE.read_text(encoding="utf-8"))
    return {c.name: c for c in data.categories}


# Packaged categories are found again when these variables change (tests, a new session).
_DISCOVERY_ENV = ("DRIVETWIN_ASSETS", "DRIVETWIN_CACHE", "HOME")


def package_category(package: AssetPackage) -> Category:
    """The catalog category an asset package provides: its manifest's words and sizes, and one
    box part (its bounding box, coloured like its splats) for footprints and overlap checks."""
    m = package.manifest
    size = m.dimensions
    box = Part(shape="box", size=(size.length / 2, size.width / 2, size.height / 2),
               pos=(0.0, 0.0, size.height / 2), rgba=(*_mean_colour(package), 1.0))  # fmt: skip
    words = tuple(dict.fromkeys([*m.synonyms, m.name.replace("_", " ")]))
    return Category(
        name=m.name,
        description=m.description or f"a reconstructed {m.name.replace('_', ' ')}",
        length=size.length,
        width=size.width,
        height=size.height,
        mass=m.mass,
        synonyms=words,
        tags=tuple(dict.fromkeys(["reconstructed", *m.tags])),
        placement=m.placement,
        motion=m.motion,
        max_count=m.max_count,
        parts=(box,),
        package=str(package.root.resolve()),
    )


def _mean_colour(package: AssetPackage) -> tuple[float, float, float]:
    """The splats' mean base colour (0..1), used for the collision proxy's rgba."""
    sh = package_splats(package.root).sh  # cached: the catalog asks on every discovery
    if not len(sh):
        return (0.5, 0.5, 0.5)
    r, g, b = (float(v) for v in np.clip(0.5 + SH_C0 * sh[:, 0].mean(axis=0), 0.0, 1.0))
    return (r, g, b)


def _packaged_categories() -> list[Category]:
    """A category for every asset package found; one whose splats cannot be read stays out."""
    categories = []
    for package in discover_packages("asset"):
        try:
            categories.append(package_category(package))
        except AssetPackageError:
            continue
    return categories


@lru_cache(maxsize=8)
def _catalog_for(discovery_key: tuple[str, ...]) -> dict[str, Category]:
    merged = dict(_builtin())
    for cat in _packaged_categories():
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


# Tags of the kit that layouts are built of: work-zone things, posts and markers (cones,
# barriers, rubble, bollards). A ring encloses these where they stand at its centre, and a line
# of them can close a road.
LAYOUT_KIT_TAGS = frozenset({"maintenance", "block", "marker"})


def is_layout_kit(name: str) -> bool:
    """Whether the category `name` is layout kit (see LAYOUT_KIT_TAGS)."""
    return bool(LAYOUT_KIT_TAGS & set(category(name).tags))


def placeable_categories() -> list[str]:
    """Categories a Worker may add (everything but the ego vehicle)."""
    return [name for name, c in catalog().items() if "ego" not in c.tags]


@cache
def shared_heads() -> dict[str, list[str]]:
    """Words that several placeable kinds' names end in and no kind is called by alone ("sign":
    the stop, construction, pedestrian and parking signs), with those kinds."""
    full = {w.lower() for c in catalog().values() for w in c.words}
    heads: dict[str, list[str]] = {}
    for name in placeable_categories():
        for word in catalog()[name].words:
            head = word.lower().split()[-1]
            if head not in full and name not in heads.setdefault(head, []):
                heads[head].append(name)
    return {h: kinds for h, kinds in heads.items() if len(kinds) > 1}


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
