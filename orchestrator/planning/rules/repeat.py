"""A request to do the last edit again ("repeat that outside Engineering Hall", "ditto for the
bus", "do the same again"): the last edit's calls once more, at the place or on the things this
clause names. What the clause says that the last edit has no slot for is refused, never dropped.
A new amount for the last edit ("actually, make that five") is the same edit with that amount.
"""

from __future__ import annotations

import re
from typing import Any

from drivetwin.orchestrator.memory import Memory, Turn
from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.orchestrator.planning.rules import numbers as nb
from drivetwin.orchestrator.planning.rules.clock import clock_time
from drivetwin.orchestrator.planning.rules.edits import referenced
from drivetwin.orchestrator.planning.rules.places import Notes, location
from drivetwin.orchestrator.planning.rules.reading import Reading
from drivetwin.tools.base import ToolCall
from drivetwin.worlds.scene import Scene

# The words that ask for the last edit again, at the start of a clause; what follows says where or
# to what. "Same again but bollards" (the last amount of something new) is the add path's.
_REPEAT = re.compile(
    r"^\s*(?:(?:ok(?:ay)?|now|and|then|also|right|please|pls|can you|could you)[,\s]+)*"
    r"(?:ditto|repeat (?:that|this|it|the last (?:one|edit|change|step))(?: (?:again|once more))?"
    r"|do (?:that|this|it|the same(?: thing)?)(?: (?:again|once more|one more time|too|as well))?"
    r"|(?:the )?same (?:again|thing)|(?:the )?same(?= (?:for|with|at|outside|by|near|on|to|in|over)\b)"
    # "add another row like that in lot B": the last layout again, where said
    r"|(?:(?:add|make|put|build|lay|set up|give me|do)\s+)?(?:another|a second|one more)\s+(?:row|line|ring|circle|grid|queue|wall|one)"
    r"\s+(?:like (?:that|this|it|the last one)|the same))"
    r"(?![\w-])(?!\s+but\b(?!\s+(?:by|at|near|next to|beside|behind|in front of|outside|in|on|over by)\b))"
)

# The same again at another place, said after an edit: "..., and the same at lot B", "ditto by the library".
SAID_AGAIN_AT = r"\b(?:the\s+)?same\s+(?:again\s+|thing\s+)?(?:for|with|at|outside|by|near|on|in|over)\b|\bditto\b"

# Words that add nothing to what is repeated.
_FILLER = re.compile(r"\b(?:again|please|pls|too|as well|once more|one more time|thanks|thank you)\b|^\s*but\b")


# Other things named after an edit, for it to be done to them too: "and the cars too", "oh, and the
# bin", "also those benches" (a few words after the article, no verb).
_ALSO_THE = re.compile(r"^\s*(?:(?:oh|and|also|plus|then|ok(?:ay)?)[,\s]+)+(?:the|those|these|that|this|all the|both(?: the)?)\s+"
                       r"(?:[a-z_0-9]+\s+){0,3}?[a-z_0-9]+(?:\s+(?:too|as well|also))?\s*[.!]*\s*$")
# Calls that change things already there: what "and the bin too" can be done to as well.
_ON_EXISTING = ("remove_assets", "set_asset_appearance", "move_asset", "place_asset", "set_behaviour")


def said_again(r: Reading) -> bool:
    """Whether the clause opens asking for an edit again ("the same at lot B", "ditto")."""
    return _REPEAT.match(r.low) is not None


def repeats(r: Reading, memory: Memory | None = None) -> bool:
    """Whether the clause asks for the last edit again (to other things: "and the bin too", when
    the last edit changed things already there)."""
    if said_again(r):
        return True
    if memory is None or not (r.mentions or r.ids) or _ALSO_THE.match(r.low) is None:
        return False
    try:
        _, calls = _last_edit(memory)
    except PlanningError:
        return False
    return bool(calls) and all(c.tool in _ON_EXISTING for c in calls)


