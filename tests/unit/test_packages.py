"""package.xml, the index's search order, executables."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from launcher.errors import LaunchError, ParseError
from launcher.packages.components import components
from launcher.packages.executables import executables, find_executable
from launcher.packages.index import PackageIndex, PackageNotFound
from launcher.packages.manifest import read_manifest
from tests.support.packages import index_for, make_tree, manifest


def test_manifest_fields(tmp_path):
    make_tree(tmp_path, {"p/package.xml": manifest("robot_sim", ("robot_description",),
                                                   "<export><build_type>ament_cmake</build_type>"
                                                   "</export>")})
    package = read_manifest(tmp_path / "p/package.xml")
    assert package.name == "robot_sim" and package.version == "1.2.3"
    assert package.dependencies == {"depend": ["robot_description"]}
    assert package.exports["build_type"][0]["text"] == "ament_cmake"
    assert package.run_dependencies() == {"robot_description"}


@pytest.mark.parametrize("text, expected", [
    ("<package><name>x</name>", "package.xml:1:24: malformed package.xml: no element found"),
    ("<package format='3'>\n  <version>1</version>\n</package>", "package.xml:1: package.xml has no <name>"),
    ("<package>\n  <name>Robot-Sim</name>\n</package>", "package.xml:2: invalid package name 'Robot-Sim'"),
], ids=["malformed", "no-name", "invalid-name"])
def test_bad_manifests(tmp_path, text, expected):
    (tmp_path / "package.xml").write_text(text)
    with pytest.raises(ParseError) as info:
        read_manifest(tmp_path / "package.xml")
    assert expected in str(info.value) and "line 1, column" not in str(info.value)


def test_search_order_ignore_markers_and_duplicates(tmp_path):
    first = make_tree(tmp_path / "ws1", {
        "src/a/package.xml": manifest("alpha"),
        "src/deep/er/b/package.xml": manifest("beta"),
        "src/ignored/COLCON_IGNORE": "",
        "src/ignored/c/package.xml": manifest("gamma"),
        "src/.hidden/d/package.xml": manifest("delta"),
    })
    second = make_tree(tmp_path / "ws2", {"alpha/package.xml": manifest("alpha"),
                                          "e/package.xml": manifest("epsilon")})
    index = index_for(first, second, tmp=tmp_path)
    assert {"alpha", "beta", "epsilon", "mujoco_sim", "mujoco_bridge",
            "robot_state_publisher"} <= set(index.packages)
    assert "gamma" not in index and "delta" not in index
    assert index.share("alpha") == first / "src/a"
    (warning,) = index.warnings
    assert "package 'alpha' is found twice" in warning and str(second / "alpha") in warning
    assert index.get("mujoco_sim").origin == "builtin"


COMPILED = "<export><build_type>ament_cmake</build_type></export>"


@pytest.mark.parametrize("name, files, stood_in", [
    ("robot_state_publisher", {"package.xml": manifest("robot_state_publisher", extra=COMPILED)},
     True),
    ("robot_state_publisher", {"package.xml": manifest("robot_state_publisher"),
                               "CMakeLists.txt": "project(robot_state_publisher)\n"}, True),
    ("robot_state_publisher", {"package.xml": manifest("robot_state_publisher", extra=(
        "<export><build_type>ament_python</build_type></export>"))}, False),
    ("std_srvs", {"package.xml": manifest("std_srvs", extra=COMPILED)}, False),
], ids=["ament_cmake", "cmakelists-only", "ament_python-is-the-users", "messages-read-as-written"])
def test_a_compiled_package_found_only_as_source_runs_the_builtin(tmp_path, name, files,
                                                                  stood_in):
    ws = make_tree(tmp_path / "src", {f"{name}/{path}": text for path, text in files.items()})
    index = index_for(ws, tmp=tmp_path)
    package = index.get(name)
    assert package.path == ws / name  # its share: the source, as it is
    if stood_in:
        assert index.notices == [f"package '{name}' at {ws / name} is source only (a compiled "
                                 "ament_cmake package, never built): launcher runs its own "
                                 "implementation of it"] and not index.warnings
        assert find_executable(package, name).argv[-1] == \
            "launcher.nodes.robot_state_publisher:main"
        assert "robot_state_publisher::RobotStatePublisher" in components(package)
    else:
        assert not index.notices and "is found twice" in index.warnings[0]
        assert name not in executables(package)


def test_not_found_lists_places_and_close_names(tmp_path):
    index = index_for(make_tree(tmp_path / "ws", {"a/package.xml": manifest("robot_sim")}))
    with pytest.raises(PackageNotFound) as info:
        index.get("robot_sm")
    text = str(info.value)
    assert "package 'robot_sm' not found (did you mean 'robot_sim'?); searched:" in text
    assert f"{tmp_path / 'ws'} (workspace)" in text and "(builtin)" in text


def test_prefix_is_a_link_farm_into_the_package(tmp_path):
    ws = make_tree(tmp_path / "ws", {"a/package.xml": manifest("robot_sim"),
                                     "a/worlds/w.xml": "<mujoco/>"})
    index = index_for(ws, tmp=tmp_path)
    prefix = index.prefix("robot_sim")
    assert (prefix / "share" / "robot_sim" / "worlds" / "w.xml").read_text() == "<mujoco/>"


def test_ament_prefixes(tmp_path):
    prefix = make_tree(tmp_path / "install", {
        "share/ament_index/resource_index/packages/ros_thing": "",
        "share/ros_thing/package.xml": manifest("ros_thing"),
    })
    index = index_for(tmp_path / "nothing", ament=str(prefix), tmp=tmp_path)
    assert index.share("ros_thing") == prefix / "share/ros_thing"
    assert index.prefix("ros_thing") == prefix


def test_an_installs_executables_are_found_where_ros2_puts_them(tmp_path):
    """`<prefix>/lib/<pkg>/<exe>`, as colcon installs a ROS 2 package's executables."""
    prefix = make_tree(tmp_path / "install", {
        "share/ament_index/resource_index/packages/ros_thing": "",
        "share/ros_thing/package.xml": manifest("ros_thing"),
        "lib/ros_thing/talker": "#!/bin/sh\necho talking\n",
        "lib/ros_thing/listener.py": "#!/usr/bin/env python3\nprint('listening')\n",
    }, executable=("lib/ros_thing/talker", "lib/ros_thing/listener.py"))
    index = index_for(tmp_path / "nothing", ament=str(prefix), tmp=tmp_path)
    talker = find_executable(index.get("ros_thing"), "talker")
    assert talker.argv == (str(prefix / "lib/ros_thing/talker"),)
    listener = find_executable(index.get("ros_thing"), "listener.py")
    assert listener.argv[-1] == str(prefix / "lib/ros_thing/listener.py")


