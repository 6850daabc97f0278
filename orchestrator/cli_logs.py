"""`drivetwin logs`: what the models were asked and answered, turn by turn (like `llm logs`).

    drivetwin logs list                  sessions and their turns, with planner and model
    drivetwin logs show SESSION[:TURN]   a turn's prompt -> requirements -> calls, and every
                                         backend request and answer behind it
    drivetwin logs replay SESSION:TURN --planner rules
                                         plan the logged prompt again; same calls or not
    drivetwin logs edits [--journal F]   the planner, model and prompt behind every change a
                                         journal holds, accepted or not

A SESSION may be written `last` (the newest session).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import click
from drivetwin.orchestrator import logs
from drivetwin.orchestrator.session_setup import command_settings
from drivetwin.tools.base import ToolCall

# How much of a message or an answer `show` prints unless --full: enough to recognise it.
QUOTE_CHARS = 300


@click.group("logs")
def logs_group() -> None:
    """What the models were asked and answered: sessions, turns, requests and answers."""


def _folder() -> Path:
    return logs.log_folder(command_settings().state_dir)


def _session_name(folder: Path, session: str) -> str:
    if session == "last":
        files = logs.session_files(folder)
        if not files:
            raise click.ClickException(f"no logged sessions in {folder}; drivetwin chat writes them")
        return files[-1].stem
    if not (folder / f"{session}.jsonl").exists():
        known = ", ".join(p.stem for p in logs.session_files(folder)[-5:]) or "none"
        raise click.ClickException(f"no logged session {session!r} in {folder}; the newest: {known}")
    return session


def _split(folder: Path, ident: str) -> tuple[str, int | None]:
    session, _, turn = ident.partition(":")
    if turn and not turn.isdigit():
        raise click.BadParameter(f"{ident!r}: a turn is SESSION:NUMBER, e.g. last:3", param_hint="ID")
    return _session_name(folder, session), int(turn) if turn else None


def _turns(lines: list[dict[str, Any]]) -> list[dict[str, Any]]:
    return [line for line in lines if line["kind"] == "turn"]


def _summary(turn: dict[str, Any]) -> str:
    outcome = "ok" if turn.get("ok") else "failed"
    prompt = str(turn.get("prompt", ""))
    return (f"{turn['session']}:{turn['turn']}  {turn.get('planner') or '-'}  {turn.get('model') or '-'}  "
            f"{outcome}  {prompt[:60]!r}")


@logs_group.command("list")
@click.option("--last", "last_n", default=5, show_default=True, type=click.IntRange(1, None),
              help="how many of the newest sessions to show")
@click.option("--json", "as_json", is_flag=True, help="print sessions and turns as JSON")
def logs_list(last_n: int, as_json: bool) -> None:
    """List the newest sessions and their turns: id, planner, model, outcome and prompt.

    Example: drivetwin logs list --last 2
    """
    folder = _folder()
    listing = []
    for path in logs.session_files(folder)[-last_n:] if folder.exists() else []:
        lines = logs.read_session(folder, path.stem)
        header = next((line for line in lines if line["kind"] == "session"), {})
        listing.append({
            "session": path.stem, "command": header.get("command"), "world": header.get("world"),
            "exchanges": sum(line["kind"] == "exchange" for line in lines),
            "turns": [{k: t.get(k) for k in ("turn", "prompt", "planner", "model", "prompt_version", "ok", "txn")}
                      for t in _turns(lines)],
        })
    if as_json:
        click.echo(json.dumps(listing, indent=2))
        return
    if not listing:
        click.echo(f"no logged sessions in {folder}")
    for session in listing:
        click.echo(f"{session['session']}  {session['command']}  world {session['world'] or '-'}  "
                   f"{len(session['turns'])} turn(s), {session['exchanges']} backend call(s)")
        for turn in session["turns"]:
            click.echo("  " + _summary({**turn, "session": session["session"]}))


def _quote(text: str, full: bool) -> str:
    return text if full or len(text) <= QUOTE_CHARS else text[:QUOTE_CHARS] + f"… ({len(text)} chars)"


def _show_turn(turn: dict[str, Any], exchanges: dict[str, dict[str, Any]], full: bool) -> None:
    click.echo(_summary(turn))
    click.echo(f"  prompt: {turn.get('prompt')}")
    click.echo(f"  planner: {turn.get('planner')}  model: {turn.get('model') or '-'}  "
               f"prompt version: {turn.get('prompt_version') or '-'}  tokens: {turn.get('tokens', 0)}")
    for step in turn.get("trace") or []:
        click.echo(f"  [{step.get('level')}] {_quote(str(step.get('input', '')), full)}")
        click.echo(f"    -> {_quote(str(step.get('output', '')), full)}")
    click.echo("  calls: " + ("; ".join(f"{c['tool']}({json.dumps(c.get('args', {}))})"
                                       for c in turn.get("calls") or []) or "none"))
    if turn.get("error"):
        click.echo(f"  error: {turn['error']}")
    for ident in turn.get("exchanges") or []:
        exchange = exchanges.get(ident)
        if exchange is None:
            continue
        answer = exchange.get("answer") or {}
        click.echo(f"  request {ident}: {exchange['backend']}/{exchange['model']}  "
                   f"{exchange['latency_s']:.2f} s  attempts {exchange.get('attempts')}")
        for message in exchange["request"]["messages"]:
            click.echo(f"    {message['role']}: {_quote(message['content'], full)}")
        if exchange.get("error"):
            click.echo(f"    error: {exchange['error']}")
        else:
            click.echo(f"    answer ({answer.get('prompt_tokens')}+{answer.get('completion_tokens')} tokens): "
                       f"{_quote(str(answer.get('text', '')), full)}")


@logs_group.command("show")
@click.argument("ident", metavar="ID")
@click.option("--full", is_flag=True, help="print whole messages and answers")
def logs_show(ident: str, full: bool) -> None:
    """Show a session's turns (or one turn): prompt -> requirements -> calls, with each request and answer.

    Example: drivetwin logs show last:2
    """
    folder = _folder()
    session, number = _split(folder, ident)
    lines = logs.read_session(folder, session)
    exchanges = {line["id"]: line for line in lines if line["kind"] == "exchange"}
    turns = [t for t in _turns(lines) if number is None or t["turn"] == number]
    if number is not None and not turns:
        raise click.ClickException(f"session {session} has no turn {number}; its turns: "
                                   + (", ".join(str(t["turn"]) for t in _turns(lines)) or "none"))
    for turn in turns:
        _show_turn(turn, exchanges, full)


def _logged_calls(turn: dict[str, Any]) -> list[ToolCall]:
    return [ToolCall.model_validate(call) for call in turn.get("calls") or []]


@logs_group.command("replay")
@click.argument("ident", metavar="SESSION:TURN")
@click.option("--planner", "planner_name", default=None, help="the planner to ask (default: the logged one)")
@click.option("--backend", default=None, help="LLM backend for the planner (default: settings)")
@click.option("--model", default=None, help="model for the planner (default: settings)")
def logs_replay(ident: str, planner_name: str | None, backend: str | None, model: str | None) -> None:
    """Plan a logged prompt again and say whether the calls are the same (exit 1 if not).

    The world is the session's, with the calls of the session's earlier applied turns
    applied again (undo and reject are not followed).

    Example: drivetwin logs replay last:3 --planner rules
    """
    from drivetwin.orchestrator.planning import PlanContext, PlanningError
    from drivetwin.orchestrator.session_setup import settings_planner
    from drivetwin.orchestrator.transaction import TransactionError, execute
    from drivetwin.tools.registry import ToolRegistry
    from drivetwin.worlds.defaults import UnknownWorldError, load_world

    folder = _folder()
    session, number = _split(folder, ident)
    lines = logs.read_session(folder, session)
    turn = next((t for t in _turns(lines) if t["turn"] == number), None)
    if turn is None:
        raise click.ClickException(f"{ident}: name a logged turn as SESSION:NUMBER (see drivetwin logs list)")
    header = next((line for line in lines if line["kind"] == "session"), {})
    registry = ToolRegistry.default()
    try:
        scene = load_world(header.get("world") or "campus")
        for earlier in _turns(lines):
            if earlier["turn"] < turn["turn"] and earlier.get("txn"):
                scene = execute(registry, scene, _logged_calls(earlier)).after
    except (UnknownWorldError, TransactionError) as exc:
        raise click.ClickException(f"cannot rebuild the world of {session}: {exc}") from exc
    name = planner_name or str(turn.get("planner") or "rules")
    planner = settings_planner(command_settings(name, backend, model))
    refusal: str | None = None
    try:
        calls = planner.plan(str(turn["prompt"]), PlanContext(scene=scene, registry=registry)).calls
    except PlanningError as exc:
        calls, refusal = [], str(exc)
    logged = _logged_calls(turn)
    same = [c.model_dump(mode="json") for c in calls] == [c.model_dump(mode="json") for c in logged]
    click.echo(f"prompt: {turn['prompt']}")
    click.echo(f"logged  ({turn.get('planner')}, {turn.get('model') or 'no model'}): "
               + ("; ".join(str(c) for c in logged) or "no calls"))
    click.echo(f"replayed ({planner.name}): " + ("; ".join(str(c) for c in calls) or refusal or "no calls"))
    click.echo("same calls" if same else "different calls")
    if not same:
        raise SystemExit(1)


@logs_group.command("edits")
@click.option("--journal", "journal_path", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              default=None, help="a session journal (default: the newest)")
@click.option("--json", "as_json", is_flag=True, help="print the changes as JSON")
def logs_edits(journal_path: Path | None, as_json: bool) -> None:
    """The planner, model and prompt behind every change in a session's journal.

    Example: drivetwin logs edits
    """
    from drivetwin.orchestrator.journal import Journal, JournalError
    from drivetwin.orchestrator.journal_files import latest_journal

    path = journal_path or latest_journal(command_settings().state_dir)
    if path is None:
        raise click.ClickException("no session journal yet; drivetwin chat writes one")
    try:
        restored = Journal(path).replay()
    except JournalError as exc:
        raise click.ClickException(str(exc)) from exc
    rows = []
    for entry in restored.history.done:
        facts = entry.facts
        rows.append({
            "txn": entry.txn, "prompt": entry.prompt, "accepted": entry.accepted,
            "planner": facts.planner if facts else None, "model": facts.model if facts else None,
            "prompt_version": facts.prompt_version if facts else None, "log": facts.log if facts else None,
        })
    if as_json:
        click.echo(json.dumps(rows, indent=2))
        return
    click.echo(f"{len(rows)} change(s) in {path}")
    for row in rows:
        state = "accepted" if row["accepted"] else "applied"
        click.echo(f"  #{row['txn']} {state}  {row['planner'] or '?'}  {row['model'] or 'no model'}  "
                   f"prompt version {row['prompt_version'] or '-'}  log {row['log'] or '-'}  {row['prompt']!r}")
