"""roslaunch's XML (ROS 1) run by `launcher launch`, each tag and substitution against a node
that reports what it was given. Expected behaviour is written from roslaunch's documentation
(wiki.ros.org/roslaunch/XML and its tag pages), as each test says."""

from __future__ import annotations

import os
import signal

import pytest
import yaml

from tests.support.packages import make_tree, manifest

# Reports its argv, its environment's GREETING, and the parameters it was given (its params
# files, any key, and -p values). A roslaunch file's node gets roslaunch's command line
# (FROM:=TO, __name:=, __ns:=, __log:=) and its parameters, for launcher's own nodes, as
# --ros-args words in LAUNCHER_NODE_PARAMETERS; a ROS 2 file's gets --ros-args.
REPORT = """
import json, os, sys, yaml

def main():
    args = sys.argv[1:]
    ros = args[args.index("--ros-args"):] if "--ros-args" in args else []
    mine = args[:len(args) - len(ros)]
    params, remaps, name, ns = {}, [], "", os.environ.get("ROS_NAMESPACE", "")
    for word in [w for w in mine if ":=" in w]:  # ROS 1's
        key, _, value = word.partition(":=")
        if key == "__name":
            name = value
        elif key == "__ns":
            ns = value
        elif not key.startswith("__"):
            remaps.append(word)
    ros1 = [w for w in mine if ":=" in w]
    mine = [w for w in mine if ":=" not in w]
    ros = ros + json.loads(os.environ.get("LAUNCHER_NODE_PARAMETERS", "[]"))
    for i, word in enumerate(ros):
        if word == "--params-file":
            with open(ros[i + 1]) as handle:
                for body in yaml.safe_load(handle).values():
                    params.update(body["ros__parameters"])
        elif word == "-p":
            key, _, text = ros[i + 1].partition(":=")
            params[key] = text if "\\n" in text else yaml.safe_load(text)
        elif word == "-r":
            key, _, value = ros[i + 1].partition(":=")
            if key == "__node":
                name = value
            elif key == "__ns":
                ns = value
            else:
                remaps.append(f"{key}:={value}")
    print("REPORT", repr({"node": f"{ns.rstrip('/')}/{name}", "args": mine,
                          "params": params, "remaps": remaps, "ros1": ros1,
                          "namespace_env": os.environ.get("ROS_NAMESPACE"),
                          "greeting": os.environ.get("GREETING")}), flush=True)
    if "--wait" in mine:
        import time
        time.sleep(60)
    return int(os.environ.get("EXIT_CODE", "0"))
"""


# A rospy node (launcher's rospy) reading parameters as ROS 1 code does.
READER = """#!/usr/bin/env python
import rospy
rospy.init_node("reader")
print("READ", rospy.get_param("/robot_description"), rospy.get_param("robot_description"),
      rospy.get_param("~gain"), rospy.has_param("/rate"), rospy.get_param("/nope", "dflt"),
      flush=True)
"""


# A rospy node run from another shell, reading and writing the graph's parameter server.
OTHER = """#!/usr/bin/env python
import rospy
rospy.init_node("other_shell")
print("GOT", repr(rospy.get_param("/robot_description")), rospy.get_param("/fleet/r1/driver/gain"),
      rospy.get_param("/gains/limits"), rospy.get_param("/fleet/tuning/kp"), flush=True)
rospy.set_param("/from_node", {"a": 12, "b": [1, 2]})
"""


@pytest.fixture
def ros1(ws):
    make_tree(ws.root / "src", {
        "tools/package.xml": manifest("tools", extra=(
            '<export><executable name="report" module="tools_app.report:main"/></export>')),
        "tools/tools_app/__init__.py": "",
        "tools/tools_app/report.py": REPORT,
        "tools/config/gains.yaml": "p: 1.5\ni: 0.1\nlimits: {max: 2}\n",
        "tools/config/substituted.yaml": "speed: $(arg speed)\n",
        "tools/config/broken.yaml": "p: [1, 2\n",
        "tools/launch/inner.launch": """<launch>
  <arg name="who" default="inner"/>
  <param name="set_inside" value="7"/>
  <node name="inner_node" pkg="tools" type="report" output="screen" args="$(arg who)"/>
</launch>
""",
        "tools/urdf/robot.txt": "<robot name='r'/>\n",
        "tools/scripts/reader.py": READER,
        "tools/scripts/other.py": OTHER,
    }, executable=("tools/scripts/reader.py", "tools/scripts/other.py"))
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "src")
    ws.env["LAUNCHER_CACHE_DIR"] = str(ws.root / "cache")
    return ws


