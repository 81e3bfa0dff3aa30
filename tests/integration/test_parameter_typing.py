"""Parameters reach a real rclpy node typed as launch_ros types them.

Each expectation below is written down from launch_ros's rules (launch_ros 0.28 /
launch 3.7: `Node.parse_nested_parameters`, `ParameterValue`, `perform_typed_substitution`,
launch_xml's `get_attr` with `value-sep`): a YAML value keeps the type YAML gave it (a quoted
'42' is a string), XML text and substitution results are read by YAML's rules, `type:`
converts. Where launcher does better than launch_ros, the test says so.
"""

from __future__ import annotations

import pytest

from tests.support.packages import make_tree, manifest

# A real rclpy node (launcher's) that lists the parameters it was given: name, type, value.
LIST_NODE = """
import rclpy
from rclpy.node import Node

def main():
    rclpy.init()
    node = Node("lister", automatically_declare_parameters_from_overrides=True)
    for name, parameter in sorted(node.get_parameters_by_prefix("").items()):
        print("PARAM", name, parameter.type_.name, repr(parameter.value), flush=True)
    node.destroy_node()
    rclpy.shutdown()
"""
URDF = '<?xml version="1.0"?>\n<robot name="r">\n  <link name="base"/>\n</robot>\n'


@pytest.fixture
def workspace(ws):
    make_tree(ws.root / "src", {
        "typed/package.xml": manifest("typed", extra=(
            '<export><executable name="lister" module="typed_app.lister:main"/></export>')),
        "typed/typed_app/__init__.py": "",
        "typed/typed_app/lister.py": LIST_NODE,
        "typed/config/robot.urdf": URDF,
        "typed/config/substituted.yaml":
            "/**:\n  ros__parameters:\n    from_file: $(var speed)\n    who: '$(var who)'\n",
    })
    ws.env["LAUNCHER_PACKAGE_PATH"] = str(ws.root / "src")
    ws.env["LAUNCHER_CACHE_DIR"] = str(ws.root / "cache")
    return ws


def received(workspace, name: str, *args: str) -> dict[str, tuple[str, str]]:
    result = workspace.run("launch", name, *args)
    assert result.returncode == 0, result.stdout + result.stderr
    out = {}
    for line in result.stdout.splitlines():
        if "PARAM " in line:
            parameter, kind, value = line.split("PARAM ", 1)[1].split(" ", 2)
            out[parameter] = (kind, value)
    return out


YAML_CASES = {
    # name: (value as written in YAML, type or None) → (rclpy type, repr of the value)
    "integer": ("42", None, ("INTEGER", "42")),
    "quoted_integer": ("'42'", None, ("STRING", "'42'")),
    "quoted_list": ("'[1, 2]'", None, ("STRING", "'[1, 2]'")),
    "quoted_true": ("'True'", None, ("STRING", "'True'")),
    "quoted_quotes": ('"\'quoted\'"', None, ("STRING", '"\'quoted\'"')),
    "plain_text": ("hello", None, ("STRING", "'hello'")),
    "boolean": ("true", None, ("BOOL", "True")),
    "double": ("2.5", None, ("DOUBLE", "2.5")),
    "int_list": ("[1, 2]", None, ("INTEGER_ARRAY", "[1, 2]")),
    "mixed_numbers": ("[1.5, 2]", None, ("DOUBLE_ARRAY", "[1.5, 2.0]")),
    "text_list": ("[a, b]", None, ("STRING_ARRAY", "['a', 'b']")),
    "substituted": ("$(var count)", None, ("INTEGER", "7")),  # YAML's rules on the result
    "substituted_twice": ("$(var count)$(var count)", None, ("INTEGER", "77")),
    "substituted_quotes": ('"$(var quoted)"', None, ("STRING", "'7'")),
    "as_str": ("$(var count)", "str", ("STRING", "'7'")),
    "as_float": ("$(var count)", "float", ("DOUBLE", "7.0")),
    "as_list": ("'[1, 2]'", "list_of_int", ("INTEGER_ARRAY", "[1, 2]")),
    # launch_ros refuses these two (its check wants a str for type str, a float for float);
    # launcher converts what was written
    "number_as_str": ("42", "str", ("STRING", "'42'")),
    "ints_as_floats": ("'[1, 2]'", "list_of_float", ("DOUBLE_ARRAY", "[1.0, 2.0]")),
}


def test_yaml_parameters_typed_as_launch_ros_types_them(workspace):
    entries = "\n".join(
        f"            - {{name: {name}, value: {text}" + (f", type: {kind}}}" if kind else "}")
        for name, (text, kind, _) in YAML_CASES.items())
    workspace.write("typed.launch.yaml", f"""
    launch:
      - arg: {{name: count, default: "7"}}
      - arg: {{name: quoted, default: "'7'"}}
      - set_parameter: {{name: global_text, value: "5"}}
      - node:
          pkg: typed
          exec: lister
          output: screen
          param:
{entries}
            - name: nested
              param:
                - {{name: leaf, value: 1}}
            - name: robot_description
              value: $(command 'cat $(find-pkg-share typed)/config/robot.urdf')
    """)
    got = received(workspace, "typed.launch.yaml")
    for name, (_, _, expected) in YAML_CASES.items():
        assert got.get(name) == expected, (name, got.get(name))
    assert got["nested.leaf"] == ("INTEGER", "1")
    # set_parameter is `-p global_text:=5` on the node's command line, as launch_ros writes
    # it: the node reads 5 by YAML's rules
    assert got["global_text"] == ("INTEGER", "5")
    # a robot description keeps its lines (launch_ros would read it by YAML's rules)
    assert got["robot_description"] == ("STRING", repr(URDF))


