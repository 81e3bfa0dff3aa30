"""`launcher batch` on Ray started for the batch (no cluster given): real Ray, real launch
tests and a real sim in lockstep; the results, the reports, the faults and the bad inputs."""

from __future__ import annotations

import csv
import importlib.util
import json
import os
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ElementTree

import psutil
import pytest

from tests.support.batch_files import write_jobs, write_lockstep
from tests.support.environment import REPO
from tests.support.processes import launcher_argv

pytestmark = [
    pytest.mark.xdist_group("ray"),  # one Ray at a time on the machine
    pytest.mark.skipif(importlib.util.find_spec("ray") is None,
                       reason="Ray is not installed (pip install 'launcher[cluster]')"),
]

CHATTER = """\
jobs:
  - test: jobs/chatter_test.py
matrix:
  rate: [5, 10]
seeds: 2
timeout: 60
env: {CHATTER_LISTEN: "0.5"}
"""


@pytest.fixture
def batch_ws(ws):
    write_jobs(ws.root / "jobs")
    return ws


def results(ws, name: str) -> list[dict]:
    return json.loads((ws.root / "batch-results" / name / "latest" /
                       "results.json").read_text())["jobs"]


@pytest.fixture(scope="module")
def chatter_run(tmp_path_factory):
    """One batch of four launch tests, its reports asked for at paths of their own."""
    from tests.support.workspace import Workspace

    root = tmp_path_factory.mktemp("chat")
    ws = Workspace(root, os.urandom(8).hex())
    write_jobs(root / "jobs")
    ws.write("chatter.batch.yaml", CHATTER)
    done = ws.run("batch", "chatter.batch.yaml", "-n", "--junit-xml", "out/junit.xml",
                  "--csv", "out/jobs.csv", timeout=180)
    return ws, done


def test_every_job_of_the_matrix_and_seeds_passes(chatter_run):
    ws, done = chatter_run
    assert done.returncode == 0, done.stdout + done.stderr
    assert [j["status"] for j in results(ws, "chatter")] == ["pass"] * 4


def test_the_table_and_the_summary_are_printed(chatter_run):
    _, done = chatter_run
    assert "rate  passed/run" in done.stdout
    assert "4 jobs: 4 passed, 0 failed" in done.stdout


def test_each_jobs_folder_comes_back_with_its_output(chatter_run):
    ws, _ = chatter_run
    for job in results(ws, "chatter"):
        folder = ws.root / "batch-results" / "chatter" / "latest" / job["log"]
        assert (folder / "output.log").is_file()
        assert (folder / "output" / "heard.txt").read_text() == str(job["seed"])


def test_the_junit_xml_has_one_case_per_job(chatter_run):
    ws, _ = chatter_run
    cases = list(ElementTree.parse(ws.root / "out" / "junit.xml").iter("testcase"))
    assert len(cases) == 4 and all(c.find("failure") is None for c in cases)


def test_the_csv_has_every_jobs_arguments_and_seed(chatter_run):
    ws, _ = chatter_run
    with open(ws.root / "out" / "jobs.csv") as f:
        rows = list(csv.DictReader(f))
    assert sorted((r["rate"], r["seed"]) for r in rows) == [("10", "0"), ("10", "1"),
                                                            ("5", "0"), ("5", "1")]


def test_the_picture_of_the_matrix_is_drawn(chatter_run):
    ws, _ = chatter_run
    picture = ws.root / "batch-results" / "chatter" / "latest" / "matrix.png"
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_nothing_of_the_batch_is_left_running(chatter_run):
    ws, _ = chatter_run
    assert not ws.processes()


def test_a_failed_job_fails_the_batch_and_rerun_failed_runs_it_alone(batch_ws):
    batch_ws.write("f.batch.yaml", "jobs:\n  - test: jobs/failing_test.py\nseeds: 3\n")
    first = batch_ws.run("batch", "f.batch.yaml", "-n", timeout=120)
    assert first.returncode == 1 and "seed 1 is the bad one" in first.stderr
    again = batch_ws.run("batch", "f.batch.yaml", "-n", "--rerun-failed", timeout=120)
    assert [(j["seed"], j["status"]) for j in results(batch_ws, "f")] == [(1, "fail")], \
        again.stdout + again.stderr