def reports(ws, *args: str) -> dict[str, dict]:
    result = ws.run("launch", *args, timeout=60)
    assert result.returncode == 0, result.stdout + result.stderr
    found = {}
    for line in result.stdout.splitlines():
        if "REPORT " in line:
            report = eval(line.split("REPORT ", 1)[1])  # noqa: S307 - our own node's repr
            found[report["node"]] = report
    return found


def test_nodes_params_and_scopes_as_roslaunch_has_them(ros1):
    """roslaunch: a node-level <param> is the node's private parameter; a <param> outside a
    node is on the parameter server for every node (launcher: given to the nodes after it);
    <group ns> and <node ns> nest; <remap> and <env> outside a node apply to the nodes after
    them in their scope; <arg value> is fixed; <rosparam> loads a YAML map."""
    ros1.write("robot.launch", """<launch>
  <arg name="speed" default="1.0"/>
  <arg name="fixed" value="constant"/>
  <param name="robot_description" textfile="$(find tools)/urdf/robot.txt"/>
  <param name="rate" value="50" type="int"/>
  <rosparam command="load" file="$(find tools)/config/gains.yaml" ns="gains"/>
  <env name="GREETING" value="hello"/>
  <group ns="fleet">
    <remap from="cmd_vel" to="/fleet/cmd"/>
    <remap from="scan" to="/fleet/scan"/>
    <node name="driver" pkg="tools" type="report" ns="r1" output="screen"
          args="--speed $(arg speed) $(arg fixed)">
      <param name="gain" value="2.5"/>
      <param name="~label" value="left" type="str"/>
      <param name="text" command="echo from-a-command"/>
      <rosparam>
        tuning: {kp: 3}
        names: [a, b]
      </rosparam>
      <rosparam command="load" file="$(find tools)/config/substituted.yaml"
                subst_value="true"/>
      <remap from="odom" to="odometry"/>
      <remap from="scan" to="own_scan"/>
    </node>
  </group>
  <param name="~later" value="9"/>
  <node name="plain" pkg="tools" type="report" output="screen"/>
</launch>
""")
    got = reports(ros1, "robot.launch", "speed:=3.5")
    driver = got["/fleet/r1/driver"]
    assert driver["args"] == ["--speed", "3.5", "constant"]
    assert driver["params"]["gain"] == 2.5 and driver["params"]["label"] == "left"
    assert driver["params"]["text"] == "from-a-command\n"
    assert driver["params"]["tuning.kp"] == 3 and driver["params"]["names"] == ["a", "b"]
    assert driver["params"]["speed"] == 3.5  # subst_value: $(arg speed) in the file
    assert driver["params"]["robot_description"] == "<robot name='r'/>\n"
    assert driver["params"]["rate"] == 50 and driver["params"]["gains.p"] == 1.5
    assert driver["params"]["gains.limits.max"] == 2
    # LoaderContext.remap_args: the scope's, less those the node remaps itself, then its own
    assert driver["remaps"] == ["cmd_vel:=/fleet/cmd", "odom:=odometry", "scan:=own_scan"]
    assert driver["greeting"] == "hello"
    plain = got["/plain"]
    assert plain["remaps"] == [] and "gain" not in plain["params"]  # the group's stay inside
    assert plain["params"]["rate"] == 50
    # a ~name outside a node is the private parameter of the nodes after it (not before)
    assert plain["params"]["later"] == 9 and "later" not in driver["params"]


def test_rosparam_dump_and_delete_run_before_the_launch_sets_its_parameters(ros1):
    """roslaunch runs `rosparam dump|delete` before it uploads the launch's parameters (as
    the real roslaunch 1.15 does): on a fresh graph, a dump of what the launch sets finds
    nothing (said, and the launch goes on); a delete does not remove what the launch sets;
    a dump of / writes what the server held then."""
    ros1.write("dump.launch", """<launch>
  <rosparam command="load" file="$(find tools)/config/gains.yaml" ns="gains"/>
  <param name="rate" value="50"/>
  <rosparam command="dump" file="$(dirname)/gains_dump.yaml" param="gains"/>
  <rosparam command="delete" param="gains"/>
  <node name="after" pkg="tools" type="report" output="screen"/>
</launch>
""")
    result = ros1.run("launch", "dump.launch", timeout=60)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "rosparam dump: nothing to write" in result.stdout + result.stderr
    assert not (ros1.root / "gains_dump.yaml").exists()
    report = next(eval(line.split("REPORT ", 1)[1])  # noqa: S307 - our own node's repr
                  for line in result.stdout.splitlines() if "REPORT " in line)
    assert report["params"] == {"rate": 50, "gains.p": 1.5, "gains.i": 0.1,
                                "gains.limits.max": 2}


