"""The driver's loop: every job submitted at once (Ray places them), results streamed back as
they finish, the progress kept, and Ctrl-C turned into a cancel of every job."""

from __future__ import annotations

import math
import sys
import time
from typing import Any

from launcher import records
from launcher.batch.cluster import Cluster
from launcher.batch.job import JobSpec
from launcher.batch.matrix import JobPlan
from launcher.batch.progress import Progress, ProgressState
from launcher.batch.resources import ray_options, unmet
from launcher.batch.results import JobResult, Status
from launcher.batch.spec import Resources
from launcher.batch.store import ResultsStore
from launcher.errors import LaunchError

GRACE = 20.0  # seconds cancelled jobs have to stop before their workers are ended
FEASIBLE_EVERY = 5.0  # seconds between looks at whether the live nodes can still run a job
COUNTS = {Status.PASS: "passed", Status.FAIL: "failed", Status.ERROR: "errors",
          Status.TIMEOUT: "timeouts", Status.CANCELLED: "cancelled"}


@records.dataclass(frozen=True)
class Job:
    """One job as the driver submits it."""

    plan: JobPlan
    spec: JobSpec
    resources: Resources
    retries: int


class BatchRunner:
    def __init__(self, cluster: Cluster, store: ResultsStore, progress: Progress) -> None:
        self.cluster = cluster
        self.store = store
        self.progress = progress
        self.jobs: dict[Any, Job] = {}  # a task's ref → its job
        self.results: dict[str, JobResult] = {}
        self.state = ProgressState(0)
        self.started = time.monotonic()
        self.interrupted: BaseException | None = None

    def run(self, jobs: list[Job]) -> dict[str, JobResult]:
        """Every job's result; Ctrl-C cancels what is left (then `interrupted` is set)."""
        self.state = ProgressState(len(jobs))
        capacity = _capacity(self.cluster, jobs[0].resources)
        for job in jobs:
            self.jobs[self.cluster.submit(job.spec, {**ray_options(job.resources),
                                                     "max_retries": job.retries})] = job
        pending = list(self.jobs)
        looked = time.monotonic()
        try:
            while pending:
                done, pending = self.cluster.wait(pending, 0.5)
                for ref in done:
                    self._collect(ref)
                if self.cluster.setup_error is not None:
                    self.cluster.cancel(pending, force=True)
                    raise LaunchError(self.cluster.setup_error)
                if time.monotonic() - looked > FEASIBLE_EVERY:
                    pending, looked = self._drop_infeasible(pending), time.monotonic()
                self.state.running = min(len(pending), capacity)
                self.state.elapsed = time.monotonic() - self.started
                self.progress.update(self.state)
        except KeyboardInterrupt as exc:
            self.interrupted = exc
            self._cancel(pending)
        self.progress.close()
        return self.results

    def _drop_infeasible(self, pending: list[Any]) -> list[Any]:
        """Jobs no live node can run any more (a node that alone had what they ask for is
        gone) are errors: Ray would keep them waiting for ever."""
        nodes = self.cluster.nodes()
        kept = []
        for ref in pending:
            job = self.jobs[ref]
            why = unmet(job.resources, nodes, self.cluster.where)
            if why is None:
                kept.append(ref)
                continue
            self.cluster.cancel([ref], force=True)
            self._record(job.plan, JobResult(job.plan.id, Status.ERROR,
                                             f"no live node can run it any more: {why}"))
        return kept

    def _collect(self, ref: Any) -> None:
        plan = self.jobs[ref].plan
        result, packed = self.cluster.outcome(ref, plan.id)
        self._record(plan, self.store.add(plan, result, packed))

    def _record(self, plan: JobPlan, result: JobResult) -> None:
        self.results[plan.id] = result
        count = COUNTS[result.status]
        setattr(self.state, count, getattr(self.state, count) + 1)
        self.progress.finished(plan, result)

    def _cancel(self, pending: list[Any]) -> None:
        print(f"\ncancelling: {len(pending)} jobs not finished are stopped (Ctrl-C again to "
              "end them at once)", file=sys.stderr)
        self.cluster.cancel(pending, force=False)
        deadline = time.monotonic() + GRACE
        try:
            while pending and time.monotonic() < deadline:
                done, pending = self.cluster.wait(pending, 0.5)
                for ref in done:
                    self._collect(ref)
        except KeyboardInterrupt:
            pass
        if pending:
            self.cluster.cancel(pending, force=True)
            for ref in pending:
                plan = self.jobs[ref].plan
                self.results[plan.id] = JobResult(plan.id, Status.CANCELLED, "cancelled")


def _capacity(cluster: Cluster, resources: Resources) -> int:
    """How many jobs the live nodes can run at once (for the progress line's estimate)."""
    per = resources.cpus or 1
    return max(1, sum(math.floor(node.cpus / per + 1e-9) for node in cluster.nodes()))
