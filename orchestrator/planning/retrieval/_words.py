"""The bank grammar's vocabulary: how people name things, places, numbers and amounts, and
the noise real typing adds (typos, dropped words, non-native grammar).

Everything is drawn from the world (landmarks, lanes, assets) and the catalog (names,
synonyms, descriptions), so an imported world gets words of its own. Choices go through one
seeded `random.Random`, so a world's bank is the same every time it is built.
"""

from __future__ import annotations

import random
import re
from collections.abc import Sequence
from typing import TypeVar

from drivetwin.worlds.catalog import Category, catalog, placeable_categories
from drivetwin.worlds.scene import Scene

T = TypeVar("T")
NUMBER_WORDS = (
    "zero",
    "one",
    "two",
    "three",
    "four",
    "five",
    "six",
    "seven",
    "eight",
    "nine",
    "ten",
    "eleven",
    "twelve",
    "thirteen",
    "fourteen",
    "fifteen",
    "sixteen",
    "seventeen",
    "eighteen",
    "nineteen",
    "twenty",
)
# Words for amounts with no digits in them.
AMOUNT_WORDS = {2: ("a couple of", "a pair of"), 12: ("a dozen",), 6: ("half a dozen",)}
METRE_WORDS = ("m", " m", " metres", " meters", " metre", "m")
SPEED_UNITS = ((" m/s", 1.0), (" km/h", 3.6), (" kph", 3.6), (" mph", 2.237))
# How often a request gets noise at all, and how often a noisy one gets a typo.
NOISE_RATE = 0.35
TYPO_RATE = 0.6
# Words this short are left alone by typos: "a", "to", "at" misspelt read as other words.
TYPO_MIN_LETTERS = 5
_ARTICLES = re.compile(r"\b(the|a|an) ")
_PLURAL_IRREGULAR = {"person": "people", "man": "men", "woman": "women", "child": "children"}


def plural(word: str) -> str:
    """English plural of the last word of `word` ("traffic cone" -> "traffic cones")."""
    head, _, last = word.rpartition(" ")
    if last in _PLURAL_IRREGULAR:
        last = _PLURAL_IRREGULAR[last]
    elif re.search(r"(s|x|ch|sh)$", last):
        last += "es"
    elif re.search(r"[^aeiou]y$", last):
        last = last[:-1] + "ies"
    elif not re.search(r"\d$", last):
        last += "s"
    return f"{head} {last}" if head else last


