"""The later practice suites (practice2 to practice14): valid, big enough in every cell, written from
their sources, and passable. Each was written to its own brief's minimums."""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path
from types import ModuleType
from typing import NamedTuple

import pytest
from drivetwin.evals import (
    practice2_source,
    practice3_source,
    practice4_source,
    practice5_source,
    practice6_source,
    practice7_source,
    practice8_source,
    practice9_source,
    practice10_source,
    practice11_source,
    practice12_source,
    practice13_source,
    practice14_source,
    practice15_source,
    practice16_source,
    practice17_source,
    practice18_source,
    practice19_source,
    practice20_source,
    practice21_source,
    practice22_source,
    practice23_source,
    practice24_source,
    practice25_source,
    practice26_source,
    practice27_source,
    practice28_source,
    practice29_source,
    practice30_source,
    practice31_source,
    practice32_source,
    practice33_source,
    practice34_source,
    practice35_source,
    practice36_source,
    practice37_source,
    practice38_source,
    practice39_source,
    run_suite,
)
from drivetwin.evals.case import Suite, load_suite

TASKS = ("search", "addition", "removal", "positioning", "moving", "arrangement", "appearance")
GRADES = ("direct", "indirect", "vague", "erroneous")
WEIGHTED_TASKS = ("search", "addition", "positioning", "arrangement")


class Brief(NamedTuple):
    """A brief's minimums: cases, cases in every task x grade cell and in every cell of the four
    weighted tasks, multi-turn (of them planned) and compound cases; the grades it weights (each
    outnumbers the direct one); and the suite's source module."""

    cases: int
    per_cell: int
    per_weighted_cell: int
    source: ModuleType
    multi_turn: int = 15
    planned: int = 8
    compound: int = 15
    weighted_grades: tuple[str, ...] = ()


