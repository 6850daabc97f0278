"""The journal survives ordinary events: reloads, torn tails, duplicates, bad lines, two writers."""

from __future__ import annotations

import json
import math
import subprocess
import sys
import textwrap

import pytest
from drivetwin.orchestrator.journal import Journal, JournalError, JournalLockedError
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.worlds.scene import Pose, Scene
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .scripted import ScriptedPlanner, call

yaws = st.floats(min_value=-50.0, max_value=50.0, allow_nan=False) | st.sampled_from(
    [math.pi, -math.pi, 0.0, -0.0, math.tau, math.nextafter(math.pi, 0.0), math.nextafter(-math.pi, 0.0)]
)
spots = st.tuples(st.floats(-50.0, 50.0, allow_nan=False), st.floats(-50.0, 50.0, allow_nan=False), yaws)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.lists(spots, min_size=1, max_size=8))
def test_save_load_save_is_byte_identical_over_random_scenes(campus, placements):
    ego = campus.ego
    assets = [ego.model_copy(update={"id": f"car_{i + 1}", "pose": Pose(x=x, y=y, yaw=yaw)})
              for i, (x, y, yaw) in enumerate(placements)]
    scene = campus.model_copy(update={"assets": assets, "ego": ego.model_copy(update={"pose": Pose(
        x=placements[0][0], y=placements[0][1], yaw=placements[0][2])})})
    once = Scene.model_validate_json(scene.model_dump_json()).model_dump_json()
    twice = Scene.model_validate_json(once).model_dump_json()
    assert once == twice


@given(yaws)
def test_a_canonical_yaw_is_its_own_canonical_form(yaw):
    first = Pose(x=0, y=0, yaw=yaw).yaw
    assert Pose(x=0, y=0, yaw=first).yaw == first and -math.pi < first <= math.pi + 1e-12


def test_turn_resume_edit_resume_never_goes_stale(session, registry):
    path = session.journal.path
    for step in range(12):  # odd angles: each reload used to move the yaw by an ulp now and then
        turn = call("move_asset", asset="ego", turn_deg=round(17.3 * step + 0.1, 1))
        session.planner = ScriptedPlanner(turn)
        assert session.submit(str(turn)).ok  # the prompt names the call, so the plan check agrees
        session.close()
        session = Session.resume(path, RulePlanner(), registry)
    session.undo()
    session.redo()
    session.close()


def test_a_torn_tail_is_cut_before_the_next_append(session):
    assert session.submit("make it rain").ok
    path = session.journal.path
    session.close()
    with path.open("a") as handle:
        handle.write('{"event":"commit","txn":9,"pro')  # a write torn by a full disk or a kill
    resumed = Session.resume(path, RulePlanner(), session.registry)
    assert resumed.submit("make it night").ok
    resumed.close()
    again = Session.resume(path, RulePlanner(), session.registry)
    assert again.scene.environment.is_night and again.scene.environment.weather.kind == "rain"
    again.close()
    assert all(json.loads(line) for line in path.read_text().splitlines())


def test_a_duplicated_undo_line_does_not_undo_an_accepted_change(session):
    assert session.submit("make it rain").ok
    session.accept()
    assert session.submit("make it night").ok
    session.undo()
    session.close()
    path = session.journal.path
    lines = path.read_text().splitlines()
    path.write_text("\n".join([*lines[:-1], lines[-2], lines[-1]]) + "\n")  # the undo line twice
    with pytest.raises(JournalError, match=r"line \d+: undo of change 2, but the newest applied change is 1"):
        Journal(path).replay()


@pytest.mark.parametrize(("line", "says"), [
    ("[]", "JSON list, not an event object"),
    ("42", "JSON int, not an event object"),
    ('{"event":"undo","txn":1}', "undo of change 1, but no change is applied"),
    ('{"event":"commit","txn":"2","prompt":"x","edit":{"ops":[]}}', "bad txn"),
    ('{"event":"accept","txn":true}', "bad txn"),
    ('{"event":"explode"}', "unknown event 'explode'"),
    ('{"event":"turn","turn":{"prompt":3}}', "bad turn"),
    ("{not json", "not valid JSON"),
    ('{"event":"commit","txn":2,"prompt":"x","edit":{"ops":[]},"n":Infinity}', "Infinity"),
    ('[' * 200 + ']' * 200, "nests deeper"),
])
def test_every_malformed_line_is_a_journal_error_naming_the_line(session, line, says):
    session.close()
    path = session.journal.path
    with path.open("a") as handle:
        handle.write(line + "\n")
    with pytest.raises(JournalError, match="line 3") as caught:  # after start and end
        Journal(path).replay()
    assert says in str(caught.value)


def test_a_non_utf8_journal_line_is_a_journal_error_naming_the_line(session):
    session.close()
    with session.journal.path.open("ab") as handle:
        handle.write(b'{"event":"turn","turn":{"prompt":"\xff","status":"failed"}}\n')
    with pytest.raises(JournalError, match="line 3 is not UTF-8"):
        Journal(session.journal.path).replay()


def test_a_second_session_on_a_journal_gets_a_clear_error(session):
    with pytest.raises(JournalLockedError, match="in use by another drivetwin session"):
        Session.resume(session.journal.path, RulePlanner(), session.registry)
    with pytest.raises(JournalLockedError):
        Session(session.scene, RulePlanner(), session.registry, journal_path=session.journal.path)
    assert Journal(session.journal.path).replay().scene == session.scene  # reading needs no lock


def test_two_processes_on_one_journal_the_second_is_refused(session):
    assert session.submit("make it rain").ok
    script = textwrap.dedent(f"""
        from drivetwin.orchestrator.journal import JournalLockedError
        from drivetwin.orchestrator.planning.rules.planner import RulePlanner
        from drivetwin.orchestrator.session import Session
        try:
            Session.resume({str(session.journal.path)!r}, RulePlanner())
        except JournalLockedError as exc:
            print("refused:", exc)
    """)
    before = session.journal.path.read_bytes()
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert proc.stdout.startswith("refused: journal") and session.journal.path.read_bytes() == before


def test_starting_a_session_never_truncates_an_existing_journal(session, campus, registry):
    assert session.submit("make it rain").ok
    session.close()
    kept = session.journal.path.read_bytes()
    fresh = Session(campus, RulePlanner(), registry, journal_path=session.journal.path)
    assert fresh.journal.set_aside is not None and fresh.journal.set_aside.read_bytes() == kept
    fresh.close()


def test_a_clean_close_is_recorded_and_a_crash_is_not(session):
    assert session.submit("make it rain").ok
    assert not Journal(session.journal.path).replay().ended_cleanly
    session.close()
    assert Journal(session.journal.path).replay().ended_cleanly


def test_redo_after_reject_is_a_clear_refusal(session):
    assert session.submit("make it rain").ok
    assert session.submit("make it night").ok
    session.undo()
    session.reject()
    from drivetwin.orchestrator.session import SessionError

    with pytest.raises(SessionError, match="nothing to redo"):
        session.redo()
    session.close()
    assert Journal(session.journal.path).replay().scene == session.scene
