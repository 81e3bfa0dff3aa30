"""Real processes under `launcher launch`: exit status, escalation, respawn, signals, leaks."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time

import psutil
import pytest

from tests.support.processes import is_router, launcher_argv

PY = sys.executable

# A child that reports the signals it gets, and ignores the ones named in argv.
STUBBORN = r'''
import signal, sys, time
ignore = set(sys.argv[1:])
def report(sig, frame):
    print(f"got {signal.Signals(sig).name} at {time.monotonic():.3f}", flush=True)
    if signal.Signals(sig).name not in ignore:
        sys.exit(0)
for name in ("SIGINT", "SIGTERM"):
    signal.signal(getattr(signal, name), report)
print(f"ready at {time.monotonic():.3f}", flush=True)
while True:
    time.sleep(0.05)
'''


def stamps(text: str, event: str) -> list[float]:
    return [float(m) for m in re.findall(rf"{event} at ([0-9.]+)", text)]


def test_clean_run_exits_zero_and_idles_out(ws):
    ws.write("ok.launch.yaml", """
    launch:
      - executable: {cmd: echo hello, output: screen}
      - timer: {period: 0.2, children: [{executable: {cmd: echo later, output: screen}}]}
    """)
    result = ws.run("launch", "ok.launch.yaml")
    assert result.returncode == 0, result.stderr
    assert "[echo-1] hello" in result.stdout and "[echo-2] later" in result.stdout
    assert "Traceback" not in result.stdout + result.stderr


def test_a_failed_process_makes_the_exit_status_one(ws):
    ws.write("fail.launch.yaml", """
    launch:
      - executable: {cmd: sh -c 'exit 3', output: screen}
      - executable: {cmd: "true"}
    """)
    result = ws.run("launch", "fail.launch.yaml")
    assert result.returncode == 1
    assert "[ERROR] [sh-1]: process exited with code 3" in result.stdout


def test_escalation_sigint_then_sigterm_then_sigkill(ws):
    ws.write("stubborn.py", STUBBORN)
    ws.write("esc.launch.yaml", f"""
    launch:
      - executable:
          cmd: {PY} stubborn.py SIGINT
          name: ignores_int
          output: screen
          sigterm_timeout: 0.6
      - executable:
          cmd: {PY} stubborn.py SIGINT SIGTERM
          name: ignores_both
          output: screen
          sigterm_timeout: 0.6
          sigkill_timeout: 0.6
    """)
    proc = ws.start("launch", "esc.launch.yaml")
    ws.wait_for_output("[ignores_int-1] ready")
    ws.wait_for_output("[ignores_both-2] ready")
    sent = time.monotonic()
    proc.send_signal(signal.SIGINT)
    assert proc.wait(30) == 130
    text = ws.output()
    # time.monotonic() is one clock for every process on Linux: compare with when we sent
    # SIGINT (the children receive it a little later, so their own SIGINT stamps are late).
    (int_a,) = re.findall(r"\[ignores_int-1\] got SIGINT at ([0-9.]+)", text)
    (term_a,) = re.findall(r"\[ignores_int-1\] got SIGTERM at ([0-9.]+)", text)
    assert float(int_a) < float(term_a)
    assert float(term_a) >= sent + 0.6 - 0.001  # only after sigterm_timeout (3-digit stamps)
    (term_b,) = re.findall(r"\[ignores_both-2\] got SIGTERM at ([0-9.]+)", text)
    assert float(term_b) >= sent + 0.6
    assert "[WARN] [ignores_both-2]: still running; sending SIGKILL" in text
    assert "process stopped: it was killed by SIGKILL" in text


def test_second_ctrl_c_escalates_at_once(ws):
    ws.write("stubborn.py", STUBBORN)
    ws.write("esc.launch.yaml", f"""
    launch:
      - executable:
          cmd: {PY} stubborn.py SIGINT SIGTERM
          output: screen
          sigterm_timeout: 60
          sigkill_timeout: 60
    """)
    proc = ws.start("launch", "esc.launch.yaml")
    ws.wait_for_output("ready")
    proc.send_signal(signal.SIGINT)
    ws.wait_for_output("got SIGINT")
    proc.send_signal(signal.SIGINT)
    ws.wait_for_output("got SIGTERM")
    proc.send_signal(signal.SIGINT)
    assert proc.wait(30) == 130  # long before the 60 s timeouts
    assert "SIGINT again: escalating" in ws.output()


def test_respawn_counts_and_delay(ws):
    ws.write("respawn.launch.yaml", """
    launch:
      - executable:
          cmd: sh -c 'echo run; exit 2'
          output: screen
          respawn: true
          respawn_delay: 0.1
          respawn_max_retries: 2
    """)
    result = ws.run("launch", "respawn.launch.yaml")
    assert result.stdout.count("[sh-1] run") == 3
    assert "respawning in 0.1 s (attempt 1 of 2)" in result.stdout
    assert "respawning in 0.1 s (attempt 2 of 2)" in result.stdout
    assert result.returncode == 1


def test_on_exit_shutdown_ends_the_launch(ws):
    ws.write("onexit.launch.yaml", """
    launch:
      - executable: {cmd: sleep 60}
      - executable: {cmd: sleep 0.2, on_exit: shutdown}
    """)
    start = time.monotonic()
    result = ws.run("launch", "onexit.launch.yaml")
    assert result.returncode == 0, result.stdout
    assert time.monotonic() - start < 30
    assert "[sleep-1]: process stopped: it was killed by SIGINT" in result.stdout


def test_event_handler_children_run_on_start_and_exit(ws):
    ws.write("events.launch.xml", """
    <launch>
      <executable cmd="sleep 0.1">
        <on_start><log message="started!"/></on_start>
        <on_exit><executable cmd="echo after" output="screen"/></on_exit>
      </executable>
    </launch>
    """)
    result = ws.run("launch", "events.launch.xml")
    assert result.returncode == 0
    assert result.stdout.index("started!") < result.stdout.index("[echo-2] after")


def start_sleepers(ws):
    """A launch with a sleep and a shell that leaves two sleeps in its group: all running."""
    ws.write("many.launch.yaml", """
    launch:
      - executable: {cmd: sleep 60}
      - executable: {cmd: "sleep 61 & sleep 62 & wait", shell: true}
    """)
    proc = ws.start("launch", "many.launch.yaml")
    deadline = time.monotonic() + 20
    while sum(p.name() == "sleep" for p in ws.processes()) < 3:
        assert time.monotonic() < deadline
        time.sleep(0.05)
    return proc


def test_sigterm_to_the_launcher_stops_everything(ws):
    proc = start_sleepers(ws)
    proc.send_signal(signal.SIGTERM)
    assert proc.wait(30) == 143
    assert not [p for p in ws.processes() if not is_router(p)]  # (the graph's: it lingers)


def test_sigkill_to_the_launcher_leaves_nothing_behind(ws):
    proc = start_sleepers(ws)
    proc.kill()
    proc.wait(10)
    deadline = time.monotonic() + 10
    while ws.processes() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not ws.processes()


def started_by_a_script(ws, name: str) -> subprocess.Popen:
    """`launcher launch NAME` with the stop signals ignored, as a shell script's background
    job (`&`: SIGINT and SIGQUIT) under nohup (SIGHUP) gets it; SIGTERM too, for good measure."""
    def ignore_stop_signals() -> None:
        for sig in (signal.SIGINT, signal.SIGQUIT, signal.SIGHUP, signal.SIGTERM):
            signal.signal(sig, signal.SIG_IGN)

    return subprocess.Popen(launcher_argv() + ["launch", name], cwd=ws.root, env=ws.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            preexec_fn=ignore_stop_signals)


def test_children_start_with_the_stop_signals_at_their_defaults(ws):
    """Whatever the launcher inherited, as systemd starts a service: an ignored signal would
    stay ignored across exec, and the launch's SIGINT would not stop its processes."""
    ws.write("dispositions.launch.yaml", """
    launch:
      - executable: {cmd: grep SigIgn /proc/self/status, output: screen}
    """)
    proc = started_by_a_script(ws, "dispositions.launch.yaml")
    out, _ = proc.communicate(timeout=60)
    assert proc.returncode == 0, out
    (mask,) = re.findall(r"SigIgn:\s+([0-9a-f]+)", out)
    ignored = {sig for sig in signal.Signals if int(mask, 16) >> (sig - 1) & 1}
    assert not ignored & {signal.SIGINT, signal.SIGQUIT, signal.SIGHUP, signal.SIGTERM}, ignored


