"""The warm start (runtime/warm.py): Python processes of a launch forked from a server that has
imported what nodes import. Each test runs the same launch warm and cold
(LAUNCHER_WARM_START=0) and finds the same process: its output, its failures, its exit, and
what ps and /proc show; and nothing one warm process changes reaches the next."""

from __future__ import annotations

import os
import re
import signal
import sys
import time

import psutil
import pytest

SCRIPT = "#!/usr/bin/env python3\n"
WARM = {"LAUNCHER_WARM_START": "1"}
COLD = {"LAUNCHER_WARM_START": "0"}


@pytest.fixture
def py_ws(ws):
    """A workspace whose PATH finds this interpreter as python3 (as a user's venv does)."""
    ws.env["PATH"] = f"{os.path.dirname(sys.executable)}:{ws.env.get('PATH', '/usr/bin:/bin')}"
    return ws


def script(ws, name: str, body: str) -> str:
    path = ws.write(name, SCRIPT + body)
    path.chmod(0o755)
    return str(path)


def primed(ws) -> str:
    """Two Python processes before the rest: a launch starts its server with the second of a
    kind (so that one node alone costs no server), and the rest start from it."""
    path = script(ws, "first.py", "pass\n")
    return "".join(f"  - executable: {{cmd: {path}, name: prime{i}}}\n" for i in range(2))


def witness(ws) -> str:
    """A process after the rest that says whether it started warm: when it did, the server
    was still in use, so the one before it was started warm too (a failed warm start gives
    the server up)."""
    path = script(ws, "witness.py", "import sys\nprint('warm', 'rclpy' in sys.modules)\n")
    return f"  - executable: {{cmd: {path}, output: screen, name: witness}}\n"


def launch(ws, body: str, env: dict[str, str], name: str = "w.launch.yaml"):
    ws.write(name, "launch:\n" + primed(ws) + body + witness(ws))
    ws.env.update(env)
    return ws.run("launch", name, timeout=90)


def lines_of(text: str, label: str) -> list[str]:
    """What process `label` printed, without pids (they differ between runs)."""
    own = re.compile(rf"^(\[(INFO|ERROR)\] )?\[{label}-\d+\]")
    return [re.sub(r"pid \[?\d+\]?", "pid N", line) for line in text.splitlines()
            if own.match(line)]


def test_the_third_python_process_of_a_kind_starts_warm(py_ws):
    """The first starts cold with no server, the second cold while its server imports, the
    third from the server, with what it imported."""
    path = script(py_ws, "which.py", "import sys\nprint('preloaded', 'rclpy' in sys.modules)\n")
    py_ws.write("three.launch.yaml", "launch:\n" + "".join(
        f"  - executable: {{cmd: {path}, output: screen, name: p{i}}}\n" for i in range(3)))
    py_ws.env.update(WARM)
    done = py_ws.run("launch", "three.launch.yaml", timeout=90)
    said = sorted(line for line in done.stdout.splitlines() if "preloaded" in line)
    assert said == ["[p0-1] preloaded False", "[p1-2] preloaded False",
                    "[p2-3] preloaded True"], done.stdout + done.stderr


def test_the_warm_start_off_starts_every_process_cold(py_ws):
    path = script(py_ws, "which.py", "import sys\nprint('preloaded', 'rclpy' in sys.modules)\n")
    cold = launch(py_ws, f"  - executable: {{cmd: {path}, output: screen}}\n", COLD)
    assert "preloaded False" in cold.stdout, cold.stdout + cold.stderr


def said_the_same_warm_as_cold(ws, entry: str, needle: str):
    """Launch `entry` (process `fails`) warm, then cold: it ran warm the first time, the
    cold run says `needle`, and both say the same lines with the same status. The warm run."""
    warm, cold = launch(ws, entry, WARM), launch(ws, entry, COLD)
    assert "warm True" in warm.stdout and "warm False" in cold.stdout, warm.stdout
    said = lines_of(cold.stdout + cold.stderr, "fails")
    assert any(needle in line for line in said), said
    assert (warm.returncode, lines_of(warm.stdout + warm.stderr, "fails")) == \
        (cold.returncode, said)
    return warm


@pytest.mark.parametrize("body", [
    "raise ValueError('boom')\n",
    "def broken(:\n    pass\n",
    "import no_such_module_here\n",
    "import sys\nprint('out', flush=True)\nsys.exit(3)\n",
], ids=["exception", "syntax error", "import error", "exit status"])
def test_a_failing_process_says_the_same_warm_as_cold(py_ws, body):
    """The same traceback, from the script's own frame, at the same place, and the same
    status: the interpreter's words, not the server's."""
    path = script(py_ws, "fails.py", body)
    entry = f"  - executable: {{cmd: {path}, output: screen, name: fails}}\n"
    warm = said_the_same_warm_as_cold(py_ws, entry, "exited with code")
    assert "warm_server" not in warm.stdout + warm.stderr


