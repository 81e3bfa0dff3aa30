"""The launches of the fault campaign (bench/fault_campaign.py): each kind of process the
launcher starts, each written into a run's own folder, and the two places some of them need
(the remote hosts, and the Ray cluster of the batch workers), each made once per campaign.

- children: 1-12 processes of the kinds that try to escape or resist (a sleeper, a `setsid`
  grandchild, `set -m` job control, a double-forking daemon, one that ignores SIGINT, one
  that ignores SIGINT and SIGTERM, a crash, a failure, a respawn storm);
- demo: the repo's robot.launch.yaml (sim, bridge, robot_state_publisher, create);
- lockstep: the repo's robot_lockstep.launch.yaml;
- camera: a world with an RGB and a depth camera (the sim and its renderer) and the bridge of
  both images;
- controllers: the sim with the ros2_control tests' arm, whose controller manager runs in it
  (gz_ros2_control), create, and a spawner of two controllers;
- control node: robot_state_publisher, ros2_control_node on mock hardware and a spawner;
- foxglove: the Foxglove bridge node beside a sleeper;
- launch test: `launcher test` of a launch_testing file whose process it checks;
- rostest: `launcher rostest` of a ROS 1 package's .test file (a rospy talker and its test);
- remote hosts: children of the kinds above on two OpenSSH hosts, each an sshd in a network
  namespace of its own (tests/support/sshd.py; root only);
- batch on Ray: `launcher batch --address` of four launch tests on a Ray cluster of two
  nodes, each on a host of its own (tests/support/ray_cluster.py; root and Ray only).
"""

from __future__ import annotations

import contextlib
import importlib.util
import json
import os
import random
import shutil
import sys
import tempfile
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import psutil
from _harness import launcher_cmd

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))  # (the children that resist, and the hosts, from the tests)
from tests.support.batch_files import write_jobs  # noqa: E402
from tests.support.hear_pkg import make_package, write_test  # noqa: E402
from tests.support.resisting import children_launch  # noqa: E402
from tests.support.robots import ARM, arm_links  # noqa: E402

if TYPE_CHECKING:
    from tests.support.ray_cluster import RayCluster
    from tests.support.sshd import SshHosts

PY = sys.executable
HOSTS = ("robot1", "robot2")
KINDS = ("children", "demo", "lockstep", "camera", "controllers", "control node", "foxglove",
         "launch test", "rostest", "remote hosts", "batch on Ray")
SIMS = ("demo", "lockstep", "camera", "controllers")  # (the kinds memory pressure is put on)

CAMERA_WORLD = """<?xml version="1.0"?><sdf version="1.9"><world name="cameras">
<plugin filename="gz-sim-sensors-system" name="gz::sim::systems::Sensors"/>
<model name="eye"><static>true</static><pose>0 0 1 0 0 0</pose><link name="link">
<sensor name="rgb" type="camera"><topic>rgb</topic><update_rate>30</update_rate><camera>
<horizontal_fov>1.2</horizontal_fov><image><width>320</width><height>240</height></image>
<clip><near>0.1</near><far>50</far></clip></camera></sensor>
<sensor name="depth" type="depth_camera"><topic>depth</topic><update_rate>30</update_rate>
<camera><horizontal_fov>1.2</horizontal_fov><image><width>320</width><height>240</height>
</image><clip><near>0.1</near><far>50</far></clip></camera></sensor></link></model>
<model name="box"><static>true</static><pose>3 0 1 0 0 0.5</pose><link name="l"><visual name="v">
<geometry><box><size>1 1 1</size></box></geometry></visual></link></model>
<light type="directional" name="sun"><pose>0 0 10 0 0 0</pose><direction>-0.5 0.2 -0.9
</direction></light></world></sdf>
"""
CAMERA_LAUNCH = """launch:
  - executable: {cmd: "gz sim -r -s -v 1 cameras.sdf"}
  - node: {pkg: ros_gz_bridge, exec: parameter_bridge,
           args: "/rgb@sensor_msgs/msg/Image[gz.msgs.Image
                  /depth@sensor_msgs/msg/Image[gz.msgs.Image"}
"""
CONTROLLERS = """controller_manager:
  ros__parameters:
    update_rate: 100
    joint_state_broadcaster: {type: joint_state_broadcaster/JointStateBroadcaster}
    forward: {type: forward_command_controller/ForwardCommandController}
forward:
  ros__parameters:
    joints: [j1]
    interface_name: position
"""
CONTROLLERS_LAUNCH = """launch:
  - executable: {cmd: "gz sim -r -s -v 1 empty.sdf"}
  - node: {pkg: ros_gz_sim, exec: create, args: "-file arm.urdf -name arm"}
  - node: {pkg: controller_manager, exec: spawner, args: "joint_state_broadcaster forward"}
"""
CONTROL_NODE_LAUNCH = """launch:
  - node: {pkg: robot_state_publisher, exec: robot_state_publisher,
           param: [{name: robot_description, value: "$(command 'cat arm.urdf')"}]}
  - node: {pkg: controller_manager, exec: ros2_control_node, param: [{from: controllers.yaml}]}
  - node: {pkg: controller_manager, exec: spawner, args: "joint_state_broadcaster forward"}
"""
FOXGLOVE_LAUNCH = """launch:
  - node: {pkg: foxglove_bridge, exec: foxglove_bridge, param: [{name: port, value: 0}]}
  - executable: {cmd: sleep 120}
"""
LAUNCH_TEST = """
import unittest
import launch
import launch_testing.actions
from launch.actions import ExecuteProcess


def generate_test_description():
    sleeper = ExecuteProcess(cmd=["sleep", "30"], name="sleeper")
    return launch.LaunchDescription([sleeper, launch_testing.actions.ReadyToTest()]), \\
        {"sleeper": sleeper}


class TestRuns(unittest.TestCase):
    def test_it_runs(self, proc_info, sleeper):
        import time
        time.sleep(20)
"""
BATCH = """jobs:
  - test: chatter_test.py
seeds: 4
timeout: 60
env: {env}
"""


