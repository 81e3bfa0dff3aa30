"""`launcher batch --address` on a real Ray cluster of two nodes on this machine, each on a host
of its own (tests/support/ray_cluster.py), the batch run from a third: jobs on both nodes, the
workspace uploaded or shared, a node lost mid-batch, Ctrl-C, a run in lockstep that repeats on
either node, two jobs on one node that do not hear each other, and what no node can run."""

from __future__ import annotations

import csv
import json
import signal
import subprocess
import time
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import pytest

from tests.support.batch_files import write_jobs, write_lockstep
from tests.support.environment import REPO
from tests.support.processes import launcher_argv
from tests.support.ray_cluster import ray_cluster

pytestmark = pytest.mark.xdist_group("ray")  # one Ray at a time on the machine


@pytest.fixture(scope="module")
def cluster():
    with ray_cluster() as made:
        yield made


@pytest.fixture
def bws(ws, cluster):
    """The batch's workspace (a folder of its own: it travels to the nodes), and a runner of
    `launcher batch` from the driver's host."""
    folder = write_jobs(ws.root / "bw")
    write_lockstep(folder, REPO)
    return Batch(ws, cluster, folder)


class Batch:
    def __init__(self, ws, cluster, folder: Path) -> None:
        self.ws, self.cluster, self.folder = ws, cluster, folder
        self.env = cluster.driver_env(ws.env)
        self.env["LAUNCHER_PACKAGE_PATH"] = str(REPO / "packages")

    def write(self, text: str, **env: str) -> None:
        """The batch file; its jobs carry the test's tag (the leak check finds them)."""
        env["LAUNCHER_TEST_TAG"] = self.ws.tag
        (self.folder / "b.batch.yaml").write_text(text + f"env: {json.dumps(env)}\n")

    def argv(self, *more: str) -> list[str]:
        return self.cluster.driver_argv(launcher_argv() + [
            "batch", str(self.folder / "b.batch.yaml"), "-n", "--address",
            self.cluster.address, *more])

    def run(self, *more: str, timeout: float = 240) -> subprocess.CompletedProcess:
        return subprocess.run(self.argv(*more), env=self.env, capture_output=True, text=True,
                              timeout=timeout)

    def start(self, *more: str) -> subprocess.Popen:
        return subprocess.Popen(self.argv(*more), env=self.env, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)

    def results(self) -> list[dict]:
        return json.loads((self.folder / "batch-results" / "b" / "latest" /
                           "results.json").read_text())["jobs"]

    def wait_for_jobs(self, batch: subprocess.Popen, *nodes: str) -> None:
        """Until a job runs on each of `nodes` (the batch still running)."""
        deadline = time.monotonic() + 90
        while not all(self.jobs_on(node) for node in nodes):
            assert time.monotonic() < deadline and batch.poll() is None, batch.stderr.read()
            time.sleep(0.2)

    def jobs_on(self, node: str) -> list:
        """The job hosts running on a node."""
        return [p for p in self.cluster.processes(node)
                if "launcher.batch.host" in " ".join(p.cmdline())]


