"""A full disk refuses the edit cleanly: the scene is unchanged and the journal has no torn line."""

from __future__ import annotations

import os
import subprocess

import pytest
from drivetwin.orchestrator.journal import Journal
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session, SessionError

# Room for the campus start event (about 40 kB) and a few edits, then the disk is full.
TMPFS_SIZE = "64k"


@pytest.fixture
def small_disk(tmp_path):
    mount = tmp_path / "small"
    mount.mkdir()
    if os.geteuid() != 0:
        pytest.skip("mounting a tmpfs needs root (mount -t tmpfs -o size=64k)")
    done = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={TMPFS_SIZE}", "tmpfs", str(mount)],
                          capture_output=True, text=True)
    if done.returncode != 0:
        pytest.skip(f"this machine does not allow mounting a tmpfs: {done.stderr.strip()}")
    yield mount
    subprocess.run(["umount", "-l", str(mount)], check=False)


def test_a_full_disk_refuses_the_edit_and_leaves_no_torn_line(small_disk, campus, registry):
    path = small_disk / "journal.jsonl"
    session = Session(campus, RulePlanner(), registry, journal_path=path)
    refused = None
    for step in range(200):
        before = session.scene
        report = session.submit("add a traffic cone" if step % 2 else "make it rain" if step % 4 else "make it snow")
        if not report.ok and "disk is full" in (report.error or ""):
            refused = report
            assert session.scene == before
            break
    assert refused is not None, "the 64 kB disk never filled"
    with pytest.raises(SessionError, match=r"disk is full|nothing to undo"):
        for _ in range(200):  # undo refuses rather than half-writes (a small event may still fit)
            session.undo()
    data = path.read_bytes()
    assert data.endswith(b"\n")
    assert Journal(path).replay().scene == session.scene  # everything reported done is in the journal
    session.journal.close()
