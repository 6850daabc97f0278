"""The example bank: thousands of (request -> Worker calls) pairs generated for one world.

`generate(scene)` runs the grammar's frames (retrieval/_frames.py) over the world's catalog,
places, lanes and assets, keeps only drafts whose calls a dry run accepts on the world, adds
noise and compound requests, and drops duplicate wordings. `world_bank(scene)` returns the
bank from the user cache (JSON Lines, one file per world and generator version), building it
the first time. A per-world *user* bank holds what a person accepted in a session (`learn`);
retrieval reads both.
"""

from __future__ import annotations

import hashlib
import json
import os
import random
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

from drivetwin.orchestrator.config import cache_dir
from drivetwin.orchestrator.memory import Memory
from drivetwin.orchestrator.planning.retrieval._frames import COMPOUNDS, FRAMES, JOINERS, LATER_FRAMES, Draft
from drivetwin.orchestrator.planning.retrieval._words import Words
from drivetwin.orchestrator.transaction import first_refusal
from drivetwin.tools.base import ToolCall
from drivetwin.tools.errors import ToolError
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.scene import Scene
from pydantic import BaseModel, ConfigDict, Field, ValidationError

# Bump when the grammar's frames or words change: cached banks of an older version are rebuilt.
GENERATOR_VERSION = "7"
# The version the random draws are seeded with. A frame added to LATER_FRAMES bumps only
# GENERATOR_VERSION, so cached banks are rebuilt and every earlier example stays as it was;
# bump this one too to redraw the whole bank.
DRAW_VERSION = "5"
BANK_FOLDER = "banks"
# Tries per wanted draft before a frame gives up (a dry run refuses some draws).
TRIES_PER_DRAFT = 3
USER_BANK_SUFFIX = ".user.jsonl"
# Planners whose sessions learn accepted edits: those that read the bank (retrieval directly,
# the hybrid through retrieval, the LLM through its retrieved few-shot examples).
LEARNING_PLANNERS = frozenset({"hybrid", "retrieval", "llm"})
_LOCK = threading.Lock()


class Example(BaseModel):
    """One request and the Worker calls that do it, with what its words named (slots)."""

    model_config = ConfigDict(extra="forbid")

    request: str = Field(min_length=1)
    calls: list[ToolCall]
    task: str
    tags: list[str] = Field(default_factory=list)
    # What the request's words named, in order: ("category", "bench"), ("count", 3)...
    slots: list[tuple[str, Any]] = Field(default_factory=list)
    # The Sr. manager's requirements for this request (kind, what, where, how).
    requirements: list[dict[str, str]] = Field(default_factory=list)


class BankError(RuntimeError):
    """A bank file cannot be read or written; the message names the file."""


def world_key(scene: Scene, version: str = GENERATOR_VERSION) -> str:
    """The world's name and a hash of what the grammar draws from (places, lanes, first
    assets) and the generator version: a different world or grammar gets a different bank."""
    static = {
        "name": scene.name,
        "landmarks": [lm.model_dump(mode="json") for lm in scene.landmarks],
        "lanes": [lane.id for lane in scene.roads.lanes],
        "version": version,
    }
    digest = hashlib.sha256(json.dumps(static, sort_keys=True).encode()).hexdigest()[:12]
    safe = "".join(c if c.isalnum() or c in "-_" else "_" for c in scene.name)[:40] or "world"
    return f"{safe}-{digest}"


def bank_path(scene: Scene) -> Path:
    """The cached bank file of this world (the embeddings lie beside it as .npy)."""
    return cache_dir() / BANK_FOLDER / f"{world_key(scene)}.jsonl"


def user_bank_path(scene: Scene) -> Path:
    """The per-world bank of requests a person accepted (kept across generator versions)."""
    safe = "".join(c if c.isalnum() or c in "-_" else "_" for c in scene.name)[:40] or "world"
    return cache_dir() / BANK_FOLDER / f"{safe}{USER_BANK_SUFFIX}"


def _seed(scene: Scene) -> int:
    return int(world_key(scene, DRAW_VERSION).rsplit("-", 1)[-1], 16)


def generate(scene: Scene, registry: ToolRegistry | None = None, scale: float = 1.0) -> list[Example]:
    """The world's bank: every frame drawn its share of times (times `scale`), each draft
    kept only if a dry run on `scene` accepts its calls, wordings unique."""
    registry = registry or ToolRegistry.default()
    rng = random.Random(_seed(scene))
    words = Words(scene, rng)
    accepted: dict[str, bool] = {}

    def valid(calls: list[dict[str, Any]]) -> bool:
        for call in calls:
            try:
                parsed = ToolCall.model_validate(call)
                registry.get(parsed.tool).parse(parsed.args)
            except (ValidationError, ToolError):
                return False
            key = json.dumps(_stand_in(call), sort_keys=True)
            if key not in accepted:
                accepted[key] = first_refusal(registry, scene, [ToolCall.model_validate(_stand_in(call))]) is None
            if not accepted[key]:
                return False
        return True

    def drawn(frames: dict[Callable[[Words], Draft | None], int], words: Words) -> list[Draft]:
        out: list[Draft] = []
        for frame, wanted in frames.items() if words.landmarks else ():
            made = 0
            for _ in range(int(wanted * scale) * TRIES_PER_DRAFT):
                if made >= int(wanted * scale):
                    break
                draft = frame(words)
                if draft is not None and valid(draft.calls):
                    out.append(draft)
                    made += 1
        return out

    drafts = drawn(FRAMES, words)
    singles = [d for d in drafts if d.task != "search"]
    for _ in range(int(COMPOUNDS * scale) if len(singles) > 1 else 0):
        first, second = rng.sample(singles, 2)
        joined = Draft(
            first.request + rng.choice(JOINERS) + second.request,
            first.calls + second.calls,
            first.task,
            first.slots + second.slots,
            first.requirements + second.requirements,
            ["compound"],
        )
        if valid(joined.calls):
            drafts.append(joined)
    for later in LATER_FRAMES:  # each from a stream of its own: the examples above stay as they were
        drafts += drawn({later: LATER_FRAMES[later]}, Words(scene, random.Random(f"{_seed(scene)}:{later.__name__}")))
    seen: set[str] = set()
    bank: list[Example] = []
    for draft in drafts:
        text, noise = words.noisy(draft.request)
        if text.lower() in seen:
            continue
        seen.add(text.lower())
        bank.append(
            Example(
                request=text,
                calls=[ToolCall.model_validate(c) for c in draft.calls],
                task=draft.task,
                tags=[*draft.tags, *noise],
                slots=draft.slots,
                requirements=draft.requirements,
            )
        )
    return bank


