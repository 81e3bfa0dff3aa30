"""Run a Python entry point: `python -m launcher.packages.entry MODULE:FUNCTION [ARGS…]`.

The module is imported and the function looked up by name; its return value is the exit
status, as console scripts work. Ctrl-C ends it with status 130 and no traceback.
"""

from __future__ import annotations

import importlib
import sys

from launcher.errors import UsageError, report
from launcher.packages.ros1_args import ros2_layout


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
        # (a roslaunch command line: their argparse must not see FROM:=TO; real ones call
        # rospy.myargv)
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
