"""mujoco_ros2_control's `ros2_control_node`: the MJCF scene that the robot description's
`mujoco_ros2_control/MujocoSystemInterface` block names, run by launcher's sim with
controller_manager inside (launcher/sim/plugins/mujoco_ros2_control.py).

The robot description is the `robot_description` parameter, else the latched
`/robot_description` topic (as ros2_control_node reads it). The hardware's parameters:
`mujoco_model` (the scene; else the MJCF from `mujoco_model_topic`, /mujoco_robot_description),
`pids_config_file`, `initial_keyframe`, `override_start_position_file`, `sim_speed_factor`
(the real-time factor; unset or < 0: 1), `headless` (false: the world is also served to a
browser, the web viewer taking the place of MuJoCo's window), `odom_free_joint_name`,
`odom_topic`. /clock goes out on the ROS graph; the sim's own topics and services
(`/world/<name>/…`) are there too, for `gz` and the bridge.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path
from typing import Any

from launcher.errors import LaunchError, reported

DESCRIPTION_WAIT = 30.0  # s to wait for /robot_description or the MJCF topic
MODEL_TOPIC = "/mujoco_robot_description"


def _latched(node: Any, topic: str, what: str) -> str:
    from launcher.bus.qos import LATCHED

    got: list[str] = []
    node.create_subscription("std_msgs/msg/String", topic, lambda m: got.append(m.data),
                             LATCHED)
    node.get_logger().info(f"Waiting for '{topic}' ({what})")
    deadline = time.monotonic() + DESCRIPTION_WAIT
    while not got and time.monotonic() < deadline:
        node.spin_once(0.1)
    if not got:
        raise LaunchError(f"ros2_control_node: no {what} on '{topic}' within "
                          f"{DESCRIPTION_WAIT:g} s")
    return got[0]


def _keyframe_state(path: str, where: str) -> dict[str, list[float]]:
    """An `override_start_position_file`: a `<key>` (as MuJoCo's 'Copy state' writes it)."""
    import xml.etree.ElementTree as ET

    from launcher.user_files import read_text

    try:
        root = ET.fromstring(read_text(Path(path)))
    except ET.ParseError as exc:
        raise LaunchError(f"{path}:{exc.position[0]}: not valid XML") from None
    key = root if root.tag == "key" else root.find(".//key")
    if key is None:
        raise LaunchError(f"{where}: override_start_position_file {path} has no <key>")
    return {name: [float(v) for v in (key.get(name) or "").split()]
            for name in ("qpos", "qvel", "ctrl", "act") if key.get(name)}


def run(argv: list[str]) -> int:
    import tempfile

    from launcher.bus import keys
    from launcher.bus.node import Node
    from launcher.control.description import parse
    from launcher.nodes.sim import start_view
    from launcher.sim.mjcf import PluginConfig
    from launcher.sim.plugins.mujoco_ros2_control import MujocoRos2Control
    from launcher.sim.server import SimServer, install_signal_handlers
    from launcher.sim.transport import BusTransport
    from launcher.sim.world import World

    ros = argv[argv.index("--ros-args"):] if "--ros-args" in argv else []
    folder: Any = None
    node = Node("sim", argv=ros, space=keys.SIM, parameter_services=False)
    log = node.get_logger()
    try:
        probe = Node("_ros2_control_node_description", argv=ros, session=node.session,
                     parameter_services=False)
        text = str(probe.parameters.get("robot_description") or "") or \
            _latched(probe, "/robot_description", "robot description")
        blocks = parse(text, "robot_description")
        mujoco_blocks = [b for b in blocks if b.is_mujoco]
        if not mujoco_blocks:
            raise LaunchError("robot_description: no <ros2_control> block with the hardware "
                              "plugin mujoco_ros2_control/MujocoSystemInterface: this "
                              "ros2_control_node runs the MuJoCo hardware")
        block = mujoco_blocks[0]
        model = block.params.get("mujoco_model", "").strip()
        if model:
            path = Path(model)
            if not path.is_file():
                raise LaunchError(f"{block.where}: mujoco_model '{model}' does not exist")
        else:
            topic = block.params.get("mujoco_model_topic", MODEL_TOPIC).strip()
            text_model = _latched(probe, topic, "MJCF")
            folder = tempfile.TemporaryDirectory(prefix="mujoco_ros2_control_")  # (0700)
            path = Path(folder.name) / "mujoco_robot_description.xml"
            path.write_text(text_model)
        probe.destroy_node()
        pids = block.params.get("pids_config_file", "").strip()
        if pids and not Path(pids).is_file():
            raise LaunchError(f"{block.where}: pids_config_file '{pids}' does not exist")
        world = World.from_path(path, BusTransport(node), as_written=True)  # (MuJoCo's model)
        started = _start_state(world, block)
        speed = float(block.params.get("sim_speed_factor", "-1") or -1)
        server = SimServer(world, node, speed if speed > 0 else 1.0, True)
        server.runner.clocks.add_ros_clock()
        install_signal_handlers(server.runner)
        plugin = MujocoRos2Control(world, server.runner, blocks, ros, PluginConfig(
            "mujoco_ros2_control", block.plugin, _element(), block.where, text), started)
        world.plugins.add(plugin, world.model, world.data)
        headless = block.params.get("headless", "false").strip().lower() in ("true", "1")
        view = None
        if not headless:
            view = start_view(_view_args(), log, None, world)
            if view is not None:
                server.services.show(view)
        log.info(f"MuJoCo model {path}: world '{world.world_name}', timestep "
                 f"{world.model.opt.timestep} s, real-time factor {server.runner.pacer.rtf:g}")
        server.run()
    finally:
        node.destroy_node()
        if folder is not None:
            folder.cleanup()
    return 0


def _start_state(world: Any, block: Any) -> bool:
    """`override_start_position_file`, else `initial_keyframe`: where the model starts
    (True), instead of the state interfaces' initial values (False)."""
    import mujoco

    model, data = world.model, world.data
    override = block.params.get("override_start_position_file", "").strip()
    if override:
        state = _keyframe_state(override, block.where)
        for name, values in state.items():
            target = getattr(data, name)
            if len(values) != len(target):
                raise LaunchError(f"{override}: {name} has {len(values)} numbers; the model "
                                  f"has {len(target)}")
            target[:] = values
        mujoco.mj_forward(model, data)
        return True
    name = block.params.get("initial_keyframe", "").strip()
    if name:
        from launcher.errors import did_you_mean

        keys = [model.key(i).name for i in range(model.nkey)]
        if name not in keys:
            raise LaunchError(f"{block.where}: initial_keyframe '{name}' is not a keyframe of "
                              f"the model{did_you_mean(name, keys)} (keyframes: "
                              f"{', '.join(keys) or 'none'})")
        now = data.time
        mujoco.mj_resetDataKeyframe(model, data, keys.index(name))
        data.time = now
        mujoco.mj_forward(model, data)
        return True
    return False


def _element() -> Any:
    import xml.etree.ElementTree as ET

    return ET.Element("plugin")


def _view_args() -> Any:
    from launcher.nodes.sim import build_parser

    return build_parser().parse_args([])


def main() -> int:
    return reported(lambda: run(sys.argv[1:]), "ros2_control_node")


if __name__ == "__main__":
    sys.exit(main())
