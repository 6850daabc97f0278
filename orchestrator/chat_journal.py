"""Which journal a `chat` writes: its own fresh file, a resumed one, or a crashed one it offers to resume."""

from __future__ import annotations

from pathlib import Path

import click
from drivetwin.orchestrator.journal import JournalError
from drivetwin.orchestrator.journal_files import latest_journal, latest_unclean, new_journal_path
from drivetwin.orchestrator.planning import Planner
from drivetwin.orchestrator.session import Session
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.defaults import UnknownWorldError, load_world
from drivetwin.worlds.scene import SceneFileError


def open_chat_session(world: str, planner: Planner, registry: ToolRegistry, state_dir: Path,
                      journal: Path | None, resume: bool, can_ask: bool) -> Session:
    """The session `chat` runs; every problem is a one-line ClickException.

    Without --journal a new session writes a new file under `state_dir` (older sessions'
    journals are kept, rotated). If the newest session did not end cleanly, a person at a
    terminal (`can_ask`) is asked whether to resume it; a script gets a one-line note.
    """
    try:
        if resume:
            path = journal or latest_journal(state_dir)
            if path is None:
                raise click.ClickException(f"no session journal to resume in {state_dir}; start one with drivetwin chat")
            return Session.resume(path, planner, registry)
        if journal is None:
            unclean = latest_unclean(state_dir)
            if unclean is not None:
                if can_ask and click.confirm(f"{unclean.describe()}. Resume it?", default=True):
                    return Session.resume(unclean.path, planner, registry)
                if not can_ask:
                    click.echo(f"note: {unclean.describe()}; resume it with: "
                               f"drivetwin chat --resume --journal {unclean.path}", err=True)
        session = Session(load_world(world), planner, registry, journal or new_journal_path(state_dir))
    except (UnknownWorldError, SceneFileError, JournalError) as exc:
        raise click.ClickException(str(exc)) from exc
    if session.journal is not None and session.journal.set_aside is not None:
        click.echo(f"note: the journal that was at {session.journal.path} is kept as {session.journal.set_aside}",
                   err=True)
    return session