def test_a_launch_started_by_a_script_stops_its_nodes_with_sigint_alone(ws):
    """A Python program that leaves SIGINT to Python (KeyboardInterrupt) ends on the launch's
    first SIGINT, though the launcher was started with SIGINT ignored: no SIGTERM needed."""
    ws.write("python.launch.yaml", f"""
    launch:
      - executable:
          cmd: {PY} -c "import time; print('ready', flush=True); time.sleep(60)"
          output: screen
          sigterm_timeout: "20"
    """)
    proc = started_by_a_script(ws, "python.launch.yaml")
    for line in proc.stdout:
        if "ready" in line:
            break
    os.kill(proc.pid, signal.SIGINT)  # the launcher catches it all the same (its own handler)
    out, _ = proc.communicate(timeout=15)
    assert proc.returncode == 130, out
    assert "SIGTERM" not in out and "SIGKILL" not in out, out
    assert "KeyboardInterrupt" in out, out


def test_children_get_unbuffered_python_and_a_tty_when_asked(ws):
    ws.write("env.launch.yaml", f"""
    launch:
      - executable:
          cmd: {PY} -c "import os, sys; print(os.environ.get('PYTHONUNBUFFERED'), sys.stdout.isatty())"
          output: screen
      - executable:
          cmd: {PY} -c "import sys; print('tty', sys.stdout.isatty())"
          output: screen
          emulate_tty: true
    """)
    result = ws.run("launch", "env.launch.yaml")
    assert "1 False" in result.stdout and "tty True" in result.stdout