@dataclass
class Run:
    """One run's launch: its command line, what it adds to the environment, and where else
    what it leaves behind may run (beside what carries the run's tag on this machine)."""
    argv: list[str]
    env: dict[str, str] = field(default_factory=dict)
    elsewhere: Callable[[], list[psutil.Process]] = list
    # its children (False) or grandchildren (True), where they are not the launcher's own
    victims: Callable[[bool], list[psutil.Process]] | None = None
    window: float = 4.0  # seconds into the run its fault may come


class Places:
    """The remote hosts and the Ray cluster, each made on first use and ended with the
    campaign; `available` says which kinds this machine can run."""

    def __init__(self, stack: contextlib.ExitStack, base: Path) -> None:
        self.stack, self.base = stack, base
        self._hosts: SshHosts | None = None
        self._cluster: RayCluster | None = None

    def available(self) -> tuple[list[str], list[str]]:
        """(the kinds this machine runs, a line for each it cannot, and why)."""
        kinds = [k for k in KINDS if k not in ("remote hosts", "batch on Ray")]
        why = []
        root = os.geteuid() == 0
        tools = all(shutil.which(t) for t in ("/usr/sbin/sshd", "ssh", "ip", "unshare"))
        if root and tools:
            kinds.append("remote hosts")
        else:
            why.append(("remote hosts", "not run: needs root, sshd, ssh, ip and unshare"))
        if root and importlib.util.find_spec("ray") is not None:
            kinds.append("batch on Ray")
        else:
            why.append(("batch on Ray", "not run: needs root and Ray (launcher[cluster])"))
        return kinds, why

    def hosts(self) -> SshHosts:
        if self._hosts is None:
            from tests.support.sshd import SshHosts  # (pytest's: only where hosts are made)
            root = Path(tempfile.mkdtemp(prefix="lnc", dir="/tmp"))
            self.stack.callback(shutil.rmtree, root, ignore_errors=True)
            self._hosts = self.stack.enter_context(SshHosts(root / "ssh", HOSTS))
            own = {"PATH": f"{os.path.dirname(PY)}:/usr/bin:/bin",
                   "LAUNCHER_ROUTER_LINGER": "0.5"}
            if "PYTHONPATH" in os.environ:  # (the launcher under test, there as here)
                own["PYTHONPATH"] = os.environ["PYTHONPATH"]
            for name in HOSTS:
                self._hosts.set_environment(name, own)
        return self._hosts

    def cluster(self) -> RayCluster:
        if self._cluster is None:
            from tests.support.ray_cluster import ray_cluster  # (idem)
            self._cluster = self.stack.enter_context(ray_cluster())
        return self._cluster


@dataclass
class Setting:
    """What one run's launch is written with."""
    folder: Path  # the run's own folder (its files, its working directory)
    rng: random.Random
    prefix: str  # the sims' launch prefix ("" for none)
    tag: tuple[str, str]  # the variable, and its value, that the run's processes carry


