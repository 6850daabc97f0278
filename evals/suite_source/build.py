"""Write the shipped suites, `evals/suites/full.jsonl`, `smoke.jsonl` and `scenarios.jsonl`, from the case modules.

Run `python evals/suite_source/build.py [OUT_DIR]` (default: evals/suites). The JSONL files are
committed; a test checks they match what this script writes.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import addition
import appearance
import arrangement
import moving
import positioning
import removal
import scenarios
import search
from dsl import Json

SUITES = Path(__file__).resolve().parent.parent / "suites"
# One case per task at two grades, chosen to be quick with the rule planner, for CI.
SMOKE_IDS = (
    "search.direct.parking_lot_b",
    "search.erroneous.traffic_lights",
    "addition.direct.car_jtekt",
    "addition.vague.bike_stop",
    "removal.direct.bench",
    "removal.indirect.maintenance_done",
    "positioning.direct.suv_jtekt",
    "positioning.erroneous.car1_lane",
    "moving.direct.ped_jaywalk",
    "moving.indirect.robot_laps",
    "arrangement.indirect.mark_maintenance",
    "arrangement.indirect.around_there",
    "appearance.direct.rain",
    "appearance.erroneous.daytime",
)


def all_cases() -> list[Json]:
    out: list[Json] = []
    for module in (search, addition, removal, positioning, moving, arrangement, appearance):
        out += module.cases()
    return out


def render(cases: list[Json]) -> str:
    return "".join(json.dumps(c, ensure_ascii=False, separators=(", ", ": ")) + "\n" for c in cases)


def main(argv: list[str]) -> int:
    out_dir = Path(argv[0]) if argv else SUITES
    cases = all_cases()
    ids = [c["id"] for c in cases]
    duplicates = sorted({i for i in ids if ids.count(i) > 1})
    if duplicates:
        print(f"duplicate case ids: {', '.join(duplicates)}", file=sys.stderr)
        return 1
    by_id = {c["id"]: c for c in cases}
    missing = [i for i in SMOKE_IDS if i not in by_id]
    if missing:
        print(f"smoke ids not in the suite: {', '.join(missing)}", file=sys.stderr)
        return 1
    (out_dir / "full.jsonl").write_text(render(cases), encoding="utf-8")
    (out_dir / "smoke.jsonl").write_text(render([by_id[i] for i in SMOKE_IDS]), encoding="utf-8")
    (out_dir / "scenarios.jsonl").write_text(render(scenarios.cases()), encoding="utf-8")
    print(f"wrote {len(cases)} cases to full.jsonl and {len(SMOKE_IDS)} to smoke.jsonl")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
