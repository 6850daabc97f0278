"""What a reconstructed object is made of: bulk densities for the mass fusion writes into a
package's manifest (volume of the convex hull × density)."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from drivetwin.worlds.packages import AssetPackageError

__all__ = ["DENSITY_KG_M3", "density_for"]

# Bulk densities (kg/m³) of what a scanned object is mostly made of. Hollow things (vehicles,
# furniture, bins) use the mass of the object over the volume of its convex hull.
DENSITY_KG_M3: dict[str, float] = {
    "concrete": 2400.0,
    "stone": 2600.0,
    "rock": 2600.0,
    "asphalt": 2300.0,
    "brick": 1900.0,
    "metal": 7850.0,
    "wood": 600.0,
    "plastic": 950.0,
    "rubber": 1100.0,
    "foam": 30.0,
    "soil": 1500.0,
    "vegetation": 400.0,
    "vehicle": 180.0,
    "furniture": 250.0,
    "container": 150.0,
    "default": 1000.0,  # water: a neutral guess when nothing is known
}


def density_for(material: str | None, tags: Iterable[str] = ()) -> tuple[str, float]:
    """(material, density) for a material name or, failing that, the first tag with a density."""
    for key in (material, *tags):
        if key is not None and key.lower() in DENSITY_KG_M3:
            return key.lower(), DENSITY_KG_M3[key.lower()]
    if material is not None:
        known = ", ".join(sorted(DENSITY_KG_M3))
        raise AssetPackageError(Path("."), [f"unknown material {material!r}; known: {known}"])
    return "default", DENSITY_KG_M3["default"]
