"""Numbers as people write them: "3", "2.5", "10,000", "1e2", and the words that are no number.

Every amount the rule planner reads (counts, metres, coordinates, speeds) is parsed here, so
"1e2 m" is 100 m rather than 2 m, and "10,000 cones" is ten thousand rather than three. A
value that is no finite amount ("nan", "inf") or cannot be what it quantifies (a count of
2.5, of 0, or negative) is refused with a message that says what was read and what is
allowed: the planner never substitutes a default for a number it was given.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from drivetwin.orchestrator.planning.base import PlanningError

# Units people type straight after a figure ("5m", "30kmh", "2s", "90deg"): a number may end
# at one of these; any other letter makes it part of a word or an id ("2nd", "car_2").
GLUED_UNITS = r"(?:m|km|kmh|kph|mph|ms|s|sec|secs|deg)"
# A written number: digits with optional thousands separators, decimals and an exponent, or
# the words that parse as floats but are no amount. Not part of an id ("car_2") or a word;
# "45ish" is about 45.
NUMBER = (
    r"(?<![\w.])(?:[-+]?(?:\d{1,3}(?:,\d{3})+(?![\d,])|\d+(?:\.\d+)?|\.\d+)(?:e[-+]?\d+)?"
    rf"(?=(?:{GLUED_UNITS}|ish)?(?!\w))|[-+]?(?:nan|infinity|inf)(?![\w]))"
)
_NUMBER = re.compile(NUMBER, re.IGNORECASE)
# The most of anything one request may count: far above what a scene can hold, so a larger
# figure is a slip or a test of limits, refused in words rather than truncated.
MAX_COUNT = 1_000_000


class NumberError(PlanningError):
    """A number in the request that cannot be the amount it stands for (nan, inf, 2.5 cones)."""


@dataclass(frozen=True)
class Number:
    """A number found in text: its value, the words it was written as, and where."""

    value: float
    text: str
    start: int
    end: int

    @property
    def finite(self) -> bool:
        return math.isfinite(self.value)


_ONES = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
         "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen"]
_TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90}
_BELOW_HUNDRED = rf"(?:{'|'.join(_TENS)})(?:[- ](?:{'|'.join(_ONES[1:10])}))?|{'|'.join(_ONES)}"
# "a hundred and eighty", and the half turn said "one eighty" or "one-eighty"
_SPELT = (rf"(?:(?:one|a)[- ]eighty|(?:one|a) hundred(?: and (?:{_BELOW_HUNDRED}))?|{_BELOW_HUNDRED}|a|an)"
          r"(?: and a half)?")
# A measure spelt out ("two metres", "forty-five degrees", "a metre", "half a metre", "a few metres"): the words
# become figures so every reader of amounts with units reads it as if typed in digits.
_SPELT_MEASURE = re.compile(
    rf"\b(half an?|a couple(?: of)?|a few|{_SPELT})\s+(?=(?:m|metres?|meters?|ft|feet|foot|km|kilometres?|kilometers?|yards?|"
    r"(?:car|vehicle)[- ]lengths|degrees?|"
    r"seconds?|secs?|m/s|km/h|kph|mph|hours?|minutes?|mins?)\b)",
    re.IGNORECASE,
)


# The half said after the unit: "a metre and a half", "two hours and a half", "3 m and a half".
_UNIT_AND_A_HALF = re.compile(rf"\b({_SPELT}|\d+)\s+(m|metres?|meters?|ft|feet|foot|km|kilometres?|kilometers?|yards?|"
                              r"seconds?|secs?|hours?|minutes?|mins?)\s+and a half\b", re.IGNORECASE)


def _half_before_unit(m: re.Match[str]) -> str:
    number, unit = m.group(1), m.group(2)
    return f"{float(number) + 0.5:g} {unit}" if number.isdigit() else f"{number} and a half {unit}"


def _spelt_value(words: str) -> float:
    low = words.lower().replace("-", " ")
    half = 0.5 if low.endswith(" and a half") else 0.0
    low = low.removesuffix(" and a half")
    if low.startswith("half"):
        return 0.5
    if low.startswith(("a couple", "a few")):  # "a couple of metres", "a few seconds": vague, said as 2 and 3
        return 2.0 if "couple" in low else 3.0
    if low in ("a", "an"):
        return 1.0 + half
    if low in ("one eighty", "a eighty"):
        return 180.0
    if "hundred" in low:
        rest = low.partition(" and ")[2]
        return 100.0 + (_spelt_value(rest) if rest else 0.0) + half
    parts = low.split()
    tens = _TENS.get(parts[0], 0)
    ones = _ONES.index(parts[-1]) if parts[-1] in _ONES else 0
    return float(tens + ones if tens else ones) + half


def spelt_counts() -> dict[str, int]:
    """Every count spelt as one word, "one" to "ninety-nine" and "hundred" ("seventy", "thirty-five")."""
    counts = {word: n for n, word in enumerate(_ONES) if n}
    for tens, value in _TENS.items():
        counts[tens] = value
        counts.update({f"{tens}-{one}": value + n for n, one in enumerate(_ONES[1:10], start=1)})
    return counts | {"hundred": 100}


# Lengths in other units, said in metres by every reader: a yard, a foot, and a car's length as people
# measure gaps on a road ("nudge it up a car length", "two car lengths back").
YARD_M = 0.9144
CAR_LENGTH_M = 4.5
FOOT_M = 0.3048
_OTHER_LENGTHS = re.compile(r"\b(\d+(?:\.\d+)?)\s*(yards?|yds?|feets?|foots?|ft|(?:car|vehicle)[- ]lengths?)\b(?!\s*tall)", re.IGNORECASE)
_ONE_CAR_LENGTH = re.compile(r"\b(?:a|one) (?:car|vehicle)[- ]length\b", re.IGNORECASE)


# Dozens said in words: "half a dozen cones" are 6, "two dozen" 24 (a bare "dozen" is the count words' 12).
_DOZENS = re.compile(r"\b(half a|a half|a|one|two|three|four|five)[- ]dozen\b", re.IGNORECASE)
_DOZEN_OF = {"half a": 6, "a half": 6, "a": 12, "one": 12, "two": 24, "three": 36, "four": 48, "five": 60}


# Hundreds and thousands of things: "a thousand people" are 1000, "two hundred cones" 200 (a
# measure, "a hundred and eighty degrees", is spelt out in figures before).
_MULTIPLES = re.compile(rf"\b({_BELOW_HUNDRED}|a)[- ](hundred|thousand)\b(?! and\b)", re.IGNORECASE)
_MULTIPLE_OF = {"hundred": 100, "thousand": 1000}


def spelt_measures(text: str) -> str:
    """`text` with measures spelt in words written in figures ("two metres" -> "2 metres"), dozens,
    hundreds and thousands as counts ("half a dozen" -> "6", "a thousand" -> "1000"), and lengths in yards or car lengths in metres ("3 yards" ->
    "2.74 m", "5 feet" -> "1.52 m")."""
    def figures(m: re.Match[str]) -> str:
        article = m.group(1).lower() in ("a", "an")
        if article and re.match(r"(?:m|ft|km|secs?|mins?|mph|kph)\b", m.string[m.end() :], re.IGNORECASE):
            return m.group(0)  # "7 a m" is a time of day; "a metre" is one
        return f"{_spelt_value(m.group(1)):g} "

    def metres(m: re.Match[str]) -> str:
        said = m.group(2).lower()
        unit = YARD_M if said.startswith("y") else FOOT_M if said.startswith("f") else CAR_LENGTH_M
        return f"{float(m.group(1)) * unit:.3g} m"

    text = _DOZENS.sub(lambda m: str(_DOZEN_OF[m.group(1).lower()]), text)
    text = _UNIT_AND_A_HALF.sub(_half_before_unit, text)
    text = _ONE_CAR_LENGTH.sub(f"{CAR_LENGTH_M:g} m", _SPELT_MEASURE.sub(figures, text))
    text = _MULTIPLES.sub(lambda m: f"{_spelt_value(m.group(1)) * _MULTIPLE_OF[m.group(2).lower()]:g}", text)
    if not re.search(rf"({NUMBER})\s*{SPEED_UNIT}", text, re.IGNORECASE):  # "walking pace, no more than 2 m/s": the figure said
        text = _PACE.sub(lambda m: f"{_PACE_MS[m.group(1).lower()]:g} m/s", text)
    return _OTHER_LENGTHS.sub(metres, text)


# A speed said as a person's pace: "at walking pace" is 1.4 m/s (5 km/h), a jog 2.5, a run 3.5.
_PACE_MS = {"walking": 1.4, "walk": 1.4, "jogging": 2.5, "jog": 2.5, "running": 3.5, "run": 3.5}
# A decimal comma ("4,5 m", "exposure 1,5"): one or two figures after it, with a unit or a setting's name (a pair
# of figures alone, "cones at 10,5", may be coordinates and stays two numbers; "10,000" is ten thousand).
_DECIMAL_COMMA = re.compile(r"(?<![\d,])(\d+),(\d{1,2})(?=\s*(?:m\b|metres?\b|meters?\b|m/s|km/?h\b|kph|mph|s\b|secs?\b|seconds?\b|"
                            r"hours?\b|h\b|degrees?\b|deg\b|%))", re.IGNORECASE)
_SETTING_DECIMAL = re.compile(r"\b((?:exposure|brightness|intensity|speed)\s*(?:(?:to|=|of|at|:)\s*)?)(\d+),(\d{1,2})\b(?![,.]?\d)",
                              re.IGNORECASE)


def decimal_points(text: str) -> str:
    """`text` with each decimal comma written as a point, as every reader of amounts expects."""
    return _SETTING_DECIMAL.sub(r"\1\2.\3", _DECIMAL_COMMA.sub(r"\1.\2", text))


_PACE = re.compile(r"\b(?:a\s+)?(walking|walk|jogging|jog|running|run)(?:ning)?\s+(?:pace|speed)\b", re.IGNORECASE)


def parse(text: str) -> float:
    """The value of one written number ("10,000" -> 10000.0, "1e2" -> 100.0, "nan" -> nan)."""
    return float(text.replace(",", "").lower())


def numbers_in(text: str) -> list[Number]:
    """Every written number in `text`, in order."""
    return [Number(parse(m.group(0)), m.group(0), m.start(), m.end()) for m in _NUMBER.finditer(text)]


def finite(number: Number, what: str) -> float:
    """The value of `number`, or a NumberError naming `what` it was meant to be."""
    if not number.finite:
        raise NumberError(f"{number.text!r} is not a number I can use as {what}; give a figure, e.g. 5")
    return number.value


def count(number: Number, what: str) -> int:
    """`number` as a count of `what`: a whole number from 1 to MAX_COUNT, else a NumberError."""
    value = finite(number, f"a number of {what}")
    if value != int(value) or value < 1:
        raise NumberError(f"{number.text!r} is not a number of {what}; say how many, e.g. 3")
    if value > MAX_COUNT:
        raise NumberError(f"{number.text} {what} is more than any scene can hold; ask for fewer")
    return int(value)



# A spacing between things laid out ("4 m apart"): not a distance to a place.
# ("2 m between", "2 metres in between each": between them, never "2 m between the bench and the bin")
SPACING = re.compile(r"(\d+(?:\.\d+)?)\s*(?:m|metres?|meters?)\s+(?:apart|spacing|gaps?|(?:in\s+)?between\b(?!\s+(?:the|a|an|that|this|those|these|lots?|parking)\b))\b"
                     r"|\b(?:every|spaced(?: out)?(?: by)?|at|spacing(?: of)?|gaps? of)\s+(\d+(?:\.\d+)?)\s*(?:m|metres?|meters?)\b"
                     r"(?:\s+(?:intervals?|centres|centers|c/c|spacing|apart))?")


def spacing_said(text: str) -> float | None:
    """The spacing the words ask for between things laid out ("4 m apart", "every 3 m", "at 5 m
    intervals"), in metres."""
    for said in SPACING.finditer(text.lower()):
        if said.group(0).startswith("at") and not said.group(0).endswith(("interval", "intervals", "centres", "centers", "c/c", "spacing", "apart")):
            continue  # "at 5 m" is where, not how far apart ("at 3 m centres" is)
        return float(said.group(1) or said.group(2))
    return None


# A speed's unit: metres a second however written ("m/s", "mps", "metres per second", "meters a sec"),
# km/h and mph ("an hour" may read "1 hour"); a bare "ms" after "at" is a speed typed in a hurry.
SPEED_UNIT = (r"(m/s|m/sec|mps|m\s?per\s?s(?:ec(?:ond)?)?|met(?:re|er)s?\s(?:per|an?|1)\s(?:sec(?:ond)?|secnd|s)\b|km/h|kmh|kph"
              r"|km\s?per\s?hour|kilomet(?:re|er)s?\s(?:per|an?|1)\shour|mph|miles?\s(?:per|an?|1)\shour)")


# The radius of a ring or a circle driven ("a radius of 3 m", "at a 3 m radius", "radius 5", "r=3 m").
RADIUS = re.compile(r"\b(?:radius|r\s*=)\s*(?:of )?(\d+(?:\.\d+)?)(?:\s*(?:m|metres?|meters?)\b)?|(\d+(?:\.\d+)?)\s*(?:m|metres?|meters?)?\s*radius\b"
                    # "six trees round the fountain, about 8 m out": how far out from the middle
                    r"|(\d+(?:\.\d+)?)\s*(?:m|metres?|meters?)\s+(?:out(?!\s+of\b)|away from (?:the |its )?(?:centre|center|middle))\b")


def radius_said(text: str) -> float | None:
    """The radius the words ask for, in metres."""
    said = RADIUS.search(text.lower())
    return float(said.group(1) or said.group(2) or said.group(3)) if said else None


# "at 5 ms": metres per second with the slash dropped.
_SPEED_MS = re.compile(rf"\b(?:at|to|of|doing) ({NUMBER})\s*(ms)\b")
# "ego.speed = 8", "set its speed to 8", "faster, like 10": a bare number said of a speed is in the simulator's unit, m/s
_SPEED_BARE = re.compile(rf"\b(?:speed|faster|slower|quicker|slow(?: it)? down)\s*(?:up\s+|down\s+)?(?:,\s*)?(?:to|of|at|=|:|is|like)?\s*(?:about\s+|around\s+|roughly\s+)?({NUMBER})()(?!\s*(?:%|x\b|times\b|{SPEED_UNIT}|m\b|metres?\b|meters?\b))")


def speed_said(low: str) -> re.Match[str] | None:
    """A speed said without its usual unit: the number (group 1) and the unit as written (group 2, "" for m/s)."""
    return _SPEED_MS.search(low) or _SPEED_BARE.search(low)


# The units measures are said in, spelt out: what a slip in one ("6 metrs") is repaired to.
UNIT_WORDS = ("metres", "meters", "metre", "meter", "kilometres", "kilometers", "seconds", "second", "minutes", "hours", "degrees",
              "yards", "feet", "inches")

__all__ = ["FOOT_M", "MAX_COUNT", "NUMBER", "RADIUS", "SPACING", "SPEED_UNIT", "UNIT_WORDS", "Number", "NumberError", "count", "finite", "numbers_in", "parse",
           "radius_said", "spacing_said", "speed_said", "spelt_measures"]
