"""The chat loop: prompts and commands in, plans, diffs and plain-words errors out.

The same loop serves a person at a terminal (prompt_toolkit line editing and history) and a
script (`--script FILE`), so a scripted demo exercises exactly what a user types.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path

from drivetwin.orchestrator.cli_export import ExportError, export_scene
from drivetwin.orchestrator.planning.llm.planner import format_trace
from drivetwin.orchestrator.session import Session, SessionError, TurnReport
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.json_input import JsonInputError, read_text_file
from drivetwin.worlds.scene import SceneFileError

# A script is a few hundred lines of prompts; a bigger file is almost certainly the wrong one.
MAX_SCRIPT_BYTES = 1024 * 1024
# Control characters (ANSI escapes, C1 controls) and invisible direction overrides: echoed
# raw they would recolour, move or rewrite the user's terminal. Newlines are kept.
_UNSAFE_CHARS = re.compile(r"[\x00-\x09\x0b-\x1f\x7f-\x9f\u200b-\u200f\u202a-\u202e\u2066-\u2069]")


def neutralised(text: str) -> str:
    """`text` with every control character shown as a visible escape (ESC -> \\x1b)."""
    return _UNSAFE_CHARS.sub(lambda m: m.group().encode("unicode_escape").decode("ascii"), text)


class ScriptFileError(ValueError):
    """A --script file that cannot be read: missing, not a regular file, too big, not UTF-8."""


def read_script(path: Path) -> list[str]:
    """The lines of a --script file; ScriptFileError says what is wrong with it."""
    try:
        return read_text_file(path, "script", MAX_SCRIPT_BYTES).splitlines()
    except JsonInputError as exc:
        raise ScriptFileError(str(exc)) from exc

HELP = """\
Type what you want changed, e.g.
  make it rain | add a parked car at the JTEKT building entrance | remove the cones you added
Commands (with or without a leading slash):
  undo, redo          step back / forward through changes
  accept, reject      confirm the last change, or throw it away for good
  save PATH, load PATH  write / read the scene as JSON
  export PATH.xosc    write the scenario as OpenSCENARIO (roads as OpenDRIVE beside it)
  scene               summary of the scene          tools   list the Worker tools
  render [PATH]       write a frame (PNG, depth and LIDAR beside it)
  explain on|off      show each planning level's input and output
  help, quit
