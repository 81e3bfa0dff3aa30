"""Nothing escapes a launch: descendants that leave their group or session, daemons, the process
of a `$(command)`, a hook's background job, a signal during start-up; and a fault campaign of
randomized signals, stubborn children, grandchildren, respawn storms and crashes, each run
checked for leftovers by the test's marker."""

from __future__ import annotations

import contextlib
import os
import random
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import psutil
import pytest

from tests.support.packages import make_tree, manifest
from tests.support.processes import launcher_argv, tagged_processes
from tests.support.resisting import DAEMON, STUBBORN, children_launch
from tests.support.workspace import Workspace

PY = sys.executable

# Each of these leaves its process group or session, or double-forks, and sleeps.
GRANDCHILD_SETPGID = ("import os, subprocess, time; subprocess.Popen(['python3', '-c', "
                      "'import os, time; os.setpgid(0, 0); time.sleep(120)']); time.sleep(120)")
ESCAPES = f"""
launch:
  - executable: {{cmd: "sh -c 'setsid sleep 120 & sleep 120'", sigterm_timeout: 1}}
  - executable: {{cmd: "{PY} daemon.py", sigterm_timeout: 1}}
  - executable: {{cmd: "sh -c 'set -m; sleep 120 & sleep 120'", sigterm_timeout: 1}}
  - executable: {{cmd: "{PY} -c \\"{GRANDCHILD_SETPGID}\\"", sigterm_timeout: 1}}
  - executable: {{cmd: "echo started", output: screen}}
"""


def no_leftovers(ws: Workspace, timeout: float = 20.0) -> None:
    """Nothing carrying the test's marker runs (waiting for a watchdog's clean-up)."""
    deadline = time.monotonic() + timeout
    while (left := tagged_processes(ws.tag)) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not left, [p.pid for p in left]


def launcher_text(ws: Workspace) -> str:
    """The launcher's own lines (not its processes' output) and its stderr."""
    own = [line for line in ws.output().splitlines()
           if re.match(r"\[(INFO|WARN|ERROR|DEBUG)\] ", line)]
    return "\n".join(own) + "\n" + ws.output("stderr.txt")


def handles_signals(pid: int, timeout: float = 30.0) -> None:
    """Wait until `pid` catches SIGTERM: the launcher's own handlers are in place (cli/entry.py;
    the interpreter's own first milliseconds are before that, and Python's)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            with open(f"/proc/{pid}/status") as handle:
                status = handle.read()
        except OSError:
            return
        caught = int(re.search(r"SigCgt:\s*([0-9a-f]+)", status).group(1), 16)
        if caught & (1 << (signal.SIGTERM - 1)):
            return
        time.sleep(0.001)
    raise AssertionError("the launcher never caught SIGTERM")


def command(proc: psutil.Process) -> str:
    try:
        return " ".join(proc.cmdline())
    except psutil.Error:  # gone, or a zombie, since it was listed
        return ""


def escapes(ws: Workspace) -> None:
    ws.write("daemon.py", DAEMON)
    ws.write("escape.launch.yaml", ESCAPES)


def wait_for_sleepers(ws: Workspace, count: int) -> None:
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        sleepers = [p for p in tagged_processes(ws.tag) if "120" in command(p)]
        if len(sleepers) >= count:
            return
        time.sleep(0.05)
    raise AssertionError(f"only {len(sleepers)} of {count} sleepers started")


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM, signal.SIGKILL])
def test_descendants_that_leave_their_group_are_stopped(ws, sig):
    escapes(ws)
    proc = ws.start("launch", "escape.launch.yaml")
    ws.wait_for_output("[echo-5] started")
    wait_for_sleepers(ws, 7)  # setsid, sleep, daemon, set -m ×2, setpgid grandchild, its parent
    proc.send_signal(sig)
    assert proc.wait(60) == (-9 if sig == signal.SIGKILL else 128 + sig)
    no_leftovers(ws)
    if sig != signal.SIGKILL:
        assert "left behind still run" in ws.output()  # the sweep said what it stopped
    assert "Traceback" not in launcher_text(ws)


def test_a_launch_that_ends_stops_what_its_processes_left_running(ws):
    ws.write("daemon.py", DAEMON)
    ws.write("gone.launch.yaml", f"""
    launch:
      - executable: {{cmd: "sh -c 'setsid sleep 120 & sleep 2'"}}
      - executable: {{cmd: "sh -c '{PY} daemon.py; sleep 2'"}}
    """)  # (the pauses: the daemons have left the group when it ends, under load too)
    result = ws.run("launch", "gone.launch.yaml")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "2 process(es) that the launch's processes left behind still run" in result.stdout
    no_leftovers(ws, 5)


def test_the_graph_router_is_not_the_launch_s_to_stop(ws):
    """The router that a launch's node started outlives the launch (it stops when idle)."""
    ws.env["LAUNCHER_ROUTER_LINGER"] = "3"
    ws.write("node.launch.yaml", """
    launch:
      - executable:
          cmd: "launcher topic pub --times 1 -w 0 /chatter std_msgs/msg/String 'data: hi'"
    """)
    result = ws.run("launch", "node.launch.yaml")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "left behind" not in result.stdout
    routers = [p for p in tagged_processes(ws.tag) if "launcher.bus.router" in command(p)]
    assert routers, "the router was stopped with the launch"
    no_leftovers(ws, 15)  # and it goes by itself once idle


