"""A robot on several computers: three OpenSSH hosts (robot1, robot2, robot3), each in a
network namespace of its own (tests/support/sshd.py), reached from a launching host as a user
reaches them (their own ssh config, keys and known_hosts). Needs root and OpenSSH's server
(the test set-up installs it); otherwise one row says why it did not run.

- launch → every node's first message heard: 30 talkers, ten on each host, against the same
  30 all on the launching host, in the same run, alternating; a listener on the launching
  host notes when it has heard every one.
- Ctrl-C → nothing the launch started left on any host (each host's own router lingers
  LAUNCHER_ROUTER_LINGER = 0.5 s after its last user, as routers do: reported apart).
- The bus's latency across hosts against on one host: a node here and an echo node on robot2
  (through the launch's gateway and robot2's bridge), 64 B and 1 MB, one-way = half a round
  trip.
"""

from __future__ import annotations

import json
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _harness import launcher_cmd, table

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

HOSTS = ("robot1", "robot2", "robot3")
PER_HOST = 10
RUNS = 3

TALKER = """import sys
import rclpy
from std_msgs.msg import String
rclpy.init()
node = rclpy.create_node("talker_" + sys.argv[1].strip("/"))
pub = node.create_publisher(String, sys.argv[1], 10)
node.create_timer(0.1, lambda: pub.publish(String(data="hi")))
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""
LISTENER = """import sys, time
from launcher.bus.node import Node
from launcher.bus.qos import QoS
node = Node("heard_all")
topics = {f"/t{i}" for i in range(int(sys.argv[1]))}
heard = set()
for topic in topics:
    node.create_subscription("std_msgs/msg/String", topic,
                             lambda m, t=topic: heard.add(t), QoS(depth=10))
print("ready", flush=True)
while heard != topics:
    node.spin_once(0.01)
print("ALL", time.time(), flush=True)
node.destroy_node()
"""
ECHO = """from launcher.bus.node import Node
from launcher.bus.qos import QoS
node = Node("echo")
pub = node.create_publisher("std_msgs/msg/String", "pong", QoS(depth=100))
node.create_subscription("std_msgs/msg/String", "ping", pub.publish_raw, QoS(depth=100),
                         raw=True)
node.spin()
"""
PINGER = """import json, sys, time
from launcher.bus.messages import build
from launcher.bus.node import Node
from launcher.bus.qos import QoS
node = Node("pinger")
size, count = int(sys.argv[1]), int(sys.argv[2])
sent, out = {}, []
def back(m):
    number = int(m.data[:8])
    if number in sent:
        out.append((time.perf_counter() - sent.pop(number)) / 2)
pub = node.create_publisher("std_msgs/msg/String", "ping", QoS(depth=100))
node.create_subscription("std_msgs/msg/String", "pong", back, QoS(depth=100))
deadline = time.monotonic() + 60
warm = build("std_msgs/msg/String", {"data": "%08d" % 10**7})
while not out and time.monotonic() < deadline:  # until the echo answers (links up)
    sent[10**7] = time.perf_counter()
    pub.publish(warm)
    node.spin(0.2)
out.clear()
body = "x" * max(0, size - 8)
for i in range(count):
    sent[i] = time.perf_counter()
    pub.publish(build("std_msgs/msg/String", {"data": "%08d" % i + body}))
    end = time.monotonic() + 2.0
    while i in sent and time.monotonic() < end:
        node.spin_once(0.05)
