"""`drivetwin serve`: the live session in a browser, with the chat beside the 3D world."""

from __future__ import annotations

import signal
import sys
import threading
from pathlib import Path
from types import FrameType

import click
from drivetwin.orchestrator.session_setup import command_settings, open_live_session

__all__ = ["serve_command"]

DEFAULT_PORT = 8080


@click.command("serve")
@click.option("--world", default="campus", show_default=True, help="world name or JSON file")
@click.option("--planner", "planner_name", default=None,
              help="rules, llm, retrieval or hybrid, or a plugin's (default: settings, hybrid)")
@click.option("--backend", default=None, help="LLM backend: embedded, ollama, openai")
@click.option("--model", default=None, help="model name, preset or GGUF path")
@click.option("--host", default="127.0.0.1", show_default=True,
              help="address to listen on; only this machine can connect unless you change it")
@click.option("--port", default=DEFAULT_PORT, show_default=True, type=click.IntRange(0, 65535),
              help="port to listen on (0: any free port)")
@click.option("--update-hz", default=30.0, show_default=True, type=click.FloatRange(1.0, 120.0),
              help="pose updates sent to the browser per second (lower it for a browser without a GPU)")
@click.option("--resume", is_flag=True, help="restore the last session from its journal")
@click.option("--journal", type=click.Path(dir_okay=False, path_type=Path), default=None,
              help="journal file (default: under $DRIVETWIN_STATE)")
@click.option("--no-sim", is_flag=True, help="edit the scene without running physics")
@click.option("--isolate-plugins", is_flag=True, help="run plugin Workers in a separate process")
def serve_command(world: str, planner_name: str | None, backend: str | None, model: str | None, host: str,
                  port: int, update_hz: float, resume: bool, journal: Path | None, no_sim: bool, isolate_plugins: bool) -> None:
    """Watch and edit a live world in your browser: the 3D view with the chat beside it.

    Example: drivetwin serve --world campus   (then open the printed URL)
    """
    try:
        from drivetwin.orchestrator.serve.app import ServeApp
    except ImportError as exc:
        raise click.ClickException(f"drivetwin serve needs the serve extra: pip install 'drivetwin[serve]' ({exc})") from exc
    settings = command_settings(planner_name, backend, model)
    opened = open_live_session(world, settings, journal=journal, resume=resume, can_ask=sys.stdin.isatty(),
                               isolate_plugins=isolate_plugins, simulate=not no_sim, background=True)
    session, live = opened.session, opened.live
    stop = threading.Event()

    def stop_serving(signum: int, frame: FrameType | None) -> None:
        stop.set()

    try:
        try:
            app = ServeApp(session, live, host=host, port=port, frames_dir=settings.state_dir / "serve_frames",
                           update_hz=update_hz)
        except OSError as exc:  # the port is taken, or the host is not this machine's
            raise click.ClickException(f"cannot listen on {host}:{port}: {exc}") from exc
        signal.signal(signal.SIGTERM, stop_serving)
        signal.signal(signal.SIGINT, stop_serving)
        journal_note = f"; journal {session.journal.path}" if session.journal is not None else ""
        click.echo(f"drivetwin serve: {session.scene.name} at {app.url}  (Ctrl-C to stop{journal_note})", err=False)
        sys.stdout.flush()
        try:
            while not stop.wait(0.5):
                pass
        finally:
            app.close()
        session.close()  # a clean end: the journal says so
    finally:
        live.close()
