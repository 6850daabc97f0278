"""The `drivetwin` command line: chat, demo, worlds, tools, backends, eval, enhance, bench."""

from __future__ import annotations

import json
import sys
from importlib.resources import files
from pathlib import Path
from typing import Any

import click
from drivetwin.orchestrator.cli_plugins import PluginCommandGroup, echo_problems, planners_group
from drivetwin.orchestrator.logs import open_log as open_request_log
from drivetwin.orchestrator.repl import ChatOptions, ScriptFileError, dump_tools, interactive, read_script, run_lines
from drivetwin.orchestrator.session import Session
from drivetwin.orchestrator.session_setup import command_settings as _settings
from drivetwin.orchestrator.session_setup import open_live_session
from drivetwin.orchestrator.session_setup import planner_or_rules as _fallback_planner
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.defaults import list_worlds, load_world, plugin_worlds
from drivetwin.worlds.scene import scene_json_schema

# Simulated seconds between scripted prompts, so each frame shows the world moving on.
SCRIPT_SECONDS_PER_STEP = 1.0


@click.group(cls=PluginCommandGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="drivetwin")
def main() -> None:
    """Author driving scenarios in a live digital twin by talking to it.

    Example: drivetwin chat --world campus
    """


def _script_lines(script: Path) -> list[str]:
    try:
        return read_script(script)
    except ScriptFileError as exc:
        raise click.ClickException(str(exc)) from exc


@main.command()
@click.option("--world", default="campus", show_default=True, help="world name or JSON file")
@click.option("--planner", "planner_name", default=None,
              help="rules, llm, retrieval or hybrid, or a plugin's (default: settings, hybrid)")
@click.option("--backend", default=None, help="LLM backend: embedded, ollama, openai")
@click.option("--model", default=None, help="model name, preset or GGUF path")
@click.option("--script", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="run the prompts and commands in FILE, then exit")
@click.option("--fail-fast", is_flag=True, help="with --script: exit non-zero at the first failure")
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              help="folder for frames and summaries")
@click.option("--render-each", is_flag=True, help="write a frame and a scene summary after each prompt")
@click.option("--resume", is_flag=True, help="restore the last session from its journal")
@click.option("--journal", type=click.Path(dir_okay=False, path_type=Path), default=None,
              help="journal file (default: under $DRIVETWIN_STATE)")
@click.option("--explain", is_flag=True, help="show each planning level's input and output")
@click.option("--no-sim", is_flag=True, help="edit the scene without running physics")
@click.option("--enhance", "enhance_model", default=None, help="SDXL folder for enhanced frames")
@click.option("--isolate-plugins", is_flag=True, help="run plugin Workers in a separate process")
def chat(world: str, planner_name: str | None, backend: str | None, model: str | None, script: Path | None,
         fail_fast: bool, out_dir: Path | None, render_each: bool, resume: bool, journal: Path | None,
         explain: bool, no_sim: bool, enhance_model: str | None, isolate_plugins: bool) -> None:
    """Edit a live world by typing what you want.

    Example: drivetwin chat --world campus --script demo.txt --fail-fast
    """
    if render_each and no_sim:
        raise click.UsageError("--render-each draws the simulated world: drop --no-sim")
    settings = _settings(planner_name, backend, model)
    open_request_log(settings.state_dir, command="chat", world=world)  # drivetwin logs reads it
    opened = open_live_session(world, settings, journal=journal, resume=resume,
                               can_ask=script is None and sys.stdin.isatty(), isolate_plugins=isolate_plugins,
                               simulate=not no_sim, background=script is None, enhance_model=enhance_model)
    session, live = opened.session, opened.live
    options = ChatOptions(out_dir=out_dir, explain=explain, fail_fast=fail_fast,
                          render_each=render_each, render=live.render)
    if out_dir:
        out_dir.mkdir(parents=True, exist_ok=True)
    try:
        if script is not None:
            status = run_lines(session, live.paced(_script_lines(script), SCRIPT_SECONDS_PER_STEP), options)
        else:
            status = interactive(session, options, settings.state_dir / "history.txt")
        session.close()  # a clean end: the journal says so, and `chat` will not offer to resume it
    finally:
        for path in live.close():
            click.echo(f"  wrote {path}")
        summary = live.enhancer_summary()
        if summary:
            click.echo(summary)
    sys.exit(status)


