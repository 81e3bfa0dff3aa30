"""Where a batch's results live: `batch-results/<name>/<time>/` beside the batch file (each
job's folder, results.json, results.csv, junit.xml, matrix.png, summary.txt), and `latest`,
which `--rerun-failed` reads."""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

from launcher import records
from launcher.batch import archive
from launcher.batch.csv_report import write_csv
from launcher.batch.junit_report import write_junit
from launcher.batch.matrix import JobPlan
from launcher.batch.picture import write_matrix_png
from launcher.batch.results import JobResult, Status
from launcher.batch.spec import BatchFile
from launcher.errors import UsageError
from launcher.private import private_folder, write_private

LATEST = "latest"


class ResultsStore:
    def __init__(self, root: Path, batch: BatchFile) -> None:
        self.root = root  # batch-results/<name>
        self.batch = batch
        self.folder: Path | None = None

    def begin(self) -> Path:
        stamp = time.strftime("%Y%m%d-%H%M%S")
        folder = self.root / stamp
        n = 1
        while folder.exists():
            n += 1
            folder = self.root / f"{stamp}-{n}"
        private_folder(folder / "jobs")
        self.folder = folder
        return folder

    def add(self, plan: JobPlan, result: JobResult, packed: bytes) -> JobResult:
        """Unpack the job's folder among the results; the result names it."""
        assert self.folder is not None
        where = Path("jobs") / f"{plan.label}-{plan.id}"
        if packed:
            archive.unpack(packed, self.folder / where)
        return records.replace(result, log=str(where))

    def finish(self, plans: list[JobPlan], results: dict[str, JobResult], summary: str,
               wall_s: float) -> list[str]:
        """Every report; the notes of what could not be written."""
        assert self.folder is not None
        jobs = [{"label": p.label, "title": p.title, "arguments": p.arguments,
                 "seed": p.seed, "repeat": p.repeat, **results[p.id].to_json()}
                for p in plans if p.id in results]
        write_private(self.folder / "results.json", json.dumps(
            {"batch": str(self.batch.path.resolve()), "wall_s": round(wall_s, 3),
             "jobs": jobs}, indent=1))
        write_csv(self.folder / "results.csv", plans, results)
        write_junit(self.folder / "junit.xml", self.batch.title, plans, results,
                    self.folder)
        write_private(self.folder / "summary.txt", summary + "\n")
        notes = []
        why = write_matrix_png(self.folder / "matrix.png", self.batch, plans, results)
        if why:
            notes.append(why)
        link = self.root / LATEST
        temporary = self.root / f".{LATEST}-{os.getpid()}"
        temporary.unlink(missing_ok=True)
        temporary.symlink_to(self.folder.name)
        temporary.replace(link)
        return notes

    def last_failures(self) -> set[str]:
        """The ids of the last run's jobs that did not pass."""
        found = self.root / LATEST / "results.json"
        if not found.is_file():
            raise UsageError(f"--rerun-failed: no earlier run of '{self.batch.title}' in "
                             f"{self.root}")
        try:
            told = json.loads(found.read_text())
            statuses = {job["id"]: job["status"] for job in told["jobs"]}
        except (ValueError, KeyError, TypeError):
            raise UsageError(f"--rerun-failed: {found} is not a run's results (was it "
                             "edited?)") from None
        if told.get("batch") != str(self.batch.path.resolve()):
            raise UsageError(f"--rerun-failed: the last run in {self.root} was of "
                             f"{told.get('batch')}, not of {self.batch.path}")
        return {job for job, status in statuses.items() if status != Status.PASS.value}
