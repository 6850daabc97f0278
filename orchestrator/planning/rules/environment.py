"""Environment requests for the rule planner: weather, time of day and lights, said or implied.

One clause may set several ("a night drive in the rain" is a time and a weather), and a goal
counts as a request ("I want to test the wipers" is rain, "bring the sun back" is clear
weather, "drivers can barely see; light up the streets" is street lights on).
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Any

from drivetwin.orchestrator.planning.intent import WEATHER_HEDGED
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules.clock import clock_time, half_of_day_said
from drivetwin.orchestrator.planning.rules.numbers import NUMBER, parse
from drivetwin.orchestrator.planning.rules.reading import Reading
from drivetwin.tools.appearance import TIME_PRESETS
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.scene import Environment

# Weather intensity (0..1) for "heavy", unqualified and "light".
HEAVY_INTENSITY, DEFAULT_INTENSITY, LIGHT_INTENSITY = 0.9, 0.6, 0.3
# A strength said in figures: "intensity 0.3", "at an intensity of 0.7", "40 %".
_INTENSITY = re.compile(rf"(?:intensity (?:of |at |to |=\s*)?|strength (?:of )?)({NUMBER})|({NUMBER})\s*(%|percent)")
# Weather kinds tried in order: "stop the rain" is clear before it is rain.
_WEATHER_ORDER = ("clear", "snow", "fog", "rain", "cloudy")
# Words that deny the weather after them: "no more fog", "we don't want any rain", "get rid of the snow",
# "turn off the fog", "off the rain" (switched off, as lamps are).
_DENIED = r"\b(?:no|not|don't|do not|without|never|get rid of|stop|end|enough|clear|lift|remove|kill|cancel|off) "
# Words that make "light" mean lamps, not a light drizzle.
_LAMP_CONTEXT = ("street", "streets", "lamps", "headlights", "lights", "light up", "lit", "switch", "turn")


# The sun said of the time, not the weather: "before the sun goes down", "as the sun rises".
_SUN_MOVING = re.compile(r"\bsun\s+(?:goes|going|has gone|is going|went|sets|setting|is setting|rises|rising|is rising|comes up|coming up|up|down"
                         r"|sinks?|sinking|is sinking|dips?|dipping|hangs? low|low in the sky)\b")


# The weather set to a kind by name ("the weather be set to clear", "weather: clear", "switch the weather to snow").
_WEATHER_TO = re.compile(r"\bweather\b(?:\s+(?:be|is|should|must|gets?|to|set|changed|changes|switched|turned|now|back|"
                         r"please)\b)*\s*(?::|=|\bto\b|\bas\b)?\s*([a-z]+)")


# Words that ask for what follows them ("make it cloudy", "needs overcast skies"), and words that
# complain of it ("it's too sunny"): with two kinds of weather said, the one asked for is set.
_ASKED_FOR = r"\b(?:make it|set (?:it |the weather )?to|turn (?:it )?|change (?:it )?to|switch (?:it )?to|wants?|needs?|should be|could be|go)\s+(?:\S+\s+){0,2}?"
_COMPLAINED_OF = r"\b(?:too|way too|far too|so) "


def _asked_for(r: Reading) -> tuple[str, ...]:
    """The one kind of weather the words ask for when they name others too, else every kind in
    the order they are tried."""
    def words(kind: str) -> str:
        return "|".join(map(re.escape, lx.WEATHER_WORDS[kind]))

    said = [k for k in _WEATHER_ORDER if r.has(lx.WEATHER_WORDS[k])]
    asked = [k for k in said if re.search(rf"{_ASKED_FOR}(?:{words(k)})\b", r.low)
             and not re.search(rf"{_COMPLAINED_OF}(?:{words(k)})\b", r.low)]
    return tuple(asked) if len(said) > 1 and len(asked) == 1 else _WEATHER_ORDER


def weather(r: Reading) -> ToolCall | None:
    """The weather a clause asks for, with its intensity, or None."""
    named = _WEATHER_TO.search(r.low)
    if named is not None and named.group(1) in ("clear", "fine", "sunny", "dry") and not r.has(("no", "not")):
        return ToolCall(tool="set_weather", args={"kind": "clear"})  # "the weather be set to clear"
    for kind in _asked_for(r):
        if r.has(lx.WEATHER_WORDS[kind]) and not (kind == "clear" and _SUN_MOVING.search(r.low) and not r.has(("sunny", "sky", "clear"))):
            if (
                kind == "clear"
                and r.has(("clear the", "clear away", "clear out"))
                and not r.has(("weather", "sky", "skies"))
            ):
                continue  # "clear the roadworks away" is a removal
            words = "|".join(map(re.escape, lx.WEATHER_WORDS[kind]))
            # "the rain stops", "the fog can be turned off": switched off after it is named
            stopped = re.search(rf"\b(?:{words})\b(?:\s+\S+){{0,3}}?\s+(?:stop|stops|end|ends|clear|clears|go away|let up|off)\b", r.low)
            # "wet roads, not a downpour though": how strong it is denied, not the rain
            strength = re.search(rf"\bnot (?:a |too |to |that |so )?(?:{'|'.join(map(re.escape, lx.HEAVY))})\b", r.low)  # "not to thick"
            # "close the fog", "shut the rain": switched off, as some say of lights
            closed = re.search(rf"\b(?:close|shut)\s+(?:the\s+|that\s+)?(?:{words})\b", r.low)
            if kind != "clear" and strength is None and (re.search(rf"{_DENIED}(?:\S+ ){{0,4}}(?:{words})\b", r.low) or stopped or closed):
                return ToolCall(tool="set_weather", args={"kind": "clear"})  # "I don't want any rain any more"
            args: dict[str, Any] = {"kind": kind}
            if kind != "clear":
                # "light snow with the headlights on": light said of the weather is its strength
                said_of_weather = re.search(rf"\blight\s+(?:{'|'.join(map(re.escape, lx.WEATHER_WORDS[kind]))})\b", r.low)
                # "rainy but not too strong": a strength denied is a light one
                denied = strength or re.search(rf"\bnot (?:too |so |very )?(?:much )?(?:{'|'.join(map(re.escape, lx.HEAVY))})\b", r.low)
                # "fog, light intensity", "low intensity rain": the strength said as such
                denied = denied or re.search(r"\b(?:light|low|weak|gentle|mild)\s+(?:intens|strength|level)"
                                             r"|\b(?:intensity|strength|level)\s*[:=]?\s*(?:light|low|weak|gentle|mild)\b", r.low)
                # "a snowstorm"; "big snow", "proper rain": how much of it, said of the weather
                big = re.search(rf"\b(?:big|huge|massive|serious|proper)\s+(?:{words})\b"
                                r"|\b(?:intensity|strength|level)\s*[:=]?\s*(?:heavy|high|strong|thick|max\w*)\b", r.low)
                heavy = (r.has(lx.HEAVY) or re.search(r"[a-z]storm\b", r.low) is not None or big is not None) and denied is None
                light = denied is not None or (r.has(lx.LIGHT) and (bool(said_of_weather) or not r.has(_LAMP_CONTEXT))) \
                    or WEATHER_HEDGED.search(r.low) is not None  # "a bit cloudy", "a touch of fog": the check's own reading
                args["intensity"] = HEAVY_INTENSITY if heavy else LIGHT_INTENSITY if light else DEFAULT_INTENSITY
                said = _INTENSITY.search(r.low)
                bare = re.search(rf"\b(?:{words})\s*(?:=|:)?\s*(0?\.\d+|1\.0*|0|1)(?![\d.:]|\s*(?:m\b|%|am\b|pm\b|h\b))", r.low)
                if said is not None:  # "fog at intensity 0.7", "rain at 40 %": the tool refuses what is past 1
                    args["intensity"] = parse(said.group(1) or said.group(2)) / (100 if said.group(3) else 1)
                elif bare is not None:  # "rain 0.6; time 21:00": a strength written after the weather
                    args["intensity"] = float(bare.group(1))
            return ToolCall(tool="set_weather", args=args)
    return None


# The sun low in the sky, going down: sunset ("the sun sinks low over the campus").
_SUN_SINKING = re.compile(r"\bsun\s+(?:is\s+)?(?:just\s+|only\s+)?(?:sinks?|sinking|dips?|dipping|hangs? low|hanging low|low in the sky"
                          r"|going down|setting)\b")  # "once the sun goes down" is night (lexicon)
# The sun just up: "when the sun is just coming up", "as the sun rises".
_SUN_RISING = re.compile(r"\bsun\s+(?:is\s+)?(?:just\s+|only\s+)?(?:coming up|comes up|came up|rising|rises|rose)\b")
# The time just before dark, said by what comes after it.
_BEFORE_DARK = re.compile(r"\b(?:just |right )?before (?:the )?(?:sun (?:goes|has gone|is going) down|sun sets|sunset|sundown|dark|nightfall)\b")


# A part of the day said as not wanted: "night, not day", "no daytime", "rather than morning".
TIME_NOT_SET = re.compile(r"\b(?:not|no|never|instead of|rather than)\s+(?:the\s+|a\s+|in the\s+)?"
                          r"(?:day(?:time|light)?|night(?:time)?|evening|morning|afternoon|dusk|dawn|noon|midday|midnight)\b"
                          # an occasion named by its day ("for the open day", "sports day"), or a day counted: no time of day
                          r"|\b(?:open|sports?|demo|test|game|race|match|school|work|working|visit|launch|media|press|every|one|some|other|next|whole|all)[\s-]+day\b"
                          # how long ("levelling all morning", "the whole afternoon") or what a place is like ("looks like a
                          # Sunday morning"): no time to set
                          r"|\b(?:all|the whole|the entire|throughout the|for the)\s+(?:morning|afternoon|evening|night|day)\b"
                          # when a thing is hard to see ("hard to see at night"): when it matters, not a time asked for
                          r"|\b(?:see|spot|visible|invisible)\s+(?:\w+\s+)?(?:at|by|in the|during the)\s+(?:night|dusk|dawn|evening)\b"
                          r"|\b(?:dark|bright|light)(?:er)?[\s-]+(?:colou?r\w*|paint\w*|shades?|tints?)\b"  # a dark colour is no dark
                          # (though "make it look like a rainy evening" asks for one)
                          r"|(?<!make it look )(?<!make it feel )(?<!make it seem )(?<!make this look )"
                          r"\b(?:like|as if it were|as though it were)\s+(?:a|an|the)\s+(?:[a-z]+\s+)?(?:morning|afternoon|evening|night)\b")


def time_of_day(r: Reading) -> ToolCall | None:
    """The time a clause asks for ("at 7 pm", "18:30", "dusk", "lunchtime"), or None."""
    blank = TIME_NOT_SET.sub(lambda m: " " * len(m.group(0)), r.low)
    if blank != r.low:  # "NIGHT!!! NOT DAY!!!": the day is what is not wanted
        r = replace(r, low=blank, masked=TIME_NOT_SET.sub(lambda m: " " * len(m.group(0)), r.masked))
    said = clock_time(r.masked)
    # "06:15, overcast": hours and minutes written with a colon are a clock time whatever the words round them
    if said is not None and (r.has(("time", "make it", "set", "at", "clock", "change", "to", "past")) or half_of_day_said(r.masked, said)
                             or re.fullmatch(r"\d{1,2}:\d{2}(?:\s*(?:am|pm|hrs|hours|h))?", said.text.strip())):
        return ToolCall(tool="set_time_of_day", args={"time": str(said)})  # the tool refuses "25:70"
    if r.has(("lunchtime", "lunch time", "lunch")):
        return ToolCall(tool="set_time_of_day", args={"time": "12:30"})
    rising = r.has(("sunrise", "dawn", "daybreak", "morning", "sun comes up", "sun is up", "sun rises"))  # a low sun in the morning
    if _BEFORE_DARK.search(r.low) or (_SUN_SINKING.search(r.low) and not rising):  # "the last light before the sun goes down": not yet night
        return ToolCall(tool="set_time_of_day", args={"time": "sunset"})
    if _SUN_RISING.search(r.low):
        return ToolCall(tool="set_time_of_day", args={"time": "sunrise"})
    # a phrase said beats a single word ("golden hour this evening" is the golden hour)
    phrased = [preset for words, preset in lx.TIME_PRESETS if r.has(tuple(w for w in words if " " in w or "-" in w))]
    worded = [preset for words, preset in lx.TIME_PRESETS if r.has(words)]
    if phrased or worded:
        preset = (phrased or worded)[0]
        shifted = _EARLY_LATE.search(r.low)
        if not phrased and shifted is not None and shifted.group(2) == preset and preset in TIME_PRESETS:
            # "early evening", "late afternoon": the named part of the day, EARLY_LATE_H sooner or later
            hour, minute = map(int, TIME_PRESETS[preset].split(":"))
            hour = (hour + (EARLY_LATE_H if shifted.group(1) == "late" else -EARLY_LATE_H)) % 24
            return ToolCall(tool="set_time_of_day", args={"time": f"{hour:02d}:{minute:02d}"})
        return ToolCall(tool="set_time_of_day", args={"time": preset})
    if _LATE.search(r.low):  # "something wintry, and late": late in the day
        return ToolCall(tool="set_time_of_day", args={"time": "evening"})
    return None


# A named part of the day said early or late in it: "early evening", "late afternoon", "late morning".
_EARLY_LATE = re.compile(r"\b(early|late)(?:[\s-]+in the)?[\s-]+(morning|afternoon|evening|night)\b")
EARLY_LATE_H = 2
# "late" said of the time alone: "make it late", "..., and late", "late, please" (not "too late", "later").
_LATE = re.compile(r"(?:\b(?:make it|make the time|and|it's|its|it is|set it|set the time|time)\s+|^\s*)(?:really |very |quite |a bit )?late\b"
                   r"(?=\s*(?:$|[,.;!?]|\b(?:please|pls|now|too|then)\b))")


# Street lamps said to be broken ("street lighting failed", "the streetlights are dead", "won't be working"): off.
# ("space the street lights out evenly" lays them out: the lamps stay lit)
LIGHTS_DOWN = re.compile(r"(?<!space the )(?<!spread the )(?<!lay the )(?<!fan the )"
                         r"\b(?:street ?light(?:s|ing)?|street ?lamps?|lamps|lighting)\s+(?:have |has |is |are )?"
                          r"(?:failed|failing|out|dead|broken|down|not working|(?:gone|went|are|is) (?:out|dark)"
                          r"|(?:won'?t|will not|don'?t|do not|aren'?t|are not|can'?t|cannot) (?:be )?(?:working|work|lit|on|come on))\b")


# "open the street light", "close the lamps", "kill the lights": switched on or off, as some say it.
LAMPS_SWITCHED_AS_SAID = re.compile(r"\b(?:open|close|shut|kill)\s+(?:the\s+|all\s+(?:the\s+)?)?(?:street\s*)?(?:lights?|lamps?|lamp posts?)\b(?! down\b)")


def lights(r: Reading) -> ToolCall | None:
    """Street or vehicle lights switched on or off, or None."""
    switched_on = re.search(r"\b(?:switch|turn|put|flip)\w*\s+(?:[\w']+\s+){0,3}?on\b", r.low)
    if LIGHTS_DOWN.search(r.low) and not switched_on:  # "street lighting failed", "the lamps are out": off (unless switched on)
        return ToolCall(tool="set_lighting", args={"street_lights": "off"})
    if not r.has(lx.LIGHTS_WORDS) or r.has(("traffic light", "traffic lights")):
        return None
    if r.has(("light", "lights")) and not r.has((*_LAMP_CONTEXT, "on", "off")):
        return None
    switched = LAMPS_SWITCHED_AS_SAID.search(r.low)
    if not re.search(r"\b(on|off|up|lit|switch|switched|turn|turned|bright|brighter|dark|darker|see|visible)\b", r.low) and not switched:
        return None  # "the lights handle it": lamps named as a circumstance, not switched
    # ("kick-off", "drop-off": a word of its own, no lights off)
    off = bool(re.search(r"(?<![\w-])off\b(?!-)", r.low)) or r.has(("no lights", "dark streets")) or (
        switched is not None and not switched.group(0).startswith("open"))
    state = "off" if off else "on"
    vehicles = r.has(("headlights", "vehicle lights", "car lights", "vehicle", "vehicles"))
    streets = not vehicles or r.has(("street lights", "street", "streetlights", "lamps", "street lamps", "lamp posts"))
    # "street and vehicle lights on": both kinds said, both switched
    return ToolCall(tool="set_lighting", args={k: state for k, said in (("street_lights", streets), ("vehicle_lights", vehicles)) if said})


# "later in the day", "two hours earlier": the clock moved from where it stands; hours when unsaid.
SHIFT_HOURS = 3
_SHIFT = re.compile(r"\b(?:(an?|one|two|three|four|five|six|\d{1,2}) (?:more )?hours? )?(later|earlier)\b")
# ...said of the clock, when no hours are: "make it later", "a bit later", "later in the day", "the time later";
# not "we can do the weather later", "for the crew later".
_OF_THE_CLOCK = re.compile(r"\b(?:make|set|push|move|bump|take|turn|put)\s+(?:it|things)\s+(?:(?:a|much|way|even)\s+)?(?:bit\s+|little\s+|touch\s+|lot\s+)?(?:later|earlier)\b"
                           r"|\b(?:bit|little|much|touch|slightly|somewhat|lot|even|way)\s+(?:later|earlier)\b|\b(?:it|things)\s+(?:be|is)\s+(?:later|earlier)\b"
                           r"|\b(?:later|earlier)\s+(?:on\s+)?in\s+the\s+(?:day|evening|afternoon|morning)\b|\b(?:time|clock|hour|hours|day|sun)\b")
_HOURS = {"a": 1, "an": 1, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6}
# The clock turned by some hours: "set the clock back 2 hours", "move the time forward by an hour".
_CLOCK_TURNED = re.compile(r"\b(?:clock|time)s?\s+(forwards?|on|ahead|back|backwards?)\s+(?:by\s+)?(an?|one|two|three|four|five|six|\d{1,2})\s+hours?\b")
# Exposure for "brighter" (divided by it for "dimmer"), and its ceiling and floor.
BRIGHTER_FACTOR, MAX_EXPOSURE, MIN_EXPOSURE = 1.5, 4.0, 0.25
# The exposure or brightness said to go up or down ("can the exposure come down?", "lower the brightness").
_LEVEL = r"(?:the )?(?:exposure|brightness)"
_UP = rf"{_LEVEL} (?:to )?(?:come|go|be turned|be brought|turned|brought) up|(?:raise|increase|turn up|bring up|push up) {_LEVEL}"
_DOWN = rf"{_LEVEL} (?:to )?(?:come|go|be turned|be brought|turned|brought) down|(?:lower|reduce|turn down|bring down|pull down) {_LEVEL}"
_EXPOSURE_TO = re.compile(r"\b(?:exposure|brightness)\s+(?:(?:down|up|back|lowered|raised|dropped|reduced)\s+)?(?:to|at|of|=|:)?\s*(\d+(?:\.\d+)?)(?!\s*(?:%|percent|m\b))")
# ("so dark, cannot see anything" complains of it; "make it so dark that ..." asks for it)
_BRIGHTER = re.compile(rf"\b(brighter|lighter|more exposure|too dark|(?<!make it )(?<!look )(?<!be )so dark(?! (?:that|you|we|it|nobody|no one|as)\b)"
                       rf"|overexpose|brighten|{_UP})\b")
_DIMMER = re.compile(rf"\b({_DOWN}|washed out|dimmer|less bright|(?:too|so|very|far too|way too) (?:bright|glaring|dazzling)|less exposure"
                     r"|underexpose|(?:tone|turn) down the (?:brightness|exposure|glare)|dim (?:it|the scene|things) down)\b")


def shifted_time(r: Reading, now: Environment) -> ToolCall | None:
    """The clock moved later or earlier from the scene's time ("a bit later", "2 hours earlier")."""
    said = _SHIFT.search(r.masked)
    turned = _CLOCK_TURNED.search(r.masked)  # "set the clock back two hours", "move the time on an hour"
    if turned is not None and clock_time(r.masked) is None:
        hours, later = _HOURS.get(turned.group(2)) or int(turned.group(2)), turned.group(1) in ("forward", "forwards", "on", "ahead")
    elif said is None or clock_time(r.masked) is not None or (said.group(1) is None and not _OF_THE_CLOCK.search(r.masked)):
        return None
    else:
        hours, later = SHIFT_HOURS if said.group(1) is None else _HOURS.get(said.group(1)) or int(said.group(1)), said.group(2) == "later"
    hour, minute = (int(x) for x in now.time_of_day.split(":"))
    minutes = hour * 60 + minute + (hours if later else -hours) * 60
    minutes = min(max(minutes, 0), 23 * 60 + 59)  # the same day: "later" at 22:00 is the end of it
    return ToolCall(tool="set_time_of_day", args={"time": f"{minutes // 60:02d}:{minutes % 60:02d}"})


