"""The user's hand on a running launch, through the real command line and the launch's graph:
`launcher ps`, `stop`, `start`, `restart` and `logs` against a real `launcher launch`; what
event handlers see of a user's stop; the bad inputs; the log files' options."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest

from tests.support.processes import launcher_argv
from tests.support.workspace import Workspace

TICKER = """
import os, time
print("hello from", os.getpid(), flush=True)
n = 0
while True:
    n += 1
    print("tick", n, flush=True)
    time.sleep(0.1)
"""
LAUNCH = f"""
launch:
  - executable: {{cmd: "{sys.executable} ticker.py", name: ticker, sigterm_timeout: 1}}
  - executable: {{cmd: "sleep 120", name: sleeper, respawn: true, sigterm_timeout: 1}}
"""


def started(ws: Workspace, name: str = "ctl.launch.yaml", text: str = LAUNCH,
            *options: str) -> subprocess.Popen:
    """A launch of `text`, once `launcher ps` sees it."""
    ws.write("ticker.py", TICKER)
    ws.write(name, text)
    proc = ws.start("launch", "-n", name, *options)
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        if name in ws.run("ps").stdout:
            return proc
        assert proc.poll() is None, ws.output() + ws.output("stderr.txt")
        time.sleep(0.2)
    raise AssertionError("the launch never answered `launcher ps`")


def ended(proc: subprocess.Popen) -> int:
    if proc.poll() is None:
        proc.send_signal(signal.SIGINT)
    return proc.wait(30)


def row(ws: Workspace, name: str) -> list[str]:
    out = ws.run("ps").stdout
    for line in out.splitlines():
        words = line.split()
        if words and words[0] == name:
            return words
    raise AssertionError(f"{name} not in:\n{out}")


def wait_row(ws: Workspace, name: str, state: str, timeout: float = 15) -> list[str]:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        words = row(ws, name)
        if words[3] == state:
            return words
        time.sleep(0.2)
    raise AssertionError(f"{name} never {state}: {row(ws, name)}")


@pytest.fixture()
def running(ws: Workspace):
    proc = started(ws)
    yield ws
    ended(proc)


def test_ps_lists_each_process_with_pid_state_restarts_and_figures(running):
    out = running.run("ps").stdout
    assert "ctl.launch.yaml" in out.splitlines()[0]
    words = wait_row(running, "ticker-1", "running")
    assert int(words[1]) > 0 and words[2] == os.uname().nodename and words[4] == "0"
    deadline = time.monotonic() + 10
    while row(running, "ticker-1")[-1] == "-" and time.monotonic() < deadline:
        time.sleep(0.2)  # (sampled once a second)
    words = row(running, "ticker-1")
    assert float(words[-3]) >= 0 and words[-1] in ("KiB", "MiB")


def test_restart_gives_a_new_process_whose_first_line_comes_again(running):
    first = int(wait_row(running, "ticker-1", "running")[1])
    result = running.run("restart", "ticker")
    assert result.returncode == 0 and "restarting ticker-1" in result.stdout
    deadline = time.monotonic() + 15
    while time.monotonic() < deadline:
        words = row(running, "ticker-1")
        if words[3] == "running" and int(words[1]) != first:
            break
        time.sleep(0.1)
    assert words[4] == "1"
    new = int(words[1])
    deadline = time.monotonic() + 10
    while f"hello from {new}" not in (logs := running.run("logs", "ticker").stdout) and \
            time.monotonic() < deadline:
        time.sleep(0.1)
    assert f"hello from {first}" in logs and f"hello from {new}" in logs


def test_a_stopped_process_stays_stopped_and_starts_again_on_start(running):
    wait_row(running, "sleeper-2", "running")
    assert running.run("stop", "sleeper").returncode == 0
    wait_row(running, "sleeper-2", "stopped")
    time.sleep(1.5)  # (it respawns on an exit of its own: not on the user's stop)
    assert row(running, "sleeper-2")[3] == "stopped"
    result = running.run("start", "sleeper-2")
    assert result.returncode == 0, result.stderr
    assert wait_row(running, "sleeper-2", "running")[4] == "1"


def test_logs_print_the_latest_lines_and_follow(running):
    time.sleep(0.5)
    out = running.run("logs", "ticker").stdout.splitlines()
    assert out[0].startswith("hello from") and out[1] == "tick 1"
    follow = subprocess.Popen(["launcher", "logs", "-f", "ticker-1"], cwd=running.root,
                              env=running.env, stdout=subprocess.PIPE, text=True)
    try:
        seen = [follow.stdout.readline().strip() for _ in range(len(out) + 5)]
    finally:
        follow.send_signal(signal.SIGINT)
        follow.wait(10)
    ticks = [int(line.split()[1]) for line in seen if line.startswith("tick")]
    assert ticks == list(range(1, len(ticks) + 1)) and len(ticks) > len(out)


def test_a_user_s_stop_of_a_required_process_does_not_end_the_launch(ws):
    ws.write("required.launch.py", """
