"""The plugin API: what `drivetwin.tools` exports is enough for a Worker, and the example uses only that."""

from __future__ import annotations

import ast
import tomllib
from pathlib import Path

import drivetwin.tools as api
from drivetwin.tools.plugins import GROUPS

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "drivetwin-speedbump" / "drivetwin_speedbump"


def _drivetwin_imports(source: Path) -> list[tuple[str, str]]:
    tree = ast.parse(source.read_text(encoding="utf-8"))
    found: list[tuple[str, str]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("drivetwin"):
            found += [(node.module or "", alias.name) for alias in node.names]
        elif isinstance(node, ast.Import):
            found += [(alias.name, "") for alias in node.names if alias.name.startswith("drivetwin")]
    return found


def test_every_public_name_of_the_plugin_api_imports() -> None:
    missing = [name for name in api.__all__ if not hasattr(api, name)]
    assert not missing and len(set(api.__all__)) == len(api.__all__)


def test_the_example_plugin_imports_only_the_public_api() -> None:
    imports = [pair for source in EXAMPLE.rglob("*.py") for pair in _drivetwin_imports(source)]
    assert imports, "the example imports nothing from drivetwin: the check would be empty"
    assert all(module == "drivetwin.tools" for module, _ in imports), imports
    assert all(name in api.__all__ for _, name in imports)


def test_every_plugin_group_is_declared_in_pyproject() -> None:
    declared = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["entry-points"]
    assert set(GROUPS) <= set(declared)
