"""Every source folder installs under `drivetwin`, typed, with its data; the layering holds."""

from __future__ import annotations

import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
ROOTS = {"orchestrator": "drivetwin.orchestrator", "tools": "drivetwin.tools", "worlds": "drivetwin.worlds",
         "prompts": "drivetwin.prompts", "evals": "drivetwin.evals"}


def _setuptools() -> dict[str, object]:
    config = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))
    tool: dict[str, object] = config["tool"]["setuptools"]
    return tool


def _source_packages() -> set[str]:
    found = set()
    for folder, package in ROOTS.items():
        for init in (REPO / folder).rglob("__init__.py"):
            relative = init.parent.relative_to(REPO / folder).parts
            found.add(".".join((package, *relative)))
    return found


def test_every_source_folder_is_a_listed_package() -> None:
    listed = set(_setuptools()["packages"])  # type: ignore[arg-type]
    missing = sorted(_source_packages() - listed)
    assert not missing, f"add to [tool.setuptools] packages in pyproject.toml: {missing}"


def test_every_folder_of_python_modules_is_a_package() -> None:
    loose = sorted(
        str(folder.relative_to(REPO))
        for root in ROOTS
        for folder in {p.parent for p in (REPO / root).rglob("*.py")}
        if not (folder / "__init__.py").is_file() and "__pycache__" not in folder.parts
    )
    assert not loose, f"folders of modules without __init__.py (they would not be installed): {loose}"


def test_each_top_level_package_ships_its_py_typed_marker() -> None:
    data: dict[str, list[str]] = _setuptools()["package-data"]  # type: ignore[assignment]
    for folder, package in ROOTS.items():
        assert (REPO / folder / "py.typed").is_file(), f"{folder}/py.typed is missing"
        assert "py.typed" in data.get(package, []), f"package-data of {package} must list py.typed"


def test_the_layering_contracts_hold() -> None:
    lint = shutil.which("lint-imports")
    if lint is None:
        pytest.skip("import-linter is not installed (the dev extra installs it)")
    done = subprocess.run([lint, "--config", str(REPO / "pyproject.toml")], capture_output=True, text=True,
                          cwd=REPO, timeout=600)
    assert done.returncode == 0, done.stdout[-2000:]
    assert "0 broken" in done.stdout


def test_the_interpreter_imports_drivetwin_from_one_tree() -> None:
    import drivetwin.orchestrator
    import drivetwin.worlds

    roots = {Path(drivetwin.orchestrator.__file__).resolve().parents[1],
             Path(drivetwin.worlds.__file__).resolve().parents[1]}
    assert len(roots) == 1 and sys.modules["drivetwin.worlds"].__spec__ is not None


# Packages that only the optional extras install (roads, scenarios, serve, enhance, ray, reconstruct, eval).
OPTIONAL = ("viser", "scenariogeneration", "pyxodr", "xmlschema", "lxml", "selenium", "sumo", "open3d",
            "diffusers", "ray", "matplotlib")


def test_the_command_line_and_the_worlds_load_without_the_optional_extras(tmp_path: Path) -> None:
    # The README's first command installs only the render and llm extras.
    script = f"""
import importlib.abc, sys
class Block(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path, target=None):
        if name.split(".")[0] in {OPTIONAL!r}:
            raise ImportError("not installed: " + name)
sys.meta_path.insert(0, Block())
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
result = CliRunner().invoke(main, ["worlds", "list"])
print(result.output)
sys.exit(result.exit_code)
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300,
                          env={**__import__("os").environ, "DRIVETWIN_DATA": str(tmp_path)})
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    assert "campus" in done.stdout
