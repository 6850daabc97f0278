"""Reading JSON that people hand us (scene files, journal lines): bounded, strict, typed errors.

A file must be a regular file (a FIFO or a device would block or never end), at most
`max_bytes` long, UTF-8, standard JSON (no `Infinity` or `NaN`, which pydantic would later
write back as `null`) and nested at most `MAX_JSON_DEPTH` deep (deeper input made the
standard parser raise RecursionError).
"""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path
from typing import Any

# A scene nests about 8 deep (scene > assets > asset > behaviour > waypoints > point);
# 64 leaves room for growth while refusing input built to exhaust the parser.
MAX_JSON_DEPTH = 64
# The largest scene file read: 5,000 assets at about 1 kB each, with room to spare.
MAX_SCENE_FILE_BYTES = 64 * 1024 * 1024
class JsonInputError(ValueError):
    """JSON input that cannot be read: not a regular file, too big, not UTF-8, not JSON, too deep."""


def read_text_file(path: str | Path, what: str, max_bytes: int) -> str:
    """The UTF-8 text of a regular file of at most `max_bytes`; JsonInputError otherwise."""
    target = Path(path)
    try:
        info = os.stat(target)
    except OSError as exc:
        raise JsonInputError(f"cannot read {what} {target}: {exc.strerror}") from exc
    if not stat.S_ISREG(info.st_mode):
        kind = "a folder" if stat.S_ISDIR(info.st_mode) else "not a regular file"
        raise JsonInputError(f"{what} {target} is {kind}; give the path of a regular file")
    if info.st_size > max_bytes:
        raise JsonInputError(f"{what} {target} is {info.st_size:,} bytes; at most {max_bytes:,} are read")
    try:
        with open(target, "rb") as handle:
            data = handle.read(max_bytes + 1)
    except OSError as exc:
        raise JsonInputError(f"cannot read {what} {target}: {exc.strerror}") from exc
    if len(data) > max_bytes:
        raise JsonInputError(f"{what} {target} grew past {max_bytes:,} bytes while being read")
    return decode_utf8(data, f"{what} {target}")


def decode_utf8(data: bytes, source: str) -> str:
    """`data` as text; a byte that is not UTF-8 is a JsonInputError naming its offset."""
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise JsonInputError(
            f"{source} is not UTF-8 text: byte 0x{data[exc.start]:02x} at offset {exc.start}"
        ) from exc


def _refuse_constant(name: str) -> Any:
    raise JsonInputError(f"{name} is not a number JSON allows; use a finite number")


def parse_json(text: str, source: str, max_depth: int = MAX_JSON_DEPTH) -> Any:
    """Parse standard JSON nested at most `max_depth` deep; JsonInputError on anything else."""
    try:
        data = json.loads(text, parse_constant=_refuse_constant)
    except JsonInputError as exc:
        raise JsonInputError(f"{source}: {exc}") from exc
    except json.JSONDecodeError as exc:
        raise JsonInputError(f"{source} is not valid JSON: {exc.msg} at line {exc.lineno}") from exc
    except RecursionError as exc:  # the parser recursed past Python's limit
        raise JsonInputError(f"{source} nests deeper than {max_depth} levels") from exc
    if _too_deep(data, max_depth):
        raise JsonInputError(f"{source} nests deeper than {max_depth} levels")
    return data


def _too_deep(data: Any, max_depth: int) -> bool:
    """Whether containers in `data` nest more than `max_depth` deep (an iterative walk)."""
    if not isinstance(data, dict | list):
        return False
    stack: list[tuple[Any, int]] = [(data, 1)]
    while stack:
        value, depth = stack.pop()
        children = value.values() if isinstance(value, dict) else value
        for child in children:
            if isinstance(child, dict | list):
                if depth + 1 > max_depth:
                    return True
                stack.append((child, depth + 1))
    return False
