"""The rule planner reads clock times (in digits, in words, a bare hour the clock is set to), numbers and near-miss spellings as written, and refuses
numbers that cannot be what they quantify instead of substituting a default."""

from __future__ import annotations

from pathlib import Path

import pytest
from drivetwin.orchestrator.planning import PlanningError
from drivetwin.orchestrator.planning.rules import numbers
from drivetwin.orchestrator.planning.rules.clock import clock_time
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.planning.rules.spelling import repair

RULES_DIR = Path(numbers.__file__).parent
# The phrase lists may not grow: understanding comes from grounding, retrieval and the check.
LEXICON_LINES = {"lexicon.py": 137, "phrases.py": 250}


def plan(context, prompt):
    return RulePlanner().plan(prompt, context)


def test_a_clock_time_with_a_colon_is_one_clause_and_sets_that_time(session):
    report = session.submit("could the clock show 21:45 please")
    assert report.ok, report.error
    assert session.scene.environment.time_of_day == "21:45"


@pytest.mark.parametrize(("words", "time"), [
    ("set the time to nine in the evening", "21:00"),
    ("seven o'clock in the morning please", "07:00"),
    ("set the clock to 9", "09:00"),
    ("the time should be eleven", "11:00"),
    ("make it 9 at night", "21:00"),
    ("set the clock for 5 in the afternoon", "17:00"),
    ("let's have it at four o'clock", "16:00"),  # the small hours are said as such
    ("2 o'clock, please", "14:00"),
    ("four o'clock in the morning", "04:00"),
    ("1 o'clock at night", "01:00"),
    ("eight o'clock", "08:00"),
])
def test_an_hour_said_in_words_or_bare_after_the_clock_is_a_time(words, time):
    assert str(clock_time(words)) == time


@pytest.mark.parametrize("words", ["put nine cones at the gate", "set the time to 9 minutes later",
                                   "set the time scale to 2", "drive 9 m/s in the evening"])
def test_a_number_that_counts_or_measures_is_not_a_time(words):
    assert clock_time(words) is None


def test_a_time_said_as_make_it_is_not_a_new_amount_for_the_last_edit(session):
    assert session.submit("add 3 traffic cones by the library").ok
    report = session.submit("make it 9 at night")
    assert report.ok, report.error
    assert session.scene.environment.time_of_day == "21:00"
    assert session.scene.count("traffic_cone") == 3


def test_a_decimal_distance_is_not_split_at_its_point(context):
    calls = plan(context, "shift the ego forward by 2.5 metres").calls
    assert [c.tool for c in calls] == ["move_asset"]
    assert 2.5 in [v for v in _numbers(calls[0].args)]


def test_a_misspelling_the_catalog_names_as_nearest_is_repaired(context):
    calls = plan(context, "i'd like one bycicle by the library").calls
    assert calls[0].tool == "add_asset" and calls[0].args["category"] == "bicycle"


def test_a_short_word_with_two_letters_swapped_is_repaired_and_one_with_a_letter_changed_is_not(context, campus):
    calls = plan(context, "two walkers at the bus stpo").calls
    assert calls[0].args["location"]["target"] == "bus stop"
    assert repair("a tuck by the gate", campus).repairs == []  # "tuck" is a word, "truck" one letter away


def test_a_command_verb_with_letters_swapped_is_repaired(campus):
    assert repair("paitn the hydrant blue", campus).text == "paint the hydrant blue"
    assert repair("plase rotaet the bench", campus).text.endswith("rotate the bench")


def test_a_slip_in_a_clock_word_is_repaired_and_the_time_read(context):
    calls = plan(context, "could the clock show a quater past eight in the evening").calls
    assert [(c.tool, c.args) for c in calls] == [("set_time_of_day", {"time": "20:15"})]


def test_an_exponent_distance_is_read_in_full(context):
    calls = plan(context, "shift the ego forward by 1e1 metres").calls
    assert 10.0 in _numbers(calls[0].args)


def test_a_count_with_a_thousands_separator_is_read_in_full_and_refused_by_the_worker(session):
    report = session.submit("drop 2,500 traffic cones on the road")
    assert report.plan is None or all(c.args.get("count") != 3 for c in report.plan.calls)
    assert not report.ok
    assert session.scene.count("traffic_cone") == 0


@pytest.mark.parametrize("word", ["nan", "inf", "-inf"])
def test_a_distance_that_is_no_number_is_refused_in_words(context, word):
    with pytest.raises(PlanningError, match=f"'{word}' is not a number"):
        plan(context, f"shift the ego forward by {word} metres")


def test_a_count_that_is_not_whole_is_refused(context):
    with pytest.raises(PlanningError, match="not a number of"):
        plan(context, "put 2.5 benches near the library")


def test_coordinates_far_outside_the_world_are_refused_not_moved_to_the_centre(session):
    before = session.scene.count("traffic_cone")
    report = session.submit("a traffic cone at x=5e8 y=2 please")
    assert not report.ok
    assert session.scene.count("traffic_cone") == before


def test_numbers_parse_separators_exponents_and_non_numbers():
    found = numbers.numbers_in("10,000 cones, 1e2 m, 2.5 s, nan and car_2")
    assert [n.value for n in found[:3]] == [10000.0, 100.0, 2.5]
    assert not found[3].finite and len(found) == 4


@pytest.mark.parametrize(("name", "lines"), sorted(LEXICON_LINES.items()))
def test_the_phrase_lists_do_not_grow(name, lines):
    assert len((RULES_DIR / name).read_text(encoding="utf-8").splitlines()) <= lines


def _numbers(value):
    if isinstance(value, dict):
        return [n for v in value.values() for n in _numbers(v)]
    if isinstance(value, list):
        return [n for v in value for n in _numbers(v)]
    return [float(value)] if isinstance(value, int | float) and not isinstance(value, bool) else []
