"""The job host of `launcher batch` alone (no Ray): it runs one job to its result, and
whatever ends it (its time limit, a stop, its lifeline, a SIGKILL of the host) leaves nothing
of the job running."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

from tests.support.batch_files import write_jobs


def spec(folder: Path, file: str, **more) -> str:
    return json.dumps({"batch": "b", "id": "j1", "title": "t", "kind": "test", "file": file,
                       "arguments": {}, "seed": 3, "timeout": 60, "root": str(folder),
                       **more})


@pytest.fixture
def scratch():
    """The task's folder for the host's temporary files (short, as the task's: the job's
    graph has its socket in it)."""
    folder = Path(tempfile.mkdtemp(prefix="lnt", dir="/tmp"))
    yield folder
    shutil.rmtree(folder, ignore_errors=True)


def start_host(ws, text: str, scratch: Path) -> subprocess.Popen:
    """The host, as the task starts it: in a session of its own, with a folder of the task's
    for its temporary files."""
    host = subprocess.Popen([sys.executable, "-m", "launcher.batch.host"], cwd=ws.root,
                            env={**ws.env, "TMPDIR": str(scratch)}, stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            start_new_session=True)
    host.stdin.write(text.encode() + b"\n")
    host.stdin.flush()
    return host


def answer(host: subprocess.Popen, timeout: float = 60) -> dict:
    """The host's answer; its lifeline stays open until it has answered."""
    out = host.stdout.read()
    host.wait(timeout)
    host.stdin.close()
    assert host.returncode == 0, host.stderr.read().decode()
    told = json.loads(out)
    Path(told["archive"]).unlink()
    return told["result"]


@pytest.fixture
def jobs(ws):
    return write_jobs(ws.root / "jobs")


def test_a_passing_test_is_passed_with_its_case(ws, jobs, scratch):
    job = spec(jobs, "chatter_test.py", env={"CHATTER_LISTEN": "0.5"})
    result = answer(start_host(ws, job, scratch))
    assert (result["status"], [c["name"] for c in result["cases"]], result["reason"]) == \
        ("pass", ["test_hears_only_its_own_seed"], "")


def test_a_failing_test_is_failed_with_its_message(ws, jobs, scratch):
    result = answer(start_host(ws, spec(jobs, "failing_test.py", seed=1), scratch))
    assert result["status"] == "fail" and "seed 1 is the bad one" in result["reason"]


def test_a_missing_executable_is_an_error_with_launchers_words(ws, jobs, scratch):
    (jobs / "bad_test.py").write_text("import launch\nimport launch_testing.actions\n"
                                      "def generate_test_description():\n"
                                      "    return launch.LaunchDescription([\n"
                                      "        launch.actions.ExecuteProcess(cmd=['nope-x']),\n"
                                      "        launch_testing.actions.ReadyToTest()])\n")
    result = answer(start_host(ws, spec(jobs, "bad_test.py"), scratch))
    assert result["status"] in ("error", "fail") and result["reason"]


def test_a_job_past_its_time_limit_is_ended_with_everything_it_started(ws, jobs, scratch):
    result = answer(start_host(ws, spec(jobs, "stuck_test.py", timeout=4), scratch))
    assert result["status"] == "timeout"
    assert result["reason"] == "ran past its time limit of 4 s; stopped"


def test_a_stop_line_cancels_the_job(ws, jobs, scratch):
    host = start_host(ws, spec(jobs, "stuck_test.py"), scratch)
    time.sleep(2)
    host.stdin.write(b"stop cancelled\n")
    host.stdin.flush()
    assert answer(host)["status"] == "cancelled"


def test_the_end_of_its_lifeline_stops_the_job_and_leaves_no_folder(ws, jobs, scratch):
    job = f"lost{os.getpid()}"
    host = start_host(ws, spec(jobs, "stuck_test.py", id=job), scratch)
    time.sleep(2)
    host.stdin.close()
    assert host.stdout.read() == b"" and host.wait(30) == 0  # no one to answer
    assert not list(scratch.glob(f"lnb-{job}-*"))


def test_a_sigkill_of_the_host_leaves_nothing_of_the_job(ws, jobs, scratch):
    host = start_host(ws, spec(jobs, "stuck_test.py"), scratch)
    deadline = time.monotonic() + 20
    while len(ws.processes()) < 4 and time.monotonic() < deadline:  # the launch is up
        time.sleep(0.1)
    os.kill(host.pid, signal.SIGKILL)
    host.wait()
    deadline = time.monotonic() + 10
    while ws.processes() and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not ws.processes()


def test_two_jobs_at_once_hear_only_themselves(ws, jobs, scratch):
    hosts = [start_host(ws, spec(jobs, "chatter_test.py", seed=seed, id=f"j{seed}"), scratch)
             for seed in (4, 5)]
    results = [answer(host) for host in hosts]
    assert [r["status"] for r in results] == ["pass", "pass"], results
