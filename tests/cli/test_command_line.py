"""The command line reads as one design: sub-commands with their own help, JSON lists, one error style."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner
from drivetwin.orchestrator.cli import BENCHMARKS, main


def test_each_benchmark_sub_command_shows_its_own_options() -> None:
    for name in ("edits", "physics", "planners"):
        result = CliRunner().invoke(main, ["bench", name, "--help"])
        assert result.exit_code == 0, result.output
        assert f"usage: drivetwin bench {name}" in result.output
        assert "--out" in result.output
        assert "Commands:" not in result.output  # not the group's help


def test_the_bench_group_lists_every_benchmark_with_a_summary() -> None:
    result = CliRunner().invoke(main, ["bench", "--help"])
    assert result.exit_code == 0
    for name, (_, summary) in BENCHMARKS.items():
        assert name in result.output and summary.split()[0] in result.output


def test_worlds_list_as_json_names_the_campus() -> None:
    result = CliRunner().invoke(main, ["worlds", "list", "--json"])
    assert result.exit_code == 0, result.output
    worlds = {entry["name"]: entry for entry in json.loads(result.output)}
    assert "campus" in worlds and worlds["campus"]["path"].endswith("campus.json")


def test_backends_list_as_json_has_a_row_per_backend(tmp_path: Path) -> None:
    result = CliRunner().invoke(main, ["backends", "list", "--json"],
                                env={"DRIVETWIN_CONFIG": str(tmp_path / "absent.toml")})
    assert result.exit_code == 0, result.output
    rows = json.loads(result.output)
    assert {"embedded", "ollama", "openai"} <= {row["backend"] for row in rows}
    assert all(isinstance(row["usable"], bool) for row in rows)


def test_enhance_without_weights_fails_in_the_common_error_style(tmp_path: Path) -> None:
    frames = tmp_path / "frames"
    frames.mkdir()
    result = CliRunner().invoke(main, ["enhance", str(frames), "--model", str(tmp_path / "no-model")])
    assert result.exit_code == 1
    assert result.output.startswith("Error: ") and "Traceback" not in result.output


def test_render_each_without_the_simulation_is_a_usage_error(tmp_path: Path) -> None:
    script = tmp_path / "s.txt"
    script.write_text("make it rain\n")
    result = CliRunner().invoke(main, ["chat", "--planner", "rules", "--no-sim", "--render-each", "--out",
                                       str(tmp_path / "out"), "--script", str(script)],
                                env={"DRIVETWIN_STATE": str(tmp_path / "state")})
    assert result.exit_code == 2
    assert "drop --no-sim" in result.output and "Traceback" not in result.output


def test_a_script_with_a_refused_line_exits_one_after_running_the_rest(tmp_path: Path) -> None:
    script = tmp_path / "s.txt"
    script.write_text("add 500 traffic cones inside the library\nmake it rain\n")
    result = CliRunner().invoke(main, ["chat", "--planner", "rules", "--no-sim", "--script", str(script)],
                                env={"DRIVETWIN_STATE": str(tmp_path / "state")})
    assert result.exit_code == 1
    assert "weather clear -> rain" in result.output  # the line after the refused one still ran
    assert "1 line(s) not done" in result.output
