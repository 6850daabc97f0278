"""What one clause of a prompt names: places, lanes, the ego, categories and existing assets.

A `Reading` is the rule planner's parse of a clause. Names of places are found first and
blanked out, so the words inside them do not count twice ("bus stop" is a place, not a bus;
"parking lot A" does not ask for parking; "our car" is the ego, not a passenger car).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace

from drivetwin.orchestrator.planning.base import PlanningError
from drivetwin.orchestrator.planning.intent import HOW_THINGS_GO
from drivetwin.orchestrator.planning.rules import lexicon as lx
from drivetwin.orchestrator.planning.rules import modifiers as md
from drivetwin.orchestrator.planning.rules import phrases as ph
from drivetwin.worlds.catalog import catalog
from drivetwin.worlds.scene import AssetInstance, Lane, Scene
from drivetwin.worlds.surface import PolylinePoint, nearest_lane, nearest_on_polyline

# An article before a word; "lot A" at the end of a name keeps its letter.
_ARTICLES = re.compile(r"\b(the|a|an)\s+(?=[a-z0-9])")
_NEW_DETERMINERS = {"a", "an", "some", "another", "new", "more", "extra", "additional", "few", "several"}
_OLD_DETERMINERS = {"the", "that", "those", "these", "our", "its", "their", "his", "her", "this", "my", "your"}
_DIRECTIONS = {"west": "westbound", "east": "eastbound", "north": "northbound", "south": "southbound"}
_COMPASS_PLACE = re.compile(r"\b(?:north|south|east|west)(?:ern)?(?= side of\b| end of\b| of\b| corner\b| half\b| edge\b"
                            r"| sidewalk\b| pavement\b| footpath\b| kerb\b| curb\b| verge\b)"
                            r"|\bto the (?:north|south|east|west)\b")


@dataclass
class Reading:
    """A clause, its normalised and place-blanked forms, and what it names."""

    text: str
    low: str
    masked: str
    mentions: list[ph.Mention]
    landmark: str | None = None
    landmark_at: int = -1
    landmark_word: str | None = None  # a head noun of several places ("the gates")
    lane: str | None = None
    lane_guessed: bool = False
    ids: list[str] = field(default_factory=list)
    ego: bool = False
    ego_at: int = -1  # where the ego is named: a thing named before it is the subject, the ego an anchor

    def has(self, words: tuple[str, ...] | list[str]) -> bool:
        """Whether any of `words` occurs outside the place names of the clause."""
        return ph.has_any(self.masked, tuple(words))


def _blank(text: str, start: int, end: int) -> str:
    return text[:start] + " " + "§" * max(1, end - start - 2) + " " + text[end:]


def _unique_place_words(scene: Scene) -> dict[str, str]:
    # A word of exactly one place's names, and no catalog or common word, names that place.
    owners: dict[str, set[str]] = {}
    for landmark in scene.landmarks:
        for name in landmark.names():
            for word in ph.tokens(name):
                owners.setdefault(word, set()).add(landmark.name)
    taken = {w for cat in catalog().values() for n in cat.words for w in ph.tokens(n)} | lx.GRAMMAR
    return {w: next(iter(o)) for w, o in owners.items() if len(o) == 1 and w not in taken and len(w) > 3}


# A place name ending in an -ing word and followed by its object ("a pedestrian crossing the
# road") reads as a verb phrase, not as the place.
_VERB_OBJECT = re.compile(r"\s+(?:the|a|an|this|that|over)\b")


# "the south-east lot", "the western car park": a place of a kind, told from the others by the compass.
_COMPASS_KIND = re.compile(r"\b((?:north|south)(?:[- ]?(?:east|west))?|east|west)(?:ern)?\s+((?:parking )?lot|car park|gate|crossing|crosswalk)\b")


def _place_by_compass(scene: Scene, low: str) -> tuple[str, int, int] | None:
    """Of the places of the kind the words name after a compass point, the one furthest that way."""
    said = _COMPASS_KIND.search(low)
    way = md.outer_direction(f"{said.group(1)} side") if said else None
    if said is None or way is None:
        return None
    kind = {"car park": "lot"}.get(said.group(2), said.group(2).removeprefix("parking "))
    alike = [lm for lm in scene.landmarks if re.fullmatch(rf"(?:.* )?{kind}(?: \w)?", ph.normalise(lm.name).strip())]
    if len(alike) < 2:
        return None
    furthest = max(alike, key=lambda lm: lm.position[0] * way[0] + lm.position[1] * way[1])
    return furthest.name, said.start(), said.end()


def find_place(scene: Scene, low: str) -> tuple[str, int, int] | None:
    """The landmark named in normalised text (articles ignored; a name with a letter or number
    that labels it wins, then the longest name), and its span."""
    best: tuple[tuple[bool, bool, int], str, int, int] | None = None
    low = re.sub(r"(?<=[a-z0-9])'s\b", "  ", low)  # "lot B's entrance" is the lot B entrance
    kinds = _kind_words(scene)
    bare = _ARTICLES.sub("", low)
    for landmark in scene.landmarks:
        for name in landmark.names():
            key = _ARTICLES.sub("", ph.normalise(name)).strip()
            spaced = r"\s+".join(map(re.escape, key.split()))
            part = re.fullmatch(r"(.+) (entrance|driveway|gate|exit)", key)
            if part is not None:  # "the entrance to lot B" is the lot B entrance
                base = r"\s+".join(map(re.escape, part.group(1).split()))
                spaced = rf"(?:{spaced}|{part.group(2)}\s+(?:to|of|for|into|from)\s+(?:the\s+)?{base})"
            # as written first: the "a" of "lot a instead" is the lot's letter, not an article
            m = re.search(rf"(?<![a-z0-9]){spaced}(?![a-z0-9])", low) or re.search(
                rf"(?<![a-z0-9]){spaced}(?![a-z0-9])", bare
            )
            if m is None:
                continue
            if key.endswith("ing") and _VERB_OBJECT.match(m.string[m.end() :]):
                continue  # "a pedestrian crossing the road": a walker crossing, not the crossing
            if _thing_named_with(m.group(0), m.string[m.end() :]):
                continue  # "the pedestrian crossing sign": a thing whose name holds a place's
            # "by lot a, the car park there": the lot's letter says which car park (its letter, not an article);
            # a word for a kind of place ("crosswalk", an alias of one of two) yields to a place named outright
            rank = (key not in kinds, any(_is_label(w) for w in ph.tokens(ph.normalise(name))[1:]), len(key))
            if best is None or rank > best[0]:
                # Map the span back to `low` by finding the same words there.
                words = r"\s+(?:(?:the|a|an)\s+)?".join(re.escape(w) for w in key.split())
                span = re.search(rf"(?<![a-z0-9])(?:{words}|{spaced})(?![a-z0-9])", low)
                start, end = (span.start(), span.end()) if span else (0, 0)
                best = (rank, landmark.name, start, end)
    if best is not None and not best[0][1] and (labelled := _labelled(scene, low, best[3])) is not None:
        return labelled[0], best[2], labelled[1]  # "car park A" where only lot B is called the car park
    by_compass = _place_by_compass(scene, low)
    if by_compass is not None and (best is None or by_compass[1] < best[2] < by_compass[2]):
        return by_compass  # "the western car park": not the car park the name alone would pick
    if best is not None:
        part = re.match(r"\s+(entrance|driveway|gate|exit)\b", low[best[3] :])
        if part is not None and scene.landmark(whole := f"{best[1]} {part.group(1)}") is not None:
            return whole, best[2], best[3] + part.end()  # "the parking B entrance": that lot's entrance, by any of its names
        return best[1], best[2], best[3]
    shortened = _shortened_name(scene, low)
    if shortened is not None:
        return shortened
    world = set(ph.tokens(scene.name))  # "in town", "on campus": the whole world, not its Town Hall
    for word, name in _unique_place_words(scene).items():
        m = re.search(rf"(?<![a-z0-9]){re.escape(word)}(?![a-z0-9])", low)
        if m and word not in world and not _other_kind(scene, name, low[: m.start()]):
            return name, m.start(), m.end()
    return None


def _other_kind(scene: Scene, name: str, before: str) -> bool:
    """Whether the word before a place's word makes it another place ("the gas station" is no
    bus station): a content word that none of the place's names holds."""
    said = ph.tokens(before)[-2:]
    mark = scene.landmark(name)
    own = {w for n in (mark.names() if mark is not None else [name]) for w in ph.tokens(ph.normalise(n))}
    # "the gas station", "a petrol station": an article, then a word naming another kind ("my drivers park" is a verb)
    return len(said) == 2 and said[0] in ("the", "a", "an", "any") and said[1] not in lx.GRAMMAR and said[1] not in own \
        and said[1].isalpha()


