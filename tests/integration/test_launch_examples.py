"""launch's own examples of its Python API, run unchanged where they are, as a user runs them:
`python3 launch_counters.py` (a LaunchService run by hand, LaunchIntrospector, a ProcessIO
handler, a Shutdown event, processes that ignore SIGINT and SIGTERM)."""

from __future__ import annotations

import subprocess
import sys

from launcher.compat import SITE
from tests.support.environment import shared


def test_launch_counters_runs_unchanged_and_stops_what_ignores_sigint_and_sigterm(ws):
    examples = shared("external", "launch_examples", "launch", "examples")
    env = dict(ws.env, PYTHONPATH=SITE, USER="tester")  # (as `. hooks/setup.sh` gives a shell)
    done = subprocess.run([sys.executable, "launch_counters.py"], cwd=examples, env=env,
                          capture_output=True, text=True, timeout=120)
    out = done.stdout + done.stderr
    assert done.returncode == 0, out
    said = ["Starting introspection of launch description...",
            "├── LogInfo('Is that you, ' + EnvVar('USER') + '?')",
            "├── ExecuteProcess(cmd=[FindExec('whoami')], cwd=None, env=None, shell=True)",
            "Starting launch of launch description...",
            "[INFO] [launch]: Is that you, tester?",
            "[INFO] [launch]: whoami says you are '",
            "Launch was asked to shutdown: saw 'Counter: 4' from 'python",
            "still running; sending SIGTERM",
            "still running; sending SIGKILL"]
    positions = [out.index(text) for text in said]
    assert positions == sorted(positions), out