from launch import LaunchDescription
from launch.actions import ExecuteProcess, Shutdown

def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=["sleep", "120"], name="vital", on_exit=[Shutdown()],
                       sigterm_timeout="1"),
        ExecuteProcess(cmd=["sleep", "120"], name="other"),
    ])
""")
    proc = started(ws, "required.launch.py", (ws.root / "required.launch.py").read_text())
    assert ws.run("stop", "vital").returncode == 0
    wait_row(ws, "vital-1", "stopped")
    time.sleep(1.0)
    assert proc.poll() is None, ws.output()
    assert ended(proc) == 130


def test_the_launch_s_cpu_and_memory_figures_go_to_its_log_folder(running):
    time.sleep(2.5)
    folder = next((running.root / "log").glob("*-*"))
    lines = (folder / "processes.csv").read_text().splitlines()
    assert lines[0] == "time,name,pid,cpu_percent,rss_bytes"
    assert {line.split(",")[1] for line in lines[1:]} == {"ticker-1", "sleeper-2"}


# --- bad inputs ---------------------------------------------------------------------------------
def test_ps_with_no_launch_running_says_so(ws):
    result = ws.run("ps")
    assert result.returncode == 1
    assert "no launch is running on this graph" in result.stderr
    assert "Traceback" not in result.stderr


def test_a_name_no_running_launch_has_gets_did_you_mean_across_launches(ws):
    first = started(ws)
    second = started(ws, "other.launch.yaml", """
launch:
  - executable: {cmd: "sleep 120", name: watcher}
""")
    try:
        result = ws.run("restart", "wacher")
        assert result.returncode == 1
        assert "no process 'wacher' in any of the 2 running launches (did you mean " \
               "'watcher'" in result.stderr, result.stderr
        assert ws.run("ps").stdout.count("running") == 3  # nothing changed
    finally:
        ended(second)
        ended(first)


def test_start_of_a_running_process_is_refused(running):
    pid = wait_row(running, "ticker-1", "running")[1]
    result = running.run("start", "ticker")
    assert result.returncode == 1
    assert f"'ticker-1' is already running (pid {pid})" in result.stderr
    assert row(running, "ticker-1")[1] == pid


ANOTHER_USER = """
import sys
from launcher.bus import graph
from launcher.bus.node import Node
node = Node("intruder", argv=[])
server = graph.servers(node.session, "", "launcher_interfaces/srv/ControlProcess")[0]
client = node.create_client("launcher_interfaces/srv/ControlProcess", server.topic)
answer = client.call(node.message("launcher_interfaces/srv/ControlProcess_Request",
                                  name="ticker-1", verb="stop", uid=int(sys.argv[1])))
print(answer.success, answer.message)
node.destroy_node()
"""


def test_a_stop_asked_by_another_user_is_refused(running):
    """(Behind the graph's token: a graph another user shares, a team's router)"""
    pid = wait_row(running, "ticker-1", "running")[1]
    result = subprocess.run([sys.executable, "-c", ANOTHER_USER, str(os.getuid() + 1000)],
                            env=running.env, capture_output=True, text=True, timeout=60)
    assert result.stdout.startswith("False 'ticker-1' is not yours"), result.stdout + \
        result.stderr
    assert row(running, "ticker-1")[1] == pid


def test_a_respawn_delay_that_is_not_a_number_is_said_where(ws):
    ws.write("bad.launch.yaml", """
launch:
  - executable: {cmd: "sleep 1", respawn: true, respawn_delay: soon}
