"""Online enhancement: a worker thread that repaints the newest frame while physics runs on.

The simulation loop calls `submit` every rendered frame and `latest` whenever it draws.
There is one mailbox slot: a frame submitted while another waits replaces it (the waiting
one is counted as dropped), so the loop never blocks on the diffusion and memory is bounded
by one pending frame plus the one being enhanced.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from drivetwin.worlds.enhance.pipeline import EnhancedFrame, FrameEnhancer
from drivetwin.worlds.enhance.settings import EnhanceSettings
from drivetwin.worlds.enhance.structure import check_frame
from drivetwin.worlds.scene import Environment
from numpy.typing import NDArray

# stop() waits this long for the frame being enhanced; a real SDXL frame on a CPU can take
# minutes, and the daemon thread dies with the process anyway.
STOP_TIMEOUT_S = 10.0


class SupportsEnhance(Protocol):
    """Anything that turns (frame, depth, env) into an EnhancedFrame, e.g. FrameEnhancer."""

    def enhance(
        self,
        frame: NDArray[np.uint8],
        depth: NDArray[np.floating] | None = None,
        env: Environment | None = None,
    ) -> EnhancedFrame: ...


@dataclass(frozen=True)
class OnlineFrame:
    """The newest enhanced frame and which submission (0-based) it came from."""

    index: int
    result: EnhancedFrame

    @property
    def image(self) -> NDArray[np.uint8]:
        """The frame to show: enhanced, or the baseline when the enhancement was rejected."""
        return np.asarray(self.result.image, dtype=np.uint8)


@dataclass(frozen=True)
class OnlineStats:
    """Counters of an OnlineEnhancer (a snapshot)."""

    submitted: int
    processed: int
    dropped: int
    rejected: int
    errors: int
    pending: int
    busy: bool
    last_error: str | None


@dataclass(frozen=True)
class _Job:
    index: int
    frame: NDArray[np.uint8]
    depth: NDArray[np.floating] | None
    env: Environment | None


class OnlineEnhancer:
    """Enhances frames in a background thread; the newest frame wins, older ones drop."""

    def __init__(self, enhancer: SupportsEnhance, name: str = "drivetwin-enhancer") -> None:
        """Start the worker thread around an already-loaded enhancer."""
        self._enhancer = enhancer
        self._cond = threading.Condition()
        self._slot: _Job | None = None
        self._latest: OnlineFrame | None = None
        self._stopping = False
        self._submitted = self._processed = self._dropped = self._rejected = self._errors = 0
        self._last_error: str | None = None
        self._busy = False
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)
        self._thread.start()

    @classmethod
    def from_settings(cls, settings: EnhanceSettings) -> OnlineEnhancer:
        """Load the SDXL pipeline described by `settings` and start the worker."""
        return cls(FrameEnhancer(settings))

    def submit(
        self,
        frame: NDArray[np.uint8],
        depth: NDArray[np.floating] | None = None,
        env: Environment | None = None,
    ) -> None:
        """Hand a frame to the worker without waiting; a frame still waiting is dropped.

        frame: RGB uint8 [H, W, 3] (copied, so the caller may reuse its buffer); depth:
        the renderer's depth [H, W] in metres; env: the Scene's environment.
        """
        job_frame = np.array(check_frame(frame), copy=True)
        job_depth = None if depth is None else np.array(depth, copy=True)
        with self._cond:
            if self._stopping:
                raise RuntimeError("this OnlineEnhancer was stopped; create a new one")
            if self._slot is not None:
                self._dropped += 1
            self._slot = _Job(self._submitted, job_frame, job_depth, env)
            self._submitted += 1
            self._cond.notify()

    def latest(self) -> OnlineFrame | None:
        """The newest finished frame, or None before the first one is done."""
        with self._cond:
            return self._latest

    def stats(self) -> OnlineStats:
        """A snapshot of the counters."""
        with self._cond:
            return OnlineStats(
                submitted=self._submitted,
                processed=self._processed,
                dropped=self._dropped,
                rejected=self._rejected,
                errors=self._errors,
                pending=0 if self._slot is None else 1,
                busy=self._busy,
                last_error=self._last_error,
            )

    def drain(self, timeout: float) -> bool:
        """Wait until no frame is waiting or being enhanced; False if `timeout` ran out first."""
        with self._cond:
            return self._cond.wait_for(lambda: self._slot is None and not self._busy, timeout)

    def stop(self, timeout: float = STOP_TIMEOUT_S) -> None:
        """Stop the worker after the frame in progress; a waiting frame is dropped."""
        with self._cond:
            self._stopping = True
            if self._slot is not None:
                self._dropped += 1
                self._slot = None
            self._cond.notify_all()
        self._thread.join(timeout)

    @property
    def running(self) -> bool:
        """Whether the worker thread is alive."""
        return self._thread.is_alive()

    def __enter__(self) -> OnlineEnhancer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()

    def _run(self) -> None:
        while True:
            with self._cond:
                while self._slot is None and not self._stopping:
                    self._cond.wait()
                if self._stopping:
                    return
                job, self._slot = self._slot, None
                self._busy = True
            assert job is not None
            try:
                result = self._enhancer.enhance(job.frame, job.depth, job.env)
            except Exception as exc:  # one bad frame must not kill the enhancer
                with self._cond:
                    self._errors += 1
                    self._last_error = f"{type(exc).__name__}: {exc}"
                    self._busy = False
                    self._cond.notify_all()
                continue
            with self._cond:
                self._busy = False
                self._processed += 1
                self._rejected += 0 if result.accepted else 1
                self._latest = OnlineFrame(job.index, result)
                self._cond.notify_all()
