"""Ray, as the batch uses it: a cluster started here for the batch (embedded) or joined at an
address; its live nodes; one task per job, submitted, streamed back, cancelled."""

from __future__ import annotations

import contextlib
import os
import secrets
import shutil
import tempfile
import threading
from pathlib import Path
from typing import Any

from launcher.batch.job import OWNER, JobSpec, sweep_stale
from launcher.batch.resources import NodeOffer
from launcher.batch.results import JobResult, Status
from launcher.errors import LaunchError

CONNECT_VARIABLE = "LAUNCHER_BATCH_CONNECT_TIMEOUT"  # seconds joining a cluster may take
PRIVATE_PREFIX = "lnray-"  # the folder of a cluster started for a batch (Ray's, the token, jobs')


class Cluster:
    """One Ray session of the driver."""

    def __init__(self, ray: Any, where: str, private: Path | None) -> None:
        self.ray = ray
        self.where = where  # "this machine" or "the cluster at ADDR"
        self.private = private  # the embedded cluster's folder (token, Ray's temp dir)
        from launcher.batch.task import run_job

        self.remote = ray.remote(run_job)
        self.cancelled: set[Any] = set()
        self.setup_error: str | None = None  # a node that cannot run any job: the batch stops

    @classmethod
    def local(cls, cpus: int) -> Cluster:
        """A cluster of this machine for the batch alone: token authentication with a private
        token, no dashboard, no usage reports; gone with the batch."""
        sweep_stale(Path(tempfile.gettempdir()), PRIVATE_PREFIX)
        private = Path(tempfile.mkdtemp(prefix=PRIVATE_PREFIX))  # short: Ray's socket paths
        (private / OWNER).write_text(str(os.getpid()))
        (private / "tmp").mkdir()
        token = private / "token"
        token.write_text(secrets.token_hex(32))
        token.chmod(0o600)
        # (TMPDIR: the jobs' folders go inside, so a batch ended by SIGKILL leaves one folder,
        # which the next batch removes)
        # (SPT_NOENV: Ray's process titles must not overwrite its processes' environment,
        # where the batch's mark is: without it, its agents escaped a SIGKILLed batch's sweep)
        os.environ.update(RAY_AUTH_MODE="token", RAY_AUTH_TOKEN_PATH=str(token),
                          RAY_USAGE_STATS_ENABLED="0", TMPDIR=str(private / "tmp"),
                          SPT_NOENV="1")
        os.environ.pop("RAY_ADDRESS", None)
        import ray

        try:
            ray.init(address="local", num_cpus=cpus, include_dashboard=False,
                     log_to_driver=False, logging_level="warning", namespace="launcher-batch",
                     object_store_memory=256 * 2**20, _temp_dir=str(private / "ray"),
                     _system_config={"task_oom_retries": 0})
        except BaseException:
            shutil.rmtree(private, ignore_errors=True)
            raise
        return cls(ray, "this machine", private)

    @classmethod
    def join(cls, address: str, runtime_env: dict[str, Any] | None) -> Cluster:
        """The running cluster at `address` (ray://… for Ray Client)."""
        import logging

        import ray

        # (joined from a thread, to bound the wait: Ray then says it set no SIGTERM handler,
        # which the batch sets itself; said by its worker module's own logger, whose records
        # reach the "ray" logger's handlers without its filters)
        logging.getLogger("ray._private.worker").addFilter(
            lambda record: "SIGTERM handler is not set" not in record.getMessage())
        limit = float(os.environ.get(CONNECT_VARIABLE, "30"))
        failure: list[BaseException] = []

        def connect() -> None:
            try:
                ray.init(address=address, runtime_env=runtime_env, log_to_driver=False,
                         logging_level="warning", namespace="launcher-batch")
            except BaseException as exc:  # noqa: BLE001 - handed to the waiting thread
                failure.append(exc)

        thread = threading.Thread(target=connect, daemon=True)
        thread.start()
        thread.join(limit)
        if thread.is_alive():
            raise LaunchError(f"--address {address}: it answered but did not act as a Ray "
                              f"cluster within {limit:g} s (the workspace's upload counts: "
                              f"{CONNECT_VARIABLE} sets the limit)")
        if failure:
            raise LaunchError(_worded(address, failure[0])) from None
        return cls(ray, f"the cluster at {address}", None)

    def nodes(self) -> list[NodeOffer]:
        offers = []
        for node in self.ray.nodes():
            if not node.get("Alive"):
                continue
            have = dict(node.get("Resources", {}))
            own = {k: v for k, v in have.items() if k not in ("CPU", "GPU", "memory",
                                                              "object_store_memory")
                   and not k.startswith("node:")}
            offers.append(NodeOffer(node.get("NodeManagerAddress", "?"), have.get("CPU", 0),
                                    have.get("GPU", 0), have.get("memory", 0), own))
        return offers

    def submit(self, spec: JobSpec, options: dict[str, Any]) -> Any:
        return self.remote.options(scheduling_strategy="SPREAD", retry_exceptions=False,
                                   **options).remote(spec.to_json())

    def wait(self, refs: list[Any], timeout: float) -> tuple[list[Any], list[Any]]:
        return self.ray.wait(refs, num_returns=1, timeout=timeout)

    def outcome(self, ref: Any, job_id: str) -> tuple[JobResult, bytes]:
        """A finished task's result, or Ray's failure in words."""
        try:
            told = self.ray.get(ref)
        except self.ray.exceptions.RayError as exc:
            if ref in self.cancelled:
                return JobResult(job_id, Status.CANCELLED, "cancelled"), b""
            return JobResult(job_id, Status.ERROR, _lost(exc)), b""
        if told.get("setup") and self.setup_error is None:
            self.setup_error = told["result"]["reason"]
        return JobResult.from_json(told["result"]), told["archive"]

    def cancel(self, refs: list[Any], force: bool) -> None:
        for ref in refs:
            self.cancelled.add(ref)
            with contextlib.suppress(Exception):  # finished meanwhile: nothing to cancel
                self.ray.cancel(ref, force=force)

    def close(self) -> None:
        self.ray.shutdown()
        if self.private is not None:
            shutil.rmtree(self.private, ignore_errors=True)