def test_include_passes_only_its_args_and_substitutions(ros1):
    """roslaunch: an included file sees only the args passed to it (unless pass_all_args);
    `ns` on include namespaces its nodes; $(optenv), $(anon), $(eval) with arg(), $(dirname)."""
    ros1.write("top.launch", """<launch>
  <arg name="who" default="outer"/>
  <arg name="radius" default="0.5"/>
  <include file="$(find tools)/launch/inner.launch" ns="one"/>
  <include file="$(find tools)/launch/inner.launch" ns="two">
    <arg name="who" value="passed"/>
  </include>
  <include file="$(find tools)/launch/inner.launch" ns="three" pass_all_args="true"/>
  <node name="subst" pkg="tools" type="report" output="screen"
        args="$(optenv NO_SUCH_VARIABLE fallback) $(dirname)"/>
  <node name="doubled" pkg="tools" type="report" output="screen"
        args="$(eval arg('radius') * 2)"/>
  <node name="measured" pkg="tools" type="report" output="screen" args="$(eval str(radius) + 'cm')"/>
  <node name="$(anon worker)" pkg="tools" type="report" output="screen"/>
</launch>
""")
    got = reports(ros1, "top.launch")
    assert got["/one/inner_node"]["args"] == ["inner"]  # not the outer 'who'
    assert got["/two/inner_node"]["args"] == ["passed"]
    assert got["/three/inner_node"]["args"] == ["outer"]
    # roslaunch's parameters outlive the file that set them: a node after the includes gets
    # what an included file set (an include with ns= sets it in its namespace)
    assert got["/subst"]["params"].get("set_inside") is None  # (all three had ns=)
    assert got["/subst"]["args"] == ["fallback", str(ros1.root)]
    # $(eval) only as a whole attribute (roslaunch/substitution_args.py resolve_args: the
    # value must start with '$(eval ' and end with ')'); args in it are typed as roslaunch
    # types an untyped value (0.5 is a float)
    assert got["/doubled"]["args"] == ["1.0"] and got["/measured"]["args"] == ["0.5cm"]
    anonymous = [name for name in got if name.startswith("/worker_")]
    assert len(anonymous) == 1


READ = """<launch>
  <param name="robot_description" value="urdf-text"/>
  <param name="rate" value="50"/>
  <node name="reader" pkg="tools" type="reader.py" output="screen">
    <param name="gain" value="2.5"/>
  </node>
</launch>
"""


def test_rospy_reads_the_launch_parameters(ros1):
    """roslaunch: a rospy node reads a <param> outside it by its graph name (/name or a
    relative one) and its own <param> as ~name."""
    ros1.write("read.launch", READ)
    done = ros1.run("launch", "read.launch", timeout=60)
    assert "READ urdf-text urdf-text 2.5 True dflt" in done.stdout, done.stdout + done.stderr


def test_a_node_reads_its_launchs_value_not_an_older_one_on_the_server(ros1):
    """roslaunch sets the parameters before it starts the nodes: a rospy node of the launch
    reads the launch's value even when the server held another one before (launcher: the
    node waits for its launch's parameters to be on the server before it asks)."""
    router = ros1.start("router", output="router.out")
    try:
        ros1.wait_for_output("listening", 30, "router.out")
        assert ros1.run("rosparam", "set", "/robot_description", "older").returncode == 0
        ros1.write("read.launch", READ)
        for _ in range(3):
            done = ros1.run("launch", "read.launch", timeout=60)
            assert "READ urdf-text urdf-text 2.5 True dflt" in done.stdout, \
                done.stdout + done.stderr
            assert ros1.run("rosparam", "set", "/robot_description", "older").returncode == 0
    finally:
        router.send_signal(signal.SIGINT)
        assert router.wait(30) == 0


def test_parameters_outlive_the_included_file(ros1):
    """roslaunch: a <param> is on the parameter server for the rest of the launch, whichever
    file set it: a node after the include reads what the included file set."""
    ros1.write("outer.launch", """<launch>
  <include file="$(find tools)/launch/inner.launch"/>
  <node name="after" pkg="tools" type="report" output="screen"/>
</launch>
""")
    got = reports(ros1, "outer.launch")
    assert got["/after"]["params"]["set_inside"] == 7
    assert got["/inner_node"]["args"] == ["inner"]


PARAMS = """<launch>
  <param name="robot_description" textfile="$(find tools)/urdf/robot.txt"/>
  <rosparam command="load" file="$(find tools)/config/gains.yaml" ns="gains"/>
  <group ns="fleet">
    <param name="rate" value="50" type="int"/>
    <param name="/absolute" value="yes"/>
    <rosparam>tuning: {kp: 3}</rosparam>
    <node name="driver" pkg="tools" type="report" ns="r1" output="screen" args="{wait}">
      <param name="gain" value="2.5"/>
    </node>
  </group>
</launch>
"""


