"""The rule planner's lexicon: finding categories, counts, places and references in words.

Everything here is plain text matching against what the world and catalog actually contain
(category synonyms, landmark names and aliases, lane ids, asset ids), so it never invents a
name that does not exist.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache

from drivetwin.orchestrator.planning.rules import numbers as nb
from drivetwin.worlds.catalog import Category, catalog
from drivetwin.worlds.scene import EGO_ID, Scene

# Counts in words: every number spelt as one word ("seventy", "thirty-five"), and the words for a few.
NUMBER_WORDS = nb.spelt_counts() | {"a": 1, "an": 1, "single": 1, "pair": 2, "couple": 2, "few": 3, "some": 3,
                                    "several": 4, "dozen": 12}
_TOKEN = re.compile(r"[a-z0-9_#.\-']+")
# Tokens with their spans, numbers written with separators kept whole ("10,000").
_TOKEN_SPANS = re.compile(r"\d{1,3}(?:,\d{3})+(?![\d,])|[a-z0-9_#.\-'+]+")
EGO_WORDS = tuple(sorted({"the ego", "ego's", "test car", "av", *(w.lower().removeprefix("the ") for c in catalog().values() if "ego" in c.tags for w in c.words)}, key=lambda w: (-len(w), w)))


def tokens(text: str) -> list[str]:
    return _TOKEN.findall(text.lower())


def normalise(text: str) -> str:
    """Lower case, single spaces, British/American spellings folded, punctuation eased."""
    out = " " + re.sub(r"\s+", " ", text.lower()) + " "
    for us, uk in (("center", "centre"), ("color", "colour"), ("gray", "grey"), ("meter", "metre")):
        out = out.replace(us, uk)
    # "more near", "most close": the comparative and superlative as learners build them
    out = re.sub(r"\b(more|most) (near|close)\b", lambda m: m.group(2).removesuffix("e") + ("er" if m.group(1) == "more" else "est"), out)
    # "6x traffic_cone", "4 x barriers": a count in a spec's notation ("3x2" stays a grid's size)
    out = re.sub(r"\b(\d+)\s?x\s+(?=[a-z])", r"\1 ", out)
    out = re.sub(r"\b(?:front |main )?(?:door|doorway)s?\b", "entrance", out)  # "the Union doors": its entrance
    out = re.sub(r"\b(nearest|closest|near|ahead of|behind|in front of|next to|beside) us\b", r"\1 the ego", out)  # the driver's "us"
    # "take that orange thing away": the particle of a phrasal verb said after its object
    out = re.sub(r"\b(take|throw|clear|carry|haul) ((?:the|that|this|those|these|all|both|every|its|their|our|my|\w+ of)"
                 r"(?: [a-z0-9_'-]+){1,5}?) (away|out|off)\b(?! of\b)", _particle_first, out)
    # A comma inside a number ("10,000") is a thousands separator, not a clause break.
    return re.sub(r"(?<!\d),|,(?!\d{3}(?!\d))", " , ", out.replace("’", "'"))


def _particle_first(m: re.Match[str]) -> str:
    """"take that thing away" as "take away that thing"; "take the bin off the sidewalk" is "take
    away the bin from the sidewalk" (a bare "take off" is a driver's turn, not a removal)."""
    verb, thing, particle = m.group(1), m.group(2), m.group(3)
    if particle != "off":
        return f"{verb} {particle} {thing}"
    place = re.match(r" (?:the|that|this)\b", m.string[m.end() :])
    return f"{verb} away {thing}{' from' if place else ''}"


def _singular(word: str) -> str:
    for suffix, repl in (("ies", "y"), ("ches", "ch"), ("shes", "sh"), ("sses", "ss"), ("es", "e"), ("s", "")):
        if word.endswith(suffix) and len(word) > len(suffix) + 2:
            return word[: -len(suffix)] + repl
    return word


@dataclass(frozen=True)
class Mention:
    """A category named in the text, where, and whether the noun was plural."""

    category: str
    start: int
    end: int
    plural: bool


def _category_phrases() -> tuple[tuple[str, str], ...]:
    """(phrase, category) for every name and synonym of the catalog as it is now: asset
    packages found after start-up (a reconstructed asset) are understood at once."""
    return _phrases_of(tuple(catalog().values()))