def test_a_job_past_its_time_limit_is_stopped_with_everything_it_started(batch_ws):
    batch_ws.write("s.batch.yaml", "jobs:\n  - test: jobs/stuck_test.py\ntimeout: 4\n")
    done = batch_ws.run("batch", "s.batch.yaml", "-n", timeout=120)
    assert done.returncode == 1
    assert results(batch_ws, "s")[0]["reason"] == "ran past its time limit of 4 s; stopped"


def test_a_run_in_lockstep_repeats_each_jobs_state(batch_ws):
    write_lockstep(batch_ws.root, REPO)
    batch_ws.own_bus().env["LAUNCHER_PACKAGE_PATH"] = str(REPO / "packages")
    batch_ws.write("l.batch.yaml", """\
        jobs:
          - launch: drive.launch.yaml
            sim_duration: 3
        matrix:
          world_name: [robot.world, empty.sdf]
        lockstep: true
        timeout: 90
        """)
    states = []
    for _ in range(2):
        done = batch_ws.run("batch", "l.batch.yaml", "-n", timeout=240)
        assert done.returncode == 0, done.stdout + done.stderr
        states.append({j["id"]: (j["sim_s"], j["state"]) for j in results(batch_ws, "l")})
    assert states[0] == states[1]
    assert all(sim == 3 for sim, _ in states[0].values())


def test_ctrl_c_cancels_every_job_and_leaves_nothing(batch_ws):
    """Ctrl-C as a terminal sends it: to the whole foreground group (Ray's own processes
    started by the batch are in it)."""
    batch_ws.write("s.batch.yaml", "jobs:\n  - test: jobs/stuck_test.py\nseeds: 3\n")
    with open(batch_ws.root / "stderr.txt", "w") as err:
        batch = subprocess.Popen(launcher_argv() + ["batch", "s.batch.yaml", "-n"],
                                 cwd=batch_ws.root, env=batch_ws.env, stdout=subprocess.DEVNULL,
                                 stderr=err, start_new_session=True)
    deadline = time.monotonic() + 60
    while len([p for p in batch_ws.processes() if "stuck_test" in command(p)]) < 2:
        assert time.monotonic() < deadline, batch_ws.output("stderr.txt")
        time.sleep(0.2)
    os.killpg(batch.pid, signal.SIGINT)
    assert batch.wait(60) == 130
    assert {j["status"] for j in results(batch_ws, "s")} == {"cancelled"}


def test_a_sigkill_of_the_batch_leaves_nothing_running(batch_ws):
    batch_ws.write("s.batch.yaml", "jobs:\n  - test: jobs/stuck_test.py\nseeds: 2\n")
    batch = batch_ws.start("batch", "s.batch.yaml", "-n")
    deadline = time.monotonic() + 60
    while not [p for p in batch_ws.processes() if "stuck_test" in command(p)]:
        assert time.monotonic() < deadline, batch_ws.output("stderr.txt")
        time.sleep(0.2)
    batch.kill()
    batch.wait()
    deadline = time.monotonic() + 15
    while left_in(batch_ws) and time.monotonic() < deadline:
        time.sleep(0.2)
    assert not left_in(batch_ws)


def command(proc: psutil.Process) -> str:
    """Its command line; "" for one that ended (or became a zombie) while it was looked at."""
    try:
        return " ".join(proc.cmdline())
    except (psutil.NoSuchProcess, psutil.ZombieProcess):
        return ""


def left_in(ws) -> list[str]:
    """What of the batch still runs: what carries the test's tag, or runs in its folder
    (Ray's agents: their titles once overwrote the environment the tag is in). A process that
    ended while it was looked at, or whose parent has yet to reap it, runs no more."""
    found = []
    for proc in ws.processes():
        try:
            found.append(" ".join(proc.cmdline()))
        except (psutil.NoSuchProcess, psutil.ZombieProcess):
            continue
    for proc in psutil.process_iter():
        try:
            if proc.cwd().startswith(str(ws.root)) and proc.pid != os.getpid():
                found.append(" ".join(proc.cmdline()) or proc.name())
        except psutil.Error:
            continue
    return found