@main.command()
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path),
              default=Path("demo_out"), show_default=True)
@click.option("--planner", "planner_name", default=None,
              help="rules, llm or hybrid (the default: rules first, the embedded LLM when they cannot plan)")
@click.option("--no-render", is_flag=True, help="skip frames (faster)")
def demo(out_dir: Path, planner_name: str | None, no_render: bool) -> None:
    """Run the paper's edits on the campus: a frame and a scene summary per step.

    Example: drivetwin demo --out demo_out
    """
    from drivetwin.orchestrator.live import LiveWorld

    script = files("drivetwin.orchestrator").joinpath("demo_script.txt").read_text(encoding="utf-8")
    out_dir.mkdir(parents=True, exist_ok=True)
    session = Session(load_world("campus"), _fallback_planner(_settings(planner_name)),
                      journal_path=out_dir / "journal.jsonl")
    live = LiveWorld(session, simulate=True, background=False)
    options = ChatOptions(out_dir=out_dir, fail_fast=True, render_each=not no_render,
                          render=None if no_render else live.render)
    try:
        status = run_lines(session, live.paced(script.splitlines(), SCRIPT_SECONDS_PER_STEP), options)
    finally:
        live.close()
    session.save(out_dir / "scene.json")
    session.close()  # a clean end: the journal says so
    click.echo(f"demo finished with status {status}; outputs in {out_dir}")
    sys.exit(status)


@main.group()
def worlds() -> None:
    """Worlds that can be loaded by name."""


@worlds.command("list")
@click.option("--json", "as_json", is_flag=True, help="print the worlds as JSON")
def worlds_list(as_json: bool) -> None:
    """Show every world: shipped, imported, reconstructed and those in $DRIVETWIN_WORLDS.

    Example: drivetwin worlds list
    """
    entries = list_worlds()
    echo_problems(plugin_worlds()[1])
    if as_json:
        click.echo(json.dumps([{"name": e.name, "description": e.description, "path": str(e.path),
                                "package": str(e.package) if e.package else None} for e in entries], indent=2))
        return
    for entry in entries:
        click.echo(f"{entry.name:16s} {entry.description}  ({entry.path})")


@main.group()
def tools() -> None:
    """Worker tools, built in and from plugins."""


@tools.command("list")
@click.option("--json", "as_json", is_flag=True, help="print each tool's JSON Schema")
def tools_list(as_json: bool) -> None:
    """Show the Worker tools with their family, source and (with --json) schema.

    Example: drivetwin tools list --json
    """
    registry = ToolRegistry.default()
    if as_json:
        click.echo(dump_tools(registry))
    else:
        for name in registry.names():
            tool = registry.get(name)
            click.echo(f"{name:22s} {tool.family:11s} {registry.sources[name]:12s} {tool.description}")
    echo_problems(registry.problems)


@main.group()
def backends() -> None:
    """LLM backends."""


@backends.command("list")
@click.option("--backend", default=None, help="mark this backend's row as the chosen one")
@click.option("--model", default=None, help="mark this model's row as the chosen one")
@click.option("--json", "as_json", is_flag=True, help="print the rows as JSON")
def backends_list(backend: str | None, model: str | None, as_json: bool) -> None:
    """Show each backend, whether it is usable now, and the command that fixes it if not.

    The row that flags, environment and config file select is marked with *.

    Example: drivetwin backends list
    """
    from dataclasses import asdict

    from drivetwin.orchestrator.backends import backends_table, list_backends

    settings = _settings(backend=backend, model=model)
    if as_json:
        click.echo(json.dumps([asdict(row) for row in list_backends(settings)], indent=2, default=str))
        return
    click.echo(backends_table(settings))


@main.group()
def config() -> None:
    """The settings every command uses: flags > environment > config file > defaults."""