def test_a_command_substitution_stops_at_once_on_ctrl_c(ws):
    ws.write("cmd.launch.yaml", """
    launch:
      - arg: {name: x, default: "$(command 'sleep 20')"}
      - executable: {cmd: "echo $(var x)", output: screen}
    """)
    proc = ws.start("launch", "cmd.launch.yaml")
    deadline = time.monotonic() + 30
    while not [p for p in tagged_processes(ws.tag) if command(p) == "sleep 20"]:
        assert time.monotonic() < deadline, "the command never started"
        time.sleep(0.02)
    sent = time.monotonic()
    proc.send_signal(signal.SIGINT)
    assert proc.wait(30) == 130
    assert time.monotonic() - sent < 4  # it waited for nothing like the 20 s of the command
    no_leftovers(ws, 5)
    assert "Traceback" not in launcher_text(ws)


def test_a_command_substitution_dies_with_a_killed_launcher(ws):
    ws.write("cmd.launch.yaml", """
    launch:
      - arg: {name: x, default: "$(command 'sleep 20')"}
    """)
    proc = ws.start("launch", "cmd.launch.yaml")
    deadline = time.monotonic() + 30
    while not [p for p in tagged_processes(ws.tag) if command(p) == "sleep 20"]:
        assert time.monotonic() < deadline, "the command never started"
        time.sleep(0.02)
    proc.kill()
    proc.wait(10)
    no_leftovers(ws)


@pytest.fixture
def hooked(ws):
    make_tree(ws.root / "src", {
        "busy/package.xml": manifest("busy"),
        "busy/hooks/busy.sh": "sleep 60 &\nexport BUSY_HOOK=ran\n",
    })
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "src")
    ws.env["LAUNCHER_CACHE_DIR"] = str(ws.root / "cache")
    return ws


def test_a_hook_s_background_job_neither_holds_up_the_launch_nor_stays(hooked):
    hooked.write("hooked.launch.yaml", """
    launch:
      - executable: {cmd: "sh -c 'echo hook=$BUSY_HOOK'", output: screen}
    """)
    started = time.monotonic()
    result = hooked.run("launch", "hooked.launch.yaml", timeout=50)
    assert time.monotonic() - started < 40  # not the hook's 60 s
    assert result.returncode == 0, result.stdout + result.stderr
    assert "hook=ran" in result.stdout
    no_leftovers(hooked, 5)