def test_executables_files_and_entry_points(tmp_path):
    ws = make_tree(tmp_path / "ws", {
        "app/package.xml": manifest("app", extra='<export><executable name="driver" '
                                                 'module="app_py.driver:main"/></export>'),
        "app/scripts/tool.sh": "#!/bin/sh\necho tool\n",
        "app/scripts/notexec.sh": "echo 1\n",
        "app/scripts/plain.py": "print(1)\n",
        "app/scripts/ros1.py": "#!/usr/bin/env python \nimport rospy\n",
        "app/scripts/py3": "#!/usr/bin/env python3\nprint(3)\n",
        "app/setup.cfg": "[options.entry_points]\nconsole_scripts =\n    square = app_py.sq:main\n",
    }, executable=("app/scripts/tool.sh", "app/scripts/ros1.py", "app/scripts/py3"))
    package = index_for(ws).get("app")
    found = executables(package)
    assert set(found) == {"tool.sh", "notexec.sh", "plain.py", "ros1.py", "py3", "driver",
                          "square"}
    # Python scripts without a usable #! line, or with ROS 1's `python`, run with launcher's
    # interpreter (executable bit or not); a python3 script runs as the system runs it
    assert found["plain.py"].argv == (sys.executable, str(package.path / "scripts/plain.py"))
    assert found["ros1.py"].argv == (sys.executable, str(package.path / "scripts/ros1.py"))
    assert found["py3"].argv == (str(package.path / "scripts/py3"),)
    assert found["driver"].argv[1:] == ("-m", "launcher.packages.entry", "app_py.driver:main")
    assert found["driver"].environment({})["PYTHONPATH"] == str(package.path)
    with pytest.raises(LaunchError, match="has no executable 'drivr' \\(did you mean 'driver'"
                                          "\\?\\); it has: driver, notexec.sh, plain.py, py3, ros1.py, "
                                          "square, tool.sh"):
        find_executable(package, "drivr")
    with pytest.raises(LaunchError, match="notexec.sh' in package 'app' is not executable; make "
                                          "it so with: chmod \\+x"):
        find_executable(package, "notexec.sh")