def test_twenty_launch_tests_run_across_both_nodes(bws):
    bws.write("jobs:\n  - test: chatter_test.py\nmatrix:\n  rate: [5, 10]\nseeds: 10\n"
              "timeout: 120\n", CHATTER_LISTEN="0.5")
    done = bws.run()
    assert done.returncode == 0, done.stdout + done.stderr
    with open(bws.folder / "batch-results" / "b" / "latest" / "results.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 20 and {r["status"] for r in rows} == {"pass"}
    assert {r["node"] for r in rows} == {bws.cluster.node_address("head"),
                                         bws.cluster.node_address("w1")}
    junit = bws.folder / "batch-results" / "b" / "latest" / "junit.xml"
    assert len(list(ElementTree.parse(junit).iter("testcase"))) == 20


def test_the_workspace_is_uploaded_to_the_nodes_by_default(bws):
    bws.write("jobs:\n  - test: chatter_test.py\n", CHATTER_LISTEN="0.3")
    done = bws.run()
    assert done.returncode == 0, done.stdout + done.stderr
    job = bws.folder / "batch-results" / "b" / "latest" / bws.results()[0]["log"]
    where = (job / "output" / "where.txt").read_text()
    assert "_ray_pkg_" in where and not where.startswith(str(bws.folder))


def test_a_shared_workspace_is_used_in_place(bws):
    bws.write("jobs:\n  - test: chatter_test.py\nshared_workspace: true\n",
              CHATTER_LISTEN="0.3")
    done = bws.run()
    assert done.returncode == 0, done.stdout + done.stderr
    job = bws.folder / "batch-results" / "b" / "latest" / bws.results()[0]["log"]
    assert (job / "output" / "where.txt").read_text() == str(bws.folder)


def test_a_node_lost_mid_batch_has_its_jobs_run_again_on_the_other(bws):
    bws.write("jobs:\n  - test: chatter_test.py\nseeds: 4\nretries: 1\ntimeout: 120\n",
              CHATTER_LISTEN="8")
    batch = bws.start()
    bws.wait_for_jobs(batch, "w1")
    bws.cluster.kill_raylet("w1")
    try:
        out, err = batch.communicate(timeout=240)
        assert batch.returncode == 0, out + err
        assert {r["status"] for r in bws.results()} == {"pass"}
        deadline = time.monotonic() + 15
        while bws.jobs_on("w1") and time.monotonic() < deadline:
            time.sleep(0.2)
        assert not bws.jobs_on("w1")
    finally:
        bws.cluster.restart("w1")


def test_a_node_lost_with_no_retries_left_is_an_error_with_the_reason(bws):
    bws.write("jobs:\n  - test: chatter_test.py\nseeds: 2\ntimeout: 120\n"
              "resources: {custom: {batch_w1: 1}}\n", CHATTER_LISTEN="8")
    batch = bws.start()
    bws.wait_for_jobs(batch, "w1")
    bws.cluster.kill_raylet("w1")
    try:
        out, err = batch.communicate(timeout=120)
        assert batch.returncode == 1, out + err
        reasons = [(r["status"], r["reason"]) for r in bws.results()]
        # the one running died with its node; the one queued behind it asked for what only
        # that node had
        assert {status for status, _ in reasons} == {"error"}, reasons
        assert any("the node running it died" in why for _, why in reasons), reasons
        assert all("died" in why or "no live node can run it any more" in why
                   for _, why in reasons), reasons
    finally:
        bws.cluster.restart("w1")


def test_ctrl_c_cancels_the_jobs_on_every_node_and_leaves_nothing(bws):
    bws.write("jobs:\n  - test: stuck_test.py\nseeds: 4\n")
    batch = bws.start()
    bws.wait_for_jobs(batch, "head", "w1")
    batch.send_signal(signal.SIGINT)
    batch.communicate(timeout=60)
    assert batch.returncode == 130
    assert {r["status"] for r in bws.results()} == {"cancelled"}
    deadline = time.monotonic() + 20
    while (bws.jobs_on("head") or bws.jobs_on("w1")) and time.monotonic() < deadline:
        time.sleep(0.2)
    assert not bws.jobs_on("head") and not bws.jobs_on("w1")


def test_sigterm_cancels_the_jobs_and_exits_143_though_rays_wait_took_it(bws):
    bws.write("jobs:\n  - test: stuck_test.py\nseeds: 2\n")
    batch = bws.start()
    bws.wait_for_jobs(batch, "head", "w1")
    batch.send_signal(signal.SIGTERM)
    _, err = batch.communicate(timeout=60)
    assert batch.returncode == 143, err
    assert {r["status"] for r in bws.results()} == {"cancelled"}


def test_joining_the_cluster_says_nothing_of_rays_own_signal_handlers(bws):
    bws.write("jobs:\n  - test: chatter_test.py\n", CHATTER_LISTEN="0.3")
    done = bws.run()
    assert done.returncode == 0, done.stdout + done.stderr
    assert "SIGTERM handler" not in done.stderr, done.stderr


def test_a_run_in_lockstep_gives_the_same_state_on_either_node_and_again(bws):
    states = []
    for node in ("head", "w1", "head"):
        bws.write("jobs:\n  - launch: drive.launch.yaml\n    sim_duration: 3\n"
                  "matrix:\n  world_name: [robot.world, empty.sdf]\nlockstep: true\n"
                  f"timeout: 120\nresources: {{custom: {{batch_{node}: 1}}}}\n"
                  f"package_path: [{REPO / 'packages'}]\n")
        done = bws.run()
        assert done.returncode == 0, done.stdout + done.stderr
        states.append({r["id"]: (r["node"], r["state"]) for r in bws.results()})
    nodes = [{node for node, _ in s.values()} for s in states]
    assert nodes == [{bws.cluster.node_address(n)} for n in ("head", "w1", "head")]
    digests = [{i: state for i, (_, state) in s.items()} for s in states]
    assert digests[0] == digests[1] == digests[2]


def test_two_jobs_on_one_node_do_not_hear_each_other(bws):
    bws.write("jobs:\n  - test: chatter_test.py\nseeds: 2\n"
              "resources: {cpus: 0.5, custom: {batch_w1: 1}}\n", CHATTER_LISTEN="3")
    done = bws.run()
    assert done.returncode == 0, done.stdout + done.stderr
    first, second = sorted(bws.results(), key=lambda r: r["started"])
    assert first["node"] == second["node"] == bws.cluster.node_address("w1")
    assert second["started"] < first["started"] + first["wall_s"]  # at the same time


def test_a_resource_no_node_has_is_said_at_once_naming_each_node(bws):
    bws.write("jobs:\n  - test: chatter_test.py\nresources: {gpus: 1}\n")
    started = time.monotonic()
    bws.env["RAY_ADDRESS"] = bws.cluster.address  # (as Ray's users name a cluster too)
    done = subprocess.run(bws.argv()[:-2], env=bws.env, capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 1
    assert f"no node of the cluster at {bws.cluster.address} can give that" in done.stderr
    assert bws.cluster.node_address("w1") in done.stderr
    assert time.monotonic() - started < 30
