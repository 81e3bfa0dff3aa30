"""A real Ray cluster of several nodes on this one machine, made by a test (root).

Each node is a `ray start --block` in a host of a private network (tests/support/netns.py): a
network namespace with an address of its own, so the nodes reach one another over a bridge
as the machines of a real cluster do; drivers run in a host of their own ("drv"), where no
node is. The nodes and every driver share one token (Ray's token authentication) in a 0600
file, and every process of the cluster carries LAUNCHER_TEST_RAY=<tag> in its environment, so
none is missed on the way out. The head checks the health of the other nodes often enough
that a node that dies is marked dead within seconds instead of Ray's default of about 15 s.

Never `ray stop` here: it ends every Ray of the machine, another test's included.
"""

from __future__ import annotations

import contextlib
import importlib.util
import json
import os
import secrets
import shutil
import subprocess
import sys
import tempfile
import time
import uuid
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import psutil
import pytest

from tests.support.environment import REQUIRE_EXTERNAL
from tests.support.netns import Network, end_all

DRIVER = "drv"  # the host drivers run on
PORT = 6379  # the head's GCS
TAG_VARIABLE = "LAUNCHER_TEST_RAY"
STOP_GRACE = 5.0  # seconds each `ray start` is given after SIGTERM, before the SIGKILLs
# Ray's Unix sockets are <root>/<node>/<session>/sockets/plasma_store, and such a path holds
# at most 107 bytes; a session folder's name is this long at most:
SESSION = "session_2026-01-01_00-00-00_000000_4194304"

# The head's health checks of the nodes: each second, dead after three missed. Measured on
# this machine: a SIGKILLed raylet marked dead by ray.nodes() 2.5–2.7 s after the kill, where
# Ray's defaults (every 3 s, five missed) took 15.6 s.
HEALTH_CHECKS = {"health_check_initial_delay_ms": 1000, "health_check_period_ms": 1000,
                 "health_check_timeout_ms": 1000, "health_check_failure_threshold": 3}


@dataclass(frozen=True)
class NodeSpec:
    name: str
    cpus: int = 1
    resources: Mapping[str, float] = field(default_factory=dict)  # Ray's custom resources


DEFAULT_NODES = (NodeSpec("head", cpus=1, resources={"batch_head": 1000}),
                 NodeSpec("w1", cpus=1, resources={"batch_w1": 1000}))

# A driver that waits until the cluster shows each address wanted alive (true) or dead
# (false), then prints what it saw last as JSON, {address: alive}, on its last line
WATCH = """
import json, sys, time, ray
wanted, timeout = json.loads(sys.argv[1]), float(sys.argv[2])
ray.init(address=sys.argv[3], logging_level="ERROR", log_to_driver=False)
deadline = time.monotonic() + timeout
while True:
    seen = {}
    for node in ray.nodes():
        address = node["NodeManagerAddress"]
        seen[address] = seen.get(address, False) or node["Alive"]
    if all(seen.get(a) is want for a, want in wanted.items()) or time.monotonic() > deadline:
        break
    time.sleep(0.1)
print(json.dumps(seen))
"""


def require() -> None:
    """Skips the test where the cluster cannot be made: without root (network namespaces),
    or without Ray, which the set-up installs for the tests (so that is a failure under
    LAUNCHER_REQUIRE_EXTERNAL=1, as in CI)."""
    if os.geteuid() != 0:
        pytest.skip("a Ray cluster of several nodes needs root (network namespaces)")
    if importlib.util.find_spec("ray") is not None and shutil.which("ip") is not None:
        return
    message = ("a Ray cluster needs Ray and the ip tool, which the set-up installs (sh "
               "hooks/bootstrap.sh test; or pip install 'launcher[cluster]')")
    if os.environ.get(REQUIRE_EXTERNAL) == "1":
        pytest.fail(f"{message}; {REQUIRE_EXTERNAL}=1 makes that a failure")
    pytest.skip(message)