def test_xacro_in_process_finds_packages_in_the_index_given_and_leaves_nothing_behind(tmp_path):
    from xacro import substitution_args

    from launcher.packages.xacro import run_xacro

    ws = make_tree(tmp_path / "ws", {
        "desc/package.xml": manifest("desc"),
        "desc/urdf/part.xacro": '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">'
                                '<link name="wheel"/></robot>',
        "desc/urdf/robot.xacro": '<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                                 '<xacro:include filename="$(find desc)/urdf/part.xacro"/>'
                                 '<link name="base"/></robot>'})
    index = index_for(ws, tmp=tmp_path)
    before = substitution_args._eval_find
    out = run_xacro(["xacro", str(ws / "desc" / "urdf" / "robot.xacro")], index)
    assert '<link name="wheel"/>' in out and '<link name="base"/>' in out
    assert substitution_args._eval_find is before  # the resolver was for that call only


def test_components_from_package_xml_setup_cfg_and_setup_py(tmp_path):
    from launcher.packages.components import components, find_component

    ws = make_tree(tmp_path / "ws", {
        "app/package.xml": manifest("app", extra='<export><component plugin="app::Driver" '
                                                 'module="app_py.driver:Driver"/></export>'),
        "app/setup.cfg": "[options.entry_points]\nrclpy_components =\n"
                         "    app::Square = app_py.square:Square\n",
        "app/setup.py": "from setuptools import setup\nname = 'app'\nsetup(entry_points={"
                        "'rclpy_components': [name + '::Talker = app_py.talk:Talker']})\n",
    })
    package = index_for(ws).get("app")
    found = components(package)
    assert {k: v.target for k, v in found.items()} == {
        "app::Driver": "app_py.driver:Driver", "app::Square": "app_py.square:Square",
        "app::Talker": "app_py.talk:Talker"}
    assert found["app::Driver"].folder == str(package.path)
    with pytest.raises(LaunchError, match="package 'app' has no component 'app::Drivr' \\(did "
                                          "you mean 'app::Driver'\\?\\); it offers: app::Driver, "
                                          "app::Square, app::Talker"):
        find_component(package, "app::Drivr")


def test_the_builtin_nodes_are_components_too():
    from launcher.packages.components import components

    index = PackageIndex.from_environment({"LAUNCHER_PACKAGE_PATH": ""}, cwd=Path("/"))
    plugins = {name for package in index for name in components(package)}
    assert {"robot_state_publisher::RobotStatePublisher", "ros_gz_bridge::RosGzBridge",
            "ros_gz_sim::Create", "mujoco_sim::Create",
            "mujoco_bridge::ParameterBridge"} <= plugins
    executables_ = executables(index.get("rclcpp_components"))
    assert {"component_container", "component_container_mt",
            "component_container_isolated"} <= set(executables_)