def test_the_graph_parameter_server_holds_every_parameter_as_roscore_does(ros1):
    """roslaunch sets each <param> and <rosparam> on the master's parameter server before its
    nodes start: one outside a node by its name in its namespace (a /name is global), a
    node's own as /NS/NODE/NAME; `rosparam` and every node then read and write them there
    while the master runs (wiki.ros.org/roslaunch/XML/param, /rosparam; the outputs of `rosparam
    list|get|set|delete|dump|load` follow ROS 1's rosparam 1.15 source, Debian's
    python3-rosparam). Here a standing `launcher router` plays roscore, and the parameters
    outlive the launch that set them."""
    router = ros1.start("router", output="router.out")
    try:
        ros1.wait_for_output("listening", 30, "router.out")
        ros1.write("params.launch", PARAMS.replace("{wait}", ""))
        done = ros1.run("launch", "params.launch", timeout=60)
        assert done.returncode == 0, done.stdout + done.stderr
        assert "parameters set on the graph's parameter server" in done.stdout
        listing = ros1.run("rosparam", "list")
        assert listing.stdout.split() == [
            "/absolute", "/fleet/r1/driver/gain", "/fleet/rate", "/fleet/tuning/kp",
            "/gains/i", "/gains/limits/max", "/gains/p", "/robot_description", "/rosdistro",
            "/rosversion", "/run_id"], listing.stderr  # the last three: the master's own
        assert ros1.run("rosparam", "list", "/fleet/r1").stdout.split() == \
            ["/fleet/r1/driver/gain"]
        gains = ros1.run("rosparam", "get", "/gains")
        assert yaml.safe_load(gains.stdout) == {"p": 1.5, "i": 0.1, "limits": {"max": 2}}
        assert ros1.run("rosparam", "get", "/fleet/rate").stdout == "50\n"
        assert ros1.run("rosparam", "get", "-p", "/robot_description").stdout == \
            "<robot name='r'/>\n\n"
        # `launcher param` sees the server as the node it is (ROS 2's view: dotted names)
        assert ros1.run("param", "get", "/_parameter_server",
                        "fleet.r1.driver.gain").stdout.strip() == "Double value is: 2.5"
        # a rospy node in another shell reads them, and what it sets is everyone's
        other = ros1.run("run", "tools", "other.py", timeout=60)
        assert "GOT \"<robot name='r'/>\\n\" 2.5 {'max': 2} 3" in other.stdout, \
            other.stdout + other.stderr
        assert yaml.safe_load(ros1.run("rosparam", "get", "/from_node").stdout) == \
            {"a": 12, "b": [1, 2]}
        # rosparam set (YAML), delete (a subtree), dump, load (into a namespace)
        assert ros1.run("rosparam", "set", "/gains/p", "4.0").returncode == 0
        assert ros1.run("rosparam", "delete", "/gains/limits").returncode == 0
        ros1.run("rosparam", "dump", str(ros1.root / "gains.yaml"), "/gains")
        assert yaml.safe_load((ros1.root / "gains.yaml").read_text()) == {"p": 4.0, "i": 0.1}
        ros1.write("more.yaml", "speed: 2\nnames: [x, y]\n")
        assert ros1.run("rosparam", "load", "more.yaml", "/loaded").returncode == 0
        assert yaml.safe_load(ros1.run("rosparam", "get", "/loaded").stdout) == \
            {"speed": 2, "names": ["x", "y"]}
        # a launch's <rosparam command="delete"> reaches what the server holds
        ros1.write("forget.launch", """<launch>
  <rosparam command="delete" param="loaded"/>
  <param name="loaded/again" value="1"/>
</launch>
""")
        forget = ros1.run("launch", "forget.launch", timeout=60)
        assert "1 parameter set on the graph's parameter server (/_parameter_server), " \
            "1 deleted" in forget.stdout, forget.stdout + forget.stderr
        assert ros1.run("rosparam", "list", "/loaded").stdout.split() == ["/loaded/again"]
        # roslaunch deletes before it sets: /loaded's old tree is gone, what the launch set
        # after the delete stays; a launched script's `rosparam` (launcher's) sees just that
        ros1.write("script.launch.yaml", """
        launch:
          - executable: {cmd: "rosparam get /loaded/again", output: screen}
          - executable: {cmd: "rosparam get /loaded/speed", output: screen}
        """)
        script = ros1.run("launch", "script.launch.yaml", timeout=60)
        said = script.stdout + script.stderr
        assert "[rosparam-1] 1\n" in said, said
        assert "[rosparam-2] error: Parameter [/loaded/speed] is not set" in said, said
    finally:
        router.send_signal(signal.SIGINT)
        assert router.wait(30) == 0


