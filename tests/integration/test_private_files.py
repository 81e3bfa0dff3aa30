"""What a launch writes is its user's own, whatever the umask: the graph's run folder (its
socket, lock and router log), the run's log folder and files, and the
params files that hold robot_description."""

from __future__ import annotations

import os
import stat

from tests.support.environment import REPO


def mode(path) -> int:
    return stat.S_IMODE(os.stat(path).st_mode)


def test_run_file_logs_and_params_files_are_private(ws):
    ws.own_bus()
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(REPO / "packages")
    ws.write("private.launch.yaml", """
    launch:
      - node:
          pkg: robot_state_publisher
          exec: robot_state_publisher
          output: screen
          param:
            - {name: robot_description, value: "<robot name='r'><link name='a'/></robot>"}
      - timer: {period: 3.0, children: [{shutdown: {reason: enough}}]}
    """)
    proc = ws.start("launch", "private.launch.yaml", output="out.txt")
    ws.wait_for_output("robot 'r'", 60, "out.txt")
    run = ws.root / "run"
    assert mode(run) == 0o700 and (run / "domain-0.sock").is_socket()
    assert mode(run / "domain-0.lock") == 0o600 and mode(run / "domain-0.log") == 0o600
    assert proc.wait(60) == 0
    (folder,) = [p for p in (ws.root / "log").iterdir() if p.is_dir() and not p.is_symlink()]
    assert mode(folder) == 0o700
    assert mode(folder / "launch.log") == 0o600
    (params,) = (folder / "params").glob("*.yaml")
    assert "robot_description" in params.read_text()
    assert mode(params) == 0o600 and mode(params.parent) == 0o700
