"""`drivetwin journal check|repair`: each corruption class is found, and repair salvages the valid prefix."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
from drivetwin.orchestrator.journal import Journal, JournalLockedError
from drivetwin.orchestrator.journal_repair import check_journal, repair_journal
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session


@pytest.fixture
def written(session):
    """A closed journal of three applied changes (rain, night, fog), the second accepted."""
    for prompt in ("make it rain", "make it night", "make it foggy"):
        assert session.submit(prompt).ok
        if prompt == "make it night":
            session.accept()
    session.close()
    return session.journal.path


def _corrupt(path, kind: str) -> None:
    lines = path.read_text().splitlines(keepends=True)
    last_commit = max(i for i, line in enumerate(lines) if '"event":"commit"' in line)
    if kind == "torn tail":
        lines[-1] = lines[-1][: len(lines[-1]) // 2]
    elif kind == "glued line":  # a torn line with the next append glued on (the old failure)
        lines[last_commit] = lines[last_commit][:40] + lines[last_commit]
    elif kind == "duplicate":
        lines.insert(last_commit + 1, lines[last_commit])
    elif kind == "garbage":
        lines.insert(last_commit, "\x00\x00garbage{]\n")
    elif kind == "wrong types":
        lines.insert(last_commit, '{"event":"undo","txn":"three"}\n')
    path.write_text("".join(lines))


@pytest.mark.parametrize("kind", ["torn tail", "glued line", "duplicate", "garbage", "wrong types"])
def test_each_corruption_class_is_found_and_repaired(written, registry, kind):
    original = written.read_bytes()
    _corrupt(written, kind)
    assert not check_journal(written).healthy
    report = repair_journal(written)
    assert report.backup is not None and report.backup.read_bytes() != original  # the damaged file is kept
    assert check_journal(written).healthy
    resumed = Session.resume(written, RulePlanner(), registry)
    # rain and the accepted night survive every class; only what came after the damage is dropped
    assert resumed.scene.environment.weather.kind in ("rain", "fog") and resumed.scene.environment.is_night
    resumed.close()


def test_repair_leaves_a_healthy_journal_alone(written):
    before = written.read_bytes()
    report = repair_journal(written)
    assert report.healthy and report.backup is None and written.read_bytes() == before


def test_repair_refuses_a_journal_a_session_is_writing(session):
    with pytest.raises(JournalLockedError):
        repair_journal(session.journal.path)


def test_the_cli_checks_and_repairs_and_says_what_it_dropped(written):
    _corrupt(written, "duplicate")
    runner = CliRunner()
    checked = runner.invoke(main, ["journal", "check", str(written)])
    assert checked.exit_code == 1 and "first bad line" in checked.output and "reuses an id" in checked.output
    repaired = runner.invoke(main, ["journal", "repair", str(written)])
    assert repaired.exit_code == 0 and "dropped" in repaired.output and ".bak" in repaired.output
    assert runner.invoke(main, ["journal", "check", str(written)]).exit_code == 0
    assert Journal(written).replay().history.done


def test_journal_check_as_json_says_what_it_found_with_the_same_exit_code(written):
    runner = CliRunner()
    healthy = runner.invoke(main, ["journal", "check", str(written), "--json"])
    assert healthy.exit_code == 0, healthy.output
    found = json.loads(healthy.output)
    assert found["healthy"] and found["problem"] is None and found["kept"] == found["lines"] > 0
    assert found["changes"] == 3 and found["path"] == str(written)
    _corrupt(written, "duplicate")
    damaged = runner.invoke(main, ["journal", "check", str(written), "--json"])
    assert damaged.exit_code == 1
    broken = json.loads(damaged.output)
    assert not broken["healthy"] and "reuses an id" in broken["problem"] and broken["kept"] < broken["lines"]