def test_a_second_launch_joins_the_first_ones_parameter_server(ros1):
    """With no roscore running, the first roslaunch starts the master and keeps it while it
    runs; a second roslaunch's parameters go onto the same server (here the graph's router,
    which lives while anything is on the graph)."""
    ros1.write("params.launch", PARAMS.replace("{wait}", "--wait"))
    first = ros1.start("launch", "params.launch")
    try:
        ros1.wait_for_output("parameters set on the graph's parameter server", 60)
        ros1.write("second.launch", """<launch>
  <param name="robot_description" value="second description"/>
  <param name="second" value="2"/>
</launch>
""")
        second = ros1.run("launch", "second.launch", timeout=60)
        assert second.returncode == 0, second.stdout + second.stderr
        got = ros1.run("rosparam", "get", "/")
        values = yaml.safe_load(got.stdout)
        assert isinstance(values, dict), got.stdout + got.stderr
        assert values["second"] == 2 and values["fleet"]["rate"] == 50, got.stdout + got.stderr
        assert values["robot_description"] == "second description"  # the last set wins
    finally:
        first.send_signal(signal.SIGINT)
        assert first.wait(30) == 130


@pytest.mark.parametrize("args, expected", [
    (("get", "/nope"), "error: Parameter [/nope] is not set"),
    (("delete", "/nope"), "error: Parameter [/nope] is not set"),
    (("set", "/x", "[1, 2"), "the value is not valid YAML at line 1, column 6"),
    (("load", "broken.yaml"), "broken.yaml:2:1: not valid YAML"),
    (("load", "missing.yaml"), "cannot read 'missing.yaml': No such file or directory"),
    (("get", "~private"), "a private name (~) has no meaning here"),
    (("set", "/", "5"), "/ holds every parameter: it can be set to a map of names"),
], ids=["get-missing", "delete-missing", "set-bad-yaml", "load-bad-yaml", "load-missing",
        "private-name", "set-root"])
def test_rosparam_bad_input(ros1, args, expected):
    ros1.write("broken.yaml", "p: [1, 2\n")
    result = ros1.run("rosparam", *args)
    assert result.returncode in (1, 2), result.stdout + result.stderr
    assert expected in result.stderr
    assert "Traceback" not in result.stderr


