"""YAML and XML parse into the same actions; bad input names file:line:col and what to do."""

import pytest

from launcher.description.actions.executable import ExecuteProcess
from launcher.errors import ParseError
from tests.support.fake_service import run
from tests.support.launch_text import xml_description, yaml_description

YAML = """
launch:
  - arg: {name: world, default: robot.xml, description: the world}
  - executable:
      cmd: /bin/echo -v 4 -r $(var world)
      respawn: true
      sigterm_timeout: 2
      env:
        - {name: A, value: "1"}
  - group:
      - let: {name: inner, value: x}
"""

XML = """
<launch>
  <arg name="world" default="robot.xml" description="the world"/>
  <executable cmd="/bin/echo -v 4 -r $(var world)" respawn="true" sigterm_timeout="2">
    <env name="A" value="1"/>
  </executable>
  <group><let name="inner" value="x"/></group>
</launch>
"""


@pytest.mark.parametrize("make, text", [(yaml_description, YAML), (xml_description, XML)],
                         ids=["yaml", "xml"])
def test_yaml_and_xml_give_the_same_actions(make, text):
    description = make(text)
    arg, executable, group = description.actions
    assert arg.name == "world" and arg.description == "the world"
    assert isinstance(executable, ExecuteProcess)
    assert executable.respawn is True and executable.sigterm_timeout == 2.0
    assert len(executable.additional_env) == 1
    context, service = run(description)
    (spec,) = service.specs
    assert spec.argv == ["/bin/echo", "-v", "4", "-r", "robot.xml"]
    assert spec.env["A"] == "1" and spec.respawn and spec.sigterm_timeout == 2.0
    assert "inner" not in context.configurations  # the group scoped it


def test_yaml_leniency_for_numbers_and_booleans():
    description = yaml_description("""
    launch:
      - timer: {period: 5, children: [{log: {message: hi}}]}
      - executable: {cmd: x, respawn: "True", respawn_delay: "0.5", sigkill_timeout: 3}
    """)
    timer, executable = description.actions
    assert timer.period == 5.0
    assert executable.respawn is True and executable.respawn_delay == 0.5


def error_of(make, text):
    with pytest.raises(ParseError) as info:
        make(text)
    return str(info.value)


@pytest.mark.parametrize("text, expected", [
    ("launch: [\n  - arg: {name: x\n", "test.launch.yaml:2:3: malformed YAML"),
    ("robot:\n  - arg: {name: x}\n", "test.launch.yaml:1:1: the root key is 'robot'; expected 'launch'"),
    ("launch:\n  - arg: {name: x}\n    let: {name: y}\n", "test.launch.yaml:2:5: each list item must be a map with exactly one key"),
    ("launch:\n  - exectuable: {cmd: ls}\n", "test.launch.yaml:2:5: unknown tag 'exectuable' (did you mean 'executable'?)"),
    ("launch:\n  - executable: {cmd: ls, respwan: true}\n", "test.launch.yaml:2:27: 'executable' has no attribute 'respwan' (did you mean 'respawn'"),
    ("launch:\n  - executable: {output: screen}\n", "test.launch.yaml:2:5: 'executable' needs the attribute 'cmd'"),
    ("launch:\n  - executable: {cmd: ls, respawn_delay: soon}\n", "test.launch.yaml:2:42: executable.respawn_delay: expected a number, got 'soon'"),
    ("launch:\n  - executable: {cmd: ls, sigterm_timeout: -1}\n", "test.launch.yaml:2:44: executable.sigterm_timeout: expected a number ≥ 0, got -1"),
    ("launch:\n  - log: {message: hi, if: 'true', unless: 'false'}\n", "test.launch.yaml:2:36: 'log' has both 'if' and 'unless'"),
    ("launch:\n  - log: {message: hi, if: maybe}\n", "test.launch.yaml:2:28: if: expected true, false, 1 or 0, got 'maybe'"),
    ("launch:\n  - log: {message: $(vr x)}\n", "test.launch.yaml:2:20: unknown substitution '$(vr)' (did you mean 'var'?)"),
    ("launch:\n  - log: {message: 'a $(var x'}\n", "test.launch.yaml:2:23: unclosed '$(var': expected ')'"),
    ("launch:\n  - executable: {cmd: ls, output: loud}\n", "test.launch.yaml:2:35: executable.output: expected one of screen, log, both, own_log, full, got 'loud'"),
    ("launch:\n  - executable: {cmd: ls, on_exit: restart}\n", "test.launch.yaml:2:5: executable: on_exit: expected 'shutdown' or a list of actions"),
    ("launch:\n  - executable:\n      cmd: ls\n      env: [{name: A, vlaue: b}]\n", "test.launch.yaml:4:23: executable.env: unknown key 'vlaue' (did you mean 'value'?)"),
], ids=["malformed", "root", "two-keys", "unknown-tag", "unknown-attr", "missing-attr",
        "wrong-type", "negative-timeout", "if-and-unless", "bad-condition",
        "unknown-substitution", "unclosed-substitution", "bad-choice", "bad-on-exit",
        "bad-entry-key"])
def test_yaml_errors(text, expected):
    assert error_of(yaml_description, text).startswith(expected)


