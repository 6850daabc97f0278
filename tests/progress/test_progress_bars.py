"""Progress bars (rich) are drawn for a person at a terminal, never into scripts, CI logs or pipes."""

from __future__ import annotations

import io

import pytest
from drivetwin.worlds.progress import on_terminal, progress_bar


class Terminal(io.StringIO):
    """A stream that says it is a terminal, as stderr does in an interactive shell."""

    def isatty(self) -> bool:
        return True


def test_a_bar_on_a_terminal_shows_the_count_unit_and_note(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("CI", raising=False)
    screen = Terminal()
    with progress_bar("eval", 4, "trials", initial=1, stream=screen) as bar:
        for _ in range(3):
            bar.advance(note="pass 2")
    drawn = screen.getvalue()
    assert "eval" in drawn and "4/4" in drawn and "trials" in drawn and "pass 2" in drawn


def test_nothing_is_drawn_into_a_pipe(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("CI", raising=False)
    pipe = io.StringIO()
    with progress_bar("eval", 4, "trials", stream=pipe) as bar:
        bar.advance(4)
    assert pipe.getvalue() == "" and not on_terminal(pipe)


def test_nothing_is_drawn_under_ci_even_on_a_terminal(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("CI", "true")
    screen = Terminal()
    with progress_bar("enhance", 2, "frames", stream=screen) as bar:
        bar.advance(2)
    assert screen.getvalue() == ""


def test_a_bar_turned_off_draws_nothing_on_a_terminal(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("CI", raising=False)
    screen = Terminal()
    with progress_bar("eval", 2, enabled=False, stream=screen) as bar:
        bar.advance(2)
    assert screen.getvalue() == ""


def test_an_eval_run_draws_its_bar_on_a_terminal_only(monkeypatch: pytest.MonkeyPatch, tmp_path) -> None:
    from drivetwin.evals import run_suite

    monkeypatch.delenv("CI", raising=False)
    screen, pipe = Terminal(), io.StringIO()
    run_suite("smoke", "reference", out_path=tmp_path / "a.jsonl", stream=screen, only=("direct",))
    run_suite("smoke", "reference", out_path=tmp_path / "b.jsonl", stream=pipe, only=("direct",))
    assert "trials" in screen.getvalue() and "pass" in screen.getvalue()
    assert pipe.getvalue() == ""


def test_eval_run_quiet_draws_no_bar_even_on_a_terminal(monkeypatch: pytest.MonkeyPatch, tmp_path) -> None:
    from click.testing import CliRunner
    from drivetwin.orchestrator.cli import main
    from drivetwin.worlds import progress

    monkeypatch.setattr(progress, "on_terminal", lambda stream=None: True)  # as if stderr were a terminal
    runner = CliRunner()
    command = ["eval", "run", "--suite", "smoke", "--planner", "reference", "--only", "direct"]
    drawn = runner.invoke(main, [*command, "--out", str(tmp_path / "a.jsonl")])
    quiet = runner.invoke(main, [*command, "--out", str(tmp_path / "b.jsonl"), "--quiet"])
    assert drawn.exit_code == 0 and quiet.exit_code == 0, drawn.output + quiet.output
    assert "trials" in drawn.stderr and "passed" in drawn.stdout
    assert "trials" not in quiet.stderr and "passed" in quiet.stdout


def test_the_edit_benchmark_draws_its_bar_on_a_terminal(monkeypatch: pytest.MonkeyPatch) -> None:
    from drivetwin.orchestrator import bench_edits

    monkeypatch.delenv("CI", raising=False)
    screen = Terminal()
    monkeypatch.setattr("sys.stderr", screen)
    row = bench_edits.measure(0, 1)
    assert row["assets"] > 0 and "edits, 0 assets" in screen.getvalue() and "3/3" in screen.getvalue()
