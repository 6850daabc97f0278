"""What a request says about the things it names beyond their category: the compass direction
to move them, the shape to lay them out in, the material to make them of, a group named by a
catalog tag ("the vehicles"), and a share of them ("one of the rovers").

Shared by the rule planner, which acts on it, and the plan-versus-request check, which holds a
plan to it, so that both read the words the same way.
"""

from __future__ import annotations

import re
import typing
from functools import cache

from drivetwin.orchestrator.planning.rules.phrases import NUMBER_WORDS, find_categories, normalise
from drivetwin.tools.appearance import COLOURS, AssetLookArgs
from drivetwin.tools.search import COMPASS_VECTORS
from drivetwin.worlds.catalog import catalog

# A compass direction said as a way to go ("2 m east", "eastward", "to the north"), not as part of
# a lane's or a place's name ("the northbound lane", "the east gate": find_place masks places),
# a side of something else ("east of the fountain") or a heading ("facing north").
_COMPASS = re.compile(r"(?<!facing )(?<!face )\b(north|south|east|west)(?:wards?)?\b"
                      r"(?!-| ?bound| gate| side of\b| entrance| crosswalk| crossing| of\b| sidewalk| pavement| footway| footpath| verge)")
# The compass heading a thing should face ("turned to face north", "pointing west").
_FACING = re.compile(r"\b(?:face|faces|facing|point|points|pointing)\s+(?:to(?:wards?)?\s+)?(?:the\s+)?(north|south|east|west)\b")


def facing_direction(text: str) -> str | None:
    """The compass point the words say a thing should face, if any."""
    said = _FACING.search(text)
    return said.group(1) if said else None


# A side or corner of a place, or the one of several furthest one way: "on the north-east corner",
# "the western one", "the southernmost".
_OUTER = re.compile(r"\b(?:(north|south)(?:[- ]?(east|west))?|(east|west))(?:ern|ernmost|most)?\s+(?:corner|side|one|end|edge)\b"
                    r"|\b(north|south|east|west)(?:ern)?-?most\b|\b(?:furthest|farthest|most) (north|south|east|west)\b(?! of\b)")


def outer_direction(text: str) -> tuple[float, float] | None:
    """The unit vector of the side, corner or extreme the words name; None for none."""
    said = _OUTER.search(text)
    if said is None:
        return None
    east, north = 0.0, 0.0
    for word in filter(None, said.groups()):
        east, north = east + COMPASS_VECTORS[word][0], north + COMPASS_VECTORS[word][1]
    size = (east**2 + north**2) ** 0.5
    return (east / size, north / size)


def compass_direction(text: str) -> str | None:
    """The one compass direction the words say to go ("2 m east"); None for none, or for two
    ("north-east", "east then north"): not one direction."""
    if _BETWEEN_POINTS.search(text):
        return None  # "2 m north-east": not east (see compass_vector)
    said = {m.group(1) for m in _COMPASS.finditer(text)}
    return said.pop() if len(said) == 1 else None


# A way between two compass points: "north-east", "south west", "northwestwards".
_BETWEEN_POINTS = re.compile(r"\b(north|south)[\s-]?(east|west)(?:wards?)?\b"
                             r"(?! ?bound| gate| side of\b| entrance| crosswalk| crossing| of\b| corner| sidewalk| pavement| footpath)")


def compass_vector(text: str) -> tuple[float, float] | None:
    """The unit vector of the way the words say to go, a point between two included ("4 m
    north-east": both ways at once); None for none or for several."""
    between = {m.groups() for m in _BETWEEN_POINTS.finditer(text)}
    if len(between) == 1:
        first, second = between.pop()
        east, north = (a + b for a, b in zip(COMPASS_VECTORS[first], COMPASS_VECTORS[second], strict=True))
        return (round(east / 2**0.5, 4), round(north / 2**0.5, 4))
    word = compass_direction(text)
    return COMPASS_VECTORS[word] if word is not None else None


# A thing picked by its size among those of a kind or group ("the biggest vehicle", "which tree is
# the tallest"): the word (group 1), read as the search tool's superlative by most_said.
SIZE_WORDS = ("tallest", "highest", "shortest", "heaviest", "lightest", "longest", "widest", "biggest", "largest", "smallest", "tiniest")
SIZE_SUPERLATIVE = re.compile(rf"\b({'|'.join(SIZE_WORDS)})\b")
_MOST_AS = {"highest": "tallest", "largest": "biggest", "tiniest": "smallest"}


def most_said(word: str) -> str:
    """The search tool's superlative for a size word ("largest" is "biggest")."""
    return _MOST_AS.get(word, word)


# Words after which a singular names a kind, not one thing: "every vehicle", "how many vehicle", "the biggest vehicle".
_COUNTING = r"\b(?:every|each|all|any|how many|\d+|" + SIZE_SUPERLATIVE.pattern.removeprefix(r"\b") + r") "



