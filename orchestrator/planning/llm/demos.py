"""Few-shot demonstrations chosen per request from the world's example bank.

The Sr. manager is shown the nearest bank requests with their requirements; a Jr. manager the
nearest single-call examples of its family, as a rendered requirement and its call. The bank
is generated from this world, so the demonstrations name its own places and assets. When the
bank cannot be read (no embedding model), the managers keep their static examples.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from drivetwin.orchestrator.planning.base import PlanContext
from drivetwin.orchestrator.planning.grounding import GroundingUnavailable
from drivetwin.orchestrator.planning.retrieval.bank import BankError, Example
from drivetwin.orchestrator.planning.retrieval.index import bank_index
from drivetwin.tools.base import Family

# Nearest examples looked at per request, before keeping those that fit the manager.
CANDIDATES = 40
_log = logging.getLogger(__name__)


@dataclass(frozen=True)
class SrDemo:
    request: str
    requirements: list[dict[str, str]]


@dataclass(frozen=True)
class JrDemo:
    requirement: str
    call: dict[str, Any]


def _nearest(prompt: str, context: PlanContext) -> list[Example]:
    try:
        return [hit.example for hit in bank_index(context.scene).nearest(prompt, CANDIDATES)]
    except (GroundingUnavailable, BankError, OSError, ValueError) as exc:
        _log.warning("few-shot retrieval unavailable, using the static examples: %s", exc)
        return []


def sr_demos(prompt: str, context: PlanContext, k: int) -> list[SrDemo]:
    """The `k` bank requests nearest `prompt` that carry requirements, best first."""
    found = [SrDemo(e.request, e.requirements) for e in _nearest(prompt, context) if e.requirements]
    return found[:k]


def jr_demos(family: Family, prompt: str, context: PlanContext, k: int) -> list[JrDemo]:
    """The `k` nearest one-call examples of `family`'s tools, as requirement -> call, best first."""
    tools = {t.name for t in context.registry.family(family)}
    demos: list[JrDemo] = []
    for example in _nearest(prompt, context):
        if len(example.calls) != 1 or len(example.requirements) != 1 or example.calls[0].tool not in tools:
            continue
        need, call = example.requirements[0], example.calls[0]
        demos.append(JrDemo(_render(need, call.args), {"tool": call.tool, "args": call.args}))
        if len(demos) == k:
            break
    return demos


def fits(value: Any, schema: Mapping[str, Any]) -> bool:
    """Whether `value` has the shape `schema` (a slimmed Jr. schema) allows: the same tool,
    only fields it offers, every field it requires. A demonstration that fills a field this
    request's grammar leaves out teaches the model to want it. Names and numbers may differ:
    those are the request's own."""
    if "anyOf" in schema:
        return any(fits(value, branch) for branch in schema["anyOf"])
    if "const" in schema:
        return bool(value == schema["const"])
    if "properties" in schema:
        props = schema["properties"]
        return (
            isinstance(value, dict)
            and all(k in props and fits(v, props[k]) for k, v in value.items())
            and all(r in value for r in schema.get("required", ()))
        )
    if schema.get("type") == "array":
        return isinstance(value, list)
    return not isinstance(value, dict)


def _render(need: dict[str, str], args: dict[str, Any]) -> str:
    """A requirement the way render_requirement shows it, grounded names after arrows."""
    what = args.get("category") or args.get("asset") or ", ".join(args.get("categories", []) or args.get("assets", []))
    location = args.get("location")
    where = location.get("target") if isinstance(location, dict) else args.get("near")

    def side(label: str, text: str, name: Any) -> str:
        return f"{label}: {text}" + (f" -> {name}" if text and name else "")

    return " | ".join(
        [
            need.get("kind", ""),
            side("what", need.get("what", ""), what),
            side("where", need.get("where", ""), where),
            f"how: {need.get('how', '')}",
        ]
    )


__all__ = ["JrDemo", "SrDemo", "fits", "jr_demos", "sr_demos"]
