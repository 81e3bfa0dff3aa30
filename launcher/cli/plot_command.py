"""`launcher plot /topic/field… [-o plot.png] [--duration S] [--bag BAG]`: fields of messages
drawn over time with matplotlib, as rqt_plot draws them: live from the graph for `--duration`
seconds from the first message (10; Ctrl-C ends sooner), or from a recorded bag. Into a PNG
(or SVG, PDF), or a window when there is a display and no `-o`. A field is a topic and a path
into its messages (`/odom/pose/pose/position/x`, `/joint_states/position/0`).

`launcher plot --processes [RUN]`: the CPU and memory of each process of a launch, as the launch
sampled them once a second (`processes.csv` in its log folder; RUN is that folder, the file, or
by default the latest run's)."""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path
from typing import Any

from launcher.bus import graph
from launcher.bus.wire import stamp_seconds
from launcher.errors import LaunchError, UsageError, did_you_mean


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("fields", nargs="*", help="/topic/path/to/field (…/position/0 for an item)")
    parser.add_argument("-o", "--output", default=None,
                        help="the picture to write (.png, .svg, .pdf); default: a window when "
                        "there is a display, else plot.png")
    parser.add_argument("-d", "--duration", type=float, default=10.0,
                        help="seconds to listen, from the first message (live; default 10)")
    parser.add_argument("--bag", default=None, help="read a recorded bag instead")
    parser.add_argument("--processes", nargs="?", const="latest", default=None, metavar="RUN",
                        help="draw the CPU and memory of a launch's processes instead (its log "
                             "folder, or its processes.csv; default: the latest run's)")


def _split(field: str, topics: list[str]) -> tuple[str, list[str]]:
    """(topic, path) of `/topic/a/b`: the longest topic that prefixes it."""
    for topic in sorted(topics, key=len, reverse=True):
        if field == topic or field.startswith(topic + "/"):
            return topic, [p for p in field[len(topic):].split("/") if p]
    raise UsageError(f"no topic for the field '{field}'{did_you_mean(field, topics)}; "
                     f"topics: {', '.join(sorted(topics)) or 'none'}")


def _value(message: Any, path: list[str], field: str) -> float:
    value = message
    for part in path:
        try:
            value = value[int(part)] if part.isdigit() else getattr(value, part)
        except (AttributeError, IndexError, TypeError):
            raise LaunchError(f"'{field}': the messages have no '{part}' there") from None
    try:
        return float(value)
    except (TypeError, ValueError):
        raise LaunchError(f"'{field}' is not a number (it is {type(value).__name__}): name a "
                          "number inside it") from None


def _stamp(message: Any, received: float) -> float:
    header = getattr(message, "header", None)
    stamp = getattr(header, "stamp", None)
    if stamp is not None and (stamp.sec or stamp.nanosec):
        return stamp_seconds(stamp)
    return received


FIRST_WAIT = 10.0  # s to wait for the first message before the --duration window starts


def _live(fields: list[str], duration: float) -> dict[str, list[tuple[float, float]]]:
    from launcher.bus.node import Node
    from launcher.bus.session import open_session

    session = open_session("client")
    try:
        known = {n: sorted(info.types) for n, info in graph.topics(session).items()
                 if info.publishers}
    finally:
        session.close()
    series: dict[str, list[tuple[float, float]]] = {f: [] for f in fields}
    node = Node("_launcher_plot", argv=[], parameter_services=False)
    try:
        for field in fields:
            topic, path = _split(field, list(known))

            def take(message: Any, field: str = field, path: list[str] = path) -> None:
                series[field].append((_stamp(message, time.time()),
                                      _value(message, path, field)))
            node.create_subscription(known[topic][0], topic, take)
        # the window opens at the first message (a busy machine may take a while to connect)
        deadline = time.monotonic() + FIRST_WAIT
        while not any(series.values()) and time.monotonic() < deadline:
            node.spin(0.05)
        node.spin(duration)
    finally:
        node.destroy_node()
    return series


