"""Frames per second of the enhancer at the renderer's resolution.

Run: `python -m drivetwin.worlds.enhance.bench --model models/sdxl [--controlnet DIR]`.
"""

from __future__ import annotations

import argparse
import json
import time
from dataclasses import asdict, dataclass

import numpy as np
from drivetwin.worlds.enhance.pipeline import FrameEnhancer, resolve_device, work_size
from drivetwin.worlds.enhance.settings import EnhanceSettings
from numpy.typing import NDArray

# The renderer's default frame size (DESIGN.md's figures are taken at 640 x 360).
RENDER_HEIGHT = 360
RENDER_WIDTH = 640


@dataclass(frozen=True)
class EnhanceBenchmark:
    """Measured speed of the enhancer on one machine."""

    device: str
    frame: tuple[int, int]
    work: tuple[int, int]
    steps_run: int
    frames: int
    seconds_per_frame: float
    frames_per_second: float


def _test_frame(height: int, width: int) -> tuple[NDArray[np.uint8], NDArray[np.float32]]:
    # A horizon scene with a box: enough structure for the check to run as in real use.
    rows = np.linspace(0.0, 1.0, height, dtype=np.float32)[:, None, None]
    frame = np.broadcast_to(rows * np.array([90, 90, 95]) + 100, (height, width, 3)).copy()
    frame[height // 2 : height // 2 + height // 6, width // 3 : width // 2] = [200, 30, 30]
    depth = np.broadcast_to(1.0 + 50.0 * (1.0 - rows[..., 0]), (height, width))
    return frame.astype(np.uint8), np.ascontiguousarray(depth, dtype=np.float32)


def measure_fps(
    settings: EnhanceSettings,
    height: int = RENDER_HEIGHT,
    width: int = RENDER_WIDTH,
    frames: int = 5,
    warmup: int = 1,
    enhancer: FrameEnhancer | None = None,
) -> EnhanceBenchmark:
    """Time `frames` full enhancements (diffusion + structure check) after `warmup` ones."""
    worker = enhancer if enhancer is not None else FrameEnhancer(settings)
    frame, depth = _test_frame(height, width)
    for _ in range(warmup):
        worker.enhance(frame, depth)
    start = time.perf_counter()
    for _ in range(frames):
        worker.enhance(frame, depth)
    seconds = (time.perf_counter() - start) / max(frames, 1)
    return EnhanceBenchmark(
        device=resolve_device(settings.device),
        frame=(height, width),
        work=work_size(height, width, settings.work_long_side),
        steps_run=int(settings.steps * settings.effective_strength()),
        frames=frames,
        seconds_per_frame=seconds,
        frames_per_second=1.0 / seconds if seconds > 0 else float("inf"),
    )


def main(argv: list[str] | None = None) -> None:
    """Command line: print the benchmark as JSON."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--model", required=True, help="SDXL folder or cached model id")
    parser.add_argument("--controlnet", default=None, help="SDXL depth ControlNet folder")
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--work-long-side", type=int, default=1024)
    args = parser.parse_args(argv)
    settings = EnhanceSettings(
        model=args.model,
        controlnet=args.controlnet,
        steps=args.steps,
        work_long_side=args.work_long_side,
    )
    print(json.dumps(asdict(measure_fps(settings, frames=args.frames)), indent=2))


if __name__ == "__main__":
    main()