print("RESULT " + json.dumps(sorted(out)), flush=True)
node.destroy_node()
"""


def main() -> None:
    from tests.support.sshd import SshHosts

    reason = unavailable()
    if reason:
        table("Several hosts over ssh (bench/hosts.py)",
              [("three hosts over ssh", "-", f"not run: {reason}")])
        return
    root = Path(tempfile.mkdtemp(prefix="launcher-bench-hosts-"))
    scripts = write_scripts(root)
    with SshHosts(root / "ssh", HOSTS) as hosts:
        for name in HOSTS:
            hosts.set_environment(name, {"PATH": f"{os.path.dirname(sys.executable)}:"
                                                 "/usr/bin:/bin",
                                         "LAUNCHER_ROUTER_LINGER": "0.5"})
        env = {**os.environ, "LAUNCHER_SSH_COMMAND": hosts.ssh_command,
               "LAUNCHER_RUN_DIR": str(root / "run"), "LAUNCHER_LOG_DIR": str(root / "log")}
        env.pop("LAUNCHER_ROUTER", None)
        heard = {"local": [], "hosts": []}
        stops, stops_all = [], []
        for _ in range(RUNS):
            for where in ("local", "hosts"):
                took, stop = launch_and_hear(hosts, root, scripts, env, where == "hosts")
                heard[where].append(took)
                if stop is not None:
                    stops.append(stop[0])
                    stops_all.append(stop[1])
        latency = {size: {where: ping(hosts, root, scripts, env, where == "hosts", size, count)
                          for where in ("local", "hosts")}
                   for size, count in ((64, 500), (1 << 20, 50))}
    local, far = statistics.median(heard["local"]), statistics.median(heard["hosts"])
    rows = [
        (f"{len(HOSTS) * PER_HOST} talkers on 3 hosts: launch -> every one heard", "",
         f"{far:.2f} s (runs {', '.join(f'{v:.2f}' for v in heard['hosts'])})"),
        (f"the same {len(HOSTS) * PER_HOST} on one host", "",
         f"{local:.2f} s (runs {', '.join(f'{v:.2f}' for v in heard['local'])})"),
        ("3 hosts / one host", "<= 1.5x", f"{far / local:.2f}x"),
        ("Ctrl-C -> nothing the launch started on any host", "<= 1 s",
         f"median {statistics.median(stops):.2f} s (runs {', '.join(f'{v:.2f}' for v in stops)})"),
        ("Ctrl-C -> nothing at all (each host's router lingers 0.5 s)", "report",
         f"median {statistics.median(stops_all):.2f} s"),
    ]
    for size, label in ((64, "64 B"), (1 << 20, "1 MB")):
        one, across = latency[size]["local"], latency[size]["hosts"]
        rows.append((f"latency {label}, one-way: across hosts (p50 / p95)", "report",
                     f"{across[0] * 1e3:.2f} / {across[1] * 1e3:.2f} ms"))
        rows.append((f"latency {label}, one-way: on one host (p50 / p95)", "report",
                     f"{one[0] * 1e3:.2f} / {one[1] * 1e3:.2f} ms "
                     f"(across/one: {across[0] / one[0]:.1f}x)"))
    table("Several hosts over ssh (bench/hosts.py)", rows)
    print("  (across hosts, a message goes node -> robot2's router -> its bridge -> the "
          "launch's gateway -> this host's router -> node: two more router hops than on one "
          "host, over veth pairs on one machine)")


def unavailable() -> str:
    if os.geteuid() != 0:
        return "needs root (network namespaces)"
    missing = [t for t in ("/usr/sbin/sshd", "ssh", "ip", "unshare")
               if not (os.path.exists(t) if t.startswith("/") else _which(t))]
    return f"needs {', '.join(missing)} (apt-get install openssh-server)" if missing else ""


def _which(tool: str) -> bool:
    import shutil

    return shutil.which(tool) is not None


def write_scripts(root: Path) -> dict[str, Path]:
    made = {}
    for name, text in (("talker", TALKER), ("listener", LISTENER), ("echo", ECHO),
                       ("pinger", PINGER)):
        made[name] = root / f"{name}.py"
        made[name].write_text(text)
    return made


def launch_file(root: Path, commands: list[tuple[str, str | None]]) -> Path:
    lines = ["extensions: [launcher]", "launch:"]
    lines += [f"  - machine: {{name: {name}, address: {name}}}" for name in HOSTS]
    for number, (command, machine) in enumerate(commands):
        where = f", machine: {machine}" if machine else ""
        lines.append(f"  - executable: {{cmd: \"{command}\", name: p{number}{where}}}")
    path = root / "bench.launch.yaml"
    path.write_text("\n".join(lines) + "\n")
    return path


def launch_and_hear(hosts, root: Path, scripts: dict[str, Path], env: dict[str, str],
                    spread: bool) -> tuple[float, tuple[float, float] | None]:
    """Seconds from the launch's start to every talker heard; with `spread`, also Ctrl-C ->
    nothing of the launch's left on any host, and nothing at all."""
    count = len(HOSTS) * PER_HOST
    commands = [(f"python3 {scripts['talker']} /t{i}",
                 HOSTS[i % len(HOSTS)] if spread else None) for i in range(count)]
    path = launch_file(root, commands)
    listener = subprocess.Popen(hosts.in_launching([sys.executable, str(scripts["listener"]),
                                                    str(count)]), env=env,
                                stdout=subprocess.PIPE, text=True)
    assert listener.stdout is not None
    listener.stdout.readline()  # ready
    started = time.time()
    launch = subprocess.Popen(hosts.in_launching([*launcher_cmd(), "launch", str(path)]),
                              env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    line = listener.stdout.readline()
    listener.wait(30)
    took = float(line.split()[1]) - started
    stop = None
    if spread:
        launch.send_signal(signal.SIGINT)
        t0 = time.monotonic()
        launched, everything = None, None
        while everything is None and time.monotonic() - t0 < 30:
            left = [p for name in HOSTS for p in hosts.processes_in(name)]
            ours = [p for p in left if not _host_router(p)]
            if launched is None and not ours:
                launched = time.monotonic() - t0
            if not left:
                everything = time.monotonic() - t0
            time.sleep(0.01)
        stop = (launched or float("nan"), everything or float("nan"))
    else:
        launch.send_signal(signal.SIGINT)
    launch.wait(60)
    return took, stop


def _host_router(proc) -> bool:
    """A host's own router (started by its bridge through discovery, lingering as routers
    do), or a connection's sshd process: the host's, not the launch's."""
    try:
        line = " ".join(proc.cmdline())
    except Exception:  # noqa: BLE001 - gone meanwhile
        return True
    return "launcher.bus.router --lock-fd" in line or proc.name().startswith("sshd")


def ping(hosts, root: Path, scripts: dict[str, Path], env: dict[str, str], spread: bool,
         size: int, count: int) -> tuple[float, float]:
    """One-way latency p50 and p95 (seconds) between a node here and an echo node on robot2
    (or here)."""
    path = launch_file(root, [(f"python3 {scripts['echo']}", "robot2" if spread else None)])
    launch = subprocess.Popen(hosts.in_launching([*launcher_cmd(), "launch", str(path)]),
                              env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        done = subprocess.run(hosts.in_launching([sys.executable, str(scripts["pinger"]),
                                                  str(size), str(count)]),
                              env=env, capture_output=True, text=True, timeout=300)
    finally:
        launch.send_signal(signal.SIGINT)
        launch.wait(60)
    line = next(line for line in done.stdout.splitlines() if line.startswith("RESULT "))
    values = json.loads(line[len("RESULT "):])
    return statistics.median(values), values[int(len(values) * 0.95) - 1]


if __name__ == "__main__":
    main()
