"""The benchmark figures on the performance page: the rows `bench/run_all --record` saved, as
run_all prints them (file, benchmark, target, result), never retyped."""

from __future__ import annotations

import json
from pathlib import Path

from md_tables import code, table

FIGURES = Path(__file__).resolve().parents[2] / "bench" / "figures.json"


def section(path: Path = FIGURES) -> str:
    if not path.is_file():
        return ("\n## Figures\n\nNo recorded run yet: `python bench/run_all --record "
                "bench/figures.json` makes one.\n")
    run = json.loads(path.read_text())
    rows = [(code(source), name, target, result) for source, name, target, result in run["rows"]]
    return (f"\n## Figures\n\nFrom `python bench/run_all --record bench/figures.json` "
            f"on {run['machine']}, {run['date']} (commit `{run['commit']}`), as it printed "
            f"them: medians of several runs, wall time as a user sees it, each ratio against "
            f"its reference measured in the same run.\n\n"
            + table(("file", "benchmark", "target", "result"), rows))