def test_a_shell_hook_with_a_syntax_error_says_where(hooked):
    (hooked.root / "src/busy/hooks/busy.sh").write_text("export A=1\nif then\n")
    hooked.write("hooked.launch.yaml", "launch: []\n")
    result = hooked.run("launch", "hooked.launch.yaml")
    assert result.returncode == 1
    assert f"{hooked.root}/src/busy/hooks/busy.sh:2: hook failed" in result.stderr
    assert "Traceback" not in result.stderr
    no_leftovers(hooked, 5)


def test_a_shell_hook_that_never_ends_is_stopped_located_and_leaves_nothing(hooked):
    """A hook waiting for something that never comes (here a sleep, and a child it put in the
    background): after LAUNCHER_HOOK_TIMEOUT the launch says which hook and line, exits 1,
    and nothing of the hook is left."""
    (hooked.root / "src/busy/hooks/busy.sh").write_text(
        "export A=1\n(sleep 600) &\nsleep 600\nexport B=2\n")
    hooked.write("hooked.launch.yaml", "launch: []\n")
    hooked.env["LAUNCHER_HOOK_TIMEOUT"] = "1"
    result = hooked.run("launch", "hooked.launch.yaml", timeout=60)
    assert result.returncode == 1, result.stdout + result.stderr
    assert f"{hooked.root}/src/busy/hooks/busy.sh:3: hook did not finish within 1 s and was " \
        "stopped, with all it started" in result.stderr, result.stderr
    assert "Traceback" not in result.stderr
    no_leftovers(hooked, 5)


def stuck(pid: int) -> str:
    """A running launcher's signal masks, and each of its threads' name and kernel wait."""
    words = []
    with contextlib.suppress(OSError):
        status = Path(f"/proc/{pid}/status").read_text()
        words += re.findall(r"^(?:SigPnd|ShdPnd|SigBlk|SigIgn|SigCgt):\s*\S+", status, re.M)
    with contextlib.suppress(OSError):
        for task in sorted(os.listdir(f"/proc/{pid}/task")):
            base = Path(f"/proc/{pid}/task/{task}")
            with contextlib.suppress(OSError):
                words.append(f"thread {task} {(base / 'comm').read_text().strip()} waits in "
                             f"{(base / 'wchan').read_text().strip()} "
                             f"({(base / 'status').read_text().split('SigBlk:')[1].split()[0]}"
                             " blocked)")
    return "\n".join(words)


def test_a_signal_during_start_up_exits_cleanly(ws):
    """Signals in the launcher's first half second (importing, loading, starting the router
    and the processes): the status a shell expects, no traceback, nothing left. (From the
    moment its handlers are in place: the interpreter's own first milliseconds are Python's,
    see cli/entry.py.)"""
    ws.write("start.launch.yaml", """
    launch:
      - executable: {cmd: "sleep 120", sigterm_timeout: 0.5}
      - executable: {cmd: "sh -c 'setsid sleep 120 & sleep 120'", sigterm_timeout: 0.5}
    """)
    rng = random.Random(7)
    for attempt in range(12):
        sig = (signal.SIGINT, signal.SIGTERM)[attempt % 2]
        proc = ws.start("launch", "start.launch.yaml")
        handles_signals(proc.pid)
        time.sleep(rng.uniform(0, 0.5))
        proc.send_signal(sig)
        try:
            code = proc.wait(30)
        except subprocess.TimeoutExpired:  # a lost signal: what the launcher was doing
            state = stuck(proc.pid)
            proc.kill()
            raise AssertionError(f"attempt {attempt}: {sig.name} lost\n{state}\n"
                                 f"{launcher_text(ws)}") from None
        assert code == 128 + sig, (attempt, ws.output("stderr.txt"))
        text = launcher_text(ws)
        assert "Traceback" not in text and "KeyboardInterrupt" not in text, text
        no_leftovers(ws)


# Python's SIGINT handler raising where the interpreter checks whether argv[0] (the `launcher`
# script) is an import path entry, as a Ctrl-C in its first milliseconds does: made to land
# there every time by a path hook that sitecustomize puts first.
CTRL_C_AT_ARGV0 = """
import sys
def hook(path):
    if path == sys.argv[0] and hook.armed:
        hook.armed = False
        raise KeyboardInterrupt
    raise ImportError
hook.armed = True
sys.path_hooks.insert(0, hook)
"""


