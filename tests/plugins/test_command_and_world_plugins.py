"""Commands (`drivetwin.commands`) and worlds (`drivetwin.worlds`) from plugins, through the one loader."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from drivetwin.orchestrator.cli import main
from drivetwin.worlds.defaults import list_worlds, load_world

from .throwaway import install

HELLO_COMMAND = '''
import click


@click.command()
@click.argument("who")
def hello(who):
    """Greet someone: a test plugin's command."""
    click.echo(f"hello {who}")


NOT_A_COMMAND = 42
'''


@pytest.fixture
def commands(site: Path) -> Path:
    install(site, "drivetwin-test-commands",
            {"hello_command": HELLO_COMMAND, "broken_command": "raise ImportError('no such thing')\n"},
            {"drivetwin.commands": {"hello": "hello_command:hello", "broken": "broken_command:cmd",
                                    "odd": "hello_command:NOT_A_COMMAND", "chat": "hello_command:hello"}})
    return site


def test_a_plugin_command_runs_as_a_drivetwin_sub_command(commands: Path) -> None:
    result = CliRunner().invoke(main, ["hello", "world"])
    assert result.exit_code == 0 and result.stdout == "hello world\n"


def test_the_help_lists_plugin_commands(commands: Path) -> None:
    result = CliRunner().invoke(main, ["--help"])
    assert result.exit_code == 0 and "Greet someone" in result.stdout


def test_a_broken_plugin_command_is_one_warning_line_and_the_rest_work(commands: Path) -> None:
    result = CliRunner().invoke(main, ["hello", "you"])
    assert result.exit_code == 0 and result.stdout == "hello you\n"
    warnings = result.stderr.splitlines()
    broken = [line for line in warnings if "broken = broken_command:cmd" in line]
    assert len(broken) == 1 and "ImportError: no such thing" in broken[0]
    assert any("odd = hello_command:NOT_A_COMMAND" in line and "is not a click command" in line for line in warnings)


def test_a_plugin_command_cannot_replace_a_built_in_one(commands: Path) -> None:
    result = CliRunner().invoke(main, ["--help"])
    assert "drivetwin already has a command 'chat'" in result.stderr
    assert main.get_command(None, "chat").name == "chat"  # type: ignore[arg-type, union-attr]
    assert "Edit a live world" in (main.get_command(None, "chat").help or "")  # type: ignore[arg-type, union-attr]


def test_built_in_commands_do_not_load_command_plugins(commands: Path) -> None:
    result = CliRunner().invoke(main, ["planners", "list"])
    assert result.exit_code == 0 and "broken_command" not in result.stderr


def test_a_world_plugin_is_listed_and_loaded_by_name(site: Path, campus) -> None:
    world = site / "plugin_town.json"
    campus.model_copy(update={"name": "plugin_town", "description": "A town from a plugin. More."}).save(world)
    install(site, "drivetwin-test-worlds", {"town_world": f"from pathlib import Path\nWORLD = Path({str(world)!r})\n"},
            {"drivetwin.worlds": {"plugin_town": "town_world:WORLD"}})
    entry = next(e for e in list_worlds() if e.name == "plugin_town")
    assert entry.description == "A town from a plugin" and entry.path == world
    assert load_world("plugin_town").name == "plugin_town"


def test_a_broken_world_plugin_is_reported_by_worlds_list(site: Path) -> None:
    install(site, "drivetwin-test-worlds", {"bad_world": "WORLD = '/nowhere/world.json'\n"},
            {"drivetwin.worlds": {"nowhere": "bad_world:WORLD"}})
    result = CliRunner().invoke(main, ["worlds", "list"])
    assert result.exit_code == 0 and "campus" in result.stdout and "nowhere" not in result.stdout
    [line] = [line for line in result.stderr.splitlines() if "nowhere = bad_world:WORLD" in line]
    assert line.startswith("broken plugin skipped:") and "drivetwin-test-worlds" in line