def test_required_test_and_machine(ros1):
    """roslaunch: a node with required="true" ends the launch when it exits; <test> is
    rostest's, which roslaunch ignores (roslaunch/xmlloader.py runs tests only for rostest);
    a <machine> on this host runs its nodes here, and a machine= no <machine> declares is
    refused at its node."""
    ros1.write("req.launch", """<launch>
  <machine name="here" address="localhost"/>
  <machine name="far" address="10.0.0.2"/>
  <node name="quick" pkg="tools" type="report" output="screen" required="true"
        machine="here"/>
  <node name="forever" pkg="tools" type="report" output="screen" args="--wait"/>
</launch>
""")
    result = ros1.run("launch", "req.launch", timeout=60)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "<machine>" not in result.stdout + result.stderr  # (no warning: one host)
    assert "REPORT" in result.stdout and "process stopped" in result.stdout
    ros1.write("far.launch", """<launch>
  <machine name="far" address="10.0.0.2"/>
  <node name="remote" pkg="tools" type="report" machine="fra"/>
</launch>
""")
    far = ros1.run("launch", "far.launch", timeout=60)
    assert far.returncode == 1
    said = far.stdout + far.stderr
    assert "far.launch:3:3: unknown machine 'fra' (did you mean 'far'?)" in said, said
    ros1.write("test.launch", """<launch>
  <test test-name="reports" pkg="tools" type="report"/>
  <node name="plain" pkg="tools" type="report" output="screen"/>
</launch>
""")
    done = ros1.run("launch", "test.launch", timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr
    assert done.stdout.count("REPORT") == 1 and "/plain" in done.stdout  # the test: not run


def test_ros2_xml_named_launch_stays_ros2(ros1):
    ros1.write("new.launch", """<launch>
  <arg name="who" default="ros2"/>
  <node pkg="tools" exec="report" name="modern" output="screen" args="$(var who)"/>
</launch>
""")
    assert reports(ros1, "new.launch")["/modern"]["args"] == ["ros2"]
    # ROS 2 has no parameter server: a ROS 2 file's set_parameter is the nodes' only
    ros1.write("set.launch", """<launch>
  <set_parameter name="rate" value="5"/>
  <node pkg="tools" exec="report" name="modern" output="screen"/>
</launch>
""")
    result = ros1.run("launch", "set.launch", timeout=60)
    assert "REPORT" in result.stdout and "load_parameters" not in result.stdout


@pytest.mark.parametrize("text, expected", [
    ('<node name="a" pkg="tools" type="report"/><node pkg="tools" exec="report"/>',
     "mixes roslaunch (ROS 1) and ROS 2 launch XML: `type=` on <node> at line 2 is ROS 1, "
     "`exec=` on <node> at line 2 is ROS 2"),
    ('<node name="a" pkg="tools"/>', "bad.launch:2:1: roslaunch's <node> needs 'type'"),
    ('<arg name="a" default="1"/><node name="n" pkg="tools" type="report" args="$(arg b)"/>',
     "bad.launch:2:28: launch configuration 'b' is not set"),
    ('<rosparam command="load" file="$(find tools)/config/broken.yaml"/><node name="n" '
     'pkg="tools" type="report"/>', "broken.yaml:2:1"),
    ('<param name="p" command="sh -c \'echo oops >&amp;2; exit 3\'"/><node name="n" '
     'pkg="tools" type="report"/>', "bad.launch:2:1: command 'sh -c 'echo oops >&2; exit 3'' "
     "failed with exit code 3; its stderr:\n    oops"),
    ('<node name="n" pkg="tools" type="nosuch" required="true"/>',
     "package 'tools' has no executable 'nosuch'"),
    ('<node name="twin" pkg="tools" type="report"/><node name="twin" pkg="tools" '
     'type="report"/>', "roslaunch file contains multiple nodes named [/twin]"),
    ('<param name="p" binfile="x.bin"/><node name="n" pkg="tools" type="report"/>',
     "<param binfile=> is not supported"),
    ('<node pkg="tools" type="report"/>', "bad.launch:2:1: roslaunch's <node> needs 'name'"),
    ('<node name="n" pkg="tools" type="report" required="sometimes"/>',
     "bad.launch:2:1: required='sometimes': roslaunch's required is true or false"),
    ('<node name="n" pkg="tools" type="report" respawn="true" required="true"/>',
     "respawn and required cannot both be set to true"),
    ('<test test-name="t" pkg="tools" type="report" respawn="true"/>',
     "<test> tags cannot have 'respawn' attribute"),
    ('<group ns=""><node name="n" pkg="tools" type="report"/></group>',
     "bad.launch:2:1: <group> tag has an empty 'ns' attribute"),
    ('<node name="n" pkg="tools" type="report"><remap from="a b" to="c"/></node>',
     "remap from [a b] is not a valid ROS name"),
    ('<arg name="a" default="1" value="2"/>', "<arg name='a'> has both value= and default="),
    ('<machine name="m" address="localhost"><env name="X" value="1"/></machine>',
     "<machine> takes no <env>"),
    ('<arg name="a" default="1"/><node name="n" pkg="tools" type="report" args="$(arg a b)"/>',
     "$(arg) takes exactly one word in roslaunch, got 2: '$(arg a b)'"),
    ('<param name="p" value="12345678901234"/>',
     "parameter [/p]: 12345678901234 does not fit ROS 1's int"),
    ('<rosparam>p: null</rosparam>', "parameter [/p] is null"),
    ('<param name="p" type="bool" value="no"/>', "roslaunch's bool is true, false, 1 or 0"),
    ('<param name="p" type="float" value="1"/>',
     "<param type='float'>: roslaunch's types are str, string, int, double, bool, boolean, "
     "yaml, auto"),
], ids=["mixed", "no-type", "undefined-arg", "rosparam-yaml", "command-fails",
        "required-missing", "duplicate-names", "binfile", "no-name", "required-bad",
        "respawn-and-required", "test-respawn", "ns-empty", "remap-bad-name",
        "arg-default-and-value", "machine-env", "arg-two-words", "int-too-big", "null",
        "bool-no", "type-float"])
def test_bad_roslaunch_files(ros1, text, expected):
    ros1.write("bad.launch", f"<launch>\n{text}\n</launch>\n")
    result = ros1.run("launch", "bad.launch", timeout=60)
    said = result.stdout + result.stderr
    assert result.returncode == 1, said
    assert expected in said, said
    assert "Traceback" not in said


def test_an_unknown_attribute_is_a_warning_and_the_launch_goes_on(ros1):
    """roslaunch's loader prints a configuration error for an attribute it does not know,
    and goes on (the real roslaunch 1.15 starts the node); launcher says where, with the
    attribute it may have meant."""
    ros1.write("typo.launch", '<launch><group nss="x"><node name="n" pkg="tools" '
                              'type="report" output="screen"/></group></launch>\n')
    result = ros1.run("launch", "typo.launch", timeout=60)
    said = result.stdout + result.stderr
    assert result.returncode == 0, said
    assert "typo.launch:1:9: roslaunch's <group> has no attribute 'nss' (did you mean " \
           "'ns'?)" in said
    assert "REPORT" in said


def test_a_launched_scripts_rosparam_is_a_real_ros1_one_when_the_user_has_it(ros1):
    """compat/bin's `rosparam` is placed last on a launched process's PATH: a ROS 1 install
    of the user's wins. The "real" one here is a stand-in the test puts on PATH."""
    real = ros1.root / "ros1" / "bin"
    real.mkdir(parents=True)
    (real / "rosparam").write_text("#!/bin/sh\necho REAL-ROS1-ROSPARAM \"$@\"\n")
    (real / "rosparam").chmod(0o755)
    ros1.env["PATH"] = f"{real}{os.pathsep}{ros1.env['PATH']}"
    ros1.write("script.launch.yaml", """
    launch:
      - executable: {cmd: "rosparam get /x", output: screen}
    """)
    done = ros1.run("launch", "script.launch.yaml", timeout=60)
    assert "[rosparam-1] REAL-ROS1-ROSPARAM get /x" in done.stdout, done.stdout + done.stderr


def test_clear_params_empties_the_servers_namespace_before_the_launch_sets_its_own(ros1):
    """roslaunch (xmlloader.py, launch.py): clear_params="true" on a group (which needs ns) or a
    node deletes what the parameter server holds under the group's namespace or the node's
    private one, before the launch's parameters are set."""
    router = ros1.start("router", output="router.out")
    try:
        ros1.wait_for_output("listening", 30, "router.out")
        for name in ("/crew/old", "/fleet/r1/driver/stale", "/keep"):
            assert ros1.run("rosparam", "set", name, "1").returncode == 0
        ros1.write("clear.launch", """<launch>
  <group ns="crew" clear_params="true"><param name="fresh" value="2"/></group>
  <node name="driver" pkg="tools" type="report" ns="fleet/r1" clear_params="true">
    <param name="gain" value="2.5"/>
  </node>
</launch>
""")
        done = ros1.run("launch", "clear.launch", timeout=60)
        assert done.returncode == 0, done.stdout + done.stderr
        names = ros1.run("rosparam", "list").stdout.split()
        assert {"/crew/fresh", "/fleet/r1/driver/gain", "/keep"} <= set(names), names
        assert "/crew/old" not in names and "/fleet/r1/driver/stale" not in names, names
    finally:
        router.send_signal(signal.SIGINT)
        router.wait(30)
    ros1.write("root.launch", '<launch>\n  <group clear_params="true"/>\n</launch>\n')
    refused = ros1.run("launch", "root.launch", timeout=60)
    assert refused.returncode == 1
    assert "root.launch:2:3: <group clear_params=\"true\">: 'ns' attribute must be set in " \
           "order to use 'clear_params'" in refused.stderr, refused.stderr


def test_a_nodes_command_line_is_roslauchs(ros1):
    """roslaunch/node_args.py create_local_process_args: the executable, `args` split as shlex
    splits them (substitutions inside quotes resolved first), the remappings as FROM:=TO,
    `__name:=`; nodeprocess.py adds `__log:=` and core.py's setup_env puts the namespace in
    ROS_NAMESPACE (no `__ns:=`; the log file is named after the node's full name). No
    --ros-args: that is ROS 2's."""
    ros1.write("argv.launch", """<launch>
  <arg name="who" default="two words"/>
  <group ns="fleet">
    <node name="driver" pkg="tools" type="report" output="screen" args="a '$(arg who)' c">
      <remap from="in" to="/out"/>
      <param name="gain" value="2"/>
    </node>
  </group>
</launch>
""")
    got = reports(ros1, "argv.launch")["/fleet/driver"]
    assert got["args"] == ["a", "two words", "c"]
    assert got["ros1"][:2] == ["in:=/out", "__name:=driver"]
    assert got["ros1"][2].startswith("__log:=") and got["ros1"][2].endswith("/fleet-driver-1.log")
    assert len(got["ros1"]) == 3 and got["namespace_env"] == "/fleet"
    assert got["params"]["gain"] == 2  # (launcher's own nodes get them from the environment)


def test_roslaunchs_views_load_the_launch_and_start_nothing(ros1):
    """roslaunch --nodes, --args NODE, --find-node NODE, --files and --dump-params
    (roslaunch/__init__.py, node_args.py, param_dump.py): the launch is loaded whole as a run
    loads it (includes, arguments, command= parameters), printed, and nothing runs."""
    marker = ros1.root / "ran"
    ros1.write("views.launch", f"""<launch>
  <arg name="who" default="two words"/>
  <param name="top" command="sh -c 'touch {marker}.param; echo 4'"/>
  <group ns="fleet">
    <env name="GREETING" value="hi there"/>
    <node name="driver" pkg="tools" type="report" args="a '$(arg who)'">
      <param name="gain" value="2"/>
    </node>
  </group>
  <param name="~later" value="9"/>
  <include file="$(find tools)/launch/inner.launch"/>
  <node name="toucher" pkg="tools" type="report" args="--wait" launch-prefix="sh -c 'touch {marker}' --"/>
</launch>
""")

    def roslaunch(*words: str) -> str:
        done = ros1.run("roslaunch", *words, "views.launch", "who:=one", timeout=60)
        assert done.returncode == 0, done.stdout + done.stderr
        return done.stdout

    assert roslaunch("--nodes").split() == ["/fleet/driver", "/inner_node", "/toucher"]
    line = roslaunch("--args", "fleet/driver")
    assert "GREETING='hi there'" in line and "ROS_NAMESPACE=/fleet " in line
    assert line.rstrip().split(" ")[-4:-1] == ["a", "one", "__name:=driver"]
    inner = ros1.root / "src" / "tools" / "launch" / "inner.launch"
    assert roslaunch("--find-node", "/inner_node").strip() == str(inner)
    assert roslaunch("--files").split() == [str(ros1.root / "views.launch"), str(inner)]
    dumped = yaml.safe_load(roslaunch("--dump-params"))
    assert dumped == {"/top": 4, "/fleet/driver/gain": 2, "/inner_node/later": 9,
                      "/toucher/later": 9, "/set_inside": 7, "/rosdistro": "noetic\n",
                      "/rosversion": "1.16.0\n"}
    assert (ros1.root / "ran.param").exists()  # command= ran, as roslaunch runs it to load
    assert not marker.exists()  # no node started
    wrong = ros1.run("roslaunch", "--args", "/drivr", "views.launch")
    assert wrong.returncode == 1 and "Traceback" not in wrong.stderr
    assert "Cannot find node named [/drivr] (did you mean '/fleet/driver'?)" in wrong.stderr


def test_roslaunch_runs_several_files_as_one_launch(ros1):
    """rlutil.resolve_launch_arguments: when the first word is a file, every word is one, and
    roslaunch loads them all into one launch, each file with its own args (the command line's
    given to all)."""
    for name, node in (("one", "first"), ("two", "second")):
        ros1.write(f"{name}.launch", f"""<launch>
  <arg name="shared"/>
  <arg name="word" default="{name}"/>
  <node name="{node}" pkg="tools" type="report" output="screen"
        args="$(arg word) $(arg shared)"/>
</launch>
""")
    done = ros1.run("roslaunch", "one.launch", "two.launch", "shared:=both", timeout=60)
    assert done.returncode == 0, done.stdout + done.stderr
    got = {}
    for line in done.stdout.splitlines():
        if "REPORT " in line:
            report = eval(line.split("REPORT ", 1)[1])  # noqa: S307 - our own node's repr
            got[report["node"]] = report["args"]
    assert got == {"/first": ["one", "both"], "/second": ["two", "both"]}
    listed = ros1.run("roslaunch", "--nodes", "one.launch", "two.launch", "shared:=x")
    assert listed.stdout.split() == ["/first", "/second"], listed.stderr
    missing = ros1.run("roslaunch", "one.launch", "three.launch")
    assert missing.returncode == 1 and "Traceback" not in missing.stderr
    assert "RLException: [three.launch] is not a launch file name" in missing.stderr


def test_a_fresh_graph_holds_what_a_fresh_master_holds(ros1):
    """A ROS 1 master holds /run_id, /rosdistro and /rosversion from its start: `rosparam
    get /` prints them on a graph nothing has used yet."""
    got = ros1.run("rosparam", "get", "/", timeout=60)
    assert got.returncode == 0, got.stderr
    tree = yaml.safe_load(got.stdout)
    assert set(tree) == {"run_id", "rosdistro", "rosversion"}, got.stdout
    assert tree["rosdistro"] == "noetic\n"


SETS = '<launch><param name="left_behind" value="1"/></launch>\n'


def test_a_launchs_parameters_end_with_the_graph_it_started(ros1):
    """roslaunch's own master ends with it, and its parameters go: whatever asks right
    after finds none of them (the graph's router lingers, its parameters do not)."""
    ros1.write("sets.launch", SETS)
    for _ in range(3):
        assert ros1.run("launch", "sets.launch", timeout=60).returncode == 0
        got = ros1.run("rosparam", "get", "/left_behind", timeout=60)
        assert got.returncode == 1 and "Parameter [/left_behind] is not set" in got.stderr, \
            got.stdout + got.stderr


def test_a_roscores_parameters_stay_for_the_next_launch(ros1):
    """A master the user started with roscore keeps what a launch set, for the next one."""
    core = ros1.start("roscore", output="core.out")
    try:
        ros1.wait_for_output("setting /run_id", 30, "core.out")
        ros1.write("sets.launch", SETS)
        assert ros1.run("launch", "sets.launch", timeout=60).returncode == 0
        got = ros1.run("rosparam", "get", "/left_behind", timeout=60)
        assert got.stdout.strip() == "1", got.stdout + got.stderr
    finally:
        core.send_signal(signal.SIGINT)
        assert core.wait(30) == 0
