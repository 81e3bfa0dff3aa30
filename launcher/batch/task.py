"""The Ray task of one job, run in a Ray worker on some node: it starts the job host in a
session of its own and keeps the host's stdin open as its lifeline (the worker's death closes
it, and the host then stops the job); a cancel is passed on as `stop cancelled`."""

from __future__ import annotations

import contextlib
import os
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from launcher import __version__
from launcher.batch.job import PROTOCOL, JobSpec

GRACE = 15.0  # seconds a cancelled job has to stop before the task gives up on it
WEDGED = 30.0  # seconds past the job's time limit after which the host itself is ended


def node_address() -> str:
    try:
        import ray.util  # (the worker's own Ray: the node's address as the cluster knows it)

        return str(ray.util.get_node_ip_address())
    except Exception:  # noqa: BLE001 - outside a Ray worker (the tests run the task bare)
        return socket.gethostname()


def run_job(spec_json: str) -> dict[str, Any]:
    """The job's result (as JSON), its packed folder (bytes) and the node it ran on."""
    spec = JobSpec.from_json(spec_json)
    node = node_address()
    if spec.protocol != PROTOCOL or spec.launcher_version != __version__:
        return {"node": node, "archive": b"", "setup": True, "result": {
            "id": spec.id, "status": "error", "node": node,
            "reason": f"node {node} runs launcher {__version__} (batch protocol {PROTOCOL}), "
                      f"the batch's machine {spec.launcher_version} (protocol "
                      f"{spec.protocol}): install the same launcher[cluster] on every node"}}
    if spec.root and not (Path(spec.root) / spec.file).is_file():
        return {"node": node, "archive": b"", "setup": True, "result": {
            "id": spec.id, "status": "error", "node": node,
            "reason": f"node {node}: the workspace is not at {spec.root} there (no "
                      f"{spec.file}): share it at the same path, or let it be uploaded"}}
    return _host(spec, spec_json, node)


def _host(spec: JobSpec, spec_json: str, node: str) -> dict[str, Any]:
    with tempfile.TemporaryFile() as errors:
        host = subprocess.Popen([sys.executable, "-m", "launcher.batch.host"],
                                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=errors,
                                start_new_session=True)
        assert host.stdin is not None and host.stdout is not None
        host.stdin.write(spec_json.encode() + b"\n")
        host.stdin.flush()
        try:
            _wait(host, spec.timeout + WEDGED)
        except KeyboardInterrupt:  # Ray's cancel: the job is stopped, then the task ends
            host.stdin.write(b"stop cancelled\n")
            host.stdin.flush()
            _wait(host, GRACE)
            raise
        line = host.stdout.readline()
        host.stdin.close()
        errors.seek(0)
        return _reply(line, errors.read(), node, spec)


def _wait(host: subprocess.Popen[bytes], limit: float) -> None:
    """Wait in short steps (a cancel lands between them); past `limit`, end the host's
    session: its watchdog then ends the job."""
    deadline = time.monotonic() + limit
    while host.poll() is None:
        if time.monotonic() > deadline:
            os.killpg(host.pid, 9)
        with contextlib.suppress(subprocess.TimeoutExpired):
            host.wait(0.1)


def _reply(line: bytes, errors: bytes, node: str, spec: JobSpec) -> dict[str, Any]:
    import json

    try:
        told = json.loads(line)
    except ValueError:
        why = errors.decode("utf-8", "replace").strip().splitlines()[-1:] or ["no word"]
        return {"node": node, "archive": b"", "result": {
            "id": spec.id, "status": "error", "node": node,
            "reason": f"the job host on {node} failed: {why[0]}"}}
    archive = Path(told["archive"])
    data = archive.read_bytes()
    archive.unlink()
    return {"node": node, "archive": data, "result": {**told["result"], "node": node}}