XML_CASES = {
    # name: attributes → (rclpy type, repr of the value)
    "integer": ('value="42"', ("INTEGER", "42")),
    "quoted": ('value="\'42\'"', ("STRING", "'42'")),
    "true_text": ('value="True"', ("BOOL", "True")),
    "list_text": ('value="[1, 2]"', ("INTEGER_ARRAY", "[1, 2]")),
    "plain_text": ('value="hello"', ("STRING", "'hello'")),
    "double": ('value="1.0"', ("DOUBLE", "1.0")),
    "as_str": ('type="str" value="42"', ("STRING", "'42'")),
    "bool_one": ('type="bool" value="1"', ("BOOL", "True")),
    "separated": ('value="1,2,3" value-sep=","', ("INTEGER_ARRAY", "[1, 2, 3]")),
    "separated_text": ('value="a;b" value-sep=";"', ("STRING_ARRAY", "['a', 'b']")),
    "separated_as_str": ('type="list_of_str" value="1,2" value-sep=","',
                         ("STRING_ARRAY", "['1', '2']")),
    "substituted": ('value="$(var count)"', ("INTEGER", "7")),
}


def test_xml_parameters_typed_as_launch_ros_types_them(workspace):
    entries = "\n".join(f'    <param name="{name}" {attrs}/>'
                        for name, (attrs, _) in XML_CASES.items())
    workspace.write("typed.launch.xml", f"""<launch>
  <arg name="count" default="7"/>
  <node pkg="typed" exec="lister" output="screen">
{entries}
    <param name="robot_description"
           value="$(command 'cat $(find-pkg-share typed)/config/robot.urdf')"/>
  </node>
</launch>
""")
    got = received(workspace, "typed.launch.xml")
    for name, (_, expected) in XML_CASES.items():
        assert got.get(name) == expected, (name, got.get(name))
    assert got["robot_description"] == ("STRING", repr(URDF))


def test_params_file_with_allow_substs_and_set_use_sim_time(workspace):
    workspace.write("subst.launch.yaml", """
    launch:
      - arg: {name: speed, default: "2.5"}
      - arg: {name: who, default: "42"}
      - set_use_sim_time: {value: true}
      - node:
          pkg: typed
          exec: lister
          output: screen
          param:
            - {from: $(find-pkg-share typed)/config/substituted.yaml, allow_substs: true}
    """)
    got = received(workspace, "subst.launch.yaml", "speed:=3.5")
    assert got["from_file"] == ("DOUBLE", "3.5") and got["who"] == ("STRING", "'42'")
    assert got["use_sim_time"] == ("BOOL", "True")


@pytest.mark.parametrize("body, message", [
    ("- {name: a, value: [1, x]}", "the list mixes int, str"),
    ("- {name: a, value: x, type: int}", "param 'a': 'x' is not an int"),
    ("- {name: a, value: maybe, type: bool}", "'maybe' is not a bool"),
    ("- {name: a, value: '{b: 1}'}", None),  # quoted: the string '{b: 1}', fine
    ("- {name: a, value: $(var m)}", "is a YAML map"),
    ("- {name: a, value: 1, type: integer}", "expected one of str, int"),
    ("- {name: a, value: [1, 2], type: int}", "type int takes one value, got a list"),
    ("- {from: $(find-pkg-share typed)/config/robot.urdf, allow_substs: true, name: x}",
     "give either 'name' or 'from'"),
    ("- {name: a, value: 1, allow_substs: true}", "'allow_substs' goes with 'from'"),
    ("- {name: a, value: 1, param: [{name: b, value: 2}]}", "give either 'value' or nested"),
], ids=["mixed-list", "not-int", "not-bool", "quoted-map-ok", "map", "unknown-type",
        "list-for-scalar", "name-and-from", "allow-substs-alone", "value-and-nested"])
def test_bad_parameters_are_clear_errors(workspace, body, message):
    workspace.write("bad.launch.yaml", f"""
    launch:
      - arg: {{name: m, default: "{{b: 1}}"}}
      - node:
          pkg: typed
          exec: lister
          output: screen
          param:
            {body}
    """)
    result = workspace.run("launch", "bad.launch.yaml")
    said = result.stdout + result.stderr
    if message is None:
        assert result.returncode == 0, said
        assert "PARAM a STRING '{b: 1}'" in result.stdout
        return
    assert result.returncode == 1
    # said at the param entry (line 8 of the file), as the launch's other errors are
    assert message in said and "bad.launch.yaml:8:" in said, said
    assert "Traceback" not in said


def test_python_launch_file_parameters(workspace):
    """launch_ros's Python API: a str stays a str, a substitution is read by YAML's rules,
    ParameterValue's value_type converts, a dict's nesting makes dotted names."""
    workspace.write("typed.launch.py", """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("count", default_value="7"),
        Node(package="typed", executable="lister", output="screen", parameters=[
            {"text": "42", "number": 42, "flag": False, "ratios": [1, 2.5],
             "names": ["a", "b"], "limits": {"max": 1.5},
             "counted": LaunchConfiguration("count"),
             "counted_text": ParameterValue(LaunchConfiguration("count"), value_type=str)},
        ]),
    ])
""")
    got = received(workspace, "typed.launch.py")
    assert got["text"] == ("STRING", "'42'") and got["number"] == ("INTEGER", "42")
    assert got["flag"] == ("BOOL", "False") and got["ratios"] == ("DOUBLE_ARRAY", "[1.0, 2.5]")
    assert got["names"] == ("STRING_ARRAY", "['a', 'b']")
    assert got["limits.max"] == ("DOUBLE", "1.5")
    assert got["counted"] == ("INTEGER", "7") and got["counted_text"] == ("STRING", "'7'")
