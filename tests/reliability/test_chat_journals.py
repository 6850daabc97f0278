"""`chat` never truncates a journal, writes its own per session, and offers to resume an unclean one."""

from __future__ import annotations

import os

import pytest
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
from drivetwin.orchestrator.journal import Journal
from drivetwin.orchestrator.journal_files import journal_folder, rotate, session_journals
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session


@pytest.fixture
def state(tmp_path, monkeypatch):
    folder = tmp_path / "state"
    monkeypatch.setenv("DRIVETWIN_STATE", str(folder))
    return folder


def _chat(tmp_path, *lines: str, extra: tuple[str, ...] = ()):
    script = tmp_path / "script.txt"
    script.write_text("\n".join(lines) + "\n")
    return CliRunner().invoke(main, ["chat", "--planner", "rules", "--no-sim", "--script", str(script), *extra])


def test_each_chat_writes_its_own_journal_and_ends_it_cleanly(state, tmp_path):
    assert _chat(tmp_path, "make it rain").exit_code == 0
    assert _chat(tmp_path, "make it night").exit_code == 0
    journals = session_journals(journal_folder(state))
    assert len(journals) == 2
    first, second = (Journal(p).replay() for p in journals)
    assert first.scene.environment.weather.kind == "rain" and first.ended_cleanly
    assert second.scene.environment.is_night and second.ended_cleanly


def test_a_script_chat_notes_an_unclean_session_in_one_line_instead_of_asking(state, tmp_path, campus, registry):
    crashed = journal_folder(state) / "session-20250101-000000-1.jsonl"
    session = Session(campus, RulePlanner(), registry, journal_path=crashed)
    assert session.submit("make it snow").ok
    session.journal.close()  # the process "died": no end event
    result = _chat(tmp_path, "make it rain")
    notes = [line for line in result.output.splitlines() if line.startswith("note:")]
    assert len(notes) == 1 and "did not end cleanly" in notes[0] and str(crashed) in notes[0]
    assert Journal(crashed).replay().scene.environment.weather.kind == "snow"  # untouched


def test_resume_continues_the_newest_journal(state, tmp_path):
    assert _chat(tmp_path, "make it rain").exit_code == 0
    result = _chat(tmp_path, "make it night", extra=("--resume",))
    assert result.exit_code == 0, result.output
    (only,) = session_journals(journal_folder(state))
    restored = Journal(only).replay()
    assert restored.scene.environment.weather.kind == "rain" and restored.scene.environment.is_night


def test_an_explicit_journal_that_exists_is_kept_not_truncated(state, tmp_path):
    journal = tmp_path / "mine.jsonl"
    assert _chat(tmp_path, "make it rain", extra=("--journal", str(journal))).exit_code == 0
    kept = journal.read_bytes()
    result = _chat(tmp_path, "make it night", extra=("--journal", str(journal)))
    assert result.exit_code == 0 and "is kept as" in result.output
    assert (tmp_path / "mine.1.jsonl").read_bytes() == kept


def test_rotation_keeps_the_newest_journals_and_any_in_use(tmp_path, campus, registry):
    folder = tmp_path / "journals"
    folder.mkdir()
    for n in range(5):
        (folder / f"session-2025010{n}-000000-1.jsonl").write_text("{}\n")
    live = Session(campus, RulePlanner(), registry, journal_path=folder / "session-20240101-000000-9.jsonl")
    os.utime(live.journal.path, (0, 0))  # the oldest of all, yet a session still writes it
    deleted = rotate(folder, keep=2)
    remaining = {p.name for p in session_journals(folder)}
    assert len(deleted) == 3 and live.journal.path.name in remaining and len(remaining) == 3
    live.close()


def test_a_person_at_a_terminal_is_asked_and_can_resume_the_unclean_session(state, campus, registry, monkeypatch):
    import io

    from drivetwin.orchestrator.chat_journal import open_chat_session

    crashed = journal_folder(state) / "session-20250101-000000-1.jsonl"
    session = Session(campus, RulePlanner(), registry, journal_path=crashed)
    assert session.submit("make it snow").ok
    session.journal.close()  # no end event
    monkeypatch.setattr("sys.stdin", io.StringIO("y\n"))
    resumed = open_chat_session("campus", RulePlanner(), registry, state, None, False, can_ask=True)
    assert resumed.journal.path == crashed and resumed.scene.environment.weather.kind == "snow"
    resumed.close()
