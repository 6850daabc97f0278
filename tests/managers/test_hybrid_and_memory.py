"""The hybrid planner's two paths, memory in the managers' prompts, schemas, versions, trace."""

from __future__ import annotations

from typing import Any

import pytest
from drivetwin.orchestrator.backends import BackendInfo, BackendUnavailable
from drivetwin.orchestrator.planning.grounding import Grounder
from drivetwin.orchestrator.planning.hybrid import HybridPlanner
from drivetwin.orchestrator.planning.llm.jr_schema import WorldNames, call_schema
from drivetwin.orchestrator.planning.llm.planner import LlmPlanner, format_trace
from drivetwin.orchestrator.planning.registry import make_planner
from drivetwin.orchestrator.planning.rules.planner import RulePlanner
from drivetwin.orchestrator.session import Session
from drivetwin.prompts.templates import prompt_version
from drivetwin.tools.registry import ToolRegistry
from drivetwin.worlds.catalog import placeable_categories
from drivetwin.worlds.scene import Scene

from .conftest import ScriptedBackend, call, requirement


def args_of(schema: object, tool: str) -> dict[str, Any]:
    """The argument schema of `tool` inside a Jr. manager's answer schema."""
    assert isinstance(schema, dict)
    options = schema.get("anyOf", [schema])
    found = next(o for o in options if o["properties"]["tool"]["const"] == tool)
    return dict(found["properties"]["args"]["properties"])


def hybrid_session(campus: Scene, backend: ScriptedBackend, grounder: Grounder) -> Session:
    return Session(campus, HybridPlanner(RulePlanner(), LlmPlanner(backend, grounder=grounder)))