def test_logs_folder_latest_link_and_own_log(ws):
    ws.write("logs.launch.yaml", """
    launch:
      - executable: {cmd: "echo to-own-log", output: own_log, name: quiet}
      - executable: {cmd: "echo to-launch-log", output: log}
    """)
    result = ws.run("launch", "logs.launch.yaml")
    assert result.returncode == 0
    latest = ws.root / "log" / "latest"
    assert latest.is_symlink()
    assert "to-own-log" in (latest / "quiet-1-stdout.log").read_text()
    assert "to-launch-log" in (latest / "launch.log").read_text()
    assert "to-own-log" not in result.stdout and "to-launch-log" not in result.stdout


def test_launcher_does_not_import_heavy_modules():
    code = ("import sys, launcher.cli.main, launcher.cli.launch_command, launcher.frontend.loader;"
            "heavy = [m for m in ('mujoco', 'numpy', 'zenoh', 'asyncio') if m in sys.modules];"
            "print(heavy)")
    out = os.popen(f"{PY} -c \"{code}\"").read().strip()
    assert out == "[]"


def test_processes_are_group_leaders(ws):
    ws.write("group.launch.yaml", "launch:\n  - executable: {cmd: sleep 30}\n")
    proc = ws.start("launch", "group.launch.yaml")
    deadline = time.monotonic() + 20
    while not [p for p in ws.processes() if p.name() == "sleep"]:
        assert time.monotonic() < deadline
        time.sleep(0.05)
    (sleep,) = [p for p in ws.processes() if p.name() == "sleep"]
    assert os.getpgid(sleep.pid) == sleep.pid and os.getsid(sleep.pid) == sleep.pid
    assert psutil.Process(sleep.pid).ppid() == proc.pid
    proc.send_signal(signal.SIGINT)
    assert proc.wait(30) == 130