def _kind_words(scene: Scene) -> set[str]:
    """Words that end the names of two places or more ("crosswalk", "gate"): a kind of place."""
    owners: dict[str, set[str]] = {}
    for landmark in scene.landmarks:
        for name in landmark.names():
            owners.setdefault(_head(ph.tokens(ph.normalise(name))), set()).add(landmark.name)
    return {word for word, marks in owners.items() if len(marks) > 1}


def _is_label(word: str) -> bool:
    return len(word) == 1 or word.isdigit()


def _labelled(scene: Scene, low: str, end: int) -> tuple[str, int] | None:
    """The one place whose name ends in the letter or number said right after a place's name
    (`end`), and where that label ends; None when no label follows or it fits no one place."""
    label = re.match(r"\s+([a-z]|\d+)(?=\s*(?:[,.;!?]|$|(?:and|the|please|with|for|near|by|at|in|on|so|to)\b))", low[end:])
    if label is None:
        return None
    owners = {lm.name for lm in scene.landmarks for n in lm.names()  # "entrance of lot A" is an entrance
              if " of " not in n and ph.tokens(ph.normalise(n))[-1:] == [label.group(1)]}
    return (owners.pop(), end + label.end()) if len(owners) == 1 else None


def _thing_named_with(place: str, after: str) -> bool:
    """Whether a place's name and the word after it together name a kind of thing."""
    following = after.split()[:1]
    said = f"{place} {following[0]}" if following else place
    return any(t.end - t.start > len(place) for t in ph.find_categories(said))


def _shortened_name(scene: Scene, low: str) -> tuple[str, int, int] | None:
    """A place said by the first and last words of a longer name ("the west lot" for "west
    parking lot"), when exactly one place's names shorten so."""
    found: dict[str, tuple[int, int]] = {}
    for landmark in scene.landmarks:
        for name in landmark.names():
            words = ph.tokens(ph.normalise(name))
            if len(words) < 3:
                continue
            m = re.search(rf"(?<![a-z0-9]){re.escape(words[0])}\s+{re.escape(words[-1])}(?![a-z0-9])", low)
            if m:
                found[landmark.name] = (m.start(), m.end())
    if len(found) != 1:
        return None
    (name, (start, end)), = found.items()
    return name, start, end


def _place_head_word(scene: Scene, low: str, mentions: list[ph.Mention]) -> str | None:
    """A word naming a kind of place ("the gates"): the head noun of a landmark's name, which is
    the word before its "of" ("centre of the scene") or its last; never part of a thing named."""
    heads = {_head(ph.tokens(name.split(" of ")[0])) for lm in scene.landmarks for name in lm.names()}
    for said in re.finditer(r"[a-z]+", low):
        word = said.group(0)
        if (word in heads or ph.singular(word) in heads) and not any(
                m.start <= said.start() < m.end for m in mentions):
            owners = [lm.name for lm in scene.landmarks if any(ph.singular(word) in ph.tokens(ph.normalise(n)) for n in lm.names())]
            if owners and all(_other_kind(scene, name, low[: said.start()]) for name in owners):
                return f"{ph.tokens(low[: said.start()])[-1]} {ph.singular(word)}"  # "the gas station": no bus station
            return ph.singular(word)
    return None


def place_kind_said(r: Reading, scene: Scene) -> str | None:
    """A kind of place the clause names besides the place it names ("is there a crossing near the
    library": crossing), or None."""
    return r.landmark_word or _place_head_word(scene, r.masked, r.mentions)


def _head(words: list[str]) -> str:
    """The head noun of a place's name: its last word, or the one before a letter or number
    that labels it ("parking lot A" is a lot)."""
    return words[-2] if len(words) > 1 and _is_label(words[-1]) else words[-1]


# Collective words that count only before "of" ("a lot of cones", "a load of bikes"; never "the parking lot", "load the van").
COUNT_BEFORE_OF = ("lot", "lots", "load")
# The lane beside the car under test that traffic drives the other way in: "the oncoming lane".
ONCOMING_WORDS = ("oncoming", "opposing", "opposite", "contraflow", "counterflow")
_ONCOMING = re.compile(rf"\b(?:{'|'.join(ONCOMING_WORDS)})(?:\s+traffic)?\s+lane\b|\blane\s+(?:of|for|with)\s+oncoming\s+traffic\b"
                       r"|\boncoming\b|\b(?:coming|driving|heading)(?: from)? (?:the other (?:way|direction)|the opposite (?:way|direction)"
                       r"|towards (?:us|the ego))\b")  # "traffic coming the other way", "a car coming from the other direction"