def _recorded(fields: list[str], bag: Path) -> dict[str, list[tuple[float, float]]]:
    from rosbags.rosbag2 import Reader

    from launcher.bus.types import registry

    series: dict[str, list[tuple[float, float]]] = {f: [] for f in fields}
    types = registry()
    with Reader(bag) as reader:
        topics = {c.topic: c for c in reader.connections}
        chosen = {field: _split(field, list(topics)) for field in fields}
        for connection, stamp, data in reader.messages():
            for field, (topic, path) in chosen.items():
                if connection.topic == topic:
                    message = types.deserialize(data, connection.msgtype)
                    series[field].append((_stamp(message, stamp / 1e9),
                                          _value(message, path, field)))
    return series


def _figures(run: str) -> dict[str, list[tuple[float, float, float]]]:
    """Each process's (time, CPU %, memory MiB) from a run's processes.csv."""
    import csv

    from launcher.runtime.logs import log_root

    path = log_root() / "latest" if run == "latest" else Path(run)
    csv_path = path / "processes.csv" if path.is_dir() else path
    try:
        with open(csv_path, newline="", encoding="utf-8") as handle:
            rows = list(csv.DictReader(handle))
    except OSError as exc:
        raise LaunchError(f"cannot read {csv_path}: {exc.strerror or exc} (a launch writes it "
                          "into its log folder once it has run a second; not with "
                          "--no-log-files)") from None
    series: dict[str, list[tuple[float, float, float]]] = {}
    try:
        for row in rows:
            series.setdefault(row["name"], []).append(
                (float(row["time"]), float(row["cpu_percent"]), int(row["rss_bytes"]) / 2**20))
    except (KeyError, ValueError):
        raise LaunchError(f"{csv_path}: not a launch's processes.csv (expected the columns "
                          "time,name,pid,cpu_percent,rss_bytes)") from None
    if not series:
        raise LaunchError(f"{csv_path} holds no samples yet")
    return series


def _draw_figures(series: dict[str, list[tuple[float, float, float]]], output: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, (cpu, memory) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    start = min(points[0][0] for points in series.values())
    for name, points in series.items():
        times = [t - start for t, _, _ in points]
        cpu.plot(times, [c for _, c, _ in points], label=name)
        memory.plot(times, [m for _, _, m in points], label=name)
    cpu.set_ylabel("CPU (% of one core)")
    memory.set_ylabel("memory (MiB)")
    memory.set_xlabel("time (s)")
    for axes in (cpu, memory):
        axes.grid(True, alpha=0.3)
    cpu.legend(loc="best", fontsize="small")
    figure.savefig(output, dpi=100, bbox_inches="tight")


def run(args: argparse.Namespace) -> int:
    try:
        import matplotlib
    except ImportError:  # said before any waiting
        raise LaunchError("launcher plot draws with matplotlib, which is not installed: "
                          "sh hooks/bootstrap.sh test installs it (or pip install "
                          "'launcher[plot]')") from None
    if args.processes is not None:
        if args.fields:
            raise UsageError("--processes draws a launch's processes: give it no fields")
        series = _figures(args.processes)
        output = Path(args.output or "processes.png")
        _draw_figures(series, output)
        print(f"wrote {output} ({len(series)} processes)")
        return 0
    if not args.fields:
        raise UsageError("name the fields to draw (/topic/path/to/field), or --processes")
    if args.duration <= 0:
        raise UsageError(f"--duration must be above 0, got {args.duration:g}")
    series = _recorded(args.fields, Path(args.bag)) if args.bag else \
        _live(args.fields, args.duration)
    window = args.output is None and bool(os.environ.get("DISPLAY"))
    if not window:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(9, 4.5))
    start = min((points[0][0] for points in series.values() if points), default=0.0)
    for field, points in series.items():
        axes.plot([t - start for t, _ in points], [v for _, v in points], label=field)
    axes.set_xlabel("time (s)")
    axes.grid(True, alpha=0.3)
    axes.legend(loc="best")
    empty = [f for f, points in series.items() if not points]
    if window:
        plt.show()
    else:
        output = Path(args.output or "plot.png")
        figure.savefig(output, dpi=100, bbox_inches="tight")
        counts = ", ".join(f"{f}: {len(p)}" for f, p in series.items())
        print(f"wrote {output} ({counts})")
    if empty:
        raise LaunchError(f"no messages for {', '.join(empty)} (is anything publishing?)")
    return 0