@pytest.mark.parametrize("text, expected", [
    ("<launch><arg name='x'>", "test.launch.xml:1:23: malformed XML"),
    ("<robot/>", "test.launch.xml:1:1: the root element is <robot>; expected <launch>"),
    ("<launch>\n  <exectuable cmd='ls'/>\n</launch>", "test.launch.xml:2:3: unknown tag 'exectuable' (did you mean 'executable'?)"),
    ("<launch>\n  <executable cmd='ls' shel='true'/>\n</launch>", "test.launch.xml:2:3: 'executable' has no attribute 'shel' (did you mean 'shell'?)"),
    ("<launch>\n  <executable cmd='ls'><log message='x'/></executable>\n</launch>", "test.launch.xml:2:24: 'executable' takes no child tag 'log'"),
], ids=["malformed", "root", "unknown-tag", "unknown-attr", "unexpected-child"])
def test_xml_errors(text, expected):
    assert error_of(xml_description, text).startswith(expected)


def test_on_exit_children_in_xml_and_yaml():
    xml = xml_description("""
    <launch><executable cmd="true"><on_exit><log message="bye"/></on_exit></executable></launch>
    """)
    yml = yaml_description("""
    launch:
      - executable: {cmd: "true", on_exit: [{log: {message: bye}}]}
    """)
    for description in (xml, yml):
        (executable,) = description.actions
        (log,) = executable.on_exit
        assert log.tags == ("log",)


def test_node_parameters_nest_in_xml_and_yaml():
    from launcher.description.actions.param_entry import ParamEntry

    xml = xml_description("""
    <launch>
      <node pkg="p" exec="e">
        <param name="limits"><param name="max" value="1.5"/><param name="min" value="0"/></param>
        <param from="file.yaml"/>
        <remap from="a" to="b"/>
      </node>
    </launch>
    """)
    yml = yaml_description("""
    launch:
      - node:
          pkg: p
          exec: e
          param:
            - {name: limits, param: [{name: max, value: "1.5"}, {name: min, value: "0"}]}
            - {from: file.yaml}
          remap: [{from: a, to: b}]
    """)
    for description in (xml, yml):
        (node,) = description.actions
        limits, from_file = node.parameters
        assert isinstance(limits, ParamEntry) and len(limits.children) == 2
        assert from_file.from_file is not None and len(node.remappings) == 1


def test_node_container_and_load_composable_node_in_xml_and_yaml():
    from launcher.description.actions.composition import LoadComposableNodes, NodeContainer

    xml = xml_description("""
    <launch>
      <node_container pkg="rclcpp_components" exec="component_container" name="box"
                      namespace="r1">
        <composable_node pkg="p" plugin="p::A" name="a" namespace="ns">
          <param name="speed" value="1.5"/>
          <remap from="x" to="y"/>
          <extra_arg name="use_intra_process_comms" value="true"/>
        </composable_node>
      </node_container>
      <load_composable_node target="/r1/box">
        <composable_node pkg="p" plugin="p::B"/>
      </load_composable_node>
    </launch>
    """)
    yml = yaml_description("""
    launch:
      - node_container:
          pkg: rclcpp_components
          exec: component_container
          name: box
          namespace: r1
          composable_node:
            - pkg: p
              plugin: p::A
              name: a
              namespace: ns
              param: [{name: speed, value: "1.5"}]
              remap: [{from: x, to: y}]
              extra_arg: [{name: use_intra_process_comms, value: "true"}]
      - load_composable_node:
          target: /r1/box
          composable_node: [{pkg: p, plugin: p::B}]
    """)
    for description in (xml, yml):
        box, load = description.actions
        assert isinstance(box, NodeContainer) and isinstance(load, LoadComposableNodes)
        (first,) = box.composable_nodes
        assert len(first.parameters) == len(first.remappings) == 1
        assert len(first.extra_arguments) == 1
        assert first.where is not None and first.where.line > 1  # errors point at the entry
        assert len(load.composable_nodes) == 1


@pytest.mark.parametrize("text, expected", [
    ("launch:\n  - node_container: {pkg: p, exec: e, name: b, composable_node: [{pkg: p}]}\n",
     "test.launch.yaml:2:66: node_container.composable_node: each entry needs 'plugin'"),
    ("launch:\n  - load_composable_node: {composable_node: []}\n",
     "'load_composable_node' needs the attribute 'target'"),
    ("launch:\n  - load_composable_node: {target: b, composable_node: [{pkg: p, plugin: q,"
     " nmae: x}]}\n", "unknown key 'nmae' (did you mean 'name'?)"),
])
def test_composition_errors(text, expected):
    with pytest.raises(ParseError, match=expected.replace("(", "\\(").replace(")", "\\)")
                       .replace("?", "\\?")):
        yaml_description(text)


def test_a_composable_nodes_condition_in_python_as_launch_ros_takes_it():
    from launcher.api import ComposableNode, IfCondition, LaunchConfiguration, UnlessCondition
    from launcher.description.actions.composition import _requests
    from launcher.runtime.context import LaunchContext

    context = LaunchContext({}, {"on": "true"})
    nodes = [ComposableNode(package="p", plugin="p::A", name="a",
                            condition=IfCondition(LaunchConfiguration("on"))),
             ComposableNode(package="p", plugin="p::B", name="b",
                            condition=UnlessCondition(LaunchConfiguration("on"))),
             ComposableNode(package="p", plugin="p::C", name="c")]
    assert [r.node_name for r in _requests(context, nodes, None)] == ["a", "c"]
    with pytest.raises(TypeError, match="expected IfCondition"):
        ComposableNode(package="p", plugin="p::A", condition=True)
