"""Spelling in context: a word no planner reads is replaced by a near word when the language
model finds the whole request much likelier with it.

The rule planner's own repair (rules/spelling.py) fixes a slip against the words it knows, one
word at a time and without context, so it must leave alone what it cannot tell apart: a short
slip ("snoe", "tel"), a word spelt by its sound ("coan", "sooveee", "wut") and a word two slips
from several others. Here each such word is judged in its sentence, as a noisy channel: the
model's log-probability of the request spelt each way, less EDIT_COST per slip, against the
request as typed. A word is replaced only when that beats the typed request by MARGIN.

A real English word (one of the MiniLM vocabulary's) is never respelt, however much likelier the
model finds another: on the development prompts SmolLM2 preferred "East the tree by the Library"
to "Ease the tree ..." and "low, what a lively campus" to "wow, ...", as strongly as it preferred
"weather" to "whether"; a real word typed for another is left to the rules' own readings.

Candidates are the words the planners read (catalog and place names, intent, amount and
grammar words) a slip or two away or sounding the same, and English words sounding the same;
the model, not a phrase list, chooses among them. Every replacement is
reported, and the check reads the request as respelt (`Plan.read_as`), so nothing is applied on
a reading the person cannot see.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from functools import cache, lru_cache

from drivetwin.orchestrator.planning.intent import asks, commands
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules.spelling import (
    Repaired,
    edits,
    english_words,
    is_english,
    is_known,
    repair,
    repair_targets,
    vocabulary,
)
from drivetwin.worlds.scene import Scene
from jellyfish import metaphone

# Log-probability one letter slip costs: a replacement two slips away must make the sentence
# e^6 times likelier just to break even.
EDIT_COST = 3.0
# How much likelier (in log-probability, after the slips' cost) the respelt request must be.
MARGIN = 2.0
# Letter slips allowed: one in a word of up to four letters, else two.
SHORT_WORD_LEN = 4
# Metaphone consonants a sound-alike needs: two for a word the planners read ("coan", "wut"),
# three for any other English word ("finsh", "closist").
SOUND, SURE_SOUND = 2, 3
# A sound-alike's letters past the first cost this much of a slip each.
SOUND_LETTER = 0.5
# Extra cost of a word the planners do not read: "coan" is a cone here, not a coin.
OTHER_WORD_COST = 3.0
# Extra cost of a word that does not keep the typed first letter, which is rarely the slip: "the eest gate" is
# the east gate, though the model may find "west" as likely (half a slip).
FIRST_LETTER_COST = 1.5
# Rounds over the request: a word respelt may make an earlier one clear.
PASSES = 2
# Candidates scored per word, nearest first (each costs one short model evaluation).
MAX_CANDIDATES = 8
# Words whose candidates are kept (finding them scans every word the planners read).
CANDIDATE_CACHE = 4096
_WORD = re.compile(r"[A-Za-z][A-Za-z'\-]*")
# An acronym or code as typed ("ODD", "JTEKT", "R1-1"): never a slip.
_CODE = re.compile(r"[A-Z0-9][A-Z0-9\-]+")

Scorer = Callable[[list[str]], list[float]]


@cache
def _domain(vocab: frozenset[str]) -> tuple[str, ...]:
    words = set(repair_targets(vocab)) | {w for w in lx.GRAMMAR if w.isalpha() and len(w) > 1}
    words |= {w + "s" for w in list(words) if len(w) > 2 and not w.endswith("s")}  # "tress" may be "trees"
    return tuple(sorted(words))


@cache
def _sounds(words: tuple[str, ...]) -> dict[str, tuple[str, ...]]:
    """Words by their Metaphone key: "coan" and "cone", "wut" and "what" sound alike."""
    by_key: dict[str, list[str]] = {}
    for word in words:
        by_key.setdefault(metaphone(word), []).append(word)
    return {key: tuple(group) for key, group in by_key.items()}


@cache
def _english() -> tuple[str, ...]:
    return tuple(sorted(w for w in english_words() if len(w) > 2))


def _slips_allowed(word: str) -> int:
    return 1 if len(word) <= SHORT_WORD_LEN else 2


def slips(typed: str, meant: str) -> float:
    """How many slips turn `meant` into `typed`: its letters changed, but a word that sounds the
    same costs one slip and half a slip per further letter ("sooveee" for "suv": three)."""
    letters = edits(typed, meant)
    if metaphone(typed) == metaphone(meant):
        return min(letters, 1 + SOUND_LETTER * (letters - 1))
    return letters


def _consonants(key: str) -> int:
    return len(key.lstrip("AEIOU"))


@lru_cache(maxsize=CANDIDATE_CACHE)
def candidates(word: str, vocab: frozenset[str]) -> tuple[str, ...]:
    """The words `word` may be a slip for, nearest first: words the planners read that are a
    slip or two away or sound the same, and English words that sound the same. A sound is only
    trusted with enough consonants to tell words apart ("umm" is no "home")."""
    low = word.lower()
    domain = _domain(vocab)
    allowed = _slips_allowed(low)
    near = {t for t in domain if abs(len(t) - len(low)) <= allowed and edits(low, t) <= allowed}
    key = metaphone(low)
    if _consonants(key) >= SOUND:
        near |= set(_sounds(domain).get(key, ()))
    if _consonants(key) >= SURE_SOUND:  # "finsh", "closist"
        near |= set(_sounds(_english()).get(key, ()))
    near.discard(low)
    return tuple(sorted(near, key=lambda t: (cost(low, t, vocab), t))[:MAX_CANDIDATES])


def cost(typed: str, meant: str, vocab: frozenset[str]) -> float:
    """The channel's cost of reading `typed` as `meant`: its slips, more for a word the planners
    do not read, which the person less likely meant here, and more for a first letter changed."""
    return EDIT_COST * slips(typed, meant) + (0.0 if meant in _domain(vocab) else OTHER_WORD_COST) \
        + (FIRST_LETTER_COST if typed[:1] != meant[:1] else 0.0)


def _suspects(text: str, scene: Scene, vocab: frozenset[str]) -> list[str]:
    """The words of `text` no planner reads and no English word: not known, no asset id, no code."""
    ids = {a.id for a in scene.all_assets()}
    out = []
    for m in _WORD.finditer(text):
        word = m.group(0)
        around = text[max(0, m.start() - 1) : m.end() + 1]
        if len(word) < 2 or "_" in around or _CODE.fullmatch(word) or word.lower() in ids:
            continue
        low = word.lower().strip("'-")
        if not is_known(low, vocab) and not is_english(low) and word not in out:
            out.append(word)
    return out


# What may stand before the first word of a request.
_OPENING = re.compile(r"(?:^|[,.;:!?])\s*(?:(?:please|pls|ok|okay|so|now|and|then|just)\s+)?$", re.IGNORECASE)


# What may stand after the last word of a request.
_CLOSING = re.compile(r"[\s.!?,;:)]*")


def _ends_on_a_name(before: str, scene: Scene) -> bool:
    """Whether the words before end on a place's name ("... to the east gate"), so the request is said (after a
    thing's name a word may still be what it is to be: "make the hydrant blauw")."""
    last = _WORD.findall(before)[-1:]
    return bool(last) and last[0].lower() in _place_words(scene)


