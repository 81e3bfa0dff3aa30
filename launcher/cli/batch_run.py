"""The running part of `launcher batch`: Ray started (with the batch's custody, so that even
a SIGKILL of the command leaves nothing) or joined, the jobs run, the reports written."""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import sys
import time
from pathlib import Path
from typing import Any

from launcher.batch.address import probe
from launcher.batch.cluster import Cluster
from launcher.batch.job import JobSpec
from launcher.batch.matrix import JobPlan
from launcher.batch.progress import Progress
from launcher.batch.resources import unmet
from launcher.batch.results import Status
from launcher.batch.runner import BatchRunner
from launcher.batch.spec import BatchFile
from launcher.batch.stopping import sweep
from launcher.batch.store import ResultsStore
from launcher.batch.table import matrix_table, summary_line
from launcher.batch.workspace import Workspace
from launcher.errors import Interrupted, ParseError
from launcher.runtime.custody import Custody


def run_batch(batch: BatchFile, jobs: list[tuple[JobPlan, JobSpec, dict[str, Any]]],
              store: ResultsStore, address: str | None, workspace: Workspace,
              args: argparse.Namespace) -> int:
    custody = None
    if address is not None:
        probe(address)
        cluster = Cluster.join(address, workspace.runtime_env(batch))
    else:
        custody = Custody()
        custody.begin()  # Ray's processes and every job carry the batch's mark
        cluster = Cluster.local(os.cpu_count() or 1)
    started = time.monotonic()
    try:
        _interruptible()  # (Ray sets its own SIGTERM handler in ray.init)
        plans = [plan for plan, _, _ in jobs]
        nodes = cluster.nodes()
        check_resources(batch, plans, nodes, cluster.where)
        folder = store.begin()
        interactive = sys.stderr.isatty() and not args.noninteractive
        runner = BatchRunner(cluster, store, Progress(sys.stderr, interactive))
        results = runner.run(jobs, batch.resources)
        wall = time.monotonic() - started
        summary = summary_line(list(results.values()), wall, len(nodes))
        notes = store.finish(plans, results, summary, wall)
        print(matrix_table(batch, plans, results).rstrip("\n"))
        print(summary)
        for note in notes:
            print(f"note: {note}", file=sys.stderr)
        copy_report(folder / "junit.xml", args.junit_xml)
        copy_report(folder / "results.csv", args.csv)
        failed = any(r.status is not Status.PASS for r in results.values())
        print(f"results: {folder}/" + ("; rerun the failures with --rerun-failed"
                                       if failed else ""))
    finally:
        cluster.close()
        if custody is not None:
            left = sweep(custody.mark) if custody.mark else []
            custody.end(nothing_left=not left)
    if runner.interrupted is not None:
        return 128 + getattr(runner.interrupted, "signum", 2)
    return 1 if failed or len(results) < len(jobs) else 0


def _interruptible() -> None:
    def interrupt(signum: int, _frame: object) -> None:
        raise Interrupted(signum)

    signal.signal(signal.SIGINT, interrupt)
    signal.signal(signal.SIGTERM, interrupt)


def check_resources(batch: BatchFile, plans: list[JobPlan], nodes: list[Any],
                    where: str) -> None:
    """Refuse at once what no node can run (Ray would wait for ever)."""
    for entry in {id(p.entry): p.entry for p in plans}.values():
        resources = entry.resources or batch.resources
        why = unmet(resources, nodes, where)
        if why:
            place = entry.places.get("resources") if entry.resources else \
                batch.places.get("resources")
            raise ParseError(f"resources: {why}", place or entry.where)


def copy_report(made: Path, wanted: str | None) -> None:
    if wanted:
        Path(wanted).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(made, wanted)