# A launch whose actions start processes as given: a helper (see ProcessSpec.helper_done_line)
# and the others, each `label=argv…` on the command line (a label starting "helper" is one;
# one starting "node" may join the graph; the word "hold" holds the graph for a helper).
HELPERS = """
import sys, time
from launcher.description.action import Action, LaunchDescription
from launcher.runtime.output import Printer
from launcher.runtime.process import ProcessSpec
from launcher.runtime.service import LaunchService, default_environment

class Start(Action):
    def __init__(self, spec):
        super().__init__()
        self.spec = spec

    def execute(self, context):
        context.service.start_process(self.spec)

class Hold(Action):
    def execute(self, context):
        context.service.hold_graph()

actions = []
for word in sys.argv[1:]:
    if word == "hold":
        actions.append(Hold())
        continue
    label, _, command = word.partition("=")
    actions.append(Start(ProcessSpec(label=label, argv=["sh", "-c", command],
                                     env=default_environment(), sigterm_timeout=1,
                                     stdout_to=frozenset({"screen"}),
                                     helper_done_line="work done" if label.startswith("helper")
                                     else "", joins_graph=label.startswith("node"))))
begin = time.monotonic()
code = LaunchService(printer=Printer(color=False)).run(LaunchDescription(actions))
print(f"ENDED {code} after {time.monotonic() - begin:.1f}")
sys.exit(code)
"""


@pytest.mark.parametrize("processes, code, least, most", [
    # done at 0.2 s, the other ends at 1 s: the launch ends then, the helper stopped
    (["helper-1=sleep 0.2; echo work done; exec sleep 60", "worker-2=sleep 1"], 0, 0.9, 8),
    # a helper alone keeps the launch until its work is done
    (["helper-1=sleep 0.5; echo work done; exec sleep 60"], 0, 0.4, 8),
    # one that never says so is an ordinary process: it fails, the launch says so
    (["helper-1=sleep 0.3; exit 3", "worker-2=sleep 0.1"], 1, 0.2, 8),
], ids=["with-others", "alone", "fails"])
def test_a_helper_keeps_the_launch_only_until_its_work_is_done(ws, processes, code, least,
                                                               most):
    ws.write("helpers.py", HELPERS)
    done = subprocess.run([sys.executable, str(ws.root / "helpers.py"), *processes],
                          env=ws.env, cwd=ws.root, capture_output=True, text=True, timeout=60)
    assert done.returncode == code, done.stdout + done.stderr
    ended = re.search(r"ENDED (\d+) after ([\d.]+)", done.stdout)
    assert ended and least <= float(ended.group(2)) <= most, done.stdout
    assert "Traceback" not in done.stdout + done.stderr


def test_nodes_wait_for_the_graphs_parameters_and_start_once_they_are_set(ws):
    """roslaunch sets every parameter before it starts a node: a node started while the
    graph is held (its parameters' helper to come) starts once the helper is done."""
    ws.write("helpers.py", HELPERS)
    done = subprocess.run([sys.executable, str(ws.root / "helpers.py"), "hold",
                           "node-1=echo node at $(date +%s.%N)",
                           "helper-2=sleep 1; echo work done at $(date +%s.%N); exec sleep 60"],
                          env=ws.env, cwd=ws.root, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr
    node = float(re.search(r"node at ([\d.]+)", done.stdout).group(1))
    helper = float(re.search(r"work done at ([\d.]+)", done.stdout).group(1))
    assert node >= helper, done.stdout


def test_a_failed_parameter_load_starts_no_node_and_fails_the_launch(ws):
    ws.write("helpers.py", HELPERS)
    done = subprocess.run([sys.executable, str(ws.root / "helpers.py"), "hold",
                           "node-1=echo NODE STARTED", "helper-2=echo refused >&2; exit 1"],
                          env=ws.env, cwd=ws.root, capture_output=True, text=True, timeout=60)
    said = done.stdout + done.stderr
    assert done.returncode == 1, said
    assert "NODE STARTED" not in said
    assert "the launch's parameters could not be set on the parameter server" in said