def brighter(r: Reading, now: Environment) -> ToolCall | None:
    """The exposure said ("exposure to 0.5"), more for "brighter", less for "too bright", keeping the time the scene is set to
    (a night scene made brighter is still night); None when lamps are what is to be lit."""
    if r.has(_LAMP_CONTEXT):
        return None
    said = _EXPOSURE_TO.search(r.masked)
    if said is not None:  # "drop the camera exposure to 0.5": that value, within what the renderer takes
        return ToolCall(tool="set_lighting", args={"exposure": min(MAX_EXPOSURE, max(MIN_EXPOSURE, float(said.group(1))))})
    if _BRIGHTER.search(r.masked) is not None:
        exposure = min(MAX_EXPOSURE, now.lighting.exposure * BRIGHTER_FACTOR)
    elif _DIMMER.search(r.masked) is not None:
        exposure = max(MIN_EXPOSURE, now.lighting.exposure / BRIGHTER_FACTOR)
    else:
        return None
    return ToolCall(tool="set_lighting", args={"exposure": round(exposure, 2)})


# The weather there is, said stronger or weaker: "heavier rain", "turn the fog down", "make the rain lighter".
_MORE_OF_IT = re.compile(r"(?<!no )(?<!any )\b(?:more|heavier|thicker|harder|stronger|denser|worse|intensify|increase"
                         r"|(?:turn|crank|ramp|bump|dial) (?:\w+ ){0,2}up)\b")
