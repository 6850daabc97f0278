"""The browser view of a live session: a viser server, the scene sync, the panel, and the
loop that moves the browser's world with the simulation.

One ServeApp serves any number of browser tabs; they all watch the same Session (the
journal's only writer) and the same simulation.
"""

from __future__ import annotations

import threading
import time
from pathlib import Path

import numpy as np
import numpy.typing as npt
import viser
from drivetwin.orchestrator.live import LiveWorld
from drivetwin.orchestrator.serve.chat_panel import ChatPanel, PanelActions
from drivetwin.orchestrator.serve.conversation import Conversation
from drivetwin.orchestrator.serve.overlays import Overlays
from drivetwin.orchestrator.serve.scene_sync import PlanarPose, SceneSync
from drivetwin.orchestrator.session import Session
from drivetwin.worlds.scene import EGO_ID

__all__ = ["UPDATE_HZ", "ServeApp", "simulated_poses"]

# Pose updates per second the loop aims for by default: smooth to the eye, and the issue's
# floor is 20. A browser drawing in software (no GPU) redraws at this rate too: lower it there.
UPDATE_HZ = 30.0
MAX_UPDATE_HZ = 120.0
LIDAR_PERIOD_S = 0.5  # a 16-channel scan of 5,760 rays every half second is plenty to look at
# Behind and above the ego for the follow camera, metres: a chase view like the rendered frames.
FOLLOW_BACK_M, FOLLOW_UP_M = 14.0, 6.0
OVERVIEW_HEIGHT_SHARE = 0.6  # the first view looks down from 0.6 x the world's size: all of it in view
DEPTH_SHOWN_MAX_M = 80.0  # the depth image fades to black at this distance


def simulated_poses(live: LiveWorld, session: Session) -> dict[str, PlanarPose]:
    """Every asset's pose now: from the running physics, or the scene's when there is none."""
    sim = live.sim
    if sim is None:
        return {a.id: (a.pose.x, a.pose.y, a.pose.z, a.pose.yaw) for a in session.scene.all_assets()}
    with sim.lock:
        world = sim.world
        return {a.id: world.planar_pose(a.id) for a in world.scene.all_assets()}