@config.command("show")
@click.option("--json", "as_json", is_flag=True, help="print the settings as JSON")
def config_show(as_json: bool) -> None:
    """Print each resolved setting, its value and where it came from.

    Example: DRIVETWIN_BACKEND=openai drivetwin config show
    """
    rows = _settings().rows()
    if as_json:
        click.echo(json.dumps({name: {"value": value, "source": source} for name, value, source in rows}, indent=2))
        return
    width = max(len(name) for name, _, _ in rows)
    for name, value, source in rows:
        click.echo(f"{name:<{width}}  {value}  [{source}]")


@main.command()
@click.argument("what", type=click.Choice(["scene"]))
def schema(what: str) -> None:
    """Print a published JSON Schema.

    Example: drivetwin schema scene > scene.schema.json
    """
    click.echo(json.dumps(scene_json_schema(), indent=2))


# Each benchmark is a module with its own argparse `main()`: the sub-command hands every
# argument to it, --help included, so `drivetwin bench edits --help` shows the benchmark's options.
BENCHMARKS: dict[str, tuple[str, str]] = {
    "edits": ("drivetwin.orchestrator.bench_edits", "add/move/remove latency and physics rate by world size"),
    "physics": ("drivetwin.worlds.bench_physics", "MuJoCo steps per second with N assets"),
    "splats": ("drivetwin.worlds.render.bench_splats", "splat rasterizer frame times (numba, torch, gsplat)"),
    "hybrid": ("drivetwin.worlds.render.bench_hybrid", "hybrid renderer stage table at 10k/100k/1M splats"),
    "planners": ("drivetwin.orchestrator.bench_planners", "planner latency on the paper's prompts"),
    "roads": ("drivetwin.worlds.opendrive.bench", "OpenDRIVE/OSM import time and lane accuracy"),
    "serve": ("drivetwin.orchestrator.serve.bench", "browser view pose updates per second with N assets"),
}


@main.group()
def bench() -> None:
    """Benchmarks: each prints figures and writes JSON (--out FILE); `bench NAME --help` lists its options."""


def _benchmark_command(name: str, module: str, summary: str) -> click.Command:
    @click.command(name=name, help=f"{summary}.\n\nExample: drivetwin bench {name} --out {name}.json",
                   context_settings={"ignore_unknown_options": True, "allow_extra_args": True},
                   add_help_option=False)
    @click.pass_context
    def run(ctx: click.Context) -> None:
        import importlib

        # argparse reads sys.argv when a benchmark's main() is called without arguments;
        # argv[0] becomes the program name its --help shows.
        sys.argv = [f"drivetwin bench {name}", *ctx.args]
        result = importlib.import_module(module).main()
        sys.exit(result if isinstance(result, int) else 0)

    return run


for _name, (_module, _summary) in BENCHMARKS.items():
    bench.add_command(_benchmark_command(_name, _module, _summary))


@main.group(name="eval")
def eval_group() -> None:
    """Measure planners on eval suites."""


@eval_group.command("run")
@click.option("--suite", default="smoke", show_default=True, help="suite name (smoke, full) or JSONL path")
@click.option("--planner", "planner_name", default="rules", show_default=True)
@click.option("--backend", default=None)
@click.option("--model", default=None)
@click.option("--trials", default=1, show_default=True, type=click.IntRange(1, 100))
@click.option("--workers", default=1, show_default=True, type=click.IntRange(1, 64))
@click.option("--executor", type=click.Choice(["local", "ray"]), default="local", show_default=True)
@click.option("--out", "out_path", type=click.Path(dir_okay=False, path_type=Path), required=True,
              help="records file (JSON Lines); an existing one is resumed")
