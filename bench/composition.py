#!/usr/bin/env python3
"""Composable nodes (issue 17): ten robots from multi_robot.launch.yaml with each robot's nodes
in one component container (container:=per_robot), in one container for all (all), and a
process per node (none), in the same run: time from `launcher launch` until every robot
publishes odometry on the ROS side, and the launch's summed RSS and USS; then fifty robots in
one world: the time until all fifty publish odometry, the sim's real-time factor while all
drive, and the machine's CPU over that window."""

from __future__ import annotations

import sys

import psutil
from _harness import table, workdir
from demo import run

MODES = ("all", "per_robot", "none")


def robots(root, count: int, mode: str, window: float) -> dict:
    topics = [f"/robot_{i}/odom" for i in range(count)]
    psutil.cpu_percent(None)
    result = run(root, "multi_robot.launch.yaml", [f"count:={count}", f"container:={mode}"],
                 topics, window, 180.0)
    result["cpu"] = psutil.cpu_percent(None)
    result["heard"] = len(result["first"])
    if result["heard"] == count:
        result["all_odom"] = max(result["first"].values()) - result["started"]
    return result


def main() -> None:
    root = workdir()
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 2
    rows = []
    for mode in MODES:
        times, rss, uss = [], [], []
        for _ in range(rounds):
            result = robots(root, 10, mode, 3.0)
            if "all_odom" not in result:
                times.append(float("nan"))
                continue
            times.append(result["all_odom"])
            rss.append(result["rss"])
            uss.append(result["uss"])
        target = "<= 3.0" if mode == "all" else "report"
        rows += [
            (f"10 robots, container:={mode}: launch -> all odometry, s", target,
             " / ".join(f"{t:.2f}" for t in times)),
            (f"10 robots, container:={mode}: sum of USS, MiB", "<= 400" if mode == "all"
             else "report", " / ".join(f"{u:.0f}" for u in uss)),
            (f"10 robots, container:={mode}: sum of RSS, MiB", "<= 700" if mode == "all"
             else "report", " / ".join(f"{r:.0f}" for r in rss)),
        ]
    fifty = robots(root, 50, "all", 10.0)
    if "all_odom" in fifty:
        rows += [("50 robots (container:=all): launch -> all odometry, s", "<= 15",
                  f"{fifty['all_odom']:.2f}"),
                 ("50 robots driving: sim RTF at 1 kHz", ">= 0.9", f"{fifty['rtf']:.3f}"),
                 ("50 robots: machine CPU over the run, %", "report", f"{fifty['cpu']:.0f}"),
                 ("50 robots: sum of USS / RSS, MiB", "report",
                  f"{fifty['uss']:.0f} / {fifty['rss']:.0f}")]
    else:
        rows.append(("50 robots (container:=all): launch -> all odometry, s", "<= 15",
                     f"not reached: {fifty['heard']} of 50 in 180 s"))
    table("composition (bench/composition.py)", rows)


if __name__ == "__main__":
    main()
