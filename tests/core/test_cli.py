"""The `drivetwin` command line, driven through click's runner in-process."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner
from drivetwin.orchestrator.cli import main


def chat(tmp_path: Path, lines: list[str], *extra: str) -> tuple[int, str]:
    script = tmp_path / "script.txt"
    script.write_text("\n".join(lines) + "\n")
    result = CliRunner().invoke(main, ["chat", "--planner", "rules", "--no-sim", "--script", str(script),
                                       "--journal", str(tmp_path / "journal.jsonl"), *extra])
    return result.exit_code, result.output


def test_a_scripted_chat_applies_each_prompt_and_exits_zero(tmp_path: Path) -> None:
    code, output = chat(tmp_path, ["make it rain", "add traffic cones to mark the maintenance"], "--fail-fast")
    assert code == 0, output
    assert "weather clear -> rain" in output
    assert "+ traffic_cone_1" in output


def test_explain_shows_each_level_with_its_input_output_and_time(tmp_path: Path) -> None:
    code, output = chat(tmp_path, ["make it rain"], "--explain")
    assert code == 0, output
    assert "planner rules, confidence" in output
    assert "[rules]" in output and " ms" in output
    assert "in : make it rain" in output
    assert "out: set_weather(" in output


def test_fail_fast_stops_at_a_refused_prompt_with_a_non_zero_status(tmp_path: Path) -> None:
    code, output = chat(tmp_path, ["add 500 traffic cones inside the library", "make it rain"], "--fail-fast")
    assert code == 1
    assert "error:" in output
    assert "weather clear -> rain" not in output


def test_an_unknown_world_is_one_clear_line_naming_the_known_ones(tmp_path: Path) -> None:
    code, output = chat(tmp_path, ["make it rain"], "--world", "atlantis")
    assert code == 1
    assert "unknown world 'atlantis'; known worlds: campus" in output
    assert "Traceback" not in output


def test_backends_list_marks_the_chosen_model() -> None:
    result = CliRunner().invoke(main, ["backends", "list", "--model", "gemma3-270m"])
    assert result.exit_code == 0, result.output
    marked = [line for line in result.output.splitlines() if "*" in line]
    assert len(marked) == 1 and "gemma3-270m" in marked[0]


def test_tools_list_json_names_every_builtin_worker_with_its_schema() -> None:
    result = CliRunner().invoke(main, ["tools", "list", "--json"])
    assert result.exit_code == 0, result.output
    tools = json.loads(result.output)
    names = {tool["name"] for tool in tools}
    assert {"add_asset", "remove_assets", "move_asset", "arrange_assets", "set_weather"} <= names
    assert all("properties" in tool["parameters"] for tool in tools)