def test_a_ctrl_c_the_interpreter_swallows_at_start_up_still_ends_the_launch(ws):
    """CPython prints a KeyboardInterrupt raised while it looks at argv[0] and runs the script
    all the same: the launch must not then start and run on as if nothing was pressed."""
    script = launcher_argv()[0]
    if not script.endswith("launcher"):
        pytest.skip("the launcher runs as `python -m launcher` here, not as a script")
    ws.write("hook/sitecustomize.py", CTRL_C_AT_ARGV0)
    ws.write("long.launch.yaml", """
    launch:
      - executable: {cmd: "sleep 120"}
    """)
    result = subprocess.run([script, "launch", "long.launch.yaml"], cwd=ws.root, timeout=30,
                            env={**ws.env, "PYTHONPATH": str(ws.root / "hook")},
                            capture_output=True, text=True)
    assert result.returncode == 130, result.stdout + result.stderr
    assert "process started" not in result.stdout
    no_leftovers(ws)


SWALLOWS_ITS_CTRL_C = """
import os, signal, time
from launch import LaunchDescription
from launch.actions import ExecuteProcess

try:  # a launch file that catches everything, as careless code does
    os.kill(os.getpid(), signal.SIGINT)
    time.sleep(0.5)
except BaseException:
    pass


def generate_launch_description():
    return LaunchDescription([ExecuteProcess(cmd=["sleep", "120"])])
"""


def test_a_ctrl_c_that_start_up_code_swallows_still_ends_the_launch(ws):
    """A signal raised while the launch is read, in code that catches everything and goes on:
    the launch's loop acts on it as it takes the signals over (before anything starts), and
    says where it landed."""
    ws.write("careless.launch.py", SWALLOWS_ITS_CTRL_C)
    result = subprocess.run([*launcher_argv(), "launch", "careless.launch.py"], cwd=ws.root,
                            timeout=60, env=ws.env, capture_output=True, text=True)
    assert result.returncode == 130, result.stdout + result.stderr
    assert re.search(r"\[WARN\] \[launch\]: SIGINT came while the launch was being read, and "
                     r"was lost there \(it landed at \S*careless\.launch\.py:\d+, in code that "
                     r"went on\): acting on it now", result.stdout + result.stderr), result.stdout
    assert "process started" not in result.stdout
    no_leftovers(ws)


MID_SPAWN = """
import os, signal, sys
from launcher.frontend.loader import load_file
from launcher.runtime.output import Printer
from launcher.runtime.service import LaunchService

class SignalledWhilePrinting(Printer):  # the signal lands as the start is said
    signalled = False

    def emit(self, record):
        super().emit(record)
        if "process started" in record.text and not self.signalled:
            self.signalled = True
            os.kill(os.getpid(), signal.SIGINT)

service = LaunchService(printer=SignalledWhilePrinting(color=False), load_description=load_file)
sys.exit(service.run(load_file(sys.argv[1])))
"""