def test_hybrid_takes_the_fast_path_without_any_model_call_when_rules_are_sure(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    backend = ScriptedBackend([])
    session = hybrid_session(campus, backend, spelling_grounder)
    report = session.submit("make it rain")
    assert report.ok and report.plan is not None
    assert backend.calls == 0
    assert report.plan.planner == "hybrid"
    assert report.plan.trace[0].input == "path: fast"
    assert session.scene.environment.weather.kind == "rain"


def test_hybrid_sends_a_vague_misspelled_prompt_to_the_llm(campus: Scene, spelling_grounder: Grounder) -> None:
    backend = ScriptedBackend(
        [
            requirement("add", "trafic conez", "libary"),
            call("add_asset", category="traffic_cone", location={"relation": "next_to", "target": "Library entrance"}),
        ]
    )
    session = hybrid_session(campus, backend, spelling_grounder)
    report = session.submit("add trafic conez near the libary")
    assert report.ok, report.error
    assert backend.calls == 2
    assert report.plan is not None and report.plan.trace[0].input == "path: llm"
    assert session.scene.count("traffic_cone") == 1


class SizedBackend(ScriptedBackend):
    """A scripted backend that reports a model size, as real backends do."""

    def __init__(self, answers: list[Any], parameters: int) -> None:
        super().__init__(answers)
        self.parameters = parameters

    def describe(self) -> BackendInfo:
        return BackendInfo(self.name, self.model, parameters=self.parameters)


@pytest.mark.parametrize(("parameters", "path", "model_calls"), [(135_000_000, "fast", 0), (9_000_000_000, "llm", 2)])
def test_an_unsure_rule_plan_is_kept_with_a_small_model_and_handed_to_a_large_one(
    campus: Scene, spelling_grounder: Grounder, parameters: int, path: str, model_calls: int
) -> None:
    backend = SizedBackend(
        [
            requirement("add", "trafic conez", "libary"),
            call("add_asset", category="traffic_cone", location={"relation": "next_to", "target": "Library entrance"}),
        ],
        parameters,
    )
    session = hybrid_session(campus, backend, spelling_grounder)
    report = session.submit("add trafic conez near the libary")  # the rules repair two typos: a guess
    assert report.ok, report.error
    assert report.plan is not None and report.plan.trace[0].input == f"path: {path}"
    assert backend.calls == model_calls
    assert session.scene.count("traffic_cone") >= 1


def test_an_explicit_threshold_overrides_the_model_size(campus: Scene, spelling_grounder: Grounder) -> None:
    backend = SizedBackend([requirement("appearance", "rain"), call("set_weather", kind="rain")], 135_000_000)
    planner = HybridPlanner(RulePlanner(), LlmPlanner(backend, grounder=spelling_grounder), confident=1.0)
    report = Session(campus, planner).submit("make it rain")
    assert report.ok and report.plan is not None
    assert report.plan.trace[0].input == "path: llm" and backend.calls == 2


def test_hybrid_falls_back_to_a_half_sure_rule_plan_when_the_model_is_down(
    campus: Scene, spelling_grounder: Grounder
) -> None:
    backend = ScriptedBackend([BackendUnavailable("no server", backend="scripted")])
    session = hybrid_session(campus, backend, spelling_grounder)
    report = session.submit("put some pylns near the library, cheers")  # a repaired word and an unknown one: 0.6
    assert report.ok, report.error
    assert report.plan is not None and report.plan.trace[0].input == "path: fallback"
    assert "no server" in report.plan.trace[0].output


def test_the_prompt_version_is_recorded_with_every_llm_plan(campus: Scene, spelling_grounder: Grounder) -> None:
    backend = ScriptedBackend([requirement("appearance", "rain"), call("set_weather", kind="rain")])
    report = Session(campus, LlmPlanner(backend, grounder=spelling_grounder)).submit("make it rain, please")  # a comma: the Sr. manager is asked
    assert report.plan is not None
    assert report.plan.prompt_version == prompt_version()
    assert report.plan.prompt_version.startswith("prompts-v")


def test_around_there_points_the_jr_manager_at_the_last_edit(campus: Scene, spelling_grounder: Grounder) -> None:
    backend = ScriptedBackend(
        [
            requirement("add", "cement rubble", "main intersection"),
            call("add_asset", category="cement_rubble", location={"relation": "at", "target": "main intersection"}),
            requirement("arrange", "road barriers", "around there", "ring"),
            call(
                "arrange_assets",
                categories=["road_barrier"],
                shape="ring",
                location={"relation": "at", "target": "cement_rubble_1"},
            ),
        ]
    )
    session = Session(campus, LlmPlanner(backend, grounder=spelling_grounder))
    assert session.submit("create cement rubble at the centre of the scene").ok
    report = session.submit("also add road barriers around there")
    assert report.ok, report.error
    sr_prompt = backend.seen[2][0]["content"]
    assert "create cement rubble" in sr_prompt, "the Sr. manager did not see the conversation"
    targets = args_of(backend.schemas[3], "arrange_assets")["location"]["properties"]["target"]
    assert targets["enum"] == ["cement_rubble_1"], "'there' was not grounded to the last edit"
    assert "there -> cement_rubble_1" in backend.seen[3][-1]["content"]


def test_the_cones_you_added_are_the_ids_the_last_turn_added(campus: Scene, spelling_grounder: Grounder) -> None:
    backend = ScriptedBackend(
        [
            requirement("add", "cones", "parking lot B", "2"),
            call("add_asset", category="traffic_cone", count=2, location={"relation": "at", "target": "parking lot B"}),
            requirement("remove", "the cones you added"),
            call("remove_assets", assets=["traffic_cone_1", "traffic_cone_2"]),
        ]
    )
    session = Session(campus, LlmPlanner(backend, grounder=spelling_grounder))
    assert session.submit("add 2 cones in parking lot B").ok
    assert session.submit("remove the cones you added").ok
    assets = args_of(backend.schemas[3], "remove_assets")["assets"]
    assert assets["items"]["enum"] == ["traffic_cone_1", "traffic_cone_2"]
    assert session.scene.count("traffic_cone") == 0


def test_a_jr_schema_offers_only_its_familys_tools_and_names_that_exist(campus: Scene) -> None:
    registry = ToolRegistry.default(plugins=False)
    schema = call_schema(registry.family("add"), WorldNames.of(campus))
    args = args_of(schema, "add_asset")
    assert schema["properties"]["tool"] == {"const": "add_asset"}
    assert args["category"]["enum"] == placeable_categories()
    targets = set(args["location"]["properties"]["target"]["enum"])
    assert "JTEKT building entrance" in targets and "main_eastbound" in targets and "ego" in targets
    assert "pylon" not in targets and "ego_vehicle" not in args["category"]["enum"]
    appearance = call_schema(registry.family("appearance"), WorldNames.of(campus))
    assert {o["properties"]["tool"]["const"] for o in appearance["anyOf"]} == {
        "set_time_of_day",
        "set_weather",
        "set_lighting",
        "set_asset_appearance",
    }


def test_format_trace_shows_every_level_with_input_output_and_time(campus: Scene, spelling_grounder: Grounder) -> None:
    backend = ScriptedBackend(["oops", requirement("appearance", "rain"), call("set_weather", kind="rain")])
    report = Session(campus, LlmPlanner(backend, grounder=spelling_grounder)).submit("make it rain, please")  # a comma: the Sr. manager is asked
    assert report.plan is not None
    text = format_trace(report.plan)
    for level in ("[sr_manager]", "[grounding:appearance]", "[jr_manager:appearance]", "[llm_planner]"):
        assert level in text
    assert "1 retries" in text and "ms" in text and "set_weather(kind='rain')" in text


def test_llm_and_hybrid_planners_are_built_by_name(campus: Scene) -> None:
    llm = make_planner("llm", backend="embedded", model="smollm2-135m")
    hybrid = make_planner("hybrid", backend="embedded", model="smollm2-135m")
    assert llm.name == "llm" and hybrid.name == "hybrid"