BRIEFS: dict[str, Brief] = {
    "practice2": Brief(160, 5, 8, practice2_source),
    "practice3": Brief(200, 6, 9, practice3_source),
    "practice4": Brief(260, 9, 9, practice4_source),
    "practice5": Brief(260, 9, 9, practice5_source),
    "practice6": Brief(140, 5, 5, practice6_source, multi_turn=12, planned=6, compound=12,
                       weighted_grades=("vague", "indirect")),
    "practice7": Brief(200, 6, 6, practice7_source, multi_turn=15, planned=6, compound=15,
                       weighted_grades=("vague", "indirect", "erroneous")),
    "practice8": Brief(200, 6, 6, practice8_source, multi_turn=15, planned=6, compound=15,
                       weighted_grades=("vague", "indirect", "erroneous")),
    "practice9": Brief(200, 6, 6, practice9_source, multi_turn=15, planned=6, compound=15,
                       weighted_grades=("vague", "indirect", "erroneous")),
    "practice10": Brief(200, 6, 6, practice10_source, multi_turn=15, planned=6, compound=15, weighted_grades=("vague", "indirect", "erroneous")),
    "practice11": Brief(200, 6, 6, practice11_source, multi_turn=15, planned=6, compound=15, weighted_grades=("vague", "indirect", "erroneous")),
    # Everyday wording by ordinary users; its grades are balanced on purpose (every cell 8 or 9).
    "practice12": Brief(250, 8, 8, practice12_source, multi_turn=30, planned=12, compound=15),
    "practice13": Brief(250, 8, 8, practice13_source, multi_turn=30, planned=12, compound=15),
    "practice14": Brief(250, 8, 8, practice14_source, multi_turn=30, planned=12, compound=15),
    "practice15": Brief(250, 8, 8, practice15_source, multi_turn=30, planned=12, compound=15),
    "practice16": Brief(250, 8, 8, practice16_source, multi_turn=30, planned=12, compound=15),
    "practice17": Brief(250, 8, 8, practice17_source, multi_turn=30, planned=12, compound=15),
    # Nine new voices; arrangement (every grade), search indirect and vague, removal vague and moving
    # indirect and vague hold 12 or more, the rest 9 or more.
    "practice18": Brief(270, 9, 9, practice18_source, multi_turn=30, planned=12, compound=15),
    # Nine more new voices; search, moving and arrangement hold 11 in every grade, the rest 9.
    "practice19": Brief(270, 9, 9, practice19_source, multi_turn=30, planned=12, compound=18),
    # Nine more new voices (an investigator, a sailor, an Australian, a food-truck owner, an ex-soldier, a
    # study's grad student, a poet, a self-corrector, a double-negator); search, moving and arrangement hold
    # 11 in every grade, the rest 9.
    "practice20": Brief(270, 9, 9, practice20_source, multi_turn=30, planned=15, compound=18),
    # Nine voices: fire officer, meteorologist, gaffer, foreman, Indian English, all-caps, civil servant, gamer, Scot.
    "practice21": Brief(270, 9, 9, practice21_source, multi_turn=30, planned=15, compound=18),
    # Nine voices: paramedic, lollipop patrol, cabbie, cyclist, Irish, Southerner, data scientist, commentator, emoji.
    "practice22": Brief(270, 9, 9, practice22_source, multi_turn=30, planned=15, compound=18),
    # Eight everyday voices: test engineer, safety driver, researcher, product manager, student, two non-native
    # speakers, someone in a hurry; every cell holds 11.
    "practice23": Brief(280, 10, 10, practice23_source, multi_turn=30, planned=15, compound=18),
    # Eight everyday voices: QA tester, driving instructor, traffic planner, simulation engineer, teacher, retired
    # volunteer, delivery driver, a Spanish or German speaker; search and moving hold 11 in every grade, the rest 10.
    "practice24": Brief(280, 10, 10, practice24_source, multi_turn=30, planned=15, compound=18),
    # Eight everyday voices: parent helping with a school project, city councillor, insurance assessor, game modder,
    # nurse on a break, bus dispatcher, journalist, newcomer to the software; every cell holds 10 to 12.
    "practice25": Brief(290, 10, 10, practice25_source, multi_turn=30, planned=15, compound=18),
    # Eight everyday voices: film location scout, delivery-robot operator, landscape gardener, retired engineer, road
    # safety auditor, event planner, night security guard, a French visiting researcher; every cell holds 11 or 12.
    "practice26": Brief(300, 11, 11, practice26_source, multi_turn=35, planned=20, compound=20),
    # Eight everyday voices: road-safety teacher, taxi driver, claims assessor, texting teenager, municipal traffic
    # planner, wheelchair user, game-level designer, a Spanish speaker; every cell holds 11 or 12.
    "practice27": Brief(310, 11, 11, practice27_source, multi_turn=40, planned=20, compound=20),
    # Eight everyday voices: farmer, HGV driver, hospital porter, ex-police officer, YouTuber, Pole, product owner, worrier.
    "practice28": Brief(320, 11, 11, practice28_source, multi_turn=40, planned=20, compound=20),
    # Eight everyday voices: field-trip teacher, race fan, Japanese speaker, architect, night-shift tester, grandparent, courier, German.
    "practice29": Brief(320, 11, 11, practice29_source, multi_turn=40, planned=20, compound=20),
    # Eight voices: Indian-English administrator, dictation user, gamer, cyclist, estates manager, lawyer, child, AV engineer.
    "practice30": Brief(320, 11, 11, practice30_source, multi_turn=40, planned=20, compound=20),
    # Eight voices: air-traffic controller, stage director, Russian, Nigerian English, estate agent, coach, tired parent,
    # hesitant over-thinker; every cell holds 13.
    "practice31": Brief(340, 11, 11, practice31_source, multi_turn=40, planned=20, compound=20),
    # Eight voices: museum curator, Brazilian Portuguese speaker, electrician, Mandarin speaker, markdown lists,
    # sarcastic user, warehouse manager, New Zealander; every cell holds 13.
    "practice32": Brief(350, 12, 12, practice32_source, multi_turn=40, planned=20, compound=20),
    # Eight voices: land surveyor, Korean speaker, fat-fingered phone typist, chef, Filipino English speaker, festival
    # steward, Welsh English speaker, rambling retired bus driver; arrangement (every grade) and the vague and erroneous
    # grades of every task hold 13, the rest 11 or 12.
    "practice33": Brief(340, 11, 11, practice33_source, multi_turn=45, planned=30, compound=20,
                        weighted_grades=("vague", "erroneous")),
    # Eight voices: terse power user, Italian speaker, Arabic speaker, campus tour guide, librarian, Kenyan English
    # speaker, marathon organiser, nervous first-timer; arrangement (every grade) and the vague and erroneous grades of
    # every task hold 13, the rest 11 or 12.
    "practice34": Brief(340, 11, 11, practice34_source, multi_turn=45, planned=30, compound=20,
                        weighted_grades=("vague", "erroneous")),
    # Eight voices: Swedish speaker, Turkish speaker, South African English speaker, itemising accountant, calm yoga
    # teacher, emergency-drill coordinator, bird-watcher, work-ticket paster; arrangement (every grade) and the vague and
    # erroneous grades of every task hold 13, the rest 11 or 12.
    "practice35": Brief(340, 11, 11, practice35_source, multi_turn=45, planned=30, compound=20,
                        weighted_grades=("vague", "erroneous")),
    # Eight voices: Dutch speaker, Vietnamese speaker, Singaporean English speaker, Jamaican English speaker, surfer and
    # skater, prescription-writing hospital pharmacist, football referee, Midwesterner; arrangement (every grade) and the
    # vague and erroneous grades of every task hold 13, the rest 11 or 12.
    "practice36": Brief(340, 11, 11, practice36_source, multi_turn=45, planned=30, compound=20,
                        weighted_grades=("vague", "erroneous")),
    # Eight voices: Greek speaker, Indonesian speaker, Ghanaian English speaker, Hong Kong Cantonese speaker, tabletop
    # game master, plumber and tradesperson, commit-message software developer, formal letter-writer; arrangement (every
    # grade) and the vague and erroneous grades of every task hold 13, the rest 11 or 12.
    "practice37": Brief(340, 11, 11, practice37_source, multi_turn=45, planned=30, compound=20, weighted_grades=("vague", "erroneous")),
    # Eight voices: Thai speaker, Israeli (Hebrew) speaker, Bengali speaker, Ukrainian speaker, rally co-driver reading
    # pace notes, theatre stage manager calling cues, TV weather forecaster, recipe writer; arrangement (every grade) and
    # the vague and erroneous grades of every task hold 13, the rest 11 or 12.
    "practice38": Brief(340, 11, 11, practice38_source, multi_turn=45, planned=30, compound=20,
                        weighted_grades=("vague", "erroneous")),
    # Eight voices: Persian (Farsi) speaker, Romanian speaker, Czech speaker, Hungarian speaker, podcast host talking to
    # listeners, auctioneer, national park ranger, bus dispatcher; arrangement (every grade) and the vague and erroneous
    # grades of every task hold 13, the rest 11 or 12.
    "practice39": Brief(340, 11, 11, practice39_source, multi_turn=45, planned=30, compound=20, weighted_grades=("vague", "erroneous")),
}
# About 8 % of the cases ask for what the world cannot do; the right outcome is a refusal.
IMPOSSIBLE_SHARE = (0.06, 0.11)