def _lost(exc: BaseException) -> str:
    """Ray's failure of a task, in words."""
    name = type(exc).__name__
    text = str(exc).strip().splitlines()
    if "NodeDied" in name or "node" in " ".join(text[:3]).lower() and "died" in str(exc):
        return f"the node running it died ({name})"
    if "WorkerCrashed" in name:
        return "the Ray worker running it died (killed, or out of memory)"
    if "OutOfMemory" in name:
        return "the node ran out of memory and Ray ended the job"
    if "RuntimeEnvSetup" in name:
        return f"Ray could not set up the job's environment: {text[-1] if text else name}"
    return f"{name}: {text[0] if text else ''}"


def _worded(address: str, exc: BaseException) -> str:
    text = str(exc)
    if isinstance(exc, ValueError) and ("working_dir" in text or "package" in text.lower()):
        return (f"the workspace could not be sent to the cluster at {address}: "
                f"{text.splitlines()[0]}; leave large files out (.rayignore, .gitignore or "
                "exclude:), or share it (shared_workspace: true)")
    if "auth" in text.lower() or "token" in text.lower():
        return (f"the Ray cluster at {address} uses token authentication and refused this "
                "machine: set RAY_AUTH_TOKEN or RAY_AUTH_TOKEN_PATH (ray get-auth-token)")
    if "version" in text.lower():
        return f"the Ray cluster at {address}: {text.splitlines()[0]}"
    return f"--address {address}: Ray could not join it: {text.splitlines()[0] if text else exc}"
