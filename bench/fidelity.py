#!/usr/bin/env python3
"""The differential corpus (tests/fidelity): its size, how many cases agree with the real
tool, and the time launcher takes per case against the real tool in the same run.

The counts come from running every case through launcher now. The timing runs a sample of
cases (every 10th by default) one at a time through launcher and through the real tool
(roslaunch 1.15, ros2 launch 3.7.1 + launch_ros 0.28.0), as `tests/fidelity/record.py`
installs them under .fidelity/; without that install the real tool's column says so. ROS 2's
is run as the recording runs it, through ros2launch's launch_a_launch_file without the
`ros2` command's own start-up (ros2cli, not installed there): a lower bound of what
`ros2 launch` takes.
"""

from __future__ import annotations

import argparse
import compileall
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

FAMILIES = (("ros1", "roslaunch", "ROS 1 files"), ("ros2", "ros2 launch", "XML and YAML files"),
            ("python", "ros2 launch", "Python launch files and scripts"))


def family(case) -> str:
    return "python" if case.name.startswith("ros2/python/") else case.flavour


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
    # launcher as installed: its modules compiled (as the real tools' are, by pip); the runs
    # themselves write no bytecode
    compileall.compile_dir(str(REPO / "launcher"), quiet=1)
    scratch = Path(tempfile.mkdtemp(prefix="bench-fidelity-"))
    with ThreadPoolExecutor(3) as pool:
        agree = list(pool.map(lambda case: compare(case, scratch / "all")[0], corpus))
    for case, agreed in zip(corpus, agree, strict=True):
        if not agreed:
            print(f"differs: {case.name}", flush=True)
    ours: dict[str, list[float]] = {name: [] for name, _, _ in FAMILIES}
    theirs: dict[str, list[float]] = {name: [] for name, _, _ in FAMILIES}
    tools = real_tools(options.oracle)
    # every Nth case of each family, each run by launcher then by the real tool, in turn
    timed = [case for name, _, _ in FAMILIES
             for case in [c for c in corpus if family(c) == name][::options.every]]
    for index, case in enumerate(timed):
        ours[family(case)].append(compare(case, scratch / "timed")[1])
        if case.flavour in tools:
            started = time.monotonic()
            tools[case.flavour]().run(case, scratch / "real" / str(index))
            theirs[family(case)].append(time.monotonic() - started)
    counts = ", ".join(f"{sum(family(c) == name for c in corpus)} {words}"
                       for name, _, words in FAMILIES)
    rows = [("corpus cases", "report", f"{len(corpus)} ({counts})"),
            (f"cases that agree with the real tool ({len(CHOICES)} by a listed choice)", "all",
             f"{sum(agree)} of {len(corpus)}")]
    for name, real, _ in FAMILIES:
        mine = statistics.median(ours[name]) if ours[name] else float("nan")
        rows.append((f"{name}: launcher per case, s (median of {len(ours[name])})",
                     "report", f"{mine:.3f}"))
        if theirs[name]:
            other = statistics.median(theirs[name])
            rows.append((f"{name}: {real} per case, s (same cases, same run)", "report",
                         f"{other:.3f}"))
            target = "≤ 0.40" if name == "python" else "report"
            rows.append((f"{name}: launcher / {real}", target, f"{mine / other:.2f}"))
        else:
            rows.append((f"{name}: {real} per case", "report",
                         "not installed (python -m tests.fidelity.record installs it)"))
    table("fidelity: the differential corpus", rows)


if __name__ == "__main__":
    main()
