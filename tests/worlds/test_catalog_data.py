"""The built-in catalog is a data file validated by its model."""

from __future__ import annotations

import json

import pytest
from drivetwin.worlds.catalog import CATALOG_FILE, CatalogFile, catalog
from pydantic import ValidationError


def test_every_category_in_the_file_is_in_the_catalog_with_its_parts() -> None:
    raw = json.loads(CATALOG_FILE.read_text(encoding="utf-8"))
    names = [entry["name"] for entry in raw["categories"]]
    assert len(names) == 23 and set(names) <= set(catalog())
    bus = catalog()["bus"]
    entry = next(e for e in raw["categories"] if e["name"] == "bus")
    assert bus.mass == entry["mass"] and len(bus.parts) == len(entry["parts"])


def test_parts_stay_inside_the_declared_size_of_their_category() -> None:
    for cat in catalog().values():
        if cat.package is not None:
            continue
        for part in cat.parts:
            reach_z = part.pos[2] + (part.size[0] if part.shape == "sphere" else
                                     part.size[1] if part.shape == "cylinder" and part.axis == "z" else
                                     part.size[0] if part.shape == "cylinder" else part.size[2])
            assert reach_z <= cat.height * 1.05 + 1e-6, (cat.name, part)


def test_a_repeated_category_name_is_refused_naming_it() -> None:
    raw = json.loads(CATALOG_FILE.read_text(encoding="utf-8"))
    raw["categories"].append(raw["categories"][1])
    with pytest.raises(ValidationError, match="repeated: passenger_car"):
        CatalogFile.model_validate(raw)


def test_an_unknown_field_in_a_category_is_refused() -> None:
    raw = json.loads(CATALOG_FILE.read_text(encoding="utf-8"))
    raw["categories"][0]["colour"] = "red"
    with pytest.raises(ValidationError, match="colour"):
        CatalogFile.model_validate(raw)
