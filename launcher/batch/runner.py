"""The driver's loop: every job submitted at once (Ray places them), results streamed back as
they finish, the progress kept, and Ctrl-C turned into a cancel of every job."""

from __future__ import annotations

import math
import sys
import time
from typing import Any

from launcher.batch.cluster import Cluster
from launcher.batch.job import JobSpec
from launcher.batch.matrix import JobPlan
from launcher.batch.progress import Progress, ProgressState
from launcher.batch.results import JobResult, Status
from launcher.batch.spec import Resources
from launcher.batch.store import ResultsStore
from launcher.errors import LaunchError

GRACE = 20.0  # seconds cancelled jobs have to stop before their workers are ended
COUNTS = {Status.PASS: "passed", Status.FAIL: "failed", Status.ERROR: "errors",
          Status.TIMEOUT: "timeouts", Status.CANCELLED: "cancelled"}


class BatchRunner:
    def __init__(self, cluster: Cluster, store: ResultsStore, progress: Progress) -> None:
        self.cluster = cluster
        self.store = store
        self.progress = progress
        self.plans: dict[Any, JobPlan] = {}  # a task's ref → its job
        self.results: dict[str, JobResult] = {}
        self.state = ProgressState(0)
        self.started = time.monotonic()
        self.interrupted: BaseException | None = None

    def run(self, jobs: list[tuple[JobPlan, JobSpec, dict[str, Any]]],
            resources: Resources) -> dict[str, JobResult]:
        """Every job's result; Ctrl-C cancels what is left (then `interrupted` is set)."""
        self.state = ProgressState(len(jobs))
        capacity = _capacity(self.cluster, resources)
        for plan, spec, options in jobs:
            self.plans[self.cluster.submit(spec, options)] = plan
        pending = list(self.plans)
        try:
            while pending:
                done, pending = self.cluster.wait(pending, 0.5)
                for ref in done:
                    self._collect(ref)
                if self.cluster.setup_error is not None:
                    self.cluster.cancel(pending, force=True)
                    raise LaunchError(self.cluster.setup_error)
                self.state.running = min(len(pending), capacity)
                self.state.elapsed = time.monotonic() - self.started
                self.progress.update(self.state)
        except KeyboardInterrupt as exc:
            self.interrupted = exc
            self._cancel(pending)
        self.progress.close()
        return self.results

    def _collect(self, ref: Any) -> None:
        plan = self.plans[ref]
        result, packed = self.cluster.outcome(ref, plan.id)
        result = self.store.add(plan, result, packed)
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
                plan = self.plans[ref]
                self.results[plan.id] = JobResult(plan.id, Status.CANCELLED, "cancelled")


def _capacity(cluster: Cluster, resources: Resources) -> int:
    """How many jobs the live nodes can run at once (for the progress line's estimate)."""
    per = resources.cpus or 1
    return max(1, sum(math.floor(node.cpus / per + 1e-9) for node in cluster.nodes()))