@contextlib.contextmanager
def ray_cluster(nodes: Sequence[NodeSpec] = DEFAULT_NODES) -> Iterator[RayCluster]:
    """A cluster in a short folder of its own under /tmp (removed after), or the test
    skipped where none can be made."""
    require()
    root = Path(tempfile.mkdtemp(prefix="lnr", dir="/tmp"))
    try:
        with RayCluster(root, nodes) as cluster:
            yield cluster
    finally:
        shutil.rmtree(root, ignore_errors=True)


class RayCluster:
    """`nodes` (the first one the head) as a Ray cluster, with a host for drivers; every
    process of it ended on exit, whatever the test did to it."""

    def __init__(self, root: Path, nodes: Sequence[NodeSpec] = DEFAULT_NODES, *,
                 tag: str = "") -> None:
        longest = max(len(str(root / node.name / SESSION / "sockets/plasma_store").encode())
                      for node in nodes)
        if longest > 107:
            raise ValueError(f"{root}: too long for Ray's Unix sockets ({longest} bytes, at "
                             f"most 107): make it with tempfile.mkdtemp(dir='/tmp')")
        self.root = root
        self.nodes = {node.name: node for node in nodes}
        self.head = nodes[0].name
        self.tag = tag or f"ray-{uuid.uuid4().hex[:8]}"
        self.network = Network((*self.nodes, DRIVER))
        self.address = f"{self.node_address(self.head)}:{PORT}"
        self.token_path = root / "token"
        self.python = Path(sys.executable)
        self.starts: dict[str, subprocess.Popen] = {}  # each node's `ray start --block`

    def __enter__(self) -> RayCluster:
        self.network.__enter__()
        try:
            self.root.mkdir(parents=True, exist_ok=True)
            self.write_token()
            for name in self.nodes:
                self.start(name)
            self.wait_ready()
        except BaseException:
            self.__exit__()
            raise
        return self

    def __exit__(self, *exc: object) -> None:
        # A `ray start` asked to stop may take longer than its node is worth (measured: not
        # done within 5 s under load), so the namespaces' removal SIGKILLs what is left; a
        # process that left its namespace is still found by its tag
        for start in self.starts.values():
            with contextlib.suppress(OSError):
                start.terminate()
        deadline = time.monotonic() + STOP_GRACE
        for start in self.starts.values():
            with contextlib.suppress(subprocess.TimeoutExpired):
                start.wait(timeout=max(0.0, deadline - time.monotonic()))
        self.network.remove()
        end_all(self.tagged)
        for start in self.starts.values():
            start.wait()  # (killed by now; reaped, not left a zombie)

    # Where things are
    def node_address(self, node: str) -> str:
        return self.network.hosts[node].address

    def processes(self, node: str) -> list[psutil.Process]:
        """Every process in the node's network namespace (DRIVER too): the node's Ray
        processes and whatever its tasks started."""
        return self.network.processes_in(node)

    def tagged(self) -> list[psutil.Process]:
        """Every live process that carries this cluster's tag, wherever it runs."""
        found = []
        for proc in psutil.process_iter():
            with contextlib.suppress(psutil.Error):
                if proc.environ().get(TAG_VARIABLE) == self.tag and \
                        proc.status() != psutil.STATUS_ZOMBIE:
                    found.append(proc)
        return found

    # Drivers
    def driver_env(self, base: Mapping[str, str]) -> dict[str, str]:
        """`base` with what a driver of this cluster needs (its token, the tag), and without
        RAY_ADDRESS: a driver names the address itself."""
        env = {k: v for k, v in base.items() if k != "RAY_ADDRESS"}
        return env | {"RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN_PATH": str(self.token_path),
                      "RAY_USAGE_STATS_ENABLED": "0", TAG_VARIABLE: self.tag}

    def driver_argv(self, argv: list[str]) -> list[str]:
        """`argv` run on the driver host."""
        return self.host_argv(DRIVER, argv)

    def host_argv(self, host: str, argv: list[str]) -> list[str]:
        return ["ip", "netns", "exec", self.network.hosts[host].namespace, *argv]

    # Nodes
    def write_token(self) -> None:
        fd = os.open(self.token_path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
        with os.fdopen(fd, "w") as token:
            token.write(secrets.token_hex(32))

    def start(self, name: str) -> None:
        with open(self.root / f"{name}.log", "ab") as log:  # (a restart appends)
            self.starts[name] = subprocess.Popen(
                self.host_argv(name, self.ray_start(name)), stdin=subprocess.DEVNULL,
                stdout=log, stderr=subprocess.STDOUT, env=self.driver_env(os.environ),
                start_new_session=True)

    def ray_start(self, name: str) -> list[str]:
        node = self.nodes[name]
        argv = [str(self.python.with_name("ray")), "start", "--block",
                f"--num-cpus={node.cpus}", f"--node-ip-address={self.node_address(name)}",
                f"--temp-dir={self.root / name}", "--object-store-memory=100000000",
                "--disable-usage-stats", f"--resources={json.dumps(dict(node.resources))}"]
        if name == self.head:
            return [*argv, "--head", f"--port={PORT}", "--include-dashboard=false",
                    f"--system-config={json.dumps(HEALTH_CHECKS)}"]
        return [*argv, f"--address={self.address}"]

    # Faults
    def kill_raylet(self, node: str) -> None:
        """SIGKILLs the node's raylet only (its `ray start --block` then ends the rest of the
        node by itself, within about a second)."""
        raylets = [p for p in self.processes(node) if p.name() == "raylet"]
        assert raylets, f"no raylet runs on {node}"
        for raylet in raylets:
            raylet.kill()

    def kill_node(self, node: str) -> None:
        """SIGKILLs every process of the node, as when its machine is switched off."""
        end_all(lambda: self.processes(node))
        if node in self.starts:
            self.starts[node].wait()

    def restart(self, node: str) -> None:
        """Starts a node other than the head again, what is left of it ended first, and
        waits until the cluster sees it alive. (The head's GCS keeps no state: a new head
        would be a new cluster.)"""
        if node == self.head:
            raise ValueError(f"{node} is the head of the cluster; restart another node")
        self.kill_node(node)
        self.start(node)
        self.wait_nodes({node: True})

    # The cluster's own view
    def wait_ready(self, timeout: float = 90) -> None:
        """Waits until the cluster sees every node alive."""
        self.wait_nodes(dict.fromkeys(self.nodes, True), timeout)

    def wait_nodes(self, wanted: Mapping[str, bool], timeout: float = 60) -> dict[str, bool]:
        """Waits until the cluster, asked by a driver, shows each node of `wanted` alive
        (true) or dead (false); returns what it saw, {address: alive}. Raises if it saw
        otherwise, and at once when the `ray start` of a node wanted alive has ended."""
        addresses = {self.node_address(node): want for node, want in wanted.items()}
        argv = [str(self.python), "-c", WATCH, json.dumps(addresses), str(timeout), self.address]
        with subprocess.Popen(self.driver_argv(argv), stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, stdin=subprocess.DEVNULL,
                              env=self.driver_env(os.environ)) as watch:
            ended = self.watch_ended(watch, [n for n, want in wanted.items() if want])
            out, err = watch.communicate()
        seen = json.loads(out.splitlines()[-1]) if watch.returncode == 0 and out else None
        if ended or seen is None or any(seen.get(a) is not want
                                        for a, want in addresses.items()):
            raise AssertionError(f"the cluster at {self.address} did not show "
                                 f"{dict(wanted)} (alive by address: {seen}){ended}; "
                                 f"the driver said: {err[-2000:]}")
        return seen

    def watch_ended(self, watch: subprocess.Popen, alive: list[str]) -> str:
        """Waits for the watching driver; ends it early where a node it waits for has
        ended, and says so with the end of that node's log."""
        while watch.poll() is None:
            for name in alive:
                if self.starts[name].poll() is not None:
                    watch.kill()
                    log = (self.root / f"{name}.log").read_text(errors="replace")
                    return (f"; {name}'s `ray start` ended with exit code "
                            f"{self.starts[name].returncode}: {log[-2000:]}")
            time.sleep(0.1)
        return ""
