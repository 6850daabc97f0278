"""Opening a live session: what `chat` and `serve` both run before their first prompt.

Settings from flags, the planner (or the rule planner when it cannot start), the Worker
registry, the session with its journal (fresh, resumed, or the crashed one offered back),
and the LiveWorld that simulates and renders it. Every problem is a one-line ClickException.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import click
from drivetwin.orchestrator.chat_journal import open_chat_session
from drivetwin.orchestrator.config import ConfigError, Settings, load_settings
from drivetwin.orchestrator.live import LiveWorld
from drivetwin.orchestrator.planning import Planner
from drivetwin.orchestrator.planning.registry import UnknownPlannerError, make_planner
from drivetwin.orchestrator.session import Session
from drivetwin.tools.registry import ToolRegistry

__all__ = ["LiveSession", "command_settings", "open_live_session", "planner_or_rules", "settings_planner"]


def command_settings(planner: str | None = None, backend: str | None = None, model: str | None = None) -> Settings:
    """This command's Settings: its flags over environment, config file and defaults."""
    try:
        return load_settings(planner=planner, backend=backend, model=model)
    except ConfigError as exc:
        raise click.ClickException(str(exc)) from exc


def settings_planner(settings: Settings) -> Planner:
    """The planner the settings name; a usage error for an unknown name."""
    name = settings.planner
    try:
        return make_planner(name, **settings.planner_options())
    except UnknownPlannerError as exc:
        raise click.UsageError(str(exc)) from exc
    except Exception as exc:  # a backend that cannot start: say so in one line
        raise click.ClickException(f"planner {name!r} cannot start: {exc}") from exc


def planner_or_rules(settings: Settings) -> Planner:
    """The asked planner, or the rule planner with a one-line note when it cannot start."""
    try:
        return settings_planner(settings)
    except click.ClickException as exc:
        if settings.planner == "rules":
            raise
        click.echo(f"note: {exc.message}; using the rule-based planner", err=True)
        return make_planner("rules")


@dataclass
class LiveSession:
    """A session and the live world (physics thread, renderer) that shows it."""

    session: Session
    live: LiveWorld


def open_live_session(world: str, settings: Settings, *, journal: Path | None, resume: bool, can_ask: bool,
                      isolate_plugins: bool = False, simulate: bool = True, background: bool = True,
                      enhance_model: str | None = None) -> LiveSession:
    """The session a command runs on, with its simulation started (in the background when asked)."""
    planner = planner_or_rules(settings)
    registry = ToolRegistry.default(isolate=isolate_plugins)
    for problem in registry.problems:
        click.echo(f"warning: plugin {problem.entry_point} skipped: {problem.error}", err=True)
    session = open_chat_session(world, planner, registry, settings.state_dir, journal, resume, can_ask=can_ask)
    if planner.name in ("hybrid", "retrieval"):
        from drivetwin.orchestrator.planning.retrieval import warm_bank

        warm_bank(session.scene)  # the example bank builds while the person types
    try:
        enhance = None
        if enhance_model:
            from drivetwin.worlds.enhance import EnhanceSettings

            enhance = EnhanceSettings(model=enhance_model)
        live = LiveWorld(session, simulate=simulate, background=background, enhance=enhance)
    except ImportError as exc:
        raise click.ClickException(
            f"--enhance needs the enhance extra: pip install 'drivetwin[enhance]' ({exc})") from exc
    except RuntimeError as exc:  # EnhancerError: weights missing or unreadable
        raise click.ClickException(str(exc)) from exc
    return LiveSession(session, live)
