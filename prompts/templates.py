"""The managers' prompt templates and few-shot examples, loaded from the versioned files here.

Templates are plain text with `$name` placeholders (string.Template, so JSON braces need no
escaping). `prompt_version()` names the manifest version plus a hash of every file, so an
eval result always says exactly which prompts produced it.
"""

from __future__ import annotations

import hashlib
import json
from functools import cache
from importlib import resources
from string import Template
from typing import Any

from pydantic import BaseModel, ConfigDict, TypeAdapter

MANIFEST = "manifest.json"
# Hex digits of the content hash kept in the version string: enough to tell edits apart.
HASH_CHARS = 8


class PromptFileError(Exception):
    """A prompt file is missing or malformed; the message names the file and the problem."""


class SrExample(BaseModel):
    """One few-shot example for the Sr. manager: a request and its requirements."""

    model_config = ConfigDict(extra="forbid")

    request: str
    requirements: list[dict[str, str]]


class JrExample(BaseModel):
    """One few-shot example for a Jr. manager: a rendered requirement and its tool call."""

    model_config = ConfigDict(extra="forbid")

    requirement: str
    call: dict[str, Any]


class _Manifest(BaseModel):
    model_config = ConfigDict(extra="forbid")

    version: str
    note: str = ""
    files: list[str]


def _read(name: str) -> str:
    try:
        return resources.files("drivetwin.prompts").joinpath(name).read_text(encoding="utf-8")
    except (FileNotFoundError, OSError) as exc:
        raise PromptFileError(f"prompt file {name!r} is missing from drivetwin.prompts") from exc


@cache
def _manifest() -> _Manifest:
    try:
        return _Manifest.model_validate_json(_read(MANIFEST))
    except ValueError as exc:
        raise PromptFileError(f"{MANIFEST} is malformed: {exc}") from exc


@cache
def prompt_version() -> str:
    """The prompts' version: the manifest's version and a hash of every listed file."""
    manifest = _manifest()
    digest = hashlib.sha256()
    for name in manifest.files:
        digest.update(name.encode())
        digest.update(_read(name).encode())
    return f"prompts-v{manifest.version}+{digest.hexdigest()[:HASH_CHARS]}"


@cache
def template(name: str) -> Template:
    """The template in `name` (a file listed in the manifest)."""
    if name not in _manifest().files:
        raise PromptFileError(f"{name!r} is not listed in {MANIFEST}; listed: {_manifest().files}")
    return Template(_read(name))


def render(name: str, **values: str) -> str:
    """The template `name` with its `$placeholders` filled; a missing value is an error."""
    try:
        return template(name).substitute(values).strip()
    except KeyError as exc:
        raise PromptFileError(f"{name} needs a value for ${exc.args[0]}") from exc


@cache
def sr_examples() -> tuple[SrExample, ...]:
    """The Sr. manager's few-shot examples."""
    try:
        items = TypeAdapter(list[SrExample]).validate_json(_read("sr_examples.json"))
    except ValueError as exc:
        raise PromptFileError(f"sr_examples.json is malformed: {exc}") from exc
    return tuple(items)


@cache
def jr_examples() -> dict[str, tuple[JrExample, ...]]:
    """The Jr. managers' few-shot examples, by tool family."""
    try:
        raw = TypeAdapter(dict[str, list[JrExample]]).validate_json(_read("jr_examples.json"))
    except ValueError as exc:
        raise PromptFileError(f"jr_examples.json is malformed: {exc}") from exc
    return {family: tuple(items) for family, items in raw.items()}


def as_json(value: Any) -> str:
    """Compact JSON, the way examples and answers are shown to the model."""
    return json.dumps(value, separators=(",", ":"), ensure_ascii=False)


__all__ = [
    "JrExample",
    "PromptFileError",
    "SrExample",
    "as_json",
    "jr_examples",
    "prompt_version",
    "render",
    "sr_examples",
    "template",
]
