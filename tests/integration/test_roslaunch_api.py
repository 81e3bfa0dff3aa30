"""roslaunch's Python API over launcher (compat/nodes/roslaunch): what ROS 1 scripts and tests
call, as roslaunch 1.16 documents and does it. Substitutions, run ids and configs are read in
this process (nothing started); the launches run in a script of their own on the test's own
graph, which must leave no process behind."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from launcher import compat
from tests.support.packages import make_tree, manifest

compat.enable_in_process()

import roslaunch  # noqa: E402
import roslaunch.config  # noqa: E402
import roslaunch.core  # noqa: E402
import roslaunch.rlutil  # noqa: E402
from roslaunch.substitution_args import ArgException, resolve_args  # noqa: E402

SLEEPER = "#!/bin/sh\nexec sleep 60\n"
DEMO = """<launch>
  <arg name="who" default="world"/>
  <param name="greeting" value="hello $(arg who)"/>
  <group ns="fleet">
    <node name="sleeper" pkg="tools" type="sleeper" args="--to $(arg who)">
      <param name="rate" value="5"/>
      <remap from="cmd" to="/cmd_vel"/>
    </node>
  </group>
  <test test-name="check" pkg="tools" type="sleeper" time-limit="20"/>
</launch>
"""


@pytest.fixture
def tools(tmp_path, monkeypatch):
    """A package `tools` whose executable `sleeper` sleeps, and demo.launch beside it."""
    make_tree(tmp_path / "src", {"tools/package.xml": manifest("tools"),
                                 "tools/scripts/sleeper": SLEEPER,
                                 "tools/launch/demo.launch": DEMO},
              executable=("tools/scripts/sleeper",))
    monkeypatch.setenv("LAUNCHER_PACKAGE_PATH", str(tmp_path / "src"))
    monkeypatch.setenv("LAUNCHER_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "src" / "tools"


# --- in this process: nothing runs -----------------------------------------------------------
def test_resolve_args_resolves_roslaunch_substitutions(tools, monkeypatch):
    monkeypatch.setenv("GREETING", "hi")
    monkeypatch.delenv("NOT_SET", raising=False)
    text = "$(arg x)/$(env GREETING)/$(optenv NOT_SET some default)/$(find tools)"
    assert resolve_args(text, {"arg": {"x": "1"}}) == f"1/hi/some default/{tools}"
    assert resolve_args("$(eval 1 + int(arg('x')))", {"arg": {"x": "2"}}) == "3"
    assert resolve_args("$(dirname)/a", filename=str(tools / "launch" / "demo.launch")) == \
        f"{tools}/launch/a"
    assert resolve_args("") == "" and resolve_args(None) is None
    with pytest.raises(ArgException, match="missing"):
        resolve_args("$(arg missing)")


def test_anonymous_names_are_kept_in_the_context_dict():
    """roslaunch: the same $(anon NAME) resolves the same within one context dict; with
    resolve_anon=False it is left as written."""
    context: dict = {}
    first = resolve_args("$(anon talker)", context)
    assert first.startswith("talker_") and resolve_args("$(anon talker)", context) == first
    assert context["anon"]["talker"] == first
    assert resolve_args("$(anon talker)", {}) != first
    assert resolve_args("n:=$(anon talker)", resolve_anon=False) == "n:=$(anon talker)"


def test_run_ids_and_launch_arguments(tools):
    assert roslaunch.rlutil.get_or_generate_uuid("given", False) == "given"
    made = roslaunch.rlutil.get_or_generate_uuid(None, False)
    assert len(made) == 36 and made != roslaunch.rlutil.get_or_generate_uuid(None, False)
    path = str(tools / "launch" / "demo.launch")
    assert roslaunch.rlutil.resolve_launch_arguments(["tools", "demo.launch", "who:=x"]) == \
        [path, "who:=x"]
    assert roslaunch.rlutil.resolve_launch_arguments([path, "who:=x"]) == [path, "who:=x"]
    with pytest.raises(roslaunch.core.RLException, match="is not a launch file name"):
        roslaunch.rlutil.resolve_launch_arguments(["nowhere.launch"])


def test_a_loaded_config_reads_as_roslaunchs(tools):
    config = roslaunch.config.load_config_default(
        [(str(tools / "launch" / "demo.launch"), ["who:=you"])], None)
    [node] = config.nodes
    assert (node.package, node.type, node.name, node.namespace) == \
        ("tools", "sleeper", "sleeper", "/fleet/")
    assert node.args == "--to you" and node.remap_args == [("cmd", "/cmd_vel")]
    assert config.params["/greeting"].value == "hello you"
    assert config.params["/fleet/sleeper/rate"].value == 5
    [test] = config.tests
    assert (test.test_name, test.type, test.time_limit) == ("check", "sleeper", 20.0)
    assert "/fleet/" in config.summary()


def test_node_xml_round_trips_through_launchers_frontend():
    node = roslaunch.core.Node("tools", "sleeper", name="s", namespace="ns", args="a b",
                               remap_args=[("x", "y")], output="screen")
    assert node.namespace == "/ns/"
    assert node.to_xml() == ('<node pkg="tools" type="sleeper" ns="/ns/" args="a b" '
                             'output="screen" respawn="false" respawn_delay="0.0" name="s" '
                             'required="false">\n  <remap from="x" to="y" />\n</node>')


# --- launches, in a script on the test's own graph --------------------------------------------
SCRIPT = """
import json, sys, time
import psutil
from launcher import compat
compat.enable_in_process()
import roslaunch, roslaunch.core, roslaunch.parent, roslaunch.rlutil, roslaunch.scriptapi

