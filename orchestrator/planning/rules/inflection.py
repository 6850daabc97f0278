"""A verb's inflected forms, for word lists written in base forms ("drive" is also "drives",
"driving", "drived" is harmless): one generator for the readers that match such lists and for the
spelling repair that must know every form as a word."""

from __future__ import annotations

import re
from functools import cache

# Letters after which a final consonant is not doubled ("snowing", "drawing", "fixing").
_NOT_DOUBLED = "wxy"


def forms(verb: str) -> tuple[str, ...]:
    """The verb as written, with -s/-es, -ing and -ed (the final e dropped, or the final consonant
    doubled after a single vowel: "pedal" -> "pedalling" as well as "pedaling")."""
    if verb.endswith("e"):
        return verb, f"{verb}s", f"{verb[:-1]}ing", f"{verb}d"
    out = [verb, f"{verb}s", f"{verb}es", f"{verb}ing", f"{verb}ed"]
    if len(verb) >= 3 and verb[-1] not in "aeiou" + _NOT_DOUBLED and verb[-2] in "aeiou" and verb[-3] not in "aeiou":
        out += [f"{verb}{verb[-1]}ing", f"{verb}{verb[-1]}ed"]
    return tuple(out)


@cache
def inflected(phrases: tuple[str, ...]) -> re.Pattern[str]:
    """A pattern for any of `phrases` with its first word in any of its `forms` ("set off" is
    also "sets off" and "setting off"), as whole words."""
    alternatives = []
    for phrase in phrases:
        verb, _, rest = phrase.partition(" ")
        words = "|".join(sorted(forms(verb), key=len, reverse=True))
        alternatives.append(rf"(?<![a-z])(?:{words}){(' ' + re.escape(rest)) if rest else ''}(?![a-z])")
    return re.compile("|".join(alternatives))


__all__ = ["forms", "inflected"]
