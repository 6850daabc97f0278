"""Every check kind judged on real scenes: one outcome that passes it and one that fails it."""

from __future__ import annotations

from typing import Any

import pytest
from drivetwin.evals.case import Case
from drivetwin.evals.checks import CHECK_KINDS, Check
from pydantic import TypeAdapter, ValidationError

ADAPTER: TypeAdapter[Any] = TypeAdapter(Check)


def check(data: dict[str, Any]) -> Any:
    return ADAPTER.validate_python(data)


CONES_AT_JTEKT = (
    "arrange_assets",
    {
        "categories": ["traffic_cone"],
        "shape": "line",
        "count": 5,
        "location": {"relation": "in_front_of", "target": "JTEKT building entrance"},
    },
)
CONES_AT_GATE = (
    "arrange_assets",
    {
        "categories": ["traffic_cone"],
        "shape": "line",
        "count": 5,
        "location": {"relation": "in_front_of", "target": "east gate"},
    },
)
RUBBLE = ("add_asset", {"category": "cement_rubble", "location": {"relation": "at", "target": "main intersection"}})
RING = (
    "arrange_assets",
    {
        "categories": ["traffic_cone"],
        "shape": "ring",
        "count": 6,
        "location": {"relation": "at", "target": "cement_rubble_1"},
    },
)
GRID = (
    "arrange_assets",
    {"categories": ["bench"], "shape": "grid", "count": 6, "location": {"relation": "at", "target": "parking lot A"}},
)
RAIN = ("set_weather", {"kind": "rain", "intensity": 0.9})
FOG = ("set_weather", {"kind": "fog"})


# (check, calls that pass it, calls that fail it, setup for both)
CASES: dict[str, tuple[dict[str, Any], tuple[Any, ...], tuple[Any, ...], tuple[Any, ...]]] = {
    "count": ({"kind": "count", "category": "traffic_cone", "min": 5, "max": 5}, (CONES_AT_JTEKT,), (RAIN,), ()),
    "count_delta": (
        {"kind": "count_delta", "category": "bench", "min": -1, "max": -1},
        (("remove_assets", {"assets": ["bench_1"]}),),
        (RAIN,),
        (),
    ),
    "near": (
        {
            "kind": "near",
            "category": "traffic_cone",
            "target": "JTEKT building entrance",
            "within": 8,
            "require_all": True,
        },
        (CONES_AT_JTEKT,),
        (CONES_AT_GATE,),
        (),
    ),
    "relative": (
        {"kind": "relative", "relation": "in_front_of", "asset": "bench_1", "target": "Library entrance"},
        (("place_asset", {"asset": "bench_1", "location": {"relation": "in_front_of", "target": "Library entrance"}}),),
        (("place_asset", {"asset": "bench_1", "location": {"relation": "left_of", "target": "Library entrance"}}),),
        (),
    ),
    "on_surface": (
        {"kind": "on_surface", "surfaces": ["sidewalk"], "category": "pedestrian"},
        (("add_asset", {"category": "pedestrian", "location": {"relation": "on_sidewalk", "target": "bus stop"}}),),
        (("add_asset", {"category": "pedestrian", "location": {"relation": "at", "target": "parking lot B"}}),),
        (),
    ),
    "in_lane": (
        {"kind": "in_lane", "lane": "main_westbound", "category": "truck", "aligned": True},
        (("add_asset", {"category": "truck", "location": {"relation": "in_lane", "target": "main_westbound"}}),),
        (("add_asset", {"category": "truck", "location": {"relation": "in_lane", "target": "main_eastbound"}}),),
        (),
    ),
    "arrangement": (
        {"kind": "arrangement", "shape": "ring", "category": "traffic_cone", "around": "cement_rubble_1"},
        (RING,),
        (
            (
                "arrange_assets",
                {
                    "categories": ["traffic_cone"],
                    "shape": "line",
                    "count": 6,
                    "location": {"relation": "at", "target": "cement_rubble_1"},
                },
            ),
        ),
        (RUBBLE,),
    ),
    "behaviour": (
        {"kind": "behaviour", "behaviour": "jaywalk", "category": "pedestrian", "crosses_lane": "main_eastbound"},
        (("add_asset", {"category": "pedestrian", "behaviour": {"kind": "jaywalk"}}),),
        (("add_asset", {"category": "pedestrian", "behaviour": {"kind": "parked"}}),),
        (),
    ),
    "environment": ({"kind": "environment", "weather": ["rain"], "intensity_min": 0.7}, (RAIN,), (FOG,), ()),
    "appearance": (
        {"kind": "appearance", "asset": "suv_1", "colour": "red"},
        (("set_asset_appearance", {"assets": ["suv_1"], "colour": "red"}),),
        (("set_asset_appearance", {"assets": ["suv_1"], "colour": "blue"}),),
        (),
    ),
    "moved": (
        {"kind": "moved", "asset": "suv_1", "min_distance": 4, "max_distance": 6, "direction": "forward"},
        (("move_asset", {"asset": "suv_1", "forward": 5}),),
        (("move_asset", {"asset": "suv_1", "forward": 10}),),
        (),
    ),
    "exists": (
        {"kind": "exists", "assets": ["fire_hydrant_1"], "present": False},
        (("remove_assets", {"assets": ["fire_hydrant_1"]}),),
        (("remove_assets", {"assets": ["trash_bin_1"]}),),
        (),
    ),
    "unchanged_except": (
        {"kind": "unchanged_except", "categories": ["traffic_cone"]},
        (CONES_AT_JTEKT,),
        (CONES_AT_JTEKT, RAIN),
        (),
    ),
    "answer_contains": (
        {"kind": "answer_contains", "any_of": ["38.5"], "none_of": ["-85"]},
        (("find_landmarks", {"query": "parking lot B"}),),
        (("find_landmarks", {"query": "parking"}),),
        (),
    ),    "scenario": (
        {"kind": "scenario", "seconds": 16, "expect": [{"kind": "stopped_before", "line": [-14.0, -1.75]}]},
        (("set_light_phases", {"light": "traffic_light_1", "phases": [{"state": "red", "duration": 60}]}),),
        (("set_light_phases", {"light": "traffic_light_1", "phases": [{"state": "green", "duration": 60}]}),),
        (),
    ),
}