def repeat(r: Reading, scene: Scene, memory: Memory, notes: Notes, earlier: list[ToolCall] | None = None) -> list[ToolCall]:
    """The last edit still in the scene (or the `earlier` calls of this request: "cones across the
    lot A entrance, and the same at lot B"), again: moved to the place named, or applied to the
    things named; as it was when the clause names neither."""
    if earlier:
        last_prompt, calls = "the request before it", earlier
    else:
        last, calls = _last_edit(memory)
        last_prompt = last.prompt
    said = _REPEAT.match(r.low)
    rest = _FILLER.sub("", r.low[said.end() :] if said is not None else r.low).strip(" ,.!")
    # "ditto for the bus", "the same to the trees": other things, first; "repeat that outside the Library": a place
    on_things = re.match(r"(?:for|to|with|on)\b(?! (?:the )?(?:left|right|side|other side)\b)", rest) is not None
    names_things = bool(r.ids or r.mentions or r.ego)
    # "now do the same with barriers": what the last edit made, made again of the things named
    creating = bool(calls) and all(c.tool in ("add_asset", "arrange_assets") for c in calls)
    kinds = [m.category for m in r.mentions] if on_things and r.mentions and creating and not r.ids else []
    things = referenced(r, scene, memory, notes) if on_things and names_things and not kinds else []
    place = location(r, scene, memory, notes) if rest and not things else None
    if not on_things and place is None and names_things:
        things = referenced(r, scene, memory, notes)
    if rest and place is None and not things:
        raise PlanningError(f"I could not tell where or to what {rest!r} is; say the whole request again")
    out: list[ToolCall] = []
    used = not (things or place)
    for call in calls:
        args = dict(call.args)
        if place is not None and place.get("relation") == "in_lane" and "lane" in (args.get("behaviour") or {}):
            lane = place.get("lane") or place.get("target")  # "ditto for the westbound lane": traffic in that lane
            args["behaviour"], used = {**args["behaviour"], "lane": lane}, True
        if kinds and call.tool in ("add_asset", "arrange_assets"):
            args.update({"categories": kinds} if call.tool == "arrange_assets" else {"category": kinds[0]})
            used = True
        if place is not None and "location" in args:
            args["location"], used = _alike(dict(place), args["location"], scene), True
        elif place is not None and call.tool == "remove_assets" and "near" in args and "target" in place:
            args["near"], used = str(place["target"]), True
        elif things and _retarget(call.tool, args, things, out):
            used = True
            continue
        out.append(ToolCall(tool=call.tool, args=args))
    if not used:
        what = "place" if place is not None else "things"
        raise PlanningError(f"{last_prompt!r} has no {what} to change for {rest!r}; say the whole request")
    if place is not None:
        notes.place = place
    return out


# A new amount for the last edit, and nothing else: "actually make that five", "no, 2 of them",
# "change it to six cones", "let's go with three instead". The amount is group "n", the words
# after it (the kind, if any) group "rest".
_SPELT_COUNT = "|".join(sorted(nb.spelt_counts(), key=len, reverse=True))
_AMOUNT = re.compile(
    r"^\s*(?:(?:actually|no|nah|sorry|oops|wait|hmm+|ok(?:ay)?|on second thought)[,.!\s]+)*"
    r"(?:(?:make|change) (?:that|it|them|those) (?:to |into )?|i meant |let'?s (?:have|do|go with) |just )"
    rf"(?P<n>\d+|{_SPELT_COUNT})(?P<rest>(?: (?!instead|in total|altogether|of them|please|thanks)[a-z]+){{0,2}})"
    r"(?:[,\s]+(?:instead|in total|altogether|of them|please|thanks))*\s*[.!]*\s*$"
)
# The calls that put a number of new things down, whose amount a correction changes.
_AMOUNT_TOOLS = ("add_asset", "arrange_assets")


# "Oops, I meant bins": the thing the last request should have named, and nothing else. The rules
# cannot take back the last edit, so this is refused with what to do; never read as a new request.
_MEANT = re.compile(r"^\s*(?:(?:oops|sorry|no|nah|wait|argh|ugh|actually)[,.!\s]+)*i (?:meant|mean)\b(?: to say)?[,:\s]+"
                    r"(?:the |a |an |some )?(?P<what>[a-z][a-z ]{0,30}?)\s*[.!]*\s*$")


def meant_instead(r: Reading) -> None:
    """A PlanningError for a clause that only says what the last request meant instead."""
    said = _MEANT.match(r.low)
    if said is not None:
        raise PlanningError(f"'I meant {said.group('what')}': say 'undo' to take back the last change, then the whole "
                            f"request again with {said.group('what')}")