_LESS_OF_IT = re.compile(r"\b(?:less|lighter|thinner|weaker|softer|milder|ease|eases|reduce|lower|(?:tone|turn|dial) (?:\w+ ){0,2}down"
                         r"|not (?:as|so)|clear (?:\w+ ){0,2}(?:a bit|a little|slightly|somewhat))\b")
# Visibility is the other way round: "improve visibility" is less fog, "poorer visibility" more.
_SEE_BETTER = re.compile(r"\b(?:improve\w*|better|increase\w*|raise|more|clearer)\s+(?:the\s+)?visibility\b|\bvisibility\s+(?:better|up|improved)\b")
_SEE_WORSE = re.compile(r"\b(?:reduce\w*|lower\w*|worse|poor\w*|less|cut|decrease\w*)\s+(?:the\s+)?visibility\b|\bvisibility\s+(?:worse|down|poor)\b")
# How much stronger "heavier" makes the weather there is; "lighter" halves it.
STRONGER_STEP = 0.3


def said_weaker(low: str) -> bool:
    """Whether the words ask for less of a weather ("less foggy", "ease the rain off", "improve visibility")."""
    return bool(_LESS_OF_IT.search(low) or _SEE_BETTER.search(low) or any(_too_much(low, kind) for kind in lx.WEATHER_WORDS))


