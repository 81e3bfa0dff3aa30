"""`colcon build` as ROS 2 users run it, with the real colcon and a real CMake from launcher's
build tools: the seed's two ament_cmake packages (their CMakeLists.txt, hooks and launch file
taken from the seed's text), an ament_python package with a console script, `--symlink-install`,
then `source install/setup.bash` and `ros2 launch`/`ros2 run` in a real bash; and the bad inputs,
each said with its file and line."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import time

import pytest

from tests.support.environment import REPO, shared

SETUP = REPO / "hooks" / "setup.bash"
SEED = ("seeds", "001_ea06ae6f7572c47f.txt")
MANIFEST = """<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.0.1</version>
  <description>{name}</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>{build}</buildtool_depend>
  <export>
    <build_type>{build}</build_type>
  </export>
</package>
"""
WORLD = """<?xml version="1.0"?>
<sdf version="1.9"><world name="seed_world">
  <model name="marker_box"><static>true</static><link name="l"><collision name="c"><geometry>
  <box><size>1 1 1</size></box></geometry></collision></link></model>
</world></sdf>
"""
BRINGUP_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(loc_bringup)

find_package(ament_cmake REQUIRED)
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""
SETUP_PY = """from setuptools import setup

package_name = 'py_nodes'
setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    entry_points={'console_scripts': ['hello = py_nodes.hello:main']},
)
"""


def seed_files() -> dict[str, str]:
    """The seed's loc_gazebo (CMakeLists.txt, both hooks) and loc_bringup's launch file, as
    the seed's text has them."""
    text = shared(*SEED).read_text(encoding="utf-8")
    start = text.index("cmake_minimum_required")
    cmake = text[start:text.index("ament_package()", start) + len("ament_package()")] + "\n"
    dsv = re.search(r"^loc_gazebo\.dsv\n(.+)\n", text, re.M).group(1)
    sh = re.search(r"^loc_gazebo\.sh\n(.+)\n", text, re.M).group(1)
    launch = text[text.index("import os\nfrom ament_index_python"):].rstrip("\n") + "\n"
    return {"loc_gazebo/CMakeLists.txt": cmake, "loc_gazebo/hooks/loc_gazebo.dsv.in": dsv + "\n",
            "loc_gazebo/hooks/loc_gazebo.sh.in": sh + "\n",
            "loc_bringup/launch/gazebo.launch.py": launch}


@pytest.fixture
def seed(ws):
    ws.own_bus()
    files = {**seed_files(),
             "loc_gazebo/package.xml": MANIFEST.format(name="loc_gazebo", build="ament_cmake"),
             "loc_gazebo/worlds/world.sdf": WORLD,
             "loc_bringup/package.xml": MANIFEST.format(name="loc_bringup",
                                                        build="ament_cmake"),
             "loc_bringup/CMakeLists.txt": BRINGUP_CMAKE,
             "py_nodes/package.xml": MANIFEST.format(name="py_nodes", build="ament_python"),
             "py_nodes/setup.py": SETUP_PY,
             "py_nodes/setup.cfg": "[develop]\nscript_dir=$base/lib/py_nodes\n[install]\n"
                                   "install_scripts=$base/lib/py_nodes\n",
             "py_nodes/resource/py_nodes": "",
             "py_nodes/py_nodes/__init__.py": "",
             "py_nodes/py_nodes/hello.py": "def main():\n    print('hello from py_nodes')\n"}
    for name, text in files.items():
        path = ws.root / "ws" / "src" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return ws


def bash(ws, script: str, timeout: float = 180) -> subprocess.CompletedProcess:
    return subprocess.run(["bash", "-c", f". {SETUP} && cd ws && {script}"], cwd=ws.root,
                          env=ws.env, capture_output=True, text=True, timeout=timeout)


