#!/usr/bin/env python3
"""The differential corpus (tests/fidelity): its size, how many cases agree with the real
tool, and the time launcher takes per case against the real tool in the same run.

The counts come from running every case through launcher now. The timing runs a sample of
cases (every 10th by default) one at a time through launcher and through the real tool
(roslaunch 1.15, ros2 launch 3.7.1 + launch_ros 0.28.0), as `tests/fidelity/record.py`
installs them under .fidelity/; without that install the real tool's column says so.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from _harness import table

REPO = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO))

from tests.fidelity.choices import CHOICES  # noqa: E402
from tests.fidelity.compare import compare  # noqa: E402
from tests.fidelity.corpus import cases  # noqa: E402
from tests.fidelity.record import ros1_tool, ros2_tool  # noqa: E402


def real_tools(oracle: Path):
    tools = {}
    if (oracle / "ros1/usr/bin/roslaunch").exists():
        tools["ros1"] = lambda: ros1_tool(oracle / "ros1")
    if (oracle / "ros2/drive.py").exists():
        tools["ros2"] = lambda: ros2_tool(oracle / "ros2")
    return tools


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--every", type=int, default=10, help="time every Nth case")
    parser.add_argument("--oracle", type=Path, default=REPO / ".fidelity")
    options, _ = parser.parse_known_args()
    corpus = cases()
    scratch = Path(tempfile.mkdtemp(prefix="bench-fidelity-"))
    with ThreadPoolExecutor(3) as pool:
        agree = list(pool.map(lambda case: compare(case, scratch / "all")[0], corpus))
    for case, agreed in zip(corpus, agree, strict=True):
        if not agreed:
            print(f"differs: {case.name}", flush=True)
    ours = {"ros1": [], "ros2": []}
    theirs = {"ros1": [], "ros2": []}
    tools = real_tools(options.oracle)
    for index, case in enumerate(corpus[::options.every]):
        ours[case.flavour].append(compare(case, scratch / "timed")[1])
        if case.flavour in tools:
            started = time.monotonic()
            tools[case.flavour]().run(case, scratch / "real" / str(index))
            theirs[case.flavour].append(time.monotonic() - started)
    rows = [("corpus cases (ROS 1, ROS 2)", "report",
             f"{len(corpus)} ({sum(c.flavour == 'ros1' for c in corpus)}, "
             f"{sum(c.flavour == 'ros2' for c in corpus)})"),
            (f"cases that agree with the real tool ({len(CHOICES)} by a listed choice)", "all",
             f"{sum(agree)} of {len(corpus)}")]
    for flavour, real in (("ros1", "roslaunch"), ("ros2", "ros2 launch")):
        mine = statistics.median(ours[flavour]) if ours[flavour] else float("nan")
        rows.append((f"{flavour}: launcher per case, s (median of {len(ours[flavour])})",
                     "report", f"{mine:.3f}"))
        if theirs[flavour]:
            other = statistics.median(theirs[flavour])
            rows.append((f"{flavour}: {real} per case, s (same cases, same run)", "report",
                         f"{other:.3f}"))
            rows.append((f"{flavour}: launcher / {real}", "report", f"{mine / other:.2f}"))
        else:
            rows.append((f"{flavour}: {real} per case", "report",
                         "not installed (python -m tests.fidelity.record installs it)"))
    table("fidelity: the differential corpus", rows)


if __name__ == "__main__":
    main()