def test_every_check_kind_has_a_passing_and_a_failing_scene() -> None:
    assert set(CASES) | {"status"} == set(CHECK_KINDS)


@pytest.mark.parametrize("kind", sorted(CASES))
def test_check_passes_the_right_outcome_and_fails_the_wrong_one(kind: str, outcome_of: Any) -> None:
    data, good, bad, setup = CASES[kind]
    judged = check(data)
    passed = judged.evaluate(outcome_of(*good, setup=setup))
    failed = judged.evaluate(outcome_of(*bad, setup=setup))
    assert passed.passed, passed.reason
    assert not failed.passed
    assert failed.reason and failed.kind == kind


def test_status_check_tells_a_refused_prompt_from_an_accepted_one(outcome_of: Any) -> None:
    judged = check({"kind": "status", "accepted": True})
    assert judged.evaluate(outcome_of(RAIN)).passed
    refused = judged.evaluate(outcome_of(accepted=False))
    assert not refused.passed and "refused" in refused.reason


def test_near_check_measures_from_a_point_when_given_one(outcome_of: Any) -> None:
    placed = outcome_of(
        ("place_asset", {"asset": "suv_1", "location": {"relation": "absolute", "x": 40.0, "y": -20.0}})
    )
    assert check({"kind": "near", "asset": "suv_1", "point": [40, -20], "within": 1}).evaluate(placed).passed
    assert not check({"kind": "near", "asset": "suv_1", "point": [0, 0], "within": 1}).evaluate(placed).passed


def test_a_check_naming_an_unknown_category_is_refused_with_the_nearest_names() -> None:
    with pytest.raises(ValidationError, match="traffic_cone"):
        check({"kind": "count", "category": "trafic_cone", "min": 1})


def test_a_near_check_without_a_target_or_point_is_refused() -> None:
    with pytest.raises(ValidationError, match="exactly one of target and point"):
        check({"kind": "near", "category": "bench"})


def test_a_missing_target_fails_the_check_with_its_name(outcome_of: Any) -> None:
    result = check({"kind": "near", "category": "bench", "scope": "all", "target": "the moon"}).evaluate(
        outcome_of(RAIN)
    )
    assert not result.passed and "the moon" in result.reason


def test_answer_words_match_whole_numbers_only(outcome_of: Any) -> None:
    found = outcome_of(("find_landmarks", {"query": "parking lot B"}))  # "(38.5, -29.0)"
    assert not check({"kind": "answer_contains", "any_of": ["38"]}).evaluate(found).passed
    assert check({"kind": "answer_contains", "all_of": ["parking lot b"]}).evaluate(found).passed


def _case(**extra: Any) -> Case:
    return Case.model_validate({"id": "c", "prompt": "p", "task": "appearance", "grade": "vague", **extra})


def test_a_case_passes_when_any_alternative_passes(outcome_of: Any) -> None:
    case = _case(
        checks=[{"kind": "unchanged_except", "environment": True}],
        alternatives=[[{"kind": "environment", "weather": ["snow"]}], [{"kind": "environment", "weather": ["fog"]}]],
    )
    assert case.judge(outcome_of(FOG))[0]
    ok, results = case.judge(outcome_of(RAIN))
    assert not ok and any(not r.passed for r in results)


def test_a_case_fails_when_a_shared_check_fails_even_if_an_alternative_passes(outcome_of: Any) -> None:
    case = _case(checks=[{"kind": "unchanged_except"}], alternatives=[[{"kind": "environment", "weather": ["fog"]}]])
    assert not case.judge(outcome_of(FOG))[0]
