"""Throwaway plugin packages for the tests: modules and a dist-info with entry_points.txt on sys.path."""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path


def install(folder: Path, dist: str, modules: dict[str, str], entry_points: dict[str, dict[str, str]]) -> None:
    """Write `modules` (name -> source) and a dist-info declaring `entry_points` (group -> name -> target).

    The caller puts `folder` on sys.path (monkeypatch.syspath_prepend), as an installed package would be.
    """
    for module, source in modules.items():
        (folder / f"{module}.py").write_text(textwrap.dedent(source), encoding="utf-8")
        sys.modules.pop(module, None)
    info = folder / f"{dist.replace('-', '_')}-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {dist}\nVersion: 0.1\n", encoding="utf-8")
    sections = [
        f"[{group}]\n" + "".join(f"{name} = {target}\n" for name, target in names.items())
        for group, names in entry_points.items()
    ]
    (info / "entry_points.txt").write_text("\n".join(sections), encoding="utf-8")
