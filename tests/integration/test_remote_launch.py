"""A launch with processes on another host, over the link as users meet it, with an `ssh` that
logs into this host itself (tests/support/loopback_ssh.py: no sshd or root needed; the real
servers are in test_remote_hosts.py). The "other host" has a login's fresh environment and a
run folder of its own. Its processes are the launch's as local ones are: their output shown
and logged as `NAME@HOST`, respawn, required, on_exit, --duration, Ctrl-C and the exit status;
nothing is left there after any end, the launcher's SIGKILL included."""

from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import sys
import time

import psutil
import pytest

from tests.support.environment import REPO
from tests.support.packages import make_tree, manifest
from tests.support.processes import launcher_argv

LOOPBACK = REPO / "tests" / "support" / "loopback_ssh.py"
# double-forks into its own session, says its pid, and sleeps
DAEMON = ("import os, time\nif os.fork(): os._exit(0)\nos.setsid()\n"
          "if os.fork(): os._exit(0)\nprint('daemon', os.getpid(), flush=True)\n"
          "time.sleep(120)\n")


@pytest.fixture
def far(ws):
    """The workspace, with `robot2` reachable over the loopback ssh: its login gets the
    launcher's PATH (as its own set-up would), its own run folder and the test's tag."""
    run = ws.root / "robot2-run"
    run.mkdir(mode=0o700)
    ws.env.update({
        "LAUNCHER_SSH_COMMAND": f"{sys.executable} {LOOPBACK}",
        "LOOPBACK_PATH": f"{os.path.dirname(sys.executable)}:/usr/bin:/bin",
        "LOOPBACK_LAUNCHER_RUN_DIR": str(run),
        "LOOPBACK_LAUNCHER_TEST_TAG": ws.tag,
        "LOOPBACK_LAUNCHER_ROUTER_LINGER": "0.5",
    })
    return ws


def with_daemon(ws) -> None:
    script = ws.write("daemon.py", DAEMON)
    write_launch(ws, f"  - executable: {{cmd: 'python3 {script}', name: far, machine: robot2,"
                     " output: screen}\n")


def write_launch(ws, body: str, name: str = "far.launch.yaml"):
    return ws.write(name, "extensions: [launcher]\nlaunch:\n"
                          "  - machine: {name: robot2, address: robot2.example}\n" + body)


def running(pid: int) -> bool:
    try:
        return psutil.Process(pid).status() != psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return False


def test_a_process_on_another_host_is_shown_and_logged_with_its_host(far):
    write_launch(far, "  - executable: {cmd: \"echo hello there\", name: far, machine: robot2,"
                      " output: screen}\n")
    done = far.run("launch", "far.launch.yaml", timeout=60)
    assert done.returncode == 0, done.stderr
    assert "[far-1@robot2] hello there" in done.stdout
    assert "connected to machine 'robot2'" in done.stdout + done.stderr


def test_its_environment_is_the_hosts_own_with_what_the_launch_set(far):
    write_launch(far, "  - set_env: {name: GREETING, value: hi}\n"
                      "  - executable: {cmd: \"sh -c 'echo $GREETING $HOME $PATH_SEEN'\","
                      " name: far, machine: robot2, output: screen}\n")
    far.env["PATH_SEEN"] = "from-the-launching-shell"
    done = far.run("launch", "far.launch.yaml", timeout=60)
    assert done.returncode == 0, done.stderr
    line = next(line for line in done.stdout.splitlines() if line.startswith("[far-1@robot2]"))
    assert "hi" in line  # the launch's own change travels
    assert "from-the-launching-shell" not in line  # this shell's environment does not


def test_ctrl_c_stops_it_there_and_the_launch_ends_with_130(far):
    with_daemon(far)
    proc = far.start("launch", "far.launch.yaml", output="out.txt")
    text = far.wait_for_output("daemon ", 60, "out.txt")
    daemon = int(text.split("daemon ")[1].split()[0])
    proc.send_signal(signal.SIGINT)
    assert proc.wait(30) == 130
    assert not running(daemon)


def test_killing_the_launcher_ends_everything_on_the_other_host_within_2_s(far):
    with_daemon(far)
    proc = far.start("launch", "far.launch.yaml", output="out.txt")
    text = far.wait_for_output("daemon ", 60, "out.txt")
    daemon = int(text.split("daemon ")[1].split()[0])
    proc.kill()
    proc.wait(10)
    deadline = time.monotonic() + 2.0
    while running(daemon) and time.monotonic() < deadline:
        time.sleep(0.02)
    assert not running(daemon)


