"""Clock times as people say them: "18:30", "6.15 pm", "7 o'clock", "half past ten at night",
"half seven" (British), "quarter to seven", "twenty past six in the evening", "six thirty in the
evening", "midnight", "nine in the evening", "set the clock to 9".

One reader for the rule planner (which sets the time) and the plan check (which compares the
time a plan sets with the one the words name), so the two cannot disagree about what a
sentence means. A time that cannot be on a clock ("25:70") is read as such and refused by
the caller rather than dropped.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

# Hours and minutes said in words; "a quarter", "half" are minutes in their own phrases.
_WORD_NUMBERS = {
    "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9,
    "ten": 10, "eleven": 11, "twelve": 12, "fifteen": 15, "twenty": 20, "twenty-five": 25,
    "twenty five": 25, "thirty": 30,
}
# The words a clock time is said in, which a slip in them ("quater to seven") is repaired to.
CLOCK_WORDS = ("quarter", "half", "past", "o'clock", *_WORD_NUMBERS)
_HOUR = r"(\d{1,2}|" + "|".join(sorted(_WORD_NUMBERS, key=len, reverse=True)) + ")"
# Words after a time that say which half of the day it is in.
_AFTERNOON = re.compile(r"^\s*(pm|p\.m\.|(?:in|of|during) (?:the )?(afternoon|evening)|at night|tonight|(?:in the|of|of the) night)\b")
_MORNING = re.compile(r"^\s*(am|a\.m\.|in the morning)\b")
# Parts of the day that put a 12-hour time said anywhere in the request after noon.
_LATER_IN_DAY = re.compile(r"\b(?:evening|afternoon|tonight|dusk|sunset|after work|rush hour home)\b")
# "18:30", "18.30" (with a time word near), "6 pm", "7 o'clock", "0630 hours".
_DIGITAL = re.compile(r"(?<![\w.:])(\d{1,2})\s*(?:([:.])\s*(\d\d))?\s*(am|pm|a\.m\.|p\.m\.|o'?\s?clock|h|hrs|hours)?(?![\w:])")
# "half past ten", "a quarter to seven", "twenty past six", "10 past 4".
_SPOKEN = re.compile(rf"\b(half|(?:a )?quarter|{_HOUR}(?: minutes)?) (past|after|to|before) {_HOUR}\b")
# "half seven": half past seven, as said in Britain (never "half a metre": only an hour follows).
_HALF_HOUR = re.compile(rf"\bhalf {_HOUR}\b(?! (?:past|after|to|before)\b)")
_O_CLOCK = re.compile(r"^\s*o'?\s?clock\b")
_NAMED = {"midnight": (0, 0), "noon": (12, 0), "midday": (12, 0)}
# Minutes before or after a named time, said just before it ("quarter to midnight").
_NEAR_NAMED = re.compile(rf"\b(?P<said>half|(?:a )?quarter|{_HOUR}(?: minutes)?) (?P<way>past|after|to|before) $")
# "18.30" without a suffix is a clock time only when the sentence is about time.
_TIME_TOPIC = re.compile(r"\b(time|clock)\b")
_WORD_HOURS = "|".join(sorted((w for w, n in _WORD_NUMBERS.items() if n <= 12), key=len, reverse=True))
# "six thirty", "seven fifteen", "ten oh five": the hour and then its minutes, as a digital clock is read aloud
# (a time only where the words say which half of the day it is in, or talk of the time: never "six twenty-metre poles").
_MINUTE_WORDS = {"oh five": 5, "ten": 10, "fifteen": 15, "twenty": 20, "twenty-five": 25, "twenty five": 25, "thirty": 30,
                 "thirty-five": 35, "thirty five": 35, "forty": 40, "forty-five": 45, "forty five": 45, "fifty": 50,
                 "fifty-five": 55, "fifty five": 55}
_READ_ALOUD = re.compile(rf"\b({_WORD_HOURS}) ({'|'.join(sorted(_MINUTE_WORDS, key=len, reverse=True))})\b(?![- ](?:metres?|m\b|minutes?))")
# An hour said in words with what makes it a time: "nine o'clock", "seven pm", "nine in the evening".
_WORD_CLOCK = re.compile(rf"\b({_WORD_HOURS})(?=\s*(?:o'?\s?clock|am\b|pm\b|a\.m\.|p\.m\.|in the (?:morning|afternoon|evening)\b|at night\b|tonight\b))")
# A bare hour the clock is set to: "set the time to 9", "the clock at nine", "time: 18".
_SET_HOUR = re.compile(rf"\b(?:time|clock)(?: of (?:the )?day)?\s*(?:to|at|=|:|is|be|should be|reads?|shows?)\s*(\d{{1,2}}|{_WORD_HOURS})\b(?!\s*(?:[:.]\d|%|m\b|km|mph|metres?|meters?|minutes?|mins?|seconds?|secs?|s\b|x\b|times\b))")


# Four figures on the 24-hour clock, said as the time the clock is set to or with "hours":
# "set the time to 0630", "clock: 1845", "0300 hours" (never "1000 cones").
_MILITARY = re.compile(r"(?P<set>\b(?:time|clock)(?: of (?:the )?day)?\s*(?:to|at|=|:|is|should be)?\s*)?(?<![\d.,:])"
                       r"(?P<hour>[01]\d|2[0-3])(?P<minute>[0-5]\d)(?![\d.,:])(?P<hours>\s*(?:h|hrs|hours)\b)?")


@dataclass(frozen=True)
class ClockTime:
    """A time read from words: hour and minute as said (possibly impossible), and the words."""

    hour: int
    minute: int
    text: str
    start: int = 0
    end: int = 0

    @property
    def valid(self) -> bool:
        return 0 <= self.hour <= 23 and 0 <= self.minute <= 59

    def __str__(self) -> str:
        return f"{self.hour:02d}:{self.minute:02d}"


def _number(word: str) -> int:
    return int(word) if word.isdigit() else _WORD_NUMBERS[word]


def _in_half_of_day(hour: int, after: str, said: str = "", o_clock: bool = False) -> int:
    """The 24-hour hour for a 12-hour `hour` given the words after it ("pm", "at night"), else
    the part of the day the rest of the request names ("a November evening ... about half five");
    one to five o'clock with nothing saying morning or night is in the afternoon (the small hours
    are said as such: "three in the morning")."""
    if _AFTERNOON.match(after):
        night_small_hours = hour <= 4 and re.match(r"^\s*(at|in the|of|of the) night", after) is not None
        return hour if hour >= 12 or night_small_hours else hour + 12
    if _MORNING.match(after):
        return 0 if hour == 12 else hour
    if 1 <= hour <= 5 and (o_clock or _O_CLOCK.match(after)) and not re.search(r"\b(?:morning|night|dawn|am|a\.m\.)\b", said + after):
        return hour + 12
    if 5 <= hour <= 11 and _LATER_IN_DAY.search(said) and not re.search(r"\b(?:morning|am|a\.m\.)\b", said):
        return hour + 12
    return hour


def half_of_day_said(text: str, time: ClockTime) -> bool:
    """Whether the words say which half of the day `time` is in ("six thirty in the evening", "7 pm"): a
    time however the sentence round it runs ("I'll test around 6 pm")."""
    return _half_of_day_after(text[time.end :]) or re.search(r"(?:am|pm|a\.m\.|p\.m\.)$", time.text) is not None


def _half_of_day_after(after: str) -> bool:
    """Whether the words straight after a time say which half of the day it is in ("pm", "in the evening")."""
    return bool(_AFTERNOON.match(after) or _MORNING.match(after))


def clock_time(text: str) -> ClockTime | None:
    """The clock time `text` names, or None. Lower-case input is expected."""
    for name, (hour, minute) in _NAMED.items():
        if (named := re.search(rf"\b{name}\b", text)) is not None:
            near = _NEAR_NAMED.search(text[: named.start()])  # "quarter to midnight", "ten past noon"
            if near is not None:
                said = near.group("said")
                minutes = 30 if said == "half" else 15 if said.endswith("quarter") else _number(said.split()[0])
                total = (hour * 60 + minute + (-minutes if near.group("way") in ("to", "before") else minutes)) % (24 * 60)
                return ClockTime(total // 60, total % 60, near.group(0) + name, near.start(), named.end())
            return ClockTime(hour, minute, name, named.start(), named.end())
    spoken = _SPOKEN.search(text)
    if spoken is not None:
        said, relation, target = spoken.group(1), spoken.group(3), spoken.group(4)
        minutes = 30 if said == "half" else 15 if said.endswith("quarter") else _number(said.split()[0])
        hour = _number(target)
        if relation in ("to", "before"):
            hour, minute = (hour - 1) % 12 or 12, 60 - minutes
        else:
            minute = minutes
        return ClockTime(_in_half_of_day(hour, text[spoken.end():], text), minute, spoken.group(0), *spoken.span())
    half = _HALF_HOUR.search(text)
    if half is not None and _number(half.group(1)) <= 12:
        hour = _in_half_of_day(_number(half.group(1)), text[half.end():], text)
        return ClockTime(hour, 30, half.group(0), *half.span())
    aloud = _READ_ALOUD.search(text)
    if aloud is not None and (_half_of_day_after(text[aloud.end():]) or _TIME_TOPIC.search(text) or _LATER_IN_DAY.search(text)):
        hour = _in_half_of_day(_number(aloud.group(1)), text[aloud.end():], text)
        return ClockTime(hour, _MINUTE_WORDS[aloud.group(2)], aloud.group(0), *aloud.span())
    military = next((m for m in _MILITARY.finditer(text) if m.group("set") or m.group("hours")), None)
    if military is not None:  # "set the time to 0630", "0300 hours"
        return ClockTime(int(military.group("hour")), int(military.group("minute")), military.group(0).strip(), *military.span())
    for m in _DIGITAL.finditer(text):
        separator, said_minutes, suffix = m.group(2), m.group(3), m.group(4)
        if separator == "." and suffix is None and not _TIME_TOPIC.search(text):
            continue  # "2.50 m" is a number, not ten to three
        said_day_half = _half_of_day_after(text[m.end():])
        if separator is None and suffix in (None, "h", "hrs", "hours") and not (suffix is None and said_day_half):
            continue  # a bare "7" or "7 hours" is an amount; "9 in the evening" is a time
        after = text[m.end():]
        if suffix is not None and suffix.startswith(("am", "a.m", "pm", "p.m")):
            after = suffix
        said_hour = int(m.group(1))
        rest = text if suffix is None and not m.group(1).startswith("0") else ""  # "05:30" is the 24-hour clock
        o_clock = suffix is not None and suffix.startswith("o")
        hour = _in_half_of_day(said_hour, after, rest, o_clock) if said_hour <= 12 else said_hour
        return ClockTime(hour, int(said_minutes or 0), m.group(0).strip(), *m.span())
    for hour_said in (_WORD_CLOCK.search(text), _SET_HOUR.search(text)):
        if hour_said is not None:
            hour = _number(hour_said.group(1))
            if hour <= 12:
                hour = _in_half_of_day(hour, text[hour_said.end():], text)
            return ClockTime(hour, 0, hour_said.group(0), *hour_said.span())
    return None


__all__ = ["CLOCK_WORDS", "ClockTime", "clock_time"]
