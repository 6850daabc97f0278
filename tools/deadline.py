"""Calls with a whole-call deadline: the call runs in a worker thread and is abandoned when late.

Python cannot stop a thread, so a late call is left to finish (or hang) on its own in a
daemon thread; the caller gets DeadlineExceeded at the deadline and goes on. Used for
plugin code (drivetwin.tools.plugin_box) and for backend requests, whose library timeouts
count per read: a server dripping one byte every few seconds never trips those.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any, TypeVar

T = TypeVar("T")


class DeadlineExceeded(TimeoutError):
    """The call did not return within its deadline."""


def call_within(function: Callable[[], T], deadline_s: float | None, name: str) -> T:
    """`function()`, or DeadlineExceeded after `deadline_s`; its exceptions (any BaseException) re-raised."""
    if deadline_s is None:
        return function()
    outcome: dict[str, Any] = {}

    def target() -> None:
        try:
            outcome["value"] = function()
        except BaseException as exc:  # SystemExit, KeyboardInterrupt: raised by the call, handed back
            outcome["error"] = exc

    worker = threading.Thread(target=target, name=name, daemon=True)
    worker.start()
    worker.join(deadline_s)
    if worker.is_alive():
        raise DeadlineExceeded(f"{name} did not answer within {deadline_s:g} s")
    if "error" in outcome:
        raise outcome["error"]
    return outcome["value"]  # type: ignore[no-any-return]