@click.option("--only", multiple=True, help="run only cases of this grade or task (repeatable), e.g. --only direct")
@click.option("--quiet", "-q", is_flag=True, help="no progress bar (one is drawn only on a terminal anyway)")
def eval_run(suite: str, planner_name: str, backend: str | None, model: str | None, trials: int,
             workers: int, executor: str, out_path: Path, only: tuple[str, ...], quiet: bool) -> None:
    """Run a suite against a planner, resumably.

    Example: drivetwin eval run --suite full --planner rules --trials 3 --out runs/rules.jsonl
    """
    from drivetwin.evals import RecordsError, RunError, SuiteError, run_suite

    if planner_name == "rules" and (backend or model):
        raise click.UsageError("the rules planner takes no --backend or --model; use --planner llm or hybrid")
    settings = _settings(planner_name, backend, model)
    # The rule planner takes no backend; the others run on the settings' backend and model.
    options: dict[str, Any] = {} if planner_name == "rules" else {
        k: v for k, v in settings.planner_options().items() if v is not None}
    try:
        summary = run_suite(suite, planner_name, planner_options=options, trials=trials, out_path=out_path,
                            executor=executor, workers=workers, progress=not quiet, only=only)
    except (RunError, SuiteError, RecordsError) as exc:
        raise click.ClickException(str(exc)) from exc
    click.echo(f"{summary.passed} passed, {summary.failed} failed, {summary.errors} errors; records in {out_path}")
    if summary.interrupted:
        click.echo("interrupted: run the same command again to resume")
        sys.exit(130)


@eval_group.command("report")
@click.argument("runs", nargs=-1, required=True, type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=Path("eval_report"),
              show_default=True)
@click.option("--json", "as_json", is_flag=True, help="print the report's figures (report.json) and the files written")
def eval_report(runs: tuple[Path, ...], out_dir: Path, as_json: bool) -> None:
    """Write Markdown, JSON and PNG reports (Tables 4 and 5) for one or more runs.

    Example: drivetwin eval report runs/rules.jsonl runs/llm.jsonl --out report
    """
    from drivetwin.evals import write_report

    written = write_report(list(runs), out_dir)
    if as_json:
        figures = json.loads((out_dir / "report.json").read_text(encoding="utf-8"))
        click.echo(json.dumps({"written": [str(p) for p in written], **figures}, indent=2))
        return
    for path in written:
        click.echo(f"wrote {path}")


@main.command()
@click.argument("src_dir", type=click.Path(exists=True, file_okay=False, path_type=Path))
@click.option("--model", required=True, help="SDXL folder or cached model id")
@click.option("--controlnet", default=None, help="SDXL depth ControlNet folder")
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=None)
@click.option("--quiet", "-q", is_flag=True, help="no progress bar (one is drawn only on a terminal anyway)")
def enhance(src_dir: Path, model: str, controlnet: str | None, out_dir: Path | None, quiet: bool) -> None:
    """Enhance a folder of rendered frames with SDXL img2img; resumes where it stopped.

    Example: drivetwin enhance demo_out --model models/sdxl
    """
    from drivetwin.worlds.enhance import EnhancerError, EnhanceSettings, enhance_folder
    from drivetwin.worlds.enhance.offline import default_output_dir

    target = out_dir or default_output_dir(src_dir)
    try:
        report = enhance_folder(src_dir, target, EnhanceSettings(model=model, controlnet=controlnet), progress=not quiet)
    except EnhancerError as exc:
        raise click.ClickException(str(exc)) from exc
    click.echo(f"enhanced frames in {target}: {report}")


from drivetwin.worlds.opendrive.cli import import_command  # noqa: E402  (worlds import)
from drivetwin.worlds.reconstruct.cli import add_reconstruct_parser  # noqa: E402  (the reconstruct group)

worlds.add_command(import_command)

add_reconstruct_parser(main)

from drivetwin.orchestrator.cli_journal import journal_group  # noqa: E402  (drivetwin journal check|repair)

main.add_command(journal_group)

from drivetwin.orchestrator.cli_export import export_command  # noqa: E402  (drivetwin export)

main.add_command(export_command)

from drivetwin.orchestrator.serve.command import serve_command  # noqa: E402  (drivetwin serve)

main.add_command(serve_command)
main.add_command(planners_group)  # drivetwin planners list (cli_plugins)

from drivetwin.orchestrator.cli_logs import logs_group  # noqa: E402  (drivetwin logs list|show|replay|edits)

main.add_command(logs_group)
