"""Offline enhancement of a folder of rendered frames, resumable after an interruption.

Layout read from SRC: every PNG/JPEG frame (sorted by name; the renderer's `*_depth.png`
previews and earlier `*_enhanced.png` outputs are not frames); optional `<stem>.depth.npy` or
`<stem>_depth.npy` beside a frame (float [H, W], metres; what `drivetwin chat --render-each`
and `drivetwin demo` write) for the depth ControlNet and the silhouette check; the
environment that builds the prompts comes from `<stem>_env.json` beside the frame (written
per frame by the renderer), else from the folder's `scene.json`. Written to OUT: `<stem>.png` per frame (the enhanced frame,
or the baseline where the enhancement was rejected), `frames.jsonl` with one record per
finished frame, and `report.json`. A frame is finished once its record is in frames.jsonl;
a rerun skips finished frames, so an interrupted run resumes where it stopped.
"""

from __future__ import annotations

import json
import os
import tempfile
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np
from drivetwin.worlds.enhance.online import SupportsEnhance
from drivetwin.worlds.enhance.pipeline import FrameEnhancer
from drivetwin.worlds.enhance.settings import EnhanceInputError, EnhanceSettings
from drivetwin.worlds.progress import progress_bar
from drivetwin.worlds.scene import Environment, Scene
from numpy.typing import NDArray
from PIL import Image

IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg")
DEPTH_SUFFIXES = (".depth.npy", "_depth.npy")
ENV_SUFFIX = "_env.json"
# Images beside the frames that are not frames: depth previews and enhanced outputs.
NOT_FRAME_STEMS = ("_depth", "_enhanced")
RECORDS_FILE = "frames.jsonl"
REPORT_FILE = "report.json"
SCENE_FILE = "scene.json"


@dataclass(frozen=True)
class EnhanceReport:
    """Outcome of enhancing a folder (all finished frames, this run and earlier ones)."""

    source: str
    output: str
    frames_total: int
    frames_done: int
    frames_this_run: int
    frames_skipped: int
    rejected: int
    rejection_rate: float
    mean_edge_ssim: float | None
    mean_edge_ssim_worst_tile: float | None
    mean_luminance_ssim: float | None
    mean_depth_disagreement: float | None
    seconds_per_frame: float | None
    model: str
    strength: float
    steps: int
    guidance: float

    def to_json(self) -> str:
        """The report as indented JSON."""
        return json.dumps(asdict(self), indent=2)


def default_output_dir(src_dir: str | Path) -> Path:
    """Where `drivetwin enhance DIR` writes when no output folder is given: DIR-enhanced."""
    src = Path(src_dir)
    return src.parent / f"{src.name}-enhanced"


def _atomic_write(path: Path, write: Any) -> None:
    """Write via a temporary file in the same folder, then rename: never a half file."""
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as handle:
            write(handle)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _read_records(path: Path) -> dict[str, dict[str, Any]]:
    records: dict[str, dict[str, Any]] = {}
    if not path.exists():
        return records
    for line in path.read_text(encoding="utf-8").splitlines():
        try:
            record = json.loads(line)
        except json.JSONDecodeError:
            continue  # a line cut short by an interruption: that frame is simply redone
        if isinstance(record, dict) and isinstance(record.get("name"), str):
            records[record["name"]] = record
    return records


def _frame_files(src: Path) -> list[Path]:
    return sorted(
        p
        for p in src.iterdir()
        if p.is_file() and p.suffix.lower() in IMAGE_SUFFIXES and not p.stem.endswith(NOT_FRAME_STEMS)
    )


def _frame_environment(frame: Path, folder_env: Environment | None, override: Environment | None) -> Environment | None:
    """The environment the frame was rendered in: the override, its own `_env.json`, the folder's."""
    if override is not None:
        return override
    own = frame.with_name(frame.stem + ENV_SUFFIX)
    if own.exists():
        return Environment.model_validate_json(own.read_text(encoding="utf-8"))
    return folder_env


def _environment(src: Path, env: Environment | None) -> Environment | None:
    if env is not None or not (src / SCENE_FILE).exists():
        return env
    return Scene.load(src / SCENE_FILE).environment