def test_a_process_there_respawns_as_a_local_one_does(far):
    write_launch(far, "  - executable: {cmd: \"sh -c 'echo run; exit 3'\", name: far,"
                      " machine: robot2, output: screen, respawn: 'true', respawn_delay: 0.2,"
                      " respawn_max_retries: 2}\n")
    done = far.run("launch", "far.launch.yaml", timeout=60)
    assert done.stdout.count("[far-1@robot2] run") == 3
    assert done.returncode == 1  # its last exit was a failure of its own


def test_a_process_there_ending_ends_the_launch_with_on_exit_shutdown(far):
    write_launch(far, "  - executable: {cmd: \"sleep 60\", name: near}\n"
                      "  - executable: {cmd: \"sh -c 'sleep 0.5; exit 0'\", name: far,"
                      " machine: robot2, on_exit: shutdown}\n")
    started = time.monotonic()
    done = far.run("launch", "far.launch.yaml", timeout=60)
    assert done.returncode == 0, done.stderr
    assert time.monotonic() - started < 30


def test_a_node_is_found_in_the_other_hosts_packages(far):
    make_tree(far.root / "robot2-src", {
        "demo/package.xml": manifest("demo"),
        "demo/scripts/talker": "#!/bin/sh\necho \"talker on robot2: $*\"\n",
    }, executable=("demo/scripts/talker",))
    far.env["LOOPBACK_LAUNCHER_PACKAGE_PATH"] = str(far.root / "robot2-src")
    write_launch(far, "  - node: {pkg: demo, exec: talker, name: chatty, machine: robot2,"
                      " output: screen}\n")
    done = far.run("launch", "far.launch.yaml", timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "talker on robot2: --ros-args -r __node:=chatty" in done.stdout


def test_a_package_missing_on_the_other_host_is_said_naming_it(far):
    write_launch(far, "  - node: {pkg: nowhere, exec: talker, machine: robot2}\n")
    done = far.run("launch", "far.launch.yaml", timeout=60)
    assert done.returncode == 1
    text = done.stdout + done.stderr
    assert "nowhere" in text and "robot2" in text


def test_a_host_that_does_not_answer_is_said_at_its_machine(far):
    far.write("far.launch.yaml", "extensions: [launcher]\nlaunch:\n"
                                 "  - machine: {name: robot9, address: robot9.unreachable}\n"
                                 "  - executable: {cmd: \"sleep 5\", name: far, machine: robot9}\n")
    done = far.run("launch", "far.launch.yaml", timeout=60)
    assert done.returncode == 1
    assert "far.launch.yaml:4:5: machine 'robot9' (robot9.unreachable): robot9.unreachable did " \
           "not answer" in done.stdout + done.stderr


def test_a_host_without_launcher_is_said(far):
    far.env["LOOPBACK_PATH"] = "/usr/bin:/bin"
    write_launch(far, "  - executable: {cmd: \"sleep 5\", name: far, machine: robot2}\n")
    done = far.run("launch", "far.launch.yaml", timeout=60)
    assert done.returncode == 1
    assert "far.launch.yaml:4:5: machine 'robot2' (robot2.example): launcher is not installed " \
           "there" in done.stdout + done.stderr


def test_a_missing_env_loader_is_said(far):
    far.write("far.launch.yaml", "extensions: [launcher]\nlaunch:\n"
                                 "  - machine: {name: robot2, address: robot2.example,"
                                 " env-loader: /nowhere/env.sh}\n"
                                 "  - executable: {cmd: \"sleep 5\", name: far, machine: robot2}\n")
    done = far.run("launch", "far.launch.yaml", timeout=60)
    assert done.returncode == 1
    assert "env-loader '/nowhere/env.sh' does not exist there or is not executable" in \
        done.stdout + done.stderr


def test_a_topic_published_there_is_heard_here(far):
    write_launch(far, "  - executable: {cmd: \"launcher topic pub -r 5 /far_chatter "
                      "std_msgs/msg/String '{data: from robot2}'\", name: far,"
                      " machine: robot2}\n")
    proc = far.start("launch", "far.launch.yaml", output="out.txt")
    try:
        heard = far.run("topic", "echo", "/far_chatter", "std_msgs/msg/String", "--once",
                        timeout=90)
        assert "data: from robot2" in heard.stdout, heard.stderr
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130


# --- one graph across the hosts ---------------------------------------------------------------
# (a node that spins until it is stopped, named by its first argument)
NODE = "import sys\nfrom launcher.bus.node import Node\nNode(sys.argv[1]).spin()\n"
BOTH = {"/near_node", "/far_node"}


def near_and_far_nodes(ws) -> None:
    """A launch of a node here and one on robot2."""
    script = ws.write("node.py", NODE)
    write_launch(ws, f"  - executable: {{cmd: '{sys.executable} {script} near_node',"
                     " name: near}\n"
                     f"  - executable: {{cmd: '{sys.executable} {script} far_node',"
                     " name: far, machine: robot2}\n")


def on_robot2(ws) -> dict[str, str]:
    """A second shell's environment on robot2: its run folder, so its own router."""
    return {**ws.env, "LAUNCHER_RUN_DIR": str(ws.root / "robot2-run")}


def listed(ws, env: dict[str, str], wanted: set[str], *options: str) -> list[str]:
    """`node list` as that shell runs it, once every wanted node is in it."""
    deadline = time.monotonic() + 60
    while True:
        done = subprocess.run([*launcher_argv(), "node", "list", *options], env=env,
                              cwd=ws.root, capture_output=True, text=True, timeout=60)
        lines = done.stdout.splitlines()
        if wanted <= {line.split()[0] for line in lines if line.strip()} or \
                time.monotonic() > deadline:
            return lines
        time.sleep(0.2)


def test_a_second_shell_on_the_other_host_sees_the_nodes_of_both_hosts(far):
    near_and_far_nodes(far)
    proc = far.start("launch", "far.launch.yaml", output="out.txt")
    try:
        assert set(listed(far, on_robot2(far), BOTH)) >= BOTH, far.output("out.txt")
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130


def test_node_list_here_says_which_host_each_node_runs_on(far):
    if os.geteuid() != 0 or shutil.which("unshare") is None:
        pytest.skip("robot2 needs a host name of its own: unshare --uts, as root")
    # robot2's login, in a UTS namespace named robot2 (this host keeps its name)
    far.env["LAUNCHER_SSH_COMMAND"] = (f"unshare --uts /bin/sh -c 'hostname robot2 && exec "
                                       f"\"$0\" \"$@\"' {sys.executable} {LOOPBACK}")
    near_and_far_nodes(far)
    proc = far.start("launch", "far.launch.yaml", output="out.txt")
    try:
        lines = listed(far, far.env, BOTH)
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130
    assert f"/near_node  [{socket.gethostname()}]" in lines, lines
    assert "/far_node   [robot2]" in lines, lines


def test_after_the_launch_no_router_or_bridge_is_left_on_either_host(far):
    near_and_far_nodes(far)
    proc = far.start("launch", "far.launch.yaml", output="out.txt")
    try:
        assert set(listed(far, on_robot2(far), BOTH)) >= BOTH, far.output("out.txt")
        bridges = [p for p in far.processes() if "--join" in p.cmdline()]
        assert len(bridges) == 1  # (robot2's, while the launch runs)
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130
    deadline = time.monotonic() + 3.0  # (each host's router lingers 0.5 s after its last user)
    while far.processes() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert [" ".join(p.cmdline()) for p in far.processes()] == []


def test_ctrl_c_while_a_host_is_connected_ends_the_launch_at_once(far):
    """A host that takes the connection and never answers: Ctrl-C does not wait for its
    timeout (a signal another thread of the launcher took runs its handler within 50 ms)."""
    far.write("far.launch.yaml", "extensions: [launcher]\nlaunch:\n"
                                 "  - machine: {name: robot9, address: robot9.silent,"
                                 " timeout: 60}\n"
                                 "  - executable: {cmd: \"sleep 60\", name: near}\n"
                                 "  - executable: {cmd: \"sleep 5\", name: far, machine: robot9}\n")
    proc = far.start("launch", "far.launch.yaml", output="out.txt")
    far.wait_for_output("[near-1]: process started", 60, "out.txt")
    time.sleep(0.5)  # (connecting to robot9 now)
    proc.send_signal(signal.SIGINT)
    started = time.monotonic()
    assert proc.wait(30) == 130
    assert time.monotonic() - started < 5
