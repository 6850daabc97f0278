"""A session's live views: the physics that keeps stepping and the frames drawn from it.

`LiveWorld` hands every scene the session commits to the simulation (between two steps,
under its lock) and draws frames, depth and LIDAR from the simulated state on request.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import Any

from drivetwin.orchestrator.session import Session
from drivetwin.worlds.scene import Scene

FRAME_WIDTH = 640
FRAME_HEIGHT = 360


class LiveWorld:
    """The simulation and renderer behind a session; closing it stops the physics thread."""

    def __init__(self, session: Session, *, simulate: bool = True, background: bool = True,
                 enhance_model: str | None = None) -> None:
        self.session = session
        self.sim: Any = None
        self._renderer: Any = None
        self._enhancer: Any = None
        self._enhance_model = enhance_model
        if simulate:
            from drivetwin.worlds.simulation import Simulation

            self.sim = Simulation(session.scene)
            session.on_change = self._changed
            if background:
                self.sim.start(realtime=True)
        self.background = background

    def _changed(self, scene: Scene) -> None:
        self.sim.apply(scene)

    def paced(self, lines: Iterable[str], seconds: float) -> Iterator[str]:
        """The lines, with `seconds` of simulated time run after each (scripted sessions)."""
        for line in lines:
            yield line
            if self.sim is not None and not self.background:
                self.sim.run_for(seconds)

    def render(self, session: Session, target: Path) -> list[Path]:
        """Write a frame of the live world to `target` (PNG), with depth and LIDAR beside it."""
        if self.sim is None:
            raise RuntimeError("rendering needs the simulation (run without --no-sim)")
        from drivetwin.worlds.render.hybrid import HybridRenderer, chase_camera, save_frame
        from drivetwin.worlds.sensors import Lidar, save_pointcloud

        target.parent.mkdir(parents=True, exist_ok=True)
        with self.sim.lock:
            if self._renderer is None:
                self._renderer = HybridRenderer(self.sim.world)
            camera = chase_camera(self.sim.world, "ego", width=FRAME_WIDTH, height=FRAME_HEIGHT)
            frame = self._renderer.render(camera, session.scene.environment)
            points = Lidar(mount="ego").scan(self.sim.world)
        written = list(save_frame(frame, target).values())
        cloud = target.with_name(target.stem + "_lidar.ply")
        save_pointcloud(points, cloud)
        written.append(cloud)
        if self._enhance_model:
            written += self._enhance(frame, session, target)
        return written

    def _enhance(self, frame: Any, session: Session, target: Path) -> list[Path]:
        """The frame repainted by SDXL, kept only if its structure held (else the baseline)."""
        from drivetwin.worlds.enhance import EnhanceSettings, FrameEnhancer
        from PIL import Image

        if self._enhancer is None:
            self._enhancer = FrameEnhancer(EnhanceSettings(model=self._enhance_model or ""))
        result = self._enhancer.enhance(frame.rgb, frame.depth, session.scene.environment)
        path = target.with_name(target.stem + "_enhanced.png")
        Image.fromarray(result.image).save(path)
        return [path]

    def close(self) -> None:
        if self.sim is not None:
            self.sim.stop()
        if self._renderer is not None and hasattr(self._renderer, "close"):
            self._renderer.close()