def test_a_signal_while_a_process_is_spawned_stops_it_too(ws):
    """Ctrl-C landing while a process is being spawned (a launch's start, a respawn storm's
    every moment): the launch still knows that process and stops it, instead of letting it
    respawn for ever behind the shutdown's back."""
    ws.write("mid_spawn.py", MID_SPAWN)
    ws.write("storm.launch.yaml", """
    launch:
      - executable: {cmd: "sh -c 'sleep 120 & exit 0'", respawn: true, respawn_delay: 0,
                     sigterm_timeout: 0.3, sigkill_timeout: 0.3}
    """)
    proc = subprocess.Popen([PY, str(ws.root / "mid_spawn.py"), str(ws.root / "storm.launch.yaml")],
                            env=ws.env, cwd=ws.root, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    try:
        out, _ = proc.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        proc.kill()
        raise AssertionError(f"the launch did not end: {proc.communicate()[0][-2000:]}") from None
    assert proc.returncode == 130, out
    assert "respawning" not in out, out
    no_leftovers(ws, 5)


def test_a_signal_during_a_failure_s_shutdown_keeps_its_status(ws):
    ws.write("stubborn.py", """
    import signal, time
    signal.signal(signal.SIGINT, lambda *_: print("got SIGINT", flush=True))  # and goes on
    print("ready", flush=True)
    while True:
        time.sleep(0.05)
    """)
    ws.write("fail.launch.yaml", f"""
    launch:
      - executable: {{cmd: "{PY} stubborn.py", output: screen, sigterm_timeout: 30}}
      - timer:
          period: 1.0
          children: [{{executable: {{cmd: "sh -c 'exit 4'", on_exit: shutdown}}}}]
    """)
    proc = ws.start("launch", "fail.launch.yaml")
    ws.wait_for_output("process exited with code 4")
    ws.wait_for_output("got SIGINT")  # the failure's shutdown has begun
    proc.send_signal(signal.SIGINT)  # hurries the shutdown on, SIGTERM to the stubborn one
    assert proc.wait(20) == 1
    assert "SIGINT during the shutdown: escalating" in ws.output()
    no_leftovers(ws, 5)


# --- the fault campaign ---------------------------------------------------------------------
@pytest.mark.parametrize("part", range(4))
def test_fault_campaign_leaves_nothing_behind(tmp_path_factory, part):
    """120 runs in four parts of 30 (which pytest-xdist's workers take side by side): a
    random launch of 1–20 children of the kinds above, hit by SIGINT, SIGTERM or SIGKILL at a
    random moment of its first 1.5 s (often inside the first 0.4 s, while the children are
    being spawned), or by two signals in a row."""
    rng = random.Random(int(os.environ.get("LAUNCHER_CAMPAIGN_SEED", "15")) * 4 + part)
    faults = {"SIGINT": 0, "SIGTERM": 0, "SIGKILL": 0, "twice": 0}
    tmp_path = tmp_path_factory.mktemp("fc")  # (short: the run folders' sockets must fit)
    for run in range(30 * part, 30 * (part + 1)):
        ws = Workspace(tmp_path / f"run{run}", f"campaign-{os.getpid()}-{run}")
        ws.env["LAUNCHER_ROUTER"] = f"unixsock-stream/{tmp_path}/no-router.sock"  # no nodes
        ws.root.mkdir()
        ws.write("daemon.py", DAEMON)
        ws.write("stubborn.py", STUBBORN)
        ws.write("campaign.launch.yaml", children_launch(rng, most=20, timeout=0.3))
        proc = ws.start("launch", "campaign.launch.yaml")
        fault = rng.choice(list(faults))
        if fault != "SIGKILL":
            handles_signals(proc.pid)
        time.sleep(rng.choice([rng.uniform(0, 0.4), rng.uniform(0, 1.5)]))
        faults[fault] += 1
        if fault == "twice":
            proc.send_signal(signal.SIGINT)
            time.sleep(rng.uniform(0, 0.3))
            proc.send_signal(signal.SIGINT)
        else:
            proc.send_signal(getattr(signal, fault))
        try:
            code = proc.wait(60)
        except subprocess.TimeoutExpired:
            proc.kill()
            raise AssertionError(f"run {run} ({fault}) did not end:\n"
                                 f"{ws.output('campaign.launch.yaml')}\n{ws.output()}") from None
        assert code in (-9, 0, 1, 130, 143), (run, code, fault, launcher_text(ws))
        text = launcher_text(ws)
        assert "Traceback" not in text, (run, text)
        try:
            no_leftovers(ws)
        except AssertionError as exc:
            raise AssertionError(f"run {run} ({fault}) left processes behind: {exc}\n"
                                 f"{ws.output('campaign.launch.yaml')}\n{text}") from None
    assert min(faults.values()) >= 3, faults
