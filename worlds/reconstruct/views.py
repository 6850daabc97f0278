"""Posed image sets: the photographs a splat fit learns from, each with its pinhole camera.

A ``PosedImages`` set is what every appearance step consumes: views (an RGB image, float32
in 0..1, and the ``Camera`` that took it) plus an optional sparse coloured point cloud that
seeds the splats. Coordinates are metres in the capture's world frame (z up for drivetwin
captures); cameras follow OpenCV (x right, y down, z forward), as ``Camera`` documents.

Sources: a COLMAP model (``colmap_model.load_colmap``), structure from motion on unposed
photographs (``colmap_model.run_sfm``), the synthetic capture (``capture_views``), or the
poses JSON documented at ``load_poses_json``.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
from drivetwin.worlds.render.camera import Camera, CameraError
from PIL import Image, UnidentifiedImageError

__all__ = [
    "POSES_FORMAT",
    "PosedImages",
    "PosedView",
    "ViewsError",
    "camera_record",
    "load_poses_json",
    "read_image",
    "write_poses_json",
]

F32 = npt.NDArray[np.float32]

POSES_FORMAT = "drivetwin-poses-v1"
# Colours of 8-bit images map to 0..1 by this divisor.
_UINT8_MAX = 255.0


class ViewsError(ValueError):
    """A posed image set, a view or a poses/COLMAP file is malformed or missing."""


def read_image(path: str | Path) -> F32:
    """An image file as float32 RGB [H,W,3] in 0..1 (alpha and palettes dropped)."""
    target = Path(path)
    try:
        with Image.open(target) as img:
            rgb = np.asarray(img.convert("RGB"), dtype=np.float32) / np.float32(_UINT8_MAX)
    except FileNotFoundError as exc:
        raise ViewsError(f"image {target} does not exist") from exc
    except (UnidentifiedImageError, OSError) as exc:
        raise ViewsError(f"cannot read image {target}: {exc}") from exc
    return np.ascontiguousarray(rgb)


@dataclass(frozen=True, eq=False)
class PosedView:
    """One photograph and the camera that took it.

    ``image`` is float32 RGB [H,W,3] in 0..1 with H, W equal to the camera's size;
    ``name`` identifies the view (usually the image's file name).
    """

    name: str
    image: F32 = field(repr=False)
    camera: Camera

    def __post_init__(self) -> None:
        image = np.ascontiguousarray(self.image, dtype=np.float32)
        expected = (self.camera.height, self.camera.width, 3)
        if image.shape != expected:
            raise ViewsError(f"view {self.name!r}: image shape {image.shape} != camera's {expected}")
        if not np.all(np.isfinite(image)) or image.min() < 0.0 or image.max() > 1.0:
            raise ViewsError(f"view {self.name!r}: image values must be finite and in [0, 1]")
        object.__setattr__(self, "image", image)


@dataclass(eq=False)
class PosedImages:
    """Views of one capture plus optional sparse points [N,3] (metres) and colours [N,3] in 0..1."""

    views: list[PosedView]
    points: F32 | None = field(default=None, repr=False)
    colors: F32 | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        if not self.views:
            raise ViewsError("a posed image set needs at least one view")
        names = [v.name for v in self.views]
        if len(set(names)) != len(names):
            raise ViewsError("view names must be unique")
        if (self.points is None) != (self.colors is None):
            raise ViewsError("give both sparse points and their colours, or neither")
        if self.points is not None and self.colors is not None:
            pts = np.ascontiguousarray(self.points, dtype=np.float32)
            col = np.ascontiguousarray(self.colors, dtype=np.float32)
            if pts.ndim != 2 or pts.shape[1] != 3 or col.shape != pts.shape:
                raise ViewsError(f"need points [N,3] and colours [N,3], got {pts.shape}, {col.shape}")
            if not np.all(np.isfinite(pts)) or (col.size and (col.min() < 0 or col.max() > 1)):
                raise ViewsError("sparse points must be finite and colours in [0, 1]")
            self.points, self.colors = pts, col

    def __len__(self) -> int:
        return len(self.views)

    def __iter__(self) -> Iterator[PosedView]:
        return iter(self.views)

    @property
    def cameras(self) -> list[Camera]:
        """The views' cameras, in view order."""
        return [v.camera for v in self.views]

    def split(self, held_out_every: int) -> tuple[PosedImages, PosedImages]:
        """(training, held-out) sets: every k-th view (0, k, 2k, ...) is held out, as in 3DGS.

        Both keep the sparse points. ``held_out_every`` must leave at least one view in each.
        """
        if held_out_every < 2:
            raise ViewsError(f"held_out_every must be >= 2 (1 would hold out every view), got {held_out_every}")
        held = [v for i, v in enumerate(self.views) if i % held_out_every == 0]
        train = [v for i, v in enumerate(self.views) if i % held_out_every != 0]
        if not train or not held:
            raise ViewsError(f"{len(self)} views with held_out_every={held_out_every} leave an empty split")
        return (PosedImages(train, self.points, self.colors), PosedImages(held, self.points, self.colors))

    def scene_extent(self) -> float:
        """Radius (m) of the camera centres around their mean, times 1.1 as 3DGS's normalisation.

        Scales thresholds and learning rates to the capture's size.
        """
        centres = np.stack([c.position for c in self.cameras])
        radius = float(np.max(np.linalg.norm(centres - centres.mean(0), axis=1)))
        return 1.1 * max(radius, 1e-3)


def camera_record(camera: Camera) -> dict[str, Any]:
    """The JSON record of a camera: size, intrinsics (pixels), world_to_camera [4,4], near, far."""
    return {
        "width": camera.width,
        "height": camera.height,
        "fx": camera.fx,
        "fy": camera.fy,
        "cx": camera.cx,
        "cy": camera.cy,
        "world_to_camera": np.asarray(camera.world_to_camera).tolist(),
        "near": camera.near,
        "far": camera.far,
    }


def _camera_from_record(record: dict[str, Any], where: str) -> Camera:
    try:
        return Camera(
            width=int(record["width"]),
            height=int(record["height"]),
            fx=float(record["fx"]),
            fy=float(record["fy"]),
            cx=float(record.get("cx", record["width"] / 2)),
            cy=float(record.get("cy", record["height"] / 2)),
            world_to_camera=np.asarray(record["world_to_camera"], dtype=np.float64),
            near=float(record.get("near", 0.05)),
            far=float(record.get("far", 1000.0)),
        )
    except KeyError as exc:
        raise ViewsError(f"{where}: missing key {exc.args[0]!r}; a view needs width, height, fx, fy, "
                         "world_to_camera (cx, cy, near, far optional)") from exc  # fmt: skip
    except (TypeError, ValueError, CameraError) as exc:
        raise ViewsError(f"{where}: {exc}") from exc


def load_poses_json(path: str | Path, image_root: str | Path | None = None) -> PosedImages:
    """Read a posed image set from the project's poses JSON.

    The file is ``{"format": "drivetwin-poses-v1", "views": [...], "points": [...]}``; each
    view is ``{"name", "image" (a path relative to image_root, default the JSON's folder),
    "width", "height", "fx", "fy", "cx", "cy", "world_to_camera" (4x4 rows, OpenCV camera,
    world metres), optional "near", "far"}``; the optional "points" are rows ``[x, y, z, r,
    g, b]`` with colours in 0..1 (the sparse cloud that seeds the splats).
    """
    target = Path(path)
    try:
        data = json.loads(target.read_text(encoding="utf-8"))
    except FileNotFoundError as exc:
        raise ViewsError(f"poses file {target} does not exist") from exc
    except json.JSONDecodeError as exc:
        raise ViewsError(f"{target} is not valid JSON: {exc.msg} at line {exc.lineno}") from exc
    if not isinstance(data, dict) or data.get("format") != POSES_FORMAT:
        raise ViewsError(f'{target} is not a poses file: expected "format": "{POSES_FORMAT}"')
    views_data = data.get("views")
    if not isinstance(views_data, list) or not views_data:
        raise ViewsError(f'{target}: "views" must be a non-empty list')
    root = Path(image_root) if image_root is not None else target.parent
    views = []
    for i, record in enumerate(views_data):
        where = f"{target} view {i}"
        if not isinstance(record, dict) or "image" not in record:
            raise ViewsError(f'{where}: each view is an object with an "image" path')
        camera = _camera_from_record(record, where)
        name = str(record.get("name", Path(record["image"]).name))
        views.append(PosedView(name, read_image(root / record["image"]), camera))
    points = colors = None
    if data.get("points"):
        rows = np.asarray(data["points"], dtype=np.float32)
        if rows.ndim != 2 or rows.shape[1] != 6:
            raise ViewsError(f'{target}: "points" rows are [x, y, z, r, g, b], got shape {rows.shape}')
        points, colors = rows[:, :3], rows[:, 3:]
    return PosedImages(views, points, colors)


def write_poses_json(images: PosedImages, path: str | Path, *, image_dir: str = "images") -> None:
    """Write ``images`` as a poses JSON plus PNG images in ``image_dir`` beside it."""
    target = Path(path)
    folder = target.parent / image_dir
    folder.mkdir(parents=True, exist_ok=True)
    records = []
    for view in images.views:
        file_name = Path(view.name).with_suffix(".png").name
        pixels = np.clip(np.rint(view.image * _UINT8_MAX), 0, _UINT8_MAX).astype(np.uint8)
        Image.fromarray(pixels).save(folder / file_name)
        records.append({"name": view.name, "image": f"{image_dir}/{file_name}", **camera_record(view.camera)})
    data: dict[str, Any] = {"format": POSES_FORMAT, "views": records}
    if images.points is not None and images.colors is not None:
        data["points"] = np.concatenate([images.points, images.colors], 1).round(6).tolist()
    target.write_text(json.dumps(data, indent=1), encoding="utf-8")
