"""Plugins on the command line: `drivetwin planners list`, commands added by plugins, broken-plugin lines.

Every command that loads plugins reports a broken one the same way, one line on stderr
(`problem_line`), and goes on with the rest.
"""

from __future__ import annotations

import json
from collections.abc import Iterable

import click
from drivetwin.orchestrator.planning.registry import discover_planners
from drivetwin.tools.plugins import COMMANDS_GROUP, PluginGroup, PluginProblem, load_group

_META_KEY = "drivetwin.plugin_commands"


def problem_line(problem: PluginProblem) -> str:
    """The one line a command prints for a broken plugin it skipped."""
    fix = f" (fix: {problem.fix})" if problem.fix else ""
    return f"broken plugin skipped: {problem.entry_point}: {problem.error}{fix}"


def echo_problems(problems: Iterable[PluginProblem]) -> None:
    for problem in problems:
        click.echo(problem_line(problem), err=True)


def _click_command(loaded: object) -> click.Command:
    if not isinstance(loaded, click.Command):
        raise TypeError(f"{loaded!r} is not a click command (decorate it with @click.command())")
    return loaded


class PluginCommandGroup(click.Group):
    """The `drivetwin` group: its own commands, then those plugins add (`drivetwin.commands`).

    A plugin command never replaces a built-in one; plugins are loaded only when a name is
    not built in or the command list is shown, so a broken one costs the other commands nothing.
    """

    def _plugins(self, ctx: click.Context) -> PluginGroup[click.Command]:
        found: PluginGroup[click.Command] | None = ctx.meta.get(_META_KEY)
        if found is None:
            found = load_group(COMMANDS_GROUP, _click_command)
            for plugin in found.loaded:
                if plugin.name in self.commands:
                    found.problems.append(PluginProblem(
                        f"{plugin.name} = {plugin.target}", f"drivetwin already has a command {plugin.name!r}",
                        COMMANDS_GROUP, "rename the plugin's entry point"))
            echo_problems(found.problems)
            ctx.meta[_META_KEY] = found
        return found

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        command = super().get_command(ctx, cmd_name)
        if command is not None:
            return command
        plugin = self._plugins(ctx).by_name().get(cmd_name)
        return plugin.value if plugin is not None else None

    def list_commands(self, ctx: click.Context) -> list[str]:
        own = super().list_commands(ctx)
        return own + sorted(name for name in self._plugins(ctx).by_name() if name not in self.commands)


@click.group("planners")
def planners_group() -> None:
    """Planners: built in and from plugins (`drivetwin.planners` entry points)."""


@planners_group.command("list")
@click.option("--json", "as_json", is_flag=True, help="print the planners (and broken plugins) as JSON")
def planners_list(as_json: bool) -> None:
    """Show every planner, where it comes from and what it does; broken plugins go to stderr.

    Example: drivetwin planners list --json
    """
    entries, problems = discover_planners()
    if as_json:
        click.echo(json.dumps({
            "planners": [{"name": e.name, "source": e.source, "description": e.description} for e in entries],
            "problems": [{"group": p.group, "entry_point": p.entry_point, "error": p.error, "fix": p.fix}
                         for p in problems],
        }, indent=2))
    else:
        for entry in entries:
            click.echo(f"{entry.name:12s} {entry.source:24s} {entry.description}")
    echo_problems(problems)
