"""COLMAP models in and out of posed image sets, and structure from motion with pycolmap.

``load_colmap`` reads a sparse model (cameras, images, points3D; text or binary, any COLMAP
version pycolmap reads) plus its image folder; ``write_colmap`` writes a posed set as a
model (a round trip, and a way to hand captures to other 3DGS tools); ``run_sfm`` poses
unposed photographs with pycolmap's SIFT extraction, exhaustive matching and incremental
mapping. pycolmap is imported inside the functions, so the rest of the package imports
without it.

COLMAP's pixel convention (pixel centres at integer + 0.5, principal point in pixels) and
camera axes (x right, y down, z forward; ``cam_from_world``) are the ``Camera``'s, so poses
copy over unchanged. SfM poses are in COLMAP's own frame: arbitrary origin, rotation and
scale, not metres and not z up, until aligned (e.g. to LIDAR by the fusion step).
"""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

import numpy as np
from drivetwin.worlds.render.camera import Camera

from .views import PosedImages, PosedView, ViewsError, read_image

__all__ = ["SIFT_PEAK_THRESHOLD", "SUPPORTED_CAMERA_MODELS", "load_colmap", "run_sfm", "write_colmap"]

# Pinhole models map to ``Camera`` exactly; distorted ones need undistortion first.
SUPPORTED_CAMERA_MODELS = ("PINHOLE", "SIMPLE_PINHOLE")
# Distortion parameters this small (in COLMAP's units) leave pixels within ~1e-3 px at 1k px.
_NEGLIGIBLE_DISTORTION = 1e-9
_UINT8_MAX = 255.0
# SIFT's contrast threshold, below COLMAP's 0.0067: small images (a few hundred pixels) give
# too few blobs at the default; measured on a 16-view 200x150 ring: 16 of 16 views register
# for 8 seeds, against 12 of 16 for 1 seed in 3 at the default.
SIFT_PEAK_THRESHOLD = 0.004


def _pycolmap() -> Any:
    try:
        import pycolmap
    except ImportError as exc:
        raise ViewsError("COLMAP models and SfM need pycolmap: pip install 'drivetwin[reconstruct]'") from exc
    return pycolmap


def _camera_of(colmap_camera: Any, cam_from_world: Any, name: str) -> Camera:
    model = colmap_camera.model.name
    params = np.asarray(colmap_camera.params, dtype=np.float64)
    if model == "PINHOLE":
        fx, fy, cx, cy = params
    elif model == "SIMPLE_PINHOLE":
        fx, cx, cy = params
        fy = fx
    elif model in ("SIMPLE_RADIAL", "RADIAL", "OPENCV") and np.all(
        np.abs(params[4 if model == "OPENCV" else 3 :]) < _NEGLIGIBLE_DISTORTION
    ):
        fx = params[0]
        fy, cx, cy = (params[1], params[2], params[3]) if model == "OPENCV" else (params[0], params[1], params[2])
    else:
        raise ViewsError(
            f"image {name!r} uses COLMAP camera model {model} with distortion; supported: "
            f"{', '.join(SUPPORTED_CAMERA_MODELS)}. Undistort first (pycolmap.undistort_images or "
            "`colmap image_undistorter`) and load the undistorted model"
        )
    view = np.eye(4)
    view[:3, :] = np.asarray(cam_from_world.matrix(), dtype=np.float64)
    return Camera(width=int(colmap_camera.width), height=int(colmap_camera.height), fx=float(fx), fy=float(fy),
                  cx=float(cx), cy=float(cy), world_to_camera=view)  # fmt: skip


def _from_reconstruction(reconstruction: Any, image_dir: Path) -> PosedImages:
    views = []
    for image_id in sorted(reconstruction.reg_image_ids()):
        image = reconstruction.image(image_id)
        camera = _camera_of(reconstruction.camera(image.camera_id), image.cam_from_world(), image.name)
        pixels = read_image(image_dir / image.name)
        if pixels.shape[:2] != (camera.height, camera.width):
            raise ViewsError(f"image {image.name!r} is {pixels.shape[1]}x{pixels.shape[0]} but its COLMAP "
                             f"camera is {camera.width}x{camera.height}; use the images the model was made from")  # fmt: skip
        views.append(PosedView(image.name, pixels, camera))
    if not views:
        raise ViewsError("the COLMAP model has no registered images")
    # In id order: the order they were added, so a written set reads back as it was.
    points3d = [reconstruction.point3D(i) for i in sorted(reconstruction.point3D_ids())]
    if points3d:
        points = np.stack([p.xyz for p in points3d]).astype(np.float32)
        colors = np.stack([p.color for p in points3d]).astype(np.float32) / np.float32(_UINT8_MAX)
        return PosedImages(views, points, colors)
    return PosedImages(views)


def load_colmap(model_dir: str | Path, image_dir: str | Path) -> PosedImages:
    """A posed image set from a COLMAP sparse model folder and the folder of its images.

    ``model_dir`` holds cameras/images/points3D as .txt or .bin (e.g. ``sparse/0``); image
    names in the model are paths relative to ``image_dir``. Pinhole camera models only (see
    ``SUPPORTED_CAMERA_MODELS``); the sparse points become the set's coloured points.
    """
    pycolmap = _pycolmap()
    folder = Path(model_dir)
    has_model = any((folder / f"images.{ext}").exists() for ext in ("txt", "bin"))
    if not folder.is_dir() or not has_model:
        raise ViewsError(f"{folder} is not a COLMAP model folder (needs cameras, images, points3D .txt or .bin)")
    try:
        reconstruction = pycolmap.Reconstruction(str(folder))
    except (RuntimeError, ValueError) as exc:
        raise ViewsError(f"cannot read the COLMAP model in {folder}: {exc}") from exc
    return _from_reconstruction(reconstruction, Path(image_dir))