""")
    result = ws.run("launch", "bad.launch.yaml")
    assert result.returncode == 1
    assert "bad.launch.yaml:2:" in result.stderr and "respawn_delay" in result.stderr
    assert "soon" in result.stderr and "Traceback" not in result.stderr


@pytest.mark.parametrize("size", ["0", "0MiB", "-5"])
def test_a_log_size_limit_of_zero_is_refused_before_anything_starts(ws, size):
    ws.write("one.launch.yaml", 'launch:\n  - executable: {cmd: "echo ran", output: screen}\n')
    result = ws.run("launch", "one.launch.yaml", f"--log-max-size={size}")
    assert result.returncode == 2
    assert f"--log-max-size: expected bytes or a size like 2GiB, got '{size}'" in result.stderr
    assert "ran" not in result.stdout


# --- the log files --------------------------------------------------------------------------------
def test_no_log_files_writes_none(ws):
    ws.write("one.launch.yaml", 'launch:\n  - executable: {cmd: "echo ran", output: screen}\n')
    result = ws.run("launch", "--no-log-files", "one.launch.yaml")
    assert result.returncode == 0 and "[echo-1] ran" in result.stdout
    assert not (ws.root / "log").exists()


def test_the_variable_ros_2_users_set_writes_none_too(ws):
    ws.write("one.launch.yaml", 'launch:\n  - executable: {cmd: "echo ran", output: screen}\n')
    ws.env["RCL_LOGGING_DISABLE_FILE_WRITING"] = "1"
    assert ws.run("launch", "one.launch.yaml").returncode == 0
    assert not (ws.root / "log").exists()


def test_log_files_rotate_at_the_size_given(ws):
    ws.write("chatty.launch.yaml", """
launch:
  - executable: {cmd: "seq 1 20000"}
""")
    result = ws.run("launch", "--log-max-size", "64KiB", "chatty.launch.yaml")
    assert result.returncode == 0
    folder = next((ws.root / "log").glob("*-*"))
    logs = sorted(p.name for p in folder.glob("launch.log*"))
    assert logs == ["launch.log", *(f"launch.log.{n}" for n in range(1, 6))]
    assert all((folder / name).stat().st_size <= 64 * 1024 for name in logs)
    last = (folder / "launch.log").read_text().splitlines()
    assert any(line.endswith("[seq-1] 20000") for line in last)


def test_plot_draws_the_figures_of_the_latest_run(ws):
    proc = started(ws)
    time.sleep(2.5)  # (a sample a second)
    ended(proc)
    result = ws.run("plot", "--processes", "-o", "figures.png")
    assert result.returncode == 0, result.stderr
    assert "wrote figures.png (2 processes)" in result.stdout
    assert (ws.root / "figures.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_plot_of_a_run_without_figures_says_so(ws):
    result = ws.run("plot", "--processes", str(ws.root))
    assert result.returncode == 1
    assert f"cannot read {ws.root}/processes.csv" in result.stderr
    assert "Traceback" not in result.stderr


def test_the_run_s_log_reaches_its_file_while_the_launch_runs(ws):
    """(A launcher that is killed leaves its log behind, all but its last half second.)"""
    proc = started(ws)
    try:
        folder = next((ws.root / "log").glob("*-*"))
        deadline = time.monotonic() + 10
        while "[ticker-1] tick 3" not in (folder / "launch.log").read_text():
            assert time.monotonic() < deadline, (folder / "launch.log").read_text()
            time.sleep(0.1)
    finally:
        proc.kill()  # (no orderly end: what is in the file is what was flushed)
        proc.wait(10)
    assert "[ticker-1] hello from" in (folder / "launch.log").read_text()


def test_too_few_file_descriptors_for_the_control_is_said_and_the_launch_runs_on(ws):
    """Zenoh aborts the process when descriptors run out while its session opens (found by the
    fault campaign's full descriptor table): the launch says why it cannot be reached, and
    runs on to its Ctrl-C."""
    ws.write("five.launch.yaml", "launch:\n" + "  - executable: {cmd: sleep 60}\n" * 5)
    proc = subprocess.Popen(["prlimit", "--nofile=40", *launcher_argv(), "launch",
                             "five.launch.yaml"], cwd=ws.root, env=ws.env, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    text = ""
    for line in proc.stdout:
        text += line
        if "cannot reach this launch" in line:
            break
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=30)
    assert proc.returncode == 130, text + out + err
    assert "`launcher ps` and its kin cannot reach this launch: too few file descriptors are " \
           "left to join the graph: " in text
    assert "(ulimit -n), where a session needs up to 32" in text
    assert "panicked" not in err
