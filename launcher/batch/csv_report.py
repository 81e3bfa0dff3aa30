"""A batch as CSV: a row per job with its arguments, seed, status and figures (for a
spreadsheet or pandas)."""

from __future__ import annotations

import csv
from datetime import UTC, datetime
from pathlib import Path

from launcher.batch.matrix import JobPlan
from launcher.batch.results import JobResult

BEFORE = ("id", "job", "kind", "file")
AFTER = ("seed", "repeat", "status", "reason", "node", "wall_s", "sim_s", "rtf", "state",
         "started", "log")


def columns(plans: list[JobPlan]) -> list[str]:
    """Every launch argument of every job (the matrix's and the fixed ones), in the order
    first seen, between the job and seed."""
    return [*BEFORE, *dict.fromkeys(k for p in plans for k in p.arguments), *AFTER]


def write_csv(path: Path, plans: list[JobPlan], results: dict[str, JobResult]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="", encoding="utf-8") as file:
        writer = csv.DictWriter(file, fieldnames=columns(plans), restval="")
        writer.writeheader()
        for plan in plans:
            writer.writerow(_row(plan, results.get(plan.id)))


def _row(plan: JobPlan, result: JobResult | None) -> dict[str, str]:
    row = {"id": plan.id, "job": plan.label, "kind": plan.entry.kind, "file": plan.entry.file,
           **plan.arguments, "seed": str(plan.seed), "repeat": str(plan.repeat)}
    if result is None:
        return row  # not run: the rest left empty
    started = (datetime.fromtimestamp(result.started, UTC).isoformat(timespec="seconds")
               if result.started else "")
    row.update(status=result.status.value, reason=result.reason, node=result.node,
               wall_s=_number(result.wall_s), sim_s=_number(result.sim_s),
               rtf=_number(result.rtf), state=result.state or "", started=started,
               log=result.log)
    return row


def _number(value: float | None) -> str:
    return "" if value is None else f"{value:.3f}".rstrip("0").rstrip(".")