@cache
def _catalog_groups() -> dict[str, frozenset[str]]:
    """Catalog tags shared by several categories, each with its categories."""
    members: dict[str, set[str]] = {}
    for name, entry in catalog().items():
        for tag in entry.tags:
            members.setdefault(tag, set()).add(name)
    return {tag: frozenset(names) for tag, names in members.items() if len(names) > 1}


def catalog_tags() -> frozenset[str]:
    """The catalog's words for groups of categories ("vehicle", "sign", "light")."""
    return frozenset(_catalog_groups())


def kind_of(categories: set[str]) -> str | None:
    """How a search names things of these categories: the category, or the smallest catalog group
    holding them all in the plural ("cars" for sedans and SUVs); None when no group does."""
    if len(categories) == 1:
        return next(iter(categories))
    groups = [(len(members), tag) for tag, members in _catalog_groups().items() if categories <= members]
    return min(groups)[1] + "s" if groups else None


def groups_said(text: str) -> dict[str, frozenset[str]]:
    """The groups the words name by a catalog tag in the plural, or in the singular after a word
    that counts ("the vehicles", "all the signs", "every parked vehicle", "2 vehicle", "how many
    vehicle"), each with its categories; not the "lights" of "the street lights", a category's own name."""
    low = normalise(text)
    names = [(m.start, m.end) for m in find_categories(text)]

    def inside_a_name(said: re.Match[str]) -> bool:
        start, end = said.start("tag"), said.end()
        return any(s <= start and end <= e and e - s > end - start for s, e in names)

    return {
        tag: members
        for tag, members in _catalog_groups().items()
        if any(
            (said.group("plural") or said.group("counted")) and not inside_a_name(said)
            for said in re.finditer(rf"(?P<counted>{_COUNTING}(?:[a-z]+ )?)?\b(?P<tag>{re.escape(tag)})(?P<plural>s)?\b", low)
        )
    }


# A layout said by its shape; "stop line" and "lane line" are road markings, not layouts.
_LAYOUT = re.compile(r"(?<!stop )(?<!lane )\b(line|row|ring|circle|grid|lattice|matrix|side by side|next to each other|avenue|queue|wall(?=s? of)"
                     r"|single file|semi-?circle|half[- ]circle|zig-?zag|slalom)s?\b")


# Setting a thing in motion: "get the suv moving", "start the truck rolling" (not a pick of moving ones).
SET_GOING = re.compile(r"\b(?:get|gets|start|starts|set|sets)\s+(?:[a-z_0-9']+\s+){1,3}(?:moving|going|driving|rolling)\b"
                       # "make the cars move": off they go, when no place or step is said after
                       r"|\b(?:make|makes|have|has|let|lets)\s+(?:[a-z_0-9']+\s+){1,3}(?:move|go|drive|roll)\s*(?:[.!?,;]|$|please\b|now\b)")
# That many on each side ("six bollards on each side of it"): two sides' worth.
EACH_SIDE = re.compile(r"\b(?:each|either|every)\s+side\b")
# Both edges said: "on both sides", "either kerb", "each edge of the lane": two rows, one a side.
BOTH_SIDES = re.compile(r"\b(?:both|either|each)\s+(?:sides?|edges?|kerbs?|curbs?)\b|\bon (?:both|each|either) side\b")


# Rows counted: "six benches in two rows" is a grid of two rows.
_ROWS = re.compile(r"\b(?:in|into|as)\s+(\d+|two|three|four|five|six)\s+(?:rows|lines|ranks)\b")


def rows_said(text: str) -> int:
    """How many rows the words lay things out in ("in two rows": 2); 0 when they count none."""
    said = _ROWS.search(text)
    return 0 if said is None else int(said.group(1)) if said.group(1).isdigit() else NUMBER_WORDS.get(said.group(1), 0)


def layout_said(text: str) -> str | None:
    """The shape of layout the words ask for ("in a line", "a row of", "a ring", "side by side"
    is a row, "in two rows" a grid), if any."""
    said = _LAYOUT.search(text)
    if said is None:
        return None
    if rows_said(text) >= 2:
        return "grid"
    # an avenue: trees in a line; a lattice: a grid
    return {"side by side": "row", "next to each other": "row", "avenue": "line", "lattice": "grid", "matrix": "grid", "queue": "line",
            "wall": "line", "single file": "line", "zigzag": "line", "zig-zag": "line", "slalom": "line", "semicircle": "ring", "semi-circle": "ring", "half circle": "ring",
            "half-circle": "ring"}.get(said.group(1), said.group(1))


_MATERIALS = frozenset(m for m in typing.get_args(typing.get_args(AssetLookArgs.model_fields["material"].annotation)[0])
                       if m != "default")