def says_oncoming(low: str) -> bool:
    """Whether the words put a thing in the ego's oncoming traffic ("a car coming the other way")."""
    return _ONCOMING.search(low.replace("_", " ")) is not None


def oncoming_lane(scene: Scene) -> Lane | None:
    """The lane of the ego's road nearest it whose traffic drives the other way; None without an
    ego on a road of two directions."""
    ego = scene.ego
    own = nearest_lane(scene, ego.pose.x, ego.pose.y) if ego is not None else None
    if ego is None or own is None:
        return None
    def foot(lane: Lane) -> PolylinePoint:
        return nearest_on_polyline(ego.pose.x, ego.pose.y, lane.centreline)

    heading = foot(own).heading
    others = [lane for lane in scene.roads.lanes if lane.road == own.road and lane.id != own.id and lane.kind == "driving"
              and math.cos(foot(lane).heading - heading) < 0]  # runs the other way
    return min(others, key=lambda lane: foot(lane).distance, default=None)


def find_lane(scene: Scene, low: str) -> tuple[str, int, int, bool] | None:
    """A lane by id, by direction (with its road if several share it), or by road alone (guessed)."""
    spaced = low.replace("_", " ")
    oncoming = _ONCOMING.search(spaced)
    if oncoming is not None and (lane := oncoming_lane(scene)) is not None:  # "in the oncoming lane": the ego's other way
        return lane.id, oncoming.start(), oncoming.end(), False
    for lane in scene.roads.lanes:
        key = lane.id.replace("_", " ")
        pos = spaced.find(key)
        if pos >= 0:
            return lane.id, pos, pos + len(key), False
    side = lane_of_side(spaced, scene)
    if side is not None:  # "the north side of Main Street": that road's lane furthest north
        return side[0].id, side[1].start(), side[1].end(), False
    # "the south side of lot B", "north of the fountain", "to the east": a compass word saying
    # where, not which way a lane runs
    words = set(ph.tokens(_COMPASS_PLACE.sub(" ", spaced)))
    directions = {_DIRECTIONS.get(w.removesuffix("wards").removesuffix("ward"), w) for w in words}
    matches = [lane for lane in scene.roads.lanes if lane.id.rsplit("_", 1)[-1] in directions]
    roads = [lane for lane in matches if lane.road.lower() in spaced] or matches
    if len({lane.id for lane in roads}) == 1 or (roads and len(matches) > 1 and roads != matches):
        return roads[0].id, 0, 0, False
    for lane in scene.roads.lanes:
        pos = spaced.find(lane.road.lower())
        if pos >= 0:
            return lane.id, pos, pos + len(lane.road), True
    return None


# A compass side of a road or place: "the north side of Main Street", "the east side of the library".
SIDE_OF = re.compile(r"\b(north|south|east|west)(?:ern)? side of (?:the )?([a-z][a-z ]*)")
# A road's kind abbreviated after its name, as on a street sign: "Main St.", "Campus Dr".
_ROAD_KIND = re.compile(r"(?<=[a-z] )(st|rd|ave|blvd|dr)\.?(?=\s)")
_ROAD_KINDS = {"st": "street", "rd": "road", "ave": "avenue", "blvd": "boulevard", "dr": "drive"}


def road_kinds_spelt(text: str) -> str:
    """`text` (lower case) with a road's abbreviated kind spelt out, and a space at the end: "main st" is Main Street."""
    return _ROAD_KIND.sub(lambda m: _ROAD_KINDS[m.group(1)], text + " ")


def lane_of_side(low: str, scene: Scene) -> tuple[Lane, re.Match[str]] | None:
    """The lane of a road on the side the words name ("the north side of Main Street": the
    westbound lane, the one furthest north) and the words; None when they name no side of a road
    of two or more lanes."""
    said = SIDE_OF.search(low)
    if said is None:
        return None
    rest = road_kinds_spelt(said.group(2))
    lanes = [lane for lane in scene.roads.lanes if lane.road and rest.startswith(ph.normalise(lane.road).strip())]
    furthest = lane_on_side(lanes, said.group(1))
    return (furthest, said) if furthest is not None else None


def lane_on_side(lanes: list[Lane], way: str) -> Lane | None:
    """Of a road's lanes, the one furthest `way` (a compass word), when one clearly is."""
    if len(lanes) < 2:
        return None
    dx, dy = md.COMPASS_VECTORS[way]

    def reach(lane: Lane) -> float:
        return float(sum(x * dx + y * dy for x, y in lane.centreline) / len(lane.centreline))

    ranked = sorted(lanes, key=reach, reverse=True)
    return ranked[0] if reach(ranked[0]) > reach(ranked[1]) + 0.5 else None


_PERCEPTION_TASK = re.compile(r"\s*(?:detection|detector|tracking|recognition|classification|perception)\b")
# "behind us", "ahead of me": said from the driver's seat, the first person is the ego vehicle.
FIRST_PERSON_EGO = re.compile(
    r"(?:\b(?:behind|ahead of|in front of|front of|beside|next to|near|past|alongside|towards?|from|around|at) "
    r"|\b(?:am|are) (?=(?:i|we) (?:in|on|driving|parked|heading|going|sitting|stopped)\b))(us|me|i|we|ours|mine)\b"  # "which lane am I in", "behind ours"
)


def _ego_span(low: str) -> tuple[int, int] | None:
    for word in ph.EGO_WORDS:
        m = re.search(rf"(?<![a-z]){re.escape(word)}(?![a-z])", low)
        if m:
            return m.start(), m.end()
    said = FIRST_PERSON_EGO.search(low)
    return (said.start(1), said.end(1)) if said else None


# "(the second car) from the west", "... from the left (in lot B)": an order across the map, counted
# from that side; left and right as the map is drawn, north up.
_FROM_SIDE = re.compile(r"\s*(?:\w+\s+)?from\s+the\s+(west|east|north|south|left|right)\b")
_SIDE_VECTORS = {"west": (-1.0, 0.0), "east": (1.0, 0.0), "north": (0.0, 1.0), "south": (0.0, -1.0),
                 "left": (-1.0, 0.0), "right": (1.0, 0.0)}
