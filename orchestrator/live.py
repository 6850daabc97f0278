"""A session's live views: the physics that keeps stepping and the frames drawn from it.

`LiveWorld` hands every scene the session commits to the simulation (between two steps,
under its lock) and draws frames, depth and LIDAR from the simulated state on request.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

from drivetwin.orchestrator.session import Session, SessionError
from drivetwin.worlds.scene import Scene

if TYPE_CHECKING:
    from drivetwin.worlds.enhance.settings import EnhanceSettings

FRAME_WIDTH = 640
FRAME_HEIGHT = 360
# On close, wait this long for the frame the enhancer is on: a scripted chat ends right after
# its last render, and that frame should not be lost; SDXL on a CPU can take minutes.
ENHANCER_DRAIN_S = 600.0


class LiveWorld:
    """The simulation and renderer behind a session; closing it stops the physics thread."""

    def __init__(self, session: Session, *, simulate: bool = True, background: bool = True,
                 enhance: EnhanceSettings | None = None) -> None:
        self.session = session
        self.sim: Any = None
        self._renderer: Any = None
        self._enhancer: Any = None
        self._enhanced_targets: dict[int, Path] = {}
        self._enhanced_written: set[int] = set()
        if enhance is not None:
            # Load up front, so that missing weights stop the chat before any edit is made.
            from drivetwin.worlds.enhance import OnlineEnhancer

            self._enhancer = OnlineEnhancer.from_settings(enhance)
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
            raise SessionError("rendering needs the simulation (run without --no-sim)")
        from drivetwin.worlds.render.hybrid import HybridRenderer, chase_camera, save_frame
        from drivetwin.worlds.sensors import Lidar, save_pointcloud

        target.parent.mkdir(parents=True, exist_ok=True)
        with self.sim.lock:
            if self._renderer is None:
                self._renderer = HybridRenderer(self.sim.world)
            self._attach_packaged_splats(session.scene)
            camera = chase_camera(self.sim.world, "ego", width=FRAME_WIDTH, height=FRAME_HEIGHT)
            frame = self._renderer.render(camera, session.scene.environment)
            points = Lidar(mount="ego").scan(self.sim.world)
        written = list(save_frame(frame, target).values())
        # The environment it was drawn in, so that `drivetwin enhance` prompts each frame right.
        env_path = target.with_name(target.stem + "_env.json")
        env_path.write_text(session.scene.environment.model_dump_json(indent=1), encoding="utf-8")
        written.append(env_path)
        cloud = target.with_name(target.stem + "_lidar.ply")
        save_pointcloud(points, cloud)
        written.append(cloud)
        if self._enhancer is not None:
            written += self._enhance_frame(frame, session, target)
        return written

    def _attach_packaged_splats(self, scene: Scene) -> None:
        """Reconstructed (packaged) assets are drawn as their own splats, riding on their bodies;
        their convex parts stay the collision proxy. Built-in assets are drawn as meshes."""
        from drivetwin.worlds.catalog import category
        from drivetwin.worlds.render.hybrid import asset_splats

        attachments = self._renderer.attachments
        wanted = {a.id: a for a in scene.all_assets() if category(a.category).package is not None}
        for asset_id in [i for i in attachments if i not in wanted]:
            del attachments[asset_id]
        for asset_id, asset in wanted.items():
            if asset_id not in attachments:
                attachments[asset_id] = asset_splats(asset.category, scale=asset.scale)

    def _enhance_frame(self, frame: Any, session: Session, target: Path) -> list[Path]:
        """Hand the frame to the enhancer thread; write whichever enhanced frame is newest.

        The enhancer runs beside the physics: a frame still waiting when the next arrives is
        dropped, never queued, and each finished frame is written beside the frame it came from
        (the baseline when its structure did not hold).
        """
        self._enhanced_targets[self._enhancer.stats().submitted] = target.with_name(target.stem + "_enhanced.png")
        self._enhancer.submit(frame.rgb, frame.depth, session.scene.environment)
        return self._write_enhanced()

    def _write_enhanced(self) -> list[Path]:
        """Write the newest finished enhanced frame if it has not been written yet."""
        from PIL import Image

        latest = self._enhancer.latest() if self._enhancer is not None else None
        if latest is None or latest.index in self._enhanced_written:
            return []
        path = self._enhanced_targets[latest.index]
        Image.fromarray(latest.image).save(path)
        self._enhanced_written.add(latest.index)
        return [path]

    def enhancer_summary(self) -> str | None:
        """What the enhancer did (frames submitted, enhanced, dropped, rejected), if it ran."""
        if self._enhancer is None:
            return None
        s = self._enhancer.stats()
        line = (f"enhancer: {s.submitted} frames submitted, {s.processed} enhanced, {s.dropped} dropped, "
                f"{s.rejected} rejected (baseline kept), {s.errors} errors")
        return line + (f"; last error: {s.last_error}" if s.last_error else "")

    def close(self) -> list[Path]:
        """Stop the physics and the renderer; the enhancer finishes its frame first.

        Returns the enhanced frames written while closing.
        """
        written: list[Path] = []
        if self._enhancer is not None:
            self._enhancer.drain(ENHANCER_DRAIN_S)
            written = self._write_enhanced()
            self._enhancer.stop()
        if self.sim is not None:
            self.sim.stop()
        if self._renderer is not None and hasattr(self._renderer, "close"):
            self._renderer.close()
        return written
