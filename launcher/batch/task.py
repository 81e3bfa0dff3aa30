"""The Ray task of one job, run in a Ray worker on some node: it starts the job host in a
session of its own and keeps the host's stdin open as its lifeline (the worker's death closes
it, and the host then stops the job); a cancel is passed on as `stop cancelled`."""

from __future__ import annotations

import contextlib
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from launcher import __version__
from launcher.batch.job import (
    OWNER,
    PROTOCOL,
    SCRATCH_PREFIX,
    SCRATCH_VARIABLE,
    JobSpec,
    sweep_stale,
)

GRACE = 15.0  # seconds a cancelled job has to stop before the task gives up on it
WEDGED = 30.0  # seconds past the job's time limit after which the host itself is ended
REMOVE_WAIT = 3.0  # seconds the job's folder is tried again while its last processes end


def node_address() -> str:
    try:
        import ray.util  # (the worker's own Ray: the node's address as the cluster knows it)

        return str(ray.util.get_node_ip_address())
    except Exception:  # noqa: BLE001 - outside a Ray worker (the tests run the task bare)
        return socket.gethostname()


def run_job(spec_json: str) -> dict[str, Any]:
    """The job's result (as JSON), its packed folder (bytes) and the node it ran on."""
    import json

    told = json.loads(spec_json)  # (read raw: a spec of another shape is said, not raised)
    node = node_address()
    if told.get("protocol") != PROTOCOL or told.get("launcher_version") != __version__:
        return _setup_error(told, node, (
            f"node {node} runs launcher {__version__} (batch protocol {PROTOCOL}), the batch's "
            f"machine {told.get('launcher_version')} (protocol {told.get('protocol')}): "
            "install the same launcher[cluster] on every node"))
    spec = JobSpec.from_json(spec_json)
    if spec.root and not (Path(spec.root) / spec.file).is_file():
        return _setup_error(told, node, (
            f"node {node}: the workspace is not at {spec.root} there (no {spec.file}): share "
            "it at the same path, or let it be uploaded"))
    # everything of the job's on this node; a folder a killed worker left is removed here
    sweep_stale(Path(tempfile.gettempdir()), SCRATCH_PREFIX)
    scratch = tempfile.mkdtemp(prefix=SCRATCH_PREFIX)
    Path(scratch, OWNER).write_text(str(os.getpid()))
    try:
        return _host(spec, spec_json, node, scratch)
    finally:
        _remove(scratch)


def _remove(scratch: str) -> None:
    """The job's folder, gone: looked at again while what the job started (ended by the job
    host's watchdog after a cancel) may still write in it, for up to REMOVE_WAIT seconds."""
    deadline = time.monotonic() + REMOVE_WAIT
    shutil.rmtree(scratch, ignore_errors=True)
    while os.path.exists(scratch) and time.monotonic() < deadline:
        time.sleep(0.1)
        shutil.rmtree(scratch, ignore_errors=True)


def _setup_error(told: dict[str, Any], node: str, reason: str) -> dict[str, Any]:
    """A node that can run no job of the batch: the batch stops."""
    return {"node": node, "archive": b"", "setup": True,
            "result": {"id": told.get("id", "?"), "status": "error", "node": node,
                       "reason": reason}}


def _host(spec: JobSpec, spec_json: str, node: str, scratch: str) -> dict[str, Any]:
    env = dict(os.environ, TMPDIR=scratch, **{SCRATCH_VARIABLE: scratch})
    with tempfile.TemporaryFile(dir=scratch) as errors:
        host = subprocess.Popen([sys.executable, "-m", "launcher.batch.host"],
                                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=errors,
                                env=env, start_new_session=True)
        assert host.stdin is not None and host.stdout is not None
        host.stdin.write(spec_json.encode() + b"\n")
        host.stdin.flush()
        try:
            wedged = _wait(host, spec.timeout + WEDGED)
        except KeyboardInterrupt:  # Ray's cancel: the job is stopped, then the task ends
            host.stdin.write(b"stop cancelled\n")
            host.stdin.flush()
            _wait(host, GRACE)
            raise
        if wedged:
            return {"node": node, "archive": b"", "result": {
                "id": spec.id, "status": "timeout", "node": node,
                "reason": f"the job did not end {WEDGED:g} s past its time limit of "
                          f"{spec.timeout:g} s; ended with everything it started"}}
        line = host.stdout.readline()
        host.stdin.close()
        errors.seek(0)
        return _reply(line, errors.read(), node, spec)


def _wait(host: subprocess.Popen[bytes], limit: float) -> bool:
    """Wait in short steps (a cancel lands between them); past `limit`, end the host's
    session (its watchdog then ends the job): True then."""
    deadline = time.monotonic() + limit
    while host.poll() is None:
        if time.monotonic() > deadline:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(host.pid, signal.SIGKILL)
            host.wait()
            return True
        with contextlib.suppress(subprocess.TimeoutExpired):
            host.wait(0.1)
    return False


def _reply(line: bytes, errors: bytes, node: str, spec: JobSpec) -> dict[str, Any]:
    import json

    try:
        told = json.loads(line)
    except ValueError:
        why = errors.decode("utf-8", "replace").strip().splitlines()[-1:] or ["no word"]
        return {"node": node, "archive": b"", "result": {
            "id": spec.id, "status": "error", "node": node,
            "reason": f"the job host on {node} failed: {why[0]}"}}
    data = Path(told["archive"]).read_bytes()
    return {"node": node, "archive": data, "result": {**told["result"], "node": node}}