def _stand_in(call: dict[str, Any]) -> dict[str, Any]:
    """The call whose dry run stands for `call`'s: a placement is refused or accepted for
    where it goes, how many and the kind of thing it is (where it may stand, how it moves),
    so one category per kind and size stands for the rest. (Dry runs of placements cost tens of
    milliseconds each; a bank has thousands.)"""
    args = dict(call["args"])
    if call["tool"] in ("add_asset", "arrange_assets"):
        names = args.get("categories") or [args.get("category")]
        kind = [_KINDS.get(n, n) for n in names]
        args.pop("colour", None)
        if call["tool"] == "add_asset":
            args["category"] = kind[0]
        else:
            args["categories"] = kind
    return {"tool": call["tool"], "args": args}


def _kinds() -> dict[str, str]:
    from drivetwin.worlds.catalog import catalog

    first: dict[tuple[str, str, float], str] = {}
    out: dict[str, str] = {}
    for cat in catalog().values():
        # Size decides whether a row or ring of them overlaps: half-metre classes of footprint.
        size = round(cat.footprint_radius * 2) / 2
        out[cat.name] = first.setdefault((cat.placement, cat.motion, size), cat.name)
    return out


_KINDS = _kinds()


def read_bank(path: Path) -> list[Example]:
    """The examples in a JSON Lines bank file ([] if it does not exist)."""
    if not path.exists():
        return []
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
        return [Example.model_validate_json(line) for line in lines if line.strip()]
    except (OSError, ValueError) as exc:
        raise BankError(f"the example bank {path} is unreadable ({exc}); delete it to rebuild") from exc


def _write(path: Path, examples: list[Example]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    partial = path.with_suffix(f".{os.getpid()}.part")
    partial.write_text("".join(e.model_dump_json() + "\n" for e in examples), encoding="utf-8")
    partial.replace(path)  # readers never see half a bank


def world_bank(scene: Scene, registry: ToolRegistry | None = None) -> list[Example]:
    """The world's generated bank, from the cache, built and cached the first time."""
    path = bank_path(scene)
    with _LOCK:
        if path.exists():
            try:
                return read_bank(path)
            except BankError:
                pass  # a damaged cache file is rebuilt, not fatal
        bank = generate(_pristine(scene), registry)
        _write(path, bank)
        return bank


def _pristine(scene: Scene) -> Scene:
    """The world as loaded by name (so every session of one world shares one bank),
    else the scene itself (an imported or edited world with no file of that name)."""
    from drivetwin.worlds.defaults import UnknownWorldError, load_world

    try:
        loaded = load_world(scene.name)
    except (UnknownWorldError, ValueError, OSError):
        return scene
    return loaded if world_key(loaded) == world_key(scene) else scene


def user_bank(scene: Scene) -> list[Example]:
    """What a person accepted in this world, oldest first."""
    return read_bank(user_bank_path(scene))


def learn(scene: Scene, request: str, calls: list[ToolCall], task: str = "learned") -> Example | None:
    """Add an accepted (request -> calls) pair to the world's user bank; retrieval uses it
    from the next prompt on. Requests with no calls (questions, failures) teach nothing."""
    if not calls or not request.strip():
        return None
    example = Example(request=request.strip(), calls=calls, task=task, tags=["user"])
    path = user_bank_path(scene)
    try:
        if any(e.request == example.request and e.calls == calls for e in read_bank(path)):
            return example  # already known: the bank does not grow by repetition
    except BankError:
        pass  # a damaged user bank is appended to; its good lines still read
    with _LOCK:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            with path.open("a", encoding="utf-8") as out:
                out.write(example.model_dump_json() + "\n")
        except OSError:
            return None  # an unwritable cache costs the lesson, never the person's accept
    return example


def learn_accepted(planner: object, scene: Scene, request: str, memory: Memory) -> Example | None:
    """Learn the newest applied turn of `request` from the session's memory (its calls are
    kept there as text: `tool(key=value, ...)`, read back with literal parsing only), when the
    session's planner is one that reads the bank (LEARNING_PLANNERS): a session driven by
    scripted or rule-only planners (tests, replays) teaches the person's bank nothing."""
    if getattr(planner, "name", None) not in LEARNING_PLANNERS:
        return None
    turn = next((t for t in reversed(memory.turns) if t.prompt == request and t.calls), None)
    if turn is None:
        return None
    try:
        calls = turn.tool_calls()
    except (SyntaxError, ValueError):
        return None  # a call that does not read back is not worth a wrong example
    return learn(scene, request, calls)


__all__ = [
    "GENERATOR_VERSION",
    "BankError",
    "Example",
    "bank_path",
    "generate",
    "learn",
    "learn_accepted",
    "read_bank",
    "user_bank",
    "user_bank_path",
    "world_bank",
    "world_key",
]