class Words:
    """Seeded word choices for one world."""

    def __init__(self, scene: Scene, rng: random.Random) -> None:
        self.scene = scene
        self.rng = rng
        allowed = set(placeable_categories())
        self.categories: dict[str, Category] = {n: c for n, c in catalog().items() if n in allowed}
        self.landmarks = [lm.name for lm in scene.landmarks]
        self.lanes = [lane.id for lane in scene.roads.lanes]
        self.assets = [a for a in scene.assets if a.id != "ego"]

    def pick(self, options: Sequence[T]) -> T:
        return options[self.rng.randrange(len(options))]

    # Things ------------------------------------------------------------------------------
    def thing(self, name: str, count: int = 1) -> str:
        """A word for category `name`, plural when `count` > 1; now and then its description."""
        cat = self.categories[name]
        words = [w for w in cat.words if "_" not in w]
        if count == 1 and cat.description and self.rng.random() < 0.12:
            return _describe(cat.description)
        word = self.pick(words)
        return plural(word) if count > 1 else word

    def asset_words(self, asset_id: str) -> str:
        """How a person names an existing asset: its id, "the <synonym>" or "<synonym> <n>"."""
        asset = self.scene.asset(asset_id)
        assert asset is not None
        same = [a for a in self.assets if a.category == asset.category]
        word = (
            self.pick([w for w in self.categories[asset.category].words if "_" not in w])
            if asset.category in self.categories
            else asset.category.replace("_", " ")
        )
        number = asset_id.rsplit("_", 1)[-1]
        options = [asset_id, f"{word} {number}", f"{word} number {number}"]
        if len(same) == 1:
            options += [f"the {word}", f"that {word}", f"the {word}"]
        return self.pick(options)

    # Places ------------------------------------------------------------------------------
    def place(self, name: str) -> str:
        """A way to say landmark `name`: its name or an alias, with or without "the"."""
        lm = next(lm for lm in self.scene.landmarks if lm.name == name)
        said = self.pick(list(lm.names())).lower() if self.rng.random() < 0.7 else lm.name
        if said.startswith("the ") or self.rng.random() < 0.25:
            return said
        return f"the {said}"

    def lane(self, lane_id: str) -> str:
        words = lane_id.replace("_", " ")
        road, _, direction = words.rpartition(" ")
        return self.pick(
            (
                lane_id,
                f"the {words} lane",
                f"lane {lane_id}",
                f"the {direction} lane of {road} street",
                f"the {direction} lane",
            )
        )

    # Numbers -----------------------------------------------------------------------------
    def count(self, n: int) -> str:
        roll = self.rng.random()
        if n in AMOUNT_WORDS and roll < 0.3:
            return self.pick(AMOUNT_WORDS[n])
        if n < len(NUMBER_WORDS) and roll < 0.6:
            return NUMBER_WORDS[n]
        return str(n)

    def metres(self, value: float) -> str:
        text = _number(value)
        if value < len(NUMBER_WORDS) and value == int(value) and self.rng.random() < 0.25:
            text = NUMBER_WORDS[int(value)]
            return text + self.pick((" metres", " meters", " metre"))
        return text + self.pick(METRE_WORDS)

    def speed(self, metres_per_s: float) -> tuple[str, float]:
        """A speed in words and the m/s value it stands for (rounded as people say it)."""
        unit, factor = SPEED_UNITS[self.rng.randrange(len(SPEED_UNITS))]
        said = round(metres_per_s * factor)
        return f"{said}{unit}", round(said / factor, 2)

    # Noise -------------------------------------------------------------------------------
    def noisy(self, text: str) -> tuple[str, list[str]]:
        """`text` with, sometimes, a typo, dropped articles or a shouted or bare form."""
        if self.rng.random() >= NOISE_RATE:
            return text, []
        tags: list[str] = []
        if self.rng.random() < TYPO_RATE:
            words = text.split(" ")
            long = [i for i, w in enumerate(words) if len(w) >= TYPO_MIN_LETTERS and w.isalpha()]
            if long:
                i = self.pick([str(i) for i in long])
                words[int(i)] = self._typo(words[int(i)])
                text = " ".join(words)
                tags.append("typo")
        roll = self.rng.random()
        if roll < 0.35:
            text, tags = _ARTICLES.sub("", text), [*tags, "dropped_words"]
        elif roll < 0.45:
            text, tags = text.upper(), [*tags, "shouted"]
        elif roll < 0.6:
            text, tags = text.rstrip(".?! ") + self.pick((" pls", " thx", " asap", " now")), [*tags, "terse"]
        return text, tags

    def _typo(self, word: str) -> str:
        i = self.rng.randrange(1, len(word) - 1)
        kind = self.rng.randrange(3)
        if kind == 0:
            return word[:i] + word[i + 1] + word[i] + word[i + 2 :]
        if kind == 1:
            return word[:i] + word[i + 1 :]
        return word[:i] + word[i] + word[i:]


def _describe(description: str) -> str:
    """A catalog description as a noun phrase without its size ("an orange traffic cone")."""
    phrase = re.sub(r",\s*[\d.]+\s*(cm|m)\b.*$", "", description).strip()
    return re.sub(r"^(a|an|the) ", "", phrase)


def _number(value: float) -> str:
    return str(int(value)) if value == int(value) else f"{value:g}"


__all__ = ["NUMBER_WORDS", "Words", "plural"]
