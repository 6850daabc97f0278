"""Lookups over a Scene's asset list by id and by category, kept beside the list.

A Scene's `assets` is a plain list (pydantic), so a lookup by id was a scan of thousands of
assets. An `AssetTable` is derived from one list object, never a second truth: it is cached
by that list's identity (the cache holds the list, so its id cannot be reused), rebuilt when
the list's length changed in place, and handed on by `WorldEdit.apply` to the list it makes,
patched with the few assets the edit changed (a dict copy in C instead of a rebuild).
"""

from __future__ import annotations

import threading
from collections.abc import Iterable
from operator import attrgetter
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from drivetwin.worlds.scene import AssetInstance

__all__ = ["AssetTable", "asset_table", "keep_table"]

# Lists whose table is kept: the live scene, a dry run's scene and its undo targets, with room
# to spare; an evicted one is rebuilt on its next lookup (about 1 ms at 5,000 assets).
TABLES_KEPT = 16
_ID = attrgetter("id")


class AssetTable:
    """The assets of one list by id and (built on first use) by category (in no set order)."""

    def __init__(self, by_id: dict[str, AssetInstance], by_category: dict[str, list[AssetInstance]] | None = None) -> None:
        self.by_id = by_id
        self._by_category = by_category

    @classmethod
    def of(cls, assets: list[AssetInstance]) -> AssetTable:
        return cls(dict(zip(map(_ID, assets), assets, strict=True)))

    def by_category(self) -> dict[str, list[AssetInstance]]:
        """The assets of each category (treat the lists as read-only: tables share them)."""
        if self._by_category is None:
            grouped: dict[str, list[AssetInstance]] = {}
            for asset in self.by_id.values():
                grouped.setdefault(asset.category, []).append(asset)
            self._by_category = grouped
        return self._by_category

    def count(self, category: str) -> int:
        return len(self.by_category().get(category, ()))

    def patched(self, gone: Iterable[AssetInstance], came: Iterable[AssetInstance]) -> AssetTable:
        """The table of a list that lost `gone` and gained `came` (matched by identity)."""
        gone, came = list(gone), list(came)
        by_id = self.by_id.copy()
        for asset in gone:
            del by_id[asset.id]
        for asset in came:
            by_id[asset.id] = asset
        grouped = None
        if self._by_category is not None:
            grouped = self._by_category.copy()  # only the touched categories' lists are copied
            touched = {a.category for a in (*gone, *came)}
            leaving = {id(a) for a in gone}
            for name in touched:
                kept = [a for a in grouped.get(name, ()) if id(a) not in leaving]
                kept.extend(a for a in came if a.category == name)
                grouped[name] = kept
        return AssetTable(by_id, grouped)


_lock = threading.Lock()
# id(list) -> (the list, its length when the table was made, the table); oldest first.
_tables: dict[int, tuple[list[AssetInstance], int, AssetTable]] = {}


def asset_table(assets: list[AssetInstance]) -> AssetTable:
    """The table of `assets` (this very list object)."""
    with _lock:
        kept = _tables.pop(id(assets), None)
        if kept is None or kept[0] is not assets or kept[1] != len(assets):
            kept = (assets, len(assets), AssetTable.of(assets))
        _remember(kept)
        return kept[2]


def keep_table(assets: list[AssetInstance], table: AssetTable) -> None:
    """Remember `table` as the table of `assets` (a list made from another with its table patched)."""
    with _lock:
        _tables.pop(id(assets), None)
        _remember((assets, len(assets), table))


def _remember(entry: tuple[list[AssetInstance], int, AssetTable]) -> None:
    _tables[id(entry[0])] = entry  # newest last
    while len(_tables) > TABLES_KEPT:
        del _tables[next(iter(_tables))]