# An ordinal counted from a side, as said, for blanking its compass word out of the clause's directions.
_ORDER_SAID = re.compile(r"\b(?:first|second|third|fourth|fifth|last)\s+(?:\w+\s+){1,2}?(from\s+the\s+(?:west|east|north|south|left|right))\b")
# A thing said to be the middle one of a row: "the middle car", "the car in the middle of the row".
_MIDDLE_SAID = re.compile(r"\bmiddle\s+([a-z]+)\b|\b([a-z]+)\s+(?:in|at) the (?:middle|centre|center) of (?:the|that|this) (?:row|line)\b")
# Within this of a place named in the clause, things are counted as at it ("the second car from the west in lot B").
ORDER_AT_PLACE_M = 25.0


def counted_kinds(low: str) -> set[str]:
    """The categories a thing counted from a side, said to be the middle one or picked by its size
    may be, by the word it was called ("the second car from the left", "the middle car", "the
    biggest vehicle": every kind the catalog tags a car or a vehicle)."""
    kinds = {c for members in md.groups_said(low).values() for c in members} if md.SIZE_SUPERLATIVE.search(low) else set()
    # "the car by the union and the one in the middle of the row": the middle one is of a kind said before
    middles = re.findall(r"[a-z]+", low) if _MIDDLE_SAID.search(low) else []
    for word in (*(ph.singular(w) for w in middles), *(ph.singular(s.group(0).split()[-4]) for s in _ORDER_SAID.finditer(low))):
        if word in md.catalog_tags():
            kinds |= {c.name for c in catalog().values() if word in c.tags}
    return kinds


def without_order(masked: str) -> str:
    """`masked` with each ordinal counted from a side blanked ("the third car from the west ...
    forward"): it picks a thing out and says no way to move it."""
    for said in _ORDER_SAID.finditer(masked):
        masked = _blank(masked, said.start(1), said.end(1))
    return masked


def _at_named_place(scene: Scene, low: str, present: list[AssetInstance]) -> list[AssetInstance]:
    place = find_place(scene, low)
    landmark = scene.landmark(place[0]) if place else None
    if landmark is None:
        return []
    return [a for a in present if math.dist((a.pose.x, a.pose.y), landmark.position) <= ORDER_AT_PLACE_M]


def _numbered(scene: Scene, low: str, mentions: list[ph.Mention]) -> tuple[list[str], list[ph.Mention]]:
    """Assets named by category and number or ordinal: "car 2", "car two", "the second car"."""
    ids: list[str] = []
    rest: list[ph.Mention] = []
    picks = numbered_picks(scene, low)
    for mention in mentions:
        before = low[: mention.start].split()[-2:]
        picked = next((ident for ident, start, _ in picks if mention.start <= start < mention.end), None)
        listed = _PICKED_AFTER.match(low, mention.end)  # "street lights 9 and 11": the later numbers name more of them
        more = [ident for ident, start, _ in picks if listed is not None and mention.end <= start < listed.end()] if picked else []
        present = sorted(
            (a for a in scene.assets if a.category == mention.category),
            key=lambda a: int(a.id.rsplit("_", 1)[-1]) if a.id.rsplit("_", 1)[-1].isdigit() else 0,
        )
        ordinal = next((lx.ORDINALS[w] for w in reversed(before) if w in lx.ORDINALS), None)
        ordinal = None if before[:1] == ["every"] else ordinal  # "every second street light": one in two, not the second
        side = _FROM_SIDE.match(low[mention.end :])
        if ordinal is not None and side is not None:  # "the second car from the west": counted across the map
            east, north = _SIDE_VECTORS[side.group(1)]
            word = ph.singular(low[mention.start : mention.end].strip())
            if word in md.catalog_tags():  # "the second car from the left": of every kind called a car, SUVs too
                present = [a for a in scene.assets if word in catalog()[a.category].tags]
            present = sorted(present, key=lambda a: -(a.pose.x * east + a.pose.y * north))
            present = _at_named_place(scene, low, present) or present
        middle = _IN_THE_MIDDLE.match(low[mention.end :])  # "the car in the middle (of the row)"; "one bin in the middle" is a place
        if before[-1:] == ["middle"] or (middle is not None and (" of " in middle.group(0) or before[-1:] in (["the"], ["that"], ["this"]))):
            ids.append(_middle_of_row(scene, low, mention).id)
        elif picked is not None:
            ids += [picked, *more]
        elif ordinal is not None and present and -1 <= ordinal <= len(present) and ordinal != 0:
            many = _how_many_of_the_order(before, ordinal, len(present))
            if many == 0:
                rest.append(mention)
            elif many > 1:  # "the last two cones", "the first 3 benches from the west": that many from that end
                ids += [a.id for a in (present[:many] if ordinal == 1 else present[-many:])]
            else:
                ids.append(present[ordinal - 1 if ordinal > 0 else -1].id)
        else:
            rest.append(mention)
    return ids, rest


def _how_many_of_the_order(before: list[str], ordinal: int, present: int) -> int:
    """How many the words take from one end ("the first two", "the last 3"): 1 unless a count
    follows "first" or "last" and there are more than that many."""
    if len(before) == 2 and before[0] == "other" and (before[1].isdigit() or before[1] in ph.NUMBER_WORDS):
        return 0  # "the other two cones": those the last edit left alone, not the second one
    said = before[-1] if len(before) == 2 and before[0] in ("first", "last") and ordinal in (1, -1) else ""
    many = int(said) if said.isdigit() else ph.NUMBER_WORDS.get(said, 1)
    return many if 1 < many < present else 1


# "(the car) in the middle of the row", "the car in the middle": the middle one of a row of its kind (never "in the
# middle of the road", a place).
_IN_THE_MIDDLE = re.compile(r"\s+(?:\w+\s+)?(?:in|at) the (?:middle|centre|center)(?: of (?:the|that|this) (?:row|line)\b|(?! of\b)\b)")
# Things of a kind further apart than this are no row ("the middle car" of the whole campus is none).
ROW_SPAN_M = 40.0