def corrects(r: Reading) -> bool:
    """Whether the clause only gives a new amount for the last edit ("make it 9 at night" names a
    time, not an amount)."""
    return _AMOUNT.match(r.low) is not None and clock_time(r.low) is None


def correct(r: Reading, scene: Scene, memory: Memory) -> list[ToolCall]:
    """The last edit's things, as many as the clause now says: what it added taken away, and its
    adding call made again with the new amount (so they stand as that request would have put them)."""
    said = _AMOUNT.match(r.low)
    assert said is not None
    last, calls = _last_edit(memory)
    added = [a for i in last.added if (a := scene.asset(i)) is not None]
    kinds = {a.category for a in added}
    adding = [c for c in calls if c.tool in _AMOUNT_TOOLS]
    if len(kinds) != 1 or len(adding) != 1:
        raise PlanningError(f"{r.text.strip()!r} changes how many things the last edit added, but {last.prompt!r} "
                            "added " + ("nothing" if not kinds else "several kinds") + "; say the whole request")
    kind = kinds.pop()
    if said.group("rest").strip() and not any(m.category == kind for m in r.mentions):
        raise PlanningError(f"the last edit added {kind.replace('_', ' ')}s, not {said.group('rest').strip()!r}; "
                            "say the whole request")
    value = nb.spelt_counts().get(said.group("n")) or int(said.group("n"))
    wanted = nb.count(nb.Number(float(value), said.group("n"), said.start("n"), said.end("n")), kind.replace("_", " "))
    if wanted == len(added):
        raise PlanningError(f"the last edit already added {wanted} {kind.replace('_', ' ')}(s); nothing to change")
    again = ToolCall(tool=adding[0].tool, args={**adding[0].args, "count": wanted})
    return [ToolCall(tool="remove_assets", args={"assets": [a.id for a in added]}), again]


def _last_edit(memory: Memory) -> tuple[Turn, list[ToolCall]]:
    """The newest turn still in the scene that changed something, with its calls read back."""
    for turn in reversed(memory.live_turns()):
        if turn.calls and (turn.added or turn.removed or turn.touched):
            try:
                return turn, turn.tool_calls()
            except (SyntaxError, ValueError):
                break
    raise PlanningError("there is no earlier edit to repeat; say what to do")


def last_location(memory: Memory) -> dict[str, Any] | None:
    """Where the last edit still in the scene put things ("same again but bollards": there too),
    or None when it put nothing anywhere in particular."""
    try:
        _, calls = _last_edit(memory)
    except PlanningError:
        return None
    where = next((c.args["location"] for c in calls if isinstance(c.args.get("location"), dict)), None)
    return dict(where) if where is not None else None


def _alike(place: dict[str, Any], was: Any, scene: Scene) -> dict[str, Any]:
    """The place named, at the part of it the last edit used: "same again, but at lot B" after a
    line across the lot A entrance is across the lot B entrance, when lot B has one."""
    before, target = (was or {}).get("target") if isinstance(was, dict) else None, place.get("target")
    if not isinstance(before, str) or not isinstance(target, str) or scene.landmark(before) is None:
        return place
    for part in (" entrance", " driveway"):
        if before.endswith(part) and not target.endswith(part) and scene.landmark(target + part) is not None:
            return {**place, "target": target + part}
    return place


def retargeted(calls: list[ToolCall], things: list[str]) -> list[ToolCall]:
    """`calls` made on `things` instead of what they named ("the bench has to go, and so does the
    bin"); [] when none of them names a thing to swap."""
    out: list[ToolCall] = []
    for call in calls:
        _retarget(call.tool, dict(call.args), things, out)
    return out


def _retarget(tool: str, args: dict[str, Any], things: list[str], out: list[ToolCall]) -> bool:
    """The call made on `things` instead of what it named (appended to `out`); False when the
    call names no thing to swap."""
    if "asset" in args:  # one thing at a time: a call for each
        out.extend(ToolCall(tool=tool, args={**args, "asset": thing}) for thing in things)
        return True
    if "assets" in args or ("category" in args and tool in ("set_asset_appearance", "remove_assets")):
        kept = {k: v for k, v in args.items() if k not in ("category", "near", "count")}
        out.append(ToolCall(tool=tool, args={**kept, "assets": list(things)}))
        return True
    return False


__all__ = ["SAID_AGAIN_AT", "correct", "corrects", "last_location", "meant_instead", "repeat", "repeats", "retargeted", "said_again"]