def launch(kind: str, setting: Setting, places: Places) -> Run:
    """The run of a launch of `kind`."""
    cmd, folder, rng = launcher_cmd(), setting.folder, setting.rng
    prefixed = [f"--launch-prefix={setting.prefix}"] if setting.prefix else []
    if kind == "children":
        (folder / "c.launch.yaml").write_text(children_launch(rng, most=12, timeout=0.5))
        return Run([*cmd, "launch", "-n", "c.launch.yaml"])
    if kind in ("demo", "lockstep"):
        name = "robot.launch.yaml" if kind == "demo" else "robot_lockstep.launch.yaml"
        return Run([*cmd, "launch", "-n", *prefixed, str(REPO / "launch_files" / name),
                    "drive:=false"])
    if kind == "camera":
        (folder / "cameras.sdf").write_text(CAMERA_WORLD)
        (folder / "cam.launch.yaml").write_text(CAMERA_LAUNCH)
        return Run([*cmd, "launch", "-n", *prefixed, "cam.launch.yaml"])
    if kind in ("controllers", "control node"):
        yaml = folder / "controllers.yaml"
        yaml.write_text(CONTROLLERS)
        arm = ARM.format(links=arm_links(4), yaml=yaml)
        if kind == "control node":
            arm = arm.replace("gz_ros2_control/GazeboSimSystem", "mock_components/GenericSystem")
        (folder / "arm.urdf").write_text(arm)
        (folder / "arm.launch.yaml").write_text(
            CONTROLLERS_LAUNCH if kind == "controllers" else CONTROL_NODE_LAUNCH)
        return Run([*cmd, "launch", "-n", *prefixed, "arm.launch.yaml"])
    if kind == "foxglove":
        (folder / "f.launch.yaml").write_text(FOXGLOVE_LAUNCH)
        return Run([*cmd, "launch", "-n", "f.launch.yaml"])
    if kind == "launch test":
        (folder / "test_runs.py").write_text(LAUNCH_TEST)
        return Run([*cmd, "test", "test_runs.py"])
    if kind == "rostest":
        return rostest(folder, cmd)
    if kind == "remote hosts":
        return remote(folder, rng, cmd, places.hosts())
    if kind == "batch on Ray":
        return batch(setting, cmd, places.cluster())
    raise ValueError(f"no launch of kind {kind!r}: {', '.join(KINDS)}")


def rostest(folder: Path, cmd: list[str]) -> Run:
    """rostest's own package: a talker, and a test that hears it, then runs on for 20 s."""
    write_test(make_package(folder / "src"), delay=20, limit=60)
    return Run([*cmd, "rostest", "hear_pkg", "hear.test"],
               {"LAUNCHER_PACKAGE_PATH": str(folder / "src"), "ROS_HOME": str(folder / "home")})


def remote(folder: Path, rng: random.Random, cmd: list[str], hosts: SshHosts) -> Run:
    """Children on the two hosts, launched from the launching host; what a host still runs
    but its sshd's own processes (a connection's sshd waits on TCP, not on the launch) is
    left behind."""
    (folder / "r.launch.yaml").write_text(
        children_launch(rng, most=8, timeout=0.5, machines=HOSTS, folder=folder))

    def elsewhere() -> list[psutil.Process]:
        found = []
        for name in HOSTS:
            for proc in hosts.processes_in(name):
                with contextlib.suppress(psutil.Error):
                    if not proc.name().startswith("sshd"):
                        found.append(proc)
        return found

    return Run(hosts.in_launching([*cmd, "launch", "-n", "r.launch.yaml"]),
               {"LAUNCHER_SSH_COMMAND": hosts.ssh_command}, elsewhere, window=6.0)


def batch(setting: Setting, cmd: list[str], cluster: RayCluster) -> Run:
    """Four launch tests on the cluster's two nodes, the driver on a host of its own; the
    jobs carry the run's tag. Its children are the cluster's job hosts, its grandchildren
    what they start; a job host left once the run is over is left behind."""
    jobs = write_jobs(setting.folder / "jobs")
    variable, value = setting.tag
    (jobs / "b.batch.yaml").write_text(BATCH.format(env=json.dumps(
        {variable: value, "CHATTER_LISTEN": setting.rng.choice(("1", "4", "8"))})))
    argv = cluster.driver_argv([*cmd, "batch", str(jobs / "b.batch.yaml"), "-n", "--address",
                                cluster.address])
    env = cluster.driver_env({})
    env["LAUNCHER_PACKAGE_PATH"] = str(REPO / "packages")

    def job_hosts() -> list[psutil.Process]:
        return [p for p in cluster.tagged() if "launcher.batch.host" in " ".join(cmdline(p))]

    def victims(deep: bool) -> list[psutil.Process]:
        if not deep:
            return job_hosts()
        found = []
        for proc in psutil.process_iter():
            with contextlib.suppress(psutil.Error):
                if proc.environ().get(variable) == value:
                    found.append(proc)
        return found

    return Run(argv, env, elsewhere=job_hosts, victims=victims, window=15.0)


def cmdline(proc: psutil.Process) -> list[str]:
    try:
        return proc.cmdline()
    except psutil.Error:
        return []
