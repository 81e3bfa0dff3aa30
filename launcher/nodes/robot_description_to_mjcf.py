"""mujoco_ros2_control's `robot_description_to_mjcf.sh` and `make_mjcf_from_robot_description.py`:
a URDF to MJCF, saved (`--save_only`) or published latched on a topic for its
ros2_control_node (`--publish_topic`), with the same options.

The URDF comes from `-u FILE`, `-r TEXT` or robot_state_publisher's `robot_description`
parameter; `<mujoco_inputs>` from `-m FILE` or the URDF; the scene from `--scene FILE` or
the URDF's `<mujoco_inputs><scene>`. Published, the files live in a private temporary folder
for as long as the node runs. The conversion is launcher's (launcher/sim/mjcf_generation),
with MuJoCo's URDF compiler; only COLLADA meshes and `decompose_mesh` need tools of their own
(trimesh, CoACD), installed apart and said.
"""

from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

from launcher.errors import LaunchError, reported
from launcher.user_files import read_text

NAME = "robot_description_to_mjcf"
DESCRIPTION_NODE = "/robot_state_publisher"


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="make_mjcf_from_robot_description.py",
        description="Convert a full URDF to MJCF for use in MuJoCo",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    add = parser.add_argument
    add("-u", "--urdf", default=None, help="Optionally pass an existing URDF file")
    add("-r", "--robot_description", help="Optionally pass the robot description string")
    add("-m", "--mujoco_inputs", default=None,
        help="Optionally specify a defaults xml for default settings, actuators, options, "
             "and additional sensors")
    add("-o", "--output", default="mjcf_data", help="Generated output path")
    add("-p", "--publish_topic", default=None,
        help="Optionally specify the topic to publish the MuJoCo model")
    add("-c", "--convert_stl_to_obj", action="store_true",
        help="If we should convert .stls to .objs (MuJoCo reads STL: kept as STL)")
    add("-s", "--save_only", action="store_true",
        help="Save files permanently on disk; without this flag, files go to a temporary "
             "directory")
    add("-f", "--add_free_joint", action="store_true",
        help="Adds a free joint before the root link of the robot in the urdf before "
             "conversion")
    add("--fuse", action=argparse.BooleanOptionalAction, default=True,
        help="Allows MuJoCo to merge static bodies. Use --no-fuse to prevent merging.")
    add("-a", "--asset_dir", default=None,
        help="Optionally pass an existing folder with pre-generated OBJ meshes.")
    add("--scene", default=None, help="Optionally pass an existing xml for the scene")
    add("--install-only", action="store_true",
        help="Only install the tools COLLADA meshes and decompose_mesh need, then exit")
    return parser


def run(argv: list[str]) -> int:
    from launcher.sim.mjcf_generation import apart

    ros = argv[argv.index("--ros-args"):] if "--ros-args" in argv else []
    args = build_parser().parse_args(argv[:len(argv) - len(ros)])
    if args.install_only:
        apart.python_with_tools(_say)
        return 0
    if not args.publish_topic and not args.save_only:
        raise LaunchError("give --publish_topic TOPIC (the MJCF for a ros2_control_node) or "
                          "--save_only (files in -o), or both")
    node = None
    try:
        if args.urdf:
            urdf_label, text = args.urdf, read_text(Path(args.urdf))
        elif args.robot_description:
            urdf_label, text = "robot_description", args.robot_description
        else:
            node = _node(ros)
            urdf_label, text = f"{DESCRIPTION_NODE}'s robot_description", _from_rsp(node)
        temporary = None
        if args.save_only:
            output = Path(args.output).resolve()
        else:
            temporary = tempfile.TemporaryDirectory(prefix="mjcf_")  # private (0700)
            output = Path(temporary.name)
        output.mkdir(parents=True, exist_ok=True)
        formatted = _convert(args, text, urdf_label, output)
        if args.publish_topic:
            node = node or _node(ros)
            _publish(node, args.publish_topic, formatted)
        elif args.scene:
            shutil.copy2(args.scene, output)
    finally:
        if node is not None:
            node.destroy_node()
    return 0


