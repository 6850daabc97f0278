"""An eval case and a suite of them: data only, one JSON object per line of a .jsonl file.

A case names its world, optional earlier turns that build the starting scene, the prompt,
its task and grade, and the checks that judge the outcome. Its JSON Schema ships as
`evals/case.schema.json` (regenerate with `python -m drivetwin.evals.schema`).
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any, Literal

from drivetwin.evals.check_base import CheckResult
from drivetwin.evals.checks import Check
from drivetwin.evals.outcome import CaseOutcome
from drivetwin.tools.base import ToolCall
from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

Task = Literal["search", "addition", "removal", "positioning", "moving", "arrangement", "appearance"]
TASKS: tuple[Task, ...] = (
    "search",
    "addition",
    "removal",
    "positioning",
    "moving",
    "arrangement",
    "appearance",
)
Grade = Literal["direct", "indirect", "vague", "erroneous"]
GRADES: tuple[Grade, ...] = ("direct", "indirect", "vague", "erroneous")
SCHEMA_PATH = Path(__file__).with_name("case.schema.json")
SUITES_DIR = Path(__file__).with_name("suites")


class SetupStep(BaseModel):
    """An earlier turn: a prompt and the calls that carry it out.

    With `planned` false (the default) the calls are replayed as they are, so the starting
    scene is the same for every planner. With `planned` true the planner under test plans
    the prompt itself (a true multi-turn case) and the calls are only a reference solution.
    """

    model_config = ConfigDict(extra="forbid")

    prompt: str = Field(min_length=1)
    calls: list[ToolCall] = Field(default_factory=list)
    planned: bool = False


class Case(BaseModel):
    """One prompt to judge, with its starting scene, its labels and its checks."""

    model_config = ConfigDict(extra="forbid")

    id: str = Field(pattern=r"^[a-z0-9][a-z0-9_.-]{0,79}$")
    world: str = "campus"
    setup: list[SetupStep] = Field(default_factory=list)
    prompt: str = Field(min_length=1)
    task: Task
    grade: Grade
    tags: list[str] = Field(default_factory=list, description="e.g. paper, multi_turn, compound")
    checks: list[Check] = Field(default_factory=list, description="all must pass")
    alternatives: list[list[Check]] = Field(
        default_factory=list,
        description="acceptable outcomes: when given, at least one list must pass as well",
    )
    # A known-good plan, used only to prove the case can pass (the `reference` planner).
    reference: list[ToolCall] = Field(default_factory=list)
    notes: str = ""

    @model_validator(mode="after")
    def _has_checks(self) -> Case:
        if not self.checks and not self.alternatives:
            raise ValueError(f"case {self.id!r} has no checks; add checks or alternatives")
        if any(not alt for alt in self.alternatives):
            raise ValueError(f"case {self.id!r} has an empty alternative; each needs checks")
        return self

    def judge(self, outcome: CaseOutcome) -> tuple[bool, list[CheckResult]]:
        """Whether the outcome passes, and the results of the checks that decided it."""
        results = [check.evaluate(outcome) for check in self.checks]
        passed = all(r.passed for r in results)
        if not self.alternatives:
            return passed, results
        tried = [[check.evaluate(outcome) for check in alt] for alt in self.alternatives]
        for alt in tried:
            if all(r.passed for r in alt):
                return passed, [*results, *alt]
        # None fitted: report the alternative that came closest.
        closest = min(tried, key=lambda alt: sum(not r.passed for r in alt))
        return False, [*results, *closest]


class SuiteError(ValueError):
    """A suite file that cannot be read or holds an invalid case; says which line and why."""


class Suite(BaseModel):
    """The cases of one suite file, in file order, and a digest of its content."""

    name: str
    path: str
    digest: str
    cases: list[Case]

    def case(self, case_id: str) -> Case:
        for case in self.cases:
            if case.id == case_id:
                return case
        raise KeyError(case_id)


def resolve_suite_path(name_or_path: str | Path) -> Path:
    """A suite file from a path, or a shipped suite by name ('smoke', 'full')."""
    path = Path(name_or_path)
    if path.is_file():
        return path
    shipped = SUITES_DIR / f"{name_or_path}.jsonl"
    if shipped.is_file():
        return shipped
    known = ", ".join(sorted(p.stem for p in SUITES_DIR.glob("*.jsonl")))
    raise SuiteError(f"no suite file {str(name_or_path)!r}; shipped suites: {known}")


def load_suite(name_or_path: str | Path) -> Suite:
    """Read and validate every case of a suite file; the first bad line raises SuiteError."""
    path = resolve_suite_path(name_or_path)
    raw = path.read_bytes()
    cases: list[Case] = []
    seen: set[str] = set()
    for number, line in enumerate(raw.decode("utf-8").splitlines(), start=1):
        if not line.strip() or line.lstrip().startswith("//"):
            continue
        try:
            case = Case.model_validate(json.loads(line))
        except json.JSONDecodeError as exc:
            raise SuiteError(f"{path}:{number}: not valid JSON: {exc.msg}") from exc
        except ValidationError as exc:
            first = exc.errors()[0]
            where = ".".join(str(p) for p in first["loc"])
            raise SuiteError(
                f"{path}:{number}: invalid case ({exc.error_count()} error(s)), "
                f"first at {where or 'top level'}: {first['msg']}"
            ) from exc
        if case.id in seen:
            raise SuiteError(f"{path}:{number}: duplicate case id {case.id!r}")
        seen.add(case.id)
        cases.append(case)
    if not cases:
        raise SuiteError(f"{path} holds no cases")
    digest = hashlib.sha256(raw).hexdigest()[:16]
    return Suite(name=path.stem, path=str(path), digest=digest, cases=cases)


def case_json_schema() -> dict[str, Any]:
    """The published JSON Schema of one suite line."""
    schema = Case.model_json_schema()
    schema["$id"] = "https://drivetwin.dev/schema/eval-case-v1.json"
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    return schema