"""


@dataclass
class ChatOptions:
    """How a chat runs: where frames go, whether to explain, whether to stop on failure."""

    out_dir: Path | None = None
    explain: bool = False
    fail_fast: bool = False
    render_each: bool = False
    echo: Callable[[str], None] = print
    render: Callable[[Session, Path], list[Path]] | None = None
    frames: list[Path] = field(default_factory=list)

    def say(self, text: str) -> None:
        """Echo `text` with control characters made visible (a prompt may hold ANSI escapes)."""
        self.echo(neutralised(text))


def scene_summary(session: Session) -> str:
    """A few lines: what the world holds now and its environment."""
    scene = session.scene
    counts: dict[str, int] = {}
    for asset in scene.assets:
        counts[asset.category] = counts.get(asset.category, 0) + 1
    env = scene.environment
    lines = [
        f"world {scene.name}: {len(scene.assets)} assets + ego at "
        f"({scene.ego.pose.x:.1f}, {scene.ego.pose.y:.1f}) doing {scene.ego.behaviour.kind}",
        f"time {env.time_of_day}, weather {env.weather.kind} ({env.weather.intensity:.1f}), "
        f"street lights {env.lighting.street_lights}",
        "assets: " + ", ".join(f"{n} {c}" for c, n in sorted(counts.items())),
    ]
    moving = [a for a in scene.assets if a.behaviour.kind != "parked"]
    if moving:
        lines.append("moving: " + ", ".join(f"{a.id} ({a.behaviour.kind})" for a in moving))
    return "\n".join(lines)


def format_report(report: TurnReport, explain: bool) -> str:
    """A turn in plain words: plan, diff, answer or error."""
    lines = []
    if report.plan is not None and report.plan.read_as is not None:
        lines.append(f"  read as: {report.plan.read_as!r}")  # words respelt in context: never a hidden reading
    if report.plan is not None:
        if explain:
            lines += [f"  {line}" for line in format_trace(report.plan).splitlines()]
        else:
            lines += [f"  plan: {call}" for call in report.plan.calls]
    if report.question is not None:
        lines.append(f"  asked: {report.question.text}")
        lines += [f"    {n}. {r.text}" for n, r in enumerate(report.question.readings, start=1)]
        lines.append("  type a number to choose, or say it another way")
    elif report.ok:
        lines += [f"  {d}" for d in report.diff] or [f"  {r}" for r in report.results]
        if report.answer and not report.diff:
            lines.append(f"  answer: {report.answer}")
        lines.append(f"  ok ({report.seconds * 1000:.0f} ms)")
    else:
        lines.append(f"  error: {report.error}")
    return "\n".join(lines)


def run_command(session: Session, line: str, options: ChatOptions) -> bool | None:
    """Run a REPL command; None if `line` is not a command, else whether it succeeded."""
    word, _, rest = line.strip().lstrip("/").partition(" ")
    word, rest = word.lower(), rest.strip()
    echo = options.say
    try:
        if word == "undo":
            echo("\n".join(f"  {d}" for d in session.undo()) or "  undone")
        elif word == "redo":
            echo("\n".join(f"  {d}" for d in session.redo()) or "  redone")
        elif word == "accept":
            echo(f"  {session.accept()}")
        elif word == "reject":
            echo("\n".join(f"  {d}" for d in session.reject()) or "  rejected")
        elif word == "save" and rest:
            echo(f"  saved {session.save(rest)}")
        elif word == "export" and rest:
            echo("\n".join(f"  wrote {path}" for path in export_scene(session.scene, rest)))
        elif word == "load" and rest:
            session.load(rest)
            echo(f"  loaded {rest}\n{scene_summary(session)}")
        elif word == "scene" and not rest:
            echo(scene_summary(session))
        elif word == "tools" and not rest:
            for name in session.registry.names():
                tool = session.registry.get(name)
                echo(f"  {name:22s} [{tool.family}] {tool.description}")
        elif word == "render":
            if options.render is None:
                raise SessionError("rendering is not available in this session")
            target = Path(rest) if rest else (options.out_dir or Path(".")) / "frame.png"
            for path in options.render(session, target):
                echo(f"  wrote {path}")
        elif word == "explain" and rest in ("on", "off"):
            options.explain = rest == "on"
            echo(f"  explain {rest}")
        elif word in ("help", "?") and not rest:
            echo(HELP)
        else:
            return None
    except (SessionError, SceneFileError, ExportError, OSError) as exc:
        echo(f"  error: {exc}")
        return False
    return True


def run_lines(session: Session, lines: Iterable[str], options: ChatOptions) -> int:
    """Run prompts and commands in order; the exit status: 1 when any line was refused, asked or
    failed (at the first one with fail_fast), else 0."""
    failures = 0
    step = 0
    for raw in lines:
        line = raw.rstrip("\n")
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        if line.strip().lower() in ("quit", "exit", "/quit", "/exit"):
            break
        options.say(f"> {line}")
        done = run_command(session, line, options)
        if done is None:
            # A bare number answers an open clarifying question; anything else is a new prompt.
            if session.pending is not None and line.strip().isdigit():
                try:
                    report = session.choose(int(line.strip()))
                except SessionError as exc:
                    report = TurnReport(line, False, error=str(exc))
            else:
                report = session.submit(line)
            options.say(format_report(report, options.explain))
            done = report.ok
            if report.ok and options.render_each and options.render and options.out_dir:
                step += 1
                stem = options.out_dir / f"step_{step:02d}"
                for path in options.render(session, stem.with_suffix(".png")):
                    options.echo(f"  wrote {path}")
                summary = stem.with_suffix(".txt")
                summary.write_text(f"> {line}\n{scene_summary(session)}\n", encoding="utf-8")
                options.frames.append(summary)
        if not done:
            failures += 1
            if options.fail_fast:
                options.echo("stopping at the first failure (--fail-fast)")
                return 1
    if failures:
        options.echo(f"{failures} line(s) not done (refused, asked or failed)")
        return 1
    return 0


def interactive(session: Session, options: ChatOptions, history_file: Path) -> int:
    """The terminal loop with line editing and a persistent history."""
    from prompt_toolkit import PromptSession
    from prompt_toolkit.history import FileHistory

    history_file.parent.mkdir(parents=True, exist_ok=True)
    prompt: PromptSession[str] = PromptSession(history=FileHistory(str(history_file)))
    options.echo(f"drivetwin on {session.scene.name}: type 'help' for commands, Ctrl-D to quit")

    def lines() -> Iterable[str]:
        while True:
            try:
                yield prompt.prompt("drivetwin> ")
            except KeyboardInterrupt:
                continue
            except EOFError:
                return

    return run_lines(session, lines(), options)


def dump_tools(registry: ToolRegistry) -> str:
    """Every tool with its source and JSON Schema, as JSON."""
    return json.dumps(
        [{**registry.get(n).json_schema(), "source": registry.sources.get(n, "?")} for n in registry.names()],
        indent=2,
    )