def sleepers():
    return [p for p in psutil.Process().children(recursive=True)
            if "sleep" in " ".join(p.cmdline())]

def until(condition):
    deadline = time.monotonic() + 20
    while not condition() and time.monotonic() < deadline:
        time.sleep(0.05)
    return condition()

out = {}
uuid = roslaunch.rlutil.get_or_generate_uuid(None, False)
roslaunch.configure_logging(uuid)
parent = roslaunch.parent.ROSLaunchParent(uuid, [[sys.argv[1], "who:=there"]],
                                          show_summary=False)
parent.start()
out["parent_started"] = bool(until(sleepers))
parent.shutdown()
out["parent_left"] = len(sleepers())

launch = roslaunch.scriptapi.ROSLaunch()
launch.start()
process = launch.launch(roslaunch.core.Node("tools", "sleeper", name="napper"))
out["node_started"] = bool(until(sleepers)) and process.is_alive()
process.stop()
out["node_alive_after_stop"] = process.is_alive() or bool(sleepers())
launch.launch(roslaunch.core.Node("tools", "sleeper", name="second"))
out["second_started"] = bool(until(sleepers))
launch.stop()
out["launch_left"] = len(sleepers())
print("RESULT", json.dumps(out), flush=True)
"""


def test_parent_and_scriptapi_run_on_launchers_runtime_and_leave_nothing(ws, tools):
    """ROSLaunchParent runs the file (its arguments given with it) until shutdown();
    scriptapi.ROSLaunch launches Nodes one by one, each process stoppable, and stop() ends
    the rest. The ws fixture fails the test if any process is left."""
    ws.own_bus()
    ws.env.update(LAUNCHER_PACKAGE_PATH=str(tools.parent),
                  LAUNCHER_CACHE_DIR=str(ws.root / "cache"))
    script = ws.write("drive.py", SCRIPT)
    done = subprocess.run([sys.executable, str(script), str(tools / "launch" / "demo.launch")],
                          cwd=ws.root, env=ws.env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    line = next(x for x in done.stdout.splitlines() if x.startswith("RESULT "))
    result = json.loads(line[len("RESULT "):])
    assert result["parent_started"] and result["parent_left"] == 0
    assert result["node_started"] and not result["node_alive_after_stop"]
    assert result["second_started"] and result["launch_left"] == 0
