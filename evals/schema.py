"""Write the published JSON Schema of an eval case: `python -m drivetwin.evals.schema`."""

from __future__ import annotations

import json

from drivetwin.evals.case import SCHEMA_PATH, case_json_schema


def render_schema() -> str:
    """The schema file's exact text."""
    return json.dumps(case_json_schema(), indent=2) + "\n"


if __name__ == "__main__":
    SCHEMA_PATH.write_text(render_schema(), encoding="utf-8")
    print(f"wrote {SCHEMA_PATH}")