def write_colmap(images: PosedImages, model_dir: str | Path, *, binary: bool = False) -> None:
    """Write ``images`` as a COLMAP model (PINHOLE cameras, one per view; sparse points with empty tracks).

    Images themselves are not written; their names are the model's image names.
    """
    pycolmap = _pycolmap()
    reconstruction = pycolmap.Reconstruction()
    for index, view in enumerate(images.views, start=1):
        cam = view.camera
        colmap_camera = pycolmap.Camera(camera_id=index, model="PINHOLE", width=cam.width, height=cam.height,
                                        params=[cam.fx, cam.fy, cam.cx, cam.cy])  # fmt: skip
        reconstruction.add_camera_with_trivial_rig(colmap_camera)
        rotation = pycolmap.Rotation3d(np.asarray(cam.world_to_camera[:3, :3]))
        pose = pycolmap.Rigid3d(rotation, np.asarray(cam.world_to_camera[:3, 3]))
        image = pycolmap.Image(name=view.name, camera_id=index, image_id=index)
        reconstruction.add_image_with_trivial_frame(image, pose)
    if images.points is not None and images.colors is not None:
        rgb = np.clip(np.rint(images.colors * _UINT8_MAX), 0, _UINT8_MAX).astype(np.uint8)
        for xyz, color in zip(images.points.astype(np.float64), rgb, strict=True):
            reconstruction.add_point3D(xyz, pycolmap.Track(), color)
    folder = Path(model_dir)
    folder.mkdir(parents=True, exist_ok=True)
    (reconstruction.write_binary if binary else reconstruction.write_text)(str(folder))


def run_sfm(
    image_dir: str | Path,
    work_dir: str | Path,
    *,
    intrinsics: tuple[float, float, float, float] | None = None,
    max_image_size: int = 1600,
    num_threads: int = -1,
    seed: int = 0,
) -> PosedImages:
    """Pose unposed photographs by structure from motion (pycolmap, CPU) and read the result.

    Runs SIFT feature extraction (one camera shared by all images), exhaustive matching
    (every pair: sequential matching of a 16-view ring registered 4 views, since views two
    steps apart share no matches) and incremental mapping into ``work_dir`` (database.db
    and sparse/N), keeps the largest model and returns its registered views with the sparse
    points. ``intrinsics``
    (fx, fy, cx, cy in pixels) fixes a known PINHOLE camera; without them the camera is
    SIMPLE_PINHOLE (one focal length, principal point at the image centre), its focal length
    estimated from the images. Poses are in COLMAP's arbitrary frame and scale. Raises
    ``ViewsError`` for bad arguments or when no model could be built (too few images,
    features or overlaps).
    """
    pycolmap = _pycolmap()
    if intrinsics is not None and (len(intrinsics) != 4 or min(intrinsics[:2]) <= 0):
        raise ViewsError(f"intrinsics must be (fx, fy, cx, cy) in pixels with fx, fy > 0, not {intrinsics}")
    images = Path(image_dir)
    if not images.is_dir() or not any(images.iterdir()):
        raise ViewsError(f"{images} is not a folder of images")
    work = Path(work_dir)
    work.mkdir(parents=True, exist_ok=True)
    database = work / "database.db"
    if database.exists():
        database.unlink()  # a stale database would mix in another capture's features
    sparse = work / "sparse"
    shutil.rmtree(sparse, ignore_errors=True)
    sparse.mkdir()
    pycolmap.set_random_seed(seed)
    reader = pycolmap.ImageReaderOptions()
    # Without distortion terms the model maps straight to a ``Camera``; one focal length
    # (square pixels, as in nearly every camera) is far better conditioned than fx and fy
    # on a small capture.
    reader.camera_model = "SIMPLE_PINHOLE"
    if intrinsics is not None:
        reader.camera_model = "PINHOLE"
        reader.camera_params = ",".join(f"{float(value):.10g}" for value in intrinsics)
    extraction = pycolmap.FeatureExtractionOptions()
    extraction.max_image_size = max_image_size
    extraction.num_threads = num_threads
    extraction.use_gpu = False
    extraction.sift.peak_threshold = SIFT_PEAK_THRESHOLD
    pycolmap.extract_features(database, images, camera_mode=pycolmap.CameraMode.SINGLE, reader_options=reader,
                              extraction_options=extraction, device=pycolmap.Device.cpu)  # fmt: skip
    pycolmap.match_exhaustive(database, device=pycolmap.Device.cpu)
    options = pycolmap.IncrementalPipelineOptions()
    options.num_threads = num_threads
    options.random_seed = seed
    if intrinsics is not None:
        options.ba_refine_focal_length = False  # known, so bundle adjustment keeps it
    models = pycolmap.incremental_mapping(database, images, sparse, options=options)
    if not models:
        raise ViewsError(f"structure from motion posed no images in {images}: need overlapping, textured "
                         "photographs (SIFT features matched across several views)")  # fmt: skip
    best = max(models.values(), key=lambda r: r.num_reg_images())
    return _from_reconstruction(best, images)
