from __future__ import annotations

from pathlib import Path

import pytest
from drivetwin.worlds.opendrive import samples
from drivetwin.worlds.opendrive.package import scene_from_file
from drivetwin.worlds.scene import Scene

DATA = Path(__file__).parents[1] / "data"


@pytest.fixture(scope="session")
def maps(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """The generated OpenDRIVE maps, written once per test session."""
    folder = tmp_path_factory.mktemp("maps")
    return {"tour": samples.geometry_tour(folder / "tour.xodr"), "crossroads": samples.crossroads(folder / "crossroads.xodr")}


@pytest.fixture(scope="session")
def town_file() -> Path:
    return DATA / "town.osm"


@pytest.fixture
def town(town_file: Path) -> Scene:
    return scene_from_file(town_file)


@pytest.fixture
def crossroads_world(maps: dict[str, Path]) -> Scene:
    return scene_from_file(maps["crossroads"])


@pytest.fixture
def user_data(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """An empty user data folder for imported worlds."""
    monkeypatch.setenv("DRIVETWIN_DATA", str(tmp_path / "data"))
    return tmp_path / "data"
