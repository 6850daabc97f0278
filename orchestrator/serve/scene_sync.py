"""Keeps a viser scene showing a Scene and the simulated poses of its assets.

The still world (ground, roads, buildings) and the asset layout are rebuilt only when the
Scene changes; between changes only poses move. Assets are drawn batched: one instanced
mesh per (category, part), so a tick sends one message per batch in which something
moved, never one per asset. Reconstructed (packaged) assets and world packages are drawn as
Gaussian splats, as the hybrid renderer draws them.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from contextlib import AbstractContextManager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
import viser
import viser.transforms as vtf
from drivetwin.orchestrator.serve.world_layer import environment_view, sun_position, world_surfaces
from drivetwin.worlds.catalog import category
from drivetwin.worlds.meshes import part_mesh
from drivetwin.worlds.mujoco_bodies import part_rgba
from drivetwin.worlds.packages import SPLATS_FILE, package_splats
from drivetwin.worlds.render.splats import SH_C0, Splats
from drivetwin.worlds.rotation import yaw_quats
from drivetwin.worlds.scene import AssetInstance, Environment, Scene

__all__ = ["PlanarPose", "SceneSync", "SyncStats", "splat_arrays"]

F64 = npt.NDArray[np.float64]
PlanarPose = tuple[float, float, float, float]  # (x, y, z, yaw): what MujocoWorld.planar_pose reads
# A pose that moved less than this is not sent: a millimetre or a milliradian is invisible
# at street scale, and parked bodies jitter by less while they settle.
POSITION_TOLERANCE_M = 1e-3
YAW_TOLERANCE_RAD = 1e-3
SUN_DISTANCE_M = 200.0  # where the sun light sits; a directional light only uses the direction
SELECTION_LABEL_HEIGHT_M = 2.5  # the selected asset's label floats this far above its origin


@dataclass
class SyncStats:
    """What the sync has sent: batches of poses, assets moved, full rebuilds."""

    ticks: int = 0
    batches_sent: int = 0
    assets_moved: int = 0
    rebuilds: int = 0


@dataclass
class _Batch:
    """One instanced node: a part of a category, or one splat asset; `rows` index the pose arrays."""

    handle: viser.BatchedMeshHandle | viser.GaussianSplatHandle
    rows: npt.NDArray[np.intp]
    asset_ids: list[str]


@dataclass
class _Layout:
    """The assets of the shown scene, in the order of the pose arrays."""

    ids: list[str] = field(default_factory=list)
    positions: F64 = field(default_factory=lambda: np.zeros((0, 3)))
    yaws: F64 = field(default_factory=lambda: np.zeros(0))


def splat_arrays(splats: Splats) -> tuple[F64, F64, F64, F64]:
    """Centres [N,3], covariances [N,3,3], colours [N,3] in 0..1 and opacities [N,1] of splats."""
    rotations = vtf.SO3(splats.quats / np.linalg.norm(splats.quats, axis=1, keepdims=True)).as_matrix()
    variances = np.exp(2.0 * splats.log_scales.astype(np.float64))
    covariances = np.einsum("nij,nj,nkj->nik", rotations, variances, rotations)
    colours = np.clip(0.5 + SH_C0 * splats.sh[:, 0, :].astype(np.float64), 0.0, 1.0)
    return (splats.means.astype(np.float64), covariances, colours,
            splats.opacities.astype(np.float64)[:, None])  # fmt: skip


def _layout_key(scene: Scene) -> tuple[object, ...]:
    """What decides the batches: which assets, their categories, scales and colours (not poses)."""
    return tuple((a.id, a.category, a.scale, a.appearance.rgba) for a in scene.all_assets())


class SceneSync:
    """Draws a Scene in a viser scene and moves its assets to the simulated poses.

    Args:
        scene_api: the server's `scene` (shared by every browser tab).
        atomic: the server's `atomic` context, so a tick's pose updates land together.
    """

    def __init__(self, scene_api: viser.SceneApi, atomic: Callable[[], AbstractContextManager[None]]) -> None:
        self.api = scene_api
        self.atomic = atomic
        self.stats = SyncStats()
        self.shown: Scene | None = None
        self.on_asset_click: Callable[[str], None] | None = None
        self._world_key: tuple[object, ...] | None = None
        self._layout_key: tuple[object, ...] | None = None
        self._environment: Environment | None = None
        self._world_nodes: list[viser.SceneNodeHandle] = []
        self._batches: dict[str, _Batch] = {}
        self._layout = _Layout()
        self._row_of: dict[str, int] = {}
        self._lights: list[viser.SceneNodeHandle] = []
        self._selection: viser.LabelHandle | None = None
        self.selected: str | None = None
        scene_api.set_up_direction("+z")
        scene_api.configure_default_lights(enabled=False)

    # Scene changes -----------------------------------------------------------------------
    def show(self, scene: Scene) -> None:
        """Make the browser show `scene`: rebuild what changed (world, layout, environment)."""
        with self.atomic():
            world_key = (scene.bounds, scene.ground, scene.roads, tuple(scene.buildings), scene.package)
            if world_key != self._world_key:
                self._build_world(scene)
                self._world_key = world_key
            layout_key = _layout_key(scene)
            if layout_key != self._layout_key:
                self._build_assets(scene)
                self._layout_key = layout_key
                self.stats.rebuilds += 1
            if scene.environment != self._environment:
                self._show_environment(scene.environment)
                self._environment = scene.environment
            if self.selected is not None and scene.asset(self.selected) is None:
                self.select(None)
        self.shown = scene

    def _build_world(self, scene: Scene) -> None:
        for node in self._world_nodes:
            node.remove()
        self._world_nodes = []
        for surface in world_surfaces(scene):
            self._world_nodes.append(self.api.add_mesh_simple(
                f"/world/{surface.name}", surface.mesh.vertices, surface.mesh.faces, color=surface.rgb,
                flat_shading=True, side="double", cast_shadow=False))  # fmt: skip
        if scene.package is not None and (Path(scene.package) / SPLATS_FILE).is_file():
            centres, covariances, colours, opacities = splat_arrays(package_splats(scene.package))
            self._world_nodes.append(
                self.api.add_gaussian_splats("/world/background_splats", centres, covariances, colours, opacities))

    def _build_assets(self, scene: Scene) -> None:
        for batch in self._batches.values():
            batch.handle.remove()
        self._batches = {}
        assets = scene.all_assets()
        self._layout = _Layout(
            ids=[a.id for a in assets],
            positions=np.asarray([(a.pose.x, a.pose.y, a.pose.z) for a in assets], dtype=np.float64).reshape(-1, 3),
            yaws=np.asarray([a.pose.yaw for a in assets], dtype=np.float64),
        )
        self._row_of = {asset_id: row for row, asset_id in enumerate(self._layout.ids)}
        groups: dict[str, list[AssetInstance]] = {}
        for asset in assets:
            groups.setdefault(asset.category, []).append(asset)
        for name, members in sorted(groups.items()):
            rows = np.asarray([self._row_of[a.id] for a in members], dtype=np.intp)
            if category(name).package is not None:
                for asset, row in zip(members, rows, strict=True):
                    self._add_splat_asset(asset, int(row))
                continue
            for index, part in enumerate(category(name).parts):
                mesh = part_mesh(part)
                colours = np.asarray([part_rgba(part, a)[:3] for a in members], dtype=np.float64)
                node = f"/assets/{name}/part_{index}"
                handle = self.api.add_batched_meshes_simple(
                    node, mesh.vertices, mesh.faces,
                    batched_wxyzs=yaw_quats(self._layout.yaws[rows]),
                    batched_positions=self._layout.positions[rows],
                    batched_scales=np.asarray([a.scale for a in members], dtype=np.float64),
                    batched_colors=np.round(colours * 255).astype(np.uint8), lod="off")  # fmt: skip
                self._batches[node] = _Batch(handle, rows, [a.id for a in members])
                handle.on_click(self._clicked(node))

    def _add_splat_asset(self, asset: AssetInstance, row: int) -> None:
        from drivetwin.worlds.render.hybrid import asset_splats

        centres, covariances, colours, opacities = splat_arrays(asset_splats(asset.category, scale=asset.scale))
        node = f"/splat_assets/{asset.id}"
        handle = self.api.add_gaussian_splats(
            node, centres, covariances, colours, opacities,
            wxyz=yaw_quats(self._layout.yaws[row : row + 1])[0], position=self._layout.positions[row])  # fmt: skip
        self._batches[node] = _Batch(handle, np.asarray([row], dtype=np.intp), [asset.id])
        handle.on_click(self._clicked(node))

    def _clicked(self, node: str) -> Callable[[viser.SceneNodePointerEvent[Any]], None]:
        def on_click(event: viser.SceneNodePointerEvent[Any]) -> None:
            asset_id = self.asset_at(node, event.instance_index)
            if asset_id is not None and self.on_asset_click is not None:
                self.on_asset_click(asset_id)

        return on_click

    def asset_at(self, node: str, instance: int | None) -> str | None:
        """The asset id drawn as instance `instance` of node `node` (None: not an asset)."""
        batch = self._batches.get(node)
        if batch is None:
            return None
        index = 0 if instance is None else instance
        return batch.asset_ids[index] if 0 <= index < len(batch.asset_ids) else None

    def _show_environment(self, environment: Environment) -> None:
        view = environment_view(environment)
        for light in self._lights:
            light.remove()
        self.api.set_background_image(view.sky, format="png")
        self._lights = [
            self.api.add_light_directional("/lights/sun", color=view.sun_rgb, intensity=view.sun_intensity,
                                           position=sun_position(view.to_sun, SUN_DISTANCE_M)),
            self.api.add_light_ambient("/lights/ambient", color=view.ambient_rgb, intensity=view.ambient_intensity),
        ]
        self.api.configure_fog(view.fog_near, view.fog_far, color=view.fog_rgb)

    # Poses -------------------------------------------------------------------------------
    def move(self, poses: Mapping[str, PlanarPose]) -> int:
        """Send the poses that changed, one message per batch that holds one; the batches sent."""
        layout = self._layout
        if not layout.ids:
            return 0
        new_positions = layout.positions.copy()
        new_yaws = layout.yaws.copy()
        for asset_id, (x, y, z, yaw) in poses.items():
            row = self._row_of.get(asset_id)
            if row is not None:
                new_positions[row] = (x, y, z)
                new_yaws[row] = yaw
        turned = np.abs(np.angle(np.exp(1j * (new_yaws - layout.yaws))))
        moved = (np.abs(new_positions - layout.positions).max(axis=1) > POSITION_TOLERANCE_M) | (
            turned > YAW_TOLERANCE_RAD)
        self.stats.ticks += 1
        if not moved.any():
            return 0
        layout.positions, layout.yaws = new_positions, new_yaws
        sent = 0
        with self.atomic():
            for batch in self._batches.values():
                if not moved[batch.rows].any():
                    continue
                handle = batch.handle
                if isinstance(handle, viser.BatchedMeshHandle):
                    handle.batched_positions = new_positions[batch.rows].astype(np.float32)
                    handle.batched_wxyzs = yaw_quats(new_yaws[batch.rows]).astype(np.float32)
                else:
                    handle.position = new_positions[batch.rows[0]]
                    handle.wxyz = yaw_quats(new_yaws[batch.rows[:1]])[0]
                sent += 1
            self._place_selection()
        self.stats.batches_sent += sent
        self.stats.assets_moved += int(moved.sum())
        return sent

    def pose_of(self, asset_id: str) -> PlanarPose | None:
        """The pose last sent for an asset (None if it is not shown)."""
        row = self._row_of.get(asset_id)
        if row is None:
            return None
        x, y, z = self._layout.positions[row]
        return float(x), float(y), float(z), float(self._layout.yaws[row])

    def instance_count(self) -> int:
        """How many assets (ego included) the browser shows."""
        return len(self._layout.ids)

    # Selection ---------------------------------------------------------------------------
    def select(self, asset_id: str | None) -> None:
        """Mark `asset_id` (None: nothing) with a label that follows it."""
        self.selected = asset_id
        if self._selection is not None:
            self._selection.remove()
            self._selection = None
        if asset_id is not None and asset_id in self._row_of:
            self._selection = self.api.add_label("/selection", f"▼ {asset_id}", font_size_mode="screen")
            self._place_selection()

    def _place_selection(self) -> None:
        if self._selection is None or self.selected is None:
            return
        pose = self.pose_of(self.selected)
        if pose is not None:
            self._selection.position = (pose[0], pose[1], pose[2] + SELECTION_LABEL_HEIGHT_M)

