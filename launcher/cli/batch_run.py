"""The running part of `launcher batch`: Ray started (under the batch's custody, so that even
a SIGKILL of the command leaves no process) or joined, the jobs run, the reports written."""

from __future__ import annotations

import argparse
import contextlib
import os
import shutil
import signal
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from launcher.batch.address import probe
from launcher.batch.cluster import Cluster
from launcher.batch.matrix import JobPlan
from launcher.batch.progress import Progress
from launcher.batch.resources import unmet
from launcher.batch.results import JobResult, Status
from launcher.batch.runner import BatchRunner, Job
from launcher.batch.spec import BatchFile
from launcher.batch.stopping import sweep
from launcher.batch.store import ResultsStore
from launcher.batch.table import matrix_table, summary_line
from launcher.batch.workspace import Workspace
from launcher.errors import Interrupted, LaunchError, ParseError
from launcher.runtime.custody import Custody


def run_batch(batch: BatchFile, jobs: list[Job], store: ResultsStore, address: str | None,
              workspace: Workspace, args: argparse.Namespace) -> int:
    with _cluster(address, workspace.runtime_env(batch)) as cluster:
        received = _interruptible()  # (after Ray's start: ray.init sets a SIGTERM handler)
        started = time.monotonic()
        nodes = cluster.nodes()
        check_resources(batch, [job.plan for job in jobs], nodes, cluster.where)
        folder = _begin(store)
        interactive = sys.stderr.isatty() and not args.noninteractive
        runner = BatchRunner(cluster, store, Progress(sys.stderr, interactive))
        results = runner.run(jobs)
        _report(batch, store, [job.plan for job in jobs], results,
                time.monotonic() - started, len(nodes), args)
    if runner.interrupted is not None:  # (Ray's waits raise a KeyboardInterrupt of their own)
        return 128 + (received[0] if received else 2)
    passed = all(r.status is Status.PASS for r in results.values())
    print(f"results: {folder}/" + ("" if passed else "; rerun the failures with "
                                                   "--rerun-failed"))
    return 0 if passed and len(results) == len(jobs) else 1


@contextlib.contextmanager
def _cluster(address: str | None, runtime_env: dict[str, Any] | None) -> Iterator[Cluster]:
    """A cluster joined at `address`, or Ray started here for the batch; closed after, and
    what Ray here leaves running ended."""
    if address is not None:
        probe(address)
        cluster = Cluster.join(address, runtime_env)
        try:
            yield cluster
        finally:
            cluster.close()
        return
    custody = Custody()
    custody.begin()  # Ray's processes and every job carry the batch's mark
    try:
        cluster = Cluster.local(_cores())
        try:
            yield cluster
        finally:
            cluster.close()
    finally:
        left = sweep(custody.mark) if custody.mark else []
        custody.end(nothing_left=not left)


def _cores() -> int:
    """The cores this process may use (its affinity), as Ray counts for a machine."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


def _interruptible() -> list[int]:
    """SIGINT and SIGTERM raise Interrupted; the signals received, in order. (Ray's waits
    turn an interrupt raised inside them into a KeyboardInterrupt of their own, without the
    signal's number: the exit status comes from this list.)"""
    received: list[int] = []

    def interrupt(signum: int, _frame: object) -> None:
        received.append(signum)
        raise Interrupted(signum)

    signal.signal(signal.SIGINT, interrupt)
    signal.signal(signal.SIGTERM, interrupt)
    return received


def _begin(store: ResultsStore) -> Path:
    try:
        return store.begin()
    except OSError as exc:
        raise LaunchError(f"the results cannot be kept in {store.root}: {exc.strerror}") \
            from None


def _report(batch: BatchFile, store: ResultsStore, plans: list[JobPlan],
            results: dict[str, JobResult], wall: float, nodes: int,
            args: argparse.Namespace) -> None:
    summary = summary_line(list(results.values()), wall, nodes)
    notes = store.finish(plans, results, summary, wall)
    print(matrix_table(batch, plans, results).rstrip("\n"))
    print(summary)
    for note in notes:
        print(f"note: {note}", file=sys.stderr)
    assert store.folder is not None
    copy_report(store.folder / "junit.xml", args.junit_xml, "--junit-xml")
    copy_report(store.folder / "results.csv", args.csv, "--csv")


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


def copy_report(made: Path, wanted: str | None, option: str) -> None:
    if not wanted:
        return
    try:
        Path(wanted).parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(made, wanted)
    except OSError as exc:
        raise LaunchError(f"{option} {wanted}: cannot be written: {exc.strerror} (the "
                          f"results are in {made.parent})") from None

