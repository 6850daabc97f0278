"""The online enhancer: a worker thread with a one-frame mailbox, newest frame wins."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest
from conftest import draw_street
from drivetwin.worlds.enhance import (
    EnhancedFrame,
    EnhanceSettings,
    OnlineEnhancer,
    structure_score,
)
from drivetwin.worlds.scene import Environment

# The stand-in diffusion takes 50 ms a frame: 100 frames queued would take 5 s.
SLOW_S = 0.05
# A submit may wait for the GIL while the worker runs numpy, and for the CPU on a loaded
# machine (29 ms seen beside an eval run); it must never wait for a frame, which takes SLOW_S.
MAX_SUBMIT_S = SLOW_S


class SlowBrightener:
    """A slow 'diffusion' that brightens the frame, scored by the real structure check."""

    def __init__(self, fail_first: bool = False) -> None:
        self.seen: list[int] = []
        self.fail_first = fail_first

    def enhance(
        self, frame: np.ndarray, depth: np.ndarray | None = None, env: Environment | None = None
    ) -> EnhancedFrame:
        time.sleep(SLOW_S)
        self.seen.append(int(frame[0, 0, 0]))
        if self.fail_first and len(self.seen) == 1:
            raise RuntimeError("out of memory")
        candidate = np.clip(frame.astype(int) + 20, 0, 255).astype(np.uint8)
        score = structure_score(frame, candidate)
        return EnhancedFrame(candidate if score.accepted else frame, candidate, score, SLOW_S)


def numbered(i: int) -> np.ndarray:
    frame = draw_street()
    frame[0, 0, 0] = i  # the frame's number, readable after enhancement (+20)
    return frame


def wait_idle(online: OnlineEnhancer, timeout: float = 5.0) -> None:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        stats = online.stats()
        if stats.pending == 0 and not stats.busy:
            return
        time.sleep(0.01)
    raise AssertionError("the worker did not finish")


def test_submitting_100_frames_to_a_slow_enhancer_never_blocks_the_caller() -> None:
    with OnlineEnhancer(SlowBrightener()) as online:
        waits, pending = [], []
        start = time.perf_counter()
        for i in range(100):
            t0 = time.perf_counter()
            online.submit(numbered(i))
            waits.append(time.perf_counter() - t0)
            pending.append(online.stats().pending)
        total = time.perf_counter() - start
    assert max(waits) < MAX_SUBMIT_S
    assert total < 100 * SLOW_S / 5  # far faster than enhancing them would be
    assert max(pending) <= 1  # the mailbox never holds more than one frame


def test_frames_that_were_overtaken_are_dropped_and_counted() -> None:
    enhancer = SlowBrightener()
    with OnlineEnhancer(enhancer) as online:
        for i in range(100):
            online.submit(numbered(i))
        wait_idle(online)
        stats = online.stats()
    assert stats.submitted == 100
    assert stats.dropped > 80  # most frames arrived while another was being enhanced
    assert stats.processed + stats.dropped == stats.submitted
    assert enhancer.seen == sorted(enhancer.seen)  # never an older frame after a newer one


def test_latest_is_the_newest_enhanced_frame() -> None:
    with OnlineEnhancer(SlowBrightener()) as online:
        assert online.latest() is None
        for i in range(10):
            online.submit(numbered(i))
        wait_idle(online)
        latest = online.latest()
    assert latest is not None and latest.index == 9
    assert latest.result.accepted
    assert latest.image[0, 0, 0] == 9 + 20


def test_the_caller_may_reuse_its_frame_buffer_after_submit() -> None:
    with OnlineEnhancer(SlowBrightener()) as online:
        buffer = numbered(7)
        online.submit(buffer)
        buffer[:] = 0
        wait_idle(online)
        latest = online.latest()
    assert latest is not None and latest.image[0, 0, 0] == 7 + 20


def test_a_failing_frame_is_counted_and_the_worker_carries_on() -> None:
    with OnlineEnhancer(SlowBrightener(fail_first=True)) as online:
        online.submit(numbered(1))
        wait_idle(online)
        online.submit(numbered(2))
        wait_idle(online)
        stats, latest = online.stats(), online.latest()
        assert online.running
    assert stats.errors == 1 and "out of memory" in (stats.last_error or "")
    assert latest is not None and latest.index == 1


def test_a_stopped_enhancer_refuses_frames() -> None:
    online = OnlineEnhancer(SlowBrightener())
    online.stop()
    assert not online.running
    with pytest.raises(RuntimeError, match="stopped"):
        online.submit(numbered(0))


def test_the_online_enhancer_runs_the_real_pipeline(tiny_sdxl: dict[str, Path]) -> None:
    settings = EnhanceSettings(
        model=str(tiny_sdxl["model"]), work_long_side=64, steps=4, strength=0.5, device="cpu"
    )
    with OnlineEnhancer.from_settings(settings) as online:
        online.submit(draw_street(), env=Environment(time_of_day="23:00"))
        wait_idle(online, timeout=60.0)
        latest, stats = online.latest(), online.stats()
    assert stats.errors == 0, stats.last_error
    assert latest is not None and latest.image.shape == draw_street().shape