@cache
def _phrases_of(categories: tuple[Category, ...]) -> tuple[tuple[str, str], ...]:
    phrases = []
    for cat in categories:
        if "ego" in cat.tags:
            continue
        for word in cat.words:
            phrases.append((word.lower(), cat.name))
    # Longest phrase first, so "traffic light" wins over "light" and "stop sign" over "stop".
    return tuple(sorted(set(phrases), key=lambda p: -len(p[0])))


def find_categories(text: str, normalised: bool = False) -> list[Mention]:
    """Every category named in `text`, in order, longest phrases first, no overlaps (where in `text` itself if `normalised`)."""
    low = text if normalised else normalise(text)
    taken: list[tuple[int, int]] = []
    found: list[Mention] = []
    for phrase, name in _category_phrases():
        for plural in (False, True):
            words = phrase.split()
            variants = [phrase]
            if plural:
                last = words[-1]
                variants = [" ".join([*words[:-1], last + s]) for s in ("s", "es")]
                if last.endswith("y"):
                    variants.append(" ".join([*words[:-1], last[:-1] + "ies"]))
                if last in ("person", "child"):  # the irregular plurals
                    variants.append(" ".join([*words[:-1], "people" if last == "person" else "children"]))
            for variant in variants:
                for m in _whole(variant).finditer(low):
                    span = (m.start(), m.end())
                    if any(not (span[1] <= a or span[0] >= b) for a, b in taken):
                        continue
                    taken.append(span)
                    found.append(Mention(name, span[0], span[1], plural or phrase == "people"))
    return sorted(found, key=lambda m: m.start)


@cache
def _whole(phrase: str) -> re.Pattern[str]:
    # apart, hyphenated or closed up ("road-work"); not the first word of a place ("the bus stop"; "benches lot A" is two)
    said = r"(?:\s|-)?".join(re.escape(w) + ("s?" if i < phrase.count(" ") and len(w) > 3 else "") for i, w in enumerate(phrase.split()))  # "road works sign"
    said = "".join(rf"(?<!{w} )" for w in ("emergency", "sudden", "hard", "full", "complete", "to a")) + said if phrase == "stop" else said  # braking
    return re.compile(rf"(?<![a-z0-9_]){said}(?![a-z0-9_])(?!(?:\s+|-)(?:car park|park|parking|lot(?!\s+[a-z0-9]\b)|stop|station|rack|union)\b)")


def find_count(text: str, before: int | None = None, what: str = "things") -> int | None:
    """The number that quantifies a noun (digits or words), looking just before `before`;
    a number that cannot be a count ("nan", "2.5") is refused, never read as a default."""
    low = normalise(text)
    window = low[:before] if before is not None else low
    return count_in_window(window, what)


def count_in_window(window: str, what: str) -> int | None:
    """The count written in the last few words of `window` (digits or number words)."""
    written = {n.end: n for n in nb.numbers_in(window)}
    for word in reversed(list(_TOKEN_SPANS.finditer(window))[-4:]):
        number = written.get(word.end())
        if number is not None:
            return nb.count(number, what)
        if word.group(0) in NUMBER_WORDS:
            return NUMBER_WORDS[word.group(0)]
    return None


def find_landmark(scene: Scene, text: str) -> tuple[str, int] | None:
    """The landmark whose name or alias appears in `text` (longest match), and where."""
    low = normalise(text)
    best: tuple[int, str, int] | None = None
    for landmark in scene.landmarks:
        for name in landmark.names():
            key = normalise(name).strip()
            pos = low.find(" " + key)
            if pos >= 0 and (best is None or len(key) > best[0]):
                best = (len(key), landmark.name, pos)
    return (best[1], best[2]) if best else None


def find_asset_ids(scene: Scene, text: str) -> list[str]:
    """Asset ids written out literally in `text` (e.g. passenger_car_2)."""
    words = {t.removesuffix("'s") for t in tokens(text)}  # "suv_1's pose": suv_1
    return [a.id for a in scene.all_assets() if a.id in words and a.id != EGO_ID]


def mentions_ego(text: str) -> bool:
    low = normalise(text)
    return any(f" {w}" in low for w in EGO_WORDS)


