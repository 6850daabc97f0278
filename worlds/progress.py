"""Progress bars for long commands (eval runs, reconstruction, enhancement, benchmarks), with rich.

Shown only to a person at a terminal: stderr must be a TTY and CI unset, so scripts, CI logs
and pipes get no bars (and no control characters). It lives in `worlds` because the lowest
layer's commands (reconstruct, enhance) use it too; evals and orchestrator import it from here.

    with progress_bar("eval", total=120, unit="trial") as bar:
        for ...:
            bar.advance(note="pass 17")
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any, Protocol, TextIO

# Set by every common CI service (GitHub Actions, GitLab, Buildkite...): their logs are not terminals
# even when a pseudo-terminal is attached.
CI_VARIABLE = "CI"


class Bar(Protocol):
    """What a long loop reports: one more item done, optionally with a short note."""

    def advance(self, steps: int = 1, note: str = "") -> None: ...


class _Silent:
    def advance(self, steps: int = 1, note: str = "") -> None:
        """Nothing: there is no terminal to draw on."""


class _RichBar:
    def __init__(self, progress: Any, task: Any) -> None:
        self._progress, self._task = progress, task

    def advance(self, steps: int = 1, note: str = "") -> None:
        self._progress.update(self._task, advance=steps, note=note)


def on_terminal(stream: TextIO | None = None) -> bool:
    """Whether a bar may be drawn on `stream` (default stderr): a TTY, and not under CI."""
    target = stream if stream is not None else sys.stderr
    return bool(getattr(target, "isatty", lambda: False)()) and not os.environ.get(CI_VARIABLE)


@contextmanager
def progress_bar(description: str, total: int | None, unit: str = "", *, initial: int = 0, enabled: bool = True,
                 stream: TextIO | None = None) -> Iterator[Bar]:
    """A bar of `total` items (None: a spinner with elapsed time) on stderr, when on a terminal."""
    target = stream if stream is not None else sys.stderr
    if not (enabled and on_terminal(target)):
        yield _Silent()
        return
    from rich.console import Console
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        SpinnerColumn,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    columns = [SpinnerColumn(), TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
               TextColumn(unit), TimeElapsedColumn(), TimeRemainingColumn(), TextColumn("{task.fields[note]}")]
    with Progress(*columns, console=Console(file=target), transient=False) as progress:
        task = progress.add_task(description, total=total, completed=initial, note="")
        yield _RichBar(progress, task)