def test_the_seeds_colcon_build_source_and_ros2_launch_sequence(seed):
    built = bash(seed, "colcon build && . install/setup.bash && echo \"GZ=$GZ_SIM_RESOURCE_PATH\""
                       " && ros2 pkg prefix loc_gazebo && ros2 run py_nodes hello")
    assert built.returncode == 0, built.stdout + built.stderr
    assert "Summary: 3 packages finished" in built.stdout, built.stdout
    install = seed.root / "ws" / "install"
    for name in ("build", "install", "log"):
        assert (seed.root / "ws" / name).is_dir()
    for name in ("setup.bash", "setup.sh", "setup.zsh", "local_setup.bash", "local_setup.sh"):
        assert (install / name).is_file(), name
    worlds = install / "loc_gazebo" / "share" / "loc_gazebo" / "worlds"
    assert str(worlds) in re.search(r"GZ=(.*)", built.stdout).group(1).split(os.pathsep)
    assert f"{install / 'loc_gazebo'}\n" in built.stdout  # found by launcher, as installed
    assert "hello from py_nodes" in built.stdout  # console_scripts in lib/<pkg>
    assert (install / "py_nodes" / "lib" / "py_nodes" / "hello").is_file()
    # the seed's bringup, as its users run it: its world found through the hook
    out = open(seed.root / "launch.out", "w")  # noqa: SIM115
    proc = subprocess.Popen(["bash", "-c", f". {SETUP} && cd ws && . install/setup.bash && "
                                           "exec ros2 launch loc_bringup gazebo.launch.py"],
                            cwd=seed.root, env=seed.env, stdout=out, stderr=subprocess.STDOUT)
    try:
        deadline = time.monotonic() + 90
        listed = ""
        while "marker_box" not in listed:
            assert time.monotonic() < deadline, seed.output("launch.out")
            listed = seed.run("gz", "model", "--list", "--timeout", "2").stdout
        assert "Requesting state for world [seed_world]" in listed
    finally:
        proc.send_signal(signal.SIGINT)
        assert proc.wait(60) == 130


def test_symlink_install_links_the_sources(seed):
    built = bash(seed, "colcon build --symlink-install")
    assert built.returncode == 0, built.stdout + built.stderr
    share = seed.root / "ws" / "install" / "loc_gazebo" / "share" / "loc_gazebo"
    world = share / "worlds" / "world.sdf"
    assert world.is_symlink()
    assert world.resolve() == (seed.root / "ws" / "src" / "loc_gazebo" / "worlds" /
                               "world.sdf").resolve()
    launch = seed.root / "ws" / "install" / "loc_bringup" / "share" / "loc_bringup" / \
        "launch" / "gazebo.launch.py"
    assert launch.is_symlink()


def test_a_malformed_package_xml_is_said_with_its_line(seed):
    seed.write("ws/src/loc_bringup/package.xml",
               MANIFEST.format(name="loc_bringup", build="ament_cmake").replace(
                   "<version>", "<version><", 1))
    done = bash(seed, "colcon build")
    assert done.returncode == 1
    assert f"{seed.root}/ws/src/loc_bringup/package.xml:4:" in done.stderr, done.stderr
    assert "malformed package.xml" in done.stderr and "Traceback" not in done.stderr
    assert not (seed.root / "ws" / "build").exists()  # nothing built from a broken tree


def test_a_package_xml_colcon_would_reject_is_said_not_built_as_plain_cmake(seed):
    seed.write("ws/src/loc_bringup/package.xml",
               MANIFEST.format(name="loc_bringup", build="ament_cmake").replace(
                   "dev@example.com", "dev@localhost"))
    done = bash(seed, "colcon build")
    assert done.returncode == 1
    assert f"{seed.root}/ws/src/loc_bringup/package.xml:6: package.xml as colcon reads it: " \
           f'Invalid email "dev@localhost"' in done.stderr, done.stderr


@pytest.mark.parametrize(("line", "said"), [
    ("find_package(rclcpp REQUIRED)",
     "find_package(rclcpp): package 'loc_bringup' needs 'rclcpp'"),
    ("add_executable(talker src/talker.cpp)",
     "add_executable(talker): package 'loc_bringup' compiles C/C++"),
])
def test_what_needs_a_compiler_or_a_ros_cpp_library_is_said_at_its_line(seed, line, said):
    seed.write("ws/src/loc_bringup/CMakeLists.txt",
               BRINGUP_CMAKE.replace("ament_package()", f"{line}\nament_package()"))
    done = bash(seed, "colcon build")
    assert done.returncode == 1
    assert f"{seed.root}/ws/src/loc_bringup/CMakeLists.txt:6: {said}" in done.stderr, \
        done.stdout + done.stderr
    assert "Traceback" not in done.stderr
