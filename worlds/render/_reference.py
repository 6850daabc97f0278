"""Slow, obviously-correct splat rasterizer: the yardstick every fast backend is tested against.

No tiles, no boxes, no shortcuts: each splat is projected with explicit 3x3 matrices, and
every pixel walks all projected splats in depth order. Use it on tiny scenes only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from drivetwin.worlds.rotation import quat_to_matrix

from .camera import Camera
from .rasterize import (
    ALPHA_MAX,
    ALPHA_MIN,
    FOV_CLAMP,
    LOW_PASS,
    TRANSMITTANCE_MIN,
    RasterOutput,
)
from .splats import Splats, eval_sh_colors

__all__ = ["ProjectedSplat", "project_reference", "rasterize_reference"]


@dataclass
class ProjectedSplat:
    """One splat on the image: id, camera z, pixel centre, inverse 2D covariance, colour."""

    id: int
    depth: float
    uv: npt.NDArray[np.float64]
    conic: npt.NDArray[np.float64]
    opacity: float
    colour: npt.NDArray[np.float64]


def project_reference(splats: Splats, camera: Camera) -> list[ProjectedSplat]:
    """Project each splat; return the ones in front of the camera, in (depth, id) order."""
    view = camera.world_to_camera
    rot_w, trans_w = view[:3, :3], view[:3, 3]
    fx, fy, cx, cy = camera.fx, camera.fy, camera.cx, camera.cy
    tan_x, tan_y = 0.5 * camera.width / fx, 0.5 * camera.height / fy
    centre = camera.position
    projected = []
    for i in range(len(splats)):
        mean = splats.means[i].astype(np.float64)
        x, y, z = rot_w @ mean + trans_w
        opacity = 1.0 / (1.0 + math.exp(-float(splats.opacity_logits[i])))
        if not camera.near < z < camera.far:
            continue
        scale = np.diag(np.exp(splats.log_scales[i].astype(np.float64)))
        rs = quat_to_matrix(splats.quats[i]) @ scale
        cov_world = rs @ rs.T
        cov_cam = rot_w @ cov_world @ rot_w.T
        # Jacobian of the pinhole projection, x/z and y/z clamped just outside the view.
        xz = min((camera.width - cx) / fx + FOV_CLAMP * tan_x, max(-cx / fx - FOV_CLAMP * tan_x, x / z))
        yz = min((camera.height - cy) / fy + FOV_CLAMP * tan_y, max(-cy / fy - FOV_CLAMP * tan_y, y / z))
        jac = np.array([[fx / z, 0.0, -fx * xz / z], [0.0, fy / z, -fy * yz / z]])
        cov2d = jac @ cov_cam @ jac.T + LOW_PASS * np.eye(2)
        if np.linalg.det(cov2d) <= 0:
            continue
        direction = (mean - centre) / np.linalg.norm(mean - centre)
        colour = eval_sh_colors(splats.sh[i : i + 1], direction[None])[0]
        uv = np.array([fx * x / z + cx, fy * y / z + cy])
        projected.append(ProjectedSplat(i, float(z), uv, np.linalg.inv(cov2d), opacity, colour))
    projected.sort(key=lambda s: (s.depth, s.id))
    return projected


def rasterize_reference(
    splats: Splats,
    camera: Camera,
    depth_limit: npt.NDArray[np.float64],
    index_min_alpha: float,
) -> RasterOutput:
    """Per-pixel front-to-back compositing over all projected splats (see ``rasterize``)."""
    projected = project_reference(splats, camera)
    h, w = camera.height, camera.width
    rgb = np.zeros((h, w, 3))
    alpha_img = np.zeros((h, w))
    depth = np.zeros((h, w))
    index = np.full((h, w), -1, np.int32)
    for row in range(h):
        for col in range(w):
            pixel = np.array([col + 0.5, row + 0.5])
            trans, colour, depth_sum = 1.0, np.zeros(3), 0.0
            for s in projected:
                if s.depth >= depth_limit[row, col]:
                    continue
                d = pixel - s.uv
                power = -0.5 * float(d @ s.conic @ d)
                alpha = min(ALPHA_MAX, s.opacity * math.exp(power))
                if alpha < ALPHA_MIN:
                    continue
                if trans * (1.0 - alpha) < TRANSMITTANCE_MIN:
                    break
                colour += alpha * trans * s.colour
                depth_sum += alpha * trans * s.depth
                if index[row, col] < 0 and alpha >= index_min_alpha:
                    index[row, col] = s.id
                trans *= 1.0 - alpha
            rgb[row, col] = colour
            alpha_img[row, col] = 1.0 - trans
            depth[row, col] = depth_sum / (1.0 - trans) if trans < 1.0 else 0.0
    return RasterOutput(
        rgb=rgb.astype(np.float32),
        alpha=alpha_img.astype(np.float32),
        transmittance=(1.0 - alpha_img).astype(np.float32),
        depth=depth.astype(np.float32),
        index=index,
    )
