"""gazebo_ros's `spawn_model` (ROS 1's spawner), over launcher's create.

  spawn_model (-urdf | -sdf) (-param P | -file F | -database MODEL) -model NAME
              [-x X] [-y Y] [-z Z] [-R ROLL] [-P PITCH] [-Y YAW] [-J JOINT POSITION]…
              [-unpause] [-gazebo_namespace NS] [-robot_namespace NS] [-reference_frame F]

`-param P` reads the node's parameter P (a launch file's `<param name="robot_description"
command="xacro …"/>` gives it to every node after it); `-database MODEL` is `model://MODEL`.
`-J JOINT POSITION` (again for each joint) starts a revolute or prismatic joint at that
position. `-unpause` runs the sim once the model is in. Exit 0 when spawned, 1 with the sim's
reason, 2 on bad arguments.
"""

from __future__ import annotations

import sys

from launcher.arguments import flag_words
from launcher.errors import UsageError, reported

FLAGS = {"-param": "-param", "-file": "-file", "-model": "-name", "-x": "-x", "-y": "-y",
         "-z": "-z", "-R": "-R", "-P": "-P", "-Y": "-Y", "-timeout": "-timeout"}
IGNORED = {"-gazebo_namespace", "-robot_namespace", "-reference_frame", "-wait"}


def create_argv(argv: list[str]) -> tuple[list[str], bool, list[tuple[str, float]]]:
    """(create's arguments, whether to unpause, the -J joint positions)."""
    out: list[str] = []
    unpause = False
    joints: list[tuple[str, float]] = []
    for word, words in flag_words(argv, __doc__):
        if word in ("-urdf", "-sdf", "-trimesh"):  # the format: the sim tells by the text
            continue
        if word == "-unpause":
            unpause = True
        elif word == "-J":
            if len(words) < 2:
                raise UsageError("-J needs a joint name and a position")
            joint, text = words.pop(0), words.pop(0)
            try:
                joints.append((joint, float(text)))
            except ValueError:
                raise UsageError(f"-J {joint} {text}: the position must be a number (radians "
                                 "or metres)") from None
        elif word in FLAGS or word in IGNORED or word == "-database":
            if not words:
                raise UsageError(f"{word} needs a value")
            value = words.pop(0)
            if word == "-database":
                out += ["-file", f"model://{value}"]
            elif word in FLAGS:
                out += [FLAGS[word], value]
        else:
            known = sorted([*FLAGS, *IGNORED, "-database", "-urdf", "-sdf", "-J", "-unpause"])
            from launcher.errors import did_you_mean

            raise UsageError(f"unknown option '{word}'{did_you_mean(word, known)} (spawn_model "
                             f"takes {', '.join(known)})")
    if "-name" not in out:
        raise UsageError("-model NAME is needed (the name of the model to spawn)")
    return out, unpause, joints


def run(argv: list[str]) -> int:
    from launcher.bus import keys
    from launcher.bus.node import Node
    from launcher.nodes import create

    own, ros = (argv[:argv.index("--ros-args")], argv[argv.index("--ros-args"):]) \
        if "--ros-args" in argv else (argv, [])
    flags, unpause, joints = create_argv(own)
    node = Node("spawn_model", argv=[*flags, *ros])
    try:
        code = create.spawn(node, joints)
        if unpause and code == 0:
            world = create.find_world(node, 0, 0)
            control = node.create_client("mujoco_sim/srv/Control", f"/world/{world}/control",
                                         space=keys.SIM)
            control.wait_for_service(10.0)
            control.call(node.message("mujoco_sim/srv/Control_Request", pause=False),
                         timeout=10.0)
        return code
    except create.SimNotFound as exc:
        raise create.SimNotFound(f"{exc.message}; is the sim running? (gazebo_ros's "
                                 "empty_world.launch, or gz sim)") from None
    finally:
        node.destroy_node()


def main() -> int:
    return reported(lambda: run(sys.argv[1:]), "spawn_model")