def _convert(args: argparse.Namespace, text: str, urdf_label: str, output: Path) -> Path:
    from launcher.packages.index import PackageIndex
    from launcher.sim.mjcf_generation import apart, convert, inputs
    from launcher.sim.resources import resolve_uri

    inputs_label, inputs_text = (args.mujoco_inputs, read_text(Path(args.mujoco_inputs))) \
        if args.mujoco_inputs else (urdf_label, text)
    taken = inputs.read_inputs(inputs_text, inputs_label)
    scene: list[ET.Element] = []
    if args.publish_topic or not args.scene:
        scene_label, scene_text = (args.scene, read_text(Path(args.scene))) if args.scene \
            else (urdf_label, text)
        scene = inputs.read_scene(scene_text, scene_label)
    if not args.publish_topic and scene:  # saved: the scene is a file of its own
        _write_scene(scene, output)
        scene = []
    pregenerated = Path(args.asset_dir).resolve() if args.asset_dir else None
    if pregenerated is not None and output / "assets" in (pregenerated, *pregenerated.parents):
        raise LaunchError(f"-a {args.asset_dir}: the output folder's assets/ is remade; give "
                          "meshes from a folder outside it")
    packages = PackageIndex.from_environment()
    base = Path(args.urdf).resolve().parent if args.urdf else None
    _say(f"Using destination directory: {output}/")
    formatted, warnings = convert.convert(
        text, urdf_label, taken,
        convert.Options(output, relative_assets=not args.publish_topic, fuse=args.fuse,
                        add_free_joint=args.add_free_joint, scene=scene,
                        pregenerated=pregenerated),
        lambda uri: resolve_uri(uri, base, packages), apart.Tools(_say))
    for warning in warnings:
        print(f"[{NAME}] warning: {warning}", file=sys.stderr, flush=True)
    _say(f"wrote {formatted}")
    return formatted


def _write_scene(scene: list[ET.Element], output: Path) -> None:
    """`--save_only` with the URDF's scene: scene.xml including the robot's MJCF."""
    root = ET.Element("mujoco", {"model": "scene"})
    ET.SubElement(root, "include", {"file": "mujoco_description_formatted.xml"})
    root.extend(scene)
    ET.indent(root)
    (output / "scene.xml").write_text(ET.tostring(root, encoding="unicode") + "\n")


def _node(ros: list[str]) -> object:
    from launcher.bus.node import Node

    return Node("mjcf_publisher", argv=ros)


def _from_rsp(node: object) -> str:
    from launcher.bus.parameters import from_message

    client = node.create_client("rcl_interfaces/srv/GetParameters",  # type: ignore[attr-defined]
                                f"{DESCRIPTION_NODE}/get_parameters")
    try:
        while not client.wait_for_service(1.0):
            _say(f"{DESCRIPTION_NODE}/get_parameters not available, waiting again...")
        answer = client.call(node.message(  # type: ignore[attr-defined]
            "rcl_interfaces/srv/GetParameters_Request", names=["robot_description"]), 10.0)
    finally:
        client.destroy()
    text = str(from_message(answer.values[0]) or "") if answer.values else ""
    if not text.strip():
        raise LaunchError(f"{DESCRIPTION_NODE} has no robot_description parameter; give the "
                          "URDF with -u FILE or -r TEXT")
    return text


def _publish(node: object, topic: str, formatted: Path) -> None:
    from launcher.bus.qos import LATCHED

    publisher = node.create_publisher("std_msgs/msg/String",  # type: ignore[attr-defined]
                                      topic.lstrip("/"), LATCHED)
    publisher.publish(node.message("std_msgs/msg/String",  # type: ignore[attr-defined]
                                   data=formatted.read_text()))
    _say(f"publishing the MJCF on {topic} (latched) until stopped")
    node.spin()  # type: ignore[attr-defined]


def _say(text: str) -> None:
    print(text, flush=True)


def main() -> int:
    return reported(lambda: run(sys.argv[1:]), NAME)


if __name__ == "__main__":
    sys.exit(main())
