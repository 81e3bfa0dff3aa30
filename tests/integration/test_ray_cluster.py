"""The Ray cluster the batch tests run on (tests/support/ray_cluster.py): two nodes on hosts of
their own that both take tasks from a driver on a third, a token that keeps other drivers
out, a lost node noticed within seconds and started again, and nothing left once it is gone."""

from __future__ import annotations

import json
import os
import secrets
import subprocess
import sys
import time

import psutil
import pytest

from tests.support.ray_cluster import DRIVER, RayCluster, ray_cluster

pytestmark = pytest.mark.xdist_group("ray")

# Measured: a lost node marked dead 2.5–2.7 s after its raylet's SIGKILL, and a fresh driver
# that asks takes 1–3 s to connect on this 2-core machine (Ray's own default: 15.6 s)
DEAD_WITHIN = 10.0

WHERE = """
import json, sys, ray
ray.init(address=sys.argv[1], logging_level="ERROR", log_to_driver=False)

@ray.remote(num_cpus=1)
def where():
    return ray.get_runtime_context().get_node_id(), ray.util.get_node_ip_address()

asks = json.loads(sys.argv[2])  # each task's custom resource: which node it must run on
ran = ray.get([where.options(resources={ask: 1}).remote() for ask in asks], timeout=60)
nodes = {node["NodeID"]: node["NodeManagerAddress"] for node in ray.nodes() if node["Alive"]}
print(json.dumps({"ran": ran, "nodes": nodes}))
"""

CONNECT = "import sys, ray; ray.init(address=sys.argv[1]); print('connected', flush=True)"


@pytest.fixture(scope="module")
def cluster():
    with ray_cluster() as made:
        yield made


def run_driver(cluster: RayCluster, code: str, *args: str, env: dict[str, str] | None = None,
               ) -> subprocess.CompletedProcess:
    argv = cluster.driver_argv([sys.executable, "-c", code, cluster.address, *args])
    return subprocess.run(argv, capture_output=True, text=True, timeout=120,
                          stdin=subprocess.DEVNULL, env=env or cluster.driver_env(os.environ))


def test_tasks_from_a_driver_on_a_host_of_its_own_run_on_both_nodes(cluster):
    # (each node offers a custom resource of its own, so each task's node is known)
    nodes = ["head", "w1", "head", "w1"]
    done = run_driver(cluster, WHERE, json.dumps([f"batch_{node}" for node in nodes]))
    assert done.returncode == 0, done.stderr[-3000:]
    seen = json.loads(done.stdout.splitlines()[-1])
    assert [address for _, address in seen["ran"]] == [cluster.node_address(n) for n in nodes]
    assert all(seen["nodes"][node_id] == address for node_id, address in seen["ran"])


@pytest.mark.parametrize("token", ["none", "another"])
def test_a_driver_without_the_clusters_token_is_refused(cluster, tmp_path, token):
    env = {k: v for k, v in cluster.driver_env(os.environ).items()
           if not k.startswith("RAY_AUTH")}
    # (an empty home: no ~/.ray/auth_token of the machine's; one try to connect, not 20)
    env |= {"HOME": str(tmp_path), "RAY_gcs_server_port_wait_time_s": "1"}
    if token == "another":
        env |= {"RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN": secrets.token_hex(32)}
    done = run_driver(cluster, CONNECT, env=env)
    assert done.returncode == 1
    assert "InvalidAuthToken: Authentication token is missing or incorrect" in done.stderr
    assert "connected" not in done.stdout


def test_a_node_whose_raylet_dies_is_marked_dead_within_seconds_and_restarts(cluster):
    started = time.monotonic()
    cluster.kill_raylet("w1")
    seen = cluster.wait_nodes({"w1": False}, timeout=DEAD_WITHIN)
    took = time.monotonic() - started
    assert seen == {cluster.node_address("head"): True, cluster.node_address("w1"): False}
    assert took < DEAD_WITHIN
    cluster.restart("w1")
    assert "raylet" in [p.name() for p in cluster.processes("w1")]


def test_a_killed_node_leaves_nothing_on_its_host_and_restarts(cluster):
    cluster.kill_node("w1")
    assert cluster.processes("w1") == []
    cluster.wait_nodes({"w1": False}, timeout=DEAD_WITHIN)
    cluster.restart("w1")
    assert "raylet" in [p.name() for p in cluster.processes("w1")]


def test_nothing_of_a_cluster_is_left_once_it_exits():
    with ray_cluster() as made:
        driver = subprocess.Popen(made.driver_argv([sys.executable, "-c", CONNECT + "\n"
                                                    "import time; time.sleep(600)",
                                                    made.address]),
                                  stdout=subprocess.PIPE, text=True, stdin=subprocess.DEVNULL,
                                  env=made.driver_env(os.environ))
        assert driver.stdout.readline() == "connected\n"
        ran = [p for host in (*made.nodes, DRIVER) for p in made.processes(host)]
        assert {"gcs_server", "raylet"} <= {p.name() for p in ran}
    assert driver.wait(timeout=5) == -9
    assert made.tagged() == []
    assert [p.pid for p in ran if is_running(p)] == []
    assert not any(os.path.exists(f"/run/netns/{host.namespace}")
                   for host in made.network.hosts.values())
    assert not made.root.exists()


def is_running(proc: psutil.Process) -> bool:
    try:
        return proc.is_running() and proc.status() != psutil.STATUS_ZOMBIE
    except psutil.Error:
        return False