# Adjective forms of the materials ("wooden bench", "metallic car").
MATERIAL_WORDS = {**{m: m for m in _MATERIALS}, "wooden": "wood", "metallic": "metal", "shiny": "glossy",
                   "planks": "wood", "timber": "wood", "steel": "metal", "aluminium": "metal", "iron": "metal", "chrome": "metal",
                   "cement": "concrete", "stone": "concrete", "glossy": "glossy", "gloss": "glossy", "matt": "matte"}


def material_said(text: str) -> str | None:
    """The material the words ask a thing to look like ("wooden benches"), as the appearance
    Worker names it."""
    return next((MATERIAL_WORDS[w] for w in re.findall(r"[a-z]+", text.lower()) if w in MATERIAL_WORDS), None)


# A colour that picks a thing out or says what it is, not what to make it: "the red one", "the blue car", "not red", "is red".
_COLOUR_SAID = re.compile(r"\b(?:(the|that|this|those|these|not|no|than|from|is|are|was|were|already|still|currently|of)\s+)?"
                          rf"({'|'.join(COLOURS)})\b(?!-)(\s+ones?\b)?")


# A traffic signal's state, never a colour to paint: "waiting at a red light", "the green signal".
SIGNAL_STATE = re.compile(r"\b(?:red|green|amber|yellow)\s+(?:lights?|signals?|phase)\b")


# A shade said alone, as a reply to a turn that painted things: "nah, darker", "a bit lighter please".
SHADE_ALONE = re.compile(r"^(?:\w+\s*[,!.]?\s+){0,2}(?:a (?:bit|little|touch|shade)\s+|slightly\s+|much\s+|even\s+)?(darker|deeper|lighter|paler|brighter)\b"
                         r"(?:\s+(?:please|pls|than that|still|again|one))*\s*[.!?]*\s*$")


# A colour said as what a thing should not be: "less red", "anything but red", "no longer red".
NOT_THAT_COLOUR = re.compile(rf"(?:\b(?:not|no|less|but|than|longer|never)|n't)\s+(?:be\s+)?({'|'.join(COLOURS)})\b")


def colours_asked(low: str) -> list[str]:
    """The colours a request asks things to be made, in order: every colour named but those that
    select or describe ("paint the red car blue" asks for blue only) and a signal's state."""
    starts = {m.start for m in find_categories(low)}
    unwanted = {m.start(1) for m in NOT_THAT_COLOUR.finditer(low)}  # "the bench should not be brown"
    asked: list[str] = []
    for m in _COLOUR_SAID.finditer(low):
        rest = low[m.end(2) :]
        if m.group(1) or m.group(3) or m.start(2) in unwanted or m.end(2) + len(rest) - len(rest.lstrip()) in starts or SIGNAL_STATE.match(low, m.start(2)):
            continue
        if asked and re.fullmatch(rf"{re.escape(asked[-1])}\s+", low[m.start(2) - len(asked[-1]) - 1 : m.start(2)]):
            continue  # "navy blue", "lime green": the first word is the shade of the second
        asked.append(m.group(2))
    return asked


# "one of the small research rovers", "two of those cones": the number counts the thing named.
_PARTITIVE = re.compile(r"\b(\w+)\s+of\s+(?:the|those|these|our|your|its|their)\s+(?:[a-z-]+\s+){0,3}$")


def partitive_word(before: str) -> str | None:
    """The word of a partitive ("one", "some" of "some of the ...") right before a thing named."""
    said = _PARTITIVE.search(before)
    return said.group(1) if said is not None else None


def partitive_count(before: str) -> int | None:
    """The number of a partitive ("one of the ...") right before a thing named, if there is one."""
    word = partitive_word(before)
    if word is None:
        return None
    return int(word) if word.isdigit() else NUMBER_WORDS.get(word)


# Words for a small step or turn ("a bit", "a tiny bit", "slightly"), and for a small move of a thing
# ("nudge it", "budge the bin", "a tad"): the rules take a small step for them, the check holds a plan to one.
SMALL = ("a bit", "slightly", "a little", "tiny bit", "little bit", "wee bit")
SMALL_MOVE = (*SMALL, "a touch", "a tad", "a smidge", "a fraction", "a few inches", "a few centimetres", "nudge", "inch",
              "budge", "scoot")


__all__ = ["COMPASS_VECTORS", "MATERIAL_WORDS", "SIZE_SUPERLATIVE", "SIZE_WORDS", "SMALL", "SMALL_MOVE", "catalog_tags", "compass_direction", "compass_vector", "facing_direction", "groups_said",
           "kind_of", "layout_said", "material_said", "most_said", "outer_direction", "partitive_count", "partitive_word", "rows_said"]
