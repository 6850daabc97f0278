"""Random sessions with resumes, crashes, torn tails, rejects and redos lose nothing (bounded soak)."""

from __future__ import annotations

import json
import random
import subprocess
import sys

from drivetwin.orchestrator.soak import SoakFigures, run_trial
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**32 - 1))
def test_random_sessions_with_resumes_lose_no_edit_and_corrupt_no_journal(seed, registry, campus, tmp_path_factory):
    figures = SoakFigures()
    run_trial(random.Random(seed), 30, tmp_path_factory.mktemp("soak"), registry, campus, figures)
    assert figures.failures == []
    assert figures.lost_edits == 0 and figures.corrupted_journals == 0
    assert figures.resumes > 0 and figures.edits_applied > 0


def test_the_soak_command_prints_figures_and_writes_json(tmp_path):
    out = tmp_path / "soak.json"
    done = subprocess.run([sys.executable, "-m", "drivetwin.orchestrator.soak", "--trials", "2", "--steps", "20",
                           "--seed", "7", "--out", str(out)], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    figures = json.loads(out.read_text())
    assert figures["trials"] == 2 and figures["lost_edits"] == 0 and figures["corrupted_journals"] == 0
    assert "lost_edits" in done.stdout
