"""`drivetwin journal check|repair FILE`: the journal's own first aid."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import click
from drivetwin.orchestrator.journal import JournalError
from drivetwin.orchestrator.journal_repair import check_journal, repair_journal


@click.group(name="journal")
def journal_group() -> None:
    """Check or repair a session journal."""


@journal_group.command("check")
@click.argument("path", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--json", "as_json", is_flag=True, help="print the check as JSON (same exit code)")
def journal_check(path: Path, as_json: bool) -> None:
    """Say whether a journal replays whole; exit 1 if it does not.

    Example: drivetwin journal check ~/.local/state/drivetwin/journals/session-20250101-120000-42.jsonl
    """
    try:
        report = check_journal(path)
    except JournalError as exc:
        raise click.ClickException(str(exc)) from exc
    if as_json:
        fields = {"path": str(report.path), "healthy": report.healthy, "lines": report.lines, "kept": report.kept,
                  "changes": report.changes, "torn_tail": report.torn_tail, "problem": report.problem}
        click.echo(json.dumps(fields, indent=2))
    else:
        click.echo(report.describe())
    sys.exit(0 if report.healthy else 1)


@journal_group.command("repair")
@click.argument("path", type=click.Path(exists=True, dir_okay=False, path_type=Path))
def journal_repair(path: Path) -> None:
    """Keep the longest whole, valid prefix of a journal (the original stays as FILE.bak).

    Example: drivetwin journal repair session.jsonl && drivetwin chat --resume --journal session.jsonl
    """
    try:
        report = repair_journal(path)
    except JournalError as exc:
        raise click.ClickException(str(exc)) from exc
    click.echo(report.describe())