def stronger(r: Reading, now: Environment) -> ToolCall | None:
    """The weather there is, made stronger or weaker as the words say ("heavier rain", "turn the
    fog down"); None when they name another weather or no change of its strength."""
    kind, level = now.weather.kind, now.weather.intensity
    if kind == "clear" or kind not in lx.WEATHER_WORDS or not r.has(lx.WEATHER_WORDS[kind]):
        return None
    more, less = _MORE_OF_IT.search(r.low), _LESS_OF_IT.search(r.low) or _too_much(r.low, kind)
    if re.search(r"\bvisibility\b", r.low):  # "improve visibility": less of it
        more, less = _SEE_WORSE.search(r.low), _SEE_BETTER.search(r.low)
    if bool(more) == bool(less):
        return None
    new = round(level / 2, 2) if less else round(min(1.0, level + STRONGER_STEP), 2)
    if less and _too_much(r.low, kind):
        new = min(new, LIGHT_INTENSITY)  # "that snow's far too much": light, not half as heavy
    return ToolCall(tool="set_weather", args={"kind": kind, "intensity": new}) if abs(new - level) >= 0.05 else None


def _too_much(low: str, kind: str) -> re.Match[str] | None:
    """The weather there is complained of as too much ("it's way too foggy", "too much rain", "the
    fog is far too thick"): less of it is wanted."""
    words = "|".join(map(re.escape, lx.WEATHER_WORDS[kind]))
    return re.search(rf"\btoo (?:much |heavy |thick |dense |strong |big )?(?:{words})\b"
                     rf"|\b(?:{words})(?:'s)?(?: (?:is|are|'s|feels?|looks?|already|now|still|getting|way|far|much|a bit))* too"
                     rf" (?:heavy|thick|dense|strong|much|intense|big)\b", low)