def find_lane(scene: Scene, text: str) -> str | None:
    """A lane named by id ("main_eastbound") or by road and direction ("eastbound lane")."""
    low = normalise(text)
    for lane in scene.roads.lanes:
        if lane.id in low:
            return lane.id
    for lane in scene.roads.lanes:
        direction = lane.id.rsplit("_", 1)[-1]
        road = lane.road.lower()
        if f"{direction} lane" in low or (direction in low and road in low):
            return lane.id
    return None


# Coordinates are plain signed numbers; "1e9" and "nan" are read as written and refused later.
_COORD = r"([-+]?(?:\d+(?:\.\d+)?|\.\d+)(?:e[-+]?\d+)?|[-+]?(?:nan|infinity|inf))"
_COORDS = re.compile(rf"\(?\s*(?:x\s*=\s*)?{_COORD}\s*[, ]\s*(?:y\s*=\s*)?{_COORD}\s*\)?")


def find_coordinates(text: str) -> tuple[float, float] | None:
    """Coordinates written as (x, y), 'x=3 y=4' or 'at 3, 4' — after 'at' or in brackets."""
    low = text.lower()
    m = re.search(r"(?:\bat\b|\bto\b|\()\s*" + _COORDS.pattern, low)
    if m is None:  # "x 40 y -20", "x = 40 m, y = 2", "easting 30, northing -20" (as a map gives them: east is x)
        m = re.search(rf"\b(?:x|easting)\s*[=:]?\s*{_COORD}\s*(?:m\b)?\s*(?:,|and)?\s*\b(?:y|north?ing)\s*[=:]?\s*{_COORD}", low)
    if m is None:
        return None
    x, y = (nb.Number(nb.parse(m.group(i)), m.group(i), m.start(i), m.end(i)) for i in (1, 2))
    return (nb.finite(x, "a coordinate"), nb.finite(y, "a coordinate"))


def find_distance(text: str) -> float | None:
    """A distance in metres ('5 m', '10 metres'); a spacing ('4 m apart'), a radius or a speed ('10 m/s') is not one."""
    low = nb.RADIUS.sub(lambda m: " " * len(m.group(0)), nb.SPACING.sub(lambda m: " " * len(m.group(0)), text.lower()))
    low = re.sub(rf"({nb.NUMBER})\s*{nb.SPEED_UNIT}", lambda m: " " * len(m.group(0)), low)
    m = re.search(rf"({nb.NUMBER})\s*(m\b|metres?\b|meters?\b|ft\b|feet\b|foot\b|cm\b|centimet(?:re|er)s?\b)", low)
    if m is None:
        return None
    said = nb.finite(nb.Number(nb.parse(m.group(1)), m.group(1), m.start(1), m.end(1)), "a distance in metres")
    return round(said * nb.FOOT_M, 2) if m.group(2).startswith("f") else said / 100 if m.group(2).startswith("c") else said


def find_speed(text: str) -> float | None:
    """A speed: 'at 3 m/s', 'at 20 km/h' (converted to m/s), however the unit is written (nb.SPEED_UNIT)."""
    low = text.lower()
    m = re.search(rf"({nb.NUMBER})\s*{nb.SPEED_UNIT}", low) or nb.speed_said(low)
    if m is None:
        return None
    value = nb.finite(nb.Number(nb.parse(m.group(1)), m.group(1), m.start(1), m.end(1)), "a speed")
    unit = m.group(2)
    return value / 3.6 if unit.startswith(("k", "kilo")) else value * 0.447 if unit.startswith(("mph", "mile")) else value


@cache
def _any_of(words: tuple[str, ...]) -> re.Pattern[str]:
    # One alternation per word list (compiled per call overflows re's cache); "early-morning" too
    return re.compile("|".join(rf"(?<![a-z]){'[ -]'.join(map(re.escape, w.split(' ')))}(?![a-z])" for w in words))


def has_any(text: str, words: tuple[str, ...]) -> bool:
    """Whether any of `words` (whole words or phrases) occurs in `text`."""
    return bool(words) and _any_of(tuple(words)).search(normalise(text)) is not None


def known_words(scene: Scene) -> set[str]:
    """Every word the rule planner understands, for judging how much of a prompt it read."""
    words = set(NUMBER_WORDS)
    for cat in catalog().values():
        for w in cat.words:
            words.update(tokens(w))
            words.update(_singular(t) for t in tokens(w))
    for landmark in scene.landmarks:
        for n in landmark.names():
            words.update(tokens(n))
    return words


def singular(word: str) -> str:
    return _singular(word)
