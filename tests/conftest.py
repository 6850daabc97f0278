"""Fixtures every test folder shares: the campus world and the built-in Workers."""

from __future__ import annotations

import pytest
from drivetwin.evals.trial import fresh_world
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.scene import Scene


@pytest.fixture(scope="session")
def registry() -> ToolRegistry:
    """The built-in Workers without installed plugins (a plugin must not change what tests see)."""
    return ToolRegistry.default(plugins=False)


@pytest.fixture
def campus() -> Scene:
    """A fresh copy of the shipped campus world for each test (the file is parsed once)."""
    return fresh_world("campus")
