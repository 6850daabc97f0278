"""Keyboard slips: each of these requests (worded here, none from a suite) is typed again with a
slip in a word of five letters or more (a letter dropped, doubled, swapped with the next, or a key's
neighbour struck instead), and the slipped request must change the scene exactly as the clean one
does, or change nothing and ask or refuse: a slip never becomes a different edit. The slips are drawn
by a seeded generator, the same on every run."""

from __future__ import annotations

import random
import re
import zlib

import pytest
from drivetwin.evals.trial import fresh_world
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.scene import Scene

CLEAN = (
    "add three traffic cones in front of the library",
    "remove the bench near the bus stop",
    "move the hydrant two metres to the left",
    "paint the suv yellow",
    "make it snow heavily",
    "set the time to half past seven in the evening",
    "put a pedestrian crossing the road ahead of the ego",
    "where is the nearest tree to the fountain",
    "take away all the street lights on the north side",
    "place a barrier across the westbound lane",
    "add a bicycle on the sidewalk outside engineering hall",
    "delete the trash bin",
    "make it foggy",
    "make the passenger car on the west end of the row blue",
    "put two barriers next to the stop sign",
    "spread five cones along the eastbound lane",
    "remove every tree",
    "move the bench to the other side of the road",
    "let the suv drive to the east gate",
    "set it to midnight",
    "add a delivery truck parked in lot a",
    "paint the traffic light by the crosswalk black",
    "how many street lights are there",
    "add a jaywalker crossing in front of the ego",
    "clear the fog",
    "move the trash bin closer to the library",
    "place four pedestrians waiting at the bus stop",
    "make the suv reverse out of its space",
    "turn the hydrant around to face the road",
    "add a row of barriers along the south sidewalk",
    "make the sky overcast",
    "rotate the bench ninety degrees",
    "put a shuttle bus at the bus stop",
    "add a school bus behind the ego",
    "remove the fire hydrant",
    "move the suv forward five metres",
    "make the bench green",
    "make it rain lightly",
    "set the clock to six in the morning",
    "add two cyclists riding along the westbound lane",
    "show me where the library is",
    "get rid of the parked cars in lot b",
    "put a construction sign before the crosswalk",
    "add a dog walker on the north sidewalk",
    "take out the stop sign near the crosswalk",
    "turn off the street lights",
    "paint every tree orange",
    "place three barriers in a line across main street",
    "remove the trees near the fountain",
    "move the bin next to the bench",
    "make the suv drive slowly around the block",
    "change the time to dusk",
    "how far is the fountain from the library",
    "arrange the benches in a semicircle",
    "add a pedestrian who stops in the middle of the road",
    "turn the weather sunny",
    "move the bus stop bench to lot a",
    "place six cones spaced evenly along the south sidewalk",
    "make the snow heavier",
    "remove half of the street lights",
    "add a truck driving towards the ego",
    "rotate the suv to face west",
    "add a wheelie bin at the east gate",
    "put a box truck in front of the library",
    "add some debris on the road ahead of the ego",
)
SLIPS_PER_REQUEST = 3
_ROWS = ("qwertyuiop", "asdfghjkl", "zxcvbnm")


def _neighbour(letter: str, rng: random.Random) -> str:
    for row in _ROWS:
        if letter in row:
            i = row.index(letter)
            return rng.choice([row[j] for j in (i - 1, i + 1) if 0 <= j < len(row)])
    return letter


def slip(word: str, rng: random.Random) -> str:
    """`word` with one keyboard slip, never in its first letter."""
    i = rng.randrange(1, len(word) - 1)
    return rng.choice((
        word[:i] + word[i + 1 :],  # dropped
        word[:i] + word[i] + word[i:],  # doubled
        word[:i] + word[i + 1] + word[i] + word[i + 2 :],  # swapped with the next
        word[:i] + _neighbour(word[i], rng) + word[i + 1 :],  # a neighbouring key
    ))


def slipped(prompt: str) -> list[str]:
    """Up to SLIPS_PER_REQUEST copies of `prompt`, each with one slip in a different long word."""
    rng = random.Random(zlib.crc32(prompt.encode()))
    words = list(re.finditer(r"[a-z]{5,}", prompt))
    out = []
    for m in rng.sample(words, min(SLIPS_PER_REQUEST, len(words))):
        typed = slip(m.group(), rng)
        if typed != m.group():
            out.append(prompt[: m.start()] + typed + prompt[m.end() :])
    return out


def _after(prompt: str, registry: ToolRegistry) -> tuple[bool, Scene]:
    session = Session(fresh_world("campus"), RulePlanner(), registry)
    return session.submit(prompt).ok, session.scene


def test_the_generator_slips_every_request_and_keeps_its_first_letters():
    for prompt in CLEAN:
        typed = slipped(prompt)
        assert typed and all(t != prompt for t in typed), prompt
        assert all([w[0] for w in t.split()] == [w[0] for w in prompt.split()] for t in typed), prompt


@pytest.mark.parametrize("prompt", CLEAN)
def test_a_slipped_request_does_what_the_clean_one_does_or_nothing(prompt, registry):
    ok, clean_scene = _after(prompt, registry)
    assert ok, prompt  # the clean request itself is done
    untouched = fresh_world("campus")
    read = 0
    for typed in slipped(prompt):
        ok, scene = _after(typed, registry)
        if ok:
            assert scene == clean_scene, f"{typed!r} changed the scene otherwise than {prompt!r}"
            read += 1
        else:
            assert scene == untouched, typed  # asked or refused: nothing changed
    assert read >= 1, f"no slip of {prompt!r} was read"  # slips are repaired, not merely refused