def _middle_of_row(scene: Scene, low: str, mention: ph.Mention) -> AssetInstance:
    """The middle one of the row of the kind `mention` names (every kind called so: "car" takes in
    SUVs), at the place the clause names if it names one; when they stand in no row, or in an even
    number, no one is the middle one and the words are refused rather than one taken at random."""
    word = ph.singular(low[mention.start : mention.end].strip())
    kinds = {c.name for c in catalog().values() if word in c.tags} if word in md.catalog_tags() else {mention.category}
    present = [a for a in scene.assets if a.category in kinds]
    row = _at_named_place(scene, low, present) or present
    xs, ys = [a.pose.x for a in row], [a.pose.y for a in row]
    if len(row) < 3 or len(row) % 2 == 0 or max(max(xs) - min(xs), max(ys) - min(ys)) > ROW_SPAN_M:
        raise PlanningError(f"no {word} is the middle one: the {len(row)} here stand in no row with one in the middle; "
                            f"say which by its place or id ({', '.join(sorted(a.id for a in row))})")
    along = (lambda a: a.pose.x) if max(xs) - min(xs) >= max(ys) - min(ys) else (lambda a: a.pose.y)
    return sorted(row, key=along)[len(row) // 2]


# Catalog words that are also verbs of the requests people make.
_VERB_NOUNS = ("stop", "plant", "post", "signal", "seat", "cycle", "park", "fence", "ring")

def used_as_verb(low: str, start: int, end: int) -> bool:
    """Whether the catalog word at low[start:end] is a verb here: one that is also a verb ("stop
    the ego", "fence it off", "fence off the tree") before a noun phrase or at the start."""
    said = low[start:end]
    if said.endswith("s") and said[:-1] in _VERB_NOUNS and re.search(r"\b(?:ego|it|he|she|someone|somebody|who|then|[a-z]+_\d+)\s+$", low[:start]):
        return True  # "the ego cycles round the loop", "then it parks in lot A": what something does
    return said in _VERB_NOUNS and bool(
        start <= 1 or re.search(r"\b(?:to|must|should|will|would|can|could|may|might|'ll|gonna|has to|have to|had to)\s+$", low[:start])
        or re.match(r"\s+(?:off\s+)?(the|our|it|that|ego|an?|some|\d+|two|three|four|five|six)\b", low[end:])
        # "make the rain stop", "the snow should stop now": a weather word's verb, at the end of the clause
        or (re.search(r"\b(?:rain|raining|snow|snowing|fog|drizzle|storm|wind|sleet|hail)\s+(?:to\s+|should\s+|must\s+|will\s+)?$", low[:start])
            and re.match(r"\s*(?:now|please|pls|already)?\s*[.!?]*\s*$", low[end:])))


# Concept words that name one person or thing, not a crowd or a mass ("somewhere to sit" is one bench).
_ONE_THING = ("someone", "somebody", "guy", "somewhere to sit", "to sit", "can sit", "sit down", "seat", "chair", "to throw", "shrub",
              "bush", "palm", "warning", "warning sign")

# A wish said of someone with the thing wished for after it ("the students could use somewhere to
# sit", "drivers need a warning").
_WISHED = re.compile(r"\b(?:could use|could do with|would like|would love|needs?|wants?|deserves?|(?:will |would |shall )?require|requires)\s+"
                     r"(?=(?:a|an|some|somewhere|something|more|another|extra|new|\d+|two|three|a few|several)\b)"
                     # "the kids have nowhere to sit": who lacks it is not what is asked
                     r"|\b(?:have|has|had|got)\s+(?:nowhere|no ?where|no place)\s+(?=to (?:sit|rest)\b)")


def without_beneficiaries(low: str, mentions: list[ph.Mention]) -> list[ph.Mention]:
    """`mentions` without those who would have what is wished for: they are not what is asked."""
    wish = _WISHED.search(low)
    return mentions if wish is None else [m for m in mentions if m.start >= wish.end()]
# Going somewhere on foot or by bike: "walk to the library", "head over to the fountain", "ride towards
# the gate", "a man heading for the east gate", "someone on her way to the union".
GOES_TO = re.compile(r"\b(?:walk|stroll|head|go|run|jog|wander|rid|cycl|ambl|hurr(?:y|i)|march|strid|trudg|rush|sprint"
                     r"|driv|mak(?:e|es|ing) (?:his|her|their|its)(?: own)? way|on (?:his|her|their|its) way|strode|rode|drove|ran|went)"
                     r"(?:e|s|es|e?d|(?:n|g)?ing|(?:g)?ed)?\b(?:\s+(?!only\b)[a-z]+ly)?(?:\s+(?:over|across|back|off|on|up|down|straight|along|out|round|around|forth))?"
                     r"(?:\s+from(?:\s+[a-z0-9_'§]+){1,5}?)?\s+(?:to|towards?|for|into)\s+"
                     # a vehicle driven there by someone: "drive the suv towards the east gate"
                     r"|\b(?:driv(?:e|es|ing)|drove)\s+(?:the|our|my|that|this|his|her|their)\s+[a-z0-9_]+"
                     r"(?:\s+(?:over|back|straight))?\s+(?:to|towards?|into)\s+"
                     # sent on its way, not put there: "send the suv towards the east gate" ("send it to the gate" may place it)
                     r"|\b(?:sen(?:d|ds|ding|t))\s+(?:the|our|my|that|this|his|her|their)\s+[a-z0-9_]+(?:\s+(?:off|on))?\s+towards?\s+")
# The words before a walk whose walker was named before them ("a man at the stop who then walks to the
# bench", "now have her jog over to the hydrant").
_SUBJECT_GONE = re.compile(r"(?:.*\b(?:who|he|she|they|him|her|them)\s+)?\s*(?:(?:and|then|now|later|after that|afterwards|slowly|quickly)\s+)*")
# A place named this far into the words after "to" is where the walk goes ("to the big fountain").
GOAL_REACH = 16


def without_goals(low: str, mentions: list[ph.Mention]) -> list[ph.Mention]:
    """`mentions` without where a walker named before it goes ("a man who walks to the bench"):
    the bench is a destination, not a thing asked for."""
    going = GOES_TO.search(low)
    walker = going is not None and (any(m.end <= going.start() and catalog()[m.category].motion == "walker" for m in mentions)
                                    or _SUBJECT_GONE.fullmatch(low[: going.start()]) is not None)  # "..., then walks to"
    if going is None or not walker:
        return mentions
    return [m for m in mentions if not going.end() <= m.start <= going.end() + GOAL_REACH]


# A warning about people on foot is the pedestrian sign's.
_ABOUT_WALKERS = re.compile(r"\b(?:cross(?:es|ing)?|crosswalk|pedestrians?|children|kids|people|walkers|school)\b")
# Words for a person who does something to a thing named beside them.
_AGENTS = ("someone", "somebody")


def _concepts(low: str, taken: list[ph.Mention]) -> list[ph.Mention]:
    found: list[ph.Mention] = []
    # "the traffic control" is the work zone's kit, not traffic
    works = [w.span() for word in lx.WORKS_WORDS for w in re.finditer(rf"(?<![a-z]){re.escape(word)}(?![a-z])", low)]
    for category, words in lx.CONCEPTS.items():
        for word in words:
            m = re.search(rf"(?<![a-z]){re.escape(word)}(?![a-z])", low)
            if m and any(s <= m.start() and m.end() <= e for s, e in works):
                continue
            if m and not any(t.start < m.end() and m.start() < t.end for t in taken + found):
                if word in _AGENTS and any(t.start > m.end() for t in taken):
                    continue  # "someone left their car there": the car is the thing, not the someone
                if category == "construction_sign" and _ABOUT_WALKERS.search(low):
                    category = "pedestrian_sign"  # "a warning that children cross here": the crossing sign
                found.append(ph.Mention(category, m.start(), m.end(), word not in _ONE_THING))
    return found


# Who something is for, or where they are ("for the students", "for somewhere children walk"): not what is asked.
# ... or whom a thing not named does something for: "something near it that warns the people", "anything to
# protect the kids": the people are who it is for.
_SERVED_BY = re.compile(r"\b(?:something|anything|some ?thing|a thing|stuff)\b[^,.;]*\b(?:that|which|to)\s+[a-z]+\s+(?:the\s+|our\s+|those\s+|these\s+|all\s+)?$")
_FOR_WHOM = re.compile(r"\bfor\s+(?:the\s+|a\s+|an\s+|somewhere\s+|anywhere\s+|a place\s+(?:where\s+)?|where\s+)?$")


# A thing picked out by where it stands, then sent somewhere: "move the tree by lot A over to the fountain".
_PICKED_BY = re.compile(r"\b(?:move|shift|relocate|take|bring|carry|drag|push|put|send)\b.*\b(?:by|near|beside|next to|at|in|outside|(?:nearest|closest)(?: to)?)\s+(?:the\s+)?$")
_SENT_TO = re.compile(r"\b(?:over |up |across |back |down )?(?:to|into|onto)\s+")


def destination(scene: Scene, low: str, place: tuple[str, int, int] | None) -> tuple[str, int, int] | None:
    """Where a thing picked out by its place is sent, when the words name both; None otherwise."""
    if place is None or not _PICKED_BY.search(low[: place[1]]):
        return None
    sent = _SENT_TO.search(low, place[2])
    there = find_place(scene, low[sent.end() :]) if sent is not None else None
    if sent is None or there is None or there[0] == place[0]:
        return None
    return there[0], there[1] + sent.end(), there[2] + sent.end()


# The person's own name for a thing, said beside it: "..., that's our steward", "call it the pace car".
_NAMED_AS = re.compile(r"[,;.\s\u2014-]+(?:(?:that|this|it|he|she)(?:'s| is)|call (?:it|him|her)|name (?:it|him|her)|as)\s+"
                       r"(?:our|the|my|your)\s+([a-z][a-z -]{1,28}?)\s*[.!]*\s*$", re.IGNORECASE)


def named_as(clause: str) -> tuple[str, str]:
    """`clause` without the person's name for what it adds, and that name ("" when none)."""
    said = _NAMED_AS.search(clause)
    if said is None or (ph.find_categories(said.group(1)) and not re.search(r"\b(?:our|my)\b", said.group(0))):
        return clause, ""  # "as the bench": a thing's own word, not a name for it
    return clause[: said.start()], said.group(1).strip().lower()


def labelled(scene: Scene, low: str) -> list[tuple[str, int, int]]:
    """Things the words name by the name the person gave them ("the steward"): id and span."""
    names: dict[str, list[str]] = {}
    for asset in scene.all_assets():
        if asset.label and asset.label != "maintenance":
            names.setdefault(asset.label.lower(), []).append(asset.id)
    out = []
    for name, ids in names.items():
        said = re.search(rf"\b(?:the|our|my|that|this)\s+({re.escape(name)})\b", low)
        if said is not None and len(ids) == 1:
            out.append((ids[0], said.start(1), said.end(1)))
    return out


# A kind and a number that picks one thing out ("car 1", "bench number two"), never an amount or a
# measure ("car 5 m ahead", "cones 3 deep"), nor a count of what follows ("plant 4 trees").
_PICK_NUMBER = r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b"
_NOT_A_MEASURE = (r"(?!\s*(?:m|metres?|meters?|ft|feet|yards?|km|kph|mph|%|x|more|of|deep|wide|high|across|seconds?|s|deg|degrees?|minutes?|mins?"
                  r"|hours?|hrs?|h|am|pm|o'?clock|times|cm|mm|miles?|percent|clockwise|anti-?clockwise|counter-?clockwise)\b)(?!\s*°)"
                  r"(?![.,]\d)(?!\s+(?:at a time|by one|after (?:the )?(?:other|another))\b)")  # "the cars one at a time": all
_PICKED = re.compile(rf"\b([a-z]+)\s+(?:number |no\. |nr |# ?)?({_PICK_NUMBER}){_NOT_A_MEASURE}")
# The numbers said after a kind's name, one or a list: "street light 9", "the lamps no. 9 and 11",
# "trees 1, 2 and 4" (the list is read whole or not at all: "cones 2 and 3 m apart" picks none).
_PICKED_AFTER = re.compile(rf"\s*(?:numbers? |nos?\.? ?|nr\.? |# ?)?{_PICK_NUMBER}"
                           rf"(?:(?:\s*,\s*(?:and\s+)?|\s+(?:and|&)\s+)(?:number |no\. |# ?)?{_PICK_NUMBER})*+{_NOT_A_MEASURE}")


def numbered_picks(scene: Scene, low: str) -> list[tuple[str, int, int]]:
    """Things the words pick out by kind and number ("use car 1", "bench number two", "street lights
    9 and 11"): the id of each one the scene has, and the span of `low` that names it (the kind and
    the first number for the first, each later number for the rest)."""
    out = []
    for mention, picked in _kinds_numbered(low):
        if any(scene.asset(ident) is None for ident, _ in picked):
            continue  # a number the scene has no such thing for (see numbered_absent)
        out += [(ident, mention.start if k == 0 else n.start(), n.end()) for k, (ident, n) in enumerate(picked)]
    for said in _PICKED.finditer(low):
        kinds = {m.category for m in ph.find_categories(said.group(1))}
        if any(start <= said.start(2) < end for _, start, end in out):
            continue  # read with the rest of its list
        if len(kinds) != 1 or _counts_what_follows(low, said.end()) or low[: said.start()].rstrip().endswith(" as"):
            continue  # "mark the SUV as vehicle 2": a label
        if scene.asset(ident := f"{kinds.pop()}_{_picked_number(said.group(2))}") is not None:
            out.append((ident, said.start(), said.end()))
    return sorted(out, key=lambda pick: pick[1])


# The highest number read as a thing's that the scene lacks; a bigger one is an amount said loosely.
ABSENT_NUMBER_MAX = 20


def numbered_absent(scene: Scene, low: str) -> list[str]:
    """Things the words pick out by kind and number that the scene does not have, though it has
    others of their kind ("rotate bench 4" where the one bench is bench_1): each as said, "bench 4"."""
    return [f"{mention.category.replace('_', ' ')} {n.group(0)}" for mention, picked in _kinds_numbered(low)
            for ident, n in picked if scene.asset(ident) is None and scene.count(mention.category)
            and _picked_number(n.group(0)) <= ABSENT_NUMBER_MAX]  # "turn the car 90": an angle, no car 90


def _kinds_numbered(low: str) -> list[tuple[ph.Mention, list[tuple[str, re.Match[str]]]]]:
    """Each kind said with numbers after it ("street lights 9 and 11"), with the id each number
    would name and where the number is."""
    out = []
    for mention in ph.find_categories(low, normalised=True):
        listed = _PICKED_AFTER.match(low, mention.end)
        if listed is None or _counts_what_follows(low, listed.end()) or low[: mention.start].rstrip().endswith(" as"):
            continue  # "mark the SUV as vehicle 2": a label
        numbers = [n for n in re.finditer(rf"\b{_PICK_NUMBER}", low[: listed.end()]) if n.start() >= mention.end]
        out.append((mention, [(f"{mention.category}_{_picked_number(n.group(0))}", n) for n in numbers]))
    return out


def _counts_what_follows(low: str, end: int) -> bool:
    """Whether the number before `end` counts the thing named after it ("next to tree 3 cones")."""
    counted = ph.find_categories(re.split(r"[,.;:!?]", low[end : end + 24])[0])  # never past the clause: "car 1. then the suv"
    # "passenger car 2 is my car": what is said of it, after its verb, is counted by nothing
    said_of = re.match(r"\s*(?:is|are|was|were|has|have|had|should|will|would|can|could|must|does|did|'s)\b", low[end:])
    return bool(counted) and said_of is None and not low[end:].lstrip().startswith(("and", "or", "to", "in", "at", "on", "by"))


def _picked_number(word: str) -> int:
    return int(word) if word.isdigit() else ph.NUMBER_WORDS[word]


def read(text: str, scene: Scene) -> Reading:
    """Parse one clause against the scene."""
    low = ph.normalise(text)
    masked = low
    spans: list[tuple[int, int]] = []
    place = find_place(scene, low)
    if place is not None:
        spans.append(place[1:])
    given = labelled(scene, low)  # "the steward": the thing the person named so
    spans += [(start, end) for _, start, end in given]
    # Lanes are read with the place blanked: "the east gate" says nothing about eastbound.
    lane = find_lane(scene, _blank(low, *place[1:]) if place is not None else low)
    if lane is not None and lane[2] > lane[1]:
        spans.append((lane[1], lane[2]))
    for road in {lane.road for lane in scene.roads.lanes if lane.road}:
        said = re.search(rf"(?<![a-z]){re.escape(ph.normalise(road).strip())}(?![a-z])", low)
        if said is not None:  # "Campus Drive" names a road: its "drive" asks no one to drive
            spans.append((said.start(), said.end()))
    ego = _ego_span(low)
    if ego is not None:
        spans.append(ego)
    for start, end in spans:
        masked = _blank(masked, start, end)
    said_names = [(said.span(), name == lm.name) for lm in scene.landmarks for name in lm.names()
                  for said in re.finditer(rf"(?<![a-z]){re.escape(ph.normalise(name).strip())}(?![a-z])", low)]
    named = [span for span, _ in said_names]  # "from the bus stop to ...": no stop sign
    # a second place named in full ("between the bus stop and the west crosswalk") asks nothing either: no
    # stop to make ("the car park", "a crosswalk" may be a kind of place asked about: "which car park ...")
    for (start, end), full in said_names:
        if full and not any(s <= start and end <= e for s, e in spans):
            masked = _blank(masked, start, end)
    # ... where the thing's word sits inside the name: "a pedestrian crossing the road" is still a pedestrian
    mentions = [m for m in ph.find_categories(text) if not any(m.start < e and s < m.end for s, e in spans)
                and not any(s < m.start < e for s, e in named)]
    # A catalog word that is also a verb ("stop the ego", "plant an avenue of trees", "post a
    # sign") is the verb before a noun phrase or at the start, the thing otherwise.
    mentions = [m for m in mentions if not used_as_verb(low, m.start, m.end)]
    mentions += _concepts(masked, mentions)
    mentions.sort(key=lambda m: m.start)
    # "somewhere for students to sit": the students are who it is for, not what is asked.
    if len(mentions) > 1 or place is not None or ego is not None:  # "slow our car down, ... for somewhere children walk"
        kept = [m for m in mentions if not _FOR_WHOM.search(low[: m.start])]
        mentions = kept if kept or place is not None or ego is not None else mentions
    mentions = [m for m in mentions if not _SERVED_BY.search(low[: m.start])]
    mentions = without_goals(low, without_beneficiaries(low, mentions))
    going = HOW_THINGS_GO.match(low, len(low) - len(low.lstrip()))
    if going is not None and any(m.start >= going.end() for m in mentions):  # "people keep saying there's nowhere to sit"
        mentions = [m for m in mentions if m.start >= going.end()]
    # "a night test of pedestrian detection": what a sensor task is about is its topic, not a thing asked for
    mentions = [m for m in mentions if not _PERCEPTION_TASK.match(low[m.end :])]
    words = {t.removesuffix("'s") for t in ph.tokens(low)}  # "suv_1's pose"
    ids = [i for i in ph.find_asset_ids(scene, low.replace(" ", "  ")) if i in words] + [i for i, _, _ in given]
    # "those cone I added": a plural said by its determiner when the noun is written singular
    mentions = [replace(m, plural=True) if re.search(r"\b(?:those|these|all)\s+$", low[: m.start]) else m for m in mentions]
    numbered, mentions = _numbered(scene, low, mentions)
    masked = without_order(masked)
    return Reading(
        text=text,
        low=low,
        masked=masked,
        mentions=mentions,
        landmark=place[0] if place else None,
        landmark_at=place[1] if place else -1,
        landmark_word=None if place else _place_head_word(scene, low, mentions),
        lane=lane[0] if lane else None,
        lane_guessed=bool(lane and lane[3]),
        ids=list(dict.fromkeys(ids + numbered)),
        ego=ego is not None,
        ego_at=ego[0] if ego is not None else -1,
    )


# A count said after the thing: "cones x4", "... 6 of them".
# "cones x4", "a ring of people, 6 of them", "lining the lane with cones, like 10" (a rough count said last)
_COUNT_AFTER = re.compile(r"^\s*[x×]\s?(\d+)\b|\b(\d+|[a-z]+) (?:of them|pieces|pcs|units|items)\b"
                          r"|,\s*(?:like|about|around|roughly|maybe|say|approximately|approx\.?)\s+(\d+)\s*(?:or so)?\s*[.!?]*\s*$")
# An amount whose noun is left out, said after the thing: "too many lamp posts, lose a few",
# "there are cones everywhere. Take three away." (the amount is the object of a verb of adding or
# taking away, and nothing follows it but a particle).
_ELIDED_COUNT = re.compile(r"\b(?:lose|remove|delete|drop|ditch|scrap|cut|take|get rid of|knock off|add|put|place|throw in|bring in)"
                           r"\s+(?:another\s+|an?\s+)?(\d+|[a-z]+)\s+(?:more\s+)?(?:away|off|out|in|down)?\s*(?:[.!?;,]|$)")


def find_count(reading: Reading, mention: ph.Mention) -> int | None:
    """The number quantifying a mention; collective nouns ("a row of") are not "one"; a number
    that cannot be a count ("nan", "2.5") is refused rather than replaced by a default."""
    before = reading.low[: mention.start]
    partitive = md.partitive_count(before)
    if partitive is not None:
        return partitive
    if not mention.plural and re.search(r"\bsome\s+(?:[a-z]+\s+)?$", before):
        return 1  # "some broken concrete", "some rubble": one heap of a thing not counted
    if re.search(r"\bboth\s+(?:of\s+)?(?:the\s+)?(?:[a-z]+\s+)?$", before):
        return 2  # "the both tree near the fountain": two, however the noun is said
    itself = reading.low[mention.start : mention.end].strip()
    if lx.COLLECTIVE_COUNTS.get(itself) and not re.search(r"\b(?:\d+|a few|several)\s*$", before):
        return lx.COLLECTIVE_COUNTS[itself]  # "a crowd at the fountain": a crowd's worth, not one
    after = _COUNT_AFTER.search(reading.low[mention.end :])  # "cones x4", "a ring of people, 6 of them"
    word = next(g for g in after.groups() if g) if after is not None else ""
    if word.isdigit() or word in ph.NUMBER_WORDS:  # not "2 more of them": more is no number
        return int(word) if word.isdigit() else ph.NUMBER_WORDS[word]
    elided = _ELIDED_COUNT.search(reading.low[mention.end :])
    if elided is not None and (elided.group(1).isdigit() or elided.group(1) in ph.NUMBER_WORDS):
        return int(elided.group(1)) if elided.group(1).isdigit() else ph.NUMBER_WORDS[elided.group(1)]
    words = ph.tokens(before)
    for k in range(len(words) - 1, max(-1, len(words) - 5), -1):
        word = words[k]
        # "a lot of cones", but not the lot of "parking lot, so the cars"
        if word in lx.COLLECTIVE_COUNTS and (word not in COUNT_BEFORE_OF or words[k + 1 : k + 2] == ["of"]):
            return lx.COLLECTIVE_COUNTS[word] or None
        if word.isdigit() or word in ph.NUMBER_WORDS or any(c.isdigit() for c in word) or word in ("nan", "inf"):
            break
    count = ph.count_in_window(before, ph.singular(reading.low[mention.start : mention.end].strip()) + "s")
    # "a no-go zone with cones": an "a" belongs to a singular noun, never to the plural one
    # ("a buss" right before is a singular misspelt, and stays one)
    count = None if count == 1 and mention.plural and not re.search(r"\b(?:1|an?)\s*$", before) else count
    if count is None and mention.plural and re.search(r"\bfill(?:s|ed|ing)?\b.*\bwith\s+(?:\w+\s+)?$", before):
        return lx.COLLECTIVE_COUNTS["lots"]  # "fill lot A with cars": lots of them, not the default few
    return count


def is_new(reading: Reading, mention: ph.Mention, add_verb: bool, present: bool) -> bool:
    """Whether a mention asks for a new asset ("a cone") rather than names one there ("the cone")."""
    if add_verb or re.search(r"\b(?:somewhere|something|nowhere|no ?where|no place|nothing|where (?:they|people|we|you|one|kids|students) (?:can|could|might))\b"
                             r"(?:\s+[\w'-]+){0,5}\s*$", reading.low[: mention.end]):
        return True  # "somewhere to sit" asks for a new one, as "a seat" does; "nowhere to sit" lacks one
    words = ph.tokens(reading.low[: mention.start])
    for k in range(len(words) - 1, max(-1, len(words) - 4), -1):
        word = words[k]
        if word == "one" and k == len(words) - 1 and k > 0 and words[k - 1] in ("put", "place", "set", "stick", "drop", "plant", "and", "plus"):
            return True  # "put two bins at the east gate and one bench at the main gate": one more, as "a" is
        if word.isdigit() or (word in ph.NUMBER_WORDS and word not in ("one", "a", "an")):
            # "all three vehicles", "the two cars", "the other two cones": a number of things already there
            picked = words[k - 1 : k] in (["other"], ["first"], ["last"], ["remaining"]) and words[k - 2 : k - 1] != [] \
                and words[k - 2] in _OLD_DETERMINERS
            return not picked and (words[k - 1 : k] == [] or words[k - 1] not in (*_OLD_DETERMINERS, "all", "both"))
        collective = word in lx.COLLECTIVE_COUNTS and (word not in COUNT_BEFORE_OF or words[k + 1 : k + 2] == ["of"])
        if word in ("new", "newer", "newest") and k > 0 and words[k - 1] in _OLD_DETERMINERS:
            return False  # "the new fire hydrant": the one just added, there now
        if word in _NEW_DETERMINERS or collective:
            return True
        if word in _OLD_DETERMINERS or word in ("all", "both", "every", "each"):
            return False
    return not present  # a bare noun: the one there is, if there is one


__all__ = ["FIRST_PERSON_EGO", "Reading", "counted_kinds", "find_count", "find_lane", "find_place", "is_new", "labelled", "named_as", "place_kind_said", "read", "says_oncoming",
           "without_order"]