def _place_words(scene: Scene) -> frozenset[str]:
    return frozenset(w.lower() for lm in scene.landmarks for name in lm.names() for w in _WORD.findall(name))


def _cased(candidate: str, typed: str) -> str:
    return candidate.capitalize() if typed[:1].isupper() else candidate


def respell(text: str, scene: Scene, score: Scorer) -> Repaired:
    """`text` with each word no planner reads replaced by the near word that makes the request
    clearly likelier to the model (`score`: log-probabilities of whole texts); the replacements
    as 'was -> now'. The rule planner's own repairs are made first, as context, and a word is
    judged again once a later one is respelt ("tern the sooveee around": "suv" makes "turn")."""
    vocab = vocabulary(scene)
    current, out = repair(text, scene).text, text
    fixes: list[str] = []
    tried: set[tuple[str, str]] = set()
    for _ in range(PASSES):
        changed = False
        for typed in _suspects(current, scene, vocab):
            if (typed, current) in tried:
                continue  # judged already, in this same sentence
            tried.add((typed, current))
            at = re.compile(rf"(?<![A-Za-z']){re.escape(typed)}(?![A-Za-z'])")
            options = candidates(typed, vocab)
            found = at.search(current)
            if found is not None and _OPENING.search(current[: found.start()]):
                # "Quita el fire hydrant": the word where a request's verb goes is a verb or a
                # question word ("tern the suv": turn), never a place's name or a stray ("Gate", "Good")
                options = tuple(c for c in options if c not in _place_words(scene) and (commands(f"{c} it") or asks(f"{c} it"))
                                and edits(typed.lower(), c) <= _slips_allowed(typed.lower()))  # "Hace" is no "Hows"
            if found is not None and _CLOSING.fullmatch(current[found.end() :]) and _ends_on_a_name(current[: found.start()], scene):
                continue  # "move the SUV to the east gate krub": a word after the request's last place is a sign-off, never "curb"
            if not options or not at.search(out):
                continue  # nothing near, or the rules' own repair made it (theirs to report)
            spelt = [at.sub(_cased(c, typed), current, count=1) for c in options]
            base, *scores = score([current, *spelt])
            gains = [s - base - cost(typed.lower(), c, vocab) for s, c in zip(scores, options, strict=True)]
            best = max(range(len(options)), key=gains.__getitem__)
            if gains[best] >= MARGIN:
                chosen = _cased(options[best], typed)
                current, out = spelt[best], at.sub(chosen, out, count=1)
                fixes.append(f"{typed} -> {chosen}")
                changed = True
        if not changed:
            break
    return Repaired(out, fixes)


__all__ = ["EDIT_COST", "MARGIN", "Scorer", "candidates", "respell", "slips"]