def test_list_names_the_jobs_without_ray(batch_ws):
    batch_ws.write("c.batch.yaml", CHATTER)
    done = batch_ws.run("batch", "c.batch.yaml", "--list", "--only", "rate=5")
    assert [line.split("  ")[1] for line in done.stdout.splitlines()] == \
        ["chatter_test[rate=5, seed=0]", "chatter_test[rate=5, seed=1]"]


# --- bad inputs: each said at its place, nothing left running -------------------------------
def test_a_matrix_key_that_is_no_launch_argument_is_said_at_its_line(batch_ws):
    batch_ws.write("c.batch.yaml", CHATTER.replace("rate:", "rtae:"))
    done = batch_ws.run("batch", "c.batch.yaml")
    assert done.returncode == 1
    assert done.stderr.strip() == (
        "error: c.batch.yaml:4:3: 'rtae' is not a launch argument of "
        "jobs/chatter_test.py (did you mean 'rate'?); it takes: rate")


def test_an_unknown_job_file_is_said_at_its_line(batch_ws):
    batch_ws.write("c.batch.yaml", CHATTER.replace("chatter_test", "chatter_tset"))
    done = batch_ws.run("batch", "c.batch.yaml")
    assert done.returncode == 1
    assert ":2:11: test: 'jobs/chatter_tset.py' does not exist (did you mean " \
           "'jobs/chatter_test.py'" in done.stderr


def test_an_empty_matrix_is_said_at_its_line(batch_ws):
    batch_ws.write("c.batch.yaml", "jobs:\n  - test: jobs/chatter_test.py\nmatrix: {}\n")
    done = batch_ws.run("batch", "c.batch.yaml")
    assert done.returncode == 1 and ":3:9: matrix: empty" in done.stderr


def test_a_gpu_no_node_has_is_said_at_once(batch_ws):
    batch_ws.write("c.batch.yaml", CHATTER + "resources: {gpus: 1}\n")
    started = time.monotonic()
    done = batch_ws.run("batch", "c.batch.yaml", timeout=60)
    assert done.returncode == 1, done.stderr
    assert ":8:12: resources: each job asks for 1 CPU, 1 GPU; no node of this machine can " \
        "give that (" in done.stderr
    assert time.monotonic() - started < 30  # said at once: not a wait for a node


def test_an_address_where_nothing_answers_is_said_at_once(batch_ws):
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]  # (closed when the batch tries it)
    batch_ws.write("c.batch.yaml", CHATTER)
    done = batch_ws.run("batch", "c.batch.yaml", "--address", f"127.0.0.1:{port}", timeout=30)
    assert done.returncode == 2
    assert f"--address 127.0.0.1:{port}: no Ray cluster answers there (connection refused)" \
        in done.stderr


def test_ray_not_installed_says_which_extra_to_install(batch_ws):
    batch_ws.write("c.batch.yaml", CHATTER)
    code = ("import sys; sys.modules['ray'] = None; sys.argv = ['launcher', 'batch', "
            "'c.batch.yaml']; from launcher.cli.entry import main; sys.exit(main())")
    done = subprocess.run([sys.executable, "-c", code], cwd=batch_ws.root, env=batch_ws.env,
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 1
    assert "launcher batch runs its jobs on Ray, which is not installed for" in done.stderr
    assert "pip install 'launcher[cluster]'" in done.stderr


def test_a_fixed_argument_may_follow_the_options(batch_ws):
    batch_ws.write("c.batch.yaml", CHATTER)
    done = batch_ws.run("batch", "c.batch.yaml", "--list", "rate:=7")
    assert done.returncode == 0, done.stderr
    assert {line.split("  ")[1] for line in done.stdout.splitlines()} == \
        {"chatter_test[seed=0]", "chatter_test[seed=1]"}


def test_a_results_folder_that_cannot_be_made_is_said(batch_ws):
    batch_ws.write("c.batch.yaml", CHATTER)
    (batch_ws.root / "taken").write_text("a file, not a folder\n")
    done = batch_ws.run("batch", "c.batch.yaml", "--results", "taken/runs", timeout=90)
    assert done.returncode == 1
    assert "error: the results cannot be kept in taken/runs" in done.stderr
