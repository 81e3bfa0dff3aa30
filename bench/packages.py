"""Package benchmarks (issue 3): index build, hook application, `launcher env`, xacro."""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
from pathlib import Path

from _harness import launcher_cmd, summary, table, workdir

from launcher.description.substitution import Text, perform_text
from launcher.description.substitutions.command import Command
from launcher.packages.hooks import apply_hooks
from launcher.packages.index import PackageIndex
from launcher.runtime.context import LaunchContext

MANIFEST = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.1.0</version><description>x</description>
<maintainer email="m@x">m</maintainer><license>MIT</license>{deps}</package>
"""
XACRO = """<?xml version="1.0"?>
<robot name="bench_bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <xacro:property name="r" value="0.05"/>
  <xacro:include filename="$(find bench_description)/urdf/wheel.xacro"/>
  <link name="$(arg prefix)base_link">
    <inertial><mass value="2.0"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><box size="0.3 0.2 0.08"/></geometry></visual>
    <collision><geometry><box size="0.3 0.2 0.08"/></geometry></collision>
  </link>
  <xacro:wheel side="left" y="0.12"/>
  <xacro:wheel side="right" y="-0.12"/>
  <link name="$(arg prefix)caster"><visual><geometry><sphere radius="${r/2}"/></geometry></visual></link>
  <joint name="caster_joint" type="fixed"><parent link="$(arg prefix)base_link"/><child link="$(arg prefix)caster"/></joint>
  <gazebo><plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::DiffDrive">
    <left_joint>left_wheel_joint</left_joint><right_joint>right_wheel_joint</right_joint>
    <wheel_separation>0.24</wheel_separation><wheel_radius>${r}</wheel_radius>
  </plugin></gazebo>
</robot>
"""
WHEEL = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="wheel" params="side y">
    <link name="$(arg prefix)${side}_wheel">
      <inertial><mass value="0.2"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" iyz="0"/></inertial>
      <visual><geometry><cylinder radius="${r}" length="0.02"/></geometry></visual>
    </link>
    <joint name="${side}_wheel_joint" type="continuous">
      <parent link="$(arg prefix)base_link"/><child link="$(arg prefix)${side}_wheel"/>
      <origin xyz="0 ${y} 0" rpy="-1.5708 0 0"/><axis xyz="0 0 1"/>
    </joint>
  </xacro:macro>
</robot>
"""


def make_workspace(root: Path, count: int, hooked: int) -> Path:
    for i in range(count):
        folder = root / "src" / f"group{i % 10}" / f"pkg_{i:03d}"
        (folder / "worlds").mkdir(parents=True, exist_ok=True)
        deps = f"<depend>pkg_{i - 1:03d}</depend>" if i % 5 else ""
        (folder / "package.xml").write_text(MANIFEST.format(name=f"pkg_{i:03d}", deps=deps))
        if i < hooked:
            (folder / "hooks").mkdir(exist_ok=True)
            (folder / "hooks" / f"pkg_{i:03d}.dsv.in").write_text(
                "prepend-non-duplicate;BENCH_PATH;@CMAKE_INSTALL_PREFIX@/share/@PROJECT_NAME@/"
                "worlds\nprepend-non-duplicate-if-exists;BENCH_MODELS;share/@PROJECT_NAME@/m\n"
                "set-if-unset;BENCH_ONE;@PROJECT_NAME@\n")
    description = root / "src" / "bench_description"
    (description / "urdf").mkdir(parents=True)
    (description / "package.xml").write_text(MANIFEST.format(name="bench_description", deps=""))
    (description / "urdf" / "robot.xacro").write_text(XACRO)
    (description / "urdf" / "wheel.xacro").write_text(WHEEL)
    return root / "src"


def timed(function, runs: int) -> list[float]:
    out = []
    for _ in range(runs):
        start = time.perf_counter()
        function()
        out.append(time.perf_counter() - start)
    return out


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=7)
    runs = parser.parse_args().runs
    root = workdir()
    big = make_workspace(root / "ws200", 200, 0)
    hooked = make_workspace(root / "ws50", 50, 50)
    env200 = {"LAUNCHER_PACKAGE_PATH": str(big), "LAUNCHER_CACHE_DIR": str(root / "cache")}
    env50 = {"LAUNCHER_PACKAGE_PATH": str(hooked), "LAUNCHER_CACHE_DIR": str(root / "cache"),
             "PATH": os.environ["PATH"]}
    index_times = timed(lambda: PackageIndex.from_environment(env200, cwd=Path("/")), runs)
    index50 = PackageIndex.from_environment(env50, cwd=Path("/"))
    assert len(index50.packages) >= 51
    apply_hooks(index50, env50)  # make the link farm once, as any first run does
    hook_times = timed(lambda: apply_hooks(index50, env50), runs)
    env_cli = {**os.environ, **env50}
    env_times = timed(lambda: subprocess.run(launcher_cmd() + ["env"], env=env_cli, check=True,
                                             stdout=subprocess.DEVNULL, cwd="/"), runs)
    xacro_file = big / "bench_description" / "urdf" / "robot.xacro"
    context = LaunchContext(env_cli)
    context.packages = PackageIndex.from_environment(env200, cwd=Path("/"))
    command = Command((Text(f"xacro {xacro_file} prefix:=r1_"),))
    perform_text(context, (command,))  # import xacro once, as the first robot of a run does
    in_process = timed(lambda: command.perform(context), runs)
    xacro_cli = str(Path(sys.executable).with_name("xacro"))
    from launcher import compat
    cli_env = {**env_cli, **env200, "PYTHONPATH": compat.SHIMS}
    cli_times = timed(lambda: subprocess.run([xacro_cli, str(xacro_file), "prefix:=r1_"],
                                             env=cli_env, check=True, stdout=subprocess.DEVNULL),
                      runs)
    table("packages (seconds)", [
        ("index build, 200 packages", "<= 0.050", summary(index_times)),
        ("hooks applied, 50 packages", "<= 0.030", summary(hook_times)),
        ("launcher env, wall time", "<= 0.15", summary(env_times)),
        ("$(command 'xacro …'), in-process", "<= 0.080", summary(in_process)),
        ("xacro as a process (for reference)", "report", summary(cli_times)),
    ])


if __name__ == "__main__":
    main()
