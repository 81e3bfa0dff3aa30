"""ROS 1's command-line words, as roslaunch and rosrun users give them (`FROM:=TO`,
`__name:=`, `__ns:=`, `_param:=value`, and `__log:=` with the master's, which mean nothing
here), and the `--ros-args` words of ROS 2 that say the same. The one mapping that launcher's
nodes (bus/ros_args.py), rospy and the entry-point runner (entry.py) all read them by."""

from __future__ import annotations

import os
import re

WORD = re.compile(r"^(?:__\w+|_\w+|[~/A-Za-z][\w/~]*):=")


def is_ros1(word: str) -> bool:
    return WORD.match(word) is not None


def as_ros2(word: str) -> list[str]:
    """The `--ros-args` words for one ROS 1 word (none for `__log:=` and the master's)."""
    name, _, value = word.partition(":=")
    if name in ("__name", "__node"):
        return ["-r", f"__node:={value}"]
    if name == "__ns":
        return ["-r", f"__ns:={value if value.startswith('/') else '/' + value}"]
    if name.startswith("__"):  # __log, __ip, __hostname, __master
        return []
    if name.startswith("_"):  # a private parameter
        return ["-p", f"{name[1:]}:={value}"]
    return ["-r", word]


def ros2_layout(words: list[str]) -> list[str]:
    """`words` with the ROS 1 ones before any `--ros-args` moved after it, as ROS 2's. A ROS 1
    command line without `__ns:=` is in ROS_NAMESPACE's namespace, as rospy reads it (that is
    how roslaunch gives a node its namespace)."""
    cut = words.index("--ros-args") if "--ros-args" in words else len(words)
    before, after = words[:cut], words[cut:]  # (after --ros-args: ROS 2's already)
    ros = [w for word in before if is_ros1(word) for w in as_ros2(word)]
    mine = [word for word in before if not is_ros1(word)]
    if len(mine) == len(before):
        return words
    space = os.environ.get("ROS_NAMESPACE", "").strip()
    if space and not any(word.startswith("__ns:=") for word in before):
        ros += as_ros2(f"__ns:={space}")
    if after:
        return [*mine, after[0], *ros, *after[1:]]
    return [*mine, "--ros-args", *ros] if ros else mine
