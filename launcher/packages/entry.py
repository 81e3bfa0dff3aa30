"""Run a Python entry point: `python -m launcher.packages.entry MODULE:FUNCTION [ARGS…]`.

The module is imported and the function looked up by name; its return value is the exit
status, as console scripts work. Ctrl-C ends it with status 130 and no traceback.
"""

from __future__ import annotations

import importlib
import re
import sys

from launcher.errors import UsageError, report

_ROS1 = re.compile(r"^(?:__\w+|_\w+|[~/A-Za-z][\w/~]*):=")


def ros2_layout(words: list[str]) -> list[str]:
    """A roslaunch command line (`FROM:=TO`, `__name:=`, `__ns:=`, `_param:=`, `__log:=`) as
    `--ros-args` words after the program's own, for launcher's implementations of ROS tools
    (gzserver, spawn_model, …), which read ROS 2's layout (real ones call rospy.myargv)."""
    cut = words.index("--ros-args") if "--ros-args" in words else len(words)
    before, after = words[:cut], words[cut:]  # (after --ros-args: ROS 2's already)
    mine = [w for w in before if not _ROS1.match(w)]
    if len(mine) == len(before):
        return words
    ros: list[str] = []
    for word in before:
        if not _ROS1.match(word):
            continue
        name, _, value = word.partition(":=")
        if name == "__name":
            ros += ["-r", f"__node:={value}"]
        elif name == "__ns":
            ros += ["-r", f"__ns:={value}"]
        elif name.startswith("__"):
            continue
        elif name.startswith("_"):
            ros += ["-p", f"{name[1:]}:={value}"]
        else:
            ros += ["-r", word]
    if after:
        return [*mine, after[0], *ros, *after[1:]]
    return [*mine, "--ros-args", *ros] if ros else mine


def main() -> int:
    if len(sys.argv) < 2 or ":" not in sys.argv[1]:
        return report(UsageError("usage: python -m launcher.packages.entry MODULE:FUNCTION "
                                 "[ARGS…]"))
    target = sys.argv[1]
    module_name, _, attribute = target.partition(":")
    # the program's own arguments, before its module is imported: one that reads sys.argv
    # at import (argparse at module level) must not see this runner's MODULE:FUNCTION
    words = sys.argv[2:]
    if module_name.startswith("launcher."):  # launcher's own nodes read ROS 2's layout
        words = ros2_layout(words)
    sys.argv = [module_name.rsplit(".", 1)[-1], *words]
    function = importlib.import_module(module_name)
    for part in attribute.split("."):
        function = getattr(function, part)
    try:
        result = function()
    except KeyboardInterrupt:  # Ctrl-C (or the launch stopping): a quiet exit, no traceback
        return 130
    return result if isinstance(result, int) else 0


if __name__ == "__main__":
    sys.exit(main())
