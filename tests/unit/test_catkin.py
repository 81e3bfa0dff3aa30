"""catkin_make's reading of a catkin package: its C++ targets (with their lines, in the
course's one-line CMakeLists.txt too), its Python scripts, and the devel setup file."""

from __future__ import annotations

import os
import subprocess

import pytest

from launcher.packages import catkin
from launcher.packages.manifest import Package

CMAKE = """cmake_minimum_required(VERSION 3.0.2)
project(nodes)
find_package(catkin REQUIRED COMPONENTS rospy)
catkin_package()
add_library(plugin SHARED src/plugin.cc) add_executable(node src/node.cpp)
add_library(headers INTERFACE)
catkin_install_python(PROGRAMS nodes/driver.py bin/tool
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
"""


@pytest.fixture
def package(tmp_path):
    (tmp_path / "CMakeLists.txt").write_text(CMAKE)
    for name in ("scripts/a.py", "nodes/driver.py", "bin/tool"):
        path = tmp_path / name
        path.parent.mkdir(exist_ok=True)
        path.write_text("#!/usr/bin/env python3\n")
        path.chmod(0o644)
    return Package(name="nodes", path=tmp_path)


def test_cxx_targets_with_their_lines(package):
    found = [(where.line, command, target) for where, command, target in
             catkin.cxx_targets(package)]
    assert found == [(5, "add_library", "plugin"), (5, "add_executable", "node")]


def test_python_scripts_are_made_runnable_once(package):
    scripts = catkin.python_scripts(package)
    assert [p.relative_to(package.path).as_posix() for p in scripts] == \
        ["scripts/a.py", "nodes/driver.py", "bin/tool"]
    assert catkin.make_runnable(scripts[0]) and os.access(scripts[0], os.X_OK)
    assert not catkin.make_runnable(scripts[0])


def test_a_workspace_without_src_is_catkin_makes_error(tmp_path):
    with pytest.raises(catkin.CatkinError, match='source space ".*/src" does not exist'):
        catkin.check_source(tmp_path)


def test_the_devel_setup_puts_the_packages_on_the_paths_once(tmp_path):
    devel = catkin.write_devel(tmp_path, "/opt/launcher/bin")
    done = subprocess.run(["sh", "-c", f". {devel}/setup.sh; . {devel}/setup.sh; "
                                       "echo $ROS_PACKAGE_PATH; echo $LAUNCHER_PACKAGE_PATH; "
                                       "echo $PATH"],
                          env={"PATH": "/usr/bin:/bin", "ROS_PACKAGE_PATH": "/other"},
                          capture_output=True, text=True)
    ros, ours, path = done.stdout.splitlines()
    assert ros == f"{tmp_path / 'src'}:/other"
    assert ours == str(tmp_path / "src")
    assert path == "/usr/bin:/bin:/opt/launcher/bin"