def environment(r: Reading, now: Environment | None = None) -> list[ToolCall]:
    """Every environment setting the clause asks for, in a stable order; `now` (the scene's)
    for settings said relative to it ("later", "brighter", "heavier rain")."""
    strength = stronger(r, now) if now is not None else None
    if strength is not None:  # "make the rain lighter": weaker rain, never a brighter picture
        return [strength]
    relative = [c for c in (shifted_time(r, now), brighter(r, now)) if c is not None] if now is not None else []
    if relative:
        return relative
    calls: list[ToolCall] = []
    found = lights(r)
    if found is not None:
        calls.append(found)
    masked_for_time = r
    if found is not None:
        # "light up the streets" is lamps, not daylight.
        # "lights on, it's too dark": the dark is why, not a time to set.
        # "it needs to be dark with the lamps on" still asks for the dark.
        masked = re.sub(r"\blight up\b|\b(?:(?:it'?s|is|too|so|very) )+dark\b", " ", r.masked)
        masked_for_time = Reading(r.text, r.low, masked, r.mentions)
    weather_call = weather(r)
    if weather_call is not None:
        calls.append(weather_call)
    when = time_of_day(masked_for_time)
    if when is not None:  # "a foggy morning" is a weather and a time
        calls.append(when)
    return calls


__all__ = ["LIGHTS_DOWN", "TIME_NOT_SET", "brighter", "environment", "lights", "shifted_time", "stronger", "time_of_day", "weather"]