def _mean(records: list[dict[str, Any]], key: str) -> float | None:
    values = [float(r[key]) for r in records if r.get(key) is not None]
    return float(np.mean(values)) if values else None


def _load_frame(path: Path) -> tuple[NDArray[np.uint8], NDArray[np.float32] | None]:
    with Image.open(path) as im:
        frame = np.asarray(im.convert("RGB"), dtype=np.uint8)
    for suffix in DEPTH_SUFFIXES:
        depth_path = path.with_name(path.stem + suffix)
        if depth_path.exists():
            return frame, np.load(depth_path).astype(np.float32)
    return frame, None


def enhance_folder(
    src_dir: str | Path,
    out_dir: str | Path,
    settings: EnhanceSettings,
    progress: bool = True,
    *,
    env: Environment | None = None,
    enhancer: SupportsEnhance | None = None,
) -> EnhanceReport:
    """Enhance every frame in `src_dir` into `out_dir`, skipping frames already finished.

    env overrides the environment of `src_dir/scene.json`; enhancer (default: a
    FrameEnhancer loaded from `settings`) is only loaded when some frame is left to do.
    """
    src, out = Path(src_dir), Path(out_dir)
    if not src.is_dir():
        raise EnhanceInputError(f"'{src}' is not a folder of rendered frames")
    if src.resolve() == out.resolve():
        raise EnhanceInputError("the output folder must differ from the source folder")
    files = _frame_files(src)
    if not files:
        raise EnhanceInputError(f"'{src}' holds no {', '.join(IMAGE_SUFFIXES)} frames")
    out.mkdir(parents=True, exist_ok=True)
    records_path = out / RECORDS_FILE
    records = _read_records(records_path)
    todo = [f for f in files if not (f.stem in records and (out / f"{f.stem}.png").exists())]
    environment = _environment(src, env)
    done_now = 0
    if todo:
        worker = enhancer if enhancer is not None else FrameEnhancer(settings)
        with records_path.open("a", encoding="utf-8") as log, \
                progress_bar("enhance", len(todo), "frames", enabled=progress) as bar:
            for file in todo:
                frame, depth = _load_frame(file)
                result = worker.enhance(frame, depth, _frame_environment(file, environment, env))
                target = out / f"{file.stem}.png"
                _atomic_write(
                    target, lambda h, img=result.image: Image.fromarray(img).save(h, "PNG")
                )
                score = result.score
                record = {"name": file.stem, "accepted": result.accepted, "seconds": result.seconds}
                record.update(
                    edge_ssim=score.edge_ssim,
                    edge_ssim_worst_tile=score.edge_ssim_worst_tile,
                    luminance_ssim=score.luminance_ssim,
                    depth_disagreement=score.depth_disagreement,
                    structure_distance=score.structure_distance,
                    reason=score.reason,
                )
                # The record goes last: a frame whose record is missing is redone on resume.
                log.write(json.dumps(record) + "\n")
                log.flush()
                records[file.stem] = record
                done_now += 1
                bar.advance(note=file.name)
    names = {f.stem for f in files}
    finished = [r for name, r in records.items() if name in names]
    rejected = sum(1 for r in finished if not r["accepted"])
    report = EnhanceReport(
        source=str(src),
        output=str(out),
        frames_total=len(files),
        frames_done=len(finished),
        frames_this_run=done_now,
        frames_skipped=len(files) - len(todo),
        rejected=rejected,
        rejection_rate=rejected / len(finished) if finished else 0.0,
        mean_edge_ssim=_mean(finished, "edge_ssim"),
        mean_edge_ssim_worst_tile=_mean(finished, "edge_ssim_worst_tile"),
        mean_luminance_ssim=_mean(finished, "luminance_ssim"),
        mean_depth_disagreement=_mean(finished, "depth_disagreement"),
        seconds_per_frame=_mean(finished, "seconds"),
        model=settings.model,
        strength=settings.effective_strength(),
        steps=settings.steps,
        guidance=settings.guidance,
    )
    _atomic_write(out / REPORT_FILE, lambda h: h.write(report.to_json().encode("utf-8")))
    return report