by_suite = pytest.mark.parametrize("name", sorted(BRIEFS))


@pytest.fixture(scope="module")
def suites() -> dict[str, Suite]:
    return {name: load_suite(name) for name in BRIEFS}


@by_suite
def test_every_line_validates_and_ids_and_tags_name_the_suite(suites: dict[str, Suite], name: str) -> None:
    assert len(suites[name].cases) >= BRIEFS[name].cases
    assert all(c.id.startswith(f"{name}.") and name in c.tags for c in suites[name].cases)


@by_suite
def test_the_jsonl_is_what_the_source_writes(name: str) -> None:
    source = BRIEFS[name].source
    lines = [json.loads(line) for line in Path(source.SUITE_PATH).read_text(encoding="utf-8").splitlines() if line.strip()]
    assert lines == source.ALL_CASES


@by_suite
def test_every_task_and_grade_cell_holds_its_minimum(suites: dict[str, Suite], name: str) -> None:
    brief = BRIEFS[name]
    cells = Counter((c.task, c.grade) for c in suites[name].cases)
    for task in TASKS:
        least = brief.per_weighted_cell if task in WEIGHTED_TASKS else brief.per_cell
        for grade in GRADES:
            assert cells[(task, grade)] >= least, (task, grade, cells[(task, grade)])


@by_suite
def test_the_grades_a_brief_weights_outnumber_the_direct_one(suites: dict[str, Suite], name: str) -> None:
    grades = Counter(c.grade for c in suites[name].cases)
    assert all(grades[g] > grades["direct"] for g in BRIEFS[name].weighted_grades), grades


@by_suite
def test_multi_turn_cases_have_earlier_turns_and_enough_are_planned(suites: dict[str, Suite], name: str) -> None:
    multi = [c for c in suites[name].cases if "multi_turn" in c.tags]
    assert len(multi) >= BRIEFS[name].multi_turn and all(c.setup for c in multi)
    planned = [c for c in multi if any(step.planned and step.calls for step in c.setup)]
    assert len(planned) >= BRIEFS[name].planned


@by_suite
def test_compound_cases_ask_two_things(suites: dict[str, Suite], name: str) -> None:
    compound = [c for c in suites[name].cases if "compound" in c.tags]
    assert len(compound) >= BRIEFS[name].compound
    assert all(len(c.reference) >= 2 for c in compound)


@by_suite
def test_impossible_cases_expect_a_refusal_that_changes_nothing(suites: dict[str, Suite], name: str) -> None:
    cases = suites[name].cases
    impossible = [c for c in cases if "impossible" in c.tags]
    low, high = IMPOSSIBLE_SHARE
    assert low <= len(impossible) / len(cases) <= high
    for c in impossible:
        kinds = {(check.kind, getattr(check, "accepted", None)) for check in c.checks}
        assert ("status", False) in kinds and ("unchanged_except", None) in kinds, c.id


@by_suite
def test_every_edit_case_guards_against_collateral_edits(suites: dict[str, Suite], name: str) -> None:
    assert all(any(check.kind == "unchanged_except" for check in c.checks) for c in suites[name].cases)


@by_suite
def test_every_reference_plan_passes(tmp_path: Path, name: str) -> None:
    source = BRIEFS[name].source
    summary = run_suite(source.SUITE_PATH, "reference", out_path=tmp_path / "ref.jsonl", progress=False)
    records = [json.loads(line) for line in (tmp_path / "ref.jsonl").read_text().splitlines()[1:]]
    not_passed = [(r["case_id"], r.get("failed_checks"), r.get("error")) for r in records if r.get("outcome") != "pass"]
    assert summary.complete and summary.failed == 0 and summary.errors == 0, not_passed[:5]
    assert summary.passed == len(source.ALL_CASES)