CHANGES = """
import os, signal, sys, time
sys.modules["json"] = None
signal.signal(signal.SIGTERM, signal.SIG_IGN)
os.chdir("/")
os.environ["LEFT_BY_THE_FIRST"] = "1"
print("changed", flush=True)
"""
LOOKS = """
import os, signal, sys
print("json", sys.modules.get("json", "absent") is not None,
      "sigterm", signal.getsignal(signal.SIGTERM) == signal.SIG_DFL,
      "cwd", os.getcwd() == os.environ["HERE"],
      "env", "LEFT_BY_THE_FIRST" in os.environ, "warm", "rclpy" in sys.modules, flush=True)
"""


def test_what_one_warm_process_changes_does_not_reach_the_next(py_ws):
    first, second = script(py_ws, "changes.py", CHANGES), script(py_ws, "looks.py", LOOKS)
    body = (f"  - executable: {{cmd: {first}, output: screen, name: first}}\n"
            f"  - timer:\n      period: 1.0\n      children:\n"
            f"        - executable: {{cmd: {second}, output: screen, name: second,\n"
            f"                        env: [{{name: HERE, value: {py_ws.root}}}]}}\n")
    done = launch(py_ws, body, WARM)
    assert "[first-3] changed" in done.stdout, done.stdout + done.stderr
    assert "[second-5] json True sigterm True cwd True env False warm True" in done.stdout, \
        done.stdout


def cmdline(proc: psutil.Process) -> list[str]:
    try:
        return proc.cmdline()
    except psutil.Error:  # (gone, or a zombie: a process that ran a moment)
        return []


def test_ps_and_proc_show_a_warm_process_as_it_would_be_cold(py_ws):
    path = script(py_ws, "sleeps.py", "import sys, time\nprint('warm', 'rclpy' in sys.modules, "
                                      "flush=True)\ntime.sleep(30)\n")
    py_ws.write("s.launch.yaml", f"launch:\n{primed(py_ws)}  - executable: "
                                 f"{{cmd: {path} one two, output: screen, "
                                 f"env: [{{name: MINE, value: here}}]}}\n")
    proc = py_ws.start("launch", "s.launch.yaml", env=WARM, output="ps.out")
    try:
        py_ws.wait_for_output("warm True", 30, "ps.out")
        deadline = time.monotonic() + 30
        found = []
        while not found and time.monotonic() < deadline:
            found = [p for p in psutil.Process(proc.pid).children(recursive=True)
                     if "sleeps.py" in " ".join(cmdline(p))]
            time.sleep(0.1)
        assert found, "the script never started"
        shown = found[0]
        assert shown.cmdline() == ["python3", path, "one", "two"]
        assert shown.name() == "python3"
        assert shown.environ().get("MINE") == "here"
        assert shown.ppid() == proc.pid  # (the launcher's own child, as one it forked)
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(30) == 130


def test_a_failing_module_says_the_same_warm_as_cold(py_ws):
    """`python3 -m MODULE`: runpy's frames and the module's, as the interpreter shows them."""
    py_ws.write("broken_mod.py",
                "import sys\nprint(sys.argv[1:], flush=True)\nraise KeyError('k')\n")
    entry = (f"  - executable: {{cmd: python3 -m broken_mod a b, cwd: {py_ws.root}, "
             f"output: screen, name: fails}}\n")
    said_the_same_warm_as_cold(py_ws, entry, "KeyError: 'k'")


def test_a_sigkill_of_the_launcher_leaves_no_warm_process_nor_server(py_ws):
    """The watchdog ends what the launch started warm, and the server, as it ends the rest."""
    path = script(py_ws, "stays.py", "import sys, time\nprint('warm', 'rclpy' in sys.modules, "
                                     "flush=True)\ntime.sleep(60)\n")
    py_ws.write("k.launch.yaml", f"launch:\n{primed(py_ws)}"
                                 f"  - executable: {{cmd: {path}, output: screen}}\n")
    proc = py_ws.start("launch", "k.launch.yaml", env=WARM, output="k.out")
    py_ws.wait_for_output("warm True", 30, "k.out")
    assert any("warm_server" in " ".join(cmdline(p)) for p in py_ws.processes())
    proc.kill()
    proc.wait()
    deadline = time.monotonic() + 15
    while [p for p in py_ws.processes() if cmdline(p)] and time.monotonic() < deadline:
        time.sleep(0.2)
    assert not [" ".join(cmdline(p)) for p in py_ws.processes() if cmdline(p)]
