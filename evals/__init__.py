"""The eval harness: suites of cases (data), a resumable parallel runner, metrics and reports.

from drivetwin.evals import run_suite, write_report
run_suite("smoke", "rules", trials=3, out_path="runs/rules.jsonl", workers=2)
write_report(["runs/rules.jsonl"], "reports/")
"""

from drivetwin.evals.case import (
    GRADES,
    TASKS,
    Case,
    Grade,
    SetupStep,
    Suite,
    SuiteError,
    Task,
    case_json_schema,
    load_suite,
)
from drivetwin.evals.check_base import CheckResult
from drivetwin.evals.checks import CHECK_KINDS, Check
from drivetwin.evals.metrics import Rate, RunMetrics, compute_metrics, pass_hat_k, wilson
from drivetwin.evals.outcome import CaseOutcome
from drivetwin.evals.records import RecordsError, RunHeader, TrialRecord, read_run
from drivetwin.evals.report import PAPER_TABLE4, write_report
from drivetwin.evals.runner import RunError, RunSummary, run_suite
from drivetwin.evals.trial import REFERENCE_PLANNER, run_trial, scene_fingerprint

__all__ = [
    "CHECK_KINDS",
    "GRADES",
    "PAPER_TABLE4",
    "REFERENCE_PLANNER",
    "TASKS",
    "Case",
    "CaseOutcome",
    "Check",
    "CheckResult",
    "Grade",
    "Rate",
    "RecordsError",
    "RunError",
    "RunHeader",
    "RunMetrics",
    "RunSummary",
    "SetupStep",
    "Suite",
    "SuiteError",
    "Task",
    "TrialRecord",
    "case_json_schema",
    "compute_metrics",
    "load_suite",
    "pass_hat_k",
    "read_run",
    "run_suite",
    "run_trial",
    "scene_fingerprint",
    "wilson",
    "write_report",
]