class ServeApp:
    """A viser server showing `session` through `live`; `close` stops it (not the session)."""

    def __init__(self, session: Session, live: LiveWorld, *, host: str = "127.0.0.1", port: int = 8080,
                 frames_dir: Path | None = None, save_path: str = "scene.json", update_hz: float = UPDATE_HZ) -> None:
        if not 0.0 < update_hz <= MAX_UPDATE_HZ:
            raise ValueError(f"update rate {update_hz} per second is out of range; give 0 < rate <= {MAX_UPDATE_HZ:g}")
        self.update_hz = update_hz
        self.session = session
        self.live = live
        self.server = viser.ViserServer(host=host, port=port, label="drivetwin", verbose=False)
        self.conversation = Conversation(session)
        self.sync = SceneSync(self.server.scene, self.server.atomic)
        self.sync.on_asset_click = self.select
        self.overlays = Overlays(self.server.scene)
        self.frames_dir = frames_dir or Path("serve_frames")
        self.follow = False
        self.updates_per_s = 0.0
        self._stop = threading.Event()
        self._scene_lock = threading.Lock()  # sync.show and overlay redraws: the loop and the panel
        self.panel = ChatPanel(self.server.gui, PanelActions(
            send=self._send, choose=self._choose, command=self._command, toggle=self._toggle,
            follow_ego=self._follow_ego, render_ego=self.render_ego, clear_selection=lambda: self.select(None),
        ), save_path)  # fmt: skip
        self._refresh_scene()
        self.server.on_client_connect(self._client_connected)
        self._thread = threading.Thread(target=self._loop, name="drivetwin-serve", daemon=True)
        self._thread.start()

    @property
    def url(self) -> str:
        return f"http://{self.server.get_host()}:{self.server.get_port()}"

    # Actions from the panel ----------------------------------------------------------------
    def _after_turn(self) -> None:
        self._refresh_scene()
        self.panel.show_status(self.status_text())
        question = self.conversation.question
        self.panel.show_conversation(self.conversation.shown(),
                                     [r.text for r in question.readings] if question else [])  # fmt: skip

    def _send(self, text: str) -> None:
        self.conversation.send(text)
        self._after_turn()

    def _choose(self, number: int) -> None:
        self.conversation.choose(number)
        self._after_turn()

    def _command(self, word: str, argument: str) -> None:
        self.conversation.command(word, argument)
        self._after_turn()

    def _toggle(self, name: str, on: bool) -> None:
        with self._scene_lock:
            self.overlays.set_enabled(name, on, self.session.scene)
        if name == "lidar" and on:
            self._scan_lidar()

    def _follow_ego(self, on: bool) -> None:
        self.follow = on

    def select(self, asset_id: str | None) -> None:
        """Make `asset_id` the target of 'this' in the next request (None: no target)."""
        self.conversation.selected = asset_id
        with self._scene_lock:
            self.sync.select(asset_id)
        self._show_selected()

    def _show_selected(self) -> None:
        asset_id = self.conversation.selected
        asset = self.session.scene.asset(asset_id) if asset_id else None
        if asset is None:
            self.panel.show_selected("*Click an asset in the view to select it.*")
            return
        pose = self.sync.pose_of(asset.id)
        now = f"now at ({pose[0]:.1f}, {pose[1]:.1f}), yaw {pose[3]:.2f}" if pose else ""
        lines = [f"**{asset.id}** ({asset.category}) — “this” in your next request", "",
                 f"- placed at ({asset.pose.x:.1f}, {asset.pose.y:.1f}), yaw {asset.pose.yaw:.2f}; {now}",
                 f"- scale {asset.scale:g}, mass {asset.physics.mass:g} kg, "
                 f"{'dynamic' if asset.physics.dynamic else 'static'}",
                 f"- behaviour: {asset.behaviour.kind}",
                 f"- appearance: {asset.appearance.material}"
                 + (f", colour {tuple(round(c, 2) for c in asset.appearance.rgba)}" if asset.appearance.rgba else "")]
        if asset.label:
            lines.append(f"- called: {asset.label}")
        self.panel.show_selected("\n".join(lines))

    def render_ego(self) -> None:
        """Render the ego camera with the hybrid renderer and show its RGB and depth."""
        target = self.frames_dir / "ego.png"
        try:
            self.live.render(self.session, target)
        except RuntimeError as exc:  # no simulation (--no-sim): say so where the frame would be
            self.server.add_notification("Cannot render", str(exc), color="red")
            return
        from PIL import Image

        rgb = np.asarray(Image.open(target).convert("RGB"), dtype=np.uint8)
        depth = np.load(target.with_name(target.stem + "_depth.npy"))
        self.panel.show_frame(rgb, _depth_image(depth))

    # The loop ---------------------------------------------------------------------------------
    def _refresh_scene(self) -> None:
        scene = self.session.scene
        with self._scene_lock:
            if scene is self.sync.shown:
                return
            self.sync.show(scene)
            self.overlays.refresh(scene)
        self._show_selected()

    def _client_connected(self, client: viser.ClientHandle) -> None:
        b = self.session.scene.bounds
        size = max(b.xmax - b.xmin, b.ymax - b.ymin)
        cx, cy = b.centre
        client.camera.position = (cx, cy - size * OVERVIEW_HEIGHT_SHARE, size * OVERVIEW_HEIGHT_SHARE)
        client.camera.look_at = (cx, cy, 0.0)

    def _loop(self) -> None:
        period = 1.0 / self.update_hz
        last_scan = 0.0
        window_start, ticks = time.perf_counter(), 0
        due = window_start
        while not self._stop.wait(max(0.0, due - time.perf_counter())):
            # Paced to the clock, not to the end of the last tick: a tick's own cost does not slow the rate.
            due = max(due + period, time.perf_counter() - period)
            self.tick()
            now = time.perf_counter()
            if self.overlays.enabled["lidar"] and now - last_scan >= LIDAR_PERIOD_S:
                self._scan_lidar()
                last_scan = now
            ticks += 1
            if now - window_start >= 1.0:
                self.updates_per_s = ticks / (now - window_start)
                window_start, ticks = now, 0
                self.panel.show_status(self.status_text())

    def tick(self) -> int:
        """One update: a changed scene is redrawn, moved poses sent, the follow camera moved."""
        self._refresh_scene()
        poses = simulated_poses(self.live, self.session)
        with self._scene_lock:
            sent = self.sync.move(poses)
        if self.follow and EGO_ID in poses:
            x, y, z, yaw = poses[EGO_ID]
            for client in self.server.get_clients().values():
                with client.atomic():
                    client.camera.position = (x - FOLLOW_BACK_M * np.cos(yaw), y - FOLLOW_BACK_M * np.sin(yaw),
                                              z + FOLLOW_UP_M)  # fmt: skip
                    client.camera.look_at = (x, y, z + 1.0)
        return sent

    def _scan_lidar(self) -> None:
        sim = self.live.sim
        if sim is None:
            return
        from drivetwin.worlds.sensors import Lidar

        points = Lidar(mount=EGO_ID).scan(sim.world, sim.lock)
        with self._scene_lock:
            self.overlays.show_lidar(points)

    def status_text(self) -> str:
        """The status line: world, asset count, simulated time, update rate, clock and weather."""
        scene = self.sync.shown or self.session.scene
        sim = self.live.sim
        clock = f"t = {sim.time:.1f} s · " if sim is not None else "no physics · "
        weather = scene.environment.weather
        sky = weather.kind if weather.kind == "clear" else f"{weather.kind} {weather.intensity:.1f}"
        return (f"**{scene.name}** · assets: {len(scene.assets)} (+ ego) · {clock}"
                f"{self.updates_per_s:.0f} updates/s · {scene.environment.time_of_day}, {sky}")

    def close(self) -> None:
        """Stop the loop and the web server."""
        self._stop.set()
        self._thread.join()
        self.server.stop()


def _depth_image(depth: npt.NDArray[np.float32]) -> npt.NDArray[np.uint8]:
    """Metric depth [H,W] (inf = sky) as a grey image: near is bright, DEPTH_SHOWN_MAX_M and beyond black."""
    shown = np.clip(1.0 - np.nan_to_num(depth, posinf=DEPTH_SHOWN_MAX_M) / DEPTH_SHOWN_MAX_M, 0.0, 1.0)
    grey = np.round(shown * 255).astype(np.uint8)
    return np.repeat(grey[:, :, None], 3, axis=2)
