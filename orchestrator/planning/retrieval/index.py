"""Nearest bank examples by meaning: MiniLM embeddings of every request, cached beside the bank.

The generated bank's embeddings are computed once per world and saved as .npy next to its
JSON Lines file, so a later process pays only a file read; the (small) user bank is embedded
when it changes. A query is one MiniLM call and one matrix product.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from drivetwin.orchestrator.planning.grounding import embed
from drivetwin.orchestrator.planning.retrieval.bank import Example, bank_path, user_bank, world_bank, world_key
from drivetwin.worlds.scene import Scene

# Requests embedded per MiniLM call while building (bounded memory, same result).
EMBED_BATCH = 256
_LOCK = threading.Lock()


@dataclass(frozen=True)
class Hit:
    """A bank example and its cosine similarity to the query."""

    example: Example
    similarity: float


class BankIndex:
    """One world's examples (generated and learned) and their unit embeddings."""

    def __init__(self, examples: list[Example], vectors: Any) -> None:
        if len(examples) != len(vectors):
            raise ValueError(f"{len(examples)} examples but {len(vectors)} embeddings")
        self.examples = examples
        self.vectors = np.asarray(vectors, dtype=np.float32)

    def nearest(self, text: str, k: int) -> list[Hit]:
        """The `k` examples closest in meaning to `text`, best first."""
        if not self.examples or k <= 0:
            return []
        query = np.asarray(embed([text])[0], dtype=np.float32)
        return self.nearest_to(query, k)

    def nearest_to(self, query: Any, k: int) -> list[Hit]:
        scores = self.vectors @ query
        k = min(k, len(scores))
        top = np.argpartition(-scores, k - 1)[:k]
        top = top[np.argsort(-scores[top])]
        return [Hit(self.examples[i], float(scores[i])) for i in top]


def _embed_all(texts: list[str]) -> Any:
    parts = [embed(texts[i : i + EMBED_BATCH]) for i in range(0, len(texts), EMBED_BATCH)]
    return np.concatenate(parts).astype(np.float32) if parts else np.zeros((0, 384), dtype=np.float32)


def _generated_vectors(path: Path, examples: list[Example]) -> Any:
    vectors_path = path.with_suffix(".npy")
    if vectors_path.exists():
        try:
            vectors = np.load(vectors_path)
            if len(vectors) == len(examples):
                return vectors
        except (OSError, ValueError):
            pass  # damaged or stale: embed again
    known = _earlier_vectors(path)
    missing = [e.request for e in examples if e.request not in known]
    known.update(zip(missing, _embed_all(missing), strict=True))
    vectors = np.stack([known[e.request] for e in examples]) if examples else _embed_all([])
    partial = vectors_path.with_suffix(".part.npy")
    np.save(partial, vectors)
    partial.replace(vectors_path)
    return vectors


def _earlier_vectors(path: Path) -> dict[str, Any]:
    """Embeddings of this world's earlier banks (other generator versions) by request text,
    so a new version embeds only the requests it changed (MiniLM is the slow part)."""
    world = path.stem.rsplit("-", 1)[0]
    known: dict[str, Any] = {}
    for other in path.parent.glob(f"{world}-*.jsonl"):
        vectors_path = other.with_suffix(".npy")
        if other == path or not vectors_path.exists():
            continue
        try:
            texts = [
                Example.model_validate_json(line).request for line in other.read_text(encoding="utf-8").splitlines()
            ]
            vectors = np.load(vectors_path)
        except (OSError, ValueError):
            continue
        if len(texts) == len(vectors):
            known.update(zip(texts, vectors, strict=True))
    return known


# Per process, by world key: the generated bank and its embeddings, and the user bank's.
_generated_cache: dict[str, tuple[list[Example], Any]] = {}
_user_cache: dict[str, tuple[int, Any]] = {}


def _generated(key: str, scene: Scene) -> tuple[list[Example], Any]:
    if key not in _generated_cache:
        examples = world_bank(scene)
        _generated_cache[key] = (examples, _generated_vectors(bank_path(scene), examples))
    return _generated_cache[key]


def bank_index(scene: Scene) -> BankIndex:
    """The index of this world's bank: generated examples plus the user's accepted ones."""
    key = world_key(scene)
    with _LOCK:
        examples, vectors = _generated(key, scene)
        learned = user_bank(scene)
        if learned:
            cached = _user_cache.get(key)
            if cached is None or cached[0] != len(learned):
                cached = (len(learned), _embed_all([e.request for e in learned]))
                _user_cache[key] = cached
            return BankIndex(examples + learned, np.concatenate([vectors, cached[1]]))
        return BankIndex(examples, vectors)


def warm_bank(scene: Scene) -> threading.Thread:
    """Build (or load) this world's bank on a background thread, so that a person's first prompt
    finds it ready, or waits only for what is left (`bank_index` takes the same lock)."""
    thread = threading.Thread(target=bank_index, args=(scene,), name="drivetwin-bank-warmup", daemon=True)
    thread.start()
    return thread


__all__ = ["BankIndex", "Hit", "bank_index", "warm_bank"]
