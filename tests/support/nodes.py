"""Node programs and the launches that run them, for tests of the graph."""

from __future__ import annotations

import contextlib
import os
import signal
import sys
from pathlib import Path

from tests.support.workspace import Workspace


def node_package(ws, name: str, scripts: dict[str, str]) -> Path:
    """A package of Python scripts in the workspace's `ws/` folder (on the package path)."""
    for file, text in scripts.items():
        path = ws.write(f"ws/{name}/scripts/{file}", text)
        path.chmod(0o755)
    ws.write(f"ws/{name}/package.xml", f"""
    <?xml version="1.0"?>
    <package format="3"><name>{name}</name><version>0.1.0</version><description>nodes
    </description><maintainer email="a@b.c">a</maintainer><license>MIT</license></package>
    """)
    paths = [p for p in ws.env.get("LAUNCHER_PACKAGE_PATH", "").split(os.pathsep) if p]
    ws.env["LAUNCHER_PACKAGE_PATH"] = os.pathsep.join([*paths, str(ws.root / "ws")])
    return ws.root / "ws" / name


PY = sys.executable

TALKER = """
import sys
from launcher.bus.node import Node
from launcher.bus.qos import LATCHED
node = Node("talker")
value = float(node.args[0]) if node.args else 1.0
pub = node.create_publisher("geometry_msgs/msg/Twist", "cmd_vel")
node.create_publisher("std_msgs/msg/String", "robot_description", LATCHED).publish(
    node.message("std_msgs/msg/String", data="<robot name='r'/>"))
node.create_timer(0.05, lambda: pub.publish(
    node.message("geometry_msgs/msg/Twist", linear={"x": value})))
node.get_logger().info(f"talking on {pub.topic}")
node.spin()
node.destroy_node()
"""


def launch(ws, name: str, body: str, *extra: str, env: dict | None = None):
    """Start a launch of `body` in the background; its output goes to NAME.out."""
    ws.write(name, body)
    proc = ws.start("launch", name, *extra, output=f"{name}.out", env=env)
    return proc, ws.root / f"{name}.out"


def wait_text(path, needle: str, timeout: float = 30) -> str:
    """The launch output at `path` once it holds `needle`."""
    return Workspace(path.parent, "").wait_for_output(needle, timeout, path.name)


def stop(proc) -> int:
    proc.send_signal(signal.SIGINT)
    return proc.wait(30)


@contextlib.contextmanager
def script_launched(ws, script: str, text: str, ready: str, args: str = ""):
    """The node program `text`, written to `script` and run by a launch of its own once it
    says `ready`; stopped (as Ctrl-C stops a launch) when the block ends."""
    ws.write(script, text)
    proc, out = launch(ws, f"{script}.launch.yaml", "launch:\n  - executable: "
                       f"{{cmd: {PY} {script} {args}, output: screen}}\n")
    try:
        wait_text(out, ready)
        yield ws
    finally:
        code = stop(proc)
    assert code == 130
