"""`launcher ps [-w] [--launch LAUNCH]`: every process of the running launches."""

from __future__ import annotations

import argparse
import sys
import time
from typing import Any

from launcher.bus.launches import Launch, Launches

REFRESH = 1.0  # seconds between the tables of -w


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = ("List every process of the launches running on this graph: its name, "
                          "pid, host, state, restarts, uptime, CPU (percent of one core, its "
                          "process group) and memory.")
    parser.add_argument("-w", "--watch", action="store_true",
                        help="refresh the table every second, in place, until Ctrl-C")
    parser.add_argument("--launch", default=None, metavar="LAUNCH",
                        help="only this launch (its file's name, or its pid)")


def run(args: argparse.Namespace) -> int:
    launches = Launches()
    try:
        if not args.watch:
            print(table(launches.running(args.launch)), end="")
            return 0
        while True:
            text = table(launches.running(args.launch))
            sys.stdout.write("\x1b[H\x1b[2J" + text if sys.stdout.isatty() else text + "\n")
            sys.stdout.flush()
            time.sleep(REFRESH)
    finally:
        launches.close()


COLUMNS = ("NAME", "PID", "HOST", "STATE", "RESTARTS", "UPTIME", "CPU%", "MEMORY")


def table(launches: list[Launch]) -> str:
    out = []
    for launch in launches:
        listing = launch.listing
        head = f"{listing.launch or launch.node}  pid {listing.pid}  up {clock(listing.uptime)}"
        out.append(head + (f"  log {listing.log_folder}" if listing.log_folder else ""))
        if listing.message:  # (it could not list them: ending, or too busy to answer)
            out.append(f"  ({listing.message})")
            continue
        rows = [COLUMNS] + [row_words(row) for row in listing.processes]
        widths = [max(len(r[i]) for r in rows) for i in range(len(COLUMNS))]
        for r in rows:
            out.append("  " + "  ".join(w.ljust(widths[i]) for i, w in enumerate(r)).rstrip())
    return "\n".join(out) + "\n"


def row_words(row: Any) -> tuple[str, ...]:
    state = row.state
    if row.has_exit_code and state in ("exited", "failed", "stopped", "respawning"):
        state += f" ({row.exit_code})" if row.exit_code >= 0 else f" (signal {-row.exit_code})"
    return (row.name, str(row.pid) if row.pid else "-", row.host, state, str(row.restarts),
            clock(row.uptime) if row.pid else "-",
            f"{row.cpu:.1f}" if row.cpu >= 0 and row.pid else "-",
            size(row.memory) if row.memory >= 0 and row.pid else "-")


def clock(seconds: float) -> str:
    whole = int(seconds)
    return f"{whole // 3600}:{whole // 60 % 60:02d}:{whole % 60:02d}"


def size(count: int) -> str:
    value = float(count)
    for unit in ("B", "KiB", "MiB", "GiB"):
        if value < 1024 or unit == "GiB":
            return f"{value:.0f} {unit}" if unit == "B" else f"{value:.1f} {unit}"
        value /= 1024
    return f"{count} B"
