"""Finds backend plugins (entry-point group `drivetwin.backends`) and opens one by name.

A plugin is an entry point whose object is a `Backend` subclass:

    [project.entry-points."drivetwin.backends"]
    mybackend = "my_package.module:MyBackend"

The built-in backends are registered the same way and, so that a checkout works before it
is reinstalled, also listed in a fallback table. They load through the one plugin loader
(drivetwin.tools.plugins): a plugin that fails to import is reported as a PluginProblem
(`plugin_problems()`, `list_backends()`, a logged warning) and skipped, never fatal.
"""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING, Any

from drivetwin.tools.plugins import BACKENDS_GROUP, PluginProblem, load_group

from .base import Backend, BackendStatus
from .errors import BackendError, BackendUnavailable, InvalidRequest, UnknownBackend

if TYPE_CHECKING:
    from ..config import Settings

_BUILTIN_BACKENDS = {
    "embedded": "drivetwin.orchestrator.backends.embedded:EmbeddedBackend",
    "ollama": "drivetwin.orchestrator.backends.ollama_backend:OllamaBackend",
    "openai": "drivetwin.orchestrator.backends.openai_backend:OpenAIBackend",
}
_log = logging.getLogger(__name__)


def _backend_class(loaded: object) -> type[Backend]:
    if not (isinstance(loaded, type) and issubclass(loaded, Backend)):
        raise TypeError(f"{loaded!r} is not a drivetwin Backend subclass")
    return loaded


def discover_backends() -> tuple[dict[str, type[Backend]], list[PluginProblem]]:
    """Load every backend plugin; return the good ones by name and the broken ones."""
    found = load_group(BACKENDS_GROUP, _backend_class, builtins=_BUILTIN_BACKENDS)
    for problem in found.problems:
        _log.warning("skipping backend plugin %s: %s", problem.entry_point, problem.error)
    return {name: plugin.value for name, plugin in found.by_name().items()}, found.problems


def backend_names() -> list[str]:
    """Names of the backends that load."""
    return sorted(discover_backends()[0])


def plugin_problems() -> list[PluginProblem]:
    """Backend plugins that are installed but broken."""
    return discover_backends()[1]


def load_backend(name: str, model: str | None = None, **options: Any) -> Backend:
    """Open backend `name` with `model` (None: the backend's default) and its options."""
    found, problems = discover_backends()
    if name not in found:
        broken = next((p for p in problems if p.name == name), None)
        if broken is not None:
            raise BackendUnavailable(
                f"backend plugin {name!r} is installed but broken ({broken.error})",
                fix=broken.fix,
                backend=name,
            )
        raise UnknownBackend(name, list(found))
    cls = found[name]
    allowed = cls.option_names()
    unknown = sorted(set(options) - set(allowed))
    if unknown:
        raise InvalidRequest(
            f"backend {name!r} has no option {', '.join(unknown)}; allowed: " + (", ".join(allowed) or "none"),
            backend=name,
        )
    try:
        return cls(model, **options)
    except BackendError:
        raise
    except Exception as error:  # a third-party plugin's constructor may fail in any way
        raise BackendError(f"backend {name!r} could not start: {type(error).__name__}: {error}", backend=name) from None


def open_backend(settings: Settings) -> Backend:
    """Open the backend that resolved settings (see drivetwin.orchestrator.config) choose."""
    return load_backend(settings.backend, settings.model, **settings.options_for(settings.backend))


def list_backends(settings: Settings | None = None) -> list[BackendStatus]:
    """Every backend/model pair and whether it is usable now; broken plugins included."""
    found, problems = discover_backends()
    rows: list[BackendStatus] = []
    for name in sorted(found):
        cls = found[name]
        options = settings.options_for(name) if settings else {}
        try:
            rows += cls.statuses(**options)
        except Exception as error:  # a plugin's status check must not break the listing
            rows.append(BackendStatus(name, "?", False, None, f"status check failed: {error}"))
    rows += [BackendStatus(p.name, "-", False, p.fix, f"broken plugin: {p.error}") for p in problems]
    return rows


def backends_table(settings: Settings | None = None) -> str:
    """The text `drivetwin backends list` prints: what is usable now and what fixes the rest."""
    rows = list_backends(settings)
    chosen = _chosen(settings)
    headers = ("backend", "model", "usable", "notes / fix")
    cells = [
        (
            row.backend,
            row.model + (" *" if (row.backend, row.model) in chosen else ""),
            "yes" if row.usable else "no",
            row.detail if row.usable else f"{row.detail}; fix: {row.fix}" if row.fix else row.detail,
        )
        for row in rows
    ]
    widths = [max(len(h), *(len(c[i]) for c in cells)) for i, h in enumerate(headers[:-1])]
    lines = ["  ".join(h.ljust(w) for h, w in zip(headers[:-1], widths, strict=True)) + "  " + headers[-1]]
    for cell in cells:
        lines.append("  ".join(c.ljust(w) for c, w in zip(cell[:-1], widths, strict=True)) + "  " + cell[-1])
    return "\n".join(lines)


def _chosen(settings: Settings | None) -> set[tuple[str, str]]:
    """The (backend, model) rows that the settings select, to mark them in the table."""
    if settings is None:
        return set()
    cls = discover_backends()[0].get(settings.backend)
    model = settings.model or (cls.default_model if cls else None) or ""
    names = {model, cls.presets.get(model, model)} if cls else {model}
    return {(settings.backend, name) for name in names}
