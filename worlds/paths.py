"""Where drivetwin keeps the user's files: cache, data, state and config folders.

The platform's folders come from `platformdirs` (XDG on Linux: ~/.cache/drivetwin,
~/.local/share/drivetwin, ~/.local/state/drivetwin, ~/.config/drivetwin); an environment
variable names another folder for each. Nothing here is ever inside the repository.
These are read when asked, never at import time, so a changed environment is honoured.
"""

from __future__ import annotations

import os
from pathlib import Path

import platformdirs

APP = "drivetwin"
ENV_CACHE = "DRIVETWIN_CACHE"
ENV_DATA = "DRIVETWIN_DATA"
ENV_STATE = "DRIVETWIN_STATE"
ENV_CONFIG = "DRIVETWIN_CONFIG"


def _folder(env: str, default: Path) -> Path:
    configured = os.environ.get(env)
    return Path(configured).expanduser() if configured else default


def cache_dir() -> Path:
    """Files built once and safe to delete (assembled models, example banks, embeddings)."""
    return _folder(ENV_CACHE, platformdirs.user_cache_path(APP))


def data_dir() -> Path:
    """Files the user made and keeps (imported worlds, asset packages)."""
    return _folder(ENV_DATA, platformdirs.user_data_path(APP))


def state_dir() -> Path:
    """Session state: journals, REPL history, backend logs."""
    return _folder(ENV_STATE, platformdirs.user_state_path(APP))


def config_file() -> Path:
    """The TOML config file (it need not exist)."""
    configured = os.environ.get(ENV_CONFIG)
    if configured:
        return Path(configured).expanduser()
    return platformdirs.user_config_path(APP) / "config.toml"


# An imported road map becomes a folder NAME/ holding this file (drivetwin.worlds.opendrive.package).
IMPORTED_WORLD_FILE = "world.json"


def imported_worlds_dir() -> Path:
    """Where `drivetwin worlds import` keeps the worlds it builds."""
    return data_dir() / "worlds"
