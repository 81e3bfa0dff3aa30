"""The fidelity page: the differential corpus's counts, launcher's deliberate differences
with their reasons, and the differences still open, all read from tests/fidelity."""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from tests.fidelity.choices import CHOICES  # noqa: E402
from tests.fidelity.corpus import cases  # noqa: E402
from tests.fidelity.extensions import EXTENSIONS  # noqa: E402
from tests.fidelity.known import KNOWN_DIFFERENCES  # noqa: E402
from tests.fidelity.left_out import LEFT_OUT  # noqa: E402
from tests.fidelity.surface_check import GAPS, sizes  # noqa: E402

INTRO = """# Fidelity: launcher against the real tools

A launch file must mean what ROS makes it mean. The repo's differential corpus
(`tests/fidelity/`) holds small launch files generated per tag, attribute, substitution and
nesting, each with a probe node that records how it was started: its argv, the environment a
launch sets, its working folder, the parameter files it was given and, for ROS 1, the whole
parameter tree as the master holds it when the node starts. A Python case (a launch file or a
script of launch's Python API) also notes, in order, what its own code saw: the launch
context, the events and their fields, what its substitutions gave. Each case was run through
real
roslaunch 1.15 (Debian's) and real ros2 launch (launch 3.7.1, launch_ros 0.28.0 over rclpy's
Kilted wheels), and what they did is recorded in `tests/fidelity/expected/`. The test suite
runs every case through launcher and compares, so it needs no ROS install.

Re-record after adding cases (the real tools are installed apart, under `.fidelity/`, never
on your PATH; ROS 2's launch is installed from checkouts you give):

```sh
python -m tests.fidelity.record --stale --ros2-source DIR   # DIR/launch, DIR/launch_ros
python -m tests.fidelity.compare                            # which cases differ now
```
"""


def page() -> str:
    corpus = cases()
    flavours = Counter("python" if case.name.startswith("ros2/python/") else case.flavour
                       for case in corpus)
    chosen = [case.name for case in corpus if case.name in CHOICES]
    known = sorted(name for name in KNOWN_DIFFERENCES)
    agree = len(corpus) - len(chosen) - len(known)
    lines = [INTRO, "## The corpus now", "",
             "| | cases |", "| --- | --- |",
             f"| ROS 1 (roslaunch XML) | {flavours['ros1']} |",
             f"| ROS 2 (XML and YAML) | {flavours['ros2']} |",
             f"| ROS 2 Python (launch files and LaunchService scripts) | "
             f"{flavours['python']} |",
             f"| agree with the real tool | {agree} |",
             f"| differ on purpose (below) | {len(chosen)} |",
             f"| differ, not yet fixed (below) | {len(known)} |", "",
             "## Where launcher differs on purpose", ""]
    if chosen:
        lines += ["| case | what launcher does instead, and why |", "| --- | --- |"]
        lines += [f"| `{name}` | {CHOICES[name].reason} |" for name in chosen]
    else:
        lines.append("No case of the corpus: launcher does what the real tool does.")
    lines += ["", "Beyond the cases: roslaunch registers its own XML-RPC server under "
              "`/roslaunch/uris` on the parameter server; launcher has no such server and "
              "sets nothing there. A ROS 1 launch whose nodes have all ended ends, as "
              "`ros2 launch` does, where roslaunch keeps its master up until Ctrl-C.", "",
              "## Differences not yet fixed", "",
              "Each is a test expected to fail until it is fixed (then it must be taken off "
              "the list: the test fails on an unexpected pass).", ""]
    lines += [f"- `{name}`" for name in known] or \
        ["None: every case agrees with the real tool, or differs on purpose (above)."]
    return "\n".join(lines + extensions() + surface()) + "\n"


EXTENSIONS_INTRO = """## launcher's extensions

What a ROS 2 launch file may say beyond ROS 2's own launch. Real `ros2 launch` refuses a file
that uses one, so such a file says so once: in XML `<launch extensions="launcher">`, in YAML
`extensions: [launcher]` beside `launch:` (the same tags and attributes as XML), in Python by
importing from `launcher.api.extensions` (not from `launch` or `launch_ros`, which stay
ROS's). Without it, the tag or attribute is an error that names the opt-in.
"""


def extensions() -> list[str]:
    lines = ["", EXTENSIONS_INTRO, "| extension | XML (and YAML) | Python | why |",
             "| --- | --- | --- | --- |"]
    lines += [f"| {e.what} | {e.xml} | {e.python} | {e.why} |" for e in EXTENSIONS]
    return lines


SURFACE_INTRO = """## The Python API, against the real packages

The public surface of the real packages (every module, and in each its classes, functions and
constants, with their signatures, base classes and enum members) is recorded in
`tests/fidelity/surface/` from the packages themselves, installed apart: launch, launch_xml,
launch_yaml, launch_ros, launch_testing, launch_testing_ros and launch_pytest (launch 3.7.1,
launch_ros 0.28.0, and the names the newer sources add), rclpy, rcl_interfaces,
lifecycle_msgs and ament_index_python (the Kilted wheels), and Debian's rospy, actionlib,
rostest, roslaunch and rosbag. A test imports every recorded module through launcher's shims
and checks that every name is there and takes every call the real one takes (the same
parameter names, positions and defaults).

```sh
python -m tests.fidelity.surface --ros2-source DIR     # record (DIR/launch, DIR/launch_ros)
python -m tests.fidelity.surface_check                 # what differs now
```
"""


def surface() -> list[str]:
    import json

    gaps = json.loads(GAPS.read_text())
    lines = ["", SURFACE_INTRO, "| | ROS 2 | ROS 1 |", "| --- | --- | --- |"]
    size = sizes()
    for what in ("modules", "names", "left_out"):
        label = {"left_out": "left out on purpose (names, a module with its names)"}.get(
            what, what)
        lines.append(f"| {label} | {size['ROS 2'][what]} | {size['ROS 1'][what]} |")
    ros1 = sum(1 for key in gaps if key.partition(".")[0].partition(":")[0] in
               ("rospy", "actionlib", "rostest", "roslaunch", "rosbag"))
    lines += [f"| not yet there | {len(gaps) - ros1} | {ros1} |", "",
              "### Left out on purpose", "", "| what | why |", "| --- | --- |"]
    by_reason: dict[str, list[str]] = {}
    for key, reason in LEFT_OUT.items():
        by_reason.setdefault(reason, []).append(key)
    for reason, keys in by_reason.items():
        lines.append(f"| {', '.join(f'`{k}`' for k in sorted(keys))} | {reason} |")
    if gaps:
        lines += ["", "### Not yet there", ""]
        lines += [f"- `{key}`: {why}" for key, why in gaps.items()]
    return lines
